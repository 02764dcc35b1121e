"""The base of hystcomp's hysteresis models (:mod:`hystcomp.models`): the
shared interface :class:`HysteresisModel` (explicit state, chunked
simulation, batches, ``to_dict``), :class:`Invertibility`, the model
registry and :func:`model_from_dict`.
"""

import numpy as np

from . import _batch
from ._validation import as_float_array, as_signal, as_state

__all__ = ["HysteresisModel", "Invertibility", "model_from_dict"]

SCHEMA_VERSION = 1

#: samples per block when an envelope has no compiled form
_BLOCK = 4096


class Invertibility:
    """Answer of ``model.is_invertible()``: truthy when the analytic inverse
    exists, with the reasons when it does not.

    Parameters
    ----------
    reasons : iterable of str
        Why the analytic inverse does not exist; empty when it does.  Kept
        as the list ``reasons``.

    Examples
    --------
    >>> from hystcomp import PI
    >>> check = PI([1.0, 2.0], [-0.5, -0.6], p0=1.0).is_invertible()
    >>> bool(check)
    False
    >>> print(check.reasons[0])
    the partial sum p0 + p_1 + ... + p_2 = -0.1 is not positive
    """

    def __init__(self, reasons):
        self.reasons = list(reasons)

    def __bool__(self):
        return not self.reasons

    def __repr__(self):
        if not self.reasons:
            return "Invertibility(True)"
        return "Invertibility(False: " + "; ".join(self.reasons) + ")"


def _partial_sum_reasons(p0, weights):
    reasons = []
    if not p0 > 0:
        reasons.append(f"p0 = {p0} is not positive")
    sums = p0 + np.cumsum(weights)
    bad = np.nonzero(sums <= 0)[0]
    if bad.size:
        j = int(bad[0])
        reasons.append(
            f"the partial sum p0 + p_1 + ... + p_{j + 1} = {sums[j]:.6g} is not positive"
        )
    return reasons


class HysteresisModel:
    """Common interface of the hysteresis models.

    Subclasses implement ``_simulate(v, state)`` (state modified in place)
    and ``default_state()``.  Every model follows the same protocol:
    ``simulate(v, initial_state=None, return_state=False)``, ``n_states``,
    ``default_state()``, ``to_dict()`` (read back by :func:`model_from_dict`),
    ``output_bounds()``, ``is_invertible()`` and ``exact_inverse()``.

    See Also
    --------
    PI, StopPI, GPI, MGPI

    Examples
    --------
    >>> from hystcomp import PI
    >>> from hystcomp.models import HysteresisModel
    >>> m = PI([1.0], [0.5], p0=1.0)
    >>> isinstance(m, HysteresisModel), m.n_states
    (True, 1)
    >>> y, state = m.simulate([0.0, 2.0, 1.0], return_state=True)
    >>> y.tolist(), state.tolist()
    ([0.0, 2.5, 1.5], [1.0])
    """

    #: number of entries of the explicit state
    n_states = 0

    def simulate(self, v, initial_state=None, return_state=False):
        """Output of the model for the input samples `v`.

        Parameters
        ----------
        v : array_like, shape (n,) or (n, m)
            Input samples (finite, inside the envelopes' domains).  Between
            two samples the input is taken as monotone, so the result does not
            depend on the sampling rate (rate independence, eq. 14/24).  A
            2-D input holds m signals in its columns (samples x signals), each
            simulated from its own state; the output then has shape (n, m).
        initial_state : array_like, optional
            State before the first sample, as returned by a previous call with
            ``return_state=True``; default the virgin state of the thesis
            (every operator output 0 before t = 0, eq. 12/22).  For a 2-D
            input, shape (m, n_states): one state per signal.
        return_state : bool, optional
            Also return the state after the last sample.

        Returns
        -------
        y : ndarray, shape (n,)
            Output samples.
        state : ndarray
            Final state (only if `return_state`).

        Examples
        --------
        Simulating in two chunks, passing the state on, gives the one-shot
        result:

        >>> import numpy as np
        >>> from hystcomp import PI
        >>> m = PI([1.0, 2.0], [0.5, 0.25], p0=1.0)
        >>> v = 3 * np.sin(np.linspace(0, 10, 100))
        >>> y1, s = m.simulate(v[:40], return_state=True)
        >>> y2 = m.simulate(v[40:], initial_state=s)
        >>> bool(np.array_equal(np.concatenate([y1, y2]), m.simulate(v)))
        True
        """
        if np.ndim(v) == 2:
            return _batch.simulate_columns(self, v, initial_state, return_state)
        # a kernel that tests the samples itself spares as_signal's pass
        x = as_signal(v, "v", finite=not self._kernel_checks_finite())
        self._check_input_domain(x, finite=True)
        virgin = self.default_state()
        state = virgin if initial_state is None else as_state(initial_state, self.n_states, virgin=virgin)
        if initial_state is not None:
            self._check_state(state, virgin)
        y = self._simulate(x, state)
        return (y, state) if return_state else y

    def simulate_batch(self, v, weights, p0=None, initial_state=None, return_state=False):
        """Outputs of a batch of models that differ from this one only in
        their weights (a Monte Carlo over the density), in one pass.

        The operator outputs do not depend on the weights (eq. 18, 25), so the
        plays run once (compiled, block by block) and each block of outputs
        is one matrix product with the weights.  Results agree with
        ``simulate`` of each model to rounding (the sum order differs).

        Parameters
        ----------
        v : array_like, shape (n,)
            Input samples, shared by every model.
        weights : array_like, shape (m, N)
            One row of operator weights p_1..p_N per model (N as this model).
        p0 : float or array_like of shape (m,), optional
            The models' p0 (PI, mGPI, stop PI); default this model's.  Not
            allowed for the GPI (its memoryless part is H).
        initial_state : array_like, optional
            State shared by every model before the first sample; default the
            virgin state.
        return_state : bool, optional
            Also return the (shared) state after the last sample.

        Returns
        -------
        Y : ndarray, shape (n, m)
            ``Y[:, j]`` is the output of the model with weights ``weights[j]``.
        state : ndarray
            Final operator state (only if `return_state`).

        Examples
        --------
        >>> import numpy as np
        >>> from hystcomp import PI
        >>> m = PI([1.0, 2.0], [0.5, 0.25], p0=1.0)
        >>> v = 3 * np.sin(np.linspace(0, 10, 50))
        >>> Y = m.simulate_batch(v, [[0.5, 0.25], [0.1, 0.0]])
        >>> Y.shape
        (50, 2)
        >>> bool(np.allclose(Y[:, 0], m.simulate(v), rtol=0, atol=1e-13))
        True
        """
        as_float_array(weights, "weights")
        if p0 is not None and not np.all(np.isfinite(as_float_array(p0, "p0"))):
            raise ValueError(f"Parameter p0 is {p0!r}; expected finite numbers")
        return _batch.simulate_batch(self, v, weights, p0, initial_state, return_state)

    def _check_state(self, state, virgin):
        """ValueError naming ``initial_state`` for a state this model cannot hold
        (none by default; the symmetric mGPI checks its play positions)."""

    def _kernel_checks_finite(self):
        """True when ``_simulate`` finds non-finite samples itself (in its
        compiled kernel's pass) and raises `as_signal`'s ValueError naming
        ``v`` before returning; `simulate` then skips `as_signal`'s test."""
        return False

    def _check_input_domain(self, x, finite=False):
        # finite=True: x passed as_signal (finite samples), or its samples
        # are tested by the kernel (`_kernel_checks_finite`), so an envelope
        # defined on the whole real line has nothing to check (a pass over
        # the record less, holding the GIL)
        for env in self._envelopes():
            if finite and env.domain == (-np.inf, np.inf):
                continue
            env.check_domain(x, "v")

    def _envelopes(self):
        return ()

    def loading_curve(self, r):
        """Initial loading curve phi(r) (eq. 30 for PI, eq. 37 for mGPI).

        The output when the input rises monotonically from 0 to `r` from the
        virgin state.  Negative `r` gives the curve for a falling input.

        Parameters
        ----------
        r : float or array_like
            End points of the monotone input.

        Returns
        -------
        float or ndarray
            phi(r), a float for a scalar `r`, else an array of `r`'s shape.

        Examples
        --------
        >>> from hystcomp import StopPI
        >>> StopPI([1.0], [1.0], p0=1.0).loading_curve([0.5, 2.0]).tolist()
        [1.0, 3.0]
        """
        rr = as_float_array(r, "r")
        flat = rr.reshape(-1)
        as_signal(flat, "r", min_length=0)   # finite end points
        out = np.empty(flat.shape)
        for j, end in enumerate(flat):
            out[j] = self.simulate(np.array([0.0, end]))[-1]
        return float(out[0]) if rr.ndim == 0 else out.reshape(rr.shape)

    def exact_inverse(self, on_unreachable="clip", input_limits=None):
        """The exact inverse compensator (per-sample monotone solve).

        See :class:`hystcomp.inverses.ExactInverse`.

        Parameters
        ----------
        on_unreachable : {"clip", "raise"}, optional
            What to do with a target the model cannot reach: clip it to the
            nearest reachable output with an
            :class:`~hystcomp.inverses.UnreachableWarning` (default), or raise
            ``ValueError``.
        input_limits : (float, float), optional
            Bounds of the compensator's output (e.g. an amplifier's voltage
            range); default from the envelopes' domains and saturation.

        Returns
        -------
        ExactInverse
            A compensator: ``simulate(u, initial_state=None, return_state=False)``.

        Examples
        --------
        >>> import numpy as np
        >>> from hystcomp import StopPI
        >>> m = StopPI([1.0, 2.0], [0.5, 0.25], p0=1.0)
        >>> u = 2 * np.sin(np.linspace(0, 10, 200))
        >>> comp = m.exact_inverse()
        >>> bool(np.max(np.abs(m.simulate(comp.simulate(u)) - u)) < 1e-9)
        True
        """
        from .inverses import ExactInverse  # inverses build on models

        return ExactInverse(self, on_unreachable=on_unreachable, input_limits=input_limits)

    def to_json(self):
        """The model as a JSON string (``to_dict`` serialised)."""
        import json

        return json.dumps(self.to_dict())

    def __eq__(self, other):
        return type(self) is type(other) and self._key() == other._key()

    def __hash__(self):
        # hash the key itself, not its repr: equal keys (0.0 and -0.0
        # included) then hash equal
        return hash(self._key())

    # operator thresholds and weights shared by the PI family
    @property
    def thresholds(self):
        """Operator thresholds r_1 < ... < r_N (eq. 49)."""
        return self._r.copy()

    @property
    def weights(self):
        """Operator weights p_1..p_N (eq. 49), p0 apart."""
        return self._p.copy()

    @property
    def n_operators(self):
        return self._r.size




#: model type name -> class; each model module registers its classes here
_MODELS = {}


def model_from_dict(d, expected=None):
    """Rebuild a model written by ``model.to_dict()``.

    Parameters
    ----------
    d : dict or str
        The description (``model.to_dict()``) or its JSON string
        (``model.to_json()``), with its ``schema_version``.
    expected : type, optional
        A model class the description must be of (a subclass counts);
        default any registered model.

    Returns
    -------
    HysteresisModel
        A model equal to the one written (PI, MGPI, GPI, StopPI or another
        registered model type).

    Raises
    ------
    ValueError
        For a malformed description, another schema version, an unknown
        model type or one that is not `expected`.

    Examples
    --------
    >>> from hystcomp import PI, model_from_dict
    >>> m = PI([1.0, 2.0], [0.5, 0.25], p0=1.0)
    >>> model_from_dict(m.to_dict()) == m
    True
    >>> model_from_dict(m.to_json(), expected=PI)
    PI(N=2, p0=1.0)
    """
    if isinstance(d, str):
        import json

        d = json.loads(d)
    if not isinstance(d, dict) or "model" not in d:
        raise ValueError(f"Model description should be a dict with a 'model' key, got {type(d).__name__}")
    version = d.get("schema_version")
    if version != SCHEMA_VERSION:
        raise ValueError(
            f"Model description has schema_version {version!r}; this hystcomp reads version {SCHEMA_VERSION}"
        )
    cls = _MODELS.get(d["model"]) if isinstance(d["model"], str) else None
    if cls is None:
        raise ValueError(f"Model type {d['model']!r} is unknown; expected one of {sorted(_MODELS)}")
    if expected is not None and not issubclass(cls, expected):
        raise ValueError(f"Description is of a {d['model']} model, not {expected.__name__}")
    try:
        return cls._from_dict(d)
    except KeyError as exc:
        raise ValueError(
            f"Model description of a {d['model']} model has no key {exc.args[0]!r}; expected "
            "the keys written by model.to_dict()"
        ) from None

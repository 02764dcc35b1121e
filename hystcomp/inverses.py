"""Inverse compensators: analytic (Krejci-Kuhnen, the thesis's mGPI recipe,
GPI cascade) and exact (per-sample monotone solve).

* :meth:`hystcomp.PI.inverse` -- Krejci-Kuhnen: exact, again a PI model;
  :meth:`hystcomp.PI.inverse_state` maps a non-zero initial state.
* :meth:`hystcomp.MGPI.inverse` -- the thesis's recipe, section 4.3,
  eqs. 54-58 (:func:`mgpi_inverse_parameters`): exact for linear envelopes,
  an approximation for nonlinear ones.
* :meth:`hystcomp.GPI.inverse` -- :class:`GPIInverse`, gamma^-1 o PI^-1.
* ``model.exact_inverse()`` -- :class:`ExactInverse`: for any model of the
  family with compiled envelopes (asymmetric ones and beta'(0) = 0 included),
  ``model.simulate(comp.simulate(u)) == u`` to rounding for reachable targets.

:func:`tracking_error` measures what a compensator leaves: the error of
``model o compensator`` on a reference.
"""

import warnings

import numpy as np

from . import _kernels as _k
from ._validation import as_scalar, as_signal, as_state, as_thresholds, as_weights, check_choice, check_simulates
from .envelopes import Envelope
from .models import GPI, MGPI, HysteresisModel, StopPI, _partial_sum_reasons

__all__ = [
    "mgpi_inverse_parameters",
    "ExactInverse",
    "GPIInverse",
    "UnreachableWarning",
    "tracking_error",
    "TrackingError",
]


class UnreachableWarning(UserWarning):
    """Some targets lie outside the outputs the model can reach; they were clipped.

    Issued by :meth:`ExactInverse.simulate` (with ``on_unreachable="clip"``)
    and :meth:`GPIInverse.simulate`; the message names the count and the first
    sample index.  Filter it with the :mod:`warnings` module to make it an
    error or silence it.

    Examples
    --------
    >>> import warnings
    >>> from hystcomp import MGPI
    >>> from hystcomp.envelopes import Tanh
    >>> model = MGPI([1.0], [0.5], p0=1.0, envelope=Tanh(2.0, 1.0))   # |y| < 3
    >>> with warnings.catch_warnings(record=True) as caught:
    ...     warnings.simplefilter("always")
    ...     v = model.exact_inverse().simulate([0.0, 1.0, 5.0])
    >>> caught[0].category is UnreachableWarning
    True
    """


def mgpi_inverse_parameters(thresholds, weights, p0, envelope):
    """Parameters of the thesis's analytic mGPI inverse (section 4.3).

    Parameters
    ----------
    thresholds, weights : array_like, shape (N,)
        r_1..r_N and p_1..p_N of the model (eq. 49).
    p0 : float
        Weight of the r = 0 operator.
    envelope : Envelope
        gamma (gl = gr), with gamma(0) = 0.

    Returns
    -------
    q : ndarray, shape (N,)
        Inverse thresholds, eq. 56: q_j = p0 gamma(r_j) + sum_{i<=j} p_i gamma(r_j - r_i).
    g : ndarray, shape (N,)
        Inverse weights, eq. 58 (eq. 57's last coefficient read as g_j):
        g_j = [1 / sum_{i=0}^{j} p_i gamma'(r_j - r_i) - g0 beta'(q_j)
        - sum_{i<j} g_i beta'(q_j - q_i)] / beta'(0), with p_0 = p0, r_0 = 0.
    g0 : float
        1/p0 (eq. 54).  The inverse envelope is beta = gamma^-1 (eq. 55).

    Examples
    --------
    Thesis section 5.2 (gamma = v), the first inverse thresholds and weights:

    >>> import numpy as np
    >>> from hystcomp.envelopes import Identity
    >>> r = 0.25 * np.arange(1, 21)
    >>> p = np.exp(-0.1 * r) * 0.25
    >>> q, g, g0 = mgpi_inverse_parameters(r, p, 1.0, Identity())
    >>> np.round(q[:3], 4).tolist(), np.round(g[:3], 4).tolist()
    ([0.25, 0.561, 0.9314], [-0.196, -0.129, -0.0914])
    """
    r = as_thresholds(thresholds)
    p = as_weights(weights, r.size)
    p0 = as_scalar(p0, "p0")
    if p0 == 0.0:
        raise ValueError("Parameter p0 is 0.0 but the analytic inverse needs p0 != 0 (its slope is 1/p0)")
    if not isinstance(envelope, Envelope):
        raise TypeError(f"Parameter envelope is {envelope!r} but should be an hystcomp Envelope")
    gamma = envelope
    beta = gamma.inverse_envelope()
    g0 = 1.0 / p0
    N = r.size
    r_all = np.concatenate([[0.0], r])
    p_all = np.concatenate([[p0], p])
    q = np.empty(N)
    g = np.empty(N)
    dbeta0 = float(beta.derivative(0.0))
    for j in range(1, N + 1):
        diffs = r_all[j] - r_all[: j + 1]          # r_j - r_i, i = 0..j
        q[j - 1] = float(np.dot(p_all[: j + 1], gamma(diffs)))                   # eq. 56
        denom = float(np.dot(p_all[: j + 1], gamma.derivative(diffs)))          # eq. 58
        blo, bhi = beta.domain
        qj = q[j - 1]
        if not ((blo < qj < bhi) if beta.domain_open else (blo <= qj <= bhi)):
            raise ValueError(
                f"Parameters thresholds, weights, p0 give q_{j} = {q[j - 1]:.6g} outside gamma's range "
                f"{gamma.range} where eq. 58 needs beta'(q_{j}): the analytic inverse does not exist "
                "for this model (use the exact inverse)"
            )
        rest = g0 * float(beta.derivative(q[j - 1]))
        if j > 1:
            rest += float(np.dot(g[: j - 1], beta.derivative(q[j - 1] - q[: j - 1])))
        g[j - 1] = (1.0 / denom - rest) / dbeta0
    return q, g, g0


def _family(model):
    """(family code, r, p, p0, envelopes, H) for the compiled solver."""
    if isinstance(model, MGPI):
        if model.symmetric:
            return _k.FAM_PLAY, model._r, model._p, model.p0, model.envelope_left, model.envelope_left, None
        r = np.concatenate([[0.0], model._r])
        p = np.concatenate([[model.p0], model._p])
        return _k.FAM_MPLAY, r, p, 0.0, model.envelope_left, model.envelope_right, None
    if isinstance(model, GPI):
        return _k.FAM_GPI, model._r, model._p, 0.0, model.envelope_left, model.envelope_right, model.H
    if isinstance(model, StopPI):
        return _k.FAM_STOP, model._r, model._p, model.p0, None, None, None
    raise TypeError(f"Parameter model is {type(model).__name__}; expected PI, MGPI, GPI or StopPI")


def _saturation_inputs(env):
    """Inputs beyond which `env` is constant to double precision, or its domain."""
    lo_d, hi_d = env.domain
    lo_r, hi_r = env.range
    width = hi_d - lo_d if np.isfinite(hi_d - lo_d) else 1.0
    if np.isfinite(lo_d):
        lo = lo_d + 1e-12 * width if env.domain_open else lo_d
    elif np.isfinite(lo_r):
        lo = float(env.inverse(lo_r + 1e-15 * (hi_r - lo_r)))
    else:
        lo = -np.inf
    if np.isfinite(hi_d):
        hi = hi_d - 1e-12 * width if env.domain_open else hi_d
    elif np.isfinite(hi_r):
        hi = float(env.inverse(hi_r - 1e-15 * (hi_r - lo_r)))
    else:
        hi = np.inf
    return lo, hi


class ExactInverse:
    """Exact inverse compensator of a hysteresis model.

    At each sample the model's output is monotone in the new input given the
    state, so the inverse solves ``Y(v; state) = u`` per sample: Newton steps
    with the slope of the operators that move on the side of the root (the
    piecewise structure), kept in a bracket and replaced by bisection when
    they leave it.  Then ``model.simulate(comp.simulate(u)) == u`` to about
    1e-13 relative, for any strictly increasing compiled envelopes
    (asymmetric ones and beta'(0) = 0 included).

    Parameters
    ----------
    model : PI, MGPI, GPI or StopPI
        The model to invert.  Its output must increase with its input: p0 > 0
        (or an increasing H) and non-negative weights; for PI models the
        looser positive partial sums suffice.
    on_unreachable : {"clip", "raise"}
        A target beyond the outputs the model can reach (saturating
        envelopes, input limits), or inside a jump of its output (asymmetric
        envelopes that cross, one of them with a bounded domain: a boundary
        that leaves its envelope's domain stops binding), is clipped to the
        nearest reachable output and reported with an :class:`UnreachableWarning` naming the count and
        first sample index (also in ``last_unreachable``), or raises.
    input_limits : (float, float), optional
        Bounds of the compensator's output, e.g. an amplifier's voltage
        range.  Default: the envelopes' domains, or the inputs where a
        saturating envelope is flat to double precision (plus the largest
        threshold).

    Examples
    --------
    >>> import numpy as np
    >>> from hystcomp import MGPI
    >>> from hystcomp.envelopes import Tanh
    >>> r = 0.5 * np.arange(1, 21)
    >>> model = MGPI.from_density(lambda r: np.exp(-0.1 * r), r, p0=1.0,
    ...                           envelope_left=Tanh(10, 0.2), envelope_right=Tanh(10, 0.1))
    >>> comp = model.exact_inverse()
    >>> u = 30 * np.sin(np.linspace(0, 12, 2000))
    >>> bool(np.max(np.abs(model.simulate(comp.simulate(u)) - u)) < 1e-9)
    True
    """

    def __init__(self, model, on_unreachable="clip", input_limits=None):
        if not isinstance(model, HysteresisModel):
            raise TypeError(f"Parameter model is {model!r}; expected an hystcomp hysteresis model")
        check_choice(on_unreachable, "on_unreachable", ("clip", "raise"))
        self.model = model
        self.on_unreachable = on_unreachable
        fam, r, p, p0, gl, gr, H = _family(model)
        self._fam, self._r, self._p, self._p0 = fam, r, p, p0
        envs = [e for e in (gl, gr, H) if e is not None]
        for e in envs:
            if e.kernel_spec()[0] == _k.CUSTOM:
                raise NotImplementedError(
                    f"The exact inverse runs compiled and needs built-in envelopes; {e!r} has no "
                    "compiled form (use Identity, Linear, Tanh, Atanh, Polynomial or their Inverse)"
                )
        self._check_monotone(model, gl)
        ident = (_k.IDENTITY, np.zeros(1))
        self._kl, self._pl = gl.kernel_spec() if gl is not None else ident
        self._kr, self._pr = gr.kernel_spec() if gr is not None else ident
        self._kh, self._ph = H.kernel_spec() if H is not None else ident
        self._hscale = 1.0 if H is not None else 0.0
        self.input_limits = self._default_limits(envs) if input_limits is None else self._user_limits(input_limits, envs)
        self.n_states = 1 + model.n_states
        self.last_unreachable = (0, -1)
        self.last_iterations = 0

    def _check_monotone(self, model, gl):
        if isinstance(model, MGPI) and model.symmetric and gl.kernel_spec()[0] in (_k.IDENTITY, _k.LINEAR):
            # piecewise-linear: positive partial sums keep every branch increasing
            reasons = _partial_sum_reasons(model.p0, model._p)
            if reasons:
                raise ValueError(
                    "The exact inverse needs an output that increases with the input: " + "; ".join(reasons)
                )
            return
        if isinstance(model, GPI):
            if np.any(model._p < 0) or model.H is None:
                raise ValueError(
                    "The exact inverse of a GPI model needs non-negative weights and an increasing H "
                    f"(got H = {model.H!r}, min weight {model._p.min():.6g})"
                )
            return
        p_all = np.concatenate([[getattr(model, "p0", 0.0)], model._p])
        if p_all[0] <= 0 or np.any(p_all[1:] < 0):
            raise ValueError(
                "The exact inverse needs an output that increases with the input: p0 > 0 and "
                f"non-negative weights (got p0 = {p_all[0]:.6g}, min weight {p_all[1:].min():.6g})"
            )

    def _default_limits(self, envs):
        lo, hi = -np.inf, np.inf
        rmax = float(self._r.max()) if self._r.size else 0.0
        sat_lo, sat_hi = [], []
        for e in envs:
            a, b = _saturation_inputs(e)
            # domain bounds are hard limits; saturation points grow by r_max for modified plays
            dlo, dhi = e.domain
            if np.isfinite(dlo):
                lo = max(lo, a)
            elif np.isfinite(a):
                sat_lo.append(a - (rmax if self._fam in (_k.FAM_PLAY, _k.FAM_MPLAY) else 0.0))
            if np.isfinite(dhi):
                hi = min(hi, b)
            elif np.isfinite(b):
                sat_hi.append(b + (rmax if self._fam in (_k.FAM_PLAY, _k.FAM_MPLAY) else 0.0))
        if sat_lo and len(sat_lo) == len([e for e in envs if not np.isfinite(e.domain[0])]):
            lo = max(lo, min(sat_lo))
        if sat_hi and len(sat_hi) == len([e for e in envs if not np.isfinite(e.domain[1])]):
            hi = min(hi, max(sat_hi))
        return (float(lo), float(hi))

    def _user_limits(self, limits, envs):
        try:
            lo, hi = float(limits[0]), float(limits[1])
        except (TypeError, IndexError, ValueError):
            raise ValueError(f"Parameter input_limits is {limits!r} but should be (lo, hi)") from None
        if not lo < hi:
            raise ValueError(f"Parameter input_limits is {limits!r} but should satisfy lo < hi")
        for e in envs:
            e.check_domain(np.array([lo, hi]) if np.isfinite(lo) and np.isfinite(hi) else np.array([]), "input_limits")
        return (lo, hi)

    def default_state(self):
        """[last input 0, the model's virgin state]."""
        return np.concatenate([[0.0], self.model.default_state()])

    def _output_rtol(self):
        """Relative output tolerance of the solve: 1e-14 of ``(1 + |target|)``
        for models whose output moves by at least 1 over their largest
        threshold, and scaled down with that output scale below it, so that a
        model written in small units (metres, coulombs) is inverted to the
        same relative accuracy (a constant, so chunked runs stay bit-identical
        to one-shot runs)."""
        if getattr(self, "_rtol", None) is None:
            r = np.asarray(self._r, dtype=np.float64)
            xs = float(r.max()) if r.size and r.max() > 0 else 1.0
            try:
                y = np.asarray(self.model.simulate(np.array([0.0, xs])), dtype=np.float64)
                ys = float(abs(y[1] - y[0]))
            except Exception:   # any model the inverse accepts simulates; be safe all the same
                ys = 1.0
            self._rtol = 1e-14 * (min(1.0, ys) if np.isfinite(ys) and ys > 0 else 1.0)
        return self._rtol

    def simulate(self, u, initial_state=None, return_state=False):
        """Compensator output v with ``model.simulate(v) == u`` (reachable u).

        Parameters
        ----------
        u : array_like, shape (n,)
            Desired model outputs.
        initial_state : array_like, optional
            ``[v_prev, *model_state]``; default :meth:`default_state`.  To
            compensate a model that has already run, pass
            ``[v_last, *model_state]``.
        return_state : bool
            Also return the final state.
        """
        target = as_signal(u, "u")
        virgin = self.default_state()
        st = virgin if initial_state is None else as_state(initial_state, self.n_states, virgin=virgin)
        xprev = st[0]
        mstate = st[1:].copy()
        kstate = mstate[:-1].copy() if self._fam == _k.FAM_STOP else mstate
        if self._fam == _k.FAM_STOP:
            xprev = mstate[-1] if initial_state is None else xprev
        out = np.empty(target.size)
        info = np.zeros(3, dtype=np.int64)
        xlast = _k.inverse_kernel(self._fam, self._kl)(
            self._fam, target, self._r, self._p, self._p0, kstate, xprev,
            self._kl, self._pl, self._kr, self._pr, self._kh, self._ph, self._hscale,
            self.input_limits[0], self.input_limits[1], self._output_rtol(), out, info,
        )
        count, first = int(info[0]), int(info[1])
        self.last_unreachable = (count, first)
        self.last_iterations = int(info[2])
        if count:
            msg = (
                f"{count} of {target.size} targets are outside the outputs the model can reach "
                f"with inputs in {self.input_limits} or fall in a jump of its output (first at sample "
                f"index {first}, u = {target[first]:.6g})"
            )
            if self.on_unreachable == "raise":
                raise ValueError(msg)
            warnings.warn(msg + "; clipped to the nearest reachable output", UnreachableWarning, stacklevel=2)
        if self._fam == _k.FAM_STOP:
            mstate = np.concatenate([kstate, [xlast]])
        final = np.concatenate([[xlast], mstate])
        return (out, final) if return_state else out

    def __repr__(self):
        return f"ExactInverse({self.model!r}, input_limits={self.input_limits})"


class GPIInverse:
    """Analytic inverse of a GPI model with gl = gr = gamma and H = k gamma
    (Al Janaideh et al.): ``v = gamma^-1(PI^-1[u])``.

    With these envelopes ``GPI[v] = PI[gamma(v)]`` for the PI model of the same
    thresholds and weights and p0 = k, and its Krejci-Kuhnen inverse is
    exact, so this compensator is exact where gamma^-1 is defined.  Targets
    whose PI^-1 falls outside gamma's range are clipped and reported.
    Usually made by :meth:`hystcomp.GPI.inverse`.  Its state is the state of
    the inverse PI model.

    Parameters
    ----------
    model : GPI
        The GPI model to invert, with gl = gr = gamma and H = k gamma, k > 0
        (see :meth:`hystcomp.GPI.is_invertible`).

    Examples
    --------
    >>> import numpy as np
    >>> from hystcomp import GPI
    >>> from hystcomp.envelopes import Tanh
    >>> gpi = GPI([0.5, 1.0], [0.4, 0.2], Tanh(2, 0.5), Tanh(2, 0.5), H=Tanh(2, 0.5))
    >>> u = 1.5 * np.sin(np.linspace(0, 9, 300))
    >>> bool(np.allclose(gpi.simulate(gpi.inverse().simulate(u)), u, atol=1e-10))
    True
    """

    def __init__(self, model):
        if not isinstance(model, GPI):
            raise TypeError(f"Parameter model is {type(model).__name__}; expected GPI")
        self.model = model
        self.pi = model.as_pi()
        self.pi_inverse = self.pi.inverse()
        self.envelope = model.envelope_left
        self.n_states = self.pi_inverse.n_states
        self.last_unreachable = (0, -1)

    def default_state(self):
        return self.pi_inverse.default_state()

    def state_for(self, model_state):
        """Initial state matching a state of the GPI model (Krejci-Kuhnen mapping).

        Parameters
        ----------
        model_state : array_like, shape (N,)
            A state of the GPI model (its generalized play outputs).

        Returns
        -------
        ndarray, shape (N,)
            The compensator state with which it inverts the model started in
            `model_state` (see :meth:`hystcomp.PI.inverse_state`).

        Examples
        --------
        >>> import numpy as np
        >>> from hystcomp import GPI
        >>> from hystcomp.envelopes import Tanh
        >>> gpi = GPI([0.5, 1.0], [0.4, 0.2], Tanh(2, 0.5), Tanh(2, 0.5), H=Tanh(2, 0.5))
        >>> _, s = gpi.simulate([0.0, 2.0, 0.5], return_state=True)
        >>> comp = gpi.inverse()
        >>> u = gpi.simulate(np.linspace(0.5, -1.0, 20), initial_state=s)
        >>> v = comp.simulate(u, initial_state=comp.state_for(s))
        >>> bool(np.allclose(v, np.linspace(0.5, -1.0, 20), atol=1e-10))
        True
        """
        return self.pi.inverse_state(model_state)

    def simulate(self, u, initial_state=None, return_state=False):
        """Compensator output v with ``model.simulate(v) == u``.

        Parameters
        ----------
        u : array_like, shape (n,)
            Desired model outputs.
        initial_state : array_like, optional
            State of the inverse PI model before the first sample; default
            its virgin state (see :meth:`state_for`).
        return_state : bool, optional
            Also return the final state.

        Returns
        -------
        v : ndarray, shape (n,)
            Compensator output (the model's input).
        state : ndarray
            Final state (only if `return_state`).

        Warns
        -----
        UnreachableWarning
            When some targets need gamma(v) outside gamma's range; they are
            clipped (``last_unreachable`` holds the count and first index).

        Examples
        --------
        >>> from hystcomp import GPI
        >>> from hystcomp.envelopes import Linear
        >>> gpi = GPI([1.0], [0.5], Linear(2.0), Linear(2.0), H=Linear(2.0))
        >>> v, s = gpi.inverse().simulate([0.0, 5.5], return_state=True)
        >>> v.round(12).tolist()          # 2 v + 0.5 (2 v - 1) = 5.5 at v = 2
        [0.0, 2.0]
        """
        target = as_signal(u, "u")
        s, state = self.pi_inverse.simulate(target, initial_state=initial_state, return_state=True)
        lo, hi = self.envelope.range
        span = hi - lo if np.isfinite(hi - lo) else 1.0
        margin = 1e-12 * span
        bad = (s <= lo) | (s >= hi)
        count = int(bad.sum())
        self.last_unreachable = (count, int(np.argmax(bad)) if count else -1)
        if count:
            warnings.warn(
                f"{count} of {s.size} targets need gamma(v) outside the envelope's range {self.envelope.range} "
                f"(first at sample index {self.last_unreachable[1]}); clipped",
                UnreachableWarning, stacklevel=2,
            )
            s = np.clip(s, lo + margin, hi - margin)
        v = self.envelope.inverse(s)
        return (v, state) if return_state else v


class TrackingError(dict):
    """Errors of ``model o compensator`` against the reference (a dict).

    Keys: ``rms``, ``max`` (absolute), ``rms_percent``, ``max_percent`` (of
    the reference's span), ``span`` and ``error`` (the error samples).
    Returned by :func:`tracking_error`.

    Examples
    --------
    >>> import numpy as np
    >>> from hystcomp import PI
    >>> m = PI([1.0], [0.5], p0=1.0)
    >>> err = tracking_error(m, PI([1.0], [0.0], p0=1.0), np.array([0.0, 2.0, 0.0]))
    >>> err          # the identity as compensator leaves the play term 0.5 F_1[u]
    TrackingError(rms=0.4082, max=0.5, rms_percent=20.41%, max_percent=25%)
    >>> err["error"].tolist()
    [0.0, 0.5, 0.5]
    """

    def __repr__(self):
        return ("TrackingError(rms={rms:.4g}, max={max:.4g}, rms_percent={rms_percent:.4g}%, "
                "max_percent={max_percent:.4g}%)").format(**self)


def tracking_error(model, compensator, u):
    """What a compensator leaves: ``e = model(compensator(u)) - u``.

    Parameters
    ----------
    model : HysteresisModel
        The hysteresis being compensated.
    compensator : object with ``simulate``
        An inverse (analytic model, :class:`ExactInverse`, ...).
    u : array_like
        The reference (desired output).

    Returns
    -------
    TrackingError
        RMS and maximum error, absolute and in % of the reference's span.

    Examples
    --------
    >>> import numpy as np
    >>> from hystcomp import PI
    >>> m = PI([1.0, 2.0], [0.5, 0.25], p0=1.0)
    >>> err = tracking_error(m, m.inverse(), 3 * np.sin(np.linspace(0, 10, 400)))
    >>> bool(err["max"] < 1e-12)
    True
    """
    check_simulates(model, "model")
    check_simulates(compensator, "compensator")
    ref = as_signal(u, "u")
    y = model.simulate(compensator.simulate(ref))
    e = y - ref
    span = float(ref.max() - ref.min()) or 1.0
    rms = float(np.sqrt(np.mean(e * e)))
    mx = float(np.max(np.abs(e)))
    return TrackingError(rms=rms, max=mx, rms_percent=100 * rms / span, max_percent=100 * mx / span, span=span,
                         error=e)

"""Model parts for the effects a rate-independent hysteresis model lacks.

Each class follows the model protocol of :mod:`hystcomp.models`
(``simulate(v, initial_state=None, return_state=False)`` with a fixed-length
float64 state, ``n_states``, ``default_state()``, ``to_dict()`` and
:func:`hystcomp.models.model_from_dict`, ``output_bounds()``,
``is_invertible()``), so the python-control blocks and the identification
code can use them like the PI family.  Simulating a record in chunks,
passing the state on, gives the one-shot result bit for bit.

* :class:`LinearStage` -- a discrete linear dynamic stage (first-order lag,
  lightly damped resonance, any state-space (A, B, C, D)) at a sampling time
  ``dt``: the rate dependence of an actuator whose hysteresis sits in series
  with linear dynamics (the Hammerstein/Wiener structures of e.g. Rakotondrabe
  2011, IEEE T-ASE 8(2), "Bouc-Wen modeling and inverse multiplicative
  structure to compensate hysteresis nonlinearity in piezoelectric actuators").
* :class:`RateDependentPI` -- a PI model whose thresholds grow with the input
  rate, ``r_i(t) = r_i + beta |dv/dt|`` (the rate-dependent play of
  M. Al Janaideh, S. Rakheja and C.-Y. Su, Mechatronics 19 (2009) 656-670,
  with their additive rate term).
* :class:`CreepOperator` -- Kuhnen's linear creep operator: a bank of
  first-order lags with logarithmically spaced time constants driven by the
  input, ``sum_j c_j L_j[v]`` (K. Kuhnen, "Modeling, identification and
  compensation of complex hysteretic and log(t)-type creep nonlinearities",
  Control and Intelligent Systems 33 (2005)); equal weights on a
  logarithmic grid give the log(t) creep after an input step.
* :class:`DriftTerm` -- a slow trend of the output that ignores the input:
  ``d(t) = sum_j a_j t^j + sum_m b_m (1 - exp(-t/tau_m))`` with ``t = k dt``
  counted in the state (sample index), so it restarts nowhere when a record
  is simulated in chunks.
* :class:`Series` and :class:`Parallel` -- composition: blocks in a chain,
  or blocks fed by the same input with outputs summed plus an offset.

Asymmetric and saturating envelopes need no new class: they are
:class:`~hystcomp.models.MGPI` models with ``envelope_left != envelope_right``
or a :class:`~hystcomp.envelopes.Tanh` envelope.
"""

import math

import numpy as np
from numba import njit

from ._kernels import play_step
from ._linear_stage import LinearStage, _frozen, lag_bank
from ._validation import as_bounds, as_float_array, as_scalar, as_signal, as_state, as_thresholds, as_vector, as_weights
from .models import SCHEMA_VERSION, Invertibility, _MODELS, model_from_dict

__all__ = ["LinearStage", "RateDependentPI", "CreepOperator", "DriftTerm", "Series", "Parallel",
           "lag_bank"]


# ----------------------------------------------------------------------------
# compiled kernels (one loop over samples each)
# ----------------------------------------------------------------------------
@njit(cache=True, no_cfunc_wrapper=True)
def _rate_play_states(v, r, beta, dt, z, prev, out):
    """Plays with thresholds r_i + beta |v_k - v_{k-1}| / dt.

    prev = [v_prev, has_prev]; z and prev are updated in place."""
    for k in range(v.size):
        x = v[k]
        rate = abs(x - prev[0]) / dt if prev[1] > 0.5 else 0.0
        prev[0] = x
        prev[1] = 1.0
        play_step(x, r, beta * rate, z)
        for i in range(r.size):
            out[k, i] = z[i]


# ----------------------------------------------------------------------------
# rate-dependent PI
# ----------------------------------------------------------------------------
class RateDependentPI:
    """PI model with rate-dependent thresholds ``r_i(t) = r_i + beta |dv/dt|``.

    ``w = p0 v + sum_i p_i F_{r_i(t)}[v]``; the rate is the backward
    difference ``(v_k - v_{k-1}) / dt`` (0 at the first sample of a virgin
    state).  With ``beta = 0`` it is the PI model (eq. 18).  Loops widen with
    the input's frequency, as measured on piezo actuators (Al Janaideh,
    Rakheja & Su 2009).

    Parameters
    ----------
    thresholds, weights, p0
        Thresholds r_i (increasing, >= 0), weights p_i and the weight p0
        of the input, as for :class:`~hystcomp.models.PI`.
    rate_coefficient : float
        beta >= 0 [s]: threshold growth per unit input rate.
    dt : float
        Sampling time [s].

    Notes
    -----
    State: the N play positions, the previous input and a flag (1 once a
    sample has been seen), N + 2 entries.

    Examples
    --------
    >>> m = RateDependentPI([0.5, 1.0], [0.5, 0.25], 1.0, rate_coefficient=0.01, dt=1e-3)
    >>> t = np.arange(0, 2, 1e-3)
    >>> slow = m.simulate(np.sin(2 * np.pi * t))
    >>> fast = m.simulate(np.sin(2 * np.pi * 10 * t))
    >>> bool(np.ptp(fast) < np.ptp(slow))   # wider thresholds: less travel
    True
    """

    _type = "RateDependentPI"

    def __init__(self, thresholds, weights, p0, rate_coefficient, dt):
        self._r = as_thresholds(thresholds)
        self._p = as_weights(weights, self._r.size)
        self.p0 = as_scalar(p0, "p0")
        self.rate_coefficient = as_scalar(rate_coefficient, "rate_coefficient", nonnegative=True)
        self.dt = as_scalar(dt, "dt", positive=True)
        self.n_states = self._r.size + 2

    thresholds = property(lambda self: self._r.copy())
    weights = property(lambda self: self._p.copy())

    def default_state(self):
        """Virgin plays (positions 0), no previous sample."""
        return np.zeros(self.n_states)

    def play_positions(self, v, initial_state=None):
        """Play positions (n, N) and the final state.

        Parameters
        ----------
        v : array_like, shape (n,)
            Input samples.
        initial_state : array_like, shape (N + 2,), optional
            N play positions, the previous input and the seen-a-sample
            flag; default :meth:`default_state`.

        Returns
        -------
        positions : ndarray, shape (n, N)
            Output of play i (threshold ``r_i + beta |dv/dt|``) at sample k
            in ``positions[k, i]``.
        state : ndarray, shape (N + 2,)
            Final state.

        Examples
        --------
        >>> m = RateDependentPI([0.5, 1.0], [0.5, 0.25], 1.0, rate_coefficient=0.1, dt=1.0)
        >>> Z, s = m.play_positions([0.0, 1.0, 2.0])    # rate 1: thresholds 0.6 and 1.1
        >>> np.round(Z, 6).tolist()
        [[0.0, 0.0], [0.4, 0.0], [1.4, 0.9]]
        """
        x = as_signal(v, "v")
        s = self.default_state() if initial_state is None else as_state(initial_state, self.n_states)
        z = s[:self._r.size].copy()
        prev = s[self._r.size:].copy()
        out = np.empty((x.size, self._r.size))
        _rate_play_states(x, self._r, self.rate_coefficient, self.dt, z, prev, out)
        return out, np.concatenate([z, prev])

    def simulate(self, v, initial_state=None, return_state=False):
        """Output for the input samples `v` (see the model protocol).

        Parameters
        ----------
        v : array_like, shape (n_samples,)
            Input samples.
        initial_state : array_like, shape (N + 2,), optional
            N play positions, the previous input and the seen-a-sample flag; default :meth:`default_state`.
        return_state : bool
            Also return the final state (to continue a record in chunks).

        Returns
        -------
        y : ndarray, shape (n_samples,)
            Output.
        state : ndarray, shape (N + 2,)
            Final state; only with ``return_state=True``.

        Examples
        --------
        >>> m = RateDependentPI([0.5, 1.0], [0.5, 0.25], 1.0, rate_coefficient=0.1, dt=1.0)
        >>> np.round(m.simulate([0.0, 1.0, 2.0]), 6).tolist()
        [0.0, 1.2, 2.925]
        """
        x = as_signal(v, "v")
        Z, s = self.play_positions(x, initial_state)
        y = self.p0 * x
        for i in range(self._r.size):       # fixed summation order: chunk-exact
            y = y + self._p[i] * Z[:, i]
        return (y, s) if return_state else y

    def output_bounds(self):
        return (-math.inf, math.inf)

    def is_invertible(self):
        return Invertibility(["the rate-dependent PI model has no analytic inverse here"])

    def to_dict(self):
        return {"schema_version": SCHEMA_VERSION, "model": self._type, "thresholds": self._r.tolist(),
                "weights": self._p.tolist(), "p0": self.p0, "rate_coefficient": self.rate_coefficient,
                "dt": self.dt}

    @classmethod
    def _from_dict(cls, d):
        return cls(d["thresholds"], d["weights"], d["p0"], d["rate_coefficient"], d["dt"])

    def __eq__(self, other):
        return type(other) is type(self) and self.to_dict() == other.to_dict()

    def __hash__(self):
        # consistent with __eq__ (equal descriptions): equal models hash equal, 0.0 and -0.0 included
        return hash(_frozen(self.to_dict()))

    def __repr__(self):
        return (f"RateDependentPI(N={self._r.size}, p0={self.p0!r}, "
                f"rate_coefficient={self.rate_coefficient!r}, dt={self.dt!r})")


# ----------------------------------------------------------------------------
# creep and drift
# ----------------------------------------------------------------------------
class CreepOperator:
    """Kuhnen's linear creep operator: ``c[v] = sum_j c_j L_j[v]``.

    L_j is the first-order lag of time constant tau_j driven by the input
    (:func:`lag_bank`).  After an input step dv the output keeps moving by
    ``dv sum_j c_j (1 - exp(-t/tau_j))``, in the sign of the step and in
    proportion to it; with equal c_j on logarithmically spaced tau_j this is
    close to ``log(t)`` between the shortest and the longest time constant.
    Added to a hysteresis model with :class:`Parallel`.

    Parameters
    ----------
    time_constants : array_like, shape (m,)
        tau_j > 0 [s].
    coefficients : array_like, shape (m,)
        c_j (output per input unit).
    dt : float
        Sampling time [s].

    Examples
    --------
    >>> c = CreepOperator([0.1, 1.0, 10.0], [0.01, 0.01, 0.01], dt=0.01)
    >>> y = c.simulate(np.ones(1000))          # 10 s after a unit step
    >>> np.round(y[[9, 99, 999]], 4).tolist()  # grows roughly as log(t)
    [0.0074, 0.0173, 0.0263]
    """

    _type = "CreepOperator"

    def __init__(self, time_constants, coefficients, dt):
        tau = as_vector(time_constants, "time_constants", positive=True)
        self.time_constants = tau
        self.coefficients = as_weights(coefficients, tau.size, "coefficients")
        self.dt = as_scalar(dt, "dt", positive=True)
        self.n_states = tau.size

    def default_state(self):
        """At rest with zero input."""
        return np.zeros(self.n_states)

    def simulate(self, v, initial_state=None, return_state=False):
        """Creep output for the input samples `v` (see the model protocol).

        Parameters
        ----------
        v : array_like, shape (n_samples,)
            Input samples.
        initial_state : array_like, shape (m,), optional
            Outputs of the m lags; default :meth:`default_state`.
        return_state : bool
            Also return the final state (to continue a record in chunks).

        Returns
        -------
        y : ndarray, shape (n_samples,)
            Output.
        state : ndarray, shape (m,)
            Final state; only with ``return_state=True``.

        Examples
        --------
        >>> c = CreepOperator([0.1, 1.0, 10.0], [0.01, 0.01, 0.01], dt=0.01)
        >>> y, s = c.simulate(np.ones(3), return_state=True)
        >>> np.round(y * 1e3, 4).tolist(), s.shape
        ([1.0611, 2.0307, 2.9173], (3,))
        """
        X, s = lag_bank(v, self.time_constants, self.dt, initial_state)
        y = np.zeros(X.shape[0])
        for j in range(self.n_states):
            y = y + self.coefficients[j] * X[:, j]
        return (y, s) if return_state else y

    def output_bounds(self, input_bounds=(-math.inf, math.inf)):
        """Bounds of the output for inputs within `input_bounds` (from rest).

        Parameters
        ----------
        input_bounds : (float, float)
            Range of the input; default unbounded.

        Returns
        -------
        (float, float)
            ``-+ sum_j |c_j| max(|lo|, |hi|)``; infinite for unbounded inputs.

        Examples
        --------
        >>> CreepOperator([0.1, 1.0], [0.01, 0.02], dt=0.01).output_bounds((-2.0, 2.0))
        (-0.06, 0.06)
        """
        m = max(abs(x) for x in as_bounds(input_bounds, "input_bounds"))
        g = float(np.sum(np.abs(self.coefficients))) * m if np.isfinite(m) else math.inf
        return (-g, g)

    def is_invertible(self):
        return Invertibility(["a creep operator alone is not invertible; invert the whole model"])

    def to_dict(self):
        return {"schema_version": SCHEMA_VERSION, "model": self._type,
                "time_constants": self.time_constants.tolist(),
                "coefficients": self.coefficients.tolist(), "dt": self.dt}

    @classmethod
    def _from_dict(cls, d):
        return cls(d["time_constants"], d["coefficients"], d["dt"])

    def __eq__(self, other):
        return type(other) is type(self) and self.to_dict() == other.to_dict()

    def __hash__(self):
        # consistent with __eq__ (equal descriptions): equal models hash equal, 0.0 and -0.0 included
        return hash(_frozen(self.to_dict()))

    def __repr__(self):
        return f"CreepOperator(m={self.n_states}, dt={self.dt!r})"


class DriftTerm:
    """A slow output trend that ignores the input (sensor or thermal drift).

    ``d(t) = sum_j polynomial[j-1] t^j + sum_m amplitudes[m] (1 - exp(-t / time_constants[m]))``
    with ``t = k dt`` for the k-th sample since the (virgin) start; the state
    is the sample count k, so chunks continue the same clock.  d(0) = 0 (a
    constant belongs to the offset of :class:`Parallel`).

    Parameters
    ----------
    dt : float
        Sampling time [s].
    polynomial : array_like, optional
        Coefficients of ``t, t^2, ...`` (no constant term).
    amplitudes : array_like, optional
        Amplitudes b_m of the settling terms ``b_m (1 - exp(-t / tau_m))``.
    time_constants : array_like, optional
        tau_m > 0 [s], one per amplitude.

    Examples
    --------
    >>> d = DriftTerm(0.5, polynomial=[0.1])
    >>> d.simulate(np.zeros(4)).tolist()
    [0.0, 0.05, 0.1, 0.15000000000000002]
    """

    _type = "DriftTerm"

    def __init__(self, dt, polynomial=(), amplitudes=(), time_constants=()):
        self.dt = as_scalar(dt, "dt", positive=True)
        self.polynomial = as_float_array(polynomial, "polynomial").reshape(-1)
        self.amplitudes = as_float_array(amplitudes, "amplitudes").reshape(-1)
        tau = as_float_array(time_constants, "time_constants").reshape(-1)
        if tau.size != self.amplitudes.size:
            raise ValueError(f"Parameter time_constants has {tau.size} entries but amplitudes has "
                             f"{self.amplitudes.size}; expected one time constant per amplitude")
        if np.any(~np.isfinite(tau)) or np.any(tau <= 0):
            raise ValueError(f"Parameter time_constants is {tau.tolist()} but should hold positive "
                             "finite times")
        for name, arr in (("polynomial", self.polynomial), ("amplitudes", self.amplitudes)):
            if not np.all(np.isfinite(arr)):
                raise ValueError(f"Parameter {name} holds non-finite values")
        self.time_constants = tau
        self.n_states = 1

    def default_state(self):
        """Sample count 0."""
        return np.zeros(1)

    def trend(self, t):
        """d(t) for times t [s].

        Parameters
        ----------
        t : float or array_like
            Times [s] since the start.

        Returns
        -------
        ndarray
            The trend, shaped as `t`.

        Examples
        --------
        >>> d = DriftTerm(1.0, amplitudes=[2.0], time_constants=[1.0])
        >>> np.round(d.trend([0.0, 1.0, np.inf]), 6).tolist()
        [0.0, 1.264241, 2.0]
        """
        t = as_float_array(t, "t")
        if np.isnan(t).any():
            raise ValueError("Parameter t holds NaN; expected times in seconds (inf gives the final value)")
        d = np.zeros_like(t)
        for j, a in enumerate(self.polynomial):
            d = d + a * t ** (j + 1)
        for b, tau in zip(self.amplitudes, self.time_constants):
            d = d - b * np.expm1(-t / tau)
        return d

    def simulate(self, v, initial_state=None, return_state=False):
        """The trend at the samples of `v` (their values are ignored).

        Parameters
        ----------
        v : array_like, shape (n_samples,)
            Input samples.
        initial_state : array_like, shape (1,), optional
            Sample count k at the first sample; default :meth:`default_state`.
        return_state : bool
            Also return the final state (to continue a record in chunks).

        Returns
        -------
        y : ndarray, shape (n_samples,)
            Output.
        state : ndarray, shape (1,)
            Final state; only with ``return_state=True``.

        Examples
        --------
        >>> d = DriftTerm(1.0, amplitudes=[2.0], time_constants=[1.0])
        >>> y, s = d.simulate(np.zeros(3), return_state=True)
        >>> np.round(y, 6).tolist(), s.tolist()
        ([0.0, 1.264241, 1.729329], [3.0])
        """
        x = as_signal(v, "v")
        s = self.default_state() if initial_state is None else as_state(initial_state, 1)
        k = s[0] + np.arange(x.size, dtype=np.float64)      # exact integers
        y = self.trend(k * self.dt)
        s = np.array([s[0] + x.size])
        return (y, s) if return_state else y

    def output_bounds(self):
        if self.polynomial.size and np.any(self.polynomial != 0):
            return (-math.inf, math.inf)
        g = float(np.sum(np.abs(self.amplitudes)))
        return (-g, g)

    def is_invertible(self):
        return Invertibility(["a drift term ignores its input: it has no inverse"])

    def to_dict(self):
        return {"schema_version": SCHEMA_VERSION, "model": self._type, "dt": self.dt,
                "polynomial": self.polynomial.tolist(), "amplitudes": self.amplitudes.tolist(),
                "time_constants": self.time_constants.tolist()}

    @classmethod
    def _from_dict(cls, d):
        return cls(d["dt"], d["polynomial"], d["amplitudes"], d["time_constants"])

    def __eq__(self, other):
        return type(other) is type(self) and self.to_dict() == other.to_dict()

    def __hash__(self):
        # consistent with __eq__ (equal descriptions): equal models hash equal, 0.0 and -0.0 included
        return hash(_frozen(self.to_dict()))

    def __repr__(self):
        return (f"DriftTerm(dt={self.dt!r}, polynomial={self.polynomial.tolist()}, "
                f"amplitudes={self.amplitudes.tolist()}, time_constants={self.time_constants.tolist()})")


# ----------------------------------------------------------------------------
# composition
# ----------------------------------------------------------------------------
def _check_block(b, name):
    for attr in ("simulate", "default_state", "n_states"):
        if not hasattr(b, attr):
            raise TypeError(f"Parameter {name} is {b!r} but should follow the model protocol "
                            f"(it has no {attr!r})")


class _Composite:
    def _split(self, state):
        out, k = [], 0
        for b in self.blocks:
            out.append(state[k:k + b.n_states])
            k += b.n_states
        return out

    def default_state(self):
        return np.concatenate([np.asarray(b.default_state(), dtype=np.float64) for b in self.blocks]
                              + [np.zeros(0)])

    def _state(self, initial_state):
        virgin = self.default_state()
        return virgin if initial_state is None else as_state(initial_state, self.n_states, virgin=virgin)

    def __eq__(self, other):
        return type(other) is type(self) and self.to_dict() == other.to_dict()

    def __hash__(self):
        # consistent with __eq__ (equal descriptions): equal models hash equal, 0.0 and -0.0 included
        return hash(_frozen(self.to_dict()))


class Series(_Composite):
    """Blocks in a chain: the output of each is the input of the next.

    ``Series(LinearStage.lag(tau, dt), PI(...))`` is a lag before the
    hysteresis (Hammerstein order reversed), ``Series(PI(...), stage)`` the
    hysteresis followed by the actuator's dynamics.

    Parameters
    ----------
    *blocks : models
        At least one block following the model protocol (``simulate``,
        ``default_state``, ``n_states``); the state of the chain is their
        states concatenated.

    Examples
    --------
    >>> from hystcomp import PI
    >>> m = Series(PI([0.5], [0.5], 1.0), LinearStage.lag(0.05, dt=0.01))
    >>> y, s = m.simulate(np.sin(np.linspace(0, 6, 100)), return_state=True)
    >>> m.n_states, s.size
    (2, 2)
    """

    _type = "Series"

    def __init__(self, *blocks):
        if not blocks:
            raise ValueError("Parameter blocks is empty; expected at least one block")
        for j, b in enumerate(blocks):
            _check_block(b, f"blocks[{j}]")
        self.blocks = tuple(blocks)
        self.n_states = sum(b.n_states for b in blocks)

    def simulate(self, v, initial_state=None, return_state=False):
        """Output of the chain (see the model protocol).

        Parameters
        ----------
        v : array_like, shape (n_samples,)
            Input samples.
        initial_state : array_like, shape (n_states,), optional
            The blocks' states concatenated, in chain order; default :meth:`default_state`.
        return_state : bool
            Also return the final state (to continue a record in chunks).

        Returns
        -------
        y : ndarray, shape (n_samples,)
            Output.
        state : ndarray, shape (n_states,)
            Final state; only with ``return_state=True``.

        Examples
        --------
        >>> from hystcomp import PI
        >>> m = Series(PI([0.5], [0.5], 1.0), LinearStage.lag(0.05, dt=0.01))
        >>> y, s = m.simulate([0.0, 1.0, 2.0], return_state=True)
        >>> np.round(y, 6).tolist(), np.round(s, 6).tolist()
        ([0.0, 0.117067, 0.462914], [1.5, 0.619944])
        """
        x = as_signal(v, "v")
        parts = self._split(self._state(initial_state))
        finals = []
        for b, s in zip(self.blocks, parts):
            x, f = b.simulate(x, initial_state=s if s.size else None, return_state=True)
            finals.append(np.asarray(f, dtype=np.float64).reshape(-1))
        s = np.concatenate(finals + [np.zeros(0)])
        return (x, s) if return_state else x

    def output_bounds(self):
        lo, hi = (-math.inf, math.inf)
        for b in self.blocks:
            try:
                lo, hi = b.output_bounds((lo, hi))
            except TypeError:
                lo, hi = b.output_bounds()
        return (lo, hi)

    def is_invertible(self):
        reasons = []
        for b in self.blocks:
            reasons += [f"{type(b).__name__}: {r}" for r in b.is_invertible().reasons] \
                if hasattr(b, "is_invertible") else [f"{type(b).__name__} has no is_invertible"]
        return Invertibility(reasons)

    def exact_inverse(self):
        """The chain of the blocks' exact inverses in reverse order."""
        check = self.is_invertible()
        if not check:
            raise ValueError("The chain has no inverse: " + "; ".join(check.reasons))
        return Series(*[b.exact_inverse() for b in reversed(self.blocks)])

    def to_dict(self):
        return {"schema_version": SCHEMA_VERSION, "model": self._type,
                "blocks": [b.to_dict() for b in self.blocks]}

    @classmethod
    def _from_dict(cls, d):
        return cls(*[model_from_dict(b) for b in d["blocks"]])

    def __repr__(self):
        return "Series(" + ", ".join(repr(b) for b in self.blocks) + ")"


class Parallel(_Composite):
    """Blocks fed by the same input, outputs summed, plus a constant offset.

    Parameters
    ----------
    *blocks : models
        At least one block following the model protocol; the state is their
        states concatenated.
    offset : float, optional
        Constant added to the sum.

    Examples
    --------
    >>> from hystcomp import PI
    >>> m = Parallel(PI([0.5], [0.5], 1.0), DriftTerm(0.1, polynomial=[1.0]), offset=2.0)
    >>> m.simulate([0.0, 0.0]).tolist()
    [2.0, 2.1]
    """

    _type = "Parallel"

    def __init__(self, *blocks, offset=0.0):
        if not blocks:
            raise ValueError("Parameter blocks is empty; expected at least one block")
        for j, b in enumerate(blocks):
            _check_block(b, f"blocks[{j}]")
        self.blocks = tuple(blocks)
        self.offset = as_scalar(offset, "offset")
        self.n_states = sum(b.n_states for b in blocks)

    def simulate(self, v, initial_state=None, return_state=False):
        """Sum of the blocks' outputs plus the offset (see the model protocol).

        Parameters
        ----------
        v : array_like, shape (n_samples,)
            Input samples.
        initial_state : array_like, shape (n_states,), optional
            The blocks' states concatenated, in order; default :meth:`default_state`.
        return_state : bool
            Also return the final state (to continue a record in chunks).

        Returns
        -------
        y : ndarray, shape (n_samples,)
            Output.
        state : ndarray, shape (n_states,)
            Final state; only with ``return_state=True``.

        Examples
        --------
        >>> from hystcomp import PI
        >>> m = Parallel(PI([0.5], [0.5], 1.0), DriftTerm(0.1, polynomial=[1.0]), offset=2.0)
        >>> y, s = m.simulate([0.0, 1.0], return_state=True)
        >>> np.round(y, 6).tolist(), s.tolist()
        ([2.0, 3.35], [0.5, 2.0])
        """
        x = as_signal(v, "v")
        parts = self._split(self._state(initial_state))
        y = np.full(x.size, self.offset)
        finals = []
        for b, s in zip(self.blocks, parts):
            yb, f = b.simulate(x, initial_state=s if s.size else None, return_state=True)
            y = y + yb
            finals.append(np.asarray(f, dtype=np.float64).reshape(-1))
        s = np.concatenate(finals + [np.zeros(0)])
        return (y, s) if return_state else y

    def output_bounds(self):
        lo = hi = self.offset
        for b in self.blocks:
            blo, bhi = b.output_bounds()
            lo, hi = lo + blo, hi + bhi
        return (lo, hi)

    def is_invertible(self):
        return Invertibility(["a sum of blocks has no block-wise inverse; use a numerical inverse"])

    def to_dict(self):
        return {"schema_version": SCHEMA_VERSION, "model": self._type, "offset": self.offset,
                "blocks": [b.to_dict() for b in self.blocks]}

    @classmethod
    def _from_dict(cls, d):
        return cls(*[model_from_dict(b) for b in d["blocks"]], offset=d.get("offset", 0.0))

    def __repr__(self):
        return "Parallel(" + ", ".join(repr(b) for b in self.blocks) + f", offset={self.offset!r})"


# register the parts so that hystcomp.models.model_from_dict rebuilds them
for _cls in (LinearStage, RateDependentPI, CreepOperator, DriftTerm, Series, Parallel):
    _MODELS.setdefault(_cls._type, _cls)

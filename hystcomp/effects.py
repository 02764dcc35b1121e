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
from ._validation import as_float_array, as_scalar, as_signal, as_state, as_thresholds, as_vector, as_weights
from .models import SCHEMA_VERSION, Invertibility, _MODELS, model_from_dict

__all__ = ["LinearStage", "RateDependentPI", "CreepOperator", "DriftTerm", "Series", "Parallel",
           "lag_bank"]


# ----------------------------------------------------------------------------
# compiled kernels (one loop over samples each)
# ----------------------------------------------------------------------------
@njit(cache=True)
def _ss_columns(A, B, C, D, U, X, out):
    """Filter every column of U (n, m) through the SISO system (A, B, C, D);
    X (m, ns) holds one state per column, updated in place."""
    n, m = U.shape
    ns = A.shape[0]
    xn = np.empty(ns)
    for j in range(m):
        x = X[j]
        for k in range(n):
            u = U[k, j]
            acc = D * u
            for a in range(ns):
                acc += C[a] * x[a]
            out[k, j] = acc
            for a in range(ns):
                s = B[a] * u
                for b in range(ns):
                    s += A[a, b] * x[b]
                xn[a] = s
            for a in range(ns):
                x[a] = xn[a]


@njit(cache=True)
def _lag_bank(v, a, x, out):
    """out[k, j] = x_j after sample k, x_j <- a_j x_j + (1 - a_j) v_k."""
    for k in range(v.size):
        vk = v[k]
        for j in range(a.size):
            xj = a[j] * x[j] + (1.0 - a[j]) * vk
            x[j] = xj
            out[k, j] = xj


@njit(cache=True)
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


def _frozen(x):
    """A hashable copy of a JSON-like description (dicts, lists, numbers, strings)."""
    if isinstance(x, dict):
        return tuple(sorted((k, _frozen(v)) for k, v in x.items()))
    if isinstance(x, (list, tuple)):
        return tuple(_frozen(v) for v in x)
    return x


def lag_bank(v, time_constants, dt, state=None):
    """Outputs of first-order lags ``x_j <- a_j x_j + (1 - a_j) v``,
    ``a_j = exp(-dt / tau_j)`` (exact discretisation of ``tau x' = v - x`` for
    an input held over each step), shape (n, m); and the final states.

    Parameters
    ----------
    v : array_like, shape (n,)
        Input samples.
    time_constants : array_like, shape (m,)
        tau_j > 0 [s].
    dt : float
        Sampling time [s].
    state : array_like, shape (m,), optional
        Lag outputs before the first sample; default 0 (at rest).

    Returns
    -------
    outputs : ndarray, shape (n, m)
        Output of lag j at sample k in ``outputs[k, j]``.
    state : ndarray, shape (m,)
        Final lag outputs (pass as `state` to continue).

    Examples
    --------
    >>> x, s = lag_bank([1.0, 1.0, 1.0], [1.0], dt=1.0)
    >>> np.round(x[:, 0], 4).tolist()
    [0.6321, 0.8647, 0.9502]
    """
    u = as_signal(v, "v")
    tau = as_vector(time_constants, "time_constants", positive=True)
    dt = as_scalar(dt, "dt", positive=True)
    x = np.zeros(tau.size) if state is None else as_state(state, tau.size, "state")
    out = np.empty((u.size, tau.size))
    _lag_bank(u, np.exp(-dt / tau), x, out)
    return out, x


# ----------------------------------------------------------------------------
# linear dynamic stage
# ----------------------------------------------------------------------------
class LinearStage:
    """A discrete SISO linear stage ``x+ = A x + B u, y = C x + D u`` at step `dt`.

    Use the factories :meth:`lag` (first-order lag) and :meth:`resonance`
    (lightly damped second-order mode), both with unit static gain.  In
    series after a hysteresis model it makes the output depend on the input's
    rate: loops widen and tilt with frequency, steps overshoot.

    Parameters
    ----------
    A : array_like, shape (ns, ns)
        State matrix.
    B, C : array_like, shape (ns,)
        Input and output vectors.
    D : float
        Feedthrough.
    dt : float
        Sampling time [s] (the record's sample spacing).
    kind : str, optional
        Label of the stage ("lag", "resonance", "inverse" from the
        factories; "custom" otherwise), used by ``repr`` and ``to_dict``.
    parameters : dict, optional
        The factory's physical parameters (e.g. ``{"time_constant": tau}``),
        kept for ``repr`` and ``to_dict``.

    Examples
    --------
    >>> lag = LinearStage.lag(0.01, dt=0.001)
    >>> y = lag.simulate(np.ones(5000))
    >>> round(float(y[-1]), 6), lag.n_states
    (1.0, 1)
    """

    _type = "LinearStage"

    def __init__(self, A, B, C, D, dt, kind="custom", parameters=None):
        A = np.atleast_2d(as_float_array(A, "A"))
        ns = A.shape[0]
        if A.ndim != 2 or A.shape != (ns, ns) or ns == 0:
            raise ValueError(f"Parameter A has shape {A.shape} but should be square, (ns, ns) with ns >= 1")
        B = as_float_array(B, "B").reshape(-1)
        C = as_float_array(C, "C").reshape(-1)
        for name, arr in (("B", B), ("C", C)):
            if arr.size != ns:
                raise ValueError(f"Parameter {name} has {arr.size} entries but should have {ns} "
                                 f"(A is {ns}x{ns})")
        for name, arr in (("A", A), ("B", B), ("C", C)):
            if not np.all(np.isfinite(arr)):
                raise ValueError(f"Parameter {name} holds non-finite values; expected finite numbers")
        self.A, self.B, self.C = np.ascontiguousarray(A), B, C
        self.D = as_scalar(D, "D")
        self.dt = as_scalar(dt, "dt", positive=True)
        self.n_states = ns
        if not isinstance(kind, str):
            raise TypeError(f"Parameter kind is {kind!r} but should be a string (a label)")
        self.kind = kind
        if parameters is not None and not isinstance(parameters, dict):
            raise TypeError(f"Parameter parameters is {parameters!r} but should be a dict of the "
                            "factory's physical parameters, or None")
        self.parameters = dict(parameters or {})

    @classmethod
    def lag(cls, time_constant, dt):
        """First-order lag ``tau y' = u - y``, exact for an input that moves
        linearly between samples (first-order hold), static gain 1:
        ``y_k = a y_{k-1} + b0 u_k + b1 u_{k-1}`` with ``a = exp(-h)``,
        ``h = dt/tau``, ``b0 = 1 - (1 - a)/h``, ``b1 = (1 - a)/h - a``.  Unlike
        the zero-order hold it keeps the lag of a time constant shorter than
        the sampling time (y ~ u - tau du/dt).

        Parameters
        ----------
        time_constant : float
            tau > 0 [s].
        dt : float
            Sampling time [s].

        Returns
        -------
        LinearStage

        Notes
        -----
        State-space form with ``x_k = a y_{k-1} + b1 u_{k-1}``:
        ``x_{k+1} = a x_k + (a b0 + b1) u_k``, ``y_k = x_k + b0 u_k``.

        Examples
        --------
        >>> st = LinearStage.lag(0.1, dt=0.01)
        >>> y = st.simulate(np.arange(2000) * 0.01)      # a ramp: y lags by tau
        >>> round(float(y[-1] - 19.99), 6)
        -0.1
        """
        tau = as_scalar(time_constant, "time_constant", positive=True)
        dt = as_scalar(dt, "dt", positive=True)
        h = dt / tau
        a = math.exp(-h)
        q = -math.expm1(-h) / h                       # (1 - a)/h without cancellation
        b0, b1 = 1.0 - q, q - a
        return cls([[a]], [a * b0 + b1], [1.0], b0, dt, kind="lag", parameters={"time_constant": tau})

    @classmethod
    def resonance(cls, frequency, damping, dt):
        """Second-order mode ``y'' + 2 zeta w y' + w^2 y = w^2 u`` (w = 2 pi
        frequency), discretised by the bilinear (Tustin) rule with the
        frequency prewarped (the discrete mode sits at `frequency`), static
        gain 1 (overshoot after steps for damping < 1/sqrt(2)).

        Parameters
        ----------
        frequency : float
            Natural frequency [Hz], below the Nyquist frequency ``0.5 / dt``.
        damping : float
            Damping ratio zeta > 0.
        dt : float
            Sampling time [s].

        Returns
        -------
        LinearStage

        Examples
        --------
        >>> st = LinearStage.resonance(20.0, 0.1, dt=1e-3)
        >>> y = st.simulate(np.ones(2000))
        >>> bool(y.max() > 1.5), round(float(y[-1]), 4)
        (True, 1.0)
        """
        f = as_scalar(frequency, "frequency", positive=True)
        z = as_scalar(damping, "damping", positive=True)
        dt = as_scalar(dt, "dt", positive=True)
        if f >= 0.5 / dt:
            raise ValueError(f"Parameter frequency is {f} Hz but should be below the Nyquist "
                             f"frequency {0.5 / dt} Hz of dt = {dt}")
        # prewarp so that the discrete mode sits exactly at `frequency`
        w = 2.0 / dt * math.tan(math.pi * f * dt)
        import control as ct

        # bilinear rule (I - A dt/2)^-1 (I + A dt/2), ...: python-control's
        # sample_system (scipy.signal.cont2discrete "bilinear") of the prewarped mode
        sysd = ct.sample_system(ct.ss([[0.0, 1.0], [-w * w, -2 * z * w]], [[0.0], [w * w]], [[1.0, 0.0]], 0.0),
                                dt, method="bilinear")
        Ad, Bd, Cd, Dd = sysd.A, sysd.B[:, 0], sysd.C[0], sysd.D[0, 0]
        return cls(Ad, Bd, Cd, float(Dd), dt, kind="resonance",
                   parameters={"frequency": f, "damping": z})

    def default_state(self):
        """At rest with zero input and output."""
        return np.zeros(self.n_states)

    def dc_gain(self):
        """Static gain ``C (I - A)^-1 B + D``."""
        return float(self.C @ np.linalg.solve(np.eye(self.n_states) - self.A, self.B) + self.D)

    def filter_columns(self, U, states=None):
        """Filter every column of U (n, m) from rest (or from `states`, (m, ns)).

        Parameters
        ----------
        U : array_like, shape (n, m)
            m input signals of n samples, one per column.
        states : array_like, shape (m, ns), optional
            State of the stage for each column before the first sample;
            default at rest (zeros).

        Returns
        -------
        outputs : ndarray, shape (n, m)
            The filtered columns.
        states : ndarray, shape (m, ns)
            Final states (pass as `states` to continue).

        Examples
        --------
        >>> lag = LinearStage.lag(0.01, dt=0.001)
        >>> out, X = lag.filter_columns(np.ones((3, 2)))
        >>> np.round(out[:, 1], 6).tolist(), X.shape
        ([0.048374, 0.138933, 0.220875], (2, 1))
        """
        U = np.ascontiguousarray(U, dtype=np.float64)
        X = np.zeros((U.shape[1], self.n_states)) if states is None else np.array(states, dtype=np.float64)
        out = np.empty_like(U)
        _ss_columns(self.A, self.B, self.C, self.D, U, X, out)
        return out, X

    def simulate(self, v, initial_state=None, return_state=False):
        """Output of the stage for the input samples `v` (see the model protocol).

        Parameters
        ----------
        v : array_like, shape (n_samples,)
            Input samples.
        initial_state : array_like, shape (n_states,), optional
            State vector x of the stage; default :meth:`default_state`.
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
        >>> lag = LinearStage.lag(0.01, dt=0.001)
        >>> y, s = lag.simulate(np.ones(3), return_state=True)
        >>> np.round(y, 6).tolist(), bool(np.allclose(lag.simulate(np.ones(6))[3:], lag.simulate(np.ones(3), s)))
        ([0.048374, 0.138933, 0.220875], True)
        """
        x = as_signal(v, "v")
        s = self.default_state() if initial_state is None else as_state(initial_state, self.n_states)
        X = s.reshape(1, -1).copy()
        out = np.empty((x.size, 1))
        _ss_columns(self.A, self.B, self.C, self.D, x.reshape(-1, 1), X, out)
        y = out[:, 0]
        return (y, X[0].copy()) if return_state else y

    def l1_gain(self, n=None):
        """Sum of ``|impulse response|`` (the peak-to-peak gain), truncated where
        the response has decayed below 1e-12 of its peak.

        Parameters
        ----------
        n : int, optional
            Number of impulse-response samples summed; default from the
            spectral radius of A (enough to decay below 1e-12), at most 10^6.

        Returns
        -------
        float
            The gain, raised by 1e-9 relative to cover rounding; inf for an
            unstable stage.

        Examples
        --------
        >>> round(LinearStage.lag(0.01, dt=0.001).l1_gain(), 6)   # monotone response: the DC gain
        1.0
        >>> round(LinearStage.resonance(20.0, 0.1, dt=1e-3).l1_gain(), 3)   # ringing: larger
        6.39
        """
        rho = max(abs(np.linalg.eigvals(self.A))) if self.n_states else 0.0
        if rho >= 1.0:
            return math.inf
        if n is None:
            n = int(min(10 ** 6, max(100, 30.0 / max(1e-12, -math.log(max(rho, 1e-300))))))
        imp = np.zeros(n)
        imp[0] = 1.0
        return float(np.sum(np.abs(self.simulate(imp)))) * (1.0 + 1e-9)

    def output_bounds(self, input_bounds=(-math.inf, math.inf)):
        """Bounds of the output for inputs within `input_bounds` (from rest).

        Parameters
        ----------
        input_bounds : (float, float)
            Range of the input; default unbounded.

        Returns
        -------
        (float, float)
            ``-+ l1_gain() max(|lo|, |hi|)``; infinite for unbounded inputs.

        Examples
        --------
        >>> lo, hi = LinearStage.lag(0.01, dt=0.001).output_bounds((-2.0, 2.0))
        >>> round(lo, 6), round(hi, 6)
        (-2.0, 2.0)
        """
        lo, hi = input_bounds
        m = max(abs(lo), abs(hi))
        if not np.isfinite(m):
            return (-math.inf, math.inf)
        g = self.l1_gain()
        return (-g * m, g * m)

    def is_invertible(self):
        """A causal stable inverse exists when D != 0 and the zeros (the
        eigenvalues of ``A - B C / D``) lie inside the unit circle."""
        if self.D == 0.0:
            return Invertibility(["D = 0: the stage delays its input by a sample; no causal inverse"])
        z = np.linalg.eigvals(self.A - np.outer(self.B, self.C) / self.D) if self.n_states else []
        if len(z) and max(abs(z)) >= 1.0:
            return Invertibility([f"the zeros {np.round(z, 6).tolist()} are not inside the unit circle"])
        return Invertibility([])

    def exact_inverse(self):
        """The inverse stage ``u = (y - C x)/D``, ``x+ = (A - B C/D) x + B y/D``."""
        check = self.is_invertible()
        if not check:
            raise ValueError("The stage has no causal stable inverse: " + "; ".join(check.reasons))
        return LinearStage(self.A - np.outer(self.B, self.C) / self.D, self.B / self.D,
                           -self.C / self.D, 1.0 / self.D, self.dt, kind="inverse")

    def inverse(self):
        return self.exact_inverse()

    def to_dict(self):
        return {"schema_version": SCHEMA_VERSION, "model": self._type, "A": self.A.tolist(),
                "B": self.B.tolist(), "C": self.C.tolist(), "D": self.D, "dt": self.dt,
                "kind": self.kind, "parameters": self.parameters}

    @classmethod
    def _from_dict(cls, d):
        return cls(d["A"], d["B"], d["C"], d["D"], d["dt"], kind=d.get("kind", "custom"),
                   parameters=d.get("parameters"))

    def __eq__(self, other):
        return type(other) is type(self) and self.to_dict() == other.to_dict()

    def __hash__(self):
        # consistent with __eq__ (equal descriptions): equal models hash equal, 0.0 and -0.0 included
        return hash(_frozen(self.to_dict()))

    def __repr__(self):
        if self.kind == "lag":
            return f"LinearStage.lag(time_constant={self.parameters['time_constant']!r}, dt={self.dt!r})"
        if self.kind == "resonance":
            p = self.parameters
            return (f"LinearStage.resonance(frequency={p['frequency']!r}, damping={p['damping']!r}, "
                    f"dt={self.dt!r})")
        return f"LinearStage(n_states={self.n_states}, dt={self.dt!r})"


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
        m = max(abs(input_bounds[0]), abs(input_bounds[1]))
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
        t = np.asarray(t, dtype=np.float64)
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

"""Discrete linear dynamics for the model parts of :mod:`hystcomp.effects`
(re-exported there): :class:`LinearStage` (a SISO state-space stage at a
sampling time, with the lag and resonance factories) and :func:`lag_bank`
(first-order lags, the basis of the creep operator).

Split from :mod:`hystcomp.effects` by concern (linear dynamics here, the
hysteresis-specific parts and their composition there); import them from
:mod:`hystcomp.effects`.
"""

import math

import numpy as np
from numba import njit

from ._validation import as_bounds, as_count, as_float_array, as_scalar, as_signal, as_state, as_vector
from .models import SCHEMA_VERSION, Invertibility

__all__ = ["LinearStage", "lag_bank"]


# ----------------------------------------------------------------------------
# compiled kernels (one loop over samples each)
# ----------------------------------------------------------------------------
@njit(cache=True, no_cfunc_wrapper=True, nogil=True)
def _ss_columns(A, B, C, D, U, X, out):
    """Filter every column of U (n, m) through the SISO system (A, B, C, D);
    X (m, ns) holds one state per column, updated in place.

    The loop runs over samples outside and columns inside, along U's rows
    in C order; first- and second-order stages (a lag, a resonance: the
    stages the diagnosis fits) keep their matrices in scalars.  The
    arithmetic of each column is the same in every branch, in the same
    order, so the branches give the same floats."""
    n, m = U.shape
    ns = A.shape[0]
    if ns == 1:
        a00, b0, c0 = A[0, 0], B[0], C[0]
        for k in range(n):
            for j in range(m):
                u = U[k, j]
                x0 = X[j, 0]
                out[k, j] = D * u + c0 * x0
                X[j, 0] = b0 * u + a00 * x0
        return
    if ns == 2:
        a00, a01, a10, a11 = A[0, 0], A[0, 1], A[1, 0], A[1, 1]
        b0, b1, c0, c1 = B[0], B[1], C[0], C[1]
        for k in range(n):
            for j in range(m):
                u = U[k, j]
                x0 = X[j, 0]
                x1 = X[j, 1]
                out[k, j] = D * u + c0 * x0 + c1 * x1
                X[j, 0] = b0 * u + a00 * x0 + a01 * x1
                X[j, 1] = b1 * u + a10 * x0 + a11 * x1
        return
    xn = np.empty(ns)
    for k in range(n):
        for j in range(m):
            u = U[k, j]
            acc = D * u
            for a in range(ns):
                acc += C[a] * X[j, a]
            out[k, j] = acc
            for a in range(ns):
                s = B[a] * u
                for b in range(ns):
                    s += A[a, b] * X[j, b]
                xn[a] = s
            for a in range(ns):
                X[j, a] = xn[a]


@njit(cache=True, no_cfunc_wrapper=True, nogil=True)
def _lag_bank(v, a, x, out):
    """out[k, j] = x_j after sample k, x_j <- a_j x_j + (1 - a_j) v_k."""
    for k in range(v.size):
        vk = v[k]
        for j in range(a.size):
            xj = a[j] * x[j] + (1.0 - a[j]) * vk
            x[j] = xj
            out[k, j] = xj


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


def _prewarped(frequency, dt):
    """The angular frequency [rad/s] of a continuous mode whose bilinear
    discretisation at step `dt` has its mode exactly at `frequency` [Hz]."""
    return 2.0 / dt * math.tan(math.pi * frequency * dt)


def _bilinear_mode(cls, w, damping, b, c, d, dt, **kw):
    """The second-order mode ``x' = [[0, 1], [-w^2, -2 zeta w]] x + b u``,
    ``y = c x + d u``, discretised by the bilinear rule: a `cls`
    (:class:`LinearStage`) with keyword arguments `kw`."""
    from scipy.signal import cont2discrete

    # bilinear rule (I - A dt/2)^-1 (I + A dt/2), ...: scipy.signal.cont2discrete
    # "bilinear" (what python-control's sample_system calls, without building two
    # StateSpace objects: a diagnosis builds these stages at every step of its search)
    sys_c = (np.array([[0.0, 1.0], [-w * w, -2 * damping * w]]), np.array(b, dtype=float)[:, None],
             np.array([c], dtype=float), np.array([[d]], dtype=float))
    Ad, Bd, Cd, Dd, _ = cont2discrete(sys_c, dt, method="bilinear")
    return cls(Ad, Bd[:, 0], Cd[0], float(Dd[0, 0]), dt, **kw)


# ----------------------------------------------------------------------------
# linear dynamic stage
# ----------------------------------------------------------------------------
class LinearStage:
    """A discrete SISO linear stage ``x+ = A x + B u, y = C x + D u`` at step `dt`.

    Use the factories :meth:`lag` (first-order lag), :meth:`resonance`
    (lightly damped second-order mode) and :meth:`recoil` (the stroke read
    from the ground while the base recoils on its mount), all with unit
    static gain.  In
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
        w = _prewarped(f, dt)
        return _bilinear_mode(cls, w, z, [0.0, w * w], [1.0, 0.0], 0.0, dt, kind="resonance",
                              parameters={"frequency": f, "damping": z})

    @classmethod
    def recoil(cls, frequency, damping, share, dt):
        """The stroke read from the ground while the stage's base recoils on a
        compliant mount: ``y = u - share * s^2 / (s^2 + 2 zeta w s + w^2) u``
        (w = 2 pi frequency), discretised by the bilinear rule with the
        frequency prewarped, as :meth:`resonance`; static gain 1.

        A stage of mass m pushing a base of mass M that sits on a mount of
        stiffness k and damping c: the base obeys ``(M + m) x_b'' + c x_b' +
        k x_b = -m u''`` (Newton's law for the two masses, the stroke u
        between them), so the ground sees ``u + x_b``, with ``share = m /
        (M + m)``, ``w^2 = k / (M + m)``, ``2 zeta w = c / (M + m)``.  Well
        below the mount's mode the reading is the stroke (no first-order
        phase: unlike a lag or a dead time); above it a share of the stroke
        is lost to the base's recoil, and near it the base rings.  Reaction
        forces exciting the base are a known limit of fast nanopositioners
        (Devasia, Eleftheriou & Moheimani, IEEE Trans. Control Syst.
        Technol. 15 (2007) 802, section II).

        Parameters
        ----------
        frequency : float
            The mount's natural frequency [Hz] (stage and base on the mount),
            below the Nyquist frequency ``0.5 / dt``.
        damping : float
            The mount's damping ratio zeta > 0.
        share : float
            The stage's share of the moving mass, m / (M + m), in (0, 1).
        dt : float
            Sampling time [s].

        Returns
        -------
        LinearStage

        Examples
        --------
        >>> st = LinearStage.recoil(5.0, 0.1, 0.2, dt=1e-3)
        >>> y = st.simulate(np.ones(4000))
        >>> round(float(y[0]), 2), round(float(y.max()), 2), round(float(y[-1]), 4), round(st.dc_gain(), 6)
        (0.8, 1.15, 1.0, 1.0)
        """
        f = as_scalar(frequency, "frequency", positive=True)
        z = as_scalar(damping, "damping", positive=True)
        a = as_scalar(share, "share", positive=True)
        dt = as_scalar(dt, "dt", positive=True)
        if f >= 0.5 / dt:
            raise ValueError(f"Parameter frequency is {f} Hz but should be below the Nyquist "
                             f"frequency {0.5 / dt} Hz of dt = {dt}")
        if a >= 1.0:
            raise ValueError(f"Parameter share is {a} but should be below 1 (the stage's share "
                             "of the moving mass, m / (M + m))")
        w = _prewarped(f, dt)
        # 1 - a s^2/(s^2 + 2 z w s + w^2) = (1 - a) + a (w^2 + 2 z w s)/(s^2 + 2 z w s + w^2)
        return _bilinear_mode(cls, w, z, [0.0, 1.0], [a * w * w, a * 2 * z * w], 1.0 - a, dt, kind="recoil",
                              parameters={"frequency": f, "damping": z, "share": a})

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
        U = np.ascontiguousarray(as_float_array(U, "U"))
        if U.ndim != 2 or not np.all(np.isfinite(U)):
            raise ValueError(f"Parameter U has shape {U.shape} (or non-finite values) but should be a finite "
                             "(n, m) array, one input column per signal")
        if states is None:
            X = np.zeros((U.shape[1], self.n_states))
        else:
            X = np.array(as_float_array(states, "states"), dtype=np.float64)
            if X.shape != (U.shape[1], self.n_states) or not np.all(np.isfinite(X)):
                raise ValueError(f"Parameter states has shape {X.shape} (or non-finite values) but should be "
                                 f"finite of shape ({U.shape[1]}, {self.n_states}): one state per column of U")
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
        else:
            n = as_count(n, "n", 1)
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
        lo, hi = as_bounds(input_bounds, "input_bounds")
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
        if self.kind == "recoil":
            p = self.parameters
            return (f"LinearStage.recoil(frequency={p['frequency']!r}, damping={p['damping']!r}, "
                    f"share={p['share']!r}, dt={self.dt!r})")
        return f"LinearStage(n_states={self.n_states}, dt={self.dt!r})"

"""Nonlinear loop analysis of hysteretic actuators: describing functions and sectors.

* :func:`describing_function` and :class:`DescribingFunction`: the complex
  gain of the first harmonic for a sinusoidal input of amplitude A.  Exact
  for the play family (a play of threshold r is python-control's
  :func:`control.friction_backlash_nonlinearity` with ``b = 2 r``), from the
  steady periodic cycle for every other model.  :class:`DescribingFunction`
  is a :class:`control.DescribingFunctionNonlinearity`, so
  :func:`control.describing_function_response` and
  :func:`control.describing_function_plot` predict limit cycles;
  :func:`limit_cycles` does the same for discrete-time loops.
* :func:`slope_bounds`: the smallest and largest incremental slope of a
  model (or of ``model o compensator``) over an input range, the sector of
  the actuator's increments.
* :func:`circle_criterion` (in :mod:`hystcomp._circle`): absolute stability
  of a loop with any nonlinearity in a sector, and how far the sector may
  grow.

References: A. Gelb, W. E. Vander Velde, *Multiple-Input Describing
Functions and Nonlinear System Design* (1968), ch. 2 and 5 (backlash);
H. K. Khalil, *Nonlinear Systems*, 3rd ed. (2002), section 7.1 (circle
criterion); W. Ye's thesis, eqs. 13, 18, 23, 30, 37 (play, PI, mGPI,
loading curves).

Examples
--------
>>> import numpy as np
>>> from hystcomp import PI
>>> model = PI([0.5, 1.0], [0.4, 0.2], p0=1.0)
>>> N = describing_function(model, [0.25, 2.0])
>>> N[0]                                   # below every threshold only p0 acts
np.complex128(1+0j)
>>> bool(N[1].imag < 0)                    # hysteresis lags
True
>>> slope_bounds(model, (-2.0, 2.0))
Sector(lower=1, upper=1.6, exact=True)
"""

import math

import numpy as np

import control as ct

from ._circle import CircleCriterion, circle_criterion
from .envelopes import Identity
from .models import MGPI, StopPI
from ._validation import as_count, as_float_array, as_scalar, as_vector

__all__ = ["describing_function", "DescribingFunction", "limit_cycles", "Sector", "slope_bounds",
           "CircleCriterion", "circle_criterion"]


def _amplitudes(amplitudes):
    a = as_float_array(amplitudes, "amplitudes")
    if a.ndim > 1:
        raise ValueError(f"Parameter amplitudes has shape {a.shape} but should be a scalar or a 1-D array")
    if not np.all(np.isfinite(a)) or np.any(a < 0):
        raise ValueError(f"Parameter amplitudes is {amplitudes!r} but should be finite and >= 0")
    return a


def _check_model(model):
    if not (hasattr(model, "simulate") and hasattr(model, "default_state")):
        raise TypeError(f"Parameter model is {type(model).__name__}; expected an hystcomp hysteresis model "
                        "(simulate, default_state)")


def _backlash_df(a, b):
    """Describing function of python-control's backlash of width b (play of
    threshold b/2), vectorised: 0 for A <= b/2 (Gelb & Vander Velde)."""
    a = np.asarray(a, dtype=np.float64)
    out = np.zeros(a.shape, dtype=complex)
    m = a > b / 2
    if b == 0:
        out[:] = 1.0
        return out
    x = 1.0 - b / a[m]
    x = np.clip(x, -1.0, 1.0)
    f = (np.arcsin(x) + x * np.sqrt(1.0 - x * x)) * 2.0 / np.pi
    out[m] = (1.0 + f) / 2.0 - 1j * (2.0 * b / a[m] - (b / a[m]) ** 2) / np.pi
    return out


# Gauss-Legendre nodes for the smooth pieces of an mGPI cycle
_GL_X, _GL_W = np.polynomial.legendre.leggauss(48)


def _integrate(f, lo, hi):
    """First-harmonic integrals of f(theta) over [lo, hi]: (int f sin, int f cos)."""
    if hi <= lo:
        return 0.0, 0.0
    th = 0.5 * (hi - lo) * _GL_X + 0.5 * (hi + lo)
    w = 0.5 * (hi - lo) * _GL_W
    y = f(th)
    return float(np.sum(w * y * np.sin(th))), float(np.sum(w * y * np.cos(th)))


def _mgpi_df(model, a):
    """Symmetric mGPI: each operator's steady cycle is gamma of the play's,
    known in closed form; one Gauss-Legendre quadrature per smooth piece."""
    g = model.envelope_left
    out = np.zeros(a.shape, dtype=complex)
    for j, amp in np.ndenumerate(a):
        if amp == 0:
            out[j] = model.p0 * float(g.derivative(0.0))
            continue
        s0, c0 = 0.0, 0.0
        # r = 0 operator: gamma(A sin theta) over theta in [-pi/2, 3pi/2)
        for lo, hi in ((-np.pi / 2, np.pi / 2), (np.pi / 2, 3 * np.pi / 2)):
            s, c = _integrate(lambda th: g(amp * np.sin(th)), lo, hi)
            s0 += model.p0 * s
            c0 += model.p0 * c
        for r, p in zip(model._r, model._p):
            if amp <= r:
                continue  # the play does not move: a constant, no first harmonic
            th_r = math.asin(2 * r / amp - 1.0)          # rising branch leaves the plateau
            th_f = math.pi - math.asin(1.0 - 2 * r / amp)  # falling branch leaves the plateau
            pieces = (
                (-np.pi / 2, th_r, lambda th: np.full(th.shape, float(g(-amp + r)))),
                (th_r, np.pi / 2, lambda th: g(amp * np.sin(th) - r)),
                (np.pi / 2, th_f, lambda th: np.full(th.shape, float(g(amp - r)))),
                (th_f, 3 * np.pi / 2, lambda th: g(amp * np.sin(th) + r)),
            )
            for lo, hi, f in pieces:
                s, c = _integrate(f, lo, hi)
                s0 += p * s
                c0 += p * c
        out[j] = (s0 + 1j * c0) / (np.pi * amp)
    return out


def _numeric_df(model, a, samples_per_cycle, cycles):
    m = int(samples_per_cycle)
    th = 2 * np.pi * np.arange(m) / m
    sin, cos = np.sin(th), np.cos(th)
    out = np.zeros(a.shape, dtype=complex)
    for j, amp in np.ndenumerate(a):
        if amp == 0:
            out[j] = np.nan
            continue
        v = amp * np.tile(sin, cycles + 1)
        y = np.asarray(model.simulate(v), dtype=np.float64)[-m:]  # pre-cycled at THIS amplitude
        out[j] = 2.0 / (amp * m) * (y @ sin + 1j * (y @ cos))
    return out


def describing_function(model, amplitudes, samples_per_cycle=2048, cycles=3):
    """Describing function N(A) of a hysteresis model, for each amplitude.

    ``N(A) = (1/(pi A)) int_0^{2 pi} w(theta) (sin theta + j cos theta) d theta``
    over the steady cycle of the output w for the input ``A sin theta``
    (python-control's convention: a lagging loop has ``Im N < 0``).

    * PI (eq. 18): exact, ``N = p0 + sum_i p_i N_b(A; 2 r_i)`` with N_b the
      backlash describing function of :func:`control.friction_backlash_nonlinearity`
      (the play of threshold r is a backlash of width b = 2 r; N_b = 0 for
      A <= r).
    * StopPI: exact, the stop is ``v - play``: ``N = p0 + sum_i p_i (1 - N_b(A; 2 r_i))``.
    * Symmetric mGPI (eq. 25): the steady cycle of each operator is the
      envelope of the play's cycle, known in closed form, so N is one
      integral per operator (48-point Gauss-Legendre per smooth piece:
      exact to about 1e-12 for smooth envelopes).
    * Every other model: numerically from the last of ``cycles + 1``
      periods of ``A sin``, simulated from the virgin state at each
      amplitude separately (so each amplitude is pre-cycled at itself;
      python-control's own :func:`control.describing_function` pre-cycles
      only at the smallest amplitude, which is wrong for nonlinearities
      with memory).  Rate-dependent models see one period as
      `samples_per_cycle` of their samples.

    Parameters
    ----------
    model : HysteresisModel
        The actuator (any object with ``simulate`` and ``default_state``).
    amplitudes : array_like
        Input amplitudes A >= 0.
    samples_per_cycle : int, optional
        Samples per period for the numerical path (default 2048; a
        multiple of 4 puts samples on the extremes).
    cycles : int, optional
        Pre-cycles before the measured period (default 3).

    Returns
    -------
    ndarray of complex
        N(A), the shape of `amplitudes`.  At A = 0: the small-signal slope
        for the analytic families, nan for the numerical path.

    Examples
    --------
    >>> import control as ct
    >>> from hystcomp import PI
    >>> N = describing_function(PI([1.0], [1.0], p0=0.0), [3.0])[0]
    >>> bool(abs(N - ct.friction_backlash_nonlinearity(2.0).describing_function(3.0)) < 1e-15)
    True
    """
    _check_model(model)
    a = _amplitudes(amplitudes)
    _numeric_options(samples_per_cycle, cycles)
    if isinstance(model, MGPI) and model.symmetric and isinstance(model.envelope_left, Identity):
        out = np.full(a.shape, complex(model.p0))
        for r, p in zip(model._r, model._p):
            out += p * _backlash_df(a, 2 * r)
        return out
    if isinstance(model, StopPI):
        out = np.full(a.shape, complex(model.p0))
        for r, p in zip(model._r, model._p):
            out += p * (1.0 - _backlash_df(a, 2 * r))
        return out
    if isinstance(model, MGPI) and model.symmetric:
        return _mgpi_df(model, a)
    n, c = _numeric_options(samples_per_cycle, cycles)
    return _numeric_df(model, a, n, c)


def _numeric_options(samples_per_cycle, cycles):
    return as_count(samples_per_cycle, "samples_per_cycle", 16), as_count(cycles, "cycles", 0)


class DescribingFunction(ct.DescribingFunctionNonlinearity):
    """A hysteresis model as a python-control describing-function nonlinearity.

    ``ct.describing_function_response(L, DescribingFunction(model), A)`` and
    ``ct.describing_function_plot(...)`` then find the intersections of
    ``L(j w)`` with ``-1/N(A)``: the amplitudes (at the model's input) and
    frequencies of the predicted limit cycles.  :meth:`describing_function`
    is :func:`describing_function` (analytic where it can be).

    Calling the object evaluates the model one sample at a time from its
    :attr:`state` (a nonlinearity with memory, like python-control's
    backlash); :meth:`reset` returns it to the virgin state.

    Parameters
    ----------
    model : HysteresisModel
        The actuator.
    samples_per_cycle, cycles : int, optional
        For the numerical path of :func:`describing_function`.

    Examples
    --------
    >>> import numpy as np
    >>> import control as ct
    >>> from hystcomp import PI
    >>> F = DescribingFunction(PI([1.0], [1.0], p0=0.0))
    >>> [F(x) for x in (0.0, 2.0, 1.5)]                 # a play of threshold 1
    [0.0, 1.0, 1.0]
    >>> bool(abs(ct.describing_function(F, 3.0) - F.describing_function(3.0)) < 1e-15)
    True
    """

    def __init__(self, model, samples_per_cycle=2048, cycles=3):
        super().__init__()
        _check_model(model)
        self.model = model
        self.samples_per_cycle, self.cycles = _numeric_options(samples_per_cycle, cycles)
        self.state = model.default_state()

    def reset(self):
        """Return :attr:`state` to the model's virgin state."""
        self.state = self.model.default_state()

    def __call__(self, x):
        y, self.state = self.model.simulate(np.array([float(x)]), initial_state=self.state, return_state=True)
        return float(y[0])

    def _isstatic(self):
        return False

    def describing_function(self, A):
        """N(A) for a scalar amplitude (see :func:`describing_function`).

        Parameters
        ----------
        A : float
            Input amplitude, >= 0.

        Returns
        -------
        complex
        """
        A = as_scalar(A, "A", nonnegative=True)
        return complex(describing_function(self.model, np.array([A]), self.samples_per_cycle,
                                           self.cycles)[0])

    def __repr__(self):
        return f"DescribingFunction({self.model!r})"


def limit_cycles(loop, model, amplitudes, omega=None):
    """Limit cycles predicted by the describing function: ``1 + L(j w) N(A) = 0``.

    Works for continuous and discrete-time `loop` (on the unit circle,
    ``z = exp(j w dt)``, up to the Nyquist frequency;
    :func:`control.describing_function_response` evaluates L at ``s = j w``
    only).  Each crossing of the Nyquist polyline of L with the polyline of
    ``-1/N(A)`` is refined by a Newton iteration on ``1 + L N = 0``.

    Parameters
    ----------
    loop : control.LTI
        The linear part L (SISO) in negative feedback with the model: the
        model's input is ``-y`` of L, its output L's input.
    model : HysteresisModel
        The nonlinearity.
    amplitudes : array_like
        Increasing amplitudes at the model's input to scan.
    omega : array_like, optional
        Frequencies [rad/s] to scan; default 4000 log-spaced points over
        the loop's poles and zeros (up to the Nyquist frequency).

    Returns
    -------
    list of (float, float)
        ``(amplitude, frequency_hz)`` of each predicted limit cycle.

    Examples
    --------
    >>> import control as ct
    >>> from hystcomp import PI
    >>> from hystcomp.iosys import discretize, pid, piezo_stage
    >>> from hystcomp.demo import demo_actuator
    >>> L = ct.series(discretize(piezo_stage(), 1e-4), pid(0.0, 150.0, 0.0, 1e-4))
    >>> [(round(a, 1), round(f, 1)) for a, f in limit_cycles(L, demo_actuator(), np.geomspace(0.01, 300, 300))]
    [(147.5, 299.8)]
    """
    from ._circle import _frequency_grid, _response

    if not isinstance(loop, ct.LTI) or loop.ninputs != 1 or loop.noutputs != 1:
        raise TypeError(f"Parameter loop is {loop!r}; expected a SISO python-control LTI system")
    a = _amplitudes(amplitudes).reshape(-1)
    if a.size < 2 or np.any(np.diff(a) <= 0):
        raise ValueError("Parameter amplitudes should hold at least two increasing values")
    w = _frequency_grid(loop, 4000) if omega is None else as_vector(omega, "omega", min_length=2,
                                                                     positive=True, increasing=True)
    N = describing_function(model, a)
    Lw = _response(loop, w)
    found = []
    e = Lw[1:] - Lw[:-1]
    for i in range(a.size - 1):
        n0, n1 = N[i], N[i + 1]
        if not (np.isfinite(n0) and np.isfinite(n1)) or n0 == 0 or n1 == 0:
            continue
        c0 = -1.0 / n0
        d = -1.0 / n1 - c0
        # the segment c0 -> c0 + d against each segment of the Nyquist polyline: c0 + s d = L_k + u e_k
        den = d.real * e.imag - d.imag * e.real
        ok = np.abs(den) > 1e-300
        q = Lw[:-1] - c0
        safe = np.where(ok, den, 1.0)
        s = np.where(ok, (q.real * e.imag - q.imag * e.real) / safe, -1.0)
        u = np.where(ok, (q.real * d.imag - q.imag * d.real) / safe, -1.0)
        for k in np.nonzero(ok & (s >= 0) & (s < 1) & (u >= 0) & (u < 1))[0]:
            amp = a[i] + s[k] * (a[i + 1] - a[i])
            om = w[k] + u[k] * (w[k + 1] - w[k])
            found.append(_refine(loop, model, amp, om))
    return found


def _refine(loop, model, amp, om):
    from ._circle import _response

    x = np.array([amp, om], dtype=float)
    for _ in range(30):
        def f(z):
            n = describing_function(model, np.array([z[0]]))[0]
            g = 1.0 + complex(_response(loop, np.array([z[1]]))[0]) * n
            return np.array([g.real, g.imag])

        f0 = f(x)
        if np.max(np.abs(f0)) < 1e-12:
            break
        J = np.empty((2, 2))
        for j in range(2):
            h = 1e-7 * max(abs(x[j]), 1e-6)
            xp = x.copy()
            xp[j] += h
            J[:, j] = (f(xp) - f0) / h
        try:
            step = np.linalg.solve(J, -f0)
        except np.linalg.LinAlgError:
            break
        x = x + step
        if x[0] <= 0 or x[1] <= 0:
            return float(amp), float(om / (2 * np.pi))
    return float(x[0]), float(x[1] / (2 * np.pi))


class Sector:
    """Smallest and largest incremental slope of an actuator: a sector [lower, upper].

    Unpacks as ``lower, upper = sector``.

    Parameters
    ----------
    lower, upper : float
        The slopes.
    exact : bool
        True when computed from the model's structure (play family),
        False when estimated from sampled input histories.

    Examples
    --------
    >>> lo, hi = Sector(1.5, 7.3, exact=True)
    >>> hi / lo
    4.866666666666666
    """

    def __init__(self, lower, upper, exact):
        self.lower = as_scalar(lower, "lower")
        self.upper = as_scalar(upper, "upper")
        if self.upper < self.lower:
            raise ValueError(f"Parameters lower = {self.lower} and upper = {self.upper} should satisfy "
                             "lower <= upper")
        self.exact = bool(exact)

    def __iter__(self):
        return iter((self.lower, self.upper))

    def __repr__(self):
        return f"Sector(lower={self.lower:.6g}, upper={self.upper:.6g}, exact={self.exact})"


def _range(input_range):
    try:
        lo, hi = float(input_range[0]), float(input_range[1])
    except (TypeError, IndexError, ValueError):
        raise ValueError(f"Parameter input_range is {input_range!r} but should be (lo, hi)") from None
    if not (np.isfinite(lo) and np.isfinite(hi) and lo < hi):
        raise ValueError(f"Parameter input_range is {input_range!r} but should be finite with lo < hi")
    return lo, hi


def _play_family_slopes(model, lo, hi, n_samples):
    """Exact slope range of PI / StopPI / symmetric mGPI over [lo, hi]
    (histories from the virgin state at 0, reversals anywhere inside)."""
    r = model._r
    p = model._p
    if isinstance(model, StopPI):
        # after travel 2 s from a reversal the stops of threshold r_i < s are saturated
        s_max = max(abs(lo), abs(hi))
        sums = model.p0 + np.sum(p) - np.concatenate([[0.0], np.cumsum(p)])
        active = np.concatenate([[True], r < s_max])
        vals = sums[active]
        return float(vals.min()), float(vals.max())
    g = model.envelope_left
    if isinstance(g, Identity):
        s_max = max(abs(lo), abs(hi))
        sums = model.p0 + np.concatenate([[0.0], np.cumsum(p)])
        active = np.concatenate([[True], r < s_max])
        vals = sums[active]
        return float(vals.min()), float(vals.max())
    v = np.union1d(np.linspace(lo, hi, 20 * int(n_samples) + 1), np.clip(np.concatenate([r, -r, lo + 2 * r, hi - 2 * r]),
                                                                 lo, hi))
    smin, smax = np.inf, -np.inf
    for sign in (1.0, -1.0):   # rising (z = v - r) and falling (z = v + r) branches
        if sign > 0:
            m_max = np.maximum((v - lo) / 2, v)
        else:
            m_max = np.maximum((hi - v) / 2, -v)
        base = model.p0 * g.derivative(v)
        terms = p[None, :] * g.derivative(v[:, None] - sign * r[None, :])
        partial = base[:, None] + np.concatenate([np.zeros((v.size, 1)), np.cumsum(terms, axis=1)], axis=1)
        allowed = np.concatenate([np.ones((v.size, 1), bool), r[None, :] < m_max[:, None]], axis=1)
        smin = min(smin, float(np.min(np.where(allowed, partial, np.inf))))
        smax = max(smax, float(np.max(np.where(allowed, partial, -np.inf))))
    return smin, smax


def _probe_input(lo, hi, n_samples, seed=0):
    """Input histories inside [lo, hi]: virgin loading to both ends, full
    sweeps, and nested reversals at random levels, in steps of
    (hi - lo) / n_samples."""
    rng = np.random.default_rng(seed)
    h = (hi - lo) / n_samples
    points = [0.0 if lo <= 0 <= hi else lo, hi, lo, hi, lo]
    centre, width = rng.uniform(lo, hi, 40), rng.uniform(0.0, 1.0, 40)
    for c, wdt in zip(centre, width):
        a = wdt * min(c - lo, hi - c)
        points += [c + a, c - a, c + a / 3, c - a / 3]
    points += list(rng.uniform(lo, hi, 40))
    segs = []
    for x0, x1 in zip(points[:-1], points[1:]):
        n = max(int(abs(x1 - x0) / h), 1)
        segs.append(np.linspace(x0, x1, n + 1)[1:])
    return np.concatenate([[points[0]], *segs])


def slope_bounds(model, input_range, compensator=None, n_samples=2000):
    """Smallest and largest incremental slope dw/dv of an actuator over an input range.

    Along any input history inside the range, ``dw = k(t) dv`` with
    ``lower <= k(t) <= upper``: the actuator's increments lie in the sector
    [lower, upper] that :func:`circle_criterion` takes.

    * PI (eq. 18), StopPI: exact.  After a reversal the branch has the
      slope of the loading curve (eq. 30) at half the travel, phi'(d/2), so
      the slopes are the partial sums ``p0 + sum_{r_i < s} p_i`` for s up to
      the largest excursion from the virgin state, ``max(|lo|, |hi|)``
      (StopPI: ``p0 + sum_{r_i >= s} p_i``).  With positive weights: p0
      right after a reversal, ``p0 + sum p_i`` on a long stroke.
    * Symmetric mGPI (eq. 25): the slope at input v with the operators of
      threshold below m moving is ``p0 gamma'(v) + sum_{r_i < m} p_i
      gamma'(v -+ r_i)``; exact in m, evaluated on ``20 n_samples`` points of v
      (and the breakpoints ``+-r_i``, ``lo + 2 r_i``, ``hi - 2 r_i``).
    * Any other model, and ``model o compensator``: estimated from sampled
      input histories (virgin loading, full sweeps and nested reversals at
      random levels, steps of ``(hi - lo)/n_samples``): an inner estimate
      (``exact=False``).

    Parameters
    ----------
    model : HysteresisModel
        The actuator.
    input_range : (float, float)
        (lo, hi), the range of the actuator's input v, or of the
        compensator's input u when `compensator` is given.
    compensator : compensator object or compensator_system block, optional
        A compensator ``C`` (e.g. the exact inverse of an identified,
        mismatched model; with ``nominal_gain``, u is scaled by it first):
        the slopes are those of ``u -> model(C(u))``.
    n_samples : int, optional
        Resolution (default 2000).

    Returns
    -------
    Sector

    Examples
    --------
    >>> from hystcomp import PI
    >>> true = PI([0.5, 1.0], [0.4, 0.2], p0=1.0)
    >>> slope_bounds(true, (-2, 2))
    Sector(lower=1, upper=1.6, exact=True)
    >>> fit = PI([0.5, 1.0], [0.3, 0.2], p0=1.1)      # a mismatched identification
    >>> lo, hi = slope_bounds(true, (-2, 2), compensator=fit.exact_inverse())
    >>> 0.85 < lo < 1.0 < hi < 1.1                     # near 1, not exactly 1
    True
    """
    _check_model(model)
    lo, hi = _range(input_range)
    n = as_count(n_samples, "n_samples", 10)
    if compensator is None:
        if isinstance(model, (StopPI,)) or (isinstance(model, MGPI) and model.symmetric):
            a, b = _play_family_slopes(model, lo, hi, n)
            return Sector(a, b, True)
        u = _probe_input(lo, hi, n)
        w = np.asarray(model.simulate(u))
    else:
        comp, gain = compensator, 1.0
        if hasattr(compensator, "compensator") and hasattr(compensator, "nominal_gain"):
            comp, gain = compensator.compensator, float(compensator.nominal_gain)
        if not hasattr(comp, "simulate"):
            raise TypeError(f"Parameter compensator is {compensator!r}; expected a compensator "
                            "(simulate) or a hystcomp.iosys.compensator_system block")
        u = _probe_input(lo, hi, n)
        import warnings

        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # targets out of reach are clipped: that is part of the slope
            v = np.asarray(comp.simulate(gain * u))
        w = np.asarray(model.simulate(v))
    du = np.diff(u)
    k = np.diff(w)[du != 0] / du[du != 0]
    return Sector(float(k.min()), float(k.max()), False)

"""The circle criterion (re-exported by :mod:`hystcomp.analysis`)."""

import numpy as np

import control as ct

__all__ = ["CircleCriterion", "circle_criterion"]


def _response(sys, omega):
    """Complex frequency response of a SISO LTI at `omega` [rad/s] (unit
    circle when discrete): ``C (xI - A)^-1 B + D`` solved for all points at once."""
    omega = np.asarray(omega, dtype=float)
    s = ct.ss(sys)
    x = np.exp(1j * omega * sys.dt) if sys.isdtime(strict=True) else 1j * omega
    flat = x.reshape(-1)
    n = s.nstates
    D = complex(np.asarray(s.D)[0, 0])
    if n == 0:
        return np.full(omega.shape, D)
    A, B, C = (np.asarray(m, dtype=complex) for m in (s.A, s.B, s.C))
    M = flat[:, None, None] * np.eye(n)[None] - A[None]
    with np.errstate(all="ignore"):
        try:
            sol = np.linalg.solve(M, np.broadcast_to(B, (flat.size, n, 1)))
            val = (C[None] @ sol)[:, 0, 0] + D
        except np.linalg.LinAlgError:  # a point on a pole: evaluate one by one
            val = np.array([complex(np.asarray(sys(z)).reshape(-1)[0]) if np.isfinite(z) else np.nan
                            for z in flat])
    return val.reshape(omega.shape)


def _frequency_grid(sys, n):
    """Log-spaced frequencies over the system's poles and zeros, plus each
    lightly damped pole's neighbourhood (rad/s); up to pi/dt when discrete."""
    s = ct.ss(sys)
    p = np.asarray(np.linalg.eigvals(s.A), dtype=complex) if s.nstates else np.zeros(0)
    z = np.asarray(ct.zeros(sys), dtype=complex) if s.nstates else np.zeros(0)
    dtime = sys.isdtime(strict=True)
    if dtime:
        p = np.log(p[p != 0]) / sys.dt
        z = np.log(z[(z != 0) & np.isfinite(z)]) / sys.dt
    mags = np.abs(np.concatenate([p, z]))
    mags = mags[(mags > 0) & np.isfinite(mags)]
    lo = (mags.min() if mags.size else 1.0) / 1e3
    hi = np.pi / sys.dt if dtime else (mags.max() if mags.size else 1.0) * 1e3
    lo = min(lo, hi / 1e6)
    grid = [np.geomspace(lo, hi, n)]
    for pole in p:
        wn = abs(pole)
        if pole.imag > 0 and wn > 0:
            zeta = -pole.real / wn
            width = max(abs(zeta), 1e-4) * wn
            grid.append(np.clip(wn + width * np.linspace(-8, 8, 401), lo, hi))
    return np.unique(np.concatenate(grid))


def _cl_stable(sys, k):
    """Is the loop with the linear gain k (u = -k y) stable?"""
    s = ct.ss(sys)
    if s.nstates == 0:
        return bool(1 + k * s.D[0, 0] != 0)
    den = 1.0 + k * float(s.D[0, 0])
    if den == 0:
        return False
    A = np.asarray(s.A) - k / den * np.asarray(s.B) @ np.asarray(s.C)
    ev = np.linalg.eigvals(A)
    if sys.isdtime(strict=True):
        return bool(np.all(np.abs(ev) < 1 - 1e-12))
    return bool(np.all(ev.real < -1e-12 * max(1.0, np.max(np.abs(ev)))))


class CircleCriterion:
    """Result of :func:`circle_criterion`.

    Every parameter is kept as the attribute of the same name.

    Parameters
    ----------
    stable : bool
        True if the criterion proves absolute stability for every
        nonlinearity in the sector.
    sector : (float, float)
        The sector [k1, k2] tested.
    upper_limit : float
        The largest k2 for which the sector [k1, k2] passes (inf when every
        k2 does, nan when the loop with the gain k1 is itself unstable).
    gain_margin : float
        The largest factor g by which the whole sector may be scaled,
        ``[g k1, g k2]``, continuing from g = 1 (if the criterion fails at
        g = 1: the largest g < 1 where it holds; 0 if none).
    worst_frequency_hz : float
        Where ``Re[(1 + k2 L)/(1 + k1 L)]`` is smallest.
    message : str
        Why the criterion holds or fails, in words.

    Examples
    --------
    >>> import control as ct
    >>> res = circle_criterion(ct.tf([1], [1, 1]), (0.0, 100.0))
    >>> res.stable, res.upper_limit
    (True, inf)
    """

    def __init__(self, stable, sector, upper_limit, gain_margin, worst_frequency_hz, message):
        self.stable = stable
        self.sector = sector
        self.upper_limit = upper_limit
        self.gain_margin = gain_margin
        self.worst_frequency_hz = worst_frequency_hz
        self.message = message

    def __bool__(self):
        return bool(self.stable)

    def __repr__(self):
        return (f"CircleCriterion(stable={self.stable}, sector=({self.sector[0]:.6g}, {self.sector[1]:.6g}), "
                f"upper_limit={self.upper_limit:.6g}, gain_margin={self.gain_margin:.6g})")


def _upper(Lw, k1):
    """(largest k2, index of the worst frequency) given k1, from
    Re(1 + (k2 - k1) M) > 0 with M = L / (1 + k1 L)."""
    with np.errstate(divide="ignore", invalid="ignore"):
        M = Lw / (1.0 + k1 * Lw)
    re = np.where(np.isfinite(M), M.real, np.inf)
    j = int(np.argmin(re))
    if re[j] >= 0:
        return np.inf, j
    return k1 - 1.0 / re[j], j


def circle_criterion(loop, bounds, n_frequencies=20000):
    """Absolute stability of a loop with any nonlinearity in a sector (circle criterion).

    The loop: ``y = L u``, ``u = -phi(t, y)`` with
    ``k1 <= phi(t, y)/y <= k2``.  Absolutely stable (Khalil, *Nonlinear
    Systems*, 3rd ed., Theorem 7.1) when ``Z = (1 + k2 L)/(1 + k1 L)`` is
    strictly positive real: the loop with the linear gain k1 is stable and
    ``Re Z(j w) > 0`` at every frequency (for 0 < k1 < k2 this is "the
    Nyquist curve of L avoids the disc on [-1/k1, -1/k2] and encircles it
    as often as L has unstable poles").  Discrete-time `loop`: the same
    on the unit circle, ``z = exp(j w dt)`` (stability: poles inside it).
    With ``M = L/(1 + k1 L)`` the condition is
    ``k2 < k1 - 1/min_w Re M(j w)``, which gives :attr:`CircleCriterion.upper_limit`
    in closed form.

    For a hysteretic actuator, pass its :func:`slope_bounds`: along any
    trajectory its increments obey ``dw = k(t) dv`` with k(t) in the
    sector, so the loop's increments are a loop with a time-varying gain
    in the sector, and the criterion makes them decay (the loop is
    incrementally stable for any reference).  For a degenerate sector
    [k, k] the result is the linear loop's: :attr:`CircleCriterion.gain_margin`
    is then the gain margin of :func:`control.stability_margins` (when the
    loop is not conditionally stable).

    Parameters
    ----------
    loop : control.LTI
        The linear part L (SISO; continuous or discrete), e.g.
        ``controller * plant`` without the actuator.
    bounds : (float, float) or Sector
        The sector [k1, k2], k1 <= k2 (e.g. :func:`slope_bounds`).
    n_frequencies : int, optional
        Grid size (default 20000 log-spaced points, plus 401 around each
        lightly damped pole); the minimum is then refined.

    Returns
    -------
    CircleCriterion

    Examples
    --------
    >>> import control as ct
    >>> L = ct.tf([1], [1, 3, 3, 1])                   # 1/(s+1)^3: linear gain margin 8
    >>> round(circle_criterion(L, (1.0, 1.0)).gain_margin, 9)   # degenerate sector: the linear margin
    8.0
    >>> res = circle_criterion(L, (1.0, 6.0))           # Nyquist enters the disc [-1, -1/6]
    >>> res.stable, round(res.upper_limit, 3)
    (False, 4.828)
    """
    if not isinstance(loop, ct.LTI) or loop.ninputs != 1 or loop.noutputs != 1:
        raise TypeError(f"Parameter loop is {loop!r}; expected a SISO python-control LTI system")
    try:
        k1, k2 = (float(x) for x in bounds)
    except (TypeError, ValueError):
        raise ValueError(f"Parameter bounds is {bounds!r} but should be (k1, k2)") from None
    if not (np.isfinite(k1) and np.isfinite(k2) and k1 <= k2):
        raise ValueError(f"Parameter bounds is {bounds!r} but should be finite with k1 <= k2")
    w = _frequency_grid(loop, int(n_frequencies))
    Lw = _response(loop, w)

    def refine(k1_, j):
        # min Re M on a dense grid between the neighbours of grid point j
        x = np.linspace(w[max(j - 1, 0)], w[min(j + 1, w.size - 1)], 2001)
        lx = _response(loop, x)
        with np.errstate(all="ignore"):
            re = np.real(lx / (1 + k1_ * lx))
        i = int(np.nanargmin(re))
        return float(re[i]), float(x[i])

    def upper(k1_):
        if not _cl_stable(loop, k1_):
            return np.nan, np.nan
        up, j = _upper(Lw, k1_)
        if not np.isfinite(up):
            return np.inf, w[j]
        re, x = refine(k1_, j)
        re = min(re, float(np.real(Lw[j] / (1 + k1_ * Lw[j]))))
        return (k1_ - 1.0 / re if re < 0 else np.inf), x

    def passes(g):
        up, _ = upper(g * k1)
        return bool(np.isfinite(up) and g * k2 < up) or (up == np.inf)

    up, wx = upper(k1)
    stable = bool(not np.isnan(up) and (k2 < up or up == np.inf))
    if np.isnan(up):
        msg = f"the loop with the linear gain k1 = {k1:g} is unstable (1 + k1 L has unstable zeros)"
    elif stable:
        msg = (f"absolutely stable: Re[(1 + k2 L)/(1 + k1 L)] > 0 at every frequency; k2 may grow to "
               f"{up:.6g}")
    else:
        msg = (f"not proven: Re[(1 + k2 L)/(1 + k1 L)] < 0 near {wx / (2 * np.pi):.4g} Hz "
               f"(the Nyquist curve enters the critical disc); k2 must stay below {up:.6g}")
    # gain margin of the sector by continuation from g = 1
    g_max = 1e4
    if stable:
        g_ok, g = 1.0, 1.0
        while g < g_max and passes(g * 1.25):
            g *= 1.25
            g_ok = g
        if g >= g_max:
            gm = np.inf
        else:
            a, b = g_ok, g_ok * 1.25
            for _ in range(45):
                m = np.sqrt(a * b)
                a, b = (m, b) if passes(m) else (a, m)
            gm = a
    else:
        g = 1.0
        while g > 1e-6 and not passes(g):
            g /= 1.25
        if g <= 1e-6:
            gm = 0.0
        else:
            a, b = g, g * 1.25
            for _ in range(45):
                m = np.sqrt(a * b)
                a, b = (m, b) if passes(m) else (a, m)
            gm = a
    return CircleCriterion(stable, (k1, k2), float(up), float(gm), float(wx / (2 * np.pi)), msg)

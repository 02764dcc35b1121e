"""The circle criterion (re-exported by :mod:`hystcomp.analysis`)."""

import numpy as np

import control as ct

from ._validation import as_count

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
    lam, V = np.linalg.eig(A)
    with np.errstate(all="ignore"):
        if np.linalg.cond(V) < 1e8:   # diagonalisable: sum of first-order terms, O(n) per point
            left = (C @ V)[0]
            right = np.linalg.solve(V, B)[:, 0]
            val = (left * right)[None, :] / (flat[:, None] - lam[None, :])
            val = val.sum(axis=1) + D
        else:
            M = flat[:, None, None] * np.eye(n)[None] - A[None]
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
    """Is the loop with the linear gain k (u = -k y) stable?  `sys` may be
    the tuple of :func:`_matrices` (faster in loops)."""
    A, B, C, D, dtime = sys if isinstance(sys, tuple) else _matrices(sys)
    if A.shape[0] == 0:
        return bool(1 + k * D != 0)
    den = 1.0 + k * D
    if den == 0:
        return False
    ev = np.linalg.eigvals(A - k / den * B @ C)
    if dtime:
        return bool(np.all(np.abs(ev) < 1 - 1e-12))
    return bool(np.all(ev.real < -1e-12 * max(1.0, np.max(np.abs(ev)))))


def _matrices(sys):
    s = ct.ss(sys)
    return (np.asarray(s.A, dtype=float), np.asarray(s.B, dtype=float), np.asarray(s.C, dtype=float),
            float(np.asarray(s.D)[0, 0]), bool(sys.isdtime(strict=True)))


def _first_root_above_one(Lw, k1, k2):
    """Per frequency, the smallest g > 1 where q(g) = 1 + g (k1 + k2) Re L + g^2 k1 k2 |L|^2
    (= |1 + g k1 L|^2 Re[(1 + g k2 L)/(1 + g k1 L)]) vanishes; inf where none."""
    b = (k1 + k2) * Lw.real
    c = k1 * k2 * np.abs(Lw) ** 2
    out = np.full(Lw.shape, np.inf)
    with np.errstate(all="ignore"):
        lin = np.abs(c) < 1e-300
        g_lin = np.where(lin & (b < 0), -1.0 / b, np.inf)
        disc = b * b - 4 * c
        sq = np.sqrt(np.where(disc >= 0, disc, np.nan))
        r1 = (-b - sq) / (2 * c)
        r2 = (-b + sq) / (2 * c)
        for r in (r1, r2):
            ok = ~lin & np.isfinite(r) & (r > 1)
            out = np.where(ok, np.minimum(out, r), out)
        out = np.where(lin, np.where(g_lin > 1, g_lin, np.inf), out)
    return out


def _factor_margin(loop, w, Lw, k1, k2):
    """Largest g >= 1 with the criterion holding on all of [1, g] (it holds at 1).

    The frequency condition fails first at the smallest root above 1 of the
    quadratic q(g) (closed form per frequency, refined on a dense grid around
    the worst one); the loop with the gain g k1 can lose stability only
    where the Nyquist curve meets -1/(g k1), found from the crossings of
    the real axis and confirmed by eigenvalues."""
    roots = _first_root_above_one(Lw, k1, k2)
    g_f = np.inf
    j = int(np.argmin(roots))
    if np.isfinite(roots[j]):
        x = np.linspace(w[max(j - 1, 0)], w[min(j + 1, w.size - 1)], 2001)
        g_f = float(min(roots[j], np.min(_first_root_above_one(_response(loop, x), k1, k2))))
    if k1 == 0:
        return g_f
    # candidates where 1 + g k1 L = 0: L real with k1 L < 0
    im = Lw.imag
    idx = np.nonzero((np.sign(im[:-1]) != np.sign(im[1:])) | (im[:-1] == 0))[0]
    cands = []
    for i in idx:
        d = im[i] - im[i + 1]
        s = im[i] / d if d != 0 else 0.0
        re = Lw[i].real + s * (Lw[i + 1].real - Lw[i].real)
        if k1 * re < 0:
            g = -1.0 / (k1 * re)
            if 1 < g < g_f:
                cands.append(g)
    mats = _matrices(loop)
    for g in sorted(cands):
        hi = g * 1.001
        if not _cl_stable(mats, hi * k1):
            lo = max(1.0, g * 0.999) if _cl_stable(mats, g * 0.999 * k1) else 1.0
            while hi / lo > 1 + 1e-12:
                m = np.sqrt(lo * hi)
                lo, hi = (m, hi) if _cl_stable(mats, m * k1) else (lo, m)
            return float(min(lo, g_f))
    return g_f


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
    w = _frequency_grid(loop, as_count(n_frequencies, "n_frequencies", 10))
    Lw = _response(loop, w)

    def refine(k1_, j):
        # min Re M on a dense grid between the neighbours of grid point j
        x = np.linspace(w[max(j - 1, 0)], w[min(j + 1, w.size - 1)], 2001)
        lx = _response(loop, x)
        with np.errstate(all="ignore"):
            re = np.real(lx / (1 + k1_ * lx))
        i = int(np.nanargmin(re))
        return float(re[i]), float(x[i])

    mats = _matrices(loop)

    def upper(k1_):
        if not _cl_stable(mats, k1_):
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
    if stable:
        gm = _factor_margin(loop, w, Lw, k1, k2)
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

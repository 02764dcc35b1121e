"""Mechanisms of the HOLDOUT39 set (``cases_holdout39.py``), each written from its law; the signals are in
:mod:`.signals39`.

Nothing here imports hystcomp (nor another set's mechanisms). Every mechanism takes the (clean) drive's field, or the
core's output, and returns the response; all are causal.

Citations: every source below was written from memory in this session (none was re-read); volumes, pages and years may
be off. The laws do not rest on them: each is checked in tests/test_realistic_holdout39.py against an independent
solution (the critical state written from its definition on a finer grid with brentq for the demagnetising field,
solve_ivp of the same lines, numpy's polynomial roots, a bridge written from its strips, a closed form, a direct
convolution, a cumulative trapezoid).
"""

import math

import numpy as np
from numba import njit


# ---- the rate-independent core: a Bi-2223 rod's critical state (Kim's law) in a solenoid, read by a pickup coil ----
#
# A sintered, textured (Bi,Pb)2Sr2Ca2Cu3O10 (Bi-2223) rod (radius R 15 ... 25 mm, 2.5 ... 4 diameters long, as cut
# for current leads and magnetic shields) sits in a copper solenoid in a bath of liquid nitrogen, cooled in zero field
# (no flux inside: the virgin state); the solenoid is fed by a current amplifier, so its field mu0 H_a is proportional
# to the drive. The flux enters the rod as pinned vortices and the rod carries the critical current density wherever
# flux has moved (Bean's critical state, Rev. Mod. Phys. 36 (1964) 31), here with Kim's field dependence J_c = J_c0 /
# (1 + |B| / B0) (Kim, Hempstead & Strnad, Phys. Rev. 129 (1963) 528), the Kim field B0 2 ... 3.5 times mu0 J_c0 R. In
# a long cylinder in an axial field, |dB/dr| <= mu0 J_c(B) with equality where flux has moved; with u = B + B |B| / (2
# B0) (so du/dB = J_c0 / J_c(B)) this is |du/dr| <= mu0 J_c0: every depth s = R - r follows a play of u at the surface
# with the threshold mu0 J_c0 s (each depth's u changes only once the surface has moved by more than that since the
# last reversal), and B = sign(u) B0 (sqrt(1 + 2 |u| / B0) - 1) there. Lengths in units of R and fields in units of
# mu0 J_c0 R (about 0.25 T for J_c0 1e7 A/m^2 at 77 K and R 20 mm), the rod's mean flux density is B_mean = int 2 r
# B(r) dr (400 rings, the midpoint rule).
#
# The rod's finite length is taken in the ellipsoid approximation: its surface field is the applied field less the
# demagnetising field of its mean magnetisation, H_s = H_a - N (B_mean / mu0 - H_s) (N 0.1 ... 0.2 for a rod 2.5 ... 4
# diameters long: Chen, Brug & Goldfarb, IEEE Trans. Magn. 27 (1991) 3601), solved at every sample for H_s (the left
# side rises monotonically with H_s, the rod's state frozen at its last sample; Newton's method inside a bracket). The
# pickup coil wound on the rod sees its mean flux and the annulus between the rod and the coil (a share g of the rod's
# area at mu0 H_a); the electronic fluxmeter's reading, times a drawn gain, is the output. Rate independent, with
# return-point memory (every ring's u a play of the surface's), but not a Prandtl-Ishlinskii model: the rings' B is a
# nonlinear function of their plays (Kim's law), so the branches change their shape along the stroke; without the
# demagnetising field it would be a Preisach model (each ring's B(u) a sum of relays along its play) whose density is
# not a function of the loop's width alone, and the demagnetising feedback couples the rings further (two minor loops
# between the same drives after different histories then differ by about 0.1 % of their rise).

@njit(cache=True)
def _b_of_u(u, b0):
    a = abs(u)
    b = 2.0 * a / (1.0 + math.sqrt(1.0 + 2.0 * a / b0))          # B0 (sqrt(1 + 2 |u| / B0) - 1), rationalised
    return b if u >= 0.0 else -b


@njit(cache=True)
def _u_of_b(b, b0):
    return b + b * abs(b) / (2.0 * b0)


def kim_u(b, b0):
    """u = B + B |B| / (2 B0) (du/dB = J_c0 / J_c(B) for Kim's law)."""
    b = np.asarray(b, float)
    return b + b * np.abs(b) / (2.0 * b0)


def kim_b(u, b0):
    """B of u: the inverse of :func:`kim_u`."""
    u = np.asarray(u, float)
    return 2.0 * u / (1.0 + np.sqrt(1.0 + 2.0 * np.abs(u) / b0))


def rings(n=400):
    """The rod's rings: radii r (midpoints), depths s = 1 - r (the plays' thresholds) and area weights 2 r / n."""
    r = (np.arange(n) + 0.5) / n
    return r, 1.0 - r, 2.0 * r / n


@njit(cache=True)
def _mean_b(xs, z, s, w, b0):
    """The mean flux density with the surface at u = xs (every ring's play moved from z) and its slope d/d(xs)."""
    m = 0.0
    dm = 0.0
    for j in range(s.shape[0]):
        zz = min(max(z[j], xs - s[j]), xs + s[j])
        m += w[j] * _b_of_u(zz, b0)
        if zz != z[j]:
            dm += w[j] / math.sqrt(1.0 + 2.0 * abs(zz) / b0)
    return m, dm


@njit(cache=True)
def _surface_field(ha, z, s, w, b0, nd, guess):
    """The surface field h_s solving (1 - N) h_s + N B_mean(h_s) = h_a (increasing in h_s), by Newton's method kept
    inside a bracket (bisection when a step leaves it)."""
    if nd == 0.0:
        return ha
    lo, hi = -1e300, 1e300
    hs = guess
    for it in range(200):
        xs = _u_of_b(hs, b0)
        m, dm = _mean_b(xs, z, s, w, b0)
        G = (1.0 - nd) * hs + nd * m - ha
        if G == 0.0:
            return hs
        if G > 0.0:
            hi = min(hi, hs)
        else:
            lo = max(lo, hs)
        dG = (1.0 - nd) + nd * dm * (1.0 + abs(hs) / b0)
        new = hs - G / dG
        if not (lo < new < hi):
            if lo > -1e300 and hi < 1e300:
                new = 0.5 * (lo + hi)
            elif lo > -1e300:
                new = lo + 2.0 * abs(G) / (1.0 - nd) + 1e-12
            else:
                new = hi - 2.0 * abs(G) / (1.0 - nd) - 1e-12
        if abs(new - hs) <= 1e-15 * (1.0 + abs(hs)):
            return new
        hs = new
    return hs


@njit(cache=True)
def _core_run(ha, z0, s, w, b0, nd):
    n = ha.shape[0]
    z = z0.copy()
    out = np.empty(n)
    hso = np.empty(n)
    hs = ha[0] if n > 0 else 0.0
    for k in range(n):
        hs = _surface_field(ha[k], z, s, w, b0, nd, hs)
        xs = _u_of_b(hs, b0)
        m = 0.0
        for j in range(s.shape[0]):
            z[j] = min(max(z[j], xs - s[j]), xs + s[j])
            m += w[j] * _b_of_u(z[j], b0)
        out[k] = m
        hso[k] = hs
    return out, hso, z


def critical_state(core, ha, z0=None, return_all=False):
    """The rod's mean flux density along the applied fields ha (the rings' u from z0; default the virgin rod, cooled in
    zero field: u = 0 everywhere); with return_all also the surface fields and the rings' u at the end."""
    r, s, w = rings(core.get("rings", 400))
    z0 = np.zeros(len(r)) if z0 is None else np.asarray(z0, float)
    m, hs, z = _core_run(np.asarray(ha, float), z0, s, w, float(core["b0"]), float(core["nd"]))
    return (m, hs, z) if return_all else m


def pickup(core, ha, b_mean):
    """The fluxmeter's reading (before the offset): gain (B_mean + g h_a)."""
    return core["gain"] * (np.asarray(b_mean, float) + core["g"] * np.asarray(ha, float))


def field_cooled(core, h_fc, n_steps=60):
    """The rings' u after the rod was cooled through T_c in the applied field h_fc (the flux inside uniform: u =
    u(h_fc) everywhere, no magnetisation) and the field then ramped to 0 in n_steps steps."""
    r, s, w = rings(core.get("rings", 400))
    z0 = np.full(len(r), float(kim_u(h_fc, core["b0"])))
    ramp = np.linspace(h_fc, 0.0, n_steps + 1)
    return critical_state(core, ramp, z0=z0, return_all=True)[2]


# ---- creep and rate dependence: the rod's E-J law (flux creep and flux flow) ----
#
# The critical state is the limit of a steep E-J curve. Thermally activated flux creep gives the power law E = E_c
# (J / J_c(B))^n (E_c 1 uV/cm, J_c the current density there; Anderson & Kim, Rev. Mod. Phys. 36 (1964) 39; Rhyner,
# Physica C 212 (1993) 292; the magnetisation relaxes by about 1 / n per e-fold of the time; n 8 ... 16 for Bi-2223 at
# 77 K, where its creep is strong), e_c = E_c / (mu0 J_c0 R^2) 0.015 ... 0.03 in the units below; flux flow gives E =
# rho_ff (J - J_d) beyond the depinning current J_d (Bardeen & Stephen, Phys. Rev. 140 (1965) A1197, rho_ff = rho_n B
# / B_c2; here rho_ff = rho_0 (1 + |B| / B0), rising with the field and floored at low fields, so that rho_ff J_c(B)
# is constant: a time constant tau = mu0 R^2 / rho_0 of 10 ... 25 ms), J_d = kappa J_c (kappa 1 without creep, 1.2 ...
# 1.4 where the creep's J_c lies below the depinning current). In units of R, mu0 J_c0 R and seconds, with w = J /
# J_c(B) = -du/dr, Faraday's law in the rod reads dB/dt = (1 / r) d/dr (r E(du/dr)), E(g) = e_c |g|^n sign(g) + (|g|
# - kappa)_+ sign(g) / tau. Each step of backward Euler is the minimiser of a convex sum: over the cells r dr (beta(u) -
# B_old u) (beta' = B(u), increasing), over the faces the step times r_face dr_face Psi(du/dr) (Psi' = E), and for the
# surface's u (the demagnetising balance (1 - N) B(u_s) + N B_mean = h_a, B_mean = B_mean,old + 2 h E_s by the flux
# through the surface) (beta(u_s) (1 - N) - (h_a - N B_mean,old) u_s) / (2 N): a finite-volume method of 64 cells (the
# surface face half a cell), each step solved by Newton's method with a backtracking line search on that sum
# (tridiagonal Hessians), from the last step's change repeated. Several steps a sample, the applied field linear
# between the samples.

@njit(cache=True)
def _beta(u, b0):
    a = abs(u)
    return b0 * (b0 / 3.0 * ((1.0 + 2.0 * a / b0) ** 1.5 - 1.0) - a)


@njit(cache=True)
def _psi(g, ec, n, itau, kap):
    a = abs(g)
    v = 0.0
    if ec > 0.0:
        v += ec * a ** (n + 1.0) / (n + 1.0)
    if itau > 0.0 and a > kap:
        v += 0.5 * itau * (a - kap) ** 2
    return v


@njit(cache=True)
def _e_of(g, ec, n, itau, kap):
    a = abs(g)
    v = 0.0
    if ec > 0.0:
        v += ec * a ** n
    if itau > 0.0 and a > kap:
        v += itau * (a - kap)
    return v if g >= 0.0 else -v


@njit(cache=True)
def _de_of(g, ec, n, itau, kap):
    a = abs(g)
    v = 0.0
    if ec > 0.0 and a > 0.0:
        v += ec * n * a ** (n - 1.0)
    if itau > 0.0 and a > kap:
        v += itau
    return v


@njit(cache=True)
def _energy(u, bold, V, A, D, h, b0, ec, n, itau, kap, cs, rhs_s):
    """The step's convex sum; u[N] the surface's u, with the weight cs = 1 / (2 N) of its demagnetising balance (0: the
    surface held)."""
    N = u.shape[0] - 1
    s = 0.0
    for j in range(N):
        s += V[j] * (_beta(u[j], b0) - bold[j] * u[j])
    for f in range(N):
        s += h * A[f] * D[f] * _psi((u[f + 1] - u[f]) / D[f], ec, n, itau, kap)
    if cs > 0.0:
        s += cs * (_beta(u[N], b0) - rhs_s * u[N])
    return s


@njit(cache=True)
def _assemble(u, bold, V, A, D, h, b0, ec, n, itau, kap, cs, rhs_s, G, Hd, Ho):
    N = u.shape[0] - 1
    for j in range(N):
        G[j] = V[j] * (_b_of_u(u[j], b0) - bold[j])
        Hd[j] = V[j] / math.sqrt(1.0 + 2.0 * abs(u[j]) / b0)
        Ho[j] = 0.0
    if cs > 0.0:
        G[N] = cs * (_b_of_u(u[N], b0) - rhs_s)
        Hd[N] = cs / math.sqrt(1.0 + 2.0 * abs(u[N]) / b0)
    else:
        G[N] = 0.0
        Hd[N] = 1.0
    Ho[N] = 0.0
    for f in range(N):
        g = (u[f + 1] - u[f]) / D[f]
        e = h * A[f] * _e_of(g, ec, n, itau, kap)
        k = h * A[f] * _de_of(g, ec, n, itau, kap) / D[f]
        G[f] -= e
        Hd[f] += k
        if f < N - 1 or cs > 0.0:
            G[f + 1] += e
            Hd[f + 1] += k
            Ho[f] = -k


@njit(cache=True)
def _thomas(Hd, Ho, rhs, x, cp, dp):
    N = Hd.shape[0]
    for j in range(N):
        m = Hd[j] - (Ho[j - 1] * cp[j - 1] if j > 0 else 0.0)
        cp[j] = Ho[j] / m
        dp[j] = (rhs[j] - (Ho[j - 1] * dp[j - 1] if j > 0 else 0.0)) / m
    for j in range(N - 1, -1, -1):
        x[j] = dp[j] - (cp[j] * x[j + 1] if j < N - 1 else 0.0)


@njit(cache=True)
def _step(u, bold, V, A, D, h, b0, ec, n, itau, kap, cs, rhs_s, G, Hd, Ho, du, ut, cp, dp, rhs):
    """One backward-Euler step: u (updated in place; u[N] the surface, held when cs = 0) minimises the step's convex
    sum, by Newton's method with a backtracking line search; returns the iterations taken."""
    M = u.shape[0]
    it = 0
    f0 = _energy(u, bold, V, A, D, h, b0, ec, n, itau, kap, cs, rhs_s)
    for it in range(200):
        _assemble(u, bold, V, A, D, h, b0, ec, n, itau, kap, cs, rhs_s, G, Hd, Ho)
        for j in range(M):
            rhs[j] = -G[j]
        _thomas(Hd, Ho, rhs, du, cp, dp)
        slope = 0.0
        big = 0.0
        for j in range(M):
            slope += G[j] * du[j]
            big = max(big, abs(du[j]))
        if big < 1e-12:
            break
        st = 1.0
        while True:
            for j in range(M):
                ut[j] = u[j] + st * du[j]
            f1 = _energy(ut, bold, V, A, D, h, b0, ec, n, itau, kap, cs, rhs_s)
            if f1 <= f0 + 1e-4 * st * slope or st < 1e-9:
                break
            st *= 0.5
        for j in range(M):
            u[j] = ut[j]
        f0 = f1
        if big * st < 1e-12:
            break
    return it


@njit(cache=True)
def _ej_run(ha, u0, dt, sub, b0, nd, ec, n, itau, kap, ncell):
    N = ncell
    dr = 1.0 / N
    V = np.empty(N)
    A = np.empty(N)
    D = np.empty(N)
    W = np.empty(N)
    for j in range(N):
        r = (j + 0.5) * dr
        V[j] = r * dr
        W[j] = 2.0 * r * dr
        A[j] = (j + 1.0) * dr
        D[j] = dr
    D[N - 1] = 0.5 * dr
    cs = 1.0 / (2.0 * nd) if nd > 0.0 else 0.0
    u = np.empty(N + 1)
    for j in range(N):
        u[j] = u0[j]
    bold = np.empty(N)
    G = np.empty(N + 1)
    Hd = np.empty(N + 1)
    Ho = np.empty(N + 1)
    du = np.empty(N + 1)
    ut = np.empty(N + 1)
    cp = np.empty(N + 1)
    dp = np.empty(N + 1)
    rhs = np.empty(N + 1)
    ulast = np.empty(N + 1)
    out = np.empty(ha.shape[0])
    uso = np.empty(ha.shape[0])
    m = 0.0
    for j in range(N):
        m += W[j] * _b_of_u(u[j], b0)
    # the surface at the start: in equilibrium with the first field (the rod's state as given)
    u[N] = _u_of_b((ha[0] - nd * m) / (1.0 - nd), b0)
    out[0] = m
    uso[0] = u[N]
    h = dt / sub
    its = 0
    for k in range(1, ha.shape[0]):
        for q in range(sub):
            target = ha[k - 1] + (ha[k] - ha[k - 1]) * (q + 1.0) / sub
            for j in range(N):
                bold[j] = _b_of_u(u[j], b0)
            # a predictor: the last step's change again (Newton then starts close to the new state)
            for j in range(N + 1):
                tmp = u[j]
                if k > 1 or q > 0:
                    u[j] += u[j] - ulast[j]
                ulast[j] = tmp
            if cs > 0.0:
                rhs_s = (target - nd * m) / (1.0 - nd)     # (1 - N) B(u_s) + N (B_mean_old + 2 h E_s) = h_a
            else:
                rhs_s = 0.0
                u[N] = _u_of_b(target, b0)
            its += _step(u, bold, V, A, D, h, b0, ec, n, itau, kap, cs * (1.0 - nd), rhs_s, G, Hd, Ho, du, ut, cp,
                         dp, rhs) + 1
            m = 0.0
            for j in range(N):
                m += W[j] * _b_of_u(u[j], b0)
        out[k] = m
        uso[k] = u[N]
    return out, uso, u[:N].copy(), its


def ej_rod(core, ha, dt, ec=0.0, n=1.0, tau=0.0, kappa=1.0, sub=4, cells=64, u0=None, return_all=False):
    """The rod with the E-J law E = e_c |J / J_c|^n + (|J / J_c| - kappa)_+ / tau (in the units above; e_c 0 or tau 0
    leaves that part out) along the applied fields ha sampled every dt (linear between the samples, sub steps a sample),
    from the cells' u0 (default the virgin rod); the mean flux density (and with return_all the surface's u and the
    cells' u at the end)."""
    u0 = np.zeros(cells) if u0 is None else np.asarray(u0, float)
    itau = 1.0 / tau if tau > 0 else 0.0
    m, us, u, its = _ej_run(np.asarray(ha, float), u0, float(dt), int(sub), float(core["b0"]), float(core["nd"]),
                            float(ec), float(n), float(itau), float(kappa), int(cells))
    ej_rod.iterations = its
    return (m, us, u) if return_all else m


# ---- drift: the fluxmeter's integrator warming after its zero ----
#
# An electronic fluxmeter integrates the pickup's voltage on a capacitor (Phi = (1 / N) int V dt); any offset voltage
# at its input integrates into a drift. The operator zeroes it just before the record (the drift-trim nulls the input
# offset and bias current then), but the input stage keeps warming after the range switch (its offset voltage
# following the chip's temperature, a first-order warm-up of tau 0.15 ... 0.5 of the record): the offset V (1 -
# exp(-t / tau)) integrates into V (t - tau (1 - exp(-t / tau))), quadratic at first and then a straight ramp
# (the drift of integrating fluxmeters: e.g. Lake Shore's and Metrolab's fluxmeter manuals, from memory).

def integrator_drift(t, tau):
    """The shape t - tau (1 - exp(-t / tau)) of the integrated warming offset (0 with zero slope at t = 0)."""
    t = np.asarray(t, float)
    return t - tau * (1.0 - np.exp(-t / tau))


# ---- asymmetry: an analogue optocoupler's LED in its efficiency droop ----
#
# The fluxmeter's output reaches the logger through an analogue optocoupler (galvanic isolation against the magnet's
# ground loops) without a servo photodiode: a transconductance stage drives the LED at i_b (1 + m s) (s the reading
# over its stroke), the photodiode's current is proportional to the LED's light. By the ABC model of an LED's carrier
# recombination (Shockley-Read-Hall A n, radiative B n^2, Auger C n^3; e.g. Piprek, phys. stat. sol. (a) 207 (2010)
# 2217) the current is q V (A n + B n^2 + C n^3) and the light B n^2: in units n / (A / B), i = n + n^2 + c n^3 and P =
# n^2, c = C A / B^2 0.005 ... 0.02. Biased deep in the droop (n 6 ... 10 times sqrt(1 / c), past the efficiency peak),
# the light rises ever more slowly with the current: a concave reading, read on its slope at the bias.

def led_density(i, c):
    """The carrier density n of the current i: the real root of c n^3 + n^2 + n - i = 0 (Newton from an upper bound)."""
    i = np.asarray(i, float)
    n = np.maximum(np.cbrt(i / c), 0.0)
    n = np.minimum(n, np.sqrt(np.maximum(i, 0.0)))
    for _ in range(100):
        f = c * n ** 3 + n * n + n - i
        df = 3 * c * n * n + 2 * n + 1
        step = f / df
        n = n - step
        if np.all(np.abs(step) <= 1e-15 * (1 + np.abs(n))):
            break
    return n


def led_reading(s, n_b, m, c):
    """The optocoupler's reading over its slope at the bias (slope 1 at s = 0): the LED at the current i_b (1 + m s),
    i_b the current of the density n_b, its light n^2."""
    s = np.asarray(s, float)
    ib = c * n_b ** 3 + n_b ** 2 + n_b
    n = led_density(ib * (1.0 + m * s), c)
    slope = 2 * n_b / (3 * c * n_b ** 2 + 2 * n_b + 1) * ib * m
    return (n * n - n_b * n_b) / slope


# ---- saturation: an AMR current sensor with barber poles ----
#
# The fluxmeter's output current runs through the primary strip of an isolated anisotropic-magnetoresistive current
# sensor: a Wheatstone bridge of four permalloy strips with barber-pole electrodes (their current at +-45 deg to the
# easy axis). The primary's field H across each strip turns its magnetisation from the easy axis by theta, sin(theta)
# = H / H_k below the anisotropy field (a single-domain strip, the Stoner-Wohlfarth hard-axis law), and each strip's
# resistance is R0 + dR cos^2(theta -+ 45 deg) (Thomson's anisotropic magnetoresistance): the bridge's output is
# proportional to sin(2 theta) / 2 = h sqrt(1 - h^2), h = H / H_k (Dibbern, Sensors and Actuators 10 (1986) 127;
# Kwiatkowski & Tumanski, J. Phys. E 19 (1986) 502): odd, flattening toward h = 1 / sqrt(2).

def amr_reading(s, eta):
    """The bridge's output over its slope at 0 (slope 1 at s = 0), the field at s times eta H_k: s sqrt(1 - (eta
    s)^2)."""
    s = np.asarray(s, float)
    return s * np.sqrt(1.0 - (eta * s) ** 2)


# ---- delay: a delta-sigma fluxmeter's linear-phase decimation filter ----
#
# A digital integrating fluxmeter samples the pickup's voltage with a delta-sigma converter and integrates the samples;
# its decimator's last stage is a linear-phase FIR low-pass (a Kaiser-windowed sinc, Kaiser 1974; its cut-off at 0.4 of
# the output rate) of 2M + 1 taps at R = 8 times the output rate, so that the reading is the flux delayed by M / R
# output samples (a pure delay in the signal's band, the FIR's ripple far below the noise) and the logger takes the
# newest output at each of its samples.

def kaiser_sinc(M, R, beta, cut=0.4):
    """The 2M + 1 taps (at R times the output rate) of the Kaiser-windowed sinc with its cut-off at ``cut`` of the
    output rate, normalised to a unit DC gain."""
    k = np.arange(-M, M + 1)
    fc = cut / R                                              # the cut-off in cycles a fine sample
    h = 2 * fc * np.sinc(2 * fc * k) * np.i0(beta * np.sqrt(1 - (k / M) ** 2)) / np.i0(beta)
    return h / h.sum()


def fir_decimate(y_fine, taps, R, n_out):
    """The FIR's outputs at every R-th fine sample, y_fine starting 2M fine samples before the first output (output j
    is sum_i taps[i] y_fine[2M + R j - i])."""
    L = len(taps)
    full = np.convolve(y_fine, taps, mode="full")
    idx = (L - 1) + R * np.arange(n_out)
    return full[idx]


# ---- out of vocabulary: the mains' hum from a ground loop ----
#
# The fluxmeter and the logger are earthed at different points; the loop between their grounds links the stray field
# of the rotary pump's motor and carries part of its return current, so the reading carries the mains' hum (50 Hz and
# its odd harmonics, the motor's and the transformers' magnetising currents: 3rd 0.2 ... 0.4, 5th 0.05 ... 0.15 of the
# fundamental) whose level follows the pump's motor as its vacuum switch turns it on and off (a residual 0.25 ... 0.45
# of it while it is off). Its amplitude at full: 3.5 ... 6 % of the reading's span. An additive signal that no part of
# the rod or the drive makes.

def mains_hum(t, f_mains, harmonics, phases, level):
    """The hum on times t: level(t) times sum_k a_k sin(2 pi k f t + phi_k) (harmonics: (k, a_k) pairs)."""
    t = np.asarray(t, float)
    s = np.zeros(len(t))
    for (k, a), ph in zip(harmonics, phases):
        s += a * np.sin(2 * math.pi * k * f_mains * t + ph)
    return np.asarray(level, float) * s

"""Mechanisms of the HOLDOUT21 set (``cases_holdout21.py``), each written from its law; the signals are in
:mod:`.signals21`.

Nothing here imports hystcomp. Every mechanism takes the (clean) drive, or the core's output, and returns the response;
all are causal. The play, its threshold grid, a path's turning points, the raised cosine and the Prony (Kelvin-chain)
creep are the earlier sets' (imported, the same laws).

Citations: every source below was written from memory in this session (none was re-read); volumes, pages and years may
be off. The laws do not rest on them: each is checked in tests/test_realistic_holdout21.py against an independent
solution (a closed form, quadrature, brentq, solve_ivp or a finer simulation).
"""

import math

import numpy as np
from scipy.special import gammainc

from .mechanisms13 import turning_points  # noqa: F401
from .mechanisms17 import prony_creep
from .mechanisms18 import exp_plays, grid, plays  # noqa: F401
from .mechanisms19 import raised_cosine  # noqa: F401


# ---- the rate-independent core ----

def loglogistic_plays(n, r_max, scale, shape, w0):
    """Thresholds on :func:`grid` weighted by the log-logistic (Fisk) density (b / a) (r / a)^(b - 1) / (1 + (r /
    a)^b)^2 (Fisk, Economica 28 (1961) 171; the law of a ratio of two gamma-like pinning strengths), a hump with an
    algebraic tail of wide plays; summing to 1 - w0."""
    r = grid(n, r_max)
    x = r / scale
    dens = (shape / scale) * x ** (shape - 1) / (1 + x ** shape) ** 2
    return r, (1 - w0) * dens / dens.sum()


# ---- creep: Becquerel's law (a gamma distribution of relaxation rates) ----

def becquerel_compliance_closed(t, tau, k):
    """The step response 1 - (1 + t / (k tau))^-k: the Laplace transform of a gamma distribution of relaxation rates
    of shape k and mean 1 / tau (Becquerel's 'compressed hyperbola' of phosphorescence decay, E. Becquerel, *La
    lumiere*, 1867; Berberan-Santos, Bodunov & Valeur, Chem. Phys. 317 (2005) 57)."""
    t = np.clip(np.asarray(t, float), 0, None)
    return -np.expm1(-k * np.log1p(t / (k * tau)))


def becquerel_prony(tau, k, lam_lo=1e-4, lam_hi=1e3, du=0.05):
    """The rates' gamma distribution in cells of about du in ln(rate) between lam_lo and lam_hi /s, each cell's mass
    (regularised incomplete gamma differences) at its geometric midpoint: retardation times and weights (summing to
    the mass between the cut-offs; slower rates are frozen, faster ones elastic, in the core's gain)."""
    lo, hi = math.log(lam_lo), math.log(lam_hi)
    edges = np.linspace(lo, hi, int(math.ceil((hi - lo) / du)) + 1)
    mass = np.diff(gammainc(k, np.exp(edges) * k * tau))
    lam = np.exp((edges[:-1] + edges[1:]) / 2)
    return 1 / lam, mass


def becquerel_compliance(t, tau, k):
    """The Prony series of :func:`becquerel_prony` at the times t."""
    taus, wts = becquerel_prony(tau, k)
    t = np.clip(np.asarray(t, float), 0, None)
    return -np.expm1(-t[..., None] / taus) @ wts


def becquerel_creep(h, dt, c, tau, k):
    """c x the Boltzmann superposition of the Becquerel compliance over the load h (the core's output), exact for h
    linear between samples, settled at h[0] at first."""
    taus, wts = becquerel_prony(tau, k)
    return prony_creep(np.asarray(h, float), dt, c, taus, wts)


# ---- rate dependence: a pneumatic bellows fed through a restrictor (ISO 6358) ----

def iso6358_phi(r, b):
    """The flow function of ISO 6358 (1989; Beater, *Pneumatic Drives*, 2007, ch. 3): 1 while the restrictor is
    choked (downstream over upstream pressure r <= b, the critical ratio), sqrt(1 - ((r - b) / (1 - b))^2) above
    it (an elliptic fall to 0 at r = 1)."""
    r = np.asarray(r, float)
    z = np.clip((r - b) / (1 - b), 0.0, 1.0)
    return np.sqrt(1 - z * z)


def bellows_rate(p, pc, b, tau_c):
    """dp/dt of a chamber at the absolute pressure p fed from a valve holding pc through a restrictor of sonic
    conductance C (isothermal: dp/dt = R T q / V, q = C rho0 p_up phi(p_down / p_up)): sign(pc - p) p_up phi / tau_c,
    tau_c = V / (C rho0 R T)."""
    up = np.maximum(p, pc)
    dn = np.minimum(p, pc)
    return np.sign(pc - p) * up * iso6358_phi(dn / up, b) / tau_c


def bellows_stage(h, dt, p_a, kappa, b, tau_c, sub=4):
    """The stage of a bellows whose extension is proportional to its gauge pressure p - p_a, fed through the
    restrictor from a proportional valve that sets pc = p_a + kappa h (h the core's output, linear between samples;
    bar per output unit): classical Runge-Kutta, `sub` steps a sample, from equilibrium at h[0]. Returns (p - p_a) /
    kappa, in the core's units."""
    h = np.asarray(h, float).tolist()
    hs = dt / sub
    ib = 1.0 / (1 - b)

    def rate(p, pc):
        if pc >= p:
            up, dn, sg = pc, p, 1.0
        else:
            up, dn, sg = p, pc, -1.0
        z = min(max((dn / up - b) * ib, 0.0), 1.0)
        return sg * up * math.sqrt(1 - z * z) / tau_c
    p = p_a + kappa * h[0]
    out = [h[0]]
    for k in range(1, len(h)):
        c0, dc = p_a + kappa * h[k - 1], kappa * (h[k] - h[k - 1]) / sub
        for j in range(sub):
            ca, cm, cb = c0 + j * dc, c0 + (j + 0.5) * dc, c0 + (j + 1) * dc
            k1 = rate(p, ca)
            k2 = rate(p + 0.5 * hs * k1, cm)
            k3 = rate(p + 0.5 * hs * k2, cm)
            k4 = rate(p + hs * k3, cb)
            p += hs * (k1 + 2 * k2 + 2 * k3 + k4) / 6
        out.append((p - p_a) / kappa)
    return np.array(out)


# ---- offset drift: a passing vehicle's magnetic dipole at a magnetic position sensor ----

def dipole_bx(X, d):
    """The field along the path (per unit mu0 m / 4 pi) of a dipole moving along a line at the closest distance d
    from the sensor, its moment along the path, X its position along it: (2 X^2 - d^2) / (X^2 + d^2)^(5/2) (the
    dipole's field (3 (m.r) r - m r^2) / r^5; e.g. Jackson, *Classical Electrodynamics*, 1999, sec. 5.6; vehicles
    as magnetic dipoles: Lenz, Proc. IEEE 78 (1990) 973)."""
    X = np.asarray(X, float)
    return (2 * X * X - d * d) / (X * X + d * d) ** 2.5


def vehicle_passes(t, passes):
    """The vehicle's position along its path: passes (t0, T, X0, X1), each a raised-cosine move from X0 to X1 over T
    s (starting and stopping at rest); far away (|X| large) between them. Returns X and each pass's moment sign (+1
    driving toward +X, -1 back: the vehicle turned round)."""
    t = np.asarray(t, float)
    X = np.full_like(t, 1e6)
    for t0, T, X0, X1 in passes:
        on = (t >= t0) & (t <= t0 + T)
        X[on] = X0 + (X1 - X0) * raised_cosine((t[on] - t0) / T)
    return X


def vehicle_offset(t, passes, d, amp):
    """The sensor's offset: amp x the dipole's field along the path normalised by its peak |-1 / d^3| (at the closest
    approach), the moment turned round with the vehicle on a pass toward -X."""
    t = np.asarray(t, float)
    out = np.zeros_like(t)
    for t0, T, X0, X1 in passes:
        on = (t >= t0) & (t <= t0 + T)
        X = X0 + (X1 - X0) * raised_cosine((t[on] - t0) / T)
        out[on] = math.copysign(1.0, X1 - X0) * dipole_bx(X, d) * d ** 3
    return amp * out


# ---- asymmetry: a Mooney-Rivlin rubber pad read by a load cell ----

def mooney_rivlin_stress(lam, c1, c2):
    """The nominal stress of an incompressible Mooney-Rivlin solid in uniaxial tension or compression, 2 (c1 + c2 /
    lam) (lam - lam^-2) (Mooney, J. Appl. Phys. 11 (1940) 582; Rivlin, Phil. Trans. R. Soc. A 241 (1948) 379;
    Treloar, *The Physics of Rubber Elasticity*, 1975): stiffer in compression than in tension."""
    lam = np.asarray(lam, float)
    return 2 * (c1 + c2 / lam) * (lam - lam ** -2)


def mooney_rivlin_energy(lam, c1, c2):
    """The strain energy c1 (I1 - 3) + c2 (I2 - 3), I1 = lam^2 + 2 / lam, I2 = 2 lam + lam^-2, of that stretch."""
    lam = np.asarray(lam, float)
    return c1 * (lam * lam + 2 / lam - 3) + c2 * (2 * lam + lam ** -2 - 3)


def pad_reading(x, strain_per_unit, c1, c2):
    """The load cell's force (scaled to slope 1 at rest) of a pad strained by strain_per_unit x (x the stage's
    travel, either sign): mooney_rivlin_stress(1 + e x) / (6 (c1 + c2) e)."""
    e = strain_per_unit
    return mooney_rivlin_stress(1 + e * np.asarray(x, float), c1, c2) / (6 * (c1 + c2) * e)


# ---- saturation: a ferrite's mean-field (Weiss) magnetisation above its Curie point ----

def weiss_field(m, rho):
    """The applied field (over k T / mu) at which the mean-field magnetisation is m: atanh(m) - rho m, from m =
    tanh(h + rho m) (Weiss, J. Phys. Theor. Appl. 6 (1907) 661), rho = T_c / T < 1 above the Curie point."""
    m = np.asarray(m, float)
    return np.arctanh(m) - rho * m


def weiss_m(h, rho, iters=64):
    """The magnetisation m solving m = tanh(h + rho m) (odd, increasing for rho < 1): bisection on the monotone
    weiss_field over 0 ... 1 (64 halvings: below 1e-19)."""
    h = np.asarray(h, float)
    a = np.abs(h)
    lo, hi = np.zeros_like(a), np.full_like(a, np.nextafter(1.0, 0.0))
    for _ in range(iters):
        mid = 0.5 * (lo + hi)
        big = weiss_field(mid, rho) > a
        hi = np.where(big, mid, hi)
        lo = np.where(big, lo, mid)
    return np.sign(h) * 0.5 * (lo + hi)


def weiss_reading(h, centre, F, rho):
    """A sensor reading the stage through the ferrite: centre + F (1 - rho) m((h - centre) / F), slope 1 at the
    centre."""
    return centre + F * (1 - rho) * weiss_m((np.asarray(h, float) - centre) / F, rho)


# ---- delay: a CAN bus position sensor whose frames wait for arbitration ----

def can_frames(n, dt, phase, d0, waits):
    """The sensor samples on its own clock at s_j = t_j - phase, converts and packs each sample in d0 s, and its
    frames queue waits[j] s behind higher-priority frames and go out in order (a node's transmit queue: no
    overtaking; response-time analysis of Tindell & Burns, 1994), arriving at a_j = max(a_{j-1}, s_j + d0 +
    waits[j]); the logger at t_k holds the newest frame arrived. Returns each record sample's frame index (-1: none
    yet), the sampling instants and the arrivals."""
    t = np.arange(n) * dt
    s = t - phase
    arr = np.maximum.accumulate(s + d0 + np.asarray(waits, float))
    idx = np.searchsorted(arr, t + 1e-9 * dt, side="right") - 1
    return idx, s, arr


def can_reading(core_at, n, dt, phase, d0, waits):
    """The logger's record: core_at(times) is the stage's position at those times; each sample the newest arrived
    frame's position (the first frame's before any arrived). Returns it and each sample's delay in samples."""
    idx, s, _ = can_frames(n, dt, phase, d0, waits)
    sj = s[np.maximum(idx, 0)]
    return core_at(sj), (np.arange(n) * dt - sj) / dt


# ---- two effects: creep with the Rouse spectrum and the tension of a sagging cable ----

def rouse_prony(tau1, n_modes):
    """Retardation times tau1 / p^2 with strengths proportional to 1 / p^2 (p = 1 ... n_modes), normalised to sum to
    1: the Rouse chain's spectrum (Rouse, J. Chem. Phys. 21 (1953) 1272; Ferry, *Viscoelastic Properties of
    Polymers*, 1980, ch. 10), here the strands of a lightly cross-linked elastomer (no flow): J(t) grows as
    sqrt(t) at first."""
    p = np.arange(1, n_modes + 1)
    w = 1.0 / p ** 2
    return tau1 / p ** 2, w / w.sum()


def rouse_creep(h, dt, c, tau1, n_modes):
    taus, wts = rouse_prony(tau1, n_modes)
    return prony_creep(np.asarray(h, float), dt, c, taus, wts)


def cable_tension(x, q):
    """The horizontal tension H (over EA) of a shallow elastic cable whose unstretched length equals the span l = 1,
    its end pulled out by x (over l): its length l + x + w^2 (l + x)^3 / (24 H^2) (the parabola's arc) equals its
    stretched length 1 + H, with q^3 = w^2 / 24 (w its weight over EA): H - x - q^3 (1 + x)^3 / H^2 = 0 (Irvine,
    *Cable Structures*, 1981, ch. 2; Ernst's equivalent modulus). Soft while it sags, elastic when taut. As the cubic
    H^3 - x H^2 - q^3 (1 + x)^3 = 0, whose one positive root lies in (0, max(x, 0) + q (1 + x)): bisection, then
    Newton."""
    x = np.asarray(x, float)
    a = q ** 3 * (1 + x) ** 3
    lo, hi = np.zeros_like(x), np.maximum(x, 0.0) + np.cbrt(a)
    for _ in range(80):
        mid = 0.5 * (lo + hi)
        pos = mid ** 3 - x * mid * mid - a > 0
        hi = np.where(pos, mid, hi)
        lo = np.where(pos, lo, mid)
    H = 0.5 * (lo + hi)
    for _ in range(3):
        H = H - (H ** 3 - x * H * H - a) / (3 * H * H - 2 * x * H)
    return H


# ---- out of vocabulary: thermally activated Barkhausen jumps ----

def depinning_rate(h, H_p, delta0, f0):
    """The rate at which a pinned wall segment escapes under the drive h below its depinning field H_p: f0 exp(-delta0
    (1 - h / H_p)^(3/2)) (the barrier of a cubic potential near its saddle-node vanishing with the 3/2 power;
    Victora, Phys. Rev. Lett. 63 (1989) 457; Neel-Arrhenius activation, Neel, Ann. Geophys. 5 (1949) 99); at and
    beyond H_p at once (inf)."""
    h = np.asarray(h, float)
    x = np.clip(1 - h / H_p, 0.0, None)
    return np.where(h >= H_p, np.inf, f0 * np.exp(-delta0 * x ** 1.5))


def barkhausen_states(h, dt, H_p, H_r, delta0, f0, uniforms):
    """The states (0 pinned, 1 jumped) of segments under the core's output h: a pinned segment jumps in a sample
    with the probability 1 - exp(-rate dt) (rate at the sample's drive; uniforms[k, i] < it), a jumped one falls back
    pinned once h drops below its return field H_r (far beyond the reverse barrier: at once). Starts pinned."""
    h = np.asarray(h, float)
    n, m = len(h), len(H_p)
    s = np.zeros((n, m), dtype=np.int8)
    cur = np.zeros(m, dtype=np.int8)
    for k in range(n):
        p = -np.expm1(-depinning_rate(h[k], H_p, delta0, f0) * dt)
        cur = np.where((cur == 0) & (uniforms[k] < p), 1, cur)
        cur = np.where(h[k] < H_r, 0, cur).astype(np.int8)
        s[k] = cur
    return s


__all__ = ["turning_points", "prony_creep", "exp_plays", "grid", "plays", "raised_cosine", "loglogistic_plays",
           "becquerel_compliance_closed", "becquerel_prony", "becquerel_compliance", "becquerel_creep",
           "iso6358_phi", "bellows_rate", "bellows_stage", "dipole_bx", "vehicle_passes", "vehicle_offset",
           "mooney_rivlin_stress", "mooney_rivlin_energy", "pad_reading", "weiss_field", "weiss_m", "weiss_reading",
           "can_frames", "can_reading", "rouse_prony", "rouse_creep", "cable_tension", "depinning_rate",
           "barkhausen_states"]

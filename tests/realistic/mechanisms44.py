"""Mechanisms of the HOLDOUT44 set (``cases_holdout44.py``), each written from its law; the signals are in
:mod:`.signals44`.

Nothing here imports hystcomp (nor another set's mechanisms). Every mechanism takes the muscles' pressures (set by the
clean drive), or the core's output, and returns the response; all are causal.

Citations: every source below was written from memory in this session (none was re-read); volumes, pages and years may
be off, and so may the material constants quoted (they are typical values, not a datasheet's). The laws do not rest on
them: each is checked in tests/test_realistic_holdout44.py against an independent solution (the joint's balance solved
by a plain bisection with the contacts written from their definition, a muscle's pull from the braid's volume by a
central difference, the bladders' hereditary integral in closed form segment by segment, LSODA (solve_ivp) of the
contacts' rubber friction, quad, brentq, closed forms).
"""

import math

import numpy as np
from numba import njit
from scipy.special import gamma as _gamma
from .excitations import on_off_intervals


# ---- the rate-independent core: an antagonistic pair of McKibben muscles with braid friction ----
#
# A revolute joint (an arm's elbow on a test stand) is driven by two McKibben pneumatic artificial muscles (a latex
# bladder inside a braided PET sleeve; Schulte 1961, Chou & Hannaford, IEEE Trans. Robot. Autom. 12 (1996) 90) pulling
# in opposition on a chain over the joint's sprocket; two proportional pressure regulators set their pressures from
# the drive: p1 = p_b (1 + k u), p2 = p_b s (1 - k u) (u = v / amp; on a unipolar stroke u = v / top: 0 V is the bias,
# the pair's middle), k the differential swing 0.5 ... 0.62 of the bias, s the second valve's span over the first's (1
# unless a case says otherwise). An optical encoder reads the joint angle. Pressures are in units of the bias p_b.
#
# A muscle's static force (Chou & Hannaford's virtual-work law as Tondu & Lopez, IEEE Control Syst. Mag. 20 (2000) 15,
# wrote it): F = pi r0^2 p [a (1 - eps)^2 - b], a = 3 / tan^2 alpha0, b = 1 / sin^2 alpha0 (alpha0 the braid's angle
# at rest, eps the contraction); forces here in units of pi r0^2 p_b. The joint's coordinate x (the sprocket's travel
# over the muscles' rest length) contracts muscle 1 and stretches muscle 2: eps1 = 1 - c1 + x, eps2 = 1 - c2 - x (c =
# 1 - the pre-contraction the chain's tension set at assembly), so A1(x) = a1 (c1 - x)^2 - b1 and A2(x) = a2 (c2 + x)^2
# - b2. The bladders' latex adds a centring stiffness K (small). The braid's fibres slide on each other and on the
# bladder with dry friction whose normal load is the pressure (Tondu & Lopez's friction, proportional to p; Davis,
# Tsagarakis, Canderle & Caldwell, 2003, on braid friction): each muscle has N_CONT contacts, each a Jenkins element in
# x (a tangential stiffness kappa_j before it slips, its sliding force mu_j times its muscle's pressure), so
# f_j = clamp(kappa_j (x - s_j), -mu_j p, mu_j p), s_j its slip. The joint's balance (quasi-static):
#     p1 A1(x) - p2 A2(x) - K x - sum_j f_j = 0,
# strictly decreasing in x on -c2 < x < c1: one root. The contacts' slip lengths ell_j = mu_j / kappa_j are log-normal.
#
# Rate independent, with return-point memory: the joint's x is increasing in u and in every s_j at fixed history, and
# every contact's bounds x -+ ell_j p are nondecreasing in u whenever the joint's own slope dx/du at fixed slips (every
# contact stuck, the stiffest case; a sliding contact only raises it) exceeds ell_j k (the sliding force's growth with
# its muscle's pressure): then the system is order-preserving (the no-passing property; Middleton, Phys. Rev. Lett. 68
# (1992) 670; Sethna et al., Phys. Rev. Lett. 70 (1993) 3347), and a monotone leg of the drive gives the same state in
# one step as in many. slope_condition() computes that margin; the test checks it for every drawn core. (Beyond a
# regulator's venting, in the saturation case, the vented muscle's contacts have no band and the other's bands grow
# while the arm barely moves: the condition is not claimed there.)
# Close to a Prandtl-Ishlinskii model (the contacts are plays in x, an Iwan model) but not one: the muscles' force law
# is nonlinear in x and in the pressures (the loops widen toward the ends), the contacts' sliding forces scale with
# their muscle's pressure, so one muscle's contacts loosen as the other's tighten.
#
# The virgin state: both muscles vented (no pressure, no friction: every contact relaxed, s_j = x), then charged
# together to the bias (the pressures' ratio fixed: the frictionless balance, x = 0 by the assembly's zeroing, does not
# move while they rise, so no contact is loaded). That is the state at 0 V for bipolar and unipolar records alike (0 V
# is the bias); no settling routine is run.

N_CONT = 64


def braid(alpha0):
    """Tondu & Lopez's a = 3 / tan^2 alpha0 and b = 1 / sin^2 alpha0 (alpha0 in rad)."""
    return 3.0 / math.tan(alpha0) ** 2, 1.0 / math.sin(alpha0) ** 2


def tondu(p, eps, a, b):
    """A muscle's static force p (a (1 - eps)^2 - b) (in pi r0^2 p_b)."""
    return p * (a * (1.0 - eps) ** 2 - b)


def zeroed_c2(a1, b1, c1, a2, b2, s=1.0):
    """The second muscle's c2 for which the frictionless balance at u = 0 is x = 0 at any common pressure: A1(0) = s
    A2(0) (the chain tightened at assembly until the arm sat at its mark)."""
    return math.sqrt(((a1 * c1 * c1 - b1) / s + b2) / a2)


def zeroed_c1(a1, b1, a2, b2, c2, s=1.0):
    """The first muscle's c1 for which the frictionless balance at u = 0 is x = 0 at any common pressure: A1(0) = s
    A2(0) (the first muscle's chain shortened at assembly until the arm sat at its mark)."""
    return math.sqrt((s * (a2 * c2 * c2 - b2) + b1) / a1)


def contacts(seed, n=N_CONT, mu_tot=0.4, ell=0.006, ells=0.55):
    """Both muscles' braid contacts: (kappa, mu, group) for 2 n contacts, group 0 for muscle 1's, 1 for muscle 2's;
    each muscle's sliding forces sum to mu_tot (per unit of its pressure), each mu_j log-normal (the log's spread 0.3),
    the slip lengths ell_j = mu_j / kappa_j log-normal about ell (the log's spread ells)."""
    rng = np.random.default_rng(seed)
    mus, kaps, grp = [], [], []
    for g in (0, 1):
        mu = np.exp(0.3 * rng.standard_normal(n))
        mu *= mu_tot / mu.sum()
        el = ell * np.exp(ells * rng.standard_normal(n))
        mus.append(mu)
        kaps.append(mu / el)
        grp.append(np.full(n, g))
    return np.concatenate(kaps), np.concatenate(mus), np.concatenate(grp).astype(np.int64)


_C_CACHE = {}


def core_contacts(core):
    """The core's contacts (cached by their parameters)."""
    key = (core["cseed"], core.get("n", N_CONT), core["mu_tot"], core["ell"], core["ells"])
    if key not in _C_CACHE:
        _C_CACHE[key] = contacts(core["cseed"], core.get("n", N_CONT), core["mu_tot"], core["ell"], core["ells"])
    return _C_CACHE[key]


def pressures(core, u):
    """The regulators' pressures (p1, p2) for the drive's u: p_b (1 + k u) and p_b s (1 - k u), neither below 0 (a
    regulator vents at most to the atmosphere)."""
    u = np.asarray(u, float)
    s = core.get("s", 1.0)
    return np.maximum(1.0 + core["k"] * u, 0.0), np.maximum(s * (1.0 - core["k"] * u), 0.0)


# ---- the joint's balance, compiled ----

@njit(cache=True)
def _grosch(v, vm, w):
    """The rising flank of the rubber friction's master curve, 0 at rest and 1 at the peak speed vm: exp(-(log10(v /
    vm))^2 / (2 w^2)) below vm, 1 above; and its derivative in v."""
    if v <= 0.0:
        return 0.0, 0.0
    if v >= vm:
        return 1.0, 0.0
    L = math.log10(v / vm)
    G = math.exp(-L * L / (2.0 * w * w))
    return G, G * (-L) / (w * w * v * math.log(10.0))


@njit(cache=True)
def _contact(x, s, kap, thr, D, vm, w, dts):
    """One contact's force at the joint's x from its slip s: clamped at its sliding force thr (D = 0), or (D > 0) a
    backward-Euler step of dts of the rubber friction thr (1 + D G(slip speed)); returns the force, its derivative in
    x and the new slip."""
    ftr = kap * (x - s)
    F = abs(ftr)
    if F <= thr:
        return ftr, kap, s
    sg = 1.0 if ftr > 0 else -1.0
    if D <= 0.0 or thr <= 0.0:
        return sg * thr, 0.0, x - sg * thr / kap
    lo, hi = 0.0, (F - thr) / kap
    tol = 1e-13 * hi + 1e-300
    d = hi
    for _ in range(100):
        G, dG = _grosch(d / dts, vm, w)
        g = F - kap * d - thr * (1.0 + D * G)
        if g > 0:
            lo = d
        else:
            hi = d
        if g == 0.0 or hi - lo <= tol:
            break
        dg = -kap - thr * D * dG / dts
        dn = d - g / dg
        if not (lo < dn < hi):
            dn = 0.5 * (lo + hi)
        if abs(dn - d) <= tol:
            d = dn
            break
        d = dn
    G, dG = _grosch(d / dts, vm, w)
    e = thr * D * dG / dts
    return sg * (F - kap * d), kap * e / (kap + e), s + sg * d


@njit(cache=True)
def _phi(x, p1, p2, a1, b1, c1, a2, b2, c2, K, H0, Hk, xp, s, kap, mu, grp, D, vm, w, dts):
    """The balance at a trial x and its derivative."""
    A1 = a1 * (c1 - x) ** 2 - b1
    A2 = a2 * (c2 + x) ** 2 - b2
    f = p1 * A1 - p2 * A2 - K * x - H0 - Hk * (x - xp)
    df = -2.0 * a1 * p1 * (c1 - x) - 2.0 * a2 * p2 * (c2 + x) - K - Hk
    for j in range(s.shape[0]):
        thr = mu[j] * (p1 if grp[j] == 0 else p2)
        fj, dfj, _ = _contact(x, s[j], kap[j], thr, D, vm, w, dts)
        f -= fj
        df -= dfj
    return f, df


@njit(cache=True)
def _solve(x0, p1, p2, a1, b1, c1, a2, b2, c2, K, H0, Hk, s, kap, mu, grp, D, vm, w, dts):
    """The joint's x where the balance holds (Newton's method in a bisection's bracket, to 1e-15), the slips updated
    in place."""
    lo, hi = -c2 + 1e-9, c1 - 1e-9
    x = min(max(x0, lo), hi)
    for _ in range(200):
        f, df = _phi(x, p1, p2, a1, b1, c1, a2, b2, c2, K, H0, Hk, x0, s, kap, mu, grp, D, vm, w, dts)
        if f > 0:
            lo = x
        else:
            hi = x
        if f == 0.0:
            break
        xn = x - f / df if df < 0 else 0.5 * (lo + hi)
        if not (lo < xn < hi):
            xn = 0.5 * (lo + hi)
        if abs(xn - x) <= 1e-15 or hi - lo <= 1e-15:
            x = xn
            break
        x = xn
    for j in range(s.shape[0]):
        thr = mu[j] * (p1 if grp[j] == 0 else p2)
        _, _, s[j] = _contact(x, s[j], kap[j], thr, D, vm, w, dts)
    return x


@njit(cache=True)
def _run(p1s, p2s, s, x, q, a1, b1, c1, a2, b2, c2, K, kap, mu, grp, lam, gw, D, vm, w, dt, nsub):
    """The joint along the pressures (p1s, p2s) from the slips s, the joint's x and the bladders' hereditary modes q
    (all updated in place): quasi-static (D = 0) or with the contacts' rubber friction (D > 0: nsub backward-Euler
    substeps a sample, the pressures linear between samples); the bladders' relaxing modes (rates lam, weights gw) if
    lam has a length. Returns x at every sample."""
    Kn = p1s.shape[0]
    out = np.empty(Kn)
    M = lam.shape[0]
    e = np.empty(M)
    ph = np.empty(M)
    for i in range(M):
        z = lam[i] * dt
        e[i] = math.exp(-z)
        ph[i] = 1.0 if z == 0.0 else -math.expm1(-z) / z
    pp1, pp2 = p1s[0], p2s[0]
    for k in range(Kn):
        H0 = 0.0
        Hk = 0.0
        for i in range(M):
            H0 += e[i] * q[i]
            Hk += gw[i] * ph[i]
        if D > 0.0:
            for j in range(1, nsub + 1):
                c = j / nsub
                xn = _solve(x, pp1 + (p1s[k] - pp1) * c, pp2 + (p2s[k] - pp2) * c, a1, b1, c1, a2, b2, c2, K, H0, Hk,
                            s, kap, mu, grp, D, vm, w, dt / nsub)
                x = xn
        else:
            xn = _solve(x, p1s[k], p2s[k], a1, b1, c1, a2, b2, c2, K, H0, Hk, s, kap, mu, grp, 0.0, 1.0, 1.0, 1.0)
            for i in range(M):
                q[i] = e[i] * q[i] + gw[i] * ph[i] * (xn - x)
            x = xn
        pp1, pp2 = p1s[k], p2s[k]
        out[k] = x
    return out


def virgin(core):
    """The virgin state (vented, then charged together to the bias): every contact relaxed at x = 0."""
    kap, _, _ = core_contacts(core)
    return dict(s=np.zeros(len(kap)), x=0.0, q=np.zeros(len(core.get("lam", ()))))


def joint(core, p1, p2, state=None, return_state=False, dt=1.0, rate=None, nsub=2, modes=None):
    """The joint's x along the pressures (p1, p2) from a state (default the virgin pair); rate = (D, vm, w) for the
    contacts' rubber friction (dt the sample interval, nsub substeps), modes = (lam, gw) for the bladders' relaxing
    latex (the state's q their forces)."""
    if rate is not None and modes is not None:
        raise ValueError("the rubber friction and the relaxing latex are not run together")
    kap, mu, grp = core_contacts(core)
    st = virgin(core) if state is None else state
    s = np.array(st["s"], float)
    lam, gw = (np.zeros(0), np.zeros(0)) if modes is None else (np.asarray(modes[0], float),
                                                                np.asarray(modes[1], float))
    q = np.zeros(len(lam)) if len(st.get("q", ())) != len(lam) else np.array(st["q"], float)
    D, vm, w = (0.0, 1.0, 1.0) if rate is None else rate
    x = _run(np.ascontiguousarray(p1, dtype=float), np.ascontiguousarray(p2, dtype=float), s, np.float64(st["x"]), q,
             core["a1"], core["b1"], core["c1"], core["a2"], core["b2"], core["c2"], core["K"], kap, mu, grp, lam, gw,
             float(D), float(vm), float(w), float(dt), int(nsub))
    if return_state:
        return x, dict(s=s, x=float(x[-1]) if len(x) else float(st["x"]), q=q)
    return x


def reading(core, x):
    """The encoder's angle in degrees: G x (G the chain's ratio, the muscles' length over the sprocket's radius, in
    degrees per unit of x)."""
    return core["G"] * np.asarray(x, float)


def slope_condition(core, umax=1.0, n=41):
    """The order-preserving condition's margin: min over |u| <= umax, and over x within the frictionless balance +-
    twice the contacts' whole sliding force over the pneumatic stiffness, of the joint's slope at fixed slips with
    every contact stuck, D0 / (S0 + sum kappa) (D0 = k A1 + s k A2 the pressures' pull per unit u, S0 = 2 a1 p1 (c1 - x)
    + 2 a2 p2 (c2 + x) + K), over the largest ell_j k_j (a contact's band's growth per unit u, k_j = k or s k). Over 1:
    the contacts' bounds are nondecreasing in u for every partition into stuck and sliding contacts (a sliding contact,
    its m_j / kappa_j = ell_j k_j below the ratio, only raises it: the mediant's rule), so the pair is order-preserving
    and has return-point memory."""
    kap, mu, grp = core_contacts(core)
    a1, b1, c1, a2, b2, c2, K = (core[q] for q in ("a1", "b1", "c1", "a2", "b2", "c2", "K"))
    k, sv = core["k"], core.get("s", 1.0)
    kj = np.where(grp == 0, k, sv * k)
    grow = float(np.max(mu / kap * kj))
    worst = np.inf
    for u in np.linspace(-umax, umax, n):
        p1, p2 = (float(q) for q in pressures(core, u))
        xb = balance_x(core, p1, p2)
        S0b = 2 * a1 * p1 * (c1 - xb) + 2 * a2 * p2 * (c2 + xb) + K
        band = 2.0 * (mu[grp == 0].sum() * p1 + mu[grp == 1].sum() * p2) / S0b
        for x in np.linspace(xb - band, xb + band, 9):
            D0 = k * (a1 * (c1 - x) ** 2 - b1) + sv * k * (a2 * (c2 + x) ** 2 - b2)
            S0 = 2 * a1 * p1 * (c1 - x) + 2 * a2 * p2 * (c2 + x) + K
            worst = min(worst, D0 / (S0 + kap.sum()))
    return worst / grow


def balance_x(core, p1, p2):
    """The frictionless balance p1 A1(x) - p2 A2(x) - K x = 0 (bisection to 1e-15)."""
    a1, b1, c1, a2, b2, c2, K = (core[q] for q in ("a1", "b1", "c1", "a2", "b2", "c2", "K"))
    lo, hi = -c2 + 1e-9, c1 - 1e-9
    for _ in range(200):
        m = 0.5 * (lo + hi)
        f = p1 * (a1 * (c1 - m) ** 2 - b1) - p2 * (a2 * (c2 + m) ** 2 - b2) - K * m
        if f > 0:
            lo = m
        else:
            hi = m
        if hi - lo < 1e-15:
            break
    return 0.5 * (lo + hi)


# ---- rate dependence: the braid's rubber friction ----
#
# The fibres slide on the latex, and rubber's friction rises with the sliding speed, over decades of it, to a peak
# where the rubber's loss modulus peaks (Grosch, Proc. R. Soc. Lond. A 274 (1963) 21: a bell-shaped master curve in
# log speed; the shape here, the curve's rising flank as a Gaussian in log10 of the speed below the peak's speed vm, of
# width w decades, flat at the peak above it, is a choice): a sliding contact's force is mu_j p (1 + D G(|ds/dt|)),
# G = exp(-(log10(v / vm))^2 / (2 w^2)) below vm, 1 above. At rest it is the dry sliding force, so the quasi-static
# core is the limit of slow moves; a fast move drags the contacts harder and the loop widens. Solved by backward Euler
# in substeps (each sliding contact's speed from its force balance, Newton's method in a bisection's bracket).

#: substeps a sample of the rubber friction
RATE_SUB = 2


# ---- creep: the bladders' latex relaxing (Chasset and Thirion's law) ----
#
# Thick latex bladders: the latex's share of the joint's stiffness relaxes. A lightly crosslinked network's relaxation
# modulus follows Chasset & Thirion's law, E(t) = E_inf [1 + (t / tau0)^-m] (Chasset & Thirion, in *Physics of
# Non-Crystalline Solids*, 1965; for a well-cured natural rubber m about 0.1 ... 0.2 and tau0 far below a millisecond,
# as remembered), here regularised at t = 0 as E_inf [1 + (1 + t / tau0)^-m], with the constants of a soft, lightly
# cured dipped latex drawn by the case (m 0.3 ... 0.38, tau0 50 ... 160 ms: chosen, not quoted): after a move the
# latex's resistance falls, and the joint goes on moving the way it went, ever slower (a creep in the direction of the
# last move, a power law in time). The hereditary force
# K_inf x + K_inf int (1 + (t - t') / tau0)^-m dx(t'), its kernel written as a sum of exponentials from its Laplace
# representation (1 + t / tau0)^-m = (1 / Gamma(m)) int_0^inf z^(m - 1) e^-z e^(-z t / tau0) dz (the trapezoidal rule
# in log z, exact for x linear between samples).

def relaxation_modes(K_tr, m, tau0, h=0.2, wmin=-60.0, wmax=4.0):
    """The exponential modes (rates lam, weights gw) of K_tr (1 + t / tau0)^-m: z = e^w on a grid of step h over
    [wmin, wmax] (the trapezoidal rule), and one mode of rate 0 for the z below e^wmin (9e-27: they do not relax within
    any record)."""
    wg = np.arange(wmin, wmax + 1e-12, h)
    z = np.exp(wg)
    lam = z / tau0
    wt = np.full(len(wg), h)
    wt[0] = wt[-1] = h / 2
    gw = K_tr * wt * np.exp(m * wg - z) / _gamma(m)
    tail = K_tr * math.exp(m * wmin) / m / _gamma(m)
    return np.r_[lam, 0.0], np.r_[gw, tail]


def kernel(modes, t):
    """The modes' kernel sum_i gw_i exp(-lam_i t)."""
    lam, gw = modes
    t = np.asarray(t, float)
    return np.exp(-np.multiply.outer(t, lam)) @ gw


# ---- delay: the playback's start relay ----
#
# The drive's playback (a DAC card's buffered output) is started by a trigger through an electromechanical relay,
# while the encoder's counter card starts on the trigger itself: the command reaches the regulators late by the
# relay's operate time (a general-purpose power relay: 5 ... 9 ms, a typical datasheet's figure as remembered; the
# coil's current rising through its L / R, the armature's travel, the contacts' closure). The logged drive is the
# programme on the logger's clock; the joint follows it late by T_op. A pure delay of the core: y(t) = core(v(t -
# T_op)).


# ---- drift: a pinhole tearing in a bladder ----
#
# The second muscle's bladder has a pinhole at the edge of its end fitting, which tears a little further every time the
# muscle is pressurised (the latex's fatigue crack growing with every load cycle: the tear's area grows by a fixed
# amount per unit rise of its pressure, a Paris-like law with its exponent 1 at these small amplitudes; Lake & Lindley,
# J. Appl. Polym. Sci. 9 (1965) 1233, on rubber's cut growth). The leak it opens draws flow through the regulator, whose
# output droops in proportion to the flow (a regulator's droop, its flow characteristic's slope); the leak's flow is
# taken proportional to the muscle's gauge pressure (a simplification: a real slit's flow is not quite linear in it),
# so the muscle's pressure is p2 / (1 + r), r = C / G the leak's conductance over the regulator's flow gain, growing
# with the muscle's cumulative pressure rises.

def tear_droop(p2, r_end):
    """The droop's ratio r at every sample: proportional to the cumulative rises of p2 (sum of max(dp2, 0)), r_end at
    the end."""
    p2 = np.asarray(p2, float)
    rise = np.r_[0.0, np.cumsum(np.maximum(np.diff(p2), 0.0))]
    return r_end * rise / rise[-1]


# ---- asymmetry: two regulators of different spans ----
#
# Muscle 2's regulator is a smaller model than muscle 1's (a 0 ... 6 bar valve beside a 0 ... 10 bar one, both on the
# same 0 ... 10 V command): p2 = p_b s (1 - k u), s 0.55 ... 0.65, the first muscle's chain shortened at assembly so
# the arm sits at its mark at the bias (c1 from zeroed_c1; no muscle stretched past its rest length). Without the latex
# the frictionless balance depends only on the pressures' ratio, (1 + k u) / (s (1 - k u)), but the muscles work at
# different points of their force curves (the first nearer its lock) and muscle 2's contacts slide at s of muscle 1's
# forces: the loop is asymmetric.


# ---- saturation: the regulator venting and the braid's lock ----
#
# Overdriven (k u beyond 1 at the ends: the command asks for a negative gauge pressure), a regulator vents its muscle
# to the atmosphere and no lower (pressures() clips at 0): the other muscle, unopposed but for the latex, runs toward
# its braid's lock (a (c - x)^2 = b, where its force vanishes: the fibres at their neutral angle, 54.7 deg) and stops
# short of it (the latex and the contacts holding it) however high its pressure. The arm's travel flattens at both
# ends.


# ---- output saturation: an AMR angle sensor ----
#
# In the pair with asymmetry, the joint's angle is read by an anisotropic magnetoresistive sensor under a diametric
# magnet on the joint's axis: the bridge's output is V0 sin(2 theta) (the film's resistance goes as cos^2 of the angle
# between its current and magnetisation, W. Thomson 1857 as remembered; a Wheatstone bridge of strips at +-45 deg; the
# single sine channel read, the cosine channel not logged), scaled to degrees at the middle: (1 / 2) sin(2 theta) in
# rad. The ends compress.

def amr_reading(theta_deg):
    """The AMR bridge's sine channel scaled to degrees at the middle: (180 / pi) (1 / 2) sin(2 theta)."""
    th = np.radians(np.asarray(theta_deg, float))
    return np.degrees(0.5 * np.sin(2.0 * th))


def amr_compression(theta_max_deg):
    """How much the reading's end is compressed at theta_max: 1 - sin(2 t) / (2 t)."""
    t = math.radians(theta_max_deg)
    return 1.0 - math.sin(2 * t) / (2 * t)


# ---- out of vocabulary: a blow gun on the same supply line ----
#
# Someone in the workshop uses a blow gun on the compressed-air line that feeds both regulators: while it is open the
# line's pressure at the regulators falls (the line's and the filter's pressure drop at that flow), below what the
# higher muscle's regulator is asked for, and a regulator cannot give more than its supply less its own small drop:
# p_i = min(p_i, p_line(t)). The blow gun's bursts (0.4 ... 1.5 s, 2 ... 6 s apart) are not in the record.

def blow_gun(t, on_range, off_range, rng):
    """The blow gun's bursts [(start, duration)] over t (the first after an off time), and a 0/1 mask of the samples in
    them."""
    return on_off_intervals(t, on_range, off_range, rng)

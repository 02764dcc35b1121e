"""Mechanisms of the HOLDOUT54 set (``cases_holdout54.py``), each written from its law; the signals are in
:mod:`.signals54`.

Nothing here imports hystcomp, nor another set's mechanisms. Every mechanism takes the strip's temperature (set by the
drive), its crystallites' high-spin fractions or its free elongation, and returns the response; all are causal.

Citations: every source below was written from memory in this session (none was re-read); volumes, pages and years may
be off, and so may the constants quoted (typical values as remembered, not a datasheet's). The laws do not rest on them:
each is checked in tests/test_realistic_holdout54.py against an independent solution (every crystallite's branch by
brentq of the Slichter-Drickamer condition and its state by the last spinodal the temperature crossed; the rest state by
an explicit decaying thermal cycling; the kinetic master equation by solve_ivp; the creep kernel's means by quad and the
Volterra solution by its own equation; the enclosure's humidity by its switching times in closed form and the sheet's
uptake by a finite-difference solution of Fick's law; the crank by its geometry; the converter's filter by three boxes
convolved and quad; the warm-up by solve_ivp; the bridge by its resistances; the scale's wrap by its sine and cosine).
"""

import math

import numpy as np
from numba import njit
from scipy.special import ndtri

# ---- the rate-independent core: a spin-crossover composite strip ----
#
# The actuator is a strip 25 mm long (5 mm wide, 60 um thick) of a composite: crystallites (80 ... 150 nm) of an
# iron(II) triazole spin-crossover compound, a molecular alloy [Fe(Htrz)_(3-3y)(NH2trz)_(3y)](BF4)2 whose transition the
# amino-triazole share y tunes to about room temperature (Kahn & Jay Martinez, Science 279 (1998) 44, as remembered),
# 0.4 of the volume in a polyurethane matrix; a thin-film heater on one face and the strip in a thermostated air stream,
# the temperature loop setting the strip's temperature T = T_b + g v (g = 0.16 K a volt of the drive, T_b the bias: the
# middle of the crystallites' loops) on the bipolar records, T = T_b + g (v - 47) on the unipolar ones (the drive's 0 V
# the cold end); the strip's own thermal time (60 um: some 10 ms) is left out: quasi-static. The strip pulls a light
# carriage against a soft return spring (its elastic stretch a gain), read by an LVDT (um; zeroed at the start of every
# record).
#
# Every crystallite is a cooperative mean-field body (Slichter & Drickamer, J. Chem. Phys. 56 (1972) 2142, as
# remembered): the free energy per mole of its high-spin fraction x,
#
#     G(x) = x Delta_H - T x Delta_S + Gamma x (1 - x) + R T [x ln x + (1 - x) ln (1 - x)],
#
# Delta_S = 60 J / (mol K) (the spin and the vibrational entropy, as remembered for iron(II) triazoles), Delta_H =
# T_half Delta_S, Gamma = 2 R T_half kappa the elastic interaction (kappa > 1: bistable, the crystallite switching with
# a hysteresis). Its state is a local minimum of G: dG/dx = 0,
#
#     g(x) = Delta_H + Gamma (1 - 2 x) - T Delta_S + R T ln(x / (1 - x)) = 0,
#
# on its low-spin branch (x below the smaller root x_- of x (1 - x) = R T / (2 Gamma)) until that branch's minimum
# merges with the maximum (g(x_-) < 0: the upper spinodal), then on its high-spin branch (x above x_+) until g(x_+) > 0
# (the lower spinodal); where Gamma <= 2 R T there is one branch. A crystallite's switching at a spinodal is quick (the
# elastic avalanche: microseconds in nanocrystals), so the strip is rate independent; each branch bends with T (the
# thermal population of the other spin state), unlike a relay's. The crystallites differ: T_half normal about the
# blend's mean (its spread s_h 6.5 ... 7.5 K, the molecular alloy's local composition), kappa log-normal (median 1.18
# ... 1.24, log spread 0.04: the crystallites' size and strain; every crystallite bistable), N_CRYST classes of equal
# volume on a two-dimensional Kronecker (R2) sequence over the two quantiles (kappa in N_LEVELS strata: its quantile's
# middle in each) (Roberts 2018, the generalised golden ratio, as remembered), shifted by the core's seed.
#
# The strip's length takes the crystallites' volume change: the high-spin lattice is larger by eps_v = 0.10 (the Fe-N
# bonds' 0.2 Angstrom; 0.08 ... 0.11 as remembered for triazole chains) and expands more (beta_HS 1.6e-4 / K against
# beta_LS 1.0e-4 / K, volumetric), a third of it along the strip; the matrix's linear expansion 1.2e-4 / K (a
# polyurethane, 0.6 of the volume): e = PHI_C / 3 [eps_v xbar + (beta_LS (1 - xbar) + beta_HS xbar) (T - T_r)] +
# PHI_M alpha_m (T - T_r), xbar the crystallites' mean high-spin fraction; the reading 1e6 L (e - e(start)) um.
#
# Rate independent, with return-point memory (every crystallite a bistable body on its branches); close to a
# Prandtl-Ishlinskii model but not one (measured in the test and stated there): the loops' centres are normal, not a
# uniform density, a crystallite's width grows with its kappa, its branches bend with the temperature, and the high-spin
# lattice's expansion multiplies the temperature by xbar.
#
# The rest state: before every record but the initial-state case's the controller's conditioning routine cycles the
# strip about the drive's 0 V temperature with a slowly decaying amplitude; its limit leaves every crystallite high spin
# whose loop's middle (its spinodals' mean) lies below that temperature and low spin otherwise (on that branch at that
# temperature): set so, not run (checked in the test against an explicit decaying cycling).

R_GAS = 8.314462618
DS = 60.0
N_CRYST = 3000
KAPPA_SPREAD = 0.04
L_STRIP = 25e-3
PHI_C, PHI_M = 0.4, 0.6
EPS_V = 0.10
BETA_LS, BETA_HS = 1.0e-4, 1.6e-4
ALPHA_M = 1.2e-4
GAIN = 0.16
V_MID = 47.0
PHI2 = 1.3247179572447460  # the real root of x^3 = x + 1: the R2 sequence's generalised golden ratio (two dims)


def r2_points(n, shift):
    """n points of the two-dimensional R2 sequence: (shift + k (1 / phi, 1 / phi^2)) mod 1, k = 1 ... n."""
    a = np.array([1.0 / PHI2, 1.0 / PHI2 ** 2])
    return (np.asarray(shift, float)[None, :] + np.arange(1, n + 1)[:, None] * a[None, :]) % 1.0


N_LEVELS = 24
N_TAB = 4001
TAU_LO, TAU_HI = 0.8, 1.25
_CRYST = {}
_TABLES = {}


def levels(k50):
    """The N_LEVELS values of kappa: the log-normal's (median k50, log spread KAPPA_SPREAD) quantiles at the strata's
    middles (j + 1/2) / N_LEVELS."""
    return k50 * np.exp(KAPPA_SPREAD * ndtri((np.arange(N_LEVELS) + 0.5) / N_LEVELS))


def crystallites(core):
    """The core's crystallite classes: (T_half (K), its kappa level's index) of N_CRYST classes of equal volume."""
    key = (core["rseed"], core["Th0"], core["sh"])
    if key not in _CRYST:
        shift = np.random.default_rng(core["rseed"]).uniform(size=2)
        u = np.clip(r2_points(N_CRYST, shift), 1e-12, 1.0 - 1e-12)
        th = core["Th0"] + core["sh"] * ndtri(u[:, 0])
        lev = np.minimum((u[:, 1] * N_LEVELS).astype(np.int64), N_LEVELS - 1)
        _CRYST[key] = (th, lev)
    return _CRYST[key]


def g_reduced(u, tau, kappa):
    """The Slichter-Drickamer condition over R T_half: (DS / R) (1 - tau) + 2 kappa (1 - 2 x) + tau u, x = 1 / (1 +
    e^-u), tau = T / T_half."""
    x = 1.0 / (1.0 + np.exp(-u))
    return DS / R_GAS * (1.0 - tau) + 2.0 * kappa * (1.0 - 2.0 * x) + tau * u


def spinodal_u(tau, kappa):
    """u at the roots x_-, x_+ of x (1 - x) = tau / (4 kappa) (dg / dx = 0), for tau < kappa."""
    r = np.sqrt(1.0 - np.asarray(tau, float) / kappa)
    xm, xp = 0.5 * (1.0 - r), 0.5 * (1.0 + r)
    return np.log(xm / (1.0 - xm)), np.log(xp / (1.0 - xp))


def spinodals(kappa):
    """(tau_up, tau_dn): where the low-spin branch ends (g(x_-) = 0, between 1 and kappa) and where the high-spin one
    does (g(x_+) = 0, between 0.5 and 1), by bisection in tau (200 halvings: to the last bit; g there falls as tau
    rises on both)."""
    def edge(side):
        lo, hi = (1.0, kappa) if side == 0 else (0.5, 1.0)
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            gm = g_reduced(spinodal_u(mid, kappa)[side], mid, kappa)
            if gm > 0.0:
                lo = mid
            else:
                hi = mid
        return 0.5 * (lo + hi)
    return edge(0), edge(1)


def _solve_branch(tau, kappa, lo, hi):
    """u with g_reduced(u, tau, kappa) = 0 between lo and hi (arrays; g rises there), by bisection (64 halvings: from
    a bracket of at most 160 to under 1e-17)."""
    lo, hi = np.array(lo, float), np.array(hi, float)
    for _ in range(64):
        mid = 0.5 * (lo + hi)
        up = g_reduced(mid, tau, kappa) > 0.0
        hi = np.where(up, mid, hi)
        lo = np.where(up, lo, mid)
    return 0.5 * (lo + hi)


def tables(k50):
    """Per kappa level: the spinodals and the two branches' high-spin fractions on N_TAB points each, uniform in w =
    sqrt(tau_up - tau) on the low-spin branch (from tau_up down to TAU_LO) and in w = sqrt(tau - tau_dn) on the
    high-spin one (from tau_dn up to TAU_HI): a branch ends at its spinodal as a square root of the distance (a
    saddle-node), so x is smooth in w there. Returns (tau_up, tau_dn, x_LS, x_HS)."""
    if k50 not in _TABLES:
        ks = levels(k50)
        t_up, t_dn = np.empty(N_LEVELS), np.empty(N_LEVELS)
        xl, xh = np.empty((N_LEVELS, N_TAB)), np.empty((N_LEVELS, N_TAB))
        for j, kap in enumerate(ks):
            t_up[j], t_dn[j] = spinodals(kap)
            tl = t_up[j] - np.linspace(0.0, math.sqrt(t_up[j] - TAU_LO), N_TAB) ** 2
            xl[j] = 1.0 / (1.0 + np.exp(-_solve_branch(tl, kap, np.full(N_TAB, -80.0), spinodal_u(tl, kap)[0])))
            th = t_dn[j] + np.linspace(0.0, math.sqrt(TAU_HI - t_dn[j]), N_TAB) ** 2
            below = th < kap
            lo = np.full(N_TAB, -80.0)
            lo[below] = spinodal_u(th[below], kap)[1]
            xh[j] = 1.0 / (1.0 + np.exp(-_solve_branch(th, kap, lo, np.full(N_TAB, 80.0))))
        _TABLES[k50] = (t_up, t_dn, xl, xh)
    return _TABLES[k50]


@njit(cache=True)
def branch_x(tab, edge, far, tau, low):
    """A branch's table (tables()) at tau, linearly interpolated in w = sqrt(|tau - edge|) (edge the branch's spinodal,
    far its table's other end; low for the low-spin branch)."""
    d = edge - tau if low else tau - edge
    w = math.sqrt(max(d, 0.0))
    p = w / math.sqrt(abs(far - edge)) * (tab.shape[0] - 1)
    i = min(int(p), tab.shape[0] - 2)
    f = p - i
    return tab[i] * (1.0 - f) + tab[i + 1] * f


@njit(cache=True)
def _ensemble(T, th, lev, t_up, t_dn, xl, xh, s):
    """The crystallites' mean high-spin fraction along the temperatures T (K): each on its branch s (0 low spin, 1 high
    spin), switching up past tau_up and down past tau_dn (tau = T / T_half); s carried in and out."""
    n = T.shape[0]
    m = th.shape[0]
    out = np.empty(n)
    for i in range(n):
        tot = 0.0
        for k in range(m):
            tau = T[i] / th[k]
            j = lev[k]
            if s[k] > 0.5:
                if tau < t_dn[j]:
                    s[k] = 0.0
            elif tau > t_up[j]:
                s[k] = 1.0
            if s[k] > 0.5:
                tot += branch_x(xh[j], t_dn[j], TAU_HI, tau, False)
            else:
                tot += branch_x(xl[j], t_up[j], TAU_LO, tau, True)
        out[i] = tot / m
    return out


def bias(core):
    """The bias T_b (K): the median of the classes' loops' middles (tau_up + tau_dn) T_half / 2."""
    th, lev = crystallites(core)
    t_up, t_dn = tables(core["k50"])[:2]
    return float(np.median(0.5 * (t_up[lev] + t_dn[lev]) * th))


def temperature(core, v):
    """The strip's temperature (K) for the drive v (V): T_b + g v, on the unipolar records T_b + g (v - 47)."""
    v = np.asarray(v, float)
    return core["Tb"] + GAIN * (v - V_MID if core["unipolar"] else v)


def rest_state(core, T):
    """The conditioning's limit at the temperature T: every class high spin (1) whose loop's middle lies below T."""
    th, lev = crystallites(core)
    t_up, t_dn = tables(core["k50"])[:2]
    return (0.5 * (t_up[lev] + t_dn[lev]) * th < T).astype(float)


def hs_fraction(core, T, s=None):
    """The mean high-spin fraction along the temperatures T (K), from the branches s (default the rest state at T[0]);
    s is updated in place when given."""
    T = np.asarray(T, float)
    th, lev = crystallites(core)
    t_up, t_dn, xl, xh = tables(core["k50"])
    s = rest_state(core, T[0]) if s is None else s
    return _ensemble(T, th, lev, t_up, t_dn, xl, xh, s)


def strain(T, xbar, T_r):
    """The strip's linear strain about the reference T_r at the temperatures T and mean high-spin fractions xbar."""
    d = np.asarray(T, float) - T_r
    xbar = np.asarray(xbar, float)
    return PHI_C / 3.0 * (EPS_V * xbar + (BETA_LS * (1.0 - xbar) + BETA_HS * xbar) * d) + PHI_M * ALPHA_M * d


def reading(T, xbar):
    """The LVDT's reading (um, zeroed at the first sample) of the strip at the temperatures T and fractions xbar."""
    e = strain(T, xbar, T[0])
    x = 1e6 * L_STRIP * e
    return x - x[0]


def core_reading(core, v, s=None):
    """The rate-independent strip's reading (um) for the drive v, from the branches s (default the rest state)."""
    T = temperature(core, v)
    return reading(T, hs_fraction(core, T, s))


# ---- creep: a nylon pushrod with logarithmic creep ----
#
# The creep record's strip works a valve's poppet through a polyamide (nylon 6) pushrod against the poppet's return
# spring (k_L), the LVDT reading the poppet. Nylon's creep compliance is close to logarithmic in time over seconds to
# hours, J(t) = J_0 + J_1 ln(1 + t / tau_c) (the semicrystalline polymers' log-time creep, Struik, Physical Aging in
# Amorphous Polymers and Other Materials, 1978, and the fibre literature, as remembered; tau_c 0.05 ... 0.2 s, a
# choice). The rod's shortening u = int J(t - s) dF(s), F = F_0 + k_L x (the spring's preload long applied: only its
# changes creep), and the poppet's travel x = d - u, d the strip's free elongation: x + k_L int J(t - s) dx(s) = d, a
# Volterra equation of the second kind, solved step by step for x linear between samples (its kernel the compliance's
# means over the samples' intervals). In the units used: k_L J_0 = c_0 (0.04 ... 0.07) and k_L J_1 = c_1 (0.04 ...
# 0.06). After a rise the poppet sags back, after a fall it recovers (labelled "creep").

def log_creep_kernel(n, dt, c0, c1, tau_c):
    """k_m: c_0 + c_1 ln(1 + t / tau_c)'s mean over [m dt, (m + 1) dt], m = 0 ... n - 1 (its antiderivative c_0 t +
    c_1 ((t + tau_c) ln(1 + t / tau_c) - t))."""
    tt = np.arange(n + 1) * dt
    A = c0 * tt + c1 * ((tt + tau_c) * np.log1p(tt / tau_c) - tt)
    return np.diff(A) / dt


@njit(cache=True)
def volterra_creep(d, kern):
    """x with x_i + sum_(1 <= j <= i) (x_j - x_(j-1)) kern_(i-j) = d_i (the record starts at rest), solved for x_i step
    by step."""
    n = d.shape[0]
    x = np.empty(n)
    x[0] = d[0]
    dx = np.zeros(n)
    for i in range(1, n):
        acc = 0.0
        for j in range(1, i):
            acc += dx[j] * kern[i - j]
        xi = (d[i] - acc + x[i - 1] * kern[0]) / (1.0 + kern[0])
        dx[i] = xi - x[i - 1]
        x[i] = xi
    return x


# ---- rate dependence: micro-crystals switching at a finite speed ----
#
# The rate record's strip was cast from micro-crystals (1 ... 3 um) instead of the nanocrystals: their transition runs
# as a front across the crystal, and each crystallite's high-spin fraction relaxes toward its free energy's minimum by
# the mean-field master equation of the Ising-like model (Glauber dynamics; Boukheddaden, Shteto, Hoo & Varret, Phys.
# Rev. B 62 (2000) 14796, as remembered):
#
#     dx / dt = [(1 - x) exp(-a / 2) - x exp(a / 2)] / tau_k,   a = (Delta_H + Gamma (1 - 2 x) - T Delta_S) / (R T),
#
# whose fixed points are the Slichter-Drickamer branches (a = ln((1 - x) / x)) and which slows near the spinodals
# (the critical slowing down of a saddle-node); tau_k 25 ... 40 ms (a choice; the nanocrystals' is under 0.1 ms and is
# left out of the other records). Solved on SUB_KIN sub-steps a sample, each exact for the linear equation with a
# frozen at the step's start (x_eq + (x - x_eq) exp(-(k_+ + k_-) h)): stable at any step; a step that would move a by
# over DA_MAX (a crystallite's switch: a avalanche) is split (the split's step DA_MAX / (4 kappa |x_eq - x| (k_+ +
# k_-) / tau)). A lag of the switching that
# grows with the drive's speed and loops that widen with it (labelled "rate_dependence").

SUB_KIN = 4


DA_MAX = 0.02


@njit(cache=True)
def _kinetic(T, th, kap, x, hk, sub):
    """The master equation's steps (hk the sub-step over tau_k); x carried in and out. Each sub-step is split where
    the step would move a by over DA_MAX (during a crystallite's switch), so that the frozen a errs by little."""
    n = T.shape[0]
    m = th.shape[0]
    out = np.empty(n)
    h = 1.0 / sub
    ds_r = DS / R_GAS
    out[0] = x.mean()
    for i in range(1, n):
        for q in range(sub):
            Ti = T[i - 1] + (T[i] - T[i - 1]) * (q + 0.5) * h
            for k in range(m):
                tau = Ti / th[k]
                c4 = 4.0 * kap[k] / tau
                left = hk
                while left > 0.0:
                    a = (ds_r * (1.0 - tau) + 2.0 * kap[k] * (1.0 - 2.0 * x[k])) / tau
                    kp, km = math.exp(-0.5 * a), math.exp(0.5 * a)
                    xe = kp / (kp + km)
                    step = left
                    da = c4 * abs(xe - x[k]) * (1.0 - math.exp(-(kp + km) * step))
                    if da > DA_MAX:
                        step = min(left, max(DA_MAX / (c4 * abs(xe - x[k]) * (kp + km)), 1e-4 * hk))
                    x[k] = xe + (x[k] - xe) * math.exp(-(kp + km) * step)
                    left -= step
        out[i] = x.mean()
    return out


def kinetic_fraction(core, T, dt, tau_k, sub=SUB_KIN):
    """The mean high-spin fraction along the temperatures T (K, on a step dt) of crystallites relaxing by the master
    equation (time constant tau_k), from the rest state at T[0] on its branches (each class's x there from the
    tables), the temperature linear between samples (its midpoint on each sub-step)."""
    T = np.asarray(T, float)
    th, lev = crystallites(core)
    t_up, t_dn, xl, xh = tables(core["k50"])
    s = rest_state(core, T[0])
    x = np.array([branch_x(xh[j], t_dn[j], TAU_HI, T[0] / t, False) if sk > 0.5 else
                  branch_x(xl[j], t_up[j], TAU_LO, T[0] / t, True) for t, j, sk in zip(th, lev, s)])
    kap = levels(core["k50"])[lev]
    return _kinetic(T, th, kap, x, dt / sub / tau_k, sub)


# ---- drift: an enclosure's humidity under an on-off hygrostat ----
#
# The drift record's strip sat in a small environmental enclosure whose humidifier is switched by an on-off hygrostat:
# on below S - b / 2, off above S + b / 2 (b 6 ... 8 % RH: a mechanical hygrostat's differential, as remembered); the
# enclosure's air mixes toward RH_hi (3 ... 6 % RH above the band: a humidifier barely keeping up) with the humidifier
# on and toward RH_lo (6 ... 10 % RH below it: the dry purge) with it off, tau_e 40 ... 60 s: a lopsided exponential
# sawtooth (a period of a minute or two). The strip's polyurethane matrix takes up water through both faces by Fick's
# law (its surfaces at equilibrium with the air, Henry's law: uptake linear in RH), a plane sheet of thickness l (60 um)
# with D 1.5e-11 ... 2.5e-11 m^2 / s (tau_1 15 ... 24 s): its mean uptake the sum of the sheet's modes, w_n = 8 / ((2 n
# + 1)^2 pi^2), tau_n = l^2 / ((2 n + 1)^2 pi^2 D) (Crank, The Mathematics of Diffusion, 1975, ch. 4, as remembered),
# each exact per step; the strip swells by beta_h (1.6e-4 per % RH at equilibrium: a polyurethane's 2.7e-4 on 0.6 of the
# volume, a choice) times its mean uptake (labelled "drift"). The loop ran 600 s before the record: it is in its limit
# cycle.

N_MODES = 400
BETA_H = 1.6e-4


def hygrostat(t_end, lead, S, b, rh_hi, rh_lo, tau_e, h=0.05):
    """The enclosure's RH (%) on steps h from -lead to beyond t_end: exponential toward rh_hi while the humidifier is
    on, toward rh_lo while off, on below S - b / 2 and off above S + b / 2; from S - b / 2 with the humidifier on
    (exact per step but for the switching, which waits for the next step). Returns (times, RH)."""
    n = int(round((t_end + lead) / h)) + 2
    rh = np.empty(n)
    r, on = S - 0.5 * b, True
    e = math.exp(-h / tau_e)
    for k in range(n):
        rh[k] = r
        if on and r > S + 0.5 * b:
            on = False
        elif not on and r < S - 0.5 * b:
            on = True
        tgt = rh_hi if on else rh_lo
        r = tgt + (r - tgt) * e
    return np.arange(n) * h - lead, rh


def sheet_uptake(times, rh, thick, D, n_modes=N_MODES):
    """The sheet's mean uptake (in % RH at equilibrium) following the surface's RH on the times (uniform): sum_n w_n
    m_n, tau_n m_n' = RH - m_n, each exact per step for RH linear between the steps, from m_n = RH at the start (the
    sheet long at the first RH); the modes beyond n_modes (their weight some 4 / (pi^2 n_modes), their times under
    1e-5 of the first's) taken as following RH at once."""
    k = 2 * np.arange(n_modes) + 1
    w = 8.0 / (k ** 2 * math.pi ** 2)
    w_fast = 1.0 - w.sum()
    tau = thick ** 2 / (k ** 2 * math.pi ** 2 * D)
    h = times[1] - times[0]
    e = np.exp(-h / tau)
    c = (1.0 - e) * tau / h  # the ramp's factor
    m = np.full(n_modes, rh[0])
    out = np.empty(len(rh))
    out[0] = rh[0]
    for i in range(1, len(rh)):
        slope = rh[i] - rh[i - 1]
        m = rh[i] + (m - rh[i - 1]) * e - slope * c
        out[i] = w @ m + w_fast * rh[i]
    return out


# ---- asymmetry: a tilted crank read by its angle ----
#
# The asymmetry record's strip turns a small mirror's hinge through a pin on a crank of radius r (3.3 ... 4 times the
# stroke's larger side), the link long enough that the pin's horizontal position follows the strip: r sin theta = r sin
# theta_0 + x; the crank stands at theta_0 (38 ... 42 deg) at rest (the mount's wedge), and the hinge's angle is read by
# a capacitive angle sensor, scaled to the pin's arc: y = r (theta - theta_0) = r (arcsin(sin theta_0 + x / r) -
# theta_0). The arcsine's slope grows toward the top dead centre: the strip's lengthening reads larger than its
# shortening (labelled "asymmetry").

def crank_reading(x, r, theta0):
    """r (arcsin(sin theta_0 + x / r) - theta_0) (um) for the pin's travel x (um)."""
    return r * (np.arcsin(math.sin(theta0) + np.asarray(x, float) / r) - theta0)


# ---- saturation: the carriage on its travel stop, the strip going slack ----
#
# The saturation record's carriage rests on its travel-limit screw once the strip has lengthened by g (0.55 ... 0.7 of
# its upward swing: the screw set too close after a service); beyond it the return spring's pull is taken by the screw,
# the strip's tension falls and it goes slack: the carriage (and the LVDT's core on it) stays on the stop, y = min(x,
# g) (the screw's steel stiff against the return spring: its give left out; labelled "saturation").

def stop_reading(x, g):
    """min(x, g): the carriage on its stop beyond g."""
    return np.minimum(np.asarray(x, float), g)


# ---- delay: the set point digitised by a sigma-delta converter ----
#
# The delay record's controller was replaced by a data-logger's: the drive is read by a sigma-delta converter whose
# decimation filter is a sinc^3 (three cascaded averages over the conversion period T_c = 1 / f_d, f_d 20 ... 30 Hz: the
# converter's 50/60 Hz rejection), and each conversion, ready at the end of its window, is applied as the loop's set
# point and held until the next (the loop itself quick: left out). The sinc^3's impulse response is the quadratic
# B-spline on [0, 3 T_c] (three boxes convolved): the set point lags the drive by 1.5 T_c on average, plus the hold's
# half period (labelled "delay").

N_GL = 12


def bspline3(s, Tc):
    """The sinc^3 filter's weight at the lag s: the quadratic B-spline on [0, 3 Tc] (unit mass)."""
    u = np.asarray(s, float) / Tc
    out = np.where((u >= 0) & (u < 1), 0.5 * u * u, 0.0)
    out = np.where((u >= 1) & (u < 2), 0.5 * (-2.0 * u * u + 6.0 * u - 3.0), out)
    out = np.where((u >= 2) & (u < 3), 0.5 * (3.0 - u) ** 2, out)
    return out / Tc


def sigma_delta(t, Tc, phase, x_at):
    """The set point on the times t: the conversion k (its window ending at t_k = phase + k Tc) is int B(s) x(t_k - s)
    ds (Gauss-Legendre, N_GL points on each of the spline's three pieces and each a tenth of Tc: the drive's knots are
    further apart), applied from t_k until t_(k+1); x before the record its first value (0 before the first
    conversion's end)."""
    t = np.asarray(t, float)
    k_last = int(math.floor((t[-1] - phase) / Tc))
    tk = phase + np.arange(k_last + 1) * Tc
    g, wg = np.polynomial.legendre.leggauss(N_GL)
    nodes = (np.arange(30)[:, None] + 0.5 * (g[None, :] + 1.0)).ravel() * Tc / 10.0
    wts = np.tile(0.5 * wg, 30) * Tc / 10.0 * bspline3(nodes, Tc)
    vals = np.array([float(np.dot(wts, x_at(np.maximum(tt - nodes, 0.0)))) for tt in tk])
    idx = np.floor((t - phase) / Tc).astype(int)
    return np.where(idx >= 0, vals[np.clip(idx, 0, k_last)], 0.0), tk


# ---- initial state: the strip fresh from its post-bake ----
#
# The initial-state record's strip came straight from its post-bake (80 C overnight to drive the casting solvent out:
# every crystallite high spin, far above every upper spinodal) and was cooled straight to the bias without the
# conditioning: every crystallite whose lower spinodal lies below the bias stays high spin (the conditioning leaves
# those whose loop's middle lies above the bias low spin), until the drive first cools it past its lower spinodal; then
# it switches, once, and stays low spin about the bias: the strip (its LVDT zeroed at the start) answers the first cold
# excursions with a shortening the rest state's does not have, and sits shorter from then on.

def baked_state(core, T_bake=353.15, n=4000):
    """The crystallites' branches after the bake at T_bake and a straight cooling to the bias: every class high spin at
    T_bake (checked: every upper spinodal lies below it), run from T_bake down to T_b."""
    th, lev = crystallites(core)
    t_up, t_dn, xl, xh = tables(core["k50"])
    s = np.ones(len(th))
    _ensemble(np.linspace(T_bake, core["Tb"], n + 1), th, lev, t_up, t_dn, xl, xh, s)
    return s


# ---- two effects: a semiconductor gauge in a quarter bridge (asymmetry) warming up (drift) ----
#
# The pair's carriage is read by a silicon strain gauge on a flexure it bends (the LVDT away): the gauge's relative
# change r = x / x_r + delta(t) (x_r = 1 / (G c), G the gauge factor and c the flexure's strain per um: r 0.22 ... 0.28
# at the stroke's larger side, a p-type gauge of G 150 at up to 1900 microstrain), in a quarter Wheatstone
# bridge, V / V_s = r / (2 (2 + r)), scaled to um by its slope at rest: y = 2 r x_r / (2 + r) (the quarter bridge's own
# nonlinearity, exact: a lengthening reads smaller than a shortening; labelled "asymmetry"). The bridge was switched on
# as the record began: the gauge warms by its own dissipation V_s^2 / (4 R) through its backing (tau_1 3 ... 6 s) and
# the flexure (tau_2 60 ... 100 s), and its resistance's temperature coefficient (uncompensated against the flexure's
# expansion) adds delta(t) = delta_inf [1 - a exp(-t / tau_1) - (1 - a) exp(-t / tau_2)] (a 0.3 ... 0.5; delta_inf x_r
# 18 ... 24 um; labelled "drift").

def bridge_reading(r, x_r):
    """The quarter bridge's reading (um) for the gauge's relative change r: 2 r x_r / (2 + r)."""
    r = np.asarray(r, float)
    return 2.0 * r * x_r / (2.0 + r)


def warm_up(t, d_inf, a, tau1, tau2):
    """The gauge's warming's share of r: d_inf [1 - a exp(-t / tau1) - (1 - a) exp(-t / tau2)]."""
    t = np.asarray(t, float)
    return d_inf * (1.0 - a * np.exp(-t / tau1) - (1.0 - a) * np.exp(-t / tau2))


# ---- out of vocabulary: a magnetic scale read within one period ----
#
# The out-of-vocabulary record's LVDT was away for calibration; a magnetoresistive sensor over a magnetic scale stood
# in, read by the arctangent of its sine and cosine without a period counter (its interpolator only): the reading is
# the carriage's position modulo the signal's period P (400 um), its zero set where the carriage rests; the wrap lies
# inside the stroke, at x_w (0.3 ... 0.45 of the upward swing), and there the reading jumps back by a whole period as
# the strip lengthens past it: no map of the strip's stroke that the vocabulary's effects draw.

P_SCALE = 400.0


def scale_reading(x, x_w, P=P_SCALE):
    """The interpolator's reading (um): ((x + P - x_w) mod P) - (P - x_w): x below x_w, x - P above."""
    x = np.asarray(x, float)
    return np.mod(x + P - x_w, P) - (P - x_w)

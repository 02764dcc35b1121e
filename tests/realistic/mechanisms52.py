"""Mechanisms of the HOLDOUT52 set (``cases_holdout52.py``), each written from its law; the signals are in
:mod:`.signals52`.

Nothing here imports hystcomp (nor another set's mechanisms but the exact relaxation step ``relax`` of HOLDOUT50's and
the hereditary sum ``hereditary`` of HOLDOUT51's, imported). Every mechanism takes the film's temperature (set by the
drive), its pores' liquid fraction or its reading, and returns the response; all are causal.

Citations: every source below was written from memory in this session (none was re-read); volumes, pages and years may
be off, and so may the constants quoted (typical values as remembered, not a datasheet's). The laws do not rest on them:
each is checked in tests/test_realistic_holdout52.py against an independent solution (the pores' states by the last
threshold the temperature crossed, from the running extremes; the rest state by an explicit decaying thermal cycling;
the creep compliance's means by quad and the Volterra solution by its own equation summed directly; the grains' flow by
a finite-volume solution of the diffusion in a sphere and the kernel's means by quad; the water loop's steps written
out and its tank and the riser by solve_ivp; the voids' balance and the Peltier's balance by brentq; the water line's
residence times by scipy's inverse Gaussian and quad; the scan's hold written out; the fringe from its intensity law;
and finer grids).
"""

import math

import numpy as np
from numba import njit
from scipy.special import ndtri

from .mechanisms50 import relax  # y relaxing toward x with a time constant, exact per step
from .mechanisms51 import hereditary  # sum_j dx_j kernel_(i-j): a hereditary integral, x linear between samples

# ---- the rate-independent core: a phase-change film of paraffin confined in mesoporous silica ----
#
# The actuator is a thin-film phase-change actuator: a film 10 um thick of a composite cast on a silicon heater chip (a
# platinum thin-film heater and its RTD, on a Peltier module), its top read by a capacitive gauge (nm; zeroed at the
# start of every record). The composite is a silicone (PDMS) matrix, half its volume, holding mesoporous silica
# nanoparticles (radius 0.2 ... 0.3 um) whose pores are filled with a broad-cut technical paraffin (the pores' wax 0.3
# of the film's volume; a skin of the blend's high-melting fraction on every grain, 0.05, solid over the whole range;
# the silica 0.15). The chip's temperature loop sets the film's temperature T = T_b + g v (g = 0.12 K a volt of the
# drive, T_b the bias: the middle of the pores' loops) on the bipolar records, T = T_b + g (v - 47) on the unipolar ones
# (the drive's 0 V the cold end); the film's own thermal time (some 0.3 ms, its latent heat included about twice that)
# is left out: quasi-static (at the programmes' quickest moves, 0.2 s, its lag would be under a sigma).
#
# The pores (Gibbs-Thomson in a cylindrical pore, as thermoporometry reads it; Brun, Lallemand, Quinson & Eyraud,
# Thermochim. Acta 21 (1977) 59; Jackson & McKenna, J. Chem. Phys. 93 (1990) 9002, for organic liquids in porous
# glasses; Petrov & Furo, Phys. Rev. E 73 (2006) 011608, for the melting-freezing hysteresis; all as remembered):
#
# * A pore of radius r holds its wax behind a non-freezing layer of t = 0.5 nm on the silica. Its crystal melts when
#   the liquid sleeve along the wall can grow, at the cylindrical interface's curvature 1 / (r - t): at T_m = T_0 - K /
#   (r - t); the pore's liquid freezes when the crystal can enter it from its mouth through a hemispherical front, of
#   curvature 2 / (q r - t) (q the mouth's radius over the pore's: a neck, 0.75 ... 1): at T_f = T_0 - 2 K / (q r - t).
#   K = sigma_sl T_0 / (rho_s Delta h) = 0.012 J / m^2 x 301 K / (0.86e6 g / m^3 x 244 J / g) = 17 K nm (the
#   solid-liquid interfacial energy and the heat of fusion as remembered for n-octadecane). The front is seeded by the
#   grain's solid skin, so no nucleation is waited for. Between T_f and T_m the pore keeps its phase: a relay of the
#   temperature, up at T_m and down at T_f, each switching all of its pore (rate independent: the fronts cross a pore in
#   microseconds).
# * The blend fractionates between the pores as it first freezes (a choice): each pore's wax has its own bulk melting
#   point T_0, normal about the blend's mean (27.5 ... 28.5 C) with a spread s_c of 8.5 ... 9.5 K (a broad cut, C15 ...
#   C26, as remembered); the pore radii are log-normal in the pore volume (median 3.8 ... 4.2 nm, log spread 0.2: a
#   silica gel's as gas sorption reads it); the necks uniform in 0.75 ... 1. N_PORES classes of equal pore volume on a
#   three-dimensional Kronecker (R2) sequence over the three quantiles (Roberts 2018, the generalised golden ratio, as
#   remembered), shifted by the core's seed.
# * The film's thickness takes its volume change (bonded to the chip and read at its top, the film is laterally
#   constrained; PDMS being nearly incompressible, (1 + nu) / (1 - nu) times its free linear strain, 3 for nu = 0.5, is
#   its volumetric strain): e = phi_m beta_m (T - T_r) + phi_k beta_s (T - T_r) + phi_p [eps_m f + (beta_s (1 - f) +
#   beta_l f) (T - T_r)], f the liquid share of the pores' wax, phi_m = 0.5 (PDMS, beta_m = 9.3e-4 / K), phi_k = 0.05
#   (the skins), phi_p = 0.3 (the pores' wax: solid beta_s = 3.5e-4 / K, liquid beta_l = 9e-4 / K, the melt's volume
#   change eps_m = 0.1; as remembered for paraffins and PDMS), the silica's left out (1.5e-6 / K). The reading is 1e9 h
#   (e - e(start)) nm, h = 10 um.
#
# Rate independent (every pore's state changes only at its thresholds), with return-point memory (relays); close to a
# Prandtl-Ishlinskii model but not one (measured in the test and stated there): the pores' thresholds are not a product
# of a uniform density of centres and a density of widths (the centres are normal, and a pore's width and its centre
# move together with its radius), and the liquid's expansion multiplies the temperature by the liquid share.
#
# The rest state: before every record but the initial-state case's the controller's conditioning routine cycles the
# film about the drive's 0 V temperature with a slowly decaying amplitude; its limit leaves every pore molten whose
# loop's middle (T_m + T_f) / 2 lies below that temperature and frozen otherwise: the state is set so, not run (checked
# in the test against an explicit decaying cycling).

N_PORES = 6000
K_GT = 17.0
T_LAYER = 0.5
Q_LO = 0.75
R_SPREAD = 0.2
H_FILM = 10e-6
PHI_M, PHI_K, PHI_P = 0.5, 0.05, 0.3
BETA_M, BETA_S, BETA_L = 9.3e-4, 3.5e-4, 9e-4
EPS_M = 0.1
GAIN = 0.12
V_MID = 47.0
PHI3 = 1.2207440846057596  # the real root of x^4 = x + 1: the R2 sequence's generalised golden ratio (three dims)


def r2_points(n, shift):
    """n points of the three-dimensional R2 sequence: (shift + k (1 / phi, 1 / phi^2, 1 / phi^3)) mod 1, k = 1 ... n."""
    a = np.array([1.0 / PHI3, 1.0 / PHI3 ** 2, 1.0 / PHI3 ** 3])
    return (np.asarray(shift, float)[None, :] + np.arange(1, n + 1)[:, None] * a[None, :]) % 1.0


_PORES = {}


def pores(core):
    """The core's pore classes: (T_m, T_f) (C) of N_PORES classes of equal volume, from the core's seed."""
    key = (core["rseed"], core["T0"], core["sc"], core["r50"])
    if key not in _PORES:
        shift = np.random.default_rng(core["rseed"]).uniform(size=3)
        u = np.clip(r2_points(N_PORES, shift), 1e-12, 1.0 - 1e-12)
        t0 = core["T0"] + core["sc"] * ndtri(u[:, 0])
        r = core["r50"] * np.exp(R_SPREAD * ndtri(u[:, 1]))
        q = Q_LO + (1.0 - Q_LO) * u[:, 2]
        tm = t0 - K_GT / (r - T_LAYER)
        tf = t0 - 2.0 * K_GT / (q * r - T_LAYER)
        _PORES[key] = (tm, tf)
    return _PORES[key]


def bias(core):
    """The bias T_b (C): the median of the pores' loops' middles."""
    tm, tf = pores(core)
    return float(np.median(0.5 * (tm + tf)))


def temperature(core, v):
    """The film's temperature (C) for the drive v (V): T_b + g v, on the unipolar records T_b + g (v - 47)."""
    v = np.asarray(v, float)
    return core["Tb"] + GAIN * (v - V_MID if core["unipolar"] else v)


def rest_state(core, T):
    """The conditioning's limit at the temperature T: every pore molten (1) whose loop's middle lies below T."""
    tm, tf = pores(core)
    return (0.5 * (tm + tf) < T).astype(float)


@njit(cache=True)
def _relays(T, tm, tf, s):
    """The pores' liquid share along the temperatures T: each a relay up at tm, down at tf (s carried in and out)."""
    n = T.shape[0]
    m = tm.shape[0]
    out = np.empty(n)
    for i in range(n):
        Ti = T[i]
        tot = 0.0
        for k in range(m):
            if s[k] > 0.5:
                if Ti < tf[k]:
                    s[k] = 0.0
            elif Ti > tm[k]:
                s[k] = 1.0
            tot += s[k]
        out[i] = tot / m
    return out


def liquid_share(core, T, s=None):
    """The pores' liquid share f along the temperatures T, from the state s (default the rest state at T[0]); s is
    updated in place when given."""
    T = np.asarray(T, float)
    tm, tf = pores(core)
    s = rest_state(core, T[0]) if s is None else s
    return _relays(T, tm, tf, s)


def strains(T, f, T_r):
    """The film's volumetric strain (its thickness strain) in its two parts: (the matrix's and skins', the pores' wax's)
    at the temperatures T and the liquid shares f, about the reference T_r."""
    T = np.asarray(T, float)
    f = np.asarray(f, float)
    d = T - T_r
    e_fix = (PHI_M * BETA_M + PHI_K * BETA_S) * d
    e_pore = PHI_P * (EPS_M * f + (BETA_S * (1.0 - f) + BETA_L * f) * d)
    return e_fix, e_pore


def reading(T, f, e_pore=None, h=H_FILM):
    """The gauge's reading (nm, zeroed at the first sample) of a film h thick at the temperatures T with the liquid
    shares f; e_pore, if given, replaces the pores' wax's strain (a filtered one)."""
    e_fix, e_p = strains(T, f, T[0])
    e = e_fix + (e_p if e_pore is None else e_pore)
    x = 1e9 * h * e
    return x - x[0]


def core_reading(core, v, s=None):
    """The rate-independent film's reading (nm) for the drive v, from the state s (default the rest state)."""
    T = temperature(core, v)
    return reading(T, liquid_share(core, T, s))


# ---- creep: a silicone button under the load, with Findley's power-law creep ----
#
# The creep record's film lifts a valve's poppet: its top presses the poppet's return spring (k_L) through a silicone
# button (free to bulge: in uniaxial stress) whose creep compliance follows Findley's power law, J(t) = J_0 + J_1 (t / 1
# s)^n (Findley, Lai & Onaran, Creep and Relaxation of Nonlinear Viscoelastic Materials, 1976, as remembered; n 0.2 ...
# 0.3 for a lightly filled silicone: a choice), the gauge reading the poppet. The button's compression u = int J(t - s)
# dF(s), F = F_0 + k_L x the spring's force (its preload F_0 long applied: only its changes creep), and the poppet's
# travel x = d - u, d the film's: x + k_L int J(t - s) dx(s) = d, a Volterra equation of the second kind, solved step by
# step for x linear between samples (its kernel the compliance's means over the samples' intervals): after a rise the
# poppet sags back, after a fall it recovers (labelled "creep"). In the units used: k_L J_0 = c_0 (0.04 ... 0.07) and
# k_L J_1 = c_1 (0.05 ... 0.08).

def findley_kernel(n, dt, c0, c1, nexp):
    """k_m: c_0 + c_1 t^n's mean over [m dt, (m + 1) dt] (t in s), m = 0 ... n - 1 (its antiderivative c_0 t + c_1
    t^(n+1) / (n + 1))."""
    tt = np.arange(n + 1) * dt
    A = c0 * tt + c1 * tt ** (nexp + 1.0) / (nexp + 1.0)
    return np.diff(A) / dt


@njit(cache=True)
def volterra_creep(d, kern):
    """x with x_i + sum_(j <= i) (x_j - x_(j-1)) kern_(i-j) = d_i (x_(-1) = x_0: the record starts at rest), solved for
    x_i step by step."""
    n = d.shape[0]
    x = np.empty(n)
    x[0] = d[0]
    dx = np.zeros(n)
    for i in range(1, n):
        acc = 0.0
        for j in range(1, i):
            acc += dx[j] * kern[i - j]
        # x_i + (x_i - x_(i-1)) kern_0 + acc = d_i
        xi = (d[i] - acc + x[i - 1] * kern[0]) / (1.0 + kern[0])
        dx[i] = xi - x[i - 1]
        x[i] = xi
    return x


# ---- rate dependence: the melt's flow out of coarse grains ----
#
# The rate record's film was cast 25 um thick with coarse silica-gel grains (radius 5.6 ... 6.9 um) instead of the
# nanoparticles (the same pores). A pore's wax that melts or warms swells inside a rigid skeleton: its excess must flow
# out of the grain through the pores (Darcy's law) before the film takes it up, and what has not flowed out is held by
# the melt's and the confining matrix's compliance: the grain consolidates as diffusion out of a sphere (Terzaghi's
# consolidation in a sphere, the same law as Crank's desorption from a sphere; Crank, The Mathematics of Diffusion,
# 1975, sec. 6.3, as remembered), its coefficient c = k M / mu = C_FLOW = 2e-11 m^2 / s (the permeability k = phi r^2 /
# (8 tortuosity) = 2.4e-19 m^2 of 4 nm pores, tortuosity 5; the melt's viscosity mu 4 mPa s; the soft matrix's
# confinement of a grain, M = 4 G ~ 0.33 MPa: a choice in the range those give): a step of the pores' strain reaches the
# film as
#
#     F(t) = 1 - (6 / pi^2) sum_n exp(-n^2 t / tau) / n^2,   tau = a^2 / (pi^2 c)  (0.16 ... 0.24 s here),
#
# (at short times Crank's 6 sqrt(c t / (pi a^2)) - 3 c t / a^2), so the pores' wax's strain reaches the film through the
# hereditary integral of F (its means over the samples' intervals, from its antiderivative t - (6 tau / pi^2) sum_n (1 -
# exp(-n^2 t / tau)) / n^4), the matrix's at once. The
# nanoparticles' tau (radius 0.2 ... 0.3 um: under 0.5 ms) is left out of the other records, and so is this film's own
# thermal time (25 um: some 5 ms with its latent heat, a fortieth of the flow's). A lag of the loop's switching part
# that grows with the drive's speed, and a loop that widens with it (labelled "rate_dependence").

C_FLOW = 2e-11
H_COARSE = 25e-6
N_SERIES = 400
U_SHORT = 0.01


def sphere_step(t, tau):
    """F(t), u = c t / a^2 = t / (pi^2 tau): Crank's short-time form 6 sqrt(u / pi) - 3 u for u <= U_SHORT (its next
    terms, 12 sqrt(u) ierfc(1 / sqrt(u)), under 1e-45 there), else 1 - (6 / pi^2) sum_(n <= N_SERIES) exp(-n^2 t / tau)
    / n^2 (its tail under 1e-40 for u > U_SHORT); 0 at t <= 0."""
    t = np.atleast_1d(np.asarray(t, float))
    u = np.maximum(t, 0.0) / (math.pi ** 2 * tau)
    n2 = np.arange(1, N_SERIES + 1, dtype=float) ** 2
    long_ = u > U_SHORT
    out = 6.0 * np.sqrt(u / math.pi) - 3.0 * u
    if long_.any():
        out[long_] = 1.0 - 6.0 / math.pi ** 2 * (np.exp(-np.outer(t[long_], n2) / tau) / n2).sum(axis=1)
    return np.where(t > 0.0, out, 0.0)


def sphere_kernel(n, dt, tau):
    """k_m: F's mean over [m dt, (m + 1) dt], m = 0 ... n - 1, from its antiderivative G(t) = t - (6 tau / pi^2) sum_k
    (1 - exp(-k^2 t / tau)) / k^4 = t - pi^2 tau / 15 + (6 tau / pi^2) sum_k exp(-k^2 t / tau) / k^4 for t > 0, G(0) = 0
    (the sum to N_SERIES terms: the rest under exp(-N_SERIES^2 dt / tau) for t >= dt, which must be negligible:
    checked); beyond 40 tau F is 1 to 1e-17."""
    if N_SERIES ** 2 * dt / tau < 60.0:
        raise ValueError("the sphere's series is too short for this step")
    n4 = np.arange(1, N_SERIES + 1, dtype=float) ** 4
    n2 = np.sqrt(n4)
    m_live = min(n, int(math.ceil(40.0 * tau / dt)) + 1)
    tt = np.arange(1, m_live + 1) * dt
    G = np.r_[0.0, tt - math.pi ** 2 * tau / 15.0 + 6.0 * tau / math.pi ** 2 * (np.exp(-np.outer(tt, n2) / tau)
                                                                               / n4).sum(axis=1)]
    k = np.ones(n)
    k[:m_live] = np.diff(G) / dt
    return k


def grain_flow(e_pore, dt, tau):
    """The pores' wax's strain as the film takes it up: its hereditary integral with F (the strain linear between the
    samples, step dt)."""
    e_pore = np.asarray(e_pore, float)
    return hereditary(e_pore, sphere_kernel(len(e_pore), dt, tau))


# ---- drift: the stage's chilled-water valve hunting ----
#
# The drift record's Peltier stands on a water-cooled plate whose water comes from a small loop: a tank (tau_w 18 ... 24
# s) cooled through a valve, its temperature held at its set point by a digital PI controller (10 Hz; K_c 0.5 of the
# valve's travel per K, T_i 60 s) moving a pneumatic valve whose stem sticks (valve stiction: it stays put while the
# controller's command stays within d_s 0.035 ... 0.045 of its position, then slips to within d_k 0.008 ... 0.012 of the
# command, past where a smooth valve would stop; the two-parameter stick-slip model of the process-control literature,
# Choudhury, Thornhill & Shah, Control Eng. Pract. 13 (2005) 641, as remembered, in a simplified form: a choice). The
# tank follows the valve (the water's temperature tau_w T_w' = -G x - T_w about its set point, G 5 K of the valve's full
# travel; exact per controller step), and the loop hunts: the integral winds up while the stem sticks, the stem slips
# past, the water overshoots: a limit cycle of some 0.1 K and a minute, its shape a lopsided sawtooth, not a sine. The
# plate's aluminium riser under the chip (8 ... 11 mm, 23e-6 / K) follows the water with its time constant tau_b (6 ...
# 12 s; exact per step for the water linear between the steps) and lifts the film toward the gauge: the reading moves by
# alpha L (T_b - T_b(0)) (labelled "drift"). The loop ran 900 s before the record from a disturbance of 0.3 K: it is in
# its limit cycle.

H_LOOP = 0.1


def valve_hunting(t_end, lead, tau_w, d_s, d_k, G=5.0, Kc=0.5, Ti=60.0, dist=0.3, h=H_LOOP):
    """The water loop's temperature T_w (K about its set point) and the valve's position x on the controller's steps
    (step h, from -lead to beyond t_end): the command c = K_c (T_w + I), I += h T_w / T_i; the stem slips to c -+ d_k
    when |c - x| > d_s, else sticks; the tank exact per step toward -G x. Returns (times, T_w, x)."""
    n = int(round((t_end + lead) / h)) + 2
    Tw = np.empty(n)
    X = np.empty(n)
    T, I, x = dist, 0.0, 0.0
    e = math.exp(-h / tau_w)
    for k in range(n):
        Tw[k], X[k] = T, x
        c = Kc * (T + I)
        if abs(c - x) > d_s:
            x = c - math.copysign(d_k, c - x)
        I += h * T / Ti
        target = -G * x
        T = target + (T - target) * e
    return np.arange(n) * h - lead, Tw, X


def riser_drift(t, times, Tw, tau_b, L_mm, alpha=23e-6):
    """The reading's change (nm) from the riser's warming: alpha L (T_b - T_b(0)), tau_b T_b' = T_w - T_b (exact per
    step for T_w linear between the loop's steps, from T_b = T_w at the loop's start), read on the record's times t.
    Returns (reading change, T_b on t)."""
    Tb = np.interp(np.asarray(t, float), times, relax(times, Tw, tau_b, Tw[0]))
    return 1e9 * alpha * L_mm * 1e-3 * (Tb - Tb[0]), Tb


# ---- asymmetry: air voids in an undegassed matrix, a stiff seat touched from above ----
#
# The asymmetry record's film was cast from PDMS that was not degassed: air voids, phi_v 0.6 ... 1.0 % of the film, and
# the air dissolved in the matrix (Henry's law: an Ostwald coefficient L_O 0.10 ... 0.14 for air in PDMS, as
# remembered), which follows the voids' pressure (its diffusion time across the film, some 30 ms, left out). The film's
# cap was set just touching a valve seat's stiff flexure at rest (no preload): as the film rises it presses the flexure,
# the pressure in the film p = p0 (1 + c x) (p0 the atmosphere; c = k / (A p0), 0.8 ... 1.2 per um here: a flexure of
# some 10 N / um on the film's square centimetre); as it sinks the cap leaves the flexure and the film is at the
# atmosphere's pressure. The gas's amount is fixed, p (v + L_O V_m) = p0 V (T / T_ref) (Boyle and Charles; V = v_0 + L_O
# V_m, the voids' volume and the dissolved air's, per area of the film, at p0 and the reference temperature), so the
# voids' volume is v = V p0 theta / p - L_O V_m: the film's top moves by x = D + V (theta p0 / p - 1), D the void-free
# film's rise. Free (x < 0): x = D + V (theta - 1); pressed (x >= 0): a quadratic in x (its positive root). The voids
# give way under the flexure and not without it: the film rises less than it sinks (labelled "asymmetry").

def void_stroke(D, theta, V, c):
    """The pressed film's rise x (nm) for the void-free rise D (nm), theta = T / T_ref, the gas's volume per area V (nm)
    and c (1 / nm): the root of c x^2 + (1 - c S) x - (S + V theta) = 0, S = D - V, in the cancellation-free form 2 (S
    + V theta) / ((1 - c S) + sqrt((1 - c S)^2 + 4 c (S + V theta)))."""
    D = np.asarray(D, float)
    theta = np.asarray(theta, float)
    S = D - V
    b = 1.0 - c * S
    rhs = S + V * theta
    return 2.0 * rhs / (b + np.sqrt(b * b + 4.0 * c * rhs))


def void_contact(D, theta, V, c):
    """The film's rise x (nm): free below the seat (x = D + V (theta - 1) where that is negative), pressed above it
    (void_stroke); continuous at x = 0."""
    free = np.asarray(D, float) + V * (np.asarray(theta, float) - 1.0)
    return np.where(free < 0.0, free, void_stroke(D, theta, V, c))


# ---- saturation: the Peltier module's current limit ----
#
# The saturation record's controller had its Peltier driver's current limit turned down (for another, smaller chip): at
# the limit I the module's cooling, S I T_c - I^2 R / 2 - K (T_h - T_c) (Peltier, Joule and conduction; Ioffe,
# Semiconductor Thermoelements and Thermoelectric Cooling, 1957, as remembered), balances the heat leaking into the chip
# from the room, (T_a - T_c) / R_leak, at a temperature T_min below which the loop cannot cool it: the film follows its
# set point down to T_min and stays there while the set point is colder (the loop's integrator clamped: no wind-up).
# Heating is not limited (the Joule heat adds to the module's pumping). The module: S 0.05 V / K, R 2 Ohm, K 0.5 W / K,
# the heat sink on chilled water at T_h (1 ... 2 K below the bias), the room T_a 22 C, R_leak 20 K / W (a choice);
# T_min at 0.55 ... 0.7 of the cold swing, the limit I that gives it found from the balance (labelled "saturation").

PELTIER = dict(S=0.05, R=2.0, K=0.5, T_a=22.0, R_leak=20.0)


def peltier_current(T_c, T_h, S=0.05, R=2.0, K=0.5, T_a=22.0, R_leak=20.0):
    """The current (A) at which the module holds the chip at T_c (C) against the room's leak: the smaller root of
    R I^2 / 2 - S T_c I + K (T_h - T_c) + (T_a - T_c) / R_leak = 0 (T_c in K in the Peltier term)."""
    Tk = T_c + 273.15
    load = K * (T_h - T_c) + (T_a - T_c) / R_leak
    return (S * Tk - math.sqrt((S * Tk) ** 2 - 2.0 * R * load)) / R


# ---- delay: a water line from a mixing valve ----
#
# The delay record's chip sat on a water-jacketed stage instead of its Peltier (the controller away for repair): a
# mixing valve blends a hot and a cold line in the set point's proportion, and the water runs to the stage through
# L 0.8 ... 1.3 m of 8 mm tubing at 5 ... 6 m/s (turbulent, Re ~ 4e4). The stage follows the water at once (its time
# left out); the water carries the set point with a transport delay and a little axial dispersion: its residence times
# are inverse Gaussian (the first passage of a dispersed plug), mean tau_d = L / u and variance 2 tau_d^2 / Pe, Pe = L
# / (0.2 d) (turbulent dispersion D ~ 0.2 u d; Taylor 1954, Levenspiel's charts, as remembered): the film's temperature
# is the set point convolved with that density (on SUB_LINE sub-steps a sample; labelled "delay").

SUB_LINE = 8


def ig_density(s, mean, pe):
    """The inverse Gaussian density of the residence times s (s), mean `mean`, shape lambda = pe mean / 2 (variance 2
    mean^2 / pe)."""
    s = np.asarray(s, float)
    lam = pe * mean / 2.0
    with np.errstate(divide="ignore", invalid="ignore"):
        out = np.sqrt(lam / (2.0 * math.pi * s ** 3)) * np.exp(-lam * (s - mean) ** 2 / (2.0 * mean ** 2 * s))
    return np.where(s > 0.0, out, 0.0)


def line_weights(h, mean, pe, width=8.0):
    """The residence-time density's masses on the sub-steps' hats (step h): w_m = int ig(s) hat_(j0+m)(s) ds over s
    within mean +- width standard deviations, by Simpson's rule on 16 points a sub-step, normalised to 1. Returns (j0,
    w): the first hat's index and the weights."""
    sd = mean * math.sqrt(2.0 / pe)
    j0 = max(int(math.floor((mean - width * sd) / h)), 0)
    j1 = int(math.ceil((mean + width * sd) / h))
    w = np.zeros(j1 - j0 + 1)
    m = 16
    c = np.ones(m + 1)
    c[1:-1:2], c[2:-1:2] = 4.0, 2.0
    u = np.linspace(0.0, 1.0, m + 1)
    for j in range(j0, j1):
        f = ig_density(j * h + u * h, mean, pe)
        w[j - j0] += float(np.sum(c * f * (1.0 - u))) * h / (3.0 * m)
        w[j + 1 - j0] += float(np.sum(c * f * u)) * h / (3.0 * m)
    return j0, w / w.sum()


def water_line(x_fine, h, mean, pe):
    """The stage's set point carried through the line: sum_m w_m x(t - (j0 + m) h) on the sub-steps (exact for x linear
    between them; x before the record its first value)."""
    j0, w = line_weights(h, mean, pe)
    x_fine = np.asarray(x_fine, float)
    pad = np.r_[np.full(j0 + len(w), x_fine[0]), x_fine]
    # np.convolve(pad, w)[n] = sum_m w_m pad[n - m]; the sub-step i sits at pad[j0 + len(w) + i]
    return np.convolve(pad, w)[len(w) + np.arange(len(x_fine))]


# ---- initial state: a night in the freezer ----
#
# The initial-state record's chip was stored overnight in the lab's freezer (-20 C, with its samples) and started
# without its conditioning: the cold freezes every pore whose freezing point lies above -20 C (every pore that melts
# above the bias among them); then the loop warms the film straight to the bias, melting every pore whose melting point
# it passes. The pores whose loop's middle lies below the bias but whose melting point lies above it stay frozen (the
# conditioning leaves them molten) until the drive first rises past their melting points; then they melt, once, and stay
# molten about the bias: the film (its gauge zeroed at the start) answers the first excursions with a rise the rest
# state's does not have, and sits higher from then on.

def freezer_state(core, T_cold=-20.0, n=4000):
    """The pores' states after the night at T_cold and a straight warm-up to the bias: every pore frozen at the start
    (the state before the night does not matter where the pore freezes there or melts on the way up: checked), the
    film run from T_cold up to T_b."""
    tm, tf = pores(core)
    s = np.zeros(len(tm))
    _relays(np.linspace(T_cold, core["Tb"], n + 1), tm, tf, s)
    return s


# ---- two effects: the PLC's scan (delay) and the gap read by a capacitance-to-digital converter (asymmetry) ----
#
# The pair's set point reaches the chip's controller through a PLC (the lab's interlock rack): it reads the drive at its
# scan instants t_k = phase + k P (P 30 ... 45 ms) and writes it to the controller's set point one scan later, held
# until the next write (a sample and hold one scan late: the set point follows the drive by one to two scans; labelled
# "delay"). The film is read by the chip's own electrode, its gap g_0 (0.3 ... 0.4 um) to the film's cap read by a
# capacitance-to-digital converter: C = eps_0 A / (g_0 - x) plus a constant parasitic, scaled to nm by its slope at the
# rest point: y = g_0 x / (g_0 - x) (the gap's inverse; fringe fields left out): a rise reads larger than a fall
# (labelled "asymmetry").

def scan_hold(t, period, phase, x_at):
    """The set point on the times t: the drive x_at(t_k) read at the last scan t_k = phase + k period with t_k +
    period <= t (0 before the first write)."""
    t = np.asarray(t, float)
    k = np.floor((t - period - phase) / period)
    tk = phase + k * period
    return np.where(k >= 0, x_at(np.maximum(tk, 0.0)), 0.0), tk


def cdc_reading(x, g0):
    """The converter's reading (nm) of the film's rise x (nm) under an electrode g0 (nm) away: g0 x / (g0 - x)."""
    x = np.asarray(x, float)
    return g0 * x / (g0 - x)


# ---- out of vocabulary: a fibre Fabry-Perot read raw past its fringe's top ----
#
# The out-of-vocabulary record's capacitive gauge was away for calibration; a fibre-optic Fabry-Perot probe stood in (a
# cleaved fibre over the film's cap: a low-finesse cavity, two-beam interference, I = I_0 (1 + V cos phi), phi = phi_0 +
# 4 pi x / lambda, lambda 850 nm), read raw and scaled by its slope at quadrature: y = (lambda / 4 pi) (sin(phi_0 + 4 pi
# x / lambda) - sin phi_0). Its working point had drifted since it was set at quadrature: the fringe's top lies inside
# the stroke, at x_top (0.3 ... 0.45 of the upward swing), and beyond it the reading falls back as the film rises: no
# monotone map of the film's stroke, and no effect of the vocabulary, draws that fold.

LAMBDA_FP = 850.0


def fringe_reading(x, x_top, lam=LAMBDA_FP):
    """(lambda / 4 pi) (sin(phi_0 + 4 pi x / lambda) - sin phi_0), phi_0 = pi / 2 - 4 pi x_top / lambda (nm)."""
    k = 4.0 * math.pi / lam
    phi0 = 0.5 * math.pi - k * x_top
    x = np.asarray(x, float)
    return (np.sin(phi0 + k * x) - math.sin(phi0)) / k

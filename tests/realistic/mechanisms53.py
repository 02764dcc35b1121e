"""Mechanisms of the HOLDOUT53 set (``cases_holdout53.py``), each written from its law; the signals are in
:mod:`.signals53`.

Nothing here imports hystcomp, nor another set's mechanisms. Every mechanism takes the cell's hydrogen pressure (set
by the drive), its particles' state or the diaphragm's reading, and returns the response; all are causal.

Citations: every source below was written from memory in this session (none was re-read); volumes, pages and years may
be off, and so may the constants quoted (typical values as remembered, not a datasheet's). The laws do not rest on them:
each is checked in tests/test_realistic_holdout53.py against an independent solution (the particles' states by the last
threshold the pressure crossed, from the running extremes looking back; the particles' thresholds regenerated from the
stated laws; the rest state by an explicit decaying pressure cycling; the pad's and the transformation's relaxations by
solve_ivp; the bench's heating by the matrix exponential and solve_ivp; the diaphragm's and the stop's balances by
brentq; the sensor's exposure by quad on a finer grid; the bed's logarithmic creep kernel by quad and its sum written
out; the pump's lines by their spectrum).
"""

import math

import numpy as np
from numba import njit
from scipy.special import ndtri

# ---- the rate-independent core: a metal-hydride actuator, LaNi5 powder behind a steel diaphragm ----
#
# The actuator is a metal-hydride cell: 2 g of an activated AB5 hydride powder (a blend of LaNi(5-y)Al(y) powders, y
# spread over 0 ... 0.5, a few um particles after their first hydriding cycles) in a shallow cup closed by a
# stainless-steel diaphragm, its hydrogen pumped in and out through a proton-exchange membrane: an electrochemical
# hydrogen pump between the cup and a reservoir at p_b (the bias: the median of the particles' equilibrium pressures),
# its potentiostat setting the membrane's potential E = KAPPA v (KAPPA = 1e-4: a divider on the drive; on the unipolar
# records E = KAPPA (v - 47), the drive's 0 V the low end). At equilibrium the pump holds Nernst's pressure ratio, ln(p
# / p_b) = 2 F E / (R T) (the hydrogen electrode's 2 electrons a molecule): G = 2 F KAPPA / (R T) = 0.0078 a volt of
# the drive at 25 C. The cell is held at 25 C by its water jacket; the pump, the gas, the jacket and the reaction are
# taken quasi-static (the pump's current and the particles' transformation and its heat are fast against the
# programmes' moves in the thin, well-cooled layer: the rate-dependence case relaxes that). The diaphragm's centre is
# read by a capacitive gauge (um, zeroed at the start of every record).
#
# The particles (Everett's independent domains: Everett & Whitton, Trans. Faraday Soc. 48 (1952) 749, for sorption
# hysteresis; for hydrides, the plateau hysteresis of each particle set by the coherency and plastic work of
# accommodating the hydride's 24 % expansion: Flanagan & Clewley, J. Less-Common Met. 83 (1982) 127, and Flanagan &
# Oates' review, Annu. Rev. Mater. Sci. 21 (1991) 269; all as remembered):
#
# * Each particle i is a relay of the pressure: it turns to its hydride (beta) when the pressure rises past its
#   absorption plateau p_a,i and back to its solid solution (alpha) when it falls past its desorption plateau p_d,i,
#   ln p_a,i = ln p_e,i + w_i / 2, ln p_d,i = ln p_e,i - w_i / 2 (the whole particle at once: the hydride's front
#   crosses a few-um particle in well under a second); between them it keeps its phase.
# * The particles' equilibrium pressures p_e,i are log-normal about p_0 (1.7 ... 2.1 bar at 25 C; LaNi5's plateau near
#   2 bar as remembered, the blend's median), ln-spread s_e 0.5 ... 0.55 (the blend's aluminium, which lowers the
#   plateau, varies from particle to particle, and so do their strains: a steeply sloping plateau); their hysteresis
#   ln(p_a / p_d) = w_i log-normal about w_0 0.24 ... 0.30 with a ln-spread 0.3 (LaNi5's ln(p_a / p_d) of about 0.25
#   at room temperature, as remembered). N_PART classes of equal mass on a two-dimensional Kronecker (R2) sequence
#   over the two quantiles (Roberts 2018, the plastic number, as remembered), shifted by the core's seed.
# * Each particle's hydrogen content (H per LaNi5): in the alpha phase Sieverts' law, x = X_A sqrt(p / p_e,i) (X_A =
#   0.3, the alpha phase's limit at its plateau); in the beta phase the hydride's sloping branch, x = X_B + K_B ln(p /
#   p_e,i) (X_B = 5.6 at its plateau, K_B = 0.25 a unit of ln p; as remembered).
# * The lattice takes about 2.9 A^3 a hydrogen atom (the nearly constant volume of H in metals, as remembered): the
#   2 g (4.63 mmol of LaNi5) swell by 8.1 mm^3 a unit of x, of which ETA = 0.2 reaches the diaphragm (the rest fills the
#   bed's pores), over its effective area of 200 mm^2; the diaphragm (thick, linear here) also bows under the gas
#   pressure, C_P = 0.5 um a bar. The reading (um) = S_X (xbar - xbar(0)) + C_P (p - p(0)), S_X = 8.1 ETA / 200 mm =
#   8.1 um a unit of x, xbar the particles' mean content.
#
# Rate independent (the particles' phases change only at their thresholds), with return-point memory (relays); close to
# a Prandtl-Ishlinskii model but not one (measured in the test and stated there): the relays' thresholds are not a
# uniform density of centres times a density of widths (the centres normal in the drive), Sieverts' law bends the alpha
# phase's share, and the hydride's sloping branch multiplies the pressure's logarithm by the hydride's share.
#
# The rest state: before every record but the initial-state case's the controller's conditioning routine cycles the
# pressure about the drive's 0 V pressure with a slowly decaying amplitude; its limit leaves every particle hydrided
# whose loop's middle (ln p_e,i) lies below that pressure's logarithm and alpha otherwise: the state is set so, not run
# (checked in the test against an explicit decaying cycling).

N_PART = 6000
W_SPREAD = 0.3
X_A, X_B, K_B = 0.3, 5.6, 0.25
S_X = 8.1
C_P = 0.5
F_FARADAY, R_GAS, T_CELL = 96485.33212, 8.314462618, 298.15
KAPPA = 1e-4
GAIN = 2.0 * F_FARADAY * KAPPA / (R_GAS * T_CELL)
V_MID = 47.0

PHI2 = 1.324717957244746  # the plastic number, the real root of x^3 = x + 1: the R2 sequence's ratio in two dims


def r2_points(n, shift):
    """n points of the two-dimensional R2 sequence: (shift + k (1 / phi, 1 / phi^2)) mod 1, k = 1 ... n."""
    a = np.array([1.0 / PHI2, 1.0 / PHI2 ** 2])
    return (np.asarray(shift, float)[None, :] + np.arange(1, n + 1)[:, None] * a[None, :]) % 1.0


_PART = {}


def particles(core):
    """The core's particles: (ln p_a, ln p_d, ln p_e) (p in bar) of N_PART classes: ln p_e = ln p_0 + s_e z_1, w = w_0
    exp(W_SPREAD z_2), (z_1, z_2) the normal quantiles of the R2 sequence shifted by default_rng(rseed)'s two
    uniforms."""
    key = (core["rseed"], core["p0"], core["se"], core["w0"])
    if key not in _PART:
        shift = np.random.default_rng(core["rseed"]).uniform(size=2)
        u = np.clip(r2_points(N_PART, shift), 1e-12, 1.0 - 1e-12)
        z = ndtri(u).T
        lpe = math.log(core["p0"]) + core["se"] * z[0]
        w = core["w0"] * np.exp(W_SPREAD * z[1])
        _PART[key] = (lpe + 0.5 * w, lpe - 0.5 * w, lpe)
    return _PART[key]


def bias(core):
    """The bias p_b (bar): the median of the particles' equilibrium pressures."""
    return float(np.exp(np.median(particles(core)[2])))


def pressure(core, v):
    """The cell's pressure (bar) for the drive v (V): p_b exp(G v), on the unipolar records p_b exp(G (v - 47))."""
    v = np.asarray(v, float)
    return core["pb"] * np.exp(GAIN * (v - V_MID if core["unipolar"] else v))


def rest_state(core, p):
    """The conditioning's limit at the pressure p: every particle hydrided (1) whose ln p_e lies below ln p."""
    return (particles(core)[2] < math.log(p)).astype(float)


@njit(cache=True)
def _relays(lp, lpa, lpd, lpe, s):
    """Along the log-pressures lp: the hydride's share F, the mean of s ln p_e and the mean of (1 - s) exp(-ln p_e / 2)
    (s carried in and out: each particle a relay up at lpa, down at lpd)."""
    n = lp.shape[0]
    m = lpa.shape[0]
    F = np.empty(n)
    SL = np.empty(n)
    SQ = np.empty(n)
    for i in range(n):
        x = lp[i]
        a = 0.0
        b = 0.0
        c = 0.0
        for k in range(m):
            if s[k] > 0.5:
                if x < lpd[k]:
                    s[k] = 0.0
            elif x > lpa[k]:
                s[k] = 1.0
            if s[k] > 0.5:
                a += 1.0
                b += lpe[k]
            else:
                c += math.exp(-0.5 * lpe[k])
        F[i] = a / m
        SL[i] = b / m
        SQ[i] = c / m
    return F, SL, SQ


def phases(core, p, s=None):
    """(F, SL, SQ) along the pressures p (see _relays), from the state s (default the rest state at p[0]); s is updated
    in place when given."""
    p = np.asarray(p, float)
    lpa, lpd, lpe = particles(core)
    s = rest_state(core, p[0]) if s is None else s
    return _relays(np.log(p), lpa, lpd, lpe, s)


def content(p, F, SL, SQ):
    """The particles' mean hydrogen content xbar (H per LaNi5) at the pressures p: the alpha particles' Sieverts content
    X_A sqrt(p) SQ, the beta particles' X_B F + K_B (F ln p - SL)."""
    p = np.asarray(p, float)
    return X_A * np.sqrt(p) * SQ + X_B * F + K_B * (F * np.log(p) - SL)


def reading(p, xbar):
    """The gauge's reading (um, zeroed at the first sample): S_X (xbar - xbar(0)) + C_P (p - p(0))."""
    p = np.asarray(p, float)
    y = S_X * np.asarray(xbar, float) + C_P * p
    return y - y[0]


def core_reading(core, v, s=None):
    """The rate-independent cell's reading (um) for the drive v, from the state s (default the rest state)."""
    p = pressure(core, v)
    return reading(p, content(p, *phases(core, p, s)))


# ---- creep: the rod behind an elastomer pad (a generalised Maxwell solid in series with the return spring) ----
#
# The creep record's diaphragm drives the output rod through a fluoroelastomer pad (a compliant coupling that spares
# the diaphragm the rod's side loads), the rod held against it by its return spring (k_s, the unit here); the gauge
# reads the rod. The pad is a generalised Maxwell (Wiechert) solid: its force F = E_inf u + sum_k E_k (u - q_k), u its
# compression, q_k the k-th arm's dashpot travel, dq_k / dt = (u - q_k) / tau_k (two arms: tau_1 1.5 ... 3 s, tau_2 15
# ... 30 s; the relaxation spectrum of a filled elastomer cut to two terms: Ferry, Viscoelastic Properties of Polymers,
# 1980, as remembered). With the diaphragm's travel d imposed (the bed is stiff against the pad) the rod's x = d - u
# and k_s x = F: x = ((E_inf + sum E_k) d - sum E_k q_k) / (1 + E_inf + sum E_k). A linear system for q driven by d,
# stepped exactly for d linear between samples (the augmented matrix exponential); the pad long at rest before the
# record (q = u). After a rise the rod sags back as the pad creeps; after a fall it recovers (labelled "creep").

def _q_system(e_inf, arms):
    """dq/dt = M q + b d for the pad's dashpots (arms: [(E_k, tau_k), ...], k_s = 1)."""
    E = np.array([a[0] for a in arms], float)
    tau = np.array([a[1] for a in arms], float)
    den = 1.0 + e_inf + E.sum()
    # u = d - x = (d + sum E_k q_k) / den
    M = (E[None, :] / den - np.eye(len(E))) / tau[:, None]
    b = 1.0 / (den * tau)
    return M, b, E, den


def pad_rod(d, dt, e_inf, arms):
    """The rod's travel x for the diaphragm's travel d (samples dt apart, linear between them), the pad at rest at d[0]
    before (its dashpots relaxed: q = u = d[0] / (1 + E_inf))."""
    from scipy.linalg import expm
    d = np.asarray(d, float)
    M, b, E, den = _q_system(e_inf, arms)
    n = len(E)
    A = np.zeros((n + 2, n + 2))
    A[:n, :n] = M
    A[:n, n] = b
    A[n, n + 1] = 1.0
    Phi = expm(A * dt)
    P, G0, G1 = Phi[:n, :n], Phi[:n, n], Phi[:n, n + 1]
    q = np.full(n, d[0] / (1.0 + e_inf))
    Q = np.empty((len(d), n))
    Q[0] = q
    for i in range(1, len(d)):
        # over the step the input is d_(i-1) + (d_i - d_(i-1)) s / dt: the augmented state (q, d, slope)
        q = P @ q + G0 * d[i - 1] + G1 * (d[i] - d[i - 1]) / dt
        Q[i] = q
    return ((e_inf + E.sum()) * d - Q @ E) / den


# ---- rate dependence: a coarse powder's first-order transformation ----
#
# The rate record's cell is filled with a coarse, once-activated powder (particles 20 ... 40 um): a particle no longer
# turns at once but transforms at a finite rate, first order in what is left to transform toward the phase its relay
# calls for, d phi_i / dt = (s_i - phi_i) / tau (the Johnson-Mehl-Avrami law with exponent 1, a surface-controlled
# first-order rate: the form hydride kinetics are often fitted by; tau 50 ... 90 ms, a choice), s_i the relay's phase
# (switched at the sample where the pressure crosses its threshold) and phi_i its hydride share. The alpha solution and
# the hydride's sloping branch follow the pressure at once (the fast diffusion of H in the phases). The content is
# linear in every phi_i, so the ensemble's sums (F, SL, SQ) relax as the particles do: each stepped exactly for s held
# over a sample interval.

@njit(cache=True)
def relax_held(u, dt, tau):
    """y with dy/dt = (u - y) / tau, u held at u_i over (t_(i-1), t_i], y_0 = u_0: y_i = u_i + (y_(i-1) - u_i) exp(-dt /
    tau)."""
    a = math.exp(-dt / tau)
    y = np.empty(u.shape[0])
    y[0] = u[0]
    for i in range(1, u.shape[0]):
        y[i] = u[i] + (y[i - 1] - u[i]) * a
    return y


def transformed_reading(p, sums, dt, tau):
    """The reading (um) of a cell whose particles transform at the rate 1 / tau: the relays' sums (F, SL, SQ) relaxed,
    the contents at the pressures p."""
    F, SL, SQ = (relax_held(np.asarray(x, float), dt, tau) for x in sums)
    return reading(p, content(p, F, SL, SQ))


# ---- drift: an illuminator warming the bench and the gauge's bracket ----
#
# The drift record's bench has a microscope's halogen illuminator switched on t_on before the record: its heat warms
# the bench plate toward a rise dT_inf with the plate's time constant tau_p (dT_p / dt = (dT_inf - T_p) / tau_p), and
# the gauge's aluminium bracket follows the plate through its foot (dT_b / dt = (T_p - T_b) / tau_b): two first-order
# lags in cascade (a lumped two-node thermal network, Newton's cooling law; Incropera & DeWitt, as remembered), from 0
# at the lamp's switching on: T_b(s) = dT_inf (1 - (tau_p exp(-s / tau_p) - tau_b exp(-s / tau_b)) / (tau_p - tau_b)).
# The bracket's length L between the gauge and the cell's clamp grows by alpha L T_b (alpha 23e-6 / K): the gauge's
# head backs off the diaphragm and the reading falls by it (the reading zeroed at the record's start; labelled
# "drift").

ALPHA_AL = 23e-6
SUB_VIDEO = 4


def bracket_warming(s, dT_inf, tau_p, tau_b):
    """The bracket's rise (K) s seconds after the lamp's switching on (closed form of the two lags in cascade)."""
    s = np.asarray(s, float)
    return dT_inf * (1.0 - (tau_p * np.exp(-s / tau_p) - tau_b * np.exp(-s / tau_b)) / (tau_p - tau_b))


def bracket_drift(t, t_on, dT_inf, tau_p, tau_b, L_mm):
    """The reading's drift (um) on the record's times t: -alpha L (T_b(t + t_on) - T_b(t_on))."""
    Tb = bracket_warming(np.asarray(t, float) + t_on, dT_inf, tau_p, tau_b)
    return -ALPHA_AL * L_mm * 1e3 * (Tb - Tb[0])


# ---- asymmetry: a thin diaphragm's membrane stiffening ----
#
# The asymmetry record's cell is closed by a thin diaphragm (h 11 ... 14 um), pressed out by the bed to w_r (10 ... 13
# um) at rest: its centre deflects by a sizeable share of its thickness, and its mid-plane's stretching stiffens it.
# For a clamped circular plate Timoshenko's large-deflection law, p a^4 / (E h^4) = 5.33 / (1 - nu^2) (w / h) + 2.6 /
# (1 - nu^2) (w / h)^3 (Timoshenko & Woinowsky-Krieger, Theory of Plates and Shells, 1959, as remembered): the cubic's
# share 2.6 / 5.33 = 0.488 of the linear stiffness k_d at w = h. The diaphragm is loaded by the bed (its stiffness k_b
# in series with the bed's free swelling) and by the gas: (k_b + k_d) w + 0.488 k_d w^3 / h^2 = (k_b + k_d) w_lin, w_lin
# the deflection a linear diaphragm would take (the core's: w_r at rest plus the core's reading), so w + beta w^3 / h^2
# = w_lin with beta = 0.488 k_d / (k_b + k_d) (k_d / (k_b + k_d) 0.5 ... 0.7). The root is unique (the left side
# rises); solved by Cardano's formula. The diaphragm gives less as it bows out and more as it comes back: a convex map
# (labelled "asymmetry").

def stiffened(w_lin, beta, h):
    """w with w + beta w^3 / h^2 = w_lin (Cardano: the depressed cubic's one real root)."""
    w_lin = np.asarray(w_lin, float)
    pc = h * h / beta
    qc = -w_lin * h * h / beta
    disc = np.sqrt(qc * qc / 4.0 + pc ** 3 / 27.0)
    return np.cbrt(-qc / 2.0 + disc) + np.cbrt(-qc / 2.0 - disc)


# ---- saturation: the diaphragm on its stop ----
#
# The saturation record's diaphragm meets a stop plate (a shim under the gauge's guard ring, set at frac 0.55 ... 0.7 of
# the way up the rise the record's drive gives): beyond it the stop's stiffness k_stop joins the diaphragm's and the
# bed's, (k_b + k_d) (w_lin - w) = k_stop (w - w_s) for w > w_s, so w = (w_lin + kappa w_s) / (1 + kappa), kappa =
# k_stop / (k_b + k_d) (25 ... 40: a steel shim in bending; labelled "saturation").

def on_stop(w_lin, w_s, kappa):
    """The diaphragm's deflection with a stop at w_s of relative stiffness kappa."""
    w_lin = np.asarray(w_lin, float)
    return np.where(w_lin > w_s, (w_lin + kappa * w_s) / (1.0 + kappa), w_lin)


# ---- delay: a video extensometer's exposure and latency ----
#
# The delay record's diaphragm is read by a video extensometer (a machine-vision camera triggered by the recorder's
# clock, a target on the rod): every sample is the image exposed over [t - L - E, t - L] (its exposure E, 2 ... 5 ms),
# L (50 ... 80 ms) the frame's transfer and the image processing, so the reading is the rod's mean over the exposure,
# L late (labelled "delay"); before the record the cell was at rest. The mean is taken on a finer grid (the reading's
# cumulative integral by the trapezoid rule, linear between the fine samples).

def exposure_late(tf, wf, t, L, E):
    """The mean of wf (on the fine times tf, from 0) over [t - L - E, t - L] at the times t (wf[0] before tf[0])."""
    cum = np.r_[0.0, np.cumsum(0.5 * (wf[1:] + wf[:-1]) * np.diff(tf))]

    def integral(x):
        x = np.asarray(x, float)
        inside = np.interp(np.clip(x, tf[0], tf[-1]), tf, cum)
        return inside + np.minimum(x - tf[0], 0.0) * wf[0]

    a, b = np.asarray(t) - L - E, np.asarray(t) - L
    return (integral(b) - integral(a)) / E


# ---- initial state: a weekend under the reservoir's full pressure ----
#
# The initial-state record's cell was left over the weekend open to a full hydrogen bottle (every particle hydrided)
# and was pumped straight down to the bias without the conditioning: the particles whose desorption plateau lies above
# the bias desorbed on the way down; the rest stay hydrided, among them those the conditioning leaves alpha (their
# loops' middles above the bias).

def weekend_state(core):
    """Every particle hydrided (1) whose desorption threshold lies below the bias."""
    return (particles(core)[1] < math.log(core["pb"])).astype(float)


# ---- the pair: the bed's logarithmic creep and the potentiostat's limit ----
#
# Creep: the pair's bed is a fresh, loosely packed powder whose grains creep at their contacts under the diaphragm's
# load, logarithmically in time (the contacts' slow yield: the log-time creep of granular packings and of friction
# contacts, Dieterich's ageing; as remembered): each change dw of the diaphragm's load settles the bed by c ln(1 + s /
# tau_c) dw after s seconds (c 0.04 ... 0.055, tau_c 20 ... 80 ms), which the diaphragm follows: y(t) = w(t) - int
# c ln(1 + (t - s) / tau_c) dw(s), w linear between samples (the kernel's means over the sample intervals).
# Saturation: the pump's potentiostat has its output limit set (a protective setting for the membrane) at E_max, frac
# 0.55 ... 0.7 of the drive's positive swing: the pressure cannot rise beyond p_b exp(2 F E_max / (R T)).

def log_kernel(n, dt, c, tau_c):
    """k_m: c ln(1 + s / tau_c)'s mean over [m dt, (m + 1) dt], m = 0 ... n - 1 (its antiderivative c ((tau_c + s) ln(1
    + s / tau_c) - s))."""
    s = np.arange(n + 1) * dt
    A = c * ((tau_c + s) * np.log1p(s / tau_c) - s)
    return np.diff(A) / dt


def hereditary(x, kern):
    """sum_(j <= i) (x_j - x_(j-1)) kern_(i-j) (x_(-1) = x_0), by FFT."""
    from scipy.signal import fftconvolve
    dx = np.diff(np.asarray(x, float), prepend=x[0])
    return fftconvolve(dx, kern)[:len(dx)]


# ---- out of vocabulary: a roughing pump's vibration ----
#
# The out-of-vocabulary record's bench carries the rotary-vane pump that evacuates the pump's anode line between runs,
# left running: its rotor's imbalance at the shaft's rate f (23.8 ... 24.6 Hz: a four-pole motor's 1440 ... 1475 rpm
# under load) and its vanes' passing at 2 f shake the gauge against the cell (the bench's response at those lines: a1,
# a2 um, phases drawn): y = w + a1 sin(2 pi f t + ph1) + a2 sin(4 pi f t + ph2). None of the labelled effects: the
# disturbance does not follow the drive.

def pump_vibration(t, f, a1, a2, ph1, ph2):
    """The gauge's vibration (um) on the times t."""
    t = np.asarray(t, float)
    return a1 * np.sin(2 * math.pi * f * t + ph1) + a2 * np.sin(4 * math.pi * f * t + ph2)

"""Mechanisms of the HOLDOUT59 set (``cases_holdout59.py``), each written from its law; the signals are in
:mod:`.signals59`.

Nothing here imports hystcomp (nor another set's mechanisms but the exact relaxation step ``relax`` of HOLDOUT50's and
the Volterra creep solver ``volterra_creep`` of HOLDOUT52's, imported). Every mechanism takes the film's temperature
(set by the drive), its microgels' states or its reading, and returns the response; all are causal.

Citations: every source below was written from memory in this session (none was re-read); volumes, pages and years may
be off, and so may the constants quoted (typical values as remembered, not a datasheet's). The laws do not rest on them:
each is checked in tests/test_realistic_holdout59.py against an independent solution (the microgels' states by the
last threshold the temperature crossed, from the running extremes; the rest state by an explicit decaying thermal
cycling; the film's swelling kinetics by a finite-volume solution of the diffusion through the film; the creep
compliances' means by quad and the Volterra solutions by their own equation summed directly; the ion exchange and the
room's pressure by solve_ivp, the gusts' sum written out; the thermistor's and the heater's laws by brentq; the DAC's
queue written out; the reflectance by a characteristic-matrix calculation; finer grids).
"""

import math

import numpy as np
from numba import njit
from scipy.special import gamma as _gamma, gammainc, ndtri

from .mechanisms50 import relax  # y relaxing toward x with a time constant, exact per step
from .mechanisms52 import volterra_creep  # x + sum_j dx_j kern_(i-j) = d, solved step by step

# ---- the core: a film of thermoresponsive microgels on a heater chip ----
#
# Every core is a hydrogel film actuator: a film 1 um thick (swollen, at the bias) of poly(N-isopropylacrylamide)
# (PNIPAM) microgels packed in a loose polyacrylamide matrix (the microgels 45 % of the film's volume, fully swollen),
# cast on a silicon chip with a platinum thin-film heater under a water bath, the chip's temperature loop setting the
# film's temperature from the drive (0.13 K a volt about the bias; on the unipolar records the drive's 0 V is 6 K below
# it), the film's top read by a heterodyne interferometer from a reference mirror above it, through the bath: the gap
# (nm, zeroed at the start of every record), which grows as the film thins.
#
# Each microgel collapses in a volume phase transition when heated past its transition temperature T_c and swells again
# when cooled; PNIPAM's collapsed globules hold intra- and inter-chain hydrogen bonds that the swollen chains do not, so
# a collapsed particle reswells only some degrees below T_c (the heating-cooling hysteresis of PNIPAM's coil-globule
# transition: Cheng, Shen & Wu, Macromolecules 39 (2006) 2325, as remembered): a relay that collapses at T_c and
# reswells at T_s = T_c - w. The film's microgels are a blend of copolymer batches (N-isopropylacrylamide with 0 ... 20
# % of a hydrophilic or a hydrophobic comonomer, which moves T_c up or down): their T_c normal about T_0 (32 ... 33 C)
# with a spread s_c (8.5 ... 9.5 K), and the hydrophobic ones (low T_c) bind a little tighter in the globule, so their
# loops are wider: w = w_0 exp(0.6 z_2 - 0.05 z_1), z_1 = (T_c - T_0) / s_c and z_2 an independent normal quantile, w_0
# 1.4 ... 1.8 K (a choice). A swollen microgel is not at its full swelling near its transition: the weakly first-order
# transition is preceded by a pre-transitional deswelling (Hirotsu, Hirokawa & Tanaka, J. Chem. Phys. 87 (1987) 1392, as
# remembered), written here as q_s = 1 - A exp(-(T_c - T) / Delta), A = 0.2, Delta = 1.2 K (a choice of form), and a
# collapsed one keeps q_c = 0.22 of its full volume (Pelton, Adv. Colloid Interface Sci. 85 (2000) 1: a PNIPAM
# microgel's diameter falls by half or more, as remembered). The film is clamped to the chip sideways, so its volume
# change is its thickness's; the matrix swells 4e-4 a kelvin (a choice: water's expansion). 8000 classes of microgels
# (stratified quantiles of T_c, the width's own quantiles shuffled by the core's seed). The film's water moves in and
# out through its 1 um within some 4 ms (Tanaka & Fillmore's collective diffusion, D = 1e-10 m^2/s between packed
# microgels, a choice), taken as at once: the core is rate independent, with return-point memory (relays); close to a
# Prandtl-Ishlinskii model but not one (the thresholds' density is not a product of a density of centres and a density
# of widths, and the swollen particles' deswelling multiplies the temperature into the state).

N_DOM = 8000
H_FILM = 1000.0
PHI_P = 0.45
Q_C = 0.22
A_PRE = 0.2
D_PRE = 1.2
E_MATRIX = 4e-4
W_SPREAD, W_TILT = 0.6, 0.05
GAIN = 0.13
V_MID = 46.0

_DOMAINS = {}


def domains(core):
    """The microgel classes' collapse and reswelling temperatures (T_c, T_s) for the core's T_0, s_c, w_0 and seed
    (cached)."""
    key = (core["dseed"], core["T0"], core["sc"], core["w0"])
    if key not in _DOMAINS:
        u1 = (np.arange(N_DOM) + 0.5) / N_DOM
        u2 = (np.random.default_rng(core["dseed"]).permutation(N_DOM) + 0.5) / N_DOM
        z1, z2 = ndtri(u1), ndtri(u2)
        tc = core["T0"] + core["sc"] * z1
        w = core["w0"] * np.exp(W_SPREAD * z2 - W_TILT * z1)
        _DOMAINS[key] = (tc, tc - w)
    return _DOMAINS[key]


def bias(core):
    """The bias temperature: the median of the microgels' loops' middles."""
    tc, ts = domains(core)
    return float(np.median(0.5 * (tc + ts)))


def temperature(core, v):
    """The film's temperature (C) for the drive v: the bias plus GAIN a volt (the unipolar drive about V_MID)."""
    v = np.asarray(v, float)
    return core["Tb"] + GAIN * (v - (V_MID if core.get("unipolar") else 0.0))


def rest_state(core, T):
    """The conditioning's limit at the temperature T: every microgel collapsed (1) whose loop's middle lies below T."""
    tc, ts = domains(core)
    return (0.5 * (tc + ts) < T).astype(float)


@njit(cache=True)
def _microgels(T, tc, ts, c, a, dl, qc):
    """The microgels' mean volume (of their full swelling) along T: each collapsing (c 1) above tc, reswelling (c 0)
    below ts (c carried in and out); a swollen one at 1 - a exp(-(tc - T) / dl), a collapsed one at qc."""
    n = T.shape[0]
    m = tc.shape[0]
    out = np.empty(n)
    for i in range(n):
        Ti = T[i]
        tot = 0.0
        for k in range(m):
            if c[k] > 0.5:
                if Ti < ts[k]:
                    c[k] = 0.0
            elif Ti > tc[k]:
                c[k] = 1.0
            if c[k] > 0.5:
                tot += qc
            else:
                tot += 1.0 - a * math.exp((Ti - tc[k]) / dl)
        out[i] = tot / m
    return out


def volume_share(core, T, c=None):
    """The microgels' mean volume q along the temperatures T, from the state c (default the rest state at T[0]); c is
    updated in place when given."""
    T = np.asarray(T, float)
    tc, ts = domains(core)
    c = rest_state(core, T[0]) if c is None else c
    return _microgels(T, tc, ts, c, A_PRE, D_PRE, Q_C)


def reading(T, q, h=H_FILM):
    """The gap's change (nm, zeroed at the first sample) over a film h thick at the temperatures T with the
    microgels' mean volume q: the film's thickness h (PHI_P q + E_MATRIX T) less its first value, its sign turned (the
    gap grows as the film thins)."""
    T = np.asarray(T, float)
    d = h * (PHI_P * np.asarray(q, float) + E_MATRIX * T)
    return d[0] - d


def core_reading(core, v, c=None):
    """The rate-independent film's reading (nm) for the drive v, from the state c (default the rest state)."""
    T = temperature(core, v)
    return reading(T, volume_share(core, T, c))


# ---- creep: an UHMW-PE foot under a spring, its compliance a stretched exponential ----
#
# The creep record's film lifts a light pushrod through a foot of ultra-high-molecular-weight polyethylene against the
# rod's return spring (k), the interferometer reading the rod's drop x (as it reads the gap). The foot's creep
# compliance is a stretched exponential (Kohlrausch-Williams-Watts), J(t) = J_0 + J_1 (1 - exp(-(t / tau)^b)) (Williams
# & Watts, Trans. Faraday Soc. 66 (1970) 80, as remembered; b 0.35 ... 0.5, tau 4 ... 10 s for UHMW-PE near room
# temperature: a choice). Its compression u = int J(t - s) dF(s), F = F_0 - k x (the preload long applied), x = d + u, d
# the film's thinning: x + k int J(t - s) dx(s) = d, the Volterra equation of HOLDOUT52's button, solved by its solver
# with this kernel's means over the samples' intervals (exact, through the incomplete gamma function). In the units
# used: k J_0 = c_0, k J_1 = c_1.

def creep_reading(d, kern):
    """The rod's drop x for the film's thinning d through a pad whose compliance's means over the samples' intervals
    are kern: x + sum_j (x_j - x_(j-1)) kern_(i-j) = d_i (HOLDOUT52's solver)."""
    return volterra_creep(np.asarray(d, float), np.asarray(kern, float))


def kww_kernel(n, dt, c0, c1, tau, b):
    """c_0 + c_1 (1 - exp(-(t / tau)^b)) averaged over every sample interval [m dt, (m + 1) dt], m < n: the integral of
    exp(-(u / tau)^b) from 0 to s is tau / b Gamma(1 / b) P(1 / b, (s / tau)^b)."""
    s = np.arange(n + 1) * dt
    ie = tau / b * _gamma(1.0 / b) * gammainc(1.0 / b, (s / tau) ** b)
    return c0 + c1 * (1.0 - np.diff(ie) / dt)


# ---- rate dependence: Tanaka and Fillmore's swelling kinetics of a thick film ----
#
# The rate record's film was cast 6 ... 8 um thick (the same microgels): the water the microgels take up or give off
# must flow through the film to its free face at the bath (the chip's face is impermeable), and the film's thickness
# follows its equilibrium (the core's) as the network's collective diffusion in a slab (Tanaka & Fillmore, J. Chem.
# Phys. 70 (1979) 1214, as remembered; Crank, The Mathematics of Diffusion, 1975, ch. 4 for the slab's series): for a
# step of the equilibrium the thickness approaches it as 1 - sum_n 8 / ((2n + 1)^2 pi^2) exp(-(2n + 1)^2 t / tau_1),
# tau_1 = 4 L^2 / (pi^2 D), D = D_COOP. The modes are stepped exactly for the equilibrium linear between samples
# (relax); the first N_MODES kept, the rest (weight under 3e-4, faster than 0.1 us) taken as at once.

D_COOP = 1e-10
N_MODES = 1000


def slab_weights():
    """The slab's modes' weights 8 / ((2n + 1)^2 pi^2), n < N_MODES, and the rest's (1 less their sum)."""
    k = 2 * np.arange(N_MODES) + 1.0
    w = 8.0 / (k * k * math.pi ** 2)
    return w, 1.0 - w.sum()


def slab_kinetics(t, x, tau1):
    """The film's thickness following its equilibrium x (linear between the times t) through the slab's modes, from
    rest at x[0]."""
    w, rest = slab_weights()
    x = np.asarray(x, float)
    out = rest * x
    for n in range(N_MODES):
        out = out + w[n] * relax(t, x, tau1 / (2 * n + 1) ** 2, x[0])
    return out


# ---- drift: the matrix exchanging its sodium for the bath's calcium ----
#
# The drift record's bath was topped up with tap water t_0 (20 ... 60 s) before the record: the matrix's acrylate
# groups (a lightly charged polyacrylamide) exchange their sodium for the water's calcium, which bridges them, and the
# matrix deswells (its Donnan pressure falls). The exchange is controlled by diffusion through the liquid film about the
# gel (Helfferich, Ion Exchange, 1962, as remembered): first order, dX / dt = (1 - X) / tau_x, tau_x 60 ... 120 s; the
# film's thickness falls by e_x (0.04 ... 0.06 of the 1 um: a choice) on full exchange. The drift (the gap growing) is
# H e_x (X(t) - X(0)), X = 1 - exp(-(t + t_0) / tau_x).

def ion_exchange(t, t0, tau_x):
    """The exchanged share X at the record's times t, the exchange begun t0 before the record."""
    return 1.0 - np.exp(-(np.asarray(t, float) + t0) / tau_x)


def exchange_drift(t, t0, tau_x, e_x, h=H_FILM):
    """The matrix's deswelling (nm of the gap) over the record, zeroed at its start."""
    X = ion_exchange(t, t0, tau_x)
    return h * e_x * (X - X[0])


# ---- asymmetry: the loop's thermistor linearised about the bias ----
#
# The asymmetry record's temperature loop reads an NTC thermistor on the chip but converts its set point to a
# resistance by a straight line through the bias, R_set = R_b (1 - B (T_set - T_b) / T_b^2) (the slope of the beta
# law at the bias; kelvin), the loop then holding the thermistor at R_set. The thermistor follows the beta law R = R_b
# exp(B (1 / T - 1 / T_b)) (Steinhart & Hart's simplest form, Deep-Sea Res. 15 (1968) 497, as remembered; B 4000 ...
# 4700 K), so the film's temperature is 1 / T = 1 / T_b + ln(R_set / R_b) / B: hotter than asked above the bias and
# less cold than asked below it.

def thermistor_temperature(T_set, Tb, B):
    """The film's temperature (C) when the loop holds the thermistor at the straight line's resistance for T_set."""
    Tk = Tb + 273.15
    x = 1.0 - B * (np.asarray(T_set, float) - Tb) / Tk ** 2
    return 1.0 / (1.0 / Tk + np.log(x) / B) - 273.15


# ---- saturation: the heater's supply at its compliance voltage ----
#
# The saturation record's heater supply was set to a low compliance voltage V_s: the platinum heater (R_H0 = 50 Ohm at
# 20 C, its coefficient 3.85e-3 / K: platinum's) under the full voltage dissipates V_s^2 / R_H(T), and the chip, R_TH =
# 20 K / W above the bath's cooling water (T_w = the bias less 8 K: a choice), reaches at most the T_max where T_max -
# T_w = R_TH V_s^2 / R_H(T_max): above it the film stays at T_max whatever the set point.

R_H0, ALPHA_PT, R_TH, T_W_BELOW = 50.0, 3.85e-3, 20.0, 8.0


def supply_voltage(T_max, T_w):
    """The compliance voltage that holds the chip at most at T_max over a bath at T_w."""
    return math.sqrt((T_max - T_w) * R_H0 * (1.0 + ALPHA_PT * (T_max - 20.0)) / R_TH)


# ---- delay: the DAC's output queue ----
#
# The delay record's set point was written by a USB data-acquisition box whose analogue output plays a queue: the
# programme's samples (at F_DAC = 1 kHz, held between) leave the queue n_b (120 ... 260) samples after they enter it, so
# the loop is set n_b / F_DAC late; the loop's own response is quick (taken as at once, the film's temperature the held
# set point's).

F_DAC = 1000.0


def dac_queue(t, n_b, x_at):
    """The set point at the times t: the programme x_at sampled at F_DAC and held, n_b samples late (0 before)."""
    k = np.floor(np.asarray(t, float) * F_DAC + 1e-9).astype(int) - n_b
    return np.where(k >= 0, x_at(np.maximum(k, 0) / F_DAC), 0.0)


# ---- initial state: a night at 45 C ----

def hot_state(core, T_hot=45.0):
    """The microgels' states after a night at T_hot (collapsed wherever T_c lies below it; the others swollen, as
    the rest state leaves them: their loops' middles lie far above the bias) and a straight cooling to the bias:
    reswollen where T_s lies above the bias, the others still collapsed."""
    tc, ts = domains(core)
    return ((tc < T_hot) & (ts <= core["Tb"])).astype(float)


# ---- the pair's creep: a nylon pad's logarithmic creep ----
#
# The pair's film lifts its pushrod through a nylon-6 pad (instead of the UHMW-PE foot) whose compliance creeps as the
# logarithm of time, J(t) = J_0 + J_1 ln(1 + t / tau_0) (the logarithmic creep of glassy and semicrystalline polymers
# under a small stress, Struik, Physical Aging in Amorphous Polymers, 1978, as remembered; tau_0 0.2 ... 0.5 s: a
# choice), solved as the creep record's.

def log_kernel(n, dt, c0, c1, tau0):
    """c_0 + c_1 ln(1 + t / tau_0) averaged over every sample interval: the integral of ln(1 + u / tau_0) from 0 to s
    is (tau_0 + s) ln(1 + s / tau_0) - s."""
    s = np.arange(n + 1) * dt
    ie = (tau0 + s) * np.log1p(s / tau0) - s
    return c0 + c1 * np.diff(ie) / dt


# ---- the pair's drift: wind on the building and the interferometer's air path ----
#
# The pair's interferometer has a dead path in air: its measuring beam runs l_d (100 ... 150 mm) further through the
# room's air than its reference beam, so the reading moves with the air's index, which follows its pressure (Edlen's
# equation: n - 1 = 2.7e-4 at 101.3 kPa and 20 C, proportional to the density; Edlen, Metrologia 2 (1966) 71, as
# remembered): by l_d (n - 1) (p - p(0)) / p_0 (the gap seems to grow as the pressure rises). A gale buffets the
# building: the wind U + u'(t), its gusts u' a Gaussian process of von Karman's spectrum, S(f) = 4 s_u^2 (L_u / U) /
# (1 + 70.8 (f L_u / U)^2)^(5/6) (L_u = 150 m, s_u = I U, I 0.15 ... 0.2, U 14 ... 18 m/s), drawn by the spectral
# representation (a sum of N_WAVES cosines at f_k = (k + 1/2) df, amplitudes sqrt(2 S(f_k) df), phases uniform from the
# gale's seed; Shinozuka & Deodatis, Appl. Mech. Rev. 44 (1991) 191, as remembered), df = 1 / (the record + LEAD). The
# room's pressure follows the windward wall's (C_p 1/2 rho (U + u')^2, C_p 0.7, rho 1.2 kg/m^3) through the building's
# leaks with a lag (tau_l 15 ... 30 s: a tight laboratory building, a choice), from LEAD s before the record.

N_WAVES, L_U, RHO_AIR, C_P, P_0, N_AIR, LEAD = 400, 150.0, 1.2, 0.7, 101325.0, 2.7e-4, 300.0


def gusts(t, U, I, seed, T_span):
    """The gusts u' (m/s) at the times t: the von Karman spectrum's spectral representation (N_WAVES cosines over the
    span T_span, phases from the seed)."""
    df = 1.0 / T_span
    f = (np.arange(N_WAVES) + 0.5) * df
    S = 4 * (I * U) ** 2 * (L_U / U) / (1 + 70.8 * (f * L_U / U) ** 2) ** (5 / 6)
    amp = np.sqrt(2 * S * df)
    ph = np.random.default_rng(seed).uniform(0.0, 2 * math.pi, N_WAVES)
    t = np.asarray(t, float)
    u = np.zeros_like(t)
    for k in range(N_WAVES):
        u += amp[k] * np.cos(2 * math.pi * f[k] * t + ph[k])
    return u


def gale_drift(t, U, I, seed, tau_l, l_mm):
    """The reading's drift (nm) on the record's times t (from 0) and the room's pressure (Pa above the calm's) there:
    the windward wall's pressure (linear between the record's steps, from -LEAD) through the leaks' lag."""
    dt = t[1] - t[0]
    n_lead = int(math.ceil(LEAD / dt))
    tt = np.r_[-np.arange(n_lead, 0, -1) * dt, t]
    q = C_P * 0.5 * RHO_AIR * (U + gusts(tt, U, I, seed, tt[-1] - tt[0])) ** 2
    p = relax(tt, q, tau_l, q[0])[n_lead:]
    return 1e9 * l_mm * 1e-3 * N_AIR * (p - p[0]) / P_0, p


# ---- out of vocabulary: the film's reflectance read raw ----
#
# The out-of-vocabulary record's film is read not by the interferometer but by a laser diode's reflectance off the film
# on its silicon chip under the bath (a single-wavelength reflectometer), its photodiode's signal taken raw as the
# film's thinning through its slope at the start. The film is a thin layer of index n_f = n_w + (n_p - n_w) h_dry / d
# between the water (n_w 1.333) and silicon (3.88, its absorption left out: a choice), d its thickness and h_dry = 0.12
# um its dry polymer (n_p 1.50): its optical thickness n_f d = n_w d + (n_p - n_w) h_dry. The reflectance of a layer
# (Airy's sum; Born & Wolf, Principles of Optics, sec. 1.6, as remembered), r = (r01 + r12 e^(2 i beta)) / (1 + r01 r12
# e^(2 i beta)), beta = 2 pi n_f d / lambda, r01 = (n_w - n_f) / (n_w + n_f), r12 = (n_f - n_si) / (n_f + n_si), R =
# |r|^2. The diode's wavelength (a choice among the bench's red diodes: it puts a fringe's extremum x_top up the stroke,
# the film x_top thinner than at the start) lambda = 4 OT(d_0 - x_top) / m, m the order that brings it nearest 650 nm:
# past x_top the reading folds back.

N_W, N_P, N_SI, H_DRY = 1.333, 1.50, 3.88, 120.0


def film_thickness0(q0, T0, h=H_FILM):
    """The film's thickness (nm) at the start: its microgels' and matrix's volume, h ((1 - PHI_P) + PHI_P q0 +
    E_MATRIX (T0 - 32))."""
    return h * ((1.0 - PHI_P) + PHI_P * q0 + E_MATRIX * (T0 - 32.0))


def reflectance(d, lam):
    """The layer's reflectance at the thicknesses d (nm) and the wavelength lam (nm), Airy's sum."""
    d = np.asarray(d, float)
    nf = N_W + (N_P - N_W) * H_DRY / d
    r01 = (N_W - nf) / (N_W + nf)
    r12 = (nf - N_SI) / (nf + N_SI)
    e = np.exp(2j * (2 * math.pi * nf * d / lam))
    return np.abs((r01 + r12 * e) / (1 + r01 * r12 * e)) ** 2


def diode_wavelength(d0, x_top):
    """The wavelength that puts a fringe's extremum (2 beta a multiple of pi) at d0 - x_top, its order the one that
    brings it nearest 650 nm."""
    ot = N_W * (d0 - x_top) + (N_P - N_W) * H_DRY
    m = max(1, round(4 * ot / 650.0))
    return 4 * ot / m, m


def reflectance_reading(g, d0, lam):
    """The raw reading (nm) for the film thinned by g from d0: (R(d0 - g) - R(d0)) over R's slope in the thinning at
    d0 (a central difference of 1e-3 nm)."""
    slope = (reflectance(d0 - 1e-3, lam) - reflectance(d0 + 1e-3, lam)) / 2e-3
    return (reflectance(d0 - np.asarray(g, float), lam) - reflectance(d0, lam)) / slope

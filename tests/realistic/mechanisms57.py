"""Mechanisms of the HOLDOUT57 set (``cases_holdout57.py``), each written from its law; the signals are in
:mod:`.signals57`.

Nothing here imports hystcomp (nor another set's mechanisms but HOLDOUT52's relay kernel ``_relays`` and Volterra solver
``volterra_creep``, HOLDOUT50's exact relaxation step ``relax``, HOLDOUT51's hereditary sum ``hereditary`` and
HOLDOUT56's camera frames ``camera_frames``, imported). Every mechanism takes the cell's humidity (set by the drive),
the cages' filled shares or the reading, and returns the response; all are causal.

Citations: every source below was written from memory in this session (none was re-read); volumes, pages and years may
be off, and so may the constants quoted (typical values as remembered, not a datasheet's). The laws do not rest on them:
each is checked in tests/test_realistic_holdout57.py against an independent solution (every cage's state by the last
threshold the humidity crossed, from the running extremes; the thresholds from the Kelvin and Raoult terms written out;
the index by the mixing rule solved for n; the rest state by an explicit decaying cycling; the walls' Abel equation by
its own sum, its closed-form step response and a finer grid; the cell's lag and the block's by solve_ivp; the
thermostat by its switching written out; the flank by its intensity law; the frames' means by quad; the slab's uptake
by quad of its series; finer grids).
"""

import math

import numpy as np
from scipy.special import ndtri

from .mechanisms50 import relax  # y relaxing toward x with a time constant, exact per step
from .mechanisms51 import hereditary  # sum_j dx_j kernel_(i-j): a hereditary integral, x linear between samples
from .mechanisms52 import _relays  # relays up at tu, down at td along T, their share (s carried in and out)
from .mechanisms52 import volterra_creep  # x + sum_j dx_j kern_(i-j) = d, solved step by step
from .mechanisms56 import camera_frames  # frames averaged over their exposure, delivered late and held

# ---- the rate-independent core: capillary condensation in the salted ink-bottle cages of a Bragg mirror ----
#
# The actuator is a humidity-tuned optical filter: a Bragg mirror on glass of six pairs of layers, a mesoporous silica
# layer (h_p 110 nm, porosity phi 0.55) and a dense titania one (h_t 60 nm, n_t 2.1), its reflection peak read by a
# spectrometer (nm; zeroed at the start of every record). The silica's pores are cages joined by narrower windows (a
# cage-like, FDU-12 / SBA-16 type film, templated by a block copolymer: ink-bottle pores), impregnated with lithium
# chloride (a salt-in-matrix sorbent, as Aristov's selective water sorbents are; the salt spread unevenly between the
# cages as the impregnating solution dried). The mirror sits in a microcell (a few microlitres, flushed at 2 l/min: its
# exchange time, some 0.2 ms, left out) at 25 C, fed by a dew-point generator whose saturator's dew point follows the
# drive: T_d = T_d0 + k_d v on the bipolar records (T_d0 the bias's dew point: the cages' loops' middle; k_d so that
# +-46 V spans ln x by +-0.2), T_d = T_d0 + k_d (v - 47) on the unipolar ones (the drive's 0 V the dry end); the cell's
# relative humidity x = p0(T_d) / p0(25 C), p0 by the Magnus formula 6.1094 exp(17.625 T / (T + 243.04)) hPa (Alduchov &
# Eskridge, J. Appl. Meteorol. 35 (1996) 601, as remembered).
#
# The cages (the Kelvin equation with Cohan's menisci and Raoult's law; Cohan, J. Am. Chem. Soc. 60 (1938) 433; the
# ink-bottle's pore blocking as in Everett's chapter in The Solid-Gas Interface, 1967, and Ravikovitch & Neimark,
# Langmuir 18 (2002) 9830, for cage-like silicas; all as remembered):
#
# * A cage of radius R, its walls covered by an adsorbed film of t = 0.5 nm (taken fixed at the thresholds: a choice),
#   fills with capillary solution when the film's spherical meniscus inside it becomes unstable, at ln x_c = ln a_w -
#   2 K / (R - t), a_w the water activity of its salt's solution (Raoult's law with the Kelvin term: the vapour over a
#   curved solution); it empties only when the meniscus in its window (radius q R, q 0.55 ... 0.8) can recede, at ln x_e
#   = ln a_w - 2 K / (q R - t) < ln x_c (pore blocking: the window holds the cage's water). K = gamma V_m / (R_g T) =
#   0.0720 J / m^2 x 18.07 cm^3 / mol / (8.314 x 298.15 J / mol) = 0.525 nm (the solution's surface tension taken as
#   water's). Between x_e and x_c the cage keeps its state: a relay of the humidity, up at x_c and down at x_e (rate
#   independent: a cage of 10 nm fills in microseconds at the cell's vapour supply).
# * N_BINS x N_PER = 6000 cage classes of equal volume: the radii log-normal (median 4.0 ... 4.6 nm, log spread 0.1),
#   each bin a 1 / N_BINS quantile slice of them, its N_PER cages spread evenly through the slice (a shifted lattice);
#   the windows uniform in q (a Kronecker sequence of the golden ratio in each bin); the salt's ln a_w normal (mean
#   -0.75, spread s_a 0.25 ... 0.3, at most -0.02: a cage's salt is a few mol / kg of its water, up to LiCl's
#   saturation), drawn for every cage apart from its size (the cages' ln a_w a shuffled lattice of the normal's
#   quantiles). The bins serve only the adsorbed film's share of an empty cage (by the bin's mean radius: within 2 % of
#   each cage's own, 16 % in the two outermost bins, the tails; a choice); every cage keeps its own thresholds. Each
#   core's seed draws the shifts and the shuffle.
# * The water in the porous layer: a filled cage is full; an empty one holds the adsorbed film, t_m c x / ((1 - x) (1 -
#   x + c x)) thick by the BET isotherm (t_m 0.28 nm a layer, c 8 ... 14: water on silica; Brunauer, Emmett & Teller, J.
#   Am. Chem. Soc. 60 (1938) 309, as remembered), its share of a sphere of radius R 1 - (1 - t / R)^3. The layer's index
#   by the Lorentz-Lorenz mixing rule, (n^2 - 1) / (n^2 + 2) = (1 - phi) L_s + phi W L_w (L = (n^2 - 1) / (n^2 + 2) of
#   silica, n 1.45, and water, n 1.333; W the pores' water share; the salt's own share of the index left out), and the
#   mirror's first-order peak at lambda = 2 (n_p h_p + n_t h_t) (the quarter-wave stack's centre). The porous layers'
#   own capillary strain (some 1e-3, out of plane: some 0.3 nm of the peak) is left out: a choice.
#
# Rate independent, with return-point memory (relays); close to a Prandtl-Ishlinskii model but not one (measured in the
# test and stated there): a cage's two thresholds are tied together through its radius, the adsorbed film multiplies a
# function of the humidity by the empty cages' share, and the index is a nonlinear mixing rule.
#
# The rest state: before every record but the initial-state case's the generator conditions the mirror with a slowly
# decaying cycling of the dew point about the drive's 0 V one; its limit leaves every cage filled whose loop's middle
# sqrt(x_c x_e) (the middle in ln x, where the cycling is symmetric) lies below the humidity at 0 V and empty otherwise
# (set so, not run: checked in the test against an explicit decaying cycling).

N_BINS, N_PER = 40, 150
N_CAGES = N_BINS * N_PER
K_KELVIN = 0.0720 * 18.07e-6 / (8.314462618 * 298.15) * 1e9  # gamma V_m / (R_g T) in nm
T_FILM = 0.5
Q_LO, Q_HI = 0.55, 0.8
LNAW_MEAN, LNAW_MAX = -0.75, -0.02
R_SPREAD = 0.1
T_MONO = 0.28
PHI = 0.55
N_SILICA, N_WATER = 1.45, 1.333
H_P, H_T, N_T = 110.0, 60.0, 2.1
T_CELL = 25.0
SPAN_LN = 0.2
V_MID = 47.0
ALPHA_K = 0.6180339887498949  # the golden ratio's fraction: the windows' Kronecker sequence in a bin


def _lorentz(n):
    return (n * n - 1.0) / (n * n + 2.0)


def cages(core):
    """The core's cage classes: (x_c, x_e, each bin's mean radius in nm), the thresholds of shape (N_BINS, N_PER)."""
    key = (core["rseed"], core["R50"], core["sa"])
    if key not in _CACHE:
        rg = np.random.default_rng(core["rseed"])
        u_r, u_q = rg.uniform(size=N_BINS), rg.uniform(size=N_BINS)
        perm = rg.permutation(N_CAGES).reshape(N_BINS, N_PER)
        j = np.arange(N_PER)
        pos = (np.arange(N_BINS)[:, None] + (j[None, :] + u_r[:, None]) / N_PER) / N_BINS
        R = core["R50"] * np.exp(R_SPREAD * ndtri(pos))
        q = Q_LO + (Q_HI - Q_LO) * ((u_q[:, None] + j[None, :] * ALPHA_K) % 1.0)
        ln_aw = np.minimum(LNAW_MEAN + core["sa"] * ndtri((perm + 0.5) / N_CAGES), LNAW_MAX)
        xc = np.exp(ln_aw - 2.0 * K_KELVIN / (R - T_FILM))
        xe = np.exp(ln_aw - 2.0 * K_KELVIN / (q * R - T_FILM))
        _CACHE[key] = (xc, xe, R.mean(axis=1))
    return _CACHE[key]


_CACHE = {}


def magnus(T):
    """The saturation vapour pressure of water (hPa) at T (C): 6.1094 exp(17.625 T / (T + 243.04))."""
    T = np.asarray(T, float)
    return 6.1094 * np.exp(17.625 * T / (T + 243.04))


def magnus_inverse(p):
    """The dew point (C) of the vapour pressure p (hPa): Magnus's formula inverted."""
    y = np.log(np.asarray(p, float) / 6.1094)
    return 243.04 * y / (17.625 - y)


def bias(core):
    """The bias (x_b, T_d0, k_d): x_b the median of the cages' loops' middles sqrt(x_c x_e), T_d0 its dew point in the
    cell and k_d (K / V) the dew point's slope that moves ln x by SPAN_LN over 46 V there."""
    xc, xe, _ = cages(core)
    xb = float(np.median(np.sqrt(xc * xe)))
    T_d0 = float(magnus_inverse(xb * float(magnus(T_CELL))))
    dlnp = 17.625 * 243.04 / (T_d0 + 243.04) ** 2
    return xb, T_d0, SPAN_LN / 46.0 / dlnp


def dew_point(core, v):
    """The saturator's dew point (C) for the drive v (V): T_d0 + k_d v, on the unipolar records T_d0 + k_d (v - 47)."""
    v = np.asarray(v, float)
    return core["Td0"] + core["kd"] * (v - V_MID if core["unipolar"] else v)


def humidity(core, v, T_c=T_CELL):
    """The cell's relative humidity for the drive v (V), the cell at T_c (C): p0(T_d) / p0(T_c)."""
    return magnus(dew_point(core, v)) / magnus(T_c)


def rest_state(core, x0):
    """The conditioning's limit at the humidity x0: every cage filled (1) whose loop's middle sqrt(x_c x_e) lies below
    x0 (N_BINS x N_PER)."""
    xc, xe, _ = cages(core)
    return (np.sqrt(xc * xe) < x0).astype(float)


def filled_shares(core, x, s=None):
    """Each bin's filled share along the humidities x (shape (len(x), N_BINS)), from the state s (N_BINS x N_PER;
    default the rest state at x[0]); s is updated in place when given."""
    x = np.asarray(x, float)
    xc, xe, _ = cages(core)
    s = rest_state(core, x[0]) if s is None else s
    return np.stack([_relays(x, xc[b], xe[b], s[b]) for b in range(N_BINS)], axis=1)


def bet_film(x, c):
    """The adsorbed film's thickness (nm) by the BET isotherm: t_m c x / ((1 - x) (1 - x + c x))."""
    x = np.asarray(x, float)
    return T_MONO * c * x / ((1.0 - x) * (1.0 - x + c * x))


def water_share(core, x, F):
    """The pores' water share W for the humidities x and the bins' filled shares F: the bins' mean of F + (1 - F) (1 -
    (1 - t / R_b)^3), t the BET film (at most R_b)."""
    _, _, Rb = cages(core)
    t = bet_film(x, core["c_bet"])
    shell = 1.0 - (1.0 - np.minimum(t[:, None] / Rb[None, :], 1.0)) ** 3
    return (F + (1.0 - F) * shell).mean(axis=1)


def peak(W):
    """The mirror's reflection peak (nm) for the pores' water share W: 2 (n_p h_p + n_t h_t), n_p by Lorentz-Lorenz."""
    L = (1.0 - PHI) * _lorentz(N_SILICA) + PHI * np.asarray(W, float) * _lorentz(N_WATER)
    return 2.0 * (np.sqrt((1.0 + 2.0 * L) / (1.0 - L)) * H_P + N_T * H_T)


def reading(core, x, F, extra_w=0.0):
    """The spectrometer's reading (nm, zeroed at the first sample) for the humidities x and the bins' filled shares F;
    extra_w (a share of the layer's volume, per sample) adds water held elsewhere in the layer."""
    lam = peak(water_share(core, x, F) + np.asarray(extra_w, float) / PHI)
    return lam - lam[0]


def core_at(core, x, s=None):
    """The rate-independent mirror's reading (nm) for the humidities x, from the state s (default the rest state)."""
    x = np.asarray(x, float)
    return reading(core, x, filled_shares(core, x, s))


def core_reading(core, v, s=None):
    """The rate-independent mirror's reading (nm) for the drive v, from the state s (default the rest state)."""
    return core_at(core, humidity(core, v), s)


# ---- creep: the cell's walls and lines buffering the water ----
#
# The creep record's cell was a larger one of PMMA on polyurethane lines (their wetted area A 15 ... 25 cm^2): the
# polymers take water into solution (Henry's law, a partition S of some 700 between the polymer and the vapour, as
# remembered for PMMA) and release it, diffusing in and out slowly (D some 1e-12 m^2 / s: semi-infinite walls over the
# record, their depth of diffusion microns against a millimetre). The cell's water balance at the flush's rate Q (1
# l/min; the flush's own time left out) is Q (x_in - x) = A S sqrt(D / pi) int x'(s) / sqrt(t - s) ds (the uptake rate
# of a semi-infinite wall whose surface follows x; Crank, The Mathematics of Diffusion, 1975, ch. 3, as remembered):
# x + beta int x'(s) (t - s)^(-1/2) ds = x_in, beta = A S sqrt(D / pi) / Q = 0.05 ... 0.08 s^(1/2), a Volterra equation
# of the second kind (Abel's kernel), solved step by step for x linear between samples by HOLDOUT52's solver (its
# kernel the means of beta t^(-1/2) over the samples' intervals). After every move the cell's humidity creeps the rest
# of the way, as t^(-1/2) (labelled "creep").

def abel_kernel(n, dt, beta):
    """k_m: beta t^(-1/2)'s mean over [m dt, (m + 1) dt], m = 0 ... n - 1: 2 beta (sqrt((m + 1) dt) - sqrt(m dt)) /
    dt."""
    tt = np.arange(n + 1) * dt
    return 2.0 * beta * np.diff(np.sqrt(tt)) / dt


def wall_buffer(x_in, dt, beta):
    """The cell's humidity with its walls buffering: x + sum_j (x_j - x_(j-1)) k_(i-j) = x_in (the walls long at the
    first sample's humidity)."""
    x_in = np.ascontiguousarray(x_in, dtype=float)
    return volterra_creep(x_in, abel_kernel(len(x_in), dt, beta))


# ---- rate dependence: the flow cell's mixing ----
#
# The rate record's mirror sat in a larger flow cell (2 ... 3.5 ml, for an immersion objective's window) on the
# generator's 1 l/min: the cell is well mixed (a stirred tank), its humidity x follows the generator's x_in by tau x' =
# x_in - x, tau = V / Q = 0.12 ... 0.21 s (exact per step for x_in linear between samples; the cell's walls glass). The
# cages follow the cell's humidity: a lag before the loop that grows with the drive's speed (labelled
# "rate_dependence").

def cell_mixing(t, x_in, tau):
    """The well-mixed cell's humidity on the times t, from x_in[0] (the cell long at the first set point)."""
    x_in = np.asarray(x_in, float)
    return relax(np.asarray(t, float), x_in, tau, float(x_in[0]))


# ---- drift: the lab's thermostat cycling the cell's temperature ----
#
# The drift record's cell stood in a room whose air conditioning runs on an on-off thermostat: the air warms toward
# T_set + 2 K while the cooling is off and cools toward T_set - 2 K while it is on (tau_r 80 ... 120 s), switching at
# T_set -+ db / 2 (the dead band db 1.0 ... 1.4 K: a crude one): a limit cycle, a rounded sawtooth of a few minutes. The
# cell's aluminium block follows the air with its time constant tau_b (10 ... 20 s; exact per step on a 0.05 s grid).
# The generator's saturator is thermostatted, so the vapour pressure it delivers holds, and the cell's humidity is x =
# p0(T_d) / p0(T_c) at the block's temperature T_c (labelled "drift"). The Kelvin term's own temperature (0.3 K in 298:
# 0.1 %) and the mirror's thermo-optic shift (some 5e-3 nm / K) are left out. The room's cycle ran from the thermostat's
# switch-on, 600 s before the record: it is in its limit cycle.

def thermostat_air(t_end, lead, T_set, db, tau_r, h=0.05, span=2.0):
    """The room air's temperature on the steps (step h, from -lead): on-off, the air relaxing toward T_set - span while
    the cooling is on and T_set + span while off (exact per step), the cooling switched on above T_set + db / 2 and off
    below T_set - db / 2 (checked at every step); starting at T_set with the cooling off. Returns (times, T_a)."""
    n = int(round((t_end + lead) / h)) + 2
    Ta = np.empty(n)
    T, on = T_set, False
    e = math.exp(-h / tau_r)
    for k in range(n):
        Ta[k] = T
        if on and T < T_set - db / 2:
            on = False
        elif not on and T > T_set + db / 2:
            on = True
        target = T_set - span if on else T_set + span
        T = target + (T - target) * e
    return np.arange(n) * h - lead, Ta


def cell_temperature(t, times, Ta, tau_b):
    """The cell block's temperature on the record's times t: tau_b T_c' = T_a - T_c (exact per step for T_a linear
    between the steps, from T_c = T_a at the start)."""
    return np.interp(np.asarray(t, float), times, relax(times, Ta, tau_b, Ta[0]))


# ---- asymmetry: the peak read on its flank ----
#
# The asymmetry record's spectrometer was away; the peak was read by edge interrogation: a diode laser at a fixed
# wavelength on the peak's long-wavelength flank, its reflected power on a photodiode, scaled to nm by the flank's slope
# at rest. The peak near the laser is taken as a Lorentzian of half-width w (12 ... 15 nm: the six pairs' broad stop
# band rounded by the layers' scatter; a choice), R = 1 / (1 + (Delta / w)^2), Delta = lambda_L - lambda_B, the laser
# set at Delta_0 = 1.1 ... 1.3 w at rest, beyond the flank's inflection (w / sqrt 3): over the stroke the reading stays
# on the flank (monotone) but is convex in the peak's shift, a rise reads larger than a fall (labelled "asymmetry").

def flank_reading(shift, w, delta0):
    """The edge reading (nm) of the peak's shift (nm): (R(delta0 - shift) - R(delta0)) / R'(delta0) with R'(delta0) the
    flank's slope against the shift, R(d) = 1 / (1 + (d / w)^2)."""
    shift = np.asarray(shift, float)

    def R(d):
        return 1.0 / (1.0 + (d / w) ** 2)
    slope = 2.0 * delta0 / w ** 2 / (1.0 + (delta0 / w) ** 2) ** 2
    return (R(delta0 - shift) - R(delta0)) / slope


# ---- saturation: a cold fitting on the line ----
#
# The saturation record's line from the generator to the cell ran past an uninsulated fitting under the room's supply
# air, colder than the generator's highest dew points: whenever the dew point exceeds the fitting's temperature T_cold
# (0.55 ... 0.7 of the upper swing of the dew point above the bias) the vapour condenses there and the gas leaves it
# saturated at T_cold (the condensate drains to a trap: a choice): the cell's dew point is min(T_d, T_cold), its
# humidity stops while the drive asks for more (labelled "saturation"). The drier end is not limited.

# ---- delay: the spectrometer's frames and its software's latency ----
#
# The delay record's spectrometer ran at f_c 25 ... 35 frames a second, each frame integrating the peak over the frame's
# whole period (back-to-back integration, ending at the frame's time t_k = phase + k / f_c), and its peak reaches the
# recorder n_lat 3 ... 5 frames later (the CCD's readout, the USB buffer and the peak fit's pipeline), held until the
# next one (labelled "delay": a latency of 0.1 ... 0.2 s and a hold). The spectrometer ran before the record: the frames
# before it show the peak at rest. The peak's mean over a frame stands in for the fit to the frame's mean spectrum (the
# peak's shift within a frame is a fraction of its width: a choice).

SUB_SPEC = 4


def spectrometer_frames(t, d_fine, h, fps, phase, n_lat):
    """The recorded reading on the times t: HOLDOUT56's camera frames (each frame's mean of d_fine, on the fine times of
    step h from 0 and linear between them, over its integration, delivered its latency later and held; before the first
    delivery d_fine[0]) with the integration the whole frame period 1 / fps and the latency n_lat / fps. Returns
    (reading, the frames' times t_k, their values)."""
    return camera_frames(t, d_fine, h, fps, 1.0 / fps, n_lat / fps, phase)


# ---- initial state: a night in a humid box ----
#
# The initial-state record's mirror was stored overnight in a humid box (x 0.9: every cage filled) and put into the cell
# at the drive's 0 V humidity without the conditioning: coming down from the box every cage whose window's x_e lies
# below that humidity stays filled (the conditioning leaves only those whose loop's middle lies below it filled). The
# cages between stay filled until the drive first takes the humidity below their windows' x_e; then they empty, once,
# and follow their loops from there: the peak (its reading zeroed at the start) sits higher at first.

def humid_box_state(core, x0):
    """The cages' states after the humid box (every cage filled) and the direct step down to x0: filled where x_e <
    x0."""
    _, xe, _ = cages(core)
    return (xe < x0).astype(float)


# ---- two effects: the walls' micropores (creep) and a two-stream generator (asymmetry) ----
#
# The pair's layer is a templated silica whose walls keep the template's micropores (as SBA-type walls do): they take
# water by micropore filling (Dubinin-Radushkevich: the walls' equilibrium uptake w_eq = w_max exp(-(ln(1 / x) /
# b_D)^2), w_max 0.14 ... 0.18 of the walls' volume, b_D = E / (R_g T) 0.9 ... 1.1; Dubinin 1960, as remembered) but
# slowly, the water diffusing into the walls: a slab's uptake, F(t) = 1 - (8 / pi^2) sum_(n odd) exp(-n^2 t / tau) /
# n^2, tau = 4 l^2 / (pi^2 D) 6 ... 12 s (Crank, The Mathematics of Diffusion, 1975, sec. 4.3, as remembered); the
# walls' water, (1 - phi) w, the hereditary integral of w_eq with F, adds to the layer's index (labelled "creep": the
# peak creeps on after every move). The humidity is set by a two-stream generator instead of the dew-point one: a wet
# and a dry stream mixed in the drive's proportion, x = x_b + g_x v (g_x the dew-point generator's slope at the bias):
# linear in the drive where the dew point's is exponential, so the humidity swings less above the bias and more below
# it than the core's, in the ratios that move the cages (labelled "asymmetry").

N_SLAB = 800


def slab_kernel(n, dt, tau):
    """k_m: F's mean over [m dt, (m + 1) dt], from its antiderivative G(t) = t - (8 tau / pi^2) (pi^4 / 96) + (8 tau /
    pi^2) sum_(n odd) exp(-n^2 t / tau) / n^4 (t > 0; G(0) = 0), the sum to N_SLAB odd terms (the rest under exp(-(2
    N_SLAB)^2 dt / tau) / (2 N_SLAB)^4 for t >= dt: checked to be negligible); beyond 40 tau F is 1 to 1e-17."""
    if (2 * N_SLAB) ** 2 * dt / tau < 60.0:
        raise ValueError("the slab's series is too short for this step")
    k_odd = 2.0 * np.arange(N_SLAB) + 1.0
    m_live = min(n, int(math.ceil(40.0 * tau / dt)) + 1)
    tt = np.arange(1, m_live + 1) * dt
    s = np.zeros(m_live)
    for kk in k_odd:
        s += np.exp(-kk * kk * tt / tau) / kk ** 4
    G = np.r_[0.0, tt - 8.0 * tau / math.pi ** 2 * (math.pi ** 4 / 96.0 - s)]
    out = np.ones(n)
    out[:m_live] = np.diff(G) / dt
    return out


def dr_uptake(x, w_max, b_d):
    """The walls' equilibrium water (a share of their volume): w_max exp(-(ln(1 / x) / b_D)^2)."""
    x = np.asarray(x, float)
    return w_max * np.exp(-(np.log(x) / b_d) ** 2)


def wall_water(x, dt, tau, w_max, b_d):
    """The walls' water (a share of the layer's volume, (1 - phi) w) on the samples: the hereditary integral of w_eq(x)
    with the slab's uptake F (the walls long at the first sample's equilibrium)."""
    return (1.0 - PHI) * hereditary(dr_uptake(x, w_max, b_d), slab_kernel(len(x), dt, tau))


def mixer_humidity(core, v):
    """The two-stream generator's humidity: x_b + g_x v, g_x = x_b k_d dln p0 / dT at T_d0 (the dew-point generator's
    slope at the bias)."""
    dlnp = 17.625 * 243.04 / (core["Td0"] + 243.04) ** 2
    return core["xb"] * (1.0 + core["kd"] * dlnp * np.asarray(v, float))


# ---- out of vocabulary: a diaphragm pump's pulsation ----
#
# The out-of-vocabulary record's carrier gas was pushed by a small diaphragm pump with no buffer volume, and the cell
# vents through a restriction: its pressure pulsates with the pump's strokes, and with it the water's partial pressure
# (its mole fraction fixed by the saturator), so the humidity ripples about the set point, x = x_set (1 + m sin(2 pi f_p
# t + phi)) (m 0.012 ... 0.018: 12 ... 18 mbar of the cell's pressure, its first harmonic only; the pump's stroke rate
# f_p 4.5 ... 6 Hz). The cages follow the ripple through their loops: minor loops traced at the pump's rate where the
# loop is steep, a ripple in the reading whose size follows the loop's local slope. The pump ran before the record. No
# effect of the vocabulary (a drift, a creep, a rate dependence, a delay, an asymmetry, a saturation, the initial state)
# draws a periodic ripple tied to an unrecorded disturbance.

def pump_ripple(t, x_set, m, f_p, phase):
    """The cell's humidity under the pump's pulsation: x_set (1 + m sin(2 pi f_p t + phase))."""
    return np.asarray(x_set, float) * (1.0 + m * np.sin(2.0 * math.pi * f_p * np.asarray(t, float) + phase))

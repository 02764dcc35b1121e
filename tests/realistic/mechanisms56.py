"""Mechanisms of the HOLDOUT56 set (``cases_holdout56.py``), each written from its law; the signals are in
:mod:`.signals56`.

Nothing here imports hystcomp (nor another set's mechanisms). Every mechanism takes the beam's temperature (set by the
drive), its grains' rutile share or its reading, and returns the response; all are causal.

Citations: every source below was written from memory in this session (none was re-read); volumes, pages and years may
be off, and so may the constants quoted (typical values as remembered, not a datasheet's). The laws do not rest on them:
each is checked in tests/test_realistic_holdout56.py against an independent solution (the grains' states by the last
threshold the temperature crossed, from the running extremes; the grains' thresholds from a Halton sequence written
out; the rest state by an explicit decaying thermal cycling; the membrane's relaxation by solve_ivp; the glass slide's
conduction by a finite-volume solution and its step response by its series; the laser's warm-up by solve_ivp; the
magnet's field by quad over its surface currents; the lid's contact by brentq; the camera's frames written out with
quad over the exposures; the water's uptake by a finite-volume solution; the wrap written out; finer grids).
"""

import math

import numpy as np
from scipy.special import ndtri

from .mechanisms52 import _relays  # relays up at tu, down at td along T, their share (s carried in and out)

# ---- the rate-independent core: a VO2 thin-film bimorph, its grains switching between M1 and rutile ----
#
# The actuator is a bimorph cantilever (L = 0.5 mm long) of a vanadium-dioxide film (t_f = 0.3 um, sputtered with
# tungsten from a second target so that its grains' transition temperatures spread) on a polyimide strip (t_s = 7.5 um),
# clamped to a heater chip on a Peltier module; the chip's temperature loop sets the beam's temperature T = T_b + g v
# (g = 0.16 K a volt of the drive, T_b the bias: the middle of the grains' loops) on the bipolar records, T = T_b + g (v
# - 47) on the unipolar ones (the drive's 0 V the cold end); the beam's own thermal time (a few ms) is left out. Its tip
# is read by a confocal chromatic point sensor (um, zeroed at the start of every record).
#
# The grains (the metal-insulator transition of VO2: monoclinic M1, insulating, below; rutile, metallic, above;
# Morin, Phys. Rev. Lett. 3 (1959) 34; its first-order, nucleation-limited switching in small grains: Lopez, Haynes,
# Boatner, Feldman & Haglund, Phys. Rev. B 65 (2002) 224113, the hysteresis widening as the grains shrink; all as
# remembered):
#
# * Each grain switches as a whole (a relay of the temperature): to rutile when it is heated past T_up, back to M1 when
#   it is cooled past T_down, T_up = T_c + 2 a w, T_down = T_c - 2 (1 - a) w: w the half width of its loop, a its share
#   above T_c (superheating is easier than supercooling in VO2: a in 0.3 ... 0.5, uniform, a choice). The half width
#   grows as the grain shrinks (fewer defects to nucleate on): w = W_INF + B_SIZE / d (W_INF = 0.5 K, B_SIZE = 100 K nm;
#   d the grain's diameter, log-normal, median 45 ... 55 nm, log spread 0.35, as AFM reads such films).
# * T_c spreads with the tungsten between the grains (about -20 K per at.% W, as remembered): normal about the film's
#   mean (66 ... 68 C) with a spread s_c of 8 ... 9 K (a graded co-sputtered film: a choice).
# * N_GRAINS classes of equal volume on the three-dimensional Halton sequence (bases 2, 3, 5) over the three quantiles,
#   shifted (mod 1) by a draw from the core's seed (a Cranley-Patterson rotation).
#
# The beam: the film's free in-plane strain against the strip's is Delta = eps_tr f + (alpha_s - alpha_f(f)) (T - T_r),
# f the rutile share (the grains' c_R axes shrink on the transition: eps_tr = 3e-3 in-plane for a fibre-textured film,
# as remembered), alpha_f(f) = alpha_M (1 - f) + alpha_R f (alpha_M = 8e-6 / K, alpha_R = 1.4e-5 / K for the film,
# alpha_s = 2e-5 / K for the polyimide; as remembered, may be off), T_r, f_r the record's first. The film being about as
# stiff a strip as the polyimide (E_f t_f ~ 40 kN / m against 19), Stoney's thin-film law will not do: Timoshenko's
# bimetal curvature (Timoshenko, J. Opt. Soc. Am. 11 (1925) 233, as remembered) kappa = 6 Delta (1 + m)^2 / (h (3 (1 +
# m)^2 + (1 + m n) (m^2 + 1 / (m n)))), m = t_f / t_s, n = E_f / E_s (E_f = 140 GPa, E_s = 2.5 GPa), h = t_f + t_s; the
# beam bends as an arc of that curvature from flat (at the record's start: its residual curl trimmed away there, a
# choice), its tip rising (1 - cos(kappa L)) / kappa (exact for an arc: not the small-angle kappa L^2 / 2).
#
# Rate independent (every grain's state changes only at its thresholds), with return-point memory (relays); close to a
# Prandtl-Ishlinskii model but not one (measured in the test and stated there): the grains' thresholds are not a uniform
# density of centres times a density of widths (the centres are normal, and a grain's loop shifts down as it widens),
# the film's expansion multiplies the temperature by the rutile share, and the arc bends the reading.
#
# The rest state: before every record but the initial-state case's the controller's conditioning routine cycles the beam
# about the drive's 0 V temperature with a slowly decaying amplitude; its limit leaves every grain rutile whose loop's
# middle (T_up + T_down) / 2 lies below that temperature and M1 otherwise: the state is set so, not run (checked in the
# test against an explicit decaying cycling).

N_GRAINS = 6000
W_INF, B_SIZE = 0.5, 100.0
D_SPREAD = 0.35
A_LO, A_HI = 0.3, 0.5
EPS_TR = 3e-3
ALPHA_M, ALPHA_R, ALPHA_S = 8e-6, 1.4e-5, 2e-5
T_F, T_S, E_F, E_S = 0.3e-6, 7.5e-6, 140e9, 2.5e9
L_BEAM = 0.5e-3
GAIN = 0.16
V_MID = 47.0
BASES = (2, 3, 5)


def radical_inverse(k, base):
    """The van der Corput radical inverse of the integers k in `base`: their digits mirrored about the point."""
    k = np.asarray(k, np.int64).copy()
    out = np.zeros(k.shape)
    f = 1.0 / base
    while np.any(k > 0):
        out += f * (k % base)
        k //= base
        f /= base
    return out


def halton_points(n, shift):
    """n points of the Halton sequence in bases 2, 3, 5 (k = 1 ... n), shifted by `shift` mod 1."""
    k = np.arange(1, n + 1)
    u = np.stack([radical_inverse(k, b) for b in BASES], axis=1)
    return (u + np.asarray(shift, float)[None, :]) % 1.0


def timoshenko_factor():
    """kappa / Delta (1 / m): Timoshenko's bimetal curvature per unit misfit strain for the film on the strip."""
    m, n = T_F / T_S, E_F / E_S
    h = T_F + T_S
    return 6.0 * (1 + m) ** 2 / (h * (3 * (1 + m) ** 2 + (1 + m * n) * (m * m + 1 / (m * n))))


_GRAINS = {}


def grains(core):
    """The core's grain classes: (T_up, T_down) (C) of N_GRAINS classes of equal volume, from the core's seed."""
    key = (core["gseed"], core["Tc"], core["sc"], core["d50"])
    if key not in _GRAINS:
        shift = np.random.default_rng(core["gseed"]).uniform(size=3)
        u = np.clip(halton_points(N_GRAINS, shift), 1e-12, 1.0 - 1e-12)
        tc = core["Tc"] + core["sc"] * ndtri(u[:, 0])
        d = core["d50"] * np.exp(D_SPREAD * ndtri(u[:, 1]))
        a = A_LO + (A_HI - A_LO) * u[:, 2]
        w = W_INF + B_SIZE / d
        _GRAINS[key] = (tc + 2.0 * a * w, tc - 2.0 * (1.0 - a) * w)
    return _GRAINS[key]


def bias(core):
    """The bias T_b (C): the median of the grains' loops' middles."""
    tu, td = grains(core)
    return float(np.median(0.5 * (tu + td)))


def temperature(core, v):
    """The beam's temperature (C) for the drive v (V): T_b + g v, on the unipolar records T_b + g (v - 47)."""
    v = np.asarray(v, float)
    return core["Tb"] + GAIN * (v - V_MID if core["unipolar"] else v)


def rest_state(core, T):
    """The conditioning's limit at the temperature T: every grain rutile (1) whose loop's middle lies below T."""
    tu, td = grains(core)
    return (0.5 * (tu + td) < T).astype(float)


def rutile_share(core, T, s=None):
    """The grains' rutile share f along the temperatures T, from the state s (default the rest state at T[0]); s is
    updated in place when given."""
    T = np.asarray(T, float)
    tu, td = grains(core)
    s = rest_state(core, T[0]) if s is None else s
    return _relays(T, tu, td, s)


def misfit(T, f):
    """The film's misfit strain against the strip, Delta = eps_tr f + (alpha_s - alpha_f(f)) (T - T_r), less its value
    at the first sample (T_r the first temperature)."""
    T = np.asarray(T, float)
    f = np.asarray(f, float)
    d = T - T[0]
    m = EPS_TR * f + (ALPHA_S - (ALPHA_M * (1.0 - f) + ALPHA_R * f)) * d
    return m - m[0]


def arc_rise(kappa, L=L_BEAM):
    """The tip's rise (um) of a beam L long bent to the curvature kappa (1 / m) from flat: (1 - cos(kappa L)) / kappa
    (in the cancellation-free form 2 sin^2(kappa L / 2) / kappa; L^2 kappa / 2 at kappa -> 0)."""
    kappa = np.asarray(kappa, float)
    safe = np.where(kappa == 0.0, 1.0, kappa)
    return 1e6 * np.where(kappa == 0.0, 0.0, 2.0 * np.sin(0.5 * safe * L) ** 2 / safe)


def reading(T, f, extra=0.0):
    """The sensor's reading (um, zeroed at the first sample) of the beam at the temperatures T, rutile shares f; extra,
    if given, a misfit strain added (zero at the first sample)."""
    return arc_rise(timoshenko_factor() * (misfit(T, f) + extra))


def core_reading(core, v, s=None):
    """The rate-independent beam's reading (um) for the drive v, from the state s (default the rest state)."""
    T = temperature(core, v)
    return reading(T, rutile_share(core, T, s))


# ---- creep: the tip pressing a silicone membrane that relaxes (a Prony series) ----
#
# The creep record's beam works a microvalve: its tip presses a PDMS membrane over the valve's seat (in contact from the
# start, under a preload long applied: only the load's changes relax). The beam is a spring k_c to its free rise d; the
# membrane a standard viscoelastic solid of two relaxation times, its force F = k_inf x + sum_j F_j, each Maxwell arm
# dF_j / dt = k_j dx / dt - F_j / tau_j (a generalised Maxwell model, the Prony series G(t) = k_inf + sum_j k_j exp(-t /
# tau_j); Ferry, Viscoelastic Properties of Polymers, 1980, as remembered; tau_1 1.5 ... 3 s, tau_2 15 ... 30 s for a
# lightly cross-linked PDMS: a choice; a_1 0.14 ... 0.2, a_2 0.1 ... 0.14); the tip's rise x from k_c (d - x) = F. After
# a rise the membrane relaxes and the tip creeps on toward d / (1 + k_inf / k_c); after a fall it creeps back (labelled
# "creep"). The beam's reading is the tip's. In the units used, a_inf = k_inf / k_c (0.3 ... 0.5), a_j = k_j / k_c.

def membrane_contact(d, dt, a_inf, a, tau):
    """The tip's rise x for the free rise d (samples dt apart, x linear between them): each arm's force (over k_c)
    stepped exactly for a linear x, G_j <- G_j e^(-dt / tau_j) + a_j (x_i - x_(i-1)) (tau_j / dt) (1 - e^(-dt / tau_j)),
    and x_i from x_i (1 + a_inf) + sum_j G_j = d_i (the arms at rest at the start)."""
    d = np.asarray(d, float)
    a = np.asarray(a, float)
    tau = np.asarray(tau, float)
    E = np.exp(-dt / tau)
    c = a * tau / dt * (1.0 - E)
    x = np.empty(len(d))
    x[0] = d[0] / (1.0 + a_inf)
    G = np.zeros(len(a))
    for i in range(1, len(d)):
        # x_i (1 + a_inf) + sum_j (G_j E_j + c_j (x_i - x_(i-1))) = d_i
        base = G * E - c * x[i - 1]
        x[i] = (d[i] - base.sum()) / (1.0 + a_inf + c.sum())
        G = base + c * x[i]
    return x


# ---- rate dependence: the chip on a glass slide, heat diffusing through it ----
#
# The rate record's chip was glued on a glass slide (to insulate it from the Peltier: a choice for that run), its loop's
# sensor left on the Peltier: the loop sets the slide's bottom face to the set point, the chip (thinned to 50 um: its
# heat capacity a twentieth of the slide's, left out) sits on its top face, insulated above (the air's film coefficient
# left out: a Biot number of 1e-3). The top face follows the bottom's by one-dimensional conduction through the slide
# (thickness l, diffusivity alpha = 5.9e-7 m^2 / s for borosilicate glass, as remembered; Carslaw & Jaeger, Conduction
# of Heat in Solids, 1959, the slab with one face held and one insulated): a step of the bottom reaches the top as
#
#     F(t) = 1 - (4 / pi) sum_n (-1)^n exp(-(2 n + 1)^2 t / tau) / (2 n + 1),   tau = 4 l^2 / (pi^2 alpha),
#
# (0.11 ... 0.21 s for l = 0.4 ... 0.55 mm): each mode a first-order lag of the set point, weighted (4 / pi) (-1)^n / (2
# n + 1). A lag that grows with the drive's speed and a loop that widens with it (labelled "rate_dependence").

ALPHA_GLASS = 5.9e-7
N_MODES = 400


def slab_step(t, tau, n_modes=N_MODES):
    """F(t): the insulated face's response to a unit step of the held face (the series to n_modes terms)."""
    t = np.atleast_1d(np.asarray(t, float))
    n = np.arange(n_modes)
    w = 4.0 / math.pi * (-1.0) ** n / (2 * n + 1)
    return 1.0 - (w[None, :] * np.exp(-np.outer(t, (2 * n + 1) ** 2) / tau)).sum(axis=1)


def slab_lag(T_set, dt, tau, n_modes=N_MODES):
    """The insulated face's temperature for the held face's T_set (samples dt apart, linear between them; at rest
    before): T_set - sum_n w_n e_n, each e_n' = -lambda_n e_n + T_set' stepped exactly for a constant slope,
    lambda_n = (2 n + 1)^2 / tau, w_n = (4 / pi) (-1)^n / (2 n + 1). (The modes' lag after a slope s is w_n s /
    lambda_n: the tail beyond n_modes under 1e-9 of a K / s slope's.)"""
    T_set = np.asarray(T_set, float)
    n = np.arange(n_modes)
    w = 4.0 / math.pi * (-1.0) ** n / (2 * n + 1)
    lam = (2 * n + 1) ** 2 / tau
    E = np.exp(-lam * dt)
    G = (1.0 - E) / lam
    out = np.empty(len(T_set))
    out[0] = T_set[0]
    e = np.zeros(n_modes)
    for i in range(1, len(T_set)):
        s = (T_set[i] - T_set[i - 1]) / dt
        e = e * E + s * G
        out[i] = T_set[i] - w @ e
    return out


# ---- drift: the sensor's light source warming up after it was switched on ----
#
# The drift record was started soon after the confocal sensor's controller was switched on (t_on 20 ... 60 s before the
# record: the operator did not wait for its warm-up). Its white LED heats the optical head's mount, and the mount's
# expansion moves the chromatic lens's focus along the axis: the reading shifts with the mount's temperature (c 0.9 ...
# 1.2 um / K, a choice in the range a datasheet's warm-up drift gives). The head is two thermal nodes (the LED's mount,
# C_1, heated by P; the housing, C_2, to the room through R_2a, to the mount through R_12; a lumped network, as a
# thermal engineer draws one): C_1 T_1' = P - (T_1 - T_2) / R_12, C_2 T_2' = (T_1 - T_2) / R_12 - T_2 / R_2a (about the
# room), both at the room's temperature when switched on: the mount warms on two time constants (some 30 s and 5
# minutes), a smooth, one-way drift (labelled "drift").

def warmup(t, t_on, P, C1, C2, R12, R2a):
    """The mount's temperature rise T_1 (K) at the times t (s; switched on at -t_on): the network's exact solution by
    its eigen-decomposition, x(t) = x_inf + V exp(Lambda (t + t_on)) V^-1 (x_0 - x_inf), x_0 = 0."""
    A = np.array([[-1 / (R12 * C1), 1 / (R12 * C1)], [1 / (R12 * C2), -1 / (R12 * C2) - 1 / (R2a * C2)]])
    b = np.array([P / C1, 0.0])
    x_inf = -np.linalg.solve(A, b)
    lam, V = np.linalg.eig(A)
    c = np.linalg.solve(V, -x_inf)
    s = np.asarray(t, float) + t_on
    x = x_inf[:, None] + V @ (c[:, None] * np.exp(np.outer(lam, s)))
    return x[0]


# ---- asymmetry: a magnet on the tip read by a Hall sensor ----
#
# The asymmetry record's beam carries a small NdFeB cylinder on its tip (radius R_m = 60 um, length 120 um, remanence
# B_r = 1.3 T) and is read by a Hall sensor on its axis, z_0 (110 ... 140 um) above its upper face (the confocal sensor
# away for repair). A uniformly magnetised cylinder's field on its axis, a distance z beyond its face, is the field of a
# solenoid's surface current (Biot-Savart; e.g. Jackson, Classical Electrodynamics, as remembered):
#
#     B(z) = (B_r / 2) ((z + l) / sqrt(R^2 + (z + l)^2) - z / sqrt(R^2 + z^2)),
#
# the sensor's voltage linear in B, scaled to um by its slope at rest: y = (B(z_0 - x) - B(z_0)) / -B'(z_0). A rise
# (nearer) reads larger than a fall (labelled "asymmetry").

def magnet_field(z, R, l, Br=1.3):
    """The on-axis field (T) of a cylinder magnet (radius R, length l, remanence Br), z beyond its face."""
    z = np.asarray(z, float)
    return 0.5 * Br * ((z + l) / np.sqrt(R * R + (z + l) ** 2) - z / np.sqrt(R * R + z * z))


def magnet_slope(z, R, l, Br=1.3):
    """dB/dz of :func:`magnet_field` (T per unit of z): (B_r / 2) (R^2 / (R^2 + (z + l)^2)^1.5 - R^2 / (R^2 +
    z^2)^1.5)."""
    return 0.5 * Br * (R * R / (R * R + (z + l) ** 2) ** 1.5 - R * R / (R * R + z * z) ** 1.5)


def hall_reading(x, z0, R, l):
    """The Hall sensor's reading (um) of the tip's rise x (um), the magnet's face z0 (um) below it at rest."""
    x = np.asarray(x, float)
    return (magnet_field(z0 - x, R, l) - magnet_field(z0, R, l)) / -magnet_slope(z0, R, l)


# ---- saturation: the tip landing on the package's lid ----
#
# The saturation record's package had a lower lid fitted (a glass cover for a dusty lab): the lid lies g above the tip
# at rest (0.55 ... 0.7 of the record's upward stroke). The tip (a glued bead, radius 10 um) lands on it in a Hertzian
# contact, F = K (x - g)^1.5, K = (4 / 3) E* sqrt(R) (E* 50 GPa for silica on glass; Johnson, Contact Mechanics, 1985,
# as remembered), against the beam's stiffness k_c = 3 E I / L^3 of its free rise d (the composite's bending stiffness E
# I: 2e-10 ... 3e-10 N m^2 over its 0.2 mm width, k_c some 5 N / m): k_c (d - x) = K (x - g)^1.5 where the free rise
# passes g. A flat top (labelled "saturation").

def lid_contact(d, g, k_c, K):
    """The tip's rise x (um) for the free rise d (um), a lid g (um) above: d below g, else the root of k_c (d - x) = K
    (x - g)^1.5 (SI inside), by Newton's method on s = sqrt(x - g) from above (convex: it converges from above)."""
    d = np.asarray(d, float)
    x = d.copy()
    on = d > g
    if on.any():
        D = (d[on] - g) * 1e-6
        s = np.sqrt(D)
        for _ in range(60):
            f = K * s ** 3 + k_c * s * s - k_c * D
            s = s - f / (3 * K * s * s + 2 * k_c * s)
        x[on] = g + 1e6 * s * s
    return x


# ---- delay: a USB data-acquisition module's output buffer ----
#
# The delay record's set point came from a laptop through a USB data-acquisition module that streams its analogue
# output from a FIFO: every sample waits for the buffer's depth to drain ahead of it (N_buf samples at its output rate
# f_out: a dead time T_d = N_buf / f_out, here 0.12 ... 0.2 s), then passes the DAC unchanged (labelled "delay").

def late(drive_at, t, T_d):
    """The set point at the times t: the drive T_d late (its first value before the record)."""
    return drive_at(np.asarray(t, float) - T_d)


# ---- initial state: the chip just off a wire bonder's hot stage ----
#
# The initial-state record's chip was wire-bonded on a hot stage at 150 C (every grain rutile) and put on the Peltier
# straight away; the loop took it straight down to the bias without the conditioning: every grain whose T_down lies
# above the bias switched back to M1 on the way down, and those whose loop's middle lies above the bias but whose
# T_down lies below it stayed rutile (the conditioning leaves them M1) until the drive first cools past their T_down:
# then they switch, once, and stay M1 about the bias: the beam (its reading zeroed at the start) answers the first cold
# excursions with a fall the rest state's does not have and sits lower from then on.

def hot_stage_state(core, T_hot=150.0, n=4000):
    """The grains' states after the hot stage at T_hot and a straight cool-down to the bias: every grain rutile at the
    start (T_hot above every T_up: checked), the beam run from T_hot down to T_b."""
    tu, td = grains(core)
    s = np.ones(len(tu))
    _relays(np.linspace(T_hot, core["Tb"], n + 1), tu, td, s)
    return s


# ---- two effects: a camera's frames (delay) and the polyimide taking up water (drift) ----
#
# The pair's tip is read by a machine-vision camera on a microscope (the confocal sensor away): frame k exposes over
# [t_k - T_exp, t_k] (t_k = phase + k / f_cam, f_cam 25 ... 30 frames a second, T_exp 8 ... 15 ms), its edge finder
# returns the blurred edge's centroid, the tip's mean position over the exposure, and the frame reaches the reading
# latency (2 ... 3 frame periods: readout, USB transfer, the edge finder) after its exposure ends, held until the next
# (labelled "delay": a sampled, averaged and held dead time of 70 ... 120 ms; the single delay case's is the drive's
# buffer, a plain dead time on the input). The chip had been brought from a dry cabinet (10 % RH) into the lab's air
# (45 ... 55 % RH) t_a = 30 ... 60 s before the record: the polyimide takes up water through its open face (the VO2
# film seals the other) by Fickian diffusion into a plane sheet sealed on one face (Crank, The Mathematics of
# Diffusion, 1975, ch. 4, as remembered), its mean uptake
#
#     M(t) / M_inf = 1 - sum_n 8 / ((2 n + 1)^2 pi^2) exp(-(2 n + 1)^2 t / tau_w),   tau_w = 4 t_s^2 / (pi^2 D),
#
# D 1.5e-13 ... 2.5e-13 m^2 / s for water in polyimide (tau_w 90 ... 150 s), and the strip swells by its hygroscopic
# coefficient 2e-5 a % RH times the uptake (as remembered for Kapton): the misfit strain takes that swelling as it does
# the strip's thermal expansion (its mean only: the gradient's own moment across the strip left out). The beam bends
# slowly on, decelerating (labelled "drift"; the single drift case's is the sensor's warm-up, outside the beam).

CHE_PI = 2e-5
N_UPTAKE = 200


def uptake(t, tau_w, n_terms=N_UPTAKE):
    """M(t) / M_inf of a plane sheet sealed on one face, its open face stepped at t = 0 (the series to n_terms terms;
    its tail some 1e-3 at t = 0, under 1e-10 from t = 1e-4 tau_w on; the records start 30 s or more after the step)."""
    t = np.atleast_1d(np.asarray(t, float))
    k = 2 * np.arange(n_terms) + 1
    return 1.0 - (8.0 / (k * k * math.pi ** 2) * np.exp(-np.outer(np.maximum(t, 0.0), k * k) / tau_w)).sum(axis=1)


def swelling(t, ta, tau_w, dRH):
    """The strip's swelling strain (the misfit's share) at the record's times t, less its value at the start: CHE dRH
    (M(t + ta) - M(ta)) / M_inf."""
    m = uptake(np.asarray(t, float) + ta, tau_w)
    return CHE_PI * dRH * (m - m[0])


def camera_frames(t, x_fine, h, fps, t_exp, latency, phase):
    """The camera's reading at the times t: the frame whose exposure [t_k - t_exp, t_k] ended last with t_k + latency
    <= t, its value the mean of x over that exposure (x_fine on the fine grid of step h from 0, linear between: the
    trapezoid rule is exact for it, the exposure's ends interpolated); before the first frame arrives, x's first value.
    Returns (reading, the frames' times t_k, their values)."""
    t = np.asarray(t, float)
    x_fine = np.asarray(x_fine, float)
    tf = np.arange(len(x_fine)) * h
    P = 1.0 / fps
    k_last = int(np.floor((t[-1] - latency - phase) / P))
    tk = phase + np.arange(k_last + 1) * P
    cum = np.r_[0.0, np.cumsum(0.5 * (x_fine[1:] + x_fine[:-1]) * h)]

    def integral(s):
        s = np.clip(s, 0.0, tf[-1])
        j = np.minimum((s / h).astype(int), len(x_fine) - 2)
        u = s - j * h
        xj, xs = x_fine[j], np.interp(s, tf, x_fine)
        return cum[j] + 0.5 * (xj + xs) * u

    a = tk - t_exp
    lo = np.maximum(a, 0.0)
    vals = (integral(tk) - integral(lo) + x_fine[0] * (lo - a)) / t_exp
    k = np.floor((t - latency - phase) / P).astype(int)
    out = np.where(k >= 0, vals[np.clip(k, 0, len(vals) - 1)], x_fine[0])
    return out, tk, vals


# ---- out of vocabulary: a 16-bit count that wraps ----
#
# The out-of-vocabulary record's confocal sensor was read through a fieldbus gateway mapped to a signed 16-bit register
# at 1 nm a count (its range is 400 um: the map should have been 10 nm a count): the count wraps from +32767 to -32768
# as the sensor's distance passes 32.767 um above its zero (the zero set z_w below the tip at rest, 0.35 ... 0.55 of the
# upward stroke below the wrap). The reading jumps by 65.536 um each time the tip crosses that height, both ways: no
# monotone map of the beam's stroke, and no effect of the vocabulary, draws it.

def int16_wrap(x_um, zero_um):
    """The register's value (um) for the tip at x_um above rest, the sensor's zero zero_um below rest: the distance in
    nm rounded to a count and wrapped into -32768 ... 32767, less its value at rest (um)."""
    def reg(xx):
        c = np.rint((np.asarray(xx, float) + zero_um) * 1e3).astype(np.int64)
        return ((c + 32768) % 65536 - 32768) * 1e-3
    return reg(x_um) - reg(0.0)

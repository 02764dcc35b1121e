"""The HOLDOUT37 set: written after HOLDOUT36 was measured, by a session that did not read how the diagnosis decides,
to be run once for the next round's measurement; kept out of ALL until then.

Mechanisms and signals that the other sets do not have (the laws are in :mod:`.mechanisms37`, the signals in
:mod:`.signals37`, each beside its source; the citations were written from memory, as they say). Every core is a
push-pull pair of liquid-nanofoam cells on a rocker: each a sealed bellows cell of water holding a hydrophobised
mesoporous silica (a "heterogeneous lyophobic system", Eroshenko et al. 2001), its pores an ink-bottle network (Mason,
Proc. R. Soc. Lond. A 390 (1983) 47 and 415 (1988) 453): 100 grains of 10^3 cavities joined by narrower necks
(Mayagoitia's construction principle: a neck 0.5 ... 0.8 of the smaller cavity it joins; the cavities' radii lognormal,
spread 0.15 ... 0.22). Water enters a cavity only through a neck from a filled neighbour or the bulk water, at the
neck's Laplace-Washburn pressure 2 gamma |cos theta_a| / r_n (pore blocking), and leaves a filled cavity by itself at
its receding pressure 2 gamma |cos theta_r| / r_s (|cos theta_r| / |cos theta_a| = 0.65 ... 0.72); pressures in units
of 2 gamma |cos theta_a| / r0, about 18 MPa. Rate independent, with return-point memory (the "no passing" of a
network whose filling is monotone in its neighbours'), but neither a Preisach model (the necks couple the cavities:
two minor loops between the same pressures differ by about 15 % of their rise) nor a Prandtl-Ishlinskii one. A servo
valve sets the cells' pressures in push-pull about a preload (midway between cell A's median emptying pressure and its
necks' 10 % entry pressure), the drive's peak reaching the necks' 17 ... 22 % entry pressure (about 7.5 MPa of swing
about 18 MPa; a unipolar stroke's 0 V is one end of the valve's stroke); each cell's bellows travels with the water's
and the bellows' compliance (kappa 0.8 ... 1.3 of the pore volume per pressure unit) plus the filled pore volume, and
the cells push the ends of a rocker whose tip is the output (times a drawn gain). The cells were run in before use
(from atmospheric pressure to the starting pressure, then cycled about it with an amplitude falling from 1.5 times the
working swing to 0 over 40 reversals). Its closeness to a PI model is measured in tests/test_realistic_holdout37.py: a
PI model of 12 plays of the drive fitted by NNLS leaves 0.39 ... 0.61 sigma RMS on the clean record (at most 5.1 ...
11.1 sigma), where the core is 76 ... 79 sigma from a straight line. Every record starts at 0 V from the run-in cells
except the two initial-state cases'.

- a clean core under harmonic tremor at a volcano (a gliding fundamental with its overtones at random phases, surges,
  long-period events), +-44 ... 48 V, with a noisy input monitor, sampled at 1.415 kHz;
- creep from the thermally activated drying of the filled cavities (a vapour bubble's nucleation: the rate nu exp(-(p -
  b) / D), D = k_B T / v*, the activation volume v* 11 ... 15 nm^3 at 15 ... 30 C: 0.26 ... 0.38 MPa per e-fold of the
  time, nu 1e6 / s; the cells rested an hour at the starting pressure); under a dental chair's treatment (raised in
  steps, held, adjusted, to the top, down to rinse, lowered in steps), on a unipolar stroke, sampled at 227 Hz;
- rate dependence from the sintered snubbers feeding the cells (Darcy flow through a Kozeny-Carman permeability, 2 ...
  5 ms on the water's and the bellows' compliance and far more where the silica takes or gives water: inside the
  core); under a horse's gaits (walk, trot, canter, gallop and back, the stride gliding through the transitions),
  +-44 ... 48 V, with a noisy input monitor, sampled at 1.115 kHz;
- an offset drift from the floor slab bending under a pallet truck (Hertz's floating plate, the radius of relative
  stiffness 0.7 ... 1 m; the cell's base and the reading's stand 0.3 ... 0.6 m apart; 2 ... 3 passes at 0.5 ... 1.1
  m/s, most with a stop of 3 ... 12 s beside the rig), 4 ... 8 % of the span at its largest, either sign; under labour
  contractions on a tocodynamometer, on a unipolar stroke, sampled at 655 Hz;
- asymmetry of a draw-wire sensor whose wire leaves 29 ... 57 degrees off the rocker tip's line (its length the
  straight distance to the tip: the ends' secants 10 ... 17 % apart, on a drawn side); under a basketball dribbled (low,
  high and crossover series, held at the waist between), +-44 ... 48 V, sampled at 745 Hz;
- saturation of an astigmatic focus-error sensor watching the rocker tip (Sheppard's arcsine on the quadrant detector;
  the line foci 1 ... 2.4 Rayleigh ranges apart; the ends compressed by 10 ... 17 %); under an infant's non-nutritive
  sucking (bursts and pauses, swallows), +-44 ... 48 V, with a noisy input monitor, sampled at 825 Hz;
- a delay of the valve's ports reaching the cells through long water-filled steel lines (Korteweg's wave speed, 1.40
  ... 1.44 km/s; 2.5 ... 6 samples, 7.6 ... 19 m of line; the valve's outlets matched, the cells' ends closed: a pure
  dead time); under oesophageal swallows on a manometry channel, on a unipolar stroke, with a noisy input monitor,
  sampled at 457 Hz;
- a core left by the cells' leak test (both ports raised together to 1.05 ... 1.2 working swings above the preload,
  held and lowered back), the record starting there at 0 V; under a rocking chair (pushes, decays, stopped by the
  feet), +-44 ... 48 V, sampled at 1.035 kHz;
- two effects: the drive reaching the valve through the analogue output's FIFO (3 ... 6 samples deep, its clock 0.2
  ... 0.8 of a sample behind) and a core left by the installer's bleeding of the lines (3 ... 6 pulses of alternating
  sign to 0.7 ... 0.95 of the stroke); under a bout of hiccups (inspiratory spikes cut off by the glottis, expiratory
  rebounds), +-44 ... 48 V, sampled at 1.275 kHz;
- out of vocabulary: the rocker's reading digitised by a 16-bit converter whose data bit 11 or 12 is stuck high (a
  cracked bus trace: 3.4 ... 8.1 % of the span added wherever that bit is 0), a sawtooth comb no monotone map of the
  core draws; under kettlebell swings (sets of swings with a float at the top, the bell parked between), +-44 ... 48 V,
  sampled at 935 Hz.

Every bipolar drive is drawn until its weaker side reaches 0.85 of its stronger (a test programme's balance). The
effects' sizes beyond a gain and an offset on the core (seeds 0 ... 2) are stated in the test.
"""

import math

import numpy as np

from . import mechanisms37 as m37
from . import signals37 as s37
from .record import case_set, finish
from .set_tools import balanced as _balanced, fits as _fits, grid as _grid, scale as _scale, solve_for as _solve_for

HOLDOUT37, case, _rng = case_set("holdout37_", 37000)

N_GRAINS = 100
L_SIDE = 10
RUN_IN = 1.5          # the run-in's first amplitude over the working swing dp
NU = 1e6              # the drying's attempt rate, 1/s (a lumped prefactor)
AGE = 3600.0          # how long the cells rested at their starting pressure before a record, s


def _foam_pair(rng, unipolar=False):
    """The core: two cells' silica (each 100 grains of 10^3 cavities; the cavities' spread sig 0.15 ... 0.22, the
    receding-to-advancing ratio lam 0.65 ... 0.72, each cell's network from its own drawn seed), the preload p_c midway
    between cell A's median emptying pressure and its necks' 10 % entry pressure, the swing dp reaching the necks'
    alpha entry pressure (alpha 0.17 ... 0.22), the compliance ratio kappa 0.8 ... 1.3 and the rocker's gain 0.7 ...
    1.4."""
    sig, lam = rng.uniform(0.15, 0.22), rng.uniform(0.65, 0.72)
    seeds = (int(rng.integers(2 ** 62)), int(rng.integers(2 ** 62)))
    fA = m37.nanofoam(N_GRAINS, L_SIDE, sig, lam, seeds[0])
    p_c = 0.5 * (float(np.quantile(fA["b"], 0.5)) + float(np.quantile(fA["a"], 0.1)))
    alpha = rng.uniform(0.17, 0.22)
    dp = float(np.quantile(fA["a"], alpha)) - p_c
    u0 = -1.0 if unipolar else 0.0
    return dict(sig=sig, lam=lam, seeds=seeds, p_c=p_c, alpha=alpha, dp=dp, kappa=rng.uniform(0.8, 1.3),
                gain=rng.uniform(0.7, 1.4), u0=u0, unipolar=unipolar)


def _foams(core):
    return tuple(m37.nanofoam(N_GRAINS, L_SIDE, core["sig"], core["lam"], s) for s in core["seeds"])


def _ports(core, u):
    """The two cells' port pressures at the valve's command u."""
    u = np.asarray(u, float)
    return core["p_c"] + core["dp"] * u, core["p_c"] - core["dp"] * u


def _run_in_states(core):
    """Both cells run in about their pressures at the record's first command (the valve at u0)."""
    pA, pB = _ports(core, core["u0"])
    return tuple(m37.run_in(N_GRAINS, L_SIDE, core["sig"], core["lam"], s, float(p0), RUN_IN * core["dp"])
                 for s, p0 in zip(core["seeds"], (pA, pB)))


def _command(core, v):
    """The valve's command from the drive: v over its peak (bipolar), or 2 v / top - 1 (unipolar: 0 V one end)."""
    v = np.asarray(v, float)
    return 2.0 * v / core["top"] - 1.0 if core["unipolar"] else v / core["amp"]


def _rocker(core, uA_p, uB_p, SA, SB):
    """The rocker's tip: gain (kappa (p_A - p_B) + S_A - S_B)."""
    return core["gain"] * (core["kappa"] * (uA_p - uB_p) + SA - SB)


def _core_u(core, u, states=None, return_states=False):
    """The core at the valve commands u from ``states`` (both cells; default the run-in states)."""
    fA, fB = _foams(core)
    sA, sB = states if states is not None else _run_in_states(core)
    pA, pB = _ports(core, u)
    SA, stA = m37.foam_cell(fA, sA, pA)
    SB, stB = m37.foam_cell(fB, sB, pB)
    out = _rocker(core, pA, pB, SA, SB)
    return (out, (stA, stB)) if return_states else out


def _core_of(core, v, states=None, return_states=False):
    return _core_u(core, _command(core, v), states, return_states)


def _history_states(core, u_hist):
    """Both cells after the valve's commands u_hist, from the run-in states."""
    _, st = _core_u(core, u_hist, return_states=True)
    return st


def _port_history_states(core, pA_hist, pB_hist):
    """Both cells after their own port pressures' histories, from the run-in states."""
    fA, fB = _foams(core)
    sA, sB = _run_in_states(core)
    return m37.foam_cell(fA, sA, pA_hist)[1], m37.foam_cell(fB, sB, pB_hist)[1]


# ---- clean ----

@case
def clean_nanofoam_rocker_volcanic_tremor_1415hz(seed):
    rng = _rng(seed, 1)
    dt = 1 / 1415

    def make():
        prog = s37.volcanic_tremor(rng, rng.uniform(19.0, 25.0))
        if not _fits(dt, prog["T_end"]):
            return None
        t = _grid(dt, prog["T_end"])
        return s37.tremor_ground_velocity(t, prog), t, prog
    x, t, prog = _balanced(make)
    amp = rng.uniform(44.0, 48.0)
    v = _scale(x, amp)
    core = dict(_foam_pair(rng), amp=amp)
    off = rng.uniform(-4.0, 4.0)
    y = _core_of(core, v) + off
    rec = finish("holdout37_clean_nanofoam_rocker_volcanic_tremor_1415hz", seed, t, v, y, set(), "explained",
                 f"a clean core (a push-pull pair of liquid-nanofoam cells on a rocker: the silica's spread "
                 f"{core['sig']:.2f}, the swing to the necks' {core['alpha']:.0%} entry pressure) under harmonic "
                 f"tremor at a volcano ({len(prog['lps'])} long-period events), +-{amp:.0f} V, 1.415 kHz", rng,
                 monitor_noise=3e-4)
    rec.extra.update(core, offset=off, prog=prog, x=x, drive=v)
    return rec


# ---- one effect ----

@case
def creep_activated_drying_dental_chair_227hz(seed):
    rng = _rng(seed, 2)
    dt = 1 / 227
    times, vals = s37.dental_chair(rng)
    while not _fits(dt, times[-1]):
        times, vals = s37.dental_chair(rng)
    t = _grid(dt, times[-1])
    p = s37.through_points(t, times, vals)
    top = rng.uniform(88.0, 97.0)
    v = top * p / p.max()
    core = dict(_foam_pair(rng, unipolar=True), top=top)
    v_star = rng.uniform(11.0, 15.0)                                     # the activation volume, nm^3
    T_k = 273.15 + rng.uniform(15.0, 30.0)
    P0 = 18e6                                                            # the pressure unit, Pa
    D = 1.380649e-23 * T_k / (v_star * 1e-27 * P0)
    fA, fB = _foams(core)
    sA, sB = _run_in_states(core)
    pA, pB = _ports(core, _command(core, v))
    SA, _ = m37.activated_cell(fA, sA, pA, dt, D, NU, AGE)
    SB, _ = m37.activated_cell(fB, sB, pB, dt, D, NU, AGE)
    y = _rocker(core, pA, pB, SA, SB)
    rec = finish("holdout37_creep_activated_drying_dental_chair_227hz", seed, t, v, y, {"creep"}, "either",
                 f"creep from the thermally activated drying of the filled cavities (activation volume {v_star:.0f} "
                 f"nm^3 at {T_k - 273.15:.0f} C: {D * 18:.2f} MPa per e-fold of the rate) under a dental chair's "
                 f"treatment, to {top:.0f} V, 227 Hz", rng)
    rec.extra.update(core, times=times, vals=vals, p=p, v_star=v_star, T_k=T_k, D=D, drive=v)
    return rec


@case
def rate_kozeny_carman_snubbers_horse_gaits_1115hz(seed):
    rng = _rng(seed, 3)
    dt = 1 / 1115

    def make():
        seq, T_end = s37.horse_gaits(rng, int(rng.integers(3, 5)))
        if not _fits(dt, T_end):
            return None
        t = _grid(dt, T_end)
        return s37.foreleg_angle(t, seq), t, seq
    x, t, seq = _balanced(make)
    amp = rng.uniform(44.0, 48.0)
    v = _scale(x, amp)
    core = dict(_foam_pair(rng), amp=amp)
    tau = rng.uniform(2e-3, 5e-3)                  # the snubber's time constant on the water's and bellows' compliance
    d_grain, eps = rng.uniform(10e-6, 40e-6), rng.uniform(0.3, 0.4)
    perm = d_grain ** 2 * eps ** 3 / (180.0 * (1.0 - eps) ** 2)
    fA, fB = _foams(core)
    sA, sB = _run_in_states(core)
    qA, qB = _ports(core, _command(core, v))
    pA, SA, _ = m37.snubbed_cell(fA, sA, qA, dt, tau, core["kappa"])
    pB, SB, _ = m37.snubbed_cell(fB, sB, qB, dt, tau, core["kappa"])
    y = _rocker(core, pA, pB, SA, SB)
    rec = finish("holdout37_rate_kozeny_carman_snubbers_horse_gaits_1115hz", seed, t, v, y, {"rate_dependence"},
                 "either",
                 f"the cells fed through sintered snubbers (Darcy flow, a Kozeny-Carman permeability of "
                 f"{perm * 1e12:.1f} um^2; {tau * 1e3:.1f} ms on the water's and bellows' compliance) under a horse's "
                 f"gaits ({len(seq) - 2} changes), +-{amp:.0f} V, 1.115 kHz", rng, monitor_noise=2.5e-4)
    rec.extra.update(core, seq=seq, amp=amp, x=x, tau=tau, d_grain=d_grain, eps=eps, perm=perm, drive=v)
    return rec


@case
def drift_floor_slab_pallet_truck_labour_contractions_655hz(seed):
    rng = _rng(seed, 4)
    dt = 1 / 655
    prog = s37.labour(rng, rng.uniform(40.0, 52.0))
    while not _fits(dt, prog["T_end"]):
        prog = s37.labour(rng, rng.uniform(40.0, 52.0))
    t = _grid(dt, prog["T_end"])
    p = s37.uterine_pressure(t, prog)
    top = rng.uniform(88.0, 97.0)
    v = top * p / p.max()
    core = dict(_foam_pair(rng, unipolar=True), top=top)
    h = _core_of(core, v)
    ell = rng.uniform(0.7, 1.0)                                      # the slab's radius of relative stiffness, m
    sep = rng.uniform(0.3, 0.6)                                      # base to stand, m
    passes = []
    n_p = int(rng.integers(2, 4))
    starts = np.sort(rng.uniform(0.05, 0.6, n_p)) * t[-1]
    for t0 in starts:
        d = float(rng.choice([-1.0, 1.0]))
        speed = rng.uniform(0.5, 1.1)
        passes.append((float(t0), -d * 8 * ell, d * 8 * ell, speed, d * rng.uniform(-1.5, 1.5) * ell,
                       rng.uniform(3.0, 12.0) if rng.uniform() < 0.6 else 0.0, rng.uniform(0.3, 1.5) * ell,
                       ((0.0, rng.uniform(0.25, 0.4)), (rng.uniform(1.1, 1.5), 1.0))))
    pot = m37.truck_offset(t, passes, sep, ell)
    mag, sd = rng.uniform(0.04, 0.08), float(rng.choice([-1.0, 1.0]))
    off = sd * mag * np.ptp(h) * pot / np.abs(pot).max()
    rec = finish("holdout37_drift_floor_slab_pallet_truck_labour_contractions_655hz", seed, t, v, h + off, {"drift"},
                 "either",
                 f"an offset drift from the floor slab bending under a pallet truck ({n_p} passes; the slab's radius "
                 f"of relative stiffness {ell:.2f} m, base and stand {sep:.2f} m apart; {mag:.1%} of the span at its "
                 f"largest) under labour contractions, to {top:.0f} V, 655 Hz", rng)
    rec.extra.update(core, prog=prog, top=top, p=p, h=h, ell=ell, sep=sep, passes=passes, pot=pot, mag=mag, side=sd,
                     offset=off, drive=v)
    return rec


def _wire_asym(stroke, phi0):
    return float(m37.draw_wire_reading(1.0, phi0, stroke) + m37.draw_wire_reading(-1.0, phi0, stroke))


@case
def asymmetry_offset_draw_wire_basketball_dribble_745hz(seed):
    rng = _rng(seed, 5)
    dt = 1 / 745

    def make():
        bounces, T_end = s37.dribbling(rng, int(rng.integers(4, 7)))
        if not _fits(dt, T_end):
            return None
        t = _grid(dt, T_end)
        return s37.ball_height(t, bounces), t, bounces
    x, t, bounces = _balanced(make)
    amp = rng.uniform(44.0, 48.0)
    v = _scale(x, amp)
    core = dict(_foam_pair(rng), amp=amp)
    h = _core_of(core, v)
    c = (h.max() + h.min()) / 2
    X = np.abs(h - c).max()
    a, sd, phi0 = rng.uniform(0.10, 0.17), float(rng.choice([-1.0, 1.0])), rng.uniform(0.5, 1.0)
    stroke = _solve_for(lambda st: _wire_asym(st, phi0), a, 1e-4, 0.999 * math.cos(phi0))
    y = c + sd * X * m37.draw_wire_reading(sd * (h - c) / X, phi0, stroke)
    rec = finish("holdout37_asymmetry_offset_draw_wire_basketball_dribble_745hz", seed, t, v, y, {"asymmetry"},
                 "either",
                 f"a draw-wire sensor whose wire leaves {math.degrees(phi0):.0f} deg off the rocker tip's line (the "
                 f"stroke {stroke:.2f} of the wire's length: the ends' secants {a:.0%} apart) under a basketball "
                 f"dribbled ({len(bounces)} bounces), +-{amp:.0f} V, 745 Hz", rng)
    rec.extra.update(core, bounces=bounces, amp=amp, x=x, h=h, centre=c, X=X, a=a, side=sd, phi0=phi0, stroke=stroke,
                     drive=v)
    return rec


@case
def saturation_astigmatic_focus_sensor_infant_suckling_825hz(seed):
    rng = _rng(seed, 6)
    dt = 1 / 825

    def make():
        bursts, T_end = s37.suckling(rng, rng.uniform(28.0, 40.0))
        if not _fits(dt, T_end):
            return None
        t = _grid(dt, T_end)
        return s37.jaw_excursion(t, bursts), t, bursts
    x, t, bursts = _balanced(make)
    amp = rng.uniform(44.0, 48.0)
    v = _scale(x, amp)
    core = dict(_foam_pair(rng), amp=amp)
    h = _core_of(core, v)
    c = (h.max() + h.min()) / 2
    X = np.abs(h - c).max()
    comp, s_f = rng.uniform(0.10, 0.17), rng.uniform(0.5, 1.2)
    z0 = _solve_for(lambda z: 1.0 - float(m37.focus_reading(1.0, z, s_f)), comp, 1e-3, math.sqrt(1 + s_f * s_f))
    y = c + X * m37.focus_reading((h - c) / X, z0, s_f)
    rec = finish("holdout37_saturation_astigmatic_focus_sensor_infant_suckling_825hz", seed, t, v, y, {"saturation"},
                 "either",
                 f"an astigmatic focus-error sensor watching the rocker tip (the line foci {2 * s_f:.1f} Rayleigh "
                 f"ranges apart, the stroke's ends {z0:.2f} of it out of focus: compressed by {comp:.0%}) under an "
                 f"infant's sucking ({len(bursts)} bursts), +-{amp:.0f} V, 825 Hz", rng, monitor_noise=3e-4)
    rec.extra.update(core, bursts=bursts, amp=amp, x=x, h=h, centre=c, X=X, comp=comp, s_f=s_f, z0=z0, drive=v)
    return rec


@case
def delay_korteweg_water_lines_oesophageal_swallows_457hz(seed):
    rng = _rng(seed, 7)
    dt = 1 / 457
    prog = s37.swallows(rng, rng.uniform(28.0, 40.0))
    while not _fits(dt, prog["T_end"]):
        prog = s37.swallows(rng, rng.uniform(28.0, 40.0))
    t = _grid(dt, prog["T_end"])
    lm = s37.manometry(t, prog)
    top = rng.uniform(88.0, 97.0)
    v = top * lm / lm.max()
    D_e = rng.uniform(6.0, 12.0)                                      # the lines' bore over their wall
    c_w = m37.korteweg_speed(D_e)
    lag = rng.uniform(2.5, 6.0)                                       # samples
    L_line = lag * dt * c_w
    v_late = top * s37.manometry(t - lag * dt, prog) / lm.max()       # the command as it reaches the cells
    core = dict(_foam_pair(rng, unipolar=True), top=top)
    y = _core_of(core, v_late)
    rec = finish("holdout37_delay_korteweg_water_lines_oesophageal_swallows_457hz", seed, t, v, y, {"delay"}, "either",
                 f"the valve's ports reaching the cells through {L_line:.1f} m of water-filled steel line (Korteweg's "
                 f"wave speed {c_w:.0f} m/s: {lag:.2f} samples) under oesophageal swallows ({len(prog['sw'])}), to "
                 f"{top:.0f} V, 457 Hz", rng, monitor_noise=2e-4)
    rec.extra.update(core, prog=prog, top=top, D_e=D_e, c_w=c_w, lag=lag, L_line=L_line, v_late=v_late, drive=v)
    return rec


@case
def initial_state_leak_test_rocking_chair_1035hz(seed):
    rng = _rng(seed, 8)
    dt = 1 / 1035
    amp = rng.uniform(44.0, 48.0)
    core = dict(_foam_pair(rng), amp=amp)
    p_test = core["p_c"] + rng.uniform(1.05, 1.2) * core["dp"]
    hist = m37.leak_test(core["p_c"], p_test)
    state = _port_history_states(core, hist, hist)

    def make():
        prog, T_end = s37.rocking_chair(rng, int(rng.integers(3, 6)))
        if not _fits(dt, T_end):
            return None
        t = _grid(dt, T_end)
        return s37.chair_angle(t, prog), t, prog
    x, t, prog = _balanced(make)
    v = _scale(x, amp)
    y = _core_of(core, v, states=state)
    rec = finish("holdout37_initial_state_leak_test_rocking_chair_1035hz", seed, t, v, y, {"initial_state"},
                 "either",
                 f"a core left by the cells' leak test (both ports raised together to {p_test * 18:.1f} MPa, the "
                 f"preload {core['p_c'] * 18:.1f} MPa, held and lowered back) under a rocking chair "
                 f"({len(prog['pushes'])} pushes), +-{amp:.0f} V, 1.035 kHz", rng)
    rec.extra.update(core, amp=amp, p_test=p_test, hist=hist, state=state, prog=prog, x=x, drive=v)
    return rec


# ---- two effects ----

@case
def pair_delay_initial_state_dac_fifo_bleeding_routine_hiccups_1275hz(seed):
    rng = _rng(seed, 9)
    dt = 1 / 1275
    amp = rng.uniform(44.0, 48.0)
    core = dict(_foam_pair(rng), amp=amp)
    u_b, n_b = rng.uniform(0.7, 0.95), int(rng.integers(3, 7))
    hist = m37.bleeding_routine(u_b, n_b)
    state = _history_states(core, hist)

    def make():
        prog = s37.hiccup_bouts(rng, rng.uniform(20.0, 28.0))
        if not _fits(dt, prog["T_end"]):
            return None
        t = _grid(dt, prog["T_end"])
        return s37.hiccup_flow(t, prog), t, prog
    x, t, prog = _balanced(make)
    v = _scale(x, amp)
    M, phase = int(rng.integers(3, 7)), rng.uniform(0.2, 0.8)
    lag = M + phase
    v_late = amp * s37.hiccup_flow(t - lag * dt, prog) / np.abs(x).max()      # the command as it leaves the DAC
    y = _core_of(core, v_late, states=state)
    rec = finish("holdout37_pair_delay_initial_state_dac_fifo_bleeding_routine_hiccups_1275hz", seed, t, v, y,
                 {"delay", "initial_state"}, "either",
                 f"the drive reaching the valve through the analogue output's FIFO ({M} samples deep, its clock "
                 f"{phase:.2f} of a sample behind: {lag:.2f} samples) and a core left by the installer's bleeding of "
                 f"the lines ({n_b} pulses to {u_b:.2f} of the stroke, alternating) under a bout of hiccups "
                 f"({len(prog['hic'])}), +-{amp:.0f} V, 1.275 kHz", rng)
    rec.extra.update(core, amp=amp, u_bleed=u_b, n_bleed=n_b, hist=hist, state=state, prog=prog, x=x, M=M,
                     phase=phase, lag=lag, v_late=v_late, drive=v)
    return rec


# ---- out of vocabulary ----

@case
def oov_stuck_adc_bit_kettlebell_swings_935hz(seed):
    rng = _rng(seed, 10)
    dt = 1 / 935

    def make():
        times, vals, T_end = s37.kettlebell(rng, int(rng.integers(2, 4)))
        if not _fits(dt, T_end):
            return None
        t = _grid(dt, T_end)
        return s37.through_points(t, times, vals), t, times, vals
    x, t, times, vals = _balanced(make)
    amp = rng.uniform(44.0, 48.0)
    v = _scale(x, amp)
    core = dict(_foam_pair(rng), amp=amp)
    h = _core_of(core, v)
    margin = rng.uniform(0.05, 0.15)
    lo, hi = h.min() - margin * np.ptp(h), h.max() + margin * np.ptp(h)
    k = int(rng.choice([11, 12]))
    off = rng.uniform(-4.0, 4.0)
    y = m37.stuck_bit_reading(h, lo, hi, 16, k) + off
    rec = finish("holdout37_oov_stuck_adc_bit_kettlebell_swings_935hz", seed, t, v, y, set(), "unexplained",
                 f"the rocker's reading digitised by a 16-bit converter whose data bit {k} is stuck high (a cracked "
                 f"bus trace: {2 ** k / 65535 * (hi - lo) / np.ptp(h):.1%} of the span added wherever the bit is 0) "
                 f"under kettlebell swings, +-{amp:.0f} V, 935 Hz", rng)
    rec.extra.update(core, amp=amp, times=times, vals=vals, x=x, h=h, lo=lo, hi=hi, bit=k, offset=off, drive=v)
    return rec

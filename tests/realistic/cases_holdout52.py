"""The HOLDOUT52 set: written after HOLDOUT51 was measured, by a session that did not read how the diagnosis decides,
and run once for round 54's measurement (3 of 30 runs right on commit e91c307); part of ALL since.

Mechanisms and signals that the other sets do not have (the laws are in :mod:`.mechanisms52`, the signals in
:mod:`.signals52`, each beside its source; the citations were written from memory, as they say). Every core is a
thin-film phase-change actuator: a film 10 um thick of silicone (PDMS) holding mesoporous silica nanoparticles whose
pores are filled with a broad-cut technical paraffin, cast on a silicon heater chip on a Peltier module, its top read
by a capacitive gauge (nm, zeroed at the start of every record). The chip's temperature loop sets the film's
temperature from the drive, 0.12 K a volt about the bias (the middle of the pores' loops; on the unipolar records the
drive's 0 V is 5.6 K below it). Each pore's wax melts and freezes at its own Gibbs-Thomson temperatures: it melts when
a liquid sleeve can grow along its wall (curvature 1 / (r - t)) and freezes when the crystal enters from its mouth
through a hemispherical front (curvature 2 / (q r - t)); 6000 classes of pores, their bulk melting points normal
(spread 8.5 ... 9.5 K: the blend fractionated between them), radii log-normal (median 3.8 ... 4.2 nm), necks 0.75 ... 1
of the pore; the film's thickness takes the matrix's and the wax's expansion and the wax's 10 % on melting. Rate
independent, with return-point memory; close to a Prandtl-Ishlinskii model but not one (measured in
tests/test_realistic_holdout52.py: a PI model of 12 plays of the drive fitted by NNLS, stated there). The stroke is
about 0.15 um over +-46 V. Every record but the initial-state case's starts at 0 V of drive from the rest state the
controller's conditioning routine leaves there (a slowly decaying thermal cycling about that temperature: every pore
molten whose loop's middle lies below it, the others frozen; the state is set so, not run), for unipolar and bipolar
records alike; nothing else is run before a record.

- a clean core under a croquet player's mallet (practice swings, the backswing, the stroke, the follow-through, the
  walk to the ball), +-44 ... 48 V, with a noisy input monitor, sampled at 1.447 kHz;
- creep of a silicone button between the film and a valve poppet's spring (Findley's power-law creep compliance, J_0 +
  J_1 t^n, n 0.2 ... 0.3; a Volterra equation of the load path); under a pastry chef's piping bag (rosettes, a long
  border, refills), on a unipolar stroke, sampled at 241 Hz;
- rate dependence from a film cast 25 um thick with coarse silica-gel grains (radius 5.6 ... 6.9 um): the pores' melt
  flows out of each grain by Darcy's law, the grain consolidating as diffusion out of a sphere (tau 0.16 ... 0.24 s);
  under a hang-glider pilot's weight shift (thermalling, roll reversals, rough air: never still), +-44 ... 48 V, with a
  noisy input monitor, sampled at 1.723 kHz;
- a drift from the stage's chilled-water valve sticking (stiction): the water loop's PI controller hunts in a limit
  cycle (some 0.1 K and a minute, a lopsided sawtooth), and the aluminium riser under the chip follows it; under a
  gardener's watering can, on a unipolar stroke, sampled at 223 Hz;
- asymmetry from air voids in an undegassed matrix and the air dissolved in it (Boyle, Charles and Henry), the film's
  cap set just touching a stiff valve seat: the gas gives way under the seat as the film rises and not as it sinks
  from it; under a cook's pepper mill, +-44 ... 48 V, sampled at 883 Hz;
- saturation from the Peltier driver's current limit turned down: below the temperature where the module's cooling
  balances the room's leak the film cannot be cooled (0.55 ... 0.7 of the cold swing); under a focus puller's
  follow-focus wheel, +-44 ... 48 V, with a noisy input monitor, sampled at 997 Hz;
- a delay of a water line from a mixing valve to a water-jacketed stage (0.8 ... 1.3 m at 5 ... 6 m/s: inverse
  Gaussian residence times, 0.13 ... 0.26 s); under a pianist's sustain pedal, on a unipolar stroke, with a noisy input
  monitor, sampled at 509 Hz;
- a film in another state at the start: a night in the freezer (-20 C: every pore frozen that melts above the bias)
  and a straight warm-up to the bias without the conditioning; under a timpanist's pedal (tuning by ear first, then the
  piece's notes and glissandi), +-44 ... 48 V, sampled at 659 Hz;
- two effects: the set point passed through a PLC's scan (read at its scans and written one scan later: a delay of one
  to two scans of 30 ... 45 ms; labelled "delay") and the film read by the chip's electrode through a
  capacitance-to-digital converter (the gap's inverse, g_0 0.3 ... 0.4 um; labelled "asymmetry"); under a bricklayer's
  trowel, +-44 ... 48 V, sampled at 757 Hz;
- out of vocabulary: the gauge replaced by a fibre Fabry-Perot probe read raw, its working point drifted so that the
  fringe's top lies inside the stroke: the reading folds back as the film rises past it; under a ten-pin bowler's
  arm, +-44 ... 48 V, sampled at 1.063 kHz.

Every bipolar drive is drawn until its weaker side reaches 0.85 of its stronger (a test programme's balance). The
effects' sizes beyond a gain and an offset on the core (seeds 0 ... 2; RMS and largest) are stated in the test.
"""

import math

import numpy as np

from . import mechanisms52 as m52
from . import signals52 as s52
from . import set_tools
from .record import case_set, finish
from .set_tools import fine as _fine, scale as _scale

HOLDOUT52, case, _rng = case_set("holdout52_", 52000)


def _film(rng, unipolar=False):
    """The core: the pores' seed (the R2 sequence's shift), the blend's mean bulk melting point T0 (C) and its spread
    between the pores sc (K), the pores' median radius r50 (nm); the bias Tb (C) follows from them."""
    core = dict(rseed=int(rng.integers(0, 2**31 - 2)), T0=rng.uniform(27.5, 28.5), sc=rng.uniform(8.5, 9.5),
                r50=rng.uniform(3.8, 4.2), unipolar=unipolar)
    core["Tb"] = m52.bias(core)
    return core


def _knotted(rng, dt, gen):
    """A balanced bipolar drive from a knot programme gen(rng) -> (knots, T_end)."""
    return set_tools.knotted(rng, dt, gen, s52.knots_at)


def _unipolar(rng, dt, gen):
    return set_tools.unipolar(rng, dt, gen, s52.knots_at)


def _bipolar(rng, dt, gen):
    return set_tools.bipolar(rng, dt, gen, s52.knots_at)


def _note(core):
    return (f"a paraffin-silica film's 6000 pore classes (the blend's T0 {core['T0']:.1f} C +- {core['sc']:.1f} K, "
            f"radii {core['r50']:.1f} nm, biased at {core['Tb']:.1f} C)")


# ---- clean ----

@case
def clean_paraffin_silica_film_croquet_mallet_1447hz(seed):
    """A clean core under a croquet player's mallet, from the rest state at 0 V; nothing else is run before it."""
    rng = _rng(seed, 1)
    dt = 1 / 1447
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s52.croquet_mallet(r, 2))
    core = dict(_film(rng), amp=amp)
    y = m52.core_reading(core, v)
    rec = finish("holdout52_clean_paraffin_silica_film_croquet_mallet_1447hz", seed, t, v, y, set(), "explained",
                 f"a clean core ({_note(core)}) under a croquet player's mallet ({len(kn)} knots), +-{amp:.0f} V, "
                 f"1.447 kHz", rng, monitor_noise=2e-4)
    rec.extra.update(core, knots=kn, x=x, drive=v)
    return rec


# ---- one effect ----

@case
def creep_findley_silicone_button_piping_bag_241hz(seed):
    """A silicone button creeping between the film and a valve poppet's spring under a pastry chef's piping bag
    (unipolar), from the rest state at 0 V (the button long at rest under the preload); nothing else is run before
    it."""
    rng = _rng(seed, 2)
    dt = 1 / 241
    t, kn, p, top, v = _unipolar(rng, dt, lambda r: s52.piping_bag(r, 2))
    core = dict(_film(rng, unipolar=True), top=top)
    c0, c1, nexp = rng.uniform(0.04, 0.07), rng.uniform(0.05, 0.08), rng.uniform(0.2, 0.3)
    d = m52.core_reading(core, v)
    kern = m52.findley_kernel(len(t), dt, c0, c1, nexp)
    y = m52.volterra_creep(d, kern)
    rec = finish("holdout52_creep_findley_silicone_button_piping_bag_241hz", seed, t, v, y, {"creep"}, "either",
                 f"a silicone button creeping under a valve poppet's spring (Findley: k J_0 {c0:.3f}, k J_1 "
                 f"{c1:.3f} s^-{nexp:.2f}) under a pastry chef's piping bag, to {top:.0f} V, 241 Hz", rng)
    rec.extra.update(core, knots=kn, p=p, c0=c0, c1=c1, nexp=nexp, d=d, drive=v)
    return rec


@case
def rate_coarse_grain_melt_flow_hang_glider_1723hz(seed):
    """The pores' melt flowing out of coarse grains under a hang-glider pilot's weight shift, from the rest state at 0 V
    (the grains long settled); nothing else is run before it."""
    rng = _rng(seed, 3)
    dt = 1 / 1723
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s52.hang_glider(r, 1))
    core = dict(_film(rng), amp=amp)
    a_um = rng.uniform(5.6, 6.9)
    tau = (a_um * 1e-6) ** 2 / (math.pi ** 2 * m52.C_FLOW)
    T = m52.temperature(core, v)
    f = m52.liquid_share(core, T)
    e_fix, e_pore = m52.strains(T, f, T[0])
    e_late = m52.grain_flow(e_pore, dt, tau)
    y = m52.reading(T, f, e_late, h=m52.H_COARSE)
    rec = finish("holdout52_rate_coarse_grain_melt_flow_hang_glider_1723hz", seed, t, v, y, {"rate_dependence"},
                 "either",
                 f"the pores' melt flowing out of coarse grains ({a_um:.1f} um: tau {tau * 1e3:.1f} ms) under a "
                 f"hang-glider pilot's weight shift, +-{amp:.0f} V, 1.723 kHz", rng, monitor_noise=3e-4)
    rec.extra.update(core, knots=kn, x=x, a_um=a_um, tau=tau, f=f, drive=v)
    return rec


@case
def drift_chilled_water_valve_stiction_watering_can_223hz(seed):
    """The stage's chilled-water valve hunting (stiction) under a gardener's watering can (unipolar), from the rest
    state at 0 V (the loop long in its limit cycle); nothing else is run before it."""
    rng = _rng(seed, 4)
    dt = 1 / 223
    t, kn, p, top, v = _unipolar(rng, dt, lambda r: s52.watering_can(r, 2))
    core = dict(_film(rng, unipolar=True), top=top)
    tau_w, d_s, d_k = rng.uniform(18.0, 24.0), rng.uniform(0.035, 0.045), rng.uniform(0.008, 0.012)
    tau_b, L_mm = rng.uniform(6.0, 12.0), rng.uniform(8.0, 11.0)
    times, Tw, X = m52.valve_hunting(t[-1], 900.0, tau_w, d_s, d_k)
    drift, T_riser = m52.riser_drift(t, times, Tw, tau_b, L_mm)
    h = m52.core_reading(core, v)
    y = h + drift
    rec = finish("holdout52_drift_chilled_water_valve_stiction_watering_can_223hz", seed, t, v, y, {"drift"}, "either",
                 f"the stage's chilled-water valve hunting (stiction {d_s:.3f} / {d_k:.3f}, the tank's tau "
                 f"{tau_w:.0f} s: the riser {np.ptp(T_riser) * 1e3:.0f} mK over the record) under a gardener's "
                 f"watering can, to {top:.0f} V, 223 Hz", rng)
    rec.extra.update(core, knots=kn, p=p, tau_w=tau_w, d_s=d_s, d_k=d_k, tau_b=tau_b, L_mm=L_mm, T_riser=T_riser, h=h,
                     drive=v)
    return rec


@case
def asymmetry_air_voids_stiff_load_pepper_mill_883hz(seed):
    """Air voids in an undegassed matrix under a stiff load, under a cook's pepper mill, from the rest state at 0 V
    (the gas settled at the load's preload); nothing else is run before it."""
    rng = _rng(seed, 5)
    dt = 1 / 883
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s52.pepper_mill(r, 4))
    core = dict(_film(rng), amp=amp)
    phi_v, L_O, c_um = rng.uniform(0.006, 0.01), rng.uniform(0.10, 0.14), rng.uniform(0.8, 1.2)
    V = (phi_v + L_O * m52.PHI_M) * m52.H_FILM * 1e9
    c = c_um * 1e-3
    T = m52.temperature(core, v)
    D = m52.reading(T, m52.liquid_share(core, T))
    theta = (T + 273.15) / (T[0] + 273.15)
    y = m52.void_contact(D, theta, V, c)
    rec = finish("holdout52_asymmetry_air_voids_stiff_load_pepper_mill_883hz", seed, t, v, y, {"asymmetry"},
                 "either",
                 f"air voids ({phi_v:.1%} of the film, the dissolved air's Ostwald coefficient {L_O:.2f}) under a "
                 f"stiff load ({c_um:.1f} per um of the preload's pressure) under a cook's pepper mill, "
                 f"+-{amp:.0f} V, 883 Hz", rng)
    rec.extra.update(core, knots=kn, x=x, phi_v=phi_v, L_O=L_O, c_um=c_um, V=V, D=D, drive=v)
    return rec


@case
def saturation_peltier_current_limit_focus_puller_997hz(seed):
    """The Peltier driver's current limit turned down under a focus puller's follow-focus wheel, from the rest state at
    0 V; nothing else is run before it."""
    rng = _rng(seed, 6)
    dt = 1 / 997
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s52.focus_puller(r, 1))
    core = dict(_film(rng), amp=amp)
    frac, sink = rng.uniform(0.55, 0.7), rng.uniform(1.0, 2.0)
    T_set = m52.temperature(core, v)
    T_min = core["Tb"] - frac * (core["Tb"] - T_set.min())
    T_h = core["Tb"] - sink
    I_max = m52.peltier_current(T_min, T_h, **m52.PELTIER)
    T = np.maximum(T_set, T_min)
    y = m52.reading(T, m52.liquid_share(core, T))
    rec = finish("holdout52_saturation_peltier_current_limit_focus_puller_997hz", seed, t, v, y, {"saturation"},
                 "either",
                 f"the Peltier driver's current limit at {I_max * 1e3:.0f} mA (the film held above {T_min:.2f} C, "
                 f"{frac:.0%} of the cold swing) under a focus puller's wheel, +-{amp:.0f} V, 997 Hz", rng,
                 monitor_noise=2.5e-4)
    rec.extra.update(core, knots=kn, x=x, frac=frac, T_min=T_min, T_h=T_h, I_max=I_max, drive=v)
    return rec


@case
def delay_mixing_valve_water_line_sustain_pedal_509hz(seed):
    """A water line from a mixing valve to the chip's stage under a pianist's sustain pedal (unipolar), from the rest
    state at 0 V (the line long at the first set point); nothing else is run before it."""
    rng = _rng(seed, 7)
    dt = 1 / 509
    t, kn, p, top, v = _unipolar(rng, dt, lambda r: s52.sustain_pedal(r, 4))
    core = dict(_film(rng, unipolar=True), top=top)
    L, u = rng.uniform(0.8, 1.3), rng.uniform(5.0, 6.0)
    tau_d, pe = L / u, L / (0.2 * 8e-3)
    sub = m52.SUB_LINE
    tf = _fine(t, sub)
    Tf_set = m52.temperature(core, top * s52.knots_at(tf, kn) / p.max())
    Tf = m52.water_line(Tf_set, dt / sub, tau_d, pe)
    T = Tf[::sub]
    y = m52.reading(T, m52.liquid_share(core, T))
    rec = finish("holdout52_delay_mixing_valve_water_line_sustain_pedal_509hz", seed, t, v, y, {"delay"}, "either",
                 f"a water line of {L:.2f} m at {u:.1f} m/s from a mixing valve (tau {tau_d * 1e3:.0f} ms, Pe "
                 f"{pe:.0f}) under a pianist's sustain pedal, to {top:.0f} V, 509 Hz", rng, monitor_noise=3e-4)
    rec.extra.update(core, knots=kn, p=p, L=L, u=u, tau_d=tau_d, pe=pe, T=T, drive=v)
    return rec


@case
def initial_state_freezer_night_timpani_pedal_659hz(seed):
    """A night in the freezer and a straight warm-up to the bias, without the conditioning, under a timpanist's pedal
    (tuning by ear first)."""
    rng = _rng(seed, 8)
    dt = 1 / 659
    amp = rng.uniform(44.0, 48.0)
    core = dict(_film(rng), amp=amp)
    s = m52.freezer_state(core)
    x, t, kn = _knotted(rng, dt, lambda r: s52.timpani_pedal(r, 10))
    v = _scale(x, amp)
    s0 = s.copy()
    y = m52.core_reading(core, v, s)
    n_off = int(np.sum(s0 != m52.rest_state(core, core["Tb"])))
    rec = finish("holdout52_initial_state_freezer_night_timpani_pedal_659hz", seed, t, v, y, {"initial_state"},
                 "either",
                 f"a night in the freezer and a straight warm-up to the bias ({n_off} of {m52.N_PORES} pore classes "
                 f"frozen that the conditioning leaves molten) under a timpanist's pedal, +-{amp:.0f} V, 659 Hz", rng)
    rec.extra.update(core, s0=s0, n_off=n_off, knots=kn, x=x, drive=v)
    return rec


# ---- two effects ----

@case
def pair_delay_asymmetry_plc_scan_cdc_gap_bricklayer_trowel_757hz(seed):
    """The set point through a PLC's scan ("delay") and the film read through a capacitance-to-digital converter
    ("asymmetry") under a bricklayer's trowel, from the rest state at 0 V; nothing else is run before it."""
    rng = _rng(seed, 9)
    dt = 1 / 757
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s52.bricklayer_trowel(r, 5))
    core = dict(_film(rng), amp=amp)
    P, g0 = rng.uniform(0.03, 0.045), rng.uniform(300.0, 400.0)
    phase = rng.uniform(0.0, P)
    xmax = np.abs(x).max()
    v_set, _ = m52.scan_hold(t, P, phase, lambda tt: amp * s52.knots_at(tt, kn) / xmax)
    h_late = m52.core_reading(core, v_set)
    y = m52.cdc_reading(h_late, g0)
    rec = finish("holdout52_pair_delay_asymmetry_plc_scan_cdc_gap_bricklayer_trowel_757hz", seed, t, v, y,
                 {"delay", "asymmetry"}, "either",
                 f"the set point through a PLC's {P * 1e3:.1f} ms scan and the film read through a "
                 f"capacitance-to-digital converter ({g0:.0f} nm gap) under a bricklayer's trowel, +-{amp:.0f} V, "
                 f"757 Hz", rng)
    rec.extra.update(core, knots=kn, x=x, P=P, phase=phase, g0=g0, v_set=v_set, h_late=h_late, drive=v)
    return rec


# ---- out of vocabulary ----

@case
def oov_fabry_perot_fringe_fold_tenpin_bowler_1063hz(seed):
    """A fibre Fabry-Perot probe read raw past its fringe's top under a ten-pin bowler's arm, from the rest state at 0
    V; nothing else is run before it."""
    rng = _rng(seed, 10)
    dt = 1 / 1063
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s52.tenpin_bowler(r, 1))
    core = dict(_film(rng), amp=amp)
    h = m52.core_reading(core, v)
    top_frac = rng.uniform(0.3, 0.45)
    x_top = top_frac * h.max()
    y = m52.fringe_reading(h, x_top)
    rec = finish("holdout52_oov_fabry_perot_fringe_fold_tenpin_bowler_1063hz", seed, t, v, y, set(), "unexplained",
                 f"a fibre Fabry-Perot probe read raw, its fringe's top {x_top:.0f} nm up the stroke (a fold) under a "
                 f"ten-pin bowler's arm, +-{amp:.0f} V, 1.063 kHz", rng)
    rec.extra.update(core, knots=kn, x=x, x_top=x_top, h=h, drive=v)
    return rec

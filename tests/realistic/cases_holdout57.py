"""The HOLDOUT57 set: written after HOLDOUT56 was measured, by a session that did not read how the diagnosis decides,
and run once for round 59's measurement (15 of 30 runs right on commit f34eb11); part of ALL since.

Mechanisms and signals that the other sets do not have (the laws are in :mod:`.mechanisms57`, the signals in
:mod:`.signals57`, each beside its source; the citations were written from memory, as they say). Every core is a
humidity-tuned optical filter: a Bragg mirror on glass of six pairs of a mesoporous silica layer (cage-like pores joined
by narrower windows: ink bottles; impregnated with lithium chloride) and a dense titania layer, in a microcell fed by a
dew-point generator whose dew point follows the drive (the cell's humidity moves by +-0.2 in ln x over +-46 V about the
bias, the middle of the cages' loops; on the unipolar records the drive's 0 V is 0.2 below it in ln x), its reflection
peak read by a spectrometer (nm, zeroed at the start of every record). Each cage fills with capillary solution when the
meniscus inside it becomes unstable (Kelvin with Cohan's spherical meniscus and Raoult's law for its salt: ln x_c = ln
a_w - 2 K / (R - t)) and empties only when the meniscus in its window can recede (ln x_e = ln a_w - 2 K / (q R - t));
6000 classes of cages, radii log-normal (median 4.0 ... 4.6 nm), windows 0.55 ... 0.8 of the cage, the salt's ln a_w
normal (spread 0.25 ... 0.3) apart from the size; the empty cages hold a BET film (c 8 ... 14), the layer's index by the
Lorentz-Lorenz rule and the peak at 2 (n_p h_p + n_t h_t). Rate independent, with return-point memory; close to a
Prandtl-Ishlinskii model but not one (measured in tests/test_realistic_holdout57.py: a PI model of 12 plays of the drive
fitted by NNLS, stated there). The peak moves by some 12 nm over +-46 V. Every record but the initial-state case's
starts at 0 V of drive from the rest state the generator's conditioning leaves there (a slowly decaying cycling of the
dew point about it: every cage filled whose loop's middle sqrt(x_c x_e) lies below its humidity, the others empty; the
state is set so, not run), for unipolar and bipolar records alike; nothing else is run before a record (but the
out-of-vocabulary case's pump).

- a clean core under an orchestra's cymbal player (rests, crashes, the plates held up to ring and choked), +-44 ... 48
  V, with a noisy input monitor, sampled at 1.571 kHz;
- creep of the cell's humidity from its PMMA walls and polyurethane lines taking water into solution and giving it back
  (a semi-infinite wall's uptake: an Abel kernel, beta t^(-1/2), beta 0.05 ... 0.08 s^(1/2)); under a letterpress
  printer's impression lever, on a unipolar stroke, sampled at 263 Hz;
- rate dependence from a larger, well-mixed flow cell (2 ... 3.5 ml at 1 l/min: tau 0.12 ... 0.21 s); under a bongo
  player's hands (never still), +-44 ... 48 V, with a noisy input monitor, sampled at 1.831 kHz;
- a drift from the room's on-off thermostat: the cell's block follows the air's limit cycle (a dead band of 1.0 ... 1.4
  K), and the generator's fixed vapour pressure makes another humidity at every temperature; under a bartender's soda
  siphon, on a unipolar stroke, sampled at 211 Hz;
- asymmetry from edge interrogation: a fixed laser on the peak's flank (a Lorentzian of half-width 12 ... 15 nm, the
  laser beyond the flank's inflection) read by its reflected power; under a bodhran player's tipper, +-44 ... 48 V,
  sampled at 937 Hz;
- saturation from a cold fitting on the line: above its temperature (0.55 ... 0.7 of the dew point's upper swing) the
  vapour condenses there and the cell's dew point stops; under a bulldozer driver's blade lever, +-44 ... 48 V, with a
  noisy input monitor, sampled at 1.093 kHz;
- a delay from the spectrometer's frames (25 ... 35 a second, each integrating over its period) and its software's
  latency (3 ... 5 frames), held between frames; under a TIG welder's pedal, on a unipolar stroke, with a noisy input
  monitor, sampled at 541 Hz;
- a mirror in another state at the start: a night in a humid box (every cage filled) and a direct step down to the
  bias without the conditioning; under a surveyor's theodolite (levelling first, then the round of targets), +-44 ...
  48 V, sampled at 701 Hz;
- two effects: the walls' micropores taking water slowly (Dubinin-Radushkevich's uptake reached by diffusion into a
  slab, tau 6 ... 12 s; labelled "creep") and a two-stream generator setting the humidity linear in the drive where the
  dew point's is exponential (labelled "asymmetry"); under a trombonist's slide, +-44 ... 48 V, sampled at 811 Hz;
- out of vocabulary: a diaphragm pump's pulsation of the cell's pressure (1.2 ... 1.8 %, 4.5 ... 6 Hz) ripples the
  humidity, and the cages trace minor loops at the pump's rate; under a stage fight's sword arm, +-44 ... 48 V, sampled
  at 1.223 kHz.

Every bipolar drive is drawn until its weaker side reaches 0.85 of its stronger (a test programme's balance). The
effects' sizes beyond a gain and an offset on the core (seeds 0 ... 2; RMS and largest) are stated in the test.
"""

import math

import numpy as np

from . import mechanisms57 as m57
from . import signals57 as s57
from . import set_tools
from .record import case_set, finish
from .set_tools import scale as _scale

HOLDOUT57, case, _rng = case_set("holdout57_", 57000)


def _mirror(rng, unipolar=False):
    """The core: the cages' seed (the lattices' shifts and the salt's shuffle), their median radius R50 (nm), the salt's
    spread sa (in ln a_w) and the BET constant c_bet; the bias (x_b, its dew point T_d0 and the dew point's slope k_d)
    follows from them."""
    core = dict(rseed=int(rng.integers(0, 2**31 - 2)), R50=rng.uniform(4.0, 4.6), sa=rng.uniform(0.25, 0.3),
                c_bet=rng.uniform(8.0, 14.0), unipolar=unipolar)
    core["xb"], core["Td0"], core["kd"] = m57.bias(core)
    return core


def _knotted(rng, dt, gen):
    """A balanced bipolar drive from a knot programme gen(rng) -> (knots, T_end)."""
    return set_tools.knotted(rng, dt, gen, s57.knots_at)


def _unipolar(rng, dt, gen):
    return set_tools.unipolar(rng, dt, gen, s57.knots_at)


def _bipolar(rng, dt, gen):
    return set_tools.bipolar(rng, dt, gen, s57.knots_at)


def _note(core):
    return (f"a salted mesoporous Bragg mirror's 6000 cage classes (radii {core['R50']:.1f} nm, the salt's spread "
            f"{core['sa']:.2f} in ln a_w, BET c {core['c_bet']:.0f}; biased at x {core['xb']:.3f})")


# ---- clean ----

@case
def clean_salted_cage_bragg_mirror_cymbal_player_1571hz(seed):
    """A clean core under an orchestra's cymbal player, from the rest state at 0 V; nothing else is run before it."""
    rng = _rng(seed, 1)
    dt = 1 / 1571
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s57.cymbal_player(r, 1))
    core = dict(_mirror(rng), amp=amp)
    y = m57.core_reading(core, v)
    rec = finish("holdout57_clean_salted_cage_bragg_mirror_cymbal_player_1571hz", seed, t, v, y, set(), "explained",
                 f"a clean core ({_note(core)}) under a cymbal player ({len(kn)} knots), +-{amp:.0f} V, 1.571 kHz",
                 rng, monitor_noise=2e-4)
    rec.extra.update(core, knots=kn, x=x, drive=v)
    return rec


# ---- one effect ----

@case
def creep_pmma_cell_wall_uptake_letterpress_263hz(seed):
    """The cell's PMMA walls and lines buffering its water under a letterpress printer's lever (unipolar), from the rest
    state at 0 V (the walls long at its humidity); nothing else is run before it."""
    rng = _rng(seed, 2)
    dt = 1 / 263
    t, kn, p, top, v = _unipolar(rng, dt, lambda r: s57.letterpress(r, 9))
    core = dict(_mirror(rng, unipolar=True), top=top)
    beta = rng.uniform(0.05, 0.08)
    x_in = m57.humidity(core, v)
    x_cell = m57.wall_buffer(x_in, dt, beta)
    y = m57.core_at(core, x_cell)
    rec = finish("holdout57_creep_pmma_cell_wall_uptake_letterpress_263hz", seed, t, v, y, {"creep"}, "either",
                 f"the cell's PMMA walls taking up and giving back water (beta {beta:.3f} s^1/2) under a letterpress "
                 f"printer's lever, to {top:.0f} V, 263 Hz", rng)
    rec.extra.update(core, knots=kn, p=p, beta=beta, x_in=x_in, x_cell=x_cell, drive=v)
    return rec


@case
def rate_stirred_flow_cell_bongo_player_1831hz(seed):
    """A larger, well-mixed flow cell under a bongo player's hands, from the rest state at 0 V (the cell long at its
    humidity); nothing else is run before it."""
    rng = _rng(seed, 3)
    dt = 1 / 1831
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s57.bongo_player(r, 3))
    core = dict(_mirror(rng), amp=amp)
    vol_ml = rng.uniform(2.0, 3.5)
    tau = vol_ml / (1000.0 / 60.0)
    x_cell = m57.cell_mixing(t, m57.humidity(core, v), tau)
    y = m57.core_at(core, x_cell)
    rec = finish("holdout57_rate_stirred_flow_cell_bongo_player_1831hz", seed, t, v, y, {"rate_dependence"}, "either",
                 f"a stirred flow cell of {vol_ml:.1f} ml at 1 l/min (tau {tau * 1e3:.0f} ms) under a bongo player's "
                 f"hands, +-{amp:.0f} V, 1.831 kHz", rng, monitor_noise=3e-4)
    rec.extra.update(core, knots=kn, x=x, vol_ml=vol_ml, tau=tau, x_cell=x_cell, drive=v)
    return rec


@case
def drift_thermostat_cycle_cell_block_soda_siphon_211hz(seed):
    """The room's on-off thermostat cycling the cell's block under a bartender's soda siphon (unipolar), from the rest
    state at 0 V (the room long in its cycle); nothing else is run before it."""
    rng = _rng(seed, 4)
    dt = 1 / 211
    t, kn, p, top, v = _unipolar(rng, dt, lambda r: s57.soda_siphon(r, 3))
    core = dict(_mirror(rng, unipolar=True), top=top)
    db, tau_r, tau_b = rng.uniform(1.0, 1.4), rng.uniform(80.0, 120.0), rng.uniform(10.0, 20.0)
    times, Ta = m57.thermostat_air(t[-1], 600.0, m57.T_CELL, db, tau_r)
    T_c = m57.cell_temperature(t, times, Ta, tau_b)
    x_cell = m57.humidity(core, v, T_c)
    y = m57.core_at(core, x_cell)
    rec = finish("holdout57_drift_thermostat_cycle_cell_block_soda_siphon_211hz", seed, t, v, y, {"drift"}, "either",
                 f"the room's thermostat cycling (dead band {db:.2f} K, the air's tau {tau_r:.0f} s, the block's "
                 f"{tau_b:.0f} s: the cell {np.ptp(T_c) * 1e3:.0f} mK over the record) under a bartender's soda "
                 f"siphon, to {top:.0f} V, 211 Hz", rng)
    rec.extra.update(core, knots=kn, p=p, db=db, tau_r=tau_r, tau_b=tau_b, T_c=T_c, x_cell=x_cell, drive=v)
    return rec


@case
def asymmetry_edge_interrogation_flank_bodhran_tipper_937hz(seed):
    """The peak read on its flank by a fixed laser under a bodhran player's tipper, from the rest state at 0 V; nothing
    else is run before it."""
    rng = _rng(seed, 5)
    dt = 1 / 937
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s57.bodhran_tipper(r, 4))
    core = dict(_mirror(rng), amp=amp)
    w = rng.uniform(12.0, 15.0)
    delta0 = rng.uniform(1.1, 1.3) * w
    h = m57.core_reading(core, v)
    y = m57.flank_reading(h, w, delta0)
    rec = finish("holdout57_asymmetry_edge_interrogation_flank_bodhran_tipper_937hz", seed, t, v, y, {"asymmetry"},
                 "either",
                 f"the peak read on its flank (half-width {w:.1f} nm, the laser {delta0:.1f} nm beyond the peak) "
                 f"under a bodhran player's tipper, +-{amp:.0f} V, 937 Hz", rng)
    rec.extra.update(core, knots=kn, x=x, w=w, delta0=delta0, h=h, drive=v)
    return rec


@case
def saturation_cold_fitting_condensation_bulldozer_blade_1093hz(seed):
    """A cold fitting on the line condensing the vapour above its temperature under a bulldozer driver's blade lever,
    from the rest state at 0 V; nothing else is run before it."""
    rng = _rng(seed, 6)
    dt = 1 / 1093
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s57.bulldozer_blade(r, 2))
    core = dict(_mirror(rng), amp=amp)
    frac = rng.uniform(0.55, 0.7)
    T_d = m57.dew_point(core, v)
    T_cold = core["Td0"] + frac * (T_d.max() - core["Td0"])
    x_cell = m57.magnus(np.minimum(T_d, T_cold)) / m57.magnus(m57.T_CELL)
    y = m57.core_at(core, x_cell)
    rec = finish("holdout57_saturation_cold_fitting_condensation_bulldozer_blade_1093hz", seed, t, v, y,
                 {"saturation"}, "either",
                 f"a cold fitting at {T_cold:.2f} C on the line ({frac:.0%} of the dew point's upper swing) under a "
                 f"bulldozer driver's blade lever, +-{amp:.0f} V, 1.093 kHz", rng, monitor_noise=2.5e-4)
    rec.extra.update(core, knots=kn, x=x, frac=frac, T_cold=T_cold, x_cell=x_cell, drive=v)
    return rec


@case
def delay_spectrometer_frames_latency_welding_pedal_541hz(seed):
    """The spectrometer's frames and its software's latency under a TIG welder's pedal (unipolar), from the rest state
    at 0 V (the spectrometer running before); nothing else is run before it."""
    rng = _rng(seed, 7)
    dt = 1 / 541
    t, kn, p, top, v = _unipolar(rng, dt, lambda r: s57.welding_pedal(r, 4))
    core = dict(_mirror(rng, unipolar=True), top=top)
    fps, n_lat = rng.uniform(25.0, 35.0), int(rng.integers(3, 6))
    phase = rng.uniform(0.0, 1.0 / fps)
    tf = set_tools.fine(t, m57.SUB_SPEC)
    d_fine = m57.core_reading(core, top * s57.knots_at(tf, kn) / p.max())
    y, tk, vals = m57.spectrometer_frames(t, d_fine, dt / m57.SUB_SPEC, fps, phase, n_lat)
    rec = finish("holdout57_delay_spectrometer_frames_latency_welding_pedal_541hz", seed, t, v, y, {"delay"}, "either",
                 f"a spectrometer at {fps:.1f} frames a second read {n_lat} frames late (latency "
                 f"{(n_lat + 0.5) / fps * 1e3:.0f} ms) under a TIG welder's pedal, to {top:.0f} V, 541 Hz", rng,
                 monitor_noise=3e-4)
    rec.extra.update(core, knots=kn, p=p, fps=fps, n_lat=n_lat, phase=phase, tk=tk, vals=vals, drive=v)
    return rec


@case
def initial_state_humid_box_night_theodolite_701hz(seed):
    """A night in a humid box and a direct step down to the bias, without the conditioning, under a surveyor's
    theodolite (levelling first)."""
    rng = _rng(seed, 8)
    dt = 1 / 701
    amp = rng.uniform(44.0, 48.0)
    core = dict(_mirror(rng), amp=amp)
    x0 = float(m57.humidity(core, 0.0))
    s = m57.humid_box_state(core, x0)
    x, t, kn = _knotted(rng, dt, lambda r: s57.theodolite(r, 5))
    v = _scale(x, amp)
    s0 = s.copy()
    y = m57.core_reading(core, v, s)
    n_off = int(np.sum(s0 != m57.rest_state(core, x0)))
    rec = finish("holdout57_initial_state_humid_box_night_theodolite_701hz", seed, t, v, y, {"initial_state"},
                 "either",
                 f"a night in a humid box and a direct step down to the bias ({n_off} of {m57.N_CAGES} cage classes "
                 f"filled that the conditioning leaves empty) under a surveyor's theodolite, +-{amp:.0f} V, 701 Hz",
                 rng)
    rec.extra.update(core, s0=s0, n_off=n_off, knots=kn, x=x, drive=v)
    return rec


# ---- two effects ----

@case
def pair_creep_asymmetry_wall_micropores_two_stream_trombone_slide_811hz(seed):
    """The walls' micropores taking water slowly ("creep") and a two-stream generator's humidity linear in the drive
    ("asymmetry") under a trombonist's slide, from the rest state at 0 V (the walls long at its humidity); nothing else
    is run before it."""
    rng = _rng(seed, 9)
    dt = 1 / 811
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s57.trombone_slide(r, 2))
    core = dict(_mirror(rng), amp=amp)
    tau, w_max, b_d = rng.uniform(6.0, 12.0), rng.uniform(0.14, 0.18), rng.uniform(0.9, 1.1)
    x_mix = m57.mixer_humidity(core, v)
    F = m57.filled_shares(core, x_mix)
    walls = m57.wall_water(x_mix, dt, tau, w_max, b_d)
    y = m57.reading(core, x_mix, F, walls)
    rec = finish("holdout57_pair_creep_asymmetry_wall_micropores_two_stream_trombone_slide_811hz", seed, t, v, y,
                 {"creep", "asymmetry"}, "either",
                 f"the walls' micropores taking water slowly (w_max {w_max:.2f}, b_D {b_d:.2f}, tau {tau:.1f} s) and "
                 f"a two-stream generator's humidity linear in the drive under a trombonist's slide, +-{amp:.0f} V, "
                 f"811 Hz", rng)
    rec.extra.update(core, knots=kn, x=x, tau=tau, w_max=w_max, b_d=b_d, x_mix=x_mix, walls=walls, drive=v)
    return rec


# ---- out of vocabulary ----

@case
def oov_pump_pulsation_ripple_stage_combat_1223hz(seed):
    """A diaphragm pump's pulsation rippling the cell's humidity under a stage fight's sword arm, from the rest state at
    0 V with the pump running 2 s before the record."""
    rng = _rng(seed, 10)
    dt = 1 / 1223
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s57.stage_combat(r, 2))
    core = dict(_mirror(rng), amp=amp)
    m_p, f_p, ph = rng.uniform(0.012, 0.018), rng.uniform(4.5, 6.0), rng.uniform(0.0, 2.0 * math.pi)
    x0 = float(m57.humidity(core, 0.0))
    t_pre = np.arange(-int(round(2.0 / dt)), 0) * dt
    s = m57.rest_state(core, x0)
    m57.filled_shares(core, m57.pump_ripple(t_pre, np.full(len(t_pre), x0), m_p, f_p, ph), s)
    s_start = s.copy()
    x_cell = m57.pump_ripple(t, m57.humidity(core, v), m_p, f_p, ph)
    y = m57.core_at(core, x_cell, s)
    rec = finish("holdout57_oov_pump_pulsation_ripple_stage_combat_1223hz", seed, t, v, y, set(), "unexplained",
                 f"a diaphragm pump's pulsation ({m_p:.1%} of the cell's pressure at {f_p:.1f} Hz) rippling the "
                 f"humidity under a stage fight's sword arm, +-{amp:.0f} V, 1.223 kHz", rng)
    rec.extra.update(core, knots=kn, x=x, m_p=m_p, f_p=f_p, ph=ph, s_start=s_start, x_cell=x_cell, drive=v)
    return rec

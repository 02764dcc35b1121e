"""The HOLDOUT59 set: written after HOLDOUT58 was measured, by a session that did not read how the diagnosis decides,
and run once for round 61's measurement (20 of 30 runs right on commit 7e9d9ce); part of ALL since.

Mechanisms and signals that the other sets do not have (the laws are in :mod:`.mechanisms59`, the signals in
:mod:`.signals59`, each beside its source; the citations were written from memory, as they say). Every core is a
thermoresponsive hydrogel film actuator: a film 1 um thick of PNIPAM microgels packed in a loose polyacrylamide matrix
on a silicon chip with a platinum heater under a water bath, its top read by a heterodyne interferometer (nm, zeroed
at the start of every record). The chip's temperature loop sets the film's temperature from the drive, 0.13 K a volt
about the bias (the middle of the microgels' loops; on the unipolar records the drive's 0 V is 6 K below it). Each
microgel collapses in its volume phase transition when heated past its T_c and swells again only when cooled some
degrees below it (the collapsed globule's hydrogen bonds): 8000 classes of microgels, their T_c normal (spread 8.5 ...
9.5 K: a blend of copolymer batches), their loops' widths log-normal about 1.4 ... 1.8 K and a little wider for the
lower T_c; a swollen microgel deswells a little ahead of its transition (a pre-transitional deswelling), a
collapsed one keeps 0.22 of its volume; the film clamped sideways, its volume change its thickness's. Rate
independent, with return-point memory; close to a Prandtl-Ishlinskii model but not one (measured in
tests/test_realistic_holdout59.py: a PI model of 12 plays of the drive fitted by NNLS, stated there). The stroke is
about 0.1 um over +-46 V. Every record but the initial-state case's starts at 0 V of drive from the rest state the
controller's conditioning routine leaves there (a slowly decaying thermal cycling about that temperature: every
microgel collapsed whose loop's middle lies below it, the others swollen; the state is set so, not run), for unipolar
and bipolar records alike; nothing else is run before a record.

- a clean core under a glassblower rolling the blowpipe on the bench's rails, +-44 ... 48 V, with a noisy input
  monitor, sampled at 1.381 kHz;
- creep of an UHMW-PE foot between the film and a pushrod's return spring (a stretched-exponential creep compliance,
  J_0 + J_1 (1 - exp(-(t / tau)^b)), b 0.35 ... 0.5, tau 4 ... 10 s; a Volterra equation of the load path); under a
  printer's letterpress impression lever, on a unipolar stroke, sampled at 263 Hz;
- rate dependence from a film cast 6 ... 8 um thick: its water flows through it to the bath as Tanaka and Fillmore's
  collective diffusion in a slab (tau_1 0.15 ... 0.26 s); under a juggler's hand (a cascade and flourishes: never
  still), +-44 ... 48 V, with a noisy input monitor, sampled at 1.907 kHz;
- a drift from the bath topped up with tap water: the matrix's sodium exchanging for calcium (first order, tau_x 60
  ... 120 s), the matrix deswelling; under a bookbinder's nipping press, on a unipolar stroke, sampled at 211 Hz;
- asymmetry from the loop's NTC thermistor converted by a straight line through the bias (its beta law, B 4000 ...
  4700 K): the film hotter than asked above the bias and less cold than asked below it; under a table-tennis player's
  bat, +-44 ... 48 V, sampled at 827 Hz;
- saturation from the heater's supply at a low compliance voltage: above the temperature where the platinum heater's
  full power balances the chip's loss to the bath the film cannot be heated (0.6 ... 0.75 of the swing); under a
  dentist's drill foot control, on a unipolar stroke, with a noisy input monitor, sampled at 379 Hz;
- a delay of the set point in a USB box's output queue (120 ... 260 samples at 1 kHz, held); under a ship's
  engine-order telegraph, +-44 ... 48 V, with a noisy input monitor, sampled at 613 Hz;
- a film in another state at the start: a night on a hot plate at 45 C (every microgel collapsed whose T_c lies below
  it) and a straight cooling to the bias without the conditioning; under a sound engineer's pan pot (the channel
  checked in the middle first, then the mix's pans), +-44 ... 48 V, sampled at 547 Hz;
- two effects: the pushrod's foot a nylon-6 pad creeping as the logarithm of time (J_0 + J_1 ln(1 + t / tau_0);
  labelled "creep") and the interferometer's air path read through the room's pressure as a gale buffets the
  building (Edlen's index; labelled "drift"); under a signalman's points lever, +-44 ... 48 V, sampled at 293 Hz;
- out of vocabulary: the film read by a laser diode's reflectance off the film on its chip taken raw as a thickness,
  a fringe's extremum inside the stroke: the reading folds back past it; under a windsurfer's boom, +-44 ... 48 V,
  sampled at 1.151 kHz.

Every bipolar drive is drawn until its weaker side reaches 0.85 of its stronger (a test programme's balance). The
effects' sizes beyond a gain and an offset on the core (seeds 0 ... 2; RMS and largest) are stated in the test.
"""

import numpy as np

from . import mechanisms59 as m59
from . import signals59 as s59
from . import set_tools
from .record import case_set, finish
from .set_tools import scale as _scale

HOLDOUT59, case, _rng = case_set("holdout59_", 59000)


def _film(rng, unipolar=False):
    """The core: the microgels' seed (their widths' shuffle), the mean transition temperature T0 (C), its spread sc (K)
    and the loops' width w0 (K); the bias Tb (C) follows from them."""
    core = dict(dseed=int(rng.integers(0, 2**31 - 2)), T0=rng.uniform(32.0, 33.0), sc=rng.uniform(8.5, 9.5),
                w0=rng.uniform(1.4, 1.8), unipolar=unipolar)
    core["Tb"] = m59.bias(core)
    return core


def _bipolar(rng, dt, gen):
    """A balanced bipolar drive from a knot programme gen(rng) -> (knots, T_end), scaled to 44 ... 48 V."""
    return set_tools.bipolar(rng, dt, gen, s59.knots_at)


def _unipolar(rng, dt, gen):
    return set_tools.unipolar(rng, dt, gen, s59.knots_at)


def _note(core):
    return (f"a PNIPAM microgel film's {m59.N_DOM} classes (T_c {core['T0']:.1f} C +- {core['sc']:.1f} K, loops "
            f"{core['w0']:.1f} K wide, biased at {core['Tb']:.1f} C)")


# ---- clean ----

@case
def clean_pnipam_microgel_film_glassblower_pipe_1381hz(seed):
    """A clean core under a glassblower's blowpipe, from the rest state at 0 V; nothing else is run before it."""
    rng = _rng(seed, 1)
    dt = 1 / 1381
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s59.glassblower_pipe(r, 2))
    core = dict(_film(rng), amp=amp)
    y = m59.core_reading(core, v)
    rec = finish("holdout59_clean_pnipam_microgel_film_glassblower_pipe_1381hz", seed, t, v, y, set(), "explained",
                 f"a clean core ({_note(core)}) under a glassblower's blowpipe ({len(kn)} knots), +-{amp:.0f} V, "
                 f"1.381 kHz", rng, monitor_noise=2e-4)
    rec.extra.update(core, knots=kn, x=x, drive=v)
    return rec


# ---- one effect ----

@case
def creep_kww_uhmwpe_foot_letterpress_lever_263hz(seed):
    """An UHMW-PE foot creeping between the film and a pushrod's spring under a printer's letterpress lever (unipolar),
    from the rest state at 0 V (the foot long at rest under the preload); nothing else is run before it."""
    rng = _rng(seed, 2)
    dt = 1 / 263
    t, kn, p, top, v = _unipolar(rng, dt, lambda r: s59.letterpress_lever(r, 2))
    core = dict(_film(rng, unipolar=True), top=top)
    c0, c1 = rng.uniform(0.03, 0.06), rng.uniform(0.2, 0.28)
    tau, b = rng.uniform(4.0, 10.0), rng.uniform(0.35, 0.5)
    d = m59.core_reading(core, v)
    kern = m59.kww_kernel(len(t), dt, c0, c1, tau, b)
    y = m59.creep_reading(d, kern)
    rec = finish("holdout59_creep_kww_uhmwpe_foot_letterpress_lever_263hz", seed, t, v, y, {"creep"}, "either",
                 f"an UHMW-PE foot creeping under a pushrod's spring (KWW: k J_0 {c0:.3f}, k J_1 {c1:.3f}, tau "
                 f"{tau:.1f} s, b {b:.2f}) under a letterpress lever, to {top:.0f} V, 263 Hz", rng)
    rec.extra.update(core, knots=kn, p=p, c0=c0, c1=c1, tau=tau, b=b, d=d, drive=v)
    return rec


@case
def rate_tanaka_fillmore_thick_film_juggler_hand_1907hz(seed):
    """A film cast thick, its water flowing through it, under a juggler's hand, from the rest state at 0 V (the film
    long settled); nothing else is run before it."""
    rng = _rng(seed, 3)
    dt = 1 / 1907
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s59.juggler_hand(r, 1))
    core = dict(_film(rng), amp=amp)
    L_um = rng.uniform(6.0, 8.0)
    tau1 = 4 * (L_um * 1e-6) ** 2 / (np.pi ** 2 * m59.D_COOP)
    T = m59.temperature(core, v)
    q = m59.volume_share(core, T)
    h_eq = m59.reading(T, q, h=L_um * 1e3)
    y = m59.slab_kinetics(t, h_eq, tau1)
    rec = finish("holdout59_rate_tanaka_fillmore_thick_film_juggler_hand_1907hz", seed, t, v, y, {"rate_dependence"},
                 "either",
                 f"a film cast {L_um:.1f} um thick, its water flowing through it (tau_1 {tau1 * 1e3:.0f} ms) under a "
                 f"juggler's hand, +-{amp:.0f} V, 1.907 kHz", rng, monitor_noise=3e-4)
    rec.extra.update(core, knots=kn, x=x, L_um=L_um, tau1=tau1, h_eq=h_eq, drive=v)
    return rec


@case
def drift_calcium_ion_exchange_nipping_press_211hz(seed):
    """The bath topped up with tap water, the matrix exchanging its sodium for calcium, under a bookbinder's nipping
    press (unipolar), from the rest state at 0 V; nothing else is run before it."""
    rng = _rng(seed, 4)
    dt = 1 / 211
    t, kn, p, top, v = _unipolar(rng, dt, lambda r: s59.nipping_press(r, 4))
    core = dict(_film(rng, unipolar=True), top=top)
    t0, tau_x, e_x = rng.uniform(20.0, 60.0), rng.uniform(60.0, 120.0), rng.uniform(0.04, 0.06)
    h = m59.core_reading(core, v)
    drift = m59.exchange_drift(t, t0, tau_x, e_x)
    y = h + drift
    rec = finish("holdout59_drift_calcium_ion_exchange_nipping_press_211hz", seed, t, v, y, {"drift"}, "either",
                 f"the matrix exchanging its sodium for the tap water's calcium (begun {t0:.0f} s before, tau "
                 f"{tau_x:.0f} s, {e_x:.1%} of the film on full exchange: {np.ptp(drift):.0f} nm over the record) "
                 f"under a bookbinder's nipping press, to {top:.0f} V, 211 Hz", rng)
    rec.extra.update(core, knots=kn, p=p, t0=t0, tau_x=tau_x, e_x=e_x, h=h, drive=v)
    return rec


@case
def asymmetry_ntc_thermistor_linearised_table_tennis_bat_827hz(seed):
    """The loop's thermistor converted by a straight line through the bias, under a table-tennis player's bat, from
    the rest state at 0 V; nothing else is run before it."""
    rng = _rng(seed, 5)
    dt = 1 / 827
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s59.table_tennis_bat(r, 3))
    core = dict(_film(rng), amp=amp)
    B = rng.uniform(4000.0, 4700.0)
    T_set = m59.temperature(core, v)
    T = m59.thermistor_temperature(T_set, core["Tb"], B)
    y = m59.reading(T, m59.volume_share(core, T))
    rec = finish("holdout59_asymmetry_ntc_thermistor_linearised_table_tennis_bat_827hz", seed, t, v, y, {"asymmetry"},
                 "either",
                 f"the loop's NTC thermistor (B {B:.0f} K) converted by a straight line through the bias (the film "
                 f"{T.max() - T_set.max():+.2f} K at the hot end, {T.min() - T_set.min():+.2f} K at the cold) under a "
                 f"table-tennis player's bat, +-{amp:.0f} V, 827 Hz", rng)
    rec.extra.update(core, knots=kn, x=x, B=B, T=T, drive=v)
    return rec


@case
def saturation_heater_supply_compliance_dental_foot_control_379hz(seed):
    """The heater's supply at a low compliance voltage under a dentist's drill foot control (unipolar), from the rest
    state at 0 V; nothing else is run before it."""
    rng = _rng(seed, 6)
    dt = 1 / 379
    t, kn, p, top, v = _unipolar(rng, dt, lambda r: s59.dental_foot_control(r, 2))
    core = dict(_film(rng, unipolar=True), top=top)
    frac = rng.uniform(0.6, 0.75)
    T_set = m59.temperature(core, v)
    T_max = T_set.min() + frac * (T_set.max() - T_set.min())
    T_w = core["Tb"] - m59.T_W_BELOW
    V_s = m59.supply_voltage(T_max, T_w)
    T = np.minimum(T_set, T_max)
    y = m59.reading(T, m59.volume_share(core, T))
    rec = finish("holdout59_saturation_heater_supply_compliance_dental_foot_control_379hz", seed, t, v, y,
                 {"saturation"}, "either",
                 f"the heater's supply at {V_s:.2f} V (the film held below {T_max:.2f} C, {frac:.0%} of the swing) "
                 f"under a dentist's foot control, to {top:.0f} V, 379 Hz", rng, monitor_noise=2.5e-4)
    rec.extra.update(core, knots=kn, p=p, frac=frac, T_max=T_max, T_w=T_w, V_s=V_s, drive=v)
    return rec


@case
def delay_dac_output_queue_engine_telegraph_613hz(seed):
    """The set point through a USB box's output queue under a ship's engine-order telegraph, from the rest state at 0
    V (the queue full of zeros); nothing else is run before it."""
    rng = _rng(seed, 7)
    dt = 1 / 613
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s59.engine_telegraph(r, 9))
    core = dict(_film(rng), amp=amp)
    n_b = int(rng.integers(120, 261))
    xmax = np.abs(x).max()
    v_set = m59.dac_queue(t, n_b, lambda tt: amp * s59.knots_at(tt, kn) / xmax)
    y = m59.core_reading(core, v_set)
    rec = finish("holdout59_delay_dac_output_queue_engine_telegraph_613hz", seed, t, v, y, {"delay"}, "either",
                 f"the set point through a USB box's output queue ({n_b} samples at 1 kHz: {n_b} ms) under a ship's "
                 f"engine-order telegraph, +-{amp:.0f} V, 613 Hz", rng, monitor_noise=3e-4)
    rec.extra.update(core, knots=kn, x=x, n_b=n_b, v_set=v_set, drive=v)
    return rec


@case
def initial_state_hot_night_pan_pot_547hz(seed):
    """A night at 45 C and a straight cooling to the bias, without the conditioning, under a sound engineer's pan pot
    (the channel checked in the middle first)."""
    rng = _rng(seed, 8)
    dt = 1 / 547
    amp = rng.uniform(44.0, 48.0)
    core = dict(_film(rng), amp=amp)
    c = m59.hot_state(core)
    x, t, kn = set_tools.knotted(rng, dt, lambda r: s59.pan_pot(r, 12), s59.knots_at)
    v = _scale(x, amp)
    c0 = c.copy()
    y = m59.core_reading(core, v, c)
    n_off = int(np.sum(c0 != m59.rest_state(core, core["Tb"])))
    rec = finish("holdout59_initial_state_hot_night_pan_pot_547hz", seed, t, v, y, {"initial_state"}, "either",
                 f"a night at 45 C and a straight cooling to the bias ({n_off} of {m59.N_DOM} microgel classes "
                 f"collapsed that the conditioning leaves swollen) under a sound engineer's pan pot, +-{amp:.0f} V, "
                 f"547 Hz", rng)
    rec.extra.update(core, c0=c0, n_off=n_off, knots=kn, x=x, drive=v)
    return rec


# ---- two effects ----

@case
def pair_creep_drift_nylon_pad_gale_air_path_points_lever_293hz(seed):
    """A nylon pad creeping under the pushrod ("creep") and the interferometer's air path read through a gale's
    buffeting of the building ("drift") under a signalman's points lever, from the rest state at 0 V (the pad long at
    rest, the gale long blowing); nothing else is run before it."""
    rng = _rng(seed, 9)
    dt = 1 / 293
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s59.points_lever(r, 4))
    core = dict(_film(rng), amp=amp)
    c0, c1, tau0 = rng.uniform(0.03, 0.06), rng.uniform(0.045, 0.06), rng.uniform(0.2, 0.5)
    U, I, gseed = rng.uniform(14.0, 18.0), rng.uniform(0.15, 0.2), int(rng.integers(0, 2**31 - 2))
    tau_l, l_mm = rng.uniform(15.0, 30.0), rng.uniform(100.0, 150.0)
    d = m59.core_reading(core, v)
    kern = m59.log_kernel(len(t), dt, c0, c1, tau0)
    crept = m59.creep_reading(d, kern)
    drift, p_room = m59.gale_drift(t, U, I, gseed, tau_l, l_mm)
    y = crept + drift
    rec = finish("holdout59_pair_creep_drift_nylon_pad_gale_air_path_points_lever_293hz", seed, t, v, y,
                 {"creep", "drift"}, "either",
                 f"a nylon pad creeping as ln(1 + t / {tau0:.2f} s) (k J_0 {c0:.3f}, k J_1 {c1:.3f}) and an air "
                 f"path of {l_mm:.0f} mm read through a gale's buffeting ({U:.0f} m/s, gusts {I:.0%}; the room "
                 f"{np.ptp(p_room):.0f} Pa over the record, the leaks' lag {tau_l:.0f} s) under a signalman's "
                 f"points lever, +-{amp:.0f} V, 293 Hz", rng)
    rec.extra.update(core, knots=kn, x=x, c0=c0, c1=c1, tau0=tau0, U=U, I=I, gseed=gseed, tau_l=tau_l, l_mm=l_mm,
                     d=d, crept=crept, p_room=p_room, drive=v)
    return rec


# ---- out of vocabulary ----

@case
def oov_reflectance_fold_windsurfer_boom_1151hz(seed):
    """The film read by its reflectance taken raw, past a fringe's extremum, under a windsurfer's boom, from the rest
    state at 0 V; nothing else is run before it."""
    rng = _rng(seed, 10)
    dt = 1 / 1151
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s59.windsurfer_boom(r, 1))
    core = dict(_film(rng), amp=amp)
    T = m59.temperature(core, v)
    q = m59.volume_share(core, T)
    h = m59.reading(T, q)
    d0 = m59.film_thickness0(q[0], T[0])
    x_top = rng.uniform(0.35, 0.5) * h.max()
    lam, order = m59.diode_wavelength(d0, x_top)
    y = m59.reflectance_reading(h, d0, lam)
    rec = finish("holdout59_oov_reflectance_fold_windsurfer_boom_1151hz", seed, t, v, y, set(), "unexplained",
                 f"the film's reflectance at {lam:.0f} nm read raw, a fringe's extremum (order {order}) {x_top:.0f} nm "
                 f"up the stroke (a fold) under a windsurfer's boom, +-{amp:.0f} V, 1.151 kHz", rng)
    rec.extra.update(core, knots=kn, x=x, d0=d0, x_top=x_top, lam=lam, order=order, h=h, drive=v)
    return rec

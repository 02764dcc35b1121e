"""The HOLDOUT56 set: written after HOLDOUT55 was measured, by a session that did not read how the diagnosis decides,
and run once for round 58's measurement (19 of 30 runs right on commit ac5079b); part of ALL since.

Mechanisms and signals that the other sets do not have (the laws are in :mod:`.mechanisms56`, the signals in
:mod:`.signals56`, each beside its source; the citations were written from memory, as they say). Every core is a
vanadium-dioxide thin-film bimorph: a cantilever 0.5 mm long of a VO2 film 0.3 um thick (co-sputtered with tungsten, so
that its grains' transition temperatures spread) on a polyimide strip 7.5 um thick, clamped to a heater chip on a
Peltier module, its tip read by a confocal chromatic sensor (um, zeroed at the start of every record). The chip's
temperature loop sets the beam's temperature from the drive, 0.16 K a volt about the bias (the middle of the grains'
loops; on the unipolar records the drive's 0 V is 7.5 K below it). Each grain switches whole between the insulating
monoclinic M1 and the metallic rutile phase at its own temperatures (the metal-insulator transition, first order and
nucleation-limited in small grains: its loop widens as the grain shrinks, w = 0.5 K + 100 K nm / d, superheating 0.3 ...
0.5 of it); 6000 classes of grains, their transition temperatures normal (spread 8 ... 9 K: the tungsten), diameters
log-normal (median 45 ... 55 nm); the grains' c_R axes shrink on the transition (3e-3 in-plane) and the beam bends as
Timoshenko's bimetal, an arc, with the film's and the strip's expansions. Rate independent, with return-point memory;
close to a Prandtl-Ishlinskii model but not one (measured in tests/test_realistic_holdout56.py: a PI model of 12 plays
of the drive fitted by NNLS, stated there). The stroke is some 30 um over +-46 V. Every record but the initial-state
case's starts at 0 V of drive from the rest state the controller's conditioning routine leaves there (a slowly decaying
thermal cycling about that temperature: every grain rutile whose loop's middle lies below it, the others M1; the state
is set so, not run), for unipolar and bipolar records alike; nothing else is run before a record.

- a clean core under a tennis player's racket (the serve's wait, take-backs, swings, follow-throughs, the ready
  position), +-44 ... 48 V, with a noisy input monitor, sampled at 1.373 kHz;
- creep of a PDMS membrane the tip presses in a microvalve (a generalised Maxwell solid of two relaxation times, 1.5
  ... 3 s and 15 ... 30 s); under a gardener's secateurs, on a unipolar stroke, sampled at 293 Hz;
- rate dependence from the chip glued on a glass slide (0.4 ... 0.55 mm), heat diffusing through it from the loop's
  face (a slab held on one face, insulated on the other: tau 0.11 ... 0.21 s); under a drummer's jazz brushes (never
  still), +-44 ... 48 V, with a noisy input monitor, sampled at 1.627 kHz;
- a drift from the confocal sensor's light source warming its optical head after switch-on (a two-node thermal network,
  some 30 s and 5 minutes); under a greenhouse's roof vent, on a unipolar stroke, sampled at 229 Hz;
- asymmetry from a magnet on the tip read by a Hall sensor on its axis (the cylinder's field, convex in the gap); under
  a goalkeeper's dives, +-44 ... 48 V, sampled at 941 Hz;
- saturation from a glass lid the tip lands on (a Hertzian contact, stiff against the beam: a flat top at 0.55 ... 0.7
  of the upward stroke); under a surfer's weight, +-44 ... 48 V, with a noisy input monitor, sampled at 1.163 kHz;
- a delay of a USB data-acquisition module's output buffer (a plain dead time of 0.12 ... 0.2 s on the set point);
  under a potter's wheel pedal, on a unipolar stroke, with a noisy input monitor, sampled at 577 Hz;
- a beam in another state at the start: the chip just wire-bonded on a hot stage at 150 C (every grain rutile) and
  cooled straight to the bias without the conditioning; under a metronome being set, +-44 ... 48 V, sampled at 719 Hz;
- two effects: the tip read by a machine-vision camera (frames of 8 ... 15 ms exposures at 25 ... 30 a second, each
  averaged over its exposure and delivered 2 ... 3 frames late: labelled "delay"), the chip just out of a dry cabinet:
  its polyimide taking up the lab air's water by diffusion and swelling (labelled "drift"); under a golfer's practice
  swings, +-44 ... 48 V, sampled at 827 Hz;
- out of vocabulary: the confocal sensor read through a fieldbus gateway's signed 16-bit register at 1 nm a count: the
  count wraps as the tip rises past 32.767 um from the sensor's zero (0.35 ... 0.55 of the upward stroke): the reading
  jumps by 65.5 um there, both ways; under a slalom skier's hips, +-44 ... 48 V, sampled at 1.049 kHz.

Every bipolar drive is drawn until its weaker side reaches 0.85 of its stronger (a test programme's balance). The
effects' sizes beyond a gain and an offset on the core (seeds 0 ... 2; RMS and largest) are stated in the test.
"""

import math

import numpy as np

from . import mechanisms56 as m56
from . import signals56 as s56
from . import set_tools
from .record import case_set, finish

HOLDOUT56, case, _rng = case_set("holdout56_", 56000)


def _beam(rng, unipolar=False):
    """The core: the grains' seed (the Halton sequence's shift), the film's mean transition temperature Tc (C) and its
    spread between the grains sc (K), the grains' median diameter d50 (nm); the bias Tb (C) follows from them."""
    core = dict(gseed=int(rng.integers(0, 2**31 - 2)), Tc=rng.uniform(66.0, 68.0), sc=rng.uniform(8.0, 9.0),
                d50=rng.uniform(45.0, 55.0), unipolar=unipolar)
    core["Tb"] = m56.bias(core)
    return core


def _bipolar(rng, dt, gen):
    return set_tools.bipolar(rng, dt, gen, s56.knots_at)


def _knotted(rng, dt, gen):
    return set_tools.knotted(rng, dt, gen, s56.knots_at)


def _unipolar(rng, dt, gen):
    return set_tools.unipolar(rng, dt, gen, s56.knots_at)


def _note(core):
    return (f"a VO2 bimorph's 6000 grain classes (Tc {core['Tc']:.1f} C +- {core['sc']:.1f} K, diameters "
            f"{core['d50']:.0f} nm, biased at {core['Tb']:.1f} C)")


# ---- clean ----

@case
def clean_vo2_bimorph_tennis_rally_1373hz(seed):
    """A clean core under a tennis player's racket, from the rest state at 0 V; nothing else is run before it."""
    rng = _rng(seed, 1)
    dt = 1 / 1373
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s56.tennis_rally(r, 2))
    core = dict(_beam(rng), amp=amp)
    y = m56.core_reading(core, v)
    rec = finish("holdout56_clean_vo2_bimorph_tennis_rally_1373hz", seed, t, v, y, set(), "explained",
                 f"a clean core ({_note(core)}) under a tennis player's racket ({len(kn)} knots), +-{amp:.0f} V, "
                 f"1.373 kHz", rng, monitor_noise=2e-4)
    rec.extra.update(core, knots=kn, x=x, drive=v)
    return rec


# ---- one effect ----

@case
def creep_pdms_membrane_prony_secateurs_293hz(seed):
    """The tip pressing a relaxing PDMS membrane under a gardener's secateurs (unipolar), from the rest state at 0 V
    (the membrane long at rest under its preload); nothing else is run before it."""
    rng = _rng(seed, 2)
    dt = 1 / 293
    t, kn, p, top, v = _unipolar(rng, dt, lambda r: s56.secateurs(r, 2))
    core = dict(_beam(rng, unipolar=True), top=top)
    a_inf = rng.uniform(0.3, 0.5)
    a = np.array([rng.uniform(0.14, 0.2), rng.uniform(0.1, 0.14)])
    tau = np.array([rng.uniform(1.5, 3.0), rng.uniform(15.0, 30.0)])
    d = m56.core_reading(core, v)
    y = m56.membrane_contact(d, dt, a_inf, a, tau)
    rec = finish("holdout56_creep_pdms_membrane_prony_secateurs_293hz", seed, t, v, y, {"creep"}, "either",
                 f"the tip pressing a PDMS membrane (k_inf / k_c {a_inf:.2f}, arms {a[0]:.3f} at {tau[0]:.1f} s and "
                 f"{a[1]:.3f} at {tau[1]:.0f} s) under a gardener's secateurs, to {top:.0f} V, 293 Hz", rng)
    rec.extra.update(core, knots=kn, p=p, a_inf=a_inf, a=a, tau=tau, d=d, drive=v)
    return rec


@case
def rate_glass_slide_conduction_jazz_brushes_1627hz(seed):
    """The chip on a glass slide, the heat diffusing through it, under a drummer's jazz brushes, from the rest state at
    0 V (the slide long at the bias); nothing else is run before it."""
    rng = _rng(seed, 3)
    dt = 1 / 1627
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s56.jazz_brushes(r, 1))
    core = dict(_beam(rng), amp=amp)
    l_mm = rng.uniform(0.4, 0.55)
    tau = 4 * (l_mm * 1e-3) ** 2 / (math.pi ** 2 * m56.ALPHA_GLASS)
    T_set = m56.temperature(core, v)
    T = m56.slab_lag(T_set, dt, tau)
    y = m56.reading(T, m56.rutile_share(core, T))
    rec = finish("holdout56_rate_glass_slide_conduction_jazz_brushes_1627hz", seed, t, v, y, {"rate_dependence"},
                 "either",
                 f"the chip on a glass slide {l_mm:.2f} mm thick (tau {tau * 1e3:.0f} ms) under a drummer's jazz "
                 f"brushes, +-{amp:.0f} V, 1.627 kHz", rng, monitor_noise=3e-4)
    rec.extra.update(core, knots=kn, x=x, l_mm=l_mm, tau=tau, T=T, drive=v)
    return rec


#: the optical head's thermal network: C_1 (J / K), C_2, R_12 (K / W), R_2a
HEAD = dict(C1=2.0, C2=25.0, R12=15.0, R2a=12.0)


@case
def drift_led_warmup_optical_head_greenhouse_vent_229hz(seed):
    """The confocal sensor's optical head warming up after switch-on, under a greenhouse's roof vent (unipolar), from
    the rest state at 0 V; nothing else is run before it."""
    rng = _rng(seed, 4)
    dt = 1 / 229
    t, kn, p, top, v = _unipolar(rng, dt, lambda r: s56.greenhouse_vent(r, 3))
    core = dict(_beam(rng, unipolar=True), top=top)
    t_on, P, c_um = rng.uniform(20.0, 60.0), rng.uniform(0.35, 0.45), rng.uniform(0.9, 1.2)
    T1 = m56.warmup(t, t_on, P, **HEAD)
    drift = c_um * (T1 - T1[0])
    h = m56.core_reading(core, v)
    y = h + drift
    rec = finish("holdout56_drift_led_warmup_optical_head_greenhouse_vent_229hz", seed, t, v, y, {"drift"}, "either",
                 f"the sensor's head warming up ({P * 1e3:.0f} mW, switched on {t_on:.0f} s before; the mount "
                 f"{T1[-1] - T1[0]:.2f} K warmer over the record, {c_um:.2f} um / K) under a greenhouse's roof vent, "
                 f"to {top:.0f} V, 229 Hz", rng)
    rec.extra.update(core, knots=kn, p=p, t_on=t_on, P=P, c_um=c_um, T1=T1, h=h, drive=v)
    return rec


@case
def asymmetry_tip_magnet_hall_sensor_goalkeeper_941hz(seed):
    """A magnet on the tip read by a Hall sensor on its axis, under a goalkeeper's dives, from the rest state at 0 V;
    nothing else is run before it."""
    rng = _rng(seed, 5)
    dt = 1 / 941
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s56.goalkeeper(r, 2))
    core = dict(_beam(rng), amp=amp)
    z0, R_m, l_m = rng.uniform(110.0, 140.0), 60.0, 120.0
    h = m56.core_reading(core, v)
    y = m56.hall_reading(h, z0, R_m, l_m)
    rec = finish("holdout56_asymmetry_tip_magnet_hall_sensor_goalkeeper_941hz", seed, t, v, y, {"asymmetry"}, "either",
                 f"a magnet on the tip (radius {R_m:.0f} um, {l_m:.0f} um long) read by a Hall sensor {z0:.0f} um "
                 f"above it under a goalkeeper's dives, +-{amp:.0f} V, 941 Hz", rng)
    rec.extra.update(core, knots=kn, x=x, z0=z0, R_m=R_m, l_m=l_m, h=h, drive=v)
    return rec


@case
def saturation_glass_lid_hertz_contact_surfer_1163hz(seed):
    """The tip landing on a glass lid under a surfer's weight, from the rest state at 0 V; nothing else is run before
    it."""
    rng = _rng(seed, 6)
    dt = 1 / 1163
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s56.surfer(r, 2))
    core = dict(_beam(rng), amp=amp)
    frac, EI = rng.uniform(0.55, 0.7), rng.uniform(2e-10, 3e-10)
    k_c = 3 * EI / m56.L_BEAM ** 3
    K = 4.0 / 3.0 * 50e9 * math.sqrt(10e-6)
    d = m56.core_reading(core, v)
    g = frac * d.max()
    y = m56.lid_contact(d, g, k_c, K)
    rec = finish("holdout56_saturation_glass_lid_hertz_contact_surfer_1163hz", seed, t, v, y, {"saturation"}, "either",
                 f"a glass lid {g:.1f} um above the tip ({frac:.0%} of its upward stroke; the beam {k_c:.1f} N/m) "
                 f"under a surfer's weight, +-{amp:.0f} V, 1.163 kHz", rng, monitor_noise=2.5e-4)
    rec.extra.update(core, knots=kn, x=x, frac=frac, EI=EI, k_c=k_c, K=K, g=g, d=d, drive=v)
    return rec


@case
def delay_usb_daq_output_fifo_potter_pedal_577hz(seed):
    """A USB data-acquisition module's output buffer under a potter's wheel pedal (unipolar), from the rest state at 0
    V; nothing else is run before it."""
    rng = _rng(seed, 7)
    dt = 1 / 577
    t, kn, p, top, v = _unipolar(rng, dt, lambda r: s56.potter_pedal(r, 2))
    core = dict(_beam(rng, unipolar=True), top=top)
    n_buf, f_out = int(rng.integers(1200, 2001)), 10_000.0
    T_d = n_buf / f_out
    v_late = m56.late(lambda tt: top * s56.knots_at(tt, kn) / p.max(), t, T_d)
    y = m56.core_reading(core, v_late)
    rec = finish("holdout56_delay_usb_daq_output_fifo_potter_pedal_577hz", seed, t, v, y, {"delay"}, "either",
                 f"a USB module's output FIFO of {n_buf} samples at 10 kHz ({T_d * 1e3:.0f} ms) under a potter's "
                 f"wheel pedal, to {top:.0f} V, 577 Hz", rng, monitor_noise=2.2e-4)
    rec.extra.update(core, knots=kn, p=p, n_buf=n_buf, T_d=T_d, D=T_d / dt, v_late=v_late, drive=v)
    return rec


@case
def initial_state_wire_bonder_hot_stage_metronome_719hz(seed):
    """The chip just off a wire bonder's hot stage and cooled straight to the bias, without the conditioning, under a
    metronome being set."""
    rng = _rng(seed, 8)
    dt = 1 / 719
    amp = rng.uniform(44.0, 48.0)
    core = dict(_beam(rng), amp=amp)
    s = m56.hot_stage_state(core)
    x, t, kn = _knotted(rng, dt, lambda r: s56.metronome(r, 4))
    v = set_tools.scale(x, amp)
    s0 = s.copy()
    y = m56.core_reading(core, v, s)
    n_off = int(np.sum(s0 != m56.rest_state(core, core["Tb"])))
    rec = finish("holdout56_initial_state_wire_bonder_hot_stage_metronome_719hz", seed, t, v, y, {"initial_state"},
                 "either",
                 f"a hot stage at 150 C and a straight cool-down to the bias ({n_off} of {m56.N_GRAINS} grain classes "
                 f"rutile that the conditioning leaves M1) under a metronome being set, +-{amp:.0f} V, 719 Hz", rng)
    rec.extra.update(core, s0=s0, n_off=n_off, knots=kn, x=x, drive=v)
    return rec


# ---- two effects ----

SUB_CAM = 8


@case
def pair_delay_drift_camera_frames_polyimide_water_golf_swing_827hz(seed):
    """The tip read by a camera's frames ("delay") and the polyimide taking up water ("drift") under a golfer's practice
    swings, from the rest state at 0 V (its temperature's; the water not yet in balance); nothing else is run before
    it."""
    rng = _rng(seed, 9)
    dt = 1 / 827
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s56.golf_swing(r, 4))
    core = dict(_beam(rng), amp=amp)
    fps, t_exp, lat_frames = rng.uniform(25.0, 30.0), rng.uniform(0.008, 0.015), rng.uniform(2.0, 3.0)
    latency = lat_frames / fps
    phase = rng.uniform(0.0, 1.0 / fps)
    ta, D, dRH = rng.uniform(30.0, 60.0), rng.uniform(1.5e-13, 2.5e-13), rng.uniform(35.0, 45.0)
    tau_w = 4 * m56.T_S ** 2 / (math.pi ** 2 * D)
    tf = set_tools.fine(t, SUB_CAM)
    xmax = np.abs(x).max()
    Tf = m56.temperature(core, amp * s56.knots_at(tf, kn) / xmax)
    ff = m56.rutile_share(core, Tf)
    sw = m56.swelling(tf, ta, tau_w, dRH)
    hf = m56.reading(Tf, ff, sw)
    y, tk, vals = m56.camera_frames(t, hf, dt / SUB_CAM, fps, t_exp, latency, phase)
    rec = finish("holdout56_pair_delay_drift_camera_frames_polyimide_water_golf_swing_827hz", seed, t, v, y,
                 {"delay", "drift"}, "either",
                 f"the tip read by a camera ({fps:.1f} frames a second, {t_exp * 1e3:.0f} ms exposures, delivered "
                 f"{latency * 1e3:.0f} ms late), the polyimide taking up water ({ta:.0f} s out of a dry cabinet, "
                 f"{dRH:.0f} % RH more, tau_w {tau_w:.0f} s) under a golfer's swings, +-{amp:.0f} V, 827 Hz", rng)
    rec.extra.update(core, knots=kn, x=x, fps=fps, t_exp=t_exp, latency=latency, phase=phase, ta=ta, D=D, dRH=dRH,
                     tau_w=tau_w, sw=sw[::SUB_CAM], tk=tk, vals=vals, drive=v)
    return rec


# ---- out of vocabulary ----

@case
def oov_fieldbus_int16_wrap_slalom_1049hz(seed):
    """The confocal sensor read through a fieldbus's signed 16-bit register that wraps, under a slalom skier's hips,
    from the rest state at 0 V; nothing else is run before it."""
    rng = _rng(seed, 10)
    dt = 1 / 1049
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s56.slalom(r, 2))
    core = dict(_beam(rng), amp=amp)
    h = m56.core_reading(core, v)
    frac = rng.uniform(0.35, 0.55)
    x_wrap = frac * h.max()
    zero_um = 32.767 - x_wrap
    y = m56.int16_wrap(h, zero_um)
    rec = finish("holdout56_oov_fieldbus_int16_wrap_slalom_1049hz", seed, t, v, y, set(), "unexplained",
                 f"the sensor read through a signed 16-bit register at 1 nm a count, wrapping {x_wrap:.1f} um up the "
                 f"stroke, under a slalom skier's hips, +-{amp:.0f} V, 1.049 kHz", rng)
    rec.extra.update(core, knots=kn, x=x, x_wrap=x_wrap, zero_um=zero_um, h=h, drive=v)
    return rec

"""The HOLDOUT58 set: written after HOLDOUT57 was measured, by a session that did not read how the diagnosis decides,
and run once for round 60's measurement (19 of 30 runs right on commit a1f24a4); part of ALL since.

Mechanisms and signals that the other sets do not have (the laws are in :mod:`.mechanisms58`, the signals in
:mod:`.signals58`, each beside its source; the citations were written from memory, as they say). Every core is a
multistable stage: a voice-coil motor on a flexure guide pushing a shuttle that presses, each through its own soft
spring, the middles of 400 pre-buckled silicon beams on a MEMS chip, the shuttle's travel read by a capacitive gauge
(um, zeroed at the start of every record). Each beam is bistable (its first mode's cubic, f(w) = k (w^3 / a^2 - w) - b:
Vangbo's buckled beam) and, pressed through a spring softer than its negative stiffness, snaps up and down at its
branches' folds (Cardano's roots between them): a hysteron with reversible branches; the beams' amplitudes log-normal
(median 7.5 ... 8.5 um), their thicknesses +-12 % (kappa_50 0.28 ... 0.32) and their imperfections normal (spread 0.22
... 0.28); they share the shuttle's travel (x = g v + 0.3 mean(w), g 0.22 um a volt), so a snap moves the others
(avalanches, a positive feedback: return-point memory kept). Rate independent; close to a Prandtl-Ishlinskii model but
not one (measured in tests/test_realistic_holdout58.py: a PI model of 12 plays of the drive fitted by NNLS, stated
there). The stroke is about 24 um over +-46 V. Every record but the initial-state case's starts at 0 V of drive from
the rest state the controller's conditioning routine leaves there (a slowly decaying dither: every beam up whose snap
points' middle lies below the travel there, the others down; the state is set so, not run), for unipolar and bipolar
records alike; nothing else is run before a record.

- a clean core under a violinist's bow (long strokes, slurs, spiccato), +-44 ... 48 V, with a noisy input monitor,
  sampled at 1.531 kHz;
- creep of the flexure guide printed in acetal (a generalised Maxwell solid: two arms, 1.5 ... 3 s and 15 ... 30 s);
  under a barista's tamper, on a unipolar stroke, sampled at 263 Hz;
- rate dependence from the chip and shuttle immersed in silicone oil (each beam's middle against the oil's viscous
  force: tau_50 0.1 ... 0.15 s, the snaps delayed; the shuttle's plate shearing it: 15 ... 25 ms); under a windsurfer's
  boom (never still), +-44 ... 48 V, with a noisy input monitor, sampled at 1.319 kHz;
- a drift from a heated enclosure's on-off thermostat (a limit cycle of exponential arcs, one to two minutes) warming
  the gauge's aluminium bracket; under a seamstress's treadle, on a unipolar stroke, sampled at 227 Hz;
- asymmetry from a helper leaf that the flexure meets as the shuttle pulls back past its rest (a bilinear return
  spring); under a rower's oar, +-44 ... 48 V, sampled at 911 Hz;
- saturation from the coil amplifier's current limit turned down (0.6 ... 0.72 of the drive's peak, both ways); under
  a kayaker's paddle, +-44 ... 48 V, with a noisy input monitor, sampled at 1.033 kHz;
- a delay of the set point through a delta-sigma converter's linear-phase FIR at a low output rate, held (50 ... 130
  ms); under a driver's accelerator in town, on a unipolar stroke, with a noisy input monitor, sampled at 577 Hz;
- a chip as it left its assembly jig (every beam pushed up) and started without the conditioning; under a crane
  driver's joystick, +-44 ... 48 V, sampled at 673 Hz;
- two effects: the drive through an audio-over-IP link (packets and a jitter buffer: a fixed latency of 11 ... 80 ms;
  labelled "delay") and the coil off the magnet gap's middle (its force factor falling off as an even curve about a
  point behind the rest; labelled "asymmetry"); under a fencer's blade, +-44 ... 48 V, sampled at 787 Hz;
- out of vocabulary: the gauge's carrier read by an AC voltmeter (an amplitude detector, its bridge's null inside the
  stroke): the reading folds back about the null; under a fly fisher's rod, +-44 ... 48 V, sampled at 1.117 kHz.

Every bipolar drive is drawn until its weaker side reaches 0.85 of its stronger (a test programme's balance). The
effects' sizes beyond a gain and an offset on the core (seeds 0 ... 2; RMS and largest) are stated in the test.
"""

import numpy as np

from . import mechanisms58 as m58
from . import signals58 as s58
from . import set_tools
from .record import case_set, finish

HOLDOUT58, case, _rng = case_set("holdout58_", 58000)


def _chip(rng, unipolar=False):
    """The core: the beams' seed (the R2 sequence's shift), kappa_50, the imperfections' spread sb and the beams' median
    amplitude a50 (um)."""
    return dict(rseed=int(rng.integers(0, 2**31 - 2)), kap50=rng.uniform(0.28, 0.32), sb=rng.uniform(0.22, 0.28),
                a50=rng.uniform(7.5, 8.5), unipolar=unipolar)


def _knotted(rng, dt, gen):
    """A balanced bipolar drive from a knot programme gen(rng) -> (knots, T_end)."""
    return set_tools.knotted(rng, dt, gen, s58.knots_at)


def _unipolar(rng, dt, gen):
    return set_tools.unipolar(rng, dt, gen, s58.knots_at)


def _bipolar(rng, dt, gen):
    return set_tools.bipolar(rng, dt, gen, s58.knots_at)


def _note(core):
    return (f"a MEMS chip's 400 bistable beams (a {core['a50']:.1f} um, kappa {core['kap50']:.2f}, imperfections "
            f"+-{core['sb']:.2f}) pressed by a voice-coil stage")


def _drive_at(kn, scale_):
    return lambda tt: scale_ * s58.knots_at(tt, kn)


# ---- clean ----

@case
def clean_bistable_beam_chip_violin_bow_1531hz(seed):
    """A clean core under a violinist's bow, from the rest state at 0 V; nothing else is run before it."""
    rng = _rng(seed, 1)
    dt = 1 / 1531
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s58.violin_bow(r, 2))
    core = dict(_chip(rng), amp=amp)
    y = m58.core_reading(core, v)
    rec = finish("holdout58_clean_bistable_beam_chip_violin_bow_1531hz", seed, t, v, y, set(), "explained",
                 f"a clean core ({_note(core)}) under a violinist's bow ({len(kn)} knots), +-{amp:.0f} V, 1.531 kHz",
                 rng, monitor_noise=2e-4)
    rec.extra.update(core, knots=kn, x=x, drive=v)
    return rec


# ---- one effect ----

@case
def creep_acetal_flexure_maxwell_barista_tamper_263hz(seed):
    """The flexure guide printed in acetal, its stiffness relaxing, under a barista's tamper (unipolar), from the rest
    state at 0 V (the flexure long at rest); nothing else is run before it."""
    rng = _rng(seed, 2)
    dt = 1 / 263
    t, kn, p, top, v = _unipolar(rng, dt, lambda r: s58.barista_tamper(r, 4))
    core = dict(_chip(rng, unipolar=True), top=top)
    phi = np.array([rng.uniform(0.06, 0.09), rng.uniform(0.08, 0.12)])
    tau = np.array([rng.uniform(1.5, 3.0), rng.uniform(15.0, 30.0)])
    xx = m58.travel(core, m58.force_travel(core, v), dt=dt, phi=phi, tau=tau)
    y = xx - xx[0]
    rec = finish("holdout58_creep_acetal_flexure_maxwell_barista_tamper_263hz", seed, t, v, y, {"creep"}, "either",
                 f"an acetal flexure relaxing (arms {phi[0]:.2f} at {tau[0]:.1f} s, {phi[1]:.2f} at {tau[1]:.0f} s) "
                 f"under a barista's tamper, to {top:.0f} V, 263 Hz", rng)
    rec.extra.update(core, knots=kn, p=p, phi=phi, tau=tau, drive=v)
    return rec


@case
def rate_silicone_oil_damped_snaps_windsurfer_boom_1319hz(seed):
    """The chip under silicone oil under a windsurfer's boom, from the rest state at 0 V; nothing else is run before
    it."""
    rng = _rng(seed, 3)
    dt = 1 / 1319
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s58.windsurfer_boom(r, 3))
    core = dict(_chip(rng), amp=amp)
    tau50, tau_s = rng.uniform(0.1, 0.15), rng.uniform(0.015, 0.025)
    sub = m58.SUB_RATE
    tf = set_tools.fine(t, sub)
    u_f = m58.force_travel(core, _drive_at(kn, amp / np.abs(x).max())(tf))
    xx = m58.oil_travel(core, u_f, dt / sub, tau50, tau_s)
    y = xx - xx[0]
    rec = finish("holdout58_rate_silicone_oil_damped_snaps_windsurfer_boom_1319hz", seed, t, v, y,
                 {"rate_dependence"}, "either",
                 f"the chip under silicone oil (the median beam's tau {tau50 * 1e3:.0f} ms, the shuttle's "
                 f"{tau_s * 1e3:.0f} ms) under a windsurfer's boom, +-{amp:.0f} V, 1.319 kHz", rng, monitor_noise=3e-4)
    rec.extra.update(core, knots=kn, x=x, tau50=tau50, tau_s=tau_s, drive=v)
    return rec


@case
def drift_enclosure_thermostat_bracket_sewing_treadle_227hz(seed):
    """A heated enclosure's thermostat cycling the gauge's bracket under a seamstress's treadle (unipolar), from the
    rest state at 0 V (the thermostat long in its cycle); nothing else is run before it."""
    rng = _rng(seed, 4)
    dt = 1 / 227
    t, kn, p, top, v = _unipolar(rng, dt, lambda r: s58.sewing_treadle(r, 6))
    core = dict(_chip(rng, unipolar=True), top=top)
    tau_a, dh, db = rng.uniform(40.0, 70.0), rng.uniform(4.0, 6.0), rng.uniform(1.6, 2.4)
    tau_b, L_mm = rng.uniform(8.0, 15.0), rng.uniform(80.0, 120.0)
    times, Ta, H = m58.thermostat(t[-1], 600.0, tau_a, dh, db)
    drift, T_br = m58.bracket_drift(t, times, Ta, tau_b, L_mm)
    h = m58.core_reading(core, v)
    y = h + drift
    rec = finish("holdout58_drift_enclosure_thermostat_bracket_sewing_treadle_227hz", seed, t, v, y, {"drift"},
                 "either",
                 f"an enclosure's thermostat (dead band {db:.1f} K, the air's tau {tau_a:.0f} s: the bracket "
                 f"{np.ptp(T_br):.2f} K over the record) under a seamstress's treadle, to {top:.0f} V, 227 Hz", rng)
    rec.extra.update(core, knots=kn, p=p, tau_a=tau_a, dh=dh, db=db, tau_b=tau_b, L_mm=L_mm, T_bracket=T_br, h=h,
                     drive=v)
    return rec


@case
def asymmetry_helper_leaf_bilinear_flexure_rowing_oar_911hz(seed):
    """A helper leaf met by the flexure behind the rest, under a rower's oar, from the rest state at 0 V; nothing else
    is run before it."""
    rng = _rng(seed, 5)
    dt = 1 / 911
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s58.rowing_oar(r, 2))
    core = dict(_chip(rng), amp=amp)
    mu, c_um = rng.uniform(0.6, 1.0), rng.uniform(0.5, 1.5)
    s, x0 = m58.rest_state(core)
    xc = x0 - c_um
    xx = m58.travel(core, m58.force_travel(core, v), s, x0, mu=mu, xc=xc)
    y = xx - xx[0]
    rec = finish("holdout58_asymmetry_helper_leaf_bilinear_flexure_rowing_oar_911hz", seed, t, v, y, {"asymmetry"},
                 "either",
                 f"a helper leaf met {c_um:.1f} um behind the rest (stiffness {mu:.2f} of the stage's) under a rower's "
                 f"oar, +-{amp:.0f} V, 911 Hz", rng)
    rec.extra.update(core, knots=kn, x=x, mu=mu, c_um=c_um, xc=xc, x0=x0, drive=v)
    return rec


@case
def saturation_coil_current_limit_kayak_paddle_1033hz(seed):
    """The coil amplifier's current limit turned down under a kayaker's paddle, from the rest state at 0 V; nothing
    else is run before it."""
    rng = _rng(seed, 6)
    dt = 1 / 1033
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s58.kayak_paddle(r, 2))
    core = dict(_chip(rng), amp=amp)
    frac = rng.uniform(0.6, 0.72)
    v_lim = frac * amp
    y = m58.core_reading(core, np.clip(v, -v_lim, v_lim))
    rec = finish("holdout58_saturation_coil_current_limit_kayak_paddle_1033hz", seed, t, v, y, {"saturation"},
                 "either",
                 f"the coil amplifier's current limit at {frac:.0%} of the drive's peak ({v_lim:.1f} V) under a "
                 f"kayaker's paddle, +-{amp:.0f} V, 1.033 kHz", rng, monitor_noise=2.5e-4)
    rec.extra.update(core, knots=kn, x=x, frac=frac, v_lim=v_lim, drive=v)
    return rec


@case
def delay_delta_sigma_fir_hold_town_throttle_577hz(seed):
    """The set point through a delta-sigma converter's FIR, held, under a driver's accelerator in town (unipolar), from
    the rest state at 0 V (the converter long at 0 V); nothing else is run before it."""
    rng = _rng(seed, 7)
    dt = 1 / 577
    t, kn, p, top, v = _unipolar(rng, dt, lambda r: s58.town_throttle(r, 4))
    core = dict(_chip(rng, unipolar=True), top=top)
    fc, M = rng.uniform(160.0, 240.0), 2 * int(rng.integers(12, 21)) + 1
    phase = rng.uniform(0.0, 1.0 / fc)
    v_set, tk, yk = m58.converter_hold(t, fc, M, phase, _drive_at(kn, top / p.max()))
    y = m58.core_reading(core, v_set)
    lat = (M - 1) / (2 * fc) + 1 / (2 * fc)
    rec = finish("holdout58_delay_delta_sigma_fir_hold_town_throttle_577hz", seed, t, v, y, {"delay"}, "either",
                 f"the set point through a delta-sigma converter ({fc:.0f} S/s, a {M}-tap FIR: {lat * 1e3:.0f} ms "
                 f"late on average) under a driver's accelerator, to {top:.0f} V, 577 Hz", rng, monitor_noise=3e-4)
    rec.extra.update(core, knots=kn, p=p, fc=fc, M=M, phase=phase, lat=lat, v_set=v_set, drive=v)
    return rec


@case
def initial_state_assembly_jig_all_up_crane_joystick_673hz(seed):
    """The chip as its assembly jig left it (every beam up), without the conditioning, under a crane driver's joystick.
    """
    rng = _rng(seed, 8)
    dt = 1 / 673
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s58.crane_joystick(r, 3))
    core = dict(_chip(rng), amp=amp)
    s0 = np.ones(m58.N_BEAMS)
    x0 = m58.balance_at(core, 0.0, s0)  # the beams that cannot stay up at the balance snap down (s0 updated)
    rest, x_rest = m58.rest_state(core)
    n_off = int(np.sum(s0 != rest))
    y = m58.core_reading(core, v, s0.copy(), x0)
    rec = finish("holdout58_initial_state_assembly_jig_all_up_crane_joystick_673hz", seed, t, v, y, {"initial_state"},
                 "either",
                 f"the chip as its assembly jig left it ({n_off} of {m58.N_BEAMS} beams up that the conditioning "
                 f"leaves down; the stage {x0 - x_rest:.1f} um out) under a crane driver's joystick, +-{amp:.0f} V, "
                 f"673 Hz", rng)
    rec.extra.update(core, s0=s0, x0=x0, n_off=n_off, knots=kn, x=x, drive=v)
    return rec


# ---- two effects ----

@case
def pair_delay_asymmetry_audio_link_coil_force_factor_fencer_blade_787hz(seed):
    """The drive through an audio-over-IP link ("delay") and the coil off its gap's middle ("asymmetry") under a
    fencer's blade, from the rest state at 0 V (the link long at 0 V); nothing else is run before it."""
    rng = _rng(seed, 9)
    dt = 1 / 787
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s58.fencer_blade(r, 3))
    core = dict(_chip(rng), amp=amp)
    frame, buf = int(rng.choice([64, 128, 192, 256])), int(rng.integers(8, 15))
    D = m58.link_delay(frame, buf)
    Xr, xo_r = rng.uniform(1.5, 1.9), rng.uniform(0.35, 0.5)
    R = m58.GAIN * amp
    v_late = _drive_at(kn, amp / np.abs(x).max())(t - D)
    s, x0 = m58.rest_state(core)
    ix2, xo = 1.0 / (Xr * R) ** 2, x0 - xo_r * R
    xx = m58.travel(core, m58.force_travel(core, v_late), s, None, ix2=ix2, xo=xo)
    y = xx - xx[0]
    rec = finish("holdout58_pair_delay_asymmetry_audio_link_coil_force_factor_fencer_blade_787hz", seed, t, v, y,
                 {"delay", "asymmetry"}, "either",
                 f"the drive through an audio-over-IP link ({frame}-sample packets, {buf} in the buffer: "
                 f"{D * 1e3:.0f} ms) and the coil {xo_r * R:.0f} um off its gap's middle (B l falling over "
                 f"{Xr * R:.0f} um) under a fencer's blade, +-{amp:.0f} V, 787 Hz", rng)
    rec.extra.update(core, knots=kn, x=x, frame=frame, buf=buf, D=D, Xr=Xr, xo_r=xo_r, R=R, ix2=ix2, xo=xo,
                     v_late=v_late, drive=v)
    return rec


# ---- out of vocabulary ----

@case
def oov_ac_voltmeter_bridge_null_fold_fly_cast_1117hz(seed):
    """The gauge's carrier read by an AC voltmeter, its null inside the stroke, under a fly fisher's rod, from the rest
    state at 0 V; nothing else is run before it."""
    rng = _rng(seed, 10)
    dt = 1 / 1117
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s58.fly_cast(r, 3))
    core = dict(_chip(rng), amp=amp)
    h = m58.core_reading(core, v)
    null_frac, e_frac = rng.uniform(0.3, 0.45), rng.uniform(0.01, 0.02)
    x_n, e = null_frac * h.max(), e_frac * np.ptp(h)
    y = m58.detector_reading(h, x_n, e)
    rec = finish("holdout58_oov_ac_voltmeter_bridge_null_fold_fly_cast_1117hz", seed, t, v, y, set(), "unexplained",
                 f"the gauge's carrier read by an AC voltmeter, its null {x_n:.1f} um up the stroke (a fold; "
                 f"quadrature {e:.2f} um) under a fly fisher's rod, +-{amp:.0f} V, 1.117 kHz", rng)
    rec.extra.update(core, knots=kn, x=x, x_n=x_n, e=e, h=h, drive=v)
    return rec


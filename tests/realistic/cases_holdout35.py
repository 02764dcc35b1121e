"""The HOLDOUT35 set: written after HOLDOUT34 was measured, by a session that did not read how the diagnosis decides,
to be run once for the next round's measurement; kept out of ALL until then.

Mechanisms and signals that the other sets do not have (the laws are in :mod:`.mechanisms35`, the signals in
:mod:`.signals35`, each beside its source; the citations were written from memory, as they say). Every core is a voice
coil (its force proportional to the drive: a current drive) pushing and pulling the proximal end of a push-pull
(Bowden) cable whose solid core runs through a curved conduit to a tool on a return spring (1.5 ... 2.5 times as stiff
as the cable), the output the proximal end's travel times a drawn gain. The core slides on the conduit's liner with
Coulomb friction per unit length f0 + b |P|: a constant drag and the capstan term of the wrap (b = mu kappa over the
length 0.25 ... 0.4; Euler-Eytelwein's belt friction, the tendon-sheath drives of Kaneko et al. 1991 and Palli &
Melchiorri 2006). The slipping fronts solve dP/ds = -+(f0 + b |P|) and never cross, so every point of the cable is a
play of g(F) = sign(F) ln(1 + |F| / c) (c = f0 / b) of threshold b s; the travel is P(1) / K + int P ds (96 segments,
the profile exact at the nodes). The drive's peak pushes the virgin cable's front (ratio - 1) b past the far end
(ratio 1.3 ... 1.6). Quasi-static: rate independent, with return-point memory, but NOT a Prandtl-Ishlinskii model of
the force: the thresholds grow with the force (the capstan), so the branches are not Masing's (the constant drag alone
would make it one). Its closeness to one is measured in tests/test_realistic_holdout35.py: a PI model of 12 plays of
the drive fitted by NNLS leaves 1.29 ... 1.32 sigma RMS on the clean record (at most 5.8 ... 6.5 sigma). Every record
starts at 0 V from the virgin cable (no force anywhere along it) except the initial-state cases'.

- a clean core under Cheyne-Stokes breathing (two crescendo-decrescendo cycles of 8 ... 13 breaths between apnoeas,
  time compressed), +-44 ... 48 V, with a noisy input monitor, sampled at 1.335 kHz;
- creep of the sensor's bracket warmed by the coil's I^2 R heat (the heat as the drive squared, through a coil-to-frame
  network of 1 ... 3 s and 12 ... 30 s, the frame 4 ... 10 times the coil's capacity), 5 ... 8 % of the core's span
  after 10 s held at the top; under set points stepping through 14 ... 22 terms of Recaman's sequence, held 2 ... 4 s,
  on a unipolar stroke, sampled at 237 Hz;
- rate dependence from the coil driven by a voltage amplifier: its motional EMF damps the proximal travel (F = F_v -
  (Bl)^2 x' / R; 4 ... 8 ms on the fully slipping cable), acting before the friction; under a curling sweeper's broom
  (two throws of bursts of strokes at 3.5 ... 5.5 Hz), +-44 ... 48 V, with a noisy input monitor, sampled at 1.045 kHz;
- an offset drift from the sensor's target riding an aerostatic pad fed by the shop's air receiver, which cycles
  between the compressor's pressure switch levels (7 ... 7.5 bar up by 1.2 ... 2 bar; exponential draw-down and
  pump-up, tau 40 ... 90 s), 4 ... 8 % of the span over the switch's band, either sign; under an ice hockey player's
  stickhandling drills (narrow and wide dribbles, toe drags, glides), +-44 ... 48 V, sampled at 637 Hz;
- asymmetry of a liquid-metal strain gauge stretched by the stage (Whitney's R = R0 lambda^2, +-13 ... 19 % about its
  rest stretch: the ends' secants as much apart, on a drawn side); under a diabolo juggler's sticks (bouts of whipping
  one way, tosses the other), +-44 ... 48 V, sampled at 1.155 kHz;
- saturation of a balanced slope (Travis) discriminator reading the stage through an oscillator's ferrite slug (two
  tanks +-1 ... 1.6 half-bandwidths off the rest frequency, the universal resonance curve; the ends compressed by 10 ...
  17 %); under an aftershock sequence (a mainshock, then Omori-Utsu's decaying rate, Gutenberg-Richter magnitudes, each
  shock a ring-down), +-44 ... 48 V, with a noisy input monitor, sampled at 778 Hz;
- a delay of a bead laid by a dispenser on the stage and read by a laser profiler downstream on a conveyor (a pure
  transport delay of 2.5 ... 6 samples, in steps of the core's finer grid, 6, 8 or 10 times the record's rate); under
  fireflies' flash dialogue (a male's flashes, a female's answers after her fixed delay, a rival's), on a unipolar
  stroke, with a noisy input monitor, sampled at 463 Hz;
- a core left by a perturb-and-observe tracker tuning a vibration harvester (steps of 1.5 ... 3 V from 0 V, the power's
  peak at 0.55 ... 0.8 of the record's peak on the virgin curve, 40 ... 70 steps, then ramped to 0 V), the record
  starting there; under two operators' strokes taken in the Thue-Morse order, +-44 ... 48 V, sampled at 986 Hz;
- two effects: a core left by an index shifter's clicks (5 ... 8 clicks of 5 ... 7 V up, some down and up again, then
  all released to 0 V) and the gain drift of the LVDT reading it, excited by a thermistor-stabilised Wien-bridge
  oscillator whose amplitude still bounces (the thermistor's slow loop: a damped oscillation of 6 ... 15 s; the record
  starting once it stays within 5 ... 9 % of its final amplitude); under a bicycle's brake lever through a descent
  (feathering, hard stops, dabs), on a unipolar stroke, sampled at 1.245 kHz;
- out of vocabulary: the stage read by a reflective two-fibre displacement probe mounted too close (a Gaussian spot
  growing with the mirror's distance; the stroke from 0.35 ... 0.55 of the peak's distance to 25 ... 45 % past it): the
  reading rises to its peak and falls back, a fold no monotone map of the core draws; under a rattleback's rocking (3
  ... 5 spins, the rocking growing until the spin reverses and dying away), +-44 ... 48 V, sampled at 885 Hz.

Every bipolar drive is drawn until its weaker side reaches 0.85 of its stronger (a test programme's balance). The
effects' sizes beyond a gain and an offset on the core (seeds 0 ... 2) are stated in the test.
"""

import math

import numpy as np
from scipy.optimize import brentq

from . import mechanisms35 as m35
from . import signals35 as s35
from .record import case_set, finish
from .set_tools import fits as _fits, grid as _grid, scale as _scale
from .set_tools import balanced


def _balanced(make, lo=0.85, tries=200):
    """:func:`.set_tools.balanced` with the 200 tries this set drew with."""
    return balanced(make, lo, tries)


HOLDOUT35, case, _rng = case_set("holdout35_", 35000)

N_NODES = 96


def _cable(rng, half):
    """The core: a push-pull cable (capstan friction b = mu kappa 0.25 ... 0.4 over its length, the drag's ratio c =
    f0 / b the unit of force, the tool's spring K 1.5 ... 2.5 times as stiff as the cable), the drive over V_F the
    force, the half-span ``half`` pulling the virgin cable's front to g = (ratio - 1) b past its far end (ratio 1.3
    ... 1.6); the travel times a drawn gain."""
    b, ratio, K = rng.uniform(0.25, 0.4), rng.uniform(1.3, 1.6), rng.uniform(1.5, 2.5)
    F_pk = m35.cable_peak_force(ratio, b)
    return dict(b=b, ratio=ratio, K=K, V_F=half / F_pk, gain=rng.uniform(0.7, 1.4))


def _core_of(core, v, state=None, return_state=False):
    F = np.asarray(v, float) / core["V_F"]
    x, st = m35.cable_travel(F, core["b"], core["K"], n=N_NODES, state=state, return_state=True)
    out = core["gain"] * x
    return (out, st) if return_state else out


# ---- clean ----

@case
def clean_bowden_cable_cheyne_stokes_breathing_1335hz(seed):
    rng = _rng(seed, 1)
    dt = 1 / 1335

    def make():
        breaths, T_end = s35.cheyne_stokes(rng, 2)
        if not _fits(dt, T_end):
            return None
        t = _grid(dt, T_end)
        return s35.breathing_volume(t, breaths), t, breaths
    x, t, breaths = _balanced(make)
    amp = rng.uniform(44.0, 48.0)
    v = _scale(x, amp)
    core = _cable(rng, amp)
    off = rng.uniform(-4.0, 4.0)
    y = _core_of(core, v) + off
    rec = finish("holdout35_clean_bowden_cable_cheyne_stokes_breathing_1335hz", seed, t, v, y, set(), "explained",
                 f"a clean core (a push-pull cable in a curved conduit, capstan friction mu kappa {core['b']:.2f}, the "
                 f"peak's front {core['ratio']:.2f}, the tool's spring {core['K']:.2f}) under Cheyne-Stokes breathing "
                 f"({len(breaths)} breaths), +-{amp:.0f} V, 1.335 kHz", rng, monitor_noise=3e-4)
    rec.extra.update(core, offset=off, breaths=breaths, x=x, amp=amp, drive=v)
    return rec


# ---- one effect ----

@case
def creep_coil_heat_bracket_recaman_setpoints_237hz(seed):
    rng = _rng(seed, 2)
    dt = 1 / 237
    times, vals, terms = s35.recaman_programme(rng)
    while not _fits(dt, times[-1]):
        times, vals, terms = s35.recaman_programme(rng)
    t = _grid(dt, times[-1])
    p = s35.keyframes(t, times, vals)
    top = rng.uniform(88.0, 97.0)
    v = top * p / p.max()
    core = _cable(rng, 50.0)
    h = _core_of(core, v)
    c = rng.uniform(0.05, 0.08)
    tau_c, tau_f, m = rng.uniform(1.0, 3.0), rng.uniform(12.0, 30.0), rng.uniform(4.0, 10.0)
    cr = m35.coil_heat_creep(v, top, dt, c, np.ptp(h), tau_c, tau_f, m)
    rec = finish("holdout35_creep_coil_heat_bracket_recaman_setpoints_237hz", seed, t, v, h + cr, {"creep"}, "either",
                 f"creep of the sensor's bracket warmed by the coil's I^2 R heat (the coil {tau_c:.1f} s, the frame "
                 f"{tau_f:.0f} s; {c:.1%} of the span after 10 s at the top) under set points by Recaman's sequence "
                 f"({len(terms)} terms), to {top:.0f} V, 237 Hz", rng)
    rec.extra.update(core, times=times, vals=vals, terms=terms, top=top, p=p, h=h, c_creep=c, tau_c=tau_c,
                     tau_f=tau_f, m_frame=m, creep=cr, drive=v)
    return rec


@case
def rate_voltage_driven_coil_back_emf_curling_sweeps_1045hz(seed):
    rng = _rng(seed, 3)
    dt = 1 / 1045

    def make():
        bursts, T_end = s35.curling_end(rng, 2)
        if not _fits(dt, T_end):
            return None
        t = _grid(dt, T_end)
        return s35.broom_head(t, bursts), t, bursts
    x, t, bursts = _balanced(make)
    amp = rng.uniform(44.0, 48.0)
    v = _scale(x, amp)
    core = _cable(rng, amp)
    tau_e = rng.uniform(4e-3, 8e-3)
    D = tau_e / (1.0 + 1.0 / core["K"])               # the damping's time constant on the fully slipping cable
    y = core["gain"] * m35.voltage_driven_cable(v / core["V_F"], dt, D, core["b"], core["K"], n=N_NODES)
    rec = finish("holdout35_rate_voltage_driven_coil_back_emf_curling_sweeps_1045hz", seed, t, v, y,
                 {"rate_dependence"}, "either",
                 f"the coil driven by a voltage amplifier, its motional EMF damping the proximal travel "
                 f"({tau_e * 1e3:.1f} ms on the slipping cable) under a curling sweeper's broom ({len(bursts)} "
                 f"bursts), +-{amp:.0f} V, 1.045 kHz", rng, monitor_noise=2.5e-4)
    rec.extra.update(core, bursts=bursts, amp=amp, x=x, tau_e=tau_e, D=D, drive=v)
    return rec



@case
def drift_air_bearing_receiver_cycling_stickhandling_637hz(seed):
    rng = _rng(seed, 4)
    dt = 1 / 637

    def make():
        times, vals = s35.stickhandling(rng, int(rng.integers(8, 12)))
        if not _fits(dt, times[-1]):
            return None
        t = _grid(dt, times[-1])
        return s35.keyframes(t, times, vals), t, times, vals
    x, t, times, vals = _balanced(make)
    amp = rng.uniform(44.0, 48.0)
    v = _scale(x, amp)
    core = _cable(rng, amp)
    h = _core_of(core, v)
    p_lo = rng.uniform(7.0, 7.5)
    p_hi = p_lo + rng.uniform(1.2, 2.0)
    p_inf = p_hi * rng.uniform(1.3, 1.6)
    tau = rng.uniform(40.0, 90.0)
    p0 = rng.uniform(p_lo, p_hi)
    pumping = bool(rng.random() < 0.5)
    p, segs = m35.receiver_pressure(t, p_lo, p_hi, p_inf, tau, p0, pumping)
    mag, sd = rng.uniform(0.04, 0.08), float(rng.choice([-1.0, 1.0]))
    off = sd * mag * np.ptp(h) * (p - p0) / (p_hi - p_lo)
    rec = finish("holdout35_drift_air_bearing_receiver_cycling_stickhandling_637hz", seed, t, v, h + off, {"drift"},
                 "either",
                 f"an offset drift from the sensor's target riding an aerostatic pad fed by a cycling air receiver "
                 f"({p_lo:.1f} ... {p_hi:.1f} bar, tau {tau:.0f} s, {len(segs)} phases; {mag:.1%} of the span over the "
                 f"switch's band) under a hockey player's stickhandling, +-{amp:.0f} V, 637 Hz", rng)
    rec.extra.update(core, times=times, vals=vals, amp=amp, x=x, h=h, p_lo=p_lo, p_hi=p_hi, p_inf=p_inf, tau=tau,
                     p0=p0, pumping=pumping, pressure=p, segs=segs, mag=mag, side=sd, offset=off, drive=v)
    return rec


@case
def asymmetry_liquid_metal_gauge_diabolo_1155hz(seed):
    rng = _rng(seed, 5)
    dt = 1 / 1155

    def make():
        times, vals = s35.diabolo_routine(rng, int(rng.integers(4, 6)))
        if not _fits(dt, times[-1]):
            return None
        t = _grid(dt, times[-1])
        return s35.keyframes(t, times, vals), t, times, vals
    x, t, times, vals = _balanced(make)
    amp = rng.uniform(44.0, 48.0)
    v = _scale(x, amp)
    core = _cable(rng, amp)
    h = _core_of(core, v)
    c = (h.max() + h.min()) / 2
    X = np.abs(h - c).max()
    a, sd = rng.uniform(0.13, 0.19), float(rng.choice([-1.0, 1.0]))
    y = c + sd * X * m35.whitney_reading(sd * (h - c) / X, a)
    rec = finish("holdout35_asymmetry_liquid_metal_gauge_diabolo_1155hz", seed, t, v, y, {"asymmetry"}, "either",
                 f"a liquid-metal strain gauge stretched by the stage (R ~ lambda^2, +-{a:.0%} about its rest stretch: "
                 f"the ends' secants {a:.0%} apart) under a diabolo juggler's sticks, +-{amp:.0f} V, 1.155 kHz", rng)
    rec.extra.update(core, times=times, vals=vals, amp=amp, x=x, h=h, centre=c, X=X, a=a, side=sd, drive=v)
    return rec


@case
def saturation_travis_discriminator_aftershocks_778hz(seed):
    rng = _rng(seed, 6)
    dt = 1 / 778

    def make():
        T_end = rng.uniform(25.0, 45.0)
        shocks = s35.omori_sequence(rng, T_end)
        t = _grid(dt, T_end)
        return s35.ground_velocity(t, shocks), t, shocks
    x, t, shocks = _balanced(make)
    amp = rng.uniform(44.0, 48.0)
    v = _scale(x, amp)
    core = _cable(rng, amp)
    h = _core_of(core, v)
    c = (h.max() + h.min()) / 2
    X = np.abs(h - c).max()
    comp, d = rng.uniform(0.10, 0.17), rng.uniform(1.0, 1.6)
    mm = brentq(lambda q: 1 - float(m35.travis_reading(1.0, q, d)) - comp, 0.05, 3.0, xtol=1e-15)
    y = c + X * m35.travis_reading((h - c) / X, mm, d)
    rec = finish("holdout35_saturation_travis_discriminator_aftershocks_778hz", seed, t, v, y, {"saturation"},
                 "either",
                 f"a balanced slope (Travis) discriminator reading the stage through an oscillator's slug (the tanks "
                 f"+-{d:.2f} half-bandwidths, the stroke +-{mm:.2f}: the ends compressed by {comp:.0%}) under an "
                 f"aftershock sequence ({len(shocks)} shocks), +-{amp:.0f} V, 778 Hz", rng, monitor_noise=3e-4)
    rec.extra.update(core, shocks=shocks, amp=amp, x=x, h=h, centre=c, X=X, comp=comp, d=d, m=mm, drive=v)
    return rec


@case
def delay_conveyor_bead_profiler_fireflies_463hz(seed):
    rng = _rng(seed, 7)
    dt = 1 / 463
    R = int(rng.choice([6, 8, 10]))
    M = int(rng.integers(math.ceil(2.5 * R), int(6.0 * R) + 1))
    flashes, T_end = s35.firefly_dialogue(rng, rng.uniform(25.0, 40.0))
    n = min(max(int(T_end / dt), 10_050), 40_000)
    tf = np.arange((n - 1) * R + 1) * (dt / R)
    lf = s35.flash_light(tf, flashes)
    top = rng.uniform(88.0, 97.0)
    v_f = top * lf / lf.max()
    v, t = v_f[::R], tf[::R]
    core = _cable(rng, 50.0)
    h_f = _core_of(core, v_f)
    y = m35.conveyor_reading(h_f, R, M)
    rec = finish("holdout35_delay_conveyor_bead_profiler_fireflies_463hz", seed, t, v, y, {"delay"}, "either",
                 f"a bead laid by a dispenser on the stage and read by a profiler downstream on a conveyor (the "
                 f"transit {M / R:.2f} samples) under a firefly dialogue ({len(flashes)} flashes), to {top:.0f} V, "
                 f"463 Hz", rng, monitor_noise=2e-4)
    rec.extra.update(core, flashes=flashes, top=top, R=R, M=M, lag=M / R, v_fine=v_f, drive=v)
    return rec


@case
def initial_state_perturb_observe_harvester_thue_morse_turns_986hz(seed):
    rng = _rng(seed, 8)
    dt = 1 / 986
    amp = rng.uniform(44.0, 48.0)
    core = _cable(rng, amp)
    v_opt = rng.uniform(0.55, 0.8) * amp
    up = np.linspace(0.0, v_opt + 40.0, 4001)
    xv = _core_of(core, up)                               # the virgin curve: where the harvester's peak sits
    x_opt = float(np.interp(v_opt, up, xv))
    width = float(np.interp(v_opt + rng.uniform(8.0, 15.0), up, xv)) - x_opt
    step = rng.uniform(1.5, 3.0)
    n_iter = int(rng.integers(40, 71))

    def travel(path, st):
        return _core_of(core, path, state=st, return_state=True)
    path, levels, powers, state = m35.perturb_and_observe(travel, x_opt, width, step, n_iter)

    def make():
        times, vals, order = s35.thue_morse_turns(rng, int(rng.integers(16, 27)))
        if not _fits(dt, times[-1]):
            return None
        t = _grid(dt, times[-1])
        return s35.keyframes(t, times, vals), t, times, vals, order
    x, t, times, vals, order = _balanced(make)
    v = _scale(x, amp)
    y = _core_of(core, v, state=state)
    rec = finish("holdout35_initial_state_perturb_observe_harvester_thue_morse_turns_986hz", seed, t, v, y,
                 {"initial_state"}, "either",
                 f"a core left by a perturb-and-observe tracker tuning an energy harvester ({n_iter} steps of "
                 f"{step:.1f} V, its peak at {v_opt:.0f} V on the virgin curve, reaching {max(levels):.0f} V; then "
                 f"ramped to 0 V) under two operators' turns in the Thue-Morse order ({len(order)} turns), "
                 f"+-{amp:.0f} V, 986 Hz", rng)
    rec.extra.update(core, amp=amp, v_opt=v_opt, x_opt=x_opt, width=width, step=step, n_iter=n_iter, path=path,
                     levels=levels, powers=powers, state=state, times=times, vals=vals, order=order, x=x, drive=v)
    return rec



# ---- two effects ----

@case
def pair_initial_state_gain_drift_index_shifter_wien_bounce_brake_lever_1245hz(seed):
    rng = _rng(seed, 9)
    dt = 1 / 1245
    top = rng.uniform(88.0, 97.0)
    core = _cable(rng, 50.0)
    click = rng.uniform(5.0, 7.0)
    h_times, clicks = s35.index_shifts(rng)
    hist = s35.keyframes(np.linspace(0.0, h_times[-1], 20 * len(h_times) + 1), h_times, clicks) * click
    _, state = _core_of(core, hist, return_state=True)
    times, vals = s35.brake_descent(rng, rng.uniform(20.0, 26.0))
    while not _fits(dt, times[-1]):
        times, vals = s35.brake_descent(rng, rng.uniform(20.0, 26.0))
    t = _grid(dt, times[-1])
    p = s35.keyframes(t, times, vals)
    v = top * p / p.max()
    h = _core_of(core, v, state=state)
    k, gam, tau = rng.uniform(0.6, 1.5), 1.0, rng.uniform(3.0, 6.0)
    swing = rng.uniform(0.05, 0.09)
    tt = np.arange(int(round(90.0 / dt)) + len(t)) * dt   # from the oscillator's switch-on (its envelope at 0.02)
    a, th = m35.wien_envelope(tt, 0.02, 0.0, k, gam, tau)
    rem = np.maximum.accumulate(np.abs(a - 1.0)[::-1])[::-1]
    n0 = int(np.argmax(rem <= swing))                    # the record starts once the bounce stays within the swing
    t_on = n0 * dt
    a, th = a[n0:n0 + len(t)], th[n0:n0 + len(t)]
    gain = a / a[0]
    y = gain * h
    rec = finish("holdout35_pair_initial_state_gain_drift_index_shifter_wien_bounce_brake_lever_1245hz", seed, t, v,
                 y, {"initial_state", "gain_drift"}, "either",
                 f"a core left by an index shifter's clicks (of {click:.1f} V each, {max(clicks)} at most, then all "
                 f"released) read by an LVDT excited by a thermistor-stabilised Wien-bridge oscillator switched on "
                 f"{t_on:.1f} s before (its amplitude bouncing: {gain.min():.2f} ... {gain.max():.2f} of its start) "
                 f"under a bicycle's brake lever on a descent, to {top:.0f} V, 1.245 kHz", rng)
    rec.extra.update(core, top=top, click=click, h_times=h_times, clicks=clicks, hist=hist, state=state, times=times,
                     vals=vals, p=p, h=h, k=k, gamma=gam, tau=tau, swing=swing, t_on=t_on, a=a, theta=th, gain_t=gain,
                     drive=v)
    return rec



# ---- out of vocabulary ----

@case
def oov_fibre_optic_probe_past_its_peak_rattleback_885hz(seed):
    rng = _rng(seed, 10)
    dt = 1 / 885

    def make():
        spins, T_end = s35.rattleback_spins(rng, int(rng.integers(3, 6)))
        if not _fits(dt, T_end):
            return None
        t = _grid(dt, T_end)
        return s35.rattleback_rocking(t, spins), t, spins
    x, t, spins = _balanced(make)
    amp = rng.uniform(44.0, 48.0)
    v = _scale(x, amp)
    core = _cable(rng, amp)
    h = _core_of(core, v)
    c = (h.max() + h.min()) / 2
    X = np.abs(h - c).max()
    D, a, tna = 1.0, rng.uniform(0.25, 0.35), rng.uniform(0.2, 0.3)
    d_pk = m35.fibre_peak_distance(D, a, tna)
    near, past = rng.uniform(0.35, 0.55), rng.uniform(0.25, 0.45)
    sd = float(rng.choice([-1.0, 1.0]))
    u = sd * (h - c) / X                                  # -1 the nearest, +1 the farthest
    dist = d_pk * (near + (1.0 + past - near) * (u + 1.0) / 2.0)
    peak = float(m35.fibre_probe(d_pk, D, a, tna))
    off = rng.uniform(-4.0, 4.0)
    y = np.ptp(h) * m35.fibre_probe(dist, D, a, tna) / peak + off
    rec = finish("holdout35_oov_fibre_optic_probe_past_its_peak_rattleback_885hz", seed, t, v, y, set(),
                 "unexplained",
                 f"the stage read by a reflective fibre-optic probe mounted too close, its stroke from {near:.2f} to "
                 f"{1 + past:.2f} of the peak's distance (the reading rising to its peak and falling back) under a "
                 f"rattleback's rocking ({len(spins)} spins), +-{amp:.0f} V, 885 Hz", rng)
    rec.extra.update(core, spins=spins, amp=amp, x=x, h=h, centre=c, X=X, D=D, a_core=a, tan_na=tna, d_pk=d_pk,
                     near=near, past=past, side=sd, dist=dist, offset=off, drive=v)
    return rec


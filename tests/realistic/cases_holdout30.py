"""The HOLDOUT30 set: written after HOLDOUT29 was measured, by a session that did not read how the diagnosis decides,
to be run once for the next round's measurement; kept out of ALL until then.

Mechanisms and signals that the other sets do not have (the laws are in :mod:`.mechanisms30`, the signals in
:mod:`.signals30`, each beside its source; the citations were written from memory, as they say). Every core is a stage
bedded on a granular (sand) layer loaded in shear, Kondner's hyperbola for soils with Masing's rules (Kondner 1963;
Hardin & Drnevich 1972): from the virgin state x = v + c v / (1 - |v| / Vm), from every reversal x_r + (v - v_r) + 2 c e
/ (1 - |e| / Vm), e = (v - v_r) / 2, with Madelung's memory rules (a closed inner loop wiped out), computed from a stack
of turning points; the bedding's compliance c 0.4 ... 0.8 of the actuator's at small loads, the peak drive 0.35 ...
0.6 of the failure drive Vm; a drawn gain. Every record but the initial-state case's starts at 0 V from the virgin
state.

- a clean core under a honeybee's waggle dance (runs of 0.6 ... 1.2 s waggling at 12 ... 15 Hz, return loops
  alternately right and left, filmed across the runs), +-44 ... 48 V, with a noisy input monitor, sampled at 1.695 kHz;
- creep of a pad of a rubber network swollen with entangled free chains relaxing by reptation (Doi-Edwards modes
  tau_d / p^2, p odd, weights 8 / (pi^2 p^2), tau_d 2 ... 6 s, in a Wiechert solid loaded by the core's force, solved
  exactly on its retardation modes), 8 ... 13 % of the core's output after 10 s of a held load; under the gauge of a
  floor pump inflating two or three bicycle tyres (strokes with diminishing steps, holds, a bleed to correct, the hose
  taken off), on a unipolar stroke, sampled at 212 Hz;
- rate dependence from a fluid inerter between the stage and the frame (y'' = wn^2 (h - y) - 2 zeta wn y' - kap |y'|
  y': the oil's inertance, its laminar and its end losses; fn 80 ... 120 Hz, zeta 0.5 ... 0.8); under a sewing
  machine's needle bar (a slider crank, seams of 6 ... 20 stitches at 4 ... 10 a second, spun up and down by the
  pedal, stopping needle up or down), on a unipolar stroke, with a noisy input monitor, sampled at 1.535 kHz;
- an offset drift from a thermocouple's ice-point reference running out of ice (held while ice is left, then warming
  as a lumped body: 1 - exp(-(t - t_melt) / tau)), 4 ... 8 % of the span at the end, either sign; under a fencer's
  place along the piste in a bout (steps, lunges and recoveries, pressed back and attacking, walks back to the
  en-garde line), +-44 ... 48 V, sampled at 652 Hz;
- asymmetry of an eccentric (harmonic) cam turned by the stage and read at its flat-faced follower (e (1 - cos phi)
  about a working angle: convex, the ends' secants 10 ... 17 % apart, on a drawn side); under a church bell rung up,
  rung near the balance and rung down (exact large swings of a rigid pendulum, Jacobi's sn), +-44 ... 48 V, with a
  noisy input monitor, sampled at 1.085 kHz;
- saturation of a magnetic reading through a saturating iron yoke (Frolich's law, x / (1 + b |x|): odd, the ends
  compressed by 12 ... 20 %); under a tightrope walker's balancing pole (damped wobbles, two near-falls), +-44 ... 48 V,
  sampled at 742 Hz;
- a delay of a tape recorder's read-after-write head (the head 2.6 ... 4.4 samples of tape downstream, its gap 0.4 ...
  0.9 samples long, a wow of 0.1 ... 0.3 %), the core on a grid eight times finer; under a piano key (notes, repeated
  notes and trills of a melody, the key bed's rebound), on a unipolar stroke, with a noisy input monitor, sampled at
  415 Hz;
- a core carrying the memory of an earlier session (a calibration stroke to 50 ... 55 V of either sign, back to 8 ...
  15 V of the other, parked at 0 V), the record starting there; a skateboarder pumping up from the bottom of a
  half-pipe (half swings of 1.0 ... 1.4 s growing by 5 ... 9 % of the width each, stalls on the copings, slowing
  down), +-44 ... 48 V, sampled at 965 Hz. The memory's first stroke lies beyond the record's reach, so the loops
  hang from it differently from a virgin core's as the swings grow: visible against the virgin core (which is here
  the core at rest at the first input too);
- two effects: a delay of a wireless telemetry link (packets at 3 ... 5 times the record's rate, a latency, the
  receiver holding the last packet: 2.6 ... 4.4 samples in all) and an offset drift from a cable heating the sensor's
  bracket (a line source switched on: E1(t_r / (t - t_on)), growing logarithmically; 4 ... 8 % of the span at the
  end), under a dog wagging its tail (bouts of wags at 3 ... 6 Hz, further to one side), +-44 ... 48 V, sampled at
  1.235 kHz;
- out of vocabulary: a single-turn absolute encoder on the stage's lead screw whose travel spans 1.4 ... 2.0 turns, so
  the reading wraps (jumps by a whole turn) whenever the travel crosses a whole turn; under an impact sprinkler
  (stepping across its arc by kicks of its arm, swept back by the reversing lever), +-44 ... 48 V, sampled at
  1.305 kHz. The jumps are as large as the reading's span, come at fixed levels of the travel in both directions and
  leave the reading a sawtooth of the travel: no gain, offset, smooth map, filter or slow drift of a PI core draws
  them.
"""

import math

import numpy as np

from . import mechanisms30 as m30
from . import signals30 as s30
from .record import case_set, finish

HOLDOUT30, case, _rng = case_set("holdout30_", 30000)


def _kondner(rng, peak):
    """The core: the bedding's compliance c 0.4 ... 0.8 of the actuator's, the peak drive 0.35 ... 0.6 of the failure
    drive Vm; a drawn gain."""
    p, c = rng.uniform(0.35, 0.6), rng.uniform(0.4, 0.8)
    return dict(p=p, c=c, Vm=peak / p, gain=rng.uniform(0.7, 1.4))


def _core_of(core, v, state=None, return_state=False):
    out = m30.kondner_core(v, core["Vm"], core["c"], state=state, return_state=return_state)
    if return_state:
        return core["gain"] * out[0], out[1]
    return core["gain"] * out


# ---- clean ----

@case
def clean_kondner_sand_bedding_honeybee_waggle_dance_1695hz(seed):
    rng = _rng(seed, 1)
    dt = 1 / 1695
    T_rec = rng.uniform(12.0, 21.0)
    t0 = rng.uniform(0.4, 0.8)
    runs, tc = [], t0
    while tc < T_rec - 1.5:
        T_run, T_ret = rng.uniform(0.6, 1.2), rng.uniform(0.9, 1.5)
        runs.append((T_run, T_ret))
        tc += T_run + T_ret
    n = int((tc + rng.uniform(0.5, 1.0)) / dt)
    t = np.arange(n) * dt
    tilt = math.radians(rng.uniform(1.0, 4.0)) * float(rng.choice([-1.0, 1.0]))
    f_w, a_w = rng.uniform(12.0, 15.0), rng.uniform(0.06, 0.12)
    x = s30.waggle_dance_x(t, t0, runs, tilt, 1.0, f_w, a_w)
    amp = rng.uniform(44.0, 48.0)
    v = amp * x / np.abs(x).max()
    core = _kondner(rng, amp)
    off = rng.uniform(-4.0, 4.0)
    y = _core_of(core, v) + off
    rec = finish("holdout30_clean_kondner_sand_bedding_honeybee_waggle_dance_1695hz", seed, t, v, y, set(), "explained",
                 f"a clean core (a sand bedding by Kondner's hyperbola, compliance {core['c']:.2f}, the peak "
                 f"{core['p']:.0%} of failure) under a honeybee's waggle dance ({len(runs)} runs, waggling at "
                 f"{f_w:.1f} Hz), +-{amp:.0f} V, 1.695 kHz", rng, monitor_noise=3e-4)
    rec.extra.update(core, offset=off, runs=runs, t0=t0, tilt=tilt, f_w=f_w, a_w=a_w, x=x, amp=amp, drive=v)
    return rec


# ---- one effect ----

@case
def creep_reptation_pad_floor_pump_bicycle_tyres_212hz(seed):
    rng = _rng(seed, 2)
    dt = 1 / 212
    events, tc, p_max_all = [], rng.uniform(1.5, 3.0), []
    n_tyres = int(rng.integers(2, 4))
    for j in range(n_tyres):
        p_tyre = rng.uniform(0.1, 0.3)                   # the tyre's pressure before, read once the hose is on
        T = rng.uniform(0.3, 0.5)
        events.append((tc, T, 0.0, p_tyre, "stroke"))   # the pump head pushed on: the gauge jumps to the tyre's
        tc += T + rng.uniform(1.0, 2.0)
        ps = s30.pump_strokes(p_tyre, rng.uniform(1.1, 1.3), rng.uniform(0.12, 0.2), int(rng.integers(8, 14)))
        for a, b in zip(ps[:-1], ps[1:]):
            T = rng.uniform(0.6, 0.9)
            events.append((tc, T, a, b, "stroke"))
            tc += T + rng.uniform(0.5, 0.8)              # the handle drawn up: the valve shut, the pressure held
        tc += rng.uniform(6.0, 12.0)                     # read off the gauge
        p_end = ps[-1] * rng.uniform(0.82, 0.92)
        T = rng.uniform(2.0, 4.0)
        events.append((tc, T, ps[-1], p_end, "bleed"))  # too hard: a little let out
        tc += T + rng.uniform(6.0, 12.0)
        T = rng.uniform(0.3, 0.6)
        events.append((tc, T, p_end, 0.0, "bleed"))     # the hose taken off: the gauge falls to 0
        tc += T + rng.uniform(4.0, 8.0)
        p_max_all.append(ps[-1])
    n = min(int(tc / dt), 40_000)
    t = np.arange(n) * dt
    p = s30.tyre_pressure(t, events)
    top = rng.uniform(88.0, 97.0)
    v = top * p / p.max()
    core = _kondner(rng, 100.0)
    h = _core_of(core, v)
    tau_d, n_m, r_n, c = rng.uniform(2.0, 6.0), 10, rng.uniform(0.4, 1.0), rng.uniform(0.08, 0.13)
    cr = m30.reptation_creep(h, dt, c, tau_d, n_m, r_n)
    rec = finish("holdout30_creep_reptation_pad_floor_pump_bicycle_tyres_212hz", seed, t, v, h + cr, {"creep"}, "either",
                 f"creep of a pad of a rubber network with entangled free chains (reptation, tau_d {tau_d:.1f} s, "
                 f"{r_n:.2f} of the network's modulus; {c:.1%} after 10 s) under a floor pump's gauge ({n_tyres} "
                 f"tyres), to {top:.0f} V, 212 Hz", rng)
    rec.extra.update(core, events=events, top=top, p=p, h=h, tau_d=tau_d, n_modes=n_m, r_n=r_n, c_creep=c, creep=cr,
                     drive=v)
    return rec


@case
def rate_fluid_inerter_sewing_machine_needle_1535hz(seed):
    rng = _rng(seed, 3)
    dt = 1 / 1535
    seams, tc = [], rng.uniform(0.6, 1.2)
    r_l = rng.uniform(0.25, 0.35)
    down = False
    for j in range(int(rng.integers(3, 6))):
        n_st, rate, t_ramp = int(rng.integers(6, 21)), rng.uniform(4.0, 10.0), rng.uniform(0.3, 0.6)
        down = bool(rng.random() < 0.5) and not down
        seams.append((tc, n_st, rate, t_ramp, down))
        tc += (n_st + (0.5 if down else 0.0)) / rate + t_ramp + rng.uniform(0.8, 2.0)
    if down:                                            # the last seam ends needle up
        t0, n_st, rate, t_ramp, _ = seams[-1]
        seams[-1] = (t0, n_st, rate, t_ramp, False)
    n = int(tc / dt)
    t = np.arange(n) * dt
    # successive seams carry on from a needle-down stop: the half turn is in the crank's angle already
    th = s30.crank_angle(t, seams)
    depth = s30.needle_depth(th, r_l, 1.0)
    top = rng.uniform(88.0, 97.0)
    v = top * depth
    core = _kondner(rng, 100.0)
    h = _core_of(core, v)
    fn, zeta, kr = rng.uniform(80.0, 120.0), rng.uniform(0.5, 0.8), rng.uniform(0.3, 1.0)
    u_pk = np.abs(np.diff(h)).max() / dt
    kap = kr * 2 * zeta * 2 * math.pi * fn / u_pk
    y = m30.inerter_stage(h, dt, fn, zeta, kap)
    rec = finish("holdout30_rate_fluid_inerter_sewing_machine_needle_1535hz", seed, t, v, y, {"rate_dependence"},
                 "either",
                 f"a fluid inerter on the stage ({fn:.0f} Hz, zeta {zeta:.2f}, end losses {kr:.2f} of the laminar at "
                 f"the peak speed) under a sewing machine's needle ({len(seams)} seams), to {top:.0f} V, 1.535 kHz",
                 rng, monitor_noise=2.5e-4)
    rec.extra.update(core, seams=seams, r_l=r_l, top=top, theta=th, depth=depth, h=h, fn=fn, zeta=zeta, kap=kap,
                     kr=kr, drive=v)
    return rec


def _fencing_bout(rng, n_phases):
    """A bout in phases, alternately attacking (steps forward, lunges and recoveries up to the far end) and pressed
    back (steps back to the near end, a parry and riposte lunge), each ending with a touch and the walk back to the
    en-garde line."""
    actions, tc, cur = [], rng.uniform(0.5, 1.0), 0.0
    sign = float(rng.choice([-1.0, 1.0]))
    for _ in range(n_phases):
        goal = sign * rng.uniform(0.9, 1.0)
        while abs(cur - goal) > 0.05:
            fwd = 1.0 if goal > cur else -1.0
            if rng.random() < 0.25:                             # a lunge and its recovery
                reach = rng.uniform(0.3, 0.45) * fwd
                T = rng.uniform(0.2, 0.3)
                x1 = float(np.clip(cur + reach, -1.0, 1.0))
                actions.append((tc, T, cur, x1, "lunge"))
                tc += T + rng.uniform(0.1, 0.3)
                T = rng.uniform(0.35, 0.5)
                back = x1 - reach * rng.uniform(0.6, 1.0)
                actions.append((tc, T, x1, back, "recover"))
                cur = back
                tc += T + rng.uniform(0.2, 0.6)
            else:
                step = rng.uniform(0.08, 0.15) * fwd * (1.0 if rng.random() < 0.8 else -1.0)
                T = rng.uniform(0.25, 0.4)
                x1 = float(np.clip(cur + step, -1.0, 1.0))
                actions.append((tc, T, cur, x1, "step"))
                cur = x1
                tc += T + rng.uniform(0.1, 0.5)
        T = rng.uniform(1.5, 2.5)                               # a touch: back to the en-garde line
        actions.append((tc + rng.uniform(0.3, 0.8), T, cur, 0.0, "walk"))
        tc = actions[-1][0] + T + rng.uniform(0.8, 1.5)
        cur = 0.0
        sign = -sign
    return actions, tc


@case
def drift_ice_point_reference_melting_fencing_bout_652hz(seed):
    rng = _rng(seed, 4)
    dt = 1 / 652
    actions, tc = _fencing_bout(rng, int(rng.integers(2, 4)))
    n = min(max(int(tc / dt), 10_050), 40_000)
    t = np.arange(n) * dt
    x = s30.fencer_path(t, actions)
    amp = rng.uniform(44.0, 48.0)
    v = amp * x / np.abs(x).max()
    core = _kondner(rng, amp)
    h = _core_of(core, v)
    t_melt = rng.uniform(0.15, 0.4) * t[-1]
    tau = rng.uniform(0.4, 1.0) * (t[-1] - t_melt)
    T = m30.ice_point_reference(t, t_melt, tau)
    mag, sd = rng.uniform(0.04, 0.08), float(rng.choice([-1.0, 1.0]))
    off = sd * mag * np.ptp(h) * T / T[-1]
    rec = finish("holdout30_drift_ice_point_reference_melting_fencing_bout_652hz", seed, t, v, h + off, {"drift"},
                 "either",
                 f"an offset drift from a thermocouple's ice-point reference whose ice is gone at {t_melt:.1f} s (then "
                 f"warming, tau {tau:.1f} s; {sd * mag:+.1%} of the span at the end) under a fencing bout "
                 f"({len(actions)} actions), +-{amp:.0f} V, 652 Hz", rng)
    rec.extra.update(core, amp=amp, actions=actions, x=x, h=h, t_melt=t_melt, tau=tau, T=T, mag=mag, side=sd,
                     offset=off, drive=v)
    return rec


@case
def asymmetry_eccentric_cam_church_bell_ringing_1085hz(seed):
    rng = _rng(seed, 5)
    dt = 1 / 1085
    w0 = 2 * math.pi * rng.uniform(0.9, 1.2)
    A, amps = rng.uniform(0.25, 0.4), []
    A_top = rng.uniform(2.9, 3.05)
    while A < A_top:                                           # rung up
        amps.append(A)
        A += rng.uniform(0.25, 0.4)
    amps += [A_top - rng.uniform(0.0, 0.04) for _ in range(int(rng.integers(2, 4)))]   # rung near the balance
    A = amps[-1]
    while A > 0.35:                                            # rung down
        A -= rng.uniform(0.3, 0.45)
        amps.append(max(A, 0.2))
    t0 = rng.uniform(0.5, 1.0)
    _, t_end = s30.bell_angle(np.zeros(1), t0, w0, amps)
    n = min(int((t_end + rng.uniform(0.5, 1.0)) / dt), 40_000)
    t = np.arange(n) * dt
    th, _ = s30.bell_angle(t, t0, w0, amps)
    amp = rng.uniform(44.0, 48.0)
    v = amp * th / np.abs(th).max()
    core = _kondner(rng, amp)
    h = _core_of(core, v)
    c = (h.max() + h.min()) / 2
    X = np.abs(h - c).max()
    asym, sd, k = rng.uniform(0.10, 0.17), float(rng.choice([-1.0, 1.0])), rng.uniform(0.5, 0.9)
    phi0 = math.atan2(2 * (1 - math.cos(k)), asym * k)        # cot phi0 = asym k / (2 (1 - cos k))
    y = c + sd * X * m30.cam_reading(sd * (h - c) / X, phi0, k)
    rec = finish("holdout30_asymmetry_eccentric_cam_church_bell_ringing_1085hz", seed, t, v, y, {"asymmetry"}, "either",
                 f"an eccentric cam turned by {k:.2f} rad about {math.degrees(phi0):.0f} deg (the ends' secants "
                 f"{asym:.0%} apart) under a church bell ({len(amps)} swings, rung up to "
                 f"{math.degrees(A_top):.0f} deg), +-{amp:.0f} V, 1.085 kHz", rng, monitor_noise=3e-4)
    rec.extra.update(core, amp=amp, w0=w0, amps=amps, t0=t0, theta=th, centre=c, X=X, asym=asym, side=sd, k=k,
                     phi0=phi0, drive=v)
    return rec


@case
def saturation_frolich_yoke_tightrope_balancing_pole_742hz(seed):
    rng = _rng(seed, 6)
    dt = 1 / 742
    T_rec = rng.uniform(16.0, 26.0)
    wobbles, tc = [], rng.uniform(0.8, 1.5)
    while tc < T_rec - 2.0:
        wobbles.append((tc, rng.uniform(0.03, 0.15) * float(rng.choice([-1.0, 1.0])), rng.uniform(0.5, 1.0),
                        rng.uniform(0.8, 2.0)))
        tc += rng.exponential(1.0) + 0.2
    sgn = float(rng.choice([-1.0, 1.0]))
    for j, frac in enumerate((rng.uniform(0.2, 0.35), rng.uniform(0.6, 0.75))):     # two near-falls
        wobbles.append((frac * T_rec, (1.0 if j == 0 else -1.0) * sgn * rng.uniform(0.95, 1.05),
                        rng.uniform(0.5, 0.8), rng.uniform(1.0, 2.0)))
    n = int(T_rec / dt)
    t = np.arange(n) * dt
    for _ in range(4):                  # the near-falls scaled so that the pole reaches its stops on both sides
        x = s30.pole_tilt(t, wobbles)
        for j in (-2, -1):
            t0, a, f, tau = wobbles[j]
            wobbles[j] = (t0, a / (x.max() if a > 0 else -x.min()), f, tau)
    x = s30.pole_tilt(t, wobbles)
    amp = rng.uniform(44.0, 48.0)
    v = amp * x / np.abs(x).max()
    core = _kondner(rng, amp)
    h = _core_of(core, v)
    c = (h.max() + h.min()) / 2
    X = np.abs(h - c).max()
    comp = rng.uniform(0.12, 0.2)
    b = comp / (1 - comp)
    y = c + X * m30.frolich_reading((h - c) / X, b)
    rec = finish("holdout30_saturation_frolich_yoke_tightrope_balancing_pole_742hz", seed, t, v, y, {"saturation"},
                 "either",
                 f"a magnetic reading through a yoke saturating by Frolich's law (the ends compressed by {comp:.0%}) "
                 f"under a tightrope walker's pole ({len(wobbles)} wobbles, two near-falls), +-{amp:.0f} V, 742 Hz",
                 rng)
    rec.extra.update(core, amp=amp, wobbles=wobbles, x=x, h=h, centre=c, X=X, comp=comp, b=b, drive=v)
    return rec


@case
def delay_tape_read_after_write_piano_key_415hz(seed):
    rng = _rng(seed, 7)
    dt, R = 1 / 415, 8
    notes, tc = [], rng.uniform(0.8, 1.5)
    T_rec = rng.uniform(25.0, 38.0)
    while tc < T_rec - 1.5:
        kind = rng.choice(["note", "repeat", "trill", "rest"], p=[0.5, 0.2, 0.15, 0.15])
        if kind == "rest":
            tc += rng.uniform(0.5, 1.5)
        elif kind == "note":
            dur = rng.uniform(0.15, 0.8)
            notes.append((tc, dur, rng.uniform(0.5, 1.5)))
            tc += dur + rng.uniform(0.15, 0.5)
        else:
            n_r = int(rng.integers(4, 13)) if kind == "trill" else int(rng.integers(2, 5))
            per = rng.uniform(0.09, 0.13) if kind == "trill" else rng.uniform(0.2, 0.35)
            vel = rng.uniform(0.8, 1.4)
            for _ in range(n_r):
                notes.append((tc, 0.45 * per, vel))
                tc += per
            tc += rng.uniform(0.2, 0.5)
    n = max(int(tc / dt), 10_050)
    tf = np.arange((n - 1) * R + 1) * (dt / R)
    t_down, t_up, bounce = rng.uniform(0.025, 0.04), rng.uniform(0.05, 0.08), rng.uniform(0.03, 0.06)
    xf = s30.key_travel(tf, notes, t_down, t_up, bounce)
    top = rng.uniform(88.0, 97.0)
    v_f = top * xf / xf.max()
    v = v_f[::R]
    t = tf[::R]
    core = _kondner(rng, 100.0)
    h_f = _core_of(core, v_f)
    D, G = rng.uniform(2.6, 4.4), rng.uniform(0.4, 0.9)
    wow, f_wow = rng.uniform(0.001, 0.003), rng.uniform(0.5, 3.0)
    y = m30.tape_readout(t, tf, h_f, D * dt, G * dt, wow, f_wow)
    rec = finish("holdout30_delay_tape_read_after_write_piano_key_415hz", seed, t, v, y, {"delay"}, "either",
                 f"a tape recorder's read head {D:.2f} samples downstream (gap {G:.2f} samples, wow {wow:.1%} at "
                 f"{f_wow:.1f} Hz) under a piano key ({len(notes)} notes), to {top:.0f} V, 415 Hz", rng,
                 monitor_noise=2e-4)
    rec.extra.update(core, notes=notes, t_down=t_down, t_up=t_up, bounce=bounce, top=top, R=R, v_fine=v_f, D=D, G=G,
                     wow=wow, f_wow=f_wow, drive=v)
    return rec


@case
def initial_state_earlier_session_halfpipe_skater_965hz(seed):
    rng = _rng(seed, 8)
    dt = 1 / 965
    amp = rng.uniform(44.0, 48.0)
    core = _kondner(rng, 55.0)
    s1 = float(rng.choice([-1.0, 1.0]))
    P1, P2 = s1 * rng.uniform(50.0, 55.0), -s1 * rng.uniform(8.0, 15.0)
    path = np.r_[np.linspace(0.0, P1, 400), np.linspace(P1, P2, 400)[1:], np.linspace(P2, 0.0, 400)[1:]]
    _, state = _core_of(core, path, return_state=True)
    halves, a, side = [], rng.uniform(0.1, 0.2), float(rng.choice([-1.0, 1.0]))
    grow = rng.uniform(0.05, 0.09)
    while a < 1.0:                                              # pumping up
        halves.append((rng.uniform(1.0, 1.4), side * a))
        a += grow
        side = -side
    for _ in range(int(rng.integers(4, 8))):                    # at the copings
        halves.append((rng.uniform(1.1, 1.4), side * 1.0))
        side = -side
    a = 1.0
    while a > 0.15:                                             # slowing down
        a -= rng.uniform(0.12, 0.2)
        halves.append((rng.uniform(1.0, 1.3), side * max(a, 0.0)))
        side = -side
    halves.append((rng.uniform(1.0, 1.3), 0.0))
    t0, stall = rng.uniform(0.8, 1.5), rng.uniform(0.3, 0.7)
    _, t_end = s30.halfpipe_path(np.zeros(1), t0, halves, stall)
    n = min(int((t_end + rng.uniform(0.5, 1.0)) / dt), 40_000)
    t = np.arange(n) * dt
    x, _ = s30.halfpipe_path(t, t0, halves, stall)
    v = amp * x
    y = _core_of(core, v, state=state)
    rec = finish("holdout30_initial_state_earlier_session_halfpipe_skater_965hz", seed, t, v, y, {"initial_state"},
                 "either",
                 f"a core left by an earlier session (to {P1:.0f} V, back to {P2:.0f} V, parked at 0 V) under a "
                 f"skateboarder pumping up in a half-pipe ({len(halves)} half swings), +-{amp:.0f} V, 965 Hz", rng)
    rec.extra.update(core, amp=amp, P1=P1, P2=P2, path=path, state=state, halves=halves, t0=t0, stall=stall, x=x,
                     drive=v)
    return rec


# ---- two effects ----

@case
def pair_delay_drift_telemetry_cable_heating_dog_tail_wag_1235hz(seed):
    rng = _rng(seed, 9)
    dt, R = 1 / 1235, 8
    bouts, tc = [], rng.uniform(0.8, 1.5)
    T_rec = rng.uniform(18.0, 28.0)
    while tc < T_rec - 2.0:
        nw, f = int(rng.integers(6, 21)), rng.uniform(3.0, 6.0)
        bouts.append((tc, nw, f, rng.uniform(0.5, 1.0)))
        tc += nw / f + rng.uniform(0.5, 2.0)
    bias = rng.uniform(0.04, 0.09) * float(rng.choice([-1.0, 1.0]))
    n = int((tc + rng.uniform(0.5, 1.0)) / dt)
    tf = np.arange((n - 1) * R + 1) * (dt / R)
    xf = s30.tail_wag(tf, bouts, bias)
    amp = rng.uniform(44.0, 48.0)
    v_f = amp * xf / np.abs(xf).max()
    v = v_f[::R]
    t = tf[::R]
    core = _kondner(rng, amp)
    h_f = _core_of(core, v_f)
    span = np.ptp(h_f)
    t_on = rng.uniform(0.1, 0.35) * t[-1]
    t_r = rng.uniform(0.05, 0.3) * (t[-1] - t_on)
    T = m30.line_source_heating(tf, t_on, t_r)
    mag, sd = rng.uniform(0.04, 0.08), float(rng.choice([-1.0, 1.0]))
    drift_f = sd * mag * span * T / T[-1]
    D = rng.uniform(2.6, 4.4)
    period = dt / rng.uniform(3.0, 5.0)
    latency = D * dt - period / 2
    y = m30.telemetry_link(t, tf, h_f + drift_f, period, latency)
    rec = finish("holdout30_pair_delay_drift_telemetry_cable_heating_dog_tail_wag_1235hz", seed, t, v, y,
                 {"delay", "drift"}, "either",
                 f"a telemetry link (packets every {period * 1e3:.2f} ms, latency {latency * 1e3:.2f} ms: {D:.2f} "
                 f"samples) and a cable heating the bracket from {t_on:.1f} s ({sd * mag:+.1%} of the span at the end) "
                 f"under a dog's tail ({len(bouts)} bouts), +-{amp:.0f} V, 1.235 kHz", rng)
    rec.extra.update(core, amp=amp, bouts=bouts, bias=bias, R=R, v_fine=v_f, t_on=t_on, t_r=t_r, mag=mag, side=sd,
                     span=span, D=D, period=period, latency=latency, drive=v)
    return rec


# ---- out of vocabulary ----

@case
def oov_wrapping_encoder_impact_sprinkler_1305hz(seed):
    rng = _rng(seed, 10)
    dt = 1 / 1305
    cycles, n_k = int(rng.integers(3, 5)), int(rng.integers(10, 17))
    kick_T, kick_gap, ret_T = rng.uniform(0.03, 0.05), rng.uniform(0.2, 0.35), rng.uniform(1.5, 2.5)
    t0 = rng.uniform(0.5, 1.0)
    _, t_end = s30.sprinkler_angle(np.zeros(1), t0, cycles, n_k, kick_T, kick_gap, ret_T)
    n = min(int((t_end + rng.uniform(0.5, 1.0)) / dt), 40_000)
    t = np.arange(n) * dt
    x, _ = s30.sprinkler_angle(t, t0, cycles, n_k, kick_T, kick_gap, ret_T)
    amp = rng.uniform(44.0, 48.0)
    v = amp * x
    core = _kondner(rng, amp)
    h = _core_of(core, v)
    period = np.ptp(h) / rng.uniform(1.4, 2.0)
    phase = rng.uniform(0.1, 0.9) * period
    y = m30.wrapped_encoder(h, period, phase)
    rec = finish("holdout30_oov_wrapping_encoder_impact_sprinkler_1305hz", seed, t, v, y, set(), "unexplained",
                 f"a single-turn encoder on the lead screw, the travel spanning {np.ptp(h) / period:.2f} turns (the "
                 f"reading wraps) under an impact sprinkler ({cycles} sweeps of {n_k} kicks), +-{amp:.0f} V, 1.305 kHz",
                 rng)
    rec.extra.update(core, amp=amp, cycles=cycles, n_kicks=n_k, kick_T=kick_T, kick_gap=kick_gap, ret_T=ret_T, t0=t0,
                     x=x, h=h, period=period, phase=phase, drive=v)
    return rec

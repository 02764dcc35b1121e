"""The HOLDOUT32 set: written after HOLDOUT31 was measured, by a session that did not read how the diagnosis decides,
to be run once for the next round's measurement; kept out of ALL until then.

Mechanisms and signals that the other sets do not have (the laws are in :mod:`.mechanisms32`, the signals in
:mod:`.signals32`, each beside its source; the citations were written from memory, as they say). Every core is a stage
on a preloaded rolling guide whose pre-sliding friction follows Dahl's solid-friction law (Dahl 1968, 1976), dF/dx =
sigma0 (1 - s F / Fc)^a (s the direction of travel, a 1.3 ... 2.2, in closed form along each branch), pushed by the
actuator (stiffness 1, free stroke v) against a return flexure: v = K x + F(x), K 1.3 ... 1.8, x solved by Newton's
method at each sample. The friction's level Fc is 0.12 ... 0.2 of the peak drive (in the actuator's force units), its
pre-sliding length Fc / sigma0 0.1 ... 0.25 of the travel; a drawn gain. A Duhem model: rate independent, but its
branches start from the present friction force (no stack of turning points), so its minor loops are not Masing's.
Every record but the initial-state case's starts at 0 V from the virgin state (x = F = 0).

- a clean core under a turntablist scratching a record against a beat (88 ... 100 bpm: baby scratches, tears,
  scribbles and pulls behind the cue on the sixteenth notes), +-44 ... 48 V, with a noisy input monitor, sampled at
  1.715 kHz;
- creep of a bituminous (mastic asphalt) damping pad by Huet's two parabolic elements (Huet 1963: delta (t / tau)^k /
  Gamma(k + 1) + (t / tau)^h / Gamma(h + 1), k 0.15 ... 0.3, h 0.45 ... 0.65, delta 1.5 ... 4, tau 2 ... 10 s), 10
  ... 15 % of the core's output after 10 s of a held load; under a bascule bridge's leaf opening for vessels (two or
  three openings, full or partial for a yacht, held 8 ... 18 s, a trapezoidal speed profile), on a unipolar stroke,
  sampled at 222 Hz;
- rate dependence from a voice-coil transducer on the stage closed by a resonant R-L-C shunt (Behrens, Fleming &
  Moheimani 2003: the stage's compliance falling by kappa 0.25 ... 0.45 above the circuit's resonance at 3 ... 8 Hz,
  damping 0.25 ... 0.5); under a dobby loom's heddle frame (a drawn weave, started, slowed for a weft change, stopped
  by a warp break and run again faster, 2.5 ... 5.5 picks a second), on a unipolar stroke, with a noisy input monitor,
  sampled at 1.545 kHz;
- an offset drift from a laser interferometer's dead path (0.3 ... 0.6 m of air) as an operator standing in the
  stage's enclosure warms its air (two lumped capacities, air and walls; the air's refractive index by the modified
  Edlen equation, Birch & Downs 1993), 4 ... 8 % of the span at its greatest, either sign; under a model beam pumping
  unit's polished rod (its four-bar geometry solved exactly; a variable-frequency drive's speeds, stopped and
  restarted), +-44 ... 48 V, sampled at 644 Hz;
- asymmetry of a vibrating-wire gauge tensioned by the stage and read by its frequency (f ~ sqrt(T), the tension
  swinging so the ends' secants differ by 10 ... 17 %, on a drawn side); under a carousel's galloping horse (two
  rides, started, run and braked; 3 ... 4 strokes a revolution), +-44 ... 48 V, sampled at 1.125 kHz;
- saturation of a lateral-effect position-sensitive detector whose junction leaks (the reading tanh(alpha x) /
  tanh(alpha L): the ends compressed by 10 ... 17 %); under an accordionist's bellows (phrases drawn and pushed in
  turn with their dynamics, bellows shakes), +-44 ... 48 V, with a noisy input monitor, sampled at 766 Hz;
- a delay of a wireless sensor's jitter buffer (time-stamped samples at 1.25 ... 2 times the logger's rate, 1 ... 4 %
  of them lost, played out after a fixed latency of 2.6 ... 4.4 logger samples and interpolated linearly), the core on
  a grid eight times finer; under one stamp of a gravity stamp mill (lifted by a cam, dropped onto the die, 60 ... 85
  drops a minute, one hung up for 2 ... 4 s), on a unipolar stroke, with a noisy input monitor, sampled at 435 Hz;
- a core left by a technician's hand pushing the stage to check its freedom (to a force equal to 55 ... 62 V of
  either sign, the other way to 0.6 ... 0.9 of it, the first way again to 0.5 ... 0.8 of it, let go), the record
  starting there; under a skipping rope's handle (basic bounces, double-unders, a trip, side swings), +-44 ... 48 V,
  sampled at 940 Hz. The guide's friction is left loaded by the push, so the record starts away from where a virgin
  core starts (which, the record starting at 0 V, is also the core at rest at the first input);
- two effects: rate dependence from a vane the stage carries through still air (Newton's quadratic drag, 15 ... 30 %
  of the flexure's force at the fastest travel) and an offset drift from the ground slab settling under an operator
  walking about the stage's table (Boussinesq: the piers' differential settlement 1 / r_a - 1 / r_b; 4 ... 8 % of the
  span at its greatest, either sign); under a launcher's engine gimbal in pitch through an ascent (pitch-over, wind
  shear responses, load relief, slosh, staging), +-44 ... 48 V, sampled at 1.285 kHz;
- out of vocabulary: a magnet on the stage sliding past a Hall sensor (a point dipole magnetised toward the sensor at
  a gap of 0.35 ... 0.5 of the travel; the sensor 30 ... 42 % into the travel from either end), under a weathervane in
  a gusty, veering wind, +-44 ... 48 V, sampled at 1.355 kHz. The field is greatest with the magnet over the sensor
  and falls on either side of it: the same reading on both sides, so no monotone map, gain, offset, filter or drift of
  the core draws it.

Every bipolar drive is drawn until its weaker side reaches 0.85 of its stronger (a test programme's balance).
"""

import math

import numpy as np
from scipy.optimize import brentq

from . import mechanisms32 as m32
from . import signals32 as s32
from .record import case_set, finish
from .set_tools import grid as _grid, scale as _scale

HOLDOUT32, case, _rng = case_set("holdout32_", 32000)


def _guide(rng, peak):
    """The core: the return flexure K 1.3 ... 1.8, Dahl's Fc 0.12 ... 0.2 of the peak drive, the pre-sliding length
    Fc / sigma0 0.1 ... 0.25 of the travel peak / K, the exponent a 1.3 ... 2.2; a drawn gain."""
    K, f, frac, a = 1.0 + rng.uniform(0.3, 0.8), rng.uniform(0.12, 0.2), rng.uniform(0.1, 0.25), rng.uniform(1.3, 2.2)
    Fc = f * peak
    return dict(K=K, Fc=Fc, sigma0=Fc / (frac * peak / K), a=a, f=f, frac=frac, gain=rng.uniform(0.7, 1.4))


def _core_of(core, v, state=None, return_state=False):
    out = m32.dahl_stage(v, core["K"], core["Fc"], core["sigma0"], core["a"], state=state, return_state=return_state)
    if return_state:
        return core["gain"] * out[0], out[1]
    return core["gain"] * out


def _balanced(make, lo=0.85, tries=200):
    """Calls make() -> (x, *rest) until x's weaker side reaches lo of its stronger; returns its result."""
    for _ in range(tries):
        out = make()
        x = out[0]
        if min(x.max(), -x.min()) >= lo * np.abs(x).max():
            return out
    raise RuntimeError("no balanced drive drawn")


# ---- clean ----

@case
def clean_dahl_guide_turntable_scratching_1715hz(seed):
    rng = _rng(seed, 1)
    dt = 1 / 1715

    def make():
        bpm, bars = rng.uniform(88.0, 100.0), int(rng.integers(4, 6))
        times, vals = s32.dj_scratches(rng, bpm, bars)
        t = _grid(dt, times[-1] + rng.uniform(0.3, 0.6))
        return s32.waypoints(t, times, vals), t, times, vals, bpm
    x, t, times, vals, bpm = _balanced(make)
    amp = rng.uniform(44.0, 48.0)
    v = _scale(x, amp)
    core = _guide(rng, amp)
    off = rng.uniform(-4.0, 4.0)
    y = _core_of(core, v) + off
    rec = finish("holdout32_clean_dahl_guide_turntable_scratching_1715hz", seed, t, v, y, set(), "explained",
                 f"a clean core (a rolling guide's Dahl friction, exponent {core['a']:.2f}, Fc {core['f']:.0%} of the "
                 f"peak, pre-sliding {core['frac']:.0%} of the travel, return flexure K {core['K']:.2f}) under a "
                 f"turntablist's scratches at {bpm:.0f} bpm, +-{amp:.0f} V, 1.715 kHz", rng, monitor_noise=3e-4)
    rec.extra.update(core, offset=off, times=times, vals=vals, bpm=bpm, x=x, amp=amp, drive=v)
    return rec


# ---- one effect ----

@case
def creep_huet_asphalt_pad_bascule_bridge_222hz(seed):
    rng = _rng(seed, 2)
    dt = 1 / 222
    moves, T_end = s32.bascule_openings(rng, int(rng.integers(2, 4)))
    t = _grid(dt, T_end)
    p = s32.leaf_angle(t, moves)
    top = rng.uniform(88.0, 97.0)
    v = top * p / p.max()
    core = _guide(rng, 100.0)
    h = _core_of(core, v)
    c, tau = rng.uniform(0.10, 0.15), rng.uniform(2.0, 10.0)
    delta, k, hx = rng.uniform(1.5, 4.0), rng.uniform(0.15, 0.3), rng.uniform(0.45, 0.65)
    cr = m32.huet_creep(h, dt, c, tau, delta, k, hx)
    rec = finish("holdout32_creep_huet_asphalt_pad_bascule_bridge_222hz", seed, t, v, h + cr, {"creep"}, "either",
                 f"creep of a mastic asphalt pad by Huet's law (k {k:.2f}, h {hx:.2f}, delta {delta:.1f}, tau "
                 f"{tau:.1f} s; {c:.1%} after 10 s) under a bascule bridge's leaf ({len(moves) // 2} openings), to "
                 f"{top:.0f} V, 222 Hz", rng)
    rec.extra.update(core, moves=moves, top=top, p=p, h=h, c_creep=c, tau=tau, delta=delta, k=k, hx=hx, creep=cr,
                     drive=v)
    return rec


WEAVES = {"plain": [1, 0], "twill 2/1": [1, 1, 0], "twill 2/2": [1, 1, 0, 0], "twill 3/1": [1, 1, 1, 0],
          "satin 5": [1, 0, 0, 0, 0], "basket 2/2": [1, 1, 0, 0, 1, 1, 0, 0, 0, 1]}


@case
def rate_rlc_shunted_voice_coil_dobby_loom_1545hz(seed):
    rng = _rng(seed, 3)
    dt = 1 / 1545
    kt, kw = s32.loom_picks(rng)
    weave = str(rng.choice(sorted(WEAVES)))
    mf = rng.uniform(0.3, 0.45)
    t = _grid(dt, kt[-1])
    x = s32.heddle_lift(t, kt, kw, WEAVES[weave], mf)
    top = rng.uniform(88.0, 97.0)
    v = top * x / x.max()
    core = _guide(rng, 100.0)
    h = _core_of(core, v)
    K_s, kappa = 1.0 + rng.uniform(0.2, 0.5), rng.uniform(0.25, 0.45)
    f_e, zeta = rng.uniform(3.0, 8.0), rng.uniform(0.25, 0.5)
    y = m32.rlc_shunt_stage(h, dt, K_s, kappa, f_e, zeta)
    rec = finish("holdout32_rate_rlc_shunted_voice_coil_dobby_loom_1545hz", seed, t, v, y, {"rate_dependence"},
                 "either",
                 f"a voice coil on the stage closed by an R-L-C shunt (kappa {kappa:.2f}, resonance {f_e:.1f} Hz, "
                 f"damping {zeta:.2f}) under a dobby loom's heddle frame ({weave}, up to {max(kw):.1f} picks a "
                 f"second), to {top:.0f} V, 1.545 kHz", rng, monitor_noise=2.5e-4)
    rec.extra.update(core, kt=kt, kw=kw, weave=weave, move_frac=mf, top=top, x=x, h=h, K_s=K_s, kappa=kappa,
                     f_e=f_e, zeta=zeta, drive=v)
    return rec


def _pumpjack(rng):
    """A drawn unit's geometry (the beam's back arm C = 1) and drive speeds, the crank starting at rest where the rod
    is at mid-stroke."""
    R, P, I, H = rng.uniform(0.35, 0.45), rng.uniform(1.1, 1.3), rng.uniform(0.95, 1.05), rng.uniform(1.2, 1.4)
    th = np.linspace(0, 2 * math.pi, 4001)
    b = s32.pumpjack_beam_angle(th, R, P, 1.0, I, H)
    mid, half = (b.max() + b.min()) / 2, (b.max() - b.min()) / 2
    j = int(np.nonzero(np.diff(np.sign(b - mid)))[0][0])
    th0 = brentq(lambda q: float(s32.pumpjack_beam_angle(q, R, P, 1.0, I, H)) - mid, th[j], th[j + 1], xtol=1e-14)
    kt, kw = s32.pumpjack_speeds(rng)
    return dict(R=R, P=P, I=I, H=H, theta0=th0, mid=mid, half=half, kt=kt, kw=kw)


def _rod(t, geo):
    """The polished rod's travel about mid-stroke (+-1 the stroke's ends)."""
    theta = geo["theta0"] + s32.speed_integral(t, geo["kt"], geo["kw"])
    return (s32.pumpjack_beam_angle(theta, geo["R"], geo["P"], 1.0, geo["I"], geo["H"]) - geo["mid"]) / geo["half"]


@case
def drift_interferometer_dead_path_operator_pumpjack_644hz(seed):
    rng = _rng(seed, 4)
    dt = 1 / 644
    geo = _pumpjack(rng)
    t = _grid(dt, geo["kt"][-1])
    x = _rod(t, geo)
    amp = rng.uniform(44.0, 48.0)
    v = _scale(x, amp)
    core = _guide(rng, amp)
    h = _core_of(core, v)
    T = t[-1]
    t_in, t_out = rng.uniform(0.1, 0.3) * T, rng.uniform(0.55, 0.8) * T
    tau_a, tau_w = rng.uniform(5.0, 15.0), rng.uniform(60.0, 150.0)
    g, share = rng.uniform(0.3, 1.0), rng.uniform(0.5, 1.5)
    rise = m32.enclosure_air_temperature(t, t_in, t_out, tau_a, tau_w, g, share)
    dT, L_dead = rng.uniform(0.5, 1.5), rng.uniform(0.3, 0.6)
    T_air = 20.0 + dT * rise / rise.max()
    err = -L_dead * (m32.edlen_refractivity(T_air, 101325.0, 0.633) - m32.edlen_refractivity(20.0, 101325.0, 0.633))
    mag, sd = rng.uniform(0.04, 0.08), float(rng.choice([-1.0, 1.0]))
    off = sd * mag * np.ptp(h) * err / np.abs(err).max()
    rec = finish("holdout32_drift_interferometer_dead_path_operator_pumpjack_644hz", seed, t, v, h + off, {"drift"},
                 "either",
                 f"an offset drift from an interferometer's {L_dead:.2f} m dead path as an operator warms the "
                 f"enclosure's air by {dT:.1f} K (from {t_in:.0f} s to {t_out:.0f} s; {sd * mag:+.1%} of the span at "
                 f"most) under a model pumping unit's rod, +-{amp:.0f} V, 644 Hz", rng)
    rec.extra.update(core, **geo, amp=amp, x=x, h=h, t_in=t_in, t_out=t_out, tau_a=tau_a, tau_w=tau_w, g=g,
                     share=share, rise=rise, dT=dT, L_dead=L_dead, T_air=T_air, err=err, mag=mag, side=sd, offset=off,
                     drive=v)
    return rec


@case
def asymmetry_vibrating_wire_gauge_carousel_1125hz(seed):
    rng = _rng(seed, 5)
    dt = 1 / 1125

    def make():
        kt, kw = s32.carousel_rides(rng, 2)
        n_cr, ph = int(rng.integers(3, 5)), rng.uniform(-0.08, 0.08)
        t = _grid(dt, kt[-1])
        return s32.horse_height(t, kt, kw, n_cr, ph), t, kt, kw, n_cr, ph
    x, t, kt, kw, n_cr, ph = _balanced(make)
    amp = rng.uniform(44.0, 48.0)
    v = _scale(x, amp)
    core = _guide(rng, amp)
    h = _core_of(core, v)
    c = (h.max() + h.min()) / 2
    X = np.abs(h - c).max()
    asym, sd = rng.uniform(0.10, 0.17), float(rng.choice([-1.0, 1.0]))
    a = brentq(lambda q: m32.vibrating_wire_asym(q) - asym, 1e-3, 0.99, xtol=1e-14)
    y = c + sd * X * m32.vibrating_wire_reading(sd * (h - c) / X, a)
    rec = finish("holdout32_asymmetry_vibrating_wire_gauge_carousel_1125hz", seed, t, v, y, {"asymmetry"}, "either",
                 f"a vibrating-wire gauge read by its frequency, the tension swinging +-{a:.0%} (the ends' secants "
                 f"{asym:.0%} apart) under a carousel's horse ({n_cr} strokes a revolution, two rides), +-{amp:.0f} V, "
                 f"1.125 kHz", rng)
    rec.extra.update(core, amp=amp, kt=kt, kw=kw, n_cranks=n_cr, phase=ph, x=x, h=h, centre=c, X=X, asym=asym, side=sd,
                     a_wire=a, drive=v)
    return rec


@case
def saturation_leaky_lateral_psd_accordion_bellows_766hz(seed):
    rng = _rng(seed, 6)
    dt = 1 / 766

    def make():
        segs, T_end = s32.bellows_phrases(rng, int(rng.integers(7, 11)))
        t = _grid(dt, T_end)
        return s32.bellows_position(t, segs), t, segs
    x, t, segs = _balanced(make)
    amp = rng.uniform(44.0, 48.0)
    v = _scale(x, amp)
    core = _guide(rng, amp)
    h = _core_of(core, v)
    c = (h.max() + h.min()) / 2
    X = np.abs(h - c).max()
    comp = rng.uniform(0.10, 0.17)
    b = brentq(lambda q: 1 - math.tanh(q) / q - comp, 1e-3, 3.0, xtol=1e-14)
    y = c + X * m32.psd_reading((h - c) / X, b)
    rec = finish("holdout32_saturation_leaky_lateral_psd_accordion_bellows_766hz", seed, t, v, y, {"saturation"},
                 "either",
                 f"a lateral-effect PSD with a leaky junction (alpha times the travel {b:.2f}: the ends compressed by "
                 f"{comp:.0%}) under an accordionist's bellows ({sum(sg[4] != 'shake' for sg in segs)} phrases, "
                 f"{sum(sg[4] == 'shake' for sg in segs)} shakes), +-{amp:.0f} V, 766 Hz", rng, monitor_noise=3e-4)
    rec.extra.update(core, amp=amp, segs=segs, x=x, h=h, centre=c, X=X, comp=comp, b=b, drive=v)
    return rec


@case
def delay_wireless_jitter_buffer_stamp_mill_435hz(seed):
    rng = _rng(seed, 7)
    dt, R = 1 / 435, 8
    drops, g, T_end = s32.stamp_drops(rng, int(rng.integers(35, 51)))
    n = min(max(int(T_end / dt), 10_050), 40_000)
    tf = np.arange((n - 1) * R + 1) * (dt / R)
    zf = s32.stamp_height(tf, drops, g)
    top = rng.uniform(88.0, 97.0)
    v_f = top * zf / zf.max()
    v = v_f[::R]
    t = tf[::R]
    core = _guide(rng, 100.0)
    h_f = _core_of(core, v_f)
    T_s = dt / rng.uniform(1.25, 2.0)
    t_s = np.arange(-rng.uniform(0, T_s), tf[-1], T_s)
    t_s = t_s[t_s >= 0.0]
    x_s = np.interp(t_s, tf, h_f)
    arrived = rng.random(len(t_s)) >= rng.uniform(0.01, 0.04)
    arrived[0] = True
    D = rng.uniform(2.6, 4.4)
    y = m32.jitter_buffer(t, t_s, x_s, arrived, D * dt)
    rec = finish("holdout32_delay_wireless_jitter_buffer_stamp_mill_435hz", seed, t, v, y, {"delay"}, "either",
                 f"a wireless sensor's jitter buffer (samples every {T_s * 1e3:.2f} ms, {1 - arrived.mean():.1%} "
                 f"lost, played out {D:.2f} samples late) under a stamp mill's stamp ({len(drops)} drops), to "
                 f"{top:.0f} V, 435 Hz", rng, monitor_noise=2e-4)
    rec.extra.update(core, drops=drops, g_fall=g, top=top, R=R, v_fine=v_f, T_s=T_s, t_s=t_s, arrived=arrived, D=D,
                     drive=v)
    return rec


@case
def initial_state_hand_pushed_guide_skipping_rope_940hz(seed):
    rng = _rng(seed, 8)
    dt = 1 / 940
    amp = rng.uniform(44.0, 48.0)
    core = _guide(rng, amp)
    s1 = float(rng.choice([-1.0, 1.0]))
    P1 = s1 * rng.uniform(55.0, 62.0)
    P2, P3 = -P1 * rng.uniform(0.6, 0.9), P1 * rng.uniform(0.5, 0.8)
    path = np.r_[np.linspace(0.0, P1, 400), np.linspace(P1, P2, 400)[1:], np.linspace(P2, P3, 400)[1:],
                 np.linspace(P3, 0.0, 400)[1:]]
    _, state = _core_of(core, path, return_state=True)

    def make():
        kt, kw, kr = s32.skipping_routine(rng)
        t = _grid(dt, kt[-1])
        return s32.handle_position(t, kt, kw, kr), t, kt, kw, kr
    x, t, kt, kw, kr = _balanced(make)
    v = _scale(x, amp)
    y = _core_of(core, v, state=state)
    rec = finish("holdout32_initial_state_hand_pushed_guide_skipping_rope_940hz", seed, t, v, y, {"initial_state"},
                 "either",
                 f"a core left by a hand pushing the stage (to {P1:.0f} V's force, back to {P2:.0f} V and {P3:.0f} V, "
                 f"let go) under a skipping rope's handle, +-{amp:.0f} V, 940 Hz", rng)
    rec.extra.update(core, amp=amp, P1=P1, P2=P2, P3=P3, path=path, state=state, kt=kt, kw=kw, kr=kr, x=x, drive=v)
    return rec


# ---- two effects ----

def _operator_walk(rng, t, foot_a, foot_b, r_min=0.8):
    """An operator walking about the table: standing spots 1.2 ... 3 m from the table's middle, walked between at
    0.4 ... 0.9 m/s (minimum-jerk), standing 1 ... 4 s at each; a spot is redrawn while the straight walk to it would
    pass nearer than r_min to a pier. Returns (path N x 2, the spots' times and positions)."""
    mid = (np.asarray(foot_a) + np.asarray(foot_b)) / 2

    def spot():
        r, ang = rng.uniform(1.2, 3.0), rng.uniform(0, 2 * math.pi)
        return mid + r * np.array([math.cos(ang), math.sin(ang)])

    def clear(p, q):
        s = np.linspace(0, 1, 200)[:, None]
        seg = p + s * (q - p)
        return min(np.hypot(*(seg - f).T).min() for f in (foot_a, foot_b)) >= r_min
    cur = spot()
    times, pts, tc = [0.0], [cur], rng.uniform(1.0, 3.0)
    times.append(tc)
    pts.append(cur)
    while tc < t[-1]:
        nxt = spot()
        while not clear(cur, nxt):
            nxt = spot()
        tc += np.hypot(*(nxt - cur)) / rng.uniform(0.4, 0.9)
        times.append(tc)
        pts.append(nxt)
        tc += rng.uniform(1.0, 4.0)
        times.append(tc)
        pts.append(nxt)
        cur = nxt
    pts = np.array(pts)
    path = np.c_[s32.waypoints(t, times, pts[:, 0]), s32.waypoints(t, times, pts[:, 1])]
    return path, times, pts


@case
def pair_rate_drift_vane_drag_walking_operator_launcher_gimbal_1285hz(seed):
    rng = _rng(seed, 9)
    dt = 1 / 1285

    def make():
        ev, T_end = s32.gimbal_events(rng)
        t = _grid(dt, T_end)
        return s32.gimbal_angle(t, ev), t, ev
    x, t, ev = _balanced(make)
    amp = rng.uniform(44.0, 48.0)
    v = _scale(x, amp)
    core = _guide(rng, amp)
    h = _core_of(core, v)
    K_v, beta = 1.0 + rng.uniform(0.2, 0.5), rng.uniform(0.15, 0.3)
    v_max = np.abs(np.diff(h)).max() / dt / K_v                     # the fastest travel without the vane
    c_q = beta * K_v * np.abs(h).max() / v_max ** 2
    xs = m32.vane_drag_stage(h, dt, K_v, c_q)
    foot_a, foot_b = np.array([0.0, 0.0]), np.array([rng.uniform(0.6, 1.0), 0.0])
    path, wt, wp = _operator_walk(rng, t, foot_a, foot_b)
    tilt = m32.walking_tilt(path, foot_a, foot_b)
    mag, sd = rng.uniform(0.04, 0.08), float(rng.choice([-1.0, 1.0]))
    off = sd * mag * np.ptp(xs) * tilt / np.abs(tilt).max()
    rec = finish("holdout32_pair_rate_drift_vane_drag_walking_operator_launcher_gimbal_1285hz", seed, t, v, xs + off,
                 {"rate_dependence", "drift"}, "either",
                 f"a vane on the stage in air (quadratic drag {beta:.0%} of the flexure's force at the fastest) and "
                 f"the slab settling under an operator walking about ({len(wt) // 2} spots; {sd * mag:+.1%} of the "
                 f"span at most) under a launcher's gimbal in pitch ({len(ev)} events), +-{amp:.0f} V, 1.285 kHz", rng)
    rec.extra.update(core, amp=amp, events=ev, x=x, h=h, K_v=K_v, beta=beta, c_q=c_q, stage=xs, foot_a=foot_a,
                     foot_b=foot_b, path=path, walk_times=wt, walk_points=wp, tilt=tilt, mag=mag, side=sd, offset=off,
                     drive=v)
    return rec


# ---- out of vocabulary ----

@case
def oov_slide_by_hall_magnet_weathervane_1355hz(seed):
    rng = _rng(seed, 10)
    dt = 1 / 1355
    fn, zeta = rng.uniform(0.6, 1.0), rng.uniform(0.2, 0.4)
    k = (2 * math.pi * fn) ** 2
    c = 2 * zeta * math.sqrt(k)

    def make():
        t = _grid(dt, rng.uniform(18.0, 24.0))
        wind, wp = s32.gusty_wind(rng)
        return s32.vane_yaw(t, k, c, wind), t, wp
    x, t, wp = _balanced(make)
    amp = rng.uniform(44.0, 48.0)
    v = _scale(x, amp)
    core = _guide(rng, amp)
    h = _core_of(core, v)
    f_null = rng.uniform(0.3, 0.42)
    if rng.random() < 0.5:
        f_null = 1 - f_null
    x_null = h.min() + f_null * np.ptp(h)
    d = rng.uniform(0.35, 0.5) * np.ptp(h)
    y = m32.slide_by_field(h - x_null, d) * d ** 3
    rec = finish("holdout32_oov_slide_by_hall_magnet_weathervane_1355hz", seed, t, v, y, set(), "unexplained",
                 f"a magnet on the stage sliding past a Hall sensor {f_null:.0%} into the travel at a gap of "
                 f"{d / np.ptp(h):.2f} of it, under a weathervane (natural frequency {fn:.2f} Hz, damping "
                 f"{zeta:.2f}) in a gusty, veering wind, +-{amp:.0f} V, 1.355 kHz", rng)
    rec.extra.update(core, amp=amp, fn=fn, zeta=zeta, k_vane=k, c_vane=c, wind=wp, x=x, h=h, f_null=f_null,
                     x_null=x_null, d=d, drive=v)
    return rec

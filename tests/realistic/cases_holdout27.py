"""The HOLDOUT27 set: written after HOLDOUT26 was measured, by a session that did not read how the diagnosis decides,
to be run once for the next round's measurement; kept out of ALL until then.

Mechanisms and signals that the other sets do not have (the laws are in :mod:`.mechanisms27`, the signals in
:mod:`.signals27`, each beside its source; the citations were written from memory, as they say). Every core is a
Masing-type hysteresis with a Ramberg-Osgood skeleton (the travel v + a S |v / S|^n sign(v) of the drive from the
virgin state, a 0.2 ... 0.4, n 2.5 ... 4.5, S 42 ... 50 V; from every reversal the skeleton doubled, x_r + 2 phi((v -
v_r) / 2); Madelung's memory rules: a closed inner loop is wiped out and the branch left before it resumed, a branch
reaching the skeleton follows it), computed with a stack of turning points, not plays; a drawn gain. Every record but
the initial-state case's starts at 0 V from the virgin state.

- a clean core (the Masing core above; a drawn gain and offset) under x of a swinging spring at its 2:1 resonance (the
  bounce at twice the swing's frequency, 0.9 ... 1.2 Hz; released stretched by 0.25 ... 0.35 of its length with a
  sideways nudge of 0.01 ... 0.03: the swing grows out of the bounce and gives its energy back, again and again), from
  0 V, scaled to peaks of +-44 ... 48 V, with a noisy input monitor, sampled at 1.805 kHz;
- creep of the stage's wet-felt pad consolidating as its water drains radially through its jacket (a long cylinder:
  the modes 4 / alpha_n^2 exp(-alpha_n^2 t / tau), alpha_n the zeros of J0, tau = a^2 / c_v 4 ... 12 s), 9 ... 13 % of
  the core's output after 10 s of a held load, by Boltzmann superposition (a Kelvin element per mode); under two scuba
  dives (the first to 24 ... 32 m for 8 ... 14 min, the second multilevel, 14 ... 20 m then 8 ... 12 m; down at 18
  m/min, up at 9 m/min, a safety stop of 3 min at 5 m; played 25 ... 35 times faster, the surface interval cut short;
  the deepest at 88 ... 97 V), on a unipolar stroke, sampled at 218 Hz;
- rate dependence from a hydraulically damped (cab) mount under the stage (its inertia track: soft when slow, stiffer by
  1 / (1 - beta), beta 0.3 ... 0.5, when fast, the long liquid column resonating at 2 ... 2.8 Hz with damping 0.2 ...
  0.35; exact by the first-order hold); under a tennis rally's ball along the court (2 or 3 points: a serve, 1 ...
  3 groundstrokes bouncing deep, volleys taken on the full; quadratic air drag, the court's bounce keeping 0.6 ... 0.75
  of the horizontal speed; played 1 ... 1.25 times slower; the ball carried to the server between points), +-44 ... 48
  V, with a noisy input monitor, sampled at 1.13 kHz;
- an offset drift of the sensor's mount held by a pneumatic clamp whose supply is shut off at 15 ... 35 % of the record
  and which then leaks through an orifice (isothermal blowdown from 4 ... 7 bar absolute; Saint-Venant and Wantzel's
  orifice flow: choked, an exponential fall, then subsonic, reaching the ambient in a finite time), the offset linear
  in the pressure's fall, 4 ... 8 % of the span at the end, either sign; under a pendulum-wave demonstration (12 ... 16
  pendulums of frequencies (K + j) / Gamma, Gamma 14 ... 20 s, from 1.6 ... 2.2 Hz, pulled aside together and
  released: in step, dephasing into travelling and standing patterns, in step again; the mean swing), +-44 ... 48 V,
  sampled at 610 Hz;
- asymmetry of a float in a conical vessel into which the stage's piston pushes liquid (the level as the cube root of
  the volume: concave, the ends' secants 10 ... 17 % apart, on a drawn side); under a heavy bag worked by a boxer (the
  bag a pendulum of 0.55 ... 0.75 Hz, damping 3 ... 6 %; 8 ... 12 combinations of 1 ... 4 punches, each a kick in the
  bag's velocity), +-44 ... 48 V, with a noisy input monitor, sampled at 1.075 kHz;
- saturation of a load cell reading a wire over two pulleys, tensioned by a hanging weight and pushed sideways at its
  middle by the stage (2 T sin(theta): odd, the ends compressed by 12 ... 20 %); under a hand saw's strokes (30 ... 45
  strokes, short while the kerf is started and growing to full length, the cutting push slower than the return, a
  pause every 5 ... 8 strokes), +-44 ... 48 V, sampled at 685 Hz;
- a delay of a sensor whose DSP aligns its channel with a third-order Thiran allpass (maximally flat group delay D 2.6
  ... 3.6 samples) and delivers it 0 or 1 sample later: 2.6 ... 4.6 samples; under one quadrature of a GMSK burst
  (BT 0.3 ... 0.5, 3.5 ... 5 bit/s, faded in and out), +-44 ... 48 V, with a noisy input monitor, sampled at 535 Hz;
- a core left by Levitt's two-down one-up staircase run with the stage as the stimulus (from the virgin state at 0 V up
  to a first level of 80 ... 88 V, steps of 8 V halving at the first three reversals, 8 ... 12 reversals, a simulated
  observer whose 70.7 % point is at 28 ... 40 V), the record starting at its last level; then a Ferris wheel's cabin
  (12 ... 16 cabins loaded one by one, the wheel moved by one cabin's angle between dwells, then 1.5 ... 2 turns; the
  top at 93 ... 98 V, beyond the staircase's first level only from about a quarter of the record on), on a unipolar
  stroke, sampled at 705 Hz;
- two effects: saturation of a balance reading the normal force on a vane the stage turns in a wind tunnel (a flat
  plate in Kirchhoff's free-streamline flow, Rayleigh's C_N = 2 pi sin a / (4 + pi |sin a|): odd, the ends compressed
  by 12 ... 20 %) and a delay of the balance's delta-sigma converter (a Kaiser-windowed sinc decimator at 4 times the
  record's rate, a group delay of 1.5 ... 2.5 samples, plus one sample of latency), the core computed on the
  modulator's grid; under the tunnel's angle-of-attack programme (a pitch-pause polar of 3 or 4 steps each way, then
  sinusoidal pitching at three frequencies), +-44 ... 48 V, sampled at 1.265 kHz;
- out of vocabulary: a resettable PTC fuse (a polyfuse: 10 ... 14 Ohm cold, its resistance rising 10^4-fold across a
  few kelvin at 120 ... 130 C; heat loss 3.5 ... 4.5 mW/K, a thermal time constant of 0.5 ... 0.9 s) in series with
  the stack (30 ... 40 uF), the amplifier's output recorded as the input. Under a steady tone at 12 ... 15 Hz (an exact
  96 ... 120 samples a period) of +-44 ... 48 V, faded in, held 4 ... 5 s, a two-tone (hi-lo) alarm of 2.5 times that
  frequency alternating with it (whole cycles, until the fuse trips), and the steady tone again for 5 ... 6 s, faded
  out, sampled at 1.445 kHz (the core on a 4x grid, the fuse on a 32x one). The steady tone draws too little current
  to trip the cold fuse (it warms by about 20 K); the hi tone draws 2.5 times as much and trips it; once tripped, the
  same steady tone holds it hot (the Joule heat (A^2 / 2) R C^2 w^2 / (1 + (R C w)^2) peaks at R C w = 1 and falls
  beyond, so the fuse settles where R C w is 5 ... 7): the stack then sees the tone cut to 0.15 ... 0.19 of it and
  lagging by about 80 degrees.
  In both holds the recorded input is the same sample for sample, and so is a core driven by it; the output differs
  between them by many noise levels beyond any gain and offset. A PI core (any plays with non-negative weights and any
  linear part) draws the same output for the same input from the same state; saturation and asymmetry are maps of it;
  rate dependence and delay are stable causal filters of it (a periodic input gives one periodic output, whatever came
  before); creep settles, and creep, drift and gain drift are slow and smooth in time (a gain and an offset between the
  holds at most); an initial state is forgotten after the first period.
"""

import math

import numpy as np
from scipy.optimize import brentq

from . import mechanisms27 as m27
from . import signals27 as s27
from .record import case_set, finish

HOLDOUT27, case, _rng = case_set("holdout27_", 27000)


def _masing(rng):
    """The core: a Masing hysteresis on a Ramberg-Osgood skeleton (a 0.2 ... 0.4, n 2.5 ... 4.5, S 42 ... 50 V); a
    drawn gain."""
    return dict(a=rng.uniform(0.2, 0.4), n=rng.uniform(2.5, 4.5), S=rng.uniform(42.0, 50.0),
                gain=rng.uniform(0.7, 1.4))


def _core_of(core, v, state=None, return_state=False):
    out = m27.masing_core(v, core["a"], core["n"], core["S"], state=state, return_state=return_state)
    if return_state:
        return core["gain"] * out[0], out[1]
    return core["gain"] * out


# ---- clean ----

@case
def clean_masing_ramberg_osgood_swinging_spring_1805hz(seed):
    rng = _rng(seed, 1)
    dt = 1 / 1805
    n = int(rng.uniform(14.0, 20.0) / dt)
    t = np.arange(n) * dt
    f_p, stretch, nudge = rng.uniform(0.9, 1.2), rng.uniform(0.25, 0.35), rng.uniform(0.01, 0.03)
    x, states = s27.swinging_spring(t, 2 * math.pi * f_p, stretch, nudge)
    amp = rng.uniform(44.0, 48.0)
    scale = amp / np.abs(x).max()
    v = scale * x
    core = _masing(rng)
    off = rng.uniform(-4.0, 4.0)
    y = _core_of(core, v) + off
    rec = finish("holdout27_clean_masing_ramberg_osgood_swinging_spring_1805hz", seed, t, v, y, set(), "explained",
                 f"a clean core (Masing branches on a Ramberg-Osgood skeleton, a {core['a']:.2f}, n {core['n']:.1f}, "
                 f"solved by its turning points) under a swinging spring at its 2:1 resonance (the swing at {f_p:.2f} "
                 f"Hz), from 0 V, +-{amp:.0f} V, 1.805 kHz", rng, monitor_noise=3e-4)
    rec.extra.update(core, offset=off, f_p=f_p, stretch=stretch, nudge=nudge, x=x, states=states, scale=scale, amp=amp,
                     drive=v)
    return rec


# ---- one effect ----

@case
def creep_radial_drainage_felt_pad_scuba_dives_218hz(seed):
    rng = _rng(seed, 2)
    dt = 1 / 218
    speed = rng.uniform(25.0, 35.0)
    d1, d2, d3 = rng.uniform(24.0, 32.0), rng.uniform(14.0, 20.0), rng.uniform(8.0, 12.0)
    dive1 = s27.dive_keys(rng.uniform(1.0, 2.0), [(d1, rng.uniform(8.0, 14.0))], 18.0, 9.0, speed)
    dive2 = s27.dive_keys(dive1[-1][0] + rng.uniform(6.0, 10.0), [(d2, rng.uniform(10.0, 15.0)),
                                                                  (d3, rng.uniform(10.0, 15.0))], 18.0, 9.0, speed)
    keys = dive1 + dive2
    T_rec = keys[-1][0] + rng.uniform(4.0, 6.0)
    n = int(T_rec / dt)
    t = np.arange(n) * dt
    top = rng.uniform(88.0, 97.0)
    v = top / d1 * s27.path_through(t, keys)
    core = _masing(rng)
    h = _core_of(core, v)
    tau, c = rng.uniform(4.0, 12.0), rng.uniform(0.09, 0.13)
    cr = m27.radial_creep(h, dt, c, tau, 10.0)
    rec = finish("holdout27_creep_radial_drainage_felt_pad_scuba_dives_218hz", seed, t, v, h + cr, {"creep"}, "either",
                 f"creep of a wet-felt pad draining radially through its jacket ({c:.1%} after 10 s; tau {tau:.1f} s) "
                 f"under two scuba dives ({d1:.0f} m, then {d2:.0f} and {d3:.0f} m; played {speed:.0f} times faster), "
                 f"to {top:.0f} V, 218 Hz", rng)
    rec.extra.update(core, speed=speed, depths=(d1, d2, d3), keys=keys, top=top, h=h, tau=tau, c=c, creep=cr)
    return rec


COURT = 11.89                     # the baseline's distance from the net, m
K_DRAG = 0.0195                   # rho C_d A / (2 m) of a tennis ball, 1/m (1.2 kg/m^3, C_d 0.55, 33 mm radius, 57 g)


@case
def rate_hydraulic_mount_inertia_track_tennis_rally_1130hz(seed):
    rng = _rng(seed, 3)
    dt = 1 / 1130
    amp = rng.uniform(44.0, 48.0)
    slow, e_x = rng.uniform(1.0, 1.25), rng.uniform(0.6, 0.75)
    n_pt = int(rng.integers(2, 4))
    tc, pieces, carries, side, x_now = rng.uniform(0.4, 0.8), [], [], -1.0, 0.0   # real seconds
    for _ in range(n_pt):
        x_srv = side * rng.uniform(11.9, 12.4)
        carry = rng.uniform(1.2, 2.0) / slow
        carries.append((tc, x_now, x_srv, carry))
        tc += carry + rng.uniform(0.3, 0.6) / slow
        shots = [(tc, x_srv, -side * rng.uniform(38.0, 50.0), -side * rng.uniform(3.5, 6.2),
                  -side * rng.uniform(11.5, 13.0))]
        n_sh = int(rng.integers(1, 4))
        hitter = -side
        for j in range(n_sh):
            _, t_end = s27.rally(shots[-1:], K_DRAG, e_x)
            x_h = shots[-1][4]
            last = j == n_sh - 1
            volley = (not last) and rng.uniform() < 0.25
            x_next = (hitter * -1) * (rng.uniform(2.5, 4.0) if volley else rng.uniform(10.5, 12.8))
            if last:
                x_next = -hitter * rng.uniform(12.6, 13.2)           # a winner: past the receiver, to the back
            x_b = None if volley else -hitter * rng.uniform(5.0, 10.0)
            u0 = -hitter * (rng.uniform(15.0, 24.0) if abs(x_h) < 5 else rng.uniform(20.0, 32.0))
            shots.append((t_end, x_h, u0, x_b, x_next))
            hitter = -hitter
        pc, t_end = s27.rally(shots, K_DRAG, e_x)
        x_now = shots[-1][4]
        pc.append((t_end, x_now, 0.0))                             # the ball stopped at the back fence
        pieces.append(pc)
        tc = t_end + rng.uniform(0.3, 0.7) / slow
        side = -side
    T_rec = slow * (tc + 0.6 / slow)
    n = int(T_rec / dt)
    t = np.arange(n) * dt
    tr = t / slow
    x = np.zeros(n)
    for (t_c, xa, xb, cs), pc in zip(carries, pieces):
        m = (tr >= t_c) & (tr < pc[0][0])
        x[m] = xa + (xb - xa) * m27.raised_cosine((tr[m] - t_c) / cs)
        nxt = [p for p in carries if p[0] > t_c]
        t1 = nxt[0][0] if nxt else np.inf
        m = (tr >= pc[0][0]) & (tr < t1)
        x[m] = s27.rally_path(tr[m], pc, K_DRAG)
    v = amp * x / np.abs(x).max()
    core = _masing(rng)
    h = _core_of(core, v)
    beta, f_t, zeta = rng.uniform(0.3, 0.5), rng.uniform(2.0, 2.8), rng.uniform(0.2, 0.35)
    y = m27.mount_stage(h, dt, beta, f_t, zeta)
    rec = finish("holdout27_rate_hydraulic_mount_inertia_track_tennis_rally_1130hz", seed, t, v, y,
                 {"rate_dependence"}, "either",
                 f"a hydraulically damped mount under the stage (beta {beta:.2f}, its inertia track at {f_t:.1f} Hz, "
                 f"damping {zeta:.2f}) under a tennis rally ({n_pt} points, played {slow:.1f} times slower), "
                 f"+-{amp:.0f} V, 1.13 kHz", rng, monitor_noise=2.5e-4)
    rec.extra.update(core, amp=amp, slow=slow, e_x=e_x, pieces=pieces, carries=carries, x=x, h=h, beta=beta, f_t=f_t,
                     zeta=zeta, drive=v)
    return rec


@case
def drift_leaking_pneumatic_clamp_pendulum_wave_610hz(seed):
    rng = _rng(seed, 4)
    dt = 1 / 610
    amp = rng.uniform(44.0, 48.0)
    n_p, Gam = int(rng.integers(12, 17)), rng.uniform(14.0, 20.0)
    K = round(rng.uniform(1.6, 2.2) * Gam)
    freqs = (K + np.arange(n_p)) / Gam
    gamma, pull = rng.uniform(0.01, 0.03), rng.uniform(1.0, 1.5)
    t_rel = rng.uniform(0.3, 0.6) + pull
    T_rec = t_rel + rng.uniform(1.1, 1.3) * Gam
    n = int(max(T_rec, 18.5) / dt)
    t = np.arange(n) * dt
    v = s27.pendulum_wave(t, t_rel, freqs, amp, gamma, pull)
    core = _masing(rng)
    h = _core_of(core, v)
    t_s = rng.uniform(0.15, 0.35) * t[-1]
    p0, pa = rng.uniform(4.0, 7.0), 1.0
    tau_b = (t[-1] - t_s) / rng.uniform(2.0, 3.5)
    p = m27.blowdown(t, t_s, p0, pa, tau_b)
    mag, side = rng.uniform(0.04, 0.08), rng.choice([-1.0, 1.0])
    frac = (p0 - p) / (p0 - pa)
    off = side * mag * np.ptp(h) * frac / frac[-1]
    rec = finish("holdout27_drift_leaking_pneumatic_clamp_pendulum_wave_610hz", seed, t, v, h + off, {"drift"},
                 "either",
                 f"an offset drift from a pneumatic clamp leaking after its supply was shut off at {t_s:.1f} s "
                 f"({p0:.1f} bar, tau {tau_b:.1f} s; {side * mag:+.1%} of the span at the end) under a pendulum wave "
                 f"({n_p} pendulums, in step every {Gam:.1f} s), +-{amp:.0f} V, 610 Hz", rng)
    rec.extra.update(core, amp=amp, freqs=freqs, Gam=Gam, gamma=gamma, pull=pull, t_rel=t_rel, h=h, t_s=t_s, p0=p0,
                     pa=pa, tau_b=tau_b, p=p, mag=mag, side=side, offset=off)
    return rec


@case
def asymmetry_conical_vessel_float_heavy_bag_1075hz(seed):
    rng = _rng(seed, 5)
    dt = 1 / 1075
    amp = rng.uniform(44.0, 48.0)
    w, zeta = 2 * math.pi * rng.uniform(0.55, 0.75), rng.uniform(0.03, 0.06)
    combos = [[0.3], [0.3, 0.6], [0.3, 0.3, 0.6], [0.3, 0.6, 0.5], [0.6, 0.5, 0.6], [0.3, 0.6, 0.5, 0.6]]
    punches, tc = [], rng.uniform(0.5, 1.0)
    n_c = int(rng.integers(8, 13))
    for _ in range(n_c):
        for dv in combos[int(rng.integers(0, len(combos)))]:
            punches.append((tc, dv * rng.uniform(0.8, 1.2)))
            tc += rng.uniform(0.15, 0.3)
        tc += rng.uniform(1.0, 2.5)
    n = int((tc + rng.uniform(1.5, 2.5)) / dt)
    t = np.arange(n) * dt
    xb = s27.heavy_bag(t, punches, w, zeta)
    v = amp * xb / np.abs(xb).max()
    core = _masing(rng)
    h = _core_of(core, v)
    c = (h.max() + h.min()) / 2
    X = np.abs(h - c).max()
    asym, side = rng.uniform(0.10, 0.17), rng.choice([-1.0, 1.0])
    xi = brentq(lambda q: -float(m27.cone_reading(1.0, q) + m27.cone_reading(-1.0, q)) - asym, 1e-4, 0.999, xtol=1e-14)
    y = c + side * X * m27.cone_reading(side * (h - c) / X, xi)
    rec = finish("holdout27_asymmetry_conical_vessel_float_heavy_bag_1075hz", seed, t, v, y, {"asymmetry"}, "either",
                 f"a float in a conical vessel filled by the stage's piston (xi {xi:.2f}; the ends' secants {asym:.0%} "
                 f"apart) under a heavy bag worked by a boxer ({n_c} combinations, {len(punches)} punches), "
                 f"+-{amp:.0f} V, 1.075 kHz", rng, monitor_noise=3e-4)
    rec.extra.update(core, amp=amp, w=w, zeta=zeta, punches=punches, xb=xb, centre=c, X=X, asym=asym, side=side,
                     xi=xi, drive=v)
    return rec


@case
def saturation_pulley_weighted_taut_wire_hand_saw_685hz(seed):
    rng = _rng(seed, 6)
    dt = 1 / 685
    amp = rng.uniform(44.0, 48.0)
    n_st = int(rng.integers(30, 46))
    strokes, since = [], 0
    every = int(rng.integers(5, 9))
    for j in range(n_st):
        L = min(1.0, rng.uniform(0.3, 0.5) + j * rng.uniform(0.06, 0.1)) * rng.uniform(0.85, 1.0)
        push = rng.uniform(0.35, 0.6)
        since += 1
        pause = rng.uniform(0.8, 1.5) if since == every else 0.0
        if pause:
            since = 0
        strokes.append((L, push, push * rng.uniform(0.6, 0.8), pause))
    t0 = rng.uniform(0.4, 0.8)
    _, keys = s27.saw_strokes(np.zeros(1), t0, strokes)
    keys = keys + [(keys[-1][0] + 0.6, 0.0)]
    n = int((keys[-1][0] + rng.uniform(0.4, 0.8)) / dt)
    t = np.arange(n) * dt
    xs = s27.cosine_path(t, keys)
    v = amp * xs / np.abs(xs).max()
    core = _masing(rng)
    h = _core_of(core, v)
    c = (h.max() + h.min()) / 2
    X = np.abs(h - c).max()
    comp = rng.uniform(0.12, 0.2)
    z = math.sqrt(1 / (1 - comp) ** 2 - 1)
    y = c + X * m27.wire_reading((h - c) / X, z)
    rec = finish("holdout27_saturation_pulley_weighted_taut_wire_hand_saw_685hz", seed, t, v, y, {"saturation"},
                 "either",
                 f"a load cell on a wire tensioned by a hanging weight and pushed sideways by the stage (the largest "
                 f"push {z:.2f} of the half span; the ends compressed by {comp:.0%}) under a hand saw ({n_st} "
                 f"strokes), +-{amp:.0f} V, 685 Hz", rng)
    rec.extra.update(core, amp=amp, strokes=strokes, keys=keys, h=h, centre=c, X=X, comp=comp, z=z)
    return rec


@case
def delay_thiran_allpass_gmsk_burst_535hz(seed):
    rng = _rng(seed, 7)
    dt = 1 / 535
    amp = rng.uniform(44.0, 48.0)
    rb, BT = rng.uniform(3.5, 5.0), rng.uniform(0.3, 0.5)
    T_b = 1 / rb
    n_bits = int(rb * rng.uniform(20.0, 28.0))
    bits = rng.integers(0, 2, n_bits).astype(bool)
    fade, t0 = rng.uniform(0.6, 1.0), rng.uniform(0.3, 0.6)
    T_rec = t0 + (n_bits + 2) * T_b
    n = int(T_rec / dt)
    t = np.arange(n) * dt
    ph = s27.gmsk_phase(t, bits, T_b, BT, t0 + T_b)
    env = m27.raised_cosine((t - t0) / fade) * (1 - m27.raised_cosine((t - (T_rec - fade - 0.2)) / fade))
    v = amp * env * np.sin(ph)
    core = _masing(rng)
    h = _core_of(core, v)
    D, lat = rng.uniform(2.6, 3.6), int(rng.integers(0, 2))
    y = m27.thiran_sensor(h, D, 3, lat)
    rec = finish("holdout27_delay_thiran_allpass_gmsk_burst_535hz", seed, t, v, y, {"delay"}, "either",
                 f"a sensor aligned by a 3rd-order Thiran allpass (D {D:.2f}) and {lat} sample of latency (a delay of "
                 f"{D + lat:.2f} samples) under one quadrature of a GMSK burst ({n_bits} bits at {rb:.1f} bit/s, BT "
                 f"{BT:.2f}), +-{amp:.0f} V, 535 Hz", rng, monitor_noise=2e-4)
    rec.extra.update(core, amp=amp, rb=rb, BT=BT, bits=bits, fade=fade, t0=t0, ph=ph, env=env, D=D, lat=lat, h=h,
                     drive=v)
    return rec


@case
def initial_state_levitt_staircase_ferris_wheel_705hz(seed):
    rng = _rng(seed, 8)
    dt = 1 / 705
    core = _masing(rng)
    start, mu, s_obs = rng.uniform(80.0, 88.0), rng.uniform(28.0, 40.0), rng.uniform(2.0, 4.0)
    n_rev = int(rng.integers(8, 13))
    levels, answers = m27.levitt_staircase(start, 8.0, n_rev, mu, s_obs, rng, top=start)
    path = np.r_[0.0, levels]
    _, state = _core_of(core, path, return_state=True)
    L0 = float(levels[-1])
    top = rng.uniform(93.0, 98.0)
    n_cab = int(rng.integers(12, 17))
    move_s, dwell_s = rng.uniform(0.5, 0.8), rng.uniform(0.8, 1.4)
    turns, turn_s, ramp_s = rng.choice([1.5, 2.0]), rng.uniform(5.0, 7.0), rng.uniform(1.5, 2.5)
    t_end_probe = n_cab * (move_s + dwell_s) + dwell_s + 2 * ramp_s + (2 * math.pi * turns - 2 * math.pi / turn_s
                                                                     * ramp_s) / (2 * math.pi / turn_s)
    n = int((t_end_probe + rng.uniform(0.8, 1.5)) / dt)
    t = np.arange(n) * dt
    th, t_stop = s27.ferris_angle(t, 0.0, n_cab, move_s, dwell_s, n_cab, turns, turn_s, ramp_s)
    v = L0 + (top - L0) * (1 - np.cos(th)) / 2
    y = _core_of(core, v, state=state)
    rec = finish("holdout27_initial_state_levitt_staircase_ferris_wheel_705hz", seed, t, v, y, {"initial_state"},
                 "either",
                 f"a core left by Levitt's 2-down 1-up staircase ({len(levels)} trials from {start:.0f} V, {n_rev} "
                 f"reversals, ending at {L0:.1f} V, where the record starts) under a Ferris wheel's cabin ({n_cab} "
                 f"cabins loaded, then {turns} turns; the top at {top:.0f} V), 705 Hz", rng)
    rec.extra.update(core, start=start, mu=mu, s_obs=s_obs, n_rev=n_rev, levels=levels, answers=answers, path=path,
                     state=state, L0=L0, top=top, n_cab=n_cab, move_s=move_s, dwell_s=dwell_s, turns=turns,
                     turn_s=turn_s, ramp_s=ramp_s, th=th, t_stop=t_stop)
    return rec


# ---- two effects ----

@case
def pair_delay_saturation_kaiser_decimator_rayleigh_vane_pitch_polar_1265hz(seed):
    rng = _rng(seed, 9)
    dt, R = 1 / 1265, 4
    amp = rng.uniform(44.0, 48.0)
    n_steps = int(rng.integers(3, 5))
    step = amp / n_steps
    osc_A = rng.permutation([1.0, rng.uniform(0.6, 0.9), rng.uniform(0.6, 0.9)]) * amp
    osc = [(osc_A[0], rng.uniform(0.6, 0.9), 3), (osc_A[1], rng.uniform(1.5, 2.0), 5), (osc_A[2], rng.uniform(3.0, 4.0),
                                                                                       8)]
    keys, sines, t_end = s27.pitch_programme(rng.uniform(0.4, 0.8), step, n_steps, rng.uniform(0.5, 0.7),
                                             rng.uniform(0.25, 0.35), osc)
    n = int((t_end + rng.uniform(0.3, 0.6)) / dt)
    tf = np.arange((n - 1) * R + 1) * (dt / R)
    v_f = s27.pitch_path(tf, keys, sines)
    v = v_f[::R]
    t = tf[::R]
    core = _masing(rng)
    h_f = _core_of(core, v_f)
    c = (h_f.max() + h_f.min()) / 2
    X = np.abs(h_f - c).max()
    comp = rng.uniform(0.12, 0.2)
    alpha_m = brentq(lambda q: float(m27.plate_reading(1.0, q)) - (1 - comp), 1e-3, 1.5, xtol=1e-14)
    s_f = c + X * m27.plate_reading((h_f - c) / X, alpha_m)
    Df = float(rng.choice([1.5, 2.0, 2.5]))
    numtaps = int(round(2 * R * Df)) + 1
    cutoff, beta_k = rng.uniform(0.35, 0.45) / R, rng.uniform(5.0, 8.0)
    y = m27.decimating_sensor(s_f, R, numtaps, cutoff, beta_k, 1)
    rec = finish("holdout27_pair_delay_saturation_kaiser_decimator_rayleigh_vane_pitch_polar_1265hz", seed, t, v, y,
                 {"delay", "saturation"}, "either",
                 f"a balance reading a vane's normal force in a wind tunnel (Rayleigh's free-streamline plate, the "
                 f"vane to {math.degrees(alpha_m):.0f} deg; the ends compressed by {comp:.0%}) through a Kaiser-sinc "
                 f"decimator ({numtaps} taps at {R}x, {Df + 1:.1f} samples late in all) under a pitch-pause polar and "
                 f"pitch oscillations, +-{amp:.0f} V, 1.265 kHz", rng)
    rec.extra.update(core, amp=amp, R=R, keys=keys, sines=sines, v_fine=v_f, centre=c, X=X, comp=comp, alpha_m=alpha_m,
                     Df=Df, numtaps=numtaps, cutoff=cutoff, beta_k=beta_k, n_steps=n_steps, step=step)
    return rec


# ---- out of vocabulary ----

@case
def oov_polyfuse_latch_hilo_alarm_1445hz(seed):
    rng = _rng(seed, 10)
    dt, sub = 1 / 1445, 4
    amp = rng.uniform(44.0, 48.0)
    N = int(rng.integers(96, 121))
    N_hi = int(round(N / 2.5))
    f_lo = 1 / (N * dt)
    fuse = dict(C=rng.uniform(30e-6, 40e-6), R0=rng.uniform(10.0, 14.0), ratio=1e4, T_c=rng.uniform(120.0, 130.0),
                width=rng.uniform(2.0, 4.0), G=rng.uniform(3.5e-3, 4.5e-3), tau_th=rng.uniform(0.5, 0.9))
    t_fade, T_A = rng.uniform(0.8, 1.2), rng.uniform(4.0, 5.0)
    c_hi, c_lo = int(round(0.6 * f_lo * 2.5)), int(round(0.4 * f_lo))     # cycles of a hi and of a lo part
    T_B, t_out, tail = rng.uniform(5.0, 6.0), rng.uniform(0.8, 1.2), rng.uniform(0.3, 0.6)
    core = _masing(rng)
    k_y = N * int(math.ceil((t_fade + T_A) / dt / N))           # the alarm starts on a whole period of the tone
    for n_al in range(2, 16):
        segs, k0 = [], k_y
        for _ in range(n_al):
            segs.append((k0 * sub, N_hi * sub, c_hi))
            k0 += N_hi * c_hi + N * c_lo
        k_end = k0                                              # the steady tone resumes (a lo part ended on a period)
        n = int(k_end + (T_B + t_out + tail) / dt)
        kf = np.arange((n - 1) * sub + 1)
        tf = kf * (dt / sub)
        t_end = k_end * dt + T_B
        env = m27.raised_cosine(tf / t_fade) * (1 - m27.raised_cosine((tf - t_end) / t_out))
        v_f = amp * env * np.sin(2 * np.pi * s27.hilo_phase(kf, N * sub, segs))
        vs, Tf = m27.polyfuse_stack(v_f, dt / sub, n_sub=8, **fuse)
        kB = k_end + N * int((T_B - 1.5) / dt / N)              # the last whole periods of the second hold
        if np.abs(vs[(kB - 3 * N) * sub:(kB + 3 * N) * sub]).max() < 0.35 * amp:   # latched: the fuse limits the tone
            break
    kA = k_y - N * int(1.5 / dt / N) - 3 * N                    # the last whole periods of the first hold
    v = v_f[::sub]
    t = tf[::sub]
    h_f = _core_of(core, vs)
    off = rng.uniform(-4.0, 4.0)
    y = h_f[::sub] + off
    rec = finish("holdout27_oov_polyfuse_latch_hilo_alarm_1445hz", seed, t, v, y, set(), "unexplained",
                 f"a polyfuse ({fuse['R0']:.0f} Ohm cold, tripping at {fuse['T_c']:.0f} C) in series with the stack "
                 f"({fuse['C'] * 1e6:.0f} uF); a steady tone at {f_lo:.2f} Hz held, a hi-lo alarm ({n_al} hi parts at "
                 f"{1 / (N_hi * dt):.1f} Hz) that trips the fuse, the steady tone again (the fuse latched hot), "
                 f"+-{amp:.0f} V, 1.445 kHz", rng)
    rec.extra.update(core, fuse=fuse, amp=amp, N=N, N_hi=N_hi, f_lo=f_lo, t_fade=t_fade, t_out=t_out, t_end=t_end,
                     segs=segs, sub=sub, n_al=n_al, c_hi=c_hi, c_lo=c_lo, k_y=k_y, k_end=k_end, kA=kA, kB=kB,
                     vs=vs[::sub], vs_fine=vs, T=Tf[::sub], offset=off)
    return rec

"""The HOLDOUT19 set: written after HOLDOUT18 was measured, by a session that did not read how the diagnosis decides,
to be run once for the next round's measurement; kept out of ALL until then.

Mechanisms and signals that the other sets do not have, or not in these combinations (the laws and signals are in
:mod:`.mechanisms19`, each beside its source; its citations were written from memory, as it says):

- a clean core (100 plays with a Maxwell density of thresholds, r^2 exp(-r^2 / 2 a^2) with a 5 ... 9 V, on 0 ... 40 ...
  46 V: the magnitude of a random three-component local field; a drawn linear part, gain and offset) under the x of
  Roessler's attractor (a = b = 0.2, c = 5.7; its rotation at 0.6 ... 1.1 Hz), centred, faded in from 0 V over 1 s, to
  peaks of +-44 ... 48 V, with a noisy input monitor, sampled at 1.93 kHz;
- creep of a water-saturated pad under the stage consolidating by Terzaghi's law (U(T) = 1 - sum 2 / M^2 exp(-M^2 T), T
  = t / T_v with T_v 1.5 ... 4 s, c 8 ... 14 % of the load in the end; Boltzmann's superposition of the load history),
  under set points held 1.8 ... 3 s at the logarithms of a Collatz (hailstone) orbit of 16 ... 28 numbers, ending at 1
  (0 V), moved between by cubic moves, on a unipolar stroke from 0 V to 88 ... 97 V, sampled at 235 Hz;
- rate dependence of a stage (12 ... 18 Hz) gliding on a layer of viscous oil: the oil's momentum diffuses across the
  layer (Couette flow at low frequencies, Stokes's oscillating layer above its first shear mode at 25 ... 45 Hz; the oil
  1.5 ... 2.5 times the stage's mass), the shear force c0 (q d) coth(q d) x' as 60 Maxwell elements and an added mass;
  under the x of a spirograph's pen (a hypotrochoid, R / r = 5 ... 8 / 2 or 3) drawn ever faster (0.2 ... 0.3 up to 1.0
  ... 1.5 turns a second), +-44 ... 48 V, with a noisy input monitor, sampled at 1.64 kHz;
- a gain drift of a piezo stack heated by its displacement current through its equivalent series resistance (the heat
  C^2 R_s v'^2, a thermal time constant of 3 ... 8 s; d33 rising with the temperature, the gain by 10 ... 14 % at the
  hottest): under whole sine cycles spelled by the Fibonacci word (abaababaab...: each a 3 ... 6 fast cycles at 3.5 ...
  6 Hz and 0.5 ... 0.8 of the peak that heat, each b one slow cycle at 0.25 ... 0.45 Hz at the full +-44 ... 48 V that
  cools), sampled at 1.09 kHz;
- asymmetry of a laser triangulation sensor (a pinhole camera beside the laser: the reading D x / (D + x), the ends'
  slopes 10 ... 17 % apart), under the lower bob of a double pendulum released from rest at large angles (its x chaotic,
  the small oscillations at 0.5 ... 0.9 Hz; the lower bob 0.3 ... 0.6 of the mass, its rod 0.6 ... 1.2 of the upper's),
  faded in from 0 V, +-44 ... 48 V, with a noisy input monitor, sampled at 1.12 kHz;
- saturation of an inclinometer on a tilt stage (the reading L sin(x / L): odd, the ends compressed by 10 ... 17 %),
  under 22 ... 30 set points of Henon's map (a = 1.4, b = 0.3) scaled to 0 ... 88 ... 97 V, reached by cubic moves at
  120 ... 250 V/s and held 0.25 ... 0.6 s, from 0 V, on a unipolar stroke, sampled at 575 Hz;
- a delay of an ultrasonic range finder (a ping every sample, the reading the position where the ping met the target, D0
  0.3 ... 0.7 m away in air at 18 ... 26 C, delivered a fixed number of samples after the ping, its round trip and 1 or
  2 samples of processing: 2.7 ... 5.3 samples), the core computed on an 8x finer grid; under Takagi's blancmange path
  (level 4 ... 6, a period of 1 ... 1.6 s), faded in from 0 V, +-44 ... 48 V, with a noisy input monitor, sampled at
  1.37 kHz;
- a core left by a teleoperator's moves (from the virgin state at 0 V: 6 ... 10 aimed moves to targets in 8 ... 88 V,
  the last but one to 80 ... 88 V, each overshooting by 3 ... 12 % of its distance and corrected, the last down to 48
  ... 54 V), the record starting there; then a swing pumped at twice its frequency (Mathieu's principal resonance, 0.6
  ... 1 Hz, eps set for an envelope growing 10 ... 20 fold) to 94 ... 97 V at its end (its largest swing either way),
  which wipes out the teleoperator's top only late, on a unipolar stroke, sampled at 945 Hz;
- two effects: a core left by a force-proving instrument's calibration (ISO 376: three preloads to 80 ... 88 V, a
  stepped series up and down, then a set point of 46 ... 52 V approached from below; the record starting there) and a
  delay of a magnetostrictive position sensor (a torsional wave from the stage's magnet to the head, 0.4 ... 1.2 m at
  2800 ... 2900 m/s, interrogated at its own 2.5 ... 4 kHz and read by the logger when ready, plus 1 ... 2 samples of
  processing: 1.3 ... 3.6 samples, jittering as the two clocks beat); under a Gibbs square wave (5 ... 8 odd harmonics)
  swept from 0.25 ... 0.35 to 0.8 ... 1.2 Hz, its amplitude growing threefold about the set point to 92 ... 98 V, on a
  unipolar stroke, sampled at 1.185 kHz;
- out of vocabulary: a square prism on a cantilever galloping in a wind tunnel (Parkinson & Smith's quasi-steady lift A1
  a - A3 a^3, A1 2.69, A3 168; the prism at 4 ... 7 Hz, zeta 1.5 ... 3 %; the onset by Den Hartog's criterion at 0.3 ...
  0.4 of the top speed; buffeted by the turbulence), the input the fan's voltage (the wind following it through 0.5 ...
  1 s of rotor inertia) on a schedule of 4 ... 6 set points up to 92 ... 97 V and back to 0, held 4 ... 6 s; the output
  a gauge across the wind at an angle, seeing the self-excited cross-wind oscillation (at the prism's frequency, not the
  input's; growing and dying with the wind's speed) and the along-wind drag (as U^2). A PI core with any effects of the
  vocabulary draws a fixed (or slowly drifting, lagging, delayed, saturated) function of the input's history; none
  oscillates at a frequency of its own while the input holds still, sampled at 385 Hz.
"""

import math

import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

from . import mechanisms19 as m19
from .record import case_set, finish

HOLDOUT19, case, _rng = case_set("holdout19_", 19000)


def _both_sides(v, frac):
    """True when the path reaches beyond frac of its largest magnitude on both sides."""
    return min(v.max(), -v.min()) > frac * np.abs(v).max()


# ---- clean ----

@case
def clean_maxwell_plays_rossler_attractor_1930hz(seed):
    rng = _rng(seed, 1)
    dt = 1 / 1930
    n = int(rng.uniform(12.0, 18.0) / dt)
    t = np.arange(n) * dt
    f_rot = rng.uniform(0.6, 1.1)
    units = 2 * np.pi * f_rot
    fade = m19.raised_cosine(t / 1.0)
    for _ in range(30):                                # starts whose centred x swings both ways beyond 85 %
        start = (rng.uniform(-5.0, 5.0), rng.uniform(-5.0, 5.0), rng.uniform(0.0, 1.0))
        x, s0 = m19.rossler_x(t, units, start)
        xc = x - (x.max() + x.min()) / 2
        if _both_sides(fade * xc, 0.85):
            break
    amp = rng.uniform(44.0, 48.0)
    scale = amp / np.abs(fade * xc).max()
    v = scale * fade * xc
    r_max, a, w0 = rng.uniform(40.0, 46.0), rng.uniform(5.0, 9.0), rng.uniform(0.25, 0.4)
    r, weights = m19.maxwell_plays(100, r_max, a, w0)
    gain, off = rng.uniform(0.7, 1.4), rng.uniform(-4.0, 4.0)
    y = gain * m19.plays(v, r, weights, w0) + off
    rec = finish("holdout19_clean_maxwell_plays_rossler_attractor_1930hz", seed, t, v, y, set(), "explained",
                 f"a clean core (100 plays, a Maxwell density of thresholds with a {a:.1f} V on 0 ... {r_max:.0f} V) "
                 f"under the x of Roessler's attractor (turning at {f_rot:.2f} Hz), faded in from 0 V, +-{amp:.0f} V, "
                 f"1.93 kHz", rng, monitor_noise=3e-4)
    rec.extra.update(thresholds=r, weights=gain * weights, linear=gain * w0, offset=off, r_max=r_max, a=a,
                     f_rot=f_rot, units=units, start=start, s0=s0, x=x, xc=xc, scale=scale, amp=amp, drive=v)
    return rec


# ---- one effect ----

@case
def creep_terzaghi_consolidation_collatz_levels_235hz(seed):
    rng = _rng(seed, 2)
    dt = 1 / 235
    for _ in range(500):                               # a hailstone orbit of 16 ... 28 numbers
        n0 = int(rng.integers(7, 400))
        orbit = m19.collatz(n0)
        if 16 <= len(orbit) <= 28:
            break
    top = rng.uniform(88.0, 97.0)
    levels = top * np.log(orbit) / math.log(orbit.max())
    holds = rng.uniform(1.8, 3.0, len(levels))
    move, lead = rng.uniform(0.25, 0.45), rng.uniform(1.0, 2.0)
    total = lead + len(levels) * move + holds.sum()
    holds[-1] += max(0.0, 44.0 - total)                # at least 10,000 samples
    total = lead + len(levels) * move + holds.sum()
    n = int(total / dt)
    t = np.arange(n) * dt
    v, starts, _ = m19.held_levels(t, lead, levels, holds, move)
    w0 = rng.uniform(0.3, 0.45)
    r, weights = m19.exp_plays(80, 45.0, rng.uniform(8.0, 16.0), w0)
    gain = rng.uniform(0.7, 1.4)
    h = gain * m19.plays(v, r, weights, w0)
    c, T_v = rng.uniform(0.08, 0.14), rng.uniform(1.5, 4.0)
    cr = m19.terzaghi_creep(h, dt, c, T_v)
    rec = finish("holdout19_creep_terzaghi_consolidation_collatz_levels_235hz", seed, t, v, h + cr, {"creep"},
                 "either", f"creep of a saturated pad consolidating by Terzaghi's law ({c:.1%} in the end, T_v "
                 f"{T_v:.2f} s) under the held logarithms of the hailstone orbit of {n0} ({len(orbit)} numbers), 0 "
                 f"... {top:.0f} V, 235 Hz", rng)
    rec.extra.update(n0=n0, orbit=orbit, top=top, levels=levels, holds=holds, move=move, lead=lead, starts=starts,
                     thresholds=r, weights=weights, linear=w0, gain=gain, core=h, c=c, T_v=T_v, creep=cr)
    return rec


@case
def rate_oil_film_shear_stage_spirograph_1640hz(seed):
    rng = _rng(seed, 3)
    dt = 1 / 1640
    n = int(rng.uniform(14.0, 20.0) / dt)
    t = np.arange(n) * dt
    T = t[-1]
    R, r_ = int(rng.integers(5, 9)), int(rng.integers(2, 4))
    if math.gcd(R, r_) != 1:
        R += 1
    d = rng.uniform(0.6, 1.2) * r_
    f0, f1 = rng.uniform(0.2, 0.3), rng.uniform(1.0, 1.5)
    theta = 2 * np.pi * (f0 * t + (f1 - f0) * t * t / (2 * T))
    x = m19.hypotrochoid_x(theta, R, r_, d)
    late = t >= 1.0
    x = x - (x[late].max() + x[late].min()) / 2        # centred on its swing after the fade
    fade = m19.raised_cosine(t / 1.0)
    amp = rng.uniform(44.0, 48.0)
    scale = amp / np.abs(fade * x).max()
    v = scale * fade * x
    w0 = rng.uniform(0.3, 0.45)
    rr, weights = m19.exp_plays(80, 42.0, rng.uniform(8.0, 16.0), w0)
    gain = rng.uniform(0.7, 1.4)
    h = gain * m19.plays(v, rr, weights, w0)
    f_n, zeta_s, m_ratio, f_film = rng.uniform(12.0, 18.0), rng.uniform(0.01, 0.03), rng.uniform(1.5, 2.5), \
        rng.uniform(25.0, 45.0)
    A, B, C = m19.oil_film_matrices(f_n, zeta_s, m_ratio, f_film)
    y = m19.foh_response(A, B, C, h, dt)
    rec = finish("holdout19_rate_oil_film_shear_stage_spirograph_1640hz", seed, t, v, y, {"rate_dependence"},
                 "either", f"a stage at {f_n:.0f} Hz gliding on oil ({m_ratio:.2f} of its mass, the first shear mode "
                 f"at {f_film:.0f} Hz), a spirograph's x (R/r {R}/{r_}) drawn from {f0:.2f} to {f1:.2f} turns a "
                 f"second, +-{amp:.0f} V, 1.64 kHz", rng, monitor_noise=2.5e-4)
    rec.extra.update(R=R, r=r_, d=d, f0=f0, f1=f1, theta=theta, xc=x, scale=scale, amp=amp, thresholds=rr,
                     weights=weights, linear=w0, gain=gain, core=h, f_n=f_n, zeta_s=zeta_s, m_ratio=m_ratio,
                     f_film=f_film, drive=v)
    return rec


@case
def gain_drift_piezo_esr_self_heating_fibonacci_word_1090hz(seed):
    rng = _rng(seed, 4)
    dt = 1 / 1090
    amp = rng.uniform(44.0, 48.0)
    seg = {"a": (int(rng.integers(3, 7)), rng.uniform(3.5, 6.0), rng.uniform(0.5, 0.8) * amp),
           "b": (1, rng.uniform(0.25, 0.45), amp)}
    lead, tail = rng.uniform(0.3, 0.8), rng.uniform(0.3, 0.8)
    n_letters = int(rng.integers(13, 17))
    while True:
        word = m19.fibonacci_word(n_letters)
        dur = lead + sum(seg[ch][0] / seg[ch][1] for ch in word) + tail
        if dur * 1090 < 39_500 or n_letters <= 8:
            break
        n_letters -= 1
    n = int(dur / dt)
    t = np.arange(n) * dt
    v, dv, starts, end = m19.word_cycles(t, lead, word, seg)
    tau = rng.uniform(3.0, 8.0)
    th = m19.esr_heating(dv ** 2, dt, tau)
    rise = rng.uniform(0.10, 0.14)
    g = 1 + rise * th / th.max()
    w0 = rng.uniform(0.3, 0.45)
    r, weights = m19.exp_plays(80, 42.0, rng.uniform(8.0, 16.0), w0)
    gain, off = rng.uniform(0.7, 1.4), rng.uniform(-3.0, 3.0)
    h = gain * m19.plays(v, r, weights, w0)
    rec = finish("holdout19_gain_drift_piezo_esr_self_heating_fibonacci_word_1090hz", seed, t, v, g * h + off,
                 {"gain_drift"}, "either", f"a gain rising by up to {rise:.1%} as a piezo stack heats by its "
                 f"displacement current (tau {tau:.1f} s), sine cycles spelled by the Fibonacci word {word} (a: "
                 f"{seg['a'][0]} at {seg['a'][1]:.1f} Hz, b: one at {seg['b'][1]:.2f} Hz), +-{amp:.0f} V, 1.09 kHz",
                 rng)
    rec.extra.update(amp=amp, seg=seg, lead=lead, word=word, starts=starts, end=end, dv=dv, tau=tau, theta=th,
                     rise=rise,
                     g=g, thresholds=r, weights=weights, linear=w0, gain=gain, offset=off, core=h)
    return rec


@case
def asymmetry_laser_triangulation_double_pendulum_1120hz(seed):
    rng = _rng(seed, 5)
    dt = 1 / 1120
    n = int(rng.uniform(12.0, 20.0) / dt)
    t = np.arange(n) * dt
    f0 = rng.uniform(0.5, 0.9)
    units = 2 * np.pi * f0
    mu, lam = rng.uniform(0.3, 0.6), rng.uniform(0.6, 1.2)
    fade = m19.raised_cosine(t / 1.0)
    for _ in range(30):                                # releases whose bob swings both ways beyond 85 %
        start = (rng.choice([-1, 1]) * rng.uniform(1.6, 2.4), rng.choice([-1, 1]) * rng.uniform(1.6, 2.6), 0.0, 0.0)
        xb, states, tau = m19.double_pendulum(t, units, start, mu, lam)
        if _both_sides(fade * xb, 0.85):
            break
    amp = rng.uniform(44.0, 48.0)
    scale = amp / np.abs(fade * xb).max()
    v = scale * fade * xb
    w0 = rng.uniform(0.3, 0.45)
    r, weights = m19.exp_plays(80, 42.0, rng.uniform(8.0, 16.0), w0)
    x = m19.plays(v, r, weights, w0)
    c = (x.max() + x.min()) / 2
    X = np.abs(x - c).max()
    asym, side = rng.uniform(0.05, 0.085), rng.choice([-1.0, 1.0])
    D = X * (1 + math.sqrt(1 + 4 * asym * asym)) / (2 * asym)     # D X / (D^2 - X^2) = asym
    gain = rng.uniform(0.7, 1.4)
    y = gain * (c + side * m19.triangulation_reading(side * (x - c), D))
    rec = finish("holdout19_asymmetry_laser_triangulation_double_pendulum_1120hz", seed, t, v, y, {"asymmetry"},
                 "either", f"a laser triangulation sensor (the target {D / X:.1f} strokes away, the ends' slopes "
                 f"{2 * asym:.0%} apart) under a double pendulum's lower bob (mass {mu:.2f}, rods 1 : {lam:.2f}, "
                 f"{f0:.2f} Hz), +-{amp:.0f} V, 1.12 kHz", rng, monitor_noise=3.5e-4)
    rec.extra.update(f0=f0, units=units, mu=mu, lam=lam, start=start, xb=xb, states=states, tau=tau, scale=scale,
                     amp=amp, thresholds=r, weights=weights, linear=w0, core=x, centre=c, asym=asym, side=side, D=D,
                     gain=gain, drive=v)
    return rec


@case
def saturation_inclinometer_tilt_stage_henon_setpoints_575hz(seed):
    rng = _rng(seed, 6)
    dt = 1 / 575
    npts = int(rng.integers(22, 31))
    xs = m19.henon_orbit(rng.uniform(-0.5, 0.5), rng.uniform(-0.2, 0.2), npts)
    top = rng.uniform(88.0, 97.0)
    levels = top * (xs - xs.min()) / np.ptp(xs)
    speed, t_min = rng.uniform(120.0, 250.0), rng.uniform(0.1, 0.18)
    moves = np.maximum(np.abs(np.diff(np.r_[0.0, levels])) / speed * 1.5, t_min)   # cubic: peak speed 1.5 x mean
    holds, lead = rng.uniform(0.25, 0.6, npts), rng.uniform(0.3, 0.6)
    total = lead + moves.sum() + holds.sum()
    holds[-1] += max(0.0, 18.0 - total)                # at least 10,000 samples
    total = lead + moves.sum() + holds.sum()
    n = int(total / dt)
    t = np.arange(n) * dt
    v, starts, _ = m19.held_levels(t, lead, levels, holds, moves)
    w0 = rng.uniform(0.3, 0.45)
    r, weights = m19.exp_plays(80, 45.0, rng.uniform(8.0, 16.0), w0)
    gain = rng.uniform(0.7, 1.4)
    h = gain * m19.plays(v, r, weights, w0)
    c = (h.max() + h.min()) / 2
    X = np.abs(h - c).max()
    comp = rng.uniform(0.10, 0.17)
    th_max = brentq(lambda a: math.sin(a) / a - (1 - comp), 1e-6, 2.0, xtol=1e-15)
    L = X / th_max
    y = c + m19.inclinometer_reading(h - c, L)
    rec = finish("holdout19_saturation_inclinometer_tilt_stage_henon_setpoints_575hz", seed, t, v, y,
                 {"saturation"}, "either", f"an inclinometer on a tilt stage (tilting up to {math.degrees(th_max):.0f} "
                 f"deg each way, the ends compressed by {comp:.0%}), {npts} set points of Henon's map, 0 ... "
                 f"{top:.0f} V, 575 Hz", rng)
    rec.extra.update(xs=xs, top=top, levels=levels, speed=speed, t_min=t_min, moves=moves, holds=holds, lead=lead,
                     starts=starts, thresholds=r, weights=weights, linear=w0, gain=gain, core=h, centre=c, comp=comp,
                     th_max=th_max, L=L)
    return rec


@case
def delay_ultrasonic_time_of_flight_takagi_path_1370hz(seed):
    rng = _rng(seed, 7)
    dt, sub = 1 / 1370, 8
    n = int(rng.uniform(12.0, 20.0) / dt)
    t = np.arange(n) * dt
    tf = np.arange((n - 1) * sub + 1) * (dt / sub)
    level, period, ph = int(rng.integers(4, 7)), rng.uniform(1.0, 1.6), rng.uniform(0.0, 1.0)
    amp = rng.uniform(44.0, 48.0)

    def path(tt):
        return amp * m19.raised_cosine(tt / 1.0) * (3 * m19.takagi(tt / period + ph, level) - 1)
    v = path(t)
    w0 = rng.uniform(0.3, 0.45)
    r, weights = m19.exp_plays(60, 40.0, rng.uniform(8.0, 16.0), w0)
    gain = rng.uniform(0.8, 1.4)
    h_f = gain * m19.plays(path(tf), r, weights, w0)
    D0, T_c = rng.uniform(0.3, 0.7), rng.uniform(18.0, 26.0)
    c_s = m19.speed_of_sound(T_c)
    latency = int(math.ceil(2 * D0 / (c_s * dt))) + int(rng.integers(1, 3))      # the echo's processing
    metres = 5e-7                                      # 50 um of stroke per 100 output units
    y, delays = m19.ultrasonic_readings(t, tf, h_f, D0, metres, c_s, latency)
    rec = finish("holdout19_delay_ultrasonic_time_of_flight_takagi_path_1370hz", seed, t, v, y, {"delay"},
                 "either", f"an ultrasonic range finder ({D0:.2f} m in air at {T_c:.0f} C, delivered {latency} "
                 f"samples after the ping: a delay of {delays[n // 2]:.2f} samples), Takagi's blancmange path (level "
                 f"{level}, {period:.1f} s), +-{amp:.0f} V, 1.37 kHz", rng, monitor_noise=2e-4)
    rec.extra.update(level=level, period=period, ph=ph, amp=amp, sub=sub, thresholds=r, weights=weights, linear=w0,
                     gain=gain, D0=D0, T_c=T_c, c_s=c_s, latency=latency, metres=metres, delays=delays, drive=v)
    return rec


@case
def initial_state_fitts_teleoperation_mathieu_swing_945hz(seed):
    rng = _rng(seed, 8)
    dt = 1 / 945
    w0 = rng.uniform(0.3, 0.45)
    r, weights = m19.exp_plays(80, 40.0, rng.uniform(10.0, 16.0), w0)
    n_moves = int(rng.integers(6, 11))
    targets = rng.uniform(8.0, 88.0, n_moves)
    targets[-2] = rng.uniform(80.0, 88.0)                # the last move comes down from the top
    targets[-1] = rng.uniform(48.0, 54.0)
    overshoots = rng.uniform(0.03, 0.12, n_moves)
    hist = m19.fitts_history(targets, overshoots)
    _, z0 = m19.plays(hist, r, weights, w0, return_state=True)
    c = targets[-1]
    f0, zeta = rng.uniform(0.6, 1.0), rng.uniform(0.005, 0.01)
    units = 2 * np.pi * f0
    dur = rng.uniform(18.0, 26.0)
    n = int(dur / dt)
    t = np.arange(n) * dt
    growth = rng.uniform(10.0, 20.0)
    eps = 4 * (math.log(growth) / (dur * units) + zeta)
    x = m19.mathieu_swing(t, units, zeta, eps, 1.0)
    peak = rng.uniform(94.0, 97.0)
    v = c + (peak - c) * x / np.abs(x).max()
    gain = rng.uniform(0.7, 1.4)
    y = gain * m19.plays(v, r, weights, w0, state=z0)
    rec = finish("holdout19_initial_state_fitts_teleoperation_mathieu_swing_945hz", seed, t, v, y,
                 {"initial_state"}, "either", f"a core left by {n_moves} teleoperated moves (overshooting and "
                 f"corrected; up to {hist.max():.0f} V, ending at {c:.1f} V, where the record starts), then a swing "
                 f"pumped at twice its {f0:.2f} Hz (eps {eps:.3f}) growing to {v.max():.0f} V, 945 Hz", rng)
    rec.extra.update(thresholds=r, weights=weights, linear=w0, targets=targets, overshoots=overshoots, history=hist,
                     state=z0, f0=f0, zeta=zeta, eps=eps, units=units, growth=growth, x=x, peak=peak, gain=gain)
    return rec


# ---- two effects ----

@case
def pair_initial_state_delay_iso376_calibration_magnetostrictive_gibbs_square_1185hz(seed):
    rng = _rng(seed, 9)
    dt, sub = 1 / 1185, 8
    w0 = rng.uniform(0.3, 0.45)
    r, weights = m19.exp_plays(80, 42.0, rng.uniform(10.0, 16.0), w0)
    top, n_steps, d0 = rng.uniform(80.0, 88.0), int(rng.integers(8, 11)), rng.uniform(46.0, 52.0)
    hist, steps = m19.iso376_history(top, n_steps, 3, d0)
    _, z0 = m19.plays(hist, r, weights, w0, return_state=True)
    n = int(rng.uniform(16.0, 24.0) / dt)
    t = np.arange(n) * dt
    tf = np.arange((n - 1) * sub + 1) * (dt / sub)
    T = t[-1]
    f0, f1, n_odd = rng.uniform(0.25, 0.35), rng.uniform(0.8, 1.2), int(rng.integers(5, 9))
    peak = rng.uniform(92.0, 98.0)
    s_max = np.abs(m19.gibbs_square(np.linspace(0, 1, 20001), n_odd)).max()

    def path(tt):
        phase = f0 * tt + (f1 - f0) * tt * tt / (2 * T)
        return d0 + (peak - d0) * (1 + 2 * tt / T) / 3 * m19.gibbs_square(phase, n_odd) / s_max
    v = path(t)
    gain = rng.uniform(0.7, 1.4)
    h_f = gain * m19.plays(path(tf), r, weights, w0, state=z0)
    L0, c_w, f_u, phase0 = rng.uniform(0.4, 1.2), rng.uniform(2800.0, 2900.0), rng.uniform(2500.0, 4000.0), \
        rng.uniform(0.0, 1.0)
    proc = rng.uniform(1.0, 2.0) * dt
    metres = 5e-7
    y, delays = m19.magnetostrictive_readings(t, tf, h_f, L0, metres, c_w, f_u, phase0, proc)
    rec = finish("holdout19_pair_initial_state_delay_iso376_calibration_magnetostrictive_gibbs_square_1185hz", seed,
                 t, v, y, {"initial_state", "delay"}, "either", f"a core left by an ISO 376 calibration (preloads "
                 f"to {top:.0f} V, {n_steps} steps up and down, a set point of {d0:.1f} V from below, where the "
                 f"record starts) read by a magnetostrictive sensor ({L0:.2f} m of waveguide, interrogated at "
                 f"{f_u:.0f} Hz: a delay of {delays[n // 10:].min():.2f} ... {delays.max():.2f} samples), a Gibbs "
                 f"square wave of {n_odd} odd harmonics swept {f0:.2f} ... {f1:.2f} Hz and growing to {peak:.0f} V, "
                 f"1.185 kHz", rng)
    rec.extra.update(thresholds=r, weights=weights, linear=w0, top=top, n_steps=n_steps, steps=steps, d0=d0,
                     history=hist, state=z0, f0=f0, f1=f1, n_odd=n_odd, peak=peak, s_max=s_max, sub=sub, gain=gain,
                     L0=L0, c_w=c_w, f_u=f_u, phase0=phase0, proc=proc, metres=metres, delays=delays)
    return rec


# ---- out of vocabulary ----

@case
def oov_galloping_prism_wind_tunnel_speed_schedule_385hz(seed):
    rng = _rng(seed, 10)
    dt = 1 / 385
    n_lv = int(rng.integers(4, 7))
    vtop = rng.uniform(92.0, 97.0)
    levels = np.r_[rng.uniform(20.0, 90.0, n_lv - 1), 0.0]
    levels[int(rng.integers(0, n_lv - 1))] = vtop
    ramp, holds, lead = rng.uniform(1.5, 2.5), rng.uniform(4.0, 6.0, n_lv), rng.uniform(1.0, 2.0)
    total = lead + n_lv * ramp + holds.sum()
    holds[-1] += max(0.0, 27.0 - total)
    total = lead + n_lv * ramp + holds.sum()
    n = int(total / dt)
    t = np.arange(n) * dt
    v, _ = m19.speed_schedule(t, lead, levels, ramp, holds)
    U_max, tau_f = 12.0, rng.uniform(0.5, 1.0)
    U = m19.fan_speed(v, dt, tau_f, U_max)
    f_s, zeta = rng.uniform(4.0, 7.0), rng.uniform(0.015, 0.03)
    w = 2 * np.pi * f_s
    A1, A3 = 2.69, 168.0
    U_g = rng.uniform(0.3, 0.4) * U_max * vtop / 100
    beta = 2 * zeta * w / (A1 * U_g)
    a_top = m19.galloping_amplitude(U_max * vtop / 100, w, zeta, beta, A1, A3)
    nb = 40
    fb, pb = rng.uniform(0.5, 1.5, nb) * f_s, rng.uniform(0, 2 * np.pi, nb)
    b0 = 0.05 * 2 * zeta * w * w * a_top / (U_max * U_max)

    def buffet(tt):
        return b0 * np.sum(np.cos(2 * np.pi * fb * tt + pb)) / math.sqrt(nb)

    def U_of_t(tt):
        return float(np.interp(tt, t, U))
    sol = solve_ivp(m19.galloping_rhs, (0, t[-1]), [0.0, 0.0], t_eval=t, method="DOP853", rtol=1e-9, atol=1e-12,
                        max_step=dt, args=(w, zeta, beta, A1, A3, U_of_t, buffet))
    yc = sol.y[0]
    kappa = rng.uniform(0.6, 1.2) * a_top / (U_max * vtop / 100) ** 2
    gauge = yc + kappa * U * U
    gain, off = rng.uniform(0.7, 1.4) * 40.0 / a_top, rng.uniform(-3.0, 3.0)
    y = gain * gauge + off
    rec = finish("holdout19_oov_galloping_prism_wind_tunnel_speed_schedule_385hz", seed, t, v, y, set(),
                 "unexplained", f"a square prism galloping in a wind tunnel ({f_s:.1f} Hz, zeta {zeta:.3f}, the onset "
                 f"at {U_g:.1f} m/s of {U_max * vtop / 100:.1f}), the fan's voltage on {n_lv} set points up to "
                 f"{vtop:.0f} V, the gauge seeing the cross-wind oscillation and the drag, 385 Hz", rng)
    rec.extra.update(levels=levels, ramp=ramp, holds=holds, lead=lead, U=U, U_max=U_max, tau_f=tau_f, f_s=f_s,
                     zeta=zeta, w=w, A1=A1, A3=A3, U_g=U_g, beta=beta, a_top=a_top, fb=fb, pb=pb, b0=b0, yc=yc,
                     kappa=kappa, gain=gain, offset=off)
    return rec

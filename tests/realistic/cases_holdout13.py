"""The HOLDOUT13 set: written after HOLDOUT12 was measured (thirteenth round), to be run once for the thirteenth
round's measurement (docs/diagnose.md).

Mechanisms and signals that the other sets do not have, or not in these combinations (the laws and signals are
in :mod:`.mechanisms13`, each beside its source):

- a clean core (70 ... 110 plays written from the play's definition at thresholds scattered at random in
  0.3 ... 42 V, gamma-distributed weights under a half-Gaussian envelope of scale 12 ... 25 V, a linear part of
  0.25 ... 0.4, gain and offset) under a load spectrum as fatigue tests draw them: turning points from a Markov
  chain on 21 levels 0, 5, ..., 100 V (from a valley the next peak j levels up with probability proportional to
  exp(-j / s), s 3 ... 5 levels, and likewise down from a peak; Rychlik, Int. J. Fatigue 18 (1996) 429) joined
  by haversine half cycles at 60 ... 120 V/s, from rest at 0 V, reaching 95 V or more, with a noisy input
  monitor, sampled at 1.75 kHz;
- creep of a Kelvin element whose dashpot follows Norton's power law (Norton, *The Creep of Steel at High
  Temperatures*, 1929): de/dt = (x_s / tau) sign(x) |x / x_s|^n on the overstress x = c h - e (c 0.06 ... 0.1 of the
  core's output, tau 0.3 ... 1 s, n 2 ... 3, x_s a half to a quarter of c max |h|), exact per sample: a large
  overstress relaxes 4^(n - 1) times as fast as one of a quarter its size, and every one ends on the algebraic tail
  x_s ((n - 1) t / tau)^(-1 / (n - 1)), not an exponential; under the standard test cycle of ISO 230-2 (5 or 6
  target positions over +-36 V at uneven intervals, each approached and held for 1.2 ... 2 s once moving up and
  once moving down, 2 or 3 bidirectional runs, overruns of 5 ... 8 V, ramps at 40 ... 80 V/s), from and back to
  0 V, sampled at 300 Hz;
- rate dependence from a current-limited amplifier between the recorded command and the stack: i = C dv/dt, so
  the stack's voltage follows the command only while the command is slower than S = I_max / C and otherwise
  slews toward it at +-S (Fleming & Leang, *Design, Modeling and Control of Nanopositioning Systems*, 2014: the
  full-power bandwidth I_max / (pi C V_pp); e.g. 10 mA into 10 uF), S = 2 pi A f_s with f_s 2.5 ... 4 Hz, exact
  for a command linear between samples; under a continuous-phase frequency-shift-keyed sine (tones drawn
  log-uniformly in 0.25 ... 5.5 Hz, successive ones 1.5 times apart or more, dwells of 1 ... 2.5 s, amplitude
  A = 40 ... 47 V, faded in over 0.5 ... 1 s): the slow tones pass untouched, the fast ones are slewed, sampled at
  1.2 kHz;
- an offset drift from a temperature controller's underdamped answer to a set-point step: amp (1 - exp(-zeta
  w_n t') (cos w_d t' + zeta / sqrt(1 - zeta^2) sin w_d t')) from the step at 15 ... 35 % of the record on (Ogata,
  *Modern Control Engineering*, 2010, sec. 5-3; the frame's expansion linear in the temperature), zeta 0.2 ... 0.4
  (an overshoot of 25 ... 53 %), a ringing period of 7 ... 14 s, amp 4 ... 7 % of the core's span, either sign:
  flat, then a rise that overshoots and rings back; under Gaussian (bell-shaped) strokes of widths 80 ... 250 ms
  and heights 35 ... 97 V (one of the first three 92 ... 97 V), each 4 widths clear of its neighbours and 0.2 ...
  0.8 s of rest at 0 V between, sampled at 450 Hz;
- asymmetry from a bridge-type displacement amplifier after the core (rigid-link kinematics: Xu & Li, Mech.
  Mach. Theory 46 (2011) 183): links inclined at 4 ... 8 deg, the output l sin(theta0) - sqrt(l^2 - (l
  cos(theta0) + x / 2)^2) scaled to slope 1, the top of the core's stroke 30 ... 50 % of the way to straight links,
  so the top is stretched by 7 ... 17 % and the bottom compressed by 6 ... 10 % (a square-root law, monotone);
  under a double-sideband suppressed-carrier drive A sin(2 pi f_c t) cos(2 pi f_m t + phi) (carrier 1.5 ... 3 Hz,
  f_m 0.04 ... 0.06 Hz, A 44 ... 49 V: nested loops shrinking to nothing where the envelope passes through zero,
  the carrier's phase flipped there), with a noisy input monitor, sampled at 950 Hz;
- output saturation of an anti-parallel diode clamp protecting the sensor's input: s - y = rho V_D sinh(y / V_D)
  by Shockley's law (rho = 2 I_s R / V_D drawn log-uniformly in 1e-4 ... 1e-2), the signal's zero in the middle of
  its range, V_D such that the ends are compressed by 12 ... 20 %: linear, then a sharp exponential knee beyond
  which the output grows only logarithmically (not a tanh, a polynomial or a rational law); under a chirp up and
  back down, 50 - 50 cos(phi), the frequency rising linearly from 0.15 ... 0.3 Hz to 1.8 ... 3 Hz at mid-record and
  falling back, on a unipolar stroke from 0 V, sampled at 620 Hz;
- a delay that grows: the sensor's recorder runs on its own clock, 80 ... 160 ppm fast (ceramic resonators and
  cheap crystals), and delivers each sample 1 ... 2 periods late, so its k-th sample is the stage's position at
  k dt / (1 + eps) - latency dt: a delay of latency + eps k samples, 2.2 ... 6 samples more at the end than at
  the start; under cycloidal point-to-point moves (x0 + D (s - sin(2 pi s) / 2 pi); R. L. Norton, *Cam Design and
  Manufacturing Handbook*, 2009) between set points in +-45 V at least 20 V apart, at 200 ... 350 V/s on average,
  holds of 0.15 ... 0.6 s, from rest at a set point 15 ... 35 V from 0 V (the core at rest there: every play's
  state the first input), with a noisy input monitor, sampled at 1.4 kHz;
- a core left by an unrecorded dithered approach: from rest at 0 V up to 92 ... 98 V, then down to the start
  18 ... 40 V with a dither of 5 ... 10 V at 40 ... 80 Hz (Zames & Shneydor, IEEE Trans. Autom. Control 21 (1976)
  660) that stays on at the target and fades out over 1 ... 2 s: the plays wider than the dither sit on the
  descending branch from the dither's lowest point, the narrower ones are demagnetised about the start (neither a
  virgin core nor one at rest at the start, nor one left by a plain excursion); then trapezoidal-velocity moves
  (40 ... 90 V/s, 150 ... 400 V/s^2; Biagiotti & Melchiorri, *Trajectory Planning for Automatic Machines and
  Robots*, 2008) with holds of 0.4 ... 1.2 s, first 3 or 4 small ones within 10 V of the start, then across the
  whole stroke (to 99 ... 100 V and 0 V among others), with a noisy input monitor, sampled at 780 Hz;
- two effects: a core left by an interrupted first-order-reversal-curve measurement (from the virgin state up to
  40 ... 45 V, then down to each of 3 ... 6 reversal points from 0.6 of that to -0.1 ... -0.4 of it and back up,
  stopped on the last rise a quarter to 0.6 of the way; Pike, Roberts & Verosub, J. Appl. Phys. 85 (1999) 6660),
  where the record starts, and a split (bi-cell) photodiode under a uniform (top-hat) circular spot reading the
  output: (R / 2) (asin u + u sqrt(1 - u^2)) of the spot's offset u R (the circular segments' areas), the ends of
  the stroke at u = 0.75 ... 0.9 (compressed by 10 ... 16 %, flat at u = 1); under a 1 ... 2 Hz sine of 10 ... 14 V
  whose centre rests at the start for 3 ... 5 s, then glides up to 36 ... 38 V, down to -36 ... -38 V and back to
  0 V, with a noisy input monitor, sampled at 510 Hz;
- out of vocabulary: Mullins's stress softening (Mullins, Rubber Chem. Technol. 42 (1969) 339) of a filled-rubber
  spring loaded by the stack's force (proportional to the drive), in Ogden & Roxburgh's pseudo-elastic form (Proc.
  R. Soc. Lond. A 455 (1999) 2861): f = eta x, eta = 1 - (1 / r) erf((W_m - W) / (m + beta W_m)), W = x^2 / 2, W_m
  its largest value so far (r 3 ... 5, m 0.1 ... 0.3 of the largest A^2 / 2, beta 0.05 ... 0.15): the virgin curve
  x = f at every new largest force, a softer curve inside (up to 20 ... 33 % more deformation) that meets it at the
  largest force; under blocks of 4 or 5 sine cycles (0.5 ... 0.9 Hz, a drawn sign each) at 0.35, 0.55, 0.4, 0.75,
  0.5, 1 and 0.65 (+-0.04) of A = 45 ... 50 V, with holds at 0 V between, sampled at 270 Hz. The record opens a
  loop only in the first cycle of a block that goes beyond the largest force so far (up the virgin curve, down
  the softened one); its later cycles, and every cycle of a block below that force, trace one curve of the input
  with no loop at all, a curve whose shape (not only its scale) depends on the largest force. A PI core (any
  plays with non-negative weights and any linear part) draws the same closed loop in every repeated cycle of one
  amplitude, of zero area only if no play moves, and then no first cycle opens a loop either; creep, rate
  dependence and delay open loops in every cycle; a drift or gain drift in time changes the output during the
  repeats and the holds too, and a gain scales the whole curve where the softened one meets the virgin curve at
  the largest force and lies above it inside; saturation and asymmetry are fixed maps; an initial state is
  forgotten after the first excursion.
"""

import math

import numpy as np
from scipy.optimize import brentq

from . import mechanisms as me
from . import mechanisms13 as m13
from .record import case_set, finish

HOLDOUT13, case, _rng = case_set("holdout13_", 13000)


def _exp_plays(rng, r_max, n, lam):
    """n thresholds evenly spaced in (0, r_max], weights of an exponential density exp(-r / lam), a drawn linear
    part w0; the weights sum to 1 - w0."""
    r = (np.arange(n) + 0.5) * r_max / n
    dens = np.exp(-r / lam)
    w0 = rng.uniform(0.3, 0.45)
    return r, (1 - w0) * dens / dens.sum(), w0


# ---- clean ----

@case
def clean_markov_load_spectrum_random_plays_1750hz(seed):
    rng = _rng(seed, 1)
    dt = 1 / 1750
    levels = np.linspace(0.0, 100.0, 21)
    scale, speed = rng.uniform(3.0, 5.0), rng.uniform(60.0, 120.0)
    total = rng.uniform(14.0, 20.0)
    while True:                                  # a spectrum that reaches the top of the stroke
        pts = m13.markov_turning_points(rng, 600, levels, scale)
        dur = np.maximum(np.abs(np.diff(pts)) / speed, 0.08)
        keep = int(np.searchsorted(np.cumsum(dur), total))
        pts, dur = pts[:keep + 2], dur[:keep + 1]
        if pts.max() >= 95.0:
            break
    v, knots = m13.haversine_path(dt, pts, dur)
    n_p = int(rng.integers(70, 111))
    r = np.sort(rng.uniform(0.3, 42.0, n_p))
    env = np.exp(-(r / rng.uniform(12.0, 25.0)) ** 2 / 2)
    raw = rng.gamma(2.0, 1.0, n_p) * env
    w0 = rng.uniform(0.25, 0.4)
    gain, off = rng.uniform(0.7, 1.4), rng.uniform(-4.0, 4.0)
    weights = gain * (1 - w0) * raw / raw.sum()
    y = m13.plays(v, r, weights, gain * w0) + off
    rec = finish("holdout13_clean_markov_load_spectrum_random_plays_1750hz", seed, np.arange(len(v)) * dt, v, y, set(),
                 "explained", f"a clean core ({n_p} plays at random thresholds, gamma-distributed weights under a "
                 "half-Gaussian envelope) under a Markov-chain load spectrum of haversine half cycles, 0 ... 100 V, "
                 "1.75 kHz", rng, monitor_noise=3e-4)
    rec.extra.update(thresholds=r, weights=weights, linear=gain * w0, offset=off, points=pts, knots=knots,
                     markov_scale=scale, speed=speed, drive=v)
    return rec


# ---- one effect ----

@case
def creep_norton_kelvin_iso230_cycle_300hz(seed):
    rng = _rng(seed, 2)
    dt = 1 / 300
    m = int(rng.integers(5, 7))
    step = 72.0 / (m - 1)
    targets = -36.0 + step * np.arange(m) + rng.uniform(-0.25, 0.25, m) * step     # ISO 230-2: uneven spacing
    runs = int(rng.integers(2, 4))
    overrun, speed = rng.uniform(5.0, 8.0), rng.uniform(40.0, 80.0)
    holds_s = rng.uniform(1.2, 2.0, 2 * m * runs)
    knots, dirs = m13.iso230_knots(targets, runs, overrun, holds_s, 0.15)
    v, holds = m13.ramps_and_holds(dt, 0.0, [(0.0, 1.0)] + knots + [(0.0, 1.0)], speed)
    holds, dirs = holds[1:-1], np.array(dirs)
    gain = rng.uniform(0.7, 1.4)
    h = me.play_core(v, 100.0, gain=gain)
    c = rng.uniform(0.06, 0.1)
    p = dict(c=c, tau=rng.uniform(0.3, 1.0), x_s=c * np.abs(h).max() / rng.uniform(2.0, 4.0), n=rng.uniform(2.0, 3.0))
    y = h + m13.norton_kelvin(h, dt, **p)
    rec = finish("holdout13_creep_norton_kelvin_iso230_cycle_300hz", seed, np.arange(len(v)) * dt, v, y, {"creep"},
                 "either", f"creep of a Kelvin element with a Norton power-law dashpot (n {p['n']:.2f}, c {c:.2f}, tau "
                 f"{p['tau']:.2f} s), the ISO 230-2 bidirectional test cycle ({m} targets, {runs} runs, holds 1.2 ... "
                 "2 s), 300 Hz", rng)
    rec.extra.update(targets=targets, runs=runs, overrun=overrun, speed=speed, holds=holds, directions=dirs,
                     knots=knots, gain=gain, core=h, **p)
    return rec


@case
def rate_slew_limited_amplifier_fsk_sine_1200hz(seed):
    rng = _rng(seed, 3)
    dt = 1 / 1200
    total = rng.uniform(20.0, 28.0)
    switches, freqs = [0.0], [rng.uniform(0.25, 0.6)]
    while switches[-1] < total:
        switches.append(switches[-1] + rng.uniform(1.0, 2.5))
        f = math.exp(rng.uniform(math.log(0.25), math.log(5.5)))
        while max(f / freqs[-1], freqs[-1] / f) < 1.5:
            f = math.exp(rng.uniform(math.log(0.25), math.log(5.5)))
        freqs.append(f)
    t = np.arange(int(total / dt)) * dt
    amp, fade = rng.uniform(40.0, 47.0), rng.uniform(0.5, 1.0)
    v, _ = m13.fsk_sine(t, switches, freqs, amp, fade)
    f_s = rng.uniform(2.5, 4.0)                 # the full-power bandwidth S / (2 pi amp)
    s_max = 2 * np.pi * amp * f_s
    va = m13.slew_limited(v, dt, s_max)
    r = (np.arange(100) + 0.5) * 0.4
    dens = 1 - r / 40.0                         # a triangular density of thresholds
    w0 = rng.uniform(0.3, 0.45)
    weights = (1 - w0) * dens / dens.sum()
    gain = rng.uniform(0.8, 1.4)
    y = gain * m13.plays(va, r, weights, w0)
    rec = finish("holdout13_rate_slew_limited_amplifier_fsk_sine_1200hz", seed, t, v, y, {"rate_dependence"}, "either",
                 f"a current-limited amplifier (slew {s_max:.0f} V/s, full power to {f_s:.1f} Hz) between the recorded "
                 f"command and the core, a continuous-phase FSK sine ({len(freqs)} tones, 0.25 ... 5.5 Hz), 1.2 kHz",
                 rng)
    rec.extra.update(switches=np.array(switches), freqs=np.array(freqs), amp=amp, fade=fade, s_max=s_max, f_s=f_s,
                     applied=va, thresholds=r, weights=weights, linear=w0, gain=gain)
    return rec


@case
def drift_pid_thermal_overshoot_gaussian_pulses_450hz(seed):
    rng = _rng(seed, 4)
    dt = 1 / 450
    total = rng.uniform(32.0, 42.0)
    widths, heights, centres = [], [], []
    w = rng.uniform(0.08, 0.25)
    c = rng.uniform(0.5, 1.0) + 4 * w
    while c + 4 * w < total:
        centres.append(c)
        widths.append(w)
        heights.append(rng.uniform(35.0, 97.0))
        w_next = rng.uniform(0.08, 0.25)
        c += 4 * w + 4 * w_next + rng.uniform(0.2, 0.8)
        w = w_next
    heights[int(rng.integers(0, 3))] = rng.uniform(92.0, 97.0)      # a full stroke early on
    t = np.arange(int(total / dt)) * dt
    v = m13.gaussian_pulses(t, centres, heights, widths)
    gain = rng.uniform(0.7, 1.4)
    h = me.play_core(v, 100.0, gain=gain)
    p = dict(t_s=total * rng.uniform(0.15, 0.35), amp=rng.choice([-1.0, 1.0]) * rng.uniform(0.04, 0.07) * np.ptp(h),
             zeta=rng.uniform(0.2, 0.4), period=rng.uniform(7.0, 14.0))
    drift = m13.pid_thermal_offset(t, **p)
    y = h + drift
    rec = finish("holdout13_drift_pid_thermal_overshoot_gaussian_pulses_450hz", seed, t, v, y, {"drift"}, "either",
                 f"an offset following a temperature controller's underdamped answer to a set-point step at "
                 f"{p['t_s']:.0f} s (zeta {p['zeta']:.2f}, ringing {p['period']:.0f} s), Gaussian strokes 0 ... 97 V "
                 "with rests, 450 Hz", rng)
    rec.extra.update(centres=np.array(centres), heights=np.array(heights), widths=np.array(widths), gain=gain, core=h,
                     offset=drift, **p)
    return rec


@case
def asymmetry_bridge_amplifier_dsb_sc_950hz(seed):
    rng = _rng(seed, 5)
    dt = 1 / 950
    t = np.arange(int(rng.uniform(22.0, 30.0) / dt)) * dt
    sig = dict(amp=rng.uniform(44.0, 49.0), f_c=rng.uniform(1.5, 3.0), f_m=rng.uniform(0.04, 0.06),
               phi_m=rng.uniform(0.0, np.pi / 4))
    v = m13.dsb_sc(t, **sig)
    r, weights, w0 = _exp_plays(rng, 40.0, 120, rng.uniform(8.0, 16.0))
    x = m13.plays(v, r, weights, w0)
    theta0 = np.radians(rng.uniform(4.0, 8.0))
    q = rng.uniform(0.3, 0.5)                   # x / 2 at the top, of the links' straightening point
    length = x.max() / 2 / (q * (1 - math.cos(theta0)))
    gain = rng.uniform(0.7, 1.4)
    y = gain * m13.bridge_amplifier(x, length, theta0)
    rec = finish("holdout13_asymmetry_bridge_amplifier_dsb_sc_950hz", seed, t, v, y, {"asymmetry"}, "either",
                 f"a bridge-type displacement amplifier after the core (links at {np.degrees(theta0):.1f} deg, "
                 f"{q:.0%} of the way to straight at the top), a DSB-SC drive ({sig['f_c']:.1f} Hz carrier), 950 Hz",
                 rng, monitor_noise=4e-4)
    rec.extra.update(thresholds=r, weights=weights, linear=w0, theta0=theta0, length=length, q=q, gain=gain, core=x,
                     signal=sig, drive=v)
    return rec


@case
def saturation_diode_clamp_v_chirp_620hz(seed):
    rng = _rng(seed, 6)
    dt = 1 / 620
    total = rng.uniform(20.0, 28.0)
    t = np.arange(int(total / dt)) * dt
    f0, f1 = rng.uniform(0.15, 0.3), rng.uniform(1.8, 3.0)
    v, _ = m13.v_chirp(t, 50.0, 50.0, f0, f1, total)
    r = (np.arange(110) + 0.5) * 45.0 / 110
    dens = np.exp(-(r / rng.uniform(10.0, 20.0)) ** 2 / 2)      # a half-Gaussian density
    w0 = rng.uniform(0.3, 0.45)
    weights = (1 - w0) * dens / dens.sum()
    x = m13.plays(v, r, weights, w0)
    mid = (x.max() + x.min()) / 2
    s = x - mid
    top = np.abs(s).max()
    rho = math.exp(rng.uniform(math.log(1e-4), math.log(1e-2)))
    kappa = rng.uniform(0.12, 0.2)              # the compression at the ends of the stroke
    v_d = brentq(lambda vd: 1 - m13.diode_clamp(np.array([top]), rho, vd)[0] / top - kappa, top / 40, top)
    gain = rng.uniform(0.8, 1.5)
    y = gain * (mid + m13.diode_clamp(s, rho, v_d))
    rec = finish("holdout13_saturation_diode_clamp_v_chirp_620hz", seed, t, v, y, {"output_saturation"}, "either",
                 f"the sensor's signal through an anti-parallel diode clamp (compressed {kappa:.0%} at the ends), a "
                 f"chirp up to {f1:.1f} Hz and back, 0 ... 100 V, 620 Hz", rng)
    rec.extra.update(thresholds=r, weights=weights, linear=w0, mid=mid, rho=rho, v_d=v_d, kappa=kappa, gain=gain,
                     core=x, f0=f0, f1=f1, total=total)
    return rec


@case
def delay_clock_skew_cycloid_moves_1400hz(seed):
    rng = _rng(seed, 7)
    dt = 1 / 1400
    total = rng.uniform(20.0, 27.0)
    v0 = rng.choice([-1.0, 1.0]) * rng.uniform(15.0, 35.0)
    v_avg = rng.uniform(200.0, 350.0)
    starts, durs, x_from, x_to = [], [], [], []
    tc, cur = rng.uniform(0.5, 1.0), v0
    while True:
        nxt = rng.uniform(-45.0, 45.0)
        while abs(nxt - cur) < 20.0:
            nxt = rng.uniform(-45.0, 45.0)
        d = max(abs(nxt - cur) / v_avg, 0.12)
        if tc + d + 0.2 > total:
            break
        starts.append(tc)
        durs.append(d)
        x_from.append(cur)
        x_to.append(nxt)
        tc += d + rng.uniform(0.15, 0.6)
        cur = nxt
    n = int(total / dt)
    t = np.arange(n) * dt
    path = dict(starts=np.array(starts), durations=np.array(durs), x_from=np.array(x_from), x_to=np.array(x_to))
    v = m13.cycloid_path(t, **path)
    eps, latency = rng.uniform(80e-6, 160e-6), rng.uniform(1.0, 2.0)
    v_seen = m13.cycloid_path(m13.skewed_instants(n, dt, latency, eps), **path)
    gain = rng.uniform(0.8, 1.4)
    rest = np.full(200, v0)                      # at rest at the first set point
    y = me.play_core(v_seen, 100.0, gain=gain, state=rest)
    d_end = latency + eps / (1 + eps) * (n - 1)
    rec = finish("holdout13_delay_clock_skew_cycloid_moves_1400hz", seed, t, v, y, {"delay"}, "either",
                 f"the sensor's recorder on its own clock ({eps * 1e6:.0f} ppm fast, {latency:.2f} samples of latency: "
                 f"the delay grows to {d_end:.1f} samples), cycloidal moves from rest at {v0:.0f} V, 1.4 kHz", rng,
                 monitor_noise=2e-4)
    rec.extra.update(eps=eps, latency=latency, delay_end=d_end, v0=v0, v_avg=v_avg, gain=gain, drive=v, **path)
    return rec


@case
def initial_state_dithered_approach_trapezoid_moves_780hz(seed):
    rng = _rng(seed, 8)
    dt = 1 / 780
    f_d = rng.uniform(40.0, 80.0)
    hist = dict(top=rng.uniform(92.0, 98.0), v0=rng.uniform(18.0, 40.0), rise_s=rng.uniform(1.0, 2.0),
                top_hold_s=rng.uniform(0.3, 1.0), approach_s=rng.uniform(2.0, 4.0), dither=rng.uniform(5.0, 10.0),
                f_d=f_d, settle_s=rng.uniform(1.0, 2.0))
    dense = m13.dithered_approach(1 / (40 * f_d), **hist)
    pre = m13.turning_points(dense)
    _, z = me.play_core(pre, 100.0, return_state=True)
    v0 = hist["v0"]
    small = [v0 + s * rng.uniform(3.0, 10.0) for s in (1, -1, 1, -1)[:int(rng.integers(3, 5))]]
    big = list(rng.permutation([rng.uniform(99.0, 100.0), 0.0, rng.uniform(55.0, 75.0), rng.uniform(20.0, 40.0)]))
    while len(big) < 8:
        p = rng.uniform(0.0, 100.0)
        if abs(p - big[-1]) >= 20.0:
            big.append(p)
    pts = small + big + [rng.uniform(40.0, 60.0)]
    holds_s = rng.uniform(0.4, 1.2, len(pts))
    mv = dict(v_max=rng.uniform(40.0, 90.0), a_max=rng.uniform(150.0, 400.0))
    v, holds = m13.trapezoidal_moves(dt, v0, rng.uniform(0.5, 1.0), pts, holds_s, **mv)
    y = me.play_core(v, 100.0, state=z)
    rec = finish("holdout13_initial_state_dithered_approach_trapezoid_moves_780hz", seed, np.arange(len(v)) * dt, v,
                 y, {"initial_state"}, "either", f"a core left by a dithered approach ({hist['dither']:.0f} V at "
                 f"{f_d:.0f} Hz) from {hist['top']:.0f} V down to {v0:.0f} V, faded out there, then "
                 "trapezoidal-velocity moves with holds, 0 ... 100 V, 780 Hz", rng, monitor_noise=1e-4)
    rec.extra.update(history=pre, history_dense=dense, history_dt=1 / (40 * f_d), points=np.array(pts), holds=holds,
                     signal=hist, drive=v, **mv)
    return rec


# ---- two effects ----

@case
def pair_initial_state_saturation_forc_bicell_swept_offset_sine_510hz(seed):
    rng = _rng(seed, 9)
    dt = 1 / 510
    top = rng.uniform(40.0, 45.0)
    k = int(rng.integers(3, 7))
    rev = np.linspace(0.6 * top, -rng.uniform(0.1, 0.4) * top, k) + rng.uniform(-2.0, 2.0, k)
    pre = m13.forc_points(top, rev, rng.uniform(0.25, 0.6))
    r, weights, w0 = _exp_plays(rng, 40.0, 120, rng.uniform(10.0, 18.0))
    _, z = m13.plays(pre, r, weights, w0, return_state=True)
    total = rng.uniform(20.0, 28.0)
    t = np.arange(int(total / dt)) * dt
    v_start = pre[-1]
    c_hi, c_lo = rng.uniform(36.0, 38.0), -rng.uniform(36.0, 38.0)
    t1, t2, t3 = (rng.uniform(0.35, 0.45) * total, rng.uniform(0.6, 0.7) * total, rng.uniform(0.85, 0.9) * total)
    t0 = rng.uniform(3.0, 5.0)
    centre = (v_start + (c_hi - v_start) * m13.raised_cosine((t - t0) / (t1 - t0))
              + (c_lo - c_hi) * m13.raised_cosine((t - t1) / (t2 - t1))
              - c_lo * m13.raised_cosine((t - t2) / (t3 - t2)))
    a_s, f = rng.uniform(10.0, 14.0), rng.uniform(1.0, 2.0)
    v = centre + a_s * m13.raised_cosine(t / 1.5) * np.sin(2 * np.pi * f * t)
    x = m13.plays(v, r, weights, w0, state=z)
    x_c = (x.max() + x.min()) / 2
    u_max = rng.uniform(0.75, 0.9)
    radius = np.abs(x - x_c).max() / u_max
    gain = rng.uniform(0.7, 1.4)
    y = gain * m13.bicell_tophat(x, x_c, radius)
    rec = finish("holdout13_pair_initial_state_saturation_forc_bicell_swept_offset_sine_510hz", seed, t, v, y,
                 {"initial_state", "output_saturation"}, "either",
                 f"a core left by an interrupted FORC run (top {top:.0f} V, {k} reversals, stopped at {v_start:.0f} V) "
                 f"read by a bi-cell photodiode under a top-hat spot ({u_max:.2f} of its radius at the ends), a sine "
                 "whose centre sweeps the stroke, 510 Hz", rng, monitor_noise=5e-4)
    rec.extra.update(history=pre, top=top, reversals=rev, thresholds=r, weights=weights, linear=w0, state=z, x_c=x_c,
                     radius=radius, u_max=u_max, gain=gain, core=x, centre=centre, a_s=a_s, f=f, drive=v)
    return rec


# ---- out of vocabulary ----

@case
def oov_mullins_softening_sine_blocks_270hz(seed):
    rng = _rng(seed, 10)
    dt = 1 / 270
    amp = rng.uniform(45.0, 50.0)
    fracs = np.array([0.35, 0.55, 0.4, 0.75, 0.5, 1.0, 0.65]) + rng.uniform(-0.04, 0.04, 7)
    fracs[5] = 1.0
    freq, cycles = rng.uniform(0.5, 0.9), int(rng.integers(4, 6))
    holds_s = rng.uniform(0.3, 0.8, 8)
    signs = rng.choice([-1.0, 1.0], 7)
    v, blocks = m13.sine_blocks(dt, amp * fracs, freq, cycles, holds_s, signs)
    p = dict(r=rng.uniform(3.0, 5.0), m=rng.uniform(0.1, 0.3) * amp ** 2 / 2, beta=rng.uniform(0.05, 0.15))
    x, mm = m13.mullins_spring(v, **p)
    gain = rng.uniform(0.8, 1.4)
    y = gain * x
    rec = finish("holdout13_oov_mullins_softening_sine_blocks_270hz", seed, np.arange(len(v)) * dt, v, y, set(),
                 "unexplained", f"a filled-rubber spring with Mullins softening (Ogden-Roxburgh, r {p['r']:.1f}) under "
                 f"the stack's force, blocks of {cycles} sine cycles at amplitudes that rise, fall back and rise, "
                 "270 Hz", rng)
    rec.extra.update(amp=amp, fracs=fracs, freq=freq, cycles=cycles, blocks=blocks, signs=signs, gain=gain,
                     running_max=mm, **p)
    return rec

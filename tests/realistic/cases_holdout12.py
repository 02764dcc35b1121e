"""The HOLDOUT12 set: written after HOLDOUT11 was measured (2026-11-26, twelfth round), to be run once
for the twelfth round's measurement (docs/diagnose.md); kept out of ALL until then.

Mechanisms and signals that the other sets do not have, or not in these combinations (the laws and
signals are in :mod:`.mechanisms12`):

- a clean core (130 plays written from the play's definition, with a Cauchy (Lorentzian) density of
  thresholds 1 / (1 + (r / g)^2), g 6 ... 14 V: a heavy tail of wide plays, a drawn linear part, gain
  and offset) under narrow-band random drive (Gaussian noise through a 4th-order Butterworth band-pass
  around 0.5 ... 1 Hz, 1.3 ... 1.6 times either side: a random carrier with a Rayleigh envelope), faded
  in from rest at 0 V to peaks of +-44 ... 50 V, with a noisy input monitor, sampled at 1.45 kHz;
- creep of a Kelvin element whose dashpot follows Eyring's stress-activated flow, de/dt = (s / tau)
  sinh((c h - e) / s) (Eyring, J. Chem. Phys. 4 (1936) 283; the nonlinear Kelvin model of polymer creep,
  Ward & Sweeney, *Mechanical Properties of Solid Polymers*, 2013, ch. 10): c 0.07 ... 0.12 of the core's
  output, tau 1 ... 3 s at small overstress, the activation scale s a quarter to a half of c max |h| (big
  steps creep several times faster at first than small ones), exact per sample, under jerk-limited
  seven-segment (S-curve) point-to-point moves (peak speed 60 ... 150 V/s, acceleration 300 ... 900
  V/s^2, jerk 3,000 ... 12,000 V/s^3; Lambrechts, Boerlage & Steinbuch, Control Eng. Pract. 13 (2005)
  145) between set points in +-45 V, each followed by a hold of 1.5 ... 4 s, sampled at 260 Hz;
- rate dependence from an orifice damper behind the stage (a piezo-hydraulic stroke amplifier whose oil
  passes an orifice): the flexure's force balances the turbulent orifice law, k (h - y) = c dy/dt |dy/dt|
  (the pressure drop grows as the square of the flow; Merritt, *Hydraulic Control Systems*, 1967, ch. 2),
  so the stage lags the core's output h by (dh/dt)^2 / a^2 (a = sqrt(k / c)), 12 ... 16 % of max |h| at
  the fastest: a lag in the square of the rate, not a fixed time, settling in finite time after a step,
  under an odd random-phase multisine (equal odd harmonics of 0.12 ... 0.2 Hz up to 5 ... 7 Hz, random
  phases; Pintelon & Schoukens, *System Identification*, 2012, sec. 2.6) faded in from 0 V to peaks of
  +-44 ... 49 V, two periods, with a noisy input monitor, sampled at 1.8 kHz;
- a gain drift from ageing after a re-poling pulse: the piezoelectric coefficient falls linearly in the
  logarithm of the time since it (Jaffe, Cook & Jaffe, *Piezoelectric Ceramics*, 1971, ch. 7),
  1 - rate log10((t + t_p) / t_p), rate 2.5 ... 4 % per decade, the pulse t_p = 0.3 ... 1 s before the
  record, under a full-wave rectified sine (85 ... 97 V, 0.7 ... 1.4 pulses per second, cusps at 0 V) on
  a unipolar stroke, sampled at 540 Hz;
- asymmetry from a preloaded Hertzian contact between the stack and its load: the approach follows
  F = K delta^(3/2) (Hertz 1882; Johnson, *Contact Mechanics*, 1985, sec. 4.2), so the output is
  1.5 F0 ((1 + F / F0)^(2/3) - 1) of the core's force F (stiffer in compression; max |F| / F0 0.3 ... 0.5),
  under skewed triangles (peaks of alternating sign and drawn heights, 0.7 ... 1 of 44 ... 48 V; periods
  1 ... 2.6 s, the rising ramp 15 ... 85 % of each, drawn per cycle), with a noisy input monitor, sampled
  at 1.15 kHz;
- output saturation of a homodyne (fibre) interferometer held at its quadrature point in the middle of
  the stroke: the signal is x_q + b sin((x - x_q) / b), b = lambda / (4 pi) (Rugar, Mamin & Guethner,
  Appl. Phys. Lett. 55 (1989) 2588), the phase reaching 0.8 ... 1.05 rad at the ends (compressed by 10 ...
  17 %), under an amplitude-modulated sine about 50 V (carrier 1.5 ... 3 Hz, modulation period 10 ...
  16 s, depth 0.5 ... 0.8, amplitude 44 ... 48 V) faded in from 0 V on a unipolar stroke, sampled at
  850 Hz;
- a delay of the sensor's sigma-delta converter: the core's output at the modulator rate (R = 8 or 16
  times the output rate) through a sinc^K decimation filter (K = 3, 4 or 5 moving sums of R samples: a
  CIC filter, Hogenauer, IEEE Trans. Acoust. Speech Signal Process. 29 (1981) 155) and delivered one
  sample late: 1 + K (R - 1) / (2 R) = 2.3 ... 3.3 samples, under a switched RC drive (the stack charged
  through a resistor, RC 40 ... 120 ms, toward targets in 5 ... 95 V switched every 0.35 ... 1.2 s) on a
  unipolar stroke, sampled at 480 Hz;
- a core left by an unrecorded band-limited random run (6 ... 10 s of low-passed noise to +-38 ... 43 V)
  stopped at its last excursion beyond 75 % of its peak, and the servo's first-order settling (0.1 ...
  0.3 s) from there to a set point 0.15 ... 0.45 of that on the same side (approached from outside), where
  the record starts, before a quasi-periodic two-tone (frequencies in the golden ratio, 0.5 ... 0.9 Hz and
  1.618 times that) whose envelope grows linearly from 0 while the level glides from the set point to
  0 V, out to beyond the run's extremes, with a noisy input monitor, sampled at 1.02 kHz;
- two effects: a core left by an unrecorded unipolar run (3 ... 5 triangles 0 ... 88 ... 97 V, a last rise
  to the top and a ramp down to a parking bias of 25 ... 40 V, held long enough for its creep to relax),
  where the record starts, and creep with the Cole-Davidson compliance c P(gamma, t / tau) (P the
  regularised incomplete gamma function, the step response of c / (1 + i omega tau)^gamma; Davidson &
  Cole, J. Chem. Phys. 19 (1951) 1484; c 0.07 ... 0.11, tau 1 ... 4 s, gamma 0.3 ... 0.6) by Boltzmann
  superposition, under a stepped cosine from the bias (levels A_k cos(2 pi k / N), N 4, 6 or 8, A_k
  growing geometrically from 10 ... 16 V to 47 ... 50 V, ending at -A_end and back to 0 V; raised-cosine
  steps, holds of 1.5 ... 3 s), with a noisy input monitor, sampled at 380 Hz;
- out of vocabulary: Coleman & Hodgdon's rate-independent Duhem law dy/dt = alpha |dv/dt| (a v - y) +
  g(v) dv/dt (Coleman & Hodgdon, Int. J. Eng. Sci. 24 (1986) 897; Duhem models: Macki, Nistri & Zecca,
  SIAM Rev. 35 (1993) 94) with g(v) = a + c (1 - 2 v^2 / v_x^2), above the anhysteretic slope a in the
  middle of the stroke and below it outside: the branches sit at about a v + s (g(v) - a) / alpha (s = 1
  rising, -1 falling), so every large loop crosses itself near |v| = v_x / sqrt(2) (0.5 ... 0.62 of the
  rail): clockwise in the middle (the rising branch above the falling one by up to 2 c / alpha = 4.4 ...
  7 output units per unit gain), counter-clockwise toward the ends (a figure eight). Under a sine
  overdriving an amplifier into its rails (v_rail tanh(m sin(2 pi f t)), v_rail 44 ... 48 V, f 0.4 ...
  0.8 Hz, the overdrive m swinging between 1.2 ... 1.5 and 2.5 ... 3.5 over 8 ... 14 s), sampled at
  330 Hz. A PI core (any plays with non-negative weights and any linear part) has its falling branch
  above or on its rising one at every input; no output map, rate, creep, drift, delay or initial-state
  part turns a loop's middle clockwise while its ends stay counter-clockwise at every amplitude.
"""

import numpy as np
from scipy.signal import butter, sosfilt

from . import mechanisms as me
from . import mechanisms12 as m12
from .record import case_set, finish

HOLDOUT12, case, _rng = case_set("holdout12_", 12000)


# ---- clean ----

@case
def clean_cauchy_plays_narrowband_random_1450hz(seed):
    rng = _rng(seed, 1)
    dt = 1 / 1450
    n = int(round(rng.uniform(14.0, 20.0) / dt))
    fc, bw = rng.uniform(0.5, 1.0), rng.uniform(1.3, 1.6)
    v = m12.narrowband_random(dt, n, fc / bw, fc * bw, rng.uniform(44.0, 50.0), rng.uniform(1.0, 2.0), rng)
    r = m12.grid(45.0, 130)
    g = rng.uniform(6.0, 14.0)
    dens = 1 / (1 + (r / g) ** 2)
    w0 = rng.uniform(0.25, 0.4)
    gain, off = rng.uniform(0.7, 1.5), rng.uniform(-4.0, 4.0)
    weights = gain * (1 - w0) * dens / dens.sum()
    y = m12.plays(v, r, weights, gain * w0) + off
    rec = finish("holdout12_clean_cauchy_plays_narrowband_random_1450hz", seed, np.arange(n) * dt, v, y, set(),
                 "explained", f"a clean core (130 plays, a Cauchy threshold density of scale {g:.0f} V) under "
                 f"narrow-band random drive ({fc / bw:.2f} ... {fc * bw:.2f} Hz), 1.45 kHz", rng, monitor_noise=3e-4)
    rec.extra.update(thresholds=r, weights=weights, linear=gain * w0, offset=off, cauchy_scale=g, f_lo=fc / bw,
                     f_hi=fc * bw, drive=v)
    return rec


# ---- one effect ----

@case
def creep_eyring_kelvin_s_curve_moves_260hz(seed):
    rng = _rng(seed, 2)
    dt = 1 / 260
    n_moves = int(rng.integers(12, 17))
    while True:                                          # set points 20 V apart at least, reaching both sides
        pts = [0.0]
        while len(pts) <= n_moves:
            p = rng.uniform(-45.0, 45.0)
            if abs(p - pts[-1]) >= 20.0:
                pts.append(p)
        if min(pts) < -32 and max(pts) > 32:
            break
    pts.append(0.0)                                      # and back to 0 V
    lim = dict(v_max=rng.uniform(60.0, 150.0), a_max=rng.uniform(300.0, 900.0), jerk=rng.uniform(3000.0, 12000.0))
    parts, holds, moves = [np.zeros(int(round(rng.uniform(1.0, 1.5) / dt)))], [], []   # from rest at 0 V
    pos = len(parts[0])
    for a, b in zip(pts[:-1], pts[1:]):
        tj, ta, tv = m12.s_curve_times(b - a, **lim)
        m = int(np.ceil((4 * tj + 2 * ta + tv) / dt))
        parts.append(m12.s_curve(np.arange(1, m + 1) * dt, a, b - a, tj, ta, tv, lim["jerk"]))
        moves.append((pos, pos + m, tj, ta, tv))
        pos += m
        nh = int(round(rng.uniform(1.5, 4.0) / dt))
        parts.append(np.full(nh, b))
        holds.append((pos, pos + nh))
        pos += nh
    v = np.concatenate(parts)
    gain = rng.uniform(0.7, 1.4)
    h = me.play_core(v, 100.0, gain=gain)
    c = rng.uniform(0.07, 0.12)
    p = dict(c=c, tau=rng.uniform(1.0, 3.0), s=c * np.abs(h).max() / rng.uniform(2.0, 4.0))
    y = h + m12.eyring_kelvin(h, dt, **p)
    rec = finish("holdout12_creep_eyring_kelvin_s_curve_moves_260hz", seed, np.arange(len(v)) * dt, v, y, {"creep"},
                 "either", f"creep of a Kelvin element with an Eyring (sinh) dashpot (c {c:.2f}, tau {p['tau']:.1f} "
                 "s), "
                 "jerk-limited S-curve moves between set points with holds of 1.5 ... 4 s, 260 Hz", rng)
    rec.extra.update(holds=holds, moves=moves, set_points=np.array(pts), gain=gain, core=h, **lim, **p)
    return rec


@case
def rate_orifice_damper_odd_multisine_1800hz(seed):
    rng = _rng(seed, 3)
    dt = 1 / 1800
    per = int(round(1 / rng.uniform(0.12, 0.2) / dt))     # a whole number of samples per period
    f0 = 1 / (per * dt)
    n = 2 * per
    t = np.arange(n) * dt
    n_tones = int((rng.uniform(5.0, 7.0) / f0 + 1) // 2)
    phases = rng.uniform(0, 2 * np.pi, n_tones)
    x, dx = m12.odd_multisine(t, f0, n_tones, phases, 1.0)
    scale = rng.uniform(44.0, 49.0) / np.abs(x).max()
    v = scale * x
    r = m12.grid(40.0, 120)
    lam = rng.uniform(8.0, 15.0)
    dens = np.exp(-r / lam)
    w0 = rng.uniform(0.3, 0.45)
    weights = (1 - w0) * dens / dens.sum()
    h = m12.plays(v, r, weights, w0)
    rho = rng.uniform(0.12, 0.16)                         # the lag at the fastest core rate, of max |h|
    r_max = np.abs(np.diff(h)).max() / dt
    a = r_max / np.sqrt(rho * np.abs(h).max())
    gain = rng.uniform(0.8, 1.4)
    y = gain * m12.orifice_stage(h, dt, a)
    rec = finish("holdout12_rate_orifice_damper_odd_multisine_1800hz", seed, t, v, y, {"rate_dependence"}, "either",
                 f"a stage behind an orifice damper (lag R^2 / a^2, {rho:.1%} of the stroke at the fastest), an odd "
                 f"random-phase multisine ({n_tones} tones, {f0:.2f} ... {(2 * n_tones - 1) * f0:.1f} Hz), 1.8 kHz",
                 rng, monitor_noise=2e-4)
    rec.extra.update(thresholds=r, weights=weights, linear=w0, gain=gain, a=a, rho=rho, f0=f0, n_tones=n_tones,
                     phases=phases, scale=scale, rate=scale * dx, core=h, drive=v)
    return rec


@case
def gain_drift_log_ageing_rectified_sine_540hz(seed):
    rng = _rng(seed, 4)
    dt = 1 / 540
    n = int(round(rng.uniform(25.0, 32.0) / dt))
    t = np.arange(n) * dt
    amp, f_pulse = rng.uniform(85.0, 97.0), rng.uniform(0.7, 1.4)
    v = m12.rectified_sine(t, amp, f_pulse)
    g0 = rng.uniform(0.7, 1.4)
    h = me.play_core(v, 100.0, gain=g0)
    rate, t_p = rng.uniform(0.025, 0.04), rng.uniform(0.3, 1.0)
    gain = m12.log_ageing_gain(t, rate, t_p)
    y = gain * h
    rec = finish("holdout12_gain_drift_log_ageing_rectified_sine_540hz", seed, t, v, y, {"gain_drift"}, "either",
                 f"a gain ageing logarithmically ({rate:.1%} per decade) since a re-poling pulse {t_p:.2f} s before, "
                 f"a full-wave rectified sine 0 ... {amp:.0f} V, 540 Hz", rng)
    rec.extra.update(rate=rate, t_p=t_p, gain=gain, core_gain=g0, amp=amp, f_pulse=f_pulse, core=h)
    return rec


@case
def asymmetry_hertz_contact_skewed_triangles_1150hz(seed):
    rng = _rng(seed, 5)
    dt = 1 / 1150
    amp = rng.uniform(44.0, 48.0)
    v, knots_t, knots_v = m12.skewed_triangles(dt, rng, amp, 0.7, (1.0, 2.6), (0.15, 0.85), int(rng.integers(9, 12)))
    r = m12.grid(40.0, 140)
    lam = rng.uniform(8.0, 16.0)
    dens = np.exp(-r / lam)
    w0 = rng.uniform(0.3, 0.45)
    weights = (1 - w0) * dens / dens.sum()
    force = m12.plays(v, r, weights, w0)
    q = rng.uniform(0.3, 0.5)
    f0 = np.abs(force).max() / q
    gain = rng.uniform(0.7, 1.4)
    y = gain * m12.hertz_contact(force, f0)
    rec = finish("holdout12_asymmetry_hertz_contact_skewed_triangles_1150hz", seed, np.arange(len(v)) * dt, v, y,
                 {"asymmetry"}, "either", f"a preloaded Hertzian contact (max |F| / F0 = {q:.2f}) after the core, "
                 "skewed triangles of drawn rise fractions and heights, 1.15 kHz", rng, monitor_noise=4e-4)
    rec.extra.update(thresholds=r, weights=weights, linear=w0, f0=f0, q=q, gain=gain, knots_t=knots_t, knots_v=knots_v,
                     force=force, drive=v)
    return rec


@case
def saturation_interferometer_fringe_am_sine_850hz(seed):
    rng = _rng(seed, 6)
    dt = 1 / 850
    n = int(round(rng.uniform(20.0, 28.0) / dt))
    t = np.arange(n) * dt
    sig = dict(mid=50.0, amp=rng.uniform(44.0, 48.0), depth=rng.uniform(0.5, 0.8), f_c=rng.uniform(1.5, 3.0),
               f_m=1 / rng.uniform(10.0, 16.0), fade_s=rng.uniform(1.0, 2.0))
    v = m12.unipolar_am_sine(t, **sig)
    r = m12.grid(40.0, 120)
    w0 = rng.uniform(0.3, 0.45)
    weights = np.full(120, (1 - w0) / 120)                 # a uniform density
    x = m12.plays(v, r, weights, w0)
    x_q = (x.max() + x.min()) / 2
    phi_max = rng.uniform(0.8, 1.05)
    b = np.abs(x - x_q).max() / phi_max
    gain = rng.uniform(0.8, 1.5)
    y = gain * m12.fringe(x, x_q, b)
    rec = finish("holdout12_saturation_interferometer_fringe_am_sine_850hz", seed, t, v, y, {"output_saturation"},
                 "either", f"a homodyne interferometer's fringe at quadrature (phase {phi_max:.2f} rad at the ends), "
                 "an AM sine about 50 V, 0 ... 100 V, 850 Hz", rng)
    rec.extra.update(thresholds=r, weights=weights, linear=w0, x_q=x_q, b=b, phi_max=phi_max, gain=gain, core=x,
                     signal=sig)
    return rec


@case
def delay_sigma_delta_sinc_rc_steps_480hz(seed):
    rng = _rng(seed, 7)
    dt = 1 / 480
    n = int(round(rng.uniform(18.0, 24.0) / dt))
    switches, targets = [rng.uniform(0.3, 0.6)], [rng.uniform(40.0, 95.0)]
    while switches[-1] < n * dt:
        switches.append(switches[-1] + rng.uniform(0.35, 1.2))
        lv = rng.uniform(5.0, 95.0)
        while abs(lv - targets[-1]) < 25.0:
            lv = rng.uniform(5.0, 95.0)
        targets.append(lv)
    rc = rng.uniform(0.04, 0.12)
    big_r, order = int(rng.choice([8, 16])), int(rng.choice([3, 4, 5]))
    v_fine = m12.rc_steps(np.arange(n * big_r) * dt / big_r, switches, targets, rc)
    v = v_fine[::big_r]
    r = m12.grid(45.0, 80)
    dens = r ** -0.5                                      # a power-law density: many narrow plays
    w0, gain = rng.uniform(0.3, 0.45), rng.uniform(0.7, 1.4)
    weights = gain * (1 - w0) * dens / dens.sum()
    h_fine = m12.plays(v_fine, r, weights, gain * w0)
    y = m12.sigma_delta(h_fine, big_r, order, latency=1)
    d = 1 + order * (big_r - 1) / (2 * big_r)
    rec = finish("holdout12_delay_sigma_delta_sinc_rc_steps_480hz", seed, np.arange(n) * dt, v, y, {"delay"}, "either",
                 f"a sigma-delta converter's sinc^{order} decimation (R = {big_r}) and one sample of latency ({d:.2f} "
                 f"samples), a switched RC drive (RC {rc * 1e3:.0f} ms), 0 ... 100 V, 480 Hz", rng)
    rec.extra.update(delay_samples=d, osr=big_r, order=order, switches=np.array(switches), targets=np.array(targets),
                     rc=rc, thresholds=r, weights=weights, linear=gain * w0)
    return rec


@case
def initial_state_random_tail_servo_golden_two_tone_1020hz(seed):
    rng = _rng(seed, 8)
    dt = 1 / 1020
    nh = int(round(rng.uniform(6.0, 10.0) / dt))
    sos = butter(2, rng.uniform(0.6, 1.2), fs=1 / dt, output="sos")
    noise = sosfilt(sos, rng.standard_normal(nh + 20_000))[20_000:] * m12.raised_cosine(np.arange(nh) * dt)
    run = rng.uniform(38.0, 43.0) * noise / np.abs(noise).max()
    stop = np.flatnonzero(np.abs(run) >= 0.75 * np.abs(run).max())[-1]    # its last excursion beyond 75 %
    run = run[:stop + 1]
    v_set = run[-1] * rng.uniform(0.15, 0.45)                # the set point, inside it on the same side
    tau_s = rng.uniform(0.1, 0.3)
    settle = np.arange(1, int(round(6 * tau_s / dt)) + 1) * dt
    pre = np.r_[run, v_set + (run[-1] - v_set) * np.exp(-settle / tau_s)]
    _, z = me.play_core(pre, 100.0, return_state=True)
    n = int(round(rng.uniform(14.0, 20.0) / dt))
    t = np.arange(n) * dt
    a1 = rng.uniform(43.0, 46.0)
    sig = dict(v0=pre[-1], glide_s=rng.uniform(2.0, 4.0), grow_s=n * dt * rng.uniform(0.45, 0.6), a1=a1,
               a2=a1 * rng.uniform(0.22, 0.3), f1=rng.uniform(0.5, 0.9), theta=rng.uniform(0, 2 * np.pi))
    v = m12.golden_two_tone(t, **sig)
    y = me.play_core(v, 100.0, state=z)
    rec = finish("holdout12_initial_state_random_tail_servo_golden_two_tone_1020hz", seed, t, v, y, {"initial_state"},
                 "either", f"a core left by a band-limited random run and a servo settling inward to {v_set:.0f} V, "
                 "then a "
                 "golden-ratio two-tone of growing envelope gliding to 0 V, 1.02 kHz", rng, monitor_noise=1e-4)
    rec.extra.update(history=pre, run_end=len(run), v_set=v_set, tau_s=tau_s, signal=sig, drive=v)
    return rec


# ---- two effects ----

@case
def pair_initial_state_creep_cole_davidson_stepped_sine_380hz(seed):
    rng = _rng(seed, 9)
    dt = 1 / 380
    top, f_tri = rng.uniform(88.0, 97.0), rng.uniform(0.3, 0.6)
    per = int(round(1 / f_tri / dt))
    tri = top * (1 - np.abs(2 * np.arange(per) / per - 1))
    v_park = rng.uniform(25.0, 40.0)
    down = np.linspace(top, v_park, int(round((top - v_park) / top * per / 2)) + 1)[1:]
    pre = np.r_[np.tile(tri, int(rng.integers(3, 6))), tri[:per // 2 + 1], down]
    _, z = me.play_core(pre, 100.0, return_state=True)
    n_per = int(rng.choice([4, 6, 8]))
    n_steps = n_per // 2 + n_per * int(round((rng.uniform(16.0, 22.0) - n_per / 2) / n_per))   # ends at -A_end
    k = np.arange(1, n_steps + 1)
    a_start, a_end = rng.uniform(10.0, 16.0), rng.uniform(47.0, 50.0)
    amps = a_start * (a_end / a_start) ** ((k - 1) / (n_steps - 1))
    levels = np.r_[amps * np.cos(2 * np.pi * k / n_per), 0.0]    # and back to 0 V
    v, holds = m12.stepped_levels(dt, rng, v_park, levels, (1.5, 3.0), (0.12, 0.25), rng.uniform(1.0, 1.5))
    gain = rng.uniform(0.7, 1.4)
    h = me.play_core(v, 100.0, gain=gain, state=z)
    p = dict(c=rng.uniform(0.07, 0.11), tau=rng.uniform(1.0, 4.0), gamma=rng.uniform(0.3, 0.6))
    y = h + m12.cole_davidson_creep(h, dt, **p)
    rec = finish("holdout12_pair_initial_state_creep_cole_davidson_stepped_sine_380hz", seed, np.arange(len(v)) * dt,
                 v, y, {"initial_state", "creep"}, "either",
                 f"a core left by a unipolar run (0 ... {top:.0f} V) parked at {v_park:.0f} V, and Cole-Davidson "
                 "creep "
                 f"(gamma {p['gamma']:.2f}, tau {p['tau']:.1f} s), a stepped cosine of growing amplitude with holds, "
                 "380 Hz", rng, monitor_noise=5e-4)
    rec.extra.update(history=pre, top=top, v_park=v_park, levels=levels, n_per=n_per, holds=holds, gain=gain,
                     core=h, drive=v, **p)
    return rec


# ---- out of vocabulary ----

@case
def oov_coleman_hodgdon_figure_eight_overdriven_sine_330hz(seed):
    rng = _rng(seed, 10)
    dt = 1 / 330
    n = int(round(rng.uniform(30.0, 40.0) / dt))
    t = np.arange(n) * dt
    sig = dict(v_rail=rng.uniform(44.0, 48.0), f=rng.uniform(0.4, 0.8), m_lo=rng.uniform(1.2, 1.5),
               m_hi=rng.uniform(2.5, 3.5), f_m=1 / rng.uniform(8.0, 14.0))
    v, m = m12.overdriven_sine(t, **sig)
    alpha = rng.uniform(0.12, 0.2)
    lobe = rng.uniform(2.2, 3.5)                            # c / alpha: the clockwise lobe's half height
    p = dict(alpha=alpha, a=1.0, c=alpha * lobe, v_x=np.sqrt(2) * sig["v_rail"] * rng.uniform(0.5, 0.62))
    gain = rng.uniform(0.8, 1.4)
    y = gain * m12.coleman_hodgdon(v, **p)
    rec = finish("holdout12_oov_coleman_hodgdon_figure_eight_overdriven_sine_330hz", seed, t, v, y, set(),
                 "unexplained", f"a Coleman-Hodgdon (Duhem) core whose loops cross themselves at "
                 f"+-{p['v_x'] / np.sqrt(2):.0f} V "
                 "(clockwise in the middle), a sine overdriving the amplifier's rails, 330 Hz", rng)
    rec.extra.update(gain=gain, lobe=lobe, overdrive=m, signal=sig, **p)
    return rec

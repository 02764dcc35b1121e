"""The HOLDOUT14 set: written after HOLDOUT13 was measured, by a session that did not read how the diagnosis
decides, and run once for the fifteenth round's measurement (docs/diagnose.md: 26 of 30 runs right); part of ALL
since.

Mechanisms and signals that the other sets do not have, or not in these combinations (the laws and signals are in
:mod:`.mechanisms14`, each beside its source):

- a clean core (90 plays from the play's definition with a Weibull density of thresholds, shape 1.3 ... 2.5, scale
  8 ... 20 V: a hump, a drawn linear part, gain and offset) under a monotone cubic (PCHIP, Fritsch & Carlson, SIAM
  J. Numer. Anal. 17 (1980) 238) through random knots in 0 ... 100 V every 0.25 ... 0.7 s (smooth, never beyond its
  knots), from rest at 0 V, one knot of the first five at 96 ... 100 V, with a noisy input monitor, sampled at
  1.65 kHz;
- creep by Schapery's nonlinear viscoelastic law (Polym. Eng. Sci. 9 (1969) 295): two Kelvin elements (0.15 ...
  0.4 s and 1.5 ... 4 s, 6 ... 10 % of the core's output in all) driven by g2(h) h, g2 = 1 + kappa (h / h_max)^2
  (kappa 0.3 ... 0.6), in a reduced time whose clock runs exp(lam |h| / h_max) times faster (lam 0.5 ... 1): large
  loads creep more and sooner than small ones; under a pseudo-random ternary sequence (a maximum-length GF(3) shift
  register, period 26; levels 0, +A, -A, A 38 ... 46 V, dwells 1 ... 1.4 s, raised-cosine edges), sampled at 400 Hz;
- rate dependence from the classical eddy-current field of a lamination in the field-separation form v = H + k dB/dt
  (Bertotti, *Hysteresis in Magnetism*, 1998, ch. 12; Zirka et al., Physica B 343 (2004) 90), B a play core of H,
  k 1 ... 2.5 ms: a lag proportional to the core's differential slope (long on the steep parts, short after a
  reversal), under a sequence of whole sine cycles each of its own frequency (0.4 ... 9 Hz, log-uniform) and
  amplitude (0.6 ... 1 of 44 ... 48 V), with a noisy input monitor, sampled at 2 kHz;
- an offset drift from hygroscopic swelling of the stack's bond layers after a step in the room's humidity: Fickian
  uptake of a plane sheet 1 - sum 8 / ((2m + 1)^2 pi^2) exp(-(2m + 1)^2 pi^2 t / (4 tau_d)) (Crank, *The Mathematics
  of Diffusion*, 1975, eq. 4.18; sqrt(t) at first), from a step at 10 ... 30 % of the record, 4 ... 7 % of the
  span at the end of the record, either sign; under pulse-width modulation (carrier 0.4 ... 0.8 Hz, duty 0.5 +-
  0.35 in a slow sine) through the amplifier's 2nd-order Butterworth low-pass (2 ... 4 Hz), on a unipolar stroke,
  sampled at 440 Hz;
- asymmetry from a preloaded disc (Belleville) spring carrying the core's force: the Almen-Laszlo load F = delta
  ((h - delta) (h - delta / 2) + 1) (Trans. ASME 58 (1936) 305; h 1 ... 1.15 of the thickness), preloaded to
  0.45 ... 0.6 h, the top of the stroke 0.08 ... 0.13 h further (toward the soft flat of the curve): the top
  stretched by 7 ... 16 %, the bottom compressed by 6 ... 10 % (monotone); under a sine (1.2 ... 2.5 Hz) whose amplitude follows an Ornstein-Uhlenbeck
  envelope (0.3 ... 1 of 45 ... 49 V, correlation time 1.5 ... 3 s), with a noisy input monitor, sampled at 1.05 kHz;
- saturation of a magnetisation by the Brillouin function B_J (J 3/2, 2, 5/2 or 7/2; between tanh and Langevin),
  the ends compressed by 10 ... 18 %, under a square wave stepping down in frequency (5 steps from 1.5 ... 2.5 Hz to
  0.2 ... 0.3 Hz, 3 periods each, amplitudes 0.5 ... 1 of 42 ... 46 V) through the amplifier's 2nd-order
  Butterworth low-pass (3 ... 6 Hz: rounded edges with 4.3 % overshoot), sampled at 700 Hz;
- a delay of the acquisition: a multiplexed ADC converts the output channel (1 ... 7) / 8 of a period before the
  drive monitor, and the output passes a causal Gaussian FIR (ISO 16610-21, sigma 0.5 ... 1 sample, linear phase,
  group delay m = ceil(3 sigma) = 2 or 3): 2.1 ... 3.9 samples in all; under Gabor wavelets (Gaussian-windowed sines
  of 1 ... 8 Hz, widths 0.15 ... 0.4 s, heights 20 ... 47 V) with a noisy input monitor, sampled at 1.6 kHz;
- a core left by an anhysteretic magnetisation whose bias was then removed (an alternating field decaying from 50
  ... 55 V to 0 about a bias of 15 ... 30 V, then the bias ramped to 0 V; Rimbert 1959; Dunlop & Ozdemir, *Rock
  Magnetism*, 1997, ch. 11): every play centred near the bias or on the descending branch from it, at 0 V where the
  record starts; under Ricker (Mexican-hat) wavelets of alternating sign whose heights grow geometrically from 8
  ... 12 V to 46 ... 49 V (the last two at full height, which wipes the memory out), sampled at 900 Hz;
- two effects: asymmetry of a single-ended capacitive gap sensor read linearly in capacitance (g0^2 / (g - x) - g0,
  the top of the stroke 8 ... 14 % of the gap: convex; Baxter, *Capacitive Sensors*, 1997) and a drift of its gap
  as the mount warms (g = g0 (1 - d (1 - exp(-t / tau_w))), tau_w 4 ... 10 s; an offset of 3 ... 6 % of the span
  with a gain change), under whole sine cycles of drawn frequency (0.6 ... 2 Hz) and amplitude (0.35 ... 1 of 44
  ... 48 V), sampled at 800 Hz;
- out of vocabulary: a push-push (toggle) latch after the core: a bistable detent that flips between 0 and a step
  of 4 ... 7 % of the span each time the stroke passes a trigger level (75 ... 82 V) after having come back below a
  release level (10 ... 20 V), under unipolar haversine strokes with holds at 0 V, full ones (86 ... 96 V) and
  partial ones (35 ... 65 V) in a drawn order, sampled at 250 Hz. Repeated full strokes draw two different loops in
  turn (the output repeats every two strokes, not every stroke), and a partial stroke leaves the latch alone. A PI
  core (any plays with non-negative weights and any linear part) draws the same loop in every repeat of one stroke
  from the same state; creep, drift and initial states change slowly or once, not in alternation with the strokes;
  saturation, asymmetry, rate dependence and delay are fixed maps or filters.
"""

import math

import numpy as np
from scipy.optimize import brentq

from . import mechanisms as me
from . import mechanisms14 as m14
# thresholds and weights of an exponential density with a drawn linear part, as HOLDOUT13 draws them
from .cases_holdout13 import _exp_plays
from .record import case_set, finish

HOLDOUT14, case, _rng = case_set("holdout14_", 14000)


# ---- clean ----

@case
def clean_weibull_plays_pchip_random_knots_1650hz(seed):
    rng = _rng(seed, 1)
    dt = 1 / 1650
    total = rng.uniform(14.0, 20.0)
    kt = np.r_[0.0, np.cumsum(rng.uniform(0.25, 0.7, 80))]
    kt = kt[kt < total]
    kv = rng.uniform(0.0, 100.0, len(kt))
    kv[0] = 0.0
    kv[int(rng.integers(1, 5))] = rng.uniform(96.0, 100.0)
    t = np.arange(int(kt[-1] / dt) + 1) * dt
    v = m14.pchip_path(t, kt, kv)
    w0 = rng.uniform(0.25, 0.4)
    dens = dict(scale=rng.uniform(8.0, 20.0), shape=rng.uniform(1.3, 2.5))
    r, weights = m14.weibull_plays(90, 45.0, w0=w0, **dens)
    gain, off = rng.uniform(0.7, 1.4), rng.uniform(-4.0, 4.0)
    y = gain * m14.plays(v, r, weights, w0) + off
    rec = finish("holdout14_clean_weibull_plays_pchip_random_knots_1650hz", seed, t, v, y, set(), "explained",
                 f"a clean core (90 plays, Weibull density of thresholds, shape {dens['shape']:.1f}) under a monotone "
                 "cubic through random knots, 0 ... 100 V, 1.65 kHz", rng, monitor_noise=3e-4)
    rec.extra.update(thresholds=r, weights=gain * weights, linear=gain * w0, offset=off, knot_t=kt, knot_v=kv,
                     drive=v, **dens)
    return rec


# ---- one effect ----

@case
def creep_schapery_nonlinear_prts_ternary_400hz(seed):
    rng = _rng(seed, 2)
    dt = 1 / 400
    start = [(1, 0, 0), (0, 1, 2), (2, 2, 1), (1, 1, 0), (0, 2, 1)][int(rng.integers(0, 5))]
    sym = m14.prts(26, start)
    amp = rng.uniform(38.0, 46.0)
    levels = np.array([0.0, amp, -amp])[sym]
    dwell, edge = rng.uniform(1.0, 1.4), rng.uniform(0.05, 0.1)
    v = m14.level_sequence(dt, levels, dwell, edge)
    gain = rng.uniform(0.7, 1.4)
    h = me.play_core(v, 100.0, gain=gain)
    c = rng.uniform(0.06, 0.1)
    split = rng.uniform(0.3, 0.6)
    p = dict(comps=np.array([split, 1 - split]) * c, taus=np.array([rng.uniform(0.15, 0.4), rng.uniform(1.5, 4.0)]),
             u_ref=float(np.abs(h).max()), kappa=rng.uniform(0.3, 0.6), lam=rng.uniform(0.5, 1.0))
    creep = m14.schapery_creep(h, dt, **p)
    y = h + creep
    rec = finish("holdout14_creep_schapery_nonlinear_prts_ternary_400hz", seed, np.arange(len(v)) * dt, v, y,
                 {"creep"}, "either", f"creep by Schapery's nonlinear law (two elements, c {c:.2f}, kappa "
                 f"{p['kappa']:.2f}, lam {p['lam']:.2f}) under a pseudo-random ternary sequence (+-{amp:.0f} V, "
                 f"dwells {dwell:.2f} s), 400 Hz", rng)
    rec.extra.update(symbols=sym, levels=levels, dwell=dwell, edge=edge, gain=gain, core=h, creep=creep, c=c, **p)
    return rec


@case
def rate_eddy_field_separation_random_period_cycles_2000hz(seed):
    rng = _rng(seed, 3)
    dt = 1 / 2000
    amp = rng.uniform(44.0, 48.0)
    total = rng.uniform(6.5, 9.0)
    freqs, amps, dur = [], [], 0.0
    while dur < total:
        f = math.exp(rng.uniform(math.log(0.4), math.log(9.0)))
        freqs.append(f)
        amps.append(amp * rng.uniform(0.6, 1.0))
        dur += 1 / f
    amps[int(np.argmin(freqs))] = amp                 # the slowest cycle at full amplitude
    v, starts = m14.sine_cycles(dt, freqs, amps)
    r, weights, w0 = _exp_plays(rng, 40.0, 40, rng.uniform(10.0, 18.0))
    k = rng.uniform(1e-3, 2.5e-3)
    b, hfield = m14.eddy_field_separation(v, dt, k, r, weights, w0)
    gain = rng.uniform(0.8, 1.4)
    y = gain * b
    rec = finish("holdout14_rate_eddy_field_separation_random_period_cycles_2000hz", seed, np.arange(len(v)) * dt, v,
                 y, {"rate_dependence"}, "either", f"the classical eddy-current field of a lamination (k {k * 1e3:.2f} "
                 f"ms) before a play core, {len(freqs)} whole sine cycles of random period (0.4 ... 9 Hz), 2 kHz",
                 rng, monitor_noise=2e-4)
    rec.extra.update(freqs=np.array(freqs), amps=np.array(amps), starts=starts, amp=amp, thresholds=r,
                     weights=weights, linear=w0, k=k, gain=gain, core=b, field=hfield, drive=v)
    return rec


@case
def drift_hygroscopic_swelling_fickian_pwm_drive_440hz(seed):
    rng = _rng(seed, 4)
    dt = 1 / 440
    total = rng.uniform(26.0, 38.0)
    n = int(total / dt)
    t = np.arange(n) * dt
    fcar, period_d = rng.uniform(0.4, 0.8), rng.uniform(8.0, 15.0)
    phase = rng.uniform(0, 2 * np.pi)
    top, f_c = rng.uniform(88.0, 95.0), rng.uniform(2.0, 4.0)

    def duty(cyc):
        return 0.5 + 0.35 * np.sin(2 * np.pi * cyc / (fcar * period_d) + phase)

    v, raw = m14.pwm_drive(dt, n, fcar, duty, top, f_c)
    gain = rng.uniform(0.7, 1.4)
    h = me.play_core(v, 100.0, gain=gain)
    t_s = total * rng.uniform(0.1, 0.3)
    tau_d = (total - t_s) * rng.uniform(0.8, 2.5)
    frac = rng.choice([-1.0, 1.0]) * rng.uniform(0.04, 0.07)
    uptake = m14.fickian_uptake(t, t_s, tau_d)
    amp = frac * np.ptp(h) / uptake[-1]
    drift = amp * uptake
    y = h + drift
    rec = finish("holdout14_drift_hygroscopic_swelling_fickian_pwm_drive_440hz", seed, t, v, y, {"drift"}, "either",
                 f"an offset from hygroscopic swelling (Fickian uptake after a humidity step at {t_s:.0f} s, tau_d "
                 f"{tau_d:.0f} s, {frac:+.1%} of the span at the end), PWM through the amplifier's low-pass, 0 ... "
                 f"{top:.0f} V, 440 Hz", rng)
    rec.extra.update(f_carrier=fcar, period_d=period_d, phase=phase, top=top, f_c=f_c, raw=raw, gain=gain, core=h,
                     t_s=t_s, tau_d=tau_d, frac=frac, amp=amp, offset=drift)
    return rec


@case
def asymmetry_belleville_preload_ou_amplitude_sine_1050hz(seed):
    rng = _rng(seed, 5)
    dt = 1 / 1050
    n = int(rng.uniform(15.0, 22.0) / dt)
    t = np.arange(n) * dt
    amp, f = rng.uniform(45.0, 49.0), rng.uniform(1.2, 2.5)
    env = m14.ou_envelope(dt, n, rng.uniform(1.5, 3.0), rng, 0.3 * amp, amp)
    v = m14.raised_cosine(t / 1.0) * m14.ou_amplitude_sine(t, f, env)
    r, weights, w0 = _exp_plays(rng, 40.0, 100, rng.uniform(8.0, 16.0))
    x = m14.plays(v, r, weights, w0)
    hb = rng.uniform(1.0, 1.15)
    d0 = rng.uniform(0.45, 0.6) * hb
    d_top = d0 + rng.uniform(0.08, 0.13) * hb
    fpu = (m14.belleville_force(d_top, hb) - m14.belleville_force(d0, hb)) / x.max()
    gain = rng.uniform(0.7, 1.4)
    y = gain * m14.belleville_output(x, hb, d0, fpu)
    rec = finish("holdout14_asymmetry_belleville_preload_ou_amplitude_sine_1050hz", seed, t, v, y, {"asymmetry"},
                 "either", f"a preloaded disc spring after the core (h {hb:.2f} t, preload at {d0 / hb:.2f} h, the top "
                 f"at {d_top / hb:.2f} h), a sine ({f:.1f} Hz) of Ornstein-Uhlenbeck amplitude, 1.05 kHz", rng,
                 monitor_noise=4e-4)
    rec.extra.update(amp=amp, f=f, envelope=env, thresholds=r, weights=weights, linear=w0, h=hb, delta0=d0,
                     delta_top=d_top, force_per_unit=fpu, gain=gain, core=x, drive=v)
    return rec


@case
def saturation_brillouin_filtered_square_sweep_700hz(seed):
    rng = _rng(seed, 6)
    dt = 1 / 700
    freqs = np.geomspace(rng.uniform(1.5, 2.5), rng.uniform(0.2, 0.3), 5)
    amp = rng.uniform(42.0, 46.0)
    fracs = rng.uniform(0.5, 1.0, 5)
    fracs[int(rng.integers(0, 3))] = 1.0
    f_c = rng.uniform(3.0, 6.0)
    v, raw = m14.filtered_square_sweep(dt, freqs, fracs * amp, 3, f_c)
    r, weights, w0 = _exp_plays(rng, 42.0, 100, rng.uniform(10.0, 18.0))
    x = m14.plays(v, r, weights, w0)
    J = float(rng.choice([1.5, 2.0, 2.5, 3.5]))
    top = np.abs(x).max()
    kappa = rng.uniform(0.10, 0.18)
    x_s = brentq(lambda s: 1 - m14.brillouin_output(np.array([top]), 0.0, s, J)[0] / top - kappa, top * 0.3, top * 50)
    gain = rng.uniform(0.8, 1.4)
    y = gain * m14.brillouin_output(x, 0.0, x_s, J)
    rec = finish("holdout14_saturation_brillouin_filtered_square_sweep_700hz", seed, np.arange(len(v)) * dt, v, y,
                 {"saturation"}, "either", f"a Brillouin saturation (J {J}, ends compressed by {kappa:.0%}) after the "
                 f"core, a square wave stepping down from {freqs[0]:.1f} to {freqs[-1]:.2f} Hz through a "
                 f"{f_c:.1f} Hz Butterworth low-pass, 700 Hz", rng)
    rec.extra.update(freqs=freqs, fracs=fracs, amp=amp, f_c=f_c, raw=raw, thresholds=r, weights=weights, linear=w0,
                     J=J, x_s=x_s, kappa=kappa, gain=gain, core=x)
    return rec


@case
def delay_mux_skew_gaussian_fir_gabor_bursts_1600hz(seed):
    rng = _rng(seed, 7)
    dt = 1 / 1600
    total = rng.uniform(8.0, 14.0)
    centres, freqs, widths, amps = [], [], [], []
    w = rng.uniform(0.15, 0.4)
    c = 4 * w + 0.1
    while c + 4 * w < total:
        centres.append(c)
        widths.append(w)
        freqs.append(rng.uniform(1.0, 8.0))
        amps.append(rng.uniform(20.0, 47.0))
        w_next = rng.uniform(0.15, 0.4)
        c += 3 * (w + w_next)
        w = w_next
    amps[int(rng.integers(0, min(3, len(amps))))] = rng.uniform(44.0, 47.0)
    sig = dict(centres=np.array(centres), freqs=np.array(freqs), widths=np.array(widths), amps=np.array(amps))
    n = int(total / dt)
    t = np.arange(n) * dt
    skew = int(rng.integers(1, 8)) / 8
    sigma = rng.uniform(0.5, 1.0)
    drive_rec = m14.gabor_bursts(t + skew * dt, **sig)       # the monitor converted skew later
    gain = rng.uniform(0.8, 1.4)
    h = me.play_core(m14.gabor_bursts(t, **sig), 100.0, gain=gain)
    y, m = m14.gaussian_fir(h, sigma)
    rec = finish("holdout14_delay_mux_skew_gaussian_fir_gabor_bursts_1600hz", seed, t, drive_rec, y, {"delay"},
                 "either", f"a multiplexed ADC ({skew:.3f} samples of skew) and a Gaussian FIR (sigma {sigma:.2f}, "
                 f"group delay {m}): {skew + m:.2f} samples in all, Gabor wavelets, 1.6 kHz", rng, monitor_noise=2e-4)
    rec.extra.update(skew=skew, sigma=sigma, m=m, delay_samples=skew + m, gain=gain, core=h, drive=drive_rec, **sig)
    return rec


@case
def initial_state_anhysteretic_bias_removed_ricker_train_900hz(seed):
    rng = _rng(seed, 8)
    dt = 1 / 900
    bias, a0, ncyc = rng.uniform(15.0, 30.0), rng.uniform(50.0, 55.0), int(rng.integers(15, 31))
    pre = m14.arm_history(bias, a0, ncyc)
    _, z = me.play_core(pre, 100.0, return_state=True)
    k = int(rng.integers(14, 21))
    heights = np.geomspace(rng.uniform(8.0, 12.0), rng.uniform(46.0, 49.0), k)
    heights[-2] = heights[-1]                    # the last two at full height, of opposite signs: the memory wiped
    heights *= np.where(np.arange(k) % 2, -1, 1)
    heights *= rng.choice([-1.0, 1.0])
    widths = rng.uniform(0.08, 0.2, k)
    gaps = rng.uniform(0.6, 1.2, k)
    centres = 0.5 + np.cumsum(gaps)
    total = centres[-1] + 0.8
    t = np.arange(int(total / dt)) * dt
    v = m14.ricker_train(t, centres, widths, heights)
    gain = rng.uniform(0.7, 1.4)
    y = me.play_core(v, 100.0, gain=gain, state=z)
    rec = finish("holdout14_initial_state_anhysteretic_bias_removed_ricker_train_900hz", seed, t, v, y,
                 {"initial_state"}, "either", f"a core left by an anhysteretic magnetisation (AC from {a0:.0f} V "
                 f"decaying to 0 about a bias of {bias:.0f} V, {ncyc} cycles) and the bias removed, then {k} Ricker "
                 "wavelets of growing height, 900 Hz", rng)
    rec.extra.update(history=pre, bias=bias, a0=a0, n_cycles=ncyc, state=z, centres=centres, widths=widths,
                     heights=heights, gain=gain)
    return rec


# ---- two effects ----

@case
def pair_asymmetry_drift_capacitive_gap_warmup_random_cycles_800hz(seed):
    rng = _rng(seed, 9)
    dt = 1 / 800
    amp = rng.uniform(44.0, 48.0)
    total = rng.uniform(20.0, 28.0)
    freqs, amps, dur = [], [], 0.0
    while dur < total:
        f = rng.uniform(0.6, 2.0)
        freqs.append(f)
        amps.append(amp * rng.uniform(0.35, 1.0))
        dur += 1 / f
    amps[int(rng.integers(0, 4))] = amp
    v, starts = m14.sine_cycles(dt, freqs, amps)
    t = np.arange(len(v)) * dt
    r, weights, w0 = _exp_plays(rng, 40.0, 100, rng.uniform(8.0, 16.0))
    x = m14.plays(v, r, weights, w0)
    q = rng.uniform(0.08, 0.14)
    g0 = x.max() / q
    frac = rng.uniform(0.03, 0.06)
    d = rng.choice([-1.0, 1.0]) * frac * np.ptp(x) / g0
    tau_w = rng.uniform(4.0, 10.0)
    g = g0 * (1 - d * (1 - np.exp(-t / tau_w)))
    gain = rng.uniform(0.7, 1.4)
    y = gain * m14.gap_sensor(x, g0, g)
    rec = finish("holdout14_pair_asymmetry_drift_capacitive_gap_warmup_random_cycles_800hz", seed, t, v, y,
                 {"asymmetry", "drift"}, "either", f"a single-ended capacitive gap sensor (the top {q:.0%} of the gap) "
                 f"whose gap changes by {d:+.2%} as its mount warms (tau {tau_w:.1f} s), whole sine cycles of drawn "
                 "frequency and amplitude, 800 Hz", rng)
    rec.extra.update(freqs=np.array(freqs), amps=np.array(amps), starts=starts, thresholds=r, weights=weights,
                     linear=w0, q=q, g0=g0, d=d, frac=frac, tau_w=tau_w, gap=g, gain=gain, core=x)
    return rec


# ---- out of vocabulary ----

@case
def oov_toggle_latch_period_doubling_strokes_250hz(seed):
    rng = _rng(seed, 10)
    dt = 1 / 250
    trigger, release = rng.uniform(75.0, 82.0), rng.uniform(10.0, 20.0)
    kinds = list(rng.permutation(["full"] * 20 + ["part"] * 7))
    kinds[:2] = ["full", "full"]
    parts, strokes, pos = [np.zeros(int(round(rng.uniform(0.4, 0.8) / dt)))], [], 0
    pos = len(parts[0])
    for kind in kinds:
        top = rng.uniform(86.0, 96.0) if kind == "full" else rng.uniform(35.0, 65.0)
        m = int(round(rng.uniform(1.0, 1.6) / dt))
        stroke = top * np.sin(np.pi * np.arange(m) / m) ** 2            # a haversine 0 -> top -> 0
        parts.append(stroke)
        strokes.append((pos, pos + m, top))
        pos += m
        hold = np.zeros(int(round(rng.uniform(0.3, 0.6) / dt)))
        parts.append(hold)
        pos += len(hold)
    v = np.concatenate(parts)
    gain = rng.uniform(0.7, 1.4)
    h = me.play_core(v, 100.0, gain=gain)
    frac = rng.uniform(0.04, 0.07)
    step = frac * np.ptp(h)
    latch = m14.toggle_latch(v, trigger, release, step)
    y = h + latch
    rec = finish("holdout14_oov_toggle_latch_period_doubling_strokes_250hz", seed, np.arange(len(v)) * dt, v, y, set(),
                 "unexplained", f"a push-push (toggle) latch after the core (a step of {frac:.1%} of the span, trigger "
                 f"{trigger:.0f} V, release {release:.0f} V), {kinds.count('full')} full and {kinds.count('part')} "
                 "partial haversine strokes, 250 Hz", rng)
    rec.extra.update(trigger=trigger, release=release, strokes=strokes, kinds=kinds, gain=gain, core=h, step=step,
                     frac=frac, latch=latch)
    return rec

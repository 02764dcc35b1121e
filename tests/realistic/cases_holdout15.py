"""The HOLDOUT15 set: written after HOLDOUT14 was measured, by a session that did not read how the diagnosis decides,
and run once for the seventeenth round's measurement (docs/diagnose.md: 20 of 30 runs right); part of ALL since.

Mechanisms and signals that the other sets do not have, or not in these combinations (the laws and signals are in
:mod:`.mechanisms15`, each beside its source):

- a clean core (100 plays from the play's definition with a beta density of thresholds on 0 ... 45 V, a 1.5 ... 3,
  b 2.5 ... 5: a hump, a drawn linear part, gain and offset) under the x coordinate of the Lorenz system (Lorenz, J.
  Atmos. Sci. 20 (1963) 130; sigma 10, rho 28, beta 8/3, 0.5 ... 0.9 Lorenz time units per second: a chaotic drive
  that circles one lobe with growing swings and jumps to the other at irregular times), faded in from rest at 0 V
  over 1 s to peaks of +-44 ... 48 V, with a noisy input monitor, sampled at 1.85 kHz;
- creep of a Burgers body (a Maxwell element in series with a Kelvin element; Burgers, 1935; Findley, Lai & Onaran,
  *Creep and Relaxation of Nonlinear Viscoelastic Materials*, 1976, ch. 5): a Kelvin strain of 4 ... 7 % of the
  core's output (0.3 ... 1.2 s) and a sustained viscous flow of 0.6 ... 1.2 % of the load per second, unbounded under
  a held load, undone only by the opposite load; under stress-dip tests (Ahlquist & Nix, Acta Metall. 19 (1971) 373):
  blocks in pairs of opposite sign, each a step to a level, a hold of 2 ... 3.5 s, a dip to 0.25 ... 0.6 of the
  level held 1.5 ... 3 s (where the Kelvin part creeps back while the flow goes on), a rest at 0 V; sampled at
  420 Hz;
- rate dependence of a stage damped by two squeeze films (a plate between two plates; the Reynolds-equation damping
  3 pi mu R^4 / (2 g^3) of each gap g: Langlois, Q. Appl. Math. 20 (1962) 131; Bao & Yang, Sens. Actuators A 136
  (2007) 3): dy/dt = (h - y) / tau(y), tau0 3 ... 6 ms at rest and several times that toward either end of the
  stroke, where a film thins (the core's extremes 35 ... 50 % of the gap); under velocity-step ramps (Dieterich, J.
  Geophys. Res. 84 (1979) 2161): ramps between ends of alternating sign (0.75 ... 1 of 44 ... 48 V), each split at
  1 ... 3 drawn points into segments at alternately slow (25 ... 50 V/s) and fast (300 ... 700 V/s) speeds, sampled
  at 1.95 kHz;
- a gain drift from a discharging cell: a ratiometric bridge sensor excited by a cell near the end of its
  discharge, read by an ADC with a fixed reference, its gain the cell's voltage by Shepherd's law in Tremblay's form
  e0 - k x / (1 - x) + a exp(-b x) (x the fraction of the capacity drawn, at constant current from 0.78 ... 0.85 on;
  Shepherd, J. Electrochem. Soc. 112 (1965) 657; Tremblay, Dessaint & Dekkiche, IEEE VPPC 2007): flat at first, then
  falling faster and faster, by 6 ... 10 % at the end (the record ends in the coda of its last event); under synthetic earthquakes on a shake table (Kanai-Tajimi
  filtered noise, ground frequency 1.2 ... 2.5 Hz, damping 0.3 ... 0.6, Kanai 1957, Tajimi 1960; Jennings-Housner-Tsai
  envelopes, 1968; peaks 0.55 ... 1 of 44 ... 48 V, the last at full height; the table's 6 ... 9 Hz command filter),
  sampled at 470 Hz;
- asymmetry of a semiconductor strain gauge in a quarter Wheatstone bridge reading the core's strain: the gauge's
  change u = w + q w^2 (p-type silicon, q 0.22 ... 0.32; Mason, Forst & Tornillo, ISA 1962) and the bridge's output
  u / (4 + 2 u) (Hoffmann, *An Introduction to Measurements using Strain Gages*, 1989), w 0.25 ... 0.4 at the top of
  the stroke: the top compressed and the bottom stretched by several per cent (monotone); under the swept sine of
  IEC 60068-2-6 (a logarithmic sweep from 0.25 ... 0.35 Hz to 4 ... 6 Hz at constant displacement, 45 ... 49 V, below
  the crossover 0.8 ... 1.5 Hz and constant velocity above it), with a noisy input monitor, sampled at 1.08 kHz;
- saturation by two compliant end stops: free travel within +-0.55 ... 0.75 of the core's extremes, beyond which a
  Hertzian contact K delta^(3/2) (Hertz 1882; Johnson, *Contact Mechanics*, 1985) balances the flexure, the ends
  compressed by 10 ... 18 % (a linear middle and a knee of exponent 3/2, symmetric); under a van der Pol oscillation
  (van der Pol, Phil. Mag. 2 (1926) 978) whose damping sweeps from 0.2 ... 0.5 to 4 ... 6 (from a near-sine at 0.9
  ... 1.4 Hz to a relaxation oscillation), its amplitude rising from 0.35 to 1 of 44 ... 48 V over the first half,
  sampled at 760 Hz;
- a delay of a camera tracking the stage: each frame the mean position over its exposure (0.3 ... 0.9 of a frame),
  the tracked row read 0.1 ... 0.8 of a frame after the first (rolling shutter), the frame delivered 2 frames after
  its readout: 2.25 ... 3.25 samples in all, and a short moving average (the exposure); under the z command of a
  probe tracking a Weierstrass-Mandelbrot surface profile (Berry & Lewis, Proc. R. Soc. Lond. A 370 (1980) 459;
  fractal dimension 1.4 ... 1.7, gamma 1.5, from 0.08 ... 0.15 Hz up to 15 Hz), faded in from 0 V, peaks of +-44 ...
  48 V, with a noisy input monitor, sampled at 340 Hz (the frame rate);
- a core left by a closed-loop servo's underdamped moves (zeta 0.2 ... 0.35, 3 ... 8 Hz; Ogata, 2010, sec. 5-3) from
  rest at 0 V to +A1, then to -A2 and back to 0 V, each overshooting and ringing out (the ringing about 0 V leaves
  the narrow plays nearly demagnetised, the wider ones on the branches of the overshoots), where the record starts;
  under point-to-point steps shaped by a zero-vibration-derivative input shaper (impulses 1/4, 1/2, 1/4 half a
  resonance period, 40 ... 80 ms, apart; Singer & Seering, J. Dyn. Syst. Meas. Control 112 (1990) 76) through the
  amplifier's 2 ... 5 ms lag, to set points of alternating sign whose heights grow geometrically from 8 ... 12 V to
  46 ... 49 V (the last two at full height, beyond the history's extremes, which wipes the memory out), sampled at
  820 Hz;
- two effects: rate dependence of a DC-stabilised charge drive (Fleming, IEEE Trans. Ultrason. Ferroelectr. Freq.
  Control 60 (2013) 1630; in its complementary-filter form, voltage drive below the crossover 0.1 ... 0.3 Hz, charge
  drive, the displacement proportional to the command, above it: the hysteresis fades out of the fast parts) and
  asymmetry of a Hall sensor on the axis of a cylindrical magnet carried by the stage (the axial field of the
  magnet's equivalent surface current, the top of the stroke 10 ... 16 % of the gap: convex); under an
  amplitude-and-phase-shift-keyed sine (a 0.8 ... 1.6 Hz carrier, symbols of 2 or 3 whole cycles, each of phase 0 or
  pi and amplitude 0.5, 0.75 or 1 of 44 ... 48 V), with a noisy input monitor, sampled at 1.38 kHz;
- out of vocabulary: stick-slip of a carriage on a friction guide pulled through a stiff flexure by the core (static
  friction above the kinetic: Rabinowicz, *Friction and Wear of Materials*, 1965; Bowden & Tabor, 1950): the carriage
  sticks until the flexure's force reaches the static level (5 ... 8 % of the span in travel), then slips, in less
  than a sample, by twice the difference of the static and kinetic levels (a jump of 2.5 ... 6.4 % of the span), and
  sticks again; under one axis of a scan along the Hilbert curve (order 4: 255 equal moves at constant speed, 0.15
  ... 0.3 s each, and holds while the other axis moves; Hilbert, Math. Ann. 38 (1891) 459), 0 ... 94 ... 99 V,
  sampled at 290 Hz. The output stays frozen while the input moves on, then jumps by the same step, again and again
  at regular input increments, between two samples. A PI core (any plays with non-negative weights and any linear
  part) is a continuous (Lipschitz) function of a continuous input and so is every named effect: creep and drift
  move slowly, rate dependence and delay are filters, saturation and asymmetry continuous monotone maps, an initial
  state changes the start; none draws repeated jumps of a fixed size while the input moves by a fraction of a volt.
"""

import math

import numpy as np
from scipy.optimize import brentq

from . import mechanisms as me
from . import mechanisms15 as m15
# thresholds and weights of an exponential density with a drawn linear part, as HOLDOUT13 and HOLDOUT14 draw them
from .cases_holdout13 import _exp_plays
from .record import case_set, finish

HOLDOUT15, case, _rng = case_set("holdout15_", 15000)


# ---- clean ----

@case
def clean_beta_plays_lorenz_chaotic_1850hz(seed):
    rng = _rng(seed, 1)
    dt = 1 / 1850
    n = int(rng.uniform(14.0, 20.0) / dt)
    t = np.arange(n) * dt
    scale, amp = rng.uniform(0.5, 0.9), rng.uniform(44.0, 48.0)
    fade = m15.raised_cosine(t / 1.0)
    for _ in range(30):                          # a start whose path visits both lobes to within 85 % of the peak
        start = np.r_[rng.uniform(-15.0, 15.0, 2), rng.uniform(15.0, 35.0)]
        path = m15.lorenz_path(dt, n, scale, start)
        x = fade * path[:, 0]
        if min(x.max(), -x.min()) > 0.85 * np.abs(x).max():
            break
    v = amp * x / np.abs(x).max()
    w0 = rng.uniform(0.25, 0.4)
    a, b = rng.uniform(1.5, 3.0), rng.uniform(2.5, 5.0)
    r, weights = m15.beta_plays(100, 45.0, a, b, w0)
    gain, off = rng.uniform(0.7, 1.4), rng.uniform(-4.0, 4.0)
    y = gain * m15.plays(v, r, weights, w0) + off
    rec = finish("holdout15_clean_beta_plays_lorenz_chaotic_1850hz", seed, t, v, y, set(), "explained",
                 f"a clean core (100 plays, beta density of thresholds, a {a:.1f}, b {b:.1f}) under the Lorenz "
                 f"system's x ({scale:.2f} units per second), faded in from 0 V, +-{amp:.0f} V, 1.85 kHz", rng,
                 monitor_noise=3e-4)
    rec.extra.update(thresholds=r, weights=gain * weights, linear=gain * w0, offset=off, a=a, b=b, time_scale=scale,
                     amp=amp, lorenz=path, drive=v)
    return rec


# ---- one effect ----

@case
def creep_burgers_flow_stress_dip_blocks_420hz(seed):
    rng = _rng(seed, 2)
    dt = 1 / 420
    amp = rng.uniform(42.0, 47.0)
    npair = int(rng.integers(3, 5))
    lv = amp * rng.uniform(0.6, 1.0, npair)
    lv[int(rng.integers(0, npair))] = amp
    first = rng.choice([-1.0, 1.0], npair)
    q, load, dip, rest = (rng.uniform(0.25, 0.6, npair), rng.uniform(2.0, 3.5, npair), rng.uniform(1.5, 3.0, npair),
                          rng.uniform(1.0, 2.0, npair))
    levels = np.ravel(np.c_[first * lv, -first * lv])
    rep = np.repeat
    edge = rng.uniform(0.05, 0.1)
    v, starts = m15.stress_dip_blocks(dt, levels, rep(q, 2), rep(load, 2), rep(dip, 2), rep(rest, 2), edge)
    gain = rng.uniform(0.7, 1.4)
    h = me.play_core(v, 100.0, gain=gain)
    c_k, tau_k = rng.uniform(0.04, 0.07), rng.uniform(0.3, 1.2)
    c_m, flow = rng.uniform(0.03, 0.05), rng.uniform(0.006, 0.012)
    tau_m = c_m / flow
    kel, mx = m15.burgers_creep(h, dt, c_k, tau_k, c_m, tau_m)
    y = h + kel + mx
    rec = finish("holdout15_creep_burgers_flow_stress_dip_blocks_420hz", seed, np.arange(len(v)) * dt, v, y,
                 {"creep"}, "either", f"creep of a Burgers body (Kelvin {c_k:.1%}, {tau_k:.2f} s; flow {flow:.1%} "
                 f"of the load per second) under {2 * npair} stress-dip blocks in pairs of opposite sign, "
                 f"+-{amp:.0f} V, 420 Hz", rng)
    rec.extra.update(levels=levels, dips=rep(q, 2), load_s=rep(load, 2), dip_s=rep(dip, 2), rest_s=rep(rest, 2),
                     edge=edge, starts=starts, gain=gain, core=h, c_k=c_k, tau_k=tau_k, c_m=c_m, tau_m=tau_m,
                     flow=flow, kelvin=kel, maxwell=mx)
    return rec


@case
def rate_squeeze_film_damper_velocity_step_ramps_1950hz(seed):
    rng = _rng(seed, 3)
    dt = 1 / 1950
    amp = rng.uniform(44.0, 48.0)
    target = rng.uniform(11.0, 15.0)
    sign = rng.choice([-1.0, 1.0])
    ends, speeds, splits, total, prev = [], [], [], 0.0, 0.0
    slow0 = bool(rng.integers(0, 2))
    while total < target:
        end = sign * amp * (1.0 if len(ends) < 2 else rng.uniform(0.75, 1.0))
        k = int(rng.integers(1, 4))
        sp = np.sort(rng.uniform(0.1, 0.9, k))
        slow = [(j % 2 == 0) == slow0 for j in range(k + 1)]
        s = np.array([rng.uniform(25.0, 50.0) if sl else rng.uniform(300.0, 700.0) for sl in slow])
        fr = np.diff(np.r_[0.0, sp, 1.0])
        total += float((abs(end - prev) * fr / s).sum()) + 0.1
        ends.append(end)
        speeds.append(s)
        splits.append(sp)
        prev, sign, slow0 = end, -sign, not slow0
    hold = rng.uniform(0.05, 0.15)
    v, kt, kv = m15.velocity_step_ramps(dt, ends, speeds, splits, hold)
    r, weights, w0 = _exp_plays(rng, 40.0, 40, rng.uniform(10.0, 18.0))
    gain = rng.uniform(0.8, 1.4)
    h = gain * m15.plays(v, r, weights, w0)
    tau0, frac = rng.uniform(3e-3, 6e-3), rng.uniform(0.35, 0.5)
    gap = np.abs(h).max() / frac
    y = m15.squeeze_film_stage(h, dt, tau0, gap)
    rec = finish("holdout15_rate_squeeze_film_damper_velocity_step_ramps_1950hz", seed, np.arange(len(v)) * dt, v, y,
                 {"rate_dependence"}, "either", f"a stage damped by two squeeze films (tau0 {tau0 * 1e3:.1f} ms, the "
                 f"core's extremes {frac:.0%} of the gap) after the core, {len(ends)} velocity-step ramps, "
                 f"+-{amp:.0f} V, 1.95 kHz", rng)
    rec.extra.update(ends=np.array(ends), speeds=speeds, splits=splits, hold=hold, knot_t=kt, knot_v=kv, amp=amp,
                     thresholds=r, weights=weights, linear=w0, gain=gain, core=h, tau0=tau0, gap=gap, frac=frac)
    return rec


@case
def gain_drift_battery_shepherd_kanai_tajimi_quakes_470hz(seed):
    rng = _rng(seed, 4)
    dt = 1 / 470
    amp = rng.uniform(44.0, 48.0)
    nev = int(rng.integers(3, 6))
    f_cmd = rng.uniform(6.0, 9.0)
    for _ in range(30):                          # noise whose command reaches beyond 36 V on both sides
        events, start = [], rng.uniform(0.3, 0.8)
        for i in range(nev):
            t1, t2 = rng.uniform(1.0, 2.0), rng.uniform(3.0, 5.0)
            c = rng.uniform(0.5, 1.0)
            dur = t2 + (4.5 if i < nev - 1 else 1.5) / c      # the record ends in the last event's coda
            peak = amp if i == nev - 1 else amp * rng.uniform(0.55, 1.0)
            events.append((start, dur, peak, 2 * np.pi * rng.uniform(1.2, 2.5), rng.uniform(0.3, 0.6), t1, t2, c))
            start += dur + rng.uniform(0.5, 1.5)
        v, raw = m15.synthetic_quakes(dt, events, rng, f_cmd)
        if v.min() < -36.0 and 36.0 < v.max() < 54.0:
            break
    t = np.arange(len(v)) * dt
    g0 = rng.uniform(0.7, 1.4)
    h = me.play_core(v, 100.0, gain=g0)
    cell = dict(e0=rng.uniform(3.6, 3.8), k=rng.uniform(0.008, 0.015), a=0.3, b=rng.uniform(12.0, 20.0))
    x0, frac = rng.uniform(0.78, 0.85), rng.uniform(0.06, 0.1)
    v0 = m15.tremblay_voltage(x0, **cell)
    x1 = brentq(lambda x: m15.tremblay_voltage(x, **cell) - (1 - frac) * v0, x0, 1 - 1e-9)
    drawn = x0 + (x1 - x0) * t / t[-1]
    gain = m15.tremblay_voltage(drawn, **cell) / v0
    y = gain * h
    rec = finish("holdout15_gain_drift_battery_shepherd_kanai_tajimi_quakes_470hz", seed, t, v, y, {"gain_drift"},
                 "either", f"a bridge sensor's gain following its cell's discharge (Shepherd-Tremblay, {x0:.0%} to "
                 f"{x1:.1%} of the capacity, -{frac:.1%} at the end), {nev} synthetic earthquakes (Kanai-Tajimi, "
                 f"Jennings envelopes), +-{amp:.0f} V, 470 Hz", rng)
    rec.extra.update(events=events, f_cmd=f_cmd, raw=raw, amp=amp, g0=g0, core=h, x0=x0, x1=x1, frac=frac,
                     drawn=drawn, gain=gain, **cell)
    return rec


@case
def asymmetry_semiconductor_quarter_bridge_iec_swept_sine_1080hz(seed):
    rng = _rng(seed, 5)
    dt = 1 / 1080
    T = rng.uniform(15.0, 22.0)
    t = np.arange(int(T / dt)) * dt
    sweep = dict(f0=rng.uniform(0.25, 0.35), f1=rng.uniform(4.0, 6.0), T=T, f_x=rng.uniform(0.8, 1.5),
                 amp=rng.uniform(45.0, 49.0))
    v, f = m15.iec_swept_sine(t, **sweep)
    r, weights, w0 = _exp_plays(rng, 40.0, 100, rng.uniform(8.0, 16.0))
    x = m15.plays(v, r, weights, w0)
    w_top, q = rng.uniform(0.25, 0.4), rng.uniform(0.22, 0.32)
    wpu = w_top / np.abs(x).max()
    gain = rng.uniform(0.7, 1.4)
    y = gain * m15.quarter_bridge(x, wpu, q)
    rec = finish("holdout15_asymmetry_semiconductor_quarter_bridge_iec_swept_sine_1080hz", seed, t, v, y,
                 {"asymmetry"}, "either", f"a semiconductor gauge (q {q:.2f}, w {w_top:.2f} at the top) in a quarter "
                 f"bridge after the core, the IEC 60068-2-6 swept sine ({sweep['f0']:.2f} ... {sweep['f1']:.1f} Hz, "
                 f"crossover {sweep['f_x']:.2f} Hz), 1.08 kHz", rng, monitor_noise=4e-4)
    rec.extra.update(thresholds=r, weights=weights, linear=w0, w_top=w_top, q=q, w_per_unit=wpu, gain=gain, core=x,
                     freq=f, drive=v, **sweep)
    return rec


@case
def saturation_hertzian_end_stops_van_der_pol_760hz(seed):
    rng = _rng(seed, 6)
    dt = 1 / 760
    T = rng.uniform(18.0, 28.0)
    n = int(T / dt)
    t = np.arange(n) * dt
    f0, mu0, mu1 = rng.uniform(0.9, 1.4), rng.uniform(0.2, 0.5), rng.uniform(4.0, 6.0)
    xv = m15.van_der_pol_path(dt, n, 2 * np.pi * f0, mu0, mu1)
    env = 0.35 + 0.65 * m15.raised_cosine(t / (0.5 * T))
    amp = rng.uniform(44.0, 48.0)
    v = amp * env * xv / np.abs(env * xv).max()
    r, weights, w0 = _exp_plays(rng, 42.0, 100, rng.uniform(10.0, 18.0))
    x = m15.plays(v, r, weights, w0)
    top = np.abs(x).max()
    gap, comp = rng.uniform(0.55, 0.75) * top, rng.uniform(0.10, 0.18)
    kappa = comp * top / ((1 - comp) * top - gap) ** 1.5
    gain = rng.uniform(0.8, 1.4)
    y = gain * m15.hertz_stops(x, gap, kappa)
    rec = finish("holdout15_saturation_hertzian_end_stops_van_der_pol_760hz", seed, t, v, y, {"saturation"}, "either",
                 f"two Hertzian end stops after the core (free within {gap / top:.0%} of its extremes, the ends "
                 f"compressed by {comp:.0%}), a van der Pol oscillation (mu {mu0:.1f} -> {mu1:.1f}, {f0:.2f} Hz), "
                 f"760 Hz", rng)
    rec.extra.update(f0=f0, mu0=mu0, mu1=mu1, envelope=env, vdp=xv, amp=amp, thresholds=r, weights=weights,
                     linear=w0, gap=gap, comp=comp, kappa=kappa, gain=gain, core=x)
    return rec


@case
def delay_camera_rolling_shutter_fractal_profile_340hz(seed):
    rng = _rng(seed, 7)
    dt = 1 / 340
    T = rng.uniform(32.0, 45.0)
    n = int(T / dt)
    t = np.arange(n) * dt
    f0, D, gamma = rng.uniform(0.08, 0.15), rng.uniform(1.4, 1.7), 1.5
    ncomp = int(math.floor(math.log(15.0 / f0) / math.log(gamma))) + 1
    amp = rng.uniform(44.0, 48.0)
    for _ in range(30):                          # phases whose profile reaches beyond 0.8 of its peak on both sides
        phases = rng.uniform(0, 2 * np.pi, ncomp)
        prof = m15.raised_cosine(t / 0.5) * m15.weierstrass_mandelbrot(t, f0, gamma, D, phases)
        if min(prof.max(), -prof.min()) > 0.8 * np.abs(prof).max():
            break
    scale = amp / np.abs(prof).max()

    def drive(tt):
        return scale * m15.raised_cosine(tt / 0.5) * m15.weierstrass_mandelbrot(tt, f0, gamma, D, phases)
    sub = 8
    t_fine = np.arange(-8 * sub, n * sub) * (dt / sub)
    r, weights, w0 = _exp_plays(rng, 40.0, 50, rng.uniform(8.0, 16.0))
    gain = rng.uniform(0.8, 1.4)
    h_fine = gain * m15.plays(drive(t_fine), r, weights, w0)
    cam = dict(latency=2, row=rng.uniform(0.1, 0.8), exposure=rng.uniform(0.3, 0.9))
    y = m15.camera_samples(t_fine, h_fine, t, dt=dt, **cam)
    v = drive(t)
    delay = cam["latency"] + cam["row"] + cam["exposure"] / 2
    rec = finish("holdout15_delay_camera_rolling_shutter_fractal_profile_340hz", seed, t, v, y, {"delay"}, "either",
                 f"a camera tracking the stage (exposure {cam['exposure']:.2f}, row {cam['row']:.2f}, 2 frames "
                 f"late: {delay:.2f} samples), a Weierstrass-Mandelbrot profile (D {D:.2f}), 340 Hz", rng,
                 monitor_noise=2e-4)
    rec.extra.update(f0=f0, D=D, gamma=gamma, phases=phases, scale=scale, thresholds=r, weights=weights, linear=w0,
                     gain=gain, sub=sub, delay_samples=delay, drive=v, **cam)
    return rec


@case
def initial_state_underdamped_servo_zvd_shaped_steps_820hz(seed):
    rng = _rng(seed, 8)
    dt = 1 / 820
    zeta, wn = rng.uniform(0.2, 0.35), 2 * np.pi * rng.uniform(3.0, 8.0)
    os_ = math.exp(-zeta * math.pi / math.sqrt(1 - zeta * zeta))
    a1 = 44.0 / (1 + os_) * rng.uniform(0.75, 0.95)
    a2 = (44.0 - os_ * a1) / (1 + os_) * rng.uniform(0.5, 0.95)
    set_points = [a1, -a2, 0.0]
    pre = m15.servo_history(1 / 4000, set_points, zeta, wn, 4.0)
    _, z = me.play_core(pre, 100.0, return_state=True)
    k = int(rng.integers(14, 21))
    heights = np.geomspace(rng.uniform(8.0, 12.0), rng.uniform(46.0, 49.0), k)
    heights[-2] = heights[-1]
    heights *= np.where(np.arange(k) % 2, -1, 1) * rng.choice([-1.0, 1.0])
    holds = rng.uniform(0.6, 1.1, k)
    step_t = 0.5 + np.r_[0.0, np.cumsum(holds[:-1])]
    total = max(step_t[-1] + holds[-1], 12.5)
    t = np.arange(int(total / dt)) * dt
    period, tau = rng.uniform(0.04, 0.08), rng.uniform(0.002, 0.005)
    v = m15.zvd_shaped_steps(t, step_t, heights, period, tau)
    gain = rng.uniform(0.7, 1.4)
    y = me.play_core(v, 100.0, gain=gain, state=z)
    rec = finish("holdout15_initial_state_underdamped_servo_zvd_shaped_steps_820hz", seed, t, v, y,
                 {"initial_state"}, "either", f"a core left by a servo's underdamped moves (zeta {zeta:.2f}) to "
                 f"{a1:.0f} V, -{a2:.0f} V and 0 V, then {k} ZVD-shaped steps of growing height, 820 Hz", rng)
    rec.extra.update(history=pre, set_points=np.array(set_points), zeta=zeta, wn=wn, overshoot=os_, state=z,
                     step_times=step_t, heights=heights, period=period, tau=tau, gain=gain)
    return rec


# ---- two effects ----

@case
def pair_rate_asymmetry_charge_drive_hall_magnet_apsk_1380hz(seed):
    rng = _rng(seed, 9)
    dt = 1 / 1380
    amp, f_c, cyc = rng.uniform(44.0, 48.0), rng.uniform(0.8, 1.6), int(rng.integers(2, 4))
    nsym = int(math.ceil(rng.uniform(18.0, 26.0) * f_c / cyc))
    amps = amp * rng.choice([0.5, 0.75, 1.0], nsym)
    amps[int(rng.integers(0, 3))] = amp
    signs = rng.choice([-1.0, 1.0], nsym)
    v, starts = m15.apsk_sine(dt, f_c, cyc, amps, signs)
    t = np.arange(len(v)) * dt
    r, weights, w0 = _exp_plays(rng, 40.0, 100, rng.uniform(8.0, 16.0))
    x = m15.plays(v, r, weights, w0)
    f_x = rng.uniform(0.1, 0.3)
    k_q = np.ptp(x) / np.ptp(v)
    xr = m15.hybrid_charge_drive(x, v, dt, f_x, k_q)
    q = rng.uniform(0.10, 0.16)
    d0 = np.abs(xr).max() / q
    radius, length = d0 * rng.uniform(0.8, 1.5), d0 * rng.uniform(1.0, 2.0)
    gain = rng.uniform(0.7, 1.4)
    y = gain * m15.hall_sensor(xr, d0, radius, length)
    rec = finish("holdout15_pair_rate_asymmetry_charge_drive_hall_magnet_apsk_1380hz", seed, t, v, y,
                 {"rate_dependence", "asymmetry"}, "either", f"a DC-stabilised charge drive (crossover {f_x:.2f} Hz) "
                 f"and a Hall sensor on a magnet's axis (the top {q:.0%} of the gap), an APSK sine ({f_c:.2f} Hz, "
                 f"{nsym} symbols of {cyc} cycles), 1.38 kHz", rng, monitor_noise=2.5e-4)
    rec.extra.update(f_c=f_c, cycles=cyc, amps=amps, signs=signs, starts=starts, thresholds=r, weights=weights,
                     linear=w0, f_x=f_x, k_q=k_q, core=x, charge_driven=xr, q=q, d0=d0, radius=radius, length=length,
                     gain=gain, drive=v)
    return rec


# ---- out of vocabulary ----

@case
def oov_stick_slip_friction_hilbert_scan_290hz(seed):
    rng = _rng(seed, 10)
    dt = 1 / 290
    axis, top, unit = int(rng.integers(0, 2)), rng.uniform(94.0, 99.0), rng.uniform(0.15, 0.3)
    v, cells = m15.hilbert_scan_axis(dt, 4, axis, top, unit)
    gain = rng.uniform(0.7, 1.4)
    h = me.play_core(v, 100.0, gain=gain)
    s_frac, ratio = rng.uniform(0.05, 0.08), rng.uniform(0.6, 0.75)
    s = s_frac * np.ptp(h)
    f_k = ratio * s
    y = m15.stick_slip(h, s, f_k)
    rec = finish("holdout15_oov_stick_slip_friction_hilbert_scan_290hz", seed, np.arange(len(v)) * dt, v, y, set(),
                 "unexplained", f"stick-slip of a carriage after the core (static level {s_frac:.1%} of the span, "
                 f"kinetic {ratio:.2f} of it: jumps of {2 * (s - f_k) / np.ptp(h):.1%}), one axis of a Hilbert-curve "
                 f"scan (order 4, {unit:.2f} s per move), 0 ... {top:.0f} V, 290 Hz", rng)
    rec.extra.update(axis=axis, top=top, unit_s=unit, cells=cells, gain=gain, core=h, s=s, f_k=f_k, s_frac=s_frac,
                     ratio=ratio, jump=2 * (s - f_k))
    return rec

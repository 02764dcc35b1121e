"""The HOLDOUT24 set: written after HOLDOUT23 was measured, by a session that did not read how the diagnosis decides,
to be run once for the next round's measurement; kept out of ALL until then.

Mechanisms and signals that the other sets do not have (the laws are in :mod:`.mechanisms24`, the signals in
:mod:`.signals24`, each beside its source; the citations were written from memory, as they say):

- a clean core (100 plays with Planck's black-body density of thresholds, r^3 / (exp(r / theta) - 1), its peak by
  Wien's law at 2.82 theta = 8 ... 18 V, on 0 ... 40 ... 46 V; a drawn linear part, gain and offset) under a synthetic
  electrocardiogram (McSharry's dynamical model: P, Q, R, S and T waves on the cardiac phase, 1 ... 1.4 beats a second
  quickening by 5 ... 10 % on every inspiration, a respiratory baseline wander), centred, faded in from 0 V over 1 s,
  to peaks of +-44 ... 48 V, with a noisy input monitor, sampled at 1.84 kHz;
- creep of a pad of hydrogel grains draining their solvent through their surfaces (diffusion out of a sphere, U(t) = 1 -
  (6 / pi^2) sum exp(-n^2 pi^2 t / t_d) / n^2, t_d 15 ... 40 s: sqrt(t) at first, exponential only beyond the record), 8
  ... 12 % of the core's output after 10 s of a held load, by Boltzmann superposition (a Kelvin element per mode); under
  two cycles of a pre-vacuum steam steriliser (from the vacuum of a leak test: 3 steam pulses to 0.45 ... 0.55 of the
  top and evacuations to 3 ... 6 %, the heat-up to 88 ... 97 V and the sterilising hold, the exhaust to the atmosphere
  at about a third, the drying vacuum, the air let in; every valve a first-order approach), played faster, on a unipolar
  stroke, sampled at 270 Hz;
- rate dependence from the stack's resistive internal electrodes: the drive diffuses along each electrode (an RC line
  open at its far end, the ceramic seeing the mean voltage tanh(sqrt(s tau)) / sqrt(s tau), a mean lag tau / 3 of 1.5
  ... 3 ms and a diffusive roll-off, neither a fixed lag nor a first-order one); under a woodpecker's drumming (6 ... 8
  drums of 12 ... 22 beats accelerating from 12 ... 16 Hz by 1.2 ... 1.5 times, each beat a swing toward the trunk
  fading through the drum, on slow posture shifts), +-44 ... 48 V, with a noisy input monitor, sampled at 1.87 kHz;
- an offset drift of a sensor whose reference cavity is sealed, carried in a cable car up a mountain (the ISA
  troposphere's pressure, the offset linear in the pressure's change: the car climbing 550 ... 900 m to a middle
  station and 350 ... 650 m more, waiting, going down part of the way; raised-cosine legs, played faster), 4 ... 8 % of
  the span at its largest, either sign; under a yo-yo (10 ... 14 throws between the hand at +44 ... 48 V and the
  string's end at the opposite, falling with a constant acceleration and climbing back, some sleeping at the end), the
  hand raised from 0 V first, sampled at 530 Hz;
- asymmetry of a float reading the level in a round-bottomed flask into which the stage's piston pushes liquid (the
  level of a sphere's cap by Viete's trigonometric root of its cubic; filled to 0.4 ... 0.7 of the radius below the
  centre, where the flask widens with the level: concave; the ends' secants 10 ... 17 % apart, compressed on a drawn
  side); under a slalom skier's lateral position through 38 ... 50 gates (the clamped cubic spline, gates 0.4 ... 0.7 s
  apart, alternating, 0.55 ... 1 of the course's width), +-44 ... 48 V, with a noisy input monitor, sampled at 990 Hz;
- saturation of a probe held between two tethers pre-stretched to 0.35 ... 0.6 of their contour length, both with the
  worm-like chain's law of Marko and Siggia (odd, stiffening without bound as a tether straightens; the ends
  compressed by 12 ... 20 %); under a violinist's melody (18 ... 24 notes on a two-octave scale across +-44 ... 48 V,
  portamento shifts, a vibrato of 5.5 ... 7 Hz starting late in each note), sampled at 780 Hz;
- a delay of a smart sensor's real-time Savitzky-Golay smoother (a quadratic over 5 or 7 of its samples, read at the
  window's centre: 2 or 3 samples late; its clock 1/4 ... 3/4 of a sample ahead of the logger's and 0 or 1 sample of
  latency: 2.25 ... 4.75 samples), the core computed on a 4x finer grid; under two hunts of a bat's echolocation calls
  (linear-period FM sweeps from 7 ... 9 Hz to 2.5 ... 3.5 Hz under Hann windows: search calls, then shorter and closer
  ones in the approach and a terminal buzz), +-44 ... 48 V, with a noisy input monitor, sampled at 625 Hz;
- a core left by a machinist's handwheel (from the virgin state at 0 V: rolled up past the work to 80 ... 88 V, back
  down past the target to 10 ... 20 V, crept up to the target at 28 ... 40 V), the record starting there; then a heart
  rate through an interval session (a warm-up to about half the stroke, efforts rising from 0.55 ... 0.65 to 0.9 of
  the history's top, the last two to 93 ... 98 V, beyond it, late in the record; first-order on- and off-kinetics of
  0.35 ... 0.6 s and 0.8 ... 1.4 s, played faster), on a unipolar stroke, sampled at 840 Hz;
- two effects: asymmetry of a Helmholtz resonator whose cavity the stage's piston shrinks (its frequency as (1 - xi
  x)^(-1/2): convex, the ends' secants 10 ... 17 % apart, on a drawn side) and a delay of the reciprocal counter that
  reads that frequency over 2 ... 4 whole periods ending a sample before the logger's tick (2 ... 3.5 samples at the
  rest frequency plus 1 of latency, shorter at the higher frequencies); under a conductor's baton beating 4/4 (10 ...
  14 bars, an accelerando from 0.5 ... 0.65 s to 0.22 ... 0.3 s a beat and a ritardando, the dynamics 0.55 ... 1 of
  +-44 ... 48 V), sampled at 720 Hz;
- out of vocabulary: an unbalanced rotor (a pendulum) on the stage's carriage, driven through a soft torsion spring by
  the core's output (the forced damped pendulum: damping 0.5 of w0, the drive's unit torque 1.1 ... 1.3 of the
  gravity torque's largest, the stride at 2/3 of w0), the sensor picking up the rotor's unbalance, 5 ... 8 % of the
  span, beside the stage's travel; under a walker's hip flexion (a Fourier series of the stride, 3 harmonics; two bouts
  of 16 ... 20 strides of an exact whole number of samples, 1.05 ... 1.25 s each, faded in and out over a stride,
  standing between), +-44 ... 48 V, sampled at 395 Hz. In the middle of each bout the input repeats every stride and so
  does the core; the rotor, in deterministic chaos, does not: the output differs from itself one, two, ... six strides
  later by many noise levels, and two rotors started 1e-9 rad apart part over a thousandfold within every bout. A PI
  core (any plays with non-negative weights and any linear part) draws the same output for the same input from the same
  state, so a periodic input gives, from its second period on, an output of its period; saturation and asymmetry are
  maps of it; rate dependence and delay are stable causal filters of it (their transients die out, and a periodic
  input gives an output of its period); creep settles, and creep, drift and gain drift are slow and smooth in time; an
  initial state is forgotten after the first period.
"""

import math

import numpy as np
from scipy.optimize import brentq

from . import mechanisms24 as m24
from . import signals24 as s24
from .record import case_set, finish

HOLDOUT24, case, _rng = case_set("holdout24_", 24000)


def _both_sides(v, frac):
    """True when the path reaches beyond frac of its largest magnitude on both sides."""
    return min(v.max(), -v.min()) > frac * np.abs(v).max()


def _core(rng, v, r_max=45.0, n=80):
    """The other cases' core: n exponentially weighted plays to r_max, a drawn linear part and gain."""
    w0 = rng.uniform(0.3, 0.45)
    r, weights = m24.exp_plays(n, r_max, rng.uniform(8.0, 16.0), w0)
    gain = rng.uniform(0.7, 1.4)
    return gain * m24.plays(v, r, weights, w0), dict(thresholds=r, weights=weights, linear=w0, gain=gain)


# ---- clean ----

@case
def clean_planck_plays_ecg_syn_1840hz(seed):
    rng = _rng(seed, 1)
    dt = 1 / 1840
    n = int(rng.uniform(14.0, 18.0) / dt)
    t = np.arange(n) * dt
    hr, rsa, f_resp, base = rng.uniform(1.0, 1.4), rng.uniform(0.05, 0.1), rng.uniform(0.2, 0.3), rng.uniform(0.1, 0.2)
    x = s24.ecg(t, hr, rsa, f_resp, base)
    xc = x - (x.max() + x.min()) / 2
    fade = m24.raised_cosine(t / 1.0)
    amp = rng.uniform(44.0, 48.0)
    scale = amp / np.abs(fade * xc).max()
    v = scale * fade * xc
    r_max, theta = rng.uniform(40.0, 46.0), rng.uniform(8.0, 18.0) / 2.8214
    w0 = rng.uniform(0.25, 0.4)
    r, weights = m24.planck_plays(100, r_max, theta, w0)
    gain, off = rng.uniform(0.7, 1.4), rng.uniform(-4.0, 4.0)
    y = gain * m24.plays(v, r, weights, w0) + off
    rec = finish("holdout24_clean_planck_plays_ecg_syn_1840hz", seed, t, v, y, set(), "explained",
                 f"a clean core (100 plays, Planck's density of thresholds, its peak at {2.8214 * theta:.1f} V, on "
                 f"0 ... "
                 f"{r_max:.0f} V) under a synthetic ECG ({hr * 60:.0f} beats a minute, RSA {rsa:.0%}), faded in from "
                 f"0 V, +-{amp:.0f} V, 1.84 kHz", rng, monitor_noise=3e-4)
    rec.extra.update(thresholds=r, weights=gain * weights, linear=gain * w0, offset=off, r_max=r_max, theta=theta,
                     hr=hr, rsa=rsa, f_resp=f_resp, base=base, x=x, xc=xc, scale=scale, amp=amp, drive=v)
    return rec


# ---- one effect ----

@case
def creep_gel_grain_drainage_steam_steriliser_270hz(seed):
    rng = _rng(seed, 2)
    dt = 1 / 270
    top = rng.uniform(88.0, 97.0)
    steps, tc = [], rng.uniform(0.8, 1.5)

    def go(target, tau, hold):
        nonlocal tc
        steps.append((tc, target, tau))
        tc += hold
    for cyc in range(2):
        for _ in range(3):                                                  # the pre-vacuum pulses
            go(rng.uniform(0.45, 0.55) * top, rng.uniform(0.3, 0.5), rng.uniform(1.5, 2.5))
            go(rng.uniform(0.03, 0.06) * top, rng.uniform(0.4, 0.7), rng.uniform(1.8, 2.8))
        go(top, rng.uniform(0.5, 0.8), rng.uniform(6.0, 9.0) if cyc == 0 else rng.uniform(4.0, 6.0))  # sterilising
        atm = rng.uniform(0.3, 0.36) * top
        go(atm, rng.uniform(0.6, 1.0), rng.uniform(1.5, 2.5))               # the exhaust
        go(rng.uniform(0.03, 0.06) * top, rng.uniform(0.5, 0.8), rng.uniform(4.0, 6.0))   # drying
        go(atm, rng.uniform(0.5, 0.8), rng.uniform(2.5, 4.0))               # the air let in
    n = int(tc / dt)
    t = np.arange(n) * dt
    v, levels = s24.vessel_pressure(t, steps, 0.0)
    h, core = _core(rng, v)
    c, t_d = rng.uniform(0.08, 0.12), rng.uniform(15.0, 40.0)
    cr = m24.gel_pad_creep(h, dt, c, t_d, 10.0)
    rec = finish("holdout24_creep_gel_grain_drainage_steam_steriliser_270hz", seed, t, v, h + cr, {"creep"},
                 "either", f"creep of a pad of draining gel grains ({c:.1%} after 10 s, t_d {t_d:.1f} s) under two "
                 f"cycles of a pre-vacuum steam steriliser to {top:.0f} V, 270 Hz", rng)
    rec.extra.update(core, top=top, steps=steps, levels=levels, h=h, c=c, t_d=t_d, creep=cr)
    return rec


@case
def rate_resistive_electrode_rc_line_woodpecker_drumming_1870hz(seed):
    rng = _rng(seed, 3)
    dt = 1 / 1870
    amp = rng.uniform(44.0, 48.0)
    n_dr = int(rng.integers(6, 9))
    postures, drums, tc, side = [], [], rng.uniform(0.5, 1.0), rng.choice([-1.0, 1.0])
    for k in range(n_dr):
        level = side * rng.uniform(0.15, 0.4)
        postures.append((tc, rng.uniform(0.35, 0.6), level))
        tc += postures[-1][1] + rng.uniform(0.15, 0.35)
        nb = int(rng.integers(12, 23))
        fa = rng.uniform(12.0, 16.0)
        fb = fa * rng.uniform(1.2, 1.5)
        drums.append((tc, nb, fa, fb, side * rng.uniform(0.45, 0.6) * (1.0 if k < 2 else rng.uniform(0.7, 1.0)),
                      rng.uniform(0.5, 1.5)))
        tc += 2 * nb / (fa + fb) + rng.uniform(0.25, 0.5)
        side = -side
    postures.append((tc, rng.uniform(0.5, 0.8), 0.0))
    tc += postures[-1][1] + rng.uniform(0.4, 0.8)
    n = int(tc / dt)
    t = np.arange(n) * dt
    x = s24.woodpecker(t, postures, drums)
    scale = amp / np.abs(x).max()
    v = scale * x
    tau = rng.uniform(4.5, 9.0) * 1e-3
    v_line = m24.electrode_line_voltage(v, dt, tau)
    h, core = _core(rng, v_line)
    rec = finish("holdout24_rate_resistive_electrode_rc_line_woodpecker_drumming_1870hz", seed, t, v, h,
                 {"rate_dependence"}, "either",
                 f"resistive internal electrodes (an RC line, tau {tau * 1e3:.1f} ms: a mean lag of "
                 f"{tau / 3 * 1e3:.1f} ms) under {n_dr} drums of a woodpecker, +-{amp:.0f} V, 1.87 kHz", rng,
                 monitor_noise=2.5e-4)
    rec.extra.update(core, amp=amp, postures=postures, drums=drums, scale=scale, tau=tau, v_line=v_line, h=h, drive=v)
    return rec


@case
def drift_sealed_cavity_barometric_cable_car_yoyo_530hz(seed):
    rng = _rng(seed, 4)
    dt = 1 / 530
    top = rng.uniform(44.0, 48.0)
    T0 = rng.uniform(0.5, 0.8)                          # the fall from rest
    a = 4 * top / T0 ** 2
    lift = rng.uniform(0.8, 1.2)
    throws, tc = [], lift + rng.uniform(0.3, 0.6)
    n_th = int(rng.integers(10, 15))
    for _ in range(n_th):
        u0 = rng.uniform(0.0, 0.5) * math.sqrt(4 * a * top)
        sleep = rng.uniform(0.3, 1.2) if rng.uniform() < 0.5 else 0.0
        throws.append((tc, u0, sleep))
        T1 = (-u0 + math.sqrt(u0 * u0 + 4 * a * top)) / a
        tc += T1 + sleep + math.sqrt(4 * a * top) / a + rng.uniform(0.3, 0.8)
    end = tc + rng.uniform(0.3, 0.6)
    n = int(end / dt)
    t = np.arange(n) * dt
    x, times = s24.yoyo(t, throws, top, a)
    v = np.where(t < lift, top * m24.raised_cosine(t / lift), x)
    h, core = _core(rng, v, r_max=42.0)
    T = t[-1]
    z0 = rng.uniform(500.0, 1500.0)
    l1 = (rng.uniform(0.05, 0.15) * T, rng.uniform(0.18, 0.25) * T, rng.uniform(550.0, 900.0))
    l2 = (l1[0] + l1[1] + rng.uniform(0.08, 0.12) * T, rng.uniform(0.15, 0.2) * T, rng.uniform(350.0, 650.0))
    l3 = (l2[0] + l2[1] + rng.uniform(0.1, 0.15) * T, rng.uniform(0.12, 0.16) * T, -rng.uniform(0.3, 0.6) * l2[2])
    legs = [l1, l2, l3]
    z = s24.cable_car(t, legs, z0)
    raw = m24.barometric_offset(z, z0)
    frac, sign = rng.uniform(0.04, 0.08), rng.choice([-1.0, 1.0])
    scale_off = sign * frac * np.ptp(h) / np.abs(raw).max()
    off = scale_off * raw
    rec = finish("holdout24_drift_sealed_cavity_barometric_cable_car_yoyo_530hz", seed, t, v, h + off, {"drift"},
                 "either", f"a sealed cavity's barometric offset of {sign * frac:+.1%} of the span at its largest (a "
                 f"cable car from {z0:.0f} m up {l1[2] + l2[2]:.0f} m) under {n_th} throws of a yo-yo, +-{top:.0f} V, "
                 f"530 Hz", rng)
    rec.extra.update(core, top=top, a=a, lift=lift, throws=throws, times=times, h=h, z0=z0, legs=legs, z=z, frac=frac,
                     sign=sign, scale_off=scale_off, offset=off)
    return rec


@case
def asymmetry_round_flask_level_slalom_gates_990hz(seed):
    rng = _rng(seed, 5)
    dt = 1 / 990
    amp = rng.uniform(44.0, 48.0)
    n_g = int(rng.integers(38, 51))
    gaps = rng.uniform(0.4, 0.7, n_g + 1)
    gate_t = rng.uniform(0.6, 1.0) + np.r_[0.0, np.cumsum(gaps)]
    sizes = rng.uniform(0.55, 1.0, n_g)
    sizes[int(rng.integers(0, 4))] = 1.0
    sizes[int(rng.integers(4, 8))] = 1.0
    gate_x = np.r_[0.0, sizes * np.where(np.arange(n_g) % 2 == 0, 1.0, -1.0) * rng.choice([-1.0, 1.0]), 0.0]
    n = int((gate_t[-1] + rng.uniform(0.5, 1.0)) / dt)
    t = np.arange(n) * dt
    x = s24.slalom(t, gate_t, gate_x)
    scale = amp / np.abs(x).max()
    v = scale * x
    w0 = rng.uniform(0.3, 0.45)
    r, weights = m24.exp_plays(80, 42.0, rng.uniform(8.0, 16.0), w0)
    x_core = m24.plays(v, r, weights, w0)
    c = (x_core.max() + x_core.min()) / 2
    X = np.abs(x_core - c).max()
    asym, side = rng.uniform(0.10, 0.17), rng.choice([-1.0, 1.0])
    u0 = -rng.uniform(0.4, 0.7)
    phi0 = 3 * u0 - u0 ** 3

    def spread(dphi):
        return float(-m24.flask_reading(-1.0, u0, dphi) - m24.flask_reading(1.0, u0, dphi)) - asym
    dphi = brentq(spread, 1e-4, 0.999 * (phi0 + 2), xtol=1e-15)
    gain = rng.uniform(0.7, 1.4)
    y = gain * (c + side * X * m24.flask_reading(side * (x_core - c) / X, u0, dphi))
    rec = finish("holdout24_asymmetry_round_flask_level_slalom_gates_990hz", seed, t, v, y, {"asymmetry"}, "either",
                 f"a float in a round-bottomed flask (filled to {u0:.2f} of the radius, the piston's volume {dphi:.2f} "
                 f"pi R^3 / 3; the ends' secants {asym:.0%} apart, compressed {'up' if side > 0 else 'down'}) under a "
                 f"slalom of {n_g} gates, +-{amp:.0f} V, 990 Hz", rng, monitor_noise=3e-4)
    rec.extra.update(gate_t=gate_t, gate_x=gate_x, scale=scale, amp=amp, thresholds=r, weights=weights, linear=w0,
                     core=x_core, centre=c, X=X, asym=asym, side=side, u0=u0, dphi=dphi, gain=gain, drive=v)
    return rec


@case
def saturation_worm_like_chain_tethers_violin_vibrato_780hz(seed):
    rng = _rng(seed, 6)
    dt = 1 / 780
    amp = rng.uniform(44.0, 48.0)
    n_notes = int(rng.integers(18, 25))
    degrees = rng.integers(0, 15, n_notes)
    degrees[int(rng.integers(0, 6))] = 14
    degrees[int(rng.integers(6, 12))] = 0
    notes, tc = [], rng.uniform(0.5, 0.9)
    for d in degrees:
        T = rng.uniform(0.55, 1.3)
        notes.append((tc, T, amp * (2 * d / 14 - 1)))
        tc += T
    notes.append((tc, 1.0, 0.0))
    tc += 1.0
    f_vib, depth = rng.uniform(5.5, 7.0), rng.uniform(0.04, 0.07) * amp
    onset, ramp, porta = rng.uniform(0.12, 0.25), 0.15, rng.uniform(0.06, 0.12)
    n = int(tc / dt)
    t = np.arange(n) * dt
    x = s24.violin(t, notes, f_vib, depth, onset, ramp, porta)
    scale = amp / np.abs(x).max()
    v = scale * x
    h, core = _core(rng, v, r_max=42.0)
    c = (h.max() + h.min()) / 2
    X = np.abs(h - c).max()
    comp, z0 = rng.uniform(0.12, 0.2), rng.uniform(0.35, 0.6)
    k0 = m24.wlc_pair_slope(z0)

    def short(F):
        return float(k0 * m24.wlc_pair_displacement(np.array([F]), z0)[0] / F) - (1 - comp)
    F_end = brentq(short, 1e-3, 1e4, xtol=1e-13)
    sc = X / F_end
    y = m24.tether_reading(h, c, sc, z0)
    rec = finish("holdout24_saturation_worm_like_chain_tethers_violin_vibrato_780hz", seed, t, v, y, {"saturation"},
                 "either", f"a probe between two worm-like-chain tethers pre-stretched to {z0:.2f} (the ends "
                 f"compressed "
                 f"by {comp:.0%}) under a violin's melody of {n_notes} notes with a {f_vib:.1f} Hz vibrato, "
                 f"+-{amp:.0f} V, 780 Hz", rng)
    rec.extra.update(core, amp=amp, notes=notes, f_vib=f_vib, depth=depth, onset=onset, ramp=ramp, porta=porta,
                     scale=scale, h=h, centre=c, X=X, comp=comp, z0=z0, F_end=F_end, sc=sc)
    return rec


@case
def delay_savitzky_golay_smoother_bat_echolocation_625hz(seed):
    rng = _rng(seed, 7)
    dt, sub = 1 / 625, 4
    calls, tc = [], rng.uniform(0.6, 1.0)
    for hunt in range(2):
        f0, f1 = rng.uniform(7.0, 9.0), rng.uniform(2.5, 3.5)
        n_s, n_a, n_b = int(rng.integers(4, 7)), int(rng.integers(4, 7)), int(rng.integers(6, 11))
        for k in range(n_s):                                       # search calls
            T = rng.uniform(0.7, 1.0)
            calls.append((tc, T, f0, f1, rng.uniform(0.6, 1.0) * rng.choice([-1.0, 1.0])))
            tc += T + rng.uniform(0.6, 1.0)
        for k in range(n_a):                                       # the approach: shorter, closer
            T = 0.7 - 0.35 * (k + 1) / n_a
            calls.append((tc, T, f0 * 0.95, f1, rng.uniform(0.6, 1.0) * rng.choice([-1.0, 1.0])))
            tc += T + 0.6 * (1 - (k + 1) / (n_a + 1)) + 0.05
        for k in range(n_b):                                       # the terminal buzz
            T = rng.uniform(0.25, 0.3)
            calls.append((tc, T, f0 * 0.9, f1, rng.uniform(0.5, 0.8) * rng.choice([-1.0, 1.0])))
            tc += T + 0.04
        tc += rng.uniform(1.0, 2.0)
    n = int(tc / dt)
    tf = np.arange((n - 1) * sub + 1) * (dt / sub)
    x = s24.bat_calls(tf, calls)
    amp = rng.uniform(44.0, 48.0)
    scale = amp / np.abs(x).max()
    v_f = scale * x
    v = v_f[::sub]
    t = tf[::sub]
    h_f, core = _core(rng, v_f, r_max=42.0)
    m = int(rng.integers(2, 4))
    phase = int(rng.integers(1, 4)) / sub
    latency = int(rng.integers(0, 2))
    y = m24.savgol_sensor(t, tf, h_f, m, phase, latency)
    lag = m + latency + phase
    rec = finish("holdout24_delay_savitzky_golay_smoother_bat_echolocation_625hz", seed, t, v, y, {"delay"}, "either",
                 f"a real-time Savitzky-Golay smoother over {2 * m + 1} samples (a delay of {lag:.2f} samples) under "
                 f"two hunts of a bat's calls ({len(calls)} calls), +-{amp:.0f} V, 625 Hz", rng, monitor_noise=2e-4)
    rec.extra.update(core, calls=calls, scale=scale, amp=amp, sub=sub, m=m, phase=phase, latency=latency, lag=lag,
                     drive=v)
    return rec


@case
def initial_state_handwheel_jog_interval_heart_rate_840hz(seed):
    rng = _rng(seed, 8)
    dt = 1 / 840
    w0 = rng.uniform(0.3, 0.45)
    r, weights = m24.exp_plays(80, 40.0, rng.uniform(10.0, 16.0), w0)
    top, low, target = rng.uniform(80.0, 88.0), rng.uniform(10.0, 20.0), rng.uniform(28.0, 40.0)
    hist = s24.handwheel_history(top, low, target)
    _, z0 = m24.plays(hist, r, weights, w0, return_state=True)
    n_b = int(rng.integers(6, 8))
    lv0 = rng.uniform(0.55, 0.65)
    levels = [rng.uniform(0.45, 0.55) * 100] + list(np.linspace(lv0, 0.9, n_b - 2) * top) + \
        [rng.uniform(93.0, 98.0), rng.uniform(93.0, 98.0)]
    tau_on, tau_off = rng.uniform(0.35, 0.6), rng.uniform(0.8, 1.4)
    bouts, tc = [], rng.uniform(0.8, 1.5)
    for j, lv in enumerate(levels):
        T = rng.uniform(3.5, 4.5) if j == 0 else rng.uniform(2.2, 3.2)
        bouts.append((tc, T, lv))
        tc += T + rng.uniform(2.0, 3.2)
    n = int((tc + rng.uniform(1.0, 2.0)) / dt)
    t = np.arange(n) * dt
    v, marks = s24.heart_rate(t, bouts, target, tau_on, tau_off)
    gain = rng.uniform(0.7, 1.4)
    y = gain * m24.plays(v, r, weights, w0, state=z0)
    rec = finish("holdout24_initial_state_handwheel_jog_interval_heart_rate_840hz", seed, t, v, y, {"initial_state"},
                 "either", f"a core left by a handwheel jog (to {top:.0f} V, down to {low:.1f} V, up to {target:.1f} "
                 f"V; "
                 f"the record starting there), then a heart rate through {len(levels)} intervals, the last to "
                 f"{max(levels[-2:]):.0f} V, 840 Hz", rng)
    rec.extra.update(thresholds=r, weights=weights, linear=w0, gain=gain, history=hist, state=z0, top=top, low=low,
                     target=target, levels=levels, bouts=bouts, tau_on=tau_on, tau_off=tau_off, marks=marks)
    return rec


# ---- two effects ----

@case
def pair_asymmetry_delay_helmholtz_resonator_reciprocal_counter_conductor_baton_720hz(seed):
    rng = _rng(seed, 9)
    dt, sub = 1 / 720, 8
    amp = rng.uniform(44.0, 48.0)
    n_bars = int(rng.integers(10, 15))
    b_slow, b_fast = rng.uniform(0.5, 0.65), rng.uniform(0.22, 0.3)
    k_top = int(rng.integers(n_bars // 2, n_bars - 2))
    bars = []
    for k in range(n_bars):
        s = min(k / k_top, 1.0)
        beat = b_slow + (b_fast - b_slow) * s if k < n_bars - 2 else b_fast * (1.3 if k == n_bars - 2 else 1.7)
        bars.append((beat, rng.uniform(0.55, 1.0)))
    j = int(rng.integers(k_top - 2, k_top + 1))
    bars[j] = (bars[j][0], 1.0)
    t0 = rng.uniform(0.6, 1.0)
    end = t0 + sum(4 * b for b, _ in bars) + rng.uniform(1.0, 1.5)
    n = int(end / dt)
    tf = np.arange((n - 1) * sub + 1) * (dt / sub)
    x, ictus = s24.baton(tf, bars, t0)
    v_f = amp * x
    v = v_f[::sub]
    t = tf[::sub]
    h_f, core = _core(rng, v_f)
    c = (h_f.max() + h_f.min()) / 2
    X = np.abs(h_f - c).max()
    asym, side = rng.uniform(0.10, 0.17), rng.choice([-1.0, 1.0])

    def spread(xi):
        return float(m24.helmholtz_reading(1.0, xi) + m24.helmholtz_reading(-1.0, xi)) - asym
    xi = brentq(spread, 1e-4, 0.9, xtol=1e-15)
    n_per = int(rng.integers(2, 5))
    half = rng.uniform(2.0, 3.5)                                    # the half gate at rest, in samples
    f0 = n_per / (2 * half * dt)
    latency = 1
    f_f = f0 * m24.helmholtz_frequency(side * (h_f - c) / X, xi)
    f_read = m24.reciprocal_counter(t, tf, f_f, n_per, latency)
    y = c + side * X * (f_read / f0 - 1) / (xi / 2)
    y_asym = (c + side * X * m24.helmholtz_reading(side * (h_f - c) / X, xi))[::sub]
    rec = finish("holdout24_pair_asymmetry_delay_helmholtz_resonator_reciprocal_counter_conductor_baton_720hz", seed,
                 t, v, y, {"asymmetry", "delay"}, "either",
                 f"a Helmholtz resonator's frequency (the cavity's change {xi:.1%}, the ends' secants {asym:.0%} "
                 f"apart) "
                 f"read by a reciprocal counter over {n_per} periods at {f0:.0f} Hz (a delay of about "
                 f"{half + latency:.1f} samples) under a conductor's baton over {n_bars} bars, +-{amp:.0f} V, 720 Hz",
                 rng)
    rec.extra.update(core, amp=amp, bars=bars, t0=t0, ictus=ictus, sub=sub, centre=c, X=X, asym=asym, side=side,
                     xi=xi, n_per=n_per, half=half, f0=f0, latency=latency, y_asym=y_asym, h=h_f[::sub])
    return rec


# ---- out of vocabulary ----

@case
def oov_chaotic_unbalanced_rotor_walking_gait_395hz(seed):
    rng = _rng(seed, 10)
    dt, sub = 1 / 395, 4
    amp = rng.uniform(44.0, 48.0)
    N = int(rng.integers(415, 494))                   # samples per stride: 1.05 ... 1.25 s
    P = N * dt
    for _ in range(50):                               # a stride reaching beyond 85 % of its largest both ways
        coeffs = [(1.0, rng.uniform(0, 2 * np.pi)), (rng.uniform(0.15, 0.3), rng.uniform(0, 2 * np.pi)),
                  (rng.uniform(0.05, 0.12), rng.uniform(0, 2 * np.pi))]
        stride = s24.gait(np.arange(2000) * (3 * P / 2000), [(0.0, 3, P)], coeffs)
        if _both_sides(stride, 0.85):
            break
    bouts, tc = [], rng.uniform(0.8, 1.2)
    bouts.append((round(tc / dt) * dt, int(rng.integers(16, 21)), P))
    tc = bouts[-1][0] + bouts[-1][1] * P + rng.uniform(2.0, 3.0)
    bouts.append((round(tc / dt) * dt, int(rng.integers(16, 21)), P))
    end = bouts[-1][0] + bouts[-1][1] * P + rng.uniform(1.5, 2.5)
    n = int(end / dt)
    tf = np.arange((n - 1) * sub + 1) * (dt / sub)
    x = s24.gait(tf, bouts, coeffs)
    scale = amp / np.abs(x).max()
    v_f = scale * x
    v = v_f[::sub]
    t = tf[::sub]
    h_f, core = _core(rng, v_f)
    hc = (h_f.max() + h_f.min()) / 2
    X = np.abs(h_f - hc).max()
    u_f = (h_f - hc) / X
    w0, q = 1.5 * 2 * np.pi / P, 0.5

    def irregular(s, sep, bout):
        """No stride of the bout's middle repeats 1 ... 6 strides later, and a 1e-9 rad start grows 1e3-fold."""
        t0, ns, _ = bout
        k0 = int(round(t0 / dt)) + (ns // 2) * N
        m = np.arange(k0 - 3 * N, k0)
        return min(np.sqrt(np.mean((s[m + L * N] - s[m]) ** 2)) for L in range(1, 7)) > 0.55 and \
            sep[int(round(t0 / dt)):int(round(t0 / dt)) + ns * N].max() > 1e-6
    k1 = (int(round(bouts[0][0] / dt)) + bouts[0][1] * N) * sub + 1
    ok = False
    for _ in range(25):                               # the chaotic band of the forcing, its periodic windows avoided
        F = rng.uniform(1.1, 1.3)
        pair = [m24.forced_rotor(u_f[:k1], dt / sub, w0, q, F, th0=d) for d in (0.0, 1e-9)]
        if not irregular(np.sin(pair[0][::sub]), np.abs(pair[1] - pair[0])[::sub], bouts[0]):
            continue
        th_f = m24.forced_rotor(u_f, dt / sub, w0, q, F)
        sep = np.abs(m24.forced_rotor(u_f, dt / sub, w0, q, F, th0=1e-9) - th_f)[::sub]
        s = np.sin(th_f[::sub])
        ok = irregular(s, sep, bouts[1])
        if ok:
            break
    if not ok:                                        # (not for seeds 0 ... 2) the last draw, flagged
        th_f = m24.forced_rotor(u_f, dt / sub, w0, q, F)
        s = np.sin(th_f[::sub])
    frac = rng.uniform(0.05, 0.08)
    b = frac * np.ptp(h_f)
    y = h_f[::sub] + b * s
    rec = finish("holdout24_oov_chaotic_unbalanced_rotor_walking_gait_395hz", seed, t, v, y, set(), "unexplained",
                 f"an unbalanced rotor driven chaotically through a torsion spring (F {F:.2f}, damping {q}, the stride "
                 f"at 2/3 of its frequency; its unbalance {frac:.1%} of the span) under two bouts of walking "
                 f"({P:.2f} s "
                 f"strides), +-{amp:.0f} V, 395 Hz", rng)
    rec.extra.update(core, N=N, P=P, coeffs=coeffs, bouts=bouts, scale=scale, amp=amp, sub=sub, hc=hc, X=X, w0=w0,
                     q=q, F=F, frac=frac, b=b, theta=th_f[::sub], chaotic=bool(ok))
    return rec

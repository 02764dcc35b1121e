"""The HOLDOUT22 set: written after HOLDOUT21 was measured, by a session that did not read how the diagnosis decides,
to be run once for the next round's measurement; kept out of ALL until then.

Mechanisms and signals that the other sets do not have (the laws are in :mod:`.mechanisms22`, the signals in
:mod:`.signals22`, each beside its source; the citations were written from memory, as they say):

- a clean core (100 plays with a Birnbaum-Saunders (fatigue-life) density of thresholds, (x + 1) / (2 g sqrt(2 pi
  x^3)) exp(-(x - 1)^2 / (2 x g^2)), x = r / s with s 8 ... 16 V and g 0.5 ... 1.2, on 0 ... 40 ... 46 V: a hump with a
  long right tail; a drawn linear part, gain and offset) under the x of Thomas's cyclically symmetric attractor (x' =
  sin y - b x and cyclically, b 0.18 ... 0.186: chaotic, both signs; 20 ... 32 of its time units a second), centred,
  faded in from 0 V over 1 s, to peaks of +-44 ... 48 V, with a noisy input monitor, sampled at 1.71 kHz;
- creep with the Jeffreys-Lomnitz law ((1 + t / tau)^alpha - 1) / alpha (tau 0.05 ... 0.3 s, alpha 0.15 ... 0.35:
  linear at first, then a power law, unbounded), 5 ... 8 % of the core's output after 10 s of a held load, by
  Boltzmann superposition (exact for a load linear between samples, by FFT convolution); under a kiln's two firings
  (a controller's linear ramps at 6 ... 25 V/s to soaks held 1 ... 6 s, a top of 88 ... 97 V in the second, a
  controlled cooling ramp, and natural cooling by Newton's law, tau 6 ... 10 s, between and at the end), on a unipolar
  stroke, sampled at 255 Hz;
- rate dependence of a closed air chamber in front of the stage that exchanges heat with its walls (the first law with
  Newton's heat transfer, a thermal time constant of 40 ... 120 ms: isothermal when slow, adiabatic, gamma = 1.4 times
  stiffer, when fast; the air 0.3 ... 0.6 times as stiff as the stack when isothermal; the stack's free stroke 1.5 ...
  2.5 % of the chamber's depth, so the gas law stays nearly linear); under a rowing ergometer's handle (a racing start
  of five short strokes at 36 ... 40 strokes a minute, then pieces of 3 or 4 strokes at 18 ... 22, 26 ... 30, 32 ... 36
  and 22 ... 26, a rest of 1 ... 2 s at the finish before each; the drive of 0.75 ... 0.9 s nearly fixed, the recovery
  shrinking with the rate; skewed bell speed profiles), played 2.2 ... 3 times faster, +-44 ... 48 V, with a noisy
  input monitor, sampled at 1.19 kHz;
- an offset drift of a strain-gauge bridge from the thermoelectric EMF of its solder junctions under a heat lamp
  switched on twice for 4 ... 9 s (the near junction following the lamp through 0.3 ... 1 s, the far one the near one
  through 2 ... 5 s: a bump up after every switch-on and down after every switch-off, decaying while the lamp stays
  on or off), 4 ... 8 % of the span at its largest, either sign; under one coordinate of a point on a Geneva wheel of
  4, 5, 6 or 8 slots (intermittent indexing between dwells) turned by a motor's crank in four runs (0.5 ... 1.6 rev/s,
  one reversed, a first-order speed lag of 0.15 ... 0.35 s, stops between), faded in from 0 V, +-44 ... 48 V, sampled
  at 640 Hz;
- asymmetry of a photodiode read at open circuit (the logarithm of its photocurrent) behind a linear graded filter
  carried by the stage (the ends' secants 10 ... 17 % apart, compressed on a drawn side); under the intermediate-axis
  rate of an astronaut's T-handle thrown 3 or 4 times (Euler's equations, I2 1.5 ... 2.2 and I3 0.8 ... 1.5 more in
  units of I1, perturbations 0.003 ... 0.03: the Dzhanibekov flips, every 0.7 ... 1.4 s), each throw faded in and out
  over 0.25 ... 0.4 s, +-44 ... 48 V, with a noisy input monitor, sampled at 1.07 kHz;
- saturation of a line sensor reading the centroid of a Gaussian spot (the mean of a normal law truncated to the
  sensor: its tail falls off near the ends; the spot's deviation 0.2 ... 0.35 of the sensor's half-width), the ends
  compressed by 12 ... 20 %; under 6 ... 8 double lane changes of a vehicle along clothoid (Euler spiral) transition
  curves, 3.5 m over 20 ... 40 m, faster and faster (each change 1.6 ... 2 s at first, 0.5 ... 0.7 s at last), on
  alternating sides, offsets 0.6 ... 1 of +-44 ... 48 V, sampled at 760 Hz;
- a delay of a smart sensor's running median: it samples 4 times per record sample, takes the median of its last 5,
  7, 9 or 11 samples and delivers it 3 ... 9 of its samples later (1.25 ... 3.5 record samples on monotone stretches),
  the core computed on that 4x grid; under a chirp-spread-spectrum (LoRa-like) frame (spreading factor 3: 5 ... 8
  preamble up-chirps, 2.25 down-chirps, 6 ... 10 payload symbols, each a cyclically shifted up-chirp across 3.1 ...
  4.4 Hz above 0.4 ... 0.8 Hz), +-44 ... 48 V, with a noisy input monitor, sampled at 520 Hz;
- a core left by a small-signal bias sweep (a C-V or d33 measurement: from the virgin state at 0 V up to 80 ... 88 V in
  steps of 6 ... 10 V, down to 3 ... 8 V and up to 30 ... 42 V, a test signal of +-1.5 ... 3 V at every step), the record
  starting there; then the load of a gantry crane (a pendulum of 0.6 ... 1 Hz, damping 1 ... 3 %, on a trolley making
  raised-cosine moves between stations, the load swinging through the holds), first within the sweep's range, then
  to 93 ... 98 V beyond its top in the last quarter or so, on a unipolar stroke, sampled at 690 Hz;
- two effects: rate dependence of a hydraulic damper with a blow-off valve behind the stage (a linear lag of 3 ... 8
  ms up to 0.15 ... 0.3 of the core's fastest speed, 4 ... 8 times softer beyond: a digressive damper) and a gain drift of the
  LVDT reading it, whose demodulator's reference slips in phase (the gain cos(phi0 + 2 pi df t), phi0 -0.35 ... 0.1
  rad, 0.35 ... 0.55 rad over the record); under a reader's gaze (7 or 8 lines of text: saccades by the main
  sequence with skewed speed profiles, fixations of 0.1 ... 0.5 s, some regressions, a return sweep with a corrective
  saccade at every line's end), on a unipolar stroke, sampled at 1.23 kHz;
- out of vocabulary: the slider of a piezo inertia (slip-stick) drive: the core moves a rod on which a slider is
  clamped by Coulomb friction; the slider follows while the rod's acceleration is within the static limit (0.65 ...
  0.8 of the core's peak acceleration in a flyback) and slips, braked by the kinetic friction (0.75 ... 0.9 of the
  static), when the rod flies back faster; under 7 bursts of 5 ... 7 cycles of a sawtooth of half cosines (a slow rise
  and a flyback of 3 ... 5 % of the period, or the reverse, or a symmetric wave; periods 0.25 ... 0.4 s, heights 20
  ... 28 V on a base of -20 ... 0 V) in a random order, between slow full sweeps to +-44 ... 48 V, sampled at 840 Hz
  (the core and the slider on a 4x grid). Every cycle of a burst repeats the same input from the same core state, yet
  the output walks by a step per cycle, one way under the slow-rise sawtooth, the other under the fast-rise one, and
  not at all under the symmetric wave; it holds still between bursts. A PI core (any plays with non-negative weights
  and any linear part) draws the same output for the same input from the same state; creep relaxes toward the core
  and moves during holds; rate dependence and delay are filters (a periodic input gives a periodic output);
  saturation and asymmetry are continuous maps; drift and gain drift are slow functions of the time, not of which
  waveform is being played; an initial state is forgotten.
"""

import math

import numpy as np
from scipy.optimize import brentq

from . import mechanisms22 as m22
from . import signals22 as s22
from .record import case_set, finish

HOLDOUT22, case, _rng = case_set("holdout22_", 22000)


def _both_sides(v, frac):
    """True when the path reaches beyond frac of its largest magnitude on both sides."""
    return min(v.max(), -v.min()) > frac * np.abs(v).max()


def _core(rng, v, r_max=45.0, n=80):
    """The other cases' core: n exponentially weighted plays to r_max, a drawn linear part and gain."""
    w0 = rng.uniform(0.3, 0.45)
    r, weights = m22.exp_plays(n, r_max, rng.uniform(8.0, 16.0), w0)
    gain = rng.uniform(0.7, 1.4)
    return gain * m22.plays(v, r, weights, w0), dict(thresholds=r, weights=weights, linear=w0, gain=gain)


# ---- clean ----

@case
def clean_fatiguelife_plays_thomas_attractor_1710hz(seed):
    rng = _rng(seed, 1)
    dt = 1 / 1710
    n = int(rng.uniform(12.0, 18.0) / dt)
    t = np.arange(n) * dt
    units, b = rng.uniform(20.0, 32.0), rng.uniform(0.18, 0.186)
    fade = m22.raised_cosine(t / 1.0)
    for _ in range(30):
        start = tuple(rng.uniform(-1.0, 1.0, 3))
        x, s0 = s22.thomas_x(t, units, start, b)
        xc = x - (x.max() + x.min()) / 2
        if _both_sides(fade * xc, 0.85):
            break
    amp = rng.uniform(44.0, 48.0)
    scale = amp / np.abs(fade * xc).max()
    v = scale * fade * xc
    r_max, beta, g, w0 = rng.uniform(40.0, 46.0), rng.uniform(8.0, 16.0), rng.uniform(0.5, 1.2), rng.uniform(0.25, 0.4)
    r, weights = m22.fatiguelife_plays(100, r_max, beta, g, w0)
    gain, off = rng.uniform(0.7, 1.4), rng.uniform(-4.0, 4.0)
    y = gain * m22.plays(v, r, weights, w0) + off
    rec = finish("holdout22_clean_fatiguelife_plays_thomas_attractor_1710hz", seed, t, v, y, set(), "explained",
                 f"a clean core (100 plays, a fatigue-life density of thresholds, scale {beta:.1f} V, shape {g:.2f}, on "
                 f"0 ... {r_max:.0f} V) under the x of Thomas's attractor (b {b:.4f}, {units:.1f} units a second), "
                 f"faded in from 0 V, +-{amp:.0f} V, 1.71 kHz", rng, monitor_noise=3e-4)
    rec.extra.update(thresholds=r, weights=gain * weights, linear=gain * w0, offset=off, r_max=r_max, beta=beta, g=g,
                     units=units, b=b, start=start, s0=s0, x=x, xc=xc, scale=scale, amp=amp, drive=v)
    return rec


# ---- one effect ----

@case
def creep_jeffreys_lomnitz_kiln_firings_255hz(seed):
    rng = _rng(seed, 2)
    dt = 1 / 255
    top = rng.uniform(88.0, 97.0)
    segments = [("ramp", rng.uniform(6.0, 10.0), rng.uniform(0.22, 0.3) * top, rng.uniform(2.0, 4.0)),
                ("ramp", rng.uniform(10.0, 16.0), rng.uniform(0.55, 0.65) * top, rng.uniform(2.0, 3.0)),
                ("ramp", rng.uniform(6.0, 10.0), rng.uniform(0.82, 0.9) * top, rng.uniform(4.0, 6.0)),
                ("cool", rng.uniform(6.0, 10.0), rng.uniform(0.1, 0.15) * top, rng.uniform(1.0, 2.0)),
                ("ramp", rng.uniform(15.0, 25.0), rng.uniform(0.4, 0.5) * top, rng.uniform(1.5, 3.0)),
                ("ramp", rng.uniform(8.0, 12.0), top, rng.uniform(4.0, 6.0)),
                ("ramp", rng.uniform(6.0, 10.0), rng.uniform(0.7, 0.78) * top, rng.uniform(3.0, 5.0)),
                ("cool", rng.uniform(6.0, 10.0), rng.uniform(0.02, 0.05) * top, rng.uniform(2.0, 3.0))]
    pieces, end = s22.kiln_segments(0.0, segments, rng.uniform(1.0, 2.0))
    n = int(end / dt)
    t = np.arange(n) * dt
    v = s22.kiln_schedule(t, 0.0, pieces)
    h, core = _core(rng, v)
    c, tau, alpha = rng.uniform(0.05, 0.08), rng.uniform(0.05, 0.3), rng.uniform(0.15, 0.35)
    cr = m22.jl_creep(h, dt, c, tau, alpha, 10.0)
    rec = finish("holdout22_creep_jeffreys_lomnitz_kiln_firings_255hz", seed, t, v, h + cr, {"creep"}, "either",
                 f"creep by the Jeffreys-Lomnitz law ({c:.1%} after 10 s, tau {tau:.2f} s, alpha {alpha:.2f}) under a "
                 f"kiln's two firings to {top:.0f} V, 255 Hz", rng)
    rec.extra.update(core, top=top, segments=segments, pieces=pieces, h=h, c=c, tau=tau, alpha=alpha, creep=cr)
    return rec


@case
def rate_air_chamber_heat_exchange_rowing_ergometer_1190hz(seed):
    rng = _rng(seed, 3)
    dt = 1 / 1190
    kc, amp, Td0 = rng.uniform(2.2, 3.0), rng.uniform(44.0, 48.0), rng.uniform(0.75, 0.9)
    plan = [(rng.uniform(36.0, 40.0), ln) for ln in (0.5, 0.5, 0.75, 0.75, 1.0)]        # the racing start
    rests = [len(plan) - 1]
    for lo, hi in ((18.0, 22.0), (26.0, 30.0), (32.0, 36.0), (22.0, 26.0)):
        sr = rng.uniform(lo, hi)
        plan += [(sr, rng.uniform(0.88, 1.0)) for _ in range(int(rng.integers(3, 5)))]
        rests.append(len(plan) - 1)
    full = int(rng.integers(5, len(plan)))
    plan[full] = (plan[full][0], 1.0)
    lead = rng.uniform(0.6, 1.0)
    moves, tc = [(0.3, lead, -amp * plan[0][1], "recovery")], 0.3 + lead     # forward to the first catch
    for i, (sr, ln) in enumerate(plan):
        Td = Td0 * (1 - 0.004 * (sr - 20.0))
        T = 60.0 / sr
        nxt = plan[i + 1][1] if i + 1 < len(plan) else 0.0
        moves.append((tc, Td / kc, amp * ln, "drive"))
        if i in rests[:-1]:                            # easy between pieces: the recovery taken slowly after a rest
            tc += Td / kc + rng.uniform(1.0, 2.0)
            moves.append((tc, (T - Td) / kc * 1.5, -amp * nxt, "recovery"))
            tc += (T - Td) / kc * 1.5
        else:
            moves.append((tc + Td / kc, (T - Td) / kc, -amp * nxt if i + 1 < len(plan) else 0.0, "recovery"))
            tc += T / kc
    n = int((tc + 0.6) / dt)
    t = np.arange(n) * dt
    v = s22.rowing_handle(t, moves, 0.0)
    h, core = _core(rng, v)
    L = np.abs(h).max() / rng.uniform(0.015, 0.025)
    kappa, tau_th, gamma = rng.uniform(0.3, 0.6), rng.uniform(0.04, 0.12), 1.4
    y = m22.air_spring_stage(h, dt, L, kappa, gamma, tau_th)
    rec = finish("holdout22_rate_air_chamber_heat_exchange_rowing_ergometer_1190hz", seed, t, v, y,
                 {"rate_dependence"}, "either", f"an air chamber exchanging heat with its walls (tau {tau_th * 1e3:.0f} "
                 f"ms, the air {kappa:.2f} of the stack's stiffness) under {len(plan)} rowing strokes played "
                 f"{kc:.2f} times faster, +-{amp:.0f} V, 1.19 kHz", rng, monitor_noise=2.5e-4)
    rec.extra.update(core, kc=kc, amp=amp, Td0=Td0, plan=plan, moves=moves, L=L, kappa=kappa, tau_th=tau_th,
                     gamma=gamma, drive=v)
    return rec


@case
def drift_thermoelectric_junctions_heat_lamp_geneva_wheel_640hz(seed):
    rng = _rng(seed, 4)
    dt = 1 / 640
    n_slots = int(rng.choice([4, 5, 6, 8]))
    tau_m = rng.uniform(0.15, 0.35)
    commands, tc = [], rng.uniform(0.6, 1.0)
    t_first = tc
    for k, (lo, hi, d_lo, d_hi) in enumerate(((0.6, 0.9, 6.0, 9.0), (0.9, 1.3, 5.0, 8.0), (1.2, 1.6, 5.0, 8.0),
                                             (0.5, 0.8, 4.0, 6.0))):
        sign = -1.0 if k == 1 else 1.0
        commands.append((tc, sign * 2 * np.pi * rng.uniform(lo, hi)))
        tc += rng.uniform(d_lo, d_hi)
        commands.append((tc, 0.0))
        tc += rng.uniform(1.0, 2.0)
    n = int((tc + 0.5) / dt)
    t = np.arange(n) * dt
    theta = s22.motor_crank(t, commands, tau_m)
    phi = s22.geneva_angle(theta, n_slots)
    amp, phase = rng.uniform(44.0, 48.0), rng.uniform(0.0, 2 * np.pi)
    v = amp * m22.raised_cosine(t / t_first) * np.cos(phi + phase)
    h, core = _core(rng, v, r_max=42.0)
    T = t[-1]
    on1 = rng.uniform(0.12, 0.25) * T
    off1 = on1 + rng.uniform(5.0, 9.0)
    on2 = off1 + rng.uniform(4.0, 7.0)
    off2 = on2 + rng.uniform(4.0, 7.0)
    switches = [(on1, 1.0), (off1, -1.0), (on2, 1.0), (off2, -1.0)]
    tau1, tau2 = rng.uniform(0.3, 1.0), rng.uniform(2.0, 5.0)
    raw = m22.lamp_offset(t, switches, tau1, tau2)
    frac, sign = rng.uniform(0.04, 0.08), rng.choice([-1.0, 1.0])
    scale_off = sign * frac * np.ptp(h) / np.abs(raw).max()
    off = scale_off * raw
    rec = finish("holdout22_drift_thermoelectric_junctions_heat_lamp_geneva_wheel_640hz", seed, t, v, h + off,
                 {"drift"}, "either", f"a thermoelectric offset of {sign * frac:+.1%} of the span at its largest (a "
                 f"lamp on twice, the junctions' lags {tau1:.2f} and {tau2:.2f} s) under a {n_slots}-slot Geneva "
                 f"wheel, +-{amp:.0f} V, 640 Hz", rng)
    rec.extra.update(core, n_slots=n_slots, tau_m=tau_m, commands=commands, t_first=t_first, amp=amp, phase=phase,
                     h=h, switches=switches, tau1=tau1, tau2=tau2, frac=frac, sign=sign, scale_off=scale_off,
                     offset=off)
    return rec


@case
def asymmetry_photodiode_open_circuit_t_handle_flips_1070hz(seed):
    rng = _rng(seed, 5)
    dt = 1 / 1070
    ramp = rng.uniform(0.25, 0.4)
    plan, tc = [], rng.uniform(0.5, 1.0)
    sb = np.linspace(0.0, 240.0, 4801)
    for _ in range(int(rng.integers(3, 5))):
        I2 = rng.uniform(1.5, 2.2)
        inertia = (1.0, I2, I2 + rng.uniform(0.8, 1.5))
        eps = tuple(float(e) for e in rng.choice([-1.0, 1.0], 2) * np.exp(rng.uniform(math.log(0.003),
                                                                                      math.log(0.03), 2)))
        w2 = s22.throw_spin(sb, inertia, eps, 1.0)
        flips = sb[1:][np.diff(np.sign(w2)) != 0]
        units = np.diff(flips).mean() / rng.uniform(0.7, 1.4)      # the body's time units a second
        T = rng.uniform(4.0, 7.0)
        plan.append((tc, T, inertia, eps, units, float(rng.choice([-1.0, 1.0]))))
        tc += T + rng.uniform(0.4, 1.0)
    n = int((tc + 0.3) / dt)
    t = np.arange(n) * dt
    amp = rng.uniform(44.0, 48.0)
    v = amp * s22.throws(t, plan, ramp)
    w0 = rng.uniform(0.3, 0.45)
    r, weights = m22.exp_plays(80, 42.0, rng.uniform(8.0, 16.0), w0)
    x_core = m22.plays(v, r, weights, w0)
    c = (x_core.max() + x_core.min()) / 2
    X = np.abs(x_core - c).max()
    asym, side = rng.uniform(0.10, 0.17), rng.choice([-1.0, 1.0])
    rho = math.exp(rng.uniform(math.log(1e4), math.log(1e6)))

    def spread(a):
        return float(-m22.photodiode_reading(-1.0, a, rho) - m22.photodiode_reading(1.0, a, rho)) - asym
    a = brentq(spread, 1e-4, 0.9, xtol=1e-15)
    gain = rng.uniform(0.7, 1.4)
    y = gain * (c + side * X * m22.photodiode_reading(side * (x_core - c) / X, a, rho))
    rec = finish("holdout22_asymmetry_photodiode_open_circuit_t_handle_flips_1070hz", seed, t, v, y, {"asymmetry"},
                 "either", f"a photodiode's open-circuit log response behind a graded filter (the light +-{a:.1%} at "
                 f"the ends, their secants {asym:.0%} apart, compressed {'up' if side > 0 else 'down'}) under "
                 f"{len(plan)} throws of a T-handle, +-{amp:.0f} V, 1.07 kHz", rng, monitor_noise=3e-4)
    rec.extra.update(plan=plan, ramp=ramp, amp=amp, thresholds=r, weights=weights, linear=w0, core=x_core, centre=c,
                     X=X, asym=asym, side=side, rho=rho, a=a, gain=gain, drive=v)
    return rec


@case
def saturation_gaussian_spot_centroid_clothoid_lane_changes_760hz(seed):
    rng = _rng(seed, 6)
    dt = 1 / 760
    n_runs = int(rng.integers(6, 9))
    full = int(rng.integers(0, 3))
    Tc = np.geomspace(rng.uniform(1.6, 2.0), rng.uniform(0.5, 0.7), n_runs)
    runs, tc, side = [], rng.uniform(0.8, 1.5), float(rng.choice([-1.0, 1.0]))
    lengths = rng.uniform(20.0, 40.0, n_runs)
    for k in range(n_runs):
        frac = 1.0 if k in (full, full + 1) else rng.uniform(0.6, 1.0)
        km = s22.clothoid_kappa(3.5 / lengths[k])
        runs.append((tc, Tc[k], frac, km, side))
        tc += Tc[k] + rng.uniform(0.4, 1.0) * Tc[k]
        runs.append((tc, Tc[k], frac, km, -side))
        tc += Tc[k] + rng.uniform(1.0, 2.0)
        side = -side
    n = int(tc / dt)
    t = np.arange(n) * dt
    amp = rng.uniform(44.0, 48.0)
    v = amp * s22.lane_changes(t, runs)
    h, core = _core(rng, v, r_max=42.0)
    c = (h.max() + h.min()) / 2
    X = np.abs(h - c).max()
    sd, comp = rng.uniform(0.2, 0.35), rng.uniform(0.12, 0.2)
    x_end = brentq(lambda x: float(m22.spot_centroid(x, sd)) / (m22.centroid_slope0(sd) * x) - (1 - comp), 1e-3, 3.0,
                   xtol=1e-14)
    F = X / x_end
    y = m22.centroid_reading(h, c, F, sd)
    rec = finish("holdout22_saturation_gaussian_spot_centroid_clothoid_lane_changes_760hz", seed, t, v, y,
                 {"saturation"}, "either", f"the centroid of a Gaussian spot on a line sensor (the spot {sd:.2f} of its "
                 f"half-width, its centre {x_end:.2f} of it out at the ends, compressed by {comp:.0%}) under {n_runs} "
                 f"double lane changes along clothoids, +-{amp:.0f} V, 760 Hz", rng)
    rec.extra.update(core, runs=runs, lengths=lengths, Tc=Tc, amp=amp, h=h, centre=c, X=X, sd=sd, comp=comp,
                     x_end=x_end, F=F)
    return rec


@case
def delay_running_median_sensor_lora_chirps_520hz(seed):
    rng = _rng(seed, 7)
    dt, sub = 1 / 520, 4
    bw, f_lo, sf = rng.uniform(3.1, 4.4), rng.uniform(0.4, 0.8), 3
    symbols = ([0] * int(rng.integers(5, 9)) + ["down", "down", ("down", 0.25)]
               + [int(k) for k in rng.integers(0, 2 ** sf, int(rng.integers(6, 11)))])
    t0, fade = rng.uniform(0.5, 1.0), 0.5
    Ts = 2 ** sf / bw
    end = t0 + Ts * (len(symbols) - 0.75)
    n = int((end + 0.5) / dt)
    tf = np.arange((n - 1) * sub + 1) * (dt / sub)
    amp = rng.uniform(44.0, 48.0)
    x, _ = s22.css_signal(tf, f_lo, bw, sf, symbols, t0, fade)
    v_f = amp * x
    v = v_f[::sub]
    t = tf[::sub]
    h_f, core = _core(rng, v_f, r_max=42.0)
    N, D = int(rng.choice([5, 7, 9, 11])), int(rng.integers(3, 10))
    y = m22.median_sensor(h_f, sub, N, D)
    rec = finish("holdout22_delay_running_median_sensor_lora_chirps_520hz", seed, t, v, y, {"delay"}, "either",
                 f"a sensor's running median of {N} of its samples at 4x the record's rate, delivered {D} of them "
                 f"later (a delay of {(D + (N - 1) / 2) / sub:.2f} samples), under a chirp-spread-spectrum frame of "
                 f"{len(symbols)} symbols ({f_lo:.2f} ... {f_lo + bw:.2f} Hz), +-{amp:.0f} V, 520 Hz", rng,
                 monitor_noise=2e-4)
    rec.extra.update(core, bw=bw, f_lo=f_lo, sf=sf, symbols=symbols, t0=t0, fade=fade, amp=amp, sub=sub, N=N, D=D,
                     drive=v)
    return rec


@case
def initial_state_bias_sweep_history_gantry_crane_load_690hz(seed):
    rng = _rng(seed, 8)
    dt = 1 / 690
    w0 = rng.uniform(0.3, 0.45)
    r, weights = m22.exp_plays(80, 40.0, rng.uniform(10.0, 16.0), w0)
    dV, v_top, v_low, v_stop = rng.uniform(6.0, 10.0), rng.uniform(80.0, 88.0), rng.uniform(3.0, 8.0), \
        rng.uniform(30.0, 42.0)
    levels = (list(np.arange(dV, v_top, dV)) + [v_top] + list(np.arange(v_top - dV, v_low, -dV)) + [v_low]
              + list(np.arange(v_low + dV, v_stop, dV)) + [v_stop])
    a_ac = rng.uniform(1.5, 3.0)
    hist = s22.bias_sweep_history(levels, a_ac, 2)
    _, z0 = m22.plays(hist, r, weights, w0, return_state=True)
    f_p, zeta, length = rng.uniform(0.6, 1.0), rng.uniform(0.01, 0.03), rng.uniform(30.0, 50.0)
    stations, lvl = [], v_stop
    for _ in range(int(rng.integers(3, 6))):
        for _ in range(50):
            to = rng.uniform(10.0, 0.8 * v_top)
            if abs(to - lvl) > 12.0:
                break
        stations.append(to)
        lvl = to
    stations += [rng.uniform(0.85, 0.95) * v_top, rng.uniform(20.0, 40.0), 100.0, rng.uniform(40.0, 60.0),
                 rng.uniform(10.0, 20.0)]
    moves, tc = [], rng.uniform(0.8, 1.5)
    for to in stations:
        T = rng.uniform(1.5, 2.5)
        moves.append((tc, T, to))
        tc += T + rng.uniform(1.0, 2.0)
    n = int(tc / dt)
    t = np.arange(n) * dt
    x_load, phi = s22.crane_load(t, moves, v_stop, length, 2 * np.pi * f_p, zeta)
    top = rng.uniform(93.0, 98.0)
    sc = (top - v_stop) / (x_load.max() - v_stop)
    v = v_stop + sc * (x_load - v_stop)
    gain = rng.uniform(0.7, 1.4)
    y = gain * m22.plays(v, r, weights, w0, state=z0)
    rec = finish("holdout22_initial_state_bias_sweep_history_gantry_crane_load_690hz", seed, t, v, y,
                 {"initial_state"}, "either", f"a core left by a bias sweep (steps of {dV:.1f} V to {v_top:.0f} V, down "
                 f"to {v_low:.1f} V, up to {v_stop:.1f} V, +-{a_ac:.1f} V at each; the record starting there), then a "
                 f"crane's swinging load ({f_p:.2f} Hz) over {len(moves)} moves to {top:.0f} V, 690 Hz", rng)
    rec.extra.update(thresholds=r, weights=weights, linear=w0, gain=gain, levels=levels, a_ac=a_ac, history=hist,
                     state=z0, v_top=v_top, v_low=v_low, v_stop=v_stop, f_p=f_p, zeta=zeta, length=length,
                     moves=moves, sc=sc, top=top, phi=phi)
    return rec


# ---- two effects ----

@case
def pair_rate_gain_drift_blowoff_damper_lvdt_demodulator_reading_gaze_1230hz(seed):
    rng = _rng(seed, 9)
    dt = 1 / 1230
    cw, left, right = rng.uniform(1.1, 1.4), rng.uniform(4.0, 8.0), rng.uniform(88.0, 96.0)
    sacc, tc, pos = [], rng.uniform(0.4, 0.8), 0.0

    def fixation():
        return float(np.clip(math.exp(rng.normal(math.log(0.22), 0.3)), 0.1, 0.5))

    def go(to):
        nonlocal tc, pos
        T = float(s22.saccade_duration(abs(to - pos) / (3.5 * cw)))     # 3.5 characters a degree
        sacc.append((tc, T, to))
        tc, pos = tc + T, to
    go(left)
    tc += fixation()
    lines = 0
    while tc < 23.0:
        while True:
            if rng.uniform() < 0.1 and pos > left + 10.0:
                to = pos - cw * rng.uniform(2.0, 8.0)                 # a regression
            else:
                to = pos + cw * float(np.clip(rng.normal(7.5, 2.0), 3.0, 14.0))
            if to > right:
                break
            go(to)
            tc += fixation()
        if pos < right - 3.0:
            go(right - rng.uniform(0.0, 2.0))
            tc += fixation()
        go(left + rng.uniform(2.0, 5.0))                               # the return sweep falls short
        tc += rng.uniform(0.12, 0.25)
        go(left)                                                       # and is corrected
        tc += fixation()
        lines += 1
    n = int((tc + 0.3) / dt)
    t = np.arange(n) * dt
    v = s22.gaze(t, sacc, 0.0)
    h, core = _core(rng, v)
    fastest = np.abs(np.diff(h)).max() / dt
    tau1 = rng.uniform(0.003, 0.008)
    tau2, v_b = tau1 / rng.uniform(4.0, 8.0), rng.uniform(0.15, 0.3) * fastest
    y_rate = m22.blowoff_stage(h, dt, tau1, tau2, v_b)
    phi0, slip = rng.uniform(-0.35, 0.1), rng.uniform(0.35, 0.55)
    df = slip / (2 * np.pi * t[-1])
    g = m22.demodulator_gain(t, phi0, df) / math.cos(phi0)
    y = g * y_rate
    rec = finish("holdout22_pair_rate_gain_drift_blowoff_damper_lvdt_demodulator_reading_gaze_1230hz", seed, t, v, y,
                 {"rate_dependence", "gain_drift"}, "either", f"a damper with a blow-off valve (tau {tau1 * 1e3:.1f} "
                 f"ms, {tau1 / tau2:.1f} times softer beyond {v_b:.0f} units/s) and an LVDT's demodulator slipping by "
                 f"{slip:.2f} rad from {phi0:+.2f} rad, under a reader's gaze over {lines} lines, 1.23 kHz", rng)
    rec.extra.update(core, cw=cw, left=left, right=right, saccades=sacc, lines=lines, h=h, fastest=fastest, tau1=tau1,
                     tau2=tau2, v_b=v_b, y_rate=y_rate, phi0=phi0, slip=slip, df=df, g=g)
    return rec


# ---- out of vocabulary ----

@case
def oov_inertia_drive_slider_sawtooth_bursts_840hz(seed):
    rng = _rng(seed, 10)
    dt, sub = 1 / 840, 4
    amp = rng.uniform(44.0, 48.0)
    pieces, tc = [], rng.uniform(0.5, 1.0)

    def move(to, T):
        nonlocal tc
        pieces.append(("move", tc, T, to))
        tc += T + rng.uniform(0.4, 0.8)

    def sweep(base):
        move(amp, rng.uniform(2.0, 3.0))
        move(-amp, rng.uniform(3.0, 4.0))
        move(base, rng.uniform(1.5, 2.5))
    base = rng.uniform(-20.0, 0.0)
    sweep(base)
    fine = dt / sub
    H, T, f = rng.uniform(20.0, 28.0), round(rng.uniform(0.25, 0.4) / fine) * fine, rng.uniform(0.03, 0.05)
    kinds = ["fwd", "fwd", "back", "back", "sym", "sym", str(rng.choice(["fwd", "back", "sym"]))]
    rng.shuffle(kinds)
    bursts = []
    for i, kind in enumerate(kinds):
        nc = int(rng.integers(5, 8))
        tc = round(tc / fine) * fine                   # on the fine grid, as T: every cycle of a burst alike on it
        pieces.append(("burst", tc, nc, T, {"fwd": f, "back": 1 - f, "sym": 0.5}[kind], base, H))
        bursts.append((tc, nc, kind))
        tc += nc * T + rng.uniform(0.5, 1.0)
        if i == len(kinds) // 2 - 1:
            sweep(base)
    move(0.0, rng.uniform(1.5, 2.5))
    n = int(tc / dt)
    tf = np.arange((n - 1) * sub + 1) * (dt / sub)
    v_f = s22.inertia_program(tf, pieces, 0.0)
    v = v_f[::sub]
    t = tf[::sub]
    h_f, core = _core(rng, v_f)
    # the rod's peak acceleration in a flyback: the core's rise over one slow-rise cycle as a half cosine over f T
    k0 = int(round((bursts[[b[2] for b in bursts].index("fwd")][0] + T) / (dt / sub)))
    cyc = h_f[k0:k0 + int(round(T / (dt / sub)))]
    a_ref = np.pi ** 2 / 2 * np.ptp(cyc) / (f * T) ** 2
    a_s = rng.uniform(0.65, 0.8) * a_ref
    a_k = rng.uniform(0.75, 0.9) * a_s
    y_f, S = m22.inertia_slider(h_f, dt / sub, a_s, a_k)
    gain2, off = rng.uniform(0.8, 1.2), rng.uniform(-3.0, 3.0)
    y = gain2 * y_f[::sub] + off
    rec = finish("holdout22_oov_inertia_drive_slider_sawtooth_bursts_840hz", seed, t, v, y, set(), "unexplained",
                 f"an inertia drive's slider (static limit {a_s / a_ref:.2f} of the flyback's peak acceleration, "
                 f"kinetic {a_k / a_s:.2f} of it) under {len(kinds)} bursts of sawtooth cycles ({H:.0f} V, {T:.2f} s, "
                 f"flyback {f:.1%}) between sweeps to +-{amp:.0f} V, 840 Hz", rng)
    rec.extra.update(core, amp=amp, pieces=pieces, bursts=bursts, H=H, T=T, f=f, sub=sub, a_ref=a_ref, a_s=a_s,
                     a_k=a_k, slip=S[::sub], gain2=gain2, offset=off)
    return rec

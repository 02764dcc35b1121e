"""The HOLDOUT17 set: written after HOLDOUT16 was measured, by a session that did not read how the diagnosis decides,
to be run once for the next round's measurement; kept out of ALL until then.

Mechanisms and signals that the other sets do not have, or not in these combinations (the laws and signals are in
:mod:`.mechanisms17`, each beside its source; its citations were written from memory, as it says):

- a clean core (110 plays from the play's definition with a Gumbel (extreme-value) density of thresholds on 0 ... 40
  ... 46 V, its mode at 6 ... 14 V and its scale 3 ... 7 V: a skewed hump with a long tail of wide plays, a drawn
  linear part, gain and offset) under an astronomical tide (the harmonic method: M2, S2, N2, K2, K1, O1 and P1 at their
  speeds with their equilibrium amplitudes times a port's response of 0.6 ... 1.4 each, a form factor (K1 + O1) / (M2
  + S2) of 0.25 ... 1.5, random phase lags; Doodson 1921, Pugh 1987), one M2 period in 0.59 ... 0.91 s (springs and
  neaps within the record), faded in from rest at 0 V over 1 s to peaks of +-44 ... 48 V, with a noisy input
  monitor, sampled at 1.72 kHz;
- creep from a magnetic after-effect (of a magnetostrictive actuator's magnetisation) with a box spectrum of
  relaxation times (a flat distribution of activation energies: retardation times log-uniform between tau1 0.03 ...
  0.1 s and tau2 15 ... 60 s; Neel 1951; Becker & Doering 1939), c 7 ... 11 % of the core's output, linear in ln t in
  between, a Prony series of 240 Kelvin elements by Boltzmann superposition; under an oedometer's load-doubling
  programme (each load twice the last, from top / 16 or top / 32; an unloading to top / 8 and 0, a reloading by
  doubling to the top, 88 ... 97 V, and an unloading by quarters; ASTM D2435), holds of 4 ... 5.5 s, on a unipolar
  stroke from 0 V, sampled at 230 Hz;
- rate dependence from the latent heat of a transformation (an SMA wire's martensite as plays of the effective stress
  v - theta: the transformation's heat warms the wire, which cools to the air in 0.12 ... 0.4 s, and the warmth
  raises the transformation stress by Clausius-Clapeyron; adiabatic, the transformation's slope falls by a factor 1 +
  0.15 ... 0.35; Shaw & Kyriakides 1995), under a Jeffcott rotor's unbalance response through its critical speed
  (1.2 ... 2 Hz, damping 0.12 ... 0.25) on a run-up at constant acceleration from 0.3 ... 0.45 to 2.4 ... 3.2 times
  the critical speed over 8 ... 12 s and a viscous coast-down back below it, about a preload of 50 V faded in from
  0 V (0 ... 94 ... 98 V), with a noisy input monitor, sampled at 1.53 kHz;
- an offset drift from a part flash-heated in vacuum (heated at 300 ... 700 K/s for 1 ... 3 s from 293 K to 600 ...
  1600 K, cooling by radiation only: dT/dt = -k (T^4 - T_a^4), k 6e-11 ... 2e-10 /K^3 s, the Stefan-Boltzmann law; a
  sharp rise and a slow, non-exponential tail), the offset 4 ... 8 % of the span at its peak (either sign) from 12
  ... 30 % of the record on; under an autofocus routine (per field: a coarse sweep of 8 ... 10 steps to the top, 88
  ... 97 V, a golden-section search (Kiefer 1953) in the best bracket down to 0.4 ... 0.8 V, a dwell for the image
  at the focus found, a retraction to 0 V; 5 ... 7 fields), on a unipolar stroke from 0 V, sampled at 590 Hz;
- asymmetry of the tangent error of a tip-tilt mirror read on a flat detector: the spot at tan(phi0 + 2 theta) -
  tan(phi0), phi0 20 ... 30 deg off the detector's normal on a drawn side, the mirror's tilt at the ends of the
  stroke 2.5 ... 4 deg (the beam's 5 ... 8 deg): one end stretched and the other compressed by several per cent
  (monotone); under a vector scan of 5 or 6 star polygons ({5/2}, {7/2}, {7/3}, {8/3}, {9/2}, {9/4}; radii 0.6 ... 1 of
  the largest, random rotations) traced edge by edge at a constant speed with corner dwells of 50 ... 100 ms, +-44
  ... 48 V, with a noisy input monitor, sampled at 1.13 kHz;
- saturation by the large deflection of a blade flexure (the stage at the tip of a cantilever loaded by the core's
  force: the elastica, Bisshopp & Drucker 1945, the ends compressed by 10 ... 17 %, odd); under one coordinate of 10
  ... 13 Keplerian orbits (a cos E by Kepler's equation: fast through the periapsis, slow round the apoapsis;
  eccentricities 0.05 ... 0.8, periods 1 ... 1.8 s, two each, semi-major axes 0.55 ... 1 of 44 ... 48 V, the
  periapsis on a drawn side), sampled at 670 Hz;
- a delay of a Hall probe at the mid-plane of a thick conducting slab (the magnet's field diffusing through it:
  1 / cosh(sqrt(s tau)), a delay of tau / 2 = 2.2 ... 3.8 samples at low frequencies with a diffusive roll-off above;
  Carslaw & Jaeger 1959), the core computed on a 4x finer grid; under shot noise (alpha-function pulses of 25 ... 60 ms
  at Poisson times, 3 ... 6 a second, heights of either sign; Rice 1944), +-44 ... 48 V, with a noisy input monitor,
  sampled at 1.24 kHz;
- a core left by a bake-out with the stack held at a bias of 25 ... 45 V: heated, its thresholds fell to 0.3 ... 0.55
  of themselves (the coercive field falls with the temperature) and the plays were dragged toward the bias; cooled
  under the bias, then the bias ramped to 0 V, where the record starts (z = min(r, max(0, bias - f r)): the field-cooled
  memory, Neel 1949, which no excursion at room temperature leaves); under a Shepard-Risset glissando (five octave-
  spaced sines from 0.12 ... 0.2 Hz gliding an octave in 4 ... 8 s under a Gaussian envelope; Shepard 1964) about a
  level rising from 0 to 50 V over 2.5 ... 4 s, its depth growing from 0.2 to 0.96 of the level, to 91 ... 98 V and
  0 ... 9 V, which wipes the memory out, on a unipolar stroke, sampled at 860 Hz;
- two effects: rate dependence of a voltage-driven magnetostrictive actuator (its coil's current lagging the voltage by
  L / R = 3 ... 8 ms) and a core left by a calibration routine's successive-approximation search (a range check to
  +-0.8 ... 0.88 of the drive's peak, then 8 ... 10 bisection steps for the voltage whose settled output reaches a drawn
  force; Kester 2005), the record starting where the search ended, held 0.6 ... 1 s; under a pump's strokes after
  the heart's (systoles of Bazett's QT = 0.37 ... 0.42 sqrt(RR), fillings of the other sign, diastasis at 0 V; the rate
  from 60 ... 72 through four stages to 150 ... 170 beats a minute and back through 0.8 to 0.65 of that, the stroke
  growing with the rate to +-44 ... 48 V at the peak), sampled at 1.41 kHz;
- out of vocabulary: the sliders of a precision guide (Maxwell-slip elements: plays of thresholds to 30 V beside a
  linear part of 0.15 ... 0.3) heal at rest and weaken as they slip: a slider's threshold is r (1 + beta ln(1 + theta /
  t_c)), theta its contact's age, which grows while it stands still (Dieterich 1972; beta 0.09 ... 0.12, t_c 10 ...
  30 ms: strong healing, 21 ... 28 % more per decade of dwell) and falls as exp(-s / d_c) with its slip s (Palmer &
  Rice 1973; d_c 18 ... 26 V); under a two-station shuttle between +-44 ... 48 V (20 ... 25 identical raised-cosine
  moves of 0.35 ... 0.6 s) with dwells spread log-uniformly over 0.03 ... 20 s in a random order, sampled at 390 Hz.
  The output stands still through every dwell, and every move repeats the same input from the same state of a PI
  core, yet the moves after long dwells break away later and stop short: the same move, and the level held after it,
  differ by many noise levels according to how long the stage stood before it. A PI core (any plays with non-negative
  weights and any linear part) draws the same output for the same input from the same state; creep moves during the
  dwells, rate dependence changes with the speed (the same in every move), drift and gain drift with the time (not
  with the dwell before a move, in a random order), delay, saturation and asymmetry are fixed filters or maps, and an
  initial state is forgotten after the first full move.
"""

import math

import numpy as np
from scipy.optimize import brentq

from . import mechanisms17 as m17
from .record import case_set, finish

HOLDOUT17, case, _rng = case_set("holdout17_", 17000)

#: the star polygons {n/k} the vector scan draws from
STARS = ((5, 2), (7, 2), (7, 3), (8, 3), (9, 2), (9, 4))


def _both_sides(v, frac):
    """True when the path reaches beyond frac of its largest magnitude on both sides."""
    return min(v.max(), -v.min()) > frac * np.abs(v).max()


# ---- clean ----

@case
def clean_gumbel_plays_tidal_constituents_1720hz(seed):
    rng = _rng(seed, 1)
    dt = 1 / 1720
    n = int(rng.uniform(15.0, 21.0) / dt)
    t = np.arange(n) * dt
    f_m2 = rng.uniform(1.1, 1.7)                        # M2 periods a second
    hours = 360.0 / m17.TIDES[0][1] * f_m2              # tidal hours a second
    amps = np.array([c[2] for c in m17.TIDES]) * rng.uniform(0.6, 1.4, len(m17.TIDES))
    form = rng.uniform(0.25, 1.5)
    amps[4:] *= form * (amps[0] + amps[1]) / (amps[4] + amps[5])
    t0_h = rng.uniform(0.0, 709.0)                     # the start within a lunar month (in hours)
    fade = m17.raised_cosine(t / 1.0)
    for _ in range(30):                                # phase lags whose tide reaches 90 % of its peak both ways
        phases = rng.uniform(0, 2 * np.pi, len(m17.TIDES))
        x = fade * m17.tide(t0_h + hours * t, amps, phases)
        if _both_sides(x, 0.9):
            break
    amp = rng.uniform(44.0, 48.0)
    scale = amp / np.abs(x).max()
    v = scale * x
    r_max, mu, beta, w0 = rng.uniform(40.0, 46.0), rng.uniform(6.0, 14.0), rng.uniform(3.0, 7.0), rng.uniform(0.25, 0.4)
    r, weights = m17.gumbel_plays(110, r_max, mu, beta, w0)
    gain, off = rng.uniform(0.7, 1.4), rng.uniform(-4.0, 4.0)
    y = gain * m17.plays(v, r, weights, w0) + off
    rec = finish("holdout17_clean_gumbel_plays_tidal_constituents_1720hz", seed, t, v, y, set(), "explained",
                 f"a clean core (110 plays, a Gumbel density of thresholds on 0 ... {r_max:.0f} V, mode {mu:.1f} V, "
                 f"scale {beta:.1f} V) under a tide of seven constituents (form factor {form:.2f}, M2 at "
                 f"{f_m2:.2f} Hz), faded in from 0 V, +-{amp:.0f} V, 1.72 kHz", rng, monitor_noise=3e-4)
    rec.extra.update(thresholds=r, weights=gain * weights, linear=gain * w0, offset=off, r_max=r_max, mu=mu, beta=beta,
                     f_m2=f_m2, hours=hours, amps=amps, phases=phases, form=form, t0_h=t0_h, scale=scale, amp=amp,
                     drive=v)
    return rec


# ---- one effect ----

@case
def creep_box_spectrum_after_effect_load_doubling_230hz(seed):
    rng = _rng(seed, 2)
    dt = 1 / 230
    top, k_first = rng.uniform(88.0, 97.0), int(rng.integers(4, 6))
    levels = m17.load_doubling_levels(top, k_first)
    holds, edge, lead = rng.uniform(4.0, 5.5, len(levels)), rng.uniform(0.15, 0.3), rng.uniform(0.5, 1.0)
    v, starts = m17.ramps_and_holds(dt, levels, holds, edge, lead)
    t = np.arange(len(v)) * dt
    w0 = rng.uniform(0.3, 0.45)
    r, weights = m17.exp_plays(80, 45.0, rng.uniform(8.0, 16.0), w0)
    gain = rng.uniform(0.7, 1.4)
    h = gain * m17.plays(v, r, weights, w0)
    tau1, tau2 = math.exp(rng.uniform(math.log(0.03), math.log(0.1))), math.exp(rng.uniform(math.log(15), math.log(60)))
    c = rng.uniform(0.07, 0.11)
    taus, wts = m17.box_prony(tau1, tau2)
    cr = m17.prony_creep(h, dt, c, taus, wts)
    rec = finish("holdout17_creep_box_spectrum_after_effect_load_doubling_230hz", seed, t, v, h + cr, {"creep"},
                 "either", f"a magnetic after-effect with a box spectrum ({c:.1%}, tau {tau1 * 1e3:.0f} ms ... "
                 f"{tau2:.0f} s) under an oedometer's load doubling from top / {2 ** k_first} (holds of 4 ... 5.5 s), "
                 f"0 ... {top:.0f} V, 230 Hz", rng)
    rec.extra.update(top=top, k_first=k_first, levels=levels, holds=holds, edge=edge, lead=lead, starts=starts,
                     thresholds=r, weights=weights, linear=w0, gain=gain, core=h, tau1=tau1, tau2=tau2, c=c, creep=cr)
    return rec


@case
def rate_latent_heat_sma_wire_rotor_runup_coastdown_1530hz(seed):
    rng = _rng(seed, 3)
    dt = 1 / 1530
    fn, zeta = rng.uniform(1.2, 2.0), rng.uniform(0.12, 0.25)
    wn = 2 * np.pi * fn
    w_a, w_b, t_up = wn * rng.uniform(0.3, 0.45), wn * rng.uniform(2.4, 3.2), rng.uniform(8.0, 12.0)
    t_down = rng.uniform(6.0, 9.0)
    tau_c = t_down / rng.uniform(1.5, 2.5)             # the coast-down ends below the critical speed
    n = int((t_up + t_down) / dt)
    t = np.arange(n) * dt
    x = m17.jeffcott_runup(dt, n, wn, zeta, w_a, w_b, t_up, tau_c)
    amp = rng.uniform(44.0, 48.0)
    xs = amp / np.abs(x).max()
    v = m17.raised_cosine(t / 1.0) * (50.0 + xs * x)
    w0 = rng.uniform(0.25, 0.4)
    r, weights = m17.exp_plays(70, 40.0, rng.uniform(8.0, 15.0), w0)
    kappa, tau = rng.uniform(0.15, 0.35), rng.uniform(0.12, 0.4)
    lam = kappa / (1 - w0)
    gain = rng.uniform(0.7, 1.4)
    y = gain * m17.latent_heat_plays(v, dt, r, weights, w0, lam, tau)
    rec = finish("holdout17_rate_latent_heat_sma_wire_rotor_runup_coastdown_1530hz", seed, t, v, y,
                 {"rate_dependence"}, "either", f"plays of the effective stress with latent heat (adiabatic slope / "
                 f"{1 + kappa:.2f}, the wire cooling in {tau * 1e3:.0f} ms) under a rotor's run-up through its "
                 f"critical speed ({fn:.2f} Hz, zeta {zeta:.2f}) and coast-down, about 50 V, 0 ... "
                 f"{v.max():.0f} V, 1.53 kHz", rng, monitor_noise=2.5e-4)
    rec.extra.update(fn=fn, zeta=zeta, w_a=w_a, w_b=w_b, t_up=t_up, tau_c=tau_c, x=x, xs=xs, amp=amp, thresholds=r,
                     weights=weights, linear=w0, kappa=kappa, lam=lam, tau=tau, gain=gain, drive=v)
    return rec


@case
def drift_radiative_flash_in_vacuum_golden_section_autofocus_590hz(seed):
    rng = _rng(seed, 4)
    dt = 1 / 590
    top, nf = rng.uniform(88.0, 97.0), int(rng.integers(5, 8))
    speed, t_min, lead = rng.uniform(250.0, 400.0), 0.03, rng.uniform(0.4, 0.8)
    pts, dws, foci = [0.0], [lead], []
    for _ in range(nf):
        focus, width = rng.uniform(0.15, 0.85) * top, rng.uniform(4.0, 10.0)
        p = m17.autofocus_points(focus, width, top, int(rng.integers(8, 11)), rng.uniform(0.4, 0.8))
        frame = rng.uniform(0.08, 0.14)
        pts += list(p) + [0.0]
        dws += [frame] * (len(p) - 1) + [rng.uniform(0.6, 1.2), rng.uniform(0.3, 0.5)]
        foci.append((focus, p[-1]))
    v, starts = m17.moves_and_dwells(dt, 0.0, pts, dws, speed, t_min)
    t = np.arange(len(v)) * dt
    w0 = rng.uniform(0.3, 0.45)
    r, weights = m17.exp_plays(80, 45.0, rng.uniform(10.0, 20.0), w0)
    gain = rng.uniform(0.7, 1.4)
    h = gain * m17.plays(v, r, weights, w0)
    T_a, k, q = 293.0, math.exp(rng.uniform(math.log(6e-11), math.log(2e-10))), rng.uniform(300.0, 700.0)
    t_on = rng.uniform(0.12, 0.3) * t[-1]
    t_off = t_on + rng.uniform(1.0, 3.0)
    T = m17.radiative_temperature(t, T_a, k, q, t_on, t_off)
    frac, sign = rng.uniform(0.04, 0.08), rng.choice([-1.0, 1.0])
    size = sign * frac * np.ptp(h) / (T.max() - T_a)
    y = h + size * (T - T_a)
    rec = finish("holdout17_drift_radiative_flash_in_vacuum_golden_section_autofocus_590hz", seed, t, v, y, {"drift"},
                 "either", f"an offset from a part flash-heated in vacuum ({q:.0f} K/s for {t_off - t_on:.1f} s, to "
                 f"{T.max():.0f} K, cooling by radiation: {sign * frac:+.1%} of the span at the peak), {nf} fields "
                 f"focused by golden-section searches, 0 ... {top:.0f} V, 590 Hz", rng)
    rec.extra.update(top=top, points=np.array(pts), dwells=np.array(dws), starts=starts, foci=np.array(foci),
                     speed=speed, t_min=t_min, thresholds=r, weights=weights, linear=w0, gain=gain, core=h, T_a=T_a,
                     k=k, q=q, t_on=t_on, t_off=t_off, T=T, frac=frac, size=size)
    return rec


@case
def asymmetry_tangent_error_tip_tilt_mirror_star_polygons_1130hz(seed):
    rng = _rng(seed, 5)
    dt = 1 / 1130
    amp = rng.uniform(44.0, 48.0)
    ns = int(rng.integers(5, 7))
    kinds = [STARS[i] for i in rng.integers(0, len(STARS), ns)]
    radii = rng.uniform(0.6, 1.0, ns)
    radii[int(rng.integers(0, ns))] = 1.0
    speed, dwell = rng.uniform(4.5, 6.5), rng.uniform(0.05, 0.1)                # radii a second, s
    jump, lead = rng.uniform(0.15, 0.3), rng.uniform(0.3, 0.6)
    for _ in range(30):                                # rotations whose vertices reach 85 % of the peak both ways
        th0 = rng.uniform(0, 2 * np.pi, ns)
        stars = [(n_, k_, R, a_) for (n_, k_), R, a_ in zip(kinds, radii, th0)]
        path, verts = m17.star_scan(dt, stars, speed, dwell, jump, lead)
        if _both_sides(path, 0.85):
            break
    scale = amp / np.abs(path).max()
    v = scale * path
    t = np.arange(len(v)) * dt
    w0 = rng.uniform(0.3, 0.45)
    r, weights = m17.exp_plays(80, 42.0, rng.uniform(8.0, 16.0), w0)
    x = m17.plays(v, r, weights, w0)
    side = rng.choice([-1.0, 1.0])
    phi0, tilt = side * np.radians(rng.uniform(20.0, 30.0)), np.radians(rng.uniform(2.5, 4.0))
    k = tilt / np.abs(x).max()
    gain = rng.uniform(0.7, 1.4)
    y = gain * m17.lever_reading(x, phi0, k)
    rec = finish("holdout17_asymmetry_tangent_error_tip_tilt_mirror_star_polygons_1130hz", seed, t, v, y,
                 {"asymmetry"}, "either", f"a tip-tilt mirror read on a flat detector {np.degrees(phi0):+.0f} deg off "
                 f"its normal (the tilt {np.degrees(tilt):.1f} deg at the ends), {ns} star polygons ("
                 f"{', '.join(f'{a}/{b}' for a, b in kinds)}) traced with corner dwells, +-{amp:.0f} V, 1.13 kHz",
                 rng, monitor_noise=3.5e-4)
    rec.extra.update(stars=stars, speed=speed, dwell=dwell, jump=jump, lead=lead, verts=scale * verts, scale=scale,
                     amp=amp, thresholds=r, weights=weights, linear=w0, core=x, phi0=phi0, tilt=tilt, k=k, gain=gain,
                     drive=v)
    return rec


@case
def saturation_elastica_blade_flexure_kepler_orbits_670hz(seed):
    rng = _rng(seed, 6)
    dt = 1 / 670
    amp, no = rng.uniform(44.0, 48.0), int(rng.integers(10, 14))
    periods, eccs = rng.uniform(1.0, 1.8, no), rng.uniform(0.05, 0.8, no)
    amps = amp * rng.uniform(0.55, 1.0, no)
    amps[int(rng.integers(0, no))] = amp
    amps *= rng.choice([-1.0, 1.0], no)
    lead = rng.uniform(0.3, 0.6)
    v, starts = m17.kepler_orbits(dt, periods, eccs, amps, np.full(no, 2), lead)
    t = np.arange(len(v)) * dt
    w0 = rng.uniform(0.3, 0.45)
    r, weights = m17.exp_plays(80, 42.0, rng.uniform(8.0, 16.0), w0)
    gain = rng.uniform(0.7, 1.4)
    h = gain * m17.plays(v, r, weights, w0)
    c = (h.max() + h.min()) / 2
    x_t = np.abs(h - c).max()
    comp = rng.uniform(0.10, 0.17)
    alpha_t = brentq(lambda a: 3 * m17.elastica_tip(np.array([a]))[0] / a - (1 - comp), 0.05, 10.0, xtol=1e-13)
    y = c + m17.elastica_stage(h - c, x_t, alpha_t)
    rec = finish("holdout17_saturation_elastica_blade_flexure_kepler_orbits_670hz", seed, t, v, y, {"saturation"},
                 "either", f"a blade flexure bent into an elastica (PL^2/EI {alpha_t:.2f} at the ends, compressed by "
                 f"{comp:.0%}) after the core, {no} Kepler orbits (e {eccs.min():.2f} ... {eccs.max():.2f}), "
                 f"+-{amp:.0f} V, 670 Hz", rng)
    rec.extra.update(periods=periods, eccs=eccs, amps=amps, lead=lead, starts=starts, amp=amp, thresholds=r,
                     weights=weights, linear=w0, gain=gain, core=h, centre=c, x_t=x_t, comp=comp, alpha_t=alpha_t)
    return rec


@case
def delay_hall_probe_in_conducting_slab_shot_noise_1240hz(seed):
    rng = _rng(seed, 7)
    dt = 1 / 1240
    dur, lam_p = rng.uniform(13.0, 19.0), rng.uniform(3.0, 6.0)
    tau_p, lead = rng.uniform(0.025, 0.06), rng.uniform(0.3, 0.6)
    n = int(dur / dt)
    t = np.arange(n) * dt
    for _ in range(30):                                # arrivals and heights that reach 85 % of the peak both ways
        arr = lead + np.cumsum(rng.exponential(1 / lam_p, int(3 * lam_p * dur)))
        times = arr[arr < dur - 0.6]
        heights = rng.choice([-1.0, 1.0], len(times)) * rng.uniform(0.35, 1.0, len(times))
        sig = m17.alpha_pulses(t, times, heights, tau_p)
        if _both_sides(sig, 0.85):
            break
    amp = rng.uniform(44.0, 48.0)
    scale = amp / np.abs(sig).max()
    v = scale * sig
    sub = 4
    t_fine = np.arange(n * sub) * (dt / sub)
    w0 = rng.uniform(0.3, 0.45)
    r, weights = m17.exp_plays(60, 40.0, rng.uniform(8.0, 16.0), w0)
    gain = rng.uniform(0.8, 1.4)
    h_fine = gain * m17.plays(scale * m17.alpha_pulses(t_fine, times, heights, tau_p), r, weights, w0)
    delay = rng.uniform(2.2, 3.8)
    tau = 2 * delay * dt
    y = m17.slab_filter(h_fine, dt / sub, tau)[::sub]
    half = math.sqrt(tau / (4e-7 * math.pi * 3.7e7))     # an aluminium slab's half thickness for that tau
    rec = finish("holdout17_delay_hall_probe_in_conducting_slab_shot_noise_1240hz", seed, t, v, y, {"delay"},
                 "either", f"a Hall probe at the mid-plane of a conducting slab (tau {tau * 1e3:.1f} ms, as aluminium "
                 f"{2 * half * 1e3:.0f} mm thick: a delay of {delay:.2f} samples), shot noise of {len(times)} alpha "
                 f"pulses ({tau_p * 1e3:.0f} ms), +-{amp:.0f} V, 1.24 kHz", rng, monitor_noise=2e-4)
    rec.extra.update(times=times, heights=heights, tau_p=tau_p, lam_p=lam_p, scale=scale, amp=amp, sub=sub,
                     thresholds=r, weights=weights, linear=w0, gain=gain, tau=tau, delay_samples=delay, drive=v)
    return rec


@case
def initial_state_bakeout_field_cooled_shepard_risset_860hz(seed):
    rng = _rng(seed, 8)
    dt = 1 / 860
    n = int(rng.uniform(16.0, 23.0) / dt)
    t = np.arange(n) * dt
    f_low, glide, sigma, up = rng.uniform(0.12, 0.2), rng.uniform(4.0, 8.0), rng.uniform(0.7, 1.0), rng.random() < 0.5
    rise, grow = rng.uniform(2.5, 4.0), rng.uniform(5.0, 8.0)
    level = 50.0 * m17.raised_cosine(t / rise)
    depth = 0.96 * (0.2 + 0.8 * m17.raised_cosine(t / grow))
    late = t > grow
    for _ in range(30):                                # a start in the glissando that swings 85 % both ways late on
        t0 = rng.uniform(0.0, 5 * glide)
        x = m17.shepard_risset(t + t0, f_low, 5, glide, sigma, up)
        x = x / np.abs(x[late]).max()
        v = level * (1 + depth * x)
        if _both_sides(x[late], 0.85) and v.max() <= 100.0 and v.min() >= 0.0:
            break
    w0 = rng.uniform(0.3, 0.45)
    r, weights = m17.exp_plays(80, 40.0, rng.uniform(10.0, 18.0), w0)
    bias, f_t = rng.uniform(25.0, 45.0), rng.uniform(0.3, 0.55)
    z0 = m17.bakeout_state(r, bias, f_t)
    gain = rng.uniform(0.7, 1.4)
    y = gain * m17.plays(v, r, weights, w0, state=z0)
    rec = finish("holdout17_initial_state_bakeout_field_cooled_shepard_risset_860hz", seed, t, v, y,
                 {"initial_state"}, "either", f"a core left by a bake-out at a bias of {bias:.0f} V (the thresholds "
                 f"at {f_t:.0%} hot), cooled under the bias and ramped to 0 V, then a Shepard-Risset glissando "
                 f"({'up' if up else 'down'}, an octave in {glide:.1f} s) about a rising level, 0 ... "
                 f"{v.max():.0f} V, 860 Hz", rng)
    rec.extra.update(f_low=f_low, glide=glide, sigma=sigma, up=up, rise=rise, grow=grow, t0=t0, x=x, thresholds=r,
                     weights=weights, linear=w0, bias=bias, f_t=f_t, state=z0, gain=gain)
    return rec


# ---- two effects ----

@case
def pair_rate_initial_state_magnetostrictive_coil_sar_search_bazett_beats_1410hz(seed):
    rng = _rng(seed, 9)
    dt = 1 / 1410
    amp = rng.uniform(44.0, 48.0)
    w0 = rng.uniform(0.3, 0.45)
    r, weights = m17.exp_plays(80, 40.0, rng.uniform(8.0, 16.0), w0)
    a_s, n_bits = amp * rng.uniform(0.8, 0.88), int(rng.integers(8, 11))
    target = rng.uniform(-0.5, 0.5) * a_s
    pts, z_sar, outs = m17.sar_history(r, weights, w0, target, -a_s, a_s, n_bits)
    v_star = pts[-1]
    hr0, hr_pk = rng.uniform(60.0, 72.0), rng.uniform(150.0, 170.0)
    hrs = np.r_[np.full(3, hr0), np.repeat(np.linspace(hr0 + (hr_pk - hr0) / 4, hr_pk, 4), 4),
                np.full(3, 0.8 * hr_pk), np.full(3, 0.65 * hr_pk)]
    strokes = np.interp(hrs, [hr0, hr_pk], [rng.uniform(0.35, 0.45), 1.0]) * amp
    fills = strokes * rng.uniform(0.85, 1.0, len(hrs))
    fills[hrs == hr_pk] = amp
    k_qt, fill_frac = rng.uniform(0.37, 0.42), rng.uniform(0.45, 0.65)
    beats, bstarts = m17.bazett_beats(dt, 60.0 / hrs, strokes, fills, k_qt, fill_frac)
    hold, glide = rng.uniform(0.6, 1.0), rng.uniform(0.3, 0.5)
    mg = int(round(glide / dt))
    v = np.r_[np.full(int(round(hold / dt)), v_star), v_star * (1 - m17.raised_cosine(np.arange(1, mg + 1) / mg)),
              beats, np.zeros(int(round(0.4 / dt)))]
    t = np.arange(len(v)) * dt
    tau = rng.uniform(0.003, 0.008)
    i_coil = m17.ramp_lag(v, dt, tau)
    gain = rng.uniform(0.7, 1.4)
    y = gain * m17.plays(i_coil, r, weights, w0, state=z_sar)
    rec = finish("holdout17_pair_rate_initial_state_magnetostrictive_coil_sar_search_bazett_beats_1410hz", seed, t, v,
                 y, {"rate_dependence", "initial_state"}, "either", f"a magnetostrictive actuator's coil lagging its "
                 f"voltage by L / R = {tau * 1e3:.0f} ms and a core left by a {n_bits}-step successive-approximation "
                 f"search (range +-{a_s:.0f} V, ending at {v_star:+.1f} V, where the record starts), {len(hrs)} pump "
                 f"strokes by Bazett's law ({hr0:.0f} ... {hr_pk:.0f} beats a minute), +-{amp:.0f} V, 1.41 kHz", rng)
    rec.extra.update(amp=amp, thresholds=r, weights=weights, linear=w0, a_s=a_s, n_bits=n_bits, target=target,
                     history=pts, state=z_sar, outs=outs, v_star=v_star, hrs=hrs, strokes=strokes, fills=fills,
                     k_qt=k_qt, fill_frac=fill_frac, bstarts=bstarts, hold=hold, glide=glide, tau=tau, gain=gain)
    return rec


# ---- out of vocabulary ----

@case
def oov_dwell_healing_slip_weakening_guide_shuttle_390hz(seed):
    rng = _rng(seed, 10)
    dt = 1 / 390
    amp, nm = rng.uniform(44.0, 48.0), int(rng.integers(20, 26))
    dwells = rng.permutation(np.geomspace(0.03, 20.0, nm)) * rng.uniform(0.9, 1.1, nm)
    move_s, lead = rng.uniform(0.35, 0.6), rng.uniform(0.5, 1.0)
    v, mstarts = m17.shuttle(dt, amp, dwells, move_s, lead)
    t = np.arange(len(v)) * dt
    w0 = rng.uniform(0.15, 0.3)
    r, weights = m17.exp_plays(60, 30.0, rng.uniform(8.0, 14.0), w0)
    beta, t_c, d_c = rng.uniform(0.09, 0.12), rng.uniform(0.01, 0.03), rng.uniform(18.0, 26.0)
    gain = rng.uniform(0.7, 1.4)
    y = gain * m17.healing_plays(v, dt, r, weights, w0, beta, t_c, d_c)
    rec = finish("holdout17_oov_dwell_healing_slip_weakening_guide_shuttle_390hz", seed, t, v, y, set(), "unexplained",
                 f"a guide's sliders healing at rest (beta {beta:.3f}, t_c {t_c * 1e3:.0f} ms) and weakening over "
                 f"{d_c:.1f} V of slip, a shuttle of {nm} moves between +-{amp:.0f} V with dwells of 0.03 ... 20 s in "
                 f"a random order, 390 Hz", rng)
    rec.extra.update(amp=amp, dwells=dwells, move_s=move_s, lead=lead, mstarts=mstarts, thresholds=r, weights=weights,
                     linear=w0, beta=beta, t_c=t_c, d_c=d_c, gain=gain)
    return rec

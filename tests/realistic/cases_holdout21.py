"""The HOLDOUT21 set: written after HOLDOUT20 was measured, by a session that did not read how the diagnosis decides,
to be run once for the next round's measurement; kept out of ALL until then.

Mechanisms and signals that the other sets do not have (the laws are in :mod:`.mechanisms21`, the signals in
:mod:`.signals21`, each beside its source; the citations were written from memory, as they say):

- a clean core (100 plays with a log-logistic (Fisk) density of thresholds, (b / a) (r / a)^(b - 1) / (1 + (r /
  a)^b)^2 with a 8 ... 16 V and b 2 ... 4, on 0 ... 40 ... 46 V: a hump with an algebraic tail of wide plays; a drawn
  linear part, gain and offset) under the x of Ueda's forced hardening Duffing oscillator (x'' + 0.05 x' + x^3 = 7.5
  cos t, chaotic in a single well; 6 ... 9 of its time units a second), centred, faded in from 0 V over 1 s, to peaks
  of +-44 ... 48 V, with a noisy input monitor, sampled at 1.52 kHz;
- creep with Becquerel's law 1 - (1 + t / (k tau))^-k (a gamma distribution of relaxation rates, shape k 0.45 ...
  0.9, mean rate 1 / tau, tau 1 ... 3 s: an algebraic tail), 11 ... 16 % of the core's output, by Boltzmann
  superposition (a Kelvin chain of about 330 cells in ln rate between 1e-4 and 1e3 /s); under a boat passing a
  staircase flight of 3 ... 5 locks up, down, 2 or 3 of them up again and down (each chamber filled or emptied through
  its sluice by Torricelli's law: the head left falls as (sqrt(lift) - k t / 2)^2, 1.5 ... 2.5 s a lock; holds of 2.5
  ... 4.5 s while the boat moves on, 4.5 ... 6 s at the top), 0 ... 88 ... 97 V, on a unipolar stroke, sampled at
  265 Hz;
- rate dependence of a pneumatic bellows stage fed through a restrictor by ISO 6358's flow law (the valve sets the
  supply 4 ... 6 bar above the atmosphere at the core's top; critical pressure ratio b 0.3 ... 0.5; choked flow, a
  fixed slew, far from equilibrium, an elliptic fall of the flow near it: a lag that is neither linear nor a fixed
  time), the choked slew at mid-stroke 0.5 ... 0.9 times the core's fastest; under voiced speech as Rosenberg's
  glottal pulses (9 ... 13 syllables of 3 ... 7 whole cycles, the pitch gliding from 3 ... 6 Hz by a factor 0.75 ...
  1.15, opening over 40 % of a cycle and closing over 16 %, amplitudes 0.55 ... 1 of 88 ... 97 V, silences of 0.15
  ... 0.4 s), on a unipolar stroke, with a noisy input monitor, sampled at 1.96 kHz;
- an offset drift of a magnetic position sensor as a vehicle (a forklift, a magnetic dipole along its path) passes it
  2 or 3 times at a closest distance d, there and back (turned round), each pass a raised-cosine move from -4 ... 6 d
  to +4 ... 6 d over 3 ... 6 s: (2 X^2 - d^2) / (X^2 + d^2)^(5/2), a dip at the closest approach between two humps,
  4 ... 8 % of the span at the dip (either sign); under a windscreen wiper's crank-rocker four-bar (Freudenstein's
  equation; coupler 3.6 ... 4.2, rocker 2.2 ... 2.8, ground 0.1 ... 0.4 beyond the coupler, in cranks: a quick
  return), parked at one end, in intermittent (single wipes and pauses of 1.2 ... 2.5 s), slow (0.65 ... 0.8 rev/s)
  and fast (1 ... 1.3 rev/s) modes, +-44 ... 48 V, sampled at 590 Hz;
- asymmetry of a Mooney-Rivlin rubber pad between the stage and a load cell (2 (c1 + c2 / lam) (lam - lam^-2), c2 /
  c1 0.1 ... 0.6; stiffer squeezed than stretched, the ends' secants 10 ... 17 % apart, squeezed on a drawn side);
  under flight-test multistep inputs (7 ... 10 manoeuvres, 3-2-1-1 or doublets, units of 0.2 ... 0.45 s,
  amplitudes 0.6 ... 1 of +-44 ... 48 V, a drawn sign, raised-cosine edges of 40 ... 80 ms, trim between), with a
  noisy input monitor, sampled at 1.06 kHz;
- saturation of a sensor reading the stage through a ferrite above its Curie point (Weiss's mean field, m = tanh(h +
  rho m), rho = T_c / T 0.5 ... 0.85: a sharper knee than tanh, odd), the ends compressed by 12 ... 20 %; under the
  heading of a ship in Kempf's zig-zag manoeuvres by Nomoto's first-order model (10/10, then 20/20, then 10/10; K
  0.9 ... 1.5 /s, T 0.25 ... 0.5 s, the rudder at 40 ... 60 deg/s), scaled to +-44 ... 48 V, sampled at 715 Hz;
- a delay of a position sensor on a CAN bus: it samples on its own clock (0.1 ... 0.9 sample out of phase with the
  logger) and needs 1.5 ... 2.5 samples to convert, its frames queue behind higher-priority traffic (mostly under 0.3
  sample, a third of them up to 1 ... 2.2 samples) and go out in order, the logger holding the newest frame arrived: a
  jittering delay of about 1.5 ... 5.5 samples, frames read twice or skipped; the core on an 8x finer grid; under a
  stepping motor's rotor (moves of whole steps of 2 ... 3 V between 18 ... 24 set points within +-44 ... 48 V, the
  step rate ramped from 15 ... 25 to 40 ... 70 steps a second and back, the rotor ringing at 15 ... 25 Hz, zeta 0.12
  ... 0.25, at every step), with a noisy input monitor, sampled at 430 Hz;
- a core left by a relay auto-tuning (from the virgin state at 0 V to a set point of 55 ... 68 V, 3 ... 6 cycles of
  the relay's +-12 ... 18 V about it, then the tuned loop's move to a park level of 28 ... 40 V, overshooting by 4 ...
  9 V and ringing out by 0.35 ... 0.6 a half cycle), the record starting at the park level; then a seal's dives (up
  to the surface at 2 ... 6 V, 6 ... 8 dives deeper and deeper from 45 ... 55 V, with wiggles of 3 ... 8 V at the
  bottom, the last two to 93 ... 98 V beyond the history's top), on a unipolar stroke, sampled at 880 Hz;
- two effects: creep with the Rouse spectrum (40 modes, times tau1 / p^2, tau1 1.5 ... 4 s, strengths as 1 / p^2:
  sqrt(t) at first), 8 ... 12 % of the core's output, and asymmetry of a load cell reading the tension of a sagging
  cable pulled by the stage (Irvine's elastic cable: soft while it sags, elastic when taut; convex, the ends' secants
  10 ... 17 % apart); under two flights' altitude (climbs with the rate falling linearly to a ceiling, level
  flight, step climbs to 88 ... 97 V in the first, constant-rate descents with level-offs, ground time between), on a
  unipolar stroke, sampled at 505 Hz;
- out of vocabulary: thermally activated Barkhausen jumps: 3 or 4 pinned wall segments after the core, each adding 3
  ... 5 % of the span when it breaks free, at the rate f0 exp(-delta0 (1 - h / H_p)^(3/2)) (f0 1e9 /s, delta0 40 ...
  60, H_p such that the mean wait at the rinse spin's level is 1.5 ... 6 s), falling back pinned once the drive is
  low; under a washing machine's drum speed (tumbling, then 4 or 5 identical rinses, each a distribution step, a spin
  to 0.55 ... 0.68 of the top held 2 ... 3.5 s, a stop and tumbling, then a final spin to 88 ... 97 V), on a unipolar
  stroke, sampled at 345 Hz. In the repeated rinse spins the core's input and state are the same, but the jumps come
  at random moments of the hold, or not at all: the output at the hold's level differs by whole jumps between rinses,
  and steps between two samples while the input holds still. A PI core (any plays with non-negative weights and any
  linear part) draws the same output for the same input from the same state and is constant while its input is;
  creep relaxes smoothly and identically after identical moves; drift and gain drift are slow functions of the time;
  rate dependence and delay are filters, saturation and asymmetry continuous maps, and an initial state is forgotten.
"""

import math

import numpy as np
from scipy.optimize import brentq

from . import mechanisms21 as m21
from . import signals21 as s21
from .record import case_set, finish

HOLDOUT21, case, _rng = case_set("holdout21_", 21000)


def _both_sides(v, frac):
    """True when the path reaches beyond frac of its largest magnitude on both sides."""
    return min(v.max(), -v.min()) > frac * np.abs(v).max()


def _core(rng, v, r_max=45.0, n=80):
    """The other cases' core: n exponentially weighted plays to r_max, a drawn linear part and gain."""
    w0 = rng.uniform(0.3, 0.45)
    r, weights = m21.exp_plays(n, r_max, rng.uniform(8.0, 16.0), w0)
    gain = rng.uniform(0.7, 1.4)
    return gain * m21.plays(v, r, weights, w0), dict(thresholds=r, weights=weights, linear=w0, gain=gain)


# ---- clean ----

@case
def clean_loglogistic_plays_ueda_oscillator_1520hz(seed):
    rng = _rng(seed, 1)
    dt = 1 / 1520
    n = int(rng.uniform(12.0, 18.0) / dt)
    t = np.arange(n) * dt
    units = rng.uniform(6.0, 9.0)
    fade = m21.raised_cosine(t / 1.0)
    for _ in range(30):
        start = (rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0))
        x, s0 = s21.ueda_x(t, units, start)
        xc = x - (x.max() + x.min()) / 2
        if _both_sides(fade * xc, 0.85):
            break
    amp = rng.uniform(44.0, 48.0)
    scale = amp / np.abs(fade * xc).max()
    v = scale * fade * xc
    r_max, a, b, w0 = rng.uniform(40.0, 46.0), rng.uniform(8.0, 16.0), rng.uniform(2.0, 4.0), rng.uniform(0.25, 0.4)
    r, weights = m21.loglogistic_plays(100, r_max, a, b, w0)
    gain, off = rng.uniform(0.7, 1.4), rng.uniform(-4.0, 4.0)
    y = gain * m21.plays(v, r, weights, w0) + off
    rec = finish("holdout21_clean_loglogistic_plays_ueda_oscillator_1520hz", seed, t, v, y, set(), "explained",
                 f"a clean core (100 plays, a log-logistic density of thresholds, a {a:.1f} V, b {b:.2f}, on 0 ... "
                 f"{r_max:.0f} V) under the x of Ueda's oscillator ({units:.2f} units a second), faded in from 0 V, "
                 f"+-{amp:.0f} V, 1.52 kHz", rng, monitor_noise=3e-4)
    rec.extra.update(thresholds=r, weights=gain * weights, linear=gain * w0, offset=off, r_max=r_max, a=a, b=b,
                     units=units, start=start, s0=s0, x=x, xc=xc, scale=scale, amp=amp, drive=v)
    return rec


# ---- one effect ----

@case
def creep_becquerel_compliance_canal_lock_flight_265hz(seed):
    rng = _rng(seed, 2)
    dt = 1 / 265
    n_l = int(rng.integers(3, 6))
    top = rng.uniform(88.0, 97.0)
    parts = rng.uniform(0.8, 1.2, n_l)
    lifts = top * parts / parts.sum()                  # the chambers' lifts, bottom to top
    part = int(rng.integers(2, 4))                     # the second boat goes part of the way up
    steps = list(lifts) + list(-lifts[::-1]) + list(lifts[:part]) + list(-lifts[:part][::-1])
    holds = rng.uniform(2.5, 4.5, len(steps))
    holds[n_l - 1] = rng.uniform(4.5, 6.0)             # at the top
    T_avg = rng.uniform(1.5, 2.5)
    k = 2 * math.sqrt(lifts.mean()) / T_avg
    lead = rng.uniform(1.0, 2.0)
    _, _, end = s21.lock_flight(np.zeros(1), lead, steps, holds, k)
    n = int(end / dt)
    t = np.arange(n) * dt
    v, seg, _ = s21.lock_flight(t, lead, steps, holds, k)
    h, core = _core(rng, v)
    c, tau, kk = rng.uniform(0.11, 0.16), rng.uniform(1.0, 3.0), rng.uniform(0.45, 0.9)
    cr = m21.becquerel_creep(h, dt, c, tau, kk)
    rec = finish("holdout21_creep_becquerel_compliance_canal_lock_flight_265hz", seed, t, v, h + cr, {"creep"},
                 "either", f"creep by Becquerel's law ({c:.1%}, tau {tau:.2f} s, k {kk:.2f}) under a boat through a "
                 f"flight of {n_l} locks to {top:.0f} V and {part} back up, 265 Hz", rng)
    rec.extra.update(core, n_l=n_l, top=top, lifts=lifts, part=part, steps=np.array(steps), holds=holds, k=k,
                     lead=lead, seg=seg, h=h, c=c, tau=tau, kk=kk, creep=cr)
    return rec


@case
def rate_pneumatic_restrictor_bellows_glottal_pulses_1960hz(seed):
    rng = _rng(seed, 3)
    dt = 1 / 1960
    top = rng.uniform(88.0, 97.0)
    n_syl = int(rng.integers(9, 14))
    full = int(rng.integers(0, 3))
    tc, syl = rng.uniform(0.4, 0.8), []
    for i in range(n_syl):
        fa = rng.uniform(3.0, 6.0)
        fb = fa * rng.uniform(0.75, 1.15)
        nc = int(rng.integers(3, 8))
        T = s21.syllable_length(fa, fb, nc)
        if tc + T + 0.3 > 19.5:                        # at most 20 s (39,200 samples)
            break
        syl.append((tc, fa, fb, nc, top * (1.0 if i == full else rng.uniform(0.55, 1.0))))
        tc += T + rng.uniform(0.15, 0.4)
    n = max(int((tc + 0.3) / dt), 11_000)
    t = np.arange(n) * dt
    v = s21.syllables(t, syl)
    h, core = _core(rng, v)
    p_a, gp, b = 1.0, rng.uniform(4.0, 6.0), rng.uniform(0.3, 0.5)
    kappa = gp / np.abs(h).max()
    dh = np.abs(np.diff(h)).max() / dt * kappa         # the core's fastest, bar/s
    rel = rng.uniform(0.5, 0.9)
    tau_c = (p_a + gp / 2) / (rel * dh)                # the choked slew at mid-stroke, rel of that
    y = m21.bellows_stage(h, dt, p_a, kappa, b, tau_c)
    rec = finish("holdout21_rate_pneumatic_restrictor_bellows_glottal_pulses_1960hz", seed, t, v, y,
                 {"rate_dependence"}, "either", f"a bellows fed through a restrictor (ISO 6358, b {b:.2f}, {gp:.1f} "
                 f"bar at the top, the choked slew {rel:.2f} of the core's fastest) under {len(syl)} voiced syllables "
                 f"of Rosenberg pulses to {top:.0f} V, 1.96 kHz", rng, monitor_noise=2.5e-4)
    rec.extra.update(core, top=top, syl=syl, p_a=p_a, gp=gp, b=b, kappa=kappa, rel=rel, tau_c=tau_c, drive=v)
    return rec


@case
def drift_passing_vehicle_dipole_wiper_linkage_590hz(seed):
    rng = _rng(seed, 4)
    dt = 1 / 590
    a_, b_, c_ = 1.0, rng.uniform(3.6, 4.2), rng.uniform(2.2, 2.8)
    d_ = b_ + rng.uniform(0.1, 0.4)
    thg = np.linspace(0, 2 * np.pi, 20001)
    phg = s21.fourbar_rocker(thg, a_, b_, c_, d_)
    th_park = float(thg[np.argmin(phg)])
    ph_lo, ph_hi = float(phg.min()), float(phg.max())
    t_acc = rng.uniform(0.15, 0.25)
    plan = []                                          # (n_rev, rate, pause after)
    for _ in range(int(rng.integers(3, 5))):
        plan.append((1, rng.uniform(0.7, 0.9), rng.uniform(1.2, 2.5)))
    plan.append((int(rng.integers(4, 7)), rng.uniform(0.65, 0.8), 0.0))
    plan.append((int(rng.integers(5, 9)), rng.uniform(1.0, 1.3), 0.0))
    plan.append((int(rng.integers(3, 5)), rng.uniform(0.65, 0.8), rng.uniform(1.2, 2.5)))
    for _ in range(int(rng.integers(2, 4))):
        plan.append((1, rng.uniform(0.7, 0.9), rng.uniform(1.2, 2.5)))
    t_park = rng.uniform(0.6, 1.0)
    tc, runs = t_park + rng.uniform(0.5, 1.0), []
    for nr, rate, pause in plan:
        runs.append((tc, nr, rate, t_acc))
        tc += s21.run_length(nr, rate, t_acc) + pause
    n = int((tc + 1.0) / dt)
    t = np.arange(n) * dt
    amp = rng.uniform(44.0, 48.0)
    phi = s21.fourbar_rocker(th_park + 2 * np.pi * s21.crank_runs(t, runs), a_, b_, c_, d_)
    wipe = amp * (2 * (phi - ph_lo) / (ph_hi - ph_lo) - 1)
    v = np.where(t < t_park, -amp * m21.raised_cosine(t / t_park), wipe)
    h, core = _core(rng, v, r_max=42.0)
    n_p = int(rng.integers(2, 4))
    slot = t[-1] / (n_p + 1)
    passes = []
    for i in range(n_p):
        T, L = rng.uniform(3.0, 6.0), rng.uniform(4.0, 6.0)
        t0 = slot * (i + 0.5) + rng.uniform(0.1, 0.4) * slot
        X0, X1 = (-L, L) if i % 2 == 0 else (L, -L)
        passes.append((t0, T, X0, X1))
    frac, sign = rng.uniform(0.04, 0.08), rng.choice([-1.0, 1.0])
    off = m21.vehicle_offset(t, passes, 1.0, sign * frac * np.ptp(h))
    rec = finish("holdout21_drift_passing_vehicle_dipole_wiper_linkage_590hz", seed, t, v, h + off, {"drift"},
                 "either", f"an offset drift of {sign * frac:+.1%} of the span at the closest approach as a vehicle "
                 f"passes a magnetic sensor {n_p} times, under a windscreen wiper's four-bar ({len(runs)} runs), "
                 f"+-{amp:.0f} V, 590 Hz", rng)
    rec.extra.update(core, bars=(a_, b_, c_, d_), th_park=th_park, ph_lo=ph_lo, ph_hi=ph_hi, t_park=t_park, runs=runs,
                     amp=amp, h=h, passes=passes, frac=frac, sign=sign, offset=off)
    return rec


@case
def asymmetry_mooney_rivlin_pad_multistep_manoeuvres_1060hz(seed):
    rng = _rng(seed, 5)
    dt = 1 / 1060
    edge = rng.uniform(0.04, 0.08)
    n_m = int(rng.integers(7, 11))
    full = int(rng.integers(0, 3))
    tc, man = rng.uniform(0.5, 1.0), []
    for i in range(n_m):
        kind = "3211" if (i == full or rng.uniform() < 0.6) else "doublet"
        unit = rng.uniform(0.2, 0.45)
        L = s21.multistep_length(unit, kind)
        if tc + L + edge + 0.5 > 36.0:
            break
        man.append((tc, unit, 1.0 if i == full else rng.uniform(0.6, 1.0), rng.choice([-1.0, 1.0]), kind))
        tc += L + edge + rng.uniform(0.8, 1.8)
    n = max(int((tc + 0.5) / dt), 10_600)
    t = np.arange(n) * dt
    amp = rng.uniform(44.0, 48.0)
    v = amp * s21.multistep(t, man, edge)
    w0 = rng.uniform(0.3, 0.45)
    r, weights = m21.exp_plays(80, 42.0, rng.uniform(8.0, 16.0), w0)
    x_core = m21.plays(v, r, weights, w0)
    c = (x_core.max() + x_core.min()) / 2
    X = np.abs(x_core - c).max()
    c1, c2 = 1.0, rng.uniform(0.1, 0.6)
    asym, side = rng.uniform(0.10, 0.17), rng.choice([-1.0, 1.0])

    def spread(e):
        return float(-m21.pad_reading(-1.0, e, c1, c2) - m21.pad_reading(1.0, e, c1, c2)) - asym
    e_max = brentq(spread, 1e-4, 0.3, xtol=1e-15)      # the pad's strain at the ends
    gain = rng.uniform(0.7, 1.4)
    y = gain * (c + side * X * m21.pad_reading(side * (x_core - c) / X, e_max, c1, c2))
    rec = finish("holdout21_asymmetry_mooney_rivlin_pad_multistep_manoeuvres_1060hz", seed, t, v, y, {"asymmetry"},
                 "either", f"a Mooney-Rivlin pad (c2 / c1 {c2:.2f}, strained {e_max:.1%} at the ends, their secants "
                 f"{asym:.0%} apart, squeezed {'up' if side > 0 else 'down'}) under {len(man)} multistep manoeuvres, "
                 f"+-{amp:.0f} V, 1.06 kHz", rng, monitor_noise=3e-4)
    rec.extra.update(man=man, edge=edge, amp=amp, thresholds=r, weights=weights, linear=w0, core=x_core, centre=c,
                     X=X, c1=c1, c2=c2, asym=asym, side=side, e_max=e_max, gain=gain, drive=v)
    return rec


@case
def saturation_weiss_mean_field_ship_zigzag_715hz(seed):
    rng = _rng(seed, 6)
    dt = 1 / 715
    K, T, rr = rng.uniform(0.9, 1.5), rng.uniform(0.25, 0.5), rng.uniform(40.0, 60.0)
    blocks = [(10.0, 10.0, int(rng.integers(3, 6))), (20.0, 20.0, int(rng.integers(3, 6))),
              (10.0, 10.0, int(rng.integers(2, 4)))]
    lead, tail = rng.uniform(0.8, 1.2), rng.uniform(1.0, 2.0)
    pieces, end = s21.zigzag(blocks, K, T, rr, lead, tail)
    n = min(int(end / dt), 40_000)
    t = np.arange(n) * dt
    psi, rud = s21.heading(t, pieces, K, T)
    amp = rng.uniform(44.0, 48.0)
    v = amp * psi / np.abs(psi).max()
    h, core = _core(rng, v, r_max=42.0)
    c = (h.max() + h.min()) / 2
    X = np.abs(h - c).max()
    rho, comp = rng.uniform(0.5, 0.85), rng.uniform(0.12, 0.2)
    F = brentq(lambda F_: float(F_ * (1 - rho) * m21.weiss_m(X / F_, rho)) - (1 - comp) * X, 1e-3 * X, 1e3 * X,
               xtol=1e-12 * X)
    y = m21.weiss_reading(h, c, F, rho)
    rec = finish("holdout21_saturation_weiss_mean_field_ship_zigzag_715hz", seed, t, v, y, {"saturation"}, "either",
                 f"a ferrite's mean-field magnetisation (T_c / T {rho:.2f}, the ends compressed by {comp:.0%}) under "
                 f"Kempf's zig-zags (10/10, 20/20, 10/10; Nomoto K {K:.2f} /s, T {T:.2f} s), +-{amp:.0f} V, 715 Hz",
                 rng)
    rec.extra.update(core, K=K, T=T, rr=rr, blocks=blocks, lead=lead, tail=tail, pieces=pieces, psi=psi, rudder=rud,
                     amp=amp, h=h, centre=c, X=X, rho=rho, comp=comp, F=F)
    return rec


@case
def delay_can_bus_arbitration_stepper_motor_430hz(seed):
    rng = _rng(seed, 7)
    dt, sub = 1 / 430, 8
    amp = rng.uniform(44.0, 48.0)
    sv = rng.uniform(2.0, 3.0)                         # a step, V
    n_full = int(amp / sv)
    n_mv = int(rng.integers(18, 25))
    k_hi, k_lo = int(rng.integers(0, 4)), int(rng.integers(4, 8))    # the moves to the extremes
    f_lo, f_hi, n_ramp = rng.uniform(15.0, 25.0), rng.uniform(40.0, 70.0), int(rng.integers(4, 9))
    wn, zeta = 2 * np.pi * rng.uniform(15.0, 25.0), rng.uniform(0.12, 0.25)
    tc, pos, steps = rng.uniform(0.4, 0.8), 0, []
    for i in range(n_mv):
        if i == k_hi:
            tgt = n_full
        elif i == k_lo:
            tgt = -n_full
        else:
            for _ in range(50):
                tgt = int(rng.integers(-n_full, n_full + 1))
                if abs(tgt - pos) * sv >= 15.0:
                    break
        ns = abs(tgt - pos)
        times, end = s21.step_times(tc, ns, f_lo, f_hi, n_ramp)
        steps += [(tj, math.copysign(sv, tgt - pos)) for tj in times]
        pos = tgt
        tc = end + rng.uniform(0.4, 1.0)
    n = max(int((tc + 0.5) / dt), 10_500)
    tf = np.arange((n - 1) * sub + 1) * (dt / sub)
    v_f = s21.rotor_angle(tf, steps, wn, zeta)
    v = v_f[::sub]
    t = tf[::sub]
    h_f, core = _core(rng, v_f, r_max=42.0)
    phase, d0 = rng.uniform(0.1, 0.9) * dt, rng.uniform(1.5, 2.5) * dt
    W = rng.uniform(1.0, 2.2) * dt
    big = rng.uniform(size=n) < 1 / 3
    waits = np.where(big, rng.uniform(0, W, n), rng.uniform(0, 0.3 * dt, n))
    y, delays = m21.can_reading(lambda s: np.interp(s, tf, h_f, left=h_f[0]), n, dt, phase, d0, waits)
    rec = finish("holdout21_delay_can_bus_arbitration_stepper_motor_430hz", seed, t, v, y, {"delay"}, "either",
                 f"a CAN bus sensor ({phase / dt:.2f} samples out of phase, {d0 / dt:.2f} samples to convert), its "
                 f"frames queued up to {W / dt:.2f} samples (a delay of {delays[n // 10:].min():.2f} ... "
                 f"{delays[n // 10:].max():.2f} samples), under a "
                 f"stepping motor ({len(steps)} steps of {sv:.2f} V, ringing at {wn / 2 / np.pi:.1f} Hz), "
                 f"+-{amp:.0f} V, 430 Hz", rng, monitor_noise=2e-4)
    rec.extra.update(core, amp=amp, sv=sv, steps=steps, wn=wn, zeta=zeta, f_lo=f_lo, f_hi=f_hi, n_ramp=n_ramp,
                     sub=sub, phase=phase, d0=d0, W=W, waits=waits, delays=delays, drive=v)
    return rec


@case
def initial_state_relay_autotune_seal_dives_880hz(seed):
    rng = _rng(seed, 8)
    dt = 1 / 880
    w0 = rng.uniform(0.3, 0.45)
    r, weights = m21.exp_plays(80, 40.0, rng.uniform(10.0, 16.0), w0)
    sp, d = rng.uniform(55.0, 68.0), rng.uniform(12.0, 18.0)
    park = rng.uniform(28.0, 40.0)
    hist = s21.relay_autotune_history(sp, d, int(rng.integers(3, 7)), park, rng.uniform(4.0, 9.0),
                                      rng.uniform(0.35, 0.6), int(rng.integers(3, 6)))
    _, z0 = m21.plays(hist, r, weights, w0, return_state=True)
    surface = rng.uniform(2.0, 6.0)
    n_d = int(rng.integers(6, 9))
    depths = np.r_[np.linspace(rng.uniform(45.0, 55.0), hist.max() - rng.uniform(3.0, 6.0), n_d - 2),
                   rng.uniform(93.0, 95.5), rng.uniform(95.5, 98.0)]
    tc, plan = rng.uniform(0.8, 1.5), []
    for D in depths:
        td, tb, ta = rng.uniform(0.7, 1.2), rng.uniform(0.8, 1.6), rng.uniform(0.7, 1.2)
        plan.append((tc, D, td, tb, ta, rng.uniform(3.0, 8.0), rng.uniform(2.0, 4.0)))
        tc += td + tb + ta + rng.uniform(0.5, 1.2)
    n = max(int(tc / dt), 11_000)
    t = np.arange(n) * dt
    phases = rng.uniform(0, 2 * np.pi, n_d)
    v = s21.dives(t, park, surface, plan, phases)
    gain = rng.uniform(0.7, 1.4)
    y = gain * m21.plays(v, r, weights, w0, state=z0)
    rec = finish("holdout21_initial_state_relay_autotune_seal_dives_880hz", seed, t, v, y, {"initial_state"},
                 "either", f"a core left by a relay auto-tuning (set point {sp:.0f} V, relay +-{d:.0f} V, to "
                 f"{hist.max():.0f} V; parked at {park:.1f} V, where the record starts), then {n_d} dives of a seal to "
                 f"{depths[-1]:.0f} V, 880 Hz", rng)
    rec.extra.update(thresholds=r, weights=weights, linear=w0, gain=gain, setpoint=sp, d=d, park=park, history=hist,
                     state=z0, surface=surface, depths=depths, plan=plan, phases=phases)
    return rec


# ---- two effects ----

@case
def pair_creep_asymmetry_rouse_chain_sagging_cable_flight_profile_505hz(seed):
    rng = _rng(seed, 9)
    dt = 1 / 505
    cl, roc0 = rng.uniform(110.0, 130.0), rng.uniform(25.0, 40.0)
    top = rng.uniform(88.0, 97.0)
    legs, tc = [], rng.uniform(0.5, 1.0)

    def climb(h0, h1):
        nonlocal tc
        T_ = s21.climb_time(h0, h1, cl, roc0)
        legs.append((tc, "climb", h0, h1, (cl, roc0), T_))
        tc += T_

    def level(h0, lo, hi):
        nonlocal tc
        T_ = rng.uniform(lo, hi)
        legs.append((tc, "level", h0, h0, None, T_))
        tc += T_

    def descend(h0, h1):
        nonlocal tc
        T_ = (h0 - h1) / rng.uniform(12.0, 20.0)
        legs.append((tc, "descend", h0, h1, None, T_))
        tc += T_
    fl = [rng.uniform(40.0, 60.0), rng.uniform(68.0, 80.0), top]
    lo1 = rng.uniform(30.0, 45.0)
    climb(0.0, fl[0]), level(fl[0], 2.0, 4.0), climb(fl[0], fl[1]), level(fl[1], 2.0, 4.0)
    climb(fl[1], fl[2]), level(fl[2], 2.0, 4.0), descend(fl[2], lo1), level(lo1, 1.5, 3.0), descend(lo1, 0.0)
    level(0.0, 2.0, 3.0)
    f2 = [rng.uniform(50.0, 65.0), rng.uniform(75.0, 85.0)]
    climb(0.0, f2[0]), level(f2[0], 1.5, 3.0), climb(f2[0], f2[1]), level(f2[1], 2.0, 4.0), descend(f2[1], 0.0)
    level(0.0, 1.5, 2.5)
    n = int(tc / dt)
    t = np.arange(n) * dt
    v = s21.flight_profile(t, legs)
    h, core = _core(rng, v)
    c, tau1 = rng.uniform(0.08, 0.12), rng.uniform(1.5, 4.0)
    cr = m21.rouse_creep(h, dt, c, tau1, 40)
    u = h + cr
    q = 3e-3
    cu = (u.max() + u.min()) / 2
    X = np.abs(u - cu).max()
    xi_mid, asym = rng.uniform(0.5, 1.5), rng.uniform(0.10, 0.17)

    def H(xi):
        return m21.cable_tension(np.asarray(xi, float) * q, q) / q

    eps = 1e-6
    slope = float(H(xi_mid + eps) - H(xi_mid - eps)) / (2 * eps)

    def spread(w):
        return float((H(xi_mid + w) - H(xi_mid)) - (H(xi_mid) - H(xi_mid - w))) / (w * slope) - asym
    w = brentq(spread, 1e-3, 5.0, xtol=1e-13)
    gain = rng.uniform(0.7, 1.4)
    y = gain * (cu + X * (H(xi_mid + w * (u - cu) / X) - H(xi_mid)) / (w * slope))
    rec = finish("holdout21_pair_creep_asymmetry_rouse_chain_sagging_cable_flight_profile_505hz", seed, t, v, y,
                 {"creep", "asymmetry"}, "either", f"creep with the Rouse spectrum ({c:.1%}, tau1 {tau1:.2f} s) and a "
                 f"sagging cable's tension (secants {asym:.0%} apart) under two flights to {top:.0f} V, 505 Hz", rng)
    rec.extra.update(core, cl=cl, roc0=roc0, top=top, legs=legs, h=h, c=c, tau1=tau1, creep=cr, u=u, q=q, cu=cu, X=X,
                     xi_mid=xi_mid, asym=asym, w=w, slope=slope, gain2=gain)
    return rec


# ---- out of vocabulary ----

@case
def oov_barkhausen_thermal_depinning_washing_machine_spins_345hz(seed):
    rng = _rng(seed, 10)
    dt = 1 / 345
    top = rng.uniform(88.0, 97.0)
    L, tum = rng.uniform(0.55, 0.68) * top, rng.uniform(0.12, 0.2) * top
    moves, tc = [], rng.uniform(0.5, 1.0)

    def go(to, dur, hold):
        nonlocal tc
        moves.append((tc, dur, to))
        tc += dur + hold

    def tumble():
        go(tum, 0.3, rng.uniform(0.6, 1.2))
        go(0.0, 0.3, rng.uniform(0.4, 0.8))
    for _ in range(int(rng.integers(5, 9))):
        tumble()
    n_r = int(rng.integers(4, 6))
    holds = []
    for _ in range(n_r):
        go(0.25 * top, 0.6, 0.8)
        T_up, T_h = rng.uniform(1.2, 1.8), rng.uniform(2.0, 3.5)
        go(L, T_up, T_h)
        holds.append((tc - T_h, tc))
        go(0.0, rng.uniform(0.8, 1.2), rng.uniform(0.6, 1.0))
        tumble()
        tumble()
    go(0.25 * top, 0.6, 0.8)
    go(L, 1.5, rng.uniform(2.0, 3.0))
    go(top, 1.5, rng.uniform(2.0, 3.0))
    go(0.0, 1.2, 1.0)
    n = int(tc / dt)
    t = np.arange(n) * dt
    v = s21.drum_speed(t, moves, tc)
    h, core = _core(rng, v)
    k_hold = int(np.searchsorted(t, holds[-1][0] + 0.5))
    hL = float(h[k_hold])                              # the core's output during the rinse spins' holds
    m = int(rng.integers(3, 5))
    f0, delta0 = 1e9, rng.uniform(40.0, 60.0, m)
    tau_w = np.exp(rng.uniform(math.log(1.5), math.log(6.0), m))
    H_p = hL / (1 - (np.log(f0 * tau_w) / delta0) ** (2 / 3))
    H_r = rng.uniform(0.2, 0.3, m) * hL
    jumps = rng.uniform(0.03, 0.05, m) * np.ptp(h)
    uni = rng.uniform(size=(n, m))
    st = m21.barkhausen_states(h, dt, H_p, H_r, delta0, f0, uni)
    gain2, off = rng.uniform(0.8, 1.2), rng.uniform(-3.0, 3.0)
    y = gain2 * (h + st @ jumps) + off
    rec = finish("holdout21_oov_barkhausen_thermal_depinning_washing_machine_spins_345hz", seed, t, v, y, set(),
                 "unexplained", f"{m} wall segments jumping by thermal activation (3 ... 5 % of the span each, mean "
                 f"waits {', '.join(f'{x:.1f}' for x in tau_w)} s at the spin level) under a washing machine's "
                 f"{n_r} rinse spins to {L:.0f} V and a final spin to {top:.0f} V, 345 Hz", rng)
    rec.extra.update(core, top=top, L=L, tum=tum, moves=moves, holds=holds, h=h, hL=hL, f0=f0, delta0=delta0,
                     tau_w=tau_w, H_p=H_p, H_r=H_r, jumps=jumps, uniforms=uni, states=st, gain2=gain2, offset=off)
    return rec

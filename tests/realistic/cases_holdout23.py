"""The HOLDOUT23 set: written after HOLDOUT22 was measured, by a session that did not read how the diagnosis decides,
to be run once for the next round's measurement; kept out of ALL until then.

Mechanisms and signals that the other sets do not have (the laws are in :mod:`.mechanisms23`, the signals in
:mod:`.signals23`, each beside its source; the citations were written from memory, as they say):

- a clean core (100 plays with a Nakagami-m density of thresholds, r^(2m - 1) exp(-m r^2 / W), m 1.2 ... 2.5 and sqrt(W)
  9 ... 16 V, on 0 ... 40 ... 46 V: the envelope law of a faded signal, a hump; a drawn linear part, gain and offset)
  under the current x of Rikitake's two-disc dynamo (mu 2, a 5: chaotic, circling about either sign and reversing at
  irregular times; 4 ... 6 of its time units a second), centred, faded in from 0 V over 1 s, to peaks of +-44 ... 48 V,
  with a noisy input monitor, sampled at 1.58 kHz;
- creep with the Fuoss-Kirkwood distribution of retardation times (the density (beta / pi) cos(beta pi / 2) cosh(beta
  s) / (cos^2(beta pi / 2) + sinh^2(beta s)) in s = ln(tau / tau0), tau0 0.5 ... 3 s, beta 0.45 ... 0.75: a loss
  peak sech(beta ln(omega tau0)), broad and symmetric in ln omega, with exponential tails), 5 ... 8 % of the core's
  output after 10 s of a held load, by Boltzmann superposition (a Kelvin chain of 192 cells from 0.1 ms to 10^4 s,
  exact for a load linear between samples); under 4 shots of a spring-lever espresso machine (a pre-infusion at the
  line pressure, 0.1 ... 0.15 of the top, for 2 ... 4 s; the lever released to a peak of 88 ... 97 V; the pressure
  falling exponentially (the spring's force linear in the piston's travel, the puck's flow by Darcy's law) with tau
  5 ... 14 s to 0.45 ... 0.6 of the peak, one shot cut short by the barista; vented to 0 V; 3 ... 6 s between shots),
  on a unipolar stroke, sampled at 275 Hz;
- rate dependence of a damper filled with a shear-thinning fluid behind the stage (the Ostwald-de Waele power law,
  stress ~ rate^n, n 0.4 ... 0.6: a lag of 2.5 ... 4 % of the core's span at its fastest that falls only as the speed's
  n-th power at slower speeds, and relaxes algebraically after a move); under the 20-m multistage shuttle run (the
  beep test: a walk to the line, a warm-up jog at 6 ... 7 km/h, levels 1 ... 8 ... 11 at 8.5 km/h and 0.5 km/h more
  each, their shuttles per level as remembered, a walk back; each leg from rest to rest with braking and starting at 2.5
  ... 4 m/s^2), played 28 ... 36 times faster, the lines at +-44 ... 48 V, with a noisy input monitor, sampled at
  1.48 kHz;
- an offset drift from a ground loop carrying a DC pump motor's current (started across the line 3 times, an inrush of
  4 ... 7 times the running current decaying as the motor spins up, 0.3 ... 0.9 s, coasting down ratio times slower
  when switched off, seen through the sensor's 5 ... 20 ms input filter), 4 ... 8 % of the span at the inrush's peak,
  either sign; under a cyclist's pedal (the crank's height for a cadence linear between knots: a start, a steady 1.1
  ... 1.4 rev/s, a sprint to 1.7 ... 2 rev/s, freewheeling stops with the crank wherever it came to rest, a restart),
  from 0 V, +-44 ... 48 V, sampled at 560 Hz;
- asymmetry of a hot-wire anemometer reading a flow set by a throttle the stage moves (King's law E^2 = A + B U^n, n
  0.4 ... 0.5, A / B U0^n 0.5 ... 1.5; the ends' secants 10 ... 17 % apart, compressed on a drawn side); under plucks
  of a spring-mass with dry friction (the ring-down of Coulomb damping: the amplitude falling linearly by 4 Delta a
  cycle, Delta 5 ... 8 % of the peak, 1.5 ... 2.5 Hz, the mass sticking off centre wherever it stops, and pulled from
  there to the next pluck, 7 ... 9 plucks of 0.55 ... 1 of +-44 ... 48 V on either side), with a noisy input monitor,
  sampled at 1.01 kHz;
- saturation of the sensor's MOS differential pair (the square law's (I1 - I2) / I_ss = u sqrt(2 - u^2): linear, then
  bending ever faster to a hard limit at u = 1; the ends at u 0.66 ... 0.85, compressed by 12 ... 20 %); under the
  sine-with-dwell tests of electronic stability control (FMVSS 126: a 0.7 Hz sine with its second peak held 0.5 s, a
  counter-clockwise series and a clockwise one, the amplitude stepped up 6 times to +-44 ... 48 V; played 1.2 ... 1.5
  times faster; 0.6 ... 1.2 s at 0 V between), sampled at 735 Hz;
- a delay of a voltage-to-frequency converter counted over gates of one sample, each read 1 ... 3.4 samples after it
  closed (a delay of 1.6 ... 3.9 samples and a one-sample moving average), the core computed on an 8x finer grid;
  under a discrete-multitone (ADSL-like) frame (5 ... 7 tones k / T_u, T_u 1.1 ... 1.5 s, QPSK data, a cyclic prefix
  of T_u / 8 ... T_u / 4, raised-cosine transmit windows of 60 ... 100 ms within the prefixes, 16 ... 22 symbols),
  faded in and out, +-44 ... 48 V, with a noisy input monitor, sampled at 470 Hz;
- a core left by a homing routine (from the virgin state at 0 V: a fast seek to the upper limit switch at 80 ... 88 V,
  stopping 1.5 ... 3 V beyond it, a back-off of 4 ... 8 V, a slow re-approach stopping 0.2 ... 0.6 V beyond, a move
  to the index mark at 5 ... 14 V and on to the park at 28 ... 40 V), the record starting there; then an electronic
  pipette's multi-dispense programme (aspirations to the plunger's home at 2 ... 4 V, aliquots stepped to the first
  stop, blow-outs beyond it and returns; the volume set first at 0.55 ... 0.75 of the switch, then higher, the last two
  blow-outs to 93 ... 98 V beyond the history's top, late in the record), on a unipolar stroke, sampled at 810 Hz;
- two effects: asymmetry of a photodiode facing an LED carried by the stage (the inverse-square law, the stage's
  largest travel 3.3 ... 5.7 % of the distance: convex, the ends' secants 10 ... 17 % apart, on a drawn side) and a gain
  drift of the same LED as its junction heats after it was switched on 0.2 ... 0.8 s before the record (a two-stage
  Foster network, the die 0.05 ... 0.25 s and the package 3 ... 8 s; the light 4 ... 7 % lower at the end); under a
  car's engine speed through the gears (cranked to idle; two runs: a launch with the clutch slipping, the gears at full
  throttle against the quadratic drag, to 3rd, then to 4th, changes up at 4,500 ... 6,000 rpm, braking with changes
  down and throttle blips, idling between; the engine stopped at the end), played 2 ... 2.6 times faster, the top rpm
  at 88 ... 97 V, on a unipolar stroke, sampled at 1.17 kHz;
- out of vocabulary: a slender push rod between the stage and its load whose lateral mode is excited parametrically:
  the core's output sets the rod's axial load (0.35 ... 0.5 of its Euler load at the centre of the stroke, swinging by
  0.5 ... 0.65 of what is left), a Mathieu-Duffing equation (Bolotin 1964) with damping 1.5 ... 3 % and an initial
  crookedness that the load amplifies; the sensor reads the rod's tip at an angle, seeing its lateral deflection (4 ...
  7 % of the span at its largest) beside the stage's travel. Under Taps (24 notes of a bugle, as remembered: the 3rd to
  6th harmonics of a fundamental, a beat of 0.9 ... 1.2 s, the held C's 3 and 5 beats long), +-44 ... 48 V, sampled
  at 410 Hz; the C (the 4th harmonic, an exact number of samples a period) at twice the rod's lateral frequency (within
  +-2 %). On every held C the rod's deflection grows and settles at half the note's frequency: the output repeats
  every two of the input's periods, not every one, while the input itself repeats every period; on the other notes it
  stays at the crookedness's small forced response. A PI core (any plays with non-negative weights and any linear part)
  draws the same output for the same input from the same state, so a periodic input gives, from its second period
  on, an output of the same period; saturation and asymmetry are maps of it; rate dependence and delay are stable
  causal filters of it (a periodic input gives an output of its period); creep and drift and gain drift are slow and
  cannot flip sign every period; an initial state is forgotten after the first period.
"""

import math

import numpy as np
from scipy.optimize import brentq

from . import mechanisms23 as m23
from . import signals23 as s23
from .record import case_set, finish

HOLDOUT23, case, _rng = case_set("holdout23_", 23000)


def _both_sides(v, frac):
    """True when the path reaches beyond frac of its largest magnitude on both sides."""
    return min(v.max(), -v.min()) > frac * np.abs(v).max()


def _core(rng, v, r_max=45.0, n=80):
    """The other cases' core: n exponentially weighted plays to r_max, a drawn linear part and gain."""
    w0 = rng.uniform(0.3, 0.45)
    r, weights = m23.exp_plays(n, r_max, rng.uniform(8.0, 16.0), w0)
    gain = rng.uniform(0.7, 1.4)
    return gain * m23.plays(v, r, weights, w0), dict(thresholds=r, weights=weights, linear=w0, gain=gain)


# ---- clean ----

@case
def clean_nakagami_plays_rikitake_dynamo_1580hz(seed):
    rng = _rng(seed, 1)
    dt = 1 / 1580
    n = int(rng.uniform(13.0, 18.0) / dt)
    t = np.arange(n) * dt
    units, mu, a = rng.uniform(4.0, 6.0), 2.0, 5.0
    fade = m23.raised_cosine(t / 1.0)
    for _ in range(30):
        start = tuple(rng.uniform(-1.0, 1.0, 3))
        x, s0 = s23.rikitake_x(t, units, start, mu, a)
        xc = x - (x.max() + x.min()) / 2
        if _both_sides(fade * xc, 0.85) and np.sum(np.diff(np.sign(xc)) != 0) >= 6:
            break
    amp = rng.uniform(44.0, 48.0)
    scale = amp / np.abs(fade * xc).max()
    v = scale * fade * xc
    r_max, m, spread = rng.uniform(40.0, 46.0), rng.uniform(1.2, 2.5), rng.uniform(9.0, 16.0)
    w0 = rng.uniform(0.25, 0.4)
    r, weights = m23.nakagami_plays(100, r_max, m, spread, w0)
    gain, off = rng.uniform(0.7, 1.4), rng.uniform(-4.0, 4.0)
    y = gain * m23.plays(v, r, weights, w0) + off
    rec = finish("holdout23_clean_nakagami_plays_rikitake_dynamo_1580hz", seed, t, v, y, set(), "explained",
                 f"a clean core (100 plays, a Nakagami density of thresholds, m {m:.2f}, spread {spread:.1f} V, on "
                 f"0 ... {r_max:.0f} V) under the current of Rikitake's dynamo ({units:.1f} units a second), faded in "
                 f"from 0 V, +-{amp:.0f} V, 1.58 kHz", rng, monitor_noise=3e-4)
    rec.extra.update(thresholds=r, weights=gain * weights, linear=gain * w0, offset=off, r_max=r_max, m=m,
                     spread=spread, units=units, mu=mu, a=a, start=start, s0=s0, x=x, xc=xc, scale=scale, amp=amp,
                     drive=v)
    return rec


# ---- one effect ----

@case
def creep_fuoss_kirkwood_spring_lever_espresso_275hz(seed):
    rng = _rng(seed, 2)
    dt = 1 / 275
    top = rng.uniform(88.0, 97.0)
    ramp = rng.uniform(0.3, 0.45)
    shots, tc = [], rng.uniform(1.0, 2.0)
    ratio = rng.uniform(0.45, 0.6)
    cut_at = int(rng.integers(1, 4))
    for k in range(4):
        tau_l = rng.uniform(5.0, 14.0)
        cut = rng.uniform(0.45, 0.65) if k == cut_at else 1.0
        shot = (tc, rng.uniform(0.1, 0.15) * top, rng.uniform(2.0, 4.0), top, tau_l, ratio * top, cut)
        shots.append(shot)
        tc += shot[2] + 2 * ramp + cut * tau_l * math.log(1 / ratio) + rng.uniform(3.0, 6.0)
    n = int(tc / dt)
    t = np.arange(n) * dt
    v, times = s23.lever_shots(t, shots, ramp)
    h, core = _core(rng, v)
    c, tau0, beta = rng.uniform(0.05, 0.08), rng.uniform(0.5, 3.0), rng.uniform(0.45, 0.75)
    cr = m23.fk_creep(h, dt, c, tau0, beta, 10.0)
    rec = finish("holdout23_creep_fuoss_kirkwood_spring_lever_espresso_275hz", seed, t, v, h + cr, {"creep"},
                 "either", f"creep with the Fuoss-Kirkwood spectrum ({c:.1%} after 10 s, tau0 {tau0:.2f} s, beta "
                 f"{beta:.2f}) under 4 shots of a spring-lever espresso machine to {top:.0f} V, 275 Hz", rng)
    rec.extra.update(core, top=top, ramp=ramp, shots=shots, times=times, ratio=ratio, h=h, c=c, tau0=tau0, beta=beta,
                     creep=cr)
    return rec


#: shuttles per level of the 20-m multistage shuttle run, levels 1 ... 12 (as remembered)
SHUTTLES = [7, 8, 8, 9, 9, 10, 10, 11, 11, 11, 12, 12]


@case
def rate_shear_thinning_damper_beep_test_1480hz(seed):
    rng = _rng(seed, 3)
    dt = 1 / 1480
    kc, amp, acc = rng.uniform(28.0, 36.0), rng.uniform(44.0, 48.0), rng.uniform(2.5, 4.0)
    last = int(rng.integers(8, 12))
    jog = rng.uniform(6.0, 7.0)
    speeds = [4.0] + [jog, jog]                         # a walk to the line, a warm-up jog there and back
    for level in range(1, last + 1):
        speeds += [8.5 if level == 1 else 8.0 + 0.5 * level] * SHUTTLES[level - 1]
    walk = rng.uniform(4.5, 5.5)
    speeds += [walk, walk]
    rest = {2: rng.uniform(2.0, 4.0)}                   # a pause at the line before level 1
    legs, end = s23.shuttle_legs(speeds, 10.0, rng.uniform(0.5, 1.0) * kc, acc, rest)
    # the walk back ends at a line; then a walk to the middle
    x_end = legs[-1][3]
    D = 10.0
    T = D / (walk / 3.6)
    legs.append((end + rng.uniform(1.0, 2.0) * kc, T, x_end, 10.0))
    end = legs[-1][0] + T
    n = int((end + 0.5 * kc) / kc / dt)
    t = np.arange(n) * dt
    x = s23.shuttle_run(t * kc, legs, acc, 10.0)
    v = amp * (x / 10.0 - 1.0)
    h, core = _core(rng, v)
    fastest = np.abs(np.diff(h)).max() / dt
    n_exp = rng.uniform(0.4, 0.6)
    e_f = rng.uniform(0.025, 0.04) * np.ptp(h)
    y = m23.shear_thinning_stage(h, dt, fastest, e_f, n_exp)
    rec = finish("holdout23_rate_shear_thinning_damper_beep_test_1480hz", seed, t, v, y, {"rate_dependence"},
                 "either", f"a shear-thinning damper (n {n_exp:.2f}, a lag of {e_f / np.ptp(h):.1%} of the span at the "
                 f"fastest) under the 20-m shuttle run to level {last}, played {kc:.0f} times faster, +-{amp:.0f} V, "
                 f"1.48 kHz", rng, monitor_noise=2.5e-4)
    rec.extra.update(core, kc=kc, amp=amp, acc=acc, last=last, speeds=speeds, legs=legs, h=h, fastest=fastest,
                     n_exp=n_exp, e_f=e_f, drive=v)
    return rec


@case
def drift_ground_loop_pump_motor_bicycle_pedal_560hz(seed):
    rng = _rng(seed, 4)
    dt = 1 / 560
    c1, c2 = rng.uniform(1.1, 1.4), rng.uniform(1.7, 2.0)
    tc = rng.uniform(0.5, 1.0)
    knots = [(tc, 0.0)]

    def knot(dur, c):
        nonlocal tc
        tc += dur
        knots.append((tc, c))
    knot(rng.uniform(1.5, 2.5), c1)                   # the start
    knot(rng.uniform(4.0, 6.0), c1)
    knot(rng.uniform(1.0, 1.5), c2)                   # a sprint
    knot(rng.uniform(3.0, 4.0), c2)
    knot(rng.uniform(0.6, 1.0), 0.0)                  # freewheeling: the crank stops where it is
    knot(rng.uniform(1.5, 3.0), 0.0)
    knot(rng.uniform(1.0, 2.0), c1 * rng.uniform(0.9, 1.1))
    knot(rng.uniform(5.0, 7.0), c1)
    knot(rng.uniform(0.5, 0.8), 0.0)
    knot(rng.uniform(1.5, 2.5), 0.0)
    knot(rng.uniform(1.0, 1.5), c2 * rng.uniform(0.95, 1.05))
    knot(rng.uniform(4.0, 6.0), c2)
    knot(rng.uniform(1.5, 2.5), 0.0)
    n = int((tc + rng.uniform(0.5, 1.0)) / dt)
    t = np.arange(n) * dt
    amp = rng.uniform(44.0, 48.0)
    theta = s23.pedal_angle(t, knots)
    v = amp * np.sin(theta)
    h, core = _core(rng, v, r_max=42.0)
    T = t[-1]
    tau_m, ratio, tau_f = rng.uniform(0.3, 0.9), rng.uniform(4.0, 7.0), rng.uniform(0.005, 0.02)
    on1 = rng.uniform(0.1, 0.2) * T
    off1 = on1 + rng.uniform(4.0, 7.0)
    on2 = off1 + rng.uniform(1.0, 2.5)                # restarted while it still coasts: a smaller inrush
    off2 = on2 + rng.uniform(3.0, 5.0)
    on3 = off2 + rng.uniform(3.0, 5.0)
    off3 = min(on3 + rng.uniform(4.0, 6.0), T - 1.0)
    runs = [(on1, off1), (on2, off2), (on3, off3)]
    raw = m23.motor_ground_offset(t, runs, tau_m, ratio, tau_f)
    frac, sign = rng.uniform(0.04, 0.08), rng.choice([-1.0, 1.0])
    scale_off = sign * frac * np.ptp(h) / np.abs(raw).max()
    off = scale_off * raw
    rec = finish("holdout23_drift_ground_loop_pump_motor_bicycle_pedal_560hz", seed, t, v, h + off, {"drift"},
                 "either", f"a ground loop's offset of {sign * frac:+.1%} of the span at its largest (a pump motor "
                 f"started 3 times, inrush {ratio:.1f}x, tau {tau_m:.2f} s) under a cyclist's pedal ({c1:.2f} and "
                 f"{c2:.2f} rev/s), +-{amp:.0f} V, 560 Hz", rng)
    rec.extra.update(core, knots=knots, amp=amp, h=h, runs=runs, tau_m=tau_m, ratio=ratio, tau_f=tau_f, frac=frac,
                     sign=sign, scale_off=scale_off, offset=off)
    return rec


@case
def asymmetry_hot_wire_king_law_coulomb_plucks_1010hz(seed):
    rng = _rng(seed, 5)
    dt = 1 / 1010
    f = rng.uniform(1.5, 2.5)
    w = 2 * np.pi * f
    amp = rng.uniform(44.0, 48.0)
    Delta = rng.uniform(0.05, 0.08) * amp
    pull, hold = rng.uniform(0.3, 0.5), rng.uniform(0.15, 0.3)
    n_pl = int(rng.integers(7, 10))
    sizes = rng.uniform(0.55, 1.0, n_pl)
    sizes[int(rng.integers(0, n_pl))] = 1.0
    signs = rng.choice([-1.0, 1.0], n_pl)
    signs[:2] = [1.0, -1.0]
    pl, tc = [], rng.uniform(0.5, 1.0)
    for sz, sg in zip(sizes, signs):
        X0 = sg * sz * amp
        pl.append((tc, X0))
        ring = (abs(X0) / (2 * Delta) + 1) * math.pi / w      # the half cycles until it sticks
        tc += pull + hold + ring + rng.uniform(0.3, 0.8)
    n = int(tc / dt)
    t = np.arange(n) * dt
    v, rests = s23.plucks(t, pl, w, Delta, pull, hold)
    w0 = rng.uniform(0.3, 0.45)
    r, weights = m23.exp_plays(80, 42.0, rng.uniform(8.0, 16.0), w0)
    x_core = m23.plays(v, r, weights, w0)
    c = (x_core.max() + x_core.min()) / 2
    X = np.abs(x_core - c).max()
    asym, side = rng.uniform(0.10, 0.17), rng.choice([-1.0, 1.0])
    lam, n_k = rng.uniform(0.5, 1.5), rng.uniform(0.4, 0.5)

    def spread(a):
        return float(-m23.king_reading(-1.0, a, lam, n_k) - m23.king_reading(1.0, a, lam, n_k)) - asym
    a = brentq(spread, 1e-3, 0.95, xtol=1e-15)
    gain = rng.uniform(0.7, 1.4)
    y = gain * (c + side * X * m23.king_reading(side * (x_core - c) / X, a, lam, n_k))
    rec = finish("holdout23_asymmetry_hot_wire_king_law_coulomb_plucks_1010hz", seed, t, v, y, {"asymmetry"},
                 "either", f"a hot-wire anemometer by King's law (n {n_k:.2f}, A / B U0^n {lam:.2f}, the flow "
                 f"+-{a:.0%}; the ends' secants {asym:.0%} apart, compressed {'up' if side > 0 else 'down'}) under "
                 f"{n_pl} plucks of a {f:.2f} Hz oscillator with dry friction, +-{amp:.0f} V, 1.01 kHz", rng,
                 monitor_noise=3e-4)
    rec.extra.update(plucks=pl, rests=rests, w=w, Delta=Delta, pull=pull, hold=hold, amp=amp, thresholds=r,
                     weights=weights, linear=w0, core=x_core, centre=c, X=X, asym=asym, side=side, lam=lam, n_k=n_k,
                     a=a, gain=gain, drive=v)
    return rec


@case
def saturation_mos_differential_pair_sine_with_dwell_735hz(seed):
    rng = _rng(seed, 6)
    dt = 1 / 735
    kc = rng.uniform(1.2, 1.5)
    f, dwell = 0.7 * kc, 0.5 / kc
    amp = rng.uniform(44.0, 48.0)
    steps = np.array([1.5, 2.5, 3.5, 4.5, 5.5, 6.5])
    man, tc = [], rng.uniform(0.6, 1.2)
    for sg in (1.0, -1.0):                              # counter-clockwise, then clockwise
        for k in steps:
            man.append((tc, amp * k / steps[-1], sg))
            tc += 1 / f + dwell + rng.uniform(0.6, 1.2)
        tc += rng.uniform(0.5, 1.5)
    n = int(tc / dt)
    t = np.arange(n) * dt
    v = s23.sine_with_dwell(t, man, f, dwell)
    h, core = _core(rng, v, r_max=42.0)
    c = (h.max() + h.min()) / 2
    X = np.abs(h - c).max()
    comp = rng.uniform(0.12, 0.2)
    u_end = math.sqrt(2 * (1 - (1 - comp) ** 2))
    F = X / u_end
    y = m23.mos_reading(h, c, F)
    rec = finish("holdout23_saturation_mos_differential_pair_sine_with_dwell_735hz", seed, t, v, y, {"saturation"},
                 "either", f"a MOS differential pair (the ends at u {u_end:.2f}, compressed by {comp:.0%}) under 12 "
                 f"sine-with-dwell manoeuvres played {kc:.2f} times faster, +-{amp:.0f} V, 735 Hz", rng)
    rec.extra.update(core, kc=kc, f=f, dwell=dwell, amp=amp, manoeuvres=man, h=h, centre=c, X=X, comp=comp,
                     u_end=u_end, F=F)
    return rec


@case
def delay_vfc_counter_gate_dmt_symbols_470hz(seed):
    rng = _rng(seed, 7)
    dt, sub = 1 / 470, 8
    T_u = rng.uniform(1.1, 1.5)
    T_cp = T_u / rng.uniform(4.0, 8.0)               # longer than the window: 0.14 ... 0.38 s
    n_t = int(rng.integers(5, 8))
    k0 = int(rng.integers(1, 3))
    ks = list(range(k0, k0 + n_t))
    n_sym = int(rng.integers(16, 23))
    qpsk = np.array([1 + 1j, 1 - 1j, -1 + 1j, -1 - 1j]) / math.sqrt(2)
    symbols = [qpsk[rng.integers(0, 4, n_t)] for _ in range(n_sym)]
    t0, w_tx, fade = rng.uniform(0.5, 1.0), rng.uniform(0.06, 0.1), 0.6
    end = t0 + n_sym * (T_u + T_cp)
    n = int((end + 0.5) / dt)
    tf = np.arange((n - 1) * sub + 1) * (dt / sub)
    x, _ = s23.dmt_frame(tf, t0, T_u, T_cp, ks, symbols, w_tx, fade)
    amp = rng.uniform(44.0, 48.0)
    scale = amp / np.abs(x).max()
    v_f = scale * x
    v = v_f[::sub]
    t = tf[::sub]
    h_f, core = _core(rng, v_f, r_max=42.0)
    L = int(rng.integers(1, 4))
    phase = rng.uniform(0.1, 0.4) if L == 3 else rng.uniform(0.1, 0.9)
    lag = L + phase
    y = m23.vfc_counter(t, tf, h_f, lag, dt)
    rec = finish("holdout23_delay_vfc_counter_gate_dmt_symbols_470hz", seed, t, v, y, {"delay"}, "either",
                 f"a VFC counted over one-sample gates read {lag:.2f} samples after they close (a delay of "
                 f"{lag + 0.5:.2f} samples) under a DMT frame of {n_sym} symbols on {n_t} tones (T_u {T_u:.2f} s), "
                 f"+-{amp:.0f} V, 470 Hz", rng, monitor_noise=2e-4)
    rec.extra.update(core, T_u=T_u, T_cp=T_cp, ks=ks, symbols=symbols, t0=t0, w_tx=w_tx, fade=fade, scale=scale,
                     amp=amp, sub=sub, L=L, phase=phase, lag=lag, drive=v)
    return rec


@case
def initial_state_homing_routine_pipette_dispensing_810hz(seed):
    rng = _rng(seed, 8)
    dt = 1 / 810
    w0 = rng.uniform(0.3, 0.45)
    r, weights = m23.exp_plays(80, 40.0, rng.uniform(10.0, 16.0), w0)
    top, over_fast, back, over_slow = rng.uniform(80.0, 88.0), rng.uniform(1.5, 3.0), rng.uniform(4.0, 8.0), \
        rng.uniform(0.2, 0.6)
    index, park = rng.uniform(5.0, 14.0), rng.uniform(28.0, 40.0)
    hist = s23.homing_history(top, over_fast, back, over_slow, index, park)
    _, z0 = m23.plays(hist, r, weights, w0, return_state=True)
    home = rng.uniform(2.0, 4.0)
    mv, tc = [], rng.uniform(0.6, 1.0)

    def go(to, T, dwell):
        nonlocal tc
        mv.append((tc, T, to))
        tc += T + dwell
    # programmes: (first stop, aliquots, blow-out beyond the first stop)
    stops = [rng.uniform(0.55, 0.75) * top, rng.uniform(0.55, 0.75) * top, rng.uniform(0.75, 0.85) * top,
             rng.uniform(0.85, 0.9) * top, rng.uniform(0.86, 0.9) * top]
    blow = [rng.uniform(4.0, 8.0), rng.uniform(4.0, 8.0), rng.uniform(4.0, 8.0), None, None]
    last_blow = [rng.uniform(93.0, 98.0), rng.uniform(93.0, 98.0)]
    for j, (stop, b) in enumerate(zip(stops, blow)):
        n_al = int(rng.integers(3, 7))
        go(stop, rng.uniform(0.4, 0.6), rng.uniform(0.3, 0.5))            # to the first stop, the tip immersed
        go(home, rng.uniform(0.5, 0.8), rng.uniform(0.3, 0.6))            # aspirate
        for i in range(1, n_al + 1):                                      # the aliquots
            go(home + (stop - home) * i / n_al, rng.uniform(0.15, 0.3), rng.uniform(0.35, 0.7))
        go(stop + b if b is not None else last_blow[j - 3], rng.uniform(0.2, 0.35), rng.uniform(0.2, 0.4))
        go(home, rng.uniform(0.4, 0.6), rng.uniform(0.6, 1.2))
    n = int(tc / dt)
    t = np.arange(n) * dt
    v = s23.moves(t, mv, park)
    gain = rng.uniform(0.7, 1.4)
    y = gain * m23.plays(v, r, weights, w0, state=z0)
    rec = finish("holdout23_initial_state_homing_routine_pipette_dispensing_810hz", seed, t, v, y, {"initial_state"},
                 "either", f"a core left by a homing routine (the switch at {top:.0f} V, backed off {back:.1f} V, the "
                 f"index at {index:.1f} V, parked at {park:.1f} V; the record starting there), then a pipette's "
                 f"5 multi-dispense programmes, blowing out to {max(last_blow):.0f} V at last, 810 Hz", rng)
    rec.extra.update(thresholds=r, weights=weights, linear=w0, gain=gain, history=hist, state=z0, top=top,
                     over_fast=over_fast, back=back, over_slow=over_slow, index=index, park=park, home=home, moves=mv,
                     stops=stops, last_blow=last_blow)
    return rec


# ---- two effects ----

@case
def pair_asymmetry_gain_drift_led_inverse_square_junction_heating_gear_shifts_1170hz(seed):
    rng = _rng(seed, 9)
    dt = 1 / 1170
    kc = rng.uniform(2.0, 2.6)                          # played faster than the car
    r1 = rng.uniform(420.0, 480.0)                      # first gear: engine rpm per m/s of road speed
    ratios = r1 * np.array([1.0, 0.56, 0.39, 0.3, 0.24]) * rng.uniform(0.97, 1.03, 5)
    ratios = np.sort(ratios)[::-1]
    A1, B = rng.uniform(3.5, 4.5), rng.uniform(2.5e-4, 3.5e-4)
    idle, launch = rng.uniform(750.0, 900.0), rng.uniform(1600.0, 2200.0)
    runs = [(3, rng.uniform(4500.0, 5200.0)), (4, rng.uniform(5500.0, 6000.0))]
    cycle = dict(down=rng.uniform(1500.0, 1900.0), T_shift=rng.uniform(0.3, 0.5), decel=rng.uniform(4.0, 6.0),
                 lead=rng.uniform(0.3, 0.6), runs=runs, idle_hold=rng.uniform(1.0, 2.0), crank=rng.uniform(0.6, 1.0))
    at, end, pieces = s23.drive_cycle(ratios, A1, B, idle, launch, **cycle)
    n = int((end + 0.5 * kc) / kc / dt)
    t = np.arange(n) * dt
    rpm, vel = at(t * kc)
    top_v = rng.uniform(88.0, 97.0)
    rpm_scale = top_v / rpm.max()
    v = rpm_scale * rpm
    h, core = _core(rng, v)
    c = (h.max() + h.min()) / 2
    X = np.abs(h - c).max()
    asym, side = rng.uniform(0.10, 0.17), rng.choice([-1.0, 1.0])

    def spread(xi):
        return float(m23.inverse_square_reading(1.0, xi) + m23.inverse_square_reading(-1.0, xi)) - asym
    xi = brentq(spread, 1e-4, 0.3, xtol=1e-15)
    y_asym = c + side * X * m23.inverse_square_reading(side * (h - c) / X, xi)
    t_on = -rng.uniform(0.2, 0.8)
    tau1, tau2 = rng.uniform(0.05, 0.25), rng.uniform(3.0, 8.0)
    share = rng.uniform(0.3, 0.5)                       # the die's share of the heating
    droop = rng.uniform(0.04, 0.07)                     # the light lost by the end, from the record's start
    T_k = 1.0

    def lost(R):
        g = m23.junction_droop(np.array([0.0, t[-1]]), t_on, share * R, tau1, (1 - share) * R, tau2, T_k)
        return 1 - g[1] / g[0] - droop
    R = brentq(lost, 1e-6, 5.0, xtol=1e-15)
    g = m23.junction_droop(t, t_on, share * R, tau1, (1 - share) * R, tau2, T_k)
    g = g / g[0]
    y = g * y_asym
    rec = finish("holdout23_pair_asymmetry_gain_drift_led_inverse_square_junction_heating_gear_shifts_1170hz", seed,
                 t, v, y, {"asymmetry", "gain_drift"}, "either",
                 f"an LED's inverse-square light (the travel {xi:.1%} of the distance, the ends' secants {asym:.0%} "
                 f"apart) and its junction heating ({droop:.1%} less light by the end; die {tau1:.2f} s, package "
                 f"{tau2:.1f} s) under a car's engine speed through the gears, played {kc:.1f} times faster, to "
                 f"{top_v:.0f} V, 1.17 kHz", rng)
    rec.extra.update(core, kc=kc, ratios=ratios, A1=A1, B=B, idle=idle, launch=launch, runs=runs, cycle=cycle,
                     pieces=pieces,
                     rpm_scale=rpm_scale, top_v=top_v, h=h, centre=c, X=X, asym=asym, side=side, xi=xi,
                     y_asym=y_asym, t_on=t_on, tau1=tau1, tau2=tau2, share=share, droop=droop, R=R, T_k=T_k, g=g,
                     vel=vel)
    return rec


# ---- out of vocabulary ----

@case
def oov_parametric_column_taps_bugle_410hz(seed):
    rng = _rng(seed, 10)
    dt, sub = 1 / 410, 4
    N_C = int(rng.integers(48, 60))                    # samples per period of the C (the 4th harmonic)
    f_C = 1 / (N_C * dt)
    f_b = f_C / 4
    beat, ramp = rng.uniform(0.9, 1.2), rng.uniform(0.03, 0.05)
    amp = rng.uniform(44.0, 48.0)
    notes, tc = [], rng.uniform(0.6, 1.0)
    for k, b in s23.TAPS:
        T = b * beat - 0.06
        notes.append((tc, T, k, amp * (1.0 if k == 4 and b >= 3 else rng.uniform(0.75, 1.0))))
        tc += b * beat
    n = int((tc + 0.8) / dt)
    tf = np.arange((n - 1) * sub + 1) * (dt / sub)
    v_f = s23.bugle(tf, notes, f_b, ramp)
    v = v_f[::sub]
    t = tf[::sub]
    h_f, core = _core(rng, v_f)
    hc = (h_f.max() + h_f.min()) / 2
    p0, eps, zeta = rng.uniform(0.35, 0.5), rng.uniform(0.5, 0.65), rng.uniform(0.015, 0.03)
    kappa = eps * (1 - p0) / np.abs(h_f - hc).max()
    p_f = p0 + kappa * (h_f - hc)
    w_m = 2 * np.pi * f_C / 2 * (1 + rng.uniform(-0.02, 0.02))
    w0 = w_m / math.sqrt(1 - p0)
    gamma, delta0 = 1.0, rng.uniform(0.02, 0.04)
    q_f = m23.column_lateral(p_f, dt / sub, w0, zeta, gamma, delta0)
    frac = rng.uniform(0.04, 0.07)
    b = frac * np.ptp(h_f) / np.abs(q_f).max()
    y = (h_f + b * q_f)[::sub]
    rec = finish("holdout23_oov_parametric_column_taps_bugle_410hz", seed, t, v, y, set(), "unexplained",
                 f"a push rod's lateral mode excited parametrically (load {p0:.2f} +- {eps:.2f} of what is left, zeta "
                 f"{zeta:.3f}, its frequency {w_m / 2 / np.pi:.2f} Hz; the deflection {frac:.1%} of the span) under "
                 f"Taps on a bugle (C at {f_C:.2f} Hz), +-{amp:.0f} V, 410 Hz", rng)
    rec.extra.update(core, N_C=N_C, f_C=f_C, f_b=f_b, beat=beat, ramp=ramp, amp=amp, notes=notes, sub=sub, hc=hc,
                     p0=p0, eps=eps, zeta=zeta, kappa=kappa, w_m=w_m, w0=w0, gamma=gamma, delta0=delta0, b=b,
                     frac=frac, q=q_f[::sub])
    return rec

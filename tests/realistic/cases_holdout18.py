"""The HOLDOUT18 set: written after HOLDOUT17 was measured, by a session that did not read how the diagnosis decides,
to be run once for the next round's measurement; kept out of ALL until then.

Mechanisms and signals that the other sets do not have, or not in these combinations (the laws and signals are in
:mod:`.mechanisms18`, each beside its source; its citations were written from memory, as it says):

- a clean core (100 plays from the play's definition with an inverse Gaussian (Wald) density of thresholds on 0 ... 40
  ... 46 V, mean 9 ... 16 V, shape 12 ... 35 V: the first-passage law of a drifting random walk, a hump with a heavy
  tail of wide plays; a drawn linear part, gain and offset) under the tip of Moon and Holmes's magnetoelastic beam (a
  cantilever buckled by two magnets into two wells, forced sideways: x'' + delta x' - x + x^3 = gamma cos(omega t),
  delta 0.2 ... 0.3, gamma 0.3 ... 0.42, the forcing at 0.8 ... 1.3 Hz: chaos, the tip jumping between the wells 6 times
  or more at irregular times and ringing inside them; Moon & Holmes 1979), faded in from rest at 0 V over 1 s to peaks
  of +-44 ... 48 V, with a noisy input monitor, sampled at 1.79 kHz;
- creep of units hopping between two sites biased by the load (Nowick & Berry's nonlinear anelasticity: the creep
  relaxes toward c h_s tanh(h / h_s) at the rate cosh(h / h_s) / tau0; c 6 ... 10 % of the core's output for small
  loads, tau0 0.5 ... 1.5 s, h_s 0.4 ... 0.8 of the core's largest output, so that at the top the creep heads for 0.39
  ... 0.68 of the linear law's amount 1.9 ... 6.1 times as fast); under a heliograph keyed in Morse (4 or 5 random words
  of 2 ... 4 letters in ITU timing: dots of one unit, dashes of three, gaps of 1, 3 and 7 units, a unit of 0.3 ... 0.45
  s; each letter keyed to its own level, 0.5 ... 1 of the top, 88 ... 97 V, one letter at the top; shaped edges of 40
  ... 80 ms), on a unipolar stroke from 0 V, sampled at 215 Hz;
- rate dependence of a heavy stage resonating at 34 ... 46 Hz (zeta 0.02 ... 0.05) with a tuned mass damper (a mass
  ratio of 0.05 ... 0.15, Den Hartog's optimal tuning; Den Hartog 1956), the stage at the core's free stroke when at
  rest: the fast tones come out up to 7 ... 12 % of the span off the quasi-static core, the slow ones less; under a
  telephone call in DTMF (a dial tone of 350 + 440 Hz for 1.5 ... 2.2 s, a ten-digit number as the keypad's pairs of 697
  ... 941 Hz and 1209 ... 1477 Hz, 0.45 ... 0.7 s each with pauses of 0.25 ... 0.45 s, two ring-backs of 440 + 480 Hz of
  1.2 ... 1.6 s; ITU-T Q.23), every frequency divided by 140 ... 175 (2.0 ... 10.5 Hz), ramps of 30 ... 50 ms, +-44 ...
  48 V, with a noisy input monitor, sampled at 1.515 kHz;
- an offset drift from the sag of a gantry's bridge under its cross carriage (another axis, not recorded: a simply
  supported beam, the sensor's mount at 0.3 ... 0.7 of the span, its deflection under the carriage the influence line of
  Maxwell's reciprocity; Timoshenko & Gere 1972): the carriage makes 3 ... 5 raised-cosine moves of 1.5 ... 3 s between
  stations at least a quarter span apart, one in each of equal slots of the record, so the offset stays flat while it
  stands and moves smoothly with it, 4 ... 8 % of the span at most (either sign); under 3 or 4 passes up and down a
  devil's staircase (the Cantor function at level 3 ... 5: 2^level steep rises between flats of a third, a ninth ... of
  the pass; Cantor 1884), to tops of 0.65 ... 1 of 88 ... 97 V in 5 ... 7.5 s each way, on a unipolar stroke from 0 V,
  sampled at 605 Hz;
- asymmetry of a slider-crank read on its crank (the core's output moves the slider of an in-line slider-crank whose
  crank stands at right angles at rest, the crank's angle read by an encoder: sin psi = u (u + 2 c0) / (2 r (u + c0)),
  the rod 1.4 ... 2.2 cranks long; Norton 2004): the rod's obliquity stretches one end of the stroke and compresses the
  other, the ends' slopes 10 ... 17 % apart (monotone, the crank turning 7 ... 17 deg for seeds 0 ... 2); under 26 ...
  33 set points drawn by the logistic map (rho 3.9 ... 3.99, a chaotic orbit; May 1976), scaled to +-44 ... 48 V,
  reached by raised-cosine moves at 150 ... 300 V/s and held 0.1 ... 0.35 s, from and back to 0 V, with a noisy input
  monitor, sampled at 1.16 kHz;
- saturation of a stage on a flexure between two fixed magnets that repel the magnet it carries (coaxial dipoles, the
  repulsion falling as the fourth power of the distance: the restoring force u + (m / 8) ((1 - u)^-4 - (1 + u)^-4) of
  the displacement over the gap, the magnets 0.3 ... 1 times as stiff as the flexure at rest; Yonnet 1981): stiffening,
  odd, the ends 0.2 ... 0.35 of the gap out and compressed by 10 ... 17 %; under the suspension travel of Sayers's
  golden car (the International Roughness Index's quarter car: the body at 1.24 Hz, the wheel hop at 10.8 Hz) on a road
  of ISO 8608's n^-2 spectrum (200 cosines of random phase from 0.011 to 2.83 cycles per metre) at a speed rising from
  10 ... 16 to 24 ... 32 m/s, faded in over 1.5 s, +-44 ... 48 V, sampled at 745 Hz;
- a delay of a fibre Bragg grating read by a swept-laser interrogator (one sweep of the band per sample; the grating's
  wavelength, linear in the stage's position, found where the sweep passes it, between 0.1 ... 0.35 and 0.35 ... 0.8 of
  the sweep, the reading delivered 2 or 3 sweeps later; Kersey et al. 1997): a delay of 1 + latency - p of 2.1 ... 3.9
  samples that itself depends on the reading, by 0.25 ... 0.45 sample, shorter for the readings late in the sweep; the
  core computed on an 8x finer grid; under random bytes in Manchester code (IEEE 802.3: each bit a transition, high then
  low for a 0; 3 ... 5 bit/s for 13 ... 20 s; each byte's level 0.5 ... 1 of +-44 ... 48 V, one byte at full;
  raised-cosine edges of 0.4 ... 0.7 of a half bit), with a noisy input monitor, sampled at 815 Hz;
- a core left by a fibre's alignment (from the virgin state at 0 V: a coarse scan up to 80 ... 86 V in 8 ... 12 steps
  scoring the coupled power, a Gaussian overlap of width 6 ... 12 output units at the stage's settled position; a return
  from the top to the best coarse point; then Rosenbrock's rule in one dimension (a trial step of 1.5 ... 3 V from the
  best point, kept and tripled up to 2 ... 3 times that when the power grows, else undone, halved and reversed, until
  under 0.05 ... 0.1 V; Rosenbrock 1960; 14 ... 23 trials for seeds 0 ... 2): the wide plays on the scan's descending
  branch, the narrow ones in the search's decaying zig-zag), the record starting where the search ended (36 ... 45 V for
  seeds 0 ... 2); then Lotka-Volterra prey cycles (g 0.6 ... 1.5, the equilibrium near the start, small cycles of 1.4
  ... 2 s; Lotka 1925, Volterra 1926), the predators culled three times at the same prey so that the orbits grow: two
  peaking below the scan's top, then at 0.85 ... 1 of and at 95 ... 99 V, which wipes the memory out (at 0.48 ... 0.6 of
  the record for seeds 0 ... 2), on a unipolar stroke, sampled at 905 Hz;
- two effects: saturation by two neo-Hookean rubber pads holding the stage between them (preloaded to a stretch of 0.8
  ... 0.9, each pad's stress lam - lam^-2; Treloar 1943: odd, stiffening as a pad is squeezed, the ends compressed by 10
  ... 16 %) and asymmetry of the nozzle-flapper air gauge reading the stage's gap (the back pressure 1 / (1 + (g /
  g_c)^2) by the flow balance of the supply orifice and the nozzle's curtain, the gap at rest 0.9 ... 1.15 g_c: the
  ends' slopes 10 ... 18 % apart); under the x of a ball in Bunimovich's stadium (caps of 0.6 ... 1 of the half
  straight, the ball at a constant speed of 3 ... 5 stadium half-lengths a second, reflected specularly: a chaotic
  billiard whose x reverses only on the caps, at 0.5 ... 1 of its largest extent; Bunimovich 1979), from rest at 0 V,
  +-44 ... 48 V, sampled at 1.325 kHz;
- out of vocabulary: a self-heated NTC thermistor bead (R25 10 ... 47 kOhm, B 3500 ... 4200 K, a dissipation constant of
  0.6 ... 1.2 mW/K and a thermal time constant of 0.4 ... 1 s) in series with a sense resistor of 0.6 ... 1 R25, whose
  voltage is the output, driven by the open-circuit EMF of a small permanent-magnet wind generator (k w sin(p theta), 4
  pole pairs, 1 ... 1.8 Hz at the rated speed; the rotor following the wind through 0.5 ... 1.5 s of inertia: a start-up
  over 3 ... 5 s, 2 or 3 extreme operating gusts of IEC 61400-1 of 4 ... 7 s and 0.25 ... 0.45 of the mean wind, a
  shut-down over 2.5 ... 4 s), +-44 ... 48 V, sampled at 455 Hz. The bead heats by 17 ... 29 K and its conductance, the
  output over the input, swings by 30 ... 39 % (seeds 0 ... 2) with the power the generator has lately put in: its loops
  are pinched (a thermal memristor: Chua & Kang 1976). The output vanishes with the input at every zero crossing,
  whatever came before, while between the zeros the same input meets outputs many noise levels apart; the lobes open at
  the slow electrical frequencies and close at the fast ones, and the conductance rises and falls within every half
  period (the heat goes as v^2) and with every gust. A PI core (any plays with non-negative weights and any linear part)
  has a remanence at v = 0 (its falling branch above its rising one) or, if no play moves, no loop at all; saturation,
  asymmetry and clipping are fixed maps of it; rate dependence (a lag or rate-dependent plays) and delay open the loops
  at v = 0 instead of closing them, and widen them with the rate; creep relaxes after the moves and leaves an output at
  v = 0 that depends on the history; an initial state is forgotten; drift and gain drift are slow functions of the time,
  where this gain would have to follow the input's own recent square, twice per electrical period. The best PI core with
  a linear part, an offset and gain and offset drifts leaves 12 ... 16 noise levels (seeds 0 ... 2).
"""

import math

import numpy as np
from scipy.optimize import brentq

from . import mechanisms18 as m18
from .record import case_set, finish

HOLDOUT18, case, _rng = case_set("holdout18_", 18000)


def _both_sides(v, frac):
    """True when the path reaches beyond frac of its largest magnitude on both sides."""
    return min(v.max(), -v.min()) > frac * np.abs(v).max()


# ---- clean ----

@case
def clean_wald_plays_magnetoelastic_beam_chaos_1790hz(seed):
    rng = _rng(seed, 1)
    dt = 1 / 1790
    n = int(rng.uniform(12.0, 20.0) / dt)
    t = np.arange(n) * dt
    f_force = rng.uniform(0.8, 1.3)
    delta, gamma = rng.uniform(0.2, 0.3), rng.uniform(0.3, 0.42)
    fade = m18.raised_cosine(t / 1.0)
    for _ in range(30):                                # starts whose chaos crosses between the wells and swings both
        start = (rng.uniform(-1.5, 1.5), rng.uniform(-1.0, 1.0))      # ways beyond 90 % of the peak
        x, u, tau = m18.magnetoelastic_beam(t, f_force, delta, gamma, start)
        crossings = int(np.sum(np.diff(np.sign(x)) != 0))
        if _both_sides(fade * x, 0.9) and crossings >= 6:
            break
    amp = rng.uniform(44.0, 48.0)
    scale = amp / np.abs(fade * x).max()
    v = scale * fade * x
    r_max, mean, shape, w0 = rng.uniform(40.0, 46.0), rng.uniform(9.0, 16.0), rng.uniform(12.0, 35.0), \
        rng.uniform(0.25, 0.4)
    r, weights = m18.wald_plays(100, r_max, mean, shape, w0)
    gain, off = rng.uniform(0.7, 1.4), rng.uniform(-4.0, 4.0)
    y = gain * m18.plays(v, r, weights, w0) + off
    rec = finish("holdout18_clean_wald_plays_magnetoelastic_beam_chaos_1790hz", seed, t, v, y, set(), "explained",
                 f"a clean core (100 plays, an inverse Gaussian density of thresholds on 0 ... {r_max:.0f} V, mean "
                 f"{mean:.1f} V, shape {shape:.0f} V) under the chaotic tip of a magnetoelastic beam (delta "
                 f"{delta:.2f}, gamma {gamma:.2f}, forced at {f_force:.2f} Hz, {crossings} well changes), faded in "
                 f"from 0 V, +-{amp:.0f} V, 1.79 kHz", rng, monitor_noise=3e-4)
    rec.extra.update(thresholds=r, weights=gain * weights, linear=gain * w0, offset=off, r_max=r_max, mean=mean,
                     shape=shape, f_force=f_force, delta=delta, gamma=gamma, start=start, x=x, u=u, tau=tau,
                     scale=scale, amp=amp, crossings=crossings, drive=v)
    return rec


# ---- one effect ----

@case
def creep_two_level_relaxation_heliograph_morse_215hz(seed):
    rng = _rng(seed, 2)
    dt = 1 / 215
    letters = list(m18.MORSE)
    words = ["".join(rng.choice(letters, int(rng.integers(2, 5)))) for _ in range(int(rng.integers(4, 6)))]
    marks, li, total = m18.morse_marks(words)
    unit, edge = rng.uniform(0.3, 0.45), rng.uniform(0.04, 0.08)
    lead, tail = rng.uniform(1.0, 2.0), rng.uniform(3.0, 4.0)
    n = int((lead + total * unit + tail) / dt)
    t = np.arange(n) * dt
    top = rng.uniform(88.0, 97.0)
    levels = top * rng.uniform(0.5, 1.0, li.max() + 1)
    levels[int(rng.integers(0, len(levels)))] = top
    starts = lead + marks[:, 0] * unit
    ends = starts + marks[:, 1] * unit
    v = m18.keyed_levels(t, starts, ends, levels[li], edge)
    w0 = rng.uniform(0.3, 0.45)
    r, weights = m18.exp_plays(80, 45.0, rng.uniform(8.0, 16.0), w0)
    gain = rng.uniform(0.7, 1.4)
    h = gain * m18.plays(v, r, weights, w0)
    c, tau0, hs_frac = rng.uniform(0.06, 0.1), rng.uniform(0.5, 1.5), rng.uniform(0.4, 0.8)
    h_s = hs_frac * h.max()
    cr = m18.two_level_creep(h, dt, c, tau0, h_s)
    rec = finish("holdout18_creep_two_level_relaxation_heliograph_morse_215hz", seed, t, v, h + cr, {"creep"},
                 "either", f"creep of two-level units biased by the load ({c:.1%}, tau0 {tau0:.2f} s, saturating at "
                 f"{h_s:.0f} output units) under a heliograph keyed in Morse ({' '.join(words)}, a unit of "
                 f"{unit * 1e3:.0f} ms), 0 ... {top:.0f} V, 215 Hz", rng)
    rec.extra.update(words=words, marks=marks, letter_of_mark=li, unit=unit, edge=edge, lead=lead, starts=starts,
                     ends=ends, top=top, levels=levels, thresholds=r, weights=weights, linear=w0, gain=gain, core=h,
                     c=c, tau0=tau0, h_s=h_s, creep=cr)
    return rec


@case
def rate_tuned_mass_damper_stage_dtmf_dialing_1515hz(seed):
    rng = _rng(seed, 3)
    dt = 1 / 1515
    fs = rng.uniform(140.0, 175.0)                     # the tones' frequencies divided by fs
    number = "".join(rng.choice(list("0123456789"), 10))
    ramp = rng.uniform(0.03, 0.05)
    tc = rng.uniform(0.3, 0.5)
    bursts = []
    d_dial = rng.uniform(1.5, 2.2)
    bursts.append((m18.DIAL_TONE[0] / fs, m18.DIAL_TONE[1] / fs, tc, tc + d_dial))
    tc += d_dial + rng.uniform(0.4, 0.7)
    for key in number:
        f1, f2 = m18.dtmf_pair(key)
        on = rng.uniform(0.45, 0.7)
        bursts.append((f1 / fs, f2 / fs, tc, tc + on))
        tc += on + rng.uniform(0.25, 0.45)
    tc += rng.uniform(0.5, 0.8)
    for i in range(2):                                 # two ring-backs, a silence between
        on = rng.uniform(1.2, 1.6)
        bursts.append((m18.RINGBACK[0] / fs, m18.RINGBACK[1] / fs, tc, tc + on))
        tc += on + (rng.uniform(1.8, 2.4) if i == 0 else rng.uniform(0.5, 0.8))
    n = int(tc / dt)
    t = np.arange(n) * dt
    amp = rng.uniform(44.0, 48.0)
    v = amp * m18.tone_bursts(t, bursts, ramp)
    w0 = rng.uniform(0.3, 0.45)
    r, weights = m18.exp_plays(70, 40.0, rng.uniform(8.0, 15.0), w0)
    gain = rng.uniform(0.7, 1.4)
    h = gain * m18.plays(v, r, weights, w0)
    f1, zeta1, mu = rng.uniform(34.0, 46.0), rng.uniform(0.02, 0.05), rng.uniform(0.05, 0.15)
    ratio, zeta2 = m18.den_hartog_tuning(mu)
    y = m18.tmd_stage(h, dt, f1, zeta1, mu, ratio * f1, zeta2)
    rec = finish("holdout18_rate_tuned_mass_damper_stage_dtmf_dialing_1515hz", seed, t, v, y, {"rate_dependence"},
                 "either", f"a stage resonating at {f1:.0f} Hz (zeta {zeta1:.2f}) with a tuned mass damper (mass ratio "
                 f"{mu:.2f}, Den Hartog's tuning), a dial tone, the number {number} in DTMF and two ring-backs (the "
                 f"frequencies over {fs:.0f}), +-{amp:.0f} V, 1.515 kHz", rng, monitor_noise=2.5e-4)
    rec.extra.update(fs=fs, number=number, bursts=bursts, ramp=ramp, amp=amp, thresholds=r, weights=weights,
                     linear=w0, gain=gain, core=h, f1=f1, zeta1=zeta1, mu=mu, f2=ratio * f1, zeta2=zeta2, drive=v)
    return rec


@case
def drift_gantry_beam_sag_moving_carriage_cantor_staircase_605hz(seed):
    rng = _rng(seed, 4)
    dt = 1 / 605
    npass = int(rng.integers(3, 5))
    top = rng.uniform(88.0, 97.0)
    tops = top * rng.uniform(0.65, 1.0, npass)
    tops[int(rng.integers(0, npass))] = top
    levels, pass_s, lead = rng.integers(3, 6, npass), rng.uniform(5.0, 7.5, npass), rng.uniform(0.5, 1.0)
    v, starts = m18.cantor_passes(dt, tops, levels, pass_s, lead)
    t = np.arange(len(v)) * dt
    w0 = rng.uniform(0.3, 0.45)
    r, weights = m18.exp_plays(80, 45.0, rng.uniform(10.0, 20.0), w0)
    gain = rng.uniform(0.7, 1.4)
    h = gain * m18.plays(v, r, weights, w0)
    nm = int(rng.integers(3, 6))
    for _ in range(100):                               # stations at least a quarter span apart, in turn
        st = rng.uniform(0.08, 0.92, nm + 1)
        if np.all(np.abs(np.diff(st)) > 0.25):
            break
    move_s = rng.uniform(1.5, 3.0, nm)
    slots = np.linspace(0.08, 0.9, nm + 1) * t[-1]
    move_starts = slots[:-1] + rng.uniform(0.0, 0.4, nm) * np.diff(slots)
    alpha = rng.uniform(0.3, 0.7)
    xi = m18.carriage_path(t, st, move_starts, move_s)
    sag = m18.beam_influence(alpha, xi)
    frac, sign = rng.uniform(0.04, 0.08), rng.choice([-1.0, 1.0])
    size = sign * frac * np.ptp(h) / np.abs(sag - sag[0]).max()
    d = size * (sag - sag[0])
    rec = finish("holdout18_drift_gantry_beam_sag_moving_carriage_cantor_staircase_605hz", seed, t, v, h + d, {"drift"},
                 "either", f"an offset from the sag of a gantry's bridge under its cross carriage ({nm} moves, the "
                 f"sensor at {alpha:.2f} of the span: {sign * frac:+.1%} of the span at most), {npass} passes up and "
                 f"down a devil's staircase, 0 ... {top:.0f} V, 605 Hz", rng)
    rec.extra.update(tops=tops, levels=levels, pass_s=pass_s, lead=lead, starts=starts, thresholds=r, weights=weights,
                     linear=w0, gain=gain, core=h, stations=st, move_starts=move_starts, move_s=move_s, alpha=alpha,
                     xi=xi, frac=frac, size=size, offset=d, top=top)
    return rec


@case
def asymmetry_slider_crank_encoder_logistic_map_setpoints_1160hz(seed):
    rng = _rng(seed, 5)
    dt = 1 / 1160
    npts = int(rng.integers(26, 34))
    for _ in range(50):                                # a chaotic orbit (no periodic window)
        rho, x0 = rng.uniform(3.9, 3.99), rng.uniform(0.05, 0.95)
        xs = m18.logistic_orbit(x0, rho, npts)
        if len(np.unique(np.round(xs, 6))) == npts and _both_sides(2 * xs - 1, 0.9):
            break
    amp = rng.uniform(44.0, 48.0)
    pts = amp * (2 * xs - 1) / np.abs(2 * xs - 1).max()
    holds, speed, t_min, lead = rng.uniform(0.1, 0.35, npts), rng.uniform(150.0, 300.0), rng.uniform(0.08, 0.15), \
        rng.uniform(0.3, 0.6)
    v, hstarts = m18.set_point_moves(dt, pts, holds, speed, t_min, lead)
    t = np.arange(len(v)) * dt
    w0 = rng.uniform(0.3, 0.45)
    r, weights = m18.exp_plays(80, 42.0, rng.uniform(8.0, 16.0), w0)
    x = m18.plays(v, r, weights, w0)
    l_r, asym, side = rng.uniform(1.4, 2.2), rng.uniform(0.05, 0.085), rng.choice([-1.0, 1.0])
    ends = np.array([x.max(), x.min()])

    def spread(k):                                     # half the difference of the ends' slope ratios
        q = m18.crank_reading(ends, k, 1.0, l_r, side) / ends
        return abs(q[0] - q[1]) / 2
    u_dead = math.sqrt(l_r * l_r - 1) + 1 - l_r      # the slide that turns the crank to its dead centre
    k = brentq(lambda k_: spread(k_) - asym, 1e-6, 0.6 * u_dead / np.abs(ends).max(), xtol=1e-14)
    psi = np.degrees(np.abs(m18.slider_crank_angle(k * ends, 1.0, l_r)).max())
    gain = rng.uniform(0.7, 1.4)
    y = gain * m18.crank_reading(x, k, 1.0, l_r, side)
    rec = finish("holdout18_asymmetry_slider_crank_encoder_logistic_map_setpoints_1160hz", seed, t, v, y,
                 {"asymmetry"}, "either", f"a slider-crank (rod {l_r:.2f} cranks, the crank turning up to {psi:.0f} "
                 f"deg, the ends' slopes {2 * asym:.0%} apart) read by an encoder on the crank, {npts} set points "
                 f"of the logistic map (rho {rho:.3f}), +-{amp:.0f} V, 1.16 kHz", rng, monitor_noise=3.5e-4)
    rec.extra.update(rho=rho, x0=x0, xs=xs, points=pts, holds=holds, speed=speed, t_min=t_min, lead=lead,
                     hstarts=hstarts, amp=amp, thresholds=r, weights=weights, linear=w0, core=x, l_r=l_r, asym=asym,
                     side=side, k=k, psi=psi, gain=gain, drive=v)
    return rec


@case
def saturation_repelling_magnet_spring_quarter_car_road_745hz(seed):
    rng = _rng(seed, 6)
    dt, sub = 1 / 745, 4
    n = int(rng.uniform(16.0, 24.0) / dt)
    t = np.arange(n) * dt
    tf = np.arange((n - 1) * sub + 1) * (dt / sub)
    V0, V1 = rng.uniform(10.0, 16.0), rng.uniform(24.0, 32.0)
    T = tf[-1]
    X = V0 * tf + (V1 - V0) * (tf / 2 - T / (2 * np.pi) * np.sin(np.pi * tf / T))     # the integral of the speed
    A, B, C = m18.quarter_car_matrices(**m18.GOLDEN_CAR)
    for _ in range(30):                                # roads whose travel swings 85 % of its peak both ways
        road, nw, aw = m18.iso8608_road(X, 200, rng)
        road = road * m18.raised_cosine(tf / 1.5)
        travel = m18.foh_filter(A, B, C, road - road[0], dt / sub)[::sub]
        if _both_sides(travel, 0.85):
            break
    amp = rng.uniform(44.0, 48.0)
    scale = amp / np.abs(travel).max()
    v = scale * travel
    w0 = rng.uniform(0.3, 0.45)
    r, weights = m18.exp_plays(80, 42.0, rng.uniform(8.0, 16.0), w0)
    gain = rng.uniform(0.7, 1.4)
    h = gain * m18.plays(v, r, weights, w0)
    c = (h.max() + h.min()) / 2
    m, comp = rng.uniform(0.3, 1.0), rng.uniform(0.10, 0.17)
    u_t = brentq(lambda u: m18.magnet_force(u, m) - (1 + m) * u / (1 - comp), 1e-6, 0.99, xtol=1e-14)
    d = np.abs(h - c).max() * (1 - comp) / u_t
    y = c + m18.magnet_stage(h - c, d, m)
    rec = finish("holdout18_saturation_repelling_magnet_spring_quarter_car_road_745hz", seed, t, v, y,
                 {"saturation"}, "either", f"a stage between two repelling magnets (their stiffness {m:.2f} of the "
                 f"flexure's, the ends at {u_t:.2f} of the gap, compressed by {comp:.0%}), the travel of the golden "
                 f"car's suspension on an ISO 8608 road at {V0:.0f} ... {V1:.0f} m/s, +-{amp:.0f} V, 745 Hz", rng)
    rec.extra.update(V0=V0, V1=V1, sub=sub, road_n=nw, road_amps=aw, travel=travel, scale=scale, amp=amp,
                     thresholds=r, weights=weights, linear=w0, gain=gain, core=h, centre=c, m=m, comp=comp, u_t=u_t,
                     d=d)
    return rec


@case
def delay_fbg_swept_laser_interrogator_manchester_code_815hz(seed):
    rng = _rng(seed, 7)
    dt, sub = 1 / 815, 8
    bit_rate = rng.uniform(3.0, 5.0)
    half = 0.5 / bit_rate
    n_bytes = int(math.ceil(rng.uniform(13.0, 20.0) * bit_rate / 8))
    bits = rng.integers(0, 2, 8 * n_bytes)
    amp = rng.uniform(44.0, 48.0)
    byte_amps = amp * rng.uniform(0.5, 1.0, n_bytes)
    byte_amps[int(rng.integers(0, n_bytes))] = amp
    levels = m18.manchester_levels(bits, np.repeat(byte_amps, 8))
    edge, lead, tail = rng.uniform(0.4, 0.7) * half, rng.uniform(0.4, 0.8), rng.uniform(0.4, 0.8)
    n = int((lead + len(levels) * half + tail) / dt)
    t = np.arange(n) * dt
    tf = np.arange((n - 1) * sub + 1) * (dt / sub)
    v = m18.level_path(t, lead, half, levels, edge)
    w0 = rng.uniform(0.3, 0.45)
    r, weights = m18.exp_plays(60, 40.0, rng.uniform(8.0, 16.0), w0)
    gain = rng.uniform(0.8, 1.4)
    h_f = gain * m18.plays(m18.level_path(tf, lead, half, levels, edge), r, weights, w0)
    latency, p_lo, rho = int(rng.integers(2, 4)), rng.uniform(0.1, 0.35), rng.uniform(0.25, 0.45)
    y, delays = m18.fbg_readings(t, tf, h_f, latency, p_lo, rho, h_f.min(), h_f.max())
    rec = finish("holdout18_delay_fbg_swept_laser_interrogator_manchester_code_815hz", seed, t, v, y, {"delay"},
                 "either", f"a fibre Bragg grating read by a swept-laser interrogator (the grating over {p_lo:.2f} ... "
                 f"{p_lo + rho:.2f} of the sweep, delivered {latency} sweeps later: a delay of {delays.min():.2f} ... "
                 f"{delays.max():.2f} samples), {n_bytes} bytes in Manchester code at {bit_rate:.1f} bit/s, +-"
                 f"{amp:.0f} V, 815 Hz", rng, monitor_noise=2e-4)
    rec.extra.update(bit_rate=bit_rate, half=half, bits=bits, byte_amps=byte_amps, levels=levels, edge=edge,
                     lead=lead, amp=amp, sub=sub, thresholds=r, weights=weights, linear=w0, gain=gain,
                     latency=latency, p_lo=p_lo, rho=rho, h_lo=h_f.min(), h_hi=h_f.max(), delays=delays, drive=v)
    return rec


@case
def initial_state_fibre_alignment_search_lotka_volterra_905hz(seed):
    rng = _rng(seed, 8)
    dt = 1 / 905
    w0 = rng.uniform(0.3, 0.45)
    r, weights = m18.exp_plays(80, 40.0, rng.uniform(10.0, 16.0), w0)
    scan_top, n_coarse = rng.uniform(80.0, 86.0), int(rng.integers(8, 13))
    v_t = rng.uniform(25.0, 55.0)                      # about where the fibre's mode sits, in volts
    x_opt = w0 * v_t + (1 - w0) * (v_t - rng.uniform(5.0, 15.0))
    width, s0, tol = rng.uniform(6.0, 12.0), rng.uniform(1.5, 3.0), rng.uniform(0.05, 0.1)
    s_max = s0 * rng.uniform(2.0, 3.0)
    pts, z0, v_star, trials = m18.alignment_history(r, weights, w0, scan_top, n_coarse, x_opt, width, s0, s_max, tol)
    g, T_small = rng.uniform(0.6, 1.5), rng.uniform(1.4, 2.0)
    units = 2 * np.pi / (math.sqrt(g) * T_small)      # LV time units per second: small cycles of T_small
    cv = v_star * rng.uniform(0.8, 1.05)              # volts per unit of prey: the equilibrium near v_star
    peak_top = rng.uniform(95.0, 99.0)
    lo_pk = max(v_star + 6.0, 1.25 * cv)
    hi_pk = max(min(scan_top - 4.0, 1.7 * cv), lo_pk + 2.0)
    peaks = np.r_[np.sort(rng.uniform(lo_pk, hi_pk, 2)), rng.uniform(0.85, 1.0) * peak_top, peak_top]
    Hs = [m18.lv_peak_orbit(p / cv, g) for p in peaks]
    dur = rng.uniform(20.0, 28.0)
    n = int(dur / dt)
    t = np.arange(n) * dt
    sw = np.cumsum(rng.uniform(0.2, 0.28, 3)) * dur * units
    x, yp = m18.lotka_volterra(t * units, g, v_star / cv, m18.lv_predators(v_star / cv, Hs[0], g, True),
                               list(zip(sw, Hs[1:])))
    v = cv * x
    gain = rng.uniform(0.7, 1.4)
    y = gain * m18.plays(v, r, weights, w0, state=z0)
    rec = finish("holdout18_initial_state_fibre_alignment_search_lotka_volterra_905hz", seed, t, v, y,
                 {"initial_state"}, "either", f"a core left by a fibre's alignment (a coarse scan to {scan_top:.0f} V "
                 f"in {n_coarse} steps, then {trials} trials of Rosenbrock's rule ending at {v_star:.1f} V, where the "
                 f"record starts), then Lotka-Volterra prey cycles (g {g:.2f}) growing in four orbits to "
                 f"{v.max():.0f} V, 905 Hz", rng)
    rec.extra.update(thresholds=r, weights=weights, linear=w0, scan_top=scan_top, n_coarse=n_coarse, x_opt=x_opt,
                     width=width, s0=s0, s_max=s_max, tol=tol, history=pts, state=z0, v_star=v_star, trials=trials, g=g,
                     T_small=T_small, units=units, cv=cv, peaks=peaks, Hs=Hs, switches=sw, prey=x, predators=yp,
                     gain=gain)
    return rec


# ---- two effects ----

@case
def pair_asymmetry_saturation_elastomer_pads_air_gauge_stadium_billiard_1325hz(seed):
    rng = _rng(seed, 9)
    dt = 1 / 1325
    n = int(rng.uniform(15.0, 24.0) / dt)
    t = np.arange(n) * dt
    a, R = 1.0, rng.uniform(0.6, 1.0)
    speed, lead = rng.uniform(3.0, 5.0) * (a + R), rng.uniform(0.3, 0.6)
    for _ in range(30):                                # paths that reach 85 % of the peak both ways
        p0, angle = (0.0, rng.uniform(-0.5, 0.5) * R), rng.uniform(-1.2, 1.2) + rng.choice([0.0, np.pi])
        bx, by, hits = m18.stadium_billiard(np.maximum(t - lead, 0.0), a, R, speed, p0, angle)
        if _both_sides(bx, 0.85):
            break
    amp = rng.uniform(44.0, 48.0)
    scale = amp / np.abs(bx).max()
    v = scale * bx
    w0 = rng.uniform(0.3, 0.45)
    r, weights = m18.exp_plays(80, 42.0, rng.uniform(8.0, 16.0), w0)
    gain = rng.uniform(0.7, 1.4)
    h = m18.plays(v, r, weights, w0)
    c = (h.max() + h.min()) / 2
    lam_p, comp = rng.uniform(0.8, 0.9), rng.uniform(0.10, 0.16)
    k0 = m18.pads_slope(0.0, lam_p)
    xi_t = brentq(lambda s: m18.pads_force(s, lam_p) - k0 * s / (1 - comp), 1e-6, lam_p * 0.999, xtol=1e-14)
    L0 = np.abs(h - c).max() * (1 - comp) / xi_t
    xs = m18.pads_stage(h - c, L0, lam_p)
    u0, asym, side = rng.uniform(0.9, 1.15), rng.uniform(0.05, 0.09), rng.choice([-1.0, 1.0])
    X = np.abs(xs).max()

    def stretch(g_c):                                  # (top slope ratio - bottom slope ratio) / 2 of the reading
        rd = m18.air_gauge_reading(np.array([X, -X]), u0 * g_c, g_c, 1.0)
        return (rd[0] / X + rd[1] / X) / 2
    g_c = brentq(lambda gc: abs(stretch(gc)) - asym, X, 200 * X, xtol=1e-12 * X)
    y = gain * (c + m18.air_gauge_reading(xs, u0 * g_c, g_c, side))
    rec = finish("holdout18_pair_asymmetry_saturation_elastomer_pads_air_gauge_stadium_billiard_1325hz", seed, t, v,
                 y, {"asymmetry", "saturation"}, "either", f"a stage between two neo-Hookean pads preloaded to a "
                 f"stretch of {lam_p:.2f} (the ends compressed by {comp:.0%}) read by a nozzle-flapper air gauge at "
                 f"{u0:.2f} of its characteristic gap (one end stretched by {asym:.0%}), a ball in a stadium "
                 f"(caps of {R:.2f} the half straight, {len(hits)} bounces), +-{amp:.0f} V, 1.325 kHz", rng)
    rec.extra.update(a=a, R=R, speed=speed, lead=lead, p0=p0, angle=angle, hits=hits, bx=bx, by=by, scale=scale,
                     amp=amp, thresholds=r, weights=weights, linear=w0, gain=gain, core=h, centre=c, lam_p=lam_p,
                     comp=comp, xi_t=xi_t, L0=L0, stage=xs, u0=u0, asym=asym, side=side, g_c=g_c)
    return rec


# ---- out of vocabulary ----

@case
def oov_self_heated_ntc_thermistor_wind_generator_gusts_455hz(seed):
    rng = _rng(seed, 10)
    dt = 1 / 455
    dur = rng.uniform(26.0, 36.0)
    n = int(dur / dt)
    t = np.arange(n) * dt
    t_up, t_down = rng.uniform(3.0, 5.0), rng.uniform(2.5, 4.0)
    ng = int(rng.integers(2, 4))
    Tg = rng.uniform(4.0, 7.0, ng)
    slots = np.linspace(t_up, dur - t_down - 1.0, ng + 1)
    tg0 = slots[:-1] + rng.uniform(0.0, 1.0, ng) * np.maximum(np.diff(slots) - Tg, 0.0)
    vg = rng.uniform(0.25, 0.45, ng)
    wind = 1.0 + sum(m18.eog_gust(t, a_, T_, g_) for a_, T_, g_ in zip(tg0, Tg, vg))
    wind = wind * m18.raised_cosine(t / t_up) * (1 - m18.raised_cosine((t - (dur - t_down)) / t_down))
    f_rated, poles, tau_r = rng.uniform(1.0, 1.8), 4, rng.uniform(0.5, 1.5)
    w_rated = 2 * np.pi * f_rated / poles
    emf, w_rot, theta = m18.generator_emf(t, w_rated * wind, tau_r, poles, 1.0)
    amp = rng.uniform(44.0, 48.0)
    v = amp * emf / np.abs(emf).max()
    r25 = math.exp(rng.uniform(math.log(10e3), math.log(47e3)))
    r_s, B = r25 * rng.uniform(0.6, 1.0), rng.uniform(3500.0, 4200.0)
    delta, tau = rng.uniform(0.6e-3, 1.2e-3), rng.uniform(0.4, 1.0)
    gain = rng.uniform(0.7, 1.4)
    out, T = m18.ntc_sense(v, dt, r25, B, r_s, delta, tau)
    y = gain * out
    rec = finish("holdout18_oov_self_heated_ntc_thermistor_wind_generator_gusts_455hz", seed, t, v, y, set(),
                 "unexplained", f"a self-heated NTC bead (R25 {r25 / 1e3:.0f} kOhm, B {B:.0f} K, {delta * 1e3:.2f} "
                 f"mW/K, {tau:.2f} s) in series with a {r_s / 1e3:.0f} kOhm sense resistor, across a wind generator "
                 f"({f_rated:.2f} Hz at the rated speed) through {ng} extreme operating gusts, +-{amp:.0f} V (the bead "
                 f"{T.max() - 298.15:.0f} K above the ambient at most), 455 Hz", rng)
    rec.extra.update(dur=dur, t_up=t_up, t_down=t_down, gust_starts=tg0, gust_T=Tg, gust_v=vg, wind=wind,
                     f_rated=f_rated, poles=poles, tau_r=tau_r, w_rated=w_rated, w_rot=w_rot, theta=theta, amp=amp,
                     r25=r25, r_s=r_s, B=B, delta=delta, tau=tau, gain=gain, T=T)
    return rec

"""The HOLDOUT16 set: written after HOLDOUT15 was measured, by a session that did not read how the diagnosis decides,
to be run once for the eighteenth round's measurement; kept out of ALL until then.

Mechanisms and signals that the other sets do not have, or not in these combinations (the laws and signals are in
:mod:`.mechanisms16`, each beside its source; citations written from memory are listed there):

- a clean core (120 plays from the play's definition with a triangular (Simpson) density of thresholds on 0 ... 40
  ... 46 V, its mode at 15 ... 45 % of that, a drawn linear part, gain and offset) under the Mackey-Glass delay
  equation (Mackey & Glass, Science 197 (1977) 287; beta 0.2, gamma 0.1, n 10, tau 17: a chaotic physiological
  series), 35 ... 60 of its time units a second, centred, faded in from rest at 0 V over 1 s to peaks of +-44 ... 48
  V, with a noisy input monitor, sampled at 1.56 kHz;
- creep with a Havriliak-Negami compliance (Havriliak & Negami, Polymer 8 (1967) 161: c / (1 + (i omega
  tau0)^alpha)^beta, c 7 ... 11 % of the core's output, tau0 0.5 ... 2.5 s, alpha 0.55 ... 0.8, beta 0.45 ... 0.7),
  a Prony series of about 600 Kelvin elements on its distribution of retardation times, by Boltzmann superposition;
  under a breathing trace by Lujan's law (Med. Phys. 26 (1999) 715: A_k sin^(2n), n 1 ... 3, 8 ... 11 breaths of 3
  ... 5 s, 0.6 ... 0.95 of the top) with two deep-inspiration breath holds of 4 ... 8 s at the top (88 ... 97 V) (a
  tumour-tracking stage), on a unipolar stroke from 0 V, sampled at 310 Hz;
- rate dependence of ferroelectric switching: plays whose walls move at R0 exp(-Ea / e) under the overstress e
  (Merz's law, Phys. Rev. 95 (1954) 690; R0 4 ... 16 kV/s, Ea 14 ... 24 V), so that a play trails its edge by Ea /
  ln(R0 / R) at the rate R (a flat density of 30 thresholds to 30 ... 42 V); under a wave maker's programme of three
  JONSWAP sea states (Hasselmann et al. 1973; peaks 0.3 ... 0.45, 0.9 ... 1.3 and 2.5 ... 3.5 Hz in a shuffled
  order, gamma 2 ... 5, random phases, each faded in and out), with a noisy input monitor, sampled at 1.88 kHz;
- an offset drift from a door held open 1.5 ... 4 s: the draught passes 2 ... 4 well-mixed air volumes of 1 ... 2.5
  s in series (the tanks-in-series model: the Erlang residence-time density; Levenspiel, *Chemical Reaction
  Engineering*, 1999), a bump that rises, peaks at 4 ... 8 % of the span (either sign) and decays, starting at 15
  ... 35 % of the record; under four ECE-15 urban driving cycles (UN ECE R83: idle, 15, 32, 50 and 35 km/h; 18 ...
  24 times real time, 50 km/h at 88 ... 97 V), on a unipolar stroke, sampled at 570 Hz;
- asymmetry of a potentiometer loaded by its meter (x / (1 + (R_p / R_L) x (1 - x)), R_p / R_L 1 ... 2, the wiper at
  0.15 ... 0.25 of the track +- 0.14 ... 0.18: concave, the bottom of the stroke stretched by 8 ... 17 %, the top
  compressed by 1 ... 7 %) reading the core (80 plays, a beta density); under a sequence of 7 ... 9 Walsh functions
  in sequency order (Walsh, Amer. J. Math. 45 (1923) 5; 16 levels of 0.1 ... 0.2 s each, amplitudes 0.5 ... 1 of 44
  ... 48 V and a sign, raised-cosine edges of 20 ... 40 ms, rests at 0 V between), sampled at 1.03 kHz;
- saturation by a piston between two closed air chambers (the polytropic law p V^1.4 = const, their stiffness 0.3
  ... 0.8 of the flexure's at rest, the chambers closed with the piston at mid-stroke: the ends compressed by 10 ...
  18 %, hardening faster than any polynomial as a chamber empties); under a bouncing ball (parabolic flights, 5 ...
  7 launches to 0.55 ... 1 of 88 ... 97 V, a restitution of 0.7 ... 0.85, bouncing down to 3 ... 6 % of the launch),
  on a unipolar stroke, sampled at 690 Hz;
- a delay of an LVDT's synchronous demodulator followed by four buffered RC sections (24 dB/octave, each 0.55 ...
  0.95 samples: a group delay of 2.2 ... 3.8 samples and a droop below 1 % in the signal's band), the core computed
  on a 4x finer grid; under a PAM-4 signal (symbols -1, -1/3, 1/3, 1 at 4.5 ... 7 a second through raised-cosine
  Nyquist pulses of roll-off 0.25 ... 0.6; Proakis, *Digital Communications*), with a noisy input monitor, sampled
  at 730 Hz;
- a core left by a previous session of a scanning-probe microscope: from rest, 3 ... 6 overview lines (+-36 ... 41
  V), then 20 ... 40 zoomed lines about a centre 15 ... 28 V off (either side, +-3 ... 8 V), parked at 0 V, where
  the record starts; under a pendulum pushed at the bottom (the exact swing 2 asin(k sn(omega0 t | k^2)), 8 ... 11
  swings of 1 or 2 periods whose amplitudes grow geometrically from 12 ... 20 deg to 160 ... 170 deg, flat-topped at
  the end; periods 0.7 ... 1.05 s at small amplitude), the last two at +-44 ... 48 V, beyond the history's extremes,
  which wipes the memory out, sampled at 930 Hz;
- two effects: rate dependence of a leaky bond layer in series with the stack's ceramic (Maxwell-Wagner interfacial
  polarisation: the ceramic sees 0.75 ... 0.87 of a fast change and all of the voltage after 20 ... 45 ms) and
  saturation of an AMR sensor reading the travel (the hard-axis magnetisation of Stoner-Wohlfarth grains with log-
  normal anisotropy fields, s 0.3 ... 0.6: linear, then a soft knee; the ends compressed by 10 ... 16 %); under 22
  synthesiser notes (a major scale two octaves up from 0.8 ... 1.2 Hz and one back down, attack-decay-sustain-
  release envelopes, each note of phase 0 or pi), with a noisy input monitor, sampled at 1.27 kHz;
- out of vocabulary: a hydraulic follower after the core whose pilot valve is on-off (a relay with a hysteresis of
  delta on the error, the cylinder's speed lagging the valve by 12 ... 25 ms, its top speed 1.6 ... 2.4 times the
  core's fastest): the loop hunts in a limit cycle (Tsypkin; its half period T from T - 2 tau tanh(T / 2 tau) = 2
  delta / k_u) of 4 ... 7 % of the span peak to peak at 12 ... 18 Hz, on top of the core's output; under a 4-bit DAC
  stepped through the Gray codes up and back down (32 levels, each held 0.6 ... 1 s after a raised-cosine step of
  0.35 ... 0.5 s), +-44 ... 48 V, sampled at 370 Hz. The output oscillates with a constant amplitude for as long as
  the input holds still. A PI core (any plays with non-negative weights and any linear part) is constant while its
  input is, and so is every named effect or it relaxes monotonically: creep and a rate part (a filter or rate-
  dependent plays) settle toward a constant, delay and initial state show the same constant, saturation and
  asymmetry are maps of it, and drift moves slowly (a few % over the record), never by an oscillation of 12 ... 18
  Hz that goes on through every hold.
"""

import math

import numpy as np
from scipy.optimize import brentq

from . import mechanisms as me
from . import mechanisms15 as m15
from . import mechanisms16 as m16
# thresholds and weights of an exponential density with a drawn linear part, as HOLDOUT13 ... HOLDOUT15 draw them
from .cases_holdout13 import _exp_plays
from .record import case_set, finish

HOLDOUT16, case, _rng = case_set("holdout16_", 16000)

#: the semitones of two octaves of a major scale
MAJOR = np.array([0, 2, 4, 5, 7, 9, 11, 12, 14, 16, 17, 19, 21, 23, 24])


def _both_sides(v, frac):
    """True when the path reaches beyond frac of its largest magnitude on both sides."""
    return min(v.max(), -v.min()) > frac * np.abs(v).max()


# ---- clean ----

@case
def clean_triangular_plays_mackey_glass_1560hz(seed):
    rng = _rng(seed, 1)
    dt = 1 / 1560
    n = int(rng.uniform(14.0, 20.0) / dt)
    t = np.arange(n) * dt
    N = int(rng.integers(440, 760))             # steps of the delay equation per tau = 17: 35 ... 60 units a second
    fade = m16.raised_cosine(t / 1.0)
    for _ in range(30):                          # a history whose path reaches 90 % of its peak on both sides
        x_hist, burn = rng.uniform(0.5, 1.3), int(rng.uniform(300.0, 500.0) * N / 17.0)
        path = m16.mackey_glass(N, n, x_hist, burn)
        mid, half = (path.max() + path.min()) / 2, (path.max() - path.min()) / 2
        x = fade * (path - mid) / half
        if _both_sides(x, 0.9):
            break
    amp = rng.uniform(44.0, 48.0)
    v = amp * x / np.abs(x).max()
    r_max, mode, w0 = rng.uniform(40.0, 46.0), rng.uniform(0.15, 0.45), rng.uniform(0.25, 0.4)
    r, weights = m16.triangular_plays(120, r_max, mode * r_max, w0)
    gain, off = rng.uniform(0.7, 1.4), rng.uniform(-4.0, 4.0)
    y = gain * m16.plays(v, r, weights, w0) + off
    rec = finish("holdout16_clean_triangular_plays_mackey_glass_1560hz", seed, t, v, y, set(), "explained",
                 f"a clean core (120 plays, a triangular density of thresholds on 0 ... {r_max:.0f} V, its mode at "
                 f"{mode:.0%}) under the Mackey-Glass series ({17 / (N * dt):.0f} units per second), faded in from "
                 f"0 V, +-{amp:.0f} V, 1.56 kHz", rng, monitor_noise=3e-4)
    rec.extra.update(thresholds=r, weights=gain * weights, linear=gain * w0, offset=off, r_max=r_max, mode=mode,
                     N=N, x_hist=x_hist, burn=burn, path=path, mid=mid, half=half, amp=amp, drive=v)
    return rec


# ---- one effect ----

@case
def creep_havriliak_negami_breath_hold_trace_310hz(seed):
    rng = _rng(seed, 2)
    dt = 1 / 310
    top = rng.uniform(88.0, 97.0)
    nb = int(rng.integers(8, 12))
    periods, amps = rng.uniform(3.0, 5.0, nb), top * rng.uniform(0.6, 0.95, nb)
    holds = np.zeros(nb)
    held = rng.choice(np.arange(1, nb), 2, replace=False)
    holds[held], amps[held] = rng.uniform(4.0, 8.0, 2), top
    n_pow, lead = int(rng.integers(1, 4)), rng.uniform(0.5, 1.5)
    v, starts = m16.lujan_breaths(dt, periods, amps, n_pow, holds, lead)
    gain = rng.uniform(0.7, 1.4)
    h = me.play_core(v, 100.0, gain=gain)
    tau0, alpha, beta = rng.uniform(0.5, 2.5), rng.uniform(0.55, 0.8), rng.uniform(0.45, 0.7)
    c = rng.uniform(0.07, 0.11)
    taus, wts = m16.hn_prony(tau0, alpha, beta)
    cr = m16.prony_creep(h, dt, c, taus, wts)
    y = h + cr
    rec = finish("holdout16_creep_havriliak_negami_breath_hold_trace_310hz", seed, np.arange(len(v)) * dt, v, y,
                 {"creep"}, "either", f"creep with a Havriliak-Negami compliance ({c:.1%}, tau0 {tau0:.2f} s, alpha "
                 f"{alpha:.2f}, beta {beta:.2f}) under {nb} breaths by Lujan's law (n {n_pow}, two held at the top), "
                 f"0 ... {top:.0f} V, 310 Hz", rng)
    rec.extra.update(periods=periods, amps=amps, holds=holds, n_pow=n_pow, lead=lead, starts=starts, top=top,
                     gain=gain, core=h, tau0=tau0, alpha=alpha, beta=beta, c=c, creep=cr)
    return rec


@case
def rate_merz_switching_plays_jonswap_sea_states_1880hz(seed):
    rng = _rng(seed, 3)
    dt = 1 / 1880
    peaks = rng.permutation([rng.uniform(0.3, 0.45), rng.uniform(0.9, 1.3), rng.uniform(2.5, 3.5)])
    durs = 1.2 / peaks + rng.uniform(2.5, 3.5, 3)
    gam = rng.uniform(2.0, 5.0, 3)
    amp = rng.uniform(44.0, 48.0)
    levels = amp * rng.uniform(0.85, 1.0, 3)
    levels[int(rng.integers(0, 3))] = amp
    for _ in range(30):                          # phases whose sea states reach beyond 0.85 of their peak both ways
        phases = rng.uniform(0, 2 * np.pi, (3, 120))
        v, starts, freqs, amps_f = m16.sea_states(dt, peaks, durs, gam, phases, levels, 0.6)
        if all(_both_sides(v[a:b], 0.85) for a, b in zip(starts, np.r_[starts[1:], len(v)])):
            break
    t = np.arange(len(v)) * dt
    r_max, w0 = rng.uniform(30.0, 42.0), rng.uniform(0.25, 0.4)
    r, weights = m16.flat_plays(30, r_max, w0)
    R0, Ea = 10 ** rng.uniform(3.6, 4.2), rng.uniform(14.0, 24.0)
    gain = rng.uniform(0.8, 1.4)
    y = gain * m16.merz_plays(v, dt, r, weights, w0, R0, Ea)
    rec = finish("holdout16_rate_merz_switching_plays_jonswap_sea_states_1880hz", seed, t, v, y, {"rate_dependence"},
                 "either", f"30 plays (a flat density to {r_max:.0f} V) whose walls move by Merz's law (R0 "
                 f"{R0:.0f} V/s, Ea {Ea:.0f} V), under three JONSWAP sea states (peaks "
                 f"{', '.join(f'{p:.2f}' for p in peaks)} Hz), +-{amp:.0f} V, 1.88 kHz", rng, monitor_noise=2.5e-4)
    rec.extra.update(peaks=peaks, durs=durs, gamma=gam, phases=phases, levels=levels, starts=starts, freqs=freqs,
                     amps_f=amps_f, amp=amp, thresholds=r, weights=weights, linear=w0, R0=R0, Ea=Ea, gain=gain,
                     drive=v)
    return rec


@case
def drift_door_draught_tanks_in_series_ece15_cycles_570hz(seed):
    rng = _rng(seed, 4)
    dt = 1 / 570
    ncyc = 4
    compress = rng.uniform(18.0, 24.0) * rng.uniform(0.95, 1.05, ncyc)
    top = rng.uniform(88.0, 97.0)
    tops = top * rng.uniform(0.9, 1.0, ncyc)
    tops[int(rng.integers(0, ncyc))] = top
    v, kt, kv = m16.ece15_cycles(dt, compress, tops)
    t = np.arange(len(v)) * dt
    r, weights, w0 = _exp_plays(rng, 45.0, 80, rng.uniform(10.0, 20.0))
    gain = rng.uniform(0.7, 1.4)
    h = gain * m16.plays(v, r, weights, w0)
    n_t, tau, open_s = int(rng.integers(2, 5)), rng.uniform(1.0, 2.5), rng.uniform(1.5, 4.0)
    t_open = rng.uniform(0.15, 0.35) * t[-1]
    bump = m16.tanks_in_series(t, n_t, tau, t_open, open_s)
    frac, sign = rng.uniform(0.04, 0.08), rng.choice([-1.0, 1.0])
    size = sign * frac * np.ptp(h) / bump.max()
    y = h + size * bump
    rec = finish("holdout16_drift_door_draught_tanks_in_series_ece15_cycles_570hz", seed, t, v, y, {"drift"},
                 "either", f"an offset from a door held open {open_s:.1f} s (the draught through {n_t} mixed volumes "
                 f"of {tau:.1f} s: {sign * frac:+.1%} of the span at its peak), four ECE-15 urban cycles "
                 f"({compress.mean():.0f} times real time), 0 ... {top:.0f} V, 570 Hz", rng)
    rec.extra.update(compress=compress, tops=tops, knot_t=kt, knot_v=kv, thresholds=r, weights=weights, linear=w0,
                     gain=gain, core=h, n_tanks=n_t, tau=tau, open_s=open_s, t_open=t_open, frac=frac, size=size,
                     bump=bump)
    return rec


@case
def asymmetry_loaded_potentiometer_walsh_functions_1030hz(seed):
    rng = _rng(seed, 5)
    dt = 1 / 1030
    nf = int(rng.integers(7, 10))
    ks = np.sort(rng.choice(np.arange(1, 16), nf, replace=False))
    amp = rng.uniform(44.0, 48.0)
    amps = amp * rng.uniform(0.5, 1.0, nf) * rng.choice([-1.0, 1.0], nf)
    amps[int(rng.integers(0, nf))] = amp * rng.choice([-1.0, 1.0])
    seg, edge, rest = rng.uniform(0.1, 0.2, nf), rng.uniform(0.02, 0.04), rng.uniform(0.3, 0.6)
    v, starts = m16.walsh_drive(dt, ks, amps, seg, edge, rest)
    t = np.arange(len(v)) * dt
    w0, a, b = rng.uniform(0.25, 0.4), rng.uniform(1.2, 2.0), rng.uniform(2.0, 4.0)
    r, weights = m15.beta_plays(80, 44.0, a, b, w0)
    x = m16.plays(v, r, weights, w0)
    ratio, x0, reach = rng.uniform(1.0, 2.0), rng.uniform(0.15, 0.25), rng.uniform(0.14, 0.18)
    k = reach / np.abs(x).max()
    gain = rng.uniform(0.7, 1.4)
    y = gain * m16.potentiometer_reading(x, x0, k, ratio)
    rec = finish("holdout16_asymmetry_loaded_potentiometer_walsh_functions_1030hz", seed, t, v, y, {"asymmetry"},
                 "either", f"a potentiometer loaded by its meter (R_p / R_L {ratio:.2f}, the wiper at {x0:.0%} "
                 f"+- {reach:.0%}) reading the core, {nf} Walsh functions (sequencies "
                 f"{', '.join(str(int(k)) for k in ks)}), +-{amp:.0f} V, "
                 f"1.03 kHz", rng)
    rec.extra.update(ks=ks, amps=amps, seg=seg, edge=edge, rest=rest, starts=starts, thresholds=r, weights=weights,
                     linear=w0, a=a, b=b, core=x, ratio=ratio, x0=x0, reach=reach, k=k, gain=gain)
    return rec


@case
def saturation_closed_air_chambers_bouncing_ball_690hz(seed):
    rng = _rng(seed, 6)
    dt = 1 / 690
    top = rng.uniform(88.0, 97.0)
    nl = int(rng.integers(5, 8))
    heights = top * rng.uniform(0.55, 1.0, nl)
    heights[int(rng.integers(0, 3))] = top
    t_flight = rng.uniform(0.8, 1.3)
    g = 8 * top / t_flight ** 2
    e, floor_frac, rest = rng.uniform(0.7, 0.85), rng.uniform(0.03, 0.06), rng.uniform(0.3, 0.8)
    v, apexes = m16.bouncing_ball(dt, heights, g, e, floor_frac, rest)
    t = np.arange(len(v)) * dt
    gain = rng.uniform(0.7, 1.4)
    h = me.play_core(v, 100.0, gain=gain)
    c = (h.max() + h.min()) / 2
    x = h - c
    xt = np.abs(x).max()
    gam, q, comp = 1.4, rng.uniform(0.3, 0.8), rng.uniform(0.10, 0.18)
    L = brentq(lambda ll: m16.gas_spring_stage(np.array([xt]), ll, q * ll / (2 * gam), gam)[0] - (1 - comp) * xt,
               0.05 * xt, 50 * xt, xtol=1e-12)
    kappa = q * L / (2 * gam)
    y = c + m16.gas_spring_stage(x, L, kappa, gam)
    rec = finish("holdout16_saturation_closed_air_chambers_bouncing_ball_690hz", seed, t, v, y, {"saturation"},
                 "either", f"a piston between two closed air chambers (gamma 1.4, their stiffness {q:.2f} of the "
                 f"flexure's at rest, the ends compressed by {comp:.0%}) after the core, {nl} launches of a bouncing "
                 f"ball (e {e:.2f}), 0 ... {top:.0f} V, 690 Hz", rng)
    rec.extra.update(heights=heights, g=g, e=e, floor_frac=floor_frac, rest=rest, apexes=apexes, top=top, gain=gain,
                     core=h, centre=c, L=L, kappa=kappa, gamma=gam, q=q, comp=comp)
    return rec


@case
def delay_lvdt_demodulator_rc4_pam4_raised_cosine_730hz(seed):
    rng = _rng(seed, 7)
    dt = 1 / 730
    Rs, roll = rng.uniform(4.5, 7.0), rng.uniform(0.25, 0.6)
    nsym = int(rng.uniform(20.0, 32.0) * Rs)
    t0 = 1.0
    n = int((t0 + (nsym + 2) / Rs) / dt)
    t = np.arange(n) * dt
    for _ in range(30):                          # symbols whose signal reaches beyond 0.85 of its peak on both sides
        symbols = rng.choice([-3.0, -1.0, 1.0, 3.0], nsym) / 3
        sig = m16.pam_signal(t, symbols, 1 / Rs, roll, t0)
        if _both_sides(sig, 0.85):
            break
    amp = rng.uniform(44.0, 48.0)
    scale = amp / np.abs(sig).max()
    sub = 4
    t_fine = np.arange(n * sub) * (dt / sub)
    r, weights, w0 = _exp_plays(rng, 40.0, 60, rng.uniform(8.0, 16.0))
    gain = rng.uniform(0.8, 1.4)
    h_fine = gain * m16.plays(scale * m16.pam_signal(t_fine, symbols, 1 / Rs, roll, t0), r, weights, w0)
    tau = rng.uniform(0.55, 0.95) * dt
    y = m16.rc4_filter(h_fine, dt / sub, tau)[::sub]
    v = scale * sig
    rec = finish("holdout16_delay_lvdt_demodulator_rc4_pam4_raised_cosine_730hz", seed, t, v, y, {"delay"},
                 "either", f"an LVDT's synchronous demodulator with four RC sections of {tau / dt:.2f} samples (a "
                 f"delay "
                 f"of {4 * tau / dt:.2f} samples), a PAM-4 signal ({Rs:.1f} symbols/s, raised-cosine roll-off "
                 f"{roll:.2f}), +-{amp:.0f} V, 730 Hz", rng, monitor_noise=2e-4)
    rec.extra.update(Rs=Rs, roll=roll, symbols=symbols, t0=t0, scale=scale, amp=amp, sub=sub, thresholds=r,
                     weights=weights, linear=w0, gain=gain, tau=tau, delay_samples=4 * tau / dt, drive=v)
    return rec


@case
def initial_state_afm_zoom_session_pendulum_pushes_930hz(seed):
    rng = _rng(seed, 8)
    dt = 1 / 930
    survey, n_survey = rng.uniform(36.0, 41.0), int(rng.integers(3, 7))
    centre, half = rng.choice([-1.0, 1.0]) * rng.uniform(15.0, 28.0), rng.uniform(3.0, 8.0)
    n_lines = int(rng.integers(20, 41))
    history = m16.scan_session_points(survey, n_survey, centre, half, n_lines)
    _, z = me.play_core(history, 100.0, return_state=True)
    omega0 = 2 * np.pi / rng.uniform(0.7, 1.05)
    m = int(rng.integers(8, 12))
    thetas = np.radians(np.geomspace(rng.uniform(12.0, 20.0), rng.uniform(160.0, 170.0), m))
    thetas[-2] = thetas[-1]
    cycles = rng.integers(1, 3, m)
    lead = rng.uniform(0.3, 0.8)
    theta, starts = m16.pendulum_pushes(dt, omega0, thetas, cycles, lead)
    amp = rng.uniform(44.0, 48.0)
    v = amp * theta / thetas[-1]
    t = np.arange(len(v)) * dt
    gain = rng.uniform(0.7, 1.4)
    y = me.play_core(v, 100.0, gain=gain, state=z)
    rec = finish("holdout16_initial_state_afm_zoom_session_pendulum_pushes_930hz", seed, t, v, y, {"initial_state"},
                 "either", f"a core left by a previous session's images ({n_survey} overview lines +-{survey:.0f} V, "
                 f"{n_lines} zoomed lines {centre:+.0f} +- {half:.0f} V, parked at 0 V), then {m} pushes of a "
                 f"pendulum ({np.degrees(thetas[0]):.0f} ... {np.degrees(thetas[-1]):.0f} deg), +-{amp:.0f} V, "
                 f"930 Hz", rng)
    rec.extra.update(survey=survey, n_survey=n_survey, centre=centre, half=half, n_lines=n_lines, history=history,
                     state=z, omega0=omega0, thetas=thetas, cycles=cycles, lead=lead, starts=starts, theta=theta,
                     amp=amp, gain=gain)
    return rec


# ---- two effects ----

@case
def pair_rate_saturation_maxwell_wagner_bond_amr_sensor_adsr_notes_1270hz(seed):
    rng = _rng(seed, 9)
    dt = 1 / 1270
    f0 = rng.uniform(0.8, 1.2)
    semis = np.r_[MAJOR, MAJOR[-2:6:-1]]             # two octaves up, one back down
    freqs = f0 * 2.0 ** (semis / 12)
    durs = np.maximum(rng.uniform(0.45, 0.75, len(freqs)), 1.5 / freqs)
    amp = rng.uniform(44.0, 48.0)
    peaks = amp * rng.uniform(0.6, 1.0, len(freqs))
    peaks[int(rng.integers(0, len(freqs)))] = amp
    env = dict(attack=rng.uniform(0.04, 0.08), decay=rng.uniform(0.1, 0.2), sustain=rng.uniform(0.55, 0.8),
               release=rng.uniform(0.1, 0.2), gap_s=rng.uniform(0.05, 0.15))
    for _ in range(30):                          # polarities (a phase of 0 or pi) that reach 0.85 of the peak both ways
        signs = rng.choice([-1.0, 1.0], len(freqs))
        sig, starts = m16.adsr_notes(dt, freqs, durs, signs * peaks, **env)
        if _both_sides(sig, 0.85):
            break
    scale = amp / np.abs(sig).max()
    v = scale * sig
    t = np.arange(len(v)) * dt
    rho, tau = rng.uniform(0.75, 0.87), rng.uniform(0.02, 0.045)
    v1 = m16.maxwell_wagner(v, dt, rho, tau)
    r, weights, w0 = _exp_plays(rng, 42.0, 80, rng.uniform(10.0, 20.0))
    x = m16.plays(v1, r, weights, w0)
    s, comp = rng.uniform(0.3, 0.6), rng.uniform(0.10, 0.16)
    xt = np.abs(x).max()
    mu = brentq(lambda mm: m16.amr_reading(np.array([xt]), mm, s)[0] - (1 - comp) * xt,
                math.log(xt) - 6, math.log(xt) + 8, xtol=1e-12)
    gain = rng.uniform(0.7, 1.4)
    y = gain * m16.amr_reading(x, mu, s)
    rec = finish("holdout16_pair_rate_saturation_maxwell_wagner_bond_amr_sensor_adsr_notes_1270hz", seed, t, v, y,
                 {"rate_dependence", "saturation"}, "either", f"a leaky bond layer in series with the ceramic "
                 f"(Maxwell-Wagner: {rho:.2f} of fast changes, tau {tau * 1e3:.0f} ms) and an AMR sensor (log-normal "
                 f"anisotropy, s {s:.2f}, the ends compressed by {comp:.0%}), {len(freqs)} ADSR notes of a major scale "
                 f"from {f0:.2f} Hz, +-{amp:.0f} V, 1.27 kHz", rng, monitor_noise=3.5e-4)
    rec.extra.update(f0=f0, freqs=freqs, durs=durs, peaks=peaks, signs=signs, starts=starts, scale=scale, amp=amp,
                     rho=rho,
                     tau=tau, stack_voltage=v1, thresholds=r, weights=weights, linear=w0, core=x, s=s, mu=mu,
                     comp=comp, gain=gain, drive=v, **env)
    return rec


# ---- out of vocabulary ----

@case
def oov_hunting_relay_hydraulic_follower_gray_code_staircase_370hz(seed):
    rng = _rng(seed, 10)
    dt = 1 / 370
    amp, edge, lead = rng.uniform(44.0, 48.0), rng.uniform(0.35, 0.5), rng.uniform(0.5, 1.0)
    holds = rng.uniform(0.6, 1.0, 32)
    v, codes = m16.gray_staircase(dt, amp, holds, edge, lead)
    t = np.arange(len(v)) * dt
    gain = rng.uniform(0.7, 1.4)
    h = me.play_core(v, 100.0, gain=gain)
    tau = rng.uniform(0.012, 0.025)
    k_u = rng.uniform(1.6, 2.4) * np.abs(np.diff(h)).max() / dt
    pp = rng.uniform(0.04, 0.07)
    delta = brentq(lambda d: 2 * m16.relay_amplitude(k_u, tau, d) - pp * np.ptp(h), 1e-6, np.ptp(h), xtol=1e-12)
    y = m16.relay_servo(h, dt, k_u, tau, delta)
    f_lc = 1 / (2 * m16.relay_half_period(k_u, tau, delta))
    rec = finish("holdout16_oov_hunting_relay_hydraulic_follower_gray_code_staircase_370hz", seed, t, v, y, set(),
                 "unexplained", f"a hydraulic follower after the core with an on-off pilot valve (hysteresis "
                 f"{delta:.2f}, lag {tau * 1e3:.0f} ms) hunting in a {f_lc:.1f} Hz limit cycle of {pp:.1%} of the "
                 f"span, a 4-bit Gray-code staircase up and down, +-{amp:.0f} V, 370 Hz", rng)
    rec.extra.update(amp=amp, edge=edge, lead=lead, holds=holds, codes=codes, gain=gain, core=h, tau=tau, k_u=k_u,
                     pp=pp, delta=delta, f_lc=f_lc)
    return rec

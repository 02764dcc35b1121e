"""The HOLDOUT20 set: written after HOLDOUT19 was measured, by a session that did not read how the diagnosis decides,
to be run once for the next round's measurement; kept out of ALL until then.

Mechanisms and signals that the other sets do not have, or not in these combinations (the laws and signals are in
:mod:`.mechanisms20`, each beside its source; its citations were written from memory, as it says):

- a clean core (100 plays with a Rice density of thresholds, (r / s^2) exp(-(r^2 + nu^2) / 2 s^2) I0(r nu / s^2) with
  nu 6 ... 12 V and s 3.5 ... 6.5 V, on 0 ... 40 ... 46 V: the magnitude of a two-component local field with a
  coherent part, a hump away from 0; a drawn linear part, gain and offset) under the x of Chua's circuit (the double
  scroll: alpha 15.6, beta 28, the diode's slopes -8/7 and -5/7; 1.6 ... 2.6 time units a second, turning at about
  1.2 ... 2 Hz in either scroll and jumping between them at irregular times), centred, faded in from 0 V over 1 s,
  to peaks of +-44 ... 48 V, with a noisy input monitor, sampled at 1.815 kHz;
- creep of a ferroelectric stack by nucleation-limited switching: regions switching exponentially with times whose
  logarithms follow a Lorentzian (about 0.4 ... 1.2 s, half width 0.8 ... 1.3 in ln tau: a heavy tail of fast and of
  very slow regions), 10 ... 15 % of the core's output in all, the regions faster than 1 ms elastic and slower than
  10^4 s frozen, by Boltzmann superposition (a Kelvin chain of 323 cells in ln tau); under a lift's car answering
  12 ... 17 calls on 7 ... 10 floors (equally spaced from the ground floor at 0 V to 88 ... 97 V, the top floor served
  in the first half, back to the ground floor at the end), its speed rising and falling as a raised cosine over 0.5 ...
  0.8 s to a rated 30 ... 50 V/s, the doors open 1.8 ... 3.2 s at each floor, on a unipolar stroke, sampled at 245 Hz;
- rate dependence of a stage (22 ... 35 Hz) braked by eddy currents: Wouterse's drag 2 a_c q / (1 + q^2), q = y' / v_c,
  viscous (zeta 0.5 ... 0.9) at low speeds, peaking at the critical speed v_c, 0.35 ... 0.6 of the fastest stroke's,
  and fading beyond it; under handwriting by the sigma-lognormal model (7 ... 10 words of 4 ... 7 overlapping strokes,
  up and down to drawn heights, each 0.18 ... 0.35 s with a lognormal speed profile and a direction turning by up to
  +-1.2 rad; pen lifts of 0.4 ... 0.9 s, the pen's height then held), scaled to +-44 ... 48 V, with a noisy input
  monitor, sampled at 1.665 kHz;
- an offset drift from the cure shrinkage of a UV-curing adhesive in the sensor's mount: the lamp switched on at 15 ...
  35 % of the record, the cure following Kamal & Sourour's autocatalytic law (k1 0.01 ... 0.03 /s, k2 0.6 ... 1.2 /s,
  m 0.8 ... 1.1, n 1.2 ... 1.6: slow to start, then fast, then a long tail), the mount moving only with the cure beyond
  the gel point (0.15 ... 0.3), 4 ... 8 % of the span at the end (either sign); under an engine's piston (the in-line
  slider-crank, r / l 0.25 ... 0.35: lingering at bottom dead centre), the engine idling at 0.6 ... 0.9 Hz with 3 ...
  5 throttle blips (toward 1.5 ... 3 Hz more for 1 ... 2.5 s, first-order rise and fall), faded in from 0 V, +-44 ...
  48 V, sampled at 615 Hz;
- asymmetry of a tendon stretched by the stage, the output the load cell's force by Fung's exponential law (q (exp(x /
  q) - 1) beyond its preload; the ends' secants 10 ... 17 % apart, stiffening on a drawn side); under the bursts of a
  Hindmarsh-Rose neuron (I 3.1 ... 3.3, r 0.005 ... 0.008, 15 ... 22 time units a second: a few spikes, then a quiet
  spell), centred and faded in from 0 V, +-44 ... 48 V, with a noisy input monitor, sampled at 1.145 kHz;
- saturation by a quasi-zero-stiffness mount (a vertical spring and two horizontal springs 0.6 ... 1.5 times as stiff,
  precompressed so that the centre's stiffness is 0.35 ... 0.6 of the vertical spring's; Carrella, Brennan & Waters):
  soft in the middle and stiffening outside, odd, the ends compressed by 14 ... 20 %; under three oscillometric blood
  pressure measurements (a cuff inflated to 88 ... 94 V in 1.2 ... 2 s, bled at 7 ... 11 V/s to 15 ... 25 V and dumped;
  the arterial pulses of 1.3 ... 2.2 beats a second riding on the bleed, largest where the cuff passes the mean
  arterial pressure at 0.5 ... 0.6 of the top), on a unipolar stroke, sampled at 655 Hz;
- a delay of a thickness gauge downstream of a rolling mill's roll gap (the actuator sets the gap; the strip at 15 ...
  25 m/s, its speed hunting by +-2 ... 5 % at 0.05 ... 0.12 Hz, reaches the gauge 0.12 ... 0.44 m on: a transit of 2.2
  ... 5 samples, varying with the speed), the core computed on a 4x finer grid; under change ringing (rounds, two
  plain courses of Plain Hunt on 5 or 6 bells and rounds; a blow every 0.22 ... 0.32 s with an open handstroke lead;
  each bell's hum, prime, tierce, quint and nominal (0.5, 1, 1.2, 1.5, 2 times its strike note, the notes a major
  scale down to a tenor of 0.9 ... 1.3 Hz) ringing on with their own decays), +-44 ... 48 V, with a noisy input
  monitor, sampled at 285 Hz;
- a core left by an AFM force-volume map (from the virgin state at 0 V: at each point of a 4 x 4 ... 6 x 6 grid over a
  tilted sample with a cell on it, an approach to the trigger 12 ... 18 V beyond the contact, the highest at 80 ... 88
  V, and a retraction by 25 ... 40 V), then parked at 30 ... 42 V, where the record starts; then a nanoindenter's
  multi-cycle load function (7 ... 9 constant-rate loadings at 40 ... 80 V/s to peaks rising evenly from 45 ... 52 V
  to 93 ... 98 V, held 0.8 ... 1.5 s, each partially unloaded to 0.45 ... 0.7 of its peak and held 0.3 ... 0.6 s, a
  full unloading at the end), which passes the map's top only in its last 40 %, on a unipolar stroke, sampled at
  985 Hz;
- two effects: rate dependence of a ground-fixed reading of a stage whose base recoils on its isolators (the stage 0.06
  ... 0.12 of the moving mass, the isolators at 2 ... 4 Hz, zeta 0.1 ... 0.25: the reaction force moves the base by -mu
  of the stroke above the isolators' frequency and not below it) and a delay of the output's logger, started by a
  software trigger 1.8 ... 3.6 samples after the input's; under a bird's wing in flap-bounding flight (up to 7 ... 9
  bursts of 4 ... 8 wingbeats at 1.5 ... 5 Hz, the downstroke 55 ... 65 % of each beat, amplitudes 0.7 ... 1 of +-44 ...
  48 V, between bounds of 0.3 ... 1 s with the wings folded; the record at most 26 s long), sampled at 1.435 kHz;
- out of vocabulary: a shallow arch (a von Mises truss, half span 2 ... 4 times its rise) pressed through its snap by
  the stage under displacement control (held 0.15 ... 0.3 of its rise up at rest, pressed to 2.1 ... 2.3 times its rise:
  past its limit point, through the flat shape and past the inverted one), the output the load cell's force; under the
  level of a tank drained by a bell siphon (6 ... 8 fills of 2 ... 7 s to 88 ... 95 V, each drained by Torricelli's law
  in one or two seconds down to 3 ... 8 V, where air breaks the siphon), on a unipolar stroke, sampled at 335 Hz. In
  every slow fill the force falls by a large part of its span while the input still rises, and rises again nearer the
  top. A PI core (any plays with non-negative weights and any linear part) rises with a rising input and so does every
  output map of the vocabulary (saturation and asymmetry are increasing maps; a negative gain makes the whole output
  fall instead); rate dependence and delay lag or shift the output and change with the fill's speed, which varies
  threefold, while the fall happens at the same input level in every fill; creep and drift are slow in time; an initial
  state is forgotten after the first fill.
"""

import math

import numpy as np
from scipy.optimize import brentq

from . import mechanisms20 as m20
from .record import case_set, finish

HOLDOUT20, case, _rng = case_set("holdout20_", 20000)


def _both_sides(v, frac):
    """True when the path reaches beyond frac of its largest magnitude on both sides."""
    return min(v.max(), -v.min()) > frac * np.abs(v).max()


# ---- clean ----

@case
def clean_rice_plays_chua_double_scroll_1815hz(seed):
    rng = _rng(seed, 1)
    dt = 1 / 1815
    n = int(rng.uniform(12.0, 18.0) / dt)
    t = np.arange(n) * dt
    units = rng.uniform(1.6, 2.6)
    fade = m20.raised_cosine(t / 1.0)
    for _ in range(30):                                # starts whose centred x swings both ways beyond 85 %
        start = (rng.uniform(-0.5, 0.5), rng.uniform(-0.2, 0.2), rng.uniform(-0.5, 0.5))
        x, s0 = m20.chua_x(t, units, start)
        xc = x - (x.max() + x.min()) / 2
        if _both_sides(fade * xc, 0.85):
            break
    amp = rng.uniform(44.0, 48.0)
    scale = amp / np.abs(fade * xc).max()
    v = scale * fade * xc
    r_max, nu, sigma, w0 = rng.uniform(40.0, 46.0), rng.uniform(6.0, 12.0), rng.uniform(3.5, 6.5), \
        rng.uniform(0.25, 0.4)
    r, weights = m20.rice_plays(100, r_max, nu, sigma, w0)
    gain, off = rng.uniform(0.7, 1.4), rng.uniform(-4.0, 4.0)
    y = gain * m20.plays(v, r, weights, w0) + off
    rec = finish("holdout20_clean_rice_plays_chua_double_scroll_1815hz", seed, t, v, y, set(), "explained",
                 f"a clean core (100 plays, a Rice density of thresholds, nu {nu:.1f} V, s {sigma:.1f} V, on 0 ... "
                 f"{r_max:.0f} V) under the x of Chua's double scroll ({units:.2f} units a second), faded in from 0 V, "
                 f"+-{amp:.0f} V, 1.815 kHz", rng, monitor_noise=3e-4)
    rec.extra.update(thresholds=r, weights=gain * weights, linear=gain * w0, offset=off, r_max=r_max, nu=nu,
                     sigma=sigma, units=units, start=start, s0=s0, x=x, xc=xc, scale=scale, amp=amp, drive=v)
    return rec


# ---- one effect ----

@case
def creep_nls_domain_switching_lift_calls_245hz(seed):
    rng = _rng(seed, 2)
    dt = 1 / 245
    n_fl = int(rng.integers(7, 11))                    # floors, the ground floor at 0 V
    top = rng.uniform(88.0, 97.0)
    floors = top * np.arange(n_fl) / (n_fl - 1)
    n_stops = int(rng.integers(12, 17))
    seq, cur = [], 0
    at_top = int(rng.integers(1, n_stops // 2))        # one call to the top floor in the first half
    for k in range(n_stops - 1):
        if k == at_top:
            nxt = n_fl - 1 if cur != n_fl - 1 else int(rng.integers(0, n_fl - 1))
        else:
            nxt = int(rng.choice([f for f in range(n_fl) if f != cur]))
        seq.append(nxt)
        cur = nxt
    if cur == 0:                                       # end at the ground floor, from elsewhere
        seq.append(int(rng.integers(1, n_fl)))
    seq.append(0)
    levels = floors[np.array(seq)]
    dwells = rng.uniform(1.8, 3.2, len(levels))
    v_max, t_acc, lead = rng.uniform(30.0, 50.0), rng.uniform(0.5, 0.8), rng.uniform(1.0, 2.0)
    _, _, _, end = m20.lift_path(np.zeros(1), lead, levels, dwells, v_max, t_acc)
    dwells[-1] += max(0.0, 42.0 - end)                 # at least 10,000 samples
    end = max(end, 42.0)
    n = int(end / dt)
    t = np.arange(n) * dt
    v, starts, durs, _ = m20.lift_path(t, lead, levels, dwells, v_max, t_acc)
    w0 = rng.uniform(0.3, 0.45)
    r, weights = m20.exp_plays(80, 45.0, rng.uniform(8.0, 16.0), w0)
    gain = rng.uniform(0.7, 1.4)
    h = gain * m20.plays(v, r, weights, w0)
    c, tau_m, w_log = rng.uniform(0.10, 0.15), rng.uniform(0.4, 1.2), rng.uniform(0.8, 1.3)
    cr = m20.nls_creep(h, dt, c, tau_m, w_log)
    rec = finish("holdout20_creep_nls_domain_switching_lift_calls_245hz", seed, t, v, h + cr, {"creep"}, "either",
                 f"creep by nucleation-limited switching ({c:.1%}, ln tau Lorentzian about {tau_m:.2f} s, half "
                 f"width {w_log:.2f}) under a lift answering {len(levels)} calls on {n_fl} floors to {top:.0f} V, "
                 f"245 Hz", rng)
    rec.extra.update(n_fl=n_fl, top=top, floors=floors, seq=np.array(seq), levels=levels, dwells=dwells,
                     v_max=v_max, t_acc=t_acc, lead=lead, starts=starts, durs=durs, thresholds=r, weights=weights,
                     linear=w0, gain=gain, core=h, c=c, tau_m=tau_m, w_log=w_log, creep=cr)
    return rec


def _handwriting(rng, lead, n_words):
    """Strokes of a few handwritten words (sigma-lognormal): in each word 4 ... 7 strokes alternately up and down to
    drawn heights, each 0.18 ... 0.35 s long (lognormal spread 0.2 ... 0.35), starting 0.55 ... 0.85 of the previous
    one's time after it (overlapping), curved by up to +-1.2 rad; pen lifts of 0.4 ... 0.9 s between words. The pen
    starts at 0; the targets are heights in -1 ... 1."""
    strokes, tc, y = [], lead, 0.0
    for _ in range(n_words):
        up = bool(rng.integers(0, 2))
        for _ in range(int(rng.integers(4, 8))):
            target = rng.uniform(0.35, 1.0) if up else -rng.uniform(0.35, 1.0)
            T = rng.uniform(0.18, 0.35)
            sg = rng.uniform(0.2, 0.35)
            mu = math.log(T) + sg * sg                 # the speed peaks T after the stroke's start
            dth = rng.uniform(-1.2, 1.2)
            mid = (np.pi / 2 if up else -np.pi / 2) + rng.uniform(-0.6, 0.6)
            th = mid - dth / 2
            per = (math.cos(th) - math.cos(th + dth)) / dth    # vertical travel per unit D
            D = (target - y) / per
            strokes.append((tc, mu, sg, D, th, dth))
            y, up = target, not up
            tc += rng.uniform(0.55, 0.85) * T
        tc += rng.uniform(0.4, 0.9)
    return strokes, tc


@case
def rate_eddy_current_brake_stage_handwriting_1665hz(seed):
    rng = _rng(seed, 3)
    dt = 1 / 1665
    lead = rng.uniform(0.3, 0.6)
    for _ in range(40):                                # words whose pen reaches beyond 80 % of its peak both ways
        strokes, end = _handwriting(rng, lead, int(rng.integers(7, 11)))
        n = int((end + 0.8) / dt)
        t = np.arange(n) * dt
        yp = m20.sigma_lognormal_y(t, strokes)
        if _both_sides(yp, 0.8) and 10_000 <= n <= 40_000:
            break
    amp = rng.uniform(44.0, 48.0)
    scale = amp / np.abs(yp).max()
    v = scale * yp
    w0 = rng.uniform(0.3, 0.45)
    r, weights = m20.exp_plays(80, 42.0, rng.uniform(8.0, 16.0), w0)
    gain = rng.uniform(0.7, 1.4)
    h = gain * m20.plays(v, r, weights, w0)
    dh = np.abs(np.diff(h)).max() / dt
    f_n, zeta0, vc_frac = rng.uniform(22.0, 35.0), rng.uniform(0.5, 0.9), rng.uniform(0.35, 0.6)
    v_c = vc_frac * dh
    a_c = zeta0 * v_c * 2 * np.pi * f_n                # the low-speed damping ratio zeta0
    y = m20.brake_stage(h, dt, f_n, a_c, v_c)
    rec = finish("holdout20_rate_eddy_current_brake_stage_handwriting_1665hz", seed, t, v, y, {"rate_dependence"},
                 "either", f"a stage at {f_n:.0f} Hz braked by eddy currents (zeta {zeta0:.2f} at low speed, the "
                 f"drag peaking at {vc_frac:.2f} of the fastest stroke's speed) under {len(strokes)} handwritten "
                 f"strokes, +-{amp:.0f} V, 1.665 kHz", rng, monitor_noise=2.5e-4)
    rec.extra.update(strokes=strokes, lead=lead, pen=yp, scale=scale, amp=amp, thresholds=r, weights=weights,
                     linear=w0, gain=gain, core=h, f_n=f_n, zeta0=zeta0, vc_frac=vc_frac, v_c=v_c, a_c=a_c, drive=v)
    return rec


@case
def drift_uv_cure_shrinkage_engine_piston_615hz(seed):
    rng = _rng(seed, 4)
    dt = 1 / 615
    T = rng.uniform(22.0, 30.0)
    n = int(T / dt)
    t = np.arange(n) * dt
    f_idle, lam = rng.uniform(0.6, 0.9), rng.uniform(0.25, 0.35)
    n_b = int(rng.integers(3, 6))
    slots = np.linspace(1.5, T - 4.0, n_b + 1)
    blips = [(rng.uniform(a, a + 0.3 * (b - a)), rng.uniform(1.0, 2.5), rng.uniform(1.5, 3.0), rng.uniform(0.3, 0.6),
              rng.uniform(0.8, 1.5)) for a, b in zip(slots[:-1], slots[1:])]
    theta = m20.engine_angle(t, f_idle, blips) + rng.uniform(0, 2 * np.pi)
    amp = rng.uniform(44.0, 48.0)
    v = amp * m20.raised_cosine(t / 1.0) * m20.piston_x(theta, lam)
    w0 = rng.uniform(0.3, 0.45)
    r, weights = m20.exp_plays(80, 42.0, rng.uniform(8.0, 16.0), w0)
    gain = rng.uniform(0.7, 1.4)
    h = gain * m20.plays(v, r, weights, w0)
    t_on = rng.uniform(0.15, 0.35) * T
    k1, k2, mm, nn, a_gel = rng.uniform(0.01, 0.03), rng.uniform(0.6, 1.2), rng.uniform(0.8, 1.1), \
        rng.uniform(1.2, 1.6), rng.uniform(0.15, 0.3)
    alpha = m20.kamal_cure(t, t_on, k1, k2, mm, nn)
    share = m20.gel_shrinkage(alpha, a_gel)
    frac, sign = rng.uniform(0.04, 0.08), rng.choice([-1.0, 1.0])
    s = sign * frac * np.ptp(h) / share[-1]            # the full cure's offset: frac of the span at the end
    off = rng.uniform(-3.0, 3.0)
    y = h + s * share + off
    rec = finish("holdout20_drift_uv_cure_shrinkage_engine_piston_615hz", seed, t, v, y, {"drift"}, "either",
                 f"an offset drift of {sign * frac:+.1%} of the span as a UV-cured adhesive shrinks (the lamp on at "
                 f"{t_on:.1f} s, Kamal k1 {k1:.3f}, k2 {k2:.2f}, m {mm:.2f}, n {nn:.2f}, gel at {a_gel:.2f}) under "
                 f"an engine's piston (idling at {f_idle:.2f} Hz, {n_b} throttle blips, r / l {lam:.2f}), "
                 f"+-{amp:.0f} V, 615 Hz", rng)
    rec.extra.update(f_idle=f_idle, lam=lam, blips=blips, theta=theta, amp=amp, thresholds=r, weights=weights,
                     linear=w0, gain=gain, core=h, t_on=t_on, k1=k1, k2=k2, m=mm, n=nn, a_gel=a_gel, alpha=alpha,
                     shrink=s, frac=frac, sign=sign, offset=off)
    return rec


@case
def asymmetry_fung_tendon_hindmarsh_rose_bursts_1145hz(seed):
    rng = _rng(seed, 5)
    dt = 1 / 1145
    n = int(rng.uniform(15.0, 22.0) / dt)
    t = np.arange(n) * dt
    I, r_slow, units = rng.uniform(3.1, 3.3), rng.uniform(0.005, 0.008), rng.uniform(15.0, 22.0)
    fade = m20.raised_cosine(t / 1.0)
    for _ in range(30):
        start = (rng.uniform(-1.6, 1.6), rng.uniform(-10.0, 0.0), rng.uniform(1.5, 3.0))
        x, s0 = m20.hindmarsh_rose_x(t, units, start, I, r_slow)
        xc = x - (x.max() + x.min()) / 2
        if _both_sides(fade * xc, 0.85):
            break
    amp = rng.uniform(44.0, 48.0)
    scale = amp / np.abs(fade * xc).max()
    v = scale * fade * xc
    w0 = rng.uniform(0.3, 0.45)
    r, weights = m20.exp_plays(80, 42.0, rng.uniform(8.0, 16.0), w0)
    x_core = m20.plays(v, r, weights, w0)
    c = (x_core.max() + x_core.min()) / 2
    X = np.abs(x_core - c).max()
    asym, side = rng.uniform(0.05, 0.085), rng.choice([-1.0, 1.0])
    u = brentq(lambda u_: (math.cosh(u_) - 1) / u_ - asym, 1e-6, 2.0, xtol=1e-15)   # the secants' half spread
    q = X / u
    gain = rng.uniform(0.7, 1.4)
    y = gain * (c + side * m20.fung_force(side * (x_core - c), q))
    rec = finish("holdout20_asymmetry_fung_tendon_hindmarsh_rose_bursts_1145hz", seed, t, v, y, {"asymmetry"},
                 "either", f"a tendon's force by Fung's exponential law (the ends' secants {2 * asym:.0%} apart, "
                 f"stiffening {'up' if side > 0 else 'down'}) under a Hindmarsh-Rose neuron's bursts (I {I:.2f}, r "
                 f"{r_slow:.4f}, {units:.0f} units a second), +-{amp:.0f} V, 1.145 kHz", rng, monitor_noise=3e-4)
    rec.extra.update(I=I, r_slow=r_slow, units=units, start=start, s0=s0, x=x, xc=xc, scale=scale, amp=amp,
                     thresholds=r, weights=weights, linear=w0, core=x_core, centre=c, asym=asym, side=side, u=u, q=q,
                     gain=gain, drive=v)
    return rec


@case
def saturation_qzs_isolator_oscillometric_cuff_655hz(seed):
    rng = _rng(seed, 6)
    dt = 1 / 655
    n_meas = 3
    top = rng.uniform(88.0, 94.0)
    map_ = rng.uniform(0.5, 0.6) * top
    f_hr, a_max = rng.uniform(1.3, 2.2), rng.uniform(3.0, 5.0)
    w_lo, w_hi = rng.uniform(0.1, 0.14) * top, rng.uniform(0.16, 0.22) * top
    tc, segs = rng.uniform(0.5, 1.0), []
    for _ in range(n_meas):
        seg = dict(t0=tc, top=top * rng.uniform(0.98, 1.0), t_inf=rng.uniform(1.2, 2.0), hold=rng.uniform(0.3, 0.6),
                   rate=rng.uniform(7.0, 11.0), dump_at=rng.uniform(15.0, 25.0), tau_dump=rng.uniform(0.3, 0.5))
        segs.append(seg)
        end_bleed = tc + seg["t_inf"] + seg["hold"] + (seg["top"] - seg["dump_at"]) / seg["rate"]
        tc = end_bleed + 5 * seg["tau_dump"] + rng.uniform(1.0, 2.0)
    n = int(tc / dt)
    t = np.arange(n) * dt
    p = np.zeros(n)
    for k, seg in enumerate(segs):
        pk, _ = m20.cuff_pressure(t, **seg)
        nxt = segs[k + 1]["t0"] if k + 1 < len(segs) else np.inf
        p = np.where((t >= seg["t0"]) & (t < nxt), pk, p)
    phase = rng.uniform(0, 1)
    v = p + m20.cuff_pulses(t, p, f_hr, phase, map_, w_lo, w_hi, a_max)
    w0 = rng.uniform(0.3, 0.45)
    r, weights = m20.exp_plays(80, 45.0, rng.uniform(8.0, 16.0), w0)
    gain = rng.uniform(0.7, 1.4)
    h = gain * m20.plays(v, r, weights, w0)
    c = (h.max() + h.min()) / 2
    X = np.abs(h - c).max()
    kappa, s0, comp = rng.uniform(0.6, 1.5), rng.uniform(0.35, 0.6), rng.uniform(0.14, 0.2)
    gamma = 1 + (1 - s0) / (2 * kappa)
    xh_max = brentq(lambda x_: s0 * x_ / m20.qzs_force(x_, kappa, gamma) - (1 - comp), 1e-6, 50.0, xtol=1e-14)
    F_s = X / float(m20.qzs_force(xh_max, kappa, gamma))
    y = c + s0 * F_s * m20.qzs_stage((h - c) / F_s, kappa, gamma)
    rec = finish("holdout20_saturation_qzs_isolator_oscillometric_cuff_655hz", seed, t, v, y, {"saturation"},
                 "either", f"a quasi-zero-stiffness mount (oblique springs {kappa:.2f} of the vertical one, the "
                 f"centre's stiffness {s0:.2f} of it; the ends compressed by {comp:.0%}) under {n_meas} oscillometric "
                 f"cuff measurements (to {top:.0f} V, MAP {map_:.0f} V, {f_hr:.1f} beats a second), 655 Hz", rng)
    rec.extra.update(top=top, map_=map_, f_hr=f_hr, a_max=a_max, w_lo=w_lo, w_hi=w_hi, segs=segs, phase=phase,
                     pressure=p, thresholds=r, weights=weights, linear=w0, gain=gain, core=h, centre=c, kappa=kappa,
                     s0=s0, gamma=gamma, comp=comp, xh_max=xh_max, F_s=F_s)
    return rec


@case
def delay_rolling_mill_strip_transit_change_ringing_285hz(seed):
    rng = _rng(seed, 7)
    dt, sub = 1 / 285, 4
    nb = int(rng.integers(5, 7))
    scale_deg = [5 / 3, 3 / 2, 4 / 3, 5 / 4, 9 / 8, 1.0][-nb:]          # a major scale down to the tenor
    f_tenor = rng.uniform(0.9, 1.3)
    primes = f_tenor * np.array(scale_deg)
    rows = m20.plain_hunt(nb)
    rows = [rows[0]] + rows + rows[1:] + [rows[0]]     # rounds, two plain courses, rounds
    interval, tau_hum = rng.uniform(0.22, 0.32), rng.uniform(2.5, 4.0)
    phases = rng.uniform(0, 2 * np.pi, (nb, len(m20.BELL_RATIOS)))
    lead = rng.uniform(0.5, 1.0)
    n_blows = len(rows) * nb + len(rows) // 2
    n = int(max(lead + n_blows * interval + 2.0, 37.0) / dt)
    t = np.arange(n) * dt
    tf = np.arange((n - 1) * sub + 1) * (dt / sub)
    bells_f, blows = m20.bell_strikes(tf - lead, rows, interval, primes, tau_hum, 0.03, phases)
    amp = rng.uniform(44.0, 48.0)
    peak = np.abs(bells_f[::sub]).max()
    v_f = amp * bells_f / peak                         # the drive on the fine grid; the record's every sub-th
    v = v_f[::sub]
    w0 = rng.uniform(0.3, 0.45)
    r, weights = m20.exp_plays(60, 40.0, rng.uniform(8.0, 16.0), w0)
    gain = rng.uniform(0.8, 1.4)
    h_f = gain * m20.plays(v_f, r, weights, w0)
    V0, d_s = rng.uniform(15.0, 25.0), rng.uniform(2.2, 5.0)
    d = V0 * d_s * dt                                  # the gauge's distance: d_s samples of transit at V0
    a_sp, f_m, phi = rng.uniform(0.02, 0.05), rng.uniform(0.05, 0.12), rng.uniform(0, 2 * np.pi)
    tg = m20.strip_transit(t, d, V0, a_sp, f_m, phi)
    y = np.interp(tg, tf, h_f, left=h_f[0])
    delays = (t - tg) / dt
    rec = finish("holdout20_delay_rolling_mill_strip_transit_change_ringing_285hz", seed, t, v, y, {"delay"},
                 "either", f"a thickness gauge {d * 1000:.0f} mm after a roll gap, the strip at {V0:.0f} m/s +- "
                 f"{a_sp:.0%} (a delay of {delays[n // 10:].min():.2f} ... {delays[n // 10:].max():.2f} samples), "
                 f"two plain courses of Plain Hunt on {nb} bells (tenor {f_tenor:.2f} Hz), +-{amp:.0f} V, 285 Hz",
                 rng, monitor_noise=2e-4)
    rec.extra.update(nb=nb, primes=primes, rows=rows, interval=interval, tau_hum=tau_hum, phases=phases, lead=lead,
                     blows=blows, amp=amp, peak=peak, sub=sub, thresholds=r, weights=weights, linear=w0, gain=gain,
                     V0=V0, d=d, d_s=d_s, a_sp=a_sp, f_m=f_m, phi=phi, t_gap=tg, delays=delays, drive=v)
    return rec


@case
def initial_state_afm_force_volume_nanoindentation_cycles_985hz(seed):
    rng = _rng(seed, 8)
    dt = 1 / 985
    w0 = rng.uniform(0.3, 0.45)
    r, weights = m20.exp_plays(80, 40.0, rng.uniform(10.0, 16.0), w0)
    g = int(rng.integers(4, 7))                        # a g x g force-volume grid
    gx, gy = np.meshgrid(np.arange(g), np.arange(g))
    gx, gy = gx.ravel() / (g - 1), gy.ravel() / (g - 1)
    base, tilt = rng.uniform(40.0, 50.0), rng.uniform(-6.0, 6.0)
    cx, cy, cw, ch_ = rng.uniform(0.3, 0.7), rng.uniform(0.3, 0.7), rng.uniform(0.15, 0.3), rng.uniform(14.0, 22.0)
    contacts = base + tilt * (gx - 0.5) + ch_ * np.exp(-((gx - cx) ** 2 + (gy - cy) ** 2) / (2 * cw * cw))
    trigger, ramp = rng.uniform(12.0, 18.0), rng.uniform(25.0, 40.0)
    hi = (contacts + trigger).max()
    contacts = contacts + (rng.uniform(80.0, 88.0) - hi)    # the cell's top triggers at 80 ... 88 V
    park = rng.uniform(30.0, 42.0)
    hist = m20.afm_history(contacts, trigger, ramp, park)
    _, z0 = m20.plays(hist, r, weights, w0, return_state=True)
    K = int(rng.integers(7, 10))
    top = rng.uniform(93.0, 98.0)
    peaks = np.linspace(rng.uniform(45.0, 52.0), top, K)
    unload = rng.uniform(0.45, 0.7, K)
    rate, hold_top, hold_low, lead = rng.uniform(40.0, 80.0), rng.uniform(0.8, 1.5), rng.uniform(0.3, 0.6), \
        rng.uniform(0.5, 1.0)
    _, (kt, _) = m20.indentation_path(np.zeros(1), park, lead, peaks, unload, rate, hold_top, hold_low, 1.0)
    tail = 1.0 + max(0.0, 11.0 - kt[-1])               # at least 10,000 samples
    n = int((kt[-1] - 1.0 + tail) / dt)
    t = np.arange(n) * dt
    v, knots = m20.indentation_path(t, park, lead, peaks, unload, rate, hold_top, hold_low, tail)
    gain = rng.uniform(0.7, 1.4)
    y = gain * m20.plays(v, r, weights, w0, state=z0)
    rec = finish("holdout20_initial_state_afm_force_volume_nanoindentation_cycles_985hz", seed, t, v, y,
                 {"initial_state"}, "either", f"a core left by an AFM force-volume map ({g} x {g} curves, triggering "
                 f"at up to {hist.max():.0f} V, retracting {ramp:.0f} V; parked at {park:.1f} V, where the record "
                 f"starts), then {K} indentation cycles with partial unloading, peaks {peaks[0]:.0f} ... {top:.0f} V, "
                 f"985 Hz", rng)
    rec.extra.update(thresholds=r, weights=weights, linear=w0, g=g, contacts=contacts, trigger=trigger, ramp=ramp,
                     park=park, history=hist, state=z0, peaks=peaks, unload=unload, rate=rate, hold_top=hold_top,
                     hold_low=hold_low, lead=lead, tail=tail, knots=knots, gain=gain)
    return rec


# ---- two effects ----

@case
def pair_rate_delay_base_recoil_logger_trigger_flap_bounding_1435hz(seed):
    rng = _rng(seed, 9)
    dt = 1 / 1435
    n_bursts = int(rng.integers(7, 10))
    e_fold, down = rng.uniform(-0.25, 0.15), rng.uniform(0.55, 0.65)
    tc, bursts = rng.uniform(0.8, 1.2), []
    full = int(rng.integers(0, 4))                     # a burst at full amplitude among the first four
    for k in range(n_bursts):
        nb_, f, bound = int(rng.integers(4, 9)), rng.uniform(1.5, 5.0), rng.uniform(0.3, 1.0)
        if tc + nb_ / f + bound > 26.0:                # at most 26 s (37,310 samples): the later bursts left out
            break
        amp_k = 1.0 if k == full else rng.uniform(0.7, 1.0)
        bursts.append((tc, nb_, f, amp_k))
        tc += nb_ / f + bound
    n = max(int((tc + 0.3) / dt), 12_000)
    t = np.arange(n) * dt
    amp = rng.uniform(44.0, 48.0)

    def path(tt):
        return amp * m20.raised_cosine(tt / 0.8) * m20.wing_elevation(tt, bursts, e_fold, down)
    v = path(t)
    w0 = rng.uniform(0.3, 0.45)
    r, weights = m20.exp_plays(80, 42.0, rng.uniform(8.0, 16.0), w0)
    gain = rng.uniform(0.7, 1.4)
    D = rng.uniform(1.8, 3.6)                          # the output logger's late start, samples
    u = gain * m20.plays(path(t - D * dt), r, weights, w0)
    mu, f_iso, zeta = rng.uniform(0.06, 0.12), rng.uniform(2.0, 4.0), rng.uniform(0.1, 0.25)
    y = m20.recoil_reading(u, dt, mu, f_iso, zeta)
    rec = finish("holdout20_pair_rate_delay_base_recoil_logger_trigger_flap_bounding_1435hz", seed, t, v, y,
                 {"rate_dependence", "delay"}, "either", f"a base recoiling on its isolators (mass ratio {mu:.2f}, "
                 f"{f_iso:.1f} Hz, zeta {zeta:.2f}) under the stage, read from the ground, by a logger started "
                 f"{D:.2f} samples late; {n_bursts} bursts of wingbeats (1.5 ... 5 Hz) between bounds, "
                 f"+-{amp:.0f} V, 1.435 kHz", rng)
    rec.extra.update(bursts=bursts, e_fold=e_fold, down=down, amp=amp, thresholds=r, weights=weights, linear=w0,
                     gain=gain, D=D, mu=mu, f_iso=f_iso, zeta=zeta, core_late=u)
    return rec


# ---- out of vocabulary ----

@case
def oov_von_mises_arch_snap_through_bell_siphon_335hz(seed):
    rng = _rng(seed, 10)
    dt = 1 / 335
    H_t = 100.0                                        # the level in V (0 ... 100 V: empty ... full)
    h_on, h_off = rng.uniform(88.0, 95.0), rng.uniform(3.0, 8.0)
    H = rng.uniform(20.0, 40.0)                        # the outlet below the floor
    T_d = rng.uniform(0.7, 1.3)                        # the drain's time without inflow, about
    k = 2 * (math.sqrt(h_on + H) - math.sqrt(h_off + H)) / T_d
    n_cyc = int(rng.integers(6, 9))
    fills = (h_on - h_off) / rng.uniform(2.0, 7.0, n_cyc)
    fills[0] = h_on / rng.uniform(3.0, 6.0)
    fills = np.minimum(fills, 0.5 * k * math.sqrt(h_off + H))     # the siphon outruns the inflow twice over
    lead = rng.uniform(1.0, 2.0)
    _, cyc = m20.bell_siphon(np.zeros(1), lead, fills, h_on, h_off, k, H)
    end = max(cyc[-1][2] + rng.uniform(1.0, 2.0), 31.0)
    n = int(end / dt)
    t = np.arange(n) * dt
    v, cycles = m20.bell_siphon(t, lead, fills, h_on, h_off, k, H)
    w0 = rng.uniform(0.3, 0.45)
    r, weights = m20.exp_plays(60, 40.0, rng.uniform(8.0, 16.0), w0)
    x_core = m20.plays(v, r, weights, w0)
    h0, a = 1.0, rng.uniform(2.0, 4.0)
    lift, reach = rng.uniform(0.15, 0.3), rng.uniform(2.1, 2.3)    # the stroke's ends in units of the arch's rise
    x = h0 * (-lift + (reach + lift) * x_core / x_core.max())
    F = m20.mises_force(x, h0, a)
    gain, off = rng.uniform(0.7, 1.4) * 40.0 / np.ptp(F), rng.uniform(-3.0, 3.0)
    y = gain * F + off
    rec = finish("holdout20_oov_von_mises_arch_snap_through_bell_siphon_335hz", seed, t, v, y, set(), "unexplained",
                 f"a shallow arch (von Mises truss, half span {a:.1f} x its rise) held {lift:.2f} x its rise up at "
                 f"rest and pressed through its snap by the stage to {reach:.2f} x its rise, read by a load cell; a "
                 f"tank's level under a bell siphon ({n_cyc} fills, {h_off:.0f} ... {h_on:.0f} V), 335 Hz", rng)
    rec.extra.update(H_t=H_t, h_on=h_on, h_off=h_off, H=H, k=k, fills=fills, lead=lead, cycles=cycles, thresholds=r,
                     weights=weights, linear=w0, core=x_core, h0=h0, a=a, lift=lift, reach=reach, x=x, force=F,
                     gain=gain, offset=off)
    return rec

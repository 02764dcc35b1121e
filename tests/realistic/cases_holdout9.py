"""The HOLDOUT9 set: written after HOLDOUT8 was measured (2026-11-25, ninth round), to be run once
for the ninth round's final measurement (docs/diagnose.md); run once (commit 91dbca8, 24 of 30
runs right) and part of ALL since.

Mechanisms and signals that the other sets do not have, or not in these combinations:

- a clean core (160 plays written here from the play's definition, with a hump-shaped gamma
  density of thresholds, a drawn linear part, gain and offset) under ring-downs: exponentially
  damped sine bursts, each of a whole number of cycles and restarted at a random amplitude and
  frequency, sampled at 640 Hz;
- creep that ages: its rate is proportional to its distance from a hold value that grows faster
  than the load (c_inf = kappa h (1 + q |h| / h_ref)), with a time constant growing with the log
  of the time since the load last moved, tau0 (1 + gamma ln(1 + s / s0)), under holds alternating
  between the low and the high half of a unipolar stroke (0 ... 100 V) with slow ramps between
  them, sampled at 200 Hz;
- a Coleman-Hodgdon (Duhem) core relaxing toward its anhysteretic line with a time constant of
  60 ... 120 ms, so that its loop width 2 (a - b) / (alpha + 1 / (tau R)) grows with the drive rate
  R, under triangle waves at four distinct frequencies (0.35 ... 15 Hz), each played twice, in a
  shuffled order, sampled at 1.6 kHz;
- an exponential warm-up (3 ... 6 s) plus an ambient-temperature step mid-record smoothed by a
  thermal time constant of 1.5 ... 3.5 s, under band-limited random drive, sampled at 480 Hz;
- a gain that falls linearly by 3 ... 8 % and recovers (a V in time), under repeated sine bursts
  of constant amplitude, sampled at 900 Hz;
- generalized plays (a quadratic-plus-linear rising envelope, a linear falling one) on a unipolar
  stroke, under a triangle staircase (a full-stroke triangle, then triangles riding on levels
  that climb and come down), sampled at 1.1 kHz;
- a Langevin saturation of the core's irreversible part beside a linear reversible part
  (B = mu0 H + J_s L(h / a), a magnetic flux density), under a sine whose amplitude grows
  geometrically from 12 % to 100 %, sampled at 700 Hz;
- a dead time of 2.5 ... 6 samples (in quarter samples) from an acquisition latency: the core
  computed in continuous time (a 4x finer grid) and its output sampled late, under a
  pseudo-random binary staircase (a 9-bit shift register, a level drawn per run of equal bits)
  smoothed by the amplifier's two lags, sampled at 2 kHz;
- two effects: a core left by one large excursion (+-52 ... 58 V) and a return to a level of
  -+5 ... 20 V, where the record starts, and a slow linear thermal offset, under random
  triangles (extremes and ramp times drawn per segment), sampled at 1.35 kHz;
- out of vocabulary: a second, unmeasured input, a mechanical preload varying slowly as a sine
  (a period of 9 ... 14 s), that scales the plays' thresholds by 1 +- 0.35 ... 0.5, so that the
  loops breathe (widen while their tips come in, then narrow), under an amplitude-keyed sine
  (groups of 2 ... 4 cycles alternately at full and 55 ... 70 % amplitude), sampled at 350 Hz.
  No PI core with the named effects draws that: a gain drift scales width and span alike, and
  an offset leaves the width alone. (The preload could also move the loops' centre, but for
  plays a centre shift is an output offset, a named drift, so it is left out.)
"""

import numpy as np
from scipy.special import expi

from . import excitations as ex
from . import mechanisms as me
from .record import case_set, finish

HOLDOUT9, case, _rng = case_set("holdout9_", 9000)


# ---- signals not in excitations.py ----

def _ring_downs(dt, n, rng, amp, freq=(0.7, 2.2), cycles=(5, 10), decay_to=(0.04, 0.12), low_fraction=0.3):
    """Damped oscillations: bursts A_i exp(-t / tau_i) sin(2 pi f_i t), each of a whole number c_i
    of cycles (so it ends at 0 V, where the next starts), tau_i such that the envelope falls to
    `decay_to` of A_i over the burst; A_i drawn in [low_fraction, 1] x amp, f_i and c_i drawn per
    burst. Cut to ``n`` samples. Returns the signal and the bursts' (start, A, f, tau)."""
    parts, bursts = [], []
    total = 0
    while total < n:
        f = rng.uniform(*freq)
        c = int(rng.integers(*cycles))
        m = int(round(c / f / dt))
        T = m * dt
        tau = T / -np.log(rng.uniform(*decay_to))
        A = amp * rng.uniform(low_fraction, 1.0)
        tt = np.arange(m) * dt
        parts.append(A * np.exp(-tt / tau) * np.sin(2 * np.pi * c * np.arange(m) / m))
        bursts.append((total, A, c / T, tau))
        total += m
    return np.concatenate(parts)[:n], bursts


def _alternating_holds(dt, rng, n_holds, hold_s, ramp_s, low=(5.0, 40.0), high=(60.0, 95.0)):
    """Holds alternating between the low and the high part of a unipolar stroke (starting at
    0 V, the first level high), each level drawn in its band, linear ramps of `ramp_s` between
    them (ex.staircase_holds)."""
    lv = [0.0] + [rng.uniform(*(high if k % 2 == 0 else low)) for k in range(n_holds)]
    return ex.staircase_holds(dt, lv, hold_s, ramp_s), np.array(lv)


def _shuffled_triangles(dt, freqs, amp, rng, repeats=2, seconds=2.5):
    """Triangle waves at each of `freqs`, each played `repeats` times, in a random order with no
    frequency twice in a row; each segment a whole number of cycles (about `seconds` long, at
    least one) starting at 0 V upward, so the segments join at 0 V. Returns the signal, the
    segment boundaries (sample indices) and the segments' frequencies (as played)."""
    order = np.repeat(np.arange(len(freqs)), repeats)
    while True:
        order = rng.permutation(order)
        if np.all(order[1:] != order[:-1]):
            break
    parts, edges, played = [], [0], []
    for i in order:
        f = freqs[i]
        c = max(1, int(round(seconds * f)))
        m = int(round(c / f / dt))
        s = np.arange(m) / m
        parts.append(amp * 2 / np.pi * np.arcsin(np.sin(2 * np.pi * c * s)))
        edges.append(edges[-1] + m)
        played.append(c / (m * dt))
    return np.concatenate(parts + [[0.0]]), np.array(edges), np.array(played)


def _sine_bursts(dt, freq, cycles, amp, n_bursts, rest_s):
    """`n_bursts` sine bursts of `cycles` whole cycles at `freq` and constant amplitude `amp`,
    each preceded by `rest_s` at 0 V, and a rest at the end."""
    m = int(round(cycles / freq / dt))
    burst = amp * np.sin(2 * np.pi * cycles * np.arange(m) / m)
    rest = np.zeros(int(round(rest_s / dt)))
    return np.concatenate([np.concatenate([rest, burst]) for _ in range(n_bursts)] + [rest])


def _ramps_through(points, durations, dt):
    """Straight ramps through `points` (starting at the first), the k-th taking durations[k] s."""
    parts = [np.linspace(a, b, max(int(round(d / dt)), 2), endpoint=False)
             for a, b, d in zip(points[:-1], points[1:], durations)]
    return np.concatenate(parts + [[points[-1]]])


def _triangle_staircase(dt, rng, top=100.0, rate=(70.0, 110.0), n_up=5, half=(10.0, 16.0), cycles=2):
    """A unipolar triangle staircase: one full-stroke triangle 0 -> top -> 0, then triangles of
    half-height `half` (drawn) riding on `n_up` levels that climb from the bottom to the top of
    the stroke and then `n_up - 1` coming down, `cycles` triangles on each, then back to 0 V;
    all ramps at one drawn rate. Every point lies in [0, top]."""
    r = rng.uniform(*rate)
    a = rng.uniform(*half)
    ups = np.linspace(a + 2.0, top - a - 2.0, n_up) + rng.uniform(-3.0, 3.0, n_up)
    centres = np.concatenate([ups, ups[-2::-1] + rng.uniform(-3.0, 3.0, n_up - 1)])
    centres = np.clip(centres, a, top - a)
    pts = [0.0, top, 0.0]
    for c in centres:
        pts += [c + a, c - a] * cycles
    pts.append(0.0)
    pts = np.array(pts)
    return _ramps_through(pts, np.abs(np.diff(pts)) / r, dt), pts


def _geometric_growing_sine(dt, n, freq, amp, start=0.12):
    """A sine at `freq` whose amplitude grows geometrically from start x amp to amp over the record."""
    tt = np.arange(n) * dt
    return amp * start ** (1 - np.arange(n) / (n - 1)) * np.sin(2 * np.pi * freq * tt)


def _lfsr_bits(n, rng, order=9, tap=5):
    """`n` bits of the maximal-length shift register x^9 + x^5 + 1 (PRBS9, period 511) from a
    random non-zero start: the new bit is s_9 xor s_5, the output bit s_9."""
    state = [int(b) for b in rng.integers(0, 2, order)]
    if not any(state):
        state[0] = 1
    out = np.empty(n, int)
    for k in range(n):
        out[k] = state[order - 1]
        state = [state[order - 1] ^ state[tap - 1]] + state[:-1]
    return out


def _two_lags(x, dt, tau):
    """x through two first-order lags of time constant `tau` in series (exact for a held input),
    starting at rest at x[0]: a drive amplifier's bandwidth, without overshoot."""
    a = np.exp(-dt / tau)
    y1 = y2 = x[0]
    out = np.empty_like(x)
    for k, xk in enumerate(x):
        y2 = a * y2 + (1 - a) * y1
        y1 = a * y1 + (1 - a) * xk
        out[k] = y2
    return out


def _smoothed_prbs(dt, n, rng, amp, bit_s, tau, low_fraction=0.45, rest_s=0.3):
    """A pseudo-random binary staircase: `rest_s` at 0 V, then cells of `bit_s` seconds, each at
    the sign of a PRBS9 bit; every run of equal bits holds one level whose magnitude is drawn in
    [low_fraction, 1] x amp; smoothed by :func:`_two_lags`. ``n`` samples."""
    n_rest = int(round(rest_s / dt))
    cell = int(round(bit_s / dt))
    bits = _lfsr_bits((n - n_rest) // cell + 1, rng)
    runs = np.concatenate([[0], np.cumsum(bits[1:] != bits[:-1])])
    mags = rng.uniform(low_fraction, 1.0, runs[-1] + 1)
    levels = np.where(bits == 1, 1.0, -1.0) * mags[runs] * amp
    raw = np.concatenate([np.zeros(n_rest), np.repeat(levels, cell)])[:n]
    return _two_lags(raw, dt, tau)


def _random_triangles(dt, rng, start, n_seg, bound=40.0, min_step=15.0, seconds=(0.4, 1.4)):
    """Ramps from `start` through `n_seg` extremes alternating in direction (the first drawn),
    each in [-bound, bound] at least `min_step` beyond the previous one, each ramp's duration
    drawn in `seconds`. Returns the signal and the extremes."""
    pts = [start]
    up = rng.random() < 0.5
    for _ in range(n_seg):
        lo, hi = (pts[-1] + min_step, bound) if up else (-bound, pts[-1] - min_step)
        if lo > hi:                          # no room this way: turn round
            up = not up
            lo, hi = (pts[-1] + min_step, bound) if up else (-bound, pts[-1] - min_step)
        pts.append(rng.uniform(lo, hi))
        up = not up
    pts = np.array(pts)
    return _ramps_through(pts, rng.uniform(*seconds, n_seg), dt), pts


def _keyed_sine(dt, freq, amp, low_fraction, groups):
    """An amplitude-keyed sine: groups of whole cycles at `freq` (their numbers of cycles in
    `groups`), alternately at amp and low_fraction x amp (switching at 0 V), starting at full
    amplitude."""
    parts = []
    for k, c in enumerate(groups):
        m = int(round(c / freq / dt))
        parts.append(amp * (1.0 if k % 2 == 0 else low_fraction) * np.sin(2 * np.pi * c * np.arange(m) / m))
    return np.concatenate(parts + [[0.0]])


# ---- mechanisms not in mechanisms.py ----

def _plays(v, r, w, w0, state=None, return_state=False):
    """y = w0 v + sum_k w_k z_k with z_k the play (backlash) of threshold r_k,
    z_k(t) = min(max(z_k(t-), v(t) - r_k), v(t) + r_k) (Brokate & Sprekels 1996, sec. 2.3),
    from z = 0 (demagnetised) unless ``state``."""
    v = np.asarray(v, float)
    z = np.zeros_like(r) if state is None else np.array(state, float)
    y = np.empty_like(v)
    for k, vk in enumerate(v):
        z = np.minimum(np.maximum(z, vk - r), vk + r)
        y[k] = w0 * vk + w @ z
    return (y, z) if return_state else y


def _gamma_density(r_max, shape, scale, n=160):
    """n thresholds evenly spaced in (0, r_max] and weights (summing to 1) of a gamma density
    (r / r_max)^(shape - 1) exp(-r / (scale r_max)): zero at r = 0 for shape > 1, a hump, then a
    tail (the play_core density decreases from r = 0)."""
    r = (np.arange(n) + 0.5) * r_max / n
    x = r / r_max
    w = x ** (shape - 1) * np.exp(-x / scale)
    return r, w / w.sum()


def _aging_integral(s, tau0, gamma, s0):
    """I(s) = int_0^s du / tau(u) for tau(u) = tau0 (1 + gamma ln(1 + u / s0)); with
    x = 1 + gamma ln(1 + u / s0) it is (s0 / (tau0 gamma)) e^(-1/gamma) [Ei(x / gamma) - Ei(1 / gamma)]."""
    x = 1 + gamma * np.log1p(np.asarray(s, float) / s0)
    return s0 / (tau0 * gamma) * np.exp(-1 / gamma) * (expi(x / gamma) - expi(1 / gamma))


def _aging_creep(h, dt, kappa, q, h_ref, tau0, gamma, s0):
    """Creep whose rate is proportional to its distance from its hold value, with a time constant
    that grows with the log of the time s since the load h last moved:

        dc/dt = (c_inf(h) - c) / tau(s),   tau(s) = tau0 (1 + gamma ln(1 + s / s0)),
        c_inf(h) = kappa h (1 + q |h| / h_ref)  (more creep per unit load at high loads),

    s restarting at 0 whenever h moves (a re-stressed material relaxes fast again: the aging of
    polymers and glasses, Struik 1978, and the stress-dependent creep of nonlinear viscoelastic
    solids, Findley et al. 1976, ch. 7). Exact for a held load: c <- c_inf + (c - c_inf)
    exp(-(I(s + dt) - I(s))) with I from :func:`_aging_integral`. Starts relaxed at 0.
    """
    h = np.asarray(h, float)
    target = kappa * h * (1 + q * np.abs(h) / h_ref)
    moved = np.concatenate([[False], h[1:] != h[:-1]])
    # the age at each sample (samples since the load last moved)
    idx = np.arange(len(h))
    last = np.maximum.accumulate(np.where(moved, idx, 0))
    age = idx - last
    I = _aging_integral(np.arange(age.max() + 2) * dt, tau0, gamma, s0)
    fac = np.exp(-(I[age + 1] - I[age]))
    c = 0.0
    out = np.empty_like(h)
    for k in range(len(h)):
        out[k] = c
        c = target[k] + (c - target[k]) * fac[k]
    return out


def _relaxing_duhem(v, dt, alpha, a, b, tau_r):
    """A Coleman-Hodgdon (Duhem) core that relaxes toward its anhysteretic line a v:

        dz/dt = alpha |dv/dt| (a v - z) + b dv/dt - (z - a v) / tau_r.

    Without the last term it is rate independent (Coleman & Hodgdon, Int. J. Eng. Sci. 24
    (1986); the major loop's branches approach a v -+ (a - b) / alpha); the thermal relaxation
    (magnetic viscosity, dielectric relaxation) closes the loop at slow drive, so that at a
    constant rate R the branches sit at a v -+ (a - b) / (alpha + 1 / (tau_r R)): the loop widens
    with the rate toward the rate-independent width. Exact per sample for a piecewise-linear v
    (the equation is linear in z); starts at z = a v[0]. Branches are monotone for b >= a / 2.
    """
    v = np.asarray(v, float)
    z = a * v[0]
    out = np.empty_like(v)
    out[0] = z
    for k in range(1, len(v)):
        s = (v[k] - v[k - 1]) / dt
        lam = alpha * abs(s) + 1 / tau_r
        shift = (a - b) * s / lam
        e = np.exp(-lam * dt)
        z = a * v[k] - shift + (z - (a * v[k - 1] - shift)) * e
        out[k] = z
    return out


def _warmup_and_ambient_step(t, a_warm, tau_warm, a_step, t_step, tau_step):
    """An offset: a warm-up a_warm (1 - exp(-t / tau_warm)) plus an ambient-temperature step at
    t_step seen through the stage's thermal time constant, a_step (1 - exp(-(t - t_step) / tau_step))
    after it (a first-order response to a step: continuous, unlike a slip)."""
    t = np.asarray(t, float)
    after = np.clip(t - t_step, 0.0, None)
    return a_warm * (1 - np.exp(-t / tau_warm)) + a_step * (1 - np.exp(-after / tau_step))


def _v_gain(t, depth, t_low, recovered=1.0):
    """1 - depth at t_low, falling linearly from 1 at t = 0 and rising linearly after to
    1 - depth (1 - recovered) at the end of t."""
    t = np.asarray(t, float)
    T = t[-1]
    down = t / t_low
    up = 1 - recovered * (t - t_low) / (T - t_low)
    return 1 - depth * np.where(t <= t_low, down, up)


def _generalized_plays(v, r, w, w0, up, down, state=None):
    """Generalized plays (Al Janaideh, Rakheja, Su, IEEE/ASME Trans. Mechatronics 16 (2011) 734):
    z_k = max(up(v) - r_k, min(down(v) + r_k, z_k)): a rising input pushes z_k along the rising
    envelope up(v) - r_k, a falling one along the falling envelope down(v) + r_k (needs
    up <= down + 2 r_k); y = w0 v + sum w_k z_k. up = down = identity is a PI core. From z = 0
    unless ``state``. `up` and `down` are functions of v."""
    v = np.asarray(v, float)
    gu, gd = up(v), down(v)
    z = np.zeros_like(r) if state is None else np.array(state, float)
    y = np.empty_like(v)
    for k in range(len(v)):
        z = np.maximum(gu[k] - r, np.minimum(gd[k] + r, z))
        y[k] = w0 * v[k] + w @ z
    return y


def _langevin_flux(h, v, a, j_s, mu):
    """B = mu H + J_s L(h / a): a linear reversible part (mu times the drive v) beside the core's
    irreversible state h, whose magnetisation saturates as a Langevin function (paramagnetic
    alignment, L(x) = coth x - 1 / x); the slope falls at the extremes to mu, not to 0."""
    return mu * np.asarray(v, float) + j_s * me.langevin(np.asarray(h, float) / a)


def _preload_modulated_plays(v, t, r, w, w0, depth, period, phase):
    """Plays whose thresholds follow an unmeasured preload F(t) = sin(2 pi t / period + phase):
    r_k (1 + depth F(t)) (stress pins domain walls harder, so the switching fields grow with a
    compressive preload), the reversible linear part w0 v unchanged: y = w0 v + sum w_k z_k,
    z_k = min(max(z_k, v - r_k(t)), v + r_k(t)). depth = 0 is a PI core. Returns y and F."""
    v = np.asarray(v, float)
    F = np.sin(2 * np.pi * np.asarray(t, float) / period + phase)
    z = np.zeros_like(r)
    y = np.empty_like(v)
    for k, vk in enumerate(v):
        rk = r * (1 + depth * F[k])
        z = np.minimum(np.maximum(z, vk - rk), vk + rk)
        y[k] = w0 * vk + w @ z
    return y, F


# ---- clean ----

@case
def clean_ring_down_bursts_640hz(seed):
    rng = _rng(seed, 1)
    dt, n = 1 / 640, 16_000
    v, bursts = _ring_downs(dt, n, rng, rng.uniform(44, 50))
    r, w = _gamma_density(45.0, rng.uniform(1.5, 2.5), rng.uniform(0.15, 0.3))
    w0 = rng.uniform(0.25, 0.45)
    y = rng.uniform(0.6, 1.6) * _plays(v, r, (1 - w0) * w, w0) + rng.uniform(-4, 4)
    rec = finish("holdout9_clean_ring_down_bursts_640hz", seed, np.arange(n) * dt, v, y, set(), "explained",
                 "a clean core (160 plays, a gamma density of thresholds) under damped sine bursts "
                 "restarted at random amplitudes, 640 Hz", rng, monitor_noise=3e-4)
    rec.extra.update(thresholds=r, weights=(1 - w0) * w, linear=w0, bursts=bursts)
    return rec


# ---- one effect ----

@case
def creep_aging_alternating_holds_200hz(seed):
    rng = _rng(seed, 2)
    dt = 1 / 200
    v, levels = _alternating_holds(dt, rng, 14, rng.uniform(3.5, 4.5), rng.uniform(0.3, 0.6))
    h = me.play_core(v, 100.0)
    p = dict(kappa=rng.uniform(0.06, 0.09), q=rng.uniform(0.3, 0.6), h_ref=np.abs(h).max(),
             tau0=rng.uniform(0.25, 0.4), gamma=rng.uniform(2.0, 3.5), s0=rng.uniform(0.02, 0.04))
    y = h + _aging_creep(h, dt, **p)
    rec = finish("holdout9_creep_aging_alternating_holds_200hz", seed, np.arange(len(v)) * dt, v, y, {"creep"},
                 "either", "creep toward a load-dependent hold value with a time constant growing with "
                 "log time, holds alternating low and high on a unipolar stroke, 200 Hz", rng)
    rec.extra.update(levels=levels, **p)
    return rec


@case
def rate_relaxing_duhem_shuffled_triangles(seed):
    rng = _rng(seed, 3)
    dt = 1 / 1600
    freqs = np.array([rng.uniform(0.35, 0.5), rng.uniform(1.2, 1.8), rng.uniform(4.0, 6.0), rng.uniform(11.0, 15.0)])
    amp = rng.uniform(42, 48)
    v, edges, played = _shuffled_triangles(dt, freqs, amp, rng)
    p = dict(alpha=rng.uniform(0.06, 0.09), a=1.0, b=rng.uniform(0.55, 0.65), tau_r=rng.uniform(0.06, 0.12))
    gain = rng.uniform(0.8, 1.3)
    y = gain * _relaxing_duhem(v, dt, **p)
    rec = finish("holdout9_rate_relaxing_duhem_shuffled_triangles", seed, np.arange(len(v)) * dt, v, y,
                 {"rate_dependence"}, "either",
                 "a Duhem core relaxing toward its anhysteretic line (tau %.0f ms) under triangles at "
                 "%s Hz in a shuffled order, 1.6 kHz" % (1e3 * p["tau_r"], ", ".join(f"{f:.2f}" for f in freqs)),
                 rng, monitor_noise=2e-4)
    rec.extra.update(freqs=played, segments=edges, amp=amp, gain=gain, drive=v, **p)
    return rec


@case
def drift_warmup_ambient_step_random(seed):
    rng = _rng(seed, 4)
    dt, n = 1 / 480, 14_400
    t = np.arange(n) * dt
    v = ex.bandlimited_random(dt, n, rng.uniform(1.5, 3.0), rng.uniform(42, 48), rng=rng)
    h = me.play_core(v, 100.0)
    span = np.ptp(h)
    p = dict(a_warm=rng.choice([-1.0, 1.0]) * rng.uniform(0.03, 0.05) * span, tau_warm=rng.uniform(3.0, 6.0),
             a_step=rng.choice([-1.0, 1.0]) * rng.uniform(0.03, 0.05) * span, t_step=rng.uniform(0.4, 0.6) * t[-1],
             tau_step=rng.uniform(1.5, 3.5))
    off = _warmup_and_ambient_step(t, **p)
    y = h + off
    rec = finish("holdout9_drift_warmup_ambient_step_random", seed, t, v, y, {"drift"}, "either",
                 "an exponential warm-up plus an ambient step mid-record through a thermal time constant, "
                 "band-limited random drive, 480 Hz", rng, monitor_noise=4e-4)
    rec.extra.update(offset=off, **p)
    return rec


@case
def gain_drift_v_shape_sine_bursts(seed):
    rng = _rng(seed, 5)
    dt = 1 / 900
    f = rng.uniform(1.5, 3.0)
    v = _sine_bursts(dt, f, int(rng.integers(4, 7)), rng.uniform(40, 48), 12, rng.uniform(0.4, 0.8))
    t = np.arange(len(v)) * dt
    depth = rng.uniform(0.03, 0.08)
    t_low = rng.uniform(0.35, 0.65) * t[-1]
    gain = _v_gain(t, depth, t_low, recovered=rng.uniform(0.75, 1.0))
    y = gain * me.play_core(v, 100.0)
    rec = finish("holdout9_gain_drift_v_shape_sine_bursts", seed, t, v, y, {"gain_drift"}, "either",
                 f"a gain falling linearly by {depth:.1%} and recovering (a V in time), constant-amplitude "
                 "sine bursts, 900 Hz", rng)
    rec.extra.update(gain=gain, depth=depth, t_low=t_low)
    return rec


@case
def asymmetry_generalized_plays_unipolar_staircase(seed):
    rng = _rng(seed, 6)
    dt = 1 / 1100
    v, pts = _triangle_staircase(dt, rng)
    q = rng.uniform(0.2, 0.35)
    r, w = me._density_thresholds(100.0, 150)
    w = w / w.sum()
    w0 = rng.uniform(0.3, 0.4)

    def up(x):
        return (1 - q) * x + q * x ** 2 / 100.0

    def down(x):
        return x

    y = _generalized_plays(v, r, (1 - w0) * w, w0, up, down)
    rec = finish("holdout9_asymmetry_generalized_plays_unipolar_staircase", seed, np.arange(len(v)) * dt, v, y,
                 {"asymmetry"}, "either",
                 f"generalized plays (rising envelope (1 - {q:.2f}) v + {q:.2f} v^2 / 100, falling v) under a "
                 "unipolar triangle staircase, 1.1 kHz", rng, monitor_noise=3e-4)
    rec.extra.update(q=q, linear=w0, thresholds=r, weights=(1 - w0) * w, extremes=pts)
    return rec


@case
def saturation_langevin_flux_growing_sine(seed):
    rng = _rng(seed, 7)
    dt, n = 1 / 700, 16_800
    v = _geometric_growing_sine(dt, n, rng.uniform(1.5, 2.5), rng.uniform(45, 50))
    h = me.play_core(v, 100.0)
    a = np.abs(h).max() / rng.uniform(2.5, 4.0)
    j_s = 3 * a * rng.uniform(0.9, 1.1)          # the irreversible part's slope at 0 about that of h
    mu = rng.uniform(0.12, 0.22)
    y = _langevin_flux(h, v, a, j_s, mu)
    rec = finish("holdout9_saturation_langevin_flux_growing_sine", seed, np.arange(n) * dt, v, y,
                 {"saturation"}, "either",
                 "B = mu H + J_s L(h / a): a Langevin saturation of the irreversible part beside a linear "
                 "one, a sine growing geometrically from 12 % to full amplitude, 700 Hz", rng)
    rec.extra.update(a=a, j_s=j_s, mu=mu)
    return rec


@case
def delay_acquisition_latency_prbs_2khz(seed):
    rng = _rng(seed, 8)
    dt, n, over = 1 / 2000, 16_000, 4
    m = int(rng.integers(10, 25))                 # the latency in quarter samples: 2.5 ... 6 samples
    v_fine = _smoothed_prbs(dt / over, over * n, rng, rng.uniform(42, 48), rng.uniform(0.06, 0.1),
                            rng.uniform(0.008, 0.015))
    y_fine = me.play_core(v_fine, 100.0)
    k = over * np.arange(n)
    v = v_fine[k]
    y = y_fine[np.maximum(k - m, 0)]              # the output converted m / 4 samples late
    rec = finish("holdout9_delay_acquisition_latency_prbs_2khz", seed, np.arange(n) * dt, v, y, {"delay"},
                 "explained", f"an acquisition latency of {m / over:.2f} samples under a smoothed "
                 "pseudo-random binary staircase (PRBS9), 2 kHz", rng, monitor_noise=2e-4)
    rec.extra["delay_samples"] = m / over
    return rec


# ---- two effects ----

@case
def pair_initial_state_drift_random_triangles(seed):
    rng = _rng(seed, 9)
    sign = rng.choice([-1.0, 1.0])
    far, level = sign * rng.uniform(52, 58), -sign * rng.uniform(5, 20)
    pre = np.concatenate([np.linspace(0, far, 400, endpoint=False), np.linspace(far, level, 400)])
    _, z = me.play_core(pre, 100.0, return_state=True)
    dt = 1 / 1350
    v, pts = _random_triangles(dt, rng, level, 24)
    t = np.arange(len(v)) * dt
    h = me.play_core(v, 100.0, state=z)
    slope = rng.choice([-1.0, 1.0]) * rng.uniform(0.03, 0.05) * np.ptp(h) / t[-1]
    off = slope * t
    y = h + off
    rec = finish("holdout9_pair_initial_state_drift_random_triangles", seed, t, v, y, {"initial_state", "drift"},
                 "either", "a core left by one large excursion and a return to a level where the record "
                 "starts, a slow linear thermal offset, random triangles, 1.35 kHz", rng, monitor_noise=3e-4)
    rec.extra.update(preload=pre, offset=off, extremes=pts)
    return rec


# ---- out of vocabulary ----

@case
def oov_preload_modulated_width_keyed_sine(seed):
    rng = _rng(seed, 10)
    dt = 1 / 350
    f = rng.uniform(1.0, 1.4)
    groups = rng.integers(2, 5, int(np.ceil(30 * f / 3)))       # 2 ... 4 cycles a group: keyed out of step
    v = _keyed_sine(dt, f, rng.uniform(44, 48), rng.uniform(0.55, 0.7), groups)
    t = np.arange(len(v)) * dt
    r, w = me._density_thresholds(100.0, 150, r_max_fraction=0.35)     # 2 r (1 + depth) below the amplitude
    w = w / w.sum()
    depth = rng.uniform(0.35, 0.5)
    period = rng.uniform(9.0, 14.0)
    y, F = _preload_modulated_plays(v, t, r, 0.65 * w, 0.35, depth, period, rng.uniform(0, 2 * np.pi))
    rec = finish("holdout9_oov_preload_modulated_width_keyed_sine", seed, t, v, y, set(), "unexplained",
                 f"plays whose thresholds follow an unmeasured preload (1 +- {depth:.2f}, period {period:.1f} s), "
                 "an amplitude-keyed sine, 350 Hz", rng)
    rec.extra.update(preload=F, depth=depth, period=period, freq=f, groups=groups, thresholds=r, weights=0.65 * w)
    return rec

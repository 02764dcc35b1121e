"""The HOLDOUT11 set: written after HOLDOUT10 was measured (2026-11-25, eleventh round), to be run once
for the eleventh round's final measurement (docs/diagnose.md); kept out of ALL until then.

Mechanisms and signals that the other sets do not have, or not in these combinations:

- a clean core (150 plays written here from the play's definition, with a bimodal density of
  thresholds: a narrow Gaussian hump at 3 ... 8 V beside a wide one at 18 ... 28 V, a drawn linear
  part, gain and offset) under a smoothed multilevel random telegraph signal (three telegraph
  processes of 0.3 ... 4 switches per second and unequal heights, summed, through an amplifier's two
  first-order lags of 25 ... 60 ms) on a unipolar stroke from rest at 0 V, sampled at 1.1 kHz;
- creep with a Kohlrausch-Williams-Watts (stretched-exponential) compliance: the step response
  c (1 - exp(-(t / tau)^beta)) (c 0.06 ... 0.1, tau 0.8 ... 3 s, beta 0.35 ... 0.6; Kohlrausch,
  Ann. Phys. 167 (1854) 179; Williams & Watts, Trans. Faraday Soc. 66 (1970) 80), applied to the
  core's output by Boltzmann superposition (a convolution of its increments with the step response,
  by FFT), under trapezoids of alternating sign whose dwells are drawn log-uniformly in
  0.3 ... 6 s, sampled at 280 Hz;
- plays with Bertotti's excess-field law: beyond its threshold a play moves at dz/dt = (e / delta)^2
  (e the overstress), i.e. the overstress is delta sqrt(dz/dt), the sqrt(dB/dt) excess field of the
  statistical theory of losses (Bertotti, IEEE Trans. Magn. 24 (1988) 621), integrated exactly per
  sample (e -> e / (1 + |e| dt / delta^2)), so that the loop widens as the square root of the rate,
  under an exponential chirp from 0.1 ... 0.15 Hz to 10 ... 14 Hz whose amplitude decays
  exponentially from 46 ... 50 V to 0.55 ... 0.7 of that, sampled at 1.9 kHz;
- a sensor baseline with a 1/f (flicker) spectrum: the McWhorter superposition of ten
  Ornstein-Uhlenbeck processes of equal variance with relaxation times spread log-uniformly over
  0.3 ... 300 s (McWhorter, in *Semiconductor Surface Physics*, 1957; a Lorentzian per trap,
  log-uniform corners sum to 1/f), each started from its stationary law, scaled to 4 ... 7 % of the
  span, under a staircase of random levels (holds of 1.5 ... 3.5 s, raised-cosine steps) with a
  one-sided sine dither of 6 ... 12 V at 2 ... 4 Hz, on a unipolar stroke, sampled at 660 Hz;
- asymmetry from electrostriction of a poled ferroelectric: the strain is Q P^2 with P = P_r + p,
  p the core's (hysteretic) polarisation change, so the output is p + p^2 / (2 P_r) (Damjanovic,
  Rep. Prog. Phys. 61 (1998) 1267: the piezoelectric coefficient of a poled ceramic, 2 Q eps P_r,
  is electrostriction biased by the remanent polarisation), max |p| / (2 P_r) 0.08 ... 0.14,
  under a sine whose frequency sweeps up log-uniformly from 0.3 ... 0.4 Hz to 2.5 ... 3.5 Hz
  with holds of 0.1 ... 0.3 s at every peak and peaks of drawn heights (0.6 ... 1 of 44 ... 50 V),
  sampled at 1.7 kHz;
- output saturation of an optical lever on a quadrant photodiode: the normalised difference signal
  of a Gaussian spot is erf(sqrt(2) x / w) (x the spot's displacement, w its 1/e^2 radius), here
  (b sqrt(pi) / 2) erf(h / b) (slope 1 at h = 0), compressing the core's extremes by 10 ... 20 %,
  under one axis of a spiral scan: an Archimedean spiral at constant angular velocity (3 ... 5 Hz)
  near the centre and constant linear velocity outside (the edge turn at 0.5 ... 0.8 Hz; Mahmood &
  Moheimani, Nanotechnology 20 (2009) 365503), 12 ... 18 turns out to 45 ... 55 V and back in
  with the same sense of rotation, sampled at 560 Hz;
- a transport delay of the air line of a pneumatic muscle: the pressure command reaches the
  muscle after L / c (L 2 ... 5 m, c 343 m/s: 5.8 ... 14.6 ms, 2.3 ... 5.8 samples; a lossless line,
  only the wave's travel time), the core evaluated on the command at t - L / c, under a slow
  raised-cosine sine (0.15 ... 0.3 Hz) with a fast one (2.5 ... 4.5 Hz, 8 ... 14 V) on top, on a
  unipolar stroke from 0, sampled at 400 Hz;
- a core left by an unrecorded sinusoidal run (3 ... 5 cycles of +-44 ... 52 V) stopped mid-cycle
  on the rise out of a trough (at 0.5 ... 0.94 of the amplitude), after which the stack discharged
  through its bleed resistor (v_stop exp(-t / RC), RC 0.3 ... 1 s) to 4 ... 12 % of that, where the
  record starts, before half-sine pulses of alternating sign and geometrically growing height
  (6 V to just beyond the run's amplitude) on that base, sampled at 880 Hz;
- two effects: a gain from self-heating by the hysteresis loss (each play dissipates w r |dz|, the
  friction work of a Prandtl element; a first-order thermal body of 4 ... 10 s heated by that power,
  the gain 1 + beta theta rising by 3 ... 6 % at the hottest) and a delay of a DAC (one sample of
  computation latency, a zero-order hold and a 2nd-order Bessel reconstruction filter of
  0.6 ... 1.5 samples' group delay: 2.1 ... 3 samples in all), under a two-tone beat (2 ... 4 Hz, the
  beat period 8 ... 16 s), sampled at 1.3 kHz;
- out of vocabulary: stress-controlled cyclic plasticity with Armstrong-Frederick nonlinear kinematic
  hardening (a yield band +-sigma_y about a backstress alpha, dalpha = C deps_p - gamma alpha |deps_p|;
  Armstrong & Frederick, CEGB report RD/B/N731 (1966), Mater. High Temp. 24 (2007) 1; Chaboche,
  Int. J. Plast. 5 (1989) 247), strain = stress / E + eps_p, integrated exactly per sample, under
  blocks of 6 ... 9 sine cycles about means of +m, -m and 0 (m 4 ... 8 V) in a shuffled order, each
  block followed by a hold of 1 ... 2 s at its mean, sampled at 360 Hz. Each biased cycle leaves a net
  plastic strain (1 / gamma) ln((C^2 - gamma^2 a^2) / (C^2 - gamma^2 b^2)) (a, b the backstress at the
  cycle's ends: ratcheting), so the return point walks in the direction of the block's mean, cycle
  after cycle, stays where it is in the symmetric blocks and during every hold. A PI core (any plays,
  with any rate, creep, offset, gain, saturation, asymmetry, delay or initial-state part) returns to
  the same output at every return to the level (return-point memory); creep would move during the
  holds and relax back during the symmetric blocks, and no drift in time follows the block means.
"""

import numpy as np
from scipy.optimize import brentq
from scipy.signal import bessel, cont2discrete, fftconvolve, lfilter, lfilter_zi
from scipy.special import erf

from . import mechanisms as me
from .record import case_set, finish

HOLDOUT11, case, _rng = case_set("holdout11_", 11000)


# ---- signals not in excitations.py ----

def _lag2(x, dt, tau):
    """x through two first-order lags of time constant tau (y_k = a y_(k-1) + (1 - a) x_k each), from 0."""
    a = np.exp(-dt / tau)
    return lfilter([1 - a], [1, -a], lfilter([1 - a], [1, -a], x))


def _smoothed_telegraph(dt, n, rates, heights, tau, rng):
    """sum_i h_i s_i(t), s_i a random telegraph process in {0, 1} (a flip with probability lambda_i dt per
    sample, 0 at t = 0), through an amplifier's two first-order lags tau. Returns the drive and the sum."""
    flips = rng.random((n, len(rates))) < np.asarray(rates) * dt
    flips[0] = False
    levels = (np.cumsum(flips, axis=0) % 2) @ np.asarray(heights, float)
    return _lag2(levels, dt, tau), levels


def _dwell_trapezoids(dt, rng, min_s, level, ramp_rate, dwell_s):
    """From 0 V, linear ramps (ramp_rate V/s) to plateaus of alternating sign (the first drawn, magnitudes
    drawn in `level`), each held for a dwell drawn log-uniformly in dwell_s, until min_s seconds have
    passed; then a ramp back to 0 V and a last dwell there. Returns the signal and the dwells' (start,
    stop) indices."""
    sign = rng.choice([-1.0, 1.0])
    parts, dwells, pos, cur, j = [np.zeros(1)], [], 1, 0.0, 0
    while cur != 0.0 or j == 0:
        lv = sign * (-1) ** j * rng.uniform(*level) if pos * dt < min_s else 0.0
        j += 1
        m = max(int(round(abs(lv - cur) / ramp_rate / dt)), 2)
        parts.append(np.linspace(cur, lv, m + 1)[1:])
        pos += m
        nh = int(round(np.exp(rng.uniform(*np.log(dwell_s))) / dt))
        parts.append(np.full(nh, lv))
        dwells.append((pos, pos + nh))
        pos += nh
        cur = lv
    return np.concatenate(parts), dwells


def _exp_chirp(dt, n, f0, f1, amp0, amp1):
    """An exponential chirp amp(t) sin(2 pi f0 T (k^(t/T) - 1) / ln k), k = f1 / f0, T = n dt: the
    instantaneous frequency f0 k^(t/T), the amplitude amp0 (amp1 / amp0)^(t/T). Returns it and the
    instantaneous frequency."""
    t = np.arange(n) * dt
    T, k = n * dt, f1 / f0
    x = t / T
    phase = 2 * np.pi * f0 * T * (k ** x - 1) / np.log(k)
    return amp0 * (amp1 / amp0) ** x * np.sin(phase), f0 * k ** x


def _dithered_staircase(dt, rng, n_levels, hold_s, step_s, dither, f_dither, top=100.0):
    """Levels (0 V first, then drawn in 0 ... top - dither - 2) held for hold_s each (drawn), joined by
    raised-cosine steps of step_s, plus a one-sided dither dither (1 - cos(2 pi f t)) / 2: >= 0, 0 at t = 0.
    Returns the signal and the level path."""
    levels = np.r_[0.0, rng.uniform(0.0, top - dither - 2.0, n_levels)]
    ms = int(round(step_s / dt))
    s = (1 - np.cos(np.pi * np.arange(1, ms + 1) / ms)) / 2
    parts = []
    for a, b in zip(levels[:-1], levels[1:]):
        parts.append(np.full(int(round(rng.uniform(*hold_s) / dt)), a))
        parts.append(a + (b - a) * s)
    parts.append(np.full(int(round(rng.uniform(*hold_s) / dt)), levels[-1]))
    path = np.concatenate(parts)
    t = np.arange(len(path)) * dt
    return path + dither * (1 - np.cos(2 * np.pi * f_dither * t)) / 2, path


def _peak_hold_sweep(dt, rng, f0, f1, n_half, amp, frac, hold_s):
    """Half cycles of a sine (raised-cosine moves from peak to peak, each of half a period of
    f0 (f1 / f0)^(k / (n_half - 1))) between peaks of alternating sign and heights drawn in frac x amp,
    a hold drawn in hold_s at every peak; from 0 V and back to it. Returns the signal and the holds'
    (start, stop) indices."""
    sign = rng.choice([-1.0, 1.0])
    freqs = f0 * (f1 / f0) ** (np.arange(n_half) / (n_half - 1))
    peaks = [sign * (-1) ** k * amp * rng.uniform(frac, 1.0) for k in range(n_half)] + [0.0]
    parts, holds, pos, cur = [np.zeros(1)], [], 1, 0.0
    for k, p in enumerate(peaks):
        m = int(round(1 / (2 * freqs[min(k, n_half - 1)]) / dt))
        parts.append(cur + (p - cur) * (1 - np.cos(np.pi * np.arange(1, m + 1) / m)) / 2)
        pos += m
        nh = int(round(rng.uniform(*hold_s) / dt))
        parts.append(np.full(nh, p))
        holds.append((pos, pos + nh))
        pos += nh
        cur = p
    return np.concatenate(parts), holds[:-1]


def _spiral_scan(dt, amp, turns, f_max, f_edge):
    """One axis of an Archimedean spiral r = p theta / (2 pi), p = amp / turns: constant angular velocity
    2 pi f_max while r < V / (2 pi f_max), constant linear velocity V = 2 pi amp f_edge outside
    (theta = sqrt(theta0^2 + 4 pi V (t - t0) / p)), out to r = amp, then in again with the same sense of
    rotation (theta_in(t) = 2 theta_end - theta_out(T - t)). Returns x = r cos(theta), r and theta."""
    p, V, w = amp / turns, 2 * np.pi * amp * f_edge, 2 * np.pi * f_max
    th0 = 2 * np.pi * (V / w) / p
    th_end = 2 * np.pi * turns
    t0 = th0 / w
    T = t0 + p * (th_end ** 2 - th0 ** 2) / (4 * np.pi * V)
    t = np.arange(int(np.floor(T / dt)) + 1) * dt
    th = np.where(t < t0, w * t, np.sqrt(th0 ** 2 + 4 * np.pi * V * np.maximum(t - t0, 0) / p))
    th = np.r_[th, 2 * th_end - th[::-1][1:]]
    r = p * np.r_[th[:len(t)], th[:len(t)][::-1][1:]] / (2 * np.pi)
    return r * np.cos(th), r, th


def _sine_on_sine(t, c_slow, f_slow, a_fast, f_fast):
    """c_slow (1 - cos(2 pi f_slow t)) + a_fast (1 - cos(2 pi f_fast t)) for t >= 0, 0 before (at rest)."""
    t = np.maximum(np.asarray(t, float), 0.0)
    return c_slow * (1 - np.cos(2 * np.pi * f_slow * t)) + a_fast * (1 - np.cos(2 * np.pi * f_fast * t))


def _growing_pulses(dt, rng, base, n_pulses, h0, h1, width_s, gap_s):
    """Half-sine pulses base + s_k h_k sin(pi u) of alternating sign (the first drawn), heights growing
    geometrically from h0 to h1, widths and gaps (at base) drawn; starts and ends with a gap."""
    sign = rng.choice([-1.0, 1.0])
    heights = np.r_[h0 * (h1 / h0) ** (np.arange(n_pulses - 1) / (n_pulses - 2)), h1]
    parts = [np.full(int(round(rng.uniform(*gap_s) / dt)), base)]
    for k, h in enumerate(heights):
        m = int(round(rng.uniform(*width_s) / dt))
        parts.append(base + sign * (-1) ** k * h * np.sin(np.pi * np.arange(1, m + 1) / (m + 1)))
        parts.append(np.full(int(round(rng.uniform(*gap_s) / dt)), base))
    return np.concatenate(parts)


def _mean_blocks(dt, rng, means, amp, cycles, freq, hold_s, ramp_rate):
    """From 0 V, for each mean m: a ramp to m, a hold, whole cycles m + amp sin(2 pi k / per) (returning to
    m after each), a hold at m. Returns the signal and per block (m, train start, stop, samples per cycle,
    the index where the hold after it ends)."""
    parts, blocks, pos, cur = [np.zeros(1)], [], 1, 0.0
    for mu in means:
        nr = max(int(round(abs(mu - cur) / ramp_rate / dt)), 2)
        parts.append(np.linspace(cur, mu, nr + 1)[1:])
        nh = int(round(rng.uniform(*hold_s) / dt))
        parts.append(np.full(nh, mu))
        pos += nr + nh
        c, per = int(rng.integers(*cycles)), int(round(1 / rng.uniform(*freq) / dt))
        parts.append(mu + amp * np.sin(2 * np.pi * np.arange(c * per) / per))
        nh2 = int(round(rng.uniform(*hold_s) / dt))
        parts.append(np.full(nh2 + 1, mu))
        blocks.append((mu, pos, pos + c * per, per, pos + c * per + nh2))
        pos += c * per + nh2 + 1
        cur = mu
    return np.concatenate(parts), blocks


# ---- mechanisms not in mechanisms.py ----

def _plays(v, r, w, w0, state=0.0, loss=False):
    """y = w0 v + sum_k w_k z_k, z_k the play of threshold r_k: z_k(t) = min(max(z_k(t-), v(t) - r_k),
    v(t) + r_k) (Brokate & Sprekels 1996, sec. 2.3), from the given state. With loss=True also the energy
    each sample dissipates, sum_k w_k r_k |dz_k| (the friction work of a Prandtl element of yield r_k)."""
    v = np.asarray(v, float)
    z = np.broadcast_to(np.asarray(state, float), r.shape).copy()
    y, q = np.empty_like(v), np.zeros_like(v)
    wr = w * r
    for k, vk in enumerate(v):
        zn = np.minimum(np.maximum(z, vk - r), vk + r)
        if loss:
            q[k] = wr @ np.abs(zn - z)
        z = zn
        y[k] = w0 * vk + w @ z
    return (y, q) if loss else y


def _grid(r_max, n):
    """n thresholds evenly spaced in (0, r_max]."""
    return (np.arange(n) + 0.5) * r_max / n


def _kww_creep(u, dt, c, tau, beta):
    """Creep with the stretched-exponential compliance c (1 - exp(-(t / tau)^beta)), by Boltzmann
    superposition: sum_(j <= k) du_j K((k - j) dt) with du_j = u_j - u_(j-1) (du_0 = 0: relaxed at u_0),
    K(0) = 0; an FFT convolution."""
    u = np.asarray(u, float)
    du = np.diff(u, prepend=u[0])
    K = c * -np.expm1(-(np.arange(len(u)) * dt / tau) ** beta)
    return fftconvolve(du, K)[:len(u)]


def _excess_field_plays(v, dt, r, w, w0, delta):
    """Plays with Bertotti's excess-field law: outside its band a play moves at dz/dt = sign(e) (e / delta)^2,
    e = v - r - z above the band, v + r - z below it; for the input held over a sample that is de/dt =
    -sign(e) e^2 / delta^2, solved exactly: e -> e / (1 + |e| dt / delta^2). delta -> 0 is the play."""
    v = np.asarray(v, float)
    z = np.zeros_like(r)
    y = np.empty_like(v)
    k2 = dt / delta ** 2
    for k, vk in enumerate(v):
        up, dn = vk - r - z, vk + r - z
        e = np.where(up > 0, up, np.where(dn < 0, dn, 0.0))
        z = z + e - e / (1 + np.abs(e) * k2)
        y[k] = w0 * vk + w @ z
    return y


def _flicker_baseline(n, dt, taus, rng):
    """The McWhorter sum of unit-variance Ornstein-Uhlenbeck processes with relaxation times taus, each
    exact per sample (x_k = a x_(k-1) + sqrt(1 - a^2) xi_k, a = exp(-dt / tau)) and started from its
    stationary law N(0, 1). Returns the sum (n samples)."""
    out = np.zeros(n)
    for tau in taus:
        a = np.exp(-dt / tau)
        x0 = rng.standard_normal()
        out += lfilter([np.sqrt(1 - a * a)], [1, -a], rng.standard_normal(n), zi=[a * x0])[0]
    return out


def _electrostrictive(p, p_r):
    """Strain of a poled ferroelectric, Q ((P_r + p)^2 - P_r^2) / (2 Q P_r) = p + p^2 / (2 P_r)."""
    p = np.asarray(p, float)
    return p + p ** 2 / (2 * p_r)


def _quadrant_detector(h, b):
    """A quadrant photodiode's normalised difference for a Gaussian spot displaced by h: erf(h / b)
    (b = w / sqrt(2)), scaled by b sqrt(pi) / 2 to slope 1 at h = 0."""
    return b * np.sqrt(np.pi) / 2 * erf(np.asarray(h, float) / b)


def _dac_bessel(v, dt, group_delay, latency=1):
    """The actuator's voltage from a DAC: the command of `latency` samples before, held (zero-order hold)
    through a 2nd-order analog Bessel reconstruction filter whose group delay at DC is group_delay s;
    the held input makes the ZOH discretisation exact at the sampling instants. From rest at v[0]."""
    b, a = bessel(2, 1 / group_delay, analog=True, norm="delay")
    bz, az, _ = cont2discrete((b, a), dt, method="zoh")
    bz = np.ravel(bz)
    u = np.r_[np.full(latency, v[0]), np.asarray(v, float)[:-latency]]
    return lfilter(bz, az, u, zi=lfilter_zi(bz, az) * v[0])[0]


def _thermal(power, dt, tau):
    """A first-order thermal body heated by `power` (per sample, held over it): theta_(k+1) = a theta_k +
    (1 - a) P_k, a = exp(-dt / tau), from 0 (the temperature rise, in units of P x thermal resistance)."""
    a = np.exp(-dt / tau)
    return np.r_[0.0, lfilter([1 - a], [1, -a], power)[:-1]]


def _armstrong_frederick(s, E, sigma_y, C, gamma):
    """Strain under a stress path s: s / E + eps_p, with a yield band |s - alpha| <= sigma_y about the
    backstress alpha, dalpha = C deps_p - gamma alpha |deps_p| (nonlinear kinematic hardening). In plastic
    flow of sign d the stress drags alpha to s - d sigma_y and deps_p = dalpha / (C - d gamma alpha), so
    eps_p gains (d / gamma) ln((C - d gamma alpha_0) / (C - d gamma alpha_1)), exact per sample (alpha
    moves monotonically within it). From the virgin state (alpha = eps_p = 0)."""
    s = np.asarray(s, float)
    out = np.empty_like(s)
    alpha = ep = 0.0
    for k, sk in enumerate(s):
        if sk - alpha > sigma_y:
            a1 = sk - sigma_y
            ep += np.log1p(gamma * (a1 - alpha) / (C - gamma * a1)) / gamma
            alpha = a1
        elif sk - alpha < -sigma_y:
            a1 = sk + sigma_y
            ep -= np.log1p(gamma * (alpha - a1) / (C + gamma * a1)) / gamma
            alpha = a1
        out[k] = sk / E + ep
    return out


# ---- clean ----

@case
def clean_smoothed_telegraph_levels_1100hz(seed):
    rng = _rng(seed, 1)
    dt = 1 / 1100
    n = int(round(rng.uniform(18.0, 26.0) / dt))
    total = rng.uniform(82.0, 95.0)
    heights = total * np.array([0.5, 0.3, 0.2])
    rates = [rng.uniform(0.3, 0.6), rng.uniform(0.8, 1.5), rng.uniform(2.0, 4.0)]
    tau = rng.uniform(0.025, 0.06)
    v, levels = _smoothed_telegraph(dt, n, rates, heights, tau, rng)
    r = _grid(45.0, 150)
    m1, m2 = rng.uniform(3.0, 8.0), rng.uniform(18.0, 28.0)
    p1 = rng.uniform(0.3, 0.5)
    dens = (p1 * np.exp(-((r - m1) / rng.uniform(2.0, 3.0)) ** 2 / 2)
            + (1 - p1) * np.exp(-((r - m2) / rng.uniform(5.0, 8.0)) ** 2 / 2))
    w0 = rng.uniform(0.25, 0.45)
    gain, off = rng.uniform(0.6, 1.6), rng.uniform(-5.0, 5.0)
    weights = gain * (1 - w0) * dens / dens.sum()
    y = _plays(v, r, weights, gain * w0, 0.0) + off
    rec = finish("holdout11_clean_smoothed_telegraph_levels_1100hz", seed, np.arange(n) * dt, v, y, set(),
                 "explained", f"a clean core (150 plays, a bimodal threshold density, humps at {m1:.0f} and "
                 f"{m2:.0f} V) "
                 "under three smoothed random telegraph processes summed, 0 ... 100 V, 1.1 kHz", rng,
                 monitor_noise=3e-4)
    rec.extra.update(thresholds=r, weights=weights, linear=gain * w0, offset=off, levels=levels, heights=heights,
                     rates=rates, tau=tau, drive=v)
    return rec


# ---- one effect ----

@case
def creep_kww_stretched_exponential_dwell_trapezoids_280hz(seed):
    rng = _rng(seed, 2)
    dt = 1 / 280
    v, dwells = _dwell_trapezoids(dt, rng, rng.uniform(32.0, 48.0), (30.0, 50.0), rng.uniform(80.0, 150.0),
                                  (0.3, 6.0))
    h = me.play_core(v, 100.0)
    p = dict(c=rng.uniform(0.07, 0.11), tau=rng.uniform(0.8, 3.0), beta=rng.uniform(0.35, 0.6))
    y = h + _kww_creep(h, dt, **p)
    rec = finish("holdout11_creep_kww_stretched_exponential_dwell_trapezoids_280hz", seed, np.arange(len(v)) * dt, v,
                 y, {"creep"}, "either",
                 f"stretched-exponential (KWW, beta {p['beta']:.2f}) creep by Boltzmann superposition, trapezoids of "
                 "alternating sign with log-uniform dwells of 0.3 ... 6 s, 280 Hz", rng)
    rec.extra.update(dwells=dwells, **p)
    return rec


@case
def rate_bertotti_excess_field_decaying_exp_chirp_1900hz(seed):
    rng = _rng(seed, 3)
    dt = 1 / 1900
    n = int(round(rng.uniform(13.0, 18.0) / dt))
    amp0 = rng.uniform(46.0, 50.0)
    v, finst = _exp_chirp(dt, n, rng.uniform(0.1, 0.15), rng.uniform(10.0, 14.0), amp0,
                          amp0 * rng.uniform(0.55, 0.7))
    r = _grid(0.7 * amp0, 120)
    w = np.full(120, rng.uniform(0.55, 0.7) / 120)
    w0 = 1 - w.sum()
    delta, gain = rng.uniform(0.07, 0.1), rng.uniform(0.8, 1.3)
    y = gain * _excess_field_plays(v, dt, r, w, w0, delta)
    rec = finish("holdout11_rate_bertotti_excess_field_decaying_exp_chirp_1900hz", seed, np.arange(n) * dt, v, y,
                 {"rate_dependence"}, "either",
                 f"plays with Bertotti's excess field (overstress {delta:.3f} sqrt(dz/dt)), an exponential chirp "
                 f"{finst[0]:.2f} ... {finst[-1]:.1f} Hz with a decaying amplitude, 1.9 kHz", rng, monitor_noise=2e-4)
    rec.extra.update(delta=delta, gain=gain, thresholds=r, weights=w, linear=w0, inst_freq=finst, drive=v)
    return rec


@case
def drift_flicker_baseline_dithered_staircase_660hz(seed):
    rng = _rng(seed, 4)
    dt = 1 / 660
    dither = rng.uniform(6.0, 12.0)
    v, path = _dithered_staircase(dt, rng, int(rng.integers(12, 17)), (1.5, 3.5), rng.uniform(0.06, 0.12), dither,
                                  rng.uniform(2.0, 4.0))
    n = len(v)
    gain = rng.uniform(0.7, 1.4)
    h = me.play_core(v, 100.0, gain=gain)
    taus = np.geomspace(0.3, 300.0, 10)
    b = _flicker_baseline(n, dt, taus, rng)
    b -= b[0]
    frac = rng.uniform(0.04, 0.07)
    off = frac * np.ptp(h) * b / np.ptp(b)
    y = h + off
    rec = finish("holdout11_drift_flicker_baseline_dithered_staircase_660hz", seed, np.arange(n) * dt, v, y, {"drift"},
                 "either", f"a 1/f sensor baseline (ten Ornstein-Uhlenbeck processes, 0.3 ... 300 s; {frac:.1%} of "
                 "the span), a staircase of random levels with a sine dither, 0 ... 100 V, 660 Hz", rng)
    rec.extra.update(offset=off, gain=gain, taus=taus, frac=frac, path=path, dither=dither)
    return rec


@case
def asymmetry_electrostrictive_poled_peak_hold_sweep_1700hz(seed):
    rng = _rng(seed, 5)
    dt = 1 / 1700
    amp = rng.uniform(44.0, 50.0)
    v, holds = _peak_hold_sweep(dt, rng, rng.uniform(0.3, 0.4), rng.uniform(2.5, 3.5), int(rng.integers(24, 32)),
                                amp, 0.6, (0.1, 0.3))
    r = _grid(0.8 * amp, 160)
    dens = np.maximum(1 - r / (0.8 * amp), 0.0)             # a triangular density: most plays narrow
    w0 = rng.uniform(0.3, 0.45)
    weights = (1 - w0) * dens / dens.sum()
    pol = _plays(v, r, weights, w0, 0.0)
    kappa = rng.uniform(0.08, 0.14)                         # max |p| / (2 P_r)
    p_r = np.abs(pol).max() / (2 * kappa)
    gain = rng.uniform(0.7, 1.4)
    y = gain * _electrostrictive(pol, p_r)
    rec = finish("holdout11_asymmetry_electrostrictive_poled_peak_hold_sweep_1700hz", seed, np.arange(len(v)) * dt, v,
                 y, {"asymmetry"}, "either",
                 f"electrostriction Q (P_r + p)^2 of a poled core (max |p| / 2 P_r = {kappa:.2f}), a log sine sweep "
                 "with holds at peaks of drawn heights, 1.7 kHz", rng, monitor_noise=4e-4)
    rec.extra.update(thresholds=r, weights=weights, linear=w0, p_r=p_r, kappa=kappa, gain=gain, holds=holds, drive=v)
    return rec


@case
def saturation_quadrant_detector_erf_spiral_scan_560hz(seed):
    rng = _rng(seed, 6)
    dt = 1 / 560
    amp = rng.uniform(45.0, 55.0)
    v, radius, _ = _spiral_scan(dt, amp, rng.uniform(12.0, 18.0), rng.uniform(3.0, 5.0), rng.uniform(0.5, 0.8))
    r = _grid(0.75 * amp, 140)
    dens = np.exp(-(r / rng.uniform(0.3, 0.45) / amp) ** 2)   # a half-Gaussian density
    w0 = rng.uniform(0.3, 0.45)
    h = _plays(v, r, (1 - w0) * dens / dens.sum(), w0, 0.0)
    hmax = np.abs(h).max()
    rho = rng.uniform(0.1, 0.2)                               # y(hmax) = (1 - rho) hmax
    b = brentq(lambda bb: _quadrant_detector(hmax, bb) - (1 - rho) * hmax, 0.05 * hmax, 100 * hmax)
    gain = rng.uniform(0.8, 1.5)
    y = gain * _quadrant_detector(h, b)
    rec = finish("holdout11_saturation_quadrant_detector_erf_spiral_scan_560hz", seed, np.arange(len(v)) * dt, v, y,
                 {"output_saturation"}, "either",
                 f"a quadrant photodiode's erf response compressing the extremes by {rho:.0%}, one axis of a "
                 "CAV-CLV spiral scan out and back in, 560 Hz", rng)
    rec.extra.update(b=b, rho=rho, gain=gain, core=h, radius=radius)
    return rec


@case
def delay_pneumatic_line_transport_sine_on_sine_400hz(seed):
    rng = _rng(seed, 7)
    dt = 1 / 400
    n = int(round(rng.uniform(30.0, 45.0) / dt))
    t = np.arange(n) * dt
    a_fast = rng.uniform(4.0, 7.0)                           # 8 ... 14 V peak to peak
    sig = dict(c_slow=rng.uniform(30.0, 42.0) - a_fast, f_slow=rng.uniform(0.15, 0.3), a_fast=a_fast,
               f_fast=rng.uniform(2.5, 4.5))
    length = rng.uniform(2.0, 5.0)
    d = length / 343.0 / dt                                  # the travel time in samples
    v = _sine_on_sine(t, **sig)
    r = _grid(45.0, 160)
    k_shape, scale = rng.uniform(1.2, 1.8), rng.uniform(10.0, 18.0)
    dens = (r / scale) ** (k_shape - 1) * np.exp(-(r / scale) ** k_shape)   # a Weibull density
    w0, gain = rng.uniform(0.3, 0.45), rng.uniform(0.8, 1.4)
    weights = gain * (1 - w0) * dens / dens.sum()
    y = _plays(_sine_on_sine(t - d * dt, **sig), r, weights, gain * w0, 0.0)
    rec = finish("holdout11_delay_pneumatic_line_transport_sine_on_sine_400hz", seed, t, v, y, {"delay"}, "either",
                 f"the transport delay of a {length:.1f} m air line ({d:.2f} samples), a fast sine on a slow one, "
                 "0 ... 100 V, 400 Hz", rng)
    rec.extra.update(delay_samples=d, line_m=length, thresholds=r, weights=weights, linear=gain * w0, signal=sig)
    return rec


@case
def initial_state_sine_run_stopped_bleed_discharge_pulses_880hz(seed):
    rng = _rng(seed, 8)
    dt = 1 / 880
    a_h, f_h = rng.uniform(42.0, 50.0), rng.uniform(1.5, 3.0)
    u = rng.uniform(2.3, 2.9)                                # the stop phase 3 pi / 2 + u: rising out of a trough
    sign = rng.choice([-1.0, 1.0])
    th = 2 * np.pi * int(rng.integers(3, 6)) + 1.5 * np.pi + u
    run = sign * a_h * np.sin(np.arange(int(th / (2 * np.pi * f_h * dt)) + 1) * 2 * np.pi * f_h * dt)
    v_stop = run[-1]
    rc, frac = rng.uniform(0.3, 1.0), rng.uniform(0.04, 0.12)
    t_dis = np.arange(1, int(round(rc * np.log(1 / frac) / dt)) + 1) * dt
    pre = np.r_[run, v_stop * np.exp(-t_dis / rc)]
    base = pre[-1]
    _, z = me.play_core(pre, 100.0, return_state=True)
    v = _growing_pulses(dt, rng, base, int(rng.integers(22, 30)), 6.0, a_h + rng.uniform(2.0, 5.0), (0.25, 0.5),
                        (0.15, 0.35))
    y = me.play_core(v, 100.0, state=z)
    rec = finish("holdout11_initial_state_sine_run_stopped_bleed_discharge_pulses_880hz", seed,
                 np.arange(len(v)) * dt, v, y, {"initial_state"}, "either",
                 f"a core left by an unrecorded +-{a_h:.0f} V sine run stopped at {v_stop:.0f} V and a discharge "
                 f"to {base:.1f} V, then half-sine pulses of alternating sign growing past the run's amplitude, 880 Hz",
                 rng, monitor_noise=2e-4)
    rec.extra.update(history=pre, run_end=len(run), v_stop=v_stop, a_h=a_h, base=base, rc=rc, drive=v, sign=sign)
    return rec


# ---- two effects ----

@case
def pair_gain_drift_delay_self_heating_dac_beat_1300hz(seed):
    rng = _rng(seed, 9)
    dt = 1 / 1300
    n = int(round(rng.uniform(24.0, 30.0) / dt))
    t = np.arange(n) * dt
    f1 = rng.uniform(2.0, 4.0)
    f2 = f1 - 1 / rng.uniform(8.0, 16.0)
    a1, a2 = rng.uniform(26.0, 30.0), rng.uniform(18.0, 24.0)
    v = a1 * np.sin(2 * np.pi * f1 * t) + a2 * np.sin(2 * np.pi * f2 * t)
    g_s = rng.uniform(0.6, 1.5)                              # the filter's group delay in samples
    u = _dac_bessel(v, dt, g_s * dt)
    r = _grid(40.0, 140)
    dens = r / 12.0 * np.exp(-(r / 12.0) ** 2 / 2)           # a Rayleigh density
    w0 = rng.uniform(0.3, 0.4)
    weights = (1 - w0) * dens / dens.sum()
    h, q = _plays(u, r, weights, w0, 0.0, loss=True)
    tau_th = rng.uniform(4.0, 10.0)
    theta = _thermal(q / dt, dt, tau_th)
    rise = rng.uniform(0.04, 0.07)
    gain = 1 + rise * theta / theta.max()
    y = gain * h
    rec = finish("holdout11_pair_gain_drift_delay_self_heating_dac_beat_1300hz", seed, t, v, y, {"gain_drift", "delay"},
                 "either", f"a gain rising by {rise:.1%} with self-heating by the hysteresis loss (tau {tau_th:.1f} s) "
                 f"and a DAC delay (latency, hold, Bessel filter; {1.5 + g_s:.2f} samples), a two-tone beat, 1.3 kHz",
                 rng, monitor_noise=3e-4)
    rec.extra.update(gain=gain, theta=theta, loss=q, tau_th=tau_th, rise=rise, group_delay_samples=g_s,
                     actuator_drive=u, thresholds=r, weights=weights, linear=w0, core=h, drive=v)
    return rec


# ---- out of vocabulary ----

@case
def oov_armstrong_frederick_ratchet_mean_blocks_360hz(seed):
    rng = _rng(seed, 10)
    dt = 1 / 360
    m = rng.uniform(0.8, 1.5)
    order = rng.permutation([1.0, 1.0, -1.0, -1.0, 0.0, 0.0])
    while np.any(order[1:] == order[:-1]):                   # no two blocks with the same mean in a row
        order = rng.permutation(order)
    amp = rng.uniform(34.0, 40.0)
    v, blocks = _mean_blocks(dt, rng, m * order, amp, (6, 10), (0.6, 1.1), (1.0, 2.0), rng.uniform(40.0, 70.0))
    sigma_y = rng.uniform(6.0, 10.0)
    a_max = (amp + m - sigma_y) / rng.uniform(0.4, 0.55)    # the backstress's limit C / gamma
    gamma = rng.uniform(0.08, 0.12)
    p = dict(E=1 / rng.uniform(0.3, 0.5), sigma_y=sigma_y, C=gamma * a_max, gamma=gamma)
    gain = rng.uniform(0.8, 1.5)
    y = gain * _armstrong_frederick(v, **p)
    rec = finish("holdout11_oov_armstrong_frederick_ratchet_mean_blocks_360hz", seed, np.arange(len(v)) * dt, v, y,
                 set(), "unexplained",
                 f"Armstrong-Frederick cyclic plasticity ratcheting under blocks of cycles about +-{m:.1f} V and 0 "
                 "(the return point walks with the block's mean, not in holds), 360 Hz", rng)
    rec.extra.update(blocks=blocks, gain=gain, m=m, amp=amp, drive=v, **p)
    return rec

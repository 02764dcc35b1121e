"""Mechanisms and signals of the HOLDOUT12 set (``cases_holdout12.py``), each written from its law.

Nothing here imports hystcomp. Every mechanism takes the (clean) drive and returns the response; all are
causal. The sources of the laws are in ``cases_holdout12``'s docstring and beside each function.
"""

import math

import numpy as np
from scipy.signal import butter, fftconvolve, sosfilt
from scipy.special import gammainc

#: the golden ratio, the frequency ratio of the two-tone of the initial-state case
GOLDEN = (1 + math.sqrt(5)) / 2


# ---- the rate-independent core ----

def plays(v, r, w, w0, state=0.0, return_state=False):
    """y = w0 v + sum_k w_k z_k, z_k the play of threshold r_k: z_k(t) = min(max(z_k(t-), v(t) - r_k),
    v(t) + r_k) (Brokate & Sprekels, *Hysteresis and Phase Transitions*, 1996, sec. 2.3), from the given
    state (0: virgin). Returns y (and the final state)."""
    v = np.asarray(v, float)
    r = np.asarray(r, float)
    z = np.broadcast_to(np.asarray(state, float), r.shape).copy()
    y = np.empty_like(v)
    for k, vk in enumerate(v):
        z = np.minimum(np.maximum(z, vk - r), vk + r)
        y[k] = w0 * vk + w @ z
    return (y, z) if return_state else y


def grid(r_max, n):
    """n thresholds evenly spaced in (0, r_max]."""
    return (np.arange(n) + 0.5) * r_max / n


# ---- signals ----

def raised_cosine(x):
    """0 for x <= 0, (1 - cos(pi x)) / 2 between, 1 for x >= 1."""
    x = np.clip(np.asarray(x, float), 0.0, 1.0)
    return (1 - np.cos(np.pi * x)) / 2


def narrowband_random(dt, n, f_lo, f_hi, peak, fade_s, rng):
    """Gaussian noise through a causal 4th-order Butterworth band-pass f_lo ... f_hi (started 40 periods of
    f_lo early, so stationary), faded in by a raised cosine over fade_s (0 at t = 0) and scaled to the
    peak. A random carrier near the band's centre with a Rayleigh-distributed envelope."""
    sos = butter(2, [f_lo, f_hi], btype="bandpass", fs=1 / dt, output="sos")
    burn = int(40 / f_lo / dt)
    x = sosfilt(sos, rng.standard_normal(n + burn))[burn:]
    x = x * raised_cosine(np.arange(n) * dt / fade_s)
    return peak * x / np.abs(x).max()


def overdriven_sine(t, v_rail, f, m_lo, m_hi, f_m):
    """A sine overdriving an amplifier whose output stage limits softly at its rails: v_rail tanh(m sin(2 pi
    f t)), the overdrive m swinging as m_lo + (m_hi - m_lo) (1 - cos(2 pi f_m t)) / 2 (peaks v_rail tanh m,
    flattened tops). Returns v and m."""
    m = m_lo + (m_hi - m_lo) * (1 - np.cos(2 * np.pi * f_m * t)) / 2
    return v_rail * np.tanh(m * np.sin(2 * np.pi * f * t)), m


def s_curve_times(dist, v_max, a_max, jerk):
    """The segment times (Tj, Ta, Tv) of a symmetric seven-segment jerk-limited (S-curve) move of length
    |dist|: jerk +J for Tj, 0 for Ta, -J for Tj (the speed reaches its peak), a cruise of Tv, then the
    mirror; velocity <= v_max, acceleration <= a_max, jerk = J. Short moves lower the peak speed (and
    the acceleration) so that the move has no cruise."""
    d = abs(dist)
    tj = a_max / jerk
    if v_max < a_max * tj:                      # the acceleration limit is not reached at v_max
        tj = math.sqrt(v_max / jerk)
        ta = 0.0
    else:
        ta = v_max / a_max - tj
    vpk = jerk * tj * (tj + ta)
    tv = d / vpk - (2 * tj + ta)
    if tv < 0:                                   # a short move: no cruise
        tv = 0.0
        tj = a_max / jerk
        vpk = a_max / 2 * (-tj + math.sqrt(tj * tj + 4 * d / a_max))
        ta = vpk / a_max - tj
        if ta < 0:
            tj, ta = (d / (2 * jerk)) ** (1 / 3), 0.0
    return tj, ta, tv


def s_curve(t, x0, dist, tj, ta, tv, jerk):
    """Position at times t (from the move's start) of the S-curve move from x0 by dist: the exact cubic
    of each constant-jerk segment; x0 before the move, x0 + dist after it."""
    t = np.asarray(t, float)
    s = math.copysign(1.0, dist)
    jerks = [jerk, 0, -jerk, 0, -jerk, 0, jerk]
    durs = [tj, ta, tj, tv, tj, ta, tj]
    out = np.full_like(t, x0)
    p, vel, acc, t0 = 0.0, 0.0, 0.0, 0.0
    for j, du in zip(jerks, durs):
        m = (t >= t0) & (t < t0 + du)
        tau = t[m] - t0
        out[m] = x0 + s * (p + vel * tau + acc * tau ** 2 / 2 + j * tau ** 3 / 6)
        p, vel, acc = (p + vel * du + acc * du ** 2 / 2 + j * du ** 3 / 6, vel + acc * du + j * du ** 2 / 2,
                       acc + j * du)
        t0 += du
    out[t >= t0] = x0 + dist
    return out


def odd_multisine(t, f0, n_tones, phases, fade_s):
    """sum_k sin(2 pi (2k + 1) f0 t + phi_k) over the first n_tones odd harmonics (equal amplitudes, random
    phases: Pintelon & Schoukens, *System Identification*, 2012, sec. 2.6), times a raised-cosine fade-in
    over fade_s. Returns the (unscaled) signal and its time derivative (analytic)."""
    t = np.asarray(t, float)
    ks = 2 * np.arange(n_tones) + 1
    arg = 2 * np.pi * f0 * np.outer(t, ks) + phases
    x = np.sin(arg).sum(axis=1)
    dx = (2 * np.pi * f0 * ks * np.cos(arg)).sum(axis=1)
    u = np.clip(t / fade_s, 0, 1)
    w = raised_cosine(u)
    dw = np.where((t > 0) & (t < fade_s), np.pi / (2 * fade_s) * np.sin(np.pi * u), 0.0)
    return w * x, w * dx + dw * x


def skewed_triangles(dt, rng, amp, frac, period_s, rise, n_cycles):
    """Triangles between peaks of alternating sign (the first drawn; heights frac ... 1 of amp, drawn per
    peak), each cycle of a drawn period whose rising ramp takes a drawn fraction `rise` of it; piecewise
    linear from 0 V back to 0 V. Returns the signal, the knots' times and values."""
    sign = rng.choice([-1.0, 1.0])
    times, vals = [0.0], [0.0]
    for k in range(2 * n_cycles):
        if k % 2 == 0:
            per, rf = rng.uniform(*period_s), rng.uniform(*rise)
        peak = sign * (-1) ** k * amp * rng.uniform(frac, 1.0)
        up = peak > vals[-1]
        dur = per * (rf if up else 1 - rf)
        if k == 0:
            dur /= 2
        times.append(times[-1] + dur)
        vals.append(peak)
    times.append(times[-1] + per / 2 * (rf if vals[-1] < 0 else 1 - rf))   # back to 0 V, half a ramp
    vals.append(0.0)
    t = np.arange(int(times[-1] / dt) + 1) * dt
    return np.interp(t, times, vals), np.array(times), np.array(vals)


def rectified_sine(t, amp, f_pulse):
    """A full-wave rectified sine amp |sin(pi f_pulse t)|: f_pulse unipolar pulses per second, cusps at 0 V."""
    return amp * np.abs(np.sin(np.pi * f_pulse * np.asarray(t, float)))


def unipolar_am_sine(t, mid, amp, depth, f_c, f_m, fade_s):
    """w(t) (mid + amp (1 - depth (1 - cos(2 pi f_m t)) / 2) sin(2 pi f_c t)), w a raised-cosine fade-in over
    fade_s: 0 V at t = 0, within 0 ... mid + amp (amp <= mid)."""
    t = np.asarray(t, float)
    env = amp * (1 - depth * (1 - np.cos(2 * np.pi * f_m * t)) / 2)
    return raised_cosine(t / fade_s) * (mid + env * np.sin(2 * np.pi * f_c * t))


def rc_steps(t, switch_times, targets, rc):
    """A switched drive charging the stack through a resistor: from 0 V, at each switch time T_i the drive
    heads for targets[i] exponentially, v = L_i + (v(T_i) - L_i) exp(-(t - T_i) / RC); 0 before T_0."""
    t = np.asarray(t, float)
    out = np.zeros_like(t)
    start = 0.0
    bounds = list(switch_times[1:]) + [np.inf]
    for ti, te, lv in zip(switch_times, bounds, targets):
        m = (t >= ti) & (t < te)
        out[m] = lv + (start - lv) * np.exp(-(t[m] - ti) / rc)
        if np.isfinite(te):
            start = lv + (start - lv) * math.exp(-(te - ti) / rc)
    return out


def golden_two_tone(t, v0, glide_s, grow_s, a1, a2, f1, theta):
    """A level gliding from v0 to 0 (raised cosine over glide_s) plus an envelope growing linearly from 0 to 1
    over grow_s times a1 sin(2 pi f1 t) + a2 sin(2 pi GOLDEN f1 t + theta): a quasi-periodic two-tone that
    never repeats; v0 at t = 0."""
    t = np.asarray(t, float)
    env = np.clip(t / grow_s, 0, 1)
    return v0 * (1 - raised_cosine(t / glide_s)) + env * (a1 * np.sin(2 * np.pi * f1 * t)
                                                         + a2 * np.sin(2 * np.pi * GOLDEN * f1 * t + theta))


def stepped_levels(dt, rng, v_start, levels, hold_s, step_s, first_hold_s):
    """A hold at v_start for first_hold_s, then raised-cosine steps (drawn durations step_s) to each level,
    each held for a drawn hold_s. Returns the signal and the holds' (start, stop) indices after each step."""
    parts = [np.full(int(round(first_hold_s / dt)), v_start)]
    pos, cur, holds = len(parts[0]), v_start, []
    for lv in levels:
        m = int(round(rng.uniform(*step_s) / dt))
        parts.append(cur + (lv - cur) * raised_cosine(np.arange(1, m + 1) / m))
        pos += m
        nh = int(round(rng.uniform(*hold_s) / dt))
        parts.append(np.full(nh, lv))
        holds.append((pos, pos + nh))
        pos += nh
        cur = lv
    return np.concatenate(parts), holds


# ---- mechanisms ----

def coleman_hodgdon(v, alpha, a, c, v_x):
    """The rate-independent Duhem law of Coleman & Hodgdon, dy/dt = alpha |dv/dt| (f(v) - y) + g(v) dv/dt,
    with f(v) = a v and g(v) = a + c (1 - 2 v^2 / v_x^2): g exceeds f' for |v| < v_x / sqrt(2) and falls
    below it outside. On a monotone stretch e = y - a v obeys de/dv = -alpha s e + p(v), s the direction,
    p = g - a = p0 + p2 v^2; with lam = alpha s its solution is q(v) + (e0 - q(v0)) exp(-lam (v - v0)),
    q = q0 + q1 v + q2 v^2 (q2 = p2 / lam, q1 = -2 q2 / lam, q0 = (p0 - q1) / lam): exact per sample for a
    drive linear between samples. From y = a v[0]."""
    v = np.asarray(v, float)
    p0, p2 = c, -2 * c / v_x ** 2
    out = np.empty_like(v)
    e = 0.0
    out[0] = a * v[0]
    for k in range(1, len(v)):
        v0, v1 = v[k - 1], v[k]
        if v1 != v0:
            lam = alpha if v1 > v0 else -alpha
            q2 = p2 / lam
            q1 = -2 * q2 / lam
            q0 = (p0 - q1) / lam
            e = q0 + q1 * v1 + q2 * v1 * v1 + (e - q0 - q1 * v0 - q2 * v0 * v0) * math.exp(-alpha * abs(v1 - v0))
        out[k] = a * v1 + e
    return out


def eyring_kelvin(u, dt, c, tau, s):
    """Creep of a Kelvin element whose dashpot follows Eyring's stress-activated flow: de/dt = (s / tau)
    sinh((c u - e) / s) (tau the retardation time at small overstress, s the activation scale; s -> inf is
    the linear Kelvin-Voigt element tau de/dt = c u - e). For u held over a sample, tanh(x / 2s) decays as
    exp(-t / tau) (x = c u - e): exact per sample. Relaxed at the start (e = c u[0])."""
    u = np.asarray(u, float)
    out = np.empty_like(u)
    q = math.exp(-dt / tau)
    e = c * u[0]
    for k, uk in enumerate(u):
        out[k] = e
        x = c * uk - e
        e = c * uk - 2 * s * math.atanh(math.tanh(x / (2 * s)) * q)
    return out


def orifice_stage(h, dt, a, substeps=16):
    """A stage behind an orifice (turbulent) damper: the force through the flexure balances the orifice's
    quadratic law, k (h - y) = c dy/dt |dy/dt| (Bernoulli: the pressure drop grows as the square of the
    flow; Merritt, *Hydraulic Control Systems*, 1967, ch. 2), so dy/dt = sign(h - y) a sqrt(|h - y|), a =
    sqrt(k / c): at a steady rate R the stage lags by R^2 / a^2 (a lag in the square of the rate, settling
    in finite time after a step). h is linear between samples; each of `substeps` substeps holds it at its
    midpoint, where sqrt|h - y| falls at a / 2 until 0 (exact for the held value; the hold's error is
    second order in the substep). From rest at h[0]."""
    h = np.asarray(h, float)
    y = np.empty_like(h)
    y[0] = yy = h[0]
    half = a * dt / substeps / 2
    fr = (np.arange(substeps) + 0.5) / substeps
    for k in range(1, len(h)):
        for hm in (h[k - 1] + (h[k] - h[k - 1]) * fr).tolist():
            d = hm - yy
            rt = math.sqrt(abs(d)) - half
            yy = hm - math.copysign(rt * rt, d) if rt > 0 else hm
        y[k] = yy
    return y


def log_ageing_gain(t, rate, t_p):
    """The gain of a ceramic ageing logarithmically since a (re)poling pulse t_p before the record:
    1 - rate log10((t + t_p) / t_p), rate the loss per decade of time (Jaffe, Cook & Jaffe, *Piezoelectric
    Ceramics*, 1971, ch. 7)."""
    return 1 - rate * np.log10(1 + np.asarray(t, float) / t_p)


def hertz_contact(f, f0):
    """The approach of a preloaded Hertzian contact (F = K delta^(3/2); Johnson, *Contact Mechanics*, 1985,
    sec. 4.2) under a force change f about the preload f0: delta0 ((1 + f / f0)^(2/3) - 1), scaled by
    3 f0 / (2 delta0) to slope 1 at f = 0: 1.5 f0 ((1 + f / f0)^(2/3) - 1). Stiffer in compression."""
    return 1.5 * f0 * ((1 + np.asarray(f, float) / f0) ** (2 / 3) - 1)


def fringe(x, x_q, b):
    """A homodyne interferometer held at its quadrature point x_q: the detector's signal is linear in
    sin(4 pi (x - x_q) / lambda); with b = lambda / (4 pi), scaled to slope 1: x_q + b sin((x - x_q) / b)."""
    return x_q + b * np.sin((np.asarray(x, float) - x_q) / b)


def sinc_kernel(big_r, order):
    """The impulse response of a sinc^K (CIC, Hogenauer) decimation filter at the modulator rate: K
    moving sums of R samples, normalised to unit DC gain; K (R - 1) + 1 taps, group delay K (R - 1) / 2."""
    h = np.ones(1)
    for _ in range(order):
        h = np.convolve(h, np.ones(big_r))
    return h / big_r ** order


def sigma_delta(y_fine, big_r, order, latency=1):
    """A sigma-delta converter's output: the modulator-rate signal y_fine (R samples per output sample, at
    rest at its first value before it) through the sinc^K filter, taken every R-th sample, and delivered
    `latency` output samples later (held at the first value). Delay: latency + K (R - 1) / (2 R) samples."""
    h = sinc_kernel(big_r, order)
    padded = np.r_[np.full(len(h) - 1, y_fine[0]), y_fine]
    filt = np.convolve(padded, h, mode="valid")[::big_r]
    return np.r_[np.full(latency, filt[0]), filt[:len(filt) - latency]]


def cole_davidson_creep(u, dt, c, tau, gamma):
    """Creep with the Cole-Davidson compliance c P(gamma, t / tau) (P the regularised lower incomplete gamma
    function: the step response of c / (1 + i omega tau)^gamma; Davidson & Cole, J. Chem. Phys. 19 (1951)
    1484), by Boltzmann superposition: sum_(j <= k) du_j K((k - j) dt), du_0 = 0 (relaxed at u_0); an FFT
    convolution."""
    u = np.asarray(u, float)
    du = np.diff(u, prepend=u[0])
    kern = c * gammainc(gamma, np.arange(len(u)) * dt / tau)
    return fftconvolve(du, kern)[:len(u)]

"""The HOLDOUT10 set: written after HOLDOUT9 was measured (2026-11-25, tenth round), to be run once
for the tenth round's final measurement (docs/diagnose.md); kept out of ALL until then.

Mechanisms and signals that the other sets do not have, or not in these combinations:

- a clean core (180 plays written here from the play's definition, with a log-normal density of
  thresholds, a drawn linear part, gain and offset) whose memory is at rest at a bias of 35 ... 60 V
  (every play's state equal to the first input, as after the actuator settled around the bias),
  under a Schroeder multisine (6 ... 10 harmonics, phases -pi k (k - 1) / N, a low crest factor)
  riding on that bias with a cosine fade-in and a slowly varying amplitude, staying in 0 ... 100 V,
  sampled at 1.25 kHz;
- creep of a fractional Kelvin-Voigt element (a springpot tau^a D^a e + e = c h, c = 0.06 ... 0.1,
  tau = 0.5 ... 2 s, a = 0.3 ... 0.6:
  its step response c (1 - E_a(-(t / tau)^a)), a Mittag-Leffler function, t^a at first and a
  t^-a tail at last), solved by Grunwald-Letnikov over the whole record's memory, under holds whose
  lengths double from 0.2 ... 0.3 s to 32 times that and halve back, levels alternating in sign,
  sampled at 320 Hz;
- plays with thermally activated (Eyring) yielding: the overstress e beyond each threshold drives
  the play at rate0 (exp(e / s) - 1) (rate0 120 ... 250 V/s, s 2.5 ... 3.5 V), so that at a steady
  rate R the effective threshold grows as r + s ln(1 + R / rate0) (the logarithmic sweep-rate law of
  coercivity, Sharrock, IEEE Trans. Magn. 30 (1994) 4884), under a
  frequency-modulated (warbling) sine whose instantaneous frequency swings between 0.1 and 1.9
  times a carrier of 4 ... 7 Hz with a period of 5 ... 8 s, sampled at 2 kHz;
- a thermal offset from an on/off heater under a thermostat with a dead band (a first-order
  thermal body warming toward the heater's temperature while on and cooling toward ambient while
  off: a warm-up, then a limit cycle of exponential segments), under a tilted raster scan (a fast
  triangular line scan of 2 ... 4 Hz plus a slow frame sawtooth with a retrace), sampled at 800 Hz;
- a gain lost by depoling: it falls as 1 - delta (1 - exp(-X / X0)) with the accumulated exposure
  X = int max(-v - v_c, 0) dt to a reverse field beyond a coercive level, so it drops only in the
  deepest negative troughs and stays put otherwise, under a sine riding on a slowly wandering
  offset (two slow sines), sampled at 520 Hz;
- a bimodular (tension-compression) stiffness after the core: the output's slope differs by a
  factor 0.55 ... 0.75 (or its inverse) on either side of zero force, with a smooth contact corner,
  under first-order reversal curves (FORCs: from the top of the stroke down to a reversal point and
  back, for 10 ... 14 reversal points down to the bottom), sampled at 1.5 kHz;
- saturation by a hardening flexure: the displacement x solves x + kappa3 x^3 = F (a Duffing
  spring; Cardano's root), the core's output F compressed by 15 ... 28 % at its extremes, under a
  sine whose amplitude climbs and descends in 11 blocks of whole cycles (an amplitude pyramid),
  sampled at 240 Hz;
- a core left by an unrecorded history: an off-centre ring-down (a decaying oscillation about a
  level of 55 ... 70 V, as of a drive amplifier ringing after a fault, settling there) and a ramp to
  5 ... 20 V where the record starts, before a smoothed Brownian (integrated noise) drive folded
  into 0 ... 100 V, sampled at 960 Hz;
- two effects: a bus latency (4 ... 9 cycles of a 1.6 ... 2.4 kHz fieldbus: 1.7 ... 5.6 samples,
  the actuator's output evaluated on a grid shifted by it) and creep from 16 Kelvin-Voigt elements
  with a log-normal distribution of retardation times (median 0.3 ... 1.5 s, 6 ... 10 % of the core's
  output in all), under minimum-jerk
  point-to-point moves (x0 + D (10 s^3 - 15 s^4 + 6 s^5)) between set points in 0 ... 100 V, each
  followed by a hold, sampled at 1 kHz;
- out of vocabulary: a Jiles-Atherton core (domain-wall pinning: dM_irr / dH_e = (M_an - M_irr) /
  (delta k) with H_e = H + alpha M, a Langevin anhysteretic M_an, a reversible part c M_an; the drive
  reaches 1.2 ... 1.6 times the anhysteretic's field scale a, so the branches bend without
  flattening), driven by major excursions alternately to +-45 ... 50 V, each followed by a hold at a
  level 0 ... 15 V on the excursion's side and a train of 6 ... 10 raised-cosine minor cycles 5 ... 9 V
  deep from that level outward, then a hold, sampled at 450 Hz. The Jiles-Atherton minor loops do
  not close: the train's return point walks from the major branch toward the anhysteretic curve,
  cycle after cycle, by 25 ... 60 noise levels in all, against the direction of the last excursion,
  while nothing moves during the holds. A PI core (any plays, with any rate, creep, offset, gain,
  saturation, asymmetry, delay or initial-state part) returns to the same output at every return
  to the level (return-point memory): no creep draws a walk that stops when the input holds and goes
  on while it cycles, and no drift one whose direction follows the last excursion.
"""

import numpy as np
from scipy.signal import butter, lfilter

from . import mechanisms as me
from .record import case_set, finish

HOLDOUT10, case, _rng = case_set("holdout10_", 10000)


# ---- signals not in excitations.py ----

def _schroeder_multisine(t, f0, n_tones):
    """The Schroeder multisine sum_k cos(2 pi k f0 t - pi k (k - 1) / N), k = 1 ... N, scaled to a
    peak of 1 over a period (Schroeder, IEEE Trans. Inf. Theory 16 (1970) 85: the phases flatten
    the envelope, a crest factor near that of a single sine)."""
    k = np.arange(1, n_tones + 1)
    ph = -np.pi * k * (k - 1) / n_tones
    s = np.cos(2 * np.pi * f0 * np.asarray(t, float)[:, None] * k + ph).sum(axis=1)
    period = np.linspace(0, 1 / f0, 4000, endpoint=False)
    peak = np.abs(np.cos(2 * np.pi * f0 * period[:, None] * k + ph).sum(axis=1)).max()
    return s / peak


def _doubling_holds(dt, rng, base, n_up=6, ramp_s=(0.05, 0.1), level=(20.0, 48.0)):
    """Holds of base, 2 base, ..., 2^(n_up - 1) base and back down to base (2 n_up holds), at
    levels alternating in sign (the first sign drawn, magnitudes drawn in `level`), reached by
    linear ramps from 0 V. Returns the signal and the holds' (start, stop) sample indices."""
    lengths = base * 2.0 ** np.r_[np.arange(n_up), np.arange(n_up)[::-1]]
    sign = rng.choice([-1.0, 1.0])
    parts, holds, pos, cur = [], [], 0, 0.0
    for j, L in enumerate(lengths):
        lv = sign * (-1) ** j * rng.uniform(*level)
        nr = max(int(round(rng.uniform(*ramp_s) / dt)), 2)
        parts.append(np.linspace(cur, lv, nr + 1)[1:])
        pos += nr
        nh = int(round(L / dt))
        parts.append(np.full(nh, lv))
        holds.append((pos, pos + nh))
        pos += nh
        cur = lv
    return np.concatenate([[0.0]] + parts), [(a + 1, b + 1) for a, b in holds]


def _fm_warble(dt, n, fc, depth, fm, amp):
    """A sine of constant amplitude whose instantaneous frequency is fc (1 + depth sin(2 pi fm t)):
    phase 2 pi fc (t + depth (1 - cos(2 pi fm t)) / (2 pi fm)); starts at 0 V. Returns the signal
    and the instantaneous frequency."""
    t = np.arange(n) * dt
    phase = 2 * np.pi * fc * (t + depth * (1 - np.cos(2 * np.pi * fm * t)) / (2 * np.pi * fm))
    return amp * np.sin(phase), fc * (1 + depth * np.sin(2 * np.pi * fm * t))


def _tilted_raster(t, f_line, a_line, a_frame, frame_s, retrace_fraction=0.15):
    """One axis of a raster scan turned by an angle: a fast triangle (the line scan, a_line) plus a
    slow sawtooth (the frame: a linear trace over frame_s from -a_frame to a_frame, then a linear
    retrace taking retrace_fraction of it), starting mid-trace so that v(0) = 0."""
    t = np.asarray(t, float)
    tri = 2 / np.pi * np.arcsin(np.sin(2 * np.pi * f_line * t))
    T = frame_s * (1 + retrace_fraction)
    ph = (t + frame_s / 2) % T
    saw = np.where(ph < frame_s, -1 + 2 * ph / frame_s, 1 - 2 * (ph - frame_s) / (frame_s * retrace_fraction))
    return a_line * tri + a_frame * saw


def _forcs(dt, top, reversals, rate):
    """First-order reversal curves: 0 -> top, then for each reversal point top -> v_r -> top, then
    back to 0, all at `rate` V/s. Returns the signal and the indices where it is back at the top."""
    pts = [0.0, top]
    for r in reversals:
        pts += [r, top]
    pts.append(0.0)
    parts, tops, pos = [], [], 0
    for a, b in zip(pts[:-1], pts[1:]):
        m = max(int(round(abs(b - a) / rate / dt)), 2)
        parts.append(np.linspace(a, b, m, endpoint=False))
        pos += m
        if b == top:
            tops.append(pos)
    return np.concatenate(parts + [[0.0]]), np.array(tops)


def _amplitude_pyramid(dt, freq, cycles, amp, fractions, rest_s=0.5):
    """A rest at 0 V, then blocks of `cycles` whole sine cycles at freq, the k-th at fractions[k] x
    amp (the blocks join at 0 V). Returns the signal and the blocks' (start, stop) indices."""
    m = int(round(cycles / freq / dt))
    one = np.sin(2 * np.pi * cycles * np.arange(m) / m)
    n0 = int(round(rest_s / dt))
    parts, blocks = [np.zeros(n0)], []
    for k, f in enumerate(fractions):
        parts.append(f * amp * one)
        blocks.append((n0 + k * m, n0 + (k + 1) * m))
    return np.concatenate(parts + [[0.0]]), blocks


def _folded_brownian(dt, n, start, sigma, fc, rng, lo=0.0, hi=100.0):
    """Brownian motion (integrated white noise of sigma V / sqrt(s)), its increments through a causal
    2nd-order Butterworth low-pass at fc (a smooth path), starting at `start` and folded into
    [lo, hi] by reflection at the ends (a continuous path)."""
    b, a = butter(2, fc, fs=1 / dt)
    inc = lfilter(b, a, sigma * np.sqrt(dt) * rng.standard_normal(n - 1))
    x = start - lo + np.concatenate([[0.0], np.cumsum(inc)])
    w = 2 * (hi - lo)
    x = np.mod(x, w)
    return lo + np.where(x > hi - lo, w - x, x)


def _offcentre_ringdown(centre, amp, freq, tau, dt, end_level, ramp_s=0.4):
    """An unrecorded history from a virgin 0 V: a ramp to centre + amp, a decaying oscillation
    centre + amp exp(-t / tau) cos(2 pi freq t) for 8 tau (down to 3e-4 amp), a ramp to end_level."""
    tt = np.arange(int(round(8 * tau / dt))) * dt
    ring = centre + amp * np.exp(-tt / tau) * np.cos(2 * np.pi * freq * tt)
    m = int(round(ramp_s / dt))
    return np.concatenate([np.linspace(0.0, centre + amp, m, endpoint=False), ring,
                           np.linspace(ring[-1], end_level, m)])


def _min_jerk_knots(rng, n_moves, move_s, hold_s, min_step=20.0, first_hold=0.5):
    """Point-to-point moves between set points drawn in 0 ... 100 V (each at least min_step from the
    last), starting at 0 V after first_hold s; each move of a duration drawn in move_s, each followed
    by a hold drawn in hold_s. Returns a list of (t_start, t_end, x0, x1) and the total time."""
    knots, t, x = [], first_hold, 0.0
    for _ in range(n_moves):
        while True:
            x1 = rng.uniform(0.0, 100.0)
            if abs(x1 - x) >= min_step:
                break
        T = rng.uniform(*move_s)
        knots.append((t, t + T, x, x1))
        t += T + rng.uniform(*hold_s)
        x = x1
    return knots, t


def _min_jerk_path(t, knots):
    """The minimum-jerk profile through the knots (Flash & Hogan, J. Neurosci. 5 (1985) 1688):
    x0 + (x1 - x0) (10 s^3 - 15 s^4 + 6 s^5), s = (t - t0) / (t1 - t0), held between moves and
    at the first set point before t = 0 (the stage at rest)."""
    t = np.asarray(t, float)
    x = np.full_like(t, knots[0][2])
    for t0, t1, x0, x1 in knots:
        s = np.clip((t - t0) / (t1 - t0), 0.0, 1.0)
        x = np.where(t >= t0, x0 + (x1 - x0) * s ** 3 * (10 - 15 * s + 6 * s ** 2), x)
    return x


def _biased_minor_trains(dt, rng, n_groups, top=(45.0, 50.0), level=(0.0, 15.0), depth=(5.0, 9.0),
                         cycles=(6, 11), freq=(0.8, 1.5), rate=(60.0, 90.0), hold_s=(0.5, 1.0)):
    """Groups: a ramp to a major extreme s top (s alternating, the first drawn), a ramp back to a level
    s l, a hold, a train of whole raised-cosine minor cycles l -> l + s d -> l, a hold. Returns the
    signal and per group (sign, train start, train stop, samples per cycle)."""
    s = rng.choice([-1.0, 1.0])
    cur, parts, groups, pos = 0.0, [], [], 0
    for _ in range(n_groups):
        A, lv, d = s * rng.uniform(*top), s * rng.uniform(*level), s * rng.uniform(*depth)
        R = rng.uniform(*rate)
        for a, b in ((cur, A), (A, lv)):
            m = max(int(round(abs(b - a) / R / dt)), 2)
            parts.append(np.linspace(a, b, m, endpoint=False))
            pos += m
        nh = int(round(rng.uniform(*hold_s) / dt))
        parts.append(np.full(nh, lv))
        pos += nh
        c = int(rng.integers(*cycles))
        per = int(round(1 / rng.uniform(*freq) / dt))
        k = np.arange(c * per)
        parts.append(lv + d * (1 - np.cos(2 * np.pi * k / per)) / 2)
        groups.append((s, pos, pos + c * per, per))
        pos += c * per
        nh = int(round(rng.uniform(*hold_s) / dt))
        parts.append(np.full(nh, lv))
        pos += nh
        cur, s = lv, -s
    return np.concatenate(parts + [[cur]]), groups


# ---- mechanisms not in mechanisms.py ----

def _plays(v, r, w, w0, state):
    """y = w0 v + sum_k w_k z_k, z_k the play of threshold r_k: z_k(t) = min(max(z_k(t-), v(t) - r_k),
    v(t) + r_k) (Brokate & Sprekels 1996, sec. 2.3), from the given state (an array or a scalar for
    all plays)."""
    v = np.asarray(v, float)
    z = np.broadcast_to(np.asarray(state, float), r.shape).copy()
    y = np.empty_like(v)
    for k, vk in enumerate(v):
        z = np.minimum(np.maximum(z, vk - r), vk + r)
        y[k] = w0 * vk + w @ z
    return y


def _lognormal_density(r_max, median, sigma_ln, n=180):
    """n thresholds evenly spaced in (0, r_max] and weights (summing to 1) of a log-normal density
    exp(-(ln(r / median))^2 / (2 sigma_ln^2)) / r: zero at r -> 0, a hump near the median, a tail."""
    r = (np.arange(n) + 0.5) * r_max / n
    w = np.exp(-np.log(r / median) ** 2 / (2 * sigma_ln ** 2)) / r
    return r, w / w.sum()


def _gl_weights(alpha, n):
    """Grunwald-Letnikov weights g_j = (-1)^j binom(alpha, j): g_0 = 1, g_j = g_(j-1) (1 - (alpha + 1) / j)."""
    g = np.empty(n)
    g[0] = 1.0
    for j in range(1, n):
        g[j] = g[j - 1] * (1 - (alpha + 1) / j)
    return g


def _fractional_kelvin_voigt(u, dt, c, tau, alpha):
    """Creep of a fractional Kelvin-Voigt element (a spring beside a springpot; Bagley & Torvik,
    J. Rheol. 27 (1983) 201; Mainardi, *Fractional Calculus and Waves in Linear Viscoelasticity*,
    2010, ch. 3): tau^alpha D^alpha e + e = c u, relaxed (e = 0) before the record. Its step
    response is c (1 - E_alpha(-(t / tau)^alpha)). Implicit Grunwald-Letnikov scheme over the whole
    history: e_k = (c u_k - (tau / dt)^alpha sum_{j>=1} g_j e_(k-j)) / ((tau / dt)^alpha + 1)."""
    u = np.asarray(u, float)
    n = len(u)
    g = _gl_weights(alpha, n)
    q = (tau / dt) ** alpha
    e = np.zeros(n)
    for k in range(1, n):
        mem = g[1:k + 1] @ e[k - 1::-1]
        e[k] = (c * u[k] - q * mem) / (q + 1)
    return e


def _eyring_plays(v, dt, r, w, w0, rate0, s):
    """Plays with thermally activated (Eyring) yielding: beyond the threshold the overstress
    e = |v - z| - r drives the play at dz/dt = sign(v - z) rate0 (exp(e / s) - 1) (Eyring,
    J. Chem. Phys. 4 (1936) 283; Kocks, Argon & Ashby 1975). For a held input e obeys
    de/dt = -rate0 (exp(e / s) - 1), solved exactly: e(t) = -s ln(1 - (1 - exp(-e0 / s)) exp(-rate0 t / s)).
    Each sample's input is held over the step (the sample's output after it). At a steady rate R the
    overstress settles at s ln(1 + R / rate0): the loop widens logarithmically with the rate; for
    rate0 -> infinity it is the play. From z = 0; y = w0 v + sum w_k z_k."""
    v = np.asarray(v, float)
    z = np.zeros_like(r)
    fac = np.exp(-rate0 * dt / s)
    y = np.empty_like(v)
    for k, vk in enumerate(v):
        d = vk - z
        e0 = np.maximum(np.abs(d) - r, 0.0)
        e1 = -s * np.log1p(-(-np.expm1(-e0 / s)) * fac)
        z = np.where(e0 > 0, vk - np.sign(d) * (r + e1), z)
        y[k] = w0 * vk + w @ z
    return y


def _thermostat_heater(n, dt, tau, lo, hi):
    """A first-order thermal body (theta = 0 ambient, 1 the heater's steady temperature) with an on/off
    heater under a thermostat with a dead band, sampled every dt: on from the start (at ambient), off
    once theta >= hi, on again once theta <= lo. Exact per sample: theta <- u + (theta - u) exp(-dt / tau).
    Returns theta and the heater state u per sample."""
    a = np.exp(-dt / tau)
    th, u = np.empty(n), np.empty(n)
    x, on = 0.0, 1.0
    for k in range(n):
        th[k], u[k] = x, on
        x = on + (x - on) * a
        if on and x >= hi:
            on = 0.0
        elif not on and x <= lo:
            on = 1.0
    return th, u


def _depoling_gain(v, dt, v_c, delta, x0):
    """Gain left after depoling by a reverse field: 1 - delta (1 - exp(-X / x0)), X(t) = int_0^t
    max(-v - v_c, 0) dt' the exposure (V s) beyond the coercive level -v_c (Kamlah, Continuum Mech.
    Thermodyn. 13 (2001) 219: switching, and with it the remanent polarisation, needs a field beyond
    the coercive one; the piezoelectric coefficient follows the polarisation). Causal: X before the
    sample. Returns the gain and X."""
    x = np.concatenate([[0.0], np.cumsum(np.maximum(-np.asarray(v, float) - v_c, 0.0))[:-1]]) * dt
    return 1 - delta * (1 - np.exp(-x / x0)), x


def _bimodular(h, g_pos, g_neg, corner):
    """A tension-compression (bimodular) stiffness: slope g_pos for h >> corner, g_neg for
    h << -corner, a smooth corner of width `corner` (a contact closing):
    ((g_pos + g_neg) / 2) h + ((g_pos - g_neg) / 2) (sqrt(h^2 + corner^2) - corner); 0 at h = 0."""
    h = np.asarray(h, float)
    return 0.5 * (g_pos + g_neg) * h + 0.5 * (g_pos - g_neg) * (np.sqrt(h ** 2 + corner ** 2) - corner)


def _hardening_flexure(F, kappa3):
    """The displacement x of a hardening (Duffing) flexure under a force F: x + kappa3 x^3 = F, the
    one real root (Cardano): x = cbrt(F / (2 kappa3) + D) + cbrt(F / (2 kappa3) - D),
    D = sqrt(F^2 / (4 kappa3^2) + 1 / (27 kappa3^3))."""
    q = np.asarray(F, float) / (2 * kappa3)
    D = np.sqrt(q ** 2 + 1 / (27 * kappa3 ** 3))
    return np.cbrt(q + D) + np.cbrt(q - D)


def _lognormal_kv(median, sigma_ln, total, n=16, tau_min=0.02, tau_max=50.0):
    """n Kelvin-Voigt retardation times spread log-uniformly in [tau_min, tau_max] and compliances
    following a log-normal distribution of retardation times (median, sigma_ln in ln units; the
    Wiechert-type spectrum of disordered solids), summing to `total`."""
    tau = np.geomspace(tau_min, tau_max, n)
    c = np.exp(-np.log(tau / median) ** 2 / (2 * sigma_ln ** 2))
    return total * c / c.sum(), tau


def _langevin_scalar(x):
    """L(x) = coth x - 1/x (x / 3 - x^3 / 45 near 0)."""
    if abs(x) < 1e-3:
        return x / 3 - x ** 3 / 45
    return 1 / np.tanh(x) - 1 / x


def _jiles_atherton(H, ms, a, k, c, alpha, iters=4):
    """Jiles-Atherton hysteresis (J. Magn. Magn. Mater. 61 (1986) 48): effective field He = H + alpha M,
    anhysteretic M_an = ms L(He / a), irreversible magnetisation pinned by domain-wall pinning sites,
    dM_irr / dHe = (M_an - M_irr) / (delta k) while M_an is ahead of M_irr in the direction delta of
    the field's motion (frozen otherwise), M = c M_an + (1 - c) M_irr. Along the effective field's path
    length s that is dM_irr / ds = (M_an - M_irr) / k, solved exactly per sample for M_an linear in s
    over the step (from where M_an overtakes M_irr if it does so within the step); He's dependence
    on M by fixed-point iteration. Rate independent (nothing moves while H holds); from the
    demagnetised state (M = 0 at H = 0)."""
    H = np.asarray(H, float)
    out = np.empty_like(H)
    M = mirr = 0.0
    he_prev = H[0]
    man_prev = ms * _langevin_scalar(he_prev / a)
    M = c * man_prev
    he_prev = H[0] + alpha * M
    out[0] = M
    for j in range(1, len(H)):
        if H[j] == H[j - 1]:
            out[j] = M
            continue
        guess = M
        for _ in range(iters):
            he = H[j] + alpha * guess
            man = ms * _langevin_scalar(he / a)
            S = abs(he - he_prev)
            delta = 1.0 if he > he_prev else -1.0
            g0, g1 = (man_prev - mirr) * delta, (man - mirr) * delta
            new = mirr
            if g1 > 0 and S > 0:
                if g0 < 0:                            # M_an overtakes M_irr within the step
                    s0 = S * g0 / (g0 - g1)
                    m0, L = mirr, S - s0
                else:
                    m0, L = man_prev, S
                m1 = (man - m0) / L
                new = man - m1 * k + (mirr - m0 + m1 * k) * np.exp(-L / k)
            guess = c * man + (1 - c) * new
        mirr, M, he_prev, man_prev = new, guess, he, man
        out[j] = M
    return out


# ---- clean ----

@case
def clean_biased_schroeder_multisine_1250hz(seed):
    rng = _rng(seed, 1)
    dt = 1 / 1250
    n = int(round(rng.uniform(16.0, 22.0) / dt))
    t = np.arange(n) * dt
    bias = rng.uniform(35.0, 60.0)
    amp = rng.uniform(0.75, 0.88) * min(bias, 100.0 - bias)
    f0, tones = rng.uniform(0.25, 0.4), int(rng.integers(6, 11))
    t_in, t_slow = rng.uniform(1.0, 1.5), rng.uniform(6.0, 10.0)
    fade = np.where(t < t_in, (1 - np.cos(np.pi * np.minimum(t, t_in) / t_in)) / 2, 1.0)
    env = fade * (0.8 + 0.2 * np.sin(2 * np.pi * t / t_slow + rng.uniform(0, 2 * np.pi)))
    v = bias + amp * env * _schroeder_multisine(t, f0, tones)
    r, w = _lognormal_density(amp, rng.uniform(0.25, 0.4) * amp, rng.uniform(0.4, 0.7))
    w0 = rng.uniform(0.3, 0.45)
    gain, off = rng.uniform(0.7, 1.5), rng.uniform(-4.0, 4.0)
    y = gain * _plays(v, r, (1 - w0) * w, w0, v[0]) + off
    rec = finish("holdout10_clean_biased_schroeder_multisine_1250hz", seed, t, v, y, set(), "explained",
                 f"a clean core (180 plays, a log-normal threshold density) at rest at a {bias:.0f} V bias, a "
                 f"Schroeder multisine of {tones} harmonics of {f0:.2f} Hz on the bias, 1.25 kHz", rng,
                 monitor_noise=3e-4)
    rec.extra.update(bias=bias, amp=amp, thresholds=r, weights=gain * (1 - w0) * w, linear=gain * w0, offset=off,
                     drive=v)
    return rec


# ---- one effect ----

@case
def creep_fractional_kelvin_voigt_doubling_holds_320hz(seed):
    rng = _rng(seed, 2)
    dt = 1 / 320
    v, holds = _doubling_holds(dt, rng, rng.uniform(0.2, 0.3))
    h = me.play_core(v, 100.0)
    p = dict(c=rng.uniform(0.06, 0.1), tau=rng.uniform(0.5, 2.0), alpha=rng.uniform(0.3, 0.6))
    y = h + _fractional_kelvin_voigt(h, dt, **p)
    rec = finish("holdout10_creep_fractional_kelvin_voigt_doubling_holds_320hz", seed, np.arange(len(v)) * dt, v, y,
                 {"creep"}, "either",
                 f"a fractional Kelvin-Voigt creep (order {p['alpha']:.2f}, Mittag-Leffler step response), holds "
                 "doubling then halving in length at levels of alternating sign, 320 Hz", rng)
    rec.extra.update(holds=holds, **p)
    return rec


@case
def rate_eyring_plays_fm_warble_2khz(seed):
    rng = _rng(seed, 3)
    dt = 1 / 2000
    n = int(round(rng.uniform(14.0, 18.0) / dt))
    fc, fm = rng.uniform(4.0, 7.0), 1 / rng.uniform(5.0, 8.0)
    amp = rng.uniform(42.0, 48.0)
    v, finst = _fm_warble(dt, n, fc, 0.9, fm, amp)
    r, w = me._density_thresholds(100.0, 120)
    w = 0.65 * w / w.sum()
    rate0, s = rng.uniform(120.0, 250.0), rng.uniform(2.5, 3.5)
    gain = rng.uniform(0.8, 1.3)
    y = gain * _eyring_plays(v, dt, r, w, 0.35, rate0, s)
    rec = finish("holdout10_rate_eyring_plays_fm_warble_2khz", seed, np.arange(n) * dt, v, y, {"rate_dependence"},
                 "either", f"plays with Eyring (thermally activated) yielding, rate0 {rate0:.0f} V/s, s {s:.2f} V, "
                 f"a warbling sine (carrier {fc:.1f} Hz, 0.1 ... 1.9 x), 2 kHz", rng, monitor_noise=2e-4)
    rec.extra.update(rate0=rate0, s=s, gain=gain, thresholds=r, weights=w, inst_freq=finst, drive=v)
    return rec


@case
def drift_thermostat_heater_raster_scan_800hz(seed):
    rng = _rng(seed, 4)
    dt = 1 / 800
    n = int(round(rng.uniform(24.0, 32.0) / dt))
    t = np.arange(n) * dt
    v = _tilted_raster(t, rng.uniform(2.0, 4.0), rng.uniform(12.0, 20.0), rng.uniform(25.0, 30.0),
                       rng.uniform(6.0, 9.0))
    h = me.play_core(v, 100.0)
    tau, lo = rng.uniform(3.0, 6.0), rng.uniform(0.35, 0.5)
    hi = lo + rng.uniform(0.15, 0.25)
    theta, heater = _thermostat_heater(n, dt, tau, lo, hi)
    beta = rng.choice([-1.0, 1.0]) * rng.uniform(0.07, 0.1) * np.ptp(h)
    off = beta * theta
    y = h + off
    rec = finish("holdout10_drift_thermostat_heater_raster_scan_800hz", seed, t, v, y, {"drift"}, "either",
                 f"an offset following an on/off heater under a thermostat (tau {tau:.1f} s, dead band "
                 f"{lo:.2f} ... {hi:.2f}), a tilted raster scan, 800 Hz", rng)
    rec.extra.update(offset=off, theta=theta, heater=heater, beta=beta, tau=tau, lo=lo, hi=hi)
    return rec


@case
def gain_drift_reverse_field_depoling_wandering_offset(seed):
    rng = _rng(seed, 5)
    dt = 1 / 520
    n = int(round(rng.uniform(30.0, 40.0) / dt))
    t = np.arange(n) * dt
    wander = (rng.choice([-1.0, 1.0]) * rng.uniform(10.0, 14.0) * np.sin(2 * np.pi * t / rng.uniform(12.0, 20.0))
              + rng.choice([-1.0, 1.0]) * rng.uniform(4.0, 7.0) * np.sin(2 * np.pi * t / rng.uniform(4.5, 7.0)))
    v = wander + rng.uniform(38.0, 44.0) * np.sin(2 * np.pi * rng.uniform(0.8, 1.6) * t)
    h = me.play_core(v, 120.0)
    v_c = rng.uniform(0.6, 0.72) * (-v.min())
    x_end = np.sum(np.maximum(-v - v_c, 0.0)) * dt
    delta, x0 = rng.uniform(0.06, 0.1), rng.uniform(0.5, 1.0) * x_end
    gain, x = _depoling_gain(v, dt, v_c, delta, x0)
    y = gain * h
    rec = finish("holdout10_gain_drift_reverse_field_depoling_wandering_offset", seed, t, v, y, {"gain_drift"},
                 "either", f"a gain lost by depoling under reverse fields beyond {-v_c:.0f} V (up to {delta:.1%}), a "
                 "sine on a slowly wandering offset, 520 Hz", rng)
    rec.extra.update(gain=gain, exposure=x, v_c=v_c, delta=delta, x0=x0)
    return rec


@case
def asymmetry_bimodular_stiffness_forcs_1500hz(seed):
    rng = _rng(seed, 6)
    dt = 1 / 1500
    top = rng.uniform(42.0, 48.0)
    n_rev = int(rng.integers(10, 15))
    rev = np.linspace(top - 2 * top / n_rev, -top, n_rev) + np.r_[rng.uniform(-2.0, 2.0, n_rev - 1), 0.0]
    v, tops = _forcs(dt, top, rev, rng.uniform(90.0, 130.0))
    h = me.play_core(v, 100.0)
    ratio = rng.uniform(0.55, 0.75)
    g_pos, g_neg = (1.0, ratio) if rng.random() < 0.5 else (ratio, 1.0)
    corner = 0.03 * np.abs(h).max()
    y = _bimodular(h, g_pos, g_neg, corner)
    rec = finish("holdout10_asymmetry_bimodular_stiffness_forcs_1500hz", seed, np.arange(len(v)) * dt, v, y,
                 {"asymmetry"}, "either",
                 f"a bimodular stiffness (slopes {g_pos:.2f} / {g_neg:.2f} either side of zero force) after the "
                 f"core, {n_rev} first-order reversal curves, 1.5 kHz", rng, monitor_noise=4e-4)
    rec.extra.update(g_pos=g_pos, g_neg=g_neg, corner=corner, reversals=rev, tops=tops, top=top)
    return rec


@case
def saturation_hardening_flexure_amplitude_pyramid_240hz(seed):
    rng = _rng(seed, 7)
    dt = 1 / 240
    fr = np.r_[np.linspace(0.2, 1.0, 6), np.linspace(0.84, 0.2, 5)] * rng.uniform(0.95, 1.0, 11)
    v, blocks = _amplitude_pyramid(dt, rng.uniform(0.8, 1.2), int(rng.integers(4, 7)), rng.uniform(44.0, 50.0), fr)
    h = me.play_core(v, 100.0)
    fmax = np.abs(h).max()
    rho = rng.uniform(0.15, 0.28)                 # x(F_max) = (1 - rho) F_max
    xmax = (1 - rho) * fmax
    kappa3 = (fmax - xmax) / xmax ** 3
    y = _hardening_flexure(h, kappa3)
    rec = finish("holdout10_saturation_hardening_flexure_amplitude_pyramid_240hz", seed, np.arange(len(v)) * dt, v, y,
                 {"saturation"}, "either",
                 f"a hardening (Duffing) flexure x + k3 x^3 = F compressing the core's extremes by {rho:.0%}, a sine "
                 "whose amplitude climbs and descends in blocks, 240 Hz", rng)
    rec.extra.update(kappa3=kappa3, rho=rho, blocks=blocks)
    return rec


@case
def initial_state_offcentre_ringdown_brownian_960hz(seed):
    rng = _rng(seed, 8)
    dt = 1 / 960
    centre = rng.uniform(55.0, 70.0)
    start = rng.uniform(5.0, 20.0)
    pre = _offcentre_ringdown(centre, rng.uniform(0.8, 0.95) * (100.0 - centre), rng.uniform(2.0, 4.0),
                              rng.uniform(0.6, 1.2), dt, start)
    _, z = me.play_core(pre, 100.0, return_state=True)
    n = int(round(rng.uniform(20.0, 30.0) / dt))
    v = _folded_brownian(dt, n, start, rng.uniform(20.0, 28.0), rng.uniform(3.0, 6.0), rng)
    y = me.play_core(v, 100.0, state=z)
    rec = finish("holdout10_initial_state_offcentre_ringdown_brownian_960hz", seed, np.arange(n) * dt, v, y,
                 {"initial_state"}, "either",
                 f"a core left by an unrecorded ring-down about {centre:.0f} V and a ramp to {start:.0f} V where the "
                 "record starts, a smoothed Brownian drive folded into 0 ... 100 V, 960 Hz", rng, monitor_noise=3e-4)
    rec.extra.update(history=pre, centre=centre, start=start, drive=v)
    return rec


# ---- two effects ----

@case
def pair_delay_creep_min_jerk_moves_1khz(seed):
    rng = _rng(seed, 9)
    dt = 1 / 1000
    knots, total = _min_jerk_knots(rng, int(rng.integers(14, 19)), (0.08, 0.2), (0.8, 2.0))
    n = int(round(total / dt))
    t = np.arange(n) * dt
    cycles, f_bus = int(rng.integers(4, 10)), rng.uniform(1600.0, 2400.0)
    d = cycles / f_bus / dt                        # the latency in samples
    comp, tau = _lognormal_kv(rng.uniform(0.3, 1.5), rng.uniform(0.8, 1.4), rng.uniform(0.06, 0.1))
    v = _min_jerk_path(t, knots)
    v_late = _min_jerk_path(t - d * dt, knots)   # what the actuator saw when the sensor's sample left
    h = me.play_core(v_late, 100.0)
    y = h + me.kelvin_voigt_creep(h, dt, comp, tau)
    rec = finish("holdout10_pair_delay_creep_min_jerk_moves_1khz", seed, t, v, y, {"delay", "creep"}, "either",
                 f"a fieldbus latency of {d:.2f} samples and creep from log-normally distributed Kelvin-Voigt "
                 "elements, minimum-jerk moves between holds in 0 ... 100 V, 1 kHz", rng, monitor_noise=2e-4)
    rec.extra.update(delay_samples=d, compliances=comp, time_constants=tau, knots=knots, drive=v)
    return rec


# ---- out of vocabulary ----

@case
def oov_jiles_atherton_minor_loop_walk_450hz(seed):
    rng = _rng(seed, 10)
    dt = 1 / 450
    v, groups = _biased_minor_trains(dt, rng, int(rng.integers(6, 9)))
    a = 47.5 / rng.uniform(1.2, 1.6)
    p = dict(ms=1.0, a=a, k=a * rng.uniform(0.5, 0.7), c=rng.uniform(0.1, 0.25), alpha=a * rng.uniform(0.05, 0.12))
    mu, gain = rng.uniform(0.05, 0.1), rng.uniform(40.0, 70.0)
    y = gain * (_jiles_atherton(v, **p) + mu * v / a)
    rec = finish("holdout10_oov_jiles_atherton_minor_loop_walk_450hz", seed, np.arange(len(v)) * dt, v, y, set(),
                 "unexplained", "a Jiles-Atherton core whose biased minor loops walk toward the anhysteretic curve "
                 "(no return-point memory), major excursions, holds and minor-cycle trains, 450 Hz", rng)
    rec.extra.update(groups=groups, mu=mu, gain=gain, drive=v, **p)
    return rec

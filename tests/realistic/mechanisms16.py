"""Mechanisms and signals of the HOLDOUT16 set (``cases_holdout16.py``), each written from its law.

Nothing here imports hystcomp. Every mechanism takes the (clean) drive, or the core's output, and returns the
response; all are causal. The sources of the laws are beside each function and in ``cases_holdout16``'s docstring.

Citations: every source below was written from memory in this session (none was re-read): the papers' volumes,
pages and years, the books' chapters, the ECE-15 knots (UN ECE Regulation 83) and the Gray patent's number may be
off. The laws themselves do not rest on them: each is checked in tests/test_realistic_holdout16.py against an
independent solution (the Havriliak-Negami distribution of relaxation times, for one, against the HN function by
quadrature).
"""

import math

import numpy as np
from scipy.signal import cont2discrete, lfilter, ss2tf
from scipy.special import ellipj, ellipk, gammainc, ndtr

from . import mechanisms13 as _m13

#: the play sum with a linear part (the play operator's definition), shared with HOLDOUT13 ... HOLDOUT15
plays = _m13.plays


# ---- rate-independent cores ----

def triangular_plays(n, r_max, mode, w0):
    """n thresholds evenly spaced in (0, r_max) with weights of a triangular (Simpson) density rising linearly from 0
    to its mode and falling linearly to 0 at r_max, summing to 1 - w0."""
    r = (np.arange(n) + 0.5) * r_max / n
    dens = np.where(r < mode, r / mode, (r_max - r) / (r_max - mode))
    return r, (1 - w0) * dens / dens.sum()


def flat_plays(n, r_max, w0):
    """n thresholds evenly spaced in (0, r_max) with equal weights (a uniform density), summing to 1 - w0."""
    r = (np.arange(n) + 0.5) * r_max / n
    return r, np.full(n, (1 - w0) / n)


def merz_rate(v, z, r, R0, Ea):
    """The speed of each play's internal variable z: a domain wall driven by the overstress e beyond the play's band
    (v - r - z up, z - v - r down) moves at R0 exp(-Ea / e) (Merz's law of ferroelectric switching, the wall velocity
    and the inverse switching time exponential in -1 / E: Merz, "Domain formation and domain wall motions in
    ferroelectric BaTiO3 single crystals", Phys. Rev. 95 (1954) 690), and not at all inside the band."""
    up = v - r - z
    e = np.maximum(up, z - v - r)
    m = e > 0
    return np.where(m, R0 * np.exp(-Ea / np.where(m, e, 1.0)), 0.0) * np.where(up > 0, 1.0, -1.0)


def merz_plays(v, dt, r, w, w0, R0, Ea):
    """Plays whose internal variables follow :func:`merz_rate` instead of jumping to the band's edge, v linear between
    samples, by the explicit midpoint rule (second order) per sample, never stepping beyond the band's edge (which the
    exact solution approaches without crossing); virgin (z = 0). At a steady rate R a play trails its edge by Ea /
    ln(R0 / R): the loops widen with the rate, as 1 / ln(R0 / R). Returns w0 v + w . z."""
    v = np.asarray(v, float)
    z = np.zeros(len(r))
    out = np.empty_like(v)
    out[0] = w0 * v[0] + w @ z
    for k in range(1, len(v)):
        va, vb = v[k - 1], v[k]
        k1 = merz_rate(va, z, r, R0, Ea)
        k2 = merz_rate((va + vb) / 2, z + 0.5 * dt * k1, r, R0, Ea)
        zn = z + dt * k2
        zn = np.where(k2 > 0, np.minimum(zn, np.maximum(z, vb - r)), np.maximum(zn, np.minimum(z, vb + r)))
        z = zn
        out[k] = w0 * vb + w @ z
    return out


# ---- signals ----

def raised_cosine(x):
    """0 for x <= 0, (1 - cos(pi x)) / 2 between, 1 for x >= 1."""
    x = np.clip(np.asarray(x, float), 0.0, 1.0)
    return (1 - np.cos(np.pi * x)) / 2


def mackey_glass_rhs(x, x_tau, beta=0.2, gamma=0.1, p=10):
    """The Mackey-Glass delay equation dx/dt = beta x(t - tau) / (1 + x(t - tau)^p) - gamma x (Mackey & Glass,
    "Oscillation and chaos in physiological control systems", Science 197 (1977) 287; chaotic at tau = 17)."""
    return beta * x_tau / (1 + x_tau ** p) - gamma * x


def mackey_glass(N, n, x_hist, burn_steps, tau=17.0):
    """The Mackey-Glass path on a step h = tau / N (so the delayed state sits on the grid at the steps' ends), by
    classical Runge-Kutta with the delayed state at the half steps by cubic Lagrange interpolation (x_{-1} ... x_2:
    (-x_{-1} + 9 x_0 + 9 x_1 - x_2) / 16), from a constant history x_hist, after burn_steps steps. Returns n states."""
    h = tau / N
    m = burn_steps + n
    xs = [x_hist] * (N + 2)                     # xs[i + N + 1] = x at step i; steps <= 0 the history
    off = N + 1
    f = mackey_glass_rhs
    for j in range(m):
        a, b = xs[j + off - N], xs[j + off - N + 1]
        mid = (-xs[j + off - N - 1] + 9 * a + 9 * b - xs[j + off - N + 2]) / 16
        xj = xs[j + off]
        k1 = f(xj, a)
        k2 = f(xj + 0.5 * h * k1, mid)
        k3 = f(xj + 0.5 * h * k2, mid)
        k4 = f(xj + h * k3, b)
        xs.append(xj + h * (k1 + 2 * k2 + 2 * k3 + k4) / 6)
    return np.array(xs[off + burn_steps:off + burn_steps + n])


def jonswap(f, f_p, gamma=3.3):
    """The JONSWAP spectrum's shape f^-5 exp(-5/4 (f_p / f)^4) gamma^exp(-(f - f_p)^2 / (2 s^2 f_p^2)), s 0.07 below
    the peak and 0.09 above (Hasselmann et al., "Measurements of wind-wave growth and swell decay during the Joint
    North Sea Wave Project", Dtsch. Hydrogr. Z. Suppl. A 8 (1973) 12); peaked at f_p."""
    f = np.asarray(f, float)
    s = np.where(f <= f_p, 0.07, 0.09)
    return f ** -5.0 * np.exp(-1.25 * (f_p / f) ** 4) * gamma ** np.exp(-(f - f_p) ** 2 / (2 * s * s * f_p * f_p))


def sea_state(t, freqs, amps, phases):
    """A sea state by the random-phase method: sum_i amps_i cos(2 pi freqs_i t + phases_i), amps_i = sqrt(2 S(f_i)
    df) on an even grid of frequencies (the wave maker's irregular-wave synthesis)."""
    t = np.asarray(t, float)
    out = np.zeros_like(t)
    for f, a, p in zip(freqs, amps, phases):
        out += a * np.cos(2 * np.pi * f * t + p)
    return out


def sea_states(dt, peaks, durs, gammas, phases, levels, edge_s):
    """A wave maker's test programme: sea states one after another, state i a JONSWAP sea of peak peaks[i] (its
    frequencies evenly spaced over 0.5 ... 4 times the peak, as many as phases[i]) lasting durs[i], faded in and out
    over edge_s (raised cosine) and scaled so that its largest magnitude is levels[i]. Returns the path, each state's
    first sample, and the frequencies and amplitudes (before scaling)."""
    parts, starts, pos, F, A = [], [], 0, [], []
    for f_p, d, g, ph, lv in zip(peaks, durs, gammas, phases, levels):
        tt = np.arange(int(round(d / dt))) * dt
        f = np.linspace(0.5 * f_p, 4.0 * f_p, len(ph))
        a = np.sqrt(2 * jonswap(f, f_p, g) * (f[1] - f[0]))
        x = raised_cosine(tt / edge_s) * raised_cosine((tt[-1] - tt) / edge_s) * sea_state(tt, f, a, ph)
        parts.append(lv * x / np.abs(x).max())
        starts.append(pos)
        pos += len(tt)
        F.append(f)
        A.append(a)
    return np.concatenate(parts + [np.zeros(1)]), np.array(starts), np.array(F), np.array(A)


def lujan_breaths(dt, periods, amps, n_pow, holds, lead_s):
    """Breathing traces by Lujan's law a cos^(2n)(pi t / T - phi) (Lujan, Larsen, Balter & Ten Haken, "A method for
    incorporating organ motion due to breathing into 3D dose calculations", Med. Phys. 26 (1999) 715), here
    amps_k sin^(2n)(pi u) over each breath's period (u 0 ... 1: the rest at exhale, 0 V, the peak at inhale); a breath
    with holds_k > 0 is held at its peak for holds_k (a deep-inspiration breath hold) between its two halves. Starts
    with lead_s at 0 V. Returns the path and each breath's first sample."""
    parts, starts, pos = [np.zeros(int(round(lead_s / dt)))], [], int(round(lead_s / dt))
    for T, a, hold in zip(periods, amps, holds):
        m = int(round(T / dt))
        u = np.arange(m) / m
        b = a * np.sin(np.pi * u) ** (2 * n_pow)
        if hold > 0:
            half = m // 2
            b = np.r_[b[:half], np.full(int(round(hold / dt)), a), b[half:]]
        starts.append(pos)
        parts.append(b)
        pos += len(b)
    parts.append(np.zeros(1))
    return np.concatenate(parts), np.array(starts)


#: the ECE-15 elementary urban cycle as knots (s, km/h): idle, 15, 32 and 50 km/h with a step down to 35 (UN ECE
#: Regulation No. 83, Annex 4; the NEDC's urban part repeats it four times), written from memory
ECE15 = np.array([[0, 0], [11, 0], [15, 15], [23, 15], [28, 0], [49, 0], [61, 32], [85, 32], [96, 0], [117, 0],
                  [143, 50], [155, 50], [163, 35], [176, 35], [188, 0], [195, 0]], float)


def ece15_cycles(dt, compress, tops):
    """Consecutive ECE-15 urban cycles, cycle i played compress[i] times faster than real time with its speeds
    scaled so that 50 km/h is tops[i] V; piecewise linear between the knots. Returns the path and the knots."""
    kt, kv, t0 = [], [], 0.0
    for c, top in zip(compress, tops):
        kt.extend(t0 + ECE15[(0 if not kt else 1):, 0] / c)
        kv.extend(ECE15[(0 if not kv else 1):, 1] * top / 50.0)
        t0 = kt[-1]
    kt, kv = np.array(kt), np.array(kv)
    t = np.arange(int(kt[-1] / dt) + 1) * dt
    return np.interp(t, kt, kv), kt, kv


def walsh_rows(order=4):
    """The 2^order Walsh functions in sequency order: the rows of Sylvester's Hadamard matrix sorted by their number
    of sign changes, row k changing sign k times (Walsh, "A closed set of normal orthogonal functions", Amer. J. Math.
    45 (1923) 5; Beauchamp, *Walsh Functions and their Applications*, 1975)."""
    H = np.array([[1.0]])
    for _ in range(order):
        H = np.block([[H, H], [H, -H]])
    changes = (np.diff(H, axis=1) != 0).sum(axis=1)
    return H[np.argsort(changes)]


def walsh_drive(dt, ks, amps, seg_s, edge_s, rest_s, order=4):
    """Walsh functions ks (sequency order) one after another, function i as 2^order levels amps[i] wal(ks[i], j) of
    seg_s[i] each, with a rest of rest_s at 0 V before each and at the end; the levels joined by raised-cosine steps of
    edge_s (each step starts at the level's end). Returns the path and each function's first sample."""
    W = walsh_rows(order)
    levels, durs, first = [0.0], [rest_s], []
    for k, a, s in zip(ks, amps, seg_s):
        first.append(len(levels))
        levels.extend(a * W[k])
        durs.extend([s] * W.shape[1])
        levels.append(0.0)
        durs.append(rest_s)
    me_ = max(int(round(edge_s / dt)), 1)
    out, cur, pos = [], 0.0, [0]
    for lv, d in zip(levels, durs):
        m = int(round(d / dt))
        out.append(np.r_[cur + (lv - cur) * raised_cosine(np.arange(1, me_ + 1) / me_), np.full(m - me_, lv)])
        pos.append(pos[-1] + m)
        cur = lv
    return np.concatenate(out), np.array(pos)[first]


def bouncing_ball(dt, heights, g, e, floor_frac, rest_s):
    """A bouncing ball's height: from the floor (0 V) to each launch height in heights (launched at sqrt(2 g H)),
    falling back under g and bouncing with the coefficient of restitution e (each apex e^2 times the last) until an
    apex falls below floor_frac of the launch height; then a rest of rest_s on the floor before the next launch.
    Parabolic arcs u t - g t^2 / 2 (Newton), the velocity reversed at each impact. Returns the path and the apexes."""
    parts, apexes = [np.zeros(int(round(rest_s / dt)))], []
    t_carry = 0.0                                    # time already spent into the next arc at the first sample
    for H in heights:
        u = math.sqrt(2 * g * H)
        while u * u / (2 * g) >= floor_frac * H:
            T = 2 * u / g
            tt = np.arange(t_carry, T, dt)
            parts.append(u * tt - g * tt * tt / 2)
            apexes.append(u * u / (2 * g))
            t_carry = tt[-1] + dt - T
            u *= e
        parts.append(np.zeros(int(round(rest_s / dt))))
        t_carry = 0.0
    return np.concatenate(parts), np.array(apexes)


def raised_cosine_pulse(t, T, beta):
    """The raised-cosine Nyquist pulse sinc(t / T) cos(pi beta t / T) / (1 - (2 beta t / T)^2), 1 at 0 and 0 at every
    other multiple of T (no intersymbol interference), pi / 4 sinc(1 / (2 beta)) at |t| = T / (2 beta) (Proakis,
    *Digital Communications*, 2001, ch. 9)."""
    x = np.asarray(t, float) / T
    den = 1 - (2 * beta * x) ** 2
    sing = np.abs(den) < 1e-10
    val = np.sinc(x) * np.cos(np.pi * beta * x) / np.where(sing, 1.0, den)
    return np.where(sing, np.pi / 4 * np.sinc(1 / (2 * beta)), val)


def pam_signal(t, symbols, T, beta, t0, span=8):
    """Pulse-amplitude modulation: sum_k symbols_k p(t - t0 - k T), p the raised-cosine pulse truncated to +-span
    symbols."""
    t = np.asarray(t, float)
    out = np.zeros_like(t)
    for k, a in enumerate(symbols):
        c = t0 + k * T
        i0, i1 = np.searchsorted(t, [c - span * T, c + span * T])
        out[i0:i1] += a * raised_cosine_pulse(t[i0:i1] - c, T, beta)
    return out


def pendulum_swing(t, omega0, theta_max):
    """The exact swing of a frictionless pendulum theta'' = -omega0^2 sin(theta) from the bottom (theta 0, moving up)
    with amplitude theta_max: theta = 2 asin(k sn(omega0 t | k^2)), k = sin(theta_max / 2) (Jacobi's elliptic sine;
    e.g. Lawden, *Elliptic Functions and Applications*, 1989, ch. 5); period 4 K(k^2) / omega0."""
    k = math.sin(theta_max / 2)
    sn = ellipj(omega0 * np.asarray(t, float), k * k)[0]
    return 2 * np.arcsin(k * sn)


def pendulum_pushes(dt, omega0, thetas, cycles, lead_s):
    """A pendulum pushed at the bottom: swing i of amplitude thetas[i] for cycles[i] whole periods from the bottom,
    each push changing the speed at the bottom (the angle stays continuous). Starts with lead_s at rest. Returns the
    angle and each swing's start time."""
    ends = [lead_s]
    for th, c in zip(thetas, cycles):
        ends.append(ends[-1] + c * 4 * ellipk(math.sin(th / 2) ** 2) / omega0)
    t = np.arange(int(ends[-1] / dt) + 1) * dt
    out = np.zeros_like(t)
    for th, a, b in zip(thetas, ends[:-1], ends[1:]):
        sel = (t >= a) & (t < b)
        out[sel] = pendulum_swing(t[sel] - a, omega0, th)
    return out, np.array(ends[:-1])


def adsr_notes(dt, freqs, durs, peaks, attack, decay, sustain, release, gap_s):
    """Notes of a synthesiser: note i a sine of freqs[i] (from phase 0) under an attack-decay-sustain-release envelope
    (linear to its peak in attack, to sustain x peak in decay, held, linear to 0 in release at the note's end),
    durs[i] long, gap_s of silence (0 V) before each and at the end. Returns the path and each note's first sample."""
    parts, starts, pos = [], [], 0
    for f, d, p in zip(freqs, durs, peaks):
        g = np.zeros(int(round(gap_s / dt)))
        parts.append(g)
        pos += len(g)
        tt = np.arange(int(round(d / dt))) * dt
        env = np.interp(tt, [0.0, attack, attack + decay, d - release, d], [0.0, 1.0, sustain, sustain, 0.0])
        parts.append(p * env * np.sin(2 * np.pi * f * tt))
        starts.append(pos)
        pos += len(tt)
    parts.append(np.zeros(int(round(gap_s / dt))))
    return np.concatenate(parts), np.array(starts)


def gray_levels(bits=4):
    """The reflected binary (Gray) code k ^ (k >> 1), k = 0 ... 2^bits - 1 (Gray, US patent 2,632,058, 1953):
    successive codes differ in one bit, so a DAC stepped through them jumps by one binary weight at a time."""
    k = np.arange(2 ** bits)
    return k ^ (k >> 1)


def gray_staircase(dt, amp, holds, edge_s, lead_s, bits=4):
    """A DAC stepped through the Gray codes up and back down (2 x 2^bits levels), code g at amp (2 g / (2^bits - 1)
    - 1), each reached by a raised-cosine step of edge_s and then held for holds[i]; from lead_s at 0 V and back to
    0 V (held lead_s) at the end. Returns the path and the codes."""
    g = gray_levels(bits)
    codes = np.r_[g, g[::-1]]
    levels = np.r_[0.0, amp * (2 * codes / (2 ** bits - 1) - 1), 0.0]
    durs = np.r_[lead_s, np.asarray(holds) + edge_s, lead_s + edge_s]
    me_ = max(int(round(edge_s / dt)), 1)
    out, cur = [], 0.0
    for lv, d in zip(levels, durs):
        m = max(int(round(d / dt)), me_)
        out.append(np.r_[cur + (lv - cur) * raised_cosine(np.arange(1, me_ + 1) / me_), np.full(m - me_, lv)])
        cur = lv
    return np.concatenate(out), codes


def scan_session_points(survey, n_survey, centre, half, n_lines):
    """The turning points of a previous session of a scanning-probe microscope on this axis: from rest at 0 V an
    overview image (n_survey lines, triangles between +-survey), then a zoomed image (n_lines lines, triangles
    between centre -+ half), then the stage parked at 0 V. A play's state after a monotone stretch depends only on its
    end, so the turning points carry the whole history (Brokate & Sprekels, *Hysteresis and Phase Transitions*,
    1996, sec. 2.3)."""
    pts = [0.0]
    for i in range(n_survey):
        pts += [survey, -survey] if i % 2 == 0 else [-survey, survey]
    s = 1.0 if centre > pts[-1] else -1.0                # enter the zoomed area from the side the stage comes from
    for i in range(n_lines):
        pts.append(centre - s * half if i % 2 == 0 else centre + s * half)
    pts.append(0.0)
    return np.array(pts)


# ---- mechanisms ----

def hn_distribution(u, alpha, beta):
    """The Havriliak-Negami distribution of relaxation (here retardation) times over u = ln(tau / tau0): (1 / pi)
    y^(alpha beta) sin(beta theta) / (y^(2 alpha) + 2 y^alpha cos(pi alpha) + 1)^(beta / 2), y = e^u, theta =
    atan2(sin(pi alpha), y^alpha + cos(pi alpha)) (Havriliak & Negami, Polymer 8 (1967) 161; the distribution e.g. in
    Kremer & Schoenhals, *Broadband Dielectric Spectroscopy*, 2003, ch. 1), whose superposition of Debye terms is
    1 / (1 + (i omega tau0)^alpha)^beta (0 < alpha < 1, 0 < beta <= 1)."""
    y = np.exp(np.asarray(u, float))
    ya = y ** alpha
    th = np.arctan2(math.sin(math.pi * alpha), ya + math.cos(math.pi * alpha))
    return y ** (alpha * beta) * np.sin(beta * th) / (ya * ya + 2 * ya * math.cos(math.pi * alpha) + 1) ** (beta / 2) \
        / math.pi


def hn_prony(tau0, alpha, beta, u_lo=-45.0, u_hi=16.0, du=0.1):
    """Retardation times and weights of a Prony series for the HN compliance: the distribution on an even grid of
    u = ln(tau / tau0) (the trapezoid rule, exponentially accurate for this smooth integrand; the mass outside
    [u_lo, u_hi] is below 1e-3 for alpha beta >= 0.25 and alpha >= 0.5)."""
    u = np.arange(u_lo, u_hi + du / 2, du)
    return tau0 * np.exp(u), hn_distribution(u, alpha, beta) * du


def ramp_lag(x, dt, tau):
    """A first-order lag tau dy/dt = x - y of an input linear between samples, exact (ramp-invariant): y_k = a y_{k-1}
    + (g - a) x_{k-1} + (1 - g) x_k, a = exp(-dt / tau), g = (1 - a) tau / dt; at rest at x[0]."""
    x = np.asarray(x, float)
    a = math.exp(-dt / tau)
    g = -math.expm1(-dt / tau) * tau / dt
    return lfilter([1 - g, g - a], [1.0, -a], x - x[0]) + x[0]


def prony_creep(h, dt, c, taus, weights):
    """Creep by Boltzmann superposition of Kelvin elements (Findley, Lai & Onaran, *Creep and Relaxation of Nonlinear
    Viscoelastic Materials*, 1976, ch. 5): c sum_i weights_i lag_{taus_i}[h], at rest at h[0] (each element's strain
    approaching c weights_i h with its retardation time; :func:`ramp_lag` per element)."""
    h = np.asarray(h, float)
    out = np.zeros_like(h)
    for tau, w in zip(taus, weights):
        if w * c * np.abs(h).max() < 1e-12:
            continue
        out += w * (h if tau < 1e-4 * dt else ramp_lag(h, dt, tau))
    return c * out


def tanks_in_series(t, n, tau, t_open, open_s):
    """The temperature of the last of n well-mixed air volumes in series, each with a residence time tau, after a
    rectangular disturbance of open_s at their inlet from t_open (a door held open): the convolution of the pulse
    with the Erlang residence-time density t^(n-1) exp(-t / tau) / ((n-1)! tau^n) (the tanks-in-series model,
    Levenspiel, *Chemical Reaction Engineering*, 1999, ch. 14), P(n, s / tau) - P(n, (s - open_s) / tau), P the
    regularised lower incomplete gamma function, s = t - t_open."""
    s = np.asarray(t, float) - t_open
    return gammainc(n, np.clip(s, 0, None) / tau) - gammainc(n, np.clip(s - open_s, 0, None) / tau)


def loaded_potentiometer(x, ratio):
    """A potentiometer's output as a fraction of its supply, the wiper at the fraction x of the track, loaded by a
    meter of R_L = R_p / ratio: x / (1 + ratio x (1 - x)) (the loading error; e.g. Bentley, *Principles of
    Measurement Systems*, 2005, ch. 5; Doebelin, *Measurement Systems*, 2004, ch. 4)."""
    x = np.asarray(x, float)
    return x / (1 + ratio * x * (1 - x))


def potentiometer_reading(h, x0, k, ratio):
    """The stage's travel h (the core's output) read through a loaded potentiometer: the wiper at x0 + k h, the
    reading (f(x0 + k h) - f(x0)) / (k f'(x0)) scaled to slope 1 at rest, f'(x) = (1 + ratio x^2) / (1 + ratio x
    (1 - x))^2."""
    d1 = (1 + ratio * x0 * x0) / (1 + ratio * x0 * (1 - x0)) ** 2
    return (loaded_potentiometer(x0 + k * np.asarray(h, float), ratio) - loaded_potentiometer(x0, ratio)) / (k * d1)


def gas_spring_balance(y, L, kappa, gamma):
    """The force balance of a piston between two closed air chambers (each L long when centred) on a flexure, in units
    of travel: y + kappa ((1 - y / L)^-gamma - (1 + y / L)^-gamma), the polytropic law p V^gamma = const (adiabatic
    gamma 1.4 for fast strokes; e.g. Cengel & Boles, *Thermodynamics*, ch. 7), kappa = p0 A / k."""
    q = np.asarray(y, float) / L
    return y + kappa * ((1 - q) ** -gamma - (1 + q) ** -gamma)


def gas_spring_stage(x, L, kappa, gamma, iters=70):
    """The piston's travel y for the flexure's free travel x: gas_spring_balance(y) = x, by bisection (increasing in
    y on (-L, L), |y| <= |x|), scaled to slope 1 at rest (times 1 + 2 gamma kappa / L): the ends compressed."""
    x = np.asarray(x, float)
    lim = np.minimum(np.abs(x), L * (1 - 1e-12))
    lo, hi = np.where(x < 0, -lim, 0.0), np.where(x < 0, 0.0, lim)
    for _ in range(iters):
        mid = (lo + hi) / 2
        g = gas_spring_balance(mid, L, kappa, gamma) - x
        lo, hi = np.where(g < 0, mid, lo), np.where(g < 0, hi, mid)
    return (1 + 2 * gamma * kappa / L) * (lo + hi) / 2


def rc4_filter(x, dt, tau):
    """Four buffered first-order RC sections in cascade (a 24 dB/octave low-pass after a synchronous demodulator),
    each tau, for an input linear between samples: the state space discretised exactly with a first-order
    (triangle) hold; at rest at x[0]. Its group delay at low frequency is 4 tau."""
    A = (np.eye(4, k=-1) - np.eye(4)) / tau
    B = np.r_[1.0, 0.0, 0.0, 0.0][:, None] / tau
    C = np.array([[0.0, 0.0, 0.0, 1.0]])
    Ad, Bd, Cd, Dd, _ = cont2discrete((A, B, C, np.zeros((1, 1))), dt, method="foh")
    b, a = ss2tf(Ad, Bd, Cd, Dd)
    x = np.asarray(x, float)
    return lfilter(b[0], a, x - x[0]) + x[0]


def stoner_wohlfarth_lognormal(x, mu, s):
    """The hard-axis magnetisation (units of saturation) of an assembly of Stoner-Wohlfarth grains with their easy
    axes across the field, each linear up to its anisotropy field H_K and saturated beyond (Stoner & Wohlfarth, Phil.
    Trans. R. Soc. A 240 (1948) 599), H_K log-normal (ln H_K ~ N(mu, s^2)): E[clip(x / H_K)] = sign(x) (Phi((ln|x| -
    mu) / s) + |x| exp(-mu + s^2 / 2) Phi((mu - s^2 - ln|x|) / s)); its slope at 0 is exp(-mu + s^2 / 2)."""
    x = np.asarray(x, float)
    ax = np.abs(x)
    lx = np.log(np.where(ax > 0, ax, 1.0))
    m = ndtr((lx - mu) / s) + ax * math.exp(-mu + s * s / 2) * ndtr((mu - s * s - lx) / s)
    return np.where(ax > 0, np.sign(x) * m, 0.0)


def amr_reading(x, mu, s):
    """An AMR sensor in a field proportional to the stage's travel x, its free layers as in
    :func:`stoner_wohlfarth_lognormal`, scaled to slope 1 at rest."""
    return stoner_wohlfarth_lognormal(x, mu, s) / math.exp(-mu + s * s / 2)


def maxwell_wagner(v, dt, rho, tau):
    """The voltage across the active ceramic of a stack in series with a leaky bond layer (ceramic C1, an insulator;
    bond C2 shunted by R2): V1 / V = (1 + s R2 C2) / (1 + s R2 (C1 + C2)) = rho + (1 - rho) / (1 + s tau), rho = C2 /
    (C1 + C2), tau = R2 (C1 + C2): the capacitive division for fast changes, all of V once the bond's charge has leaked
    (interfacial polarisation: Maxwell, *A Treatise on Electricity and Magnetism*, 1873, vol. 1, art. 328; Wagner,
    Arch. Elektrotech. 2 (1914) 371). Exact for V linear between samples, at rest at v[0]."""
    v = np.asarray(v, float)
    return rho * v + (1 - rho) * ramp_lag(v, dt, tau)


def relay_half_period(k_u, tau, delta):
    """The half period T of the symmetric limit cycle of an on-off loop around an integrator with a lag, tau y'' + y'
    = k_u u, u = +-1 switched with the hysteresis +-delta on x - y: T - 2 tau tanh(T / (2 tau)) = 2 delta / k_u
    (by symmetry, the velocity -w at one switch is +w at the next, w = k_u tanh(T / (2 tau))). Solved by bisection."""
    lo, hi = 0.0, 2 * delta / k_u + 2 * tau
    for _ in range(200):
        mid = (lo + hi) / 2
        if mid - 2 * tau * math.tanh(mid / (2 * tau)) < 2 * delta / k_u:
            lo = mid
        else:
            hi = mid
    return (lo + hi) / 2


def relay_amplitude(k_u, tau, delta):
    """Half the peak-to-peak swing of that limit cycle: delta plus the overshoot after a switch, where the velocity w
    decays toward -k_u and passes 0 after t* = tau ln((w + k_u) / k_u): tau w - k_u t*."""
    w = k_u * math.tanh(relay_half_period(k_u, tau, delta) / (2 * tau))
    return delta + tau * w - k_u * tau * math.log((w + k_u) / k_u)


def relay_servo(x, dt, k_u, tau, delta, sub=8):
    """A hydraulic follower (tracer) whose on-off pilot valve opens fully one way or the other: the cylinder's speed
    lags the valve, tau y'' + y' = k_u u, u = +1 once x - y exceeds delta and -1 once it falls below -delta (a relay
    with hysteresis; the loop hunts in a limit cycle: Tsypkin, *Relay Control Systems*, 1984; Astrom & Hagglund,
    Automatica 20 (1984) 645), x the core's output linear between samples. Exact between switches (y = y0 + k_u u t +
    tau (w0 - k_u u) (1 - exp(-t / tau))), each switch found by bisection on a grid of dt / sub. Starts at rest at
    y = x[0] with u = +1. Returns y."""
    x = np.asarray(x, float).tolist()
    y, w, u = x[0], 0.0, 1.0
    out = np.empty(len(x))
    out[0] = y
    h = dt / sub

    def adv(y, w, u, s):
        e = math.exp(-s / tau)
        return y + k_u * u * s + tau * (w - k_u * u) * (1 - e), k_u * u + (w - k_u * u) * e

    for k in range(1, len(x)):
        x0, sl = x[k - 1], (x[k] - x[k - 1]) / dt
        t = 0.0
        for j in range(1, sub + 1):
            t1 = j * h
            while True:
                y1, w1 = adv(y, w, u, t1 - t)
                e1 = x0 + sl * t1 - y1
                if u * e1 >= -delta:
                    break
                lo, hi = 0.0, t1 - t                     # the switch inside (t, t1]: u e crosses -delta
                for _ in range(50):
                    mid = (lo + hi) / 2
                    ym, _ = adv(y, w, u, mid)
                    if u * (x0 + sl * (t + mid) - ym) >= -delta:
                        lo = mid
                    else:
                        hi = mid
                y, w = adv(y, w, u, hi)
                t += hi
                u = -u
            y, w, t = y1, w1, t1
        out[k] = y
    return out

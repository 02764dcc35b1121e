"""Mechanisms and signals of the HOLDOUT14 set (``cases_holdout14.py``), each written from its law.

Nothing here imports hystcomp. Every mechanism takes the (clean) drive, or the core's output, and returns the
response; all are causal. The sources of the laws are beside each function and in ``cases_holdout14``'s docstring.
"""

import math

import numpy as np
from scipy.interpolate import PchipInterpolator
from scipy.signal import butter, sosfilt

from . import mechanisms13 as _m13

#: the play sum with a linear part (the play operator's definition), shared with HOLDOUT13
plays = _m13.plays


# ---- the rate-independent core ----

def weibull_plays(n, r_max, scale, shape, w0):
    """n thresholds evenly spaced in (0, r_max] with weights of a Weibull density (shape / scale) (r / scale)^(shape -
    1) exp(-(r / scale)^shape) (a hump for shape > 1; Weibull, J. Appl. Mech. 18 (1951) 293), summing to 1 - w0."""
    r = (np.arange(n) + 0.5) * r_max / n
    dens = (r / scale) ** (shape - 1) * np.exp(-(r / scale) ** shape)
    return r, (1 - w0) * dens / dens.sum()


# ---- signals ----

def raised_cosine(x):
    """0 for x <= 0, (1 - cos(pi x)) / 2 between, 1 for x >= 1."""
    x = np.clip(np.asarray(x, float), 0.0, 1.0)
    return (1 - np.cos(np.pi * x)) / 2


def pchip_path(t, knot_t, knot_v):
    """The monotone piecewise-cubic Hermite interpolant through the knots (Fritsch & Carlson, "Monotone piecewise
    cubic interpolation", SIAM J. Numer. Anal. 17 (1980) 238): smooth (C1), and monotone between neighbouring knots,
    so it never overshoots them (a drive that stays inside the stroke)."""
    return PchipInterpolator(knot_t, knot_v)(np.asarray(t, float))


def prts(n_symbols, seed_state=(1, 0, 0)):
    """A pseudo-random ternary sequence: a_{k+3} = a_{k+1} + 2 a_k (mod 3), the shift register of the primitive
    polynomial x^3 + 2 x + 1 over GF(3), period 3^3 - 1 = 26, each non-zero triple of symbols once per period
    (Godfrey, *Perturbation Signals for System Identification*, 1993, ch. 3: maximum-length ternary sequences)."""
    a = list(seed_state)
    while len(a) < n_symbols:
        a.append((a[-2] + 2 * a[-3]) % 3)
    return np.array(a[:n_symbols])


def level_sequence(dt, levels, dwell_s, edge_s):
    """Each level held for dwell_s, joined by raised-cosine steps of edge_s (the step starts at the dwell's end);
    starts at levels[0]."""
    m, me_ = int(round(dwell_s / dt)), max(int(round(edge_s / dt)), 1)
    out = [np.full(m, float(levels[0]))]
    for a, b in zip(levels[:-1], levels[1:]):
        out.append(a + (b - a) * raised_cosine(np.arange(1, me_ + 1) / me_))
        out.append(np.full(m - me_, float(b)))
    return np.concatenate(out)


def sine_cycles(dt, freqs, amps):
    """Whole sine cycles one after the other, cycle i of frequency freqs[i] and amplitude amps[i] (amps[i] sin over
    one period, from 0 V to 0 V): a random-period, random-amplitude cycle sequence. Returns the path and each cycle's
    first sample."""
    parts, starts, pos = [], [], 0
    for f, a in zip(freqs, amps):
        m = max(int(round(1 / (f * dt))), 4)
        parts.append(a * np.sin(2 * np.pi * np.arange(m) / m))
        starts.append(pos)
        pos += m
    return np.concatenate(parts + [np.zeros(1)]), np.array(starts)


def pwm_drive(dt, n, f_carrier, duty, top, f_c):
    """Pulse-width modulation between 0 and `top` (carrier f_carrier, duty cycle duty(k) for carrier period k, a
    callable) through the amplifier's 2nd-order Butterworth low-pass at f_c (causal: sosfilt, from rest at 0 V)."""
    per = int(round(1 / (f_carrier * dt)))
    k = np.arange(n)
    cyc = k // per
    raw = np.where((k % per) < np.round(duty(cyc) * per), top, 0.0)
    sos = butter(2, f_c, fs=1 / dt, output="sos")
    return sosfilt(sos, raw), raw


def ou_envelope(dt, n, tau, rng, lo, hi):
    """An Ornstein-Uhlenbeck process of correlation time tau (exact AR(1) update, exp(-dt / tau)), started from its
    stationary law, mapped into [lo, hi] by lo + (hi - lo) (1 + tanh(x)) / 2 (x of unit variance; Uhlenbeck &
    Ornstein, Phys. Rev. 36 (1930) 823)."""
    a = math.exp(-dt / tau)
    e = rng.standard_normal(n) * math.sqrt(1 - a * a)
    x = np.empty(n)
    x[0] = rng.standard_normal()
    for k in range(1, n):
        x[k] = a * x[k - 1] + e[k]
    return lo + (hi - lo) * (1 + np.tanh(x)) / 2


def ou_amplitude_sine(t, f, env):
    """A sine at f whose amplitude follows the envelope env (one value per sample)."""
    return env * np.sin(2 * np.pi * f * np.asarray(t, float))


def filtered_square_sweep(dt, freqs, amps, cycles, f_c, tail_s=0.6):
    """A square wave stepping through the frequencies (`cycles` whole periods each, +amps[i] for the first half of
    each period, -amps[i] for the second), then 0 V for tail_s, through the amplifier's 2nd-order Butterworth
    low-pass at f_c (causal, from 0 V): each edge a step response with the filter's 4.3 % overshoot (Butterworth,
    Wireless Engineer 7 (1930) 536). Returns the drive and the raw square."""
    parts = []
    for f, a in zip(freqs, amps):
        m = int(round(1 / (f * dt)))
        ph = (np.arange(m * cycles) % m) / m
        parts.append(np.where(ph < 0.5, a, -a))
    raw = np.concatenate(parts + [np.zeros(int(round(tail_s / dt)))])
    sos = butter(2, f_c, fs=1 / dt, output="sos")
    return sosfilt(sos, raw), raw


def gabor_bursts(t, centres, freqs, widths, amps):
    """A train of Gabor (Gaussian-windowed sine) wavelets, sum_i a_i exp(-(t - c_i)^2 / (2 s_i^2)) sin(2 pi f_i (t -
    c_i)) (Gabor, J. IEE 93 (1946) 429: the signal of least time-frequency spread), evaluated at any instants."""
    t = np.asarray(t, float)[:, None]
    c, s = np.asarray(centres), np.asarray(widths)
    return (np.asarray(amps) * np.exp(-(t - c) ** 2 / (2 * s ** 2)) * np.sin(2 * np.pi * np.asarray(freqs) * (t - c))
            ).sum(axis=1)


def ricker_train(t, centres, widths, amps):
    """A train of Ricker (Mexican-hat) wavelets, sum_i a_i (1 - u_i^2) exp(-u_i^2 / 2), u_i = (t - c_i) / s_i (the
    negative second derivative of a Gaussian; Ricker, Geophysics 18 (1953) 10): a main lobe of height a_i between two
    side lobes of -0.446 a_i."""
    t = np.asarray(t, float)[:, None]
    u = (t - np.asarray(centres)) / np.asarray(widths)
    return (np.asarray(amps) * (1 - u * u) * np.exp(-u * u / 2)).sum(axis=1)


def arm_history(bias, a0, n_cycles):
    """The turning points of an anhysteretic magnetisation (ARM) and the removal of its bias: an alternating field
    decaying linearly from a0 to 0 about a steady bias, then the bias ramped to 0 (Rimbert, C. R. Acad. Sci. 248
    (1959) 2612; Dunlop & Ozdemir, *Rock Magnetism*, 1997, ch. 11: anhysteretic remanence). From the virgin state at
    0 V: 0, bias + a0, bias - a_1, ..., bias, 0."""
    amps = a0 * (1 - np.arange(2 * n_cycles) / (2 * n_cycles))
    sign = np.where(np.arange(2 * n_cycles) % 2 == 0, 1.0, -1.0)
    return np.r_[0.0, bias + sign * amps, bias, 0.0]


# ---- mechanisms ----

def schapery_creep(u, dt, comps, taus, u_ref, kappa, lam):
    """Creep by Schapery's single-integral nonlinear viscoelastic law (Schapery, "On the characterization of
    nonlinear viscoelastic materials", Polym. Eng. Sci. 9 (1969) 295) with g0 = g1 = 1, a Prony series of transient
    compliances (c_j, tau_j), the stress factor g2 = 1 + kappa (u / u_ref)^2 and the stress shift factor a =
    exp(-lam |u| / u_ref) of the reduced time psi = int dt / a: each element obeys de_j/dpsi = (c_j g2(u) u - e_j) /
    tau_j, exact per sample with u held (e_j relaxes by exp(-dt / (tau_j a(u)))). Relaxed at the start."""
    u = np.asarray(u, float)
    comps, taus = np.asarray(comps, float), np.asarray(taus, float)
    g2 = 1 + kappa * (u / u_ref) ** 2
    a = np.exp(-lam * np.abs(u) / u_ref)
    e = comps * g2[0] * u[0]
    out = np.empty_like(u)
    for k in range(len(u)):
        out[k] = e.sum()
        target = comps * g2[k] * u[k]
        e = target + (e - target) * np.exp(-dt / (taus * a[k]))
    return out


def fickian_uptake(t, t_s, tau_d, terms=200):
    """The fraction of its final moisture a plane sheet (thickness 2 l, both faces exposed) has absorbed a time t -
    t_s after a step in the ambient humidity, by Fick's second law: 1 - sum_m 8 / ((2m + 1)^2 pi^2) exp(-(2m + 1)^2
    pi^2 (t - t_s) / (4 tau_d)), tau_d = l^2 / D (Crank, *The Mathematics of Diffusion*, 2nd ed., 1975, eq. 4.18);
    (2 / sqrt(pi)) sqrt((t - t_s) / tau_d) at first (used below 0.05 tau_d, where the series converges slowly and the
    short-time series' further terms, ierfc(n / sqrt(0.05)), are below 1e-9), exponential at last; 0 before the
    step."""
    tp = np.clip(np.asarray(t, float) - t_s, 0.0, None)
    m = 2 * np.arange(terms)[:, None] + 1
    s = (8 / (m ** 2 * np.pi ** 2) * np.exp(-(m ** 2) * np.pi ** 2 * tp[None, :] / (4 * tau_d))).sum(axis=0)
    early = 2 / math.sqrt(math.pi) * np.sqrt(tp / tau_d)      # Crank's short-time series, its ierfc terms < 1e-9
    return np.where(tp < 0.05 * tau_d, early, 1 - s)


def eddy_field_separation(v, dt, k, r, w, w0, sub=3):
    """A magnetic core whose applied field v splits into the static hysteresis field H and the classical eddy-current
    field of a lamination, v = H + k dB/dt with B = w0 H + sum_i w_i play_{r_i}[H] (loss separation, k = sigma d^2 /
    12 for a sheet of thickness d: Bertotti, *Hysteresis in Magnetism*, 1998, ch. 12; the dynamic field added to the
    static loop: Zirka, Moroz, Marketos & Moses, Physica B 343 (2004) 90). B lags by a time k dB/dH, long on the
    steep parts of the loop and short just after a reversal (only w0 moves). Backward Euler on `sub` steps per
    sample, v linear between samples; each step's H solves H + (k / h) (B(H) - B_old) = v exactly (B piecewise linear
    and convex in the direction of motion: Newton ends in a few steps). Virgin at H = v[0]. Returns B and H."""
    v = np.asarray(v, float)
    r, w = np.asarray(r, float), np.asarray(w, float)
    h = dt / sub
    q = k / h
    H = float(v[0])
    z = np.clip(np.zeros_like(r), H - r, H + r)
    B = np.empty_like(v)
    Hs = np.empty_like(v)
    B[0], Hs[0] = w0 * H + w @ z, H
    vl = v.tolist()
    for n in range(1, len(vl)):
        for j in range(1, sub + 1):
            target = vl[n - 1] + (vl[n] - vl[n - 1]) * j / sub
            if target == H:
                continue
            s = 1.0 if target > H else -1.0
            bp = z + s * r                               # a play starts to move once H passes its breakpoint
            x = H
            for _ in range(60):
                moving = (bp - x) * s < 0
                g = x - target + q * (w0 * (x - H) + s * (w[moving] * (x - bp[moving]) * s).sum())
                slope = 1 + q * (w0 + w[moving].sum())
                x_new = x - g / slope
                if abs(x_new - x) <= 1e-13 * (1 + abs(x)):
                    x = x_new
                    break
                x = x_new
            H = x
            np.minimum(np.maximum(z, H - r), H + r, out=z)
        Hs[n] = H
        B[n] = w0 * H + w @ z
    return B, Hs


def belleville_force(delta, h):
    """The Almen-Laszlo load of a disc (Belleville) spring deflected by delta (in units of its thickness t, h its
    free cone height over t): F = delta ((h - delta) (h - delta / 2) + 1) in units of 4 E t^4 / ((1 - nu^2) K1 D^2)
    (Almen & Laszlo, Trans. ASME 58 (1936) 305). Stiffest unloaded, softest at delta = h (slope 1 - h^2 / 2):
    monotone for h < sqrt(2)."""
    d = np.asarray(delta, float)
    return d * ((h - d) * (h - d / 2) + 1)


def belleville_deflection(f, h, iters=70):
    """The deflection at the load f >= 0 (the inverse of :func:`belleville_force`, monotone for h < sqrt(2)), by
    bisection on [0, 2 h + f + 1] (F >= delta for delta >= 2 h, so the root lies below max(2 h, f))."""
    f = np.asarray(f, float)
    lo, hi = np.zeros_like(f), 2 * h + np.abs(f) + 1
    for _ in range(iters):
        mid = (lo + hi) / 2
        low = belleville_force(mid, h) < f
        lo, hi = np.where(low, mid, lo), np.where(low, hi, mid)
    return (lo + hi) / 2


def belleville_output(x, h, delta0, force_per_unit):
    """The stage's travel across a preloaded disc spring that carries the core's force: delta(F0 + x force_per_unit)
    - delta0 (F0 = F(delta0) the preload), scaled to slope 1 at the preload."""
    f0 = belleville_force(delta0, h)
    slope0 = (h - delta0) * (h - delta0 / 2) + 1 - delta0 * ((h - delta0 / 2) + (h - delta0) / 2)
    return (belleville_deflection(f0 + force_per_unit * np.asarray(x, float), h) - delta0) * slope0 / force_per_unit


def brillouin(x, J):
    """The Brillouin function B_J(x) = ((2J + 1) / 2J) coth((2J + 1) x / 2J) - (1 / 2J) coth(x / 2J): the mean
    moment <m> / J of a moment J in the field (x = g mu_B J B / kT; Brillouin, J. Phys. Radium 8 (1927) 74; Kittel,
    *Introduction to Solid State Physics*, ch. 11); tanh for J = 1/2, Langevin's L for J -> infinity; slope (J + 1) /
    (3 J) at 0 (the series is used for |x| < 1e-4)."""
    x = np.asarray(x, float)
    a, b = (2 * J + 1) / (2 * J), 1 / (2 * J)
    small = np.abs(x) < 1e-4
    xs = np.where(small, 1.0, x)
    full = a / np.tanh(a * xs) - b / np.tanh(b * xs)
    return np.where(small, (J + 1) / (3 * J) * x, full)


def brillouin_output(x, x_c, x_s, J):
    """An output that saturates by the Brillouin law about x_c: x_c + x_s B_J(3 J (x - x_c) / ((J + 1) x_s)) (slope 1
    at x_c, x_s the saturation value)."""
    return x_c + x_s * brillouin(3 * J * (np.asarray(x, float) - x_c) / ((J + 1) * x_s), J)


def gaussian_fir(y, sigma):
    """A causal linear-phase FIR of Gaussian weights, g_k proportional to exp(-(k - m)^2 / (2 sigma^2)), k = 0 ... 2m,
    m = ceil(3 sigma) (the Gaussian profile filter of ISO 16610-21:2011, made causal by a delay of m samples: group
    delay m exactly, by symmetry). Starts from rest at y[0]. Returns the output and m."""
    m = int(math.ceil(3 * sigma))
    k = np.arange(2 * m + 1)
    g = np.exp(-(k - m) ** 2 / (2 * sigma ** 2))
    g /= g.sum()
    y = np.asarray(y, float)
    pad = np.r_[np.full(2 * m, y[0]), y]
    return np.convolve(pad, g, mode="valid"), m


def gap_sensor(x, g0, g):
    """A single-ended capacitive gap sensor read linearly in capacitance: C = eps A / (g - x) (parallel plates, g the
    gap at rest, x the target's approach; Baxter, *Capacitive Sensors*, 1997, ch. 2), calibrated at g0 as g0^2 / (g -
    x) - g0: x + x^2 / g0 + ... (slope 1 at rest, convex: asymmetric); a gap g that changes (thermal expansion of the
    mount) shifts the offset and the gain together."""
    return g0 * g0 / (np.asarray(g, float) - np.asarray(x, float)) - g0


def toggle_latch(v, trigger, release, step):
    """A push-push (toggle) latch: a bistable detent that flips between 0 and `step` each time the stroke passes
    `trigger` after having come back below `release` (a cam follower that parks alternately high and low, as in a
    retractable pen's rotary cam; a T flip-flop in mechanics). Starts at 0, armed. Rate independent; under repeated
    equal strokes the output repeats every two strokes, not every stroke."""
    out = np.empty(len(v))
    state, armed = 0.0, True
    for k, x in enumerate(np.asarray(v, float).tolist()):
        if armed and x >= trigger:
            state = step - state
            armed = False
        elif not armed and x <= release:
            armed = True
        out[k] = state
    return out

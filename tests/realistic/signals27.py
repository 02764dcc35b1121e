"""Excitation signals of the HOLDOUT27 set (``cases_holdout27.py``), each written from its source; the mechanisms are
in :mod:`.mechanisms27`.

Citations were written from memory in this session (none was re-read; volumes, pages and years may be off); the
signals are checked in tests/test_realistic_holdout27.py against independent solutions (solve_ivp, brentq, closed
forms, quadrature, scipy's own routines).
"""

import math

import numpy as np
from scipy.integrate import solve_ivp
from scipy.special import erfc

from .mechanisms19 import raised_cosine


# ---- the swinging spring (the clean case) ----

def swinging_spring_rhs(t, s):
    """A mass on a spring swinging in a vertical plane, tuned to the 2:1 resonance of its bounce and its swing (Vitt &
    Gorelik 1933; Lynch, J. Phys. A 35 (2002) 1; units: the hanging length 1, the swing's angular frequency 1, so g = 1
    and the spring's k / m = 4, its natural length 3/4): (x, z, x', z'), z up."""
    x, z, u, w = s
    r = math.hypot(x, z)
    f = 4.0 * (1.0 - 0.75 / r)
    return [u, w, -f * x, -f * z - 1.0]


def swinging_spring_energy(s):
    """(x'^2 + z'^2) / 2 + 2 (r - 3/4)^2 + z, conserved."""
    x, z, u, w = (np.asarray(q, float) for q in s)
    return 0.5 * (u * u + w * w) + 2.0 * (np.hypot(x, z) - 0.75) ** 2 + z


def swinging_spring(t, omega_p, stretch, nudge):
    """x of the swinging spring at the times t (s), its swing at omega_p rad/s, released stretched by `stretch` below
    its hanging point with a sideways nudge `nudge` (units of the length and the swing's frequency): it bounces at
    first, the swing grows out of the bounce, takes its energy and gives it back, again and again (the 2:1 resonance's
    exchange). DOP853, rtol 1e-11."""
    tau = np.asarray(t, float) * omega_p
    s0 = [0.0, -1.0 - stretch, nudge, 0.0]
    sol = solve_ivp(swinging_spring_rhs, (tau[0], tau[-1]), s0, t_eval=tau, method="DOP853", rtol=1e-11, atol=1e-12)
    return sol.y[0], sol.y


# ---- a scuba diver's depth (the creep case) ----

def path_through(t, keys):
    """A path linear between keys (t_i, x_i) in time order, held at the ends."""
    kt = np.array([k[0] for k in keys], float)
    kx = np.array([k[1] for k in keys], float)
    return np.interp(np.asarray(t, float), kt, kx)


def dive_keys(t0, legs, descent, ascent, speed):
    """The keys of a dive's depth (m) from the surface: legs [(depth, bottom minutes)] in order (deepest first: a
    multilevel dive works its way up), the descent at `descent` m/min, every ascent at `ascent` m/min (a recreational
    table's 9 or 10 m/min; 18 m/min down), a safety stop of 3 min at 5 m, surfacing; all `speed` times faster."""
    keys, tc, d = [(t0, 0.0)], t0, 0.0
    for depth, minutes in legs:
        rate = descent if depth > d else ascent
        tc += abs(depth - d) / rate * 60 / speed
        keys.append((tc, depth))
        tc += minutes * 60 / speed
        keys.append((tc, depth))
        d = depth
    tc += (d - 5.0) / ascent * 60 / speed
    keys.append((tc, 5.0))
    tc += 3 * 60 / speed
    keys.append((tc, 5.0))
    tc += 5.0 / ascent * 60 / speed
    keys.append((tc, 0.0))
    return keys


# ---- a tennis rally (the rate case) ----

def drag_flight(s, x0, u0, k):
    """The ball's position along the court s seconds after it leaves x0 at the horizontal speed u0 (signed), under
    quadratic air drag u' = -k u |u| (the vertical motion's coupling left out): x0 + sign(u0) ln(1 + k |u0| s) / k."""
    s = np.asarray(s, float)
    return x0 + np.sign(u0) * np.log1p(k * abs(u0) * s) / k


def drag_time_to(dx, u0, k):
    """The time to travel dx (> 0) from the speed |u0|: (exp(k dx) - 1) / (k |u0|); and the speed there, |u0| exp(-k
    dx)."""
    return math.expm1(k * dx) / (k * abs(u0)), abs(u0) * math.exp(-k * dx)


def rally(shots, k, e_x):
    """The pieces of a rally: shots [(t_hit, x_hit, u0, x_bounce or None, x_next)]: the ball leaves x_hit at u0 toward
    x_next, loses the fraction 1 - e_x of its horizontal speed where it bounces (x_bounce; a volley takes it on the
    full), and is struck at x_next. Returns [(t_start, x_start, u_start)] flight pieces and the end time."""
    pieces = []
    for t_h, x_h, u0, x_b, x_n in shots:
        sgn = math.copysign(1.0, u0)
        if x_b is not None:
            tb, ub = drag_time_to(abs(x_b - x_h), u0, k)
            pieces.append((t_h, x_h, u0))
            pieces.append((t_h + tb, x_b, sgn * e_x * ub))
            tn, _ = drag_time_to(abs(x_n - x_b), e_x * ub, k)
            t_end = t_h + tb + tn
        else:
            pieces.append((t_h, x_h, u0))
            tn, _ = drag_time_to(abs(x_n - x_h), u0, k)
            t_end = t_h + tn
    return pieces, t_end


def rally_path(t, pieces, k):
    """The ball's position through flight pieces (t_start, x_start, u_start) in time order, each until the next."""
    t = np.asarray(t, float)
    x = np.zeros_like(t)
    starts = [p[0] for p in pieces[1:]] + [np.inf]
    for (t0, x0, u0), t1 in zip(pieces, starts):
        m = (t >= t0) & (t < t1)
        x[m] = drag_flight(t[m] - t0, x0, u0, k)
    return x


# ---- a pendulum-wave demonstration (the drift case) ----

def pendulum_wave(t, t_rel, freqs, A, gamma, pull):
    """The mean swing of pendulums of the frequencies freqs (Hz; (K + j) / Gamma: in step again after Gamma s), pulled
    aside together by a raised cosine over `pull` s to A and released at t_rel, each then A e^(-gamma s) (cos w s +
    (gamma / w) sin w s) (released from rest, lightly damped)."""
    t = np.asarray(t, float)
    x = A * raised_cosine((t - (t_rel - pull)) / pull)
    m = t >= t_rel
    s = t[m] - t_rel
    acc = np.zeros_like(s)
    for f in freqs:
        w = 2 * math.pi * f
        acc += np.exp(-gamma * s) * (np.cos(w * s) + gamma / w * np.sin(w * s))
    x[m] = A * acc / len(freqs)
    return x


# ---- a heavy bag worked by a boxer (the asymmetry case) ----

def damped_free(s, y0, v0, w, zeta):
    """y and y' of y'' + 2 zeta w y' + w^2 y = 0 from (y0, v0), underdamped, in closed form."""
    s = np.asarray(s, float)
    wd = w * math.sqrt(1 - zeta * zeta)
    sig = zeta * w
    b = (v0 + sig * y0) / wd
    ex, co, si = np.exp(-sig * s), np.cos(wd * s), np.sin(wd * s)
    return ex * (y0 * co + b * si), ex * ((-sig * y0 + wd * b) * co + (-sig * b - wd * y0) * si)


def heavy_bag(t, punches, w, zeta):
    """The bag's swing (a pendulum, small angles: w, zeta) from rest, each punch (time, dv) changing its velocity by dv
    at once (a short impact: momentum, the bag's position continuous). Returns x."""
    t = np.asarray(t, float)
    x = np.zeros_like(t)
    y, v, tp = 0.0, 0.0, None
    starts = [p[0] for p in punches[1:]] + [np.inf]
    for (tk, dv), t1 in zip(punches, starts):
        if tp is not None:
            y, v = (float(q) for q in damped_free(tk - tp, y, v, w, zeta))
        v += dv
        m = (t >= tk) & (t < t1)
        x[m] = damped_free(t[m] - tk, y, v, w, zeta)[0]
        tp = tk
    return x


# ---- a hand saw's strokes (the saturation case) ----

def saw_strokes(t, t0, strokes):
    """The blade's position through strokes [(length, push_s, return_s, pause_after)], each a push from -length / 2 to
    +length / 2 (the cut, slower) and a return (faster), both with a raised-cosine speed, centred on the kerf; the
    blade taken from its rest at 0 to the back of the first stroke by a raised cosine over the first push's time.
    Returns the position and the keys."""
    keys = [(t0, 0.0)]
    tc = t0
    L0, p0 = strokes[0][0], strokes[0][1]
    tc += p0
    keys.append((tc, -L0 / 2))
    for L, push, ret, pause in strokes:
        if keys[-1][1] != -L / 2:
            tc += ret * 0.5
            keys.append((tc, -L / 2))
        tc += push
        keys.append((tc, L / 2))
        tc += ret
        keys.append((tc, -L / 2))
        if pause > 0:
            tc += pause
            keys.append((tc, -L / 2))
    return cosine_path(t, keys), keys


def cosine_path(t, keys):
    """A raised cosine from each key (t_i, x_i) to the next, held at the ends."""
    t = np.asarray(t, float)
    x = np.full_like(t, keys[0][1])
    for (t0, x0), (t1, x1) in zip(keys[:-1], keys[1:]):
        m = (t >= t0) & (t < t1)
        x[m] = x0 + (x1 - x0) * raised_cosine((t[m] - t0) / (t1 - t0))
    x[t >= keys[-1][0]] = keys[-1][1]
    return x


# ---- GMSK (the delay case) ----

def gmsk_q(t, T, BT):
    """The phase pulse of GMSK (Murota & Hirade, IEEE Trans. Commun. 29 (1981) 1044): the integral of the frequency
    pulse g(t) = (1 / 2T) [Q(c (t / T - 1/2)) - Q(c (t / T + 1/2))], c = 2 pi BT / sqrt(ln 2) (a rectangle of one bit
    through a Gaussian filter of bandwidth B), in closed form: with F(u) = u erfc(u) - exp(-u^2) / sqrt(pi) (an
    antiderivative of erfc), q(t) = 1/2 + (F(a (t/T - 1/2)) - F(a (t/T + 1/2))) / (4 a), a = c / sqrt 2; 0 long
    before the bit and 1/2 long after."""
    c = 2 * math.pi * BT / math.sqrt(math.log(2))
    a = c / math.sqrt(2)
    u = np.asarray(t, float) / T

    def F(z):
        return z * erfc(z) - np.exp(-z * z) / math.sqrt(math.pi)
    return 0.5 + (F(a * (u - 0.5)) - F(a * (u + 0.5))) / (4 * a)


def gmsk_phase(t, bits, T, BT, t0):
    """The phase 2 pi h sum_k a_k q(t - t0 - k T), h = 1/2 (MSK's: each bit turns it by +-pi / 2), a_k = +-1."""
    t = np.asarray(t, float)
    ph = np.zeros_like(t)
    for k, b in enumerate(bits):
        ph += math.pi * (1.0 if b else -1.0) * gmsk_q(t - t0 - k * T, T, BT)
    return ph


# ---- a Ferris wheel's cabin (the initial-state case) ----

def ferris_angle(t, t0, n_cab, move_s, dwell_s, n_load, turns, turn_s, ramp_s):
    """The wheel's angle: n_load loading steps of 2 pi / n_cab (one cabin on, the wheel moved by a raised cosine over
    move_s, then dwell_s at the platform), then `turns` continuous turns (ramped up and down by raised-cosine speeds of
    ramp_s, turn_s a turn at full speed). Returns the angle and the times at which the run ends."""
    t = np.asarray(t, float)
    th = np.zeros_like(t)
    tc, ang = t0, 0.0
    step = 2 * math.pi / n_cab
    for _ in range(n_load):
        tc += dwell_s
        m = t >= tc
        th[m] = ang + step * raised_cosine((t[m] - tc) / move_s)
        tc += move_s
        ang += step
    tc += dwell_s
    total = 2 * math.pi * turns
    w = 2 * math.pi / turn_s
    # speed: ramp up over ramp_s (angle w ramp_s / 2), cruise, ramp down (w ramp_s / 2)
    cruise = (total - w * ramp_s) / w
    m = t >= tc
    s = t[m] - tc
    a1 = np.where(s < ramp_s, w * (s - ramp_s / math.pi * np.sin(math.pi * s / ramp_s)) / 2, w * ramp_s / 2)
    a2 = w * np.clip(s - ramp_s, 0.0, cruise)
    s3 = np.clip(s - ramp_s - cruise, 0.0, ramp_s)
    a3 = w * (s3 - (s3 - ramp_s / math.pi * np.sin(math.pi * s3 / ramp_s)) / 2)
    th[m] = ang + a1 + a2 + a3
    return th, tc + 2 * ramp_s + cruise


# ---- a wind tunnel's angle-of-attack programme (the pair) ----

def pitch_programme(t0, step, n_steps, hold_s, move_s, osc):
    """Keys and sinusoids of a tunnel's programme: a pitch-pause polar (from 0 up by `step` n_steps times, down to
    -n_steps steps and back to 0, each step a raised-cosine move of move_s held hold_s for the balance to settle), then
    sinusoidal pitching about 0 [(amplitude, frequency, cycles)] (a dynamic test at several reduced frequencies), each
    a whole number of cycles faded in and out over one cycle. Returns (keys, [(t_start, A, f, n)], t_end)."""
    keys, tc = [(t0, 0.0)], t0
    seq = list(range(1, n_steps + 1)) + list(range(n_steps - 1, -n_steps - 1, -1)) + list(range(-n_steps + 1, 1))
    for j in seq:
        tc += move_s
        keys.append((tc, j * step))
        tc += hold_s
        keys.append((tc, j * step))
    sines = []
    for A, f, n in osc:
        sines.append((tc, A, f, n))
        tc += n / f + 0.5
    return keys, sines, tc


def pitch_path(t, keys, sines):
    """The programme's angle: the keys' raised-cosine path plus each sinusoid A w(s) sin(2 pi f s), w a raised-cosine
    fade over the first and the last cycle."""
    t = np.asarray(t, float)
    x = cosine_path(t, keys)
    for t0, A, f, n in sines:
        s = t - t0
        m = (s >= 0) & (s < n / f)
        T1 = 1 / f
        env = raised_cosine(s[m] / T1) * raised_cosine((n / f - s[m]) / T1)
        x[m] += A * env * np.sin(2 * math.pi * f * s[m])
    return x


# ---- a two-tone (hi-lo) alarm on a steady tone (the out-of-vocabulary case) ----

def hilo_phase(k, N_lo, segments):
    """The phase (in cycles) at the samples k of a tone of N_lo samples a period, interrupted by segments [(k_start,
    N_hi, cycles)] during which the period is N_hi samples (the hi tone of a two-tone alarm), each a whole number of
    cycles, so that the phase is whole at their ends and the lo tone returns in step. Returns phase mod 1."""
    k = np.asarray(k)
    ph = np.mod(k, N_lo) / N_lo
    for k0, N_hi, cyc in segments:
        L = N_hi * cyc
        m = (k >= k0) & (k < k0 + L)
        # during the segment the phase runs at 1 / N_hi from its value at k0 (k0 a multiple of N_lo: phase 0)
        ph[m] = np.mod(k[m] - k0, N_hi) / N_hi
        after = k >= k0 + L
        ph[after] = np.mod(k[after] - (k0 + L), N_lo) / N_lo
    return ph


__all__ = ["swinging_spring_rhs", "swinging_spring_energy", "swinging_spring", "path_through", "dive_keys",
           "drag_flight", "drag_time_to", "rally", "rally_path", "pendulum_wave", "damped_free", "heavy_bag",
           "saw_strokes", "cosine_path", "gmsk_q", "gmsk_phase", "ferris_angle", "pitch_programme", "pitch_path",
           "hilo_phase"]

"""Excitation signals of the HOLDOUT22 set (``cases_holdout22.py``), each written from its source; the mechanisms are
in :mod:`.mechanisms22`.

Citations were written from memory in this session (none was re-read; volumes, pages and years may be off); the
signals are checked in tests/test_realistic_holdout22.py against independent solutions (solve_ivp, brentq, closed
forms, quadrature, a finer grid).
"""

import math

import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import brentq
from scipy.special import betainc

from .mechanisms19 import raised_cosine


# ---- Thomas's cyclically symmetric attractor (the clean case) ----

def thomas_rhs(t, s, b):
    """x' = sin y - b x, y' = sin z - b y, z' = sin x - b z (R. Thomas, Int. J. Bifurc. Chaos 9 (1999) 1889; a
    'labyrinth chaos' of three cyclically coupled feedback circuits, chaotic with both signs of x for b about 0.18 ...
    0.187)."""
    x, y, z = s
    return [math.sin(y) - b * x, math.sin(z) - b * y, math.sin(x) - b * z]


def thomas_x(t, units, start, b, settle=300.0):
    """x at the times t (s), `units` of Thomas's time a second, after `settle` units from `start` (DOP853, rtol
    1e-11). Returns x and the state the record starts from."""
    s0 = solve_ivp(thomas_rhs, (0, settle), np.array(start, float), args=(b,), method="DOP853", rtol=1e-11,
                   atol=1e-12).y[:, -1]
    tau = np.asarray(t, float) * units
    sol = solve_ivp(thomas_rhs, (tau[0], tau[-1]), s0, args=(b,), t_eval=tau, method="DOP853", rtol=1e-11,
                    atol=1e-12)
    return sol.y[0], s0


# ---- a kiln's firing schedule (the creep case) ----

def kiln_segments(start, segments, lead):
    """A programmable kiln controller's schedule: from `start` (V) at rest for `lead` s, then segments ('ramp', rate
    V/s, target, hold s): a linear ramp at the rate to the target, held; or ('cool', tau s, target, hold s): the
    kiln switched off, cooling by Newton's law toward the room at 0 V, T0 exp(-s / tau), until the target is
    reached, then held by the controller (e.g. Hamer & Hamer, *The Potter's Dictionary*, on firing
    schedules: slow early ramps, soaks at the top, controlled and natural cooling). Returns pieces (t0, kind, T0,
    target, par, duration, hold)."""
    pieces, tc, lvl = [], lead, start
    for kind, par, target, hold in segments:
        if kind == "ramp":
            dur = abs(target - lvl) / par
        else:
            dur = par * math.log(lvl / target)
        pieces.append((tc, kind, lvl, target, par, dur, hold))
        tc += dur + hold
        lvl = target
    return pieces, tc


def kiln_schedule(t, start, pieces):
    """The temperature (in V) of :func:`kiln_segments`' pieces at the times t."""
    t = np.asarray(t, float)
    v = np.full_like(t, start)
    for t0, kind, T0, target, par, dur, hold in pieces:
        m = t >= t0
        s = np.clip(t[m] - t0, 0, dur)
        if kind == "ramp":
            v[m] = T0 + math.copysign(par, target - T0) * s
        else:
            v[m] = T0 * np.exp(-s / par)
        v[m & (t >= t0 + dur)] = target
    return v


# ---- rowing strokes (the rate-dependence case) ----

def stroke_profile(s, a, b):
    """A skewed bell of handle speed: the regularised incomplete beta function I_s(a, b), 0 at s = 0, 1 at s = 1,
    its speed peaking at (a - 1) / (a + b - 2)."""
    return betainc(a, b, np.clip(np.asarray(s, float), 0.0, 1.0))


def rowing_handle(t, moves, start):
    """The handle's position: moves (t0, T, to, kind), each from where the last ended: a drive ('drive', from the
    catch to the finish) with the speed profile I(2, 2.6) (the legs, then the back and arms: a peak before
    mid-drive) or a recovery ('recovery', back to the next catch) with I(2.4, 2) (arms and body first, the slide
    last); held between (e.g. Kleshnev's ergometer biomechanics: the drive nearly fixed at 0.7 ... 0.9 s, the recovery
    shrinking with the stroke rate). `start` before the first."""
    t = np.asarray(t, float)
    v = np.full_like(t, start)
    lvl = start
    for t0, T, to, kind in moves:
        a, b = (2.0, 2.6) if kind == "drive" else (2.4, 2.0)
        m = t >= t0
        v[m] = lvl + (to - lvl) * stroke_profile((t[m] - t0) / T, a, b)
        lvl = to
    return v


# ---- a Geneva wheel (the drift case) ----

def geneva_angle(theta, n):
    """The wheel's angle of an external Geneva drive with n slots turned by the crank's cumulative angle theta (the
    pin enters tangentially: crank radius / centre distance lam = sin(pi / n)); during engagement, |theta - 2 pi k|
    < alpha = pi / 2 - pi / n, tan(phi) = lam sin(theta) / (1 - lam cos(theta)) (e.g. Norton, *Design of Machinery*,
    2004, on intermittent motion); a dwell between. Cumulative: 2 pi k / n + phi."""
    theta = np.asarray(theta, float)
    lam = math.sin(math.pi / n)
    alpha = math.pi / 2 - math.pi / n
    k = np.round(theta / (2 * np.pi))
    th = theta - 2 * np.pi * k
    phi = np.arctan2(lam * np.sin(th), 1 - lam * np.cos(th))
    phi = np.where(th > alpha, math.pi / n, np.where(th < -alpha, -math.pi / n, phi))
    return 2 * np.pi * k / n + phi


def motor_crank(t, commands, tau_m):
    """The crank's cumulative angle of a motor whose speed follows a piecewise-constant command (t_k, omega_k rad/s,
    from 0 before the first) through a first-order lag tau_m (an induction motor on a ramp-less drive): omega =
    omega_k + (omega(t_k) - omega_k) exp(-(t - t_k) / tau_m), integrated in closed form."""
    t = np.asarray(t, float)
    th = np.zeros_like(t)
    w0, a0 = 0.0, 0.0                                  # speed and angle at the current command's start
    times = [c[0] for c in commands] + [np.inf]
    for (tk, wk), tn in zip(commands, times[1:]):
        m = (t >= tk) & (t < tn)
        s = t[m] - tk
        th[m] = a0 + wk * s + (w0 - wk) * tau_m * -np.expm1(-s / tau_m)
        if np.isfinite(tn):
            s_end = tn - tk
            a0 += wk * s_end + (w0 - wk) * tau_m * -math.expm1(-s_end / tau_m)
            w0 = wk + (w0 - wk) * math.exp(-s_end / tau_m)
    return th


# ---- a tumbling T-handle (the asymmetry case) ----

def euler_rhs(t, w, I1, I2, I3):
    """Euler's equations of a torque-free rigid body in its principal axes (Euler 1765; Landau & Lifshitz,
    *Mechanics*, sec. 37): I1 w1' = (I2 - I3) w2 w3 and cyclically. Spun about the intermediate axis (I1 < I2 < I3)
    it flips over and back at regular intervals (the Dzhanibekov effect, the tennis-racket theorem)."""
    w1, w2, w3 = w
    return [(I2 - I3) * w2 * w3 / I1, (I3 - I1) * w3 * w1 / I2, (I1 - I2) * w1 * w2 / I3]


def throw_spin(s, inertia, eps, units):
    """The intermediate-axis rate w2 / w0 at the times s (s) after a throw spun at w0 = 1 about axis 2 with
    perturbations eps = (e1, e3) on the other axes, `units` of the body's time a second (DOP853, rtol 1e-11)."""
    s = np.asarray(s, float)
    I1, I2, I3 = inertia
    w = [eps[0], math.sqrt(1.0 - eps[0] ** 2 - eps[1] ** 2), eps[1]]
    sol = solve_ivp(euler_rhs, (0, s[-1] * units), w, args=(I1, I2, I3), t_eval=s * units, method="DOP853",
                    rtol=1e-11, atol=1e-13)
    return sol.y[1]


def throws(t, plan, ramp):
    """An astronaut's throws of a T-handle read by a gyro on its intermediate axis: plan (t0, T, inertia, eps, units,
    sign), each spin faded in and out by raised cosines over `ramp` s (caught and thrown again), 0 between."""
    t = np.asarray(t, float)
    v = np.zeros_like(t)
    for t0, T, inertia, eps, units, sign in plan:
        m = (t >= t0) & (t <= t0 + T)
        s = t[m] - t0
        env = raised_cosine(s / ramp) * raised_cosine((T - s) / ramp)
        v[m] = sign * env * throw_spin(s, inertia, eps, units)
    return v


# ---- clothoid lane changes (the saturation case) ----

def clothoid_curvature(s, kappa_m):
    """A lane change of unit length made of four clothoid (Euler spiral) arcs: the curvature rises linearly to kappa_m
    over the first quarter, falls to 0, to -kappa_m and back to 0 over the next three (the transition curves of road
    design: curvature linear in the arc length; e.g. Meek & Walton, J. Comput. Appl. Math. 170 (2004) 59)."""
    s = np.clip(np.asarray(s, float), 0.0, 1.0)
    q = 4 * s
    return kappa_m * np.where(q < 1, q, np.where(q < 3, 2 - q, q - 4))


def clothoid_offset_table(kappa_m, n=40001):
    """The lateral offset (and heading) along the unit lane change: heading = int kappa (closed form: piecewise
    quadratic), offset = int sin(heading) by the composite Simpson rule on n points (error below 1e-13)."""
    s = np.linspace(0.0, 1.0, n)
    q = 4 * s
    # the heading, the integral of the curvature: kappa_m / 4 G(q), G piecewise quadratic (q = 4 s)
    G = np.where(q < 1, q * q / 2, np.where(q < 3, 2 * q - q * q / 2 - 1, q * q / 2 - 4 * q + 8))
    head = kappa_m / 4 * G
    f = np.sin(head)
    h = s[1] - s[0]
    # cumulative Simpson on pairs of intervals, the odd points by the trapezoid-corrected half step
    y = np.zeros(n)
    y[2::2] = np.cumsum(h / 3 * (f[0:-2:2] + 4 * f[1:-1:2] + f[2::2]))
    y[1::2] = y[0:-1:2] + h / 12 * (5 * f[0:-1:2] + 8 * f[1::2] - f[2::2])
    return s, head, y


def clothoid_kappa(D):
    """The peak curvature (per unit length) of the unit lane change whose lateral offset is D (brentq)."""
    return brentq(lambda k: clothoid_offset_table(k, 4001)[2][-1] - D, 1e-6, 6.0, xtol=1e-15)


def lane_changes(t, runs):
    """The vehicle's lateral position: runs (t0, T, D, kappa_m, sign): a lane change traversed at constant speed in T
    s, its shape that of the unit lane change of peak curvature kappa_m scaled to end D (drive units) over, out (sign
    +1) or back (-1); the offset held between."""
    t = np.asarray(t, float)
    v = np.zeros_like(t)
    tabs = {}
    lvl = 0.0
    for t0, T, D, km, sign in runs:
        if km not in tabs:
            s, _, y = clothoid_offset_table(km)
            tabs[km] = (s, y / y[-1])
        s, y = tabs[km]
        m = t >= t0
        v[m] = lvl + sign * D * np.interp(np.clip((t[m] - t0) / T, 0, 1), s, y)
        lvl += sign * D
    return v


# ---- a chirp-spread-spectrum (LoRa-like) frame (the delay case) ----

def css_frequency(t, f_lo, bw, sf, symbols, t0):
    """The instantaneous frequency of a chirp-spread-spectrum frame (the LoRa physical layer: each symbol a linear
    up-chirp across the band bw in 2^sf / bw s, cyclically shifted by its value k, wrapping from the top back to the
    bottom; Vangelista, IEEE Signal Process. Lett. 24 (2017) 1818): symbols are k (an up-chirp) or 'down' (a
    down-chirp) or ('down', fraction) (a part of one); before t0 and after the frame f_lo."""
    t = np.asarray(t, float)
    Ts = 2 ** sf / bw
    f = np.full_like(t, f_lo)
    tc = t0
    for sym in symbols:
        frac = sym[1] if isinstance(sym, tuple) else 1.0
        m = (t >= tc) & (t < tc + frac * Ts)
        x = (t[m] - tc) / Ts
        if isinstance(sym, tuple) or sym == "down":
            f[m] = f_lo + bw * (1.0 - x)
        else:
            f[m] = f_lo + bw * np.mod(sym / 2 ** sf + x, 1.0)
        tc += frac * Ts
    return f


def css_signal(t, f_lo, bw, sf, symbols, t0, fade):
    """sin of the integrated frequency (phase continuous; the trapezoid rule on the sampled frequency), faded in from
    0 over `fade` s from t0 and out over the last `fade` s of the frame. Returns it and the frame's end."""
    t = np.asarray(t, float)
    f = css_frequency(t, f_lo, bw, sf, symbols, t0)
    dt = t[1] - t[0]
    ph = 2 * np.pi * np.r_[0.0, np.cumsum((f[1:] + f[:-1]) / 2) * dt]
    Ts = 2 ** sf / bw
    end = t0 + Ts * sum(s[1] if isinstance(s, tuple) else 1.0 for s in symbols)
    env = raised_cosine((t - t0) / fade) * raised_cosine((end - t) / fade)
    return env * np.sin(ph - ph[np.searchsorted(t, t0)]), end


# ---- a C-V (bias sweep) measurement's history and a gantry crane's swinging load (the initial-state case) ----

def bias_sweep_history(levels, a_ac, n_ac):
    """The turning points of a small-signal (C-V or d33) bias sweep: the bias stepped through `levels`, at each a
    test signal of +-a_ac for n_ac cycles, ending at the level (e.g. the butterfly measurement of Damjanovic, Rep.
    Prog. Phys. 61 (1998) 1267, or a capacitance-voltage sweep); from the virgin state at 0 V."""
    pts = [0.0]
    for L in levels:
        pts.append(L)
        for _ in range(n_ac):
            pts += [L + a_ac, L - a_ac]
        pts.append(L)
    return np.array(pts)


def trolley(t, moves, start):
    """The trolley's position, velocity and acceleration: moves (t0, T, to), each a raised-cosine move from where the
    last ended (a smooth start and stop), held between."""
    t = np.asarray(t, float)
    x, u, a = np.full_like(t, start), np.zeros_like(t), np.zeros_like(t)
    lvl = start
    for t0, T, to in moves:
        m = t >= t0
        s = np.clip((t[m] - t0) / T, 0.0, 1.0)
        on = (s > 0) & (s < 1)
        D = to - lvl
        x[m] = lvl + D * (1 - np.cos(np.pi * s)) / 2
        u[m] = np.where(on, D * np.pi / (2 * T) * np.sin(np.pi * s), 0.0)
        a[m] = np.where(on, D * np.pi ** 2 / (2 * T * T) * np.cos(np.pi * s), 0.0)
        lvl = to
    return x, u, a


def crane_rhs(t, s, acc, length, w0, zeta):
    """The load's swing angle under the trolley's acceleration acc(t) (a pendulum on a moving pivot, e.g.
    Abdel-Rahman et al., J. Vib. Control 9 (2003) 863): phi'' = -w0^2 sin(phi) - (x_t'' / l) cos(phi) - 2 zeta w0 phi'
    (the rope's and the air's damping)."""
    phi, om = s
    return [om, -w0 * w0 * math.sin(phi) - acc(t) / length * math.cos(phi) - 2 * zeta * w0 * om]


def crane_load(t, moves, start, length, w0, zeta):
    """The load's horizontal position x_t + l sin(phi) under :func:`trolley`'s moves, the swing integrated piece by
    piece (each move, each hold; DOP853, rtol 1e-11), from rest. Returns it and the angle."""
    t = np.asarray(t, float)
    pieces, lvl, tc = [], start, 0.0
    for t0, T, to in moves:
        pieces.append((tc, t0, 0.0, 1.0, t0))          # a hold: no acceleration
        pieces.append((t0, t0 + T, to - lvl, T, t0))
        lvl, tc = to, t0 + T
    pieces.append((tc, max(float(t[-1]), tc), 0.0, 1.0, tc))
    phi = np.zeros_like(t)
    s = np.array([0.0, 0.0])
    for a, b, D, T, t0 in pieces:
        if b <= a:
            continue
        c = D * math.pi ** 2 / (2 * T * T)

        def acc(tt, c=c, T=T, t0=t0):
            return c * math.cos(math.pi * (tt - t0) / T)
        m = (t >= a) & (t <= b)
        sol = solve_ivp(crane_rhs, (a, b), s, args=(acc, length, w0, zeta), t_eval=t[m], method="DOP853",
                        rtol=1e-11, atol=1e-13, dense_output=True)
        phi[m] = sol.y[0]
        s = sol.sol(b)
    x, _, _ = trolley(t, moves, start)
    return x + length * np.sin(phi), phi


# ---- a reader's gaze (the two-effect case) ----

def saccade_duration(amp_deg):
    """The main sequence: a saccade's duration grows linearly with its amplitude, about 21 ms + 2.2 ms per degree
    (Carpenter, *Movements of the Eyes*, 1988; Bahill, Clark & Stark, Math. Biosci. 24 (1975) 191)."""
    return 0.021 + 0.0022 * np.asarray(amp_deg, float)


def gaze(t, saccades, start):
    """The horizontal gaze: saccades (t0, T, to) between fixations, each with a skewed speed profile I_s(2, 3) (the
    peak speed in the first 40 % of the movement, as in large saccades; Van Opstal & Van Gisbergen, Vision Res. 27
    (1987) 731), held still between them (fixations)."""
    t = np.asarray(t, float)
    v = np.full_like(t, start)
    lvl = start
    for t0, T, to in saccades:
        m = t >= t0
        v[m] = lvl + (to - lvl) * stroke_profile((t[m] - t0) / T, 2.0, 3.0)
        lvl = to
    return v


# ---- an inertia drive's sawtooth bursts (the out-of-vocabulary case) ----

def warped_cosine(s, f):
    """One cycle (s in [0, 1)) of an inertia drive's waveform from 0 to 1 and back, each way a half cosine (zero
    speed at both ends): the rise over 1 - f of the cycle and the fall over f (f small: a slow rise and a fast
    flyback; 1 - f small: the reverse; 1/2: a symmetric wave). Pohl, Rev. Sci. Instrum. 58 (1987) 54 on the
    slip-stick (inertial) translator."""
    s = np.mod(np.asarray(s, float), 1.0)
    w = np.where(s < 1 - f, s / (1 - f), 1 + (s - (1 - f)) / f)
    return (1 - np.cos(np.pi * w)) / 2


def inertia_program(t, pieces, start):
    """The drive: pieces ('burst', t0, n, T, f, base, H): n cycles of :func:`warped_cosine` of period T and height H
    on the base; ('move', t0, T, to): a raised-cosine move of the base (a slow sweep); the drive rests between."""
    t = np.asarray(t, float)
    v = np.full_like(t, start)
    lvl = start
    for p in pieces:
        if p[0] == "burst":
            _, t0, n, T, f, base, H = p
            m = (t >= t0) & (t < t0 + n * T)
            v[m] = base + H * warped_cosine((t[m] - t0) / T, f)
            v[t >= t0 + n * T] = base
            lvl = base
        else:
            _, t0, T, to = p
            m = t >= t0
            v[m] = lvl + (to - lvl) * raised_cosine((t[m] - t0) / T)
            lvl = to
    return v


__all__ = ["thomas_rhs", "thomas_x", "kiln_segments", "kiln_schedule", "stroke_profile", "rowing_handle",
           "geneva_angle", "motor_crank", "euler_rhs", "throw_spin", "throws", "clothoid_curvature",
           "clothoid_offset_table", "clothoid_kappa", "lane_changes", "css_frequency", "css_signal",
           "bias_sweep_history", "trolley", "crane_rhs", "crane_load", "saccade_duration", "gaze", "warped_cosine",
           "inertia_program"]

"""Mechanisms and signals of the HOLDOUT13 set (``cases_holdout13.py``), each written from its law.

Nothing here imports hystcomp. Every mechanism takes the (clean) drive, or the core's output, and returns
the response; all are causal. The sources of the laws are beside each function and in ``cases_holdout13``'s
docstring.
"""

import math

import numpy as np
from scipy.special import erf


# ---- the rate-independent core ----

def plays(v, r, w, w0, state=0.0, return_state=False):
    """y = w0 v + sum_k w_k z_k with z_k the play of threshold r_k >= 0: z_k(t) = min(max(z_k(t-), v(t) - r_k),
    v(t) + r_k) (the play, or backlash, operator: Krasnosel'skii & Pokrovskii, *Systems with Hysteresis*, 1989;
    Brokate & Sprekels, *Hysteresis and Phase Transitions*, 1996, sec. 2.3), from the given state (a number or
    one per play; 0: virgin). Returns y (and the final state)."""
    v = np.asarray(v, float)
    r = np.asarray(r, float)
    w = np.asarray(w, float)
    z = np.broadcast_to(np.asarray(state, float), r.shape).copy()
    y = np.empty_like(v)
    for k, vk in enumerate(v.tolist()):
        np.maximum(z, vk - r, out=z)
        np.minimum(z, vk + r, out=z)
        y[k] = w0 * vk + w @ z
    return (y, z) if return_state else y


def turning_points(x):
    """The first value, every turning point (repeated values collapsed) and the last value of a sampled path.
    A play's state after a monotone stretch depends only on its end, so a rate-independent core driven by these
    points ends in the same state as driven by the whole path (Brokate & Sprekels 1996, sec. 2.3)."""
    x = np.asarray(x, float)
    x = x[np.r_[True, np.diff(x) != 0]]
    if len(x) < 3:
        return x
    s = np.sign(np.diff(x))
    turn = np.flatnonzero(s[1:] != s[:-1]) + 1
    return x[np.r_[0, turn, len(x) - 1]]


# ---- signals ----

def raised_cosine(x):
    """0 for x <= 0, (1 - cos(pi x)) / 2 between, 1 for x >= 1 (a haversine)."""
    x = np.clip(np.asarray(x, float), 0.0, 1.0)
    return (1 - np.cos(np.pi * x)) / 2


def markov_turning_points(rng, n, levels, scale, start=0):
    """n turning points of a Markov chain on the given levels, starting at a valley at levels[start]: from a
    valley at level i the next peak is level j > i with probability proportional to exp(-(j - i) / scale)
    (scale in levels), from a peak the next valley j < i likewise: a load sequence drawn from a min-max
    (turning-point) transition matrix, as fatigue tests draw their load spectra (Rychlik, "Simulation of load
    sequences from rainflow matrices: Markov method", Int. J. Fatigue 18 (1996) 429). Many small half cycles,
    few large ones."""
    levels = np.asarray(levels, float)
    i, up, out = start, True, [levels[start]]
    for _ in range(n - 1):
        cand = np.arange(i + 1, len(levels)) if up else np.arange(0, i)
        p = np.exp(-np.abs(cand - i) / scale)
        i = int(rng.choice(cand, p=p / p.sum()))
        out.append(levels[i])
        up = not up
    return np.array(out)


def haversine_path(dt, points, durations):
    """Half cycles of haversine (raised-cosine) shape, a + (b - a) (1 - cos(pi s)) / 2, from each point to the
    next over its duration, sampled every dt from 0 (the first point) to the last knot. Returns the path and
    the knots' times."""
    points = np.asarray(points, float)
    durations = np.asarray(durations, float)
    knots = np.r_[0.0, np.cumsum(durations)]
    t = np.arange(int(knots[-1] / dt) + 1) * dt
    i = np.clip(np.searchsorted(knots, t, side="right") - 1, 0, len(durations) - 1)
    s = (t - knots[i]) / durations[i]
    return points[i] + (points[i + 1] - points[i]) * raised_cosine(s), knots


def ramps_and_holds(dt, start, knots, speed):
    """From `start`, a ramp at constant `speed` (V/s) to each knot's level, then a hold of the knot's time:
    knots = [(level, hold_s), ...]. Returns the path and, per knot, (first, stop) sample indices of its hold."""
    parts, holds, pos, cur = [np.array([start], float)], [], 1, start
    for level, hold_s in knots:
        m = max(int(math.ceil(abs(level - cur) / speed / dt)), 1)
        parts.append(np.linspace(cur, level, m + 1)[1:])
        pos += m
        nh = int(round(hold_s / dt))
        parts.append(np.full(nh, float(level)))
        holds.append((pos, pos + nh))
        pos += nh
        cur = level
    return np.concatenate(parts), holds


def iso230_knots(targets, runs, overrun, hold_s, dwell_s):
    """The standard (linear) test cycle of ISO 230-2 (*Test code for machine tools - Part 2: Determination of
    accuracy and repeatability of positioning of numerically controlled axes*, 2014): every target position
    P_1 < ... < P_m approached and held once moving up (from an overrun below P_1) and once moving down (from an
    overrun above P_m), in `runs` bidirectional runs. Returns knots [(level, hold_s), ...] with the targets'
    holds drawn from hold_s (an array, one per held target) and a short dwell at each overrun, and each knot's
    approach direction (+1, -1; 0 at the overruns)."""
    knots, dirs, h = [], [], iter(hold_s)
    for _ in range(runs):
        knots.append((targets[0] - overrun, dwell_s))
        dirs.append(0)
        for p in targets:
            knots.append((p, next(h)))
            dirs.append(1)
        knots.append((targets[-1] + overrun, dwell_s))
        dirs.append(0)
        for p in targets[::-1]:
            knots.append((p, next(h)))
            dirs.append(-1)
    return knots, dirs


def fsk_sine(t, switch_times, freqs, amp, fade_s):
    """Continuous-phase frequency-shift keying: amp w(t) sin(phi(t)) with phi = 2 pi int f dt, f = freqs[i] from
    switch_times[i] on (switch_times[0] = 0), the phase continuous at every switch (the waveform and its value
    continuous; only the slope's frequency jumps); w a raised-cosine fade-in over fade_s. Returns the signal and
    phi."""
    t = np.asarray(t, float)
    T = np.asarray(switch_times, float)
    f = np.asarray(freqs, float)
    phi0 = np.r_[0.0, np.cumsum(2 * np.pi * f[:-1] * np.diff(T))]
    i = np.clip(np.searchsorted(T, t, side="right") - 1, 0, len(f) - 1)
    phi = phi0[i] + 2 * np.pi * f[i] * (t - T[i])
    return amp * raised_cosine(t / fade_s) * np.sin(phi), phi


def gaussian_pulses(t, centres, heights, widths):
    """A train of bell-shaped (Gaussian) strokes, sum_i h_i exp(-(t - c_i)^2 / (2 w_i^2)), as a pick-and-place or
    dispensing stage makes them: a rest at (very nearly) 0 V between well-separated strokes."""
    t = np.asarray(t, float)[:, None]
    return (np.asarray(heights) * np.exp(-(t - np.asarray(centres)) ** 2 / (2 * np.asarray(widths) ** 2))).sum(axis=1)


def dsb_sc(t, amp, f_c, f_m, phi_m):
    """Double-sideband suppressed-carrier modulation: amp sin(2 pi f_c t) cos(2 pi f_m t + phi_m). The envelope
    |cos| passes through 0 and the carrier's phase flips by pi there: nested loops that shrink to nothing and grow
    again (a carrier times a slow cosine: Haykin, *Communication Systems*, 4th ed., 2001, ch. 2)."""
    t = np.asarray(t, float)
    return amp * np.sin(2 * np.pi * f_c * t) * np.cos(2 * np.pi * f_m * t + phi_m)


def v_chirp(t, mid, amp, f0, f1, T):
    """A linear chirp up and back down: the frequency rises linearly from f0 to f1 over [0, T/2] and falls back to
    f0 at T; v = mid - amp cos(phi), phi = 2 pi int f dt (from mid - amp at t = 0). Returns v and the frequency."""
    t = np.asarray(t, float)
    h = T / 2
    tf = np.minimum(t, h)
    tb = np.clip(t - h, 0.0, None)
    phi = 2 * np.pi * (f0 * tf + (f1 - f0) * tf ** 2 / (2 * h) + f1 * tb - (f1 - f0) * tb ** 2 / (2 * h))
    freq = np.where(t <= h, f0 + (f1 - f0) * t / h, f1 - (f1 - f0) * (t - h) / h)
    return mid - amp * np.cos(phi), freq


def cycloid_path(t, starts, durations, x_from, x_to):
    """Point-to-point moves of cycloidal profile, x0 + D (s - sin(2 pi s) / (2 pi)), s the move's elapsed fraction
    (zero speed and zero acceleration at both ends; R. L. Norton, *Cam Design and Manufacturing Handbook*, 2nd ed.,
    2009, the cycloidal displacement function), held at each move's end until the next move starts; x_from[0] before
    the first. Evaluated at arbitrary times t (moves sorted by start, not overlapping)."""
    t = np.asarray(t, float)
    starts, durations = np.asarray(starts, float), np.asarray(durations, float)
    x_from, x_to = np.asarray(x_from, float), np.asarray(x_to, float)
    i = np.searchsorted(starts, t, side="right") - 1
    j = np.clip(i, 0, len(starts) - 1)
    s = np.clip((t - starts[j]) / durations[j], 0.0, 1.0)
    x = x_from[j] + (x_to[j] - x_from[j]) * (s - np.sin(2 * np.pi * s) / (2 * np.pi))
    return np.where(i < 0, x_from[0], x)


def trapezoidal_move(tau, dist, v_max, a_max):
    """Displacement at times tau (from the move's start) of a move of length dist with a trapezoidal velocity
    profile (constant acceleration a_max to v_max, cruise, constant deceleration; a triangular profile when the
    move is too short to reach v_max: Biagiotti & Melchiorri, *Trajectory Planning for Automatic Machines and
    Robots*, 2008, ch. 3). Returns the displacement and the move's duration."""
    d = abs(dist)
    if d >= v_max ** 2 / a_max:
        ta, vp = v_max / a_max, v_max
        T = d / v_max + ta
    else:
        ta = math.sqrt(d / a_max)
        vp, T = a_max * ta, 2 * ta
    tau = np.clip(np.asarray(tau, float), 0.0, T)
    acc = 0.5 * a_max * np.minimum(tau, ta) ** 2
    cruise = vp * np.clip(tau - ta, 0.0, T - 2 * ta)
    dec_t = np.clip(tau - (T - ta), 0.0, ta)
    dec = vp * dec_t - 0.5 * a_max * dec_t ** 2
    return math.copysign(1.0, dist) * (acc + cruise + dec), T


def trapezoidal_moves(dt, start, first_hold_s, points, holds_s, v_max, a_max):
    """A hold at `start`, then trapezoidal-velocity moves to each point, each followed by its hold. Returns the
    path and the holds' (first, stop) indices."""
    parts = [np.full(max(int(round(first_hold_s / dt)), 1), float(start))]
    pos, cur, holds = len(parts[0]), float(start), []
    for p, h in zip(points, holds_s):
        _, T = trapezoidal_move(0.0, p - cur, v_max, a_max)
        m = max(int(math.ceil(T / dt)), 1)
        parts.append(cur + trapezoidal_move(np.arange(1, m + 1) * dt, p - cur, v_max, a_max)[0])
        pos += m
        nh = int(round(h / dt))
        parts.append(np.full(nh, float(p)))
        holds.append((pos, pos + nh))
        pos += nh
        cur = float(p)
    return np.concatenate(parts), holds


def dithered_approach(dt, top, v0, rise_s, top_hold_s, approach_s, dither, f_d, settle_s):
    """An unrecorded positioning run from rest at 0 V: a ramp to `top`, a hold, then a ramp down to v0 over
    approach_s with a sinusoidal dither of amplitude `dither` at f_d on top (faded in over the first 30 % of the
    approach), kept on at the target and faded out linearly over settle_s (a dither to overcome stiction and
    hysteresis while positioning: Zames & Shneydor, "Dither in nonlinear systems", IEEE Trans. Autom. Control 21
    (1976) 660; faded out at the target like an AC demagnetisation about it). Sampled every dt; ends at v0. With
    dither / 0.3 below top - v0 the path never rises above `top`."""
    up = np.linspace(0.0, top, int(round(rise_s / dt)) + 1)
    hold = np.full(int(round(top_hold_s / dt)), float(top))
    m, ms = int(round(approach_s / dt)), int(round(settle_s / dt))
    tau = np.arange(1, m + ms + 1) * dt
    s = np.minimum(tau / (m * dt), 1.0)
    env = np.minimum(np.minimum(s / 0.3, 1.0), np.clip(((m + ms) * dt - tau) / settle_s, 0.0, 1.0))
    down = top + (v0 - top) * s + dither * env * np.sin(2 * np.pi * f_d * tau)
    return np.r_[up, hold, down]


def forc_points(top, reversals, stop_fraction):
    """The turning points of an interrupted first-order-reversal-curve (FORC) measurement from the virgin state at
    0 V: up to `top`, then for each reversal point b_k down to it and back up toward `top` (Pike, Roberts &
    Verosub, "Characterizing interactions in fine magnetic particle systems using first order reversal curves",
    J. Appl. Phys. 85 (1999) 6660), stopped on the last rise at b_K + stop_fraction (top - b_K)."""
    pts = [0.0, top]
    for b in reversals[:-1]:
        pts += [b, top]
    b = reversals[-1]
    return np.array(pts + [b, b + stop_fraction * (top - b)])


def sine_blocks(dt, amps, freq, cycles, hold_s, signs):
    """Blocks of whole sine cycles, a_i s_i sin(2 pi f t) (s_i = +-1; f rounded to a whole number of samples per
    cycle), each from 0 V back to 0 V and followed by a
    hold at 0 V of hold_s[i]; a hold first. Returns the path and each block's (first, stop) indices."""
    n_per = int(round(1 / freq / dt))            # a whole number of samples per cycle: the cycles repeat exactly
    n_c = n_per * cycles
    base = np.sin(2 * np.pi * np.arange(n_c) / n_per)
    parts = [np.zeros(int(round(hold_s[0] / dt)))]
    pos, blocks = len(parts[0]), []
    for a, s, h in zip(amps, signs, hold_s[1:]):
        parts.append(a * s * base)
        blocks.append((pos, pos + n_c))
        pos += n_c
        parts.append(np.zeros(int(round(h / dt))))
        pos += len(parts[-1])
    return np.concatenate(parts), blocks


# ---- mechanisms ----

def norton_kelvin(u, dt, c, tau, x_s, n):
    """Creep of a Kelvin element whose dashpot follows Norton's power law (Norton, *The Creep of Steel at High
    Temperatures*, 1929: strain rate K stress^n; the nonlinear Kelvin body, Findley, Lai & Onaran, *Creep and
    Relaxation of Nonlinear Viscoelastic Materials*, 1976): de/dt = (x_s / tau) sign(x) |x / x_s|^n with the
    overstress x = c u - e (n > 1; n -> 1 is the linear element tau de/dt = c u - e). With u held over a sample,
    |x|^(1 - n) grows linearly: |x(t)| = |x0| (1 + (n - 1) (t / tau) |x0 / x_s|^(n - 1))^(-1 / (n - 1)), exact per
    sample: big overstresses relax fast at first, and every one ends on the algebraic tail x_s ((n - 1) t /
    tau)^(-1 / (n - 1)). Relaxed at the start (e = c u[0])."""
    u = np.asarray(u, float)
    out = np.empty_like(u)
    e = c * u[0]
    p = n - 1.0
    for k, uk in enumerate(u.tolist()):
        out[k] = e
        x = c * uk - e
        if x != 0.0:
            ax = abs(x)
            x = math.copysign(ax * (1 + p * dt / tau * (ax / x_s) ** p) ** (-1 / p), x)
        e = c * uk - x
    return out


def slew_limited(v, dt, s_max):
    """The voltage on a capacitive load from an amplifier whose output current is limited to I_max: i = C dv/dt, so
    the output follows the command v only while |dv/dt| <= S = I_max / C and otherwise moves toward it at +-S
    (Fleming & Leang, *Design, Modeling and Control of Nanopositioning Systems*, 2014, the chapter on piezoelectric
    drive electronics: the current limit sets the full-power bandwidth I_max / (pi C V_pp)). Exact for a command
    linear between samples (the catch-up instants solved per sample); from the first command value."""
    v = np.asarray(v, float)
    out = np.empty_like(v)
    a = out[0] = v[0]
    tracking = True
    vl = v.tolist()
    for k in range(1, len(vl)):
        v0, v1 = vl[k - 1], vl[k]
        m = (v1 - v0) / dt
        rest, e = dt, v0 - a
        while rest > 0:
            if tracking:
                if abs(m) <= s_max:
                    a, rest = v1, 0.0
                else:
                    a += math.copysign(s_max, m) * rest
                    rest, tracking = 0.0, False
            else:
                sg = 1.0 if e > 0 else -1.0
                rate = m - sg * s_max                          # de/dt while moving at full slew
                if rate * sg < 0 and -e / rate < rest:         # catches up within the sample
                    ts = -e / rate
                    a += sg * s_max * ts
                    rest -= ts
                    e, tracking = 0.0, True
                    if abs(m) > s_max:                         # and falls behind at once the other way
                        a += math.copysign(s_max, m) * rest
                        rest, tracking = 0.0, False
                    else:
                        a, rest = v1, 0.0
                else:
                    a += sg * s_max * rest
                    rest = 0.0
            e = v1 - a
        if not tracking and e == 0.0:
            tracking = True
        out[k] = a
    return out


def pid_thermal_offset(t, t_s, amp, zeta, period):
    """The offset of a frame whose temperature controller (a PID loop, closed-loop underdamped) answers a set-point
    step at t_s: amp (1 - exp(-zeta w_n t') (cos w_d t' + zeta / sqrt(1 - zeta^2) sin w_d t')), t' = t - t_s >= 0, 0
    before (the unit-step response of the underdamped second-order system, Ogata, *Modern Control Engineering*, 5th
    ed., 2010, sec. 5-3; thermal expansion linear in the temperature): overshoot exp(-pi zeta / sqrt(1 - zeta^2)),
    ringing period `period` = 2 pi / w_d."""
    tp = np.clip(np.asarray(t, float) - t_s, 0.0, None)
    wd = 2 * np.pi / period
    wn = wd / math.sqrt(1 - zeta ** 2)
    resp = 1 - np.exp(-zeta * wn * tp) * (np.cos(wd * tp) + zeta / math.sqrt(1 - zeta ** 2) * np.sin(wd * tp))
    return amp * resp


def bridge_amplifier(x, l, theta0):
    """The output of a bridge-type displacement amplifier (rigid-link kinematics: Xu & Li, "Analytical modeling,
    optimization and testing of a compound bridge-type compliant displacement amplifier", Mech. Mach. Theory 46
    (2011) 183): links of length l inclined at theta0, each end pushed out by x / 2, so the output moves by
    l sin(theta0) - sqrt(l^2 - (l cos(theta0) + x / 2)^2); scaled by 2 tan(theta0) to slope 1 at x = 0. The ratio
    grows as the links flatten (x > 0) and falls as they steepen: an asymmetric, monotone map (x / 2 < l (1 -
    cos(theta0)))."""
    x = np.asarray(x, float)
    c, s = l * math.cos(theta0), l * math.sin(theta0)
    return 2 * math.tan(theta0) * (s - np.sqrt(l * l - (c + x / 2) ** 2))


def diode_clamp(s, rho, v_d, iters=80):
    """A signal s through a series resistor R into an anti-parallel diode pair (input protection): (s - y) / R =
    2 I_s sinh(y / V_D) by Shockley's law (V_D = n kT / q; Sedra & Smith, *Microelectronic Circuits*, the chapter
    on diodes), i.e. s = y + rho V_D sinh(y / V_D) with rho = 2 I_s R / V_D; y solved by bisection (|y| <= |s|, the
    right side increasing) and scaled by (1 + rho) to slope 1 at 0. Linear at small signals, then a sharp
    exponential knee past which y grows only logarithmically."""
    s = np.asarray(s, float)
    lo, hi = -np.abs(s), np.abs(s)
    with np.errstate(over="ignore"):                 # sinh overflows to inf far beyond the knee: still "too high"
        for _ in range(iters):
            mid = (lo + hi) / 2
            f = mid + rho * v_d * np.sinh(mid / v_d) - s
            lo, hi = np.where(f < 0, mid, lo), np.where(f < 0, hi, mid)
    return (1 + rho) * (lo + hi) / 2


def skewed_instants(n, dt, latency, eps):
    """The true times of a recorder's samples 0 ... n-1 when its clock runs fast by eps (a fraction; crystal and
    ceramic-resonator tolerances are 1e-5 ... 1e-3) and its pipeline delivers each sample `latency` periods late:
    k dt / (1 + eps) - latency dt. Against the drive's clock the delay grows from `latency` samples by eps / (1 +
    eps) samples per sample (unsynchronised clocks drift apart at their frequency offset, the reason for IEEE 1588
    time synchronisation)."""
    k = np.arange(n)
    return k * dt / (1 + eps) - latency * dt


def bicell_tophat(x, x_c, R):
    """The normalised difference signal of a split (bi-cell) photodiode under a uniform circular spot of radius R
    displaced by u R from the split: (A_1 - A_2) / (A_1 + A_2) = (2 / pi) (asin u + u sqrt(1 - u^2)) (twice the
    area of the circular segment between the split and the spot's centre line over the disc's area), here scaled
    to slope 1 at the centre x_c: x_c + (R / 2) (asin u + u sqrt(1 - u^2)), u = (x - x_c) / R. Flat for |u| >= 1
    (the spot wholly on one side)."""
    u = np.clip((np.asarray(x, float) - x_c) / R, -1.0, 1.0)
    return x_c + R / 2 * (np.arcsin(u) + u * np.sqrt(1 - u * u))


def mullins_eta(x, m_max, r, m, beta):
    """Ogden & Roxburgh's softening factor (Proc. R. Soc. Lond. A 455 (1999) 2861), eta = 1 - (1 / r) erf((W_m -
    W) / (m + beta W_m)), for a linear virgin spring W = x^2 / 2 and the largest deformation so far m_max
    (W_m = m_max^2 / 2). eta = 1 at the maximum, lower inside."""
    wm = np.asarray(m_max, float) ** 2 / 2
    return 1 - erf((wm - np.asarray(x, float) ** 2 / 2) / (m + beta * wm)) / r


def mullins_spring(f, r, m, beta, iters=80):
    """The deformation x of a filled-rubber spring under the force f (unit virgin stiffness) with Mullins's stress
    softening (Mullins, "Softening of rubber by deformation", Rubber Chem. Technol. 42 (1969) 339), in Ogden &
    Roxburgh's pseudo-elastic form f = eta(x, x_max) x. At a new largest force the spring is on its virgin curve
    (eta = 1, x = f), so x_max is the running maximum of |f|; below it x solves eta x = f (eta x increasing in |x|,
    the root between |f| and x_max; bisection). Rate independent and without a loop under cycles below the
    maximum; every new maximum softens the curve inside it."""
    f = np.asarray(f, float)
    mm = np.maximum.accumulate(np.abs(f))
    lo, hi = np.abs(f), mm.copy()
    for _ in range(iters):
        mid = (lo + hi) / 2
        g = mullins_eta(mid, mm, r, m, beta) * mid - np.abs(f)
        lo, hi = np.where(g < 0, mid, lo), np.where(g < 0, hi, mid)
    return np.sign(f) * (lo + hi) / 2, mm

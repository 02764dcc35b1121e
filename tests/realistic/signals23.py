"""Excitation signals of the HOLDOUT23 set (``cases_holdout23.py``), each written from its source; the mechanisms are
in :mod:`.mechanisms23`.

Citations were written from memory in this session (none was re-read; volumes, pages and years may be off); the
signals are checked in tests/test_realistic_holdout23.py against independent solutions (solve_ivp, brentq, closed
forms, quadrature, the FFT).
"""

import math

import numpy as np
from scipy.integrate import solve_ivp

from .mechanisms19 import raised_cosine


# ---- the Rikitake two-disc dynamo (the clean case) ----

def rikitake_rhs(t, s, mu, a):
    """x' = -mu x + y z, y' = -mu y + (z - a) x, z' = 1 - x y (Rikitake, Proc. Camb. Phil. Soc. 54 (1958) 89: two
    coupled disc dynamos, a model of the geomagnetic field's reversals; chaotic for mu 2, a 5: x, a disc's current,
    circles about one sign and reverses at irregular times)."""
    x, y, z = s
    return [-mu * x + y * z, -mu * y + (z - a) * x, 1.0 - x * y]


def rikitake_x(t, units, start, mu, a, settle=200.0):
    """x at the times t (s), `units` of the dynamo's time a second, after `settle` units from `start` (DOP853, rtol
    1e-11). Returns x and the state the record starts from."""
    s0 = solve_ivp(rikitake_rhs, (0, settle), np.array(start, float), args=(mu, a), method="DOP853", rtol=1e-11,
                   atol=1e-12).y[:, -1]
    tau = np.asarray(t, float) * units
    sol = solve_ivp(rikitake_rhs, (tau[0], tau[-1]), s0, args=(mu, a), t_eval=tau, method="DOP853", rtol=1e-11,
                    atol=1e-12)
    return sol.y[0], s0


# ---- a spring-lever espresso machine's shots (the creep case) ----

def lever_shots(t, shots, ramp):
    """The brew pressure of a spring-lever espresso machine, shots (t0, p_line, T_pi, p_peak, tau_l, p_end, cut):
    the lever pulled down opens the group to the line pressure (a raised cosine over `ramp` s to p_line, held: the
    pre-infusion, T_pi s in all); released, the spring drives the piston: the pressure rises over `ramp` to p_peak,
    then falls as the spring extends, exponentially with tau_l (the spring's force linear in the piston's travel, the
    puck's flow by Darcy's law linear in the pressure: p' = -p / tau_l), until the piston bottoms out at p_end or the
    barista lifts the lever at the fraction `cut` of that time; then the group vents to 0 over `ramp` s. Returns the
    pressure and the pieces' times (t0, t1, t2, t3, t4): the pull, the release, the peak, the end of the extraction,
    the vent's end."""
    t = np.asarray(t, float)
    p = np.zeros_like(t)
    times = []
    for t0, p_line, T_pi, p_peak, tau_l, p_end, cut in shots:
        t1 = t0 + T_pi
        t2 = t1 + ramp
        t3 = t2 + cut * tau_l * math.log(p_peak / p_end)
        p3 = p_peak * math.exp(-(t3 - t2) / tau_l)
        t4 = t3 + ramp
        m = (t >= t0) & (t < t1)
        p[m] = p_line * raised_cosine((t[m] - t0) / ramp)
        m = (t >= t1) & (t < t2)
        p[m] = p_line + (p_peak - p_line) * raised_cosine((t[m] - t1) / ramp)
        m = (t >= t2) & (t < t3)
        p[m] = p_peak * np.exp(-(t[m] - t2) / tau_l)
        m = (t >= t3) & (t < t4)
        p[m] = p3 * (1 - raised_cosine((t[m] - t3) / ramp))
        times.append((t0, t1, t2, t3, t4))
    return p, times


# ---- the 20-m multistage shuttle run (the rate-dependence case) ----

def leg_speed(D, T, a):
    """The top speed of a leg of D m run in T s from rest to rest, accelerating and braking at a (a trapezoidal speed
    profile: T = D / v + v / a), the smaller root of v^2 / a - T v + D = 0 (needs a T^2 >= 4 D)."""
    return (a * T - math.sqrt(a * a * T * T - 4 * a * D)) / 2


def leg_position(s, D, T, a):
    """The distance covered s s into such a leg (closed form: parabolas and a line), clipped to [0, T]."""
    v = leg_speed(D, T, a)
    ta = v / a
    s = np.clip(np.asarray(s, float), 0.0, T)
    return np.where(s < ta, a * s * s / 2,
                    np.where(s < T - ta, v * ta / 2 + v * (s - ta), D - a * (T - s) ** 2 / 2))


def shuttle_legs(speeds_kmh, start_x, lead, acc, rest_after=None):
    """The legs of a runner between the lines at 0 and 20 m, each run in the time a runner at the level's speed takes
    over 20 m (the beep interval of the 20-m multistage shuttle run; Leger & Lambert, Eur. J. Appl. Physiol. 49 (1982)
    1: 8.5 km/h at level 1, 9 at level 2, 0.5 more each level, about a minute a level), from rest to rest at each line
    (a turn); the first from start_x. `rest_after`: {leg index: seconds at the line}. Returns legs (t0, T, x0, x1)
    and the end."""
    legs, tc, x = [], lead, start_x
    rest_after = rest_after or {}
    for i, kmh in enumerate(speeds_kmh):
        to = 20.0 if x < 10.0 else 0.0
        if i == 0 and 0.0 < x < 20.0:
            to = 0.0
        D = abs(to - x)
        T = D / (kmh / 3.6)
        legs.append((tc, T, x, to))
        tc += T + rest_after.get(i, 0.0)
        x = to
    return legs, tc


def shuttle_run(t, legs, acc, start_x):
    """The runner's position (m) along the legs of :func:`shuttle_legs` (each with the trapezoidal profile of
    :func:`leg_position` at the acceleration acc, m/s^2), held between."""
    t = np.asarray(t, float)
    x = np.full_like(t, start_x)
    for t0, T, x0, x1 in legs:
        m = t >= t0
        x[m] = x0 + math.copysign(1.0, x1 - x0) * leg_position(t[m] - t0, abs(x1 - x0), T, acc)
    return x


# ---- a cyclist's pedal (the drift case) ----

def pedal_angle(t, knots, theta0=0.0):
    """The crank's angle (rad) for a cadence (rev/s) linear between knots (t_k, c_k) (0 before the first and after the
    last knot's value held), integrated in closed form (a quadratic on each piece)."""
    t = np.asarray(t, float)
    tk = np.array([k[0] for k in knots], float)
    ck = np.array([k[1] for k in knots], float)
    cum = np.r_[0.0, np.cumsum((ck[1:] + ck[:-1]) / 2 * np.diff(tk))]
    th = np.zeros_like(t)
    j = np.clip(np.searchsorted(tk, t, side="right") - 1, 0, len(tk) - 2)
    s = np.clip(t - tk[j], 0, None)
    L = tk[j + 1] - tk[j]
    inside = t < tk[-1]
    slope = (ck[j + 1] - ck[j]) / L
    th_in = cum[j] + ck[j] * s + slope * s * s / 2
    th_after = cum[-1] + ck[-1] * (t - tk[-1])
    th = np.where(t < tk[0], 0.0, np.where(inside, th_in, th_after))
    return theta0 + 2 * np.pi * th


# ---- a plucked oscillator with dry friction (the asymmetry case) ----

def coulomb_free(s, x0, w, Delta):
    """The free motion of x'' + w^2 x = -w^2 Delta sign(x') released from rest at x0 (Coulomb friction: Den Hartog,
    Trans. ASME 53 (1931) 107): half cycles x = c_k + (x_k - c_k) cos(w s), c_k = Delta sign(x_k), x_{k+1} = 2 c_k -
    x_k (the amplitude falling by 2 Delta each half cycle, linearly), until |x_k| <= Delta, where it sticks. Returns
    x at the times s >= 0 after the release and the rest position."""
    s = np.asarray(s, float)
    x = np.full_like(s, x0)
    xk, k, half = x0, 0, math.pi / w
    while abs(xk) > Delta:
        c = math.copysign(Delta, xk)
        m = s >= k * half
        x[m] = c + (xk - c) * np.cos(w * np.clip(s[m] - k * half, 0, half))
        xk = 2 * c - xk
        k += 1
    return x, xk


def plucks(t, pl, w, Delta, pull, hold):
    """Plucks (t0, X0): from where the oscillator rests, a hand pulls it to X0 along a raised cosine over `pull` s,
    holds it `hold` s and lets go; it rings down by :func:`coulomb_free` and rests where it sticks. Returns the path
    and the rest positions."""
    t = np.asarray(t, float)
    x = np.zeros_like(t)
    rest, rests = 0.0, []
    for t0, X0 in pl:
        m = t >= t0
        x[m] = rest + (X0 - rest) * raised_cosine((t[m] - t0) / pull)
        tr = t0 + pull + hold
        m = t >= tr
        x[m], rest = coulomb_free(t[m] - tr, X0, w, Delta)
        rests.append(rest)
    return x, rests


# ---- the sine-with-dwell manoeuvre (the saturation case) ----

def sine_with_dwell(t, manoeuvres, f, dwell):
    """The steering of the sine-with-dwell test of electronic stability control (US FMVSS No. 126, 2007: a 0.7 Hz
    sine whose second peak is held for 500 ms, the amplitude stepped up manoeuvre by manoeuvre; counter-clockwise and
    clockwise series): for each (t0, A, sign), sign A sin(2 pi f s) to three quarters of a period, held at -sign A for
    `dwell` s, then the last quarter back to 0; 0 between."""
    t = np.asarray(t, float)
    v = np.zeros_like(t)
    q3 = 0.75 / f
    for t0, A, sg in manoeuvres:
        s = t - t0
        m = (s >= 0) & (s < q3)
        v[m] = sg * A * np.sin(2 * np.pi * f * s[m])
        m = (s >= q3) & (s < q3 + dwell)
        v[m] = -sg * A
        m = (s >= q3 + dwell) & (s < 1 / f + dwell)
        v[m] = sg * A * np.sin(2 * np.pi * f * (s[m] - dwell))
    return v


# ---- a discrete multitone (DMT) frame (the delay case) ----

def dmt_symbol(s, data, ks, T_u):
    """One DMT symbol (ADSL's real-valued OFDM: Bingham, IEEE Commun. Mag. 28 (1990) 5): sum_k Re(d_k exp(2 pi i k s /
    T_u)) over the tones k, s from the start of its useful part (periodic in T_u, so the cyclic prefix is its value at
    s < 0)."""
    s = np.asarray(s, float)
    out = np.zeros_like(s)
    for d, k in zip(data, ks):
        out += (d * np.exp(2j * np.pi * k * s / T_u)).real
    return out


def dmt_frame(t, t0, T_u, T_cp, ks, symbols, w_tx, fade):
    """Symbols of T_cp + T_u s from t0, each a cyclic prefix and its useful part, joined by the transmitter's window:
    each symbol extended cyclically w_tx s (< T_cp) into the next one's prefix while fading out along a raised cosine,
    the next one fading in over the same stretch (so every useful part is sent untouched); faded in over `fade` s from
    t0 and out over the last `fade` s. Returns the signal and the frame's end."""
    t = np.asarray(t, float)
    Ts = T_cp + T_u
    end = t0 + Ts * len(symbols)
    x = np.zeros_like(t)
    for j, data in enumerate(symbols):
        a, b = t0 + j * Ts, t0 + (j + 1) * Ts
        hi = b + w_tx if j < len(symbols) - 1 else b
        m = (t >= a) & (t < hi)
        tm = t[m]
        wgt = np.ones(len(tm))
        if j > 0:
            wgt *= raised_cosine((tm - a) / w_tx)
        if j < len(symbols) - 1:
            wgt *= 1 - raised_cosine((tm - b) / w_tx)
        x[m] += wgt * dmt_symbol(tm - a - T_cp, data, ks, T_u)
    env = raised_cosine((t - t0) / fade) * raised_cosine((end - t) / fade)
    return env * x, end


# ---- a homing routine and a pipette's programme (the initial-state case) ----

def homing_history(top, over_fast, back, over_slow, index, park):
    """The turning points of a stage's homing routine (as a motion controller runs it after power-up; e.g. the
    home-switch search of CNC controllers): from the virgin state at 0 V a fast seek toward the upper limit switch at
    `top`, stopping over_fast beyond it, a back-off to top - back, a slow re-approach stopping over_slow beyond the
    switch, then a move to the index mark and on to the park position, where the record starts."""
    return np.array([0.0, top + over_fast, top - back, top + over_slow, index, park])


def moves(t, mv, start):
    """Raised-cosine moves (t0, T, to) from where the last ended, held between; `start` before the first."""
    t = np.asarray(t, float)
    v = np.full_like(t, start)
    lvl = start
    for t0, T, to in mv:
        m = t >= t0
        v[m] = lvl + (to - lvl) * raised_cosine((t[m] - t0) / T)
        lvl = to
    return v


# ---- a car's engine speed through the gears (the two-effect case) ----

def gear_speed(s, v0, A, B):
    """The road speed in a gear under full throttle against the air's drag, v' = A - B v^2 (a constant tractive
    force, Newton's law of the quadratic drag): v = V tanh(sqrt(A B) s + atanh(v0 / V)), V = sqrt(A / B)."""
    V = math.sqrt(A / B)
    return V * np.tanh(math.sqrt(A * B) * np.asarray(s, float) + math.atanh(v0 / V))


def gear_time(v0, v1, A, B):
    """The time :func:`gear_speed` takes from v0 to v1."""
    V = math.sqrt(A / B)
    return (math.atanh(v1 / V) - math.atanh(v0 / V)) / math.sqrt(A * B)


def drive_cycle(ratios, A1, B, idle, launch, down, T_shift, decel, lead, runs, idle_hold, crank):
    """The engine's speed (rpm) and the car's (m/s): the engine cranked to idle (raised cosine over `crank` s), then for
    each run (top gear, rpm at which to change up): a launch in first (the clutch slipping, the engine held at
    `launch` rpm while the car gathers speed, v' = A_k - B v^2 with A_k = A1 r_k / r_1), the gears taken at full
    throttle to the run's rpm, each change over T_shift s (the speed held, the engine's speed falling along a raised
    cosine to the next gear's), then braking at `decel` with changes down at `down` rpm (a blip: the engine's speed
    rising along a raised cosine to the lower gear's while the car slows), the clutch out at the first gear's idle
    speed (the engine held at idle over T_shift), idle_hold s at idle; after the last run the engine stops (to 0 over
    `crank` s). rpm = v r_k (r_k in rpm per m/s). Returns a function of t giving (rpm, v), the end time and the
    pieces (t0, T, kind, data)."""
    pieces = []                                        # (t0, T, kind, data)
    tc = lead
    pieces.append((tc, crank, "ramp", (0.0, idle)))
    tc += crank + idle_hold
    for top, rpm_up in runs:
        # launch: the engine at `launch`, the car in first until v r_1 reaches it
        A = A1
        pieces.append((tc, T_shift, "ramp", (idle, launch)))
        tc += T_shift
        v_lock = launch / ratios[0]
        T = gear_time(0.0, v_lock, A, B)
        pieces.append((tc, T, "slip", (launch, A)))
        tc += T
        v = v_lock
        for k in range(top):
            A = A1 * ratios[k] / ratios[0]
            v_up = rpm_up / ratios[k] if k < top - 1 else None
            if v_up is not None:
                T = gear_time(v, v_up, A, B)
                pieces.append((tc, T, "gear", (v, A, ratios[k])))
                tc += T
                v = v_up
                pieces.append((tc, T_shift, "ramp", (rpm_up, v * ratios[k + 1])))
                tc += T_shift
            else:                                      # the top gear: to the shift speed, then off the throttle
                T = gear_time(v, rpm_up / ratios[k], A, B)
                pieces.append((tc, T, "gear", (v, A, ratios[k])))
                tc += T
                v = rpm_up / ratios[k]
        # braking, changing down
        for k in range(top - 1, -1, -1):
            v_dn = down / ratios[k] if k > 0 else idle / ratios[0]
            T = (v - v_dn) / decel
            pieces.append((tc, T, "brake", (v, decel, ratios[k])))
            tc += T
            v = v_dn
            if k > 0:
                T = min(T_shift, v / decel)
                pieces.append((tc, T, "blip", (v, decel, ratios[k], ratios[k - 1])))
                tc += T
                v -= decel * T
        pieces.append((tc, T_shift, "ramp", (v * ratios[0], idle)))
        tc += T_shift + idle_hold
    pieces.append((tc, crank, "ramp", (idle, 0.0)))
    tc += crank

    def at(t):
        t = np.asarray(t, float)
        rpm, vel = np.zeros_like(t), np.zeros_like(t)
        for t0, T, kind, d in pieces:
            m = t >= t0
            s = np.clip(t[m] - t0, 0, T)
            if kind == "ramp":
                rpm[m] = d[0] + (d[1] - d[0]) * raised_cosine(s / T)
            elif kind == "slip":
                rpm[m] = d[0]
                vel[m] = gear_speed(s, 0.0, d[1], B)
            elif kind == "gear":
                vel[m] = gear_speed(s, d[0], d[1], B)
                rpm[m] = vel[m] * d[2]
            elif kind == "brake":
                vel[m] = d[0] - d[1] * s
                rpm[m] = vel[m] * d[2]
            else:                                      # blip
                vel[m] = d[0] - d[1] * s
                rpm[m] = vel[m] * (d[2] + (d[3] - d[2]) * raised_cosine(s / T))
        return rpm, vel
    return at, tc, pieces


# ---- a bugle call (the out-of-vocabulary case) ----

#: Taps as remembered (harmonic of the bugle's fundamental, beats): G is the 3rd harmonic, C the 4th, E the 5th, the
#: high G the 6th; the fermatas lengthen the held notes
TAPS = [(3, .75), (3, .25), (4, 3), (3, .75), (4, .25), (5, 3), (3, .5), (4, .5), (5, 1), (3, .5), (4, .5), (5, 1),
        (3, .5), (4, .5), (5, 2), (4, .75), (5, .25), (6, 3), (5, 1), (4, 1), (3, 2), (3, .75), (3, .25), (4, 5)]


def bugle(t, notes, f_b, ramp):
    """A bugle's notes (t0, T, harmonic, amplitude): each a sine of harmonic x f_b from phase 0 at t0, tongued on and
    off by raised cosines over `ramp` s (a natural trumpet plays only its harmonics: Benade, *Fundamentals of Musical
    Acoustics*, 1976), silent between."""
    t = np.asarray(t, float)
    v = np.zeros_like(t)
    for t0, T, k, amp in notes:
        m = (t >= t0) & (t < t0 + T)
        s = t[m] - t0
        v[m] = amp * raised_cosine(s / ramp) * raised_cosine((T - s) / ramp) * np.sin(2 * np.pi * k * f_b * s)
    return v


__all__ = ["rikitake_rhs", "rikitake_x", "lever_shots", "leg_speed", "leg_position", "shuttle_legs", "shuttle_run",
           "pedal_angle", "coulomb_free", "plucks", "sine_with_dwell", "dmt_symbol", "dmt_frame", "homing_history",
           "moves", "gear_speed", "gear_time", "drive_cycle", "TAPS", "bugle"]

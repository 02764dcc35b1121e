"""Excitations of the HOLDOUT31 set (``cases_holdout31.py``), each beside its source; the mechanisms are in
:mod:`.mechanisms31`. Citations written from memory in this session (none was re-read), as in mechanisms31.
"""

import math

import numpy as np

from .mechanisms19 import raised_cosine


def min_jerk(s):
    """The minimum-jerk profile 10 s^3 - 15 s^4 + 6 s^5 on 0 ... 1 (Flash & Hogan, J. Neurosci. 5 (1985) 1688),
    clipped outside."""
    s = np.clip(np.asarray(s, float), 0.0, 1.0)
    return s ** 3 * (10 - 15 * s + 6 * s * s)


def waypoint_path(t, times, values):
    """A hand's (or a machine's) path through waypoints (times[i], values[i]): a minimum-jerk move between consecutive
    ones (a hold where two are equal), values[0] before times[0], values[-1] after the last."""
    t = np.asarray(t, float)
    x = np.full_like(t, float(values[0]))
    for (ta, xa), (tb, xb) in zip(zip(times[:-1], values[:-1]), zip(times[1:], values[1:])):
        m = t >= ta
        x[m] = xa + (xb - xa) * min_jerk((t[m] - ta) / (tb - ta))
    return x


# ---- clean: a helmsman tacking a dinghy upwind ----

def dinghy_tacks(rng, n_tacks, side0):
    """The tiller's waypoints of a dinghy beating to windward: on each tack (2 ... 3.5 s) the helmsman's small
    corrections to the waves and gusts (a waypoint every 0.4 ... 1.2 s, up to +-0.3), a bear-away in a gust now and
    then (a push of 0.4 ... 0.6 held 1 ... 2 s), and at its end a tack: the tiller pushed hard over to 0.85 ... 1.0
    (alternately to each side), held through the turn, brought back across to meet the new course (an overshoot of 0.2
    ... 0.45) and centred (e.g. Dobson, *Sailing: The Basics*, on the roll tack). Returns (times, values), starting at
    0 at rest."""
    times, vals = [0.0], [0.0]
    tc = rng.uniform(0.6, 1.2)
    times.append(tc)
    vals.append(0.0)
    side = side0
    for j in range(n_tacks + 1):
        t_beat = tc + rng.uniform(2.0, 3.5)
        while tc < t_beat:
            if rng.random() < 0.12:
                a = rng.uniform(0.4, 0.6) * float(rng.choice([-1.0, 1.0]))
                tc += rng.uniform(0.5, 0.8)
                times += [tc, tc + rng.uniform(1.0, 2.0)]
                vals += [a, a]
                tc = times[-1]
            else:
                tc += rng.uniform(0.4, 1.2)
                times.append(tc)
                vals.append(rng.uniform(-0.3, 0.3))
        if j < n_tacks:
            A = side * rng.uniform(0.85, 1.0)
            for dT, val in ((rng.uniform(0.4, 0.7), A), (rng.uniform(1.0, 2.0), A),
                            (rng.uniform(0.6, 1.0), -side * rng.uniform(0.2, 0.45)), (rng.uniform(0.5, 0.9), 0.0)):
                tc += dT
                times.append(tc)
                vals.append(val)
            side = -side
    tc += rng.uniform(0.8, 1.5)
    times.append(tc)
    vals.append(0.0)
    return np.array(times), np.array(vals)


# ---- creep: a city bus's load along its route ----

def bus_route(rng, n_stops):
    """Passengers boarding and alighting a city bus along a route, as the load on its air suspension: at each stop
    (after 6 ... 14 s of driving) first 0 ... 5 alight, then 1 ... 7 board, each a step of the passenger's weight (50
    ... 100 kg) taken in 0.4 ... 0.9 s, one every 1.0 ... 2.5 s; at the terminus everyone alights. Returns events
    (t0, T, dm) and the end time."""
    events, tc, on = [], rng.uniform(2.0, 4.0), []
    for j in range(n_stops + 1):
        last = j == n_stops
        n_off = len(on) if last else int(rng.integers(0, min(len(on), 5) + 1))
        for _ in range(n_off):
            m = on.pop(int(rng.integers(len(on))))
            T = rng.uniform(0.4, 0.9)
            events.append((tc, T, -m))
            tc += T + rng.uniform(0.6, 1.6)
        if not last:
            for _ in range(int(rng.integers(1, 8))):
                m = rng.uniform(50.0, 100.0)
                on.append(m)
                T = rng.uniform(0.4, 0.9)
                events.append((tc, T, m))
                tc += T + rng.uniform(0.6, 1.6)
            tc += rng.uniform(6.0, 14.0)                  # the doors shut: the load held while driving
    return events, tc + rng.uniform(3.0, 6.0)


def bus_load(t, events):
    """The load: the sum of the passengers' steps, each a raised cosine over its T s."""
    t = np.asarray(t, float)
    x = np.zeros_like(t)
    for t0, T, dm in events:
        x += dm * raised_cosine((t - t0) / T)
    return x


# ---- rate: a snare drummer's open-close-open roll ----

def drum_roll(rng, n_rolls):
    """One stick's strokes in double-stroke rolls played open-close-open (slow, accelerating to 14 ... 20 strokes a
    second and back; each hand plays two strokes, the second a rebound 0.75 ... 0.9 as high, then lifts over the other
    hand's two), the stick lifted the less the faster (height about 1 / (1 + rate / 6)); a few accents between rolls
    and rests on the head. Returns strokes (t0, T, H) and the end time."""
    strokes, tc = [], rng.uniform(0.5, 1.0)
    for _ in range(n_rolls):
        r0, r1 = rng.uniform(3.0, 5.0), rng.uniform(14.0, 20.0)
        n_half = int(rng.integers(5, 9))                 # doubles accelerating, then as many slowing
        rates = np.r_[np.geomspace(r0, r1, n_half), np.geomspace(r1, r0, n_half)[1:]]
        for r in rates:
            P = 1.0 / r
            H = 1.0 / (1.0 + r / 6.0) * rng.uniform(0.95, 1.05)
            reb = rng.uniform(0.75, 0.9)
            strokes += [(tc, P, H), (tc + P, P, reb * H), (tc + 2 * P, 2 * P, H * rng.uniform(0.9, 1.1))]
            tc += 4 * P
        tc += rng.uniform(0.5, 1.5)
        for _ in range(int(rng.integers(1, 4))):          # accents
            T = rng.uniform(0.3, 0.5)
            strokes.append((tc, T, rng.uniform(0.9, 1.0)))
            tc += T + rng.uniform(0.2, 0.6)
        tc += rng.uniform(0.5, 1.5)
    return strokes, tc


def stick_height(t, strokes):
    """The stick's height over the head: each stroke an arc H sin^2(pi s / T) from the head and back (0 between)."""
    t = np.asarray(t, float)
    x = np.zeros_like(t)
    for t0, T, H in strokes:
        m = (t >= t0) & (t < t0 + T)
        x[m] = H * np.sin(math.pi * (t[m] - t0) / T) ** 2
    return x


# ---- drift: a fly fisherman casting ----

def fly_casting(rng, n_casts):
    """The rod's angle (forward positive) while fly fishing: from the fishing position the line is lifted (+0.3), and
    false casts follow, each a back cast (a quick stop at -A, 0.25 ... 0.4 s) and a pause while the line unrolls behind
    (0.4 ... 0.8 s), then a forward cast to +A and a pause, A growing with the line let out; the delivery lowers the
    rod to 0.2 ... 0.45 and the fly is fished back by strips (small twitches); then the next cast (e.g. Kreh,
    *Presenting the Fly*, 1999). Returns waypoints (times, values), at 0 at the start and the end."""
    times, vals, tc = [0.0], [0.0], rng.uniform(0.6, 1.2)
    times.append(tc)
    vals.append(0.0)
    for _ in range(n_casts):
        A = rng.uniform(0.45, 0.6)
        seq = [(rng.uniform(0.5, 0.8), 0.3)]
        for _ in range(int(rng.integers(2, 6))):
            A = min(A + rng.uniform(0.08, 0.2), 1.0)
            seq += [(rng.uniform(0.25, 0.4), -A * rng.uniform(0.95, 1.0)), (rng.uniform(0.4, 0.8), None),
                    (rng.uniform(0.25, 0.4), A * rng.uniform(0.9, 1.0)), (rng.uniform(0.3, 0.6), None)]
        low = rng.uniform(0.2, 0.45)
        seq += [(rng.uniform(0.6, 1.0), low), (rng.uniform(1.0, 2.0), None)]
        for _ in range(int(rng.integers(4, 10))):          # strips
            seq += [(rng.uniform(0.12, 0.2), low + rng.uniform(0.04, 0.1)), (rng.uniform(0.2, 0.4), low),
                    (rng.uniform(0.3, 0.9), None)]
        for dT, val in seq:
            tc += dT
            times.append(tc)
            vals.append(vals[-1] if val is None else val)
    tc += rng.uniform(0.8, 1.5)
    times.append(tc)
    vals.append(0.0)
    return np.array(times), np.array(vals)


# ---- asymmetry: a power kite flown in figure eights ----

def kite_lateral(psi, kappa):
    """The kite's place across the wind window in a figure eight, its phase psi advancing uniformly in a frame where
    it moves fastest through the window's centre (the power zone) and slowest at the edges where it turns: the angle
    phi along the path with phi' proportional to 1 + kappa cos 2 phi (integrated in closed form: tan phi = sqrt((1 +
    kappa) / (1 - kappa)) tan psi), and the lateral place sin phi = sqrt(1 + kappa) sin psi / sqrt(1 - kappa cos 2
    psi)."""
    psi = np.asarray(psi, float)
    return np.sqrt(1.0 + kappa) * np.sin(psi) / np.sqrt(1.0 - kappa * np.cos(2.0 * psi))


def kite_session(t, t0, segments, T_tr):
    """A power kite's session: after it is launched to the zenith (at rest at 0 before t0) the pilot flies segments
    (T, A, B, f, kappa): figure eights of width A about B at f per second (B = 0 across the window's centre, B near
    +-(1 - A) for loops to one side, A small for parking at the zenith); A, B, f and kappa pass from one segment to the
    next by raised cosines over T_tr s; the phase psi is the integral of 2 pi f (a cumulative trapezoid on the samples).
    Returns the lateral place in -1 ... 1."""
    t = np.asarray(t, float)
    pars = np.zeros((4, len(t)))
    prev = np.array([0.0, 0.0, segments[0][3], segments[0][4]])
    tc = t0
    for T, A, B, f, kap in segments:
        new = np.array([A, B, f, kap])
        w = raised_cosine((t - tc) / T_tr)
        m = t >= tc
        pars[:, m] = prev[:, None] + (new - prev)[:, None] * w[m]
        prev = new
        tc += T
    A, B, f, kap = pars
    f[t < t0] = segments[0][3]
    dt = t[1] - t[0]
    psi = np.r_[0.0, np.cumsum(0.5 * (f[1:] + f[:-1]) * 2 * math.pi * dt)]
    psi -= psi[np.searchsorted(t, t0)]
    return A * kite_lateral(psi, kap) + B


# ---- saturation: a steam locomotive's Walschaerts valve gear ----

def walschaerts_valve(theta, rho, E, L):
    """The valve's travel from mid position in Walschaerts's gear: the expansion link, rocked by the return crank a
    quarter turn from the main crank, gives rho E sin(theta) (rho the reverser's setting, -1 full backward gear ... 1
    full forward, E the link's full throw), and the combination lever, moved by the crosshead, adds the lap and lead,
    -L cos(theta) (e.g. Bell, *Locomotives*, 1935; the gear's amplitude sqrt(rho^2 E^2 + L^2), L even in mid gear)."""
    return rho * E * np.sin(theta) - L * np.cos(theta)


def loco_run(t, theta0, rho0, phases):
    """The crank angle and the reverser of a locomotive run through phases (T, w_end, rho_end, rho_T): over each the
    wheels' angular speed goes linearly to w_end (the crank angle integrated exactly: theta0 + w0 s + (w1 - w0) s^2 /
    (2 T)) and the reverser is wound from its setting to rho_end by a raised cosine over its first rho_T s. Returns
    (theta, rho)."""
    t = np.asarray(t, float)
    th = np.full_like(t, theta0)
    rho = np.full_like(t, rho0)
    tc, w0, r0, th0 = 0.0, 0.0, rho0, theta0
    for T, w1, r1, rT in phases:
        m = t >= tc
        s = np.minimum(t[m] - tc, T)
        th[m] = th0 + w0 * s + (w1 - w0) * s * s / (2 * T) + w1 * np.maximum(t[m] - tc - T, 0.0)
        rho[m] = r0 + (r1 - r0) * raised_cosine((t[m] - tc) / rT)
        th0 += w0 * T + (w1 - w0) * T / 2
        tc += T
        w0, r0 = w1, r1
    return th, rho


# ---- delay: a trampolinist's routine ----

def trampoline_flights(rng, n_routines):
    """A trampolinist's flights: standing on the bed, 6 ... 9 build-up bounces with flight times growing from 0.45 s to
    1.6 ... 1.9 s, a routine of ten skills (each 0.93 ... 1.0 of the top flight time), the bounce killed (the landing
    absorbed), 2 ... 4 s on the bed; contact 0.2 ... 0.3 s (e.g. FIG's code of points on the ten-skill routine).
    Returns flights (t0, T) and the end time."""
    flights, tc = [], rng.uniform(0.8, 1.5)
    for _ in range(n_routines):
        n_b = int(rng.integers(6, 10))
        T_top = rng.uniform(1.6, 1.9)
        for T in np.r_[np.geomspace(0.45, T_top, n_b), T_top * rng.uniform(0.93, 1.0, 10)]:
            flights.append((tc, T))
            tc += T + rng.uniform(0.2, 0.3)
        tc += rng.uniform(2.0, 4.0)
    return flights, tc


def flight_height(t, flights):
    """The athlete's height over the bed: a free fall's parabola in each flight, (4 H / T^2) s (T - s) with H = g T^2
    / 8 (here g = 8 so H = T^2), 0 on the bed."""
    t = np.asarray(t, float)
    x = np.zeros_like(t)
    for t0, T in flights:
        m = (t >= t0) & (t < t0 + T)
        s = t[m] - t0
        x[m] = 4.0 * s * (T - s)
    return x


# ---- initial state: weighing on an equal-arm balance ----

def balance_trials(box, m_obj, k_sens):
    """Weighing an object on an equal-arm balance by trial with a box of weights (largest first: a weight is left on
    if the object still outweighs, else taken off), each trial a release of the beam: the beam's rest tilt
    arctan(k_sens (m_obj - m_weights)) (the balance's sensitivity: tan theta = l dm / (M d), l the arm, M d the beam's
    moment), the last trial read by the method of swings. Returns the list of rest tilts."""
    eq, on = [], 0.0
    eq.append(math.atan(k_sens * m_obj))                          # the pan empty
    for w in box:
        d = m_obj - (on + w)
        eq.append(math.atan(k_sens * d))
        if d >= 0:
            on += w
    eq.append(math.atan(k_sens * (m_obj - on)))                   # read by swings
    return eq


def balance_tilt(t, releases):
    """The beam's tilt: releases (t0, T, theta_eq, f, zeta, T_arr): released from the arrest at 0 at t0, the beam
    swings about its rest tilt as a damped pendulum (theta_eq (1 - exp(-z w s) (cos wd s + z w / wd sin wd s)), w = 2
    pi f, wd = w sqrt(1 - z^2)) for T s, then the arrestment lifts it back to 0 over T_arr s (a raised cosine from
    where it was caught); 0 in between."""
    t = np.asarray(t, float)
    x = np.zeros_like(t)
    for t0, T, eq, f, z, Ta in releases:
        w = 2 * math.pi * f
        wd = w * math.sqrt(1 - z * z)

        def sw(s):
            return eq * (1 - np.exp(-z * w * s) * (np.cos(wd * s) + z * w / wd * np.sin(wd * s)))
        m = (t >= t0) & (t < t0 + T)
        x[m] = sw(t[m] - t0)
        caught = float(sw(np.array(T)))
        m = (t >= t0 + T) & (t < t0 + T + Ta)
        x[m] = caught * (1 - raised_cosine((t[m] - t0 - T) / Ta))
    return x


# ---- the pair: a flight simulator's motion platform in pitch ----

def platform_pitch(t, cues):
    """A flight simulator's pitch under classical washout (Reid & Nahon, UTIAS report 296, 1985): cues (t0, kind,
    a, T1, T2): "tilt" a sustained acceleration by tilt coordination, the platform tilted to a below the pilots'
    rotation threshold (a minimum-jerk ramp over T1), held T2 and back over T1; "onset" a transient of the high-pass
    washout, a (s / T1) exp(1 - s / T1) (peak a at s = T1); "turb" turbulence for T2 s, a sum of five sines of 0.5 ...
    3 Hz with amplitudes falling as 1 / f under a raised-cosine envelope (seeded by T1)."""
    t = np.asarray(t, float)
    x = np.zeros_like(t)
    for t0, kind, a, T1, T2 in cues:
        s = t - t0
        if kind == "tilt":
            x += a * (min_jerk(s / T1) - min_jerk((s - T1 - T2) / T1))
        elif kind == "onset":
            m = s > 0
            x[m] += a * (s[m] / T1) * np.exp(1 - s[m] / T1)
        else:
            r = np.random.default_rng(int(T1))
            fs = r.uniform(0.5, 3.0, 5)
            ph = r.uniform(0, 2 * math.pi, 5)
            m = (s > 0) & (s < T2)
            env = np.sin(math.pi * s[m] / T2) ** 2
            x[m] += a * env * sum(np.sin(2 * math.pi * f_ * s[m] + p) / f_ for f_, p in zip(fs, ph)) / 2.0
    return x


# ---- out of vocabulary: a watch's balance wheel on a timing machine ----

def balance_wheel(t, f, tau_a, positions, t_hack, T_stop):
    """A mechanical watch's balance on a timing machine: the balance swings isochronously at f (sin 2 pi f t), its
    amplitude relaxing with time constant tau_a (Q / (pi f)) toward each position's (positions: (T, A), the watch
    turned dial up, crown down, ...: the amplitude differs by position), started from rest at t = 0 by a flick; at
    t_hack the crown is pulled and the hacking lever stops the balance (the amplitude falls with time constant 0.05 s),
    and after T_stop s the crown is pushed back and it starts again toward the last position's amplitude."""
    t = np.asarray(t, float)
    A = np.zeros_like(t)
    a_prev, tc = 0.0, 0.0
    for T, a in positions:
        m = t >= tc
        A[m] = a + (a_prev - a) * np.exp(-(t[m] - tc) / tau_a)
        a_prev = a + (a_prev - a) * math.exp(-T / tau_a)
        tc += T
    m = t >= t_hack
    a_h = np.interp(t_hack, t, A)
    A[m] = a_h * np.exp(-(t[m] - t_hack) / 0.05)
    m = t >= t_hack + T_stop
    a_end = positions[-1][1]
    A[m] = a_end * (1 - np.exp(-(t[m] - t_hack - T_stop) / tau_a))
    ph = 2 * math.pi * f * t
    ph[m] = 2 * math.pi * f * (t[m] - t_hack - T_stop)
    return A * np.sin(ph)

"""Excitations of the HOLDOUT32 set (``cases_holdout32.py``), each beside its source; the mechanisms are in
:mod:`.mechanisms32`. Citations written from memory in this session (none was re-read), as in mechanisms32.

Every generator returns a path normalised to about -1 ... 1 (or 0 ... 1 for the unipolar ones) that starts at 0 at
rest; the cases scale it to volts.
"""

import math

import numpy as np
from scipy.integrate import solve_ivp


def min_jerk(s):
    """The minimum-jerk profile 10 s^3 - 15 s^4 + 6 s^5 on 0 ... 1 (Flash & Hogan, J. Neurosci. 5 (1985) 1688),
    clipped outside."""
    s = np.clip(np.asarray(s, float), 0.0, 1.0)
    return s ** 3 * (10 - 15 * s + 6 * s * s)


def waypoints(t, times, values):
    """Minimum-jerk moves between consecutive waypoints (a hold where two are equal); values[0] before the first,
    values[-1] after the last."""
    t = np.asarray(t, float)
    x = np.full_like(t, float(values[0]))
    for (ta, xa), (tb, xb) in zip(zip(times[:-1], values[:-1]), zip(times[1:], values[1:])):
        m = t >= ta
        x[m] = xa + (xb - xa) * min_jerk((t[m] - ta) / (tb - ta))
    return x


def speed_integral(t, knots_t, knots_w):
    """The angle swept at a speed linear between knots (a drive's ramps): the exact integral of the piecewise-linear
    speed, 0 at t = 0."""
    t = np.asarray(t, float)
    kt, kw = np.asarray(knots_t, float), np.asarray(knots_w, float)
    cum = np.r_[0.0, np.cumsum(0.5 * (kw[1:] + kw[:-1]) * np.diff(kt))]
    j = np.clip(np.searchsorted(kt, t, side="right") - 1, 0, len(kt) - 2)
    tau = np.clip(t - kt[j], 0.0, None)
    slope = (kw[j + 1] - kw[j]) / (kt[j + 1] - kt[j])
    inside = t <= kt[-1]
    part = np.where(inside, kw[j] * tau + 0.5 * slope * tau * tau, kw[-1] * (t - kt[-1]))
    return np.where(inside, cum[j] + part, cum[-1] + part)


# ---- clean: a turntablist scratching a record ----

def dj_scratches(rng, bpm, n_bars):
    """A turntablist's hand on the record against a beat (bpm): per beat one of the basic scratches on the sixteenth
    notes (e.g. Webber, *DJ Skills*, 2008): a baby scratch (pushed forward over the cue and pulled back, a sixteenth
    each), a tear (the forward push in two parts with a stop between), a scribble (the record shaken fast, a
    thirty-second each way, over a quarter), a backspin-style pull behind the cue and back, or a rest on the cue.
    Returns (times, values) for :func:`waypoints`: 0 on the cue, +-1 a quarter turn; every waypoint on the
    thirty-second-note grid after a lead-in of one beat."""
    beat = 60.0 / bpm
    q = beat / 4
    times, vals = [0.0, beat], [0.0, 0.0]
    tc = beat
    for _ in range(4 * n_bars):
        kind = rng.choice(["baby", "baby", "tear", "scribble", "back", "rest"])
        A = rng.uniform(0.55, 1.0)
        if kind == "baby":
            times += [tc + q, tc + 2 * q]
            vals += [A, 0.0]
            if rng.random() < 0.5:
                times += [tc + 3 * q, tc + 4 * q]
                vals += [-A * rng.uniform(0.5, 0.9), 0.0]
        elif kind == "tear":
            times += [tc + q, tc + 1.5 * q, tc + 2 * q, tc + 3 * q]
            vals += [A / 2, A / 2, A, 0.0]
        elif kind == "scribble":
            c0, a = rng.uniform(-0.3, 0.3), rng.uniform(0.08, 0.18)
            for j in range(8):
                times.append(tc + (j + 1) * q / 2)
                vals.append(0.0 if j == 7 else c0 + a * (1 if j % 2 == 0 else -1))
        elif kind == "back":
            times += [tc + q, tc + 3 * q]
            vals += [-A, 0.0]
        tc += beat
    times.append(tc + beat)
    vals.append(0.0)
    return times, vals


# ---- creep: a bascule bridge opening for shipping ----

def trapezoid_move(t, D, v_max, acc):
    """A move of D at most v_max fast with accelerations +-acc (a drive's trapezoidal speed profile; triangular when
    D is short): the position at t after its start, D after its end. Returns (positions, duration)."""
    t = np.asarray(t, float)
    D_abs = abs(D)
    ta = min(v_max / acc, math.sqrt(D_abs / acc))
    vp = acc * ta
    tc = (D_abs - acc * ta * ta) / vp
    T = 2 * ta + tc
    x = np.where(t <= 0, 0.0, np.where(t < ta, 0.5 * acc * t * t, np.where(
        t < ta + tc, 0.5 * acc * ta * ta + vp * (t - ta),
        np.where(t < T, D_abs - 0.5 * acc * (T - t) ** 2, D_abs))))
    return math.copysign(1.0, D) * x, T


def bascule_openings(rng, n_open):
    """A bascule bridge's leaf angle (0 closed, 1 fully open) over a session of openings for passing vessels: the
    barriers closed, the leaves raised by their drive (a trapezoidal speed profile: 0.08 ... 0.12 of the full angle a
    second, accelerating over 1.5 ... 2.5 s), fully for a ship or to 0.45 ... 0.75 for a sailing yacht's mast, held
    while it passes (8 ... 18 s), lowered and seated, the road traffic let over for 6 ... 14 s before the next (e.g.
    Tower Bridge's and the Chicago River bridges' operating practice). Returns a list of moves (start, from, to,
    v_max, acc) and the end time."""
    moves, tc, cur = [], rng.uniform(3.0, 6.0), 0.0
    full = int(rng.integers(n_open))                                 # at least one full opening, for a ship
    for j in range(n_open):
        target = 1.0 if (j == full or rng.random() < 0.5) else rng.uniform(0.45, 0.75)
        vm, T_acc = rng.uniform(0.08, 0.12), rng.uniform(1.5, 2.5)
        _, T = trapezoid_move(0.0, target - cur, vm, vm / T_acc)
        moves.append((tc, cur, target, vm, vm / T_acc))
        tc += T + rng.uniform(8.0, 18.0)
        _, T = trapezoid_move(0.0, -target, vm, vm / T_acc)
        moves.append((tc, target, 0.0, vm, vm / T_acc))
        tc += T + rng.uniform(6.0, 14.0)
    return moves, tc


def leaf_angle(t, moves):
    """The leaf angle along :func:`bascule_openings`' moves."""
    x = np.zeros(len(t))
    for t0, a, b, vm, acc in moves:
        m = t >= t0
        x[m] = a + trapezoid_move(t[m] - t0, b - a, vm, acc)[0]
    return x


# ---- rate dependence: a dobby loom's heddle frame ----

def loom_picks(rng):
    """A dobby loom's speed over a run (picks a second): started from rest in 1.0 ... 1.5 s to 2.5 ... 4 picks a
    second, run, slowed for a weft change and back up, stopped by a warp break (the weaver mends it for 1.5 ... 3 s),
    restarted at a higher speed of 4 ... 5.5 picks a second and stopped. Returns the speed's knots (times, rates)."""
    r1, r2 = rng.uniform(2.5, 4.0), rng.uniform(4.0, 5.5)
    kt, kw = [0.0, rng.uniform(0.3, 0.6)], [0.0, 0.0]
    for dT, w in ((rng.uniform(1.0, 1.5), r1), (rng.uniform(2.0, 3.5), r1), (rng.uniform(0.6, 1.0), rng.uniform(1.0,
                  1.6)), (rng.uniform(1.0, 2.0), rng.uniform(1.0, 1.6)), (rng.uniform(0.6, 1.0), r1),
                  (rng.uniform(2.0, 3.0), r1), (rng.uniform(0.3, 0.5), 0.0), (rng.uniform(1.5, 3.0), 0.0),
                  (rng.uniform(1.0, 1.5), r2), (rng.uniform(3.0, 4.5), r2), (rng.uniform(0.4, 0.7), 0.0),
                  (rng.uniform(0.5, 1.0), 0.0)):
        kt.append(kt[-1] + dT)
        kw.append(w)
    return kt, kw


def heddle_lift(t, kt, kw, pattern, move_frac):
    """One heddle frame's lift (0 down, 1 up) as the loom weaves: the pick count is the integral of the speed; the
    frame's state on pick i is pattern[i mod len], and it changes during the first move_frac of a pick by a simple
    harmonic cam's motion (1 - cos) / 2, dwelling for the rest (the shed open for the shuttle; e.g. Marks & Robinson,
    *Principles of Weaving*, 1976, on dobby shedding)."""
    phi = speed_integral(t, kt, kw)
    i = np.floor(phi).astype(int)
    frac = phi - i
    pat = np.asarray(pattern, float)
    prev, cur = pat[(i - 1) % len(pat)], pat[i % len(pat)]
    prev = np.where(i <= 0, 0.0, prev)
    s = np.clip(frac / move_frac, 0.0, 1.0)
    return prev + (cur - prev) * (0.5 - 0.5 * np.cos(np.pi * s))


# ---- drift: a beam pumping unit's polished rod ----

def pumpjack_beam_angle(theta, R, P, C, I, H):
    """The walking beam's angle of a conventional (class I) beam pumping unit for the crank angle theta: saddle
    bearing at the origin, crankshaft at (-I, -H), crank R, pitman P, the beam's back arm C; the back arm's end E =
    -C (cos b, sin b) must lie P from the crank pin Q = (-I + R cos theta, -H + R sin theta). The two circles'
    intersection above the crank (API Spec 11E's geometry): returns b (the horsehead up for b > 0)."""
    qx, qy = -I + R * np.cos(theta), -H + R * np.sin(theta)
    d2 = qx * qx + qy * qy
    # E on |E| = C with |E - Q| = P: E.Q = (C^2 + d2 - P^2) / 2; E = -C (cos b, sin b)
    cphi = (C * C + d2 - P * P) / (2 * C * np.sqrt(d2))            # cos of the angle between E and Q
    ang_q = np.arctan2(qy, qx)
    e_ang = ang_q - np.arccos(np.clip(cphi, -1.0, 1.0))              # the branch with E above the crank
    return np.arctan2(-np.sin(e_ang), -np.cos(e_ang))


def pumpjack_speeds(rng):
    """A model pumping unit's crank speed (radians a second) on a variable-frequency drive (a field unit runs at 5 ...
    15 strokes a minute; the model ten times faster): started, run at 60 ... 90 strokes a minute, raised to 100 ... 130
    as the well fills, slowed to 45 ... 65 as it pumps off, stopped for 2 ... 4 s and restarted at 70 ... 95. Returns
    knots (times, speeds)."""
    spm = [rng.uniform(60, 90), rng.uniform(100, 130), rng.uniform(45, 65), rng.uniform(70, 95)]
    w = [2 * math.pi * s / 60.0 for s in spm]
    kt, kw = [0.0, rng.uniform(0.3, 0.8)], [0.0, 0.0]
    for dT, ww in ((rng.uniform(1.5, 2.5), w[0]), (rng.uniform(6.0, 9.0), w[0]), (rng.uniform(2.0, 3.0), w[1]),
                   (rng.uniform(6.0, 9.0), w[1]), (rng.uniform(2.0, 3.0), w[2]), (rng.uniform(6.0, 9.0), w[2]),
                   (rng.uniform(1.5, 2.5), 0.0), (rng.uniform(2.0, 4.0), 0.0), (rng.uniform(1.5, 2.5), w[3]),
                   (rng.uniform(6.0, 9.0), w[3]), (rng.uniform(1.5, 2.5), 0.0), (rng.uniform(0.5, 1.0), 0.0)):
        kt.append(kt[-1] + dT)
        kw.append(ww)
    return kt, kw


# ---- asymmetry: a carousel's galloping horses ----

def carousel_rides(rng, n_rides):
    """A carousel's platform speed over rides (revolutions a second; a short ride): each ride started over 3 ... 4 s
    to 5 ... 7 revolutions a minute, run 5 ... 8 s, braked over 3 ... 4 s, the riders changing for 1.5 ... 2.5 s.
    Returns knots."""
    kt, kw = [0.0, rng.uniform(0.5, 1.0)], [0.0, 0.0]
    for _ in range(n_rides):
        w = rng.uniform(5.0, 7.0) / 60.0
        for dT, ww in ((rng.uniform(3.0, 4.0), w), (rng.uniform(5.0, 8.0), w), (rng.uniform(3.0, 4.0), 0.0),
                       (rng.uniform(1.5, 2.5), 0.0)):
            kt.append(kt[-1] + dT)
            kw.append(ww)
    return kt, kw


def horse_height(t, kt, kw, n_cranks, phase):
    """A horse's height: its pole hangs from a crank of the overhead shaft, geared to make n_cranks strokes a
    revolution of the platform: sin(2 pi n_cranks rev(t) + phase) - sin(phase), rev the platform's revolutions (the
    ride starting with the horse wherever it stopped)."""
    rev = speed_integral(t, kt, kw)
    return np.sin(2 * math.pi * n_cranks * rev + phase) - math.sin(phase)


# ---- saturation: an accordion's bellows ----

def bellows_phrases(rng, n_phrases):
    """An accordionist's bellows (+1 fully drawn, -1 fully closed, 0 half open): phrases drawn and pushed in turn (the
    bellows changed at the phrase's end, in 0.08 ... 0.15 s), each 1.5 ... 4 s with the bellows' speed following its
    dynamics (a crescendo, a diminuendo or an even tone: the air flow, and so the speed, goes with the loudness), and
    now and then a bellows shake (the bellows reversed on every note, 6 ... 9 a second, 0.08 ... 0.15 in and out)
    (e.g. Macerollo, *Accordion Resource Manual*, 1980). Returns segments (start, duration, from, to, kind, extra)."""
    segs, tc, cur, side = [], rng.uniform(0.4, 0.8), 0.0, float(rng.choice([-1.0, 1.0]))
    for j in range(n_phrases):
        if j > 0 and rng.random() < 0.3:
            f = rng.uniform(6.0, 9.0)
            T = int(rng.integers(6, 14)) / f
            segs.append((tc, T, cur, cur, "shake", (f, rng.uniform(0.08, 0.15))))
            tc += T + rng.uniform(0.08, 0.15)
        target = side * rng.uniform(0.87, 1.0)
        T = rng.uniform(1.5, 4.0)
        segs.append((tc, T, cur, target, str(rng.choice(["cresc", "dim", "even"])), None))
        tc += T + rng.uniform(0.08, 0.15)
        cur, side = target, -side
    segs.append((tc, rng.uniform(1.0, 1.5), cur, 0.0, "even", None))
    return segs, tc + segs[-1][1] + rng.uniform(0.5, 1.0)


def bellows_position(t, segs):
    """The bellows along :func:`bellows_phrases`: within a phrase the travel is the speed's integral, the speed sin(pi
    s) (started and stopped smoothly, s the phrase's fraction) times 1 + s (crescendo), 2 - s (diminuendo) or 1; a
    shake moves the bellows in by amp sin^2(pi f tau) and out again, f times a second, for a whole number of cycles."""
    x = np.zeros(len(t))
    for t0, T, a, b, kind, extra in segs:
        m = t >= t0
        if kind == "shake":
            f, amp = extra
            tau = np.clip(t[m] - t0, 0.0, T)
            x[m] = a - math.copysign(1.0, a) * amp * np.sin(math.pi * f * tau) ** 2
            continue
        s = np.clip((t[m] - t0) / T, 0.0, 1.0)
        I0 = (1 - np.cos(math.pi * s)) / math.pi                                  # int_0^s sin(pi r) dr
        I1 = np.sin(math.pi * s) / math.pi ** 2 - s * np.cos(math.pi * s) / math.pi   # int_0^s r sin(pi r) dr
        if kind == "cresc":
            F = (I0 + I1) / (3 / math.pi)
        elif kind == "dim":
            F = (2 * I0 - I1) / (3 / math.pi)
        else:
            F = I0 / (2 / math.pi)
        x[m] = a + (b - a) * F
    return x


# ---- delay: a stamp mill's stamp ----

def stamp_drops(rng, n_drops):
    """One stamp of a gravity stamp mill: lifted by a cam's tappet at a steady speed (an involute cam lifts
    uniformly) through 0.9 ... 1.0 of the full drop in 0.4 ... 0.5 of a cycle, released at the top with the lift's
    speed, rising a little, falling freely onto the ore on the die and resting there until the cam comes round again
    (e.g. Richards, *Ore Dressing*, 1903, on the California stamp); 60 ... 85 drops a minute, varied by the feeder
    every twelve drops, and one hung up on its finger at the top for 2 ... 4 s while the die is cleared. Returns drops
    (start, lift time, height, hold at the top), the fall's gravity (heights a second squared) and the end time."""
    drops, tc = [], rng.uniform(0.5, 1.0)
    g = rng.uniform(45.0, 60.0)
    hang = int(rng.integers(n_drops // 3, 2 * n_drops // 3))
    for j in range(n_drops):
        if j % 12 == 0:
            cycle = 60.0 / rng.uniform(60, 85)
        hold = rng.uniform(2.0, 4.0) if j == hang else 0.0
        drops.append((tc, cycle * rng.uniform(0.4, 0.5), rng.uniform(0.9, 1.0), hold))
        tc += cycle + hold
    return drops, g, tc + rng.uniform(0.5, 1.0)


def stamp_release(T_l, H, hold):
    """The speed u at the release (the uniform lift's, H / (0.95 T_l); 0 after a hang) and the fall's start."""
    return (0.0 if hold > 0 else H / (0.95 * T_l)), T_l + hold


def stamp_height(t, drops, g):
    """The stamp's height along :func:`stamp_drops`: a quadratic take-up over the first 10 % of the lift (the
    tappet's engagement), then the uniform lift at u; a hung stamp held at H; from the release a projectile, H + u s -
    g s^2 / 2, until it lands at s = (u + sqrt(u^2 + 2 g H)) / g."""
    z = np.zeros(len(t))
    for t0, T_l, H, hold in drops:
        u_l = H / (0.95 * T_l)
        m = (t >= t0) & (t < t0 + T_l)
        s = t[m] - t0
        ta = 0.1 * T_l
        z[m] = np.where(s < ta, 0.5 * u_l * s * s / ta, u_l * (s - ta / 2))
        u, t_rel = stamp_release(T_l, H, hold)
        z[(t >= t0 + T_l) & (t < t0 + t_rel)] = H
        s_land = (u + math.sqrt(u * u + 2 * g * H)) / g
        m = (t >= t0 + t_rel) & (t < t0 + t_rel + s_land)
        s = t[m] - t0 - t_rel
        z[m] = H + u * s - 0.5 * g * s * s
    return z


# ---- initial state: a skipping rope's handle ----

def skipping_routine(rng):
    """A skipper's turning speed (turns a second) and the circle of the wrists: basic bounces at 1.8 ... 2.3 turns a
    second, a run of double-unders (3.0 ... 3.6 a second, the wrists' circle smaller), a trip (the rope stopped by a
    foot in 0.15 ... 0.3 s, the handle left where it was, and the rope restarted), slow side swings (1.2 ... 1.5 a
    second), stopped. Returns (knots_t, knots_w, radius_knots): the speed and the circle's radius linear between
    knots."""
    kt, kw, kr = [0.0, rng.uniform(0.3, 0.6)], [0.0, 0.0], [1.0, 1.0]
    for dT, w, r in ((rng.uniform(0.5, 0.8), rng.uniform(1.8, 2.3), 1.0), (rng.uniform(3.0, 5.0), None, 1.0),
                     (rng.uniform(0.5, 0.8), rng.uniform(3.0, 3.6), rng.uniform(0.6, 0.75)),
                     (rng.uniform(2.0, 3.5), None, None), (rng.uniform(0.15, 0.3), 0.0, None),
                     (rng.uniform(1.0, 2.0), 0.0, 1.0), (rng.uniform(0.5, 0.8), rng.uniform(1.8, 2.3), 1.0),
                     (rng.uniform(3.0, 5.0), None, None), (rng.uniform(0.5, 0.8), rng.uniform(1.2, 1.5), 1.0),
                     (rng.uniform(2.0, 3.0), None, None), (rng.uniform(0.5, 0.8), 0.0, None),
                     (rng.uniform(0.5, 1.0), 0.0, None)):
        kt.append(kt[-1] + dT)
        kw.append(kw[-1] if w is None else w)
        kr.append(kr[-1] if r is None else r)
    return kt, kw, kr


def handle_position(t, kt, kw, kr):
    """The handle's sideways position: the wrist's circle radius r(t) at the turning angle's 2 pi turns(t), x = r sin
    (0 at rest at the start; the rope's tripping stops it where it is, and the speed's knots bring it on)."""
    turns = speed_integral(t, kt, kw)
    return np.interp(t, kt, kr) * np.sin(2 * math.pi * turns)


# ---- the pair: a launcher's engine gimbal in pitch ----

def gimbal_events(rng):
    """A launcher's engine gimbal in pitch through an ascent (compressed in time): held at the pad, the pitch-over
    kick, the gravity turn's small trim, responses to wind shear (damped oscillations of the attitude loop, 0.8 ...
    1.6 Hz, damping 0.2 ... 0.35), load relief around maximum dynamic pressure (a slow deflection held), propellant
    slosh coupling (a lightly damped 0.5 ... 0.8 Hz oscillation growing and dying out) and the transient at staging.
    Returns events (start, kind, parameters) and the end time."""
    ev, tc = [], rng.uniform(1.0, 2.0)
    ev.append((tc, "move", (rng.uniform(0.45, 0.7), rng.uniform(1.5, 2.5), rng.uniform(1.0, 2.0))))
    tc += rng.uniform(3.5, 5.0)
    for _ in range(int(rng.integers(3, 5))):
        ev.append((tc, "ring", (float(rng.choice([-1.0, 1.0])) * rng.uniform(0.35, 0.7), rng.uniform(0.8, 1.6),
                               rng.uniform(0.2, 0.35))))
        tc += rng.uniform(1.5, 3.0)
    ev.append((tc, "move", (-rng.uniform(0.4, 0.6), rng.uniform(1.5, 2.5), rng.uniform(2.0, 3.5))))
    tc += rng.uniform(2.0, 3.0)
    ev.append((tc, "slosh", (rng.uniform(0.25, 0.4), rng.uniform(0.5, 0.8), rng.uniform(2.5, 4.0))))
    tc += rng.uniform(5.0, 7.0)
    ev.append((tc, "ring", (float(rng.choice([-1.0, 1.0])) * rng.uniform(0.6, 0.9), rng.uniform(1.8, 2.6),
                           rng.uniform(0.15, 0.25))))
    return ev, tc + rng.uniform(3.0, 4.0)


def gimbal_angle(t, events):
    """The gimbal angle along :func:`gimbal_events`: a move (amplitude, ramp time, hold) a minimum-jerk deflection held
    and taken back; a ring (amplitude, f, zeta) the damped oscillation a sin(w_d s) exp(-zeta w s) of a second-order
    loop disturbed at rest; slosh (amplitude, f, T) a sin(2 pi f s) (s / T) exp(1 - s / T), the coupling growing
    and dying away."""
    x = np.zeros(len(t))
    for t0, kind, p in events:
        s = t - t0
        m = s > 0
        if kind == "move":
            A, Tr, Th = p
            x += A * (min_jerk(s / Tr) - min_jerk((s - Tr - Th) / Tr))
        elif kind == "ring":
            A, f, z = p
            w = 2 * math.pi * f
            x[m] += A * np.sin(w * math.sqrt(1 - z * z) * s[m]) * np.exp(-z * w * s[m])
        else:
            A, f, T = p
            x[m] += A * np.sin(2 * math.pi * f * s[m]) * (s[m] / T) * np.exp(1 - s[m] / T)
    return x


# ---- out of vocabulary: a weathervane in a gusty, veering wind ----

def vane_rhs(t, s, k, c, wind):
    """A weathervane's yaw theta in a wind of speed U from direction psi: theta'' = -k U^2 sin(theta - psi) - c U
    theta' (the tail's lift ~ U^2 and its aerodynamic damping ~ U; e.g. Wieringa on wind vane dynamics, J. Appl.
    Meteorol. 6 (1967) 1114); ``wind(t)`` returns (U, psi)."""
    U, psi = wind(t)
    return [s[1], -k * U * U * math.sin(s[0] - psi) - c * U * s[1]]


def gusty_wind(rng):
    """A wind of mean speed 1 with gusts (a few random sines, +-20 ... 35 %) veering and backing through +-0.8 ... 1.1
    rad (random sines of 0.05 ... 0.4 Hz), 0 at the start. Returns a function of t -> (U, psi) and its parameters."""
    fu = rng.uniform(0.1, 0.6, 4)
    au = rng.uniform(0.2, 0.35) * rng.dirichlet(np.ones(4))
    pu = rng.uniform(0, 2 * math.pi, 4)
    fp = rng.uniform(0.05, 0.4, 5)
    ap = rng.uniform(0.8, 1.1) * rng.dirichlet(np.ones(5))
    pp = rng.uniform(0, 2 * math.pi, 5)

    def wind(t):
        U = 1.0 + float(np.sum(au * np.sin(2 * math.pi * fu * t + pu)))
        psi = float(np.sum(ap * (np.sin(2 * math.pi * fp * t + pp) - np.sin(pp))))
        return U, psi
    return wind, dict(fu=fu, au=au, pu=pu, fp=fp, ap=ap, pp=pp)


def vane_yaw(t, k, c, wind):
    """The vane's yaw by solve_ivp (DOP853, rtol 1e-9), at rest along the wind at the start."""
    sol = solve_ivp(vane_rhs, (t[0], t[-1]), [0.0, 0.0], t_eval=t, args=(k, c, wind), method="DOP853", rtol=1e-9,
                    atol=1e-11, max_step=0.05)
    return sol.y[0]

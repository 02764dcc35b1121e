"""Signals of the HOLDOUT50 set (``cases_holdout50.py``): everyday scenes, each drawn from a generator here.

Every scene is a programme of knots (time, position) joined by moves; the evaluator takes any times (a record's grid or
a finer one) and returns the position, exactly the first knot's before the programme starts and the last's after it.
The move is a skewed reach, written from its definition: the distribution function of the Beta(2, 4) law,

    R(s) = 1 - (1 - s)^4 (1 + 4 s),  s in 0 ... 1,

whose speed 20 s (1 - s)^3 is 0 at both ends and peaks at a quarter of the move (at 135/64 = 2.11 times the mean speed):
a quick start and a long, gentle homing, as a hand's reach lands on its target (the Beta law's distribution function is
a regularised incomplete beta function; for these integer parameters it is the polynomial above, expanded here by hand:
1 - (1 - s)^4 (1 + 4 s) = 10 s^2 - 20 s^3 + 15 s^4 - 4 s^5). Its acceleration jumps to 20 (a unit move over a unit
time) at the start and is 0 at the end. Nothing here imports hystcomp.
"""

import numpy as np

from .set_tools import Programme as _Prog, knots_at as _knots_at

#: the move's peak speed (a unit move over a unit time), at s = 1/4
PEAK_SPEED = 135.0 / 64.0


def reach(s):
    """The move 0 ... 1 over s in 0 ... 1 (0 before, 1 after): 1 - (1 - s)^4 (1 + 4 s)."""
    s = np.clip(np.asarray(s, float), 0.0, 1.0)
    return 1.0 - (1.0 - s) ** 4 * (1.0 + 4.0 * s)


def knots_at(t, knots):
    """The position on times t through knots [(time, position), ...] joined by skewed reaches; the first knot's
    position before it, the last's after."""
    return _knots_at(t, knots, reach)


def _side(rng):
    """A side drawn at even odds: +1 or -1 (one uniform draw)."""
    return 1.0 if rng.uniform() < 0.5 else -1.0


# ---- a table-tennis player's bat (the clean case) ----

def table_tennis(rng, n_rallies):
    """A table-tennis player's bat (its face's angle: + forehand, - backhand): for every rally, 6 ... 13 strokes on a
    side drawn each time, each a backswing (to 0.2 ... 0.4 of the reach on the other side in 0.15 ... 0.3 s), the
    stroke (to 0.6 ... 1 in 0.1 ... 0.18 s), the follow-through held 0.05 ... 0.15 s and the return to the ready
    position (within 0.08 of 0, either way, in 0.2 ... 0.35 s); between rallies the ball fetched (the bat at 0, held 2
    ... 4 s). The full reach on both sides in the first rally. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.5, 1.0))
    for r in range(n_rallies):
        n = int(rng.integers(6, 14))
        for k in range(n):
            sd = (1.0 if k == 0 else -1.0) if r == 0 and k < 2 else _side(rng)
            a = 1.0 if (r == 0 and k < 2) else rng.uniform(0.6, 1.0)
            p.to(rng.uniform(0.15, 0.3), -sd * rng.uniform(0.2, 0.4))
            p.to(rng.uniform(0.1, 0.18), sd * a)
            p.hold(rng.uniform(0.05, 0.15))
            p.to(rng.uniform(0.2, 0.35), _side(rng) * rng.uniform(0.0, 0.08))
        p.to(rng.uniform(0.3, 0.5), 0.0)
        p.hold(rng.uniform(2.0, 4.0))
    return p.kn, p.t


# ---- a drill press's feed lever (unipolar) ----

def drill_press(rng, n_holes):
    """A drill press's quill (0 up, 1 the full depth of the stop) through a batch of holes: for every hole the bit
    brought down to the work (to 0.1 ... 0.2 in 0.5 ... 1 s, held 1 ... 2 s), then pecked in (3 ... 5 pecks, each 0.12
    ... 0.2 deeper in 0.4 ... 0.8 s, a dwell of 1.5 ... 3 s at its depth, backed off by 0.3 ... 0.5 of the depth to
    clear the chips in 0.2 ... 0.4 s and brought back in 0.3 ... 0.5 s), the last to 0.85 ... 1 (the stop once at
    least) and held 3 ... 5 s, the quill let up (to 0 in 0.8 ... 1.5 s) and 6 ... 12 s to clamp the next piece.
    Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(1.0, 2.0))
    full = int(rng.integers(0, n_holes))
    for k in range(n_holes):
        x = rng.uniform(0.1, 0.2)
        p.to(rng.uniform(0.5, 1.0), x)
        p.hold(rng.uniform(1.0, 2.0))
        n = int(rng.integers(3, 6))
        last = 1.0 if k == full else rng.uniform(0.85, 1.0)
        for j in range(n):
            x = last if j == n - 1 else min(x + rng.uniform(0.12, 0.2), last - 0.05)
            p.to(rng.uniform(0.4, 0.8), x)
            if j < n - 1:
                p.hold(rng.uniform(1.5, 3.0))
                p.to(rng.uniform(0.2, 0.4), x * (1.0 - rng.uniform(0.3, 0.5)))
                p.to(rng.uniform(0.3, 0.5), x)
        p.hold(rng.uniform(3.0, 5.0))
        p.to(rng.uniform(0.8, 1.5), 0.0)
        p.hold(rng.uniform(6.0, 12.0))
    return p.kn, p.t


# ---- a xylophone player's mallet ----

def xylophone(rng, n_phrases):
    """A xylophone player's right mallet over the bars (+ up the keyboard, - down it), never still: for every phrase,
    8 ... 16 notes (leaps to a bar 0.2 ... 1 of the reach away either way, within the reach, in 0.05 ... 0.15 s), a roll
    on one bar (10 ... 20 strokes of 0.05 ... 0.12 either side of it, 0.03 ... 0.06 s each) and a glissando (a sweep to
    the other end, 0.8 ... 1 of the reach, in 0.25 ... 0.5 s). The full reach both ways in the first phrase. No holds:
    no two knots alike in a row. Returns the knots and the end."""
    p = _Prog()
    x = 0.0
    p.to(0.2, 0.05)
    x = 0.05
    for ph in range(n_phrases):
        for k in range(int(rng.integers(8, 17))):
            if ph == 0 and k < 2:
                x_new = 1.0 if k == 0 else -1.0
            else:
                x_new = x
                while abs(x_new - x) < 0.2:
                    x_new = float(np.clip(x + _side(rng) * rng.uniform(0.2, 1.0), -1.0, 1.0))
            x = x_new
            p.to(rng.uniform(0.05, 0.15), x)
        c = float(np.clip(x, -0.85, 0.85))
        a = rng.uniform(0.05, 0.12)
        for k in range(int(rng.integers(10, 21))):
            p.to(rng.uniform(0.03, 0.06), c + (a if k % 2 == 0 else -a))
        x = -np.sign(c if c != 0.0 else 1.0) * rng.uniform(0.8, 1.0)
        p.to(rng.uniform(0.25, 0.5), x)
    p.to(rng.uniform(0.3, 0.5), 0.0)
    return p.kn, p.t


# ---- a treadmill's hill programme (unipolar) ----

def treadmill_hills(rng, n_hills):
    """A treadmill's incline through a hill workout (0 flat, 1 its steepest): a warm-up on the flat (held 10 ... 20 s),
    then for every hill a climb (to 0.4 ... 1 in 2 ... 5 s: the steepest once at least), held 8 ... 20 s, eased to 0.1
    ... 0.3 (in 2 ... 4 s) and held 5 ... 10 s; a cool-down back to the flat (in 3 ... 6 s, held 8 ... 15 s). Returns
    the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(10.0, 20.0))
    full = int(rng.integers(0, n_hills))
    for k in range(n_hills):
        p.to(rng.uniform(2.0, 5.0), 1.0 if k == full else rng.uniform(0.4, 1.0))
        p.hold(rng.uniform(8.0, 20.0))
        p.to(rng.uniform(2.0, 4.0), rng.uniform(0.1, 0.3))
        p.hold(rng.uniform(5.0, 10.0))
    p.to(rng.uniform(3.0, 6.0), 0.0)
    p.hold(rng.uniform(8.0, 15.0))
    return p.kn, p.t


# ---- an ice skater's strides ----

def ice_skater(rng, n_laps):
    """An ice skater's strides (+ a push with the right skate, - with the left): for every lap, 6 ... 10 strides on the
    straight (each a push to 0.6 ... 1 of the reach in 0.25 ... 0.4 s and the glide back to 0.1 ... 0.2 on that side
    in 0.3 ... 0.5 s, held 0.2 ... 0.5 s, the sides in turn), a turn's crossovers (4 ... 7 quick pushes, the outside
    skate's 0.5 ... 0.8 of the reach, the inside one's 0.2 ... 0.4, 0.15 ... 0.25 s each) and a coast (to 0 in 0.3
    ... 0.6 s, held 1 ... 3 s). The full reach both ways in the first lap. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.5, 1.0))
    for lap in range(n_laps):
        sd = _side(rng)
        for k in range(int(rng.integers(6, 11))):
            a = 1.0 if (lap == 0 and k < 2) else rng.uniform(0.6, 1.0)
            p.to(rng.uniform(0.25, 0.4), sd * a)
            p.to(rng.uniform(0.3, 0.5), sd * rng.uniform(0.1, 0.2))
            p.hold(rng.uniform(0.2, 0.5))
            sd = -sd
        out = _side(rng)
        for k in range(int(rng.integers(4, 8))):
            if k % 2 == 0:
                p.to(rng.uniform(0.15, 0.25), out * rng.uniform(0.5, 0.8))
            else:
                p.to(rng.uniform(0.15, 0.25), -out * rng.uniform(0.2, 0.4))
        p.to(rng.uniform(0.3, 0.6), 0.0)
        p.hold(rng.uniform(1.0, 3.0))
    return p.kn, p.t


# ---- a volleyball player's pepper drill ----

def volleyball_pepper(rng, n_sets):
    """A volleyball player's arms in a pepper drill with a partner (+ up, the arms raised to hit; - down, to dig),
    never still: for every set of 5 ... 10 exchanges, a dig (to 0.6 ... 1 of the reach down in 0.1 ... 0.2 s), a set
    (to 0.3 ... 0.6 up in 0.2 ... 0.35 s), a hit (to 0.8 ... 1 up in 0.08 ... 0.15 s) and the ready position (within
    0.1 of 0, either way, in 0.25 ... 0.45 s); between sets the ball retrieved with the arms swinging (3 ... 6 swings
    of 0.1 ... 0.3 either way, 0.3 ... 0.6 s each). The full reach both ways in the first set. No holds: no two knots
    alike in a row. Returns the knots and the end."""
    p = _Prog()
    p.to(0.3, -0.05)
    for st in range(n_sets):
        for k in range(int(rng.integers(5, 11))):
            first = st == 0 and k == 0
            p.to(rng.uniform(0.1, 0.2), -(1.0 if first else rng.uniform(0.6, 1.0)))
            p.to(rng.uniform(0.2, 0.35), rng.uniform(0.3, 0.6))
            p.to(rng.uniform(0.08, 0.15), 1.0 if first else rng.uniform(0.8, 1.0))
            p.to(rng.uniform(0.25, 0.45), _side(rng) * rng.uniform(0.01, 0.1))
        for k in range(int(rng.integers(3, 7))):
            p.to(rng.uniform(0.3, 0.6), (1.0 if k % 2 == 0 else -1.0) * rng.uniform(0.1, 0.3))
    p.to(rng.uniform(0.3, 0.5), 0.0)
    return p.kn, p.t


# ---- a lawn mower's pull-start cord (unipolar) ----

def pull_start(rng, n_attempts):
    """A lawn mower's pull-start cord (0 the handle on its guide, 1 the cord's full length out): for every attempt the
    slack taken up (1 ... 3 tugs to 0.1 ... 0.2 in 0.15 ... 0.3 s and back to 0 in 0.2 ... 0.3 s), the pull (to 0.8
    ... 1 in 0.25 ... 0.45 s: the full length once at least), the handle let back on the recoil spring (to 0 in 0.4
    ... 0.8 s) and 1.5 ... 4 s to prime the bulb or set the choke. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.5, 1.0))
    full = int(rng.integers(0, n_attempts))
    for k in range(n_attempts):
        for _ in range(int(rng.integers(1, 4))):
            p.to(rng.uniform(0.15, 0.3), rng.uniform(0.1, 0.2))
            p.to(rng.uniform(0.2, 0.3), 0.0)
        p.to(rng.uniform(0.25, 0.45), 1.0 if k == full else rng.uniform(0.8, 1.0))
        p.to(rng.uniform(0.4, 0.8), 0.0)
        p.hold(rng.uniform(0.5, 1.5))
    return p.kn, p.t


# ---- a safecracker's dial ----

def safe_dial(rng, n_numbers):
    """A safecracker's combination dial (+ turned right, - left, from its index): first listening for the contact points
    (30 ... 45 small turns of 0.001 ... 0.006 of the reach either way, within 0.01 of the index, 0.2 ... 0.5 s each,
    listened to for 0.3 ... 1.2 s after some), then the combination dialled: every number a spin to 0.7 ... 1 of the
    reach (the sides in turn, the full reach in the first two; in 0.7 ... 1.4 s), held 0.8 ... 2 s, a nudge back of
    0.02 ... 0.05 (0.2 ... 0.4 s, held 0.5 ... 1 s) and the dial back to the index (in 0.6 ... 1.2 s, held 1 ... 2
    s). Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.5, 1.0))
    x = 0.0
    for _ in range(int(rng.integers(30, 46))):
        x = float(np.clip(x + _side(rng) * rng.uniform(0.001, 0.006), -0.01, 0.01))
        p.to(rng.uniform(0.2, 0.5), x)
        if rng.uniform() < 0.5:
            p.hold(rng.uniform(0.3, 1.2))
    p.to(0.4, 0.0)
    p.hold(rng.uniform(0.5, 1.0))
    sd = _side(rng)
    for k in range(n_numbers):
        a = (sd if k % 2 == 0 else -sd) * (1.0 if k < 2 else rng.uniform(0.7, 1.0))
        p.to(rng.uniform(0.7, 1.4), a)
        p.hold(rng.uniform(0.8, 2.0))
        p.to(rng.uniform(0.2, 0.4), a - np.sign(a) * rng.uniform(0.02, 0.05))
        p.hold(rng.uniform(0.5, 1.0))
        p.to(rng.uniform(0.6, 1.2), 0.0)
        p.hold(rng.uniform(1.0, 2.0))
    return p.kn, p.t


# ---- a boxer shadow-boxing ----

def shadow_boxing(rng, n_rounds):
    """A boxer shadow-boxing (the lead hand: + punched out, - pulled back behind the guard as the head slips), never
    still: for every round 6 ... 10 combinations, each 2 ... 5 punches (a jab to 0.7 ... 1 of the reach in 0.08 ...
    0.15 s, or one in three a hook to 0.4 ... 0.7 in 0.15 ... 0.25 s, each back to the guard at -0.1 ... -0.3 in 0.1
    ... 0.2 s), a slip or a weave (to -0.5 ... -1 in 0.2 ... 0.35 s and back to the guard in 0.2 ... 0.3 s) and a
    bounce on the feet (3 ... 6 bobs of 0.05 ... 0.15 either way about the guard, 0.15 ... 0.3 s each). The full reach
    both ways in the first combination. No holds: no two knots alike in a row. Returns the knots and the end."""
    p = _Prog()
    p.to(0.3, -0.15)
    for rd in range(n_rounds):
        for cb in range(int(rng.integers(6, 11))):
            first = rd == 0 and cb == 0
            for k in range(int(rng.integers(2, 6))):
                if first and k == 0:
                    p.to(rng.uniform(0.08, 0.15), 1.0)
                elif rng.uniform() < 1 / 3:
                    p.to(rng.uniform(0.15, 0.25), rng.uniform(0.4, 0.7))
                else:
                    p.to(rng.uniform(0.08, 0.15), rng.uniform(0.7, 1.0))
                p.to(rng.uniform(0.1, 0.2), -rng.uniform(0.1, 0.3))
            p.to(rng.uniform(0.2, 0.35), -(1.0 if first else rng.uniform(0.5, 1.0)))
            g = -rng.uniform(0.1, 0.3)
            p.to(rng.uniform(0.2, 0.3), g)
            for k in range(int(rng.integers(3, 7))):
                p.to(rng.uniform(0.15, 0.3), g + (1.0 if k % 2 == 0 else -1.0) * rng.uniform(0.05, 0.15))
    p.to(rng.uniform(0.3, 0.5), 0.0)
    return p.kn, p.t


# ---- a speed-cuber's wrist ----

def rubiks_cube(rng, n_solves):
    """A speed-cuber's right wrist turning a face (+ clockwise, - anticlockwise): for every solve an inspection (the
    wrist at 0, held 3 ... 6 s), then 25 ... 45 turns, each a quarter turn (0.45 ... 0.55 of the reach) or now and then
    (one in four) a half turn (0.9 ... 1) either way in 0.08 ... 0.15 s, the regrip (back to within 0.05 of 0 in 0.1
    ... 0.2 s) and now and then (one in five) a look at the cube (held 0.3 ... 1 s). The full reach both ways in the
    first solve. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.5, 1.0))
    for sv in range(n_solves):
        p.hold(rng.uniform(3.0, 6.0))
        for k in range(int(rng.integers(25, 46))):
            if sv == 0 and k < 2:
                a = 1.0 if k == 0 else -1.0
            else:
                a = _side(rng) * (rng.uniform(0.9, 1.0) if rng.uniform() < 0.25 else rng.uniform(0.45, 0.55))
            p.to(rng.uniform(0.08, 0.15), a)
            p.to(rng.uniform(0.1, 0.2), _side(rng) * rng.uniform(0.0, 0.05))
            if rng.uniform() < 0.2:
                p.hold(rng.uniform(0.3, 1.0))
        p.to(0.2, 0.0)
    p.hold(rng.uniform(0.5, 1.0))
    return p.kn, p.t

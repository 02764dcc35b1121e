"""Signals of the HOLDOUT54 set (``cases_holdout54.py``): everyday scenes, each drawn from a generator here.

Every scene is a programme of knots (time, position) joined by moves; the evaluator takes any times (a record's grid or
a finer one) and returns the position, exactly the first knot's before the programme starts and the last's after it.
The move is the cycloidal rise of cam design, written from its definition: the point-to-point path whose acceleration
is one full sine period, so that the speed and the acceleration are zero at both ends (the cycloidal motion of cam
profiles, as in Rothbart, Cam Design Handbook, 2004, as remembered; a choice for a hand's smooth reach):

    R(s) = s - sin(2 pi s) / (2 pi),  s in 0 ... 1,

its speed 1 - cos(2 pi s) (peak twice the mean at s = 1/2). Nothing here imports hystcomp.
"""

import numpy as np

from .set_tools import Programme as _Prog, knots_at as _knots_at


def reach(s):
    """The move 0 ... 1 over s in 0 ... 1 (0 before, 1 after): s - sin(2 pi s) / (2 pi)."""
    s = np.clip(np.asarray(s, float), 0.0, 1.0)
    return s - np.sin(2.0 * np.pi * s) / (2.0 * np.pi)


def reach_speed(s):
    """The move's speed (a unit move over a unit time) at s in [0, 1]: 1 - cos(2 pi s)."""
    s = np.asarray(s, float)
    return 1.0 - np.cos(2.0 * np.pi * s)


def knots_at(t, knots):
    """The position on times t through knots [(time, position), ...] joined by cycloidal rises; the first knot's
    position before it, the last's after."""
    return _knots_at(t, knots, reach)


def _side(rng):
    """A side drawn at even odds: +1 or -1 (one uniform draw)."""
    return 1.0 if rng.uniform() < 0.5 else -1.0


def hammer_thrower(rng, n_throws):
    """A hammer thrower's hammer head along the line of the throw (+ in front, - behind), for every throw: the thrower
    steps into the circle (held 3 ... 6 s at 0), 2 ... 3 preliminary winds (the head swung behind to -0.4 ... -0.7 and
    in front to 0.3 ... 0.6, 0.5 ... 0.8 s each way), 3 ... 4 turns (to -0.75 ... -1 and 0.75 ... 1, each turn quicker,
    0.45 ... 0.3 s each way), the release held (0.5 ... 1 s at 1) and the walk out (to 0 in 1 ... 1.5 s, held 4 ... 8
    s). The full reach both ways in the first throw. Returns the knots and the end."""
    p = _Prog()
    for k in range(n_throws):
        p.hold(rng.uniform(3.0, 6.0))
        for _ in range(int(rng.integers(2, 4))):
            p.to(rng.uniform(0.5, 0.8), -rng.uniform(0.4, 0.7))
            p.to(rng.uniform(0.5, 0.8), rng.uniform(0.3, 0.6))
        n = int(rng.integers(3, 5))
        for j in range(n):
            d = 0.45 - 0.15 * j / (n - 1)
            p.to(d, -(1.0 if k == 0 and j == n - 1 else rng.uniform(0.75, 1.0)))
            p.to(d, 1.0 if k == 0 and j == n - 1 else rng.uniform(0.75, 1.0))
        p.hold(rng.uniform(0.5, 1.0))
        p.to(rng.uniform(1.0, 1.5), 0.0)
        p.hold(rng.uniform(4.0, 8.0))
    return p.kn, p.t


def dough_kneading(rng, n_batches):
    """A baker's hands on a dough (0 at rest, 1 the hardest push; unipolar): for every batch 10 ... 18 pushes (to 0.6
    ... 1 in 0.4 ... 0.7 s, held 0.3 ... 1 s, the dough folded back with the hands eased to 0.05 ... 0.2 in 0.4 ... 0.7
    s, held 0.5 ... 1 s), the dough turned and left to rest (to 0 in 0.5 ... 1 s, held 12 ... 20 s). The hardest push
    at least once. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(1.0, 2.0))
    full = int(rng.integers(0, n_batches))
    for k in range(n_batches):
        for j in range(int(rng.integers(10, 19))):
            p.to(rng.uniform(0.4, 0.7), 1.0 if (k == full and j == 0) else rng.uniform(0.6, 1.0))
            p.hold(rng.uniform(0.3, 1.0))
            p.to(rng.uniform(0.4, 0.7), rng.uniform(0.05, 0.2))
            p.hold(rng.uniform(0.5, 1.0))
        p.to(rng.uniform(0.5, 1.0), 0.0)
        p.hold(rng.uniform(12.0, 20.0))
    return p.kn, p.t


def unicyclist(rng, n_legs):
    """A unicyclist's pedal torque balancing (+ forward, - back), never still: for every leg 12 ... 20 quick
    corrections about a drift (0.1 ... 0.45 either side of a slowly wandering middle, 0.25 ... 0.5 s each), then a hop
    over a kerb (a wind-up to 0.7 ... 1 on one side in 0.4 ... 0.7 s and the landing to 0.7 ... 1 on the other in 0.3
    ... 0.5 s). The full reach both ways in the first leg's hop. No holds: no two knots alike in a row. Returns the
    knots and the end."""
    p = _Prog()
    x = 0.0
    for leg in range(n_legs):
        mid = 0.0
        for _ in range(int(rng.integers(12, 21))):
            mid = float(np.clip(mid + _side(rng) * rng.uniform(0.0, 0.1), -0.3, 0.3))
            x_new = float(np.clip(mid + _side(rng) * rng.uniform(0.1, 0.45), -0.7, 0.7))
            if x_new == x:
                x_new += 0.01
            p.to(rng.uniform(0.25, 0.5), x_new)
            x = x_new
        sd = _side(rng)
        p.to(rng.uniform(0.4, 0.7), sd * (1.0 if leg == 0 else rng.uniform(0.7, 1.0)))
        p.to(rng.uniform(0.3, 0.5), -sd * (1.0 if leg == 0 else rng.uniform(0.7, 1.0)))
        x = p.kn[-1][1]
    p.to(rng.uniform(0.5, 0.8), 0.0)
    return p.kn, p.t


def cheese_press(rng, n_turns):
    """A cheesemaker's press screw (0 off, 1 the full pressing; unipolar): the press wound up in 2 ... 4 stages (each
    to a higher level, in 1 ... 2 s, held 8 ... 15 s while the whey runs), the full pressing held 20 ... 30 s, released
    (to 0 in 1 ... 2 s) and the cheese turned in its mould (held 10 ... 20 s); n_turns times. The full pressing every
    time. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(2.0, 4.0))
    for _ in range(n_turns):
        n = int(rng.integers(2, 5))
        levels = np.sort(rng.uniform(0.2, 0.9, size=n))
        for lv in levels:
            p.to(rng.uniform(1.0, 2.0), lv)
            p.hold(rng.uniform(8.0, 15.0))
        p.to(rng.uniform(1.0, 2.0), 1.0)
        p.hold(rng.uniform(20.0, 30.0))
        p.to(rng.uniform(1.0, 2.0), 0.0)
        p.hold(rng.uniform(10.0, 20.0))
    return p.kn, p.t


def pizza_peel(rng, n_pizzas):
    """A pizzaiolo's peel (+ into the oven, - out onto the counter): for every pizza the peel slid under it on the
    counter (to -0.7 ... -1 in 0.4 ... 0.7 s, held 0.5 ... 1 s), slid into the oven (to 0.7 ... 1 in 0.3 ... 0.5 s) and
    jerked out from under it (to 0 in 0.2 ... 0.3 s), 2 ... 4 turns of the pizza in the oven (to 0.5 ... 0.9 in 0.3
    ... 0.5 s and back to 0.1 ... 0.3, 0.3 ... 0.5 s, held 2 ... 4 s between), the pizza taken out (to 0.8 ... 1 and
    to -0.6 ... -0.9, 0.4 ... 0.6 s each) and the peel set down (to 0 in 0.4 ... 0.6 s, held 3 ... 6 s). The full reach
    both ways with the first pizza. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(1.0, 2.0))
    for k in range(n_pizzas):
        p.to(rng.uniform(0.4, 0.7), -(1.0 if k == 0 else rng.uniform(0.7, 1.0)))
        p.hold(rng.uniform(0.5, 1.0))
        p.to(rng.uniform(0.3, 0.5), 1.0 if k == 0 else rng.uniform(0.7, 1.0))
        p.to(rng.uniform(0.2, 0.3), 0.0)
        for _ in range(int(rng.integers(2, 5))):
            p.hold(rng.uniform(2.0, 4.0))
            p.to(rng.uniform(0.3, 0.5), rng.uniform(0.5, 0.9))
            p.to(rng.uniform(0.3, 0.5), rng.uniform(0.1, 0.3))
        p.to(rng.uniform(0.4, 0.6), rng.uniform(0.8, 1.0))
        p.to(rng.uniform(0.4, 0.6), -rng.uniform(0.6, 0.9))
        p.to(rng.uniform(0.4, 0.6), 0.0)
        p.hold(rng.uniform(3.0, 6.0))
    return p.kn, p.t


def bow_thruster(rng, n_manoeuvres):
    """A harbour pilot's bow-thruster joystick (+ to starboard, - to port): for every manoeuvre 3 ... 5 pushes (to 0.3
    ... 1 either way, every other one beyond 0.7, in 0.5 ... 1.5 s), each held while the bow swings (2 ... 4 s), and
    the stick back to 0 between them (in 0.4 ... 0.8 s, held 0.5 ... 1.5 s); after the manoeuvre a long wait (held 6 ...
    10 s). The full reach both ways in the first manoeuvre. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(1.0, 2.0))
    ends = [1.0, -1.0] if rng.uniform() < 0.5 else [-1.0, 1.0]
    for m in range(n_manoeuvres):
        for k in range(int(rng.integers(3, 6))):
            x = ends[k] if (m == 0 and k < 2) else _side(rng) * rng.uniform(0.7 if k % 2 == 0 else 0.3, 1.0)
            p.to(rng.uniform(0.5, 1.5), x)
            p.hold(rng.uniform(2.0, 4.0))
            p.to(rng.uniform(0.4, 0.8), 0.0)
            p.hold(rng.uniform(0.5, 1.5))
        p.hold(rng.uniform(6.0, 10.0))
    return p.kn, p.t


def tattoo_pedal(rng, n_lines):
    """A tattoo artist's foot pedal (0 up, 1 pressed fully; unipolar): for every line 3 ... 6 strokes (each pressed to
    0.6 ... 1 in 0.15 ... 0.3 s, held 0.8 ... 3 s while the needle draws, let up to 0 ... 0.1 in 0.1 ... 0.2 s, held
    0.3 ... 1 s while the skin is wiped), then a longer pause to dip the needle and look (held 3 ... 6 s). Fully
    pressed at least once. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.5, 1.0))
    full = int(rng.integers(0, n_lines))
    for k in range(n_lines):
        for j in range(int(rng.integers(3, 7))):
            p.to(rng.uniform(0.15, 0.3), 1.0 if (k == full and j == 0) else rng.uniform(0.6, 1.0))
            p.hold(rng.uniform(0.8, 3.0))
            p.to(rng.uniform(0.1, 0.2), rng.uniform(0.0, 0.1))
            p.hold(rng.uniform(0.3, 1.0))
        p.to(0.2, 0.0)
        p.hold(rng.uniform(3.0, 6.0))
    return p.kn, p.t


def marshaller(rng, n_signals):
    """An aircraft marshaller's right wand (+ raised, - lowered across the body): first the wand held still while the
    aircraft taxis in (within 0.04 of 0 for 14 ... 20 s: small sways of 0.005 ... 0.03 in 0.5 ... 1 s, held 1 ... 2.5
    s), then the signals: each a wave between two levels (3 ... 5 waves of 0.3 ... 1 either way, 0.4 ... 0.8 s each;
    the top and the bottom of the reach in the first two signals), held at the end (1 ... 3 s); the wand lowered to 0
    at the end (in 0.5 ... 1 s, held 2 ... 4 s). Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.5, 1.0))
    x, t_still = 0.0, rng.uniform(14.0, 20.0)
    while p.t < t_still:
        x = float(np.clip(x + _side(rng) * rng.uniform(0.005, 0.03), -0.04, 0.04))
        p.to(rng.uniform(0.5, 1.0), x)
        p.hold(rng.uniform(1.0, 2.5))
    p.to(rng.uniform(0.5, 1.0), 0.0)
    p.hold(rng.uniform(1.0, 2.0))
    ends = [1.0, -1.0] if rng.uniform() < 0.5 else [-1.0, 1.0]
    for k in range(n_signals):
        sd = _side(rng)
        for j in range(int(rng.integers(3, 6))):
            x = ends[k] if (k < 2 and j == 0) else sd * rng.uniform(0.3, 1.0)
            p.to(rng.uniform(0.4, 0.8), x)
            sd = -sd
        p.hold(rng.uniform(1.0, 3.0))
    p.to(rng.uniform(0.5, 1.0), 0.0)
    p.hold(rng.uniform(2.0, 4.0))
    return p.kn, p.t


def chimney_sweep(rng, n_flues):
    """A chimney sweep's rods (+ pushed up the flue, - drawn back): for every flue 6 ... 10 scrubbing strokes (to 0.6
    ... 1 and back to -0.2 ... -0.5, 0.35 ... 0.6 s each way), the rods pulled down to add a length (to -0.7 ... -1 in
    0.5 ... 0.8 s, held 2 ... 4 s) and the soot let settle (to 0 in 0.5 ... 1 s, held 5 ... 9 s). The full reach both
    ways in the first flue. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(1.0, 2.0))
    for k in range(n_flues):
        for j in range(int(rng.integers(6, 11))):
            p.to(rng.uniform(0.35, 0.6), 1.0 if (k == 0 and j == 0) else rng.uniform(0.6, 1.0))
            p.to(rng.uniform(0.35, 0.6), -rng.uniform(0.2, 0.5))
        p.to(rng.uniform(0.5, 0.8), -(1.0 if k == 0 else rng.uniform(0.7, 1.0)))
        p.hold(rng.uniform(2.0, 4.0))
        p.to(rng.uniform(0.5, 1.0), 0.0)
        p.hold(rng.uniform(5.0, 9.0))
    return p.kn, p.t


def bell_ringer(rng, n_touches):
    """A church bell-ringer's sally and tail end (+ the handstroke, - the backstroke): for every touch the bell raised
    from rest (the rope swung 3 ... 5 times, each higher: 0.2 ... 1 of the reach, 1 ... 1.6 s each way), rung full
    circle 6 ... 10 strokes (to 0.85 ... 1 either way in turn, 1 ... 1.3 s each), stood at the balance (to 0 in 0.8 ...
    1.2 s, held 4 ... 8 s). The full reach both ways in the first touch. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(1.0, 2.0))
    for k in range(n_touches):
        n = int(rng.integers(3, 6))
        for j in range(n):
            a = 0.2 + 0.8 * (j + 1) / n * rng.uniform(0.9, 1.0)
            p.to(rng.uniform(1.0, 1.6), min(a, 1.0))
            p.to(rng.uniform(1.0, 1.6), -min(a, 1.0))
        sd = 1.0
        for j in range(int(rng.integers(6, 11))):
            p.to(rng.uniform(1.0, 1.3), sd * (1.0 if (k == 0 and j < 2) else rng.uniform(0.85, 1.0)))
            sd = -sd
        p.to(rng.uniform(0.8, 1.2), 0.0)
        p.hold(rng.uniform(4.0, 8.0))
    return p.kn, p.t

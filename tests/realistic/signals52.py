"""Signals of the HOLDOUT52 set (``cases_holdout52.py``): everyday scenes, each drawn from a generator here.

Every scene is a programme of knots (time, position) joined by moves; the evaluator takes any times (a record's grid or
a finer one) and returns the position, exactly the first knot's before the programme starts and the last's after it.
The move is a beta reach, written from its definition: a hand's point-to-point move whose speed is a beta density in
the move's time, skewed so that it slows down longer than it speeds up (the asymmetric, bell-shaped speed profiles of
aimed arm movements, the deceleration the longer the more precise the aim; Nagasaki, Exp. Brain Res. 74 (1989) 319,
as remembered; the beta form is a choice):

    R(s) = I_s(A, B) = int_0^s u^(A-1) (1 - u)^(B-1) du / B(A, B),  s in 0 ... 1,

I the regularised incomplete beta function, A = 2.4 and B = 3.4 (a choice: the speed peaks at s = (A - 1) / (A + B - 2)
= 0.368 of the move, at about 1.9 times the mean speed; it leaves 0 as s^1.4 and lands as (1 - s)^2.4, so the move
starts and ends at rest with a continuous speed). Nothing here imports hystcomp.
"""

import math

import numpy as np
from scipy.special import betainc

from .set_tools import Programme as _Prog, knots_at as _knots_at

#: the beta reach's exponents
A_REACH, B_REACH = 2.4, 3.4


def reach(s):
    """The move 0 ... 1 over s in 0 ... 1 (0 before, 1 after): the regularised incomplete beta I_s(A, B)."""
    s = np.clip(np.asarray(s, float), 0.0, 1.0)
    return betainc(A_REACH, B_REACH, s)


def reach_speed(s):
    """The move's speed (a unit move over a unit time) at s in [0, 1]: the beta density s^(A-1) (1 - s)^(B-1) / B(A,
    B)."""
    s = np.asarray(s, float)
    lb = math.lgamma(A_REACH) + math.lgamma(B_REACH) - math.lgamma(A_REACH + B_REACH)
    return s ** (A_REACH - 1) * (1 - s) ** (B_REACH - 1) / math.exp(lb)


def knots_at(t, knots):
    """The position on times t through knots [(time, position), ...] joined by beta reaches; the first knot's position
    before it, the last's after."""
    return _knots_at(t, knots, reach)


def _side(rng):
    """A side drawn at even odds: +1 or -1 (one uniform draw)."""
    return 1.0 if rng.uniform() < 0.5 else -1.0


# ---- a croquet player's mallet (the clean case) ----

def croquet_mallet(rng, n_strokes):
    """A croquet player's mallet head along the line of play (+ swung through the ball, - drawn back): for every
    stroke the walk to the ball (held 3 ... 6 s at 0), the stance and the sighting (the head grounded behind the ball:
    within 0.03 of 0 in 0.5 ... 1 s, held 1 ... 2 s), 2 ... 4 practice swings (back to -0.2 ... -0.45, through to 0.1
    ... 0.3, 0.4 ... 0.7 s each way), the backswing (to -0.6 ... -1 in 0.5 ... 0.8 s), the pause at its top (held 0.1
    ... 0.3 s), the stroke (to 0.6 ... 1 in 0.2 ... 0.35 s), the follow-through held (0.5 ... 1 s) and the mallet
    lowered to 0 (in 0.6 ... 1 s). The full reach both ways in the first stroke. Returns the knots and the end."""
    p = _Prog()
    for k in range(n_strokes):
        p.hold(rng.uniform(3.0, 6.0))
        p.to(rng.uniform(0.5, 1.0), _side(rng) * rng.uniform(0.0, 0.03))
        p.hold(rng.uniform(1.0, 2.0))
        for _ in range(int(rng.integers(2, 5))):
            p.to(rng.uniform(0.4, 0.7), -rng.uniform(0.2, 0.45))
            p.to(rng.uniform(0.4, 0.7), rng.uniform(0.1, 0.3))
        p.to(rng.uniform(0.5, 0.8), -(1.0 if k == 0 else rng.uniform(0.6, 1.0)))
        p.hold(rng.uniform(0.1, 0.3))
        p.to(rng.uniform(0.2, 0.35), 1.0 if k == 0 else rng.uniform(0.6, 1.0))
        p.hold(rng.uniform(0.5, 1.0))
        p.to(rng.uniform(0.6, 1.0), 0.0)
    p.hold(rng.uniform(2.0, 4.0))
    return p.kn, p.t


# ---- a pastry chef's piping bag (unipolar) ----

def piping_bag(rng, n_trays):
    """A pastry chef's squeeze on a piping bag (0 the bag at rest, 1 the hardest squeeze): for every tray 6 ... 10
    rosettes (each a squeeze to 0.6 ... 1 in 0.3 ... 0.6 s, held while the swirl is piped, 1.5 ... 3 s, the squeeze
    let go to 0 ... 0.08 in 0.2 ... 0.4 s and the nozzle moved to the next spot, held 0.8 ... 1.5 s), then a border
    piped in one long squeeze (to 0.75 ... 1 in 0.4 ... 0.7 s, held 6 ... 12 s), the squeeze let go (to 0 in 0.3 ...
    0.5 s) and the bag refilled (held 10 ... 18 s). The hardest squeeze at least once. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(1.0, 2.0))
    full = int(rng.integers(0, n_trays))
    for k in range(n_trays):
        for j in range(int(rng.integers(6, 11))):
            p.to(rng.uniform(0.3, 0.6), 1.0 if (k == full and j == 0) else rng.uniform(0.6, 1.0))
            p.hold(rng.uniform(1.5, 3.0))
            p.to(rng.uniform(0.2, 0.4), rng.uniform(0.0, 0.08))
            p.hold(rng.uniform(0.8, 1.5))
        p.to(rng.uniform(0.4, 0.7), rng.uniform(0.75, 1.0))
        p.hold(rng.uniform(6.0, 12.0))
        p.to(rng.uniform(0.3, 0.5), 0.0)
        p.hold(rng.uniform(10.0, 18.0))
    return p.kn, p.t


# ---- a hang-glider pilot's weight shift ----

def hang_glider(rng, n_legs):
    """A hang-glider pilot's control bar across the glider (+ the body shifted right, - left), never still: for every
    leg of the flight a stretch of thermalling (2 ... 4 circles, each the bar held into the turn at 0.35 ... 0.6 on one
    side, corrected by 0.05 ... 0.15 either way every 0.5 ... 0.9 s, 3 ... 5 corrections a circle), a roll reversal to
    the other side (to 0.7 ... 1 in 0.6 ... 1 s and back to 0.1 ... 0.3 in 0.5 ... 0.9 s), and a glide through rough
    air (8 ... 16 quick corrections of 0.1 ... 0.35 either side of the middle, 0.2 ... 0.45 s each). The full reach both
    ways in the first leg's reversals. No holds: no two knots alike in a row. Returns the knots and the end."""
    p = _Prog()
    p.to(0.4, 0.05)
    for leg in range(n_legs):
        sd = _side(rng)
        for c in range(int(rng.integers(2, 5))):
            base = sd * rng.uniform(0.35, 0.6)
            for _ in range(int(rng.integers(3, 6))):
                p.to(rng.uniform(0.5, 0.9), base + _side(rng) * rng.uniform(0.05, 0.15))
        for k in range(2):
            a = 1.0 if leg == 0 else rng.uniform(0.7, 1.0)
            p.to(rng.uniform(0.6, 1.0), -sd * a)
            p.to(rng.uniform(0.5, 0.9), -sd * rng.uniform(0.1, 0.3))
            sd = -sd
        x = p.kn[-1][1]
        for _ in range(int(rng.integers(8, 17))):
            x_new = _side(rng) * rng.uniform(0.1, 0.35)
            if x_new == x:
                x_new += 0.01
            p.to(rng.uniform(0.2, 0.45), x_new)
            x = x_new
    p.to(rng.uniform(0.5, 0.8), 0.0)
    return p.kn, p.t


# ---- a gardener's watering can (unipolar) ----

def watering_can(rng, n_fills):
    """A gardener's watering can, its tilt (0 upright, 1 the full pour): for every fill 4 ... 7 plants, each the can
    tilted (to 0.5 ... 1 in 0.5 ... 1 s), the pour held 2 ... 5 s with 0 ... 2 small changes of 0.03 ... 0.1 either way
    (in 0.3 ... 0.6 s, within 0.4 ... 1), the can set upright (to 0 in 0.3 ... 0.6 s) and carried to the next plant
    (held 2 ... 4 s); after the fill's last plant the walk to the tap and the refill (held 15 ... 25 s). The full pour
    at least once. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(2.0, 4.0))
    full = int(rng.integers(0, n_fills))
    for k in range(n_fills):
        for j in range(int(rng.integers(4, 8))):
            x = 1.0 if (k == full and j == 0) else rng.uniform(0.5, 1.0)
            p.to(rng.uniform(0.5, 1.0), x)
            pour = rng.uniform(2.0, 5.0)
            n_ch = int(rng.integers(0, 3))
            for _ in range(n_ch):
                p.hold(pour / (n_ch + 1))
                x = float(np.clip(x + _side(rng) * rng.uniform(0.03, 0.1), 0.4, 1.0))
                p.to(rng.uniform(0.3, 0.6), x)
            p.hold(pour / (n_ch + 1))
            p.to(rng.uniform(0.3, 0.6), 0.0)
            p.hold(rng.uniform(2.0, 4.0))
        p.hold(rng.uniform(15.0, 25.0))
    return p.kn, p.t


# ---- a ten-pin bowler's arm ----

def tenpin_bowler(rng, n_frames):
    """A ten-pin bowler's bowling arm (+ swung forward, - back): for every frame two balls, each the ball picked up
    from the return (held 1 ... 3 s at 0), the set-up on the approach (held 1 ... 2 s), the pushaway (to 0.2 ... 0.35 in
    0.3 ... 0.5 s), the downswing into the backswing (to -0.7 ... -1 in 0.5 ... 0.7 s), the forward swing and release
    (to 0.7 ... 1 in 0.4 ... 0.6 s), the follow-through held (0.5 ... 1.2 s), the arm lowered (to 0 in 0.5 ... 1 s) and
    the ball watched down the lane (held 2.5 ... 4 s); after each ball the pinsetter's cycle (held 4 ... 8 s). The full
    reach both ways in the first ball. Returns the knots and the end."""
    p = _Prog()
    for f in range(n_frames):
        for b in range(2):
            first = f == 0 and b == 0
            p.hold(rng.uniform(1.0, 3.0))
            p.hold(rng.uniform(1.0, 2.0))
            p.to(rng.uniform(0.3, 0.5), rng.uniform(0.2, 0.35))
            p.to(rng.uniform(0.5, 0.7), -(1.0 if first else rng.uniform(0.7, 1.0)))
            p.to(rng.uniform(0.4, 0.6), 1.0 if first else rng.uniform(0.7, 1.0))
            p.hold(rng.uniform(0.5, 1.2))
            p.to(rng.uniform(0.5, 1.0), 0.0)
            p.hold(rng.uniform(2.5, 4.0))
            p.hold(rng.uniform(4.0, 8.0))
    return p.kn, p.t


# ---- a focus puller's follow-focus wheel ----

def focus_puller(rng, n_takes):
    """A camera assistant's follow-focus wheel (+ toward the near mark, - toward infinity, 0 the middle mark): for every
    take 5 ... 9 racks to the next mark (0.3 ... 1 of the reach either way, at least 0.3 from the last and every other
    one beyond 0.75, in 0.6 ... 2 s), each mark held for the shot (1 ... 4 s), one in three with a touch-up for the
    actor's drift (0.02 ... 0.06 either way in 0.3 ... 0.6 s, held the rest of the shot); after the take the wheel back
    to its middle mark (in 1 ... 2 s, held 4 ... 8 s while the camera resets). The full reach both ways in the first
    take. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(1.0, 2.0))
    ends = [1.0, -1.0] if rng.uniform() < 0.5 else [-1.0, 1.0]
    x = 0.0
    for tk in range(n_takes):
        n = int(rng.integers(5, 10))
        for k in range(n):
            if tk == 0 and k < 2:
                x_new = ends[k]
            else:
                x_new = x
                lo = 0.75 if k % 2 == 0 else 0.3
                while abs(x_new - x) < 0.3:
                    x_new = _side(rng) * rng.uniform(lo, 1.0)
            x = x_new
            p.to(rng.uniform(0.6, 2.0), x)
            shot = rng.uniform(1.0, 4.0)
            if rng.uniform() < 1 / 3:
                first = rng.uniform(0.3, 0.6) * shot
                p.hold(first)
                x = float(np.clip(x + _side(rng) * rng.uniform(0.02, 0.06), -1.0, 1.0))
                d = rng.uniform(0.3, 0.6)
                p.to(d, x)
                p.hold(max(shot - first - d, 0.3))
            else:
                p.hold(shot)
        x = 0.0
        p.to(rng.uniform(1.0, 2.0), 0.0)
        p.hold(rng.uniform(4.0, 8.0))
    return p.kn, p.t


# ---- a pianist's sustain pedal (unipolar) ----

def sustain_pedal(rng, n_phrases):
    """A pianist's sustain pedal (0 up, 1 pressed to the floor) in legato pedalling: for every phrase at a tempo of 60
    ... 100 beats a minute, 8 ... 14 chords, each one or two beats long; at every chord change the pedal let up (to 0
    ... 0.1 in 0.08 ... 0.15 s) just after the chord is struck and pressed again (to 0.8 ... 1 in 0.1 ... 0.2 s; one
    chord in five half-pedalled, to 0.4 ... 0.6), held for the rest of the chord; after the phrase the pedal up (to 0 in
    0.2 ... 0.4 s) and the breath (held 1.5 ... 3 s). The pedal to the floor at least once. Returns the knots and the
    end."""
    p = _Prog()
    p.hold(rng.uniform(0.5, 1.0))
    floor = False
    for ph in range(n_phrases):
        beat = 60.0 / rng.uniform(60.0, 100.0)
        for k in range(int(rng.integers(8, 15))):
            length = beat * (1.0 if rng.uniform() < 0.6 else 2.0)
            t_up, t_dn = rng.uniform(0.08, 0.15), rng.uniform(0.1, 0.2)
            half = rng.uniform() < 0.2 and floor
            depth = rng.uniform(0.4, 0.6) if half else (1.0 if not floor else rng.uniform(0.8, 1.0))
            floor = floor or not half
            if k > 0:
                p.to(t_up, rng.uniform(0.0, 0.1))
            p.to(t_dn, depth)
            p.hold(max(length - t_up - t_dn, 0.05))
        p.to(rng.uniform(0.2, 0.4), 0.0)
        p.hold(rng.uniform(1.5, 3.0))
    return p.kn, p.t


# ---- a timpanist's tuning pedal ----

def timpani_pedal(rng, n_notes):
    """A timpanist's pedal (+ the toe down, the pitch up; - the heel down; the reach a fourth either way of the middle
    note, five semitones, 0.2 of the reach each): first the drum tuned by ear to the piece's first note (for 14 ... 20
    s: the pedal eased 0.005 ... 0.03 of the reach either way, within 0.05 of the middle, in 0.4 ... 1 s, and held 1
    ... 2.5 s while the drum is tapped and heard), the pedal at the middle note (held 2 ... 4 s), then the piece: every
    note a pitch a whole number of semitones from the middle (1 ... 10 semitones from the last, within the reach; the
    top and the bottom of the reach in the first four notes), reached by a quick re-tuning (0.2 ... 0.5 s) or, one in
    three, a glissando (1 ... 2.5 s), and held for the note or its roll (0.8 ... 3 s); the pedal back to the middle
    note at the end (in 0.5 ... 1 s, held 2 ... 4 s). Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.5, 1.0))
    x, t_tune = 0.0, rng.uniform(14.0, 20.0)
    while p.t < t_tune:
        x = float(np.clip(x + _side(rng) * rng.uniform(0.005, 0.03), -0.05, 0.05))
        p.to(rng.uniform(0.4, 1.0), x)
        p.hold(rng.uniform(1.0, 2.5))
    p.to(rng.uniform(0.5, 1.0), 0.0)
    p.hold(rng.uniform(2.0, 4.0))
    semi = 0
    ends = [5, -5] if rng.uniform() < 0.5 else [-5, 5]
    at = sorted(rng.choice(4, size=2, replace=False))
    for k in range(n_notes):
        if k in at:
            new = ends[at.index(k)]
        else:
            new = semi
            while new == semi or abs(new - semi) > 10:
                new = int(rng.integers(-5, 6))
        semi = new
        p.to(rng.uniform(1.0, 2.5) if rng.uniform() < 1 / 3 else rng.uniform(0.2, 0.5), semi / 5.0)
        p.hold(rng.uniform(0.8, 3.0))
    p.to(rng.uniform(0.5, 1.0), 0.0)
    p.hold(rng.uniform(2.0, 4.0))
    return p.kn, p.t


# ---- a bricklayer's trowel ----

def bricklayer_trowel(rng, n_bricks):
    """A bricklayer's trowel (+ out over the wall, - back to the mortar board): for every brick the mortar scooped (to
    -0.7 ... -1 in 0.4 ... 0.7 s, held 0.3 ... 0.6 s), a bed thrown along the course (to 0.6 ... 1 in 0.3 ... 0.5 s)
    and furrowed (2 ... 4 strokes of 0.1 ... 0.2 either way about 0.5, 0.2 ... 0.3 s each), the brick's end buttered
    (to 0.1 ... 0.3 in 0.3 ... 0.5 s, held 0.5 ... 1 s), the brick laid (the trowel at 0, held 1 ... 2 s), tapped down
    with the handle (3 ... 5 taps, 0.05 ... 0.15 either side of 0, 0.1 ... 0.2 s each) and the squeezed mortar cut off
    (to 0.3 ... 0.5 in 0.25 ... 0.4 s, back to 0 in 0.25 ... 0.4 s, held 1 ... 2 s); every 6 ... 10 bricks the course
    checked with the level (held 4 ... 8 s). The full reach both ways with the first brick. Returns the knots and the
    end."""
    p = _Prog()
    p.hold(rng.uniform(1.0, 2.0))
    check = int(rng.integers(6, 11))
    for b in range(n_bricks):
        p.to(rng.uniform(0.4, 0.7), -(1.0 if b == 0 else rng.uniform(0.7, 1.0)))
        p.hold(rng.uniform(0.3, 0.6))
        p.to(rng.uniform(0.3, 0.5), 1.0 if b == 0 else rng.uniform(0.6, 1.0))
        for _ in range(int(rng.integers(2, 5))):
            p.to(rng.uniform(0.2, 0.3), 0.5 + _side(rng) * rng.uniform(0.1, 0.2))
        p.to(rng.uniform(0.3, 0.5), rng.uniform(0.1, 0.3))
        p.hold(rng.uniform(0.5, 1.0))
        p.to(rng.uniform(0.3, 0.5), 0.0)
        p.hold(rng.uniform(1.0, 2.0))
        for j in range(int(rng.integers(3, 6))):
            p.to(rng.uniform(0.1, 0.2), (1.0 if j % 2 == 0 else -1.0) * rng.uniform(0.05, 0.15))
        p.to(rng.uniform(0.1, 0.2), 0.0)
        p.to(rng.uniform(0.25, 0.4), rng.uniform(0.3, 0.5))
        p.to(rng.uniform(0.25, 0.4), 0.0)
        p.hold(rng.uniform(1.0, 2.0))
        check -= 1
        if check == 0:
            p.hold(rng.uniform(4.0, 8.0))
            check = int(rng.integers(6, 11))
    return p.kn, p.t


# ---- a cook's pepper mill ----

def pepper_mill(rng, n_dishes):
    """A cook's pepper mill, its top's twist (+ clockwise, - back): for every dish seasoned 6 ... 12 grinding twists
    (to 0.7 ... 1 each way in turn, 0.25 ... 0.45 s each: the full twist both ways in the first dish), then the mill set
    down (to 0 in 0.3 ... 0.5 s, held 3 ... 8 s while the dish is stirred). Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.5, 1.0))
    for d in range(n_dishes):
        sd = _side(rng)
        for k in range(int(rng.integers(6, 13))):
            a = 1.0 if (d == 0 and k < 2) else rng.uniform(0.7, 1.0)
            p.to(rng.uniform(0.25, 0.45), sd * a)
            sd = -sd
        p.to(rng.uniform(0.3, 0.5), 0.0)
        p.hold(rng.uniform(3.0, 8.0))
    return p.kn, p.t

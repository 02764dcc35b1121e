"""Signals of the HOLDOUT55 set (``cases_holdout55.py``): everyday scenes, each drawn from a generator here.

Every scene is a programme of knots (time, position) joined by moves; the evaluator takes any times (a record's grid or
a finer one) and returns the position, exactly the first knot's before the programme starts and the last's after it.
The move is the minimum-jerk reach, written from its definition: the point-to-point move that minimises the integrated
squared jerk between rest and rest (Flash & Hogan, J. Neurosci. 5 (1985) 1688, as remembered):

    R(s) = 10 s^3 - 15 s^4 + 6 s^5,  s in 0 ... 1,

its speed 30 s^2 (1 - s)^2 (symmetric, peaking at mid-move at 1.875 times the mean speed; it starts and ends at rest
with a continuous speed and acceleration). Nothing here imports hystcomp.
"""

import numpy as np

from .set_tools import Programme as _Prog, knots_at as _knots_at
from .set_tools import minimum_jerk as _minimum_jerk, minimum_jerk_speed as _minimum_jerk_speed


#: the move 0 ... 1 over s in 0 ... 1 (0 before, 1 after), and its speed: the minimum-jerk polynomial
reach, reach_speed = _minimum_jerk, _minimum_jerk_speed


def knots_at(t, knots):
    """The position on times t through knots [(time, position), ...] joined by minimum-jerk reaches; the first knot's
    position before it, the last's after."""
    return _knots_at(t, knots, reach)


def _side(rng):
    """A side drawn at even odds: +1 or -1 (one uniform draw)."""
    return 1.0 if rng.uniform() < 0.5 else -1.0


# ---- a fly fisher's cast (the clean case) ----

def fly_cast(rng, n_casts):
    """A fly fisher's rod tip along the cast (+ forward, - back): for every cast the line lifted from the water (to 0.1
    ... 0.25 in 0.5 ... 0.9 s), 2 ... 4 false casts (the back cast to -0.65 ... -1 in 0.25 ... 0.45 s, the pause as the
    line unrolls behind, 0.15 ... 0.4 s, the forward cast to 0.65 ... 1 in 0.25 ... 0.45 s, its pause), the
    presentation (to 0.3 ... 0.5, the rod lowered to 0 in 0.8 ... 1.5 s) and the fly left to drift (held 2 ... 4 s).
    The full reach both ways in the first cast. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(1.0, 2.0))
    for k in range(n_casts):
        p.to(rng.uniform(0.5, 0.9), rng.uniform(0.1, 0.25))
        nf = int(rng.integers(2, 5))
        for j in range(nf):
            p.to(rng.uniform(0.25, 0.45), -(1.0 if (k == 0 and j == 0) else rng.uniform(0.65, 1.0)))
            p.hold(rng.uniform(0.15, 0.4))
            p.to(rng.uniform(0.25, 0.45), 1.0 if (k == 0 and j == nf - 1) else rng.uniform(0.65, 1.0))
            p.hold(rng.uniform(0.15, 0.4))
        p.to(rng.uniform(0.3, 0.5), rng.uniform(0.3, 0.5))
        p.to(rng.uniform(0.8, 1.5), 0.0)
        p.hold(rng.uniform(2.0, 4.0))
    return p.kn, p.t


# ---- a barista's tamper (unipolar) ----

def barista_tamp(rng, n_shots):
    """A barista's press on the tamper (0 none, 1 the hardest): for every shot the grind dosed (held 0 for 4 ... 8 s),
    a light settling press (to 0.2 ... 0.35 in 0.3 ... 0.5 s, let go to 0 in 0.2 ... 0.3 s), the tamp (to 0.7 ... 1 in
    0.4 ... 0.7 s, held level 4 ... 8 s), the polish (eased to 0.45 ... 0.6 in 0.3 s, held 2 ... 4 s), the tamper
    lifted (to 0 in 0.3 ... 0.5 s) and the shot pulled (held 0 for 20 ... 30 s). The hardest tamp at least once.
    Returns the knots and the end."""
    p = _Prog()
    hard = int(rng.integers(0, n_shots))
    for k in range(n_shots):
        p.hold(rng.uniform(4.0, 8.0))
        p.to(rng.uniform(0.3, 0.5), rng.uniform(0.2, 0.35))
        p.to(rng.uniform(0.2, 0.3), 0.0)
        p.to(rng.uniform(0.4, 0.7), 1.0 if k == hard else rng.uniform(0.7, 1.0))
        p.hold(rng.uniform(4.0, 8.0))
        p.to(0.3, rng.uniform(0.45, 0.6))
        p.hold(rng.uniform(2.0, 4.0))
        p.to(rng.uniform(0.3, 0.5), 0.0)
        p.hold(rng.uniform(20.0, 30.0))
    return p.kn, p.t


# ---- a conductor's baton ----

def conductor(rng, n_bars):
    """An orchestra conductor's baton across the body (+ out to the right, - in to the left), never still: bars of four
    beats (the downbeat to the middle, 0.05 either way, then to the left, -0.5 ... -0.85, the right, 0.5 ... 0.85, and
    the upbeat to 0.1 ... 0.25; each beat 0.35 ... 0.6 s as the tempo drifts), every fourth bar a climax (its second and
    third beats to 0.9 ... 1 each side). The full reach both ways in the first climax. No holds. Returns the knots and
    the end."""
    p = _Prog()
    p.to(0.5, 0.15)
    beat = rng.uniform(0.4, 0.55)
    for b in range(n_bars):
        beat = float(np.clip(beat + rng.uniform(-0.03, 0.03), 0.35, 0.6))
        big = b % 4 == 3
        p.to(beat, _side(rng) * rng.uniform(0.0, 0.05))
        p.to(beat, -(1.0 if b == 3 else rng.uniform(0.9, 1.0)) if big else -rng.uniform(0.5, 0.85))
        p.to(beat, (1.0 if b == 3 else rng.uniform(0.9, 1.0)) if big else rng.uniform(0.5, 0.85))
        p.to(beat, rng.uniform(0.1, 0.25))
    p.to(0.6, 0.0)
    return p.kn, p.t


# ---- a bell ringer's rope (unipolar) ----

def bell_ringer(rng, n_touches):
    """A bell ringer's pull on the rope (0 slack, 1 the hardest): for every touch 8 ... 14 strokes alternating
    handstroke (a pull to 0.75 ... 1 in 0.4 ... 0.6 s) and backstroke (to 0.5 ... 0.75), the rope let rise between
    (to 0 ... 0.05 in 0.8 ... 1.2 s: the bell swinging through), then the bell stood (held 0 for 15 ... 30 s). The
    hardest pull at least once. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(3.0, 6.0))
    for k in range(n_touches):
        for j in range(int(rng.integers(8, 15))):
            top = (1.0 if (k == 0 and j == 0) else rng.uniform(0.75, 1.0)) if j % 2 == 0 else rng.uniform(0.5, 0.75)
            p.to(rng.uniform(0.4, 0.6), top)
            p.to(rng.uniform(0.8, 1.2), rng.uniform(0.0, 0.05))
        p.to(0.3, 0.0)
        p.hold(rng.uniform(15.0, 30.0))
    return p.kn, p.t


# ---- a rower's stroke ----

def rowing(rng, n_pieces):
    """A rower's oar handle along the boat (+ the finish, - the catch): for every piece 4 ... 8 strokes (the drive
    from the catch, -0.7 ... -1, to the finish, 0.7 ... 1, in 0.7 ... 0.9 s, and the recovery back in 1.1 ... 1.6 s,
    the rate rising through the piece), then the oar held easy at the middle (0.02 either way, 2 ... 4 s). The full
    reach both ways in the first piece. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(1.0, 2.0))
    for k in range(n_pieces):
        n = int(rng.integers(4, 9))
        p.to(rng.uniform(0.8, 1.2), -rng.uniform(0.7, 1.0))
        for j in range(n):
            f = 1.0 - 0.2 * j / n
            p.to(f * rng.uniform(0.7, 0.9), 1.0 if (k == 0 and j == 1) else rng.uniform(0.7, 1.0))
            p.to(f * rng.uniform(1.1, 1.6), -(1.0 if (k == 0 and j == 2) else rng.uniform(0.7, 1.0)))
        p.to(rng.uniform(0.8, 1.2), _side(rng) * rng.uniform(0.0, 0.02))
        p.hold(rng.uniform(2.0, 4.0))
    p.to(0.5, 0.0)
    p.hold(1.0)
    return p.kn, p.t


# ---- a windscreen wiper ----

def wiper(rng, n_bursts):
    """A windscreen wiper's arm (+ the passenger's side, - the driver's): for every burst of rain 3 ... 6 sweeps (to
    0.85 ... 1 one side and the other, 0.45 ... 0.65 s each, the arm turning a moment at each end, 0.05 ... 0.1 s),
    then the interval mode's pause at the middle (parked at 0, 1 ... 3 s). The full reach both ways in the first burst.
    Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.5, 1.0))
    for k in range(n_bursts):
        sd = _side(rng)
        for j in range(int(rng.integers(3, 7))):
            for side in (sd, -sd):
                p.to(rng.uniform(0.45, 0.65), side * (1.0 if k == 0 else rng.uniform(0.85, 1.0)))
                p.hold(rng.uniform(0.05, 0.1))
        p.to(rng.uniform(0.3, 0.4), 0.0)
        p.hold(rng.uniform(1.0, 3.0))
    return p.kn, p.t


# ---- a blacksmith's bellows (unipolar) ----

def bellows(rng, n_heats):
    """A blacksmith's bellows lever (0 up, 1 pressed right down): for every heat 5 ... 10 pumps (pressed to 0.6 ... 1
    in 0.5 ... 0.8 s, let rise to 0 ... 0.1 in 0.6 ... 1 s), then the iron worked at the anvil (the lever left up, held
    0 for 6 ... 12 s). The hardest pump at least once. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(1.0, 2.0))
    for k in range(n_heats):
        for j in range(int(rng.integers(5, 11))):
            p.to(rng.uniform(0.5, 0.8), 1.0 if (k == 0 and j == 1) else rng.uniform(0.6, 1.0))
            p.to(rng.uniform(0.6, 1.0), rng.uniform(0.0, 0.1))
        p.to(0.3, 0.0)
        p.hold(rng.uniform(6.0, 12.0))
    return p.kn, p.t


# ---- an archer's draw ----

def archer(rng, n_arrows, t_calm):
    """An archer's bow hand along the shot (+ the bow pushed out, - the string drawn back to the anchor): first the
    stance and the nocking (small adjustments within 0.04 either way, every 0.6 ... 1.2 s, for t_calm s), then for every
    arrow the bow raised (to 0.3 ... 0.5 in 0.8 ... 1.2 s), the draw (to -0.8 ... -1 in 1 ... 1.6 s), the anchor held
    (1.5 ... 3 s), the release (to 0.75 ... 1 in 0.15 ... 0.25 s), the follow-through held (0.6 ... 1 s) and the bow
    lowered (to 0 in 0.8 ... 1.2 s, held 2 ... 4 s while the next arrow is nocked). The full reach both ways in the
    first arrow. Returns the knots and the end."""
    p = _Prog()
    while p.t < t_calm:
        p.to(rng.uniform(0.6, 1.2), _side(rng) * rng.uniform(0.005, 0.04))
    p.to(0.5, 0.0)
    for k in range(n_arrows):
        p.to(rng.uniform(0.8, 1.2), rng.uniform(0.3, 0.5))
        p.to(rng.uniform(1.0, 1.6), -(1.0 if k == 0 else rng.uniform(0.8, 1.0)))
        p.hold(rng.uniform(1.5, 3.0))
        p.to(rng.uniform(0.15, 0.25), 1.0 if k == 0 else rng.uniform(0.75, 1.0))
        p.hold(rng.uniform(0.6, 1.0))
        p.to(rng.uniform(0.8, 1.2), 0.0)
        p.hold(rng.uniform(2.0, 4.0))
    return p.kn, p.t


# ---- a kayaker's paddle ----

def kayak(rng, n_sets):
    """A kayaker's paddle shaft across the boat (+ the right blade in the water, - the left): for every set a sprint of
    8 ... 14 strokes side to side (to 0.7 ... 1, 0.45 ... 0.7 s each), a draw stroke held on one side (to 0.6 ... 0.9,
    held 4 ... 7 s while the boat turns), and the paddle rested across the deck (at 0, 8 ... 14 s). The full reach
    both ways in the first sprint. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(2.0, 4.0))
    for k in range(n_sets):
        sd = _side(rng)
        n = int(rng.integers(8, 15))
        for j in range(n):
            full = k == 0 and j in (2, 3)
            p.to(rng.uniform(0.45, 0.7), (sd if j % 2 == 0 else -sd) * (1.0 if full else rng.uniform(0.7, 1.0)))
        p.to(rng.uniform(0.5, 0.8), _side(rng) * rng.uniform(0.6, 0.9))
        p.hold(rng.uniform(4.0, 7.0))
        p.to(rng.uniform(0.6, 0.9), 0.0)
        p.hold(rng.uniform(8.0, 14.0))
    return p.kn, p.t


# ---- a violinist's bow ----

def violin_bow(rng, n_phrases):
    """A violinist's bow along the strings (+ a down-bow's end, - an up-bow's): for every phrase 6 ... 12 notes, each a
    stroke to the other side (to 0.5 ... 1, 0.3 ... 1.4 s: quick detache and long sustained notes), a rest between the
    phrases (the bow lifted back to the middle, held 1 ... 2 s). The full reach both ways in the first phrase. Returns
    the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.5, 1.0))
    for k in range(n_phrases):
        sd = _side(rng)
        for j in range(int(rng.integers(6, 13))):
            full = k == 0 and j in (1, 2)
            p.to(rng.uniform(0.3, 1.4), (sd if j % 2 == 0 else -sd) * (1.0 if full else rng.uniform(0.5, 1.0)))
        p.to(rng.uniform(0.4, 0.7), 0.0)
        p.hold(rng.uniform(1.0, 2.0))
    return p.kn, p.t

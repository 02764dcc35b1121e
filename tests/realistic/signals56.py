"""Signals of the HOLDOUT56 set (``cases_holdout56.py``): everyday scenes, each drawn from a generator here.

Every scene is a programme of knots (time, position) joined by moves; the evaluator takes any times (a record's grid or
a finer one) and returns the position, exactly the first knot's before the programme starts and the last's after it.
The move is the minimum-jerk reach (set_tools.minimum_jerk; Flash & Hogan, J. Neurosci. 5 (1985) 1688, as
remembered): R(s) = 10 s^3 - 15 s^4 + 6 s^5, s in 0 ... 1, starting and ending at rest. Nothing here imports hystcomp.
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


# ---- a tennis rally (the clean case) ----

def tennis_rally(rng, n_points):
    """A tennis player's racket across the body (+ forehand side, - backhand): for every point the serve's wait (held 2
    ... 4 s at 0), then 4 ... 7 shots, each a take-back to one side (to 0.5 ... 1 in 0.4 ... 0.7 s), the swing through
    to the other (to 0.3 ... 0.8 of the other side in 0.15 ... 0.3 s), the follow-through held 0.1 ... 0.3 s and the
    ready position (within 0.05 of 0 in 0.4 ... 0.8 s, held 0.3 ... 0.8 s). The full reach both ways in the first point.
    Returns the knots and the end."""
    p = _Prog()
    for k in range(n_points):
        p.hold(rng.uniform(2.0, 4.0))
        for j in range(int(rng.integers(4, 8))):
            sd = (1.0 if j % 2 == 0 else -1.0) if k == 0 else _side(rng)
            p.to(rng.uniform(0.4, 0.7), sd * (1.0 if (k == 0 and j < 2) else rng.uniform(0.5, 1.0)))
            p.to(rng.uniform(0.15, 0.3), -sd * rng.uniform(0.3, 0.8))
            p.hold(rng.uniform(0.1, 0.3))
            p.to(rng.uniform(0.4, 0.8), _side(rng) * rng.uniform(0.0, 0.05))
            p.hold(rng.uniform(0.3, 0.8))
        p.to(rng.uniform(0.5, 1.0), 0.0)
    p.hold(rng.uniform(1.0, 2.0))
    return p.kn, p.t


# ---- a gardener's secateurs (unipolar) ----

def secateurs(rng, n_bushes):
    """A gardener's grip on secateurs (0 open, 1 the hardest squeeze): for every bush 5 ... 9 cuts (each a squeeze to
    0.5 ... 1 in 0.3 ... 0.6 s, held as the blade bites through, 0.8 ... 2.5 s, let go to 0 ... 0.1 in 0.2 ... 0.4 s,
    held while the next stem is found, 1 ... 3 s), then the clippings gathered (held 8 ... 15 s at 0). The hardest
    squeeze at least once. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(1.0, 2.0))
    full = int(rng.integers(0, n_bushes))
    for k in range(n_bushes):
        for j in range(int(rng.integers(5, 10))):
            p.to(rng.uniform(0.3, 0.6), 1.0 if (k == full and j == 0) else rng.uniform(0.5, 1.0))
            p.hold(rng.uniform(0.8, 2.5))
            p.to(rng.uniform(0.2, 0.4), rng.uniform(0.0, 0.1))
            p.hold(rng.uniform(1.0, 3.0))
        p.to(rng.uniform(0.2, 0.4), 0.0)
        p.hold(rng.uniform(8.0, 15.0))
    return p.kn, p.t


# ---- a drummer's jazz brushes (never still) ----

def jazz_brushes(rng, n_choruses):
    """A drummer's brush across the snare (+ right, - left), never still: for every chorus 6 ... 12 sweeps of a ballad
    (to 0.5 ... 1 either side, alternating, in 0.5 ... 1.1 s), then 10 ... 20 quick taps of an up-tempo bridge (to 0.1
    ... 0.45 either side in 0.12 ... 0.3 s). The full reach both ways in the first chorus. No holds. Returns the knots
    and the end."""
    p = _Prog()
    p.to(0.4, 0.05)
    for c in range(n_choruses):
        sd = _side(rng)
        for j in range(int(rng.integers(6, 13))):
            sd = -sd
            p.to(rng.uniform(0.5, 1.1), sd * (1.0 if (c == 0 and j < 2) else rng.uniform(0.5, 1.0)))
        for _ in range(int(rng.integers(10, 21))):
            p.to(rng.uniform(0.12, 0.3), _side(rng) * rng.uniform(0.1, 0.45))
    p.to(0.6, 0.0)
    return p.kn, p.t


# ---- a greenhouse vent (unipolar, slow) ----

def greenhouse_vent(rng, n_spells):
    """A greenhouse's roof vent opened by its controller through a day, compressed (0 shut, 1 wide open): for every
    spell of weather the vent opened to 0.2 ... 1 in 1.5 ... 4 s, held 6 ... 20 s, trimmed 2 ... 4 times by 0.05 ... 0.2
    (in 1 ... 2 s, held 4 ... 12 s), and shut to 0 ... 0.1 (in 1.5 ... 4 s, held 5 ... 15 s). Wide open at least once;
    shut at the end. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(3.0, 6.0))
    full = int(rng.integers(0, n_spells))
    for k in range(n_spells):
        lvl = 1.0 if k == full else rng.uniform(0.2, 1.0)
        p.to(rng.uniform(1.5, 4.0), lvl)
        p.hold(rng.uniform(6.0, 20.0))
        for _ in range(int(rng.integers(2, 5))):
            lvl = float(np.clip(lvl + _side(rng) * rng.uniform(0.05, 0.2), 0.1, 1.0))
            p.to(rng.uniform(1.0, 2.0), lvl)
            p.hold(rng.uniform(4.0, 12.0))
        p.to(rng.uniform(1.5, 4.0), rng.uniform(0.0, 0.1))
        p.hold(rng.uniform(5.0, 15.0))
    p.to(2.0, 0.0)
    p.hold(rng.uniform(3.0, 6.0))
    return p.kn, p.t


# ---- a goalkeeper's dives ----

def goalkeeper(rng, n_drills):
    """A goalkeeper's body across the goal (+ right post, - left): for every drill the set position (held 1 ... 2.5 s
    near 0), 3 ... 6 saves (a dive to 0.55 ... 1 of one side in 0.3 ... 0.5 s, on the ground 0.5 ... 1.2 s, up and back
    to within 0.1 of the middle in 0.8 ... 1.4 s, held 0.8 ... 2 s), then the ball thrown out (to 0.2 ... 0.4 one way
    and back, 0.5 ... 0.9 s each). The full reach both ways in the first drill. Returns the knots and the end."""
    p = _Prog()
    for k in range(n_drills):
        p.hold(rng.uniform(1.0, 2.5))
        for j in range(int(rng.integers(3, 7))):
            sd = (1.0 if j % 2 == 0 else -1.0) if k == 0 else _side(rng)
            p.to(rng.uniform(0.3, 0.5), sd * (1.0 if (k == 0 and j < 2) else rng.uniform(0.55, 1.0)))
            p.hold(rng.uniform(0.5, 1.2))
            p.to(rng.uniform(0.8, 1.4), _side(rng) * rng.uniform(0.0, 0.1))
            p.hold(rng.uniform(0.8, 2.0))
        p.to(rng.uniform(0.5, 0.9), _side(rng) * rng.uniform(0.2, 0.4))
        p.to(rng.uniform(0.5, 0.9), 0.0)
    p.hold(rng.uniform(1.0, 2.0))
    return p.kn, p.t


# ---- a surfer pumping along a wave ----

def surfer(rng, n_waves):
    """A surfer's weight over the board (+ toes, - heels): for every wave the paddle out and the wait (held 2 ... 4 s at
    0), the pop-up (to 0.1 ... 0.3 in 0.4 ... 0.7 s), 3 ... 6 pumps (to 0.4 ... 0.8 and -0.3 ... -0.6, 0.4 ... 0.8 s
    each), a bottom turn and a cutback (to 0.8 ... 1 of one side in 0.5 ... 0.8 s, held 0.3 ... 0.6 s, to 0.8 ... 1 of
    the other in 0.6 ... 0.9 s, held 0.3 ... 0.6 s) and the kick-out (to 0 in 0.8 ... 1.5 s). The full reach both ways
    in the first wave. Returns the knots and the end."""
    p = _Prog()
    for k in range(n_waves):
        p.hold(rng.uniform(2.0, 4.0))
        p.to(rng.uniform(0.4, 0.7), rng.uniform(0.1, 0.3))
        for _ in range(int(rng.integers(3, 7))):
            p.to(rng.uniform(0.4, 0.8), rng.uniform(0.4, 0.8))
            p.to(rng.uniform(0.4, 0.8), -rng.uniform(0.3, 0.6))
        sd = 1.0 if k == 0 else _side(rng)
        p.to(rng.uniform(0.5, 0.8), sd * (1.0 if k == 0 else rng.uniform(0.8, 1.0)))
        p.hold(rng.uniform(0.3, 0.6))
        p.to(rng.uniform(0.6, 0.9), -sd * (1.0 if k == 0 else rng.uniform(0.8, 1.0)))
        p.hold(rng.uniform(0.3, 0.6))
        p.to(rng.uniform(0.8, 1.5), 0.0)
    p.hold(rng.uniform(1.0, 2.0))
    return p.kn, p.t


# ---- a potter's wheel pedal (unipolar) ----

def potter_pedal(rng, n_pots):
    """A potter's foot on the wheel's pedal (0 stopped, 1 full speed): for every pot the centring at speed (to 0.8 ...
    1 in 0.5 ... 1 s, held 4 ... 8 s), the opening and the pulls (3 ... 5 times to 0.3 ... 0.6 in 0.4 ... 0.8 s, held 2
    ... 5 s), the trimming (to 0.15 ... 0.3, held 3 ... 6 s) and the wheel stopped to lift the pot off (to 0 in 0.5 ...
    1 s, held 4 ... 9 s). Full speed at least once. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(1.0, 2.0))
    full = int(rng.integers(0, n_pots))
    for k in range(n_pots):
        p.to(rng.uniform(0.5, 1.0), 1.0 if k == full else rng.uniform(0.8, 1.0))
        p.hold(rng.uniform(4.0, 8.0))
        for _ in range(int(rng.integers(3, 6))):
            p.to(rng.uniform(0.4, 0.8), rng.uniform(0.3, 0.6))
            p.hold(rng.uniform(2.0, 5.0))
        p.to(rng.uniform(0.4, 0.8), rng.uniform(0.15, 0.3))
        p.hold(rng.uniform(3.0, 6.0))
        p.to(rng.uniform(0.5, 1.0), 0.0)
        p.hold(rng.uniform(4.0, 9.0))
    return p.kn, p.t


# ---- a metronome being set (the initial-state case) ----

def metronome(rng, n_tempi):
    """A metronome's pendulum (+ right, - left) as a teacher sets it: for every tempo 6 ... 12 beats at a swing of 0.5
    ... 1 (0.35 ... 0.9 s a beat, the same within a tempo), then stopped by hand (to 0 in 0.3 ... 0.6 s) and held 2 ...
    4 s while the weight is moved. The full reach both ways in the first tempo. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(1.0, 2.0))
    for k in range(n_tempi):
        beat, amp = rng.uniform(0.35, 0.9), 1.0 if k == 0 else rng.uniform(0.5, 1.0)
        sd = _side(rng)
        for _ in range(int(rng.integers(6, 13))):
            p.to(beat, sd * amp)
            sd = -sd
        p.to(rng.uniform(0.3, 0.6), 0.0)
        p.hold(rng.uniform(2.0, 4.0))
    return p.kn, p.t


# ---- a golfer's practice swings (the pair) ----

def golf_swing(rng, n_balls):
    """A golfer's club head along the swing (- back, + through): for every ball the address (held 2 ... 4 s at 0), 1
    ... 3 waggles (to -0.1 ... -0.25 and back, 0.3 ... 0.5 s each), the backswing (to -0.7 ... -1 in 0.8 ... 1.2 s), its
    top (held 0.1 ... 0.3 s), the downswing (to 0.7 ... 1 in 0.25 ... 0.4 s), the finish held (1 ... 2 s) and the club
    lowered (to 0 in 0.8 ... 1.3 s). The full reach both ways on the first ball. Returns the knots and the end."""
    p = _Prog()
    for k in range(n_balls):
        p.hold(rng.uniform(2.0, 4.0))
        for _ in range(int(rng.integers(1, 4))):
            p.to(rng.uniform(0.3, 0.5), -rng.uniform(0.1, 0.25))
            p.to(rng.uniform(0.3, 0.5), 0.0)
        p.to(rng.uniform(0.8, 1.2), -(1.0 if k == 0 else rng.uniform(0.7, 1.0)))
        p.hold(rng.uniform(0.1, 0.3))
        p.to(rng.uniform(0.25, 0.4), 1.0 if k == 0 else rng.uniform(0.7, 1.0))
        p.hold(rng.uniform(1.0, 2.0))
        p.to(rng.uniform(0.8, 1.3), 0.0)
    p.hold(rng.uniform(1.0, 2.0))
    return p.kn, p.t


# ---- a slalom skier (the out-of-vocabulary case) ----

def slalom(rng, n_runs):
    """A slalom skier's hips across the fall line (+ right, - left): for every run the start (held 2 ... 4 s at 0),
    8 ... 14 gates (a turn to 0.5 ... 1 of alternating sides in 0.5 ... 0.9 s), the finish (to 0 in 0.6 ... 1 s) and
    the chairlift (held 3 ... 6 s). The full reach both ways in the first run. Returns the knots and the end."""
    p = _Prog()
    for k in range(n_runs):
        p.hold(rng.uniform(2.0, 4.0))
        sd = _side(rng)
        for j in range(int(rng.integers(8, 15))):
            p.to(rng.uniform(0.5, 0.9), sd * (1.0 if (k == 0 and j < 2) else rng.uniform(0.5, 1.0)))
            sd = -sd
        p.to(rng.uniform(0.6, 1.0), 0.0)
        p.hold(rng.uniform(3.0, 6.0))
    return p.kn, p.t

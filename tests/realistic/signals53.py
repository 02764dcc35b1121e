"""Signals of the HOLDOUT53 set (``cases_holdout53.py``): everyday scenes, each drawn from a generator here.

Every scene is a programme of knots (time, position) joined by moves; the evaluator takes any times (a record's grid or
a finer one) and returns the position, exactly the first knot's before the programme starts and the last's after it.
The move is the minimum-jerk reach, written from its definition: the point-to-point move that minimises the integral
of the squared jerk with the position, speed and acceleration given at both ends (Flash & Hogan, J. Neurosci. 5
(1985) 1688, as remembered):

    R(s) = 10 s^3 - 15 s^4 + 6 s^5,  s in 0 ... 1,

its speed 30 s^2 (1 - s)^2, symmetric, peaking at the middle at 1.875 times the mean speed; it starts and ends at rest
with no acceleration. Nothing here imports hystcomp.
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


# ---- a kayaker's paddle (the clean case) ----

def kayak_paddle(rng, n_runs):
    """A kayaker's paddle shaft rolled toward the stroke's side (+ right blade in, - left): for every run a launch (held
    2 ... 4 s at 0), 6 ... 10 forward strokes alternating sides (each to 0.6 ... 1 in 0.35 ... 0.6 s, the blade's pull
    held 0.2 ... 0.5 s), a sweep turn (to 0.4 ... 0.7 on one side, held 1 ... 2 s, and back), a glide with the paddle
    across the deck (to 0 in 0.5 ... 0.9 s, held 1.5 ... 3 s). The full reach both ways in the first run's first two
    strokes. Returns the knots and the end."""
    p = _Prog()
    for k in range(n_runs):
        p.hold(rng.uniform(2.0, 4.0))
        sd = _side(rng)
        for j in range(int(rng.integers(6, 11))):
            p.to(rng.uniform(0.35, 0.6), sd * (1.0 if (k == 0 and j < 2) else rng.uniform(0.6, 1.0)))
            p.hold(rng.uniform(0.2, 0.5))
            sd = -sd
        p.to(rng.uniform(0.5, 0.9), _side(rng) * rng.uniform(0.4, 0.7))
        p.hold(rng.uniform(1.0, 2.0))
        p.to(rng.uniform(0.5, 0.9), 0.0)
        p.hold(rng.uniform(1.5, 3.0))
    return p.kn, p.t


# ---- a barista's tamper (unipolar) ----

def barista_tamp(rng, n_shots):
    """A barista's tamping pressure (0 the tamper lifted, 1 the firmest press): for every shot the grind dosed (held 6
    ... 12 s at 0), a light settling tamp (to 0.2 ... 0.35 in 0.3 ... 0.5 s, held 0.5 ... 1 s, lifted to 0), the firm
    tamp (to 0.75 ... 1 in 0.4 ... 0.7 s) held while it is polished (5 ... 10 s), the tamper lifted (to 0 in 0.3 ... 0.5
    s); the shot pulled and the puck knocked out (held 12 ... 20 s). The firmest press at least once. Returns the knots
    and the end."""
    p = _Prog()
    full = int(rng.integers(0, n_shots))
    for k in range(n_shots):
        p.hold(rng.uniform(6.0, 12.0))
        p.to(rng.uniform(0.3, 0.5), rng.uniform(0.2, 0.35))
        p.hold(rng.uniform(0.5, 1.0))
        p.to(rng.uniform(0.3, 0.5), 0.0)
        p.hold(rng.uniform(0.5, 1.0))
        p.to(rng.uniform(0.4, 0.7), 1.0 if k == full else rng.uniform(0.75, 1.0))
        p.hold(rng.uniform(5.0, 10.0))
        p.to(rng.uniform(0.3, 0.5), 0.0)
        p.hold(rng.uniform(12.0, 20.0))
    return p.kn, p.t


# ---- a conductor's baton ----

def conductor_baton(rng, n_phrases):
    """A conductor's baton across the body (+ right, - left), never still: for every phrase 4 ... 8 bars of a beat
    pattern (each bar 3 ... 4 beats: the downbeat's rebound to one side, 0.3 ... 0.7, the cross beat to the other,
    0.5 ... 1, and back toward the middle, 0.05 ... 0.25 either side; 0.25 ... 0.5 s a beat), the phrase's climax
    (a wide sweep to 0.8 ... 1 on both sides in 0.5 ... 0.9 s each). The full reach both ways in the first climax. No
    holds: no two knots alike in a row. Returns the knots and the end."""
    p = _Prog()
    p.to(0.4, 0.05)
    for ph in range(n_phrases):
        sd = _side(rng)
        for _ in range(int(rng.integers(4, 9))):
            p.to(rng.uniform(0.25, 0.5), sd * rng.uniform(0.3, 0.7))
            p.to(rng.uniform(0.25, 0.5), -sd * rng.uniform(0.5, 1.0))
            for _ in range(int(rng.integers(1, 3))):
                x = p.kn[-1][1]
                x_new = _side(rng) * rng.uniform(0.05, 0.25)
                p.to(rng.uniform(0.25, 0.5), x_new if x_new != x else x_new + 0.01)
        for k in range(2):
            p.to(rng.uniform(0.5, 0.9), sd * (1.0 if ph == 0 else rng.uniform(0.8, 1.0)))
            sd = -sd
        p.to(rng.uniform(0.4, 0.7), sd * rng.uniform(0.1, 0.2))
    p.to(rng.uniform(0.5, 0.8), 0.0)
    return p.kn, p.t


# ---- a weightlifter's sets (unipolar) ----

def weightlifter_sets(rng, n_sets):
    """A weightlifter's bar height in a set of presses (0 racked, 1 locked out overhead): for every set 3 ... 6 reps
    (each pressed to 0.85 ... 1 in 0.8 ... 1.5 s, locked out 1 ... 2.5 s, lowered to the shoulders, 0.15 ... 0.25, in
    1 ... 1.8 s, paused 0.5 ... 1 s), the bar racked (to 0 in 0.8 ... 1.2 s) and the rest between sets (held 15 ... 30
    s). Locked out at 1 at least once. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(3.0, 6.0))
    full = int(rng.integers(0, n_sets))
    for k in range(n_sets):
        for j in range(int(rng.integers(3, 7))):
            p.to(rng.uniform(0.8, 1.5), 1.0 if (k == full and j == 0) else rng.uniform(0.85, 1.0))
            p.hold(rng.uniform(1.0, 2.5))
            p.to(rng.uniform(1.0, 1.8), rng.uniform(0.15, 0.25))
            p.hold(rng.uniform(0.5, 1.0))
        p.to(rng.uniform(0.8, 1.2), 0.0)
        p.hold(rng.uniform(15.0, 30.0))
    return p.kn, p.t


# ---- a see-saw ----

def see_saw(rng, n_turns):
    """A see-saw's tilt (+ the near end up, - down) with two children: for every turn 4 ... 8 bounces (each end to
    0.6 ... 1 in 0.6 ... 1.1 s, the end on the ground held 0.2 ... 0.6 s while the child pushes off), then the two
    balancing (within 0.1 of level in 1 ... 2 s, held 2 ... 4 s) and one child climbing off and on (to 0 ... 0.1 held 3
    ... 5 s). The full reach both ways in the first turn. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(1.0, 2.0))
    for k in range(n_turns):
        sd = _side(rng)
        for j in range(int(rng.integers(4, 9))):
            p.to(rng.uniform(0.6, 1.1), sd * (1.0 if (k == 0 and j < 2) else rng.uniform(0.6, 1.0)))
            p.hold(rng.uniform(0.2, 0.6))
            sd = -sd
        p.to(rng.uniform(1.0, 2.0), _side(rng) * rng.uniform(0.0, 0.1))
        p.hold(rng.uniform(2.0, 4.0))
        p.to(rng.uniform(0.5, 1.0), rng.uniform(0.0, 0.1))
        p.hold(rng.uniform(3.0, 5.0))
    p.to(rng.uniform(0.5, 1.0), 0.0)
    p.hold(rng.uniform(1.0, 2.0))
    return p.kn, p.t


# ---- a windscreen wiper ----

def windscreen_wiper(rng, n_showers):
    """A windscreen wiper's blade angle (+ the driver's side, - the passenger's, 0 the middle of its sweep): for every
    shower 3 ... 6 intermittent wipes (each a sweep to one end, 0.75 ... 1, and across to the other in 0.45 ... 0.7 s
    each way, and back to the middle in 0.3 ... 0.5 s, the blade parked there 1.5 ... 4 s) and 4 ... 8 continuous wipes
    (end to end, no park); after the shower the blade parked (held 3 ... 6 s). The full reach both ways in the first
    wipe. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(1.0, 2.0))
    for k in range(n_showers):
        for j in range(int(rng.integers(3, 7))):
            first = k == 0 and j == 0
            p.to(rng.uniform(0.45, 0.7), 1.0 if first else rng.uniform(0.75, 1.0))
            p.to(rng.uniform(0.45, 0.7), -1.0 if first else -rng.uniform(0.75, 1.0))
            p.to(rng.uniform(0.3, 0.5), 0.0)
            p.hold(rng.uniform(1.5, 4.0))
        for j in range(int(rng.integers(4, 9))):
            p.to(rng.uniform(0.45, 0.7), rng.uniform(0.75, 1.0))
            p.to(rng.uniform(0.45, 0.7), -rng.uniform(0.75, 1.0))
        p.to(rng.uniform(0.3, 0.5), 0.0)
        p.hold(rng.uniform(3.0, 6.0))
    return p.kn, p.t


# ---- a sewing machine's foot pedal (unipolar) ----

def sewing_pedal(rng, n_seams):
    """A sewing machine's foot pedal (0 off, 1 flat out): for every seam the cloth lined up (held 3 ... 6 s at 0), a
    few slow stitches to start (to 0.15 ... 0.3 in 0.3 ... 0.6 s, held 1 ... 2 s), the run along the seam (to 0.6 ...
    1 in 0.4 ... 0.8 s, held 3 ... 8 s, with 1 ... 3 eases of 0.1 ... 0.3 and back, each held 0.5 ... 1.5 s), a slowing
    at the corner (to 0.1 ... 0.2 in 0.3 ... 0.5 s, held 1 ... 2 s) and off (to 0 in 0.2 ... 0.4 s, held 2 ... 5 s
    while the cloth is turned). Flat out at least once. Returns the knots and the end."""
    p = _Prog()
    full = int(rng.integers(0, n_seams))
    for k in range(n_seams):
        p.hold(rng.uniform(3.0, 6.0))
        p.to(rng.uniform(0.3, 0.6), rng.uniform(0.15, 0.3))
        p.hold(rng.uniform(1.0, 2.0))
        top = 1.0 if k == full else rng.uniform(0.6, 1.0)
        p.to(rng.uniform(0.4, 0.8), top)
        p.hold(rng.uniform(1.0, 3.0))
        for _ in range(int(rng.integers(1, 4))):
            p.to(rng.uniform(0.3, 0.6), top - rng.uniform(0.1, 0.3))
            p.hold(rng.uniform(0.5, 1.5))
            p.to(rng.uniform(0.3, 0.6), top)
            p.hold(rng.uniform(1.0, 2.5))
        p.to(rng.uniform(0.3, 0.5), rng.uniform(0.1, 0.2))
        p.hold(rng.uniform(1.0, 2.0))
        p.to(rng.uniform(0.2, 0.4), 0.0)
        p.hold(rng.uniform(2.0, 5.0))
    return p.kn, p.t


# ---- a radio operator's tuning dial ----

def tuning_dial(rng, n_stations):
    """A short-wave listener's fine-tuning dial (+ up the band, - down, 0 the band's middle): first a search about the
    middle by small turns (8 ... 14 turns within 0.04 either way, 0.3 ... 0.7 s each, held 0.5 ... 1.5 s), then for
    every station a sweep to it (0.3 ... 1 either way, at least 0.3 from the last, in 0.8 ... 1.6 s), the station tuned
    in (2 ... 4 small touches of 0.01 ... 0.04, 0.2 ... 0.4 s each) and listened to (held 2 ... 5 s); back to the middle
    at the end (in 1 ... 2 s, held 2 ... 4 s). Both band edges among the first two stations. Returns the knots and the
    end."""
    p = _Prog()
    p.hold(rng.uniform(1.0, 2.0))
    for _ in range(int(rng.integers(8, 15))):
        p.to(rng.uniform(0.3, 0.7), _side(rng) * rng.uniform(0.0, 0.04))
        p.hold(rng.uniform(0.5, 1.5))
    ends = [1.0, -1.0] if rng.uniform() < 0.5 else [-1.0, 1.0]
    x = p.kn[-1][1]
    for k in range(n_stations):
        if k < 2:
            x_new = ends[k]
        else:
            x_new = x
            while abs(x_new - x) < 0.3:
                x_new = _side(rng) * rng.uniform(0.3, 1.0)
        x = x_new
        p.to(rng.uniform(0.8, 1.6), x)
        for _ in range(int(rng.integers(2, 5))):
            xt = float(np.clip(x + _side(rng) * rng.uniform(0.01, 0.04), -1.0, 1.0))
            p.to(rng.uniform(0.2, 0.4), xt)
        p.hold(rng.uniform(2.0, 5.0))
    p.to(rng.uniform(1.0, 2.0), 0.0)
    p.hold(rng.uniform(2.0, 4.0))
    return p.kn, p.t


# ---- a fencer's lunges ----

def fencer_bout(rng, n_points):
    """A fencer's front foot along the piste (+ a lunge forward, - a retreat): for every point the en garde (held 2 ...
    4 s at 0), 2 ... 4 steps forward and back (0.15 ... 0.35 either way, 0.3 ... 0.5 s each, held 0.2 ... 0.5 s), a
    lunge (to 0.7 ... 1 in 0.25 ... 0.4 s, held 0.3 ... 0.8 s) and the recovery or the opponent's riposte and the
    retreat (to -0.6 ... -1 in 0.5 ... 0.8 s, held 0.5 ... 1 s), back to en garde (to 0 in 0.6 ... 1 s). The full reach
    both ways in the first point. Returns the knots and the end."""
    p = _Prog()
    for k in range(n_points):
        p.hold(rng.uniform(2.0, 4.0))
        for _ in range(int(rng.integers(2, 5))):
            p.to(rng.uniform(0.3, 0.5), _side(rng) * rng.uniform(0.15, 0.35))
            p.hold(rng.uniform(0.2, 0.5))
        p.to(rng.uniform(0.25, 0.4), 1.0 if k == 0 else rng.uniform(0.7, 1.0))
        p.hold(rng.uniform(0.3, 0.8))
        p.to(rng.uniform(0.5, 0.8), -(1.0 if k == 0 else rng.uniform(0.6, 1.0)))
        p.hold(rng.uniform(0.5, 1.0))
        p.to(rng.uniform(0.6, 1.0), 0.0)
    p.hold(rng.uniform(2.0, 4.0))
    return p.kn, p.t


# ---- a sailor's tiller ----

def sailor_tiller(rng, n_legs):
    """A dinghy sailor's tiller (+ pushed to port, - to starboard): for every leg 4 ... 8 small steering corrections
    (0.05 ... 0.25 either way, 0.4 ... 0.9 s each, held 0.5 ... 1.5 s), then a tack (the tiller pushed to 0.8 ... 1 in
    0.5 ... 0.8 s, held 1 ... 2 s while the boat turns, and centred in 0.5 ... 0.9 s), the next leg's corrections and a
    gybe the other way (to -0.8 ... -1, the same times). The full reach both ways in the first leg. Returns the knots
    and the end."""
    p = _Prog()
    p.hold(rng.uniform(1.0, 3.0))
    for k in range(n_legs):
        sd = _side(rng)
        for turn in range(2):
            for _ in range(int(rng.integers(4, 9))):
                p.to(rng.uniform(0.4, 0.9), _side(rng) * rng.uniform(0.05, 0.25))
                p.hold(rng.uniform(0.5, 1.5))
            p.to(rng.uniform(0.5, 0.8), sd * (1.0 if k == 0 else rng.uniform(0.8, 1.0)))
            p.hold(rng.uniform(1.0, 2.0))
            p.to(rng.uniform(0.5, 0.9), 0.0)
            sd = -sd
    p.hold(rng.uniform(2.0, 4.0))
    return p.kn, p.t

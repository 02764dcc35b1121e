"""Signals of the HOLDOUT51 set (``cases_holdout51.py``): everyday scenes, each drawn from a generator here.

Every scene is a programme of knots (time, position) joined by moves; the evaluator takes any times (a record's grid or
a finer one) and returns the position, exactly the first knot's before the programme starts and the last's after it.
The move is a lognormal reach, written from its definition: the speed of a rapid hand movement as the kinematic theory
of rapid human movements draws it, a lognormal profile in time (Plamondon, Biol. Cybern. 72 (1995) 295, as remembered),
here truncated to the move's time and renormalised so that it ends exactly on its target:

    R(s) = Phi((ln s - MU) / SIGMA) / Phi(-MU / SIGMA),  s in 0 ... 1 (R(0) = 0),

Phi the standard normal distribution function, MU = -1.25 and SIGMA = 0.38 (a choice: the speed peaks at s =
exp(MU - SIGMA^2) = 0.248 of the move, at 3.94 times the mean speed, and the profile's tail beyond s = 1 holds
5.0e-4 of the move, which the renormalisation folds in, so the speed falls from 4.7e-3 times the mean speed to 0 at
the move's end). Its speed is 0 at the start with every derivative: a quick, smooth start and a long, gentle landing
on the target, as a hand's rapid reach has it. Nothing here imports
hystcomp.
"""

import math

import numpy as np
from scipy.special import ndtr

from .set_tools import Programme as _Prog, knots_at as _knots_at

#: the lognormal reach's parameters (in units of the move's time) and its peak speed (a unit move over a unit time)
MU, SIGMA = -1.25, 0.38
PEAK_SPEED = 3.9407
_NORM = float(ndtr(-MU / SIGMA))


def reach(s):
    """The move 0 ... 1 over s in 0 ... 1 (0 before, 1 after): Phi((ln s - MU) / SIGMA) / Phi(-MU / SIGMA)."""
    s = np.clip(np.asarray(s, float), 0.0, 1.0)
    with np.errstate(divide="ignore"):
        z = (np.log(s) - MU) / SIGMA
    return np.where(s > 0.0, ndtr(z) / _NORM, 0.0)


def reach_speed(s):
    """The move's speed (a unit move over a unit time) at s in (0, 1]: the lognormal density over Phi(-MU / SIGMA)."""
    s = np.asarray(s, float)
    z = (np.log(s) - MU) / SIGMA
    return np.exp(-0.5 * z * z) / (s * SIGMA * math.sqrt(2.0 * math.pi)) / _NORM


def knots_at(t, knots):
    """The position on times t through knots [(time, position), ...] joined by lognormal reaches; the first knot's
    position before it, the last's after."""
    return _knots_at(t, knots, reach)


def _side(rng):
    """A side drawn at even odds: +1 or -1 (one uniform draw)."""
    return 1.0 if rng.uniform() < 0.5 else -1.0


# ---- a snooker player's cue (the clean case) ----

def snooker_cue(rng, n_shots):
    """A snooker player's cue tip along the line of the shot (+ through the cue ball, - drawn back): for every shot the
    tip brought to the ball (to within 0.03 of 0 in 0.5 ... 1 s, held 1 ... 2 s), feathering (3 ... 6 small strokes,
    0.05 ... 0.15 either way, 0.3 ... 0.5 s each), the final backswing (to -0.6 ... -1 in 0.4 ... 0.7 s), the pause
    (held 0.3 ... 0.8 s), the stroke through the ball (to 0.6 ... 1 in 0.12 ... 0.25 s), the freeze (held 0.5 ... 1.5
    s), the cue back to 0 (in 0.5 ... 1 s) and a walk round the table (held 2 ... 4 s). The full reach both ways in the
    first shot. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.5, 1.0))
    for k in range(n_shots):
        p.to(rng.uniform(0.5, 1.0), _side(rng) * rng.uniform(0.0, 0.03))
        p.hold(rng.uniform(1.0, 2.0))
        for _ in range(int(rng.integers(3, 7))):
            p.to(rng.uniform(0.3, 0.5), _side(rng) * rng.uniform(0.05, 0.15))
        p.to(rng.uniform(0.4, 0.7), -(1.0 if k == 0 else rng.uniform(0.6, 1.0)))
        p.hold(rng.uniform(0.3, 0.8))
        p.to(rng.uniform(0.12, 0.25), 1.0 if k == 0 else rng.uniform(0.6, 1.0))
        p.hold(rng.uniform(0.5, 1.5))
        p.to(rng.uniform(0.5, 1.0), 0.0)
        p.hold(rng.uniform(2.0, 4.0))
    return p.kn, p.t


# ---- an archer's draw (unipolar) ----

def archery(rng, n_ends):
    """A target archer's draw (0 the bow at rest, 1 the full draw at the anchor): for every end of three arrows, each
    arrow nocked (held 2 ... 4 s), the bow raised with a pre-draw (to 0.1 ... 0.2 in 1 ... 1.5 s), drawn (to 0.93 ... 1
    in 1.5 ... 2.5 s: the full draw once at least), anchored and aimed (held 3 ... 6 s), and released (to 0 in 0.05 ...
    0.1 s) with the follow-through held 1 ... 2 s; one arrow in four let down first (eased to 0.15 ... 0.3 in 1.5 ...
    2.5 s, held 2 ... 4 s, drawn and aimed again); after the end the walk to the target and back (held 12 ... 20 s).
    Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(1.0, 2.0))
    full = int(rng.integers(0, 3 * n_ends))
    for e in range(n_ends):
        for a in range(3):
            top = 1.0 if 3 * e + a == full else rng.uniform(0.93, 1.0)
            p.hold(rng.uniform(2.0, 4.0))
            p.to(rng.uniform(1.0, 1.5), rng.uniform(0.1, 0.2))
            p.to(rng.uniform(1.5, 2.5), top)
            p.hold(rng.uniform(3.0, 6.0))
            if rng.uniform() < 0.25:
                p.to(rng.uniform(1.5, 2.5), rng.uniform(0.15, 0.3))
                p.hold(rng.uniform(2.0, 4.0))
                p.to(rng.uniform(1.5, 2.5), top)
                p.hold(rng.uniform(3.0, 6.0))
            p.to(rng.uniform(0.05, 0.1), 0.0)
            p.hold(rng.uniform(1.0, 2.0))
        p.hold(rng.uniform(12.0, 20.0))
    return p.kn, p.t


# ---- a cross-country skier's poles ----

def cross_country_skier(rng, n_sections):
    """A classic cross-country skier's right arm (its pole's swing: + planted forward, - pushed back), never still: for
    every section a stretch of diagonal stride (8 ... 14 swings, each to 0.6 ... 1 of the reach on alternate sides in
    0.3 ... 0.5 s), double poling (4 ... 8 pushes: the arms thrown forward to 0.8 ... 1 in 0.2 ... 0.3 s and pushed back
    to -0.7 ... -1 in 0.25 ... 0.4 s) and a herringbone climb (6 ... 12 short, quick swings of 0.3 ... 0.6 either side
    in 0.2 ... 0.3 s), then a tuck down the next hill (the arm near -0.2, wobbling 0.02 ... 0.05 about it, 0.3 ... 0.6 s
    each, 4 ... 8 times). The full reach both ways in the first stride. No holds: no two knots alike in a row. Returns
    the knots and the end."""
    p = _Prog()
    p.to(0.3, 0.05)
    for sc in range(n_sections):
        sd = _side(rng)
        for k in range(int(rng.integers(8, 15))):
            a = 1.0 if (sc == 0 and k < 2) else rng.uniform(0.6, 1.0)
            p.to(rng.uniform(0.3, 0.5), sd * a)
            sd = -sd
        for _ in range(int(rng.integers(4, 9))):
            p.to(rng.uniform(0.2, 0.3), rng.uniform(0.8, 1.0))
            p.to(rng.uniform(0.25, 0.4), -rng.uniform(0.7, 1.0))
        sd = _side(rng)
        for _ in range(int(rng.integers(6, 13))):
            p.to(rng.uniform(0.2, 0.3), sd * rng.uniform(0.3, 0.6))
            sd = -sd
        c = -0.2
        for k in range(int(rng.integers(4, 9))):
            p.to(rng.uniform(0.3, 0.6), c + (1.0 if k % 2 == 0 else -1.0) * rng.uniform(0.02, 0.05))
    p.to(rng.uniform(0.3, 0.5), 0.0)
    return p.kn, p.t


# ---- a weightlifter's session (unipolar) ----

def weightlifter(rng, n_lifts):
    """A weightlifter's bar height through a clean-and-jerk session (0 the bar on the platform, 1 locked out overhead):
    for every lift the set-up (held 2 ... 4 s), the first pull (to 0.45 ... 0.55 in 0.5 ... 0.8 s), the clean to the
    rack (to 0.62 ... 0.7 in 0.3 ... 0.5 s, held in the rack 1.5 ... 3 s), the jerk's dip (to 0.55 ... 0.6 in 0.3 ...
    0.5 s) and drive (to 0.95 ... 1 in 0.25 ... 0.4 s: the full height once at least), the lockout (held 2 ... 4 s),
    the bar lowered to the rack (in 0.6 ... 1 s, held 0.5 ... 1 s) and to the platform (in 0.8 ... 1.5 s); between
    lifts the rest (chalk, plates changed: held 20 ... 40 s). Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(3.0, 6.0))
    full = int(rng.integers(0, n_lifts))
    for k in range(n_lifts):
        p.hold(rng.uniform(2.0, 4.0))
        p.to(rng.uniform(0.5, 0.8), rng.uniform(0.45, 0.55))
        rack = rng.uniform(0.62, 0.7)
        p.to(rng.uniform(0.3, 0.5), rack)
        p.hold(rng.uniform(1.5, 3.0))
        p.to(rng.uniform(0.3, 0.5), rng.uniform(0.55, 0.6))
        p.to(rng.uniform(0.25, 0.4), 1.0 if k == full else rng.uniform(0.95, 1.0))
        p.hold(rng.uniform(2.0, 4.0))
        p.to(rng.uniform(0.6, 1.0), rack)
        p.hold(rng.uniform(0.5, 1.0))
        p.to(rng.uniform(0.8, 1.5), 0.0)
        p.hold(rng.uniform(20.0, 40.0))
    return p.kn, p.t


# ---- a skateboarder carving ----

def skateboard_carving(rng, n_runs):
    """A skateboarder's board (its lean: + toeside, - heelside): for every run 3 ... 5 pushes (the board near level,
    wobbling 0.03 ... 0.1 either way, 0.4 ... 0.7 s each), then 6 ... 12 carves on alternate edges (each a lean to 0.5
    ... 1 of the reach in 0.4 ... 0.8 s, held at the apex 0.2 ... 0.5 s), a kick turn (a sharp lean to 0.85 ... 1 on
    either edge in 0.15 ... 0.25 s, held 0.2 ... 0.4 s) and the board level again (in 0.3 ... 0.6 s, held 1 ... 3 s).
    The full reach both ways in the first run's carves. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.5, 1.0))
    for r in range(n_runs):
        for _ in range(int(rng.integers(3, 6))):
            p.to(rng.uniform(0.4, 0.7), _side(rng) * rng.uniform(0.03, 0.1))
        sd = _side(rng)
        for k in range(int(rng.integers(6, 13))):
            a = 1.0 if (r == 0 and k < 2) else rng.uniform(0.5, 1.0)
            p.to(rng.uniform(0.4, 0.8), sd * a)
            p.hold(rng.uniform(0.2, 0.5))
            sd = -sd
        p.to(rng.uniform(0.15, 0.25), _side(rng) * rng.uniform(0.85, 1.0))
        p.hold(rng.uniform(0.2, 0.4))
        p.to(rng.uniform(0.3, 0.6), 0.0)
        p.hold(rng.uniform(1.0, 3.0))
    return p.kn, p.t


# ---- a gardener's hedge trimmer ----

def hedge_trimmer(rng, n_stretches):
    """A hedge trimmer's blade swept across a hedge's face (+ to the right, - to the left), never still: for every
    stretch of hedge 4 ... 8 sweeps (each to 0.6 ... 1 of the reach on alternate sides in 0.4 ... 0.8 s), at the end of
    each sweep 2 ... 4 trims (jiggles of 0.05 ... 0.15 back and forth, 0.1 ... 0.2 s each), then the gardener steps
    along (the blade near 0, moving 0.02 ... 0.08 either way, 0.3 ... 0.6 s each, 3 ... 5 times). The full reach both
    ways in the first stretch. No holds: no two knots alike in a row. Returns the knots and the end."""
    p = _Prog()
    p.to(0.3, 0.04)
    for st in range(n_stretches):
        sd = _side(rng)
        for k in range(int(rng.integers(4, 9))):
            a = sd * (1.0 if (st == 0 and k < 2) else rng.uniform(0.6, 1.0))
            p.to(rng.uniform(0.4, 0.8), a)
            for j in range(int(rng.integers(2, 5))):
                d = rng.uniform(0.05, 0.15)
                p.to(rng.uniform(0.1, 0.2), a - sd * d)
                p.to(rng.uniform(0.1, 0.2), a - sd * 0.2 * d)
            sd = -sd
        for k in range(int(rng.integers(3, 6))):
            p.to(rng.uniform(0.3, 0.6), (1.0 if k % 2 == 0 else -1.0) * rng.uniform(0.02, 0.08))
    p.to(rng.uniform(0.3, 0.5), 0.0)
    return p.kn, p.t


# ---- a trumpet player's valve (unipolar) ----

def trumpet_valve(rng, n_phrases):
    """A trumpet player's first valve (0 up, 1 pressed to its stop) through a tune: for every phrase at a tempo of 90
    ... 160 beats a minute, 8 ... 16 notes, each an eighth, quarter or half note (weights 0.4, 0.4, 0.2), the valve
    pressed for about half of them (to 1 in 0.02 ... 0.04 s; one press in six a half-valve effect, to 0.4 ... 0.6),
    held for the note less 0.03 ... 0.05 s and released (to 0 in 0.03 ... 0.05 s) in time for the next; open notes
    leave it up; between phrases a breath (held 1 ... 3 s). The full press at least once. Returns the knots and the
    end."""
    p = _Prog()
    p.hold(rng.uniform(0.5, 1.0))
    pressed_full = False
    for ph in range(n_phrases):
        beat = 60.0 / rng.uniform(90.0, 160.0)
        for k in range(int(rng.integers(8, 17))):
            u = rng.uniform()
            length = beat * (0.5 if u < 0.4 else (1.0 if u < 0.8 else 2.0))
            if rng.uniform() < 0.5 or (ph == 0 and k == 0):
                half = rng.uniform() < 1 / 6 and pressed_full
                depth = rng.uniform(0.4, 0.6) if half else 1.0
                pressed_full = pressed_full or not half
                t_dn, t_up = rng.uniform(0.02, 0.04), rng.uniform(0.03, 0.05)
                p.to(t_dn, depth)
                p.hold(max(length - t_dn - t_up, 0.01))
                p.to(t_up, 0.0)
            else:
                p.hold(length)
        p.hold(rng.uniform(1.0, 3.0))
    return p.kn, p.t


# ---- a model railway's controller ----

def model_railway(rng, n_runs):
    """A model railway's controller knob (+ forward, - reverse): first the shunting (for 14 ... 20 s: the locomotive
    inched back and forth to couple wagons, moves of 0.005 ... 0.04 of the reach either way, within 0.05 of the
    centre, in 0.5 ... 1.5 s, held 1 ... 3 s), the knob back to 0 (held 2 ... 4 s), then the main line: for every run a
    start (to 0.7 ... 1 either way in 2 ... 4 s, the two ways in turn and the full reach in the first two), cruising
    (held 2 ... 5 s), a slowing for a curve (to 0.4 ... 0.6 of that speed in 1 ... 2 s, held 1 ... 2 s, back up in 1
    ... 2 s) and braking into the station (to 0 in 2 ... 3 s, held 2 ... 4 s). Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.5, 1.0))
    x, t_shunt = 0.0, rng.uniform(14.0, 20.0)
    while p.t < t_shunt:
        x = float(np.clip(x + _side(rng) * rng.uniform(0.005, 0.04), -0.05, 0.05))
        p.to(rng.uniform(0.5, 1.5), x)
        p.hold(rng.uniform(1.0, 3.0))
    p.to(rng.uniform(0.5, 1.0), 0.0)
    p.hold(rng.uniform(2.0, 4.0))
    sd = _side(rng)
    for k in range(n_runs):
        a = sd * (1.0 if k < 2 else rng.uniform(0.7, 1.0))
        p.to(rng.uniform(2.0, 4.0), a)
        p.hold(rng.uniform(2.0, 5.0))
        p.to(rng.uniform(1.0, 2.0), a * rng.uniform(0.4, 0.6))
        p.hold(rng.uniform(1.0, 2.0))
        p.to(rng.uniform(1.0, 2.0), a)
        p.to(rng.uniform(2.0, 3.0), 0.0)
        p.hold(rng.uniform(2.0, 4.0))
        sd = -sd
    return p.kn, p.t


# ---- a theatre's fly system ----

def theatre_flyman(rng, n_cues):
    """A flyman's batten on a counterweight line set (+ flown out above its trim, - lowered in below it): for every cue
    a move to the next trim (0.3 ... 1 of the reach, either way, at least 0.3 from the last, in 2 ... 5 s; the full
    reach both ways in the first four cues), held for the scene (6 ... 14 s), with now and then (one cue in three) a
    touch-up of the trim (0.02 ... 0.05 either way in 0.5 ... 1 s, held the rest of the scene); the batten back to its
    trim at the end (in 2 ... 4 s, held 3 ... 6 s). Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(2.0, 4.0))
    x = 0.0
    ends = [1.0, -1.0] if rng.uniform() < 0.5 else [-1.0, 1.0]
    at = sorted(rng.choice(4, size=2, replace=False))
    for k in range(n_cues):
        if k in at:
            x_new = ends[at.index(k)]
        else:
            x_new = x
            while abs(x_new - x) < 0.3:
                x_new = _side(rng) * rng.uniform(0.3, 1.0)
        x = x_new
        p.to(rng.uniform(2.0, 5.0), x)
        scene = rng.uniform(6.0, 14.0)
        if rng.uniform() < 1 / 3:
            first = rng.uniform(0.3, 0.6) * scene
            p.hold(first)
            x = float(np.clip(x + _side(rng) * rng.uniform(0.02, 0.05), -1.0, 1.0))
            d = rng.uniform(0.5, 1.0)
            p.to(d, x)
            p.hold(max(scene - first - d, 0.5))
        else:
            p.hold(scene)
    p.to(rng.uniform(2.0, 4.0), 0.0)
    p.hold(rng.uniform(3.0, 6.0))
    return p.kn, p.t


# ---- a petanque player's throws ----

def petanque(rng, n_ends):
    """A petanque player's throwing arm (+ swung forward, - back): for every end three boules, each the stance (held 1
    ... 2 s at 0), the backswing (to -0.6 ... -1 in 0.4 ... 0.6 s), the forward swing and release (to 0.7 ... 1 in 0.3
    ... 0.5 s), the follow-through (held 0.5 ... 1 s) and the arm down (to 0 in 0.5 ... 1 s), watching the boule roll
    (held 2 ... 4 s); after the end the walk to the jack and back (held 5 ... 9 s). The full reach both ways in the
    first throw. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.5, 1.0))
    for e in range(n_ends):
        for b in range(3):
            first = e == 0 and b == 0
            p.hold(rng.uniform(1.0, 2.0))
            p.to(rng.uniform(0.4, 0.6), -(1.0 if first else rng.uniform(0.6, 1.0)))
            p.to(rng.uniform(0.3, 0.5), 1.0 if first else rng.uniform(0.7, 1.0))
            p.hold(rng.uniform(0.5, 1.0))
            p.to(rng.uniform(0.5, 1.0), 0.0)
            p.hold(rng.uniform(2.0, 4.0))
        p.hold(rng.uniform(5.0, 9.0))
    return p.kn, p.t

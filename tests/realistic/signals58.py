"""Signals of the HOLDOUT58 set (``cases_holdout58.py``): everyday scenes, each drawn from a generator here.

Every scene is a programme of knots (time, position) joined by moves; the evaluator takes any times (a record's grid or
a finer one) and returns the position, exactly the first knot's before the programme starts and the last's after it.
The move is the minimum-jerk reach (set_tools.minimum_jerk; Flash & Hogan, J. Neurosci. 5 (1985) 1688, as
remembered): R(s) = 10 s^3 - 15 s^4 + 6 s^5, s in 0 ... 1, starting and ending at rest. Nothing here imports hystcomp.
"""

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


# ---- a violinist's bow (the clean case) ----

def violin_bow(rng, n_phrases):
    """A violinist's bow along the string (+ an up-bow's travel, - a down-bow's): for every phrase the bow set on the
    string (held 1 ... 2 s at 0), 4 ... 8 strokes alternating up and down (each to 0.4 ... 1 in 0.5 ... 1.6 s: long
    notes and short), some with a slur's pause held 0.1 ... 0.4 s, a few quick spiccato strokes (0.1 ... 0.25 either
    side in 0.15 ... 0.25 s) and the bow lifted back to 0 (in 0.5 ... 0.8 s). The full bow both ways in the first
    phrase. Returns the knots and the end."""
    p = _Prog()
    for k in range(n_phrases):
        p.hold(rng.uniform(1.0, 2.0))
        sd = _side(rng)
        for j in range(int(rng.integers(4, 9))):
            p.to(rng.uniform(0.5, 1.6), sd * (1.0 if (k == 0 and j < 2) else rng.uniform(0.4, 1.0)))
            if rng.uniform() < 0.4:
                p.hold(rng.uniform(0.1, 0.4))
            sd = -sd
        for _ in range(int(rng.integers(3, 7))):
            p.to(rng.uniform(0.15, 0.25), _side(rng) * rng.uniform(0.1, 0.25))
        p.to(rng.uniform(0.5, 0.8), 0.0)
    p.hold(rng.uniform(1.0, 2.0))
    return p.kn, p.t


# ---- a barista's tamper (unipolar) ----

def barista_tamper(rng, n_shots):
    """A barista's press on a tamper (0 resting, 1 the firmest press): for every shot the basket dosed (held 4 ... 8 s
    at 0 ... 0.05), the tamp (to 0.7 ... 1 in 0.4 ... 0.8 s, held 2 ... 5 s), a lighter polish (let go to 0.2 ... 0.4
    and pressed again to 0.5 ... 0.8, 0.3 ... 0.6 s each, held 1 ... 2 s), let go (to 0 in 0.3 ... 0.6 s) and the shot
    pulled (held 8 ... 14 s). The firmest press at least once. Returns the knots and the end."""
    p = _Prog()
    full = int(rng.integers(0, n_shots))
    for k in range(n_shots):
        p.to(rng.uniform(0.5, 1.0), rng.uniform(0.0, 0.05))
        p.hold(rng.uniform(4.0, 8.0))
        p.to(rng.uniform(0.4, 0.8), 1.0 if k == full else rng.uniform(0.7, 1.0))
        p.hold(rng.uniform(2.0, 5.0))
        p.to(rng.uniform(0.3, 0.6), rng.uniform(0.2, 0.4))
        p.to(rng.uniform(0.3, 0.6), rng.uniform(0.5, 0.8))
        p.hold(rng.uniform(1.0, 2.0))
        p.to(rng.uniform(0.3, 0.6), 0.0)
        p.hold(rng.uniform(8.0, 14.0))
    return p.kn, p.t


# ---- a windsurfer's boom (never still) ----

def windsurfer_boom(rng, n_reaches):
    """A windsurfer's pull on the boom (+ sheeted in, - let out against the rig), never still: for every reach 6 ... 12
    gust corrections (to 0.2 ... 0.7 of one side, 0.2 ... 0.45 s each), a tack (to 0.8 ... 1 one way in 0.5 ... 0.9 s
    and through to the other in 0.6 ... 1 s) and the rig settled (to 0.05 ... 0.2 in 0.4 ... 0.7 s). The full reach
    both ways in the first reach's tack. No holds. Returns the knots and the end."""
    p = _Prog()
    p.to(0.3, 0.03)
    for k in range(n_reaches):
        x = p.kn[-1][1]
        for _ in range(int(rng.integers(6, 13))):
            x_new = _side(rng) * rng.uniform(0.2, 0.7)
            if x_new == x:
                x_new += 0.01
            p.to(rng.uniform(0.2, 0.45), x_new)
            x = x_new
        sd = _side(rng)
        p.to(rng.uniform(0.5, 0.9), sd * (1.0 if k == 0 else rng.uniform(0.8, 1.0)))
        p.to(rng.uniform(0.6, 1.0), -sd * (1.0 if k == 0 else rng.uniform(0.8, 1.0)))
        p.to(rng.uniform(0.4, 0.7), _side(rng) * rng.uniform(0.05, 0.2))
    p.to(rng.uniform(0.4, 0.7), 0.0)
    return p.kn, p.t


# ---- a seamstress's treadle (unipolar) ----

def sewing_treadle(rng, n_seams):
    """A seamstress's foot on a sewing machine's speed pedal (0 off, 1 flat out): for every seam the cloth set (held 4
    ... 9 s at 0), the seam run (pressed to 0.4 ... 1 in 0.5 ... 1 s, held 3 ... 10 s with 0 ... 2 changes of 0.05 ...
    0.2 either way, within 0.3 ... 1), eased off at a corner (to 0 ... 0.1 in 0.3 ... 0.5 s, held 1 ... 3 s, pressed
    again to 0.3 ... 0.8 for 2 ... 5 s) and let go (to 0 in 0.3 ... 0.6 s). Flat out at least once. Returns the knots
    and the end."""
    p = _Prog()
    full = int(rng.integers(0, n_seams))
    for k in range(n_seams):
        p.hold(rng.uniform(4.0, 9.0))
        x = 1.0 if k == full else rng.uniform(0.4, 1.0)
        p.to(rng.uniform(0.5, 1.0), x)
        p.hold(rng.uniform(1.5, 4.0))
        for _ in range(int(rng.integers(0, 3))):
            x = min(max(x + _side(rng) * rng.uniform(0.05, 0.2), 0.3), 1.0)
            p.to(rng.uniform(0.3, 0.6), x)
            p.hold(rng.uniform(1.5, 3.0))
        p.to(rng.uniform(0.3, 0.5), rng.uniform(0.0, 0.1))
        p.hold(rng.uniform(1.0, 3.0))
        p.to(rng.uniform(0.3, 0.6), rng.uniform(0.3, 0.8))
        p.hold(rng.uniform(2.0, 5.0))
        p.to(rng.uniform(0.3, 0.6), 0.0)
    p.hold(rng.uniform(4.0, 8.0))
    return p.kn, p.t


# ---- a rower's oar ----

def rowing_oar(rng, n_pieces):
    """A rower's oar handle along the boat (+ the finish, drawn to the body; - the catch, reached forward): for every
    piece 5 ... 9 strokes (the catch at 0.6 ... 1 forward, reached on the recovery in 0.8 ... 1.3 s, the drive to the
    finish at 0.6 ... 1 in 0.5 ... 0.8 s, the hands away to 0 ... 0.2 in 0.3 ... 0.5 s), then easy (to 0 in 0.5 ... 1 s,
    held 2 ... 4 s). The full reach both ways in the first piece. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(1.0, 2.0))
    for k in range(n_pieces):
        for j in range(int(rng.integers(5, 10))):
            full = k == 0 and j == 0
            p.to(rng.uniform(0.8, 1.3), -(1.0 if full else rng.uniform(0.6, 1.0)))
            p.to(rng.uniform(0.5, 0.8), 1.0 if full else rng.uniform(0.6, 1.0))
            p.to(rng.uniform(0.3, 0.5), rng.uniform(0.0, 0.2))
        p.to(rng.uniform(0.5, 1.0), 0.0)
        p.hold(rng.uniform(2.0, 4.0))
    return p.kn, p.t


# ---- a kayaker's paddle ----

def kayak_paddle(rng, n_runs):
    """A kayaker's paddle shaft tilted (+ a right stroke, - a left one): for every run 6 ... 12 strokes alternating (to
    0.6 ... 1 in 0.35 ... 0.6 s, held 0.1 ... 0.3 s in the water), a sweep turn (to 0.8 ... 1 one side, held 0.6 ... 1.2
    s), a brace (to 0.5 ... 0.9 the other side in 0.2 ... 0.4 s) and the paddle across the deck (to 0 in 0.5 ... 0.9 s,
    held 2 ... 5 s). The full reach both ways in the first run. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(1.0, 2.0))
    for k in range(n_runs):
        sd = _side(rng)
        for j in range(int(rng.integers(6, 13))):
            p.to(rng.uniform(0.35, 0.6), sd * (1.0 if (k == 0 and j < 2) else rng.uniform(0.6, 1.0)))
            p.hold(rng.uniform(0.1, 0.3))
            sd = -sd
        p.to(rng.uniform(0.4, 0.7), sd * rng.uniform(0.8, 1.0))
        p.hold(rng.uniform(0.6, 1.2))
        p.to(rng.uniform(0.2, 0.4), -sd * rng.uniform(0.5, 0.9))
        p.to(rng.uniform(0.5, 0.9), 0.0)
        p.hold(rng.uniform(2.0, 5.0))
    return p.kn, p.t


# ---- a driver's accelerator in town (unipolar) ----

def town_throttle(rng, n_blocks):
    """A driver's accelerator pedal in town (0 off, 1 floored): for every block the lights (held 3 ... 8 s at 0), the
    pull away (to 0.5 ... 1 in 0.6 ... 1.2 s, held 1 ... 3 s), cruising (to 0.2 ... 0.45, held 3 ... 7 s, 1 ... 3 small
    changes of 0.05 ... 0.15, within 0.1 ... 0.6) and off for the next lights (to 0 in 0.4 ... 0.8 s). Floored at least
    once. Returns the knots and the end."""
    p = _Prog()
    full = int(rng.integers(0, n_blocks))
    for k in range(n_blocks):
        p.hold(rng.uniform(3.0, 8.0))
        p.to(rng.uniform(0.6, 1.2), 1.0 if k == full else rng.uniform(0.5, 1.0))
        p.hold(rng.uniform(1.0, 3.0))
        x = rng.uniform(0.2, 0.45)
        p.to(rng.uniform(0.5, 1.0), x)
        p.hold(rng.uniform(1.0, 3.0))
        for _ in range(int(rng.integers(1, 4))):
            x = min(max(x + _side(rng) * rng.uniform(0.05, 0.15), 0.1), 0.6)
            p.to(rng.uniform(0.4, 0.8), x)
            p.hold(rng.uniform(1.0, 2.5))
        p.to(rng.uniform(0.4, 0.8), 0.0)
    p.hold(rng.uniform(2.0, 4.0))
    return p.kn, p.t


# ---- a crane driver's joystick ----

def crane_joystick(rng, n_lifts):
    """A tower-crane driver's slewing joystick (+ right, toward the building, - left, back to the stack): for every lift
    the hook slung (held 2 ... 5 s at 0), inching to take up the load (2 ... 4 nudges of 0.05 ... 0.2 either way, 0.3
    ... 0.6 s, back to 0; 10 ... 14 of 0.03 ... 0.1 for the first lift's heavy load), the slew (to 0.6 ... 1 in 0.8 ...
    1.5 s, held 2 ... 5 s), slowed (to 0.1 ... 0.3 in 0.6 ... 1 s, held 1 ... 2 s), the counter swing's check (to 0.1
    ... 0.25 the other way, 0.4 ... 0.8 s) and released (to 0 in 0.4 ... 0.8 s). Every lift slews right, the first to
    the full reach, but the last, which slews back to the stack at the full reach left. Returns the knots and the
    end."""
    p = _Prog()
    for k in range(n_lifts):
        p.hold(rng.uniform(2.0, 5.0))
        for _ in range(int(rng.integers(10, 15)) if k == 0 else int(rng.integers(2, 5))):
            p.to(rng.uniform(0.3, 0.6), _side(rng) * rng.uniform(0.03, 0.1 if k == 0 else 0.2))
            p.to(rng.uniform(0.3, 0.6), 0.0)
        sd = -1.0 if k == n_lifts - 1 else 1.0
        p.to(rng.uniform(0.8, 1.5), sd * (1.0 if k in (0, n_lifts - 1) else rng.uniform(0.6, 1.0)))
        p.hold(rng.uniform(2.0, 5.0))
        p.to(rng.uniform(0.6, 1.0), sd * rng.uniform(0.1, 0.3))
        p.hold(rng.uniform(1.0, 2.0))
        p.to(rng.uniform(0.4, 0.8), -sd * rng.uniform(0.1, 0.25))
        p.to(rng.uniform(0.4, 0.8), 0.0)
    p.hold(rng.uniform(1.0, 2.0))
    return p.kn, p.t


# ---- a fencer's blade ----

def fencer_blade(rng, n_bouts):
    """A fencer's blade across the line (+ the sixte side, - the quarte): for every bout the en garde (held 1 ... 3 s
    at 0 ... 0.1), 3 ... 6 engagements (a beat or a parry, to 0.5 ... 1 one side in 0.15 ... 0.3 s, the riposte to 0.3
    ... 0.8 the other in 0.2 ... 0.35 s, held 0.2 ... 0.6 s), a feint's small moves (2 ... 4 of 0.1 ... 0.3 either side,
    0.2 ... 0.35 s) and the return to guard (to 0 in 0.5 ... 0.8 s, held 1 ... 3 s). The full reach both ways in the
    first bout. Returns the knots and the end."""
    p = _Prog()
    for k in range(n_bouts):
        p.to(rng.uniform(0.4, 0.7), _side(rng) * rng.uniform(0.0, 0.1))
        p.hold(rng.uniform(1.0, 3.0))
        for j in range(int(rng.integers(3, 7))):
            sd = (1.0 if j == 0 else -1.0) if k == 0 and j < 2 else _side(rng)
            p.to(rng.uniform(0.15, 0.3), sd * (1.0 if (k == 0 and j < 2) else rng.uniform(0.5, 1.0)))
            p.to(rng.uniform(0.2, 0.35), -sd * rng.uniform(0.3, 0.8))
            p.hold(rng.uniform(0.2, 0.6))
        for _ in range(int(rng.integers(2, 5))):
            p.to(rng.uniform(0.2, 0.35), _side(rng) * rng.uniform(0.1, 0.3))
        p.to(rng.uniform(0.5, 0.8), 0.0)
        p.hold(rng.uniform(1.0, 3.0))
    return p.kn, p.t


# ---- a fly fisher's rod ----

def fly_cast(rng, n_casts):
    """A fly fisher's rod tip (+ the forward cast, - the back cast): for every cast 2 ... 4 false casts (back to 0.6
    ... 1 in 0.3 ... 0.5 s, the pause for the line to straighten 0.2 ... 0.5 s, forward to 0.6 ... 1 in 0.3 ... 0.5 s,
    paused 0.2 ... 0.5 s), the delivery (to 0.2 ... 0.4 in 0.5 ... 0.8 s), the fly fished (the rod lowered to 0 in 1
    ... 2 s, held 3 ... 6 s with 0 ... 3 small twitches of 0.03 ... 0.1). The full reach both ways in the first cast.
    Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(1.0, 2.0))
    for k in range(n_casts):
        for j in range(int(rng.integers(2, 5))):
            full = k == 0 and j == 0
            p.to(rng.uniform(0.3, 0.5), -(1.0 if full else rng.uniform(0.6, 1.0)))
            p.hold(rng.uniform(0.2, 0.5))
            p.to(rng.uniform(0.3, 0.5), 1.0 if full else rng.uniform(0.6, 1.0))
            p.hold(rng.uniform(0.2, 0.5))
        p.to(rng.uniform(0.5, 0.8), rng.uniform(0.2, 0.4))
        p.to(rng.uniform(1.0, 2.0), 0.0)
        p.hold(rng.uniform(1.0, 2.0))
        for _ in range(int(rng.integers(0, 4))):
            p.to(0.2, rng.uniform(0.03, 0.1))
            p.to(0.3, 0.0)
            p.hold(rng.uniform(0.5, 1.0))
    p.hold(rng.uniform(1.0, 2.0))
    return p.kn, p.t

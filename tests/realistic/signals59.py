"""Signals of the HOLDOUT59 set (``cases_holdout59.py``): everyday scenes, each drawn from a generator here.

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


# ---- a glassblower's pipe (the clean case) ----

def glassblower_pipe(rng, n_gathers):
    """A glassblower rolling the blowpipe along the bench's rails (+ rolled out toward the tip, - back): for every
    gather the pipe laid on the rails (held 1 ... 2 s at 0), 5 ... 9 rolls alternating out and back (each to 0.5 ... 1
    in 0.5 ... 1.1 s, a short stop of 0.1 ... 0.3 s at its end while the jacks shape the glass), 2 ... 4 quick half
    rolls (0.1 ... 0.3 either side in 0.25 ... 0.4 s) and the pipe back to the middle (in 0.5 ... 0.9 s) for a puff of
    air (held 1 ... 2.5 s). The full roll both ways in the first gather. Returns the knots and the end."""
    p = _Prog()
    for g in range(n_gathers):
        p.hold(rng.uniform(1.0, 2.0))
        sd = _side(rng)
        for j in range(int(rng.integers(5, 10))):
            p.to(rng.uniform(0.5, 1.1), sd * (1.0 if (g == 0 and j < 2) else rng.uniform(0.5, 1.0)))
            p.hold(rng.uniform(0.1, 0.3))
            sd = -sd
        for _ in range(int(rng.integers(2, 5))):
            p.to(rng.uniform(0.25, 0.4), _side(rng) * rng.uniform(0.1, 0.3))
        p.to(rng.uniform(0.5, 0.9), 0.0)
        p.hold(rng.uniform(1.0, 2.5))
    return p.kn, p.t


# ---- a letterpress printer's impression lever (unipolar) ----

def letterpress_lever(rng, n_runs):
    """A printer's impression lever on a platen press (0 at rest, 1 the full pull): for every run of 6 ... 10 sheets,
    each the lever pulled (to 0.7 ... 1 in 0.5 ... 0.9 s), the impression dwelt (held 1.5 ... 4 s), the lever let back
    (to 0 in 0.4 ... 0.7 s) and the sheet taken out and the next fed (held 2 ... 4 s); after the run the forme
    re-inked (held 12 ... 20 s). The full pull at least once. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(1.0, 2.0))
    full = int(rng.integers(0, n_runs))
    for r in range(n_runs):
        for j in range(int(rng.integers(6, 11))):
            p.to(rng.uniform(0.5, 0.9), 1.0 if (r == full and j == 0) else rng.uniform(0.7, 1.0))
            p.hold(rng.uniform(1.5, 4.0))
            p.to(rng.uniform(0.4, 0.7), 0.0)
            p.hold(rng.uniform(2.0, 4.0))
        p.hold(rng.uniform(12.0, 20.0))
    return p.kn, p.t


# ---- a juggler's hand ----

def juggler_hand(rng, n_patterns):
    """A juggler's right hand across the body (+ out to the side, - in across), never still: for every pattern 10 ...
    18 throws and catches of a cascade (the hand swung in to -0.3 ... -0.6 for the throw and out to 0.3 ... 0.6 for the
    catch, 0.2 ... 0.35 s each way), then a flourish of 2 ... 3 wide sweeps (to 0.8 ... 1 each way in 0.35 ... 0.6 s).
    The full sweep both ways in the first pattern's flourish. No holds: no two knots alike in a row. Returns the knots
    and the end."""
    p = _Prog()
    p.to(0.4, 0.05)
    for k in range(n_patterns):
        for _ in range(int(rng.integers(10, 19))):
            p.to(rng.uniform(0.2, 0.35), -rng.uniform(0.3, 0.6))
            p.to(rng.uniform(0.2, 0.35), rng.uniform(0.3, 0.6))
        for j in range(int(rng.integers(2, 4))):
            a = 1.0 if (k == 0 and j == 0) else rng.uniform(0.8, 1.0)
            p.to(rng.uniform(0.35, 0.6), -a)
            p.to(rng.uniform(0.35, 0.6), a)
    p.to(rng.uniform(0.5, 0.8), 0.0)
    return p.kn, p.t


# ---- a bookbinder's nipping press (unipolar) ----

def nipping_press(rng, n_books):
    """A bookbinder's nipping press, its screw's pressure (0 open, 1 the hardest nip): for every book the screw turned
    down in 2 ... 4 steps (each 0.15 ... 0.4 more, in 0.6 ... 1.2 s, held 1 ... 3 s while the boards settle; the last to
    0.75 ... 1), the book nipped (held 8 ... 20 s) and the screw opened (to 0 in 0.8 ... 1.5 s); the book taken out and
    the next set up (held 6 ... 12 s). The hardest nip at least once. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(2.0, 4.0))
    full = int(rng.integers(0, n_books))
    for b in range(n_books):
        n = int(rng.integers(2, 5))
        top = 1.0 if b == full else rng.uniform(0.75, 1.0)
        x = 0.0
        for k in range(n):
            x = top if k == n - 1 else min(x + rng.uniform(0.15, 0.4), top)
            p.to(rng.uniform(0.6, 1.2), x)
            p.hold(rng.uniform(1.0, 3.0))
        p.hold(rng.uniform(8.0, 20.0))
        p.to(rng.uniform(0.8, 1.5), 0.0)
        p.hold(rng.uniform(6.0, 12.0))
    return p.kn, p.t


# ---- a table-tennis player's bat ----

def table_tennis_bat(rng, n_rallies):
    """A table-tennis player's bat across the table (+ the forehand side, - the backhand): for every rally the serve
    (the bat to 0.3 ... 0.5 either side in 0.4 ... 0.6 s, held 0.5 ... 1 s, through to 0 ... 0.2 the other way in
    0.2 ... 0.3 s), 4 ... 10 strokes (each to 0.6 ... 1 on a side, forehand or backhand at even odds, in 0.25 ... 0.45
    s, and back toward the ready position within 0.1 of 0 in 0.2 ... 0.35 s), then the ball fetched (the bat at 0, held
    3 ... 6 s). The full reach both ways in the first rally. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.5, 1.0))
    for r in range(n_rallies):
        sd = _side(rng)
        p.to(rng.uniform(0.4, 0.6), sd * rng.uniform(0.3, 0.5))
        p.hold(rng.uniform(0.5, 1.0))
        p.to(rng.uniform(0.2, 0.3), -sd * rng.uniform(0.0, 0.2))
        ends = [1.0, -1.0] if rng.uniform() < 0.5 else [-1.0, 1.0]
        for k in range(int(rng.integers(4, 11))):
            x = ends[k] if (r == 0 and k < 2) else _side(rng) * rng.uniform(0.6, 1.0)
            p.to(rng.uniform(0.25, 0.45), x)
            p.to(rng.uniform(0.2, 0.35), _side(rng) * rng.uniform(0.0, 0.1))
        p.to(rng.uniform(0.3, 0.5), 0.0)
        p.hold(rng.uniform(3.0, 6.0))
    return p.kn, p.t


# ---- a dentist's drill foot control (unipolar) ----

def dental_foot_control(rng, n_teeth):
    """A dentist's foot control for the drill (0 off, 1 the full speed): for every tooth 3 ... 6 bursts (each the pedal
    pressed to 0.5 ... 1 in 0.3 ... 0.6 s, held 1 ... 4 s with 0 ... 2 changes of speed of 0.1 ... 0.3 either way
    within 0.4 ... 1, in 0.3 ... 0.5 s, and let off to 0 in 0.2 ... 0.4 s, a look and a rinse, held 1.5 ... 4 s), then
    the tooth checked and the bur changed (held 6 ... 12 s). The full speed at least once. Returns the knots and the
    end."""
    p = _Prog()
    p.hold(rng.uniform(1.0, 2.0))
    full = int(rng.integers(0, n_teeth))
    for k in range(n_teeth):
        for j in range(int(rng.integers(3, 7))):
            x = 1.0 if (k == full and j == 0) else rng.uniform(0.5, 1.0)
            p.to(rng.uniform(0.3, 0.6), x)
            n_ch = int(rng.integers(0, 3))
            burst = rng.uniform(1.0, 4.0)
            for _ in range(n_ch):
                p.hold(burst / (n_ch + 1))
                x = float(np.clip(x + _side(rng) * rng.uniform(0.1, 0.3), 0.4, 1.0))
                p.to(rng.uniform(0.3, 0.5), x)
            p.hold(burst / (n_ch + 1))
            p.to(rng.uniform(0.2, 0.4), 0.0)
            p.hold(rng.uniform(1.5, 4.0))
        p.hold(rng.uniform(6.0, 12.0))
    return p.kn, p.t


# ---- a ship's engine-order telegraph ----

def engine_telegraph(rng, n_orders):
    """A ship's engine-order telegraph on the bridge while berthing (+ ahead, - astern; the orders dead slow 0.25,
    slow 0.5, half 0.75, full 1; stop 0): n_orders orders, each the handle swung to the new order (in 0.4 ... 0.9 s)
    and held while the engine answers and the ship moves (2 ... 7 s); never the same order twice in a row; full ahead
    and full astern both among the first five; the last order stop (held 3 ... 6 s). Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(1.0, 2.0))
    steps = np.array([-1.0, -0.75, -0.5, -0.25, 0.0, 0.25, 0.5, 0.75, 1.0])
    at = sorted(rng.choice(5, size=2, replace=False))
    ends = [1.0, -1.0] if rng.uniform() < 0.5 else [-1.0, 1.0]
    x = 0.0
    for k in range(n_orders):
        if k in at:
            new = ends[at.index(k)]
        else:
            new = x
            while new == x:
                new = float(steps[int(rng.integers(0, 9))])
        x = new
        p.to(rng.uniform(0.4, 0.9), x)
        p.hold(rng.uniform(2.0, 7.0))
    p.to(rng.uniform(0.4, 0.9), 0.0)
    p.hold(rng.uniform(3.0, 6.0))
    return p.kn, p.t


# ---- a sound engineer's pan pot ----

def pan_pot(rng, n_moves):
    """A sound engineer's pan pot on a mixing desk (+ right, - left): first the channel checked in the middle (for 10
    ... 16 s: nudges of 0.005 ... 0.03 either way, within 0.05 of the middle, in 0.3 ... 0.8 s, each held 1 ... 2.5 s
    while listening), then the mix's pans: each to a new place 0.2 ... 1 either side (at least 0.3 from the last; hard
    left and hard right among the first four) in 0.3 ... 1.5 s, held 1 ... 4 s; the pot back to the middle at the end
    (in 0.5 ... 1 s, held 2 ... 4 s). Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.5, 1.0))
    x, t_check = 0.0, rng.uniform(10.0, 16.0)
    while p.t < t_check:
        x = float(np.clip(x + _side(rng) * rng.uniform(0.005, 0.03), -0.05, 0.05))
        p.to(rng.uniform(0.3, 0.8), x)
        p.hold(rng.uniform(1.0, 2.5))
    at = sorted(rng.choice(4, size=2, replace=False))
    ends = [1.0, -1.0] if rng.uniform() < 0.5 else [-1.0, 1.0]
    for k in range(n_moves):
        if k in at:
            new = ends[at.index(k)]
        else:
            new = x
            while abs(new - x) < 0.3:
                new = _side(rng) * rng.uniform(0.2, 1.0)
        x = new
        p.to(rng.uniform(0.3, 1.5), x)
        p.hold(rng.uniform(1.0, 4.0))
    p.to(rng.uniform(0.5, 1.0), 0.0)
    p.hold(rng.uniform(2.0, 4.0))
    return p.kn, p.t


# ---- a signalman's points lever ----

def points_lever(rng, n_trains):
    """A signalman's lever for a pair of points (+ pulled over to reverse, - pushed home past normal against its
    stop), with long waits between trains: for every train the lever moved (to 0.7 ... 1 either way in 0.8 ... 1.5 s,
    the side turned about at even odds), held while the train passes (6 ... 14 s), eased back to its middle (to within
    0.1 of 0 in 0.6 ... 1 s) and held until the next train is offered (8 ... 16 s). The full throw both ways in the
    first four trains. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(2.0, 4.0))
    at = sorted(rng.choice(4, size=2, replace=False))
    ends = [1.0, -1.0] if rng.uniform() < 0.5 else [-1.0, 1.0]
    for k in range(n_trains):
        x = ends[at.index(k)] if k in at else _side(rng) * rng.uniform(0.7, 1.0)
        p.to(rng.uniform(0.8, 1.5), x)
        p.hold(rng.uniform(6.0, 14.0))
        p.to(rng.uniform(0.6, 1.0), _side(rng) * rng.uniform(0.0, 0.1))
        p.hold(rng.uniform(8.0, 16.0))
    p.to(rng.uniform(0.6, 1.0), 0.0)
    p.hold(rng.uniform(2.0, 4.0))
    return p.kn, p.t


# ---- a windsurfer's boom ----

def windsurfer_boom(rng, n_reaches):
    """A windsurfer's back hand on the boom (+ sheeted in, - eased out past the neutral, 0 the sail luffing): for every
    reach the sail sheeted in (to 0.5 ... 0.8 in 0.6 ... 1 s) and trimmed in the gusts (4 ... 8 trims of 0.05 ... 0.2
    either way within 0.3 ... 1, in 0.3 ... 0.7 s, held 0.5 ... 2 s), a gybe (the sail flipped: to -0.7 ... -1 in 0.4
    ... 0.7 s, held 0.3 ... 0.8 s) and the sail let luff to 0 (in 0.5 ... 1 s, held 2 ... 4 s). The full sheet-in and
    the full flip in the first reach. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(1.0, 2.0))
    for r in range(n_reaches):
        x = rng.uniform(0.5, 0.8)
        p.to(rng.uniform(0.6, 1.0), x)
        n = int(rng.integers(4, 9))
        for k in range(n):
            x = 1.0 if (r == 0 and k == n - 1) else float(np.clip(x + _side(rng) * rng.uniform(0.05, 0.2), 0.3, 1.0))
            p.to(rng.uniform(0.3, 0.7), x)
            p.hold(rng.uniform(0.5, 2.0))
        p.to(rng.uniform(0.4, 0.7), -(1.0 if r == 0 else rng.uniform(0.7, 1.0)))
        p.hold(rng.uniform(0.3, 0.8))
        p.to(rng.uniform(0.5, 1.0), 0.0)
        p.hold(rng.uniform(2.0, 4.0))
    return p.kn, p.t

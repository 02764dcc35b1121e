"""Signals of the HOLDOUT45 set (``cases_holdout45.py``): everyday scenes, each drawn from a generator here.

Every scene is a programme of knots (time, position) joined by moves; the evaluator takes any times (a record's grid or
a finer one) and returns the position, exactly the first knot's before the programme starts and the last's after it.
The move is the cam designer's "modified trapezoid" motion law (Neklutin's cam law, 1950s, as cam texts tabulate it;
written here from its definition and from memory): the acceleration rises as a quarter sine wave over the move's first
eighth, stays at its peak for a quarter, falls as a quarter sine wave over the next eighth, and the second half mirrors
the first with the sign reversed, so the move starts and ends at rest with zero acceleration; its peak acceleration is
8 pi / (2 + pi) = 4.888 and its peak speed 2 times a unit move's over its time (squared). Nothing here imports hystcomp.
"""

import math

import numpy as np

from .set_tools import Programme as _Prog, knots_at as _knots_at

#: the modified trapezoid's peak acceleration 8 pi / (2 + pi)
A_MT = 8.0 * math.pi / (2.0 + math.pi)


def modified_trapezoid(s):
    """The modified-trapezoid move 0 ... 1 over s in 0 ... 1 (clipped outside), its position in closed form: the
    acceleration A sin(4 pi s) over s < 1/8, A over 1/8 ... 3/8, A cos(4 pi (s - 3/8)) over 3/8 ... 1/2, integrated
    twice from rest; the second half x(s) = 1 - x(1 - s); A = 8 pi / (2 + pi)."""
    s = np.clip(np.asarray(s, float), 0.0, 1.0)
    A = A_MT
    k = 4.0 * math.pi
    h = np.minimum(s, 1.0 - s)
    # first eighth
    x1 = A * (h - np.sin(k * h) / k) / k
    v1 = A / k
    x1e = A * (0.125 - 1.0 / k) / k
    # the constant acceleration, w = h - 1/8 in 0 ... 1/4
    w = h - 0.125
    x2 = x1e + v1 * w + 0.5 * A * w * w
    v2 = v1 + 0.25 * A
    x2e = x1e + 0.25 * v1 + A / 32.0
    # the falling quarter sine, w = h - 3/8 in 0 ... 1/8
    w3 = h - 0.375
    x3 = x2e + v2 * w3 + A * (1.0 - np.cos(k * w3)) / (k * k)
    xh = np.where(h < 0.125, x1, np.where(h < 0.375, x2, x3))
    return np.where(s <= 0.5, xh, 1.0 - xh)


def knots_at(t, knots):
    """The position on times t through knots [(time, position), ...] joined by modified-trapezoid moves; the first
    knot's position before it, the last's after."""
    return _knots_at(t, knots, modified_trapezoid)


def _side(rng):
    return 1.0 if rng.uniform() < 0.5 else -1.0


# ---- pinball flippers (the clean case) ----

def pinball(rng, n_balls):
    """A pinball player's flippers (+ the right flipper up, - the left): for every ball, flicks of one flipper or the
    other (up to 0.85 ... 1 in 0.05 ... 0.09 s, back in 0.08 ... 0.15 s), now and then a cradle (the flipper held up
    0.6 ... 2 s, then let down), pauses between shots (0.3 ... 1.2 s at rest); between balls the plunger's pull (at rest
    2 ... 4 s). Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.5, 1.0))
    for _ in range(n_balls):
        for _ in range(int(rng.integers(6, 12))):
            sd = _side(rng)
            p.to(rng.uniform(0.05, 0.09), sd * rng.uniform(0.85, 1.0))
            if rng.uniform() < 0.3:
                p.hold(rng.uniform(0.6, 2.0))
            p.to(rng.uniform(0.08, 0.15), 0.0)
            p.hold(rng.uniform(0.3, 1.2))
        p.hold(rng.uniform(2.0, 4.0))
    return p.kn, p.t


# ---- a bookbinder's nipping press (unipolar) ----

def nipping_press(rng, n_books):
    """A bookbinder's nipping press (0 open, 1 screwed fully down): for every book, screwed down in turns of the
    handle (each 0.1 ... 0.2 of the travel in 0.4 ... 0.7 s, the grip changed between turns, 0.2 ... 0.5 s), to 0.6 ...
    1 (fully down once at least), held while the glue sets (12 ... 25 s), eased off a little now and then to check the
    spine (to 0.6 ... 0.8 of the setting, 6 ... 10 s), then opened (1 ... 2 s) and left open while the next is set in
    (3 ... 6 s). Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(1.0, 2.0))
    tops = rng.uniform(0.6, 1.0, n_books)
    tops[int(rng.integers(0, n_books))] = 1.0
    for top in tops:
        h = 0.0
        while h < top - 1e-9:
            h = min(top, h + rng.uniform(0.1, 0.2))
            p.to(rng.uniform(0.4, 0.7), h)
            p.hold(rng.uniform(0.2, 0.5))
        p.hold(rng.uniform(12.0, 25.0))
        if rng.uniform() < 0.5:
            p.to(rng.uniform(0.5, 1.0), h * rng.uniform(0.6, 0.8))
            p.hold(rng.uniform(6.0, 10.0))
        p.to(rng.uniform(1.0, 2.0), 0.0)
        p.hold(rng.uniform(3.0, 6.0))
    return p.kn, p.t


# ---- a snowboarder's run ----

def snowboard(rng, n_runs):
    """A snowboard's edge angle (+ toe side, - heel side): for every pitch of the run, carved turns (edge to edge,
    0.8 ... 1 of the reach, 0.7 ... 1.3 s a turn), then quick short swings down a steep part (0.5 ... 0.8 of the reach,
    0.06 ... 0.1 s an edge change, 10 ... 20 of them), then a skid to a stop (flat, held 1 ... 2 s). Returns the knots
    and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.4, 0.8))
    for _ in range(n_runs):
        sd = _side(rng)
        for k in range(int(rng.integers(3, 6))):
            p.to(rng.uniform(0.7, 1.3), (sd if k % 2 == 0 else -sd) * rng.uniform(0.8, 1.0))
        a = rng.uniform(0.5, 0.8)
        for k in range(int(rng.integers(10, 21))):
            p.to(rng.uniform(0.06, 0.1), (a if k % 2 == 0 else -a) * rng.uniform(0.85, 1.0))
        p.to(rng.uniform(0.3, 0.5), 0.0)
        p.hold(rng.uniform(1.0, 2.0))
    return p.kn, p.t


# ---- a paper guillotine (unipolar) ----

def guillotine(rng, n_cuts):
    """A print shop's lever guillotine's handle (0 down, 1 up): for every cut, raised (0.7 ... 1.2 s) to 0.7 ... 1 (its
    top once at least), held while the stack is squared and clamped (1.5 ... 4 s), brought down through the cut (0.25
    ... 0.45 s) and left down while the stack is turned (1 ... 5 s). Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(1.0, 2.0))
    tops = rng.uniform(0.7, 1.0, n_cuts)
    tops[int(rng.integers(0, n_cuts))] = 1.0
    for top in tops:
        p.to(rng.uniform(0.7, 1.2), top)
        p.hold(rng.uniform(1.5, 4.0))
        p.to(rng.uniform(0.25, 0.45), 0.0)
        p.hold(rng.uniform(1.0, 5.0))
    return p.kn, p.t


# ---- a lever windlass ----

def windlass(rng, n_hauls):
    """A yacht's lever windlass's handle pumped to haul the anchor (+ forward, - back): for every haul, full strokes
    (0.75 ... 1 of the reach each way, 0.6 ... 1.0 s each), 4 ... 8 of them, then a rest at the middle (1 ... 3 s) while
    the chain is checked. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.5, 1.0))
    for _ in range(n_hauls):
        sd = _side(rng)
        for k in range(int(rng.integers(4, 9))):
            p.to(rng.uniform(0.6, 1.0), sd * rng.uniform(0.75, 1.0))
            p.to(rng.uniform(0.6, 1.0), -sd * rng.uniform(0.75, 1.0))
        p.to(rng.uniform(0.4, 0.7), 0.0)
        p.hold(rng.uniform(1.0, 3.0))
    return p.kn, p.t


# ---- a guitarist's whammy bar ----

def whammy_bar(rng, n_licks):
    """A guitarist's tremolo arm (+ pulled up, - dived): for every lick, a dive (to 0.85 ... 1 down in 0.3 ... 0.6 s)
    and back, a pull-up (0.85 ... 1 up) and back, and a shimmer of vibrato about the middle (5 ... 7 a second, 0.1 ...
    0.25 of the reach, 6 ... 14 swings), then rest (0.5 ... 1.5 s). Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.4, 0.8))
    for _ in range(n_licks):
        for sd in ((-1.0, 1.0) if rng.uniform() < 0.5 else (1.0, -1.0)):
            p.to(rng.uniform(0.3, 0.6), sd * rng.uniform(0.85, 1.0))
            p.hold(rng.uniform(0.1, 0.4))
            p.to(rng.uniform(0.3, 0.6), 0.0)
        f, a = rng.uniform(5.0, 7.0), rng.uniform(0.1, 0.25)
        for k in range(int(rng.integers(6, 15))):
            p.to(0.5 / f, a if k % 2 == 0 else -a)
        p.to(0.5 / f, 0.0)
        p.hold(rng.uniform(0.5, 1.5))
    return p.kn, p.t


# ---- an office stapler (unipolar) ----

def stapler(rng, n_stacks):
    """An office stapler's top (0 up, 1 pressed through): for every stack of papers, staples pressed (down to 0.85 ...
    1 in 0.08 ... 0.16 s, through once at least, let up in 0.1 ... 0.2 s), 2 ... 4 of them 0.4 ... 1.2 s apart, then
    the stack put aside and the next squared (2 ... 4 s), a refill now and then (the top opened: held at 0 for 4 ... 7
    s). Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.8, 1.5))
    full = int(rng.integers(0, n_stacks))
    for j in range(n_stacks):
        for k in range(int(rng.integers(2, 5))):
            d = 1.0 if (j == full and k == 0) else rng.uniform(0.85, 1.0)
            p.to(rng.uniform(0.08, 0.16), d)
            p.to(rng.uniform(0.1, 0.2), 0.0)
            p.hold(rng.uniform(0.4, 1.2))
        p.hold(rng.uniform(2.0, 4.0))
        if rng.uniform() < 0.2:
            p.hold(rng.uniform(4.0, 7.0))
    return p.kn, p.t


# ---- an abacus ----

def abacus(rng, n_sums):
    """An abacus's beads under a reckoner's finger (+ pushed up, - down): first the beads nudged into place (three bouts
    of small moves, 0.01 ... 0.03 of the reach, 0.15 ... 0.3 s each, 6 ... 12 a bout, 0.5 ... 1 s apart), then sums
    flicked across (to 0.8 ... 1 either way in 0.12 ... 0.25 s, 0.2 ... 0.6 s between), each sum ended at the middle (1
    ... 2 s). Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.5, 1.0))
    for _ in range(3):
        for _ in range(int(rng.integers(6, 13))):
            p.to(rng.uniform(0.15, 0.3), _side(rng) * rng.uniform(0.01, 0.03))
        p.to(0.2, 0.0)
        p.hold(rng.uniform(0.5, 1.0))
    for _ in range(n_sums):
        for _ in range(int(rng.integers(4, 9))):
            p.to(rng.uniform(0.12, 0.25), _side(rng) * rng.uniform(0.8, 1.0))
            p.hold(rng.uniform(0.2, 0.6))
        p.to(rng.uniform(0.2, 0.4), 0.0)
        p.hold(rng.uniform(1.0, 2.0))
    return p.kn, p.t


# ---- a speed skater ----

def speed_skater(rng, n_laps):
    """A speed skater's hips (+ over the right skate, - the left): a warm-up of small shuffles first (0.03 ... 0.08 of
    the reach, 0.3 ... 0.5 s each, 10 ... 20 of them), then for every lap strides (0.8 ... 1 of the reach each side,
    0.35 ... 0.6 s a stride, 8 ... 14 of them) and crossovers on the bend (quicker: 0.5 ... 0.75 of the reach, 0.15 ...
    0.25 s each, 6 ... 10 of them), a glide at the middle between laps (1 ... 2 s). Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.5, 1.0))
    for k in range(int(rng.integers(10, 21))):
        p.to(rng.uniform(0.3, 0.5), (1 if k % 2 == 0 else -1) * rng.uniform(0.03, 0.08))
    p.to(0.3, 0.0)
    p.hold(rng.uniform(0.5, 1.0))
    for _ in range(n_laps):
        sd = _side(rng)
        for k in range(int(rng.integers(8, 15))):
            p.to(rng.uniform(0.35, 0.6), (sd if k % 2 == 0 else -sd) * rng.uniform(0.8, 1.0))
        for k in range(int(rng.integers(6, 11))):
            p.to(rng.uniform(0.15, 0.25), (1 if k % 2 == 0 else -1) * rng.uniform(0.5, 0.75))
        p.to(rng.uniform(0.3, 0.5), 0.0)
        p.hold(rng.uniform(1.0, 2.0))
    return p.kn, p.t


# ---- a glassblower rolling the pipe ----

def glassblower(rng, n_gathers):
    """A glassblower's blowpipe rolled on the bench's rails (+ rolled out, - back): for every gather, long rolls back
    and forth (0.7 ... 1 of the reach, 0.8 ... 1.4 s each) while the glass is shaped, 4 ... 8 of them, then the pipe
    held still at the middle for a puff (1 ... 2.5 s). Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.5, 1.0))
    for _ in range(n_gathers):
        sd = _side(rng)
        for k in range(int(rng.integers(4, 9))):
            p.to(rng.uniform(0.8, 1.4), (sd if k % 2 == 0 else -sd) * rng.uniform(0.7, 1.0))
        p.to(rng.uniform(0.4, 0.7), 0.0)
        p.hold(rng.uniform(1.0, 2.5))
    return p.kn, p.t

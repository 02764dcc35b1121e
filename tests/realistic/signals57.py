"""Signals of the HOLDOUT57 set (``cases_holdout57.py``): everyday scenes, each drawn from a generator here.

Every scene is a programme of knots (time, position) joined by moves; the evaluator takes any times (a record's grid or
a finer one) and returns the position, exactly the first knot's before the programme starts and the last's after it. The
move is the cycloidal rise of cam design, written from its definition: the follower's acceleration one period of a sine
over the move, so that it starts and ends at rest with no jump of acceleration (the cycloidal motion law; Rothbart, Cam
Design Handbook, 2004, as remembered):

    R(s) = s - sin(2 pi s) / (2 pi),  s in 0 ... 1,

its speed 1 - cos(2 pi s) (peak 2 at mid-move, twice the mean). Nothing here imports hystcomp.
"""

import math

import numpy as np

from .set_tools import Programme as _Prog, knots_at as _knots_at


def reach(s):
    """The move 0 ... 1 over s in 0 ... 1 (0 before, 1 after): the cycloidal rise s - sin(2 pi s) / (2 pi)."""
    s = np.clip(np.asarray(s, float), 0.0, 1.0)
    return s - np.sin(2.0 * math.pi * s) / (2.0 * math.pi)


def reach_speed(s):
    """The move's speed (a unit move over a unit time) at s in [0, 1]: 1 - cos(2 pi s)."""
    return 1.0 - np.cos(2.0 * math.pi * np.asarray(s, float))


def knots_at(t, knots):
    """The position on times t through knots [(time, position), ...] joined by cycloidal moves; the first knot's
    position before it, the last's after."""
    return _knots_at(t, knots, reach)


def _side(rng):
    """A side drawn at even odds: +1 or -1 (one uniform draw)."""
    return 1.0 if rng.uniform() < 0.5 else -1.0


# ---- an orchestra's cymbal player (the clean case) ----

def cymbal_player(rng, n_pieces):
    """A cymbal player's right plate (+ struck forward, - drawn back): for every piece the rests (held 3 ... 6 s at 0),
    the plates raised to the ready (0.1 ... 0.2 either way in 0.6 ... 1 s, held 1 ... 2 s), 3 ... 6 crashes (drawn back
    to -0.5 ... -1 in 0.4 ... 0.7 s, struck to 0.6 ... 1 in 0.15 ... 0.3 s, the plates held up to ring 1 ... 3 s, the
    ring choked back to 0 ... 0.15 in 0.3 ... 0.6 s) and the plates lowered (to 0 in 0.8 ... 1.5 s). The full reach
    both ways in the first piece's first crash. Returns the knots and the end."""
    p = _Prog()
    for k in range(n_pieces):
        p.hold(rng.uniform(3.0, 6.0))
        p.to(rng.uniform(0.6, 1.0), _side(rng) * rng.uniform(0.1, 0.2))
        p.hold(rng.uniform(1.0, 2.0))
        for j in range(int(rng.integers(3, 7))):
            first = k == 0 and j == 0
            p.to(rng.uniform(0.4, 0.7), -(1.0 if first else rng.uniform(0.5, 1.0)))
            p.to(rng.uniform(0.15, 0.3), 1.0 if first else rng.uniform(0.6, 1.0))
            p.hold(rng.uniform(1.0, 3.0))
            p.to(rng.uniform(0.3, 0.6), rng.uniform(0.0, 0.15))
        p.to(rng.uniform(0.8, 1.5), 0.0)
    p.hold(rng.uniform(2.0, 4.0))
    return p.kn, p.t


# ---- a letterpress printer's impression lever (unipolar) ----

def letterpress(rng, n_sheets):
    """A printer's impression lever on a tabletop letterpress (0 at rest, 1 the full impression): for every sheet the
    lever pulled (to 0.7 ... 1 in 0.5 ... 0.9 s), the impression held (2 ... 5 s), the lever let back (to 0 in 0.4 ...
    0.8 s) and the sheet changed and the forme inked (held 4 ... 9 s); every 5 ... 8 sheets the ink replenished on the
    disc (held 15 ... 25 s). The full impression at least once. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(1.0, 3.0))
    full = int(rng.integers(0, n_sheets))
    ink = int(rng.integers(5, 9))
    for k in range(n_sheets):
        p.to(rng.uniform(0.5, 0.9), 1.0 if k == full else rng.uniform(0.7, 1.0))
        p.hold(rng.uniform(2.0, 5.0))
        p.to(rng.uniform(0.4, 0.8), 0.0)
        p.hold(rng.uniform(4.0, 9.0))
        ink -= 1
        if ink == 0:
            p.hold(rng.uniform(15.0, 25.0))
            ink = int(rng.integers(5, 9))
    return p.kn, p.t


# ---- a bongo player's hands ----

def bongo_player(rng, n_phrases):
    """A bongo player's weight between the two drums (+ the hembra, the larger, - the macho), never still: for every
    phrase a martillo (8 ... 16 strokes alternating about a lean of 0.1 ... 0.3 to one side, 0.15 ... 0.4 either way of
    it, 0.15 ... 0.3 s each), a fill (4 ... 8 strokes across, to 0.6 ... 1 each way in turn, 0.2 ... 0.4 s each) and a
    slap with a flourish (to 0.7 ... 1 on one side in 0.3 ... 0.5 s and back to within 0.2 of the middle in 0.4 ... 0.7
    s). The full reach both ways in the first fill. No holds: no two knots alike in a row. Returns the knots and the
    end."""
    p = _Prog()
    p.to(0.4, 0.05)
    for ph in range(n_phrases):
        lean = _side(rng) * rng.uniform(0.1, 0.3)
        sd = _side(rng)
        for _ in range(int(rng.integers(8, 17))):
            p.to(rng.uniform(0.15, 0.3), lean + sd * rng.uniform(0.15, 0.4))
            sd = -sd
        for j in range(int(rng.integers(4, 9))):
            a = 1.0 if (ph == 0 and j < 2) else rng.uniform(0.6, 1.0)
            p.to(rng.uniform(0.2, 0.4), sd * a)
            sd = -sd
        p.to(rng.uniform(0.3, 0.5), _side(rng) * rng.uniform(0.7, 1.0))
        x_new = _side(rng) * rng.uniform(0.02, 0.2)
        p.to(rng.uniform(0.4, 0.7), x_new)
    p.to(rng.uniform(0.5, 0.8), 0.0)
    return p.kn, p.t


# ---- a soda siphon (unipolar) ----

def soda_siphon(rng, n_rounds):
    """A bartender's soda siphon lever (0 shut, 1 pressed fully): for every round of drinks 3 ... 6 glasses topped up,
    each a press (to 0.5 ... 1 in 0.2 ... 0.4 s), a squirt held 1 ... 3 s (0 ... 2 eased changes of 0.05 ... 0.15 either
    way, within 0.3 ... 1, in 0.2 ... 0.4 s), the lever let go (to 0 in 0.15 ... 0.3 s) and the next glass (held 2 ... 5
    s); after the round the drinks served (held 20 ... 35 s). The full press at least once. Returns the knots and the
    end."""
    p = _Prog()
    p.hold(rng.uniform(2.0, 4.0))
    full = int(rng.integers(0, n_rounds))
    for k in range(n_rounds):
        for j in range(int(rng.integers(3, 7))):
            x = 1.0 if (k == full and j == 0) else rng.uniform(0.5, 1.0)
            p.to(rng.uniform(0.2, 0.4), x)
            squirt = rng.uniform(1.0, 3.0)
            eases = int(rng.integers(0, 3))
            part = squirt / (eases + 1)
            p.hold(part)
            while eases > 0:
                x = min(max(x + rng.uniform(0.05, 0.15) * _side(rng), 0.3), 1.0)
                p.to(rng.uniform(0.2, 0.4), x)
                p.hold(part)
                eases -= 1
            p.to(rng.uniform(0.15, 0.3), 0.0)
            p.hold(rng.uniform(2.0, 5.0))
        p.hold(rng.uniform(20.0, 35.0))
    return p.kn, p.t


# ---- a bodhran player's tipper ----

def bodhran_tipper(rng, n_tunes):
    """A bodhran player's tipper (+ the down-stroke, - the up-stroke): for every tune 10 ... 20 strokes in a jig's
    triplets (down, up, down, the first of each triplet the stronger: 0.7 ... 1 against 0.4 ... 0.7, 0.12 ... 0.25 s
    each), a roll of the tune's ending (to 0.2 ... 0.4 either way, 4 ... 8 strokes of 0.08 ... 0.15 s), the tipper at
    rest (to 0 in 0.3 ... 0.6 s, held 3 ... 7 s between tunes). The full reach both ways in the first triplet. Returns
    the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.5, 1.5))
    for tn in range(n_tunes):
        n = int(rng.integers(10, 21))
        for j in range(n):
            strong = j % 3 == 0
            a = 1.0 if (tn == 0 and j < 2) else (rng.uniform(0.7, 1.0) if strong else rng.uniform(0.4, 0.7))
            p.to(rng.uniform(0.12, 0.25), a if j % 2 == 0 else -a)
        sd = _side(rng)
        for _ in range(int(rng.integers(4, 9))):
            p.to(rng.uniform(0.08, 0.15), sd * rng.uniform(0.2, 0.4))
            sd = -sd
        p.to(rng.uniform(0.3, 0.6), 0.0)
        p.hold(rng.uniform(3.0, 7.0))
    return p.kn, p.t


# ---- a bulldozer's blade lever ----

def bulldozer_blade(rng, n_passes):
    """A bulldozer driver's blade lever (+ the blade raised, - lowered into the ground): for every pass the blade set to
    cut (to -0.5 ... -1 in 0.5 ... 1 s), held through the push (3 ... 6 s, with 1 ... 3 trims of 0.05 ... 0.2 either
    way in 0.3 ... 0.6 s, within -1 ... -0.2), raised to spread the load (to 0.5 ... 1 in 0.5 ... 1 s, held 1 ... 3 s)
    and floated back (to 0 in 0.5 ... 1 s) for the reverse to the next pass (held 3 ... 6 s). The full reach both ways
    in the first pass. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(1.0, 2.0))
    for k in range(n_passes):
        x = -(1.0 if k == 0 else rng.uniform(0.5, 1.0))
        p.to(rng.uniform(0.5, 1.0), x)
        push = rng.uniform(3.0, 6.0)
        n_tr = int(rng.integers(1, 4))
        for _ in range(n_tr):
            p.hold(push / (n_tr + 1))
            x = float(np.clip(x + _side(rng) * rng.uniform(0.05, 0.2), -1.0, -0.2))
            p.to(rng.uniform(0.3, 0.6), x)
        p.hold(push / (n_tr + 1))
        p.to(rng.uniform(0.5, 1.0), 1.0 if k == 0 else rng.uniform(0.5, 1.0))
        p.hold(rng.uniform(1.0, 3.0))
        p.to(rng.uniform(0.5, 1.0), 0.0)
        p.hold(rng.uniform(3.0, 6.0))
    return p.kn, p.t


# ---- a welder's foot pedal (unipolar) ----

def welding_pedal(rng, n_beads):
    """A TIG welder's amperage pedal (0 off, 1 full current): for every bead the arc struck and the puddle formed (to
    0.6 ... 1 in 0.3 ... 0.6 s, held 1 ... 2 s), the bead run with the pedal pulsed for the filler (5 ... 10 pulses of
    0.1 ... 0.25 down from the puddle's current and back, 0.2 ... 0.4 s each way), the crater filled (to 0.2 ... 0.35 in
    0.5 ... 1 s, held 0.5 ... 1 s), the arc off (to 0 in 0.2 ... 0.4 s) and the torch moved and the work checked (held
    4 ... 9 s). The full current at least once. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(1.0, 2.0))
    full = int(rng.integers(0, n_beads))
    for k in range(n_beads):
        x = 1.0 if k == full else rng.uniform(0.6, 1.0)
        p.to(rng.uniform(0.3, 0.6), x)
        p.hold(rng.uniform(1.0, 2.0))
        for _ in range(int(rng.integers(5, 11))):
            p.to(rng.uniform(0.2, 0.4), x - rng.uniform(0.1, 0.25))
            p.to(rng.uniform(0.2, 0.4), x)
        p.to(rng.uniform(0.5, 1.0), rng.uniform(0.2, 0.35))
        p.hold(rng.uniform(0.5, 1.0))
        p.to(rng.uniform(0.2, 0.4), 0.0)
        p.hold(rng.uniform(4.0, 9.0))
    return p.kn, p.t


# ---- a surveyor's theodolite ----

def theodolite(rng, n_targets):
    """A surveyor's theodolite, its horizontal circle (+ clockwise of the reference mark, - anticlockwise; the reach a
    quarter turn): first the instrument levelled and the reference mark sighted (for 14 ... 20 s: the tangent screw
    turned 0.005 ... 0.03 either way, within 0.05 of the mark, in 0.4 ... 1 s, held 1 ... 2.5 s), held on the mark (2
    ... 4 s), then the round of targets: each swung to (0.3 ... 1 either way, at least 0.3 from the last, in 0.8 ... 2
    s), fine-pointed (0 ... 2 touches of 0.005 ... 0.02 in 0.3 ... 0.6 s) and read (held 2 ... 5 s); the top and the
    bottom of the reach in the first four targets; back to the mark at the end (in 1 ... 2 s, held 2 ... 4 s). Returns
    the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.5, 1.0))
    t_lev = rng.uniform(14.0, 20.0)
    screw = 0.0
    while p.t < t_lev:
        screw = min(max(screw + rng.uniform(0.005, 0.03) * _side(rng), -0.05), 0.05)
        p.to(rng.uniform(0.4, 1.0), screw)
        p.hold(rng.uniform(1.0, 2.5))
    p.to(rng.uniform(0.5, 1.0), 0.0)
    p.hold(rng.uniform(2.0, 4.0))
    sweep = (1.0, -1.0) if rng.uniform() < 0.5 else (-1.0, 1.0)
    forced = dict(zip(sorted(rng.choice(4, size=2, replace=False)), sweep))
    x = 0.0
    for k in range(n_targets):
        if k in forced:
            new = forced[k]
        else:
            new = x
            while abs(new - x) < 0.3:
                new = _side(rng) * rng.uniform(0.3, 1.0)
        x = new
        p.to(rng.uniform(0.8, 2.0), x)
        for _ in range(int(rng.integers(0, 3))):
            x = float(np.clip(x + _side(rng) * rng.uniform(0.005, 0.02), -1.0, 1.0))
            p.to(rng.uniform(0.3, 0.6), x)
        p.hold(rng.uniform(2.0, 5.0))
    p.to(rng.uniform(1.0, 2.0), 0.0)
    p.hold(rng.uniform(2.0, 4.0))
    return p.kn, p.t


# ---- a trombonist's slide ----

def trombone_slide(rng, n_phrases):
    """A trombonist's slide about its middle (fourth) position (+ out toward the seventh, - in toward the first; the
    positions 1 ... 7 at (pos - 4) / 3 of the reach): for every phrase 6 ... 12 notes, each at a position 1 ... 7
    (moved to in 0.15 ... 0.35 s, one in four a glissando of 0.6 ... 1.2 s), held for the note (0.3 ... 1.5 s, one in
    three with a vibrato of 3 ... 6 wiggles of 0.02 ... 0.04 either way, 0.15 ... 0.25 s each); after the phrase the
    slide back to the middle (in 0.4 ... 0.8 s) for the breath (held 2 ... 4 s). The first and the seventh positions in
    the first phrase. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(1.0, 2.0))
    for ph in range(n_phrases):
        n = int(rng.integers(6, 13))
        forced = {0: 1, 1: 7} if ph == 0 else {}
        for j in range(n):
            pos = forced.get(j, int(rng.integers(1, 8)))
            x = (pos - 4) / 3.0
            p.to(rng.uniform(0.6, 1.2) if rng.uniform() < 0.25 else rng.uniform(0.15, 0.35), x)
            dur = rng.uniform(0.3, 1.5)
            if rng.uniform() < 1 / 3:
                sd = _side(rng)
                for _ in range(int(rng.integers(3, 7))):
                    p.to(rng.uniform(0.15, 0.25), float(np.clip(x + sd * rng.uniform(0.02, 0.04), -1.0, 1.0)))
                    sd = -sd
                p.to(0.15, x)
            p.hold(dur)
        p.to(rng.uniform(0.4, 0.8), 0.0)
        p.hold(rng.uniform(2.0, 4.0))
    return p.kn, p.t


# ---- a stage-combat fight ----

def stage_combat(rng, n_phrases):
    """A stage fighter's sword arm in a rehearsed fight (+ the cut to the right, - to the left): for every phrase of the
    choreography 4 ... 8 cuts and parries (each to 0.5 ... 1 on the other side from the last, in 0.3 ... 0.6 s, the
    blades held at the contact 0.2 ... 0.5 s), then the fighters reset (to 0 in 0.8 ... 1.5 s, held 3 ... 6 s while the
    director gives notes). The full reach both ways in the first phrase. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(1.0, 2.0))
    for ph in range(n_phrases):
        sd = _side(rng)
        for j in range(int(rng.integers(4, 9))):
            p.to(rng.uniform(0.3, 0.6), sd * (1.0 if (ph == 0 and j < 2) else rng.uniform(0.5, 1.0)))
            p.hold(rng.uniform(0.2, 0.5))
            sd = -sd
        p.to(rng.uniform(0.8, 1.5), 0.0)
        p.hold(rng.uniform(3.0, 6.0))
    return p.kn, p.t

"""Signals of the HOLDOUT41 set (``cases_holdout41.py``): everyday scenes, each drawn from a generator here.

Every scene is a programme of knots (time, position) joined by moves; the evaluator takes any times (a record's grid or
a finer one) and returns the position, exactly the first knot's before the programme starts and the last's after it. The
moves: a harmonic (cosine) move (1 - cos(pi s)) / 2, a hand's or a lever's relaxed move, or a quintic (minimum-jerk)
move 10 s^3 - 15 s^4 + 6 s^5 (zero speed and acceleration at both ends: Flash & Hogan, J. Neurosci. 5 (1985) 1688, from
memory). Nothing here imports hystcomp.
"""

import math

import numpy as np

from .set_tools import Programme as _Prog, knots_at as _knots_at


def harmonic(s):
    """The harmonic move 0 ... 1 over s in 0 ... 1 (clipped outside)."""
    s = np.clip(np.asarray(s, float), 0.0, 1.0)
    return 0.5 - 0.5 * np.cos(math.pi * s)


def quintic(s):
    """The minimum-jerk move 0 ... 1 over s in 0 ... 1 (clipped outside)."""
    s = np.clip(np.asarray(s, float), 0.0, 1.0)
    return s * s * s * (10.0 - 15.0 * s + 6.0 * s * s)


def knots_at(t, knots, kind="quintic"):
    """The position on times t through knots [(time, position), ...] joined by quintic (kind "quintic") or harmonic
    ("harmonic") moves; the first knot's position before it, the last's after."""
    return _knots_at(t, knots, quintic if kind == "quintic" else harmonic)


# ---- an oscillating desk fan (the clean case) ----

def desk_fan(rng):
    """The fan head's yaw about the middle of its sweep: started at the middle, oscillating on speed settings 1, 2 and
    3 (sweep periods 2.6 ... 3.2, 1.9 ... 2.3 and 1.4 ... 1.7 s in the rig's time), pinned still now and then by the
    user (holds of 0.6 ... 1.5 s at wherever it is), a narrower sweep when the knob is half pulled, back to the middle
    at the end. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.4, 0.8))
    for period in (rng.uniform(2.6, 3.2), rng.uniform(1.9, 2.3), rng.uniform(1.4, 1.7)):
        for _ in range(int(rng.integers(3, 5))):
            width = 1.0 if rng.uniform() > 0.25 else rng.uniform(0.4, 0.6)
            p.to(period / 2 * rng.uniform(0.97, 1.03), width * rng.uniform(0.97, 1.0))
            if rng.uniform() < 0.25:
                p.hold(rng.uniform(0.6, 1.5))
            p.to(period / 2 * rng.uniform(0.97, 1.03), -width * rng.uniform(0.97, 1.0))
    p.to(rng.uniform(0.7, 1.0), 0.0)
    p.hold(0.5)
    return p.kn, p.t


# ---- a forklift stacking pallets (unipolar) ----

def forklift_shelves(rng, n_pallets):
    """The forks' height (0 on the floor, 1 at the top shelf): for every pallet, raised to a shelf of 1 ... 5 (the top
    one once at least), held while the pallet is pushed in (5 ... 12 s), lowered to the floor and held while the next is
    fetched (4 ... 9 s). Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(1.0, 2.0))
    shelves = rng.integers(1, 6, n_pallets)
    shelves[int(rng.integers(0, n_pallets))] = 5
    for sh in shelves:
        p.to(rng.uniform(1.2, 2.5) * sh / 5 + 0.4, sh / 5)
        p.hold(rng.uniform(5.0, 12.0))
        p.to(rng.uniform(1.0, 2.0) * sh / 5 + 0.4, 0.0)
        p.hold(rng.uniform(4.0, 9.0))
    return p.kn, p.t


# ---- shaking a spray can ----

def spray_can(rng, n_rounds):
    """The can's tilt: rounds of a slow tilt to either side (0.8 ... 1.4 s each way), then a bout of fast shaking (the
    ball rattling: 4 ... 6 shakes a second, 8 ... 16 shakes, near the full tilt), a rest upright (0.5 ... 1 s). Returns
    the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.3, 0.6))
    for _ in range(n_rounds):
        for side in (1.0, -1.0):
            p.to(rng.uniform(0.8, 1.4), side * rng.uniform(0.9, 1.0))
        p.to(rng.uniform(0.5, 0.9), 0.0)
        f = rng.uniform(4.0, 6.0)
        a = rng.uniform(0.8, 1.0)
        for _ in range(int(rng.integers(8, 17))):
            p.to(0.25 / f, a)
            p.to(0.5 / f, -a)
            p.to(0.25 / f, 0.0)
        p.hold(rng.uniform(0.5, 1.0))
    return p.kn, p.t


# ---- a garage door through a day (unipolar) ----

def garage_door(rng, n_trips):
    """The door's opening (0 shut, 1 fully open): opened for each car (fully, 8 ... 12 s a travel in the rig's time
    scaled to 2 ... 3 s), held open while it passes (3 ... 8 s), shut again; now and then stopped half way by the
    safety beam and reopened. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(1.0, 2.0))
    for _ in range(n_trips):
        p.to(rng.uniform(2.0, 3.0), 1.0)
        p.hold(rng.uniform(3.0, 8.0))
        if rng.uniform() < 0.35:
            mid = rng.uniform(0.4, 0.7)
            p.to(rng.uniform(1.0, 1.5), mid)
            p.hold(rng.uniform(0.5, 1.0))
            p.to(rng.uniform(1.0, 1.5), 1.0)
            p.hold(rng.uniform(1.0, 2.0))
        p.to(rng.uniform(2.0, 3.0), 0.0)
        p.hold(rng.uniform(4.0, 10.0))
    return p.kn, p.t


# ---- a speed bag ----

def speed_bag(rng, n_combos):
    """The bag's swing: combinations of triplets (the bag rebounding thrice a punch: a full swing out and back,
    2.2 ... 3 rebounds a second in the rig's time), alternating fists (the swing's side), pauses between combinations
    (0.8 ... 1.6 s, the bag at rest). Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.4, 0.8))
    for _ in range(n_combos):
        f = rng.uniform(2.2, 3.0)
        side = 1.0
        for _ in range(int(rng.integers(4, 9))):
            a = rng.uniform(0.85, 1.0)
            for q in range(3):
                p.to(0.5 / f, side * a * (1.0 - 0.12 * q))
                p.to(0.5 / f, -side * a * (1.0 - 0.12 * q) * 0.9)
            side = -side
        p.to(0.4, 0.0)
        p.hold(rng.uniform(0.8, 1.6))
    return p.kn, p.t


# ---- a rolling pin on pizza dough ----

def rolling_pin(rng, n_doughs):
    """The pin's place along the board: for every dough, strokes forward and back across it at an even pace (0.5 ... 0.8
    s a stroke), growing longer as the dough spreads (0.5 to 1 of the board), the pin lifted and set down at the middle
    between doughs (1 ... 2 s). Returns the knots and the end (harmonic moves)."""
    p = _Prog()
    p.hold(rng.uniform(0.3, 0.6))
    for _ in range(n_doughs):
        n = int(rng.integers(8, 14))
        for q in range(n):
            reach = 0.5 + 0.5 * q / (n - 1)
            p.to(rng.uniform(0.5, 0.8), reach * rng.uniform(0.97, 1.0))
            p.to(rng.uniform(0.5, 0.8), -reach * rng.uniform(0.97, 1.0))
        p.to(0.5, 0.0)
        p.hold(rng.uniform(1.0, 2.0))
    return p.kn, p.t


# ---- a sewing machine's foot pedal (unipolar) ----

def sewing_pedal(rng, n_seams):
    """The pedal's press (0 released, 1 floored): for every seam, pressed to a sewing speed (0.3 ... 1, floored once),
    eased up and down around it, released at the seam's end and held up while the cloth is turned (0.6 ... 1.5 s).
    Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.5, 1.0))
    top = int(rng.integers(0, n_seams))
    for q in range(n_seams):
        level = 1.0 if q == top else rng.uniform(0.3, 1.0)
        p.to(rng.uniform(0.25, 0.5), level)
        for _ in range(int(rng.integers(2, 5))):
            p.to(rng.uniform(0.3, 0.8), float(np.clip(level + rng.uniform(-0.25, 0.15), 0.2, 1.0)))
            p.hold(rng.uniform(0.2, 0.6))
        p.to(rng.uniform(0.2, 0.4), 0.0)
        p.hold(rng.uniform(0.6, 1.5))
    return p.kn, p.t


# ---- a bobblehead ----

def bobblehead(rng, n_nudges):
    """The head's nod: nudged (a first swing of 0.5 ... 1), ringing down on its spring (1.6 ... 2.2 swings a second in
    the rig's time, each swing 0.8 ... 0.88 of the one before, 10 ... 18 swings) until nudged again, the first nudges
    small. Returns the knots and the end (harmonic moves between the turning points)."""
    p = _Prog()
    p.hold(rng.uniform(0.5, 1.0))
    for q in range(n_nudges):
        a = rng.uniform(0.15, 0.3) if q == 0 else rng.uniform(0.5, 1.0)
        f = rng.uniform(1.6, 2.2)
        dec = rng.uniform(0.8, 0.88)
        side = 1.0 if rng.uniform() < 0.5 else -1.0
        for _ in range(int(rng.integers(10, 19))):
            p.to(0.5 / f, side * a)
            side, a = -side, a * dec
        p.to(0.25 / f, 0.0)
        p.hold(rng.uniform(0.3, 0.8))
    return p.kn, p.t


# ---- a tai chi form ----

def tai_chi(rng, n_moves):
    """The hands' sideways place: slow flowing moves between postures (2 ... 4 s each, from one side to the other or to
    a middle posture), a short settle in some postures (0.3 ... 1 s). Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.5, 1.0))
    side = 1.0
    for _ in range(n_moves):
        target = side * rng.uniform(0.85, 1.0) if rng.uniform() < 0.75 else rng.uniform(-0.3, 0.3)
        p.to(rng.uniform(2.0, 4.0), target)
        if rng.uniform() < 0.4:
            p.hold(rng.uniform(0.3, 1.0))
        side = -side
    p.to(rng.uniform(2.0, 3.0), 0.0)
    p.hold(0.5)
    return p.kn, p.t


# ---- flag waving at a race ----

def flag_waving(rng, n_laps):
    """The flag's lean: as every lap's leader passes, big figure waves (1.1 ... 1.6 waves a second, 4 ... 8 waves),
    the flag held out still to one side for the pack (0.6 ... 1.2 s), lowered to the middle between laps (1 ... 2.5 s).
    Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.5, 1.0))
    for _ in range(n_laps):
        f = rng.uniform(1.1, 1.6)
        for _ in range(int(rng.integers(4, 9))):
            p.to(0.5 / f, rng.uniform(0.85, 1.0))
            p.to(0.5 / f, -rng.uniform(0.85, 1.0))
        side = 1.0 if rng.uniform() < 0.5 else -1.0
        p.to(0.4, side * rng.uniform(0.6, 0.8))
        p.hold(rng.uniform(0.6, 1.2))
        p.to(0.5, 0.0)
        p.hold(rng.uniform(1.0, 2.5))
    return p.kn, p.t

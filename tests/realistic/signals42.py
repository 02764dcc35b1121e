"""Signals of the HOLDOUT42 set (``cases_holdout42.py``): everyday scenes, each drawn from a generator here.

Every scene is a programme of knots (time, position) joined by moves; the evaluator takes any times (a record's grid or
a finer one) and returns the position, exactly the first knot's before the programme starts and the last's after it. The
move is the septic (zero-jerk) point-to-point law 35 s^4 - 84 s^5 + 70 s^6 - 20 s^7 (zero speed, acceleration and jerk
at both ends: the 4-5-6-7 polynomial of cam and robot-joint design, e.g. Biagiotti & Melchiorri, *Trajectory Planning
for Automatic Machines and Robots*, 2008, from memory). Nothing here imports hystcomp.
"""

import numpy as np

from .set_tools import Programme as _Prog, knots_at as _knots_at


def septic(s):
    """The zero-jerk move 0 ... 1 over s in 0 ... 1 (clipped outside)."""
    s = np.clip(np.asarray(s, float), 0.0, 1.0)
    s4 = s ** 4
    return s4 * (35.0 - 84.0 * s + 70.0 * s * s - 20.0 * s * s * s)


def knots_at(t, knots):
    """The position on times t through knots [(time, position), ...] joined by septic moves; the first knot's position
    before it, the last's after."""
    return _knots_at(t, knots, septic)


# ---- a tower crane's jib slewing between loads (the clean case) ----

def tower_crane(rng, n_lifts):
    """The jib's slew angle about the middle of its working arc: for every lift, slewed to the pick-up side (most of
    the arc, 1.2 ... 2 s in the rig's time), held while the load is hooked (0.4 ... 1 s), slewed across to the drop
    side, small corrections as the banksman signals (2 ... 4 nudges of 0.05 ... 0.15), held while it is landed, the side
    alternating lift by lift; back to the middle at the end. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.3, 0.6))
    side = 1.0 if rng.uniform() < 0.5 else -1.0
    for _ in range(n_lifts):
        a = side * rng.uniform(0.6, 1.0)
        p.to(rng.uniform(1.2, 2.0), a)
        p.hold(rng.uniform(0.4, 1.0))
        b = -side * rng.uniform(0.7, 1.0)
        p.to(rng.uniform(1.6, 2.6), b)
        for _ in range(int(rng.integers(2, 5))):
            p.to(rng.uniform(0.25, 0.5), b - side * rng.uniform(0.05, 0.15) * rng.choice([-1.0, 1.0]))
        p.hold(rng.uniform(0.4, 1.0))
        side = -side
    p.to(rng.uniform(1.0, 1.5), 0.0)
    p.hold(0.5)
    return p.kn, p.t


# ---- a hospital bed's backrest through a day (unipolar) ----

def hospital_backrest(rng, n_changes):
    """The backrest's angle (0 flat, 1 upright): raised for meals and visits to 0.4 ... 1 (upright once at least),
    held (6 ... 14 s in the rig's time), lowered part way or flat for rest (held 5 ... 10 s), flat at the end. Returns
    the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(1.0, 2.0))
    levels = rng.uniform(0.4, 1.0, n_changes)
    levels[int(rng.integers(0, n_changes))] = 1.0
    for lv in levels:
        p.to(rng.uniform(2.0, 3.5) * lv + 0.5, lv)
        p.hold(rng.uniform(6.0, 14.0))
        down = 0.0 if rng.uniform() < 0.6 else lv * rng.uniform(0.2, 0.5)
        p.to(rng.uniform(1.5, 3.0) * (lv - down) + 0.5, down)
        p.hold(rng.uniform(5.0, 10.0))
    if p.kn[-1][1] != 0.0:
        p.to(rng.uniform(1.0, 2.0), 0.0)
        p.hold(rng.uniform(3.0, 5.0))
    return p.kn, p.t


# ---- a flour sifter shaken over a bowl ----

def flour_sifter(rng, n_rounds):
    """The sifter's sideways place: rounds of a slow sweep across the bowl and back (1 ... 1.6 s each way), then a
    bout of quick shakes (3.5 ... 5.5 a second, 10 ... 18 shakes, 0.7 ... 1 of the sweep's reach, tapering), held still
    over the bowl's middle (0.4 ... 0.9 s). Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.3, 0.6))
    for _ in range(n_rounds):
        for sd in (1.0, -1.0):
            p.to(rng.uniform(1.0, 1.6), sd * rng.uniform(0.9, 1.0))
        p.to(rng.uniform(0.5, 0.8), 0.0)
        f = rng.uniform(3.5, 5.5)
        a = rng.uniform(0.7, 1.0)
        n = int(rng.integers(10, 19))
        for k in range(n):
            ak = a * (1.0 - 0.3 * k / n)
            p.to(0.25 / f, ak)
            p.to(0.5 / f, -ak)
            p.to(0.25 / f, 0.0)
        p.hold(rng.uniform(0.4, 0.9))
    return p.kn, p.t


# ---- a dumbwaiter between a restaurant's floors (unipolar) ----

def dumbwaiter(rng, n_trips):
    """The car's height (0 the kitchen, 1 the top floor): sent to the dining room (0.5) or the top floor for every
    order, held while the plates are taken (3 ... 7 s), sent back down, held while the next is loaded (4 ... 9 s).
    Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(1.0, 2.0))
    floors = np.where(rng.uniform(size=n_trips) < 0.5, 0.5, 1.0)
    floors[int(rng.integers(0, n_trips))] = 1.0
    for fl in floors:
        p.to(rng.uniform(2.0, 3.0) * fl + 0.6, fl)
        p.hold(rng.uniform(3.0, 7.0))
        p.to(rng.uniform(2.0, 3.0) * fl + 0.6, 0.0)
        p.hold(rng.uniform(4.0, 9.0))
    return p.kn, p.t


# ---- sanding a board by hand ----

def sanding_block(rng, n_boards):
    """The block's place along the board: for every board, strokes back and forth at 0.8 ... 1.3 strokes a second,
    long ones (0.8 ... 1 of the reach) and short ones over a blemish (0.3 ... 0.5, about a drawn spot), the block lifted
    and the dust blown off at the middle between boards (0.8 ... 1.5 s). Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.3, 0.6))
    for _ in range(n_boards):
        f = rng.uniform(0.8, 1.3)
        for _ in range(int(rng.integers(6, 11))):
            if rng.uniform() < 0.7:
                p.to(0.5 / f, rng.uniform(0.8, 1.0))
                p.to(0.5 / f, -rng.uniform(0.8, 1.0))
            else:
                c, w = rng.uniform(-0.4, 0.4), rng.uniform(0.3, 0.5)
                for _ in range(int(rng.integers(2, 4))):
                    p.to(0.3 / f, c + w)
                    p.to(0.3 / f, c - w)
        p.to(0.5, 0.0)
        p.hold(rng.uniform(0.8, 1.5))
    return p.kn, p.t


# ---- a trapeze artist's swing ----

def trapeze(rng, n_acts):
    """The bar's swing: for every act, the swing pumped up from small (0.2 ... 0.3) to full (0.9 ... 1) over 5 ... 8
    swings at 0.5 ... 0.7 swings a second in the rig's time, a few full swings, a catch (the swing held short at one end,
    0.3 ... 0.6 s), then let die down to the middle. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.4, 0.8))
    for _ in range(n_acts):
        f = rng.uniform(0.5, 0.7)
        n_up = int(rng.integers(5, 9))
        a0, a1 = rng.uniform(0.2, 0.3), rng.uniform(0.9, 1.0)
        side = 1.0 if rng.uniform() < 0.5 else -1.0
        for k in range(n_up):
            p.to(0.5 / f, side * (a0 + (a1 - a0) * k / (n_up - 1)))
            side = -side
        for _ in range(int(rng.integers(2, 5))):
            p.to(0.5 / f, side * a1 * rng.uniform(0.97, 1.0))
            side = -side
        p.hold(rng.uniform(0.3, 0.6))
        a = a1
        while a > 0.15:
            a *= rng.uniform(0.6, 0.75)
            p.to(0.5 / f, side * a)
            side = -side
        p.to(0.25 / f, 0.0)
        p.hold(rng.uniform(0.5, 1.0))
    return p.kn, p.t


# ---- an excavator digging a trench (unipolar) ----

def excavator(rng, n_scoops):
    """The boom's height (0 the bucket in the trench, 1 the boom fully up): for every scoop, the bucket dragged through
    the trench (held low, 1 ... 2 s), lifted to dump on the spoil heap (0.6 ... 1, fully up once at least), held while
    it dumps (0.4 ... 1 s), lowered back. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.5, 1.0))
    ups = rng.uniform(0.6, 1.0, n_scoops)
    ups[int(rng.integers(0, n_scoops))] = 1.0
    for up in ups:
        p.hold(rng.uniform(1.0, 2.0))
        p.to(rng.uniform(0.8, 1.4), up)
        p.hold(rng.uniform(0.4, 1.0))
        p.to(rng.uniform(0.7, 1.2), 0.0)
    p.hold(rng.uniform(0.8, 1.5))
    return p.kn, p.t


# ---- a lathe's cross-slide facing a part ----

def lathe_facing(rng, n_parts):
    """The cross-slide's place (0 the part's centre line): for every part, facing passes fed across from one edge to
    the centre (slowly, 2 ... 3.5 s) and rapid returns (0.5 ... 0.8 s), the edge alternating between the front (+) and
    the rear (-) tool post, the first part's passes shallow (0.2 ... 0.35 of the reach). Returns the knots and the
    end."""
    p = _Prog()
    p.hold(rng.uniform(0.5, 1.0))
    for k in range(n_parts):
        reach = rng.uniform(0.2, 0.35) if k == 0 else rng.uniform(0.85, 1.0)
        side = 1.0 if k % 2 == 0 else -1.0
        for _ in range(int(rng.integers(3, 6))):
            p.to(rng.uniform(0.5, 0.8), side * reach)
            p.to(rng.uniform(2.0, 3.5), 0.0)
        p.hold(rng.uniform(0.5, 1.2))
    return p.kn, p.t


# ---- a blacksmith at the anvil ----

def blacksmith(rng, n_heats):
    """The hammer's height over the anvil's face (+ up, - down the far side of the horn where the work is bent): for
    every heat, a bout of blows (1.2 ... 1.8 a second, 6 ... 12 blows, lifted 0.7 ... 1), the work turned over the horn
    (a slow sweep to -0.8 ... -1 and back, 1.5 ... 2.5 s), the piece put back in the forge (the hammer rested at the
    middle, 1 ... 2 s). Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.5, 1.0))
    for _ in range(n_heats):
        f = rng.uniform(1.2, 1.8)
        for _ in range(int(rng.integers(6, 13))):
            p.to(0.6 / f, rng.uniform(0.7, 1.0))
            p.to(0.4 / f, -rng.uniform(0.2, 0.4))
        p.to(rng.uniform(0.8, 1.2), -rng.uniform(0.8, 1.0))
        p.to(rng.uniform(0.7, 1.3), 0.0)
        p.hold(rng.uniform(1.0, 2.0))
    return p.kn, p.t


# ---- a cuckoo clock's pendulum ----

def cuckoo_clock(rng, n_windings):
    """The pendulum's swing: started by hand (0.8 ... 1 of the full swing), ticking at 0.9 ... 1.2 swings a second in
    the rig's time, its swing settling to 0.6 ... 0.8 of the start, stopped by hand at the middle now and then to set
    the hands (1 ... 2 s) and restarted. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.4, 0.8))
    for _ in range(n_windings):
        f = rng.uniform(0.9, 1.2)
        a0 = rng.uniform(0.8, 1.0)
        a_end = a0 * rng.uniform(0.6, 0.8)
        side = 1.0 if rng.uniform() < 0.5 else -1.0
        n = int(rng.integers(10, 19))
        for k in range(n):
            a = a_end + (a0 - a_end) * np.exp(-3.0 * k / n)
            p.to(0.5 / f, side * a)
            side = -side
        p.to(0.25 / f, 0.0)
        p.hold(rng.uniform(1.0, 2.0))
    return p.kn, p.t

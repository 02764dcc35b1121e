"""Signals of the HOLDOUT43 set (``cases_holdout43.py``): everyday scenes, each drawn from a generator here.

Every scene is a programme of knots (time, position) joined by moves; the evaluator takes any times (a record's grid or
a finer one) and returns the position, exactly the first knot's before the programme starts and the last's after it. The
move is a motion controller's trapezoidal speed profile with equal thirds (accelerate at a constant rate for the first
third of the move, cruise, decelerate for the last third: the "1/3-1/3-1/3" profile, position piecewise quadratic and
linear, zero speed at both ends; the profile of any point-to-point axis controller, written here from its definition).
Nothing here imports hystcomp.
"""

import numpy as np

from .set_tools import Programme as _Prog, knots_at as _knots_at

#: the acceleration phase's share of a move
ACC = 1.0 / 3.0


def trapezoid(s, a=ACC):
    """The trapezoidal-speed move 0 ... 1 over s in 0 ... 1 (clipped outside): constant acceleration over s < a, a
    cruise, constant deceleration over s > 1 - a."""
    s = np.clip(np.asarray(s, float), 0.0, 1.0)
    vmax = 1.0 / (1.0 - a)
    up = 0.5 * vmax * s * s / a
    mid = vmax * (s - 0.5 * a)
    r = 1.0 - s
    down = 1.0 - 0.5 * vmax * r * r / a
    return np.where(s < a, up, np.where(s > 1.0 - a, down, mid))


def knots_at(t, knots):
    """The position on times t through knots [(time, position), ...] joined by trapezoidal-speed moves; the first
    knot's position before it, the last's after."""
    return _knots_at(t, knots, trapezoid)


# ---- a window cleaner's squeegee (the clean case) ----

def squeegee(rng, n_panes):
    """The squeegee's place across a shop window (0 its middle): for every pane, the pane wetted with the applicator in
    quick short scrubs about a drawn spot (4 ... 7 scrubs of 0.2 ... 0.4 of the width, 0.25 ... 0.4 s each), then wiped
    in long overlapping strokes from edge to edge (3 or 4 strokes, 0.8 ... 1 of the half width each side, 1.0 ... 1.6 s
    each), the blade wiped dry on a cloth at the middle (held 0.4 ... 0.9 s). Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.3, 0.6))
    for _ in range(n_panes):
        c = rng.uniform(-0.4, 0.4)
        w = rng.uniform(0.2, 0.4)
        for k in range(int(rng.integers(4, 8))):
            p.to(rng.uniform(0.25, 0.4), c + (w if k % 2 == 0 else -w))
        side = 1.0 if rng.uniform() < 0.5 else -1.0
        for _ in range(int(rng.integers(3, 5))):
            p.to(rng.uniform(1.0, 1.6), side * rng.uniform(0.8, 1.0))
            side = -side
        p.to(rng.uniform(0.5, 0.8), 0.0)
        p.hold(rng.uniform(0.4, 0.9))
    return p.kn, p.t


# ---- a toaster's lever (unipolar) ----

def toaster(rng, n_slices):
    """The toaster carriage's depth (0 up, 1 fully down): for every round, the lever pressed down (to 1, or to 0.6 ...
    0.8 when a bagel's top sticks out), held while it toasts (6 ... 12 s in the rig's time), popped up fast (0.2 ... 0.4
    s), held while the toast is buttered and the next slice put in (4 ... 8 s); now and then the lever lifted early to
    check the colour (to 0.3 ... 0.5 and back down). Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(1.0, 2.0))
    depth = np.where(rng.uniform(size=n_slices) < 0.7, 1.0, rng.uniform(0.6, 0.8, n_slices))
    depth[int(rng.integers(0, n_slices))] = 1.0
    for d in depth:
        p.to(rng.uniform(0.6, 1.0), d)
        p.hold(rng.uniform(6.0, 12.0))
        if rng.uniform() < 0.3:
            p.to(rng.uniform(0.4, 0.7), rng.uniform(0.3, 0.5))
            p.hold(rng.uniform(1.0, 2.0))
            p.to(rng.uniform(0.4, 0.7), d)
            p.hold(rng.uniform(3.0, 5.0))
        p.to(rng.uniform(0.2, 0.4), 0.0)
        p.hold(rng.uniform(4.0, 8.0))
    return p.kn, p.t


# ---- a wet dog shaking itself dry ----

def wet_dog(rng, n_shakes):
    """The dog's trunk twist (0 straight): for every bout, the head shaken first, a small twist (0.2 ... 0.35) at 5 ...
    7 twists a second; the shake running down the body, the twist growing to 0.85 ... 1 at 4 ... 5.5 a second (8 ... 14
    twists) and dying away; a pause, standing still (0.6 ... 1.4 s), sometimes a slow sidestep lean (0.4 ... 0.7 of the
    twist, 0.6 ... 1 s each way). Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.3, 0.6))
    for _ in range(n_shakes):
        f0 = rng.uniform(5.0, 7.0)
        a0 = rng.uniform(0.2, 0.35)
        side = 1.0 if rng.uniform() < 0.5 else -1.0
        for _ in range(int(rng.integers(3, 6))):
            p.to(0.5 / f0, side * a0)
            side = -side
        f = rng.uniform(4.0, 5.5)
        a1 = rng.uniform(0.85, 1.0)
        n = int(rng.integers(8, 15))
        for k in range(n):
            env = min(1.0, 0.5 + k / 3.0) * (1.0 - 0.6 * max(0.0, k - n / 2) / n)
            p.to(0.5 / f, side * a1 * env)
            side = -side
        p.to(0.25 / f, 0.0)
        p.hold(rng.uniform(0.6, 1.4))
        if rng.uniform() < 0.5:
            lean = rng.uniform(0.4, 0.7) * (1.0 if rng.uniform() < 0.5 else -1.0)
            p.to(rng.uniform(0.6, 1.0), lean)
            p.to(rng.uniform(0.6, 1.0), 0.0)
            p.hold(rng.uniform(0.3, 0.6))
    return p.kn, p.t


# ---- a bathtub filled, used and drained (unipolar) ----

def bathtub(rng, n_baths):
    """The water's level in a bathtub (0 empty, 1 the overflow): for every bath, filled from the taps (a steady rise,
    3 ... 5 s to 0.7 ... 0.9 in the rig's time), held while the bather soaks (5 ... 9 s), the level rising as the bather
    gets in (a quick 0.08 ... 0.12 more), topped up with hot water (to the overflow once at least), let out part way
    when the bather gets out, then drained (4 ... 6 s) and left empty (3 ... 6 s). Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(1.0, 2.0))
    top_once = int(rng.integers(0, n_baths))
    for k in range(n_baths):
        lv = rng.uniform(0.7, 0.8)
        p.to(rng.uniform(3.0, 5.0), lv)
        p.hold(rng.uniform(1.0, 2.0))
        lv += rng.uniform(0.08, 0.12)
        p.to(rng.uniform(0.4, 0.7), lv)
        p.hold(rng.uniform(5.0, 9.0))
        top = 1.0 if k == top_once else min(1.0, lv + rng.uniform(0.03, 0.08))
        p.to(rng.uniform(1.0, 2.0), top)
        p.hold(rng.uniform(3.0, 6.0))
        p.to(rng.uniform(0.4, 0.7), top - rng.uniform(0.08, 0.12))
        p.hold(rng.uniform(1.0, 2.0))
        p.to(rng.uniform(4.0, 6.0), 0.0)
        p.hold(rng.uniform(3.0, 6.0))
    return p.kn, p.t


# ---- a badminton rally ----

def badminton(rng, n_rallies):
    """The racket's swing (+ forehand, - backhand): for every rally, a serve (a short swing, 0.3 ... 0.5), then 6 ... 12
    shots, each a backswing and a stroke through to the other side: clears and smashes full (0.85 ... 1), drops and net
    shots short (0.25 ... 0.5), 0.35 ... 0.6 s a shot; the racket brought back to ready (0) between rallies (1 ... 2
    s). Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.4, 0.8))
    for _ in range(n_rallies):
        s = rng.uniform(0.3, 0.5)
        p.to(rng.uniform(0.3, 0.5), -s)
        p.to(rng.uniform(0.3, 0.5), s)
        p.to(rng.uniform(0.3, 0.5), 0.0)
        for _ in range(int(rng.integers(6, 13))):
            side = 1.0 if rng.uniform() < 0.6 else -1.0
            amp = rng.uniform(0.85, 1.0) if rng.uniform() < 0.6 else rng.uniform(0.25, 0.5)
            p.to(rng.uniform(0.2, 0.3), -side * amp * rng.uniform(0.6, 0.9))
            p.to(rng.uniform(0.15, 0.3), side * amp)
        p.to(rng.uniform(0.4, 0.7), 0.0)
        p.hold(rng.uniform(1.0, 2.0))
    return p.kn, p.t


# ---- a cradle rocked to sleep ----

def cradle(rng, n_nights):
    """A cradle's tilt: for every settling, rocked up from rest (0.2 ... 0.35) to a full rock (0.9 ... 1) over 5 ... 8
    half swings at 0.8 ... 1.1 swings a second in the rig's time, rocked full a while (4 ... 8 half swings), then let
    swing out with the rocks shrinking by 0.7 ... 0.85 each, held still at rest (1 ... 2 s). Returns the knots and the
    end."""
    p = _Prog()
    p.hold(rng.uniform(0.4, 0.8))
    for _ in range(n_nights):
        f = rng.uniform(0.8, 1.1)
        n_up = int(rng.integers(5, 9))
        a0, a1 = rng.uniform(0.2, 0.35), rng.uniform(0.9, 1.0)
        side = 1.0 if rng.uniform() < 0.5 else -1.0
        for k in range(n_up):
            p.to(0.5 / f, side * (a0 + (a1 - a0) * k / (n_up - 1)))
            side = -side
        for _ in range(int(rng.integers(4, 9))):
            p.to(0.5 / f, side * a1 * rng.uniform(0.96, 1.0))
            side = -side
        a = a1
        while a > 0.12:
            a *= rng.uniform(0.7, 0.85)
            p.to(0.5 / f, side * a)
            side = -side
        p.to(0.25 / f, 0.0)
        p.hold(rng.uniform(1.0, 2.0))
    return p.kn, p.t


# ---- a roller blind (unipolar) ----

def roller_blind(rng, n_moves):
    """A spring roller blind's drop (0 rolled up, 1 fully down): pulled down to a drawn height (0.3 ... 1, fully down
    once at least) in a steady pull (0.6 ... 1.2 s a full drop in the rig's time), or let up part way to it (its spring
    rolling it up fast: 0.25 ... 0.45 s a full drop), held there (0.8 ... 2 s), now and then let roll up all the way;
    rolled up at the end. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.5, 1.0))
    heights = rng.uniform(0.3, 1.0, n_moves)
    heights[int(rng.integers(0, n_moves))] = 1.0
    for hgt in heights:
        d = hgt - p.kn[-1][1]
        p.to((rng.uniform(0.6, 1.2) if d > 0 else rng.uniform(0.25, 0.45)) * max(abs(d), 0.2), hgt)
        p.hold(rng.uniform(0.8, 2.0))
        if rng.uniform() < 0.4:
            p.to(rng.uniform(0.25, 0.45) * max(hgt, 0.2), 0.0)
            p.hold(rng.uniform(0.6, 1.5))
    if p.kn[-1][1] != 0.0:
        p.to(rng.uniform(0.25, 0.45) * max(p.kn[-1][1], 0.2), 0.0)
    p.hold(rng.uniform(0.8, 1.5))
    return p.kn, p.t


# ---- a mezzaluna rocking over herbs ----

def mezzaluna(rng, n_bunches):
    """A mezzaluna (a two-handled rocking blade) mincing herbs: for every bunch, the blade rocked from handle to handle
    (0.8 ... 1 of the rock each way, 0.3 ... 0.5 s a rock, 8 ... 14 rocks), the first bunch's rocks gentle (0.2 ...
    0.35: tender leaves), the herbs scraped together with the blade held level (0) between bunches (0.6 ... 1.2 s).
    Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.5, 1.0))
    for k in range(n_bunches):
        reach = rng.uniform(0.2, 0.35) if k == 0 else rng.uniform(0.8, 1.0)
        side = 1.0 if rng.uniform() < 0.5 else -1.0
        for _ in range(int(rng.integers(8, 15))):
            p.to(rng.uniform(0.3, 0.5), side * reach * rng.uniform(0.9, 1.0))
            side = -side
        p.to(rng.uniform(0.3, 0.5), 0.0)
        p.hold(rng.uniform(0.6, 1.2))
    return p.kn, p.t


# ---- a gymnast on the pommel horse ----

def pommel_horse(rng, n_routines):
    """A pommel-horse gymnast's hips over the horse (+ the right pommel side, - the left): for every routine, circles
    (the hips swung side to side at 0.8 ... 1.1 circles a second, 0.85 ... 1 of the reach, 6 ... 10 half circles),
    scissors (short swings 0.4 ... 0.6, 4 ... 6), a travel along the horse (a slow lean to one end, 0.7 ... 0.9, 1 ...
    1.5 s) and back, a dismount to the middle and a rest (1 ... 2 s). Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.5, 1.0))
    for _ in range(n_routines):
        f = rng.uniform(0.8, 1.1)
        side = 1.0 if rng.uniform() < 0.5 else -1.0
        for _ in range(int(rng.integers(6, 11))):
            p.to(0.5 / f, side * rng.uniform(0.85, 1.0))
            side = -side
        for _ in range(int(rng.integers(4, 7))):
            p.to(0.35 / f, side * rng.uniform(0.4, 0.6))
            side = -side
        p.to(rng.uniform(1.0, 1.5), side * rng.uniform(0.7, 0.9))
        p.to(rng.uniform(1.0, 1.5), 0.0)
        p.hold(rng.uniform(1.0, 2.0))
    return p.kn, p.t


# ---- a child on a rocking horse ----

def rocking_horse(rng, n_rides):
    """A rocking horse's pitch: for every ride, rocked by the child at 0.7 ... 1 rocks a second, the rocks 0.6 ... 1 of
    the full pitch, growing while the child gallops and shrinking as it tires (10 ... 18 half rocks), then stopped level
    (0) while the child climbs off and back on (1 ... 2 s). Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.4, 0.8))
    for _ in range(n_rides):
        f = rng.uniform(0.7, 1.0)
        side = 1.0 if rng.uniform() < 0.5 else -1.0
        n = int(rng.integers(10, 19))
        peak = rng.uniform(0.9, 1.0)
        for k in range(n):
            a = 0.6 + (peak - 0.6) * np.sin(np.pi * (k + 0.5) / n)
            p.to(0.5 / f, side * a)
            side = -side
        p.to(0.25 / f, 0.0)
        p.hold(rng.uniform(1.0, 2.0))
    return p.kn, p.t

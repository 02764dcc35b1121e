"""Signals of the HOLDOUT44 set (``cases_holdout44.py``): everyday scenes, each drawn from a generator here.

Every scene is a programme of knots (time, position) joined by moves; the evaluator takes any times (a record's grid or
a finer one) and returns the position, exactly the first knot's before the programme starts and the last's after it.
The move is the cam designer's "modified sine" motion law (Kloomok & Muffley's family of cam laws, 1955, as cam texts
tabulate it, written here from its definition and from memory): the acceleration is a quarter sine wave of a quarter of
the move's period over its first eighth, a cosine a third as fast over the middle three quarters, and a quarter sine
wave back to 0 over its last eighth, so the acceleration is continuous and 0 at both ends (zero speed and zero
acceleration at both knots), the peak speed 1.76 times the mean and the peak acceleration 5.53 times the move's over
its time squared. Nothing here imports hystcomp.
"""

import math

import numpy as np

from .set_tools import Programme as _Prog, knots_at as _knots_at

#: the modified sine's acceleration coefficient 4 pi^2 / (pi + 4)
C_A = 4.0 * math.pi ** 2 / (math.pi + 4.0)


def modified_sine(s):
    """The modified-sine move 0 ... 1 over s in 0 ... 1 (clipped outside), its position in closed form: the
    acceleration C sin(4 pi s) over s < 1/8, C cos(4 pi (s - 1/8) / 3) over 1/8 ... 7/8, and -C sin(4 pi (1 - s)) over
    s > 7/8, integrated twice from rest; C = 4 pi^2 / (pi + 4)."""
    s = np.clip(np.asarray(s, float), 0.0, 1.0)
    C = C_A
    k1 = 4.0 * math.pi
    # first eighth: v = C (1 - cos k1 s) / k1, x = C (s - sin(k1 s) / k1) / k1
    x1 = C * (s - np.sin(k1 * s) / k1) / k1
    # middle: from s1 = 1/8, v1 = C / k1, x1e = C (1/8 - 1/k1) / k1; a = C cos(k2 w), w = s - 1/8, k2 = 4 pi / 3
    k2 = k1 / 3.0
    w = s - 0.125
    v1 = C / k1
    x1e = C * (0.125 - 1.0 / k1) / k1
    x2 = x1e + v1 * w + C * (1.0 - np.cos(k2 * w)) / (k2 * k2)
    # last eighth: by symmetry x(s) = 1 - x(1 - s)
    r = 1.0 - s
    x3 = 1.0 - C * (r - np.sin(k1 * r) / k1) / k1
    return np.where(s < 0.125, x1, np.where(s > 0.875, x3, x2))


def knots_at(t, knots):
    """The position on times t through knots [(time, position), ...] joined by modified-sine moves; the first knot's
    position before it, the last's after."""
    return _knots_at(t, knots, modified_sine)


def _side(rng):
    return 1.0 if rng.uniform() < 0.5 else -1.0


# ---- a vacuum cleaner pushed over a floor (the clean case) ----

def vacuum_cleaner(rng, n_runs):
    """The cleaner's nozzle along the operator's stroke (0 at the operator's stance): for every run across a room,
    long strokes pushed forward and pulled back over open floor (2 ... 3 of each, 0.75 ... 1 of the reach, 0.7 ... 1.1
    s each way), now and then quick short jabs under a piece of furniture (0.2 ... 0.4 of the reach, 0.18 ... 0.3 s each
    way, 3 ... 6 of them about a drawn spot), then the operator stepping along (the nozzle held at the stance, 0.3 ...
    0.7 s), and after every third run the cleaner stopped to move a chair (held at 0, 1 ... 2 s). Returns the knots
    and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.4, 0.8))
    for j in range(n_runs):
        for _ in range(int(rng.integers(2, 4))):
            p.to(rng.uniform(0.7, 1.1), rng.uniform(0.75, 1.0))
            p.to(rng.uniform(0.7, 1.1), -rng.uniform(0.75, 1.0))
        if rng.uniform() < 0.5:
            c = rng.uniform(-0.5, 0.5)
            for k in range(int(rng.integers(3, 7))):
                p.to(rng.uniform(0.18, 0.3), c + (1 if k % 2 == 0 else -1) * rng.uniform(0.2, 0.4))
        p.to(rng.uniform(0.4, 0.6), 0.0)
        p.hold(rng.uniform(0.3, 0.7))
        if j % 3 == 2:
            p.hold(rng.uniform(1.0, 2.0))
    return p.kn, p.t


# ---- a trolley jack (unipolar) ----

def trolley_jack(rng, n_lifts):
    """A hydraulic trolley jack's saddle height (0 lowered, 1 its top): for every lift, pumped up in strokes (each
    raising it 0.08 ... 0.15 over 0.3 ... 0.5 s, the handle's return stroke a pause of 0.3 ... 0.6 s) to 0.6 ... 1 (its
    top once at least), held while the car is worked on (15 ... 30 s), now and then topped up by a stroke or two after a
    while, then let down through the release valve (2 ... 4 s) and left lowered (3 ... 6 s). Returns the knots and the
    end."""
    p = _Prog()
    p.hold(rng.uniform(1.0, 2.0))
    tops = rng.uniform(0.6, 1.0, n_lifts)
    tops[int(rng.integers(0, n_lifts))] = 1.0
    for top in tops:
        h = 0.0
        while h < top - 1e-9:
            h = min(top, h + rng.uniform(0.08, 0.15))
            p.to(rng.uniform(0.3, 0.5), h)
            p.hold(rng.uniform(0.3, 0.6))
        p.hold(rng.uniform(15.0, 30.0))
        if top < 0.9 and rng.uniform() < 0.5:
            for _ in range(int(rng.integers(1, 3))):
                h = min(1.0, h + rng.uniform(0.05, 0.1))
                p.to(rng.uniform(0.3, 0.5), h)
                p.hold(rng.uniform(0.3, 0.6))
            p.hold(rng.uniform(5.0, 9.0))
        p.to(rng.uniform(2.0, 4.0), 0.0)
        p.hold(rng.uniform(3.0, 6.0))
    return p.kn, p.t


# ---- a cheerleader's pom-pom routine ----

def pompom(rng, n_counts):
    """A cheerleader's arm (+ up to the right, - down to the left): for every eight-count, a slow sweep across (0.85
    ... 1 of the reach, 0.8 ... 1.4 s), a quick punch out and back (to 0.85 ... 1 in 0.12 ... 0.2 s), and a shake
    about a drawn arm position (the pom-pom shaken at 6 ... 9 shakes a second, 0.15 ... 0.35 of the reach, 8 ... 16
    shakes); the arm brought back to the hip (0) and held between counts (0.4 ... 1 s). Returns the knots and the
    end."""
    p = _Prog()
    p.hold(rng.uniform(0.4, 0.8))
    for _ in range(n_counts):
        sd = _side(rng)
        p.to(rng.uniform(0.8, 1.4), sd * rng.uniform(0.85, 1.0))
        p.to(rng.uniform(0.8, 1.4), -sd * rng.uniform(0.85, 1.0))
        for _ in range(int(rng.integers(1, 3))):
            d = _side(rng) * rng.uniform(0.85, 1.0)
            p.to(rng.uniform(0.12, 0.2), d)
            p.to(rng.uniform(0.12, 0.2), 0.0)
        c = rng.uniform(-0.5, 0.5)
        f = rng.uniform(6.0, 9.0)
        a = rng.uniform(0.15, 0.35)
        p.to(rng.uniform(0.2, 0.4), c)
        for k in range(int(rng.integers(8, 17))):
            p.to(0.5 / f, c + (a if k % 2 == 0 else -a))
        p.to(rng.uniform(0.2, 0.4), 0.0)
        p.hold(rng.uniform(0.4, 1.0))
    return p.kn, p.t


# ---- a kitchen drawer (unipolar) ----

def kitchen_drawer(rng, n_uses):
    """A kitchen drawer's opening (0 shut, 1 fully out) while a meal is cooked: for every use, pulled out to 0.4 ...
    1 (fully out once at least; 0.6 ... 1.2 s), held while the cook looks for something (1 ... 4 s), sometimes pulled
    a little further or pushed part way in (0.1 ... 0.2), then pushed shut (0.3 ... 0.6 s, quicker than it was opened)
    and left shut (2 ... 6 s). Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(1.0, 2.0))
    outs = rng.uniform(0.4, 1.0, n_uses)
    outs[int(rng.integers(0, n_uses))] = 1.0
    for o in outs:
        p.to(rng.uniform(0.6, 1.2), o)
        p.hold(rng.uniform(1.0, 4.0))
        if rng.uniform() < 0.4:
            o2 = float(np.clip(o + _side(rng) * rng.uniform(0.1, 0.2), 0.2, 1.0))
            p.to(rng.uniform(0.3, 0.6), o2)
            p.hold(rng.uniform(1.0, 3.0))
        p.to(rng.uniform(0.3, 0.6), 0.0)
        p.hold(rng.uniform(2.0, 6.0))
    return p.kn, p.t


# ---- a foosball rod ----

def foosball(rng, n_points):
    """A foosball rod's slide (0 centred): for every point, the rod shuffled side to side while the ball is worked
    (0.3 ... 0.7 of the travel, 0.15 ... 0.3 s a shuffle, 4 ... 9 of them), a shot's wind-up slide to one side (0.85
    ... 1, 0.3 ... 0.5 s) and a snap across to the other (0.85 ... 1, 0.12 ... 0.2 s), then the rod centred and still
    while the ball is fetched (1 ... 2 s). Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.4, 0.8))
    for _ in range(n_points):
        for _ in range(int(rng.integers(4, 10))):
            p.to(rng.uniform(0.15, 0.3), _side(rng) * rng.uniform(0.3, 0.7))
        sd = _side(rng)
        p.to(rng.uniform(0.3, 0.5), sd * rng.uniform(0.85, 1.0))
        p.to(rng.uniform(0.12, 0.2), -sd * rng.uniform(0.85, 1.0))
        p.to(rng.uniform(0.3, 0.5), 0.0)
        p.hold(rng.uniform(1.0, 2.0))
    return p.kn, p.t


# ---- a discus thrower's wind-up ----

def discus(rng, n_throws):
    """A discus thrower's throwing arm across the body (+ back, - across the front): for every throw, preliminary
    swings back and forth growing to full (2 ... 4 swings, the first 0.4 ... 0.6, the last 0.8 ... 1, 0.6 ... 0.9 s
    each way), a hold at full wind-up (0.2 ... 0.4 s), the turn and release (through to -0.9 ... -1 in 0.3 ... 0.45 s),
    the follow-through back to the middle (0.6 ... 1 s) and a walk back to the circle (2 ... 3 s at rest). Returns the
    knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.4, 0.8))
    for _ in range(n_throws):
        n = int(rng.integers(2, 5))
        sd = _side(rng)
        for k in range(n):
            a = rng.uniform(0.4, 0.6) + (rng.uniform(0.9, 1.0) - 0.5) * k / max(n - 1, 1)
            p.to(rng.uniform(0.6, 0.9), sd * min(a, 1.0))
            p.to(rng.uniform(0.6, 0.9), -sd * min(a, 1.0) * rng.uniform(0.7, 1.0))
        p.to(rng.uniform(0.6, 0.9), sd * rng.uniform(0.9, 1.0))
        p.hold(rng.uniform(0.2, 0.4))
        p.to(rng.uniform(0.3, 0.45), -sd * rng.uniform(0.9, 1.0))
        p.to(rng.uniform(0.6, 1.0), 0.0)
        p.hold(rng.uniform(2.0, 3.0))
    return p.kn, p.t


# ---- a trigger sprayer (unipolar) ----

def trigger_sprayer(rng, n_plants):
    """A trigger sprayer's trigger (0 released, 1 squeezed to its stop) while house plants are misted: for every
    plant, 3 ... 9 squeezes (each pulled to 0.6 ... 1 in 0.1 ... 0.18 s and let spring back in 0.08 ... 0.14 s, 0.05
    ... 0.25 s apart), now and then a slow, careful half squeeze for a fern (to 0.3 ... 0.5 over 0.4 ... 0.7 s, held
    0.3 ... 0.6 s), then the walk to the next plant (released, 1 ... 3 s); a full squeeze once at least. Returns the
    knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(1.0, 2.0))
    full = int(rng.integers(0, n_plants))
    for j in range(n_plants):
        for k in range(int(rng.integers(3, 10))):
            p.to(rng.uniform(0.1, 0.18), 1.0 if (j == full and k == 0) else rng.uniform(0.6, 1.0))
            p.to(rng.uniform(0.08, 0.14), 0.0)
            p.hold(rng.uniform(0.05, 0.25))
        if rng.uniform() < 0.3:
            p.to(rng.uniform(0.4, 0.7), rng.uniform(0.3, 0.5))
            p.hold(rng.uniform(0.3, 0.6))
            p.to(rng.uniform(0.2, 0.3), 0.0)
        p.hold(rng.uniform(1.0, 3.0))
    return p.kn, p.t


# ---- a folding hand fan ----

def hand_fan(rng, n_bouts):
    """A folding fan on a hot day (+ toward the face, - away): first only fluttered in the fingers while its owner
    reads (three bouts of 8 ... 20 flutters at 1.5 ... 2.5 a second, 0.01 ... 0.03 of the full wave, rested in the lap
    between), then waved in earnest (n_bouts bouts of 8 ... 20 waves at 1.5 ... 2.5 waves a second, 0.6 ... 1 of the
    full wave), the fan rested in the lap (0) for 0.8 ... 2 s after every bout. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.5, 1.0))
    for b in range(3 + n_bouts):
        f = rng.uniform(1.5, 2.5)
        lo, hi, n = (0.01, 0.03, int(rng.integers(8, 21))) if b < 3 else (0.6, 1.0, int(rng.integers(8, 21)))
        sd = _side(rng)
        for _ in range(n):
            p.to(0.5 / f, sd * rng.uniform(lo, hi))
            sd = -sd
        p.to(rng.uniform(0.3, 0.5), 0.0)
        p.hold(rng.uniform(0.8, 2.0))
    return p.kn, p.t


# ---- a breaststroke swimmer's arms ----

def breaststroke(rng, n_lengths):
    """A breaststroke swimmer's hands (+ the outsweep's reach, - the insweep's): for every length, 6 ... 10 strokes:
    the outsweep (to 0.85 ... 1, 0.4 ... 0.6 s), the quick insweep under the chest (to -0.85 ... -1, 0.2 ... 0.3 s),
    the recovery forward to the middle (0.25 ... 0.35 s) and the glide (held, 0.3 ... 0.8 s); a turn at the wall
    (held, 1 ... 2 s). Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.4, 0.8))
    for _ in range(n_lengths):
        for _ in range(int(rng.integers(6, 11))):
            p.to(rng.uniform(0.4, 0.6), rng.uniform(0.85, 1.0))
            p.to(rng.uniform(0.2, 0.3), -rng.uniform(0.85, 1.0))
            p.to(rng.uniform(0.25, 0.35), 0.0)
            p.hold(rng.uniform(0.3, 0.8))
        p.hold(rng.uniform(1.0, 2.0))
    return p.kn, p.t


# ---- a barista swirling a milk jug ----

def milk_jug(rng, n_jugs):
    """A barista's milk jug (+ tilted to the spout side, - back): for every jug, swirled (the tilt rocking at 2 ...
    3 a second, 0.4 ... 0.7 of the full tilt, 6 ... 12 rocks, the amplitude drifting), tapped on the counter (a quick
    dip to -0.2 ... -0.3 and back), then poured (tilted slowly to 0.85 ... 1 over 1 ... 1.6 s, rocked by 0.1 ... 0.2
    for the latte art's wiggle, 4 ... 8 wiggles at 3 ... 4 a second, then back past the middle to -0.85 ... -1 as the
    jug is set down and emptied into the sink), then held level (1 ... 2 s). Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.4, 0.8))
    for _ in range(n_jugs):
        f = rng.uniform(2.0, 3.0)
        a = rng.uniform(0.4, 0.7)
        sd = _side(rng)
        for _ in range(int(rng.integers(6, 13))):
            a = float(np.clip(a + rng.uniform(-0.08, 0.08), 0.35, 0.75))
            p.to(0.5 / f, sd * a)
            sd = -sd
        p.to(rng.uniform(0.15, 0.25), 0.0)
        p.to(rng.uniform(0.08, 0.12), -rng.uniform(0.2, 0.3))
        p.to(rng.uniform(0.08, 0.12), 0.0)
        lv = rng.uniform(0.85, 1.0)
        p.to(rng.uniform(1.0, 1.6), lv)
        fw, r = rng.uniform(3.0, 4.0), rng.uniform(0.1, 0.2)
        for k in range(int(rng.integers(4, 9))):
            p.to(0.5 / fw, lv - r * (1 if k % 2 == 0 else 0))
        p.to(rng.uniform(0.6, 1.0), -rng.uniform(0.85, 1.0))
        p.to(rng.uniform(0.5, 0.8), 0.0)
        p.hold(rng.uniform(1.0, 2.0))
    return p.kn, p.t

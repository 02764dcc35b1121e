"""Signals of the HOLDOUT48 set (``cases_holdout48.py``): everyday scenes, each drawn from a generator here.

Every scene is a programme of knots (time, position) joined by moves; the evaluator takes any times (a record's grid or
a finer one) and returns the position, exactly the first knot's before the programme starts and the last's after it.
The move is one whose speed is a raised cosine squared, sin^4(pi s) (a design chosen here, written from its definition,
not quoted: one step smoother than the cycloidal move, whose speed is sin^2(pi s), so that its speed, acceleration and
jerk are all 0 at both ends; the even powers of a sine are what cam designers blend, as remembered):

    speed (8 / 3) sin^4(pi s) on s in 0 ... 1 (8 / 3 = 1 / int_0^1 sin^4: the move covers 1),
    position s - (2 / (3 pi)) sin(2 pi s) + (1 / (12 pi)) sin(4 pi s),

its speed's peak 8 / 3 at the middle (a unit move's over its time), its acceleration's peak 2 pi sqrt(3) (about 10.9)
at s = 1/3 and 2/3. Nothing here imports hystcomp.
"""

import math

import numpy as np

from .set_tools import Programme as _Prog, knots_at as _knots_at

#: the move's peak speed (a unit move over a unit time)
PEAK_SPEED = 8.0 / 3.0


def sin4_move(s):
    """The move 0 ... 1 over s in 0 ... 1 (clipped outside) whose speed is (8 / 3) sin^4(pi s), in closed form."""
    s = np.clip(np.asarray(s, float), 0.0, 1.0)
    return s - 2.0 / (3.0 * math.pi) * np.sin(2 * math.pi * s) + 1.0 / (12.0 * math.pi) * np.sin(4 * math.pi * s)


def knots_at(t, knots):
    """The position on times t through knots [(time, position), ...] joined by sin^4-speed moves; the first knot's
    position before it, the last's after."""
    return _knots_at(t, knots, sin4_move)


def _side(rng):
    """A side drawn at even odds: +1 or -1 (one uniform draw)."""
    return 1.0 if rng.uniform() < 0.5 else -1.0


# ---- a helmsman's wheel (the clean case) ----

def helmsman(rng, n_legs):
    """A helmsman's wheel in pilotage waters (+ to starboard, - to port): for every leg, 2 ... 4 wheel orders, each the
    wheel put over toward its side (to 0.4 ... 1 of the reach in 0.6 ... 1.2 s) and held while the ship answers (1 ...
    2.5 s), then met (eased to 0.1 ... 0.3 of the reach the other way in 0.4 ... 0.8 s, held 0.5 ... 1.2 s) and brought
    to midships (in 0.4 ... 0.8 s, held 1 ... 2.5 s: the ship steady). Hard over (the full reach) to both sides in the
    first leg. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.5, 1.0))
    for leg in range(n_legs):
        n_orders = int(rng.integers(2, 5))
        for k in range(n_orders):
            sd = _side(rng)
            if leg == 0 and k < 2:
                sd, a = (1.0, 1.0) if k == 0 else (-1.0, 1.0)
            else:
                a = rng.uniform(0.4, 1.0)
            p.to(rng.uniform(0.6, 1.2), sd * a)
            p.hold(rng.uniform(1.0, 2.5))
            p.to(rng.uniform(0.4, 0.8), -sd * rng.uniform(0.1, 0.3))
            p.hold(rng.uniform(0.5, 1.2))
            p.to(rng.uniform(0.4, 0.8), 0.0)
            p.hold(rng.uniform(1.0, 2.5))
    return p.kn, p.t


# ---- a fitter's bench vice (unipolar) ----

def bench_vice(rng, n_pieces):
    """A fitter's bench vice (0 open on the work, 1 the tightest): for every workpiece, the handle pulled round in steps
    (each 0.2 ... 0.35 of the travel more in 0.3 ... 0.6 s, 0.5 ... 1 s between pulls) to tight (0.8 ... 1), held while
    the piece is filed (8 ... 15 s), eased to 0.4 ... 0.6 of it to turn the piece (in 0.3 ... 0.6 s, held 3 ... 5 s),
    pulled tight again (to 0.8 ... 1 of it, held 6 ... 10 s) and opened (to 0 in 0.5 ... 1 s, 3 ... 6 s while the next
    piece is put in). The tightest reached once at least. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(1.0, 2.0))
    tops = rng.uniform(0.8, 1.0, n_pieces)
    tops[int(rng.integers(0, n_pieces))] = 1.0
    for top in tops:
        h = 0.0
        while h < top - 1e-9:
            h = min(top, h + rng.uniform(0.2, 0.35))
            p.to(rng.uniform(0.3, 0.6), h)
            p.hold(rng.uniform(0.5, 1.0) if h < top else rng.uniform(8.0, 15.0))
        p.to(rng.uniform(0.3, 0.6), top * rng.uniform(0.4, 0.6))
        p.hold(rng.uniform(3.0, 5.0))
        p.to(rng.uniform(0.3, 0.6), top * rng.uniform(0.8, 1.0))
        p.hold(rng.uniform(6.0, 10.0))
        p.to(rng.uniform(0.5, 1.0), 0.0)
        p.hold(rng.uniform(3.0, 6.0))
    return p.kn, p.t


# ---- a sprinter's arms ----

def sprinter(rng, n_runs):
    """A sprinter's arm swing (+ forward, - back), never still: for every run, out of the blocks with big swings
    (0.9 ... 1 of the reach) at a cadence rising from 1.5 ... 2 to 4 ... 4.8 swings a second over 6 ... 10 swings, held
    at the top cadence for 10 ... 18 swings (0.7 ... 0.9 of the reach), eased down to 1.2 ... 1.6 a second over 6 ...
    10 swings (0.5 ... 0.8 of the reach), then a walk back (10 ... 16 small swings, 0.2 ... 0.4 of the reach, at 0.8
    ... 1.2 a second); brought to the middle at the end. A swing is half a cycle, to one side. No holds. Returns the
    knots and the end."""
    p = _Prog()
    sd = _side(rng)
    k = 0

    def swing(f, a):
        nonlocal k
        p.to(0.5 / f * rng.uniform(0.95, 1.05), (sd if k % 2 == 0 else -sd) * a)
        k += 1
    for _ in range(n_runs):
        f0, f1 = rng.uniform(1.5, 2.0), rng.uniform(4.0, 4.8)
        n_up = int(rng.integers(6, 11))
        for j in range(n_up):
            swing(f0 + (f1 - f0) * (j + 1) / n_up, rng.uniform(0.9, 1.0))
        for _ in range(int(rng.integers(10, 19))):
            swing(f1, rng.uniform(0.7, 0.9))
        f2 = rng.uniform(1.2, 1.6)
        n_dn = int(rng.integers(6, 11))
        for j in range(n_dn):
            swing(f1 + (f2 - f1) * (j + 1) / n_dn, rng.uniform(0.5, 0.8))
        fw = rng.uniform(0.8, 1.2)
        for _ in range(int(rng.integers(10, 17))):
            swing(fw, rng.uniform(0.2, 0.4))
    p.to(rng.uniform(0.3, 0.5), 0.0)
    return p.kn, p.t


# ---- a tram driver's master controller (unipolar) ----

def tram_controller(rng, n_sections):
    """A tram driver's master controller (0 the off notch, 1 the fifth, the full power): for every section between
    stops, notched up one notch at a time (0.2 of the travel in 0.2 ... 0.4 s, each held 1 ... 3 s while the motors
    take it) to the third ... fifth, run on it (6 ... 12 s, a notch back and forward again now and then), shut off to
    coast (to 0 in 0.3 ... 0.6 s, 3 ... 6 s) and held off through the braking and the stop (6 ... 12 s). The fifth
    notch in one section at least. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(2.0, 4.0))
    tops = rng.integers(3, 6, n_sections)
    tops[int(rng.integers(0, n_sections))] = 5
    for top in tops:
        for notch in range(1, int(top) + 1):
            p.to(rng.uniform(0.2, 0.4), 0.2 * notch)
            p.hold(rng.uniform(1.0, 3.0))
        run = rng.uniform(6.0, 12.0)
        if rng.uniform() < 0.5:
            p.hold(run / 2)
            p.to(rng.uniform(0.2, 0.4), 0.2 * (top - 1))
            p.hold(rng.uniform(1.5, 3.0))
            p.to(rng.uniform(0.2, 0.4), 0.2 * top)
            p.hold(run / 2)
        else:
            p.hold(run)
        p.to(rng.uniform(0.3, 0.6), 0.0)
        p.hold(rng.uniform(3.0, 6.0) + rng.uniform(6.0, 12.0))
    return p.kn, p.t


# ---- a tango dancer's weight ----

def tango(rng, n_phrases):
    """A tango dancer's weight over the feet (+ right, - left): for every phrase, 4 ... 8 walking steps (the weight
    shifted to 0.5 ... 1 of the reach, the sides in turn, in 0.3 ... 0.6 s, a pause of 0.3 ... 1.2 s after half of
    them), an ocho (2 ... 4 pivots between 0.4 ... 0.7 either way, 0.15 ... 0.3 s each) and a pose held at its end
    (0.6 ... 1 of the reach, 1.5 ... 3 s), then the weight back over both feet (the middle, 1 ... 2 s). The full reach
    to both sides in the first phrase's steps. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.5, 1.0))
    sd = _side(rng)
    for ph in range(n_phrases):
        n_steps = int(rng.integers(4, 9))
        for k in range(n_steps):
            a = 1.0 if (ph == 0 and k < 2) else rng.uniform(0.5, 1.0)
            p.to(rng.uniform(0.3, 0.6), (sd if k % 2 == 0 else -sd) * a)
            if rng.uniform() < 0.5:
                p.hold(rng.uniform(0.3, 1.2))
        for j in range(int(rng.integers(2, 5))):
            p.to(rng.uniform(0.15, 0.3), (1.0 if j % 2 == 0 else -1.0) * _side(rng) * rng.uniform(0.4, 0.7))
        p.to(rng.uniform(0.3, 0.6), _side(rng) * rng.uniform(0.6, 1.0))
        p.hold(rng.uniform(1.5, 3.0))
        p.to(rng.uniform(0.3, 0.6), 0.0)
        p.hold(rng.uniform(1.0, 2.0))
    return p.kn, p.t


# ---- a model ship rolling in a wave tank ----

def ship_rolling(rng, n_groups):
    """A model ship's roll in a wave tank's beam sea (+ to starboard, - to port), never still: for every wave group, 6
    ... 10 rolls (a roll is half a period, to one side, the period 0.8 ... 1.4 s for the group, each half 0.9 ... 1.1 of
    it) whose amplitude swells from 0.3 ... 0.5 of the reach to 0.8 ... 1 at the group's crest (the crest of the first
    group at the full reach) and dies back; between groups a lull of 4 ... 8 small rolls (0.1 ... 0.25 of the reach).
    Brought upright at the end. No holds. Returns the knots and the end."""
    p = _Prog()
    sd = _side(rng)
    k = 0
    for g in range(n_groups):
        T = rng.uniform(0.8, 1.4)
        n = int(rng.integers(6, 11))
        crest = 1.0 if g == 0 else rng.uniform(0.8, 1.0)
        lo = rng.uniform(0.3, 0.5)
        for j in range(n):
            a = lo + (crest - lo) * math.sin(math.pi * (j + 0.5) / n)
            if g == 0 and j in (n // 2 - 1, n // 2):
                a = 1.0
            p.to(0.5 * T * rng.uniform(0.9, 1.1), (sd if k % 2 == 0 else -sd) * a)
            k += 1
        for _ in range(int(rng.integers(4, 9))):
            p.to(0.5 * T * rng.uniform(0.9, 1.1), (sd if k % 2 == 0 else -sd) * rng.uniform(0.1, 0.25))
            k += 1
    p.to(rng.uniform(0.4, 0.7), 0.0)
    return p.kn, p.t


# ---- a riveter's pneumatic hammer (unipolar) ----

def rivet_gun(rng, n_rivets):
    """A riveter's pneumatic hammer's trigger (0 let go, 1 squeezed to its stop): for every rivet, the trigger squeezed
    (to 0.85 ... 1 in 30 ... 60 ms) for a burst of 0.3 ... 0.8 s, feathered 1 ... 3 times in it (a dip to 0.5 ... 0.7 of
    the squeeze and back, 40 ... 80 ms each way, 0.1 ... 0.2 s apart), let go (in 30 ... 60 ms), 0.6 ... 1.5 s while
    the bucking bar is moved to the next rivet; sometimes (one rivet in three) a second burst after 0.3 ... 0.6 s. The
    stop reached once at least. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.5, 1.0))
    full = int(rng.integers(0, n_rivets))
    for r in range(n_rivets):
        for _ in range(1 if rng.uniform() > 1 / 3 else 2):
            a = 1.0 if r == full else rng.uniform(0.85, 1.0)
            p.to(rng.uniform(0.03, 0.06), a)
            burst = rng.uniform(0.3, 0.8)
            n_f = int(rng.integers(1, 4))
            p.hold(burst / (n_f + 1))
            for _ in range(n_f):
                p.to(rng.uniform(0.04, 0.08), a * rng.uniform(0.5, 0.7))
                p.to(rng.uniform(0.04, 0.08), a)
                p.hold(min(rng.uniform(0.1, 0.2), burst / (n_f + 1)))
            p.to(rng.uniform(0.03, 0.06), 0.0)
            p.hold(rng.uniform(0.3, 0.6))
        p.hold(rng.uniform(0.6, 1.5))
    return p.kn, p.t


# ---- an astronomer's hand paddle ----

def telescope_paddle(rng, n_targets):
    """An astronomer's hand paddle on a telescope's declination drive (+ north, - south): first guiding on a star (20
    ... 30 small corrections of 0.005 ... 0.03 of the reach either way, 0.1 ... 0.3 s each, held 0.3 ... 1 s after
    some), then slews to new targets: for each, the paddle pushed to 0.8 ... 1 of the reach (0.5 ... 1 s; the full reach
    north and south in the first two), held while the telescope runs (1.5 ... 3 s), let back to the middle (0.3 ... 0.6
    s), nudged to centre the target (1 ... 3 nudges of 0.05 ... 0.15 either way, 0.2 ... 0.4 s, each let back and held
    0.3 ... 0.8 s) and held through the exposure (2 ... 4 s). Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.5, 1.0))
    for _ in range(int(rng.integers(20, 31))):
        p.to(rng.uniform(0.1, 0.3), _side(rng) * rng.uniform(0.005, 0.03))
        if rng.uniform() < 0.4:
            p.hold(rng.uniform(0.3, 1.0))
    p.to(0.3, 0.0)
    p.hold(rng.uniform(0.5, 1.0))
    sd = _side(rng)
    for k in range(n_targets):
        a = 1.0 if k < 2 else rng.uniform(0.8, 1.0)
        p.to(rng.uniform(0.5, 1.0), (sd if k % 2 == 0 else -sd) * a)
        p.hold(rng.uniform(1.5, 3.0))
        p.to(rng.uniform(0.3, 0.6), 0.0)
        for _ in range(int(rng.integers(1, 4))):
            p.to(rng.uniform(0.2, 0.4), _side(rng) * rng.uniform(0.05, 0.15))
            p.to(rng.uniform(0.2, 0.4), 0.0)
            p.hold(rng.uniform(0.3, 0.8))
        p.hold(rng.uniform(2.0, 4.0))
    return p.kn, p.t


# ---- a karateka's kata ----

def karate_kata(rng, n_sequences):
    """A karateka's lead arm through a kata (+ a strike forward, - a block back): for every sequence, 3 ... 6
    techniques, each either a strike (out to 0.8 ... 1 of the reach in 0.08 ... 0.15 s, snapped back to 0.1 ... 0.3 in
    0.1 ... 0.2 s) or a block (back to 0.5 ... 0.8 of the reach in 0.25 ... 0.45 s, then to 0.1 ... 0.3 forward in 0.2
    ... 0.4 s), a stance held 0.4 ... 1 s after each; the sequence closed by a kiai (a strike to the full reach held 0.5
    ... 1 s) and a return to the ready stance (the middle, 1 ... 2 s). A full block back in the first sequence. Returns
    the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.5, 1.0))
    for sq in range(n_sequences):
        n_tech = int(rng.integers(3, 7))
        for k in range(n_tech):
            if rng.uniform() < 0.5 and not (sq == 0 and k == 0):
                p.to(rng.uniform(0.08, 0.15), rng.uniform(0.8, 1.0))
                p.to(rng.uniform(0.1, 0.2), rng.uniform(0.1, 0.3))
            else:
                p.to(rng.uniform(0.25, 0.45), -(1.0 if sq == 0 and k == 0 else rng.uniform(0.5, 0.8)))
                p.to(rng.uniform(0.2, 0.4), rng.uniform(0.1, 0.3))
            p.hold(rng.uniform(0.4, 1.0))
        p.to(rng.uniform(0.08, 0.15), 1.0)
        p.hold(rng.uniform(0.5, 1.0))
        p.to(rng.uniform(0.3, 0.6), 0.0)
        p.hold(rng.uniform(1.0, 2.0))
    return p.kn, p.t


# ---- a railway handcar's lever ----

def handcar(rng, n_runs):
    """A railway handcar's see-saw lever (+ the front crew's end down, - the back crew's), for every run 10 ... 20
    strokes (to 0.7 ... 1 of the reach, the ends in turn, each half a cycle of 0.4 ... 0.8 s, the run's pace), then a
    coast with the lever held level (1 ... 3 s). The full reach both ways in the first run. Returns the knots and the
    end."""
    p = _Prog()
    p.hold(rng.uniform(0.5, 1.0))
    sd = _side(rng)
    for r in range(n_runs):
        half = rng.uniform(0.4, 0.8)
        n = int(rng.integers(10, 21))
        for k in range(n):
            a = 1.0 if (r == 0 and k in (2, 3)) else rng.uniform(0.7, 1.0)
            p.to(half * rng.uniform(0.95, 1.05), (sd if k % 2 == 0 else -sd) * a)
        p.to(half, 0.0)
        p.hold(rng.uniform(1.0, 3.0))
    return p.kn, p.t

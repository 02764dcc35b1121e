"""Signals of the HOLDOUT49 set (``cases_holdout49.py``): everyday scenes, each drawn from a generator here.

Every scene is a programme of knots (time, position) joined by moves; the evaluator takes any times (a record's grid or
a finer one) and returns the position, exactly the first knot's before the programme starts and the last's after it.
The move is the smooth transition function of analysis (the one that glues bump functions, e.g. in Lee's Introduction
to Smooth Manifolds, as remembered), written from its definition, not quoted as a cam law:

    S(s) = phi(s) / (phi(s) + phi(1 - s)),  phi(x) = e^(-1/x) for x > 0, 0 otherwise,

rising from 0 to 1 over s in 0 ... 1 with every derivative 0 at both ends (it is infinitely smooth, flat to all orders
there), symmetric (S(s) + S(1 - s) = 1), its speed's peak 2 at the middle (a unit move over its time). Written as the
logistic function of 1 / (1 - s) - 1 / s, which is the same quantity without overflow. Nothing here imports hystcomp.
"""

import numpy as np
from scipy.special import expit

from .set_tools import Programme as _Prog, knots_at as _knots_at

#: the move's peak speed (a unit move over a unit time)
PEAK_SPEED = 2.0


def smooth_move(s):
    """The move 0 ... 1 over s in 0 ... 1 (0 before, 1 after): e^(-1/s) / (e^(-1/s) + e^(-1/(1-s)))."""
    s = np.asarray(s, float)
    inside = (s > 0.0) & (s < 1.0)
    si = np.where(inside, s, 0.5)
    out = expit(1.0 / (1.0 - si) - 1.0 / si)
    return np.where(inside, out, np.where(s >= 1.0, 1.0, 0.0))


def knots_at(t, knots):
    """The position on times t through knots [(time, position), ...] joined by smooth moves; the first knot's position
    before it, the last's after."""
    return _knots_at(t, knots, smooth_move)


def _side(rng):
    """A side drawn at even odds: +1 or -1 (one uniform draw)."""
    return 1.0 if rng.uniform() < 0.5 else -1.0


# ---- a canoeist's paddle (the clean case) ----

def canoe(rng, n_bouts):
    """A canoeist's paddle (its shaft's lean: + paddling on the right, - on the left): for every bout, 2 ... 3 runs of 3
    ... 5 strokes on one side, each the catch (out to 0.7 ... 1 of the reach in 0.25 ... 0.4 s), the power phase
    (held 0.3 ... 0.6 s), the J-correction (back to 0.3 ... 0.5 of it on that side in 0.15 ... 0.3 s, held 0.1 ... 0.3
    s) and the recovery (to 0.05 ... 0.15 on that side in 0.3 ... 0.5 s, held 0.2 ... 0.5 s); between the runs the
    paddle swung across to the other side; after every bout a rest, the paddle across the knees (0, held 2 ... 4 s). The
    full reach on both sides in the first bout. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.5, 1.0))
    sd = _side(rng)
    for bout in range(n_bouts):
        n_runs = int(rng.integers(2, 4))
        for run in range(n_runs):
            n_str = int(rng.integers(3, 6))
            for k in range(n_str):
                a = 1.0 if (bout == 0 and run < 2 and k == 0) else rng.uniform(0.7, 1.0)
                p.to(rng.uniform(0.25, 0.4), sd * a)
                p.hold(rng.uniform(0.3, 0.6))
                p.to(rng.uniform(0.15, 0.3), sd * a * rng.uniform(0.3, 0.5))
                p.hold(rng.uniform(0.1, 0.3))
                p.to(rng.uniform(0.3, 0.5), sd * rng.uniform(0.05, 0.15))
                p.hold(rng.uniform(0.2, 0.5))
            sd = -sd
        p.to(rng.uniform(0.5, 0.8), 0.0)
        p.hold(rng.uniform(2.0, 4.0))
    return p.kn, p.t


# ---- a nurse's blood-pressure readings (unipolar) ----

def sphygmomanometer(rng, n_readings):
    """A sphygmomanometer's cuff pressure (0 the cuff empty, 1 the gauge's full scale) through a nurse's readings: for
    every reading, the cuff pumped with the bulb (squeezes of 0.1 ... 0.16 of the scale, each in 0.25 ... 0.4 s, 0.3 ...
    0.6 s apart) to 0.85 ... 1 of it, held 2 ... 4 s, then bled down a step a heartbeat (0.02 ... 0.04 of the scale in
    0.1 s, a beat 0.7 ... 1 s) to 0.35 ... 0.5 of it, let down to 0 (in 1 ... 2 s) and 15 ... 30 s while the arm rests.
    The full scale in one reading at least. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(1.0, 2.0))
    tops = rng.uniform(0.85, 1.0, n_readings)
    tops[int(rng.integers(0, n_readings))] = 1.0
    for top in tops:
        x = 0.0
        while x < top - 1e-9:
            x = min(top, x + rng.uniform(0.1, 0.16))
            p.to(rng.uniform(0.25, 0.4), x)
            p.hold(rng.uniform(0.3, 0.6) if x < top else rng.uniform(2.0, 4.0))
        low = rng.uniform(0.35, 0.5)
        while x > low:
            x = max(low, x - rng.uniform(0.02, 0.04))
            p.to(0.1, x)
            p.hold(rng.uniform(0.6, 0.9))
        p.to(rng.uniform(1.0, 2.0), 0.0)
        p.hold(rng.uniform(15.0, 30.0))
    return p.kn, p.t


# ---- a harmonica player's breath ----

def harmonica(rng, n_phrases):
    """A harmonica player's breath (+ blowing, - drawing), never still: for every phrase, 6 ... 12 notes (blow and draw
    in turn, each to 0.5 ... 1 of the reach in 0.15 ... 0.4 s), a trill (8 ... 14 fast alternations, 0.25 ... 0.45 of
    the reach either side of 0.3 ... 0.5 of it, 0.05 ... 0.09 s each), a bend (a deep draw to 0.9 ... 1 over 0.6 ... 1
    s and back to 0.2 ... 0.4 over 0.4 ... 0.7 s) and a breath between phrases (a slow blow to 0.2 ... 0.3 in 0.8 ...
    1.3 s). The full reach both ways in the first phrase. No holds: no two knots alike in a row. Returns the knots and
    the end."""
    p = _Prog()
    sd = _side(rng)
    for ph in range(n_phrases):
        n = int(rng.integers(6, 13))
        for k in range(n):
            a = 1.0 if (ph == 0 and k < 2) else rng.uniform(0.5, 1.0)
            p.to(rng.uniform(0.15, 0.4), (sd if k % 2 == 0 else -sd) * a)
        c = _side(rng) * rng.uniform(0.3, 0.5)
        amp = rng.uniform(0.25, 0.45)
        for k in range(int(rng.integers(8, 15))):
            p.to(rng.uniform(0.05, 0.09), c + (amp if k % 2 == 0 else -amp))
        p.to(rng.uniform(0.6, 1.0), -rng.uniform(0.9, 1.0))
        p.to(rng.uniform(0.4, 0.7), -rng.uniform(0.2, 0.4))
        p.to(rng.uniform(0.8, 1.3), rng.uniform(0.2, 0.3))
    p.to(rng.uniform(0.4, 0.7), 0.0)
    return p.kn, p.t


# ---- a theatre's lighting fader (unipolar) ----

def lighting_fader(rng, n_cues):
    """A lighting operator's master fader through a play's cues (0 the blackout, 1 full): for every cue, a fade to a
    level of 0.5 ... 1 (over 2 ... 5 s), held through the scene (6 ... 14 s), now and then (one cue in three) a
    cross-fade to another level of 0.4 ... 1 (over 2 ... 4 s, held 4 ... 8 s), and every third cue a blackout (to 0 in
    0.4 ... 1 s, held 3 ... 6 s). Full once at least; a blackout at the end. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(2.0, 4.0))
    full = int(rng.integers(0, n_cues))
    for c in range(n_cues):
        p.to(rng.uniform(2.0, 5.0), 1.0 if c == full else rng.uniform(0.5, 1.0))
        p.hold(rng.uniform(6.0, 14.0))
        if rng.uniform() < 1 / 3:
            p.to(rng.uniform(2.0, 4.0), rng.uniform(0.4, 1.0))
            p.hold(rng.uniform(4.0, 8.0))
        if c % 3 == 2 or c == n_cues - 1:
            p.to(rng.uniform(0.4, 1.0), 0.0)
            p.hold(rng.uniform(3.0, 6.0))
    return p.kn, p.t


# ---- a Charleston dancer's kicks ----

def charleston(rng, n_phrases):
    """A Charleston dancer's kicking leg (+ a kick forward, - a kick back): for every phrase, 2 ... 4 rounds of a kick
    forward (to 0.6 ... 1 of the reach in 0.15 ... 0.25 s, the step back to 0 in 0.15 ... 0.25 s) and a kick back (to
    0.6 ... 1 back, the same), then 4 ... 8 swivels (0.2 ... 0.35 either way, 0.12 ... 0.2 s each), a pose (a kick held
    1 ... 2 s at 0.7 ... 1 of the reach, either way) and the feet together (0, held 0.5 ... 1.5 s). The full reach
    both ways in the first phrase. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.5, 1.0))
    for ph in range(n_phrases):
        for rd in range(int(rng.integers(2, 5))):
            for sd in (1.0, -1.0):
                a = 1.0 if (ph == 0 and rd == 0) else rng.uniform(0.6, 1.0)
                p.to(rng.uniform(0.15, 0.25), sd * a)
                p.to(rng.uniform(0.15, 0.25), 0.0)
        for k in range(int(rng.integers(4, 9))):
            p.to(rng.uniform(0.12, 0.2), (1.0 if k % 2 == 0 else -1.0) * rng.uniform(0.2, 0.35))
        p.to(rng.uniform(0.2, 0.35), _side(rng) * rng.uniform(0.7, 1.0))
        p.hold(rng.uniform(1.0, 2.0))
        p.to(rng.uniform(0.2, 0.35), 0.0)
        p.hold(rng.uniform(0.5, 1.5))
    return p.kn, p.t


# ---- a mountain bike's fork on a rocky trail ----

def mtb_fork(rng, n_sections):
    """A mountain bike's fork about its sag (+ compressed, - extended), never still: for every section of trail, 6 ...
    14 rock hits (compressed to 0.4 ... 1 of the reach in 0.04 ... 0.1 s, rebounding past the sag to 0.2 ... 0.6 of it
    extended in 0.1 ... 0.25 s and settling to within 0.1 of the sag, either way, in 0.2 ... 0.4 s), one drop (bottomed
    out to the full reach in 0.05 ... 0.1 s, rebounding to 0.8 ... 1 extended in 0.15 ... 0.3 s, settling as after a
    hit), and a smooth stretch (8 ... 16 small bobs of 0.05 ... 0.15 either way, 0.12 ... 0.25 s each). The full reach
    both ways in the first section. No holds: no two knots alike in a row. Returns the knots and the end."""
    p = _Prog()
    p.to(0.3, 0.02)
    for sc in range(n_sections):
        n_hits = int(rng.integers(6, 15))
        drop_at = int(rng.integers(0, n_hits))
        for k in range(n_hits):
            if k == drop_at:
                p.to(rng.uniform(0.05, 0.1), 1.0)
                p.to(rng.uniform(0.15, 0.3), -(1.0 if sc == 0 else rng.uniform(0.8, 1.0)))
            else:
                p.to(rng.uniform(0.04, 0.1), rng.uniform(0.4, 1.0))
                p.to(rng.uniform(0.1, 0.25), -rng.uniform(0.2, 0.6))
            p.to(rng.uniform(0.2, 0.4), _side(rng) * rng.uniform(0.01, 0.1))
        for k in range(int(rng.integers(8, 17))):
            p.to(rng.uniform(0.12, 0.25), (1.0 if k % 2 == 0 else -1.0) * rng.uniform(0.05, 0.15))
    p.to(rng.uniform(0.3, 0.5), 0.0)
    return p.kn, p.t


# ---- a hot-glue gun's trigger (unipolar) ----

def glue_gun(rng, n_beads):
    """A hot-glue gun's trigger (0 let go, 1 squeezed to its stop): for every bead, squeezed to 0.7 ... 1 in 0.08 ...
    0.15 s and held 0.5 ... 2 s while the glue runs, squeezed again 0 ... 2 times (eased to 0.3 ... 0.5 of the squeeze
    and back, 0.1 ... 0.2 s each way, held 0.3 ... 0.8 s), let go in 0.05 ... 0.1 s, 1 ... 3 s to the next joint. The
    stop reached once at least. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.5, 1.0))
    full = int(rng.integers(0, n_beads))
    for k in range(n_beads):
        a = 1.0 if k == full else rng.uniform(0.7, 1.0)
        p.to(rng.uniform(0.08, 0.15), a)
        p.hold(rng.uniform(0.5, 2.0))
        for _ in range(int(rng.integers(0, 3))):
            p.to(rng.uniform(0.1, 0.2), a * rng.uniform(0.3, 0.5))
            p.to(rng.uniform(0.1, 0.2), a)
            p.hold(rng.uniform(0.3, 0.8))
        p.to(rng.uniform(0.05, 0.1), 0.0)
        p.hold(rng.uniform(1.0, 3.0))
    return p.kn, p.t


# ---- a radio amateur's tuning knob ----

def shortwave(rng, n_stations):
    """A radio amateur's tuning knob on a shortwave receiver (+ up the band, - down it): first fine-tuning a weak
    station (20 ... 30 small turns of 0.005 ... 0.03 of the reach either way, 0.15 ... 0.4 s each, listened to for 0.3
    ... 1 s after some), then for every new station a spin to 0.7 ... 1 of the reach (the full reach up and down in the
    first two; in 0.6 ... 1.5 s), held 1 ... 3 s, fine-tuned by 2 ... 4 nudges (0.02 ... 0.06 either way, 0.2 ... 0.4
    s, held 0.4 ... 1 s), listened to (2 ... 4 s) and the knob brought back to the band's middle (0, in 0.6 ... 1.2 s,
    held 1 ... 2 s). Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.5, 1.0))
    x = 0.0
    for _ in range(int(rng.integers(20, 31))):
        x = float(np.clip(x + _side(rng) * rng.uniform(0.005, 0.03), -0.05, 0.05))
        p.to(rng.uniform(0.15, 0.4), x)
        if rng.uniform() < 0.5:
            p.hold(rng.uniform(0.3, 1.0))
    p.to(0.4, 0.0)
    p.hold(rng.uniform(0.5, 1.0))
    sd = _side(rng)
    for k in range(n_stations):
        a = (sd if k % 2 == 0 else -sd) * (1.0 if k < 2 else rng.uniform(0.7, 1.0))
        p.to(rng.uniform(0.6, 1.5), a)
        p.hold(rng.uniform(1.0, 3.0))
        y = a
        for _ in range(int(rng.integers(2, 5))):
            y = float(np.clip(y + _side(rng) * rng.uniform(0.02, 0.06), -1.0, 1.0))
            p.to(rng.uniform(0.2, 0.4), y)
            p.hold(rng.uniform(0.4, 1.0))
        p.hold(rng.uniform(2.0, 4.0))
        p.to(rng.uniform(0.6, 1.2), 0.0)
        p.hold(rng.uniform(1.0, 2.0))
    return p.kn, p.t


# ---- a cook's gas burner (unipolar) ----

def gas_burner(rng, n_dishes):
    """A cook's gas burner knob (0 off, 1 the full flame): first a sauce kept warm on the lowest flame (the knob to
    0.03 ... 0.07 and 18 ... 26 small trims of 0.005 ... 0.015 either way, within 0.02 ... 0.09, 0.2 ... 0.4 s each,
    held 1 ... 2.5 s), then for every dish the pot
    brought to the boil (to 0.85 ... 1 in 0.3 ... 0.6 s, held 4 ... 8 s), turned down to a simmer (to 0.15 ... 0.35 in
    0.3 ... 0.6 s, held 6 ... 10 s), now and then (one dish in two) a second boost (to 0.6 ... 0.9, held 3 ... 6 s, and
    back to the simmer) and off (0, in 0.3 ... 0.6 s, held 3 ... 6 s). The full flame once at least. Returns the knots
    and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.5, 1.0))
    x = rng.uniform(0.03, 0.07)
    p.to(rng.uniform(0.3, 0.6), x)
    p.hold(rng.uniform(1.0, 2.5))
    for _ in range(int(rng.integers(18, 27))):
        x = float(np.clip(x + _side(rng) * rng.uniform(0.005, 0.015), 0.02, 0.09))
        p.to(rng.uniform(0.2, 0.4), x)
        p.hold(rng.uniform(1.0, 2.5))
    full = int(rng.integers(0, n_dishes))
    for k in range(n_dishes):
        p.to(rng.uniform(0.3, 0.6), 1.0 if k == full else rng.uniform(0.85, 1.0))
        p.hold(rng.uniform(4.0, 8.0))
        low = rng.uniform(0.15, 0.35)
        p.to(rng.uniform(0.3, 0.6), low)
        p.hold(rng.uniform(6.0, 10.0))
        if rng.uniform() < 0.5:
            p.to(rng.uniform(0.3, 0.6), rng.uniform(0.6, 0.9))
            p.hold(rng.uniform(3.0, 6.0))
            p.to(rng.uniform(0.3, 0.6), low)
            p.hold(rng.uniform(3.0, 6.0))
        p.to(rng.uniform(0.3, 0.6), 0.0)
        p.hold(rng.uniform(3.0, 6.0))
    return p.kn, p.t


# ---- a mower's scythe ----

def scythe(rng, n_swaths):
    """A mower's scythe (+ the swing's right end, - its left): for every swath, 10 ... 18 strokes, each the cut from
    the right to the left (to 0.7 ... 1 of the reach in 0.5 ... 0.8 s) and the return to the right (to 0.8 ... 1 in 0.6
    ... 0.9 s, held 0.1 ... 0.3 s now and then), then the blade whetted (the scythe at 0, held 4 ... 8 s). The full
    reach both ways in the first swath. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.5, 1.0))
    for sw in range(n_swaths):
        for k in range(int(rng.integers(10, 19))):
            full = sw == 0 and k == 1
            p.to(rng.uniform(0.5, 0.8), -(1.0 if full else rng.uniform(0.7, 1.0)))
            p.to(rng.uniform(0.6, 0.9), 1.0 if full else rng.uniform(0.8, 1.0))
            if rng.uniform() < 0.3:
                p.hold(rng.uniform(0.1, 0.3))
        p.to(rng.uniform(0.5, 0.8), 0.0)
        p.hold(rng.uniform(4.0, 8.0))
    return p.kn, p.t

"""Signals of the HOLDOUT46 set (``cases_holdout46.py``): everyday scenes, each drawn from a generator here.

Every scene is a programme of knots (time, position) joined by moves; the evaluator takes any times (a record's grid or
a finer one) and returns the position, exactly the first knot's before the programme starts and the last's after it.
The move is the cam designer's "1-3 harmonic" motion law (a first and a third harmonic; the law as I remember it being
credited to Freudenstein, around 1960; written here from its definition, the attribution from memory):

    x(s) = s - (a sin(2 pi s) + b sin(6 pi s)) / (2 pi),   a = 1 - 3 b,   b = 1 / 84,

a = 1 - 3 b so that the move starts and ends at rest (its speed 1 - a cos(2 pi s) - 3 b cos(6 pi s) is 0 at both ends;
its acceleration, a sine series, is 0 there too), b = 1 / 84 so that the acceleration's peak at the quarter is flat
(its second derivative there, proportional to a - 81 b, vanishes): peak speed 2 and peak acceleration 2 pi (1 - 12 b)
= 12 pi / 7 = 5.386 times a unit move's over its time (squared). Nothing here imports hystcomp.
"""

import math

import numpy as np

from .set_tools import Programme as _Prog, knots_at as _knots_at

#: the third harmonic's coefficient b and the first's a = 1 - 3 b
B13 = 1.0 / 84.0
A13 = 1.0 - 3.0 * B13


def harmonic13(s):
    """The 1-3 harmonic move 0 ... 1 over s in 0 ... 1 (clipped outside), in closed form."""
    s = np.clip(np.asarray(s, float), 0.0, 1.0)
    return s - (A13 * np.sin(2.0 * math.pi * s) + B13 * np.sin(6.0 * math.pi * s)) / (2.0 * math.pi)


def knots_at(t, knots):
    """The position on times t through knots [(time, position), ...] joined by 1-3 harmonic moves; the first knot's
    position before it, the last's after."""
    return _knots_at(t, knots, harmonic13)


def _side(rng):
    return 1.0 if rng.uniform() < 0.5 else -1.0


def _end_to_end(p, rng, n_bursts, count, move, dwell):
    """`n_bursts` bursts of moves to 0.8 ... 1 of the reach, alternately to either side (the first side drawn), a number
    in the range `count` of them, each taking a time drawn from `move` and held for one drawn from `dwell`; after each
    burst, back to the middle (0.3 ... 0.5 s) and held there (1 ... 2 s). Appended to the programme `p`."""
    for _ in range(n_bursts):
        sd = _side(rng)
        for k in range(int(rng.integers(*count))):
            p.to(rng.uniform(*move), (sd if k % 2 == 0 else -sd) * rng.uniform(0.8, 1.0))
            p.hold(rng.uniform(*dwell))
        p.to(rng.uniform(0.3, 0.5), 0.0)
        p.hold(rng.uniform(1.0, 2.0))


# ---- a barber stropping a razor (the clean case) ----

def barber_strop(rng, n_razors):
    """A barber's razor on a hanging strop (+ drawn away, - drawn back): for every razor, strokes from end to end (0.8
    ... 1 of the strop's reach, 0.35 ... 0.7 s each), the razor rolled over on its spine at every end (a dwell of 0.08
    ... 0.2 s), 8 ... 14 strokes; then the edge tried on the thumbnail, the razor held at the strop's middle (1 ... 2
    s). Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.5, 1.0))
    _end_to_end(p, rng, n_razors, (8, 15), (0.35, 0.7), (0.08, 0.2))
    return p.kn, p.t


# ---- an organist's swell pedal (unipolar) ----

def swell_pedal(rng, n_pieces):
    """A church organ's swell pedal (0 the box's shutters closed, 1 wide open): for every piece, a crescendo in steps
    (each 0.15 ... 0.3 of the travel in 0.3 ... 0.6 s, held through a phrase, 5 ... 12 s) to 0.7 ... 1 (wide open once
    at least), a diminuendo to 0.2 ... 0.5 of the top held 5 ... 10 s, the box closed for the last chord and the pause
    before the next (at 0, 3 ... 5 s). Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(1.0, 2.0))
    tops = rng.uniform(0.7, 1.0, n_pieces)
    tops[int(rng.integers(0, n_pieces))] = 1.0
    for top in tops:
        h = 0.0
        while h < top - 1e-9:
            h = min(top, h + rng.uniform(0.15, 0.3))
            p.to(rng.uniform(0.3, 0.6), h)
            p.hold(rng.uniform(5.0, 12.0))
        p.to(rng.uniform(0.4, 0.8), h * rng.uniform(0.2, 0.5))
        p.hold(rng.uniform(5.0, 10.0))
        p.to(rng.uniform(0.3, 0.6), 0.0)
        p.hold(rng.uniform(3.0, 5.0))
    return p.kn, p.t


# ---- log birling ----

def log_birling(rng, n_bouts):
    """A log roller's feet on a floating log (+ the log rolled toward the far bank, - back), never still (the log
    would throw the roller): from the first instant, for every bout, a run of quick steps (0.4 ... 0.75 of the reach
    either way, 0.07 ... 0.14 s a step, 8 ... 16 of them), then a sudden check and reversal of the roll (2 or 3 long
    swings to 0.85 ... 1 of the reach, 0.4 ... 0.8 s each), the next bout's steps straight after; the roll brought to
    the middle at the end. No holds. Returns the knots and the end."""
    p = _Prog()
    for _ in range(n_bouts):
        a = rng.uniform(0.4, 0.75)
        sd = _side(rng)
        for k in range(int(rng.integers(8, 17))):
            p.to(rng.uniform(0.07, 0.14), (sd if k % 2 == 0 else -sd) * a * rng.uniform(0.85, 1.0))
        sd = _side(rng)
        for k in range(int(rng.integers(2, 4))):
            p.to(rng.uniform(0.4, 0.8), (sd if k % 2 == 0 else -sd) * rng.uniform(0.85, 1.0))
    p.to(rng.uniform(0.2, 0.4), 0.0)
    return p.kn, p.t


# ---- a bartender's beer tap (unipolar) ----

def beer_tap(rng, n_pints):
    """A bartender's beer tap (0 shut, 1 fully open): for every pint, the handle pulled (to 0.85 ... 1 in 0.3 ... 0.6 s;
    fully open once at least), held while the glass fills (3 ... 6 s), eased back to 0.3 ... 0.5 of it for the head (1
    ... 2 s), shut (0.2 ... 0.4 s), and the pint served before the next (2 ... 6 s at 0). Returns the knots and the
    end."""
    p = _Prog()
    p.hold(rng.uniform(1.0, 2.0))
    tops = rng.uniform(0.85, 1.0, n_pints)
    tops[int(rng.integers(0, n_pints))] = 1.0
    for top in tops:
        p.to(rng.uniform(0.3, 0.6), top)
        p.hold(rng.uniform(3.0, 6.0))
        p.to(rng.uniform(0.2, 0.4), top * rng.uniform(0.3, 0.5))
        p.hold(rng.uniform(1.0, 2.0))
        p.to(rng.uniform(0.2, 0.4), 0.0)
        p.hold(rng.uniform(2.0, 6.0))
    return p.kn, p.t


# ---- a flag semaphore signaller ----

#: a semaphore arm's positions at 45 deg steps, from straight down (-1) to straight up (+1)
SEMAPHORE = (-1.0, -0.5, 0.0, 0.5, 1.0)


def semaphore(rng, n_words):
    """One arm of a flag semaphore signaller (+ raised, - lowered): for every word, 3 ... 6 letters, the arm swung to
    one of its positions at 45 deg steps (straight down, low, level, high, straight up: -1, -0.5, 0, 0.5, 1; never the
    same twice running) in 0.2 ... 0.35 s and held 0.5 ... 0.9 s while the letter is read; the arm straight up and
    straight down at least once each in the message; between words the "rest" (the arm level, 1 ... 1.5 s). Returns the
    knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.5, 1.0))
    letters = []
    for _ in range(n_words):
        word = []
        last = 0.0
        for _ in range(int(rng.integers(3, 7))):
            pos = last
            while pos == last:
                pos = SEMAPHORE[int(rng.integers(0, 5))]
            word.append(pos)
            last = pos
        letters.append(word)
    # the message spells both extremes somewhere: force them into two letters if the draw missed them
    flat = [(i, j) for i, w in enumerate(letters) for j in range(len(w))]
    for ext in (1.0, -1.0):
        if not any(letters[i][j] == ext for i, j in flat):
            for _ in range(100):
                i, j = flat[int(rng.integers(0, len(flat)))]
                w = letters[i]
                ok = (j == 0 or w[j - 1] != ext) and (j == len(w) - 1 or w[j + 1] != ext) and w[j] != -ext
                if ok:
                    w[j] = ext
                    break
    for w in letters:
        for pos in w:
            p.to(rng.uniform(0.2, 0.35), pos)
            p.hold(rng.uniform(0.5, 0.9))
        p.to(rng.uniform(0.2, 0.35), 0.0)
        p.hold(rng.uniform(1.0, 1.5))
    return p.kn, p.t


# ---- a cowboy's lasso ----

def lasso(rng, n_throws):
    """A roper's lasso seen from the side (one coordinate of the loop's swing, + out, - in), the loop kept spinning from
    the first instant: for every throw, the loop built up over 5 ... 9 turns (0.35 ... 0.5 s a turn, each half a swing
    to one side; the swing growing from 0.2 ... 0.3 of the reach to 0.85 ... 1), the throw (out to 0.9 ... 1 in 0.25 ...
    0.4 s), the rope hauled in (back to -0.85 ... -1 in 0.6 ... 1 s) and swung back through the middle into the next
    loop (0.3 ... 0.5 s). No holds. Returns the knots and the end."""
    p = _Prog()
    for _ in range(n_throws):
        turns = int(rng.integers(5, 10))
        a0, a1 = rng.uniform(0.2, 0.3), rng.uniform(0.85, 1.0)
        T = rng.uniform(0.35, 0.5)
        sd = _side(rng)
        for k in range(2 * turns):
            a = a0 + (a1 - a0) * k / (2 * turns - 1)
            p.to(T / 2, (sd if k % 2 == 0 else -sd) * a)
        p.to(rng.uniform(0.25, 0.4), rng.uniform(0.9, 1.0))
        p.to(rng.uniform(0.6, 1.0), -rng.uniform(0.85, 1.0))
        p.to(rng.uniform(0.3, 0.5), 0.0)
    return p.kn, p.t


# ---- a drummer's hi-hat pedal (unipolar) ----

def hi_hat(rng, n_bars):
    """A drummer's hi-hat pedal (0 the cymbals open, 1 pressed shut): for every bar, foot "chicks" on the beats (the
    pedal pressed to 0.85 ... 1 in 0.05 ... 0.09 s, let up in 0.06 ... 0.12 s; 4 beats 0.3 ... 0.5 s apart), a bar now
    and then played closed (the pedal held down 1 ... 2 s) or splashed (a quick press and release, then the hat left
    ringing open 0.6 ... 1.2 s); pressed fully shut at least once. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.8, 1.5))
    full = int(rng.integers(0, n_bars))
    for j in range(n_bars):
        beat = rng.uniform(0.3, 0.5)
        kind = rng.uniform()
        if kind < 0.2:
            p.to(rng.uniform(0.05, 0.09), rng.uniform(0.85, 1.0) if j != full else 1.0)
            p.hold(rng.uniform(1.0, 2.0))
            p.to(rng.uniform(0.06, 0.12), 0.0)
        elif kind < 0.35:
            p.to(rng.uniform(0.05, 0.09), rng.uniform(0.85, 1.0) if j != full else 1.0)
            p.to(rng.uniform(0.06, 0.12), 0.0)
            p.hold(rng.uniform(0.6, 1.2))
        else:
            for k in range(4):
                down, up = rng.uniform(0.05, 0.09), rng.uniform(0.06, 0.12)
                p.to(down, 1.0 if (j == full and k == 0) else rng.uniform(0.85, 1.0))
                p.to(up, 0.0)
                p.hold(max(beat - down - up, 0.05))
    p.hold(rng.uniform(0.8, 1.5))
    return p.kn, p.t


# ---- a tightrope walker's balancing pole ----

def tightrope(rng, n_gusts):
    """A tightrope walker's balancing pole (+ tipped right, - left): first the walker's small corrections while the air
    is still (three bouts of small tips, 0.01 ... 0.03 of the reach, 0.2 ... 0.4 s each, 6 ... 12 a bout, 0.5 ... 1 s
    apart), then gusts: for every gust, big recoveries to 0.8 ... 1 either way (0.3 ... 0.6 s each, 3 ... 6 of them,
    0.1 ... 0.4 s apart), the pole brought level after it (1 ... 2 s). Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.5, 1.0))
    for _ in range(3):
        for _ in range(int(rng.integers(6, 13))):
            p.to(rng.uniform(0.2, 0.4), _side(rng) * rng.uniform(0.01, 0.03))
        p.to(0.25, 0.0)
        p.hold(rng.uniform(0.5, 1.0))
    _end_to_end(p, rng, n_gusts, (3, 7), (0.3, 0.6), (0.1, 0.4))
    return p.kn, p.t


# ---- a gondolier's oar ----

def gondolier(rng, n_reaches):
    """A gondolier's oar in its forcola (+ the blade pushed aft, - brought forward): for every reach of canal, strokes
    (the push to 0.8 ... 1 of the reach in 0.6 ... 1 s, the feathered return to -0.6 ... -1 in 0.5 ... 0.8 s; 6 ... 12
    of them; the push's side fixed by the forcola), the oar held still while the gondola glides round a corner (at the
    middle, 1.5 ... 3 s); the far forward stroke (to -0.9 ... -1) at least once per reach. Returns the knots and the
    end."""
    p = _Prog()
    p.hold(rng.uniform(0.5, 1.0))
    sd = _side(rng)
    for _ in range(n_reaches):
        n = int(rng.integers(6, 13))
        deep = int(rng.integers(0, n))
        for k in range(n):
            p.to(rng.uniform(0.6, 1.0), sd * rng.uniform(0.8, 1.0))
            p.to(rng.uniform(0.5, 0.8), -sd * (rng.uniform(0.9, 1.0) if k == deep else rng.uniform(0.6, 1.0)))
        p.to(rng.uniform(0.3, 0.5), 0.0)
        p.hold(rng.uniform(1.5, 3.0))
    return p.kn, p.t


# ---- a sommelier swirling a glass ----

def wine_swirl(rng, n_wines):
    """A sommelier's glass seen from one side (+ swirled out, - in): for every wine, the glass swirled (circles of 0.6
    ... 0.9 s, each half a swing to one side of 0.7 ... 1 of the reach, 4 ... 8 circles), tilted against the light and
    held (at 0.3 ... 0.5 of the reach, 1 ... 2 s), brought back to the middle for the nose and the sip (1.5 ... 3 s).
    Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.5, 1.0))
    for _ in range(n_wines):
        T = rng.uniform(0.6, 0.9)
        sd = _side(rng)
        for k in range(2 * int(rng.integers(4, 9))):
            p.to(T / 2, (sd if k % 2 == 0 else -sd) * rng.uniform(0.7, 1.0))
        p.to(rng.uniform(0.3, 0.5), _side(rng) * rng.uniform(0.3, 0.5))
        p.hold(rng.uniform(1.0, 2.0))
        p.to(rng.uniform(0.3, 0.5), 0.0)
        p.hold(rng.uniform(1.5, 3.0))
    return p.kn, p.t

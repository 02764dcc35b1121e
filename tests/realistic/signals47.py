"""Signals of the HOLDOUT47 set (``cases_holdout47.py``): everyday scenes, each drawn from a generator here.

Every scene is a programme of knots (time, position) joined by moves; the evaluator takes any times (a record's grid or
a finer one) and returns the position, exactly the first knot's before the programme starts and the last's after it.
The move is a motion controller's jerk-limited "S-curve" (the seven-segment profile: the jerk +J, 0, -J while the speed
rises, a cruise, then -J, 0, +J while it falls; e.g. Lambrechts, Boerlage & Steinbuch, "Trajectory planning and
feedforward design for electromechanical motion systems", Control Eng. Practice 13 (2005) 145, as remembered; written
here from its definition), with each jerk phase and each constant-acceleration phase an eighth of the move and the
cruise a quarter:

    the jerk on s in 0 ... 1: +J on [0, 1/8), 0 on [1/8, 1/4), -J on [1/4, 3/8), 0 on [3/8, 5/8), -J on [5/8, 3/4),
    0 on [3/4, 7/8), +J on [7/8, 1],

J = 1 / (j (j + c)(1 - 2 j - c)) with j = c = 1/8 (= 256 / 5, so that the move covers 1: the speed's peak J j (j + c)
held over the cruise and, by the profile's symmetry, over half of each speed change): the speed and the acceleration 0
at both ends, the acceleration's peak J j = 6.4 and the speed's peak J j (j + c) = 1.6 times a unit move's over its
time. Nothing here imports hystcomp.
"""

import numpy as np

from .set_tools import Programme as _Prog, knots_at as _knots_at

#: the jerk phase's and the constant-acceleration phase's share of the move
JF = 1.0 / 8.0
AF = 1.0 / 8.0
#: the segments' bounds on 0 ... 1 and their jerks (in units of J)
BOUNDS = np.array([0.0, JF, JF + AF, 2 * JF + AF, 1 - 2 * JF - AF, 1 - JF - AF, 1 - JF, 1.0])
JERKS = np.array([1.0, 0.0, -1.0, 0.0, -1.0, 0.0, 1.0])
#: the jerk J that makes the move cover 1
J_SC = 1.0 / (JF * (JF + AF) * (1.0 - 2.0 * JF - AF))


def _segment_starts():
    """The position, speed and acceleration at every segment's start (jerk J_SC), by integrating the constant jerks
    exactly."""
    st = [(0.0, 0.0, 0.0)]
    for k in range(7):
        p, v, a = st[-1]
        h = BOUNDS[k + 1] - BOUNDS[k]
        jk = J_SC * JERKS[k]
        st.append((p + v * h + a * h * h / 2 + jk * h ** 3 / 6, v + a * h + jk * h * h / 2, a + jk * h))
    return np.array(st)


_STARTS = _segment_starts()


def scurve(s):
    """The S-curve move 0 ... 1 over s in 0 ... 1 (clipped outside), piecewise cubic in closed form."""
    s = np.clip(np.asarray(s, float), 0.0, 1.0)
    k = np.clip(np.searchsorted(BOUNDS, s, side="right") - 1, 0, 6)
    h = s - BOUNDS[k]
    p, v, a = _STARTS[k, 0], _STARTS[k, 1], _STARTS[k, 2]
    return p + v * h + a * h * h / 2 + J_SC * JERKS[k] * h ** 3 / 6


def knots_at(t, knots):
    """The position on times t through knots [(time, position), ...] joined by S-curve moves; the first knot's position
    before it, the last's after."""
    return _knots_at(t, knots, scurve)


def _side(rng):
    """A side drawn at even odds: +1 or -1 (one uniform draw)."""
    return float(np.sign(rng.uniform() - 0.5) or 1.0)


# ---- a bobsleigh pilot's steering (the clean case) ----

def bobsleigh(rng, n_stretches):
    """A bobsleigh pilot's steering rings (+ pulled right, - left): for every stretch of the track, 3 ... 5 curves, each
    steered into (to 0.8 ... 1 of the reach toward its side in 0.25 ... 0.4 s, the side drawn), held through it (0.5 ...
    1.2 s) with a correction or two (a few tenths back and forth, 0.15 ... 0.3 s each), let out to the straight (to the
    middle in 0.25 ... 0.4 s, held 0.3 ... 0.8 s); a longer straight after every stretch (held at the middle 1 ... 2
    s). Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.5, 1.0))
    for _ in range(n_stretches):
        for _ in range(int(rng.integers(3, 6))):
            sd = _side(rng)
            a = rng.uniform(0.8, 1.0)
            p.to(rng.uniform(0.25, 0.4), sd * a)
            p.hold(rng.uniform(0.5, 1.2))
            for _ in range(int(rng.integers(1, 3))):
                p.to(rng.uniform(0.15, 0.3), sd * a * rng.uniform(0.6, 0.85))
                p.to(rng.uniform(0.15, 0.3), sd * a * rng.uniform(0.9, 1.0))
            p.to(rng.uniform(0.25, 0.4), 0.0)
            p.hold(rng.uniform(0.3, 0.8))
        p.hold(rng.uniform(1.0, 2.0))
    return p.kn, p.t


# ---- a cider press (unipolar) ----

def cider_press(rng, n_cheeses):
    """A cider press's screw (0 slack, 1 the full pressure): for every cheese of pomace, the screw turned down in steps
    (0.25 ... 0.4 of the travel in 1 ... 2 s each, the juice left to run 4 ... 8 s after each), the full pressure held
    10 ... 15 s, eased to 0.3 ... 0.5 of it while the cheese is cut and restacked (5 ... 8 s), turned down again to 0.8
    ... 1 and held 8 ... 12 s, then slackened off for the next cheese (at 0, 4 ... 6 s). The full pressure is reached
    once at least. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(1.0, 2.0))
    tops = rng.uniform(0.8, 1.0, n_cheeses)
    tops[int(rng.integers(0, n_cheeses))] = 1.0
    for top in tops:
        h = 0.0
        while h < top - 1e-9:
            h = min(top, h + rng.uniform(0.25, 0.4))
            p.to(rng.uniform(1.0, 2.0), h)
            p.hold(rng.uniform(4.0, 8.0) if h < top else rng.uniform(10.0, 15.0))
        p.to(rng.uniform(1.0, 2.0), top * rng.uniform(0.3, 0.5))
        p.hold(rng.uniform(5.0, 8.0))
        p.to(rng.uniform(1.0, 2.0), top * rng.uniform(0.8, 1.0))
        p.hold(rng.uniform(8.0, 12.0))
        p.to(rng.uniform(1.0, 2.0), 0.0)
        p.hold(rng.uniform(4.0, 6.0))
    return p.kn, p.t


# ---- a maraca player ----

def maracas(rng, n_phrases):
    """A maraca player's hand (+ shaken forward, - back), never still: for every phrase, 8 ... 16 shakes at its own
    tempo (2 ... 6 shakes a second, each half a swing to one side), the swings 0.5 ... 1 of the reach with accents to
    0.9 ... 1 on every fourth; the next phrase straight after; brought to the middle at the end. No holds. Returns the
    knots and the end."""
    p = _Prog()
    for _ in range(n_phrases):
        f = rng.uniform(2.0, 6.0)
        sd = _side(rng)
        for k in range(2 * int(rng.integers(8, 17))):
            a = rng.uniform(0.9, 1.0) if k % 4 == 0 else rng.uniform(0.5, 0.9)
            p.to(0.5 / f * rng.uniform(0.9, 1.1), (sd if k % 2 == 0 else -sd) * a)
    p.to(rng.uniform(0.2, 0.4), 0.0)
    return p.kn, p.t


# ---- a lever espresso machine (unipolar) ----

def espresso_lever(rng, n_shots):
    """A lever espresso machine's group (0 the lever up and the piston at rest, 1 the spring's full pressure): for every
    shot, the lever pulled down to pre-infuse (0.25 ... 0.4 in 0.5 ... 1 s, held 3 ... 6 s), let go (the spring to 0.85
    ... 1 in 0.3 ... 0.6 s, held 2 ... 4 s), the pressure falling as the piston rises (to 0.5 ... 0.7 over 8 ... 14 s,
    in two stages), the lever up at the end (to 0 in 0.5 ... 1 s), the basket knocked out and refilled (at 0, 6 ... 12
    s). The spring's full pressure reached once at least. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(1.0, 2.0))
    tops = rng.uniform(0.85, 1.0, n_shots)
    tops[int(rng.integers(0, n_shots))] = 1.0
    for top in tops:
        p.to(rng.uniform(0.5, 1.0), rng.uniform(0.25, 0.4))
        p.hold(rng.uniform(3.0, 6.0))
        p.to(rng.uniform(0.3, 0.6), top)
        p.hold(rng.uniform(2.0, 4.0))
        end = top * rng.uniform(0.5, 0.7)
        p.to(rng.uniform(4.0, 7.0), 0.5 * (top + end))
        p.to(rng.uniform(4.0, 7.0), end)
        p.to(rng.uniform(0.5, 1.0), 0.0)
        p.hold(rng.uniform(6.0, 12.0))
    return p.kn, p.t


# ---- a ship's engine-order telegraph ----

#: the telegraph's orders from full astern (-1) to full ahead (+1)
TELEGRAPH = (-1.0, -0.6, -0.3, 0.0, 0.3, 0.6, 1.0)


def engine_telegraph(rng, n_orders):
    """A ship's engine-order telegraph in harbour (+ ahead, - astern): n_orders orders, each a position of the handle
    (full, half and slow astern, stop, slow, half and full ahead: -1, -0.6, -0.3, 0, 0.3, 0.6, 1; never the same
    twice running, moving at most three positions at a time while manoeuvring), the handle swung there in 0.3 ... 0.6 s
    and held while the engine answers (1 ... 3 s); full ahead and full astern rung once each at least. Returns the knots
    and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.5, 1.0))
    orders, i = [], 3
    for _ in range(n_orders):
        j = i
        while j == i:
            j = int(np.clip(i + rng.integers(-3, 4), 0, 6))
        orders.append(j)
        i = j
    for ext in (0, 6):
        if ext not in orders:
            k = int(rng.integers(1, n_orders - 1))
            orders[k] = ext
            # the neighbours must differ from the order forced in
            for q in (k - 1, k + 1):
                if 0 <= q < n_orders and orders[q] == ext:
                    orders[q] = 3
    for j in orders:
        p.to(rng.uniform(0.3, 0.6), TELEGRAPH[j])
        p.hold(rng.uniform(1.0, 3.0))
    p.to(rng.uniform(0.3, 0.6), 0.0)
    p.hold(rng.uniform(1.0, 2.0))
    return p.kn, p.t


# ---- a rodeo bull ----

def rodeo_bull(rng, n_rides):
    """A mechanical rodeo bull's buck (+ nose up, - down), kept moving from the first instant: for every ride, bucks
    (swings to 0.7 ... 1 of the reach, either way in turn, 0.2 ... 0.45 s each, 12 ... 24 of them) with spins between
    (4 ... 8 smaller swings, 0.3 ... 0.6 of the reach, 0.15 ... 0.3 s each), the rider thrown and the bull brought round
    through the middle (0.4 ... 0.7 s) into the next ride. No holds. Returns the knots and the end."""
    p = _Prog()
    for _ in range(n_rides):
        sd = _side(rng)
        for k in range(int(rng.integers(12, 25))):
            p.to(rng.uniform(0.2, 0.45), (sd if k % 2 == 0 else -sd) * rng.uniform(0.7, 1.0))
            if k % 6 == 5:
                for q in range(int(rng.integers(4, 9))):
                    p.to(rng.uniform(0.15, 0.3), (-sd if q % 2 == 0 else sd) * rng.uniform(0.3, 0.6))
        p.to(rng.uniform(0.4, 0.7), 0.0)
    p.to(rng.uniform(0.2, 0.3), 0.1 * _side(rng))
    p.to(rng.uniform(0.2, 0.3), 0.0)
    return p.kn, p.t


# ---- a telegraphist's Morse key (unipolar) ----

#: Morse code of the letters a telegraphist sends (dots and dashes)
MORSE = {"A": ".-", "B": "-...", "C": "-.-.", "D": "-..", "E": ".", "F": "..-.", "G": "--.", "H": "....", "I": "..",
         "J": ".---", "K": "-.-", "L": ".-..", "M": "--", "N": "-.", "O": "---", "P": ".--.", "Q": "--.-", "R": ".-.",
         "S": "...", "T": "-", "U": "..-", "V": "...-", "W": ".--", "X": "-..-", "Y": "-.--", "Z": "--.."}


def morse_key(rng, n_words):
    """A telegraphist's straight key (0 up, 1 pressed to its stop): n_words words of 3 ... 6 random letters sent at 10
    ... 16 words a minute (a dot's unit 1.2 / wpm s): a dot pressed for one unit, a dash for three, a unit's gap inside
    a letter, three between letters, seven between words; each press down to 0.85 ... 1 of the travel (the stop once at
    least) and each release in 15 ... 30 ms. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.5, 1.0))
    unit = 1.2 / rng.uniform(10.0, 16.0)
    letters = list(MORSE)
    full = None
    presses = []
    for _ in range(n_words):
        word = [letters[int(rng.integers(0, 26))] for _ in range(int(rng.integers(3, 7)))]
        presses.append([MORSE[c] for c in word])
    n_press = sum(len(code) for w in presses for code in w)
    full = int(rng.integers(0, n_press))
    i = 0
    for w in presses:
        for code in w:
            for mark in code:
                mv = rng.uniform(0.015, 0.030)
                depth = 1.0 if i == full else rng.uniform(0.85, 1.0)
                p.to(mv, depth)
                p.hold((1.0 if mark == "." else 3.0) * unit - mv)
                p.to(mv, 0.0)
                p.hold(unit - mv)
                i += 1
            p.hold(2.0 * unit)
        p.hold(4.0 * unit)
    p.hold(rng.uniform(0.5, 1.0))
    return p.kn, p.t


# ---- a helicopter pilot's cyclic ----

def helicopter_cyclic(rng, n_manoeuvres):
    """A helicopter pilot's cyclic stick, fore and aft (+ forward, - back): first a hover, the stick barely moved
    (small corrections of 0.005 ... 0.025 of the reach either way, 0.2 ... 0.5 s each, 15 ... 25 of them, now and then
    held 0.3 ... 1 s), then manoeuvres: for each, the stick to 0.8 ... 1 of the reach (0.3 ... 0.6 s), held 0.5 ...
    1.5 s, through to the other side (to 0.6 ... 1), held, and back to the middle (0.3 ... 0.6 s, held 1 ... 2 s);
    forward and back to the full reach once each at least. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.5, 1.0))
    for _ in range(int(rng.integers(15, 26))):
        p.to(rng.uniform(0.2, 0.5), _side(rng) * rng.uniform(0.005, 0.025))
        if rng.uniform() < 0.3:
            p.hold(rng.uniform(0.3, 1.0))
    p.to(0.3, 0.0)
    p.hold(rng.uniform(0.5, 1.0))
    sd = _side(rng)
    for k in range(n_manoeuvres):
        a = 1.0 if k < 2 else rng.uniform(0.8, 1.0)
        s1 = sd if k % 2 == 0 else -sd
        p.to(rng.uniform(0.3, 0.6), s1 * a)
        p.hold(rng.uniform(0.5, 1.5))
        p.to(rng.uniform(0.4, 0.8), -s1 * rng.uniform(0.6, 1.0))
        p.hold(rng.uniform(0.5, 1.5))
        p.to(rng.uniform(0.3, 0.6), 0.0)
        p.hold(rng.uniform(1.0, 2.0))
    return p.kn, p.t


# ---- a puppeteer's marionette ----

def puppeteer(rng, n_scenes):
    """A marionette's control bar, tilted (+ right, - left): for every scene, 3 ... 5 rounds of a dance (a jig: 6 ... 12
    quick tilts to 0.5 ... 0.9 of the reach, either way in turn, 0.12 ... 0.25 s each) ending in a pose struck (the bar
    tilted to 0.6 ... 1 of the reach, the side drawn, in 0.15 ... 0.3 s) and held while the puppet speaks (2 ... 4 s);
    between scenes the puppet rests upright (at the middle, 2 ... 3 s); the full tilt to both sides in the first
    scene's poses. Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.5, 1.0))
    fulls = [1.0, -1.0]
    for s in range(n_scenes):
        for k in range(int(rng.integers(3, 6))):
            sd = _side(rng)
            for j in range(int(rng.integers(6, 13))):
                p.to(rng.uniform(0.12, 0.25), (sd if j % 2 == 0 else -sd) * rng.uniform(0.5, 0.9))
            pos = fulls[k] if (s == 0 and k < 2) else _side(rng) * rng.uniform(0.6, 1.0)
            p.to(rng.uniform(0.15, 0.3), pos)
            p.hold(rng.uniform(2.0, 4.0))
        p.to(rng.uniform(0.2, 0.4), 0.0)
        p.hold(rng.uniform(2.0, 3.0))
    return p.kn, p.t


# ---- a juggler ----

def juggler(rng, n_patterns):
    """A juggler's right hand, side to side (+ out, - in): for every pattern, a cascade of throws and catches (the hand
    carried in to 0.7 ... 1 of the reach and out again, half a cycle of 0.25 ... 0.35 s each way, 10 ... 20 cycles),
    then the balls caught and held (the hand at 0.2 ... 0.4 either way, 1 ... 2 s) and brought to the middle (held 1 ...
    2 s). Returns the knots and the end."""
    p = _Prog()
    p.hold(rng.uniform(0.5, 1.0))
    for _ in range(n_patterns):
        half = rng.uniform(0.25, 0.35)
        sd = _side(rng)
        for k in range(2 * int(rng.integers(10, 21))):
            p.to(half, (sd if k % 2 == 0 else -sd) * rng.uniform(0.7, 1.0))
        p.to(rng.uniform(0.3, 0.5), _side(rng) * rng.uniform(0.2, 0.4))
        p.hold(rng.uniform(1.0, 2.0))
        p.to(rng.uniform(0.3, 0.5), 0.0)
        p.hold(rng.uniform(1.0, 2.0))
    return p.kn, p.t

"""Signals of the HOLDOUT40 set (``cases_holdout40.py``): everyday scenes, each drawn from a generator here.

Every scene is a programme of knots (time, position) joined by moves, or of oscillating bouts; the evaluators take any
times (a record's grid or a finer one) and return the position, exactly 0 before the programme starts. The moves: a
cycloidal move s - sin(2 pi s) / (2 pi) (zero speed and acceleration at both ends: a hand's or a motor's point-to-point
move, e.g. the cam laws of Rothbart, *Cams*, 1956, from memory) or a trapezoidal-speed move (a constant speed between
short ramps: a bow's stroke). Nothing here imports hystcomp.
"""

import math

import numpy as np

from .set_tools import knots_at as _knots_at


def cycloidal(s):
    """The cycloidal move 0 ... 1 over s in 0 ... 1 (clipped outside)."""
    s = np.clip(np.asarray(s, float), 0.0, 1.0)
    return s - np.sin(2 * math.pi * s) / (2 * math.pi)


def trapezoid(s, a):
    """The trapezoidal-speed move 0 ... 1 over s in 0 ... 1: speed ramps of a share a at either end (a < 0.5)."""
    s = np.clip(np.asarray(s, float), 0.0, 1.0)
    vmax = 1.0 / (1.0 - a)
    return np.where(s < a, 0.5 * vmax * s * s / a,
                    np.where(s > 1 - a, 1.0 - 0.5 * vmax * (1.0 - s) ** 2 / a, vmax * (s - a / 2)))


def knots_eval(t, knots, kind="cyc", a=0.15):
    """The position on times t through knots [(time, position), ...] joined by cycloidal (kind "cyc") or trapezoidal
    ("trap", ramps a) moves; the first knot's position before it, the last's after."""
    return _knots_at(t, knots, cycloidal if kind == "cyc" else (lambda s: trapezoid(s, a)))


def bouts_eval(t, bouts):
    """Oscillating bouts [(t0, f, n, amp_in, amp_out, shape)]: amp(t) sin(2 pi f (t - t0)) over n whole cycles, the
    amplitude linear from amp_in to amp_out, shape "sin" or a sharpened swing ("flick": sign(s) |s|^0.6); 0 outside."""
    t = np.asarray(t, float)
    x = np.zeros(len(t))
    for t0, f, n, a0, a1, shape in bouts:
        dur = n / f
        m = (t >= t0) & (t < t0 + dur)
        tt = t[m] - t0
        s = np.sin(2 * math.pi * f * tt)
        if shape == "flick":
            s = np.sign(s) * np.abs(s) ** 0.6
        x[m] += (a0 + (a1 - a0) * tt / dur) * s
    return x


# ---- a windscreen wiper through a shower (the clean case) ----

def windscreen_wiper(rng):
    """The wiper arm's angle about the middle of its arc (the record starting with the arm there): intermittent wipes
    (one sweep each way, 1.5 ... 2.5 s apart), normal (0.9 ... 1.1 s a cycle) and fast (0.6 ... 0.75 s) continuous
    wiping,
    intermittent again, and the arm brought back to the middle. Returns the knots and the end."""
    t, kn = 0.0, [(0.0, 0.0)]
    t += rng.uniform(0.5, 1.0)
    kn.append((t, 0.0))

    def sweep(t, period, n):
        for _ in range(n):
            t += period / 2 * rng.uniform(0.97, 1.03)
            kn.append((t, 1.0 * rng.uniform(0.97, 1.0)))
            t += period / 2 * rng.uniform(0.97, 1.03)
            kn.append((t, -1.0 * rng.uniform(0.97, 1.0)))
        return t
    t += 0.3
    kn.append((t, -1.0))
    for _ in range(int(rng.integers(1, 3))):                         # intermittent
        t = sweep(t, rng.uniform(1.0, 1.2), 1)
        t += rng.uniform(1.5, 2.5)
        kn.append((t, kn[-1][1]))
    t = sweep(t, rng.uniform(0.9, 1.1), int(rng.integers(4, 8)))    # normal
    t = sweep(t, rng.uniform(0.6, 0.75), int(rng.integers(5, 9)))   # fast
    t = sweep(t, rng.uniform(0.9, 1.1), int(rng.integers(3, 5)))
    for _ in range(int(rng.integers(1, 3))):
        t += rng.uniform(1.5, 2.5)
        kn.append((t, kn[-1][1]))
        t = sweep(t, rng.uniform(1.0, 1.2), 1)
    t += 0.5
    kn.append((t, 0.0))
    t += 1.0
    kn.append((t, 0.0))
    return kn, t


# ---- a lift through a morning (creep; unipolar) ----

def lift_morning(rng, n_trips):
    """The car's height (0 the ground floor, 1 the top floor of 5 ... 8): trips between random floors, 3 ... 4 s a floor
    at full speed (cycloidal moves of 2.5 + 1.8 floors^0.7 s), the doors open 6 ... 20 s at every stop, back at the
    ground floor at the end. Returns the knots and the end."""
    top = int(rng.integers(5, 9))
    t, f, kn = 0.0, 0, [(0.0, 0.0)]
    t += rng.uniform(1.0, 3.0)
    kn.append((t, 0.0))
    for k in range(n_trips):
        g = 0 if k == n_trips - 1 else int(rng.integers(0, top + 1))
        if g == f:
            g = top if f == 0 else 0
        if k == 0:
            g = top                                        # the first passenger rides to the top
        t += 2.5 + 1.8 * abs(g - f) ** 0.7
        kn.append((t, g / top))
        t += rng.uniform(6.0, 20.0)
        kn.append((t, g / top))
        f = g
    if f != 0:
        t += 2.5 + 1.8 * f ** 0.7
        kn.append((t, 0.0))
        t += 2.0
        kn.append((t, 0.0))
    return kn, t


# ---- a skipping rope (rate dependence) ----

def skipping_rope(rng, n_bouts):
    """The rope's height at the jumper's feet over the turn (its sine): bouts of 8 ... 16 turns at 1.8 ... 2.6 a second,
    some with a few double-unders (3 ... 6 turns at 3.2 ... 3.8 a second), the amplitude 0.9 ... 1; rests of 1.5 ... 3 s
    between. Returns the bouts and the end."""
    t, bouts = rng.uniform(0.5, 1.5), []
    for _ in range(n_bouts):
        f = rng.uniform(1.8, 2.6)
        n = int(rng.integers(8, 17))
        a = rng.uniform(0.9, 1.0)
        bouts.append((t, f, n, a, a, "sin"))
        t += n / f
        if rng.random() < 0.6:
            fd, nd = rng.uniform(3.2, 3.8), int(rng.integers(3, 7))
            bouts.append((t, fd, nd, a, a, "sin"))
            t += nd / fd
        t += rng.uniform(1.5, 3.0)
    return bouts, t


# ---- a car park's barrier (drift; unipolar) ----

def car_park_barrier(rng, n_cars):
    """The boom's angle (0 down, 1 up): cars arriving at random (gaps 2 ... 12 s), the boom raised in 2 ... 3 s, up 3
    ... 8 s (longer for a queue), lowered in 2 ... 3 s. Returns the knots and the end."""
    t, kn = 0.0, [(0.0, 0.0)]
    k = 0
    while k < n_cars:
        t += rng.uniform(2.0, 12.0)
        kn.append((t, 0.0))
        t += rng.uniform(2.0, 3.0)
        kn.append((t, 1.0))
        queue = int(rng.integers(1, 4)) if rng.random() < 0.3 else 1
        t += sum(rng.uniform(3.0, 8.0) for _ in range(queue))
        kn.append((t, 1.0))
        t += rng.uniform(2.0, 3.0)
        kn.append((t, 0.0))
        k += queue
    t += 2.0
    kn.append((t, 0.0))
    return kn, t


# ---- a hand saw through a plank (asymmetry) ----

def hand_saw(rng, n_cuts):
    """The saw's place along its stroke: each cut starts with 3 ... 5 short strokes (a quarter to half the length) to
    start the kerf, then 6 ... 12 full strokes (a push of 0.5 ... 0.7 s, a pull of 0.4 ... 0.55 s), a pause of 2 ... 4
    s with the saw at rest mid-stroke between cuts. Returns the knots and the end."""
    t, kn = 0.0, [(0.0, 0.0)]
    for _ in range(n_cuts):
        t += rng.uniform(1.0, 2.0)
        kn.append((t, 0.0))
        for j in range(int(rng.integers(3, 6))):
            a = rng.uniform(0.25, 0.5)
            t += rng.uniform(0.3, 0.45)
            kn.append((t, a))
            t += rng.uniform(0.3, 0.45)
            kn.append((t, -a))
        for j in range(int(rng.integers(6, 13))):
            t += rng.uniform(0.5, 0.7)
            kn.append((t, rng.uniform(0.9, 1.0)))
            t += rng.uniform(0.4, 0.55)
            kn.append((t, -rng.uniform(0.9, 1.0)))
        t += 0.5
        kn.append((t, 0.0))
        t += rng.uniform(2.0, 4.0)
        kn.append((t, 0.0))
    return kn, t


# ---- a violin bow (saturation) ----

def violin_bow(rng, n_phrases):
    """The bow's place along its length (-1 the frog, 1 the tip, 0 the middle): phrases of 6 ... 12 notes, each a
    stroke at constant speed (trapezoidal, 0.25 ... 2 s), down- and up-bows alternating, of whole, half or quarter bows
    (the lengths drawn, the bow kept within its ends), lifted and set back at the middle between phrases (2 ... 4 s).
    Returns the knots and the end."""
    t, kn = 0.0, [(0.0, 0.0)]
    for _ in range(n_phrases):
        t += rng.uniform(2.0, 4.0)
        kn.append((t, 0.0))
        x, sd = 0.0, 1.0
        for _ in range(int(rng.integers(6, 13))):
            length = float(rng.choice([2.0, 1.0, 0.5], p=[0.35, 0.4, 0.25]))
            nx = float(np.clip(x + sd * length, -1.0, 1.0))
            if abs(nx - x) < 0.2:
                nx = x - sd * min(length, 1.0)
            t += rng.uniform(0.25, 0.5) + 0.75 * abs(nx - x)
            kn.append((t, nx))
            x, sd = nx, -sd
        t += 0.6
        kn.append((t, 0.0))
    t += 1.0
    kn.append((t, 0.0))
    return kn, t


# ---- a bicycle pump (delay; unipolar) ----

def bicycle_pump(rng, n_tyres):
    """The handle's depth (0 up, 1 fully down): per tyre 10 ... 20 strokes, pushed down in 0.35 ... 0.55 s and drawn up
    in 0.5 ... 0.8 s, shorter as the tyre fills (the last a 0.7 ... 0.85 of the first); a check of the gauge (3 ... 6
    s, the handle up) halfway, and 5 ... 10 s to move to the next tyre. Returns the knots and the end."""
    t, kn = 0.0, [(0.0, 0.0)]
    for _ in range(n_tyres):
        t += rng.uniform(1.0, 3.0)
        kn.append((t, 0.0))
        n = int(rng.integers(10, 21))
        last = rng.uniform(0.7, 0.85)
        for j in range(n):
            d = 1.0 - (1.0 - last) * j / (n - 1)
            t += rng.uniform(0.35, 0.55)
            kn.append((t, d))
            t += rng.uniform(0.5, 0.8)
            kn.append((t, 0.0))
            if j == n // 2:
                t += rng.uniform(3.0, 6.0)
                kn.append((t, 0.0))
        t += rng.uniform(5.0, 10.0)
        kn.append((t, 0.0))
    return kn, t


# ---- a playground swing (initial state) ----

def playground_swing(rng):
    """The seat's swing (its angle's share of the largest): pushed from rest (3 ... 5 pushes, the amplitude growing by
    steps), the child pumping higher (4 ... 8 swings), then left to die out (a decay time of 2 ... 4 swings) until
    stopped by the feet below a tenth; period 2 ... 2.4 s. Returns the bouts (one cycle each) and the end."""
    T = rng.uniform(2.0, 2.4)
    t, a, bouts = rng.uniform(0.5, 1.5), 0.0, []
    for _ in range(int(rng.integers(3, 6))):
        na = min(a + rng.uniform(0.15, 0.25), 0.8)
        bouts.append((t, 1 / T, 1, a if a > 0 else 0.05, na, "sin"))
        a = na
        t += T
    for _ in range(int(rng.integers(4, 9))):
        na = min(a + 0.1, 1.0)
        bouts.append((t, 1 / T, 1, a, na, "sin"))
        a, t = na, t + T
    tau = rng.uniform(2.0, 4.0)
    while a > 0.1:
        na = a * math.exp(-1 / tau)
        bouts.append((t, 1 / T, 1, a, na, "sin"))
        a, t = na, t + T
    bouts.append((t, 1 / T, 1, a, 0.0, "sin"))
    return bouts, t + T + 1.0


# ---- a rowing ergometer (the pair) ----

def rowing_ergometer(rng, n_pieces):
    """The handle's place about the middle of the stroke (-1 the catch, 1 the finish): pieces of 8 ... 12 strokes at 24
    ... 34 a minute, the drive a third of the stroke's time, the recovery the rest, the handle hooked at the middle
    3 ...
    8 s between pieces. Returns the knots and the end."""
    t, kn = 0.0, [(0.0, 0.0)]
    for _ in range(n_pieces):
        t += rng.uniform(3.0, 8.0)
        kn.append((t, 0.0))
        t += 0.8
        kn.append((t, -rng.uniform(0.95, 1.0)))
        rate = rng.uniform(24.0, 34.0)
        for _ in range(int(rng.integers(8, 13))):
            P = 60.0 / rate * rng.uniform(0.97, 1.03)
            t += P / 3
            kn.append((t, rng.uniform(0.95, 1.0)))
            t += 2 * P / 3
            kn.append((t, -rng.uniform(0.95, 1.0)))
        t += 0.8
        kn.append((t, 0.0))
    t += 1.0
    kn.append((t, 0.0))
    return kn, t


# ---- a cat's tail (out of vocabulary) ----

def cat_tail(rng, n_moods):
    """The tail tip's side-to-side place: moods in turn of lazy swishes (3 ... 6 sweeps of 1 ... 2 s to 0.5 ... 1 of
    either side), twitches (6 ... 15 flicks of the tip, 0.1 ... 0.25 each way, 4 ... 7 a second) and thumping (8 ... 20
    fast, full swings at 1.5 ... 2.5 a second), the tail still (at the middle) 1 ... 4 s between. Returns the knots and
    the end."""
    t, kn = 0.0, [(0.0, 0.0)]
    for m in range(n_moods):
        t += rng.uniform(1.0, 4.0)
        kn.append((t, 0.0))
        kind = ("swish", "twitch", "thump")[m % 3] if m < 3 else str(rng.choice(["swish", "twitch", "thump"]))
        sd = float(rng.choice([-1.0, 1.0]))
        if kind == "swish":
            for _ in range(int(rng.integers(3, 7))):
                t += rng.uniform(1.0, 2.0)
                kn.append((t, sd * rng.uniform(0.5, 1.0)))
                sd = -sd
        elif kind == "twitch":
            for _ in range(int(rng.integers(6, 16))):
                t += 1 / rng.uniform(8.0, 14.0)
                kn.append((t, sd * rng.uniform(0.1, 0.25)))
                sd = -sd
        else:
            for _ in range(int(rng.integers(8, 21))):
                t += 1 / rng.uniform(3.0, 5.0)
                kn.append((t, sd * rng.uniform(0.9, 1.0)))
                sd = -sd
        t += 0.5
        kn.append((t, 0.0))
    t += 1.0
    kn.append((t, 0.0))
    return kn, t

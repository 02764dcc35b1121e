"""Small tools the later sets (HOLDOUT31 on) share for drawing their records: a time grid within
the sample budget, whether a programme fits it, a drive driven about evenly to both sides, a
scaling to an amplitude, a root for a parameter, and (HOLDOUT40 on) drives from knot programmes
(:func:`knots_at`, :class:`Programme`) and a core's stroke. Written once here (they had been copied into
every set's ``cases_holdoutNN.py``); each set binds them under its old private names, so the
records are the same to the bit.
"""

import numpy as np
from scipy.optimize import brentq


def grid(dt, T, lo=10_050, hi=40_000):
    """Sample times ``0, dt, ...`` for a programme of ``T`` s, with at least ``lo`` and at most
    ``hi`` samples."""
    n = min(max(int(T / dt), lo), hi)
    return np.arange(n) * dt


def fits(dt, T_end):
    """Whether a programme of T_end s fits in a record of at most 40,000 samples (it ends at rest inside it)."""
    return T_end < 39_990 * dt


def balanced(make, lo=0.85, tries=400):
    """Calls make() -> (x, *rest) or None (a programme too long for the record) until x's weaker
    side reaches lo of its stronger; returns its result."""
    for _ in range(tries):
        out = make()
        if out is None:
            continue
        x = out[0]
        if min(x.max(), -x.min()) >= lo * np.abs(x).max():
            return out
    raise RuntimeError("no balanced drive drawn")


def scale(x, amp):
    """``x`` scaled to the peak magnitude ``amp``."""
    return amp * x / np.abs(x).max()


def solve_for(fn, target, lo, hi):
    """The parameter p in [lo, hi] with fn(p) = target (brentq, to 1e-15)."""
    return brentq(lambda p: fn(p) - target, lo, hi, xtol=1e-15)


def knotted(rng, dt, gen, evaluate):
    """A balanced bipolar drive from a knot programme ``gen(rng) -> (knots, T_end)``, evaluated
    on the time grid by ``evaluate(t, knots)``: ``(drive, t, knots)``."""
    def make():
        kn, T_end = gen(rng)
        if not fits(dt, T_end):
            return None
        t = grid(dt, T_end)
        return evaluate(t, kn), t, kn
    return balanced(make)


def bipolar(rng, dt, gen, evaluate):
    """A balanced bipolar drive (:func:`knotted`) scaled to a peak drawn from 44 ... 48 V:
    ``(drive, t, knots, peak, scaled drive)``."""
    x, t, kn = knotted(rng, dt, gen, evaluate)
    amp = rng.uniform(44.0, 48.0)
    return x, t, kn, amp, scale(x, amp)


def fine(t, sub):
    """The times t (uniform, from 0) with sub - 1 more between each two."""
    return np.arange((len(t) - 1) * sub + 1) * (t[1] - t[0]) / sub


def unipolar(rng, dt, gen, evaluate):
    """A unipolar drive 0 ... top (top 88 ... 97 V) from a knot programme ``gen(rng)``, drawn
    until it fits the record: ``(t, knots, programme, top, drive)``."""
    kn, T_end = gen(rng)
    while not fits(dt, T_end):
        kn, T_end = gen(rng)
    t = grid(dt, T_end)
    p = evaluate(t, kn)
    top = rng.uniform(88.0, 97.0)
    return t, kn, p, top, top * p / p.max()


def stroke(h):
    """The middle of ``h``'s range and its half range: ``(centre, half)``."""
    c = (h.max() + h.min()) / 2
    return c, np.abs(h - c).max()


def minimum_jerk(s):
    """The minimum-jerk move 0 ... 1 over s in 0 ... 1 (0 before, 1 after): 10 s^3 - 15 s^4 + 6 s^5 (Flash and
    Hogan 1985, from memory), zero speed and acceleration at both ends."""
    s = np.clip(np.asarray(s, float), 0.0, 1.0)
    return s ** 3 * (10.0 - 15.0 * s + 6.0 * s * s)


def minimum_jerk_speed(s):
    """:func:`minimum_jerk`'s speed (a unit move over a unit time) at s in [0, 1]: 30 s^2 (1 - s)^2."""
    s = np.asarray(s, float)
    return 30.0 * s * s * (1.0 - s) ** 2


def knots_at(t, knots, move):
    """The position on times t through knots [(time, position), ...] joined by ``move(s)`` (a
    point-to-point move 0 ... 1 over s in 0 ... 1); the first knot's position before it, the last's
    after."""
    t = np.asarray(t, float)
    T = np.array([k[0] for k in knots])
    X = np.array([k[1] for k in knots])
    i = np.clip(np.searchsorted(T, t, side="right") - 1, 0, len(T) - 2)
    d = T[i + 1] - T[i]
    s = np.where(d > 0, (t - T[i]) / np.where(d > 0, d, 1.0), 1.0)
    x = X[i] + (X[i + 1] - X[i]) * move(s)
    x = np.where(t <= T[0], X[0], x)
    return np.where(t >= T[-1], X[-1], x)


class Programme:
    """A programme being written: knots appended as (dt after the last, position)."""

    def __init__(self, x0=0.0):
        self.t, self.kn = 0.0, [(0.0, x0)]

    def to(self, dt, x):
        self.t += dt
        self.kn.append((self.t, float(x)))

    def hold(self, dt):
        self.to(dt, self.kn[-1][1])

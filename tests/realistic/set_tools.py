"""Small tools the later sets (HOLDOUT31 on) share for drawing their records: a time grid within
the sample budget, whether a programme fits it, a drive driven about evenly to both sides, a
scaling to an amplitude, a root for a parameter, and (HOLDOUT40 on) drives from knot programmes
and a core's stroke. Written once here (they had been copied into
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

"""The load change into a hold (:func:`hystcomp.diagnose.record.find_holds`) and the creep test's holds.

A hold reached by a slow ramp or a valve's first-order approach counts the whole change since the input last turned
back, not only the input's change over the last seconds: before round 27 the step was the hold's level minus the mean
input over the 2 s before it, and a plateau approached more slowly than that left creep untested. A stair of a
staircase counts every stair since the staircase turned: on a fast staircase (the library's identification
experiment, 0.1-0.3 s stairs) creep has not caught up with the stairs before, and counting the last stair alone lost
creep on hidden_effect_data("creep", seed=0), which the mean over 2 s and the change since the turn both name.

Tolerances: the inputs carry noise of 1e-4 of their span; the steps are compared to the drawn level changes within
1 % of the span (the 11-sample smoothing and the noise move the walk's extreme by far less), 1.5 % for a first-order
approach, whose first hold starts about 1 % of the span short of the level.
"""

import os
import sys

import numpy as np
import pytest
from scipy.signal import lfilter

from hystcomp.diagnose import diagnose
from hystcomp.diagnose.record import find_holds
from hystcomp.diagnose.signatures import _merged_holds
from hystcomp.models import PI

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "benchmarks"))
from bench_holds import python_runs  # noqa: E402  (the Python scan find_holds ran until round 28)

DT = 0.01


def _noisy(v, seed=0):
    return v + 1e-4 * np.ptp(v) * np.random.default_rng(seed).standard_normal(v.size)


def _first_order(levels, hold=14.0, tau=2.0):
    """A valve's first-order approach (time constant `tau`) to each level in turn, `hold` seconds per level."""
    target = np.repeat(levels, int(round(hold / DT)))
    a = np.exp(-DT / tau)
    return lfilter([1 - a], [1, -a], target)


def test_a_slow_ramp_counts_whole_into_the_hold():
    # 10 s ramps from 0 to 1, down to -0.6, up to 0.2: the old 2 s mean counted a fifth of each
    t = np.arange(0, 48, DT)
    v = _noisy(np.interp(t, [0, 10, 16, 26, 32, 42, 48], [0, 1, 1, -0.6, -0.6, 0.2, 0.2]))
    holds = find_holds(v, DT, np.ptp(v))
    steps = [s for k, j, s in holds if (j - k) * DT > 3]
    np.testing.assert_allclose(steps, [1.0, -1.6, 0.8], atol=0.016)


def test_a_staircase_counts_every_stair_since_it_turned():
    # stairs 0 -> 0.3 -> 0.6 -> 1.0 (each 0.5 s ramps, 3 s holds), then down to 0.1 and back up to 0.5: the steps
    # are the changes since the start or the last reversal (0.3, 0.6, 1.0; then -0.9 from 1.0 and 0.4 from 0.1)
    t = np.arange(0, 21, DT)
    kt = [0, 0.5, 3.5, 4, 7, 7.5, 10.5, 12, 15, 16, 21]
    kv = [0, 0.3, 0.3, 0.6, 0.6, 1.0, 1.0, 0.1, 0.1, 0.5, 0.5]
    v = _noisy(np.interp(t, kt, kv))
    holds = [(k, j, s) for k, j, s in find_holds(v, DT, np.ptp(v)) if (j - k) * DT > 1]
    np.testing.assert_allclose([s for *_, s in holds], [0.3, 0.6, 1.0, -0.9, 0.4], atol=0.01)
    # an overshoot: up to 1.0, straight back to 0.7 and held there: the step is the fall from 1.0 (-0.3)
    t = np.arange(0, 8, DT)
    v = _noisy(np.interp(t, [0, 2, 2.1, 2.6, 8], [0, 1.0, 1.0, 0.7, 0.7]))
    (k, j, s), = [h for h in find_holds(v, DT, np.ptp(v)) if (h[1] - h[0]) * DT > 1]
    assert s == pytest.approx(-0.3, abs=0.01)


def test_a_first_order_approach_is_one_hold_for_creep():
    # the approach keeps moving by more than the hold's tolerance for a while: it splits each plateau into short
    # holds; for creep they are one hold per plateau, with the whole change into it
    levels = [0.8, -0.5, 0.9, -0.9, 0.3]
    v = _noisy(_first_order(levels))
    span = np.ptp(v)
    holds = find_holds(v, DT, span)
    assert len(holds) > 5 * len(levels)               # split: measured 60 pieces
    assert all(abs(s) > 0.02 * span for *_, s in holds)  # every piece counts its approach

    class Rec:                                                    # the record's attributes that the test reads
        pass

    rec = Rec()
    rec.holds, rec.v, rec.span = holds, v, span
    merged = _merged_holds(rec)
    assert len(merged) == len(levels)
    # the first piece starts where the approach is within about 1 % of the span of its level (measured 0.6-1.1 %)
    np.testing.assert_allclose([s for *_, s in merged], np.diff([0.0, *levels]), atol=0.015 * span)
    # each merged hold runs to its plateau's end (14 s per level), less the smoothing's half-width
    np.testing.assert_allclose([j * DT for _, j, _ in merged], 14.0 * np.arange(1, len(levels) + 1), atol=0.2)


@pytest.mark.parametrize("seed", [0, 1])
def test_creep_under_first_order_approaches_is_tested_and_named(seed):
    # creep of a Kelvin-Voigt chain (0.7 s and 4 s, 5 % and 7 % of the core's output) under plateaus that a valve
    # approaches with a 2 s time constant: before round 27 creep was untested here (the 2 s mean before each hold
    # had caught up with it) and rate dependence was named (measured: seeds 0 and 1, `unexplained`)
    rng = np.random.default_rng(seed)
    levels = rng.uniform(0.3, 1.0, 14) * np.where(np.arange(14) % 2 == 0, 1.0, -1.0)
    v = _first_order(levels)
    t = np.arange(v.size) * DT
    r = np.linspace(0, 1, 21)[1:-1]
    core = PI(r, np.exp(-r / 0.5) / 15, 0.5).simulate(v)
    y = core.copy()
    for tau, c in ((0.7, 0.05), (4.0, 0.07)):
        a = np.exp(-DT / tau)
        y += c * lfilter([1 - a], [1, -a], core)
    y = y + 0.002 * np.ptp(y) * rng.standard_normal(y.size)
    rep = diagnose(t, v, y, progress=False)
    assert "creep" not in rep.untested, rep.report()
    assert rep.effects == ["creep"] and rep.verdict == "explained", rep.report()


def test_the_compiled_scan_finds_the_python_scans_runs_to_the_last_sample():
    # the same arithmetic in the same order, so the same runs exactly (no tolerance): random walks, noisy staircases
    # whose stairs are just under, at and over the shortest run, and noisy sines, with tolerances at the noise's scale
    from hystcomp.diagnose._hold_runs import hold_runs
    rng = np.random.default_rng(28)
    found = 0
    for i in range(300):
        n = int(rng.integers(30, 2500))
        min_len = int(rng.integers(2, 60))
        kind = i % 3
        if kind == 0:
            vs = np.cumsum(rng.standard_normal(n))
        elif kind == 1:
            stair = min_len + int(rng.integers(-3, 4))
            vs = np.repeat(rng.standard_normal(n // max(stair, 1) + 1), max(stair, 1))[:n]
            vs = vs + 1e-3 * rng.standard_normal(n)
        else:
            vs = np.sin(np.linspace(0, rng.uniform(1, 30), n)) + 1e-3 * rng.standard_normal(n)
        tol = float(rng.choice([1e-3, 3e-3, 0.3, 2.0]))
        starts, ends = hold_runs(vs, tol, min_len)
        runs = python_runs(vs, tol, min_len)
        assert list(zip(starts.tolist(), ends.tolist())) == runs
        found += len(runs)
    assert found > 500      # the check compared runs, not empty lists (measured: several thousand)


def test_a_staircase_of_stairs_just_under_the_shortest_hold_has_no_hold():
    # 0.1 s stairs at 1 kHz (100 samples, the shortest hold): the smoothing's half-widths leave each run short, so no
    # hold (the compiled scan's worst case: every start scans almost a shortest hold); stairs of 0.15 s are holds, one
    # inside each stair, 130 samples of its 150 (the smoothing's 5 samples into each neighbour, and the hold's own
    # shrinking by 5 at each end); the first and the last 135 (the record's ends have no neighbour)
    fs = 1000.0
    rng = np.random.default_rng(3)
    levels = rng.uniform(-1, 1, 40)
    v = _noisy(np.repeat(levels, 100))
    assert find_holds(v, 1 / fs, float(np.ptp(v))) == []
    v = _noisy(np.repeat(levels, 150))
    holds = find_holds(v, 1 / fs, float(np.ptp(v)))
    assert [(a // 150, b - a) for a, b, _ in holds] == [(i, 135 if i in (0, 39) else 130) for i in range(40)]

"""A dead time longer than the delay part's first bound (round 59).

The dead time's first bound is 0.2 % of the record (at least 20 samples, at most 5 %);
a drive's output buffer, a camera's frame pipeline or a water line's transport delay can
hold 0.1-0.2 s, which on a record of 30,000 samples at 500 Hz is 50-100 samples, beyond
that bound's 60.  The part now has a ``reach`` (hystcomp.identify.parts.Delay._reach): when
the best dead time ends at the first bound, the search moves on up to the longest lag tried
(0.5 s here: 250 samples).  HOLDOUT56's USB module (a 10 kHz output FIFO of 1200-2000
samples, 89-114 samples of the record) was read as a resonance at every seed before it.

The record: the realistic generator's PI core (tests/realistic/mechanisms.py, not a
hystcomp part) driven by an analytic input read at the true late instants (not by
interpolating samples, as the part does).
"""

import numpy as np
import pytest

from hystcomp.diagnose import diagnose
from hystcomp.diagnose.base import rest_point
from hystcomp.diagnose.record import Record
from hystcomp.identify.part_base import Context
from hystcomp.identify.parts_dynamics import Delay
from hystcomp.identify.search import Structure
from realistic import mechanisms as me

DT, N, LATE = 2e-3, 30_000, 0.15          # 500 Hz, 60 s, a dead time of 75 samples


def _drive(t):
    # incommensurate sines faded in and out, to +-40 V (analytic: read at any instant)
    fade = np.clip(t / 4.0, 0.0, 1.0) * np.clip((N * DT - t) / 4.0, 0.0, 1.0)
    return fade * (24.0 * np.sin(2 * np.pi * 0.31 * t) + 16.0 * np.sin(2 * np.pi * 0.87 * t + 0.6))


@pytest.fixture(scope="module")
def record():
    rng = np.random.default_rng(59)
    t = np.arange(N) * DT
    h = me.play_core(_drive(np.maximum(t - LATE, 0.0)), 100.0)
    sigma = 0.002 * np.ptp(h)
    return t, _drive(t), h + sigma * rng.standard_normal(N), sigma


def _delay_fit(t, v, y, reach):
    """The base model plus a dead time, fitted as a diagnosis's first step fits it;
    ``reach=False`` takes the part's reach away (the search before round 59)."""
    rec = Record(t, v, y, 0.3, "auto")
    ctx, vp, cur, _ = rest_point(rec, 20, None)
    part = Delay() if reach else type("NoReach", (Delay,), {"_reach": lambda self, ctx: None})()
    part.prepare(rec.y, ctx)
    st = Structure().extended(part)
    start = {k: dict(x) for k, x in cur.values.items()}
    start["delay"] = {"delay": 1.0}
    starts = [{"delay": s} for s in part.initial_values(ctx, set(st.kinds))]
    pt = vp.optimise(st, start, free={"delay"}, max_evaluations=12, starts=starts)
    return pt.values["delay"]["delay"], float(np.sqrt(pt.rss / pt.n_train)), part.parameters(ctx, set(st.kinds))[0]


def test_bounds_and_reach():
    # first bound 0.2 % of 30,000 samples = 60; reach 0.5 s / 2 ms = 250 samples
    v = np.zeros(N)
    q = Delay().parameters(Context(v, DT, 0.0, 1.0, N * DT), {"delay"})[0]
    assert (q.lower, q.upper) == (0.0, 60.0)
    assert q.reach == pytest.approx((0.0, 250.0))
    # at most 5 % of the record: 400 samples at 2 ms hold 0.8 s, the reach stops at 20 samples;
    # the first bound (20) is as wide, so there is no wider reach
    assert Delay().parameters(Context(np.zeros(400), DT, 0.0, 1.0, 0.8), {"delay"})[0].reach is None
    # a record whose first bound already holds the longest lag (60 samples of 10 ms: 0.6 s,
    # beyond 0.5 s) has none either
    assert Delay().parameters(Context(v, 1e-2, 0.0, 1.0, N * 1e-2), {"delay"})[0].reach is None


def test_the_search_moves_past_the_first_bound(record):
    t, v, y, sigma = record
    d_old, rms_old, _ = _delay_fit(t, v, y, reach=False)
    d_new, rms_new, _ = _delay_fit(t, v, y, reach=True)
    # without the reach the dead time stops at its first bound (60 samples, 15 short) and
    # leaves far more than the noise; with it, the true 75 samples within half a sample
    # (the part interpolates between samples; the record was read at the true instants)
    # and a training RMS within 1.2 noise levels (the PI core is the part's own kind)
    assert d_old == pytest.approx(60.0, abs=0.6)
    assert rms_old > 5 * sigma
    assert d_new == pytest.approx(LATE / DT, abs=0.5)
    assert rms_new < 1.2 * sigma


def test_named_a_delay_and_explained(record):
    t, v, y, sigma = record
    rep = diagnose(t, v, y, progress=False)
    assert rep.effects == ["delay"]
    assert rep.verdict == "explained" and rep.rms_heldout <= 1.5 * sigma
    desc = next(p for p in rep.model.describe() if p["kind"] in ("delay", "delay_drift"))
    assert desc["delay_samples"] == pytest.approx(LATE / DT, abs=0.5)

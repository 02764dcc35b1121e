"""An offset drift made of events in time: the drift may be a broken line of 24 segments
(hystcomp.identify.parts_drift.EventDrift, round 32).

The six-segment broken line (``slow_drift``) follows a thermal cycle or a fixture settling, but
not an offset that moves in a few seconds at a few moments of a long record: a door opened,
a lamp switched, another axis moved. On the realistic sets such drifts were missed in 19 of
the 945 runs of round 31 (the records' descriptions: a gantry's carriage, a heat lamp, an
indexing table, a flash-heated part, a temperature controller's overshoot).

The record: the realistic generator's PI core (tests/realistic/mechanisms.py, 200 plays of its
own density, not hystcomp's) under triangles of random amplitude at 1.6 Hz, 40 s at 500 Hz.
The sensor's bracket sits by a door that is opened three times for 2.5 s (at 4, 10 and 16 s):
the air by the bracket warms toward the corridor's temperature with a time constant of 0.6 s
while the door is open and cools back with 1.5 s after it shuts, and the bracket follows the
air with 1.2 s (two first-order lags, integrated here in closed form per sample); the bracket's
expansion is an offset of 6 % of the output span at the air's full swing. Output noise 0.2 %
of its span.
"""

import numpy as np
import pytest

from hystcomp.diagnose import diagnose
from hystcomp.identify.parts import PARTS
from realistic import mechanisms as me

RATE = 500.0
OPENINGS = (4.0, 10.0, 16.0)
OPEN_FOR = 2.5


def _lag(x, dt, tau):
    """A first-order lag of the samples x (zero-order hold), exact per sample; `tau` a
    time constant or one per sample."""
    a = np.broadcast_to(np.exp(-dt / np.asarray(tau, dtype=float)), np.shape(x))
    out = np.empty_like(x)
    s = 0.0
    for k, xk in enumerate(x):
        s = a[k] * s + (1.0 - a[k]) * xk
        out[k] = s
    return out


@pytest.fixture(scope="module")
def record():
    rng = np.random.default_rng(7)
    t = np.arange(int(40 * RATE)) / RATE
    dt = 1.0 / RATE
    # triangles at 1.6 Hz whose peaks are drawn anew every cycle, about 0, +-20 ... 48 V
    n_cyc = int(np.ceil(t[-1] * 1.6)) + 1
    peaks = rng.uniform(20.0, 48.0, n_cyc)
    phase = (t * 1.6) % 1.0
    k = np.minimum((t * 1.6).astype(int), n_cyc - 1)
    tri = np.where(phase < 0.5, 4.0 * phase - 1.0, 3.0 - 4.0 * phase)
    v = peaks[k] * np.sin(0.5 * np.pi * tri)
    h = me.play_core(v, 100.0)
    door = np.zeros_like(t)
    for a in OPENINGS:
        door[(t >= a) & (t < a + OPEN_FOR)] = 1.0
    # the air: 0.6 s toward 1 while open, 1.5 s back toward 0 when shut
    air = _lag(door, dt, np.where(door > 0, 0.6, 1.5))
    bracket = _lag(air, dt, 1.2)
    drift = 0.06 * np.ptp(h) * bracket
    sigma = 0.002 * np.ptp(h)
    y = h + drift + sigma * rng.standard_normal(t.size)
    return t, v, y, sigma, drift


def test_the_drift_is_events(record):
    # the record's premise (not the diagnosis): the offset moves by many noise levels within
    # each opening (measured 17-24 sigma, 3.3-4.6 % of the output span) and is back within a
    # noise level before the held-out end (the last 30 %, from 28 s; measured 0.22 sigma)
    t, v, y, sigma, drift = record
    for a in OPENINGS:
        inside = (t >= a) & (t < a + OPEN_FOR + 2.0)
        assert np.ptp(drift[inside]) > 10 * sigma
    assert np.abs(drift[t >= 28.0]).max() < sigma


def test_drift_events_named_drift_by_the_finer_broken_line(record):
    t, v, y, sigma, _ = record
    rep = diagnose(t, v, y, progress=False)
    assert rep.effects == ["drift"]
    desc = next(p for p in rep.model.describe() if p.get("effect") == "drift")
    assert desc["kind"] == "event_drift"
    # within the explained bound (measured 1.04 noise floors; the six-segment line gained 108
    # noise variances held out at the same step, the finer one 114)
    assert rep.verdict == "explained" and rep.rms_heldout <= 1.5 * sigma
    held = ~rep._rec.train
    assert np.sqrt(np.mean((y - rep.model.simulate(v))[held] ** 2)) == pytest.approx(rep.rms_heldout, rel=1e-9)


def test_without_the_finer_line_the_events_are_not_explained(record, monkeypatch):
    # why the part is there: the six-segment line names the drift but cannot follow the
    # openings, and the core's weights bend to what it leaves (measured 2.66 noise floors held
    # out, verdict unexplained, a slow trend and the record's start still flagged)
    t, v, y, sigma, _ = record
    monkeypatch.delitem(PARTS, "event_drift")
    rep = diagnose(t, v, y, progress=False)
    assert rep.effects == ["drift"] and rep.verdict == "unexplained"
    assert rep.rms_heldout > 2.0 * sigma
    kinds = [p.get("kind") for p in rep.model.describe()]
    assert "slow_drift" in kinds and "event_drift" not in kinds

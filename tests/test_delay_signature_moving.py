"""The delay's signature reads the samples where the model's output moves.

A dead time shifts the output only while it moves; on a record of short moves between long holds
(7 % of the samples moving here) its residual averaged over the whole record falls under the
threshold although, where the output moves, it is plain (round 11: creep + a fieldbus latency under
minimum-jerk moves, 0.16-0.35 noise floors over the record, 1.0-1.7 over the moves).
"""

import numpy as np

from hystcomp.diagnose.record import Record
from hystcomp.diagnose.signatures import MOVING, PARTIAL, _partial, _static_nuisance, evidence


def _moves_and_holds(dt=1e-3, move=0.1, hold=1.2):
    """Smooth moves (half-cosine ramps of `move` s) between holds of `hold` s."""
    levels = [0.0, 60.0, 10.0, 90.0, 30.0, 80.0, 5.0, 70.0, 20.0, 100.0, 40.0, 0.0]
    parts = [np.full(int(hold / dt), levels[0])]
    m = int(move / dt)
    for a, b in zip(levels[:-1], levels[1:]):
        parts.append(a + (b - a) * 0.5 * (1 - np.cos(np.pi * np.arange(1, m + 1) / m)))
        parts.append(np.full(int(hold / dt), b))
    v = np.concatenate(parts)
    return np.arange(v.size) * dt, v


def test_a_dead_time_under_moves_and_holds_is_seen_where_the_output_moves():
    rng = np.random.default_rng(11)
    t, v = _moves_and_holds()
    sigma = 0.4
    pred = 0.9 * v
    late = np.interp(np.arange(v.size) - 1.5, np.arange(v.size), pred)    # 1.5 samples late
    e = late - pred + sigma * rng.standard_normal(v.size)
    rec = Record(t, v, pred + e, 0.3)
    ev = evidence(rec, e, pred, sigma, only="delay")["delay"]
    moving = ev["moving_share"]
    assert 0.05 < moving < 0.15
    # over the whole record the shift is diluted below the threshold ...
    dp = np.gradient(pred)
    whole = _partial(e, _static_nuisance(rec), (dp / np.abs(dp).max())[:, None]) / sigma
    assert whole < PARTIAL
    # ... where the output moves (|d pred| above MOVING of its peak) it is present (measured
    # 0.48 over the record, 0.96 over the moving 7 %; asked: above 1.5 x the threshold and
    # 1.8 x the diluted statistic)
    assert ev["present"] and ev["statistic"] > 1.5 * PARTIAL
    assert ev["statistic"] > 1.8 * whole
    assert 0 < MOVING < 0.1


def test_no_dead_time_no_delay_signature_on_moves_and_holds():
    # white noise alone: the statistic over the moving samples stays under the threshold
    # (the partial RMS of noise along one column over m samples is about sigma / sqrt(m):
    # 0.03 noise floors here)
    rng = np.random.default_rng(12)
    t, v = _moves_and_holds()
    sigma = 0.05
    pred = 0.9 * v
    e = sigma * rng.standard_normal(v.size)
    ev = evidence(Record(t, v, pred + e, 0.3), e, pred, sigma, only="delay")["delay"]
    assert not ev["present"] and ev["statistic"] < 0.2

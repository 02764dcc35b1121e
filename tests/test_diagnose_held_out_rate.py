"""The held-out part stays inside the fitted part's input rate (round 12): with
``held_out="auto"`` a timed record whose end moves the input more than twice as fast as
the rest (the 99th percentiles of the smoothed rate) holds out a block inside it, as one
whose end leaves the input range does (round 7)."""

import json

import numpy as np
import pytest

from hystcomp.diagnose import diagnose
from hystcomp.diagnose.record import FASTER, Record, _rate_excess, inner_block
from realistic import mechanisms as me


def _exp_chirp(dt, T, f0, f1, amp):
    """A sine whose frequency grows exponentially from f0 to f1 Hz over T s."""
    t = np.arange(int(round(T / dt))) * dt
    k = np.log(f1 / f0)
    return t, amp * np.sin(2 * np.pi * f0 * T / k * (np.exp(t / T * k) - 1))


def test_a_chirps_fast_end_is_not_held_out():
    # 0.2 -> 6 Hz at a fixed amplitude: the end moves about 3 times as fast as the rest
    t, v = _exp_chirp(1e-3, 20.0, 0.2, 6.0, 40.0)
    y = np.tanh(v / 30.0)
    rec = Record(t, v, y, 0.3)
    (a, b), = rec.blocks
    n = v.size
    assert b < n and b - a == n - rec.k_val
    assert rec.held_moved_faster > FASTER and rec.held_moved_from_end <= 0.05   # moved for its rate alone
    rate = np.gradient(v, t)
    # the block chosen moves at most FASTER times as fast as the rest (by its own rate: the record's
    # rate is the 5-sample smoothed one, which differs from the raw gradient by < 0.1 % at 6 Hz, 1 kHz)
    assert _rate_excess(rate, a, b) <= FASTER * 1.001
    assert "times as fast as the rest" in rec.held_out_line()
    # "last" keeps the end; a record without a time axis has no rate, so the end stays
    assert Record(t, v, y, 0.3, held_out="last").blocks == [(rec.k_val, n)]
    assert Record(None, v, y, 0.3).blocks == [(rec.k_val, n)]
    # a steady sine: nothing moves
    s = 40.0 * np.sin(2 * np.pi * 1.5 * t)
    assert Record(t, s, np.tanh(s / 30.0), 0.3).blocks == [(rec.k_val, n)]


def test_inner_block_reads_range_and_rate_together():
    # an amplitude that grows AND a frequency that grows: the block must satisfy both limits
    t = np.linspace(0.0, 10.0, 2000)
    v = np.linspace(0.6, 1.0, t.size) * np.sin(2 * np.pi * (0.5 * t + 0.15 * t ** 2))
    span = float(np.ptp(v))
    rate = np.gradient(v, t)
    a_range = inner_block(v, 600, span)
    a_both = inner_block(v, 600, span, rate=rate)
    assert a_both is not None and a_both <= a_range
    assert _rate_excess(rate, a_both, a_both + 600) <= FASTER


def test_under_a_chirp_a_dynamic_stage_is_judged_inside_the_fitted_rates():
    # a Bouc-Wen hysteresis driving a second-order stage (tests/realistic, not a hystcomp part)
    # under an exponential chirp 0.2 -> 5.4 Hz: with the end held out the rate part extrapolates
    # to rates the fit never saw and leaves 1.67 noise floors (measured); from the block inside,
    # 1.12 (measured), explained, and the model reproduces the reported RMS on the block
    rng = np.random.default_rng([1, 4242])
    f1 = rng.uniform(5, 7)
    t, v = _exp_chirp(1e-3, 20.0, 0.2, f1, 40.0)
    y = me.bouc_wen_stage(v, 1e-3, fn=rng.uniform(10, 14), zeta=0.4)
    y = y + 0.002 * np.ptp(y) * rng.standard_normal(y.size)
    last = diagnose(t, v, y, progress=False, held_out="last")
    auto = diagnose(t, v, y, progress=False)
    assert last.effects == auto.effects == ["rate_dependence"]
    assert last.held_out_moved_faster == 0.0 and auto.held_out_moved_faster > FASTER
    assert last.rms_heldout > 1.5 * last.noise_floor and last.verdict == "unexplained"
    assert auto.rms_heldout < 1.3 * auto.noise_floor and auto.verdict == "explained"
    held = ~auto._rec.train
    rms = float(np.sqrt(np.mean((y - auto.model.simulate(v))[held] ** 2)))
    assert rms == pytest.approx(auto.rms_heldout, rel=1e-9)
    d = json.loads(auto.to_json())
    assert d["schema_version"] == 30 and d["held_out_moved_faster"] == pytest.approx(auto.held_out_moved_faster)
    assert "times as fast as the rest" in auto.report()

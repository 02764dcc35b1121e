"""A gain of no set shape (:class:`SlowGainDrift`): the part, its fit and its naming.

The record is written here from its physics (an actuator whose gain follows the
temperature of a stage that is switched on: it warms along an S-shaped curve and
settles), not from the part's broken line.
"""

import numpy as np
import pytest

from hystcomp.diagnose import diagnose
from hystcomp.identify.parts import PARTS, Context, SlowGainDrift
from hystcomp.identify.parts_dynamics import SLOW_GAIN_SEGMENTS
from realistic import excitations as ex
from realistic import mechanisms as me


def test_slow_gain_is_one_plus_a_broken_line_held_after_the_fit():
    ctx = Context(np.zeros(1000), 0.01, 0.0, 1.0, 10.0, fit_end=8.0)
    g = {f"g{i}": 0.05 * i for i in range(1, SLOW_GAIN_SEGMENTS + 1)}
    cols = np.ones((1000, 2))
    out = SlowGainDrift().filter(cols, g, ctx)
    t = ctx.time
    # linear between knots at 0, 2, 4, 6, 8 s: 1 + 0.05 * t / 2 here, then held
    np.testing.assert_allclose(out[t <= 8.0, 0], 1.0 + 0.025 * t[t <= 8.0], rtol=0, atol=1e-12)
    np.testing.assert_allclose(out[t >= 8.0, 1], 1.0 + 0.05 * SLOW_GAIN_SEGMENTS, rtol=0, atol=1e-12)
    assert PARTS["slow_gain_drift"].effect == "gain_drift" and PARTS["slow_gain_drift"].slot == "filter"
    # without a driver (a part built outside a search) the search starts from no change
    assert SlowGainDrift().initial_values(ctx, set()) == [{f"g{i}": 0.0 for i in range(1, SLOW_GAIN_SEGMENTS + 1)}]


def _warming_record(seed):
    """Gain 1 + a (1 + tanh((t - t0)/w)) / 2: it rises along an S-curve around t0 = 7 s
    and settles before the held-out part, under two-tone decaying sines."""
    rng = np.random.default_rng([seed, 8484])
    dt, n = 1e-3, 22_000
    t = np.arange(n) * dt
    v = ex.decaying_sines(dt, n, (0.9, 2.1), 45.0)
    a = rng.uniform(0.06, 0.08)
    gain = 1.0 + a * 0.5 * (1.0 + np.tanh((t - 7.0) / rng.uniform(1.5, 2.5)))
    h = me.play_core(v, 100.0) * gain
    y = h + 0.002 * np.ptp(h) * rng.standard_normal(n)
    return t, v, y


def test_a_gain_that_rises_along_an_s_curve_and_settles_is_named_gain_drift():
    t, v, y = _warming_record(2)
    rep = diagnose(t, v, y, progress=False)
    assert rep.effects == ["gain_drift"], rep.report()
    kinds = [d["kind"] for d in rep.model.describe()]
    assert "slow_gain_drift" in kinds, kinds
    # the exponential approach of GainDrift cannot follow an S-curve: the broken line does better
    # held out (what made it the step's part)
    cand = rep.steps[0]["evidence"]["candidates"]
    assert cand["slow_gain_drift"] < cand["gain_drift"]
    held = slice(rep._rec.held_start, rep._rec.held_end)
    rms = float(np.sqrt(np.mean((y - rep.model.simulate(v))[held] ** 2)))
    assert rms == pytest.approx(rep.rms_heldout, rel=1e-9)


def test_the_diagnosed_slow_gain_model_has_an_exact_inverse():
    t, v, y = _warming_record(2)
    rep = diagnose(t, v, y, effects=["gain_drift"], progress=False)
    model = rep.model
    assert "slow_gain_drift" in [d["kind"] for d in model.describe()], model.describe()
    # the first 12 s (the warming and its settling; the compensator runs in Python,
    # about 1 ms per sample)
    k = 12_000
    ref = model.simulate(v)[:k]
    u = model.exact_inverse().simulate(ref)
    # 1e-6 of the output span: the bound of the other parts' inverse tests
    # (tests/test_parts_inverse.py)
    assert np.max(np.abs(model.simulate(np.concatenate([u, v[k:]]))[:k] - ref)) < 1e-6 * np.ptp(ref)

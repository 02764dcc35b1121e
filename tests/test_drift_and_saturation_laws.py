"""A drift of no set shape (:class:`SlowDrift`) and a slowly saturating output map
(:class:`OutputAlgebraic`): the parts, their fits and their naming.

The records are written here from their physics (a fixture settling along a smooth step,
Langevin saturation of a magnetisation), not from the parts' own columns or maps.
"""

import numpy as np
import pytest

from hystcomp.diagnose import diagnose
from hystcomp.identify.parts import PARTS, Context, OutputAlgebraic, SlowDrift
from hystcomp.identify.parts_drift import SLOW_DRIFT_SEGMENTS
from realistic import excitations as ex
from realistic import mechanisms as me


def _rms_held(rep, y, v):
    held = slice(rep._rec.held_start, rep._rec.held_end)
    return float(np.sqrt(np.mean((y - rep.model.simulate(v))[held] ** 2)))


def test_slow_drift_columns_are_a_broken_line_held_after_the_fit():
    ctx = Context(np.zeros(1000), 0.01, 0.0, 1.0, 10.0, fit_end=7.0)
    D = SlowDrift().columns({}, ctx)[0]
    assert D.shape == (1000, SLOW_DRIFT_SEGMENTS)
    t = ctx.time
    # the hats add up to 1 once the first knot's hat (the offset's) has gone
    np.testing.assert_allclose(D[t >= 7.0 / SLOW_DRIFT_SEGMENTS].sum(axis=1), 1.0, rtol=0, atol=1e-12)
    # after the fitted part every column keeps its value at fit_end: the last level is held
    after = t >= 7.0
    np.testing.assert_array_equal(D[after], np.tile(D[np.argmax(after)], (after.sum(), 1)))
    assert D[-1, -1] == 1.0 and np.all(D[-1, :-1] == 0.0)
    # another record keeps the clock it was fitted on
    assert ctx.like(np.zeros(50)).fit_end == 7.0
    assert PARTS["slow_drift"].effect == "drift" and PARTS["output_algebraic"].effect == "saturation"


def _settling_record(seed):
    """A fixture settling along a smooth step (a tanh in time, as a clamp's
    temperature after a door was opened) that ends before the held-out part, under
    band-limited random drive."""
    rng = np.random.default_rng([seed, 6262])
    dt, n = 1e-3, 24_000
    t = np.arange(n) * dt
    v = ex.bandlimited_random(dt, n, 2.5, 45.0, rng=rng)
    h = me.play_core(v, 100.0)
    step = 0.05 * np.ptp(h) * 0.5 * (1.0 + np.tanh((t - 8.0) / 2.0))
    y = h + step + 0.002 * np.ptp(h) * rng.standard_normal(n)
    return t, v, y


def test_a_settling_offset_is_named_drift_and_held_after_it_settles():
    t, v, y = _settling_record(3)
    rep = diagnose(t, v, y, progress=False)
    assert rep.effects == ["drift"], rep.report()
    kinds = [d["kind"] for d in rep.model.describe()]
    # a broken line in time, held at its last level after the fitted part: the six segments
    # until round 32; since then the 24 of the drift made of events (the 4 s step is one event)
    assert "event_drift" in kinds, kinds
    # within 1.5 noise floors (the play density is not the core's 20 plays exactly)
    assert rep.verdict == "explained" and rep.rms_heldout < 1.5 * rep.noise_floor, rep.report()
    assert _rms_held(rep, y, v) == pytest.approx(rep.rms_heldout, rel=1e-9)


def _langevin_unipolar_record(seed):
    """A magnetostrictive-like output saturating as a Langevin function of the
    hysteresis, driven by a unipolar stroke 0 ... 120 V."""
    rng = np.random.default_rng([seed, 7373])
    v = ex.unipolar_triangles(18_000, 6, 120.0, decay=0.4)
    h = me.play_core(v, 120.0)
    top = rng.uniform(0.5, 0.7) * np.max(h)
    y = top * me.langevin(3.0 * h / top)
    y = y + 0.002 * np.ptp(y) * rng.standard_normal(y.size)
    return np.arange(v.size) * 1e-3, v, y


def test_langevin_saturation_of_a_unipolar_stroke_is_saturation_alone():
    # before the algebraic map, the held-out unipolar rational case was named
    # saturation + asymmetry + gain_drift in 3/3 runs: one-sided saturation
    # drew a symmetric envelope and other parts mopped up
    t, v, y = _langevin_unipolar_record(1)
    rep = diagnose(t, v, y, progress=False)
    assert rep.effects == ["saturation"], rep.report()
    assert rep.verdict == "explained" and rep.rms_heldout < 1.5 * rep.noise_floor, rep.report()
    assert _rms_held(rep, y, v) == pytest.approx(rep.rms_heldout, rel=1e-9)


def test_output_algebraic_map_target_inverts_the_output_and_the_compensator_takes_it():
    part = OutputAlgebraic()
    part.set_output_range(0.0, 3.0)
    ctx = Context(np.linspace(0.0, 1.0, 5), 1e-3, 0.0, 1.0, 5e-3)
    vals = {"limit": 2.5, "centre": -1.0, "exponent": 1.7}
    u = np.linspace(-1.0, 4.0, 11) + 0.013     # off the centre, where the slope has a kink
    y = part.output(u, vals, ctx)
    # the target is the map's inverse wherever it is not clipped at 98 % of the limit
    back, w = part.target(y, vals, ctx)
    np.testing.assert_allclose(back, u, rtol=0, atol=1e-12)
    assert np.all(np.diff(y) > 0) and np.all(w > 0)
    # the slope is the derivative of the map (central differences, step 1e-6: error ~1e-10)
    d = (part.output(u + 1e-6, vals, ctx) - part.output(u - 1e-6, vals, ctx)) / 2e-6
    np.testing.assert_allclose(part.output_slope(u, vals, ctx), d, rtol=0, atol=1e-8)
    # a one-sided record lets the centre reach the output's ends, a two-sided one not
    assert OutputAlgebraic().parameters(ctx, set())[1].lower == -1.0
    two = Context(np.linspace(-1.0, 1.0, 5), 1e-3, 0.0, 1.0, 5e-3)
    assert OutputAlgebraic().parameters(two, set())[1].lower > -1.0


def test_the_diagnosed_algebraic_model_has_an_exact_inverse():
    t, v, y = _langevin_unipolar_record(1)
    rep = diagnose(t, v, y, effects=["saturation"], progress=False)
    model = rep.model
    assert "output_algebraic" in [d["kind"] for d in model.describe()], model.describe()
    ref = model.simulate(v)
    u = model.exact_inverse().simulate(ref)
    # the compensator brackets the input to 1e-9 of its range (144 V here), so the
    # output meets the reference to that times the model's slope: 1e-6 of the output
    # span is the bound the other parts' inverse tests use (tests/test_parts_inverse.py)
    assert np.max(np.abs(model.simulate(u) - ref)) < 1e-6 * np.ptp(ref)
    # and the input found is the one that made the reference
    assert np.max(np.abs(u - v)) < 1e-4 * np.ptp(v)

"""A stiffness that differs on either side of one output level (bimodular
elasticity: a stack stiffer in compression than in tension) after the
hysteresis: :class:`hystcomp.identify.parts.OutputHinge`, an asymmetry on
the output side."""

import numpy as np
import pytest
from realistic import excitations as ex
from realistic import mechanisms as me

from hystcomp.identify.parts import OutputHinge
from hystcomp.identify.parts_dynamics import HINGE_RATIO, HINGE_WIDTH


def test_the_hinge_has_slope_zero_below_its_corner_and_one_above():
    z = np.linspace(-1, 1, 2001)
    for c in (-0.5, 0.0, 0.4):
        b = OutputHinge().shape(z, {"corner": c})
        slope = np.gradient(b, z)
        far = np.abs(z - c) > 10 * HINGE_WIDTH      # beyond the rounded corner
        # softplus: the slope is 1 / (1 + exp(-(z - c) / w)), within exp(-10) of 0 or 1 there
        assert np.all(slope[far & (z < c)] < 1e-4) and np.all(slope[far & (z > c)] > 1 - 1e-4)
        assert np.all(np.diff(slope) >= -1e-12)       # convex: one corner, no wiggle
        # at the corner the value is w ln 2, the rounding's largest departure from max(z - c, 0)
        assert np.max(np.abs(b - np.maximum(z - c, 0))) == pytest.approx(HINGE_WIDTH * np.log(2), rel=1e-3)


def _bimodular_record(seed=0):
    """200 plays (not hystcomp's kernel) under triangles of decaying
    amplitude, 24 s at 1 kHz, followed by a spring whose compliance is 0.6
    times smaller for a negative force than for a positive one (a sharp
    corner, not the hinge's rounded one), and output noise of 0.2 % of the
    span."""
    rng = np.random.default_rng([seed, 8821])
    dt, n = 1e-3, 24_000
    v = ex.triangles(dt, n, 0.7, 45.0)
    f = me.play_core(v, 100.0)
    f = f - f.min() - 0.4 * np.ptp(f)          # zero force at 40 % of the stroke
    x = np.where(f > 0, f, 0.6 * f)              # stiffer in compression (f < 0)
    return np.arange(n) * dt, v, x + 0.002 * np.ptp(x) * rng.standard_normal(n)


def test_a_bimodular_spring_after_the_core_is_named_asymmetry_by_the_hinge():
    from hystcomp.diagnose import diagnose

    t, v, y = _bimodular_record()
    rep = diagnose(t, v, y, progress=False)
    assert rep.effects == ["asymmetry"], rep.report()
    kinds = [d["kind"] for d in rep.model.describe()]
    assert "output_hinge" in kinds, kinds
    assert rep.verdict == "explained" and rep.rms_heldout < 1.5 * rep.noise_floor, rep.report()
    # the slope ratio stays within [1/HINGE_RATIO, HINGE_RATIO]: the weight's bounds are set
    # from the driving output's scale (k scale), and the fitted weight is inside them
    hinge = [p for p in rep.model.structure.parts if p.kind == "output_hinge"][0]
    _, lo, hi, _ = hinge.columns(rep.model.values["output_hinge"], rep.model._ctx)
    assert lo[0] == pytest.approx((1 / HINGE_RATIO - 1) * hinge._scale) and hi[0] == pytest.approx(
        (HINGE_RATIO - 1) * hinge._scale)
    k = rep.model.theta[rep.model.names.index("output_hinge")]
    assert lo[0] <= k <= hi[0]
    held = ~rep._rec.train
    rms = np.sqrt(np.mean((y - rep.model.simulate(v))[held] ** 2))
    assert rms == pytest.approx(rep.rms_heldout, rel=1e-9)
    # the exact inverse steps the hinge too: model(inverse(r)) = r
    k = 3000
    ref = 0.8 * rep.model.simulate(v)[:k]
    u = rep.model.exact_inverse().simulate(ref)
    assert np.max(np.abs(rep.model.simulate(u) - ref)) < 1e-6 * np.ptp(ref)

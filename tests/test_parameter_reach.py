"""Parameter.reach (round 13): a nonlinear parameter whose best point ends at an edge of its
first bounds is searched on within its wider reach (VariableProjection.optimise); without a
reach it stays at the edge. A toy input part, a dead time of d samples, on a record delayed by
6 samples: first bounds 0 ... 2, reach 0 ... 10."""

import numpy as np
import pytest

from hystcomp.identify._part_kernels import fractional_delay
from hystcomp.identify.parts import Context, Parameter, Part
from hystcomp.identify.search import Structure, VariableProjection


class _Shift(Part):
    effect = "delay"
    kind = "toy_shift"
    slot = "input"
    order = 10
    description = "a dead time (toy)"

    def __init__(self, reach):
        self.reach = reach

    def parameters(self, ctx, kinds):
        return [Parameter("d", 1.0, 0.0, 2.0, False, self.reach)]

    def transform(self, x, values, ctx):
        out = np.empty_like(x)
        fractional_delay(np.ascontiguousarray(x), float(values["d"]), out)
        return out


@pytest.mark.parametrize("reach, expected", [((0.0, 10.0), 6.0), (None, 2.0)])
def test_search_goes_on_within_the_reach_from_an_edge(reach, expected):
    n = 2000
    t = np.arange(n) * 0.01
    v = np.sin(2 * np.pi * 0.3 * t) * (1 + t / t[-1])
    delayed = np.empty_like(v)
    fractional_delay(v, 6.0, delayed)
    y = 2.0 * delayed                    # a linear "core" of the delayed input
    ctx = Context(v, 0.01, 0.0, float(np.abs(v).max()), t[-1] + 0.01, n_thresholds=4)
    part = _Shift(reach)
    vp = VariableProjection(ctx, y, np.arange(n) < 3 * n // 4)
    st = Structure([part])
    pt = vp.optimise(st, {part.kind: {"d": 1.0}}, max_evaluations=40)
    # to 0.05 sample: Nelder-Mead's tolerance is 1e-3 of the reach's width (0.01 sample)
    assert pt.values[part.kind]["d"] == pytest.approx(expected, abs=0.05)


@pytest.mark.parametrize("param", [
    Parameter("d", 1.0, 0.0, 2.0, False, (0.5, 10.0)),      # reach does not contain the bounds
    Parameter("d", 1.0, 0.0, np.inf, False),                # an infinite bound
    Parameter("d", 1.0, 0.1, 2.0, True, (0.0, 10.0)),       # log scale, reach down to 0
])
def test_bad_bounds_or_reach_named(param):
    class _Bad(_Shift):
        kind = "toy_bad"

        def parameters(self, ctx, kinds):
            return [param]

    n = 400
    v = np.sin(np.linspace(0, 20, n))
    ctx = Context(v, 0.01, 0.0, 1.0, n * 0.01, n_thresholds=4)
    vp = VariableProjection(ctx, v.copy(), np.arange(n) < 300)
    part = _Bad(None)
    with pytest.raises(ValueError, match="Parameter 'd' of part 'toy_bad'"):
        vp.optimise(Structure([part]), {part.kind: {"d": 1.0}}, max_evaluations=5)

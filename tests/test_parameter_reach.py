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

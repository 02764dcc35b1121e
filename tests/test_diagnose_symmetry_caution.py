"""An asymmetry named as asymmetric envelopes that are mostly point symmetric
(loops that widen or narrow towards both ends alike) may be the core's shape
rather than an asymmetry: the report, the JSON and the gap figure say so
(round 41: HOLDOUT39's superconducting rod in Kim's critical state, whose loops
narrow as the field grows, got such envelopes named as an asymmetry on its clean
record at two seeds; over the committed realistic sets, on records driven to
both sides, a reversed share below 0.35 came on 4 of the 7 runs without a
labelled asymmetry and on none of the 11 with one).

The records come from cores written here or in the test generator
(``realistic.mechanisms``), not from hystcomp's parts: plays whose thresholds
shrink with the input's magnitude, ``r / (1 + |v| / B0)`` (Kim's law in a
critical-state core: symmetric under v -> -v), and the generator's plays whose
thresholds grow with the signed level (a true asymmetry), each with 0.2 %
output noise.
"""

import json

import matplotlib
import matplotlib.pyplot as plt
import numpy as np
import pytest
from realistic import excitations as ex
from realistic import mechanisms as me

from hystcomp.diagnose import diagnose
from hystcomp.diagnose.symmetry import (BALANCED, POINT_SYMMETRIC, antisymmetric_share, input_balance,
                                        symmetry_caution)

matplotlib.use("Agg")

DT, N = 2e-3, 12_000


def _kim_core(v, span, b0=20.0, n=200):
    """A linear term and 200 plays whose thresholds shrink with the input's
    magnitude, r_k / (1 + |v| / b0): the loops narrow towards both ends alike
    (symmetric under v -> -v), as a critical state whose critical current
    falls with the field."""
    r, w = me._density_thresholds(span, n, 0.6)
    w = w / w.sum()
    z = np.zeros_like(r)
    y = np.empty_like(v)
    for k, vk in enumerate(v):
        rk = r / (1.0 + abs(vk) / b0)
        z = np.minimum(np.maximum(z, vk - rk), vk + rk)
        y[k] = 0.35 * vk + 0.65 * (w @ z)
    return y


def _record(core, unipolar=False, seed=0):
    rng = np.random.default_rng([seed, 4101])
    v = ex.unipolar_triangles(N, 8, 90.0, decay=0.5) if unipolar else ex.triangles(DT, N, 0.8, 45.0)
    h = core(v, 90.0)
    return np.arange(N) * DT, v, h + 0.002 * np.ptp(h) * rng.standard_normal(N)


def _share_by_reflection(rho, ql, qr):
    """The reversed share written from the reflection itself: the model
    reflected through the origin has gl'(s) = -gr(-s), gr'(s) = -gl(-s); the
    reversed half of each envelope's departure from s is half its difference
    from the reflected one's."""
    s = np.linspace(-1.0, 1.0, 2001)
    gl = rho * (s + ql * s ** 2)
    gl_ref = -(-s + qr * s ** 2)      # -gr(-s); gr's halves mirror gl's
    # the linear gain (rho + 1) / 2 is common to both and the weights absorb it
    gain = 0.5 * (rho + 1.0)
    kept = 0.5 * (gl + gl_ref) - gain * s
    rev = 0.5 * (gl - gl_ref)
    a, k = np.sqrt(np.mean(rev ** 2)), np.sqrt(np.mean(kept ** 2))
    return a / (a + k)


@pytest.mark.parametrize("rho, ql, qr", [(1.0, 0.1, -0.1), (1.0, 0.1, 0.1), (0.98, 0.043, -0.063),
                                          (1.3, -0.2, 0.05), (0.7, 0.0, 0.0), (1.1, 0.25, -0.25)])
def test_the_share_is_what_reflection_reverses(rho, ql, qr):
    # 401 points against 2001: the RMS over a polynomial of degree 4 differs by O(1/n), under 1e-2 relative
    got = antisymmetric_share({"rho": rho, "q_left": ql, "q_right": qr})
    assert got == pytest.approx(_share_by_reflection(rho, ql, qr), abs=1e-2)


def test_the_share_needs_the_parts_values_and_a_skew_is_asymmetry():
    assert antisymmetric_share(None) is None
    assert antisymmetric_share({"rho": 1.0}) is None
    assert antisymmetric_share({"rho": 1.0, "q_left": 0.1, "q_right": -0.1, "skew": 0.3}) == 1.0


def test_the_balance_is_the_weaker_sides_reach():
    assert input_balance(-45.0, 45.0, 0.0) == 1.0
    assert input_balance(-20.0, 80.0, 0.0) == pytest.approx(0.25)
    assert input_balance(0.0, 100.0, 0.0) == 0.0
    assert input_balance(10.0, 100.0, 0.0) == 0.0
    # about a rest point that is not 0 V
    assert input_balance(10.0, 100.0, 50.0) == pytest.approx(40.0 / 50.0)


def test_the_caution_holds_its_bounds():
    assert symmetry_caution(None, 1.0) == ""
    assert symmetry_caution(POINT_SYMMETRIC, 1.0) == ""
    assert symmetry_caution(POINT_SYMMETRIC - 0.01, BALANCED - 0.01) == ""
    long = symmetry_caution(0.25, BALANCED)
    assert long.startswith("the asymmetric envelopes named are 75 % point symmetric")
    assert "4 of the 7 runs" in long and "none of the 11" in long
    assert symmetry_caution(0.1, 1.0, short=True) == "the asymmetry is 90 % point symmetric (the core may not be PI)"


@pytest.fixture(scope="module")
def kim():
    t, v, y = _record(_kim_core)
    return diagnose(t, v, y, progress=False)


def test_a_symmetric_core_named_an_asymmetry_is_cautioned(kim):
    # round 41: the loops that narrow towards both ends are read as asymmetric
    # envelopes of opposite curvature (q_left 0.12, q_right -0.23 at seed 0)
    assert "asymmetry" in kim.effects
    assert "asymmetric_envelopes" in kim.model.values
    assert kim.asymmetry_antisymmetric_share < POINT_SYMMETRIC
    assert kim.input_balance > 0.95
    text = kim.report()
    assert "caution: the asymmetric envelopes named are" in text
    js = json.loads(json.dumps(kim.to_dict()))
    assert js["schema_version"] == 22
    assert js["asymmetry_antisymmetric_share"] == pytest.approx(kim.asymmetry_antisymmetric_share)
    assert js["input_balance"] == pytest.approx(kim.input_balance)
    # the gap figure's title carries the short caution
    figs = kim.plots()
    assert "point symmetric (the core may not be PI)" in figs["gap"]._suptitle.get_text().replace("\n", " ")
    for f in figs.values():
        plt.close(f)


def test_a_true_asymmetry_is_not_cautioned():
    # the generator's plays whose thresholds grow with the signed level: wider
    # loops at the top than at the bottom
    t, v, y = _record(lambda v, span: me.asymmetric_play_core(v, span, 0.5))
    d = diagnose(t, v, y, progress=False)
    assert "asymmetry" in d.effects
    assert "point symmetric" not in d.report()
    share = d.asymmetry_antisymmetric_share
    assert share is None or share >= POINT_SYMMETRIC


def test_a_unipolar_record_cannot_show_a_reflection():
    t, v, y = _record(_kim_core, unipolar=True)
    d = diagnose(t, v, y, progress=False)
    assert d.input_balance == 0.0
    assert "point symmetric" not in d.report()

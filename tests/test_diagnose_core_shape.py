"""Asymmetric envelopes that are mostly point symmetric (loops that widen or
narrow towards both ends alike), named as the only asymmetry on a record
driven to both sides, are the core's shape, not an asymmetry: kept in the
model, not named (round 42's decision; round 41 gave it as a caution:
HOLDOUT39's superconducting rod in Kim's critical state, whose loops narrow
as the field grows, got such envelopes named as an asymmetry on its clean
record at two seeds; over the committed realistic sets, on records driven to
both sides, a reversed share below 0.35 came on 4 of the 7 runs without a
labelled asymmetry and on none of the 11 with one).

The records come from cores written here or in the test generator
(``realistic.mechanisms``), not from hystcomp's parts: plays whose thresholds
shrink with the input's magnitude, ``r / (1 + |v| / B0)`` (Kim's law in a
critical-state core: symmetric under v -> -v), and the generator's plays whose
thresholds grow with the signed level (a true asymmetry), each with 0.2 %
output noise.  The rule's bounds are tested on the search's output written
here (:func:`_searched`), so that each bound is met and missed by one value.
"""

import json

import matplotlib
import matplotlib.pyplot as plt
import numpy as np
import pytest
from realistic import excitations as ex
from realistic import mechanisms as me

from hystcomp.diagnose import diagnose
from hystcomp.envelopes import Polynomial
from hystcomp.models import MGPI
from hystcomp.signals import identification_experiment
from hystcomp.diagnose.symmetry import (BALANCED, POINT_SYMMETRIC, antisymmetric_share, core_shape, input_balance)

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


def _searched(share=0.25, balance=0.98, kinds=("asymmetric_envelopes",), revised_by=None, effects=None):
    """The keyword arguments a search hands on, as far as :func:`core_shape`
    reads them: one asymmetry step per kind in `kinds`, then a creep step."""
    steps = []
    for k in kinds:
        ev = {"extension": {"kind": k}}
        if revised_by:
            ev["revised"] = {"by": revised_by}
        steps.append({"effect": "asymmetry", "evidence": ev, "alternatives": [{"effect": "saturation"}]})
    steps.append({"effect": "creep", "evidence": {"extension": {"kind": "creep"}}, "alternatives": []})
    return {"effects": list(effects or ["asymmetry", "creep"]), "steps": steps,
            "ambiguous": {"asymmetry": ["saturation"]}, "stopped": "max_effects = 4 reached",
            "asymmetry_antisymmetric_share": share, "input_balance": balance}


def test_the_rule_reads_point_symmetric_envelopes_as_the_cores_shape():
    said = []
    kw = core_shape(_searched(), said.append)
    assert kw["effects"] == ["creep"]
    assert kw["ambiguous"] == {}
    assert kw["steps"][0]["core_shape"] and kw["steps"][0]["alternatives"] == []
    assert "core_shape" not in kw["steps"][1]
    cs = kw["core_shape"]
    assert (cs["part"], cs["antisymmetric_share"], cs["input_balance"], cs["step"]) == (
        "asymmetric_envelopes", 0.25, 0.98, 1)
    assert cs["why"].startswith("the asymmetric envelopes are 75 % point symmetric (reversed share 0.25 < 0.35)")
    assert kw["stopped"].endswith("asymmetry read as the core's shape (point-symmetric envelopes), not named")
    assert len(said) == 1 and said[0].startswith("core shape: ")


@pytest.mark.parametrize("kw", [
    _searched(share=POINT_SYMMETRIC),                       # at the bound: an asymmetry
    _searched(share=None),                                  # no envelopes in the final model
    _searched(balance=BALANCED - 0.01),                     # one side mostly: no reflection to see
    _searched(kinds=("asymmetric_envelopes", "level_thresholds")),   # another part names it too
    _searched(revised_by="output_quadratic"),               # replaced in the revision by another part
    _searched(effects=["creep"]),                           # not named (tentative)
])
def test_the_rule_leaves_an_asymmetry_it_cannot_read_so(kw):
    before = list(kw["effects"])
    out = core_shape(kw, lambda s: None)
    assert out["effects"] == before and out["core_shape"] is None
    assert not any(st.get("core_shape") for st in out["steps"])


def test_the_rule_holds_its_bounds_just_inside():
    assert core_shape(_searched(share=POINT_SYMMETRIC - 1e-3), lambda s: None)["core_shape"] is not None
    assert core_shape(_searched(balance=BALANCED), lambda s: None)["core_shape"] is not None


@pytest.fixture(scope="module")
def kim():
    t, v, y = _record(_kim_core)
    return diagnose(t, v, y, progress=False)


def test_a_symmetric_core_is_read_as_the_cores_shape(kim):
    # the loops that narrow towards both ends are fitted as asymmetric
    # envelopes of opposite curvature (72 % point symmetric at seed 0); they
    # stay in the model, and the asymmetry is not named
    assert "asymmetry" not in kim.effects
    assert "asymmetric_envelopes" in kim.model.values
    assert kim.asymmetry_antisymmetric_share < POINT_SYMMETRIC
    assert kim.input_balance > 0.95
    assert kim.core_shape["part"] == "asymmetric_envelopes"
    assert kim.core_shape["antisymmetric_share"] == kim.asymmetry_antisymmetric_share
    step = kim.steps[kim.core_shape["step"] - 1]
    assert step["effect"] == "asymmetry" and step["core_shape"]
    # the model with the envelopes reproduces the reported held-out RMS (the same numbers, recomputed)
    t, v, y = _record(_kim_core)
    held = ~kim._rec.train
    rms = np.sqrt(np.mean((y - kim.model.simulate(v))[held] ** 2))
    assert rms == pytest.approx(kim.rms_heldout, rel=1e-9)
    text = kim.report()
    assert "read as the core's shape" in text and "core: PI with point-symmetric envelopes" in text
    assert "caution" not in text
    js = json.loads(json.dumps(kim.to_dict()))
    assert js["schema_version"] == 30
    assert js["core_shape"]["step"] == kim.core_shape["step"]
    assert js["steps"][kim.core_shape["step"] - 1]["core_shape"] is True
    assert "asymmetry" not in js["effects"]
    assert js["asymmetry_antisymmetric_share"] == pytest.approx(kim.asymmetry_antisymmetric_share)
    assert js["input_balance"] == pytest.approx(kim.input_balance)
    # the gap figure's panel says what the step was read as
    figs = kim.plots()
    titles = [a.get_title() for a in figs["gap"].axes]
    assert any(t.startswith("+ point-symmetric envelopes (asymmetry fitted, read as the core's shape") for t in titles)
    for f in figs.values():
        plt.close(f)


def test_a_true_asymmetry_is_named():
    # the generator's plays whose thresholds grow with the signed level: wider
    # loops at the top than at the bottom
    t, v, y = _record(lambda v, span: me.asymmetric_play_core(v, span, 0.5))
    d = diagnose(t, v, y, progress=False)
    assert "asymmetry" in d.effects and d.core_shape is None
    assert "core's shape" not in d.report()
    share = d.asymmetry_antisymmetric_share
    assert share is None or share >= POINT_SYMMETRIC


# slow since round 61 (35 s in the default suite, whose CI run had reached 18 min of its 20): run with
# `pytest -m slow`
@pytest.mark.slow
def test_a_unipolar_record_cannot_show_a_reflection():
    t, v, y = _record(_kim_core, unipolar=True)
    d = diagnose(t, v, y, progress=False)
    assert d.input_balance == 0.0
    assert d.core_shape is None and "core's shape" not in d.report()


@pytest.mark.parametrize("seed", [20, 21])
def test_thesis_envelopes_of_opposite_curvature_are_the_cores_shape(seed):
    # an mGPI core (thesis eq. 23) whose envelopes bend by opposite curvatures,
    # gl(v) = v + c v^2 / A and gr(v) = v - c v^2 / A: reflected through the
    # origin the model is itself (-gr(-v) = gl(v)), loops that narrow towards
    # both ends alike. Until round 42 the library's generator drew this as its
    # asymmetry ("envelopes", c about 0.07 ... 0.11, within +-0.05 of opposite);
    # it is the core's shape: explained, nothing named. The library's model
    # parts make the record here, so this checks the rule's reading, not the
    # search's reach (the realistic sets do that).
    t, v, _ = identification_experiment(dt=0.01)
    rng = np.random.default_rng([seed, 4201])
    c = float(rng.uniform(0.07, 0.11))
    A = float(np.max(np.abs(v)))
    r = np.linspace(0.09 * A, 0.9 * A, 10)
    p = np.exp(-r / (0.4 * A))
    env = dict(interval=(-2 * A, 2 * A))
    y = MGPI(r, 0.7 * p / p.sum(), 0.3, envelope_left=Polynomial([0.0, 1.0, c / A], **env),
             envelope_right=Polynomial([0.0, 1.0, -c / A], **env)).simulate(v)
    y = y + 0.002 * np.ptp(y) * rng.standard_normal(y.size)
    rep = diagnose(t, v, y, progress=False)
    assert rep.effects == [] and rep.verdict == "explained"
    assert rep.core_shape is not None and rep.core_shape["antisymmetric_share"] < POINT_SYMMETRIC

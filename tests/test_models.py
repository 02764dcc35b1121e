"""Models: PI, MGPI (symmetric and asymmetric), GPI and StopPI against the
reference loops, chunking, loading curves, bounds, invertibility reasons,
serialisation and bad input."""

import json
import os
import sys

import numpy as np
import pytest

sys.path.insert(0, os.path.dirname(__file__))
import conftest as ref  # noqa: E402

from hystcomp import GPI, MGPI, PI, StopPI, model_from_dict  # noqa: E402
from hystcomp.envelopes import Atanh, Custom, Identity, Linear, Polynomial, Tanh  # noqa: E402

RNG = np.random.default_rng(2024)
R = np.array([0.25, 0.6, 1.0, 1.7, 2.5])
P = np.array([0.5, 0.3, 0.25, 0.1, 0.05])
V = ref.test_signal(500, amp=4.0, seed=3)


def _tanh_custom(a, b):
    return Custom(lambda x: a * np.tanh(b * x), lambda x: a * b / np.cosh(b * x) ** 2,
                  lambda y: np.arctanh(y / a) / b, range=(-a, a), name=f"tanh{a},{b}")


def _models():
    """One of each model type, built-in and Custom envelopes."""
    return {
        "PI": PI(R, P, 1.0),
        "PI_negative_weights": PI(R, [0.5, -0.2, 0.3, -0.1, 0.2], 0.8),
        "MGPI_identity": MGPI(R, P, 1.0),
        "MGPI_tanh": MGPI(R, P, 1.0, envelope=Tanh(5.0, 0.3)),
        "MGPI_tanh_offset": MGPI(R, P, 0.7, envelope=Tanh(5.0, 0.3, c=0.2)),
        "MGPI_atanh": MGPI(R, P, 1.0, envelope=Atanh(1.0, 0.1)),
        "MGPI_poly": MGPI(R, P, 1.0, envelope=Polynomial([0.0, 1.0, 0.0, 0.05], (-8.0, 8.0))),
        "MGPI_asym": MGPI(R, P, 1.0, envelope_left=Tanh(5.0, 0.3), envelope_right=Tanh(4.0, 0.2)),
        "MGPI_asym_poly": MGPI(R, P, 1.0, envelope_left=Polynomial([0.0, 1.0, 0.0, 0.05], (-8.0, 8.0)),
                               envelope_right=Linear(1.5)),
        "MGPI_custom": MGPI(R, P, 1.0, envelope=_tanh_custom(5.0, 0.3)),
        "MGPI_custom_asym": MGPI(R, P, 1.0, envelope_left=_tanh_custom(5.0, 0.3),
                                 envelope_right=_tanh_custom(4.0, 0.2)),
        "GPI": GPI(R, P, Tanh(5.0, 0.3), Tanh(4.0, 0.2), H=Tanh(2.0, 0.3)),
        "GPI_noH": GPI(R, P, Linear(1.0), Linear(2.0)),
        "GPI_linH": GPI(R, P, Tanh(5.0, 0.3), Tanh(5.0, 0.3), H=0.5),
        "StopPI": StopPI(R, P, 0.4),
    }


MODELS = _models()
# Python-side reference outputs, computed with math functions
REFS = {
    "PI": lambda v: ref.ref_pi(v, R, P, 1.0),
    "PI_negative_weights": lambda v: ref.ref_pi(v, R, [0.5, -0.2, 0.3, -0.1, 0.2], 0.8),
    "MGPI_identity": lambda v: ref.ref_pi(v, R, P, 1.0),
    "MGPI_tanh": lambda v: ref.ref_mgpi(v, R, P, 1.0, ref.ref_tanh(5.0, 0.3), ref.ref_tanh(5.0, 0.3)),
    "MGPI_tanh_offset": lambda v: ref.ref_mgpi(v, R, P, 0.7, ref.ref_tanh(5.0, 0.3, 0.2),
                                               ref.ref_tanh(5.0, 0.3, 0.2)),
    "MGPI_atanh": lambda v: ref.ref_mgpi(v, R, P, 1.0, ref.ref_atanh(1.0, 0.1), ref.ref_atanh(1.0, 0.1)),
    "MGPI_poly": lambda v: ref.ref_mgpi(v, R, P, 1.0, ref.ref_poly([0.0, 1.0, 0.0, 0.05], -8.0, 8.0),
                                        ref.ref_poly([0.0, 1.0, 0.0, 0.05], -8.0, 8.0)),
    "MGPI_asym": lambda v: ref.ref_mgpi(v, R, P, 1.0, ref.ref_tanh(5.0, 0.3), ref.ref_tanh(4.0, 0.2)),
    "MGPI_asym_poly": lambda v: ref.ref_mgpi(v, R, P, 1.0, ref.ref_poly([0.0, 1.0, 0.0, 0.05], -8.0, 8.0),
                                             ref.ref_linear(1.5)),
    "MGPI_custom": lambda v: ref.ref_mgpi(v, R, P, 1.0, ref.ref_tanh(5.0, 0.3), ref.ref_tanh(5.0, 0.3)),
    "MGPI_custom_asym": lambda v: ref.ref_mgpi(v, R, P, 1.0, ref.ref_tanh(5.0, 0.3), ref.ref_tanh(4.0, 0.2)),
    "GPI": lambda v: ref.ref_gpi(v, R, P, ref.ref_tanh(5.0, 0.3), ref.ref_tanh(4.0, 0.2), ref.ref_tanh(2.0, 0.3)),
    "GPI_noH": lambda v: ref.ref_gpi(v, R, P, ref.ident, ref.ref_linear(2.0)),
    "GPI_linH": lambda v: ref.ref_gpi(v, R, P, ref.ref_tanh(5.0, 0.3), ref.ref_tanh(5.0, 0.3),
                                      ref.ref_linear(0.5)),
    "StopPI": lambda v: ref.ref_stop_pi(v, R, P, 0.4),
}


def _input_for(name):
    # Atanh(1, 0.1) has domain |v| < 10; every other model takes V (|V| < 6)
    return V


@pytest.mark.parametrize("name", list(MODELS))
def test_simulate_matches_reference(name):
    model = MODELS[name]
    v = _input_for(name)
    y = model.simulate(v)
    yr = REFS[name](v)
    # the compiled sums add the same terms in another order and use numba's
    # tanh: agreement to 1e-13 of the output scale (|y| <= ~20).
    scale = max(1.0, np.max(np.abs(yr)))
    assert np.max(np.abs(y - yr)) <= 1e-13 * scale, np.max(np.abs(y - yr))


def test_pi_equals_mgpi_with_identity():
    y_pi = PI(R, P, 1.0).simulate(V)
    y_m = MGPI(R, P, 1.0, envelope=Identity()).simulate(V)
    np.testing.assert_array_equal(y_pi, y_m)
    assert PI(R, P, 1.0).n_states == MGPI(R, P, 1.0).n_states == R.size


@pytest.mark.parametrize("sym", [True, False])
def test_custom_envelope_equals_builtin(sym):
    # long enough to cross the 4096-sample block boundary of the NumPy path
    v = np.concatenate([V] * 10)
    if sym:
        mc = MGPI(R, P, 1.0, envelope=_tanh_custom(5.0, 0.3))
        mb = MGPI(R, P, 1.0, envelope=Tanh(5.0, 0.3))
    else:
        mc = MGPI(R, P, 1.0, envelope_left=_tanh_custom(5.0, 0.3), envelope_right=_tanh_custom(4.0, 0.2))
        mb = MGPI(R, P, 1.0, envelope_left=Tanh(5.0, 0.3), envelope_right=Tanh(4.0, 0.2))
    yc, sc = mc.simulate(v, return_state=True)
    yb, sb = mb.simulate(v, return_state=True)
    # same formulas, NumPy vs numba tanh and sum order: 1e-12 (brief's bound)
    np.testing.assert_allclose(yc, yb, rtol=0, atol=1e-12)
    np.testing.assert_allclose(sc, sb, rtol=0, atol=1e-12)


def _split(n, rng, k):
    cuts = np.sort(rng.choice(np.arange(1, n), size=k, replace=False))
    return [0, *cuts.tolist(), n]


@pytest.mark.parametrize("name", list(MODELS))
def test_chunked_equals_one_shot_exactly(name):
    model = MODELS[name]
    v = _input_for(name)
    y, s = model.simulate(v, return_state=True)
    rng = np.random.default_rng(abs(hash(name)) % 2**32)
    for k in (1, 3, 17):
        edges = _split(v.size, rng, k)
        state, parts = None, []
        for a, b in zip(edges[:-1], edges[1:]):
            out, state = model.simulate(v[a:b], initial_state=state, return_state=True)
            parts.append(out)
        np.testing.assert_array_equal(np.concatenate(parts), y)
        np.testing.assert_array_equal(state, s)
    # one sample at a time
    state, parts = None, []
    for x in v[:60]:
        out, state = model.simulate([x], initial_state=state, return_state=True)
        parts.append(out)
    np.testing.assert_array_equal(np.concatenate(parts), y[:60])


@pytest.mark.parametrize("name", list(MODELS))
def test_simulate_does_not_modify_initial_state(name):
    model = MODELS[name]
    _, s = model.simulate(V[:50], return_state=True)
    keep = s.copy()
    model.simulate(V[50:], initial_state=s)
    np.testing.assert_array_equal(s, keep)
    assert s.shape == (model.n_states,)


# -- loading curves -----------------------------------------------------------
def test_pi_loading_curve_formula_vs_simulate():
    m = PI(R, [0.5, -0.2, 0.3, -0.1, 0.2], 0.8)
    r = np.linspace(-4.0, 4.0, 81)
    sim = np.array([m.simulate([0.0, x])[-1] for x in r])
    # piecewise-linear formula vs the operator recursion: rounding only
    np.testing.assert_allclose(m.loading_curve(r), sim, rtol=0, atol=1e-14)
    assert isinstance(m.loading_curve(1.3), float)


@pytest.mark.parametrize("env", [Tanh(5.0, 0.3), Atanh(1.0, 0.1), Polynomial([0.0, 1.0, 0.0, 0.05], (-8, 8)),
                                 Linear(3.0)], ids=repr)
def test_mgpi_loading_curve_eq37(env):
    m = MGPI(R, P, 0.9, envelope=env)
    r = np.linspace(0.0, 6.0, 61)
    # eq. 37: phi(r) = p0 g(r) + sum_{r_i < r} p_i g(r - r_i), g(0) = 0
    phi = np.array([0.9 * env(x) + sum(pi * env(x - ri) for ri, pi in zip(R, P) if ri < x) for x in r])
    np.testing.assert_allclose(m.loading_curve(r), phi, rtol=1e-14, atol=1e-14)
    # odd envelopes: the falling curve is -phi
    np.testing.assert_allclose(m.loading_curve(-r), -phi, rtol=1e-14, atol=1e-14)


def test_pi_from_loading_curve_round_trip():
    m = PI(R, [0.5, -0.2, 0.3, -0.1, 0.2], 0.8)
    rec = PI.from_loading_curve(m.loading_curve, R)
    # slopes from exact kinks: differences of values of size ~5, 1e-13 absolute
    assert rec.p0 == pytest.approx(0.8, abs=1e-13)
    np.testing.assert_allclose(rec.weights, m.weights, rtol=0, atol=1e-13)
    np.testing.assert_array_equal(rec.thresholds, R)


# -- output bounds ------------------------------------------------------------
@pytest.mark.parametrize("seed", range(4))
def test_output_bounds_contain_simulated_outputs(seed):
    rng = np.random.default_rng(seed)
    r = np.sort(rng.uniform(0.1, 5.0, 6))
    p = rng.uniform(0.01, 1.0, 6)
    a1, a2 = rng.uniform(1, 5, 2)
    for m in (MGPI(r, p, 0.7, envelope=Tanh(a1, rng.uniform(0.1, 2))),
              MGPI(r, p, 0.7, envelope_left=Tanh(a1, rng.uniform(0.1, 2)), envelope_right=Tanh(a2, 0.5))):
        v = np.cumsum(rng.standard_normal(3000)) * 2.0  # random walk, reaches saturation
        y = m.simulate(v)
        lo, hi = m.output_bounds()
        assert lo <= y.min() and y.max() <= hi
        U = max(a1, a2) if not m.symmetric else a1
        # eq. 29: Q = U (p0 + sum p_i) for positive weights
        # (to 1e-14 relative: the bounds are widened by the rounding of the sum)
        assert hi == pytest.approx(U * (0.7 + p.sum()), rel=1e-14)
        assert lo == pytest.approx(-U * (0.7 + p.sum()), rel=1e-14)
        # and the bound is not vacuous: the walk drives the output past half of it
        assert np.abs(y).max() > 0.5 * hi


def test_output_bounds_unbounded_envelopes():
    assert PI(R, P, 1.0).output_bounds() == (-np.inf, np.inf)
    assert StopPI(R, P, 0.0).output_bounds() == (-float(np.sum(P * R)), float(np.sum(P * R)))
    assert StopPI(R, P, 1.0).output_bounds() == (-np.inf, np.inf)


# -- invertibility ------------------------------------------------------------
def test_is_invertible_reasons():
    assert PI(R, P, 1.0).is_invertible()

    c = PI(R, P, 0.0).is_invertible()
    assert not c and any("p0 = 0.0 is not positive" in s for s in c.reasons)
    c = PI(R, P, -1.0).is_invertible()
    assert not c and any("p0 = -1.0" in s for s in c.reasons)

    c = PI([1.0, 2.0, 3.0], [0.5, -2.0, 0.1], 1.0).is_invertible()
    assert not c and any("partial sum p0 + p_1 + ... + p_2 = -0.5" in s for s in c.reasons)

    c = MGPI(R, P, 1.0, envelope_left=Tanh(5.0, 0.3), envelope_right=Tanh(4.0, 0.3)).is_invertible()
    assert not c and any("gl != gr" in s for s in c.reasons)

    # gamma = v^3 is strictly increasing but gamma'(0) = 0: eq. 58 divides by
    # beta'(0) = 1/gamma'(0) which is infinite.
    c = MGPI(R, P, 1.0, envelope=Polynomial([0.0, 0.0, 0.0, 1.0], (-5.0, 5.0))).is_invertible()
    assert not c and any("beta'(0)" in s for s in c.reasons)

    c = MGPI(R, P, 1.0, envelope=Tanh(5.0, 0.3, c=0.2)).is_invertible()
    assert not c and any("gamma(0)" in s for s in c.reasons)

    # a saturating gamma with large weights: q_5 = phi(r_5) ~ 6.06 > sup gamma = 5,
    # where eq. 58 would need beta'(q_5) (found by this suite: inverse() used to
    # fail with an unrelated Atanh domain error while is_invertible() said yes)
    c = MGPI(R, P, 1.0, envelope=Tanh(5.0, 0.3)).is_invertible()
    assert not c and any("inverse thresholds" in s and "6.06" in s for s in c.reasons)
    assert MGPI(R, P, 1.0, envelope=Tanh(20.0, 0.1)).is_invertible()


@pytest.mark.parametrize(
    "model, phrase, points_to_exact",
    [
        (MGPI(R, P, 1.0, envelope_left=Tanh(5.0, 0.3), envelope_right=Tanh(4.0, 0.3)), "gl != gr", True),
        (MGPI(R, P, 1.0, envelope=Polynomial([0.0, 0.0, 0.0, 1.0], (-5.0, 5.0))), "beta'(0)", True),
        (MGPI(R, P, 1.0, envelope=Tanh(5.0, 0.3, c=0.2)), "gamma(0)", True),
        (MGPI(R, P, 1.0, envelope=Tanh(5.0, 0.3)), "inverse thresholds", True),
        (MGPI(R, P, -1.0, envelope=Tanh(5.0, 0.3)), "p0 = -1.0", False),
        (PI(R, [0.5, -2.0, 0.1, 0.1, 0.1], 1.0), "partial sum", False),
        (GPI(R, P, Tanh(5.0, 0.3), Tanh(4.0, 0.3), H=Tanh(1.0, 0.3)), "gl = gr", True),
    ],
    ids=["asym", "v^3", "offset", "q_range", "p0", "partial", "gpi"],
)
def test_inverse_raises_with_reason(model, phrase, points_to_exact):
    with pytest.raises(ValueError) as info:
        model.inverse()
    msg = str(info.value)
    assert phrase in msg
    if points_to_exact:
        assert "exact_inverse" in msg


def test_stop_pi_invertibility():
    assert StopPI(R, P, 0.5).is_invertible()
    c = StopPI(R, P, 0.0).is_invertible()
    assert not c and "p0" in c.reasons[0]
    assert not StopPI(R, [0.1, -0.1, 0.1, 0.1, 0.1], 1.0).is_invertible()


# -- serialisation ------------------------------------------------------------
SERIALISABLE = [n for n in MODELS if "custom" not in n]


@pytest.mark.parametrize("name", SERIALISABLE)
def test_json_round_trip_exact(name):
    m = MODELS[name]
    d = json.loads(json.dumps(m.to_dict()))
    back = model_from_dict(d)
    assert back == m
    assert type(back) is type(m)
    v = _input_for(name)
    np.testing.assert_array_equal(back.simulate(v), m.simulate(v))
    assert model_from_dict(m.to_json()) == m
    assert d["schema_version"] == 1


def test_symmetric_and_asymmetric_dicts_differ():
    assert "envelope" in MODELS["MGPI_tanh"].to_dict()
    d = MODELS["MGPI_asym"].to_dict()
    assert "envelope_left" in d and "envelope_right" in d and "envelope" not in d
    assert "envelope" not in MODELS["PI"].to_dict()


def test_schema_version_mismatch_raises():
    d = MODELS["MGPI_tanh"].to_dict()
    d["schema_version"] = 99
    with pytest.raises(ValueError, match="schema_version 99"):
        model_from_dict(d)
    del d["schema_version"]
    with pytest.raises(ValueError, match="schema_version None"):
        model_from_dict(d)
    with pytest.raises(ValueError, match="unknown"):
        model_from_dict({"schema_version": 1, "model": "NoSuchModel"})
    with pytest.raises(ValueError, match="not GPI"):
        GPI.from_dict(MODELS["PI"].to_dict())


def test_custom_envelope_model_to_dict_raises_type_error():
    with pytest.raises(TypeError, match="Custom.*cannot be written"):
        MODELS["MGPI_custom"].to_dict()
    with pytest.raises(TypeError, match="cannot be written"):
        GPI(R, P, _tanh_custom(1.0, 1.0), Tanh(1.0, 1.0)).to_dict()


# -- bad input -----------------------------------------------------------------
@pytest.mark.parametrize(
    "factory, exc, pattern",
    [
        (lambda: PI(R, P[:-1], 1.0), ValueError, r"weights has 4 entries but there are 5 thresholds"),
        (lambda: MGPI(R, P[:-1], 1.0), ValueError, r"weights has 4 entries"),
        (lambda: GPI(R, P[:3], Identity(), Identity()), ValueError, r"weights has 3 entries"),
        (lambda: StopPI(R, np.ones(6)), ValueError, r"weights has 6 entries"),
        (lambda: PI([1.0, 3.0, 2.0], [1, 1, 1], 1.0), ValueError,
         r"thresholds is not strictly increasing: thresholds\[2\] = 2.0"),
        (lambda: PI([1.0, 1.0], [1, 1], 1.0), ValueError, r"thresholds is not strictly increasing"),
        (lambda: PI([0.0, 1.0], [1, 1], 1.0), ValueError, r"thresholds starts at 0.0 .* must be > 0"),
        (lambda: MGPI([-1.0, 1.0], [1, 1], 1.0), ValueError, r"thresholds starts at -1.0"),
        (lambda: StopPI([0.0, 1.0], [1, 1]), ValueError, r"thresholds starts at 0.0"),
        (lambda: GPI([0.0, 1.0], [1, 1], Identity(), Identity()), ValueError, r"thresholds starts at 0.0"),
        (lambda: PI(R, P, np.nan), ValueError, r"p0 is nan"),
        (lambda: PI(R, P, "x"), TypeError, r"p0 is 'x'"),
        (lambda: PI(R, [1, np.inf, 1, 1, 1], 1.0), ValueError, r"weights holds a non-finite value \(inf\) at index 1"),
        (lambda: MGPI(R, P, 1.0, envelope=Tanh(1, 1), envelope_left=Tanh(1, 1)), ValueError,
         r"envelope sets both sides"),
        (lambda: MGPI(R, P, 1.0, envelope=Tanh(1, 1), envelope_right=Tanh(1, 1)), ValueError,
         r"envelope sets both sides"),
        (lambda: MGPI(R, P, 1.0, envelope_left=Tanh(1, 1)), ValueError,
         r"envelope_left and envelope_right go together"),
        (lambda: MGPI(R, P, 1.0, envelope_right=Tanh(1, 1)), ValueError,
         r"envelope_left and envelope_right go together"),
        (lambda: MGPI(R, P, 1.0, envelope=np.tanh), TypeError, r"envelope_left .* should be an hystcomp Envelope"),
        (lambda: GPI(R, P, Identity(), "tanh"), TypeError, r"envelope_right is 'tanh'"),
        (lambda: GPI(R, P, Identity(), Identity(), H=-1.0), ValueError, r"H is -1.0 but should be >= 0"),
    ],
)
def test_bad_constructor_arguments(factory, exc, pattern):
    with pytest.raises(exc, match=pattern):
        factory()


@pytest.mark.parametrize("name", list(MODELS))
def test_bad_simulate_arguments(name):
    m = MODELS[name]
    v = np.array([0.0, 0.5, 1.0, np.nan, 2.0])
    with pytest.raises(ValueError, match=r"Parameter v holds a non-finite value \(nan\) at sample index 3"):
        m.simulate(v)
    with pytest.raises(ValueError, match=r"Parameter v holds a non-finite value \(inf\) at sample index 0"):
        m.simulate([np.inf, 1.0])
    with pytest.raises(ValueError, match=rf"initial_state has {m.n_states + 1} entries but this model has "
                                         rf"{m.n_states} states"):
        m.simulate(V[:5], initial_state=np.zeros(m.n_states + 1))
    # a 2-D input is a batch of signals (issue 13, tests/test_batch.py); 3-D is an error
    with pytest.raises(ValueError, match=r"Parameter v has shape \(2, 3, 1\)"):
        m.simulate(np.zeros((2, 3, 1)))


@pytest.mark.parametrize("b", [0.5, 2.0])
def test_atanh_model_domain_violation(b):
    env = Atanh(1.0, b)
    edge = 1.0 / b
    for m in (MGPI(R, P, 1.0, envelope=env), MGPI(R, P, 1.0, envelope_left=env, envelope_right=Atanh(2.0, b)),
              GPI(R, P, env, env, H=env)):
        for bad, k in (([0.0, 0.5 * edge, edge], 2), ([0.0, -edge * 1.01, 0.0], 1)):
            with pytest.raises(ValueError) as info:
                m.simulate(np.array(bad))
            msg = str(info.value)
            assert f"v[{k}]" in msg and "Atanh" in msg and "outside the domain" in msg


def test_from_density_discretisation():
    m = MGPI.from_density(lambda r: np.exp(-0.1 * r), R, 1.0, envelope=Tanh(5.0, 0.3))
    widths = np.diff(np.concatenate([[0.0], R]))
    np.testing.assert_allclose(m.weights, np.exp(-0.1 * R) * widths, rtol=1e-15)
    assert m.envelope == Tanh(5.0, 0.3)
    with pytest.raises(ValueError, match="density"):
        MGPI.from_density(np.ones(3), R, 1.0)


def test_operator_responses_sum_to_output():
    for name in ("MGPI_tanh", "MGPI_asym", "MGPI_custom"):
        m = MODELS[name]
        w = m.operator_responses(V)
        assert w.shape == (V.size, R.size + 1)
        p_all = np.concatenate([[m.p0], m.weights])
        # same operators, the sum taken by a matrix product: rounding only
        np.testing.assert_allclose(w @ p_all, m.simulate(V), rtol=0, atol=1e-13)
        _, s = m.simulate(V[:100], return_state=True)
        w2 = m.operator_responses(V[100:], initial_state=s)
        np.testing.assert_allclose(w2, w[100:], rtol=0, atol=1e-13)


def test_gpi_as_pi_cascade():
    g = Tanh(5.0, 0.3)
    gpi = GPI(R, P, g, g, H=Tanh(2.5, 0.3))  # H = 0.5 gamma
    pi = gpi.as_pi()
    assert pi.p0 == pytest.approx(0.5, rel=1e-12)
    # GPI[v] = PI[gamma(v)]: the same recursion on gamma(v), rounding only
    np.testing.assert_allclose(gpi.simulate(V), pi.simulate(g(V)), rtol=0, atol=1e-13)
    with pytest.raises(ValueError, match="not a PI model"):
        MODELS["GPI"].as_pi()

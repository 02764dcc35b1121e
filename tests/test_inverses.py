"""Inverses: Krejci-Kuhnen PI inverse, the thesis's mGPI recipe, the GPI
cascade inverse and the exact inverse (unreachable targets, beta'(0) = 0)."""

import os
import sys
import warnings

import numpy as np
import pytest

sys.path.insert(0, os.path.dirname(__file__))
import conftest as ref  # noqa: E402

from hystcomp import GPI, MGPI, PI, ExactInverse, GPIInverse, StopPI, UnreachableWarning  # noqa: E402
from hystcomp.envelopes import Custom, Identity, Linear, Polynomial, Tanh  # noqa: E402
from hystcomp.inverses import mgpi_inverse_parameters, tracking_error  # noqa: E402

R = np.array([0.25, 0.6, 1.0, 1.7, 2.5])
P = np.array([0.5, 0.3, 0.25, 0.1, 0.05])
U = ref.test_signal(600, amp=4.0, seed=7)


def _span(u):
    return float(np.ptp(u))


def test_mgpi_identity_inverse_equals_pi_inverse():
    p = np.array([0.5, -0.2, 0.3, -0.1, 0.2])
    a = MGPI(R, p, 0.8).inverse()
    b = PI(R, p, 0.8).inverse()
    # eqs. 56-58 with gamma = v reduce to Krejci-Kuhnen: same numbers up to the
    # rounding of two different sum orders (1e-14 relative)
    np.testing.assert_allclose(a.thresholds, b.thresholds, rtol=1e-14)
    np.testing.assert_allclose(a.weights, b.weights, rtol=1e-13, atol=1e-15)
    assert a.p0 == pytest.approx(b.p0, rel=1e-15)
    assert isinstance(a.envelope, Identity)
    np.testing.assert_allclose(a.simulate(U), b.simulate(U), rtol=0, atol=1e-13 * _span(U))


def test_pi_inverse_both_orders_with_nonzero_state():
    m = PI(R, [0.5, -0.2, 0.3, -0.1, 0.2], 0.8)
    inv = m.inverse()
    _, s = m.simulate(U[:123], return_state=True)
    assert np.any(s != 0)
    si = m.inverse_state(s)
    v = U[123:]
    # 1e-12 of the span: both compositions are piecewise-linear with slopes of
    # order 1, so only the rounding of ~10 terms per sample remains.
    tol = 1e-12 * _span(v)
    np.testing.assert_allclose(inv.simulate(m.simulate(v, initial_state=s), initial_state=si), v, rtol=0, atol=tol)
    np.testing.assert_allclose(m.simulate(inv.simulate(v, initial_state=si), initial_state=s), v, rtol=0, atol=tol)
    # a wrong initial state breaks it (the check can fail)
    bad = inv.simulate(m.simulate(v, initial_state=s))
    assert np.max(np.abs(bad - v)) > 1e-3


def test_mgpi_recipe_exact_for_linear_envelope():
    m = MGPI(R, P, 1.0, envelope=Linear(3.0))
    inv = m.inverse()
    assert isinstance(inv.envelope, Linear) and inv.envelope.k == pytest.approx(1 / 3, rel=1e-15)
    # eq. 54: g0 = 1/p0; with a linear gamma the recipe is exact (rounding only)
    assert inv.p0 == 1.0
    u = 3 * U
    np.testing.assert_allclose(m.simulate(inv.simulate(u)), u, rtol=0, atol=1e-12 * _span(u))


def test_mgpi_recipe_parameters_eq56():
    g = Tanh(20.0, 0.1)   # q_j stay inside gamma's range (-20, 20)
    q, w, g0 = mgpi_inverse_parameters(R, P, 1.0, g)
    # eq. 56: q_j = p0 gamma(r_j) + sum_{i<=j} p_i gamma(r_j - r_i) = phi(r_j) (eq. 37)
    phi = MGPI(R, P, 1.0, envelope=g).loading_curve(R)
    np.testing.assert_allclose(q, phi, rtol=1e-14)
    assert g0 == 1.0
    # eq. 58, first weight: g_1 = [1/(p0 g'(r1) + p1 g'(0)) - g0 beta'(q1)] / beta'(0)
    beta = g.inverse_envelope()
    g1 = (1.0 / (g.derivative(R[0]) + P[0] * g.derivative(0.0)) - beta.derivative(q[0])) / beta.derivative(0.0)
    assert w[0] == pytest.approx(g1, rel=1e-13)


def test_mgpi_recipe_is_approximate_for_tanh_but_exact_inverse_is_not():
    m = MGPI(R, P, 1.0, envelope=Tanh(20.0, 0.1))
    u = 0.5 * U
    approx = tracking_error(m, m.inverse(), u)
    exact = tracking_error(m, m.exact_inverse(), u)
    # the analytic recipe leaves a visible error for a nonlinear envelope; the
    # exact inverse tracks to rounding (1e-9 of the span, the brief's bound)
    assert approx["max_percent"] > 1e-3
    assert exact["max"] <= 1e-9 * exact["span"]
    assert set(exact) >= {"rms", "max", "rms_percent", "max_percent", "span", "error"}


def _tanh_model(sym=True):
    if sym:
        return MGPI(R, P, 1.0, envelope=Tanh(2.0, 0.5))
    return MGPI(R, P, 1.0, envelope_left=Tanh(2.0, 0.5), envelope_right=Tanh(3.0, 0.3))


@pytest.mark.parametrize("sym", [True, False])
def test_unreachable_targets_clip_warn_count_and_raise(sym):
    m = _tanh_model(sym)
    lo, hi = m.output_bounds()
    Q = min(-lo, hi) if sym else 2.0 * (1.0 + P.sum())  # reachable: (-3 sum, 2 sum)
    t = np.linspace(0, 4 * np.pi, 400)
    u = 0.5 * Q * np.sin(t)
    u[57] = 1.5 * hi          # beyond the upper bound
    u[58] = 1.2 * hi
    u[300] = 1.3 * lo         # beyond the lower bound
    comp = m.exact_inverse()
    with pytest.warns(UnreachableWarning, match=r"3 of 400 targets .*first at sample index 57"):
        v = comp.simulate(u)
    assert comp.last_unreachable == (3, 57)
    y = m.simulate(v)
    ok = np.ones(u.size, bool)
    ok[[57, 58, 300]] = False
    # reachable targets tracked to rounding; clipped ones end at the nearest
    # reachable output (the saturation value, within 1e-6 of the bound)
    assert np.max(np.abs(y[ok] - u[ok])) <= 1e-9 * _span(u[ok])
    assert y[57] <= hi and y[57] >= hi * (1 - 1e-6) if sym else y[57] > 0.99 * 2.0 * (1 + P.sum())
    assert y[300] >= lo
    raising = m.exact_inverse(on_unreachable="raise")
    with pytest.raises(ValueError, match=r"first at sample index 57"):
        raising.simulate(u)
    # reachable input: no warning, counter reset
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        comp.simulate(u[ok])
    assert comp.last_unreachable == (0, -1)


def test_input_limits_make_targets_unreachable():
    m = PI(R, P, 1.0)
    comp = m.exact_inverse(input_limits=(-1.0, 1.0), on_unreachable="clip")
    u = np.array([0.0, 0.5, 3.0, 0.2])
    with pytest.warns(UnreachableWarning):
        v = comp.simulate(u)
    assert comp.last_unreachable == (1, 2)
    assert np.all(v <= 1.0) and np.all(v >= -1.0)
    assert v[2] == 1.0
    with pytest.raises(ValueError, match="input_limits"):
        m.exact_inverse(input_limits=(1.0, -1.0))
    with pytest.raises(ValueError, match="on_unreachable"):
        m.exact_inverse(on_unreachable="ignore")


def test_exact_inverse_beta_prime_zero_where_recipe_raises():
    # gamma = v^3: gamma'(0) = 0, the recipe divides by beta'(0) = infinity
    m = MGPI(R, P, 1.0, envelope=Polynomial([0.0, 0.0, 0.0, 1.0], (-6.0, 6.0)))
    with pytest.raises(ValueError, match="exact_inverse"):
        m.inverse()
    comp = m.exact_inverse()
    # targets inside what v in [-6, 6] reaches from any state (see properties)
    u = 30.0 * np.sin(np.linspace(0, 6 * np.pi, 500)) * np.linspace(1, 0.2, 500)
    v = comp.simulate(u)
    assert comp.last_unreachable == (0, -1)
    np.testing.assert_allclose(m.simulate(v), u, rtol=0, atol=1e-9 * _span(u))


def test_gpi_inverse_exact():
    g = Tanh(3.0, 0.4)
    gpi = GPI(R, P, g, g, H=Tanh(1.5, 0.4))   # H = 0.5 gamma
    inv = gpi.inverse()
    assert isinstance(inv, GPIInverse)
    u = 0.6 * gpi.output_bounds()[1] * np.sin(np.linspace(0, 10, 500))
    # gamma^-1 o PI^-1 is exact; atanh near the range ends amplifies rounding,
    # so 1e-10 of the span
    np.testing.assert_allclose(gpi.simulate(inv.simulate(u)), u, rtol=0, atol=1e-10 * _span(u))
    assert inv.last_unreachable == (0, -1)
    # with a non-zero state mapped by state_for
    _, s = gpi.simulate(np.linspace(0, 2, 20), return_state=True)
    v, _ = inv.simulate(u, initial_state=inv.state_for(s), return_state=True)
    np.testing.assert_allclose(gpi.simulate(v, initial_state=s), u, rtol=0, atol=1e-10 * _span(u))


def test_gpi_inverse_with_linear_cascade():
    gpi = GPI(R, P, Linear(2.0), Linear(2.0), H=1.0)   # H = v = 0.5 gamma
    assert gpi.is_invertible()
    u = 3 * U
    np.testing.assert_allclose(gpi.simulate(gpi.inverse().simulate(u)), u, rtol=0, atol=1e-12 * _span(u))


def test_gpi_inverse_unreachable_is_clipped_and_warned():
    g = Tanh(1.0, 1.0)
    gpi = GPI([0.5], [0.5], g, g, H=Tanh(1.0, 1.0))
    inv = gpi.inverse()
    with pytest.warns(UnreachableWarning, match="sample index 1"):
        inv.simulate([0.0, 5.0, 0.0])
    assert inv.last_unreachable[0] >= 1 and inv.last_unreachable[1] == 1


def test_exact_inverse_rejects_unsupported_models():
    with pytest.raises(NotImplementedError, match="compiled"):
        MGPI(R, P, 1.0, envelope=Custom(np.sinh, np.cosh, np.arcsinh)).exact_inverse()
    with pytest.raises(ValueError, match="increases with the input"):
        MGPI(R, P, -1.0, envelope=Tanh(1.0, 1.0)).exact_inverse()
    with pytest.raises(ValueError, match="increases with the input"):
        PI(R, [0.5, -2.0, 0.1, 0.1, 0.1], 1.0).exact_inverse()
    with pytest.raises(ValueError, match="increasing H"):
        GPI(R, P, Tanh(1, 1), Tanh(1, 1)).exact_inverse()
    with pytest.raises(TypeError, match="model"):
        ExactInverse("PI")


@pytest.mark.parametrize(
    "model",
    [
        PI(R, [0.5, -0.2, 0.3, -0.1, 0.2], 0.8),
        StopPI(R, P, 0.7),
        GPI(R, P, Tanh(5.0, 0.3), Tanh(4.0, 0.2), H=Linear(0.5)),
        MGPI(R, P, 1.0, envelope_left=Tanh(5.0, 0.3), envelope_right=Tanh(4.0, 0.2)),
        # the SIMD solver of the symmetric tanh mGPI (play_solve_tanh)
        MGPI(R, P, 1.0, envelope=Tanh(5.0, 0.3)),
        MGPI(R, P, 0.4, envelope=Tanh(3.0, 2.0, -0.7)),
    ],
    ids=["PI", "StopPI", "GPI", "MGPI_asym", "MGPI_tanh", "MGPI_tanh_steep_offset"],
)
def test_exact_inverse_every_family_and_chunks(model):
    u = 0.5 * U
    comp = model.exact_inverse()
    v, s = comp.simulate(u, return_state=True)
    np.testing.assert_allclose(model.simulate(v), u, rtol=0, atol=1e-9 * _span(u))
    # the compensator's state continues exactly
    v1, s1 = comp.simulate(u[:250], return_state=True)
    v2, s2 = comp.simulate(u[250:], initial_state=s1, return_state=True)
    np.testing.assert_array_equal(np.concatenate([v1, v2]), v)
    np.testing.assert_array_equal(s2, s)
    # its state holds [v_last, model state]: continuing the model from it works
    _, ms = model.simulate(v, return_state=True)
    np.testing.assert_allclose(s[1:], ms, rtol=0, atol=1e-12 * max(1.0, np.max(np.abs(ms))))


def _jump_model():
    # crossing envelopes (0.5 v above v for v < 0) and a left one bounded to [-8, 8]: once
    # v - r_5 leaves the domain, that play's lower boundary stops binding and its output drops
    # from 0.5 (v - r_5) to v + r_5, so the model's output jumps at v = -8 + r_5 (found by
    # hypothesis in test_properties.test_exact_inverse_composition, round 23)
    r = np.array([0.15378899, 0.30757799, 0.35757799, 0.85757799, 1.35757799])
    p = np.array([0.20652791, 0.01, 1.0, 1.0, 0.20652791])
    return MGPI(r, p, 1.0, envelope_left=Polynomial([0.0, 0.5, 0.0, 0.0], interval=(-8.0, 8.0)),
                envelope_right=Identity()), -8.0 + r[-1]


def test_exact_inverse_target_in_a_jump():
    model, x_jump = _jump_model()
    # the jump, from the virgin state: the outputs just above and just below it
    y_above, y_below = model.simulate(np.array([x_jump]))[0], model.simulate(np.array([x_jump - 1e-12]))[0]
    assert y_above - y_below > 0.1
    comp = model.exact_inverse()
    inside = [y_below + 0.3 * (y_above - y_below), y_below + 0.7 * (y_above - y_below)]
    for target in inside:
        with pytest.warns(UnreachableWarning, match="jump of its output"):
            v = comp.simulate(np.array([target]))
        assert comp.last_unreachable == (1, 0)
        # clipped to the nearer side of the jump (to 1e-10: the bracket closes within 1e-15 of the
        # input, the reference point below is 1e-12 off the jump, the output's slope there is about 2)
        nearer = y_below if target - y_below < y_above - target else y_above
        assert model.simulate(v)[0] == pytest.approx(nearer, abs=1e-10)
        with pytest.raises(ValueError, match="jump of its output"):
            ExactInverse(model, on_unreachable="raise").simulate(np.array([target]))
    # targets on either side of the jump are met to 1e-12 of the span, with no warning
    u = np.array([-10.0, y_below - 0.05, y_above + 0.05, -13.0, -6.0])
    with warnings.catch_warnings():
        warnings.simplefilter("error", UnreachableWarning)
        v = comp.simulate(u)
    assert comp.last_unreachable == (0, -1)
    np.testing.assert_allclose(model.simulate(v), u, rtol=0, atol=1e-12 * np.ptp(u))


def test_steep_continuous_output_is_not_a_jump():
    # an Atanh envelope near its domain's end is steep, not discontinuous: targets there are met
    from hystcomp.envelopes import Atanh
    model = MGPI(np.array([0.1, 0.2]), np.array([0.5, 0.5]), 1.0, envelope_left=Atanh(1.0, 0.5),
                 envelope_right=Atanh(2.0, 0.5))
    u = np.array([3.0, 6.0, 9.0, -9.0, 4.0])
    with warnings.catch_warnings():
        warnings.simplefilter("error", UnreachableWarning)
        v = model.exact_inverse().simulate(u)
    np.testing.assert_allclose(model.simulate(v), u, rtol=0, atol=1e-9 * np.ptp(u))

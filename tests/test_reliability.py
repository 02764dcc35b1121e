"""Regression tests of issue 12: wrong answers the audit found, each checked
against an independent reference (the equivalent PI, brute-force simulation,
the operator definition), and errors that must name their argument."""

import warnings

import numpy as np
import pytest

from hystcomp import GPI, MGPI, PI
from hystcomp.envelopes import Atanh, Polynomial, Tanh
from hystcomp.preisach import KP, Preisach, preisach_grid


# --------------------------------------------------------------------------
# symmetric mGPI whose envelope's range starts or ends at 0
# --------------------------------------------------------------------------
@pytest.mark.parametrize("sign", [1.0, -1.0])
def test_mgpi_range_ending_at_zero_matches_pi(sign):
    # gamma(v) = v on [0, 10] (or [-10, 0]): on inputs of that sign the mGPI
    # is the PI with the same weights, sample for sample
    interval = (0.0, 10.0) if sign > 0 else (-10.0, 0.0)
    g = Polynomial([0.0, 1.0], interval=interval)
    r, p = [1.0, 2.0], [0.5, 0.25]
    m = MGPI(r, p, 1.0, envelope=g)
    v = sign * np.array([0.0, 5.0, 3.0, 0.5, 7.0, 0.0, 9.5])
    expected = PI(r, p, 1.0).simulate(v)
    # exact arithmetic on these dyadic values: equality to 1e-12
    np.testing.assert_allclose(m.simulate(v), expected, atol=1e-12)
    np.testing.assert_allclose(m.operator_outputs(m.default_state()), 0.0, atol=0)


def test_mgpi_range_ending_at_zero_regressors_and_iosys():
    from hystcomp.identify._regressors import _initial_positions
    from hystcomp.iosys import hysteresis_system, initial_state

    g = Polynomial([0.0, 1.0], interval=(0.0, 10.0))
    r = np.array([1.0, 2.0])
    m = MGPI(r, [0.5, 0.25], 1.0, envelope=g)
    z0 = _initial_positions(r, g)
    np.testing.assert_array_equal(z0, m.default_state())
    assert g(z0).tolist() == [0.0, 0.0]
    np.testing.assert_array_equal(initial_state(hysteresis_system(m)), m.default_state())


def test_mgpi_range_ending_at_zero_exact_inverse():
    g = Polynomial([0.0, 1.0, 0.5], interval=(0.0, 4.0))   # v + v^2/2, range [0, 12]
    m = MGPI([0.5, 1.0], [0.4, 0.2], 1.0, envelope=g)
    u = np.array([0.0, 3.0, 1.0, 6.0, 2.0, 4.0])   # reachable from the virgin state
    v = m.exact_inverse().simulate(u)
    # per-sample monotone solve to 1e-9 (its bisection tolerance is far below)
    np.testing.assert_allclose(m.simulate(v), u, atol=1e-9)


# --------------------------------------------------------------------------
# GPI output bounds
# --------------------------------------------------------------------------
def test_gpi_output_bounds_hold():
    m = GPI([0.1], [1.0], Tanh(10, 1.0), Tanh(5, 1.0))
    lo, hi = m.output_bounds()
    v = 100 * np.sin(np.linspace(0, 30, 3000))
    y = m.simulate(v)
    assert lo <= y.min() and y.max() <= hi
    # and they are tight here: the play reaches sup gl - r = 9.9 (to 1e-9,
    # tanh(100) is 1 to machine precision)
    assert hi == pytest.approx(9.9, abs=1e-9)
    assert y.max() == pytest.approx(9.9, abs=1e-9)


def test_gpi_output_bounds_random():
    rng = np.random.default_rng(12)
    for _ in range(30):
        a_l, a_r = rng.uniform(0.5, 10, 2)
        r = np.sort(rng.uniform(0.01, 3, 3)) + np.arange(3) * 1e-3
        p = rng.uniform(-1, 1, 3)
        m = GPI(r, p, Tanh(a_l, rng.uniform(0.2, 2)), Tanh(a_r, rng.uniform(0.2, 2)))
        lo, hi = m.output_bounds()
        y = m.simulate(50 * rng.standard_normal(400))
        # 1e-12 absolute: sums of a few O(10) terms in another order
        assert lo - 1e-12 <= y.min() and y.max() <= hi + 1e-12


# --------------------------------------------------------------------------
# Preisach / KP level computation
# --------------------------------------------------------------------------
def test_preisach_switches_exactly_at_cell_centres():
    rng = np.random.default_rng(3)
    for _ in range(100):
        lo = rng.uniform(-5, 0)
        hi = lo + rng.uniform(0.1, 7)
        n = int(rng.integers(2, 30))
        m = Preisach.from_density(lambda a, b: np.ones_like(a), (lo, hi), n)
        c, _ = preisach_grid((lo, hi), n)
        # level = #{j : c_j <= v}: exactly j + 1 at c_j, j just below it
        assert m.level(c).tolist() == list(range(1, n + 1))
        assert m.level(np.nextafter(c, -np.inf)).tolist() == list(range(n))
        for j in range(n):
            at = m.simulate(np.array([lo - 1.0, c[j]]))[-1]
            above = m.simulate(np.array([lo - 1.0, np.nextafter(c[j], np.inf)]))[-1]
            below = m.simulate(np.array([lo - 1.0, np.nextafter(c[j], -np.inf)]))[-1]
            assert at == above and at != below


@pytest.mark.parametrize("cls", [Preisach, KP])
@pytest.mark.parametrize("big", [1e18, 1e300, np.finfo(float).max])
def test_plane_models_saturate_with_the_right_sign(cls, big):
    m = cls.from_density(lambda a, b: np.ones_like(a), (-1.0, 1.0), 5)
    y = m.simulate(np.array([0.0, big, -big, big]))
    top = m.simulate(np.array([0.0, 2.0, -2.0, 2.0]))
    # saturated: the same outputs as an input just beyond the grid
    np.testing.assert_allclose(y[1:], top[1:], atol=1e-12)
    assert y[1] > 0 > y[2]


# --------------------------------------------------------------------------
# Polynomial monotonicity check
# --------------------------------------------------------------------------
def test_polynomial_dip_between_check_points_is_refused():
    # gamma'(v) = (v - a)^2 - 1e-6 < 0 on a 2e-3 wide interval around a,
    # between the points of a 257-point grid on [-1, 1]
    a, e = 0.1234, 1e-6
    P = np.polynomial.Polynomial([-a, 1.0]) ** 3 / 3 - np.polynomial.Polynomial([0.0, e])
    with pytest.raises(ValueError, match="not increasing"):
        Polynomial(P.coef, interval=(-1.0, 1.0))


def test_polynomial_flat_point_is_accepted_and_inverted():
    a = 0.1234
    P = np.polynomial.Polynomial([-a, 1.0]) ** 3 / 3     # gamma' = (v - a)^2 >= 0
    g = Polynomial(P.coef, interval=(-1.0, 1.0))
    x = np.array([-0.9, 0.0, 0.3, 0.9])
    # Newton on a cubic, to 1e-9 in v
    np.testing.assert_allclose(g.inverse(g(x)), x, atol=1e-9)


# --------------------------------------------------------------------------
# NumericalInverse: unreachable targets with unbounded input limits
# --------------------------------------------------------------------------
def test_numerical_inverse_default_limits_stay_finite():
    from hystcomp.differential import BoucWen
    from hystcomp.inverses import UnreachableWarning

    m = BoucWen(A=1.0, alpha=0.6, beta=0.5, n=1.0, gain=0.0)   # output saturates
    comp = m.exact_inverse()
    u = np.concatenate([[0.0, 0.5], np.full(60, 5.0), np.full(60, -5.0)])
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        v = comp.simulate(u)
    assert any(issubclass(w.category, UnreachableWarning) for w in caught)
    assert np.all(np.isfinite(v))
    y = m.simulate(v)
    # clipped to the nearest reachable output: the saturation level, to 1e-6
    sat = m.simulate(np.array([0.0, 50.0]))[-1]
    assert y[1] == pytest.approx(0.5, abs=1e-9)
    assert y[61] == pytest.approx(sat, abs=1e-6)
    assert y[-1] == pytest.approx(-sat, abs=1e-6)
    # the inputs do not run away sample after sample
    assert np.max(np.abs(v)) < 1e3


# --------------------------------------------------------------------------
# hashes
# --------------------------------------------------------------------------
def test_equal_models_hash_equal():
    a = MGPI([1.0], [0.5], 1.0, envelope=Atanh(2.0, 0.5, offset=0.0))
    b = MGPI([1.0], [0.5], 1.0, envelope=Atanh(2.0, 0.5, offset=-0.0))
    assert a == b and hash(a) == hash(b)
    c = PI([1.0], [0.0], 1.0)
    d = PI([1.0], [-0.0], 1.0)
    assert c == d and hash(c) == hash(d)
    e = Preisach((-1.0, 1.0), np.triu(np.zeros((2, 2))).T)
    f = Preisach((-1.0, 1.0), -np.triu(np.zeros((2, 2))).T)
    assert e == f and hash(e) == hash(f)
    assert len({a, b, c, d}) == 2

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


# --------------------------------------------------------------------------
# clear errors instead of crashes (issue 12, second list)
# --------------------------------------------------------------------------
@pytest.mark.parametrize("make", [
    lambda: PI([1.0, 2.0], [0.5, 0.25], 1.0),
    lambda: MGPI([1.0, 2.0], [0.5, 0.25], 1.0, envelope=Tanh(2.0, 1.0)),
    lambda: MGPI([1.0], [0.5], 1.0, envelope_left=Tanh(2.0, 1.0), envelope_right=Tanh(3.0, 1.0)),
])
@pytest.mark.parametrize("bad", [np.inf, -np.inf])
def test_initial_state_holding_inf_is_refused(make, bad):
    from hystcomp import StopPI

    for m in (make(), StopPI([1.0, 2.0], [0.5, 0.25], 1.0)):
        state = m.default_state().copy()
        state[0] = bad
        with pytest.raises(ValueError, match=r"initial_state holds -?inf at index 0"):
            m.simulate([0.0, 1.0], initial_state=state)


def test_virgin_state_at_an_infinite_domain_end_is_accepted_back():
    from hystcomp.envelopes import Custom

    # a custom envelope on the whole line whose range (0, 2) excludes 0
    g = Custom(lambda v: 1.0 + np.tanh(v), lambda v: 1.0 - np.tanh(v) ** 2,
               lambda y: np.arctanh(y - 1.0), domain=(-np.inf, np.inf), range=(0.0, 2.0))
    m = MGPI([1.0], [0.5], 1.0, envelope=g)
    s0 = m.default_state()
    assert s0.tolist() == [-np.inf]
    v = np.array([0.0, 2.0, -1.0])
    np.testing.assert_array_equal(m.simulate(v, initial_state=s0), m.simulate(v))


def test_model_from_dict_with_a_missing_key_names_it():
    from hystcomp import GPI, StopPI, model_from_dict

    models = [PI([1.0], [0.5], 1.0), StopPI([1.0], [0.5], 1.0),
              MGPI([1.0], [0.5], 1.0, envelope=Tanh(2.0, 1.0)),
              GPI([1.0], [0.5], Tanh(2.0, 1.0), Tanh(3.0, 1.0)),
              Preisach.from_density(lambda a, b: np.ones_like(a), (-1, 1), 3)]
    for m in models:
        d = m.to_dict()
        assert model_from_dict(d) == m
        for key in d:
            if key in ("schema_version", "model", "H", "offset"):
                continue
            broken = {k: v for k, v in d.items() if k != key}
            with pytest.raises(ValueError, match=repr(key)):
                model_from_dict(broken)


def test_fit_on_a_constant_input_says_so():
    from hystcomp.identify import fit

    for kw in ({}, {"envelope": "atanh"}, {"envelope": "tanh", "asymmetric": True}):
        with pytest.raises(ValueError, match="Parameter v is constant"):
            fit(np.zeros(200), np.zeros(200), **kw)


@pytest.mark.parametrize("call, name", [
    (lambda s: s.staircase(5, []), "levels"),
    (lambda s: s.staircase(1, [0.0, 1.0]), "n"),
    (lambda s: s.staircase(-3, [1.0]), "n"),
    (lambda s: s.staircase(2.5, [1.0]), "n"),
    (lambda s: s.staircase(5, [0.0, np.nan]), "levels"),
    (lambda s: s.staircase(5, "ab"), "levels"),
    (lambda s: s.multisine(np.linspace(0, 1, 100), [1.0], taper=-0.1), "taper"),
    (lambda s: s.multisine(np.linspace(0, 1, 100), [1.0], taper=0.0), "taper"),
    (lambda s: s.multisine(np.linspace(0, 1, 100), []), "frequencies"),
    (lambda s: s.multisine(np.linspace(0, 1, 100), [np.nan]), "frequencies"),
    (lambda s: s.multisine(np.linspace(0, 1, 100), [-1.0]), "frequencies"),
    (lambda s: s.multisine([], [1.0]), "t"),
    (lambda s: s.multisine(np.linspace(1, 0, 100), [1.0]), "t"),
    (lambda s: s.multisine(np.linspace(0, 1, 100), [1.0], amplitude=np.inf), "amplitude"),
    (lambda s: s.decaying_sine([], 1.0), "t"),
    (lambda s: s.decaying_sine([0.0, 0.0, 1.0], 1.0), "t"),
    (lambda s: s.decaying_sine(np.linspace(0, 1, 10), np.nan), "frequency"),
    (lambda s: s.decaying_sine(np.linspace(0, 1, 10), 1.0, final_fraction=-0.5), "final_fraction"),
    (lambda s: s.decaying_sine(np.linspace(0, 1, 10), "fast"), "frequency"),
    (lambda s: s.identification_experiment(frequencies=[np.nan]), "frequencies"),
    (lambda s: s.identification_experiment(steps="four"), "steps"),
    (lambda s: s.identification_experiment(steps=0), "steps"),
])
def test_signals_validate_their_arguments(call, name):
    from hystcomp import signals

    with pytest.raises((ValueError, TypeError), match=rf"Parameter {name}\b"):
        call(signals)


def test_wrong_types_give_type_errors_naming_the_argument():
    from hystcomp.identify import validate
    from hystcomp.inverses import tracking_error
    from hystcomp.iosys import check_wiring, compensator_system, hysteresis_system
    from hystcomp.loops import compare

    m = PI([1.0], [0.5], 1.0)
    v = np.sin(np.linspace(0, 10, 300))
    t = 1e-3 * np.arange(300)
    cases = [
        (lambda: compensator_system("x"), "model"),
        (lambda: compensator_system(m, compensator="x"), "compensator"),
        (lambda: compensator_system("x", compensator=m.exact_inverse(), nominal_gain="auto",
                                    input_range=(0, 1)), "model"),
        (lambda: validate("x", v, v), "model"),
        (lambda: validate(None, v, v), "model"),
        (lambda: tracking_error("x", m.exact_inverse(), v), "model"),
        (lambda: tracking_error(m, None, v), "compensator"),
        (lambda: compare("x", v, t), "scenarios"),
        (lambda: compare([1, 2], v, t), r"scenarios\[0\]"),
        (lambda: compare({"a": 1}, v, t), r"scenarios\['a'\]"),
        (lambda: check_wiring("x", ["u"], ["y"]), "syslist"),
        (lambda: check_wiring(None, ["u"], ["y"]), "syslist"),
        (lambda: check_wiring([1, 2], ["u"], ["y"]), r"syslist\[0\]"),
        (lambda: check_wiring([hysteresis_system(m)], 5, ["w"]), "inplist"),
    ]
    for call, name in cases:
        with pytest.raises(TypeError, match=rf"Parameter {name}"):
            call()

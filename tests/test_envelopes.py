"""Envelopes: value / derivative / inverse consistency, domain errors, closed
form inverses, dict round trips and agreement with the compiled kernels."""

import json
import re

import numpy as np
import pytest

from hystcomp import _kernels as K
from hystcomp.envelopes import (
    Atanh,
    Custom,
    Identity,
    Inverse,
    Linear,
    Polynomial,
    Tanh,
    envelope_from_dict,
)


def _sinh_custom(with_finv):
    return Custom(np.sinh, np.cosh, np.arcsinh if with_finv else None, name="sinh")


# (envelope, sample inputs strictly inside its domain)
CASES = {
    "Identity": (Identity(), np.linspace(-5, 5, 41)),
    "Linear": (Linear(3.0), np.linspace(-5, 5, 41)),
    "Tanh": (Tanh(10.0, 0.2), np.linspace(-8, 8, 41)),
    "Tanh_offset": (Tanh(2.0, 0.7, c=0.4), np.linspace(-2.5, 2.5, 41)),
    "Atanh": (Atanh(1.0, 0.5), np.linspace(-1.9, 1.9, 41)),
    "Atanh_offset": (Atanh(2.0, 0.25, offset=-0.3), np.linspace(-3.9, 3.9, 41)),
    "Polynomial": (Polynomial([0.0, 1.0, 0.0, 0.5], interval=(-3, 3)), np.linspace(-3, 3, 41)),
    "Polynomial_quad": (Polynomial([0.1, 2.0, 0.3, 0.2], interval=(-2, 2)), np.linspace(-2, 2, 41)),
    "Custom_finv": (_sinh_custom(True), np.linspace(-3, 3, 41)),
    "Custom_newton": (_sinh_custom(False), np.linspace(-3, 3, 41)),
    "Inverse_poly": (Inverse(Polynomial([0.0, 1.0, 0.0, 1.0], interval=(-2, 2))), np.linspace(-9.9, 9.9, 41)),
    "Inverse_tanh": (Inverse(Tanh(3.0, 0.5)), np.linspace(-2.9, 2.9, 41)),
}
IDS = list(CASES)


@pytest.mark.parametrize("name", IDS)
def test_derivative_matches_central_difference(name):
    env, x = CASES[name]
    lo, hi = env.domain
    # stay inside closed domains by the step h
    h = 1e-6
    x = np.clip(x, lo + 2 * h if np.isfinite(lo) else -np.inf, hi - 2 * h if np.isfinite(hi) else np.inf)
    fd = (env(x + h) - env(x - h)) / (2 * h)
    d = env.derivative(x)
    # central difference error ~ h^2 f'''/6 + eps*|f|/h: with h = 1e-6 and |f|
    # up to ~30, about 1e-8 absolute; allow 1e-6 relative to the slope scale.
    scale = np.maximum(1.0, np.abs(d))
    assert np.all(np.abs(fd - d) <= 1e-6 * scale), np.max(np.abs(fd - d) / scale)
    assert np.all(d > 0) or name.startswith("Polynomial")


@pytest.mark.parametrize("name", IDS)
def test_inverse_of_value_is_identity(name):
    env, x = CASES[name]
    y = env(x)
    assert y.shape == x.shape
    assert np.all(np.diff(y) > 0), "envelope must be strictly increasing on the samples"
    back = env.inverse(y)
    # closed forms: a few ulps; the Newton / kernel inverses stop at 1e-14
    # relative; 1e-12 of the input scale (max 10) covers both with margin.
    assert np.max(np.abs(back - x)) <= 1e-12 * max(1.0, np.max(np.abs(x)))


@pytest.mark.parametrize("name", IDS)
def test_vectorised_matches_scalar_calls(name):
    env, x = CASES[name]
    x2 = x.reshape(-1, 1)[:40].reshape(5, 8)
    vals = env(x2)
    ders = env.derivative(x2)
    assert vals.shape == (5, 8) and ders.shape == (5, 8)
    scalar_vals = np.array([env(float(xi)) for xi in x2.reshape(-1)]).reshape(5, 8)
    scalar_ders = np.array([env.derivative(float(xi)) for xi in x2.reshape(-1)]).reshape(5, 8)
    assert isinstance(env(float(x[3])), float)
    # same arithmetic element by element, except the Newton inverse whose
    # stopping test is vectorised: allow 1e-13 relative.
    np.testing.assert_allclose(vals, scalar_vals, rtol=1e-13, atol=1e-13)
    np.testing.assert_allclose(ders, scalar_ders, rtol=1e-13, atol=1e-13)


@pytest.mark.parametrize("name", IDS)
def test_nan_and_inf_inputs_raise(name):
    env, x = CASES[name]
    for bad in (np.nan, np.inf, -np.inf):
        xs = x[:5].copy()
        xs[3] = bad
        with pytest.raises(ValueError, match=r"v\[3\]") as info:
            env(xs)
        assert "finite" in str(info.value)
        with pytest.raises(ValueError, match=r"\[3\]"):
            env.derivative(xs)
        ys = env(x[:5])
        ys[3] = bad
        with pytest.raises(ValueError, match=r"\[3\]"):
            env.inverse(ys)


@pytest.mark.parametrize(
    "env, bad, index, bound",
    [
        (Atanh(1.0, 0.5), [0.0, 1.0, 2.5, 3.0], 2, "2.0"),
        (Atanh(1.0, 0.5), [0.0, -2.0], 1, "-2.0"),          # open bound itself
        (Atanh(3.0, 4.0, offset=1.0), [0.1, 0.2, 0.24, -0.3, 0.25], 3, "-0.25"),
        (Polynomial([0.0, 1.0, 0.0, 1.0], interval=(-1.0, 2.0)), [0.0, 2.0, 2.0000001], 2, "2.0"),
        (Custom(np.log, lambda x: 1 / x, np.exp, domain=(0.0, np.inf), name="log"), [1.0, 0.0], 1, "0.0"),
    ],
)
def test_domain_error_names_envelope_bound_and_index(env, bad, index, bound):
    with pytest.raises(ValueError) as info:
        env(np.array(bad))
    msg = str(info.value)
    assert repr(env) in msg
    assert f"[{index}]" in msg
    assert re.search(rf"bound {re.escape(bound)}\b", msg), msg
    with pytest.raises(ValueError, match=re.escape(f"[{index}]")):
        env.derivative(np.array(bad))


def test_closed_polynomial_domain_accepts_its_ends():
    g = Polynomial([0.0, 1.0, 0.0, 1.0], interval=(-1.0, 2.0))
    assert g(np.array([-1.0, 2.0])).tolist() == [-2.0, 10.0]
    assert g.range == (-2.0, 10.0)
    assert g.inverse(np.array([-2.0, 10.0])).tolist() == pytest.approx([-1.0, 2.0], abs=1e-14)


def test_inverse_outside_range_raises_with_index():
    with pytest.raises(ValueError, match=r"sample index 1.*range"):
        Tanh(2.0, 1.0).inverse(np.array([0.0, 2.0]))
    with pytest.raises(ValueError, match=r"sample index 2"):
        Polynomial([0.0, 1.0], interval=(0.0, 1.0)).inverse(np.array([0.0, 1.0, 1.5]))


@pytest.mark.parametrize(
    "coeffs, interval",
    [
        ([0.0, -1.0, 0.0, 1.0], (-1.0, 1.0)),   # dips at 0
        ([0.0, 0.0, 1.0], (-1.0, 1.0)),         # v^2 decreases on [-1, 0]
        ([1.0, -2.0], (0.0, 1.0)),              # decreasing
        ([3.0, 0.0], (0.0, 1.0)),               # constant
        ([0.0, 1.0, -1.0], (0.0, 1.0)),         # turns down at 0.5
    ],
)
def test_polynomial_rejects_non_increasing(coeffs, interval):
    with pytest.raises(ValueError, match="not increasing"):
        Polynomial(coeffs, interval=interval)


@pytest.mark.parametrize(
    "coeffs, interval",
    [
        ([0.0, 0.0, 0.0, 1.0], (-1.0, 1.0)),    # v^3: zero slope at an interior point
        ([0.0, 0.0, 1.0], (0.0, 1.0)),          # v^2: zero slope at the lower end
        ([0.0, 2.0, -1.0], (0.0, 1.0)),         # 2v - v^2: zero slope at the upper end
    ],
)
def test_polynomial_accepts_strictly_increasing_with_isolated_flat_point(coeffs, interval):
    g = Polynomial(coeffs, interval=interval)
    x = np.linspace(*interval, 101)
    assert np.all(np.diff(g(x)) > 0)
    assert np.max(np.abs(g.inverse(g(x)) - x)) < 1e-7  # flat point: inverse ill-conditioned (cube root of eps)


def test_polynomial_bad_arguments_name_parameter():
    with pytest.raises(ValueError, match="coeffs"):
        Polynomial([1.0])
    with pytest.raises(ValueError, match="coeffs"):
        Polynomial([0.0, np.nan])
    with pytest.raises(ValueError, match="interval"):
        Polynomial([0.0, 1.0], interval=(1.0, 0.0))


@pytest.mark.parametrize(
    "factory, name",
    [(lambda: Linear(-1.0), "k"), (lambda: Tanh(0.0, 1.0), "a"), (lambda: Tanh(1.0, -1.0), "b"),
     (lambda: Atanh(1.0, 0.0), "b"), (lambda: Tanh(1.0, 1.0, c=np.inf), "c")],
    ids=["Linear_k", "Tanh_a", "Tanh_b", "Atanh_b", "Tanh_c"],
)
def test_bad_parameters_name_the_argument(factory, name):
    with pytest.raises(ValueError, match=rf"Parameter {name} is"):
        factory()


def test_custom_with_and_without_finv_agree():
    with_inv = _sinh_custom(True)
    newton = _sinh_custom(False)
    y = np.linspace(-50.0, 50.0, 201)
    # Newton stops at 1e-15 relative steps (documented 1e-14): compare to 1e-13.
    np.testing.assert_allclose(newton.inverse(y), np.arcsinh(y), rtol=1e-13, atol=1e-14)
    np.testing.assert_array_equal(with_inv.inverse(y), np.arcsinh(y))  # finv is used as given
    # bounded domain, numeric inverse inside it
    lg = Custom(np.log, lambda x: 1.0 / x, domain=(0.0, np.inf), range=(-np.inf, np.inf), name="log")
    np.testing.assert_allclose(lg.inverse(np.array([-3.0, 0.0, 2.0])), np.exp([-3.0, 0.0, 2.0]), rtol=1e-13)
    assert "log" in repr(lg)


def test_custom_range_from_finite_domain_ends():
    g = Custom(lambda x: 2 * x, lambda x: 2 + 0 * x, domain=(-1.0, 3.0))
    assert g.range == (-2.0, 6.0)
    assert Custom(np.tanh, lambda x: 1 - np.tanh(x) ** 2).range == (-np.inf, np.inf)


def test_custom_bad_arguments():
    with pytest.raises(TypeError, match="callable"):
        Custom(1.0, np.cosh)
    with pytest.raises(ValueError, match="domain"):
        Custom(np.sinh, np.cosh, domain=(1.0, 1.0))


def test_custom_to_dict_raises_type_error():
    with pytest.raises(TypeError, match="cannot be written"):
        _sinh_custom(True).to_dict()
    with pytest.raises(TypeError, match="cannot be written"):
        Inverse(_sinh_custom(True)).to_dict()


# -- closed-form inverse envelopes -------------------------------------------
@pytest.mark.parametrize(
    "env, expected_type",
    [
        (Identity(), Identity),
        (Linear(3.0), Linear),
        (Tanh(10.0, 0.2), Atanh),
        (Tanh(2.0, 0.7, c=0.4), Atanh),
        (Tanh(1.5, 2.0, c=-1.1), Atanh),
        (Atanh(1.0, 0.5), Tanh),
        (Atanh(2.0, 0.25, offset=-0.3), Tanh),
        (Atanh(0.5, 3.0, offset=0.8), Tanh),
    ],
)
def test_inverse_envelope_closed_forms(env, expected_type):
    beta = env.inverse_envelope()
    assert type(beta) is expected_type
    # domain and range swap
    np.testing.assert_allclose(beta.domain, env.range, rtol=1e-15)
    np.testing.assert_allclose(beta.range, env.domain, rtol=1e-15)
    lo, hi = env.domain
    lo, hi = max(lo, -6.0), min(hi, 6.0)
    x = np.linspace(lo, hi, 203)[1:-1]
    y = env(x)
    # beta(gamma(x)) = x up to the conditioning of the inversion: rounding y
    # (relative eps) moves x by eps |y| / gamma'(x), large where tanh saturates;
    # allow 64 such units plus 1e-13 absolute.
    eps = np.finfo(float).eps
    tol = 1e-13 + 64 * eps * (np.abs(y) + 1.0) / env.derivative(x)
    assert np.all(np.abs(beta(y) - x) <= tol)
    assert np.all(np.abs(beta(y) - env.inverse(y)) <= tol)
    # beta'(y) = 1/gamma'(x); where gamma' is tiny (saturated tanh) both sides
    # are ill-conditioned (relative error ~ eps / gamma'), so compare where
    # gamma' >= 1e-4 of its maximum: the error there is below 1e-11 relative.
    d = env.derivative(x)
    ok = d >= 1e-4 * d.max()
    assert ok.sum() > 50
    np.testing.assert_allclose(beta.derivative(y[ok]), 1.0 / d[ok], rtol=1e-9)
    # the inverse of the inverse is the original envelope (parameters to rounding)
    back = beta.inverse_envelope()
    assert type(back) is type(env)
    np.testing.assert_allclose(back(x), env(x), rtol=1e-13, atol=1e-13)


def test_linear_and_tanh_inverse_parameters():
    assert Linear(4.0).inverse_envelope().k == 0.25
    b = Tanh(10.0, 0.2, c=0.5).inverse_envelope()
    # y = a tanh(b v + c) <=> v = (1/b) atanh(y/a) - c/b
    assert (b.a, b.b, b.offset) == pytest.approx((5.0, 0.1, -2.5), rel=1e-15)
    t = Atanh(2.0, 0.25, offset=-0.3).inverse_envelope()
    # y = a atanh(b v) + d <=> v = (1/b) tanh(y/a - d/a)
    assert (t.a, t.b, t.c) == pytest.approx((4.0, 0.5, 0.15), rel=1e-15)


def test_generic_inverse_envelope_for_polynomial():
    g = Polynomial([0.0, 1.0, 0.0, 1.0], interval=(-2.0, 2.0))
    beta = g.inverse_envelope()
    assert isinstance(beta, Inverse)
    assert beta.inverse_envelope() == g
    y = np.linspace(-10.0, 10.0, 51)
    np.testing.assert_allclose(g(beta(y)), y, rtol=0, atol=1e-12)


# -- serialisation ------------------------------------------------------------
@pytest.mark.parametrize(
    "env",
    [
        Identity(), Linear(3.0), Tanh(10.0, 0.2), Tanh(2.0, 0.7, c=0.4), Atanh(1.0, 0.5),
        Atanh(2.0, 0.25, offset=-0.3), Polynomial([0.1, 2.0, 0.3, 0.2], interval=(-2, 2)),
        Inverse(Polynomial([0.0, 1.0, 0.0, 1.0], interval=(-2, 2))),
        Inverse(Tanh(3.0, 0.5)),
    ],
    ids=repr,
)
def test_to_dict_round_trip(env):
    d = json.loads(json.dumps(env.to_dict()))
    back = envelope_from_dict(d)
    assert back == env
    assert type(back) is type(env)
    assert back.domain == env.domain and back.range == env.range
    lo, hi = env.domain
    x = np.linspace(max(lo, -3.0), min(hi, 3.0), 31)[1:-1]
    np.testing.assert_array_equal(back(x), env(x))


def test_envelope_from_dict_errors():
    with pytest.raises(ValueError, match="'type'"):
        envelope_from_dict({"a": 1})
    with pytest.raises(ValueError, match="unknown"):
        envelope_from_dict({"type": "Sigmoid"})


# -- compiled kernels ---------------------------------------------------------
@pytest.mark.parametrize("name", [n for n in IDS if not n.startswith("Custom")])
def test_compiled_kernel_matches_numpy(name):
    env, x = CASES[name]
    kind, prm = env.kernel_spec()
    assert kind != K.CUSTOM
    kv = np.array([K.env_value(kind, prm, float(xi)) for xi in x])
    kd = np.array([K.env_derivative(kind, prm, float(xi)) for xi in x])
    y = env(x)
    ki = np.array([K.env_inverse(kind, prm, float(yi)) for yi in y])
    # same formulas in numba and NumPy; numba's tanh/atanh or the Newton
    # polynomial inverse may differ by a few ulps: 1e-13 relative.
    np.testing.assert_allclose(kv, y, rtol=1e-13, atol=1e-13)
    np.testing.assert_allclose(kd, env.derivative(x), rtol=1e-13, atol=1e-13)
    np.testing.assert_allclose(ki, x, rtol=1e-12, atol=1e-12)


def test_custom_has_no_compiled_form():
    assert _sinh_custom(True).kernel_spec()[0] == K.CUSTOM
    assert Inverse(_sinh_custom(True)).kernel_spec()[0] == K.CUSTOM


def test_inverse_of_an_inverse_keeps_a_closed_domain_closed():
    # Inverse(Inverse(P)) has P's closed domain [-2, 2]; it used to be treated as open, so v = 2 (P's own end,
    # where P(2) = 2 + 8 = 10) was refused
    P = Polynomial([0, 1, 0, 1], interval=(-2, 2))
    twice = Inverse(Inverse(P))
    assert twice.domain == (-2.0, 2.0) and not twice.domain_open
    assert float(twice(2.0)) == pytest.approx(10.0, rel=1e-12)
    with pytest.raises(ValueError, match="outside the domain"):
        twice(2.0 + 1e-9)

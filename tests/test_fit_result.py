"""One fit result (issue 14): parameters by name with standard errors and
covariance, AIC/BIC, report(), to_dict()/to_json(); the old names and
attributes keep working."""

import json

import numpy as np
import pytest

from hystcomp import MGPI, PI
from hystcomp.envelopes import Tanh
from hystcomp.identify import EnvelopeFitResult, FitResult, ModelFit, fit, fit_backlash_like, fit_weights
from hystcomp.identify.solver import _Problem

R = np.array([0.6, 1.2, 1.8, 2.4])
P = np.array([0.4, 0.3, 0.2, 0.1])
T = np.linspace(0, 4, 2000)
V = 3 * np.sin(2 * np.pi * T) * (0.6 + 0.4 * np.cos(0.7 * np.pi * T))
CLEAN = PI(R, P, p0=1.0).simulate(V) + 0.2
SIGMA = 0.05


def test_standard_errors_match_a_monte_carlo_over_noise_draws():
    """The Gram-matrix standard errors against the scatter of the estimates
    over 300 independent noise draws on a case built for it: every weight
    well inside its constraint (no bound active), white Gaussian noise of a
    known level, an input with minor loops so that the columns are not
    collinear."""
    rng = np.random.default_rng(20241123)
    prob = _Problem(R, "nonnegative", None, True, None)   # compiled once for the 300 solves
    est, se = [], []
    for _ in range(300):
        res = fit_weights(V, CLEAN + SIGMA * rng.standard_normal(V.size), thresholds=R, model="pi",
                          _problem=prob)
        est.append([res.params[n] for n in res.param_names])
        se.append([res.stderr[n] for n in res.param_names])
    est, se = np.array(est), np.array(se)
    assert res.param_names == ["p0", "p1", "p2", "p3", "p4", "offset"]
    empirical = est.std(axis=0, ddof=1)
    predicted = se.mean(axis=0)
    # the empirical standard deviation of 300 draws has a relative sampling
    # error of 1/sqrt(2 * 299) = 4.1 %; 15 % is 3.6 of those (the predicted
    # one varies from draw to draw by only ~1/sqrt(2n) = 1.6 %)
    np.testing.assert_allclose(predicted, empirical, rtol=0.15)
    # the estimates are unbiased: the mean within 4 standard errors of the mean
    truth = np.array([1.0, *P, 0.2])
    assert np.all(np.abs(est.mean(axis=0) - truth) < 4 * empirical / np.sqrt(300))
    # and the correlations (here large: neighbouring plays overlap) too
    emp_corr = np.corrcoef(est.T)
    np.testing.assert_allclose(res.correlation, emp_corr, atol=0.15)


def test_weight_held_at_zero_has_zero_standard_error():
    y = PI(R, [0.4, 0.0, 0.2, 0.1], p0=1.0).simulate(V) - 0.05 * PI([1.2], [1.0], p0=0.0).simulate(V)
    res = fit_weights(V, y + 0.01 * np.random.default_rng(0).standard_normal(V.size), thresholds=R,
                      model="pi")
    assert abs(res.params["p2"]) < 1e-6 and res.stderr["p2"] == 0.0   # QP accuracy ~1e-9
    assert res.stderr["p1"] > 0 and "held on a constraint" in res.report()


def test_envelope_fit_covariance_is_joint():
    """fit(): the envelope parameter and the weights together.  The weights'
    standard errors in the joint fit are at least those of the weights for
    the envelope held fixed (a Schur complement), and the envelope
    parameter's is finite and small on a clean record."""
    true = MGPI([1.0, 2.0], [0.5, 0.2], 1.0, envelope=Tanh(1 / 0.3, 0.3))
    y = true.simulate(V) + 0.01 * np.random.default_rng(1).standard_normal(V.size)
    res = fit(V, y, thresholds=[1.0, 2.0])
    assert isinstance(res, FitResult) and res.param_names[0] == "ln(b V)"
    assert 0 < res.stderr["ln(b V)"] < 0.05
    fixed = fit_weights(V, y, thresholds=[1.0, 2.0], envelope=res.envelope)
    for name in ("p0", "p1", "p2"):
        assert res.stderr[name] >= fixed.stderr[name] * (1 - 1e-6)
    cov = res.covariance
    assert cov.shape == (5, 5) and np.allclose(cov, cov.T) and np.all(np.linalg.eigvalsh(cov) > -1e-12)
    assert res.n_parameters == fixed.n_parameters + 1


def test_nonlinear_fit_has_shape_parameter_errors():
    from hystcomp.differential import BacklashLike

    v = 4 * np.sin(np.linspace(0, 20, 2000))
    y = BacklashLike(alpha=1.5, c=3.0, B1=1.0).simulate(v) + 0.01 * np.random.default_rng(2).standard_normal(2000)
    res = fit_backlash_like(v, y)
    err = res.stderr
    assert res.param_names == ["shape[0]", "shape[1]", "shape[2]", "offset"]
    assert all(0 < err[f"shape[{i}]"] < 0.1 for i in range(3)) and np.isnan(err["offset"])
    assert res.aic < res.bic and "shape[0]" in res.report()


def test_one_class_and_old_attributes():
    assert EnvelopeFitResult is FitResult and ModelFit is FitResult
    res = fit_weights(V, CLEAN, thresholds=R, model="pi")
    # the old attributes
    np.testing.assert_allclose(res.weights, P, atol=1e-6)
    assert res.p0 == pytest.approx(1.0, abs=1e-6) and res.offset == pytest.approx(0.2, abs=1e-6)
    assert res.n_parameters == 6 and res.rmse < 1e-6 and res.success
    assert res.params["p3"] == pytest.approx(0.2, abs=1e-6)
    n = res.n_train
    assert res.aic - res.bic == pytest.approx(2 * 6 - 6 * np.log(n))
    d = json.loads(res.to_json())
    assert d["params"]["p1"]["value"] == pytest.approx(0.4, abs=1e-6)
    assert d["param_names"] == res.param_names and len(d["covariance"]) == 6
    assert d["n_train"] == n and d["model"].startswith("PI(")
    assert repr(res).startswith("FitResult(model=PI(")

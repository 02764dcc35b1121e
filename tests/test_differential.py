"""Bouc-Wen (eq. 3), backlash-like (eqs. 5-6) and Duhem (eqs. 1-2) models:
integration in the input against scipy's solve_ivp on the same input
path, the analytic bounds, rate independence, identification, numerical
inverses and python-control blocks."""

import json
import math
import warnings

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from hystcomp.differential import BacklashLike, BoucWen, Duhem
from hystcomp.identify import fit_backlash_like, fit_bouc_wen, fit_duhem
from hystcomp.inverses import UnreachableWarning
from hystcomp.models import model_from_dict


def path_reference(rate, v, w0=0.0, v0=0.0):
    """Integrate dw/dv = rate(w, v, s) along the piecewise-linear input path
    with solve_ivp (RK45, rtol 1e-12), one monotone segment at a time."""
    out = []
    w = w0
    for x in v:
        if x != v0:
            s = 1.0 if x > v0 else -1.0
            sol = solve_ivp(lambda u, y: [rate(y[0], u, s)], (v0, x), [w], rtol=1e-12, atol=1e-14)
            w = float(sol.y[0, -1])
        v0 = x
        out.append(w)
    return np.array(out)


def bw_rate(A, alpha, beta, n):
    return lambda w, u, s: A - beta * abs(w) ** n - alpha * s * abs(w) ** (n - 1) * w


SIGNAL = 3 * np.sin(np.linspace(0, 12, 121)) * np.linspace(1.0, 0.4, 121)


@pytest.mark.parametrize("n", [1.0, 1.5, 2.0, 3.0])
def test_bouc_wen_matches_solve_ivp(n):
    m = BoucWen(A=1.0, alpha=0.7, beta=0.3, n=n)
    ref = path_reference(bw_rate(1.0, 0.7, 0.3, n), SIGNAL)
    # n = 1 is solved in closed form (rounding); otherwise RK4 sub-steps with
    # |dv| * stiffness <= 0.05, split at w = 0.  Measured: 4.3e-7 for n = 1.5
    # (on the first step from w = 0, where |w|^1.5 is not twice
    # differentiable, so RK4 loses its order), 5e-9 for n = 2, 3e-9 for n = 3
    tol = {1.0: 1e-10, 1.5: 1e-6}.get(n, 1e-8)
    np.testing.assert_allclose(m.simulate(SIGNAL), ref, rtol=0, atol=tol)


def test_bouc_wen_stiff_steps():
    """Large steps on a stiff loop (|dv| * stiffness ~ 1e4): bounded work and
    the right equilibrium."""
    m = BoucWen(A=1.0, alpha=600.0, beta=400.0, n=2.0)
    y = m.simulate([0.0, 3.0, -3.0, 2.0])
    wb = m.w_bound()
    # after a long monotone step w sits at the branch's equilibrium +-wb
    np.testing.assert_allclose(y[1:], [wb, -wb, wb], rtol=1e-12)


@pytest.mark.parametrize("params", [(1.0, 0.5, 0.5, 1.0), (2.0, 1.5, -0.5, 2.0), (0.5, 0.3, 0.3, 3.0),
                                    (1.0, 1.0, 0.0, 1.5)])
def test_bouc_wen_bounded_by_analytic_bound(params):
    """|w| <= max(|w0|, (A / (alpha + beta))^(1/n)) for every input."""
    A, alpha, beta, n = params
    m = BoucWen(A, alpha, beta, n)
    rng = np.random.default_rng(1)
    wb = m.w_bound()
    for _ in range(5):
        v = np.cumsum(rng.normal(0, 2.0, 400))
        w = m.simulate(v)
        # the integration's error (< 1e-8 above) is the only slack
        assert np.abs(w).max() <= wb * (1 + 1e-9)
    # and from a state outside the band, |w| never exceeds its start
    w = m.simulate(v, initial_state=[0.0, 3 * wb])
    assert np.abs(w).max() <= 3 * wb
    lo, hi = m.output_bounds()
    assert lo == -hi and hi >= wb


def test_backlash_like_matches_solve_ivp_and_eq6_bound():
    m = BacklashLike(alpha=1.5, c=3.0, B1=1.0)
    rate = lambda w, u, s: s * 1.5 * (3.0 * u - w) + 1.0
    np.testing.assert_allclose(m.simulate(SIGNAL), path_reference(rate, SIGNAL), rtol=0, atol=1e-9)
    # eq. 6: w = c v + d(v), |d| <= (c - B1) / alpha from d(0) = 0
    v = np.cumsum(np.random.default_rng(2).normal(0, 1.0, 2000))
    d = m.simulate(v) - 3.0 * v
    assert np.abs(d).max() <= (3.0 - 1.0) / 1.5 * (1 + 1e-12)


@pytest.mark.parametrize("model", [BoucWen(1.0, 0.7, 0.3, 2.0, gain=0.3), BoucWen(1.0, 0.7, 0.3, 1.0),
                                   BacklashLike(1.0, 2.0, 0.5)])
def test_rate_independence(model):
    """Same input path, sampled 8 times more finely (or replayed at another
    rate: there is no time in the model): same outputs at the common samples."""
    v = SIGNAL
    fine = np.concatenate([np.linspace(a, b, 9)[1:] for a, b in zip(np.r_[0.0, v[:-1]], v)])
    # Bouc-Wen n = 2: RK4 error (1e-8, see above); closed forms: rounding
    tol = 1e-8 if (isinstance(model, BoucWen) and model.n != 1.0) else 1e-12
    np.testing.assert_allclose(model.simulate(fine)[7::8], model.simulate(v), rtol=0, atol=tol)


@pytest.mark.parametrize("model", [BoucWen(1.0, 0.7, 0.3, 1.7, gain=0.3, offset=1.0, sign=-1),
                                   BacklashLike(1.0, 2.0, 0.5, offset=-1.0)])
def test_chunked_and_round_trip(model):
    v = np.sin(np.linspace(0, 30, 2001)) * 4
    y, s = model.simulate(v, return_state=True)
    parts, st = [], None
    for k in range(0, v.size, 333):
        yk, st = model.simulate(v[k:k + 333], initial_state=st, return_state=True)
        parts.append(yk)
    np.testing.assert_array_equal(np.concatenate(parts), y)
    np.testing.assert_array_equal(st, s)
    back = model_from_dict(json.loads(json.dumps(model.to_dict())))
    assert back == model
    np.testing.assert_array_equal(back.simulate(v), y)


def test_invalid_parameters():
    with pytest.raises(ValueError, match="Parameter n is 0.5 but should be >= 1"):
        BoucWen(1.0, 0.5, 0.5, n=0.5)
    with pytest.raises(ValueError, match="alpha \\+ beta > 0"):
        BoucWen(1.0, 0.2, -0.4)
    with pytest.raises(ValueError, match="alpha >= beta"):
        BoucWen(1.0, 0.2, 0.4)
    with pytest.raises(ValueError, match="Parameter A is -1.0 but should be > 0"):
        BoucWen(-1.0, 0.5, 0.5)
    with pytest.raises(ValueError, match="Parameter gain"):
        BoucWen(1.0, 0.5, 0.5, gain=-1)
    with pytest.raises(ValueError, match="sign"):
        BoucWen(1.0, 0.5, 0.5, sign=2)
    with pytest.raises(ValueError, match="B1 is 3.0 but should be <= c = 2.0"):
        BacklashLike(1.0, 2.0, 3.0)
    with pytest.raises(ValueError, match="Parameter alpha is 0.0 but should be > 0"):
        BacklashLike(0.0, 2.0, 1.0)
    with pytest.raises(TypeError, match="f1"):
        Duhem(3.0, lambda w, v, p: 1.0)
    with pytest.raises(ValueError, match="max_step"):
        Duhem(lambda w, v, p: 1.0, lambda w, v, p: 1.0, max_step=0.0)
    with pytest.raises(ValueError, match=r"Parameter initial_state holds -?inf at index"):
        BoucWen(1.0, 0.5, 0.5).simulate([1.0], initial_state=[0.0, np.inf])


# ----------------------------------------------------------------------------
# Duhem with user shape functions
# ----------------------------------------------------------------------------
def f1(w, v, p):
    return p[0] * (p[1] * v - w) + p[2]


def f2(w, v, p):
    return -p[0] * (p[1] * v - w) + p[2]


def test_duhem_compiled_and_python_paths_agree_with_closed_form():
    exact = BacklashLike(1.5, 3.0, 1.0).simulate(SIGNAL)
    d = Duhem(f1, f2, params=[1.5, 3.0, 1.0], max_step=0.01)
    assert d.compiled
    # RK4 with sub-steps <= 0.01 in v on a linear ODE: error ~ (0.01 * 1.5)^4
    np.testing.assert_allclose(d.simulate(SIGNAL), exact, rtol=0, atol=1e-9)
    table = {"k": 1.5}

    def g1(w, v, p):        # a dict lookup: numba cannot compile it
        return table["k"] * (p[1] * v - w) + p[2]

    def g2(w, v, p):
        return -table["k"] * (p[1] * v - w) + p[2]

    py = Duhem(g1, g2, params=[0.0, 3.0, 1.0], max_step=0.01)
    assert not py.compiled
    np.testing.assert_allclose(py.simulate(SIGNAL), d.simulate(SIGNAL), rtol=0, atol=1e-12)
    with pytest.raises(TypeError, match="cannot be written"):
        d.to_dict()


def test_duhem_reports_divergence():
    d = Duhem(lambda w, v, p: w * w + 1.0, lambda w, v, p: 1.0, max_step=0.5)
    with pytest.raises(FloatingPointError, match="diverged at sample index"):
        d.simulate(np.linspace(0, 50, 20))


# ----------------------------------------------------------------------------
# identification: recovery of known parameters from simulated data
# ----------------------------------------------------------------------------
def test_fit_bouc_wen_recovers_parameters():
    true = BoucWen(A=1.2, alpha=0.9, beta=0.3, n=1.6, gain=0.4, offset=0.2, sign=-1)
    v = 3 * np.sin(np.linspace(0, 18, 1500)) * np.linspace(1.0, 0.5, 1500)
    res = fit_bouc_wen(v, true.simulate(v))
    m = res.model
    assert m.sign == -1 and res.n_parameters == 6
    # noiseless data: the optimum is the truth; least_squares stops at its
    # tolerances (1e-8 relative steps) -> parameters to 1e-4
    for name in ("A", "alpha", "beta", "n", "gain", "offset"):
        assert getattr(m, name) == pytest.approx(getattr(true, name), rel=1e-4, abs=1e-4), name
    assert res.rmse < 1e-6


def test_fit_backlash_like_recovers_parameters():
    true = BacklashLike(alpha=0.8, c=2.0, B1=0.6, offset=0.5)
    v = 5 * np.sin(np.linspace(0, 18, 1500))
    res = fit_backlash_like(v, true.simulate(v))
    for name in ("alpha", "c", "B1", "offset"):
        assert getattr(res.model, name) == pytest.approx(getattr(true, name), rel=1e-5), name


def test_fit_duhem_recovers_parameters():
    v = 4 * np.sin(np.linspace(0, 20, 600))
    y = BacklashLike(1.5, 3.0, 1.0).simulate(v)
    res = fit_duhem(v, y, f1, f2, [1.0, 2.0, 0.5], bounds=([1e-3, 1e-3, 0], [10, 10, 10]), max_step=0.02,
                    gain=False)
    # RK4 with max_step 0.02 vs the closed form: 1e-8 level model error
    np.testing.assert_allclose(res.model.params, [1.5, 3.0, 1.0], rtol=1e-5)


# ----------------------------------------------------------------------------
# numerical inverse
# ----------------------------------------------------------------------------
@pytest.mark.parametrize("model", [BoucWen(1.0, 0.6, 0.2, 1.5, gain=0.5), BoucWen(1.0, 0.6, 0.2, 1.0),
                                   BoucWen(0.5, 0.6, 0.2, 2.0, gain=1.5, sign=-1), BacklashLike(1.0, 2.0, 0.5),
                                   Duhem(f1, f2, params=[1.5, 3.0, 1.0], max_step=0.01)])
def test_numerical_inverse(model):
    lo, hi = model.output_bounds()
    amp = 0.8 * hi if np.isfinite(hi) else 2.0
    u = amp * np.sin(np.linspace(0, 12, 400)) * np.linspace(1, 0.3, 400)
    comp = model.exact_inverse()
    with warnings.catch_warnings():
        warnings.simplefilter("error", UnreachableWarning)
        v, st = comp.simulate(u, return_state=True)
    # bisection to 1e-12 (relative) in v: output errors below 1e-9
    assert np.abs(model.simulate(v) - u).max() < 1e-9
    np.testing.assert_allclose(st[1:], model.simulate(v, return_state=True)[1], rtol=0, atol=1e-12)
    assert comp.n_states == model.n_states + 1 and comp.default_state().shape == (comp.n_states,)


def test_numerical_inverse_unreachable_and_not_monotone():
    m = BoucWen(1.0, 0.5, 0.5, 1.0)      # saturates at |w| = 1
    comp = m.exact_inverse()
    with pytest.warns(UnreachableWarning, match="1 of 3 targets"):
        v = comp.simulate([0.5, 2.0, 0.5])
    assert abs(m.simulate(v)[1] - 1.0) < 1e-9          # clipped to the saturation
    with pytest.raises(ValueError, match="increases with the input"):
        BoucWen(1.0, 0.6, 0.2, 1.0, gain=0.5, sign=-1).exact_inverse()


# ----------------------------------------------------------------------------
# python-control blocks
# ----------------------------------------------------------------------------
iosys = pytest.importorskip("hystcomp.iosys")


@pytest.mark.parametrize("model", [BoucWen(1.0, 0.6, 0.2, 2.0, gain=0.5), BacklashLike(1.0, 2.0, 0.5)])
def test_blocks_agree_with_model(model):
    import control as ct

    t = np.arange(300) * 0.01
    v = 2 * np.sin(2 * np.pi * t)
    block = iosys.hysteresis_system(model, dt=0.01)
    resp = ct.input_output_response(block, t, v, X0=iosys.initial_state(block))
    np.testing.assert_allclose(resp.outputs, model.simulate(v), rtol=0, atol=1e-12)
    comp = iosys.compensator_system(model, dt=0.01)
    vc = ct.input_output_response(comp, t, v, X0=iosys.initial_state(comp)).outputs
    assert np.abs(model.simulate(vc) - v).max() < 1e-9


def test_bouc_wen_in_a_feedback_loop():
    loops = pytest.importorskip("hystcomp.loops")
    import control as ct

    m = BoucWen(1.0, 0.6, 0.2, 1.0, gain=0.5)
    plant = ct.tf([1.0], [0.01, 1.0])
    ctrl = iosys.pid(2.0, 50.0, 0.0, dt=0.001)
    loop = loops.build_loop("feedback", m, plant, controller=ctrl, dt=0.001)
    t = np.arange(3000) * 0.001
    resp = loop.simulate(t, np.sin(2 * np.pi * t))
    w, v = resp.outputs[1], resp.outputs[2]       # outputs y, w, v (hystcomp.loops.Loop)
    np.testing.assert_allclose(w, m.simulate(v), rtol=0, atol=1e-12)
    assert math.isfinite(float(np.abs(resp.outputs[0]).max()))

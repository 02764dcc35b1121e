"""Preisach (eq. 7) and KP (eq. 8) models: against plain relay / KP-operator
loops written from the definitions, the defining properties (wiping out,
congruent minor loops, rate independence), identification, the numerical
inverse and the python-control blocks."""

import json
import warnings

import numpy as np
import pytest

from hystcomp.identify import fit_kp, fit_preisach
from hystcomp.inverses import UnreachableWarning
from hystcomp.models import model_from_dict
from hystcomp.numerical_inverse import NumericalInverse
from hystcomp.preisach import KP, Preisach, preisach_grid


def density(a, b):
    return np.exp(-(a - b)) * (1.0 + 0.3 * a)


def make(cls, n=8, rng=None, signed=False, offset=0.0):
    if rng is None:
        return cls.from_density(density, (-1.0, 1.0), n, offset=offset)
    mu = np.tril(rng.uniform(-0.5 if signed else 0.0, 1.0, (n, n)))
    return cls((-1.0, 1.0), mu, offset)


# ----------------------------------------------------------------------------
# references written from the definitions (one Python loop per relay)
# ----------------------------------------------------------------------------
def relay_reference(model, v, relays):
    """Relays of Fig. 2.4: +1 once v >= alpha, -1 once v < beta."""
    c = model.levels
    R = relays.copy()
    out = []
    for x in v:
        for i in range(model.n):
            for j in range(i + 1):
                if x >= c[i]:
                    R[i, j] = 1.0
                elif x < c[j]:
                    R[i, j] = -1.0
        out.append(model.offset + float((R * model.weights).sum()))
    return np.array(out)


def kp_reference(model, v):
    """KP operators: k <- max(rho(v - alpha), min(rho(v - beta), k)) with the
    ramp rho(x) = clip(2x/h, -1, 1); virgin k = rho(0 - (alpha+beta)/2)."""
    c, h, n = model.levels, model.h, model.n

    def rho(x):
        return min(1.0, max(-1.0, 2.0 * x / h))

    K = np.zeros((n, n))
    for i in range(n):
        for j in range(i + 1):
            K[i, j] = rho(-0.5 * (c[i] + c[j]))
    out = []
    for x in v:
        for i in range(n):
            for j in range(i + 1):
                K[i, j] = max(rho(x - c[i]), min(rho(x - c[j]), K[i, j]))
        out.append(model.offset + float((K * model.weights).sum()))
    return np.array(out)


def test_grid_levels_and_edges():
    c, e = preisach_grid((0.0, 10.0), 5)
    assert c.tolist() == [1.0, 3.0, 5.0, 7.0, 9.0]
    assert e.tolist() == [0.0, 2.0, 4.0, 6.0, 8.0, 10.0]


@pytest.mark.parametrize("signed", [False, True])
def test_preisach_matches_relays(signed):
    rng = np.random.default_rng(1)
    m = make(Preisach, 7, rng, signed=signed, offset=0.25)
    v = rng.uniform(-1.3, 1.3, 300)
    # the demagnetised default state as relays: up iff c_i + c_j <= 0
    relays = m.relay_states(m.default_state())
    ref = relay_reference(m, v, relays)
    # same relays, different summation order: rounding only (1e-12 absolute
    # on outputs of order 10)
    np.testing.assert_allclose(m.simulate(v), ref, rtol=0, atol=1e-12)
    # from negative saturation too
    ref2 = relay_reference(m, v, m.relay_states(m.saturated_state()))
    np.testing.assert_allclose(m.simulate(v, initial_state=m.saturated_state()), ref2, rtol=0, atol=1e-12)


def test_preisach_default_state_is_demagnetised():
    m = make(Preisach, 10)
    R = m.relay_states(m.default_state())
    c = m.levels
    i, j = np.tril_indices(10)
    assert np.all((R[i, j] > 0) == (c[i] + c[j] <= 0))


def test_preisach_wiping_out():
    """After a minor loop inside [m, M] the input returns to M: every relay
    is as before the loop (the staircase state equal, output equal)."""
    m = make(Preisach, 20)
    rng = np.random.default_rng(2)
    y0, s0 = m.simulate([0.9, -0.7, 0.6], return_state=True)
    inner = rng.uniform(-0.7, 0.6, 40)
    y1, s1 = m.simulate(np.concatenate([inner, [0.6]]), initial_state=s0, return_state=True)
    np.testing.assert_array_equal(s1, s0)
    assert y1[-1] == y0[-1]
    # exceeding M wipes out the memory of the smaller maximum 0.6
    a = m.simulate([0.9, -0.7, 0.6, -0.2, 0.8])
    b = m.simulate([0.9, -0.7, 0.8])
    assert a[-1] == b[-1]


def test_preisach_congruent_minor_loops():
    """The same oscillation between v1 and v2 after two different histories
    gives loops that differ by a constant (Mayergoyz's congruency)."""
    m = make(Preisach, 25)
    cycle = np.concatenate([np.linspace(-0.2, 0.5, 30), np.linspace(0.5, -0.2, 30)] * 2)
    ya = m.simulate(np.concatenate([[1.0, -0.2], cycle]))[2:]
    yb = m.simulate(np.concatenate([[0.9, -1.0, 0.7, -0.2], cycle]))[4:]
    d = ya - yb
    assert np.ptp(d) < 1e-12          # the row sums only differ in rounding
    assert abs(d[0]) > 0.01           # and the histories did differ


def test_preisach_rate_independence_exact():
    m = make(Preisach, 15)
    rng = np.random.default_rng(3)
    v = rng.uniform(-1, 1, 60)
    fine = np.concatenate([np.linspace(a, b, 9)[1:] for a, b in zip(np.r_[0.0, v[:-1]], v)])
    np.testing.assert_array_equal(m.simulate(fine)[7::8], m.simulate(v))


@pytest.mark.parametrize("cls", [Preisach, KP])
def test_chunked_equals_one_shot(cls):
    m = make(cls, 12)
    v = np.sin(np.linspace(0, 40, 3001)) * np.linspace(1.2, 0.1, 3001)
    y, s = m.simulate(v, return_state=True)
    parts, st = [], None
    for k in range(0, v.size, 700):
        yk, st = m.simulate(v[k:k + 700], initial_state=st, return_state=True)
        parts.append(yk)
    np.testing.assert_array_equal(np.concatenate(parts), y)
    np.testing.assert_array_equal(st, s)
    assert s.shape == (m.n_states,) and s.dtype == np.float64


@pytest.mark.parametrize("cls", [Preisach, KP])
def test_round_trip_dict(cls):
    m = make(cls, 6, np.random.default_rng(4), offset=-0.5)
    back = model_from_dict(json.loads(json.dumps(m.to_dict())))
    assert back == m and type(back) is cls
    assert cls.from_dict(m.to_dict()) == m
    with pytest.raises(ValueError, match=r"lacks the key\(s\) \['input_range'\]"):
        model_from_dict({"schema_version": 1, "model": cls.__name__, "weights": [[1.0]]})


def test_output_bounds():
    m = make(Preisach, 10, offset=0.3)
    lo, hi = m.output_bounds()
    y = m.simulate(np.sin(np.linspace(0, 30, 2000)) * 2)
    assert lo <= y.min() and y.max() <= hi
    # saturated: the bound is attained
    assert abs(m.simulate([5.0])[-1] - hi) < 1e-12 and abs(m.simulate([-5.0])[-1] - lo) < 1e-12


def test_invalid_parameters():
    with pytest.raises(ValueError, match="above the diagonal"):
        Preisach((0, 1), np.ones((3, 3)))
    with pytest.raises(ValueError, match=r"square \(n, n\)"):
        KP((0, 1), np.ones((3, 2)))
    with pytest.raises(ValueError, match="v_min < v_max"):
        Preisach((1, 0), np.eye(3))
    with pytest.raises(ValueError, match="non-finite"):
        Preisach((0, 1), np.diag([1.0, np.nan]))
    m = make(Preisach, 4)
    with pytest.raises(ValueError, match="0 <= k_i <= i"):
        m.simulate([0.0], initial_state=[0, 3, 0, 0])
    with pytest.raises(ValueError, match="not a staircase"):
        m.simulate([0.0], initial_state=[1, 0, 1, 1])
    with pytest.raises(ValueError, match="4 states"):
        m.simulate([0.0], initial_state=[0, 0])
    assert not m.is_invertible()
    assert "no analytic inverse" in m.is_invertible().reasons[0]


# ----------------------------------------------------------------------------
# KP
# ----------------------------------------------------------------------------
@pytest.mark.parametrize("signed", [False, True])
def test_kp_matches_operators(signed):
    rng = np.random.default_rng(5)
    m = make(KP, 6, rng, signed=signed, offset=0.1)
    v = np.concatenate([rng.uniform(-1.3, 1.3, 150), np.sin(np.linspace(0, 9, 150))])
    # rounding only: the kernel sums per diagonal with prefix sums
    np.testing.assert_allclose(m.simulate(v), kp_reference(m, v), rtol=0, atol=1e-12)


def test_kp_continuous_and_rate_independent():
    m = make(KP, 20)
    v = np.linspace(-1, 1, 20001)
    y = m.simulate(v)
    # piecewise linear with slopes bounded by 2 sum|mu| / h: no jumps
    assert np.abs(np.diff(y)).max() <= 2 * np.abs(m.weights).sum() / m.h * (v[1] - v[0]) + 1e-12
    rng = np.random.default_rng(6)
    u = rng.uniform(-1, 1, 80)
    fine = np.concatenate([np.linspace(a, b, 7)[1:] for a, b in zip(np.r_[0.0, u[:-1]], u)])
    # the plays are exact on monotone segments; 1e-12: rounding of the sums
    np.testing.assert_allclose(m.simulate(fine)[5::6], m.simulate(u), rtol=0, atol=1e-12)


def test_kp_wiping_out():
    m = make(KP, 20)
    _, s0 = m.simulate([0.9, -0.7, 0.6], return_state=True)
    rng = np.random.default_rng(7)
    _, s1 = m.simulate(np.concatenate([rng.uniform(-0.7, 0.6, 30), [0.6]]), initial_state=s0,
                       return_state=True)
    np.testing.assert_allclose(s1, s0, rtol=0, atol=1e-15)


def test_kp_tends_to_preisach_on_fine_grids():
    """The KP ramps have the cell width: a KP model and a Preisach model of
    the same density differ by O(h) in the output."""
    errs = []
    v = np.sin(np.linspace(0, 20, 3001)) * np.linspace(1, 0.3, 3001)
    for n in (10, 40):
        errs.append(np.abs(KP.from_density(density, (-1, 1), n).simulate(v)
                           - Preisach.from_density(density, (-1, 1), n).simulate(v)).max())
    assert errs[1] < 0.5 * errs[0]


# ----------------------------------------------------------------------------
# identification
# ----------------------------------------------------------------------------
def forc_input(model):
    """First-order reversal curves on the level grid: from negative
    saturation up to edge i+1, then down through every lower edge."""
    e = model.edges
    v = []
    for i in range(model.n):
        v += [e[0] - 0.1, e[i + 1]] + list(e[i::-1])
    return np.array(v)


@pytest.mark.parametrize("cls,fitter", [(Preisach, fit_preisach), (KP, fit_kp)])
def test_fit_recovers_weights(cls, fitter):
    rng = np.random.default_rng(8)
    true = make(cls, 6, rng, offset=0.4)
    v = np.tile(forc_input(true), 2)
    if cls is KP:
        # KP responds between grid points too: add midpoints
        v = np.concatenate([np.linspace(a, b, 3)[1:] for a, b in zip(v[:-1], v[1:])])
    res = fitter(v, true.simulate(v), n=6, input_range=(-1, 1), regularization=1e-10)
    # the ridge of 1e-10 (scaled) and the solver tolerance bias the weights
    # by far less than 1e-4 of their size (about 0.5)
    np.testing.assert_allclose(res.model.weights, true.weights, rtol=0, atol=1e-4)
    assert abs(res.model.offset - 0.4) < 1e-4
    assert res.rmse < 1e-5 and res.n_parameters == 22 and res.success


def test_fit_preisach_checks_arguments():
    with pytest.raises(ValueError, match="positive integer"):
        fit_preisach([0.0, 1.0], [0.0, 1.0], n=0)
    with pytest.raises(ValueError, match="constant"):
        fit_preisach(np.zeros(5), np.zeros(5))
    with pytest.raises(ValueError, match="3 samples but v has 2"):
        fit_kp([0.0, 1.0], [0.0, 1.0, 2.0])


# ----------------------------------------------------------------------------
# numerical inverse
# ----------------------------------------------------------------------------
def test_preisach_closest_match():
    m = make(Preisach, 30)
    comp = m.exact_inverse()
    u = 0.9 * m.output_bounds()[1] * np.sin(np.linspace(0, 25, 1500)) * np.linspace(1, 0.4, 1500)
    v, st = comp.simulate(u, return_state=True)
    y = m.simulate(v)
    # closest match: the error is at most half the largest output step the
    # model can make between adjacent levels (bounded by the largest
    # 2 * (row sum + column sum) of the weights) -- and it is the best level:
    mu = m.weights
    step = 2 * (mu.sum(axis=1) + mu.sum(axis=0)).max()
    assert np.abs(y - u).max() <= 0.5 * step
    # best among the levels: no other level from the same state is closer
    s = None
    for k in range(0, 200):
        ys = [m.simulate([x], initial_state=s)[0] for x in m.edges]
        assert np.min(np.abs(np.array(ys) - u[k])) == pytest.approx(abs(y[k] - u[k]), abs=1e-14)
        _, s = m.simulate([v[k]], initial_state=s, return_state=True)
    np.testing.assert_array_equal(st[1:], m.simulate(v, return_state=True)[1])


def test_kp_inverse_and_unreachable():
    m = make(KP, 20)
    comp = m.exact_inverse()
    u = 0.9 * m.output_bounds()[1] * np.sin(np.linspace(0, 25, 1500))
    # bisection to 1e-12 in the input: the output error is below 1e-9
    assert np.abs(m.simulate(comp.simulate(u)) - u).max() < 1e-9
    with pytest.warns(UnreachableWarning, match="first at sample index 1"):
        comp.simulate([0.0, 10.0])
    with pytest.raises(ValueError, match="outside the outputs"):
        NumericalInverse(m, on_unreachable="raise").simulate([0.0, 10.0])
    with pytest.raises(ValueError, match="non-negative weights"):
        make(KP, 5, np.random.default_rng(0), signed=True).exact_inverse()


# ----------------------------------------------------------------------------
# python-control blocks and loops (hystcomp.iosys, hystcomp.loops)
# ----------------------------------------------------------------------------
iosys = pytest.importorskip("hystcomp.iosys")


@pytest.mark.parametrize("cls", [Preisach, KP])
def test_hysteresis_block_agrees_with_model(cls):
    import control as ct

    m = make(cls, 10)
    block = iosys.hysteresis_system(m, dt=0.01)
    t = np.arange(400) * 0.01
    v = np.sin(2 * np.pi * t) * np.linspace(1.1, 0.2, t.size)
    resp = ct.input_output_response(block, t, v, X0=iosys.initial_state(block))
    np.testing.assert_allclose(resp.outputs, m.simulate(v), rtol=0, atol=1e-12)


def test_compensator_block_kp():
    import control as ct

    m = make(KP, 15)
    block = iosys.compensator_system(m, dt=0.01)
    t = np.arange(300) * 0.01
    u = 0.8 * m.output_bounds()[1] * np.sin(2 * np.pi * t)
    with warnings.catch_warnings():
        warnings.simplefilter("error", UnreachableWarning)
        v = ct.input_output_response(block, t, u, X0=iosys.initial_state(block)).outputs
    assert np.abs(m.simulate(v) - u).max() < 1e-9


def test_preisach_in_a_loop():
    loops = pytest.importorskip("hystcomp.loops")
    import control as ct

    m = make(Preisach, 20)
    plant = ct.tf([1.0], [0.01, 1.0])
    loop = loops.build_loop("open_loop", m, plant, dt=0.001)
    t = np.arange(2000) * 0.001
    r = np.sin(2 * np.pi * t)
    resp = loop.simulate(t, r)
    # Loop.system's outputs are y, w, v in this order (hystcomp.loops.Loop)
    w, v = resp.outputs[1], resp.outputs[2]
    # the actuator output in the loop is the model's response to its input
    np.testing.assert_allclose(w, m.simulate(v), rtol=0, atol=1e-12)


def test_fit_large_plane():
    """25 x 25 cells (325 > 300 weights: the constant-data cvxpy problem
    instead of the parametrised one, which would not fit in memory at
    50 x 50)."""
    true = Preisach.from_density(density, (-1.0, 1.0), 25, offset=0.1)
    v = forc_input(true)
    res = fit_preisach(v, true.simulate(v), n=25, input_range=(-1, 1), regularization=1e-10)
    # FORC input excites every relay; the ridge and solver tolerance leave
    # errors below 1e-4 of the largest weight
    assert res.success and res.rmse < 1e-5
    np.testing.assert_allclose(res.model.weights, true.weights, rtol=0, atol=1e-4 * true.weights.max())

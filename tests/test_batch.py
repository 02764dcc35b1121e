"""Batch simulation: 2-D inputs and batches of weights (issue 13 point 4)."""

import numpy as np
import pytest

from hystcomp import GPI, MGPI, PI, StopPI
from hystcomp.envelopes import Polynomial, Tanh

R = 0.5 * np.arange(1, 9)
P = np.exp(-0.2 * R) * 0.5


def _models():
    return [
        PI(R, P, p0=1.0),
        MGPI(R, P, p0=1.0, envelope=Tanh(10.0, 0.2)),
        MGPI(R, P, p0=1.0, envelope_left=Tanh(10.0, 0.2), envelope_right=Tanh(10.0, 0.1)),
        StopPI(R, P, p0=1.0),
        GPI(R, P, Tanh(10.0, 0.2), Tanh(10.0, 0.1), H=Tanh(10.0, 0.2)),
    ]


def _input(n=3000, seed=1):
    rng = np.random.default_rng(seed)
    t = np.linspace(0, 12, n)
    return 4 * np.sin(t) * (1 + 0.5 * np.sin(0.3 * t)) + 0.05 * rng.standard_normal(n)


@pytest.mark.parametrize("model", _models(), ids=lambda m: type(m).__name__)
def test_2d_input_equals_columns(model):
    V = np.column_stack([_input(seed=s) for s in range(3)])
    Y, S = model.simulate(V, return_state=True)
    assert Y.shape == V.shape and S.shape == (3, model.n_states)
    for j in range(3):
        y, s = model.simulate(V[:, j], return_state=True)
        # same kernel on the same column: bit for bit
        assert np.array_equal(Y[:, j], y)
        assert np.array_equal(S[j], s)
    # initial states per column continue each signal
    Y2 = model.simulate(V, initial_state=S)
    assert np.array_equal(Y2[:, 1], model.simulate(V[:, 1], initial_state=S[1]))


def test_2d_input_bad_state_shape():
    m = PI(R, P, p0=1.0)
    with pytest.raises(ValueError, match="initial_state has shape"):
        m.simulate(np.zeros((10, 2)), initial_state=np.zeros((3, R.size)))
    with pytest.raises(ValueError, match=r"v\[:, 1\]"):
        m.simulate(np.column_stack([np.zeros(4), [0, np.nan, 0, 0]]))


@pytest.mark.parametrize("model", _models(), ids=lambda m: type(m).__name__)
def test_batch_matches_loop(model):
    rng = np.random.default_rng(7)
    W = rng.uniform(0.0, 1.0, (6, R.size))
    v = _input()
    has_p0 = hasattr(model, "p0")
    p0 = rng.uniform(0.5, 1.5, 6) if has_p0 else None
    Y = model.simulate_batch(v, W, p0=p0)
    assert Y.shape == (v.size, 6)
    for j in range(6):
        d = model.to_dict()
        d["weights"] = W[j].tolist()
        if has_p0:
            d["p0"] = float(p0[j])
        from hystcomp.models import model_from_dict
        y = model_from_dict(d).simulate(v)
        # the batch sums the operators in a different order (BLAS): rounding
        # only, a few ulp of the output span
        assert np.max(np.abs(Y[:, j] - y)) <= 1e-13 * np.ptp(y)


def test_batch_state_and_chunks():
    m = MGPI(R, P, p0=1.0, envelope=Tanh(10.0, 0.2))
    W = np.vstack([P, 2 * P])
    v = _input(10000)
    Y, s = m.simulate_batch(v, W, return_state=True)
    Y1, s1 = m.simulate_batch(v[:4321], W, return_state=True)
    Y2 = m.simulate_batch(v[4321:], W, initial_state=s1)
    assert np.max(np.abs(np.vstack([Y1, Y2]) - Y)) <= 1e-13 * np.ptp(Y)
    assert np.array_equal(s, m.simulate(v, return_state=True)[1])


def test_batch_custom_free_polynomial_envelope():
    m = MGPI(R, P, p0=1.0, envelope=Polynomial([0.0, 1.0, 0.0, 0.01], interval=(-20, 20)))
    v = _input()
    Y = m.simulate_batch(v, P[None, :])
    assert np.max(np.abs(Y[:, 0] - m.simulate(v))) <= 1e-13 * np.ptp(Y)


def test_batch_errors():
    m = PI(R, P, p0=1.0)
    v = _input(100)
    with pytest.raises(ValueError, match="weights has shape"):
        m.simulate_batch(v, np.ones((3, R.size + 1)))
    with pytest.raises(ValueError, match="weights holds NaN"):
        m.simulate_batch(v, np.full((2, R.size), np.nan))
    with pytest.raises(ValueError, match="p0 has shape"):
        m.simulate_batch(v, np.ones((3, R.size)), p0=[1.0, 2.0])
    g = GPI(R, P, Tanh(10.0, 0.2), Tanh(10.0, 0.1))
    with pytest.raises(ValueError, match="has no p0"):
        g.simulate_batch(v, np.ones((1, R.size)), p0=1.0)

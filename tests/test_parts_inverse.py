"""Compensating what diagnose finds (issue 11 point 5): the causal inverse of a diagnosed
model (PartsModel.exact_inverse), checked against the model itself and, for hidden creep,
against the TRUE system that made the record (not the model)."""

import numpy as np
import pytest

from hystcomp.datasets import hidden_effect_data
from hystcomp.diagnose import diagnose
from hystcomp.identify import fit_weights
from hystcomp.identify.parts import Context, Delay, GainDrift, InputLag, OutputLag, OutputResonance, SlewLimit
from hystcomp.identify.search import PartsModel, Structure, VariableProjection

DT = 0.01


def _true_response(seed, v, amplitude):
    """hidden_effect_data's true creep system on the input v.  Its actuator's thresholds
    scale with max|v|, so one extra sample at the identification amplitude keeps the same
    actuator; the system is causal, so that sample is dropped."""
    vv = np.append(v, amplitude)
    t = np.arange(vv.size) * DT
    return hidden_effect_data("creep", seed=seed, dt=DT, experiment=(t, vv)).clean[:-1]


@pytest.mark.parametrize("seed", [0, 1])
def test_compensator_of_the_diagnosed_model_beats_the_plain_pi_fit_3x(seed):
    d = hidden_effect_data("creep", seed=seed, dt=DT)
    A = float(np.max(np.abs(d.v)))
    rep = diagnose(d.t, d.v, d.y, progress=False)
    assert "creep" in rep.effects
    plain = fit_weights(d.v, d.y)
    # a staircase with 2 s holds over 10 ... 90 % of the measured output range
    lo, hi = np.percentile(d.y, [10, 90])
    levels = [0.5 * (lo + hi)] + [lo + (hi - lo) * f for f in (0.9, 0.2, 0.7, 0.1, 0.8, 0.35, 0.6)]
    r = np.repeat(levels, 200)
    v_diag = rep.model.exact_inverse(input_limits=(-A, A)).simulate(r)
    v_plain = np.clip(plain.model.exact_inverse().simulate(r - plain.offset), -A, A)
    # the compensator inverts its model (to the bisection's resolution, 1e-9 of the input span)
    assert np.max(np.abs(rep.model.simulate(v_diag) - r)) < 1e-6 * np.ptp(d.y)
    e_diag = np.sqrt(np.mean((_true_response(seed, v_diag, A) - r) ** 2))
    e_plain = np.sqrt(np.mean((_true_response(seed, v_plain, A) - r) ** 2))
    # measured 13.3x (seed 0) and 3.6x (seed 1); the issue asks at least 3x
    assert e_plain >= 3.0 * e_diag, (e_plain, e_diag)


@pytest.mark.parametrize("effect", ["drift", "saturation", "asymmetry"])
def test_inverse_follows_the_diagnosed_model(effect):
    d = hidden_effect_data(effect, seed=4, dt=DT)
    rep = diagnose(d.t, d.v, d.y, progress=False)
    # a reachable reference: the model's own output for a slower, smaller input
    n = 600
    u = 0.7 * np.max(np.abs(d.v)) * np.sin(np.linspace(0, 4 * np.pi, n)) * np.linspace(1, 0.5, n)
    r = rep.model.simulate(np.concatenate([u, np.zeros(d.v.size - n)]))[:n]
    v = rep.model.exact_inverse().simulate(r)
    y = rep.model.simulate(np.concatenate([v, np.zeros(d.v.size - n)]))[:n]
    # the model's output equals the reference to the input resolution times the slope
    assert np.max(np.abs(y - r)) < 1e-6 * np.ptp(d.y), rep.effects


def _model_with(parts, values, y_of_v, n=400):
    """A PartsModel of the given parts and nonlinear values, weights fitted to y_of_v(v)."""
    v = np.sin(np.linspace(0, 20, n)) * np.linspace(1.0, 0.4, n)
    ctx = Context(v, 0.01, 0.0, 1.0, n * 0.01, n_thresholds=6)
    st = Structure(list(parts))
    pt = VariableProjection(ctx, y_of_v(v), np.arange(n) < 3 * n // 4).evaluate(st, values)
    return PartsModel(st, pt.values, pt.theta, ctx, pt.names), v


@pytest.mark.parametrize("part,word", [(Delay(), "dead time"), (OutputResonance(), "unstable"),
                                       (SlewLimit(), "out of reach")])
def test_parts_without_a_causal_inverse_are_named(part, word):
    ctx = Context(np.zeros(4), 0.01, 0.0, 1.0, 4.0)
    values = {part.kind: {p.name: p.initial for p in part.parameters(ctx, {part.kind})}}
    model, _ = _model_with([part], values, lambda v: 2 * v)
    with pytest.raises(ValueError, match=f"{part.kind}.*{word}"):
        model.exact_inverse()


@pytest.mark.parametrize("parts,values", [
    ([InputLag()], {"input_lag": {"time_constant": 0.05}}),
    ([OutputLag()], {"output_lag": {"time_constant": 0.05}}),
    ([OutputLag(), GainDrift()], {"output_lag": {"time_constant": 0.02},
                                  "gain_drift": {"g": 0.3, "time_constant": 1.0}}),
], ids=["lag_before", "lag_after", "lag_after_and_gain_drift"])
def test_rate_dependent_models_are_inverted_with_their_lag_states(parts, values):
    """Lags before and after the hysteresis (the diagnosis's rate dependence) have a direct
    feedthrough, so the compensator inverts them sample by sample: the model driven by the
    compensator's output follows a reachable reference (the model's own output for another
    input, so every sample is reachable)."""
    from hystcomp.models import PI

    actuator = PI([0.3, 0.6], [0.5, 0.3], 1.0)
    model, v = _model_with(parts, values, lambda v: actuator.simulate(v) + 0.01 * v ** 3)
    assert set(model.structure.kinds) >= {p.kind for p in parts}
    u = 0.8 * np.sin(np.linspace(0, 9, v.size) + 0.3) * np.linspace(0.9, 0.3, v.size)
    r = model.simulate(u)
    w = model.exact_inverse().simulate(r)
    # the compensator reproduces the model's output to the solve's resolution (1e-9 of the
    # input span) times the largest slope through the lead of the lag: 1e-6 of the span is
    # three orders above that and four below any misfit the inverse could hide
    assert np.max(np.abs(model.simulate(w) - r)) < 1e-6 * np.ptp(r)
    # and it is not the trivial answer: the input it finds is the one that made r
    assert np.max(np.abs(w - u)) < 1e-4 * np.ptp(u)


def test_bad_input_limits():
    v = np.sin(np.linspace(0, 20, 400))
    ctx = Context(v, None, 0.0, 1.0, None, n_thresholds=6)
    pt = VariableProjection(ctx, 2 * v, np.arange(400) < 300).evaluate(Structure(), {})
    model = PartsModel(Structure(), pt.values, pt.theta, ctx, pt.names)
    with pytest.raises(ValueError, match="input_limits"):
        model.exact_inverse(input_limits=(1.0, -1.0))
    with pytest.raises(TypeError, match="input_limits"):
        model.exact_inverse(input_limits=3.0)

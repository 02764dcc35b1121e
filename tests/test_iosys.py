"""hystcomp.iosys: blocks equal models, plant/PID helpers, wiring errors."""

import warnings

import control as ct
import numpy as np
import pytest

from hystcomp import GPI, MGPI, PI, StopPI
from hystcomp.envelopes import Atanh, Linear, Tanh
from hystcomp.iosys import (
    WiringError, check_wiring, compensator_system, discretize, hysteresis_system, initial_state,
    interconnect, mean_gain, pid, piezo_stage,
)

DT = 1e-3
R = 0.5 * np.arange(1, 9)
DENS = np.exp(-0.1 * R) * 0.5


def _models():
    return {
        "PI": PI(R, DENS, p0=1.0),
        "GPI": GPI(R, DENS, Tanh(10.0, 0.2), Tanh(10.0, 0.1), H=Tanh(10.0, 0.2)),
        "MGPI sym": MGPI(R, DENS, 1.0, envelope=Tanh(10.0, 0.2)),
        "MGPI asym": MGPI(R, DENS, 1.0, envelope_left=Tanh(10.0, 0.2), envelope_right=Tanh(10.0, 0.1)),
        "StopPI": StopPI(R, DENS, p0=1.0),
    }


def _input(n=400):
    t = np.arange(n) * DT
    return t, 4.0 * np.sin(2 * np.pi * 3 * t) * (1 + t) + 0.5 * np.sin(2 * np.pi * 17 * t)


def _response(sys, t, u, x0=None):
    x0 = initial_state(sys) if x0 is None else x0
    return np.asarray(ct.input_output_response(sys, t, u, X0=x0).outputs).reshape(-1)


# 1e-12 is the bound; the fast paths run the same kernel with the
# same arguments as simulate, and the generic path calls simulate itself, so
# in practice the difference is exactly 0.
@pytest.mark.parametrize("name", list(_models()))
def test_block_equals_model(name):
    model = _models()[name]
    t, v = _input()
    block = hysteresis_system(model, dt=DT)
    assert np.max(np.abs(_response(block, t, v) - model.simulate(v))) <= 1e-12


@pytest.mark.parametrize("name", ["PI", "MGPI sym", "StopPI"])
def test_block_chunked_equals_model(name):
    # two python-control runs, the second from the first's final state
    model = _models()[name]
    t, v = _input()
    block = hysteresis_system(model, dt=DT)
    r1 = ct.input_output_response(block, t[:150], v[:150], X0=initial_state(block))
    # state after sample 149 = the model's state after v[:150]
    _, s150 = model.simulate(v[:150], return_state=True)
    x_last = block._rhs(t[149], r1.states[:, -1], v[149:150])
    assert np.array_equal(block.to_model_state(x_last), s150)
    y2 = _response(block, t[150:], v[150:], x0=x_last)
    assert np.max(np.abs(np.concatenate([r1.outputs, y2]) - model.simulate(v))) <= 1e-12


def _inverse_cases():
    m = _models()
    pi_lin = MGPI(R, DENS, 1.0, envelope=Linear(2.0))
    atanh = MGPI(0.025 * np.arange(1, 21), np.exp(-0.1 * 0.025 * np.arange(1, 21)) * 0.025, 1.0,
                 envelope=Atanh(1.0, 0.5))
    gpi_sym = GPI([0.5, 1.0], [0.4, 0.2], Tanh(2, 0.5), Tanh(2, 0.5), H=Tanh(2, 0.5))
    return {
        "PI exact": (m["PI"], "exact", 3.0),
        "PI analytic": (m["PI"], "analytic", 3.0),
        "MGPI linear analytic": (pi_lin, "analytic", 3.0),
        "MGPI atanh analytic": (atanh, "analytic", 0.3),
        "MGPI sym exact": (m["MGPI sym"], "exact", 3.0),
        "MGPI asym exact": (m["MGPI asym"], "exact", 3.0),
        "StopPI exact": (m["StopPI"], "exact", 3.0),
        "GPI exact": (m["GPI"], "exact", 3.0),
        "GPI analytic": (gpi_sym, "analytic", 1.0),
    }


@pytest.mark.parametrize("name", list(_inverse_cases()))
def test_compensator_block_equals_inverse(name):
    model, method, amp = _inverse_cases()[name]
    t = np.arange(300) * DT
    u = amp * np.sin(2 * np.pi * 4 * t) * (1 + 2 * t)
    comp = model.exact_inverse() if method == "exact" else model.inverse()
    block = compensator_system(model, method=method, dt=DT)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        expected = comp.simulate(u)
    # 1e-12: same kernel, same arguments (fast paths) or simulate itself
    assert np.max(np.abs(_response(block, t, u) - expected)) <= 1e-12


def test_nominal_gain_scales_the_compensated_actuator():
    model = _models()["MGPI sym"]
    t = np.arange(300) * DT
    u = np.sin(2 * np.pi * 4 * t)
    block = compensator_system(model, nominal_gain=2.5, dt=DT)
    v = _response(block, t, u)
    # the exact inverse solves to ~1e-14 relative: model(v) = 2.5 u
    assert np.max(np.abs(model.simulate(v) - 2.5 * u)) < 1e-10
    auto = compensator_system(model, nominal_gain="auto", input_range=(-2.0, 2.0))
    assert auto.nominal_gain == pytest.approx(mean_gain(model, (-2.0, 2.0)), rel=0, abs=0)
    with pytest.raises(ValueError, match="input_range"):
        compensator_system(model, nominal_gain="auto")
    with pytest.raises(ValueError, match="nominal_gain"):
        compensator_system(model, nominal_gain=-1.0)


def test_mean_gain_of_pi_major_loop():
    # PI with p0 = 1 and one play of width r = 1, weight 1, over [-2, 2]: on
    # the rising branch w = v + (v - 1) above v = -2 + 2 = 0 ... the chord is
    # (w(2) - w(-2)) / 4 = (3 - (-3)) / 4 = 1.5
    assert mean_gain(PI([1.0], [1.0], p0=1.0), (-2.0, 2.0)) == pytest.approx(1.5, abs=1e-12)
    with pytest.raises(ValueError, match="input_range"):
        mean_gain(PI([1.0], [1.0], p0=1.0), (2.0, -2.0))


def test_output_function_is_pure():
    model = _models()["MGPI sym"]
    block = hysteresis_system(model, dt=DT)
    x = np.zeros(model.n_states)
    y1 = block._out(0.0, x, [3.0])
    y2 = block._out(0.0, x, [3.0])
    assert np.array_equal(y1, y2) and np.array_equal(x, np.zeros(model.n_states))


def test_params_hold_gains_not_models():
    # two blocks in one interconnection keep their own models; params hold
    # only the actuator gain (python-control merges the params of all blocks)
    a = hysteresis_system(PI([1.0], [1.0], p0=1.0), name="a", inputs="v", outputs="w1")
    b = hysteresis_system(PI([1.0], [3.0], p0=2.0), name="b", inputs="w1", outputs="w2")
    sys = interconnect([a, b], inplist=["v"], outlist=["w2"])
    t, v = _input(100)
    expected = PI([1.0], [3.0], p0=2.0).simulate(PI([1.0], [1.0], p0=1.0).simulate(v))
    assert np.max(np.abs(_response(sys, t, v) - expected)) <= 1e-12
    assert a.params == {"actuator_gain": 1.0} and b.params == {"actuator_gain": 1.0}
    assert sys.params == {"actuator_gain": 1.0}


def test_virgin_state_is_x0_zero():
    # Tanh(10, 0.2, 0.05) does not pass through 0: the virgin plays sit at
    # gamma^-1(0) = -0.25, and before the blocks took the virgin state as
    # their origin, input_output_response without X0 started from plays at
    # 0 and was off by 1.6 here (1.15 in the case)
    model = MGPI(R, DENS, 1.0, envelope=Tanh(10.0, 0.2, 0.05))
    assert np.all(model.default_state() == -0.25)
    t, v = _input()
    old_way = model.simulate(v, initial_state=np.zeros(model.n_states))
    assert np.max(np.abs(old_way - model.simulate(v))) > 1.0           # the offset the fix removes
    for block in (hysteresis_system(model, dt=DT), hysteresis_system(model, dt=DT).copy("b2")):
        y = np.asarray(ct.input_output_response(block, t, v).outputs)
        # (z - 0.25) + 0.25 rounds: 1e-12 on outputs of size ~10
        assert np.max(np.abs(y - model.simulate(v))) <= 1e-12
        assert np.array_equal(initial_state(block), np.zeros(model.n_states))
    comp = compensator_system(model, dt=DT)
    u = 2.0 * np.sin(2 * np.pi * 4 * t)
    vc = np.asarray(ct.input_output_response(comp, t, u).outputs).reshape(-1)
    # exact inverse solves to ~1e-14 relative
    assert np.max(np.abs(model.simulate(vc) - u)) <= 1e-10
    # states convert both ways; the chunked run continues where the first stopped
    block = hysteresis_system(model, dt=DT)
    r1 = ct.input_output_response(block, t[:150], v[:150])
    _, s150 = model.simulate(v[:150], return_state=True)
    x150 = block._rhs(t[149], r1.states[:, -1], v[149:150])
    np.testing.assert_allclose(block.to_model_state(x150), s150, rtol=0, atol=1e-12)
    np.testing.assert_allclose(block.from_model_state(s150), x150, rtol=0, atol=1e-12)
    y2 = np.asarray(ct.input_output_response(block, t[150:], v[150:], x150).outputs)
    assert np.max(np.abs(np.concatenate([r1.outputs, y2]) - model.simulate(v))) <= 1e-12


def test_named_states_and_documented_attributes():
    m = _models()
    assert hysteresis_system(m["PI"]).state_labels == [f"play[{i}]" for i in range(R.size)]
    assert hysteresis_system(m["MGPI asym"]).state_labels == [f"operator[{i}]" for i in range(R.size + 1)]
    assert hysteresis_system(m["StopPI"]).state_labels[-2:] == [f"stop[{R.size - 1}]", "input_prev"]
    block = hysteresis_system(m["MGPI sym"], name="act")
    assert block.model is m["MGPI sym"] and isinstance(block, ct.NonlinearIOSystem)
    comp = compensator_system(m["PI"], nominal_gain=2.0)
    assert comp.state_labels[0] == "command_prev" and comp.state_labels[1] == "model_play[0]"
    assert comp.model is m["PI"] and comp.method == "exact" and comp.nominal_gain == 2.0
    for attr, value in (("model", None), ("compensator", None), ("nominal_gain", 3.0)):
        with pytest.raises(AttributeError):
            setattr(comp, attr, value)
    with pytest.raises(AttributeError):
        block.model = None
    assert not hasattr(block, "_hystcomp") and not hasattr(comp, "_hystcomp")


def test_params_sweep_actuator_and_nominal_gain():
    model = _models()["MGPI sym"]
    t, v = _input(300)
    block = hysteresis_system(model, dt=DT)
    w = model.simulate(v)
    for k in (0.8, 1.0, 1.25):
        y = np.asarray(ct.input_output_response(block, t, v, params={"actuator_gain": k}).outputs)
        assert np.max(np.abs(y - k * w)) <= 1e-12        # one product per sample
    # the default comes back after a sweep (python-control keeps params per call)
    assert np.max(np.abs(np.asarray(ct.input_output_response(block, t, v).outputs) - w)) <= 1e-12
    assert hysteresis_system(model, actuator_gain=0.5).params == {"actuator_gain": 0.5}
    comp = compensator_system(model, dt=DT)
    u = np.sin(2 * np.pi * 4 * t)
    for k in (1.5, 2.5):
        vc = np.asarray(ct.input_output_response(comp, t, u, params={"nominal_gain": k}).outputs).reshape(-1)
        assert np.max(np.abs(model.simulate(vc) - k * u)) < 1e-10   # the inverse solves to ~1e-14 rel.
    with pytest.raises(ValueError, match=r"params\['actuator_gain'\] is nan"):
        ct.input_output_response(block, t, v, params={"actuator_gain": float("nan")})
    with pytest.raises(ValueError, match=r"params\['nominal_gain'\] is -1"):
        ct.input_output_response(comp, t, u, params={"nominal_gain": -1})
    with pytest.raises(ValueError, match="actuator_gain"):
        hysteresis_system(model, actuator_gain="big")


def test_piezo_stage_and_discretize():
    g = piezo_stage(gain=2.0, natural_freq_hz=300.0, damping=0.05)
    assert float(ct.dcgain(g)) == pytest.approx(2.0, rel=1e-12)
    wn = 2 * np.pi * 300.0
    poles = np.sort_complex(g.poles())
    assert np.allclose(np.abs(poles), wn, rtol=1e-12)
    assert np.allclose(-poles.real / np.abs(poles), 0.05, rtol=1e-12)
    d = discretize(g, 1e-4)
    assert d.dt == 1e-4 and d.input_labels == ["w"] and d.output_labels == ["y"]
    assert np.allclose(np.abs(d.poles()), np.exp(-0.05 * wn * 1e-4), rtol=1e-12)
    assert np.all(d.D == 0)
    assert d.state_labels == ["position", "velocity"] and d.name == "stage"
    # zero-order hold: A_d = expm(A dt), B_d = int_0^dt expm(A s) ds B (van Loan's block exponential)
    from scipy.linalg import expm
    M = expm(np.block([[g.A, g.B], [np.zeros((1, 3))]]) * 1e-4)
    np.testing.assert_allclose(d.A, M[:2, :2], rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(d.B, M[:2, 2:], rtol=1e-12, atol=1e-12 * np.abs(M[:2, 2:]).max())
    with pytest.raises(WiringError, match="already discrete"):
        discretize(d, 2e-4)


def test_pid_matches_its_equations_and_limits():
    dt = 1e-3
    kp, ki, kd, tau = 0.5, 20.0, 0.01, 5e-3
    c = pid(kp, ki, kd, dt, tau_d=tau)
    t = np.arange(200) * dt
    e = np.sin(2 * np.pi * 5 * t)
    u = _response(c, t, e)
    a = np.exp(-dt / tau)
    integ, f = 0.0, 0.0
    ref = []
    for ek in e:
        ref.append(kp * ek + ki * (integ + dt * ek) + kd * (ek - f) / tau)
        integ += dt * ek
        f = a * f + (1 - a) * ek
    # two orderings of the same few products: rounding only
    assert np.max(np.abs(u - ref)) < 1e-12
    lim = pid(kp, ki, kd, dt, tau_d=tau, output_limits=(-0.3, 0.3))
    ul = _response(lim, t, 2 * np.ones_like(t))
    assert ul.max() <= 0.3 and ul.min() >= -0.3
    # anti-windup: the integral stops while saturated, so after the error
    # flips the output leaves the upper limit at once
    e2 = np.concatenate([np.ones(100), -np.ones(100)])
    resp = ct.input_output_response(lim, t, e2)
    assert resp.states[0, 100] <= resp.states[0, 20] + 1e-15
    assert np.asarray(resp.outputs).reshape(-1)[101] < 0.3
    with pytest.raises(ValueError, match="output_limits"):
        pid(1, 1, 0, dt, output_limits=(1.0, -1.0))


# ---------------------------------------------------------------------------
# wiring errors
# ---------------------------------------------------------------------------
def _blocks(dt=1e-4):
    act = hysteresis_system(PI([1.0], [1.0], p0=1.0), name="actuator")
    err = ct.summing_junction(["r", "-y"], "e", name="error")
    ctrl = pid(0.0, 10.0, 0.0, dt, inputs="e", outputs="v", name="ctrl")
    return act, err, ctrl


def test_timebase_mismatch_continuous_plant():
    act, err, ctrl = _blocks()
    with pytest.raises(WiringError, match=r"\['plant'\] are continuous.*discretize"):
        check_wiring([act, err, ctrl, piezo_stage(name="plant")], ["r"], ["y"])


def test_timebase_mismatch_two_rates():
    act, err, ctrl = _blocks()
    with pytest.raises(WiringError, match=r"\['plant'\] have dt = 0.0002"):
        check_wiring([act, err, ctrl, piezo_stage(name="plant", dt=2e-4)], ["r"], ["y"])


def test_algebraic_loop_is_named():
    act, err, ctrl = _blocks()
    static = ct.ss([], [], [], [[1.0]], 1e-4, inputs="w", outputs="y", name="static_plant")
    with pytest.raises(WiringError, match="algebraic loop.*'actuator'.*'static_plant'"):
        check_wiring([act, err, ctrl, static], ["r"], ["y"])


def test_unknown_signal_names():
    act, err, ctrl = _blocks()
    plant = piezo_stage(name="plant", dt=1e-4)
    with pytest.raises(WiringError, match="external input 'ref'"):
        check_wiring([act, err, ctrl, plant], ["ref"], ["y"])
    with pytest.raises(WiringError, match="output 'pos' is not a signal"):
        check_wiring([act, err, ctrl, plant], ["r"], ["pos"])
    bad = piezo_stage(name="plant", dt=1e-4, inputs="force")
    with pytest.raises(WiringError, match="input 'force' of block 'plant'"):
        check_wiring([act, err, ctrl, bad], ["r"], ["y"])
    check_wiring([act, err, ctrl, plant], ["r"], ["y"])  # the right wiring passes
    sys = interconnect([act, err, ctrl, plant], inplist=["r"], outlist=["y"])
    assert sys.dt == 1e-4


def test_bad_arguments_name_themselves():
    with pytest.raises(ValueError, match="method"):
        compensator_system(PI([1.0], [1.0], p0=1.0), method="magic")
    with pytest.raises(TypeError, match="model"):
        hysteresis_system(object())
    with pytest.raises(ValueError, match="natural_freq_hz"):
        piezo_stage(natural_freq_hz=-3)


@pytest.mark.parametrize("f,zeta,dt", [(20.0, 0.1, 1e-3), (300.0, 0.05, 1e-4), (450.0, 0.7, 1e-3)])
def test_linear_stage_resonance_is_the_prewarped_bilinear_rule(f, zeta, dt):
    # LinearStage.resonance goes through ct.sample_system(..., "bilinear"): the
    # same matrices as the bilinear rule written out (Tustin with the mode
    # prewarped to sit at f), to 1e-12 relative
    from hystcomp.effects import LinearStage

    w = 2.0 / dt * np.tan(np.pi * f * dt)
    A = np.array([[0.0, 1.0], [-w * w, -2 * zeta * w]])
    M = np.linalg.inv(np.eye(2) - 0.5 * dt * A)
    Ad, Bd = M @ (np.eye(2) + 0.5 * dt * A), M @ (dt * np.array([0.0, w * w]))
    Cd = np.array([1.0, 0.0]) @ M
    st = LinearStage.resonance(f, zeta, dt)
    for got, want in ((st.A, Ad), (st.B, Bd), (st.C, Cd), (st.D, 0.5 * Cd @ np.array([0.0, w * w]) * dt)):
        np.testing.assert_allclose(got, want, rtol=0, atol=1e-12 * max(1.0, np.abs(want).max()))

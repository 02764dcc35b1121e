"""fast_response: any discrete interconnection compiled, equal to control.input_output_response."""

import numpy as np
import pytest

import control as ct

from hystcomp import MGPI, PI, StopPI
from hystcomp.demo import demo_actuator
from hystcomp.envelopes import Tanh
from hystcomp.iosys import (compensator_system, hysteresis_system, initial_state, interconnect, pid,
                            piezo_stage)
from hystcomp.loops import build_scenarios, fast_response

DT = 1e-4
T = np.arange(1200) * DT
R = 1.8 * np.sin(2 * np.pi * 25 * T)


def _same(sys, r=R, x0=None):
    x0 = initial_state(sys) if x0 is None else x0
    fast = fast_response(sys, T, r, x0)
    slow = ct.input_output_response(sys, T, r, x0)
    # python-control iterates its signals to a fixed point and sums in another order:
    # equal to rounding, 1e-12 of the signals' size
    scale = max(1.0, np.abs(slow.outputs).max())
    np.testing.assert_allclose(fast.outputs, slow.outputs, rtol=0, atol=1e-12 * scale)
    np.testing.assert_allclose(fast.states, slow.states, rtol=0, atol=1e-12 * max(1.0, np.abs(slow.states).max()))
    assert fast.output_labels == slow.output_labels and fast.states.shape == slow.states.shape
    return fast


def test_nested_user_loop_with_transfer_function_controller():
    act = demo_actuator()
    h = hysteresis_system(act, dt=DT, name="act", inputs="v", outputs="w")
    comp = compensator_system(act, nominal_gain="auto", input_range=(-2, 2), dt=DT, name="comp", inputs="u",
                              outputs="v")
    ctrl = ct.ss(ct.sample_system(ct.tf([0.05, 40.0], [1, 0]), DT), inputs="e", outputs="u", name="ctrl")
    err = ct.summing_junction(["r", "-y"], "e", name="err")
    inner = ct.interconnect([h, piezo_stage(dt=DT, inputs="w", outputs="y")], inplist="v", outlist="y",
                            name="plant", inputs="v", outputs="y")
    _same(ct.interconnect([err, ctrl, comp, inner], inplist="r", outlist="y", name="user"))


@pytest.mark.parametrize("model", [
    PI([0.5, 1.0, 1.5], [0.3, 0.2, 0.1], p0=1.0),
    StopPI([0.5, 1.0], [0.3, 0.2], p0=1.0),
    MGPI([0.5, 1.0], [0.3, 0.2], 1.0, envelope_left=Tanh(10.0, 0.2), envelope_right=Tanh(12.0, 0.15)),
], ids=["pi", "stop", "mgpi_asym"])
def test_saturated_pid_feedforward_and_exact_inverse(model):
    h = hysteresis_system(model, dt=DT, name="act", inputs="v", outputs="w")
    comp = compensator_system(model, nominal_gain=1.5, dt=DT, name="comp", inputs="u", outputs="v")
    c = pid(0.3, 80.0, 1e-4, dt=DT, output_limits=(-1.2, 1.2), inputs="e", outputs="uc")
    ff = ct.ss([], [], [], [[0.5]], DT, inputs="r", outputs="uf", name="ff")
    add = ct.summing_junction(["uf", "uc"], "u", name="add")
    err = ct.summing_junction(["r", "-y"], "e", name="err")
    loop = interconnect([err, c, ff, add, comp, h, piezo_stage(dt=DT, inputs="w", outputs="y")],
                        inplist=["r"], outlist=["y", "v"], name="two_dof")
    _same(loop)


def test_every_built_scenario_and_a_non_default_initial_state():
    act = demo_actuator()
    loops = build_scenarios(act, piezo_stage(), controller=pid(0.0, 40.0, 0.0, dt=DT),
                            compensator=compensator_system(act, nominal_gain="auto", input_range=(-2, 2)), dt=DT)
    for loop in loops.values():
        _same(loop.system)
    sys = loops["feedback"].system
    x0 = initial_state(sys) + 0.01 * np.arange(sys.nstates)
    _same(sys, x0=x0)


def test_a_single_block():
    _same(hysteresis_system(PI([0.5, 1.0], [0.3, 0.2], p0=1.0), dt=DT, inputs="r", outputs="y"))


def test_errors_name_the_block():
    h = hysteresis_system(PI([0.5], [0.3], p0=1.0), dt=DT, name="act", inputs="u", outputs="y")
    cont = ct.ss([[-1.0]], [[1.0]], [[1.0]], [[0.0]], inputs="y", outputs="z", name="slow_sensor")
    with pytest.raises(ValueError, match="slow_sensor"):
        fast_response(cont, T, R)
    user = ct.nlsys(lambda t, x, u, p: -x + u, lambda t, x, u, p: x, states=1, inputs="y", outputs="z",
                    dt=DT, name="my_filter")
    with pytest.raises(NotImplementedError, match="my_filter"):
        fast_response(ct.interconnect([h, user], inplist="u", outlist="z"), T, R)
    with pytest.raises(ValueError, match="inputs"):
        fast_response(h, T, np.ones((2, T.size)))
    with pytest.raises(ValueError, match="timepts"):
        fast_response(h, T * 2, R)


def test_params_and_shifted_virgin_state_through_the_compiled_loop():
    # an envelope with gamma(0) != 0: virgin plays at -0.5, block states shifted by it;
    # X0 = 0 is virgin in both engines, and params sweep the two gains in both
    model = MGPI([0.5, 1.0, 1.5], [0.3, 0.2, 0.1], 1.0, envelope=Tanh(5.0, 0.4, 0.2))
    assert np.all(model.default_state() == -0.5)
    h = hysteresis_system(model, dt=DT, name="act", inputs="v", outputs="w")
    comp = compensator_system(model, nominal_gain=1.5, dt=DT, name="comp", inputs="u", outputs="v")
    c = pid(0.0, 60.0, 0.0, dt=DT, inputs="e", outputs="u")
    err = ct.summing_junction(["r", "-y"], "e", name="err")
    loop = interconnect([err, c, comp, h, piezo_stage(dt=DT, inputs="w", outputs="y")],
                        inplist=["r"], outlist=["y", "w", "v"], name="loop")
    assert loop.params == {"actuator_gain": 1.0, "nominal_gain": 1.5}
    _same(loop, x0=0)
    for params in ({"actuator_gain": 0.7}, {"nominal_gain": 2.0}, {"actuator_gain": 1.3, "nominal_gain": 1.1}):
        fast = fast_response(loop, T, R, params=params)
        slow = ct.input_output_response(loop, T, R, params=params)
        # as in _same: equal to rounding (1e-12 of the signals' size)
        scale = max(1.0, np.abs(slow.outputs).max())
        np.testing.assert_allclose(fast.outputs, slow.outputs, rtol=0, atol=1e-12 * scale)
    base = fast_response(loop, T, R)
    assert np.max(np.abs(fast_response(loop, T, R, params={"actuator_gain": 0.7}).outputs - base.outputs)) > 1e-3
    with pytest.raises(ValueError, match="nominal_gain"):
        fast_response(loop, T, R, params={"nominal_gain": 0.0})

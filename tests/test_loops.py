"""hystcomp.loops: scenarios, compiled loops == python-control, comparison."""

import numpy as np
import pytest

from hystcomp import GPI, MGPI, PI, StopPI
from hystcomp.envelopes import Tanh
from hystcomp.iosys import WiringError, compensator_system, pid, piezo_stage
from hystcomp.loops import (
    SCENARIOS, build_loop, build_scenarios, compare, loop_width, plot_comparison, simulate_loop,
)

DT = 1e-4
N = 300  # python-control runs ~300 us per step for these loops: keep them short


def _actuator():
    r = 0.25 * np.arange(1, 11)
    return MGPI.from_density(lambda x: np.exp(-0.1 * x), r, p0=1.0, envelope=Tanh(30.0, 0.05))


def _reference(n=N, f=20.0):
    t = np.arange(n) * DT
    return t, 3.0 * np.sin(2 * np.pi * f * t) / (1 + 0.1 * t)


CASES = {
    "mgpi exact": (_actuator, "exact", None),
    "mgpi analytic": (_actuator, "analytic", None),
    "mgpi exact limited pid": (_actuator, "exact", (-0.3, 0.3)),
    "pi exact": (lambda: PI(0.5 * np.arange(1, 6), 0.2 * np.ones(5), p0=1.0), "exact", None),
    "stop exact": (lambda: StopPI(0.5 * np.arange(1, 6), 0.2 * np.ones(5), p0=1.0), "exact", None),
    "mgpi asym exact": (lambda: MGPI(0.5 * np.arange(1, 6), 0.2 * np.ones(5), 1.0,
                                     envelope_left=Tanh(10.0, 0.2), envelope_right=Tanh(10.0, 0.1)),
                        "exact", None),
}


@pytest.mark.parametrize("case", list(CASES))
def test_compiled_loops_equal_python_control(case):
    make, method, limits = CASES[case]
    model = make()
    comp = compensator_system(model, method=method, nominal_gain="auto", input_range=(-1.5, 1.5))
    ctrl = pid(0.05, 60.0, 1e-5, DT, output_limits=limits)  # stable gains (GM > 1)
    loops = build_scenarios(model, piezo_stage(), controller=ctrl, compensator=comp, dt=DT)
    assert list(loops) == list(SCENARIOS)
    t, r = _reference()
    for name, loop in loops.items():
        slow = np.asarray(loop.simulate(t, r).outputs)
        fast = np.asarray(simulate_loop(loop, t, r).outputs)
        assert fast.shape == slow.shape == (3, N)
        # the 1e-9: both run the same kernels; only the order of the
        # few products of the linear blocks differs (measured <= 1e-11)
        assert np.max(np.abs(fast - slow)) <= 1e-9, name
    if limits is not None:  # the limits were active in this case
        v = np.asarray(loops["feedback"].simulate(t, r, engine="compiled").outputs)[2]
        assert np.isclose(np.abs(v).max(), 0.3)


def test_gpi_actuator_has_no_compiled_path_and_compare_falls_back():
    model = GPI([0.5, 1.0], [0.4, 0.2], Tanh(2, 0.5), Tanh(2, 0.5), H=Tanh(2, 0.5))
    loop = build_loop("feedback_compensated", model, piezo_stage(), controller=pid(0, 60.0, 0, DT),
                      compensator=compensator_system(model, method="analytic"), dt=DT)
    t, r = _reference(100, f=5.0)
    r = 0.3 * r
    with pytest.raises(NotImplementedError, match="GPI.*loop.simulate"):
        simulate_loop(loop, t, r)
    res = compare([loop], t, r)
    assert res.rows[0]["engine"] == "python-control"
    assert np.array_equal(np.asarray(res.responses[loop.name].outputs), np.asarray(loop.simulate(t, r).outputs))


def test_feedforward_and_nominal_gain_claims_small():
    # the claims on a short record (the demo reports full size)
    model = _actuator()
    n = 20000
    t = np.arange(n) * DT
    r = 5.0 * np.sin(2 * np.pi * 5 * t) / (1 + 0.1 * t)
    comp = compensator_system(model, nominal_gain="auto", input_range=(-2.0, 2.0))
    ctrl = pid(0.0, 40.0, 0.0, DT)
    res = compare(build_scenarios(model, piezo_stage(), controller=ctrl, compensator=comp, dt=DT), t, r,
                  engine="compiled")
    assert res.row("feedforward")["rms"] * 10 <= res.row("open_loop")["rms"]
    assert res.row("feedback_compensated")["rms"] < res.row("feedback")["rms"]
    # the trap: a unit-gain compensator at the same controller gains tracks worse than PID alone
    unit = build_loop("feedback_compensated", model, piezo_stage(), controller=ctrl,
                      compensator=compensator_system(model), dt=DT)
    assert compare([unit], t, r).rows[0]["rms"] > res.row("feedback")["rms"]


def test_table_and_plot(tmp_path):
    model = _actuator()
    loops = build_scenarios(model, piezo_stage(), controller=pid(0, 60.0, 0, DT),
                            compensator=compensator_system(model), dt=DT,
                            scenarios=["open_loop", "feedforward"])
    t, r = _reference(2000)
    res = compare(loops, t, r)
    row = res.row("open_loop")
    y = np.asarray(res.responses["open_loop"].outputs)[0]
    span = r.max() - r.min()
    assert row["rms"] == pytest.approx(np.sqrt(np.mean((y - r) ** 2)), rel=1e-12)
    assert row["max_percent"] == pytest.approx(100 * np.abs(y - r).max() / span, rel=1e-12)
    assert "feedforward" in str(res)
    res.to_csv(tmp_path / "t.csv", extra={"case": "x"})
    lines = (tmp_path / "t.csv").read_text().splitlines()
    assert lines[0].startswith("case,scenario") and len(lines) == 3
    fig = plot_comparison(res, title="test")
    assert len(fig.axes) == 3 and len(fig.axes[0].lines) == 3
    fig.savefig(tmp_path / "c.png")


def test_loop_width():
    r = np.sin(np.linspace(0, 4 * np.pi, 4001))
    assert loop_width(r, r) == 0.0
    # a constant offset does not open the loop; a direction-dependent one does
    assert loop_width(r, r + 0.3) == pytest.approx(0.0, abs=1e-15)
    assert loop_width(r, r + 0.1 * np.sign(np.gradient(r))) == pytest.approx(0.2, abs=1e-12)


def test_bad_loops():
    model = _actuator()
    with pytest.raises(ValueError, match="needs a controller"):
        build_loop("feedback", model, piezo_stage(), dt=DT)
    with pytest.raises(ValueError, match="needs a compensator"):
        build_loop("feedforward", model, piezo_stage(), dt=DT)
    with pytest.raises(ValueError, match="scenario"):
        build_loop("sideways", model, piezo_stage(), dt=DT)
    with pytest.raises(WiringError, match="controller.*dt = 0.001.*dt = 0.0001"):
        build_loop("feedback", model, piezo_stage(), controller=pid(0, 1, 0, 1e-3), dt=DT)
    with pytest.raises(WiringError, match="plant.*dt = 0.0002"):
        build_loop("open_loop", model, piezo_stage(dt=2e-4), dt=DT)
    with pytest.raises(ValueError, match="dt is None"):
        build_loop("open_loop", model, piezo_stage())
    import control as ct

    leaky = ct.ss([[0.5]], [[1.0]], [[1.0]], [[0.1]], DT)
    with pytest.raises(WiringError, match="algebraic loop"):
        build_loop("feedback", model, leaky, controller=pid(0, 1, 0, DT))
    loop = build_loop("open_loop", model, piezo_stage(), dt=DT)
    with pytest.raises(ValueError, match="dt is 0.0001"):
        simulate_loop(loop, np.arange(10) * 2e-4, np.zeros(10))


def test_python_control_argument_order_and_the_old_calls():
    model = _actuator()
    comp = compensator_system(model, nominal_gain="auto", input_range=(-1.5, 1.5))
    loops = build_scenarios(model, piezo_stage(), controller=pid(0.0, 60.0, 0.0, DT), compensator=comp, dt=DT)
    loop = loops["feedback_compensated"]
    t, r = _reference()
    new = np.asarray(simulate_loop(loop, t, r).outputs)
    for old_call in (lambda: simulate_loop(loop, r, t), lambda: simulate_loop(loop, r),
                     lambda: simulate_loop(loop, reference=r, t=t), lambda: simulate_loop(loop, reference=r)):
        with pytest.warns(DeprecationWarning, match="timepts, inputs"):
            np.testing.assert_array_equal(np.asarray(old_call().outputs), new)
    with pytest.warns(DeprecationWarning):
        old = loop.simulate(t=t, reference=r)
    np.testing.assert_array_equal(np.asarray(old.outputs), np.asarray(loop.simulate(t, r).outputs))
    with pytest.warns(DeprecationWarning):
        old_rows = compare(loops, r, t).rows
    assert [row["rms"] for row in old_rows] == [row["rms"] for row in compare(loops, t, r).rows]
    with pytest.raises(TypeError, match="unexpected keyword"):
        simulate_loop(loop, t, r, ref=r)
    with pytest.raises(ValueError, match="timepts has 3 samples"):
        simulate_loop(loop, t[:3], r)


def test_loop_params_and_initial_state_in_both_engines():
    model = _actuator()
    comp = compensator_system(model, nominal_gain="auto", input_range=(-1.5, 1.5))
    loop = build_loop("feedback_compensated", model, piezo_stage(), controller=pid(0.0, 60.0, 0.0, DT),
                      compensator=comp, dt=DT)
    t, r = _reference()
    x0 = loop.initial_state()
    labels = loop.system.state_labels
    x0[[labels.index("plant_position"), labels.index("plant_velocity")]] = [0.01, -0.5]   # displaced, moving
    for kw in (dict(params={"actuator_gain": 0.8}), dict(params={"nominal_gain": 3.0}), dict(initial_state=x0)):
        slow = np.asarray(loop.simulate(t, r, **kw).outputs)
        fast = np.asarray(loop.simulate(t, r, engine="compiled", **kw).outputs)
        # compiled and python-control: the same kernels, products summed in another order
        assert np.max(np.abs(fast - slow)) <= 1e-9, kw
        assert np.max(np.abs(slow - np.asarray(loop.simulate(t, r).outputs))) > 1e-4, kw   # it changed something


@pytest.mark.parametrize("scale", [1e-9, 1.0, 1e3], ids=["nm", "unit", "kV"])
def test_compiled_exact_compensator_uses_the_inverse_tolerance_in_any_units(scale):
    # An actuator whose output is in metres (scale 1e-9: nanometres per volt), in
    # micrometres (1) or kilovolts (1e3).  The compiled loops solve the exact
    # inverse with the tolerance ExactInverse.simulate and the python-control
    # block use (ExactInverse._output_rtol, scaled with the model's output), not
    # an absolute 1e-14, which at the nm scale stops the solve 1e-6 of the span early.
    r = 0.25 * np.arange(1, 11)
    model = MGPI.from_density(lambda x: np.exp(-0.1 * x), r, p0=1.0, envelope=Tanh(30.0 * scale, 0.05))
    comp = compensator_system(model, method="exact", nominal_gain="auto", input_range=(-1.5, 1.5))
    t, ref = _reference()
    ref = ref * scale
    loop = build_loop("feedforward", model, piezo_stage(), compensator=comp, dt=DT)
    slow = np.asarray(loop.simulate(t, ref).outputs)
    fast = np.asarray(simulate_loop(loop, t, ref).outputs)
    # an initial state runs the general compiled interconnection (fast_response)
    general = np.asarray(simulate_loop(loop, t, ref, initial_state=loop.initial_state()).outputs)
    # the compensator's output v: ExactInverse.simulate of the loop's targets k_nom u
    v = comp.compensator.simulate(comp.nominal_gain * loop.feedforward_gain * ref)
    # 1e-12 of the span: the same solver with the same tolerance on the same
    # targets (the targets' products are formed in another order in each engine:
    # measured <= 8.4e-16 of the span at each of the three scales)
    for name, got, want in (("python-control", fast, slow), ("fast_response", general, slow),
                            ("ExactInverse.simulate", fast[2], v)):
        want = np.asarray(want)
        span = np.ptp(want, axis=-1, keepdims=True)
        assert np.max(np.abs(got - want) / span) <= 1e-12, (name, scale)

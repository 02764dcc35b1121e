"""Blocks, loops and comparisons pickle with plain pickle, and compare() runs on any executor."""

import pickle
from concurrent.futures import ProcessPoolExecutor, ThreadPoolExecutor

import control as ct
import numpy as np
import pytest

from hystcomp import MGPI, PI, StopPI
from hystcomp.envelopes import Tanh
from hystcomp.iosys import (compensator_system, hysteresis_system, initial_state, interconnect, pid,
                            piezo_stage)
from hystcomp.loops import build_scenarios, compare

DT = 1e-4


def _models():
    r = 0.25 * np.arange(1, 9)
    return {
        "pi": PI(r, np.exp(-0.1 * r) * 0.25, p0=1.0),
        "mgpi": MGPI.from_density(lambda x: np.exp(-0.1 * x), r, p0=1.0, envelope=Tanh(10.0, 0.2)),
        "mgpi_asym": MGPI(r, np.exp(-0.1 * r) * 0.25, 1.0, envelope_left=Tanh(10.0, 0.2),
                          envelope_right=Tanh(12.0, 0.15)),
        "stop": StopPI(r, np.exp(-0.1 * r) * 0.25, p0=1.0),
    }


def _response(sys, v):
    t = np.arange(len(v)) * DT
    return np.asarray(ct.input_output_response(sys, t, v, X0=initial_state(sys)).outputs)


@pytest.mark.parametrize("name", ["pi", "mgpi", "mgpi_asym", "stop"])
def test_blocks_pickle_and_simulate_identically(name):
    model = _models()[name]
    v = 1.5 * np.sin(np.linspace(0, 12, 300))
    blocks = [hysteresis_system(model, dt=DT, name="act"),
              compensator_system(model, nominal_gain=1.3, dt=DT, name="comp"),
              compensator_system(model, method="analytic", dt=DT, name="comp2") if name in ("pi", "mgpi") else None]
    for block in [b for b in blocks if b is not None]:
        copy = pickle.loads(pickle.dumps(block))
        assert copy.name == block.name and copy.nstates == block.nstates
        np.testing.assert_array_equal(_response(copy, v), _response(block, v))   # same kernels: bit-identical
        assert type(copy) is type(block) and copy.params == block.params
        assert copy.state_labels == block.state_labels
        if hasattr(block, "nominal_gain"):
            assert copy.nominal_gain == block.nominal_gain
            assert type(copy.compensator) is type(block.compensator)
        else:
            assert type(copy.model) is type(block.model)


def test_blocks_with_a_shifted_virgin_state_pickle_and_deepcopy():
    import copy as copy_module

    model = MGPI([0.5, 1.0], [0.3, 0.2], 1.0, envelope=Tanh(5.0, 0.4, 0.2))   # virgin plays at -0.5
    block = hysteresis_system(model, dt=DT, name="act", actuator_gain=1.2)
    v = 1.5 * np.sin(np.linspace(0, 12, 300))
    for other in (pickle.loads(pickle.dumps(block)), copy_module.deepcopy(block), block.copy("act2")):
        assert other.params == {"actuator_gain": 1.2}
        np.testing.assert_array_equal(_response(other, v), _response(block, v))
    t = np.arange(v.size) * DT
    # X0 = 0 is the virgin state; 1e-12: (z - 0.5) + 0.5 rounds
    np.testing.assert_allclose(np.asarray(ct.input_output_response(block, t, v).outputs).reshape(-1),
                               1.2 * model.simulate(v), rtol=0, atol=1e-12)


def test_saturated_pid_pickles():
    c = pid(2.0, 50.0, 0.001, dt=DT, output_limits=(-1.0, 1.0))
    copy = pickle.loads(pickle.dumps(c))
    e = np.sin(np.linspace(0, 20, 400)) * 3
    np.testing.assert_array_equal(_response(copy, e), _response(c, e))


@pytest.fixture(scope="module")
def scenarios():
    act = _models()["pi"]
    return build_scenarios(act, piezo_stage(), controller=pid(0.0, 40.0, 0.0, dt=DT),
                           compensator=compensator_system(act, nominal_gain="auto", input_range=(-2, 2)), dt=DT)


def test_built_loops_pickle(scenarios):
    t = np.arange(1500) * DT
    r = 1.5 * np.sin(2 * np.pi * 20 * t)
    for name, loop in scenarios.items():
        copy = pickle.loads(pickle.dumps(loop))
        a = loop.simulate(t, r, engine="python-control").outputs
        b = copy.simulate(t, r, engine="python-control").outputs
        np.testing.assert_array_equal(a, b, err_msg=name)


def test_compare_on_executors_equals_serial(scenarios):
    t = np.arange(3000) * DT
    r = 1.5 * np.sin(2 * np.pi * 10 * t)
    serial = compare(scenarios, t, r)
    seen = []
    with ThreadPoolExecutor(2) as ex:
        threaded = compare(scenarios, t, r, executor=ex, progress=lambda d, n, name: seen.append(d))
    with ProcessPoolExecutor(2) as ex:
        processes = compare(scenarios, t, r, executor=ex)
    for other in (threaded, processes):
        assert [row["scenario"] for row in other.rows] == [row["scenario"] for row in serial.rows]
        for a, b in zip(serial.rows, other.rows):
            assert a["rms"] == b["rms"] and a["max"] == b["max"]      # same kernels, same numbers
    assert sorted(seen) == list(range(1, len(scenarios) + 1))
    pickle.loads(pickle.dumps(serial))                                 # results pickle too
    with pytest.raises(TypeError, match="executor"):
        compare(scenarios, t, r, executor="dask")


def test_compare_through_a_dask_cluster(scenarios):
    distributed = pytest.importorskip("distributed")
    t = np.arange(2000) * DT
    r = 1.5 * np.sin(2 * np.pi * 10 * t)
    serial = compare(scenarios, t, r)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, distributed.Client(cluster) as client:
        remote = compare(scenarios, t, r, executor=client.get_executor())
    assert [row["rms"] for row in remote.rows] == [row["rms"] for row in serial.rows]


@pytest.mark.parametrize("dt", [0, 0.0, None, float("nan"), -1e-3, "1e-3", float("inf")])
def test_blocks_reject_a_non_discrete_dt(dt):
    with pytest.raises(ValueError, match="Parameter dt"):
        hysteresis_system(_models()["pi"], dt=dt)
    with pytest.raises(ValueError, match="Parameter dt"):
        compensator_system(_models()["pi"], dt=dt)


def test_interconnect_accepts_python_control_names_and_connections():
    act = hysteresis_system(_models()["pi"], dt=DT, name="act", inputs="u", outputs="w")
    stage = piezo_stage(dt=DT, inputs="w", outputs="y")
    by_name = interconnect([act, stage], inplist=["act.u"], outlist=["stage.y"], name="a")
    explicit = interconnect([act, stage], inplist=["act.u"], outlist=["stage.y"], name="b",
                            connections=[["stage.w", "act.w"]])
    reference = ct.interconnect([act, stage], inplist=["act.u"], outlist=["stage.y"],
                                connections=[["stage.w", "act.w"]])
    v = 1.5 * np.sin(np.linspace(0, 10, 200))
    ys = [_response(s, v) for s in (by_name, explicit, reference)]
    np.testing.assert_array_equal(ys[0], ys[2])
    np.testing.assert_array_equal(ys[1], ys[2])
    from hystcomp.iosys import WiringError
    with pytest.raises(WiringError, match="has no signal 'x'"):
        interconnect([act, stage], inplist=["act.x"], outlist=["stage.y"])

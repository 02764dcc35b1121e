"""The mismatch study: identify from noisy records, compensate, run against the true actuator."""

import pickle
from concurrent.futures import ProcessPoolExecutor

import numpy as np
import pytest

from hystcomp import PI
from hystcomp.iosys import pid, piezo_stage
from hystcomp.mismatch import MismatchStudy, identification_input, mismatch_study

DT = 1e-4
ACT = PI([0.5, 1.0, 1.5, 2.0], [0.3, 0.2, 0.1, 0.05], p0=1.0)
T = np.arange(3000) * DT
R = 1.5 * np.sin(2 * np.pi * 5 * T)


def _study(**kw):
    return mismatch_study(ACT, piezo_stage(), pid(0.0, 40.0, 0.0, dt=DT), R, T, (-2.5, 2.5), **kw)


def test_without_noise_every_fit_is_the_true_model():
    s = _study(n_seeds=2, noise=0.0)
    assert max(r["model_rms"] for r in s.rows) < 1e-9          # cvxpy solves to ~1e-10 here
    for sc in ("feedforward", "feedback_compensated", "two_dof"):
        np.testing.assert_allclose(s.errors(sc), s.nominal[sc], rtol=1e-5)


def test_more_noise_costs_more_and_seeds_differ():
    quiet = _study(n_seeds=4, noise=0.002)
    loud = _study(n_seeds=4, noise=0.05)
    assert np.median(loud.errors("feedforward")) > np.median(quiet.errors("feedforward"))
    assert np.median([r["model_rms"] for r in loud.rows]) > 5 * np.median([r["model_rms"] for r in quiet.rows])
    assert len(set(loud.errors("feedforward"))) == 4
    # a fitted compensator is never better than the true one by more than noise luck allows
    assert loud.summary()["feedforward"]["max"] >= loud.nominal["feedforward"]


def test_executor_gives_the_serial_rows_and_results_pickle():
    serial = _study(n_seeds=3, noise=0.01)
    with ProcessPoolExecutor(2) as ex:
        parallel = _study(n_seeds=3, noise=0.01, executor=ex)
    assert parallel.rows == serial.rows
    assert pickle.loads(pickle.dumps(serial)).rows == serial.rows


def test_bad_arguments_are_named():
    with pytest.raises(ValueError, match="input_range"):
        identification_input((2.0, -2.0))
    with pytest.raises(ValueError, match="noise"):
        _study(n_seeds=1, noise=-0.1)
    with pytest.raises(TypeError, match="executor"):
        _study(n_seeds=1, executor="dask")
    with pytest.raises(ValueError, match="scenario"):
        MismatchStudy([dict(seed=0, feedforward=1.0)], {}, 0.0).errors("open_loop")

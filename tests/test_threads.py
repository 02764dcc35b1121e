"""Kernels release the GIL (issue 13 point 3): two threads give the same
results as sequential calls.  (The speed-up is measured in
benchmarks/bench_models.py, not timed here.)"""

import threading

import numpy as np

from hystcomp import MGPI, PI
from hystcomp.envelopes import Tanh


def test_kernels_are_nogil():
    from hystcomp import _kernels as _k
    for f in (_k.pi_sum, _k.play_sum, _k.play_sum_closed, _k.play_sum_tanh, _k.mplay_sum, _k.play_solve_pi,
              _k.play_solve_closed, _k.play_solve_tanh, _k.inverse_solve, _k.inverse_solve_other, _k.play_states):
        assert f.targetoptions.get("nogil") is True, f.__name__


def test_identification_kernels_are_nogil():
    # the diagnosis fits a step's candidates on threads (diagnose(..., workers=2)): the kernels
    # behind its columns release the GIL (round 23: without it two threads took as long as one)
    from hystcomp import _linear_stage
    from hystcomp.identify import _part_kernels as pk
    for f in (pk.core_columns, pk.fractional_delay, pk.drifting_delay, pk.slew_limit, pk.column_ranges,
              _linear_stage._ss_columns, _linear_stage._lag_bank):
        assert f.targetoptions.get("nogil") is True, f.__name__


def test_two_threads_same_results():
    r = 0.5 * np.arange(1, 21)
    p = np.exp(-0.1 * r) * 0.5
    models = [PI(r, p, p0=1.0), MGPI(r, p, p0=1.0, envelope=Tanh(10.0, 0.2))]
    t = np.linspace(0, 50, 20000)
    v = [8 * np.sin(t), 6 * np.sin(1.7 * t + 0.3)]
    expected = [[m.simulate(x) for x in v] for m in models]
    got = [[None, None], [None, None]]

    def run(i, j):
        got[i][j] = models[i].simulate(v[j])

    threads = [threading.Thread(target=run, args=(i, j)) for i in range(2) for j in range(2)]
    for th in threads:
        th.start()
    for th in threads:
        th.join()
    for i in range(2):
        for j in range(2):
            assert np.array_equal(got[i][j], expected[i][j])

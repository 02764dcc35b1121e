"""``diagnose(..., workers=2)``: a step's candidate fits (and a pair step's) on two threads give
the same diagnosis as one thread, report for report (JSON without the timings), solve for solve.

The record: the benchmark's turning drift (an offset that rises over the first 65 % of the record
and falls back) over hidden creep, at 4 ms: searched twice (end, then blocks), with pair steps in
the first search, so the threaded paths all run. The equality is exact (no tolerance): each fit is
the same computation on either thread, and the memo caches hold arrays computed from their keys
alone.
"""

import argparse
import json

import numpy as np
import pytest

from hystcomp import diagnose as dg
from hystcomp.datasets import hidden_effect_data
from hystcomp.identify.search import optimise_all


def _timeless(d):
    if isinstance(d, dict):
        return {k: _timeless(v) for k, v in d.items() if k != "elapsed"}
    if isinstance(d, list):
        return [_timeless(x) for x in d]
    return d


@pytest.fixture(scope="module")
def turning():
    d = hidden_effect_data("creep", seed=0, dt=4e-3)
    return d.t, d.v, d.y + 0.04 * np.ptp(d.y) * np.sin(np.pi * d.t / (1.3 * d.t[-1])) ** 2


def test_two_threads_give_the_same_diagnosis(turning):
    one = dg.diagnose(*turning, progress=False, workers=1)
    two = dg.diagnose(*turning, progress=False, workers=2)
    # the paths the threads serve ran: two searches, pair steps in the first
    assert one.other_split is not None
    assert one.effects == ["drift", "creep"] and one.verdict == "explained"
    assert one.n_evaluations == two.n_evaluations
    assert json.dumps(_timeless(one.to_dict()), sort_keys=True, default=str) == \
        json.dumps(_timeless(two.to_dict()), sort_keys=True, default=str)
    np.testing.assert_array_equal(one.model.simulate(turning[1]), two.model.simulate(turning[1]))


@pytest.mark.parametrize("bad", [0, -1, 1.5, "2", True, None])
def test_bad_workers_name_the_parameter(turning, bad):
    with pytest.raises(ValueError, match=r"Parameter workers is .* but should be an integer >= 1"):
        dg.diagnose(*turning, progress=False, workers=bad)


class _Engine:
    """A stand-in for VariableProjection: optimise() sleeps a little (so that two threads
    finish out of order) and fails as a fit may."""

    def optimise(self, structure, delay=0.0):
        import time

        time.sleep(delay)
        if structure == "unsolvable":
            raise np.linalg.LinAlgError("singular")
        if structure == "bug":
            raise KeyError("not a fit's error")
        return structure


@pytest.mark.parametrize("workers", [1, 2, 3])
def test_optimise_all_keeps_the_order_and_returns_fit_errors(workers):
    jobs = [("a", {"delay": 0.05}), ("unsolvable", {}), ("b", {"delay": 0.0}), ("c", {"delay": 0.02})]
    out = list(optimise_all(_Engine(), jobs, workers))
    assert out[0] == "a" and out[2:] == ["b", "c"]
    assert isinstance(out[1], np.linalg.LinAlgError)
    # an error that is not a fit's propagates
    with pytest.raises(KeyError):
        list(optimise_all(_Engine(), [("a", {}), ("bug", {})], workers))


def test_cli_jobs_with_one_file_threads_the_candidates(turning, tmp_path, capsys):
    path = tmp_path / "turning.csv"
    np.savetxt(path, np.column_stack(turning), delimiter=",", header="t,v,y", comments="")
    outs = []
    for jobs in ("1", "2"):
        parser = dg.add_arguments(argparse.ArgumentParser(prog="hystcomp diagnose"))
        assert dg.run(parser.parse_args([str(path), "--json", "--quiet", "--jobs", jobs])) == 0
        outs.append(_timeless(json.loads(capsys.readouterr().out)))
    assert outs[0] == outs[1]
    assert outs[0]["effects"] == ["drift", "creep"]

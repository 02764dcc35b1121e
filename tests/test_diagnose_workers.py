"""``diagnose(..., workers=2)``: a step's candidate fits (and a pair step's) on two threads give
the same diagnosis as one thread, report for report (JSON without the timings), solve for solve.
The default, ``workers=None``, is :func:`hystcomp.diagnose.default_workers` (2 on two or more
cores, since round 24); :func:`diagnose_many` on an executor fits one thread a record.

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


@pytest.mark.parametrize("bad", [0, -1, 1.5, "2", True])
def test_bad_workers_name_the_parameter(turning, bad):
    with pytest.raises(ValueError, match=r"Parameter workers is .* but should be None or an integer >= 1"):
        dg.diagnose(*turning, progress=False, workers=bad)


@pytest.mark.parametrize("cores, expected", [({0}, 1), ({0, 1}, 2), ({0, 1, 2, 3, 4, 5, 6, 7}, 2)])
def test_default_workers_follow_the_cores(monkeypatch, cores, expected):
    import os

    monkeypatch.setattr(os, "sched_getaffinity", lambda pid: cores, raising=False)
    assert dg.default_workers() == expected


def test_default_workers_without_affinity(monkeypatch):
    # not on Linux: os.cpu_count() decides
    import os

    monkeypatch.delattr(os, "sched_getaffinity", raising=False)
    for count, expected in ((None, 1), (1, 1), (4, 2)):
        monkeypatch.setattr(os, "cpu_count", lambda count=count: count)
        assert dg.default_workers() == expected


def _spy_workers(monkeypatch):
    """Record the `workers` every candidate step of a diagnosis is fitted with."""
    from hystcomp.diagnose import search

    seen = []
    real = search.optimise_all

    def spy(vp, jobs, workers=1):
        seen.append(workers)
        return real(vp, jobs, workers)

    monkeypatch.setattr(search, "optimise_all", spy)
    return seen


def test_workers_none_is_the_default_workers(monkeypatch):
    d = hidden_effect_data("drift", seed=1, dt=0.01)
    seen = _spy_workers(monkeypatch)
    monkeypatch.setattr(dg, "default_workers", lambda: 2)
    dg.diagnose(d.t, d.v, d.y, progress=False)
    assert seen and set(seen) == {2}
    seen.clear()
    dg.diagnose(d.t, d.v, d.y, progress=False, workers=1)
    assert set(seen) == {1}


class _Here:
    """An executor that runs each job at once, here, and keeps the options it was given."""

    def __init__(self):
        self.options = []

    def submit(self, fn, job):
        from concurrent.futures import Future

        self.options.append(dict(job[1]))
        f = Future()
        f.set_result(fn(job))
        return f


def test_diagnose_many_on_an_executor_uses_one_thread_a_record():
    d = hidden_effect_data("drift", seed=1, dt=0.01)
    ex = _Here()
    reps = dg.diagnose_many([(d.t, d.v, d.y)] * 2, executor=ex, progress=False, effects=["drift"])
    assert [o["workers"] for o in ex.options] == [1, 1]
    assert reps[0].effects == reps[1].effects == ["drift"]
    # unless asked otherwise
    ex = _Here()
    dg.diagnose_many([(d.t, d.v, d.y)], executor=ex, progress=False, effects=["drift"], workers=2)
    assert ex.options[0]["workers"] == 2


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


def test_cli_without_jobs_uses_the_default_workers(tmp_path, monkeypatch, capsys):
    d = hidden_effect_data("drift", seed=1, dt=0.01)
    path = tmp_path / "drift.csv"
    np.savetxt(path, np.column_stack([d.t, d.v, d.y]), delimiter=",", header="t,v,y", comments="")
    seen = _spy_workers(monkeypatch)
    monkeypatch.setattr(dg, "default_workers", lambda: 2)
    parser = dg.add_arguments(argparse.ArgumentParser(prog="hystcomp diagnose"))
    assert dg.run(parser.parse_args([str(path), "--json", "--quiet"])) == 0
    assert json.loads(capsys.readouterr().out)["effects"] == ["drift"]
    assert seen and set(seen) == {2}


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

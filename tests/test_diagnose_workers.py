"""``diagnose(..., workers=2)``: a step's candidate fits (and a pair step's) on two threads, or in
two forked processes (the default where :func:`hystcomp.identify.parallel_fits.can_fork`, since
round 25), give the same diagnosis as one thread, report for report (JSON without the timings),
solve for solve.
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
import multiprocessing
import sys
import threading
import warnings

import numpy as np
import pytest

from hystcomp import diagnose as dg
from hystcomp.datasets import hidden_effect_data
from hystcomp.identify.parallel_fits import optimise_all


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


def test_two_threads_give_the_same_diagnosis(turning, monkeypatch):
    from hystcomp.identify import parallel_fits

    one = dg.diagnose(*turning, progress=False, workers=1)
    monkeypatch.setattr(parallel_fits, "can_fork", lambda: False)     # threads
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
    """A stand-in for VariableProjection: optimise() sleeps a little (so that two workers
    finish out of order), counts one inner solve and fails as a fit may."""

    def __init__(self):
        self.n_evaluations = 0

    def optimise(self, structure, delay=0.0):
        import time

        time.sleep(delay)
        self.n_evaluations += 1
        if structure == "unsolvable":
            raise np.linalg.LinAlgError("singular")
        if structure == "bug":
            raise KeyError("not a fit's error")
        return structure


_FORKABLE = sys.platform.startswith("linux") and "fork" in multiprocessing.get_all_start_methods()
_KINDS = [False] + ([True] if _FORKABLE else [])


@pytest.mark.parametrize("processes", _KINDS)
@pytest.mark.parametrize("workers", [1, 2, 3])
def test_optimise_all_keeps_the_order_and_returns_fit_errors(workers, processes):
    jobs = [("a", {"delay": 0.05}), ("unsolvable", {}), ("b", {"delay": 0.0}), ("c", {"delay": 0.02})]
    engine = _Engine()
    with warnings.catch_warnings():
        # Python >= 3.12 warns when a process with threads forks (pytest-xdist's worker has one)
        warnings.simplefilter("ignore", DeprecationWarning)
        out = list(optimise_all(engine, jobs, workers, processes=processes))
        assert out[0] == "a" and out[2:] == ["b", "c"]
        assert isinstance(out[1], np.linalg.LinAlgError)
        # the solves of forked children are counted here too
        assert engine.n_evaluations == 4
        # an error that is not a fit's propagates
        with pytest.raises(KeyError):
            list(optimise_all(_Engine(), [("a", {}), ("bug", {})], workers, processes=processes))


def test_can_fork_only_without_other_threads(monkeypatch):
    from hystcomp.identify import parallel_fits

    monkeypatch.setattr(threading, "active_count", lambda: 1)
    assert parallel_fits.can_fork() == _FORKABLE
    monkeypatch.setattr(threading, "active_count", lambda: 2)
    assert parallel_fits.can_fork() is False
    monkeypatch.setattr(threading, "active_count", lambda: 1)
    monkeypatch.setattr(sys, "platform", "darwin")
    assert parallel_fits.can_fork() is False
    with pytest.raises(ValueError, match=r"Parameter processes is True but this platform \(darwin\) cannot fork"):
        optimise_all(_Engine(), [("a", {})], 2, processes=True)


def test_forked_fits_give_the_diagnosis_of_one_thread(turning, monkeypatch):
    """The same record as above, its candidate fits forced into forked processes."""
    if not _FORKABLE:
        pytest.skip("this platform cannot fork")
    from hystcomp.identify import parallel_fits

    real = parallel_fits.optimise_all
    kinds = []

    def forked(vp, jobs, workers=1, processes=None):
        kinds.append(workers)
        return real(vp, jobs, workers, processes=True)

    from hystcomp.diagnose import search

    one = dg.diagnose(*turning, progress=False, workers=1)
    monkeypatch.setattr(search, "optimise_all", forked)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", DeprecationWarning)
        two = dg.diagnose(*turning, progress=False, workers=2)
    assert kinds and set(kinds) == {2}
    assert one.n_evaluations == two.n_evaluations
    assert json.dumps(_timeless(one.to_dict()), sort_keys=True, default=str) == \
        json.dumps(_timeless(two.to_dict()), sort_keys=True, default=str)
    np.testing.assert_array_equal(one.model.simulate(turning[1]), two.model.simulate(turning[1]))


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


class _Sleeper:
    """An engine whose fits sleep and leave a file each when they start (in whatever process)."""

    def __init__(self, where):
        self.where = where
        self.n_evaluations = 0

    def optimise(self, structure, delay=0.0):
        import time

        (self.where / f"started_{structure}").touch()
        time.sleep(delay)
        return structure


@pytest.mark.skipif(not _FORKABLE, reason="this platform cannot fork")
def test_fits_not_started_are_dropped_when_the_caller_stops(tmp_path):
    # sixteen fits of 0.2 s in two processes; the caller takes the first and stops (as on
    # Ctrl-C): the fits not yet handed to the children are cancelled, those handed end
    jobs = [(str(i), {"delay": 0.2}) for i in range(16)]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", DeprecationWarning)
        fits = optimise_all(_Sleeper(tmp_path), jobs, 2, processes=True)
        assert next(fits) == "0"
        fits.close()
    started = sorted(p.name for p in tmp_path.iterdir())
    # handed to the children: two under way and the executor's call queue (workers + 1) when
    # the caller stopped, and the two or so that moved up while it shut the executor down
    assert 2 <= len(started) <= 9, started


def _children(pid):
    """Process ids whose parent is `pid` (Linux /proc)."""
    import os

    out = []
    for d in os.listdir("/proc"):
        if d.isdigit():
            try:
                with open(f"/proc/{d}/stat") as f:
                    fields = f.read().rsplit(")", 1)[1].split()
            except OSError:
                continue
            if int(fields[1]) == pid:
                out.append(int(d))
    return out


@pytest.mark.skipif(not _FORKABLE, reason="this platform cannot fork")
def test_ctrl_c_while_children_fit_ends_with_one_line(tmp_path):
    import os
    import signal
    import subprocess
    import time

    d = hidden_effect_data("creep", seed=0, dt=2e-3)
    path = tmp_path / "creep.csv"
    np.savetxt(path, np.column_stack([d.t, d.v, d.y]), delimiter=",", header="t,v,y", comments="")
    proc = subprocess.Popen([sys.executable, "-m", "hystcomp", "diagnose", str(path), "--quiet"],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            preexec_fn=lambda: (signal.signal(signal.SIGINT, signal.SIG_DFL), os.setpgrp()))
    try:
        kids = []
        for _ in range(1200):           # until the first step's children are fitting (at most 120 s)
            kids = _children(proc.pid)
            if len(kids) >= 2 or proc.poll() is not None:
                break
            time.sleep(0.1)
        assert len(kids) >= 2, "the diagnosis ended before it forked"
        os.killpg(proc.pid, signal.SIGINT)        # Ctrl-C reaches the whole process group
        _, err = proc.communicate(timeout=120)
    finally:
        if proc.poll() is None:
            proc.kill()
    assert proc.returncode == 130
    assert err.strip().splitlines()[-1] == "hystcomp diagnose: interrupted"
    assert "Traceback" not in err
    # the children ended with the parent (it waits for them), none left running on its own
    assert not [k for k in kids if os.path.exists(f"/proc/{k}")]


class _Dying(_Engine):
    """An engine whose fit of "die" kills the forked child that makes it (and only a child)."""

    def __init__(self):
        import os

        super().__init__()
        self.parent = os.getpid()

    def optimise(self, structure, delay=0.0):
        import os

        if structure == "die" and os.getpid() != self.parent:
            os._exit(1)
        return super().optimise(structure, delay)


@pytest.mark.skipif(not _FORKABLE, reason="this platform cannot fork")
def test_a_child_that_dies_leaves_its_fits_to_this_process():
    jobs = [("a", {}), ("die", {"delay": 0.05}), ("b", {}), ("c", {})]
    engine = _Dying()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", DeprecationWarning)
        with pytest.warns(RuntimeWarning, match=r"a forked candidate fit ended abnormally .* made in this process"):
            out = list(optimise_all(engine, jobs, 2, processes=True))
    # every fit, in order; the ones after the dead child's were made here
    assert out == ["a", "die", "b", "c"]


@pytest.mark.skipif(not _FORKABLE, reason="this platform cannot fork")
def test_without_a_process_pool_the_fits_run_on_threads(monkeypatch):
    # a container without /dev/shm: multiprocessing cannot make the pool's locks
    import concurrent.futures

    def no_pool(*args, **kwargs):
        raise OSError(38, "Function not implemented")

    monkeypatch.setattr(concurrent.futures, "ProcessPoolExecutor", no_pool)
    engine = _Engine()
    out = list(optimise_all(engine, [("a", {"delay": 0.02}), ("unsolvable", {}), ("b", {})], 2, processes=True))
    assert out[0] == "a" and out[2] == "b" and isinstance(out[1], np.linalg.LinAlgError)
    assert engine.n_evaluations == 3


def _revised(workers, processes, kinds):
    """The revision of a model holding `kinds` on the play core with a warming offset of
    test_diagnose_revise_evidence, its refits `workers` side by side."""
    from hystcomp.diagnose import revise as rv
    from hystcomp.diagnose import search
    from hystcomp.identify import parallel_fits
    from hystcomp.identify.parts import PARTS
    from hystcomp.identify.search import Structure
    from test_diagnose_revise_evidence import _setup

    rec, ctx, vp, _, _ = _setup()
    st = Structure()
    for kind in kinds:
        part = PARTS[kind]()
        part.prepare(rec.y, ctx)
        st = st.extended(part)
    start = {}
    for p, q in st.parameters(ctx):
        start.setdefault(p.kind, {})[q.name] = q.initial
    cur = vp.evaluate(st, start)

    def rms_val(pt):
        return float(np.sqrt(np.mean((rec.y - pt.prediction)[~rec.train] ** 2)))

    r = rms_val(cur)
    effects = [PARTS[k].effect for k in kinds]
    steps = [{"effect": e, "rms_before": (2.0 - 0.2 * i) * r, "evidence": {"acceptable": {k: 1.0}}}
             for i, (e, k) in enumerate(zip(effects, kinds))]
    said, sizes = [], []
    real = parallel_fits.run_all

    def spy(vp, tasks, workers=1):
        if tasks:       # a step without alternatives asks for none
            sizes.append(len(tasks))
        return real(vp, tasks, workers, processes=processes)

    rv.run_all = spy
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", DeprecationWarning)
            _, pt, revisions = search._revise(vp, ctx, rec, st, cur, steps, effects, list(kinds),
                                              [{k: r} for k in kinds], 0.05, rms_val, said.append, workers)
    finally:
        rv.run_all = real
    return said, pt, revisions, steps, vp.n_evaluations, sizes


@pytest.mark.parametrize("processes", _KINDS)
def test_revision_refits_side_by_side_give_the_revision_of_one_thread(processes):
    # the lag is dropped first (a later effect, the drift, holds the warming), the drift kept,
    # then the envelopes dropped: the refits after a dropped part are made again from the
    # model without it (3 refits from the first model, then 2 from the second)
    kinds = ["output_lag", "offset_drift", "asymmetric_envelopes"]
    one = _revised(1, None, kinds)
    two = _revised(2, processes, kinds)
    assert [s.split(":")[1].split()[-1] for s in one[0]] == ["dropped", "kept", "dropped"]
    assert one[5] == two[5] == [3, 2]
    assert one[0] == two[0]
    assert one[1].rss == two[1].rss and np.array_equal(one[1].theta, two[1].theta)
    assert one[2] == two[2] and one[3] == two[3]
    # the refits' inner solves are counted alike (forked children's too)
    assert one[4] == two[4]

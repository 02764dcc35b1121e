"""Several candidate fits side by side: :func:`optimise_all` (one
variable-projection search a candidate) and :func:`run_all` (any fits made
from the same engine, e.g. a diagnosis's revision refits).

A diagnosis step fits every candidate effect from the same model
(:meth:`~hystcomp.identify.search.VariableProjection.optimise`, one
variable-projection search each); the fits are independent.  They run in
forked processes where that is safe (Linux, a process that runs no other
thread: :func:`can_fork`), else on threads.

Processes, because the search's Python code holds the GIL: on two cores, on
the benchmark's record searched twice, two threads took 0.82 of one
worker's time, two forked processes 0.65 (best against best, round 25,
``benchmarks/bench_diagnose.py``).  A forked child starts with the parent's
memory (the record, its memo caches), so nothing is copied in; it sends back
the fit (a :class:`~hystcomp.identify.search.FitPoint`) and its count of
inner solves (a fit on a thread counts its own the same way).  Round 48
runs a diagnosis's revision refits side by side too (:func:`run_all`,
:func:`hystcomp.diagnose.revise.revise`).  Each fit is the same computation in any process or thread
(the memo caches hold arrays computed from their keys alone), so the
results are identical with any `workers` and either kind.
"""

import copy
import multiprocessing
import sys
import threading

from .search import _LOCK, FIT_ERRORS

__all__ = ["optimise_all", "run_all", "can_fork"]

#: the engine and tasks the forked children run (set in the parent just before
#: it forks, so the children inherit them; cleared after)
_FORKED = None


def can_fork():
    """Whether :func:`optimise_all` may fit in forked processes here: on
    Linux, with the ``fork`` start method, from a process that runs no
    other thread (forking a process with threads may deadlock the child:
    a lock held by another thread stays held there) and is not itself a
    pool's worker (those may not have children).  Elsewhere (macOS,
    Windows, a Jupyter kernel, a thread pool) the fits run on threads.

    Examples
    --------
    >>> can_fork() in (True, False)
    True
    """
    return (_platform_forks() and threading.active_count() == 1
            and not multiprocessing.current_process().daemon)


def _platform_forks():
    """Linux with the ``fork`` start method (macOS's fork is unsafe with its
    system libraries; Windows has none)."""
    return sys.platform.startswith("linux") and "fork" in multiprocessing.get_all_start_methods()


class _Optimise:
    """A task of :func:`run_all`: ``vp.optimise(structure, **kw)``."""

    def __init__(self, job):
        self.structure, self.kw = job

    def __call__(self, vp):
        return vp.optimise(self.structure, **self.kw)


def _fit(vp, task):
    try:
        return task(vp)
    except FIT_ERRORS as exc:
        return exc


def _fit_forked(i):
    """Task `i` of :data:`_FORKED`, in a forked child: the fit and its inner solves."""
    vp, tasks = _FORKED
    n0 = vp.n_evaluations
    out = _fit(vp, tasks[i])
    return out, vp.n_evaluations - n0


def optimise_all(vp, jobs, workers=1, processes=None):
    """:meth:`~hystcomp.identify.search.VariableProjection.optimise` for
    several candidates, in order.

    Parameters
    ----------
    vp : VariableProjection
    jobs : list of (Structure, dict)
        Each candidate's structure and the keyword arguments of
        :meth:`~hystcomp.identify.search.VariableProjection.optimise`
        (``start``, ``free``, ``max_evaluations``, ``starts``).
    workers : int
        Fits side by side (1: one after another, in this thread).
    processes : bool or None
        With ``workers > 1``: True fits in forked processes, False on
        threads; None (default) in processes when :func:`can_fork`.  The
        results are the same either way; ``vp.n_evaluations`` counts the
        inner solves of the fits taken from the iterator, in whatever
        process or thread they were made (fits run ahead and not taken are
        not counted, so the count is the same with any `workers`).

    Returns
    -------
    iterator
        One :class:`~hystcomp.identify.search.FitPoint` per job, in the
        jobs' order, as each is ready (or the
        :data:`~hystcomp.identify.search.FIT_ERRORS` exception it ended
        with; any other exception propagates).

    Raises
    ------
    ValueError
        `processes` is True where this platform cannot fork.

    Examples
    --------
    >>> import numpy as np
    >>> from hystcomp.identify.parts import Context, Drift
    >>> from hystcomp.identify.search import Structure, VariableProjection
    >>> t = np.linspace(0.0, 10.0, 500); v = np.sin(t)
    >>> vp = VariableProjection(Context(v, 0.02, 0.0, 1.0, 10.0, n_thresholds=6), 2 * v, t < 7)
    >>> drift = {"start": {"offset_drift": {"time_constant": 3.0}}, "max_evaluations": 4}
    >>> jobs = [(Structure(), {"start": {}}), (Structure([Drift()]), drift)]
    >>> [round(pt.rss, 6) for pt in optimise_all(vp, jobs, workers=2)]
    [0.0, 0.0]
    """
    return run_all(vp, [_Optimise(job) for job in jobs], workers, processes)


def run_all(vp, tasks, workers=1, processes=None):
    """Several fits from the engine `vp`, in order: each task is a callable
    ``task(vp)`` that returns a :class:`~hystcomp.identify.search.FitPoint`
    (made with `vp`'s methods only, so that it is the same computation in
    any process or thread).  :func:`optimise_all` is this with one
    ``vp.optimise`` a task.

    Parameters
    ----------
    vp : VariableProjection
    tasks : list of callable
        ``task(vp) -> FitPoint``.  In forked children the tasks are
        inherited, not pickled (closures are fine); their results are
        pickled back.
    workers, processes
        As in :func:`optimise_all`.

    Returns
    -------
    iterator
        Each task's result, in the tasks' order, as each is ready (or the
        :data:`~hystcomp.identify.search.FIT_ERRORS` exception it ended
        with; any other exception propagates).  With one worker the tasks
        run lazily, one as each result is asked for, so a caller that stops
        early runs no more than it used; with more, they run ahead (close
        the iterator when stopping early).

    Examples
    --------
    A stand-in engine whose one "fit" doubles a number and counts a solve:

    >>> class Doubler:
    ...     n_evaluations = 0
    ...     def fit(self, x):
    ...         self.n_evaluations += 1
    ...         return 2 * x
    >>> engine = Doubler()
    >>> list(run_all(engine, [lambda e: e.fit(1), lambda e: e.fit(5)], workers=2)), engine.n_evaluations
    ([2, 10], 2)
    """
    if processes and not _platform_forks():
        raise ValueError(f"Parameter processes is {processes!r} but this platform ({sys.platform}) cannot fork; "
                         "pass None or False (threads)")
    if workers <= 1 or len(tasks) < 2:
        return (_fit(vp, task) for task in tasks)
    if processes is None:
        processes = can_fork()
    n = min(workers, len(tasks))
    if processes:
        return _in_processes(vp, tasks, n)
    from concurrent.futures import ThreadPoolExecutor

    def on_threads():
        ex = ThreadPoolExecutor(n)
        try:
            for out, solves in ex.map(lambda task: _counted(vp, task), tasks):
                with _LOCK:
                    vp.n_evaluations += solves
                yield out
        finally:
            # a caller that stops early: the fits not started are dropped, those under way end first
            ex.shutdown(wait=True, cancel_futures=True)
    return on_threads()


def _counted(vp, task):
    """A task on a thread, fitted by a shallow copy of `vp` (the same record
    and memo caches) that counts its own inner solves: they are added to
    `vp` as its result is taken, as a forked child's are, so that fits run
    ahead and not taken are not counted."""
    view = copy.copy(vp)
    view.n_evaluations = 0
    out = _fit(view, task)
    return out, view.n_evaluations


def _quiet_child():
    """A forked child ignores Ctrl-C: the parent stops the fits (its own
    KeyboardInterrupt), and the child prints no traceback of its own."""
    import signal

    signal.signal(signal.SIGINT, signal.SIG_IGN)


def _in_processes(vp, tasks, n):
    """The fits in `n` forked children, in order.  Where no process pool can
    be made (no working ``sem_open``: a container without ``/dev/shm``) the
    fits run on threads; where a child dies (killed for memory, say) the
    fits not yet received are made here, one after another, with a
    warning: the same results either way."""
    global _FORKED
    from concurrent.futures import ProcessPoolExecutor
    from concurrent.futures.process import BrokenProcessPool

    try:
        ex = ProcessPoolExecutor(n, mp_context=multiprocessing.get_context("fork"), initializer=_quiet_child)
    except (OSError, ImportError, NotImplementedError):
        yield from run_all(vp, tasks, n, processes=False)
        return
    _FORKED = (vp, tasks)
    done = 0
    try:
        # the children are forked at the first submit (all of them, before the
        # executor starts its own thread), so they inherit _FORKED
        try:
            for out, solves in ex.map(_fit_forked, range(len(tasks))):
                with _LOCK:
                    vp.n_evaluations += solves
                done += 1
                yield out
        except BrokenProcessPool as exc:
            import warnings

            warnings.warn(f"a forked candidate fit ended abnormally ({exc}); the {len(tasks) - done} fits left "
                          "are made in this process", RuntimeWarning, stacklevel=2)
            for task in tasks[done:]:
                yield _fit(vp, task)
    finally:
        # on Ctrl-C (or an error) the fits not started are dropped; those under
        # way end first (one fit each)
        ex.shutdown(wait=True, cancel_futures=True)
        _FORKED = None

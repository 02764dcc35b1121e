"""Several candidate fits side by side: :func:`optimise_all`.

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
inner solves.  Each fit is the same computation in any process or thread
(the memo caches hold arrays computed from their keys alone), so the
results are identical with any `workers` and either kind.
"""

import multiprocessing
import sys
import threading

from .search import _LOCK, FIT_ERRORS

__all__ = ["optimise_all", "can_fork"]

#: the engine and jobs the forked children fit (set in the parent just before
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


def _fit(vp, job):
    structure, kw = job
    try:
        return vp.optimise(structure, **kw)
    except FIT_ERRORS as exc:
        return exc


def _fit_forked(i):
    """Job `i` of :data:`_FORKED`, in a forked child: the fit and its inner solves."""
    vp, jobs = _FORKED
    n0 = vp.n_evaluations
    out = _fit(vp, jobs[i])
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
        children's solves too.

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
    if processes and not _platform_forks():
        raise ValueError(f"Parameter processes is {processes!r} but this platform ({sys.platform}) cannot fork; "
                         "pass None or False (threads)")
    if workers <= 1 or len(jobs) < 2:
        return (_fit(vp, job) for job in jobs)
    if processes is None:
        processes = can_fork()
    n = min(workers, len(jobs))
    if processes:
        return _in_processes(vp, jobs, n)
    from concurrent.futures import ThreadPoolExecutor

    def on_threads():
        with ThreadPoolExecutor(n) as ex:
            yield from ex.map(lambda job: _fit(vp, job), jobs)
    return on_threads()


def _quiet_child():
    """A forked child ignores Ctrl-C: the parent stops the fits (its own
    KeyboardInterrupt), and the child prints no traceback of its own."""
    import signal

    signal.signal(signal.SIGINT, signal.SIG_IGN)


def _in_processes(vp, jobs, n):
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
        yield from optimise_all(vp, jobs, n, processes=False)
        return
    _FORKED = (vp, jobs)
    done = 0
    try:
        # the children are forked at the first submit (all of them, before the
        # executor starts its own thread), so they inherit _FORKED
        try:
            for out, solves in ex.map(_fit_forked, range(len(jobs))):
                with _LOCK:
                    vp.n_evaluations += solves
                done += 1
                yield out
        except BrokenProcessPool as exc:
            import warnings

            warnings.warn(f"a forked candidate fit ended abnormally ({exc}); the {len(jobs) - done} fits left "
                          "are made in this process", RuntimeWarning, stacklevel=2)
            for job in jobs[done:]:
                yield _fit(vp, job)
    finally:
        # on Ctrl-C (or an error) the fits not started are dropped; those under
        # way end first (one fit each)
        ex.shutdown(wait=True, cancel_futures=True)
        _FORKED = None

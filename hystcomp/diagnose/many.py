"""Many records at once: :func:`diagnose_many` runs independent diagnoses on an executor."""

__all__ = ["diagnose_many"]


def _one(job):
    """One diagnosis (module level, so that an executor can run it in another process)."""
    from . import diagnose

    (t, v, y), options = job
    return diagnose(t, v, y, **options)


def diagnose_many(records, executor=None, **options):
    """Diagnose several records, each an independent job.

    Parameters
    ----------
    records : iterable of (t, v, y)
        One tuple per record, as the arguments of
        :func:`~hystcomp.diagnose.diagnose` (``t`` may be None).
    executor : concurrent.futures.Executor, optional
        Runs the diagnoses on it (a ``ProcessPoolExecutor``, or
        ``distributed.Client(...).get_executor()`` for dask across
        machines); the results are those of a run here.  None runs them one
        after the other.
    **options
        Keyword arguments of :func:`~hystcomp.diagnose.diagnose` (e.g.
        ``effects``, ``validation``, ``progress``).  With an executor,
        ``workers`` is 1 unless given: the records already run side by
        side.

    Returns
    -------
    list of Diagnosis
        In the order of `records`.

    Examples
    --------
    >>> from hystcomp.datasets import hidden_effect_data
    >>> recs = [hidden_effect_data(e, seed=3, dt=0.01)[:3] for e in ("drift", None)]
    >>> [d.effects for d in diagnose_many(recs, effects=["drift"], progress=False)]
    [['drift'], []]
    """
    if executor is not None:
        options.setdefault("workers", 1)
    jobs = []
    for i, rec in enumerate(records):
        try:
            t, v, y = rec
        except (TypeError, ValueError):
            raise TypeError(f"Parameter records[{i}] is {type(rec).__name__}; expected a (t, v, y) tuple") from None
        jobs.append(((t, v, y), dict(options)))
    if executor is None:
        return [_one(job) for job in jobs]
    if not hasattr(executor, "submit"):
        raise TypeError(f"Parameter executor is {executor!r}; expected a concurrent.futures.Executor (or None)")
    futures = [executor.submit(_one, job) for job in jobs]
    return [f.result() for f in futures]

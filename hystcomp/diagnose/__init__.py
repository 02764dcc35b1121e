"""Find where a hysteresis model and a measurement disagree, name the missing
effects by evidence, and say honestly when the data are not explained.

:func:`diagnose` fits a plain PI model (eq. 18; thresholds up to the full
input span) on the first part of a record and estimates the record's
**noise floor** from the record itself (:func:`~hystcomp.diagnose.noise.noise_floor`:
the high-frequency part of the residual, and the output's scatter during
input holds).  Then, step by step, it tries every candidate effect's model
part (:mod:`hystcomp.identify.parts`), each fitted by variable projection
with the one constrained least-squares solve of :mod:`hystcomp.identify`:

=================  =============================================================
effect             parts tried
=================  =============================================================
rate_dependence    lag after the hysteresis, resonance after it, lag before it,
                   rate-dependent thresholds ``r_i + beta |dv/dt|``, the base
                   recoiling on its mount (the stroke read from the ground)
creep              lags of the input on a log grid of time constants
drift              ``a t + b (1 - exp(-t/tau))``; broken lines in time of 6
                   segments (no set shape) and of 24 (events)
gain_drift         gain ``1 + g (t/T - 1/2)`` on the hysteresis
asymmetry          asymmetric mGPI envelopes (with saturation: two saturating
                   envelopes)
saturation         mGPI envelope ``tanh(b v)/b`` (eq. 25)
output_saturation  clipping of the output
delay              dead time in fractional samples (up to 0.2 % of the record,
                   then on up to 0.5 s when the best ends there)
initial_state      a preload history before the record (the plays' start state)
=================  =============================================================

An effect is named only when **its signature is present** in the current
residual (:mod:`~hystcomp.diagnose.signatures`: a statistic in noise floors
against a stated threshold), **its extension pays** on the training part
(the BIC falls) **and** it lowers the held-out mean square by at least
``MIN_GAIN`` = 0.25 noise variances.  Among those the one with the largest
held-out gain is added, and then every nonlinear parameter of the model is
refitted jointly (warm-started).  The verdict is ``"explained"`` only when
the final held-out RMS is within 1.5 noise floors and no signature test
fires on the final residual; otherwise ``"unexplained"``, with what
remains (in time, against input, against rate, at the record's start).
A record the held-out end leaves unexplained with no drift named is
re-judged on blocks held out between fitted stretches (a drift that turns
cannot be extrapolated into the end; ``held_out`` of :func:`diagnose`).
A record left unexplained is also fitted with a rate-independent core of the
Preisach type (a KP model, :mod:`~hystcomp.diagnose.preisach_core`), judged
the same way: when it explains the record, the report says what the
vocabulary misses may be a core that is not PI (or a static map, which
such a core draws too); it changes no name, and when no effect was named it
is taken: the verdict is ``"explained"`` and the model returned is that core.

Without a time axis (``t=None``: a quasi-static point sequence such as a
B-H loop) rate dependence, creep, drift, gain drift and delay are reported
untestable, never named.
"""

import numpy as np

from .cli import add_arguments, load_csv, main, run
from .record import HELD_OUT, find_holds
from .report import SCHEMA_VERSION, Diagnosis
from .search import EFFECTS, EXPLAINED, MIN_GAIN, run_search

__all__ = ["EFFECTS", "ALL", "Diagnosis", "diagnose", "diagnose_many", "default_workers", "evidence", "add_arguments",
           "run", "load_csv"]

#: every effect (the default candidates of :func:`diagnose`)
ALL = EFFECTS


def default_workers():
    """The workers :func:`diagnose` fits a step's candidates with when
    ``workers`` is None: 2 when this process may run on two or more cores
    (its CPU affinity, else ``os.cpu_count()``), else 1.  Two, not more: a
    step has 3-17 candidates of uneven cost, and on threads the search's
    Python code holds the GIL (on the benchmark's record searched twice
    two threads took 0.82 of one's time; two forked processes, the default
    where :func:`hystcomp.identify.parallel_fits.can_fork`, 0.65).

    Examples
    --------
    >>> default_workers() in (1, 2)
    True
    """
    import os

    try:
        cores = len(os.sched_getaffinity(0))
    except (AttributeError, OSError):      # not on Linux
        cores = os.cpu_count() or 1
    return 2 if cores >= 2 else 1


def diagnose(t, v=None, y=None, effects=ALL, validation=0.3, max_effects=4, base="pi", n_thresholds=20,
             progress=True, *, time="t", input="v", output="y", held_out="auto", workers=None):
    """Name the effects a PI model lacks by evidence, add them, and give an
    honest verdict.

    Parameters
    ----------
    t : array_like, shape (n,), None or pandas.DataFrame
        Time [s] (increasing, uniformly sampled, any step), or None for a
        record without a time axis (then rate_dependence, creep, drift,
        gain_drift and delay are untestable and reported in ``untested``).
        A datetime or timedelta axis (numpy or pandas) counts in seconds
        from its first sample.  A DataFrame is the whole record, its
        columns named by `time`, `input` and `output` (then `v` and `y`
        are not given).
    v, y : array_like, shape (n,)
        Input and measured output (pandas Series welcome).
    effects : sequence of str
        Candidates among :data:`EFFECTS` and the effects of parts you
        registered (:func:`hystcomp.identify.parts.register`); default all
        of :data:`EFFECTS`.
    validation : float
        Fraction of the record held out (not fitted; every effect is judged
        on it).
    max_effects : int
        At most this many effects are added.
    base : "pi" or PI
        The base model: ``"pi"`` (thresholds ``i/N`` of the largest input
        excursion from the origin, N = `n_thresholds`; on a record whose
        span is less than 1.5 times that excursion, a unipolar stroke, N - 4
        of them below half the span and 4 above, see
        :func:`~hystcomp.diagnose.base.play_thresholds`) or a
        :class:`~hystcomp.models.PI` whose thresholds are used.
    n_thresholds : int
        Number of plays of the default base model.  A base model above the
        explained bound (before the search) and a final model above it (at
        its end) are refitted with twice as many (:attr:`Diagnosis.finer_core`;
        not with `base` given as a PI).
    progress : bool
        Progress lines on stderr.
    time : str or None
        With a DataFrame: the time column (or the index's name); None for a
        record without a time axis.
    input, output : str
        With a DataFrame: the input and measured-output columns.
    held_out : {"auto", "last", "blocks"}
        Which part is held out: ``"last"`` the record's end; ``"blocks"``
        five blocks spread over the record after its first 30 % (see
        :func:`hystcomp.diagnose.record.spread_blocks`): a drift or gain
        drift of no set shape is then judged by interpolation between
        fitted stretches; ``"auto"`` (default) the end, unless its input
        leaves the rest's range by more than 5 % of the span (a record whose
        amplitude grows to the end) or, on a timed record, moves more than
        twice as fast as the rest (the 99th percentiles of the input's rate:
        a chirp's fast end): then a block of the same length inside the
        record whose input stays within the rest's range and rate (see
        :func:`hystcomp.diagnose.record.inner_block`; the report says so and
        :attr:`Diagnosis.validation` gives where).  When that leaves the
        record unexplained with no drift or gain drift named, ``"auto"``
        re-judges it on blocks and reports the blocks' diagnosis if it
        names a drift or gain drift and leaves fewer noise floors
        (:attr:`Diagnosis.other_split` has the other split's verdict).
    workers : int or None
        Candidate fits of a step run side by side: in forked processes
        where :func:`hystcomp.identify.parallel_fits.can_fork` (Linux, a
        process with no other thread), else on threads.  None (the
        default): :func:`default_workers`, 2 when this process may run on
        two or more cores, else 1.  The diagnosis is the same with any
        number and either kind; with 2 on two cores the benchmark's record
        searched twice took 0.65 of one worker's time in processes, 0.82
        on threads (``benchmarks/bench_diagnose.py --workers 1 2``).  Pass 1 when
        several records are diagnosed in parallel processes already
        (:func:`diagnose_many` with an executor does).

    Returns
    -------
    Diagnosis

    Examples
    --------
    >>> from hystcomp.datasets import hidden_effect_data
    >>> d = hidden_effect_data("drift", seed=3, dt=0.01)
    >>> rep = diagnose(d.t, d.v, d.y, progress=False)
    >>> rep.effects[0], rep.verdict, rep.rms_after < 0.5 * rep.rms_before
    ('drift', 'explained', True)

    The same record as a DataFrame with a datetime time column:

    >>> import pandas as pd
    >>> df = pd.DataFrame({"time": pd.Timestamp("2024-05-01 12:00") + pd.to_timedelta(d.t, unit="s"),
    ...                    "volt": d.v, "um": d.y})
    >>> diagnose(df, time="time", input="volt", output="um", effects=["drift"],
    ...          progress=False).effects
    ['drift']
    """
    from .._validation import check_choice
    from ..models import PI

    from ..identify._records import _frame_record, _is_frame
    from ..identify.parts import PARTS

    if _is_frame(t):
        t, v, y, _ = _frame_record(t, time, input, output, v, y, what="t")
    elif v is None or y is None:
        raise TypeError("Parameters v and y are missing; pass diagnose(t, v, y) with arrays or "
                        "diagnose(frame, time=..., input=..., output=...) with a DataFrame")

    effects = list(effects)
    known = tuple(EFFECTS) + tuple(sorted({c.effect for c in PARTS.values() if c.effect not in EFFECTS}))
    for e in effects:
        check_choice(e, "effects", known)
    if int(max_effects) != max_effects or max_effects < 0:
        raise ValueError(f"Parameter max_effects is {max_effects} but should be an integer >= 0")
    thresholds = None
    if isinstance(base, PI):
        thresholds = base.thresholds
    elif not (isinstance(base, str) and base == "pi"):
        raise ValueError(f"Parameter base is {base!r} but should be 'pi' or a PI model")
    check_choice(held_out, "held_out", HELD_OUT)
    n_thresholds = int(n_thresholds)
    if n_thresholds < 2:
        raise ValueError(f"Parameter n_thresholds is {n_thresholds} but should be >= 2")
    if workers is None:
        workers = default_workers()
    if isinstance(workers, bool) or not isinstance(workers, (int, np.integer)) or workers < 1:
        raise ValueError(f"Parameter workers is {workers!r} but should be None or an integer >= 1")
    # the inner solves are many small dense products (tall n x ~25 matrices): a
    # multi-threaded BLAS only adds contention on a shared machine (10-100x
    # slower under load, measured), so the search runs with one BLAS thread
    try:
        from threadpoolctl import threadpool_limits
    except ImportError:         # optional: without it the BLAS keeps its threads
        import contextlib

        limit = contextlib.nullcontext()
    else:
        limit = threadpool_limits(limits=1, user_api="blas")
    with limit:
        kw = run_search(t, v, y, effects, validation, int(max_effects), n_thresholds, thresholds, progress,
                        held_out, int(workers))
    return Diagnosis(**kw)


def evidence(t, v, y, model=None, validation=0.3, held_out="auto"):
    """The signature tests of every effect on a model's residual (default:
    the base PI model fitted on the training part).

    Parameters
    ----------
    t : array_like or None
        Time [s], or None without a time axis.
    v, y : array_like, shape (n,)
        Input and measured output.
    model : model, optional
        A model whose ``simulate(v)`` predicts y (e.g. :attr:`Diagnosis.model`);
        default the base PI model.
    validation : float
        Fraction held out (not used to fit the default model).
    held_out : {"auto", "last", "blocks"}
        Which part is held out, as in :func:`diagnose` (``"auto"`` without
        the re-judging on blocks).

    Returns
    -------
    dict
        effect -> dict with ``signature``, ``statistic`` (in noise floors),
        ``threshold``, ``present``, ``testable``, ``where``, ``reading``.

    Examples
    --------
    >>> from hystcomp.datasets import hidden_effect_data
    >>> d = hidden_effect_data("saturation", seed=0, dt=0.01, mechanism="cubic")
    >>> ev = evidence(d.t, d.v, d.y)
    >>> ev["saturation"]["present"], ev["creep"]["present"]
    (True, False)
    """
    from ..identify.search import Structure, VariableProjection
    from .noise import noise_floor
    from .record import Record
    from .base import base_context
    from .signatures import evidence as _evidence

    rec = Record(t, v, y, validation, held_out)
    ctx = base_context(rec)
    base = VariableProjection(ctx, rec.y, rec.train).evaluate(Structure(), {}).prediction
    sigma, _ = noise_floor(rec, rec.y - base)
    pred = base if model is None else (rec.output_sign * np.asarray(model.simulate(rec.v), dtype=np.float64)
                                       - rec.y_offset)
    return _evidence(rec, rec.y - pred, pred, sigma)


# the public objects belong to hystcomp.diagnose (documented API and docstring checks)
Diagnosis.__module__ = __name__
for _f in (add_arguments, load_csv, run):
    _f.__module__ = __name__
del _f


from .many import diagnose_many  # noqa: E402  (it calls diagnose)

"""Comparison of closed-loop scenarios: :func:`compare`, :class:`Comparison`,
:func:`loop_width` and :func:`plot_comparison`, re-exported (and documented)
by :mod:`hystcomp.loops`.
"""

import csv
import sys
import time
from concurrent.futures import as_completed

import numpy as np

from ._validation import as_choices, as_count, as_pair, as_signal, check_choice

def loop_width(reference, output, n_bins=100):
    """Width of the output-vs-reference loop.

    The largest spread of the tracking error ``y - r`` among samples whose
    reference values fall in the same bin (`n_bins` bins over the
    reference's span): 0 for perfect tracking, the vertical width of the
    hysteresis loop for an uncompensated actuator (a pure lag also opens
    the loop).

    Parameters
    ----------
    reference : array_like, shape (n,)
        Reference samples r.
    output : array_like, shape (n,)
        Output samples y.
    n_bins : int, optional
        Number of bins over the reference's span (default 100).

    Returns
    -------
    float
        The loop width, in output units.

    Examples
    --------
    >>> import numpy as np
    >>> r = np.sin(np.linspace(0, 4 * np.pi, 4001))
    >>> round(loop_width(r, r + 0.1 * np.sign(np.gradient(r))), 6)
    0.2
    """
    r = as_signal(reference, "reference")
    y = as_signal(output, "output")
    if y.size != r.size:
        raise ValueError(f"Parameter output has {y.size} samples but reference has {r.size}; expected "
                         "one output sample per reference sample")
    n_bins = as_count(n_bins, "n_bins", 1)
    e = y - r
    span = r.max() - r.min()
    if span == 0:
        return float(e.max() - e.min())
    idx = np.minimum(((r - r.min()) / span * n_bins).astype(np.int64), n_bins - 1)
    hi = np.full(n_bins, -np.inf)
    lo = np.full(n_bins, np.inf)
    np.maximum.at(hi, idx, e)
    np.minimum.at(lo, idx, e)
    ok = np.isfinite(hi)
    return float(np.max(hi[ok] - lo[ok]))


_FIELDS = ("scenario", "label", "engine", "rms", "max", "rms_percent", "max_percent", "loop_width",
           "loop_width_percent", "seconds")


class Comparison:
    """Result of :func:`compare`.

    Printing it shows the table; every parameter is kept as the attribute
    of the same name.

    Parameters
    ----------
    rows : list of dict
        One per scenario: ``scenario``, ``label``, ``engine``, ``rms``,
        ``max`` (tracking error y - r), ``rms_percent``, ``max_percent`` (of
        the reference span), ``loop_width`` (:func:`loop_width`),
        ``loop_width_percent``, ``seconds`` (simulation wall time).
    responses : dict
        scenario name -> :class:`control.TimeResponseData`.
    reference, t : ndarray
        The reference and its time vector.

    Examples
    --------
    >>> import numpy as np
    >>> from hystcomp import PI
    >>> from hystcomp.iosys import piezo_stage
    >>> from hystcomp.loops import build_loop, compare
    >>> loop = build_loop("open_loop", PI([1.0], [0.5], p0=1.0), piezo_stage(), dt=1e-4)
    >>> t = np.arange(2000) * 1e-4
    >>> result = compare([loop], t, 2 * np.sin(2 * np.pi * 5 * t))
    >>> isinstance(result, Comparison), [row["scenario"] for row in result.rows]
    (True, ['open_loop'])
    >>> print(str(result).splitlines()[0])
    scenario               engine                RMS       max    RMS %    max %     width  width %
    """

    def __init__(self, rows, responses, reference, t):
        self.rows = rows
        self.responses = responses
        self.reference = reference
        self.t = t

    def row(self, name):
        """The table row of one scenario.

        Parameters
        ----------
        name : str
            Scenario (loop) name.

        Returns
        -------
        dict
            See :class:`Comparison`'s `rows`.

        Raises
        ------
        KeyError
            If no row has that name (the message lists the names).

        Examples
        --------
        >>> c = Comparison([{"scenario": "open_loop", "rms": 0.5}], {}, None, None)
        >>> c.row("open_loop")["rms"]
        0.5
        """
        for row in self.rows:
            if row["scenario"] == name:
                return row
        raise KeyError(f"no scenario {name!r}; have {[r['scenario'] for r in self.rows]}")

    def __str__(self):
        head = (f"{'scenario':22s} {'engine':15s} {'RMS':>9s} {'max':>9s} {'RMS %':>8s} {'max %':>8s} "
                f"{'width':>9s} {'width %':>8s}")
        lines = [head, "-" * len(head)]
        for row in self.rows:
            lines.append(
                f"{row['scenario']:22s} {row['engine']:15s} {row['rms']:9.4g} {row['max']:9.4g} "
                f"{row['rms_percent']:8.3g} {row['max_percent']:8.3g} {row['loop_width']:9.4g} "
                f"{row['loop_width_percent']:8.3g}"
            )
        return "\n".join(lines)

    def to_csv(self, path, extra=None):
        """Write the table as CSV.

        Parameters
        ----------
        path : str or path-like
            The CSV file to write (overwritten).
        extra : dict, optional
            Constant columns put before the table's (e.g. the model's name).

        Examples
        --------
        >>> import os, tempfile
        >>> row = dict(scenario="open_loop", label="open loop", engine="compiled", rms=0.1,
        ...            max=0.2, rms_percent=2.5, max_percent=5.0, loop_width=0.3,
        ...            loop_width_percent=7.5, seconds=0.01)
        >>> path = os.path.join(tempfile.mkdtemp(), "loops.csv")
        >>> Comparison([row], {}, None, None).to_csv(path, extra={"model": "PI"})
        >>> print(open(path).read().splitlines()[1])
        PI,open_loop,open loop,compiled,0.1,0.2,2.5,5.0,0.3,7.5,0.01
        """
        extra = dict(extra or {})
        with open(path, "w", newline="") as fh:
            writer = csv.DictWriter(fh, fieldnames=list(extra) + list(_FIELDS))
            writer.writeheader()
            for row in self.rows:
                writer.writerow({**extra, **{k: row[k] for k in _FIELDS}})


def _run_scenario(loop, t, r, engine, span):
    """One row of :func:`compare` and its response (module level, so that
    an executor can run it in another process)."""
    from .loops import _LABELS, compiled_support

    eng = engine
    if eng == "auto":
        eng = "compiled" if compiled_support(loop) is None else "python-control"
    t0 = time.perf_counter()
    resp = loop.simulate(t, r, engine=eng)
    secs = time.perf_counter() - t0
    y = np.asarray(resp.outputs)[0]
    e = y - r
    rms = float(np.sqrt(np.mean(e * e)))
    mx = float(np.max(np.abs(e)))
    width = loop_width(r, y)
    row = dict(scenario=loop.name, label=_LABELS.get(loop.scenario, loop.scenario), engine=eng,
               rms=rms, max=mx, rms_percent=100 * rms / span, max_percent=100 * mx / span,
               loop_width=width, loop_width_percent=100 * width / span, seconds=secs)
    return row, resp


def compare(scenarios, timepts=None, inputs=None, engine="auto", progress=None, executor=None, **deprecated):
    """Run scenarios on one reference and tabulate their tracking.

    Parameters
    ----------
    scenarios : dict of Loop, or iterable of Loop
        The loops to run (a dict from :func:`build_scenarios`).
    timepts : array_like, shape (n,)
        Uniform time vector with the loops' step (python-control's order:
        ``timepts, inputs``; the old order ``(reference, t)`` and the
        keywords ``reference=``, ``t=`` still work with a
        DeprecationWarning).
    inputs : array_like, shape (n,)
        Reference samples r.
    engine : {"auto", "compiled", "python-control"}
        "auto": :func:`simulate_loop` where the blocks have compiled
        kernels, python-control's simulation otherwise.
    progress : callable, optional
        Called as ``progress(done, total, name)`` after each scenario.
    executor : concurrent.futures.Executor, optional
        Runs the scenarios in parallel (a ``ProcessPoolExecutor``, or
        ``distributed.Client(...).get_executor()`` for dask); None runs them
        one after the other.  The loops and results pickle, and the rows are
        identical either way (in the scenarios' order).

    Returns
    -------
    Comparison
        Table rows and each scenario's :class:`control.TimeResponseData`.

    Examples
    --------
    >>> import numpy as np
    >>> from hystcomp import PI
    >>> from hystcomp.iosys import compensator_system, piezo_stage
    >>> act = PI([1.0, 2.0], [0.5, 0.25], p0=1.0)
    >>> from hystcomp.loops import build_scenarios
    >>> loops = build_scenarios(act, piezo_stage(), compensator=compensator_system(act), dt=1e-4)
    >>> t = np.arange(2000) * 1e-4
    >>> result = compare(loops, t, 2 * np.sin(2 * np.pi * 5 * t))
    >>> [row["engine"] for row in result.rows]
    ['compiled', 'compiled']
    >>> bool(result.row("feedforward")["loop_width"] < result.row("open_loop")["loop_width"] / 10)
    True
    """
    from .loops import _time_and_reference

    from .loops import Loop

    check_choice(engine, "engine", ("auto", "compiled", "python-control"))
    if isinstance(scenarios, (str, bytes)) or not hasattr(scenarios, "__iter__"):
        raise TypeError(f"Parameter scenarios is {scenarios!r} but should be a dict or list of Loop")
    loops = list(scenarios.values()) if isinstance(scenarios, dict) else list(scenarios)
    keys = list(scenarios) if isinstance(scenarios, dict) else range(len(loops))
    for key, loop in zip(keys, loops):
        if not isinstance(loop, Loop):
            raise TypeError(f"Parameter scenarios[{key!r}] is {loop!r} ({type(loop).__name__}) "
                            "but should be a Loop (see build_scenarios)")
    if not loops:
        raise ValueError("Parameter scenarios is empty; pass at least one Loop")
    t, r = _time_and_reference(loops[0], timepts, inputs, deprecated, "compare")
    span = float(r.max() - r.min()) or 1.0
    if executor is None:
        results = []
        for j, loop in enumerate(loops):
            results.append(_run_scenario(loop, t, r, engine, span))
            if progress is not None:
                progress(j + 1, len(loops), loop.name)
    else:
        if not hasattr(executor, "submit"):
            raise TypeError(f"Parameter executor is {executor!r}; expected a concurrent.futures.Executor "
                            "(an object with submit()) or None")
        futures = [executor.submit(_run_scenario, loop, t, r, engine, span) for loop in loops]
        index = {f: j for j, f in enumerate(futures)}
        done = 0
        for f in as_completed(futures):
            done += 1
            if progress is not None:
                progress(done, len(loops), loops[index[f]].name)
        results = [f.result() for f in futures]
    rows = [row for row, _ in results]
    responses = {loop.name: resp for loop, (_, resp) in zip(loops, results)}
    return Comparison(rows, responses, r, t)


def plot_comparison(comparison, title=None, scenarios=None, time_window=None):
    """Tracking, tracking error and y-vs-r loops of a :class:`Comparison`.

    Parameters
    ----------
    comparison : Comparison
        The result of :func:`compare`.
    title : str, optional
        Figure title.
    scenarios : iterable of str, optional
        Scenarios to draw, in this order; default every row.
    time_window : (float, float), optional
        (t0, t1) limits of the two time panels (the loops panel shows every
        sample).

    Returns
    -------
    matplotlib.figure.Figure
        Three panels: reference and outputs in time, errors y - r in time,
        output against reference.

    Examples
    --------
    >>> import numpy as np
    >>> from hystcomp import PI
    >>> from hystcomp.iosys import piezo_stage
    >>> from hystcomp.loops import build_loop
    >>> loop = build_loop("open_loop", PI([1.0], [0.5], p0=1.0), piezo_stage(), dt=1e-4)
    >>> t = np.arange(1000) * 1e-4
    >>> fig = plot_comparison(compare([loop], t, np.sin(2 * np.pi * 10 * t)), title="open loop")
    >>> [ax.get_title() for ax in fig.axes]
    ['tracking', 'tracking error', 'y against r']
    """
    from .plotting import new_figure

    if not isinstance(comparison, Comparison):
        raise TypeError(f"Parameter comparison is {comparison!r} ({type(comparison).__name__}) but should "
                        "be a Comparison (the result of compare)")
    have = [row["scenario"] for row in comparison.rows]
    names = as_choices(scenarios, "scenarios", have)
    if time_window is not None:
        time_window = as_pair(time_window, "time_window")
    fig, axes = new_figure(1, 3, size=(15, 4.6))
    t, r = comparison.t, comparison.reference
    axes[0].plot(t, r, "k--", lw=1.2, label="reference r")
    for name in names:
        row = comparison.row(name)
        y = np.asarray(comparison.responses[name].outputs)[0]
        lab = f"{row['label']} ({row['rms_percent']:.2g} % RMS)"
        axes[0].plot(t, y, lw=0.9, label=lab)
        axes[1].plot(t, y - r, lw=0.9, label=row["label"])
        axes[2].plot(r, y, lw=0.7, label=row["label"])
    lim = [r.min(), r.max()]
    axes[2].plot(lim, lim, "k--", lw=1, label="y = r")
    axes[0].set(xlabel="time t [s]", ylabel="position y", title="tracking")
    axes[1].set(xlabel="time t [s]", ylabel="error y - r", title="tracking error")
    axes[2].set(xlabel="reference r", ylabel="position y", title="y against r")
    axes[0].legend(fontsize=7, loc="upper right")
    axes[2].legend(fontsize=7, loc="upper left")
    for ax in axes:
        ax.grid(True, alpha=0.3)
    if time_window is not None:
        axes[0].set_xlim(*time_window)
        axes[1].set_xlim(*time_window)
    if title:
        fig.suptitle(title)
    return fig


def _stderr_progress(done, total, name):  # pragma: no cover - cosmetic
    bar = "#" * int(30 * done / total)
    sys.stderr.write(f"\r[{bar:30s}] {done}/{total} {name:24s}")
    if done == total:
        sys.stderr.write("\n")
    sys.stderr.flush()


# documented and pickled as hystcomp.loops.* (their public home)
for _obj in (loop_width, Comparison, compare, plot_comparison):
    _obj.__module__ = "hystcomp.loops"
del _obj

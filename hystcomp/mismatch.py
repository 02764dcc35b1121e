"""Compensation under parameter mismatch: identify, compensate, run against the truth.

The thesis leaves "compensation error under parameter mismatch" as future work. This
module measures it: for each seed, the true actuator is driven by an identification input,
its output is recorded with sensor noise, a model is fitted to that record
(:func:`hystcomp.identify.fit_weights`), a compensator is built from the *fitted* model, and
the loops (inverse feedforward, PID + compensator, feedforward + PID + compensator) run
against the *true* actuator. The spread of the tracking errors over the seeds is what
identification noise costs; the same loops with a compensator built from the true model
give the floor (:attr:`MismatchStudy.nominal`).

Every seed is an independent job, so :func:`mismatch_study` takes ``executor=``: any
:class:`concurrent.futures.Executor` (a process pool, or dask's
``distributed.Client(...).get_executor()``) runs them in parallel with results identical to
a serial run.
"""

import warnings

import numpy as np

from ._validation import as_count, as_scalar, as_signal, check_simulates
from .iosys import compensator_system
from .loops import build_scenarios, compare

__all__ = ["mismatch_study", "MismatchStudy", "identification_input"]

#: scenarios a mismatch study reports (they are the ones that use the compensator)
STUDIED = ("feedforward", "feedback_compensated", "two_dof")


def identification_input(input_range, n_samples=20_000, n_cycles=10):
    """A record that exercises the whole input range and nested minor loops.

    Sines about the middle of `input_range` whose amplitude decays linearly from the
    full half-range to 0.2 of it over `n_cycles` cycles, starting at the middle (a
    rate-independent model needs no time axis, so none is returned).

    Parameters
    ----------
    input_range : (float, float)
        (lo, hi) with lo < hi, the actuator input range of the study.
    n_samples : int
        Number of samples.
    n_cycles : int
        Number of sine cycles.

    Returns
    -------
    ndarray, shape (n_samples,)

    Examples
    --------
    >>> v = identification_input((-2.0, 2.0), n_samples=1000)
    >>> bool(abs(v.max() - 2.0) < 0.05), float(v[0])
    (True, 0.0)
    """
    lo, hi = _input_range(input_range)
    n = as_count(n_samples, "n_samples", 1)
    n_cycles = as_count(n_cycles, "n_cycles", 1)
    s = np.arange(n) / n
    mid, half = 0.5 * (lo + hi), 0.5 * (hi - lo)
    return mid + half * (1 - 0.8 * s) * np.sin(2 * np.pi * n_cycles * s)


def _iterable(x, name):
    try:
        return list(x)
    except TypeError:
        raise TypeError(f"Parameter {name} is {x!r} but should be a list") from None


def _input_range(input_range):
    try:
        lo, hi = float(input_range[0]), float(input_range[1])
    except (TypeError, IndexError, ValueError):
        raise ValueError(f"Parameter input_range is {input_range!r} but should be (lo, hi)") from None
    if not (np.isfinite(lo) and np.isfinite(hi) and lo < hi):
        raise ValueError(f"Parameter input_range is {input_range!r} but should be finite with lo < hi")
    return lo, hi


def _loops_with(compensator_model, true_model, plant, controller, dt, input_range):
    comp = compensator_system(compensator_model, nominal_gain="auto", input_range=input_range)
    return build_scenarios(true_model, plant, controller=controller, compensator=comp, dt=dt,
                           scenarios=("feedforward", "feedback_compensated", "two_dof"))


def _one_seed(seed, true_model, plant, controller, reference, t, dt, input_range, v_id, noise,
              fit_options):
    """Fit on one noisy record and run the loops against the true actuator."""
    from .identify import fit_weights

    rng = np.random.default_rng(seed)
    y_true = true_model.simulate(v_id)
    y = y_true + noise * np.ptp(y_true) * rng.standard_normal(len(v_id))
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        fit = fit_weights(v_id, y, **fit_options)
    model_error = fit.model.simulate(v_id) + fit.offset - y_true
    loops = _loops_with(fit.model, true_model, plant, controller, dt, input_range)
    result = compare(loops, t, reference)
    row = dict(seed=int(seed), model_rms=float(np.sqrt(np.mean(model_error ** 2))))
    for r in result.rows:
        row[r["scenario"]] = r["rms_percent"]
    return row, sorted({str(w.message) for w in caught})


class MismatchStudy:
    """Tracking errors of compensators built from identified (mismatched) models.

    Returned by :func:`mismatch_study`; the constructor only stores its arguments.

    Parameters
    ----------
    rows : list of dict
        One per seed: ``seed``, ``model_rms`` (RMS of fitted minus true model output on
        the identification input, in output units) and the RMS tracking error of each
        scenario in % of the reference span (keys ``feedforward``,
        ``feedback_compensated``, ``two_dof``).
    nominal : dict
        The same scenarios with the compensator built from the true model.
    noise : float
        Sensor noise of the identification records, as a fraction of the output span.

    Examples
    --------
    >>> s = MismatchStudy([dict(seed=0, model_rms=0.1, feedforward=0.5)], dict(feedforward=0.1), 0.01)
    >>> s.summary()["feedforward"]["median"]
    0.5
    """

    def __init__(self, rows, nominal, noise):
        if isinstance(rows, (str, bytes, dict)) or not all(isinstance(row, dict) for row in _iterable(rows, "rows")):
            raise TypeError(f"Parameter rows is {rows!r} but should be a list of dicts (one per seed)")
        if not isinstance(nominal, dict):
            raise TypeError(f"Parameter nominal is {nominal!r} but should be a dict (scenario -> error)")
        self.rows, self.nominal = list(rows), nominal
        self.noise = as_scalar(noise, "noise", nonnegative=True)

    def errors(self, scenario):
        """RMS tracking errors (% of span) of one scenario over the seeds.

        Parameters
        ----------
        scenario : str
            One of the scenarios in the rows.

        Returns
        -------
        ndarray

        Examples
        --------
        >>> MismatchStudy([dict(seed=0, feedforward=0.5)], {}, 0.01).errors("feedforward").tolist()
        [0.5]
        """
        if not self.rows or scenario not in self.rows[0]:
            known = sorted(k for k in (self.rows[0] if self.rows else {}) if k not in ("seed", "model_rms"))
            raise ValueError(f"Parameter scenario is {scenario!r}; the study has {known}")
        return np.array([r[scenario] for r in self.rows])

    def summary(self):
        """Median, 90th percentile and maximum of each scenario's error, with the nominal.

        Returns
        -------
        dict
            scenario -> dict(nominal, median, p90, max), in % of the reference span.

        Examples
        --------
        >>> MismatchStudy([dict(seed=0, feedforward=0.5)], dict(feedforward=0.1), 0.01).summary()
        {'feedforward': {'nominal': 0.1, 'median': 0.5, 'p90': 0.5, 'max': 0.5}}
        """
        out = {}
        for sc in [k for k in self.rows[0] if k not in ("seed", "model_rms")]:
            e = self.errors(sc)
            out[sc] = dict(nominal=self.nominal.get(sc), median=float(np.median(e)),
                           p90=float(np.percentile(e, 90)), max=float(e.max()))
        return out

    def __str__(self):
        lines = [f"compensation under mismatch: {len(self.rows)} identifications at sensor noise "
                 f"{100 * self.noise:.3g} % of the output span; RMS tracking error, % of the reference span",
                 f"{'scenario':24s} {'nominal':>9s} {'median':>9s} {'90 %':>9s} {'max':>9s}"]
        for sc, d in self.summary().items():
            nom = "-" if d["nominal"] is None else f"{d['nominal']:.4g}"
            lines.append(f"{sc:24s} {nom:>9s} {d['median']:9.4g} {d['p90']:9.4g} {d['max']:9.4g}")
        return "\n".join(lines)

    def plot(self, ax=None):
        """Each scenario's errors over the seeds (points) with the nominal (bar).

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Where to draw (a new figure's axes if None).

        Returns
        -------
        matplotlib Axes

        Examples
        --------
        >>> import matplotlib
        >>> matplotlib.use("Agg")
        >>> ax = MismatchStudy([dict(seed=0, feedforward=0.5)], dict(feedforward=0.1), 0.01).plot()
        >>> ax.get_ylabel()
        'RMS tracking error [% of span]'
        """
        if ax is None:
            from matplotlib.figure import Figure

            ax = Figure(figsize=(6.4, 4.0), layout="constrained").subplots()
        scen = list(self.summary())
        rng = np.random.default_rng(0)
        for i, sc in enumerate(scen):
            e = self.errors(sc)
            ax.plot(i + 0.12 * rng.uniform(-1, 1, e.size), e, "o", ms=4, alpha=0.7,
                    color=f"C{i}", label="compensator from a fitted model (one per seed)" if i == 0 else None)
            if self.nominal.get(sc) is not None:
                ax.hlines(self.nominal[sc], i - 0.3, i + 0.3, color="k", lw=2,
                          label="compensator from the true model" if i == 0 else None)
        ax.set_xticks(range(len(scen)), [s.replace("_", " ") for s in scen])
        ax.set_yscale("log")
        ax.set_ylabel("RMS tracking error [% of span]")
        ax.set_title(f"{len(self.rows)} identifications, sensor noise {100 * self.noise:.3g} % of span")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(loc="lower left", fontsize="small")
        return ax


def mismatch_study(true_model, plant, controller, reference, t, input_range, n_seeds=10, noise=0.002,
                   identification=None, fit_options=None, executor=None, progress=None):
    """Identify the actuator from noisy records and run compensated loops against the truth.

    Parameters
    ----------
    true_model : HysteresisModel
        The actuator that makes the records and sits in the loops.
    plant : control.StateSpace or control.TransferFunction
        The stage after the actuator (e.g. :func:`hystcomp.iosys.piezo_stage`).
    controller : control system
        The feedback controller (e.g. from :func:`hystcomp.design.design_pid`).
    reference : array_like, shape (n,)
        Reference of the loops.
    t : array_like, shape (n,)
        Uniform time vector of the loops; its step is the loops' sampling time.
    input_range : (float, float)
        Actuator input range: of the identification input and of the compensators'
        nominal gain (``nominal_gain="auto"``).
    n_seeds : int
        Number of noisy identification records (seeds 0 .. n_seeds - 1).
    noise : float
        Sensor noise std as a fraction of the output span (>= 0).
    identification : array_like, optional
        The identification input; default :func:`identification_input` over `input_range`.
    fit_options : dict, optional
        Keyword arguments of :func:`hystcomp.identify.fit_weights`; default: the true
        model's structure (``model="mgpi"`` with its envelope when it is a symmetric mGPI,
        else ``model="pi"``) and its thresholds, so the mismatch comes from the noise only.
        Pass e.g. ``dict(model="pi")`` to add a structural mismatch.
    executor : concurrent.futures.Executor, optional
        Runs the seeds in parallel; None runs them one after the other.
    progress : callable, optional
        Called as ``progress(done, total)`` after each seed.

    Returns
    -------
    MismatchStudy

    Examples
    --------
    >>> import numpy as np
    >>> from hystcomp import PI
    >>> from hystcomp.iosys import piezo_stage, pid
    >>> act = PI([0.5, 1.0, 1.5], [0.3, 0.2, 0.1], p0=1.0)
    >>> t = np.arange(2000) * 1e-4
    >>> study = mismatch_study(act, piezo_stage(), pid(0.0, 40.0, 0.0, dt=1e-4), np.sin(2 * np.pi * 5 * t), t,
    ...                        (-2.0, 2.0), n_seeds=2, noise=0.0, identification=np.sin(np.linspace(0, 40, 4000)) * 2)
    >>> bool(np.allclose(study.errors("feedforward"), study.nominal["feedforward"], rtol=1e-6))
    True
    """
    from concurrent.futures import as_completed

    from .models import MGPI, PI

    check_simulates(true_model, "true_model")
    lo, hi = _input_range(input_range)
    r = as_signal(reference, "reference")
    t = as_signal(t, "t")
    if t.size != r.size or t.size < 2:
        raise ValueError(f"Parameter t has {t.size} samples but reference has {r.size} (need equal, >= 2)")
    dt = float(t[1] - t[0])
    n = as_count(n_seeds, "n_seeds", 1)
    if fit_options is not None and not isinstance(fit_options, dict):
        raise TypeError(f"Parameter fit_options is {fit_options!r} but should be a dict of keyword "
                        "arguments for hystcomp.identify.fit, or None")
    noise = as_scalar(noise, "noise")
    if noise < 0:
        raise ValueError(f"Parameter noise is {noise!r} but should be >= 0 (a fraction of the output span)")
    v_id = identification_input((lo, hi)) if identification is None else as_signal(identification, "identification")
    if fit_options is None:
        thresholds = getattr(true_model, "thresholds", None)
        fit_options = dict(thresholds=thresholds)
        if isinstance(true_model, MGPI) and not isinstance(true_model, PI) and true_model.symmetric:
            fit_options.update(model="mgpi", envelope=true_model.envelope_left)
        else:
            fit_options.update(model="pi")
    nominal_result = compare(_loops_with(true_model, true_model, plant, controller, dt, (lo, hi)), t, r)
    nominal = {row["scenario"]: row["rms_percent"] for row in nominal_result.rows}
    args = (true_model, plant, controller, r, t, dt, (lo, hi), v_id, noise, dict(fit_options))
    if executor is None:
        results = []
        for k in range(n):
            results.append(_one_seed(k, *args))
            if progress is not None:
                progress(k + 1, n)
    else:
        if not hasattr(executor, "submit"):
            raise TypeError(f"Parameter executor is {executor!r}; expected a concurrent.futures.Executor "
                            "(an object with submit()) or None")
        futures = [executor.submit(_one_seed, k, *args) for k in range(n)]
        for done, _ in enumerate(as_completed(futures), 1):
            if progress is not None:
                progress(done, n)
        results = [f.result() for f in futures]
    # the identification's warnings (e.g. thresholds the input never reaches), once, not per seed
    for message in sorted({m for _, messages in results for m in messages}):
        warnings.warn(f"{message} (in the identifications of mismatch_study)", UserWarning, stacklevel=2)
    return MismatchStudy([row for row, _ in results], nominal, noise)

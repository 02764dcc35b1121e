"""The one result of every identification front end: :class:`FitResult`.

Parameters by name with standard errors and covariance, fit statistics
(RSS, AIC, BIC), a readable :meth:`FitResult.report` and
:meth:`FitResult.to_dict` / :meth:`FitResult.to_json`, in the manner of
lmfit's ``ModelResult``.  :func:`~hystcomp.identify.fit_weights`,
:func:`~hystcomp.identify.fit` and the fits of the other models
(:func:`~hystcomp.identify.fit_preisach`, ...) all return it
(``EnvelopeFitResult`` and ``ModelFit`` are other names of the same class).

Standard errors are the linearised (Gauss-Newton) ones: ``s^2 (J^T W J)^-1``
with ``s^2 = RSS_w / (n - k)`` (n training samples, k free parameters), J the
Jacobian of the prediction with respect to the parameters (for the weights
of a PI/mGPI model the regressor columns, whose Gram matrix the fit has
already built).  Parameters held on an active constraint (a weight at 0, an
unreached threshold) are not free: their standard error is 0 and the
covariance is that of the fit restricted to the constraint's face.  They
assume independent noise of equal variance (or variance ~ 1/weight) and
ignore the bias of a penalty or of a wrong model structure.
"""

import json
import math

import numpy as np


def _jsonable(x):
    if isinstance(x, dict):
        return {str(k): _jsonable(v) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [_jsonable(v) for v in x]
    if isinstance(x, np.ndarray):
        return _jsonable(x.tolist())
    if isinstance(x, (bool, np.bool_)):
        return bool(x)
    if isinstance(x, (np.integer,)):
        return int(x)
    if isinstance(x, (float, np.floating)):
        return float(x) if math.isfinite(x) else None
    return x


def information_criteria(rss, n, k):
    """(AIC, BIC) of a least-squares fit: ``n ln(RSS/n) + 2k`` and
    ``n ln(RSS/n) + k ln n``.

    Parameters
    ----------
    rss : float
        Residual sum of squares over the training samples.
    n : int
        Number of training samples.
    k : int
        Number of free parameters.

    Returns
    -------
    aic, bic : float

    Examples
    --------
    >>> aic, bic = information_criteria(1.0, 100, 3)
    >>> round(aic, 3), round(bic, 3)
    (-454.517, -446.702)
    """
    ll = n * math.log(max(rss / n, np.finfo(float).tiny))
    return ll + 2 * k, ll + k * math.log(n)


def covariance_from_jacobian(J, residual, n_free=None, weights=None, rcond=1e-12):
    """Linearised covariance ``s^2 (J^T W J)^+`` with ``s^2 = RSS_w / (n - k)``.

    Parameters
    ----------
    J : ndarray, shape (n, k)
        Jacobian of the prediction (or of the residual) at the optimum.
    residual : ndarray, shape (n,)
        Residuals at the optimum.
    n_free : int, optional
        Number of free parameters counted in the degrees of freedom
        (default k).
    weights : ndarray, shape (n,), optional
        Sample weights W (default 1).
    rcond : float
        Relative cut-off of the pseudo-inverse.

    Returns
    -------
    ndarray, shape (k, k)

    Examples
    --------
    >>> rng = np.random.default_rng(0)
    >>> J = np.column_stack([np.ones(400), np.linspace(0, 1, 400)])
    >>> e = 0.1 * rng.standard_normal(400)
    >>> np.round(np.sqrt(np.diag(covariance_from_jacobian(J, e))), 3).tolist()
    [0.01, 0.017]
    """
    J = np.asarray(J, dtype=np.float64)
    e = np.asarray(residual, dtype=np.float64)
    w = np.ones(e.size) if weights is None else np.asarray(weights, dtype=np.float64)
    k = J.shape[1] if n_free is None else int(n_free)
    n = int(np.count_nonzero(w))
    dof = max(n - k, 1)
    s2 = float(np.sum(w * e * e)) / dof
    G = J.T @ (J * w[:, None])
    return s2 * np.linalg.pinv(G, rcond=rcond, hermitian=True)


class FitResult:
    """Outcome of an identification (:func:`~hystcomp.identify.fit_weights`,
    :func:`~hystcomp.identify.fit`, :func:`~hystcomp.identify.fit_preisach`,
    :func:`~hystcomp.identify.fit_kp`, :func:`~hystcomp.identify.fit_bouc_wen`,
    :func:`~hystcomp.identify.fit_backlash_like`,
    :func:`~hystcomp.identify.fit_duhem`); ``EnvelopeFitResult`` and
    ``ModelFit`` are other names of this class.

    Attributes
    ----------
    model : HysteresisModel
        The identified model (predictions are ``model.simulate(v) + offset``).
    offset : float
        The fitted output offset kept apart from the model (0 when the model
        carries its own).
    params : dict
        Parameter name -> fitted value (``p0``, ``p1`` .. ``pN``, ``offset``;
        envelope parameters in the coordinates of the search; the shape
        parameters of the other models).
    stderr : dict
        Parameter name -> standard error (0 for a parameter held on a
        constraint, NaN when it could not be estimated).
    covariance : ndarray, shape (k, k)
        Covariance of the parameters in the order of ``params``.
    correlation : ndarray, shape (k, k)
        The covariance as correlations.
    rmse, rss : float
        RMS and sum of squares of the training residuals.
    aic, bic : float
        ``n ln(RSS/n) + 2k`` and ``n ln(RSS/n) + k ln n`` (n training
        samples, k free parameters).
    n_train, n_parameters : int
        Training samples and free parameters.
    residuals : ndarray, pandas.Series or list
        ``y - prediction`` for every sample (one per record; a Series on the
        input's index when the input had one).
    validation : ValidationResult or None
        Errors on held-out samples (front ends that hold data out).
    success, message : bool, str
        Solver (or optimiser) outcome.

    Front ends add their own attributes: ``weights``, ``p0``,
    ``thresholds``, ``envelope``, ``condition``, ``unreached`` (weights);
    ``envelope_parameters``, ``cost``, ``converged``, ``nfev``,
    ``at_bound`` (envelope search); ``fit_time`` (other models).

    Examples
    --------
    >>> import numpy as np
    >>> from hystcomp import PI
    >>> from hystcomp.identify import fit_weights
    >>> rng = np.random.default_rng(1)
    >>> v = 3 * np.sin(np.linspace(0, 20, 3000))
    >>> y = PI([1.0, 2.0], [0.5, 0.2], p0=1.0).simulate(v) + 0.1 + 0.01 * rng.standard_normal(3000)
    >>> res = fit_weights(v, y, thresholds=[1.0, 2.0], model="pi")
    >>> sorted(res.params)
    ['offset', 'p0', 'p1', 'p2']
    >>> bool(abs(res.params["p1"] - 0.5) < 4 * res.stderr["p1"])
    True
    >>> print(res.report().splitlines()[0])
    PI fit: 2 operators, 3000 training samples
    >>> res.to_dict()["params"]["p1"]["stderr"] > 0
    True
    """

    _defaults = dict(offset=0.0, param_names=(), param_values=(), covariance=None, validation=None,
                     message="", success=True, index=None)

    def __init__(self, **kw):
        for k, v in self._defaults.items():
            setattr(self, k, v)
        self.__dict__.update(kw)

    # -- parameters by name -------------------------------------------------
    @property
    def params(self):
        """Parameter name -> fitted value (dict)."""
        return dict(zip(self.param_names, (float(x) for x in self.param_values)))

    @property
    def stderr(self):
        """Parameter name -> standard error (dict; NaN where unknown)."""
        k = len(self.param_names)
        if self.covariance is None:
            return dict(zip(self.param_names, [math.nan] * k))
        d = np.sqrt(np.maximum(np.diag(self.covariance), 0.0))
        d = np.where(np.isfinite(np.diag(self.covariance)), d, np.nan)
        return dict(zip(self.param_names, (float(x) for x in d)))

    @property
    def correlation(self):
        """Correlation matrix of the parameters (NaN where a standard error is 0 or unknown)."""
        if self.covariance is None:
            return None
        s = np.sqrt(np.maximum(np.diag(self.covariance), 0.0))
        with np.errstate(divide="ignore", invalid="ignore"):
            return self.covariance / np.outer(s, s)

    @property
    def rss(self):
        """Training residual sum of squares (``rmse^2 n_train``)."""
        return float(self.rmse) ** 2 * int(self.n_train)

    def predict(self, v, initial_state=None):
        """Model output plus offset for an input record.

        Parameters
        ----------
        v : array_like or pandas.Series, shape (n_samples,)
            Input record.
        initial_state : ndarray, optional
            State of the model at the first sample (default: its virgin
            state, ``model.default_state()``).

        Returns
        -------
        ndarray or pandas.Series, shape (n_samples,)
            ``model.simulate(v) + offset`` (a Series on v's index when v is
            a Series).

        Examples
        --------
        >>> import numpy as np
        >>> from hystcomp import PI
        >>> from hystcomp.identify import fit_weights
        >>> v = 3 * np.sin(np.linspace(0, 20, 3000))
        >>> true = PI([1.0, 2.0], [0.5, 0.2], p0=1.0)
        >>> res = fit_weights(v, true.simulate(v) + 0.1, thresholds=[1.0, 2.0], model="pi")
        >>> bool(np.allclose(res.predict(v[:50]), true.simulate(v[:50]) + 0.1, atol=1e-6))
        True
        """
        from ._records import _index_of, _is_series, _with_index

        index = _index_of(v)
        x = v.to_numpy() if _is_series(v) else v
        out = self.model.simulate(x, initial_state=initial_state) + self.offset
        return _with_index(out, index, "prediction")

    # -- output -------------------------------------------------------------
    def _param_lines(self):
        if not len(self.param_names):
            return []
        if len(self.param_names) > 30:       # a Preisach plane: the cells are in .params
            return [f"  {len(self.param_names)} parameters (by name in .params, e.g. "
                    f"{self.param_names[0]!r}); no listing"]
        err = self.stderr
        width = max(len(n) for n in self.param_names)
        lines = ["  parameters (value +/- standard error):"]
        for name, val in self.params.items():
            e = err[name]
            tail = "(held on a constraint)" if e == 0 else (f"+/- {e:.3g}" if math.isfinite(e) else
                                                            "+/- ?")
            rel = f" ({100 * e / abs(val):.2g} %)" if math.isfinite(e) and e > 0 and val != 0 else ""
            lines.append(f"    {name:<{width}} = {val:12.6g} {tail}{rel}")
        return lines

    def report(self):
        """A readable summary (str): the model, the parameters with their
        standard errors, the fit statistics and the solver outcome.

        Returns
        -------
        str

        Examples
        --------
        >>> import numpy as np
        >>> from hystcomp import PI
        >>> from hystcomp.identify import fit_weights
        >>> v = 3 * np.sin(np.linspace(0, 20, 3000))
        >>> res = fit_weights(v, PI([1.0], [0.5], p0=1.0).simulate(v), thresholds=[1.0], model="pi")
        >>> "rmse" in res.report() and "p1" in res.report()
        True
        """
        lines = []
        if hasattr(self, "envelope_parameters"):
            env = (repr(self.envelope) if self.envelope is not None
                   else f"left {self.envelope_left!r}, right {self.envelope_right!r}")
            head = (f"envelope fit: {env}; parameters {self.envelope_parameters}; "
                    f"cost (training MSE) = {self.cost:.6g}; converged = {self.converged} "
                    f"({self.optimizer_message}); {self.nfev} evaluations")
            if self.at_bound:
                head += f"\n  parameters {self.at_bound} ended on a bound of the search interval"
            lines.append(head)
        if hasattr(self, "thresholds"):
            from ..envelopes import Identity

            lines += [
                f"{type(self.model).__name__} fit: {self.thresholds.size} operators, "
                f"{self.n_train} training samples",
                f"  solver: {self.solver} status={self.status} success={self.success}",
                f"  p0 = {self.p0:.6g}, offset = {self.offset:.6g}",
                f"  weights = {np.array2string(self.weights, precision=4, max_line_width=100)}",
            ]
            if getattr(self, "envelope", None) is not None and not isinstance(self.envelope, Identity):
                lines.insert(len(lines) - 3, f"  envelope: {self.envelope!r}")
        else:
            lines.append(f"{self.model!r}")
        lines += self._param_lines()
        stats = f"  rmse = {self.rmse:.6g}"
        if getattr(self, "aic", None) is not None:
            stats += f"  aic = {self.aic:.6g}  bic = {self.bic:.6g}"
        if getattr(self, "condition", None) is not None:
            stats += f"  condition = {self.condition:.3g}"
        stats += f"  ({self.n_parameters} parameters, {self.n_train} training samples)"
        if getattr(self, "fit_time", None) is not None:
            stats += f"\n  fit time = {self.fit_time:.3g} s, success = {self.success}"
        lines.append(stats)
        unreached = getattr(self, "unreached", None)
        if unreached is not None and unreached.size:
            lines.append(f"  unreached thresholds (weights fixed to 0): {unreached.tolist()}")
        if self.validation is not None:
            val = self.validation
            lines.append(
                f"  validation: rms = {val['rms']:.6g} ({val['rms_percent']:.4g} % of span), "
                f"max = {val['max']:.6g} ({val['max_percent']:.4g} %), n = {val['n']}"
            )
        if self.message:
            lines.append(f"  message: {self.message}")
        return "\n".join(lines)

    def to_dict(self):
        """The result as a JSON-ready dict: the model's repr, the parameters
        (value and standard error), the covariance, the statistics and the
        outcome (no per-sample arrays).

        Returns
        -------
        dict

        Examples
        --------
        >>> import numpy as np
        >>> from hystcomp import PI
        >>> from hystcomp.identify import fit_weights
        >>> v = 3 * np.sin(np.linspace(0, 20, 3000))
        >>> res = fit_weights(v, PI([1.0], [0.5], p0=1.0).simulate(v), thresholds=[1.0], model="pi")
        >>> d = res.to_dict()
        >>> round(d["params"]["p1"]["value"], 6), d["success"]
        (0.5, True)
        """
        err = self.stderr
        out = {"model": repr(self.model), "params": {n: {"value": v, "stderr": err[n]}
                                                      for n, v in self.params.items()},
               "param_names": list(self.param_names),
               "covariance": None if self.covariance is None else np.asarray(self.covariance),
               "offset": self.offset, "rmse": self.rmse, "rss": self.rss,
               "aic": getattr(self, "aic", None), "bic": getattr(self, "bic", None),
               "n_train": self.n_train, "n_parameters": self.n_parameters,
               "success": self.success, "message": self.message}
        for key in ("status", "solver", "condition", "thresholds", "weights", "p0", "envelope_parameters",
                    "cost", "converged", "optimizer_message", "nfev", "at_bound", "fit_time"):
            if hasattr(self, key):
                out[key] = getattr(self, key)
        if hasattr(self, "unreached"):
            out["unreached"] = self.unreached
        if self.validation is not None:
            out["validation"] = {k: v for k, v in self.validation.items() if k != "residuals"}
        return _jsonable(out)

    def to_json(self, **kwargs):
        """:meth:`to_dict` as a JSON string.

        Parameters
        ----------
        **kwargs
            Passed to :func:`json.dumps` (e.g. ``indent=2``).

        Returns
        -------
        str

        Examples
        --------
        >>> import json, numpy as np
        >>> from hystcomp import PI
        >>> from hystcomp.identify import fit_weights
        >>> v = 3 * np.sin(np.linspace(0, 20, 3000))
        >>> res = fit_weights(v, PI([1.0], [0.5], p0=1.0).simulate(v), thresholds=[1.0], model="pi")
        >>> sorted(json.loads(res.to_json())["params"])
        ['offset', 'p0', 'p1']
        """
        return json.dumps(self.to_dict(), **kwargs)

    def __repr__(self):
        return f"{type(self).__name__}(model={self.model!r}, rmse={self.rmse:.4g}, success={self.success})"

"""Envelope parameters by variable projection: :func:`fit`."""

import math
import warnings

import numpy as np

from .._validation import check_choice
from ..envelopes import Atanh, Identity, Linear, Polynomial, Tanh
from ._records import _apply_validation, _frame_arguments, _is_record_list, _is_series, _records
from .solver import _Problem
from ._result import FitResult
from .weights import _attach_index, _check_data, fit_weights

# envelopes by variable projection
# ----------------------------------------------------------------------------
#: the outcome of :func:`fit` is a :class:`FitResult` (this name is kept)
EnvelopeFitResult = FitResult

#: names of the searched envelope parameters (the coordinates of the search)
_ENVELOPE_NAMES = {
    ("tanh", False): ["ln(b V)"], ("atanh", False): ["b V"], ("polynomial", False): ["c2", "c3"],
    ("tanh", True): ["ln(b_l V)", "h_l/V", "ln rho", "ln(b_r V)", "h_r/V"],
    ("atanh", True): ["b_l V", "ln rho", "b_r V"], ("linear", True): ["ln rho"],
    ("polynomial", True): ["c2_l", "c3_l", "ln rho", "c2_r", "c3_r"],
}


def _joint_covariance(out, make, xbest, asymmetric, v, y, sample_weight, validation, bounds):
    """Covariance of the envelope parameters and the weights together, from
    the Jacobian of the prediction (central differences for the envelope
    parameters, the regressor columns for the weights: the prediction is
    linear in them), on the training samples.  Weights at 0 (held by the
    constraint) and envelope parameters on a bound of the search are not
    free (standard error 0 and NaN respectively)."""
    from ..models import MGPI
    from ._result import covariance_from_jacobian

    recs, multi = _records(v, y, sample_weight)
    _apply_validation(recs, validation, multi)
    r = out.thresholds
    xbest = np.asarray(xbest, dtype=np.float64)
    k_env = xbest.size
    theta = np.asarray(out.param_values, dtype=np.float64)[len(xbest):]   # the linear part
    lead = 1
    n_w = r.size

    def predict(x, th):
        e = make(x)
        kw = dict(envelope_left=e[0], envelope_right=e[1]) if asymmetric else dict(envelope=e)
        mdl = MGPI(r, th[lead:lead + n_w], th[0], **kw)
        off = th[lead + n_w] if th.size > lead + n_w else 0.0
        return np.concatenate([mdl.simulate(rec[0]) + off for rec in recs])

    base = predict(xbest, theta)
    cols, free = [], []
    for j in range(k_env):
        lo, hi = bounds[j]
        h = 1e-5 * max(1.0, abs(xbest[j]))
        if j in out.at_bound or not (lo < xbest[j] - h and xbest[j] + h < hi):
            continue
        xp, xm = xbest.copy(), xbest.copy()
        xp[j] += h
        xm[j] -= h
        try:
            cols.append((predict(xp, theta) - predict(xm, theta)) / (2 * h))
        except ValueError:        # a step outside the envelope's domain
            continue
        free.append(j)
    for i in range(theta.size):
        # weights held at 0 by the constraint (or never reached) are not free
        if lead <= i < lead + n_w and abs(theta[i]) <= 1e-9 * max(float(np.max(np.abs(theta))), 1e-300):
            continue
        th = theta.copy()
        th[i] += 1.0
        cols.append(predict(xbest, th) - base)
        free.append(k_env + i)
    w = np.concatenate([rec[2] if rec[2] is not None else np.ones(rec[0].size) for rec in recs])
    yy = np.concatenate([rec[1] for rec in recs])
    J = np.column_stack(cols)
    cov_free = covariance_from_jacobian(J, yy - base, weights=w)
    m = k_env + theta.size
    cov = np.zeros((m, m))
    cov[np.ix_(free, free)] = cov_free
    for j in range(k_env):
        if j not in free:
            cov[j, j] = np.nan
    return cov


def _family(envelope, recs):
    """(make(params) -> Envelope, x0, bounds) for a family name, with the start
    from the data: gamma'(0) = 1 so that weights keep PI units."""
    vmin = min(float(rec[0].min()) for rec in recs)
    vmax = max(float(rec[0].max()) for rec in recs)
    V = max(abs(vmin), abs(vmax))
    if envelope == "tanh":
        # gamma = tanh(b v)/b; start with b V = 1 (mild saturation at the peaks)
        def make(x):
            b = math.exp(x[0]) / V
            return Tanh(1.0 / b, b)
        return make, [0.0], [(math.log(1e-3), math.log(5.0))]
    if envelope == "atanh":
        # gamma = atanh(b v)/b, b V < 1; parameter u = b V in (0, 0.999)
        def make(x):
            b = x[0] / V
            return Atanh(1.0 / b, b)
        return make, [0.5], [(1e-3, 0.999)]
    if envelope == "polynomial":
        # gamma = v + c2 v^2/V + c3 v^3/V^2 on [vmin, vmax] (must increase)
        lo, hi = vmin - 1e-9 * V, vmax + 1e-9 * V

        def make(x):
            return Polynomial([0.0, 1.0, x[0] / V, x[1] / V ** 2], interval=(lo, hi))
        return make, [0.0, 0.0], [(-1.0, 1.0), (-0.3, 1.0)]
    raise ValueError(
        f"Parameter envelope is {envelope!r} but should be 'tanh', 'atanh', 'linear', 'polynomial' "
        "or a (make, x0, bounds) triple"
    )


def _family_asymmetric(envelope, recs):
    """(make(params) -> (gl, gr), x0, bounds) for a family name, left and right
    apart.  A common scale of gl and gr is carried by the weights (the
    modified play is positively homogeneous in its envelopes), so gr is
    normalised and gl carries the ratio rho = (scale of gl) / (scale of gr)."""
    vmin = min(float(rec[0].min()) for rec in recs)
    vmax = max(float(rec[0].max()) for rec in recs)
    V = max(abs(vmin), abs(vmax))
    span = vmax - vmin
    log_rho = (math.log(0.1), math.log(10.0))
    if envelope == "tanh":
        # gl = rho/b_r tanh(b_l (v + h_l)), gr = 1/b_r tanh(b_r (v + h_r)):
        # params [ln(b_l V), h_l/V, ln rho, ln(b_r V), h_r/V]; Tanh(a, b, c)
        # with c = b h (the thesis's 20 tanh(0.1 v + 0.2) has h = 2)
        def make(x):
            bl, br = math.exp(x[0]) / V, math.exp(x[3]) / V
            rho = math.exp(x[2])
            return (Tanh(rho / br, bl, bl * x[1] * V), Tanh(1.0 / br, br, br * x[4] * V))
        lb = (math.log(1e-3), math.log(5.0))
        return make, [0.0, 0.0, 0.0, 0.0, 0.0], [lb, (-0.5, 0.5), log_rho, lb, (-0.5, 0.5)]
    if envelope == "atanh":
        # gl = rho/b_r atanh(b_l v), gr = 1/b_r atanh(b_r v); params [b_l V, ln rho, b_r V]
        def make(x):
            bl, br = x[0] / V, x[2] / V
            return (Atanh(math.exp(x[1]) / br, bl), Atanh(1.0 / br, br))
        return make, [0.5, 0.0, 0.5], [(1e-3, 0.999), log_rho, (1e-3, 0.999)]
    if envelope == "linear":
        # gl = rho v, gr = v
        def make(x):
            return (Linear(math.exp(x[0])), Identity())
        return make, [0.0], [log_rho]
    if envelope == "polynomial":
        # gl = rho (v + c2l v^2/V + c3l v^3/V^2), gr = v + c2r v^2/V + c3r v^3/V^2 on
        # [vmin - span, vmax + span] (the plays evaluate gl(v - r), gr(v + r))
        lo, hi = vmin - span, vmax + span

        def make(x):
            rho = math.exp(x[2])
            return (Polynomial([0.0, rho, rho * x[0] / V, rho * x[1] / V ** 2], interval=(lo, hi)),
                    Polynomial([0.0, 1.0, x[3] / V, x[4] / V ** 2], interval=(lo, hi)))
        return make, [0.0, 0.0, 0.0, 0.0, 0.0], [(-0.3, 0.3), (-0.1, 0.3), log_rho, (-0.3, 0.3),
                                                   (-0.1, 0.3)]
    raise ValueError(
        f"Parameter envelope is {envelope!r} but should be 'tanh', 'atanh', 'linear', 'polynomial' "
        "or a (make, x0, bounds) triple with make(params) -> (envelope_left, envelope_right)"
    )


def fit(v, y=None, envelope="tanh", asymmetric=False, thresholds=None, constraints="nonnegative",
        regularization=None, offset=True, solver=None, sample_weight=None, validation=None,
        n_thresholds=20, maxiter=60, optimizer=None, *, input="v", output="y"):
    """Identify an mGPI model with its envelope by variable projection.

    For each candidate envelope the weights are solved exactly (the convex
    problem of :func:`fit_weights`, compiled once and re-solved with new
    data); scipy.optimize (bounded Powell) minimises the resulting training
    MSE over the envelope parameters.  Envelopes are normalised to
    gamma'(0) = 1, so the weights keep the units of a PI model (their scale
    is carried by the weights, not the envelope).

    Parameters
    ----------
    v, y, thresholds, constraints, regularization, offset, solver, sample_weight, validation, n_thresholds
        As in :func:`fit_weights` (a DataFrame as `v` is the record, its
        columns named by `input` and `output`).
    input, output : str
        With a DataFrame `v`: the input and measured-output columns.
    envelope : {"tanh", "atanh", "linear", "polynomial"} or (make, x0, bounds)
        The family: ``tanh(b v)/b``, ``atanh(b v)/b``, the identity (a PI
        fit: Linear(k) only rescales the weights), or ``v + c2 v^2/V +
        c3 v^3/V^2`` (V = max|v|); or a callable ``make(params) -> Envelope``
        with a start and bounds.
    asymmetric : bool
        Fit the left and right envelopes apart (an asymmetric mGPI model,
        whose p0 is the weight of the r = 0 modified play w_0).  A common
        scale of gl and gr is carried by the weights, so gr is normalised and
        gl carries the ratio rho of the two scales.  Families (V = max|v|):
        "tanh": ``gl = rho/b_r tanh(b_l (v + h_l))``, ``gr = 1/b_r tanh(b_r
        (v + h_r))``, parameters ``[ln(b_l V), h_l/V, ln rho, ln(b_r V),
        h_r/V]``; "atanh": ``gl = rho/b_r atanh(b_l v)``, ``gr = 1/b_r
        atanh(b_r v)``, ``[b_l V, ln rho, b_r V]``; "linear": ``gl = rho v``,
        ``gr = v``, ``[ln rho]``; "polynomial": a cubic per side, ``[c2l,
        c3l, ln rho, c2r, c3r]``.  A custom triple's make returns the pair
        ``(gl, gr)``.
    maxiter : int
        Iterations of the outer optimiser (Powell), or the budget of
        residual evaluations of least squares (its finite-difference
        Jacobians, one evaluation per parameter per step, come on top).
    optimizer : {"powell", "least_squares"}, optional
        The outer optimiser: bounded Powell on the training MSE (default for
        symmetric envelopes) or ``scipy.optimize.least_squares`` (trust-region
        reflective, finite-difference Jacobian of the variable-projection
        residual; default for asymmetric=True, where Powell stalls on the
        five tanh parameters).

    Returns
    -------
    EnvelopeFitResult

    Examples
    --------
    >>> import numpy as np
    >>> from hystcomp import MGPI
    >>> from hystcomp.envelopes import Tanh
    >>> t = np.linspace(0, 2, 4001)
    >>> v = 4 * np.sin(2 * np.pi * t)
    >>> true = MGPI([1.0, 2.0, 3.0], [0.5, 0.3, 0.2], 1.0, envelope=Tanh(1 / 0.3, 0.3))
    >>> res = fit(v, true.simulate(v), thresholds=true.thresholds)
    >>> round(res.envelope.b, 3), bool(res.converged)
    (0.3, True)
    """
    from scipy import optimize

    v, y, index = _frame_arguments(v, y, input, output)
    v, y = _plain(v), _plain(y)
    out = _fit(v, y, envelope, asymmetric, thresholds, constraints, regularization, offset, solver,
               sample_weight, validation, n_thresholds, maxiter, optimizer, optimize)
    return _attach_index(out, index)


def _plain(x):
    """Records without their pandas index (the index is put back on the result)."""
    if _is_record_list(x):
        return [e.to_numpy() if _is_series(e) else e for e in x]
    return x.to_numpy() if _is_series(x) else x


def _fit(v, y, envelope, asymmetric, thresholds, constraints, regularization, offset, solver,
         sample_weight, validation, n_thresholds, maxiter, optimizer, optimize):
    kw = dict(thresholds=thresholds, constraints=constraints, regularization=regularization,
              offset=offset, solver=solver, sample_weight=sample_weight, validation=validation,
              n_thresholds=n_thresholds)
    if envelope == "linear" and not asymmetric:
        res = fit_weights(v, y, model="pi", **kw)
        out = FitResult(**res.__dict__)
        out.envelope_parameters = []
        out.cost, out.converged, out.optimizer_message, out.nfev = res.train_mse, True, \
            "no envelope parameter (Linear(k) only rescales the weights)", 0
        out.at_bound = []
        return out
    recs, _ = _records(v, y, sample_weight)
    # a constant input has no scale to start the envelope search from
    _check_data(recs, 1)
    if isinstance(envelope, tuple):
        make, x0, bounds = envelope
    elif asymmetric:
        make, x0, bounds = _family_asymmetric(envelope, recs)
    else:
        make, x0, bounds = _family(envelope, recs)

    def envs(x):
        e = make(np.asarray(x, float))
        if asymmetric:
            if not (isinstance(e, tuple) and len(e) == 2):
                raise TypeError(f"make(params) returned {e!r} but asymmetric=True needs a pair "
                                "(envelope_left, envelope_right)")
            return dict(envelope_left=e[0], envelope_right=e[1])
        return dict(envelope=e)

    # one problem object: the compiled QP is reused for every candidate
    first = fit_weights(v, y, _warn=False, **envs(x0), **kw)
    prob = _Problem(first.thresholds, constraints, regularization, offset, solver)
    kw["thresholds"] = first.thresholds
    cache = {}

    def cost(x):
        key = tuple(np.round(x, 12))
        if key in cache:
            return cache[key]
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", UserWarning)
                res = fit_weights(v, y, _problem=prob, _warn=False, **envs(x), **kw)
            c = res.train_mse
        except (ValueError, RuntimeError):
            c = np.inf
        cache[key] = c
        return c

    optimizer = check_choice(optimizer or ("least_squares" if asymmetric else "powell"), "optimizer",
                             ("powell", "least_squares"))
    if optimizer == "powell":
        opt = optimize.minimize(cost, np.asarray(x0, float), method="Powell", bounds=bounds,
                                options={"maxiter": maxiter, "xtol": 1e-4, "ftol": 1e-9})
        success, message, nfev, xbest = bool(opt.success), str(opt.message), int(opt.nfev), opt.x
    else:
        # the variable-projection residual sqrt(w_k) (y_k - yhat_k(x)) on the
        # training samples (weights after the validation split)
        wrecs, wmulti = _records(v, y, sample_weight)
        _apply_validation(wrecs, validation, wmulti)
        sw = [np.sqrt(rec[2]) if rec[2] is not None else None for rec in wrecs]
        big = 1e3 * math.sqrt(np.mean(np.concatenate([rec[1] for rec in wrecs]) ** 2) + 1.0)
        n_all = sum(rec[0].size for rec in wrecs)

        def residual(x):
            try:
                with warnings.catch_warnings():
                    warnings.simplefilter("ignore", UserWarning)
                    res = fit_weights(v, y, _problem=prob, _warn=False, **envs(x), **kw)
            except (ValueError, RuntimeError):
                return np.full(n_all, big)
            e = res.residuals if isinstance(res.residuals, list) else [res.residuals]
            return np.concatenate([ej if wj is None else ej * wj for ej, wj in zip(e, sw)])

        lo = np.array([b[0] for b in bounds], float)
        hi = np.array([b[1] for b in bounds], float)
        # finite-difference steps 1e-5 relative: well above the QP solver's
        # ~1e-8 relative noise in the weights, well below the parameters' scale
        opt = optimize.least_squares(residual, np.clip(np.asarray(x0, float), lo, hi), bounds=(lo, hi),
                                     diff_step=1e-5, max_nfev=maxiter)
        success, message, nfev, xbest = bool(opt.status > 0), str(opt.message), int(opt.nfev), opt.x
    res = fit_weights(v, y, **envs(xbest), **kw)
    out = FitResult(**res.__dict__)
    out.envelope_parameters = np.asarray(xbest).tolist()
    out.cost = res.train_mse
    out.converged = success
    out.optimizer_message = message
    out.nfev = nfev
    # parameters that ended on a bound of the search box (e.g. tanh with
    # b -> 0 is the PI model): worth saying, the optimum may lie outside
    out.at_bound = [i for i, (x, (lo, hi)) in enumerate(zip(xbest, bounds))
                    if min(x - lo, hi - x) <= 1e-3 * (hi - lo)]
    names = _ENVELOPE_NAMES.get((envelope, bool(asymmetric)) if isinstance(envelope, str) else None,
                                [f"envelope[{i}]" for i in range(len(xbest))])
    out.param_names = list(names) + list(res.param_names)
    out.param_values = np.concatenate([np.asarray(xbest, dtype=np.float64), res.param_values])
    out.n_parameters = res.n_parameters + len(xbest)
    from ._result import information_criteria

    out.aic, out.bic = information_criteria(out.rss, out.n_train, out.n_parameters)
    try:
        out.covariance = _joint_covariance(out, make, xbest, asymmetric, v, y, sample_weight, validation,
                                           bounds)
    except (ValueError, np.linalg.LinAlgError):
        out.covariance = None
    return out


# ----------------------------------------------------------------------------
# scikit-learn style estimator

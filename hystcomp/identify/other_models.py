"""Identification of other hysteresis models (Preisach, KP, Bouc-Wen, backlash-like, Duhem) and their comparison."""

import math

import numpy as np

from .._validation import as_scalar, as_signal, check_choice
from ._records import _BLOCK
from ._result import FitResult, information_criteria
from .solver import _pick_solver, _split_gram, solve_weights
from .envelope_fit import fit
from .weights import fit_weights

# backlash-like, Duhem, and a side-by-side comparison
# ----------------------------------------------------------------------------
#: the outcome of the fits of this module is a :class:`FitResult` (this name is kept)
ModelFit = FitResult


def _model_fit(model, e, n_parameters, t0, success, message, names, values, covariance=None):
    """The FitResult of a fit whose model carries its own offset."""
    import time

    n = int(e.size)
    rss = float(e @ e)
    aic, bic = information_criteria(rss, n, n_parameters)
    return FitResult(model=model, rmse=float(np.sqrt(rss / n)), n_parameters=n_parameters, n_train=n,
                     aic=aic, bic=bic, fit_time=time.perf_counter() - t0, success=success,
                     message=message, residuals=e, param_names=list(names),
                     param_values=np.asarray(values, dtype=np.float64), covariance=covariance)


def _plane_solve(G, b, yy, wsum, regularization, solver):
    """Non-negative weights and a free offset from the Gram matrix (offset
    last): the scaled problem of :func:`fit_weights` (equilibrated columns,
    ``_split_gram`` and the cvxpy QP ``_WeightQP``) with a small ridge that
    makes the weights of cells the data never reach (duplicates of the
    offset column) zero."""
    m = G.shape[0]
    K = m - 1
    s = np.sqrt(np.maximum(np.diag(G) / wsum, 0.0))
    s[s == 0] = 1.0
    sigma = math.sqrt(yy / wsum) or 1.0
    Gs = G / np.outer(s, s) / wsum
    bs = b / s / (wsum * sigma)
    free = np.ones(m, bool)
    R, d = _split_gram(Gs, bs, free)
    if solver == "bvls":
        # the same problem as bounded least squares: the ridge as rows below R
        # (SciPy's BVLS; no cvxpy, so no solver thread pool: safe in a
        # process forked from one that has used cvxpy)
        Ra = np.vstack([R, np.hstack([math.sqrt(regularization) * np.eye(K), np.zeros((K, 1))])])
        da = np.concatenate([d, np.zeros(K)])
        x, status, err = solve_weights(Ra, da, lower=np.append(np.zeros(K), -np.inf))
    elif m <= 300:
        C = np.zeros((K, m))
        C[np.arange(K), np.arange(K)] = 1.0
        M = np.zeros((K, m))
        M[np.arange(K), np.arange(K)] = 1.0
        x, status, err = solve_weights(R, d, C=C, lb=np.zeros(K), M=M, lam=regularization, fixed=~free,
                                       solver=solver)
    else:
        # large planes (a 50 x 50 grid has 1,275 cells): the parametrised
        # (DPP) form of _WeightQP would build a tensor of m^2 x m^2 entries;
        # the same problem with constant data compiles in O(m^2)
        import cvxpy as cp

        xv = cp.Variable(m)
        res = cp.hstack([R @ xv - d, math.sqrt(regularization) * xv[:K]])
        prob = cp.Problem(cp.Minimize(cp.norm(res, 2)), [xv[:K] >= 0])
        err = ""
        try:
            prob.solve(solver=_pick_solver(solver))
        except cp.error.SolverError as exc:
            err = str(exc)
        x, status = xv.value, prob.status
    if x is None or status in ("infeasible", "unbounded", "infeasible_inaccurate", "unbounded_inaccurate"):
        raise RuntimeError(f"the weight problem was not solved (cvxpy status {status!r}{': ' + err if err else ''})")
    theta = sigma * x / s
    theta[:K] = np.maximum(theta[:K], 0.0)   # solver round-off below the bound
    return theta, status


def _plane_fit(kind, v, y, n, input_range, regularization, solver, progress, train=None):
    import time

    from ..preisach import KP, Preisach
    from .. import _kernels_other as _ko

    t0 = time.perf_counter()
    x = as_signal(v, "v")
    yv = as_signal(y, "y")
    if x.size != yv.size:
        raise ValueError(f"Parameter y has {yv.size} samples but v has {x.size}; expected equal lengths")
    if train is None:
        mask = np.ones(x.size, bool)
    else:
        mask = np.asarray(train)
        if mask.dtype != bool or mask.shape != x.shape:
            raise ValueError(f"Parameter train is an array of {mask.dtype} with shape {mask.shape} but should be "
                             f"a boolean mask of the {x.size} samples (True: fitted)")
        if not mask.any():
            raise ValueError("Parameter train selects no sample; at least one sample must be fitted")
    if not (isinstance(n, (int, np.integer)) and n >= 1):
        raise ValueError(f"Parameter n is {n!r} but should be a positive integer (cells per axis)")
    if input_range is None:
        lo, hi = float(x.min()), float(x.max())
        if not hi > lo:
            raise ValueError("Parameter v is constant; a Preisach plane needs an input that moves")
        input_range = (lo, hi)
    regularization = as_scalar(regularization, "regularization", nonnegative=True)
    cls = Preisach if kind == "preisach" else KP
    proto = cls(input_range, np.eye(n))          # grid, default state
    ci, cj = np.tril_indices(n)
    K = ci.size
    G = np.zeros((K + 1, K + 1))
    bvec = np.zeros(K + 1)
    if kind == "preisach":
        k = proto._check_state(proto.default_state())
        starts = np.empty(_BLOCK, np.int64)
        states = np.empty((_BLOCK, n), np.int64)
    else:
        z = proto.default_state()
        cd = (ci - cj).astype(np.int64)
        A = np.empty((_BLOCK, K))
    nblocks = (x.size + _BLOCK - 1) // _BLOCK
    for bi, s0 in enumerate(range(0, x.size, _BLOCK)):
        xs, ys, ms = x[s0:s0 + _BLOCK], yv[s0:s0 + _BLOCK], mask[s0:s0 + _BLOCK]
        if kind == "preisach":
            S = _ko.preisach_segments(xs, proto.v_min, proto.h, k, starts, states)
            # rows: one per segment of constant state, weighted by its fitted samples
            cnt = np.add.reduceat(ms.astype(np.float64), starts[:S])
            ysum = np.add.reduceat(np.where(ms, ys, 0.0), starts[:S])
            rows = np.where(cj[None, :] < states[:S][:, ci], 1.0, -1.0)
            rows = np.hstack([rows, np.ones((S, 1))])
            G += rows.T @ (rows * cnt[:, None])
            bvec += rows.T @ ysum
        else:
            Ab = A[: xs.size]
            _ko.kp_regressors(xs, proto.v_min, proto.h, z, cd, cj.astype(np.int64), Ab)
            rows = np.hstack([Ab, np.ones((xs.size, 1))])[ms]
            G += rows.T @ rows
            bvec += rows.T @ ys[ms]
        if progress and nblocks > 4:
            import sys

            done = (bi + 1) / nblocks
            sys.stderr.write(f"\r{kind} regressors [{'#' * int(30 * done):<30}] {100 * done:5.1f}%")
            if bi + 1 == nblocks:
                sys.stderr.write("\n")
    yf = yv[mask]
    theta, status = _plane_solve(G, bvec, float(yf @ yf), float(yf.size), regularization, solver)
    mu = np.zeros((n, n))
    mu[ci, cj] = theta[:K]
    model = cls(input_range, mu, float(theta[K]))
    # the residual on the fitted samples (the model runs over the whole record)
    e = (yv - model.simulate(x))[mask]
    # cells by their (row, column) in the Preisach plane; no covariance (a
    # ridge-penalised, mostly bound-constrained problem of hundreds of cells)
    names = [f"mu[{i},{j}]" for i, j in zip(ci, cj)] + ["offset"]
    return _model_fit(model, e, K + 1, t0, status in ("optimal", "optimal_inaccurate"),
                      "" if status == "optimal" else f"cvxpy status {status}", names, theta[:K + 1])


def fit_preisach(v, y, n=20, input_range=None, regularization=1e-6, solver=None, progress=False, train=None):
    """Identify a :class:`~hystcomp.preisach.Preisach` model: non-negative
    cell weights and an offset by constrained least squares.

    The output is linear in the weights (eq. 7), so the problem is the
    convex one of :func:`fit_weights`: the Gram matrix is accumulated block
    by block, one row per segment of constant relay state (weighted by its
    length, so a slow record costs its number of level changes, not its
    samples), then solved by cvxpy after column equilibration.

    Parameters
    ----------
    v, y : array_like, shape (n_samples,)
        Input and measured output, simulated from the demagnetised state.
    n : int
        Cells per axis (n (n + 1) / 2 weights).
    input_range : (float, float), optional
        Grid interval; default the range of v.
    regularization : float
        Ridge weight in scaled units (every column normalised to unit RMS,
        y to unit RMS): keeps the problem well posed where cells are not
        excited; 1e-6 changes the training RMS by far less than the grid's
        quantisation.
    solver : str, optional
        cvxpy solver (default: the first of CLARABEL, OSQP, SCS, ECOS), or
        ``"bvls"``: the same problem by SciPy's bounded-variable least
        squares, without cvxpy (what :func:`hystcomp.diagnose.diagnose` uses:
        a cvxpy solver's thread pool may hang a process forked from one that
        has used it).
    progress : bool
        Progress bar on stderr.
    train : array of bool, optional
        The samples fitted (default all).  The relays run over the whole
        record from its first sample; only the samples marked True enter
        the least-squares problem, so the rest can judge the fit held out
        (as :func:`hystcomp.diagnose.diagnose` does).  The result's
        residuals, RMSE and criteria are on those samples.

    Returns
    -------
    ModelFit

    Examples
    --------
    >>> import numpy as np
    >>> from hystcomp.preisach import Preisach
    >>> true = Preisach.from_density(lambda a, b: np.exp(-(a - b)), (-1, 1), 6, offset=0.3)
    >>> v = np.sin(np.linspace(0, 30, 3000)) * np.linspace(1, 0.2, 3000)
    >>> res = fit_preisach(v, true.simulate(v), n=6, input_range=(-1, 1))
    >>> bool(res.rmse < 1e-6)
    True
    """
    return _plane_fit("preisach", v, y, n, input_range, regularization, solver, progress, train)


def fit_kp(v, y, n=20, input_range=None, regularization=1e-6, solver=None, progress=False, train=None):
    """Identify a :class:`~hystcomp.preisach.KP` model (non-negative cell
    weights and an offset), as :func:`fit_preisach` does for the Preisach
    model; the regressors are the KP operator outputs (dense rows, built in
    the compiled kernel block by block).

    Parameters
    ----------
    v, y : array_like, shape (n_samples,)
        Input and measured output, simulated from the KP model's default
        state.
    n : int
        Cells per axis (n (n + 1) / 2 weights).
    input_range : (float, float), optional
        Grid interval; default the range of v.
    regularization : float
        Ridge weight in scaled units, as in :func:`fit_preisach`.
    solver : str, optional
        cvxpy solver (default: the first of CLARABEL, OSQP, SCS, ECOS), or
        ``"bvls"`` (no cvxpy), as in :func:`fit_preisach`.
    progress : bool
        Progress bar on stderr.
    train : array of bool, optional
        The samples fitted (default all), as in :func:`fit_preisach`.

    Returns
    -------
    ModelFit

    Examples
    --------
    >>> import numpy as np
    >>> from hystcomp.preisach import KP
    >>> true = KP.from_density(lambda a, b: 1 + 0 * a, (-1, 1), 5)
    >>> v = np.sin(np.linspace(0, 30, 3000)) * np.linspace(1, 0.2, 3000)
    >>> res = fit_kp(v, true.simulate(v), n=5, input_range=(-1, 1))
    >>> bool(res.rmse < 1e-6)
    True
    """
    return _plane_fit("kp", v, y, n, input_range, regularization, solver, progress, train)


def _linear_tail(w, x, y, gain):
    """Least-squares gain (>= 0, when fitted) and offset of y ~ gain x + w + offset."""
    r = y - w
    if not gain:
        return 0.0, float(r.mean())
    xc = x - x.mean()
    g = float(xc @ (r - r.mean()) / (xc @ xc)) if xc @ xc > 0 else 0.0
    g = max(g, 0.0)
    return g, float((r - g * x).mean())


def _nonlinear_fit(make, x0, bounds, v, y, gain, max_nfev, n_linear):
    """Variable projection: least_squares over the shape parameters, the
    gain and offset solved linearly inside."""
    import time

    from scipy import optimize

    t0 = time.perf_counter()
    x = as_signal(v, "v")
    yv = as_signal(y, "y")
    if x.size != yv.size:
        raise ValueError(f"Parameter y has {yv.size} samples but v has {x.size}; expected equal lengths")
    scale = float(np.std(yv)) or 1.0

    def inner(p):
        m = make(p, 0.0, 0.0)
        w = m.simulate(x)          # sign * w (+ 0 gain, 0 offset)
        g, o = _linear_tail(w, x, yv, gain)
        return m, g, o, w

    def resid(p):
        try:
            m, g, o, w = inner(p)
        except (ValueError, FloatingPointError):
            return np.full(x.size, 1e3)
        r = (w + g * x + o - yv) / scale
        return np.where(np.isfinite(r), r, 1e3)

    best = None
    for start in x0:
        sol = optimize.least_squares(resid, start, bounds=bounds, max_nfev=max_nfev, x_scale="jac")
        if best is None or sol.cost < best.cost:
            best = sol
    m, g, o, w = inner(best.x)
    model = make(best.x, g, o)
    e = yv - model.simulate(x)
    # the shape parameters' covariance from the Jacobian least_squares
    # returns (of the variable-projection residual, in units of `scale`);
    # the linear gain and offset solved inside get none (NaN)
    k = len(best.x)
    J = np.asarray(best.jac, dtype=np.float64)
    s2 = 2.0 * float(best.cost) / max(x.size - k - n_linear, 1)
    cov = np.full((k + n_linear, k + n_linear), np.nan)
    cov[:k, :k] = s2 * np.linalg.pinv(J.T @ J, hermitian=True)
    names = [f"shape[{i}]" for i in range(k)] + (["gain"] if n_linear == 2 else []) + ["offset"]
    values = list(best.x) + ([g] if n_linear == 2 else []) + [o]
    return _model_fit(model, e, k + n_linear, t0, bool(best.success), best.message, names, values, cov)


def _loop_scales(v, y):
    """Slope of the line through the loop and the loop's half-height."""
    x = as_signal(v, "v")
    yv = as_signal(y, "y")
    xc = x - x.mean()
    k = float(xc @ (yv - yv.mean()) / (xc @ xc)) if xc @ xc > 0 else 1.0
    r = yv - k * x
    half = 0.5 * float(np.ptp(r)) or 0.1 * (float(np.std(yv)) or 1.0)
    return k, half


def fit_bouc_wen(v, y, gain=True, n_exponent=None, max_nfev=200):
    """Identify a :class:`~hystcomp.differential.BoucWen` model by nonlinear
    least squares (scipy.optimize.least_squares, trust-region reflective).

    Shape parameters ``[ln A, ln(alpha + beta), (alpha - beta)/(alpha + beta), n]``
    (the valid range as bounds: alpha + beta > 0, 0 <= alpha - beta,
    1 <= n <= 6); the linear gain (>= 0) and the offset are solved inside
    each evaluation (variable projection).  With `gain`, both output signs
    ``y = gain v +- w`` are tried (``-w``: the piezo form of Low and Guo).  Starts from the data: the slope
    k of the line through the loop and the loop's half-height H give
    ``A = k``, ``w_bound = H`` (so ``alpha + beta = A / H^n``), from a few
    ratios and exponents; the best fit wins.

    Parameters
    ----------
    v, y : array_like, shape (n_samples,)
        Input and measured output.
    gain : bool
        Fit the linear term ``gain * v`` (needed for piezo loops, which do
        not saturate); False fits eq. 3 alone.
    n_exponent : float, optional
        Fix n instead of fitting it.
    max_nfev : int
        Budget of residual evaluations per start.

    Returns
    -------
    ModelFit

    Examples
    --------
    >>> import numpy as np
    >>> from hystcomp.differential import BoucWen
    >>> true = BoucWen(A=2.0, alpha=0.8, beta=0.2, n=1.0, gain=0.5, offset=0.1)
    >>> v = 3 * np.sin(np.linspace(0, 20, 2000))
    >>> res = fit_bouc_wen(v, true.simulate(v), n_exponent=1.0)
    >>> [round(p, 4) for p in (res.model.A, res.model.alpha, res.model.beta, res.model.gain)]
    [2.0, 0.8, 0.2, 0.5]
    """
    from ..differential import BoucWen

    k, half = _loop_scales(v, y)
    fixed_n = n_exponent is not None
    if fixed_n:
        n_exponent = as_scalar(n_exponent, "n_exponent")
        if n_exponent < 1:
            raise ValueError(f"Parameter n_exponent is {n_exponent} but should be >= 1")

    def maker(sign):
        def make(p, g, o):
            A = math.exp(p[0])
            ssum = math.exp(p[1])
            n = n_exponent if fixed_n else p[3]
            return BoucWen(A, 0.5 * ssum * (1 + p[2]), 0.5 * ssum * (1 - p[2]), n, gain=g, offset=o, sign=sign)
        return make

    A0 = max(abs(k), 1e-12)
    x = as_signal(v, "v")
    yv = as_signal(y, "y")
    # coarse grid of starts around the data's scales, both signs of w (w
    # alone is a clockwise loop); the best start of each sign seeds least
    # squares and the better fit wins (one start drifts to A -> 0 on real loops)
    best_start = {}
    for sign in ((1, -1) if gain else (1,)):
        make = maker(sign)
        for n0 in ([n_exponent] if fixed_n else [1.0, 2.0]):
            for fa in ((0.1, 0.3, 1.0) if gain else (1.0,)):
                for fw in (0.1, 0.3, 1.0):
                    for ratio in (0.2, 0.8):
                        a = fa * A0
                        p = [math.log(a), math.log(a / (fw * half) ** n0), ratio]
                        if not fixed_n:
                            p.append(n0)
                        sw = make(p, 0.0, 0.0).simulate(x)      # sign * w
                        g, o = _linear_tail(sw, x, yv, gain)
                        cost = float(np.mean((sw + g * x + o - yv) ** 2))
                        if sign not in best_start or cost < best_start[sign][0]:
                            best_start[sign] = (cost, p)
    lo = [math.log(A0) - 12.0, -np.inf, 0.0] + ([] if fixed_n else [1.0])
    hi = [math.log(A0) + 6.0, np.inf, 1.0] + ([] if fixed_n else [6.0])
    fits = [_nonlinear_fit(maker(sign), [p], (lo, hi), v, y, gain, max_nfev, 2 if gain else 1)
            for sign, (_, p) in best_start.items()]
    best = min(fits, key=lambda f: f.rmse)
    best.fit_time = sum(f.fit_time for f in fits)
    return best


def fit_backlash_like(v, y, max_nfev=200):
    """Identify a :class:`~hystcomp.differential.BacklashLike` model (eq. 5)
    by nonlinear least squares over ``[ln alpha, ln c, B1 / c]`` (bounds:
    alpha, c > 0, 0 < B1 <= c), the offset solved inside.  Starts: c = the
    slope k of the line through the loop, ``(c - B1) / alpha`` = the loop's
    half-height H.

    Parameters
    ----------
    v, y : array_like, shape (n_samples,)
        Input and measured output.
    max_nfev : int
        Budget of residual evaluations per start (two starts).

    Returns
    -------
    ModelFit

    Examples
    --------
    >>> import numpy as np
    >>> from hystcomp.differential import BacklashLike
    >>> true = BacklashLike(alpha=1.5, c=3.0, B1=1.0, offset=-0.2)
    >>> v = 4 * np.sin(np.linspace(0, 20, 2000))
    >>> res = fit_backlash_like(v, true.simulate(v))
    >>> [round(p, 4) for p in (res.model.alpha, res.model.c, res.model.B1, res.model.offset)]
    [1.5, 3.0, 1.0, -0.2]
    """
    from ..differential import BacklashLike

    k, half = _loop_scales(v, y)
    c0 = max(abs(k), 1e-12)

    def make(p, g, o):
        c = math.exp(p[1])
        return BacklashLike(math.exp(p[0]), c, c * p[2], offset=o)

    starts = [[math.log(c0 * (1 - f) / half), math.log(c0), f] for f in (0.3, 0.7)]
    return _nonlinear_fit(make, starts, ([-np.inf, -np.inf, 1e-9], [np.inf, np.inf, 1.0]), v, y, False,
                          max_nfev, 1)


def fit_duhem(v, y, f1, f2, params0, bounds=(-np.inf, np.inf), max_step=None, gain=True, max_nfev=200):
    """Identify the parameters of a :class:`~hystcomp.differential.Duhem`
    model with user shape functions ``f1(w, v, p)``, ``f2(w, v, p)`` by
    nonlinear least squares (scipy.optimize.least_squares); the gain
    (>= 0, if `gain`) and offset are solved inside.

    Parameters
    ----------
    v, y : array_like, shape (n_samples,)
        Input and measured output.
    f1, f2 : callable
        Shape functions ``f(w, v, p)`` of the Duhem model for increasing
        and decreasing input (numba-compilable ones run fast).
    params0 : array_like
        Starting parameters (or a list of starting points: the best fit wins).
    bounds : (lower, upper)
        Bounds of the parameters, as for ``least_squares``.
    max_step : float, optional
        RK4 sub-step in the input; default 1/200 of the range of v.
    gain : bool
        Fit a linear term ``gain * v`` (>= 0) beside w.
    max_nfev : int
        Budget of residual evaluations per start.

    Returns
    -------
    ModelFit

    Examples
    --------
    A Coleman-Hodgdon (backlash-like) shape, recovered:

    >>> import numpy as np
    >>> from hystcomp.differential import BacklashLike
    >>> f1 = lambda w, v, p: p[0] * (p[1] * v - w) + p[2]
    >>> f2 = lambda w, v, p: -p[0] * (p[1] * v - w) + p[2]
    >>> v = 4 * np.sin(np.linspace(0, 20, 800))
    >>> y = BacklashLike(1.5, 3.0, 1.0).simulate(v)
    >>> res = fit_duhem(v, y, f1, f2, [1.0, 2.0, 0.5], bounds=([1e-3, 1e-3, 0], [10, 10, 10]),
    ...                 max_step=0.02, gain=False)
    >>> np.round(res.model.params, 3).tolist()
    [1.5, 3.0, 1.0]
    """
    from ..differential import Duhem

    x = as_signal(v, "v")
    if max_step is None:
        max_step = float(np.ptp(x)) / 200 or 1.0
    p0 = np.asarray(params0, dtype=np.float64)
    starts = [p0] if p0.ndim == 1 else list(p0)
    proto = Duhem(f1, f2, params=starts[0], max_step=max_step)

    def make(p, g, o):
        return proto.with_params(p, gain=g, offset=o)

    return _nonlinear_fit(make, starts, bounds, x, y, gain, max_nfev, 2 if gain else 1)


class ModelComparison(list):
    """Rows of :func:`compare_models` (a list of dicts) with a readable table.

    Examples
    --------
    >>> import numpy as np
    >>> from hystcomp.differential import BacklashLike
    >>> v = 4 * np.sin(np.linspace(0, 20, 2000))
    >>> res = compare_models(v, BacklashLike(1.5, 3.0, 1.0).simulate(v), models=("backlash_like",))
    >>> res[0]["name"], res[0]["n_parameters"]
    ('backlash_like', 4)
    >>> print(res.table().splitlines()[0])
    model           params   train rms  held-out rms  held-out max  fit time [s]
    """

    def table(self):
        """The comparison as a fixed-width text table (str).

        Examples
        --------
        >>> rows = ModelComparison([{"name": "pi", "n_parameters": 3, "train_rms": 0.1, "rms": 0.2,
        ...                          "max": 0.5, "fit_time": 0.01}])
        >>> print(rows.table().splitlines()[-1])
        pi                   3         0.1           0.2           0.5          0.01
        """
        head = f"{'model':<14}{'params':>8}{'train rms':>12}{'held-out rms':>14}{'held-out max':>14}{'fit time [s]':>14}"
        lines = [head, "-" * len(head)]
        for r in self:
            lines.append(f"{r['name']:<14}{r['n_parameters']:>8d}{r['train_rms']:>12.4g}{r['rms']:>14.4g}"
                         f"{r['max']:>14.4g}{r['fit_time']:>14.3g}")
        return "\n".join(lines)

    def __str__(self):
        return self.table()


_COMPARE_DEFAULT = ("pi", "mgpi", "preisach", "kp", "bouc_wen", "backlash_like")


def compare_models(v, y, models=_COMPARE_DEFAULT, train_fraction=0.5, n_cells=20, n_thresholds=20,
                   max_train_samples=20000, train=None, progress=False, executor=None):
    """Fit several hysteresis models on the first part of a record and
    compare them on the rest, side by side.

    Each model is fitted on ``v[:split], y[:split]`` (``split`` =
    `train_fraction` of the samples, or ``v[start:split]`` with
    ``train=(start, split)``; for speed the training part is
    decimated to at most `max_train_samples` samples, which keeps the
    reversal points of a slowly sampled record), then simulated over the
    whole record from its default state and scored on the held-out samples
    ``split:``.

    Parameters
    ----------
    v, y : array_like, shape (n_samples,)
        Input and measured output (one record).
    models : sequence of str
        Among "pi" (:func:`fit_weights`, PI model), "mgpi" (:func:`fit`,
        tanh envelope), "preisach", "kp" (:func:`fit_preisach`,
        :func:`fit_kp` with `n_cells` per axis), "bouc_wen", "backlash_like".
    train_fraction : float
        In (0, 1).
    n_cells, n_thresholds : int
        Grid of the Preisach/KP planes; thresholds of the PI/mGPI models.
    max_train_samples : int
        Largest number of training samples after decimation.
    train : (int, int), optional
        Sample indices ``(start, split)`` of the training part (e.g. to skip
        a start-up transient); overrides `train_fraction`.  The held-out
        part is always ``split:``.
    progress : bool
        A line per model on stderr.
    executor : concurrent.futures.Executor, optional
        Fits the models as independent jobs on it (e.g. a
        ``ProcessPoolExecutor``, or ``distributed.Client(...).get_executor()``
        for dask); results are the same as without.  None fits them one
        after the other here.

    Returns
    -------
    ModelComparison
        One dict per model: ``name``, ``model`` (the fitted model; a
        PI-family model's offset is in ``offset``), ``n_parameters``,
        ``train_rms``, ``rms`` and ``max`` (held-out), ``fit_time`` [s],
        ``prediction`` (whole record).  ``print(result)`` shows the table.

    Examples
    --------
    >>> import numpy as np
    >>> from hystcomp.differential import BacklashLike
    >>> v = 4 * np.sin(np.linspace(0, 20, 2000))
    >>> y = BacklashLike(1.5, 3.0, 1.0).simulate(v)
    >>> res = compare_models(v, y, models=("pi", "backlash_like"))
    >>> [r["name"] for r in res], bool(res[1]["rms"] < 1e-6)
    (['pi', 'backlash_like'], True)
    """
    import sys

    x = as_signal(v, "v")
    yv = as_signal(y, "y")
    if x.size != yv.size:
        raise ValueError(f"Parameter y has {yv.size} samples but v has {x.size}; expected equal lengths")
    frac = as_scalar(train_fraction, "train_fraction")
    if not 0.0 < frac < 1.0:
        raise ValueError(f"Parameter train_fraction is {frac} but should be in (0, 1)")
    known = ("pi", "mgpi", "preisach", "kp", "bouc_wen", "backlash_like")
    for name in models:
        check_choice(name, "models[...]", known)
    start, split = 0, int(round(frac * x.size))
    if train is not None:
        try:
            start, split = int(train[0]), int(train[1])
        except (TypeError, IndexError, ValueError):
            raise ValueError(f"Parameter train is {train!r} but should be (start, split) sample indices") from None
        if not 0 <= start < split <= x.size:
            raise ValueError(f"Parameter train is {train!r} but should satisfy 0 <= start < split <= {x.size}")
    if split - start < 10 or x.size - split < 1:
        raise ValueError(f"Parameters v and train_fraction/train leave {split - start} training and "
                         f"{x.size - split} held-out samples; expected at least 10 and 1")
    step = max(1, int(math.ceil((split - start) / max_train_samples)))
    vt, yt = x[start:split:step], yv[start:split:step]
    jobs = [(name, vt, yt, x, yv, start, split, n_cells, n_thresholds) for name in models]
    if executor is None:
        rows = map(_compare_one, jobs)
    else:
        if not hasattr(executor, "submit"):
            raise TypeError(f"Parameter executor is {executor!r}; expected a concurrent.futures.Executor "
                            "(or None)")
        futures = [executor.submit(_compare_one, job) for job in jobs]
        rows = (f.result() for f in futures)
    out = ModelComparison()
    for row in rows:
        out.append(row)
        if progress:
            sys.stderr.write(f"compare_models: {row['name']:<14} held-out rms {row['rms']:.4g} "
                             f"({row['fit_time']:.2f} s)\n")
    return out


def _compare_one(job):
    """Fit one model of :func:`compare_models` and score it (module level, so that an
    executor can run it in another process)."""
    import time

    name, vt, yt, x, yv, start, split, n_cells, n_thresholds = job
    t0 = time.perf_counter()
    offset = 0.0
    if name in ("pi", "mgpi"):
        if name == "pi":
            res = fit_weights(vt, yt, model="pi", n_thresholds=n_thresholds)
        else:
            res = fit(vt, yt, envelope="tanh", n_thresholds=n_thresholds)
        model, offset, npar = res.model, res.offset, res.thresholds.size + 2
        if name == "mgpi":
            npar += 1
    elif name in ("preisach", "kp"):
        lo, hi = float(x.min()), float(x.max())
        fitter = fit_preisach if name == "preisach" else fit_kp
        res = fitter(vt, yt, n=n_cells, input_range=(lo, hi))
        model, npar = res.model, res.n_parameters
    elif name == "bouc_wen":
        res = fit_bouc_wen(vt, yt)
        model, npar = res.model, res.n_parameters
    else:
        res = fit_backlash_like(vt, yt)
        model, npar = res.model, res.n_parameters
    fit_time = time.perf_counter() - t0
    pred = model.simulate(x) + offset
    e = yv - pred
    held = e[split:]
    etrain = e[start:split]
    return {"name": name, "model": model, "offset": offset, "n_parameters": int(npar),
            "train_rms": float(np.sqrt(np.mean(etrain * etrain))),
            "rms": float(np.sqrt(np.mean(held * held))), "max": float(np.max(np.abs(held))),
            "fit_time": fit_time, "prediction": pred}

__all__ = ["ModelFit", "ModelComparison", "fit_preisach", "fit_kp", "fit_bouc_wen", "fit_backlash_like",
            "fit_duhem", "compare_models"]

"""The one constrained least-squares solve of hystcomp's identification.

:func:`solve_weights` is the entry point every front end calls
(:func:`~hystcomp.identify.fit_weights`, :func:`~hystcomp.identify.fit`,
:func:`hystcomp.diagnose.diagnose` through :mod:`hystcomp.identify.search`):

``minimize ||R x - d||^2 + lam ||M x||^2  subject to  lower <= x <= upper,
C x >= lb, x[fixed] = 0``

on a factored, equilibrated problem (``R^T R = G``, ``R^T d = b`` from the Gram
matrix of the regressor columns).  With linear inequality constraints or a
penalty it is a cvxpy problem (DPP parameters, compiled once and cached per
shape, so a variable-projection loop pays the compilation once); with bounds
only it is solved exactly by bounded-variable least squares (an active-set
method, :func:`scipy.optimize.lsq_linear` with ``method="bvls"``), because
cvxpy's per-call overhead of tens of milliseconds would dominate the
variable-projection loops of :func:`hystcomp.diagnose.diagnose`.
"""

import functools
import math

import numpy as np

from .._validation import as_scalar, check_choice
from ._records import _EPS

# the convex weight problem
# ----------------------------------------------------------------------------
@functools.lru_cache(maxsize=None)
def _pick_solver(solver):
    import cvxpy as cp

    installed = cp.installed_solvers()
    if solver is not None:
        if solver.upper() not in installed:
            raise ValueError(
                f"Parameter solver is {solver!r} but the installed cvxpy solvers are {installed}"
            )
        return solver.upper()
    for name in ("CLARABEL", "OSQP", "SCS", "ECOS"):
        if name in installed:
            return name
    raise RuntimeError(f"no QP solver among the installed cvxpy solvers {installed}")


class _WeightQP:
    """minimize (||R x - d||^2 + lam ||M x||^2)^(1/2) subject to C x >= lb, x[fixed] = 0.

    R, d, C, M are cvxpy Parameters (DPP), so repeated solves with new data
    (variable projection) reuse the compiled problem.
    """

    def __init__(self, m, n_ineq, n_pen, fixed, solver):
        import cvxpy as cp

        self.cp = cp
        self.x = cp.Variable(m)
        self.R = cp.Parameter((m, m))
        self.d = cp.Parameter(m)
        self.C = cp.Parameter((n_ineq, m))
        self.lb = cp.Parameter(n_ineq)
        # minimise the 2-norm of the stacked residual (same minimiser as the
        # sum of squares, but the solver's gap tolerance then applies to the
        # RMS rather than to its square: ~1e-8 relative instead of ~1e-4)
        res = self.R @ self.x - self.d
        if n_pen:
            self.M = cp.Parameter((n_pen, m))
            res = cp.hstack([res, self.M @ self.x])
        obj = cp.norm(res, 2)
        cons = [self.C @ self.x >= self.lb]
        fixed = np.flatnonzero(fixed)
        if fixed.size:
            cons.append(self.x[fixed] == 0)
        self.problem = cp.Problem(cp.Minimize(obj), cons)
        self.solver = solver

    def solve(self, R, d, C, lb, M=None, lam=0.0):
        self.lb.value = lb
        self.R.value = R
        self.d.value = d
        self.C.value = C
        if M is not None:
            self.M.value = math.sqrt(lam) * M
        try:
            self.problem.solve(solver=self.solver)
        except self.cp.error.SolverError as exc:
            return None, "solver_error", str(exc)
        return self.x.value, self.problem.status, ""


def _split_gram(G, b, free, rcond=1e-13):
    """R, d with R^T R = G and R^T d = b on the free columns (eigen
    factorisation: robust when G is singular; eigenvalues below
    ``rcond * m * max`` are dropped)."""
    m = G.shape[0]
    R = np.zeros((m, m))
    d = np.zeros(m)
    idx = np.flatnonzero(free)
    Gf = G[np.ix_(idx, idx)]
    lam, U = np.linalg.eigh(0.5 * (Gf + Gf.T))
    tol = max(lam.max(), 0.0) * m * rcond
    pos = lam > tol
    sq = np.sqrt(lam[pos])
    Rf = sq[:, None] * U[:, pos].T
    df = (U[:, pos].T @ b[idx]) / sq
    R[np.ix_(np.arange(Rf.shape[0]), idx)] = Rf
    d[: Rf.shape[0]] = df
    return R, d


class _Problem:
    """The scaled weight problem for one set of thresholds and settings."""

    def __init__(self, r, constraints, regularization, offset, solver):
        self.r = r
        self.constraints = check_choice(constraints, "constraints", ("nonnegative", "invertible"))
        self.offset = bool(offset)
        self.lam = 0.0
        self.reg = None
        if regularization is not None:
            ok = (isinstance(regularization, (tuple, list)) and len(regularization) == 2
                  and regularization[0] in ("ridge", "smooth"))
            if not ok:
                raise ValueError(
                    f"Parameter regularization is {regularization!r} but should be None, "
                    "('ridge', lam) or ('smooth', lam)"
                )
            self.reg = regularization[0]
            self.lam = as_scalar(regularization[1], "regularization[1]", nonnegative=True)
        self.solver = _pick_solver(solver)
        self._qp = {}

    def solve(self, G, b, yy, wsum, unreached, lead=1):
        """Scaled solve; columns are `lead` (0 or 1: p0 or the H coefficient),
        the N operator weights, then the offset if any."""
        N = self.r.size
        K = lead + N
        m = G.shape[0]
        # equilibrate: column RMS s_j, output RMS sigma -> dimensionless problem
        s = np.sqrt(np.maximum(np.diag(G) / wsum, 0.0))
        s[s == 0] = 1.0
        sigma = math.sqrt(yy / wsum) or 1.0
        Gs = G / np.outer(s, s) / wsum
        bs = b / s / (wsum * sigma)
        free = np.ones(m, bool)
        free[lead:K] = ~unreached
        R, d = _split_gram(Gs, bs, free)
        # constraints C x >= lb (in scaled units x_j = s_j p_j / sigma); the
        # lead weight (p0, or the coefficient of H) is kept >= eps, the
        # operator weights (or, "invertible", the partial sums) >= 0 / eps.
        # Without a lead column (GPI with H = None) every bound is 0.
        if self.constraints == "nonnegative":
            C = np.zeros((K, m))
            C[np.arange(K), np.arange(K)] = 1.0
            lb = np.zeros(K)
            if lead:
                lb[0] = _EPS
        else:
            # partial sums p0 + p_1 + ... + p_k >= eps, rows scaled by s_0
            C = np.tril(np.ones((K, K))) * (s[0] / s[:K])[None, :]
            C = np.hstack([C, np.zeros((K, m - K))])
            lb = np.full(K, _EPS if lead else 0.0)
        M = None
        if self.reg == "ridge":
            M = np.zeros((N, m))
            M[np.arange(N), lead + np.arange(N)] = 1.0
        elif self.reg == "smooth":
            # first differences of the density p_i / (r_i - r_{i-1}), made
            # dimensionless with r_N and the median column RMS
            dr = np.diff(np.concatenate([[0.0], self.r]))
            scale = self.r[-1] * float(np.median(s[lead:K]))
            D = np.zeros((max(N - 1, 1), m))
            for i in range(N - 1):
                D[i, lead + i] = -scale / (s[lead + i] * dr[i])
                D[i, lead + 1 + i] = scale / (s[lead + 1 + i] * dr[i + 1])
            M = D
        x, status, err = solve_weights(R, d, C=C, lb=lb, M=M, lam=self.lam, fixed=~free, solver=self.solver,
                                       cache=self._qp)
        if x is None or status in ("infeasible", "unbounded", "infeasible_inaccurate", "unbounded_inaccurate"):
            raise RuntimeError(
                f"the weight problem was not solved (cvxpy status {status!r} with solver "
                f"{self.solver}{': ' + err if err else ''})"
            )
        x = np.where(free, x, 0.0)
        # kept for covariance() (the Gram matrix and the constraints at the optimum)
        self._last = dict(x=x, Gs=Gs, s=s, sigma=sigma, wsum=wsum, C=C, lb=lb, M=M, free=free)
        theta = sigma * x / s
        # training MSE from the Gram form (exact up to rounding)
        mse = max(float(x @ Gs @ x - 2 * bs @ x) * sigma ** 2 + yy / wsum, 0.0)
        cond = float(np.linalg.cond(Gs[np.ix_(free, free)]))
        return theta, status, mse, cond


    def covariance(self, rss_w, n_train, n_free, tol=1e-7):
        """Covariance of the last solution's coefficients (unscaled units):
        ``s^2 (A^T W A)^-1`` with ``s^2 = RSS_w / (n - k)``, restricted to the
        face of the active constraints (a weight at its bound, a partial sum
        of an invertible model at its bound, an unreached threshold: those
        directions have zero variance); with a penalty, the sandwich
        ``H^-1 G H^-1`` (H = G + lam M^T M).

        Parameters
        ----------
        rss_w : float
            Weighted training residual sum of squares.
        n_train : int
            Training samples (non-zero weight).
        n_free : int
            Free parameters (degrees of freedom ``n_train - n_free``).
        tol : float
            A constraint is active when its slack is below `tol` (scaled units,
            where the coefficients are of order 1).

        Returns
        -------
        ndarray, shape (m, m)
        """
        from scipy.linalg import null_space

        last = self._last
        x, Gs, s, C, lb = last["x"], last["Gs"], last["s"], last["C"], last["lb"]
        m = x.size
        rows = [C[(C @ x - lb) <= tol]]
        fixed = np.flatnonzero(~last["free"])
        if fixed.size:
            E = np.zeros((fixed.size, m))
            E[np.arange(fixed.size), fixed] = 1.0
            rows.append(E)
        A = np.vstack(rows)
        Z = null_space(A) if A.shape[0] else np.eye(m)
        cov = np.zeros((m, m))
        if Z.shape[1]:
            Gz = Z.T @ Gs @ Z
            if last["M"] is not None and self.lam > 0:
                Hz = Gz + self.lam * (last["M"] @ Z).T @ (last["M"] @ Z)
                Hi = np.linalg.pinv(Hz, hermitian=True)
                inner = Hi @ Gz @ Hi
            else:
                inner = np.linalg.pinv(Gz, hermitian=True)
            cov = Z @ inner @ Z.T
        s2 = float(rss_w) / max(int(n_train) - int(n_free), 1)
        # x = s theta / sigma and A^T W A = wsum diag(s) Gs diag(s)
        scale = 1.0 / s
        return s2 / last["wsum"] * cov * np.outer(scale, scale)


# ----------------------------------------------------------------------------


def solve_weights(R, d, lower=None, upper=None, C=None, lb=None, M=None, lam=0.0, fixed=None, solver=None,
                  cache=None):
    """The constrained least-squares solve of every identification front end.

    ``minimize ||R x - d||^2 + lam ||M x||^2`` subject to
    ``lower <= x <= upper``, ``C x >= lb`` and ``x[fixed] = 0``.

    Parameters
    ----------
    R : ndarray, shape (m, m)
        Factor of the (equilibrated) Gram matrix, ``R^T R = G``.
    d : ndarray, shape (m,)
        ``R^T d = b`` (the right-hand side in the factored form).
    lower, upper : ndarray, shape (m,), optional
        Bounds (``-inf`` / ``inf`` for none); default unbounded.
    C : ndarray, shape (p, m), optional
        Linear inequality constraints ``C x >= lb`` (e.g. the partial sums of
        an invertible PI model).
    lb : ndarray, shape (p,), optional
        Their right-hand side (required with `C`).
    M : ndarray, shape (q, m), optional
        Penalty rows (ridge, smoothness).
    lam : float
        Penalty weight.
    fixed : ndarray of bool, shape (m,), optional
        Coefficients held at 0.
    solver : str, optional
        cvxpy solver name (used only with `C` or `M`); default the first
        installed of CLARABEL, OSQP, SCS, ECOS.
    cache : dict, optional
        Where compiled cvxpy problems are kept between calls (keyed by shape).

    Returns
    -------
    x : ndarray or None
        The minimiser (None when the solver failed).
    status : str
        ``"optimal"`` or the solver's status.
    message : str
        The solver's error message, if any.

    Examples
    --------
    >>> R = np.eye(2); d = np.array([1.0, -1.0])
    >>> x, status, _ = solve_weights(R, d, lower=np.zeros(2))
    >>> np.round(x, 9).tolist(), status
    ([1.0, 0.0], 'optimal')
    """
    m = R.shape[1]
    if C is None and M is None:
        from scipy.optimize import lsq_linear

        lo = np.full(m, -np.inf) if lower is None else np.array(lower, dtype=np.float64)
        hi = np.full(m, np.inf) if upper is None else np.array(upper, dtype=np.float64)
        if fixed is not None:
            lo[fixed] = 0.0
            hi[fixed] = 0.0
            # lsq_linear needs lo < hi: a fixed coefficient gets a zero column instead
            R = R.copy()
            R[:, fixed] = 0.0
            lo[fixed], hi[fixed] = -1.0, 1.0
        if np.all(np.isinf(lo)) and np.all(np.isinf(hi)):
            x = np.linalg.lstsq(R, d, rcond=None)[0]
        else:
            x = lsq_linear(R, d, bounds=(lo, hi), method="bvls", tol=1e-12).x
        if fixed is not None:
            x[fixed] = 0.0
        return x, "optimal", ""
    if C is None:
        C = np.zeros((0, m))
        lb = np.zeros(0)
    if lower is not None or upper is not None:
        rows, rhs = [C], [lb]
        for bound, sign in ((lower, 1.0), (upper, -1.0)):
            if bound is None:
                continue
            bound = np.asarray(bound, dtype=np.float64)
            k = np.flatnonzero(np.isfinite(bound))
            E = np.zeros((k.size, m))
            E[np.arange(k.size), k] = sign
            rows.append(E)
            rhs.append(sign * bound[k])
        C, lb = np.vstack(rows), np.concatenate(rhs)
    fixed = np.zeros(m, bool) if fixed is None else np.asarray(fixed, bool)
    solver = _pick_solver(solver)
    key = (m, C.shape[0], 0 if M is None else M.shape[0], tuple(fixed), solver)
    cache = {} if cache is None else cache
    qp = cache.get(key)
    if qp is None:
        qp = cache[key] = _WeightQP(m, C.shape[0], key[2], fixed, solver)
    return qp.solve(R, d, C, lb, M, lam)

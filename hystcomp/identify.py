"""Identification of PI and mGPI models from measured data.

The output of a PI or symmetric mGPI model (eq. 49) is linear in its weights:

``y(t) = p0 gamma(v(t)) + sum_i p_i gamma(F_{r_i}[v](t)) + offset``

where F_r is the classical play (the state convention of
:mod:`hystcomp.models`: for one envelope the modified play equals
``gamma(F_r[v])``).  For given thresholds and envelope the weights are
therefore a linear least-squares problem with linear constraints.
:func:`fit_weights` builds the Gram matrix ``A^T W A`` and ``A^T W y`` block by
block (memory independent of the number of samples; the plays run in the
compiled kernel :func:`hystcomp._kernels.play_states`) and solves the
constrained problem with cvxpy.  :func:`fit` adds the envelope parameters by
variable projection (scipy.optimize outside, the convex weight problem
inside).  :func:`validate` and :func:`compensation_error` measure what a fit
is worth.
"""

import math
import warnings

import numpy as np

from . import _kernels as _k
from ._validation import as_scalar, as_signal, as_thresholds, check_choice
from .envelopes import Atanh, Custom, Envelope, Identity, Linear, Polynomial, Tanh
from .envelopes import extended_values as _extended
from .inverses import tracking_error
from .models import GPI, MGPI, PI
from .operators import modified_play

__all__ = ["FitResult", "EnvelopeFitResult", "HysteresisRegressor", "fit_weights", "fit", "validate",
           "compensation_error"]

#: samples per block when accumulating the Gram matrix
_BLOCK = 8192
#: lower bound of p0 (and of the partial sums) in scaled units: the p0
#: operator's contribution must be at least this fraction of the output RMS
_EPS = 1e-6


# ----------------------------------------------------------------------------
# input checking
# ----------------------------------------------------------------------------
def _is_record_list(x):
    if isinstance(x, (list, tuple)) and len(x) > 0:
        return all(np.ndim(e) == 1 for e in x)
    return False


def _records(v, y, sample_weight):
    """Lists of checked records (v_j, y_j, w_j)."""
    multi = _is_record_list(v)
    if multi != _is_record_list(y):
        raise ValueError(
            "Parameters v and y must both be arrays or both be lists of records; got "
            f"{type(v).__name__} and {type(y).__name__}"
        )
    vs = list(v) if multi else [v]
    ys = list(y) if multi else [y]
    if len(vs) != len(ys):
        raise ValueError(f"Parameter y has {len(ys)} records but v has {len(vs)}; expected one per record")
    if sample_weight is None:
        ws = [None] * len(vs)
    else:
        ws = list(sample_weight) if multi else [sample_weight]
        if len(ws) != len(vs):
            raise ValueError(
                f"Parameter sample_weight has {len(ws)} records but v has {len(vs)}; expected one per record"
            )
    out = []
    for j, (vj, yj, wj) in enumerate(zip(vs, ys, ws)):
        sfx = f"[{j}]" if multi else ""
        vj = as_signal(vj, "v" + sfx, min_length=1)
        yj = as_signal(yj, "y" + sfx, min_length=1)
        if vj.size != yj.size:
            raise ValueError(
                f"Parameter y{sfx} has {yj.size} samples but v{sfx} has {vj.size}; expected equal lengths"
            )
        if wj is not None:
            wj = as_signal(wj, "sample_weight" + sfx)
            if wj.size != vj.size:
                raise ValueError(
                    f"Parameter sample_weight{sfx} has {wj.size} samples but v{sfx} has {vj.size}; "
                    "expected equal lengths"
                )
            if np.any(wj < 0):
                k = int(np.argmax(wj < 0))
                raise ValueError(
                    f"Parameter sample_weight{sfx} is {wj[k]} at sample index {k}; expected weights >= 0"
                )
        out.append([vj, yj, wj])
    return out, multi


def _apply_validation(recs, validation, multi):
    """Zero the training weight of held-out samples; return the held-out masks
    (or separate validation records)."""
    if validation is None:
        return None, None
    if isinstance(validation, tuple) and len(validation) == 2:
        return None, validation
    if np.ndim(validation) == 0 and not isinstance(validation, (bool, np.bool_)):
        frac = as_scalar(validation, "validation")
        if not 0.0 < frac < 1.0:
            raise ValueError(
                f"Parameter validation is {frac} but a fraction must be in (0, 1) "
                "(the last part of each record is held out)"
            )
        masks = []
        for vj, _, _ in recs:
            m = np.zeros(vj.size, bool)
            m[int(round(vj.size * (1.0 - frac))):] = True
            masks.append(m)
    else:
        ms = list(validation) if multi else [validation]
        if len(ms) != len(recs):
            raise ValueError(f"Parameter validation has {len(ms)} masks but there are {len(recs)} records")
        masks = []
        for j, (m, (vj, _, _)) in enumerate(zip(ms, recs)):
            m = np.asarray(m)
            if m.dtype != bool or m.shape != vj.shape:
                raise ValueError(
                    f"Parameter validation[{j}] has dtype {m.dtype} and shape {m.shape}; expected a "
                    f"boolean mask of shape {vj.shape} (True = held out), a fraction or (v, y)"
                )
            masks.append(m)
    for rec, m in zip(recs, masks):
        w = np.ones(rec[0].size) if rec[2] is None else rec[2].copy()
        w[m] = 0.0
        rec[2] = w
    return masks, None


# ----------------------------------------------------------------------------
# regressors and Gram matrix
# ----------------------------------------------------------------------------
def _initial_positions(r, env):
    """Virgin play positions: gamma(z0) = 0 (models.MGPI.default_state)."""
    return MGPI(r, np.zeros(r.size), 1.0, envelope=env).default_state()


class _SymmetricRegressors:
    """PI / symmetric mGPI columns: gamma(v) (p0), gamma(F_{r_i}[v]) (p_i).

    The plays run in input coordinates (compiled classical play); a column
    is "unreached" when its play position never moves.
    """

    lead = 1

    def __init__(self, r, env):
        self.r, self.env = r, env
        self.N = r.size
        self._z0 = _initial_positions(r, env)

    def start(self):
        return self._z0.copy()

    def raw(self, vs, state, A):
        _k.play_states(vs, self.r, state, A[:, 1:self.N + 1])

    def finish(self, vs, A):
        N = self.N
        if isinstance(self.env, Identity):
            A[:, 0] = vs
        else:
            A[:, 0] = _extended(self.env, vs)
            A[:, 1:N + 1] = _extended(self.env, A[:, 1:N + 1])


class _AsymmetricRegressors:
    """Asymmetric mGPI columns: the modified plays w_0 (r = 0, weight p0) ..
    w_N with two envelopes (eq. 23), state w carried between blocks."""

    lead = 1

    def __init__(self, r, gl, gr):
        self.r, self.gl, self.gr = r, gl, gr
        self.N = r.size
        self.r_all = np.concatenate([[0.0], r])
        self.kl, self.pl = gl.kernel_spec()
        self.kr, self.pr = gr.kernel_spec()
        self.compiled = self.kl != _k.CUSTOM and self.kr != _k.CUSTOM

    def start(self):
        return np.zeros(self.N + 1)

    def raw(self, vs, state, A):
        if self.compiled:
            _k.mplay_states(vs, self.r_all, state, self.kl, self.pl, self.kr, self.pr, A[:, :self.N + 1])
        else:
            out, new = modified_play(vs, self.r_all, self.gl, self.gr, state=state)
            A[:, :self.N + 1] = out
            state[:] = new

    def finish(self, vs, A):
        pass


class _GPIRegressors:
    """GPI columns: H(v) (its coefficient, only when H is fitted) and the
    generalized plays of eq. 20 with a = gl(v), b = gr(v)."""

    def __init__(self, r, gl, gr, H):
        self.r, self.gl, self.gr, self.H = r, gl, gr, H
        self.N = r.size
        self.lead = 0 if H is None else 1

    def start(self):
        return np.zeros(self.N)

    def raw(self, vs, state, A):
        L = self.lead
        _k.two_input_play_states(self.gl._value(vs), self.gr._value(vs), self.r, state,
                                 A[:, L:L + self.N])

    def finish(self, vs, A):
        if self.lead:
            A[:, 0] = self.H._value(vs)


def _gram(recs, reg, offset):
    """Accumulate G = A^T W A, b = A^T W y, y^T W y over all records.

    Columns: ``reg.lead`` leading column(s) (p0 or H), the N operator columns
    of `reg`, and 1 (offset) -- built block by block, never the whole
    samples x operators matrix.  Also returns the range of every operator's
    raw output (play position or play output) over the training samples.
    """
    N, L = reg.N, reg.lead
    m = L + N + int(offset)
    G = np.zeros((m, m))
    b = np.zeros(m)
    yy = 0.0
    wsum = 0.0
    n_train = 0
    zmin = np.full(N, np.inf)
    zmax = np.full(N, -np.inf)
    block = np.empty((min(_BLOCK, max(rec[0].size for rec in recs)), m))
    for vj, yj, wj in recs:
        z = reg.start()
        for s in range(0, vj.size, _BLOCK):
            vs = vj[s:s + _BLOCK]
            ys = yj[s:s + _BLOCK]
            A = block[: vs.size]
            reg.raw(vs, z, A)
            if wj is not None:
                ws = wj[s:s + _BLOCK]
                keep = ws > 0
                if not keep.any():
                    continue
                if not keep.all():
                    A = A[keep]
                    vs, ys, ws = vs[keep], ys[keep], ws[keep]
            else:
                ws = None
            zmin = np.minimum(zmin, A[:, L:L + N].min(axis=0))
            zmax = np.maximum(zmax, A[:, L:L + N].max(axis=0))
            reg.finish(vs, A)
            if offset:
                A[:, L + N] = 1.0
            if ws is None:
                G += A.T @ A
                b += A.T @ ys
                yy += float(ys @ ys)
                wsum += vs.size
            else:
                Aw = A * ws[:, None]
                G += A.T @ Aw
                b += Aw.T @ ys
                yy += float(ys @ (ws * ys))
                wsum += float(ws.sum())
            n_train += vs.size
    return G, b, yy, wsum, n_train, zmin, zmax


# ----------------------------------------------------------------------------
# the convex weight problem
# ----------------------------------------------------------------------------
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


def _split_gram(G, b, free):
    """R, d with R^T R = G and R^T d = b on the free columns (eigen
    factorisation: robust when G is singular)."""
    m = G.shape[0]
    R = np.zeros((m, m))
    d = np.zeros(m)
    idx = np.flatnonzero(free)
    Gf = G[np.ix_(idx, idx)]
    lam, U = np.linalg.eigh(0.5 * (Gf + Gf.T))
    tol = max(lam.max(), 0.0) * m * 1e-13
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
        key = (m, lead, C.shape[0], 0 if M is None else M.shape[0], tuple(~free))
        qp = self._qp.get(key)
        if qp is None:
            qp = self._qp[key] = _WeightQP(m, C.shape[0], key[3], ~free, self.solver)
        x, status, err = qp.solve(R, d, C, lb, M, self.lam)
        if x is None or status in ("infeasible", "unbounded", "infeasible_inaccurate", "unbounded_inaccurate"):
            raise RuntimeError(
                f"the weight problem was not solved (cvxpy status {status!r} with solver "
                f"{self.solver}{': ' + err if err else ''})"
            )
        x = np.where(free, x, 0.0)
        theta = sigma * x / s
        # training MSE from the Gram form (exact up to rounding)
        mse = max(float(x @ Gs @ x - 2 * bs @ x) * sigma ** 2 + yy / wsum, 0.0)
        cond = float(np.linalg.cond(Gs[np.ix_(free, free)]))
        return theta, status, mse, cond


# ----------------------------------------------------------------------------
# results
# ----------------------------------------------------------------------------
class ValidationResult(dict):
    """Errors of a model on data (a dict): ``rms``, ``max`` (absolute),
    ``rms_percent``, ``max_percent`` (of the measured output's span),
    ``span``, ``n`` and ``residuals``."""

    def __repr__(self):
        return ("ValidationResult(rms={rms:.4g}, max={max:.4g}, rms_percent={rms_percent:.4g}%, "
                "max_percent={max_percent:.4g}%, n={n})").format(**self)


class FitResult:
    """Outcome of :func:`fit_weights`.

    Attributes
    ----------
    model : PI, MGPI or GPI
        The identified model (without the offset).
    weights, p0, offset : ndarray, float, float
        The identified parameters; predictions are ``model.simulate(v) + offset``.
        For a GPI fit ``p0`` is the coefficient of H (0 without H).
    envelope, envelope_left, envelope_right, H
        The envelopes used (``envelope`` None when gl != gr); H the fitted
        memoryless term of a GPI model.
    thresholds : ndarray
    rmse : float
        RMS of the residuals over the training samples (unweighted).
    residuals : ndarray or list of ndarray
        ``y - prediction`` for every sample (one array per record).
    aic, bic : float
        ``n ln(RSS/n) + 2k`` and ``n ln(RSS/n) + k ln n`` (n training
        samples, k free parameters).
    condition : float
        Condition number of the column-equilibrated Gram matrix (free columns).
    unreached : ndarray
        Thresholds whose play never moved over the training samples (weights
        fixed to 0).
    validation : ValidationResult or None
        Errors on the held-out samples.
    success, message, status : bool, str, str
        Solver outcome.

    Examples
    --------
    >>> import numpy as np
    >>> from hystcomp import PI
    >>> v = 3 * np.sin(np.linspace(0, 20, 3000))
    >>> y = PI([1.0, 2.0], [0.5, 0.2], p0=1.0).simulate(v) + 0.1
    >>> res = fit_weights(v, y, thresholds=[1.0, 2.0], model="pi")
    >>> np.round(res.weights, 4).tolist(), round(res.offset, 4), bool(res.rmse < 1e-6)
    ([0.5, 0.2], 0.1, True)
    >>> print(res.report().splitlines()[0])
    PI fit: 2 operators, 3000 training samples
    """

    def __init__(self, **kw):
        self.__dict__.update(kw)

    def predict(self, v, initial_state=None):
        """Model output plus offset for an input record.

        Parameters
        ----------
        v : array_like, shape (n_samples,)
            Input record.
        initial_state : ndarray, optional
            State of the model at the first sample (default: its virgin
            state, ``model.default_state()``).

        Returns
        -------
        ndarray, shape (n_samples,)
            ``model.simulate(v) + offset``.

        Examples
        --------
        >>> import numpy as np
        >>> from hystcomp import PI
        >>> v = 3 * np.sin(np.linspace(0, 20, 3000))
        >>> true = PI([1.0, 2.0], [0.5, 0.2], p0=1.0)
        >>> res = fit_weights(v, true.simulate(v) + 0.1, thresholds=[1.0, 2.0], model="pi")
        >>> bool(np.allclose(res.predict(v[:50]), true.simulate(v[:50]) + 0.1, atol=1e-6))
        True
        """
        return self.model.simulate(v, initial_state=initial_state) + self.offset

    def report(self):
        """A readable summary (str)."""
        lines = [
            f"{type(self.model).__name__} fit: {self.thresholds.size} operators, "
            f"{self.n_train} training samples",
            f"  solver: {self.solver} status={self.status} success={self.success}",
            f"  p0 = {self.p0:.6g}, offset = {self.offset:.6g}",
            f"  weights = {np.array2string(self.weights, precision=4, max_line_width=100)}",
            f"  rmse = {self.rmse:.6g}  aic = {self.aic:.6g}  bic = {self.bic:.6g}  "
            f"condition = {self.condition:.3g}",
        ]
        if getattr(self, "envelope", None) is not None and not isinstance(self.envelope, Identity):
            lines.insert(1, f"  envelope: {self.envelope!r}")
        if self.unreached.size:
            lines.append(f"  unreached thresholds (weights fixed to 0): {self.unreached.tolist()}")
        if self.validation is not None:
            val = self.validation
            lines.append(
                f"  validation: rms = {val['rms']:.6g} ({val['rms_percent']:.4g} % of span), "
                f"max = {val['max']:.6g} ({val['max_percent']:.4g} %), n = {val['n']}"
            )
        if self.message:
            lines.append(f"  message: {self.message}")
        return "\n".join(lines)

    def __repr__(self):
        return (f"FitResult(model={self.model!r}, rmse={self.rmse:.4g}, "
                f"success={self.success})")


def _default_thresholds(recs, n=20):
    vmin = min(float(rec[0].min()) for rec in recs)
    vmax = max(float(rec[0].max()) for rec in recs)
    # equally spaced in (0, span/2), the last one below span/2 so that a
    # signal that sweeps the span moves every play
    return 0.5 * (vmax - vmin) * np.arange(1, n + 1) / (n + 1)


def _check_data(recs, min_samples):
    n = sum(int(np.count_nonzero(rec[2])) if rec[2] is not None else rec[0].size for rec in recs)
    if n < min_samples:
        raise ValueError(
            f"Parameters v, y give {n} training samples (non-zero weight) but at least "
            f"{min_samples} are needed for {min_samples - 1} parameters plus one"
        )
    vmin = min(float(rec[0].min()) for rec in recs)
    vmax = max(float(rec[0].max()) for rec in recs)
    if vmax - vmin <= 1e-12 * max(abs(vmin), abs(vmax), 1.0):
        raise ValueError(
            f"Parameter v is constant ({vmin}); identification needs an input that moves"
        )


def _resolve_envelopes(model, envelope, envelope_left, envelope_right, H):
    """(regressor kind "sym" | "asym" | "gpi", gl, gr) from the arguments."""
    for name, g in (("envelope", envelope), ("envelope_left", envelope_left),
                    ("envelope_right", envelope_right)):
        if g is not None and not isinstance(g, Envelope):
            raise TypeError(f"Parameter {name} is {g!r} but should be an hystcomp Envelope")
    sides = envelope_left is not None or envelope_right is not None
    if envelope is not None and sides:
        raise ValueError("Parameter envelope sets both sides; pass either envelope or "
                         "envelope_left/envelope_right, not both")
    if model != "gpi" and H is not None:
        raise ValueError(f"Parameter H is {H!r} but only model='gpi' has a memoryless term H")
    if model == "gpi" and H is not None and not isinstance(H, Envelope):
        H = as_scalar(H, "H")
    if model == "pi":
        if (envelope is not None and not isinstance(envelope, Identity)) or sides:
            raise ValueError(f"Parameter envelope is {envelope!r} but model='pi' uses the identity; "
                             "use model='mgpi' (or 'gpi') for envelopes")
        g = Identity()
        return "sym", g, g
    if model == "mgpi":
        if sides and (envelope_left is None or envelope_right is None):
            raise ValueError("Parameters envelope_left and envelope_right go together for "
                             "model='mgpi'; pass both, or envelope for a symmetric model")
        if not sides:
            g = Identity() if envelope is None else envelope
            return "sym", g, g
        if envelope_left == envelope_right:
            return "sym", envelope_left, envelope_left
        return "asym", envelope_left, envelope_right
    # gpi
    if envelope is None and envelope_left is None:
        raise ValueError("Parameter envelope_left is None but model='gpi' needs its envelopes "
                         "(envelope for gl = gr, or envelope_left and envelope_right)")
    gl = envelope if envelope is not None else envelope_left
    gr = envelope if envelope is not None else (envelope_right if envelope_right is not None else gl)
    return "gpi", gl, gr


def _scaled(env, c):
    """The envelope c * env (c > 0), in the same family when there is one."""
    if isinstance(env, Identity):
        return Linear(c)
    if isinstance(env, Linear):
        return Linear(c * env.k)
    if isinstance(env, Tanh):
        return Tanh(c * env.a, env.b, env.c)
    if isinstance(env, Atanh):
        return Atanh(c * env.a, env.b, c * env.offset)
    if isinstance(env, Polynomial):
        return Polynomial(c * np.asarray(env.coeffs), interval=env.domain)
    return Custom(lambda x: c * env._value(x), lambda x: c * env._derivative(x),
                  lambda y: env._inverse(y / c), domain=env.domain,
                  range=(c * env.range[0], c * env.range[1]), name=f"{c:.6g}*{env!r}")



def fit_weights(v, y, thresholds=None, envelope=None, model="mgpi", constraints="nonnegative",
                regularization=None, offset=True, solver=None, sample_weight=None, validation=None,
                n_thresholds=20, envelope_left=None, envelope_right=None, H=None,
                _problem=None, _warn=True):
    """Identify the weights of a PI, mGPI or GPI model by constrained least squares.

    Solves ``min sum_k w_k (y_k - yhat_k)^2`` (plus an optional penalty) over
    p0, p_1..p_N and an offset, where ``yhat = p0 gamma(v) + sum_i p_i
    gamma(F_{r_i}[v]) + offset`` (eq. 49), on the Gram matrix ``A^T W A``
    accumulated block by block, with cvxpy.

    Parameters
    ----------
    v, y : array_like or list of array_like
        Input and measured output; a list gives several records, each
        starting from the virgin state (operator outputs 0).
    thresholds : array_like, optional
        r_1 < ... < r_N; default `n_thresholds` equally spaced in
        (0, (max v - min v)/2).
    envelope : Envelope, optional
        gamma of the mGPI model (default Identity: the PI model); for
        model="gpi" it sets gl = gr.
    model : {"mgpi", "pi", "gpi"}
        "pi" requires ``envelope=None``.  "mgpi" with `envelope_left` and
        `envelope_right` (different) is the asymmetric mGPI: its columns are
        the modified plays w_0 (r = 0, weight p0) .. w_N with two envelopes
        (eq. 23).  "gpi": columns are the generalized plays of eq. 20 (a =
        gl(v), b = gr(v)) and, when `H` is given, H(v) with its own fitted
        coefficient (returned as ``p0``; ``.model`` is a :class:`~hystcomp.GPI`
        whose H is that coefficient times the given shape).
    envelope_left, envelope_right : Envelope, optional
        gl and gr apart (model "mgpi": both needed; "gpi": gr defaults to gl).
    H : None, float or Envelope, optional
        model="gpi" only.  None: no memoryless term (H = 0, p0 = 0, and
        without a leading column the constraints bound every weight by 0);
        an Envelope: the shape of H, scaled by a fitted coefficient > 0; a
        number: H(v) = c v with c fitted (the number itself is not used).
    constraints : {"nonnegative", "invertible"}
        "nonnegative": p0 > 0, p_i >= 0 (the inverse always exists);
        "invertible": all partial sums p0 + p_1 + ... + p_j > 0 (eq. 53).
        "> 0" means at least 1e-6 of the output RMS in p0's contribution.
    regularization : None, ("ridge", lam) or ("smooth", lam)
        Dimensionless penalty added to MSE/RMS(y)^2: ridge on the operators'
        contributions ``sum (s_i p_i / RMS(y))^2`` (s_i the RMS of column i),
        smooth on the first differences of the density p_i/(r_i - r_{i-1})
        scaled by r_N and the median column RMS.
    offset : bool
        Fit a constant output offset (returned apart from the model).
    solver : str, optional
        A cvxpy solver name; default the first installed of CLARABEL, OSQP, SCS.
    sample_weight : array_like or list, optional
        Non-negative weight per sample; 0 excludes a sample from the fit (the
        operators still run through it).
    validation : None, float, boolean mask(s) or (v_val, y_val)
        Held-out data: a fraction (the last part of each record), masks
        (True = held out, same shape as the records; the operators run
        through them) or separate records.  Reported in ``result.validation``.
    n_thresholds : int
        Number of default thresholds.

    Returns
    -------
    FitResult

    Warns
    -----
    UserWarning
        Naming the thresholds whose play never moves over the training
        samples: their columns are constant, their weights are not
        identifiable and are fixed to 0.

    Examples
    --------
    >>> import numpy as np
    >>> from hystcomp import PI
    >>> t = np.linspace(0, 2, 4001)
    >>> v = 3 * np.sin(2 * np.pi * t)
    >>> true = PI([0.5, 1.0, 1.5, 2.0], [0.4, 0.3, 0.2, 0.1], p0=1.0)
    >>> res = fit_weights(v, true.simulate(v), thresholds=true.thresholds, model="pi")
    >>> np.round(res.weights, 4).tolist(), round(res.p0, 4)
    ([0.4, 0.3, 0.2, 0.1], 1.0)

    A GPI model with a memoryless term H = 0.5 tanh(0.2 v) (shape given, scale fitted):

    >>> from hystcomp import GPI
    >>> from hystcomp.envelopes import Tanh
    >>> gpi = GPI([0.5, 1.0], [0.6, 0.3], Tanh(5, 0.2), Tanh(5, 0.3), H=Tanh(0.5, 0.2))
    >>> res = fit_weights(v, gpi.simulate(v), thresholds=[0.5, 1.0], model="gpi",
    ...                   envelope_left=Tanh(5, 0.2), envelope_right=Tanh(5, 0.3), H=Tanh(1, 0.2))
    >>> np.round(res.weights, 4).tolist(), round(res.p0, 4), round(res.model.H.a, 4)
    ([0.6, 0.3], 0.5, 0.5)
    """
    check_choice(model, "model", ("mgpi", "pi", "gpi"))
    reg_kind, gl, gr = _resolve_envelopes(model, envelope, envelope_left, envelope_right, H)
    recs, multi = _records(v, y, sample_weight)
    masks, val_records = _apply_validation(recs, validation, multi)
    if thresholds is None:
        r = _default_thresholds(recs, int(n_thresholds))
    else:
        r = as_thresholds(thresholds)
    lead = 0 if (reg_kind == "gpi" and H is None) else 1
    _check_data(recs, r.size + lead + 1 + int(bool(offset)))
    H_shape = None
    if reg_kind == "gpi" and H is not None:
        H_shape = H if isinstance(H, Envelope) else Linear(1.0)
    envs = [gl] if gr is gl else [gl, gr]
    if H_shape is not None:
        envs.append(H_shape)
    for env in envs:
        for j, rec in enumerate(recs):
            lo, hi = env.domain
            bad = (rec[0] <= lo) | (rec[0] >= hi) if env.domain_open else (rec[0] < lo) | (rec[0] > hi)
            if bad.any():
                k = int(np.argmax(bad))
                raise ValueError(
                    f"Parameter v{f'[{j}]' if multi else ''} is {rec[0][k]} at sample index {k}, outside "
                    f"the domain {env.domain} of the envelope {env!r}"
                )
    if reg_kind == "sym":
        reg = _SymmetricRegressors(r, gl)
    elif reg_kind == "asym":
        reg = _AsymmetricRegressors(r, gl, gr)
    else:
        reg = _GPIRegressors(r, gl, gr, H_shape)
    prob = _problem or _Problem(r, constraints, regularization, offset, solver)
    G, b, yy, wsum, n_train, zmin, zmax = _gram(recs, reg, offset)
    if wsum <= 0:
        raise ValueError("Parameter sample_weight is zero on every sample; nothing to fit")
    moved = zmax - zmin
    if reg_kind == "sym":
        # play positions are in input units
        span = max(float(rec[0].max() - rec[0].min()) for rec in recs)
        unreached = moved <= 1e-12 * span
    else:
        # operator outputs: constant relative to the most active operator
        unreached = moved <= 1e-12 * float(np.max(moved, initial=0.0))
    if unreached.any() and _warn:
        warnings.warn(
            f"thresholds {r[unreached].tolist()} are never reached by the training data (their "
            "play does not move, the column is constant): their weights are not identifiable "
            "and are fixed to 0",
            UserWarning, stacklevel=2,
        )
    theta, status, mse, cond = prob.solve(G, b, yy, wsum, unreached, lead=lead)
    p0 = float(theta[0]) if lead else 0.0
    p = theta[lead:lead + r.size].copy()
    off = float(theta[lead + r.size]) if offset else 0.0
    H_fit = None
    if reg_kind == "sym":
        mdl = PI(r, p, p0) if isinstance(gl, Identity) else MGPI(r, p, p0, envelope=gl)
    elif reg_kind == "asym":
        mdl = MGPI(r, p, p0, envelope_left=gl, envelope_right=gr)
    else:
        if H_shape is not None:
            H_fit = p0 if not isinstance(H, Envelope) else _scaled(H, p0)
        mdl = GPI(r, p, gl, gr, H=H_fit)
    envelope = gl if reg_kind == "sym" else None
    # residuals over every sample (model simulation from the virgin state)
    residuals = [rec[1] - (mdl.simulate(rec[0]) + off) for rec in recs]
    rss = 0.0
    for rec, e in zip(recs, residuals):
        keep = rec[2] > 0 if rec[2] is not None else slice(None)
        rss += float(np.sum(e[keep] ** 2))
    n = n_train
    k = r.size + lead + int(offset) - int(unreached.sum())
    rmse = math.sqrt(rss / n)
    ll = n * math.log(max(rss / n, np.finfo(float).tiny))
    success = status == "optimal"
    message = "" if success else f"cvxpy status {status!r}"
    result = FitResult(
        model=mdl, weights=p, p0=p0, offset=off, thresholds=r, envelope=envelope,
        envelope_left=gl, envelope_right=gr, H=H_fit,
        rmse=rmse, residuals=residuals if multi else residuals[0],
        aic=ll + 2 * k, bic=ll + k * math.log(n), condition=cond, n_train=n, n_parameters=k,
        unreached=r[unreached], success=success, status=status, message=message,
        solver=prob.solver, train_mse=mse, validation=None,
    )
    if masks is not None:
        e = np.concatenate([res[m] for res, m in zip(residuals, masks)])
        yv = np.concatenate([rec[1][m] for rec, m in zip(recs, masks)])
        result.validation = _errors(e, yv)
    elif val_records is not None:
        result.validation = validate(result, *val_records)
    return result


# ----------------------------------------------------------------------------
# validation
# ----------------------------------------------------------------------------
def _errors(e, y):
    if e.size == 0:
        raise ValueError("Parameter validation holds no samples; expected at least one held-out sample")
    span = float(y.max() - y.min()) or 1.0
    rms = float(np.sqrt(np.mean(e * e)))
    mx = float(np.max(np.abs(e)))
    return ValidationResult(rms=rms, max=mx, rms_percent=100 * rms / span, max_percent=100 * mx / span,
                            span=span, n=int(e.size), residuals=e)


def validate(model, v, y, offset=0.0, mask=None):
    """Errors of a model (or a :class:`FitResult`, with its offset) on data.

    The model runs from its virgin state over each whole record; `mask`
    (True = evaluated) selects the samples that count, so a record can carry
    a warm-up that is simulated but not scored.

    Parameters
    ----------
    model : HysteresisModel or FitResult
    v, y : array_like or list of array_like
    offset : float
        Added to the model output (ignored for a FitResult, which has its own).
    mask : array_like of bool or list, optional

    Returns
    -------
    ValidationResult
        ``rms``, ``max``, ``rms_percent``, ``max_percent`` (of the span of
        the measured y on the scored samples), ``span``, ``n``, ``residuals``.

    Examples
    --------
    >>> import numpy as np
    >>> from hystcomp import PI
    >>> m = PI([1.0], [0.5], p0=1.0)
    >>> v = 2 * np.sin(np.linspace(0, 10, 500))
    >>> validate(m, v, m.simulate(v) + 0.01)["rms"].__round__(6)
    0.01
    """
    if isinstance(model, FitResult):
        offset = model.offset
        model = model.model
    offset = as_scalar(offset, "offset")
    recs, multi = _records(v, y, None)
    if mask is None:
        masks = [np.ones(rec[0].size, bool) for rec in recs]
    else:
        masks = list(mask) if multi else [mask]
        masks = [np.asarray(m, bool) for m in masks]
        for j, (m, rec) in enumerate(zip(masks, recs)):
            if m.shape != rec[0].shape:
                raise ValueError(f"Parameter mask{f'[{j}]' if multi else ''} has shape {m.shape} but "
                                 f"the record has {rec[0].shape}")
    e = np.concatenate([(rec[1] - model.simulate(rec[0]) - offset)[m] for rec, m in zip(recs, masks)])
    yv = np.concatenate([rec[1][m] for rec, m in zip(recs, masks)])
    return _errors(e, yv)


def compensation_error(true_model, estimated_model, u):
    """Tracking error of ``true_model o estimated_model^-1`` on a reference u.

    The question the thesis leaves open (section 6.2): how well does a
    compensator built from an identified model cancel the true hysteresis?
    The compensator is ``estimated_model.exact_inverse()``.

    Parameters
    ----------
    true_model : HysteresisModel
    estimated_model : HysteresisModel or FitResult
        (a FitResult's offset is ignored: compensation acts on the model.)
    u : array_like
        Reference output.

    Returns
    -------
    TrackingError
        See :func:`hystcomp.inverses.tracking_error`.

    Examples
    --------
    >>> import numpy as np
    >>> from hystcomp import PI
    >>> true = PI([1.0, 2.0], [0.5, 0.25], p0=1.0)
    >>> est = PI([1.0, 2.0], [0.45, 0.25], p0=1.0)
    >>> err = compensation_error(true, est, 3 * np.sin(np.linspace(0, 10, 400)))
    >>> bool(0 < err["rms_percent"] < 5)
    True
    """
    if isinstance(estimated_model, FitResult):
        estimated_model = estimated_model.model
    return tracking_error(true_model, estimated_model.exact_inverse(), u)


# ----------------------------------------------------------------------------
# envelopes by variable projection
# ----------------------------------------------------------------------------
class EnvelopeFitResult(FitResult):
    """Outcome of :func:`fit`: a :class:`FitResult` plus ``envelope``,
    ``envelope_parameters``, ``cost`` (final training MSE), ``converged``,
    ``optimizer_message``, ``nfev`` and ``at_bound`` (indices of parameters
    that ended on a bound of the search interval).

    Examples
    --------
    >>> import numpy as np
    >>> from hystcomp import MGPI
    >>> from hystcomp.envelopes import Tanh
    >>> v = 3 * np.sin(np.linspace(0, 20, 3000))
    >>> true = MGPI([1.0, 2.0], [0.5, 0.2], 1.0, envelope=Tanh(1 / 0.3, 0.3))
    >>> res = fit(v, true.simulate(v), thresholds=[1.0, 2.0])
    >>> round(res.envelope.b, 4), bool(res.converged), res.at_bound
    (0.3, True, [])
    """

    def report(self):
        env = (repr(self.envelope) if self.envelope is not None
               else f"left {self.envelope_left!r}, right {self.envelope_right!r}")
        head = (f"envelope fit: {env}; parameters {self.envelope_parameters}; "
                f"cost (training MSE) = {self.cost:.6g}; converged = {self.converged} "
                f"({self.optimizer_message}); {self.nfev} evaluations")
        if self.at_bound:
            head += f"\n  parameters {self.at_bound} ended on a bound of the search interval"
        return head + "\n" + super().report()


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


def fit(v, y, envelope="tanh", asymmetric=False, thresholds=None, constraints="nonnegative",
        regularization=None, offset=True, solver=None, sample_weight=None, validation=None,
        n_thresholds=20, maxiter=60, optimizer=None):
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
        As in :func:`fit_weights`.
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

    kw = dict(thresholds=thresholds, constraints=constraints, regularization=regularization,
              offset=offset, solver=solver, sample_weight=sample_weight, validation=validation,
              n_thresholds=n_thresholds)
    if envelope == "linear" and not asymmetric:
        res = fit_weights(v, y, model="pi", **kw)
        out = EnvelopeFitResult(**res.__dict__)
        out.envelope_parameters = []
        out.cost, out.converged, out.optimizer_message, out.nfev = res.train_mse, True, \
            "no envelope parameter (Linear(k) only rescales the weights)", 0
        out.at_bound = []
        return out
    recs, _ = _records(v, y, sample_weight)
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
    out = EnvelopeFitResult(**res.__dict__)
    out.envelope_parameters = np.asarray(xbest).tolist()
    out.cost = res.train_mse
    out.converged = success
    out.optimizer_message = message
    out.nfev = nfev
    # parameters that ended on a bound of the search box (e.g. tanh with
    # b -> 0 is the PI model): worth saying, the optimum may lie outside
    out.at_bound = [i for i, (x, (lo, hi)) in enumerate(zip(xbest, bounds))
                    if min(x - lo, hi - x) <= 1e-3 * (hi - lo)]
    return out


# ----------------------------------------------------------------------------
# scikit-learn style estimator
# ----------------------------------------------------------------------------
class HysteresisRegressor:
    """A scikit-learn style wrapper of :func:`fit_weights` and :func:`fit`.

    Hyper-parameters are set in ``__init__`` and stored unchanged;
    ``fit(v, y)`` returns ``self`` and sets the fitted attributes (names
    ending in ``_``); ``predict(v)`` runs the fitted model from its virgin
    state and adds the offset.  (It follows the estimator conventions without
    depending on scikit-learn: v is a 1-D signal, not a feature matrix,
    because the model has memory.)

    Parameters
    ----------
    model : {"pi", "mgpi", "gpi"}
    thresholds : array_like, optional
        Default: `n_thresholds` equally spaced over the data (as :func:`fit_weights`).
    envelope : None, Envelope or family name
        An :class:`~hystcomp.envelopes.Envelope` is used as given (for
        model="gpi" it sets gl = gr); a family name ("tanh", "atanh",
        "polynomial", "linear") is fitted by :func:`fit` (model="mgpi" only).
    envelope_left, envelope_right : Envelope, optional
        Given asymmetric envelopes (model "mgpi" or "gpi").
    asymmetric : bool
        With a family name: fit gl and gr apart.
    H : None, float or Envelope
        Memoryless term of model="gpi" (its coefficient is fitted).
    constraints, regularization, offset, n_thresholds, solver
        As in :func:`fit_weights`.

    Attributes
    ----------
    result_ : FitResult
    model_ : PI, MGPI or GPI
    weights_, p0_, offset_, thresholds_, rmse_ : the fitted values

    Examples
    --------
    >>> import numpy as np
    >>> from hystcomp import PI
    >>> v = 3 * np.sin(np.linspace(0, 20, 3000))
    >>> true = PI([0.5, 1.0, 1.5], [0.3, 0.2, 0.1], p0=1.0)
    >>> est = HysteresisRegressor(model="pi", thresholds=[0.5, 1.0, 1.5]).fit(v, true.simulate(v))
    >>> np.round(est.weights_, 4).tolist()
    [0.3, 0.2, 0.1]
    >>> float(np.max(np.abs(est.predict(v) - true.simulate(v)))) < 1e-5
    True
    """

    def __init__(self, model="mgpi", thresholds=None, envelope=None, envelope_left=None,
                 envelope_right=None, asymmetric=False, H=None, constraints="nonnegative",
                 regularization=None, offset=True, n_thresholds=20, solver=None):
        self.model = model
        self.thresholds = thresholds
        self.envelope = envelope
        self.envelope_left = envelope_left
        self.envelope_right = envelope_right
        self.asymmetric = asymmetric
        self.H = H
        self.constraints = constraints
        self.regularization = regularization
        self.offset = offset
        self.n_thresholds = n_thresholds
        self.solver = solver

    _PARAMS = ("model", "thresholds", "envelope", "envelope_left", "envelope_right", "asymmetric",
               "H", "constraints", "regularization", "offset", "n_thresholds", "solver")

    def get_params(self, deep=True):
        """The hyper-parameters (dict), as scikit-learn's ``get_params``.

        Parameters
        ----------
        deep : bool
            Accepted for scikit-learn compatibility; the hyper-parameters
            hold no sub-estimators, so it changes nothing.

        Returns
        -------
        dict
            Hyper-parameter name -> value.

        Examples
        --------
        >>> HysteresisRegressor(model="pi", n_thresholds=5).get_params()["n_thresholds"]
        5
        """
        return {k: getattr(self, k) for k in self._PARAMS}

    def set_params(self, **params):
        """Set hyper-parameters; returns self.

        Parameters
        ----------
        **params
            Hyper-parameter name -> new value (names of ``__init__``).

        Returns
        -------
        HysteresisRegressor
            self.

        Raises
        ------
        ValueError
            For a name that is not a hyper-parameter.

        Examples
        --------
        >>> HysteresisRegressor().set_params(model="pi").model
        'pi'
        """
        for k, val in params.items():
            if k not in self._PARAMS:
                raise ValueError(f"Parameter {k!r} is not a hyper-parameter of HysteresisRegressor; "
                                 f"expected one of {list(self._PARAMS)}")
            setattr(self, k, val)
        return self

    def fit(self, v, y, sample_weight=None, validation=None):
        """Identify the model from input `v` and output `y` (arrays or lists
        of records); returns self.

        Parameters
        ----------
        v, y : array_like or list of array_like
            Input and measured output, as in :func:`fit_weights`.
        sample_weight : array_like or list, optional
            Non-negative weight per sample, as in :func:`fit_weights`.
        validation : None, float, boolean mask(s) or (v_val, y_val)
            Held-out data, as in :func:`fit_weights`.

        Returns
        -------
        HysteresisRegressor
            self, with the fitted attributes set.

        Examples
        --------
        >>> import numpy as np
        >>> from hystcomp import PI
        >>> v = 3 * np.sin(np.linspace(0, 20, 3000))
        >>> est = HysteresisRegressor(model="pi", thresholds=[1.0, 2.0])
        >>> est.fit(v, PI([1.0, 2.0], [0.5, 0.2], p0=1.0).simulate(v)) is est
        True
        """
        kw = dict(thresholds=self.thresholds, constraints=self.constraints,
                  regularization=self.regularization, offset=self.offset,
                  n_thresholds=self.n_thresholds, solver=self.solver,
                  sample_weight=sample_weight, validation=validation)
        if isinstance(self.envelope, (str, tuple)):
            if self.model != "mgpi":
                raise ValueError(f"Parameter envelope is {self.envelope!r} (a family to fit) but "
                                 f"model is {self.model!r}; envelope families are fitted for 'mgpi'")
            res = fit(v, y, envelope=self.envelope, asymmetric=self.asymmetric, **kw)
        else:
            res = fit_weights(v, y, model=self.model, envelope=self.envelope,
                              envelope_left=self.envelope_left, envelope_right=self.envelope_right,
                              H=self.H, **kw)
        self.result_ = res
        self.model_ = res.model
        self.weights_ = res.weights
        self.p0_ = res.p0
        self.offset_ = res.offset
        self.thresholds_ = res.thresholds
        self.rmse_ = res.rmse
        return self

    def predict(self, v):
        """Model output plus offset for an input record (from the virgin state).

        Parameters
        ----------
        v : array_like, shape (n_samples,)
            Input record.

        Returns
        -------
        ndarray, shape (n_samples,)

        Examples
        --------
        >>> import numpy as np
        >>> from hystcomp import PI
        >>> v = 3 * np.sin(np.linspace(0, 20, 3000))
        >>> true = PI([1.0, 2.0], [0.5, 0.2], p0=1.0)
        >>> est = HysteresisRegressor(model="pi", thresholds=[1.0, 2.0]).fit(v, true.simulate(v))
        >>> bool(np.allclose(est.predict(v), true.simulate(v), atol=1e-6))
        True
        """
        if not hasattr(self, "result_"):
            raise RuntimeError("This HysteresisRegressor is not fitted yet; call fit(v, y) first")
        return self.result_.predict(v)

    def score(self, v, y):
        """Coefficient of determination R^2 of ``predict(v)`` against y.

        Parameters
        ----------
        v : array_like, shape (n_samples,)
            Input record.
        y : array_like, shape (n_samples,)
            Measured output.

        Returns
        -------
        float
            ``1 - sum(e^2) / sum((y - mean y)^2)``; 1 is a perfect fit.

        Examples
        --------
        >>> import numpy as np
        >>> from hystcomp import PI
        >>> v = 3 * np.sin(np.linspace(0, 20, 3000))
        >>> y = PI([1.0, 2.0], [0.5, 0.2], p0=1.0).simulate(v)
        >>> est = HysteresisRegressor(model="pi", thresholds=[1.0, 2.0]).fit(v, y)
        >>> round(est.score(v, y), 6)
        1.0
        """
        y = as_signal(y, "y")
        e = y - self.predict(v)
        return 1.0 - float(e @ e) / float(np.sum((y - y.mean()) ** 2))

    def __repr__(self):
        args = ", ".join(f"{k}={getattr(self, k)!r}" for k in self._PARAMS)
        return f"HysteresisRegressor({args})"


# ----------------------------------------------------------------------------
# the other models of the thesis's survey (issue 7): Preisach, KP, Bouc-Wen,
# backlash-like, Duhem, and a side-by-side comparison
# ----------------------------------------------------------------------------
class ModelFit:
    """Outcome of :func:`fit_preisach`, :func:`fit_kp`, :func:`fit_bouc_wen`,
    :func:`fit_backlash_like` and :func:`fit_duhem`.

    Attributes
    ----------
    model : HysteresisModel
        The identified model (its offset included: ``model.simulate(v)``
        predicts y).
    rmse : float
        RMS of the training residuals.
    n_parameters : int
        Number of fitted parameters (weights or shape parameters, offset).
    fit_time : float
        Wall time of the fit [s].
    success : bool
        The optimiser's convergence flag.
    message : str
        The optimiser's message.

    Examples
    --------
    >>> import numpy as np
    >>> from hystcomp.differential import BacklashLike
    >>> v = 4 * np.sin(np.linspace(0, 20, 2000))
    >>> res = fit_backlash_like(v, BacklashLike(alpha=1.5, c=3.0, B1=1.0).simulate(v))
    >>> res.n_parameters, bool(res.rmse < 1e-6), bool(res.success)
    (4, True, True)
    """

    def __init__(self, **kw):
        self.__dict__.update(kw)

    def predict(self, v, initial_state=None):
        """The model's output (offset included).

        Parameters
        ----------
        v : array_like, shape (n_samples,)
            Input record.
        initial_state : ndarray, optional
            State of the model at the first sample (default:
            ``model.default_state()``).

        Returns
        -------
        ndarray, shape (n_samples,)

        Examples
        --------
        >>> import numpy as np
        >>> from hystcomp.differential import BacklashLike
        >>> v = 4 * np.sin(np.linspace(0, 20, 2000))
        >>> true = BacklashLike(alpha=1.5, c=3.0, B1=1.0)
        >>> res = fit_backlash_like(v, true.simulate(v))
        >>> bool(np.allclose(res.predict(v), true.simulate(v), atol=1e-6))
        True
        """
        return self.model.simulate(v, initial_state=initial_state)

    def report(self):
        """A readable summary (str)."""
        return (f"{self.model!r}\n  {self.n_parameters} parameters, training rmse = {self.rmse:.6g}, "
                f"fit time = {self.fit_time:.3g} s, success = {self.success}"
                + (f"\n  message: {self.message}" if self.message else ""))

    def __repr__(self):
        return f"ModelFit(model={self.model!r}, rmse={self.rmse:.4g}, success={self.success})"


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
    if m <= 300:
        C = np.zeros((K, m))
        C[np.arange(K), np.arange(K)] = 1.0
        M = np.zeros((K, m))
        M[np.arange(K), np.arange(K)] = 1.0
        qp = _WeightQP(m, K, K, ~free, _pick_solver(solver))
        x, status, err = qp.solve(R, d, C, np.zeros(K), M, regularization)
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


def _plane_fit(kind, v, y, n, input_range, regularization, solver, progress):
    import time

    from .preisach import KP, Preisach, preisach_grid
    from . import _kernels_other as _ko

    t0 = time.perf_counter()
    x = as_signal(v, "v")
    yv = as_signal(y, "y")
    if x.size != yv.size:
        raise ValueError(f"Parameter y has {yv.size} samples but v has {x.size}; expected equal lengths")
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
        xs, ys = x[s0:s0 + _BLOCK], yv[s0:s0 + _BLOCK]
        if kind == "preisach":
            S = _ko.preisach_segments(xs, proto.v_min, proto.h, k, starts, states)
            # rows: one per segment of constant state, weighted by its length
            cnt = np.diff(np.append(starts[:S], xs.size)).astype(np.float64)
            ysum = np.add.reduceat(ys, starts[:S])
            rows = np.where(cj[None, :] < states[:S][:, ci], 1.0, -1.0)
            rows = np.hstack([rows, np.ones((S, 1))])
            G += rows.T @ (rows * cnt[:, None])
            bvec += rows.T @ ysum
        else:
            Ab = A[: xs.size]
            _ko.kp_regressors(xs, proto.v_min, proto.h, z, cd, cj.astype(np.int64), Ab)
            rows = np.hstack([Ab, np.ones((xs.size, 1))])
            G += rows.T @ rows
            bvec += rows.T @ ys
        if progress and nblocks > 4:
            import sys

            done = (bi + 1) / nblocks
            sys.stderr.write(f"\r{kind} regressors [{'#' * int(30 * done):<30}] {100 * done:5.1f}%")
            if bi + 1 == nblocks:
                sys.stderr.write("\n")
    theta, status = _plane_solve(G, bvec, float(yv @ yv), float(x.size), regularization, solver)
    mu = np.zeros((n, n))
    mu[ci, cj] = theta[:K]
    model = cls(input_range, mu, float(theta[K]))
    e = yv - model.simulate(x)
    return ModelFit(model=model, rmse=float(np.sqrt(np.mean(e * e))), n_parameters=K + 1,
                    fit_time=time.perf_counter() - t0, success=status in ("optimal", "optimal_inaccurate"),
                    message="" if status == "optimal" else f"cvxpy status {status}", residuals=e)


def fit_preisach(v, y, n=20, input_range=None, regularization=1e-6, solver=None, progress=False):
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
        cvxpy solver (default: the first of CLARABEL, OSQP, SCS, ECOS).
    progress : bool
        Progress bar on stderr.

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
    return _plane_fit("preisach", v, y, n, input_range, regularization, solver, progress)


def fit_kp(v, y, n=20, input_range=None, regularization=1e-6, solver=None, progress=False):
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
        cvxpy solver (default: the first of CLARABEL, OSQP, SCS, ECOS).
    progress : bool
        Progress bar on stderr.

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
    return _plane_fit("kp", v, y, n, input_range, regularization, solver, progress)


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
    return ModelFit(model=model, rmse=float(np.sqrt(np.mean(e * e))), n_parameters=len(best.x) + n_linear,
                    fit_time=time.perf_counter() - t0, success=bool(best.success), message=best.message,
                    residuals=e, params=best.x)


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
    from .differential import BoucWen

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
    from .differential import BacklashLike

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
    from .differential import Duhem

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
                   max_train_samples=20000, train=None, progress=False):
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
    import time

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
    out = ModelComparison()
    for name in models:
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
        out.append({"name": name, "model": model, "offset": offset, "n_parameters": int(npar),
                    "train_rms": float(np.sqrt(np.mean(etrain * etrain))),
                    "rms": float(np.sqrt(np.mean(held * held))), "max": float(np.max(np.abs(held))),
                    "fit_time": fit_time, "prediction": pred})
        if progress:
            sys.stderr.write(f"compare_models: {name:<14} held-out rms {out[-1]['rms']:.4g} "
                             f"({fit_time:.2f} s)\n")
    return out


__all__ += ["ModelFit", "ModelComparison", "fit_preisach", "fit_kp", "fit_bouc_wen", "fit_backlash_like",
            "fit_duhem", "compare_models"]

"""Weights of PI, mGPI and GPI models by constrained least squares (eq. 49): :func:`fit_weights`, and what a fit is worth: :func:`validate`, :func:`compensation_error`."""

import math
import warnings

import numpy as np

from .._validation import as_scalar, as_thresholds, check_choice, check_simulates
from ..envelopes import Atanh, Custom, Envelope, Identity, Linear, Polynomial, Tanh
from ..inverses import tracking_error
from ..models import GPI, MGPI, PI
from ._records import _apply_validation, _frame_arguments, _records, _with_index
from ._regressors import _SymmetricRegressors, _AsymmetricRegressors, _GPIRegressors, _gram
from ._result import FitResult, information_criteria
from .solver import _Problem

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


def _attach_index(result, index):
    """Residuals as pandas Series on the input's index (one per record)."""
    result.index = index
    if index is None:
        return result
    if isinstance(result.residuals, list):
        result.residuals = [_with_index(e, i, "residual") for e, i in zip(result.residuals, index)]
    else:
        result.residuals = _with_index(result.residuals, index, "residual")
    return result


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



def fit_weights(v, y=None, thresholds=None, envelope=None, model="mgpi", constraints="nonnegative",
                regularization=None, offset=True, solver=None, sample_weight=None, validation=None,
                n_thresholds=20, envelope_left=None, envelope_right=None, H=None,
                _problem=None, _warn=True, *, input="v", output="y"):
    """Identify the weights of a PI, mGPI or GPI model by constrained least squares.

    Solves ``min sum_k w_k (y_k - yhat_k)^2`` (plus an optional penalty) over
    p0, p_1..p_N and an offset, where ``yhat = p0 gamma(v) + sum_i p_i
    gamma(F_{r_i}[v]) + offset`` (eq. 49), on the Gram matrix ``A^T W A``
    accumulated block by block, with cvxpy.

    Parameters
    ----------
    v, y : array_like or list of array_like
        Input and measured output; a list gives several records, each
        starting from the virgin state (operator outputs 0).  pandas
        Series keep their index in ``residuals``.  A DataFrame (or a list
        of them) as `v` is the record itself, its columns named by `input`
        and `output` (then `y` is not given).
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
    input, output : str
        With a DataFrame `v`: the input and measured-output columns.

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
    v, y, index = _frame_arguments(v, y, input, output)
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
    rss = rss_w = 0.0
    for rec, e in zip(recs, residuals):
        keep = rec[2] > 0 if rec[2] is not None else slice(None)
        rss += float(np.sum(e[keep] ** 2))
        rss_w += float(np.sum(e * e * rec[2])) if rec[2] is not None else float(np.sum(e * e))
    n = n_train
    k = r.size + lead + int(offset) - int(unreached.sum())
    rmse = math.sqrt(rss / n)
    aic, bic = information_criteria(rss, n, k)
    names = (["p0"] if lead else []) + [f"p{i + 1}" for i in range(r.size)] + (["offset"] if offset else [])
    cov = prob.covariance(rss_w, n, k)
    success = status == "optimal"
    message = "" if success else f"cvxpy status {status!r}"
    result = FitResult(
        model=mdl, weights=p, p0=p0, offset=off, thresholds=r, envelope=envelope,
        envelope_left=gl, envelope_right=gr, H=H_fit,
        rmse=rmse, residuals=residuals if multi else residuals[0],
        aic=aic, bic=bic, condition=cond, n_train=n, n_parameters=k,
        param_names=names, param_values=np.asarray(theta, dtype=np.float64).copy(), covariance=cov,
        unreached=r[unreached], success=success, status=status, message=message,
        solver=prob.solver, train_mse=mse, validation=None, index=index,
    )
    _attach_index(result, index)
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
    check_simulates(model, "model")
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
    check_simulates(true_model, "true_model")
    if isinstance(estimated_model, FitResult):
        estimated_model = estimated_model.model
    if not callable(getattr(estimated_model, "exact_inverse", None)):
        raise TypeError(f"Parameter estimated_model is {estimated_model!r} but should be a hysteresis "
                        "model with exact_inverse() (or a FitResult)")
    return tracking_error(true_model, estimated_model.exact_inverse(), u)


# ----------------------------------------------------------------------------
# envelopes by variable projection

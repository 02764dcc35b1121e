"""The base model of a diagnosis: the plays' thresholds, where they start at
rest, and the parts' context of a record (:mod:`hystcomp.diagnose.search`
builds every step on it)."""

import numpy as np

from ..identify.parts import Context
from ..identify.parts_output import ONE_SIDED_SPAN
from ..identify.search import Structure, VariableProjection

__all__ = ["base_context", "misfit_share", "play_thresholds", "rest_point", "step_kind", "REST_BIC", "LOADING_PLAYS"]


def base_context(rec, n_thresholds=20, thresholds=None):
    """The parts' :class:`~hystcomp.identify.parts.Context` of a record:
    its scaling and clock, and the base model's play thresholds (`thresholds`
    in input units when given, else :func:`play_thresholds`)."""
    if rec.dt is None:
        fit_end = held = None
    elif rec.held_out_in_middle:
        fit_end, held = None, [(a * rec.dt, b * rec.dt) for a, b in rec.blocks]
    else:
        fit_end, held = rec.held_start * rec.dt, None
    ctx = Context(rec.v, rec.dt, rec.origin, rec.scale, rec.duration, n_thresholds, fit_end=fit_end,
                  held_out=held)
    if thresholds is not None:
        r = np.asarray(thresholds, dtype=np.float64) / rec.scale
        ctx.thresholds = np.concatenate([[0.0], r[r > 0]])
    else:
        ctx.thresholds = play_thresholds(rec.span / rec.scale, n_thresholds)
    return ctx


#: how far (BIC, on the fitted part) the base model with its plays at rest at
#: the other rest point must beat the default one to be taken: equal
#: parameters, so 10 is a training mean square lower by a factor exp(-10 / n)
#: ("very strong" evidence on Kass and Raftery's scale, 1995)
REST_BIC = 10.0


def misfit_share(rms_base, rms, sigma):
    """Share of the base model's held-out mean square above the noise that a
    model leaving held-out RMS `rms` removes (1: all of it; 1 when the base
    model is within the noise already).

    Examples
    --------
    >>> misfit_share(2.0, 1.0, 1.0), misfit_share(2.0, 0.5, 1.0), misfit_share(0.9, 0.9, 1.0)
    (1.0, 1.0, 1.0)
    >>> round(misfit_share(3.0, 2.0, 1.0), 3)
    0.625
    """
    excess0 = rms_base ** 2 - sigma ** 2
    return 1.0 - max(rms ** 2 - sigma ** 2, 0.0) / excess0 if excess0 > 0 else 1.0


def rest_point(rec, n_thresholds=20, thresholds=None):
    """The base model's context, engine and fit with the plays at rest at the
    better of the record's rest points (:attr:`Record.other_origin`).

    A record that never reaches 0 V may start with its actuator switched on at
    0 V and driven to the first sample (the plays at rest at 0) or settled at
    its first sample (at rest there); neither is an unknown memory, so the
    search takes the one whose base model fits the fitted part better (by
    more than :data:`REST_BIC`, else the default) and names no effect for it.
    Sets ``rec``'s origin; returns ``(ctx, vp, fit, rest)`` with ``rest`` the
    report's summary (``origin``, ``other``, the two BICs and ``why``)."""
    default = (rec.origin, *_base_fit(rec, n_thresholds, thresholds))
    if rec.other_origin is None:
        return (*default[1:], {"origin": rec.origin, "other": None})
    rec.set_origin(rec.other_origin)
    other = (rec.other_origin, *_base_fit(rec, n_thresholds, thresholds))
    take = other[3].bic < default[3].bic - REST_BIC
    (origin, ctx, vp, fit), (not_taken, _, vp_other, fit_other) = (other, default) if take else (default, other)
    vp.n_evaluations += vp_other.n_evaluations     # the solves of both base fits are counted
    rec.set_origin(origin)
    rec.other_origin = not_taken
    rest = {"origin": origin, "other": not_taken, "bic": round(fit.bic, 1), "bic_other": round(fit_other.bic, 1)}
    rest["why"] = (f"the record never reaches 0: the plays start at rest at {origin:.4g} (base model BIC "
                   f"{fit.bic:.1f}), not at {not_taken:.4g} ({fit_other.bic:.1f}); "
                   + ("the other rest point fits better by more than " if take else
                      "the default, kept unless the other fits better by more than ") + f"{REST_BIC:g}")
    return ctx, vp, fit, rest


def _base_fit(rec, n_thresholds, thresholds):
    """The base model's context, engine and fit at the record's current origin."""
    ctx = base_context(rec, n_thresholds, thresholds)
    vp = VariableProjection(ctx, rec.y, rec.train)
    return ctx, vp, vp.evaluate(Structure(), {})


#: plays kept above half the input span on a record whose scale exceeds it
LOADING_PLAYS = 4


def play_thresholds(span, n):
    """Thresholds of the base model's `n` plays (scaled input, origin 0).

    After the first loading, an input that moves within a span ``span`` moves
    only the plays with thresholds below ``span / 2``.  A bipolar record
    (``span`` = 2) gets ``i / n`` as before.  A record whose scale is larger
    than half its span (a unipolar stroke 0 ... V: ``span`` = 1) gets
    ``n - LOADING_PLAYS`` thresholds evenly below ``span / 2``, where its
    loops need the resolution, and ``LOADING_PLAYS`` evenly from there to 1
    for the first loading curve; evenly up to 1 (``i / n``) it would spend
    half its plays on thresholds that only the first loading moves.

    Parameters
    ----------
    span : float
        The input's span over its scale (``(max v - min v) / scale``).
    n : int
        Number of plays (the first has threshold 0).

    Returns
    -------
    ndarray, shape (n,)

    Examples
    --------
    >>> play_thresholds(2.0, 4).tolist()
    [0.0, 0.25, 0.5, 0.75]
    >>> play_thresholds(1.0, 12).round(4).tolist()
    [0.0, 0.0625, 0.125, 0.1875, 0.25, 0.3125, 0.375, 0.4375, 0.5, 0.625, 0.75, 0.875]
    """
    half = 0.5 * span
    if span >= ONE_SIDED_SPAN or n <= 2 * LOADING_PLAYS:     # two-sided (0.5 span is exact)
        return np.arange(n) / n
    m = n - LOADING_PLAYS
    return np.concatenate([np.arange(m) / m * half, half + np.arange(LOADING_PLAYS) / LOADING_PLAYS * (1.0 - half)])


def step_kind(step):
    """The part that draws a search step's effect: the revision's
    replacement when the revision put one in, else the part the step took.

    Examples
    --------
    >>> step_kind({"evidence": {"extension": {"kind": "creep_lags"}}})
    'creep_lags'
    >>> step_kind({"evidence": {"extension": {"kind": "creep_lags"}, "revised": {"by": "event_drift"}}})
    'event_drift'
    """
    ev = step["evidence"]
    return (ev.get("revised") or {}).get("by") or ev["extension"]["kind"]

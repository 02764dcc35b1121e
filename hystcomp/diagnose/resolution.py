"""The core's resolution: whether what a diagnosis leaves is the base model's
grid of play thresholds rather than a missing effect.

The base PI model has ``n_thresholds`` plays (20 by default) on a fixed grid.
A hysteresis core whose loops bend between those thresholds leaves a misfit
of the order of the grid's interpolation error, which on a record with little
noise is several noise floors: a PI actuator with thresholds off the grid and
noise of 0.03 % of its output span left 1.8 noise floors with 20 plays and
1.3 with 40 (round 28).  That misfit is no effect of the vocabulary, and
naming none while calling the record ``unexplained`` tells the user nothing
to do.  So a base model above the explained bound is refitted with
:data:`FINER` times as many plays before any effect is tried, and a diagnosis
still above the bound at its end refits its final model (every nonlinear
parameter as found) the same way; either fit is taken when its held-out RMS
is within the explained bound and no signature is present in its residual
(checked first, an Iwan joint's core that the grid misses gets no effect
named; checked at the end alone, a drift had been named on it).  The
held-out part judges the finer core, as it judges every part: more plays
that only fit the noise of the fitted part do not lower it.  On the
realistic test records (0.2 % noise) 20 and 40 plays left the same base
misfit to within 0.03 noise floors on every clean record at seed 0
(0.91-1.08 floors either way).
"""

from ..identify.search import VariableProjection
from .base import base_context
from .signatures import evidence

__all__ = ["FINER", "finer_core"]

#: how many times as many plays the finer core has
FINER = 2


def finer_core(rec, vp, struct, cur, sigma, n_thresholds, explained_limit, untested, rms_val, say):
    """A model (the base model before the search, the final model at its end)
    refitted with :data:`FINER` times as many plays, and whether it is taken.

    Parameters
    ----------
    rec : Record
        The record (its origin set as the search left it).
    vp : VariableProjection
        The search's engine (the finer fit's solve is counted in it).
    struct : Structure
        The model's parts.
    cur : FitPoint
        The model's fit (its nonlinear values are kept).
    sigma : float
        Noise floor.
    n_thresholds : int
        The base model's number of plays.
    explained_limit : float
        The explained bound, in noise floors.
    untested : dict
        Effects the record cannot show (their signatures do not count).
    rms_val : callable
        The search's held-out RMS of a fit.
    say : callable
        Progress lines.

    Returns
    -------
    finer : dict
        ``plays``, ``rms_heldout``, ``noise_floors``, ``signatures_present``
        and ``taken`` (:attr:`Diagnosis.finer_core`).
    taken : tuple or None
        ``(ctx, engine, fit, evidence)`` of the finer core when it is taken
        (the engine counts the search's solves so far and the finer one).
    """
    ctx = base_context(rec, FINER * int(n_thresholds))
    ctx.noise = sigma
    vp2 = VariableProjection(ctx, rec.y, rec.train)
    pt = vp2.evaluate(struct, cur.values)
    vp.n_evaluations += 1
    vp2.n_evaluations = vp.n_evaluations
    ev = evidence(rec, rec.y - pt.prediction, pt.prediction, sigma)
    rms = rms_val(pt)
    signs = sorted(k for k, x in ev.items() if x["present"] and k not in untested)
    ok = rms <= explained_limit * sigma and not signs
    which = f"{ctx.thresholds.size} plays" + (", no effect" if not struct.parts else "")
    say(f"finer core ({which}): held-out RMS {rms:.4g} ({rms / sigma:.3g} noise floors)"
        + ("; taken: the grid of thresholds, not an effect, was what remained" if ok else "; not taken"))
    finer = {"plays": int(ctx.thresholds.size), "rms_heldout": rms, "noise_floors": round(rms / sigma, 4),
             "signatures_present": signs, "taken": ok}
    return finer, ((ctx, vp2, pt, ev) if ok else None)

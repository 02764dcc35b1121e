"""A memory at the record's start, creep or a drift: told apart where they differ.

An unknown initial state (a preload history, a memory left by earlier use)
misfits the record only until the input's first full excursion: from there on
the plays have run over the whole range and forget where they started (the
wiping-out property of the PI model, eq. 18; Mayergoyz 1991, ch. 1, for the
Preisach family it belongs to). A drift goes on in time. A drift that settles
early (an exponential with a short time constant, or a broken line whose
first segment carries it) draws the same start, and after it both are flat:
on the held-out part, the record's last 30 % (or a block inside it), the two
parts then gain alike. Measured on the twenty realistic sets before this rule (round 22):
at the first step of 43 runs the best drift part and the best initial-state
part both gained within 10 % of the best held-out gain (0.1-9.1 % apart).
On the 41 of them whose record holds one of the two effects, the larger
held-out gain pointed at the right one 35 times.

The part of the record that holds the difference is the training part,
where the start lies: there a memory draws a level *and a gain* of its own
until the input has covered its range (a play of threshold r keeps its state
until the input has run over 2 r), which a function of time alone does not.
On those 41 runs the lowest training BIC among the near ties pointed at the
right one 38 times, by 880 to 73,000 (the three wrong by 82, 886 and
2,631).

So when the step's choice is a drift, gain drift or initial state, and a part
of the other kind passed every acceptance rule at the step with a held-out
gain within :data:`~hystcomp.diagnose.search.AMBIGUOUS` (10 %) of the best
gain, the one whose training BIC is lower by more than
:data:`~hystcomp.diagnose.base.REST_BIC` is taken. The other stays a near
tie in the report.

Creep or a drift (round 43). Creep (lags of the input and of the hysteresis
output, :class:`hystcomp.identify.parts_dynamics.Creep`) and a drift both
draw a slow motion; creep draws it from the input's own steps (the output
keeps moving in the direction of the last step, Kelvin-Voigt creep), a drift
from time alone, and a drift of no set shape (a broken line in time) can draw
any slow motion, creep's relaxations among them. Unlike a memory at the
start, the training part does not tell them apart: there too the broken
line follows the relaxations (tried as a third side of :func:`start_or_trend`
on the 12 runs of the forty-one sets where creep came within 10 % of a
drift or an initial state held out, the lower training BIC mended 1 and
left 4 worse). But the near ties themselves point one way: on those
forty-one sets (1,275 runs, round 42) creep and a drift came within 10 %
of each other's held-out gain at 10 steps (a drift chosen at 5, creep at
5), all on records whose labels hold creep and no drift, and at no step of
the 201 runs whose labels hold a drift. So when the step's choice is a drift and the
creep part passed every acceptance rule at the step with a held-out gain
within :data:`~hystcomp.diagnose.search.AMBIGUOUS` of the best, creep is
taken (:func:`creep_or_trend`); the drift stays a near tie in the report.
"""

from ..identify.parts import PARTS
from .base import REST_BIC

__all__ = ["START_OR_TREND", "creep_or_trend", "start_or_trend", "start_or_trend_revised"]

#: the effects a misfit in time at the record's start may be
START_OR_TREND = {"drift": "trend", "gain_drift": "trend", "initial_state": "start"}


def _rival(kind, candidates, kind_of, bic_of, near):
    """The candidate of the other kind (drift against initial state) among
    those for which `near` holds, with the lowest training BIC, when that is
    lower than that of `kind`'s own candidate (among `candidates` too) by
    more than ``REST_BIC``; else None."""
    side = START_OR_TREND.get(PARTS[kind].effect)
    if side is None:
        return None
    rivals = [c for c in candidates if START_OR_TREND.get(PARTS[kind_of(c)].effect) not in (None, side) and near(c)]
    if not rivals:
        return None
    mine = next(c for c in candidates if kind_of(c) == kind)
    other = min(rivals, key=bic_of)
    return other if bic_of(other) < bic_of(mine) - REST_BIC else None


def start_or_trend(kind, ok, ambiguous):
    """The part to add at a step, between a drift and an initial state.

    Parameters
    ----------
    kind : str
        The part the step chose by its held-out gain (and Occam's rules).
    ok : list of tuple
        The parts that passed every acceptance rule at the step, as
        ``(held-out gain in noise variances, kind, training BIC change, signature present)``.
    ambiguous : float
        A part within this share of the best held-out gain is a near tie.

    Returns
    -------
    kind : str
        The part to add: `kind`, or a part of the other kind (drift against
        initial state) whose training BIC is lower by more than ``REST_BIC``.
    why : dict or None
        When the choice changed: the part the held-out gain chose, the one
        taken, both held-out gains and both training BIC changes.
    """
    if not ok:
        return kind, None
    top = ok[0][0]
    best = _rival(kind, ok, lambda j: j[1], lambda j: j[2], lambda j: j[0] >= (1.0 - ambiguous) * top)
    if best is None:
        return kind, None
    mine = next(j for j in ok if j[1] == kind)
    why = {"held_out_chose": kind, "taken": best[1],
           "held_out_gain_noise_variances": {kind: round(mine[0], 3), best[1]: round(best[0], 3)},
           "training_bic_change": {kind: round(mine[2], 1), best[1]: round(best[2], 1)},
           "reason": ("a drift and an initial state gain alike on the held-out part (both flat there); the "
                      "training part, which holds the record's start, tells them apart")}
    return best[1], why


def start_or_trend_revised(best, tried, margin, rms_val):
    """The revision's counterpart of :func:`start_or_trend`.

    Parameters
    ----------
    best : tuple
        ``(kind, structure, fit)`` the revision chose by held-out RMS (and
        Occam's rules).
    tried : list of tuple
        Every ``(kind, structure, fit)`` the revision fitted for the step.
    margin : float
        Held-out mean square within which two fits are a near tie (the
        revision's: ``TIE`` of the step's gain, at least ``MIN_GAIN`` noise
        variances).
    rms_val : callable
        Held-out RMS of a fit.

    Returns
    -------
    tuple
        `best`, or a fit of the other kind (drift against initial state)
        within `margin` of it whose training BIC is lower by more than
        ``REST_BIC``.
    """
    floor = rms_val(best[2]) ** 2
    other = _rival(best[0], tried, lambda c: c[0], lambda c: c[2].bic,
                   lambda c: rms_val(c[2]) ** 2 - floor <= margin)
    return best if other is None else other


def creep_or_trend(kind, ok, ambiguous):
    """The part to add at a step, between a drift and creep (see the module
    docstring): creep when the step chose a drift by its held-out gain and
    a creep part (``creep_lags``, or ``creep_back`` where it is tried) passed
    every acceptance rule at the step with a held-out gain of at least
    ``1 - ambiguous`` times the best.

    Parameters
    ----------
    kind : str
        The part the step chose (after :func:`start_or_trend`).
    ok : list of tuple
        The parts that passed every acceptance rule at the step, as
        ``(held-out gain in noise variances, kind, training BIC change, signature present)``,
        best first.
    ambiguous : float
        A part within this share of the best held-out gain is a near tie.

    Returns
    -------
    kind : str
        `kind`, or the best creep part's kind.
    why : dict or None
        When the choice changed: the part the held-out gain chose, the one
        taken, both held-out gains and the reason.

    Examples
    --------
    >>> ok = [(31.7, "event_drift", -900.0, True), (29.0, "creep_lags", -850.0, True)]
    >>> creep_or_trend("event_drift", ok, 0.1)[0]
    'creep_lags'
    >>> creep_or_trend("event_drift", ok[:1] + [(28.0, "creep_lags", -850.0, True)], 0.1)[0]
    'event_drift'
    """
    if not ok or PARTS[kind].effect != "drift":
        return kind, None
    top = ok[0][0]
    creep = [j for j in ok if PARTS[j[1]].effect == "creep" and j[0] >= (1.0 - ambiguous) * top]
    if not creep:
        return kind, None
    mine = next(j for j in ok if j[1] == kind)
    taken = creep[0][1]
    why = {"held_out_chose": kind, "taken": taken,
           "held_out_gain_noise_variances": {kind: round(mine[0], 3), taken: round(creep[0][0], 3)},
           "reason": ("creep and a drift gain alike on the held-out part; creep draws the slow motion from the "
                      "input's own steps, a drift from time alone (a broken line in time can draw creep's "
                      "relaxations too), so the near tie goes to creep")}
    return taken, why

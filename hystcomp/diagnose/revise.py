"""The revision of a diagnosis once every effect is in (a floating search):
near ties and other forms of a chosen effect refitted in its place, then
parts a later effect made redundant dropped (:func:`revise`, called by
:mod:`hystcomp.diagnose.search` when two or more effects are named)."""

from ..identify.parallel_fits import run_all
from ..identify.parts import PARTS
from ..identify.search import PartsModel, Structure
from .start_or_trend import start_or_trend_revised

__all__ = ["TIE", "PARSIMONY", "SAME_EFFECT_FORMS", "n_parameters", "refit", "revise"]


def n_parameters(part, structure, ctx):
    """How many nonlinear parameters `part` has within `structure`."""
    return len(part.parameters(ctx, set(structure.kinds)))


#: an alternative whose held-out mean square at its step was within this share of
#: the chosen part's gain (or min_gain noise variances) is a near tie, retried at the end
TIE = 0.1
#: revised fits within this many noise variances (held-out mean square) of the
#: best are equally good: the one with the fewest nonlinear parameters is kept
PARSIMONY = 0.05
#: other parts of a chosen effect refitted in its place once later effects are in
SAME_EFFECT_FORMS = 2


def refit(vp, ctx, st, start, rms_val, new=None, starts=()):
    """Fit `st` from `start`: the new part's parameters first (from its
    starting points), then every nonlinear parameter jointly."""
    if new is not None:
        pt = vp.optimise(st, start, free={new.kind}, max_evaluations=12 * max(len(new.parameters(ctx, set(st.kinds))), 1),
                         starts=list(starts))
        start = pt.values
    else:
        pt = vp.evaluate(st, start)
    n_par = len(st.parameters(ctx))
    if n_par:
        joint = vp.optimise(st, start, free=None, max_evaluations=10 * n_par)
        if joint.rss < pt.rss and rms_val(joint) <= rms_val(pt):
            pt = joint
    return pt


def _refit_task(ctx, st, start, rms_val, new=None):
    """:func:`refit` as a task of :func:`~hystcomp.identify.parallel_fits.run_all`; the `new`
    part's starting points are taken in the task, so that an error there (a fit's error) leaves
    the alternative out, as an error of the fit does."""
    def task(vp):
        starts = () if new is None else [{new.kind: v} for v in new.initial_values(ctx, set(st.kinds))]
        return refit(vp, ctx, st, start, rms_val, new, starts)
    return task


def revise(vp, ctx, rec, struct, cur, steps, chosen, chosen_kinds, step_trials, sigma, rms_val, say, *, min_gain,
           workers=1):
    """Revisit the effects chosen greedily once all are in (a floating
    search): a part whose step was a near tie with another effect's part, or
    (for every step but the last) one of the ``SAME_EFFECT_FORMS`` other
    parts of its effect that fitted best at its step, is replaced by it when
    that lowers the held-out RMS with the later effects in the model; then a
    part whose removal raises the held-out mean square by less than min_gain
    noise variances is dropped (a later effect made it redundant).  Returns
    the structure, the fit point and the revisions.

    With ``workers > 1`` the refits run side by side
    (:func:`~hystcomp.identify.parallel_fits.run_all`): a step's
    alternatives together, and the refits without each part from the same
    model together (those after a part that is dropped are made again from
    the model without it).  Each refit is the same computation, so the
    revision is the same with any number of workers."""
    revisions = []
    s2 = sigma ** 2
    for j in range(len(chosen_kinds)):
        kind = chosen_kinds[j]
        trials = step_trials[j]
        gain = steps[j]["rms_before"] ** 2 - trials[kind] ** 2
        margin = max(TIE * gain, min_gain * s2)
        # another effect's part only when it passed every acceptance rule at the
        # step, its signature included (an effect is named only on its evidence)
        passed = steps[j]["evidence"].get("acceptable", {})
        alts = sorted((r, k) for k, r in trials.items()
                      if k != kind and r ** 2 - trials[kind] ** 2 <= margin
                      and (PARTS[k].effect == chosen[j] or (PARTS[k].effect not in chosen and k in passed)))
        near = {k for _, k in alts}
        if j < len(chosen_kinds) - 1:
            # the same effect's other forms, with the later effects in the model: a
            # shapeless drift chosen first may have stood in for a trend that the
            # parametric drift draws once creep is in (SAME_EFFECT_FORMS best at its step)
            same = sorted((r, k) for k, r in trials.items() if k != kind and PARTS[k].effect == chosen[j]
                          and (r, k) not in alts)
            alts += same[:SAME_EFFECT_FORMS]
        tried = [(kind, struct, cur)]
        jobs = []
        for _, alt in alts:
            cls = PARTS[alt]
            if cls.slot == "output" and any(p.slot == "output" and p.kind != kind for p in struct.parts):
                continue
            part = cls()
            part.prepare(rec.y, ctx)
            keep = [p for p in struct.parts if p.kind != kind]
            part.attach(PartsModel(Structure(keep), cur.values, cur.theta, ctx, cur.names))
            st = Structure(keep + [part])
            start = {k: dict(v) for k, v in cur.values.items() if k != kind}
            start[alt] = {q.name: q.initial for q in part.parameters(ctx, set(st.kinds))}
            for p, q in st.parameters(ctx):
                start.setdefault(p.kind, {}).setdefault(q.name, q.initial)
            jobs.append((alt, st, _refit_task(ctx, st, start, rms_val, part)))
        # the alternatives' refits side by side (a fit's error leaves that alternative out)
        for (alt, st, _), pt in zip(jobs, run_all(vp, [task for _, _, task in jobs], workers)):
            if isinstance(pt, Exception):
                continue
            say(f"revise: {kind} -> {alt}: held-out RMS {rms_val(cur):.4g} -> {rms_val(pt):.4g}")
            tried.append((alt, st, pt))
        # the best fit; among fits within PARSIMONY noise variances of it, the
        # part with the fewest nonlinear parameters (the current one on a tie)
        lowest = min(rms_val(p_) ** 2 for _, _, p_ in tried)
        close = [c for c in tried if rms_val(c[2]) ** 2 <= lowest + PARSIMONY * s2]
        best = min(close, key=lambda c: (n_parameters(PARTS[c[0]](), c[1], ctx), c[0] != kind,
                                         rms_val(c[2])))
        # a drift and an initial state within the near tie: the training fit decides
        taken = start_or_trend_revised(best, tried, margin, rms_val)
        by_bic, best = taken is not best, taken
        if best[0] != kind:
            alt, st, pt = best
            cls = PARTS[alt]
            revisions.append({"step": j + 1, "replaced": kind, "by": alt, "effect_before": chosen[j],
                              "effect_after": cls.effect, "rms_before": rms_val(cur), "rms_after": rms_val(pt),
                              "reason": ("a drift and an initial state gain alike held out; the training part, "
                                         "which holds the record's start, tells them apart") if by_bic else
                                        ("near tie at its step; the other part fits better with the later "
                                         "effects in the model") if alt in near else
                                        ("another form of the same effect fits better with the later effects "
                                         "in the model")})
            steps[j]["effect"] = cls.effect
            steps[j]["evidence"]["revised"] = revisions[-1]
            chosen[j], chosen_kinds[j] = cls.effect, alt
            struct, cur = st, pt
    # backward: drop what a later effect made redundant (`live`: the step of
    # each chosen part; a dropped step stays in `steps`, marked).  The refits
    # without each part from j on start from the same model and run side by
    # side; once a part is dropped, those after it are made again from the
    # model without it
    live = list(range(len(chosen_kinds)))
    j = 0
    while j < len(chosen_kinds) and len(chosen_kinds) > 1:
        jobs = []
        for kind in chosen_kinds[j:]:
            st = Structure([p for p in struct.parts if p.kind != kind])
            start = {k: dict(v) for k, v in cur.values.items() if k != kind}
            jobs.append((st, _refit_task(ctx, st, start, rms_val)))
        fits = run_all(vp, [task for _, task in jobs], workers)
        try:
            for (st, _), pt in zip(jobs, fits):
                kind = chosen_kinds[j]
                if isinstance(pt, Exception):
                    j += 1
                    continue
                before, after = rms_val(cur), rms_val(pt)
                # what the part still adds with every other effect in: the held-out mean
                # square it saves, in noise variances (kept at min_gain or more)
                steps[live[j]]["evidence"]["held_out_loss_without_it_noise_variances"] = round(
                    (after ** 2 - before ** 2) / s2, 3)
                if after ** 2 - before ** 2 < min_gain * s2:
                    say(f"revise: {chosen[j]} ({kind}) dropped: without it the held-out RMS is {after:.4g} "
                        f"(with it {before:.4g})")
                    revisions.append({"step": live[j] + 1, "replaced": kind, "by": None, "effect_before": chosen[j],
                                      "effect_after": None, "rms_before": before, "rms_after": after,
                                      "reason": f"redundant once the later effects are in: it lowers the held-out "
                                                f"mean square by less than {min_gain} noise variances"})
                    steps[live[j]]["evidence"]["revised"] = revisions[-1]
                    steps[live[j]]["dropped"] = True
                    del chosen[j], chosen_kinds[j], live[j]
                    struct, cur = st, pt
                    break
                say(f"revise: {chosen[j]} ({kind}) kept: without it {after:.4g} (with it {before:.4g})")
                j += 1
        finally:
            fits.close()
    return struct, cur, revisions

"""Names held back after the search: on a record left unexplained, an effect
added after the first step whose step gained little held out, and which the
final model does not need either, is tentative, not named; on a record
explained, so is a saturation or an asymmetry that gained little; on any
record, so is a drift added after the first step that gained little
(:func:`small_later_steps`, called by :mod:`hystcomp.diagnose.search` on the
reported split and on the summary of the split not taken)."""

__all__ = ["LATER_GAIN", "EXPLAINED_SHAPE_GAIN", "EXPLAINED_FIRST_ASYMMETRY_GAIN", "EXPLAINED_LATER_SATURATION_GAIN",
           "UNEXPLAINED_SHAPE_GAIN", "LATER_DRIFT_GAIN", "small_later_steps"]

#: on a record left unexplained, an effect added after the first step is
#: named only when its step lowered the held-out mean square by at least this
#: many noise variances (a pair's steps are judged together and exempt).  Round
#: 36: over the thirty-five realistic sets (1,095 runs) the 16 such steps that
#: gained 0.29-2.62 noise variances were all wrong (an initial state, a
#: saturation, an asymmetry, a delay or a drift picking at a misfit of another
#: kind); the first right one gained 3.48.  The part stays in the model,
#: tentative.  Round 38: the same bound holds for what the final model loses
#: without the part (the others refitted, ``held_out_loss_without_it``): a
#: step may gain little when it is added and much once a revision has put an
#: earlier step in another form.  Over the thirty-seven sets (1,155 runs) the
#: 20 wrong steps the rule holds back lose 0.27-2.52 noise variances without
#: them; the one right step it held back (HOLDOUT36's optical lever's
#: asymmetry beside the oil's warm-up drift, seed 1: 2.10 gained at its step)
#: loses 363 once the drift's event form is replaced by its trend
LATER_GAIN = 3.0

#: on a record explained, a saturation (any step) or an asymmetry added after
#: the first step is named only when its step lowered the held-out mean
#: square by at least this many noise variances, or the final model would
#: lose that many without it.  These parts bend the static curve (an output
#: map, the envelopes, the thresholds' levels), enough to take up the small
#: misfit of a core that is not quite PI.  Round 47, over the forty-five
#: committed realistic sets (1,395 runs), on `explained` records (the larger
#: of gain and loss): the asymmetries added after the first step below 2.5
#: (0.51 ... 2.24) were wrong 15 times (beside a dead time, creep, an initial
#: state, a saturation) and right once, on a run wrong for another reason
#: (HOLDOUT24's pair, seed 2, 1.59), the smallest right one above 2.71
#: (HOLDOUT44's pair, seed 1); the saturations below 3.5 were all wrong (12:
#: 0.52 ... 3.50, 6 of them on clean records), the smallest right one 3.72
#: (HOLDOUT30's yoke).  A first asymmetry is held to
#: :data:`EXPLAINED_FIRST_ASYMMETRY_GAIN`: right ones gained 1.53 and 2.25 (a
#: float in a conical vessel, a unipolar staircase)
EXPLAINED_SHAPE_GAIN = 2.5

#: on a record explained, an asymmetry found at the first step is named only
#: when its step lowered the held-out mean square by at least this many noise
#: variances, or the final model would lose that many without it.  A core
#: whose strain is even in its polarisation or its magnetisation (a relaxor
#: stack, a Galfenol rod) is lopsided by itself, and an asymmetric map takes
#: up a trace of that.  Round 54, over the forty-nine committed realistic sets
#: (1,605 runs), on `explained` records (the larger of gain and loss): the six
#: first asymmetries below 1.5 (0.25 ... 1.30) were all wrong (four on clean
#: records: HOLDOUT51's PMN-PT stack at every seed, HOLDOUT49's Galfenol rod;
#: two beside a dead time), the smallest right one 1.53 (HOLDOUT27's float in a
#: conical vessel, seed 2); from 1.5 to 2.5, two right and one wrong.  Chosen
#: before HOLDOUT52 was measured
EXPLAINED_FIRST_ASYMMETRY_GAIN = 1.5

#: on a record explained, a saturation (of the envelope or of the output)
#: added after the first step is named only when its step lowered the
#: held-out mean square by at least this many noise variances, or the final
#: model would lose that many without it.  Once a first effect has brought
#: the record to its noise floor, what a saturating map still takes up is
#: mostly the core's own bend at its extremes (a magnetic core, a fluid's
#: yield, a cam's sine), not a limit of its own.  Round 50, over the
#: forty-eight committed realistic sets (1,485 runs), on `explained` records
#: (the larger of gain and loss): 24 saturations were named after the first
#: step, 7 of them labelled, all in pairs (7.1 and 10.8: creep with a
#: saturation; 13.4: rate dependence; 20.6 ... 67: a drift or a gain drift
#: with an output saturation) and 17 not (2.9 ... 69, beside a dead time,
#: creep, rate dependence, a drift or an initial state; 9 of them under 10,
#: 4 of those on HOLDOUT47's saturating clutch fluid).  Held to this bound
#: on the saved steps, 9 runs come right and 1 goes wrong (HOLDOUT26's pair
#: of creep and a saturation, seed 0, 7.1).  A first saturation keeps
#: :data:`EXPLAINED_SHAPE_GAIN` (98 labelled, from 3.7).
#: Chosen before HOLDOUT48 was measured
EXPLAINED_LATER_SATURATION_GAIN = 10.0

#: the saturation effects held to :data:`EXPLAINED_LATER_SATURATION_GAIN`
_SATURATION = ("saturation", "output_saturation")

#: effects held to a bound on a record explained (:data:`EXPLAINED_SHAPE_GAIN`
#: after the first step), and each one's bound at the first step
_SHAPE = {"saturation": EXPLAINED_SHAPE_GAIN, "output_saturation": EXPLAINED_SHAPE_GAIN,
          "asymmetry": EXPLAINED_FIRST_ASYMMETRY_GAIN}

#: on a record left unexplained, a saturation or an asymmetry added after the
#: first step is named only when its step lowered the held-out mean square by
#: at least this many noise variances, or the final model would lose that many
#: without it (the larger of the two).  What the model leaves on such a record
#: is mostly a core that is not PI, and these parts bend the static curve
#: enough to take up a share of its shape at any size.  Round 49, over the
#: forty-six committed realistic sets (1,455 runs), on `unexplained` records:
#: of the 62 saturations and asymmetries added after the first step, 45 were
#: not labelled (beside creep, a drift, a dead time, rate dependence, an
#: initial state, a saturation labelled alone; 3.1 ... 110 noise variances,
#: all but two under 49) and 17 were (3.5 ... 363; five above 60: two
#: asymmetric Preisach densities, a photoresistor's asymmetry at two seeds and
#: a tyre's saturation in a pair).  Held to this bound on the saved steps,
#: 22 runs came right and 8 went wrong (three of the tuning set's asymmetric
#: Preisach core, five pairs whose second effect is a saturation or an
#: asymmetry); chosen before HOLDOUT47 was measured
UNEXPLAINED_SHAPE_GAIN = 60.0

#: on any record, an offset drift added after the first step is named only
#: when its step lowered the held-out mean square by at least this many noise
#: variances, or the final model would lose that many without it.  A drift's
#: parts are broken lines in time (6 or 24 segments) or a trend with a
#: time constant: once a first effect has taken the record's misfit, what
#: is left of a core that is not quite PI, or of the first part's own
#: misfit, drifts slowly too, and a broken line takes up a few noise
#: variances of it.  Round 60, over the fifty-eight committed realistic sets
#: (1,785 runs), the larger of gain and loss: the seven drifts named after
#: the first step below 5 (1.53 ... 4.91: beside rate dependence, a
#: saturation, an asymmetry, an initial state; one on HOLDOUT57's clean
#: mirror) were all unlabelled; the smallest labelled ones are pairs, 5.88
#: (the tuning set's saturation and drift, seed 0) and 5.90 (HOLDOUT3's
#: asymmetry and drift, seed 0).  Chosen before HOLDOUT58 was measured
LATER_DRIFT_GAIN = 5.0

#: why a later drift needs more
_WHY_DRIFT = (" for a drift after the first step, which may be taking up a slow misfit the earlier parts leave")

#: why a later saturation or asymmetry on a record left unexplained needs more
_WHY_SHAPE = (" for a saturation or an asymmetry after the first step on a record left unexplained, which may be "
              "taking up the shape of a core that is not PI")

#: why a first asymmetry on a record explained needs some gain
_WHY_FIRST_ASYMMETRY = (" for an asymmetry at the first step on a record explained, which may be taking up a trace "
                        "of a core lopsided by itself")

#: why a later saturation on a record explained needs more
_WHY_SATURATION = (" for a saturation after the first step on a record explained, which may be taking up the bend "
                   "of a core that saturates by itself")


def small_later_steps(kw, say):
    """On a record left unexplained, make tentative (not named) every effect
    added after the first step whose step lowered the held-out mean square by
    less than :data:`LATER_GAIN` noise variances and without which the final
    model (the other effects refitted) would lose less than that too, and a
    saturation or an asymmetry added after the first step under
    :data:`UNEXPLAINED_SHAPE_GAIN` (round 49); on a record explained, a
    saturation (at any step) or an asymmetry added after the first step
    under :data:`EXPLAINED_SHAPE_GAIN` (round 47), a saturation added
    after the first step under :data:`EXPLAINED_LATER_SATURATION_GAIN`
    (round 50), and an asymmetry found at the first step under
    :data:`EXPLAINED_FIRST_ASYMMETRY_GAIN` (round 54); on any record, a
    drift added after the first step under :data:`LATER_DRIFT_GAIN`
    (round 60).
    A pair's steps (judged together), dropped and tentative steps are left
    as they are.  The parts stay in the model, and the verdict does not
    change.  Applied to the reported split, after the choice between
    splits; returns `kw` updated."""
    if not kw["effects"] or not kw.get("steps"):
        return kw
    if kw["verdict"] == "unexplained":
        bound, only, where = LATER_GAIN, None, "a record left unexplained"
    elif kw["verdict"] == "explained":
        bound, only, where = EXPLAINED_SHAPE_GAIN, _SHAPE, "a record explained"
    else:
        return kw
    small = {}
    for i, st in enumerate(kw["steps"]):
        ev = st["evidence"]
        gain = ev.get("held_out_gain_noise_variances")
        if st.get("dropped") or st.get("tentative") or ev.get("paired") or gain is None:
            continue
        # a later step of any effect (unexplained), or any step of an effect in `only` (explained); a later drift on
        # any record
        later_drift = i > 0 and st["effect"] == "drift"
        judged = later_drift or (i > 0 if only is None else st["effect"] in only)
        if not judged:
            continue
        # what the final model loses without it (absent when it was not refitted without it)
        loss = ev.get("held_out_loss_without_it_noise_variances")
        # a later saturation or asymmetry on a record left unexplained, a later saturation on a record explained:
        # held to their own bounds
        need, why = bound, ""
        if later_drift:
            need, why = LATER_DRIFT_GAIN, _WHY_DRIFT
        elif only is None and st["effect"] in _SHAPE:
            need, why = UNEXPLAINED_SHAPE_GAIN, _WHY_SHAPE
        elif only is not None and i > 0 and st["effect"] in _SATURATION:
            need, why = EXPLAINED_LATER_SATURATION_GAIN, _WHY_SATURATION
        elif only is not None and i == 0:
            need = only[st["effect"]]
            why = _WHY_FIRST_ASYMMETRY if st["effect"] == "asymmetry" else ""
        if 0.0 <= gain < need and (loss is None or loss < need):
            small[i] = (gain, need, why)
    # an effect that another step names stays named
    named = {st["effect"] for i, st in enumerate(kw["steps"])
             if i not in small and not st.get("dropped") and not st.get("tentative")}
    small = {i: g for i, g in small.items() if kw["steps"][i]["effect"] in kw["effects"]
             and kw["steps"][i]["effect"] not in named}
    if not small:
        return kw
    for i, (gain, need, why) in small.items():
        st = kw["steps"][i]
        st["tentative"] = True
        st["alternatives"] = []
        loss = st["evidence"].get("held_out_loss_without_it_noise_variances")
        without = "" if loss is None else f", and the final model loses {loss:.2f} without it"
        when = "found at the first step" if i == 0 else "added after the first step"
        st["evidence"]["small_later_step"] = (
            f"{when} on {where}, it lowers the held-out mean square by only {gain:.2f} noise "
            f"variances{without} (naming needs {need:g}{why}): tentative, not named")
    gone = {kw["steps"][i]["effect"]: g for i, g in small.items()}
    kw["effects"] = [e for e in kw["effects"] if e not in gone]
    kw["tentative"] = list(kw["tentative"]) + list(gone)
    kw["ambiguous"] = {e: a for e, a in kw["ambiguous"].items() if e not in gone}
    what = ", ".join(f"{e} ({g:.2f})" for e, (g, _, _) in gone.items())
    steps = "steps" if 0 in small else "later steps"
    needs = sorted({need for _, need, _ in small.values()})
    under = " or ".join(f"{b:g}" for b in needs)
    kw["stopped"] += f"; tentative: {what}, {steps} gaining under {under} noise variances"
    say(f"tentative, not named: {what} (noise variances gained held out at {steps} of {where})")
    return kw

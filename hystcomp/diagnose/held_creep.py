"""Creep that stays named on a record whose core is out of the vocabulary.

When the best model within hystcomp's vocabulary leaves most of a record's
misfit (:data:`hystcomp.diagnose.search.NAMED_SHARE`, ``OOV_LEFT``), every
extension is made tentative: what they take up may be the shape of a core
that is not PI.  Creep found by its hold test is the one exception kept.
While the input is held still, a rate-independent core, PI or not, holds
its output still too (its output is a function of the input's history of
extrema, and a hold adds none), so a residual that relaxes during the holds
in proportion to the step into them cannot be the core's shape.  The
exception asks three things of a creep step:

- its signature (the residual's relaxation during the holds, against the
  step into each, :func:`hystcomp.diagnose.signatures.evidence`) was
  present when it was added;
- the creep part took up at least :data:`CREEP_TAKEN_SHARE` of that
  relaxation: the final model's residual relaxes by at most half as much;
- the final model loses at least :data:`CREEP_KEPT_GAIN` noise variances held
  out without it (or gained that much at its step).

Round 55, over the fifty-three committed realistic sets (1,635 runs): four
runs had a creep step made tentative by the out-of-vocabulary rule (all
left unexplained): three creep records (HOLDOUT42's Avrami after-run, seeds
1 and 2, HOLDOUT43's activated contact line, seed 0) and one rate record
(HOLDOUT44's rubber friction, seed 0, wrong either way).  Chosen before
HOLDOUT53 was measured.
"""

#: the creep part must have taken up at least this share of the holds'
#: relaxation (the signature's statistic at its step against the final one)
CREEP_TAKEN_SHARE = 0.5

#: ... and be worth at least this many noise variances held out (the larger
#: of its step's gain and the final model's loss without it)
CREEP_KEPT_GAIN = 10.0


def creep_beyond_core(steps, final_evidence):
    """The creep steps that stay named when the out-of-vocabulary rule makes
    the other extensions tentative: ``{index: reason}``.

    `steps` are a diagnosis's steps, `final_evidence` the signatures of the
    final model's residual (:func:`hystcomp.diagnose.signatures.evidence`).

    Examples
    --------
    >>> st = {"effect": "creep", "evidence": {"signature": {"statistic": 10.8, "threshold": 3.7,
    ...       "present": True, "testable": True}, "held_out_gain_noise_variances": 14.4,
    ...       "held_out_loss_without_it_noise_variances": 85.8}}
    >>> final = {"creep": {"statistic": 1.8, "threshold": 3.2, "present": False}}
    >>> list(creep_beyond_core([st], final))
    [0]
    >>> final["creep"]["statistic"] = 6.0
    >>> creep_beyond_core([st], final)
    {}
    """
    kept = {}
    after = (final_evidence or {}).get("creep") or {}
    for i, st in enumerate(steps):
        if st.get("effect") != "creep" or st.get("dropped"):
            continue
        ev = st.get("evidence", {})
        sig = ev.get("signature") or {}
        if not (sig.get("present") and sig.get("testable", True)) or "statistic" not in after:
            continue
        before = float(sig["statistic"])
        left = float(after["statistic"])
        worth = max(ev.get("held_out_gain_noise_variances") or 0.0,
                    ev.get("held_out_loss_without_it_noise_variances") or 0.0)
        if left <= (1.0 - CREEP_TAKEN_SHARE) * before and worth >= CREEP_KEPT_GAIN:
            kept[i] = (f"creep stays named: the residual relaxed during the holds ({before:.3g} > "
                       f"{float(sig.get('threshold', 0.0)):.3g}), which no rate-independent core does (its output "
                       f"holds still while its input does); the creep part took up {100 * (1 - left / before):.0f} % "
                       f"of it (naming needs {100 * CREEP_TAKEN_SHARE:.0f} %) and is worth {worth:.3g} noise "
                       f"variances held out (needs {CREEP_KEPT_GAIN:g})")
    return kept

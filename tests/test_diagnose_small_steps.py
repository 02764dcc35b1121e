"""Small later steps on a record left unexplained are tentative, not named (round 36).

The rule (``hystcomp.diagnose.small_steps.LATER_GAIN``) was set on the thirty-five realistic sets:
the 16 effects named after the first step on records left unexplained whose step gained
0.29-2.62 noise variances held out were all wrong; the first right one gained 3.48.  The unit
tests below check the rule's bookkeeping on hand-made search results; two tests run it on seen
records: HOLDOUT9's unipolar staircase on generalized plays (seed 0), where it made the initial
state tentative in the evaluation of round 36, and HOLDOUT36's warming servo valve read through an
oblique optical lever (seed 1), where since round 38 it no longer holds back an asymmetry that
gained 2.10 noise variances at its step but without which the final model loses 363: the rule
asks both the step's gain and that loss to be under the bound.
"""

import copy
import json

import numpy as np
import pytest

from hystcomp.diagnose import diagnose
from hystcomp.diagnose.small_steps import (EXPLAINED_FIRST_ASYMMETRY_GAIN, EXPLAINED_LATER_SATURATION_GAIN,
                                          EXPLAINED_SHAPE_GAIN, LATER_DRIFT_GAIN, LATER_GAIN,
                                          UNEXPLAINED_SHAPE_GAIN)
from hystcomp.diagnose.small_steps import small_later_steps as _small_later_steps


def _step(effect, gain, **kw):
    return {"effect": effect, "evidence": {"held_out_gain_noise_variances": gain, **kw.pop("evidence", {})},
            "alternatives": [], **kw}


def _kw(steps, verdict="unexplained"):
    effects = list(dict.fromkeys(s["effect"] for s in steps if not s.get("tentative") and not s.get("dropped")))
    return {"verdict": verdict, "effects": effects, "steps": steps, "tentative": [], "stopped": "no remaining "
            "effect pays", "ambiguous": {e: ["delay"] for e in effects}}


def _run(steps, verdict="unexplained"):
    kw = _kw(copy.deepcopy(steps), verdict)
    return _small_later_steps(kw, lambda s: None)


def test_a_later_step_under_the_bound_is_tentative_and_the_first_stays_named():
    out = _run([_step("asymmetry", 24.8), _step("initial_state", 0.54)])
    assert out["effects"] == ["asymmetry"]
    assert out["tentative"] == ["initial_state"]
    assert out["steps"][1]["tentative"] and "0.54 noise variances" in out["steps"][1]["evidence"]["small_later_step"]
    assert "initial_state" not in out["ambiguous"] and "asymmetry" in out["ambiguous"]
    assert "tentative: initial_state (0.54)" in out["stopped"]


def test_the_bound_is_three_noise_variances():
    assert LATER_GAIN == 3.0
    below = _run([_step("creep", 100.0), _step("delay", 2.99)])
    above = _run([_step("creep", 100.0), _step("delay", 3.01)])
    assert below["effects"] == ["creep"] and above["effects"] == ["creep", "delay"]


def _loss(effect, gain, loss):
    return _step(effect, gain, evidence={"held_out_loss_without_it_noise_variances": loss})


def test_a_small_step_the_final_model_needs_stays_named():
    # round 38: HOLDOUT36's oil warm-up drift beside an oblique optical lever (seed 1): the asymmetry's step gained
    # 2.10 noise variances, and the final model (the drift's event form replaced by its trend) loses 363 without it
    out = _run([_step("drift", 71.3), _loss("asymmetry", 2.10, 362.7)])
    assert out["effects"] == ["drift", "asymmetry"] and out["tentative"] == []
    assert not out["steps"][1].get("tentative")


def test_the_loss_without_it_has_the_same_bound():
    below = _run([_step("creep", 100.0), _loss("delay", 1.0, 2.99)])
    above = _run([_step("creep", 100.0), _loss("delay", 1.0, 3.01)])
    assert below["effects"] == ["creep"] and above["effects"] == ["creep", "delay"]
    said = below["steps"][1]["evidence"]["small_later_step"]
    assert "only 1.00 noise variances, and the final model loses 2.99 without it (naming needs 3)" in said
    # a step whose own gain is large stays named whatever the final model loses without it
    assert _run([_step("creep", 100.0), _loss("delay", 3.5, 0.4)])["effects"] == ["creep", "delay"]


@pytest.mark.parametrize("case", ["first", "explained", "paired", "dropped", "negative", "named_twice"])
def test_what_the_rule_leaves_alone(case):
    steps = [_step("saturation", 40.0), _step("asymmetry", 1.0)]
    verdict = "unexplained"
    if case == "first":
        steps = [_step("saturation", 1.0), _step("asymmetry", 80.0)]
    elif case == "explained":
        # on a record explained only an asymmetry is held back (round 47)
        steps = [_step("saturation", 40.0), _step("delay", 1.0)]
        verdict = "explained"
    elif case == "paired":
        steps[1]["evidence"]["paired"] = "fitted jointly with drift (slow_drift)"
    elif case == "dropped":
        steps[1]["dropped"] = True
    elif case == "negative":
        # a step whose own gain is negative (the revision or a pair put it in) is judged elsewhere
        steps[1]["evidence"]["held_out_gain_noise_variances"] = -4.3
    elif case == "named_twice":
        # a later small step of an effect that an earlier step names
        steps = [_step("saturation", 40.0), _step("asymmetry", 80.0), _step("saturation", 1.0)]
    before = _kw(copy.deepcopy(steps), verdict)
    out = _run(steps, verdict)
    assert out["effects"] == before["effects"] and out["tentative"] == []
    assert not any(s.get("tentative") for s in out["steps"])


def test_a_later_shape_step_on_a_record_left_unexplained_needs_sixty_noise_variances():
    # round 49: on `unexplained` records the later saturations and asymmetries were mostly not labelled (45 of 62
    # on the committed sets, up to 110 noise variances): they need 60, their gain or the final model's loss
    assert UNEXPLAINED_SHAPE_GAIN == 60.0
    for effect in ("saturation", "output_saturation", "asymmetry"):
        below = _run([_step("creep", 100.0), _step(effect, 59.9)])
        above = _run([_step("creep", 100.0), _step(effect, 60.1)])
        needed = _run([_step("creep", 100.0), _loss(effect, 20.0, 60.1)])
        assert below["effects"] == ["creep"] and below["tentative"] == [effect], effect
        assert above["effects"] == ["creep", effect] and needed["effects"] == ["creep", effect]
        said = below["steps"][1]["evidence"]["small_later_step"]
        assert "only 59.90 noise variances (naming needs 60 for a saturation or an asymmetry after the first" in said
        assert below["stopped"].endswith(f"tentative: {effect} (59.90), later steps gaining under 60 noise variances")
    # other effects keep the bound of 3; a first step, a pair's step and an explained record are left alone here
    assert _run([_step("creep", 100.0), _step("delay", 4.0)])["effects"] == ["creep", "delay"]
    assert _run([_step("saturation", 4.0), _step("creep", 100.0)])["effects"] == ["saturation", "creep"]
    paired = [_step("creep", 100.0), _step("saturation", 10.0, evidence={"paired": "fitted jointly with creep"})]
    assert _run(paired)["effects"] == ["creep", "saturation"]
    assert _run([_step("creep", 100.0), _step("asymmetry", 10.0)], "explained")["effects"] == ["creep", "asymmetry"]
    # both bounds at once: the stop line names both
    both = _run([_step("creep", 100.0), _step("delay", 1.0), _step("asymmetry", 30.0)])
    assert both["effects"] == ["creep"] and both["tentative"] == ["delay", "asymmetry"]
    assert both["stopped"].endswith("later steps gaining under 3 or 60 noise variances")


def _assert_model_reproduces_the_rms(rep, r):
    """The returned model, tentative parts and all, reproduces the reported held-out RMS (to 1e-9 relative)."""
    held = ~rep._rec.train
    rms = float(np.sqrt(np.mean((r.y - rep.model.simulate(r.v))[held] ** 2)))
    assert rms == pytest.approx(rep.rms_heldout, rel=1e-9)


def test_on_a_seen_record_the_part_stays_in_the_model():
    from realistic import HOLDOUT9

    r = HOLDOUT9["holdout9_asymmetry_generalized_plays_unipolar_staircase"](0)
    rep = diagnose(r.t, r.v, r.y, progress=False)
    # measured in round 36: asymmetry, then an initial state gaining 0.54 noise variances; 1.53 floors left
    assert rep.verdict == "unexplained"
    assert rep.effects == ["asymmetry"] and rep.tentative == ["initial_state"], rep.report()
    st = rep.steps[1]
    assert st["tentative"] and st["evidence"]["held_out_gain_noise_variances"] < LATER_GAIN
    text = rep.report()
    assert "(naming needs 3): tentative, not named" in text
    assert "effects: asymmetry (tentative, not named: initial_state)" in text
    assert rep._final_name() == "PI + asymmetry + initial_state (tentative)"
    d = json.loads(json.dumps(rep.to_dict()))
    assert d["effects"] == ["asymmetry"] and d["tentative_effects"] == ["initial_state"]
    assert d["steps"][1]["tentative"] is True
    # the model keeps the tentative part: it reproduces the reported held-out RMS
    _assert_model_reproduces_the_rms(rep, r)


def test_on_a_seen_record_a_step_the_final_model_needs_is_named():
    from realistic import HOLDOUT36

    r = HOLDOUT36["holdout36_pair_drift_asymmetry_oil_warmup_optical_lever_hammock_1265hz"](1)
    rep = diagnose(r.t, r.v, r.y, progress=False)
    # measured in round 38: a drift (events), then an asymmetry gaining 2.10 noise variances; the drift's event form
    # is then replaced by its trend, and without the asymmetry the held-out mean square rises by 363
    assert rep.effects == ["drift", "asymmetry"] and rep.tentative == [], rep.report()
    ev = rep.steps[1]["evidence"]
    assert ev["held_out_gain_noise_variances"] < LATER_GAIN <= ev["held_out_loss_without_it_noise_variances"]
    assert "small_later_step" not in ev


def test_the_split_not_taken_is_summarised_by_the_same_rule():
    from hystcomp.diagnose.splits import choose_split
    from test_diagnose_blocks import _split

    end = _split("unexplained", ["asymmetry", "initial_state"], 1.5)
    end["steps"] = [_step("asymmetry", 24.8), _step("initial_state", 0.54)]
    end["ambiguous"], end["stopped"] = {}, "no remaining effect pays"
    end = _small_later_steps(end, lambda s: None)
    blocks = _split("unexplained", ["saturation", "delay"], 1.7, blocks=True)
    blocks["steps"] = [_step("saturation", 30.0), _step("delay", 1.0)]
    blocks["ambiguous"], blocks["stopped"] = {}, "no remaining effect pays"
    chosen = choose_split(end, blocks, lambda s: None)
    # no drift named by the blocks: the end is taken; the blocks' summary names what the rule names
    assert chosen["effects"] == ["asymmetry"] and chosen["tentative"] == ["initial_state"]
    assert chosen["other_split"]["effects"] == ["saturation"] and chosen["other_split"]["tentative"] == ["delay"]


def test_on_a_record_explained_a_small_later_asymmetry_is_tentative():
    # round 47: on records explained, the asymmetries added after the first step below 2.5 noise variances were wrong
    # 15 times in 16 over the forty-five committed sets
    assert EXPLAINED_SHAPE_GAIN == 2.5
    out = _run([_step("delay", 40.0), _loss("asymmetry", 0.81, 0.78)], verdict="explained")
    assert out["verdict"] == "explained"
    assert out["effects"] == ["delay"] and out["tentative"] == ["asymmetry"]
    said = out["steps"][1]["evidence"]["small_later_step"]
    assert said == ("added after the first step on a record explained, it lowers the held-out mean square by only "
                    "0.81 noise variances, and the final model loses 0.78 without it (naming needs 2.5): tentative, "
                    "not named")
    assert "tentative: asymmetry (0.81), later steps gaining under 2.5 noise variances" in out["stopped"]
    assert "asymmetry" not in out["ambiguous"] and "delay" in out["ambiguous"]


@pytest.mark.parametrize("gain, loss, named", [(2.49, None, False), (2.51, None, True), (0.34, 2.71, True),
                                               (1.0, 2.49, False), (-0.2, None, True)])
def test_the_bound_on_a_record_explained(gain, loss, named):
    # 0.34 gained, 2.71 lost without it: HOLDOUT44's pair at seed 1, the smallest right asymmetry above the bound
    step = _step("asymmetry", gain) if loss is None else _loss("asymmetry", gain, loss)
    out = _run([_step("creep", 30.0), step], verdict="explained")
    assert out["effects"] == (["creep", "asymmetry"] if named else ["creep"])
    assert out["verdict"] == "explained"


@pytest.mark.parametrize("effect", ["initial_state", "gain_drift", "delay", "rate_dependence", "creep"])
def test_on_a_record_explained_other_effects_stay_named(effect):
    # a later drift is held to LATER_DRIFT_GAIN on any record (round 60)
    out = _run([_step("asymmetry", 30.0), _step(effect, 0.5)], verdict="explained")
    assert out["effects"] == ["asymmetry", effect] and out["tentative"] == []


def test_on_a_record_explained_a_small_saturation_is_tentative_at_any_step():
    # round 47: on records explained, the saturations below 3.5 noise variances were all wrong (12, six on clean
    # records); the smallest right one gained 3.72
    out = _run([_step("saturation", 0.63)], verdict="explained")
    assert out["effects"] == [] and out["tentative"] == ["saturation"] and out["verdict"] == "explained"
    said = out["steps"][0]["evidence"]["small_later_step"]
    assert said.startswith("found at the first step on a record explained, it lowers the held-out mean square by "
                           "only 0.63 noise variances (naming needs 2.5)")
    assert "tentative: saturation (0.63), steps gaining under 2.5 noise variances" in out["stopped"]
    out = _run([_step("saturation", 3.72)], verdict="explained")
    assert out["effects"] == ["saturation"] and out["tentative"] == []
    out = _run([_step("initial_state", 9.0), _loss("output_saturation", 2.37, 2.37)], verdict="explained")
    assert out["effects"] == ["initial_state"] and out["tentative"] == ["output_saturation"]
    # on a record left unexplained the first step stays named, whatever it is
    assert _run([_step("saturation", 0.63)])["effects"] == ["saturation"]


@pytest.mark.parametrize("gain, loss, named", [(1.49, None, False), (1.53, None, True), (0.25, 1.6, True),
                                               (1.14, 1.3, False), (2.25, None, True)])
def test_on_a_record_explained_a_first_asymmetry_needs_its_own_bound(gain, loss, named):
    # round 54: the six first asymmetries on explained records below 1.5 noise variances were wrong (0.25 ... 1.30;
    # HOLDOUT51's clean PMN-PT stack gained 0.25, 0.54 and 1.14); right ones gained 1.53 and 2.25
    assert EXPLAINED_FIRST_ASYMMETRY_GAIN == 1.5
    step = _step("asymmetry", gain) if loss is None else _loss("asymmetry", gain, loss)
    out = _run([step], verdict="explained")
    assert out["verdict"] == "explained"
    assert out["effects"] == (["asymmetry"] if named else [])
    if not named:
        said = out["steps"][0]["evidence"]["small_later_step"]
        assert said.startswith(f"found at the first step on a record explained, it lowers the held-out mean square "
                               f"by only {gain:.2f} noise variances")
        assert said.endswith("(naming needs 1.5 for an asymmetry at the first step on a record explained, which may "
                             "be taking up a trace of a core lopsided by itself): tentative, not named")
        assert "tentative: asymmetry" in out["stopped"] and out["tentative"] == ["asymmetry"]
    # a later asymmetry keeps the bound of 2.5
    later = _run([_step("creep", 30.0), _step("asymmetry", 2.0)], verdict="explained")
    assert later["effects"] == ["creep"]


def test_on_a_record_explained_a_pair_stays_named():
    paired = _step("asymmetry", 1.0, evidence={"paired": "fitted jointly with saturation (output_tanh)"})
    assert _run([_step("saturation", 30.0), paired], verdict="explained")["effects"] == ["saturation", "asymmetry"]


def test_on_a_seen_explained_record_a_small_asymmetry_is_tentative_and_stays_in_the_model():
    from realistic import HOLDOUT44

    r = HOLDOUT44["holdout44_delay_playback_start_relay_trigger_sprayer_521hz"](0)
    rep = diagnose(r.t, r.v, r.y, progress=False)
    # measured in round 46: the dead time, then an asymmetry gaining 0.81 noise variances (0.78 lost without it),
    # explained at 1.00 true noise levels; round 47 holds the asymmetry back
    assert rep.verdict == "explained"
    assert rep.effects == ["delay"] and rep.tentative == ["asymmetry"], rep.report()
    ev = rep.steps[1]["evidence"]
    assert rep.steps[1]["tentative"] and ev["held_out_gain_noise_variances"] < EXPLAINED_SHAPE_GAIN
    assert "on a record explained" in ev["small_later_step"]
    # the dead time is reported with its near tie, a lag (rate_dependence), as in round 46
    assert "verdict: explained; effects: delay (or rate_dependence) (tentative, not named: asymmetry)" in rep.report()
    _assert_model_reproduces_the_rms(rep, r)


def test_on_a_seen_clean_record_a_small_saturation_is_tentative_and_nothing_is_named():
    from realistic import HOLDOUT40

    r = HOLDOUT40["holdout40_clean_depoled_pzt_grain_switching_windscreen_wiper_1385hz"](0)
    rep = diagnose(r.t, r.v, r.y, progress=False)
    # measured in round 46: a saturation (a cubic output map) gaining 0.63 noise variances at the first step, explained
    # at 1.04 noise floors, on a clean core whose grains switch (not quite PI); round 47 holds it back
    assert rep.verdict == "explained"
    assert rep.effects == [] and rep.tentative == ["saturation"], rep.report()
    assert rep.steps[0]["tentative"] and "found at the first step" in rep.steps[0]["evidence"]["small_later_step"]
    assert "verdict: explained; effects: none (tentative, not named: saturation)" in rep.report()
    _assert_model_reproduces_the_rms(rep, r)


def test_on_a_record_explained_a_later_saturation_needs_ten_noise_variances():
    # round 50: on `explained` records the saturations added after the first step were not labelled in 17 of 24 over
    # the forty-eight committed sets (9 of them under 10 noise variances); they need 10, their gain or the final
    # model's loss without them
    assert EXPLAINED_LATER_SATURATION_GAIN == 10.0
    for effect in ("saturation", "output_saturation"):
        below = _run([_step("delay", 40.0), _step(effect, 9.99)], verdict="explained")
        above = _run([_step("delay", 40.0), _step(effect, 10.01)], verdict="explained")
        needed = _run([_step("delay", 40.0), _loss(effect, 3.0, 10.01)], verdict="explained")
        assert below["effects"] == ["delay"] and below["tentative"] == [effect], effect
        assert below["verdict"] == "explained" and below["steps"][1]["tentative"]
        assert above["effects"] == ["delay", effect] and needed["effects"] == ["delay", effect]
        said = below["steps"][1]["evidence"]["small_later_step"]
        assert said == ("added after the first step on a record explained, it lowers the held-out mean square by only "
                        "9.99 noise variances (naming needs 10 for a saturation after the first step on a record "
                        "explained, which may be taking up the bend of a core that saturates by itself): tentative, "
                        "not named")
        assert below["stopped"].endswith(f"tentative: {effect} (9.99), later steps gaining under 10 noise variances")
    # a first saturation keeps the bound of 2.5; a later asymmetry too; a pair's saturation is judged with its pair
    assert _run([_step("saturation", 3.0), _step("delay", 40.0)], "explained")["effects"] == ["saturation", "delay"]
    assert _run([_step("delay", 40.0), _step("asymmetry", 3.0)], "explained")["effects"] == ["delay", "asymmetry"]
    paired = [_step("creep", 100.0), _step("saturation", 5.0, evidence={"paired": "fitted jointly with creep"})]
    assert _run(paired, "explained")["effects"] == ["creep", "saturation"]
    # on a record left unexplained the bound of 60 holds instead (round 49), with its own reason
    said = _run([_step("delay", 40.0), _step("saturation", 30.0)])["steps"][1]["evidence"]["small_later_step"]
    assert "naming needs 60 for a saturation or an asymmetry after the first step on a record left unexplained" in said
    # both explained bounds at once: the stop line names both
    both = _run([_step("delay", 40.0), _step("asymmetry", 1.0), _step("saturation", 5.0)], "explained")
    assert both["effects"] == ["delay"] and both["tentative"] == ["asymmetry", "saturation"]
    assert both["stopped"].endswith("later steps gaining under 2.5 or 10 noise variances")


def test_the_blocks_are_weighed_against_the_effects_the_end_would_name():
    # round 57: the blocks may not add an effect to the end's; the end's small later steps are not its effects
    from hystcomp.diagnose.splits import blocks_explain_what_end_named, choose_split
    from test_diagnose_blocks import _split

    end = _split("unexplained", ["asymmetry", "initial_state"], 2.0)
    end["steps"] = [_step("asymmetry", 24.8), _step("initial_state", 0.54)]
    end["ambiguous"], end["stopped"] = {}, "no remaining effect pays"
    before = copy.deepcopy(end["steps"])
    for named, taken in ((["asymmetry"], True), (["asymmetry", "initial_state"], False)):
        blocks = _split("explained", named, 1.2, blocks=True)
        assert blocks_explain_what_end_named(end, blocks) is taken
    # the end's steps are weighed on a copy: left as they were
    assert end["steps"] == before and end["effects"] == ["asymmetry", "initial_state"]
    chosen = choose_split(end, _split("explained", ["asymmetry"], 1.2, blocks=True), lambda s: None)
    assert chosen["verdict"] == "explained" and chosen["effects"] == ["asymmetry"]


@pytest.mark.parametrize("verdict", ["explained", "unexplained"])
@pytest.mark.parametrize("gain, loss, named", [(4.99, None, False), (5.01, None, True), (1.53, 1.53, False),
                                               (3.3, 4.91, False), (2.0, 5.88, True), (-2.7, 0.74, True)])
def test_a_later_drift_needs_five_noise_variances_on_any_record(verdict, gain, loss, named):
    # round 60: over the fifty-eight committed sets the seven drifts named after the first step whose gain and loss
    # were both under 5 noise variances (1.53 ... 4.91) were all unlabelled; the smallest labelled ones are 5.88 and
    # 5.90 (pairs with a saturation and with an asymmetry); a step with a negative gain is judged elsewhere
    assert LATER_DRIFT_GAIN == 5.0
    step = _step("drift", gain) if loss is None else _loss("drift", gain, loss)
    out = _run([_step("rate_dependence", 27.1), step], verdict=verdict)
    assert out["verdict"] == verdict
    assert out["effects"] == (["rate_dependence", "drift"] if named else ["rate_dependence"])
    if not named:
        assert out["tentative"] == ["drift"] and out["steps"][1]["tentative"]
        said = out["steps"][1]["evidence"]["small_later_step"]
        where = "explained" if verdict == "explained" else "left unexplained"
        assert said.startswith(f"added after the first step on a record {where}, it lowers the held-out mean square "
                               f"by only {gain:.2f} noise variances")
        assert said.endswith("(naming needs 5 for a drift after the first step, which may be taking up a slow misfit "
                             "the earlier parts leave): tentative, not named")
        assert out["stopped"].endswith(f"tentative: drift ({gain:.2f}), later steps gaining under 5 noise variances")


def test_a_first_drift_and_a_later_gain_drift_keep_their_bounds():
    # the drift's bound is for a drift after the first step: a first drift is left alone on any record; a gain drift
    # after the first step keeps the bound of 3 (labelled ones gained 1-3 at later steps)
    for verdict in ("explained", "unexplained"):
        assert _run([_step("drift", 0.8)], verdict)["effects"] == ["drift"]
    assert _run([_step("creep", 40.0), _step("gain_drift", 3.5)])["effects"] == ["creep", "gain_drift"]
    assert _run([_step("creep", 40.0), _step("gain_drift", 2.5)])["effects"] == ["creep"]
    assert _run([_step("creep", 40.0), _step("gain_drift", 0.5)], "explained")["effects"] == ["creep", "gain_drift"]
    # a pair's drift is judged with its pair
    paired = [_step("asymmetry", 60.0), _step("drift", 2.0, evidence={"paired": "fitted jointly with asymmetry"})]
    assert _run(paired, "explained")["effects"] == ["asymmetry", "drift"]

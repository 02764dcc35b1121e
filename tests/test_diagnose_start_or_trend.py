"""A memory at the record's start or a drift (hystcomp/diagnose/start_or_trend.py).

When a drift part and an initial-state part gain alike on the held-out part
(both flat there), the training fit, which holds the record's start, decides.
The rule itself is tested on hand-made step tables; the diagnosis on records
of the realistic sets (tests/realistic: mechanisms written from their physics
by sessions that did not read the diagnosis), where it decides a step, where
it must leave a true drift alone, and in the revision.
"""

import json

import pytest

from hystcomp.diagnose import diagnose
from hystcomp.diagnose.base import REST_BIC
from hystcomp.diagnose.start_or_trend import START_OR_TREND, start_or_trend
from realistic import ALL

AMB = 0.1


def _ok(*rows):
    """Acceptable parts as the search sorts them: (gain, kind, training BIC change, signature present)."""
    return sorted(((g, k, b, True) for k, g, b in rows), reverse=True)


def test_rule_takes_the_other_kind_on_a_near_tie_with_a_lower_training_bic():
    ok = _ok(("offset_drift", 159.8, -45035.0), ("slow_drift", 159.6, -49830.0),
             ("initial_state", 159.0, -48944.0), ("ringing_preload", 127.3, -60000.0))
    kind, why = start_or_trend("offset_drift", ok, AMB)
    # the preload's BIC is lowest but its gain is 80 % of the best: not a near tie
    assert kind == "initial_state"
    assert why["held_out_chose"] == "offset_drift" and why["taken"] == "initial_state"
    assert why["training_bic_change"] == {"offset_drift": -45035.0, "initial_state": -48944.0}
    # ... and the reverse: an initial state chosen held out gives way to a drift that fits training better
    ok = _ok(("ringing_preload", 38.8, -24336.0), ("slow_drift", 39.1 - 0.5, -25216.0))
    assert start_or_trend("ringing_preload", ok, AMB)[0] == "slow_drift"


@pytest.mark.parametrize("rows, why", [
    ([("slow_drift", 50.0, -100.0), ("initial_state", 44.0, -5000.0)], "outside the near tie (88 %)"),
    ([("slow_drift", 50.0, -100.0), ("initial_state", 49.0, -100.0 - REST_BIC)], "BIC lower by REST_BIC only"),
    ([("slow_drift", 50.0, -100.0), ("slow_gain_drift", 49.0, -5000.0)], "drift and gain drift: one kind"),
    ([("output_lag", 50.0, -100.0), ("initial_state", 49.0, -5000.0)], "the choice is no drift"),
])
def test_rule_keeps_the_choice(rows, why):
    ok = _ok(*rows)
    assert start_or_trend(ok[0][1], ok, AMB) == (ok[0][1], None), why


def test_sides():
    assert START_OR_TREND == {"drift": "trend", "gain_drift": "trend", "initial_state": "start"}


_CACHE = {}


def _run(prefix, seed, held_out="auto"):
    name = [n for n in ALL if n.startswith(prefix)][0]
    if (name, seed, held_out) not in _CACHE:
        rec = ALL[name](seed)
        _CACHE[name, seed, held_out] = (rec, diagnose(rec.t, rec.v, rec.y, progress=False, held_out=held_out))
    return _CACHE[name, seed, held_out]


@pytest.mark.parametrize("prefix, seed, held_out", [
    # until round 57 also HOLDOUT15's underdamped servo at seed 1 (a servo's ringing leaves it; the drift 29.6,
    # the preload 27.3): since then the blocks split, which names the initial state alone and explains the
    # record, is reported, and its step carries no near tie with a drift
    # a preload below the stroke before random drive; the slow drift 24.8, the two-point preload 24.0, the
    # training BIC lower by 29,500 for the preload (round 31; until round 30 this test's first record was
    # HOLDOUT19's teleoperation at seed 0, below)
    ("holdout5_initial_state_preload_below_random", 2, "auto"),
])
def test_a_memory_is_named_where_a_drift_gained_a_hair_more(prefix, seed, held_out):
    rec, rep = _run(prefix, seed, held_out)
    assert rep.effects == ["initial_state"]
    ev = rep.steps[0]["evidence"]
    told = ev["start_or_trend"]
    assert START_OR_TREND[rep.steps[0]["effect"]] == "start"
    chose = told["held_out_chose"]
    assert chose in ev["acceptable"] and told["taken"] == ev["extension"]["kind"]
    bic = told["training_bic_change"]
    assert bic[told["taken"]] < bic[chose] - REST_BIC
    # the held-out gains were a near tie: the drift stays one in the report
    assert rep.ambiguous == {"initial_state": ["drift"]}
    gains = told["held_out_gain_noise_variances"]
    assert gains[told["taken"]] >= (1 - AMB) * gains[chose]
    # the model reproduces the reported held-out RMS (1e-9 relative)
    sim = rep.model.simulate(rec.v)
    held = ~rep._rec.train
    rms = float(((rec.y - sim)[held] ** 2).mean() ** 0.5)
    assert rms == pytest.approx(rep.rms_heldout, rel=1e-9)
    text = rep.report()
    assert "the training part, which holds the record's start, takes initial_state" in text
    js = json.loads(json.dumps(rep.to_dict()))
    assert js["schema_version"] == 30
    assert js["steps"][0]["evidence"]["start_or_trend"]["taken"] == told["taken"]


def test_a_memory_that_gains_most_held_out_needs_no_rule():
    # a teleoperator's moves leave the memory. Rounds 22-30: the offset drift gained 159.8 noise variances
    # held out, the two-point preload 159.0, and the rule took the preload (round 21 named drift). Since
    # round 31 the preload of four free reversals gains most held out (160.6), so the step takes it
    # without the rule, and the drift stays a near tie
    rec, rep = _run("holdout19_initial_state_fitts", 0)
    assert rep.effects == ["initial_state"]
    ev = rep.steps[0]["evidence"]
    assert "start_or_trend" not in ev and ev["extension"]["kind"] == "staircase_preload"
    gains = ev["acceptable"]
    assert gains["staircase_preload"] > max(gains["offset_drift"], gains["slow_drift"]) > gains["initial_state"]
    assert rep.ambiguous == {"initial_state": ["drift"]}


@pytest.mark.parametrize("prefix, seed", [
    # a cooling drift beside eddy currents: drift and preload within 1 % held out, the drift's training
    # BIC lower by 880
    ("holdout5_pair_eddy_cooling", 2),
    # a cooling drift under random drive: the drift ahead held out by 7 % and in training by 27,500
    ("holdout4_drift_cooling_random", 1),
])
def test_a_true_drift_stays_a_drift(prefix, seed):
    rec, rep = _run(prefix, seed)
    assert "drift" in rep.effects and "initial_state" not in rep.effects
    assert not any("start_or_trend" in st["evidence"] for st in rep.steps)


def test_the_revision_keeps_the_memory():
    # eddy currents in a magnetostrictive coil and a memory: the revision refits a drift in the memory's place,
    # within 0.05 noise variances held out and with fewer parameters; the training part keeps the memory
    rec, rep = _run("holdout17_pair_rate_initial_state_magnetostrictive", 1)
    assert set(rep.effects) == {"rate_dependence", "initial_state"}
    assert not any(r["effect_after"] == "drift" for r in rep.revisions)

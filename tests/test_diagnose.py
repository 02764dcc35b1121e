"""hystcomp.diagnose, blind: only (t, v, y) go in.

Records of the library's own generator (hystcomp.datasets.hidden_effect_data,
40 s at dt = 0.01 s) with one hidden effect must get that effect named first;
clean records no effect and the verdict "explained"; records the model cannot
explain the verdict "unexplained" with what remains.  Measured records: the
piezo record (hystcomp.data) and B-H loops without a time axis
(tests/data/szewczyk_bh, see its SOURCE.md).  The realistic generator of
tests/realistic/ is evaluated by benchmarks/eval_diagnose_realistic.py (a
table in docs/diagnose.md), not here: it takes minutes.
"""

import json
import os
import re

import numpy as np
import pytest

from hystcomp.datasets import EFFECTS as LIB_EFFECTS
from hystcomp.datasets import hidden_effect_data
from hystcomp.diagnose import ALL, EFFECTS, diagnose, evidence
from hystcomp.diagnose.record import find_holds
from hystcomp.identify.search import PartsModel
from hystcomp.signals import identification_experiment

DT = 0.01
HERE = os.path.dirname(__file__)


def test_canonical_effect_names():
    assert set(EFFECTS) == {"rate_dependence", "creep", "drift", "gain_drift", "asymmetry", "saturation",
                            "output_saturation", "delay", "initial_state"}
    assert ALL == EFFECTS


@pytest.mark.parametrize("effect", LIB_EFFECTS)
def test_library_generator_effect_named_first(effect):
    # seeds 20 and 21 were not looked at while the detector was tuned
    named = 0
    for seed in (20, 21):
        d = hidden_effect_data(effect, seed=seed, dt=DT)
        rep = diagnose(d.t, d.v, d.y, progress=False)
        named += rep.effects[:1] == [effect]
        assert rep.rms_after <= 0.5 * rep.rms_before, (d.mechanism, rep.report())
        # never closer than chance below the sensor noise (1200 held-out samples: +-5 %)
        assert rep.rms_after > 0.85 * d.noise
    assert named == 2, effect


def test_clean_records_explained_without_effects():
    bad = []
    for seed in range(120, 128):
        d = hidden_effect_data(None, seed=seed, dt=DT)
        rep = diagnose(d.t, d.v, d.y, progress=False)
        if rep.effects or rep.verdict != "explained":
            bad.append((seed, rep.effects, rep.verdict))
        else:
            # the noise floor comes from the record itself: within 20 % of the true noise
            assert rep.noise_floor == pytest.approx(d.noise, rel=0.2)
            assert rep.rms_heldout <= 1.5 * rep.noise_floor
    assert len(bad) <= 1, bad


def test_report_json_and_model_reproduces_heldout_rms():
    d = hidden_effect_data("drift", seed=7, dt=DT)
    rep = diagnose(d.t, d.v, d.y, progress=False)
    assert rep.effects[0] == "drift" and rep.verdict == "explained"
    step = rep.steps[0]
    assert step["rms_before"] == rep.rms_before and step["rms_after"] < step["rms_before"]
    ev = step["evidence"]
    assert ev["signature"]["present"] and ev["signature"]["statistic"] > ev["signature"]["threshold"]
    assert isinstance(rep.model, PartsModel) and "drift" in rep.model.effects
    k = int(round(d.t.size * 0.7))
    pred = rep.model.simulate(d.v)
    rms = np.sqrt(np.mean((d.y[k:] - pred[k:]) ** 2))
    assert rms == pytest.approx(rep.rms_heldout, rel=1e-9)   # the same numbers, recomputed
    base = rep.base_model.simulate(d.v)
    assert np.sqrt(np.mean((d.y[k:] - base[k:]) ** 2)) == pytest.approx(rep.rms_before, rel=1e-9)
    js = json.loads(rep.to_json())
    assert js["schema_version"] == 30
    for key in ("verdict", "noise_floor", "effects", "steps", "untested", "stopped", "remaining",
                "rms_before_pct", "rms_after_pct", "held_out_blocks", "other_split"):
        assert key in js
    s = js["steps"][0]
    assert list(s)[:5] == ["effect", "rms_before", "rms_after", "rms_before_pct", "rms_after_pct"]
    assert s["rms_after_pct"] == pytest.approx(100 * s["rms_after"] / np.ptp(d.y))
    # every RMS also in % of the output span, the held-out one too (schema 13)
    assert js["rms_heldout_pct"] == pytest.approx(100 * rep.rms_heldout / np.ptp(d.y), rel=1e-12)
    assert js["noise_floor_pct"] == pytest.approx(100 * rep.noise_floor / np.ptp(d.y), rel=1e-12)
    assert js["rest"] == {"origin": 0.0, "other": None}       # the record reaches 0 V
    # the signature gates the fit: at the first step the parts fitted are those
    # whose effect's signature is present in the base residual, the others are
    # listed as not fitted (and both lists are non-empty on this record)
    from hystcomp.identify.parts import PARTS

    fitted, skipped = s["evidence"]["candidates"], s["evidence"]["signature_absent"]
    assert fitted and skipped and not set(fitted) & set(skipped)
    first = rep.first_evidence
    assert all(first[PARTS[k].effect]["present"] for k in fitted if PARTS[k].effect in first)
    assert all(not first[PARTS[k].effect]["present"] for k in skipped if PARTS[k].effect in first)


@pytest.mark.parametrize("effect,mechanism,seed", [("rate_dependence", "lag", 3),
                                                   ("asymmetry", "branch_gain", 5),
                                                   ("rate_dependence", "rate_thresholds", 2)])
def test_model_reproduces_reported_rms_for_every_part_kind(effect, mechanism, seed):
    d = hidden_effect_data(effect, seed=seed, dt=DT, mechanism=mechanism)
    rep = diagnose(d.t, d.v, d.y, progress=False)
    k = int(round(d.t.size * 0.7))
    rms = np.sqrt(np.mean((d.y[k:] - rep.model.simulate(d.v)[k:]) ** 2))
    assert rms == pytest.approx(rep.steps[-1]["rms_after"], rel=1e-9)


def test_two_hidden_effects_both_named():
    # asymmetry (branch gain) and an offset drift of 4 % of the span
    d = hidden_effect_data("asymmetry", seed=4, dt=DT, mechanism="branch_gain")
    y = d.y + 0.04 * np.ptp(d.y) * (d.t / d.t[-1]) ** 1.5
    rep = diagnose(d.t, d.v, y, progress=False)
    assert {"asymmetry", "drift"} <= set(rep.effects), rep.report()
    assert rep.verdict == "explained"
    gaps = [rep.rms_before] + [s["rms_after"] for s in rep.steps]
    assert all(b < a for a, b in zip(gaps, gaps[1:]))


def test_out_of_vocabulary_misfit_is_unexplained():
    # a hum not tied to the input (a pump's vibration on the sensor, 0.37 Hz, 1 % of the output span): no part
    # of the vocabulary and no rate-independent core draws it: "unexplained", saying where (measured: 3.87
    # noise floors left, the Preisach-type core 4.39)
    d = hidden_effect_data(None, seed=5, dt=DT)
    y = d.y + 0.01 * np.ptp(d.clean) * np.sin(2 * np.pi * 0.37 * d.t + 0.4)
    rep = diagnose(d.t, d.v, y, progress=False)
    assert rep.verdict == "unexplained", rep.report()
    assert rep.remaining and rep.rms_heldout > 1.5 * rep.noise_floor
    assert "correlated_residual" in rep.remaining
    assert not rep.preisach_core["explains"] and not rep.preisach_core["taken"]


def test_a_static_map_outside_the_vocabulary_is_drawn_by_a_preisach_type_core():
    # a dead zone on the output (not among the effects): the PI model and the vocabulary leave structure
    # (16 noise floors, measured); a Preisach-type core, which draws a monotone map after the core closely,
    # leaves 0.99 and is taken: explained with nothing named, what the PI model left kept under pi_remaining
    d = hidden_effect_data(None, seed=5, dt=DT)
    c = np.median(d.clean)
    w = 0.15 * np.ptp(d.clean)
    y = d.clean - np.clip(d.clean - c, -w, w) + (d.y - d.clean)
    rep = diagnose(d.t, d.v, y, progress=False)
    pc = rep.preisach_core
    assert rep.verdict == "explained" and rep.effects == [] and pc["taken"], rep.report()
    assert rep.rms_heldout <= rep.explained_limit * rep.noise_floor and rep.remaining == {}
    # the PI model's misfit is still readable: far above the bound, with structure
    assert pc["pi_remaining"]["held_out"].startswith("held-out RMS") and rep.rms_before > 5 * rep.noise_floor
    assert "with the PI core, remained: held-out RMS" in rep.report()


def test_no_time_axis_leaves_timed_effects_untested():
    d = hidden_effect_data("saturation", seed=1, dt=DT, mechanism="tanh_envelope")
    rep = diagnose(None, d.v, d.y, progress=False)
    assert {"rate_dependence", "creep", "drift", "delay"} <= set(rep.untested)
    assert not set(rep.effects) & {"rate_dependence", "creep", "drift", "delay", "gain_drift"}
    assert rep.effects[0] == "saturation"
    assert "time axis" in rep.untested["rate_dependence"]


def test_noisy_input_holds_are_found_and_creep_named():
    exp = identification_experiment(dt=DT)
    d = hidden_effect_data("creep", seed=6, dt=DT, mechanism="multi_time_constant")
    rng = np.random.default_rng(0)
    v_meas = d.v + 5e-4 * np.ptp(d.v) * rng.standard_normal(d.v.size)   # amplifier monitor noise
    holds = find_holds(v_meas, DT, np.ptp(v_meas))
    assert len(holds) >= 0.8 * len(find_holds(exp.v, DT, np.ptp(exp.v)))
    rep = diagnose(d.t, v_meas, d.y, progress=False)
    assert "creep" not in rep.untested and rep.effects[0] == "creep", rep.report()


def test_unipolar_record_without_false_drift():
    d = hidden_effect_data(None, seed=8, dt=DT)
    v = 50.0 * (d.v - d.v.min()) / np.ptp(d.v)                 # 0 .. 50 V
    from hystcomp.models import PI

    r = np.linspace(0, 50, 41)[1:-1]
    y = PI(r, np.exp(-r / 20) / 20, 0.4).simulate(v)
    y = y + 0.002 * np.ptp(y) * np.random.default_rng(1).standard_normal(y.size)
    rep = diagnose(d.t, v, y, progress=False)
    assert rep.effects == [] and rep.verdict == "explained", rep.report()


def test_coarse_sampling_step_and_record_away_from_zero():
    # dt = 1 s (Nyquist 0.5 Hz: no fixed frequency grid above it) and an input at 1000 +- 1
    d = hidden_effect_data(None, seed=9, dt=DT)
    t = np.arange(d.t.size) * 1.0
    rep = diagnose(t[::4], 1000.0 + d.v[::4], d.y[::4], progress=False)
    assert rep.verdict in ("explained", "unexplained") and np.isfinite(rep.rms_heldout)
    assert rep.rms_heldout < 0.5 * np.std(d.y)


def test_piezo_record_initial_state_not_asymmetry():
    from hystcomp.data import load_piezo

    t, v, y = load_piezo()
    rep = diagnose(t[::5], v[::5], y[::5], progress=False)
    assert "asymmetry" not in rep.effects[:1]
    assert rep.effects[:1] == ["initial_state"] or (rep.verdict == "unexplained" and rep.remaining)
    assert rep.effects[0] == "initial_state"
    assert rep.rms_after < 0.2 * rep.rms_before
    if rep.verdict == "unexplained":
        # until round 17: the initial state alone, unexplained (1.75 noise floors) with no drift
        # named, so re-judged on blocks spread over the record, which names no drift either
        # and is not taken
        assert rep.other_split["held_out"] == "blocks" and "not taken" in rep.other_split["why"]
    else:
        # rounds 18-30 at 1 kHz: the ringing preload at step 1 (0.0795 um), asymmetry at step 2,
        # the two-point preload back in the revision (0.0680 um, 1.41 noise floors). Since
        # round 31 the preload of four free reversals alone (0.0663 um, 1.37 noise floors,
        # fitted reversals -0.98, 0.24, -0.26, 0.05 of the scaled input: a shrinking
        # alternation), explained within its bound; the level shift is the initial state's
        assert rep.effects == ["initial_state"]
        kinds = [p["kind"] for p in rep.model.describe() if p.get("effect") == "initial_state"]
        assert kinds == ["staircase_preload"]
        assert rep.rms_heldout <= rep.explained_limit * rep.noise_floor


def _bh(material):
    from scipy.io import loadmat

    folder = os.path.join(HERE, "data", "szewczyk_bh")
    H = loadmat(os.path.join(folder, f"H_{material}.mat"))["HmeasT"]
    B = loadmat(os.path.join(folder, f"B_{material}.mat"))["BmeasT"]
    return H.T.ravel(), B.T.ravel()       # the loops one after the other, smallest first


@pytest.mark.parametrize("material", ["MnZn_ferrite", "M130_27s"])
def test_bh_loops_without_time_axis_saturation_no_rate_effect(material):
    H, B = _bh(material)
    rep = diagnose(None, H, B, progress=False)
    assert rep.effects[0] == "saturation", rep.report()
    assert not set(rep.effects) & {"rate_dependence", "creep", "drift", "delay", "gain_drift"}
    assert "rate_dependence" in rep.untested


def test_evidence_signatures_point_at_the_effect():
    sat = evidence(*hidden_effect_data("saturation", seed=0, dt=DT, mechanism="cubic")[:3])
    assert sat["saturation"]["present"] and sat["saturation"]["statistic"] > sat["saturation"]["threshold"]
    cr = evidence(*hidden_effect_data("creep", seed=0, dt=DT, mechanism="multi_time_constant")[:3])
    assert cr["creep"]["present"]
    rd = evidence(*hidden_effect_data("rate_dependence", seed=0, dt=DT, mechanism="lag")[:3])
    assert rd["rate_dependence"]["present"]
    none = evidence(*hidden_effect_data(None, seed=0, dt=DT)[:3])
    assert not any(v["present"] for v in none.values()), {k: v["statistic"] for k, v in none.items()}


def test_single_frequency_leaves_rate_dependence_untested():
    t = np.arange(0, 20, 0.01)
    v = np.sin(2 * np.pi * 0.5 * t)
    d = hidden_effect_data("rate_dependence", seed=0, dt=0.01, experiment=(t, v), mechanism="lag")
    rep = diagnose(d.t, d.v, d.y, progress=False)
    assert "rate_dependence" in rep.untested and "rate_dependence" not in rep.effects
    assert "one rate" in rep.untested["rate_dependence"]
    # ... and it warns that a delay named at one frequency may be a lag (the same phase shift)
    assert "dead time" in rep.untested["rate_dependence"]


def test_plots(tmp_path):
    import matplotlib

    matplotlib.use("Agg")
    d = hidden_effect_data("asymmetry", seed=0, dt=DT)
    rep = diagnose(d.t, d.v, d.y, progress=False, max_effects=1)
    figs = rep.plots()
    assert set(figs) == {"signatures", "loops", "gap"}
    assert len(figs["gap"].axes) == 1 + len(rep.steps)        # one residual panel per step
    paths = rep.save_plots(tmp_path)
    assert all(os.path.getsize(p) > 1000 for p in paths)


def test_bad_arguments():
    d = hidden_effect_data(None, seed=0, dt=DT)
    with pytest.raises(ValueError, match="effects"):
        diagnose(d.t, d.v, d.y, effects=["friction"], progress=False)
    with pytest.raises(ValueError, match="validation"):
        diagnose(d.t, d.v, d.y, validation=1.5, progress=False)
    with pytest.raises(ValueError, match="not increasing"):
        diagnose(d.t[::-1], d.v, d.y, progress=False)
    with pytest.raises(ValueError, match="has 10 samples but v has"):
        diagnose(d.t, d.v, d.y[:10], progress=False)
    with pytest.raises(ValueError, match="base"):
        diagnose(d.t, d.v, d.y, base="bouc-wen", progress=False)
    with pytest.raises(ValueError, match="constant"):
        diagnose(d.t, np.ones(d.t.size), d.y, progress=False)


def test_write_your_own_effect_example_in_the_docs_runs():
    text = open(os.path.join(HERE, "..", "docs", "diagnose.md")).read()
    section = text.split("## Write your own effect", 1)[1]
    code = re.findall(r"```python\n(.*?)```", section, re.S)[0]
    scope = {}
    exec(compile(code, "docs/diagnose.md", "exec"), scope)
    rep = scope["rep"]
    assert rep.effects[:1] == ["dead_zone"] and rep.rms_after < 0.5 * rep.rms_before


def test_output_falling_with_input_and_constant_output():
    # a sensor wired the other way round: the same record with -y is explained the same way
    d = hidden_effect_data(None, seed=11, dt=DT)
    rep = diagnose(d.t, d.v, -d.y, progress=False)
    assert rep.effects == [] and rep.verdict == "explained", rep.report()
    k = int(round(d.t.size * 0.7))
    rms = np.sqrt(np.mean((-d.y[k:] - rep.model.simulate(d.v)[k:]) ** 2))
    assert rms == pytest.approx(rep.rms_heldout, rel=1e-9)
    with pytest.raises(ValueError, match="y is constant"):
        diagnose(d.t, d.v, np.ones(d.t.size), progress=False)


def test_fast_structure_below_a_high_frequency_floor_is_not_explained():
    # an output unrelated to the input (another record's response): its fast structure fools the
    # second-difference noise estimate, but the residual is far from white -> "unexplained"
    a = hidden_effect_data(None, seed=12, dt=DT)
    b = hidden_effect_data(None, seed=13, dt=DT, amplitude=0.5)
    rep = diagnose(a.t, a.v, np.roll(b.y, 700), progress=False)
    assert rep.verdict == "unexplained", rep.report()


def _clean(seed):
    d = hidden_effect_data(None, seed=seed, dt=DT)
    return d, d.clean, d.y - d.clean


@pytest.mark.parametrize("effect", ["delay", "gain_drift", "output_saturation"])
def test_new_effects_named(effect):
    # seed 40 was not used while tuning; one mechanism per effect, built from a clean record
    d, H, noise = _clean(40)
    if effect == "delay":                                   # 4 samples of dead time
        y = np.concatenate([np.full(4, H[0]), H[:-4]]) + noise
    elif effect == "gain_drift":                            # gain +12 % over the record
        y = H * (1 + 0.12 * d.t / d.t[-1]) + noise
    else:                                                   # the sensor clips the top 10 %
        lo, hi = np.percentile(H, [3, 90])
        y = np.clip(H, lo, hi) + noise
    rep = diagnose(d.t, d.v, y, progress=False)
    assert rep.effects == [effect], rep.report()
    assert rep.verdict == "explained"


def test_creep_on_an_asymmetric_actuator_both_named():
    # the combined case: creep (two input lags, 6 % of the span) on asymmetric branches
    from hystcomp.effects import lag_bank

    a = hidden_effect_data("asymmetry", seed=40, dt=DT, mechanism="branch_gain")
    X = lag_bank(a.v, [0.3, 2.0], DT)[0]
    y = a.y + 0.06 * np.ptp(a.clean) * (X @ [0.5, 0.5] - a.v)
    rep = diagnose(a.t, a.v, y, progress=False)
    assert set(rep.effects[:2]) == {"asymmetry", "creep"}, rep.report()


def test_evidence_only_one_effect_equals_the_full_evidence():
    from hystcomp.diagnose.record import Record
    from hystcomp.diagnose.signatures import evidence as signatures

    d = hidden_effect_data("creep", seed=1, dt=DT)
    rec = Record(d.t, d.v, d.y, 0.3)
    e = rec.y - np.polyval(np.polyfit(rec.v, rec.y, 1), rec.v)
    full = signatures(rec, e, rec.y - e, 0.01)
    for k in full:
        assert signatures(rec, e, rec.y - e, 0.01, only=k)[k] == full[k]


def test_diagnose_many_on_an_executor_equals_one_by_one():
    from concurrent.futures import ProcessPoolExecutor

    from hystcomp.diagnose import diagnose_many

    recs = [hidden_effect_data(e, seed=2, dt=DT)[:3] for e in ("drift", "creep", None)]
    here = diagnose_many(recs, progress=False)
    with ProcessPoolExecutor(2) as ex:
        there = diagnose_many(recs, executor=ex, progress=False)
    for a, b in zip(here, there):
        assert (a.effects, a.verdict) == (b.effects, b.verdict)
        assert b.rms_heldout == pytest.approx(a.rms_heldout, rel=1e-9)
        # the diagnosed model came back through pickle and still simulates
        assert np.allclose(b.model.simulate(recs[0][1]), a.model.simulate(recs[0][1]), rtol=0, atol=1e-9)
    with pytest.raises(TypeError, match="records\\[0\\]"):
        diagnose_many([1.0])
    with pytest.raises(TypeError, match="executor"):
        diagnose_many(recs[:1], executor=object())

"""hystcomp.diagnose, blind: only (t, v, y) of simulated measurements with one
hidden effect go in; the effect must be named first and the held-out RMS must
at least halve; data without an effect must give none in >= 19 of 20 seeds.

The records are the 40 s identification experiment at dt = 0.01 s (4000
samples) -- the full confusion matrix over many seeds at dt = 0.004 s lives in
examples/diagnose_hidden_effects.py and docs/diagnose.md.
"""

import json

import numpy as np
import pytest

from hystcomp.datasets import EFFECTS, hidden_effect_data
from hystcomp.diagnose import ALL, diagnose, evidence
from hystcomp.effects import Parallel
from hystcomp.signals import identification_experiment

DT = 0.01


@pytest.mark.parametrize("seed", [0, 1])
@pytest.mark.parametrize("effect", EFFECTS)
def test_names_the_hidden_effect_and_halves_the_gap(effect, seed):
    d = hidden_effect_data(effect, seed=seed, dt=DT)
    rep = diagnose(d.t, d.v, d.y, progress=False)
    assert rep.effects and rep.effects[0] == effect, (d.mechanism, rep.summary())
    assert rep.rms_after <= 0.5 * rep.rms_before, (d.mechanism, rep.summary())
    # the gap closes down to about the sensor noise (never below it by more than chance:
    # 1200 held-out samples give the noise RMS to +-5 %; 0.9 leaves margin)
    assert rep.rms_after > 0.9 * d.noise


def test_no_false_alarms_in_19_of_20_seeds():
    false = []
    for seed in range(100, 120):
        d = hidden_effect_data(None, seed=seed, dt=DT)
        rep = diagnose(d.t, d.v, d.y, progress=False)
        if rep.effects:
            false.append((seed, rep.effects))
        else:
            assert rep.rms_after == rep.rms_before and "none" in rep.summary()
    assert len(false) <= 1, false


def test_report_contents_and_final_model():
    d = hidden_effect_data("drift", seed=7, dt=DT)
    rep = diagnose(d.t, d.v, d.y, progress=False)
    assert rep.effects[0] == "drift"
    step = rep.steps[0]
    assert step["rms_before"] == rep.rms_before
    assert step["rms_after"] < step["rms_before"]
    ev = step["evidence"]
    assert set(ev) >= {"signature", "extension", "held_out_gain", "candidates"}
    assert set(ev["candidates"]) == set(ALL)
    assert ev["signature"]["r2_time"] > 0.5        # the drift signature is visible in the residual
    # the final model is a protocol model that reproduces the reported held-out RMS
    assert isinstance(rep.model, Parallel)
    pred = rep.model.simulate(d.v)
    k = int(round(d.t.size * 0.7))
    rms = np.sqrt(np.mean((d.y[k:] - pred[k:]) ** 2))
    assert rms == pytest.approx(rep.rms_after, rel=1e-9)   # the same numbers, another code path
    assert rep.validation == (pytest.approx(d.t[k]), pytest.approx(d.t[-1]))
    # the base model too
    base = rep.base_model.simulate(d.v)
    assert np.sqrt(np.mean((d.y[k:] - base[k:]) ** 2)) == pytest.approx(rep.rms_before, rel=1e-9)
    js = json.loads(rep.to_json())
    assert list(js) == ["effects", "rms_before", "rms_after", "validation", "steps"]
    assert list(js["steps"][0]) == ["effect", "rms_before", "rms_after", "evidence"]


def test_chained_effects_are_added_in_order_of_pay():
    # drift and a strong saturation together: both found, each step shrinking the gap
    d = hidden_effect_data("saturation", seed=3, dt=DT, mechanism="tanh_envelope")
    y = d.y + 0.05 * np.ptp(d.y) * d.t / d.t[-1]
    rep = diagnose(d.t, d.v, y, progress=False)
    assert set(rep.effects[:2]) == {"saturation", "drift"}
    gaps = [rep.rms_before] + [s["rms_after"] for s in rep.steps]
    assert all(b < 0.9 * a for a, b in zip(gaps, gaps[1:]))


def test_without_holds_creep_and_drift_are_untested():
    exp = identification_experiment(dt=DT, holds=False)
    d = hidden_effect_data("creep", seed=1, dt=DT, experiment=(exp.t, exp.v))
    rep = diagnose(d.t, d.v, d.y, progress=False)
    assert set(rep.untested) == {"creep", "drift"}
    assert "untested" in rep.untested["creep"]
    assert "creep" not in rep.effects and "drift" not in rep.effects
    assert "untested" in rep.summary()


def test_evidence_signatures_point_at_the_effect():
    sat = evidence(*hidden_effect_data("saturation", seed=0, dt=DT, mechanism="cubic")[:3])
    assert sat["saturation"]["r2_cubic"] > 0.2 and sat["saturation"]["cubic_coefficient"] < 0
    cr = evidence(*hidden_effect_data("creep", seed=0, dt=DT, mechanism="multi_time_constant")[:3])
    assert cr["creep"]["corr_step"] > 0.5
    rd = evidence(*hidden_effect_data("rate_dependence", seed=0, dt=DT, mechanism="lag")[:3])
    assert rd["rate_dependence"]["r2_rate"] > 0.2
    none = evidence(*hidden_effect_data(None, seed=0, dt=DT)[:3])
    assert none["saturation"]["r2_cubic"] < 0.2 and none["rate_dependence"]["r2_rate"] < 0.2


def test_plots(tmp_path):
    import matplotlib

    matplotlib.use("Agg")
    d = hidden_effect_data("asymmetry", seed=0, dt=DT)
    rep = diagnose(d.t, d.v, d.y, progress=False, max_effects=1)
    figs = rep.plots()
    assert set(figs) == {"signatures", "loops", "gap"}
    assert len(figs["signatures"].axes) == 6
    paths = rep.save_plots(tmp_path)
    assert all((tmp_path / p.split("/")[-1]).stat().st_size > 1000 for p in paths)


def test_bad_arguments():
    d = hidden_effect_data(None, seed=0, dt=DT)
    with pytest.raises(ValueError, match="effects"):
        diagnose(d.t, d.v, d.y, effects=["friction"], progress=False)
    with pytest.raises(ValueError, match="validation"):
        diagnose(d.t, d.v, d.y, validation=1.5, progress=False)
    with pytest.raises(ValueError, match="not increasing"):
        diagnose(d.t[::-1], d.v, d.y, progress=False)
    with pytest.raises(ValueError, match="has 10 samples but t has"):
        diagnose(d.t, d.v, d.y[:10], progress=False)
    with pytest.raises(ValueError, match="base"):
        diagnose(d.t, d.v, d.y, base="bouc-wen", progress=False)


def test_single_frequency_leaves_rate_dependence_untested():
    t = np.arange(0, 20, 0.01)
    v = np.sin(2 * np.pi * 0.5 * t)
    d = hidden_effect_data("rate_dependence", seed=0, dt=0.01, experiment=(t, v), mechanism="lag")
    rep = diagnose(d.t, d.v, d.y, progress=False)
    assert "rate_dependence" in rep.untested and "rate_dependence" not in rep.effects
    assert "one rate" in rep.untested["rate_dependence"]

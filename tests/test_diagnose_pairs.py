"""Two effects fitted jointly, and extensions left tentative on an out-of-vocabulary core.

The records come from the realistic mechanisms of ``tests/realistic`` (not hystcomp's model
parts) with parameters and seeds that neither the tuning set nor the held-out sets use.
"""

import json

import numpy as np
import pytest

from hystcomp.diagnose import diagnose
from hystcomp.identify.parts import PARTS
from realistic import excitations as ex
from realistic import mechanisms as me


def _creep_on_warming_stage(seed, compliances=(0.025, 0.035), hold=2.0):
    """Kelvin-Voigt creep under a thermal offset: a staircase with `hold` s holds."""
    rng = np.random.default_rng([seed, 7070])
    dt = 1e-3
    levels = np.concatenate([[0.0], np.tile([35.0, -45.0], 5) * rng.uniform(0.6, 1.0, 10)])
    v = ex.staircase_holds(dt, levels, hold, 0.05)
    t = np.arange(len(v)) * dt
    h = me.play_core(v, 90.0)
    y = h + me.kelvin_voigt_creep(h, dt, list(compliances), [0.3, 3.0]) + me.thermal_offset(t, 0.05 * np.ptp(h), 12.0)
    y = y + 0.002 * np.ptp(y) * rng.standard_normal(len(y))
    return t, v + 5e-4 * np.ptp(v) * rng.standard_normal(len(v)), y


def test_creep_under_a_drift_is_found_with_it(monkeypatch):
    # creep alone does not carry to the held-out part while the stage warms; the pair step
    # fits it jointly with the drift. Since round 11 (creep driven by the model's output with
    # the right sign) creep alone carries on the 2 s holds of seeds 0-7, so the pair step is
    # exercised on 1.5 s holds and stronger creep, where seed 2 pairs (seeds 0-2 measured:
    # seed 2 pairs, 0 and 1 find creep, then drift). Since round 32 the drift made of events
    # (24 segments) follows this warming well enough that creep alone is named first and the
    # drift after it (test below); the pair step is exercised here without that part
    monkeypatch.delitem(PARTS, "event_drift")
    t, v, y = _creep_on_warming_stage(2, compliances=(0.05, 0.07), hold=1.5)
    rep = diagnose(t, v, y, progress=False)
    assert set(rep.effects) == {"creep", "drift"}, rep.report()
    paired = [s for s in rep.steps if "paired" in s["evidence"]]
    assert len(paired) == 2, rep.report()
    # the two steps are the lead alone, then the pair: the second step ends at the pair's RMS
    assert paired[1]["rms_before"] == pytest.approx(paired[0]["rms_after"])
    assert paired[0]["evidence"]["pair_lead"] is True and paired[1]["evidence"]["pair_lead"] is False
    # the report and the gap figure say that the lead stands alone (its held-out RMS may rise)
    # and that the next step is the pair
    lead, partner = paired[0]["effect"], paired[1]["effect"]
    assert "alone fits the training part best but does not carry" in rep.report()
    import matplotlib.pyplot as plt
    figs = rep.plots()
    titles = [a.get_title() for a in figs["gap"].axes]
    assert any(f"+ {lead} (alone; {partner} is fitted jointly with it in the next panel)" in t for t in titles), titles
    assert any(f"+ {partner} (fitted jointly with {lead} " in t for t in titles), titles
    for f in figs.values():
        plt.close(f)
    # the returned model reproduces the reported held-out RMS
    held = slice(rep._rec.held_start, rep._rec.held_end)
    rms = float(np.sqrt(np.mean((y - rep.model.simulate(v))[held] ** 2)))
    assert rms == pytest.approx(rep.rms_heldout, rel=1e-9)
    # within 2.5 noise floors: the thermal law and the two Kelvin-Voigt elements are
    # not the parts' laws exactly (measured 1.56 floors; the base PI leaves about 5)
    assert rep.rms_heldout < 2.5 * rep.noise_floor


def test_creep_under_a_drift_with_every_part_needs_no_pair():
    # the record above with every registered part: creep is named alone at the first step (it
    # carries 68.7 noise variances held out), then the drift made of events; explained
    # (measured 1.32 noise floors, against 1.56 by the pair step without that part)
    t, v, y = _creep_on_warming_stage(2, compliances=(0.05, 0.07), hold=1.5)
    rep = diagnose(t, v, y, progress=False)
    assert rep.effects == ["creep", "drift"], rep.report()
    assert not [s for s in rep.steps if "paired" in s["evidence"]]
    assert rep.steps[1]["evidence"]["extension"]["kind"] == "event_drift"
    assert rep.verdict == "explained" and rep.rms_heldout < 1.5 * rep.noise_floor, rep.report()


def test_a_shapeless_drift_chosen_first_gives_way_to_the_trend_once_creep_is_in():
    # seed 0: the shapeless drift (SlowDrift) carries to the held-out part best at the
    # first step (creep alone does not, its fit spoiled by the warming); once creep is
    # in, the revision refits the drift's other forms in its place and the parametric
    # trend wins (measured in round 11: 2.47 noise floors without the revision, 1.76
    # with it; seed 1 did this before round 11's creep sign)
    t, v, y = _creep_on_warming_stage(0)
    rep = diagnose(t, v, y, progress=False)
    assert set(rep.effects) == {"creep", "drift"}, rep.report()
    swaps = [r for r in rep.revisions if r["replaced"] == "slow_drift" and r["by"] == "offset_drift"]
    assert len(swaps) == 1 and "same effect" in swaps[0]["reason"], rep.revisions
    assert swaps[0]["rms_after"] < 0.8 * swaps[0]["rms_before"]
    assert rep.rms_heldout < 2.0 * rep.noise_floor, rep.report()
    held = slice(rep._rec.held_start, rep._rec.held_end)
    rms = float(np.sqrt(np.mean((y - rep.model.simulate(v))[held] ** 2)))
    assert rms == pytest.approx(rep.rms_heldout, rel=1e-9)


def test_flag_core_extensions_are_tentative_not_named():
    # a shape-memory (flag-shaped) core: no PI with any extension fits it
    rng = np.random.default_rng([3, 9191])
    dt = 1e-3
    v = ex.decaying_sines(dt, 14_000, (0.6, 1.3), 45.0)
    y = me.flag_core(v, 90.0, bias_fraction=0.33)
    y = y + 0.002 * np.ptp(y) * rng.standard_normal(len(y))
    rep = diagnose(np.arange(len(v)) * dt, v, y, progress=False)
    assert rep.verdict == "unexplained"
    assert rep.effects == [], rep.report()
    assert "out_of_vocabulary" in rep.remaining, rep.remaining
    js = json.loads(rep.to_json())
    assert js["schema_version"] == 30
    assert js["effects"] == [] and js["tentative_effects"] == rep.tentative
    assert 0.0 <= js["misfit_share_explained"] < 0.9
    if rep.tentative:
        assert all(s["tentative"] for s in js["steps"])
        assert "tentative, not named" in rep.report()
        # the figures say so too: every step panel and the final one
        import matplotlib.pyplot as plt

        figs = rep.plots()
        titles = [a.get_title() for a in figs["gap"].axes]
        assert all("[tentative]" in t for t in titles[1:len(rep.steps) + 1]), titles
        assert "tentative, not named" in figs["loops"]._suptitle.get_text()
        plt.close("all")


def _tanh_saturated(v):
    """A PI-like core behind a tanh output map, and a noise level of 0.05 % of its span."""
    h = me.play_core(v, 90.0)
    y = np.tanh(1.8 * h / np.abs(h).max())
    return y, 0.0005 * np.ptp(y)


def _saturation_with_chatter(amplitude, seed=5):
    """A tanh-saturating output on a PI-like core under a staircase with 1.5 s holds,
    output noise 0.05 % of the span, plus a 37 Hz chatter while the input moves (its
    amplitude `amplitude` noise RMS times the input's rate over its largest): no part
    describes it, and the holds, where it is silent, confirm the noise floor."""
    rng = np.random.default_rng([seed, 9301])
    dt = 1e-3
    levels = np.concatenate([[0.0], np.tile([40.0, -40.0], 6) * np.linspace(1.0, 0.5, 12)])
    v = ex.staircase_holds(dt, levels, 1.5, 0.4)
    t = np.arange(len(v)) * dt
    y, sigma = _tanh_saturated(v)
    rate = np.abs(np.gradient(v, dt))
    y = y + amplitude * sigma * rate / rate.max() * np.sin(2 * np.pi * 37.0 * t)
    return t, v, y + sigma * rng.standard_normal(len(y))


def _saturation_with_ripple(floors, seed=5):
    """The same saturation under decaying sines (no holds), with a 3.7 Hz ripple of
    `floors` noise RMS not tied to the input."""
    rng = np.random.default_rng([seed, 9301])
    dt = 1e-3
    v = ex.decaying_sines(dt, 14_000, (0.6, 1.3), 45.0)
    y, sigma = _tanh_saturated(v)
    t = np.arange(len(v)) * dt
    y = y + floors * sigma * np.sqrt(2.0) * np.sin(2 * np.pi * 3.7 * t + 0.3)
    return t, v, y + sigma * rng.standard_normal(len(y))


# slow since round 61 (73 s in the default suite, whose CI run had reached 18 min of its 20): run with
# `pytest -m slow`
@pytest.mark.slow
def test_what_leaves_more_than_six_confirmed_noise_floors_is_not_named():
    # saturation (100 times the noise) removes over 98 % of the base misfit above
    # the noise in every record here.  With the floor confirmed by the holds, a
    # chatter that leaves 5.5 noise floors keeps saturation named (unexplained),
    # one that leaves 13 leaves it tentative: more than OOV_LEFT = 6 confirmed
    # floors left is not an explanation, whatever the share
    from hystcomp.diagnose.search import OOV_LEFT

    assert OOV_LEFT == 6.0
    small = diagnose(*_saturation_with_chatter(30.0), progress=False)
    assert "holds" in small.noise_info
    assert small.effects == ["saturation"] and small.verdict == "unexplained", small.report()
    assert 3.0 < small.rms_heldout / small.noise_floor < OOV_LEFT
    # the chatter correlates the residual; the holds' scatter confirms the floor,
    # so the report says the correlation is missed structure, not doubt in the floor
    assert "confirms the noise floor" in small.remaining["correlated_residual"]
    big = diagnose(*_saturation_with_chatter(80.0), progress=False)
    assert "holds" in big.noise_info
    assert big.effects == [] and big.tentative == ["saturation"], big.report()
    assert big.misfit_share_explained > 0.98
    assert big.rms_heldout > OOV_LEFT * big.noise_floor
    assert f"naming allows at most {OOV_LEFT:g}" in big.remaining["out_of_vocabulary"]
    # without holds, on a time axis, the high-frequency floor counts as confirmed
    # (round 35: on the realistic records it was 0.96-1.62 of the true noise), so a
    # 3.7 Hz ripple that leaves more than 6 floors holds the saturation back ...
    t, v, y = _saturation_with_ripple(15.0)
    timed = diagnose(t, v, y, progress=False)
    assert "holds" not in timed.noise_info
    assert timed.rms_heldout > OOV_LEFT * timed.noise_floor
    assert timed.effects == [] and timed.tentative == ["saturation"], timed.report()
    # ... while without a time axis the floor is the high-frequency estimate of a
    # point sequence, which can be far below its scatter (smooth B-H loops:
    # tests/test_diagnose.py), and the floors left do not hold the part back
    ripple = diagnose(None, v, y, progress=False)
    assert "holds" not in ripple.noise_info
    assert ripple.rms_heldout > OOV_LEFT * ripple.noise_floor
    assert ripple.effects == ["saturation"] and ripple.verdict == "unexplained", ripple.report()
    assert "holds in the record would tell" in ripple.remaining["correlated_residual"]


def test_named_effects_explain_most_of_the_misfit():
    # the counterpart: a saturating output on a PI core is named, and its model
    # removes nearly all of the misfit above the noise
    rng = np.random.default_rng([4, 9192])
    dt = 1e-3
    v = ex.decaying_sines(dt, 14_000, (0.6, 1.3), 45.0)
    h = me.play_core(v, 90.0)
    y = np.tanh(1.8 * h / np.abs(h).max())
    y = y + 0.002 * np.ptp(y) * rng.standard_normal(len(y))
    rep = diagnose(np.arange(len(v)) * dt, v, y, progress=False)
    assert rep.effects == ["saturation"], rep.report()
    assert rep.tentative == []
    assert rep.misfit_share_explained > 0.99
    # and no near tie: the clipping map, next best, gains about 0.77 of the tanh
    # map's held-out gain on the seen tanh-output cases (near tie: 0.9)
    assert rep.ambiguous == {}, rep.report()


# slow since round 61 (26 s in the default suite, whose CI run had reached 18 min of its 20): run with
# `pytest -m slow`
@pytest.mark.slow
def test_a_part_replaced_by_another_of_its_effect_is_titled_by_both_parts():
    # HOLDOUT7's butterfly (seed 0): the revision replaces the algebraic saturation
    # map by the tanh map; "saturation (replaced by saturation)" said nothing, the
    # gap figure's step title names the two parts
    import matplotlib.pyplot as plt
    from realistic import ALL

    r = ALL["holdout7_oov_preisach_butterfly_trapezoids"](0)
    rep = diagnose(r.t, r.v, r.y, progress=False)
    same = [rv for rv in rep.revisions if rv["by"] is not None and rv["effect_before"] == rv["effect_after"]]
    assert same, rep.report()
    titles = [a.get_title() for a in rep.plots()["gap"].axes]
    plt.close("all")
    for rv in same:
        step_title = titles[rv["step"]]
        assert f"({rv['replaced']}, replaced by {rv['by']} in the revision)" in step_title, titles

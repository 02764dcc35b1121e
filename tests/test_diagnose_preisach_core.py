"""A Preisach-type core on a record left unexplained (hystcomp/diagnose/preisach_core.py; round 44), and
the held-out mask of the plane fits it uses (``fit_kp``, ``fit_preisach``: ``train``).

The fit's mask is checked against the fit on the record cut at the same sample (the same weights to
1e-10: the same least-squares problem, rounding aside) and against an output changed where the mask
is False (no change at all: those samples do not enter). The diagnosis's check runs on records of the
realistic sets (tests/realistic: mechanisms written from their physics by sessions that did not read
the diagnosis): a clean core that is not a PI model, which the vocabulary leaves unexplained with nothing
named and a KP core explains, so the KP core is taken (round 45: verdict ``explained``, the model returned is
the KP core and reproduces the reported held-out RMS); records it does not explain; and a record with an
effect named, whose name, verdict and model the check leaves alone.
"""

import json

import numpy as np
import pytest

from hystcomp.diagnose import diagnose
from hystcomp.diagnose.preisach_core import CELLS, PreisachCoreModel, describe, preisach_core
from hystcomp.identify import fit_kp, fit_preisach
from hystcomp.identify.search import PartsModel
from hystcomp.preisach import KP, model_from_dict
from realistic import ALL


@pytest.fixture(scope="module")
def kp_record():
    rng = np.random.default_rng(3)
    true = KP.from_density(lambda a, b: np.exp(-(a - b)) * (1.0 + 0.5 * a), (-1.0, 1.0), 8)
    v = np.sin(np.linspace(0.0, 40.0, 4000)) * np.linspace(1.0, 0.3, 4000)
    return v, true.simulate(v) + 1e-3 * rng.standard_normal(v.size)


@pytest.mark.parametrize("fit", [fit_kp, fit_preisach])
def test_a_leading_mask_is_the_record_cut_there(kp_record, fit):
    v, y = kp_record
    train = np.arange(v.size) < 2800
    cut = fit(v[:2800], y[:2800], n=8, input_range=(-1.0, 1.0))
    masked = fit(v, y, n=8, input_range=(-1.0, 1.0), train=train)
    np.testing.assert_allclose(masked.param_values, cut.param_values, rtol=0, atol=1e-10)
    assert masked.n_train == 2800 and masked.rmse == pytest.approx(cut.rmse, rel=1e-9)


@pytest.mark.parametrize("fit", [fit_kp, fit_preisach])
def test_samples_outside_the_mask_do_not_enter(kp_record, fit):
    v, y = kp_record
    # every third sample held out, and the held-out output moved far away: the weights do not move
    train = np.arange(v.size) % 3 != 0
    y2 = np.where(train, y, y + 5.0)
    a = fit(v, y, n=8, input_range=(-1.0, 1.0), train=train)
    b = fit(v, y2, n=8, input_range=(-1.0, 1.0), train=train)
    np.testing.assert_array_equal(a.param_values, b.param_values)
    assert a.residuals.size == int(train.sum())


@pytest.mark.parametrize("train, match", [
    (np.ones(5, bool), "boolean mask of the 4000 samples"),
    (np.ones(4000), "boolean mask"),
    (np.zeros(4000, bool), "selects no sample"),
])
def test_a_bad_mask_is_named(kp_record, train, match):
    v, y = kp_record
    with pytest.raises(ValueError, match=match):
        fit_kp(v, y, n=4, train=train)


def test_an_explained_record_gets_no_check():
    said = []
    kw = preisach_core({"verdict": "explained"}, said.append)
    assert kw["preisach_core"] is None and not said
    assert describe(None) is None


def test_the_lines_say_what_it_can_and_cannot_tell():
    pc = {"model": "KP", "cells": 16, "weights": 136, "rms_heldout": 0.1, "noise_floors": 1.01,
          "signatures_present": [], "explains": True, "seconds": 1.0}
    line = describe(pc)
    assert "1.01 noise floors held out with no signature present" in line
    assert "core that is rate independent but not PI" in line and "static map" in line
    assert "taken" not in line
    line = describe(dict(pc, taken=True))
    assert "taken as the model (verdict explained)" in line and "static map" in line
    line = describe(dict(pc, noise_floors=3.84, explains=False, signatures_present=["asymmetry"]))
    assert "(signatures present: asymmetry)" in line and "explains the record either" in line


def _case(prefix, seed, held_out="auto"):
    name = [n for n in ALL if n.startswith(prefix)][0]
    rec = ALL[name](seed)
    return rec, diagnose(rec.t, rec.v, rec.y, progress=False, held_out=held_out)


@pytest.fixture(scope="module")
def capstan():
    # HOLDOUT35's push-pull cable with capstan friction, clean, seed 0: not a PI core (every point of the
    # cable a play of log(1 + |F| / c)); the vocabulary leaves it at 1.32 noise floors with nothing named, a
    # saturation removing none of the misfit, and a correlated residual: unexplained by the PI model.  Held out
    # at the end: since round 57, with held_out="auto" the blocks split, which explains it with the PI model and
    # nothing named (its saturation tentative), is taken before a Preisach-type core is tried
    return _case("holdout35_clean_bowden_cable", 0, "last")


def test_a_core_that_is_not_pi_is_explained_by_a_preisach_type_core(capstan):
    rec, rep = capstan
    # taken: explained, nothing named, the model returned is the KP core
    assert rep.verdict == "explained" and rep.effects == [] and rep.tentative == [] and rep.remaining == {}
    assert isinstance(rep.model, PreisachCoreModel) and rep.model.effects == []
    pc = rep.preisach_core
    assert pc["taken"] and pc["lag1_autocorrelation"] <= 0.6
    assert pc["model"] == "KP" and pc["cells"] == CELLS and pc["weights"] == CELLS * (CELLS + 1) // 2
    # within the explained bound (1.5 noise floors less the floor's standard error) with no signature:
    # measured 1.01 noise floors
    assert pc["explains"] and pc["noise_floors"] <= rep.explained_limit and pc["signatures_present"] == []
    assert pc["rms_heldout"] == pytest.approx(pc["noise_floors"] * rep.noise_floor, rel=1e-3)
    # the KP core's held-out RMS, recomputed from the fit here on the diagnosis's own split
    r = rep._rec
    fit = fit_kp(r.v, r.y, n=CELLS, input_range=(r.vmin, r.vmax), train=r.train, solver="bvls")
    rms = float(np.sqrt(np.mean((r.y - fit.model.simulate(r.v))[~r.train] ** 2)))
    assert rms == pytest.approx(pc["rms_heldout"], rel=1e-9)
    # the model returned reproduces the reported held-out RMS on the record as measured, to 1e-9 (the same
    # arithmetic but the sign and level moved into the weights: rounding only)
    held = ~r.train
    rms_model = float(np.sqrt(np.mean((np.asarray(rec.y) - rep.model.simulate(rec.v))[held] ** 2)))
    assert rms_model == pytest.approx(rep.rms_heldout, rel=1e-9)
    assert rep.rms_heldout == pytest.approx(pc["rms_heldout"], rel=1e-9) and rep.rms_after == rep.rms_heldout
    # the search's final PI model is kept (its held-out RMS as the check-free diagnosis reports it: below), the
    # base model too; the share of the base model's misfit above the noise removed
    assert isinstance(rep.pi_model, PartsModel) and isinstance(rep.base_model, PartsModel)
    assert rep.rms_before > rep.rms_heldout
    assert rep.misfit_share_explained == pytest.approx(
        1 - max(rep.rms_heldout ** 2 - rep.noise_floor ** 2, 0) / (rep.rms_before ** 2 - rep.noise_floor ** 2))
    # its dictionary rebuilds a KP model that simulates the same
    again = model_from_dict(json.loads(json.dumps(rep.model.to_dict())))
    assert type(again) is KP and np.array_equal(again.simulate(rec.v), rep.model.simulate(rec.v))
    js = json.loads(rep.to_json())
    assert js["schema_version"] == 30 and js["preisach_core"]["explains"] is True
    assert js["preisach_core"]["taken"] is True and js["verdict"] == "explained"
    assert js["model"][0]["kind"] == "preisach_core" and js["model"][0]["cells"] == CELLS
    text = rep.report()
    assert "a Preisach-type core (a KP model of 16 x 16 cells" in text
    assert "taken as the model (verdict explained)" in text
    assert text.splitlines()[-1].startswith("verdict: explained; effects: none;")
    assert "Preisach type (KP) explains the record with no effect: taken as the model" in rep.stopped


@pytest.mark.parametrize("prefix, signature", [
    # HOLDOUT23's push rod excited parametrically (its output repeats every two input periods), out of
    # vocabulary: 13.1 noise floors left, the KP core 13.2 (measured)
    ("holdout23_oov_parametric_column_taps_bugle", None),
    # HOLDOUT9's warm-up drift under random drive: the diagnosis names the drift and leaves 1.8 noise floors;
    # a rate-independent core cannot draw a drift in time (7.4 noise floors, the drift signature present)
    ("holdout9_drift_warmup_ambient_step_random", "drift"),
])
def test_what_no_preisach_type_core_explains(prefix, signature):
    rec, rep = _case(prefix, 0)
    assert rep.verdict == "unexplained"
    pc = rep.preisach_core
    # at least 3 noise floors left: twice the explained bound (measured 13.2 and 7.4)
    assert not pc["explains"] and pc["noise_floors"] > 3.0 and not pc["taken"]
    assert isinstance(rep.model, PartsModel)
    if signature:
        assert signature in pc["signatures_present"]
    assert "explains the record either" in rep.report()


def test_the_taken_core_compensates_itself(capstan):
    # the README's promise, a returned model whose exact_inverse() compensates it, holds for the KP core: its
    # inverse drives it along a reference inside its reachable range to 1e-6 of the output span (the inverse
    # solves each sample's monotone relay equation to its own tolerance; measured: 1.2e-15)
    rec, rep = capstan
    m = rep.model
    lo, hi = m.output_bounds()
    t = np.linspace(0.0, 1.0, 3000)
    ref = 0.5 * (lo + hi) + 0.35 * (hi - lo) * np.sin(2 * np.pi * 3 * t) * (1 - 0.5 * t)
    u = m.exact_inverse().simulate(ref)
    assert np.abs(m.simulate(u) - ref).max() <= 1e-6 * (hi - lo)


def test_taken_only_the_verdict_and_the_model_change(monkeypatch, capstan):
    # the same record diagnosed with the check switched off: unexplained with the PI model, the same names
    # and the same base model; the check changed the verdict, the model and the RMS reported, nothing else
    import hystcomp.diagnose.search as search

    rec, rep = capstan
    monkeypatch.setattr(search, "preisach_core", lambda kw, say: dict(kw, preisach_core=None))
    off = diagnose(rec.t, rec.v, rec.y, progress=False, held_out="last")
    assert off.preisach_core is None and rep.preisach_core is not None
    assert off.verdict == "unexplained" and rep.verdict == "explained"
    assert (off.effects, off.rms_before, off.steps) == (rep.effects, rep.rms_before, rep.steps)
    assert isinstance(off.model, PartsModel) and off.rms_heldout > rep.rms_heldout
    held = ~rep._rec.train
    rms_pi = float(np.sqrt(np.mean((np.asarray(rec.y) - rep.pi_model.simulate(rec.v))[held] ** 2)))
    assert rms_pi == pytest.approx(off.rms_heldout, rel=1e-9) and off.pi_model is None


@pytest.fixture(scope="module")
def named_and_explained_by_kp():
    # HOLDOUT41's Faraday polarimeter at seed 0, labelled saturation: the diagnosis names the saturation and
    # leaves the record unexplained at 1.67 noise floors; a KP core alone explains it (1.17, measured in
    # round 44), as it draws a saturating map before the core too
    return _case("holdout41_saturation_faraday_polarimeter", 0)


def test_an_effect_named_keeps_the_pi_model_and_its_verdict(monkeypatch, named_and_explained_by_kp):
    import hystcomp.diagnose.search as search

    rec, rep = named_and_explained_by_kp
    pc = rep.preisach_core
    assert rep.effects == ["saturation"] and pc["explains"] and not pc["taken"]
    assert rep.verdict == "unexplained" and isinstance(rep.model, PartsModel)
    assert "taken" not in describe(pc) and "may be the core's shape" in rep.report()
    monkeypatch.setattr(search, "preisach_core", lambda kw, say: dict(kw, preisach_core=None))
    off = diagnose(rec.t, rec.v, rec.y, progress=False)
    assert (off.verdict, off.effects, off.rms_heldout) == (rep.verdict, rep.effects, rep.rms_heldout)


def test_the_gap_figure_shows_the_preisach_type_core_last(capstan):
    import matplotlib.pyplot as plt

    rec, rep = capstan
    figs = rep.plots()
    try:
        axes = figs["gap"].axes
        # the base PI (nothing named) and the KP core alone, taken, its held-out RMS in the title as reported
        assert len(axes) == 2
        title = axes[-1].get_title()
        assert title.startswith("final: a Preisach-type core alone (KP, 16 x 16 cells), taken as the model")
        assert f"{rep.preisach_core['noise_floors']:.2f} noise floors" in title
        assert figs["loops"]._suptitle.get_text().endswith("KP core (16 x 16 cells, Preisach type)")
    finally:
        for f in figs.values():
            plt.close(f)


def test_bvls_solves_the_same_problem_as_cvxpy(kp_record):
    # the plane's problem (weights >= 0, a free offset, the small ridge) by SciPy's BVLS and by cvxpy: the same
    # weights to the cvxpy solver's tolerance (1e-6 of the largest; measured on realistic records: the
    # held-out RMS to 1e-4 relative or better, the weights to 8e-5)
    v, y = kp_record
    a = fit_kp(v, y, n=8, input_range=(-1.0, 1.0))
    b = fit_kp(v, y, n=8, input_range=(-1.0, 1.0), solver="bvls")
    assert np.abs(a.param_values - b.param_values).max() <= 1e-6 * np.abs(a.param_values).max()
    assert b.rmse == pytest.approx(a.rmse, rel=1e-6)


def test_the_diagnosis_solves_without_cvxpy(monkeypatch, capstan):
    # round 44's CI hung when the check solved the plane with cvxpy (CLARABEL) in processes forked from a pytest
    # worker that had used cvxpy before: the solver's thread pool does not survive a fork. The diagnosis solves
    # it by BVLS; any cvxpy solve during a diagnosis fails this test
    import cvxpy

    def no_cvxpy(*args, **kwargs):
        raise AssertionError("cvxpy called during a diagnosis")

    monkeypatch.setattr(cvxpy.Problem, "solve", no_cvxpy)
    rec, rep = capstan
    again = diagnose(rec.t, rec.v, rec.y, progress=False, held_out="last")
    assert again.preisach_core == {**rep.preisach_core, "seconds": again.preisach_core["seconds"]}

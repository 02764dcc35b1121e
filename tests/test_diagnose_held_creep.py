"""Creep found by its hold test stays named on a record whose misfit is mostly outside the vocabulary (round 55,
:mod:`hystcomp.diagnose.held_creep`).

The record here is built from mechanisms that hystcomp has no part for: the library's clean PI record read through a
fringe that folds back past its top (a raw interferometer reading, rate independent, not monotone) and logarithmic
creep of the input (Jung & Gweon 2000: every step relaxes as gamma dv log10(1 + t / tau0), superposed step by step),
which the creep part's lags only approximate. The fold leaves far more than the noise, so the out-of-vocabulary rule
holds every extension tentative; the creep stays named, since a rate-independent core, folded or not, holds its output
still while its input is held.
"""

import json

import numpy as np
import pytest
from scipy.signal import fftconvolve

from hystcomp.datasets import hidden_effect_data
from hystcomp.diagnose import diagnose
from hystcomp.diagnose.held_creep import CREEP_KEPT_GAIN, CREEP_TAKEN_SHARE, creep_beyond_core

DT = 0.01


def _folded_with_log_creep(fold_at=0.55, gamma=0.25, seed=5):
    """The library's clean record (no effect) read through a fringe whose top lies at `fold_at` of the stroke, plus
    logarithmic creep of the input, gamma output spans per input span per decade (tau0 = 0.1 s), plus its noise."""
    d = hidden_effect_data(None, seed=seed, dt=DT)
    lo, span = d.clean.min(), np.ptp(d.clean)
    y = lo + fold_at * span * np.sin((d.clean - lo) / (fold_at * span) * (np.pi / 2))
    g = np.log10(1.0 + np.arange(d.t.size) * DT / 0.1)
    dv = np.diff(d.v, prepend=d.v[0])
    y = y + gamma * span / np.ptp(d.v) * fftconvolve(dv, g)[: d.t.size]
    return d.t, d.v, y + (d.y - d.clean)


@pytest.fixture(scope="module")
def folded():
    t, v, y = _folded_with_log_creep()
    return diagnose(t, v, y, progress=False)


def test_creep_stays_named_beside_a_fold_no_part_draws(folded):
    rep = folded
    # measured (round 55): 23.5 noise floors left, the fold's asymmetry tentative, creep named
    assert rep.verdict == "unexplained" and rep.rms_heldout > 10 * rep.noise_floor, rep.report()
    assert rep.effects == ["creep"] and "asymmetry" in rep.tentative
    oov = rep.remaining["out_of_vocabulary"]
    assert "a kind hystcomp has no part for" in oov and "creep stays named" in oov
    (creep,) = [s for s in rep.steps if s["effect"] == "creep"]
    assert not creep.get("tentative")
    assert creep["evidence"]["named_beyond_vocabulary"].startswith("creep stays named: the residual relaxed")
    assert all(s.get("tentative") for s in rep.steps if s["effect"] != "creep")
    assert "named beyond the vocabulary's misfit: creep" in rep.stopped


def test_the_json_carries_why_creep_stayed_named(folded):
    js = json.loads(folded.to_json())
    assert js["schema_version"] == 30
    assert js["effects"] == ["creep"] and "asymmetry" in js["tentative_effects"]
    why = [s["evidence"].get("named_beyond_vocabulary") for s in js["steps"] if s["effect"] == "creep"]
    assert why and "no rate-independent core does" in why[0]


def _step(effect="creep", statistic=10.0, threshold=3.0, present=True, gain=5.0, loss=40.0, **kw):
    return {"effect": effect, **kw,
            "evidence": {"signature": {"statistic": statistic, "threshold": threshold, "present": present,
                                       "testable": True},
                         "held_out_gain_noise_variances": gain, "held_out_loss_without_it_noise_variances": loss}}


@pytest.mark.parametrize("left, expect", [
    (0.0, True), ((1 - CREEP_TAKEN_SHARE) * 10.0, True),     # taken up wholly; exactly the share needed
    ((1 - CREEP_TAKEN_SHARE) * 10.0 + 1e-6, False), (9.0, False),   # less than half of it taken up
])
def test_creep_must_have_taken_up_the_holds_relaxation(left, expect):
    kept = creep_beyond_core([_step()], {"creep": {"statistic": left, "threshold": 3.0, "present": left > 3.0}})
    assert (0 in kept) is expect


@pytest.mark.parametrize("step", [
    _step(present=False),                                 # no relaxation during the holds at its step
    _step(gain=CREEP_KEPT_GAIN / 2, loss=CREEP_KEPT_GAIN / 2),   # worth too little held out
    _step(gain=None, loss=None),                          # nothing measured held out
    _step(dropped=True),                                  # dropped by a revision
    _step(effect="drift"),                                # a trend, not creep: a core's misfit may draw one
])
def test_only_creep_that_pays_and_relaxed_during_holds_stays_named(step):
    assert creep_beyond_core([step], {"creep": {"statistic": 0.0, "threshold": 3.0, "present": False}}) == {}


def test_without_a_final_hold_test_nothing_stays_named():
    # a record whose final residual was not tested for creep (no holds): nothing to compare with
    assert creep_beyond_core([_step()], {}) == {}
    assert creep_beyond_core([_step()], None) == {}

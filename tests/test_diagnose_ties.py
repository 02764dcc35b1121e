"""Near ties: effects the record does not tell apart are reported as such.

The record comes from the realistic mechanisms of ``tests/realistic`` (not hystcomp's
model parts) with parameters and a seed that no set of cases uses.
"""

import json

import numpy as np
import pytest

from hystcomp.diagnose import diagnose
from hystcomp.diagnose.search import PARSIMONY
from realistic import excitations as ex
from realistic import mechanisms as me


def _dead_time_record(seed):
    """A PI-like core behind a dead time of 2-3 samples, under band-limited random drive:
    at these frequencies e^(-s d) and 1/(1 + s tau) differ by less than the noise."""
    rng = np.random.default_rng([seed, 4242])
    dt, n = 1e-3, 16_000
    v = ex.bandlimited_random(dt, n, 6.0, 40.0, rng=rng)
    y = me.play_core(me.fractional_delay(v, rng.uniform(2.0, 3.0)), 80.0)
    y = y + 0.002 * np.ptp(y) * rng.standard_normal(n)
    return np.arange(n) * dt, v, y


def test_dead_time_and_lag_are_reported_as_a_near_tie():
    # on every delay case of the seen sets the dead time and the lag after the
    # hysteresis came within 0.3 % of each other's held-out gain; of parts within
    # PARSIMONY noise variances with as many parameters the dead time is named
    # (occam_rank), and the lag is reported as its near tie.  Here the lag after
    # the hysteresis fits 0.003 noise variances better than the dead time.
    t, v, y = _dead_time_record(11)
    rep = diagnose(t, v, y, progress=False)
    assert len(rep.effects) == 1, rep.report()
    named, other = rep.effects[0], "rate_dependence"
    assert named == "delay", rep.report()
    acc = rep.steps[0]["evidence"]["acceptable"]
    assert max(acc.values()) - acc["delay"] <= PARSIMONY
    assert rep.ambiguous == {named: [other]}, rep.report()
    step = rep.steps[0]
    alt = step["alternatives"][0]
    # the definition: the alternative passed every acceptance rule with at least
    # 90 % of the named part's held-out gain
    assert alt["kind"] in step["evidence"]["acceptable"]
    assert alt["held_out_gain_noise_variances"] >= 0.9 * alt["named_gain_noise_variances"]
    js = json.loads(rep.to_json())
    assert js["ambiguous"] == {named: [other]}
    assert js["steps"][0]["alternatives"][0]["effect"] == other
    assert f"{named} (or {other})" in rep.report()
    assert "near tie" in rep.report()


def _viscoplastic_random_record(seed):
    """Viscoplastic plays (a play's threshold widened by its rate) under band-limited
    random drive: a rate dependence that a dead time does not describe."""
    rng = np.random.default_rng([seed, 4343])
    dt, n = 1e-3, 16_000
    v = ex.bandlimited_random(dt, n, 6.0, 40.0, rng=rng)
    y = me.viscoplastic_core(v, dt, 80.0, eta=rng.uniform(4e-3, 6e-3))
    y = y + 0.002 * np.ptp(y) * rng.standard_normal(n)
    return np.arange(n) * dt, v, y


@pytest.mark.parametrize("seed", [1, 2])
def test_a_dead_time_is_preferred_only_on_a_tie(seed):
    # the dead time's occam rank breaks ties only: on rate-dependent plays the
    # rate parts fit better than the dead time by more than PARSIMONY (0.3
    # noise variances on these seeds), and rate dependence is named
    t, v, y = _viscoplastic_random_record(seed)
    rep = diagnose(t, v, y, progress=False)
    assert rep.effects == ["rate_dependence"], rep.report()
    acc = rep.steps[0]["evidence"]["acceptable"]
    assert max(acc.values()) - acc.get("delay", -np.inf) > PARSIMONY


def _unipolar_random_record(seed):
    """A clean PI-like core under a band-limited random drive between about 10 and 90 V."""
    rng = np.random.default_rng([seed, 4343])
    dt, n = 1e-3, 14_000
    v = ex.bandlimited_random(dt, n, 2.0, 38.0, offset=50.0, rng=rng)
    y = me.play_core(v, 95.0)
    y = y + 0.002 * np.ptp(y) * rng.standard_normal(n)
    return np.arange(n) * dt, v + 4e-4 * np.ptp(v) * rng.standard_normal(n), y


def test_unipolar_record_gets_its_plays_where_its_loops_are():
    # thresholds up to the full scale (i/20 of 90 V) put half the plays where only the
    # first loading moves them: on the unseen unipolar random case that left 2.4-2.6
    # noise floors on two of three clean records (unexplained, once a drift named);
    # 16 plays below half the span and 4 above give 1.0-1.3
    from hystcomp.diagnose.search import play_thresholds

    t, v, y = _unipolar_random_record(5)
    rep = diagnose(t, v, y, progress=False)
    r = rep.model._ctx.thresholds
    span = (v.max() - v.min()) / rep._rec.scale
    np.testing.assert_array_equal(r, play_thresholds(span, 20))
    assert np.sum(r < 0.5 * span) == 16
    assert rep.effects == [] and rep.verdict == "explained", rep.report()
    # the returned model is simulated with the thresholds it was fitted with
    held = slice(rep._rec.held_start, rep._rec.held_end)
    rms = float(np.sqrt(np.mean((y - rep.model.simulate(v))[held] ** 2)))
    assert rms == pytest.approx(rep.rms_heldout, rel=1e-9)


def test_thresholds_given_are_the_models_thresholds():
    # thresholds passed by the caller are the returned model's too (the model built
    # for another input used to fall back to i/n)
    t, v, y = _unipolar_random_record(6)
    from hystcomp.models import PI

    base = PI([5.0, 10.0, 20.0, 40.0], [1.0] * 4, 1.0)
    rep = diagnose(t, v, y, effects=["drift"], base=base, progress=False)
    scale = rep._rec.scale
    np.testing.assert_allclose(rep.model._ctx.thresholds * scale, [0.0, 5.0, 10.0, 20.0, 40.0], rtol=1e-12)
    held = slice(rep._rec.held_start, rep._rec.held_end)
    rms = float(np.sqrt(np.mean((y - rep.model.simulate(v))[held] ** 2)))
    assert rms == pytest.approx(rep.rms_heldout, rel=1e-9)


def test_loop_figure_thinning_note_reads_as_english():
    # "every 3rd half-cycle", not "every 3th" (the loops figure of long records)
    from hystcomp.diagnose.report import _ordinal

    assert [_ordinal(n) for n in (1, 2, 3, 4, 11, 12, 13, 21, 22, 103, 111)] == [
        "1st", "2nd", "3rd", "4th", "11th", "12th", "13th", "21st", "22nd", "103rd", "111th"]


def test_a_shift_and_a_lag_share_their_first_order_signature():
    # a dead time T and a lag tau leave the same residual to first order (both
    # 1 - s T): either test present makes both present, so both parts are fitted
    # and the fits decide (HOLDOUT27's Thiran allpass, a delay of 2.6-4.6 samples:
    # the rate test at 0.83-1.05 noise floors, the delay's own at 0.25-0.54, so
    # the dead time was not fitted at seeds 0 and 1 and a lag was named)
    from hystcomp.diagnose.signatures import _shift_or_lag

    def entry(stat, testable=True):
        return {"signature": "s", "statistic": stat, "threshold": 0.5, "present": testable and stat > 0.5,
                "testable": testable, "reading": ""}

    ev = {"delay": entry(0.25), "rate_dependence": entry(0.83)}
    _shift_or_lag(ev)
    assert ev["delay"]["present"] and ev["rate_dependence"]["present"]
    assert ev["delay"]["statistic"] == 0.25                  # its own statistic is kept
    assert "through the rate dependence's test (0.83 > 0.50)" in ev["delay"]["reading"]
    ev = {"delay": entry(0.9), "rate_dependence": entry(0.1)}
    _shift_or_lag(ev)
    assert ev["rate_dependence"]["present"] and "through the delay's test" in ev["rate_dependence"]["reading"]
    ev = {"delay": entry(0.2), "rate_dependence": entry(0.3)}
    _shift_or_lag(ev)
    assert not ev["delay"]["present"] and not ev["rate_dependence"]["present"]
    # one frequency: rate dependence untested, and the delay on its own test
    ev = {"delay": entry(0.2), "rate_dependence": entry(0.0, testable=False)}
    _shift_or_lag(ev)
    assert not ev["delay"]["present"] and not ev["rate_dependence"]["present"]
    ev = {"delay": entry(0.7), "rate_dependence": entry(0.0, testable=False)}
    _shift_or_lag(ev)
    assert ev["delay"]["present"] and not ev["rate_dependence"]["present"]


def test_either_test_alone_returns_both():
    # the search asks for one effect's test after a fit (only=...): the pair comes together
    from hystcomp.diagnose.record import Record
    from hystcomp.diagnose.signatures import evidence

    t, v, y = _dead_time_record(5)
    rec = Record(t, v, y, 0.3)
    e = y - me.play_core(v, 80.0)
    for only in ("delay", "rate_dependence"):
        ev = evidence(rec, e, y - e, 0.002 * np.ptp(y), only=only)
        assert set(ev) == {"delay", "rate_dependence"}
    assert set(evidence(rec, e, y - e, 0.002 * np.ptp(y), only="creep")) == {"creep"}

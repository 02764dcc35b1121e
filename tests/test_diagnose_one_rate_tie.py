"""A delay named on a drive that excites one rate only is a near tie of a rate
dependence (round 37): there the rate test is untested, no rate part is fitted
to tie with the delay, and the report's untested line says that "a delay named
here may be a lag"; ``ambiguous`` now says so too. HOLDOUT35's voltage-driven
coil, whose back-EMF lags its travel, was named a delay at all three seeds of
a drive with its power at one frequency, with no near tie reported."""

import json

import numpy as np
from realistic import mechanisms as me

from hystcomp.diagnose import ALL, diagnose
from hystcomp.diagnose.signatures import ONE_RATE


def _dead_time_at_one_rate(seed=0):
    """A PI-like core (200 plays of a decaying density, not hystcomp's parts)
    under a 3 Hz sine whose amplitude swells and fades over 7 s, 20 s at
    1 kHz, read 20 samples late, with output noise of 0.2 % of the span."""
    rng = np.random.default_rng([seed, 3708])
    dt, n, d = 1e-3, 20_000, 20
    t = np.arange(n) * dt
    v = 45.0 * np.sin(2 * np.pi * 3.0 * t) * (0.6 + 0.4 * np.cos(2 * np.pi * t / 7.0))
    h = me.play_core(v, 100.0)
    y = np.concatenate([np.full(d, h[0]), h[:-d]])
    return t, v, y + 0.002 * np.ptp(y) * rng.standard_normal(n)


def test_a_delay_at_one_rate_is_reported_with_rate_dependence_as_a_near_tie():
    t, v, y = _dead_time_at_one_rate()
    d = diagnose(t, v, y, progress=False)
    assert d._rec.peak_share >= ONE_RATE
    assert "one rate of excitation" in d.untested["rate_dependence"]
    assert d.effects == ["delay"] and d.verdict == "explained"
    assert d.ambiguous == {"delay": ["rate_dependence"]}
    assert "effects: delay (or rate_dependence)" in d.report()
    assert json.loads(d.to_json())["ambiguous"] == {"delay": ["rate_dependence"]}


def test_no_tie_when_rate_dependence_is_not_a_candidate():
    t, v, y = _dead_time_at_one_rate()
    d = diagnose(t, v, y, progress=False, effects=[e for e in ALL if e != "rate_dependence"])
    assert d.effects == ["delay"] and "rate_dependence" not in d.untested
    assert d.ambiguous == {}

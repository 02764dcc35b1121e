"""An initial state named on a record that starts at an end of its input range
may be the memory of the actuator's use before the record: the report, the
JSON and the gap figure say so (since round 40; over the committed realistic sets,
1,845 runs as of round 61, an initial state named on a record starting within 5 %
of the span of an end was the labelled effect in 19 of 56 runs, against 164 of 178
elsewhere; HOLDOUT37's
creep and dead-time records, filled and run in at the stroke's end, got one at
every seed).

The records here come from the test generator's own core (200 plays of a
decaying density with a linear term, ``realistic.mechanisms.play_core``, not
hystcomp's parts) with 0.2 % output noise; "prior use" is one full excursion
0 -> top -> 0 before the record, which leaves the plays that came down raised.
"""

import json

import matplotlib
import numpy as np
import pytest
from realistic import excitations as ex
from realistic import mechanisms as me

from hystcomp.diagnose import diagnose
from hystcomp.diagnose.record import START_END, START_RECORD, Record, start_caution

matplotlib.use("Agg")

DT, N = 2e-3, 12_000


def _unipolar(prior, seed=0):
    """Unipolar triangles 0 ... 100 V (8 periods, decaying by half), from the
    virgin state or after one full excursion (`prior`)."""
    rng = np.random.default_rng([seed, 4001])
    v = ex.unipolar_triangles(N, 8, 100.0, decay=0.5)
    state = None
    if prior:
        pre = np.concatenate([np.linspace(0.0, 100.0, 500), np.linspace(100.0, 0.0, 500)])
        _, state = me.play_core(pre, 100.0, return_state=True)
    h = me.play_core(v, 100.0, state=state)
    return np.arange(N) * DT, v, h + 0.002 * np.ptp(h) * rng.standard_normal(N)


def _bipolar_after_use(seed=0):
    """Triangles +-45 V starting at 0 V, mid-range, after one excursion to
    +45 V and back to 0: an initial state inside the range."""
    rng = np.random.default_rng([seed, 4002])
    v = ex.triangles(DT, N, 0.8, 45.0)
    pre = np.concatenate([np.linspace(0.0, 45.0, 400), np.linspace(45.0, 0.0, 400)])
    _, state = me.play_core(pre, 90.0, return_state=True)
    h = me.play_core(v, 90.0, state=state)
    return np.arange(N) * DT, v, h + 0.002 * np.ptp(h) * rng.standard_normal(N)


def test_the_caution_names_the_end_and_stops_at_the_bound():
    for inside in (START_END, 0.5, 1.0 - START_END):
        assert start_caution(inside) == ""
    low, high = start_caution(0.0), start_caution(0.99)
    assert low.startswith("the record starts at the low end of its input range (0 % of its span from it)")
    assert high.startswith("the record starts at the high end of its input range (1 % of its span from it)")
    # the figures measured on the realistic sets (START_RECORD, round 61: 19 of 56 at an end, 164 of 178 inside)
    (right_end, named_end), (right_in, named_in) = START_RECORD["end"], START_RECORD["inside"]
    assert f"{right_end} of {named_end} runs, against {right_in} of {named_in} elsewhere" in low
    assert right_end / named_end < 0.5 < 0.9 < right_in / named_in
    assert start_caution(0.01, short=True).endswith("(the initial state may be prior use)")


def test_the_start_is_the_smoothed_first_input_in_the_range():
    t, v, y = _unipolar(prior=False)
    rec = Record(t, v, y, 0.3)
    assert rec.start_in_input_range == pytest.approx((rec.vs[0] - v.min()) / np.ptp(v), rel=1e-12)
    assert rec.start_in_input_range < 0.01
    # the stroke mirrored (100 V - v) starts at its top; a monitor's noise of
    # 0.05 % of the span moves the start by far less than the bound (0.05)
    noisy = 100.0 - v + 0.05 * np.random.default_rng(1).standard_normal(N)
    assert Record(t, noisy, y, 0.3).start_in_input_range > 1.0 - 0.01
    t, v, y = _bipolar_after_use()
    assert abs(Record(t, v, y, 0.3).start_in_input_range - 0.5) < 0.01


def test_prior_use_at_the_end_is_named_and_cautioned():
    t, v, y = _unipolar(prior=True)
    d = diagnose(t, v, y, progress=False)
    assert "initial_state" in d.effects
    assert "caution: the record starts at the low end of its input range" in d.report()
    js = json.loads(d.to_json())
    assert js["schema_version"] == 30
    assert js["start_in_input_range"] == pytest.approx(d._rec.start_in_input_range, rel=1e-12) and \
        js["start_in_input_range"] < START_END
    assert "may be prior use" in d.plots()["gap"]._suptitle.get_text().replace("\n", " ")


def test_no_caution_without_an_initial_state_or_inside_the_range():
    # the same stroke from the virgin state: nothing named, no caution
    t, v, y = _unipolar(prior=False)
    d = diagnose(t, v, y, progress=False)
    assert d.effects == [] and d.start_in_input_range < START_END
    assert "starts at the low end" not in d.report()
    # an initial state on a record starting mid-range: named, not cautioned
    t, v, y = _bipolar_after_use()
    d = diagnose(t, v, y, progress=False)
    assert "initial_state" in d.effects
    assert "starts at the" not in d.report() and START_END < d.start_in_input_range < 1.0 - START_END

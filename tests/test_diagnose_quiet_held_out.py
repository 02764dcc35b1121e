"""A held-out part over which the input barely moves (a quiet tail) tests
nothing the input drives: the report, the JSON and the gap figure say so
(round 37: HOLDOUT35's aftershock sequence at seed 2 left the last 30 % of its
record moving over 0.22 % of the input span, and the report read "unexplained
at 0.99 noise floors" with no word on why the held-out part could not judge)."""

import json

import matplotlib
import numpy as np
import pytest
from realistic import excitations as ex
from realistic import mechanisms as me

from hystcomp.diagnose import diagnose
from hystcomp.diagnose.record import QUIET, Record, quiet_caution

matplotlib.use("Agg")


def _record(quiet_end, seed=0):
    """A PI-like core (200 plays of a decaying density, not hystcomp's parts)
    under triangles, 20 s at 500 Hz, with output noise of 0.2 % of the span;
    with `quiet_end` the input stops at 60 % of the record and is held there
    with a monitor's noise of 0.01 % of its span."""
    rng = np.random.default_rng([seed, 3707])
    dt, n = 2e-3, 10_000
    v = ex.triangles(dt, n, 0.8, 45.0)
    if quiet_end:
        k = int(0.6 * n)
        v[k:] = v[k - 1] + 1e-4 * np.ptp(v) * rng.standard_normal(n - k)
    h = me.play_core(v, 100.0)
    return np.arange(n) * dt, v, h + 0.002 * np.ptp(h) * rng.standard_normal(n)


def test_the_caution_names_the_share_and_stops_at_the_bound():
    assert quiet_caution(QUIET) == "" and quiet_caution(0.3) == ""
    s = quiet_caution(0.0123)
    assert s.startswith("the held-out part moves the input over only 1.2 % of its span")
    assert "held_out='blocks'" in s
    assert quiet_caution(0.0123, short=True).endswith("(it tests little)")


def test_the_held_out_share_is_the_held_out_inputs_span_over_the_inputs():
    t, v, y = _record(quiet_end=True)
    rec = Record(t, v, y, 0.3)
    k = rec.k_val
    assert rec.blocks == [(k, v.size)]                      # the end is held out: the block is not moved
    assert rec.held_input_share == pytest.approx(np.ptp(v[k:]) / np.ptp(v), rel=1e-12)
    assert rec.held_input_share < 1e-3                      # the monitor's noise only
    rec = Record(t, v, y, 0.3, "blocks")
    assert rec.held_input_share == pytest.approx(np.ptp(v[~rec.train]) / np.ptp(v), rel=1e-12)
    assert rec.held_input_share > 0.5                       # the blocks from 30 % on hold triangles out


def test_a_quiet_end_is_cautioned_in_the_report_the_json_and_the_figure():
    t, v, y = _record(quiet_end=True)
    d = diagnose(t, v, y, progress=False)
    assert d.held_out_input_share < QUIET
    assert "caution: the held-out part moves the input over only" in d.report()
    js = json.loads(d.to_json())
    assert js["schema_version"] == 30
    assert js["held_out_input_share"] == pytest.approx(np.ptp(v[~d._rec.train]) / np.ptp(v), rel=1e-12)
    fig = d.plots()["gap"]
    assert "it tests little" in fig._suptitle.get_text().replace("\n", " ")
    # the same record with the input moving to its end: no caution
    t, v, y = _record(quiet_end=False)
    d = diagnose(t, v, y, progress=False)
    assert d.held_out_input_share > 0.5 and "tests nothing the input drives" not in d.report()
    assert json.loads(d.to_json())["held_out_input_share"] == pytest.approx(d.held_out_input_share)

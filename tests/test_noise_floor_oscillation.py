"""The noise floor from holds (hystcomp.diagnose.noise.noise_floor) is not taken from an output
that oscillates while the input is held (round 18).

The scatter of the output during the holds sets the floor when it exceeds the residual's
high-frequency part, so that coloured sensor noise is not underestimated. HOLDOUT16's
hydraulic follower hunts in a limit cycle through every hold (12-18 Hz, 4-7 % of the span);
its scatter during the holds made a floor of 8-11 true noise levels and the record, whose
residual was that limit cycle, came out ``explained``. An oscillation swings its
autocorrelation to about -1 at half its period; sensor noise, white or low-pass filtered,
keeps it near or above 0.

The records: the realistic generator's PI core (tests/realistic/mechanisms.py, 200 plays of
its own density, not hystcomp's) under a staircase of 30 random levels within +-45 V, each
held 0.8 s after a 50 ms ramp, 400 Hz; with a vibration of 3 % of the output span at 11 Hz
through the whole record plus white sensor noise (0.2 % of the span), or with low-pass
filtered sensor noise alone (AR(1), coefficient 0.8, 0.4 % of the span).
"""

import numpy as np
import pytest

from hystcomp.diagnose import diagnose
from hystcomp.diagnose.noise import OSCILLATING, hold_oscillation
from realistic import mechanisms as me

DT = 1 / 400


def _staircase(rng):
    levels = rng.uniform(-45.0, 45.0, 30)
    levels[:2] = [45.0, -45.0]
    v, prev = [], 0.0
    for lv in levels:
        v.append(np.linspace(prev, lv, int(0.05 / DT), endpoint=False))
        v.append(np.full(int(0.8 / DT), lv))
        prev = lv
    return np.concatenate(v)


@pytest.fixture(scope="module")
def core():
    rng = np.random.default_rng(3)
    v = _staircase(rng)
    return rng, np.arange(v.size) * DT, v, me.play_core(v, 100.0)


def test_a_vibration_through_the_holds_does_not_set_the_floor(core):
    rng, t, v, h = core
    span = np.ptp(h)
    sigma = 0.002 * span
    y = h + 0.03 * span * np.sin(2 * np.pi * 11.0 * t) + sigma * rng.standard_normal(t.size)
    rep = diagnose(t, v, y, progress=False)
    osc = rep.noise_info["holds_oscillate"]
    # half the vibration's period is 400 / 22 = 18.2 samples
    assert abs(osc["lag_samples"] - 18) <= 1 and osc["autocorrelation"] < OSCILLATING
    assert rep.noise_info["method"] == "high_frequency"
    # the floor is the sensor noise (the second difference of a 11 Hz sine at 400 Hz is 3 % of
    # its amplitude, 1e-3 of the span, half the noise: within 30 %), not the vibration's 2.1 %
    assert rep.noise_floor == pytest.approx(sigma, rel=0.3)
    assert rep.verdict == "unexplained" and "correlated_residual" in rep.remaining
    assert "oscillates while the input is held" in rep.remaining["correlated_residual"]


def test_low_pass_sensor_noise_still_sets_the_floor_from_the_holds(core):
    rng, t, v, h = core
    span = np.ptp(h)
    e = np.empty(t.size)
    w = rng.standard_normal(t.size)
    e[0] = w[0]
    for k in range(1, t.size):
        e[k] = 0.8 * e[k - 1] + w[k]
    e *= 0.004 * span / e.std()
    rep = diagnose(t, v, h + e, progress=False)
    assert "holds_oscillate" not in rep.noise_info and rep.noise_info["method"] == "holds"
    # the holds' scatter about a quadratic over half a hold (160 samples) is the noise's
    # standard deviation less what the quadratic takes (within 15 %)
    assert rep.noise_floor == pytest.approx(0.004 * span, rel=0.15)
    # and the pooled autocorrelation of AR(1) noise stays above 0 (0.8^k)
    seg = [e[k:k + 160] - e[k:k + 160].mean() for k in range(0, 9600, 320)]
    assert hold_oscillation(seg)[1] > -0.2

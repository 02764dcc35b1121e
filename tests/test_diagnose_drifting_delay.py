"""A dead time that drifts along the record (hystcomp.identify.parts.DriftingDelay, round 13):
a sensor recorded on its own clock, fast against the drive's by a frequency offset eps, sees
the input ever later, by eps samples a sample. HOLDOUT13's clock-skew record
(tests/realistic/cases_holdout13.py) had a fixed dead time at best until the part existed.
Here: the realistic generator's PI core (tests/realistic/mechanisms.py) driven by an analytic
input evaluated at the sensor's true instants (not by interpolating samples, as the part does).
"""

import numpy as np
import pytest

from hystcomp.diagnose import diagnose
from hystcomp.identify._part_kernels import drifting_delay, fractional_delay
from realistic import mechanisms as me


def test_kernel_is_the_fixed_delay_at_both_ends_and_interpolates_between():
    rng = np.random.default_rng(0)
    x = np.cumsum(rng.standard_normal(200))
    a, b, c = np.empty_like(x), np.empty_like(x), np.empty_like(x)
    drifting_delay(x, 2.5, 2.5, a)
    fractional_delay(x, 2.5, b)
    np.testing.assert_array_equal(a, b)                 # no drift: the fixed dead time
    drifting_delay(x, 1.0, 5.0, c)
    # at sample k the delay is 1 + 4 k / 199; on a linear input the output is k - d_k
    ramp = np.arange(200.0)
    drifting_delay(ramp, 1.0, 5.0, c)
    d = 1.0 + 4.0 * np.arange(200) / 199
    np.testing.assert_allclose(c[10:], (ramp - d)[10:], atol=1e-12)


def test_kernel_keeps_a_band_limited_input_s_shape():
    # a dead time delays without filtering: a sine at 0.02 ... 0.1 cycles a sample delayed by
    # a fraction of a sample matches the exactly delayed sine to within the cubic Lagrange
    # interpolator's error (its worst, half-way between samples: 1 - (9 cos(w/2) - cos(3w/2)) / 8,
    # 2.3e-4 at 0.05 cycles a sample; the bound allows 2x); linear interpolation would be off by
    # up to 1 - cos(w/2) (1.2e-2 at 0.05 cycles a sample)
    k = np.arange(3000.0)
    for cycles in (0.02, 0.05, 0.1):
        w = 2 * np.pi * cycles
        worst = 1.0 - (9 * np.cos(w / 2) - np.cos(3 * w / 2)) / 8
        for d in (0.5, 2.25, 7.8):
            out = np.empty_like(k)
            fractional_delay(np.sin(w * k), d, out)
            err = np.abs(out - np.sin(w * (k - d)))[20:-20].max()
            assert err <= 2 * worst + 1e-12, (cycles, d, err)
    # exact on cubic polynomials away from the start (x[0] is held before it)
    cube = (k / 100.0) ** 3
    out = np.empty_like(k)
    fractional_delay(cube, 3.3, out)
    np.testing.assert_allclose(out[10:], ((k[10:] - 3.3) / 100.0) ** 3, rtol=1e-12, atol=1e-12)


def _drive(t):
    # a sum of incommensurate sines, faded in, to +-45 V (an analytic input, read at any instant)
    fade = np.clip(t / 3.0, 0.0, 1.0)
    return fade * (28.0 * np.sin(2 * np.pi * 0.37 * t) + 17.0 * np.sin(2 * np.pi * 1.13 * t + 1.0))


@pytest.fixture(scope="module")
def record():
    rng = np.random.default_rng(3)
    dt, n = 1e-3, 30_000
    t = np.arange(n) * dt
    eps, latency = 2e-4, 1.0                               # 1 + 6 samples of delay at the end
    seen = t / (1 + eps) - latency * dt
    h = me.play_core(_drive(np.maximum(seen, 0.0)), 100.0)
    sigma = 0.002 * np.ptp(h)
    return t, _drive(t), h + sigma * rng.standard_normal(n), sigma, latency, latency + eps / (1 + eps) * (n - 1)


def test_clock_skew_named_delay_with_its_drift(record):
    t, v, y, sigma, d0, d1 = record
    rep = diagnose(t, v, y, progress=False)
    assert rep.effects == ["delay"]
    desc = next(p for p in rep.model.describe() if p["kind"] == "delay_drift")
    # the delay at both ends within 0.5 sample (the part interpolates between samples,
    # the record was read at the true instants)
    assert desc["delay_samples"] == pytest.approx(d0, abs=0.5)
    assert desc["delay_end_samples"] == pytest.approx(d1, abs=0.5)
    assert rep.rms_heldout <= 1.5 * sigma and rep.verdict == "explained"

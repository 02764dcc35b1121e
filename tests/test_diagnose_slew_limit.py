"""A slew-rate limit before the hysteresis (hystcomp.identify.parts.SlewLimit, round 13): a
current-limited piezo amplifier charges the stack at most at I_max / C, so the actuator's input
falls behind a fast command. HOLDOUT13's amplifier record (tests/realistic/cases_holdout13.py)
got nothing named until the part existed (unexplained at 2.6-28 noise floors, a viscous-play
rate part tentative); here a record of the realistic generator's own PI core
(tests/realistic/mechanisms.py, not hystcomp's plays) behind a slew limit written below from
its definition in continuous time, under sine bursts of hopping frequency.
"""

import numpy as np
import pytest

from hystcomp.diagnose import diagnose
from hystcomp.identify._part_kernels import slew_limit
from realistic import mechanisms as me


def _slewed(t, v, s):
    """The stack voltage of an amplifier that follows v at most at s V/s: between samples
    the command is held (zero-order hold) and the voltage runs towards it at full rate
    until it arrives, integrated in ten sub-steps a sample."""
    u = np.empty_like(v)
    u[0] = v[0]
    dt = (t[1] - t[0]) / 10
    cur = v[0]
    for k in range(1, v.size):
        for _ in range(10):
            cur += np.clip(v[k] - cur, -s * dt, s * dt)
        u[k] = cur
    return u


def test_kernel_moves_at_most_one_step_and_follows_slow_input():
    x = np.r_[np.zeros(5), np.ones(10), np.linspace(1.0, 0.9, 50)]
    out = np.empty_like(x)
    slew_limit(x, 0.25, out)
    assert np.all(np.abs(np.diff(out)) <= 0.25 + 1e-15)
    # a unit step: a ramp of 0.25 a sample, arriving after four samples exactly
    assert out[5:10].tolist() == [0.25, 0.5, 0.75, 1.0, 1.0]
    # a ramp slower than the limit is followed exactly once caught up
    np.testing.assert_array_equal(out[15:], x[15:])


@pytest.fixture(scope="module")
def record():
    rng = np.random.default_rng(11)
    dt = 1 / 800
    t = np.arange(int(30 / dt)) * dt
    # bursts of 3 s at hopping frequencies (0.3 ... 4 Hz), amplitude 45 V
    f = np.repeat(rng.permutation([0.3, 0.6, 1.0, 1.6, 2.5, 4.0, 0.45, 3.2, 0.8, 2.0]), int(3 / dt))[:t.size]
    v = 45.0 * np.sin(2 * np.pi * np.cumsum(f) * dt)
    s = 300.0                      # V/s: a 45 V sine is limited above 1.06 Hz
    h = me.play_core(_slewed(t, v, s), 100.0)
    sigma = 0.002 * np.ptp(h)
    return t, v, h + sigma * rng.standard_normal(t.size), sigma, s


def test_slew_limited_amplifier_named_and_explained(record):
    t, v, y, sigma, s = record
    rep = diagnose(t, v, y, progress=False)
    assert rep.effects == ["rate_dependence"]
    desc = next(p for p in rep.model.describe() if p["kind"] == "input_slew")
    # the fitted limit: within 3 % of the true one (the held command between samples
    # against the kernel's sample steps: 1/10 of a sample step at most, under 1 %)
    rate_max = np.max(np.abs(np.diff(v))) / (t[1] - t[0])
    assert desc["relative_slew_rate"] * rate_max == pytest.approx(s, rel=0.03)
    # within 1.5 true noise levels, the verdict "explained", and the model reproduces
    # the reported held-out RMS
    assert rep.rms_heldout <= 1.5 * sigma and rep.verdict == "explained"
    held = (t >= rep.validation[0]) & (t <= rep.validation[1])
    e = y - rep.model.simulate(v)
    assert np.sqrt(np.mean(e[held] ** 2)) == pytest.approx(rep.rms_heldout, rel=1e-9)

"""The HOLDOUT4 set: written after HOLDOUT3 was measured (2026-11-23, third round), never run
through the diagnosis. Use it once, for the final measurement of the next tuning round, and
write a new one after.

Mechanisms and signals that the other sets do not have, or not in these combinations: an
eddy-current term with two time constants (a laminated core with a skin depth), logarithmic
creep on a unipolar staircase with a noisy monitor, a stage that cools (a falling offset) under
random drive, a warming actuator's gain under random drive, a hard clip on a unipolar stroke,
a dead time of 1.5 samples under slow triangles, a positive preload before triangles, creep
together with a gain drift, a flag-shaped core under random drive, and a clean record sampled
at 20 Hz.
"""

import numpy as np

from . import excitations as ex
from . import mechanisms as me
from .record import case_set, finish

HOLDOUT4, case, _rng = case_set("holdout4_", 4000)


@case
def clean_slow_triangles(seed):
    rng = _rng(seed, 1)
    dt, n = 0.05, 6_000
    v = ex.triangles(dt, n, 0.01, 40.0, decay=0.6)
    y = me.play_core(v, 80.0, gain=rng.uniform(0.3, 3.0))
    return finish("holdout4_clean_slow_triangles", seed, np.arange(n) * dt, v, y, set(), "explained",
                  "a clean core sampled at 20 Hz under slow decaying triangles", rng, monitor_noise=3e-4)


@case
def rate_eddy_two_time_constants(seed):
    rng = _rng(seed, 2)
    dt = 5e-4
    v = np.concatenate([ex.triangles(dt, 7_000, f, 45.0, decay=0.5) for f in (0.4, 4.0, 15.0)])
    h = me.play_core(v, 100.0)
    k = rng.uniform(1.0, 1.5) * np.ptp(h) / np.ptp(v) * 1e-3
    y = h + k * (0.6 * me.low_passed_rate(v, dt, 1e-3) + 0.4 * me.low_passed_rate(v, dt, 6e-3))
    return finish("holdout4_rate_eddy_two_time_constants", seed, np.arange(len(v)) * dt, v, y,
                  {"rate_dependence"}, "either", "eddy-current term with two time constants, triangles", rng)


@case
def creep_log_unipolar_staircase(seed):
    rng = _rng(seed, 3)
    dt = 1e-3
    levels = np.concatenate([[0.0], rng.uniform(10, 90, 8)])
    v = ex.staircase_holds(dt, levels, 2.2, 0.05)
    h = me.play_core(v, 100.0)
    y = h + me.log_creep(h, dt, rng.uniform(0.03, 0.05))
    return finish("holdout4_creep_log_unipolar_staircase", seed, np.arange(len(v)) * dt, v, y, {"creep"},
                  "either", "logarithmic creep, unipolar staircase, noisy monitor", rng, monitor_noise=5e-4)


@case
def drift_cooling_random(seed):
    rng = _rng(seed, 4)
    dt, n = 1e-3, 22_000
    v = ex.bandlimited_random(dt, n, 2.5, 45.0, rng=rng)
    h = me.play_core(v, 100.0)
    t = np.arange(n) * dt
    y = h - rng.uniform(0.04, 0.07) * np.ptp(h) * (1 - np.exp(-t / rng.uniform(6.0, 12.0)))
    return finish("holdout4_drift_cooling_random", seed, t, v, y, {"drift"}, "either",
                  "a stage cooling down (falling offset) under band-limited random drive", rng)


@case
def gain_drift_warming_random(seed):
    rng = _rng(seed, 5)
    dt, n = 1e-3, 22_000
    v = ex.bandlimited_random(dt, n, 2.0, 45.0, rng=rng)
    t = np.arange(n) * dt
    y = me.play_core(v, 100.0) * me.thermal_gain(t, rng.uniform(0.05, 0.09), rng.uniform(8.0, 15.0))
    return finish("holdout4_gain_drift_warming_random", seed, t, v, y, {"gain_drift"}, "either",
                  "a warming actuator's gain under band-limited random drive", rng)


@case
def clip_unipolar(seed):
    rng = _rng(seed, 6)
    v = ex.unipolar_triangles(18_000, 7, 120.0, decay=0.3)
    h = me.play_core(v, 120.0)
    y = me.clip(h, -np.inf, rng.uniform(0.8, 0.88) * h.max())
    return finish("holdout4_clip_unipolar", seed, np.arange(len(v)) * 1e-3, v, y, {"output_saturation"},
                  "either", "a sensor range clipping the top of a unipolar stroke", rng)


@case
def delay_slow_triangles(seed):
    rng = _rng(seed, 7)
    dt = 2e-3
    v = np.concatenate([ex.triangles(dt, 5_000, f, 45.0, decay=0.5) for f in (0.5, 3.0)])
    y = me.play_core(me.fractional_delay(v, rng.uniform(1.3, 1.7)), 100.0)
    return finish("holdout4_delay_slow_triangles", seed, np.arange(len(v)) * dt, v, y, {"delay"},
                  "explained", "a dead time of about 1.5 samples under triangles", rng)


@case
def initial_state_positive_preload_triangles(seed):
    rng = _rng(seed, 8)
    top = rng.uniform(60, 80)
    pre = np.concatenate([np.linspace(0, top, 300), np.linspace(top, 10, 300)])
    _, z = me.play_core(pre, 100.0, return_state=True)
    v = ex.triangles(1e-3, 16_000, 1.0, 35.0, offset=0.0, decay=0.6)
    v = v + (pre[-1] - v[0]) * np.exp(-np.arange(len(v)) / 200.0)
    y = me.play_core(v, 100.0, state=z)
    return finish("holdout4_initial_state_positive_preload_triangles", seed, np.arange(len(v)) * 1e-3, v, y,
                  {"initial_state"}, "explained", "triangles after a positive excursion", rng)


@case
def pair_creep_gain_drift(seed):
    rng = _rng(seed, 9)
    dt = 1e-3
    levels = np.concatenate([[0.0], np.tile([40.0, -40.0], 5) * rng.uniform(0.5, 1.0, 10)])
    v = ex.staircase_holds(dt, levels, 2.0, 0.05)
    t = np.arange(len(v)) * dt
    h = me.play_core(v, 90.0)
    y = (h + me.kelvin_voigt_creep(h, dt, [0.04], [rng.uniform(0.4, 0.9)])) \
        * me.thermal_gain(t, rng.uniform(0.06, 0.1), rng.uniform(10.0, 20.0))
    return finish("holdout4_pair_creep_gain_drift", seed, t, v, y, {"creep", "gain_drift"}, "either",
                  "creep on a warming actuator, staircase with holds", rng, monitor_noise=4e-4)


@case
def oov_flag_random(seed):
    rng = _rng(seed, 10)
    dt, n = 1e-3, 18_000
    v = ex.bandlimited_random(dt, n, 2.0, 50.0, rng=rng)
    y = me.flag_core(v, 100.0, bias_fraction=rng.uniform(0.25, 0.4), r_fraction=0.1)
    return finish("holdout4_oov_flag_random", seed, np.arange(n) * dt, v, y, set(), "unexplained",
                  "a flag-shaped (superelastic) core under band-limited random drive", rng)

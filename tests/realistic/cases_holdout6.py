"""The HOLDOUT6 set: written after HOLDOUT5 was measured (2026-11-23, fifth round), never run
through the diagnosis. Use it once, for the final measurement of the next tuning round, and
write a new one after.

Mechanisms and signals that the other sets do not have, or not in these combinations: a clean
core under triangles around an offset sampled at 500 Hz, logarithmic creep after holds of
random lengths, a linear sensor drift with a slow wander under two-tone sines, a dead time
under a chirp, a Bouc-Wen stage under band-limited random drive, arctangent saturation of the
output under triangles, plays whose thresholds grow with the level under bipolar random drive,
a gain rising linearly in time under a staircase with holds, a dead time with arctangent
saturation, and a double (antiferroelectric-like) loop under decaying sines.
"""

import numpy as np

from . import excitations as ex
from . import mechanisms as me
from .record import case_set, finish

HOLDOUT6, case, _rng = case_set("holdout6_", 6000)


def _arctan_saturation(h, top):
    """Output saturating as 2/pi arctan: approaches its limit as 1/u, like the algebraic
    map with p = 1, but with another knee (arctan(x) = x - x^3/3 + ...)."""
    return top * (2.0 / np.pi) * np.arctan(0.5 * np.pi * h / top)


def _holds_of_random_lengths(dt, levels, rng, shortest=0.5, longest=3.0, ramp_s=0.05):
    """Holds at `levels`, each of a length drawn between `shortest` and `longest` seconds."""
    parts = [np.full(int(rng.uniform(shortest, longest) / dt), levels[0])]
    for a, b in zip(levels[:-1], levels[1:]):
        parts.append(np.linspace(a, b, max(int(ramp_s / dt), 2), endpoint=False))
        parts.append(np.full(int(rng.uniform(shortest, longest) / dt), b))
    return np.concatenate(parts)


@case
def clean_triangles_offset_500hz(seed):
    rng = _rng(seed, 1)
    dt, n = 2e-3, 9_000
    v = ex.triangles(dt, n, 0.6, 30.0, offset=50.0, decay=0.5)
    y = me.play_core(v - 50.0, 70.0, gain=rng.uniform(0.6, 1.6)) + rng.uniform(-5, 5)
    return finish("holdout6_clean_triangles_offset_500hz", seed, np.arange(n) * dt, v, y, set(), "explained",
                  "a clean core under triangles around 50 V, sampled at 500 Hz", rng, monitor_noise=2e-4)


@case
def creep_log_random_holds(seed):
    rng = _rng(seed, 2)
    dt = 1e-3
    levels = np.concatenate([[0.0], rng.uniform(-45, 45, 9)])
    v = _holds_of_random_lengths(dt, levels, rng)
    h = me.play_core(v, 100.0)
    y = h + me.log_creep(h, dt, rng.uniform(0.02, 0.035))
    return finish("holdout6_creep_log_random_holds", seed, np.arange(len(v)) * dt, v, y, {"creep"},
                  "either", "logarithmic creep after holds of random lengths (0.5 ... 3 s)", rng,
                  monitor_noise=4e-4)


@case
def drift_linear_wander(seed):
    rng = _rng(seed, 3)
    dt, n = 1e-3, 20_000
    t = np.arange(n) * dt
    v = ex.decaying_sines(dt, n, (0.7, 1.9), 45.0)
    h = me.play_core(v, 100.0)
    T = t[-1]
    drift = np.ptp(h) * (rng.uniform(0.02, 0.04) * rng.choice([-1.0, 1.0]) * t / T
                         + 0.01 * np.sin(2 * np.pi * t / rng.uniform(25.0, 40.0)))
    y = h + drift
    return finish("holdout6_drift_linear_wander", seed, t, v, y, {"drift"}, "either",
                  "a sensor drifting linearly with a slow wander, two-tone sines", rng)


@case
def delay_chirp(seed):
    rng = _rng(seed, 4)
    dt, n = 1e-3, 20_000
    v = ex.chirp(dt, n, 0.5, 12.0, 45.0)
    d = rng.uniform(1.5, 3.0)
    y = me.play_core(me.fractional_delay(v, d), 100.0)
    return finish("holdout6_delay_chirp", seed, np.arange(n) * dt, v, y, {"delay"}, "either",
                  f"dead time {d:.2f} samples under a chirp 0.5 ... 12 Hz", rng)


@case
def rate_bouc_wen_random(seed):
    rng = _rng(seed, 5)
    dt = 5e-4
    v = np.concatenate([ex.bandlimited_random(dt, 7_000, fc, 1.0, rng=rng) for fc in (1.0, 6.0, 15.0)])
    v = 45.0 * v / np.max(np.abs(v))
    y = me.bouc_wen_stage(v, dt, fn=rng.uniform(40.0, 60.0), zeta=rng.uniform(0.2, 0.35))
    return finish("holdout6_rate_bouc_wen_random", seed, np.arange(len(v)) * dt, v, y, {"rate_dependence"},
                  "either", "a Bouc-Wen stage under band-limited random drive of three bandwidths", rng)


@case
def saturation_arctan_triangles(seed):
    rng = _rng(seed, 6)
    dt, n = 1e-3, 18_000
    v = ex.triangles(dt, n, 0.8, 50.0, decay=0.5)
    h = me.play_core(v, 100.0)
    y = _arctan_saturation(h, rng.uniform(0.6, 0.8) * np.max(np.abs(h)))
    return finish("holdout6_saturation_arctan_triangles", seed, np.arange(n) * dt, v, y, {"saturation"},
                  "either", "output saturating as an arctangent, triangles", rng)


@case
def asymmetry_level_thresholds_random(seed):
    rng = _rng(seed, 7)
    dt, n = 1e-3, 18_000
    v = ex.bandlimited_random(dt, n, 1.5, 45.0, rng=rng)
    y = me.asymmetric_play_core(v, 100.0, skew=rng.choice([-1.0, 1.0]) * rng.uniform(0.5, 0.7))
    return finish("holdout6_asymmetry_level_thresholds_random", seed, np.arange(n) * dt, v, y, {"asymmetry"},
                  "either", "thresholds growing with the input level, bipolar random drive", rng)


@case
def gain_drift_linear_staircase(seed):
    rng = _rng(seed, 8)
    dt = 1e-3
    levels = np.concatenate([[0.0], np.tile([40.0, -40.0], 5) * rng.uniform(0.5, 1.0, 10)])
    v = ex.staircase_holds(dt, levels, 1.5, 0.3)
    t = np.arange(len(v)) * dt
    y = me.play_core(v, 100.0) * (1.0 + rng.uniform(0.05, 0.08) * t / t[-1])
    return finish("holdout6_gain_drift_linear_staircase", seed, t, v, y, {"gain_drift"}, "either",
                  "a gain rising linearly in time (no creep), staircase with holds", rng, monitor_noise=3e-4)


@case
def pair_delay_arctan(seed):
    rng = _rng(seed, 9)
    dt, n = 1e-3, 20_000
    v = ex.bandlimited_random(dt, n, 5.0, 50.0, rng=rng)
    h = me.play_core(me.fractional_delay(v, rng.uniform(2.0, 4.0)), 100.0)
    y = _arctan_saturation(h, rng.uniform(0.6, 0.75) * np.max(np.abs(h)))
    return finish("holdout6_pair_delay_arctan", seed, np.arange(n) * dt, v, y, {"delay", "saturation"},
                  "either", "a dead time and arctangent saturation, band-limited random drive", rng)


@case
def oov_double_loop(seed):
    rng = _rng(seed, 10)
    dt, n = 1e-3, 18_000
    v = ex.decaying_sines(dt, n, (0.5, 1.3), 50.0)
    # two flag cores of opposite bias: loops open near +-bias only, pinched at the origin and
    # at the extremes (an antiferroelectric's double loop); no PI core draws it
    y = me.flag_core(v, 100.0, bias_fraction=rng.uniform(0.5, 0.6), r_fraction=rng.uniform(0.08, 0.12))
    return finish("holdout6_oov_double_loop", seed, np.arange(n) * dt, v, y, set(), "unexplained",
                  "a double loop (flag-shaped, wider bias) under decaying two-tone sines", rng)

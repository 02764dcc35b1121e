"""The HOLDOUT5 set: written after HOLDOUT4 was measured (2026-11-23, fourth round), never run
through the diagnosis. Use it once, for the final measurement of the next tuning round, and
write a new one after.

Mechanisms and signals that the other sets do not have, or not in these combinations: a
fixture that slips once (a step in the offset), a gain that follows a slow thermal cycle,
Langevin saturation of a bipolar drive, a clip at both ends under random drive, an asymmetric
loop under a unipolar staircase, a preload below the stroke before random drive, an eddy
current on a stage that cools, a viscoplastic core under a chirp, two Kelvin-Voigt elements
sampled at 2 kHz under a bipolar staircase, a butterfly under random drive and a clean record
sampled at 200 Hz.
"""

import numpy as np

from . import excitations as ex
from . import mechanisms as me
from .record import case_set, finish

HOLDOUT5, case, _rng = case_set("holdout5_", 5000)


@case
def clean_random_200hz(seed):
    rng = _rng(seed, 1)
    dt, n = 5e-3, 8_000
    v = ex.bandlimited_random(dt, n, 1.5, 40.0, rng=rng)
    y = me.play_core(v, 80.0, gain=rng.uniform(0.5, 2.0))
    return finish("holdout5_clean_random_200hz", seed, np.arange(n) * dt, v, y, set(), "explained",
                  "a clean core sampled at 200 Hz under band-limited random drive", rng, monitor_noise=3e-4)


@case
def drift_slip_step(seed):
    rng = _rng(seed, 2)
    dt, n = 1e-3, 22_000
    t = np.arange(n) * dt
    v = ex.decaying_sines(dt, n, (0.8, 1.7), 45.0)
    h = me.play_core(v, 100.0)
    t_slip = rng.uniform(5.0, 11.0)
    step = rng.choice([-1.0, 1.0]) * rng.uniform(0.03, 0.05) * np.ptp(h)
    y = h + step * 0.5 * (1 + np.tanh((t - t_slip) / 0.05))
    return finish("holdout5_drift_slip_step", seed, t, v, y, {"drift"}, "either",
                  "a fixture that slips once (a step in the offset) during the record", rng)


@case
def gain_drift_thermal_cycle(seed):
    rng = _rng(seed, 3)
    dt, n = 1e-3, 22_000
    t = np.arange(n) * dt
    v = ex.triangles(dt, n, 1.2, 45.0, decay=0.4)
    gain = 1.0 + rng.uniform(0.04, 0.07) * np.sin(2 * np.pi * t / rng.uniform(40.0, 60.0) + rng.uniform(0, 1))
    y = me.play_core(v, 100.0) * gain
    return finish("holdout5_gain_drift_thermal_cycle", seed, t, v, y, {"gain_drift"}, "either",
                  "a gain following a slow thermal cycle, triangles", rng)


@case
def saturation_langevin_bipolar(seed):
    rng = _rng(seed, 4)
    dt, n = 1e-3, 20_000
    v = ex.decaying_sines(dt, n, (0.5, 1.1), 50.0)
    h = me.play_core(v, 100.0)
    top = rng.uniform(0.5, 0.8) * np.max(np.abs(h))
    y = top * me.langevin(3.0 * h / top)
    return finish("holdout5_saturation_langevin_bipolar", seed, np.arange(n) * dt, v, y, {"saturation"},
                  "either", "a magnetisation saturating as a Langevin function, bipolar sines", rng)


@case
def clip_both_ends_random(seed):
    rng = _rng(seed, 5)
    dt, n = 1e-3, 18_000
    v = ex.bandlimited_random(dt, n, 2.0, 50.0, rng=rng)
    h = me.play_core(v, 100.0)
    y = me.clip(h, rng.uniform(0.82, 0.9) * h.min(), rng.uniform(0.82, 0.9) * h.max())
    return finish("holdout5_clip_both_ends_random", seed, np.arange(n) * dt, v, y, {"output_saturation"},
                  "either", "a sensor range clipping both ends under band-limited random drive", rng)


@case
def asymmetry_unipolar_staircase(seed):
    rng = _rng(seed, 6)
    dt = 1e-3
    levels = np.concatenate([[0.0], rng.uniform(5, 95, 9)])
    v = ex.staircase_holds(dt, levels, 1.0, 0.4)
    # thresholds r (1 + skew v/50) grow along the stroke 0 ... 100 (from the virgin state at 0)
    y = me.asymmetric_play_core(v, 100.0, rng.uniform(0.25, 0.35))
    return finish("holdout5_asymmetry_unipolar_staircase", seed, np.arange(len(v)) * dt, v, y,
                  {"asymmetry"}, "either", "a loop wider at one end, unipolar staircase with short holds", rng)


@case
def initial_state_preload_below_random(seed):
    rng = _rng(seed, 7)
    low = -rng.uniform(55, 75)
    pre = np.concatenate([np.linspace(0, low, 300), np.linspace(low, -5, 300)])
    _, z = me.play_core(pre, 100.0, return_state=True)
    dt, n = 1e-3, 16_000
    v = ex.bandlimited_random(dt, n, 2.0, 35.0, rng=rng)
    v = v + (pre[-1] - v[0]) * np.exp(-np.arange(n) / 150.0)
    y = me.play_core(v, 100.0, state=z)
    return finish("holdout5_initial_state_preload_below_random", seed, np.arange(n) * dt, v, y,
                  {"initial_state"}, "explained", "random drive after a negative excursion", rng)


@case
def pair_eddy_cooling(seed):
    rng = _rng(seed, 8)
    dt = 5e-4
    v = np.concatenate([ex.triangles(dt, 8_000, f, 45.0, decay=0.5) for f in (0.5, 5.0, 12.0)])
    t = np.arange(len(v)) * dt
    h = me.play_core(v, 100.0)
    k = rng.uniform(1.0, 1.5) * np.ptp(h) / np.ptp(v) * 1e-3
    y = h + k * me.low_passed_rate(v, dt, 2e-3) - rng.uniform(0.04, 0.06) * np.ptp(h) * (1 - np.exp(-t / 4.0))
    return finish("holdout5_pair_eddy_cooling", seed, t, v, y, {"rate_dependence", "drift"}, "either",
                  "an eddy-current term on a stage that cools, triangles at three rates", rng)


@case
def rate_viscoplastic_chirp(seed):
    rng = _rng(seed, 9)
    dt, n = 5e-4, 30_000
    v = ex.chirp(dt, n, 0.3, 15.0, 45.0)
    y = me.viscoplastic_core(v, dt, 100.0, rng.uniform(2e-3, 4e-3))
    return finish("holdout5_rate_viscoplastic_chirp", seed, np.arange(n) * dt, v, y, {"rate_dependence"},
                  "either", "viscoplastic plays under a chirp 0.3 ... 15 Hz", rng)


@case
def creep_two_elements_2khz(seed):
    rng = _rng(seed, 10)
    dt = 5e-4
    levels = np.concatenate([[0.0], np.tile([35.0, -35.0], 4) * rng.uniform(0.5, 1.0, 8)])
    v = ex.staircase_holds(dt, levels, 1.5, 0.05)
    h = me.play_core(v, 80.0)
    y = h + me.kelvin_voigt_creep(h, dt, [0.03, 0.03], [rng.uniform(0.05, 0.1), rng.uniform(0.5, 1.0)])
    return finish("holdout5_creep_two_elements_2khz", seed, np.arange(len(v)) * dt, v, y, {"creep"},
                  "either", "two Kelvin-Voigt elements, bipolar staircase sampled at 2 kHz", rng,
                  monitor_noise=3e-4)


@case
def oov_butterfly_random(seed):
    rng = _rng(seed, 11)
    dt, n = 1e-3, 18_000
    v = ex.bandlimited_random(dt, n, 2.0, 50.0, rng=rng)
    p = me.play_core(v, 100.0)
    y = me.butterfly(p, rng.uniform(0.8, 1.2) / np.abs(p).max())
    return finish("holdout5_oov_butterfly_random", seed, np.arange(n) * dt, v, y, set(), "unexplained",
                  "a butterfly (strain of a ferroelectric) under band-limited random drive", rng)

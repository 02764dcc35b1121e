"""The HOLDOUT set: never used to tune the diagnosis.

Different parameter draws, and mechanisms and signals that the tuning set does not have:
band-limited random excitation, flag-shaped (shape-memory) hysteresis, logarithmic creep on
a unipolar staircase, Bouc-Wen stage under triangles, creep with drift, gain drift with
asymmetry, a symmetric-density Preisach core at saturation.
"""

import numpy as np

from . import excitations as ex
from . import mechanisms as me
from .record import case_set, finish

HOLDOUT, case, _rng = case_set("holdout_", 1000)


@case
def clean_random(seed):
    rng = _rng(seed, 1)
    dt, n = 1e-3, 20_000
    v = ex.bandlimited_random(dt, n, 2.0, 45.0, rng=rng)
    y = me.play_core(v, 90.0, gain=rng.uniform(0.3, 3.0))
    return finish("holdout_clean_random", seed, np.arange(n) * dt, v, y, set(), "explained",
                  "band-limited random drive", rng)


@case
def clean_quasi_static_unipolar(seed):
    rng = _rng(seed, 2)
    v = ex.unipolar_triangles(9_000, 9, 100.0, decay=0.7)
    y = me.play_core(v, 100.0)
    return finish("holdout_clean_quasi_static_unipolar", seed, None, v, y, set(), "explained",
                  "unipolar point sequence, no time axis", rng)


@case
def clean_half_second_sampling(seed):
    rng = _rng(seed, 3)
    dt, n = 0.5, 8_000
    v = ex.decaying_sines(dt, n, (1 / 150, 1 / 60), 30.0)
    y = me.play_core(v, 60.0)
    return finish("holdout_clean_half_second_sampling", seed, np.arange(n) * dt, v, y, set(),
                  "explained", "0.5 s sampling", rng, monitor_noise=5e-4)


@case
def creep_log_unipolar(seed):
    rng = _rng(seed, 4)
    levels = np.concatenate([[0.0], rng.uniform(10, 100, 9)])
    v = ex.staircase_holds(1e-3, levels, 2.0, 0.05)
    y = me.play_core(v, 100.0) + me.log_creep(v, 1e-3, rng.uniform(0.025, 0.04))
    return finish("holdout_creep_log_unipolar", seed, np.arange(len(v)) * 1e-3, v, y, {"creep"},
                  "explained", "unipolar staircase with logarithmic creep", rng, monitor_noise=5e-4)


@case
def oov_flag(seed):
    rng = _rng(seed, 5)
    v = ex.decaying_sines(1e-3, 16_000, (0.5, 1.0), 50.0)
    y = me.flag_core(v, 100.0, bias_fraction=rng.uniform(0.3, 0.4))
    return finish("holdout_oov_flag", seed, np.arange(len(v)) * 1e-3, v, y, set(), "unexplained",
                  "flag-shaped (superelastic) loops", rng)


@case
def clipping_triangles(seed):
    rng = _rng(seed, 6)
    v = ex.triangles(1e-3, 16_000, 0.7, 50.0, decay=0.5)
    h = me.play_core(v, 100.0)
    c = rng.uniform(0.7, 0.8) * np.abs(h).max()
    y = me.clip(h, -np.inf, c)                      # clips one side only
    return finish("holdout_clipping_triangles", seed, np.arange(len(v)) * 1e-3, v, y,
                  {"output_saturation"}, "either", "one-sided sensor clipping", rng)


@case
def asymmetry_preisach_strong(seed):
    rng = _rng(seed, 7)
    v = ex.bandlimited_random(1e-3, 12_000, 1.5, 55.0, rng=rng)
    y = me.preisach_core(v, -56, 56, interaction=rng.uniform(0.2, 0.28))
    return finish("holdout_asymmetry_preisach_strong", seed, np.arange(len(v)) * 1e-3, v, y,
                  {"asymmetry"}, "either", "Preisach plane, strongly shifted interaction field", rng)


@case
def initial_state_unipolar(seed):
    rng = _rng(seed, 8)
    pre = np.concatenate([np.linspace(0, 100, 300), np.linspace(100, rng.uniform(20, 40), 300)])
    _, z = me.play_core(pre, 100.0, return_state=True)
    v = ex.triangles(1e-3, 16_000, 0.6, 45.0, offset=pre[-1], decay=0.5)
    v = np.clip(v, 0, 100)
    y = me.play_core(v, 100.0, state=z)
    return finish("holdout_initial_state_unipolar", seed, np.arange(len(v)) * 1e-3, v, y,
                  {"initial_state"}, "explained", "unipolar drive, record starts after a preload",
                  rng, monitor_noise=5e-4)


@case
def delay_fast_sampling(seed):
    rng = _rng(seed, 9)
    dt = 2e-4
    v = ex.decaying_sines(dt, 20_000, (5.0, 15.0), 50.0)
    d = rng.uniform(1.4, 2.4)
    y = me.play_core(me.fractional_delay(v, d), 100.0)
    return finish("holdout_delay_fast_sampling", seed, np.arange(len(v)) * dt, v, y, {"delay"},
                  "explained", f"dead time {d:.2f} samples at 5 kHz", rng)


@case
def pair_creep_drift(seed):
    rng = _rng(seed, 10)
    levels = np.concatenate([[0.0], np.tile([40.0, -40.0], 5) * rng.uniform(0.6, 1.0, 10)])
    v = ex.staircase_holds(1e-3, levels, 2.0, 0.05)
    t = np.arange(len(v)) * 1e-3
    h = me.play_core(v, 100.0)
    y = h + me.kelvin_voigt_creep(h, 1e-3, [0.03, 0.03], [0.4, 2.5]) + me.thermal_offset(t, 0.04 * np.ptp(h), 10.0)
    return finish("holdout_pair_creep_drift", seed, t, v, y, {"creep", "drift"}, "either",
                  "creep on a warming stage", rng, monitor_noise=5e-4)


@case
def rate_bouc_wen_triangles(seed):
    rng = _rng(seed, 11)
    dt = 5e-4
    v = np.concatenate([ex.triangles(dt, 8_000, f, 50.0, decay=0.5) for f in (1.0, 10.0, 30.0)])
    y = me.bouc_wen_stage(v, dt, fn=rng.uniform(70, 90), zeta=0.25)
    return finish("holdout_rate_bouc_wen_triangles", seed, np.arange(len(v)) * dt, v, y,
                  {"rate_dependence"}, "either", "Bouc-Wen stage under triangles", rng)


@case
def pair_gain_drift_asymmetry(seed):
    rng = _rng(seed, 12)
    v = ex.decaying_sines(1e-3, 20_000, (0.5, 1.0), 48.0)
    t = np.arange(len(v)) * 1e-3
    y = me.asymmetric_play_core(v, 100.0, skew=0.7) * me.thermal_gain(t, 0.08, 5.0)
    return finish("holdout_pair_gain_drift_asymmetry", seed, t, v, y, {"gain_drift", "asymmetry"},
                  "either", "asymmetric core whose gain rises as it warms", rng)

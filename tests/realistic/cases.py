"""The TUNING set: cases on which the diagnosis may be tuned (see ``cases_holdout.py``).

Each case draws its magnitudes from the seed, so seeds differ in more than the noise.
Output sensor noise is 0.2 % of the output span unless said otherwise.
"""

import numpy as np

from . import excitations as ex
from . import mechanisms as me
from .record import case_set, finish

TUNING, case, _rng = case_set("", 0)


def _sines(rng, dt=1e-3, n=20_000, freqs=(1.0,), span=100.0, offset=0.0):
    return ex.decaying_sines(dt, n, freqs, span / 2 * rng.uniform(0.85, 1.0), offset)


def _stairs(rng, amp=50.0, n_levels=10, hold_s=2.0, ramp_s=0.05):
    """Alternating positive and negative levels of random size, each held hold_s seconds."""
    signs = np.where(np.arange(n_levels) % 2 == 0, 1.0, -1.0)
    levels = np.concatenate([[0.0], signs * rng.uniform(0.3, 1.0, n_levels) * amp])
    return ex.staircase_holds(1e-3, levels, hold_s, ramp_s)


# ---- clean records: no effect, explained ----

@case
def clean_play_sines(seed):
    rng = _rng(seed, 1)
    v = _sines(rng, freqs=(0.5, 1.0))
    y = me.play_core(v, 100.0, gain=rng.uniform(0.5, 2.0))
    return finish("clean_play_sines", seed, np.arange(len(v)) * 1e-3, v, y, set(), "explained",
                  "continuous-density play core, 200 plays", rng)


@case
def clean_unipolar_triangles(seed):
    rng = _rng(seed, 2)
    n, dt = 16_000, 1e-3
    v = ex.unipolar_triangles(n, 12, 100.0, decay=0.6)             # 0 ... 100 V
    y = me.play_core(v, 100.0, gain=0.15)
    return finish("clean_unipolar_triangles", seed, np.arange(n) * dt, v, y, set(), "explained",
                  "unipolar 0-100 V drive, rate-independent core", rng)


@case
def clean_staircase_noisy_monitor(seed):
    rng = _rng(seed, 3)
    v = _stairs(rng)
    y = me.play_core(v, 100.0)
    return finish("clean_staircase_noisy_monitor", seed, np.arange(len(v)) * 1e-3, v, y, set(),
                  "explained", "holds without creep; monitor noise 0.05 % of span", rng,
                  monitor_noise=5e-4)


@case
def clean_quasi_static(seed):
    rng = _rng(seed, 4)
    v = ex.quasi_static_loops(8_000, [1.0, 0.7, 0.45, 0.25, 1.0, 0.6])
    v = v * rng.uniform(80, 120)
    y = me.play_core(v, np.ptp(v))
    return finish("clean_quasi_static", seed, None, v, y, set(), "explained",
                  "point sequence without time axis", rng)


@case
def clean_slow_sampling(seed):
    rng = _rng(seed, 5)
    dt, n = 1.0, 6_000
    v = ex.triangles(dt, n, 1 / 200.0, 40.0, decay=0.7) + ex.triangles(dt, n, 1 / 37.0, 8.0, decay=0.0)
    y = me.play_core(v, np.ptp(v))
    return finish("clean_slow_sampling", seed, np.arange(n) * dt, v, y, set(), "explained",
                  "sampling step 1 s", rng)


# ---- one effect ----

@case
def creep_kelvin_voigt(seed):
    rng = _rng(seed, 10)
    v = _stairs(rng)
    h = me.play_core(v, 100.0)
    c = rng.uniform(0.03, 0.06) * np.array([0.5, 0.3, 0.2])
    y = h + me.kelvin_voigt_creep(h, 1e-3, c, [0.15, 0.8, 3.0])
    return finish("creep_kelvin_voigt", seed, np.arange(len(v)) * 1e-3, v, y, {"creep"}, "explained",
                  "3 Kelvin-Voigt elements driven by the hysteretic strain", rng, monitor_noise=5e-4)


@case
def creep_logarithmic(seed):
    rng = _rng(seed, 11)
    v = _stairs(rng)
    y = me.play_core(v, 100.0) + me.log_creep(v, 1e-3, rng.uniform(0.02, 0.035))
    return finish("creep_logarithmic", seed, np.arange(len(v)) * 1e-3, v, y, {"creep"}, "explained",
                  "log10 creep law after every step (Jung & Gweon)", rng)


@case
def rate_viscoplastic(seed):
    rng = _rng(seed, 12)
    dt = 5e-4
    v = _sines(rng, dt=dt, n=24_000, freqs=(1.0, 6.0, 20.0))
    y = me.viscoplastic_core(v, dt, 100.0, eta=rng.uniform(4e-4, 8e-4))
    return finish("rate_viscoplastic", seed, np.arange(len(v)) * dt, v, y, {"rate_dependence"},
                  "either", "overstress plays: internal variable moves at a finite rate", rng)


@case
def rate_bouc_wen_stage(seed):
    rng = _rng(seed, 13)
    dt = 5e-4
    v = _sines(rng, dt=dt, n=24_000, freqs=(1.0, 8.0, 25.0))
    y = me.bouc_wen_stage(v, dt, fn=rng.uniform(50, 70), zeta=0.3)
    return finish("rate_bouc_wen_stage", seed, np.arange(len(v)) * dt, v, y, {"rate_dependence"},
                  "either", "Bouc-Wen hysteresis driving a 2nd-order stage", rng)


@case
def asymmetry_thresholds(seed):
    rng = _rng(seed, 14)
    v = _sines(rng, freqs=(0.5, 1.0))
    y = me.asymmetric_play_core(v, 100.0, skew=rng.uniform(0.6, 0.8))
    return finish("asymmetry_thresholds", seed, np.arange(len(v)) * 1e-3, v, y, {"asymmetry"},
                  "either", "thresholds grow with the input level: loop width differs top to bottom", rng)


@case
def asymmetry_preisach(seed):
    rng = _rng(seed, 15)
    v = _sines(rng, n=12_000, freqs=(0.5, 1.0))
    y = me.preisach_core(v, -55, 55, interaction=rng.uniform(0.12, 0.2))
    # relabelled from {"asymmetry"} after the first evaluations: measured on a
    # -50..50 V loop, this density's branches flatten towards both extremes
    # (secant slope 2.0-2.3 mid-branch against 0.2-0.4 at the far end even without
    # the shifted field), so the mechanism saturates as well as being asymmetric
    return finish("asymmetry_preisach", seed, np.arange(len(v)) * 1e-3, v, y, {"asymmetry", "saturation"},
                  "either", "Preisach plane (Gaussian density) with a shifted interaction field (not PI): "
                  "asymmetric and saturating", rng)


@case
def saturation_tanh_output(seed):
    rng = _rng(seed, 16)
    v = _sines(rng, freqs=(0.5, 1.0))
    h = me.play_core(v, 100.0)
    a = rng.uniform(1.6, 2.2)
    y = np.tanh(a * h / np.abs(h).max())
    return finish("saturation_tanh_output", seed, np.arange(len(v)) * 1e-3, v, y, {"saturation"},
                  "explained", "magnetisation-like smooth saturation of the core's output", rng)


@case
def saturation_clipping(seed):
    rng = _rng(seed, 17)
    v = _sines(rng, freqs=(0.5, 1.0))
    h = me.play_core(v, 100.0)
    c = rng.uniform(0.75, 0.85) * np.abs(h).max()
    y = me.clip(h, -c, c)
    return finish("saturation_clipping", seed, np.arange(len(v)) * 1e-3, v, y, {"output_saturation"},
                  "either", "sensor range clips the top of the loop", rng)


@case
def saturation_quasi_static_bh(seed):
    rng = _rng(seed, 18)
    v = ex.quasi_static_loops(8_000, [1.0, 0.8, 0.5, 1.0, 0.3, 0.9]) * 3000.0    # H in A/m
    h = me.play_core(v, 6000.0)
    y = 1.4 * np.tanh(rng.uniform(2.0, 2.6) * h / np.abs(h).max())               # B in T
    return finish("saturation_quasi_static_bh", seed, None, v, y, {"saturation"}, "explained",
                  "B-H-like loops without a time axis", rng)


@case
def drift_thermal_offset(seed):
    rng = _rng(seed, 19)
    v = _sines(rng, freqs=(0.5, 1.0))
    t = np.arange(len(v)) * 1e-3
    h = me.play_core(v, 100.0)
    y = h + me.thermal_offset(t, rng.uniform(0.03, 0.05) * np.ptp(h), tau=8.0)
    return finish("drift_thermal_offset", seed, t, v, y, {"drift"}, "either",
                  "warming stage: exponential offset plus a slow ripple", rng)


@case
def drift_thermal_gain(seed):
    rng = _rng(seed, 20)
    v = _sines(rng, freqs=(0.5, 1.0))
    t = np.arange(len(v)) * 1e-3
    y = me.play_core(v, 100.0) * me.thermal_gain(t, rng.uniform(0.06, 0.1), tau=6.0)
    return finish("drift_thermal_gain", seed, t, v, y, {"gain_drift"}, "either",
                  "actuator gain rises as it warms", rng)


@case
def delay_fractional(seed):
    rng = _rng(seed, 21)
    v = _sines(rng, freqs=(1.0, 4.0))
    d = rng.uniform(2.2, 4.6)
    y = me.play_core(me.fractional_delay(v, d), 100.0)
    rec = finish("delay_fractional", seed, np.arange(len(v)) * 1e-3, v, y, {"delay"}, "explained",
                 f"dead time {d:.2f} samples", rng)
    rec.extra["delay_samples"] = d
    return rec


@case
def initial_state_preload(seed):
    rng = _rng(seed, 22)
    pre = np.concatenate([np.linspace(0, 48, 400), np.linspace(48, -rng.uniform(20, 35), 400),
                          np.linspace(-30, 0, 300)])
    _, z = me.play_core(pre, 100.0, return_state=True)
    v = _sines(rng, freqs=(0.5, 1.0))
    v[:300] *= np.linspace(0, 1, 300) ** 2      # the record starts gently from 0
    y = me.play_core(v, 100.0, state=z)
    return finish("initial_state_preload", seed, np.arange(len(v)) * 1e-3, v, y, {"initial_state"},
                  "explained", "the actuator was driven before the record began", rng)


# ---- two effects ----

@case
def pair_asymmetry_creep(seed):
    rng = _rng(seed, 30)
    v = _stairs(rng)
    h = me.asymmetric_play_core(v, 100.0, skew=0.7)
    y = h + me.kelvin_voigt_creep(h, 1e-3, np.array([0.025, 0.02]), [0.3, 2.0])
    return finish("pair_asymmetry_creep", seed, np.arange(len(v)) * 1e-3, v, y, {"asymmetry", "creep"},
                  "either", "asymmetric core with Kelvin-Voigt creep", rng, monitor_noise=5e-4)


@case
def pair_saturation_drift(seed):
    rng = _rng(seed, 31)
    v = _sines(rng, freqs=(0.5, 1.0))
    t = np.arange(len(v)) * 1e-3
    h = me.play_core(v, 100.0)
    y = np.tanh(2.0 * h / np.abs(h).max()) + 0.06 * (1 - np.exp(-t / 6.0))
    return finish("pair_saturation_drift", seed, t, v, y, {"saturation", "drift"}, "either",
                  "saturating output on a warming stage", rng)


@case
def pair_delay_asymmetry(seed):
    rng = _rng(seed, 32)
    v = _sines(rng, freqs=(1.0, 4.0))
    y = me.asymmetric_play_core(me.fractional_delay(v, 3.3), 100.0, skew=0.7)
    return finish("pair_delay_asymmetry", seed, np.arange(len(v)) * 1e-3, v, y, {"delay", "asymmetry"},
                  "either", "dead time before an asymmetric core", rng)


# ---- out of vocabulary: unexplained, nothing named ----

@case
def oov_butterfly(seed):
    rng = _rng(seed, 40)
    v = _sines(rng, freqs=(0.5, 1.0))
    p = me.play_core(v, 100.0)
    y = me.butterfly(p, 1.0 / np.abs(p).max())
    return finish("oov_butterfly", seed, np.arange(len(v)) * 1e-3, v, y, set(), "unexplained",
                  "strain ~ polarisation squared: non-monotone, no PI-type model", rng)

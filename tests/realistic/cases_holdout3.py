"""The HOLDOUT3 set: written after HOLDOUT2 was measured (2026-11-23) and run once, for the
third round's final measurement (docs/diagnose.md); part of ``ALL`` since.

Mechanisms and signals that the other sets do not have: a clockwise loop (an output that
falls behind the input the other way round, which no PI with non-negative weights draws), a
periodic thermal offset (an air-conditioning cycle), a gain that declines linearly (ageing
or depolarisation), a soft clip ``h / (1 + |h/c|^4)^(1/4)``, three Kelvin-Voigt elements
under a record that holds in one half and oscillates in the other, an eddy-current term
proportional to the filtered input rate, a dead time with an output saturation, a small
positive preload under a noisy monitor, asymmetry with a warming stage, and a unipolar
random drive.
"""

import numpy as np

from . import excitations as ex
from . import mechanisms as me
from .record import case_set, finish

HOLDOUT3, case, _rng = case_set("holdout3_", 3000)


def eddy_current(v, dt, coefficient, tau):
    """A rate term ``coefficient * dv/dt`` through a first-order low-pass of time constant tau
    (the classical eddy-current field of a laminated core, Bertotti 1998, ch. 12)."""
    return coefficient * me.low_passed_rate(v, dt, tau)


@case
def clean_unipolar_random(seed):
    rng = _rng(seed, 1)
    dt, n = 1e-3, 16_000
    v = ex.bandlimited_random(dt, n, 1.5, 40.0, offset=50.0, rng=rng)
    y = me.play_core(v, 100.0, gain=rng.uniform(0.5, 2.0))
    return finish("holdout3_clean_unipolar_random", seed, np.arange(n) * dt, v, y, set(), "explained",
                  "unipolar band-limited random drive, noisy monitor", rng, monitor_noise=4e-4)


@case
def oov_clockwise(seed):
    rng = _rng(seed, 2)
    dt, n = 1e-3, 16_000
    v = ex.decaying_sines(dt, n, (0.5, 1.1), 45.0)
    h = me.play_core(v, 100.0)
    # rises with the input, but the loop runs clockwise: a v - h with a above h's slope
    a = rng.uniform(1.6, 2.0) * np.ptp(h) / np.ptp(v)
    y = a * v - h
    return finish("holdout3_oov_clockwise", seed, np.arange(n) * dt, v, y, set(), "unexplained",
                  "a loop traversed clockwise", rng)


@case
def drift_periodic_thermal(seed):
    rng = _rng(seed, 3)
    dt, n = 1e-3, 24_000
    v = ex.decaying_sines(dt, n, (0.6, 1.3), 45.0)
    t = np.arange(n) * dt
    h = me.play_core(v, 100.0)
    y = h + rng.uniform(0.02, 0.04) * np.ptp(h) * np.sin(2 * np.pi * t / rng.uniform(25, 35) + rng.uniform(0, 6))
    return finish("holdout3_drift_periodic_thermal", seed, t, v, y, {"drift"}, "either",
                  "offset following an air-conditioning cycle", rng)


@case
def gain_drift_ageing(seed):
    rng = _rng(seed, 4)
    dt, n = 1e-3, 24_000
    v = ex.decaying_sines(dt, n, (0.7, 1.5), 45.0)
    t = np.arange(n) * dt
    y = me.play_core(v, 100.0) * (1.0 - rng.uniform(0.05, 0.08) * t / t[-1])
    return finish("holdout3_gain_drift_ageing", seed, t, v, y, {"gain_drift"}, "either",
                  "gain declining linearly (ageing, depolarisation)", rng)


@case
def saturation_soft_clip(seed):
    rng = _rng(seed, 5)
    dt, n = 1e-3, 16_000
    v = ex.decaying_sines(dt, n, (0.5, 1.0), 50.0)
    h = me.play_core(v, 100.0)
    c = rng.uniform(0.55, 0.75) * np.abs(h).max()
    y = h / (1 + np.abs(h / c) ** 4) ** 0.25
    return finish("holdout3_saturation_soft_clip", seed, np.arange(n) * dt, v, y, {"saturation"}, "either",
                  "soft clip h / (1 + |h/c|^4)^(1/4)", rng)


@case
def creep_holds_then_sines(seed):
    rng = _rng(seed, 6)
    dt = 1e-3
    stairs = ex.staircase_holds(dt, np.concatenate([[0.0], rng.uniform(-45, 45, 6)]), 1.8, 0.04)
    sines = ex.decaying_sines(dt, 8_000, (1.0, 3.0), 40.0)
    v = np.concatenate([stairs, sines])
    h = me.play_core(v, 100.0)
    y = h + me.kelvin_voigt_creep(h, dt, [0.015, 0.02, 0.02], [0.1, 0.7, 4.0])
    return finish("holdout3_creep_holds_then_sines", seed, np.arange(len(v)) * dt, v, y, {"creep"}, "either",
                  "three Kelvin-Voigt elements; holds, then sines", rng, monitor_noise=3e-4)


@case
def rate_eddy_current(seed):
    rng = _rng(seed, 7)
    dt = 5e-4
    v = np.concatenate([ex.decaying_sines(dt, 8_000, (f, 1.7 * f), 45.0) for f in (0.5, 5.0, 20.0)])
    h = me.play_core(v, 100.0)
    y = h + eddy_current(v, dt, rng.uniform(0.8, 1.2) * np.ptp(h) / np.ptp(v) * 2e-3, 2e-3)
    return finish("holdout3_rate_eddy_current", seed, np.arange(len(v)) * dt, v, y, {"rate_dependence"},
                  "either", "an eddy-current term: filtered input rate added to the plays", rng)


@case
def pair_delay_saturation(seed):
    rng = _rng(seed, 8)
    dt, n = 5e-4, 20_000
    v = ex.decaying_sines(dt, n, (2.0, 7.0), 50.0)
    h = me.play_core(me.fractional_delay(v, rng.uniform(3.0, 5.0)), 100.0)
    y = np.tanh(rng.uniform(1.5, 2.0) * h / np.abs(h).max())
    return finish("holdout3_pair_delay_saturation", seed, np.arange(n) * dt, v, y, {"delay", "saturation"},
                  "either", "dead time before a core whose output saturates", rng)


@case
def initial_state_small_preload(seed):
    rng = _rng(seed, 9)
    top = rng.uniform(55, 70)
    pre = np.concatenate([np.linspace(0, top, 300), np.linspace(top, 15.0, 300)])
    _, z = me.play_core(pre, 100.0, return_state=True)
    v = ex.decaying_sines(1e-3, 16_000, (0.6, 1.2), 45.0, offset=15.0)
    y = me.play_core(v, 100.0, state=z)
    return finish("holdout3_initial_state_small_preload", seed, np.arange(len(v)) * 1e-3, v, y,
                  {"initial_state"}, "explained", "a small positive preload, noisy monitor", rng,
                  monitor_noise=4e-4)


@case
def pair_asymmetry_drift(seed):
    rng = _rng(seed, 10)
    dt, n = 1e-3, 22_000
    v = ex.decaying_sines(dt, n, (0.6, 1.4), 45.0)
    t = np.arange(n) * dt
    h = me.asymmetric_play_core(v, 100.0, skew=rng.uniform(0.5, 0.8))
    y = h + me.thermal_offset(t, rng.uniform(0.04, 0.06) * np.ptp(h), rng.uniform(5.0, 9.0))
    return finish("holdout3_pair_asymmetry_drift", seed, t, v, y, {"asymmetry", "drift"}, "either",
                  "asymmetric core on a warming stage", rng)

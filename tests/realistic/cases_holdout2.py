"""The HOLDOUT2 set: written after the diagnosis was tuned, and never run through it while
tuning. Use it once, for the final measurement of a tuning round, and write a new one after.

Mechanisms, laws and signals that neither :data:`TUNING` nor :data:`HOLDOUT` has: power-law
creep (Changhai & Lining 2011 report t^n laws for piezo stacks), a random-walk sensor drift,
a rational (not tanh) output saturation, a hysteron with a jump (a relay added to the plays),
a viscoplastic core under band-limited random drive, a chirp, a negative preload, rate
dependence with creep, asymmetry on a unipolar stroke, a dead time under random excitation.

The cases are not part of :data:`ALL` (so the acceptance test does not run them either).
"""

import numpy as np

from . import excitations as ex
from . import mechanisms as me
from .record import case_set, finish

HOLDOUT2, case, _rng = case_set("holdout2_", 2000)


def power_law_creep(u, dt, coefficient, exponent, t0=0.01):
    """Creep after each load step du: du * coefficient * ((t - t_step + t0)^n - t0^n), t in s.

    A power law in time (exponent n ~ 0.05 ... 0.2), unbounded and not a sum of a few
    exponentials; starts at 0 at each step."""
    u = np.asarray(u, float)
    t = np.arange(len(u)) * dt
    du = np.diff(u, prepend=u[0])
    steps = np.flatnonzero(np.abs(du) > 1e-9 * (np.ptp(u) + 1e-300))
    out = np.zeros_like(u)
    for s in steps:
        out[s:] += du[s] * coefficient * ((t[s:] - t[s] + t0) ** exponent - t0 ** exponent)
    return out


def random_walk_drift(n, dt, size, rng, corner_s=2.0):
    """Sensor drift as a low-passed random walk (1/f^2-like), scaled to peak-to-peak `size`."""
    w = np.cumsum(rng.standard_normal(n))
    a = np.exp(-dt / corner_s)
    out = np.empty(n)
    acc = 0.0
    for k in range(n):
        acc = a * acc + (1 - a) * w[k]
        out[k] = acc
    out -= out[0]
    span = np.ptp(out) or 1.0
    return size * out / span


def relay(v, low, high, state=-1.0):
    """A single hysteron: +1 above `high`, -1 below `low`, memory between."""
    v = np.asarray(v, float)
    out = np.empty_like(v)
    s = state
    for k, vk in enumerate(v):
        if vk >= high:
            s = 1.0
        elif vk <= low:
            s = -1.0
        out[k] = s
    return out


@case
def clean_chirp(seed):
    rng = _rng(seed, 1)
    dt, n = 2e-3, 15_000
    v = ex.chirp(dt, n, 0.05, 2.0, rng.uniform(40, 50))
    y = me.play_core(v, 100.0)
    return finish("holdout2_clean_chirp", seed, np.arange(n) * dt, v, y, set(), "explained",
                  "rate-independent core under a slow chirp, noisy monitor", rng, monitor_noise=3e-4)


@case
def creep_power_law(seed):
    rng = _rng(seed, 2)
    levels = np.concatenate([[0.0], rng.uniform(-45, 45, 9)])
    v = ex.staircase_holds(1e-3, levels, 2.5, 0.05)
    h = me.play_core(v, 100.0)
    y = h + power_law_creep(h, 1e-3, rng.uniform(0.04, 0.07), rng.uniform(0.08, 0.15))
    return finish("holdout2_creep_power_law", seed, np.arange(len(v)) * 1e-3, v, y, {"creep"}, "either",
                  "power-law creep after every step", rng, monitor_noise=5e-4)


@case
def drift_random_walk(seed):
    rng = _rng(seed, 3)
    dt, n = 1e-3, 20_000
    v = ex.decaying_sines(dt, n, (0.5, 1.0, 2.0), 45.0)
    h = me.play_core(v, 100.0)
    y = h + random_walk_drift(n, dt, 0.05 * np.ptp(h), rng)
    return finish("holdout2_drift_random_walk", seed, np.arange(n) * dt, v, y, {"drift"}, "either",
                  "sensor drift as a low-passed random walk", rng)


@case
def saturation_rational_unipolar(seed):
    rng = _rng(seed, 4)
    v = ex.unipolar_triangles(20_000, 6, 150.0, decay=0.5)
    h = me.play_core(v, 150.0)
    ymax = rng.uniform(0.5, 0.7) * np.max(np.abs(h))
    y = h / (1 + np.abs(h) / ymax)
    return finish("holdout2_saturation_rational_unipolar", seed, np.arange(len(v)) * 1e-3, v, y,
                  {"saturation"}, "either", "unipolar stroke, output saturating as h / (1 + |h|/ymax)", rng)


@case
def oov_relay_jump(seed):
    rng = _rng(seed, 5)
    dt, n = 1e-3, 20_000
    v = ex.decaying_sines(dt, n, (0.5, 1.0), 50.0)
    h = me.play_core(v, 100.0)
    y = h + rng.uniform(0.08, 0.12) * np.ptp(h) * relay(v, -15.0, 15.0)
    return finish("holdout2_oov_relay_jump", seed, np.arange(n) * dt, v, y, set(), "unexplained",
                  "plays plus one hysteron that jumps (a relay): loops with steps", rng)


@case
def rate_viscoplastic_random(seed):
    rng = _rng(seed, 6)
    dt, n = 1e-3, 20_000
    v = ex.bandlimited_random(dt, n, rng.uniform(3.0, 6.0), 50.0, rng=rng)
    y = me.viscoplastic_core(v, dt, 100.0, eta=rng.uniform(0.01, 0.02))
    return finish("holdout2_rate_viscoplastic_random", seed, np.arange(n) * dt, v, y, {"rate_dependence"},
                  "either", "viscoplastic plays under band-limited random drive", rng)


@case
def initial_state_negative_preload(seed):
    rng = _rng(seed, 7)
    pre = np.concatenate([np.linspace(0, -rng.uniform(70, 90), 300), np.linspace(-80, -10, 300)])
    _, z = me.play_core(pre, 100.0, return_state=True)
    v = ex.decaying_sines(1e-3, 18_000, (0.7, 1.4), 40.0, offset=pre[-1])
    y = me.play_core(v, 100.0, state=z)
    return finish("holdout2_initial_state_negative_preload", seed, np.arange(len(v)) * 1e-3, v, y,
                  {"initial_state"}, "explained", "bipolar drive after a negative excursion", rng)


@case
def pair_rate_creep(seed):
    rng = _rng(seed, 8)
    dt = 1e-3
    stairs = ex.staircase_holds(dt, [0.0, 35.0, -30.0, 20.0, -40.0, 0.0], 2.0, 0.05)
    sines = ex.decaying_sines(dt, 10_000, (2.0, 8.0), 45.0)
    v = np.concatenate([stairs, sines])
    h = me.viscoplastic_core(v, dt, 100.0, eta=rng.uniform(0.008, 0.015))
    y = h + me.kelvin_voigt_creep(h, dt, [0.04], [rng.uniform(0.6, 1.2)])
    return finish("holdout2_pair_rate_creep", seed, np.arange(len(v)) * dt, v, y, {"rate_dependence", "creep"},
                  "either", "viscoplastic core with creep, staircase then sines", rng, monitor_noise=4e-4)


@case
def asymmetry_unipolar(seed):
    rng = _rng(seed, 9)
    v = ex.unipolar_triangles(18_000, 6, 100.0, decay=0.5)
    # the core's rest (every play at 0) is at mid-stroke, 50 V, and the record starts
    # at 0 V: the core was taken from 50 V to 0 V before the first sample, a preload
    # history (an initial state; 40 noise std RMS over the first 20 % against a core
    # at rest at 0 V). The first label, asymmetry alone, missed it (round 15).
    y = me.asymmetric_play_core(v - 50.0, 100.0, skew=-rng.uniform(0.5, 0.8))
    return finish("holdout2_asymmetry_unipolar", seed, np.arange(len(v)) * 1e-3, v, y,
                  {"asymmetry", "initial_state"}, "either",
                  "unipolar stroke, loops wider at the bottom, core at rest at mid-stroke (50 V) before the "
                  "record starts at 0 V", rng)


@case
def delay_random_drive(seed):
    rng = _rng(seed, 10)
    dt, n = 1e-3, 20_000
    v = ex.bandlimited_random(dt, n, 8.0, 50.0, rng=rng)
    d = rng.uniform(2.5, 4.0)
    y = me.play_core(me.fractional_delay(v, d), 100.0)
    return finish("holdout2_delay_random_drive", seed, np.arange(n) * dt, v, y, {"delay"}, "explained",
                  f"dead time {d:.2f} samples under band-limited random drive", rng)

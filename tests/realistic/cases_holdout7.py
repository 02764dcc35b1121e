"""The HOLDOUT7 set: written after HOLDOUT6 was measured (2026-11-25, seventh round), run once
through the diagnosis for the seventh round's final measurement (docs/diagnose.md), part of
ALL since.

Mechanisms and signals that the other sets do not have, or not in these combinations: a clean
core under trapezoids (ramps and flat holds) from rest, sampled at 1.6 kHz; four Kelvin-Voigt
elements (20 ms ... 5 s) under a staircase that walks up to the top, down to the bottom and
back (a stepwise loop) at 1.25 kHz; viscoplastic plays under stepped-frequency sines (four
frequencies, each held for a whole number of cycles) at 2 kHz; a fast warming offset (time
constant about a second) under band-limited random drive; a clip of the top of unipolar
raised-cosine bursts (0 ... 100 V); plays whose thresholds grow with the level under a sum of
two triangles; a dead time of about 2.4 samples under wide-band random drive at 2 kHz; a core
preloaded by an unfinished decaying alternation before triangles of growing amplitude; a dead time
with a cooling actuator's falling gain under an amplitude-modulated sine; and a butterfly (the
square of a Preisach polarisation with a shifted interaction field) under trapezoids.
"""

import numpy as np

from . import excitations as ex
from . import mechanisms as me
from .record import case_set, finish

HOLDOUT7, case, _rng = case_set("holdout7_", 7000)


# ---- signals not in excitations.py ----

def _trapezoids(dt, n, freq, amp, ramp_fraction=0.3, decay=0.5, rest_s=0.5):
    """A trapezoid wave at `freq`: ramps taking `ramp_fraction` of each half period, flat holds
    at +-amp in between, the amplitude decaying linearly by `decay`; preceded by `rest_s` at 0 V.

    A clipped triangle: the triangle scaled by 1 / ramp_fraction and clipped to +-1. Starts at
    0 V and the first ramp goes up. ``n`` samples in all.
    """
    n_rest = int(round(rest_s / dt))
    m = n - n_rest
    tt = np.arange(m) * dt
    tri = 2 / np.pi * np.arcsin(np.sin(2 * np.pi * freq * tt))
    trap = np.clip(tri / ramp_fraction, -1.0, 1.0)
    return np.concatenate([np.zeros(n_rest), amp * (1 - decay * np.arange(m) / m) * trap])


def _two_triangles(dt, n, f1, f2, a1, a2):
    """The sum of two triangle waves (incommensurate frequencies give nested minor loops)."""
    tt = np.arange(n) * dt
    return (a1 * 2 / np.pi * np.arcsin(np.sin(2 * np.pi * f1 * tt))
            + a2 * 2 / np.pi * np.arcsin(np.sin(2 * np.pi * f2 * tt)))


def _stepped_sines(dt, freqs, cycles, amp):
    """Sines at each frequency in turn, each held for a whole number of `cycles` from phase 0
    (so the segments join at 0 V with continuous level). Returns the signal and the segment
    boundaries (sample indices, len(freqs) + 1 of them)."""
    parts, edges = [], [0]
    for f, c in zip(freqs, cycles):
        m = int(round(c / f / dt))
        parts.append(amp * np.sin(2 * np.pi * c * np.arange(m) / m))
        edges.append(edges[-1] + m)
    return np.concatenate(parts), np.array(edges)


def _raised_cosine_bursts(dt, freq, tops, rest_s=0.2):
    """Unipolar bursts 0 -> top -> 0 V, each one period of (1 - cos) / 2 at `freq`, with
    `rest_s` at 0 V before each."""
    m = int(round(1 / freq / dt))
    pulse = 0.5 * (1 - np.cos(2 * np.pi * np.arange(m) / m))
    rest = np.zeros(int(round(rest_s / dt)))
    return np.concatenate([np.concatenate([rest, top * pulse]) for top in tops] + [rest])


def _growing_triangles(dt, n, freq, amp, start=0.15, grow_fraction=0.6):
    """Triangles from 0 V whose amplitude grows linearly from start x amp to amp over the first
    `grow_fraction` of the record and stays at amp after."""
    s = np.arange(n) / n
    env = np.minimum(start + (1 - start) * s / grow_fraction, 1.0)
    return amp * env * 2 / np.pi * np.arcsin(np.sin(2 * np.pi * freq * np.arange(n) * dt))


def _am_sine(dt, n, carrier, modulation, amp, depth):
    """A sine at `carrier` whose amplitude swings between amp and (1 - depth) amp at
    `modulation` Hz (a beat-like envelope, starting at full amplitude)."""
    tt = np.arange(n) * dt
    env = 1 - depth * 0.5 * (1 - np.cos(2 * np.pi * modulation * tt))
    return amp * env * np.sin(2 * np.pi * carrier * tt)


def _stepwise_loop_levels(top, steps, rng, jitter=0.08):
    """Levels 0 -> top -> -top -> 0 in `steps` steps per quarter, each level jittered."""
    q = np.arange(1, steps + 1) / steps
    shape = np.concatenate([[0.0], q, q[::-1][1:], [0.0], -q, -q[::-1][1:], [0.0]])
    j = 1 + jitter * rng.uniform(-1, 1, len(shape))
    return top * shape * j


def _decaying_alternation(first, ratio, reversals, ramp=300):
    """A preload history: ramps 0 -> first -> -ratio first -> ratio^2 first ... -> 0."""
    ext = [first * (-ratio) ** k for k in range(reversals)]
    pts = [0.0] + ext + [0.0]
    return np.concatenate([np.linspace(a, b, ramp, endpoint=False) for a, b in zip(pts[:-1], pts[1:])]
                          + [[0.0]])


# ---- clean ----

@case
def clean_trapezoids_1600hz(seed):
    rng = _rng(seed, 1)
    dt, n = 1 / 1600, 16_000
    v = _trapezoids(dt, n, rng.uniform(0.5, 0.8), rng.uniform(42, 50), ramp_fraction=rng.uniform(0.25, 0.4))
    y = me.play_core(v, 100.0, gain=rng.uniform(0.7, 1.5)) + rng.uniform(-3, 3)
    return finish("holdout7_clean_trapezoids_1600hz", seed, np.arange(n) * dt, v, y, set(), "explained",
                  "a clean core under decaying trapezoids from rest, sampled at 1.6 kHz", rng,
                  monitor_noise=3e-4)


# ---- one effect ----

@case
def creep_four_kv_stepwise_loop(seed):
    rng = _rng(seed, 2)
    dt = 8e-4
    levels = _stepwise_loop_levels(rng.uniform(40, 48), 3, rng)
    v = ex.staircase_holds(dt, levels, 2.0, 0.05)
    h = me.play_core(v, 100.0)
    c = rng.uniform(0.04, 0.06) * rng.dirichlet([3.0, 3.0, 3.0, 3.0])
    tau = [rng.uniform(0.02, 0.04), rng.uniform(0.15, 0.3), rng.uniform(0.8, 1.4), rng.uniform(3.0, 5.0)]
    y = h + me.kelvin_voigt_creep(h, dt, c, tau)
    return finish("holdout7_creep_four_kv_stepwise_loop", seed, np.arange(len(v)) * dt, v, y, {"creep"},
                  "either", "four Kelvin-Voigt elements (20 ms ... 5 s), a staircase up, down and back "
                  "at 1.25 kHz", rng, monitor_noise=3e-4)


@case
def rate_viscoplastic_stepped_sines(seed):
    rng = _rng(seed, 3)
    dt = 5e-4
    freqs = np.array([0.5, 2.0, 6.0, 15.0]) * rng.uniform(0.9, 1.1, 4)
    v, edges = _stepped_sines(dt, freqs, (3, 6, 10, 15), rng.uniform(42, 48))
    y = me.viscoplastic_core(v, dt, 100.0, eta=rng.uniform(5e-3, 9e-3))
    rec = finish("holdout7_rate_viscoplastic_stepped_sines", seed, np.arange(len(v)) * dt, v, y,
                 {"rate_dependence"}, "either",
                 "viscoplastic plays under stepped-frequency sines (" + ", ".join(f"{f:.2f}" for f in freqs)
                 + " Hz), 2 kHz", rng, monitor_noise=2e-4)
    rec.extra["freqs"] = freqs
    rec.extra["segments"] = edges
    return rec


@case
def drift_fast_warming_random(seed):
    rng = _rng(seed, 4)
    dt, n = 1e-3, 24_000
    t = np.arange(n) * dt
    v = ex.bandlimited_random(dt, n, rng.uniform(2.0, 3.5), 45.0, rng=rng)
    h = me.play_core(v, 100.0)
    amp = rng.choice([-1.0, 1.0]) * rng.uniform(0.05, 0.08) * np.ptp(h)
    y = h + me.thermal_offset(t, amp, tau=rng.uniform(0.8, 1.6))
    return finish("holdout7_drift_fast_warming_random", seed, t, v, y, {"drift"}, "either",
                  "an offset settling within about a second (plus a slow ripple), band-limited random drive",
                  rng, monitor_noise=3e-4)


@case
def clip_unipolar_bursts(seed):
    rng = _rng(seed, 5)
    dt = 1e-3
    tops = rng.uniform(55.0, 100.0, 11)
    tops[rng.integers(0, 11, 2)] = 100.0            # at least one full-stroke burst
    v = _raised_cosine_bursts(dt, rng.uniform(0.8, 1.2), tops)
    h = me.play_core(v, 100.0)
    level = rng.uniform(0.8, 0.88) * h.max()
    y = me.clip(h, -np.inf, level)
    rec = finish("holdout7_clip_unipolar_bursts", seed, np.arange(len(v)) * dt, v, y, {"output_saturation"},
                 "either", "a sensor range clipping the top of unipolar raised-cosine bursts (0 ... 100 V)",
                 rng, monitor_noise=3e-4)
    rec.extra["clip_level"] = level
    return rec


@case
def asymmetry_two_triangles(seed):
    rng = _rng(seed, 6)
    dt, n = 1e-3, 20_000
    v = _two_triangles(dt, n, rng.uniform(0.35, 0.5), rng.uniform(1.5, 1.9), 30.0, 18.0)
    y = me.asymmetric_play_core(v, 100.0, skew=rng.choice([-1.0, 1.0]) * rng.uniform(0.45, 0.65))
    return finish("holdout7_asymmetry_two_triangles", seed, np.arange(n) * dt, v, y, {"asymmetry"},
                  "either", "thresholds growing with the input level under a sum of two triangles", rng,
                  monitor_noise=3e-4)


@case
def delay_wideband_random_2khz(seed):
    rng = _rng(seed, 7)
    dt, n = 5e-4, 24_000
    v = ex.bandlimited_random(dt, n, rng.uniform(15.0, 25.0), 45.0, rng=rng)
    d = rng.uniform(2.1, 2.8)
    y = me.play_core(me.fractional_delay(v, d), 100.0)
    rec = finish("holdout7_delay_wideband_random_2khz", seed, np.arange(n) * dt, v, y, {"delay"}, "either",
                 f"dead time {d:.2f} samples under band-limited random drive (15 ... 25 Hz) at 2 kHz", rng,
                 monitor_noise=2e-4)
    rec.extra["delay_samples"] = d
    return rec


@case
def initial_state_alternating_preload(seed):
    rng = _rng(seed, 8)
    # an alternation stopped after two or three reversals (an unfinished demagnetisation): the
    # remanence at 0 V is 4 ... 10 % of the output span
    pre = _decaying_alternation(rng.choice([-1.0, 1.0]) * rng.uniform(55, 65), rng.uniform(0.75, 0.85),
                                int(rng.integers(2, 4)))
    _, z = me.play_core(pre, 100.0, return_state=True)
    dt, n = 1e-3, 20_000
    v = _growing_triangles(dt, n, rng.uniform(0.8, 1.2), rng.uniform(47, 50))
    y = me.play_core(v, 100.0, state=z)
    rec = finish("holdout7_initial_state_alternating_preload", seed, np.arange(n) * dt, v, y,
                 {"initial_state"}, "explained",
                 "a partial demagnetisation (decaying alternation) before triangles of growing amplitude",
                 rng, monitor_noise=3e-4)
    rec.extra["preload"] = pre
    return rec


# ---- two effects ----

@case
def pair_delay_cooling_gain_am(seed):
    rng = _rng(seed, 9)
    dt, n = 1e-3, 24_000
    t = np.arange(n) * dt
    v = _am_sine(dt, n, rng.uniform(2.5, 3.5), rng.uniform(0.12, 0.2), 48.0, rng.uniform(0.4, 0.6))
    d = rng.uniform(2.5, 4.0)
    h = me.play_core(me.fractional_delay(v, d), 100.0)
    y = h * me.thermal_gain(t, -rng.uniform(0.06, 0.09), tau=rng.uniform(4.0, 8.0))
    rec = finish("holdout7_pair_delay_cooling_gain_am", seed, t, v, y, {"delay", "gain_drift"}, "either",
                 f"a dead time of {d:.2f} samples and a falling gain (a cooling actuator), "
                 "amplitude-modulated sine", rng, monitor_noise=3e-4)
    rec.extra["delay_samples"] = d
    return rec


# ---- out of vocabulary ----

@case
def oov_preisach_butterfly_trapezoids(seed):
    rng = _rng(seed, 10)
    dt, n = 1e-3, 12_000
    v = _trapezoids(dt, n, rng.uniform(0.6, 0.9), 50.0, ramp_fraction=0.35, decay=0.4)
    # the strain of a ferroelectric goes as the square of its polarisation; here the polarisation
    # is a Preisach plane with a shifted interaction field, so the butterfly's wings differ too
    p = me.preisach_core(v, -55, 55, interaction=rng.uniform(0.05, 0.1))
    y = me.butterfly(p, rng.uniform(0.8, 1.2) / np.max(p ** 2))
    return finish("holdout7_oov_preisach_butterfly_trapezoids", seed, np.arange(n) * dt, v, y, set(),
                  "unexplained", "a butterfly (square of a Preisach polarisation) under trapezoids", rng,
                  monitor_noise=3e-4)

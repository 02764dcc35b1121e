"""Excitation signals as experimenters drive actuators, written independently of hystcomp.signals."""

import numpy as np

__all__ = ["decaying_sines", "staircase_holds", "triangles", "bandlimited_random", "quasi_static_loops",
           "unipolar_triangles", "on_off_intervals"]


def decaying_sines(dt, n, freqs, amp, offset=0.0, rng=None):
    """Segments of sines at each frequency (the list played twice), amplitude decaying to 0.3x.

    Each segment starts at its offset and has amplitude amp*(1 - 0.7 s) over s in [0, 1),
    so each excites the major loop and nested minor loops.
    """
    seq = list(freqs) * 2
    m = n // len(seq)
    out = []
    for f in seq:
        tt = np.arange(m) * dt
        s = np.arange(m) / m
        out.append(offset + amp * (1 - 0.7 * s) * np.sin(2 * np.pi * f * tt))
    v = np.concatenate(out)
    return np.concatenate([v, np.full(n - len(v), offset)])


def staircase_holds(dt, levels, hold_s, ramp_s):
    """Linear ramps between `levels`, each level held for `hold_s` seconds (starts at levels[0])."""
    nh = int(round(hold_s / dt))
    nr = max(int(round(ramp_s / dt)), 1)
    out = [np.full(nh, levels[0])]
    for a, b in zip(levels[:-1], levels[1:]):
        out.append(np.linspace(a, b, nr + 1)[1:])
        out.append(np.full(nh, b))
    return np.concatenate(out)


def triangles(dt, n, freq, amp, offset=0.0, decay=0.7):
    """A triangle wave at `freq`, amplitude decaying linearly by the fraction `decay`."""
    tt = np.arange(n) * dt
    tri = 2 / np.pi * np.arcsin(np.sin(2 * np.pi * freq * tt))
    return offset + amp * (1 - decay * np.arange(n) / n) * tri


def bandlimited_random(dt, n, fc, amp, offset=0.0, rng=None):
    """White noise through a 4th-order low-pass at fc (forward-backward), scaled to peak amp."""
    from scipy.signal import butter, sosfiltfilt

    rng = np.random.default_rng(rng)
    sos = butter(4, fc, fs=1 / dt, output="sos")
    x = sosfiltfilt(sos, rng.standard_normal(n + 2000))[1000:-1000]
    return offset + amp * x / np.abs(x).max()


def quasi_static_loops(n, amps, offset=0.0):
    """Closed triangular loops with the given amplitudes (a point sequence, no time axis)."""
    m = n // len(amps)
    out = []
    for a in amps:
        s = np.arange(m) / m
        out.append(offset + a * 2 / np.pi * np.arcsin(np.sin(2 * np.pi * s)))
    v = np.concatenate(out)
    return np.concatenate([v, np.full(n - len(v), v[-1])])


def unipolar_triangles(n, periods, top, decay=0.6):
    """Triangles from 0 up to `top` (decaying by the fraction `decay`) and back: 0 ... top.

    `periods` is the number of full triangles in the n samples; starts and ends at 0.
    """
    s = np.arange(n) / n
    phase = periods * s
    tri01 = 1 - np.abs(2 * (phase % 1) - 1)
    return top * (1 - decay * s) * tri01


def chirp(dt, n, f0, f1, amp):
    """A linear chirp from f0 to f1 Hz with amplitude amp (starts at 0)."""
    t = np.arange(n) * dt
    T = t[-1] if t[-1] > 0 else 1.0
    phase = 2 * np.pi * (f0 * t + 0.5 * (f1 - f0) * t ** 2 / T)
    return amp * np.sin(phase)


def on_off_intervals(t, on_range, off_range, rng):
    """A machine switching on and off at random over the times t (a pump on its pressure switch, a fan on its
    thermostat, a blow gun in use): off for a time drawn uniformly from `off_range`, on for one from `on_range`, and so
    on to the end. Returns the on intervals [(start, duration)] and a 0/1 mask of the samples inside them."""
    t = np.asarray(t, float)
    ivs = []
    s = float(rng.uniform(*off_range))
    while s < t[-1]:
        d = float(rng.uniform(*on_range))
        ivs.append((s, d))
        s += d + float(rng.uniform(*off_range))
    on = np.zeros(len(t))
    for a, d in ivs:
        on[(t >= a) & (t < a + d)] = 1.0
    return ivs, on

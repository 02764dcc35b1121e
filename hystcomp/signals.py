"""Excitation signals that let identification and diagnosis see every effect.

:func:`identification_experiment` builds one record from four parts, each
revealing some effects (the table is in ``docs/diagnose.md``):

=====================  =====================================================
part                   what it reveals
=====================  =====================================================
slow decaying sine     the hysteresis itself: nested loops from the largest
                       to small amplitudes (the loading curve and every
                       threshold), saturation at the large amplitudes,
                       asymmetry of the branches; drift over its duration
sines at several       rate dependence: a rate-independent model gives the
frequencies            same loop at every frequency, so loops that widen or
                       tilt with frequency are dynamics
staircase with holds   creep (the output keeps moving after each step, in
in both directions     its sign) and drift (moving the same way whatever the
                       step); overshoot after steps (resonance); positive
                       against negative levels (asymmetry)
multisine              rate dependence over a band (lag and resonance),
                       many minor loops
=====================  =====================================================

The record is two passes: the first (``1 - tail`` of the duration) holds
all four parts, the second (the last ``tail``) repeats the sines, the
staircase and the multisine, shorter, so that a held-out tail (the
``validation`` fraction of :func:`hystcomp.diagnose.diagnose`) checks every
effect on data the fit has not seen.
"""

from collections import namedtuple

import numpy as np

from ._validation import as_scalar, as_signal

__all__ = ["Experiment", "identification_experiment", "staircase", "multisine", "decaying_sine"]

def _as_times(t, min_length=1):
    t = as_signal(t, "t", min_length=min_length)
    d = np.diff(t)
    if np.any(d <= 0):
        k = int(np.argmax(d <= 0)) + 1
        raise ValueError(
            f"Parameter t is not strictly increasing: t[{k}] = {t[k]} follows t[{k - 1}] = {t[k - 1]}"
        )
    return t


def _as_frequencies(frequencies):
    try:
        f = np.asarray(frequencies, dtype=np.float64).reshape(-1)
    except (TypeError, ValueError):
        raise TypeError(f"Parameter frequencies is {frequencies!r} but should be a sequence of numbers [Hz]") from None
    if f.size == 0 or not np.all(np.isfinite(f)) or np.any(f <= 0):
        raise ValueError(f"Parameter frequencies is {f.tolist()} but should hold finite positive frequencies [Hz]")
    return f


def _as_count(n, name, minimum):
    if isinstance(n, (bool, np.bool_)) or not isinstance(n, (int, np.integer)):
        if not (isinstance(n, (float, np.floating)) and float(n).is_integer()):
            raise TypeError(f"Parameter {name} is {n!r} but should be an integer")
    n = int(n)
    if n < minimum:
        raise ValueError(f"Parameter {name} is {n} but should be >= {minimum}")
    return n


#: result of :func:`identification_experiment`
Experiment = namedtuple("Experiment", ["t", "v", "segments"])
Experiment.__doc__ = """An excitation record: time t [s], input v, and segments, a list of
(name, t_start, t_end) for each part (a named tuple, returned by
:func:`identification_experiment`).

Examples
--------
>>> exp = identification_experiment(dt=0.01, duration=40.0)
>>> t, v, segments = exp
>>> segments[0][0], segments[0][1], t.size == v.size
('decaying sine', 0.0, True)
"""


def decaying_sine(t, frequency, amplitude=1.0, final_fraction=0.1):
    """``A q^(t/T) sin(2 pi f t)`` decaying from A to ``final_fraction A`` over
    the span of `t` (T its duration).

    Parameters
    ----------
    t : array_like, shape (n,)
        Sample times [s], increasing; the sine starts at ``t[0]``.
    frequency : float
        f [Hz].
    amplitude : float
        A, the initial amplitude.
    final_fraction : float
        q, the amplitude at the end of `t` relative to A.

    Returns
    -------
    ndarray, shape (n,)

    Examples
    --------
    >>> t = np.linspace(0, 4, 4001)
    >>> v = decaying_sine(t, 1.0)
    >>> round(float(v[250]), 4), round(float(np.abs(v[-300:]).max()), 2)
    (0.866, 0.12)
    """
    t = _as_times(t)
    frequency = as_scalar(frequency, "frequency", nonnegative=True)
    amplitude = as_scalar(amplitude, "amplitude")
    final_fraction = as_scalar(final_fraction, "final_fraction", positive=True)
    T = float(t[-1] - t[0]) or 1.0
    return amplitude * final_fraction ** ((t - t[0]) / T) * np.sin(2 * np.pi * frequency * (t - t[0]))


def staircase(n, levels):
    """Hold each of `levels` for ``n // len(levels)`` samples (the remainder on
    the last level).

    Parameters
    ----------
    n : int
        Number of samples, at least ``len(levels)``.
    levels : array_like
        The levels, in order.

    Returns
    -------
    ndarray, shape (n,)

    Examples
    --------
    >>> staircase(5, [0.0, 1.0]).tolist()
    [0.0, 0.0, 1.0, 1.0, 1.0]
    """
    try:
        levels = np.asarray(levels, dtype=np.float64)
    except (TypeError, ValueError):
        raise TypeError(f"Parameter levels is {levels!r} but should be a sequence of numbers") from None
    if levels.ndim != 1 or levels.size == 0 or not np.all(np.isfinite(levels)):
        raise ValueError(
            f"Parameter levels is {levels.tolist()} but should be a non-empty 1-D sequence of finite numbers"
        )
    n = _as_count(n, "n", 1)
    if n < levels.size:
        raise ValueError(f"Parameter n is {n} but should be at least len(levels) = {levels.size}")
    m = n // levels.size
    v = np.repeat(levels, m)
    return np.concatenate([v, np.full(n - v.size, levels[-1])])


def multisine(t, frequencies, amplitude=1.0, taper=0.1):
    """Sum of equal-amplitude sines with Schroeder phases (low crest factor),
    scaled to peak `amplitude` and tapered to 0 at both ends (cosine ramps
    over the fraction `taper` of the record).

    Parameters
    ----------
    t : array_like, shape (n,)
        Sample times [s], increasing.
    frequencies : array_like
        Sine frequencies [Hz].
    amplitude : float
        Peak of the result.
    taper : float
        Fraction of the record over which each end ramps from 0 (raised
        cosine).

    Returns
    -------
    ndarray, shape (n,)

    Examples
    --------
    >>> t = np.linspace(0, 2, 2001)
    >>> v = multisine(t, [1, 2, 4])
    >>> round(float(np.abs(v).max()), 6), abs(float(v[0])), abs(float(v[-1]))
    (1.0, 0.0, 0.0)
    """
    t = _as_times(t, min_length=2)
    t = t - t[0]
    f = _as_frequencies(frequencies)
    amplitude = as_scalar(amplitude, "amplitude")
    taper = as_scalar(taper, "taper", positive=True)
    if taper > 0.5:
        raise ValueError(f"Parameter taper is {taper} but should be in (0, 0.5] (a fraction at each end)")
    K = f.size
    phases = -np.pi * np.arange(1, K + 1) * np.arange(K) / K
    v = np.zeros_like(t)
    for fk, ph in zip(f, phases):
        v += np.sin(2 * np.pi * fk * t + ph)
    T = t[-1] if t[-1] > 0 else 1.0
    ramp = np.clip(np.minimum(t, T - t) / (taper * T), 0.0, 1.0)
    v *= 0.5 - 0.5 * np.cos(np.pi * ramp)
    peak = np.abs(v).max()
    return amplitude * v / peak if peak > 0 else v


def identification_experiment(dt=1e-3, duration=40.0, amplitude=1.0, frequencies=(0.5, 1.0, 2.0, 4.0, 8.0),
                              steps=4, tail=0.3, holds=True):
    """A record that shows every effect :func:`hystcomp.diagnose.diagnose` tests.

    Parts (module docstring for what each reveals): a slow decaying sine
    (1/4 of the first pass), sines at each of `frequencies` at full amplitude
    (an integer number of periods each, the frequency rounded to fit), a staircase with holds through
    `steps` levels up to +amplitude, down to -amplitude and back to 0, and a
    multisine over the band of `frequencies`.  The last `tail` of the
    duration repeats the sines, staircase and multisine.  Every part starts
    and ends at 0.

    Parameters
    ----------
    dt : float
        Sampling time [s].
    duration : float
        Record length [s].
    amplitude : float
        Peak input.
    frequencies : sequence of float
        Sine frequencies [Hz], each at most 1/10 of the sampling rate.
    steps : int
        Levels per quarter of the staircase (0 -> +A, +A -> 0, 0 -> -A, -A -> 0).
    tail : float
        Fraction of the duration taken by the second pass (0 for none).
    holds : bool
        False replaces the staircase by sines (for showing what diagnosis
        says when the data cannot show creep and drift).

    Returns
    -------
    Experiment
        ``(t, v, segments)``.

    Examples
    --------
    >>> exp = identification_experiment(dt=0.01, duration=40.0)
    >>> exp.t.size, [s[0] for s in exp.segments][:4]
    (4000, ['decaying sine', 'sines', 'staircase', 'multisine'])
    >>> float(np.abs(exp.v).max())
    1.0
    """
    dt = as_scalar(dt, "dt", positive=True)
    duration = as_scalar(duration, "duration", positive=True)
    A = as_scalar(amplitude, "amplitude", positive=True)
    tail = as_scalar(tail, "tail", nonnegative=True)
    if tail >= 0.9:
        raise ValueError(f"Parameter tail is {tail} but should be below 0.9 (the first pass needs room)")
    f = np.sort(_as_frequencies(frequencies))
    if f[-1] > 0.1 / dt:
        raise ValueError(f"Parameter frequencies reaches {f[-1]} Hz but should stay below a tenth of the "
                         f"sampling rate ({0.1 / dt} Hz for dt = {dt})")
    n_total = duration / dt
    if n_total > 1e9:
        raise ValueError(f"Parameters duration/dt give {n_total:.3g} samples; at most 1e9 are supported "
                         f"(duration = {duration}, dt = {dt})")
    n_total = int(round(n_total))
    if n_total < 400:
        raise ValueError(f"Parameters duration/dt give {n_total} samples but at least 400 are needed")
    steps = _as_count(steps, "steps", 1)
    up = np.arange(1, steps + 1) / steps
    levels = A * np.concatenate([up, up[::-1][1:], [0.0], -up, -up[::-1][1:], [0.0]])

    def sines(n):
        # n // len(f) samples per frequency, each frequency nudged so that an
        # integer number of periods fills its share exactly (no gaps, no jumps)
        counts = [n // f.size] * f.size
        counts[-1] += n - sum(counts)
        out = []
        for fk, m in zip(f, counts):
            periods = max(1, int(round(m * dt * fk)))
            out.append(A * np.sin(2 * np.pi * periods * np.arange(m) / m))
        return np.concatenate(out)

    def stairs(n):
        if not holds:
            return sines(n)
        return staircase(n, levels)

    def msine(n):
        tt = np.arange(n) * dt
        T = n * dt
        fm = np.unique(np.clip(np.round(np.geomspace(f[0], f[-1], 3 * f.size) * T) / T, 1.0 / T, None))
        return multisine(tt, fm, A)

    def dsine(n):
        tt = np.arange(n) * dt
        f0 = f[0]
        periods = max(2, int(n * dt * f0))
        return decaying_sine(tt, periods / (n * dt), A)

    n2 = int(round(tail * n_total))
    n1 = n_total - n2
    parts = [("decaying sine", dsine, 0.25), ("sines", sines, 0.25), ("staircase", stairs, 0.3),
             ("multisine", msine, 0.2)]
    pieces, segments, k0 = [], [], 0
    for total, plist in ((n1, parts), (n2, parts[1:])):
        if total == 0:
            continue
        wsum = sum(p[2] for p in plist)
        counts = [int(total * p[2] / wsum) for p in plist]
        counts[-1] = total - sum(counts[:-1])
        for (name, make, _), n in zip(plist, counts):
            seg = make(n)
            pieces.append(seg)
            segments.append((name if holds or name != "staircase" else "sines (no holds)",
                             k0 * dt, (k0 + n) * dt))
            k0 += n
    v = np.concatenate(pieces)
    t = np.arange(v.size) * dt
    return Experiment(t, v, segments)

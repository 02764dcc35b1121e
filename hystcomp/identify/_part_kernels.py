"""Compiled kernels of the model parts of :mod:`hystcomp.identify.parts`.

One recursion serves every hysteresis core the parts build: modified plays
(eq. 23) with thresholds ``r_i + beta |dx/dt|`` (for ``r_i > 0``; the operator
with ``r_0 = 0`` stays the input itself) (rate-dependent thresholds,
Al Janaideh et al. 2009) and envelopes

``gl(s) = rho f(s; q_l, b_l)``, ``gr(s) = f(s; q_r, b_r)``,
``f(s; q, b) = tanh(b (s + q s^2)) / b`` (``s + q s^2`` for ``b = 0``),

in units where the input scale is 1.  With ``rho = 1``, ``q = b = 0`` and
``beta = 0`` the outputs are the classical plays of
:func:`hystcomp._kernels.play_states` (eq. 18).

Viscous plays: with ``decay = exp(-dt / tau) > 0`` a play outside its band
``[lo, hi]`` is not clamped to it but relaxes towards it, ``w <- c + (w -
c) decay`` with ``c`` the clamped value: the overstress law of Perzyna
(1966), ``dw/dt = -(w - c) / tau``, exact per sample for an input held
over the sample.  ``decay = 0`` is the rate-independent play.

Thermally activated plays: with ``overstress_scale = s > 0`` as well, the
overstress relaxes by Eyring's law of activated flow (Eyring, J. Chem. Phys.
4 (1936) 283; the sinh flow law of viscoplasticity), ``d|w - c|/dt = -(s /
tau) sinh(|w - c| / s)``: like Perzyna's for overstresses well below ``s``,
far faster above.  Over a sample with the input held, ``tanh(|w - c| / 2s)``
falls by the factor ``exp(-dt / tau)`` (separate the variables: ``dE /
sinh(E) = d ln tanh(E/2)``), so ``|w - c| <- 2 s artanh(tanh(|w - c| / 2s)
decay)``, exact and stable for any step.  With ``z = exp(-|w - c| / s) - 1``
and ``D = decay`` that is ``s log1p(-2 D z / (2 + z (1 + D)))`` (``tanh(E/2)
= -z / (2 + z)``, ``artanh(T) = log1p(2T / (1 - T)) / 2``): one ``expm1``
and one ``log1p``, a quarter faster than ``tanh`` and ``artanh``.
"""

import math

import numpy as np
from numba import njit


@njit(cache=True, inline="always")
def _env(s, q, b):
    u = s + q * s * s
    if b == 0.0:
        return u
    return math.tanh(b * u) / b


@njit(cache=True, inline="always")
def _clamp(w, lo, hi):
    """A play's output `w` pushed into its band: first down to `hi`, then up to `lo`."""
    if w > hi:
        w = hi
    if w < lo:
        w = lo
    return w


@njit(cache=True, inline="always")
def _poly_band(xk, ri, shift, rho, ql, qr, positive):
    """The band ``(lo, hi)`` of a play with polynomial envelopes (threshold
    `ri`; `positive`: a play with ``r_i > 0``, which sees ``x - shift``)."""
    xi = xk - shift if positive else xk
    s = xi - ri
    lo = rho * (s + ql * s * s)
    s = xi + ri
    return lo, s + qr * s * s


def activated_overstress(overstress, decay, overstress_scale):
    """The overstress ``|w - c|`` of a thermally activated play after one
    sample with the input held (Eyring's law, see the module docstring):
    ``s log1p(-2 D z / (2 + z (1 + D)))``, ``z = expm1(-|w - c| / s)``.
    Scalars or arrays: the compiled kernel and the exact inverse
    (:mod:`hystcomp.identify.parts_inverse`) both step with it.

    Examples
    --------
    Well below the scale ``s`` the overstress falls by ``decay`` (Perzyna's
    law); ten times above it, to about ``s``:

    >>> activated_overstress(np.array([0.01, 1.0]), 0.5, 0.1).round(5).tolist()
    [0.005, 0.10985]
    """
    z = np.expm1(-overstress / overstress_scale)
    return overstress_scale * np.log1p(-2.0 * decay * z / (2.0 + z * (1.0 + decay)))


_activated_overstress = njit(cache=True, inline="always")(activated_overstress)


@njit(cache=True, inline="always")
def _relax(w, c, decay, overstress_scale):
    """A viscous play's output `w` relaxed towards its clamped value `c` over
    one sample (see the module docstring: Perzyna's linear law, or Eyring's
    with ``overstress_scale > 0``)."""
    e = w - c
    if overstress_scale > 0.0:
        if e != 0.0:
            c = c + math.copysign(_activated_overstress(abs(e), decay, overstress_scale), e)
        return c
    return c + e * decay


@njit(cache=True, nogil=True)
def core_columns(x, r, beta, inv_dt, rho, ql, qr, bl, br, preload, out, shift=0.0, level=0.0, decay=0.0,
                 overstress_scale=0.0):
    """out[k, i] = modified play i after sample k (see the module docstring).

    x : input (scaled), r : thresholds (scaled, r[0] may be 0), beta : rate
    coefficient [s] (0: rate independent), inv_dt : 1/dt (unused when beta is
    0), preload : inputs applied at rest (rate 0) before the first sample,
    starting from the virgin state ``w = 0``.  shift : the plays with
    ``r_i > 0`` see ``x - shift`` (thresholds ``r_i + shift`` rising and
    ``r_i - shift`` falling: asymmetric thresholds).  level : thresholds
    that grow with the input level, ``r_i max(1 + level x, 0.05)`` (a loop
    wider at one end of the stroke than at the other).  decay : viscous
    plays (see the module docstring; the preload is applied at rest, fully
    relaxed, and the play with ``r_i = 0`` stays the input itself).
    overstress_scale : with ``decay > 0``, the viscous plays relax by
    Eyring's law of activated flow with this scale (scaled input units; 0:
    Perzyna's linear law).
    """
    N = r.size
    w = np.zeros(N)
    for k in range(preload.size):
        for i in range(N):
            xk = preload[k] - shift if r[i] > 0.0 else preload[k]
            ri = r[i] * max(1.0 + level * preload[k], 0.05)
            lo = rho * _env(xk - ri, ql, bl)
            hi = _env(xk + ri, qr, br)
            w[i] = _clamp(w[i], lo, hi)
    if beta == 0.0 and bl == 0.0 and br == 0.0 and decay == 0.0:
        # rate-independent plays with polynomial envelopes (the classical
        # plays, eq. 18, asymmetric envelopes, thresholds shifted or growing
        # with the level): the general loop's expressions without its rate,
        # tanh and viscous terms (the same floats, 6-8 times faster)
        for k in range(x.size):
            xk = x[k]
            grow = max(1.0 + level * xk, 0.05)
            for i in range(N):
                pos = r[i] > 0.0
                lo, hi = _poly_band(xk, r[i] * grow if pos else 0.0, shift, rho, ql, qr, pos)
                wi = _clamp(w[i], lo, hi)
                w[i] = wi
                out[k, i] = wi
        return
    if beta == 0.0 and bl == 0.0 and br == 0.0:
        # viscous or activated plays with polynomial envelopes and fixed thresholds:
        # the general loop's expressions without its rate and tanh terms (the same
        # floats, 1.5-2.5 times faster)
        for k in range(x.size):
            xk = x[k]
            grow = max(1.0 + level * xk, 0.05)
            for i in range(N):
                pos = r[i] > 0.0
                lo, hi = _poly_band(xk, r[i] * grow if pos else 0.0, shift, rho, ql, qr, pos)
                wi = _clamp(w[i], lo, hi)
                if pos:
                    wi = _relax(w[i], wi, decay, overstress_scale)
                w[i] = wi
                out[k, i] = wi
        return
    prev = x[0] if x.size else 0.0
    for k in range(x.size):
        xk = x[k]
        extra = beta * abs(xk - prev) * inv_dt if beta != 0.0 else 0.0
        prev = xk
        grow = max(1.0 + level * xk, 0.05)
        for i in range(N):
            ri = r[i] * grow + extra if r[i] > 0.0 else 0.0
            xi = xk - shift if r[i] > 0.0 else xk
            lo = rho * _env(xi - ri, ql, bl)
            hi = _env(xi + ri, qr, br)
            wi = _clamp(w[i], lo, hi)
            if decay > 0.0 and r[i] > 0.0:
                wi = _relax(w[i], wi, decay, overstress_scale)
            w[i] = wi
            out[k, i] = wi


@njit(cache=True, nogil=True)
def fractional_delay(x, d, out):
    """out[k] = x at sample k - d (cubic Lagrange interpolation; x[0] before
    the start): :func:`drifting_delay` with the same delay at both ends."""
    drifting_delay(x, d, d, out)


@njit(cache=True, inline="always")
def _sample(x, i):
    """x[i], x[0] before the start and x[-1] after the end."""
    if i <= 0:
        return x[0]
    if i >= x.size:
        return x[x.size - 1]
    return x[i]


@njit(cache=True, nogil=True)
def drifting_delay(x, d0, d1, out):
    """out[k] = x at sample k - d_k, d_k = d0 + (d1 - d0) k / (n - 1): a dead
    time that changes linearly along the record (x[0] before the start).

    Between samples the input is read by cubic Lagrange interpolation on the
    four nearest samples (Laakso, Valimaki, Karjalainen & Laine, IEEE
    Signal Processing Magazine 13 (1996) 30, "Splitting the unit delay"):
    its gain at 0.05 cycles a sample is 0.9998 half-way between samples,
    where linear interpolation's is cos(pi 0.05) = 0.988, a low-pass that a
    dead time does not have.  It is exact on cubic polynomials and on the
    samples themselves (at f = 0 the weights are 0, 1, 0, 0)."""
    n = x.size
    for k in range(n):
        d = d0 + (d1 - d0) * k / (n - 1) if n > 1 else d0
        s = k - d
        if s <= 0.0:
            out[k] = x[0]
        else:
            j = int(math.floor(s))
            f = s - j
            a = f + 1.0
            b = f - 1.0
            c = f - 2.0
            out[k] = (-f * b * c / 6.0 * _sample(x, j - 1) + a * b * c / 2.0 * _sample(x, j)
                      - a * f * c / 2.0 * _sample(x, j + 1) + a * f * b / 6.0 * _sample(x, j + 2))


@njit(cache=True, nogil=True)
def slew_limit(x, step, out):
    """out[k] follows x at most `step` per sample (a slew-rate limit: an
    amplifier whose output current is limited drives the capacitive stack at
    ``dV/dt <= I_max / C``), from out[0] = x[0]."""
    n = x.size
    if n == 0:
        return
    u = x[0]
    out[0] = u
    for k in range(1, n):
        d = x[k] - u
        if d > step:
            d = step
        elif d < -step:
            d = -step
        u += d
        out[k] = u


@njit(cache=True, nogil=True)
def column_ranges(a, k):
    """``max - min`` of each of the first `k` columns of `a` (rows in C
    order: one pass, where NumPy's two reductions along the rows of a
    column slice each make a pass of their own)."""
    n = a.shape[0]
    hi = np.empty(k)
    lo = np.empty(k)
    for j in range(k):
        hi[j] = -np.inf
        lo[j] = np.inf
    for i in range(n):
        for j in range(k):
            v = a[i, j]
            if v > hi[j]:
                hi[j] = v
            if v < lo[j]:
                lo[j] = v
    return hi - lo

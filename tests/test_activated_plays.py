"""Thermally activated plays (:class:`hystcomp.identify.parts.ActivatedPlays`):
viscous plays whose overstress relaxes by Eyring's sinh law,
``d|w - c|/dt = -(s / tau) sinh(|w - c| / s)``; Perzyna's linear law of
:class:`~hystcomp.identify.parts.ViscousPlays` below the overstress scale
``s``, far faster above it."""

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.optimize import brentq

from hystcomp.identify.parts import ActivatedPlays, Context
from test_viscous_plays import _columns, assert_named_with_part_and_inverts


def _eyring_ode(x, r, dt, tau, s):
    """Independent reference: each play's state obeys dz/dt = -(s/tau)
    sinh((z - c)/s) outside its band (c the nearest band edge, the input
    held over the sample).  The law is separable: the overstress E = |z -
    c|/s falls from E0 to E1 in the time tau * integral_{E1}^{E0} dE /
    sinh(E); E1 is where that time is dt (scipy's quad and brentq, not the
    closed form; dt = 1e-3 takes E down to no less than 1e-300 here)."""
    z = np.zeros(r.size)
    out = np.empty((x.size, r.size))
    for k, xk in enumerate(x):
        for i, ri in enumerate(r):
            if ri == 0.0:
                z[i] = xk
                continue
            c = min(max(z[i], xk - ri), xk + ri)
            e0 = abs(z[i] - c) / s
            if e0 > 0.0:
                # in u = ln E the integrand E / sinh(E) is smooth and bounded
                def late(u1):
                    return tau * quad(lambda u: np.exp(u) / np.sinh(np.exp(u)), u1, np.log(e0), epsabs=1e-14,
                                      epsrel=1e-13, limit=200)[0] - dt
                u1 = brentq(late, -700.0, np.log(e0), xtol=1e-14, rtol=1e-14)
                z[i] = c + np.sign(z[i] - c) * s * np.exp(u1)
        out[k] = z
    return out


def test_the_kernel_follows_eyrings_law():
    rng = np.random.default_rng(11)
    dt = 1e-3
    x = np.cumsum(rng.normal(0, 0.03, 150))
    x /= np.max(np.abs(x))
    r = np.array([0.0, 0.1, 0.3, 0.6])
    for tau, s in ((5e-3, 0.02), (2e-2, 0.1)):
        got = _columns(x, r, np.exp(-dt / tau), s)
        # the closed form per sample against the law solved by quadrature and
        # root finding: 1e-9 of the input scale (the root is found to 1e-14
        # relative each sample; 150 samples carry it forward)
        np.testing.assert_allclose(got, _eyring_ode(x, r, dt, tau, s), rtol=0, atol=1e-9)


def test_a_large_overstress_scale_is_the_viscous_play_and_a_large_overstress_relaxes_faster():
    dt, tau = 1e-3, 1e-2
    t = np.arange(2000) * dt
    x = np.sin(2 * np.pi * 3.0 * t)
    r = np.linspace(0.0, 0.8, 6)
    linear = _columns(x, r, np.exp(-dt / tau), 0.0)
    # s far above every overstress (at most 2: sinh(E) = E (1 + E^2 / 6 + ...),
    # E <= 2e-4): Perzyna's law to 1e-8
    np.testing.assert_allclose(_columns(x, r, np.exp(-dt / tau), 1e4), linear, rtol=0, atol=1e-8)
    # s small: the states stay closer to their bands than the linear law's
    band = np.clip(linear, x[:, None] - r, x[:, None] + r)
    eyr = _columns(x, r, np.exp(-dt / tau), 0.02)
    band_e = np.clip(eyr, x[:, None] - r, x[:, None] + r)
    lag_lin = np.abs(linear - band)[:, 1:].max()
    lag_eyr = np.abs(eyr - band_e)[:, 1:].max()
    # measured: 0.175 (linear) against 0.082 (Eyring, s = 0.02)
    assert lag_eyr < 0.6 * lag_lin, (lag_eyr, lag_lin)


def test_the_part_sets_its_options_within_bounds():
    ctx = Context(np.sin(np.linspace(0, 20, 4000)), 1e-3, 0.0, 1.0, 4.0)
    part = ActivatedPlays()
    tau, s = part.parameters(ctx, set())
    assert tau.name == "time_constant" and s.name == "overstress_scale" and s.log
    for start in part.initial_values(ctx, set()):
        assert tau.lower <= start["time_constant"] <= tau.upper and s.lower <= start["overstress_scale"] <= s.upper
    opts = {}
    part.core_options({"time_constant": 1e-3, "overstress_scale": 0.03}, ctx, opts)
    assert opts["decay"] == pytest.approx(np.exp(-1.0)) and opts["overstress_scale"] == 0.03


def _activated_record(seed=0):
    """200 plays of a decaying threshold density whose overstress relaxes
    by Eyring's law (tau = 20 ms at the scale s = 1.5 V; integrated here by
    RK4 in 8 sub-steps a sample, not hystcomp's closed form) beside a linear
    part, under a two-tone drive whose amplitude and speed vary (0.4 and
    6 Hz), 10 s at 2 kHz, output noise 0.2 % of the span."""
    rng = np.random.default_rng([seed, 7311])
    dt, n = 5e-4, 20_000
    t = np.arange(n) * dt
    env = 0.5 + 0.5 * np.sin(2 * np.pi * t / 10.0) ** 2
    v = 45 * env * (0.7 * np.sin(2 * np.pi * 0.4 * t) + 0.3 * np.sin(2 * np.pi * 6.0 * t))
    r = np.linspace(0.5, 90.0, 200)
    wts = np.exp(-r / 30.0)
    tau, s, m = 0.02, 1.5, 8
    h = dt / m
    z = np.zeros(r.size)
    Z = np.empty((n, r.size))

    def f(u, c):
        return -(s / tau) * np.sinh((u - c) / s)

    for k in range(n):
        c = np.clip(z, v[k] - r, v[k] + r)
        for _ in range(m):
            k1 = f(z, c)
            k2 = f(z + 0.5 * h * k1, c)
            k3 = f(z + 0.5 * h * k2, c)
            k4 = f(z + h * k3, c)
            z = z + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
        Z[k] = z
    y = 0.3 * v + Z @ (wts / wts.sum())
    return t, v, y + 0.002 * np.ptp(y) * rng.standard_normal(n)


def test_activated_plays_are_named_rate_dependence_and_the_model_inverts():
    assert_named_with_part_and_inverts(*_activated_record(), "activated_plays")

"""Shared helpers of the test suite: plain-Python reference loops written from
the thesis's equations (W. Ye, mGPI thesis), independent of the compiled
kernels, and hypothesis settings.

The references below are deliberately naive: one Python loop per sample and
per operator, with ``math`` functions for the envelopes, so that a bug in the
numba kernels or in the NumPy envelope code cannot hide in both.
"""

import math
import os

import numpy as np
import pytest
from hypothesis import HealthCheck, settings

# Hypothesis: small, bounded runs (the machine is shared and noisy, so no
# per-example deadline; nothing here is a timing test).
settings.register_profile(
    "hystcomp",
    max_examples=40,
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large],
    derandomize=False,
)
# a long search for edge cases (not run by default): HYSTCOMP_HYPOTHESIS=long pytest tests/test_properties.py ...
settings.register_profile("hystcomp-long", parent=settings.get_profile("hystcomp"), max_examples=2000)
settings.load_profile("hystcomp-long" if os.environ.get("HYSTCOMP_HYPOTHESIS") == "long" else "hystcomp")


# ----------------------------------------------------------------------------
# scalar envelope functions written from their definitions (reference side)
# ----------------------------------------------------------------------------
def ref_tanh(a, b, c=0.0):
    """gamma(v) = a tanh(b v + c)."""
    return lambda x: a * math.tanh(b * x + c)


def ref_atanh(a, b, offset=0.0):
    """gamma(v) = a atanh(b v) + offset on |v| < 1/b; -inf/+inf outside
    (an operator boundary outside the domain never binds)."""

    def f(x):
        u = b * x
        if u <= -1.0:
            return -math.inf
        if u >= 1.0:
            return math.inf
        return a * math.atanh(u) + offset

    return f


def ref_poly(coeffs, lo, hi):
    """sum_k c_k v**k on [lo, hi]; -inf/+inf outside the closed interval."""

    def f(x):
        if x < lo:
            return -math.inf
        if x > hi:
            return math.inf
        return sum(c * x**k for k, c in enumerate(coeffs))

    return f


def ref_linear(k):
    return lambda x: k * x


def ident(x):
    return x


# ----------------------------------------------------------------------------
# operators, straight from the thesis's recursions
# ----------------------------------------------------------------------------
def ref_play(v, r, w0=None):
    """Play operator F_r, eq. 13: w(t) = max{v(t) - r, min{v(t) + r, w(t_i)}}.

    Returns an (n, N) list-of-lists matrix and the final state.
    """
    w = [0.0] * len(r) if w0 is None else [float(x) for x in w0]
    out = []
    for x in v:
        row = []
        for i, ri in enumerate(r):
            w[i] = max(x - ri, min(x + ri, w[i]))
            row.append(w[i])
        out.append(row)
    return np.array(out), np.array(w)


def ref_stop(v, r, e0=None, vprev=0.0):
    """Stop operator E_r, eq. 16: e(t) = e_r(v(t) - v(t_i) + e(t_i)),
    e_r(x) = min{r, max{-r, x}}; before the first sample v = 0, e = 0 so that
    e(0) = e_r(v(0)) (eq. 15)."""
    e = [0.0] * len(r) if e0 is None else [float(x) for x in e0]
    out = []
    for x in v:
        row = []
        for i, ri in enumerate(r):
            e[i] = min(ri, max(-ri, x - vprev + e[i]))
            row.append(e[i])
        vprev = x
        out.append(row)
    return np.array(out), np.array(e), vprev


def ref_generalized_play(v, r, gl, gr, w0=None):
    """Generalized play F^gamma_lr, eq. 20:
    w(t) = max{gl(v(t)) - r, min{gr(v(t)) + r, w(t_i)}}."""
    w = [0.0] * len(r) if w0 is None else [float(x) for x in w0]
    out = []
    for x in v:
        row = []
        for i, ri in enumerate(r):
            w[i] = max(gl(x) - ri, min(gr(x) + ri, w[i]))
            row.append(w[i])
        out.append(row)
    return np.array(out), np.array(w)


def ref_modified_play(v, r, gl, gr, w0=None):
    """Modified generalized play F^gamma_mr, eq. 23:
    w(t) = max{gl(v(t) - r), min{gr(v(t) + r), w(t_i)}}, w before t=0 is 0 (eq. 22)."""
    w = [0.0] * len(r) if w0 is None else [float(x) for x in w0]
    out = []
    for x in v:
        row = []
        for i, ri in enumerate(r):
            w[i] = max(gl(x - ri), min(gr(x + ri), w[i]))
            row.append(w[i])
        out.append(row)
    return np.array(out), np.array(w)


# ----------------------------------------------------------------------------
# models as sums of reference operators
# ----------------------------------------------------------------------------
def ref_pi(v, r, p, p0):
    """PI model, eq. 18 (discrete): p0 v + sum_i p_i F_{r_i}[v]."""
    w, _ = ref_play(v, r)
    return np.array([p0 * x + sum(pi * wi for pi, wi in zip(p, row)) for x, row in zip(v, w)])


def ref_mgpi(v, r, p, p0, gl, gr):
    """mGPI model, eq. 49: p0 F^gamma_m0[v] + sum_i p_i F^gamma_{m r_i}[v]."""
    r_all = [0.0] + list(r)
    p_all = [p0] + list(p)
    w, _ = ref_modified_play(v, r_all, gl, gr)
    return np.array([sum(pi * wi for pi, wi in zip(p_all, row)) for row in w])


def ref_gpi(v, r, p, gl, gr, H=None):
    """GPI model, eq. 21: H(v) + sum_i p_i F^gamma_{l r_i}[v]."""
    w, _ = ref_generalized_play(v, r, gl, gr)
    h = (lambda x: 0.0) if H is None else H
    return np.array([h(x) + sum(pi * wi for pi, wi in zip(p, row)) for x, row in zip(v, w)])


def ref_stop_pi(v, r, p, p0):
    """Stop-type PI: p0 v + sum_i p_i E_{r_i}[v]."""
    e, _, _ = ref_stop(v, r)
    return np.array([p0 * x + sum(pi * ei for pi, ei in zip(p, row)) for x, row in zip(v, e)])


# ----------------------------------------------------------------------------
# signals and fixtures
# ----------------------------------------------------------------------------
def test_signal(n=400, amp=3.0, seed=0):
    """A decaying, drifting, noisy oscillation: many minor loops and reversals."""
    rng = np.random.default_rng(seed)
    t = np.linspace(0.0, 10.0, n)
    return amp * np.sin(2 * np.pi * 0.7 * t) / (1 + 0.1 * t) + 0.3 * amp * np.sin(5.3 * t) * np.exp(-0.1 * t) \
        + 0.05 * amp * rng.standard_normal(n)


test_signal.__test__ = False  # a helper, not a test


@pytest.fixture
def rng():
    return np.random.default_rng(12345)

"""Properties of the PI family (hypothesis): rate independence, wiping-out,
counter-clockwise loops, Lipschitz bounds and exact inverses."""

import warnings

import numpy as np
import pytest
from hypothesis import assume, given
from hypothesis import strategies as st

from hystcomp import GPI, MGPI, PI, UnreachableWarning
from hystcomp.envelopes import Identity, Linear, Polynomial, Tanh

F = dict(allow_nan=False, allow_infinity=False)


@st.composite
def thresholds(draw, n_max=5, step_max=0.5):
    steps = draw(st.lists(st.floats(0.05, step_max, **F), min_size=1, max_size=n_max))
    return np.cumsum(steps)


@st.composite
def tanh_env(draw, c=False):
    return Tanh(draw(st.floats(1.0, 5.0, **F)), draw(st.floats(0.1, 1.0, **F)),
                draw(st.floats(-0.3, 0.3, **F)) if c else 0.0)


@st.composite
def poly_env(draw, c1_min=0.2):
    # gamma' = c1 + 2 c2 v + 3 c3 v^2 > 0 everywhere when c2^2 < 3 c1 c3
    c1 = draw(st.floats(c1_min, 2.0, **F))
    c3 = draw(st.floats(0.0, 0.1, **F))
    c2 = draw(st.floats(-0.9, 0.9, **F)) * np.sqrt(3 * c1 * c3)
    return Polynomial([0.0, c1, c2, c3], interval=(-8.0, 8.0))


def envelopes():
    return st.one_of(st.just(Identity()), tanh_env(), poly_env())


@st.composite
def models(draw, kinds=("PI", "MGPI", "MGPI_asym", "GPI")):
    kind = draw(st.sampled_from(kinds))
    r = draw(thresholds())
    p = np.array(draw(st.lists(st.floats(0.01, 1.0, **F), min_size=r.size, max_size=r.size)))
    p0 = draw(st.floats(0.1, 2.0, **F))
    if kind == "PI":
        return PI(r, p, p0)
    if kind == "MGPI":
        return MGPI(r, p, p0, envelope=draw(envelopes()))
    if kind == "MGPI_asym":
        return MGPI(r, p, p0, envelope_left=draw(envelopes()), envelope_right=draw(envelopes()))
    return GPI(r, p, draw(envelopes()), draw(envelopes()), H=Linear(p0))


def signals(lo=-5.0, hi=5.0, min_size=2, max_size=40):
    return st.lists(st.floats(lo, hi, **F), min_size=min_size, max_size=max_size).map(np.array)


# -- rate independence -----------------------------------------------------------
@given(models(), signals(), st.data())
def test_rate_independence(model, v, data):
    """Inserting repeated samples, or extra samples on the monotone segment
    between two samples (an increasing time reparametrisation), leaves the
    output at the original samples unchanged.  Exactly: with monotone inserted
    points the max/min of eqs. 13/20/23 pick the same floating-point values
    (rounding is monotone), so np.array_equal."""
    pieces, idx = [], []
    n = 0
    for k in range(v.size):
        if k > 0:
            a, b = v[k - 1], v[k]
            t = np.sort(np.array(data.draw(st.lists(st.floats(0.0, 1.0, **F), max_size=3))))
            mids = np.clip(a + t * (b - a), min(a, b), max(a, b))
            if b < a:
                mids = np.sort(mids)[::-1]
            else:
                mids = np.sort(mids)
            pieces.append(mids)
            n += mids.size
        reps = data.draw(st.integers(1, 3))
        pieces.append(np.full(reps, v[k]))
        idx.append(n + reps - 1)
        n += reps
    fine = np.concatenate(pieces)
    y = model.simulate(v)
    yf = model.simulate(fine)
    np.testing.assert_array_equal(yf[idx], y)


# -- wiping out ------------------------------------------------------------------
@given(models(kinds=("PI", "MGPI", "MGPI_asym")), signals(-3, 3, 1, 20), signals(-3, 3, 1, 20),
       signals(-1, 1, 1, 20))
def test_wiping_out(model, h1, h2, tail):
    """After the input reaches a new maximum A dominating all previous values
    (A - r_N > max |history|, so every operator is driven to its left
    boundary), the output no longer depends on the earlier history."""
    A = 3.0 + model.thresholds[-1] + 0.5          # <= 6 < 8, inside the polynomial domains
    rest = np.concatenate([[A], A * tail])        # afterwards anything within [-A, A]
    y1 = model.simulate(np.concatenate([h1, rest]))[h1.size:]
    y2 = model.simulate(np.concatenate([h2, rest]))[h2.size:]
    np.testing.assert_array_equal(y1, y2)


@given(models(kinds=("GPI",)), signals(-3, 3, 1, 20), signals(-3, 3, 1, 20), signals(-1, 1, 1, 20))
def test_wiping_out_gpi(model, h1, h2, tail):
    """For the generalized play the left boundary is gl(v) - r: the excursion
    must also give gl(A) - r_N above every previous operator output."""
    gl = model.envelope_left
    A = 6.0
    assume(gl(A) - model.thresholds[-1] > max(0.0, gl(3.0)))
    rest = np.concatenate([[A], A * tail])
    y1 = model.simulate(np.concatenate([h1, rest]))[h1.size:]
    y2 = model.simulate(np.concatenate([h2, rest]))[h2.size:]
    np.testing.assert_array_equal(y1, y2)


# -- counter-clockwise loops -------------------------------------------------------
@given(models(), st.lists(st.floats(-5, 5, **F), min_size=2, max_size=6))
def test_counter_clockwise_loops(model, waypoints):
    """Orientation convention: the input v on the horizontal axis, the output y
    on the vertical one; counter-clockwise means a positive shoelace area
    A = 1/2 sum (v_k y_{k+1} - v_{k+1} y_k).  For a periodic input the loop of
    the second period is closed and, for positive weights, A >= 0.

    The polygon joins samples by chords while the true path between two samples
    is monotone: it differs from the chord by at most half the step's box,
    |dv| |dy| / 2; fine sampling (30 samples per segment) keeps that slack
    small, and it is the only tolerance."""
    pts = [0.0, *waypoints, 0.0]
    period = np.concatenate([np.linspace(a, b, 30, endpoint=False) for a, b in zip(pts[:-1], pts[1:])])
    v = np.concatenate([period, period, period[:1]])
    y = model.simulate(v)
    vv, yy = v[period.size:], y[period.size:]
    # periodic after the first period: the loop closes
    assert yy[-1] == pytest.approx(yy[0], abs=1e-12 * (1 + abs(yy[0])))
    area = 0.5 * np.sum(vv[:-1] * yy[1:] - vv[1:] * yy[:-1])
    slack = 0.5 * np.sum(np.abs(np.diff(vv)) * np.abs(np.diff(yy))) + 1e-12
    assert area >= -slack, (area, slack)


# -- Lipschitz --------------------------------------------------------------------
@given(thresholds(), st.data(), signals())
def test_lipschitz_pi(r, data, v):
    """|y_k - y_{k-1}| <= L |v_k - v_{k-1}|, L = |p0| + sum |p_i| (any signs)."""
    p = np.array(data.draw(st.lists(st.floats(-1.0, 1.0, **F), min_size=r.size, max_size=r.size)))
    p0 = data.draw(st.floats(-2.0, 2.0, **F))
    y = PI(r, p, p0).simulate(v)
    L = abs(p0) + np.abs(p).sum()
    # rounding of ~N+1 terms of size <= L*10: 1e-12 absolute slack
    assert np.all(np.abs(np.diff(y)) <= L * np.abs(np.diff(v)) * (1 + 1e-12) + 1e-12)


def _sup_slope(env):
    if isinstance(env, Identity):
        return 1.0
    if isinstance(env, Tanh):
        return env.a * env.b
    # Polynomial with c3 >= 0: gamma' is a convex parabola, largest at an end
    return float(max(env.derivative(-8.0), env.derivative(8.0)))


@given(models(kinds=("MGPI", "MGPI_asym")), signals(-4.5, 4.5))
def test_lipschitz_mgpi(model, v):
    """mGPI with positive weights: L = sup |gamma'| (p0 + sum p_i) (gl, gr both)."""
    y = model.simulate(v)
    L = max(_sup_slope(model.envelope_left), _sup_slope(model.envelope_right)) * (model.p0 + model.weights.sum())
    scale = 1.0 + np.max(np.abs(y))
    assert np.all(np.abs(np.diff(y)) <= L * np.abs(np.diff(v)) * (1 + 1e-12) + 1e-13 * scale)


# -- PI o PI^-1 ---------------------------------------------------------------------
@given(thresholds(), st.data(), signals(), signals(-3, 3, 1, 10))
def test_pi_inverse_identity_both_orders(r, data, u, prefix):
    p = np.array(data.draw(st.lists(st.floats(-0.3, 1.0, **F), min_size=r.size, max_size=r.size)))
    p0 = data.draw(st.floats(0.2, 2.0, **F))
    assume(np.all(p0 + np.cumsum(p) > 0.1))
    m = PI(r, p, p0)
    inv = m.inverse()
    span = max(float(np.ptp(u)), 1e-3)
    # partial sums >= 0.1 bound the inverse weights by ~10: rounding of a few
    # dozen terms stays below 1e-12 of the span (brief's bound)
    tol = 1e-12 * max(span, 1.0)
    np.testing.assert_allclose(m.simulate(inv.simulate(u)), u, rtol=0, atol=tol)
    np.testing.assert_allclose(inv.simulate(m.simulate(u)), u, rtol=0, atol=tol)
    # non-zero initial state, mapped by inverse_state
    _, s = m.simulate(prefix, return_state=True)
    si = m.inverse_state(s)
    np.testing.assert_allclose(inv.simulate(m.simulate(u, initial_state=s), initial_state=si), u, rtol=0, atol=tol)
    np.testing.assert_allclose(m.simulate(inv.simulate(u, initial_state=si), initial_state=s), u, rtol=0, atol=tol)


# -- exact inverse ---------------------------------------------------------------------
def _reach(model, comp):
    """Outputs reachable from any state: at the input limits every operator is
    at least at its boundary there (eq. 23), so targets inside
    [p0 gr(lo) + sum p_i gr(lo + r_i), p0 gl(hi) + sum p_i gl(hi - r_i)] are
    reachable whatever the history (with the max below when gl lies above gr)."""
    lo, hi = comp.input_limits
    lo, hi = max(lo, -50.0), min(hi, 50.0)   # unbounded (Identity) sides: any target, use +-50
    r, p, p0 = model.thresholds, model.weights, model.p0
    gl, gr = model.envelope_left, model.envelope_right
    lo_d, hi_d = gl.domain
    up = p0 * gl(hi) + np.sum(p * gl(np.clip(hi - r, lo_d, hi_d)))
    # at the lower limit w = max{gl(lo - r), min{gr(lo + r), w}} <= max{gl(lo - r), gr(lo + r)}
    # (gl may lie above gr there, e.g. Tanh(1, .) left and Tanh(2, .) right)
    def upper_at_lo(x_l, x_r):
        return max(float(gl(np.clip(x_l, *gl.domain))), float(gr(np.clip(x_r, *gr.domain))))

    down = p0 * upper_at_lo(lo, lo) + sum(pi * upper_at_lo(lo - ri, lo + ri) for ri, pi in zip(r, p))
    return down, up


def _may_jump(model):
    """Whether the model's output can jump: envelopes that cross (the left one
    above the right one somewhere) of which one has a bounded domain, where its
    boundary stops binding (see test_exact_inverse_target_in_a_jump)."""
    gl, gr = model.envelope_left, model.envelope_right
    if gl is gr or not any(np.isfinite(e.domain).any() for e in (gl, gr)):
        return False
    lo, hi = max(gl.domain[0], gr.domain[0], -50.0), min(gl.domain[1], gr.domain[1], 50.0)
    x = np.linspace(lo, hi, 2001)[1:-1]
    return bool(np.any(gl(x) > gr(x)))


@given(models(kinds=("MGPI", "MGPI_asym")), st.lists(st.floats(-1.0, 1.0, **F), min_size=1, max_size=40))
def test_exact_inverse_composition(model, shape):
    # a model whose output jumps has targets no input reaches (tested apart)
    assume(not _may_jump(model))
    comp = model.exact_inverse()
    down, up = _reach(model, comp)
    assert down < 0 < up
    u = np.array(shape) * 0.9 * np.where(np.array(shape) > 0, up, -down)
    with warnings.catch_warnings():
        warnings.simplefilter("error", UnreachableWarning)
        v = comp.simulate(u)
    assert comp.last_unreachable == (0, -1)
    span = max(float(np.ptp(u)), float(up - down) * 1e-3)
    # the per-sample solve stops at 1e-14 relative; 1e-9 of the span (brief's
    # bound) leaves room for flat (saturated / v^3-like) envelopes
    np.testing.assert_allclose(model.simulate(v), u, rtol=0, atol=1e-9 * span)


@given(st.floats(1.0, 5.0, **F), st.floats(0.1, 1.0, **F), st.floats(1.0, 5.0, **F), thresholds(), st.data())
def test_exact_inverse_unreachable_targets(a_l, b_l, a_r, r, data):
    p = np.array(data.draw(st.lists(st.floats(0.01, 1.0, **F), min_size=r.size, max_size=r.size)))
    model = MGPI(r, p, 1.0, envelope_left=Tanh(a_l, b_l), envelope_right=Tanh(a_r, 0.5))
    lo, hi = model.output_bounds()
    n = 30
    u = np.array(data.draw(st.lists(st.floats(-0.5, 0.5, **F), min_size=n, max_size=n))) * min(a_l, a_r) * (1 + p.sum())
    bad = sorted(data.draw(st.sets(st.integers(0, n - 1), min_size=1, max_size=5)))
    for k in bad:
        u[k] = 1.5 * hi if k % 2 else 1.5 * lo
    comp = model.exact_inverse()
    with pytest.warns(UnreachableWarning, match=f"{len(bad)} of {n} targets"):
        v = comp.simulate(u)
    assert comp.last_unreachable == (len(bad), bad[0])
    y = model.simulate(v)
    ok = np.setdiff1d(np.arange(n), bad)
    np.testing.assert_allclose(y[ok], u[ok], rtol=0, atol=1e-9 * (hi - lo))
    assert np.all(y <= hi) and np.all(y >= lo)
    with pytest.raises(ValueError, match=f"first at sample index {bad[0]}"):
        model.exact_inverse(on_unreachable="raise").simulate(u)


@given(st.floats(0.0, 1e-3, **F), st.floats(0.05, 0.5, **F), thresholds(), st.data())
def test_exact_inverse_flat_slope_at_zero(eps, c3, r, data):
    """gamma = c3 v^3 + eps v: gamma'(0) = eps tiny or 0; the recipe raises for
    eps = 0 (beta'(0) infinite) but the exact inverse still inverts."""
    p = np.array(data.draw(st.lists(st.floats(0.01, 1.0, **F), min_size=r.size, max_size=r.size)))
    model = MGPI(r, p, 1.0, envelope=Polynomial([0.0, eps, 0.0, c3], interval=(-6.0, 6.0)))
    if eps == 0.0:
        with pytest.raises(ValueError, match="exact_inverse"):
            model.inverse()
    comp = model.exact_inverse()
    v = np.array(data.draw(st.lists(st.floats(-5.0, 5.0, **F), min_size=2, max_size=40)))
    u = model.simulate(v)        # reachable by construction
    span = max(float(np.ptp(u)), 1e-6)
    np.testing.assert_allclose(model.simulate(comp.simulate(u)), u, rtol=0, atol=1e-9 * max(span, 1.0))


@given(st.floats(1.0, 5.0, **F), st.floats(0.1, 1.0, **F), st.floats(0.2, 2.0, **F), thresholds(), st.data())
def test_gpi_analytic_inverse_exact(a, b, k, r, data):
    """GPI with gl = gr = gamma and H = k gamma is PI[gamma(v)]: GPIInverse is exact."""
    p = np.array(data.draw(st.lists(st.floats(0.0, 1.0, **F), min_size=r.size, max_size=r.size)))
    g = Tanh(a, b)
    gpi = GPI(r, p, g, g, H=Tanh(k * a, b))
    inv = gpi.inverse()
    # reachable targets: outputs of the model for inputs with |b v| <= 2 (where
    # atanh is well conditioned: gamma' >= 0.07 a b)
    v = np.array(data.draw(st.lists(st.floats(-2.0, 2.0, **F), min_size=2, max_size=40))) / b
    u = gpi.simulate(v)
    back = inv.simulate(u)
    span = max(float(np.ptp(u)), 1.0)
    # PI^-1 is exact to rounding; gamma^-1 then gamma again: 1e-9 of the span
    np.testing.assert_allclose(gpi.simulate(back), u, rtol=0, atol=1e-9 * span)
    # and the inverse recovers the input itself (gamma strictly increasing)
    np.testing.assert_allclose(back, v, rtol=0, atol=1e-7 * (1 + np.max(np.abs(v))))
    assert inv.last_unreachable == (0, -1)

"""Property tests for the corners of issue 12 (point 4).

Every property compares the package with an independent plain-Python/numpy
formula written out here (the play recursion, the relay, the definition of
the generalized play), on inputs that sit exactly on the places where a
rounding or a sign goes wrong: thresholds, grid points (Preisach/KP cell
centres and edges), the ends of an envelope's domain and range, 1e18 and
1e-300.  Then every model's ``to_dict``/``from_dict`` with each key missing
in turn, and the round trip (equal, equal hash, also across 0.0 / -0.0).
"""

import json

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import hystcomp.effects as eff
from hystcomp import GPI, KP, MGPI, PI, Atanh, BacklashLike, BoucWen, Linear, Polynomial, Preisach, StopPI, Tanh
from hystcomp.envelopes import envelope_from_dict
from hystcomp.models import model_from_dict

FAST = settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])

HUGE, TINY = 1e18, 1e-300


# --------------------------------------------------------------------------
# independent references
# --------------------------------------------------------------------------
def play_positions(v, r, z0):
    """The classical play, eq. 13, written out: z <- max(v - r, min(v + r, z))."""
    z = np.array(z0, dtype=float)
    out = np.empty((len(v), len(r)))
    for k, x in enumerate(v):
        z = np.maximum(x - r, np.minimum(x + r, z))
        out[k] = z
    return out


def scale(*terms):
    """Sum of magnitudes of the terms of a weighted sum, per sample: the
    rounding of a sum in another order is a few eps of it."""
    return sum(np.abs(t) for t in terms)


# a model sums N + 1 terms in its own order: 1e-13 of the sum of magnitudes
# is ~ 500 eps, far above N eps for N <= 4 and far below any real defect
RTOL = 1e-13


def thresholds_st(max_size=4):
    return st.lists(st.floats(0.05, 3.0), min_size=1, max_size=max_size, unique=True).map(
        lambda r: np.array(sorted(r))).filter(lambda r: np.all(np.diff(r) > 1e-6))


# --------------------------------------------------------------------------
# PI: inputs exactly on thresholds and their sums, 1e18, 1e-300
# --------------------------------------------------------------------------
@FAST
@given(r=thresholds_st(), data=st.data())
def test_pi_on_thresholds_and_extremes_matches_the_play(r, data):
    n = r.size
    p = np.array(data.draw(st.lists(st.floats(-0.5, 1.0), min_size=n, max_size=n)))
    p0 = data.draw(st.floats(0.1, 2.0))
    special = sorted({0.0, HUGE, -HUGE, TINY, -TINY} | {s * k * x for x in r for k in (1, 2) for s in (1, -1)}
                     | {a + b for a in r for b in r} | {a - b for a in r for b in r})
    v = np.array(data.draw(st.lists(st.sampled_from(special) | st.floats(-8.0, 8.0), min_size=1, max_size=25)))
    m = PI(r, p, p0)
    y, state = m.simulate(v, return_state=True)
    z = play_positions(v, r, np.zeros(n))
    expected = p0 * v + z @ p
    assert np.all(np.abs(y - expected) <= RTOL * scale(p0 * v, *(z * p).T))
    # the state is the play positions themselves: the same max/min, bit for bit
    assert np.array_equal(state, z[-1])


@FAST
@given(r=thresholds_st(), data=st.data())
def test_stop_pi_on_thresholds_matches_v_minus_play(r, data):
    n = r.size
    p = np.array(data.draw(st.lists(st.floats(0.0, 1.0), min_size=n, max_size=n)))
    special = sorted({0.0, TINY, -TINY} | {s * k * x for x in r for k in (1, 2) for s in (1, -1)})
    v = np.array(data.draw(st.lists(st.sampled_from(special) | st.floats(-8.0, 8.0), min_size=1, max_size=25)))
    m = StopPI(r, p, 1.0)
    stops = v[:, None] - play_positions(v, r, np.zeros(n))      # the stop is v - play (eq. 16)
    expected = v + stops @ p
    # the stop is computed incrementally (s <- clip(s + dv, -r, r)): it rounds at
    # the scale of the input history, eps * max |v| per step
    atol = 1e-13 * np.maximum.accumulate(np.abs(v)) * (1.0 + np.abs(p).sum())
    assert np.all(np.abs(m.simulate(v) - expected) <= atol)
    # every stop stays in [-r, r]
    assert np.all(np.abs(stops) <= r + 1e-13 * np.maximum.accumulate(np.abs(v))[:, None])


# --------------------------------------------------------------------------
# symmetric mGPI: envelope ranges that contain 0, start or end at 0, or
# exclude it; inputs on the domain's ends; initial states on the ends
# --------------------------------------------------------------------------
POLY_CASES = {
    # name: gamma(0) as a function of (c1, c2) of gamma(v) = c0 + c1 v + c2 v^2 on [0, 10]
    "range starts at 0": lambda c1, c2: 0.0,
    "range excludes 0 (above)": lambda c1, c2: 1.0,
    "range ends at 0": lambda c1, c2: -(10 * c1 + 100 * c2),
    "range excludes 0 (below)": lambda c1, c2: -(10 * c1 + 100 * c2) - 1.0,
    "0 at v = 5": lambda c1, c2: -(5 * c1 + 25 * c2),
}


def _virgin_position(coeffs):
    """Where the play starts, from the definition: gamma^-1(0) if 0 is inside
    gamma's range, else the end of the domain where gamma is nearest 0."""
    lo, hi = np.polynomial.polynomial.polyval([0.0, 10.0], coeffs)
    if lo < 0.0 < hi:
        roots = np.roots(np.asarray(coeffs)[::-1])
        roots = roots[np.isreal(roots)].real
        # "range ends at 0" may leave gamma(10) = +1e-15 after rounding: a root at 10 + 1e-15
        return float(np.clip(roots[(roots >= -1e-9) & (roots <= 10 + 1e-9)][0], 0.0, 10.0))
    return 10.0 if hi <= 0.0 else 0.0


@FAST
@given(case=st.sampled_from(sorted(POLY_CASES)), c1=st.floats(0.2, 2.0), c2=st.sampled_from([0.0, 0.05, 0.3]),
       r=thresholds_st(3), data=st.data())
def test_mgpi_polynomial_envelope_matches_gamma_of_the_play(case, c1, c2, r, data):
    coeffs = [POLY_CASES[case](c1, c2), c1, c2]
    g = Polynomial(coeffs, interval=(0.0, 10.0))
    n = r.size
    p = np.array(data.draw(st.lists(st.floats(-0.3, 1.0), min_size=n, max_size=n)))
    special = sorted({0.0, 10.0, 5.0, TINY} | {x for x in r} | {10.0 - x for x in r} | {2 * x for x in r})
    v = np.array(data.draw(st.lists(st.sampled_from(special) | st.floats(0.0, 10.0), min_size=1, max_size=20)))
    m = MGPI(r, p, 0.7, envelope=g)
    z0 = np.full(n, _virgin_position(coeffs))
    assert np.allclose(m.default_state(), z0, rtol=0, atol=1e-12)
    gamma = lambda x: np.polynomial.polynomial.polyval(x, coeffs)  # noqa: E731
    z = play_positions(v, r, z0)
    expected = 0.7 * gamma(v) + gamma(z) @ p
    # gamma evaluated in another order (Horner vs. powers): 1e-12 of the magnitudes
    assert np.all(np.abs(m.simulate(v) - expected) <= 1e-12 * (scale(0.7 * gamma(v), *(gamma(z) * p).T) + 1))

    # an explicit initial state on either end of gamma's (closed) domain
    zs = np.array(data.draw(st.lists(st.sampled_from([0.0, 10.0]), min_size=n, max_size=n)))
    z = play_positions(v, r, zs)
    expected = 0.7 * gamma(v) + gamma(z) @ p
    got = m.simulate(v, initial_state=zs)
    assert np.all(np.abs(got - expected) <= 1e-12 * (scale(0.7 * gamma(v), *(gamma(z) * p).T) + 1))


@FAST
@given(a=st.floats(0.5, 5.0), b=st.floats(0.2, 3.0), c=st.floats(-2.0, 2.0), r=thresholds_st(3), data=st.data())
def test_mgpi_tanh_with_offset_matches_gamma_of_the_play(a, b, c, r, data):
    n = r.size
    p = np.array(data.draw(st.lists(st.floats(-0.3, 1.0), min_size=n, max_size=n)))
    z0 = -c / b                    # tanh(b z + c) = 0: the virgin play position
    special = sorted({0.0, z0, HUGE, -HUGE, TINY, -TINY} | {z0 + s * x for x in r for s in (1, -1, 2, -2)})
    v = np.array(data.draw(st.lists(st.sampled_from(special) | st.floats(-6.0, 6.0), min_size=1, max_size=20)))
    m = MGPI(r, p, 1.3, envelope=Tanh(a, b, c))
    gamma = lambda x: a * np.tanh(b * x + c)  # noqa: E731
    z = play_positions(v, r, np.full(n, z0))
    expected = 1.3 * gamma(v) + gamma(z) @ p
    y = m.simulate(v)
    assert np.all(np.isfinite(y))
    # tanh evaluated at b z + c computed in another order: 1e-12 relative
    assert np.all(np.abs(y - expected) <= 1e-12 * (scale(1.3 * gamma(v), *(gamma(z) * p).T) + 1))
    # the output never leaves the bound of eq. 29
    lo, hi = m.output_bounds()
    assert np.all((y >= lo - 1e-12 * abs(lo)) & (y <= hi + 1e-12 * abs(hi)))


@FAST
@given(b=st.floats(0.2, 2.0), offset=st.floats(-1.0, 1.0), side=st.sampled_from([-1.0, 1.0]))
def test_state_on_an_open_domain_end_is_refused(b, offset, side):
    # Atanh's domain is open: a play position on its end would make gamma infinite
    g = Atanh(1.0, b, offset=offset)
    lo, hi = g.domain
    m = MGPI([0.5, 1.0], [0.5, 0.25], 1.0, envelope=g)
    edge = hi if side > 0 else lo
    with pytest.raises(ValueError, match="initial_state"):
        m.simulate([0.5 * (lo + hi)], initial_state=[edge, 0.5 * (lo + hi)])
    # just inside the end it is a valid state and the output is finite
    inside = edge - side * 1e-9 * (hi - lo)
    assert np.all(np.isfinite(m.simulate([0.5 * (lo + hi)], initial_state=[inside, 0.5 * (lo + hi)])))


# --------------------------------------------------------------------------
# GPI: the generalized play of eq. 20, written out; the bounds it reports
# --------------------------------------------------------------------------
@FAST
@given(al=st.floats(1.0, 12.0), bl=st.floats(0.2, 2.0), ar=st.floats(1.0, 12.0), br=st.floats(0.2, 2.0),
       c=st.floats(-1.0, 1.0), r=thresholds_st(3), with_h=st.booleans(), data=st.data())
def test_gpi_matches_the_generalized_play_and_stays_in_its_bounds(al, bl, ar, br, c, r, with_h, data):
    n = r.size
    p = np.array(data.draw(st.lists(st.floats(-0.3, 1.0), min_size=n, max_size=n)))
    gl = lambda x: al * np.tanh(bl * x + c)  # noqa: E731
    gr = lambda x: ar * np.tanh(br * x)  # noqa: E731
    H = Tanh(0.5, 1.0) if with_h else None
    m = GPI(r, p, Tanh(al, bl, c), Tanh(ar, br), H=H)
    special = sorted({0.0, HUGE, -HUGE, TINY, -TINY} | {s * x for x in r for s in (1, -1, 2, -2)})
    v = np.array(data.draw(st.lists(st.sampled_from(special) | st.floats(-6.0, 6.0), min_size=1, max_size=20)))
    w = np.zeros(n)
    rows = []
    for x in v:
        w = np.maximum(gl(x) - r, np.minimum(gr(x) + r, w))
        rows.append(w.copy())
    W = np.array(rows)
    h = 0.5 * np.tanh(v) if with_h else np.zeros_like(v)
    expected = h + W @ p
    y = m.simulate(v)
    assert np.all(np.abs(y - expected) <= 1e-12 * (scale(h, *(W * p).T) + 1))
    lo, hi = m.output_bounds()
    assert np.all((y >= lo - 1e-12 * abs(lo)) & (y <= hi + 1e-12 * abs(hi))), (y.min(), y.max(), lo, hi)


# --------------------------------------------------------------------------
# Preisach: relays switching exactly on the cell centres; KP: continuity
# across centres and edges; both saturate with the right sign at +-1e18
# --------------------------------------------------------------------------
def plane_st():
    return st.tuples(st.integers(2, 6), st.floats(-3.0, 0.5), st.floats(0.5, 4.0), st.integers(0, 2**31 - 1))


def _plane(n, lo, width, seed, cls):
    mu = np.tril(np.random.default_rng(seed).uniform(0.0, 1.0, (n, n)))
    return cls((lo, lo + width), mu, offset=0.25), mu


def _grid_inputs(m, data, size=25):
    e = m.v_min + np.arange(m.n + 1) * m.h
    special = sorted(set(m.levels.tolist()) | set(e.tolist()) | {0.0, TINY, -TINY, m.v_min - 1.0, m.v_max + 1.0})
    return np.array(data.draw(st.lists(st.sampled_from(special), min_size=1, max_size=size)))


@FAST
@given(plane=plane_st(), data=st.data())
def test_preisach_relays_switch_exactly_on_the_cell_centres(plane, data):
    m, mu = _plane(*plane, Preisach)
    c = m.levels
    v = _grid_inputs(m, data)
    # relay (i, j), alpha = c_i >= beta = c_j: +1 after v >= alpha, -1 after v < beta;
    # the demagnetised start has it up iff alpha + beta <= 0
    i, j = np.tril_indices(m.n)
    state = np.where(c[i] + c[j] <= 0.0, 1.0, -1.0)
    expected = []
    for x in v:
        state = np.where(x >= c[i], 1.0, np.where(x < c[j], -1.0, state))
        expected.append(0.25 + state @ mu[i, j])
    # the same relays summed in another order: 1e-13 of the weight sum
    np.testing.assert_allclose(m.simulate(v), expected, rtol=0, atol=1e-13 * mu.sum())


@FAST
@given(plane=plane_st(), cls=st.sampled_from([Preisach, KP]), data=st.data())
def test_plane_models_saturate_with_the_sign_of_huge_inputs(plane, cls, data):
    m, mu = _plane(*plane, cls)
    v = np.array(data.draw(st.lists(st.sampled_from([HUGE, -HUGE, 1e300, -1e300, TINY, 0.0]), min_size=1,
                                    max_size=8)) + [data.draw(st.sampled_from([HUGE, -HUGE]))])
    y = m.simulate(v)
    assert np.all(np.isfinite(y))
    # all relays up after +1e18, all down after -1e18 (1e-13 of the weight sum: summation order)
    assert abs(y[-1] - (0.25 + np.sign(v[-1]) * mu.sum())) <= 1e-13 * mu.sum()


@FAST
@given(plane=plane_st(), data=st.data())
def test_kp_is_continuous_across_centres_and_edges(plane, data):
    m, mu = _plane(*plane, KP)
    v = _grid_inputs(m, data)
    delta = 1e-7 * m.h
    shifted = v + delta * np.array(data.draw(st.lists(st.sampled_from([-1.0, 1.0]), min_size=v.size,
                                                      max_size=v.size)))
    # each KP operator is a ramp of slope 2/h fed by a play (1-Lipschitz in the
    # sup norm): a shift of at most delta moves the output by at most
    # 2 delta / h * sum mu, plus rounding (1e-12 of the weight sum)
    bound = 2.0 * delta / m.h * mu.sum() + 1e-12 * mu.sum()
    assert np.max(np.abs(m.simulate(v) - m.simulate(shifted))) <= bound


# --------------------------------------------------------------------------
# to_dict / from_dict: every key missing in turn, round trips, hashes
# --------------------------------------------------------------------------
def _models(zero):
    """One model of each registered type; `zero` is 0.0 or -0.0 in every
    parameter that may be 0 (equal models, bit-different descriptions)."""
    lag = eff.LinearStage.lag(0.01, 1e-3)
    return [
        PI([0.5, 1.0], [0.4, 0.2], 1.0 + zero),
        PI([0.5, 1.0], [0.4, zero], zero),
        StopPI([0.5], [0.4], zero),
        MGPI([0.5], [0.4], 1.0, envelope=Tanh(2.0, 1.0, zero)),
        MGPI([0.5], [0.4], 1.0, envelope=Atanh(2.0, 0.5, offset=zero)),
        MGPI([0.5], [0.4], 1.0, envelope=Polynomial([zero, 1.0], interval=(zero, 10.0))),
        MGPI([0.5], [0.4], 1.0, envelope_left=Tanh(2.0, 1.0, zero), envelope_right=Linear(3.0)),
        GPI([0.5], [0.4], Tanh(2.0, 1.0), Tanh(3.0, 1.0, zero), H=Tanh(1.0, 1.0, zero)),
        Preisach((-1.0, 1.0), np.tril(np.ones((3, 3))), zero),
        KP((-1.0, 1.0), np.tril(np.ones((3, 3))), zero),
        BoucWen(1.0, 0.6, 0.2, 1.0, 0.5, offset=zero),
        BacklashLike(1.0, 3.0, 1.0, offset=zero),
        lag,
        eff.RateDependentPI([0.5], [0.5], 1.0, zero, 1e-3),
        eff.CreepOperator([0.1], [0.01], 0.01),
        eff.DriftTerm(0.5, [0.1, zero], [0.2], [1.0]),
        eff.Series(PI([0.5], [0.5], zero), lag),
        eff.Parallel(PI([0.5], [0.5], 1.0), lag, offset=zero),
    ]


# keys a description may leave out: the constructor's default is then used
# (schema 1 files written before the key existed stay readable)
OPTIONAL = {
    "GPI": {"H": None}, "Preisach": {"offset": 0.0}, "KP": {"offset": 0.0},
    "BoucWen": {"gain": 0.0, "offset": 0.0, "sign": 1}, "BacklashLike": {"offset": 0.0},
    "LinearStage": {"kind": "custom", "parameters": None}, "Parallel": {"offset": 0.0},
}

MODEL_IDS = [f"{type(m).__name__}-{k}" for k, m in enumerate(_models(0.0))]


@pytest.mark.parametrize("k", range(len(MODEL_IDS)), ids=MODEL_IDS)
def test_round_trip_is_equal_with_equal_hash(k):
    m, m_neg = _models(0.0)[k], _models(-0.0)[k]
    for d in (m.to_dict(), json.loads(json.dumps(m.to_dict())), m.to_json() if hasattr(m, "to_json") else None):
        if d is None:
            continue
        back = model_from_dict(d)
        assert back == m and hash(back) == hash(m)
        assert back.to_dict() == m.to_dict()
    # 0.0 and -0.0: equal models, equal hashes, interchangeable as dict keys
    assert m_neg == m and hash(m_neg) == hash(m)
    assert {m: 1}[m_neg] == 1
    v = 0.45 * (1.0 + np.sin(np.linspace(0.0, 6.0, 50)))    # in every domain here
    np.testing.assert_array_equal(model_from_dict(m.to_dict()).simulate(v), m.simulate(v))


@pytest.mark.parametrize("k", range(len(MODEL_IDS)), ids=MODEL_IDS)
def test_each_missing_key_is_named_or_defaulted(k):
    m = _models(0.0)[k]
    d = m.to_dict()
    name = d["model"]
    for key in d:
        partial = {kk: vv for kk, vv in d.items() if kk != key}
        optional = OPTIONAL.get(name, {})
        if key in optional:
            rebuilt = model_from_dict(partial)
            assert rebuilt == model_from_dict({**d, key: optional[key]}), key
            continue
        with pytest.raises(ValueError) as exc:
            model_from_dict(partial)
        assert repr(key) in str(exc.value) or key in str(exc.value), (key, str(exc.value))


ENVELOPES = [Tanh(2.0, 1.0, 0.5), Atanh(1.0, 0.5, offset=0.2), Linear(3.0),
             Polynomial([0.0, 1.0, 0.0, 0.5], interval=(-2.0, 2.0))]


@pytest.mark.parametrize("env", ENVELOPES, ids=lambda e: type(e).__name__)
def test_envelope_dicts_name_a_missing_key(env):
    d = env.to_dict()
    back = envelope_from_dict(d)
    assert back == env and hash(back) == hash(env)
    for key in d:
        partial = {kk: vv for kk, vv in d.items() if kk != key}
        try:
            rebuilt = envelope_from_dict(partial)
        except (ValueError, TypeError) as exc:
            assert key in str(exc), (key, str(exc))
        else:
            # a key with a default (Tanh's c, Atanh's offset, Polynomial's interval)
            # rebuilds the envelope with that default
            defaults = {"c": 0.0, "offset": 0.0, "interval": [-1.0, 1.0]}
            assert key in defaults, key
            assert rebuilt == envelope_from_dict({**d, key: defaults[key]}), key


# --------------------------------------------------------------------------
# chunks and inverses at the corners
# --------------------------------------------------------------------------
@settings(max_examples=25, deadline=None)
@given(k=st.integers(0, len(MODEL_IDS) - 1), data=st.data())
def test_chunked_run_equals_one_shot_on_corner_inputs(k, data):
    # inputs on the thresholds (0.5), the grids' centres and edges (+-1/3, +-2/3, 1 for
    # the 3-cell plane on [-1, 1]), 0, 1e-300 and the domains' ends used above
    m = _models(0.0)[k]
    corners = [0.0, TINY, 0.5, 0.4, 0.9, 1.0 / 3.0, 2.0 / 3.0, 1.0, 0.25]
    v = np.array(data.draw(st.lists(st.sampled_from(corners) | st.floats(0.0, 0.95), min_size=2, max_size=30)))
    cut = data.draw(st.integers(1, v.size - 1))
    whole = m.simulate(v)
    first, state = m.simulate(v[:cut], return_state=True)
    rest = m.simulate(v[cut:], initial_state=state)
    # the same arithmetic sample by sample: bit-identical
    np.testing.assert_array_equal(np.concatenate([first, rest]), whole)


@FAST
@given(r=thresholds_st(), data=st.data())
def test_pi_exact_inverse_on_its_own_thresholds_and_huge_targets(r, data):
    n = r.size
    p = np.array(data.draw(st.lists(st.floats(0.0, 1.0), min_size=n, max_size=n)))
    m = PI(r, p, data.draw(st.floats(0.2, 2.0)))
    phi = m.loading_curve(r)          # the inverse's thresholds are phi(r_i) (eq. 52)
    special = sorted({0.0, TINY, -TINY, HUGE, -HUGE} | {s * k * x for x in phi for k in (1, 2) for s in (1, -1)})
    u = np.array(data.draw(st.lists(st.sampled_from(special) | st.floats(-10.0, 10.0), min_size=1, max_size=20)))
    back = m.simulate(m.exact_inverse().simulate(u))
    # composition of two weighted sums: 1e-12 of the largest target so far, plus
    # the inverse kernel's absolute bracket tolerance, ~1e-15 in v, times the
    # largest slope (see the scale test below): 1e-14 (1 + slope)
    slope = m.p0 + p.sum()
    assert np.all(np.abs(back - u) <= 1e-12 * np.maximum.accumulate(np.abs(u)) + 1e-14 * (1 + slope))


def _scaled_models(s):
    return [PI(np.array([0.5, 1.0, 1.5]) * s, [0.3, 0.2, 0.1], 1.0), StopPI(np.array([0.5, 1.0]) * s, [0.3, 0.2], 1.0),
            MGPI(np.array([0.5, 1.0, 1.5]) * s, [0.3, 0.2, 0.1], 1.0, envelope=Tanh(2 * s, 1 / s))]


@pytest.mark.parametrize("k", range(3), ids=["PI", "StopPI", "MGPI"])
def test_exact_inverse_accuracy_at_unit_scale(k):
    u = 1.5 * np.sin(np.linspace(0, 12, 200)) * np.exp(-np.linspace(0, 1, 200))
    m = _scaled_models(1.0)[k]
    # 1e-13: the documented accuracy of the inverse's Newton steps (inverses.py)
    assert np.max(np.abs(m.simulate(m.exact_inverse().simulate(u)) - u)) < 1e-13


@pytest.mark.parametrize("k", range(3), ids=["PI", "StopPI", "MGPI"])
def test_exact_inverse_is_scale_invariant(k):
    # the same model and targets in units 1e12 times smaller: the same relative accuracy (the
    # bracket stops at 1e-15 of the largest threshold plus |x|, the output tolerance scales with
    # the model's output over that threshold); found by the corner tests, issue 12
    u = 1.5 * np.sin(np.linspace(0, 12, 200)) * np.exp(-np.linspace(0, 1, 200))
    s = 1e-12
    m = _scaled_models(s)[k]
    assert np.max(np.abs(m.simulate(m.exact_inverse().simulate(u * s)) - u * s)) / s < 1e-13

"""Elementary operators against plain-Python loops of the thesis's equations
(eq. 13 play, eq. 16 stop, eq. 20 generalized play, eq. 23 modified play),
with initial states and chunking."""

import os
import sys

import numpy as np
import pytest

sys.path.insert(0, os.path.dirname(__file__))
import conftest as ref  # noqa: E402  (reference loops shared by the tests)

from hystcomp import generalized_play, modified_play, play, stop  # noqa: E402
from hystcomp.envelopes import Atanh, Custom, Identity, Linear, Polynomial, Tanh  # noqa: E402

R = np.array([0.0, 0.3, 0.8, 1.5, 2.6])
V = ref.test_signal(300, amp=3.0, seed=1)


def _chunks(x, cuts):
    edges = [0, *cuts, x.size]
    return [x[a:b] for a, b in zip(edges[:-1], edges[1:])]


def _run_chunked(op, v, cuts, *args, state=None):
    outs = []
    for part in _chunks(v, cuts):
        w, state = op(part, *args, state=state)
        outs.append(w)
    return np.vstack(outs), state


# play and stop use only max/min/+/- in the same order as the reference: the
# results must agree exactly.
def test_play_matches_eq13_reference():
    w, s = play(V, R)
    wr, sr = ref.ref_play(V, R)
    np.testing.assert_array_equal(w, wr)
    np.testing.assert_array_equal(s, sr)
    assert w.shape == (V.size, R.size)


def test_play_with_initial_state_and_chunks():
    z0 = np.array([0.5, -0.7, 1.2, 0.0, -2.0])
    w, s = play(V, R, state=z0)
    wr, sr = ref.ref_play(V, R, z0)
    np.testing.assert_array_equal(w, wr)
    np.testing.assert_array_equal(s, sr)
    wc, sc = _run_chunked(play, V, [1, 57, 58, 200], R, state=z0)
    np.testing.assert_array_equal(wc, w)
    np.testing.assert_array_equal(sc, s)


def test_play_does_not_modify_the_callers_state():
    z0 = np.array([0.5, -0.7, 1.2, 0.0, -2.0])
    keep = z0.copy()
    play(V, R, state=z0)
    np.testing.assert_array_equal(z0, keep)


def test_stop_matches_eq16_reference():
    r = R[1:]
    e, s = stop(V, r)
    er, sr, vlast = ref.ref_stop(V, r)
    np.testing.assert_array_equal(e, er)
    np.testing.assert_array_equal(s, np.concatenate([sr, [vlast]]))
    # eq. 15: e(0) = e_r(v(0))
    np.testing.assert_array_equal(e[0], np.clip(V[0], -r, r))


def test_stop_with_initial_state_and_chunks():
    r = R[1:]
    st = np.array([0.1, -0.5, 1.0, 2.0, 0.7])  # e_1..e_4 and the previous input
    e, s = stop(V, r, state=st)
    er, sr, vlast = ref.ref_stop(V, r, st[:-1], st[-1])
    np.testing.assert_array_equal(e, er)
    np.testing.assert_array_equal(s, np.concatenate([sr, [vlast]]))
    ec, sc = _run_chunked(stop, V, [3, 150, 151], r, state=st)
    np.testing.assert_array_equal(ec, e)
    np.testing.assert_array_equal(sc, s)


def test_stop_and_play_are_complementary():
    # classical identity F_r[v] + E_r[v] = v for the virgin state (the play
    # starting at 0 and the stop at e_r(v(0)) with v(0) in [-r, r]).
    v = np.concatenate([[0.0], V])
    r = R[1:]
    w, _ = play(v, r)
    e, _ = stop(v, r)
    np.testing.assert_allclose(w + e, np.repeat(v[:, None], r.size, axis=1), rtol=0, atol=1e-14)


ENVELOPE_PAIRS = {
    "identity": (Identity(), Identity(), ref.ident, ref.ident),
    "linear": (Linear(2.0), Linear(0.5), ref.ref_linear(2.0), ref.ref_linear(0.5)),
    "tanh_sym": (Tanh(4.0, 0.5), Tanh(4.0, 0.5), ref.ref_tanh(4.0, 0.5), ref.ref_tanh(4.0, 0.5)),
    "tanh_asym": (Tanh(4.0, 0.5, 0.2), Tanh(3.0, 0.3), ref.ref_tanh(4.0, 0.5, 0.2), ref.ref_tanh(3.0, 0.3)),
    "atanh": (Atanh(1.0, 0.2), Atanh(1.5, 0.2, 0.1), ref.ref_atanh(1.0, 0.2), ref.ref_atanh(1.5, 0.2, 0.1)),
    "poly": (Polynomial([0.0, 1.0, 0.0, 0.2], (-6.0, 6.0)), Polynomial([0.0, 2.0, 0.1, 0.1], (-6.0, 6.0)),
             ref.ref_poly([0.0, 1.0, 0.0, 0.2], -6.0, 6.0), ref.ref_poly([0.0, 2.0, 0.1, 0.1], -6.0, 6.0)),
}


@pytest.mark.parametrize("name", list(ENVELOPE_PAIRS))
def test_generalized_play_matches_eq20_reference(name):
    gl, gr, fl, fr = ENVELOPE_PAIRS[name]
    w0 = np.array([0.3, -0.4, 0.0, 1.0, -1.0])
    for state in (None, w0):
        w, s = generalized_play(V, R, gl, gr, state=state)
        wr, sr = ref.ref_generalized_play(V, R, fl, fr, state)
        # envelope values come from NumPy vs math: equal to 1 ulp of the value
        # scale (|gamma| <= 16 here): 1e-14 absolute.
        np.testing.assert_allclose(w, wr, rtol=0, atol=1e-14)
        np.testing.assert_allclose(s, sr, rtol=0, atol=1e-14)
        wc, sc = _run_chunked(generalized_play, V, [10, 11, 123], R, gl, gr, state=state)
        np.testing.assert_array_equal(wc, w)
        np.testing.assert_array_equal(sc, s)


@pytest.mark.parametrize("name", list(ENVELOPE_PAIRS))
def test_modified_play_matches_eq23_reference(name):
    gl, gr, fl, fr = ENVELOPE_PAIRS[name]
    v = V
    if name == "atanh":
        v = V * (4.9 - R[-1]) / np.max(np.abs(V))  # keep |v| < 1/b = 5; v +- r may leave it
    w0 = np.array([0.3, -0.4, 0.0, 1.0, -1.0])
    for state in (None, w0):
        w, s = modified_play(v, R, gl, gr, state=state)
        wr, sr = ref.ref_modified_play(v, R, fl, fr, state)
        # compiled envelope vs math.*: a few ulps of |gamma| <= ~40: 1e-13 absolute.
        np.testing.assert_allclose(w, wr, rtol=0, atol=1e-13)
        np.testing.assert_allclose(s, sr, rtol=0, atol=1e-13)
        wc, sc = _run_chunked(modified_play, v, [1, 2, 250], R, gl, gr, state=state)
        np.testing.assert_array_equal(wc, w)
        np.testing.assert_array_equal(sc, s)


def test_modified_play_with_identity_is_the_play():
    w, s = modified_play(V, R, Identity())
    wp, sp = play(V, R)
    np.testing.assert_array_equal(w, wp)
    np.testing.assert_array_equal(s, sp)


def test_modified_play_custom_envelope_block_path():
    # a Custom envelope runs the NumPy fallback: it must agree with the
    # compiled Tanh and with the reference to rounding.
    a, b = 4.0, 0.5
    g = Custom(lambda x: a * np.tanh(b * x), lambda x: a * b / np.cosh(b * x) ** 2,
               lambda y: np.arctanh(y / a) / b, range=(-a, a), name="tanh")
    w0 = np.array([0.3, -0.4, 0.0, 1.0, -1.0])
    w, s = modified_play(V, R, g, state=w0)
    wt, st = modified_play(V, R, Tanh(a, b), state=w0)
    wr, _ = ref.ref_modified_play(V, R, ref.ref_tanh(a, b), ref.ref_tanh(a, b), w0)
    np.testing.assert_allclose(w, wt, rtol=0, atol=1e-14)
    np.testing.assert_allclose(w, wr, rtol=0, atol=1e-14)
    np.testing.assert_allclose(s, st, rtol=0, atol=1e-14)


def test_modified_play_rejects_inputs_outside_the_domain():
    with pytest.raises(ValueError, match=r"v\[2\]"):
        modified_play([0.0, 1.0, 5.0], [0.5], Atanh(1.0, 0.2))


def test_operators_reject_bad_arguments():
    with pytest.raises(ValueError, match="state"):
        play(V, R, state=np.zeros(3))
    with pytest.raises(ValueError, match="state"):
        stop(V, R[1:], state=np.zeros(4))  # needs N + 1 = 5 entries
    with pytest.raises(ValueError, match=r"v holds a non-finite value \(nan\) at sample index 4"):
        play([0.0, 1.0, 2.0, 3.0, np.nan], R)
    with pytest.raises(ValueError, match="thresholds.*not strictly increasing"):
        play(V, [0.0, 1.0, 1.0])
    with pytest.raises(ValueError, match="thresholds.*>= 0"):
        play(V, [-1.0, 1.0])
    with pytest.raises(TypeError, match="envelope_left"):
        generalized_play(V, R, lambda x: x)
    with pytest.raises(TypeError, match="envelope_right"):
        modified_play(V, R, Identity(), np.tanh)

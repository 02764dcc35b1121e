"""The signatures' partial RMS (:func:`hystcomp.diagnose.signatures._partial`),
computed from one Gram matrix of ``[N, F]``, against the definition by two
least-squares fits (``numpy.linalg.lstsq``, an SVD: another code path):
with well-posed columns, with columns that repeat others (rank-deficient,
as hat functions on a branch the input never takes), and without columns."""

import math

import numpy as np
import pytest

from hystcomp.diagnose.signatures import _partial


def _by_svd(e, N, F):
    def rss(A):
        if A.shape[1] == 0:
            return float(e @ e)
        c, *_ = np.linalg.lstsq(A, e, rcond=None)
        r = e - A @ c
        return float(r @ r)
    return math.sqrt(max(rss(N) - rss(np.column_stack([N, F])), 0.0) / e.size)


def _columns(seed, n=5000):
    rng = np.random.default_rng(seed)
    x = np.linspace(-1.0, 1.0, n)
    N = np.column_stack([np.ones(n), x, np.maximum(0.0, 1.0 - np.abs(x[:, None] - np.linspace(-1, 1, 9)) * 4)])
    F = np.column_stack([x ** 3, x ** 5, np.sin(7 * x)])
    e = 0.3 * x ** 3 + 0.1 * np.sin(7 * x) + 0.05 * x + 0.02 * rng.standard_normal(n)
    return e, N, F


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_partial_rms_equals_two_least_squares_fits(seed):
    e, N, F = _columns(seed)
    ref = _by_svd(e, N, F)
    assert ref > 0.01                                   # F explains a real part of e
    # both sides are exact up to rounding of sums over 5,000 rows of O(1) terms
    assert _partial(e, N, F) == pytest.approx(ref, rel=1e-9)


def test_partial_rms_with_repeated_and_zero_columns():
    e, N, F = _columns(3)
    # a column of N repeated in F, a zero column (a branch the input never takes)
    # and a column twice in N: each counts once, as in the SVD's minimum-norm fit
    N2 = np.column_stack([N, N[:, 2], np.zeros(e.size)])
    F2 = np.column_stack([F, N[:, 1], np.zeros(e.size)])
    assert _partial(e, N2, F2) == pytest.approx(_by_svd(e, N2, F2), rel=1e-9)
    assert _partial(e, N2, F2) == pytest.approx(_partial(e, N, F), rel=1e-9)
    # columns that add nothing beyond N: the partial RMS is 0 (up to rounding)
    assert _partial(e, N, N[:, :3]) < 1e-7 * math.sqrt(float(e @ e) / e.size)


def test_partial_rms_without_nuisance_columns():
    e, N, F = _columns(4)
    empty = np.zeros((e.size, 0))
    assert _partial(e, empty, F) == pytest.approx(_by_svd(e, empty, F), rel=1e-9)


def test_record_memo_gives_the_evidence_computed_afresh():
    """The columns that depend on the record alone (and their Gram matrices) are built once per record
    (``Record.signature_memo``); every later residual's evidence is bit-equal to the one a fresh record computes."""
    from hystcomp.datasets import hidden_effect_data
    from hystcomp.diagnose.record import Record
    from hystcomp.diagnose.signatures import evidence

    d = hidden_effect_data("creep", seed=1, dt=0.01, duration=60.0)
    rng = np.random.default_rng(5)
    rec = Record(d.t, d.v, d.y, 0.3)
    assert rec.signature_memo == {}
    residuals = [rng.standard_normal(rec.n) * 0.01 + 0.02 * np.sin(k + rec.v / 20.0) for k in range(3)]
    pred = rec.y - residuals[0]
    kept = [evidence(rec, e, pred, 0.01) for e in residuals]
    # the memo holds the nuisance and the record-only blocks (rate, drift, asymmetry, saturation, start)
    assert {"nuisance", ("rate",), ("drift", "common"), ("drift", "by_level"), ("asymmetry",), ("saturation",),
            ("initial_state",)} <= set(rec.signature_memo)
    for e, ev in zip(residuals, kept):
        assert ev == evidence(Record(d.t, d.v, d.y, 0.3), e, pred, 0.01)
    # residuals that differ give statistics that differ (the memo holds no residual)
    assert kept[0]["asymmetry"]["statistic"] != kept[1]["asymmetry"]["statistic"]

"""The engine's memo of play columns (:func:`hystcomp.identify.search._core_columns`):
a design from the memo equals one computed afresh, inputs that the input
parts change and core options that differ are told apart, and the memo is
bounded and read-only."""

import numpy as np
import pytest

from hystcomp.identify import search
from hystcomp.identify.parts import Context, Delay, PICore, Saturation, SlowDrift
from hystcomp.identify.search import Structure


def _ctx():
    t = np.arange(3000) * 1e-3
    v = 2.0 * np.sin(2 * np.pi * 1.3 * t) * (1 + 0.3 * np.sin(2 * np.pi * 0.2 * t))
    return Context(v, 1e-3, 0.0, 2.6, 3.0, n_thresholds=10)


def _fresh(structure, values, ctx):
    """The design with the memo emptied first (every block computed)."""
    ctx.core_cache.clear()
    return structure.design(values, ctx)[0]


@pytest.mark.parametrize("part, values", [
    (SlowDrift(), [{}, {}]),
    (Delay(), [{"delay": {"delay": 0.0}}, {"delay": {"delay": 3.5}}, {"delay": {"delay": 0.0}}]),
    (Saturation(), [{"saturation_envelope": {"b": 0.5}}, {"saturation_envelope": {"b": 1.5}},
                    {"saturation_envelope": {"b": 0.5}}]),
])
def test_memo_gives_the_design_computed_afresh(part, values):
    ctx = _ctx()
    s = Structure().extended(part)
    if values[0] == {}:
        values = [{part.kind: {q.name: q.start for q in part.parameters(ctx, set(s.kinds))}}] * 2
    memo = [s.design(v, ctx)[0] for v in values]
    fresh = [_fresh(s, v, ctx) for v in values]
    for a, b in zip(memo, fresh):
        # the same arithmetic on the same block: equal to the last bit
        np.testing.assert_array_equal(a, b)
    if part.kind != "slow_drift":
        # different delays / envelopes give different plays (so the key tells them apart)
        assert not np.allclose(memo[0], memo[1])


def test_memo_is_bounded_and_read_only():
    ctx = _ctx()
    s = Structure().extended(Saturation())
    for b in np.linspace(0.1, 2.0, search.CORE_CACHE + 4):
        s.design({"saturation_envelope": {"b": float(b)}}, ctx)
    assert len(ctx.core_cache) == search.CORE_CACHE
    C = next(iter(ctx.core_cache.values()))
    with pytest.raises(ValueError):
        C[0, 0] = 1.0
    # the thresholds are part of the key: changing them changes the plays
    before = PICore().core(ctx.x, {}, ctx)
    ctx.thresholds = ctx.thresholds * 0.5
    after = Structure().design({}, ctx)[0][:, :ctx.thresholds.size]
    assert not np.allclose(before, after)
    np.testing.assert_array_equal(after, PICore().core(ctx.x, {}, ctx))


def test_plays_gram_memo_gives_the_fit_computed_afresh():
    """The inner solve keeps ``C^T C`` of a memoised play block per set of
    fitted rows: a fit that reuses it equals, to the last bit, the same fit
    by an engine that has to form it; another row set gets its own entry;
    a block a filter made (writeable) is never kept; and the stacked design
    (what :meth:`PartsModel.simulate` used to multiply) gives the same
    prediction up to rounding."""
    from hystcomp.identify.parts import Drift, OutputLag
    from hystcomp.identify.search import VariableProjection

    ctx = _ctx()
    y = np.tanh(ctx.x) + 0.01 * np.arange(ctx.x.size) / ctx.x.size
    train = np.arange(ctx.x.size) < 2100
    s = Structure().extended(Drift())
    q = {"time_constant": 0.5}
    other = {"time_constant": 1.5}
    vp = VariableProjection(ctx, y, train)
    vp.evaluate(s, {"offset_drift": q})
    reused = vp.evaluate(s, {"offset_drift": other})
    assert len(vp._gram_cache) == 1                  # one play block, one row set
    fresh = VariableProjection(ctx, y, train).evaluate(s, {"offset_drift": other})
    np.testing.assert_array_equal(reused.theta, fresh.theta)
    np.testing.assert_array_equal(reused.prediction, fresh.prediction)
    # blocks spread over the record: another row set, another entry
    blocks = (np.arange(ctx.x.size) // 300) % 3 != 1
    vp.train = blocks
    on_blocks = vp.evaluate(s, {"offset_drift": q})
    assert len(vp._gram_cache) == 2
    np.testing.assert_array_equal(on_blocks.theta, VariableProjection(ctx, y, blocks).evaluate(
        s, {"offset_drift": q}).theta)
    # (and the row sets do give different fits: the key tells them apart)
    assert not np.allclose(on_blocks.theta, VariableProjection(ctx, y, train).evaluate(
        s, {"offset_drift": q}).theta)
    # a lag after the core makes a new (writeable) block at every solve: nothing kept
    vp2 = VariableProjection(ctx, y, train)
    vp2.evaluate(Structure().extended(OutputLag()), {"output_lag": {"time_constant": 0.01}})
    assert len(vp2._gram_cache) == 0
    # the stacked design's product equals the blockwise one up to rounding
    A = s.design({"offset_drift": other}, ctx)[0]
    np.testing.assert_allclose(A @ reused.theta, reused.prediction, rtol=0, atol=1e-12 * np.abs(y).max())


def test_additive_columns_memo_gives_the_fit_computed_afresh():
    """The additive parts' columns (a drift's, an offset's) are built and
    stacked once per part instance and values, read-only, and kept for the
    last ADDITIVE_CACHE sets; the inner solve keeps their fitted rows and
    Gram matrix per row set. A fit through both memos equals, to the last
    bit, the same fit by an engine and a context that form everything anew;
    other values or another instance of the part get their own entry."""
    from hystcomp.identify.parts import Drift, OutputLag
    from hystcomp.identify.search import VariableProjection

    ctx = _ctx()
    y = np.tanh(ctx.x) + 0.01 * np.arange(ctx.x.size) / ctx.x.size
    train = np.arange(ctx.x.size) < 2100
    drift = Drift()
    s = Structure().extended(drift).extended(OutputLag())
    vp = VariableProjection(ctx, y, train)
    pts = [vp.evaluate(s, {"offset_drift": {"time_constant": 0.5}, "output_lag": {"time_constant": tau}})
           for tau in (0.01, 0.02, 0.01)]
    # the lag's time constant changes, the drift's columns are those of one entry
    assert len(ctx.additive_cache) == 1 and len(vp._additive_cache) == 1
    F = next(iter(ctx.additive_cache.values()))[1][0]
    with pytest.raises(ValueError):
        F[0, 0] = 1.0
    for tau, pt in zip((0.01, 0.02, 0.01), pts):
        ctx2 = _ctx()
        fresh = VariableProjection(ctx2, y, train).evaluate(
            s, {"offset_drift": {"time_constant": 0.5}, "output_lag": {"time_constant": tau}})
        np.testing.assert_array_equal(pt.theta, fresh.theta)
        np.testing.assert_array_equal(pt.prediction, fresh.prediction)
    # another drift time constant, or another instance of the part: new entries, bounded
    vp.evaluate(s, {"offset_drift": {"time_constant": 1.5}, "output_lag": {"time_constant": 0.01}})
    s2 = Structure().extended(Drift())
    vp.evaluate(s2, {"offset_drift": {"time_constant": 0.5}})
    assert len(ctx.additive_cache) == 3
    for tc in np.linspace(0.2, 2.0, search.ADDITIVE_CACHE + 3):
        s2.design({"offset_drift": {"time_constant": float(tc)}}, ctx)
    assert len(ctx.additive_cache) == search.ADDITIVE_CACHE


def test_optimise_solves_each_point_once_and_keeps_the_best():
    """The local search asks for the start again (Nelder-Mead's first vertex) and for vertices clipped to the
    box more than once; each point is solved once, and the point returned is the best of those solved."""
    ctx = _ctx()
    rng = np.random.default_rng(3)
    s = Structure().extended(Delay())
    k = np.arange(ctx.x.size)
    truth = 1.5 * np.interp(k - 2.3, k, ctx.x) + 0.2          # the input 2.3 samples late, scaled
    vp = search.VariableProjection(ctx, truth + 1e-3 * rng.standard_normal(truth.size), np.arange(truth.size) < 2400)
    solved = []
    evaluate = vp.evaluate

    def counted(structure, values):
        solved.append(values["delay"]["delay"])
        return evaluate(structure, values)

    vp.evaluate = counted
    # a repeated start and a start at the edge of the bounds (clipped vertices)
    start = {"delay": {"delay": 0.5}}
    best = vp.optimise(s, start, starts=[{"delay": {"delay": 0.5}}, {"delay": {"delay": 0.0}}], max_evaluations=40)
    assert len(solved) == len(set(solved)) and len(solved) >= 5
    assert best.rss == min(evaluate(s, {"delay": {"delay": d}}).rss for d in solved)
    assert best.values["delay"]["delay"] == pytest.approx(2.3, abs=0.05)     # noise 1e-3: the delay is found

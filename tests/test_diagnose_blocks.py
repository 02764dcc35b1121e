"""Held-out blocks spread over the record (``held_out="blocks"``) and the
re-judging of ``held_out="auto"``: a drift that turns back cannot be tested by
extrapolation into the record's end; between fitted stretches it can."""

import numpy as np
import pytest
from realistic import excitations as ex
from realistic import mechanisms as me

from hystcomp.diagnose import diagnose
from hystcomp.diagnose.record import N_BLOCKS, Record, spread_blocks


def _warm_up_and_cool_down(seed=0):
    """A PI-like core (200 plays of a decaying density, not hystcomp's parts)
    under triangles of decaying amplitude, 30 s at 500 Hz, with a mount that
    warms and cools: an offset of 4 % of the span rising over the first 65 %
    of the record and falling back after it (sin^2), and output noise of
    0.2 % of the span."""
    rng = np.random.default_rng([seed, 4417])
    dt, n = 2e-3, 15_000
    v = ex.triangles(dt, n, 0.8, 45.0)
    t = np.arange(n) * dt
    h = me.play_core(v, 100.0)
    off = 0.04 * np.ptp(h) * np.sin(np.pi * t / (1.3 * t[-1])) ** 2
    return t, v, h + off + 0.002 * np.ptp(h) * rng.standard_normal(n)


def test_blocks_share_the_held_out_fraction_after_the_records_first_part():
    for n in (70, 1001, 40_000):
        k = int(round(0.7 * n))
        blocks = spread_blocks(n, n - k)
        assert len(blocks) == N_BLOCKS
        starts, ends = np.array(blocks).T
        assert starts[0] == int(round(0.3 * n)) and ends[-1] < n           # fitted stretch after the last
        assert np.all(ends - starts == (n - k) // N_BLOCKS)
        assert np.all(starts[1:] > ends[:-1])                              # fitted stretches between
    rec = Record(np.arange(1000) * 0.01, np.sin(np.arange(1000) / 10), np.cos(np.arange(1000) / 10), 0.3,
                 "blocks")
    assert (~rec.train).sum() == 300 and rec.held_out_in_middle
    assert "5 blocks spread over the record" in rec.held_out_line()
    with pytest.raises(ValueError, match="held_out.*'middle'.*'blocks'"):
        Record(None, np.sin(np.arange(100)), np.cos(np.arange(100)), 0.3, "middle")


def test_a_drift_that_turns_back_is_named_on_blocks_spread_over_the_record():
    t, v, y = _warm_up_and_cool_down()
    # the end held out: the broken line of the shapeless drift is held at its last
    # level past the fitted part, while the offset falls back; nothing pays there
    last = diagnose(t, v, y, progress=False, held_out="last")
    assert last.effects == [] and last.verdict == "unexplained", last.report()
    assert last.other_split is None
    # auto: the same end first, then the record re-judged on blocks, taken because
    # drift is named there and fewer noise floors are left (1.05 against 4.2 measured)
    rep = diagnose(t, v, y, progress=False)
    assert rep.effects == ["drift"] and rep.verdict == "explained", rep.report()
    o = rep.other_split
    assert o["held_out"] == "end" and o["effects"] == [] and o["verdict"] == "unexplained"
    assert o["noise_floors_left"] == pytest.approx(last.rms_heldout / last.noise_floor, rel=1e-9)
    assert rep.rms_heldout / rep.noise_floor < 1.5 < o["noise_floors_left"]
    assert len(rep.held_out_blocks) == N_BLOCKS and rep.validation[0] == rep.held_out_blocks[0][0]
    # the model reproduces the reported RMS on the blocks' samples (same parts as the fit)
    held = ~rep._rec.train
    assert held.sum() == pytest.approx(0.3 * t.size, abs=N_BLOCKS)
    rms = np.sqrt(np.mean((y - rep.model.simulate(v))[held] ** 2))
    assert rms == pytest.approx(rep.rms_heldout, rel=1e-9)
    # no knot of the drift's broken line inside a block
    from hystcomp.identify.parts_dynamics import _knot_times

    knots = _knot_times(rep.model._ctx, 4)
    for a, b in rep.model._ctx.held_out:
        assert not np.any((knots > a) & (knots < b))
    text = rep.report()
    assert "5 blocks spread over the record" in text and "this diagnosis is taken" in text
    d = rep.to_dict()
    assert d["schema_version"] == 30 and len(d["held_out_blocks"]) == N_BLOCKS
    assert d["other_split"]["held_out"] == "end"
    # the figures mark each block's start and end
    import matplotlib.pyplot as plt
    from matplotlib.colors import to_rgb

    ax = rep.plots()["gap"].axes[0]
    dashed = [ln for ln in ax.lines if ln.get_linestyle() == "--"]
    assert len(dashed) == 2 * N_BLOCKS
    shaded = [p for p in ax.patches if np.allclose(p.get_facecolor()[:3], to_rgb("tab:orange"))]
    assert len(shaded) == N_BLOCKS

    plt.close("all")


def test_blocks_asked_for_are_used_without_re_judging():
    t, v, y = _warm_up_and_cool_down(seed=1)
    rep = diagnose(t, v, y, progress=False, held_out="blocks", effects=["drift", "creep"])
    assert rep.effects == ["drift"] and rep.other_split is None
    assert len(rep.held_out_blocks) == N_BLOCKS


def _split(verdict, effects, left, remaining=(), blocks=False, rec=None):
    """A search's result as run_search returns it (only the keys the choice reads)."""
    rec = rec or Record(np.arange(1000) * 0.01, np.sin(np.arange(1000) / 10), np.cos(np.arange(1000) / 10), 0.3,
                        "blocks" if blocks else "last")
    return {"_rec": rec, "verdict": verdict, "effects": list(effects), "tentative": [], "rms_heldout": left,
            "noise_floor": 1.0, "explained_limit": 1.48, "remaining": {k: "-" for k in remaining},
            "elapsed": 1.0, "n_evaluations": 10}


def test_the_blocks_are_taken_for_a_start_the_end_cannot_test():
    from hystcomp.diagnose.splits import choose_split

    said = []
    # the end's held-out part at the floor, only the start's signature left; the blocks
    # name an initial state and explain the record (HOLDOUT31's shock in transit)
    end = _split("unexplained", [], 0.99, remaining=("initial_state", "delay"))
    blocks = _split("explained", ["initial_state"], 0.98, blocks=True)
    chosen = choose_split(end, blocks, said.append)
    assert chosen["verdict"] == "explained" and chosen["effects"] == ["initial_state"]
    assert chosen["other_split"]["held_out"] == "end" and "cannot test" in chosen["other_split"]["why"]
    # not when the end's held-out part is above the explained limit: that part is not
    # explained, whatever the start does
    chosen = choose_split(_split("unexplained", [], 1.6, remaining=("initial_state", "held_out")), blocks,
                           said.append)
    assert chosen["verdict"] == "unexplained" and chosen["other_split"]["held_out"] == "blocks"
    # not when no signature stays at the start, nor when the blocks do not explain the
    # record or name something else
    for end, blk in ((_split("unexplained", [], 0.99, remaining=("delay",)), blocks),
                     (end, _split("unexplained", ["initial_state"], 1.2, blocks=True)),
                     (end, _split("explained", ["asymmetry"], 0.98, blocks=True))):
        assert choose_split(end, blk, said.append)["other_split"]["held_out"] == "blocks"


def test_the_blocks_are_taken_for_a_start_both_found_but_only_they_explain():
    from hystcomp.diagnose.splits import choose_split, start_found_by_both

    said = []
    # the end found an initial state (tentative beside a misfit out of the vocabulary)
    # and left 8.3 noise floors; the blocks name it and explain the record (HOLDOUT52's
    # freezer night, whose end held out inner loops the end's fit never saw)
    end = _split("unexplained", [], 8.26, remaining=("out_of_vocabulary",))
    end["tentative"] = ["initial_state", "drift"]
    blocks = _split("explained", ["initial_state"], 1.43, blocks=True)
    assert start_found_by_both(end, blocks)
    chosen = choose_split(end, blocks, said.append)
    assert chosen["verdict"] == "explained" and chosen["effects"] == ["initial_state"]
    why = chosen["other_split"]["why"]
    assert chosen["other_split"]["held_out"] == "end" and "8.26" in why and "1.43" in why
    assert said[-1].startswith("taken: ")
    # named at the end, not only tentative, counts as found
    named = _split("unexplained", ["initial_state", "rate_dependence"], 1.93)
    assert choose_split(named, blocks, said.append)["other_split"]["held_out"] == "end"
    # not when the end found no initial state, when the blocks name none or do not explain
    # the record, or when they leave more floors than the end
    plain = _split("unexplained", ["asymmetry"], 2.0)
    for e, blk in ((plain, blocks),
                   (end, _split("explained", ["asymmetry"], 1.2, blocks=True)),
                   (end, _split("unexplained", ["initial_state"], 1.6, blocks=True)),
                   (named, _split("explained", ["initial_state"], 2.5, blocks=True))):
        assert not start_found_by_both(e, blk)
        assert choose_split(e, blk, said.append)["other_split"]["held_out"] == "blocks"


def test_the_blocks_are_taken_when_they_explain_the_record_with_what_the_end_named():
    from hystcomp.diagnose.splits import blocks_explain_what_end_named, choose_split

    said = []
    # the end named a saturation and left 2.15 noise floors; the blocks explain the record
    # with nothing named (HOLDOUT34's clean stage on stiffening pads at seed 2)
    end = _split("unexplained", ["saturation"], 2.15)
    blocks = _split("explained", [], 1.17, blocks=True)
    assert blocks_explain_what_end_named(end, blocks)
    chosen = choose_split(end, blocks, said.append)
    assert chosen["verdict"] == "explained" and chosen["effects"] == []
    assert "no effect the end did not name" in chosen["other_split"]["why"] and said[-1].startswith("taken: ")
    # the same effects, or fewer, are taken; one the end did not name is not (HOLDOUT51's
    # sigma-delta gauge: a rate dependence beside the delay, which the end did not need)
    for eff, taken in ((["saturation"], True), (["saturation", "rate_dependence"], False), (["delay"], False)):
        blk = _split("explained", eff, 1.2, blocks=True)
        assert blocks_explain_what_end_named(end, blk) is taken
        assert (choose_split(end, blk, said.append)["other_split"]["held_out"] == "end") is taken
    # not when the blocks leave more floors, nor when they do not explain the record
    for blk in (_split("explained", [], 2.5, blocks=True), _split("unexplained", [], 1.6, blocks=True)):
        assert not blocks_explain_what_end_named(end, blk)
        assert choose_split(end, blk, said.append)["verdict"] == "unexplained"

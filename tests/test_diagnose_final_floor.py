"""The floor an "explained" verdict is judged against: the high-frequency
part again on the final model's residual, when lower
(hystcomp.diagnose.noise.final_residual_floor, round 61).  The test on HOLDOUT46's record is slow
(``pytest -m slow``); the others run in the default suite.

The base model's residual carries a missed effect's fast structure, and its
median absolute second difference reads part of it as noise: HOLDOUT46's
laser sensor (a 5.84-sample latency behind a sampled staircase, seed 0) got a
floor of 1.091 true noise levels and was called explained at 1.61.
"""

import json

import numpy as np
import pytest

from hystcomp.diagnose import diagnose
from hystcomp.diagnose.noise import final_residual_floor, noise_floor
from hystcomp.diagnose.record import Record

SIGMA = 0.01


def _record(structure, n=12000, seed=0):
    """White noise SIGMA on a smooth output; the base residual adds
    `structure` times the misfit of a sensor that holds its reading for
    three samples (a staircase: fast structure at every third sample)."""
    rng = np.random.default_rng(seed)
    t = np.arange(n) * 1e-3
    v = np.sin(2 * np.pi * 3 * t) + 0.5 * np.sin(2 * np.pi * 17 * t + 1.0)
    smooth = 0.8 * v
    noise = SIGMA * rng.standard_normal(n)
    staircase = np.repeat(smooth[::3], 3)[:n]
    rec = Record(t, v, smooth + noise, 0.3, held_out="last")
    return rec, noise + structure * (smooth - staircase), noise


def test_fast_structure_in_the_base_residual_is_not_the_floor():
    rec, base, final = _record(0.2)
    sigma, info = noise_floor(rec, base)
    assert info["method"] == "high_frequency"
    # the staircase's second differences raise the base estimate by about 20 %
    assert sigma > 1.15 * SIGMA
    floor = final_residual_floor(rec, final, sigma, info)
    # 12,000 samples: the estimate's standard error is 1.39 / sqrt(12000) = 1.3 %;
    # 4 % is three of those
    assert floor == pytest.approx(SIGMA, rel=0.04)
    assert info["final_high_frequency"] == floor


def test_a_higher_final_estimate_leaves_the_floor():
    rec, base, final = _record(0.0)
    sigma, info = noise_floor(rec, base)
    # a final residual with more high-frequency content (a model that adds noise)
    assert final_residual_floor(rec, 1.2 * final, sigma, info) == sigma
    assert "final_high_frequency" not in info


def test_a_floor_the_holds_set_stands():
    rec, base, final = _record(0.2)
    info = {"method": "holds", "holds": 0.013, "high_frequency": 0.012, "relative_standard_error": 0.01}
    assert final_residual_floor(rec, final, 0.013, info) == 0.013
    assert "final_high_frequency" not in info


def test_the_resolution_bounds_the_final_floor():
    # a final residual with no noise at all: the floor is the solves' resolution
    # (1e-5 of the output span), never below it
    rec, base, final = _record(0.2)
    sigma, info = noise_floor(rec, base)
    floor = final_residual_floor(rec, np.zeros_like(final), sigma, info)
    assert floor == pytest.approx(1e-5 * rec.y_span)


# 24 s in the default suite (round 61), whose CI time is near its bound; the slow acceptance
# (tests/test_diagnose_realistic.py, OVER_KNOWN) also holds this record at seed 0 to 1.5 true noise levels
@pytest.mark.slow
def test_on_a_seen_record_the_final_floor_decides_the_verdict():
    from realistic import HOLDOUT46

    r = HOLDOUT46["holdout46_delay_laser_sensor_latency_hi_hat_587hz"](0)
    rep = diagnose(r.t, r.v, r.y, progress=False)
    # measured in round 61: the base residual's floor 0.3091 (1.091 true noise levels), the final
    # residual's 0.3043; held-out RMS 0.4565 is 1.477 of the first and 1.500 of the second, against a
    # limit of 1.481.  Before, "explained" at 1.61 true noise levels with an asymmetry named beside the
    # delay; now unexplained, and the asymmetry, a later step gaining 6.78, is tentative
    assert rep.verdict == "unexplained"
    assert rep.effects == ["delay"] and rep.tentative == ["asymmetry"], rep.report()
    final = rep.noise_info["final_high_frequency"]
    assert final < rep.noise_floor
    assert rep.rms_heldout > rep.explained_limit * final
    assert rep.rms_heldout <= rep.explained_limit * rep.noise_floor
    assert "x the noise floor measured on the final model's residual" in rep.remaining["held_out"]
    d = json.loads(json.dumps(rep.to_dict()))
    assert d["noise_floor_method"]["final_high_frequency"] == pytest.approx(final)
    # the gap figure's panel of the final model gives both ratios, the search's floor's and the verdict's
    import matplotlib.pyplot as plt

    figs = rep.plots()
    titles = [a.get_title() for a in figs["gap"].axes]
    said = [t.replace("\n", " ") for t in titles if "verdict's floor" in t]
    assert len(said) == 1 and said[0].startswith("final:"), titles
    assert f"{rep.rms_heldout / final:.2f} of the verdict's floor, {final:.3g}, from its own residual" in said[0]
    for fig in figs.values():
        plt.close(fig)

"""An "explained" verdict needs the held-out RMS within 1.5 noise floors by the
floor's own standard error (hystcomp.diagnose.noise.noise_floor gives it as
``relative_standard_error``): a floor estimated a little high does not pass a
residual a little above the bound.
"""

import math

import numpy as np
import pytest

from hystcomp.datasets import hidden_effect_data
from hystcomp.diagnose import diagnose, search
from hystcomp.diagnose.noise import HF_STANDARD_ERROR, _hf_noise


def test_high_frequency_floor_standard_error_as_stated():
    # the spread of the second-difference estimate over 400 white-noise records of
    # 10,000 samples: HF_STANDARD_ERROR / sqrt(N) of the true standard deviation.
    # 400 records measure a standard deviation to 1 / sqrt(2 x 399) = 3.5 %; 12 %
    # is more than three of those
    rng = np.random.default_rng(1)
    n = 10_000
    est = np.array([_hf_noise(rng.standard_normal(n)) for _ in range(400)])
    assert np.mean(est) == pytest.approx(1.0, abs=0.01)       # unbiased to 1 % (its SE here 0.07 %)
    assert np.std(est) * math.sqrt(n) == pytest.approx(HF_STANDARD_ERROR, rel=0.12)


@pytest.fixture(scope="module")
def clean():
    d = hidden_effect_data(None, seed=121, dt=0.01)
    rep = diagnose(d.t, d.v, d.y, progress=False)
    assert rep.verdict == "explained" and not rep.effects
    return d, rep


def test_noise_floor_reports_its_standard_error(clean):
    d, rep = clean
    se = rep.noise_info["relative_standard_error"]
    if rep.noise_info["method"] == "high_frequency":
        assert se == pytest.approx(HF_STANDARD_ERROR / math.sqrt(d.y.size - 2))
    assert 0.0 < se < 0.05
    js = rep.to_dict()
    assert js["noise_floor_method"]["relative_standard_error"] == se
    assert js["explained_limit"] == rep.explained_limit == pytest.approx(1.5 * (1.0 - se))
    # within the bound less the margin
    assert rep.rms_heldout <= 1.5 * (1.0 - se) * rep.noise_floor


def test_explained_bound_keeps_the_standard_error_margin(clean, monkeypatch):
    # set the bound so the record's held-out RMS sits inside the margin (below the
    # bound, above the bound less one standard error): no longer "explained"; set
    # it so the RMS sits below the bound less the margin: "explained"
    d, rep = clean
    q = rep.rms_heldout / rep.noise_floor
    se = rep.noise_info["relative_standard_error"]
    monkeypatch.setattr(search, "EXPLAINED", q / (1.0 - 0.5 * se))
    inside = diagnose(d.t, d.v, d.y, progress=False)
    assert q < search.EXPLAINED
    assert inside.verdict == "unexplained"
    assert "standard error" in inside.remaining["held_out"]
    monkeypatch.setattr(search, "EXPLAINED", q / (1.0 - 2.0 * se))
    assert diagnose(d.t, d.v, d.y, progress=False).verdict == "explained"

"""The loops figure of a diagnosis draws whole half-cycles of the held-out part:
its reversals are the input's extremes, not the noise's sign changes during a hold."""

import numpy as np
import pytest

from hystcomp.diagnose.report import reversals
from realistic import excitations as ex
from realistic import mechanisms as me


def test_reversals_of_a_noisy_staircase_are_its_turning_levels():
    rng = np.random.default_rng([7, 1])
    levels = np.array([0.0, 10.0, 25.0, -5.0, -30.0, 20.0, 5.0])
    v = ex.staircase_holds(1e-3, levels, 0.5, 0.05)
    v = v + 0.02 * rng.standard_normal(v.size)         # a noisy monitor: 0.03 % of the span
    r = reversals(v, 0.02 * np.ptp(v))
    # the direction turns at 25 (up -> down), -30 (down -> up) and 20 (up -> down)
    assert [round(float(np.mean(v[k - 5:k + 5]))) for k in r] == [25, -30, 20]
    # the sign of the raw rate changes at thousands of samples (the noise during holds)
    assert np.count_nonzero(np.diff(np.sign(np.diff(v))) != 0) > 1000


def test_loops_figure_of_a_staircase_shows_its_ramps(tmp_path):
    import matplotlib

    matplotlib.use("Agg")
    from hystcomp.diagnose import diagnose

    rng = np.random.default_rng([7, 2])
    levels = np.concatenate([[0.0], np.tile([30.0, -5.0, -30.0, 5.0], 3)])
    v = ex.staircase_holds(1e-3, levels, 0.6, 0.3)
    y = me.play_core(v, 60.0)
    v = v + 0.01 * rng.standard_normal(v.size)
    y = y + 0.03 * rng.standard_normal(v.size)
    rep = diagnose(np.arange(v.size) * 1e-3, v, y, effects=["drift"], progress=False)
    ax = rep.plots()["loops"].axes[0]
    x = np.concatenate([ln.get_xdata() for ln in ax.lines])
    # the drawn half-cycles cover the ramps: inputs all over the span, not only the hold levels
    hist, _ = np.histogram(x, bins=12, range=(-30, 30))
    assert np.count_nonzero(hist) == 12, hist
    assert "every" not in ax.get_title()                 # few half-cycles: nothing thinned


@pytest.mark.parametrize("tol", [0.5, 2.0])
def test_reversals_of_a_sine_are_its_extremes(tol):
    t = np.linspace(0.0, 3.0, 3001)
    v = 10.0 * np.sin(2 * np.pi * t)
    r = reversals(v, tol)
    np.testing.assert_allclose(t[r], [0.25, 0.75, 1.25, 1.75, 2.25, 2.75], atol=1.5e-3)


def test_rate_panel_keeps_its_samples_readable_past_a_step():
    # a step in the input (one sample at 40,000 V/s, as at 3.26 s of the measured piezo record)
    # would squeeze every other sample into one column of the rate panel: its axis holds the
    # middle 99.8 % of the samples and its label counts those beyond
    import matplotlib

    matplotlib.use("Agg")
    from hystcomp.diagnose import diagnose

    dt = 1e-3
    t = np.arange(20000) * dt
    v = 40.0 * np.sin(2 * np.pi * 0.5 * t) * np.minimum(t / 2.0, 1.0)
    v[t >= 12.0] += 20.0                        # one step of 20 V in one sample: 20,000 V/s
    y = me.play_core(v, 60.0) + 0.03 * np.random.default_rng(5).standard_normal(t.size)
    rep = diagnose(t, v, y, effects=["drift"], progress=False, workers=1)
    ax = rep.plots()["signatures"].axes[2]
    lo, hi = ax.get_xlim()
    assert hi < 1000.0 and lo > -1000.0          # the sine's rates: up to 2 pi 0.5 40 = 126 V/s
    assert hi > 126.0 and lo < -126.0
    beyond = int(ax.get_xlabel().split("; ")[1].split()[0])
    assert ax.get_xlabel().endswith("samples beyond the axis") and 1 <= beyond <= 40     # 0.2 % of 20,000


def test_rate_panel_without_a_step_shows_every_sample():
    import matplotlib

    matplotlib.use("Agg")
    from hystcomp.diagnose import diagnose

    t = np.arange(20000) * 1e-3
    v = 40.0 * np.sin(2 * np.pi * 0.5 * t) * np.minimum(t / 2.0, 1.0)
    y = me.play_core(v, 60.0) + 0.03 * np.random.default_rng(6).standard_normal(t.size)
    rep = diagnose(t, v, y, effects=["drift"], progress=False, workers=1)
    ax = rep.plots()["signatures"].axes[2]
    x = np.concatenate([ln.get_xdata() for ln in ax.lines])
    lo, hi = ax.get_xlim()
    assert lo <= x.min() and x.max() <= hi
    assert "beyond" not in ax.get_xlabel()

"""A rate term beside the hysteresis (eddy currents): the part, its fit and its naming.

The record's rate term is written here from its physics (the low-passed input rate added
to a density of plays, tests/realistic), not from the part's own columns.
"""

import numpy as np
import pytest

from hystcomp.diagnose import diagnose
from hystcomp.identify.parts import PARTS, Context, RateTerm
from realistic import excitations as ex
from realistic import mechanisms as me


def _eddy_record(seed):
    rng = np.random.default_rng([seed, 5151])
    dt = 5e-4
    v = np.concatenate([ex.decaying_sines(dt, 6_000, (f, 1.6 * f), 40.0) for f in (0.7, 6.0, 18.0)])
    h = me.play_core(v, 90.0)
    y = h + 1.5e-3 * np.ptp(h) / np.ptp(v) * me.low_passed_rate(v, dt, 1.5e-3)
    y = y + 0.002 * np.ptp(y) * rng.standard_normal(len(y))
    return np.arange(len(v)) * dt, v, y


def test_rate_term_column_is_the_low_passed_rate():
    # a ramp's rate is constant: the low-passed column rises to it as 1 - exp(-t/tau)
    dt, tau = 1e-3, 5e-3
    ctx = Context(np.arange(200) * 0.01, dt, 0.0, 1.0, 0.2)
    col = RateTerm().columns({"time_constant": tau}, ctx)[0][:, 0]
    k = np.arange(1, 200)
    np.testing.assert_allclose(col[k], 1.0 - np.exp(-k * dt / tau), rtol=1e-12)
    assert "rate_term" in PARTS and PARTS["rate_term"].effect == "rate_dependence"


def test_eddy_current_record_is_named_rate_dependence():
    # no lag or resonance after the hysteresis draws a rate term beside it (it leads);
    # before the part, the unseen eddy-current case left 25-32 noise floors, nothing named
    t, v, y = _eddy_record(2)
    rep = diagnose(t, v, y, progress=False)
    assert rep.effects == ["rate_dependence"], rep.report()
    assert [d["kind"] for d in rep.model.describe()].count("rate_term") == 1
    # within 1.5 noise floors (the play density is not the core's 20 plays exactly)
    assert rep.verdict == "explained" and rep.rms_heldout < 1.5 * rep.noise_floor
    held = slice(rep._rec.held_start, rep._rec.held_end)
    rms = float(np.sqrt(np.mean((y - rep.model.simulate(v))[held] ** 2)))
    assert rms == pytest.approx(rep.rms_heldout, rel=1e-9)
    # the inverse says it does not take the part, naming it
    with pytest.raises(ValueError, match="rate_term"):
        rep.model.exact_inverse()

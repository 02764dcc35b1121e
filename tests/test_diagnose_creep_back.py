"""Creep back: an output that sags against each step (round 56, :class:`hystcomp.identify.parts.BackCreep`).

The records here are built from a law hystcomp has no part for: the library's clean PI record (``hidden_effect_data``
with no effect) passed through a power-law relaxation modulus, ``y(t) = int G(t - s) dh(s)`` with
``G(t) = g_inf + (1 - g_inf) (1 + t / tau0)^-alpha`` (Nutting's power law of a filled rubber's stress relaxation, as in
Findley, Lai & Onaran 1976, *Creep and Relaxation of Nonlinear Viscoelastic Materials*, ch. 5), by direct convolution.
A pad of that kind between the actuator and its load under an imposed travel relaxes its force, so the output
overshoots at each step and sags back towards ``g_inf`` of it: creep against the step. The creep part's lags
(coefficients >= 0) keep the output moving *with* the step and cannot draw it; the creep-back part can, and it is
tried only where the base model's residual relaxes against the steps into the holds.

The same law with the sign of the relaxation turned (``G`` rising from ``g_inf`` to 1) is creep on: there the creep
part is taken and creep back is never tried.
"""

import json

import numpy as np
import pytest
from scipy.signal import fftconvolve

from hystcomp.datasets import hidden_effect_data
from hystcomp.diagnose import diagnose
from hystcomp.identify.parts import BackCreep, Context, Creep, RateTerm
from hystcomp.identify.parts_dynamics import _lag_bounds

DT = 0.01


def _relaxed(back=True, g_inf=0.7, alpha=0.5, tau0=2.0, seed=5):
    """The library's clean record through a power-law relaxation (`back`) or its mirror, creep on (not `back`),
    plus the record's own noise."""
    d = hidden_effect_data(None, seed=seed, dt=DT)
    t = np.arange(d.t.size) * DT
    decay = (1.0 - g_inf) * (1.0 + t / tau0) ** -alpha
    G = g_inf + decay if back else 1.0 - decay
    y = fftconvolve(np.diff(d.clean, prepend=0.0), G)[: d.t.size]
    return d.t, d.v, y + (d.y - d.clean)


@pytest.fixture(scope="module")
def sagging():
    t, v, y = _relaxed()
    return (t, v, y), diagnose(t, v, y, progress=False)


def _kinds(rep):
    return [s["evidence"]["extension"]["kind"] for s in rep.steps]


def test_a_pad_that_relaxes_back_is_named_creep(sagging):
    (t, v, y), rep = sagging
    # measured (round 56): creep back gains 17.0 noise variances held out and leaves 1.07 noise floors; the bound
    # on explained is 1.5 floors less the floor's standard error, so the verdict has a margin of about 0.4 floors
    assert rep.effects == ["creep"] and rep.verdict == "explained", rep.report()
    assert _kinds(rep) == ["creep_back"]
    sig = rep.steps[0]["evidence"]["signature"]
    assert sig["present"] and sig["relaxation_per_step"] < 0 and sig["statistic"] == -sig["relaxation_per_step"]
    assert rep.steps[0]["evidence"]["held_out_gain_noise_variances"] > 10.0
    # the report says which way the residual relaxed in the holds
    assert "it relaxes back, against the step" in rep.report()


def test_the_model_reproduces_the_reported_rms_and_inverts(sagging):
    (t, v, y), rep = sagging
    held = t >= rep.validation[0]
    pred = rep.model.simulate(v)
    # the model is built from the fit's own parts: the same numbers to rounding
    assert np.sqrt(np.mean((y - pred)[held] ** 2)) == pytest.approx(rep.rms_heldout, rel=1e-9)
    # the compensator: the model driven by the inverse's input follows a reference inside its reach; the
    # tolerance is the inverse's default input resolution (1e-9 of the span) times the model's steepest slope
    ref = pred[: 1500]
    u = rep.model.exact_inverse().simulate(ref)
    np.testing.assert_allclose(rep.model.simulate(np.r_[u, np.zeros(v.size - u.size)])[: u.size], ref,
                               rtol=0, atol=1e-6 * np.ptp(ref))


def test_the_json_carries_the_relaxations_sign(sagging):
    js = json.loads(sagging[1].to_json())
    assert js["schema_version"] == 30
    assert js["steps"][0]["evidence"]["signature"]["relaxation_per_step"] < 0


def test_creep_on_takes_the_creep_part_and_never_tries_creep_back():
    t, v, y = _relaxed(back=False)
    rep = diagnose(t, v, y, progress=False)
    assert "creep" in rep.effects, rep.report()
    assert "creep_lags" in _kinds(rep) and "creep_back" not in _kinds(rep)
    # creep back is not even a candidate: the base model's residual relaxes with the steps
    assert all("creep_back" not in s["evidence"]["candidates"] for s in rep.steps)
    sig = [s for s in rep.steps if s["effect"] == "creep"][0]["evidence"]["signature"]
    assert sig["relaxation_per_step"] > 0 and "it relaxes on, with the step" in rep.report()


def test_creep_back_starts_above_the_rate_terms_time_constants():
    # x - L_tau[x] = tau L_tau[dx/dt]: on short time constants creep back would be a rate term
    for n, dt in ((4000, 0.01), (40_000, 1e-3), (2000, 1.0)):
        ctx = Context(np.sin(np.linspace(0, 20, n)), dt, 0.0, 1.0, n * dt)
        back, on = BackCreep().time_constants(ctx), Creep().time_constants(ctx)
        assert back[0] >= min(4 * _lag_bounds(ctx)[1], on[-1] / 10) - 1e-12
        assert back[-1] == pytest.approx(on[-1]) and back.size >= 3
        lo, hi = RateTerm().parameters(ctx, set())[0].lower, RateTerm().parameters(ctx, set())[0].upper
        assert (lo, hi) == _lag_bounds(ctx)


def test_creep_back_sags_against_a_step():
    x = np.r_[np.zeros(10), np.ones(990)]
    ctx = Context(x, 0.1, 0.0, 1.0, 100.0)
    cols, lower, upper, names = BackCreep().columns({}, ctx)
    assert np.all(lower == 0) and np.all(np.isinf(upper))
    # each column jumps with the step and decays back to 0: with a coefficient >= 0 the output overshoots and sags
    assert np.all(cols[:10] == 0) and np.all(cols[10] > 0) and np.all(np.diff(cols[10:], axis=0) <= 0)
    assert names[0].startswith("creep_back_input_")

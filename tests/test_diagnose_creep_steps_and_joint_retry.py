"""Two rules of the diagnosis's fifth round (docs/diagnose.md, "How it decides").

- The creep signature regresses each hold's relaxation on the signed step into
  the hold (linear creep relaxes in proportion to the step), not on its sign.
- Before the search stops, the best candidates are refitted with every
  nonlinear parameter free and judged again (``JOINT_RETRY``).
"""

import numpy as np

from hystcomp.diagnose import diagnose
from hystcomp.diagnose.record import Record
from hystcomp.diagnose.signatures import evidence


def _staircase(levels, dt=0.01, ramp=0.2, hold=2.0):
    v = [np.zeros(int(hold / dt))]
    for a, b in zip(levels[:-1], levels[1:]):
        v.append(np.linspace(a, b, int(ramp / dt), endpoint=False))
        v.append(np.full(int(hold / dt), b))
    v = np.concatenate(v)
    return np.arange(v.size) * dt, v


def test_creep_signature_reads_the_relaxation_after_a_mean_step():
    # steps of very different sizes (4 to 85 % of the span): a residual that
    # relaxes during each hold in proportion to the step into it, a linear ramp
    # of a * step / mean|step| over the hold, plus white noise sigma
    t, v = _staircase([0.0, 5.0, -30.0, 40.0, 35.0, -45.0, 10.0, -12.0, 44.0, -8.0, 30.0])
    rec = Record(t, v, v, 0.3)
    steps = np.array([s for k, j, s in rec.holds if abs(s) > 0.02 * rec.span])
    assert steps.size >= 8 and np.ptp(np.abs(steps)) > 0.5 * rec.span
    sigma, a = 0.01, 0.05
    mean_step = np.abs(steps).mean()
    e = np.zeros(v.size)
    expected = []
    for k, j, s in rec.holds:
        if abs(s) <= 0.02 * rec.span:
            continue
        e[k:j] = a * s / mean_step * np.linspace(0.0, 1.0, j - k)
        m = max(2, (j - k) // 5)
        # last fifth minus first fifth of a ramp 0 -> 1: 1 - (m - 1)/(L - 1)
        expected.append(1.0 - (m - 1) / (j - k - 1))
    e += sigma * np.random.default_rng(0).standard_normal(v.size)
    ev = evidence(rec, e, v, sigma, only="creep")["creep"]
    want = a * float(np.mean(expected)) / sigma       # 4.0 noise floors
    # the noise adds sigma * sqrt(2/m) (m = 40 samples) to each hold's difference:
    # about 0.1 noise floors on the coefficient over 10 holds; 10 % is 4 of those
    assert ev["present"]
    assert abs(ev["statistic"] - want) < 0.1 * want, (ev["statistic"], want)
    # proportional relaxations leave no scatter for the standard error: the
    # threshold stays at its floor of 0.3 noise floors (a regression on the
    # step's sign alone left 2.5 standard errors of 1.4-4.6 floors on the
    # realistic staircases with mixed step sizes)
    assert ev["threshold"] == 0.3


def test_creep_signature_absent_without_relaxation():
    t, v = _staircase([0.0, 5.0, -30.0, 40.0, 35.0, -45.0, 10.0, -12.0, 44.0, -8.0, 30.0])
    rec = Record(t, v, v, 0.3)
    sigma = 0.01
    e = sigma * np.random.default_rng(1).standard_normal(v.size)
    ev = evidence(rec, e, v, sigma, only="creep")["creep"]
    assert not ev["present"] and ev["statistic"] < 0.3


def test_asymmetry_after_saturation_named_after_a_joint_refit():
    # the tuning set's Preisach plane with a shifted interaction field (not a PI
    # core, so the verdict stays "unexplained"): the asymmetric envelopes fitted
    # with the saturation frozen remove 8 % of the misfit above the noise (the
    # rules need 10 % with a third of their own signature, or 35 %); refitted
    # jointly they pass. Since round 49 a later asymmetry on a record left unexplained is named only above
    # 60 noise variances (UNEXPLAINED_SHAPE_GAIN): this one (5.1) is added, and held tentative
    from realistic import ALL

    # (the two effects' parts only: the acceptance test runs this record with every part)
    rec = ALL["asymmetry_preisach"](0)
    res = diagnose(rec.t, rec.v, rec.y, effects=["saturation", "asymmetry"], progress=False)
    assert [st["effect"] for st in res.steps] == ["saturation", "asymmetry"], res.stopped
    assert res.effects == ["saturation"] and res.tentative == ["asymmetry"] and res.verdict == "unexplained"
    assert "naming needs 60 for a saturation or an asymmetry" in res.steps[1]["evidence"]["small_later_step"]
    ev = res.steps[1]["evidence"]
    assert ev["refitted_jointly_before_acceptance"] is True
    assert res.steps[0]["evidence"]["refitted_jointly_before_acceptance"] is False
    # the joint refit is what the step reports, and the returned model reproduces it
    # (1e-9 relative: the same parts and values, recomputed)
    held = ~Record(rec.t, rec.v, rec.y, 0.3).train
    rms = np.sqrt(np.mean((rec.y - res.model.simulate(rec.v))[held] ** 2))
    assert abs(rms - res.rms_heldout) <= 1e-9 * res.rms_heldout
    assert res.steps[1]["rms_after"] < res.steps[1]["rms_before"]

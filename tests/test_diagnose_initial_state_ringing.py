"""A core left by a ringing move: the initial state's preload may end in a decaying
alternation about the record's first input (hystcomp.identify.parts_core.RingingPreload,
round 18), and the initial state's signature has windows by the input's reach.

An actuator parked by an underdamped servo rings about its set point before it settles; a
decaying alternation demagnetises the narrow plays and leaves the wide ones on the branches of
the first overshoots. The two-point preload (virgin -> u1 -> u2 -> the first sample) leaves
every narrow play on one branch instead, and a record whose excursions grow slowly keeps that
misfit for most of its length, where a slow drift drew it better (HOLDOUT15's servo memory was
named drift at 3 of 3 seeds in round 17).

The record: the realistic generator's PI core (tests/realistic/mechanisms.py, 200 plays of its
own density, not hystcomp's) left by a continuous damped cosine (not the part's sequence of
reversal points) from +45 V about 5 V, damping ratio 0.15 (each half cycle 0.62 of the last),
6 Hz, then a 0.7 Hz sine about 5 V whose amplitude grows from 6 V to 43 V over 30 s, so the
memory fades as the excursions grow, over most of the record. Output noise 0.2 % of its span.
"""

import math

import numpy as np
import pytest

from hystcomp.diagnose import diagnose
from hystcomp.diagnose.signatures import evidence
from realistic import mechanisms as me

ZETA = 0.15


@pytest.fixture(scope="module")
def record():
    rng = np.random.default_rng(11)
    ts = np.arange(0.0, 1.5, 1 / 20_000)
    wn = 2 * np.pi * 6.0
    wd = wn * math.sqrt(1 - ZETA ** 2)
    ring = 5.0 + 40.0 * np.exp(-ZETA * wn * ts) * (np.cos(wd * ts) + ZETA / math.sqrt(1 - ZETA ** 2) * np.sin(wd * ts))
    pre = np.r_[np.linspace(0.0, 45.0, 2000), ring]
    _, z = me.play_core(pre, 100.0, return_state=True)
    dt = 1 / 250
    t = np.arange(int(32 / dt)) * dt
    amp = 6.0 + 37.0 * np.clip(t / 30.0, 0.0, 1.0)
    v = 5.0 + amp * np.sin(2 * np.pi * 0.7 * t)
    h = me.play_core(v, 100.0, state=z)
    virgin = me.play_core(v, 100.0)
    sigma = 0.002 * np.ptp(h)
    return t, v, h + sigma * rng.standard_normal(t.size), sigma, h - virgin


def test_the_memory_lasts_over_most_of_the_record(record):
    t, v, y, sigma, memory = record
    # the record's premise (not the diagnosis): the preloaded core differs from the virgin
    # one by more than 5 noise levels over the first 30 % and by more than one still at 50 %
    n = t.size
    assert np.abs(memory[: int(0.3 * n)]).min() < np.abs(memory).max()
    assert np.sqrt(np.mean(memory[: int(0.3 * n)] ** 2)) > 5 * sigma
    assert np.abs(memory[int(0.45 * n): int(0.55 * n)]).max() > sigma


def test_reach_windows_find_the_memory(record):
    # the initial state's signature on the memory alone (the residual a virgin-start
    # model leaves): its windows by the input's reach (ending where the reach first
    # passes 40, 60 and 80 % of the span) see a misfit that fades as the excursions grow.
    # With the time windows alone (first 5, 10, 20 %, before the first full excursion
    # only when that comes in the first 60 %) the statistic was 0.24 noise floors,
    # absent: the slow trend the test allows for draws most of it (measured on dc58b72;
    # with the reach windows 0.57). The record is fixed (seed 11), so the margin is not
    # a matter of noise.
    from hystcomp.diagnose.record import Record

    t, v, y, sigma, memory = record
    rec = Record(t, v, y, validation=0.3)
    ev = evidence(rec, memory, y - memory, sigma, only="initial_state")["initial_state"]
    assert ev["present"] and ev["statistic"] > ev["threshold"]


def test_ringing_memory_named_initial_state_and_explained(record):
    t, v, y, sigma, _ = record
    rep = diagnose(t, v, y, progress=False)
    assert rep.effects == ["initial_state"]
    assert rep.verdict == "explained" and rep.rms_heldout <= 1.5 * sigma
    desc = next(p for p in rep.model.describe() if p["kind"] == "ringing_preload")
    # the fitted decay of the alternation: the true one is 0.62 a half cycle; the part's
    # sequence of reversal points about the first input stands in for a continuous cosine
    # over 200 plays drawn with 20, so only its presence and rough size are asserted
    assert 0.3 < desc["ringing"] < 0.85, desc
    # the returned model reproduces the reported held-out RMS (the 1e-9), and its
    # exact inverse starts from the same preloaded plays: model(inverse(r)) = r to 1e-6 of
    # the span over the record's first 4,000 samples, where the memory is
    held = ~rep._rec.train
    assert np.sqrt(np.mean((y - rep.model.simulate(v))[held] ** 2)) == pytest.approx(rep.rms_heldout, rel=1e-9)
    ref = 0.8 * rep.model.simulate(v)[:4000]
    u = rep.model.exact_inverse().simulate(ref)
    assert np.max(np.abs(rep.model.simulate(u) - ref)) < 1e-6 * np.ptp(ref)

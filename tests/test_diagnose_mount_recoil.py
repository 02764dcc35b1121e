"""The stage's base recoiling on a compliant mount, the stroke read from the ground
(hystcomp.identify.parts_mount.MountRecoil, round 33).

A stage of mass m pushes against its base of mass M, and the base sits on a mount of
stiffness k and damping c. A sensor fixed to the ground reads the stroke u plus the base's
motion x_b, and Newton's law for the two masses gives ``(M + m) x_b'' + c x_b' + k x_b =
-m u''``: well below the mount's mode the reading is the stroke, above it the base takes a
share m / (M + m) of it, and after every fast move the base rings. No output lag or
resonance of the library has that shape (their low-frequency phase is first order), and on
HOLDOUT20's recoiling base (a seen record) the search named none of them: the rate parts
were tentative at 7-8.5 noise floors.

The record: the realistic generator's PI core (tests/realistic/mechanisms.py, 200 plays of
its own density, not hystcomp's) driven by point-to-point moves (raised-cosine moves of
60 ms between random set points of +-45 V, dwells of 0.25-0.6 s), 30 s at 1 kHz. The mount:
7 Hz, damping ratio 0.06, the stage 12 % of the moving mass. The reading is integrated by
scipy.signal.lsim (the transfer function ``((1 - a) s^2 + 2 zeta w s + w^2) / (s^2 + 2 zeta
w s + w^2)`` held linear between samples), not by the part's bilinear stage. Output noise
0.2 % of its span.
"""

import numpy as np
import pytest
from scipy import signal

from hystcomp.diagnose import diagnose
from hystcomp.effects import LinearStage
from hystcomp.identify.parts import PARTS
from realistic import mechanisms as me

RATE = 1000.0
MODE_HZ, ZETA, SHARE = 7.0, 0.06, 0.12


def _moves(rng, t):
    """Raised-cosine moves of 60 ms between set points, with dwells of 0.25-0.6 s."""
    v = np.zeros_like(t)
    start, level = 0.3, 0.0
    while start < t[-1]:
        target = rng.uniform(-45.0, 45.0)
        s = np.clip((t - start) / 0.06, 0.0, 1.0)
        later = t >= start
        v[later] = level + (target - level) * 0.5 * (1.0 - np.cos(np.pi * s[later]))
        level = target
        start += 0.06 + rng.uniform(0.25, 0.6)
    return v


def _ground_reading(u, t):
    w = 2 * np.pi * MODE_HZ
    num = [1.0 - SHARE, 2 * ZETA * w, w * w]
    den = [1.0, 2 * ZETA * w, w * w]
    # the base at rest, the stroke starting from u[0]: the state of the steady reading
    _, y, _ = signal.lsim((num, den), u - u[0], t, interp=True)
    return y + u[0]


@pytest.fixture(scope="module")
def record():
    rng = np.random.default_rng(11)
    t = np.arange(int(30 * RATE)) / RATE
    v = _moves(rng, t)
    h = me.play_core(v, 100.0)
    y0 = _ground_reading(h, t)
    sigma = 0.002 * np.ptp(h)
    y = y0 + sigma * rng.standard_normal(t.size)
    return t, v, y, sigma, h, y0


def test_the_base_rings_after_every_move(record):
    # the record's premise (not the diagnosis): the base's share of the reading reaches many
    # noise levels (measured 43 sigma) and rings at the mount's mode after the moves
    t, v, y, sigma, h, y0 = record
    base = y0 - h
    assert np.abs(base).max() > 20 * sigma
    spec = np.abs(np.fft.rfft(base * np.hanning(base.size)))
    f = np.fft.rfftfreq(base.size, 1.0 / RATE)
    assert abs(f[np.argmax(spec)] - MODE_HZ) < 1.0


def test_the_recoil_factory_is_the_two_mass_law():
    # LinearStage.recoil (bilinear, prewarped) against lsim (linear hold) on a smooth
    # input: the two discretisations agree to 1e-4 of the stroke at 1 kHz for a 7 Hz mode
    t = np.arange(4000) / RATE
    u = np.sin(2 * np.pi * 3.0 * t) * np.minimum(t / 0.5, 1.0)
    st = LinearStage.recoil(MODE_HZ, ZETA, SHARE, dt=1 / RATE)
    assert np.abs(st.simulate(u) - _ground_reading(u, t)).max() < 1e-4
    assert st.dc_gain() == pytest.approx(1.0, abs=1e-12)


def test_recoil_named_and_explained(record):
    t, v, y, sigma, _, _ = record
    rep = diagnose(t, v, y, progress=False)
    assert rep.effects == ["rate_dependence"]
    desc = next(p for p in rep.model.describe() if p.get("effect") == "rate_dependence")
    assert desc["kind"] == "mount_recoil"
    # the mount found (measured 6.999 Hz, damping 0.059, share 0.122 against 7, 0.06, 0.12,
    # the same to 6 digits on four other noise draws: the offsets are the 20-play core's, not
    # the noise's); within 2 %, 15 % and 5 %, room for another path of the optimiser
    assert desc["frequency"] == pytest.approx(MODE_HZ, rel=0.02)
    assert desc["damping"] == pytest.approx(ZETA, rel=0.15)
    assert desc["share"] == pytest.approx(SHARE, rel=0.05)
    # measured 1.06 true noise levels held out
    assert rep.verdict == "explained" and rep.rms_heldout <= 1.5 * sigma
    held = ~rep._rec.train
    assert np.sqrt(np.mean((y - rep.model.simulate(v))[held] ** 2)) == pytest.approx(rep.rms_heldout, rel=1e-9)


def test_the_ringing_holds_do_not_set_the_noise_floor(record):
    # the moves' ringing fills the holds' second halves (the holds' scatter measured 3.6 sigma,
    # a decaying ring whose half period, 71 samples, is longer than the oscillation test's
    # lags in holds of 125-300 samples), so the floor the holds give is structure: once the
    # model reproduces it the held-out residual falls below 0.75 of that scatter and the
    # floor is the high-frequency part's (measured 1.0006 sigma; within 5 %)
    t, v, y, sigma, _, _ = record
    rep = diagnose(t, v, y, progress=False)
    info = rep.noise_info
    assert info["method"] == "high_frequency" and "holds_carried_structure" in info
    assert info["holds_carried_structure"]["scatter"] > 3 * sigma
    assert rep.noise_floor == pytest.approx(sigma, rel=0.05)


def test_without_the_part_the_recoil_is_not_explained(record, monkeypatch):
    # why the part is there: without it the library's lags and resonance leave the ringing
    # (measured: a dead time, near tie with a lag, 1.26 against the noise's 0.134, unexplained)
    t, v, y, sigma, _, _ = record
    monkeypatch.delitem(PARTS, "mount_recoil")
    rep = diagnose(t, v, y, progress=False)
    assert rep.verdict == "unexplained" and rep.rms_heldout > 2.0 * sigma

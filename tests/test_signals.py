"""hystcomp.signals: the identification experiment holds every part it promises."""

import numpy as np
import pytest

from hystcomp.diagnose.record import find_holds as _holds
from hystcomp.signals import decaying_sine, identification_experiment, multisine, staircase


def test_experiment_parts_and_layout():
    exp = identification_experiment(dt=0.01, duration=40.0, amplitude=2.0)
    t, v, seg = exp
    assert t.size == v.size == 4000
    np.testing.assert_allclose(np.diff(t), 0.01, rtol=1e-9)
    names = [s[0] for s in seg]
    assert names == ["decaying sine", "sines", "staircase", "multisine", "sines", "staircase", "multisine"]
    # the segments tile the record
    assert seg[0][1] == 0.0 and seg[-1][2] == pytest.approx(40.0)
    for a, b in zip(seg[:-1], seg[1:]):
        assert a[2] == pytest.approx(b[1])
    # the second pass (the default held-out tail) starts at 70 % of the record
    assert seg[4][1] == pytest.approx(28.0)
    assert np.abs(v).max() == pytest.approx(2.0)
    # every part starts and ends near 0 (no jump between parts larger than a staircase step)
    for _, a, b in seg:
        k = int(round(a / 0.01))
        assert abs(v[k]) < 0.6


def test_staircase_holds_in_both_directions_and_none_without():
    exp = identification_experiment(dt=0.01)
    holds = _holds(exp.v, 0.01, np.ptp(exp.v))
    steps = np.array([h[2] for h in holds])
    # 4 levels per quarter: 16 levels per pass, holds after rising and after falling steps
    assert len(holds) >= 24
    assert (steps > 0).sum() >= 8 and (steps < 0).sum() >= 8
    no = identification_experiment(dt=0.01, holds=False)
    assert _holds(no.v, 0.01, np.ptp(no.v)) == []
    assert "sines (no holds)" in [s[0] for s in no.segments]


def test_sines_at_every_frequency():
    dt = 0.005
    t, v, seg = identification_experiment(dt=dt, frequencies=(1.0, 5.0))
    a, b = seg[1][1], seg[1][2]
    part = v[int(a / dt):int(b / dt)]
    spec = np.abs(np.fft.rfft(part))
    f = np.fft.rfftfreq(part.size, dt)
    top = sorted(f[np.argsort(spec)[-2:]])
    assert top == pytest.approx([1.0, 5.0], abs=0.2)


def test_helpers():
    assert staircase(7, [1.0, 2.0, 3.0]).tolist() == [1, 1, 2, 2, 3, 3, 3]
    tt = np.linspace(0, 1, 1001)
    v = multisine(tt, [2, 4, 8], amplitude=3.0)
    assert np.abs(v).max() == pytest.approx(3.0) and abs(v[0]) < 1e-12 and abs(v[-1]) < 1e-12
    d = decaying_sine(tt, 5.0, final_fraction=0.5)
    assert np.abs(d[-100:]).max() < 0.55 * np.abs(d[:100]).max()


def test_bad_arguments():
    with pytest.raises(ValueError, match="frequencies"):
        identification_experiment(dt=0.1, frequencies=(1.0, 8.0))
    with pytest.raises(ValueError, match="dt"):
        identification_experiment(dt=0.0)
    with pytest.raises(ValueError, match="tail"):
        identification_experiment(tail=0.95)

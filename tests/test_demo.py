"""hystcomp.demo end to end on a short record."""

import argparse
import csv
import os

import numpy as np
import pytest

from hystcomp import demo
from hystcomp.iosys import compensator_system


def _args(tmp_path, *extra):
    p = argparse.ArgumentParser()
    demo.add_arguments(p)
    return p.parse_args(["--out", str(tmp_path), "--duration", "2", *extra])


def test_demo_runs_and_tells_the_story(tmp_path):
    lines = []
    res = demo.run(_args(tmp_path), echo=lines.append, progress_stream=None)
    # 2 references x 7 loops
    assert len(res["rows"]) == 14
    assert all(ok for ok, _ in res["checks"].values()), res["checks"]
    assert len(res["checks"]) == 7
    # the same specification, two safe crossovers: the compensated loop reaches a higher one
    d = res["design"]
    assert d["compensated_hz"] > d["raw_hz"]
    for f in (1.0, 5.0):
        rows = {r["loop"]: r for r in res["rows"] if r["reference_hz"] == f}
        for key in ("pid_raw_safe", "pid_raw_fast", "pid_compensated", "two_dof"):
            assert rows[key]["rms"] < rows["open_loop"]["rms"], (f, key)
    names = sorted(os.listdir(tmp_path))
    assert "loop_comparison.csv" in names
    assert sum(n.endswith(".png") for n in names) == 3
    with open(tmp_path / "loop_comparison.csv") as fh:
        rows = list(csv.DictReader(fh))
    assert len(rows) == 14 and float(rows[0]["rms"]) == pytest.approx(res["rows"][0]["rms"], rel=1e-12)
    text = "\n".join(lines)
    assert "stability_margins" in text and "PASS" in text and "FAIL" not in text
    # the margins table prints crossover frequencies, not the stability margin / 2 pi
    fc = d["compensated_hz"]
    gm, pm, f_phase, f_gain = d["margins"][("comp", "k_nom")]
    assert f_gain == pytest.approx(fc, rel=1e-4) and pm == pytest.approx(60.0, abs=0.01)
    assert f"{f_gain:12.2f} Hz" in text and f"{f_phase:13.1f} Hz" in text


def test_every_option_has_help():
    p = argparse.ArgumentParser()
    demo.add_arguments(p)
    for action in p._actions:
        if action.dest != "help":
            assert action.help, action.dest


def test_demo_actuator_gain_matches_the_issue():
    # the issue: the raw actuator's mean gain is "about 2.5" in this setting
    k = compensator_system(demo.demo_actuator(), nominal_gain="auto", input_range=(-2.0, 2.0)).nominal_gain
    assert 2.2 < k < 3.0
    assert bool(demo.demo_actuator().is_invertible())  # the analytic inverse exists


def test_stability_table_reads_python_controls_tuple_right():
    from hystcomp.iosys import discretize, piezo_stage

    plant = discretize(piezo_stage(), 1e-4)
    (k1, gm1, pm1, fp1, fc1), (k2, gm2, _, fp2, fc2) = demo.stability_table(0, 40.0, 0, 1e-4, [2.712, 5.424], plant)
    # the issue: 17.3 Hz gain crossover, 300 Hz phase crossover for this loop
    assert fc1 == pytest.approx(17.3, abs=0.05) and fp1 == pytest.approx(300.0, abs=0.5)
    # a loop gain twice as large halves the gain margin and keeps the phase crossover
    # (python-control's frd evaluation: 1e-6)
    assert gm1 / gm2 == pytest.approx(2.0, rel=1e-6) and fp2 == pytest.approx(fp1, rel=1e-6)
    assert fc2 > fc1


def test_crossover_scan_guarantee_shrinks_with_bandwidth():
    from hystcomp.iosys import piezo_stage

    rows = demo.crossover_scan(piezo_stage(), 1e-4, 2.712, {"raw": (1.485, 3.867), "comp": (2.712, 2.712)},
                               [20.0, 50.0, 80.0, 90.0])
    # 90 Hz: the resonance peak crosses 0 dB with a roll-off at 180 Hz: not designable, skipped
    assert [r["crossover_hz"] for r in rows] == [20.0, 50.0, 80.0]
    g_raw = np.array([r["g_raw"] for r in rows])
    g_comp = np.array([r["g_comp"] for r in rows])
    assert np.all(np.diff(g_raw) < 0) and np.all(np.diff(g_comp) < 0)
    assert np.all(g_comp > g_raw)          # the wider sector always guarantees less

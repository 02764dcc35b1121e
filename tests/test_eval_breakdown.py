"""The realistic evaluation's breakdown of wrong runs (``benchmarks/eval_diagnose_realistic.py``:
``breakdown``, ``--summary``), on hand-made rows whose kinds are known."""

import json
import os
import sys

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "benchmarks"))

from eval_diagnose_realistic import WRONG_KINDS, breakdown, main, read_csv, write_csv, wrong_kind  # noqa: E402


def _row(expected, effects, right, verdict="explained", tie=None, error=None, **kw):
    row = {"case": "c", "seed": 0, "expected": expected, "effects": effects, "right": right,
           "right_or_tie": right if tie is None else tie, "verdict": verdict, "error": error,
           "expect_verdict": "either", "ambiguous": {}, "explained_over_limit": False,
           "clean": not expected, "combined": len(expected) >= 2}
    row.update(kw)
    return row


ROWS = [
    _row(["creep"], ["creep"], True),
    _row(["creep"], ["creep"], False, verdict="unexplained"),                       # verdict
    _row(["drift"], [], False, verdict="unexplained"),                               # missed
    _row(["asymmetry", "creep"], ["creep"], False),                                  # missed, silent
    _row(["creep"], ["creep", "asymmetry"], False, verdict="unexplained"),           # extra
    _row([], ["saturation"], False),                                                 # extra (clean)
    _row(["delay"], ["rate_dependence"], False, tie=True),                           # confused, a tie
    _row(["rate_dependence"], ["delay"], False, tie=True),                           # confused, a tie
    _row(["delay"], ["rate_dependence", "asymmetry"], False, verdict="unexplained"),  # confused
    _row(["delay"], [], False, verdict="crash", error="ValueError: x"),              # crash
    # a gain drift is a drift by family: right by family, here wrongly marked, is a verdict error
    _row(["drift"], ["gain_drift"], False, verdict="unexplained"),
]


def test_each_wrong_run_gets_one_kind():
    kinds = [wrong_kind(r) for r in ROWS]
    assert kinds == [None, "verdict", "missed", "missed", "extra", "extra", "confused", "confused", "confused",
                     "crash", "verdict"]
    assert set(kinds) - {None} == set(WRONG_KINDS)


def test_breakdown_counts_kinds_ties_and_families():
    b = breakdown(ROWS)
    assert b["n"] == 11 and b["wrong"] == 10
    assert list(b["kinds"]) == list(WRONG_KINDS)          # in the documented order
    assert b["kinds"]["verdict"] == {"count": 2, "tie": 0, "unexplained": 2}
    assert b["kinds"]["missed"] == {"count": 2, "tie": 0, "unexplained": 1}
    assert b["kinds"]["extra"] == {"count": 2, "tie": 0, "unexplained": 1}
    assert b["kinds"]["confused"] == {"count": 3, "tie": 2, "unexplained": 1}
    assert b["kinds"]["crash"]["count"] == 1
    # families missed: delay 2 (the crash is not counted), rate 1, drift 1, asymmetry 1
    assert dict(b["missed"]) == {"delay": 2, "rate_dependence": 1, "drift": 1, "asymmetry": 1}
    assert dict(b["extra"]) == {"asymmetry": 2, "saturation": 1, "rate_dependence": 2, "delay": 1}
    assert dict(b["confusions"]) == {("delay", "rate_dependence"): 1, ("rate_dependence", "delay"): 1,
                                     ("delay", "asymmetry+rate_dependence"): 1}
    assert sum(x["count"] for x in b["kinds"].values()) == b["wrong"]


def test_breakdown_of_right_runs_only():
    b = breakdown(ROWS[:1])
    assert b["wrong"] == 0 and b["kinds"] == {} and b["missed"] == []


def test_summary_reprints_a_saved_run(tmp_path, capsys):
    path = tmp_path / "run.json"
    path.write_text(json.dumps({"rows": ROWS, "right": 1, "n": len(ROWS), "seconds": 12.0}))
    assert main(["--summary", str(path)]) == 0
    out = capsys.readouterr().out
    assert "right verdict: 1/11" in out and "crashes: 1; total 12 s" in out
    assert "wrong runs: 10/11" in out
    assert "3  an expected effect missed and another named instead (2 tie, 1 unexplained)" in out
    assert "delay -> rate_dependence 1" in out


@pytest.mark.parametrize("name, text", [("bad.json", "{not json"), ("other.csv", "case,seed\nx,0\n")])
def test_summary_of_a_bad_file_is_one_line_and_exit_2(tmp_path, capsys, name, text):
    """A file that is not a saved run (broken JSON, or a CSV file with other columns than a results file's)."""
    path = tmp_path / name
    path.write_text(text)
    with pytest.raises(SystemExit) as exc:
        main(["--summary", str(path)])
    assert exc.value.code == 2
    err = capsys.readouterr().err
    assert f"--summary '{path}': not a --json or --csv file of this script" in err


def test_csv_round_trip_and_summary(tmp_path, capsys):
    """A results file holds every field the figures and the breakdown need: written and read
    back, the rows give the same summary as the JSON, and a step's fields survive."""
    rows = [dict(r, case=f"c{i}", true_noise=0.1, rms_heldout=0.12345678, noise_floor=0.1, rms_base=0.5,
                 seconds=1.234, steps=[{"effect": "creep", "kind": "creep_lags", "gain": 36.8515,
                                        "loss_without": None, "dropped": False, "tentative": True,
                                        "core_shape": False}])
            for i, r in enumerate(ROWS)]
    rows[1]["ambiguous"] = {"creep": ["drift", "gain_drift"]}
    path = tmp_path / "runs.csv"
    write_csv(rows, str(path), measured_on="abc1234")
    back = read_csv(str(path))
    assert [(r["case"], r["effects"], r["verdict"], r["right"], r["right_or_tie"], r["error"]) for r in back] == [
        (r["case"], r["effects"], r["verdict"], r["right"], r["right_or_tie"], r["error"]) for r in rows]
    assert back[1]["ambiguous"] == {"creep": ["drift", "gain_drift"]}
    assert back[0]["rms_heldout"] == pytest.approx(0.123457, abs=1e-9)     # 6 significant digits
    assert back[0]["steps"] == [{"effect": "creep", "kind": "creep_lags", "gain": 36.8515, "loss_without": None,
                                 "dropped": False, "tentative": True, "core_shape": False}]
    assert {r["measured_on"] for r in back} == {"abc1234"}
    assert main(["--summary", str(path)]) == 0
    assert "right verdict: 1/11" in capsys.readouterr().out


def test_compare_lists_changed_runs(tmp_path, capsys):
    """--compare: the runs whose named effects or verdict changed, and the net change in right runs."""
    rows = [dict(r, case=f"c{i}") for i, r in enumerate(ROWS)]
    old = tmp_path / "old.json"
    old.write_text(json.dumps({"rows": rows}))
    new_rows = [dict(r) for r in rows]
    new_rows[2] = dict(new_rows[2], effects=["drift"], right=True, right_or_tie=True)   # missed -> right
    new_rows[0] = dict(new_rows[0], effects=[], right=False, right_or_tie=False)        # right -> wrong
    new = tmp_path / "new.json"
    new.write_text(json.dumps({"rows": new_rows}))
    assert main(["--summary", str(new), "--compare", str(old)]) == 0
    out = capsys.readouterr().out
    assert "changed answers: 2 of 11 runs; right: +1 -1 (net +0)" in out


def test_perturbation_is_small_and_repeatable():
    """--perturb moves the output by noise of the given share of the true noise, the same for a
    case and seed on every run, another for another seed."""
    import numpy as np

    from eval_diagnose_realistic import perturbed

    y = np.linspace(0.0, 1.0, 20000)
    a = perturbed(y, 0.5, 1e-4, "case", 0)
    assert np.array_equal(a, perturbed(y, 0.5, 1e-4, "case", 0))
    assert not np.array_equal(a, perturbed(y, 0.5, 1e-4, "case", 1))
    # the standard deviation of 20,000 draws is within 3 % of 0.5e-4 (its relative standard error is 0.5 %)
    assert np.std(a - y) == pytest.approx(0.5e-4, rel=0.03)


def test_negative_perturbation_is_refused(capsys):
    with pytest.raises(SystemExit) as exc:
        main(["--perturb", "-1", "--cases", "x"])
    assert exc.value.code == 2
    assert "--perturb -1.0: should be 0 or more" in capsys.readouterr().err

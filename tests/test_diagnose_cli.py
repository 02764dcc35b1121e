"""``hystcomp diagnose DATA.csv``: through a tiny argparse harness around
hystcomp.diagnose.add_arguments/run (and through the real command when
hystcomp/cli.py has the subcommand)."""

import argparse
import json
import subprocess
import sys

import numpy as np
import pytest

from hystcomp import diagnose as dg
from hystcomp.datasets import hidden_effect_data


def _run(argv, capsys):
    parser = dg.add_arguments(argparse.ArgumentParser(prog="hystcomp diagnose"))
    status = dg.run(parser.parse_args(argv))
    out, err = capsys.readouterr()
    return status, out, err


def _write(path, header, rows):
    with open(path, "w") as fh:
        fh.write(",".join(header) + "\n")
        for r in rows:
            fh.write(",".join(str(x) for x in r) + "\n")
    return str(path)


@pytest.fixture(scope="module")
def drift_csv(tmp_path_factory):
    d = hidden_effect_data("drift", seed=2, dt=0.0125)
    p = tmp_path_factory.mktemp("cli") / "drift.csv"
    return _write(p, ["time", "volts", "um"], zip(d.t, d.v, d.y))


def test_json_schema(drift_csv, capsys, tmp_path):
    status, out, err = _run([drift_csv, "--time", "time", "--input", "volts", "--output", "um", "--json",
                             "--plots", str(tmp_path / "figs"), "--units", "V,um"], capsys)
    assert status == 0, err
    js = json.loads(out)                 # exactly one JSON object on stdout
    assert js["schema_version"] == 30
    assert list(js)[:4] == ["schema_version", "verdict", "noise_floor", "noise_floor_pct"]
    assert js["effects"][0] == "drift" and js["verdict"] == "explained"
    assert js["rms_after"] < 0.5 * js["rms_before"]
    assert js["rms_after_pct"] == pytest.approx(100 * js["rms_after"] / js["output_span"])
    assert isinstance(js["untested"], dict) and js["stopped"]
    s = js["steps"][0]
    assert list(s) == ["effect", "rms_before", "rms_after", "rms_before_pct", "rms_after_pct", "evidence", "dropped",
                       "tentative", "core_shape", "alternatives"]
    assert s["dropped"] is False and s["tentative"] is False and js["tentative_effects"] == []
    assert isinstance(js["ambiguous"], dict) and isinstance(s["alternatives"], list)
    assert isinstance(s["evidence"]["acceptable"], dict) and "offset_drift" in s["evidence"]["acceptable"]
    assert js["misfit_share_explained"] > 0.9
    assert isinstance(js["revisions"], list)
    assert s["effect"] == "drift"
    sig = s["evidence"]["signature"]
    assert sig["present"] and sig["statistic"] > sig["threshold"]
    assert sorted(p.name for p in (tmp_path / "figs").glob("*.png")) == [
        "diagnose_gap.png", "diagnose_loops.png", "diagnose_signatures.png"]
    # progress (tqdm) shows on a terminal only: redirected, stderr has only the files written
    assert "diagnose:" not in err and "\r" not in err and "wrote" in err


def test_units_on_the_axes(drift_csv, capsys):
    from hystcomp.diagnose import diagnose

    d = hidden_effect_data("drift", seed=2, dt=0.0125)
    rep = diagnose(d.t, d.v, d.y, effects=["drift"], progress=False)
    figs = rep.plots(input_unit="V", output_unit="um")
    labels = [a.get_xlabel() + " | " + a.get_ylabel() for f in figs.values() for a in f.axes]
    assert any("input v [V]" in lab and "residual [um]" in lab for lab in labels)
    assert any("dv/dt [V/s]" in lab for lab in labels) and any("output y [um]" in lab for lab in labels)
    assert not any("units]" in lab for lab in labels)
    # by default no unit is written (no "input units" placeholder)
    bare = [a.get_xlabel() + " | " + a.get_ylabel() for f in rep.plots().values() for a in f.axes]
    assert any(lab.startswith("input v | output y") for lab in bare) and not any("units" in lab for lab in bare)
    # the signatures panel says why a test under its threshold is present (its pair's test read the misfit)
    text = figs["signatures"].axes[3].texts[0].get_text()
    for name, ev in rep.first_evidence.items():
        line = next(li for li in text.splitlines() if li.startswith(name + ":"))
        assert ("PRESENT" in line) == ev["present"]
        if ev["present"] and ev["statistic"] <= ev["threshold"]:
            assert line.endswith("'s test)") and "PRESENT (by " in line, line
    assert any("PRESENT (by rate_dependence's test)" in li for li in text.splitlines())   # delay here: 0.46 < 0.5
    status, out, err = _run([drift_csv, "--units", "V", "--quiet"], capsys)
    assert status == 2 and "--units" in err and "Traceback" not in err


def test_the_figures_name_the_columns(drift_csv, capsys, tmp_path, monkeypatch):
    """From the CLI the axes carry the CSV's column names, with units only when --units gives them (not the
    placeholders "input units", "output units")."""
    from hystcomp.diagnose.report import Diagnosis

    seen = []
    plots = Diagnosis.plots

    def recording(self, *args, **kwargs):
        figs = plots(self, *args, **kwargs)
        seen.append([a.get_xlabel() + " | " + a.get_ylabel() for f in figs.values() for a in f.axes])
        return figs

    monkeypatch.setattr(Diagnosis, "plots", recording)
    common = [drift_csv, "--time", "time", "--input", "volts", "--output", "um", "--quiet"]
    assert _run(common + ["--plots", str(tmp_path / "a")], capsys)[0] == 0
    assert _run(common + ["--plots", str(tmp_path / "b"), "--units", "V,um"], capsys)[0] == 0
    bare, with_units = seen
    assert any(lab.startswith("volts | um") for lab in bare)              # the loops: output against input
    assert any(lab.startswith("volts | residual") for lab in bare)
    assert any("rate of volts [per s]" in lab for lab in bare)
    assert not any("units" in lab or "input v" in lab for lab in bare)
    assert any(lab.startswith("volts [V] | um [um]") for lab in with_units)
    assert any("rate of volts [V/s]" in lab and "residual [um]" in lab for lab in with_units)
    # a bad name is refused naming the argument
    with pytest.raises(TypeError, match="input_name"):
        plots(Diagnosis.__new__(Diagnosis), input_name="")


def test_summary_text_and_none(tmp_path, capsys):
    d = hidden_effect_data(None, seed=3, dt=0.0125)
    p = _write(tmp_path / "plain.csv", ["t", "v", "y"], zip(d.t, d.v, d.y))
    status, out, _ = _run([p, "--quiet"], capsys)
    assert status == 0 and "verdict: explained; effects: none" in out
    status, out, _ = _run([p, "--quiet", "--json"], capsys)
    assert json.loads(out)["effects"] == [] and json.loads(out)["steps"] == []


def test_no_time_column(tmp_path, capsys):
    d = hidden_effect_data("saturation", seed=3, dt=0.0125, mechanism="tanh_envelope")
    p = _write(tmp_path / "bh.csv", ["H", "B"], zip(d.v, d.y))
    status, out, err = _run([p, "--no-time", "--input", "H", "--output", "B", "--json", "--quiet"], capsys)
    assert status == 0, err
    js = json.loads(out)
    assert js["effects"][0] == "saturation"
    assert {"rate_dependence", "creep", "drift", "delay"} <= set(js["untested"])


def test_one_second_sampling_step(tmp_path, capsys):
    # dt = 1 s: nothing may assume a frequency above Nyquist (once a "bad data file")
    d = hidden_effect_data("drift", seed=4, dt=0.0125)
    p = _write(tmp_path / "slow.csv", ["t", "v", "y"], zip(np.arange(d.t.size) * 1.0, d.v, d.y))
    status, out, err = _run([p, "--quiet", "--json"], capsys)
    assert status == 0, err
    assert json.loads(out)["verdict"] in ("explained", "unexplained")


def test_internal_failure_is_one_line_not_bad_file(tmp_path, capsys, monkeypatch):
    d = hidden_effect_data(None, seed=3, dt=0.0125)
    p = _write(tmp_path / "plain.csv", ["t", "v", "y"], zip(d.t, d.v, d.y))
    from hystcomp.diagnose import search

    def broken(*args, **kw):
        raise np.linalg.LinAlgError("SVD did not converge")
    monkeypatch.setattr(search, "run_search", broken)
    monkeypatch.setattr(dg, "run_search", broken)
    status, out, err = _run([p, "--quiet"], capsys)
    assert status == 2 and out == ""
    lines = err.strip().splitlines()
    assert len(lines) == 1 and "internal error" in lines[0] and "SVD did not converge" in lines[0]


GOOD = [(0.01 * k, np.sin(0.1 * k), np.sin(0.1 * k)) for k in range(200)]


@pytest.mark.parametrize("case,header,rows,message", [
    ("missing column", ["t", "v", "z"], GOOD, "no column 'y'"),
    ("non-numeric", ["t", "v", "y"], GOOD[:50] + [(0.5, "abc", 1.0)] + GOOD[51:], "not a number"),
    ("nan", ["t", "v", "y"], GOOD[:50] + [(0.5, "nan", 1.0)] + GOOD[51:], "finite"),
    ("unsorted time", ["t", "v", "y"], GOOD[:50] + [(0.1, 0.0, 0.0)] + GOOD[51:], "does not increase"),
    ("too few samples", ["t", "v", "y"], GOOD[:20], "at least 100"),
    ("constant input", ["t", "v", "y"], [(0.01 * k, 1.0, np.sin(0.1 * k)) for k in range(200)], "constant"),
    ("uneven time", ["t", "v", "y"], [(0.01 * k + (0.004 if k == 100 else 0), np.sin(0.1 * k), 0.0)
                                     for k in range(200)], "uniformly sampled"),
])
def test_bad_files_exit_2_with_one_line(tmp_path, capsys, case, header, rows, message):
    p = _write(tmp_path / "bad.csv", header, rows)
    status, out, err = _run([p, "--json"], capsys)
    assert status == 2, case
    assert out == ""
    lines = err.strip().splitlines()
    assert len(lines) == 1 and message in lines[0] and lines[0].startswith("hystcomp diagnose: error:")
    assert "Traceback" not in err


def test_missing_file_exit_2(tmp_path, capsys):
    status, _, err = _run([str(tmp_path / "nope.csv")], capsys)
    assert status == 2 and "cannot read" in err


def _cli_has_diagnose():
    try:
        from hystcomp import cli
        parser = cli.build_parser()
        return any("diagnose" in getattr(a, "choices", {}) or {} for a in parser._actions
                   if isinstance(a, argparse._SubParsersAction))
    except Exception:
        return False


@pytest.mark.skipif(not _cli_has_diagnose(), reason="hystcomp/cli.py has no diagnose subcommand yet "
                    "(wired by the lead)")
def test_through_the_hystcomp_command(drift_csv, tmp_path):
    bad = _write(tmp_path / "bad.csv", ["t", "v"], GOOD)
    proc = subprocess.run([sys.executable, "-m", "hystcomp.cli", "diagnose", bad, "--json"],
                          capture_output=True, text=True, timeout=300)
    assert proc.returncode == 2 and len(proc.stderr.strip().splitlines()) == 1
    proc = subprocess.run([sys.executable, "-m", "hystcomp.cli", "diagnose", drift_csv, "--time", "time",
                           "--input", "volts", "--output", "um", "--json"],
                          capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, proc.stderr
    assert json.loads(proc.stdout)["effects"][0] == "drift"
    proc = subprocess.run([sys.executable, "-m", "hystcomp.diagnose", bad, "--json"],
                          capture_output=True, text=True, timeout=300)
    assert proc.returncode == 2 and len(proc.stderr.strip().splitlines()) == 1


def test_several_files_on_two_processes(tmp_path, capsys):
    # several records, diagnosed independently (on an executor with --jobs): a JSON list
    # naming each file, the same answers as one file at a time
    from hystcomp.datasets import hidden_effect_data

    paths = []
    for effect in ("drift", None):
        d = hidden_effect_data(effect, seed=3, dt=0.01)
        paths.append(_write(tmp_path / f"{effect}.csv", ["t", "v", "y"], zip(d.t, d.v, d.y)))
    status, out, err = _run([*map(str, paths), "--json", "--jobs", "2", "--plots", str(tmp_path / "figs")],
                            capsys)
    assert status == 0, err
    js = json.loads(out)
    assert [r["file"] for r in js] == [str(p) for p in paths]
    assert js[0]["effects"][:1] == ["drift"] and js[1]["effects"] == []
    one = json.loads(_run([str(paths[0]), "--json", "--quiet"], capsys)[1])
    assert one["effects"] == js[0]["effects"] and one["rms_heldout"] == pytest.approx(js[0]["rms_heldout"])
    assert (tmp_path / "figs" / "drift" / "diagnose_gap.png").exists()
    status, _, err = _run([str(paths[0]), str(tmp_path / "missing.csv")], capsys)
    assert status == 2 and "missing.csv" in err and "Traceback" not in err


def test_held_out_option(tmp_path, capsys):
    # a staircase whose largest levels come last: by default (auto) a block inside the
    # record is held out, with --held-out last the end; both in the JSON and the report
    from realistic import excitations as ex
    from realistic import mechanisms as me

    rng = np.random.default_rng([6, 781])
    levels = np.array([0.0, 10.0, -10.0, 15.0, -12.0, 12.0, -15.0, 40.0, -40.0, 35.0])
    v = ex.staircase_holds(2e-3, levels, 0.8, 0.05)
    t = np.arange(v.size) * 2e-3
    y = me.play_core(v, 100.0) + 0.05 * rng.standard_normal(v.size)
    path = _write(tmp_path / "late.csv", ["t", "v", "y"], zip(t, v, y))
    out = {}
    for mode in ("auto", "last"):
        status, o, err = _run([path, "--json", "--quiet", "--held-out", mode], capsys)
        assert status == 0, err
        out[mode] = json.loads(o)
    assert out["auto"]["held_out_moved"] > 0.05 and out["auto"]["validation"][1] < t[-1] - 1.0
    assert out["auto"]["held_out_beyond_fitted_range"] <= 0.05
    assert out["last"]["held_out_moved"] == 0.0 and out["last"]["validation"][1] == pytest.approx(t[-1])
    assert out["last"]["held_out_beyond_fitted_range"] > 0.05
    status, o, err = _run([path, "--quiet"], capsys)
    assert status == 0 and "inside the record" in o
    # five blocks spread over the record: each inside it, the first after its first 30 %
    status, o, err = _run([path, "--json", "--quiet", "--held-out", "blocks"], capsys)
    assert status == 0, err
    blocks = json.loads(o)["held_out_blocks"]
    assert len(blocks) == 5 and blocks[0][0] >= 0.3 * t[-1] - 2e-3 and blocks[-1][1] < t[-1]
    assert all(b[0] < b[1] < c[0] for b, c in zip(blocks, blocks[1:]))
    with pytest.raises(SystemExit) as exc:           # argparse: a choice, exit 2
        _run([path, "--held-out", "middle"], capsys)
    assert exc.value.code == 2 and "--held-out" in capsys.readouterr().err
    # the Python API names the argument and the value
    with pytest.raises(ValueError, match="held_out.*'middle'"):
        dg.diagnose(t, v, y, held_out="middle", progress=False)

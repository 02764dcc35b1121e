"""The ``hystcomp`` command never shows a traceback (issue 12): bad options
and bad files give one line naming what is wrong and exit 2; an unexpected
failure gives one line and exit 1; ``--debug`` shows the traceback."""

import subprocess
import sys

import numpy as np
import pytest

from hystcomp import cli


def _one_line_error(capsys, command):
    err = capsys.readouterr().err.strip().splitlines()
    assert err, "no message on stderr"
    assert not any("Traceback" in line for line in err)
    assert err[-1].startswith(f"hystcomp {command}: error:") or "error:" in err[-1]
    return err[-1]


@pytest.mark.parametrize("argv, names", [
    (["demo", "--dt", "0"], "--dt"),
    (["demo", "--dt", "-1e-4"], "--dt"),
    (["demo", "--dt", "nan"], "--dt"),
    (["demo", "--duration", "0"], "--duration"),
    (["demo", "--duration", "inf"], "--duration"),
    (["demo", "--dt", "1", "--duration", "0.5"], "--dt"),
    (["demo", "--freqs", "0"], "--freqs"),
    (["demo", "--freqs", "1", "-5"], "--freqs"),
    (["demo", "--crossovers", "0"], "--crossovers"),
    (["demo", "--phase-margin", "200"], "--phase-margin"),
    (["demo", "--required-margin", "0"], "--required-margin"),
    (["demo", "--stage-hz", "-300"], "--stage-hz"),
    (["demo", "--damping", "-0.1"], "--damping"),
    (["demo", "--dt", "abc"], "--dt"),
    (["demo", "--engine", "fast"], "--engine"),
    (["thesis", "--bogus"], "--bogus"),
    (["diagnose"], "DATA.csv"),
    (["diagnose", "x.csv", "--validation", "x"], "--validation"),
])
def test_bad_options_exit_2_naming_the_option(argv, names, capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    with pytest.raises(SystemExit) as exc:
        cli.main(argv)
    assert exc.value.code == 2
    line = _one_line_error(capsys, argv[0])
    assert names in line


@pytest.mark.parametrize("command", ["demo", "thesis"])
def test_out_pointing_at_a_file_fails_before_any_work(command, tmp_path, capsys):
    target = tmp_path / "afile"
    target.write_text("not a folder")
    for out in (target, target / "sub"):
        with pytest.raises(SystemExit) as exc:
            cli.main([command, "--out", str(out)])
        assert exc.value.code == 2
        line = _one_line_error(capsys, command)
        assert "--out" in line and str(out) in line
    assert target.read_text() == "not a folder"   # nothing written over it


def _csv(path, header="t,v,y", n=300, bom=False):
    t = 0.01 * np.arange(n)
    v = np.sin(2 * np.pi * 0.5 * t)
    rows = "\n".join(f"{a:.6g},{b:.6g},{b + 0.1 * np.sign(b):.6g}" for a, b in zip(t, v))
    text = header + "\n" + rows + "\n"
    path.write_bytes((b"\xef\xbb\xbf" if bom else b"") + text.encode())
    return path


def test_diagnose_plots_pointing_at_a_file_fails_before_the_diagnosis(tmp_path, capsys, monkeypatch):
    import hystcomp.diagnose as diagnose_pkg

    def never(*args, **kwargs):   # the diagnosis must not start
        raise AssertionError("diagnose ran before the --plots folder was checked")

    monkeypatch.setattr(diagnose_pkg, "diagnose", never)
    data = _csv(tmp_path / "rec.csv")
    target = tmp_path / "plots.png"
    target.write_text("x")
    code = diagnose_pkg.run(diagnose_pkg.add_arguments(__import__("argparse").ArgumentParser())
                            .parse_args([str(data), "--plots", str(target), "--quiet"]))
    assert code == 2
    line = capsys.readouterr().err.strip()
    assert "--plots" in line and "plots.png" in line and "Traceback" not in line
    with pytest.raises(SystemExit) as exc:
        cli.main(["diagnose", str(data), "--plots", str(target), "--quiet"])
    assert exc.value.code == 2


def test_csv_with_byte_order_mark_is_read(tmp_path):
    from hystcomp.diagnose.cli import load_csv

    plain = load_csv(_csv(tmp_path / "plain.csv"))
    excel = load_csv(_csv(tmp_path / "excel.csv", bom=True))   # Excel's "CSV UTF-8"
    for a, b in zip(plain, excel):
        np.testing.assert_array_equal(a, b)


@pytest.mark.parametrize("content, words", [
    (b"", "empty"),
    (b"\x00\xff\xfe\x00garbage", "not a text CSV"),
    (b"a,b,c\n1,2,3\n", "no column"),
])
def test_diagnose_bad_files_exit_2(tmp_path, capsys, content, words):
    path = tmp_path / "bad.csv"
    path.write_bytes(content)
    assert cli.main(["diagnose", str(path), "--quiet"]) == 2
    line = capsys.readouterr().err.strip()
    assert words in line and "Traceback" not in line and len(line.splitlines()) == 1


def test_diagnose_a_folder_as_data_exits_2(tmp_path, capsys):
    assert cli.main(["diagnose", str(tmp_path), "--quiet"]) == 2
    assert "Traceback" not in capsys.readouterr().err


def test_unexpected_failure_is_one_line_exit_1(tmp_path, capsys, monkeypatch):
    def boom(out, echo=print, dt=None, quiet=False):
        raise RuntimeError("simulated internal failure")

    monkeypatch.setattr(cli, "reproduce", boom)
    assert cli.main(["thesis", "--out", str(tmp_path / "o")]) == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1
    assert "hystcomp thesis" in err[0] and "RuntimeError" in err[0] and "simulated internal failure" in err[0]
    assert "--debug" in err[0]
    # bad input raised deep inside is reported as such, exit 2
    monkeypatch.setattr(cli, "reproduce", lambda out, echo=print, dt=None, quiet=False: float("x"))
    assert cli.main(["thesis", "--out", str(tmp_path / "o")]) == 2
    err = capsys.readouterr().err.strip()
    assert "ValueError" in err and "Traceback" not in err
    # --debug (before or after the command) shows the traceback: the exception propagates
    monkeypatch.setattr(cli, "reproduce", boom)
    for argv in (["--debug", "thesis", "--out", str(tmp_path / "o")],
                 ["thesis", "--out", str(tmp_path / "o"), "--debug"]):
        with pytest.raises(RuntimeError, match="simulated internal failure"):
            cli.main(argv)


def test_no_traceback_in_a_fresh_process(tmp_path):
    afile = tmp_path / "afile"
    afile.write_text("x")
    for argv in (["demo", "--dt", "0"], ["thesis", "--out", str(afile)],
                 ["diagnose", str(tmp_path / "missing.csv")]):
        proc = subprocess.run([sys.executable, "-m", "hystcomp.cli", *argv], capture_output=True,
                              text=True, timeout=300, cwd=tmp_path)
        assert proc.returncode == 2, proc.stderr
        assert "Traceback" not in proc.stderr and proc.stderr.strip()

"""``python -m hystcomp``, ``--quiet`` on every subcommand, tqdm progress that
stays off redirected streams."""

import argparse
import io
import os
import subprocess
import sys

from hystcomp import __version__, cli, demo
from hystcomp._progress import progress_bar


class _Terminal(io.StringIO):
    def isatty(self):
        return True


def test_python_dash_m_hystcomp_version():
    proc = subprocess.run([sys.executable, "-m", "hystcomp", "--version"],
                          capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.strip() == f"hystcomp {__version__}"


def test_every_subcommand_has_quiet():
    parser = cli.build_parser()
    subs = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
    assert sorted(subs.choices) == ["demo", "diagnose", "thesis"]
    for name, sub in subs.choices.items():
        options = {o for a in sub._actions for o in a.option_strings}
        assert "--quiet" in options, name


def test_progress_bar_shows_on_a_terminal_only():
    tty, pipe = _Terminal(), io.StringIO()
    assert sum(progress_bar(range(5), desc="x", file=tty)) == 10
    assert sum(progress_bar(range(5), desc="x", file=pipe)) == 10
    assert "5/5" in tty.getvalue()   # tqdm drew the bar
    assert pipe.getvalue() == ""     # not a terminal: nothing, no carriage returns
    quiet = _Terminal()
    list(progress_bar(range(5), file=quiet, enabled=False))
    assert quiet.getvalue() == ""
    # a bar that does not show answers the bar's methods and draws nothing
    for silent in (progress_bar(total=3, file=pipe), progress_bar(total=3, file=quiet, enabled=False)):
        assert silent.disable
        with silent as bar:
            bar.set_postfix_str("a", refresh=False)
            bar.set_description_str("b", refresh=False)
            bar.update()
        silent.close()
        out = io.StringIO()
        silent.write("line", file=out)
        assert out.getvalue() == "line\n"
    assert pipe.getvalue() == "" and quiet.getvalue() == ""


def test_a_bar_starts_no_monitor_thread():
    # tqdm's monitor thread would keep the diagnosis from forking its candidate fits
    # (hystcomp.identify.parallel_fits.can_fork asks for a process with no other thread)
    import threading

    before = threading.active_count()
    bar = progress_bar(total=3, desc="x", file=_Terminal())
    assert not bar.disable
    bar.update()
    assert threading.active_count() == before
    assert getattr(type(bar), "monitor", None) is None
    bar.close()


def _demo_args(out, *extra):
    p = argparse.ArgumentParser()
    demo.add_arguments(p)
    return p.parse_args(["--out", str(out), "--duration", "0.01", "--freqs", "5",
                         "--crossovers", "50", "80", "--no-figures", *extra])


def test_demo_progress_on_terminal_and_quiet(tmp_path):
    lines, tty = [], _Terminal()
    demo.run(_demo_args(tmp_path / "a"), echo=lines.append, progress_stream=tty)
    assert "loops" in tty.getvalue() and "\r" in tty.getvalue()
    assert any(line.startswith("  wrote ") for line in lines)
    lines, tty = [], _Terminal()
    res = demo.run(_demo_args(tmp_path / "b", "--quiet"), echo=lines.append, progress_stream=tty)
    assert tty.getvalue() == ""
    assert not any(line.startswith("  wrote ") for line in lines)
    assert any("PASS" in line or "FAIL" in line for line in lines)  # results still print
    assert os.path.exists(res["files"][0])


def test_thesis_quiet_prints_only_the_table(tmp_path):
    lines = []
    rows = cli.reproduce(tmp_path, echo=lines.append, dt=0.05, quiet=True)
    assert len(rows) == 6
    assert lines[0].startswith("Compensation error")
    assert not any("wrote" in line for line in lines)
    assert len(lines) == 2 + len(rows)   # title, header, one line per row


def test_redirected_subprocess_has_no_carriage_returns(tmp_path):
    proc = subprocess.run([sys.executable, "-m", "hystcomp", "demo", "--out", str(tmp_path), "--duration", "0.01",
                           "--freqs", "5", "--crossovers", "50", "80", "--no-figures"],
                          capture_output=True, text=True, timeout=600)
    # exit 1: a 10 ms record is too short for every check of the demo to pass
    assert proc.returncode in (0, 1) and "checks" in proc.stdout, proc.stderr
    assert "\r" not in proc.stderr and "\r" not in proc.stdout


def test_diagnose_progress_on_a_terminal_only(monkeypatch):
    """diagnose(progress=True): a tqdm bar counting the candidate fits, with the search's
    steps written above it, on a terminal; nothing at all on a redirected stream."""
    from hystcomp.datasets import hidden_effect_data
    from hystcomp.diagnose import diagnose

    d = hidden_effect_data("drift", seed=1)
    tty = _Terminal()
    monkeypatch.setattr(sys, "stderr", tty)
    rep = diagnose(d.t, d.v, d.y, effects=["drift", "creep"])
    out = tty.getvalue()
    assert rep.effects == ["drift"]
    assert "diagnose: added drift" in out and "2fit" in out and "\r" in out
    pipe = io.StringIO()
    monkeypatch.setattr(sys, "stderr", pipe)
    assert diagnose(d.t, d.v, d.y, effects=["drift", "creep"]).effects == ["drift"]
    assert pipe.getvalue() == ""

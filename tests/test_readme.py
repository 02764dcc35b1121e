"""The README's quick-start test command is the one CI runs."""

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def _commands(text):
    return [c.strip() for c in re.findall(r"```bash\n(.*?)```", text, flags=re.S)]


def test_readme_has_exactly_two_quick_start_commands():
    quick = ROOT.joinpath("README.md").read_text().split("## Quick start", 1)[1].split("\n## ", 1)[0]
    cmds = _commands(quick)
    assert len(cmds) == 2, cmds
    assert "hystcomp demo" in cmds[0]
    assert "pytest" in cmds[1]


def test_ci_runs_the_readme_test_command_verbatim():
    quick = ROOT.joinpath("README.md").read_text().split("## Quick start", 1)[1]
    test_cmd = _commands(quick)[1]
    ci = ROOT.joinpath(".ci", "run").read_text().splitlines()
    assert test_cmd in ci, f"{test_cmd!r} not a line of .ci/run"

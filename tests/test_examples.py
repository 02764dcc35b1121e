"""Every examples/*.py script runs and writes non-empty PNG figures."""

import os
import pathlib
import subprocess
import sys

import pytest

EXAMPLES = sorted((pathlib.Path(__file__).resolve().parent.parent / "examples").glob("*.py"))
PNG_MAGIC = b"\x89PNG\r\n\x1a\n"


def test_examples_found():
    assert len(EXAMPLES) >= 5


@pytest.mark.parametrize("script", EXAMPLES, ids=lambda p: p.name)
def test_example_runs_and_writes_pngs(script, tmp_path):
    env = dict(os.environ, MPLBACKEND="Agg")
    out = tmp_path / "out"
    proc = subprocess.run([sys.executable, str(script), "--out", str(out)], env=env,
                          capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stderr
    pngs = sorted(out.glob("*.png"))
    assert pngs, f"{script.name} wrote no PNG into {out}"
    for png in pngs:
        data = png.read_bytes()
        assert len(data) > 1000 and data.startswith(PNG_MAGIC), png.name
    assert proc.stdout.strip(), f"{script.name} printed nothing (examples print their key numbers)"

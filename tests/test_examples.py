"""Every examples/*.py script runs and writes non-empty PNG figures."""

import ast
import os
import pathlib
import subprocess
import sys

import pytest

EXAMPLES = sorted((pathlib.Path(__file__).resolve().parent.parent / "examples").rglob("*.py"))
PNG_MAGIC = b"\x89PNG\r\n\x1a\n"


def test_examples_found():
    assert len(EXAMPLES) >= 5


#: the example the default suite runs through its command line; the others are slow checks
#: (``pytest -m slow``): the documentation build, which CI runs after the suite, runs every
#: example too (sphinx-gallery fails the build when one raises), and since round 58 these runs,
#: 2-3 CPU-minutes, are left to it to keep CI within its 20 minutes
QUICK = "thesis_fig2_1.py"


@pytest.mark.parametrize("script", [pytest.param(p, marks=() if p.name == QUICK else pytest.mark.slow)
                                    for p in EXAMPLES], ids=lambda p: p.name)
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


@pytest.mark.parametrize("script", EXAMPLES, ids=lambda p: p.name)
def test_example_has_a_sphinx_gallery_header(script):
    # sphinx-gallery takes the page title from the docstring's first line,
    # underlined with "=" exactly as long; prose follows after a blank line
    lines = (ast.get_docstring(ast.parse(script.read_text())) or "").splitlines()
    assert len(lines) >= 4, script.name
    assert lines[1] == "=" * len(lines[0]), (script.name, lines[:2])
    assert lines[2] == "" and lines[3].strip(), script.name


def test_teaching_path_has_three_notebooks_with_exercises():
    teaching = [p for p in EXAMPLES if p.parent.name == "teaching"]
    assert len(teaching) == 3
    for script in teaching:
        text = script.read_text()
        assert text.count("# %%") >= 3, script.name  # notebook cells
        assert "# Exercises" in text and "# 1. " in text and "# 3. " in text, script.name

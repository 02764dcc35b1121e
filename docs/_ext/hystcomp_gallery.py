"""A small Sphinx gallery: run every ``examples/*.py`` and embed what it shows.

Each example is a plain script that takes ``--out DIR`` and writes PNG
figures there; by default each runs in seconds (longer studies are behind
explicit options such as ``--seeds``).  At build time every script runs in a
subprocess, headless (``MPLBACKEND=Agg``), and a page is generated with the
script's docstring, its printed output, its figures and its source.
A script that fails, or writes no figure, fails the build.
"""

import os
import subprocess
import sys
import time
from pathlib import Path

from sphinx.errors import ExtensionError
from sphinx.util import logging

logger = logging.getLogger(__name__)


def _title_and_body(source):
    """Title from the docstring: a first line underlined with "=" (the
    sphinx-gallery header), else the first paragraph's part before its first
    top-level colon, or its first sentence; the rest becomes the body."""
    import ast

    doc = (ast.get_docstring(ast.parse(source)) or "Example").strip()
    lines = doc.splitlines()
    if len(lines) >= 2 and lines[1].strip() and set(lines[1].strip()) == {"="}:
        # sphinx-gallery's header: a title line underlined with "="
        return lines[0].strip(), "\n".join(lines[2:]).strip()
    first, _, rest = doc.partition("\n\n")
    para = " ".join(line.strip() for line in first.splitlines())
    depth, cut = 0, None
    for i, ch in enumerate(para):
        depth += ch in "([{"
        depth -= ch in ")]}"
        if ch == ":" and depth == 0 and i >= 10:
            cut = (i, i + 1)
            break
    if cut is None:
        end = para.find(". ")
        cut = (end + 1, end + 2) if end > 0 else (len(para), len(para))
    title = para[: cut[0]].strip().rstrip(".")
    lead = para[cut[1]:].strip()
    body = "\n\n".join(x for x in (lead, rest.strip()) if x)
    return title, body


def _run_examples(app):
    root = Path(app.srcdir).parent
    examples = sorted((root / "examples").glob("*.py"))
    gallery = Path(app.srcdir) / "gallery"
    images = gallery / "_images"
    images.mkdir(parents=True, exist_ok=True)
    env = dict(os.environ, MPLBACKEND="Agg")
    pages = []
    for script in examples:
        name = script.stem
        out = images / name
        out.mkdir(parents=True, exist_ok=True)
        for old in out.glob("*.png"):
            old.unlink()
        logger.info(f"[gallery] running {script.name}")
        t0 = time.perf_counter()
        proc = subprocess.run([sys.executable, str(script), "--out", str(out)], cwd=root, env=env,
                              capture_output=True, text=True, timeout=600)
        seconds = time.perf_counter() - t0
        if proc.returncode != 0:
            raise ExtensionError(f"example {script.name} failed (exit {proc.returncode}):\n{proc.stderr[-3000:]}")
        pngs = sorted(out.glob("*.png"))
        if not pngs:
            raise ExtensionError(f"example {script.name} wrote no PNG figure into --out")
        source = script.read_text()
        title, body = _title_and_body(source)
        rst = [f".. _gallery_{name}:", "", title, "=" * len(title), ""]
        if body:
            rst += ["::", ""] + ["    " + line for line in body.splitlines()] + [""]
        rst += [f"*Ran in {seconds:.1f} s while building these pages.*", ""]
        for png in pngs:
            rel = png.relative_to(gallery).as_posix()
            rst += [f".. image:: {rel}", f"   :alt: {png.stem}", "   :width: 100%", ""]
        printed = proc.stdout.strip()
        if printed:
            rst += ["Output", "------", "", "::", ""] + ["    " + line for line in printed.splitlines()] + [""]
        rst += ["Source", "------", "", f".. literalinclude:: ../../examples/{script.name}",
                "   :language: python", ""]
        (gallery / f"{name}.rst").write_text("\n".join(rst))
        pages.append((name, title, pngs[0].relative_to(gallery).as_posix()))
    index = ["Gallery", "=======", "",
             "Every example in ``examples/`` runs while these pages are built; each is a plain script",
             "(``python examples/NAME.py --out DIR``).", "", ".. toctree::", "   :hidden:", ""]
    index += [f"   {name}" for name, _, _ in pages]
    index.append("")
    for name, title, thumb in pages:
        index += [f":ref:`{title} <gallery_{name}>`", "", f".. image:: {thumb}", "   :width: 45%",
                  f"   :target: {name}.html", ""]
    (gallery / "index.rst").write_text("\n".join(index))


def setup(app):
    app.connect("builder-inited", _run_examples)
    return {"version": "1.0", "parallel_read_safe": True}

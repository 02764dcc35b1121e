"""Sphinx configuration of the hystcomp documentation.

Build:  sphinx-build -W -b html docs docs/_build/html
The gallery extension (_ext/hystcomp_gallery.py) runs every examples/*.py
headless (MPLBACKEND=Agg) and embeds its output and figures,
so a broken example or a stale API name fails the build.
"""

import os
import sys

sys.path.insert(0, os.path.abspath("_ext"))

import hystcomp  # noqa: E402

project = "hystcomp"
author = "hystcomp developers"
copyright = "2026, hystcomp developers"
release = hystcomp.__version__
version = release

extensions = [
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "sphinx.ext.mathjax",
    "sphinx.ext.viewcode",
    "numpydoc",
    "myst_parser",
    "hystcomp_gallery",
]

source_suffix = {".rst": "restructuredtext", ".md": "markdown"}
exclude_patterns = ["_build", "gallery/_images/**/*.md"]
myst_heading_anchors = 3
numpydoc_show_class_members = False
numpydoc_class_members_toctree = False
autosummary_generate = False
autodoc_default_options = {"members": True, "undoc-members": False, "show-inheritance": True}
autodoc_member_order = "bysource"

html_theme = "pydata_sphinx_theme"
html_title = "hystcomp"
html_static_path = ["_static"]
html_theme_options = {"navigation_with_keys": False}
suppress_warnings = ["myst.xref_missing"]

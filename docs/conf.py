"""Sphinx configuration of the hystcomp documentation.

Build:  sphinx-build -W -b html docs docs/_build/html
sphinx-gallery runs every examples/*.py headless (MPLBACKEND=Agg) and embeds
its printed output and figures (thumbnails, .py and .ipynb downloads,
back-references from the API pages), so a broken example or a stale API name
fails the build.  The API reference is one page per module (autosummary,
template in _templates/module.rst).  Math: MathJax through myst's dollarmath
and amsmath.
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
    # MathJax 3 copied into _static: the formulas render without a network (a classroom,
    # a laptop on a train, the headless browser that checks the pages)
    "sphinx-mathjax-offline",
    "sphinx.ext.viewcode",
    "numpydoc",
    "myst_parser",
    "sphinx_gallery.gen_gallery",
]

source_suffix = {".rst": "restructuredtext", ".md": "markdown"}
# no "smart" typography: "--out" in an example's or docstring's command line must stay two
# hyphens (an en dash would break the command a reader copies)
smartquotes = False
exclude_patterns = ["_build"]
templates_path = ["_templates"]
myst_heading_anchors = 3
myst_enable_extensions = ["dollarmath", "amsmath"]
numpydoc_show_class_members = False
numpydoc_class_members_toctree = False
autosummary_generate = True
autosummary_ignore_module_all = False  # a module's __all__ is its public API
autodoc_default_options = {"members": True, "undoc-members": False, "show-inheritance": True}
autodoc_member_order = "bysource"

html_theme = "pydata_sphinx_theme"
html_title = "hystcomp"
html_static_path = ["_static"]
html_css_files = ["hystcomp.css"]  # code blocks wrap instead of scrolling
html_theme_options = {"navigation_with_keys": False}
suppress_warnings = ["myst.xref_missing"]

sphinx_gallery_conf = {
    "examples_dirs": "../examples",
    "gallery_dirs": "gallery",
    "filename_pattern": r"\.py$",  # run every example (not only plot_*.py)
    # figures the examples save (detached from pyplot) and pyplot figures
    "image_scrapers": ("hystcomp_scraper.saved_figures", "matplotlib"),
    "doc_module": ("hystcomp",),
    "backreferences_dir": "api/backreferences",
    "within_subsection_order": "FileNameSortKey",
    "download_all_examples": True,
    "remove_config_comments": True,
    "show_memory": False,
}

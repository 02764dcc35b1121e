"""sphinx-gallery image scraper for figures an example saves.

hystcomp's plotting helpers build :class:`matplotlib.figure.Figure` objects
detached from pyplot (so they are safe in threads and servers), and the
examples save them with ``fig.savefig(...)``.  sphinx-gallery's own
``"matplotlib"`` scraper only sees figures that pyplot manages, so this
scraper records every detached figure passed to ``Figure.savefig`` while an
example runs and embeds it in the gallery page (pyplot figures are left to
the ``"matplotlib"`` scraper, listed next to this one in ``conf.py``).
"""

from pathlib import PurePosixPath

from matplotlib.figure import Figure
from sphinx_gallery.scrapers import figure_rst

_saved = []
_original_savefig = Figure.savefig


def _recording_savefig(self, *args, **kwargs):
    if self.canvas.manager is None and all(f is not self for f in _saved):
        _saved.append(self)
    return _original_savefig(self, *args, **kwargs)


Figure.savefig = _recording_savefig


def saved_figures(block, block_vars, gallery_conf, **kwargs):
    """Embed the detached figures saved by the code block just run.

    Parameters
    ----------
    block : tuple
        The code block (label, content, line number); unused.
    block_vars : dict
        sphinx-gallery's block variables (``image_path_iterator``).
    gallery_conf : dict
        sphinx-gallery's configuration (``src_dir``).
    **kwargs
        Unused (sphinx-gallery's scraper signature).

    Returns
    -------
    str
        reST embedding the figures, or ``""`` when none was saved.
    """
    paths = []
    for fig, path in zip(list(_saved), block_vars["image_path_iterator"]):
        _original_savefig(fig, path, dpi=100)
        paths.append(PurePosixPath(path))
    _saved.clear()
    return figure_rst(paths, gallery_conf["src_dir"]) if paths else ""

"""Progress bars for long runs: tqdm on stderr, silent when not on a terminal.

One helper for every progress display of the package, so that redirected
output (a log file, CI, a pipe) stays free of carriage returns and a
``--quiet`` flag silences them all.
"""

import sys

__all__ = ["progress_bar"]


def progress_bar(iterable=None, total=None, desc=None, enabled=True, file=None, unit="it"):
    """A tqdm progress bar that shows only on a terminal.

    Parameters
    ----------
    iterable : iterable, optional
        Items to iterate over (as :class:`tqdm.tqdm`); omit it and call
        ``update()`` by hand.
    total : int, optional
        Number of steps (default ``len(iterable)`` when it has one).
    desc : str, optional
        Label in front of the bar.
    enabled : bool
        False silences the bar (``--quiet``); True (default) shows it when
        `file` is a terminal and keeps quiet otherwise (tqdm's
        ``disable=None``).
    file : file-like, optional
        Stream of the bar (default: the current ``sys.stderr``).
    unit : str
        Name of one step (default ``"it"``).

    Returns
    -------
    tqdm.tqdm or _SilentBar
        The bar; use it as an iterable or a context manager.  A silent bar
        (disabled, or `file` not a terminal) is a small stand-in with the
        same methods (``update``, ``close``, ``write``, ...), so that tqdm
        is imported only when a bar shows (0.2 s of a run's start-up).

    Examples
    --------
    >>> import io
    >>> sum(progress_bar(range(4), desc="sum", file=io.StringIO()))  # not a terminal: silent
    6
    """
    stream = sys.stderr if file is None else file
    isatty = getattr(stream, "isatty", None)
    if not enabled or (isatty is not None and not isatty()):   # tqdm's disable=None rule
        return _SilentBar(iterable)
    return _bar_class()(iterable, total=total, desc=desc, file=stream,
                        disable=None if enabled else True, unit=unit, dynamic_ncols=True)


_BAR = []


def _bar_class():
    """tqdm without its monitor thread (``monitor_interval = 0``): the bars
    here are updated often, and a process with no thread but its own may
    fork the diagnosis's candidate fits
    (:func:`hystcomp.identify.parallel_fits.can_fork`)."""
    if not _BAR:
        from tqdm import tqdm

        _BAR.append(type("Bar", (tqdm,), {"monitor_interval": 0}))
    return _BAR[0]


class _SilentBar:
    """What `progress_bar` returns when no bar shows: iterates over the
    iterable and ignores the bar's methods (``disable`` is True, as on a
    disabled tqdm bar)."""

    disable = True

    def __init__(self, iterable=None):
        self.iterable = iterable

    def __iter__(self):
        return iter(() if self.iterable is None else self.iterable)

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        return False

    def update(self, n=1):
        pass

    def set_postfix_str(self, s="", refresh=True):
        pass

    def set_description_str(self, desc=None, refresh=True):
        pass

    def close(self):
        pass

    @staticmethod
    def write(s, file=None, end="\n"):
        """Write `s` to `file` (default stdout), as ``tqdm.write`` does."""
        (sys.stdout if file is None else file).write(s + end)

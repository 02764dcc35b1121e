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
    tqdm.tqdm
        The bar; use it as an iterable or a context manager.

    Examples
    --------
    >>> import io
    >>> sum(progress_bar(range(4), desc="sum", file=io.StringIO()))  # not a terminal: silent
    6
    """
    from tqdm import tqdm

    return tqdm(iterable, total=total, desc=desc, file=sys.stderr if file is None else file,
                disable=None if enabled else True, unit=unit, dynamic_ncols=True)

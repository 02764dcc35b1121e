"""Command line: ``hystcomp diagnose DATA.csv [--no-time] [--json] [--plots DIR]``."""

import argparse
import json
import os
import sys

import numpy as np

def load_csv(path, time="t", input="v", output="y", min_samples=100):
    """(t, v, y) from a CSV file with a header row, read by pandas; ValueError
    with a one-line reason for missing columns, non-numeric cells, NaN,
    unsorted time or too few samples.  ``time=None``: the file has no time
    column (t is None).

    What measurement files carry is understood: the separator is sniffed
    (comma, semicolon, tab, whitespace or ``|``), lines starting with ``#``
    are comments, a row of units right below the header (``s,V,um``) is
    skipped, ``.gz``/``.bz2``/``.zip``/``.xz`` files are decompressed, a
    byte-order mark (Excel's "CSV UTF-8") is ignored, and a time column of
    dates and times (ISO 8601) becomes seconds from the first sample.

    Parameters
    ----------
    path : str or path-like
        The CSV file (a header row, at least `min_samples` samples).
    time : str or None
        Header name of the time column [s]; None for a record without one.
    input, output : str
        Header names of the input and output columns.
    min_samples : int
        Fewest samples accepted (diagnose needs 100).

    Returns
    -------
    t, v, y : ndarray
        The three columns, time strictly increasing (t is None without a
        time column).

    Raises
    ------
    ValueError
        With a one-line reason naming the file (and line) at fault.

    Examples
    --------
    >>> import os, tempfile
    >>> folder = tempfile.mkdtemp()
    >>> path = os.path.join(folder, "record.csv")
    >>> k = np.arange(100)
    >>> np.savetxt(path, np.column_stack([0.01 * k, k % 7, k % 5]), delimiter=";",
    ...            header="# bench 3\\ntime;volt;um\\ns;V;um", comments="")
    >>> t, v, y = load_csv(path, time="time", input="volt", output="um")
    >>> t.size, float(v[8]), float(y[8])
    (100, 1.0, 3.0)
    >>> load_csv(path)
    Traceback (most recent call last):
    ...
    ValueError: ... has no column 't' (header: time, volt, um)
    >>> import shutil
    >>> shutil.rmtree(folder)
    """
    import pandas as pd

    names = [n for n in (time, input, output) if n is not None]
    try:
        layout = _layout(path)
    except OSError as exc:
        raise ValueError(f"cannot read {path}: {exc.strerror or exc}") from None
    except (UnicodeDecodeError, EOFError, ValueError) as exc:
        if isinstance(exc, ValueError) and str(exc).startswith(str(path)):
            raise
        raise ValueError(f"{path} is not a text CSV file") from None
    if layout is None:
        raise ValueError(f"{path} is empty; expected a header row with columns {', '.join(names)}")
    header, sep, skip, first_line, decimal, first_row = layout
    clock = time is not None and time in header and len(first_row) == len(header) and \
        _is_clock(first_row[header.index(time)]) and not _is_number(first_row[header.index(time)])
    for name in names:
        if name not in header:
            raise ValueError(f"{path} has no column {name!r} (header: {', '.join(header)})")
    if len(set(header)) != len(header):
        dup = sorted({h for h in header if header.count(h) > 1})
        raise ValueError(f"{path} repeats the column name(s) {', '.join(map(repr, dup))} in its header")
    options = dict(sep=sep, skiprows=skip, header=None, names=header, usecols=list(dict.fromkeys(names)),
                   comment="#", skip_blank_lines=True, skipinitialspace=True, encoding="utf-8-sig",
                   decimal=decimal, engine="c")
    try:
        try:
            # the fast path: every column parsed straight to float64 (a text
            # time column of dates is read as text)
            dtypes = {n: (str if n == time and clock else np.float64) for n in names}
            df = pd.read_csv(path, dtype=dtypes, **options)
        except ValueError:
            # a cell that is not a number: read as text, and the checks below
            # name the line
            df = pd.read_csv(path, **options)
    except (pd.errors.ParserError, ValueError, UnicodeDecodeError) as exc:
        raise ValueError(f"{path} cannot be parsed as CSV ({' '.join(str(exc).split())})") from None
    out = {}
    for name in names:
        col = df[name]
        if name == time and col.dtype.kind not in "biuf":
            col = _clock_times(col)
        out[name] = _finite_column(path, name, col, first_line)
    n = len(df)
    if n < min_samples:
        raise ValueError(f"{path} has {n} samples; diagnose needs at least {min_samples}")
    if time is None:
        return None, out[input], out[output]
    t = out[time]
    d = np.diff(t)
    if np.any(d <= 0):
        k = int(np.argmax(d <= 0))
        raise ValueError(f"{path} line {first_line + k + 1}: time {t[k + 1]} does not increase "
                         f"(previous {t[k]})")
    return t, out[input], out[output]


def _open_text(path):
    """A text handle on a (possibly compressed) file, byte-order mark removed."""
    import io

    p = os.fspath(path)
    low = p.lower()
    if low.endswith(".gz"):
        import gzip

        raw = gzip.open(p, "rb")
    elif low.endswith(".bz2"):
        import bz2

        raw = bz2.open(p, "rb")
    elif low.endswith(".xz"):
        import lzma

        raw = lzma.open(p, "rb")
    elif low.endswith(".zip"):
        import zipfile

        zf = zipfile.ZipFile(p)
        raw = zf.open(zf.namelist()[0])
    else:
        raw = open(p, "rb")
    return io.TextIOWrapper(raw, encoding="utf-8-sig", newline="")


def _layout(path):
    """(header names, separator, physical lines to skip, file line of the
    first data row) from the file's first lines, or None for an empty file.
    Comment lines (``#``) before the header and a units row below it are
    skipped."""
    import csv

    with _open_text(path) as fh:
        head = []
        for _ in range(64):
            line = fh.readline()
            if not line:
                break
            head.append(line.rstrip("\r\n"))
    if any("\x00" in line for line in head):
        raise ValueError("binary")
    rows = [(i, line) for i, line in enumerate(head) if line.strip() and not line.lstrip().startswith("#")]
    if not rows:
        return None
    h_i, h_line = rows[0]
    sample = "\n".join(line for _, line in rows[:20])
    try:
        sep = csv.Sniffer().sniff(sample, delimiters=",;\t| ").delimiter
    except csv.Error:
        sep = ","

    def cells(line):
        return line.split() if sep == " " else [c.strip() for c in next(csv.reader([line], delimiter=sep))]

    header = cells(h_line)
    skip = list(range(h_i + 1))       # comments and blank lines before the header, and the header
    first = h_i + 2                   # file line (1-based) of the first data row
    data = rows[1:]
    if data:
        u_i, u_line = data[0]
        row = cells(u_line)
        if row and not any(_is_number(c) for c in row) and not any(_is_clock(c) for c in row):
            skip.append(u_i)          # a row of units below the header
            first = u_i + 2
            data = data[1:]
    # "0,25;1,5": a semicolon file with decimal commas (European locales)
    decimal = "."
    sample_cells = [c for _, line in data[:20] for c in cells(line) if c] if sep == ";" else []
    if (any("," in c for c in sample_cells) and not any("." in c for c in sample_cells)
            and all(_is_number(c.replace(",", ".")) for c in sample_cells)):
        decimal = ","
    first_row = cells(data[0][1]) if data else []
    return header, (r"\s+" if sep == " " else sep), skip, first, decimal, first_row


def _is_number(cell):
    try:
        float(cell)
    except ValueError:
        return False
    return True


def _is_clock(cell):
    """A date/time cell (an ISO 8601 time column is data, not units)."""
    import re

    return re.match(r"\s*\d{1,4}[-/:.]\d", cell) is not None


def _clock_times(col):
    """A text time column of dates/times as seconds from the first sample
    (left as text when it is not one: the number check then names the cell)."""
    import pandas as pd

    from ..identify._records import _seconds

    try:
        stamps = pd.to_datetime(col, format="ISO8601")
    except (ValueError, TypeError):
        try:
            stamps = pd.to_timedelta(col)
        except (ValueError, TypeError):
            return col
    if stamps.isna().any():
        return col
    return pd.Series(_seconds(stamps, "time"), index=col.index)


def _finite_column(path, name, col, first_line):
    """A column as float64, ValueError naming the file line of the first
    cell that is not a finite number."""
    import pandas as pd

    if col.dtype.kind in "biuf":
        vals = col.to_numpy(dtype=np.float64)
        bad = ~np.isfinite(vals)
        if bad.any():
            k = int(np.argmax(bad))
            raise ValueError(f"{path} line {first_line + k}: column {name!r} holds {vals[k]}; expected a "
                             "finite number")
        return vals
    vals = pd.to_numeric(col, errors="coerce").to_numpy(dtype=np.float64, na_value=np.nan)
    bad = ~np.isfinite(vals)
    if not bad.any():
        return vals
    k = int(np.argmax(bad))
    cell = col.iloc[k]
    if isinstance(cell, str) and _is_number(cell):
        raise ValueError(f"{path} line {first_line + k}: column {name!r} holds {float(cell)}; expected a "
                         "finite number")
    raise ValueError(f"{path} line {first_line + k}: column {name!r} holds "
                     f"{'' if cell is None or cell != cell else cell!r}, not a number")


def add_arguments(parser):
    """Add the ``diagnose`` arguments to an argparse parser (sub-parser).

    Parameters
    ----------
    parser : argparse.ArgumentParser
        The parser (or sub-parser) to extend.

    Returns
    -------
    argparse.ArgumentParser
        The same parser.

    Examples
    --------
    >>> import argparse
    >>> args = add_arguments(argparse.ArgumentParser()).parse_args(["data.csv", "--max-effects", "1"])
    >>> args.data, args.max_effects, args.validation, args.jobs
    (['data.csv'], 1, 0.3, None)
    """
    parser.add_argument("data", metavar="DATA.csv", nargs="+",
                        help="CSV file(s) with a header row; several files are diagnosed independently")
    parser.add_argument("--jobs", type=int, default=None,
                        help="diagnose several files on this many processes (default one after the other); "
                             "with one file, fit each step's candidate effects with this many workers (forked processes "
                             "on Linux, else threads; the same diagnosis; default 2 on a machine with two or "
                             "more cores, else 1)")
    parser.add_argument("--time", default="t", help="time column [s] (default t)")
    parser.add_argument("--no-time", action="store_true",
                        help="the record has no time axis (a quasi-static point sequence such as a B-H "
                             "loop): rate dependence, creep, drift and delay are then untestable")
    parser.add_argument("--input", default="v", help="input column (default v)")
    parser.add_argument("--output", default="y", help="measured output column (default y)")
    parser.add_argument("--json", action="store_true", help="print one JSON object to stdout")
    parser.add_argument("--plots", metavar="DIR", help="write the diagnosis figures (PNG) into DIR")
    parser.add_argument("--units", metavar="IN,OUT", default=None,
                        help="units of the input and output columns for the figures' axes, e.g. V,um (default "
                             "none: the axes carry the columns' names alone)")
    parser.add_argument("--validation", type=float, default=0.3, help="held-out fraction (default 0.3)")
    parser.add_argument("--held-out", choices=("auto", "last", "blocks"), default="auto",
                        help="which part is held out: the end (last); five blocks spread over the record "
                             "(blocks: a drift of no set shape is judged by interpolation); or auto (default): "
                             "the end unless its input leaves the rest's range by more than 5 %% of the span "
                             "or moves over twice as fast as the rest, then a block inside the record, re-judged on "
                             "blocks when that leaves the record unexplained with no drift named")
    parser.add_argument("--max-effects", type=int, default=4, help="at most this many effects (default 4)")
    parser.add_argument("--quiet", action="store_true", help="no progress lines on stderr")
    return parser


def run(args):
    """Run ``hystcomp diagnose`` for parsed `args`; returns the exit status.

    Parameters
    ----------
    args : argparse.Namespace
        Arguments parsed by a parser built with :func:`add_arguments`.

    Returns
    -------
    int
        Exit status: 0 on success (the report or JSON printed to stdout), 2
        when the record cannot be used or diagnosed (one line on stderr, never
        a traceback; an internal failure says so and is not blamed on the
        file).

    Examples
    --------
    >>> import argparse
    >>> args = add_arguments(argparse.ArgumentParser()).parse_args(["no-such-file.csv", "--quiet"])
    >>> run(args)   # prints "hystcomp diagnose: error: cannot read no-such-file.csv: ..." on stderr
    2
    """
    files = list(args.data) if isinstance(args.data, (list, tuple)) else [args.data]
    jobs = getattr(args, "jobs", None)
    if jobs is not None and jobs < 1:
        return _fail(f"error: --jobs is {jobs} but should be >= 1")
    units = getattr(args, "units", None)
    if units is not None:
        units = str(units).split(",")
        if len(units) != 2 or not all(u.strip() for u in units):
            return _fail(f"error: --units is {args.units!r} but should be two units separated by a comma, e.g. V,um")
        units = [u.strip() for u in units]
    else:
        units = [None, None]
    # the figures' axes name the columns as the file does (the default columns v and y as "input v", "output y")
    names = dict(input_name="input v" if args.input == "v" else args.input,
                 output_name="output y" if args.output == "y" else args.output)
    records = []
    for path in files:
        try:
            records.append(_load(args, path))
        except ValueError as exc:
            return _fail(f"error: {exc}")
    if args.plots:
        # before the diagnosis, not after it: a bad folder fails at once
        from .._validation import check_output_folder

        try:
            check_output_folder(args.plots, "--plots")
        except ValueError as exc:
            return _fail(f"error: {exc}")
    options = dict(validation=args.validation, max_effects=args.max_effects, held_out=args.held_out)
    try:
        if len(files) == 1:
            reps = [_diagnose(records[0], dict(options, workers=jobs), not args.quiet)]
        else:
            from .many import diagnose_many

            if jobs is not None and jobs > 1:
                from concurrent.futures import ProcessPoolExecutor

                with ProcessPoolExecutor(jobs) as ex:
                    reps = diagnose_many(records, executor=ex, progress=False, **options)
            else:
                reps = diagnose_many(records, progress=not args.quiet, **options)
    except Exception as exc:   # an internal limit or bug: one line, never a traceback
        return _fail(f"internal error while diagnosing {', '.join(files)} ({type(exc).__name__}: {exc}); "
                     "the records themselves were read fine -- please report this")
    try:
        if args.plots:
            import matplotlib

            matplotlib.use("Agg")
            for path, rep in zip(files, reps):
                folder = args.plots if len(files) == 1 else os.path.join(
                    args.plots, os.path.splitext(os.path.basename(path))[0])
                for p in rep.save_plots(folder, *units, **names):
                    print(f"wrote {p}", file=sys.stderr)
    except Exception as exc:
        return _fail(f"error: cannot write the figures to {args.plots} ({type(exc).__name__}: {exc})")
    if args.json:
        if len(files) == 1:
            print(reps[0].to_json())
        else:
            print(json.dumps([{"file": path, **rep.to_dict()} for path, rep in zip(files, reps)]))
    else:
        for path, rep in zip(files, reps):
            if len(files) > 1:
                print(f"== {path}")
            print(rep.report())
    return 0


def _load(args, path):
    """The record of one file, checked (ValueError naming the file)."""
    from .record import Record

    t, v, y = load_csv(path, None if args.no_time else args.time, args.input, args.output)
    try:
        # what is wrong with the record itself (or the options) is the user's to fix
        Record(t, v, y, args.validation, args.held_out)
        if args.max_effects < 0:
            raise ValueError(f"--max-effects is {args.max_effects} but should be >= 0")
    except ValueError as exc:
        raise ValueError(f"{path}: {exc}") from None
    return t, v, y


def _diagnose(record, options, progress):
    from . import diagnose

    t, v, y = record
    return diagnose(t, v, y, progress=progress, **options)


def _fail(msg):
    line = " ".join(str(msg).split())
    print(f"hystcomp diagnose: {line}", file=sys.stderr)
    return 2


def main(argv=None):
    """``python -m hystcomp.diagnose DATA.csv ...`` (the same as ``hystcomp diagnose``)."""
    parser = add_arguments(argparse.ArgumentParser(prog="hystcomp diagnose",
                                                   description="name the effects a PI model lacks"))
    return run(parser.parse_args(argv))

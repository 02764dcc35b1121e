"""Command line: ``hystcomp diagnose DATA.csv [--no-time] [--json] [--plots DIR]``."""

import argparse
import json
import os
import math
import sys

import numpy as np

def load_csv(path, time="t", input="v", output="y"):
    """(t, v, y) from a CSV file with a header row; ValueError with a one-line
    reason for missing columns, non-numeric cells, NaN, unsorted time or too
    few samples.  ``time=None``: the file has no time column (t is None).

    Parameters
    ----------
    path : str or path-like
        The CSV file (comma separated, a header row, at least 100 samples).
    time : str or None
        Header name of the time column [s]; None for a record without one.
    input, output : str
        Header names of the input and output columns.

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
    >>> np.savetxt(path, np.column_stack([0.01 * k, k % 7, k % 5]), delimiter=",",
    ...            header="time,volt,um", comments="")
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
    import csv

    try:
        # utf-8-sig: Excel's "CSV UTF-8" starts with a byte-order mark
        with open(path, newline="", encoding="utf-8-sig") as fh:
            rows = list(csv.reader(fh))
    except OSError as exc:
        raise ValueError(f"cannot read {path}: {exc.strerror or exc}") from None
    except UnicodeDecodeError:
        raise ValueError(f"{path} is not a text CSV file") from None
    if not rows:
        names = ", ".join(n for n in (time, input, output) if n is not None)
        raise ValueError(f"{path} is empty; expected a header row with columns {names}")
    header = [h.strip() for h in rows[0]]
    cols = {}
    for name in (time, input, output):
        if name is None:
            continue
        if name not in header:
            raise ValueError(f"{path} has no column {name!r} (header: {', '.join(header)})")
        cols[name] = header.index(name)
    body = [r for r in rows[1:] if any(c.strip() for c in r)]
    out = {name: np.empty(len(body)) for name in cols}
    for i, row in enumerate(body, start=2):
        for name, j in cols.items():
            try:
                val = float(row[j])
            except (IndexError, ValueError):
                cell = row[j] if j < len(row) else ""
                raise ValueError(f"{path} line {i}: column {name!r} holds {cell!r}, not a number") from None
            if not math.isfinite(val):
                raise ValueError(f"{path} line {i}: column {name!r} holds {val}; expected a finite number")
            out[name][i - 2] = val
    if len(body) < 100:
        raise ValueError(f"{path} has {len(body)} samples; diagnose needs at least 100")
    if time is None:
        return None, out[input], out[output]
    t = out[time]
    d = np.diff(t)
    if np.any(d <= 0):
        k = int(np.argmax(d <= 0))
        raise ValueError(f"{path} line {k + 3}: time {t[k + 1]} does not increase (previous {t[k]})")
    return t, out[input], out[output]


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
    (['data.csv'], 1, 0.3, 1)
    """
    parser.add_argument("data", metavar="DATA.csv", nargs="+",
                        help="CSV file(s) with a header row; several files are diagnosed independently")
    parser.add_argument("--jobs", type=int, default=1,
                        help="diagnose several files on this many processes (default 1)")
    parser.add_argument("--time", default="t", help="time column [s] (default t)")
    parser.add_argument("--no-time", action="store_true",
                        help="the record has no time axis (a quasi-static point sequence such as a B-H "
                             "loop): rate dependence, creep, drift and delay are then untestable")
    parser.add_argument("--input", default="v", help="input column (default v)")
    parser.add_argument("--output", default="y", help="measured output column (default y)")
    parser.add_argument("--json", action="store_true", help="print one JSON object to stdout")
    parser.add_argument("--plots", metavar="DIR", help="write the diagnosis figures (PNG) into DIR")
    parser.add_argument("--units", metavar="IN,OUT", default="input units,output units",
                        help="units of the input and output columns for the figures' axes, e.g. V,um")
    parser.add_argument("--validation", type=float, default=0.3, help="held-out fraction (default 0.3)")
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
    if int(getattr(args, "jobs", 1)) < 1:
        return _fail(f"error: --jobs is {args.jobs} but should be >= 1")
    units = str(getattr(args, "units", "input units,output units")).split(",")
    if len(units) != 2 or not all(u.strip() for u in units):
        return _fail(f"error: --units is {args.units!r} but should be two units separated by a comma, e.g. V,um")
    units = [u.strip() for u in units]
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
    options = dict(validation=args.validation, max_effects=args.max_effects)
    try:
        if len(files) == 1:
            reps = [_diagnose(records[0], options, not args.quiet)]
        else:
            from .many import diagnose_many

            if args.jobs > 1:
                from concurrent.futures import ProcessPoolExecutor

                with ProcessPoolExecutor(args.jobs) as ex:
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
                for p in rep.save_plots(folder, *units):
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
        Record(t, v, y, args.validation)
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

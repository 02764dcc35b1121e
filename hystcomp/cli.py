"""The ``hystcomp`` console command.

::

    hystcomp demo   [--out DIR] [--quiet] [...]  # closed-loop study: loops tuned to one specification,
                                                 # with and without compensator
    hystcomp thesis [--out DIR] [--quiet]        # all thesis figures + section 5 error table
    hystcomp diagnose DATA.csv [--time t | --no-time] [--input v --output y] [--json] [--plots DIR]
                                                 # [--quiet]
    hystcomp --version

``python -m hystcomp`` is the same command.  Progress bars (tqdm, on stderr)
show only on a terminal; ``--quiet`` silences them and the status lines.

``demo`` runs the thesis's mGPI actuator in front of a piezo stage through
loops whose PID is tuned to one specification (phase margin at a gain
crossover), finds with the circle criterion the highest crossover each loop
reaches safely with and without the compensator, and compares their tracking
(see :mod:`hystcomp.demo`); ``thesis``
writes the PNG figures of the thesis reproduction, prints the table of
section 5 compensation errors (analytic inverse of eqs. 54-58 vs the exact
inverse) and saves it as ``compensation_errors.csv``.
"""

import argparse
import csv
import os
import sys

from . import __version__

__all__ = ["main", "build_parser", "reproduce"]

_FIELDS = ("section", "inverse", "rms", "max", "rms_percent", "max_percent", "span")


def reproduce(out, echo=print, dt=None, quiet=False):
    """Write every thesis figure and the section 5 error table into `out`.

    Parameters
    ----------
    out : str or path
        Output folder (created if missing).
    echo : callable, optional
        Receives the status and result lines (default :func:`print`).
    dt : float, optional
        Sampling step of the cases (default :data:`hystcomp.thesis.DT`).
    quiet : bool, optional
        Only the error table: no status lines, no "wrote FILE" lines and no
        progress bars (default False; the bars, tqdm on stderr, show only
        on a terminal).

    Returns
    -------
    list of dict
        The rows of the compensation error table
        (:func:`hystcomp.thesis.compensation_errors`).

    Examples
    --------
    >>> import tempfile, os
    >>> with tempfile.TemporaryDirectory() as d:
    ...     rows = reproduce(d, echo=lambda s: None, dt=0.01)
    ...     "compensation_errors.csv" in os.listdir(d)
    True
    """
    import matplotlib

    matplotlib.use("Agg")  # figures are only written to files
    from . import plotting, thesis

    from ._validation import check_output_folder

    check_output_folder(out, "out")
    status = (lambda line: None) if quiet else echo
    os.makedirs(out, exist_ok=True)
    status(f"hystcomp {__version__}: reproducing W. Ye's thesis into {out}")
    status("building figures (sections 2.1, 3.4.3, 3.5, 4.1, 5.2-5.4) ...")
    for stem, fig in plotting.thesis_figures(dt=dt, progress=not quiet).items():
        path = os.path.join(out, stem + ".png")
        fig.savefig(path, dpi=100)
        status(f"  wrote {path}")
    status("computing section 5 compensation errors ...")
    rows = thesis.compensation_errors(**({} if dt is None else {"dt": dt}), progress=not quiet)
    path = os.path.join(out, "compensation_errors.csv")
    with open(path, "w", newline="") as fh:
        writer = csv.DictWriter(fh, fieldnames=_FIELDS)
        writer.writeheader()
        for row in rows:
            writer.writerow({k: row[k] for k in _FIELDS})
    status("")
    echo("Compensation error model(inverse(u)) - u (% of the reference span)")
    echo(f"{'section':8s} {'inverse':9s} {'RMS %':>10s} {'max %':>10s}")
    for row in rows:
        echo(f"{row['section']:8s} {row['inverse']:9s} {row['rms_percent']:10.3g} {row['max_percent']:10.3g}")
    status(f"  wrote {path}")
    return rows


def build_parser(command=None):
    """The argument parser of the ``hystcomp`` command.

    Parameters
    ----------
    command : str, optional
        The subcommand the parser will see, when known (`main` passes it):
        the options of the other subcommands are then not defined, so that
        ``hystcomp demo`` does not import the diagnosis and identification
        code (with scikit-learn: 1.3-1.8 s measured).  Default None: every
        subcommand with all its options.

    Examples
    --------
    >>> build_parser().parse_args(["thesis", "--out", "x"]).out
    'x'
    """
    from . import demo

    parser = argparse.ArgumentParser(
        prog="hystcomp",
        description="Model and cancel actuator hysteresis (PI, GPI, mGPI) in control loops.",
    )
    parser.add_argument("--version", action="version", version=f"%(prog)s {__version__}",
                        help="print the hystcomp version and exit")
    parser.add_argument("--debug", action="store_true",
                        help="show the full traceback of an unexpected error (also accepted "
                             "after the command)")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", required=True)
    text = ("closed-loop study: the thesis's mGPI actuator (saturating tanh envelope) in front of a "
            "piezo stage; PIDs tuned to one phase margin at a scan of gain crossovers, the circle "
            "criterion's guaranteed gain with and without the exact compensator, the highest safe "
            "crossover of each, and the tracking of open loop, inverse feedforward, PID, PID + "
            "compensator and feedforward + PID; prints the tables, writes PNG figures and a CSV")
    demo.add_arguments(sub.add_parser("demo", help=text, description=text))
    text = ("find what a fitted PI model misses in a measured record (rate dependence, creep, drift, "
            "gain drift, asymmetry, saturation, output saturation, delay, initial state): name an effect "
            "only when its signature is in the residual and its model part pays on held-out data; "
            "verdict 'explained' or 'unexplained' against the record's own noise floor")
    p = sub.add_parser("diagnose", help=text, description=text)
    if command in (None, "diagnose"):
        from . import diagnose

        diagnose.add_arguments(p)
    text = ("reproduce the thesis: figures of sections 2.1, 3.4.3, 3.5, 4.1, 5.2-5.4, "
            "a printed table of the section 5 compensation errors and its CSV")
    p = sub.add_parser("thesis", help=text, description=text)
    p.add_argument("--out", metavar="DIR", default="hystcomp-thesis",
                   help="output folder for the PNG figures and compensation_errors.csv "
                        "(default: ./hystcomp-thesis, created if missing)")
    p.add_argument("--quiet", action="store_true",
                   help="print only the error table: no status lines, no progress bars")
    return parser


def main(argv=None):
    """Entry point of the ``hystcomp`` console script; returns the exit status.

    Examples
    --------
    >>> main(["--version"])
    Traceback (most recent call last):
    ...
    SystemExit: 0
    """
    argv = list(sys.argv[1:] if argv is None else argv)
    debug = "--debug" in argv
    argv = [a for a in argv if a != "--debug"]
    # the subcommand is the first argument that is not an option (the main
    # parser's options take no value); unknown names get the full parser
    command = next((a for a in argv if not a.startswith("-")), None)
    parser = build_parser(command if command in ("demo", "thesis") else None)
    args = parser.parse_args(argv)
    _check_options(parser, args)
    try:
        return _dispatch(args)
    except KeyboardInterrupt:
        print(f"hystcomp {args.command}: interrupted", file=sys.stderr)
        return 130
    except Exception as exc:   # never a traceback unless asked for
        if debug:
            raise
        return _report_failure(args.command, exc)


#: exceptions that mean "the options or files given are not usable" (exit 2)
_BAD_INPUT = (ValueError, TypeError, OSError, UnicodeDecodeError)


def _report_failure(command, exc):
    """One line on stderr naming what failed, and a hint; the exit status."""
    what = " ".join(str(exc).split()) or "(no message)"
    if isinstance(exc, _BAD_INPUT):
        print(f"hystcomp {command}: error: {type(exc).__name__}: {what} "
              f"(check the options and files; see hystcomp {command} --help)", file=sys.stderr)
        return 2
    print(f"hystcomp {command}: internal error: {type(exc).__name__}: {what} "
          "(run again with --debug to see the traceback, and please report it)", file=sys.stderr)
    return 1


def _check_options(parser, args):
    """Reject option values the commands cannot use, and unusable output
    folders, before any long work starts (one line on stderr, exit 2 as for
    argparse's usage errors)."""
    import math

    from ._validation import check_output_folder

    class _Errors:
        @staticmethod
        def error(msg):
            print(f"hystcomp {args.command}: error: {msg}", file=sys.stderr)
            raise SystemExit(2)

    parser = _Errors

    def number(name, value, low, strict=True, high=None):
        ok = math.isfinite(value) and (value > low if strict else value >= low)
        ok = ok and (high is None or value < high)
        if not ok:
            expected = f"{'>' if strict else '>='} {low}" + (f" and < {high}" if high is not None else "")
            parser.error(f"argument --{name}: {value} is not a finite number {expected}")

    if args.command == "demo":
        number("duration", args.duration, 0.0)
        number("dt", args.dt, 0.0)
        if args.dt >= args.duration:
            parser.error(f"argument --dt: {args.dt} s is not shorter than --duration {args.duration} s")
        for f in args.freqs:
            number("freqs", f, 0.0)
        for f in args.crossovers:
            number("crossovers", f, 0.0)
        number("phase-margin", args.phase_margin, 0.0, high=180.0)
        number("required-margin", args.required_margin, 0.0)
        number("stage-hz", args.stage_hz, 0.0)
        number("damping", args.damping, 0.0, strict=False)
    folder = {"demo": ("out", "--out"), "thesis": ("out", "--out"), "diagnose": ("plots", "--plots")}
    attr, option = folder.get(args.command, (None, None))
    path = getattr(args, attr, None) if attr else None
    if path:
        try:
            check_output_folder(path, option)
        except ValueError as exc:
            parser.error(str(exc))


def _dispatch(args):
    if args.command == "thesis":
        reproduce(args.out, quiet=args.quiet)
        return 0
    if args.command == "diagnose":
        from . import diagnose

        return diagnose.run(args)
    if args.command == "demo":
        from . import demo

        res = demo.run(args)
        return 0 if all(ok for ok, _ in res["checks"].values()) else 1
    return 2


if __name__ == "__main__":
    sys.exit(main())

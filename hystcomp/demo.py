"""``hystcomp demo``: the thesis's actuator in closed loops.

An mGPI actuator with the thesis's weights (p0 = 1, p(r) = e^{-0.1 r},
r_i = 0.25 i, 20 operators; section 5) and a saturating envelope
``gamma(v) = 30 tanh(0.05 v)`` drives the default piezo stage
(:func:`hystcomp.iosys.piezo_stage`: 300 Hz, 5 % damping) sampled at 10 kHz.
Two references, ``5 sin(2 pi f t)/(1 + 0.1 t)`` for f = 1 Hz (the thesis's
chapter 5) and a faster f = 5 Hz, run through the five scenarios of
:mod:`hystcomp.loops` with the exact and the analytic compensator (both with
``nominal_gain="auto"``) and an integral controller.  The demo prints the
comparison table, the stability margins of the nominal linear loops and the
checks of the issue, and writes PNG figures and ``loop_comparison.csv``.

Wired into the console command by :mod:`hystcomp.cli` through
:func:`add_arguments` and :func:`run`.
"""

import argparse
import os
import sys
import time

import numpy as np

__all__ = ["add_arguments", "run", "main", "demo_actuator", "reference", "stability_table"]


def demo_actuator():
    """The demo's actuator: the thesis's section 5 weights with
    ``gamma = 30 tanh(0.05 v)``.

    Examples
    --------
    >>> demo_actuator()
    MGPI(N=20, p0=1.0, envelope=Tanh(a=30.0, b=0.05))
    """
    from .envelopes import Tanh
    from .models import MGPI

    return MGPI.from_density(lambda r: np.exp(-0.1 * r), 0.25 * np.arange(1, 21), p0=1.0,
                             envelope=Tanh(30.0, 0.05))


def reference(t, freq_hz=1.0, amplitude=5.0):
    """``amplitude sin(2 pi freq_hz t) / (1 + 0.1 t)`` (thesis chapter 5 for 1 Hz, 5).

    Parameters
    ----------
    t : ndarray
        Times in seconds.
    freq_hz : float, optional
        Frequency in Hz (default 1, the thesis's).
    amplitude : float, optional
        Amplitude at t = 0 (default 5, the thesis's).

    Returns
    -------
    ndarray
        The reference at `t`.

    Examples
    --------
    >>> round(float(reference(np.array([0.25]))[0]), 6)
    4.878049
    """
    return amplitude * np.sin(2 * np.pi * freq_hz * t) / (1.0 + 0.1 * t)


def stability_table(kp, ki, kd, dt, gains, plant):
    """Gain and phase margins of the nominal linear loops ``C(z) k P(z)``.

    For each actuator gain k in `gains` (e.g. the compensated actuator's
    nominal gain, the raw actuator's smallest and largest slopes) returns
    ``(k, gain margin, phase margin [deg], phase crossover [Hz])`` (the
    frequency where the gain margin is measured) from
    :func:`control.stability_margins`.

    Parameters
    ----------
    kp, ki, kd : float
        PID gains (see :func:`hystcomp.iosys.pid`).
    dt : float
        Sampling time in seconds.
    gains : iterable of float
        Actuator gains k to try.
    plant : control.LTI
        The plant, discretised at `dt` (:func:`hystcomp.iosys.discretize`).

    Returns
    -------
    list of tuple
        ``(k, gain margin, phase margin [deg], phase crossover [Hz])`` per
        gain.

    Examples
    --------
    >>> from hystcomp.iosys import discretize, piezo_stage
    >>> rows = stability_table(0.0, 40.0, 0.0, 1e-4, [1.0, 2.5], discretize(piezo_stage(), 1e-4))
    >>> [(k, round(gm, 3), round(pm, 1)) for k, gm, pm, _ in rows]   # the margin shrinks as 1/k
    [(1.0, 4.714, 89.9), (2.5, 1.885, 89.7)]
    """
    import warnings

    import control as ct

    from .iosys import pid

    c = pid(kp, ki, kd, dt)
    p = ct.ss(plant)
    rows = []
    for k in gains:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # python-control's note on its 'frd' fallback
            gm, pm, wcg, wcp = ct.stability_margins(ct.series(p, c) * k)[:4]
        rows.append((float(k), float(gm), float(pm), float(wcg) / (2 * np.pi)))
    return rows


def add_arguments(parser):
    """Add the demo's options to an :class:`argparse.ArgumentParser`.

    Parameters
    ----------
    parser : argparse.ArgumentParser
        The parser (or subparser) to extend: ``--out``, ``--duration``,
        ``--dt``, ``--freqs``, ``--kp``, ``--ki``, ``--kd``, ``--stage-hz``,
        ``--damping``, ``--engine`` and ``--no-figures``.

    Examples
    --------
    >>> p = argparse.ArgumentParser()
    >>> add_arguments(p)
    >>> p.parse_args([]).out
    'hystcomp-demo'
    """
    parser.add_argument("--out", metavar="DIR", default="hystcomp-demo",
                        help="output folder for the PNG figures and loop_comparison.csv "
                             "(default: ./hystcomp-demo, created if missing)")
    parser.add_argument("--duration", type=float, default=10.0, metavar="S",
                        help="length of each reference in seconds (default: 10, the thesis's)")
    parser.add_argument("--dt", type=float, default=1e-4, metavar="S",
                        help="sampling time of the loops in seconds (default: 1e-4, 10 kHz)")
    parser.add_argument("--freqs", type=float, nargs="+", default=[1.0, 5.0], metavar="HZ",
                        help="frequencies of the references 5 sin(2 pi f t)/(1 + 0.1 t) (default: 1 5)")
    parser.add_argument("--kp", type=float, default=0.0, help="PID proportional gain (default: 0)")
    parser.add_argument("--ki", type=float, default=40.0,
                        help="PID integral gain (default: 40; the loops go unstable near 70, see docs/loops.md)")
    parser.add_argument("--kd", type=float, default=0.0, help="PID derivative gain (default: 0)")
    parser.add_argument("--stage-hz", type=float, default=300.0,
                        help="resonance of the piezo stage in Hz (default: 300)")
    parser.add_argument("--damping", type=float, default=0.05,
                        help="damping ratio of the piezo stage (default: 0.05)")
    parser.add_argument("--engine", choices=("auto", "compiled", "python-control"), default="auto",
                        help="how the loops run: compiled (numba; default via auto) or python-control's "
                             "input_output_response (about 1000x slower: use with a short --duration)")
    parser.add_argument("--no-figures", action="store_true", help="skip the PNG figures")


def _progress(stream):
    start = time.perf_counter()

    def show(done, total, name):
        if stream is None:
            return
        bar = "#" * int(30 * done / total)
        stream.write(f"\r  [{bar:30s}] {done}/{total} {name:40s} {time.perf_counter() - start:5.1f} s")
        if done == total:
            stream.write("\n")
        stream.flush()

    return show


def run(args, echo=print, progress_stream=None):
    """Run the demo with parsed options; returns a dict of results.

    Parameters
    ----------
    args : argparse.Namespace
        Options as set by :func:`add_arguments`.
    echo : callable, optional
        Receives the printed lines (default :func:`print`).
    progress_stream : file-like, optional
        Where the progress bar goes; default the current ``sys.stderr``
        (looked up at call time, so redirected streams are honoured).

    Returns
    -------
    dict
        ``rows`` (the table, one dict per reference, compensator and
        scenario), ``checks`` (name -> (passed, text)), ``files`` (written).

    Examples
    --------
    A 10 ms run without figures (the demo's own default is 10 s):

    >>> import io, tempfile
    >>> parser = argparse.ArgumentParser()
    >>> add_arguments(parser)
    >>> args = parser.parse_args(["--out", tempfile.mkdtemp(), "--duration", "0.01",
    ...                           "--freqs", "5", "--no-figures"])
    >>> res = run(args, echo=lambda line: None, progress_stream=io.StringIO())
    >>> len(res["rows"]), sorted({row["scenario"] for row in res["rows"]})
    (8, ['feedback', 'feedback_compensated', 'feedforward', 'open_loop', 'two_dof'])
    >>> [os.path.basename(p) for p in res["files"]]
    ['loop_comparison.csv']
    """
    if progress_stream is None:
        progress_stream = sys.stderr
    from . import __version__
    from .iosys import compensator_system, mean_gain, pid, piezo_stage
    from .loops import build_scenarios, compare

    out = args.out
    os.makedirs(out, exist_ok=True)
    dt = float(args.dt)
    t = np.arange(int(round(args.duration / dt)) + 1) * dt
    model = demo_actuator()
    stage = piezo_stage(natural_freq_hz=args.stage_hz, damping=args.damping)
    controller = pid(args.kp, args.ki, args.kd, dt)
    input_range = (-2.0, 2.0)  # the exact inverse needs |v| < 1.9 for |w| <= 5
    echo(f"hystcomp {__version__} demo: {model!r} + piezo stage ({args.stage_hz:g} Hz, damping "
         f"{args.damping:g}), PID kp={args.kp:g} ki={args.ki:g} kd={args.kd:g}, dt={dt:g} s, "
         f"{t.size} samples per run")
    comps = {}
    for method in ("exact", "analytic"):
        comps[method] = compensator_system(model, method=method, nominal_gain="auto", input_range=input_range)
    k_nom = comps["exact"].nominal_gain
    work = []
    for f in args.freqs:
        r = reference(t, f)
        for method, comp in comps.items():
            loops = build_scenarios(model, stage, controller=controller, compensator=comp, dt=dt)
            if method != "exact":  # the uncompensated loops do not depend on the compensator
                loops = {k: v for k, v in loops.items() if k not in ("open_loop", "feedback")}
            for lp in loops.values():
                work.append((f, method, lp, r))
    show = _progress(progress_stream)
    rows, results = [], {}
    for j, (f, method, lp, r) in enumerate(work):
        res = compare([lp], r, t, engine=args.engine)
        row = dict(res.rows[0])
        row.update(reference_hz=f, compensator=method if lp.compensator is not None else "none")
        rows.append(row)
        results[(f, method, lp.scenario)] = res
        show(j + 1, len(work), f"{f:g} Hz {method} {lp.scenario}")
    echo("")
    echo(f"Tracking error y - r (reference 5 sin(2 pi f t)/(1 + 0.1 t), span {np.ptp(reference(t, 1.0)):.3g}); "
         f"compensators with nominal gain k = {k_nom:.4f} (mean slope over v in {input_range})")
    head = (f"{'f [Hz]':>6s} {'compensator':11s} {'scenario':22s} {'RMS':>9s} {'max':>9s} {'RMS %':>8s} "
            f"{'max %':>8s} {'width %':>8s}")
    echo(head)
    echo("-" * len(head))
    for row in rows:
        echo(f"{row['reference_hz']:6g} {row['compensator']:11s} {row['scenario']:22s} {row['rms']:9.4g} "
             f"{row['max']:9.4g} {row['rms_percent']:8.3g} {row['max_percent']:8.3g} "
             f"{row['loop_width_percent']:8.3g}")
    files = []
    path = os.path.join(out, "loop_comparison.csv")
    fields = ["reference_hz", "compensator", "scenario", "label", "engine", "rms", "max", "rms_percent",
              "max_percent", "loop_width", "loop_width_percent", "seconds"]
    import csv

    with open(path, "w", newline="") as fh:
        w = csv.DictWriter(fh, fieldnames=fields)
        w.writeheader()
        for row in rows:
            w.writerow({k: row[k] for k in fields})
    files.append(path)
    # checks of the issue
    checks = {}

    def get(f, method, scen):
        comp = "none" if scen in ("open_loop", "feedback") else method
        for row in rows:
            if row["reference_hz"] == f and row["compensator"] == comp and row["scenario"] == scen:
                return row["rms"]
        raise KeyError((f, method, scen))

    for f in args.freqs:
        for method in comps:
            ol, ff = get(f, method, "open_loop"), get(f, method, "feedforward")
            checks[f"feedforward {method} {f:g} Hz"] = (
                ff * 10 <= ol, f"inverse feedforward ({method}) cuts the open-loop RMS error {ol / ff:.1f}x "
                               f"at {f:g} Hz (target >= 10x): {ol:.4g} -> {ff:.4g}")
            fb, fbc = get(f, method, "feedback"), get(f, method, "feedback_compensated")
            checks[f"pid+comp {method} {f:g} Hz"] = (
                fbc < fb, f"PID + {method} compensator beats PID alone at {f:g} Hz: {fb:.4g} -> {fbc:.4g} RMS")
    echo("")
    echo("checks")
    for ok, text in checks.values():
        echo(f"  {'PASS' if ok else 'FAIL'}  {text}")
    # stability of the nominal linear loops
    from .iosys import discretize

    plant_d = discretize(stage, dt)
    # slopes of the raw actuator near v = 0: p0 gamma'(0) just after a reversal
    # (only the r = 0 operator moves), (p0 + sum p_i) gamma'(0) on a long stroke
    dg0 = float(model.envelope.derivative(0.0))
    k_lo, k_hi = model.p0 * dg0, (model.p0 + float(np.sum(model.weights))) * dg0
    echo("")
    echo("stability margins of the nominal linear loop C(z) k P(z) (python-control stability_margins)")
    echo(f"  {'actuator gain k':30s} {'gain margin':>12s} {'phase margin':>13s} {'at':>10s}")
    for label, k in (("compensated, k_nom", k_nom), ("raw, smallest slope", k_lo), ("raw, largest slope", k_hi)):
        _, gm, pm, fc = stability_table(args.kp, args.ki, args.kd, dt, [k], plant_d)[0]
        echo(f"  {label + f' = {k:.3f}':30s} {gm:12.3g} {pm:12.3g}d {fc:8.3g}Hz")
    if not args.no_figures:
        import matplotlib

        matplotlib.use("Agg")
        from .loops import Comparison, plot_comparison

        for f in args.freqs:
            for method in comps:
                keys = [(f, "exact", "open_loop"), (f, method, "feedforward"), (f, "exact", "feedback"),
                        (f, method, "feedback_compensated"), (f, method, "two_dof")]
                rows_f = [results[k].rows[0] for k in keys]
                resp = {results[k].rows[0]["scenario"]: results[k].responses[results[k].rows[0]["scenario"]]
                        for k in keys}
                comp_ = Comparison(rows_f, resp, reference(t, f), t)
                fig = plot_comparison(comp_, title=f"{f:g} Hz reference, {method} compensator "
                                                   f"(nominal gain {k_nom:.3f}), PID ki = {args.ki:g}",
                                      time_window=(0.0, min(t[-1], 2.0 / f)))
                path = os.path.join(out, f"loops_{f:g}Hz_{method}.png")
                fig.savefig(path, dpi=90)
                files.append(path)
    for p in files:
        echo(f"  wrote {p}")
    return dict(rows=rows, checks=checks, files=files)


def main(argv=None):
    """Stand-alone entry point: ``python -m hystcomp.demo [options]``.

    Parameters
    ----------
    argv : list of str, optional
        Command-line arguments (see :func:`add_arguments`); default
        ``sys.argv[1:]``.

    Returns
    -------
    int
        0 when every check of the demo passes, else 1.

    Examples
    --------
    >>> import contextlib, io, tempfile
    >>> with contextlib.redirect_stdout(io.StringIO()) as text, contextlib.redirect_stderr(io.StringIO()):
    ...     code = main(["--out", tempfile.mkdtemp(), "--duration", "0.05", "--freqs", "5",
    ...                  "--no-figures"])
    >>> code, [line.split()[0] for line in text.getvalue().splitlines()
    ...        if line.startswith(("  PASS", "  FAIL"))]
    (0, ['PASS', 'PASS', 'PASS', 'PASS'])
    """
    parser = argparse.ArgumentParser(prog="hystcomp demo", description=__doc__.split("\n\n")[0])
    add_arguments(parser)
    args = parser.parse_args(argv)
    res = run(args)
    return 0 if all(ok for ok, _ in res["checks"].values()) else 1


if __name__ == "__main__":
    sys.exit(main())

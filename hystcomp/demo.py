"""``hystcomp demo``: the thesis's actuator in closed loops tuned to one specification.

An mGPI actuator with the thesis's weights (p0 = 1, p(r) = e^{-0.1 r},
r_i = 0.25 i, 20 operators; section 5) and a saturating envelope
``gamma(v) = 30 tanh(0.05 v)`` drives the default piezo stage
(:func:`hystcomp.iosys.piezo_stage`: 300 Hz, 5 % damping) sampled at 10 kHz;
command v in V, actuator output w and stage position y in um.

The story, step by step:

1. The raw actuator's incremental slope over v in [-2, 2] V lies in the
   sector [1.49, 3.87] um/V (:func:`hystcomp.analysis.slope_bounds`, exact);
   the compensated actuator ``model o C`` (exact inverse with
   ``nominal_gain="auto"``) is the gain k_nom = 2.71.
2. One PID family (integral, proportional, a filtered derivative if the
   phase needs it, a low-pass roll-off at twice the crossover for the
   resonance) is tuned by :func:`hystcomp.design.pid_gains` to a phase
   margin of 60 deg at a gain crossover f_c, on the nominal loop
   ``C k_nom P``; both loops share it.
3. For each f_c the circle criterion (:func:`hystcomp.analysis.circle_criterion`)
   gives the factor by which the loop gain may grow with any slope in the
   actuator's sector; a loop is "safe" when that guaranteed margin is at
   least 2 (6 dB).  The compensated loop (sector [k_nom, k_nom]) stays
   safe to a higher crossover than the raw one (sector [1.49, 3.87]).
4. References ``5 sin(2 pi f t)/(1 + 0.1 t)`` (f = 1 Hz, the thesis's
   chapter 5, and 5 Hz) run through open loop, inverse feedforward, the
   raw loop at its safe crossover, the raw loop at the compensated loop's
   crossover (not proven safe), PID + compensator and feedforward + PID.

It prints the crossover scan, the margins of each designed loop
(:func:`control.stability_margins`: gain margin, phase margin, phase and
gain crossover frequencies), the tracking table and the checks, and writes
PNG figures and ``loop_comparison.csv``.  Wired into the console command by
:mod:`hystcomp.cli` through :func:`add_arguments` and :func:`run`.
"""

import argparse
import os
import sys

import numpy as np

from ._progress import progress_bar
from ._validation import as_count, as_float_array, as_pair, as_scalar, as_vector

__all__ = ["add_arguments", "run", "main", "demo_actuator", "reference", "stability_table", "crossover_scan"]


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
    t = as_float_array(t, "t")
    if not np.all(np.isfinite(t)):
        raise ValueError("Parameter t holds NaN or inf; expected finite times in seconds")
    freq_hz = as_scalar(freq_hz, "freq_hz")
    amplitude = as_scalar(amplitude, "amplitude")
    return amplitude * np.sin(2 * np.pi * freq_hz * t) / (1.0 + 0.1 * t)


def stability_table(kp, ki, kd, dt, gains, plant, controller=None):
    """Margins of the nominal linear loops ``C(z) k P(z)`` for several actuator gains k.

    For each k in `gains` (e.g. the compensated actuator's nominal gain and
    the raw actuator's smallest and largest slopes) returns
    ``(k, gain margin, phase margin [deg], phase crossover [Hz], gain
    crossover [Hz])`` from :func:`control.stability_margins`, which returns
    ``(gm, pm, sm, wpc, wgc, wms)``: the gain margin is measured at the
    phase crossover wpc, the phase margin at the gain crossover wgc.

    Parameters
    ----------
    kp, ki, kd : float
        PID gains (see :func:`hystcomp.iosys.pid`); ignored when
        `controller` is given.
    dt : float
        Sampling time in seconds.
    gains : iterable of float
        Actuator gains k to try.
    plant : control.LTI
        The plant, discretised at `dt` (:func:`hystcomp.iosys.discretize`).
    controller : control.LTI, optional
        Any discrete controller (e.g. :func:`hystcomp.design.design_pid`).

    Returns
    -------
    list of tuple
        ``(k, gain margin, phase margin [deg], phase crossover [Hz], gain
        crossover [Hz])`` per gain.

    Examples
    --------
    The integral controller of the first version of this demo (ki = 40):

    >>> from hystcomp.iosys import discretize, piezo_stage
    >>> rows = stability_table(0.0, 40.0, 0.0, 1e-4, [2.712], discretize(piezo_stage(), 1e-4))
    >>> [(round(gm, 3), round(pm, 1), round(fp), round(fc, 1)) for _, gm, pm, fp, fc in rows]
    [(1.738, 89.7, 300, 17.3)]
    """
    from .design import loop_margins
    from .iosys import pid

    c = pid(kp, ki, kd, dt) if controller is None else controller
    rows = []
    for k in as_vector(gains, "gains"):
        m = loop_margins(c, plant, actuator_gain=float(k))
        rows.append((float(k), m.gain_margin, m.phase_margin_deg, m.phase_crossover_hz, m.crossover_hz))
    return rows


def crossover_scan(plant, dt, nominal_gain, sectors, crossovers_hz, phase_margin_deg=60.0,
                   rolloff_factor=2.0, n_frequencies=4000):
    """Tune one PID per crossover and ask the circle criterion about each sector.

    Parameters
    ----------
    plant : control.LTI
        The stage (continuous).
    dt : float
        Sampling time.
    nominal_gain : float
        The actuator gain the PID is tuned for (k_nom).
    sectors : dict
        name -> (k1, k2): the actuator slope sectors to test (e.g. "raw":
        :func:`hystcomp.analysis.slope_bounds`, "compensated": (k_nom, k_nom)).
    crossovers_hz : iterable of float
        Gain crossover frequencies to try.
    phase_margin_deg : float, optional
        Phase margin of every design (default 60).
    rolloff_factor : float, optional
        The low-pass roll-off sits at this multiple of the crossover
        (default 2).
    n_frequencies : int, optional
        Frequency grid of :func:`hystcomp.analysis.circle_criterion`
        (default 4000, plus 401 points around the resonance).

    Returns
    -------
    list of dict
        Per crossover that can be designed: ``crossover_hz``, ``gains``
        (:class:`hystcomp.design.PIDGains`), ``gain_margin`` (of the
        linear loop at k_nom) and, per sector name,
        the guaranteed factor ``g_<name>``
        (:attr:`hystcomp.analysis.CircleCriterion.gain_margin`).

    Examples
    --------
    >>> from hystcomp.iosys import piezo_stage
    >>> rows = crossover_scan(piezo_stage(), 1e-4, 2.712, {"compensated": (2.712, 2.712)}, [40.0])
    >>> round(rows[0]["g_compensated"], 2), round(rows[0]["gain_margin"], 2)
    (5.52, 5.52)
    """
    import control as ct

    from .analysis import circle_criterion
    from .design import pid_gains
    from .iosys import discretize

    if not isinstance(plant, ct.LTI):
        raise TypeError(f"Parameter plant is {plant!r} ({type(plant).__name__}); expected a python-control "
                        "LTI system")
    dt = as_scalar(dt, "dt", positive=True)
    nominal_gain = as_scalar(nominal_gain, "nominal_gain")
    if nominal_gain == 0:
        raise ValueError("Parameter nominal_gain is 0 but should be nonzero")
    if not isinstance(sectors, dict):
        raise TypeError(f"Parameter sectors is {sectors!r} but should be a dict name -> (k1, k2)")
    for name, sec in sectors.items():
        k1, k2 = as_pair(sec, f"sectors[{name!r}]", increasing=False)
        if k1 > k2:
            raise ValueError(f"Parameter sectors[{name!r}] is {sec!r} but should be (k1, k2) with k1 <= k2")
    crossovers_hz = as_vector(crossovers_hz, "crossovers_hz", positive=True)
    phase_margin_deg = as_scalar(phase_margin_deg, "phase_margin_deg", positive=True)
    if phase_margin_deg >= 180:
        raise ValueError(f"Parameter phase_margin_deg is {phase_margin_deg} but should be below 180")
    rolloff_factor = as_scalar(rolloff_factor, "rolloff_factor", positive=True)
    n_frequencies = as_count(n_frequencies, "n_frequencies", 10)
    pd = discretize(plant, dt)
    out = []
    for fc in crossovers_hz:
        try:
            g = pid_gains(plant, fc, phase_margin_deg, actuator_gain=nominal_gain, dt=dt, filter="lowpass",
                          filter_hz=rolloff_factor * fc)
        except ValueError:
            continue  # not reachable with this controller family
        c = g.system()
        L = ct.series(pd, c)
        # the degenerate sector [k_nom, k_nom] gives the linear gain margin (eigenvalue-exact);
        # each distinct sector is asked once (the compensated sector is usually that one)
        margin = {}

        def guaranteed(sec):
            key = (float(sec[0]), float(sec[1]))
            if key not in margin:
                margin[key] = circle_criterion(L, key, n_frequencies=n_frequencies).gain_margin
            return margin[key]

        row = dict(crossover_hz=float(fc), gains=g, gain_margin=guaranteed((nominal_gain, nominal_gain)))
        for name, sec in sectors.items():
            row[f"g_{name}"] = guaranteed(tuple(sec))
        out.append(row)
    return out


def add_arguments(parser):
    """Add the demo's options to an :class:`argparse.ArgumentParser`.

    Parameters
    ----------
    parser : argparse.ArgumentParser
        The parser (or subparser) to extend: ``--out``, ``--duration``,
        ``--dt``, ``--freqs``, ``--phase-margin``, ``--crossovers``,
        ``--required-margin``, ``--stage-hz``, ``--damping``, ``--engine``,
        ``--no-figures`` and ``--quiet``.

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
    parser.add_argument("--phase-margin", type=float, default=60.0, metavar="DEG",
                        help="phase margin of every PID design in degrees (default: 60)")
    parser.add_argument("--crossovers", type=float, nargs="+", default=[20, 30, 40, 50, 60, 70, 80],
                        metavar="HZ", help="gain crossover frequencies to scan (default: 20 30 ... 80)")
    parser.add_argument("--required-margin", type=float, default=2.0, metavar="G",
                        help="gain factor the circle criterion must guarantee over the actuator's slope "
                             "sector for a loop to count as safe (default: 2, i.e. 6 dB)")
    parser.add_argument("--stage-hz", type=float, default=300.0,
                        help="resonance of the piezo stage in Hz (default: 300)")
    parser.add_argument("--damping", type=float, default=0.05,
                        help="damping ratio of the piezo stage (default: 0.05)")
    parser.add_argument("--engine", choices=("auto", "compiled", "python-control"), default="auto",
                        help="how the loops run: compiled (numba; default via auto) or python-control's "
                             "input_output_response (about 1000x slower: use with a short --duration)")
    parser.add_argument("--no-figures", action="store_true", help="skip the PNG figures")
    parser.add_argument("--quiet", action="store_true",
                        help="no progress bar and no 'wrote FILE' lines (the tables and checks still print)")


_LOOPS = (  # key, scenario, controller, label
    ("open_loop", "open_loop", None, "open loop (1/k_nom)"),
    ("feedforward", "feedforward", None, "inverse feedforward"),
    ("pid_raw_safe", "feedback", "raw", "PID at the raw loop's safe f_c"),
    ("pid_raw_fast", "feedback", "comp", "PID at the compensated f_c (raw)"),
    ("pid_compensated", "feedback_compensated", "comp", "PID + compensator"),
    ("two_dof", "two_dof", "comp", "feedforward + PID + compensator"),
)


def run(args, echo=print, progress_stream=None):
    """Run the demo with parsed options; returns a dict of results.

    Parameters
    ----------
    args : argparse.Namespace
        Options as set by :func:`add_arguments`.
    echo : callable, optional
        Receives the printed lines (default :func:`print`).
    progress_stream : file-like, optional
        Where the progress bar (tqdm) goes; default the current
        ``sys.stderr`` (looked up at call time, so redirected streams are
        honoured).  The bar shows only when the stream is a terminal and
        ``args.quiet`` is not set.

    Returns
    -------
    dict
        ``rows`` (the tracking table, one dict per reference and loop),
        ``scan`` (:func:`crossover_scan`), ``design`` (the chosen
        crossovers, sectors and margins), ``checks`` (name -> (passed,
        text)), ``files`` (written).

    Examples
    --------
    A 10 ms run without figures (the demo's own default is 10 s):

    >>> import io, tempfile
    >>> parser = argparse.ArgumentParser()
    >>> add_arguments(parser)
    >>> args = parser.parse_args(["--out", tempfile.mkdtemp(), "--duration", "0.01",
    ...                           "--freqs", "5", "--crossovers", "50", "80", "--no-figures"])
    >>> res = run(args, echo=lambda line: None, progress_stream=io.StringIO())
    >>> len(res["rows"]), res["design"]["raw_hz"], res["design"]["compensated_hz"]
    (7, 50.0, 80.0)
    >>> [os.path.basename(p) for p in res["files"]]
    ['loop_comparison.csv']
    """
    import csv

    import control as ct

    from . import __version__
    from .analysis import slope_bounds
    from .iosys import compensator_system, piezo_stage
    from .loops import build_loop, compare

    out = args.out
    os.makedirs(out, exist_ok=True)
    dt = float(args.dt)
    t = np.arange(int(round(args.duration / dt)) + 1) * dt
    model = demo_actuator()
    stage = piezo_stage(natural_freq_hz=args.stage_hz, damping=args.damping)
    input_range = (-2.0, 2.0)  # the exact inverse needs |v| < 1.9 for |w| <= 5
    echo(f"hystcomp {__version__} demo: {model!r} + piezo stage ({args.stage_hz:g} Hz, damping "
         f"{args.damping:g}), dt = {dt:g} s, {t.size} samples per run; v in V, w and y in um")
    comp = compensator_system(model, method="exact", nominal_gain="auto", input_range=input_range)
    comp_analytic = compensator_system(model, method="analytic", nominal_gain="auto", input_range=input_range)
    k_nom = comp.nominal_gain
    raw = slope_bounds(model, input_range)
    echo("")
    echo(f"1. actuator slopes over v in {input_range} V (hystcomp.analysis.slope_bounds, exact): "
         f"raw in [{raw.lower:.3f}, {raw.upper:.3f}] um/V; compensated: k_nom = {k_nom:.3f} um/V "
         "(mean slope; exact inverse with nominal_gain='auto')")
    # 2-3. one PID family tuned to the same specification, safe crossover of each loop
    sectors = {"raw": (raw.lower, raw.upper), "compensated": (k_nom, k_nom)}
    scan = crossover_scan(stage, dt, k_nom, sectors, args.crossovers, args.phase_margin)
    if not scan:
        raise ValueError(f"Parameter crossovers is {args.crossovers!r}: no PID with phase margin "
                         f"{args.phase_margin:g} deg could be designed at any of them")
    need = float(args.required_margin)
    echo("")
    echo(f"2-3. PID tuned for phase margin {args.phase_margin:g} deg at each gain crossover f_c on the nominal "
         f"loop C k_nom P (roll-off at 2 f_c); circle criterion: factor g the loop gain may grow by with "
         f"any slope in the sector (safe: g >= {need:g})")
    head = (f"   {'f_c [Hz]':>8s} {'kp':>8s} {'ki':>8s} {'kd':>9s} {'GM at k_nom':>11s} "
            f"{'g raw':>7s} {'g comp':>7s}")
    echo(head)
    for row in scan:
        g = row["gains"]
        echo(f"   {row['crossover_hz']:8g} {g.kp:8.4f} {g.ki:8.2f} {g.kd:9.2e} {row['gain_margin']:11.3f} "
             f"{row['g_raw']:7.3f} {row['g_compensated']:7.3f}")
    safe_raw = [r for r in scan if r["g_raw"] >= need]
    safe_comp = [r for r in scan if r["g_compensated"] >= need]
    best_raw = safe_raw[-1] if safe_raw else scan[0]
    best_comp = safe_comp[-1] if safe_comp else scan[0]
    fc_raw, fc_comp = best_raw["crossover_hz"], best_comp["crossover_hz"]
    echo(f"   safe crossover: raw loop {fc_raw:g} Hz (g = {best_raw['g_raw']:.2f}), compensated loop "
         f"{fc_comp:g} Hz (g = {best_comp['g_compensated']:.2f}); the raw loop at {fc_comp:g} Hz has "
         f"g = {best_comp['g_raw']:.2f}")
    ctrl = {"raw": best_raw["gains"].system(), "comp": best_comp["gains"].system()}
    echo("")
    echo("   margins of the nominal linear loops C k P (python-control stability_margins: GM at the phase "
         "crossover, PM at the gain crossover)")
    echo(f"   {'controller':14s} {'actuator gain k':24s} {'GM':>7s} {'PM [deg]':>9s} {'phase crossover':>16s} "
         f"{'gain crossover':>15s}")
    from .iosys import discretize

    pd = discretize(stage, dt)
    g_dc = float(np.real(ct.dcgain(pd)))
    margins = {}
    for cname, fc in (("raw", fc_raw), ("comp", fc_comp)):
        for label, k in (("k_nom", k_nom), ("smallest slope", raw.lower), ("largest slope", raw.upper)):
            _, gm, pm, fp, fg = stability_table(0, 0, 0, dt, [k], pd, controller=ctrl[cname])[0]
            margins[(cname, label)] = (gm, pm, fp, fg)
            echo(f"   {f'f_c = {fc:g} Hz':14s} {label + f' = {k:.3f}':24s} {gm:7.3f} {pm:9.1f} {fp:13.1f} Hz "
                 f"{fg:12.2f} Hz")
    # 4. tracking
    work = []
    for f in args.freqs:
        r = reference(t, f)
        for key, scen, cname, label in _LOOPS:
            lp = build_loop(scen, model, stage, controller=ctrl[cname] if cname else None,
                            compensator=comp if scen in ("feedforward", "feedback_compensated", "two_dof") else None,
                            dt=dt, name=key,
                            # the uncompensated open loop is calibrated linearly: 1 / (k_nom G(1))
                            feedforward_gain=1.0 / (k_nom * g_dc) if scen == "open_loop" else "auto")
            work.append((f, key, label, lp, r))
        lp = build_loop("feedforward", model, stage, compensator=comp_analytic, dt=dt, name="feedforward_analytic")
        work.append((f, "feedforward_analytic", "inverse feedforward (analytic)", lp, r))
    quiet = bool(getattr(args, "quiet", False))
    rows, responses = [], {}
    bar = progress_bar(total=len(work), desc="loops", enabled=not quiet, file=progress_stream, unit="loop")
    for f, key, label, lp, r in work:
        bar.set_postfix_str(f"{f:g} Hz {key}", refresh=False)
        res = compare([lp], t, r, engine=args.engine)
        row = dict(res.rows[0])
        fc = {"pid_raw_safe": fc_raw}.get(key, fc_comp if key in ("pid_raw_fast", "pid_compensated", "two_dof")
                                           else float("nan"))
        row.update(reference_hz=f, loop=key, label=label, crossover_hz=fc)
        rows.append(row)
        responses[(f, key)] = res.responses[key]
        bar.update()
    bar.close()
    echo("")
    echo(f"4. tracking error y - r [um], reference 5 sin(2 pi f t)/(1 + 0.1 t) (span "
         f"{np.ptp(reference(t, 1.0)):.3g} um)")
    head = f"   {'f [Hz]':>6s} {'loop':36s} {'f_c [Hz]':>8s} {'RMS':>9s} {'max':>9s} {'RMS %':>8s} {'max %':>8s}"
    echo(head)
    echo("   " + "-" * (len(head) - 3))
    for row in rows:
        echo(f"   {row['reference_hz']:6g} {row['label']:36s} {row['crossover_hz']:8g} {row['rms']:9.4g} "
             f"{row['max']:9.4g} {row['rms_percent']:8.3g} {row['max_percent']:8.3g}")
    files = []
    path = os.path.join(out, "loop_comparison.csv")
    fields = ["reference_hz", "loop", "label", "scenario", "crossover_hz", "engine", "rms", "max", "rms_percent",
              "max_percent", "loop_width", "loop_width_percent", "seconds"]
    with open(path, "w", newline="") as fh:
        w = csv.DictWriter(fh, fieldnames=fields)
        w.writeheader()
        for row in rows:
            w.writerow({k: row.get(k, row.get("scenario")) for k in fields})
    files.append(path)

    def rms(f, key):
        return next(r["rms"] for r in rows if r["reference_hz"] == f and r["loop"] == key)

    checks = {}
    for f in args.freqs:
        ol = rms(f, "open_loop")
        worst = max(("pid_raw_safe", "pid_raw_fast", "pid_compensated", "two_dof"), key=lambda k: rms(f, k))
        checks[f"feedback beats open loop {f:g} Hz"] = (
            rms(f, worst) < ol, f"every feedback loop beats open loop at {f:g} Hz: worst {worst} "
                                f"{rms(f, worst):.4g} < open loop {ol:.4g} RMS")
        ff = rms(f, "feedforward")
        checks[f"feedforward {f:g} Hz"] = (
            ff * 10 <= ol, f"inverse feedforward (exact) cuts the open-loop RMS error {ol / ff:.1f}x at {f:g} Hz "
                           f"(target >= 10x): {ol:.4g} -> {ff:.4g}")
        a, b = rms(f, "pid_raw_safe"), rms(f, "pid_compensated")
        checks[f"bandwidth pays {f:g} Hz"] = (
            b < a, f"PID + compensator at {fc_comp:g} Hz beats the raw loop at its safe {fc_raw:g} Hz at {f:g} Hz: "
                   f"{a:.4g} -> {b:.4g} RMS ({a / b:.2f}x)")
    checks["compensation buys bandwidth"] = (
        fc_comp > fc_raw and best_comp["g_raw"] < need <= best_comp["g_compensated"],
        f"at {fc_comp:g} Hz the compensated loop is guaranteed g = {best_comp['g_compensated']:.2f} >= {need:g}, "
        f"the raw loop only g = {best_comp['g_raw']:.2f} (its safe crossover: {fc_raw:g} Hz)")
    echo("")
    echo("checks")
    for ok, text in checks.values():
        echo(f"  {'PASS' if ok else 'FAIL'}  {text}")
    design = dict(raw_hz=fc_raw, compensated_hz=fc_comp, raw_sector=(raw.lower, raw.upper), nominal_gain=k_nom,
                  margins=margins, controllers=ctrl)
    if not args.no_figures:
        files += _figures(out, args, t, rows, responses, scan, design, need)
    if not quiet:
        for p in files:
            echo(f"  wrote {p}")
    return dict(rows=rows, scan=scan, design=design, checks=checks, files=files)


def _figures(out, args, t, rows, responses, scan, design, need):
    import matplotlib

    matplotlib.use("Agg")
    from .plotting import new_figure

    files = []
    fig, ax = new_figure(1, 1, size=(6.4, 4.2))
    fcs = [r["crossover_hz"] for r in scan]
    ax.plot(fcs, [r["g_compensated"] for r in scan], "o-", label="compensated: sector [k_nom, k_nom]")
    ax.plot(fcs, [r["g_raw"] for r in scan], "s-", label=f"raw: sector [{design['raw_sector'][0]:.2f}, "
                                                         f"{design['raw_sector'][1]:.2f}] um/V")
    ax.axhline(need, color="k", ls="--", lw=1, label=f"required g = {need:g}")
    ax.set(xlabel="gain crossover f_c [Hz] (phase margin %g deg)" % args.phase_margin,
           ylabel="guaranteed gain factor g (circle criterion)",
           title="How far the loop gain may grow with any actuator slope")
    ax.set_ylim(0, None)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8, loc="upper right")
    path = os.path.join(out, "crossover_scan.png")
    fig.savefig(path, dpi=90)
    files.append(path)
    keys = ("open_loop", "pid_raw_safe", "pid_raw_fast", "pid_compensated", "two_dof")
    short = {"open_loop": "open loop", "pid_raw_safe": "PID, raw actuator", "pid_raw_fast": "PID, raw actuator",
             "pid_compensated": "PID + compensator", "two_dof": "feedforward + PID + compensator"}
    for f in args.freqs:
        fig, axes = new_figure(1, 3, size=(15, 4.6))
        r = reference(t, f)
        win = t <= min(t[-1], 2.0 / f)
        last = t >= t[-1] - 1.0 / f   # one period at the end: no overplotted bands
        axes[0].plot(t[win], r[win], "k--", lw=1.2, label="reference r")
        for key in keys:
            row = next(x for x in rows if x["reference_hz"] == f and x["loop"] == key)
            y = np.asarray(responses[(f, key)].outputs)[0]
            fc = "" if np.isnan(row["crossover_hz"]) else f", f_c {row['crossover_hz']:g} Hz"
            lab = f"{short[key]}{fc}: {row['rms_percent']:.2g} % RMS"
            axes[0].plot(t[win], y[win], lw=0.9, label=lab)
            axes[1].plot(t[win], (y - r)[win], lw=0.9, label=lab)
            axes[2].plot(r[last], (y - r)[last], lw=0.9, label=lab)
        axes[0].set(xlabel="time t [s]", ylabel="position y [um]", title="tracking")
        axes[1].set(xlabel="time t [s]", ylabel="error y - r [um]", title="tracking error", yscale="symlog")
        axes[1].set_yscale("symlog", linthresh=1e-3)
        axes[2].set(xlabel="reference r [um]", ylabel="error y - r [um]", title="error against reference (last period)")
        axes[2].set_yscale("symlog", linthresh=1e-3)
        for ax in axes:
            ax.grid(True, alpha=0.3)
        handles, labels = axes[0].get_legend_handles_labels()
        fig.legend(handles, labels, loc="outside lower center", ncols=3, fontsize=8)
        fig.suptitle(f"{f:g} Hz reference; PID tuned to {args.phase_margin:g} deg phase margin, exact compensator "
                     f"(k_nom = {design['nominal_gain']:.3f} um/V)")
        path = os.path.join(out, f"loops_{f:g}Hz.png")
        fig.savefig(path, dpi=90)
        files.append(path)
    return files


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
    ...     code = main(["--out", tempfile.mkdtemp(), "--duration", "0.5", "--freqs", "5",
    ...                  "--crossovers", "50", "80", "--no-figures"])
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

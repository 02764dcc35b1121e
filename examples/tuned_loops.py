"""Loops tuned to one specification, with and without compensation
===============================================================

The thesis's mGPI actuator drives the 300 Hz piezo stage.  One PID family
(integral, proportional, a low-pass roll-off at twice the crossover) is tuned by
``hystcomp.design.design_pid`` to a 60 deg phase margin at a gain crossover on
the nominal loop ``C k_nom P``.  The circle criterion
(``hystcomp.analysis.circle_criterion``) then says by how much the loop gain may
grow with any actuator slope in a sector (``hystcomp.analysis.slope_bounds``):
the raw actuator's [1.49, 3.87] um/V, the exactly compensated actuator's
[k_nom, k_nom], and the sector of a compensator built from a mismatched
identification (weights 15 % off).

In the Nyquist plane the sector [k1, k2] is the critical disc on
[-1/k1, -1/k2]: the raw actuator's disc is wide and reaches toward the loop's
curve, so a loop tuned for a high crossover comes close to it; the
compensated actuator's "disc" is the point -1/k_nom.  A 6 dB guarantee (g >= 2)
holds for the raw loop up to 50 Hz and for the compensated one up to 80 Hz.

Run:  python examples/tuned_loops.py [--out DIR]
"""

import argparse
import tempfile
import os

import matplotlib

matplotlib.use("Agg")

import control as ct  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.figure import Figure  # noqa: E402

from hystcomp import MGPI  # noqa: E402
from hystcomp.analysis import circle_criterion, slope_bounds  # noqa: E402
from hystcomp.demo import demo_actuator, reference  # noqa: E402
from hystcomp.design import design_pid, loop_margins  # noqa: E402
from hystcomp.iosys import compensator_system, discretize, piezo_stage  # noqa: E402
from hystcomp.loops import build_loop, compare  # noqa: E402

DT = 1e-4


def main(argv=None):
    parser = argparse.ArgumentParser(description=(__doc__ or "").partition("\n")[0])
    parser.add_argument("--out", default=None,
                        help="folder for the figures (default: a new temporary folder)")
    args = parser.parse_args(argv)
    if args.out is None:
        args.out = tempfile.mkdtemp(prefix="hystcomp-tuned_loops-")
    os.makedirs(args.out, exist_ok=True)
    model = demo_actuator()
    stage = piezo_stage()
    comp = compensator_system(model, nominal_gain="auto", input_range=(-2.0, 2.0))
    k_nom = comp.nominal_gain
    # a compensator built from a mismatched identification: weights 15 % high, p0 5 % low
    fit = MGPI(model.thresholds, 1.15 * model.weights, 0.95 * model.p0, envelope=model.envelope)
    comp_fit = compensator_system(fit, nominal_gain=k_nom, input_range=(-2.0, 2.0))
    u_range = (-5.0 / k_nom, 5.0 / k_nom)       # the compensators' input for |y| <= 5 um
    sectors = {
        "raw": slope_bounds(model, (-2.0, 2.0)),
        "compensated": slope_bounds(model, u_range, compensator=comp),
        "mismatched compensator": slope_bounds(model, u_range, compensator=comp_fit),
    }
    print("actuator slope sectors [um/V]:")
    for name, sec in sectors.items():
        print(f"  {name:24s} [{sec.lower:.4f}, {sec.upper:.4f}]  ({'exact' if sec.exact else 'sampled'})")
    pd = discretize(stage, DT)
    print(f"\n{'f_c [Hz]':>8s} {'GM(k_nom)':>9s} {'PM [deg]':>8s} " + " ".join(f"{'g ' + n:>26s}" for n in sectors))
    loops, curves = {}, {}
    for fc in (50.0, 80.0):
        c = design_pid(stage, fc, 60.0, actuator_gain=k_nom, dt=DT, filter="lowpass", filter_hz=2 * fc)
        m = loop_margins(c, stage, k_nom)
        L = ct.series(pd, c)
        g = {n: circle_criterion(L, tuple(s)).gain_margin for n, s in sectors.items()}
        print(f"{fc:8g} {m.gain_margin:9.3f} {m.phase_margin_deg:8.2f} " + " ".join(f"{g[n]:26.3f}" for n in sectors))
        w = 2 * np.pi * np.geomspace(1, 5000, 4000)
        curves[fc] = L(np.exp(1j * w * DT))
        loops[f"PID, raw actuator, f_c {fc:g} Hz"] = build_loop("feedback", model, stage, controller=c, dt=DT,
                                                                 name=f"raw_{fc:g}")
        if fc == 80.0:
            loops[f"PID + compensator, f_c {fc:g} Hz"] = build_loop(
                "feedback_compensated", model, stage, controller=c, compensator=comp, dt=DT, name="comp")
            loops[f"PID + mismatched compensator, f_c {fc:g} Hz"] = build_loop(
                "feedback_compensated", model, stage, controller=c, compensator=comp_fit, dt=DT, name="fit")
    t = np.arange(0, 2.0, DT)
    r = reference(t, 5.0)
    res = compare(list(loops.values()), t, r)
    print("\n5 Hz reference, 2 s:")
    for label, row in zip(loops, res.rows):
        print(f"  {label:44s} RMS {row['rms']:.4f} um ({row['rms_percent']:.2f} % of the span)")
    fig = Figure(figsize=(13, 5), layout="constrained")
    ax_n, ax_e = fig.subplots(1, 2)
    for fc, color in ((50.0, "C1"), (80.0, "C0")):
        ax_n.plot(curves[fc].real, curves[fc].imag, color=color, lw=1.2, label=f"C P, f_c = {fc:g} Hz")
    th = np.linspace(0, 2 * np.pi, 400)
    for (name, sec), color in zip(sectors.items(), ("C3", "k", "C2")):
        a, b = -1 / sec.lower, -1 / sec.upper
        centre, radius = (a + b) / 2, abs(a - b) / 2
        ax_n.plot(centre + radius * np.cos(th), radius * np.sin(th), color=color, lw=1.5 if radius > 1e-3 else 0,
                  marker=None if radius > 1e-3 else "x", label=f"critical disc, {name}")
        if radius <= 1e-3:
            ax_n.plot([centre], [0], "x", color=color, ms=9, mew=2)
    ax_n.set(xlim=(-0.8, 0.2), ylim=(-0.6, 0.4), aspect="equal",
             xlabel="Re [-] (loop gain, dimensionless)", ylabel="Im [-]",
             title="Nyquist curves of C P and the sectors' critical discs")
    ax_n.grid(True, alpha=0.3)
    ax_n.legend(fontsize=7, loc="lower left")
    last = t >= t[-1] - 0.2
    for (label, row), color in zip(zip(loops, res.rows), ("C1", "C0", "k", "C2")):
        y = np.asarray(res.responses[row["scenario"]].outputs)[0]
        ax_e.plot(t[last], (y - r)[last], lw=1, color=color, label=f"{label}: {row['rms_percent']:.2f} % RMS")
    ax_e.set(xlabel="time t [s]", ylabel="tracking error y - r [um]", title="5 Hz reference, the last period")
    ax_e.grid(True, alpha=0.3)
    ax_e.legend(fontsize=7, loc="upper right")
    ax_e.set_ylim(-0.6, 1.0)
    path = os.path.join(args.out, "tuned_loops.png")
    fig.savefig(path, dpi=90)
    print(f"wrote {path}")


if __name__ == "__main__":
    main()

"""Compensating what the diagnosis finds
=====================================

A record of an actuator with hidden creep (``hidden_effect_data("creep")``: a PI actuator
whose output keeps moving after each step) is diagnosed; the diagnosis names creep and
returns a model built from its parts. That model's ``exact_inverse()`` is a causal
compensator: at every sample, the input for which the model's output equals the
reference. It is compared with the compensator of a plain PI fit on a staircase with
2 s holds, both run against the *true* system that made the record. The plain
compensator cancels the hysteresis but not the creep: its error grows during every hold.

Run: python examples/compensate_diagnosed.py --out DIR
"""

import argparse
import os
import tempfile

import matplotlib

matplotlib.use("Agg")
import numpy as np  # noqa: E402
from matplotlib.figure import Figure  # noqa: E402

from hystcomp.datasets import hidden_effect_data  # noqa: E402
from hystcomp.diagnose import diagnose  # noqa: E402
from hystcomp.identify import fit_weights  # noqa: E402

DT = 0.01


def true_response(seed, v, amplitude):
    """The record's true system on the input v (one extra sample at the identification
    amplitude keeps hidden_effect_data's actuator, whose thresholds scale with max|v|)."""
    vv = np.append(v, amplitude)
    t = np.arange(vv.size) * DT
    return hidden_effect_data("creep", seed=seed, dt=DT, experiment=(t, vv)).clean[:-1]


def main(argv=None):
    ap = argparse.ArgumentParser(description=(__doc__ or "").partition("\n")[0])
    ap.add_argument("--out", default=None, help="folder for compensate_diagnosed.png (default: a new temporary folder)")
    ap.add_argument("--seed", type=int, default=0)
    args = ap.parse_args(argv)
    if args.out is None:
        args.out = tempfile.mkdtemp(prefix="hystcomp-compensate_diagnosed-")
    d = hidden_effect_data("creep", seed=args.seed, dt=DT)
    A = float(np.max(np.abs(d.v)))
    rep = diagnose(d.t, d.v, d.y, progress=False)
    plain = fit_weights(d.v, d.y)
    print(f"diagnosis: {rep.verdict}, effects {rep.effects}; hidden mechanism: {d.mechanism}")

    lo, hi = np.percentile(d.y, [10, 90])
    levels = [0.5 * (lo + hi)] + [lo + (hi - lo) * f for f in (0.9, 0.2, 0.7, 0.1, 0.8, 0.35, 0.6)]
    r = np.repeat(levels, 200)
    t = np.arange(r.size) * DT
    v_diag = rep.model.exact_inverse(input_limits=(-A, A)).simulate(r)
    v_plain = np.clip(plain.model.exact_inverse().simulate(r - plain.offset), -A, A)
    y_diag, y_plain = true_response(args.seed, v_diag, A), true_response(args.seed, v_plain, A)
    e_diag = np.sqrt(np.mean((y_diag - r) ** 2))
    e_plain = np.sqrt(np.mean((y_plain - r) ** 2))
    span = np.ptp(d.y)
    print(f"RMS tracking error against the true system: diagnosed-model compensator {e_diag:.4g} "
          f"({100 * e_diag / span:.2f} % of the output span), plain PI compensator {e_plain:.4g} "
          f"({100 * e_plain / span:.2f} %): {e_plain / e_diag:.1f}x")

    fig = Figure(figsize=(9, 6), layout="constrained")
    ax = fig.subplots(2, 1, sharex=True)
    ax[0].plot(t, r, "k--", lw=1.0, label="reference")
    ax[0].plot(t, y_plain, lw=1.0, label=f"plain PI compensator (RMS {e_plain:.3g})")
    ax[0].plot(t, y_diag, lw=1.0, label=f"diagnosed model's compensator (RMS {e_diag:.3g})")
    ax[0].set(ylabel="output [output units]", title="Staircase through the true actuator (hidden creep)")
    ax[0].legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    ax[1].plot(t, y_plain - r, lw=1.0, label="plain PI compensator")
    ax[1].plot(t, y_diag - r, lw=1.0, label="diagnosed model's compensator")
    ax[1].axhline(0.0, color="k", lw=0.5)
    ax[1].set(xlabel="time [s]", ylabel="tracking error [output units]")
    ax[1].legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    os.makedirs(args.out, exist_ok=True)
    path = os.path.join(args.out, "compensate_diagnosed.png")
    fig.savefig(path, dpi=110)
    print("wrote", path)


if __name__ == "__main__":
    main()

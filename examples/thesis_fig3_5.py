"""Thesis Fig. 3.5: input-output relationship of the PI model
==========================================================

Thesis Fig. 3.5: input-output relationship of the PI model (section 3.2, eq. 18).

The PI model with p0 = 1 and density p(r) = e^{-0.001 r}, initial value w(0) = 0.
The thesis gives neither the input nor the thresholds of this figure; the input
of Fig. 2.1, v(t) = 10 sin(2 pi t)/(1 + 0.1 t) on t in [0, 10], and r_i = 0.5 i,
N = 20 (R = 10) are used. With a nearly flat density every operator carries
almost the same weight, so the loop is wide and its branches are parabolas
joined at the reversal points (the loading curve phi(r) = r + sum_i p_i (r - r_i)
grows quadratically, eq. 30).

Run:  python examples/thesis_fig3_5.py [--out DIR]
"""
import argparse
import tempfile
import os

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
from matplotlib.figure import Figure  # noqa: E402

from hystcomp import MGPI, PI  # noqa: E402


def main(argv=None):
    parser = argparse.ArgumentParser(description=(__doc__ or "").partition("\n")[0])
    parser.add_argument("--out", default=None,
                        help="folder for the figures (default: a new temporary folder)")
    args = parser.parse_args(argv)
    if args.out is None:
        args.out = tempfile.mkdtemp(prefix="hystcomp-thesis_fig3_5-")
    os.makedirs(args.out, exist_ok=True)

    t = np.arange(0.0, 10.0 + 1e-9, 1e-3)
    v = 10 * np.sin(2 * np.pi * t) / (1 + 0.1 * t)
    r = 0.5 * np.arange(1, 21)
    mgpi = MGPI.from_density(lambda r: np.exp(-0.001 * r), r, p0=1.0)   # p_i = p(r_i)(r_i - r_{i-1})
    model = PI(r, mgpi.weights, p0=1.0)
    w = model.simulate(v)

    fig = Figure(figsize=(11, 4.4), layout="constrained")
    ax1, ax2 = fig.subplots(1, 2)
    ax1.plot(v, w, lw=0.9)
    ax1.set_title("Figure 3.5: Input-output relationship of PI model\n"
                  "p0 = 1, p(r) = exp(-0.001 r), w(0) = 0", fontsize=9)
    ax1.set_xlabel("input v(t)")
    ax1.set_ylabel("output w(t)")
    ax1.grid(alpha=0.3)
    rr = np.linspace(0, 10, 201)
    ax2.plot(rr, model.loading_curve(rr), label="loading curve phi(r) (eq. 30)")
    ax2.plot(rr, rr, "k--", lw=0.8, label="p0 r alone")
    ax2.set_title("its initial loading curve", fontsize=9)
    ax2.set_xlabel("r")
    ax2.set_ylabel("phi(r)")
    ax2.grid(alpha=0.3)
    ax2.legend(fontsize=8)
    path = os.path.join(args.out, "fig3_5.png")
    fig.savefig(path, dpi=100)

    print("Fig. 3.5: PI model, p0 = 1, p(r) = exp(-0.001 r), r_i = 0.5 i, N = 20")
    print(f"  sum of weights p_i = {model.weights.sum():.4f} (integral of p over [0, 10]: "
          f"{1000 * (1 - np.exp(-0.01)):.4f})")
    print(f"  output range [{w.min():.3f}, {w.max():.3f}] for input range [{v.min():.3f}, {v.max():.3f}]")
    print(f"  loading curve phi(10) = {model.loading_curve(10.0):.3f}")
    print(f"wrote {path}")


if __name__ == "__main__":
    main()

"""Thesis section 3.5: PI, GPI and mGPI models and the output bound
================================================================

Thesis section 3.5 (Figs. 3.17-3.19, eq. 29): PI, GPI and mGPI models with
R = 10, p0 = 1, p(r) = e^{-0.1 r}, envelopes gl = 10 tanh(0.2 v),
gr = 10 tanh(0.1 v), under v(t) = 10 sin(2 pi t) + t, t in [0, 10].

Run:  python examples/thesis_3_5.py [--out DIR]
"""
import argparse
import tempfile
import os

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402

from hystcomp import plotting, thesis  # noqa: E402
from hystcomp.operators import generalized_play  # noqa: E402


def main(argv=None):
    parser = argparse.ArgumentParser(description=(__doc__ or "").partition("\n")[0])
    parser.add_argument("--out", default=None,
                        help="folder for the figures (default: a new temporary folder)")
    args = parser.parse_args(argv)
    if args.out is None:
        args.out = tempfile.mkdtemp(prefix="hystcomp-thesis_3_5-")
    os.makedirs(args.out, exist_ok=True)
    case = thesis.section_3_5()
    v = case.signal
    print(case.caption)
    print(f"  {case.notes}")
    for name, model in case.models.items():
        w = model.simulate(v)
        print(f"  {name:5s} output range [{w.min():8.3f}, {w.max():8.3f}]")
    gpi = case.models["GPI"]
    W, _ = generalized_play(v, [10.0], gpi.envelope_left, gpi.envelope_right)
    print(f"  GPI operator r = 10: max |output| = {np.abs(W).max():g} (never moves)")
    mgpi = case.models["mGPI"]
    print(f"  eq. 29 bound, thesis (integral): {thesis.mgpi_bound_limit():.4f}")
    print(f"  eq. 29 bound, r_i = 0.5 i, N = 20: {thesis.mgpi_bound():.4f} "
          f"(output_bounds() = {mgpi.output_bounds()[1]:.4f})")
    print(f"  eq. 29 bound, r_i = 0.001 i, N = 10000: {thesis.mgpi_bound(spacing=0.001):.4f}")
    path = os.path.join(args.out, "fig3_17-3_19.png")
    plotting.figure_3_5(case).savefig(path, dpi=90)
    print(f"  wrote {path}")


if __name__ == "__main__":
    main()

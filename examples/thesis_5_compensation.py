"""Thesis chapter 5: inverse compensation of the mGPI model
========================================================

Thesis chapter 5 (Figs. 5.3, 5.4, 5.6): inverse compensation of the mGPI
model with gamma = v, 3v and atanh(0.5 v); the analytic inverse of eqs.
54-58 against the exact inverse.

Run:  python examples/thesis_5_compensation.py [--out DIR]
"""
import argparse
import tempfile
import os

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402

from hystcomp import plotting, thesis  # noqa: E402


def main(argv=None):
    parser = argparse.ArgumentParser(description=(__doc__ or "").partition("\n")[0])
    parser.add_argument("--out", default=None,
                        help="folder for the figures (default: a new temporary folder)")
    args = parser.parse_args(argv)
    if args.out is None:
        args.out = tempfile.mkdtemp(prefix="hystcomp-thesis_5_compensation-")
    os.makedirs(args.out, exist_ok=True)
    for name in thesis.SECTION_5:
        case = thesis.section_5(name)
        inv = case.model.inverse()
        table = thesis.THESIS_TABLES[name]
        dq = np.max(np.abs(np.round(inv.thresholds, 4) - table["q"]))
        ng = len(table["g"])
        dg = np.max(np.abs(np.round(inv.weights[:ng], 4) - table["g"]))
        print(f"Section {name}: {case.caption}")
        print(f"  inverse table vs thesis (4 decimals): max |dq| = {dq:.1e}, max |dg| = {dg:.1e} "
              f"({ng} printed weights)")
        path = os.path.join(args.out, f"fig{case.extra['figure'].replace('.', '_')}.png")
        plotting.figure_5(case).savefig(path, dpi=100)
        print(f"  wrote {path}")
    print()
    print("Compensation error model(inverse(u)) - u, % of the reference span:")
    print(f"  {'section':8s} {'inverse':9s} {'RMS %':>10s} {'max %':>10s}")
    for row in thesis.compensation_errors():
        print(f"  {row['section']:8s} {row['inverse']:9s} {row['rms_percent']:10.3g} {row['max_percent']:10.3g}")


if __name__ == "__main__":
    main()

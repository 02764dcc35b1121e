"""Thesis section 4.1: the PI model's initial loading curve
========================================================

Thesis section 4.1 (Figs. 4.1-4.2, eqs. 34-35): the PI model
w = v + int_0^R e^{-0.1 r} F_r[v] dr and its initial loading curve
phi(r) = 11 r - 100 + 100 e^{-0.1 r}.

Run:  python examples/thesis_4_1.py [--out DIR]
"""
import argparse
import tempfile
import os

import matplotlib

matplotlib.use("Agg")

from hystcomp import plotting, thesis  # noqa: E402


def main(argv=None):
    parser = argparse.ArgumentParser(description=(__doc__ or "").partition("\n")[0])
    parser.add_argument("--out", default=None,
                        help="folder for the figures (default: a new temporary folder)")
    args = parser.parse_args(argv)
    if args.out is None:
        args.out = tempfile.mkdtemp(prefix="hystcomp-thesis_4_1-")
    os.makedirs(args.out, exist_ok=True)
    print("Section 4.1: loading curve of eq. 34 vs eq. 35")
    for spacing in (0.5, 0.05, 0.005):
        case = thesis.section_4_1(spacing=spacing, dt=0.01)
        dev = thesis.loading_curve_deviation(case)
        print(f"  r_i = {spacing} i (N = {case.model.n_operators:5d}): max |phi_N - phi| on [0, 10] = "
              f"{dev:.5f} (bound h*R = {thesis.loading_curve_error_bound(spacing, case.extra['R']):.4f})")
    case = thesis.section_4_1()
    path = os.path.join(args.out, "fig4_1-4_2.png")
    plotting.figure_4_1(case).savefig(path, dpi=100)
    print(f"  wrote {path}")


if __name__ == "__main__":
    main()

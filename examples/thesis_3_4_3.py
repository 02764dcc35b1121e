"""Thesis section 3.4.3: the mGPI model with four envelope sets
============================================================

Thesis section 3.4.3, table 3.1 (Figs. 3.13-3.16): the mGPI model with four
envelope sets under v(t) = 6 sin(pi t) + 4 cos(3.3 pi t), t in [0, 10].

Run:  python examples/thesis_3_4_3.py [--out DIR]
"""
import argparse
import tempfile
import os

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402

from hystcomp import PI, plotting, thesis  # noqa: E402


def main(argv=None):
    parser = argparse.ArgumentParser(description=(__doc__ or "").partition("\n")[0])
    parser.add_argument("--out", default=None,
                        help="folder for the figures (default: a new temporary folder)")
    args = parser.parse_args(argv)
    if args.out is None:
        args.out = tempfile.mkdtemp(prefix="hystcomp-thesis_3_4_3-")
    os.makedirs(args.out, exist_ok=True)
    for k in (1, 2, 3, 4):
        case = thesis.section_3_4_3(k)
        model = case.model
        w = model.simulate(case.signal)
        print(f"{case.caption}: output range [{w.min():.3f}, {w.max():.3f}], "
              f"output_bounds() = ({model.output_bounds()[0]:.3f}, {model.output_bounds()[1]:.3f})")
        if k == 1:  # gamma = v: the mGPI model is the classical PI model
            pi = PI(model.thresholds, model.weights, model.p0)
            print(f"  max |mGPI(gamma = v) - PI| = {np.max(np.abs(w - pi.simulate(case.signal))):.3g}")
        path = os.path.join(args.out, f"fig{case.extra['figure'].replace('.', '_')}.png")
        plotting.figure_3_4_3(case).savefig(path, dpi=100)
        print(f"  wrote {path}")


if __name__ == "__main__":
    main()

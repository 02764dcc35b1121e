"""Thesis Fig. 2.1: a typical hysteresis loop
==========================================

Thesis Fig. 2.1: a typical hysteresis loop (multivalued, wiping out,
congruent minor loops) under v(t) = 10 sin(2 pi t)/(1 + 0.1 t), t in [0, 10].

Run:  python examples/thesis_fig2_1.py [--out DIR]
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
        args.out = tempfile.mkdtemp(prefix="hystcomp-thesis_fig2_1-")
    os.makedirs(args.out, exist_ok=True)
    case = thesis.figure_2_1()
    w = case.model.simulate(case.signal)
    print(case.caption)
    print(f"  model: {case.model!r}; {case.notes}")
    print(f"  input range [{case.signal.min():.3f}, {case.signal.max():.3f}], "
          f"output range [{w.min():.3f}, {w.max():.3f}]")
    path = os.path.join(args.out, "fig2_1.png")
    plotting.figure_2_1(case).savefig(path, dpi=110)
    print(f"  wrote {path}")


if __name__ == "__main__":
    main()

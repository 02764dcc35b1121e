"""Thesis Figs. 3.7 and 3.12: the elementary operators for several thresholds
==========================================================================

Thesis Figs. 3.7 and 3.12: the elementary operators for several thresholds r.

Fig. 3.7: input-output relationships under v(t) = 10 sin(t) with different
thresholds r, (a) the classical play operator (eq. 13), (b) the generalized
play operator (eq. 20) with gl(v) = 5 tanh(0.25 v), gr(v) = 5 tanh(0.5 v).
Fig. 3.12: the modified generalized play operator (eq. 23) with
gl(v) = gr(v) = 5 tanh(0.5 v) and different thresholds r.

The thesis does not list its thresholds; r = 0, 1, 2, 3, 4 are used here.
Points to look for: the generalized play's boundaries are the envelopes
shifted along the output axis, so its output range shrinks with r and its
zero crossings are gl^-1(r) and gr^-1(-r), not +-r; the modified play's
boundaries are the envelope shifted along the input axis, so every operator
saturates at +-5 and crosses zero at v = +-r (thesis section 3.4.1).

Run:  python examples/thesis_3_7_3_12.py [--out DIR]
"""
import argparse
import tempfile
import os

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
from matplotlib.figure import Figure  # noqa: E402

from hystcomp import Tanh, generalized_play, modified_play, play  # noqa: E402


def main(argv=None):
    parser = argparse.ArgumentParser(description=(__doc__ or "").partition("\n")[0])
    parser.add_argument("--out", default=None,
                        help="folder for the figures (default: a new temporary folder)")
    args = parser.parse_args(argv)
    if args.out is None:
        args.out = tempfile.mkdtemp(prefix="hystcomp-thesis_3_7_3_12-")
    os.makedirs(args.out, exist_ok=True)

    t = np.linspace(0.0, 4 * np.pi, 4001)      # two periods of v(t) = 10 sin(t)
    v = 10 * np.sin(t)
    r = np.array([0.0, 1.0, 2.0, 3.0, 4.0])
    gl, gr = Tanh(5.0, 0.25), Tanh(5.0, 0.5)
    g = Tanh(5.0, 0.5)

    classical, _ = play(v, r)
    generalized, _ = generalized_play(v, r, gl, gr)
    modified, _ = modified_play(v, r, g)

    fig = Figure(figsize=(15, 4.6), layout="constrained")
    axes = fig.subplots(1, 3)
    panels = [
        (classical, "Figure 3.7 (a): classical play operator, v(t) = 10 sin(t)"),
        (generalized, "Figure 3.7 (b): generalized play operator,\n"
                      "gl = 5 tanh(0.25 v), gr = 5 tanh(0.5 v)"),
        (modified, "Figure 3.12: modified generalized play operator,\n"
                   "gl = gr = 5 tanh(0.5 v)"),
    ]
    for ax, (w, title) in zip(axes, panels):
        for i, ri in enumerate(r):
            ax.plot(v, w[:, i], lw=1.2, label=f"r = {ri:g}")
        ax.axhline(0.0, color="k", lw=0.5)
        ax.axvline(0.0, color="k", lw=0.5)
        ax.set_title(title, fontsize=9)
        ax.set_xlabel("input v(t)")
        ax.set_ylabel("operator output")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7, loc="upper left")
    path = os.path.join(args.out, "fig3_7_3_12.png")
    fig.savefig(path, dpi=100)

    print("Figs. 3.7 and 3.12: operators under v(t) = 10 sin(t), r = 0, 1, 2, 3, 4")
    print(f"{'r':>4s} {'play range':>18s} {'generalized range':>20s} {'modified range':>18s}")
    for i, ri in enumerate(r):
        rows = [(w[:, i].min(), w[:, i].max()) for w in (classical, generalized, modified)]
        print(f"{ri:4g} " + " ".join(f"[{a:7.3f}, {b:6.3f}]" for a, b in rows))
    # zero crossings on the first full rising branch (v from -10 up to 10, t in [1.5 pi, 2.5 pi])
    second = (t >= 1.5 * np.pi) & (t <= 2.5 * np.pi)
    for name, w in (("generalized", generalized), ("modified", modified)):
        xs = []
        for i in range(1, r.size):
            wi, vi = w[second, i], v[second]
            k = np.nonzero((wi[:-1] <= 0) & (wi[1:] > 0))[0]
            xs.append(f"r={r[i]:g}: v={vi[k[0] + 1]:.3f}" if k.size else f"r={r[i]:g}: none")
        print(f"rising zero crossings, {name} play: " + ", ".join(xs))
    print(f"wrote {path}")


if __name__ == "__main__":
    main()

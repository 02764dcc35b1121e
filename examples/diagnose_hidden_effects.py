"""Blind test of the diagnosis on the library's generator
======================================================

Hide one effect, see whether it is named.  For each effect (and none) and each seed, :func:`hystcomp.datasets.hidden_effect_data`
draws a random PI actuator, one mechanism of the effect with a random size,
and sensor noise on the identification experiment; only (t, v, y) go into
:func:`hystcomp.diagnose.diagnose`.  Prints the confusion matrix (hidden
effect against the first effect named), the share of runs whose held-out
RMS shrank by at least half and of "explained" verdicts, and draws the
matrix and the diagnosis figures of one run.

    python examples/diagnose_hidden_effects.py --out figs                # seconds
    python examples/diagnose_hidden_effects.py --seeds 40 --dt 0.004     # the full run of docs/diagnose.md
"""

import argparse
import os
import tempfile
import time

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402

from hystcomp.datasets import EFFECTS, hidden_effect_data  # noqa: E402
from hystcomp.diagnose import EFFECTS as NAMED  # noqa: E402
from hystcomp.diagnose import diagnose  # noqa: E402
from hystcomp.plotting import new_figure  # noqa: E402

ROWS = ("none",) + EFFECTS
COLS = ("none",) + NAMED


def confusion(seeds, dt, first_seed=0, echo=print):
    """(matrix counts[hidden][named], halved counts, runs, mechanisms) over the seeds."""
    counts = {h: {c: 0 for c in COLS} for h in ROWS}
    halved = {h: 0 for h in ROWS}
    runs = []
    for h in ROWS:
        for s in range(first_seed, first_seed + seeds):
            d = hidden_effect_data(None if h == "none" else h, seed=s, dt=dt)
            rep = diagnose(d.t, d.v, d.y, progress=False)
            named = rep.effects[0] if rep.effects else "none"
            counts[h][named] += 1
            ratio = rep.rms_after / rep.rms_before
            halved[h] += ratio <= 0.5
            runs.append((h, d.mechanism, s, named, ratio, rep.elapsed))
            echo(f"  {h:16s} {str(d.mechanism):20s} seed {s:3d}: named {named:16s} held-out RMS x {ratio:.3f}"
                 f"  {rep.verdict:11s} ({rep.elapsed:.1f} s)")
    return counts, halved, runs


def main(argv=None):
    ap = argparse.ArgumentParser(description=(__doc__ or "").partition("\n")[0])
    ap.add_argument("--out", default=None, help="folder for the figures (default: a new temporary folder)")
    ap.add_argument("--seeds", type=int, default=1, help="seeds per effect (default 1: a quick look)")
    ap.add_argument("--first-seed", type=int, default=0)
    ap.add_argument("--dt", type=float, default=0.01, help="sampling time [s] of the 40 s experiment")
    args = ap.parse_args(argv)
    if args.out is None:
        args.out = tempfile.mkdtemp(prefix="hystcomp-diagnose_hidden_effects-")
    os.makedirs(args.out, exist_ok=True)
    t0 = time.perf_counter()
    print(f"blind diagnosis: {args.seeds} seed(s) per effect, dt = {args.dt} s "
          f"({int(round(40 / args.dt))} samples per record)")
    counts, halved, runs = confusion(args.seeds, args.dt, args.first_seed)
    n = args.seeds
    print("\nconfusion matrix (rows: hidden effect; columns: first effect named)")
    print(f"{'':16s} " + " ".join(f"{c[:10]:>10s}" for c in COLS) + "   RMS halved")
    for h in ROWS:
        print(f"{h:16s} " + " ".join(f"{counts[h][c]:10d}" for c in COLS)
              + (f"   {halved[h]:4d}/{n}" if h != "none" else ""))
    print("\nper mechanism: named first / held-out RMS halved / runs (worst RMS ratio)")
    mechs = sorted({(r[0], r[1]) for r in runs if r[1] is not None})
    for h, m in mechs:
        sel = [r for r in runs if r[0] == h and r[1] == m]
        print(f"  {h:16s} {m:20s} {sum(r[3] == h for r in sel):3d} / {sum(r[4] <= 0.5 for r in sel):3d} / "
              f"{len(sel):3d}   ({max(r[4] for r in sel):.3f})")
    correct = sum(counts[h][h] for h in ROWS)
    print(f"\ncorrect first effect: {correct}/{len(ROWS) * n}; "
          f"mean time per diagnosis {np.mean([r[5] for r in runs]):.2f} s; "
          f"total {time.perf_counter() - t0:.1f} s")

    fig, ax = new_figure(1, 1, size=(7.5, 6))
    M = np.array([[counts[h][c] for c in COLS] for h in ROWS])
    ax.imshow(M, cmap="Blues")
    for i in range(M.shape[0]):
        for j in range(M.shape[1]):
            ax.text(j, i, str(M[i, j]), ha="center", va="center",
                    color="white" if M[i, j] > 0.6 * M.max() else "black")
    ax.set_xticks(range(len(COLS)), COLS, rotation=30, ha="right")
    ax.set_yticks(range(len(ROWS)), ROWS)
    ax.set(xlabel="first effect named by diagnose", ylabel="hidden effect",
           title=f"Blind diagnosis, {n} seed(s) per row, dt = {args.dt} s")
    path = os.path.join(args.out, "diagnose_confusion.png")
    fig.savefig(path, dpi=90)
    print(f"wrote {path}")
    d = hidden_effect_data("creep", seed=args.first_seed, dt=args.dt)
    rep = diagnose(d.t, d.v, d.y, progress=False)
    print(f"\nexample run (hidden creep, mechanism {d.mechanism}):\n{rep.summary()}")
    for p in rep.save_plots(args.out):
        print(f"wrote {p}")
    return 0


if __name__ == "__main__":
    main()

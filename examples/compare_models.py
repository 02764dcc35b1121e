"""Preisach, KP, Bouc-Wen and backlash-like models next to the PI model
====================================================================

Preisach, KP, Bouc-Wen and backlash-like models next to the PI model,
on the measured piezo record: one fit each, their loops on one figure.

Data: A. Chandra et al. (2023), a piezo actuator driven by a 1 Hz, +-150 V
sine at 5 kHz (MIT licence; ``hystcomp/data/SOURCE.md``).  Every model is
fitted on t in [3.5, 7) s (after the ringing of the voltage step at
t = 3.26 s) with :func:`hystcomp.identify.compare_models`, simulated over
the whole record from its default state and scored on t >= 7 s.  The
figure shows the held-out loops of all models over the measured one (left)
and their held-out errors (right); the table is printed.

Run: ``python examples/compare_models.py --out figures``
"""

import argparse
import tempfile
from pathlib import Path

import numpy as np

from hystcomp.data import load_piezo
from hystcomp.identify import compare_models

MODELS = ("pi", "preisach", "kp", "bouc_wen", "backlash_like")
LABELS = {"pi": "PI", "preisach": "Preisach", "kp": "KP", "bouc_wen": "Bouc-Wen", "backlash_like": "backlash-like"}


def run(n_cells=15, max_train_samples=5000):
    t, v, y = load_piezo()
    i0, i1 = np.searchsorted(t, 3.5), np.searchsorted(t, 7.0)
    res = compare_models(v, y, models=MODELS, n_cells=n_cells, max_train_samples=max_train_samples,
                         train=(i0, i1))
    return t, v, y, i1, res


def plot(t, v, y, split, res, out):
    from hystcomp.plotting import new_figure

    fig, ax = new_figure(1, 2, size=(12, 4.8))
    held = slice(split, None)
    ax[0].plot(v[held], y[held], color="0.6", lw=3, label="measured")
    for r in res:
        ax[0].plot(v[held], r["prediction"][held], lw=0.9,
                   label=f"{LABELS[r['name']]} ({r['n_parameters']} par., rms {r['rms']:.3f} um)")
        ax[1].plot(t[held], y[held] - r["prediction"][held], lw=0.6, label=LABELS[r["name"]])
    ax[0].set(xlabel="voltage [V]", ylabel="displacement [um]", title="held-out loops (t >= 7 s)")
    ax[1].set(xlabel="t [s]", ylabel="measured - model [um]", title="held-out error")
    ax[0].legend(fontsize=8)
    ax[1].legend(fontsize=8, ncol=2)
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    path = out / "compare_models.png"
    fig.savefig(path, dpi=120)
    return path


def main():
    ap = argparse.ArgumentParser(description=(__doc__ or "").partition("\n")[0])
    ap.add_argument("--out", default=None,
                        help="folder for the figures (default: a new temporary folder)")
    args = ap.parse_args()
    if args.out is None:
        args.out = tempfile.mkdtemp(prefix="hystcomp-compare_models-")
    t, v, y, split, res = run()
    print(res.table())
    print(f"wrote {plot(t, v, y, split, res, args.out)}")


if __name__ == "__main__":
    main()

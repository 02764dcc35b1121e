"""Identify PI and mGPI models of a measured piezo actuator
========================================================

Data: A. Chandra et al. (2023), a piezo actuator driven by a 1 Hz, +-150 V
sine sampled at 5 kHz (MIT licence; ``hystcomp/data/SOURCE.md``).  The
models run from the virgin state at t = 0 (0 V until t = 3.26 s), are fitted
on t in [3.5, 7) s and validated on t >= 7 s (three held-out cycles).

Fits: a PI model with 20 operators, and mGPI models whose envelope is
fitted by variable projection (tanh and atanh families, gamma'(0) = 1), and
an asymmetric mGPI (gl = rho v, gr = v: different slopes for rising and
falling input).

Run: ``python examples/identify_piezo.py --out figures``
"""

import argparse
import tempfile
import time
from pathlib import Path

import numpy as np

from hystcomp.data import load_piezo
from hystcomp.identify import fit, fit_weights


def run(n_thresholds=20, families=("tanh", "atanh"), maxiter=60, asymmetric_families=("linear",)):
    """Fit every model; return (t, v, y, train, held, results) with results a
    list of (name, FitResult, seconds).  `asymmetric_families` are fitted with
    left and right envelopes apart (asymmetric mGPI)."""
    t, v, y = load_piezo()
    train = (t >= 3.5) & (t < 7.0)
    held = t >= 7.0
    results = []
    t0 = time.perf_counter()
    res = fit_weights(v, y, model="pi", n_thresholds=n_thresholds,
                      sample_weight=train.astype(float), validation=held)
    results.append(("PI", res, time.perf_counter() - t0))
    for fam in families:
        t0 = time.perf_counter()
        res = fit(v, y, envelope=fam, n_thresholds=n_thresholds,
                  sample_weight=train.astype(float), validation=held, maxiter=maxiter)
        results.append((f"mGPI ({fam})", res, time.perf_counter() - t0))
    for fam in asymmetric_families:
        t0 = time.perf_counter()
        res = fit(v, y, envelope=fam, asymmetric=True, n_thresholds=n_thresholds,
                  sample_weight=train.astype(float), validation=held, maxiter=maxiter)
        results.append((f"mGPI asym ({fam})", res, time.perf_counter() - t0))
    return t, v, y, train, held, results


def table(results):
    rows = [f"{'model':<20}{'train RMS [um]':>15}{'held-out RMS [um]':>19}{'RMS % stroke':>14}"
            f"{'max % stroke':>14}{'time [s]':>10}"]
    for name, res, sec in results:
        val = res.validation
        rows.append(f"{name:<20}{res.rmse:>15.4f}{val['rms']:>19.4f}{val['rms_percent']:>14.3f}"
                    f"{val['max_percent']:>14.3f}{sec:>10.2f}")
    return "\n".join(rows)


def plot(t, v, y, held, results, out):
    from hystcomp.plotting import new_figure

    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    fig, ax = new_figure(1, 2, size=(11, 4.5))
    ax[0].plot(v[held], y[held], "k.", ms=1, label="measured (held out)")
    for name, res, _ in results:
        ax[0].plot(v[held], (y - res.residuals)[held], lw=1, label=name)
        ax[1].plot(t[held], res.residuals[held], lw=0.6, label=name)
    ax[0].set(xlabel="voltage [V]", ylabel="displacement [um]", title="loops, t >= 7 s")
    ax[1].set(xlabel="t [s]", ylabel="residual [um]", title="held-out residual")
    ax[0].legend(fontsize=8)
    ax[1].legend(fontsize=8)
    path = out / "identify_piezo.png"
    fig.savefig(path, dpi=120)
    return path


def main(argv=None):
    ap = argparse.ArgumentParser(description=(__doc__ or "").partition("\n")[0])
    ap.add_argument("--out", default=None,
                        help="folder for the figures (default: a new temporary folder)")
    ap.add_argument("--thresholds", type=int, default=20, help="number of operators")
    args = ap.parse_args(argv)
    if args.out is None:
        args.out = tempfile.mkdtemp(prefix="hystcomp-identify_piezo-")
    t, v, y, train, held, results = run(args.thresholds)
    print(table(results))
    for name, res, _ in results:
        print(f"\n[{name}]\n{res.report()}")
    if args.out:
        print("\nfigure:", plot(t, v, y, held, results, args.out))


if __name__ == "__main__":
    main()

"""Diagnose a measured piezo record: which effect does a PI model lack?
====================================================================

Diagnose the measured piezo record (Chandra et al. 2023): which effect does a PI model lack?

The whole record goes in: 3.26 s at 0 V, the voltage step to -87 V, then the
1 Hz, +-150 V sine; the last 30 % (t = 7 .. 10 s) is held out.  A second run
starts at the step, to show where the base model's error comes from (see
docs/diagnose.md for the explanation).

    python examples/diagnose_piezo.py --out figs           # every 5th sample (1 kHz), seconds
    python examples/diagnose_piezo.py --out figs --full    # all 50,001 samples at 5 kHz
"""

import argparse
import tempfile
import os

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402

from hystcomp.data import load_piezo  # noqa: E402
from hystcomp.diagnose import diagnose  # noqa: E402


def main(argv=None):
    ap = argparse.ArgumentParser(description=(__doc__ or "").partition("\n")[0])
    ap.add_argument("--out", default=None,
                        help="folder for the figures (default: a new temporary folder)")
    ap.add_argument("--full", action="store_true", help="all samples (5 kHz) instead of every 5th")
    args = ap.parse_args(argv)
    if args.out is None:
        args.out = tempfile.mkdtemp(prefix="hystcomp-diagnose_piezo-")
    os.makedirs(args.out, exist_ok=True)
    t, v, y = load_piezo()
    if not args.full:
        t, v, y = t[::5], v[::5], y[::5]
    print(f"piezo record: {t.size} samples, t = {t[0]:.4g} .. {t[-1]:.4g} s, "
          f"dt = {np.median(np.diff(t)) * 1e3:.3g} ms")

    rep = diagnose(t, v, y, progress=False)
    print("\n== whole record (the 0 V hold and the voltage step included) ==")
    print(rep.summary())
    for s in rep.steps:
        c = ", ".join(f"{k} {val:.4g}" for k, val in s["evidence"]["candidates"].items())
        print(f"  step candidates (held-out RMS): {c}")
    skip = ("signature", "reading", "testable")
    for name, ev in rep.first_evidence.items():
        nums = ", ".join(f"{a}={b}" for a, b in ev.items() if a not in skip)
        print(f"  signature of {name} in the base residual: {nums or '-'}")
    for p in rep.save_plots(args.out):
        print(f"wrote {p}")

    # where the base error comes from: residual level during the 0 V hold vs after the step
    e = y - rep.base_model.simulate(v)
    k_step = int(np.argmax(np.abs(v) > 1.0))
    print(f"\nbase residual: mean {e[:k_step].mean():+.3f} um during the 0 V hold "
          f"(t < {t[k_step]:.4g} s), {e[k_step + 5:].mean():+.3f} um after the step; "
          f"measured output at rest {y[:k_step].mean():+.3f} um")

    rep2 = diagnose(t[k_step:], v[k_step:], y[k_step:], progress=False)
    print("\n== from the voltage step on (the 0 V hold left out) ==")
    print(rep2.summary())
    print(f"\nheld-out RMS: whole record {rep.rms_before:.4g} -> {rep.rms_after:.4g} um; "
          f"from the step on {rep2.rms_before:.4g} -> {rep2.rms_after:.4g} um")
    sub = os.path.join(args.out, "from_step")
    for p in rep2.save_plots(sub):
        print(f"wrote {p}")
    return 0


if __name__ == "__main__":
    main()

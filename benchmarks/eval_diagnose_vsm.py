"""The diagnosis on 15 measured VSM hysteresis loops read without a time axis (the table of
docs/diagnose.md, "Measured: VSM loops of rocks and magnetosomes").

The loops are HystLab's example data (tests/data/hystlab_vsm, see its SOURCE.md): one major loop
of a rock, sediment or magnetosome specimen per file, field [T] against moment [A m^2] as
measured, read by tests/measured_vsm.py.  Each is diagnosed with ``t=None`` and one worker (as
the realistic evaluation runs), BLAS on one thread.

Usage::

    python benchmarks/eval_diagnose_vsm.py            # prints a Markdown table and a summary
"""

import os
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "tests"))

from measured_vsm import LOOPS, read_micromag  # noqa: E402

from hystcomp.diagnose import diagnose  # noqa: E402

TIME_EFFECTS = {"rate_dependence", "creep", "drift", "gain_drift", "delay"}


def main():
    try:
        from threadpoolctl import threadpool_limits

        threadpool_limits(limits=1, user_api="blas")
    except ImportError:
        pass
    print("| file | specimen | points | Hmax [T] | effects named | verdict | held-out RMS of the base model, % of "
          "span | of the final model | noise floors left | s |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    named, timed, total = 0, 0, 0.0
    for name, (what, _) in LOOPS.items():
        H, m, _ = read_micromag(name)
        t0 = time.perf_counter()
        rep = diagnose(None, H, m, progress=False, workers=1)
        sec = time.perf_counter() - t0
        total += sec
        d = rep.to_dict()
        tentative = [s["effect"] for s in rep.steps if s.get("tentative")]
        effects = ", ".join(rep.effects) or "none"
        if tentative:
            effects += f" ({', '.join(tentative)} tentative)"
        named += rep.effects[:1] == ["saturation"]
        timed += bool(set(rep.effects) & TIME_EFFECTS)
        print(f"| {name} | {what} | {H.size} | {abs(H).max():.2f} | {effects} | {rep.verdict} | "
              f"{d['rms_before_pct']:.2f} | {d['rms_after_pct']:.2f} | {rep.rms_heldout / rep.noise_floor:.1f} | "
              f"{sec:.1f} |")
    print(f"\nsaturation named first on {named} of {len(LOOPS)} loops; a time effect named on {timed}; "
          f"{total:.1f} s in all")


if __name__ == "__main__":
    main()

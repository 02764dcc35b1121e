"""Benchmark: a diagnosis's revision refits side by side (round 48).

Once two or more effects are named, the diagnosis revises them
(:func:`hystcomp.diagnose.revise.revise`): each step's near ties and other
forms are refitted with the later effects in the model, then the model is
refitted without each part in turn.  Each refit is a variable-projection
search over every nonlinear parameter, so on a long record with several
effects the revision can take half of the diagnosis.  Until round 47 the
refits ran one after another whatever ``workers`` was; since round 48 they
run ``workers`` side by side (:func:`hystcomp.identify.parallel_fits.run_all`),
the same refits, so the same answer.

The records are realistic test records (``tests/realistic``, mechanisms
written from their physics, not hystcomp's parts) whose diagnosis revises
two or more effects.  Each is diagnosed with ``workers=2`` (the default on
two cores) twice, alternately: the refits side by side, and one after
another as before round 48 (the baseline, measured in the same run).  The
answers (effects, verdict, held-out RMS, inner solves) must be the same.
The machine is shared: the load (``os.getloadavg``) is printed next to the
figures.

Run: ``python benchmarks/bench_revision.py [--cases NAME SEED ...] [--repeats 1]``
"""

import argparse
import os
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "tests"))

from realistic import ALL  # noqa: E402

from hystcomp.diagnose import diagnose, revise  # noqa: E402
from hystcomp.identify import parallel_fits  # noqa: E402

#: records whose diagnosis revises two or more effects (case, seed): HOLDOUT45's rod behind a FIR probe
#: conditioner (37,599 samples, two effects) and under magnetic viscosity (three effects)
RECORDS = [("holdout45_delay_probe_conditioner_fir_stapler_557hz", 2),
           ("holdout45_creep_magnetic_viscosity_nipping_press_287hz", 1)]


def _one_after_another(vp, tasks, workers=1, processes=None):
    """The baseline: the revision's refits one after another (before round 48)."""
    return parallel_fits.run_all(vp, tasks, 1)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cases", nargs="+", default=None, metavar="NAME SEED",
                    help="case names and seeds, alternately (default: two HOLDOUT45 records)")
    ap.add_argument("--repeats", type=int, default=1)
    ap.add_argument("--workers", type=int, default=2)
    args = ap.parse_args(argv)
    records = RECORDS if args.cases is None else list(zip(args.cases[::2], map(int, args.cases[1::2])))
    for name, _ in records:
        if name not in ALL:
            ap.error(f"--cases: {name!r} is not a case of tests/realistic's ALL")
    # warm-up: numba caches and imports are not the diagnosis
    rec = ALL[records[0][0]](records[0][1])
    diagnose(rec.t[:4000], rec.v[:4000], rec.y[:4000], progress=False, workers=1)
    real = revise.run_all
    ways = [("side by side (round 48)", real), ("one after another (baseline)", _one_after_another)]
    same = True
    for name, seed in records:
        rec = ALL[name](seed)
        times, answers = {w: [] for w, _ in ways}, {}
        for _ in range(args.repeats):
            for way, fn in ways:      # alternately, so that a change in the load hits both
                revise.run_all = fn
                try:
                    t0 = time.perf_counter()
                    rep = diagnose(rec.t, rec.v, rec.y, progress=False, workers=args.workers)
                    times[way].append(time.perf_counter() - t0)
                finally:
                    revise.run_all = real
                answers[way] = (tuple(rep.effects), rep.verdict, rep.rms_after, rep.n_evaluations)
        print(f"\n{name}, seed {seed}: {rec.t.size} samples; workers={args.workers}; "
              f"{rep.verdict}, effects {list(rep.effects) or 'none'}, {len(rep.revisions)} revisions, "
              f"{rep.n_evaluations} inner solves")
        base = min(times[ways[1][0]])
        for way, _ in ways:
            best = min(times[way])
            each = ", ".join(f"{x:.1f}" for x in times[way])
            print(f"  revision refits {way:30s} {best:7.1f} s  ({best / base:.2f} of the baseline; runs {each})")
        same &= len(set(answers.values())) == 1
    print("\nthe same answer both ways: " + ("yes" if same else "NO"))
    print("load average (1, 5, 15 min): " + ", ".join(f"{x:.2f}" for x in os.getloadavg()))
    return 0 if same else 1


if __name__ == "__main__":
    raise SystemExit(main())

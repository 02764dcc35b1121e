"""Finding the holds of a long record: :func:`hystcomp.diagnose.record.find_holds`
against its Python scan, measured in the same run.

``find_holds`` looks for runs in which the smoothed input stays within a
tolerance of the run's running mean; a run too short moves the start one
sample on.  On an input that stays put for just under the shortest hold
(0.1 s), every start scans almost a shortest hold before it fails: the cost is
the record's length times the shortest hold's.  Until round 28 that scan was
a Python loop (kept below as the baseline, the same arithmetic); it is
compiled now (:mod:`hystcomp.diagnose._hold_runs`).

Records (the input only; the noise is 1e-4 of the span, as a monitor's):

* ``staircase``: a 10 kHz staircase whose stairs last one shortest hold
  (1,000 samples), the worst case named above;
* ``triangle``: a 10 kHz triangle wave at 0.5 Hz with 2 s holds at its turns,
  an ordinary record.

For each record and length the script prints the best of ``--repeats`` wall
times of ``find_holds`` (compiled scan, plus the levels and load changes it
computes for each hold) and of the Python scan of the same runs (on up to
``--baseline-max`` samples; beyond, not run), their ratio, and checks that
both give the same runs.  The first call's compilation is measured apart.

Run::

    python benchmarks/bench_holds.py                  # 50,000 ... 1,000,000 samples
    python benchmarks/bench_holds.py --lengths 50000  # a quicker look

Target (round 28): the staircase of 1,000,000 samples in at most 5 s (the
Python scan: 59 s for 100,000 samples in round 27).  The exit status is 0
whatever the figures; the load average is printed with them.
"""

import argparse
import math
import os
import time

import numpy as np


def python_runs(vs, tol, min_len):
    """The Python scan ``find_holds`` ran until round 28 (the baseline)."""
    n, out, k = vs.size, [], 0
    while k < n - 1:
        total, j = vs[k], k + 1
        while j < n and abs(vs[j] - total / (j - k)) <= tol:
            total += vs[j]
            j += 1
        if j - k >= min_len:
            out.append((k, j))
            k = j
        else:
            k += 1
    return out


def staircase(n, rng, fs=10_000.0, stair=0.1):
    m = int(round(stair * fs))
    levels = rng.uniform(-1.0, 1.0, n // m + 1)
    v = np.repeat(levels, m)[:n]
    return v + 1e-4 * 2.0 * rng.standard_normal(n)


def triangle(n, rng, fs=10_000.0, f=0.5, hold=2.0):
    t = np.arange(n) / fs
    period = 1.0 / f + 2 * hold
    ph = np.mod(t, period)
    ramp = 0.5 / f
    v = np.where(ph < ramp, -1 + 2 * ph / ramp, 1.0)
    v = np.where(ph >= ramp + hold, 1 - 2 * (ph - ramp - hold) / ramp, v)
    v = np.where(ph >= 2 * ramp + hold, -1.0, v)
    return v + 1e-4 * 2.0 * rng.standard_normal(n)


def best(fn, repeats):
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        out = fn()
        times.append(time.perf_counter() - t0)
    return min(times), out


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--lengths", type=int, nargs="+", default=[50_000, 100_000, 1_000_000])
    p.add_argument("--repeats", type=int, default=2)
    p.add_argument("--baseline-max", type=int, default=100_000)
    a = p.parse_args(argv)

    from hystcomp.diagnose import record
    from hystcomp.diagnose._hold_runs import hold_runs

    dt, min_len = 1e-4, 1000
    t0 = time.perf_counter()
    hold_runs(np.zeros(20), 1e-4, 10)
    print(f"first call (compilation or cache load): {time.perf_counter() - t0:.2f} s")
    print(f"load average: {', '.join(f'{x:.2f}' for x in os.getloadavg())}")
    print(f"{'record':10} {'samples':>9} {'holds':>6} {'find_holds':>11} {'Python scan':>12} {'ratio':>7}  same runs")
    verdict = True
    for name, make in (("staircase", staircase), ("triangle", triangle)):
        for n in a.lengths:
            v = make(n, np.random.default_rng(n))
            span = float(np.ptp(v))
            tn, holds = best(lambda: record.find_holds(v, dt, span), a.repeats)
            line = f"{name:10} {n:9d} {len(holds):6d} {tn:10.3f}s"
            if n <= a.baseline_max:
                noise = record._input_noise(v)
                tol = max(5.0 * noise * math.sqrt(2.0 / 11.0), 1e-4 * span)
                vs = record._smooth(v, 5)
                tp, runs = best(lambda: python_runs(vs, tol, min_len), 1)
                starts, ends = hold_runs(vs, tol, min_len)
                same = runs == list(zip(starts.tolist(), ends.tolist()))
                verdict &= same
                line += f" {tp:11.3f}s {tp / tn:6.0f}x  {same}"
            else:
                line += f" {'(not run)':>12} {'':>7}"
            print(line)
            if name == "staircase" and n == 1_000_000:
                ok = tn <= 5.0
                verdict &= ok
                print(f"  target: the staircase of 1,000,000 samples in at most 5 s: {'PASS' if ok else 'FAIL'}")
    print("the same runs as the Python scan, and the target:", "PASS" if verdict else "FAIL")


if __name__ == "__main__":
    main()

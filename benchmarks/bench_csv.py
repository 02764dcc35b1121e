"""Loading a long measurement CSV: :func:`hystcomp.diagnose.load_csv` (pandas)
against plain baselines measured in the same run.

The script writes a CSV of ``--rows`` rows (default 10 million; columns
``t,v,y``, six significant digits, about 270 MB) into a temporary folder,
then loads it in fresh subprocesses and prints, for each loader, the wall
time and the peak resident memory of the subprocess (``resource.getrusage``
``ru_maxrss``, which includes the interpreter and the imports):

* ``load_csv``: the loader of ``hystcomp diagnose`` on all rows;
* ``csv.reader loop``: the hand-written loader it replaced (a
  ``csv.reader`` over the whole file and a float per cell, as in hystcomp
  before issue 14), on ``--baseline-rows`` rows (default 1 million), and
  scaled linearly to all rows;
* ``numpy.loadtxt``: on the same ``--baseline-rows`` rows, scaled;
* ``python -c "import pandas"``: the floor of any such subprocess.

Imports are not timed (the import of hystcomp, numba and cvxpy is a
cold-start matter, see ``bench_coldstart.py``); the memory is the
subprocess's peak (``VmHWM`` of ``/proc/self/status``, falling back to
``resource.getrusage(...).ru_maxrss``, which on Linux survives ``exec`` and
may show the parent's peak), imports included.

Run::

    python benchmarks/bench_csv.py                 # 10 million rows
    python benchmarks/bench_csv.py --rows 1000000  # a quicker look

Target (issue 14): 10 million rows in at most 10 s and 2 GB.  The exit
status is 0 whatever the figures; the load average is printed with them.
"""

import argparse
import os
import shutil
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# the loader hystcomp used before issue 14 (its reading loop, for comparison)
OLD_LOADER = r'''
import csv, math
import numpy as np
def old_load(path, names=("t", "v", "y")):
    with open(path, newline="", encoding="utf-8-sig") as fh:
        rows = list(csv.reader(fh))
    header = [h.strip() for h in rows[0]]
    cols = {n: header.index(n) for n in names}
    body = [r for r in rows[1:] if any(c.strip() for c in r)]
    out = {n: np.empty(len(body)) for n in cols}
    for i, row in enumerate(body):
        for n, j in cols.items():
            val = float(row[j])
            if not math.isfinite(val):
                raise ValueError(val)
            out[n][i] = val
    return out["t"], out["v"], out["y"]
'''

# (imports, timed call): the imports are not timed (hystcomp's import, with
# numba and cvxpy, is a cold-start matter: benchmarks/bench_coldstart.py)
SNIPPETS = {
    "load_csv": ("from hystcomp.diagnose import load_csv", "t, v, y = load_csv(PATH)"),
    "csv.reader loop": (OLD_LOADER, "t, v, y = old_load(PATH)"),
    "numpy.loadtxt": ("import numpy as np", "t, v, y = np.loadtxt(PATH, delimiter=',', skiprows=1, unpack=True)"),
    "import pandas": ("import pandas", "t = [0]"),
}

# peak memory of the subprocess: VmHWM (the high-water mark of its own
# address space); ru_maxrss is printed too but on Linux it survives exec and
# can carry the parent's peak
RUNNER = r'''
import resource, sys, time
PATH = sys.argv[1]
exec(compile(sys.argv[2], "<imports>", "exec"))
r0 = resource.getrusage(resource.RUSAGE_SELF)
t0 = time.perf_counter()
exec(compile(sys.argv[3], "<call>", "exec"))
wall = time.perf_counter() - t0
r1 = resource.getrusage(resource.RUSAGE_SELF)
cpu = (r1.ru_utime - r0.ru_utime) + (r1.ru_stime - r0.ru_stime)
hwm = float("nan")
try:
    with open("/proc/self/status") as fh:
        for line in fh:
            if line.startswith("VmHWM:"):
                hwm = int(line.split()[1]) / 1024.0
except OSError:
    pass
print(wall, cpu, hwm, resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0, len(t))
'''


def write_csv(path, n, chunk=1_000_000):
    """t = 0.001 k (three decimals), a sine input and a lagging output (six significant digits)."""
    import numpy as np

    with open(path, "w") as fh:
        fh.write("t,v,y\n")
        for a in range(0, n, chunk):
            k = np.arange(a, min(n, a + chunk))
            t = 0.001 * k
            v = 5.0 * np.sin(2 * np.pi * 0.7 * t)
            y = 4.0 * np.sin(2 * np.pi * 0.7 * t - 0.3) + 0.01 * np.cos(37.0 * t)
            block = np.column_stack([t, v, y])
            fh.write("\n".join(f"{r[0]:.3f},{r[1]:.6g},{r[2]:.6g}" for r in block.tolist()))
            fh.write("\n")


def run(name, path):
    env = dict(os.environ, PYTHONPATH=ROOT + os.pathsep + os.environ.get("PYTHONPATH", ""))
    proc = subprocess.run([sys.executable, "-c", RUNNER, path, *SNIPPETS[name]], capture_output=True,
                          text=True, env=env)
    if proc.returncode:
        raise SystemExit(f"{name} failed:\n{proc.stderr}")
    wall, cpu, hwm, maxrss, n = proc.stdout.split()
    hwm = float(hwm)
    return float(wall), float(cpu), (hwm if hwm == hwm else float(maxrss)), int(n)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rows", type=int, default=10_000_000)
    parser.add_argument("--baseline-rows", type=int, default=1_000_000)
    args = parser.parse_args(argv)
    folder = tempfile.mkdtemp(prefix="bench_csv_")
    try:
        big = os.path.join(folder, "big.csv")
        small = os.path.join(folder, "small.csv")
        t0 = time.perf_counter()
        write_csv(big, args.rows)
        write_csv(small, args.baseline_rows)
        tiny = os.path.join(folder, "tiny.csv")
        write_csv(tiny, 100)
        print(f"wrote {args.rows} rows ({os.path.getsize(big) / 1e6:.0f} MB) and {args.baseline_rows} rows "
              f"in {time.perf_counter() - t0:.1f} s")
        print(f"load average: {' '.join(f'{x:.2f}' for x in os.getloadavg())} on {os.cpu_count()} cores")
        scale = args.rows / args.baseline_rows
        floor = run("import pandas", small)
        print(f"{'loader':<18}{'rows':>11}{'wall [s]':>10}{'CPU [s]':>9}{'peak RSS [MB]':>15}"
              f"{'scaled to ' + str(args.rows) + ' rows':>29}")
        print(f"{'import pandas':<18}{'-':>11}{floor[0]:>10.2f}{floor[1]:>9.2f}{floor[2]:>15.0f}")
        wall, cpu, rss, n = run("load_csv", big)
        assert n == args.rows, n
        print(f"{'load_csv':<18}{n:>11}{wall:>10.2f}{cpu:>9.2f}{rss:>15.0f}")
        for name in ("csv.reader loop", "numpy.loadtxt"):
            w, c, r, n = run(name, small)
            base = run(name, tiny)[2]    # the same loader's floor (its imports, 100 rows)
            # time scales with the rows; memory above the loader's floor too
            print(f"{name:<18}{n:>11}{w:>10.2f}{c:>9.2f}{r:>15.0f}"
                  f"{w * scale:>10.1f} s wall {c * scale:>6.1f} s CPU {base + (r - base) * scale:>6.0f} MB")
        print(f"target: {args.rows} rows in <= 10 s and <= 2048 MB -> load_csv "
              f"{'meets it' if wall <= 10 and rss <= 2048 else 'MISSES it'} ({wall:.1f} s wall, {cpu:.1f} s CPU, "
              f"{rss:.0f} MB)")
        print(f"load average after: {' '.join(f'{x:.2f}' for x in os.getloadavg())}")
    finally:
        shutil.rmtree(folder, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())

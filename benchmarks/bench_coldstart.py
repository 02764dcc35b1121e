"""Cold-start cost of hystcomp: first calls in a fresh process, empty numba cache.

Each figure runs a fresh Python subprocess with ``NUMBA_CACHE_DIR`` set to a
new empty temporary directory, so every kernel the call needs is compiled
from scratch (what a new install, a CI run or a cluster worker pays).  The
same snippet is then run again in a new process on the now-filled cache
(the "warm" figure: imports plus loading the cached machine code) and a
third time inside one process after a first call (the "hot" figure: the
compiled kernel alone).  The plain reference is ``python -c "import numpy"``
measured in the same run: the floor of any subprocess.

Run::

    python benchmarks/bench_coldstart.py             # all figures, best of 2
    python benchmarks/bench_coldstart.py --repeats 3
    python benchmarks/bench_coldstart.py --only pi   # one figure

Targets (issue 13): ``hystcomp demo --no-figures`` <= 12 s wall, first
``PI.simulate`` <= 2 s, first ``exact_inverse().simulate`` <= 5 s, all with
an empty cache.  The exit status is 0 whatever the timings (a loaded machine
is not an error); the load average is printed with the figures.
"""

import argparse
import os
import shutil
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

SETUP = (
    "import numpy as np, time\n"
    "from hystcomp import PI, MGPI\n"
    "from hystcomp.envelopes import Tanh\n"
    "r = 0.5 * np.arange(1, 21); p = np.exp(-0.1 * r) * 0.5\n"
    "v = 10 * np.sin(np.linspace(0, 40, 100000))\n"
)

# (name, setup, timed statement, target seconds or None)
FIGURES = [
    ("pi", "first PI.simulate", "m = PI(r, p, p0=1.0)", "m.simulate(v)", 2.0),
    ("pi_inverse", "first PI exact_inverse().simulate",
     "m = PI(r, p, p0=1.0); u = m.simulate(v)", "m.exact_inverse().simulate(u)", 5.0),
    ("mgpi", "first tanh mGPI simulate",
     "m = MGPI(r, p, p0=1.0, envelope=Tanh(10, 0.2))", "m.simulate(v)", None),
    ("mgpi_inverse", "first tanh mGPI exact_inverse().simulate",
     "m = MGPI(r, p, p0=1.0, envelope=Tanh(10, 0.2)); u = m.simulate(v)",
     "m.exact_inverse().simulate(u)", None),
]

SNIPPET = SETUP + "{setup}\nt0 = time.perf_counter()\n{stmt}\nt1 = time.perf_counter()\n{stmt}\nt2 = time.perf_counter()\nprint(t1 - t0, t2 - t1)\n"


def _env(cache):
    env = dict(os.environ)
    env["NUMBA_CACHE_DIR"] = cache
    env["PYTHONPATH"] = ROOT + os.pathsep + env.get("PYTHONPATH", "")
    env.setdefault("MPLBACKEND", "Agg")
    return env


def _run(args, cache):
    t0 = time.perf_counter()
    before = os.times()
    out = subprocess.run(args, env=_env(cache), capture_output=True, text=True, cwd=ROOT)
    wall = time.perf_counter() - t0
    after = os.times()
    if out.returncode != 0:
        raise RuntimeError(f"{args} failed:\n{out.stderr[-2000:]}")
    # CPU time of the subprocess (user + system): less sensitive to the load
    # of a shared machine than the wall time
    _run.cpu = (after.children_user - before.children_user) + (after.children_system - before.children_system)
    return wall, out.stdout


def load():
    try:
        return "load average %.2f %.2f %.2f" % os.getloadavg()
    except OSError:
        return "load average unknown"


def measure_snippet(setup, stmt, repeats):
    cold_call, cold_wall, warm_call, hot = [], [], [], []
    for _ in range(repeats):
        cache = tempfile.mkdtemp(prefix="hystcomp-cold-")
        try:
            code = SNIPPET.format(setup=setup, stmt=stmt)
            wall, out = _run([sys.executable, "-c", code], cache)
            first, second = map(float, out.split())
            cold_call.append(first)
            cold_wall.append(wall)
            hot.append(second)
            _, out = _run([sys.executable, "-c", code], cache)
            warm_call.append(float(out.split()[0]))
        finally:
            shutil.rmtree(cache, ignore_errors=True)
    return min(cold_call), min(cold_wall), min(warm_call), min(hot)


def measure_demo(repeats):
    cold, warm, cold_cpu, warm_cpu = [], [], [], []
    for _ in range(repeats):
        cache = tempfile.mkdtemp(prefix="hystcomp-cold-")
        try:
            # the CSV goes to the temporary folder, not into the checkout
            args = [sys.executable, "-m", "hystcomp.cli", "demo", "--no-figures", "--out",
                    os.path.join(cache, "demo")]
            cold.append(_run(args, cache)[0])
            cold_cpu.append(_run.cpu)
            warm.append(_run(args, cache)[0])
            warm_cpu.append(_run.cpu)
        finally:
            shutil.rmtree(cache, ignore_errors=True)
    return min(cold), min(warm), min(cold_cpu), min(warm_cpu)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=2)
    parser.add_argument("--only", default=None,
                        help="one of: demo, " + ", ".join(f[0] for f in FIGURES))
    args = parser.parse_args(argv)
    import numba
    import numpy

    import hystcomp
    print(f"  hystcomp {hystcomp.__version__}, numba {numba.__version__}, numpy {numpy.__version__}, "
          f"Python {sys.version.split()[0]}, {os.cpu_count()} cores; best of {args.repeats}")
    print(f"  {load()} (before)")
    ref = min(_run([sys.executable, "-c", "import numpy"], tempfile.gettempdir())[0]
              for _ in range(3))
    ref_imp = min(_run([sys.executable, "-c", "import hystcomp"], tempfile.gettempdir())[0]
                  for _ in range(3))
    print()
    print(f"{'figure':44s} {'cold call':>10s} {'cold proc':>10s} {'warm call':>10s} {'hot call':>10s}  target")
    print("-" * 100)
    print("%-44s %10s %9.2fs" % ('reference: python -c "import numpy"', "", ref))
    print("%-44s %10s %9.2fs" % ('reference: python -c "import hystcomp"', "", ref_imp))
    results = []
    for key, name, setup, stmt, target in FIGURES:
        if args.only not in (None, key):
            continue
        cc, cw, wc, hot = measure_snippet(setup, stmt, args.repeats)
        print(f"{name:44s} {cc:9.2f}s {cw:9.2f}s {wc:9.3f}s {hot:9.4f}s  "
              + (f"<= {target} s (call)" if target else "(no target)"), flush=True)
        if target:
            results.append((f"{name} <= {target} s, empty cache", cc, target))
    if args.only in (None, "demo"):
        cold, warm, cold_cpu, warm_cpu = measure_demo(args.repeats)
        print(f"{'hystcomp demo --no-figures (whole process)':44s} {'':>10s} {cold:9.2f}s {warm:9.2f}s {'':>10s}  <= 12 s (cold process)")
        print(f"{'  same, CPU time (user + system)':44s} {'':>10s} {cold_cpu:9.2f}s {warm_cpu:9.2f}s")
        results.append(("hystcomp demo --no-figures <= 12 s, empty cache", cold, 12.0))
    print()
    print("  cold call: the first call in a fresh process with an empty NUMBA_CACHE_DIR (compilation included);")
    print("  cold proc: that whole subprocess, imports included; warm call: the first call in a new process")
    print("  once the cache is filled; hot call: the second call in the same process.")
    print(f"  {load()} (after)")
    print()
    print("targets")
    for label, value, target in results:
        print(f"  {'PASS' if value <= target else 'FAIL'}  {label:52s} (measured {value:.2f} s)")
    return 0


if __name__ == "__main__":
    sys.exit(main())

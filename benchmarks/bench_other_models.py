"""Speed of the Preisach, KP, Bouc-Wen and backlash-like models (issue 7).

Prints the wall time of ``simulate`` on 1,000,000 samples for:

* Preisach, 50 x 50 cells (1,275 relays), on a slowly varying sine (the
  usual case: a few relays switch per sample) and on uniform random input
  (the worst case: every sample jumps across many levels);
* KP on the same grid;
* Bouc-Wen with n = 1 (closed form), n = 2 and n = 1.5 (RK4 sub-steps);
* backlash-like (closed form);
* the numerical inverses of Preisach, KP and Bouc-Wen (100,000 samples),

next to two plain baselines measured in the same run: a NumPy relay update
of all 1,275 relays per sample (the textbook Preisach loop, timed on 2,000
samples and scaled) and the 20-operator PI model (a machine-speed yardstick),
then checks the issue's targets: Preisach 50 x 50 on 1,000,000 samples
< 2 s; Bouc-Wen on 1,000,000 samples < 1 s.

Run::

    python benchmarks/bench_other_models.py            # 1,000,000 samples
    python benchmarks/bench_other_models.py --quick    # 100,000 samples

The exit status is 0 whatever the timings (a noisy machine is not an error).
"""

import argparse
import platform
import time

import numba
import numpy as np

import hystcomp
from hystcomp import PI
from hystcomp.differential import BacklashLike, BoucWen
from hystcomp.preisach import KP, Preisach

TARGET_PREISACH = 2.0    # s for 1,000,000 samples, 50 x 50 cells
TARGET_BOUC_WEN = 1.0    # s for 1,000,000 samples


def best_time(fn, repeats):
    best = np.inf
    for _ in range(repeats):
        t0 = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - t0)
    return best


def inputs(n, seed=0):
    rng = np.random.default_rng(seed)
    t = np.arange(n) / 5000.0      # 5 kHz, 1 Hz main sine, like the piezo record
    amp = 0.6 + 0.4 * np.sin(2 * np.pi * t / 37.0)
    sine = amp * np.sin(2 * np.pi * t) + 0.005 * rng.standard_normal(n)
    return sine, rng.uniform(-1.0, 1.0, n)


def numpy_relays(model, v):
    """Textbook Preisach loop: update every relay at every sample."""
    ci, cj = np.tril_indices(model.n)
    a, b = model.levels[ci], model.levels[cj]
    mu = model.weights[ci, cj]
    R = model.relay_states(model.default_state())[ci, cj]
    out = np.empty(v.size)
    for k, x in enumerate(v):
        R[x >= a] = 1.0
        R[x < b] = -1.0
        out[k] = mu @ R
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--samples", type=int, default=1_000_000)
    ap.add_argument("--quick", action="store_true", help="100,000 samples")
    ap.add_argument("--repeats", type=int, default=3)
    args = ap.parse_args()
    n = 100_000 if args.quick else args.samples
    sine, rand = inputs(n)
    density = lambda a, b: np.exp(-2.0 * (a - b))  # noqa: E731
    pre = Preisach.from_density(density, (-1, 1), 50)
    kp = KP.from_density(density, (-1, 1), 50)
    bw = {nn: BoucWen(1.0, 0.6, 0.4, nn, gain=0.2) for nn in (1.0, 2.0, 1.5)}
    bl = BacklashLike(1.5, 3.0, 1.0)
    r = 0.05 * np.arange(1, 21)
    pi = PI(r, np.exp(-r) * 0.05, 1.0)

    # compile / load the kernels
    for m in [pre, kp, bl, pi, *bw.values()]:
        m.simulate(sine[:100])
    for m in (pre, kp, bw[2.0]):
        m.exact_inverse().simulate(0.1 * np.sin(np.linspace(0, 3, 50)))

    print(f"  hystcomp {hystcomp.__version__}, numpy {np.__version__}, numba {numba.__version__}, "
          f"Python {platform.python_version()}, {platform.machine()}")
    print(f"  {n:,} samples, best of {args.repeats}; sine: 5 kHz, 1 Hz, amplitude 0.2..1 + noise 0.005; "
          "random: uniform in [-1, 1]\n")
    rows = []

    def row(name, secs, note=""):
        rows.append((name, secs, note))
        print(f"{name:<44}{secs:>10.3f} s  {1e9 * secs / n:>8.1f} ns/sample  {note}")

    print(f"{'figure':<44}{'time':>12}  {'per sample':>18}")
    print("-" * 100)
    t_pre_sine = best_time(lambda: pre.simulate(sine), args.repeats)
    row("Preisach 50x50 (1,275 relays), sine", t_pre_sine)
    t_pre_rand = best_time(lambda: pre.simulate(rand), args.repeats)
    row("Preisach 50x50 (1,275 relays), random", t_pre_rand)
    m_base = 2000
    t_base = best_time(lambda: numpy_relays(pre, rand[:m_base]), 1) * n / m_base
    diff = np.abs(numpy_relays(pre, rand[:m_base]) - pre.simulate(rand[:m_base])).max()
    row("  baseline: NumPy update of all relays", t_base,
        f"timed on {m_base:,} samples and scaled; max |diff| to Preisach.simulate {diff:.1e}")
    row("KP 50x50, sine", best_time(lambda: kp.simulate(sine), args.repeats))
    t_bw = {}
    for nn, m in bw.items():
        t_bw[nn] = best_time(lambda m=m: m.simulate(3 * sine), args.repeats)
        row(f"Bouc-Wen n = {nn:g}, input 3 x sine", t_bw[nn],
            "closed form" if nn == 1.0 else "RK4 sub-steps")
    row("backlash-like, input 3 x sine", best_time(lambda: bl.simulate(3 * sine), args.repeats), "closed form")
    row("  yardstick: PI, 20 operators, sine", best_time(lambda: pi.simulate(sine), args.repeats))
    m_inv = min(n, 100_000)
    for name, m, u in (("Preisach", pre, pre.simulate(sine[:m_inv])), ("KP", kp, kp.simulate(sine[:m_inv])),
                       ("Bouc-Wen n = 2", bw[2.0], bw[2.0].simulate(3 * sine[:m_inv]))):
        comp = m.exact_inverse()
        secs = best_time(lambda: comp.simulate(u), 1) * n / m_inv
        err = np.abs(m.simulate(comp.simulate(u)) - u).max() / np.ptp(u)
        row(f"{name} numerical inverse", secs,
            f"timed on {m_inv:,} samples, scaled; max |model(comp(u)) - u| / span = {err:.1e}")

    scale = 1_000_000 / n
    print("\ntargets (scaled to 1,000,000 samples)")
    for label, val, target in (
        ("Preisach 50x50, 1e6 samples, sine   < 2 s", t_pre_sine * scale, TARGET_PREISACH),
        ("Preisach 50x50, 1e6 samples, random < 2 s", t_pre_rand * scale, TARGET_PREISACH),
        ("Bouc-Wen n = 1, 1e6 samples < 1 s", t_bw[1.0] * scale, TARGET_BOUC_WEN),
        ("Bouc-Wen n = 2, 1e6 samples < 1 s", t_bw[2.0] * scale, TARGET_BOUC_WEN),
        ("Bouc-Wen n = 1.5, 1e6 samples < 1 s", t_bw[1.5] * scale, TARGET_BOUC_WEN),
    ):
        print(f"  {'PASS' if val < target else 'FAIL'}  {label:<46} (measured {val:.3f} s)")


if __name__ == "__main__":
    main()

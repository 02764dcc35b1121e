"""Speed of hystcomp's python-control blocks and compiled loops.

1. Per-step cost of the hysteresis block inside python-control
   (``ct.input_output_response`` of :func:`hystcomp.iosys.hysteresis_system`
   of the demo's 20-operator tanh mGPI) against an equally sized linear
   ``nlsys`` block (20 states, update ``a*x + b*u``, output ``c @ x + d*u``
   in NumPy), measured in the same run.  Target: at most 1.5x.
2. :func:`hystcomp.loops.simulate_loop` against ``control.input_output_response``
   of the same loop (the demo's PID + exact compensator + mGPI + piezo
   stage), and the largest difference between the two.  Target: at least
   100x faster.
3. :func:`hystcomp.loops.fast_response` on a loop a user builds with
   ``control.interconnect`` (summing junction, a sampled PI controller as a
   transfer function, the exact compensator, and a nested interconnection of
   the mGPI actuator and the stage) against ``control.input_output_response``
   of the same system.  Targets: at least 100x faster, equal to 1e-12.

Run::

    python benchmarks/bench_loops.py            # 2,000 python-control steps
    python benchmarks/bench_loops.py --steps 500

The exit status is 0 whatever the timings (a noisy machine is not an error).
"""

import argparse
import platform
import time

import control as ct
import numpy as np

import hystcomp
from hystcomp.demo import demo_actuator, reference
from hystcomp.iosys import compensator_system, hysteresis_system, pid, piezo_stage
from hystcomp.iosys import initial_state
from hystcomp.loops import build_loop, fast_response, simulate_loop

TARGET_BLOCK_RATIO = 1.5
TARGET_SPEEDUP = 100.0
DT = 1e-4


def best(fn, repeats):
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return min(times)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--steps", type=int, default=2000, help="samples of the python-control runs")
    ap.add_argument("--repeats", type=int, default=3, help="runs per figure; the best is kept")
    args = ap.parse_args(argv)
    n = args.steps
    model = demo_actuator()
    t = np.arange(n) * DT
    v = 1.5 * np.sin(2 * np.pi * 20 * t)
    print(f"  hystcomp {hystcomp.__version__}, control {ct.__version__}, numpy {np.__version__}, "
          f"Python {platform.python_version()}, {platform.machine()}")
    print(f"  {model!r}; {n} python-control steps, best of {args.repeats}")

    # 1. one block inside python-control
    block = hysteresis_system(model, dt=DT)
    N = model.n_states
    a = np.full(N, 0.99)
    b = np.full(N, 0.01)
    c = np.full(N, 0.05)

    def upd(t_, x, u, params):
        return a * x + b * u[0]

    def out(t_, x, u, params):
        return np.array([c @ x + 0.5 * u[0]])

    linear = ct.nlsys(upd, out, states=N, inputs="v", outputs="w", dt=DT, name="linear")
    for sys in (block, linear):  # warm up (compilation)
        ct.input_output_response(sys, t[:10], v[:10])
    t_block = best(lambda: ct.input_output_response(block, t, v), args.repeats) / n
    t_lin = best(lambda: ct.input_output_response(linear, t, v), args.repeats) / n
    y = np.asarray(ct.input_output_response(block, t, v).outputs)
    diff_block = float(np.max(np.abs(y - model.simulate(v))))

    # 2. the loop
    comp = compensator_system(model, nominal_gain="auto", input_range=(-2.0, 2.0))
    loop = build_loop("feedback_compensated", model, piezo_stage(), controller=pid(0.0, 40.0, 0.0, DT),
                      compensator=comp, dt=DT)
    r = reference(t, 5.0)
    simulate_loop(loop, t[:10], r[:10])  # compile
    t_ct = best(lambda: loop.simulate(t, r), args.repeats) / n
    n_fast = 1_000_000
    tf = np.arange(n_fast) * DT
    rf = reference(tf, 5.0)
    t_fast = best(lambda: simulate_loop(loop, tf, rf), args.repeats) / n_fast
    d = np.max(np.abs(np.asarray(loop.simulate(t, r).outputs) - np.asarray(simulate_loop(loop, t, r).outputs)))

    # 3. a loop the user builds, nested, through fast_response
    h = hysteresis_system(model, dt=DT, name="act", inputs="v", outputs="w")
    cu = compensator_system(model, nominal_gain="auto", input_range=(-2.0, 2.0), dt=DT, name="comp",
                            inputs="u", outputs="v")
    ctrl = ct.ss(ct.sample_system(ct.tf([0.05, 40.0], [1, 0]), DT), inputs="e", outputs="u", name="ctrl")
    err = ct.summing_junction(["r", "-y"], "e", name="err")
    inner = ct.interconnect([h, piezo_stage(dt=DT, inputs="w", outputs="y")], inplist="v", outlist="y",
                            name="plant", inputs="v", outputs="y")
    user = ct.interconnect([err, ctrl, cu, inner], inplist="r", outlist="y", name="user")
    x0 = initial_state(user)
    fast_response(user, t[:10], r[:10], x0)  # compile
    t_user_ct = best(lambda: ct.input_output_response(user, t, r, x0), args.repeats) / n
    t_user_fast = best(lambda: fast_response(user, tf, rf, x0), args.repeats) / n_fast
    d_user = float(np.max(np.abs(np.asarray(fast_response(user, t, r, x0).outputs)
                                 - np.asarray(ct.input_output_response(user, t, r, x0).outputs))))

    print()
    print(f"{'figure':58s} {'us/step':>10s}")
    print("-" * 70)
    print(f"{'hysteresis block (20-operator tanh mGPI) in python-control':58s} {t_block * 1e6:10.2f}")
    print(f"{'linear nlsys block, 20 states (NumPy), baseline':58s} {t_lin * 1e6:10.2f}")
    print(f"{'loop PID + exact compensator + mGPI + stage, python-control':58s} {t_ct * 1e6:10.2f}")
    print(f"{'same loop, simulate_loop (compiled), 1,000,000 steps':58s} {t_fast * 1e6:10.3f}")
    print(f"{'user-built nested loop, input_output_response':58s} {t_user_ct * 1e6:10.2f}")
    print(f"{'same loop, fast_response (compiled), 1,000,000 steps':58s} {t_user_fast * 1e6:10.3f}")
    print()
    print(f"  max |block - model.simulate| = {diff_block:.1e};  max |simulate_loop - python-control| = {d:.1e}; "
          f"max |fast_response - python-control| = {d_user:.1e}")
    ratio = t_block / t_lin
    speedup = t_ct / t_fast
    print()
    print("targets")
    print(f"  {'PASS' if ratio <= TARGET_BLOCK_RATIO else 'FAIL'}  hysteresis block <= {TARGET_BLOCK_RATIO}x "
          f"linear nlsys block        (measured {ratio:.2f}x)")
    print(f"  {'PASS' if speedup >= TARGET_SPEEDUP else 'FAIL'}  simulate_loop >= {TARGET_SPEEDUP:.0f}x "
          f"python-control              (measured {speedup:.0f}x)")
    print(f"  {'PASS' if d <= 1e-9 else 'FAIL'}  simulate_loop == python-control to 1e-9      (measured {d:.1e})")
    speed_user = t_user_ct / t_user_fast
    print(f"  {'PASS' if speed_user >= TARGET_SPEEDUP else 'FAIL'}  fast_response >= {TARGET_SPEEDUP:.0f}x "
          f"input_output_response       (measured {speed_user:.0f}x)")
    print(f"  {'PASS' if d_user <= 1e-12 else 'FAIL'}  fast_response == python-control to 1e-12     "
          f"(measured {d_user:.1e})")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

"""Closed-loop study: the thesis's mGPI actuator on a piezo stage, five scenarios.

Writes closed_loop.png (tracking, error, y-vs-r loops) into --out and prints
the comparison table.  Run: python examples/closed_loop.py --out DIR
"""

import argparse
import os

import matplotlib

matplotlib.use("Agg")
import numpy as np  # noqa: E402

from hystcomp.demo import demo_actuator, reference  # noqa: E402
from hystcomp.iosys import compensator_system, pid, piezo_stage  # noqa: E402
from hystcomp.loops import build_scenarios, compare, plot_comparison  # noqa: E402


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--out", default=".", help="folder for closed_loop.png")
    args = ap.parse_args(argv)
    dt = 1e-4
    t = np.arange(0, 2.0, dt)
    actuator = demo_actuator()
    comp = compensator_system(actuator, method="exact", nominal_gain="auto", input_range=(-2.0, 2.0))
    loops = build_scenarios(actuator, piezo_stage(), controller=pid(0.0, 40.0, 0.0, dt), compensator=comp, dt=dt)
    result = compare(loops, reference(t, 5.0), t)
    print(result)
    os.makedirs(args.out, exist_ok=True)
    fig = plot_comparison(result, title="5 Hz reference, exact compensator with nominal gain "
                                        f"{comp.nominal_gain:.3f}, integral control ki = 40")
    fig.savefig(os.path.join(args.out, "closed_loop.png"), dpi=80)


if __name__ == "__main__":
    main()

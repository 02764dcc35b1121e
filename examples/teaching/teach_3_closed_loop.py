"""Teaching 3: a closed loop with and without compensation
=======================================================

The actuator of thesis chapter 5 (an mGPI model with a saturating envelope
``gamma(v) = 30 tanh(0.05 v)``: command ``v`` in V, stroke ``w`` in um) drives a piezo stage
(a 300 Hz resonance, position ``y`` in um).  A PID controller tuned to a 60 deg phase
margin fights the hysteresis as a disturbance; an inverse compensator in front of the
actuator removes it before the controller sees it.  Four loops on a 5 Hz reference:

- open loop: the command is the reference divided by the actuator's mean slope
  (a linear calibration, blind to hysteresis);
- PID: feedback on the raw actuator;
- PID + compensator: feedback through the exact inverse of the actuator model;
- feedforward + PID + compensator: the reference also goes straight through the
  compensator, so the controller only corrects what is left.

The loops are python-control systems (``control.interconnect``), run compiled.
"""

# %%
# The actuator, the stage and the controller
# ------------------------------------------
import matplotlib.pyplot as plt
import numpy as np

from hystcomp.demo import demo_actuator, reference
from hystcomp.design import design_pid
from hystcomp.iosys import compensator_system, piezo_stage
from hystcomp.loops import build_loop, compare

CROSSOVER_HZ = 80.0  # gain crossover of the PID [Hz]  (exercise 1)
REFERENCE_HZ = 5.0  # frequency of the reference [Hz]  (exercise 2)
METHOD = "exact"  # or "analytic": the compensator   (exercise 3)

dt = 1e-4  # sampling time [s]
t = np.arange(0.0, 1.0, dt)
actuator = demo_actuator()
stage = piezo_stage()  # 300 Hz, 5 % damping, unit static gain [um/um]
compensator = compensator_system(actuator, method=METHOD, nominal_gain="auto",
                                 input_range=(-2.0, 2.0))
k_nom = compensator.nominal_gain  # the actuator's mean slope over +-2 V [um/V]
controller = design_pid(stage, CROSSOVER_HZ, 60.0, actuator_gain=k_nom, dt=dt,
                        filter="lowpass", filter_hz=2 * CROSSOVER_HZ)
print(f"actuator {actuator!r}, mean slope k_nom = {k_nom:.3f} um/V")

# %%
# Four loops, one reference
# -------------------------
# ``compare`` runs every loop on the reference ``5 sin(2 pi f t) / (1 + 0.1 t)`` um and
# reports the tracking error in % of the reference's span.  Feedback alone lags the
# reference, with or without the compensator; the compensator pays most when it lets a
# feedforward path do the work, because the compensated actuator is linear.
parts = dict(controller=controller, dt=dt)
loops = [
    build_loop("open_loop", actuator, stage, dt=dt, feedforward_gain=1 / k_nom),
    build_loop("feedback", actuator, stage, **parts),
    build_loop("feedback_compensated", actuator, stage,
               compensator=compensator, **parts),
    build_loop("two_dof", actuator, stage, compensator=compensator, **parts),
]
r = reference(t, REFERENCE_HZ)
result = compare(loops, t, r)
print(result)

# %%
# Tracking and error
# ------------------
# The first two periods in time (left); the error against the reference over the last
# period (right), where each loop draws its own hysteresis-shaped error loop.
labels = {"open_loop": "open loop (1/k_nom)", "feedback": "PID",
          "feedback_compensated": "PID + compensator",
          "two_dof": "feedforward + PID + compensator"}
period = t >= t[-1] - 1.0 / REFERENCE_HZ
first = t <= 2.0 / REFERENCE_HZ
fig, (ax_y, ax_e) = plt.subplots(1, 2, figsize=(11, 4.6),
                                 layout="constrained")
ax_y.plot(t[first], r[first], "k--", lw=1.2, label="reference r")
for row in result.rows:
    y = np.asarray(result.responses[row["scenario"]].outputs)[0]
    lab = f"{labels[row['scenario']]}: {row['rms_percent']:.2g} % RMS"
    ax_y.plot(t[first], y[first], lw=1, label=lab)
    ax_e.plot(r[period], (y - r)[period], lw=1, label=lab)
ax_y.set(xlabel="time t [s]", ylabel="stage position y [um]",
         title=f"{REFERENCE_HZ:g} Hz reference")
ax_e.set(xlabel="reference r [um]", ylabel="error y - r [um]",
         title="error over the last period")
ax_e.set_yscale("symlog", linthresh=1e-3)
fig.legend(*ax_y.get_legend_handles_labels(), loc="outside lower center",
           ncols=3, fontsize=8)
for ax in (ax_y, ax_e):
    ax.grid(True, alpha=0.3)

# %%
# Exercises
# ---------
# Change one parameter at a time and re-run.
#
# 1. Set ``CROSSOVER_HZ = 30.0``.  Which loop suffers most, and why does a slower
#    controller leave more of the hysteresis in the error?  (``hystcomp demo`` asks the
#    circle criterion how fast each loop may be made safely.)
# 2. Set ``REFERENCE_HZ = 1.0`` and then ``20.0``.  How does the PID loop's error scale
#    with the reference frequency, and the feedforward loop's?
# 3. Set ``METHOD = "analytic"`` (the thesis's eqs. 54-58 instead of the exact inverse).
#    How much of the feedforward loop's advantage remains?

# %%
# Keeping the figures
# -------------------
# Run as a script, ``python teach_3_closed_loop.py --out DIR`` writes every figure as a
# PNG into ``DIR`` (in a notebook, or without ``--out``, nothing is written).
import argparse  # noqa: E402
import os  # noqa: E402

parser = argparse.ArgumentParser(description="Teaching 3")
parser.add_argument("--out", help="folder for the PNG figures")
args, _ = parser.parse_known_args()  # notebooks pass arguments of theirs
if args.out:
    os.makedirs(args.out, exist_ok=True)
    for num in plt.get_fignums():
        path = os.path.join(args.out, f"teach_3_closed_loop_{num}.png")
        plt.figure(num).savefig(path, dpi=100)
        print("wrote", path)

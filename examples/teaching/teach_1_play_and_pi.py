"""Teaching 1: the play operator and the Prandtl-Ishlinskii model
==============================================================

A play operator is a piston in a cylinder of length ``2r``: the output ``w`` (the cylinder)
stays put while the input ``v`` (the piston) moves inside, and is dragged along once the
piston touches a wall (thesis eqs. 12-13):

.. math::

   w(t_{i+1}) = \\max\\{v(t_{i+1}) - r, \\min\\{v(t_{i+1}) + r, w(t_i)\\}\\}.

The Prandtl-Ishlinskii (PI) model adds up many plays with weights ``p_i`` and a linear
term (eq. 18, discrete): :math:`w = p_0 v + \\sum_i p_i F_{r_i}[v]`.  Run the cells in
order, then do the exercises at the end.  The actuator here is generic: input ``v`` in
volts, output ``w`` in micrometres, weights in um/V.
"""

# %%
# One play operator
# -----------------
# A decaying sine drives one play with threshold ``R_ONE`` V.  The output stays constant
# while the input reverses (the flat parts), then follows it at a distance ``r``.
import matplotlib.pyplot as plt
import numpy as np

from hystcomp import PI, play

R_ONE = 1.0  # threshold of the single play [V]  (exercise 1)

t = np.linspace(0.0, 4.0, 801)  # time [s]
v = 4.0 * np.sin(2 * np.pi * t) / (1.0 + 0.5 * t)  # input [V]
w, _ = play(v, [R_ONE])  # one column per threshold

fig, (ax_t, ax_vw) = plt.subplots(1, 2, figsize=(10, 3.8),
                                  layout="constrained")
ax_t.plot(t, v, label="input v")
ax_t.plot(t, w[:, 0], label=f"play output F_r[v], r = {R_ONE:g} V")
ax_t.set(xlabel="time t [s]", ylabel="v, F_r[v] [V]", title="in time")
ax_t.legend(loc="upper right", fontsize=8)
ax_vw.plot(v, w[:, 0])
walls = np.array([-4.0, 4.0])
ax_vw.plot(walls, walls - R_ONE, "k:", lw=0.8, label="walls v - r, v + r")
ax_vw.plot(walls, walls + R_ONE, "k:", lw=0.8)
ax_vw.set(xlabel="input v [V]", ylabel="output F_r[v] [V]",
          title="output against input")
ax_vw.legend(loc="upper left", fontsize=8)
for ax in (ax_t, ax_vw):
    ax.grid(True, alpha=0.3)

# %%
# Several thresholds
# ------------------
# Plays with larger thresholds wait longer before they move.  A play with ``r = 0`` is the
# input itself.
thresholds = np.array([0.0, 0.5, 1.0, 1.5, 2.0])  # [V]
W, _ = play(v, thresholds)
fig, ax = plt.subplots(figsize=(6, 4.2), layout="constrained")
for j, r in enumerate(thresholds):
    ax.plot(v, W[:, j], lw=1, label=f"r = {r:g} V")
ax.set(xlabel="input v [V]", ylabel="play output F_r[v] [V]",
       title="plays with five thresholds")
ax.legend(loc="upper left", fontsize=8)
ax.grid(True, alpha=0.3)

# %%
# The PI model
# ------------
# Weights from the thesis's density ``p(r) = exp(-DECAY r)`` (eq. 18 discretised as
# ``p_i = p(r_i) (r_i - r_{i-1})``), ``p0`` the linear part.  The loop is the weighted sum of
# the plays above; its *loading curve* (the output when ``v`` rises from 0 from the virgin
# state) is eq. 30, :math:`\phi(r) = p_0 r + \sum_i p_i (r - r_i)^+`.
P0 = 1.0  # linear weight [um/V]        (exercise 2)
DECAY = 0.5  # density decay rate [1/V]  (exercise 3)
r_i = np.linspace(0.25, 4.0, 16)  # thresholds [V]
widths = np.diff(np.concatenate([[0.0], r_i]))
p_i = np.exp(-DECAY * r_i) * widths  # weights [um/V]
model = PI(r_i, p_i, p0=P0)
y = model.simulate(v)

r = np.linspace(0.0, 4.0, 81)
phi = P0 * r + np.maximum(r[:, None] - r_i, 0.0) @ p_i  # eq. 30, discrete
print(f"PI model: {model!r}")
print(f"output range [{y.min():.3f}, {y.max():.3f}] um")
print(f"total weight p0 + sum p_i = {P0 + p_i.sum():.3f} um/V")
print(f"loading curve at 4 V: model.loading_curve "
      f"{model.loading_curve(4.0):.4f} um, eq. 30 {phi[-1]:.4f} um")

fig, (ax_l, ax_c) = plt.subplots(1, 2, figsize=(10, 3.8),
                                 layout="constrained")
ax_l.plot(v, y)
ax_l.set(xlabel="input v [V]", ylabel="output w [um]",
         title="PI model: nested loops")
ax_c.plot(r, phi, label="eq. 30")
ax_c.plot(r[::8], model.loading_curve(r[::8]), "o",
          label="model.loading_curve")
ax_c.set(xlabel="input r [V]", ylabel="loading curve phi(r) [um]",
         title="initial loading curve")
ax_c.legend(loc="upper left", fontsize=8)
for ax in (ax_l, ax_c):
    ax.grid(True, alpha=0.3)

# %%
# Memory: the model remembers reversal points
# --------------------------------------------
# Two inputs that end at the same value, 1 V, give different outputs: the output depends on
# the history, not only on the present input.  A larger excursion wipes out the memory of
# smaller ones (the *wiping-out* property).
# up to 3 V and back to 1 V; down to -3 V and up to 1 V
v_a = np.concatenate([np.linspace(0, 3, 100), np.linspace(3, 1, 100)])
v_b = np.concatenate([np.linspace(0, -3, 100), np.linspace(-3, 1, 100)])
print(f"at v = 1 V: after +3 V w = {model.simulate(v_a)[-1]:.3f} um, "
      f"after -3 V w = {model.simulate(v_b)[-1]:.3f} um")

# %%
# Exercises
# ---------
# Change one parameter at a time, re-run the cells, and compare with the figures above.
#
# 1. Set ``R_ONE = 3.0``.  How long does the output stay flat after each reversal, and what
#    happens once the input amplitude falls below ``r``?
# 2. Set ``P0 = 0.0``.  Where does the loop become flat, and why does the thesis require
#    ``p0 > 0`` for the inverse (hint: the slope of the loading curve at 0 is ``p0``)?
# 3. Set ``DECAY = 0.0`` (uniform density, every play the same weight).  How do the
#    loading curve and the loop's width change?  Compare with eq. 30: what is
#    :math:`\phi''(r)`?

# %%
# Keeping the figures
# -------------------
# Run as a script, ``python teach_1_play_and_pi.py --out DIR`` writes every figure as a
# PNG into ``DIR`` (in a notebook, or without ``--out``, nothing is written).
import argparse  # noqa: E402
import os  # noqa: E402

parser = argparse.ArgumentParser(description="Teaching 1")
parser.add_argument("--out", help="folder for the PNG figures")
args, _ = parser.parse_known_args()  # notebooks pass arguments of theirs
if args.out:
    os.makedirs(args.out, exist_ok=True)
    for num in plt.get_fignums():
        path = os.path.join(args.out, f"teach_1_play_and_pi_{num}.png")
        plt.figure(num).savefig(path, dpi=100)
        print("wrote", path)

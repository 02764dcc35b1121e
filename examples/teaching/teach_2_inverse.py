"""Teaching 2: the inverse and why it cancels
==========================================

A compensator placed in front of the actuator feeds it ``v = C[u]`` so that the actuator's
output ``w = H[C[u]]`` equals the demand ``u``.  For the Prandtl-Ishlinskii model the
inverse is again a PI model (Krejci-Kuhnen): its loading curve ``psi`` undoes the model's
loading curve ``phi`` (thesis eq. 41), :math:`\\psi(\\phi(r)) = r`, so the inverse's
thresholds are the model's loading curve at its thresholds, :math:`q_j = \\phi(r_j)`, and
its weights follow from the slopes, :math:`\\psi'(q) = 1 / \\phi'(r)` (eq. 53).  For the
mGPI model with a curved envelope the thesis's recipe (eqs. 54-58) matches the slopes only
at the thresholds; hystcomp's exact inverse solves ``H[v] = u`` sample by sample instead.
Units: demand ``u`` and output ``w`` in um, actuator input ``v`` in V.
"""

# %%
# A PI model and its inverse
# --------------------------
import matplotlib.pyplot as plt
import numpy as np

from hystcomp import MGPI, PI, Tanh, tracking_error

N_OPERATORS = 8  # number of plays             (exercise 1)
P0 = 1.0  # linear weight of the model [um/V]  (exercise 2)
r_i = np.linspace(0.5, 4.0, N_OPERATORS)  # thresholds [V]
widths = np.diff(np.concatenate([[0.0], r_i]))
p_i = np.exp(-0.3 * r_i) * widths  # weights [um/V]
model = PI(r_i, p_i, p0=P0)
inverse = model.inverse()

# the model's loading curve at its thresholds (eq. 30)
phi_r = model.loading_curve(r_i)
# slopes of phi between thresholds: p0 + p_1 + ... + p_j
partial = P0 + np.cumsum(p_i)
# g_j = 1/(p0 + ... + p_j) - 1/(p0 + ... + p_{j-1})
g = np.diff(np.concatenate([[1.0 / P0], 1.0 / partial]))
print(f"model: p0 = {P0:g} um/V, r_j = {np.round(r_i, 3).tolist()} V")
print(f"inverse: p0' = {inverse.p0:.4f} V/um (1/p0 = {1 / P0:.4f})")
print(f"  thresholds q_j  = {np.round(inverse.thresholds, 4).tolist()} um")
print(f"  phi(r_j)        = {np.round(phi_r, 4).tolist()} um")
print(f"  weights g_j     = {np.round(inverse.weights, 4).tolist()} V/um")
print(f"  from the slopes = {np.round(g, 4).tolist()} V/um")

# %%
# Loading curves mirror each other
# --------------------------------
# ``phi`` (the model's) and ``psi`` (the inverse's) are mirror images about the diagonal:
# one is the other with the axes swapped.  Both are piecewise linear, with kinks at
# ``r_j`` and ``q_j = phi(r_j)``, which is why the PI inverse is exact.
r = np.linspace(0.0, 4.0, 201)
phi = model.loading_curve(r)
q = np.linspace(0.0, float(phi[-1]), 201)
psi = inverse.loading_curve(q)
fig, ax = plt.subplots(figsize=(5.2, 5.0), layout="constrained")
ax.plot(r, phi, label="model: phi(r), r in V, phi in um")
ax.plot(q, psi, label="inverse: psi(q), q in um, psi in V")
ax.plot([0, phi[-1]], [0, phi[-1]], "k:", lw=0.8, label="diagonal")
ax.set(xlabel="input of the curve [V or um]",
       ylabel="output of the curve [um or V]",
       title="loading curves: psi(phi(r)) = r", aspect="equal")
ax.legend(loc="upper left", fontsize=8)
ax.grid(True, alpha=0.3)
gap = np.abs(inverse.loading_curve(phi) - r).max()
print(f"max |psi(phi(r)) - r| = {gap:.2e} V")

# %%
# The cascade: compensator, then actuator
# ---------------------------------------
# The compensator's loop turns the other way (clockwise); in cascade with the actuator the
# two loops cancel and the output follows the demand on a straight line.
t = np.linspace(0.0, 4.0, 2001)  # time [s]
u = 5.0 * np.sin(2 * np.pi * t) / (1.0 + 0.3 * t)  # demand [um]
v = inverse.simulate(u)  # actuator input [V]
w = model.simulate(v)  # actuator output [um]
err = tracking_error(model, inverse, u)
print(f"PI cascade: RMS error {err['rms']:.2e} um "
      f"({err['rms_percent']:.2e} % of the span)")
fig, (ax_c, ax_a, ax_w) = plt.subplots(1, 3, figsize=(12, 3.8),
                                       layout="constrained")
ax_c.plot(u, v)
ax_c.set(xlabel="demand u [um]", ylabel="actuator input v [V]",
         title="compensator C")
ax_a.plot(v, w)
ax_a.set(xlabel="actuator input v [V]", ylabel="output w [um]",
         title="actuator H")
ax_w.plot(u, w)
ax_w.set(xlabel="demand u [um]", ylabel="output w [um]",
         title=f"H[C[u]]: RMS error {err['rms']:.1e} um")
for ax in (ax_c, ax_a, ax_w):
    ax.grid(True, alpha=0.3)

# %%
# A curved envelope: the thesis's recipe against the exact inverse
# ----------------------------------------------------------------
# The mGPI model applies an envelope ``gamma`` to each play (eq. 25).  With a saturating
# ``gamma(v) = A tanh(v / A)`` (slope 1 at 0, like the PI above, and levels at ``+-A``) the
# thesis's analytic inverse (eqs. 54-58) matches the slopes of the loading curves only at
# the thresholds, so it leaves an error; the exact inverse does not.
LEVEL = 12.0  # A: where each play's envelope saturates [V]  (exercise 3)
envelope = Tanh(LEVEL, 1.0 / LEVEL)
mgpi = MGPI(r_i, p_i, p0=P0, envelope=envelope)
u_m = 0.8 * u  # stay inside the reachable outputs
fig, ax = plt.subplots(figsize=(7, 3.8), layout="constrained")
compensators = {"analytic (eqs. 54-58)": mgpi.inverse(),
                "exact": mgpi.exact_inverse()}
for name, comp in compensators.items():
    e = tracking_error(mgpi, comp, u_m)
    print(f"mGPI, {name:22s}: RMS {e['rms_percent']:.3g} %, "
          f"max {e['max_percent']:.3g} % of the span")
    ax.plot(t, mgpi.simulate(comp.simulate(u_m)) - u_m, lw=1,
            label=f"{name}: {e['rms_percent']:.2g} % RMS of the span")
ax.set(xlabel="time t [s]", ylabel="error H[C[u]] - u [um]",
       title=f"mGPI with {envelope!r}")
ax.legend(loc="lower right", fontsize=8)
ax.grid(True, alpha=0.3)

# %%
# Exercises
# ---------
# Change one parameter at a time and re-run.
#
# 1. Set ``N_OPERATORS = 2``.  Is the PI inverse still exact?  Count the kinks of ``phi``
#    and ``psi``.
# 2. Set ``P0 = 0.2``.  What happens to ``p0' = 1/p0`` and to the size of the actuator input
#    ``v`` the compensator asks for?  Why does a small ``p0`` make a compensator sensitive
#    to noise?
# 3. Set ``LEVEL = 100.0`` (a nearly linear envelope) and then ``9.0`` (a strongly
#    saturating one).  How does the analytic inverse's error change, and why does the exact
#    inverse not care?

# %%
# Keeping the figures
# -------------------
# Run as a script, ``python teach_2_inverse.py --out DIR`` writes every figure as a
# PNG into ``DIR`` (in a notebook, or without ``--out``, nothing is written).
import argparse  # noqa: E402
import os  # noqa: E402

parser = argparse.ArgumentParser(description="Teaching 2")
parser.add_argument("--out", help="folder for the PNG figures")
args, _ = parser.parse_known_args()  # notebooks pass arguments of theirs
if args.out:
    os.makedirs(args.out, exist_ok=True)
    for num in plt.get_fignums():
        path = os.path.join(args.out, f"teach_2_inverse_{num}.png")
        plt.figure(num).savefig(path, dpi=100)
        print("wrote", path)

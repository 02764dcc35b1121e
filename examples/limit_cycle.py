"""Predicting a limit cycle with the describing function
=====================================================

The thesis's mGPI actuator (saturating tanh envelope) drives the 300 Hz piezo
stage under pure integral control with too much gain (ki = 150 and 100 /s).
The describing function of the actuator (exact for this symmetric mGPI: one
quadrature per operator of the play's closed-form cycle) against the loop's
Nyquist curve predicts where the loop oscillates: ``L(j w) N(A) = -1``.
``hystcomp.analysis.limit_cycles`` finds the intersections on the sampled
loop; python-control's ``describing_function_response`` finds the same ones on
the continuous loop with ``hystcomp.analysis.DescribingFunction``.  The
compiled loop then confirms amplitude and frequency.

At ki = 100 there are two intersections: the small cycle is unstable (a small
kick dies out), the large one stable (a kick that drives the loop well beyond
the small amplitude ends on it).  The linear margins at the actuator's small-signal slope (1.5) call
this loop stable; the describing function shows that it is stable only for
small disturbances.

Run:  python examples/limit_cycle.py [--out DIR]
"""

import argparse
import tempfile
import os

import matplotlib

matplotlib.use("Agg")

import control as ct  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.figure import Figure  # noqa: E402

from hystcomp.analysis import DescribingFunction, describing_function, limit_cycles  # noqa: E402
from hystcomp.demo import demo_actuator  # noqa: E402
from hystcomp.iosys import discretize, pid, piezo_stage  # noqa: E402
from hystcomp.loops import build_loop, simulate_loop  # noqa: E402

DT = 1e-4


def oscillation(v, t, t_from):
    """Half the peak-to-peak value and the frequency (mean-crossings) of v after t_from."""
    last = v[t >= t_from]
    mid = 0.5 * (last.max() + last.min())
    up = np.nonzero((last[:-1] < mid) & (last[1:] >= mid))[0]
    if up.size < 2 or np.ptp(last) < 1e-9:
        return 0.0, float("nan")
    return 0.5 * np.ptp(last), (up.size - 1) / ((up[-1] - up[0]) * DT)


def main(argv=None):
    parser = argparse.ArgumentParser(description=(__doc__ or "").partition("\n")[0])
    parser.add_argument("--out", default=None,
                        help="folder for the figures (default: a new temporary folder)")
    args = parser.parse_args(argv)
    if args.out is None:
        args.out = tempfile.mkdtemp(prefix="hystcomp-limit_cycle-")
    os.makedirs(args.out, exist_ok=True)
    model = demo_actuator()
    stage = piezo_stage()
    amps = np.geomspace(0.01, 300, 300)
    N = describing_function(model, amps)
    t = np.arange(0, 3.0, DT)
    fig = Figure(figsize=(14, 4.6), layout="constrained")
    ax_n, ax_t, ax_z = fig.subplots(1, 3)
    ax_n.plot((-1 / N).real, (-1 / N).imag, "k-", lw=2, label="-1/N(A) of the actuator")
    for a in (0.1, 1, 10, 100):
        z = -1 / describing_function(model, [a])[0]
        ax_n.plot(z.real, z.imag, "k.", ms=6)
        ax_n.annotate(f"A = {a:g} V", (z.real, z.imag), textcoords="offset points", xytext=(4, -12), fontsize=7)
    print(f"{'ki [1/s]':>8s} {'kick':30s} {'predicted A [V]':>16s} {'f [Hz]':>8s} {'python-control A':>17s} "
          f"{'simulated A [V]':>16s} {'f [Hz]':>8s}")
    win = int(round(0.005 / DT))
    runs = ((150.0, "C3", "0.5 um step for 10 ms", lambda f: np.where(t < 0.01, 0.5, 0.0)),
            (100.0, "C2", "5 um burst at f for 30 ms", lambda f: np.where(t < 0.03, 5.0, 0.0) * np.sin(2 * np.pi * f * t)),
            (100.0, "C0", "10 um burst at f for 30 ms", lambda f: np.where(t < 0.03, 10.0, 0.0) * np.sin(2 * np.pi * f * t)))
    drawn = set()
    for ki, color, kick_text, kick in runs:
        controller = pid(0.0, ki, 0.0, DT)
        L = ct.series(discretize(stage, DT), controller)
        cycles = sorted(limit_cycles(L, model, amps))
        Lc = ct.tf([ki], [1, 0]) * ct.tf(stage)
        resp = ct.describing_function_response(Lc, DescribingFunction(model), amps, warn_nyquist=False)
        pc = sorted(a for a, _ in resp.intersections)
        large = cycles[-1]
        if ki not in drawn:
            drawn.add(ki)
            w = 2 * np.pi * np.linspace(200, 400, 4000)
            Lw = L(np.exp(1j * w * DT))
            ax_n.plot(Lw.real, Lw.imag, color=color, lw=1, label=f"L(exp(j w dt)), ki = {ki:g} /s, 200-400 Hz")
            for a, f in cycles:
                ax_t.axhline(a, color=color, ls="--", lw=1)
        loop = build_loop("feedback", model, stage, controller=controller, dt=DT)
        v = simulate_loop(loop, t, kick(large[1])).outputs[2]
        amp, freq = oscillation(v, t, 2.5)
        for (a, f), ac in zip(cycles, pc):
            if (a, f) != large:
                sim = f"{'(unstable cycle)':>16s}"
            else:
                sim = f"{amp:16.4g} {freq:8.2f}" if amp > 0 else f"{'(kick decays)':>16s}"
            print(f"{ki:8g} {kick_text:30s} {a:16.4g} {f:8.2f} {ac:17.4g} {sim}")
        n = t.size // win
        env = np.abs(v[: n * win]).reshape(n, win).max(axis=1)
        ax_t.semilogy(t[: n * win: win], np.maximum(env, 1e-6), color=color, lw=1.2,
                      label=f"ki = {ki:g} /s, {kick_text}")
        if amp > 0:
            last = t >= 2.99
            phase = np.angle(np.sum(v[last] * np.exp(-2j * np.pi * large[1] * t[last]))) + np.pi / 2
            ax_z.plot(t[last] * 1e3, v[last], color=color, lw=1.2, label=f"ki = {ki:g} /s, simulated")
            ax_z.plot(t[last] * 1e3, large[0] * np.sin(2 * np.pi * large[1] * t[last] + phase), color="k", ls=":",
                      lw=1.2, label=f"ki = {ki:g} /s, describing function ({large[0]:.1f} V, {large[1]:.1f} Hz)")
    ax_n.set(xlim=(-0.75, 0.1), ylim=(-0.5, 0.2), title="Nyquist curve against -1/N(A)",
             xlabel="Re [-] (loop gain, dimensionless)", ylabel="Im [-]")
    ax_n.grid(True, alpha=0.3)
    ax_n.legend(fontsize=7, loc="lower left")
    ax_t.set(xlabel="time t [s]", ylabel="peak |v| per 5 ms [V]", ylim=(1e-4, 1e3),
             title="kicked loops (dashed: predicted cycle amplitudes)")
    ax_t.grid(True, alpha=0.3)
    ax_t.legend(fontsize=7, loc="center right")
    ax_z.set(xlabel="time t [ms]", ylabel="actuator command v [V]", title="the last 10 ms")
    ax_z.grid(True, alpha=0.3)
    ax_z.set_ylim(-170, 340)
    ax_z.legend(fontsize=7, loc="upper right")
    path = os.path.join(args.out, "limit_cycle.png")
    fig.savefig(path, dpi=90)
    print(f"wrote {path}")


if __name__ == "__main__":
    main()

"""hystcomp.design: controllers tuned to a specification, checked with python-control."""

import numpy as np
import pytest

import control as ct

from hystcomp import PI
from hystcomp.design import (
    PIDGains, design_pid, design_state_feedback, loop_margins, pid_gains, resonance,
)
from hystcomp.iosys import compensator_system, discretize, pid, piezo_stage
from hystcomp.loops import build_loop, simulate_loop

DT = 1e-4
K_NOM = 2.712


@pytest.mark.parametrize("fc, pm, kind, extra", [
    (40.0, 60.0, "lowpass", dict(filter_hz=80.0)),
    (80.0, 60.0, "lowpass", dict(filter_hz=160.0)),
    (150.0, 60.0, "notch", {}),
    (500.0, 60.0, "notch", {}),    # above the notch: needs the derivative's lead
    (40.0, 80.0, "notch", {}),
])
@pytest.mark.parametrize("dt", [DT, None])
def test_pid_meets_crossover_and_phase_margin(fc, pm, kind, extra, dt):
    c = design_pid(piezo_stage(), fc, pm, actuator_gain=K_NOM, dt=dt, filter=kind, **extra)
    assert (c.dt == dt) if dt else c.isctime(strict=True)
    m = loop_margins(c, piezo_stage(), actuator_gain=K_NOM)
    # the design solves the phase condition with brentq (xtol 1e-12) and scales |L(j wc)| to 1 on the
    # exact loop; stability_margins finds the crossings by polynomial roots: agreement to ~1e-6,
    # asserted to 1e-4 relative on the crossover and 0.01 deg on the phase margin
    assert m.crossover_hz == pytest.approx(fc, rel=1e-4)
    assert m.phase_margin_deg == pytest.approx(pm, abs=0.01)
    assert m.gain_margin > 1.0
    loop = ct.feedback(ct.series(discretize(piezo_stage(), dt) if dt else piezo_stage(), c) * K_NOM, 1)
    poles = ct.poles(loop)
    assert np.all(np.abs(poles) < 1) if dt else np.all(poles.real < 0)


def test_derivative_appears_only_when_the_phase_needs_it():
    low = pid_gains(piezo_stage(), 150.0, 60.0, actuator_gain=K_NOM, dt=DT)
    high = pid_gains(piezo_stage(), 500.0, 60.0, actuator_gain=K_NOM, dt=DT)
    assert low.kd == 0 and low.tau_d is None
    assert high.kd > 0 and high.tau_d > 0 and high.ki > 0


def test_old_demo_loop_margins_read_correctly():
    # the issue: python-control gives 17.3 Hz gain crossover and 300 Hz phase crossover for the
    # first demo's integral controller (ki = 40) with the compensated actuator (k_nom = 2.712)
    m = loop_margins(pid(0.0, 40.0, 0.0, DT), piezo_stage(), actuator_gain=K_NOM)
    assert m.crossover_hz == pytest.approx(17.3, abs=0.05)
    assert m.phase_crossover_hz == pytest.approx(300.0, abs=0.5)
    assert m.gain_margin == pytest.approx(1.738, abs=1e-3)
    # what the old table printed as "at 0.0674 Hz" was the stability margin / (2 pi)
    assert m.stability_margin / (2 * np.pi) == pytest.approx(0.0674, abs=1e-4)


def test_unreachable_specifications_are_named():
    with pytest.raises(ValueError, match="cannot be met"):
        pid_gains(piezo_stage(), 40.0, 60.0, filter=None)   # a flat plant: at most 90 deg of lag
    with pytest.raises(ValueError, match="crosses 0 dB again near 2[0-9][0-9]"):
        pid_gains(piezo_stage(), 90.0, 60.0, actuator_gain=K_NOM, dt=DT, filter="lowpass", filter_hz=180.0)
    with pytest.raises(ValueError, match="Nyquist"):
        pid_gains(piezo_stage(), 6000.0, 60.0, dt=DT)
    with pytest.raises(ValueError, match="filter"):
        pid_gains(piezo_stage(), 40.0, 60.0, filter="bandstop")
    with pytest.raises(TypeError, match="unexpected"):
        design_pid(piezo_stage(), 40.0, 60.0, gain=3)


def test_resonance_of_continuous_and_discrete_plants():
    for plant in (piezo_stage(natural_freq_hz=250.0, damping=0.03),
                  discretize(piezo_stage(natural_freq_hz=250.0, damping=0.03), DT)):
        f, z = resonance(plant)
        assert f == pytest.approx(250.0, rel=1e-9) and z == pytest.approx(0.03, rel=1e-9)
    assert resonance(ct.tf([1], [1, 1])) is None


def test_designed_controller_runs_in_the_loop_builders_compiled():
    act = PI([0.5, 1.0], [0.4, 0.2], p0=1.0)
    c = design_pid(piezo_stage(), 60.0, 60.0, actuator_gain=1.0, dt=DT, filter="lowpass", filter_hz=120.0)
    loop = build_loop("feedback_compensated", act, piezo_stage(), controller=c,
                      compensator=compensator_system(act), dt=DT)
    t = np.arange(3000) * DT
    r = np.sin(2 * np.pi * 5 * t)
    a = loop.simulate(t, r).outputs
    b = simulate_loop(loop, t, r).outputs
    np.testing.assert_allclose(a, b, rtol=0, atol=1e-9)   # the compiled loop's documented agreement
    # a 60 Hz crossover leaves |S(j 2 pi 5 Hz)| ~ 5/60: RMS error ~ 0.083 x 0.707 = 0.059 (bound +35 %)
    assert float(np.sqrt(np.mean((b[0, 1500:] - r[1500:]) ** 2))) < 0.08


def test_pid_gains_system_matches_iosys_pid_when_unfiltered():
    g = PIDGains(0.5, 20.0, 1e-3, 2e-3, None, None, None, DT, 10.0, 60.0)
    a = g.system()
    b = pid(0.5, 20.0, 1e-3, DT, tau_d=2e-3)
    w = np.linspace(1, 3000, 50)
    np.testing.assert_allclose(a(np.exp(1j * w * DT)), b(np.exp(1j * w * DT)), rtol=1e-12)


@pytest.mark.parametrize("dt", [None, DT])
def test_state_feedback_with_integral_action(dt):
    d = design_state_feedback(piezo_stage(), bandwidth_hz=30.0, actuator_gain=K_NOM, dt=dt)
    cl = d.closed_loop.linearize(0, 0)
    ev = np.linalg.eigvals(cl.A)
    freqs = np.abs(np.log(ev) / dt) / (2 * np.pi) if dt else np.abs(ev) / (2 * np.pi)
    assert np.all(np.abs(ev) < 1) if dt else np.all(ev.real < 0)
    # the slowest closed-loop mode sits near the requested bandwidth (symmetric-root-locus weight): 20 %
    assert min(freqs) == pytest.approx(30.0, rel=0.2)
    # integral action: unit static gain from the reference (xd = [r, 0], ud = 0) to y
    assert cl.C[0] @ np.linalg.solve((np.eye(cl.nstates) if dt else 0) - cl.A, cl.B[:, 0]) == pytest.approx(1.0, abs=1e-9)
    # the observer-based one-degree-of-freedom form is a stable loop with integral action
    c = d.output_feedback()
    p = discretize(piezo_stage(), dt) if dt else piezo_stage()
    loop = ct.feedback(ct.series(p, c) * K_NOM, 1)
    poles = ct.poles(loop)
    assert np.all(np.abs(poles) < 1) if dt else np.all(poles.real < 0)
    assert float(np.real(ct.dcgain(loop))) == pytest.approx(1.0, abs=1e-9)
    m = loop_margins(c, piezo_stage(), actuator_gain=K_NOM)
    assert m.gain_margin > 3 and m.phase_margin_deg > 60


def test_state_feedback_output_form_tracks_with_the_hysteretic_actuator():
    act = PI([0.5, 1.0], [0.4, 0.2], p0=1.0)
    comp = compensator_system(act, nominal_gain=1.0)
    d = design_state_feedback(piezo_stage(), bandwidth_hz=30.0, actuator_gain=1.0, dt=DT)
    loop = build_loop("feedback_compensated", act, piezo_stage(), controller=d.output_feedback(),
                      compensator=comp, dt=DT)
    t = np.arange(4000) * DT
    r = np.where(t > 0.01, 1.0, 0.0)
    y = simulate_loop(loop, t, r).outputs[0]
    assert abs(y[-1] - 1.0) < 1e-3        # integral action: no static error after 0.4 s (tau ~ 5 ms)

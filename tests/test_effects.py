"""Model parts of hystcomp.effects: each follows the model protocol (explicit
fixed-length state, chunked == one-shot bit for bit, to_dict round trip) and
computes what its formula says (checked against plain loops / closed forms)."""

import json
import math

import numpy as np
import pytest

from hystcomp import PI, MGPI, Polynomial, model_from_dict, modified_play
from hystcomp.effects import (CreepOperator, DriftTerm, LinearStage, Parallel, RateDependentPI, Series,
                              lag_bank)

DT = 1e-3
T = np.arange(0, 3, DT)
V = np.sin(2 * np.pi * T) * np.exp(-0.3 * T) + 0.2 * np.sin(2 * np.pi * 7 * T)
R = np.array([0.1, 0.3, 0.5])
W = np.array([0.5, 0.3, 0.2])


def _parts():
    pi = PI(R, W, 1.0)
    return {
        "lag": LinearStage.lag(0.02, DT),
        "resonance": LinearStage.resonance(30.0, 0.1, DT),
        "rate_pi": RateDependentPI(R, W, 1.0, 0.005, DT),
        "creep": CreepOperator([0.1, 1.0], [0.05, 0.02], DT),
        "drift": DriftTerm(DT, polynomial=[0.01, -0.002], amplitudes=[0.1], time_constants=[0.7]),
        "series": Series(LinearStage.lag(0.01, DT), pi, LinearStage.resonance(40.0, 0.2, DT)),
        "parallel": Parallel(pi, CreepOperator([0.2], [0.1], DT), DriftTerm(DT, polynomial=[0.1]),
                             offset=0.5),
    }


@pytest.mark.parametrize("name", list(_parts()))
def test_protocol_chunked_equals_one_shot_bit_for_bit(name):
    m = _parts()[name]
    y, s = m.simulate(V, return_state=True)
    assert s.shape == (m.n_states,) and s.dtype == np.float64
    assert m.default_state().shape == (m.n_states,)
    parts, state = [], None
    for a, b in ((0, 7), (7, 1000), (1000, 1001), (1001, V.size)):
        yc, state = m.simulate(V[a:b], initial_state=state, return_state=True)
        parts.append(yc)
    np.testing.assert_array_equal(np.concatenate(parts), y)
    np.testing.assert_array_equal(state, s)


@pytest.mark.parametrize("name", list(_parts()))
def test_to_dict_round_trip(name):
    m = _parts()[name]
    d = json.loads(json.dumps(m.to_dict()))
    back = model_from_dict(d)
    assert type(back) is type(m)
    np.testing.assert_array_equal(back.simulate(V), m.simulate(V))


def test_lag_step_response_closed_form():
    tau = 0.02
    y = LinearStage.lag(tau, DT).simulate(np.ones(200))
    h = DT / tau
    a = math.exp(-h)
    b0 = 1 - (1 - a) / h
    k = np.arange(200)
    # first-order hold from rest, step at k = 0 (the input ramps 0 -> 1 over the sample
    # before): y_k = 1 - (1 - b0) a^k; rounding only (1e-13)
    np.testing.assert_allclose(y, 1 - (1 - b0) * a ** k, atol=1e-13)
    # a ramp is followed with a delay of exactly tau once the transient has died
    ramp = np.arange(2000) * DT
    yr = LinearStage.lag(tau, DT).simulate(ramp)
    assert yr[-1] == pytest.approx(ramp[-1] - tau, abs=1e-12)


def test_resonance_static_gain_and_overshoot():
    st = LinearStage.resonance(20.0, 0.1, 1e-4)
    assert st.dc_gain() == pytest.approx(1.0, abs=1e-12)
    y = st.simulate(np.ones(20000))
    # continuous second-order overshoot exp(-pi z / sqrt(1 - z^2)) = 0.7292 for z = 0.1;
    # Tustin at 500 samples per period is within 0.5 % of it
    assert y.max() - 1 == pytest.approx(math.exp(-math.pi * 0.1 / math.sqrt(1 - 0.01)), rel=5e-3)
    with pytest.raises(ValueError, match="Nyquist"):
        LinearStage.resonance(600.0, 0.1, 1e-3)


def test_resonance_matches_scipy_bilinear():
    from scipy.signal import cont2discrete

    f, z, dt = 30.0, 0.2, 2e-3
    st = LinearStage.resonance(f, z, dt)
    w = 2 / dt * math.tan(math.pi * f * dt)           # the prewarped frequency
    A = np.array([[0.0, 1.0], [-w * w, -2 * z * w]])
    sys_c = (A, np.array([[0.0], [w * w]]), np.array([[1.0, 0.0]]), np.zeros((1, 1)))
    Ad, Bd, Cd, Dd, _ = cont2discrete(sys_c, dt, method="bilinear")
    # same formulas, evaluated by another code path: rounding only
    np.testing.assert_allclose(st.A, Ad, atol=1e-12)
    np.testing.assert_allclose(st.B, Bd[:, 0], atol=1e-9)
    np.testing.assert_allclose(st.C, Cd[0], atol=1e-12)
    assert st.D == pytest.approx(Dd[0, 0], abs=1e-12)
    # prewarping: at `frequency` the discrete response equals the continuous one,
    # w^2 / (2 j zeta w^2) = 1 / (2 j zeta), exactly (rounding only)
    zf = np.exp(2j * np.pi * f * dt)
    H = st.C @ np.linalg.solve(zf * np.eye(2) - st.A, st.B) + st.D
    assert H == pytest.approx(1 / (2j * z), rel=1e-9)


@pytest.mark.parametrize("ns", [1, 2, 3])
def test_filter_columns_matches_scipy_dlsim(ns):
    """Every column through the stage equals scipy.signal.dlsim's response
    (another code path: rounding only), from rest and from given states, for
    the one- and two-state branches of the kernel and the general one."""
    from scipy.signal import dlsim

    rng = np.random.default_rng(ns)
    if ns == 1:
        st = LinearStage.lag(0.02, DT)
    elif ns == 2:
        st = LinearStage.resonance(30.0, 0.2, DT)
    else:  # a lag in series with a resonance, as one three-state system
        lag, res = LinearStage.lag(0.02, DT), LinearStage.resonance(30.0, 0.2, DT)
        A = np.zeros((3, 3))
        A[0, 0] = lag.A[0, 0]
        A[1:, 1:] = res.A
        A[1:, 0] = res.B * lag.C[0]
        B = np.concatenate([lag.B, res.B * lag.D])
        C = np.concatenate([res.D * lag.C, res.C])
        st = LinearStage(A, B, C, res.D * lag.D, DT)
    U = rng.standard_normal((400, 4))
    X0 = rng.standard_normal((4, ns))
    out, X = st.filter_columns(U, X0)
    for j in range(4):
        _, yref, xref = dlsim((st.A, st.B[:, None], st.C[None, :], [[st.D]], DT), U[:, j], x0=X0[j])
        np.testing.assert_allclose(out[:, j], yref[:, 0], rtol=1e-12, atol=1e-12)
        # dlsim's states are before each sample: the final state is one more step
        x_end = st.A @ xref[-1] + st.B * U[-1, j]
        np.testing.assert_allclose(X[j], x_end, rtol=1e-12, atol=1e-12)
    # a column alone gives the same floats as among others (independent states)
    np.testing.assert_array_equal(st.filter_columns(U[:, 2:3], X0[2:3])[0][:, 0], out[:, 2])


def test_stage_inverse_cancels_the_stage():
    st = LinearStage.lag(0.02, DT)
    assert st.is_invertible()
    u = st.exact_inverse().simulate(st.simulate(V))
    # exact in exact arithmetic; the inverse (gain 1/b0 = 40 at high frequency, zero at
    # -0.98) amplifies rounding: 1e-10 leaves two orders of margin
    np.testing.assert_allclose(u, V, atol=1e-10)
    # Tustin puts the resonance's two zeros at z = -1: no stable causal inverse, and it says so
    res = LinearStage.resonance(30.0, 0.3, DT)
    check = res.is_invertible()
    assert not check and "unit circle" in check.reasons[0]
    with pytest.raises(ValueError, match="no causal stable inverse"):
        res.exact_inverse()


def test_series_inverse_compensates_hysteresis_and_lag():
    model = Series(PI(R, W, 1.0), LinearStage.lag(0.01, DT))
    comp = model.exact_inverse()
    u = 0.8 * np.sin(2 * np.pi * T)
    # the exact PI inverse and the inverse lag: model(comp(u)) = u to solver precision
    np.testing.assert_allclose(model.simulate(comp.simulate(u)), u, atol=1e-8)


def test_rate_pi_reduces_to_pi_at_zero_rate_coefficient():
    y0 = RateDependentPI(R, W, 1.0, 0.0, DT).simulate(V)
    # same plays; only the summation order differs from PI's kernel (rounding, 1e-12)
    np.testing.assert_allclose(y0, PI(R, W, 1.0).simulate(V), atol=1e-12)


def test_rate_pi_thresholds_follow_the_rate():
    # a plain-loop reference of r_i + beta |dv/dt|
    beta = 0.01
    m = RateDependentPI(R, W, 1.0, beta, DT)
    z = np.zeros(R.size)
    ref = np.empty(V.size)
    for k, x in enumerate(V):
        rate = abs(x - V[k - 1]) / DT if k else 0.0
        for i, r in enumerate(R):
            z[i] = min(max(z[i], x - r - beta * rate), x + r + beta * rate)
        ref[k] = x + W @ z
    np.testing.assert_allclose(m.simulate(V), ref, atol=1e-12)
    # loops widen with frequency: the loop area (|closed integral of y dv| over the last
    # period) at 10 Hz is more than twice that at 1 Hz (measured 1.81 against 0.785;
    # a rate-independent model gives equal areas)
    tt = np.arange(0, 2, DT)

    def area(f):
        v = np.sin(2 * np.pi * f * tt)
        y = m.simulate(v)
        per = int(round(1 / (f * DT)))
        vv, yy = v[-per:], y[-per:]
        return abs(np.sum(0.5 * (yy[1:] + yy[:-1]) * np.diff(vv)))
    assert area(10) > 2 * area(1)


def test_creep_step_response_closed_form():
    tau, c = np.array([0.1, 1.0]), np.array([0.05, 0.02])
    y = CreepOperator(tau, c, DT).simulate(np.ones(3000))
    k = np.arange(3000)[:, None]
    ref = ((1 - np.exp(-DT / tau) ** (k + 1)) * c).sum(axis=1)
    np.testing.assert_allclose(y, ref, atol=1e-12)      # rounding only
    # creep follows the sign and size of the step
    np.testing.assert_allclose(CreepOperator(tau, c, DT).simulate(-2 * np.ones(3000)), -2 * y, atol=1e-12)


def test_drift_clock_and_formula():
    d = DriftTerm(0.5, polynomial=[0.1, 0.01], amplitudes=[2.0], time_constants=[3.0])
    y = d.simulate(np.zeros(10))
    t = 0.5 * np.arange(10)
    np.testing.assert_allclose(y, 0.1 * t + 0.01 * t ** 2 + 2 * (1 - np.exp(-t / 3)), atol=1e-14)
    assert d.simulate(np.zeros(3), initial_state=[4.0])[0] == y[4]


def test_lag_bank_matches_loop():
    x, s = lag_bank(V[:50], [0.01, 0.05], DT)
    ref = np.zeros(2)
    a = np.exp(-DT / np.array([0.01, 0.05]))
    for k in range(50):
        ref = a * ref + (1 - a) * V[k]
        np.testing.assert_allclose(x[k], ref, atol=1e-15)


def test_part_core_kernel_matches_modified_play():
    # hystcomp.identify's core kernel (the plays of diagnose's parts) against the
    # library's modified play (eq. 23) with quadratic and with tanh envelopes
    from hystcomp.identify._part_kernels import core_columns

    Vm = 1.0
    rho, cl, cr = 1.3, 0.1, -0.15
    gl = Polynomial([0.0, rho, rho * cl / Vm], interval=(-2, 2))
    gr = Polynomial([0.0, 1.0, cr / Vm], interval=(-2, 2))
    r_all = np.concatenate([[0.0], R])
    ref, _ = modified_play(V, r_all, gl, gr)
    out = np.empty_like(ref)
    core_columns(V, r_all, 0.0, 0.0, rho, cl, cr, 0.0, 0.0, np.zeros(0), out)
    np.testing.assert_allclose(out, ref, atol=1e-13)   # Horner vs factored polynomial: rounding
    m = MGPI(R, W, 1.0, envelope_left=gl, envelope_right=gr)
    np.testing.assert_allclose(m.simulate(V), out @ np.concatenate([[1.0], W]), atol=1e-12)
    # symmetric tanh envelope: gamma(F_r[v]) of the plays (the mGPI's state convention)
    from hystcomp.envelopes import Tanh

    b = 0.8
    env = Tanh(1.0 / b, b)
    core_columns(V, r_all, 0.0, 0.0, 1.0, 0.0, 0.0, b, b, np.zeros(0), out)
    m = MGPI(R, W, 1.0, envelope=env)
    np.testing.assert_allclose(m.simulate(V), out @ np.concatenate([[1.0], W]), atol=1e-12)
    # rate-dependent thresholds: the same plays as RateDependentPI (r_0 = 0 stays the input)
    rd = RateDependentPI(R, W, 1.0, rate_coefficient=0.02, dt=DT)
    core_columns(V, r_all, 0.02, 1.0 / DT, 1.0, 0.0, 0.0, 0.0, 0.0, np.zeros(0), out)
    np.testing.assert_allclose(rd.simulate(V), out @ np.concatenate([[1.0], W]), atol=1e-12)


@pytest.mark.parametrize("rho, ql, qr, shift, level", [
    (1.0, 0.0, 0.0, 0.0, 0.0),          # the classical plays (eq. 18)
    (1.3, 0.1, -0.15, 0.0, 0.0),        # asymmetric polynomial envelopes
    (1.0, 0.0, 0.0, 0.05, 0.4),         # thresholds shifted and growing with the level
])
def test_part_core_kernel_rate_independent_branch(rho, ql, qr, shift, level):
    """The kernel's branch for rate-independent plays with polynomial
    envelopes gives the same floats as its general loop, with and without a
    preload history, and the classical plays are those of PI (eq. 18)."""
    from hystcomp.identify._part_kernels import core_columns

    r_all = np.concatenate([[0.0], R])
    for preload in (np.zeros(0), np.array([0.9, -0.4])):
        fast = np.empty((V.size, r_all.size))
        core_columns(V, r_all, 0.0, 0.0, rho, ql, qr, 0.0, 0.0, preload, fast, shift, level)
        # a rate coefficient of 1e-300 with 1/dt = 0 sends the call through the
        # general loop, where its rate term is then exactly 0: the same
        # arithmetic, another path
        general = np.empty_like(fast)
        core_columns(V, r_all, 1e-300, 0.0, rho, ql, qr, 0.0, 0.0, preload, general, shift, level)
        np.testing.assert_array_equal(fast, general)
        if preload.size == 0 and rho == 1.0 and ql == 0.0 and shift == 0.0 and level == 0.0:
            pi = PI(R, W, 1.0)
            np.testing.assert_allclose(fast @ np.concatenate([[1.0], W]), pi.simulate(V), atol=1e-12)


@pytest.mark.parametrize("decay, overstress_scale", [(0.9, 0.0), (0.3, 0.0), (0.9, 0.05), (0.995, 0.4)])
@pytest.mark.parametrize("rho, ql, qr, shift, level", [(1.0, 0.0, 0.0, 0.0, 0.0), (1.3, 0.1, -0.15, 0.05, 0.4)])
def test_part_core_kernel_viscous_branch(decay, overstress_scale, rho, ql, qr, shift, level):
    """The kernel's branch for viscous and thermally activated plays with
    polynomial envelopes and fixed thresholds (round 18) gives the same
    floats as its general loop, with and without a preload history."""
    from hystcomp.identify._part_kernels import core_columns

    r_all = np.concatenate([[0.0], R])
    for preload in (np.zeros(0), np.array([0.9, -0.4])):
        fast = np.empty((V.size, r_all.size))
        core_columns(V, r_all, 0.0, 0.0, rho, ql, qr, 0.0, 0.0, preload, fast, shift, level, decay,
                     overstress_scale)
        general = np.empty_like(fast)     # as above: the general loop with a rate term of exactly 0
        core_columns(V, r_all, 1e-300, 0.0, rho, ql, qr, 0.0, 0.0, preload, general, shift, level, decay,
                     overstress_scale)
        np.testing.assert_array_equal(fast, general)
        # and the plays do relax: not the rate-independent ones
        plain = np.empty_like(fast)
        core_columns(V, r_all, 0.0, 0.0, rho, ql, qr, 0.0, 0.0, preload, plain, shift, level)
        assert not np.allclose(fast, plain)


def test_bad_arguments_are_named():
    with pytest.raises(ValueError, match="time_constant"):
        LinearStage.lag(-1.0, DT)
    with pytest.raises(ValueError, match="Parameter A has shape"):
        LinearStage(np.zeros((2, 3)), [1, 1], [1, 1], 0.0, DT)
    with pytest.raises(ValueError, match="coefficients"):
        CreepOperator([0.1, 1.0], [0.1], DT)
    with pytest.raises(ValueError, match="time_constants"):
        DriftTerm(DT, amplitudes=[1.0], time_constants=[])
    with pytest.raises(ValueError, match="rate_coefficient"):
        RateDependentPI(R, W, 1.0, -0.1, DT)
    with pytest.raises(TypeError, match="model protocol"):
        Series(PI(R, W, 1.0), object())
    with pytest.raises(ValueError, match="initial_state"):
        LinearStage.lag(0.1, DT).simulate(V, initial_state=[0.0, 0.0])


def test_python_control_block_runs_the_composite():
    iosys = pytest.importorskip("hystcomp.iosys")
    ct = pytest.importorskip("control")
    if not hasattr(iosys, "hysteresis_system"):
        pytest.skip("hystcomp.iosys.hysteresis_system not there yet")
    m = _parts()["parallel"]
    sys = iosys.hysteresis_system(m, dt=DT)
    tt = T[:500]
    r = ct.input_output_response(sys, tt, V[:500])
    # the generic protocol block steps the same model: same numbers up to rounding
    np.testing.assert_allclose(np.ravel(r.outputs), m.simulate(V[:500]), atol=1e-12)

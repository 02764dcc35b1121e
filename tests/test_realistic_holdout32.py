"""HOLDOUT32 (tests/realistic/cases_holdout32.py, laws in mechanisms32.py, signals in signals32.py): well formed, in
ALL (joined after its one measurement in round 34, 15 of 30 runs right), and every mechanism follows its law. Nothing
here runs the diagnosis.

Tolerances: a record that is its stated law plus the sensor noise leaves a residual RMS within 1.5 sigma of the law (the
noise alone gives 1.0; the laws are evaluated on the clean drive). A law checked against an independent solution
(solve_ivp, quad, a closed form, an FFT of the transfer function, a Kirchhoff or eigenvalue solution of a discretised
model, or a direct sum) agrees to the stated tolerance, set from the solvers' own tolerances or the scheme's order (each
stated beside it), far below sigma (2e-3 of the span). Effects are asked to move the output by at least 7 sigma beyond
what a gain and an offset on the core absorb; the measured values for seeds 0 ... 2 are stated beside each.
"""

import math
from functools import lru_cache

import numpy as np
import pytest
from scipy.integrate import quad, solve_ivp
from scipy.optimize import brentq, isotonic_regression

from realistic import HOLDOUT32, family
from realistic import cases_holdout32 as c32
from realistic import mechanisms32 as m32
from realistic import signals32 as s32
from test_realistic_generator import (_assert_drives_start_at_zero, _assert_measured_set, _assert_set_layout,
                                      _assert_spans_and_rates, _linear_misfit, _rms)

pytestmark = pytest.mark.slow

P = "holdout32_"
EFFECTS = {"creep", "rate_dependence", "drift", "asymmetry", "saturation", "initial_state", "delay"}
CLEAN = "clean_dahl_guide_turntable_scratching_1715hz"
CREEP = "creep_huet_asphalt_pad_bascule_bridge_222hz"
RATE = "rate_rlc_shunted_voice_coil_dobby_loom_1545hz"
DRIFT = "drift_interferometer_dead_path_operator_pumpjack_644hz"
ASYM = "asymmetry_vibrating_wire_gauge_carousel_1125hz"
SAT = "saturation_leaky_lateral_psd_accordion_bellows_766hz"
DELAY = "delay_wireless_jitter_buffer_stamp_mill_435hz"
INIT = "initial_state_hand_pushed_guide_skipping_rope_940hz"
PAIR = "pair_rate_drift_vane_drag_walking_operator_launcher_gimbal_1285hz"
OOV = "oov_slide_by_hall_magnet_weathervane_1355hz"
UNIPOLAR = {CREEP, RATE, DELAY}
MONITORED = {CLEAN: 3e-4, RATE: 2.5e-4, SAT: 3e-4, DELAY: 2e-4}


@lru_cache(maxsize=None)
def _rec(name, seed):
    return HOLDOUT32[P + name](seed)


def _core(e, v, state=None):
    return e["gain"] * m32.dahl_stage(v, e["K"], e["Fc"], e["sigma0"], e["a"], state=state)


def _dahl_ivp(knots, K, Fc, sigma0, a, x0=0.0, F0=0.0):
    """The stage along a piecewise-linear drive through `knots`, integrated in v by solve_ivp (written here from the
    law, not from dahl_stage): on each monotone leg (direction s) dx/dv = 1 / (K + sigma0 u^a), dF/dv = sigma0 u^a /
    (K + sigma0 u^a), u = 1 - s F / Fc (DOP853, rtol 1e-12). Returns x and F at the knots."""
    xs, Fs, st = [x0], [F0], np.array([x0, F0])
    for va, vb in zip(knots[:-1], knots[1:]):
        s = 1.0 if vb > va else -1.0

        def rhs(v, y):
            w = sigma0 * (1.0 - s * y[1] / Fc) ** a
            return [1.0 / (K + w), w / (K + w)]
        sol = solve_ivp(rhs, (va, vb), st, method="DOP853", rtol=1e-12, atol=1e-12)
        st = sol.y[:, -1]
        xs.append(st[0])
        Fs.append(st[1])
    return np.array(xs), np.array(Fs)


# ---- the set ----

def test_holdout32_is_well_formed_and_in_all():
    H = HOLDOUT32
    first = _assert_measured_set(H, P, EFFECTS)
    _assert_set_layout(H, P, first, _rec, MONITORED, others_carry_drive=True)
    assert len(family(EFFECTS)) == 7
    pair = first[P + PAIR]
    assert pair.expect_effects == {"rate_dependence", "drift"} and pair.expect_verdict == "either"
    assert first[P + CLEAN].expect_verdict == "explained"
    assert first[P + OOV].expect_verdict == "unexplained"
    _assert_spans_and_rates(H, P, first, _rec, UNIPOLAR)
    _assert_drives_start_at_zero(H, P, _rec)


# ---- clean: a Dahl rolling guide under a turntablist's scratches ----

def test_clean_dahl_guide_under_turntable_scratching():
    # one branch of Dahl's law against solve_ivp of dF/dx = sigma0 (1 - s F / Fc)^a from a reversal, in the travel
    # since it, s (x - x_r) (DOP853, rtol 1e-12: 1e-9 of Fc)
    Fc, sig0 = 7.0, 2.5
    for a in (1.3, 1.8, 2.2):
        for s, F_r in ((1.0, 0.0), (-1.0, 5.5), (1.0, -6.2)):
            xq = np.linspace(0, 12, 61)
            sol = solve_ivp(lambda d, F: [s * sig0 * (1 - s * F[0] / Fc) ** a], (0, 12), [F_r], t_eval=xq,
                            method="DOP853", rtol=1e-12, atol=1e-12)
            F = s * Fc * (1 - m32.dahl_branch(1 - s * F_r / Fc, xq, a, sig0 / Fc))
            np.testing.assert_allclose(F, sol.y[0], atol=1e-9 * Fc)
    # the stage along a path with reversals against the law integrated in v (1e-8 of the travel), its minor loops not
    # Masing's (a reversal's first slope dF/dx is sigma0 (1 + |F_r| / Fc)^a, not the virgin curve's sigma0), and
    # rate independent: the same path sampled 1x and 7x as densely agrees at the shared samples (Newton's 1e-13)
    K, Fc, sig0, a = 1.5, 7.5, 1.2, 1.7
    knots = [0.0, 40.0, -25.0, 10.0, -5.0, 46.0, -46.0, 0.0]
    v = np.concatenate([np.linspace(p, q, 300)[1:] if j else np.linspace(p, q, 300)
                        for j, (p, q) in enumerate(zip(knots[:-1], knots[1:]))])
    x, st = m32.dahl_stage(v, K, Fc, sig0, a, return_state=True)
    xk, Fk = _dahl_ivp(knots, K, Fc, sig0, a)
    np.testing.assert_allclose(x[np.r_[0, 299 * np.arange(1, len(knots))]], xk, atol=1e-8 * np.ptp(x))
    assert st[1] == pytest.approx(Fk[-1], abs=1e-8 * Fc)
    _, st40 = m32.dahl_stage(v[:300], K, Fc, sig0, a, return_state=True)
    F_r = st40[1]
    assert sig0 * (1 + abs(F_r) / Fc) ** a > 2.2 * sig0
    v7 = np.interp(np.arange(7 * (len(v) - 1) + 1) / 7, np.arange(len(v)), v)
    np.testing.assert_allclose(m32.dahl_stage(v7, K, Fc, sig0, a)[::7], x, atol=1e-11 * np.ptp(x))
    # a state carried over gives the same as one run (1e-12)
    x1, st1 = m32.dahl_stage(v[:1000], K, Fc, sig0, a, return_state=True)
    np.testing.assert_allclose(np.r_[x1, m32.dahl_stage(v[1000:], K, Fc, sig0, a, state=st1)], x, atol=1e-12)
    for seed in (0, 1, 2):
        rec = _rec(CLEAN, seed)
        e = rec.extra
        model = _core(e, e["drive"]) + e["offset"]
        assert _rms(rec.y - model) < 1.5 * rec.noise_std
        # the scratches lie on the thirty-second-note grid after a beat's lead-in
        g = 60.0 / e["bpm"] / 8
        assert np.allclose(np.round(np.asarray(e["times"]) / g) * g, e["times"], atol=1e-9)
        # the core is far from a straight line (the friction's hysteresis: measured 41 ... 68 sigma); for the record
        # (not asserted): a PI model of 12 plays fitted by NNLS leaves 2.3 ... 5.4 sigma RMS, at most 11 ... 22 sigma
        assert _linear_misfit(model, e["drive"]) > 20 * rec.noise_std


# ---- creep: Huet's bituminous pad under a bascule bridge ----

def test_huet_creep_under_bascule_bridge():
    # the creep function's Laplace transform against quad: s L[psi](s) = delta (s tau)^-k + (s tau)^-h, Huet's complex
    # compliance (1e-7 relative: quad's tolerance on the weakly singular integrand)
    tau, delta, k, h = 3.0, 2.5, 0.22, 0.55
    for s in (0.05, 0.4, 3.0):
        lap = quad(lambda t: float(m32.huet_function(t, tau, delta, k, h)) * math.exp(-s * t), 0, np.inf,
                   epsabs=1e-13, epsrel=1e-11, limit=400)[0]
        assert s * lap == pytest.approx(delta * (s * tau) ** -k + (s * tau) ** -h, rel=1e-7)
    # the FFT convolution against the direct sum of the kernel (1e-10 of the span)
    r = np.random.default_rng(5)
    f = np.cumsum(r.normal(0, 1, 2500))
    dt = 0.01
    got = m32.huet_creep(f, dt, 0.12, tau, delta, k, h)
    mm = np.arange(2500.0)
    kern = sum(w * (dt / tau) ** p * ((mm + 1) ** (p + 1) - mm ** (p + 1)) / math.gamma(p + 2)
               for w, p in ((delta, k), (1.0, h)))
    df = np.r_[0.0, np.diff(f)]
    ref = 0.12 * np.array([np.dot(df[:j + 1], kern[j::-1]) for j in range(2500)]) / float(
        m32.huet_function(10.0, tau, delta, k, h))
    np.testing.assert_allclose(got, ref, atol=1e-10 * np.ptp(ref))
    # a ramp over T1 and a hold against quad of Boltzmann's integral (1e-9), and a step held 10 s creeps by c (2e-3
    # relative: the step spread over its one sample)
    T1 = 2.0
    tq = np.arange(3000) * dt
    got = m32.huet_creep(np.minimum(tq / T1, 1.0), dt, 0.12, tau, delta, k, h)
    norm = float(m32.huet_function(10.0, tau, delta, k, h))
    for j in (60, 200, 2500):
        ref = quad(lambda u: float(m32.huet_function(tq[j] - u, tau, delta, k, h)) / T1, 0, min(tq[j], T1),
                   epsabs=1e-13, limit=200)[0]
        assert got[j] == pytest.approx(0.12 * ref / norm, abs=1e-9)
    step = m32.huet_creep(np.r_[0.0, np.ones(1100)], dt, 0.12, tau, delta, k, h)
    assert step[1001] == pytest.approx(0.12, rel=2e-3)
    for seed in (0, 1, 2):
        rec = _rec(CREEP, seed)
        e = rec.extra
        hh = _core(e, rec.v)
        cr = m32.huet_creep(hh, rec.t[1], e["c_creep"], e["tau"], e["delta"], e["k"], e["hx"])
        assert _rms(rec.y - hh - cr) < 1.5 * rec.noise_std
        # the leaf: closed at the start and the end, fully open once, never faster than its drive allows
        p = e["p"]
        assert p[0] == 0.0 and abs(p[-1]) < 1e-12 and p.max() == pytest.approx(1.0) and p.min() > -1e-12
        vmax = max(mv[3] for mv in e["moves"])
        assert np.abs(np.diff(p)).max() / rec.t[1] <= vmax * (1 + 1e-6)
        # the creep moves the output by over 7 sigma beyond a gain and offset on the core (measured 32 ... 44)
        assert _linear_misfit(hh + cr, hh) > 7 * rec.noise_std


# ---- rate: an R-L-C shunted voice coil under a dobby loom ----

def test_rlc_shunted_voice_coil_under_dobby_loom():
    # the transfer function against the circuit and the stage solved in the frequency domain (K Y + Bl I = H, (L s + R
    # + 1 / (C s)) I = Bl s Y; 1e-12)
    K, Bl, L, R, C = 1.35, 0.8, 0.9, 7.0, 0.004
    Lp = L + Bl * Bl / K
    kappa, w = (Bl * Bl / K) / Lp, 1 / math.sqrt(Lp * C)
    zeta = R / Lp / (2 * w)
    for s in (0.5j, 6j, 40j, 300j, 3 + 20j):
        M = np.array([[K, Bl], [-Bl * s, L * s + R + 1 / (C * s)]])
        Y = np.linalg.solve(M, np.array([1.0, 0.0]))[0]
        assert abs(Y - m32.rlc_shunt_transfer(s, K, kappa, w / (2 * math.pi), zeta)) < 1e-12
    # the exact recursion against the transfer function applied by FFT to a smooth pulse (its width 400 samples: the
    # linear interpolation's error ~1e-8; 1e-6)
    dt = 1e-4
    tq = np.arange(40000) * dt
    pulse = np.exp(-((tq - 0.8) / 0.04) ** 2) - 0.6 * np.exp(-((tq - 1.6) / 0.1) ** 2)
    got = m32.rlc_shunt_stage(pulse, dt, K, kappa, 5.0, 0.3)
    N = 2 * len(tq)
    f = np.fft.rfftfreq(N, dt)
    ref = np.fft.irfft(np.fft.rfft(pulse, N) * m32.rlc_shunt_transfer(2j * math.pi * f, K, kappa, 5.0, 0.3), N)
    np.testing.assert_allclose(got, ref[:len(tq)], atol=1e-6)
    # a slow ramp sees 1 / K (1e-5: the lag of a ramp over 100 s), a step (1 - kappa) / K at once (1e-9)
    slow = m32.rlc_shunt_stage(np.linspace(0, 1, 100001), 1e-3, K, kappa, 5.0, 0.3)
    assert slow[-1] == pytest.approx(1 / K, rel=1e-5)
    step = m32.rlc_shunt_stage(np.r_[0.0, np.ones(5)], 1e-12, K, kappa, 5.0, 0.3)
    assert step[1] == pytest.approx((1 - kappa) / K, rel=1e-9)
    # the pick count is the exact integral of the loom's speed (a fine trapezoid of it: 1e-8)
    tq = np.linspace(0, 12, 120001)
    kt, kw = [0.0, 1.0, 3.0, 5.0, 12.0], [0.0, 0.0, 4.0, 2.0, 2.0]
    num = np.r_[0.0, np.cumsum(0.5 * (np.interp(tq[1:], kt, kw) + np.interp(tq[:-1], kt, kw)) * np.diff(tq))]
    np.testing.assert_allclose(s32.speed_integral(tq, kt, kw), num, atol=1e-8)
    for seed in (0, 1, 2):
        rec = _rec(RATE, seed)
        e = rec.extra
        hh = _core(e, e["drive"])
        y = m32.rlc_shunt_stage(hh, rec.t[1], e["K_s"], e["kappa"], e["f_e"], e["zeta"])
        assert _rms(rec.y - y) < 1.5 * rec.noise_std
        # the frame dwells at the weave's states: at each pick's end it sits where the pattern says
        pat = c32.WEAVES[e["weave"]]
        picks = s32.speed_integral(rec.t, e["kt"], e["kw"])
        j = np.nonzero(np.diff(np.floor(picks)) > 0)[0][:40]
        assert np.allclose(e["x"][j], [pat[int(np.floor(picks[i])) % len(pat)] for i in j], atol=1e-9)
        # the shunt moves the output by over 7 sigma beyond a gain and offset on the core (measured 35 ... 62)
        assert _linear_misfit(y, hh) > 7 * rec.noise_std


# ---- drift: an interferometer's dead path under a pumping unit ----

def test_interferometer_dead_path_under_pumpjack():
    # the modified Edlen equation at 20 C, 101.325 kPa, 633 nm: n - 1 = 2.718e-4 (the value metrology tables quote for
    # a HeNe laser in standard air; 1e-7), and n - 1 falling with the air's density, -(n - 1) / (273.15 + t) per K
    # within 0.5 % (ideal gas; the compressibility term's own temperature dependence adds 0.3 %)
    n20 = float(m32.edlen_refractivity(20.0, 101325.0, 0.633))
    assert n20 == pytest.approx(2.718e-4, abs=1e-7)
    dn = (float(m32.edlen_refractivity(20.01, 101325.0, 0.633)) - float(m32.edlen_refractivity(19.99, 101325.0,
                                                                                                  0.633))) / 0.02
    assert dn == pytest.approx(-n20 / 293.15, rel=5e-3)
    # the enclosure's air against solve_ivp of the two capacities with the operator's heat on and off (DOP853, rtol
    # 1e-11: 1e-9)
    ta, tw, g, sh, t_in, t_out = 8.0, 90.0, 0.5, 1.2, 5.0, 30.0
    tq = np.linspace(0, 60, 601)

    def rhs(t, T):
        q = 1.0 if t_in <= t < t_out else 0.0
        return [(q - (T[0] - T[1]) - g * T[0]) / ta, (sh * (T[0] - T[1]) - T[1]) / tw]
    sol = solve_ivp(rhs, (0, 60), [0.0, 0.0], t_eval=tq, method="DOP853", rtol=1e-11, atol=1e-12,
                    max_step=0.05)
    np.testing.assert_allclose(m32.enclosure_air_temperature(tq, t_in, t_out, ta, tw, g, sh), sol.y[0], atol=1e-6)
    # the pumping unit's beam angle closes its four-bar loop (|E - Q| = P, E above the crank: 1e-12) and agrees with
    # brentq on the loop's closure (1e-10)
    R, Pp, I, H = 0.4, 1.2, 1.0, 1.3
    th = np.linspace(0, 2 * math.pi, 73)
    b = s32.pumpjack_beam_angle(th, R, Pp, 1.0, I, H)
    qx, qy = -I + R * np.cos(th), -H + R * np.sin(th)
    np.testing.assert_allclose(np.hypot(-np.cos(b) - qx, -np.sin(b) - qy), Pp, atol=1e-12)
    assert np.all(-np.sin(b) > qy)
    for j in (0, 20, 50):
        bb = brentq(lambda q: math.hypot(-math.cos(q) - qx[j], -math.sin(q) - qy[j]) - Pp, -0.9, 0.9, xtol=1e-14)
        assert b[j] == pytest.approx(bb, abs=1e-10)
    for seed in (0, 1, 2):
        rec = _rec(DRIFT, seed)
        e = rec.extra
        hh = _core(e, rec.v)
        assert _rms(rec.y - hh - e["offset"]) < 1.5 * rec.noise_std
        assert np.abs(e["offset"]).max() == pytest.approx(e["mag"] * np.ptp(hh), rel=1e-9)
        assert e["offset"][0] == 0.0 and np.argmax(np.abs(e["offset"])) > np.searchsorted(rec.t, e["t_in"])
        # the rod starts at mid-stroke and reaches both ends of it
        assert abs(e["x"][0]) < 1e-9 and e["x"].max() == pytest.approx(1.0, abs=1e-3)
        assert e["x"].min() == pytest.approx(-1.0, abs=1e-3)
        # the drift moves the output by over 7 sigma beyond a gain and offset on the core (measured 13 ... 17)
        assert _linear_misfit(hh + e["offset"], hh) > 7 * rec.noise_std


# ---- asymmetry: a vibrating-wire gauge under a carousel ----

def test_vibrating_wire_gauge_under_carousel():
    # the reading against a beaded string's fundamental (the tridiagonal eigenproblem of N = 400 beads): its
    # frequency ratio at two tensions is sqrt of theirs for any N (1e-9: the eigensolver's relative accuracy on the
    # smallest eigenvalue, eps times the matrix's condition ~ N^2, scaled by 2 / a), and the fundamental is Mersenne's
    # 1 / (2 L) sqrt(T / mu) (5e-6 relative at N = 400: the discretisation's pi^2 / (24 N^2))
    N, Lw, mu = 400, 1.0, 1.0

    def fundamental(T):
        hh = Lw / (N + 1)
        A = (np.diag(np.full(N, 2.0)) - np.diag(np.ones(N - 1), 1) - np.diag(np.ones(N - 1), -1)) * T / (mu * hh * hh)
        return math.sqrt(np.linalg.eigvalsh(A)[0]) / (2 * math.pi)
    f0 = fundamental(1.0)
    assert f0 == pytest.approx(1 / (2 * Lw), rel=5e-6)
    a = 0.3
    for u in (-1.0, -0.4, 0.5, 1.0):
        ratio = fundamental(1 + a * u) / f0
        assert float(m32.vibrating_wire_reading(u, a)) == pytest.approx(2 * (ratio - 1) / a, abs=1e-9)
    for seed in (0, 1, 2):
        rec = _rec(ASYM, seed)
        e = rec.extra
        hh = _core(e, rec.v)
        c, X = e["centre"], e["X"]
        y = c + e["side"] * X * m32.vibrating_wire_reading(e["side"] * (hh - c) / X, e["a_wire"])
        assert _rms(rec.y - y) < 1.5 * rec.noise_std
        assert m32.vibrating_wire_asym(e["a_wire"]) == pytest.approx(e["asym"], abs=1e-12)
        # the horse rises and falls n_cranks times a revolution: the strokes over the record match the revolutions
        rev = s32.speed_integral(rec.t, e["kt"], e["kw"])
        peaks = np.sum((e["x"][1:-1] > e["x"][:-2]) & (e["x"][1:-1] >= e["x"][2:]))
        assert abs(peaks - e["n_cranks"] * rev[-1]) <= 2
        # the wire moves the output by over 7 sigma beyond a gain and offset on the core (measured 11 ... 13)
        assert _linear_misfit(y, hh) > 7 * rec.noise_std


# ---- saturation: a leaky lateral-effect PSD under an accordion's bellows ----

def test_leaky_psd_under_accordion_bellows():
    # the ratio against a resistor ladder (Kirchhoff: N series resistors along the layer, a shunt conductance at each
    # node, the electrodes grounded, the photocurrent injected at one node; numpy's solve): (I2 - I1) / (I1 + I2) ->
    # tanh(alpha x) / tanh(alpha L) to the ladder's O(h^2) (2e-6 at N = 2000)
    N, aL = 2000, 1.3
    hh = 2.0 / N
    g_s = (aL * hh) ** 2                                          # the shunt over the series conductance, per node
    main = np.full(N - 1, 2.0 + g_s)
    A = np.diag(main) - np.diag(np.ones(N - 2), 1) - np.diag(np.ones(N - 2), -1)
    for x in (-0.7, -0.2, 0.3, 0.85):
        j = int(round((x + 1) / hh)) - 1                          # the interior node at x
        b = np.zeros(N - 1)
        b[j] = 1.0
        V = np.linalg.solve(A, b)
        I1, I2 = V[0], V[-1]                                      # the currents into the grounded ends
        xj = -1 + (j + 1) * hh
        assert (I2 - I1) / (I1 + I2) == pytest.approx(float(m32.leaky_psd_ratio(xj, aL)), abs=2e-6)
    for seed in (0, 1, 2):
        rec = _rec(SAT, seed)
        e = rec.extra
        hh_ = _core(e, e["drive"])
        c, X = e["centre"], e["X"]
        y = c + X * m32.psd_reading((hh_ - c) / X, e["b"])
        assert _rms(rec.y - y) < 1.5 * rec.noise_std
        assert 1 - float(m32.psd_reading(1.0, e["b"])) == pytest.approx(e["comp"], abs=1e-12)
        # the bellows reach each phrase's target, shakes return to where they started
        for t0, T, _, b_, kind, _ in e["segs"]:
            k = np.searchsorted(rec.t, t0 + T + 0.02)
            if k < len(rec.t) and kind != "shake":
                assert e["x"][k] == pytest.approx(b_, abs=1e-9)
        # the detector moves the output by over 7 sigma beyond a gain and offset on the core (measured 9 ... 13)
        assert _linear_misfit(y, hh_) > 7 * rec.noise_std


# ---- delay: a wireless jitter buffer under a stamp mill ----

def test_wireless_jitter_buffer_under_stamp_mill():
    # the buffer against a loop over the samples (exact)
    r = np.random.default_rng(4)
    ts = np.cumsum(r.uniform(0.001, 0.002, 600))
    xs = np.sin(9 * ts) + ts
    arr = r.random(600) > 0.05
    arr[0] = True
    tq = np.linspace(0, 1, 777)
    got = m32.jitter_buffer(tq, ts, xs, arr, 0.007)
    ka, xa = ts[arr], xs[arr]
    ref = []
    for t in tq - 0.007:
        if t <= ka[0]:
            ref.append(xa[0])
        elif t >= ka[-1]:
            ref.append(xa[-1])
        else:
            i = max(i for i in range(len(ka)) if ka[i] <= t)
            ref.append(xa[i] + (xa[i + 1] - xa[i]) * (t - ka[i]) / (ka[i + 1] - ka[i]) if ka[i] < t else xa[i])
    np.testing.assert_allclose(got, ref, atol=1e-12)
    for seed in (0, 1, 2):
        rec = _rec(DELAY, seed)
        e = rec.extra
        R = e["R"]
        hf = _core(e, e["v_fine"])
        tf = np.arange(len(hf)) * rec.t[1] / R
        y = m32.jitter_buffer(rec.t, e["t_s"], np.interp(e["t_s"], tf, hf), e["arrived"], e["D"] * rec.t[1])
        assert _rms(rec.y - y) < 1.5 * rec.noise_std
        assert 2.6 <= e["D"] <= 4.4 and e["v_fine"].min() >= 0.0 and 0.95 < e["arrived"].mean() < 1.0
        # each stamp lands (the projectile's root: height 0 there, 1e-9) before the cam lifts it again
        for (t0, T_l, H, hold), nxt in zip(e["drops"], e["drops"][1:]):
            u, t_rel = s32.stamp_release(T_l, H, hold)
            s_land = (u + math.sqrt(u * u + 2 * e["g_fall"] * H)) / e["g_fall"]
            assert H + u * s_land - 0.5 * e["g_fall"] * s_land ** 2 == pytest.approx(0.0, abs=1e-9)
            assert t0 + t_rel + s_land < nxt[0]
        # the buffer moves the output by over 7 sigma beyond a gain and offset on the core (measured 34 ... 43)
        assert _linear_misfit(y, hf[::R]) > 7 * rec.noise_std


# ---- initial state: a hand-pushed guide under a skipping rope ----

def test_hand_pushed_guide_under_skipping_rope():
    for seed in (0, 1, 2):
        rec = _rec(INIT, seed)
        e = rec.extra
        model = _core(e, rec.v, state=e["state"])
        assert _rms(rec.y - model) < 1.5 * rec.noise_std
        assert rec.v[0] == 0.0 and abs(e["P1"]) > np.abs(rec.v).max()      # the push beyond the record's reach
        # the state against the law integrated in v along the hand's pushes from the virgin state (1e-8)
        knots = [0.0, e["P1"], e["P2"], e["P3"], 0.0]
        xk, Fk = _dahl_ivp(knots, e["K"], e["Fc"], e["sigma0"], e["a"])
        assert e["state"][0] == pytest.approx(xk[-1], abs=1e-8 * e["amp"])
        assert e["state"][1] == pytest.approx(Fk[-1], abs=1e-8 * e["Fc"])
        assert abs(e["state"][1]) > 0.3 * e["Fc"]                            # the friction left loaded
        # the handle stays within the wrists' circle
        assert np.abs(e["x"]).max() <= 1.0 + 1e-12
        # far from the same core started virgin (which, the record starting at 0 V, is also the core at rest at the
        # first input: x = F = 0): over 7 sigma beyond a gain and an offset (measured 29 ... 31)
        assert _linear_misfit(model, _core(e, rec.v)) > 7 * rec.noise_std


# ---- two effects: a vane in air and a walking operator under a launcher's gimbal ----

def test_vane_drag_and_walking_operator_under_launcher_gimbal():
    # the vane against solve_ivp of y' = sign(h - K y) sqrt(|h - K y| / c) (LSODA, rtol 1e-10; the midpoint steps'
    # error near the reversals, where the speed's square root is singular, 1e-5 of the span)
    dt = 1e-3
    tq = np.arange(4000) * dt
    hq = 30 * np.sin(2 * math.pi * 1.3 * tq) * np.exp(-((tq - 2) / 1.0) ** 2) + 10 * np.exp(-((tq - 1) / 0.1) ** 2)
    K, c = 1.3, 0.02

    def rhs(t, s):
        e = float(np.interp(t, tq, hq)) - K * s[0]
        return [math.copysign(math.sqrt(abs(e) / c), e)]
    sol = solve_ivp(rhs, (0, tq[-1]), [0.0], t_eval=tq, method="LSODA", rtol=1e-10, atol=1e-12, max_step=dt)
    got = m32.vane_drag_stage(hq, dt, K, c)
    np.testing.assert_allclose(got, sol.y[0], atol=1e-5 * np.ptp(got))
    # Boussinesq's settlement against his half-space solution's vertical displacement P / (4 pi G) (2 (1 - nu) / R +
    # z^2 / R^3) taken to the surface (1e-12 relative)
    Pl, E, nu = 800.0, 3e7, 0.3
    G = E / (2 * (1 + nu))
    for rr in (0.8, 1.5, 3.0):
        Rz = math.hypot(rr, 1e-9)
        uz = Pl / (4 * math.pi * G) * (2 * (1 - nu) / Rz + 1e-18 / Rz ** 3)
        assert float(m32.boussinesq_settlement(rr, Pl, E, nu)) == pytest.approx(uz, rel=1e-12)
    for seed in (0, 1, 2):
        rec = _rec(PAIR, seed)
        e = rec.extra
        hh = _core(e, rec.v)
        xs = m32.vane_drag_stage(hh, rec.t[1], e["K_v"], e["c_q"])
        y = xs + e["offset"]
        assert _rms(rec.y - y) < 1.5 * rec.noise_std
        assert np.abs(e["offset"]).max() == pytest.approx(e["mag"] * np.ptp(xs), rel=1e-9) and e["offset"][0] == 0.0
        # the operator never comes within 0.8 m of either pier
        for f in (e["foot_a"], e["foot_b"]):
            assert np.hypot(*(e["path"] - f).T).min() >= 0.8 - 1e-9
        # each effect beyond a gain and offset on the rest: the vane beyond the drifting core (measured 39 ... 49),
        # the settlement beyond the vane-dragged core (measured 14 ... 27)
        assert _linear_misfit(y, hh + e["offset"]) > 7 * rec.noise_std
        assert _linear_misfit(y, xs) > 7 * rec.noise_std


# ---- out of vocabulary: a slide-by Hall sensor under a weathervane ----

def test_slide_by_hall_magnet_under_weathervane():
    # the point dipole's field against Biot-Savart for a small current loop (radius a = d / 100, m = I pi a^2) by quad
    # around it: the normal component at the sensor (1e-3 relative: the loop's finite size, (a / d)^2 terms)
    d, a = 1.0, 0.01
    for x in (0.0, 0.5, 1.2, math.sqrt(2) + 0.3, 2.5):
        def dBz(phi):
            # the loop in the plane z = 0 about (x, 0, 0) seen from the sensor at (0, 0, d): dl x r / r^3, z part
            px, py = x + a * math.cos(phi), a * math.sin(phi)
            dlx, dly = -a * math.sin(phi), a * math.cos(phi)
            rx, ry, rz = -px, -py, d
            return (dlx * ry - dly * rx) / (rx * rx + ry * ry + rz * rz) ** 1.5
        bz = quad(dBz, 0, 2 * math.pi, epsabs=1e-15, limit=200)[0] / (4 * math.pi)   # mu0 I / (4 pi), mu0 I = 1
        dip = float(m32.slide_by_field(x, d)) * math.pi * a * a / (4 * math.pi)
        assert bz == pytest.approx(dip, rel=1e-3, abs=1e-3 * abs(float(m32.slide_by_field(0.0, d))) * a * a / 4)
    for seed in (0, 1, 2):
        rec = _rec(OOV, seed)
        e = rec.extra
        hh = _core(e, rec.v)
        model = m32.slide_by_field(hh - e["x_null"], e["d"]) * e["d"] ** 3
        assert _rms(rec.y - model) < 1.5 * rec.noise_std
        # the vane's yaw against an independent integration (Radau, rtol 1e-10) of its equation (1e-6)
        wind = _wind_of(e["wind"])
        sol = solve_ivp(s32.vane_rhs, (0, rec.t[-1]), [0.0, 0.0], t_eval=rec.t[::50], args=(e["k_vane"], e["c_vane"],
                        wind), method="Radau", rtol=1e-10, atol=1e-12, max_step=0.05)
        np.testing.assert_allclose(e["x"][::50], sol.y[0], atol=1e-6)
        # the sensor lies inside the travel, 30 ... 42 % from one end: the reading rises and falls along it
        f = (e["x_null"] - hh.min()) / np.ptp(hh)
        assert 0.29 < min(f, 1 - f) < 0.43
        # no monotone map of the core (isotonic regression, rising or falling: it takes in every saturation and
        # asymmetry) comes near the reading: over 30 sigma away (measured 228 ... 275)
        o = np.argsort(hh)
        ys = rec.y[o]
        miss = min(np.abs(ys - isotonic_regression(ys, increasing=inc).x).max() for inc in (True, False))
        assert miss > 30 * rec.noise_std


def _wind_of(p):
    """The wind of :func:`signals32.gusty_wind` rebuilt from its stored parameters."""
    def wind(t):
        U = 1.0 + float(np.sum(p["au"] * np.sin(2 * math.pi * p["fu"] * t + p["pu"])))
        psi = float(np.sum(p["ap"] * (np.sin(2 * math.pi * p["fp"] * t + p["pp"]) - np.sin(p["pp"]))))
        return U, psi
    return wind

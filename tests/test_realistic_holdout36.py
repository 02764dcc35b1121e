"""HOLDOUT36 (tests/realistic/cases_holdout36.py, laws in mechanisms36.py, signals in signals36.py): well formed, in
ALL (joined after its one measurement in round 38, 19 of 30 runs right), and every mechanism follows its law. Nothing here runs the diagnosis.

Tolerances: a record that is its stated law plus the sensor noise leaves a residual RMS within 1.5 sigma of the law (the
noise alone gives 1.0; the laws are evaluated on the clean drive). A law checked against an independent solution (an
exact solution on the Bethe lattice, a brute-force relaxation of the whole lattice, solve_ivp, brentq, a closed form, a
reflection written as vectors or a direct sum) agrees to the stated tolerance, set from the solvers' own tolerances, the
sampling statistics or the scheme's order (each stated beside it), far below sigma (2e-3 of the span). Effects are
asked to move the output by at least 7 sigma beyond what a gain and an offset on the core absorb (the initial state
against the same core started demagnetised); the measured values for seeds 0 ... 2 are stated beside each.
"""

import math
from functools import lru_cache

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.optimize import brentq, isotonic_regression
from scipy.stats import norm

from realistic import HOLDOUT36, family
from realistic import cases_holdout36 as c36
from realistic import mechanisms36 as m36
from realistic import signals36 as s36
from test_realistic_generator import (_assert_drives_start_at_zero, _assert_measured_set, _assert_set_layout,
                                      _assert_spans_and_rates, _linear_misfit, _rms)
from realistic.set_checks import pi_fit_rms as _pi_fit_rms

pytestmark = pytest.mark.slow

P = "holdout36_"
EFFECTS = {"creep", "rate_dependence", "drift", "asymmetry", "saturation", "initial_state", "delay"}
CLEAN = "clean_servo_torque_motor_sleep_spindles_1455hz"
CREEP = "creep_snoek_after_effect_cold_valve_balloon_flight_233hz"
RATE = "rate_aluminium_bobbin_shorted_turn_hand_whisk_1065hz"
DRIFT = "drift_tramway_stray_current_geyser_645hz"
ASYM = "asymmetry_reluctance_sensor_lc_oscillator_nystagmus_735hz"
SAT = "saturation_nozzle_flapper_pilot_pressure_dolphin_strokes_795hz"
DELAY = "delay_strobed_camera_pipeline_coughs_447hz"
INIT = "initial_state_spool_unsticking_routine_sneezes_1005hz"
PAIR = "pair_drift_asymmetry_oil_warmup_optical_lever_hammock_1265hz"
OOV = "oov_jfet_follower_phase_reversal_hand_plane_905hz"
UNIPOLAR = {CREEP, DRIFT, DELAY}
MONITORED = {CLEAN: 3e-4, RATE: 2.5e-4, SAT: 3e-4, DELAY: 2e-4}


@lru_cache(maxsize=None)
def _rec(name, seed):
    return HOLDOUT36[P + name](seed)


def _core(e, v, state=None):
    return c36._core_of(e, v, state=state)


def _seg(a, b, n=200):
    return np.linspace(a, b, n + 1)[1:]


# ---- independent references for the iron: the Bethe lattice's exact branch and a brute-force relaxation ----

def _dss_chain(H, R, J=1.0):
    """The ascending branch from all grains down of the zero-temperature RFIM on a Bethe lattice of coordination z = 2
    (a chain), Gaussian fields of spread R (Dhar, Shukla & Sethna, J. Phys. A 30 (1997) 5259, written here from their
    recursion): p_n the chance that a grain with n of its z neighbours up has a positive local field, P* = sum_n C(z-1,
    n) P*^n (1 - P*)^(z-1-n) p_n the chance that a neighbour is up with the grain held down (for z = 2: P* = p_0 / (1 -
    p_1 + p_0)), and the magnetisation 2 sum_n C(z, n) P*^n (1 - P*)^(z-n) p_n - 1."""
    p = [norm.sf((-H - J * (2 * n - 2)) / R) for n in range(3)]
    Ps = p[0] / (1.0 - p[1] + p[0])
    return 2.0 * ((1 - Ps) ** 2 * p[0] + 2 * Ps * (1 - Ps) * p[1] + Ps ** 2 * p[2]) - 1.0


def _relax(s, h, nb, J, field, sg):
    """Every grain at -sg whose local field at ``field`` has the sign sg flipped, the whole lattice at once, until none
    is left (the ferromagnetic coupling makes the order of the flips irrelevant)."""
    while True:
        f = field + h + J * s[nb].sum(axis=1)
        flip = (s == -sg) & (sg * f > 0.0)
        if not flip.any():
            return s
        s = s.copy()
        s[flip] = sg


def _solve_ref(T, a, b, s, q, h, nb, J):
    """One sample of the gapped iron written here by brute force: the grains' thresholds -h - J sum_j s_j recomputed
    over the whole lattice at every step; the nearest trigger beyond q fired (its grain flipped, the lattice relaxed at
    that field) unless the left side (1 + a) q + b m reaches T first, and undone (q stopping at the trigger) if it
    would carry the left side past T."""
    N = len(h)
    while True:
        M = s.sum()
        phi = (1.0 + a) * q + b * M / N
        if phi == T:
            return s, q
        sg = 1 if T > phi else -1
        root = (T - b * M / N) / (1.0 + a)
        thr = -h - J * s[nb].sum(axis=1)
        cand = np.nonzero((s == -sg) & (sg * (thr - q) >= -1e-9))[0]
        if len(cand) == 0:
            return s, root
        i = cand[np.argmin(sg * thr[cand])]
        t = thr[i]
        if sg * ((1.0 + a) * t + b * M / N - T) >= 0.0:
            return s, root
        s2 = s.copy()
        s2[i] = sg
        s2 = _relax(s2, h, nb, J, t, sg)
        if sg * ((1.0 + a) * t + b * s2.sum() / N - T) > 0.0:
            return s, t
        s, q = s2, t


def _gapped_ref(iron, state, Hd, k, chi):
    s, q = state[0].astype(int), state[2]
    out = []
    for T in Hd:
        s, q = _solve_ref(T, k * chi, k, s, q, iron["h"], iron["nb"].astype(int), iron["J"])
        out.append(s.sum() / len(s) + chi * q)
    return np.array(out), s, q


def _small_iron(L, R, seed):
    h = R * np.random.default_rng(seed).standard_normal(L ** 3)
    return m36.make_iron(m36.cubic_neighbours(L), h)


# ---- the set ----

def test_holdout36_is_well_formed_and_in_all():
    H = HOLDOUT36
    first = _assert_measured_set(H, P, EFFECTS)
    _assert_set_layout(H, P, first, _rec, MONITORED, others_carry_drive=True)
    assert len(family(EFFECTS)) == 7
    pair = first[P + PAIR]
    assert pair.expect_effects == {"drift", "asymmetry"} and pair.expect_verdict == "either"
    assert first[P + CLEAN].expect_verdict == "explained"
    assert first[P + OOV].expect_verdict == "unexplained"
    _assert_spans_and_rates(H, P, first, _rec, UNIPOLAR)
    _assert_drives_start_at_zero(H, P, _rec)


# ---- clean: a servo valve's torque motor (its iron a random-field Ising model), under the EEG of stage-2 sleep ----

def test_rfim_iron_against_the_bethe_lattice_and_a_brute_force_relaxation():
    # the ascending branch of a periodic chain of 10^6 grains (R = 1) from all down against Dhar, Shukla & Sethna's
    # exact branch on the Bethe lattice of coordination 2 (0.005: the sampling spread at 10^6 grains is about 0.001;
    # measured 0.0015 at most), by the sorted sweep and by the triggers' heap (the gapped solver with no gap) alike
    # (exactly), and the descending branch from all up the ascending one mirrored (measured 0.0020 at most)
    N, R = 1_000_000, 1.0
    iron = m36.make_iron(m36.chain_neighbours(N), R * np.random.default_rng(5).standard_normal(N))
    Hs = np.linspace(-2.5, 2.5, 21)
    m_up, st = m36.open_iron(iron, m36.saturated(iron, -1), Hs)
    B_up, st2 = m36.gapped_iron(iron, m36.saturated(iron, -1), Hs, 0.0, 0.0)
    np.testing.assert_allclose(m_up, _dss_chain(Hs, R), atol=0.005)
    np.testing.assert_array_equal(B_up, m_up)
    np.testing.assert_array_equal(st[0], st2[0])
    m_dn, _ = m36.open_iron(iron, m36.saturated(iron, 1), -Hs)
    np.testing.assert_allclose(m_dn, -_dss_chain(Hs, R), atol=0.005)
    # with no coupling every grain is the sign of q + h: no hysteresis (exactly)
    h = np.random.default_rng(6).standard_normal(8 ** 3) * 2.0
    iron0 = m36.make_iron(m36.cubic_neighbours(8), h, J=0.0)
    qs = np.r_[_seg(0, 3.0), _seg(3.0, -1.0), _seg(-1.0, 2.0), _seg(2.0, -3.5)]
    m0, _ = m36.open_iron(iron0, m36.saturated(iron0, -1), qs)
    np.testing.assert_array_equal(m0, np.sign(qs[:, None] + h[None, :]).mean(axis=1))
    # the gapped iron on a small lattice (6^3, R = 2.5: large avalanches, some held back) against the brute-force
    # relaxation written here, along a path with reversals, from the demagnetised state and from saturation (the flux
    # exactly; the iron's field to 1e-12)
    small = _small_iron(6, 2.5, 11)
    for st0 in (m36.demagnetise(small), m36.saturated(small, -1)):
        path = np.r_[_seg(0.0, 9.0, 60), _seg(9.0, -4.0, 60), _seg(-4.0, 6.0, 60), _seg(6.0, 1.0, 40)]
        B, stB, Q = m36.gapped_iron(small, st0, path, 3.0, 0.05, return_field=True)
        Bref, sref, qref = _gapped_ref(small, st0, path, 3.0, 0.05)
        np.testing.assert_allclose(B, Bref, atol=1e-12)
        np.testing.assert_array_equal(stB[0], sref)
        assert stB[2] == pytest.approx(qref, abs=1e-12)
        # the gap's law q + k B = H_d holds (1e-12) but where an avalanche was held back (on this coarse lattice with
        # its large avalanches, measured 62 ... 74 % of the samples)
        assert np.mean(np.abs(Q + 3.0 * B - path) < 1e-12) > 0.3


def test_clean_torque_motor_under_sleep_eeg():
    iron, st = m36.torque_motor_iron(64, 4.2, 2024)
    # the demagnetised iron: m within 1 % of 0
    assert abs(st[3]) / len(iron["h"]) < 0.01
    # rate independent: a path and the same path sampled 7 times as densely agree at the shared samples, one step
    # within a monotone stretch gives what many do, and a state carried over gives the same as one run (exactly)
    k, chi = 3.5, 0.05
    knots = [0.0, 6.0, -2.0, 4.5, -6.5, 3.0, -1.0, 0.0]
    Hd = np.concatenate([np.linspace(a, b, 150, endpoint=False) for a, b in zip(knots[:-1], knots[1:])] + [[0.0]])
    B, sB = m36.gapped_iron(iron, st, Hd, k, chi)
    H7 = np.interp(np.arange(7 * (len(Hd) - 1) + 1) / 7, np.arange(len(Hd)), Hd)
    np.testing.assert_array_equal(m36.gapped_iron(iron, st, H7, k, chi)[0][::7], B)
    Bk, sk = m36.gapped_iron(iron, st, knots, k, chi)
    np.testing.assert_array_equal(Bk[1:], B[::150][1:])
    np.testing.assert_array_equal(sk[0], sB[0])
    B1, s1 = m36.gapped_iron(iron, st, Hd[:500], k, chi)
    np.testing.assert_array_equal(np.r_[B1, m36.gapped_iron(iron, s1, Hd[500:], k, chi)[0]], B)
    # return-point memory: a minor loop from a reversal and back leaves the state it found (exactly)
    _, sa = m36.gapped_iron(iron, st, np.r_[_seg(0, 6.0), _seg(6.0, -2.5)], k, chi)
    Bl, sl = m36.gapped_iron(iron, sa, np.r_[_seg(-2.5, 1.5), _seg(1.5, -0.5), _seg(-0.5, 1.0), _seg(1.0, -2.5)], k,
                             chi)
    np.testing.assert_array_equal(sl[0], sa[0])
    assert sl[2] == sa[2]
    # not a Preisach model: on the open iron two minor loops between the same fields, formed after different histories
    # (down from +0.95 of the peak's field, or up from -0.95 of it), have ascending branches whose rises differ by over
    # 3 % of the rise (measured 7.8 and 8.3 %; a Preisach model's are congruent: its hysterons in the triangle between
    # the loop's ends are the only ones to move, all down at the loop's foot); the Preisach model written here (2000
    # random relays) on the same histories agrees to 1e-12
    q_pk = m36.virgin_field(iron, st, 0.62, 25.0)
    rng = np.random.default_rng(8)
    al = rng.uniform(-1.2, 1.2, 2000) * q_pk
    be = al - rng.uniform(0.0, 1.0, 2000) * q_pk

    def preisach(path):
        r = -np.ones(2000)
        out = []
        for x in path:
            r = np.where(x >= al, 1.0, np.where(x <= be, -1.0, r))
            out.append(r.mean())
        return np.array(out)
    worst = 0.0
    for fa, fb in ((0.1, 0.5), (-0.5, 0.0)):
        Ha, Hb = fa * q_pk, fb * q_pk
        loop = np.r_[_seg(Ha, Hb), _seg(Hb, Ha), _seg(Ha, Hb)]
        pA = np.r_[_seg(0, 0.95 * q_pk), _seg(0.95 * q_pk, Ha), loop]
        pB = np.r_[_seg(0, -0.95 * q_pk), _seg(-0.95 * q_pk, Hb), _seg(Hb, Ha), loop]
        rises = []
        for model in (lambda p: m36.open_iron(iron, st, p)[0], preisach):
            a, b = model(pA), model(pB)
            rises.append((a[-200:] - a[-201], b[-200:] - b[-201]))
        (ra, rb), (pa, pb) = rises
        worst = max(worst, np.abs(ra - rb).max() / max(ra[-1], rb[-1]))
        np.testing.assert_allclose(pa, pb, atol=1e-12)
    assert worst > 0.03
    for seed in (0, 1, 2):
        rec = _rec(CLEAN, seed)
        e = rec.extra
        model = _core(e, e["drive"]) + e["offset"]
        assert _rms(rec.y - model) < 1.5 * rec.noise_std
        assert 3.8 <= e["R"] <= 4.6 and 2.5 <= e["k"] <= 4.5 and 0.03 <= e["chi"] <= 0.08
        assert 0.55 <= e["m_pk"] <= 0.7
        # the drive's peak field takes the demagnetised iron to m_pk on its virgin curve (the gapped virgin curve
        # passes through the same states as the open one; 1e-3: the virgin ramp's step)
        ir, s0 = c36._iron_of(e)
        Bv, _ = m36.gapped_iron(ir, s0, np.linspace(0.0, e["H_pk"], 400), e["k"], e["chi"])
        assert Bv[-1] - e["chi"] * e["q_pk"] == pytest.approx(e["m_pk"], abs=1e-3)
        # the lattice's grain: the largest single avalanche along the major range of the open iron (steps of 2e-5) is
        # under 0.6 sigma of the record (measured 0.30 ... 0.46)
        qs = np.r_[np.arange(0.0, e["q_pk"], 2e-5), np.arange(e["q_pk"], -e["q_pk"], -2e-5)]
        mm, _ = m36.open_iron(ir, s0, qs)
        assert np.abs(np.diff(mm)).max() * e["gain"] < 0.6 * rec.noise_std
        # the EEG: at rest (exactly 0) before it fades in and after it fades out, spindles at 11 ... 15 Hz, one
        # K-complex at the full depth
        ev = e["events"]
        assert np.all(e["x"][(rec.t <= e["t_on"]) | (rec.t >= e["t_off"])] == 0.0)
        assert all(11.0 <= x[3] <= 15.0 for x in ev if x[0] == "spindle")
        sp = next(x for x in ev if x[0] == "spindle")            # one spindle alone: its zero crossings at its rate
        tt = np.linspace(sp[1], sp[1] + sp[2], 20001)
        xs = s36.sleep_eeg(tt, [sp], -10.0, 1e9)[1:-1]
        assert abs(np.sum(np.diff(np.sign(xs)) != 0) - 2 * sp[3] * sp[2]) <= 2
        assert sum(x[2] == 1.0 for x in ev if x[0] == "k") == 1
        # the core is far from a straight line (measured 72 ... 99 sigma) and close to a PI model: 12 plays of the
        # drive fitted by NNLS leave 0.69 ... 0.91 sigma RMS, at most 4.8 ... 6.1 sigma
        assert _linear_misfit(model, e["drive"]) > 20 * rec.noise_std
        rms, mx = _pi_fit_rms(model, e["drive"])
        assert 0.3 * rec.noise_std < rms < 3.0 * rec.noise_std and mx < 12 * rec.noise_std


# ---- creep: the diffusion after-effect of carbon and nitrogen in the armature's iron, under a hot-air balloon ----

def test_snoek_after_effect_under_balloon_flight():
    # the Snoek peak at 1 Hz: omega tau = 1 at the peak's temperature (1e-15); the cold valve's times in the stated
    # ranges (carbon 9 ... 36 s, nitrogen 1.4 ... 5 s at -5 ... 5 C)
    assert m36.snoek_tau(40.0, 40.0, 0.87) == pytest.approx(1 / (2 * math.pi), rel=1e-15)
    for T_c in (-5.0, 5.0):
        assert 9.0 <= m36.snoek_tau(T_c, 40.0, 0.87) <= 36.0 and 1.4 <= m36.snoek_tau(T_c, 25.0, 0.79) <= 5.0
    # the first-order-hold Debye lag against solve_ivp of tau w' = x - w with x linear between the samples, integrated
    # sample to sample (the input's kinks at the samples; DOP853, rtol 1e-12; 1e-10)
    dt, tau = 1 / 233, 0.9
    x = np.convolve(np.random.default_rng(4).uniform(-1, 1, 400), np.ones(8) / 8, mode="same")
    ref = [x[0]]
    for k in range(len(x) - 1):
        sol = solve_ivp(lambda t, w: [(x[k] + (x[k + 1] - x[k]) * t / dt - w[0]) / tau], (0.0, dt), [ref[-1]],
                        method="DOP853", rtol=1e-12, atol=1e-14)
        ref.append(sol.y[0, -1])
    np.testing.assert_allclose(m36.debye_lag(x, dt, tau), ref, atol=1e-10)
    # a step held 10 s: the seen flux creeps by sum c_j (1 - exp(-10 / tau_j)) of it (closed form; the step taken
    # over one sample of 1e-4 s, 1e-4 relative)
    dtf = 1e-4
    step = np.r_[0.0, np.ones(int(round(10.0 / dtf)))]
    y = m36.after_effect(step, dtf, (0.08, 0.05), (20.0, 3.0))
    creep = 0.08 * (1 - math.exp(-10 / 20.0)) + 0.05 * (1 - math.exp(-10 / 3.0))
    assert y[-1] - y[1] == pytest.approx(creep, rel=1e-4)
    for seed in (0, 1, 2):
        rec = _rec(CREEP, seed)
        e = rec.extra
        dt = rec.t[1]
        B = _core(e, rec.v) / e["gain"]
        np.testing.assert_array_equal(B, e["B"])
        y = e["gain"] * m36.after_effect(B, dt, (e["c_C"], e["c_N"]), (e["tau_C"], e["tau_N"]))
        assert _rms(rec.y - y) < 1.5 * rec.noise_std
        assert 0.05 <= e["c10"] <= 0.08 and -5.0 <= e["T_c"] <= 5.0
        assert e["c_C"] * (1 - math.exp(-10 / e["tau_C"])) + e["c_N"] * (1 - math.exp(-10 / e["tau_N"])) == \
            pytest.approx(e["c10"], rel=1e-12)
        # the flight: every level flight held exactly, from the ground and back to it; during the first level flight
        # after a climb the seen flux keeps rising (the held-back share following)
        p = e["p"]
        assert p[0] == 0.0 and p[-1] == 0.0
        times, vals = np.asarray(e["times"]), np.asarray(e["vals"])
        holds = [(a, b) for a, b, va, vb in zip(times[:-1], times[1:], vals[:-1], vals[1:]) if va == vb and va > 0]
        assert len(holds) >= 6
        a, b = holds[0]
        seg = (rec.t > a + 0.05) & (rec.t < b)
        assert np.ptp(p[seg]) == 0.0 and np.all(np.diff(y[seg]) > 0.0)
        # the after-effect moves the output by over 7 sigma beyond a gain and offset on the core (measured 19 ... 36)
        assert _linear_misfit(y, e["gain"] * B) > 7 * rec.noise_std


# ---- rate: the coils' aluminium bobbins (a shorted turn on the armature's flux), under a hand whisk ----

def _eddy_ref(iron, state, Hd, dt, k, chi, kappa, tau, sub):
    """The trapezoidal stepping written here on the brute-force solver: per sub-step the bobbin's current from the
    flux's change, i_new = ((tau - h / 2) i_old - kappa (B_new - B_old)) / (tau + h / 2), and the iron's field solving
    q + (k + g) B = H_d + ((tau - h / 2) i_old + kappa B_old) / (tau + h / 2), g = kappa / (tau + h / 2)."""
    Hf = np.interp(np.arange((len(Hd) - 1) * sub + 1) / sub, np.arange(len(Hd)), Hd)
    s, q = state[0].astype(int), state[2]
    N = len(s)
    hstep = dt / sub
    tp, tm = tau + hstep / 2, tau - hstep / 2
    g = kappa / tp
    Bo, io = s.sum() / N + chi * q, 0.0
    out = []
    for H in Hf:
        s, q = _solve_ref(H + (tm * io + kappa * Bo) / tp, (k + g) * chi, k + g, s, q, iron["h"],
                          iron["nb"].astype(int), iron["J"])
        Bn = s.sum() / N + chi * q
        io = (tm * io - kappa * (Bn - Bo)) / tp
        Bo = Bn
        out.append(Bn)
    return np.array(out)[::sub]


def test_bobbin_shorted_turn_under_hand_whisk():
    # the stepping against the trapezoidal rule on the brute-force solver written here, on a small lattice (6^3, R =
    # 2.5) along a path with reversals (1e-12: the same arithmetic on the same events)
    small = _small_iron(6, 2.5, 12)
    st = m36.demagnetise(small)
    dt = 1 / 1065
    Hd = 8.0 * np.sin(2 * math.pi * 9 * np.arange(120) * dt) * np.sin(2 * math.pi * 2.5 * np.arange(120) * dt)
    got = m36.bobbin_eddy_iron(small, st, Hd, dt, 3.0, 0.05, 3.0 * 3e-3, 1e-3, sub=4)
    np.testing.assert_allclose(got, _eddy_ref(small, st, Hd, dt, 3.0, 0.05, 3.0 * 3e-3, 1e-3, 4), atol=1e-12)
    # with the drive held the bobbin's current dies away (its own L / R: under 1e-6 of its largest 40 samples on)
    _, cur = m36.bobbin_eddy_iron(small, st, np.r_[np.linspace(0, 6.0, 40), np.full(80, 6.0)], dt, 3.0, 0.05,
                                  3.0 * 3e-3, 1e-3, sub=8, return_current=True)
    assert np.abs(cur[80:]).max() < 1e-6 * np.abs(cur).max()
    for seed in (0, 1, 2):
        rec = _rec(RATE, seed)
        e = rec.extra
        dt = rec.t[1]
        iron, st = c36._iron_of(e)
        y = e["gain"] * m36.bobbin_eddy_iron(iron, st, e["drive"] / e["V_H"], dt, e["k"], e["chi"], e["kappa"],
                                             e["tau_s"])
        assert _rms(rec.y - y) < 1.5 * rec.noise_std
        assert 0.5e-3 <= e["tau_s"] <= 1.5e-3 and 2e-3 <= e["tau_e"] <= 5e-3
        h = _core(e, e["drive"])
        if seed == 0:
            # the scheme: 16 sub-steps a sample against 64 differ by under 0.05 sigma RMS (measured 0.005) and at most
            # by about one avalanche held back at another instant (under 0.5 sigma; measured 0.23)
            y64 = e["gain"] * m36.bobbin_eddy_iron(iron, st, e["drive"] / e["V_H"], dt, e["k"], e["chi"],
                                                   e["kappa"], e["tau_s"], sub=64)
            assert _rms(y64 - y) < 0.05 * rec.noise_std and np.abs(y64 - y).max() < 0.5 * rec.noise_std
            # a damping: the departure from the static core falls with the rate: tenfold slower, at least fivefold
            # less on the record's first 8000 samples (measured 8.3-fold)
            v = e["drive"][:8000]
            dev = []
            for slow in (1, 10):
                vs = np.interp(np.arange((len(v) - 1) * slow + 1) / slow, np.arange(len(v)), v)
                ys = m36.bobbin_eddy_iron(iron, st, vs / e["V_H"], dt, e["k"], e["chi"], e["kappa"], e["tau_s"])
                dev.append(np.abs(e["gain"] * ys[::slow] - h[:8000]).max())
            assert dev[1] < dev[0] / 5
        # the whisk is lifted out (at 0) between the bouts and goes both ways
        for (t0, T, *_), (t1, *_) in zip(e["bouts"][:-1], e["bouts"][1:]):
            assert e["x"][np.searchsorted(rec.t, (t0 + T + t1) / 2)] == 0.0
        assert e["x"].max() > 0.85 * np.abs(e["x"]).max() and e["x"].min() < -0.85 * np.abs(e["x"]).max()
        # the shorted turn moves the output by over 7 sigma beyond a gain and offset on the core (measured 28 ... 60)
        assert _linear_misfit(y, h) > 7 * rec.noise_std


# ---- drift: a DC tramway's stray current lifting the laboratory's ground, under a geyser ----

def test_tramway_stray_current_under_geyser():
    # a tram's current after notching against solve_ivp of the series motors' decay di/ds = -(i - I_c) / tau_m, and its
    # share of the rail against solve_ivp of its run dx/ds = a s (DOP853, rtol 1e-12; 1e-9)
    t0, ramp, I_s, t_n, I_c, tau_m, run, acc, lam = 1.0, 0.4, 1.0, 2.0, 0.35, 1.7, 8.0, 1.2, 9.0
    tq = np.linspace(t0 + t_n, t0 + run - ramp - 1e-9, 400)
    sol = solve_ivp(lambda s, y: [-(y[0] - I_c) / tau_m, acc * s], (t_n, run - ramp), [I_s, 0.5 * acc * t_n ** 2],
                    t_eval=tq - t0, method="DOP853", rtol=1e-12, atol=1e-14)
    np.testing.assert_allclose(m36.tram_current(tq, t0, ramp, I_s, t_n, I_c, tau_m, run), sol.y[0], atol=1e-9)
    np.testing.assert_allclose(m36.tram_offset(tq, [(t0, ramp, I_s, t_n, I_c, tau_m, run, acc, -1.0)], lam),
                               -sol.y[0] * np.exp(-sol.y[1] / lam), atol=1e-9)
    assert m36.tram_offset(np.array([t0 - 0.5, t0 + run + 0.5]), [(t0, ramp, I_s, t_n, I_c, tau_m, run, acc, 1.0)],
                           lam).tolist() == [0.0, 0.0]
    for seed in (0, 1, 2):
        rec = _rec(DRIFT, seed)
        e = rec.extra
        h = _core(e, rec.v)
        np.testing.assert_array_equal(h, e["h"])
        assert _rms(rec.y - h - e["offset"]) < 1.5 * rec.noise_std
        np.testing.assert_array_equal(m36.tram_offset(rec.t, e["trams"], e["lam"]), e["pot"])
        off = e["offset"]
        assert off[0] == 0.0 and np.abs(off).max() == pytest.approx(e["mag"] * np.ptp(h), rel=1e-12)
        assert 2 <= len(e["trams"]) <= 4
        # the geyser: quiet (exactly 0) for much of the record between its eruptions, every eruption to at least 0.75
        # of the highest
        p = e["p"]
        assert p[0] == 0.0 and p[-1] == 0.0 and np.mean(p == 0.0) > 0.25
        assert max(e["vals"]) == 1.0
        # the drift moves the output by over 7 sigma beyond a gain and offset on the core (measured 31 ... 39)
        assert _linear_misfit(h + off, h) > 7 * rec.noise_std


# ---- asymmetry: a variable-reluctance proximity sensor in an LC oscillator, under optokinetic nystagmus ----

def test_reluctance_sensor_under_nystagmus():
    # the oscillator: a tank whose inductance is the gap's, L = L0 / g, by solve_ivp of L C v'' + v = 0 over 20 periods
    # (the period from the last upward zero crossing; DOP853, rtol 1e-12): its frequency sqrt(g) times the rest gap's
    # (1e-7 relative)
    for g in (0.7, 1.0, 1.3):
        Lg = 1.0 / g
        sol = solve_ivp(lambda t, y: [y[1], -y[0] / Lg], (0.0, 20 * 2 * math.pi * math.sqrt(Lg) + 1.0), [0.0, 1.0],
                        method="DOP853", rtol=1e-12, atol=1e-14, dense_output=True)
        T_est = 2 * math.pi * math.sqrt(Lg)
        t20 = brentq(lambda t: sol.sol(t)[0], 20 * T_est - 0.25 * T_est, 20 * T_est + 0.25 * T_est, xtol=1e-14)
        assert (20 / t20) / (1 / (2 * math.pi)) == pytest.approx(float(m36.reluctance_frequency(g)), rel=1e-7)
    # the reading: slope 1 at 0 (central differences, 1e-8) and the ends' secants a apart (1e-12)
    for seed in (0, 1, 2):
        e = _rec(ASYM, seed).extra
        assert float(m36.reluctance_reading(1e-6, e["r"]) - m36.reluctance_reading(-1e-6, e["r"])) / 2e-6 == \
            pytest.approx(1.0, abs=1e-8)
        assert float(m36.reluctance_reading(1.0, e["r"]) + m36.reluctance_reading(-1.0, e["r"])) == \
            pytest.approx(e["a"], abs=1e-12)
    for seed in (0, 1, 2):
        rec = _rec(ASYM, seed)
        e = rec.extra
        h = _core(e, rec.v)
        c, X = e["centre"], e["X"]
        y = c + e["side"] * X * m36.reluctance_reading(e["side"] * (h - c) / X, e["r"])
        assert _rms(rec.y - y) < 1.5 * rec.noise_std
        assert 0.10 <= e["a"] <= 0.17 and 0.0 < e["r"] < 0.99
        # the eye: slow phases at constant speeds (the path linear between its points), both ways, fixating the centre
        # (exactly 0) between the trials
        x = e["x"]
        assert x.max() > 0.85 * np.abs(x).max() and x.min() < -0.85 * np.abs(x).max()
        tt, vv = np.asarray(e["times"]), np.asarray(e["vals"])
        np.testing.assert_allclose(x, np.interp(rec.t, tt, vv) / np.abs(vv).max(), atol=1e-12)
        assert np.mean(x == 0.0) > 0.05
        # the sensor moves the output by over 7 sigma beyond a gain and offset on the core (measured 14 ... 19)
        assert _linear_misfit(y, h) > 7 * rec.noise_std


# ---- saturation: the pilot stage's differential pressure (a double nozzle-flapper), under a dolphin's strokes ----

def test_pilot_pressure_under_dolphin_strokes():
    # a nozzle's back pressure against brentq of its continuity, (1 - p) a_o^2 = p (pi d_n g)^2 (1e-12), the pilot's
    # slope at 0 against central differences (1e-8), its oddness (1e-15) and its rise across the stroke
    for g, gc in ((0.3, 1.0), (1.0, 0.8), (2.2, 1.5)):
        p = brentq(lambda pp: (1 - pp) * gc ** 2 - pp * g ** 2, 0.0, 1.0, xtol=1e-15)
        assert float(m36.nozzle_back_pressure(g, gc)) == pytest.approx(p, abs=1e-12)
    for beta in (0.5, 0.75):
        assert float(m36.pilot_pressure(1e-5, beta) - m36.pilot_pressure(-1e-5, beta)) / 2e-5 == pytest.approx(
            m36.pilot_slope(beta), abs=1e-8)
        xs = np.linspace(-0.95, 0.95, 77)
        np.testing.assert_allclose(m36.pilot_pressure(xs, beta), -m36.pilot_pressure(-xs, beta), atol=1e-15)
        assert np.all(np.diff(m36.pilot_pressure(xs, beta)) > 0)
    for seed in (0, 1, 2):
        rec = _rec(SAT, seed)
        e = rec.extra
        h = _core(e, e["drive"])
        c, X = e["centre"], e["X"]
        y = c + X * m36.pilot_reading((h - c) / X, e["stroke"], e["beta"])
        assert _rms(rec.y - y) < 1.5 * rec.noise_std
        assert 1 - float(m36.pilot_reading(1.0, e["stroke"], e["beta"])) == pytest.approx(e["comp"], abs=1e-12)
        assert 0.10 <= e["comp"] <= 0.17 and 0.5 <= e["beta"] <= 0.75 and e["stroke"] < 0.95
        # the flukes: still (exactly 0) in the glides and leaps, both ways
        x = e["x"]
        assert np.mean(x == 0.0) > 0.05
        assert x.max() > 0.85 * np.abs(x).max() and x.min() < -0.85 * np.abs(x).max()
        # the pilot moves the output by over 7 sigma beyond a gain and offset on the core (measured 14 ... 21)
        assert _linear_misfit(y, h) > 7 * rec.noise_std


# ---- delay: a strobed camera's fixed pipeline, under bouts of coughing ----

def test_camera_pipeline_under_coughs():
    # the reading is the travel on the frames' grid M frames earlier: for a smooth travel it is that travel delayed by
    # M / R record samples (closed form, 1e-12), held at its first value until the first frame arrives
    for R, M in ((6, 17), (8, 45), (10, 26)):
        dt = 1 / 447
        tf = np.arange(3000 * R + 1) * (dt / R)
        hf = np.sin(2 * math.pi * 2.3 * tf + 0.4) + 0.3 * np.cos(2 * math.pi * 7.0 * tf)
        got = m36.camera_pipeline(hf, R, M)
        t = tf[::R] - M * dt / R
        ref = np.sin(2 * math.pi * 2.3 * t + 0.4) + 0.3 * np.cos(2 * math.pi * 7.0 * t)
        k0 = math.ceil(M / R)
        np.testing.assert_allclose(got[k0:], ref[k0:], atol=1e-12)
        assert np.all(got[:k0] == hf[0])
    for seed in (0, 1, 2):
        rec = _rec(DELAY, seed)
        e = rec.extra
        R, M = e["frames"], e["M"]
        assert R in (6, 8, 10) and 3.8 <= e["R"] <= 4.6           # the frames a sample; the iron's disorder
        hf = _core(e, e["v_fine"])
        y = m36.camera_pipeline(hf, R, M)
        assert _rms(rec.y - y) < 1.5 * rec.noise_std
        assert e["lag"] == M / R and 2.5 <= e["lag"] <= 6.0
        np.testing.assert_array_equal(e["v_fine"][::R], e["drive"])
        # a dead time, no filter: every reading is one of the travel's own values, unsmoothed
        assert np.isin(y, hf).all()
        # the coughs: each bout's coughs from a smaller lung volume, one peak the largest
        pk = [cg[3] for cg in e["coughs"]]
        assert max(pk) == 1.0 and np.abs(e["v_fine"]).max() == pytest.approx(e["top"], rel=1e-12)
        # the camera moves the output by over 7 sigma beyond a gain and offset on the core (measured 141 ... 151)
        assert _linear_misfit(y, hf[::R]) > 7 * rec.noise_std


# ---- initial state: a servo amplifier's spool-unsticking routine, then a series of sneezes ----

def test_unsticking_routine_then_sneezes():
    path = m36.unsticking_routine(2.0, 5, 3, 2, n_per=4)
    ext = [path[i] for i in range(1, len(path) - 1) if abs(path[i]) > abs(path[i - 1]) and abs(path[i]) >=
           abs(path[i + 1]) and path[i] != 0.0]
    assert ext == [2.0, -4.0, 6.0, -8.0, 10.0] and path[0] == 0.0 and path[-1] == 0.0
    for seed in (0, 1, 2):
        rec = _rec(INIT, seed)
        e = rec.extra
        model = _core(e, rec.v, state=e["state"])
        assert _rms(rec.y - model) < 1.5 * rec.noise_std
        assert rec.v[0] == 0.0 and 4 <= e["n_pulses"] <= 7
        assert 0.5 * e["amp"] <= e["biggest"] <= 0.8 * e["amp"]
        assert np.abs(e["hist"]).max() == pytest.approx(e["biggest"], rel=1e-12)
        # the routine re-played from its path leaves the stored state, and so do its turning points alone (rate
        # independence; exactly)
        hist = e["hist"]
        _, st = c36._core_of(e, hist, return_state=True)
        np.testing.assert_array_equal(st[0], e["state"][0])
        hh = hist[np.r_[True, np.diff(hist) != 0]]                  # the holds dropped
        turns = [hh[0]] + [hh[i] for i in range(1, len(hh) - 1) if (hh[i] - hh[i - 1]) * (hh[i + 1] - hh[i]) < 0] \
            + [hh[-1]]
        _, st2 = c36._core_of(e, np.array(turns), return_state=True)
        np.testing.assert_array_equal(st2[0], e["state"][0])
        # the sneezes: every expulsion after its inspirations, which grow; the record's first breath small
        ph = e["phases"]
        assert ph[0][0] == "in" and -ph[0][3] < 0.5
        for i, p in enumerate(ph):
            if p[0] == "in" and i + 1 < len(ph) and ph[i + 1][0] == "in":
                assert -ph[i + 1][3] >= -p[3]
        # far from the same core started demagnetised: over 7 sigma beyond a gain and an offset, and moderate (measured
        # 28 ... 51)
        dev = _linear_misfit(model, _core(e, rec.v))
        assert 7 * rec.noise_std < dev < 100 * rec.noise_std


# ---- two effects: the oil warming (a null shift) and an optical lever at an oblique angle, under a hammock ----

def test_oil_warmup_and_optical_lever_under_hammock():
    # the warm-up against solve_ivp of the two-node network (DOP853, rtol 1e-12; 1e-9 of the largest temperature)
    A = m36.oil_network(35.0, 250.0, 3.0)
    tq = np.linspace(0.0, 400.0, 801)
    sol = solve_ivp(lambda t, T: A @ T + np.array([1.0, 0.0]), (0.0, 410.0), [0.0, 0.0], t_eval=tq + 10.0,
                    method="DOP853", rtol=1e-12, atol=1e-14)
    np.testing.assert_allclose(m36.oil_warmup(tq, 10.0, A), sol.y[0], atol=1e-9 * sol.y[0].max())
    # the lever against the reflection written as vectors: the beam d reflected by a mirror whose normal is turned by
    # theta (r = d - 2 (d.n) n) meets a scale at the distance D at D tan(phi0 + 2 theta) from the foot of its normal
    # (1e-12)
    D, phi0 = 1.7, 0.6
    for th in (-0.04, 0.0, 0.03):
        n = np.array([math.cos(phi0 / 2 + th), math.sin(phi0 / 2 + th)])
        d = np.array([-1.0, 0.0])
        r = d - 2 * (d @ n) * n
        assert D * r[1] / r[0] == pytest.approx(D * math.tan(phi0 + 2 * th), abs=1e-12)
    for seed in (0, 1, 2):
        e = _rec(PAIR, seed).extra
        assert float(m36.optical_lever(1e-6, e["phi0"], e["dphi"]) - m36.optical_lever(-1e-6, e["phi0"],
                                                                                        e["dphi"])) / 2e-6 == \
            pytest.approx(1.0, abs=1e-8)
        assert float(m36.optical_lever(1.0, e["phi0"], e["dphi"]) + m36.optical_lever(-1.0, e["phi0"], e["dphi"])) \
            == pytest.approx(e["a"], abs=1e-12)
    for seed in (0, 1, 2):
        rec = _rec(PAIR, seed)
        e = rec.extra
        h = _core(e, rec.v)
        c, X = e["centre"], e["X"]
        z = c + e["side"] * X * m36.optical_lever(e["side"] * (h - c) / X, e["phi0"], e["dphi"])
        w = m36.oil_warmup(rec.t, e["t_on"], m36.oil_network(e["tau_x"], e["tau_a"], e["ratio"]))
        off = e["side2"] * e["mag"] * np.ptp(h) * (w - w[0]) / (w[-1] - w[0])
        assert _rms(rec.y - z - off) < 1.5 * rec.noise_std
        assert off[0] == 0.0 and abs(off[-1]) == pytest.approx(e["mag"] * np.ptp(h), rel=1e-12)
        assert np.all(np.diff(w) > 0)                                        # the oil only warms
        assert 0.10 <= e["a"] <= 0.17 and 0.5 <= e["phi0"] <= 0.8
        # the hammock swings both ways, each extreme on the other side of the last, at rest at either end
        vv = np.asarray(e["vals"])
        ext = vv[2:-2]
        assert np.all(np.sign(ext[1:]) == -np.sign(ext[:-1])) and e["x"][0] == 0.0 and e["x"][-1] == 0.0
        # each effect beyond a gain and an offset on the rest: the warming beyond the lever's reading (measured 12
        # ... 18), the lever beyond the core with the warming (measured 13 ... 19)
        assert _linear_misfit(z + off, z) > 7 * rec.noise_std
        assert _linear_misfit(z + off, h + off) > 7 * rec.noise_std


# ---- out of vocabulary: a JFET op-amp follower's phase reversal, under a hand plane's strokes ----

def test_phase_reversal_under_hand_plane():
    # the follower: the input itself above the common-mode limit, the rail below it less its transition (exactly)
    xs = np.linspace(0.0, 1.0, 1001)
    out = m36.phase_reversal(xs, 0.15, 0.02, 1.1)
    np.testing.assert_array_equal(out[xs >= 0.15], xs[xs >= 0.15])
    np.testing.assert_array_equal(out[xs <= 0.13], np.full((xs <= 0.13).sum(), 1.1))
    for seed in (0, 1, 2):
        rec = _rec(OOV, seed)
        e = rec.extra
        h = _core(e, rec.v)
        y = np.ptp(h) * m36.phase_reversal(e["u"], e["x_c"], e["width"], e["rail"]) + e["offset"]
        assert _rms(rec.y - y) < 1.5 * rec.noise_std
        assert 0.1 <= e["x_c"] <= 0.2 and e["u"].min() == 0.0 and e["u"].max() == pytest.approx(1.0, abs=1e-12)
        # the plane's strokes reach both ends of the board; it rests at the middle (exactly 0) between boards
        x = e["x"]
        assert x.max() > 0.85 * np.abs(x).max() and x.min() < -0.85 * np.abs(x).max() and x[0] == 0.0
        # the reversed stretch: over a tenth of the samples folded to the rail (measured 13 ... 22 %)
        assert np.mean(e["u"] < e["x_c"]) > 0.1
        # no monotone map of the core (isotonic regression, rising or falling: it takes in every saturation and
        # asymmetry) comes near the reading: over 15 sigma away (measured 238 ... 256)
        o = np.argsort(h)
        ys = rec.y[o]
        miss = min(np.abs(ys - isotonic_regression(ys, increasing=inc).x).max() for inc in (True, False))
        assert miss > 15 * rec.noise_std

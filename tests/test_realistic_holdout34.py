"""HOLDOUT34 (tests/realistic/cases_holdout34.py, laws in mechanisms34.py, signals in signals34.py): well formed, in
ALL (joined after its one measurement in round 36, 7 of 30 runs right), and every mechanism follows its law. Nothing here runs the diagnosis.

Tolerances: a record that is its stated law plus the sensor noise leaves a residual RMS within 1.5 sigma of the law (the
noise alone gives 1.0; the laws are evaluated on the clean drive). A law checked against an independent solution
(solve_ivp, quad, brentq, a per-pad loop, a closed form, the transfer function applied by FFT, lfilter or a direct
sum) agrees to the stated tolerance, set from the solvers' own tolerances or the scheme's order (each stated beside
it), far below sigma (2e-3 of the span). Effects are asked to move the output by at least 7 sigma beyond what a gain
and an offset on the core absorb (the initial state against the same core started virgin); the measured values for
seeds 0 ... 2 are stated beside each.
"""

import math
from functools import lru_cache

import numpy as np
import pytest
from scipy.integrate import quad, solve_ivp
from scipy.optimize import brentq, isotonic_regression
from scipy.signal import lfilter

from realistic import HOLDOUT34, family
from realistic import cases_holdout34 as c34
from realistic import mechanisms34 as m34
from realistic import signals34 as s34
from test_realistic_generator import (_assert_drives_start_at_zero, _assert_measured_set, _assert_set_layout,
                                      _assert_spans_and_rates, _linear_misfit, _rms)
from realistic.set_checks import pi_fit_rms as _pi_fit_rms

pytestmark = pytest.mark.slow

P = "holdout34_"
EFFECTS = {"creep", "rate_dependence", "drift", "asymmetry", "saturation", "initial_state", "delay", "gain_drift"}
CLEAN = "clean_gent_pads_washing_machine_agitator_1785hz"
CREEP = "creep_andrade_lead_shim_sit_stand_desk_241hz"
RATE = "rate_rebound_valved_damper_stop_and_go_pedal_1595hz"
DRIFT = "drift_sand_leg_compaction_serpenoid_snake_612hz"
ASYM = "asymmetry_cds_photoresistor_tug_of_war_1145hz"
SAT = "saturation_oil_bulged_membrane_windsurf_pumping_767hz"
DELAY = "delay_ema_smart_sensor_pogo_stick_451hz"
INIT = "initial_state_estop_swept_sine_slow_waltz_968hz"
PAIR = "pair_gain_drift_saturation_hene_mode_sweep_diode_tia_cocktail_shaker_1215hz"
OOV = "oov_tomlinson_detent_follower_hula_hoop_1385hz"
UNIPOLAR = {CREEP, RATE, DELAY}
MONITORED = {CLEAN: 3e-4, RATE: 2.5e-4, SAT: 3e-4, DELAY: 2e-4}


@lru_cache(maxsize=None)
def _rec(name, seed):
    return HOLDOUT34[P + name](seed)


def _core(e, v, state=None):
    return c34._core_of(e, v, state=state)


# ---- an independent reference for the pad bed: a per-pad loop with brentq at every sample ----

def _bed_ref(F, w, gs, Jm, kf, e0=None, x0=0.0):
    e = np.zeros(len(w)) if e0 is None else np.array(e0, float)
    x = x0
    out = []
    for f in F:
        def g(xn):
            s = np.clip(e + (xn - x), -gs, gs)
            return kf * xn + float(np.sum(w * s * Jm / (Jm - s * s))) - f
        span = abs(g(x)) / kf + 1e-12
        xn = brentq(g, x - span, x + span, xtol=1e-15, rtol=1e-15) if g(x) != 0 else x
        e = np.clip(e + (xn - x), -gs, gs)
        x = xn
        out.append(x)
    return np.array(out), e, x


# ---- the set ----

def test_holdout34_is_well_formed_and_in_all():
    H = HOLDOUT34
    first = _assert_measured_set(H, P, EFFECTS)
    _assert_set_layout(H, P, first, _rec, MONITORED, others_carry_drive=True)
    assert len(family(EFFECTS)) == 7
    pair = first[P + PAIR]
    assert pair.expect_effects == {"gain_drift", "saturation"} and pair.expect_verdict == "either"
    assert first[P + CLEAN].expect_verdict == "explained"
    assert first[P + OOV].expect_verdict == "unexplained"
    _assert_spans_and_rates(H, P, first, _rec, UNIPOLAR)
    _assert_drives_start_at_zero(H, P, _rec)


# ---- clean: Gent rubber pads that stick and slip, under a washing machine's agitator ----

def test_clean_gent_pads_under_washing_machine_agitator():
    # Gent's shear stress is the derivative of his energy written from the first invariant of the simple-shear
    # deformation gradient (numpy's trace of F F^T; central differences, 1e-7)
    Jm = 3.0
    for gam in (-1.2, -0.4, 0.1, 0.9, 1.5):
        def W(g):
            Fd = np.array([[1.0, g, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]])
            return -0.5 * Jm * math.log(1 - (np.trace(Fd @ Fd.T) - 3) / Jm)
        hh = 1e-5
        assert float(m34.gent_shear(gam, Jm)) == pytest.approx((W(gam + hh) - W(gam - hh)) / (2 * hh), abs=1e-7)
        assert float(m34.gent_energy(gam, Jm)) == pytest.approx(W(gam), abs=1e-12)
    # the bed against a per-pad loop (brentq for the travel at every sample, each pad's strain clipped at its slip
    # strain) along a path with reversals, from the virgin state and from a carried-over one (1e-12: both solve to
    # the last bits)
    r = np.random.default_rng(3)
    bed = dict(w=r.dirichlet(np.ones(5)), gs=np.sort(r.uniform(0.4, 1.6, 5)), Jm=4.0)
    kf = 0.35
    knots = [0.0, 0.9, -0.3, 1.8, -1.1, 0.5, -2.0, 1.0, 0.0]
    Fq = np.concatenate([np.linspace(a, b, 30, endpoint=False) for a, b in zip(knots[:-1], knots[1:])] + [[0.0]])
    got, st = m34.pad_stage(Fq, bed, kf, return_state=True)
    ref, e_ref, x_ref = _bed_ref(Fq, bed["w"], bed["gs"], bed["Jm"], kf)
    np.testing.assert_allclose(got, ref, atol=1e-12)
    np.testing.assert_allclose(st[0], e_ref, atol=1e-12)
    np.testing.assert_allclose(m34.pad_stage(Fq[::-1], bed, kf, state=st),
                               _bed_ref(Fq[::-1], bed["w"], bed["gs"], bed["Jm"], kf, e_ref, x_ref)[0], atol=1e-12)
    # rate independent (the path sampled 1x and 7x as densely agrees at the shared samples), a state carried over gives
    # the same as one run, and return-point memory: a minor loop from a reversal and back returns exactly (1e-12)
    bed = m34.pad_bed(64, 1.0, 0.45, 0.65)
    pts = [0.0, 1.6, -0.5, 0.9, -1.7, 0.7, 0.0]
    F = np.concatenate([np.linspace(a, b, 300, endpoint=False) for a, b in zip(pts[:-1], pts[1:])] + [[0.0]])
    x, st = m34.pad_stage(F, bed, 0.4, return_state=True)
    F7 = np.interp(np.arange(7 * (len(F) - 1) + 1) / 7, np.arange(len(F)), F)
    np.testing.assert_allclose(m34.pad_stage(F7, bed, 0.4)[::7], x, atol=1e-12)
    x1, st1 = m34.pad_stage(F[:1000], bed, 0.4, return_state=True)
    np.testing.assert_allclose(np.r_[x1, m34.pad_stage(F[1000:], bed, 0.4, state=st1)], x, atol=1e-12)
    loop = np.r_[np.linspace(1.6, -0.4, 200), np.linspace(-0.4, 0.8, 200)[1:], np.linspace(0.8, -0.4, 200)[1:]]
    xl = m34.pad_stage(np.r_[np.linspace(0, 1.6, 200), loop], bed, 0.4)
    assert xl[399] == pytest.approx(xl[-1], abs=1e-12)
    # not a Prandtl-Ishlinskii core: the first descending branch is not Masing's (the reversal's value less twice the
    # virgin curve at half the distance from the reversal), off by over 2 % of the travel's span, while the same bed of
    # linear pads (J_m -> infinity) follows Masing's rule (1e-9)
    up = np.linspace(0.0, 1.6, 401)
    dn = np.linspace(1.6, -1.6, 801)[1:]
    for lin, bad in ((False, True), (True, False)):
        b = dict(bed, Jm=1e12) if lin else bed
        xv = m34.pad_stage(np.r_[up, dn], b, 0.4)
        masing = xv[400] - 2 * m34.pad_stage((1.6 - dn) / 2, b, 0.4)     # the virgin curve at the half distances
        if bad:
            assert np.abs(xv[401:] - masing).max() > 0.02 * np.ptp(xv)
        else:
            np.testing.assert_allclose(xv[401:], masing, atol=1e-9)
    for seed in (0, 1, 2):
        rec = _rec(CLEAN, seed)
        e = rec.extra
        model = _core(e, e["drive"]) + e["offset"]
        assert _rms(rec.y - model) < 1.5 * rec.noise_std
        # the agitator is at rest between its bouts (exactly 0 midway between them) and rocks to both sides
        for (t0, T, *_), (t1, *_) in zip(e["bouts"][:-1], e["bouts"][1:]):
            assert e["x"][np.searchsorted(rec.t, (t0 + T + t1) / 2)] == 0.0
        # the core is far from a straight line (the pads' slip: measured 82 ... 114 sigma), and close to a PI model:
        # 12 plays of the drive fitted by NNLS leave 1.4 ... 1.8 sigma RMS, at most 4.6 ... 7.5 sigma
        assert _linear_misfit(model, e["drive"]) > 20 * rec.noise_std
        rms, mx = _pi_fit_rms(model, e["drive"])
        assert 0.5 * rec.noise_std < rms < 3.0 * rec.noise_std and mx < 12 * rec.noise_std


# ---- creep: Andrade's law of a lead shim under a sit-stand desk ----

def test_andrade_creep_under_sit_stand_desk():
    beta, kappa, dt = 1.0, 0.03, 0.02
    # the FFT convolution against a direct sum whose kernel is quad of the law over each sample (1e-10 of the span)
    r = np.random.default_rng(5)
    f = np.cumsum(r.normal(0, 1, 600))
    got = m34.andrade_creep(f, dt, 0.07, beta, kappa)
    kern = np.array([quad(lambda s: float(m34.andrade(s, beta, kappa)), j * dt, (j + 1) * dt, epsabs=1e-15,
                          epsrel=1e-13)[0] / dt for j in range(600)])
    df = np.r_[0.0, np.diff(f)]
    norm = float(m34.andrade(10.0, beta, kappa))
    ref = 0.07 * np.array([np.dot(df[:j + 1], kern[j::-1]) for j in range(600)]) / norm
    np.testing.assert_allclose(got, ref, atol=1e-10 * np.ptp(ref))
    # a ramp over T1 and a hold against quad of Boltzmann's integral (1e-9), and a step held 10 s creeps by c (2e-3
    # relative: the step spread over its one sample)
    T1 = 2.0
    tq = np.arange(1500) * dt
    got = m34.andrade_creep(np.minimum(tq / T1, 1.0), dt, 0.07, beta, kappa)
    for j in (30, 100, 1400):
        ref = quad(lambda s: float(m34.andrade(tq[j] - s, beta, kappa)) / T1, 0, min(tq[j], T1), epsabs=1e-14,
                   limit=200)[0]
        assert got[j] == pytest.approx(0.07 * ref / norm, abs=1e-9)
    step = m34.andrade_creep(np.r_[0.0, np.ones(550)], dt, 0.07, beta, kappa)
    assert step[501] == pytest.approx(0.07, rel=2e-3)
    for seed in (0, 1, 2):
        rec = _rec(CREEP, seed)
        e = rec.extra
        h = _core(e, rec.v)
        cr = m34.andrade_creep(h, rec.t[1], e["c_creep"], e["beta"], e["kappa"])
        assert _rms(rec.y - h - cr) < 1.5 * rec.noise_std
        assert e["kappa"] * 10 == pytest.approx(e["flow"] * 10 ** (1 / 3), rel=1e-12)
        # the desk: seated at the start and the end, stood up at least once, held (sitting or standing) for most of
        # the day, never faster than its motors' 0.3 of the travel a second (the eased move's peak pi / 2 times its
        # mean)
        p = e["p"]
        assert p[0] == 0.0 and p[-1] == 0.0 and p.max() > 0.9 and p.min() > -1e-12
        assert np.abs(np.diff(p)).max() / rec.t[1] <= 0.3 * math.pi / 2 * (1 + 1e-6)
        holds = np.sum([tb - ta for ta, tb, a, b in zip(e["times"][:-1], e["times"][1:], e["vals"][:-1],
                                                         e["vals"][1:]) if a == b])
        assert holds > 0.6 * e["times"][-1]
        # the creep moves the output by over 7 sigma beyond a gain and offset on the core (measured 48 ... 54)
        assert _linear_misfit(h + cr, h) > 7 * rec.noise_std


# ---- rate: a damper valved harder in rebound under an accelerator pedal ----

def test_rebound_valved_damper_under_stop_and_go_pedal():
    # the stepping against solve_ivp of y' = (h(t) - y) / tau(sign), h linear between the samples (DOP853, rtol
    # 1e-11; 2e-6 of the span: the implicit midpoint's second order, measured 3e-7)
    dt = 1 / 1595
    r = np.random.default_rng(9)
    n = 3000
    h = np.cumsum(r.normal(0, 1, n))
    h = np.convolve(h, np.ones(25) / 25, mode="same")
    tq = np.arange(n) * dt
    te, tc = 9e-3, 3e-3
    got = m34.valved_damper_stage(h, dt, te, tc)

    def rhs(t, y):
        d = float(np.interp(t, tq, h)) - y[0]
        return [d / (te if d > 0 else tc)]
    sol = solve_ivp(rhs, (0, tq[-1]), [h[0]], t_eval=tq, method="DOP853", rtol=1e-11, atol=1e-13, max_step=dt / 4)
    np.testing.assert_allclose(got, sol.y[0], atol=2e-6 * np.ptp(h))
    for seed in (0, 1, 2):
        rec = _rec(RATE, seed)
        e = rec.extra
        h = _core(e, e["drive"])
        y = m34.valved_damper_stage(h, rec.t[1], e["tau_e"], e["tau_c"])
        assert _rms(rec.y - y) < 1.5 * rec.noise_std
        assert 2.0 <= e["ratio"] <= 3.5 and 2.5e-3 <= e["tau_c"] <= 5e-3
        # the pedal: released at the start and the end, kicked down to the floor at least once in under 0.2 s
        p = e["p"]
        assert p[0] == 0.0 and p[-1] == 0.0 and p.max() >= 0.95
        v = np.asarray(e["vals"])
        tt = np.asarray(e["times"])
        assert any(v[k] >= 0.95 and v[k - 1] == 0.0 and tt[k] - tt[k - 1] <= 0.2 for k in range(1, len(v)))
        # the damper moves the output by over 7 sigma beyond a gain and offset on the core (measured 41 ... 79)
        assert _linear_misfit(y, h) > 7 * rec.noise_std


# ---- drift: sand-filled legs compacting under a compressor's vibration ----

def test_sand_leg_compaction_under_serpenoid_snake():
    # Knight's law against solve_ivp of its rate, d phi / d t = [machine on] B / ((tau + t_s)(1 + B ln(1 + t_s /
    # tau))^2), t_s the running time so far, integrated in the wall-clock time with the machine switched on and off
    # (DOP853, rtol 1e-11; 1e-9)
    runs = [(2.0, 6.0), (11.0, 4.0), (20.0, 9.0)]
    B, tau = 0.9, 1.3
    tq = np.linspace(0, 32, 3201)

    def rhs(t, y):
        on = any(t0 <= t < t0 + T for t0, T in runs)
        return [B / ((tau + y[1]) * (1 + B * math.log1p(y[1] / tau)) ** 2) if on else 0.0, 1.0 if on else 0.0]
    sol = solve_ivp(rhs, (0, 32), [0.0, 0.0], t_eval=tq, method="DOP853", rtol=1e-11, atol=1e-13, max_step=0.01)
    np.testing.assert_allclose(m34.knight_compaction(m34.shaking_time(tq, runs), B, tau), sol.y[0], atol=1e-9)
    for seed in (0, 1, 2):
        rec = _rec(DRIFT, seed)
        e = rec.extra
        h = _core(e, rec.v)
        assert _rms(rec.y - h - e["offset"]) < 1.5 * rec.noise_std
        off = e["offset"]
        assert off[0] == 0.0 and off[-1] == pytest.approx(e["side"] * e["mag"] * np.ptp(h), rel=1e-12)
        assert np.all(e["side"] * np.diff(off) >= 0.0)                # the legs only settle
        np.testing.assert_array_equal(e["t_shake"], m34.shaking_time(rec.t, e["runs"]))
        still = np.diff(e["t_shake"]) == 0.0
        assert still.mean() > 0.2 and np.all(np.diff(off)[still] == 0.0)   # still while the compressor stops
        # the joint swings to both sides and freezes (exactly 0) between the stretches
        assert e["x"].max() > 0.85 and e["x"].min() < -0.85
        for (t0, T, *_), (t1, *_) in zip(e["stretches"][:-1], e["stretches"][1:]):
            assert e["x"][np.searchsorted(rec.t, (t0 + T + t1) / 2)] == 0.0
        # the drift moves the output by over 7 sigma beyond a gain and offset on the core (measured 24 ... 25)
        assert _linear_misfit(h + off, h) > 7 * rec.noise_std


# ---- asymmetry: a CdS photoresistor under a tug of war ----

def test_cds_photoresistor_under_tug_of_war():
    # Rose's exponent against his model solved numerically: the electrons' quasi-Fermi level E_F (n = exp(E_F / kT),
    # energies from the band edge) makes the trap states below it, of density exp(E / kT_c) / kT_c (quad from deep in
    # the gap), recombination centres, so the generation g = n N_r(E_F); solved for n by brentq at two rates a decade
    # apart, the log-slope of n against g is T_c / (T + T_c) (1e-6)
    T, Tc = 300.0, 900.0
    k = 1.0

    def g_of(EF):
        Nr = quad(lambda E: math.exp(E / (k * Tc)) / (k * Tc), -60 * k * Tc, EF, epsabs=1e-300, epsrel=1e-13)[0]
        return math.exp(EF / (k * T)) * Nr
    EFs = [brentq(lambda E: math.log(g_of(E)) - math.log(gg), -40 * k * T, 0.0, xtol=1e-14) for gg in (1e-12, 1e-11)]
    slope = (EFs[1] - EFs[0]) / (k * T) / math.log(10.0)
    assert slope == pytest.approx(m34.rose_exponent(T, Tc), abs=1e-6)
    for seed in (0, 1, 2):
        rec = _rec(ASYM, seed)
        e = rec.extra
        h = _core(e, rec.v)
        c, X = e["centre"], e["X"]
        y = c + e["side"] * X * m34.ldr_reading(e["side"] * (h - c) / X, e["a_light"], e["gamma"])
        assert _rms(rec.y - y) < 1.5 * rec.noise_std
        assert -m34.ldr_asym(e["a_light"], e["gamma"]) == pytest.approx(e["asym"], abs=1e-12)
        assert 0.6 <= e["gamma"] <= 0.85 and 0 < e["a_light"] < 1
        # the mark moves both ways, by heaves that each slip back (never past their pull)
        assert e["x"].max() > 0.85 * np.abs(e["x"]).max() and e["x"].min() < -0.85 * np.abs(e["x"]).max()
        # the photoresistor moves the output by over 7 sigma beyond a gain and offset on the core (measured 14 ... 16)
        assert _linear_misfit(y, h) > 7 * rec.noise_std


# ---- saturation: an oil-bulged membrane under a windsurfer ----

def test_oil_bulged_membrane_under_windsurfing():
    # the cap's volume against quad of the sphere's discs (radius R = (a^2 + h^2) / (2 h), Laplace's constant curvature;
    # 1e-12), and the apex against brentq on that volume (1e-12)
    a = 1.0
    for hgt in (0.1, 0.5, 0.9, 1.3):
        R = (a * a + hgt * hgt) / (2 * hgt)
        vol = quad(lambda z: math.pi * (R * R - (R - hgt + z) ** 2), 0.0, hgt, epsabs=1e-15)[0]
        assert float(m34.cap_volume(hgt, a)) == pytest.approx(vol, abs=1e-12)
        assert float(m34.membrane_apex(vol, a)) == pytest.approx(hgt, abs=1e-12)
        assert float(m34.membrane_apex(-vol, a)) == pytest.approx(-hgt, abs=1e-12)
    for b in (0.5, 1.0):
        assert float(m34.membrane_reading(1e-7, b)) / 1e-7 == pytest.approx(1.0, abs=1e-9)
    for seed in (0, 1, 2):
        rec = _rec(SAT, seed)
        e = rec.extra
        h = _core(e, e["drive"])
        c, X = e["centre"], e["X"]
        y = c + X * m34.membrane_reading((h - c) / X, e["b"])
        assert _rms(rec.y - y) < 1.5 * rec.noise_std
        assert 1 - float(m34.membrane_reading(1.0, e["b"])) == pytest.approx(e["comp"], abs=1e-12)
        # the sail on both tacks
        assert e["x"].max() > 0.85 * np.abs(e["x"]).max() and e["x"].min() < -0.85 * np.abs(e["x"]).max()
        # the membrane moves the output by over 7 sigma beyond a gain and offset on the core (measured 12 ... 17)
        assert _linear_misfit(y, h) > 7 * rec.noise_std


# ---- delay: a smart sensor's moving average under a pogo stick ----

def test_ema_smart_sensor_under_pogo_stick():
    # the firmware's filter against lfilter of its difference equation (1e-12) and against its transfer function
    # applied by FFT to a smooth pulse (1e-9), and its delay at low frequency, (2^k - 1) / R + the latency, from the
    # phase's slope at 1e-6 of the record's rate (1e-6)
    r = np.random.default_rng(2)
    for R, k in ((6, 5), (10, 4)):
        xf = np.cumsum(r.normal(0, 1, 4000 * R + 1))
        al = 2.0 ** -k
        s = lfilter([al], [1, -(1 - al)], xf, zi=[(1 - al) * xf[0]])[0]
        ref = np.r_[xf[0], s[::R][:-1]]
        np.testing.assert_allclose(m34.ema_sensor(xf, R, k), ref, atol=1e-12 * np.abs(xf).max())
        n = 2 ** 15
        tq = np.arange(n)
        pulse = np.exp(-((tq - 6000) / 300.0) ** 2)
        fr = np.fft.rfftfreq(2 * n)
        out = np.fft.irfft(np.fft.rfft(pulse, 2 * n) * m34.ema_transfer(np.exp(2j * math.pi * fr), k), 2 * n)[:n]
        s2 = np.empty(n)
        acc = 0.0
        for j in range(n):
            acc += al * (pulse[j] - acc)
            s2[j] = acc
        np.testing.assert_allclose(s2, out, atol=1e-9)
        w = 2 * math.pi * 1e-6 / R
        ph = np.angle(m34.ema_transfer(np.exp(1j * w), k))
        assert -ph / w / R + 1 == pytest.approx((2.0 ** k - 1) / R + 1, rel=1e-6)
    for seed in (0, 1, 2):
        rec = _rec(DELAY, seed)
        e = rec.extra
        R = e["R"]
        hf = _core(e, e["v_fine"])
        y = m34.ema_sensor(hf, R, e["k"])
        assert _rms(rec.y - y) < 1.5 * rec.noise_std
        assert e["lag"] == pytest.approx((2.0 ** e["k"] - 1) / R + 1) and 2.5 <= e["lag"] <= 6.2
        # the spring: free (exactly 0) in every flight, continuous at touch-down and lift-off, never stretched
        z = e["v_fine"]
        assert z.min() >= 0.0 and np.abs(np.diff(z)).max() < 0.05 * z.max()
        for kind, t0, dur, _ in e["segs"]:
            if kind == "stance":
                assert float(s34.pogo_compression(np.array([t0 + dur]), [(kind, t0, dur, _)])[0]) < 1e-12
        # the filter moves the output by over 7 sigma beyond a gain and offset on the core (measured 26 ... 43)
        assert _linear_misfit(y, hf[::R]) > 7 * rec.noise_std


# ---- initial state: an emergency stop during a swept-sine test, then a slow waltz ----

def test_estop_swept_sine_under_slow_waltz():
    # the path: the chirp's phase against quad of its instantaneous frequency (1e-9), and the decay through the diode
    # from the cut's value (1e-12)
    A, f0, f1, Tsw, t_cut, tau_L = 60.0, 0.7, 6.0, 25.0, 11.3, 0.01
    tp, path = m34.estop_path(A, f0, f1, Tsw, t_cut, tau_L)
    j = np.searchsorted(tp, 7.0)
    phase = 2 * math.pi * quad(lambda s: f0 + (f1 - f0) * s / Tsw, 0, tp[j], epsabs=1e-13)[0]
    assert path[j] == pytest.approx(A * math.sin(phase), abs=1e-9)
    kc = np.searchsorted(tp, t_cut)
    assert path[kc + 100] == pytest.approx(path[kc] * math.exp(-(tp[kc + 100] - t_cut) / tau_L), abs=1e-12)
    assert path[-1] == 0.0
    for seed in (0, 1, 2):
        rec = _rec(INIT, seed)
        e = rec.extra
        model = _core(e, rec.v, state=e["state"])
        assert _rms(rec.y - model) < 1.5 * rec.noise_std
        assert rec.v[0] == 0.0 and e["A"] > np.abs(rec.v).max()          # the test drove beyond the record's reach
        # rate independence: the state the path left is the one its turning points alone leave (1e-12)
        p = e["path"]
        turns = [p[0]] + [p[i] for i in range(1, len(p) - 1) if (p[i] - p[i - 1]) * (p[i + 1] - p[i]) < 0] + [p[-1]]
        lin = np.concatenate([np.linspace(a, b, 5) for a, b in zip(turns[:-1], turns[1:])])
        _, st = c34._core_of(e, lin, return_state=True)
        np.testing.assert_allclose(st[0], e["state"][0], atol=1e-12)
        assert st[1] == pytest.approx(e["state"][1], abs=1e-12)
        # the waltz: a bar is a sway out and back (0 on every bar line)
        tt, vv = np.asarray(e["times"]), np.asarray(e["vals"])
        bar_lines = tt[1:-1][vv[1:-1] == 0.0]
        np.testing.assert_allclose(np.diff(bar_lines), e["bar"], rtol=1e-9)
        # far from the same core started virgin (the pads unstrained): over 7 sigma beyond a gain and an offset
        # (measured 103 ... 150)
        assert _linear_misfit(model, _core(e, rec.v)) > 7 * rec.noise_std


# ---- two effects: a helium-neon laser's mode sweeping and a diode-feedback TIA, under a cocktail shaker ----

def test_hene_mode_sweep_and_diode_tia_under_cocktail_shaker():
    # the mode sum against the cavity's resonances found from the round trip: nu_q = q c / (2 L) for a tube of
    # length L near the line at nu_0 (the modes within 4 FWHM; the power periodic in the tube's growth by lambda / 2,
    # 1e-9), and the TIA against brentq of the diodes' feedback current 2 I_s sinh(V / n V_T) = i (1e-12)
    c0, nu0 = 299792458.0, 473.61e12
    fwhm, thresh = 1.5e9, 0.35
    L0 = 0.2
    for dL in (0.0, 1.1e-7, 2.6e-7):
        L = L0 + dL
        fsr = c0 / (2 * L)
        qs = np.arange(int(2 * L * (nu0 - 4 * fwhm) / c0), int(2 * L * (nu0 + 4 * fwhm) / c0) + 2)
        nu = qs * c0 / (2 * L) - nu0
        ref = np.maximum(np.exp(-4 * math.log(2) * (nu / fwhm) ** 2) - thresh, 0).sum()
        phase = (2 * L * nu0 / c0) % 1.0                   # the modes at (j - phase) fsr from the line's centre
        got = float(m34.hene_power(phase, fsr / 1e9, fwhm / 1e9, thresh))
        assert got == pytest.approx(ref, abs=1e-9)
    assert float(m34.hene_power(0.37, 1.0, 1.5, 0.4)) == pytest.approx(float(m34.hene_power(1.37, 1.0, 1.5, 0.4)),
                                                                        abs=1e-12)
    for i in (-3.0, -0.2, 0.01, 1.7, 12.0):
        V = brentq(lambda q: 2 * 0.25 * math.sinh(q) - i, -20, 20, xtol=1e-15)
        assert float(m34.diode_tia(i, 0.25)) == pytest.approx(V, abs=1e-12)
    for seed in (0, 1, 2):
        rec = _rec(PAIR, seed)
        e = rec.extra
        h = _core(e, rec.v)
        c, X = e["centre"], e["X"]
        g = m34.hene_power(e["phase"], e["fsr"], e["fwhm"], e["thresh"])
        g = g / g[0]
        y = c + X * m34.tia_reading(g * (h - c) / X, e["b"])
        assert _rms(rec.y - y) < 1.5 * rec.noise_std
        assert 1 - float(m34.tia_reading(1.0, e["b"])) == pytest.approx(e["comp"], abs=1e-12)
        # the tube grows by the drawn number of half-wavelengths over the record
        assert e["phase"][-1] - e["phase"][0] == pytest.approx(e["sweeps"], rel=1e-9)
        # each effect beyond a gain and offset on the rest: the mode sweeping beyond the core read by the same TIA
        # (measured 16 ... 22), the diodes beyond the core under the same gain drift (measured 13 ... 21)
        steady = c + X * m34.tia_reading((h - c) / X, e["b"])
        linear = c + g * (h - c)
        assert _linear_misfit(y, steady) > 7 * rec.noise_std
        assert _linear_misfit(y, linear) > 7 * rec.noise_std


# ---- out of vocabulary: a follower over a magnetic detent rack under a hula hoop ----

def test_tomlinson_detent_follower_under_hula_hoop():
    # the quasi-static follower against solve_ivp of its overdamped motion, gamma y' = K (h - y) - F0 sin(2 pi y / p),
    # with gamma / K 1e-4 of the drive's time (Radau, rtol 1e-10): away from the slips (where the fast relaxation
    # lags) they agree to 1e-3 of the pitch; and the follower slips pitch by pitch, sticking between
    eta, p = 3.0, 1.0
    c = eta * p / (2 * math.pi)
    tq = np.linspace(0, 20, 8001)
    hq = 3.3 * np.sin(2 * math.pi * tq / 10)
    got = m34.tomlinson_follower(hq, eta, p)
    eps = 1e-4

    def rhs(t, y):
        return [((3.3 * math.sin(2 * math.pi * t / 10) - y[0]) - c * math.sin(2 * math.pi * y[0] / p)) / eps]
    sol = solve_ivp(rhs, (0, 20), [0.0], t_eval=tq, method="Radau", rtol=1e-10, atol=1e-12, max_step=0.005)
    settled = np.abs(np.diff(got, prepend=got[0])) < 1e-3 * p
    settled &= np.r_[settled[1:], True] & np.r_[True, settled[:-1]]
    np.testing.assert_allclose(got[settled], sol.y[0][settled], atol=1e-3 * p)
    jumps = np.abs(np.diff(got))
    assert jumps.max() > 0.5 * p and np.sum(jumps > 0.5 * p) >= 8
    for seed in (0, 1, 2):
        rec = _rec(OOV, seed)
        e = rec.extra
        h = _core(e, rec.v)
        y = m34.tomlinson_follower(h, e["eta"], e["pitch"]) + e["offset"]
        assert _rms(rec.y - y) < 1.5 * rec.noise_std
        assert 2.0 <= e["eta"] <= 4.0
        # the hip circles to both sides and the sessions end in a drop (exactly 0 between them)
        assert e["x"].max() > 0.6 and e["x"].min() < -0.6
        for (t0, T, *_), (t1, *_) in zip(e["sessions"][:-1], e["sessions"][1:]):
            assert e["x"][np.searchsorted(rec.t, (t0 + T + t1) / 2)] == 0.0
        # no monotone map of the core (isotonic regression, rising or falling: it takes in every saturation and
        # asymmetry) comes near the reading: over 15 sigma away (measured 32 ... 43)
        o = np.argsort(h)
        ys = rec.y[o]
        miss = min(np.abs(ys - isotonic_regression(ys, increasing=inc).x).max() for inc in (True, False))
        assert miss > 15 * rec.noise_std

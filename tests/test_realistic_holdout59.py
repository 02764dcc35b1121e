"""HOLDOUT59 (tests/realistic/cases_holdout59.py, laws in mechanisms59.py, signals in signals59.py): well formed,
measured once in round 61 (7e9d9ce, 20 of 30 runs right) and part of ALL since, and every mechanism follows its law.
Nothing here runs the diagnosis.

Tolerances: a record that is its stated law plus the sensor noise leaves a residual RMS within 1.5 sigma of the law (the
noise alone gives 1.0; the laws are evaluated on the clean drive). A law checked against an independent solution (every
microgel's state by the last threshold the temperature crossed, from the running extremes looking back; the microgels'
thresholds from the stated laws written out here; the rest state by an explicit decaying thermal cycling; the creep
compliances' means by quad and the Volterra solutions by their own equation summed directly; the slab's kinetics by a
finite-volume solution of the diffusion through the film and solve_ivp; the ion exchange and the room's pressure by
solve_ivp; the gusts' sum written out and its variance by quad of the spectrum; the thermistor's and the heater's laws
by brentq; the DAC's queue written out; the reflectance by the layer's characteristic matrix; finer grids) agrees to
the stated tolerance, set from the solvers' own tolerances or the scheme's order (each stated beside it), far below
sigma (2e-3 of the span).

Effects are asked to move the output by at least 7 sigma beyond what a gain and an offset on the core absorb, both at
its largest and as an RMS over the whole record (the core: the same film, rate independent, its temperature the set
point's, without the effect; the creep against the film's own thinning; the rate dependence against the film of the
same thick cast with its water flowing at once; the drift against the film in a bath without calcium; the asymmetry
against the film under a loop that converts by the thermistor's own law; the saturation against the film under an
unlimited supply; the delay against the set point at once; the initial state against the same film from the rest state;
the pair's creep against a rigid pad and its drift against a calm day); the measured values for seeds 0 ... 2 are
stated beside each (RMS; largest), in sigma: creep 7.9 ... 9.5 (29 ... 36), rate 49.8 ... 67.8 (162 ... 191), drift 20.4
... 24.2 (44 ... 60), asymmetry 9.0 ... 9.6 (37 ... 46), saturation 42.5 ... 55.0 (87 ... 145), delay 16.5 ... 23.3
(164 ... 249), initial state 13.7 ... 17.7 (30 ... 40), the pair's creep alone 8.3 ... 9.1 (27 ... 30) and its drift
alone 11.2 ... 18.3 (22 ... 33) (and within the record: the creep beyond a gain and an offset on the drifting reading
without it 9.1 ... 10.1 (28 ... 29), the drift beyond those on the crept reading without it 11.3 ... 18.4 (22 ...
33)); the out-of-vocabulary fold is 86 ... 141 sigma from any monotone map of the core the recorded drive makes. The
creep (7.9, seed 2) and the pair's creep (8.3, seed 1) are the smallest margins in the set.

The pair, {creep, drift}: the pushrod on a nylon-6 pad creeping as the logarithm of time (the single creep case's foot
is UHMW-PE with a stretched-exponential compliance that saturates) and the interferometer's air path read through the
room's pressure as a gale buffets the building (a wander of tens of seconds, both ways; the single drift case's is the
matrix's ion exchange, one way and exponential).

The clean core's closeness to a Prandtl-Ishlinskii model, a PI model of 12 plays of the drive (set_checks.pi_fit_rms)
fitted by NNLS: it leaves 2.30 ... 2.58 sigma RMS on the clean record (seeds 0 ... 2; its largest residual 8.6 ... 9.9
sigma), where the core is far from a straight line (57 ... 63 sigma at most). That is a little above the 2 sigma aimed
at: the core's widths are a continuous spread that 12 evenly spaced plays can only sample (a core of uniform centres and
no pre-transitional term still leaves some 2 sigma in trials), so the set's clean record sits at the edge of what a PI
model explains. What a PI model misses: the microgels' thresholds are not a uniform density of
centres times a density of widths (their T_c are normal about T_0, the widths lean on T_c), and a swollen microgel's
pre-transitional deswelling multiplies the temperature into the state; the widths' spread is continuous where 12 plays
give 12.
"""

import math
from functools import lru_cache

import numpy as np
import pytest
from scipy.integrate import quad, solve_ivp
from scipy.optimize import brentq, isotonic_regression
from scipy.special import ndtri

import realistic
from realistic import HOLDOUT59
from realistic import cases_holdout59 as c59
from realistic import mechanisms59 as m59
from realistic import signals59 as s59
from test_realistic_generator import _assert_joined_ten, _linear_misfit, _rms
from realistic.set_checks import assert_knots_evaluator as _knots_evaluator, assert_minimum_jerk as _minimum_jerk
from realistic.set_checks import assert_relay_core as _relay_core, holds as _holds, pi_fit_rms as _pi_fit_rms
from realistic.set_checks import never_still as _never_still
from test_realistic_holdout50 import _big, _full_both_ways, _lopsided
from test_realistic_holdout52 import _states_by_history

pytestmark = pytest.mark.slow

P = "holdout59_"
EFFECTS = {"creep", "rate_dependence", "drift", "asymmetry", "saturation", "initial_state", "delay"}
CLEAN = "clean_pnipam_microgel_film_glassblower_pipe_1381hz"
CREEP = "creep_kww_uhmwpe_foot_letterpress_lever_263hz"
RATE = "rate_tanaka_fillmore_thick_film_juggler_hand_1907hz"
DRIFT = "drift_calcium_ion_exchange_nipping_press_211hz"
ASYM = "asymmetry_ntc_thermistor_linearised_table_tennis_bat_827hz"
SAT = "saturation_heater_supply_compliance_dental_foot_control_379hz"
DELAY = "delay_dac_output_queue_engine_telegraph_613hz"
INIT = "initial_state_hot_night_pan_pot_547hz"
PAIR = "pair_creep_drift_nylon_pad_gale_air_path_points_lever_293hz"
OOV = "oov_reflectance_fold_windsurfer_boom_1151hz"
UNIPOLAR = {CREEP, DRIFT, SAT}
MONITORED = {CLEAN: 2e-4, RATE: 3e-4, SAT: 2.5e-4, DELAY: 3e-4}
ORDER = ("clean_", "creep_", "rate_", "drift_", "asymmetry_", "saturation_", "delay_", "initial_state_", "pair_",
         "oov_")


@lru_cache(maxsize=None)
def _rec(name, seed):
    return HOLDOUT59[P + name](seed)


@lru_cache(maxsize=None)
def _core_cached(name, seed):
    """The core's reading for a record's clean drive, from the rest state (cached: several checks use it)."""
    e = _rec(name, seed).extra
    return m59.core_reading(e, e["drive"])


# ---- the set ----

def test_holdout59_is_well_formed_and_joined():
    H = HOLDOUT59
    assert c59.HOLDOUT59 is H and realistic.HOLDOUT59 is H and "HOLDOUT59" in realistic.__all__
    _assert_joined_ten(H, P, EFFECTS, ORDER, _rec, MONITORED, UNIPOLAR, PAIR, {"creep", "drift"}, ASYM)


def test_reach_and_programmes():
    # the minimum-jerk reach against quad of its speed and the knots' evaluator against a direct search
    # (set_checks.assert_minimum_jerk, assert_knots_evaluator)
    _minimum_jerk(s59.reach, s59.reach_speed)
    _knots_evaluator(s59.reach, s59.knots_at)
    rng = np.random.default_rng(7)
    # the juggler never still; the pan pot within 0.05 of the middle for its first 10 s; the telegraph's orders on the
    # quarter steps, never the same twice in a row; the unipolar programmes within 0 ... 1, reaching 1
    assert _never_still({"knots": s59.juggler_hand(rng, 1)[0]})
    kn, _ = s59.pan_pot(rng, 12)
    assert max(abs(x) for t, x in kn if t <= 10.0) <= 0.05 and max(x for t, x in kn) == 1.0
    kn, _ = s59.engine_telegraph(rng, 9)
    orders = [x for t, x in kn][1::2]
    assert all(4 * x == round(4 * x) for x in orders) and all(a != b for a, b in zip(orders, orders[1:]))
    for gen in (s59.letterpress_lever, s59.nipping_press, s59.dental_foot_control):
        xs = [x for t, x in gen(rng, 2)[0]]
        assert min(xs) >= 0.0 and max(xs) == 1.0


# ---- the core: a PNIPAM microgel film ----

def _domains_written_out(e):
    """The microgels' (T_c, T_s) from the stated laws: T_c = T_0 + s_c z_1 on the stratified quantiles (k + 1/2) / N,
    the widths w_0 exp(0.6 z_2 - 0.05 z_1), z_2 the same quantiles shuffled by the seed's permutation."""
    N = m59.N_DOM
    perm = np.random.default_rng(e["dseed"]).permutation(N)
    z1 = np.array([ndtri((k + 0.5) / N) for k in range(N)])
    z2 = np.array([ndtri((perm[k] + 0.5) / N) for k in range(N)])
    tc = e["T0"] + e["sc"] * z1
    return tc, tc - e["w0"] * np.exp(0.6 * z2 - 0.05 * z1)


def _volume_written_out(T, c, tc):
    """The microgels' mean volume at the temperature T in the states c: 0.22 collapsed, 1 - 0.2 exp(-(T_c - T) / 1.2)
    swollen."""
    return float(np.mean(np.where(c > 0.5, 0.22, 1.0 - 0.2 * np.exp(-(tc - T) / 1.2))))


def test_core_microgels_states_and_reading_against_their_definitions():
    for seed in (0, 1, 2):
        rec = _rec(CLEAN, seed)
        e = rec.extra
        tc, ts = m59.domains(e)
        tc_w, ts_w = _domains_written_out(e)
        # (1e-12 K: rounding)
        np.testing.assert_allclose(tc, tc_w, rtol=0, atol=1e-12)
        np.testing.assert_allclose(ts, ts_w, rtol=0, atol=1e-12)
        # every microgel reswells below where it collapses; the bias is the median of the loops' middles (exact)
        assert np.all(tc > ts) and e["Tb"] == float(np.median(0.5 * (tc + ts)))
        v = e["drive"]
        T = m59.temperature(e, v)
        np.testing.assert_allclose(T, e["Tb"] + 0.13 * v, rtol=0, atol=1e-12)
        c0 = (0.5 * (tc + ts) < T[0]).astype(float)
        np.testing.assert_array_equal(m59.rest_state(e, T[0]), c0)
        q = m59.volume_share(e, T)
        # the mean volume at 40 samples (the first, and spread over the record) against every microgel's state from its
        # history and the volumes written out (1e-12: rounding of a mean of 8000)
        picks = np.r_[0, np.linspace(1, len(T) - 1, 39).astype(int)]
        states = np.array([_states_by_history(T, i, tc, ts, c0) for i in picks])
        ref = np.array([_volume_written_out(T[i], st, tc) for i, st in zip(picks, states)])
        np.testing.assert_allclose(q[picks], ref, rtol=0, atol=1e-12)
        # the microgels switch over the record: over 10 % of them in another state at some pick than at the start
        # (measured 40 ... 45 %)
        assert np.mean(np.any(states != c0, axis=0)) > 0.1
        # the reading: the gap, 1000 (0.45 q + 4e-4 T) nm less its first value, its sign turned (1e-9 nm)
        y = m59.reading(T, q)
        d = 1000.0 * (0.45 * q + 4e-4 * T)
        np.testing.assert_allclose(y, d[0] - d, rtol=0, atol=1e-9)
        assert _rms(rec.y - y) < 1.5 * rec.noise_std
        x = e["x"]
        assert x[0] == 0.0 and x[-1] == 0.0 and _full_both_ways(e)


def test_rest_state_is_the_limit_of_a_decaying_cycling():
    e = dict(_rec(CLEAN, 0).extra)
    tc, ts = m59.domains(e)
    Tb = e["Tb"]
    # from every microgel swollen, a cycling about the bias decaying from 60 K by 0.2 % a half cycle (its turning
    # points: the core is rate independent) leaves the rest state's states, but for the microgels whose loop's middle
    # lies within the last steps of the bias (measured: none of 8000), and the reading within 0.5 sigma of the rest
    # state's (a microgel's step is 0.03 nm, 0.1 sigma; measured 0)
    c = np.zeros(m59.N_DOM)
    amp = 60.0 * 0.998 ** np.arange(9000)
    m59.volume_share(e, np.r_[Tb + amp * (-1.0) ** np.arange(9000), Tb], c)
    assert np.sum(c != m59.rest_state(e, Tb)) <= 3
    y_cycled = m59.core_reading(e, e["drive"], c)
    assert np.abs(y_cycled - _core_cached(CLEAN, 0)).max() < 0.5 * _rec(CLEAN, 0).noise_std


def test_core_return_point_memory_rate_independence_and_pi_closeness():
    e = dict(_rec(CLEAN, 0).extra)
    # return-point memory (1e-12 nm), a loop (at 0 V its minor loop's rising branch over 2 nm, 7 sigma, below its
    # falling one) and rate independence (set_checks.assert_relay_core)
    _relay_core(lambda vv: m59.core_reading(e, vv), e["drive"], 2.0)
    for seed in (0, 1, 2):
        rec = _rec(CLEAN, seed)
        # a PI model of 12 plays fitted by NNLS leaves 1.5 ... 3.0 sigma RMS (measured 2.30 ... 2.58) and at most 12
        # sigma (measured 8.6 ... 9.9), where the core is far from a straight line (over 40 sigma: measured 57 ... 63)
        r, m = _pi_fit_rms(rec.y, rec.v)
        assert 1.5 * rec.noise_std < r < 3.0 * rec.noise_std and m < 12 * rec.noise_std
        assert _linear_misfit(_core_cached(CLEAN, seed), rec.v) > 40 * rec.noise_std


# ---- creep: an UHMW-PE foot, its compliance a stretched exponential, under a letterpress lever ----

def _volterra_direct(y, kern, d, idx):
    """The Volterra equation's residual at the samples idx: y_i + sum_(j <= i) (y_j - y_(j-1)) kern_(i-j) - d_i."""
    dy = np.diff(y, prepend=y[0])
    return np.array([y[i] + float(np.dot(dy[1:i + 1], kern[i - 1::-1][:i])) - d[i] for i in idx])


def test_kww_foot_under_letterpress_lever():
    # the kernel: c_0 + c_1 (1 - exp(-(t / tau)^b))'s mean over each sample interval, against quad (1e-12)
    dt, c0, c1, tau, b = 1 / 263, 0.05, 0.2, 6.0, 0.4
    k = m59.kww_kernel(3000, dt, c0, c1, tau, b)
    for mm in (0, 1, 7, 100, 2999):
        ref = quad(lambda u: c0 + c1 * (1 - math.exp(-(u / tau) ** b)), mm * dt, (mm + 1) * dt, epsabs=1e-15,
                   epsrel=1e-13)[0] / dt
        assert k[mm] == pytest.approx(ref, abs=1e-12)
    for seed in (0, 1, 2):
        rec = _rec(CREEP, seed)
        e = rec.extra
        t, dt = rec.t, rec.t[1]
        assert 0.03 <= e["c0"] <= 0.06 and 0.2 <= e["c1"] <= 0.28 and 4 <= e["tau"] <= 10 and 0.35 <= e["b"] <= 0.5
        dd = e["d"]
        np.testing.assert_array_equal(dd, _core_cached(CREEP, seed))
        kk = m59.kww_kernel(len(t), dt, e["c0"], e["c1"], e["tau"], e["b"])
        y = m59.creep_reading(dd, kk)
        # the Volterra equation summed directly at 12 samples (1e-9 nm: rounding over 40,000 terms)
        idx = np.linspace(1, len(t) - 1, 12).astype(int)
        assert np.abs(_volterra_direct(y, kk, dd, idx)).max() < 1e-9
        assert _rms(rec.y - y) < 1.5 * rec.noise_std
        # after the lever's pulls the rod keeps sinking back: held at a pull's top for 1.5 s or more, the reading moves
        # on by over 2 sigma (measured 21 ... 27 at the most)
        p = e["p"]
        assert p[0] == 0.0 and p[-1] == 0.0 and p.max() == pytest.approx(1.0, abs=1e-12)
        runs = [(a, b_) for a, b_ in _holds(rec.v, int(1.5 / dt)) if rec.v[a] > 0.5 * e["top"]]
        assert len(runs) >= 4 and max(abs(y[b_ - 1] - y[a]) for a, b_ in runs) > 2 * rec.noise_std
        # the foot moves the reading beyond a gain and an offset on the film's own thinning: over 7 sigma RMS and at
        # most (measured 7.9 ... 9.5 RMS, 29 ... 36 at most)
        _big(rec, y, dd)


# ---- rate dependence: a thick film's swelling kinetics, under a juggler's hand ----

def _slab_fv(t, x, tau1, n_cells=400):
    """The slab's mean by a finite-volume solution of u_t = D u_zz (u_z = 0 at the chip, u = x at the bath's face;
    D / L^2 = 4 / (pi^2 tau1)) in exact time: the cells' symmetric matrix's eigenvectors (eigh), each mode of u - x
    stepped exactly for x linear between the times t, from rest at x[0]."""
    k = 4.0 / (math.pi ** 2 * tau1) * n_cells ** 2
    A = np.diag(np.full(n_cells, -2 * k)) + np.diag(np.full(n_cells - 1, k), 1) + np.diag(np.full(n_cells - 1, k), -1)
    A[0, 0], A[-1, -1] = -k, -3 * k
    lam, V = np.linalg.eigh(A)
    c = V.T @ np.ones(n_cells)
    mean_v = V.mean(axis=0)
    dt = t[1] - t[0]
    e = np.exp(lam * dt)
    g = (e - 1.0) / lam
    a = np.zeros(n_cells)
    out = np.empty(len(t))
    out[0] = x[0]
    for i in range(1, len(t)):
        a = a * e - (x[i] - x[i - 1]) / dt * c * g
        out[i] = x[i] + float(mean_v @ a)
    return out


def test_thick_film_kinetics_under_juggler_hand():
    # the modes' weights: 8 / ((2n + 1)^2 pi^2), all of them summing to 1 (the rest under 3e-4: 2 / (pi^2 N_MODES))
    w, rest = m59.slab_weights()
    assert w[0] == pytest.approx(8 / math.pi ** 2, rel=1e-14) and 0 < rest < 3e-4
    for seed in (0, 1, 2):
        rec = _rec(RATE, seed)
        e = rec.extra
        t = rec.t
        assert 6.0 <= e["L_um"] <= 8.0
        assert e["tau1"] == pytest.approx(4 * (e["L_um"] * 1e-6) ** 2 / (math.pi ** 2 * 1e-10), rel=1e-14)
        T = m59.temperature(e, e["drive"])
        h_eq = m59.reading(T, m59.volume_share(e, T), h=e["L_um"] * 1e3)
        np.testing.assert_array_equal(h_eq, e["h_eq"])
        y = m59.slab_kinetics(t, h_eq, e["tau1"])
        assert _rms(rec.y - y) < 1.5 * rec.noise_std
        # against the finite-volume solution over the record (0.02 sigma: the cells' O(h^2) error in the modes' rates,
        # some 1e-5 relative; measured 6e-4 ... 7e-4)
        ref = _slab_fv(t, h_eq, e["tau1"])
        assert np.abs(y - ref).max() < 0.02 * rec.noise_std
        x = e["x"]
        assert x[0] == 0.0 and _full_both_ways(e) and _never_still(e)
        # the flow moves the reading beyond a gain and an offset on the same film with its water at once: over 7 sigma
        # RMS and at most (measured 49.8 ... 67.8 RMS, 162 ... 191 at most)
        _big(rec, y, h_eq)


# ---- drift: the matrix's ion exchange, under a nipping press ----

def test_ion_exchange_under_nipping_press():
    for seed in (0, 1, 2):
        rec = _rec(DRIFT, seed)
        e = rec.extra
        t = rec.t
        assert 20 <= e["t0"] <= 60 and 60 <= e["tau_x"] <= 120 and 0.04 <= e["e_x"] <= 0.06
        # the exchanged share against solve_ivp of dX / dt = (1 - X) / tau_x from X = 0 at -t0 (1e-9: the solver's
        # tolerance)
        X = m59.ion_exchange(t, e["t0"], e["tau_x"])
        sol = solve_ivp(lambda s, z: [(1 - z[0]) / e["tau_x"]], (-e["t0"], t[-1]), [0.0], method="DOP853",
                        rtol=1e-12, atol=1e-13, dense_output=True)
        np.testing.assert_allclose(X, sol.sol(t)[0], rtol=0, atol=1e-9)
        drift = m59.exchange_drift(t, e["t0"], e["tau_x"], e["e_x"])
        np.testing.assert_allclose(drift, 1000.0 * e["e_x"] * (X - X[0]), rtol=0, atol=1e-9)
        h = _core_cached(DRIFT, seed)
        np.testing.assert_array_equal(h, e["h"])
        y = h + drift
        assert _rms(rec.y - y) < 1.5 * rec.noise_std
        # one way: the gap grows all through the record, by over 30 sigma
        assert np.all(np.diff(drift) > 0) and drift[-1] > 30 * rec.noise_std
        p = e["p"]
        assert p[0] == 0.0 and p[-1] == 0.0 and p.max() == pytest.approx(1.0, abs=1e-12)
        assert len(_holds(rec.v, int(8.0 / rec.t[1]))) >= 3
        # the exchange moves the reading beyond a gain and an offset on the film in a bath without calcium: over 7
        # sigma RMS and at most (measured 20.4 ... 24.2 RMS, 44 ... 60 at most)
        _big(rec, y, h)


# ---- asymmetry: the thermistor linearised about the bias, under a table-tennis bat ----

def test_linearised_thermistor_under_table_tennis_bat():
    for seed in (0, 1, 2):
        rec = _rec(ASYM, seed)
        e = rec.extra
        assert 4000 <= e["B"] <= 4700
        T_set = m59.temperature(e, e["drive"])
        Tk = e["Tb"] + 273.15
        # the film's temperature: the beta law's root in T of R(T) = R_set, by brentq (1e-10 K), at 300 samples
        for i in np.linspace(0, len(T_set) - 1, 300).astype(int):
            r_set = 1.0 - e["B"] * (T_set[i] - e["Tb"]) / Tk ** 2
            ref = brentq(lambda TT: math.exp(e["B"] * (1 / (TT + 273.15) - 1 / Tk)) - r_set, e["Tb"] - 20,
                         e["Tb"] + 20, xtol=1e-13)
            assert e["T"][i] == pytest.approx(ref, abs=1e-10)
        # hotter than asked above the bias, less cold below it (by over 0.2 K at the drive's ends: measured 1.2 ... 1.3
        # K and 0.8 ... 0.9 K)
        T = e["T"]
        assert T.max() - T_set.max() > 0.2 and T.min() - T_set.min() > 0.2
        y = m59.reading(T, m59.volume_share(e, T))
        assert _rms(rec.y - y) < 1.5 * rec.noise_std
        core = _core_cached(ASYM, seed)
        # the film's excursions from its start differ to the two sides by over 20 % of the larger (measured 31 %), the
        # core's by under 8 % (measured 2 ... 3 %)
        assert _lopsided(y) > 0.2 and _lopsided(core) < 0.08
        x = e["x"]
        assert x[0] == 0.0 and x[-1] == 0.0 and _full_both_ways(e)
        # the thermistor's law moves the reading beyond a gain and an offset on the film under a loop that converts by
        # the law itself: over 7 sigma RMS and at most (measured 9.0 ... 9.6 RMS, 37 ... 46 at most)
        _big(rec, y, core)


# ---- saturation: the heater's supply at its compliance, under a dental foot control ----

def test_heater_compliance_under_dental_foot_control():
    for seed in (0, 1, 2):
        rec = _rec(SAT, seed)
        e = rec.extra
        T_set = m59.temperature(e, e["drive"])
        assert 0.6 <= e["frac"] <= 0.75
        assert e["T_max"] == pytest.approx(T_set.min() + e["frac"] * np.ptp(T_set), abs=1e-12)
        assert e["T_w"] == e["Tb"] - 8.0
        # the chip's balance at the full voltage: T - T_w = 20 V_s^2 / (50 (1 + 3.85e-3 (T - 20))), its root in T by
        # brentq is T_max (1e-10 K)
        ref = brentq(lambda TT: TT - e["T_w"] - 20.0 * e["V_s"] ** 2 / (50.0 * (1 + 3.85e-3 * (TT - 20.0))),
                     e["T_w"], e["T_w"] + 100.0, xtol=1e-13)
        assert ref == pytest.approx(e["T_max"], abs=1e-10)
        T = np.minimum(T_set, e["T_max"])
        y = m59.reading(T, m59.volume_share(e, T))
        assert _rms(rec.y - y) < 1.5 * rec.noise_std
        # the film held at T_max wherever the set point is hotter: the reading constant over each such stretch (exact:
        # no microgel switches and none deswells at a constant temperature), the set point above T_max over 5 % of the
        # record or more
        held = T_set > e["T_max"]
        assert held.mean() > 0.05
        edges = np.flatnonzero(np.diff(held.astype(int)))
        for a, b in zip(edges[::2], edges[1::2]):
            seg = y[a + 1:b + 1]
            assert np.all(seg == seg[0])
        p = e["p"]
        assert p[0] == 0.0 and p[-1] == 0.0 and p.max() == pytest.approx(1.0, abs=1e-12)
        # the supply moves the reading beyond a gain and an offset on the film under an unlimited supply: over 7 sigma
        # RMS and at most (measured 42.5 ... 55.0 RMS, 87 ... 145 at most)
        _big(rec, y, _core_cached(SAT, seed))


# ---- delay: the DAC's output queue, under an engine-order telegraph ----

def test_dac_queue_under_engine_telegraph():
    for seed in (0, 1, 2):
        rec = _rec(DELAY, seed)
        e = rec.extra
        t = rec.t
        assert 120 <= e["n_b"] <= 260
        x_amp = e["amp"] / np.abs(e["x"]).max()
        # the queue written out: at every 53rd sample the DAC's sample that left the queue last (its index the
        # clock's count less n_b), the programme there (1e-12 V), 0 before the first left
        for i in range(0, len(t), 53):
            k = int(math.floor(t[i] * 1000.0 + 1e-9)) - e["n_b"]
            ref = 0.0 if k < 0 else float(x_amp * s59.knots_at(np.array([k / 1000.0]), e["knots"])[0])
            assert e["v_set"][i] == pytest.approx(ref, abs=1e-12)
        y = m59.core_reading(e, e["v_set"])
        assert _rms(rec.y - y) < 1.5 * rec.noise_std
        # a delay above all: the core of the drive read n_b ms late (on the record's grid, linear between samples)
        # leaves under 3 sigma RMS (the DAC's 1 ms hold; measured 0.07 ... 0.10)
        core = _core_cached(DELAY, seed)
        late = np.interp(t - e["n_b"] / 1000.0, t, core, left=0.0)
        assert _rms(late - y) < 3 * rec.noise_std
        x = e["x"]
        assert x[0] == 0.0 and x[-1] == 0.0 and _full_both_ways(e)
        assert len(_holds(e["drive"], int(1.5 / t[1]))) >= 6
        # the queue moves the reading beyond a gain and an offset on the set point at once: over 7 sigma RMS and at
        # most (measured 16.5 ... 23.3 RMS, 164 ... 249 at most)
        _big(rec, y, core)


# ---- initial state: a night at 45 C, under a pan pot ----

def test_hot_night_under_pan_pot():
    for seed in (0, 1, 2):
        rec = _rec(INIT, seed)
        e = rec.extra
        tc, ts = m59.domains(e)
        c = m59.hot_state(e)
        np.testing.assert_array_equal(c, e["c0"])
        # collapsed at 45 C wherever T_c lies below it, then cooled to the bias: reswollen where T_s lies above it
        # (written out); the microgels that never collapsed at 45 C are swollen at rest too
        ref = np.where(tc < 45.0, (ts <= e["Tb"]).astype(float), 0.0)
        np.testing.assert_array_equal(c, ref)
        rest = m59.rest_state(e, e["Tb"])
        assert np.all(rest[tc >= 45.0] == 0.0)
        # over 200 microgel classes collapsed that the conditioning leaves swollen (measured 296 ... 351 of 8000), none
        # the other way
        assert e["n_off"] == np.sum(c != rest) and e["n_off"] > 200 and np.all(c >= rest)
        model = m59.core_reading(e, e["drive"], c.copy())
        assert _rms(rec.y - model) < 1.5 * rec.noise_std
        # the check first: the drive within 5 % of its reach over the first 15 % of the record, the film within 20
        # sigma of the same film from the rest state there; then the pans' cold swings reswell the microgels the night
        # left collapsed, once, and the film (its gap zeroed at the start) sits thicker for the rest of the record: by
        # over 20 sigma over the record's second half (measured at least 41 ... 50; within 13 ... 15 over the check)
        x = e["x"]
        first = np.argmax(np.abs(x) > 0.051)
        assert x[0] == 0.0 and first > 0.15 * len(x) and _full_both_ways(e)
        core = _core_cached(INIT, seed)
        assert np.abs(model[:first] - core[:first]).max() < 20 * rec.noise_std
        assert np.all(core[len(x) // 2:] - model[len(x) // 2:] > 20 * rec.noise_std)
        # far from the same film from the rest state: over 7 sigma RMS beyond a gain and an offset and at most
        # (measured 13.7 ... 17.7 RMS, 30 ... 40 at most)
        _big(rec, model, core)


# ---- two effects: a nylon pad's creep and a gale on the air path, under a points lever ----

def test_nylon_pad_and_gale_under_points_lever():
    # the log kernel's means against quad (1e-12)
    dt, c0, c1, tau0 = 1 / 293, 0.04, 0.05, 0.3
    k = m59.log_kernel(3000, dt, c0, c1, tau0)
    for mm in (0, 1, 7, 100, 2999):
        ref = quad(lambda u: c0 + c1 * math.log1p(u / tau0), mm * dt, (mm + 1) * dt, epsabs=1e-15,
                   epsrel=1e-13)[0] / dt
        assert k[mm] == pytest.approx(ref, abs=1e-12)
    # von Karman's spectrum integrates to s_u^2 (quad; 1e-3 relative: the constant 70.8 is rounded, measured 2.4e-4),
    # and the waves' sum of S df keeps over 90 % of it
    U, I = 16.0, 0.18
    S = lambda f: 4 * (I * U) ** 2 * (150.0 / U) / (1 + 70.8 * (f * 150.0 / U) ** 2) ** (5 / 6)  # noqa: E731
    tot = quad(S, 0.0, np.inf, limit=400)[0]
    assert tot == pytest.approx((I * U) ** 2, rel=1e-3)
    for seed in (0, 1, 2):
        rec = _rec(PAIR, seed)
        e = rec.extra
        t = rec.t
        assert 0.045 <= e["c1"] <= 0.06 and 14 <= e["U"] <= 18 and 15 <= e["tau_l"] <= 30 and 100 <= e["l_mm"] <= 150
        d = e["d"]
        np.testing.assert_array_equal(d, _core_cached(PAIR, seed))
        kk = m59.log_kernel(len(t), t[1], e["c0"], e["c1"], e["tau0"])
        crept = m59.creep_reading(d, kk)
        idx = np.linspace(1, len(t) - 1, 12).astype(int)
        assert np.abs(_volterra_direct(crept, kk, d, idx)).max() < 1e-9
        # the gusts written out at 5 times (1e-9 m/s): sum_k sqrt(2 S(f_k) df) cos(2 pi f_k t + phi_k)
        n_lead = int(math.ceil(300.0 / t[1]))
        span = (len(t) - 1) * t[1] + n_lead * t[1]
        df = 1.0 / span
        ph = np.random.default_rng(e["gseed"]).uniform(0.0, 2 * math.pi, 400)
        Uk, Ik = e["U"], e["I"]
        Sk = lambda f: 4 * (Ik * Uk) ** 2 * (150.0 / Uk) / (1 + 70.8 * (f * 150.0 / Uk) ** 2) ** (5 / 6)  # noqa: E731
        for tt in (-300.0, -12.3, 0.0, 17.0, t[-1]):
            ref = sum(math.sqrt(2 * Sk((j + 0.5) * df) * df) * math.cos(2 * math.pi * (j + 0.5) * df * tt + ph[j])
                      for j in range(400))
            assert float(m59.gusts(np.array([tt]), Uk, Ik, e["gseed"], span)[0]) == pytest.approx(ref, abs=1e-9)
        assert sum(Sk((j + 0.5) * df) * df for j in range(400)) > 0.9 * (Ik * Uk) ** 2
        # the room's pressure against solve_ivp of tau_l p' = q - p over the record's last 3000 samples, q the wall's
        # pressure linear between samples, from the record's value there (1e-6 Pa: the solver's tolerance)
        drift, p_room = m59.gale_drift(t, Uk, Ik, e["gseed"], e["tau_l"], e["l_mm"])
        np.testing.assert_array_equal(p_room, e["p_room"])
        ts_ = t[-3000:]
        q = 0.7 * 0.6 * (Uk + m59.gusts(ts_, Uk, Ik, e["gseed"], span)) ** 2
        sol = solve_ivp(lambda s, z: [(np.interp(s, ts_, q) - z[0]) / e["tau_l"]], (ts_[0], ts_[-1]), [p_room[-3000]],
                        method="DOP853", rtol=1e-12, atol=1e-10, t_eval=ts_, max_step=t[1])
        np.testing.assert_allclose(p_room[-3000:], sol.y[0], rtol=0, atol=1e-6)
        # Edlen's index: the drift 1e9 l_d 2.7e-4 (p - p(0)) / 101325 nm (1e-9)
        np.testing.assert_allclose(drift, 1e9 * e["l_mm"] * 1e-3 * 2.7e-4 * (p_room - p_room[0]) / 101325.0, rtol=0,
                                   atol=1e-9)
        y = crept + drift
        assert _rms(rec.y - y) < 1.5 * rec.noise_std
        # a wander both ways: the drift rises and falls by over 5 sigma
        assert np.max(drift - np.minimum.accumulate(drift)) > 5 * rec.noise_std
        assert np.max(np.maximum.accumulate(drift) - drift) > 5 * rec.noise_std
        x = e["x"]
        assert x[0] == 0.0 and x[-1] == 0.0 and _full_both_ways(e)
        # each alone beyond a gain and an offset on the core, and each beyond those on the record without it: over 7
        # sigma RMS and at most (measured: the creep alone 8.3 ... 9.1 RMS, 27 ... 30 at most; the drift alone 11.2
        # ... 18.3, 22 ... 33; the creep beyond the drift 9.1 ... 10.1, 28 ... 29; the drift beyond the creep 11.3 ...
        # 18.4, 22 ... 33)
        for a_, b_ in ((crept, d), (d + drift, d), (y, d + drift), (y, crept)):
            _big(rec, a_, b_)


# ---- out of vocabulary: the film's reflectance read raw, under a windsurfer's boom ----

def _reflectance_matrix(d, lam):
    """The layer's reflectance by its characteristic matrix (Born & Wolf's, written out here): [B, C] = M [1, n_si],
    M = [[cos delta, -i sin delta / n_f], [-i n_f sin delta, cos delta]], r = (n_w B - C) / (n_w B + C)."""
    nf = 1.333 + (1.50 - 1.333) * 120.0 / d
    delta = 2 * math.pi * nf * d / lam
    B = math.cos(delta) + (-1j * math.sin(delta) / nf) * 3.88
    C = -1j * nf * math.sin(delta) + math.cos(delta) * 3.88
    r = (1.333 * B - C) / (1.333 * B + C)
    return abs(r) ** 2


def test_reflectance_fold_under_windsurfer_boom():
    for seed in (0, 1, 2):
        rec = _rec(OOV, seed)
        e = rec.extra
        T = m59.temperature(e, e["drive"])
        q = m59.volume_share(e, T)
        h = m59.reading(T, q)
        np.testing.assert_array_equal(h, e["h"])
        np.testing.assert_array_equal(h, _core_cached(OOV, seed))
        # the film's thickness at the start: 1000 (0.55 + 0.45 q0 + 4e-4 (T0 - 32)) nm (1e-9)
        assert e["d0"] == pytest.approx(1000.0 * (0.55 + 0.45 * q[0] + 4e-4 * (T[0] - 32.0)), abs=1e-9)
        # Airy's sum against the characteristic matrix at 50 thicknesses over the stroke (1e-12)
        for g in np.linspace(h.min(), h.max(), 50):
            dd = e["d0"] - g
            assert float(m59.reflectance(np.array([dd]), e["lam"])[0]) == pytest.approx(
                _reflectance_matrix(dd, e["lam"]), abs=1e-12)
        # a red diode (600 ... 700 nm) whose fringe's extremum (the reflectance's slope in the thickness 0, by brentq
        # on a central difference) lies within 5 nm of x_top: the Fresnel coefficients' change with the swelling's
        # index moves it a little (measured 3.3 nm)
        lam = e["lam"]
        assert 600.0 < lam < 700.0

        def slope(g):
            return _reflectance_matrix(e["d0"] - g - 1e-4, lam) - _reflectance_matrix(e["d0"] - g + 1e-4, lam)
        g_ext = brentq(slope, e["x_top"] - 10.0, e["x_top"] + 10.0, xtol=1e-9)
        assert abs(g_ext - e["x_top"]) < 5.0
        y = m59.reflectance_reading(h, e["d0"], lam)
        assert _rms(rec.y - y) < 1.5 * rec.noise_std
        # the fold: the film thins past x_top, and there the reading falls back by over 10 sigma from its top
        assert h.max() > e["x_top"] and y.max() - y[np.argmax(h)] > 10 * rec.noise_std
        x = e["x"]
        assert x[0] == 0.0 and _full_both_ways(e)
        # no monotone map of the core the recorded drive makes comes near the reading: over 30 sigma away (measured
        # 86 ... 141)
        hc = m59.core_reading(e, rec.v)
        o = np.argsort(hc)
        ys = rec.y[o]
        miss = min(np.abs(ys - isotonic_regression(ys, increasing=inc).x).max() for inc in (True, False))
        assert miss > 30 * rec.noise_std

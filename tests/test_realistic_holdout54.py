"""HOLDOUT54 (tests/realistic/cases_holdout54.py, laws in mechanisms54.py, signals in signals54.py): well formed, in ALL
since it was measured once (round 56), and every mechanism follows its law. Nothing here runs the diagnosis.

Tolerances: a record that is its stated law plus the sensor noise leaves a residual RMS within 1.5 sigma of the law (the
noise alone gives 1.0; the laws are evaluated on the clean drive). A law checked against an independent solution (the
crystallites' classes from the stated laws and a Kronecker sequence written out here; the spinodals as the extrema of
the Slichter-Drickamer temperature tau(x) by a bounded minimiser, every branch's fraction by brentq of tau(x) and every
class's branch by the last spinodal the temperature crossed, from the running extremes looking back; the rest state by
an explicit decaying thermal cycling; the creep kernel by quad and the Volterra solution by its own equation summed
directly and on a finer grid; the master equation by solve_ivp and twice the sub-steps; the hygrostat's period in closed
form and the sheet's uptake by Crank-Nicolson; the crank by its geometry; the sinc^3 filter by three boxes convolved and
each conversion by quad over the drive's programme; the warm-up by solve_ivp; the bridge from its resistances; the scale
from its sine and cosine; finer grids) agrees to the stated tolerance, set from the solvers' own tolerances or the
scheme's order (each stated beside it), far below sigma (2e-3 of the span; the master equation's sub-steps, where a
class caught near its saddle is decided apart by any two solutions, within half a sigma).

Effects are asked to move the output by at least 7 sigma beyond what a gain and an offset on the core absorb, both at
its largest and as an RMS over the whole record (the core: the same strip, rate independent, its temperature the set
point's, without the effect; the creep against the strip's own elongation; the rate dependence against the same strip
switching at once; the drift against the strip in a steady humidity; the asymmetry against the strip's travel; the
saturation against the free strip; the delay against the strip at the set point at once; the initial state against the
same strip from the rest state; the pair's asymmetry against a linear gauge and its drift against a gauge at a steady
temperature); the measured values for seeds 0 ... 2 are stated beside each (RMS; largest), in sigma: creep 8.4 ... 12.4
(47 ... 65), rate 20.2 ... 28.1 (80 ... 147), drift 11.6 ... 17.7 (20.6 ... 30.8), asymmetry 9.1 ... 9.9 (61 ... 68),
saturation 18.6 ... 26.3 (48.5 ... 66.2), delay 31.3 ... 37.7 (303 ... 353), initial state 84.9 ... 101.1 (112 ... 126),
the pair's warm-up drift alone 10.8 ... 11.8 (34.3 ... 40.9) and its bridge's asymmetry alone 9.2 ... 10.9 (23.2 ...
28.7) (and within the record: the drift beyond a gain and an offset on the asymmetric reading without it 10.4 ... 11.3
(34.1 ... 40.5), the asymmetry beyond those on the drifting reading without it 8.7 ... 10.2 (20.5 ... 28.0)); the
out-of-vocabulary wrap is 56 ... 72 sigma from any monotone map of the core the recorded drive makes. The creep (8.4,
seed 2) and the pair's asymmetry beyond its drift (8.7, seed 1) are the smallest margins in the set.

The pair, {asymmetry, drift}: the carriage read by a silicon gauge in a quarter bridge (the bridge's own nonlinearity, 2
r / (2 + r): smooth and convex in the stroke; the single asymmetry case's is a crank near its dead centre, read by its
angle: an arcsine) switched on with the record, the gauge warming by its own dissipation (a monotone two-time-constant
rise inside the bridge's nonlinearity; the single drift case's is an enclosure's humidity, a lopsided sawtooth taken up
through the matrix by diffusion).

The clean core's closeness to a Prandtl-Ishlinskii model, a PI model of 12 plays of the drive (set_checks.pi_fit_rms)
fitted by NNLS: it leaves 1.17 ... 1.41 sigma RMS on the clean record (seeds 0 ... 2; its largest residual 6.7 ... 6.8
sigma), where the core is far from a straight line (132 ... 147 sigma at most, stated below). What a PI model misses:
the loops' centres are normal, not a uniform density; a crystallite's loop widens with its interaction; its branches
bend with the temperature (the other spin state's thermal population, steepening as a square root toward the spinodal);
and the high-spin lattice's expansion multiplies the temperature by the high-spin fraction.
"""

import math
from functools import lru_cache

import numpy as np
import pytest
from scipy.integrate import quad, solve_ivp
from scipy.linalg import solve_banded
from scipy.optimize import brentq, isotonic_regression, minimize_scalar
from scipy.special import ndtri

import realistic
from realistic import HOLDOUT54
from realistic import cases_holdout54 as c54
from realistic import mechanisms54 as m54
from realistic import signals54 as s54
from test_realistic_generator import _assert_joined_ten, _linear_misfit, _rms
from realistic.set_checks import assert_knots_evaluator as _knots_evaluator
from realistic.set_checks import assert_relay_core as _relay_core, beyond_gain_and_offset as _fit, holds as _holds
from realistic.set_checks import pi_fit_rms as _pi_fit_rms

pytestmark = pytest.mark.slow

P = "holdout54_"
EFFECTS = {"creep", "rate_dependence", "drift", "asymmetry", "saturation", "initial_state", "delay"}
CLEAN = "clean_spin_crossover_strip_hammer_thrower_1531hz"
CREEP = "creep_nylon_pushrod_log_creep_dough_kneading_263hz"
RATE = "rate_micro_crystal_master_equation_unicyclist_1301hz"
DRIFT = "drift_hygrostat_matrix_swelling_cheese_press_211hz"
ASYM = "asymmetry_tilted_crank_angle_pizza_peel_877hz"
SAT = "saturation_travel_stop_slack_strip_bow_thruster_1019hz"
DELAY = "delay_sigma_delta_sinc3_tattoo_pedal_547hz"
INIT = "initial_state_post_bake_marshaller_wand_683hz"
PAIR = "pair_asymmetry_drift_quarter_bridge_warm_up_chimney_sweep_797hz"
OOV = "oov_magnetic_scale_period_wrap_bell_ringer_1117hz"
UNIPOLAR = {CREEP, DRIFT, DELAY}
MONITORED = {CLEAN: 2e-4, RATE: 3e-4, SAT: 2.5e-4, DELAY: 3e-4}
ORDER = ("clean_", "creep_", "rate_", "drift_", "asymmetry_", "saturation_", "delay_", "initial_state_", "pair_",
         "oov_")
#: the figures measured (in sigma), filled as the tests run: (kind, what, seed) -> (RMS, largest)
MEASURED = {}


@lru_cache(maxsize=None)
def _rec(name, seed):
    return HOLDOUT54[P + name](seed)


@lru_cache(maxsize=None)
def _core_cached(name, seed):
    """The core's reading for a record's clean drive, from the rest state (cached: several checks use it)."""
    e = _rec(name, seed).extra
    return m54.core_reading(e, e["drive"])


def _big(rec, a, b, what="", floor=7.0):
    """(RMS, largest) of a beyond a gain and an offset on b, in sigma; both asked over `floor`."""
    mx, rms = _fit(a, b)
    MEASURED[(rec.name[len(P):].split("_")[0], what, rec.seed)] = (rms / rec.noise_std, mx / rec.noise_std)
    assert rms > floor * rec.noise_std and mx > floor * rec.noise_std, (rec.name, what, rms / rec.noise_std)
    return rms / rec.noise_std, mx / rec.noise_std


def _full_both_ways(e):
    """The programme reaches the full reach both ways (its knots), and the sampled drive within 1e-3 of it."""
    kx = [k[1] for k in e["knots"]]
    return max(kx) == 1.0 and min(kx) == -1.0 and e["x"].max() > 0.999 and e["x"].min() < -0.999


def _lopsided(u):
    """How far the excursions from the first sample differ to the two sides, over the larger."""
    u = np.asarray(u) - u[0]
    return abs(u.max() + u.min()) / max(u.max(), -u.min())


# ---- the set ----

def test_holdout54_is_well_formed_and_in_all():
    H = HOLDOUT54
    assert c54.HOLDOUT54 is H and realistic.HOLDOUT54 is H and "HOLDOUT54" in realistic.__all__
    # every drive starts at 0 V, the initial-state case's too (its strip starts elsewhere, not its drive)
    _assert_joined_ten(H, P, EFFECTS, ORDER, _rec, MONITORED, UNIPOLAR, PAIR, {"asymmetry", "drift"}, ASYM)


def test_reach_and_programmes():
    # the cycloidal rise against quad of its speed 1 - cos(2 pi s) (1e-12); its speed by central differences (1e-6)
    # and its peak at the middle, twice the mean speed (1e-12)
    for sv in np.linspace(0.0, 1.0, 41):
        ref = quad(lambda u: 1 - math.cos(2 * math.pi * u), 0.0, sv, epsabs=1e-15, epsrel=1e-13)[0]
        assert float(s54.reach(sv)) == pytest.approx(ref, abs=1e-12)
    assert s54.reach(0.0) == 0.0 and s54.reach(1.0) == 1.0 and s54.reach(-0.5) == 0.0 and s54.reach(1.5) == 1.0
    si = np.linspace(0.01, 0.99, 99)
    sp = (s54.reach(si + 1e-6) - s54.reach(si - 1e-6)) / 2e-6
    np.testing.assert_allclose(sp, s54.reach_speed(si), rtol=0, atol=1e-6)
    assert float(s54.reach_speed(0.5)) == pytest.approx(2.0, abs=1e-12)
    # the knots' evaluator against a direct search (1e-12), the first knot's value before and the last's after
    _knots_evaluator(s54.reach, s54.knots_at)
    rng = np.random.default_rng(7)
    # the unicyclist never still; the marshaller's wand within 0.04 for its first 14 s; the unipolar programmes within
    # 0 ... 1 and reaching 1
    kx = [k[1] for k in s54.unicyclist(rng, 3)[0]]
    assert all(a != b for a, b in zip(kx, kx[1:]))
    kn, _ = s54.marshaller(rng, 6)
    assert max(abs(x) for t, x in kn if t <= 14.0) <= 0.04 and max(x for t, x in kn) == 1.0
    for gen in (s54.dough_kneading, s54.cheese_press, s54.tattoo_pedal):
        xs = [x for t, x in gen(rng, 2)[0]]
        assert min(xs) >= 0.0 and max(xs) == 1.0


# ---- the core: a spin-crossover strip's crystallites ----

def _crystallites_written_out(e):
    """The classes' (T_half, kappa) from the stated laws: the R2 sequence k (1/phi, 1/phi^2) + shift mod 1, phi the
    real root of x^3 = x + 1 (found here by brentq); T_half normal, kappa the log-normal's quantile at the middle of
    its stratum (24 strata)."""
    phi = brentq(lambda x: x ** 3 - x - 1, 1.0, 2.0, xtol=1e-15)
    shift = np.random.default_rng(e["rseed"]).uniform(size=2)
    k = np.arange(1, 3001)[:, None]
    u = np.modf(shift[None, :] + k * np.array([phi ** -1, phi ** -2])[None, :])[0]
    u = np.clip(u, 1e-12, 1 - 1e-12)
    th = e["Th0"] + e["sh"] * ndtri(u[:, 0])
    j = np.floor(u[:, 1] * 24).astype(int)
    return th, e["k50"] * np.exp(0.04 * ndtri((j + 0.5) / 24))


def _tau_of_x(x, kappa):
    """The Slichter-Drickamer equilibrium written for the temperature: tau = T / T_half = (DS / R + 2 kappa (1 - 2 x))
    / (DS / R - ln(x / (1 - x))), from Delta_H - T Delta_S + Gamma (1 - 2 x) + R T ln(x / (1 - x)) = 0."""
    a = 60.0 / 8.314462618
    return (a + 2 * kappa * (1 - 2 * x)) / (a - math.log(x / (1 - x)))


def _spinodals_by_extrema(kappa):
    """tau_up and tau_dn as the local maximum and minimum of tau(x) (S-shaped for kappa > 1), by bounded minimisation
    on either side of x = 1/2 (xatol 1e-12)."""
    o = dict(xatol=1e-12, maxiter=500)
    xu = minimize_scalar(lambda x: -_tau_of_x(x, kappa), bounds=(1e-9, 0.5), method="bounded", options=o).x
    xd = minimize_scalar(lambda x: _tau_of_x(x, kappa), bounds=(0.5, 1 - 1e-9), method="bounded", options=o).x
    return _tau_of_x(xu, kappa), _tau_of_x(xd, kappa), xu, xd


def _x_by_brentq(tau, kappa, branch, xu, xd):
    """The high-spin fraction on a branch at tau: the root of tau(x) = tau in (0, x_u) (low spin) or (x_d, x*) (high
    spin; x* where the denominator vanishes), by brentq (xtol 1e-15)."""
    xstar = 1 / (1 + math.exp(-60.0 / 8.314462618))
    if branch == 0:
        return brentq(lambda x: _tau_of_x(x, kappa) - tau, 1e-300, xu, xtol=1e-15, rtol=1e-15)
    return brentq(lambda x: _tau_of_x(x, kappa) - tau, xd, xstar - 1e-15, xtol=1e-15, rtol=1e-15)


def _branch_by_history(T, i, up, dn, s0):
    """Every crystallite's branch at T[i] from the definition: the last of its spinodals the temperature crossed up to
    then (high spin where it last rose above T_up, low spin where it last fell below T_dn), else its first branch s0.
    (The last crossing is found from the running extremes looking back from i.)"""
    back = T[:i + 1][::-1]
    rmax, rmin = np.maximum.accumulate(back), np.minimum.accumulate(back)
    m_up = np.searchsorted(rmax, up, side="right")
    m_dn = np.searchsorted(-rmin, -dn, side="right")
    return np.where(m_up < m_dn, 1.0, np.where(m_dn < m_up, 0.0, s0))


def _reading_written_out(T, xbar):
    """1e6 L (e - e(0)), e = 0.4 / 3 (0.1 xbar + (1.0e-4 (1 - xbar) + 1.6e-4 xbar) (T - T0)) + 0.6 * 1.2e-4 (T - T0),
    L = 25 mm, T0 the first temperature (um)."""
    d = T - T[0]
    e = 0.4 / 3 * (0.1 * xbar + (1.0e-4 * (1 - xbar) + 1.6e-4 * xbar) * d) + 0.6 * 1.2e-4 * d
    return 1e6 * 25e-3 * (e - e[0])


def test_core_crystallites_branches_and_reading_against_their_definitions():
    for seed in (0, 1, 2):
        rec = _rec(CLEAN, seed)
        e = rec.extra
        th, lev = m54.crystallites(e)
        th_w, kap_w = _crystallites_written_out(e)
        # (1e-7 K: the sequence's rounding, some 1e-12 in a quantile at k = 3000, through the normal quantile's slope)
        np.testing.assert_allclose(th, th_w, rtol=0, atol=1e-7)
        np.testing.assert_allclose(m54.levels(e["k50"])[lev], kap_w, rtol=1e-13)
        assert kap_w.min() > 1.05
        t_up, t_dn, xl, xh = m54.tables(e["k50"])
        for j, kap in enumerate(m54.levels(e["k50"])):
            # the spinodals against the extrema of tau(x) (1e-9: the bounded minimiser's xatol through the extremum's
            # curvature, measured under 1e-15)
            tu, td, xu, xd = _spinodals_by_extrema(kap)
            assert t_up[j] == pytest.approx(tu, abs=1e-9) and t_dn[j] == pytest.approx(td, abs=1e-9)
            if seed == 0 and j % 6 == 0:
                # the branches' tables at 30 points each, up to 1e-9 of the spinodal, against brentq of tau(x) (1e-7:
                # linear interpolation in the square root of the distance to the spinodal, steps of some 1.1e-4 in it;
                # measured under 2e-8)
                for tau in np.r_[np.linspace(0.9, tu - 1e-5, 25), tu - np.logspace(-6, -9, 5)]:
                    assert m54.branch_x(xl[j], t_up[j], m54.TAU_LO, tau, True) == pytest.approx(
                        _x_by_brentq(tau, kap, 0, xu, xd), abs=1e-7)
                for tau in np.r_[np.linspace(td + 1e-5, 1.1, 25), td + np.logspace(-6, -9, 5)]:
                    assert m54.branch_x(xh[j], t_dn[j], m54.TAU_HI, tau, False) == pytest.approx(
                        _x_by_brentq(tau, kap, 1, xu, xd), abs=1e-7)
        # the bias is the median of the loops' middles (exact)
        mid = 0.5 * (t_up[lev] + t_dn[lev]) * th
        assert e["Tb"] == float(np.median(mid))
        v = e["drive"]
        T = m54.temperature(e, v)
        np.testing.assert_allclose(T, e["Tb"] + 0.16 * v, rtol=0, atol=1e-12)
        s0 = (mid < T[0]).astype(float)
        np.testing.assert_array_equal(m54.rest_state(e, T[0]), s0)
        xbar = m54.hs_fraction(e, T)
        # 150 of the classes (every 20th) run alone through the same ensemble, at 10 samples, against every class's
        # branch from its history and its fraction by brentq on that branch (1e-7: the tables' interpolation, above)
        sub = slice(0, None, 20)
        s_sub = s0[sub].copy()
        t_sub = (t_up[lev[sub]], t_dn[lev[sub]])
        x_sub = m54._ensemble(T, th[sub], lev[sub], t_up, t_dn, xl, xh, s_sub)
        picks = np.r_[0, np.linspace(1, len(T) - 1, 9).astype(int)]
        kaps = m54.levels(e["k50"])[lev[sub]]
        ext = {k: _spinodals_by_extrema(k)[2:] for k in set(kaps.tolist())}
        switched = 0.0
        for i in picks:
            br = _branch_by_history(T, i, t_sub[0] * th[sub], t_sub[1] * th[sub], s0[sub])
            switched = np.maximum(switched, br != s0[sub])
            ref = np.mean([_x_by_brentq(T[i] / t, k, b, *ext[k]) for t, k, b in zip(th[sub], kaps, br)])
            assert x_sub[i] == pytest.approx(ref, abs=1e-7)
        # the crystallites switch over the record: over 10 % of them on the other branch at some pick (the loop is not
        # empty; measured 12 ... 21 %)
        MEASURED[("clean", "switched", seed)] = (float(np.mean(switched)),) * 2
        assert np.mean(switched) > 0.1
        y = m54.reading(T, xbar)
        np.testing.assert_allclose(y, _reading_written_out(T, xbar), rtol=0, atol=1e-9)
        assert _rms(rec.y - y) < 1.5 * rec.noise_std
        x = e["x"]
        assert x[0] == 0.0 and x[-1] == 0.0 and _full_both_ways(e)
        assert len(_holds(v, int(1.0 / rec.t[1]))) >= 2


def test_rest_state_is_the_limit_of_a_decaying_cycling():
    e = dict(_rec(CLEAN, 0).extra)
    Tb = e["Tb"]
    # from every crystallite low spin, a cycling about the bias decaying from 25 K by 0.2 % a half cycle (its turning
    # points: the core is rate independent) leaves the rest state's branches, but for the classes whose loop's middle
    # lies within the last steps of the bias (measured: none of 3000), and the reading within 0.5 sigma of the rest
    # state's (a class's switch is some 0.08 um, 0.4 sigma; measured 0)
    s = np.zeros(m54.N_CRYST)
    amp = 25.0 * 0.998 ** np.arange(9000)
    m54.hs_fraction(e, np.r_[Tb + amp * (-1.0) ** np.arange(9000), Tb], s)
    assert np.sum(s != m54.rest_state(e, Tb)) <= 3
    y_cycled = m54.core_reading(e, e["drive"], s)
    assert np.abs(y_cycled - _core_cached(CLEAN, 0)).max() < 0.5 * _rec(CLEAN, 0).noise_std


def test_core_return_point_memory_rate_independence_and_pi_closeness():
    e = dict(_rec(CLEAN, 0).extra)
    # a minor loop from a turning point closes there and leaves no trace (1e-12 um): return-point memory; it is a loop:
    # at 0 V its rising branch lies over 0.5 um (2 sigma) below its falling one (measured 0.89 um); rate independent:
    # the drive played on another time grid (every sample twice) reads the same at the same drive
    _relay_core(lambda v: m54.core_reading(e, v), e["drive"], 0.5)
    for seed in (0, 1, 2):
        rec = _rec(CLEAN, seed)
        # a PI model of 12 plays fitted by NNLS leaves 0.8 ... 2.0 sigma RMS (measured 1.17 ... 1.41) and at most 10
        # sigma (measured 6.7 ... 6.8), where the core is far from a straight line (over 60 sigma: measured 132 ... 147)
        r, m = _pi_fit_rms(rec.y, rec.v)
        MEASURED[("clean", "pi", seed)] = (r / rec.noise_std, m / rec.noise_std)
        assert 0.8 * rec.noise_std < r < 2.0 * rec.noise_std and m < 10 * rec.noise_std
        lin = _linear_misfit(_core_cached(CLEAN, seed), rec.v)
        MEASURED[("clean", "linear", seed)] = (lin / rec.noise_std, lin / rec.noise_std)
        assert lin > 60 * rec.noise_std


# ---- creep: a nylon pushrod, under a baker kneading dough ----

def test_log_creep_pushrod_under_dough_kneading():
    # the kernel: c_0 + c_1 ln(1 + t / tau_c)'s mean over each sample interval, against quad (1e-12)
    dt, c0, c1, tc = 1 / 263, 0.05, 0.05, 0.1
    k = m54.log_creep_kernel(3000, dt, c0, c1, tc)
    for mm in (0, 1, 7, 100, 2999):
        ref = quad(lambda u: c0 + c1 * math.log1p(u / tc), mm * dt, (mm + 1) * dt, epsabs=1e-15)[0] / dt
        assert k[mm] == pytest.approx(ref, abs=1e-12)
    # with c_1 = 0 (an elastic rod) a step of d gives x = d / (1 + c_0) at once and for ever (1e-12)
    d = np.r_[0.0, np.full(200, 10.0)]
    x = m54.volterra_creep(d, m54.log_creep_kernel(201, dt, c0, 0.0, tc))
    np.testing.assert_allclose(x[1:], 10.0 / (1 + c0), rtol=0, atol=1e-12)
    for seed in (0, 1, 2):
        rec = _rec(CREEP, seed)
        e = rec.extra
        t, dt = rec.t, rec.t[1]
        assert 0.04 <= e["c0"] <= 0.07 and 0.04 <= e["c1"] <= 0.06 and 0.05 <= e["tau_c"] <= 0.2
        dd = e["d"]
        np.testing.assert_array_equal(dd, _core_cached(CREEP, seed))
        kk = m54.log_creep_kernel(len(t), dt, e["c0"], e["c1"], e["tau_c"])
        y = m54.volterra_creep(dd, kk)
        # the Volterra equation summed directly at 12 samples: x_i + sum_(1 <= j <= i) (x_j - x_(j-1)) k_(i-j) = d_i
        # (1e-9 um: the sums' rounding)
        dx = np.diff(y, prepend=y[0])
        for i in np.linspace(1, len(y) - 1, 12).astype(int):
            assert y[i] + float(np.dot(dx[1:i + 1], kk[:i][::-1])) == pytest.approx(dd[i], abs=1e-9)
        assert _rms(rec.y - y) < 1.5 * rec.noise_std
        if seed == 0:
            # on a grid twice as fine (the strip's reading linear between samples) the poppet moves by under 0.1 sigma
            # RMS at the record's samples (measured 3e-6 sigma)
            d2 = np.interp(np.arange(2 * len(t) - 1) * dt / 2, t, dd)
            y2 = m54.volterra_creep(d2, m54.log_creep_kernel(len(d2), dt / 2, e["c0"], e["c1"], e["tau_c"]))[::2]
            MEASURED[("creep", "grid", 0)] = (_rms(y2 - y) / rec.noise_std,) * 2
            assert _rms(y2 - y) < 0.1 * rec.noise_std
        # after every push held, the poppet sags back while the strip stands: over 1 sigma in the holds of 0.3 s or
        # more at the top (in at least 5 of them)
        sags = [y[a] - y[b - 1] for a, b in _holds(e["drive"], int(0.3 / dt))
                if e["drive"][a] > 0.5 * e["top"]]
        assert sum(s > rec.noise_std for s in sags) >= 5
        p = e["p"]
        assert p[0] == 0.0 and p[-1] == 0.0 and p.max() == pytest.approx(1.0, abs=1e-12)
        # the creep moves the reading beyond a gain and an offset on the strip's own elongation: over 7 sigma RMS and
        # at most (measured 8.4 ... 12.4 RMS, 47 ... 65 at most)
        _big(rec, y, dd, "creep")


# ---- rate dependence: micro-crystals' master equation, under a unicyclist ----

def test_master_equation_under_unicyclist():
    e0 = dict(_rec(RATE, 0).extra)
    th, lev = m54.crystallites(e0)
    kap = m54.levels(e0["k50"])[lev]
    # a held temperature: the master equation's fixed point is the branch it starts on (the tables' value, 2e-6)
    T_hold = np.full(4000, e0["Tb"] + 2.0)
    x_hold = m54.kinetic_fraction(e0, T_hold, 1 / 1301, 0.03)
    assert x_hold[-1] == pytest.approx(float(m54.hs_fraction(e0, T_hold[:2])[-1]), abs=2e-6)
    for seed in (0, 1, 2):
        rec = _rec(RATE, seed)
        e = rec.extra
        t, dt = rec.t, rec.t[1]
        assert 0.025 <= e["tau_k"] <= 0.04
        T = m54.temperature(e, e["drive"])
        y = m54.reading(T, e["xbar"])
        assert _rms(rec.y - y) < 1.5 * rec.noise_std
        x = e["x"]
        kx = [k[1] for k in e["knots"]]
        assert x[0] == 0.0 and _full_both_ways(e) and all(a != b for a, b in zip(kx, kx[1:]))
        if seed == 0:
            # 40 classes (every 75th) by solve_ivp of dx/dt = [(1 - x) e^(-a/2) - x e^(a/2)] / tau_k (Radau, rtol
            # 1e-9), the temperature linear between samples, over the record's first 4500 samples: the sub-steps' mean
            # within 5e-5 of it (the frozen a's first order in the sub-step; measured 2.9e-5), 0.02 um in the
            # reading, 0.1 sigma. (A little later one of the 40, caught by a drive that turns just past its lower
            # spinodal, lingers near its saddle, where any two solutions part: the window ends before.)
            sub = slice(0, None, 75)
            th_s, kap_s = th[sub], kap[sub]
            t_up, t_dn, xl, xh = m54.tables(e["k50"])
            s0 = m54.rest_state(e, T[0])[sub]
            x0 = np.array([m54.branch_x(xh[j], t_dn[j], m54.TAU_HI, T[0] / tt, False) if sk > 0.5 else
                           m54.branch_x(xl[j], t_up[j], m54.TAU_LO, T[0] / tt, True)
                           for tt, j, sk in zip(th_s, lev[sub], s0)])
            n = 4500
            mine = m54._kinetic(T[:n], th_s, kap_s, x0.copy(), dt / m54.SUB_KIN / e["tau_k"], m54.SUB_KIN)
            a_ = 60.0 / 8.314462618

            def rhs(tt, xx):
                Ti = np.interp(tt, t[:n], T[:n])
                tau = Ti / th_s
                a = (a_ * (1 - tau) + 2 * kap_s * (1 - 2 * xx)) / tau
                return ((1 - xx) * np.exp(-a / 2) - xx * np.exp(a / 2)) / e["tau_k"]
            sol = solve_ivp(rhs, (0, t[n - 1]), x0, method="Radau", rtol=1e-9, atol=1e-12, t_eval=t[:n],
                            max_step=dt)
            err = np.abs(sol.y.mean(axis=0) - mine).max()
            MEASURED[("rate", "ivp", 0)] = (err, err)
            assert err < 5e-5
            # twice the sub-steps move the reading over the first 12000 samples by under 0.5 sigma RMS (measured
            # 0.24: the few classes the drive leaves near their saddles, whose fate any two solutions decide
            # apart)
            x8 = m54.kinetic_fraction(e, T[:12000], dt, e["tau_k"], sub=2 * m54.SUB_KIN)
            d8 = _rms(m54.reading(T[:12000], x8) - y[:12000]) / rec.noise_std
            MEASURED[("rate", "sub", 0)] = (d8, d8)
            assert d8 < 0.5
        # the finite speed moves the reading beyond a gain and an offset on the same strip switching at once: over 7
        # sigma RMS and at most (measured 20.2 ... 28.1 RMS, 80 ... 147 at most)
        _big(rec, y, _core_cached(RATE, seed), "rate")


# ---- drift: an enclosure's hygrostat, under a cheesemaker's press ----

def _sheet_fd(times, rh, thick, D, nz=200):
    """The plane sheet's mean uptake by Crank-Nicolson in its half-thickness (nz cells, symmetric at the middle, the
    face at the air's RH), from the sheet at the first RH."""
    hz = thick / 2 / nz
    dtt = times[1] - times[0]
    lam = D * dtt / hz ** 2
    c = np.full(nz, rh[0])
    ab = np.zeros((3, nz))
    ab[0, 1:], ab[1, :], ab[2, :-1] = -lam / 2, 1 + lam, -lam / 2
    ab[1, 0] = 1 + lam / 2  # the middle: no flux
    ab[1, -1] = 1 + 3 * lam / 2  # the face: the air's RH half a cell away
    out = np.empty(len(rh))
    out[0] = rh[0]
    for i in range(1, len(rh)):
        lap = np.empty(nz)
        lap[1:-1] = c[:-2] - 2 * c[1:-1] + c[2:]
        lap[0] = c[1] - c[0]
        lap[-1] = c[-2] - 3 * c[-1] + 2 * rh[i - 1]
        rhs = c + lam / 2 * lap
        rhs[-1] += lam * rh[i]
        c = solve_banded((1, 1), ab, rhs)
        out[i] = c.mean()
    return out


def test_hygrostat_swelling_under_cheese_press():
    for seed in (0, 1, 2):
        rec = _rec(DRIFT, seed)
        e = rec.extra
        t, dt = rec.t, rec.t[1]
        assert 45 <= e["S"] <= 50 and 6 <= e["b"] <= 8 and 40 <= e["tau_e"] <= 60 and 1.5e-11 <= e["D"] <= 2.5e-11
        times, rh = m54.hygrostat(t[-1], 600.0, e["S"], e["b"], e["rh_hi"], e["rh_lo"], e["tau_e"])
        # the limit cycle's period against its closed form: the rise through the band toward RH_hi and the fall toward
        # RH_lo, tau ln((target - start) / (target - end)) each (within 0.1 s: the switching waits for the loop's 0.05
        # s steps)
        lo_, hi_ = e["S"] - e["b"] / 2, e["S"] + e["b"] / 2
        period = e["tau_e"] * (math.log((e["rh_hi"] - lo_) / (e["rh_hi"] - hi_))
                               + math.log((hi_ - e["rh_lo"]) / (lo_ - e["rh_lo"])))
        ups = times[1:][(rh[1:] > hi_) & (rh[:-1] <= hi_)]
        assert len(ups) >= 4 and np.all(np.abs(np.diff(ups) - period) < 0.1)
        # the sheet's uptake against Crank-Nicolson over the record and 300 s before it (0.02 % RH, 0.08 um: the
        # scheme's second order on 200 cells and 0.05 s; measured 2.1e-5 % RH)
        keep = times >= -300.0
        U = m54.sheet_uptake(times, rh, 60e-6, e["D"])
        if seed == 0:
            fd = _sheet_fd(times[keep], rh[keep], 60e-6, e["D"])
            U2 = m54.sheet_uptake(times[keep], rh[keep], 60e-6, e["D"])
            err = np.abs(fd - U2)[int(60 / 0.05):].max()
            MEASURED[("drift", "fick", 0)] = (err, err)
            assert err < 0.02
        Ut = np.interp(t, times, U)
        np.testing.assert_array_equal(Ut, e["U"])
        drift = 1e6 * 25e-3 * 1.6e-4 * (Ut - Ut[0])
        h = _core_cached(DRIFT, seed)
        np.testing.assert_array_equal(h, e["h"])
        y = h + drift
        assert _rms(rec.y - y) < 1.5 * rec.noise_std
        # not a ramp: the drift moves both ways by over 5 sigma
        assert np.max(drift - np.minimum.accumulate(drift)) > 5 * rec.noise_std
        assert np.max(np.maximum.accumulate(drift) - drift) > 5 * rec.noise_std
        p = e["p"]
        assert p[0] == 0.0 and p[-1] == 0.0 and p.max() == pytest.approx(1.0, abs=1e-12)
        assert len(_holds(rec.v, int(10.0 / dt))) >= 2
        # the swelling moves the reading beyond a gain and an offset on the strip in a steady humidity: over 7 sigma
        # RMS and at most (measured 11.6 ... 17.7 RMS, 20.6 ... 30.8 at most)
        _big(rec, y, h, "drift")


# ---- asymmetry: a tilted crank read by its angle, under a pizzaiolo's peel ----

def test_tilted_crank_under_pizza_peel():
    for seed in (0, 1, 2):
        rec = _rec(ASYM, seed)
        e = rec.extra
        assert 0.25 <= e["rho"] <= 0.3 and math.radians(38) <= e["theta0"] <= math.radians(42)
        d = _core_cached(ASYM, seed)
        np.testing.assert_array_equal(d, e["d"])
        assert e["r_um"] == pytest.approx(np.abs(d).max() / e["rho"], rel=1e-14)
        y = m54.crank_reading(d, e["r_um"], e["theta0"])
        # the geometry: the pin at the angle theta = theta_0 + y / r lies x = r (sin theta - sin theta_0) along
        # (1e-9 um), and the crank stays short of its dead centre (theta under 80 deg)
        th_ = e["theta0"] + y / e["r_um"]
        np.testing.assert_allclose(e["r_um"] * (np.sin(th_) - math.sin(e["theta0"])), d, rtol=0, atol=1e-9)
        assert th_.max() < math.radians(80)
        assert _rms(rec.y - y) < 1.5 * rec.noise_std
        # the reading's excursions to the two sides differ by over 20 % of the larger (measured 35 ... 36 %; the strip's
        # 0.02 ... 1.3 %), the strip's by under 15 %
        MEASURED[("asymmetry", "lopsided", seed)] = (_lopsided(y), _lopsided(d))
        assert _lopsided(y) > 0.2 and _lopsided(d) < 0.15
        x = e["x"]
        assert x[0] == 0.0 and x[-1] == 0.0 and _full_both_ways(e)
        # the crank moves the reading beyond a gain and an offset on the strip's travel: over 7 sigma RMS and at most
        # (measured 9.1 ... 9.9 RMS, 61 ... 68 at most)
        _big(rec, y, d, "asymmetry")


# ---- saturation: the carriage on its travel stop, under a bow-thruster joystick ----

def test_travel_stop_under_bow_thruster():
    for seed in (0, 1, 2):
        rec = _rec(SAT, seed)
        e = rec.extra
        d = _core_cached(SAT, seed)
        np.testing.assert_array_equal(d, e["d"])
        assert 0.55 <= e["frac"] <= 0.7 and e["g"] == pytest.approx(e["frac"] * d.max(), rel=1e-14)
        y = m54.stop_reading(d, e["g"])
        # on the stop the reading is g exactly, off it the strip's
        on = d >= e["g"]
        assert np.all(y[on] == e["g"]) and np.array_equal(y[~on], d[~on])
        assert on.mean() > 0.03
        assert _rms(rec.y - y) < 1.5 * rec.noise_std
        x = e["x"]
        assert x[0] == 0.0 and _full_both_ways(e)
        # the stop moves the reading beyond a gain and an offset on the free strip: over 7 sigma RMS and at most
        # (measured 18.6 ... 26.3 RMS, 48.5 ... 66.2 at most)
        _big(rec, y, d, "saturation")


# ---- delay: a sigma-delta converter's sinc^3 filter, under a tattoo artist's pedal ----

def test_sigma_delta_under_tattoo_pedal():
    # the sinc^3's weight is three boxes of width Tc convolved (on a grid of Tc / 2000: 1e-3 / Tc, the grid's first
    # order) with unit mass (1e-12) and its mean lag 1.5 Tc (1e-12)
    Tc = 0.04
    hbox = Tc / 2000
    box = np.full(2000, 1 / Tc)
    conv = np.convolve(np.convolve(box, box), box) * hbox * hbox
    s_ = (np.arange(len(conv)) + 1.5) * hbox
    np.testing.assert_allclose(m54.bspline3(s_, Tc), conv, rtol=0, atol=1e-3 / Tc)
    assert quad(lambda s: float(m54.bspline3(s, Tc)), 0, 3 * Tc, points=[Tc, 2 * Tc])[0] == pytest.approx(1, abs=1e-12)
    assert quad(lambda s: s * float(m54.bspline3(s, Tc)), 0, 3 * Tc, points=[Tc, 2 * Tc])[0] == pytest.approx(
        1.5 * Tc, abs=1e-12)
    for seed in (0, 1, 2):
        rec = _rec(DELAY, seed)
        e = rec.extra
        t = rec.t
        assert 20 <= e["f_d"] <= 30 and e["Tc"] == pytest.approx(1 / e["f_d"], rel=1e-14) and 0 <= e["phase"] <= e["Tc"]
        pmax = e["p"].max()

        def drive_at(tt):
            return e["top"] * s54.knots_at(np.atleast_1d(tt), e["knots"]) / pmax
        # at every 211th sample the conversion whose window ended last, against quad of B(s) x(t_k - s) over the
        # drive's own programme (1e-6 V: the quadrature's; measured under 1e-9)
        for i in range(0, len(t), 211):
            k = math.floor((t[i] - e["phase"]) / e["Tc"])
            if k < 0:
                assert e["v_set"][i] == 0.0
                continue
            tk = e["phase"] + k * e["Tc"]
            ref = quad(lambda s: float(m54.bspline3(s, e["Tc"])) * float(drive_at(max(tk - s, 0.0))[0]), 0,
                       3 * e["Tc"], points=[e["Tc"], 2 * e["Tc"]], epsabs=1e-11, limit=200)[0]
            assert e["v_set"][i] == pytest.approx(ref, abs=1e-6)
        y = m54.core_reading(e, e["v_set"])
        assert _rms(rec.y - y) < 1.5 * rec.noise_std
        p = e["p"]
        assert p[0] == 0.0 and p[-1] == 0.0 and max(k[1] for k in e["knots"]) == 1.0
        # the converter moves the reading beyond a gain and an offset on the strip at the set point at once: over 7
        # sigma RMS and at most (measured 31.3 ... 37.7 RMS, 303 ... 353 at most)
        _big(rec, y, _core_cached(DELAY, seed), "delay")


# ---- initial state: fresh from the post-bake, under a marshaller's wand ----

def test_post_bake_under_marshaller_wand():
    for seed in (0, 1, 2):
        rec = _rec(INIT, seed)
        e = rec.extra
        th, lev = m54.crystallites(e)
        t_up, t_dn = m54.tables(e["k50"])[:2]
        s = m54.baked_state(e)
        np.testing.assert_array_equal(s, e["s0"])
        # every class high spin at 80 C (every upper spinodal below it), then cooled to the bias: high spin exactly
        # where its lower spinodal lies below the bias (written out)
        assert np.all(t_up[lev] * th < 353.15)
        np.testing.assert_array_equal(s, (t_dn[lev] * th < e["Tb"]).astype(float))
        # over 300 classes high spin that the conditioning leaves low spin (measured 737 ... 863 of 3000)
        rest = m54.rest_state(e, e["Tb"])
        assert e["n_off"] == np.sum(s != rest) and e["n_off"] > 300 and np.all(s >= rest)
        model = m54.core_reading(e, e["drive"], s.copy())
        assert _rms(rec.y - model) < 1.5 * rec.noise_std
        # held still first: the drive within 4 % of its reach over the first 20 % of the record, the strip within 20
        # sigma of the same strip from the rest state there; then the signals' cold strokes switch the classes the
        # bake left high spin, once, and the strip (its LVDT zeroed at the start) sits shorter for the rest of the
        # record: by over 30 sigma over the record's second half (measured at least 157 ... 214)
        x = e["x"]
        first = np.argmax(np.abs(x) > 0.041)
        assert x[0] == 0.0 and first > 0.2 * len(x) and _full_both_ways(e)
        core = _core_cached(INIT, seed)
        assert np.abs(model[:first] - core[:first]).max() < 20 * rec.noise_std
        gap = np.min(core[len(x) // 2:] - model[len(x) // 2:]) / rec.noise_std
        MEASURED[("initial", "gap", seed)] = (gap, gap)
        assert gap > 30
        # far from the same strip from the rest state: over 7 sigma RMS beyond a gain and an offset and at most
        # (measured 84.9 ... 101.1 RMS, 112 ... 126 at most)
        _big(rec, model, core, "initial_state")


# ---- two effects: a quarter bridge warming up, under a chimney sweep's rods ----

def test_quarter_bridge_warm_up_under_chimney_sweep():
    for seed in (0, 1, 2):
        rec = _rec(PAIR, seed)
        e = rec.extra
        t = rec.t
        assert 0.22 <= e["q"] <= 0.28 and 18 <= e["D_um"] <= 24 and 0.3 <= e["a"] <= 0.5
        assert 3 <= e["tau1"] <= 6 and 60 <= e["tau2"] <= 100
        h = _core_cached(PAIR, seed)
        np.testing.assert_array_equal(h, e["h"])
        x_r = e["x_r"]
        assert np.abs(h).max() / x_r == pytest.approx(e["q"], rel=1e-14)
        # the warming: two first-order lags from 0 toward a and 1 - a of delta_inf, by solve_ivp (rtol 1e-10: 1e-9 of
        # delta_inf)
        d_inf = e["D_um"] / x_r
        sol = solve_ivp(lambda tt, z: [(e["a"] - z[0]) / e["tau1"], (1 - e["a"] - z[1]) / e["tau2"]], (0, t[-1]),
                        [0.0, 0.0], rtol=1e-10, atol=1e-13, t_eval=t[::50])
        np.testing.assert_allclose(e["delta"][::50], d_inf * sol.y.sum(axis=0), rtol=0, atol=1e-9 * d_inf)
        # the bridge from its resistances: the gauge R_0 (1 + r) against R_0 in one arm, two R_0 in the other, V / V_s
        # = R_g / (R_g + R_0) - 1/2, read as 4 (V / V_s) x_r (1e-9 um)
        R0 = 350.0
        Rg = R0 * (1 + h / x_r + e["delta"])
        y = m54.bridge_reading(h / x_r + e["delta"], x_r)
        np.testing.assert_allclose(y, 4 * (Rg / (Rg + R0) - 0.5) * x_r, rtol=0, atol=1e-9)
        assert _rms(rec.y - y) < 1.5 * rec.noise_std
        x = e["x"]
        assert x[0] == 0.0 and x[-1] == 0.0 and _full_both_ways(e)
        # each alone beyond a gain and an offset on the core, and each beyond those on the record without it: over 7
        # sigma RMS and at most (measured the drift alone 10.8 ... 11.8 RMS, 34.3 ... 40.9 at most; the asymmetry alone
        # 9.2 ... 10.9, 23.2 ... 28.7; the drift beyond the asymmetry 10.4 ... 11.3, 34.1 ... 40.5; the asymmetry beyond
        # the drift 8.7 ... 10.2, 20.5 ... 28.0)
        asym_only = m54.bridge_reading(h / x_r, x_r)
        drift_only = h + x_r * e["delta"]
        _big(rec, drift_only, h, "drift alone")
        _big(rec, asym_only, h, "asymmetry alone")
        _big(rec, y, asym_only, "drift beyond asymmetry")
        _big(rec, y, drift_only, "asymmetry beyond drift")


# ---- out of vocabulary: a magnetic scale's wrap, under a bell-ringer's rope ----

def test_scale_wrap_under_bell_ringer():
    for seed in (0, 1, 2):
        rec = _rec(OOV, seed)
        e = rec.extra
        h = _core_cached(OOV, seed)
        np.testing.assert_array_equal(h, e["h"])
        # the interpolator from its sine and cosine: the phase atan2(sin, cos) of 2 pi (x + P - x_w) / P taken into [0,
        # 2 pi), scaled to P, less the rest's (1e-9 um)
        ph = np.arctan2(np.sin(2 * np.pi * (h + 400 - e["x_w"]) / 400), np.cos(2 * np.pi * (h + 400 - e["x_w"]) / 400))
        y = np.mod(ph, 2 * np.pi) * 400 / (2 * np.pi) - (400 - e["x_w"])
        assert np.all(np.abs(h - e["x_w"]) > 1e-6)
        np.testing.assert_allclose(m54.scale_reading(h, e["x_w"]), y, rtol=0, atol=1e-9)
        assert _rms(rec.y - y) < 1.5 * rec.noise_std
        # the wrap: the strip passes x_w, there the reading jumps back by the period, and the stroke is less than a
        # period (one wrap)
        assert h.max() > e["x_w"] and np.ptp(h) < 400
        x = e["x"]
        assert x[0] == 0.0 and _full_both_ways(e)
        # no monotone map of the core the recorded drive makes comes near the reading: over 30 sigma away (measured
        # 56 ... 72)
        hc = m54.core_reading(e, rec.v)
        o = np.argsort(hc)
        ys = rec.y[o]
        miss = min(np.abs(ys - isotonic_regression(ys, increasing=inc).x).max() for inc in (True, False))
        MEASURED[("oov", "monotone", seed)] = (miss / rec.noise_std,) * 2
        assert miss > 30 * rec.noise_std


def test_zz_print_measured():
    """Prints the figures measured above (run with -s); asserts nothing beyond them."""
    for k in sorted(MEASURED, key=str):
        print(k, "%.4g %.4g" % MEASURED[k])

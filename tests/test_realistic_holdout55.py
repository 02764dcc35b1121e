"""HOLDOUT55 (tests/realistic/cases_holdout55.py, laws in mechanisms55.py, signals in signals55.py): well formed,
measured once in round 57 (58bc36b, 16 of 30 runs right) and part of ALL since, and every mechanism follows its law.
Nothing here runs the diagnosis.

Tolerances: a record that is its stated law plus the sensor noise leaves a residual RMS within 1.5 sigma of the law (the
noise alone gives 1.0; the laws are evaluated on the clean drive). A law checked against an independent solution (every
crystallite's state by the last threshold the field crossed, from the running extremes looking back; the crystallites'
thresholds from the stated laws and a Kronecker sequence written out here; the rest state by an explicit decaying
cycling of the field; the reading from Stoney's law written out; the Debye modes, the oil's lag, the holder's lag and
the alpha_c relaxation by solve_ivp; the thermostat's switching times by brentq; the membrane's and the stops' balances
by brentq; the link's packets written out; the log creep kernel's means by quad and its hereditary sum summed directly;
finer grids) agrees to the stated tolerance, set from the solvers' own tolerances or the scheme's order (each stated
beside it), far below sigma (2e-3 of the span, some 6 nm).

Effects are asked to move the output by at least 7 sigma beyond what a gain and an offset on the core absorb, both at
its largest and as an RMS over the whole record (the core: the same film, rate independent, its field the drive's,
without the effect; the creep against the film without its slow polarisation; the rate dependence against the beam in
air; the drift against the film in a still room; the asymmetry against the free tip; the saturation against the tip
without stops; the delay against the drive at once; the initial state against the same film from the rest state; the
pair's rate dependence against the film without its alpha_c relaxation and its creep against a rigid clamp); the
measured values for seeds 0 ... 2 are stated beside each (RMS; largest), in sigma: creep 11.2 ... 14.7 (59 ... 67), rate
10.6 ... 21.9 (46 ... 85), drift 19.5 ... 24.6 (39 ... 44), asymmetry 18.5 ... 22.1 (39 ... 41), saturation 19.9 ...
21.5 (41 ... 51), delay 30.3 ... 40.9 (120 ... 154), initial state 19.7 ... 21.2 (33 ... 35), the pair's alpha_c
relaxation alone 9.8 ... 10.2 (42 ... 50) and its clamp's creep alone 8.2 ... 10.0 (18 ... 26) (and within the record:
the relaxation beyond a gain and an offset on the creeping reading without it 9.8 ... 10.2 (42 ... 50), the creep beyond
those on the relaxing reading without it 8.3 ... 10.1 (18 ... 26)); the out-of-vocabulary butterfly is 260 ... 288 sigma
from any monotone map of the core the recorded drive makes. The pair's creep (8.2, seed 2) is the smallest margin in the
set.

The pair, {creep, rate_dependence}: the clamp's bond creeping logarithmically under the bending moment (a hereditary
integral of the bend; the single creep case's is the film's own slow polarisation, a box of Debye modes added to P
before its square) and the film's alpha_c relaxation (a standard linear solid: the film stiffer on quick moves, a lead;
the single rate case's is the beam overdamped in oil, a lag).

The clean core's closeness to a Prandtl-Ishlinskii model, a PI model of 12 plays of the drive (set_checks.pi_fit_rms)
fitted by NNLS: it leaves 1.77 ... 1.99 sigma RMS on the clean record (seeds 0 ... 2; its largest residual 7.6 ... 8.3
sigma), where the core is far from a straight line (72 ... 78 sigma at most, stated below). What a PI model misses: the
crystallites' relays are not a uniform density of centres times a density of widths (their centres, the internal fields,
are normal), and the strain is the polarisation's square.
"""

import math
from functools import lru_cache

import numpy as np
import pytest
from scipy.integrate import quad, solve_ivp
from scipy.optimize import brentq, isotonic_regression
from scipy.special import ndtri

import realistic
from realistic import HOLDOUT55
from realistic import cases_holdout55 as c55
from realistic import mechanisms55 as m55
from realistic import signals55 as s55
from test_realistic_generator import _assert_joined_ten, _linear_misfit, _rms
from realistic.set_checks import assert_knots_evaluator as _knots_evaluator, assert_minimum_jerk as _minimum_jerk
from realistic.set_checks import assert_relay_core as _relay_core, holds as _holds, pi_fit_rms as _pi_fit_rms
from test_realistic_holdout50 import _big, _full_both_ways, _lopsided

pytestmark = pytest.mark.slow

P = "holdout55_"
EFFECTS = {"creep", "rate_dependence", "drift", "asymmetry", "saturation", "initial_state", "delay"}
CLEAN = "clean_pvdf_trfe_unimorph_fly_cast_1381hz"
CREEP = "creep_maxwell_wagner_polarisation_barista_tamp_227hz"
RATE = "rate_silicone_oil_drag_conductor_baton_1597hz"
DRIFT = "drift_room_thermostat_bimorph_bell_ringer_211hz"
ASYM = "asymmetry_micropump_membrane_rowing_stroke_863hz"
SAT = "saturation_silicone_end_stops_wiper_1019hz"
DELAY = "delay_wireless_link_latency_bellows_557hz"
INIT = "initial_state_factory_poling_archer_677hz"
PAIR = "pair_creep_rate_clamp_log_creep_alpha_c_kayak_409hz"
OOV = "oov_thin_film_butterfly_violin_bow_1213hz"
UNIPOLAR = {CREEP, DRIFT, DELAY}
MONITORED = {CLEAN: 2e-4, RATE: 3e-4, SAT: 2.5e-4, DELAY: 3e-4}
ORDER = ("clean_", "creep_", "rate_", "drift_", "asymmetry_", "saturation_", "delay_", "initial_state_", "pair_",
         "oov_")


@lru_cache(maxsize=None)
def _rec(name, seed):
    return HOLDOUT55[P + name](seed)


@lru_cache(maxsize=None)
def _core_cached(name, seed):
    """The core's reading for a record's clean drive, from the rest state (cached: several checks use it)."""
    e = _rec(name, seed).extra
    return m55.core_reading(e, e["drive"])


def _lag_ivp(t, x, tau, y0):
    """tau y' + y = x(t), x linear between the times t, by solve_ivp (Radau, rtol 1e-10, atol 1e-12 of x's scale),
    step limited to a sample (the input's kinks): y at the times t."""
    sc = max(float(np.abs(x).max()), 1e-30)
    sol = solve_ivp(lambda s, z: [(np.interp(s, t, x) - z[0]) / tau], (t[0], t[-1]), [y0], method="Radau",
                    rtol=1e-10, atol=1e-12 * sc, max_step=t[1] - t[0], t_eval=t)
    return sol.y[0]


# ---- the set ----

def test_holdout55_is_well_formed_and_joined():
    H = HOLDOUT55
    assert c55.HOLDOUT55 is H and realistic.HOLDOUT55 is H and "HOLDOUT55" in realistic.__all__
    _assert_joined_ten(H, P, EFFECTS, ORDER, _rec, MONITORED, UNIPOLAR, PAIR, {"creep", "rate_dependence"}, ASYM)


def test_reach_and_programmes():
    # the minimum-jerk reach (set_tools.minimum_jerk) against quad of its speed, and its speed (set_checks)
    _minimum_jerk(s55.reach, s55.reach_speed)
    # the knots' evaluator against a direct search of its knots (1e-12)
    _knots_evaluator(s55.reach, s55.knots_at)
    rng = np.random.default_rng(7)
    # the conductor never still; the archer's stance within 0.04 for its first 14 s; the unipolar programmes within
    # 0 ... 1 and reaching 1
    kx = [k[1] for k in s55.conductor(rng, 8)[0]]
    assert all(a != b for a, b in zip(kx, kx[1:]))
    kn, _ = s55.archer(rng, 2, 14.0)
    assert max(abs(x) for t, x in kn if t <= 14.0) <= 0.04 and max(x for t, x in kn) == 1.0
    for gen in (s55.barista_tamp, s55.bell_ringer, s55.bellows):
        xs = [x for t, x in gen(rng, 2)[0]]
        assert min(xs) >= 0.0 and max(xs) == 1.0


# ---- the core: a P(VDF-TrFE) unimorph's crystallites ----

def _crystallites_written_out(e):
    """The crystallites' (alpha, beta, w) from the stated laws: the Kronecker sequence k (1/g, 1/g^2) + shift mod 1, g
    the real root of x^3 = x + 1 (found here by brentq); the first 4000 soft (E_c log-normal about E50 with log spread
    0.35, E_b normal Ebm +- sb, each of share fs / 4000), the next 500 hard (105 MV/m, 0.12; 12 +- 6 MV/m; (1 - fs) /
    500); alpha = E_c - E_b, beta = -E_c - E_b."""
    g = brentq(lambda x: x ** 3 - x - 1, 1.0, 2.0, xtol=1e-15)
    shift = np.random.default_rng(e["rseed"]).uniform(size=2)
    k = np.arange(1, 4501)[:, None]
    u = np.modf(shift[None, :] + k * np.array([1 / g, 1 / g ** 2])[None, :])[0]
    u = np.clip(u, 1e-12, 1 - 1e-12)
    soft = np.arange(4500) < 4000
    ec = np.where(soft, e["E50"] * np.exp(0.35 * ndtri(u[:, 0])), 105.0 * np.exp(0.12 * ndtri(u[:, 0])))
    eb = np.where(soft, e["Ebm"] + e["sb"] * ndtri(u[:, 1]), 12.0 + 6.0 * ndtri(u[:, 1]))
    w = np.where(soft, e["fs"] / 4000, (1 - e["fs"]) / 500)
    return ec - eb, -ec - eb, w


def _states_by_history(E, i, a, b, s0):
    """Every crystallite's state at the field E[i] from the relay's definition: the last of its thresholds the field
    crossed up to then (up where it last rose above alpha, down where it last fell below beta), else its first state
    s0. (The last crossing of a threshold is found from the running extremes looking back from i.)"""
    back = E[:i + 1][::-1]
    rmax, rmin = np.maximum.accumulate(back), np.minimum.accumulate(back)
    m_up = np.searchsorted(rmax, a, side="right")
    m_dn = np.searchsorted(-rmin, -b, side="right")
    return np.where(m_up < m_dn, 1.0, np.where(m_dn < m_up, -1.0, s0))


def _reading_written_out(E, m):
    """Stoney's tip, 1e9 x 3 Y_f' t_f L^2 / (Y_s' t_s^2) x Q (P^2 - P(0)^2), P = 0.075 m + 8.8541878128e-12 x 11 x 1e6
    E, with Y_f' = 5 GPa, Y_s' = 180 GPa, t_f = 2 um, L = 2 mm, t_s = 10 um, Q = 0.45 (nm)."""
    Pol = 0.075 * m + 8.8541878128e-12 * 11 * 1e6 * E
    k = 1e9 * 3 * 5e9 * 2e-6 * 4e-6 / (180e9 * 1e-10)
    return k * 0.45 * (Pol ** 2 - Pol[0] ** 2)


def test_core_crystallites_states_and_reading_against_their_definitions():
    for seed in (0, 1, 2):
        rec = _rec(CLEAN, seed)
        e = rec.extra
        a, b, w = m55.crystallites(e)
        a_w, b_w, w_w = _crystallites_written_out(e)
        # (1e-7 MV/m: the sequence's rounding, some 1e-12 in a quantile at k = 4500, through the normal quantile's slope
        # in the tails)
        np.testing.assert_allclose(a, a_w, rtol=0, atol=1e-7)
        np.testing.assert_allclose(b, b_w, rtol=0, atol=1e-7)
        np.testing.assert_allclose(w, w_w, rtol=1e-14, atol=0)
        assert np.all(a > b) and w.sum() == pytest.approx(1.0, abs=1e-12)
        v = e["drive"]
        E = m55.field(e, v)
        np.testing.assert_allclose(E, v / 2.0, rtol=0, atol=1e-12)
        # the rest state at 0: up where beta < -23.5, else down where alpha > 23.5, else up where the middle is below 0
        s0 = np.where(b < -23.5, 1.0, np.where(a > 23.5, -1.0, np.where(a + b < 0, 1.0, -1.0)))
        np.testing.assert_array_equal(m55.rest_state(e, E[0]), s0)
        mm = m55.switched_share(e, E)
        # the mean state at 40 samples (the first, and spread over the record) against every crystallite's state from
        # its history (1e-12: both sum the same shares)
        picks = np.r_[0, np.linspace(1, len(E) - 1, 39).astype(int)]
        states = np.array([_states_by_history(E, i, a, b, s0) for i in picks])
        np.testing.assert_allclose(mm[picks], states @ w, rtol=0, atol=1e-12)
        # the crystallites switch over the record: over a third of the soft ones in another state at some pick than at
        # the start, none of the hard ones
        changed = np.any(states != s0, axis=0)
        assert np.mean(changed[:4000]) > 1 / 3 and not np.any(changed[4000:])
        y = m55.core_reading(e, v)
        np.testing.assert_allclose(y, _reading_written_out(E, mm), rtol=0, atol=1e-9)
        assert _rms(rec.y - y) < 1.5 * rec.noise_std
        # the polarisation stays positive by far (over 0.05 C/m^2): the strain's square is monotone on the record
        assert m55.polarisation(E, mm).min() > 0.05
        x = e["x"]
        assert x[0] == 0.0 and x[-1] == 0.0 and _full_both_ways(e)
        assert len(_holds(v, int(1.0 / rec.t[1]))) >= 2


def test_rest_state_is_the_limit_of_a_decaying_cycling():
    # from the poling (every crystallite up), a cycling of the field about 0 decaying from the amplifier's swing
    # (23.5 MV/m) by 0.2 % a half cycle (its turning points: the core is rate independent), then the field brought to
    # the drive's 0 V (0 on a bipolar rig, -23.5 MV/m on a unipolar one), leaves the rest state's crystallites, but for
    # those whose loop's middle lies within the last steps of 0 (measured: none of 4500), and the reading within 0.5
    # sigma of the rest state's (measured 0)
    for name in (CLEAN, CREEP):
        e = dict(_rec(name, 0).extra)
        E0 = float(m55.field(e, 0.0))
        assert E0 == (0.0 if name == CLEAN else -23.5)
        s = np.ones(m55.N_SOFT + m55.N_HARD)
        amp = 23.5 * 0.998 ** np.arange(9000)
        m55.switched_share(e, np.r_[amp * (-1.0) ** np.arange(9000), 0.0, E0], s)
        assert np.sum(s != m55.rest_state(e, E0)) <= 3
        y_cycled = m55.core_reading(e, e["drive"], s)
        assert np.abs(y_cycled - _core_cached(name, 0)).max() < 0.5 * _rec(name, 0).noise_std
        # on the unipolar rig every soft crystallite is down at the drive's 0 V but for those with beta below it (the
        # conditioning could not switch them), every hard one up
        rest = m55.rest_state(e, E0)
        a, b, _ = m55.crystallites(e)
        assert np.all(rest[4000:] == 1.0) or name == CLEAN
        if name == CREEP:
            np.testing.assert_array_equal(rest, np.where(b < -23.5, 1.0, -1.0))


def test_core_return_point_memory_rate_independence_and_pi_closeness():
    e = dict(_rec(CLEAN, 0).extra)
    # return-point memory (1e-12 nm), a loop (at 0 V the minor loop's rising branch over 7 sigma, 40 nm, below its
    # falling one: measured 322 nm) and rate independence
    _relay_core(lambda vv: m55.core_reading(e, vv), e["drive"], 40.0)
    lin = []
    for seed in (0, 1, 2):
        rec = _rec(CLEAN, seed)
        # a PI model of 12 plays fitted by NNLS leaves 1.0 ... 2.5 sigma RMS (measured 1.77 ... 1.99) and at most 12
        # sigma (measured 7.6 ... 8.3), where the core is far from a straight line (over 60 sigma: measured 72 ... 78)
        r, mx = _pi_fit_rms(rec.y, rec.v)
        assert 1.0 * rec.noise_std < r < 2.5 * rec.noise_std and mx < 12 * rec.noise_std
        lin.append(_linear_misfit(_core_cached(CLEAN, seed), rec.v) / rec.noise_std)
        assert lin[-1] > 60


# ---- creep: the film's slow Maxwell-Wagner polarisation, under a barista's tamper ----

def test_maxwell_wagner_creep_under_barista_tamp():
    for seed in (0, 1, 2):
        rec = _rec(CREEP, seed)
        e = rec.extra
        t, dt = rec.t, rec.t[1]
        assert 6.0 <= e["dchi"] <= 9.0
        v = e["drive"]
        E = m55.field(e, v)
        np.testing.assert_allclose(E, (v - 47.0) / 2.0, rtol=0, atol=1e-12)
        P_mw = m55.mw_polarisation(E, dt, e["dchi"])
        np.testing.assert_array_equal(P_mw, e["P_mw"])
        if seed == 0:
            # the 8 Debye modes (times log-spaced 0.3 ... 40 s) against solve_ivp of the whole system on the first 30 s
            # (Radau, rtol 1e-10, its error growing over the 6800 steps; 1e-7 of the slow polarisation's largest, some
            # 1e-10 C/m^2, 4e-5 nm: far below the 2e-5 C/m^2 a sigma is)
            n = int(30.0 / dt)
            taus = np.geomspace(0.3, 40.0, 8)
            x = 8.8541878128e-12 * e["dchi"] * 1e6 * E[:n] / 8
            sol = solve_ivp(lambda s, z: (np.interp(s, t[:n], x) - z) / taus, (0.0, t[n - 1]), np.full(8, x[0]),
                            method="Radau", rtol=1e-10, atol=1e-16, max_step=dt, t_eval=t[:n])
            np.testing.assert_allclose(P_mw[:n], sol.y.sum(axis=0), rtol=0, atol=1e-7 * np.abs(P_mw).max())
        y = m55.reading(m55.polarisation(E, e["m"], P_mw))
        assert _rms(rec.y - y) < 1.5 * rec.noise_std
        # on the held tamp the film creeps on (the reading rises over 5 sigma after the drive stops at its top)
        runs = [(a_, b_) for a_, b_ in _holds(v, int(3.0 / dt)) if v[a_] > 0.6 * v.max()]
        assert runs and max(y[b_ - 1] - y[a_] for a_, b_ in runs) > 5 * rec.noise_std
        p = e["p"]
        assert p[0] == 0.0 and p[-1] == 0.0 and max(k_[1] for k_ in e["knots"]) == 1.0 and p.max() > 0.999
        # the slow polarisation moves the reading beyond a gain and an offset on the film without it: over 7 sigma RMS
        # and at most (measured 11.2 ... 14.7 RMS, 59 ... 67 at most)
        _big(rec, y, _core_cached(CREEP, seed))


# ---- rate dependence: the beam in silicone oil, under a conductor's baton ----

def test_oil_drag_under_conductor():
    for seed in (0, 1, 2):
        rec = _rec(RATE, seed)
        e = rec.extra
        t, dt = rec.t, rec.t[1]
        assert 0.02 <= e["tau"] <= 0.032
        h = _core_cached(RATE, seed)
        np.testing.assert_array_equal(h, e["h"])
        y = m55.lag(h, dt, e["tau"], 0.0)
        if seed == 0:
            # the exact step against solve_ivp over the first 1.5 s (Radau, rtol 1e-10, its order lost at the input's
            # kinks every sample: 1e-3 nm, against a sigma of 6 nm; measured 4e-4)
            n = int(1.5 / dt)
            np.testing.assert_allclose(y[:n], _lag_ivp(t[:n], h[:n], e["tau"], 0.0), rtol=0, atol=1e-3)
        assert _rms(rec.y - y) < 1.5 * rec.noise_std
        assert all(a != b for a, b in zip([k[1] for k in e["knots"]], [k[1] for k in e["knots"]][1:]))
        x = e["x"]
        assert x[0] == 0.0 and _full_both_ways(e)
        # the oil moves the reading beyond a gain and an offset on the beam in air: over 7 sigma RMS and at most
        # (measured 10.6 ... 21.9 RMS, 46 ... 85 at most)
        _big(rec, y, h)


# ---- drift: the room's thermostat, under a bell ringer's rope ----

def test_thermostat_drift_under_bell_ringer():
    for seed in (0, 1, 2):
        rec = _rec(DRIFT, seed)
        e = rec.extra
        t, dt = rec.t, rec.t[1]
        times, temps, ons = e["times"], e["temps"], e["ons"]
        T_on, T_off, tau_r = e["T_on"], e["T_off"], e["tau_r"]
        lo, hi = 21.0 - e["db"] / 2, 21.0 + e["db"] / 2
        # every switching where the air's exponential leg reaches the dead band's edge, found again by brentq from the
        # previous knot (1e-9 s); the heating off at the top, on at the bottom
        for k in range(len(times) - 1):
            target = T_on if ons[k] else T_off
            edge = hi if ons[k] else lo
            ref = brentq(lambda s_: target + (temps[k] - target) * math.exp(-(s_ - times[k]) / tau_r) - edge,
                         times[k] + 1e-12, times[k] + 10 * tau_r, xtol=1e-12)
            assert times[k + 1] == pytest.approx(ref, abs=1e-9) and temps[k + 1] == edge
            assert ons[k + 1] != ons[k]
        # over the record the heating switches at least once; the holder swings 0.2 ... 1 K
        assert np.sum((times > 0) & (times < t[-1])) >= 1 and 0.2 < np.ptp(e["Th"]) < 1.0
        if seed == 0:
            # the holder against solve_ivp of tau_h T' = T_air - T over the record, the air from its closed form, from
            # the holder's first value (rtol 1e-10: 1e-5 K, 0.01 nm; the fine grid's air linear between its points,
            # h^2 / 8 of its curvature, under 1e-9 K)
            Th = e["Th"]
            sol = solve_ivp(lambda s_, z: [(float(m55.air_at(s_, times, temps, ons, T_on, T_off, tau_r)) - z[0])
                                           / e["tau_h"]], (0.0, t[-1]), [Th[0]], method="Radau", rtol=1e-10,
                            atol=1e-12, max_step=1.0, dense_output=True)
            np.testing.assert_allclose(Th, sol.sol(t)[0], rtol=0, atol=1e-5)
        h = _core_cached(DRIFT, seed)
        np.testing.assert_array_equal(h, e["h"])
        y = h + m55.STONEY_NM * 127.4e-6 * (e["Th"] - e["Th"][0])
        np.testing.assert_allclose(y, m55.reading(m55.polarisation(m55.field(e, e["drive"]),
                                                                   m55.switched_share(e, m55.field(e, e["drive"]))),
                                                  (130e-6 - 2.6e-6) * (e["Th"] - e["Th"][0])), rtol=0, atol=1e-9)
        assert _rms(rec.y - y) < 1.5 * rec.noise_std
        drift = y - h
        assert np.max(drift - np.minimum.accumulate(drift)) > 5 * rec.noise_std
        assert np.max(np.maximum.accumulate(drift) - drift) > 5 * rec.noise_std
        p = e["p"]
        assert p[0] == 0.0 and p[-1] == 0.0 and max(k_[1] for k_ in e["knots"]) == 1.0 and p.max() > 0.999
        assert len(_holds(rec.v, int(10.0 / dt))) >= 2
        # the thermostat moves the reading beyond a gain and an offset on the film in a still room: over 7 sigma RMS
        # and at most (measured 19.5 ... 24.6 RMS, 39 ... 44 at most)
        _big(rec, y, h)


# ---- asymmetry: the tip on a micropump's membrane, under a rower's stroke ----

def test_membrane_contact_under_rowing():
    for seed in (0, 1, 2):
        rec = _rec(ASYM, seed)
        e = rec.extra
        assert 0.5 <= e["r1"] <= 0.8 and 0.3 <= e["r3"] <= 0.5
        ws = _core_cached(ASYM, seed)
        np.testing.assert_array_equal(ws, e["ws"])
        assert e["k3"] == pytest.approx(e["r3"] / ws.max() ** 2, rel=1e-14)
        y = m55.membrane_contact(ws, e["r1"], e["k3"])
        # the tip's balance ws - w = r1 w + k3 w^3 against brentq (xtol 1e-12) at 300 samples (1e-9 nm)
        for i in np.linspace(0, len(ws) - 1, 300).astype(int):
            if ws[i] <= 0.0:
                ref = ws[i]
            else:
                ref = brentq(lambda w_: w_ + e["r1"] * w_ + e["k3"] * w_ ** 3 - ws[i], 0.0, ws[i], xtol=1e-12)
            assert y[i] == pytest.approx(ref, abs=1e-9)
        assert _rms(rec.y - y) < 1.5 * rec.noise_std
        # the tip rises less than it sinks: its excursions from rest differ to the two sides by over 20 % of the
        # larger, the free tip's by under 20 % (measured 0.39 ... 0.44, the free tip's 0.04 ... 0.05)
        assert _lopsided(y) > 0.2 + _lopsided(ws)
        x = e["x"]
        assert x[0] == 0.0 and x[-1] == 0.0 and _full_both_ways(e)
        # the membrane moves the reading beyond a gain and an offset on the free tip: over 7 sigma RMS and at most
        # (measured 18.5 ... 22.1 RMS, 39 ... 41 at most)
        _big(rec, y, ws)


# ---- saturation: silicone end stops, under a windscreen wiper ----

def test_end_stops_under_wiper():
    for seed in (0, 1, 2):
        rec = _rec(SAT, seed)
        e = rec.extra
        ws = _core_cached(SAT, seed)
        np.testing.assert_array_equal(ws, e["ws"])
        assert 0.55 <= e["f_up"] <= 0.7 and 0.55 <= e["f_dn"] <= 0.7 and 0.3 <= e["kh"] <= 0.5
        g_up, g_dn, kh = e["g_up"], e["g_dn"], e["kh"]
        y = m55.two_stops(ws, g_up, g_dn, kh)
        # the Hertz balance d + kh d^(3/2) = |ws| - g past a stop against brentq (xtol 1e-12) at 300 samples (1e-9 nm)
        for i in np.linspace(0, len(ws) - 1, 300).astype(int):
            if ws[i] > g_up:
                ref = g_up + brentq(lambda d: d + kh * d ** 1.5 - (ws[i] - g_up), 0.0, ws[i] - g_up, xtol=1e-12)
            elif ws[i] < -g_dn:
                ref = -g_dn - brentq(lambda d: d + kh * d ** 1.5 - (-ws[i] - g_dn), 0.0, -ws[i] - g_dn, xtol=1e-12)
            else:
                ref = ws[i]
            assert y[i] == pytest.approx(ref, abs=1e-9)
        assert _rms(rec.y - y) < 1.5 * rec.noise_std
        # the stops reached both ways over 2 % of the record each
        assert np.mean(ws > g_up) > 0.02 and np.mean(ws < -g_dn) > 0.02
        x = e["x"]
        assert x[0] == 0.0 and x[-1] == 0.0 and _full_both_ways(e)
        # the stops move the reading beyond a gain and an offset on the tip without stops: over 7 sigma RMS and at
        # most (measured 19.9 ... 21.5 RMS, 41 ... 51 at most)
        _big(rec, y, ws)


# ---- delay: a wireless link's latency, under a blacksmith's bellows ----

def test_wireless_link_under_bellows():
    for seed in (0, 1, 2):
        rec = _rec(DELAY, seed)
        e = rec.extra
        t = rec.t
        D, ph = e["D"], e["phase"]
        assert 0.06 <= D <= 0.09 and 0.0 <= ph <= 7.5e-3
        kn, top, p = e["knots"], e["top"], e["p"]
        # the packets written out at every 53rd sample: the two packets about t - D (their times ph + k 7.5 ms), the
        # command there from the programme itself, interpolated (1e-9 V), 0 before the first packet is played
        for i in range(0, len(t), 53):
            s_ = t[i] - D
            if s_ < ph:
                ref = 0.0
            else:
                k = int(math.floor((s_ - ph) / 7.5e-3))
                ta, tb = ph + k * 7.5e-3, ph + (k + 1) * 7.5e-3
                va, vb = (top * float(s55.knots_at(np.array([tt]), kn)[0]) / p.max() for tt in (ta, tb))
                ref = va + (vb - va) * (s_ - ta) / 7.5e-3
            assert e["v_node"][i] == pytest.approx(ref, abs=1e-9)
        y = m55.core_reading(e, e["v_node"])
        assert _rms(rec.y - y) < 1.5 * rec.noise_std
        assert p[0] == 0.0 and p[-1] == 0.0 and max(k_[1] for k_ in kn) == 1.0
        # a delay above all: beyond the core under the drive read D late the packets' hold leaves under 2 sigma RMS
        # (measured 0.02)
        late = np.interp(t - D, t, e["drive"], left=0.0)
        assert _rms(m55.core_reading(e, late) - y) < 2 * rec.noise_std
        # the link moves the reading beyond a gain and an offset on the drive at once: over 7 sigma RMS and at most
        # (measured 30.3 ... 40.9 RMS, 120 ... 154 at most)
        _big(rec, y, _core_cached(DELAY, seed))


# ---- initial state: the factory's poling, under an archer's draw ----

def test_factory_poling_under_archer():
    for seed in (0, 1, 2):
        rec = _rec(INIT, seed)
        e = rec.extra
        s = e["s0"]
        # every crystallite up; the rest state differs in the ones the conditioning left down (over 1500 of the 4000
        # soft classes, measured 1946 ... 1967, and the few hard ones whose internal field points the other way: their
        # down threshold beyond the drive, they stay up for good, a constant)
        assert np.all(s == 1.0)
        rest = m55.rest_state(e, 0.0)
        assert e["n_off"] == np.sum(s != rest) and np.sum(s[:4000] != rest[:4000]) > 1500
        model = m55.core_reading(e, e["drive"], s.copy())
        assert _rms(rec.y - model) < 1.5 * rec.noise_std
        # the stance first: the drive within 4 % of its reach over the first 20 % of the record; the reading there
        # stays within 20 sigma of the rested film's (measured 4.8 ... 5.8) and afterwards the two differ
        x = e["x"]
        first = np.argmax(np.abs(x) > 0.041)
        assert x[0] == 0.0 and first > 0.2 * len(x) and _full_both_ways(e)
        core = _core_cached(INIT, seed)
        assert np.abs(model[:first] - core[:first]).max() < 20 * rec.noise_std
        # far from the same film from the rest state: over 7 sigma RMS beyond a gain and an offset and at most
        # (measured 19.7 ... 21.2 RMS, 33 ... 35 at most)
        _big(rec, model, core)


# ---- two effects: the clamp's log creep and the film's alpha_c relaxation, under a kayaker's paddle ----

def test_clamp_creep_and_alpha_c_under_kayak():
    # the kernel: c_1 ln(1 + t / tau_0)'s mean over each sample interval, against quad (1e-12)
    dt, c1, tau0 = 1 / 409, 0.06, 0.7
    k = m55.log_creep_kernel(3000, dt, c1, tau0)
    for mm in (0, 1, 7, 100, 2999):
        ref = quad(lambda u: c1 * math.log1p(u / tau0), mm * dt, (mm + 1) * dt, epsabs=1e-15)[0] / dt
        assert k[mm] == pytest.approx(ref, abs=1e-12)
    for seed in (0, 1, 2):
        rec = _rec(PAIR, seed)
        e = rec.extra
        t, dt = rec.t, rec.t[1]
        assert 0.6 <= e["ra"] <= 0.8 and 0.03 <= e["tau_a"] <= 0.045
        assert 0.055 <= e["c1"] <= 0.07 and 0.5 <= e["tau0"] <= 1.0
        ws = _core_cached(PAIR, seed)
        np.testing.assert_array_equal(ws, e["ws"])
        mb = m55.alpha_c_bend(ws, dt, e["ra"], e["tau_a"])
        np.testing.assert_array_equal(mb, e["mb"])
        if seed == 0:
            # the relaxation's lag against solve_ivp over the first 4 s (as the oil's: 1e-3 nm)
            n = int(4.0 / dt)
            ref = ws[:n] + e["ra"] * (ws[:n] - _lag_ivp(t[:n], ws[:n], e["tau_a"], ws[0]))
            np.testing.assert_allclose(mb[:n], ref, rtol=0, atol=1e-3)
        kern = m55.log_creep_kernel(len(t), dt, e["c1"], e["tau0"])
        y = mb + m55.hereditary(mb, kern)
        # the hereditary sum directly at 12 samples (1e-7 nm: the FFT's rounding over 30,000 terms)
        dm = np.diff(mb, prepend=mb[0])
        for i in np.linspace(0, len(t) - 1, 12).astype(int):
            assert y[i] == pytest.approx(mb[i] + float(dm[:i + 1] @ kern[i::-1]), abs=1e-7)
        assert _rms(rec.y - y) < 1.5 * rec.noise_std
        x = e["x"]
        assert x[0] == 0.0 and x[-1] == 0.0 and _full_both_ways(e)
        # each alone beyond a gain and an offset on the core, and each beyond those on the record without it: over 7
        # sigma RMS and at most (measured: the relaxation alone 9.8 ... 10.2 RMS, 42 ... 50 at most; the creep alone
        # 8.2 ... 10.0 RMS, 18 ... 26 at most; the relaxation beyond the creep 9.8 ... 10.2 RMS, 42 ... 50 at most; the
        # creep beyond the relaxation 8.3 ... 10.1 RMS, 18 ... 26 at most)
        creep_only = ws + m55.hereditary(ws, kern)
        for a_, b_ in ((mb, ws), (creep_only, ws), (y, creep_only), (y, mb)):
            _big(rec, a_, b_)


# ---- out of vocabulary: a film spun too thin, the butterfly, under a violinist's bow ----

def test_thin_film_butterfly_under_violin_bow():
    for seed in (0, 1, 2):
        rec = _rec(OOV, seed)
        e = rec.extra
        assert e["t_film"] == 0.25
        v = e["drive"]
        E = m55.field(e, v, 0.25)
        np.testing.assert_allclose(E, v / 0.25, rtol=0, atol=1e-12)
        # its conditioning swings the thin film's field by 47 V / 0.25 um = 188 MV/m: every crystallite reached
        mm = m55.switched_share(e, E, a0=188.0)
        y = m55.reading(m55.polarisation(E, mm))
        np.testing.assert_allclose(y, _reading_written_out(E, mm), rtol=0, atol=1e-8)
        assert _rms(rec.y - y) < 1.5 * rec.noise_std
        # switched through: the polarisation changes sign, the mean state reaching over 0.9 either way
        Pol = m55.polarisation(E, mm)
        assert Pol.min() < 0 < Pol.max() and mm.min() < -0.9 and mm.max() > 0.9
        x = e["x"]
        assert x[0] == 0.0 and _full_both_ways(e)
        # no monotone map of the core the recorded drive makes comes near the reading: over 30 sigma away (measured
        # 260 ... 288)
        hc = m55.core_reading(e, rec.v)
        o = np.argsort(hc)
        ys = rec.y[o]
        miss = min(np.abs(ys - isotonic_regression(ys, increasing=inc).x).max() for inc in (True, False))
        assert miss > 30 * rec.noise_std

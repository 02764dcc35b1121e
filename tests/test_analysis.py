"""hystcomp.analysis: describing functions, slope sectors, the circle criterion."""

import numpy as np
import pytest

import control as ct

from hystcomp import MGPI, PI, StopPI
from hystcomp.analysis import (
    DescribingFunction, Sector, circle_criterion, describing_function, limit_cycles, slope_bounds,
)
from hystcomp.analysis import _numeric_df
from hystcomp.demo import demo_actuator
from hystcomp.envelopes import Linear, Tanh
from hystcomp.iosys import compensator_system, discretize, pid, piezo_stage
from hystcomp.loops import build_loop, simulate_loop

DT = 1e-4


# ---------------------------------------------------------------------------- describing functions
def test_play_is_python_controls_backlash():
    for r in (0.25, 1.0, 2.0):
        ours = describing_function(PI([r], [1.0], p0=0.0), [0.5 * r, r, 1.5 * r, 4 * r, 40 * r])
        theirs = [ct.friction_backlash_nonlinearity(2 * r).describing_function(a)
                  for a in (0.5 * r, r, 1.5 * r, 4 * r, 40 * r)]
        np.testing.assert_allclose(ours, theirs, rtol=0, atol=1e-15)


def test_analytic_pi_df_matches_the_numeric_steady_cycle():
    model = PI([0.5, 1.0, 1.5], [0.4, 0.3, 0.2], p0=1.0)
    amps = np.array([3.0, 2.0, 1.2, 0.8, 0.3])
    exact = describing_function(model, amps)
    numeric = _numeric_df(model, amps, 2048, 3)
    # 2048 samples per period: the kinks of the play cycle cost O(1/n^2) ~ 1e-7
    np.testing.assert_allclose(numeric, exact, rtol=0, atol=1e-6)
    assert exact[-1] == 1.0                      # below every threshold only p0 acts
    assert np.all(exact[:-1].imag < 0)           # the loop lags
    # python-control's numeric describing_function pre-cycles only the smallest amplitude: on this
    # nonlinearity with memory it is off by percents; ours is pre-cycled at each amplitude
    theirs = ct.describing_function(DescribingFunction(model), amps, try_method=False, num_points=2048)
    assert np.max(np.abs(theirs - exact)) > 1e-2


def test_mgpi_quadrature_matches_the_numeric_steady_cycle():
    model = demo_actuator()
    amps = np.array([0.1, 1.0, 3.0, 10.0, 50.0])
    # 48-point Gauss-Legendre per smooth piece against 8192 samples per period: 1e-7
    np.testing.assert_allclose(describing_function(model, amps), _numeric_df(model, amps, 8192, 2),
                               rtol=0, atol=1e-7)
    # small amplitude: only the r = 0 operator moves, N -> p0 gamma'(0) = 1.5
    assert describing_function(model, [1e-4])[0] == pytest.approx(1.5, rel=1e-6)


def test_stop_pi_is_one_minus_backlash():
    model = StopPI([0.5, 1.0], [0.5, 0.5], p0=0.2)
    amps = np.array([0.3, 0.8, 1.2, 3.0])
    np.testing.assert_allclose(describing_function(model, amps), _numeric_df(model, amps, 4096, 2),
                               rtol=0, atol=1e-6)


def test_numeric_path_is_independent_of_the_order_of_amplitudes():
    # an asymmetric mGPI has no closed form here: the numeric steady cycle is used
    model = MGPI([0.5, 1.0], [0.4, 0.2], p0=1.0, envelope_left=Linear(1.0), envelope_right=Linear(1.3))
    amps = np.array([0.4, 1.1, 2.5])
    a = describing_function(model, amps)
    b = describing_function(model, amps[::-1])[::-1]
    np.testing.assert_array_equal(a, b)
    assert np.all(np.isfinite(a))


def test_describing_function_object_in_python_control():
    model = PI([0.5], [1.0], p0=0.5)
    F = DescribingFunction(model)
    assert isinstance(F, ct.DescribingFunctionNonlinearity)
    assert [F(x) for x in (0.0, 1.0, 0.8)] == [0.0, 1.0, 0.9]   # 0.5 v + play(threshold 0.5)
    F.reset()
    assert F(0.0) == 0.0
    assert F.describing_function(2.0) == describing_function(model, [2.0])[0]
    with pytest.raises(ValueError, match="amplitudes"):
        describing_function(model, [-1.0])
    with pytest.raises(TypeError, match="model"):
        describing_function(object(), [1.0])


def _oscillation(v, t, t_from):
    last = v[t >= t_from]
    mid = 0.5 * (last.max() + last.min())
    up = np.nonzero((last[:-1] < mid) & (last[1:] >= mid))[0]
    freq = (up.size - 1) / ((up[-1] - up[0]) * DT)
    return 0.5 * (last.max() - last.min()), freq


def test_limit_cycle_predicted_and_confirmed_by_simulation():
    """The demo's raw actuator with too much integral gain (ki = 150): the describing function
    predicts the oscillation's amplitude at the actuator input and its frequency; the loop,
    simulated, oscillates there (issue 11: within 10 %)."""
    model = demo_actuator()
    controller = pid(0.0, 150.0, 0.0, DT)
    L = ct.series(discretize(piezo_stage(), DT), controller)
    amps = np.geomspace(0.01, 300, 300)
    (amp, freq), = limit_cycles(L, model, amps)
    # python-control's own search on the continuous loop finds the same point (the sampling's
    # half-step delay moves it by < 1 %)
    Lc = ct.tf([150.0], [1, 0]) * ct.tf(piezo_stage())
    resp = ct.describing_function_response(Lc, DescribingFunction(model), amps, warn_nyquist=False)
    (amp_c, w_c), = resp.intersections
    assert amp_c == pytest.approx(amp, rel=0.01) and w_c / (2 * np.pi) == pytest.approx(freq, rel=0.01)
    import matplotlib

    matplotlib.use("Agg")
    cplt = ct.describing_function_plot(Lc, DescribingFunction(model), amps[::3], warn_nyquist=False,
                                       omega=2 * np.pi * np.linspace(250, 350, 2000))
    assert len(cplt.lines) == 2                       # the Nyquist curve and -1/N(A) are drawn
    loop = build_loop("feedback", model, piezo_stage(), controller=controller, dt=DT)
    t = np.arange(0, 3.0, DT)
    v = simulate_loop(loop, t, np.where(t < 0.01, 0.5, 0.0)).outputs[2]
    sim_amp, sim_freq = _oscillation(v, t, 2.5)
    assert sim_amp == pytest.approx(amp, rel=0.10)
    assert sim_freq == pytest.approx(freq, rel=0.10)


def test_two_limit_cycles_small_one_unstable():
    """ki = 100: two intersections; the small one separates decay from the large oscillation."""
    model = demo_actuator()
    controller = pid(0.0, 100.0, 0.0, DT)
    L = ct.series(discretize(piezo_stage(), DT), controller)
    cycles = limit_cycles(L, model, np.geomspace(0.01, 300, 300))
    assert len(cycles) == 2
    (small, _), (large, f_large) = sorted(cycles)
    loop = build_loop("feedback", model, piezo_stage(), controller=controller, dt=DT)
    t = np.arange(0, 3.0, DT)
    quiet = simulate_loop(loop, t, np.where(t < 0.01, 0.5, 0.0)).outputs[2]
    assert np.ptp(quiet[t > 2.5]) < 1e-6                # a small kick dies out
    # a kick that drives v well beyond the small cycle: the loop settles on the large one
    kick = np.where(t < 0.03, 10.0, 0.0) * np.sin(2 * np.pi * f_large * t)
    loud = simulate_loop(loop, t, kick).outputs[2]
    sim_amp, sim_freq = _oscillation(loud, t, 2.5)
    assert sim_amp == pytest.approx(large, rel=0.10) and sim_freq == pytest.approx(f_large, rel=0.10)


# ---------------------------------------------------------------------------- slope sectors
def test_pi_slopes_exact_and_confirmed_by_sampling():
    model = PI([0.5, 1.0, 1.5, 3.0], [0.4, 0.3, 0.2, 0.1], p0=1.0)
    sec = slope_bounds(model, (-2.0, 2.0))
    assert sec.exact and (sec.lower, sec.upper) == pytest.approx((1.0, 1.9), abs=1e-15)  # r = 3 never moves
    # histories sampled from the model itself stay inside and reach both ends
    sampled = slope_bounds(_Opaque(model), (-2.0, 2.0))
    assert not sampled.exact
    assert sec.lower - 1e-9 <= sampled.lower <= sec.lower + 1e-9
    assert sec.upper - 1e-9 <= sampled.upper <= sec.upper + 1e-9
    lo, hi = sec                                             # unpacks
    assert (lo, hi) == (sec.lower, sec.upper)


class _Opaque:
    """A model seen only through the protocol (forces the sampled path)."""

    def __init__(self, model):
        self.model = model

    def simulate(self, v, initial_state=None, return_state=False):
        return self.model.simulate(v, initial_state, return_state)

    def default_state(self):
        return self.model.default_state()


def test_mgpi_and_stop_slopes_against_sampling():
    for model in (demo_actuator(), StopPI([0.5, 1.0], [0.5, 0.5], p0=0.2),
                  MGPI([0.3, 0.7], [0.5, 0.4], p0=1.0, envelope=Tanh(3.0, 0.4))):
        exact = slope_bounds(model, (-2.0, 2.0), n_samples=4000)
        sampled = slope_bounds(_Opaque(model), (-2.0, 2.0), n_samples=4000)
        # sampled histories are an inner estimate: inside the exact sector (a finite-difference slope
        # is a mean of the true slope over a step), within 1 % of its ends; the exact one is on a grid
        # of 20 n_samples points in v: 1e-8 relative
        span = exact.upper - exact.lower
        assert exact.lower * (1 - 1e-8) <= sampled.lower <= exact.lower + 0.01 * span
        assert exact.upper - 0.01 * span <= sampled.upper <= exact.upper * (1 + 1e-8)
    # the demo's actuator: p0 gamma'(2) after a reversal; the operators r < 2 on a long stroke
    sec = slope_bounds(demo_actuator(), (-2.0, 2.0))
    assert sec.lower == pytest.approx(1.5 / np.cosh(0.1) ** 2, rel=1e-12)
    assert 3.8 < sec.upper < 3.9


def test_compensated_slopes_matched_and_mismatched():
    true = PI([0.5, 1.0], [0.4, 0.2], p0=1.0)
    comp = compensator_system(true, nominal_gain=1.3)
    matched = slope_bounds(true, (-1.5, 1.5), compensator=comp)
    assert matched.lower == pytest.approx(1.3, abs=1e-9) and matched.upper == pytest.approx(1.3, abs=1e-9)
    fit = PI([0.5, 1.0], [0.3, 0.25], p0=1.1)                   # identified with errors
    mism = slope_bounds(true, (-1.5, 1.5), compensator=fit.exact_inverse())
    assert mism.lower < 1.0 < mism.upper
    raw = slope_bounds(true, (-1.5, 1.5))
    assert mism.upper / mism.lower < raw.upper / raw.lower     # still far narrower than raw
    with pytest.raises(ValueError, match="input_range"):
        slope_bounds(true, (1.0, -1.0))
    with pytest.raises(TypeError, match="compensator"):
        slope_bounds(true, (-1, 1), compensator=3.0)


# ---------------------------------------------------------------------------- circle criterion
def test_first_order_lag_absolutely_stable_for_any_sector_from_zero():
    L = ct.tf([2.0], [1.0, 3.0])
    for k in (1.0, 1e3, 1e6):
        res = circle_criterion(L, (0.0, k))
        assert res.stable and res.upper_limit == np.inf
    # sampled, the lag has a phase lag that grows to 180 deg: no longer stable for every k
    Ld = discretize(ct.ss(L), 0.01)
    res = circle_criterion(Ld, (0.0, 1e3))
    assert not res.stable and 1 < res.upper_limit < 1e3


def test_third_order_lag_enters_the_disc():
    L = ct.tf([1.0], [1.0, 3.0, 3.0, 1.0])                     # 1/(s+1)^3, linear gain margin 8
    res = circle_criterion(L, (1.0, 6.0))
    assert not res.stable and "disc" in res.message
    # brute force: k2 limit = k1 - 1/min Re M, M = L/(1 + k1 L), on a fine grid
    w = np.linspace(1e-3, 50, 2_000_001)
    Lw = 1.0 / (1j * w + 1) ** 3
    limit = 1.0 - 1.0 / np.min((Lw / (1 + Lw)).real)
    assert res.upper_limit == pytest.approx(limit, rel=1e-6)
    assert res.upper_limit < 8.0                                 # more conservative than Nyquist at k2
    # the linear loops at the sector's ends: Nyquist says stable below 8, the circle criterion agrees
    # that [1, k2] is fine for k2 just below its limit, and refuses just above
    assert circle_criterion(L, (1.0, 0.999 * limit)).stable
    assert not circle_criterion(L, (1.0, 1.001 * limit)).stable
    # a proven sector implies the linear loops at its extremes are stable (Nyquist): check both
    for k in (1.0, 0.999 * limit):
        assert np.all(ct.poles(ct.feedback(L * k, 1)).real < 0)
    # and the sector's gain margin is at most the Nyquist margin of its upper end, 8 / k2
    res = circle_criterion(L, (1.0, 2.0))
    assert res.stable and 1.0 < res.gain_margin < 8.0 / 2.0


@pytest.mark.parametrize("loop, k", [
    (ct.tf([1.0], [1.0, 3.0, 3.0, 1.0]), 1.0),
    (ct.tf([4.0], [1.0, 2.0, 2.0, 1.0]), 0.5),
    (ct.series(discretize(piezo_stage(), DT), pid(0.0, 40.0, 0.0, DT)), 2.712),   # the old demo loop
])
def test_degenerate_sector_gives_the_linear_gain_margin(loop, k):
    import warnings

    res = circle_criterion(loop, (k, k))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")   # python-control's note on its 'frd' fallback
        gm = ct.stability_margins(loop * k)[0]
    # python-control falls back to interpolating the frequency response for the sampled loop:
    # agreement to 1e-3 there (1e-6 for the continuous loops, found by polynomial roots)
    assert res.stable and res.gain_margin == pytest.approx(gm, rel=1e-3 if loop.isdtime() else 1e-6)
    # and the closed loop is on its stability boundary there: bisection to 1e-9 relative
    for g, inside in ((res.gain_margin * (1 - 1e-6), True), (res.gain_margin * (1 + 1e-6), False)):
        poles = ct.poles(ct.feedback(loop * k * g, 1))
        assert (np.all(np.abs(poles) < 1) if loop.isdtime() else np.all(poles.real < 0)) == inside


def test_unstable_linear_part_at_k1():
    L = ct.tf([1.0], [1.0, 0.0, 0.0])                           # double integrator
    res = circle_criterion(L, (0.5, 1.0))
    assert not res.stable and np.isnan(res.upper_limit) and "unstable" in res.message


def test_random_time_varying_gains_in_a_proven_sector_decay():
    # a discrete loop, a gain switching at random inside the proven sector: the state decays
    L = ct.series(discretize(piezo_stage(), DT), pid(0.0, 40.0, 0.0, DT))
    res = circle_criterion(L, (1.0, 3.0))
    assert res.stable
    s = ct.ss(L)
    A, B, C = np.asarray(s.A), np.asarray(s.B), np.asarray(s.C)
    rng = np.random.default_rng(1)
    x = np.ones(A.shape[0])
    for _ in range(40_000):
        k = rng.uniform(1.0, 3.0)
        x = A @ x - B[:, 0] * k * (C @ x)[0]
    assert np.linalg.norm(x) < 1e-6


def test_bad_bounds_are_named():
    with pytest.raises(ValueError, match="bounds"):
        circle_criterion(ct.tf([1], [1, 1]), (2.0, 1.0))
    with pytest.raises(TypeError, match="loop"):
        circle_criterion("L", (0, 1))
    assert list(Sector(1.0, 2.0, True)) == [1.0, 2.0]

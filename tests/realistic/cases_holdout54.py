"""The HOLDOUT54 set: written after HOLDOUT53 was measured, by a session that did not read how the diagnosis decides,
and run once for round 56's measurement (15 of 30 runs right on commit abb8290); part of ALL since.

Mechanisms and signals that the other sets do not have (the laws are in :mod:`.mechanisms54`, the signals in
:mod:`.signals54`, each beside its source; the citations were written from memory, as they say). Every core is a
spin-crossover composite strip: crystallites of an iron(II) triazole molecular alloy (its transition tuned to about room
temperature), 0.4 of the volume in a polyurethane matrix, 25 mm long, its temperature set by a heater and a temperature
loop from the drive (0.16 K a volt about the bias, the middle of the crystallites' loops; on the unipolar records the
drive's 0 V is 7.5 K below it), pulling a light carriage read by an LVDT (um, zeroed at the start of every record).
Every crystallite is a cooperative Slichter-Drickamer body: its high-spin fraction on the low-spin branch of its free
energy's minimum until that branch ends at its upper spinodal, then on the high-spin branch until its lower spinodal
(each branch bending with the temperature); 3000 classes, their T_half normal (spread 6.5 ... 7.5 K: the alloy's local
composition), their interaction over 2 R T_half log-normal (median 1.18 ... 1.24); the strip's length takes the
high-spin lattice's 10 % and its larger expansion, and the matrix's. Rate independent, with return-point memory; close
to a Prandtl-Ishlinskii model but not one (measured in tests/test_realistic_holdout54.py: a PI model of 12 plays of the
drive fitted by NNLS, stated there). The stroke is some 0.1 ... 0.15 mm over +-46 V. Every record but the initial-state
case's starts at 0 V of drive from the rest state the controller's conditioning routine leaves there (a slowly decaying
thermal cycling about that temperature: every crystallite high spin whose loop's middle lies below it, the others low
spin; the state is set so, not run), for unipolar and bipolar records alike; nothing else is run before a record.

- a clean core under a hammer thrower's winds and turns, +-44 ... 48 V, with a noisy input monitor, sampled at 1.531
  kHz;
- creep of a nylon pushrod between the strip and a valve poppet's spring (logarithmic creep compliance, J_0 + J_1 ln(1
  + t / tau_c); a Volterra equation of the load path); under a baker kneading dough, on a unipolar stroke, sampled at
  263 Hz;
- rate dependence from a strip cast with micro-crystals: each crystallite relaxing to its free energy's minimum by the
  Ising-like model's mean-field master equation (tau_k 25 ... 40 ms; slowing near the spinodals); under a unicyclist's
  balancing (never still), +-44 ... 48 V, with a noisy input monitor, sampled at 1.301 kHz;
- a drift from an enclosure's on-off hygrostat: the humidity's lopsided sawtooth taken up through the strip's matrix
  (Fick's law in a plane sheet) and swelling it; under a cheesemaker's press, on a unipolar stroke, sampled at 211 Hz;
- asymmetry from a crank standing at 38 ... 42 deg (its radius 3.3 ... 4 times the stroke's larger side), its angle
  read (an arcsine of the strip's travel); under a pizzaiolo's peel, +-44 ... 48 V, sampled at 877 Hz;
- saturation from the carriage's travel-limit screw set too close (0.55 ... 0.7 of the upward swing): the strip goes
  slack beyond it; under a harbour pilot's bow-thruster joystick, +-44 ... 48 V, with a noisy input monitor, sampled at
  1.019 kHz;
- a delay from a sigma-delta converter's sinc^3 filter (20 ... 30 conversions a second, each held until the next: some
  1.5 ... 2 periods); under a tattoo artist's foot pedal, on a unipolar stroke, with a noisy input monitor, sampled at
  547 Hz;
- a strip in another state at the start: fresh from its post-bake at 80 C (every crystallite high spin) cooled straight
  to the bias without the conditioning; under an aircraft marshaller's wand (held still first, then the signals),
  +-44 ... 48 V, sampled at 683 Hz;
- two effects: the carriage read by a silicon strain gauge in a quarter bridge (its own nonlinearity, 2 r / (2 + r);
  labelled "asymmetry") switched on with the record, the gauge warming by its own dissipation (two time constants;
  labelled "drift"); under a chimney sweep's rods, +-44 ... 48 V, sampled at 797 Hz;
- out of vocabulary: the LVDT replaced by a magnetic scale's interpolator without a period counter, its wrap inside the
  stroke: the reading jumps back a whole period as the strip lengthens past it; under a church bell-ringer's rope,
  +-44 ... 48 V, sampled at 1.117 kHz.

Every bipolar drive is drawn until its weaker side reaches 0.85 of its stronger (a test programme's balance). The
effects' sizes beyond a gain and an offset on the core (seeds 0 ... 2; RMS and largest) are stated in the test.
"""

import math

import numpy as np

from . import mechanisms54 as m54
from . import signals54 as s54
from . import set_tools
from .record import case_set, finish
from .set_tools import scale as _scale

HOLDOUT54, case, _rng = case_set("holdout54_", 54000)


def _strip(rng, unipolar=False):
    """The core: the crystallites' seed (the R2 sequence's shift), the alloy's mean T_half Th0 (K) and its spread sh
    (K), the interaction's median k50 (over 2 R T_half); the bias Tb (K) follows from them."""
    core = dict(rseed=int(rng.integers(0, 2**31 - 2)), Th0=rng.uniform(296.0, 300.0), sh=rng.uniform(6.5, 7.5),
                k50=rng.uniform(1.18, 1.24), unipolar=unipolar)
    core["Tb"] = m54.bias(core)
    return core


def _knotted(rng, dt, gen):
    """A balanced bipolar drive from a knot programme gen(rng) -> (knots, T_end)."""
    return set_tools.knotted(rng, dt, gen, s54.knots_at)


def _unipolar(rng, dt, gen):
    return set_tools.unipolar(rng, dt, gen, s54.knots_at)


def _bipolar(rng, dt, gen):
    x, t, kn = _knotted(rng, dt, gen)
    amp = rng.uniform(44.0, 48.0)
    return x, t, kn, amp, _scale(x, amp)


def _note(core):
    return (f"a spin-crossover strip's {m54.N_CRYST} crystallite classes (T_half {core['Th0']:.1f} K +- "
            f"{core['sh']:.1f} K, kappa {core['k50']:.2f}, biased at {core['Tb']:.1f} K)")


# ---- clean ----

@case
def clean_spin_crossover_strip_hammer_thrower_1531hz(seed):
    """A clean core under a hammer thrower's winds and turns, from the rest state at 0 V; nothing else is run before
    it."""
    rng = _rng(seed, 1)
    dt = 1 / 1531
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s54.hammer_thrower(r, 1))
    core = dict(_strip(rng), amp=amp)
    y = m54.core_reading(core, v)
    rec = finish("holdout54_clean_spin_crossover_strip_hammer_thrower_1531hz", seed, t, v, y, set(), "explained",
                 f"a clean core ({_note(core)}) under a hammer thrower ({len(kn)} knots), +-{amp:.0f} V, 1.531 kHz",
                 rng, monitor_noise=2e-4)
    rec.extra.update(core, knots=kn, x=x, drive=v)
    return rec


# ---- one effect ----

@case
def creep_nylon_pushrod_log_creep_dough_kneading_263hz(seed):
    """A nylon pushrod creeping between the strip and a valve poppet's spring under a baker kneading dough (unipolar),
    from the rest state at 0 V (the rod long at rest under the preload); nothing else is run before it."""
    rng = _rng(seed, 2)
    dt = 1 / 263
    t, kn, p, top, v = _unipolar(rng, dt, lambda r: s54.dough_kneading(r, 2))
    core = dict(_strip(rng, unipolar=True), top=top)
    c0, c1, tau_c = rng.uniform(0.04, 0.07), rng.uniform(0.04, 0.06), rng.uniform(0.05, 0.2)
    d = m54.core_reading(core, v)
    kern = m54.log_creep_kernel(len(t), dt, c0, c1, tau_c)
    y = m54.volterra_creep(d, kern)
    rec = finish("holdout54_creep_nylon_pushrod_log_creep_dough_kneading_263hz", seed, t, v, y, {"creep"}, "either",
                 f"a nylon pushrod creeping under a valve poppet's spring (k J_0 {c0:.3f}, k J_1 {c1:.3f}, tau_c "
                 f"{tau_c * 1e3:.0f} ms) under a baker kneading dough, to {top:.0f} V, 263 Hz", rng)
    rec.extra.update(core, knots=kn, p=p, c0=c0, c1=c1, tau_c=tau_c, d=d, drive=v)
    return rec


@case
def rate_micro_crystal_master_equation_unicyclist_1301hz(seed):
    """Micro-crystals switching at a finite speed under a unicyclist's balancing, from the rest state at 0 V; nothing
    else is run before it."""
    rng = _rng(seed, 3)
    dt = 1 / 1301
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s54.unicyclist(r, 3))
    core = dict(_strip(rng), amp=amp)
    tau_k = rng.uniform(0.025, 0.04)
    T = m54.temperature(core, v)
    xbar = m54.kinetic_fraction(core, T, dt, tau_k)
    y = m54.reading(T, xbar)
    rec = finish("holdout54_rate_micro_crystal_master_equation_unicyclist_1301hz", seed, t, v, y,
                 {"rate_dependence"}, "either",
                 f"micro-crystals relaxing by the master equation (tau_k {tau_k * 1e3:.0f} ms) under a unicyclist's "
                 f"balancing, +-{amp:.0f} V, 1.301 kHz", rng, monitor_noise=3e-4)
    rec.extra.update(core, knots=kn, x=x, tau_k=tau_k, xbar=xbar, drive=v)
    return rec


@case
def drift_hygrostat_matrix_swelling_cheese_press_211hz(seed):
    """An enclosure's on-off hygrostat swelling the strip's matrix under a cheesemaker's press (unipolar), from the
    rest state at 0 V (the enclosure long in its cycle); nothing else is run before it."""
    rng = _rng(seed, 4)
    dt = 1 / 211
    t, kn, p, top, v = _unipolar(rng, dt, lambda r: s54.cheese_press(r, 2))
    core = dict(_strip(rng, unipolar=True), top=top)
    S, b = rng.uniform(45.0, 50.0), rng.uniform(6.0, 8.0)
    tau_e, D = rng.uniform(40.0, 60.0), rng.uniform(1.5e-11, 2.5e-11)
    rh_hi, rh_lo = S + b / 2 + rng.uniform(3.0, 6.0), S - b / 2 - rng.uniform(6.0, 10.0)
    times, rh = m54.hygrostat(t[-1], 600.0, S, b, rh_hi, rh_lo, tau_e)
    U = m54.sheet_uptake(times, rh, 60e-6, D)
    Ut = np.interp(t, times, U)
    drift = 1e6 * m54.L_STRIP * m54.BETA_H * (Ut - Ut[0])
    h = m54.core_reading(core, v)
    y = h + drift
    rec = finish("holdout54_drift_hygrostat_matrix_swelling_cheese_press_211hz", seed, t, v, y, {"drift"}, "either",
                 f"an enclosure's hygrostat at {S:.0f} % RH +- {b / 2:.1f} (tau {tau_e:.0f} s; the matrix's uptake "
                 f"{np.ptp(Ut):.1f} % RH over the record) under a cheesemaker's press, to {top:.0f} V, 211 Hz", rng)
    rec.extra.update(core, knots=kn, p=p, S=S, b=b, tau_e=tau_e, D=D, rh_hi=rh_hi, rh_lo=rh_lo, U=Ut, h=h, drive=v)
    return rec


@case
def asymmetry_tilted_crank_angle_pizza_peel_877hz(seed):
    """A crank standing tilted, read by its angle, under a pizzaiolo's peel, from the rest state at 0 V; nothing else is
    run before it."""
    rng = _rng(seed, 5)
    dt = 1 / 877
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s54.pizza_peel(r, 2))
    core = dict(_strip(rng), amp=amp)
    rho, theta0 = rng.uniform(0.25, 0.3), math.radians(rng.uniform(38.0, 42.0))
    d = m54.core_reading(core, v)
    r_um = np.abs(d).max() / rho
    y = m54.crank_reading(d, r_um, theta0)
    rec = finish("holdout54_asymmetry_tilted_crank_angle_pizza_peel_877hz", seed, t, v, y, {"asymmetry"}, "either",
                 f"a crank of {r_um:.0f} um standing at {math.degrees(theta0):.0f} deg, read by its angle, under a "
                 f"pizzaiolo's peel, +-{amp:.0f} V, 877 Hz", rng)
    rec.extra.update(core, knots=kn, x=x, rho=rho, r_um=r_um, theta0=theta0, d=d, drive=v)
    return rec


@case
def saturation_travel_stop_slack_strip_bow_thruster_1019hz(seed):
    """The carriage's travel-limit screw set too close under a harbour pilot's bow-thruster joystick, from the rest
    state at 0 V; nothing else is run before it."""
    rng = _rng(seed, 6)
    dt = 1 / 1019
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s54.bow_thruster(r, 1))
    core = dict(_strip(rng), amp=amp)
    frac = rng.uniform(0.55, 0.7)
    d = m54.core_reading(core, v)
    g = frac * d.max()
    y = m54.stop_reading(d, g)
    rec = finish("holdout54_saturation_travel_stop_slack_strip_bow_thruster_1019hz", seed, t, v, y, {"saturation"},
                 "either",
                 f"the carriage's travel stop {g:.0f} um up ({frac:.0%} of the upward swing) under a harbour pilot's "
                 f"bow-thruster joystick, +-{amp:.0f} V, 1.019 kHz", rng, monitor_noise=2.5e-4)
    rec.extra.update(core, knots=kn, x=x, frac=frac, g=g, d=d, drive=v)
    return rec


@case
def delay_sigma_delta_sinc3_tattoo_pedal_547hz(seed):
    """The set point through a sigma-delta converter's sinc^3 filter under a tattoo artist's foot pedal (unipolar),
    from the rest state at 0 V (the converter long reading 0 V); nothing else is run before it."""
    rng = _rng(seed, 7)
    dt = 1 / 547
    t, kn, p, top, v = _unipolar(rng, dt, lambda r: s54.tattoo_pedal(r, 3))
    core = dict(_strip(rng, unipolar=True), top=top)
    f_d = rng.uniform(20.0, 30.0)
    Tc = 1.0 / f_d
    phase = rng.uniform(0.0, Tc)
    pmax = p.max()
    v_set, _ = m54.sigma_delta(t, Tc, phase, lambda tt: top * s54.knots_at(tt, kn) / pmax)
    y = m54.core_reading(core, v_set)
    rec = finish("holdout54_delay_sigma_delta_sinc3_tattoo_pedal_547hz", seed, t, v, y, {"delay"}, "either",
                 f"the set point through a sigma-delta converter's sinc^3 filter at {f_d:.1f} conversions a second "
                 f"under a tattoo artist's pedal, to {top:.0f} V, 547 Hz", rng, monitor_noise=3e-4)
    rec.extra.update(core, knots=kn, p=p, f_d=f_d, Tc=Tc, phase=phase, v_set=v_set, drive=v)
    return rec


@case
def initial_state_post_bake_marshaller_wand_683hz(seed):
    """A strip fresh from its post-bake and cooled straight to the bias, without the conditioning, under an aircraft
    marshaller's wand (held still first)."""
    rng = _rng(seed, 8)
    dt = 1 / 683
    amp = rng.uniform(44.0, 48.0)
    core = dict(_strip(rng), amp=amp)
    s = m54.baked_state(core)
    x, t, kn = _knotted(rng, dt, lambda r: s54.marshaller(r, 6))
    v = _scale(x, amp)
    s0 = s.copy()
    y = m54.core_reading(core, v, s)
    n_off = int(np.sum(s0 != m54.rest_state(core, core["Tb"])))
    rec = finish("holdout54_initial_state_post_bake_marshaller_wand_683hz", seed, t, v, y, {"initial_state"},
                 "either",
                 f"a strip fresh from its post-bake cooled straight to the bias ({n_off} of {m54.N_CRYST} classes high "
                 f"spin that the conditioning leaves low spin) under a marshaller's wand, +-{amp:.0f} V, 683 Hz", rng)
    rec.extra.update(core, s0=s0, n_off=n_off, knots=kn, x=x, drive=v)
    return rec


# ---- two effects ----

@case
def pair_asymmetry_drift_quarter_bridge_warm_up_chimney_sweep_797hz(seed):
    """The carriage read by a silicon gauge in a quarter bridge ("asymmetry") switched on with the record and warming
    ("drift") under a chimney sweep's rods, from the rest state at 0 V; nothing else is run before it."""
    rng = _rng(seed, 9)
    dt = 1 / 797
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s54.chimney_sweep(r, 2))
    core = dict(_strip(rng), amp=amp)
    q, D_um = rng.uniform(0.22, 0.28), rng.uniform(18.0, 24.0)
    a, tau1, tau2 = rng.uniform(0.3, 0.5), rng.uniform(3.0, 6.0), rng.uniform(60.0, 100.0)
    h = m54.core_reading(core, v)
    x_r = np.abs(h).max() / q
    delta = m54.warm_up(t, D_um / x_r, a, tau1, tau2)
    y = m54.bridge_reading(h / x_r + delta, x_r)
    rec = finish("holdout54_pair_asymmetry_drift_quarter_bridge_warm_up_chimney_sweep_797hz", seed, t, v, y,
                 {"asymmetry", "drift"}, "either",
                 f"a silicon gauge in a quarter bridge (r up to {q:.2f}) warming by {D_um:.0f} um (tau {tau1:.1f} s "
                 f"and {tau2:.0f} s) under a chimney sweep's rods, +-{amp:.0f} V, 797 Hz", rng)
    rec.extra.update(core, knots=kn, x=x, q=q, D_um=D_um, a=a, tau1=tau1, tau2=tau2, x_r=x_r, delta=delta, h=h,
                     drive=v)
    return rec


# ---- out of vocabulary ----

@case
def oov_magnetic_scale_period_wrap_bell_ringer_1117hz(seed):
    """A magnetic scale read within one period, its wrap inside the stroke, under a church bell-ringer's rope, from the
    rest state at 0 V; nothing else is run before it."""
    rng = _rng(seed, 10)
    dt = 1 / 1117
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s54.bell_ringer(r, 1))
    core = dict(_strip(rng), amp=amp)
    h = m54.core_reading(core, v)
    wfrac = rng.uniform(0.3, 0.45)
    x_w = wfrac * h.max()
    y = m54.scale_reading(h, x_w)
    rec = finish("holdout54_oov_magnetic_scale_period_wrap_bell_ringer_1117hz", seed, t, v, y, set(), "unexplained",
                 f"a magnetic scale's interpolator without a period counter, its wrap {x_w:.0f} um up the stroke, "
                 f"under a bell-ringer's rope, +-{amp:.0f} V, 1.117 kHz", rng)
    rec.extra.update(core, knots=kn, x=x, x_w=x_w, h=h, drive=v)
    return rec

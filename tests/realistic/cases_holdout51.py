"""The HOLDOUT51 set: written after HOLDOUT50 was measured, by a session that did not read how the diagnosis decides,
and run once for round 53's measurement (14 of 30 runs right on commit 1388680); part of ALL since.

Mechanisms and signals that the other sets do not have (the laws are in :mod:`.mechanisms51`, the signals in
:mod:`.signals51`, each beside its source; the citations were written from memory, as they say). Every core is a
multilayer stack of the relaxor 0.9 PMN - 0.1 PT (200 layers of 100 um, 20 mm active) on a 0 ... 200 V amplifier that
biases it (120 V on the bipolar records, 70 V on the unipolar ones, 1 V a volt of drive), driving a flexure-hinged lever
of ratio 5 whose tip a capacitive gauge reads (um, zeroed at the start of every record). Its polarisation is a
Smolenskii ensemble of 4096 polar clusters (Curie temperatures normal about the room's 25 C +-1 K, spread 9 ... 11 K;
log-normal sizes, median 28 ... 32 nm; random fields, spread 0.68 ... 0.74 MV / m), each a Landau-Devonshire body in
its well, the blocked ones switching where the thermally activated barrier falls to 25 k T, the ergodic ones in their
deeper well; the strain is electrostrictive, Q P^2. Rate independent, with return-point memory; a slim loop; close to a
Prandtl-Ishlinskii model but not one (measured in tests/test_realistic_holdout51.py: a PI model of 12 plays of the drive
fitted by NNLS, stated there). The stroke at the tip is about 27 um over +-46 V of drive. Every record but the
initial-state case's starts at 0 V of drive from the rest state the controller's start-up dither leaves at the bias
(every bistable cluster in its deeper well there: the state is set so, not run), for unipolar and bipolar records
alike; nothing else is run before a record.

- a clean core under a snooker player's cue (feathering, the backswing, the pause, the stroke through the ball, the
  freeze), +-44 ... 48 V, with a noisy input monitor, sampled at 1.183 kHz;
- creep from the relaxor's slow dielectric relaxation (Cole-Cole, alpha 0.45 ... 0.6, tau 1.5 ... 3 s, 0.16 ... 0.21
  of its susceptibility); under an archer's draws (anchor, aim, release, let-downs), on a unipolar stroke, sampled at
  263 Hz;
- rate dependence from the amplifier's series resistor (1.5 ... 2.2 kOhm) charging the stack's field-dependent
  capacitance; under a cross-country skier's poles (diagonal stride, double poling, herringbone, tuck: never still),
  +-44 ... 48 V, with a noisy input monitor, sampled at 1.811 kHz;
- a drift from the stack's temperature as its water-cooled housing's chiller cycles through its dead band (the
  relaxor's polarisation falling as it warms); under a weightlifter's clean-and-jerk session, on a unipolar stroke,
  sampled at 211 Hz;
- asymmetry from the amplifier's bias switch left at its low position (60 ... 66 V), where the strain is convex in the
  drive; under a skateboarder's carves and kick turns, +-44 ... 48 V, sampled at 953 Hz;
- saturation from the lever stage's overtravel stops set too tight (Hertz contacts of steel balls at 0.55 ... 0.65 of
  the free stroke each way); under a gardener's hedge trimmer (sweeps and trims: never still), +-44 ... 48 V, with a
  noisy input monitor, sampled at 1.327 kHz;
- a delay of the gauge's sigma-delta converter (its sinc^3 filter and a word's latency: 2.5 samples); under a trumpet
  player's first valve, on a unipolar stroke, with a noisy input monitor, sampled at 431 Hz;
- a stack in another state at the start: a night short-circuited at 0 V and the start-up dither skipped (the stack
  ramped straight to its bias); under a model railway's controller (shunting first, then main-line runs), +-44 ... 48
  V, sampled at 617 Hz;
- two effects: creep of a flexible epoxy bond line under the stack (logarithmic creep compliance; labelled "creep") and
  the gauge's range too small, its converter clipping the reading (labelled "output_saturation"); under a theatre
  flyman's batten (cues, scenes held, trims touched up), +-44 ... 48 V, sampled at 337 Hz;
- out of vocabulary: the bias supply's fuse blown, the field swinging through zero and the electrostrictive stroke a
  butterfly; under a petanque player's throws, +-44 ... 48 V, sampled at 1.129 kHz. The record does not carry the
  lost bias: the recorded drive is the PC's.

Every bipolar drive is drawn until its weaker side reaches 0.85 of its stronger (a test programme's balance). The
effects' sizes beyond a gain and an offset on the core (seeds 0 ... 2; RMS and largest) are stated in the test.
"""

import math

import numpy as np

from . import mechanisms51 as m51
from . import signals51 as s51
from . import set_tools
from .record import case_set, finish
from .set_tools import fine as _fine, scale as _scale

HOLDOUT51, case, _rng = case_set("holdout51_", 51000)


def _stack(rng, unipolar=False):
    """The core: the clusters' seed (the Sobol sequence's scrambling), the clusters' mean Curie temperature Tc (K) and
    its spread dTc (K), their median size d50 (nm), the random fields' spread sI (MV / m), the rest of the ceramic's
    permittivity eps_bg, and the amplifier's bias (V) and gain (V a volt of drive)."""
    return dict(rseed=int(rng.integers(0, 2**31 - 2)), Tc=rng.uniform(297.15, 299.15), dTc=rng.uniform(9.0, 11.0),
                d50=rng.uniform(28.0, 32.0), sI=rng.uniform(0.68, 0.74), eps_bg=rng.uniform(1400.0, 1600.0),
                bias=70.0 if unipolar else 120.0, gain=1.0, unipolar=unipolar)


def _knotted(rng, dt, gen):
    """A balanced bipolar drive from a knot programme gen(rng) -> (knots, T_end)."""
    return set_tools.knotted(rng, dt, gen, s51.knots_at)


def _unipolar(rng, dt, gen):
    return set_tools.unipolar(rng, dt, gen, s51.knots_at)


def _bipolar(rng, dt, gen):
    return set_tools.bipolar(rng, dt, gen, s51.knots_at)


def _reading(core, v, stack=None):
    """The rate-independent stack's reading (um at the lever's tip) for the drive v, from `stack` (default the rest
    state)."""
    return m51.core_reading(core, m51.amp_voltage(core, v), stack)


# ---- clean ----

@case
def clean_pmn_pt_stack_snooker_cue_1183hz(seed):
    """A clean core under a snooker player's cue, from the rest state at 0 V; nothing else is run before it."""
    rng = _rng(seed, 1)
    dt = 1 / 1183
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s51.snooker_cue(r, 2))
    core = dict(_stack(rng), amp=amp)
    y = _reading(core, v)
    rec = finish("holdout51_clean_pmn_pt_stack_snooker_cue_1183hz", seed, t, v, y, set(), "explained",
                 f"a clean core (a PMN-PT stack's 4096 polar clusters, T_c {core['Tc'] - 273.15:.1f} +- "
                 f"{core['dTc']:.1f} C, {core['d50']:.1f} nm, random fields {core['sI']:.2f} MV/m, biased at 120 V) "
                 f"under a snooker player's cue ({len(kn)} knots), +-{amp:.0f} V, 1.183 kHz", rng, monitor_noise=2e-4)
    rec.extra.update(core, knots=kn, x=x, drive=v)
    return rec


# ---- one effect ----

@case
def creep_cole_cole_relaxation_archery_263hz(seed):
    """The relaxor's slow dielectric relaxation under an archer's draws (unipolar), from the rest state at 0 V (the
    stack long at its bias: nothing relaxing); nothing else is run before it."""
    rng = _rng(seed, 2)
    dt = 1 / 263
    t, kn, p, top, v = _unipolar(rng, dt, lambda r: s51.archery(r, 2))
    core = dict(_stack(rng, unipolar=True), top=top)
    alpha, tau, share = rng.uniform(0.45, 0.6), rng.uniform(1.5, 3.0), rng.uniform(0.16, 0.21)
    U = m51.amp_voltage(core, v)
    E = m51.field(U)
    P = m51.core_polarisation(core, U)
    chi_s = share * np.ptp(P) / np.ptp(E)
    Ps = chi_s * m51.hereditary(E, m51.cole_cole_kernel(len(t), dt, tau, alpha))
    y = m51.reading(P + Ps)
    rec = finish("holdout51_creep_cole_cole_relaxation_archery_263hz", seed, t, v, y, {"creep"}, "either",
                 f"the relaxor's slow dielectric relaxation (Cole-Cole, alpha {alpha:.2f}, tau {tau:.2f} s, "
                 f"{share:.0%} of its susceptibility) under an archer's draws, to {top:.0f} V, 263 Hz", rng)
    rec.extra.update(core, knots=kn, p=p, alpha=alpha, tau=tau, share=share, chi_s=chi_s, P=P, Ps=Ps, drive=v)
    return rec


@case
def rate_series_resistor_charging_cross_country_skier_1811hz(seed):
    """The amplifier's series resistor charging the stack under a cross-country skier's poles, from the rest state at 0
    V (the stack charged to its bias); nothing else is run before it."""
    rng = _rng(seed, 3)
    dt = 1 / 1811
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s51.cross_country_skier(r, int(r.integers(1, 3))))
    core = dict(_stack(rng), amp=amp)
    R = rng.uniform(1.5e3, 2.2e3)
    sub = m51.SUB_RC
    tf = _fine(t, sub)
    vf = amp * s51.knots_at(tf, kn) / np.abs(x).max()
    Uf = m51.charging(core, m51.amp_voltage(core, vf), dt / sub, R)
    U = Uf[::sub]
    y = m51.reading(m51.core_polarisation(core, U))
    rec = finish("holdout51_rate_series_resistor_charging_cross_country_skier_1811hz", seed, t, v, y,
                 {"rate_dependence"}, "either",
                 f"the amplifier's {R / 1e3:.2f} kOhm series resistor charging the stack under a cross-country "
                 f"skier's poles, +-{amp:.0f} V, 1.811 kHz", rng, monitor_noise=3e-4)
    rec.extra.update(core, knots=kn, x=x, R=R, U=U, drive=v)
    return rec


@case
def drift_chiller_dead_band_weightlifter_211hz(seed):
    """The stack's temperature following its chiller's dead band under a weightlifter's session (unipolar), from the
    rest state at 0 V; nothing else is run before it."""
    rng = _rng(seed, 4)
    dt = 1 / 211
    t, kn, p, top, v = _unipolar(rng, dt, lambda r: s51.weightlifter(r, int(r.integers(4, 6))))
    core = dict(_stack(rng, unipolar=True), top=top)
    band, d_cold, d_load = rng.uniform(1.0, 1.4), rng.uniform(6.0, 8.0), rng.uniform(3.0, 5.0)
    tau_w, tau_s = rng.uniform(60.0, 100.0), rng.uniform(8.0, 14.0)
    t_lead = rng.uniform(8.0, 9.0) * (tau_w * (math.log((band + d_load) / (d_load - band))
                                               + math.log((band + d_cold) / (d_cold - band))))
    dT, Tc = m51.stack_temperature(t, t_lead, band, d_cold, d_load, tau_w, tau_s, dt)
    U = m51.amp_voltage(core, v)
    E = m51.field(U)
    st = m51.Stack(core, E[0])
    P = st.run_warming(E, dT)
    y = m51.reading(P)
    rec = finish("holdout51_drift_chiller_dead_band_weightlifter_211hz", seed, t, v, y, {"drift"}, "either",
                 f"the stack's temperature under its chiller's dead band (+-{band:.2f} K, the coolant's tau "
                 f"{tau_w:.0f} s, the housing's {tau_s:.0f} s: {np.ptp(dT):.2f} K over the record) under a "
                 f"weightlifter's session, to {top:.0f} V, 211 Hz", rng)
    rec.extra.update(core, knots=kn, p=p, band=band, d_cold=d_cold, d_load=d_load, tau_w=tau_w, tau_s=tau_s,
                     t_lead=t_lead, dT=dT, T_coolant=Tc, drive=v)
    return rec


@case
def asymmetry_bias_switch_low_skateboard_carving_953hz(seed):
    """The amplifier's bias switch left low under a skateboarder's carves, from the rest state at 0 V (the dither's
    limit at that bias); nothing else is run before it."""
    rng = _rng(seed, 5)
    dt = 1 / 953
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s51.skateboard_carving(r, int(r.integers(2, 4))))
    core = dict(_stack(rng), amp=amp)
    low = rng.uniform(60.0, 66.0)
    y = _reading(dict(core, bias=low), v)
    rec = finish("holdout51_asymmetry_bias_switch_low_skateboard_carving_953hz", seed, t, v, y, {"asymmetry"}, "either",
                 f"the amplifier's bias switch left low ({low:.1f} V for 120) under a skateboarder's carves, "
                 f"+-{amp:.0f} V, 953 Hz", rng)
    rec.extra.update(core, knots=kn, x=x, low=low, drive=v)
    return rec


@case
def saturation_hertz_overtravel_stops_hedge_trimmer_1327hz(seed):
    """The lever stage's overtravel stops set too tight under a gardener's hedge trimmer, from the rest state at 0 V;
    nothing else is run before it."""
    rng = _rng(seed, 6)
    dt = 1 / 1327
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s51.hedge_trimmer(r, int(r.integers(2, 4))))
    core = dict(_stack(rng), amp=amp)
    k_e, R_b = rng.uniform(10.0, 14.0), rng.uniform(10.0, 20.0)
    K_H = 4.0 / 3.0 * 115e9 * math.sqrt(R_b * 1e-3) * 1e-9
    f_hi, f_lo = rng.uniform(0.55, 0.65), rng.uniform(0.55, 0.65)
    xf = _reading(core, v)
    g_hi, g_lo = f_hi * xf.max(), -f_lo * xf.min()
    y = m51.stopped(xf, k_e, K_H, g_hi, g_lo)
    rec = finish("holdout51_saturation_hertz_overtravel_stops_hedge_trimmer_1327hz", seed, t, v, y,
                 {"output_saturation"}, "either",
                 f"the lever stage's overtravel stops at +{g_hi:.1f} / -{g_lo:.1f} um (steel balls of {R_b:.0f} mm, "
                 f"the tip's stiffness {k_e:.1f} N/um) under a hedge trimmer, +-{amp:.0f} V, 1.327 kHz", rng,
                 monitor_noise=2.5e-4)
    rec.extra.update(core, knots=kn, x=x, k_e=k_e, R_b=R_b, K_H=K_H, g_hi=g_hi, g_lo=g_lo, xf=xf, drive=v)
    return rec


@case
def delay_sigma_delta_gauge_trumpet_valve_431hz(seed):
    """The gauge's sigma-delta converter's filter and latency under a trumpet player's valve (unipolar), from the rest
    state at 0 V; nothing else is run before it."""
    rng = _rng(seed, 7)
    dt = 1 / 431
    t, kn, p, top, v = _unipolar(rng, dt, lambda r: s51.trumpet_valve(r, int(r.integers(4, 7))))
    core = dict(_stack(rng, unipolar=True), top=top)
    sub = m51.SUB_GAUGE
    tf = _fine(t, sub)
    vf = top * s51.knots_at(tf, kn) / p.max()
    yf = _reading(core, vf)
    y = m51.gauge_filtered(yf, sub)
    rec = finish("holdout51_delay_sigma_delta_gauge_trumpet_valve_431hz", seed, t, v, y, {"delay"}, "either",
                 f"the gauge's sinc^3 filter and a word's latency (2.5 samples) under a trumpet player's valve, to "
                 f"{top:.0f} V, 431 Hz", rng, monitor_noise=3e-4)
    rec.extra.update(core, knots=kn, p=p, y_fine=yf, drive=v)
    return rec


@case
def initial_state_shorted_overnight_model_railway_617hz(seed):
    """The stack short-circuited overnight and ramped to its bias without the dither, under a model railway's
    controller (shunting first)."""
    rng = _rng(seed, 8)
    dt = 1 / 617
    amp = rng.uniform(44.0, 48.0)
    core = dict(_stack(rng), amp=amp)
    st = m51.overnight_stack(core)
    x, t, kn = _knotted(rng, dt, lambda r: s51.model_railway(r, int(r.integers(3, 5))))
    v = _scale(x, amp)
    s0 = st.s.copy()
    y = _reading(core, v, st)
    rest = m51.Stack(core, m51.field(core["bias"]))
    n_off = int(np.sum((s0 != rest.s) & (rest.a < 0)))
    rec = finish("holdout51_initial_state_shorted_overnight_model_railway_617hz", seed, t, v, y, {"initial_state"},
                 "either",
                 f"the stack short-circuited overnight and ramped to its bias without the dither ({n_off} of "
                 f"{m51.N_CLUSTERS} clusters in the other well) under a model railway's controller, +-{amp:.0f} V, "
                 f"617 Hz", rng)
    rec.extra.update(core, s0=s0, n_off=n_off, knots=kn, x=x, drive=v)
    return rec


# ---- two effects ----

@case
def pair_creep_saturation_bond_line_gauge_range_theatre_flyman_337hz(seed):
    """A flexible epoxy bond line creeping under the stack ("creep") and the gauge's converter clipping ("output
    saturation") under a theatre flyman's batten, from the rest state at 0 V (the bond line long at rest under the
    preload); nothing else is run before it."""
    rng = _rng(seed, 9)
    dt = 1 / 337
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s51.theatre_flyman(r, int(r.integers(7, 10))))
    core = dict(_stack(rng), amp=amp)
    k_L, J1, t0 = rng.uniform(1.5, 2.5), rng.uniform(0.022, 0.03), rng.uniform(0.05, 0.1)
    h = _reading(core, v)
    ext = h / m51.LEVER
    d = m51.hereditary(k_L * ext, m51.log_creep_kernel(len(t), dt, J1, t0))
    yc = h - m51.LEVER * d
    f_hi, f_lo = rng.uniform(0.55, 0.7), rng.uniform(0.55, 0.7)
    c_hi, c_lo = f_hi * h.max(), -f_lo * h.min()
    y = np.clip(yc, -c_lo, c_hi)
    rec = finish("holdout51_pair_creep_saturation_bond_line_gauge_range_theatre_flyman_337hz", seed, t, v, y,
                 {"creep", "output_saturation"}, "either",
                 f"a flexible epoxy bond line creeping under the stack ({J1 * 1e3:.1f} nm/N a decade, k_L "
                 f"{k_L:.1f} N/um) and the gauge's converter clipping at +{c_hi:.1f} / -{c_lo:.1f} um under a theatre "
                 f"flyman's batten, +-{amp:.0f} V, 337 Hz", rng)
    # the converter clips the gauge's noisy signal: the noise drawn by finish (its sigma 0.2 % of the clipped reading's
    # span), added to the creeping stroke, then clipped
    rec.y = np.clip(yc + (rec.y - y), -c_lo, c_hi)
    rec.extra.update(core, knots=kn, x=x, k_L=k_L, J1=J1, t0=t0, d=d, c_hi=c_hi, c_lo=c_lo, h=h, y_creep=yc,
                     drive=v)
    return rec


# ---- out of vocabulary ----

@case
def oov_bias_fuse_butterfly_petanque_1129hz(seed):
    """The bias supply's fuse blown under a petanque player's throws, from the rest state at 0 V (the dither ran about
    0 V); nothing else is run before it."""
    rng = _rng(seed, 10)
    dt = 1 / 1129
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s51.petanque(r, 1))
    core = dict(_stack(rng), amp=amp)
    y = _reading(dict(core, bias=0.0), v)
    rec = finish("holdout51_oov_bias_fuse_butterfly_petanque_1129hz", seed, t, v, y, set(), "unexplained",
                 f"the bias supply's fuse blown (the field through zero: a butterfly) under a petanque player's "
                 f"throws, +-{amp:.0f} V, 1.129 kHz", rng)
    rec.extra.update(core, knots=kn, x=x, drive=v)
    return rec

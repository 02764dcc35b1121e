"""The HOLDOUT53 set: written after HOLDOUT52 was measured, by a session that did not read how the diagnosis decides,
and run once for round 55's measurement (17 of 30 runs right on commit 464057e); part of ALL since.

Mechanisms and signals that the other sets do not have (the laws are in :mod:`.mechanisms53`, the signals in
:mod:`.signals53`, each beside its source; the citations were written from memory, as they say). Every core is a
metal-hydride actuator: 2 g of an activated AB5 hydride powder (a blend of LaNi(5-y)Al(y), y 0 ... 0.5) in a cup closed
by a steel diaphragm, its hydrogen pumped in and out through a proton-exchange membrane by an electrochemical hydrogen
pump whose potentiostat follows the drive (1e-4 of it: at equilibrium Nernst's ln(p / p_b) = 2 F E / (R T), 0.0078 a
volt of the drive about the bias p_b, the median of the particles' plateaus; on the unipolar records the bias lies at 47
V of drive), its diaphragm's centre read by a capacitive gauge (um, zeroed at the start of every record). Every particle
is a relay of the pressure (Everett's independent domains): it hydrides at its absorption plateau and gives its hydrogen
back at its desorption plateau, ln(p_a / p_d) = w log-normal about 0.24 ... 0.30 (the work of accommodating the
hydride's swelling), the plateaus' middles log-normal about 1.7 ... 2.1 bar with a ln-spread of 0.5 ... 0.55 (the
blend); 6000 classes; the alpha phase's hydrogen by Sieverts' law and the hydride's on its sloping branch; the lattice's
swelling (2.9 A^3 a hydrogen atom) and the gas's pressure bow the diaphragm. Rate independent, with return-point memory;
close to a Prandtl-Ishlinskii model but not one (measured in tests/test_realistic_holdout53.py: a PI model of 12 plays
of the drive fitted by NNLS, stated there). The stroke is about 12 ... 17 um over +-46 V (about 20 um over the unipolar
strokes). Every record but the initial-state case's starts at 0 V of drive from the rest state the controller's
conditioning routine leaves there (a slowly decaying pressure cycling about that pressure: every particle hydrided whose
loop's middle lies below it, the others alpha; the state is set so, not run), for unipolar and bipolar records alike;
nothing else is run before a record.

- a clean core under a kayaker's paddle (alternating strokes, a sweep turn, the glide), +-44 ... 48 V, with a noisy
  input monitor, sampled at 1.381 kHz;
- creep of a fluoroelastomer pad between the diaphragm and the output rod on its return spring (a generalised Maxwell
  solid of two arms, 1.5 ... 3 s and 15 ... 30 s, stepped exactly); under a barista's tamper, on a unipolar stroke,
  sampled at 251 Hz;
- rate dependence from a coarse, once-activated powder whose particles transform at a finite rate (first order, tau
  50 ... 90 ms); under a conductor's baton (never still), +-44 ... 48 V, with a noisy input monitor, sampled at 1.697
  kHz;
- a drift from a microscope's illuminator switched on before the record: the bench plate and the gauge's aluminium
  bracket warming (two first-order lags in cascade, 1.5 ... 2.5 K, tau 60 ... 120 s and 30 ... 60 s); under a
  weightlifter's sets of presses, on a unipolar stroke, sampled at 229 Hz;
- asymmetry from a thin diaphragm's membrane stiffening (Timoshenko's large-deflection law of a clamped plate, the
  diaphragm 11 ... 14 um thick pressed out 10 ... 13 um at rest); under a see-saw, +-44 ... 48 V, sampled at 907 Hz;
- saturation from the diaphragm meeting a stop plate (a steel shim, 25 ... 40 times stiffer than the diaphragm and the
  bed, at 0.55 ... 0.7 of the rise); under a windscreen wiper, +-44 ... 48 V, with a noisy input monitor, sampled at
  1.013 kHz;
- a delay of a video extensometer (its exposure of 2 ... 5 ms, 50 ... 80 ms before it is read); under a sewing
  machine's foot pedal, on a unipolar stroke, with a noisy input monitor, sampled at 521 Hz;
- a cell in another state at the start: a weekend open to a full hydrogen bottle (every particle hydrided) and a
  straight pump-down to the bias without the conditioning; under a short-wave listener's tuning dial (a search by
  small turns first, then the stations), +-44 ... 48 V, sampled at 677 Hz;
- two effects: a fresh, loosely packed bed creeping at its grains' contacts (logarithmically in time, c ln(1 + t /
  tau_c); labelled "creep") and the potentiostat's output limit set at 0.55 ... 0.7 of the drive's positive swing (the
  pressure capped; labelled "saturation"); under a fencer's lunges, +-44 ... 48 V, sampled at 773 Hz;
- out of vocabulary: the rotary-vane pump on the bench left running, its rotor's imbalance (23.8 ... 24.6 Hz) and its
  vanes' passing (twice that) shaking the gauge against the cell; under a dinghy sailor's tiller, +-44 ... 48 V,
  sampled at 1.129 kHz.

Every bipolar drive is drawn until its weaker side reaches 0.85 of its stronger (a test programme's balance). The
effects' sizes beyond a gain and an offset on the core (seeds 0 ... 2; RMS and largest) are stated in the test.
"""

import math

import numpy as np

from . import mechanisms53 as m53
from . import signals53 as s53
from . import set_tools
from .record import case_set, finish
from .set_tools import fine as _fine, scale as _scale

HOLDOUT53, case, _rng = case_set("holdout53_", 53000)


def _cell(rng, unipolar=False):
    """The core: the particles' seed (the R2 sequence's shift), the blend's median plateau p0 (bar), the plateaus'
    ln-spread se and the particles' median hysteresis w0 (in ln p); the bias pb follows from them."""
    core = dict(rseed=int(rng.integers(0, 2**31 - 2)), p0=rng.uniform(1.7, 2.1), se=rng.uniform(0.5, 0.55),
                w0=rng.uniform(0.24, 0.30), unipolar=unipolar)
    core["pb"] = m53.bias(core)
    return core


def _knotted(rng, dt, gen):
    """A balanced bipolar drive from a knot programme gen(rng) -> (knots, T_end)."""
    return set_tools.knotted(rng, dt, gen, s53.knots_at)


def _unipolar(rng, dt, gen):
    return set_tools.unipolar(rng, dt, gen, s53.knots_at)


def _bipolar(rng, dt, gen):
    return set_tools.bipolar(rng, dt, gen, s53.knots_at)


def _note(core):
    return (f"an AB5 hydride cell's 6000 particle classes (plateaus {core['p0']:.2f} bar, ln-spread {core['se']:.2f}, "
            f"hysteresis {core['w0']:.2f}; biased at {core['pb']:.2f} bar)")


# ---- clean ----

@case
def clean_hydride_cell_kayak_paddle_1381hz(seed):
    """A clean core under a kayaker's paddle, from the rest state at 0 V; nothing else is run before it."""
    rng = _rng(seed, 1)
    dt = 1 / 1381
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s53.kayak_paddle(r, 2))
    core = dict(_cell(rng), amp=amp)
    y = m53.core_reading(core, v)
    rec = finish("holdout53_clean_hydride_cell_kayak_paddle_1381hz", seed, t, v, y, set(), "explained",
                 f"a clean core ({_note(core)}) under a kayaker's paddle ({len(kn)} knots), +-{amp:.0f} V, 1.381 kHz",
                 rng, monitor_noise=2.5e-4)
    rec.extra.update(core, knots=kn, x=x, drive=v)
    return rec


# ---- one effect ----

@case
def creep_elastomer_pad_maxwell_barista_tamp_251hz(seed):
    """A fluoroelastomer pad creeping between the diaphragm and the output rod under a barista's tamper (unipolar), from
    the rest state at 0 V (the pad long relaxed); nothing else is run before it."""
    rng = _rng(seed, 2)
    dt = 1 / 251
    t, kn, p, top, v = _unipolar(rng, dt, lambda r: s53.barista_tamp(r, 4))
    core = dict(_cell(rng, unipolar=True), top=top)
    e_inf = rng.uniform(1.2, 1.8)
    arms = [(rng.uniform(1.0, 1.4), rng.uniform(1.5, 3.0)), (rng.uniform(0.8, 1.2), rng.uniform(15.0, 30.0))]
    d = m53.core_reading(core, v)
    y = m53.pad_rod(d, dt, e_inf, arms)
    rec = finish("holdout53_creep_elastomer_pad_maxwell_barista_tamp_251hz", seed, t, v, y, {"creep"}, "either",
                 f"a fluoroelastomer pad creeping under the rod's return spring (E_inf {e_inf:.2f}, arms "
                 f"{arms[0][0]:.2f} / {arms[0][1]:.1f} s and {arms[1][0]:.2f} / {arms[1][1]:.0f} s) under a barista's "
                 f"tamper, to {top:.0f} V, 251 Hz", rng)
    rec.extra.update(core, knots=kn, p=p, e_inf=e_inf, arms=arms, d=d, drive=v)
    return rec


@case
def rate_coarse_powder_transformation_conductor_baton_1697hz(seed):
    """A coarse powder's particles transforming at a finite rate under a conductor's baton, from the rest state at 0 V
    (the particles long settled); nothing else is run before it."""
    rng = _rng(seed, 3)
    dt = 1 / 1697
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s53.conductor_baton(r, 2))
    core = dict(_cell(rng), amp=amp)
    tau = rng.uniform(0.05, 0.09)
    p = m53.pressure(core, v)
    sums = m53.phases(core, p)
    y = m53.transformed_reading(p, sums, dt, tau)
    rec = finish("holdout53_rate_coarse_powder_transformation_conductor_baton_1697hz", seed, t, v, y,
                 {"rate_dependence"}, "either",
                 f"a coarse powder transforming at a finite rate (tau {tau * 1e3:.0f} ms) under a conductor's baton, "
                 f"+-{amp:.0f} V, 1.697 kHz", rng, monitor_noise=2e-4)
    rec.extra.update(core, knots=kn, x=x, tau=tau, F=sums[0], drive=v)
    return rec


@case
def drift_illuminator_bracket_warming_weightlifter_229hz(seed):
    """A microscope's illuminator warming the bench and the gauge's bracket under a weightlifter's sets (unipolar), from
    the rest state at 0 V; nothing else is run before it."""
    rng = _rng(seed, 4)
    dt = 1 / 229
    t, kn, p, top, v = _unipolar(rng, dt, lambda r: s53.weightlifter_sets(r, 3))
    core = dict(_cell(rng, unipolar=True), top=top)
    t_on, dT_inf = rng.uniform(10.0, 40.0), rng.uniform(1.5, 2.5)
    tau_p, tau_b, L_mm = rng.uniform(60.0, 120.0), rng.uniform(30.0, 60.0), rng.uniform(50.0, 70.0)
    h = m53.core_reading(core, v)
    drift = m53.bracket_drift(t, t_on, dT_inf, tau_p, tau_b, L_mm)
    y = h + drift
    rec = finish("holdout53_drift_illuminator_bracket_warming_weightlifter_229hz", seed, t, v, y, {"drift"}, "either",
                 f"a microscope's illuminator switched on {t_on:.0f} s before (the bench toward +{dT_inf:.1f} K, tau "
                 f"{tau_p:.0f} s; the bracket's {L_mm:.0f} mm, tau {tau_b:.0f} s) under a weightlifter's sets, to "
                 f"{top:.0f} V, 229 Hz", rng)
    rec.extra.update(core, knots=kn, p=p, t_on=t_on, dT_inf=dT_inf, tau_p=tau_p, tau_b=tau_b, L_mm=L_mm, h=h,
                     drive=v)
    return rec


@case
def asymmetry_thin_diaphragm_stiffening_see_saw_907hz(seed):
    """A thin diaphragm stiffening as it bows out under a see-saw, from the rest state at 0 V; nothing else is run
    before it."""
    rng = _rng(seed, 5)
    dt = 1 / 907
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s53.see_saw(r, 2))
    core = dict(_cell(rng), amp=amp)
    hd, w_rest, share = rng.uniform(11.0, 14.0), rng.uniform(10.0, 13.0), rng.uniform(0.5, 0.7)
    beta = 0.488 * share
    h = m53.core_reading(core, v)
    w = m53.stiffened(w_rest + h, beta, hd)
    y = w - w[0]
    rec = finish("holdout53_asymmetry_thin_diaphragm_stiffening_see_saw_907hz", seed, t, v, y, {"asymmetry"},
                 "either",
                 f"a thin diaphragm ({hd:.0f} um, pressed out {w_rest:.0f} um at rest, its share of the stiffness "
                 f"{share:.2f}) stiffening under a see-saw, +-{amp:.0f} V, 907 Hz", rng)
    rec.extra.update(core, knots=kn, x=x, hd=hd, w_rest=w_rest, share=share, beta=beta, h=h, drive=v)
    return rec


@case
def saturation_diaphragm_stop_shim_windscreen_wiper_1013hz(seed):
    """The diaphragm meeting a stop plate under a windscreen wiper, from the rest state at 0 V; nothing else is run
    before it."""
    rng = _rng(seed, 6)
    dt = 1 / 1013
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s53.windscreen_wiper(r, 1))
    core = dict(_cell(rng), amp=amp)
    frac, kappa = rng.uniform(0.55, 0.7), rng.uniform(25.0, 40.0)
    h = m53.core_reading(core, v)
    w_s = frac * h.max()
    y = m53.on_stop(h, w_s, kappa)
    rec = finish("holdout53_saturation_diaphragm_stop_shim_windscreen_wiper_1013hz", seed, t, v, y, {"saturation"},
                 "either",
                 f"the diaphragm on a stop plate {w_s:.1f} um up ({frac:.0%} of the rise, {kappa:.0f} times stiffer) "
                 f"under a windscreen wiper, +-{amp:.0f} V, 1.013 kHz", rng, monitor_noise=3e-4)
    rec.extra.update(core, knots=kn, x=x, frac=frac, kappa=kappa, w_s=w_s, h=h, drive=v)
    return rec


@case
def delay_video_extensometer_sewing_pedal_521hz(seed):
    """A video extensometer's exposure and latency under a sewing machine's foot pedal (unipolar), from the rest state
    at 0 V; nothing else is run before it."""
    rng = _rng(seed, 7)
    dt = 1 / 521
    t, kn, p, top, v = _unipolar(rng, dt, lambda r: s53.sewing_pedal(r, 3))
    core = dict(_cell(rng, unipolar=True), top=top)
    L, E = rng.uniform(0.05, 0.08), rng.uniform(0.002, 0.005)
    tf = _fine(t, m53.SUB_VIDEO)
    wf = m53.core_reading(core, top * s53.knots_at(tf, kn) / p.max())
    y = m53.exposure_late(tf, wf, t, L, E)
    rec = finish("holdout53_delay_video_extensometer_sewing_pedal_521hz", seed, t, v, y, {"delay"}, "either",
                 f"a video extensometer ({E * 1e3:.1f} ms exposures read {L * 1e3:.0f} ms late) under a sewing "
                 f"machine's foot pedal, to {top:.0f} V, 521 Hz", rng, monitor_noise=2e-4)
    rec.extra.update(core, knots=kn, p=p, L=L, E=E, drive=v)
    return rec


@case
def initial_state_weekend_full_bottle_tuning_dial_677hz(seed):
    """A weekend open to a full hydrogen bottle and a straight pump-down to the bias, without the conditioning, under a
    short-wave listener's tuning dial (a search by small turns first)."""
    rng = _rng(seed, 8)
    dt = 1 / 677
    amp = rng.uniform(44.0, 48.0)
    core = dict(_cell(rng), amp=amp)
    s = m53.weekend_state(core)
    x, t, kn = _knotted(rng, dt, lambda r: s53.tuning_dial(r, 5))
    v = _scale(x, amp)
    s0 = s.copy()
    y = m53.core_reading(core, v, s)
    n_off = int(np.sum(s0 != m53.rest_state(core, core["pb"])))
    rec = finish("holdout53_initial_state_weekend_full_bottle_tuning_dial_677hz", seed, t, v, y, {"initial_state"},
                 "either",
                 f"a weekend open to a full bottle and a straight pump-down ({n_off} of {m53.N_PART} particle classes "
                 f"hydrided that the conditioning leaves alpha) under a tuning dial, +-{amp:.0f} V, 677 Hz", rng)
    rec.extra.update(core, s0=s0, n_off=n_off, knots=kn, x=x, drive=v)
    return rec


# ---- two effects ----

@case
def pair_creep_saturation_bed_log_creep_potentiostat_limit_fencer_773hz(seed):
    """A loosely packed bed creeping logarithmically ("creep") and the potentiostat's output limit ("saturation") under
    a fencer's lunges, from the rest state at 0 V; nothing else is run before it."""
    rng = _rng(seed, 9)
    dt = 1 / 773
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s53.fencer_bout(r, 5))
    core = dict(_cell(rng), amp=amp)
    c, tau_c, frac = rng.uniform(0.04, 0.055), rng.uniform(0.02, 0.08), rng.uniform(0.55, 0.7)
    v_max = frac * v.max()
    v_lim = np.minimum(v, v_max)
    w = m53.core_reading(core, v_lim)
    y = w - m53.hereditary(w, m53.log_kernel(len(t), dt, c, tau_c))
    rec = finish("holdout53_pair_creep_saturation_bed_log_creep_potentiostat_limit_fencer_773hz", seed, t, v, y,
                 {"creep", "saturation"}, "either",
                 f"a loosely packed bed creeping (c {c:.3f}, tau_c {tau_c * 1e3:.0f} ms) and the potentiostat limited "
                 f"at {v_max:.1f} V of drive ({frac:.0%}) under a fencer's lunges, +-{amp:.0f} V, 773 Hz", rng)
    rec.extra.update(core, knots=kn, x=x, c=c, tau_c=tau_c, frac=frac, v_max=v_max, w=w, drive=v)
    return rec


# ---- out of vocabulary ----

@case
def oov_roughing_pump_vibration_sailor_tiller_1129hz(seed):
    """A rotary-vane pump on the bench shaking the gauge under a dinghy sailor's tiller, from the rest state at 0 V;
    nothing else is run before it."""
    rng = _rng(seed, 10)
    dt = 1 / 1129
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s53.sailor_tiller(r, 1))
    core = dict(_cell(rng), amp=amp)
    f, a1, a2 = rng.uniform(23.8, 24.6), rng.uniform(0.35, 0.5), rng.uniform(0.15, 0.25)
    ph1, ph2 = rng.uniform(0.0, 2 * math.pi), rng.uniform(0.0, 2 * math.pi)
    h = m53.core_reading(core, v)
    y = h + m53.pump_vibration(t, f, a1, a2, ph1, ph2)
    rec = finish("holdout53_oov_roughing_pump_vibration_sailor_tiller_1129hz", seed, t, v, y, set(), "unexplained",
                 f"a rotary-vane pump on the bench ({f:.1f} Hz: {a1:.2f} um, {a2:.2f} um at twice that) under a "
                 f"dinghy sailor's tiller, +-{amp:.0f} V, 1.129 kHz", rng)
    rec.extra.update(core, knots=kn, x=x, f=f, a1=a1, a2=a2, ph1=ph1, ph2=ph2, h=h, drive=v)
    return rec

"""The HOLDOUT48 set: written after HOLDOUT47 was measured, by a session that did not read how the diagnosis decides,
and run once for round 50's measurement (24 of 30 runs right on commit 92e115f); part of ALL since.

Mechanisms and signals that the other sets do not have (the laws are in :mod:`.mechanisms48`, the signals in
:mod:`.signals48`, each beside its source; the citations were written from memory, as they say). Every core is a
magnetic shape-memory (MSM) actuator: a Ni-Mn-Ga single crystal in its 10M martensite (eps_0 = 1 - c/a 0.056 ...
0.062, K_u 1.6 ... 1.9e5 J/m^3, J_s 0.58 ... 0.64 T), 15 ... 20 mm long, trained to two twin variants, bonded between
the frame and a push rod held at its mid-stroke by a pair of centring springs (kappa 1.3 ... 1.6 MPa per unit of the
second variant's share xi); two coils, one across the element (lengthening it) and one along it (shortening it), fed by
a current amplifier through steering diodes (coil Y for a positive drive, coil X for a negative one; coil Y alone on the
unipolar records), their field up to q = 0.08 ... 0.10 of the anisotropy field at the full drive (tens of mT). The
field's magnetic stress on the twin boundaries, J_s h (1 - h / 2 H_a) / eps_0 (O'Handley's and Likhachev & Ullakko's
energy difference of the two variants), works against the boundaries' friction: 1000 regions in series, each swept by
its boundary when the stress on it passes its threshold, b_i + tau_i up or b_i - tau_i down (twinning stresses tau_i
log-normal about 0.08 ... 0.12 MPa, the type II twins' low ones; internal stresses b_i normal, spread 0.06 ... 0.10
MPa; a Latin hypercube), the springs' push back shearing the ensemble (a region held part-swept at its threshold). Rate
independent, with return-point memory; close to a Prandtl-Ishlinskii model but not one (measured in
tests/test_realistic_holdout48.py: a PI model of 12 plays of the drive fitted by NNLS, stated there). The reading is a
laser Doppler vibrometer's displacement decoder on the push rod's end (um), zeroed at each record's first sample. Every
record but the initial-state case's starts at 0 V and 0 A from the element as the controller's centring routine leaves
it at power-down (the Preisach demagnetised state about the springs' middle; the state is set so, not run), for
unipolar and bipolar records alike. No settling routine is run and nothing else is run before a record.

- a clean core under a helmsman's wheel (orders put over, held, met and brought to midships), +-44 ... 48 V, with a
  noisy input monitor, sampled at 1.291 kHz;
- creep from the centring springs made as polyurethane bushes, their stress relaxing (a Prony series of 0.5, 5 and 50
  s, 20 ... 30 % of their stiffness in all), so that after a move the region at its threshold goes on switching; under
  a fitter's bench vice (pulled tight in steps, held while filing), on a unipolar stroke, sampled at 277 Hz;
- rate dependence from the twin boundaries' finite mobility (each region swept at a speed rising with the stress
  above its threshold: 10 ... 30 ms at 0.1 MPa over it); under a sprinter's arms (never still: no holds), +-44 ... 48 V,
  with a noisy input monitor, sampled at 1.613 kHz;
- a drift from the coil's Joule heat warming the actuator from cold (tau 60 ... 120 s; about 10 ... 12 K by the end):
  the alloy's magnetisation and anisotropy falling (the gain down 5 ... 7 %) and the housing's and the element's
  expansion moving the reading's zero (-1.4 ... -2.2 um per kelvin); under a tram driver's master controller (notched
  up and held, coasting, stops), on a unipolar stroke, sampled at 347 Hz;
- asymmetry from the centring spring on the lengthening side replaced by one 1.8 ... 2.5 times as stiff; under a tango
  dancer's weight (steps, ochos and poses), +-44 ... 48 V, sampled at 1.093 kHz;
- saturation from the push rod's end stops set inside the element's travel (at 0.6 ... 0.75 of the free excursion on
  either side: the element blocked there, its regions not switching); under a model ship rolling in a wave tank (wave
  groups and lulls, never still: no holds), +-44 ... 48 V, with a noisy input monitor, sampled at 911 Hz;
- a delay of the vibrometer's digital decoder (a linear-phase FIR of 81 ... 121 taps at 10.24 kHz and an output latency
  of 1 ... 2 ms: 2.1 ... 3.4 samples on average in these records); under a riveter's pneumatic hammer (bursts of the
  trigger, feathered), on a unipolar stroke, with a noisy input monitor, sampled at 433 Hz;
- an element in another state at the start: a replacement fitted as its supplier reset it (every region in the short
  variant), without the centring routine, the springs pulling it up to rest below the middle; under an astronomer's
  hand paddle (guiding corrections first, then slews), +-44 ... 48 V, sampled at 857 Hz;
- two effects: an oil dashpot on the push rod (45 ... 70 ms against the springs; labelled "rate_dependence") and the
  amplifier's gain set 1.8 ... 2.2 times its rating, the field's stress bending and the element running out of regions
  to switch at the swing's ends (the strain's limit; labelled "saturation"); under a karateka's kata (strikes, blocks
  and stances), +-44 ... 48 V, sampled at 661 Hz;
- out of vocabulary: the vibrometer left on its velocity decoder (the reading the push rod's speed, averaged over 1 ...
  2 ms: zero in every hold), which no map of the core draws; under a railway handcar's see-saw lever, +-44 ... 48 V,
  sampled at 1.171 kHz. The record does not carry the decoder: nothing of it is in the drive.

Every bipolar drive is drawn until its weaker side reaches 0.85 of its stronger (a test programme's balance). The
effects' sizes beyond a gain and an offset on the core (seeds 0 ... 2; RMS and largest) are stated in the test.
"""

import numpy as np

from . import mechanisms48 as m48
from . import signals48 as s48
from . import set_tools
from .record import case_set, finish
from .set_tools import fine as _fine, scale as _scale

HOLDOUT48, case, _rng = case_set("holdout48_", 48000)


def _msm(rng, unipolar=False):
    """The core: the element's regions (their lattice seed, the twinning stresses' median and spread and the internal
    stresses' spread, MPa), the alloy (eps_0 = 1 - c/a, K_u in J/m^3, J_s in T, its Curie point in K), the full drive's
    field over the anisotropy field, the centring springs' kappa (MPa per unit xi) and the element's length (mm)."""
    return dict(rseed=int(rng.integers(0, 2**31 - 2)), tau_m=rng.uniform(0.08, 0.12), s_tau=rng.uniform(0.15, 0.3),
                s_b=rng.uniform(0.06, 0.10), eps0=rng.uniform(0.056, 0.062), K=rng.uniform(1.6e5, 1.9e5),
                Js=rng.uniform(0.58, 0.64), Tc=rng.uniform(365.0, 375.0), q=rng.uniform(0.08, 0.10),
                kappa=rng.uniform(1.3, 1.6), L0=rng.uniform(15.0, 20.0), unipolar=unipolar)


def _reading(core, v, element=None, gain=1.0):
    """The vibrometer's reading (um) of the rate-independent actuator for the drive v, from the element (default
    demagnetised)."""
    return m48.core_reading(core, v, element, gain)


def _knotted(rng, dt, gen):
    """A balanced bipolar drive from a knot programme gen(rng) -> (knots, T_end)."""
    return set_tools.knotted(rng, dt, gen, s48.knots_at)


def _unipolar(rng, dt, gen):
    return set_tools.unipolar(rng, dt, gen, s48.knots_at)


def _bipolar(rng, dt, gen):
    return set_tools.bipolar(rng, dt, gen, s48.knots_at)


# ---- clean ----

@case
def clean_msm_element_helmsman_wheel_1291hz(seed):
    """A clean core under a helmsman's wheel, from the centred element at 0 V; nothing else is run before it."""
    rng = _rng(seed, 1)
    dt = 1 / 1291
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s48.helmsman(r, 2))
    core = dict(_msm(rng), amp=amp)
    y = _reading(core, v)
    rec = finish("holdout48_clean_msm_element_helmsman_wheel_1291hz", seed, t, v, y, set(), "explained",
                 f"a clean core (a Ni-Mn-Ga element, twinning stress {core['tau_m']:.2f} MPa, centring springs "
                 f"{core['kappa']:.2f} MPa per unit share, field up to {core['q']:.3f} H_a) under a helmsman's wheel "
                 f"({len(kn)} knots), +-{amp:.0f} V, 1.291 kHz", rng, monitor_noise=3e-4)
    rec.extra.update(core, knots=kn, x=x, drive=v)
    return rec


# ---- one effect ----

@case
def creep_elastomer_centring_springs_bench_vice_277hz(seed):
    """The centring springs' elastomer relaxing under a fitter's bench vice (unipolar), from the centred element at 0
    V; nothing else is run before it."""
    rng = _rng(seed, 2)
    dt = 1 / 277
    t, kn, p, top, v = _unipolar(rng, dt, lambda r: s48.bench_vice(r, int(r.integers(3, 5))))
    core = dict(_msm(rng, unipolar=True), top=top)
    c_tot = rng.uniform(0.2, 0.3)
    share = rng.dirichlet([3.0, 3.0, 3.0])
    kj = core["kappa"] * c_tot * share
    k_inf = core["kappa"] * (1.0 - c_tot)
    F_inf = m48.springs(dict(core, kappa=k_inf))
    el = m48.Element(core, F=F_inf)
    x0 = el.st[0]
    xs = el.run(m48.drive_stress(core, v), kj=kj, tj=m48.CREEP_TAUS, dt=dt)
    y = m48.travel(core, xs, x0)
    rec = finish("holdout48_creep_elastomer_centring_springs_bench_vice_277hz", seed, t, v, y, {"creep"}, "either",
                 f"the centring springs' elastomer relaxing ({c_tot:.0%} of their stiffness over 0.5 ... 50 s) under a "
                 f"fitter's bench vice, to {top:.0f} V, 277 Hz", rng)
    rec.extra.update(core, knots=kn, p=p, c_tot=c_tot, kj=kj, k_inf=k_inf, xs=xs, x0=x0, drive=v)
    return rec


@case
def rate_twin_boundary_mobility_sprinter_arms_1613hz(seed):
    """The twin boundaries' finite mobility under a sprinter's arms, from the centred element at 0 V; nothing else is
    run before it."""
    rng = _rng(seed, 3)
    dt = 1 / 1613
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s48.sprinter(r, int(r.integers(1, 3))))
    core = dict(_msm(rng), amp=amp)
    eta_m = rng.uniform(1e-3, 3e-3)
    tf = _fine(t, m48.SUB_MOB)
    vf = amp * s48.knots_at(tf, kn) / np.abs(x).max()
    el = m48.Element(core)
    x0 = el.st[0]
    xs = m48.mobile_share(el, m48.drive_stress(core, vf), dt / m48.SUB_MOB, eta_m)[::m48.SUB_MOB]
    y = m48.travel(core, xs, x0)
    rec = finish("holdout48_rate_twin_boundary_mobility_sprinter_arms_1613hz", seed, t, v, y, {"rate_dependence"},
                 "either", f"the twin boundaries' mobility (a region swept in {eta_m / 0.1 * 1e3:.0f} ms at 0.1 MPa "
                 f"over its threshold) under a sprinter's arms, +-{amp:.0f} V, 1.613 kHz", rng, monitor_noise=2.5e-4)
    rec.extra.update(core, knots=kn, x=x, eta_m=eta_m, xs=xs, x0=x0, drive=v)
    return rec


@case
def drift_coil_heating_element_tram_controller_347hz(seed):
    """The element warmed by its coil from cold (its magnetisation and anisotropy falling, its length growing) under a
    tram driver's master controller (unipolar), from the centred element at 0 V; nothing else is run before it."""
    rng = _rng(seed, 4)
    dt = 1 / 347
    t, kn, p, top, v = _unipolar(rng, dt, lambda r: s48.tram_controller(r, 3))
    core = dict(_msm(rng, unipolar=True), top=top)
    dT_full, tau_th = rng.uniform(45.0, 60.0), rng.uniform(60.0, 120.0)
    alpha_e, L_h = rng.uniform(12e-6, 16e-6), rng.uniform(80.0, 110.0)
    T = m48.warm_up(t, dT_full * (v / top) ** 2, tau_th)
    Js, K = m48.warm_constants(core, T)
    el = m48.Element(core)
    x0 = el.st[0]
    xs = el.run(m48.drive_stress(core, v, Js=Js, K=K))
    z = m48.expansion(T, alpha_e, core["L0"], L_h)
    y = m48.travel(core, xs, x0) + z
    rec = finish("holdout48_drift_coil_heating_element_tram_controller_347hz", seed, t, v, y, {"drift"}, "either",
                 f"the element warmed by its coil from cold (tau {tau_th:.0f} s, {T[-1]:.1f} K by the end: J_s "
                 f"{Js[-1] / core['Js'] - 1:+.1%}, K_u {K[-1] / core['K'] - 1:+.1%}, {z[-1]:+.1f} um of expansion) "
                 f"under a tram driver's controller, to {top:.0f} V, 347 Hz", rng)
    rec.extra.update(core, knots=kn, p=p, dT_full=dT_full, tau_th=tau_th, alpha_e=alpha_e, L_h=L_h, T=T, Js_T=Js, K_T=K,
                     xs=xs, x0=x0, z=z, drive=v)
    return rec


@case
def asymmetry_mismatched_centring_springs_tango_1093hz(seed):
    """The spring on the lengthening side stiffer than the other, under a tango dancer's weight, from the centred
    element at 0 V; nothing else is run before it."""
    rng = _rng(seed, 5)
    dt = 1 / 1093
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s48.tango(r, int(r.integers(3, 5))))
    core = dict(_msm(rng), amp=amp)
    ratio = rng.uniform(1.8, 2.5)
    el = m48.Element(core, F=m48.springs(core, ratio))
    x0 = el.st[0]
    xs = el.run(m48.drive_stress(core, v))
    y = m48.travel(core, xs, x0)
    rec = finish("holdout48_asymmetry_mismatched_centring_springs_tango_1093hz", seed, t, v, y, {"asymmetry"},
                 "either", f"the lengthening side's centring spring {ratio:.2f} times the other's under a tango "
                 f"dancer's weight, +-{amp:.0f} V, 1.093 kHz", rng)
    rec.extra.update(core, knots=kn, x=x, ratio=ratio, xs=xs, x0=x0, drive=v)
    return rec


@case
def saturation_end_stops_inside_stroke_ship_rolling_911hz(seed):
    """The push rod's end stops set inside the element's travel, under a model ship rolling in a wave tank, from the
    centred element at 0 V; nothing else is run before it."""
    rng = _rng(seed, 6)
    dt = 1 / 911
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s48.ship_rolling(r, int(r.integers(3, 5))))
    core = dict(_msm(rng), amp=amp)
    free = m48.core_share(core, v)
    xr = m48.Element(core).st[0]
    f_lo, f_hi, Ks = rng.uniform(0.6, 0.75), rng.uniform(0.6, 0.75), rng.uniform(150.0, 250.0) * core["kappa"]
    lo, hi = xr - f_lo * (xr - free.min()), xr + f_hi * (free.max() - xr)
    el = m48.Element(core, F=m48.springs(core, stops=(lo, hi, Ks)))
    x0 = el.st[0]
    xs = el.run(m48.drive_stress(core, v))
    y = m48.travel(core, xs, x0)
    rec = finish("holdout48_saturation_end_stops_inside_stroke_ship_rolling_911hz", seed, t, v, y, {"saturation"},
                 "either", f"end stops set at {f_lo:.2f} and {f_hi:.2f} of the free travel's excursions under a model "
                 f"ship rolling in a wave tank, +-{amp:.0f} V, 911 Hz", rng, monitor_noise=3e-4)
    rec.extra.update(core, knots=kn, x=x, f_lo=f_lo, f_hi=f_hi, Ks=Ks, lo=lo, hi=hi, free=free, xs=xs, x0=x0,
                     drive=v)
    return rec


@case
def delay_vibrometer_decoder_fir_rivet_gun_433hz(seed):
    """The vibrometer's digital decoder (its linear-phase FIR and output latency) under a riveter's hammer (unipolar),
    from the centred element at 0 V; nothing else is run before it."""
    rng = _rng(seed, 7)
    dt = 1 / 433
    t, kn, p, top, v = _unipolar(rng, dt, lambda r: s48.rivet_gun(r, int(r.integers(25, 40))))
    core = dict(_msm(rng, unipolar=True), top=top)
    n_taps = 2 * int(rng.integers(40, 61)) + 1
    f_c, T_lat, phase = rng.uniform(800.0, 1200.0), rng.uniform(0.001, 0.002), rng.uniform(0.0, 1.0 / m48.F_DEC)
    h = m48.decoder_fir(n_taps, f_c)
    t_dec = phase + np.arange(-n_taps, int((t[-1] - phase) * m48.F_DEC) + 1) / m48.F_DEC
    y_dec = _reading(core, top * s48.knots_at(t_dec, kn) / p.max())
    y_out = m48.decoder_output(y_dec, h)
    y = m48.held_reading(t, t_dec, y_out, T_lat, 0.0)
    T_d = (n_taps - 1) / (2 * m48.F_DEC) + T_lat + 0.5 / m48.F_DEC
    rec = finish("holdout48_delay_vibrometer_decoder_fir_rivet_gun_433hz", seed, t, v, y, {"delay"}, "either",
                 f"the vibrometer's decoder ({n_taps} taps at 10.24 kHz, cut off at {f_c:.0f} Hz, latency "
                 f"{T_lat * 1e3:.1f} ms: {T_d / dt:.2f} samples' delay on average) under a riveter's hammer, to "
                 f"{top:.0f} V, 433 Hz", rng, monitor_noise=2e-4)
    rec.extra.update(core, knots=kn, p=p, n_taps=n_taps, f_c=f_c, T_lat=T_lat, phase=phase, h=h, t_dec=t_dec,
                     y_out=y_out, T_d=T_d, D=T_d / dt, drive=v)
    return rec


@case
def initial_state_supplier_reset_element_telescope_paddle_857hz(seed):
    """A replacement element fitted as its supplier reset it (short), without the centring routine, under an
    astronomer's hand paddle (guiding first)."""
    rng = _rng(seed, 8)
    dt = 1 / 857
    amp = rng.uniform(44.0, 48.0)
    core = dict(_msm(rng), amp=amp)
    el = m48.supplier_element(core)
    x, t, kn = _knotted(rng, dt, lambda r: s48.telescope_paddle(r, int(r.integers(4, 7))))
    v = _scale(x, amp)
    y = _reading(core, v, el)
    rec = finish("holdout48_initial_state_supplier_reset_element_telescope_paddle_857hz", seed, t, v, y,
                 {"initial_state"}, "either",
                 f"a replacement element fitted short, as its supplier reset it (resting at a share of "
                 f"{el.st[0]:.3f}, the centred element's {m48.Element(core).st[0]:.3f}), under an astronomer's hand "
                 f"paddle, +-{amp:.0f} V, 857 Hz", rng)
    rec.extra.update(core, xi0=el.xi.copy(), st0=el.st.copy(), knots=kn, x=x, drive=v)
    return rec


# ---- two effects ----

@case
def pair_rate_saturation_oil_dashpot_overdriven_coils_karate_kata_661hz(seed):
    """An oil dashpot on the push rod ("rate_dependence") and the amplifier's gain set too high, the element running
    out of regions ("saturation"), under a karateka's kata, from the centred element at 0 V; nothing else is run
    before it."""
    rng = _rng(seed, 9)
    dt = 1 / 661
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s48.karate_kata(r, int(r.integers(3, 6))))
    core = dict(_msm(rng), amp=amp)
    tau_d, over = rng.uniform(0.045, 0.07), rng.uniform(1.8, 2.2)
    eta_d = tau_d * core["kappa"]
    tf = _fine(t, m48.SUB_DASH)
    vf = amp * s48.knots_at(tf, kn) / np.abs(x).max()
    el = m48.Element(core)
    x0 = el.st[0]
    xs = el.run(m48.drive_stress(core, vf, over), eta=eta_d, dt=dt / m48.SUB_DASH)[::m48.SUB_DASH]
    y = m48.travel(core, xs, x0)
    rec = finish("holdout48_pair_rate_saturation_oil_dashpot_overdriven_coils_karate_kata_661hz", seed, t, v, y,
                 {"rate_dependence", "saturation"}, "either",
                 f"an oil dashpot on the push rod ({tau_d * 1e3:.1f} ms against the springs) and the amplifier's gain "
                 f"{over:.2f} times its rating (the field to {over * core['q']:.2f} H_a) under a karateka's kata, "
                 f"+-{amp:.0f} V, 661 Hz", rng)
    rec.extra.update(core, knots=kn, x=x, tau_d=tau_d, eta_d=eta_d, over=over, xs=xs, x0=x0, drive=v)
    return rec


# ---- out of vocabulary ----

@case
def oov_vibrometer_velocity_decoder_handcar_1171hz(seed):
    """The vibrometer left on its velocity decoder (the reading the push rod's speed) under a railway handcar's lever,
    from the centred element at 0 V; nothing else is run before it."""
    rng = _rng(seed, 10)
    dt = 1 / 1171
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s48.handcar(r, int(r.integers(2, 4))))
    core = dict(_msm(rng), amp=amp)
    T_a = rng.uniform(0.001, 0.002)
    y = m48.velocity_reading(core, t, T_a, lambda u: amp * s48.knots_at(u, kn) / np.abs(x).max())
    rec = finish("holdout48_oov_vibrometer_velocity_decoder_handcar_1171hz", seed, t, v, y, set(), "unexplained",
                 f"the vibrometer left on its velocity decoder (averaged over {T_a * 1e3:.1f} ms) under a railway "
                 f"handcar's lever, +-{amp:.0f} V, 1.171 kHz", rng)
    rec.extra.update(core, knots=kn, x=x, T_a=T_a, drive=v)
    return rec

"""The HOLDOUT46 set: written after HOLDOUT45 was measured, by a session that did not read how the diagnosis decides,
and run once for round 48's measurement (22 of 30 runs right on commit e9bf6a2); part of ALL since.

Mechanisms and signals that the other sets do not have (the laws are in :mod:`.mechanisms46`, the signals in
:mod:`.signals46`, each beside its source; the citations were written from memory, as they say). Every core is a
polypyrrole bilayer bender: a PPy(DBS) film 1.5 ... 3 um thick on the gold-coated face of a polyimide strip (100 ...
130 um, 10 ... 14 mm free) in aqueous NaDBS, its potential set by a potentiostat from the drive (in units of kT/e,
25.69 mV, about the middle E_mid: dE v / amp on the bipolar records, dE 6 ... 7, 154 ... 180 mV; dE_top v / top up from
the middle on the unipolar ones, dE_top 10 ... 12.5), read by a laser triangulation sensor at 0.85 ... 0.95 of the
strip's length (um). The film's charge is a double layer's, c E (c 0.02 ... 0.035 of the faradaic capacity per kT/e),
and its domains' mean oxidation: every domain a lattice gas of redox sites with an attraction between oxidised
neighbours, the Frumkin isotherm E - E_i = ln(theta / (1 - theta)) + g_i (1 - 2 theta) with g_i > 2, so that it is
bistable and switches as a whole at its spinodals, E_i +- Delta(g_i) (Delta = g s - 2 artanh s, s = sqrt(1 - 2 / g)),
moving reversibly along its branches between (Laviron 1974; the many-particle electrode of Dreyer et al. 2010); 600
classes of domains on a golden-ratio lattice over the formal potentials (normal, spread 9.5 ... 12 kT/e about -1 ... 1)
and the interactions (g - 2 log-normal, median 1.8 ... 2.6, the log's spread 0.4 ... 0.5). The strip's curvature
follows the charge (the film's free strain beta (q - q_0), beta 0.8 ... 1.5 %; Stoney's limit of Timoshenko's bimetal
formula), read as the small deflection at the spot: y = Y (q - q_0), a few hundred um per unit charge. Rate
independent, with return-point memory (a Preisach model of the potential); close to a Prandtl-Ishlinskii model but not
one (the switching potentials are spread as a normal distribution, the branches curved). Its closeness to a PI model
is measured in tests/test_realistic_holdout46.py (a PI model of 12 plays of the drive fitted by NNLS, stated there).
Every record but the initial-state case's starts at 0 V from the film as grown: grown at the middle potential, every
domain formed there in its stable state (oxidised where E_i lies below it: the Maxwell rule, which is also the state a
slow AC conditioning would leave, the Preisach demagnetised state); the cell rests at that open-circuit potential and
the potentiostat is switched on there, at 0 V, for unipolar and bipolar records alike. No settling routine is run and
nothing else is run before a record.

- a clean core under a barber stropping a razor, +-44 ... 48 V, with a noisy input monitor, sampled at 1.237 kHz;
- creep from the thermally activated switching of small domains (a thin film grown at a low current density: 20 ... 30
  sites a domain): a domain on a branch that is no longer its stable one crosses the free-energy barrier between the
  isotherm's minima, B = n_s (f(theta_b) - f(theta_a)), at the Arrhenius rate 10 /s e^-B, so that after a move the
  reading goes on the way it went, spread over decades of time; under an organ's swell pedal, on a unipolar stroke,
  sampled at 271 Hz;
- rate dependence from the domains' finite electron-transfer rate (Butler-Volmer kinetics with the Frumkin interaction,
  k0 25 ... 50 /s: the loops widen with the drive's speed, most where the domains switch); under a log roller's feet on
  a floating log (never still: no holds), +-44 ... 48 V, with a noisy input monitor, sampled at 1.583 kHz;
- a drift from the polyimide taking up water through its bare face (Fickian diffusion, the strip put into the
  electrolyte 3 ... 8 min before the record: the uneven swelling's moment bends it, by 12 ... 20 % of the stroke by the
  end); under a bartender's beer tap, on a unipolar stroke, sampled at 397 Hz;
- asymmetry from a film whose modulus follows its oxidation (1.8 ... 2.6 times stiffer oxidised, by the rule of
  mixtures: the curvature per unit strain larger on the oxidised side); under a flag semaphore signaller's arm, +-44 ...
  48 V, sampled at 1.069 kHz;
- saturation of the film overdriven (2.2 ... 2.8 times its rated swing: its domains nearly all oxidised at the top and
  reduced at the bottom, the double layer's charge left); under a roper's lasso (kept spinning: no holds), +-44 ...
  48 V, with a noisy input monitor, sampled at 953 Hz;
- a delay of the laser sensor (its own sampling at 2 ... 5 kHz and its processing latency, 6 ... 10 ms: 4.5 ... 5.8
  samples on average in these records); under a drummer's hi-hat pedal, on a unipolar stroke, with a noisy input
  monitor, sampled at 587 Hz;
- a film in another state at the start: grown 1.15 ... 1.45 times the swing above the middle and stepped down to it at
  the start (the domains that formed oxidised there and whose lower spinodal lies below the middle stay oxidised); under
  a tightrope walker's pole, only tipped at first (three bouts at 1 ... 3 % of the reach), then swung in gusts, +-44 ...
  48 V, sampled at 859 Hz;
- two effects: the clamp's PTFE pad creeping under its screw (a log creep carrying the strip's root, and the whole
  strip, sideways by 10 ... 16 % of the stroke by the end; labelled "drift") and the film overoxidised at the top of its
  swing (its active share falling at a rate exponential in the potential, 25 ... 35 % lost by the end, the reading a(t)
  times the core's; labelled "gain_drift"); under a gondolier's oar, +-44 ... 48 V, sampled at 613 Hz. Both labels are
  of the drift family;
- out of vocabulary: the film run in NaCl instead of NaDBS, taking in Cl- above its as-grown charge, which swells it as
  Na+ does below (mixed ion exchange): the reading is highest at the as-grown charge and falls on both sides, a fold no
  monotone map of the core draws; under a sommelier swirling a glass, +-44 ... 48 V, sampled at 1.151 kHz. The record
  does not carry the exchange: nothing of it is in the drive.

Every bipolar drive is drawn until its weaker side reaches 0.85 of its stronger (a test programme's balance). The
effects' sizes beyond a gain and an offset on the core (seeds 0 ... 2; RMS and largest) are stated in the test.
"""

import math

import numpy as np

from . import mechanisms46 as m46
from . import signals46 as s46
from . import set_tools
from .record import case_set, finish
from .set_tools import scale as _scale

HOLDOUT46, case, _rng = case_set("holdout46_", 46000)


def _film(rng, unipolar=False):
    """The core: the domains' lattice seed, their formal potentials' spread and centre (kT/e), the interactions' median
    and spread, the double layer's share, the bilayer (film and substrate thicknesses, their moduli's ratio, the film's
    strain per unit charge, the strip's free length and the laser's spot: Y, um per unit charge), and the swing: dE
    (bipolar, kT/e) or dE_top (unipolar)."""
    core = dict(dseed=int(rng.integers(0, 2**31)), sig=rng.uniform(9.5, 12.0), mu=rng.uniform(-1.0, 1.0),
                g_med=rng.uniform(1.8, 2.6), g_spread=rng.uniform(0.4, 0.5), c=rng.uniform(0.02, 0.035),
                t_f=rng.uniform(1.5e-6, 3e-6), t_s=rng.uniform(100e-6, 130e-6), n_mod=rng.uniform(0.25, 0.45),
                beta=rng.uniform(0.008, 0.015), L=rng.uniform(0.010, 0.014), unipolar=unipolar)
    core["x_m"] = rng.uniform(0.85, 0.95) * core["L"]
    core["Y"] = m46.bilayer_gain(core["t_f"], core["t_s"], core["n_mod"], core["beta"], core["x_m"])
    if unipolar:
        core["dE_top"] = rng.uniform(10.0, 12.5)
    else:
        core["dE"] = rng.uniform(6.0, 7.0)
    return core


def _core_of(core, v, state=None):
    """The laser's reading of the rate-independent film (from the state; default the rest state)."""
    return m46.core_of(core, v, state=state)


def _knotted(rng, dt, gen):
    """A balanced bipolar drive from a knot programme gen(rng) -> (knots, T_end)."""
    return set_tools.knotted(rng, dt, gen, s46.knots_at)


def _unipolar(rng, dt, gen):
    return set_tools.unipolar(rng, dt, gen, s46.knots_at)


def _bipolar(rng, dt, gen):
    return set_tools.bipolar(rng, dt, gen, s46.knots_at)


def _mv(E):
    return E * m46.KT_E_MV


# ---- clean ----

@case
def clean_ppy_bilayer_barber_strop_1237hz(seed):
    """A clean core under a barber's strop, from the as-grown film at rest at 0 V; nothing else is run before it."""
    rng = _rng(seed, 1)
    dt = 1 / 1237
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s46.barber_strop(r, int(r.integers(2, 5))))
    core = dict(_film(rng), amp=amp)
    off = rng.uniform(-50.0, 50.0)
    y = _core_of(core, v) + off
    rec = finish("holdout46_clean_ppy_bilayer_barber_strop_1237hz", seed, t, v, y, set(), "explained",
                 f"a clean core (a PPy(DBS) bilayer: swing +-{_mv(core['dE']):.0f} mV, formal potentials spread "
                 f"{_mv(core['sig']):.0f} mV) under a barber's strop ({len(kn)} knots), +-{amp:.0f} V, 1.237 kHz", rng,
                 monitor_noise=3e-4)
    rec.extra.update(core, offset=off, knots=kn, x=x, drive=v)
    return rec


# ---- one effect ----

@case
def creep_thermal_nucleation_swell_pedal_271hz(seed):
    """Thermally activated switching of a thin film's small domains under an organ's swell pedal (unipolar), from the
    as-grown film at rest at 0 V; nothing else is run before it."""
    rng = _rng(seed, 2)
    dt = 1 / 271
    t, kn, p, top, v = _unipolar(rng, dt, lambda r: s46.swell_pedal(r, int(r.integers(2, 4))))
    core = dict(_film(rng, unipolar=True), top=top)
    ns = rng.uniform(20.0, 30.0)
    E = m46.potential(core, v)
    y = m46.reading(core, m46.charge(core, E, m46.creep_path(core, E, dt, ns)))
    rec = finish("holdout46_creep_thermal_nucleation_swell_pedal_271hz", seed, t, v, y, {"creep"}, "either",
                 f"the domains' thermally activated switching ({ns:.0f} sites a domain, attempt rate "
                 f"{m46.NU_CREEP:.0f} /s) under an organ's swell pedal, to {top:.0f} V, 271 Hz", rng)
    rec.extra.update(core, knots=kn, p=p, ns=ns, nu=m46.NU_CREEP, drive=v)
    return rec


@case
def rate_electron_transfer_kinetics_log_birling_1583hz(seed):
    """The domains' finite electron-transfer rate under a log roller's feet, from the as-grown film at rest at 0 V;
    nothing else is run before it."""
    rng = _rng(seed, 3)
    dt = 1 / 1583
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s46.log_birling(r, int(r.integers(2, 4))))
    core = dict(_film(rng), amp=amp)
    k0 = rng.uniform(25.0, 50.0)
    E = m46.potential(core, v)
    y = m46.reading(core, m46.charge(core, E, m46.kinetic_path(core, E, dt, k0)))
    rec = finish("holdout46_rate_electron_transfer_kinetics_log_birling_1583hz", seed, t, v, y, {"rate_dependence"},
                 "either", f"the domains' electron-transfer kinetics (k0 {k0:.0f} /s) under a log roller's feet, "
                 f"+-{amp:.0f} V, 1.583 kHz", rng, monitor_noise=2.5e-4)
    rec.extra.update(core, knots=kn, x=x, k0=k0, nsub=m46.RATE_SUB, drive=v)
    return rec


@case
def drift_polyimide_water_uptake_beer_tap_397hz(seed):
    """The strip's polyimide taking up water under a bartender's beer tap (unipolar), from the as-grown film at rest at
    0 V; nothing else is run before it."""
    rng = _rng(seed, 4)
    dt = 1 / 397
    t, kn, p, top, v = _unipolar(rng, dt, lambda r: s46.beer_tap(r, int(r.integers(6, 10))))
    core = dict(_film(rng, unipolar=True), top=top)
    t0, D, share = rng.uniform(180.0, 480.0), rng.uniform(2e-13, 4e-13), rng.uniform(0.12, 0.2)
    h = _core_of(core, v)
    tau = D * (t0 + t) / core["t_s"] ** 2
    M = m46.uptake_moment(tau) - m46.uptake_moment(tau[0])
    A = share * np.ptp(h) / M[-1]
    alpha_w = A * 1e-6 * core["t_s"] / (6.0 * core["x_m"] ** 2)
    y = h - A * M
    rec = finish("holdout46_drift_polyimide_water_uptake_beer_tap_397hz", seed, t, v, y, {"drift"}, "either",
                 f"a drift from the polyimide's water uptake (immersed {t0 / 60:.0f} min before, swelling "
                 f"{alpha_w:.2%} saturated: {share:.0%} of the stroke by the end) under a beer tap, to {top:.0f} V, "
                 f"397 Hz", rng)
    rec.extra.update(core, knots=kn, p=p, t0=t0, D=D, share=share, tau=tau, M=M, A=A, alpha_w=alpha_w, h=h, drive=v)
    return rec


@case
def asymmetry_redox_stiffening_film_semaphore_1069hz(seed):
    """A film whose modulus follows its oxidation under a semaphore signaller's arm, from the as-grown film at rest at 0
    V; nothing else is run before it."""
    rng = _rng(seed, 5)
    dt = 1 / 1069
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s46.semaphore(r, int(r.integers(4, 7))))
    core = dict(_film(rng), amp=amp)
    r_E = rng.uniform(1.8, 2.6)
    E = m46.potential(core, v)
    qF = m46.film_path(core, E)
    q = m46.charge(core, E, qF)
    y = m46.stiffening_reading(core, q, qF, r_E)
    h = m46.reading(core, q)
    rec = finish("holdout46_asymmetry_redox_stiffening_film_semaphore_1069hz", seed, t, v, y, {"asymmetry"}, "either",
                 f"a film {r_E:.2f} times stiffer oxidised than reduced under a semaphore signaller's arm, "
                 f"+-{amp:.0f} V, 1.069 kHz", rng)
    rec.extra.update(core, knots=kn, x=x, r_E=r_E, qF=qF, h_const=h, drive=v)
    return rec


@case
def saturation_redox_capacity_overdriven_lasso_953hz(seed):
    """The film overdriven past its redox capacity under a roper's lasso, from the as-grown film at rest at 0 V; nothing
    else is run before it."""
    rng = _rng(seed, 6)
    dt = 1 / 953
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s46.lasso(r, int(r.integers(3, 6))))
    core = dict(_film(rng), amp=amp)
    over = rng.uniform(2.2, 2.8)
    E = over * m46.potential(core, v)
    y = m46.reading(core, m46.charge(core, E, m46.film_path(core, E)))
    rec = finish("holdout46_saturation_redox_capacity_overdriven_lasso_953hz", seed, t, v, y, {"saturation"},
                 "either", f"the film overdriven ({over:.2f} times its rated swing: +-{_mv(over * core['dE']):.0f} mV) "
                 f"under a roper's lasso, +-{amp:.0f} V, 953 Hz", rng, monitor_noise=3e-4)
    rec.extra.update(core, knots=kn, x=x, over=over, E=E, drive=v)
    return rec


@case
def delay_laser_sensor_latency_hi_hat_587hz(seed):
    """The laser sensor's sampling and latency under a drummer's hi-hat pedal (unipolar), from the as-grown film at rest
    at 0 V; nothing else is run before it."""
    rng = _rng(seed, 7)
    dt = 1 / 587
    t, kn, p, top, v = _unipolar(rng, dt, lambda r: s46.hi_hat(r, int(r.integers(10, 17))))
    core = dict(_film(rng, unipolar=True), top=top)
    f_L = rng.uniform(2000.0, 5000.0)
    phase = rng.uniform(0.0, 1.0 / f_L)
    T_p = rng.uniform(0.006, 0.010)
    s = m46.sensor_instants(t, T_p, f_L, phase)
    seen = np.isfinite(s)
    v_seen = np.where(seen, top * s46.knots_at(np.where(seen, s, 0.0), kn) / p.max(), 0.0)
    y = _core_of(core, v_seen)
    T_d = T_p + 0.5 / f_L
    rec = finish("holdout46_delay_laser_sensor_latency_hi_hat_587hz", seed, t, v, y, {"delay"}, "either",
                 f"the laser sensor's latency ({T_p * 1e3:.1f} ms) and sampling ({f_L / 1e3:.1f} kHz): {T_d / dt:.2f} "
                 f"samples' delay on average, under a drummer's hi-hat, to {top:.0f} V, 587 Hz", rng,
                 monitor_noise=2e-4)
    rec.extra.update(core, knots=kn, p=p, f_L=f_L, phase=phase, T_p=T_p, T_d=T_d, D=T_d / dt, s=s, v_seen=v_seen,
                     drive=v)
    return rec


@case
def initial_state_grown_above_middle_tightrope_859hz(seed):
    """A film grown above the record's middle and stepped down to it at the start, under a tightrope walker's pole (the
    pole only tipped at first)."""
    rng = _rng(seed, 8)
    dt = 1 / 859
    amp = rng.uniform(44.0, 48.0)
    core = dict(_film(rng), amp=amp)
    rho = rng.uniform(1.15, 1.45)
    state = m46.grown_at(core, rho * core["dE"])
    x, t, kn = _knotted(rng, dt, lambda r: s46.tightrope(r, int(r.integers(3, 6))))
    v = _scale(x, amp)
    y = _core_of(core, v, state=state)
    rec = finish("holdout46_initial_state_grown_above_middle_tightrope_859hz", seed, t, v, y, {"initial_state"},
                 "either", f"a film grown {_mv(rho * core['dE']):.0f} mV above the record's middle ({rho:.2f} times "
                 f"the swing) under a tightrope walker's pole, +-{amp:.0f} V, 859 Hz", rng)
    rec.extra.update(core, rho=rho, st0=state[0], z0=state[1], knots=kn, x=x, drive=v)
    return rec


# ---- two effects ----

@case
def pair_drift_gain_drift_clamp_pad_creep_overoxidation_gondolier_613hz(seed):
    """The clamp's PTFE pad creeping (the strip's root carried sideways: "drift") and the film overoxidised at the top
    of its swing (its active share falling: "gain_drift"), under a gondolier's oar, from the as-grown film at rest at
    0 V; nothing else is run before it."""
    rng = _rng(seed, 9)
    dt = 1 / 613
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s46.gondolier(r, int(r.integers(3, 5))))
    core = dict(_film(rng), amp=amp)
    h = _core_of(core, v)
    b_ox, loss = rng.uniform(1.5, 2.5), rng.uniform(0.25, 0.35)
    I = m46.overoxidation_integral(t, m46.potential(core, v), core["dE"], b_ox)
    k_ox = -math.log(1.0 - loss) / I[-1]
    a = np.exp(-k_ox * I)
    t_c, tau_c, share = rng.uniform(20.0, 60.0), rng.uniform(5.0, 20.0), rng.uniform(0.1, 0.16)
    sgn = float(rng.choice([-1.0, 1.0]))
    shape = m46.clamp_creep(t, t_c, tau_c)
    d_c = sgn * share * np.ptp(h) / shape[-1]
    y = a * h + d_c * shape
    rec = finish("holdout46_pair_drift_gain_drift_clamp_pad_creep_overoxidation_gondolier_613hz", seed, t, v, y,
                 {"drift", "gain_drift"}, "either",
                 f"the clamp's pad creeping ({d_c * shape[-1]:+.1f} um by the end, tau {tau_c:.0f} s) and the film "
                 f"overoxidised ({loss:.0%} lost by the end, b {_mv(b_ox):.0f} mV) under a gondolier's oar, "
                 f"+-{amp:.0f} V, 613 Hz", rng)
    rec.extra.update(core, knots=kn, x=x, b_ox=b_ox, loss=loss, I=I, k_ox=k_ox, a=a, t_c=t_c, tau_c=tau_c,
                     share=share, d_c=d_c, h=h, drive=v)
    return rec


# ---- out of vocabulary ----

@case
def oov_mixed_ion_swelling_fold_wine_swirl_1151hz(seed):
    """The film run in NaCl (anions taken in above its as-grown charge) under a sommelier's swirled glass, from the
    as-grown film at rest at 0 V; nothing else is run before it."""
    rng = _rng(seed, 10)
    dt = 1 / 1151
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s46.wine_swirl(r, int(r.integers(2, 5))))
    core = dict(_film(rng), amp=amp)
    r, w = rng.uniform(0.6, 1.1), rng.uniform(0.01, 0.03)
    E = m46.potential(core, v)
    q = m46.charge(core, E, m46.film_path(core, E))
    off = rng.uniform(-50.0, 50.0)
    y = m46.mixed_ion_reading(core, q, r, w) + off
    rec = finish("holdout46_oov_mixed_ion_swelling_fold_wine_swirl_1151hz", seed, t, v, y, set(), "unexplained",
                 f"the film in NaCl: Cl- taken in above its as-grown charge, swelling {r:.2f} times as much as Na+ "
                 f"(rounded over {w:.3f}) under a sommelier's swirled glass, +-{amp:.0f} V, 1.151 kHz", rng)
    rec.extra.update(core, knots=kn, x=x, r=r, w=w, q=q, offset=off, drive=v)
    return rec

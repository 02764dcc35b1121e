"""The HOLDOUT43 set: written after HOLDOUT42 was measured, by a session that did not read how the diagnosis decides,
and run once for round 45's measurement (17 of 30 runs right on commit 7bbed6c); part of ALL since.

Mechanisms and signals that the other sets do not have (the laws are in :mod:`.mechanisms43`, the signals in
:mod:`.signals43`, each beside its source; the citations were written from memory, as they say). Every core is an
electrowetting cell: a water drop of about a microlitre in silicone oil on a fluoropolymer-coated dielectric, driven by
an AC amplifier whose command sets the square of its amplitude, so that the Lippmann term c_L = cos theta_Y + eps V^2 /
(2 gamma d) is linear in the drive (c_mid + dc v / amp; on a unipolar stroke 0 V is the smallest footprint, c_mid -
dc, and the top the largest, c_mid + dc; the middle's angle theta_mid 108 ... 116 deg, dc 0.24 ... 0.3), and a
capacitance meter reads the drop's footprint (C_mid mean(R_m^2), C_mid 25 ... 45 pF). The drop keeps its volume (a
spherical cap: its apparent angle at the mean contact radius is Cardano's root of tau^3 + 3 tau = omega / R^3, tau =
tan(theta / 2)); its contact line is 360 sectors pinned by the coating's defects (contact-angle hysteresis; Joanny & de
Gennes 1984), each pinned while its unbalanced force c_L - cos theta(Rbar) - kappa (R_m - Rbar) stays within its own
strength h_m (log-normal about h0 0.035 ... 0.05, the log's spread 0.45 ... 0.6; the line's elasticity kappa 0.6 ...
1.2) and sliding to the threshold beyond it. Rate independent, with return-point memory (every sector a stop of a
common force monotone in the drive), close to a Prandtl-Ishlinskii model (the sectors are plays with a mean-field
spring: an Iwan model) but not one: the cap's restoring force is nonlinear in the radius, and the reading is the area.
Its closeness to a PI model is measured in tests/test_realistic_holdout43.py (a PI model of 12 plays of the drive
fitted by NNLS, stated there). Every record but the initial-state case's starts at 0 V from the virgin drop (deposited
at the command's middle and settled by the rig's routine: the command cycled about the middle with amplitudes falling
to nothing; then taken to the record's first command); nothing else is run before it.

- a clean core under a window cleaner's squeegee (scrubbing, then long strokes from edge to edge), +-44 ... 48 V, with
  a noisy input monitor, sampled at 1.63 kHz;
- creep from the contact line's thermally activated creep below its threshold (the molecular-kinetic rate law dR/dt
  = 2 W_m sinh(f / F), W_m = w0 exp(-h_m / F): h0 / F 5 ... 8, the creep's time at the threshold F / (kappa w0) 0.05
  ... 0.2 s: a logarithmic creep in the direction of the last move); under a toaster's lever, on a unipolar stroke,
  sampled at 253 Hz;
- rate dependence from the contact line's friction (zeta dR/dt = gamma (f - h sign f) beyond the threshold; tau_c =
  zeta / (gamma kappa) 6 ... 14 ms); under a wet dog shaking itself dry, +-44 ... 48 V, with a noisy input monitor,
  sampled at 1.495 kHz;
- a drift from the drop dissolving into the oil (not pre-saturated with water: Picknett and Bexon's diffusion-limited
  loss, proportional to R (0.27 theta^2 + 1.30), about 6 ... 10 % of the volume by the end), the footprint shrinking at
  a given command; under a bathtub filled, used and drained, on a unipolar stroke, sampled at 362 Hz;
- asymmetry of a relaxation oscillator reading the capacitance (its frequency follows 1 / (C_p + C), scaled by a line
  fitted at the middle: the ends' secants 12 ... 18 % apart, on a drawn side); under a badminton rally, +-44 ... 48 V,
  with a noisy input monitor, sampled at 1.205 kHz;
- saturation of the lock-in's synchronous detector (a Gilbert cell's differential pair: tanh, the ends compressed by
  10 ... 17 %); under a cradle rocked to sleep, +-44 ... 48 V, sampled at 1.055 kHz;
- a delay of the lock-in's output filter (two RC sections of 0.6 ... 1.4 samples each: 1.2 ... 2.8 samples' delay);
  under a roller blind, on a unipolar stroke, with a noisy input monitor, sampled at 488 Hz;
- a drop left in another state by the previous test (the command taken from the middle to +- 0.6 ... 0.95 of the
  swing and back, from the virgin drop), the record starting there at 0 V; under a mezzaluna mincing herbs (the first
  bunch's rocks gentle), +-44 ... 48 V, sampled at 872 Hz;
- two effects: the drop dissolving into the oil (about 7 ... 11 % of its volume by the end, labelled "drift") and the
  lock-in's detector (the ends compressed by 12 ... 18 %, labelled "output_saturation"); under a gymnast on the pommel
  horse, +-44 ... 48 V, sampled at 1.322 kHz;
- out of vocabulary: a diaphragm vacuum pump on the bench cycling on its pressure switch (on 0.8 ... 2.5 s, off 1 ... 3
  s), its vibration shaking the line over its defects (the pinning strengths 0.2 ... 0.4 of theirs while it runs, the
  line relaxing toward its equilibrium); under a child's rocking horse, +-44 ... 48 V, sampled at 1.118 kHz. The record
  does not carry the pump: no map of the recorded drive draws it.

Every bipolar drive is drawn until its weaker side reaches 0.85 of its stronger (a test programme's balance). The
effects' sizes beyond a gain and an offset on the core (seeds 0 ... 2) are stated in the test.
"""

import math

import numpy as np

from . import mechanisms43 as m43
from . import signals43 as s43
from . import set_tools
from .record import case_set, finish
from .set_tools import scale as _scale

HOLDOUT43, case, _rng = case_set("holdout43_", 43000)


def _cell(rng, unipolar=False):
    """The core: the sectors' seed and pinning, the line's elasticity, the drop's volume (R = 1 at theta_mid), the
    command's middle and swing, and the meter's C_mid."""
    th = math.radians(rng.uniform(108.0, 116.0))
    return dict(sseed=int(rng.integers(0, 2**31)), h0=rng.uniform(0.035, 0.05), hs=rng.uniform(0.45, 0.6),
                kap=rng.uniform(0.6, 1.2), theta_mid=th, om=m43.omega_for(th), c_mid=math.cos(th),
                dc=rng.uniform(0.24, 0.3), C_mid=rng.uniform(25.0, 45.0), unipolar=unipolar)


def _lippmann(core, v):
    """The Lippmann term from the drive: c_mid + dc v / amp, or c_mid + dc (2 v / top - 1) (unipolar)."""
    v = np.asarray(v, float)
    if core["unipolar"]:
        return core["c_mid"] + core["dc"] * (2.0 * v / core["top"] - 1.0)
    return core["c_mid"] + core["dc"] * v / core["amp"]


def _core_of(core, v, state=None):
    """The meter's reading of the rate-independent drop (from the sectors' radii state; default the virgin drop)."""
    return m43.drop(core, _lippmann(core, v), state=state)[1]


def _knotted(rng, dt, gen):
    """A balanced bipolar drive from a knot programme gen(rng) -> (knots, T_end)."""
    return set_tools.knotted(rng, dt, gen, s43.knots_at)


def _unipolar(rng, dt, gen):
    return set_tools.unipolar(rng, dt, gen, s43.knots_at)


_stroke = set_tools.stroke


# ---- clean ----

@case
def clean_electrowetting_drop_squeegee_1630hz(seed):
    """A clean core under a window cleaner's squeegee, from the virgin drop at 0 V; nothing else is run before it."""
    rng = _rng(seed, 1)
    dt = 1 / 1630
    x, t, kn = _knotted(rng, dt, lambda r: s43.squeegee(r, int(r.integers(2, 4))))
    amp = rng.uniform(44.0, 48.0)
    v = _scale(x, amp)
    core = dict(_cell(rng), amp=amp)
    off = rng.uniform(-2.0, 2.0)
    y = _core_of(core, v) + off
    rec = finish("holdout43_clean_electrowetting_drop_squeegee_1630hz", seed, t, v, y, set(), "explained",
                 f"a clean core (an electrowetting drop pinned by its coating: theta_mid "
                 f"{math.degrees(core['theta_mid']):.0f} deg, h0 {core['h0']:.3f}) under a window cleaner's squeegee "
                 f"({len(kn)} knots), +-{amp:.0f} V, 1.63 kHz", rng, monitor_noise=3e-4)
    rec.extra.update(core, offset=off, knots=kn, x=x, drive=v)
    return rec


# ---- one effect ----

@case
def creep_activated_contact_line_toaster_253hz(seed):
    """The contact line's thermally activated creep under a toaster's lever (unipolar), from the virgin drop at 0 V
    (the smallest footprint); nothing else is run before it."""
    rng = _rng(seed, 2)
    dt = 1 / 253
    t, kn, p, top, v = _unipolar(rng, dt, lambda r: s43.toaster(r, int(r.integers(4, 7))))
    core = dict(_cell(rng, unipolar=True), top=top)
    ratio, tau0 = rng.uniform(5.0, 8.0), rng.uniform(0.05, 0.2)
    F = core["h0"] / ratio
    w0 = F / (core["kap"] * tau0)
    core["W"] = m43.creep_speeds(core, F, w0)
    nsub = m43.CREEP_SUB
    rb, y = m43.drop(core, _lippmann(core, v), dt=dt, nsub=nsub, F=F)
    rec = finish("holdout43_creep_activated_contact_line_toaster_253hz", seed, t, v, y, {"creep"}, "either",
                 f"the contact line's thermally activated creep (h0 / F {ratio:.1f}, {tau0 * 1e3:.0f} ms at the "
                 f"threshold) under a toaster's lever, to {top:.0f} V, 253 Hz", rng)
    rec.extra.update(core, knots=kn, p=p, F=F, w0=w0, ratio=ratio, tau0=tau0, nsub=nsub, drive=v)
    return rec


@case
def rate_contact_line_friction_wet_dog_1495hz(seed):
    """The contact line's friction under a wet dog shaking itself dry, from the virgin drop at 0 V; nothing else is
    run before it."""
    rng = _rng(seed, 3)
    dt = 1 / 1495
    x, t, kn = _knotted(rng, dt, lambda r: s43.wet_dog(r, int(r.integers(3, 5))))
    amp = rng.uniform(44.0, 48.0)
    v = _scale(x, amp)
    core = dict(_cell(rng), amp=amp)
    tau_c = rng.uniform(0.006, 0.014)
    y = m43.drop(core, _lippmann(core, v), tau_c=tau_c, dt=dt, nsub=m43.FRICTION_SUB)[1]
    rec = finish("holdout43_rate_contact_line_friction_wet_dog_1495hz", seed, t, v, y, {"rate_dependence"}, "either",
                 f"the contact line's friction (tau_c {tau_c * 1e3:.0f} ms) under a wet dog shaking itself dry, "
                 f"+-{amp:.0f} V, 1.495 kHz", rng, monitor_noise=2.5e-4)
    rec.extra.update(core, knots=kn, x=x, tau_c=tau_c, nsub=m43.FRICTION_SUB, drive=v)
    return rec


def _dissolution_rate(core, loss, n):
    """The per-sample rate for which the drop at the middle (R = 1, theta_mid) would lose the share loss of its volume
    over n samples."""
    w = float(m43.dissolution_weight(1.0, core["theta_mid"]))
    return (1.0 - (1.0 - loss) ** (1.0 / n)) / w


@case
def drift_drop_dissolving_in_oil_bathtub_362hz(seed):
    """The drop dissolving into the oil under a bathtub (unipolar), from the virgin drop at 0 V (the smallest
    footprint); nothing else is run before it; the oil fresh from its bottle."""
    rng = _rng(seed, 4)
    dt = 1 / 362
    t, kn, p, top, v = _unipolar(rng, dt, lambda r: s43.bathtub(r, int(r.integers(2, 4))))
    core = dict(_cell(rng, unipolar=True), top=top)
    loss = rng.uniform(0.06, 0.10)
    rate = _dissolution_rate(core, loss, len(t))
    rb, y, oms = m43.dissolving(core, _lippmann(core, v), rate)
    h = _core_of(core, v)
    rec = finish("holdout43_drift_drop_dissolving_in_oil_bathtub_362hz", seed, t, v, y, {"drift"}, "either",
                 f"a drift from the drop dissolving into the oil (about {loss:.0%} of its volume by the end; "
                 f"{1 - oms[-1] / oms[0]:.1%}) under a bathtub, to {top:.0f} V, 362 Hz", rng)
    rec.extra.update(core, knots=kn, p=p, h=h, loss=loss, rate=rate, omegas=oms, drive=v)
    return rec


@case
def asymmetry_relaxation_oscillator_badminton_1205hz(seed):
    """A relaxation oscillator reading the capacitance under a badminton rally, from the virgin drop at 0 V; nothing
    else is run before it."""
    rng = _rng(seed, 5)
    dt = 1 / 1205
    x, t, kn = _knotted(rng, dt, lambda r: s43.badminton(r, int(r.integers(3, 5))))
    amp = rng.uniform(44.0, 48.0)
    v = _scale(x, amp)
    core = dict(_cell(rng), amp=amp)
    h = _core_of(core, v)
    c, X = _stroke(h)
    a, sd = rng.uniform(0.12, 0.18), float(rng.choice([-1.0, 1.0]))
    q = m43.oscillator_for(a)
    y = c + sd * X * m43.oscillator_reading(sd * (h - c) / X, q)
    rec = finish("holdout43_asymmetry_relaxation_oscillator_badminton_1205hz", seed, t, v, y, {"asymmetry"}, "either",
                 f"a relaxation oscillator reading the capacitance ((C_p + C_mid) / the half stroke {q:.1f}: the "
                 f"ends' secants {a:.0%} apart) under a badminton rally, +-{amp:.0f} V, 1.205 kHz", rng,
                 monitor_noise=2.5e-4)
    rec.extra.update(core, knots=kn, x=x, h=h, centre=c, X=X, a=a, side=sd, q=q, drive=v)
    return rec


@case
def saturation_gilbert_detector_cradle_1055hz(seed):
    """The lock-in's synchronous detector overloading under a cradle rocked to sleep, from the virgin drop at 0 V;
    nothing else is run before it."""
    rng = _rng(seed, 6)
    dt = 1 / 1055
    x, t, kn = _knotted(rng, dt, lambda r: s43.cradle(r, int(r.integers(2, 4))))
    amp = rng.uniform(44.0, 48.0)
    v = _scale(x, amp)
    core = dict(_cell(rng), amp=amp)
    h = _core_of(core, v)
    c, X = _stroke(h)
    comp = rng.uniform(0.10, 0.17)
    z = m43.gilbert_for(comp)
    y = c + X * m43.gilbert((h - c) / X, z)
    rec = finish("holdout43_saturation_gilbert_detector_cradle_1055hz", seed, t, v, y, {"saturation"}, "either",
                 f"the lock-in's synchronous detector (a Gilbert cell: the ends compressed by {comp:.0%}) under a "
                 f"cradle rocked to sleep, +-{amp:.0f} V, 1.055 kHz", rng)
    rec.extra.update(core, knots=kn, x=x, h=h, centre=c, X=X, comp=comp, z=z, drive=v)
    return rec


def _fine(dt, t, kn, p, top, core):
    """The drive and the core's reading on a grid R_FINE times finer."""
    R = m43.R_FINE
    tf = np.arange(R * (len(t) - 1) + 1) * dt / R
    v_fine = top * s43.knots_at(tf, kn) / p.max()
    return tf, v_fine, _core_of(core, v_fine)


@case
def delay_lockin_output_filter_roller_blind_488hz(seed):
    """The lock-in's output filter under a roller blind (unipolar), from the virgin drop at 0 V (the smallest
    footprint); nothing else is run before it; the blind rolled up (0 V) before the record."""
    rng = _rng(seed, 7)
    dt = 1 / 488
    t, kn, p, top, v = _unipolar(rng, dt, lambda r: s43.roller_blind(r, int(r.integers(8, 13))))
    core = dict(_cell(rng, unipolar=True), top=top)
    tau = rng.uniform(0.6, 1.4)
    tf, v_fine, y_fine = _fine(dt, t, kn, p, top, core)
    y = m43.lockin_filter(y_fine, 1.0 / m43.R_FINE, tau)[::m43.R_FINE]
    rec = finish("holdout43_delay_lockin_output_filter_roller_blind_488hz", seed, t, v, y, {"delay"}, "either",
                 f"the lock-in's output filter (two RC sections of {tau:.2f} samples: {2 * tau:.2f} samples' delay) "
                 f"under a roller blind, to {top:.0f} V, 488 Hz", rng, monitor_noise=2e-4)
    rec.extra.update(core, knots=kn, p=p, tau=tau, D=2 * tau, tf=tf, v_fine=v_fine, y_fine=y_fine, drive=v)
    return rec


@case
def initial_state_prior_excursion_mezzaluna_872hz(seed):
    """Left in another state by the previous test: the command taken from the middle (the virgin drop) to v_p and
    back (60 steps each way); the record starts there at 0 V, under a mezzaluna mincing herbs."""
    rng = _rng(seed, 8)
    dt = 1 / 872
    amp = rng.uniform(44.0, 48.0)
    core = dict(_cell(rng), amp=amp)
    rho, sd = rng.uniform(0.6, 0.95), float(rng.choice([-1.0, 1.0]))
    v_p = sd * rho * amp
    ramp = np.r_[np.linspace(0.0, v_p, 61), np.linspace(v_p, 0.0, 61)[1:]]
    state = m43.drop(core, _lippmann(core, ramp), return_state=True)[2]
    x, t, kn = _knotted(rng, dt, lambda r: s43.mezzaluna(r, int(r.integers(4, 7))))
    v = _scale(x, amp)
    y = _core_of(core, v, state=state)
    rec = finish("holdout43_initial_state_prior_excursion_mezzaluna_872hz", seed, t, v, y, {"initial_state"},
                 "either",
                 f"a drop left by the previous test ({v_p:+.0f} V applied and removed) under a mezzaluna mincing "
                 f"herbs, +-{amp:.0f} V, 872 Hz", rng)
    rec.extra.update(core, rho=rho, side=sd, v_p=v_p, state=state, knots=kn, x=x, drive=v)
    return rec


# ---- two effects ----

@case
def pair_drift_output_saturation_dissolving_gilbert_pommel_horse_1322hz(seed):
    """The drop dissolving into the oil, read through the lock-in's overloading detector, under a gymnast on the
    pommel horse, from the virgin drop at 0 V; nothing else is run before it; the oil fresh from its bottle."""
    rng = _rng(seed, 9)
    dt = 1 / 1322
    x, t, kn = _knotted(rng, dt, lambda r: s43.pommel_horse(r, int(r.integers(2, 4))))
    amp = rng.uniform(44.0, 48.0)
    v = _scale(x, amp)
    core = dict(_cell(rng), amp=amp)
    loss = rng.uniform(0.07, 0.11)
    rate = _dissolution_rate(core, loss, len(t))
    rb, hd, oms = m43.dissolving(core, _lippmann(core, v), rate)
    c, X = _stroke(hd)
    comp = rng.uniform(0.12, 0.18)
    z = m43.gilbert_for(comp)
    y = c + X * m43.gilbert((hd - c) / X, z)
    rec = finish("holdout43_pair_drift_output_saturation_dissolving_gilbert_pommel_horse_1322hz", seed, t, v, y,
                 {"drift", "output_saturation"}, "either",
                 f"the drop dissolving into the oil (about {loss:.0%} of its volume by the end) and the lock-in's "
                 f"detector (the ends compressed by {comp:.0%}) under a gymnast on the pommel horse, +-{amp:.0f} V, "
                 f"1.322 kHz", rng)
    rec.extra.update(core, knots=kn, x=x, loss=loss, rate=rate, omegas=oms, h_drift=hd, centre=c, X=X, comp=comp,
                     z=z, drive=v)
    return rec


# ---- out of vocabulary ----

@case
def oov_bench_pump_vibration_depinning_rocking_horse_1118hz(seed):
    """A bench pump's vibration shaking the line loose under a child's rocking horse, from the virgin drop at 0 V;
    nothing else is run before it (the pump off at the start)."""
    rng = _rng(seed, 10)
    dt = 1 / 1118
    x, t, kn = _knotted(rng, dt, lambda r: s43.rocking_horse(r, int(r.integers(2, 4))))
    amp = rng.uniform(44.0, 48.0)
    v = _scale(x, amp)
    core = dict(_cell(rng), amp=amp)
    keep = rng.uniform(0.2, 0.4)
    ivs, on = m43.pump_cycles(t, (0.8, 2.5), (1.0, 3.0), rng)
    hsc = 1.0 - (1.0 - keep) * on
    y_seen = m43.drop(core, _lippmann(core, v), hscale=hsc)[1]
    off = rng.uniform(-2.0, 2.0)
    rec = finish("holdout43_oov_bench_pump_vibration_depinning_rocking_horse_1118hz", seed, t, v, y_seen + off, set(),
                 "unexplained",
                 f"a bench pump's vibration ({len(ivs)} runs, the pinning {keep:.0%} of itself while it runs) under a "
                 f"child's rocking horse, +-{amp:.0f} V, 1.118 kHz", rng)
    rec.extra.update(core, knots=kn, x=x, keep=keep, ivs=ivs, on=on, hscale=hsc, offset=off, drive=v)
    return rec

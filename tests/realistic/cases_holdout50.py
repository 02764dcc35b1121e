"""The HOLDOUT50 set: written after HOLDOUT49 was measured, by a session that did not read how the diagnosis decides,
and run once for round 52's measurement (16 of 30 runs right on commit 1d50c7f); part of ALL since.

Mechanisms and signals that the other sets do not have (the laws are in :mod:`.mechanisms50`, the signals in
:mod:`.signals50`, each beside its source; the citations were written from memory, as they say). Every core is a robot
wrist joint's harmonic drive (a size-25 cup-type gear of ratio 50, pitch radius 32 mm) on a locked-output torsion bench:
its motor in current (torque) mode, its output flange bolted to the bench's fixture, its twist read by the motor's
encoder (arcsec at the output), zeroed at the start. The twist: 42 tooth pairs in the gear's two mesh zones, each
pressed into its tooth space by the wave generator's ellipse (an interference falling off parabolically from the major
axis, 12.5 ... 14.5 um there, plus profile errors), each a wedge with friction on its flanks (beta 60 ... 68 deg, mu
0.08 ... 0.12: a seated tooth's detent; it rides out at P tan(beta + phi) and slides back at P tan(beta - phi), P its
radial load), the teeth bending in series (4 ... 6 N/um) and sharing the rim's travel; the cup and fixture in series
(K_s 3.4 ... 4.2e4 N m / rad); and before it all the wave generator's Coulomb friction (0.07 ... 0.1 of the full torque,
reflected), a play on the motor's torque. Rate independent, with return-point memory; close to a Prandtl-Ishlinskii
model but not one (measured in tests/test_realistic_holdout50.py: a PI model of 12 plays of the drive fitted by NNLS,
stated there). The full drive's torque is 45 ... 50 N m, the twist up to about 5 arcmin either way. Every record but the
initial-state case's starts at 0 V from the rest state the bench's zeroing leaves (every tooth at its space's centre,
the friction's play at 0: the state is set so, not run), for unipolar and bipolar records alike; nothing else is run
before a record.

- a clean core under a table-tennis player's bat (rallies of forehands and backhands, the ball fetched between),
  +-44 ... 48 V, with a noisy input monitor, sampled at 1.051 kHz;
- creep from the fixture's bracket, printed in glass-filled polyamide, creeping by Schapery's nonlinear viscoelastic
  law (Nutting's power law, n 0.2 ... 0.3, of a reduced time that runs faster under load; its transient 0.1 ... 0.14 of
  its compliance at 1 s); under a drill press's feed lever (pecks, dwells, the quill let up), on a unipolar stroke,
  sampled at 241 Hz;
- rate dependence from a heavy replacement rotor (the next motor sizes up, with its brake: J_m 3.5 ... 5e-4 kg m^2)
  swinging on the gear's compliance at 24 ... 33 Hz, the wave generator's friction damping it; under a xylophone
  player's mallet (leaps, rolls, glissandi: never still), +-44 ... 48 V, with a noisy input monitor, sampled at 1.913
  kHz;
- a drift from the fixture's column in the sun by the window as cumulus clouds pass (8 ... 12 K in full sun, tau 30 ...
  50 s): the column's growth turning the flange under the encoder; under a treadmill's hill programme, on a unipolar
  stroke, sampled at 307 Hz;
- asymmetry from worn driving flanks on one side (a shoulder joint that held its arm against gravity for years: those
  flanks 12 ... 16 deg flatter and their friction 0.55 ... 0.7 of the others'); under an ice skater's strides and
  crossovers, +-44 ... 48 V, sampled at 877 Hz;
- saturation from the motor's iron (the amplifier scaled for a larger motor: 2.2 ... 2.6 times the rated current at the
  full drive, the torque linear to a knee and beyond it Frohlich's law of a saturating iron); under a volleyball
  player's pepper drill (digs, sets, hits: never still), +-44 ... 48 V, with a noisy input monitor, sampled at 1.289
  kHz;
- a delay of the encoder's position over its serial interface and the bus (latched 2.2 ... 3.4 samples before the
  logger's sample); under a lawn mower's pull-start cord, on a unipolar stroke, with a noisy input monitor, sampled at
  223 Hz;
- a joint in another state at the start: the amplifier tripped while the joint was driven to the full negative torque,
  the wave generator's friction holding 0.07 ... 0.1 of it locked in the gear, and the bench's zeroing not run; under a
  safecracker's dial (listening for the contacts first, then the combination), +-44 ... 48 V, sampled at 529 Hz;
- two effects: a delay of the setpoints over a field bus (1.0 ... 2.2 samples late, joined by straight lines by the
  amplifier's interpolator one cycle behind; labelled "delay") and rate dependence from the amplifier's current loop
  left with another motor's gains (a second-order loop at 8 ... 14 Hz, damping 0.3 ... 0.45; labelled
  "rate_dependence"); under a boxer's shadow-boxing (combinations, slips, bounces: never still), +-44 ... 48 V, sampled
  at 383 Hz;
- out of vocabulary: a sign-magnitude amplifier with its direction line left open (the torque |v| whichever way the
  drive points: the twist even in the drive); under a speed-cuber's wrist (inspections, quarter and half turns),
  +-44 ... 48 V, sampled at 739 Hz. The record does not carry the lost sign: the recorded drive is the PC's.

Every bipolar drive is drawn until its weaker side reaches 0.85 of its stronger (a test programme's balance). The
effects' sizes beyond a gain and an offset on the core (seeds 0 ... 2; RMS and largest) are stated in the test.
"""

import math

import numpy as np

from . import mechanisms50 as m50
from . import signals50 as s50
from . import set_tools
from .record import case_set, finish
from .set_tools import fine as _fine, scale as _scale

HOLDOUT50, case, _rng = case_set("holdout50_", 50000)


def _joint(rng, unipolar=False):
    """The core: the teeth's seed (their profile errors), the flanks' slope beta (rad) and friction mu, the rim's radial
    stiffness k_r and the teeth's bending stiffness k_t (N/um), the interference at the major axis iota_0 (um), its
    fall-off angle phi_e (deg) and the profile errors' spread (um), the wave generator's friction r_f (of the full
    torque), the cup's and fixture's stiffness K_s (N m / rad) and the full drive's torque T_max (N m)."""
    return dict(rseed=int(rng.integers(0, 2**31 - 2)), beta=math.radians(rng.uniform(60.0, 68.0)),
                mu=rng.uniform(0.08, 0.12), kr=rng.uniform(0.8, 1.2), kt=rng.uniform(4.0, 6.0),
                iota0=rng.uniform(12.5, 14.5), phi_e=rng.uniform(38.0, 42.0), err=rng.uniform(0.5, 0.9),
                rf=rng.uniform(0.07, 0.1), Ks=rng.uniform(3.4e4, 4.2e4), T_max=rng.uniform(45.0, 50.0),
                unipolar=unipolar)


def _knotted(rng, dt, gen):
    """A balanced bipolar drive from a knot programme gen(rng) -> (knots, T_end)."""
    return set_tools.knotted(rng, dt, gen, s50.knots_at)


def _unipolar(rng, dt, gen):
    return set_tools.unipolar(rng, dt, gen, s50.knots_at)


def _bipolar(rng, dt, gen):
    return set_tools.bipolar(rng, dt, gen, s50.knots_at)


#: the pair's fine steps a sample (the current loop and the core run on them)
PAIR_SUB = 4


def _reading(core, v, joint=None):
    """The reading (arcsec) of the rate-independent joint for the drive v, from `joint` (default the rest state)."""
    return m50.core_reading(core, v, joint)


# ---- clean ----

@case
def clean_harmonic_drive_table_tennis_1051hz(seed):
    """A clean core under a table-tennis player's bat, from the rest state at 0 V; nothing else is run before it."""
    rng = _rng(seed, 1)
    dt = 1 / 1051
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s50.table_tennis(r, int(r.integers(2, 4))))
    core = dict(_joint(rng), amp=amp)
    y = _reading(core, v)
    rec = finish("holdout50_clean_harmonic_drive_table_tennis_1051hz", seed, t, v, y, set(), "explained",
                 f"a clean core (a harmonic drive's 42 wedged teeth, beta {math.degrees(core['beta']):.1f} deg, mu "
                 f"{core['mu']:.3f}, interference {core['iota0']:.1f} um, the wave generator's friction "
                 f"{core['rf']:.3f} of the full torque) under a table-tennis player's bat ({len(kn)} knots), "
                 f"+-{amp:.0f} V, 1.051 kHz", rng, monitor_noise=3e-4)
    rec.extra.update(core, knots=kn, x=x, drive=v)
    return rec


# ---- one effect ----

@case
def creep_printed_bracket_schapery_drill_press_241hz(seed):
    """The fixture's printed bracket creeping (Schapery) under a drill press's feed lever (unipolar), from the rest
    state at 0 V after a long rest unloaded; nothing else is run before it."""
    rng = _rng(seed, 2)
    dt = 1 / 241
    t, kn, p, top, v = _unipolar(rng, dt, lambda r: s50.drill_press(r, int(r.integers(3, 5))))
    core = dict(_joint(rng, unipolar=True), top=top)
    kappa, n = rng.uniform(0.1, 0.14), rng.uniform(0.2, 0.3)
    a1, a2, share = rng.uniform(0.5, 1.0), rng.uniform(0.6, 1.0), rng.uniform(0.4, 0.5)
    y_um, fg, _s = m50.Joint(core).run(m50.motor_force(core, v))
    z = m50.bracket_creep(t, fg, core, kappa, n, a1, a2, share)
    y = m50.arcsec(y_um + z)
    rec = finish("holdout50_creep_printed_bracket_schapery_drill_press_241hz", seed, t, v, y, {"creep"}, "either",
                 f"the fixture's printed bracket creeping (Schapery: Nutting's t^{n:.2f}, {kappa:.3f} of its "
                 f"compliance at 1 s, g_1 1 + {a1:.2f} s^2, log a_s -{a2:.2f} s^2) under a drill press's feed lever, "
                 f"to {top:.0f} V, 241 Hz", rng)
    rec.extra.update(core, knots=kn, p=p, kappa=kappa, n=n, a1=a1, a2=a2, share=share, fg=fg, z=z, drive=v)
    return rec


@case
def rate_heavy_rotor_swing_xylophone_1913hz(seed):
    """A heavy replacement rotor swinging on the gear's compliance under a xylophone player's mallet, from the rest
    state at 0 V (the rotor still); nothing else is run before it."""
    rng = _rng(seed, 3)
    dt = 1 / 1913
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s50.xylophone(r, int(r.integers(4, 7))))
    core = dict(_joint(rng), amp=amp)
    J_m = rng.uniform(3.5e-4, 5.0e-4)
    sub = m50.SUB_ROTOR
    tf = _fine(t, sub)
    vf = amp * s50.knots_at(tf, kn) / np.abs(x).max()
    ys, fs = m50.swing(core, m50.motor_force(core, vf), dt / sub, J_m)
    y = m50.arcsec(ys[::sub])
    rec = finish("holdout50_rate_heavy_rotor_swing_xylophone_1913hz", seed, t, v, y, {"rate_dependence"}, "either",
                 f"a heavy replacement rotor (J_m {J_m * 1e4:.2f}e-4 kg m^2) swinging on the gear under a xylophone "
                 f"player's mallet, +-{amp:.0f} V, 1.913 kHz", rng, monitor_noise=2.5e-4)
    rec.extra.update(core, knots=kn, x=x, J_m=J_m, y_um=ys[::sub], fg=fs[::sub], drive=v)
    return rec


@case
def drift_sunlit_fixture_column_clouds_treadmill_307hz(seed):
    """The fixture's column in the sun as clouds pass, under a treadmill's hill programme (unipolar), from the rest
    state at 0 V; nothing else is run before it."""
    rng = _rng(seed, 4)
    dt = 1 / 307
    t, kn, p, top, v = _unipolar(rng, dt, lambda r: s50.treadmill_hills(r, 3))
    core = dict(_joint(rng, unipolar=True), top=top)
    L_c, R_arm = rng.uniform(150.0, 200.0), rng.uniform(100.0, 140.0)
    shade, dT_sun, tau_c = rng.uniform(0.15, 0.3), rng.uniform(8.0, 12.0), rng.uniform(30.0, 50.0)
    light = m50.cloud_light(rng, -6 * tau_c, t[-1], shade)
    tt = np.r_[np.arange(-6 * tau_c, 0.0, dt), t]
    T = m50.relax(tt, dT_sun * m50.light_at(tt, light), tau_c, dT_sun * shade)[-len(t):]
    z = m50.column_turn(T, L_c, R_arm)
    y = m50.arcsec(m50.core_y(core, v) + z)
    rec = finish("holdout50_drift_sunlit_fixture_column_clouds_treadmill_307hz", seed, t, v, y, {"drift"}, "either",
                 f"the fixture's column in the sun as clouds pass ({dT_sun:.1f} K in full sun, tau {tau_c:.0f} s: "
                 f"{np.ptp(m50.arcsec(z)):.1f} arcsec over the record) under a treadmill's hill programme, to "
                 f"{top:.0f} V, 307 Hz", rng)
    rec.extra.update(core, knots=kn, p=p, L_c=L_c, R_arm=R_arm, shade=shade, dT_sun=dT_sun, tau_c=tau_c,
                     light=light, T=T, z=z, drive=v)
    return rec


@case
def asymmetry_worn_driving_flanks_ice_skater_877hz(seed):
    """Worn driving flanks on one side under an ice skater's strides, from the rest state at 0 V; nothing else is run
    before it."""
    rng = _rng(seed, 5)
    dt = 1 / 877
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s50.ice_skater(r, int(r.integers(2, 4))))
    core = dict(_joint(rng), amp=amp)
    d_beta, wear_mu = math.radians(rng.uniform(12.0, 16.0)), rng.uniform(0.55, 0.7)
    worn = dict(core, beta_p=core["beta"] - d_beta, mu_p=core["mu"] * wear_mu)
    y = _reading(worn, v)
    rec = finish("holdout50_asymmetry_worn_driving_flanks_ice_skater_877hz", seed, t, v, y, {"asymmetry"}, "either",
                 f"driving flanks worn on one side ({math.degrees(d_beta):.1f} deg flatter, friction "
                 f"{wear_mu:.0%} of the others') under an ice skater's strides, +-{amp:.0f} V, 877 Hz", rng)
    rec.extra.update(core, knots=kn, x=x, d_beta=d_beta, wear_mu=wear_mu, drive=v)
    return rec


@case
def saturation_motor_iron_volleyball_pepper_1289hz(seed):
    """The motor's iron saturating (the amplifier scaled for a larger motor) under a volleyball player's pepper drill,
    from the rest state at 0 V; nothing else is run before it."""
    rng = _rng(seed, 6)
    dt = 1 / 1289
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s50.volleyball_pepper(r, int(r.integers(2, 4))))
    core = dict(_joint(rng), amp=amp)
    lam, i_k, i_s = rng.uniform(2.2, 2.6), rng.uniform(1.3, 1.6), rng.uniform(0.5, 0.8)
    fm = m50.f_max(core) * m50.motor_iron(lam * v / amp, i_k, i_s)
    y_um = m50.Joint(core).run(fm)[0]
    y = m50.arcsec(y_um)
    rec = finish("holdout50_saturation_motor_iron_volleyball_pepper_1289hz", seed, t, v, y, {"saturation"}, "either",
                 f"the motor's iron saturating ({lam:.2f} times the rated current at the full drive, the knee at "
                 f"{i_k:.2f}) under a volleyball player's pepper drill, +-{amp:.0f} V, 1.289 kHz", rng,
                 monitor_noise=3e-4)
    rec.extra.update(core, knots=kn, x=x, lam=lam, i_k=i_k, i_s=i_s, fm=fm, drive=v)
    return rec


@case
def delay_encoder_serial_latency_pull_start_223hz(seed):
    """The encoder's position reaching the logger late under a lawn mower's pull-start cord (unipolar), from the rest
    state at 0 V; nothing else is run before it."""
    rng = _rng(seed, 7)
    dt = 1 / 223
    t, kn, p, top, v = _unipolar(rng, dt, lambda r: s50.pull_start(r, int(r.integers(18, 25))))
    core = dict(_joint(rng, unipolar=True), top=top)
    L = rng.uniform(2.2, 3.4) * dt
    v_late = top * s50.knots_at(t - L, kn) / p.max()
    y = _reading(core, v_late)
    rec = finish("holdout50_delay_encoder_serial_latency_pull_start_223hz", seed, t, v, y, {"delay"}, "either",
                 f"the encoder's position latched {L * 1e3:.2f} ms ({L / dt:.2f} samples) before the logger's "
                 f"sample under a lawn mower's pull-start cord, to {top:.0f} V, 223 Hz", rng, monitor_noise=2e-4)
    rec.extra.update(core, knots=kn, p=p, L=L, D=L / dt, v_late=v_late, drive=v)
    return rec


@case
def initial_state_amplifier_trip_safe_dial_529hz(seed):
    """The amplifier tripped at the full negative drive the session before, the zeroing not run, under a safecracker's
    dial (listening first)."""
    rng = _rng(seed, 8)
    dt = 1 / 529
    amp = rng.uniform(44.0, 48.0)
    core = dict(_joint(rng), amp=amp)
    joint = m50.tripped_joint(core)
    x, t, kn = _knotted(rng, dt, lambda r: s50.safe_dial(r, int(r.integers(4, 7))))
    v = _scale(x, amp)
    u0, z0, s0 = joint.u.copy(), joint.z, joint.s
    y = _reading(core, v, joint)
    rec = finish("holdout50_initial_state_amplifier_trip_safe_dial_529hz", seed, t, v, y, {"initial_state"}, "either",
                 f"the amplifier tripped at the full negative drive (the wave generator's friction holding "
                 f"{-z0 * m50.R_P:.1f} N m in the gear, {np.sum(u0 != 0.0)} teeth off their seats), the zeroing not "
                 f"run, under a safecracker's dial, +-{amp:.0f} V, 529 Hz", rng)
    rec.extra.update(core, u0=u0, z0=z0, s0=s0, knots=kn, x=x, drive=v)
    return rec


# ---- two effects ----

@case
def pair_delay_rate_bus_latency_current_loop_shadow_boxing_383hz(seed):
    """The setpoints late over a field bus ("delay") and a sluggish current loop ("rate_dependence") under a boxer's
    shadow-boxing, from the rest state at 0 V and 0 A; nothing else is run before it."""
    rng = _rng(seed, 9)
    dt = 1 / 383
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s50.shadow_boxing(r, int(r.integers(2, 4))))
    core = dict(_joint(rng), amp=amp)
    L = rng.uniform(1.0, 2.2) * dt
    T_d = L + dt
    w, zeta = 2 * math.pi * rng.uniform(8.0, 14.0), rng.uniform(0.3, 0.45)
    sub = PAIR_SUB
    tf = _fine(t, sub)
    c = m50.interpolated_late(t, v, T_d)
    i_f = m50.current_loop(m50.interpolated_late(tf, v, T_d, t), dt / sub, w, zeta)
    y = m50.arcsec(m50.core_y(core, i_f)[::sub])
    rec = finish("holdout50_pair_delay_rate_bus_latency_current_loop_shadow_boxing_383hz", seed, t, v, y,
                 {"delay", "rate_dependence"}, "either",
                 f"the setpoints {T_d / dt:.2f} samples late over a field bus and a current loop at "
                 f"{w / 2 / math.pi:.1f} Hz (damping {zeta:.2f}) under a boxer's shadow-boxing, +-{amp:.0f} V, 383 Hz",
                 rng)
    rec.extra.update(core, knots=kn, x=x, L=L, T_d=T_d, D=T_d / dt, w=w, zeta=zeta, c=c, i=i_f[::sub], drive=v)
    return rec


# ---- out of vocabulary ----

@case
def oov_sign_magnitude_direction_open_rubiks_cube_739hz(seed):
    """A sign-magnitude amplifier with its direction line open under a speed-cuber's wrist, from the rest state at 0
    V; nothing else is run before it."""
    rng = _rng(seed, 10)
    dt = 1 / 739
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s50.rubiks_cube(r, 2))
    core = dict(_joint(rng), amp=amp)
    y = _reading(core, np.abs(v))
    rec = finish("holdout50_oov_sign_magnitude_direction_open_rubiks_cube_739hz", seed, t, v, y, set(), "unexplained",
                 f"a sign-magnitude amplifier with its direction line open (the torque |v| either way) under a "
                 f"speed-cuber's wrist, +-{amp:.0f} V, 739 Hz", rng)
    rec.extra.update(core, knots=kn, x=x, drive=v)
    return rec

"""The HOLDOUT26 set: written after HOLDOUT25 was measured, by a session that did not read how the diagnosis decides,
to be run once for the next round's measurement; kept out of ALL until then.

Mechanisms and signals that the other sets do not have (the laws are in :mod:`.mechanisms26`, the signals in
:mod:`.signals26`, each beside its source; the citations were written from memory, as they say). Every core is a bolted
joint's microslip (Segalman's four-parameter Iwan model: Jenkins elements whose slip displacements have the density R
phi^chi, chi -0.6 ... -0.1, and a macroslip lump of 0.1 ... 0.8 of the rest, in parallel with the stage's flexure; the
joint 1.2 ... 2.5 times as stiff as the flexure; the out-of-vocabulary case's a slighter one, below), pushed by the
drive as a force and read through its exact inverse plays (the clean case's solved by its force balance instead); every
record but the initial-state case's starts at 0 V from the virgin state.

- a clean core (the joint above, solved sample by sample by its force balance, not through plays; a drawn gain and
  offset) under x_0 of Lorenz's 1996 model of a latitude circle (8 ... 12 sites, F = 8, chaotic; 1.2 ... 1.8 model
  units a second, its mean frequency near 1 Hz), centred, faded in from 0 V over 1 s, to peaks of +-44 ... 48 V, with
  a noisy input monitor, sampled at 1.775 kHz;
- creep of a hydrogen-charged niobium flexure by the Gorsky effect (the hydrogen diffusing across the bent flexure's
  0.5 ... 0.9 mm, from its compressed side to its stretched one; the odd Neumann modes k^2 / tau with the weights 96 /
  (pi^4 k^4), tau = d^2 / (pi^2 D) = 5 ... 16 s), 9 ... 13 % of the core's output after 10 s of a held load, by
  Boltzmann superposition (a Kelvin element per mode, exact for a load linear between samples); under an on-load tap
  changer's regulator (16 taps of 5.5 ... 6.1 V to 88 ... 97 V, energised on tap 0; a dead band of 0.55 ... 0.75 taps,
  1.5 ... 3 s before the first step and 0.8 ... 1.5 s between the next ones, each a raised cosine of 0.15 ... 0.3 s)
  through a day's load compressed into 70 ... 95 s (night, morning rise, midday, an evening peak that takes it to the
  top tap, night; the load's fluctuations three sines of 0.5 ... 1.1 taps at 0.03 ... 0.2 Hz), on a unipolar stroke,
  sampled at 205 Hz;
- rate dependence from a plate sheared through an oil gap beside the stage's flexure (unsteady Couette flow: the drag
  mu A q coth(q H) times the plate's velocity, q = sqrt(s / nu); tau_c = mu A / (k H) 1.2 ... 3 ms, the gap's viscous
  time H^2 / nu 4 ... 12 ms: Couette's dashpot when slow, the oil's inertia growing as sqrt(s) when fast; 40 modes and
  a mass for the rest, exact by the first-order hold), on the core's output; under 3 or 4 spins of Euler's disk (the
  contact point's coordinate cos(alpha) cos(phase); Moffatt's finite-time singularity: alpha falling as (t0 - t)^(1/3)
  from 0.25 ... 0.35 rad to 0.015 ... 0.03, the precession rising as (t0 - t)^(-1/6) from 2.2 ... 3.4 Hz to 7 ... 14
  Hz, played 3 ... 4 times slower; the disk carried by hand between spins), +-44 ... 48 V, with a noisy input
  monitor, sampled at 1.985 kHz;
- an offset drift of a capacitive sensor whose target was cleaned with acetone and still carries a drop (the offset
  its volume, a dielectric in the gap: Picknett & Bexon's stages, pinned while its angle falls from 25 ... 40 deg to
  the receding 8 ... 15 deg, then shrinking at that angle, at Hu & Larson's rate pi R D c_v (0.27 theta^2 + 1.30);
  gone after 0.4 ... 0.7 of the record), 4 ... 8 % of the span, either sign; under 3 or 4 drawings of a lateral
  harmonograph (two damped pendulums at 0.6 ... 0.9 Hz and 1.5, 2 or 3 times that, 1.2 % detuned, each pulled aside,
  held and let go), +-44 ... 48 V, sampled at 595 Hz;
- asymmetry of a scissor lab jack that the stage raises by pushing its sliding feet in (the height sqrt(L^2 - s^2),
  the feet 0.5 ... 0.7 of a bar apart at rest: concave, the ends' secants 11 ... 18 % apart, on a drawn side); under a
  steering wheel through parking manoeuvres (10 ... 13 targets, full lock both ways (1.5 turns) at least once; turned
  hand over hand in grabs of at most 90 ... 135 deg, 0.18 ... 0.3 s each with 0.06 ... 0.15 s to re-grip, or let slip
  back to straight by the tyres' self-aligning torque, tau 0.3 ... 0.6 s), +-44 ... 48 V, with a noisy input monitor,
  sampled at 1.095 kHz;
- saturation of a Hall probe carried along the axis of a gradient (anti-Helmholtz) coil pair (Biot-Savart: the coils
  +-0.6 ... 0.85 of their radius from the centre, the probe to where the ends are compressed by 12 ... 20 %; odd);
  under a springboard's tip through 4 ... 6 dives (the diver walking out, the hurdle timed to the ringing board, the
  landing's plastic impact, the press with diver and board together, the take-off where the board stops pushing, the
  board ringing down; 50 ... 90 kg divers on a board of 4 ... 5.5 kN/m and 15 ... 25 kg), the stage brought from 0 V
  to the board at rest first, +-44 ... 48 V, sampled at 665 Hz;
- a delay of a sensor behind a 4-pole Bessel-Thomson anti-aliasing filter (the flattest group delay: 2.3 ... 4.6
  samples at DC, its corner near 2.1 / delay), the core and the filter computed on a 4x finer grid; under the
  capacitor of Pearson & Anson's neon-lamp relaxation oscillator (striking at 88 ... 92 V, out at 58 ... 62 V, charged
  through tau_c 0.2 ... 0.35 s and discharged through 12 ... 20 ms) on a variac turned up through the strike to a fast
  flicker, down below it (the lamp dark, the capacitor following the supply past the middle), up and down again,
  centred on the middle of strike and extinction, +-44 ... 48 V, with a noisy input monitor, sampled at 515 Hz;
- a core left by a regula falsi (Illinois) search for the drive that brings the output to a point of the major loop's
  falling branch at 30 ... 42 V (0 V, 100 V, then the secants, 6 ... 10 steps), the record starting at its last
  iterate; then a bungee-jumping session from a platform at that level (5 ... 7 jumpers of 45 ... 115 kg, lightest
  first, on cords let out from 4 ... 5 m to 10 ... 11 m; free fall, the cord a spring in tension only with damping 8
  ... 14 %, slack rebounds, the hang, the haul back; played 2 ... 2.5 times faster; the deepest to 88 ... 97 V, passing
  80 V only from about the middle of the record), on a unipolar stroke, sampled at 895 Hz;
- two effects: creep of the stage's elastomer mounts by Wiechert's log-normal spectrum of retardation times (tau_m 0.8
  ... 3 s, 1 ... 2 e-folds wide; 8 ... 12 % after 10 s) read by a camera with an equisolid-angle fisheye (2 f sin(theta
  / 2), theta = atan(x / D): odd, the ends compressed by 12 ... 20 %); under a weightlifter's bar (2 or 3 snatches and
  2 cleans and jerks, the bar held overhead 2 ... 4 s for the referees, on the platform 3 ... 5 s between lifts; to 88
  ... 97 V), on a unipolar stroke, sampled at 645 Hz;
- out of vocabulary: a loose steel ball (restitution 0.94 ... 0.96, 10 ... 15 % of the platform's mass) on the stage's
  sprung platform (100 ... 140 Hz, damping 25 ... 35 %), the sensor on the platform; the core a slight, smooth
  microslip (no macroslip lump, 300 elements, the joint 0.25 ... 0.45 times as stiff as the flexure). Under a siren's
  steady tone at 13.7 ... 17.1 Hz (an exact 80 ... 100 samples a period) of +-44 ... 48 V, faded in, held 4 ... 5 s,
  then 5 or more yelps (the pitch swept 35 ... 50 % up and back in triangles of about 0.4 ... 0.6 s, their number the
  first after which the ball keeps bouncing; their length set so that they add a whole number of cycles), then the
  steady tone again for 5 ... 6 s and faded out, sampled at 1.365 kHz. The platform's largest downward acceleration
  under the steady tone is 0.9 ... 0.95 g: the ball, resting, is never thrown; the yelps (up to about 1.9 g) throw it,
  and once bouncing it keeps bouncing under the same steady tone (a bounce a period, 4 ... 7 mm high: the period-1
  orbit of a ball on a vibrating table, stable below about 1 g; Holmes 1982). In both holds the input is the same
  sample for sample and so is the core (its memory set by the same +-extremes); the output differs between them by
  many noise levels beyond any gain and offset (the impacts' kicks and the ball's weight taken off), while the
  platform's own linear dynamics moves the output by about one noise level beyond a gain and offset. A PI core (any
  plays with non-negative weights and any linear part) draws the same output for the same input from the same state;
  saturation and asymmetry are maps of it; rate dependence and delay are stable causal filters of it (a periodic input
  gives one periodic output, whatever came before); creep settles, and creep, drift and gain drift are slow and smooth
  in time (a gain and an offset between the holds at most); an initial state is forgotten after the first period.
"""

import math

import numpy as np
from scipy.optimize import brentq

from . import mechanisms26 as m26
from . import signals26 as s26
from .record import case_set, finish

HOLDOUT26, case, _rng = case_set("holdout26_", 26000)

G = 9.81


def _joint(rng, r_top=(30.0, 42.0), n=60, lump=True, k_t=(1.2, 2.5)):
    """A bolted joint's microslip as the core: Segalman's four-parameter Iwan model (chi -0.6 ... -0.1, the macroslip
    lump beta 0.1 ... 0.8 of the rest, or none, the joint k_t = 1.2 ... 2.5 times as stiff as the flexure beside it),
    its sliders scaled so that the macroslip force is r_top, read through its exact inverse plays; a drawn gain."""
    chi, beta, k_t = rng.uniform(-0.6, -0.1), rng.uniform(0.1, 0.8), rng.uniform(*k_t)
    if not lump:
        beta = 0.0
    phi, w = m26.segalman_iwan(n, 1.0, chi, beta, k_t)
    r, wp, w0 = m26.iwan_inverse_plays(phi, w, 1.0)
    lam = rng.uniform(*r_top) / r[-1]
    gain = rng.uniform(0.7, 1.4)
    return dict(thresholds=r * lam, weights=wp, linear=w0, gain=gain, phi=phi * lam, iwan_w=w, chi=chi, beta=beta,
                k_t=k_t)


def _core_of(core, v, state=0.0):
    return core["gain"] * m26.plays(v, core["thresholds"], core["weights"], core["linear"], state=state)


# ---- clean ----

@case
def clean_segalman_iwan_joint_lorenz96_1775hz(seed):
    rng = _rng(seed, 1)
    dt = 1 / 1775
    n = int(rng.uniform(12.0, 16.0) / dt)
    t = np.arange(n) * dt
    N, F = int(rng.integers(8, 13)), 8.0
    start = F + rng.normal(0.0, 1.0, N)
    units = rng.uniform(1.2, 1.8)
    x, s0 = s26.lorenz96_x0(t, units, start, F)
    xc = x - (x.max() + x.min()) / 2
    fade = m26.raised_cosine(t / 1.0)
    amp = rng.uniform(44.0, 48.0)
    scale = amp / np.abs(fade * xc).max()
    v = scale * fade * xc
    core = _joint(rng, r_top=(28.0, 40.0))
    u = m26.iwan_displacement(v, core["phi"], core["iwan_w"], 1.0)
    off = rng.uniform(-4.0, 4.0)
    y = core["gain"] * u + off
    rec = finish("holdout26_clean_segalman_iwan_joint_lorenz96_1775hz", seed, t, v, y, set(), "explained",
                 f"a clean core (a stage pushed against a bolted joint's microslip: Segalman's Iwan model, chi "
                 f"{core['chi']:.2f}, beta {core['beta']:.2f}, solved by the force balance) under x_0 of Lorenz's 1996 "
                 f"model ({N} sites, F 8), faded in from 0 V, +-{amp:.0f} V, 1.775 kHz", rng, monitor_noise=3e-4)
    rec.extra.update(core, offset=off, N=N, F=F, start=start, s0=s0, units=units, x=x, xc=xc, scale=scale, amp=amp,
                     u=u, drive=v)
    return rec


# ---- one effect ----

@case
def creep_gorsky_hydrogen_niobium_flexure_tap_changer_205hz(seed):
    rng = _rng(seed, 2)
    dt = 1 / 205
    T_rec = rng.uniform(70.0, 95.0)
    n = int(T_rec / dt)
    t = np.arange(n) * dt
    n_taps, top = 16, rng.uniform(88.0, 97.0)
    step_v = top / n_taps
    fr = np.array([0.0, 0.1, 0.22, 0.35, 0.5, 0.62, 0.72, 0.84, 1.0]) + np.r_[0, rng.uniform(-0.02, 0.02, 7), 0]
    knot_r = np.array([rng.uniform(1.5, 3.0), rng.uniform(1.5, 3.0), rng.uniform(8.0, 10.5), rng.uniform(6.0, 8.5),
                       rng.uniform(7.0, 9.5), rng.uniform(11.0, 13.0), rng.uniform(16.3, 17.0), rng.uniform(8.0, 10.0),
                       rng.uniform(2.0, 3.5)])
    wiggles = [(rng.uniform(0.5, 1.1), rng.uniform(0.03, 0.2), rng.uniform(0, 2 * np.pi)) for _ in range(3)]
    r_req = s26.required_tap(t, fr * T_rec, knot_r, wiggles)
    band, t_first, t_next = rng.uniform(0.55, 0.75), rng.uniform(1.5, 3.0), rng.uniform(0.8, 1.5)
    tap0 = 0                                                   # energised on its lowest tap
    steps = s26.tap_changer(t, r_req, tap0, band, t_first, t_next, n_taps)
    t_move = rng.uniform(0.15, 0.3)
    v = s26.tap_drive(t, tap0, steps, step_v, t_move)
    core = _joint(rng)
    h = _core_of(core, v)
    d, D = rng.uniform(0.5e-3, 0.9e-3), 5e-9                 # the flexure's thickness (m), hydrogen's diffusivity
    tau = d * d / (math.pi ** 2 * D)
    c = rng.uniform(0.09, 0.13)
    cr = m26.gorsky_creep(h, dt, c, tau, 10.0)
    rec = finish("holdout26_creep_gorsky_hydrogen_niobium_flexure_tap_changer_205hz", seed, t, v, h + cr, {"creep"},
                 "either",
                 f"creep of a hydrogen-charged niobium flexure by the Gorsky effect ({c:.1%} after 10 s; {d * 1e3:.2f} "
                 f"mm thick, tau {tau:.1f} s) under an on-load tap changer through a day's load ({len(steps)} steps of "
                 f"{step_v:.1f} V to {top:.0f} V), 205 Hz", rng)
    rec.extra.update(core, T_rec=T_rec, top=top, step_v=step_v, knot_t=fr * T_rec, knot_r=knot_r, wiggles=wiggles,
                     r_req=r_req, band=band, t_first=t_first, t_next=t_next, tap0=tap0, steps=steps, t_move=t_move,
                     h=h, d=d, D=D, tau=tau, c=c, creep=cr)
    return rec


@case
def rate_unsteady_couette_oil_gap_euler_disk_spins_1985hz(seed):
    rng = _rng(seed, 3)
    dt = 1 / 1985
    amp = rng.uniform(44.0, 48.0)
    a_disk, slow, glide = 0.0375, rng.uniform(3.0, 4.0), rng.uniform(0.4, 0.7)
    n_sp = int(rng.integers(3, 5))
    spins, tc = [], rng.uniform(0.5, 0.8) + glide
    for _ in range(n_sp):
        a0, a_end, T = rng.uniform(0.25, 0.35), rng.uniform(0.015, 0.03), rng.uniform(2.5, 4.0)
        t0 = T / (1 - (a_end / a0) ** 3)
        omega0 = 2 * math.sqrt(G / (a_disk * a0)) / slow
        spins.append((tc, T, t0, a0, omega0, rng.uniform(0, 2 * np.pi)))
        tc += T + glide + rng.uniform(0.2, 0.5)
    n = int((tc + rng.uniform(0.3, 0.6)) / dt)
    t = np.arange(n) * dt
    x = s26.euler_disk_spins(t, spins, glide)
    v = amp * x
    core = _joint(rng)
    h = _core_of(core, v)
    tau_c, t_nu = rng.uniform(1.2, 3.0) * 1e-3, rng.uniform(4.0, 12.0) * 1e-3
    y = m26.couette_stage(h, dt, tau_c, t_nu)
    rec = finish("holdout26_rate_unsteady_couette_oil_gap_euler_disk_spins_1985hz", seed, t, v, y,
                 {"rate_dependence"}, "either",
                 f"a plate sheared through an oil gap beside the flexure (unsteady Couette flow: tau_c "
                 f"{tau_c * 1e3:.1f} "
                 f"ms, the gap's viscous time {t_nu * 1e3:.1f} ms) under {n_sp} spins of Euler's disk (Moffatt's "
                 f"finite-time singularity, played {slow:.1f} times slower), +-{amp:.0f} V, 1.985 kHz", rng,
                 monitor_noise=2.5e-4)
    rec.extra.update(core, amp=amp, a_disk=a_disk, slow=slow, glide=glide, spins=spins, x=x, h=h, tau_c=tau_c,
                     t_nu=t_nu, drive=v)
    return rec


@case
def drift_evaporating_acetone_droplet_capacitive_target_harmonograph_595hz(seed):
    rng = _rng(seed, 4)
    dt = 1 / 595
    amp = rng.uniform(44.0, 48.0)
    pull, hold = rng.uniform(0.6, 1.0), rng.uniform(0.3, 0.6)
    n_dr = int(rng.integers(3, 5))
    drawings, tc = [], rng.uniform(0.4, 0.8) + pull + hold
    for _ in range(n_dr):
        f1 = rng.uniform(0.6, 0.9)
        ratio = rng.choice([1.5, 2.0, 3.0]) * (1 + rng.uniform(-0.012, 0.012))
        A1, A2 = rng.uniform(0.4, 1.0) * rng.choice([-1.0, 1.0]), rng.uniform(0.3, 0.8) * rng.choice([-1.0, 1.0])
        drawings.append((tc, [(A1, f1, rng.uniform(0.03, 0.08)), (A2, f1 * ratio, rng.uniform(0.04, 0.1))]))
        tc += rng.uniform(9.0, 13.0) + pull + hold
    T_rec = tc - pull - hold
    n = int(T_rec / dt)
    t = np.arange(n) * dt
    x = s26.harmonograph(t, drawings, pull, hold)
    scale = amp / np.abs(x).max()
    v = scale * x
    core = _joint(rng)
    h = _core_of(core, v)
    theta0, theta_r = math.radians(rng.uniform(25.0, 40.0)), math.radians(rng.uniform(8.0, 15.0))
    T1, T2 = m26.droplet_stages(theta0, theta_r)
    life = rng.uniform(0.4, 0.7) * t[-1]
    t_scale = life / (T1 + T2)                                  # R0^2 / K, s
    vol = m26.droplet_volume(t / t_scale, theta0, theta_r)
    frac, sign = rng.uniform(0.04, 0.08), rng.choice([-1.0, 1.0])
    off = sign * frac * np.ptp(h) * (1.0 - vol)
    rec = finish("holdout26_drift_evaporating_acetone_droplet_capacitive_target_harmonograph_595hz", seed, t, v,
                 h + off, {"drift"}, "either",
                 f"a drop of acetone evaporating from a capacitive sensor's target (pinned, then receding at "
                 f"{math.degrees(theta_r):.0f} deg; gone after {life:.0f} s; {sign * frac:+.1%} of the span) under "
                 f"{n_dr} drawings of a lateral harmonograph, +-{amp:.0f} V, 595 Hz", rng)
    rec.extra.update(core, amp=amp, pull=pull, hold=hold, drawings=drawings, x=x, scale=scale, h=h, theta0=theta0,
                     theta_r=theta_r, T1=T1, T2=T2, life=life, t_scale=t_scale, vol=vol, frac=frac, sign=sign,
                     offset=off)
    return rec


@case
def asymmetry_scissor_lab_jack_parking_steering_1095hz(seed):
    rng = _rng(seed, 5)
    dt = 1 / 1095
    amp, lock = rng.uniform(44.0, 48.0), 540.0
    grab_max, grab_s, regrip = rng.uniform(90.0, 135.0), rng.uniform(0.18, 0.3), rng.uniform(0.06, 0.15)
    n_mv = int(rng.integers(10, 14))
    targets, cur = [], 0.0
    for j in range(n_mv):
        if cur != 0.0 and rng.uniform() < 0.4:
            targets.append(0.0)                                   # straightened by letting the wheel slip back
        else:
            tgt = rng.choice([-1.0, 1.0]) * (1.0 if rng.uniform() < 0.45 else rng.uniform(0.2, 0.8))
            targets.append(float(tgt))
        cur = targets[-1]
    targets[int(rng.integers(0, 4))] = 1.0
    targets[int(rng.integers(5, 9))] = -1.0
    targets.append(0.0)
    moves, tc, lvl = [], rng.uniform(0.5, 1.0), 0.0
    for tgt in targets:
        if tgt == lvl:
            continue
        if tgt == 0.0 and rng.uniform() < 0.8:
            tau = rng.uniform(0.3, 0.6)
            moves.append(("release", tc, 0.0, tau))
            tc += 5 * tau
        else:
            moves.append(("grab", tc, tgt * lock, grab_max, grab_s, regrip))
            k = max(1, math.ceil(abs(tgt * lock - lvl) / grab_max - 1e-9))
            tc += k * grab_s + (k - 1) * regrip
        tc += rng.uniform(0.3, 1.2)                               # the car rolls with the wheel held
        lvl = tgt * lock if tgt else 0.0
    n = int((tc + rng.uniform(0.3, 0.6)) / dt)
    t = np.arange(n) * dt
    ang, ends = s26.steering(t, moves)
    v = amp * ang / lock
    core = _joint(rng)
    x_core = core["gain"] * m26.plays(v, core["thresholds"], core["weights"], core["linear"])
    c = (x_core.max() + x_core.min()) / 2
    X = np.abs(x_core - c).max()
    asym, side = rng.uniform(0.11, 0.18), rng.choice([-1.0, 1.0])
    s0 = rng.uniform(0.5, 0.7)

    def spread(ds):
        return -float(m26.scissor_reading(1.0, s0, ds) + m26.scissor_reading(-1.0, s0, ds)) - asym
    ds = brentq(spread, 1e-4, 0.95 * min(s0, 1 - s0), xtol=1e-14)
    y = c + side * X * m26.scissor_reading(side * (x_core - c) / X, s0, ds)
    rec = finish("holdout26_asymmetry_scissor_lab_jack_parking_steering_1095hz", seed, t, v, y, {"asymmetry"},
                 "either",
                 f"a scissor lab jack raised by the stage (its feet {s0:.2f} of a bar apart at rest, pushed in by up "
                 f"to "
                 f"{ds:.2f}; the ends' secants {asym:.0%} apart) under a steering wheel through parking manoeuvres "
                 f"({len(moves)} moves, hand over hand to +-1.5 turns, let slip back), +-{amp:.0f} V, 1.095 kHz", rng,
                 monitor_noise=3e-4)
    rec.extra.update(core, amp=amp, lock=lock, moves=moves, ends=ends, ang=ang, core_out=x_core, centre=c, X=X,
                     asym=asym, side=side, s0=s0, ds=ds, drive=v)
    return rec


@case
def saturation_gradient_coil_pair_hall_probe_springboard_dives_665hz(seed):
    rng = _rng(seed, 6)
    dt = 1 / 665
    amp = rng.uniform(44.0, 48.0)
    k, m_tip, zeta = rng.uniform(4000.0, 5500.0), rng.uniform(15.0, 25.0), rng.uniform(0.015, 0.03)
    walk = rng.uniform(1.8, 2.6)
    n_dv = int(rng.integers(4, 7))
    lead = rng.uniform(0.8, 1.2)
    dives, tc = [], lead + rng.uniform(0.3, 0.6)
    for _ in range(n_dv):
        M, stand = rng.uniform(50.0, 90.0), rng.uniform(0.6, 1.2)
        hh = s26.timed_hurdle(k, m_tip, M, zeta, rng.uniform(-0.3, 0.3))
        dives.append((tc, M, stand, hh))
        tc += walk + stand + rng.uniform(4.5, 7.0)
    n = int(tc / dt)
    t = np.arange(n) * dt
    yb, events = s26.springboard(t, dives, k, m_tip, zeta, walk)
    centre, half = (yb.max() + yb.min()) / 2, (yb.max() - yb.min()) / 2
    v_rest = -amp * centre / half
    v = amp * (yb - centre) / half - v_rest * (1 - m26.raised_cosine(t / lead))    # from 0 V to the board at rest
    core = _joint(rng)
    h = _core_of(core, v)
    c = (h.max() + h.min()) / 2
    X = np.abs(h - c).max()
    comp, d = rng.uniform(0.12, 0.2), rng.uniform(0.6, 0.85)
    z_max = brentq(lambda z: float(m26.gradient_reading(1.0, d, z)) - (1 - comp), 1e-3, d, xtol=1e-14)
    y = c + X * m26.gradient_reading((h - c) / X, d, z_max)
    rec = finish("holdout26_saturation_gradient_coil_pair_hall_probe_springboard_dives_665hz", seed, t, v, y,
                 {"saturation"}, "either",
                 f"a Hall probe carried along the axis of a gradient (anti-Helmholtz) coil pair (the coils +-{d:.2f} "
                 f"of their radius apart, the probe to +-{z_max:.2f}; the ends compressed by {comp:.0%}) under a "
                 f"springboard's tip through {n_dv} dives (hurdle, press, take-off, ringing down), +-{amp:.0f} V, "
                 f"665 Hz",
                 rng)
    rec.extra.update(core, amp=amp, k=k, m_tip=m_tip, zeta=zeta, walk=walk, lead=lead, v_rest=v_rest, dives=dives,
                     events=events, yb=yb,
                     y_centre=centre, y_half=half, h=h, centre=c, X=X, comp=comp, d=d, z_max=z_max)
    return rec


@case
def delay_bessel_thomson_antialias_neon_relaxation_variac_515hz(seed):
    rng = _rng(seed, 7)
    dt, sub = 1 / 515, 4
    amp = rng.uniform(44.0, 48.0)
    v_s, v_e = rng.uniform(88.0, 92.0), rng.uniform(58.0, 62.0)
    v_m = v_e - rng.uniform(8.0, 12.0)
    mid, half = (v_s + v_e) / 2, (v_s - v_e) / 2
    tau_c, tau_d = rng.uniform(0.2, 0.35), rng.uniform(0.012, 0.02)
    # the variac: held below the strike, turned up through it to a fast flicker and down to a slow one, below the
    # strike (the lamp dark, the capacitor following the supply down past the middle), up again and back down; the
    # supply never so high that the lamp would stay lit ((E - v_e) tau_d / tau_c < v_e - v_m)
    T = [0.0, rng.uniform(1.5, 2.5)]
    E = [mid, mid]
    plan = [((96.0, 100.0), (3.0, 4.0)), ((120.0, 130.0), (4.0, 6.0)), ((100.0, 105.0), (4.0, 6.0)),
            ((84.0, 87.0), (2.0, 3.0)), ((66.0, 70.0), (3.0, 4.0)), ((66.0, 70.0), (1.0, 2.0)),
            ((115.0, 125.0), (4.0, 5.0)), ((96.0, 100.0), (4.0, 5.0))]
    steps_E = [(rng.uniform(*e_r), rng.uniform(*d_r)) for e_r, d_r in plan]
    for e_to, dur in steps_E + [(mid, rng.uniform(2.0, 3.0)), (mid, rng.uniform(1.5, 2.5))]:
        T.append(T[-1] + dur)
        E.append(e_to)
    T_rec = T[-1]
    kt, kE = np.array(T), np.array(E)
    n = int(T_rec / dt)
    tf = np.arange((n - 1) * sub + 1) * (dt / sub)
    Vf, switches = s26.neon_oscillator(tf, kt, kE, mid, v_s, v_e, tau_c, tau_d, v_m)
    v_f = amp * (Vf - mid) / half
    v = v_f[::sub]
    t = tf[::sub]
    core = _joint(rng)
    h_f = _core_of(core, v_f)
    D = rng.uniform(2.3, 4.6)
    y_f = m26.bessel_sensor(h_f, dt / sub, D * dt)
    y = y_f[::sub]
    rec = finish("holdout26_delay_bessel_thomson_antialias_neon_relaxation_variac_515hz", seed, t, v, y, {"delay"},
                 "either",
                 f"a sensor behind a 4-pole Bessel-Thomson anti-aliasing filter (group delay {D:.2f} samples) under a "
                 f"neon-lamp relaxation oscillator on a variac ({sum(1 for s in switches if s[1])} flashes, the supply "
                 f"{min(E):.0f} ... {max(E):.0f} V), +-{amp:.0f} V, 515 Hz", rng, monitor_noise=2e-4)
    rec.extra.update(core, amp=amp, v_s=v_s, v_e=v_e, v_m=v_m, tau_c=tau_c, tau_d=tau_d, knots_t=kt, knots_E=kE,
                     switches=switches, sub=sub, D=D, v_fine=v_f, drive=v)
    return rec


@case
def initial_state_illinois_regula_falsi_bungee_jumps_895hz(seed):
    rng = _rng(seed, 8)
    dt = 1 / 895
    core = _joint(rng)
    x_star = rng.uniform(30.0, 42.0)
    target = float(_core_of(core, np.array([0.0, 100.0, x_star]))[-1])      # on the major loop's falling branch
    n_it = int(rng.integers(6, 11))
    path, meas = m26.illinois_search(core["thresholds"], core["weights"], core["linear"], core["gain"], target, 0.0,
                                     100.0, n_it)
    _, z0 = m26.plays(path, core["thresholds"], core["weights"], core["linear"], return_state=True)
    start = float(path[-1])
    top = rng.uniform(88.0, 97.0)
    speed = rng.uniform(2.0, 2.5)                               # the session's video played this much faster
    n_j = int(rng.integers(5, 8))
    masses = np.sort(rng.uniform(45.0, 115.0, n_j))            # the lightest first, the heaviest last
    k_cord, zeta = rng.uniform(150.0, 220.0), rng.uniform(0.08, 0.14)
    lengths = np.linspace(rng.uniform(4.0, 5.0), rng.uniform(10.0, 11.0), n_j)     # the cord let out for the later
    jumps, tc = [], rng.uniform(0.4, 0.8)
    haul = rng.uniform(1.2, 1.8)
    for mass, L in zip(masses, lengths):
        hang = rng.uniform(3.5, 5.0)
        jumps.append((tc, float(L), math.sqrt(k_cord / mass), zeta, hang))
        tc += hang + haul + rng.uniform(0.3, 0.8)
    n = int(tc / dt)
    t = np.arange(n) * dt
    deepest = max(float(np.max(s26.bungee_jump(np.linspace(0, speed * j[4], 8001), j[1], j[2], zeta)[0]))
                  for j in jumps)
    scale = (top - start) / deepest
    v = s26.bungee_session(t, start, scale, jumps, haul, speed=speed)
    y = _core_of(core, v, state=z0)
    rec = finish("holdout26_initial_state_illinois_regula_falsi_bungee_jumps_895hz", seed, t, v, y,
                 {"initial_state"}, "either",
                 f"a core left by a regula falsi (Illinois) search for the drive of a set output ({n_it} steps between "
                 f"0 and 100 V, ending at {start:.1f} V, where the record starts) under a bungee-jumping session from "
                 f"a platform at that level ({n_j} jumpers of {masses.min():.0f} ... {masses.max():.0f} kg, the cord "
                 f"{lengths[0]:.1f} ... {lengths[-1]:.1f} m, the deepest to {top:.0f} V, played {speed:.1f} times "
                 f"faster), 895 Hz", rng)
    rec.extra.update(core, x_star=x_star, target=target, path=path, meas=meas, state=z0, start=start, top=top,
                     speed=speed, masses=masses, lengths=lengths, k_cord=k_cord, zeta=zeta, jumps=jumps, haul=haul,
                     scale=scale,
                     deepest=deepest)
    return rec


# ---- two effects ----

@case
def pair_creep_saturation_wiechert_mounts_fisheye_camera_weightlifting_645hz(seed):
    rng = _rng(seed, 9)
    dt = 1 / 645
    top = rng.uniform(88.0, 97.0)
    kinds = ["snatch", "snatch", "clean_jerk", "clean_jerk"]
    if rng.uniform() < 0.5:
        kinds.insert(2, "snatch")
    lifts, tc = [], rng.uniform(0.8, 1.5)
    for kind in kinds:
        d = dict(first=rng.uniform(0.35, 0.5), second=rng.uniform(0.15, 0.25), peak=rng.uniform(0.1, 0.16),
                 catch=rng.uniform(0.2, 0.3),
                 recover=rng.uniform(1.2, 2.0) if kind == "snatch" else rng.uniform(0.6, 1.0),
                 stand=rng.uniform(1.0, 1.6), pause=rng.uniform(1.0, 2.5), dip=rng.uniform(0.3, 0.45),
                 drive=rng.uniform(0.15, 0.25), split=rng.uniform(0.15, 0.25), hold=rng.uniform(2.0, 4.0),
                 lower=rng.uniform(0.7, 1.2))
        keys = s26.lift_keys(kind, tc, d)
        lifts.append((kind, keys))
        tc = keys[-1][0] + rng.uniform(3.0, 5.0)                  # the bar on the platform while plates are changed
    n = int(tc / dt)
    t = np.arange(n) * dt
    all_keys = [k for _, keys in lifts for k in keys]
    v = top * s26.keyframe_path(t, all_keys)
    core = _joint(rng)
    h = _core_of(core, v)
    c_cr, tau_m, s_ln = rng.uniform(0.08, 0.12), rng.uniform(0.8, 3.0), rng.uniform(1.0, 2.0)
    cr = m26.wiechert_creep(h, dt, c_cr, tau_m, s_ln, 10.0)
    hc = h + cr
    c = (hc.max() + hc.min()) / 2
    X = np.abs(hc - c).max()
    comp = rng.uniform(0.12, 0.2)
    a = brentq(lambda q: float(m26.fisheye_reading(1.0, q)) - (1 - comp), 1e-3, 20.0, xtol=1e-14)
    y = c + X * m26.fisheye_reading((hc - c) / X, a)
    rec = finish("holdout26_pair_creep_saturation_wiechert_mounts_fisheye_camera_weightlifting_645hz", seed, t, v, y,
                 {"creep", "saturation"}, "either",
                 f"creep of the stage's elastomer mounts by Wiechert's log-normal spectrum ({c_cr:.1%} after 10 s; "
                 f"tau_m {tau_m:.1f} s, {s_ln:.1f} e-folds wide) read by a camera with an equisolid-angle fisheye "
                 f"(the view's edge {math.degrees(math.atan(a)):.0f} deg off the axis; the ends compressed by "
                 f"{comp:.0%}) under a weightlifter's bar ({len(kinds)} lifts: snatches, cleans and jerks, to "
                 f"{top:.0f} V), 645 Hz", rng)
    rec.extra.update(core, top=top, lifts=lifts, keys=all_keys, h=h, c_cr=c_cr, tau_m=tau_m, s_ln=s_ln, creep=cr,
                     centre=c, X=X, comp=comp, a=a)
    return rec


# ---- out of vocabulary ----

@case
def oov_rattling_ball_sprung_platform_yelp_siren_1365hz(seed):
    rng = _rng(seed, 10)
    dt, sub = 1 / 1365, 4
    amp = rng.uniform(44.0, 48.0)
    N = int(rng.integers(80, 101))                              # samples a period of the steady tone: 13.5 ... 17 Hz
    f_h = 1 / (N * dt)
    t_fade, T_A = rng.uniform(0.8, 1.2), rng.uniform(4.0, 5.0)
    depth, n_y0 = rng.uniform(0.35, 0.5), int(rng.integers(5, 9))
    T_m0 = rng.uniform(0.4, 0.6)
    T_B, t_out, tail = rng.uniform(5.0, 6.0), rng.uniform(0.8, 1.2), rng.uniform(0.3, 0.6)
    core = _joint(rng, n=300, lump=False, k_t=(0.25, 0.45))    # a smooth, slight microslip: no macroslip
    f_p, zeta_p = rng.uniform(100.0, 140.0), rng.uniform(0.25, 0.35)
    w_p = 2 * np.pi * f_p
    mu, e, gamma_h = rng.uniform(0.1, 0.15), rng.uniform(0.94, 0.96), rng.uniform(0.9, 0.95)
    v_stick = 1e-4
    t_y = t_fade + T_A
    for n_y in range(n_y0, n_y0 + 8):                           # the siren yelps until the ball rattles on after it
        K = max(1, round(f_h * depth * T_m0 * n_y / 2))
        T_m = 2 * K / (f_h * depth * n_y)                       # the yelps add K whole cycles: the tone returns in step
        t_end = t_y + n_y * T_m + T_B
        n = int((t_end + t_out + tail) / dt)
        kf = np.arange((n - 1) * sub + 1)
        tf = kf * (dt / sub)
        env = m26.raised_cosine(tf / t_fade) * (1 - m26.raised_cosine((tf - t_end) / t_out))
        v_f = amp * s26.yelp_siren(kf, N * sub, t_y, n_y, T_m, depth, dt / sub, env)
        h_f = _core_of(core, v_f)
        hc = (h_f.max() + h_f.min()) / 2
        acc = m26.platform_rest_accel(h_f - hc, dt / sub, w_p, zeta_p, mu)
        s_m = gamma_h * G / float(np.max(-acc[tf < t_y]))         # metres a volt of the core: the steady tone's
        p, b, fly, impacts = m26.rattling_platform(s_m * (h_f - hc), dt / sub, w_p, zeta_p, mu, e, G, v_stick)
        kA = N * int((t_y / dt - 4 * N) // N)                   # largest pull on the resting ball gamma_h g
        kB = N * int((t_end / dt - 4 * N) // N)
        if np.all(fly[::sub][kB - 2 * N:kB + 3 * N] | (np.abs(b - p)[::sub][kB - 2 * N:kB + 3 * N] < 1e-12)) and \
                sum(1 for q in impacts if (kB - 2 * N) * dt <= q[0] < (kB + 3 * N) * dt) >= 5:
            break
    v = v_f[::sub]
    t = tf[::sub]
    y = hc + p[::sub] / s_m
    rec = finish("holdout26_oov_rattling_ball_sprung_platform_yelp_siren_1365hz", seed, t, v, y, set(), "unexplained",
                 f"a loose steel ball (restitution {e:.2f}, {mu:.0%} of the platform's mass) on the stage's sprung "
                 f"platform ({f_p:.0f} Hz, damping {zeta_p:.0%}), the sensor on the platform; under a siren's tone at "
                 f"{f_h:.2f} Hz (the platform's pull on the resting ball {gamma_h:.2f} g at most) faded in, held, "
                 f"{n_y} yelps of {depth:.0%} up, held again: the ball rests through the first hold, is thrown by the "
                 f"yelps and keeps bouncing through the second, +-{amp:.0f} V, 1.365 kHz", rng)
    rec.extra.update(core, amp=amp, N=N, f_h=f_h, t_fade=t_fade, t_y=t_y, depth=depth, n_y=n_y, K=K, T_m=T_m,
                     t_end=t_end, t_out=t_out, sub=sub, hc=hc, f_p=f_p, zeta_p=zeta_p, mu=mu, e=e, gamma_h=gamma_h,
                     s_m=s_m, v_stick=v_stick, p=p[::sub], b=b[::sub], fly=fly[::sub], impacts=impacts, kA=kA, kB=kB)
    return rec

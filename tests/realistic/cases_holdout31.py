"""The HOLDOUT31 set: written after HOLDOUT30 was measured, by a session that did not read how the diagnosis decides,
to be run once for the next round's measurement; kept out of ALL until then.

Mechanisms and signals that the other sets do not have (the laws are in :mod:`.mechanisms31`, the signals in
:mod:`.signals31`, each beside its source; the citations were written from memory, as they say). Every core is a stage
held by a metal strap flexure in its elastic-plastic transition, Richard & Abbott's formula without hardening with
Masing's rules (Richard & Abbott 1975; Masing 1926): from the virgin state x = v + c V0 eps(v / V0), eps(q) = q / (1 -
|q|^n)^(1/n), from every reversal x_r + 2 (e + c V0 eps(e / V0)), e = (v - v_r) / 2, with Madelung's memory rules (a
closed inner loop wiped out), computed from a stack of turning points; the strap's compliance c 0.4 ... 0.8 of the
actuator's at small loads, the knee's sharpness n 1.7 ... 2.6, the peak drive 0.65 ... 0.85 of the plastic asymptote's
V0; a drawn gain. Every record but the initial-state case's starts at 0 V from the virgin state.

- a clean core under a helmsman tacking a dinghy upwind (corrections to the waves every 0.4 ... 1.2 s, bear-aways in the
  gusts, and two tacks: the tiller hard over to either side in turn, held, brought across to meet the new course and
  centred), +-44 ... 48 V, with a noisy input monitor, sampled at 1.735 kHz;
- creep of a pad whose anelastic relaxation has a Gaussian spread of activation energies (a log-normal spectrum of
  relaxation times about tau_m 2 ... 8 s, its width beta 0.8 ... 1.6 in ln tau; Wagner 1913, Nowick & Berry 1972),
  10 ... 15 % of the core's output after 10 s of a held load; under the load of a city bus along its route (passengers
  alighting and boarding one by one at 3 ... 5 stops, the load held while driving 6 ... 14 s, everyone off at the
  terminus), on a unipolar stroke, sampled at 228 Hz;
- rate dependence from a piezoelectric patch on the stage shunted by a resistor (Hagood & von Flotow 1991: the patch's
  stiffness rising from short-circuit to open-circuit with frequency, a standard linear solid; coupling 0.6 ... 0.75,
  short-circuit stiffness 0.3 ... 0.5 of the actuator's, its loss peak at 6 ... 12 Hz); under a snare drummer's stick
  in open-close-open double-stroke rolls (accelerating to 14 ... 20 strokes a second and back, the stick lifted the
  less the faster, accents between), on a unipolar stroke, with a noisy input monitor, sampled at 1.555 kHz;
- an offset drift from the stage's support standing in a spherical dewar of liquid nitrogen boiling off by the heat
  through its wetted wall (the wetted zone's area 2 pi R d, the free surface's pi d (2 R - d): (2 R - d)^2 growing
  linearly in time, the level falling fast near the top and ever more slowly; the support's cold length shrinking with
  it), 4 ... 8 % of the span at the end, either sign; under a fly fisherman's rod (false casts with growing reach, the
  delivery, strips of the retrieve), +-44 ... 48 V, sampled at 626 Hz;
- asymmetry of a parallel-plate optical micrometer: a glass plate (index 1.5 ... 1.7) in a laser beam, pre-tilted and
  tilted further by the stage by 0.22 ... 0.3 rad each way, the beam's lateral shift (Snell) read on a detector (the
  ends' secants 10 ... 17 % apart, on a drawn side); under a power kite flown in figure eights, loops to either side and
  parked at the zenith (fastest through the window's centre), +-44 ... 48 V, sampled at 1.105 kHz;
- saturation of an LED on the stage between two photodiodes read ratiometrically ((P1 - P2) / (P1 + P2) of
  inverse-square irradiances, u / (1 + u^2): the ends compressed by 10 ... 17 %); under a steam locomotive's
  Walschaerts valve gear (started in full forward gear, notched up as it gathers speed, stopped, put into full backward
  gear and set back), +-44 ... 48 V, with a noisy input monitor, sampled at 754 Hz;
- a delay of a programmable logic controller's scan cycle (the input latched at each scan's start, the output written
  at its end, scans of jittering length; 2.6 ... 4.4 samples in all on average), the core on a grid eight times finer;
  under a trampolinist's routines (build-up bounces, ten skills, the bounce killed), on a unipolar stroke, with a noisy
  input monitor, sampled at 425 Hz;
- a core carrying the memory of a drop in transit (the crate's shock loading the stage to 54 ... 60 V of either sign, a
  rebound of 0.1 ... 0.25 of it the other way and one of 0.03 ... 0.08 back, the packing's foam damping it, then at rest
  at 0 V), the record starting there; weighing on an equal-arm balance by trial with a 50-20-20-10-5-2-2(-1) set of
  weights (each trial a release of the beam, damped swings about its rest tilt, caught by the arrestment), +-44 ...
  48 V, sampled at 975 Hz. The drop's first shock lies beyond the record's reach, so the record's loops hang from it,
  unlike a virgin core's (which, the record starting at 0 V, is also the core at rest at the first input);
- two effects: creep of a PTFE slide pad by Findley's power law (t^n, n 0.3 ... 0.45; 10 ... 15 % after 10 s) and a gain
  drift of a Hall sensor reading a hard ferrite magnet on the stage as the magnet warms after the drive coil's bias is
  switched on (the remanence's reversible coefficient -0.18 ... -0.20 % per K, 45 ... 60 K at full warmth of a lumped
  warm-up; the gain 5 ... 12 % down at the end); under a flight simulator's motion platform in pitch (tilt-coordination
  holds for the take-off run and the braking, washout transients, turbulence), +-44 ... 48 V, sampled at 1.275 kHz;
- out of vocabulary: an LVDT on the stage read by an AC voltmeter instead of a phase-sensitive demodulator, so the
  reading is the magnitude of the travel from the LVDT's null (with its residual quadrature voltage, 0.4 ... 1 % of the
  span), the null 30 ... 42 % into the travel from either end; under a mechanical watch's balance wheel on a timing
  machine (the amplitude varying as the watch is turned between positions, stopped by the hacking lever and started
  again), +-44 ... 48 V, sampled at 1.315 kHz. The reading folds at the null: the same reading on both sides of it, so a
  rising travel lowers it and then raises it; no monotone map, gain, offset, filter or drift of a PI core draws that.
"""

import math

import numpy as np
from scipy.optimize import brentq

from . import mechanisms31 as m31
from . import signals31 as s31
from .record import case_set, finish
from .set_tools import grid as _grid

HOLDOUT31, case, _rng = case_set("holdout31_", 31000)


def _strap(rng, peak):
    """The core: the strap's compliance c 0.4 ... 0.8 of the actuator's, the knee's sharpness n 1.7 ... 2.6, the peak
    drive 0.65 ... 0.85 of the plastic asymptote's V0; a drawn gain."""
    p, c, n = rng.uniform(0.65, 0.85), rng.uniform(0.4, 0.8), rng.uniform(1.7, 2.6)
    return dict(p=p, c=c, n=n, V0=peak / p, gain=rng.uniform(0.7, 1.4))


def _core_of(core, v, state=None, return_state=False):
    out = m31.strap_core(v, core["V0"], core["c"], core["n"], state=state, return_state=return_state)
    if return_state:
        return core["gain"] * out[0], out[1]
    return core["gain"] * out


# ---- clean ----

@case
def clean_richard_abbott_strap_dinghy_tacking_1735hz(seed):
    rng = _rng(seed, 1)
    dt = 1 / 1735
    side0 = float(rng.choice([-1.0, 1.0]))
    times, vals = s31.dinghy_tacks(rng, 2, side0)
    t = _grid(dt, times[-1] + rng.uniform(0.3, 0.8))
    x = s31.waypoint_path(t, times, vals)
    amp = rng.uniform(44.0, 48.0)
    v = amp * x / np.abs(x).max()
    core = _strap(rng, amp)
    off = rng.uniform(-4.0, 4.0)
    y = _core_of(core, v) + off
    rec = finish("holdout31_clean_richard_abbott_strap_dinghy_tacking_1735hz", seed, t, v, y, set(), "explained",
                 f"a clean core (a strap flexure by Richard & Abbott's formula, compliance {core['c']:.2f}, knee "
                 f"{core['n']:.2f}, the peak {core['p']:.0%} of the plastic asymptote) under a helmsman tacking a "
                 f"dinghy ({int(np.sum(np.abs(vals) >= 0.85)) // 2} tacks), +-{amp:.0f} V, 1.735 kHz", rng,
                 monitor_noise=3e-4)
    rec.extra.update(core, offset=off, times=times, vals=vals, x=x, amp=amp, drive=v)
    return rec


# ---- one effect ----

@case
def creep_lognormal_spectrum_pad_city_bus_route_228hz(seed):
    rng = _rng(seed, 2)
    dt = 1 / 228
    events, T_end = s31.bus_route(rng, int(rng.integers(3, 6)))
    t = _grid(dt, T_end)
    p = s31.bus_load(t, events)
    top = rng.uniform(88.0, 97.0)
    v = top * p / p.max()
    core = _strap(rng, 100.0)
    h = _core_of(core, v)
    tau_m, beta, c = rng.uniform(2.0, 8.0), rng.uniform(0.8, 1.6), rng.uniform(0.10, 0.15)
    cr = m31.lognormal_creep(h, dt, c, tau_m, beta)
    rec = finish("holdout31_creep_lognormal_spectrum_pad_city_bus_route_228hz", seed, t, v, h + cr, {"creep"}, "either",
                 f"creep of a pad with a log-normal spectrum of relaxation times (tau_m {tau_m:.1f} s, width "
                 f"{beta:.2f}; {c:.1%} after 10 s) under a city bus's load ({len(events)} passengers on and off), "
                 f"to {top:.0f} V, 228 Hz", rng)
    rec.extra.update(core, events=events, top=top, p=p, h=h, tau_m=tau_m, beta=beta, c_creep=c, creep=cr, drive=v)
    return rec


@case
def rate_shunted_piezo_patch_snare_drum_roll_1555hz(seed):
    rng = _rng(seed, 3)
    dt = 1 / 1555
    strokes, T_end = s31.drum_roll(rng, 2)
    t = _grid(dt, T_end)
    x = s31.stick_height(t, strokes)
    top = rng.uniform(88.0, 97.0)
    v = top * x / x.max()
    core = _strap(rng, 100.0)
    h = _core_of(core, v)
    k_sc, kc, f_t = rng.uniform(0.3, 0.5), rng.uniform(0.6, 0.75), rng.uniform(6.0, 12.0)
    dk = k_sc * kc * kc / (1 - kc * kc)
    K = 1 + k_sc
    tau = math.sqrt(K / (K + dk)) / (2 * math.pi * f_t)
    y = m31.shunted_patch_stage(h, dt, k_sc, dk, tau)
    rec = finish("holdout31_rate_shunted_piezo_patch_snare_drum_roll_1555hz", seed, t, v, y, {"rate_dependence"},
                 "either",
                 f"a resistively shunted piezo patch on the stage (coupling {kc:.2f}, short-circuit stiffness "
                 f"{k_sc:.2f} of the actuator's, the loss peak at {f_t:.1f} Hz) under a snare drummer's rolls "
                 f"({len(strokes)} strokes), to {top:.0f} V, 1.555 kHz", rng, monitor_noise=2.5e-4)
    rec.extra.update(core, strokes=strokes, top=top, x=x, h=h, k_sc=k_sc, kc=kc, dk=dk, f_t=f_t, tau=tau, drive=v)
    return rec


@case
def drift_ln2_dewar_boil_off_fly_casting_626hz(seed):
    rng = _rng(seed, 4)
    dt = 1 / 626
    times, vals = s31.fly_casting(rng, int(rng.integers(2, 4)))
    t = _grid(dt, times[-1] + rng.uniform(0.3, 0.8))
    x = s31.waypoint_path(t, times, vals)
    amp = rng.uniform(44.0, 48.0)
    v = amp * x / np.abs(x).max()
    core = _strap(rng, amp)
    h = _core_of(core, v)
    R, d0, d1 = 1.0, rng.uniform(1.7, 1.95), rng.uniform(0.4, 0.9)
    q = ((2 * R - d1) ** 2 - (2 * R - d0) ** 2) / (4 * R * t[-1])   # the wall's heat flux, in depth boiled a second
    lev = m31.dewar_level(t, R, d0, q)
    mag, sd = rng.uniform(0.04, 0.08), float(rng.choice([-1.0, 1.0]))
    off = sd * mag * np.ptp(h) * (d0 - lev) / (d0 - lev[-1])
    rec = finish("holdout31_drift_ln2_dewar_boil_off_fly_casting_626hz", seed, t, v, h + off, {"drift"}, "either",
                 f"an offset drift from the stage's support in a spherical dewar of liquid nitrogen boiling off "
                 f"through its wetted wall (the level from {d0:.2f} R to {d1:.2f} R; {sd * mag:+.1%} of the span at "
                 f"the end) under a fly fisherman's casts, +-{amp:.0f} V, 626 Hz", rng)
    rec.extra.update(core, amp=amp, times=times, vals=vals, x=x, h=h, R=R, d0=d0, d1=d1, q=q, level=lev, mag=mag,
                     side=sd, offset=off, drive=v)
    return rec


def _kite_segments(rng):
    """Figure eights (one of them the full window's width), loops to either side and parking at the zenith, in a
    drawn order."""
    segs = [(rng.uniform(6.0, 9.0), rng.uniform(0.92, 1.0), 0.0, rng.uniform(0.25, 0.45), rng.uniform(0.3, 0.6))]
    kinds = ["eights", "loops_left", "loops_right", "park"]
    rng.shuffle(kinds)
    for k in kinds:
        if k == "eights":
            segs.append((rng.uniform(5.0, 8.0), rng.uniform(0.6, 0.9), 0.0, rng.uniform(0.25, 0.45),
                         rng.uniform(0.3, 0.6)))
        elif k == "park":
            segs.append((rng.uniform(2.0, 4.0), rng.uniform(0.02, 0.06), rng.uniform(-0.1, 0.1), rng.uniform(0.5, 1.0),
                         0.0))
        else:
            A = rng.uniform(0.25, 0.4)
            B = (1.0 if k == "loops_right" else -1.0) * (1 - A) * rng.uniform(0.9, 1.0)
            segs.append((rng.uniform(4.0, 6.0), A, B, rng.uniform(0.4, 0.7), rng.uniform(0.2, 0.4)))
    return segs


@case
def asymmetry_parallel_plate_micrometer_power_kite_1105hz(seed):
    rng = _rng(seed, 5)
    dt = 1 / 1105
    segs = _kite_segments(rng)
    t0, T_tr = rng.uniform(0.5, 1.0), rng.uniform(1.0, 2.0)
    t = _grid(dt, t0 + sum(s[0] for s in segs))
    x = s31.kite_session(t, t0, segs, T_tr)
    amp = rng.uniform(44.0, 48.0)
    v = amp * x / np.abs(x).max()
    core = _strap(rng, amp)
    h = _core_of(core, v)
    c = (h.max() + h.min()) / 2
    X = np.abs(h - c).max()
    asym, sd = rng.uniform(0.10, 0.17), float(rng.choice([-1.0, 1.0]))
    n_g, k = rng.uniform(1.5, 1.7), rng.uniform(0.22, 0.3)
    th0 = brentq(lambda a: m31.plate_asym(a, k, n_g) - asym, 0.01, 0.7, xtol=1e-14)
    y = c + sd * X * m31.plate_reading(sd * (h - c) / X, th0, k, n_g)
    rec = finish("holdout31_asymmetry_parallel_plate_micrometer_power_kite_1105hz", seed, t, v, y, {"asymmetry"},
                 "either",
                 f"a glass plate (index {n_g:.2f}) tilted by {k:.2f} rad about {th0:.2f} rad in a laser beam, its "
                 f"shift read (the ends' secants {asym:.0%} apart) under a power kite ({len(segs)} manoeuvres), "
                 f"+-{amp:.0f} V, 1.105 kHz", rng)
    rec.extra.update(core, amp=amp, segs=segs, t0=t0, T_tr=T_tr, x=x, h=h, centre=c, X=X, asym=asym, side=sd, n_g=n_g,
                     k=k, theta0=th0, drive=v)
    return rec


@case
def saturation_ratiometric_led_pair_walschaerts_valve_gear_754hz(seed):
    rng = _rng(seed, 6)
    dt = 1 / 754
    E, L = 1.0, rng.uniform(0.18, 0.3)
    th0 = math.atan2(L, E)                                        # standing in full forward gear, the valve at mid
    tw = 2 * math.pi
    rho_run = rng.uniform(0.25, 0.45)
    w_run, w_back = tw * rng.uniform(1.2, 2.0), -tw * rng.uniform(0.5, 0.9)
    phases = [(rng.uniform(1.0, 2.0), 0.0, 1.0, 1.0),                                   # standing
              (rng.uniform(3.0, 5.0), tw * rng.uniform(0.4, 0.7), 1.0, 1.0),            # starting in full gear
              (rng.uniform(4.0, 8.0), w_run, rho_run, rng.uniform(2.0, 4.0)),          # notched up
              (rng.uniform(4.0, 8.0), w_run, rho_run, 1.0),                            # running
              (rng.uniform(5.0, 8.0), 0.0, rho_run, 1.0),                              # braking to a stand
              (rng.uniform(2.0, 3.0), 0.0, -1.0, rng.uniform(1.0, 1.5)),               # into full backward gear
              (rng.uniform(3.0, 4.0), w_back, -1.0, 1.0),                              # setting back
              (rng.uniform(2.0, 4.0), w_back, -1.0, 1.0),
              (rng.uniform(2.0, 3.0), 0.0, -1.0, 1.0),
              (rng.uniform(2.0, 3.0), 0.0, 0.0, 1.5)]                                  # mid gear, at a stand
    t = _grid(dt, sum(p[0] for p in phases))
    th, rho = s31.loco_run(t, th0, 1.0, phases)
    x = s31.walschaerts_valve(th, rho, E, L) / math.hypot(E, L)
    amp = rng.uniform(44.0, 48.0)
    v = amp * x / np.abs(x).max()
    core = _strap(rng, amp)
    h = _core_of(core, v)
    c = (h.max() + h.min()) / 2
    X = np.abs(h - c).max()
    comp = rng.uniform(0.10, 0.17)
    u_max = math.sqrt(comp / (1 - comp))                            # 1 - 1 / (1 + u^2) = comp at the ends
    y = c + X * m31.ratiometric_pair(u_max * (h - c) / X) / u_max
    rec = finish("holdout31_saturation_ratiometric_led_pair_walschaerts_valve_gear_754hz", seed, t, v, y,
                 {"saturation"}, "either",
                 f"an LED on the stage between two photodiodes read ratiometrically, the travel {u_max:.2f} of their "
                 f"distance each way (the ends compressed by {comp:.0%}) "
                 f"under a locomotive's Walschaerts valve gear (lap and lead {L:.2f} of the link's throw, notched up "
                 f"to {rho_run:.0%}), +-{amp:.0f} V, 754 Hz", rng, monitor_noise=3e-4)
    rec.extra.update(core, amp=amp, E=E, L=L, theta0=th0, phases=phases, theta=th, rho=rho, x=x, h=h, centre=c, X=X,
                     comp=comp, u_max=u_max, drive=v)
    return rec


@case
def delay_plc_scan_cycle_trampoline_routine_425hz(seed):
    rng = _rng(seed, 7)
    dt, R = 1 / 425, 8
    flights, T_end = s31.trampoline_flights(rng, int(rng.integers(1, 3)))
    n = min(max(int(T_end / dt), 10_050), 40_000)
    tf = np.arange((n - 1) * R + 1) * (dt / R)
    xf = s31.flight_height(tf, flights)
    top = rng.uniform(88.0, 97.0)
    v_f = top * xf / xf.max()
    v = v_f[::R]
    t = tf[::R]
    core = _strap(rng, 100.0)
    h_f = _core_of(core, v_f)
    D, jit = rng.uniform(2.6, 4.4), rng.uniform(0.2, 0.4)
    T_scan = D * dt / 1.5
    scans = [-rng.uniform(0.0, T_scan)]
    while scans[-1] < t[-1]:
        scans.append(scans[-1] + T_scan * (1 + jit * rng.uniform(-1.0, 1.0)))
    scans = np.array(scans)
    y = m31.plc_register(t, tf, h_f, scans)
    rec = finish("holdout31_delay_plc_scan_cycle_trampoline_routine_425hz", seed, t, v, y, {"delay"}, "either",
                 f"a PLC's scan cycle (scans of {T_scan * 1e3:.2f} ms +-{jit:.0%}: {D:.2f} samples on average) under a "
                 f"trampolinist ({len(flights)} flights), to {top:.0f} V, 425 Hz", rng, monitor_noise=2e-4)
    rec.extra.update(core, flights=flights, top=top, R=R, v_fine=v_f, D=D, jit=jit, T_scan=T_scan, scans=scans,
                     drive=v)
    return rec


@case
def initial_state_transit_drop_beam_balance_weighing_975hz(seed):
    rng = _rng(seed, 8)
    dt = 1 / 975
    amp = rng.uniform(44.0, 48.0)
    core = _strap(rng, 62.0)
    s1 = float(rng.choice([-1.0, 1.0]))
    P1 = s1 * rng.uniform(54.0, 60.0)
    P2, P3 = -P1 * rng.uniform(0.1, 0.25), P1 * rng.uniform(0.03, 0.08)
    path = np.r_[np.linspace(0.0, P1, 400), np.linspace(P1, P2, 400)[1:], np.linspace(P2, P3, 400)[1:],
                 np.linspace(P3, 0.0, 400)[1:]]
    _, state = _core_of(core, path, return_state=True)
    m_obj, k_sens = rng.uniform(22.0, 28.0), rng.uniform(0.03, 0.05)
    box = [50.0, 20.0, 20.0, 10.0, 5.0, 2.0, 2.0, 1.0][:int(rng.integers(7, 9))]     # a 5-2-2-1 set of weights
    eqs = s31.balance_trials(box, m_obj, k_sens)
    releases, tc = [], rng.uniform(0.8, 1.5)
    f_b, z = rng.uniform(0.8, 1.4), rng.uniform(0.08, 0.16)
    for j, eq in enumerate(eqs):
        T = rng.uniform(4.0, 6.0) if j == len(eqs) - 1 else rng.uniform(1.5, 2.5)
        Ta = rng.uniform(0.4, 0.7)
        releases.append((tc, T, eq, f_b, z, Ta))
        tc += T + Ta + rng.uniform(0.4, 0.9)
    t = _grid(dt, tc)
    x = s31.balance_tilt(t, releases)
    v = amp * x / np.abs(x).max()
    y = _core_of(core, v, state=state)
    rec = finish("holdout31_initial_state_transit_drop_beam_balance_weighing_975hz", seed, t, v, y, {"initial_state"},
                 "either",
                 f"a core left by a drop in transit (to {P1:.0f} V, back to {P2:.0f} V and {P3:.0f} V, at rest at 0 V) "
                 f"under an equal-arm balance weighing {m_obj:.1f} g by trial ({len(releases)} releases), "
                 f"+-{amp:.0f} V, 975 Hz", rng)
    rec.extra.update(core, amp=amp, P1=P1, P2=P2, P3=P3, path=path, state=state, m_obj=m_obj, k_sens=k_sens, box=box,
                     eqs=eqs, releases=releases, x=x, drive=v)
    return rec


# ---- two effects ----

def _flight_cues(rng):
    """A flight in the simulator, compressed: taxi, the take-off run (a tilt held back), rotation and climb, turbulence,
    the level-off and descent, the flare and touchdown, braking (a tilt held forward), taxi."""
    cues, tc = [], rng.uniform(0.5, 1.0)
    cues.append((tc, "turb", rng.uniform(0.04, 0.08), int(rng.integers(1, 10 ** 6)), rng.uniform(2.0, 3.0)))
    tc += rng.uniform(2.0, 3.0)
    a_to, T1, hold = rng.uniform(0.85, 1.0), rng.uniform(1.0, 1.5), rng.uniform(2.5, 4.0)
    cues += [(tc, "onset", rng.uniform(0.1, 0.2), rng.uniform(0.3, 0.5), 0.0), (tc, "tilt", a_to, T1, hold)]
    tc += T1 + hold
    cues.append((tc, "onset", rng.uniform(0.1, 0.2), rng.uniform(0.3, 0.6), 0.0))        # rotation
    tc += T1
    T1c, holdc = rng.uniform(1.0, 1.5), rng.uniform(1.5, 2.5)
    cues.append((tc, "tilt", rng.uniform(0.25, 0.35), T1c, holdc))                      # climb attitude
    tc += 2 * T1c + holdc
    cues.append((tc - T1c, "turb", rng.uniform(0.08, 0.15), int(rng.integers(1, 10 ** 6)), rng.uniform(2.5, 3.5)))
    tc += rng.uniform(1.0, 1.5)
    cues.append((tc, "onset", -rng.uniform(0.1, 0.2), rng.uniform(0.4, 0.7), 0.0))      # level-off
    tc += rng.uniform(0.8, 1.2)
    T1d, holdd = rng.uniform(1.0, 1.5), rng.uniform(1.0, 2.0)
    cues.append((tc, "tilt", -rng.uniform(0.15, 0.3), T1d, holdd))                      # descent
    tc += 2 * T1d + holdd
    cues += [(tc, "onset", rng.uniform(0.1, 0.2), rng.uniform(0.4, 0.7), 0.0),          # flare
             (tc + 1.2, "onset", -rng.uniform(0.1, 0.2), rng.uniform(0.2, 0.3), 0.0)]   # touchdown
    tc += 1.5
    a_br, T1b, holdb = rng.uniform(0.95, 1.1), rng.uniform(1.0, 1.5), rng.uniform(2.5, 4.0)
    cues.append((tc, "tilt", -a_br, T1b, holdb))
    tc += 2 * T1b + holdb
    cues.append((tc, "turb", rng.uniform(0.04, 0.08), int(rng.integers(1, 10 ** 6)), rng.uniform(2.0, 3.0)))
    return cues, tc + rng.uniform(1.5, 2.5)


@case
def pair_creep_gain_drift_ptfe_findley_warming_magnet_flight_simulator_1275hz(seed):
    rng = _rng(seed, 9)
    dt = 1 / 1275
    cues, T_end = _flight_cues(rng)
    t = _grid(dt, T_end)
    x = s31.platform_pitch(t, cues)
    amp = rng.uniform(44.0, 48.0)
    v = amp * x / np.abs(x).max()
    core = _strap(rng, amp)
    h = _core_of(core, v)
    c_cr, n_exp = rng.uniform(0.10, 0.15), rng.uniform(0.3, 0.45)
    cr = m31.findley_creep(h, dt, c_cr, n_exp)
    xs = h + cr
    xc = (xs.max() + xs.min()) / 2
    alpha, dT = -rng.uniform(0.0018, 0.002), rng.uniform(45.0, 60.0)
    t_on = rng.uniform(0.05, 0.2) * t[-1]
    tau = rng.uniform(0.2, 0.4) * (t[-1] - t_on)
    G = m31.magnet_warmup_gain(t, t_on, tau, dT, alpha)
    y = xc + G * (xs - xc)
    rec = finish("holdout31_pair_creep_gain_drift_ptfe_findley_warming_magnet_flight_simulator_1275hz", seed, t, v, y,
                 {"creep", "gain_drift"}, "either",
                 f"creep of a PTFE pad by Findley's law (t^{n_exp:.2f}, {c_cr:.1%} after 10 s) and a Hall reading of a "
                 f"warming ferrite magnet (from {t_on:.1f} s, tau {tau:.1f} s, {alpha * dT:+.1%} at full warmth; "
                 f"{G[-1] - 1:+.1%} at the end) under a flight simulator's pitch ({len(cues)} cues), +-{amp:.0f} V, "
                 f"1.275 kHz", rng)
    rec.extra.update(core, amp=amp, cues=cues, x=x, h=h, c_creep=c_cr, n_exp=n_exp, creep=cr, centre=xc, alpha=alpha,
                     dT=dT, t_on=t_on, tau=tau, G=G, drive=v)
    return rec


# ---- out of vocabulary ----

@case
def oov_unphased_lvdt_watch_balance_wheel_1315hz(seed):
    rng = _rng(seed, 10)
    dt = 1 / 1315
    f, tau_a = rng.uniform(2.5, 4.0), rng.uniform(1.0, 2.5)
    n_pos = int(rng.integers(4, 6))
    amps = rng.uniform(0.75, 0.97, n_pos)
    amps[int(rng.integers(n_pos))] = 1.0
    positions = [(rng.uniform(4.0, 5.5), float(a)) for a in amps]
    t_hack = sum(p[0] for p in positions)
    T_stop = rng.uniform(1.0, 2.0)
    t = _grid(dt, t_hack + T_stop + rng.uniform(3.0, 4.0))
    x = s31.balance_wheel(t, f, tau_a, positions, t_hack, T_stop)
    amp = rng.uniform(44.0, 48.0)
    v = amp * x / np.abs(x).max()
    core = _strap(rng, amp)
    h = _core_of(core, v)
    f_null = rng.uniform(0.3, 0.42)
    if rng.random() < 0.5:
        f_null = 1 - f_null
    x_null = h.min() + f_null * np.ptp(h)
    e_q = rng.uniform(0.004, 0.01) * np.ptp(h)
    y = m31.unphased_lvdt(h, x_null, e_q)
    rec = finish("holdout31_oov_unphased_lvdt_watch_balance_wheel_1315hz", seed, t, v, y, set(), "unexplained",
                 f"an LVDT read by an AC voltmeter (no phase), its null {f_null:.0%} into the travel, the quadrature "
                 f"null {e_q / np.ptp(h):.1%} of the span, under a watch's balance wheel at {f:.2f} Hz ({n_pos} "
                 f"positions, hacked and restarted), +-{amp:.0f} V, 1.315 kHz", rng)
    rec.extra.update(core, amp=amp, f=f, tau_a=tau_a, positions=positions, t_hack=t_hack, T_stop=T_stop, x=x, h=h,
                     f_null=f_null, x_null=x_null, e_q=e_q, drive=v)
    return rec

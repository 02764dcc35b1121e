"""The HOLDOUT33 set: written after HOLDOUT32 was measured, by a session that did not read how the diagnosis decides,
to be run once for the next round's measurement; kept out of ALL until then.

Mechanisms and signals that the other sets do not have (the laws are in :mod:`.mechanisms33`, the signals in
:mod:`.signals33`, each beside its source; the citations were written from memory, as they say). Every core is a stage
moved by a magnetic actuator whose armature is an ensemble of Stoner-Wohlfarth grains (Stoner & Wohlfarth 1948): single-
domain, elongated grains whose easy axes lie in the plane of the coil's axis, spread about it by a Gaussian of 0.6 ...
0.9 rad, their anisotropy fields log-normal (the log's spread 0.45 ... 0.65); each grain's moment sits in one of the
two minima of E = sin^2(theta - psi) / 2 - u cos(theta), turns reversibly with the field and jumps to the other minimum
where that one vanishes, at the astroid's switching field (48 easy-axis angles x 80 anisotropy fields, each branch
tabulated and interpolated to 1e-8). The coil's field is the drive over V_K (the drive's peak 1.8 ... 2.4 times the
median anisotropy field); the stage's travel is the armature's moment along the axis plus 1.2 ... 2.0 of the field (the
coil's own flux through the gap), times a drawn gain. It is NOT a Prandtl-Ishlinskii model: rate independent, with
return-point memory (every grain's state is a symmetric relay at +-its switching field), but a grain switches at fixed
fields, not at a distance from the last reversal, so the branches are not Masing's, and loops that stay within the
smallest switching fields are reversible (a PI model of 12 plays fitted by NNLS leaves 8.7 ... 10.6 sigma RMS on the
clean record, at most 28 ... 32 sigma). The unipolar records' armature sits in a bias magnet's field opposing the coil's
(0.95 ... 1.05 of the stroke's middle), so that their stroke swings the field both ways. Every record but the
initial-state cases' starts at 0 V from the virgin, thermally demagnetised state (half the grains of every kind in
either minimum).

- a clean core under a footbridge's lateral sway as its crowd grows past the lock-in number (the walkers falling into
  step push with the deck's velocity, Dallard et al. 2001: a negative damping, bounded as their sway is, growing the
  sway from the unsynchronised footfalls' to its limit and letting it die as they stop; a mode at 0.85 ... 1.1 Hz),
  +-44 ... 48 V, with a noisy input monitor, sampled at 1.725 kHz;
- creep of an epoxy-grout bed under the actuator by Bazant & Chern's log-double-power law (ln(1 + (t / lambda)^n), n
  0.2 ... 0.4, lambda 1 ... 5 s: a power law early, logarithmic late), 10 ... 15 % of the core's output after 10 s of a
  held load; under a theatre's flown batten through a performance's cues (hauled in to full trim, to a border's half
  trim or out, held through the scenes), on a unipolar stroke, sampled at 233 Hz;
- rate dependence from a dashpot whose bypass tube runs laminar (Hagen-Poiseuille) at slow strokes and turbulent
  (Blasius, the force as the speed^(7/4), the friction factor jumping at Re = 2300) above 20 ... 35 % of the fastest
  travel, 15 ... 30 % of the flexure's force there; under a rotary telephone dial (7 ... 10 digits wound to the finger
  stop by hand and returned by the governor at 10 pulses a second), on a unipolar stroke, with a noisy input monitor,
  sampled at 1.565 kHz;
- an offset drift from a sunlit sensor bracket cooling under passing cumulus clouds (each cloud's edge crossing the
  Sun's disc in 0.5 ... 3.7 s, the disc's covered segment dimming it to the cloud's transmission of 0.2 ... 0.5; the
  bracket a lumped body of 4 ... 12 s), 4 ... 8 % of the span at its greatest, either sign; under a cow chewing its cud
  (boli of 12 ... 20 chews on alternate sides, rests between), +-44 ... 48 V, sampled at 648 Hz;
- asymmetry of a quarter-wave air column closed by a piston on the stage and read by its resonance (c / 4 (L + 0.61 a):
  convex, the ends' secants 10 ... 17 % apart, on a drawn side); under a goalkeeper's place along the line through a
  penalty shoot-out (bouncing on the line, diving, walking back), +-44 ... 48 V, sampled at 1.135 kHz;
- saturation of a slotted optical interrupter read as an analogue sensor (a round beam of uniform irradiance cut by the
  flag's straight edge: the open area's semicircle law, the ends compressed by 10 ... 17 %); under a prospector panning
  for gold (dipping, shaking, swirling and rocking the pan), +-44 ... 48 V, with a noisy input monitor, sampled at
  757 Hz;
- a delay of a soft silicone push rod between the stage and its sensor (a longitudinal wave's transit of 2.6 ... 4.4
  samples; the far end's dashpot nearly matched to the rod, reflecting +-2 ... 8 %, so faint echoes follow every 2
  transits), the core on a grid four times finer; under a plunger butter churn's dasher (bouts of strokes lifted slowly
  and plunged fast, slower and shorter as the butter comes), on a unipolar stroke, with a noisy input monitor, sampled
  at 443 Hz;
- a core left by a magnetiser's capacitor discharge that rang for want of its crowbar diode (the first lobe 1.35 ...
  1.6 times the record's peak field, either sign, each next lobe the other way and smaller by exp(-pi zeta /
  sqrt(1 - zeta^2)), zeta 0.3 ... 0.5), the record starting there at 0 V; under a guitarist's strumming hand (an intro
  swelling over two to four bars, then verses and a chorus in drawn eighth-note patterns, 84 ... 120 bpm), +-44 ...
  48 V, sampled at 952 Hz. Each grain holds the sign of the last lobe that reached its switching field, unlike the
  virgin core's half-and-half, until the record's own strokes reach it;
- two effects: a core left by a pulse magnetiser (4 ... 5 times the median anisotropy field, either sign: every grain
  switched) and a stabilising knock-down the other way (to 0.75 ... 0.9 of the record's peak), and saturation of a
  laminar fluidic jet sensor reading the stage (Bickley's plane jet, sech^2, split between two receivers: (tanh -
  tanh^3 / 3), the ends compressed by 10 ... 17 %); under a welder's torch weaving the four passes of a butt weld (root,
  hot pass, fill, cap; a dwell at each toe), +-44 ... 48 V, sampled at 1.255 kHz;
- out of vocabulary: the armature's moment across the coil's axis, its texture tilted 0.35 ... 0.55 rad off the axis,
  read by a Hall plate facing sideways; under a fish's tail swimming in bursts and coasts (bursts of 2 ... 5 beats at
  3 ... 6 a second, fast starts, coasts with the tail straight), +-44 ... 48 V, sampled at 1.375 kHz. As the field falls
  the grains turn out across the axis, and their transverse moments flip sign as they switch: along each branch the
  reading first moves against the drive and then with it (a hump inside the stroke), which no monotone map, gain,
  offset, filter, delay or drift of the core draws.

Every bipolar drive is drawn until its weaker side reaches 0.85 of its stronger (a test programme's balance).
"""

import math

import numpy as np
from scipy.optimize import brentq

from . import mechanisms33 as m33
from . import signals33 as s33
from .record import case_set, finish
from .set_tools import grid as _grid, scale as _scale

HOLDOUT33, case, _rng = case_set("holdout33_", 33000)


def _armature(rng, half, bias=0.0, tilt=0.0):
    """The core: an armature of Stoner-Wohlfarth grains (its texture's spread 0.6 ... 0.9 rad about the coil's axis,
    ``tilt`` off it; the log anisotropy fields' spread 0.45 ... 0.65), the field (the drive less the bias) over V_K, the
    drive's half-span ``half`` reaching 1.8 ... 2.4 times the median anisotropy field; the travel the moment plus
    1.2 ... 2.0 of the field (the coil's own flux), times a drawn gain."""
    spread, sig, r_pk = rng.uniform(0.6, 0.9), rng.uniform(0.45, 0.65), rng.uniform(1.8, 2.4)
    return dict(spread=spread, sigma_K=sig, tilt=tilt, r_pk=r_pk, V_K=half / r_pk, V_bias=bias,
                c_lin=rng.uniform(1.2, 2.0), gain=rng.uniform(0.7, 1.4))


_ENS = {}


def _ensemble(core):
    key = (core["spread"], core["sigma_K"], core["tilt"])
    if key not in _ENS:
        _ENS[key] = m33.armature_ensemble(*key)
    return _ENS[key]


def _field(core, v):
    return (np.asarray(v, float) - core["V_bias"]) / core["V_K"]


def _core_of(core, v, state=None, return_state=False):
    h = _field(core, v)
    M, st = m33.armature_moment(h, _ensemble(core), state=state, return_state=True)
    out = core["gain"] * (M + core["c_lin"] * h)
    return (out, st) if return_state else out


def _balanced(make, lo=0.85, tries=200):
    """Calls make() -> (x, *rest) until x's weaker side reaches lo of its stronger; returns its result."""
    for _ in range(tries):
        out = make()
        x = out[0]
        if min(x.max(), -x.min()) >= lo * np.abs(x).max():
            return out
    raise RuntimeError("no balanced drive drawn")


def _unipolar_bias(rng):
    """A permanent bias magnet's field opposing the coil's, so that the unipolar stroke swings the field both ways:
    0.95 ... 1.05 of the stroke's middle (50 V)."""
    return 50.0 * rng.uniform(0.95, 1.05)


# ---- clean ----

@case
def clean_sw_armature_footbridge_crowd_sway_1725hz(seed):
    rng = _rng(seed, 1)
    dt = 1 / 1725

    def make():
        p = s33.crowd_programme(rng)
        t = _grid(dt, p["T_end"])
        return s33.footbridge_sway(t, p), t, p
    x, t, p = _balanced(make)
    amp = rng.uniform(44.0, 48.0)
    v = _scale(x, amp)
    core = _armature(rng, amp)
    off = rng.uniform(-4.0, 4.0)
    y = _core_of(core, v) + off
    rec = finish("holdout33_clean_sw_armature_footbridge_crowd_sway_1725hz", seed, t, v, y, set(), "explained",
                 f"a clean core (Stoner-Wohlfarth grains, texture spread {core['spread']:.2f} rad, anisotropy spread "
                 f"{core['sigma_K']:.2f}, peak field {core['r_pk']:.2f} of the median) under a footbridge's lateral "
                 f"sway as its crowd locks in (mode {p['fn']:.2f} Hz), +-{amp:.0f} V, 1.725 kHz", rng,
                 monitor_noise=3e-4)
    rec.extra.update(core, offset=off, crowd=p, x=x, amp=amp, drive=v)
    return rec


# ---- one effect ----

@case
def creep_log_double_power_grout_bed_theatre_fly_233hz(seed):
    rng = _rng(seed, 2)
    dt = 1 / 233
    times, vals = s33.fly_cues(rng)
    t = _grid(dt, times[-1])
    p = s33.glide(t, times, vals)
    top = rng.uniform(88.0, 97.0)
    v = top * p / p.max()
    core = _armature(rng, 50.0, bias=_unipolar_bias(rng))
    h = _core_of(core, v)
    c, lam, n = rng.uniform(0.10, 0.15), rng.uniform(1.0, 5.0), rng.uniform(0.2, 0.4)
    cr = m33.log_double_power_creep(h, dt, c, lam, n)
    n_cues = sum(1 for a, b in zip(vals, vals[1:]) if a != b)
    rec = finish("holdout33_creep_log_double_power_grout_bed_theatre_fly_233hz", seed, t, v, h + cr, {"creep"},
                 "either",
                 f"creep of an epoxy-grout bed by Bazant & Chern's log-double-power law (n {n:.2f}, lambda "
                 f"{lam:.1f} s; {c:.1%} after 10 s) under a theatre's flown batten ({n_cues} cues), to {top:.0f} V, "
                 f"233 Hz", rng)
    rec.extra.update(core, times=times, vals=vals, top=top, p=p, h=h, c_creep=c, lam=lam, n_exp=n, creep=cr, drive=v)
    return rec


@case
def rate_turbulent_bypass_dashpot_rotary_dial_1565hz(seed):
    rng = _rng(seed, 3)
    dt = 1 / 1565
    ev, digits, T_end = s33.dial_number(rng, int(rng.integers(7, 11)))
    t = _grid(dt, T_end)
    x = s33.dial_angle(t, ev)
    top = rng.uniform(88.0, 97.0)
    v = top * x / x.max()
    core = _armature(rng, 50.0, bias=_unipolar_bias(rng))
    h = _core_of(core, v)
    K_s, beta, rc = 1.0 + rng.uniform(0.2, 0.5), rng.uniform(0.15, 0.3), rng.uniform(0.2, 0.35)
    v_max = np.abs(np.diff(h)).max() / dt / K_s                    # the fastest travel without the dashpot
    v_crit = rc * v_max
    gam = 0.3164 * m33.RE_CRIT ** 0.75 / 64.0
    c_lam = beta * (np.ptp(h) / 2) * rc ** 1.75 / (gam * v_crit)  # the force at v_max beta of the flexure's half-span
    y = m33.bypass_dashpot_stage(h, dt, K_s, c_lam, v_crit)
    rec = finish("holdout33_rate_turbulent_bypass_dashpot_rotary_dial_1565hz", seed, t, v, y, {"rate_dependence"},
                 "either",
                 f"a dashpot whose bypass tube turns turbulent (Blasius) above {rc:.0%} of the fastest travel, "
                 f"{beta:.0%} of the flexure's force there, under a rotary dial ({''.join(map(str, digits))}), to "
                 f"{top:.0f} V, 1.565 kHz", rng, monitor_noise=2.5e-4)
    rec.extra.update(core, events=ev, digits=digits, top=top, x=x, h=h, K_s=K_s, beta=beta, rc=rc, v_crit=v_crit,
                     c_lam=c_lam, drive=v)
    return rec


@case
def drift_cloud_shadows_sunlit_bracket_cow_rumination_648hz(seed):
    rng = _rng(seed, 4)
    dt = 1 / 648

    def make():
        times, vals = s33.rumination(rng, int(rng.integers(2, 4)))
        t = _grid(dt, times[-1])
        return s33.glide(t, times, vals), t, times, vals
    x, t, times, vals = _balanced(make)
    amp = rng.uniform(44.0, 48.0)
    v = _scale(x, amp)
    core = _armature(rng, amp)
    h = _core_of(core, v)
    T = t[-1]
    clouds, tc = [], rng.uniform(0.1, 0.3) * T
    while tc < 0.85 * T:
        dur = rng.uniform(3.0, 10.0)
        clouds.append((tc, dur, rng.uniform(0.2, 0.5)))
        tc += dur + rng.uniform(2.0, 8.0)
    H_base, wind = rng.uniform(800.0, 2000.0), rng.uniform(5.0, 15.0)
    T_edge = math.radians(0.53) * H_base / wind
    G = m33.cloud_irradiance(t, clouds, T_edge)
    tau = rng.uniform(4.0, 12.0)
    temp = m33.lumped_lag(t, G, tau, 1.0)
    mag, sd = rng.uniform(0.04, 0.08), float(rng.choice([-1.0, 1.0]))
    dT = temp - 1.0
    off = sd * mag * np.ptp(h) * dT / np.abs(dT).max()
    rec = finish("holdout33_drift_cloud_shadows_sunlit_bracket_cow_rumination_648hz", seed, t, v, h + off, {"drift"},
                 "either",
                 f"an offset drift from a sunlit sensor bracket (time constant {tau:.1f} s) cooling under "
                 f"{len(clouds)} passing cumulus clouds (edges {T_edge:.1f} s across the Sun; {sd * mag:+.1%} of the "
                 f"span at most) under a cow chewing its cud, +-{amp:.0f} V, 648 Hz", rng)
    rec.extra.update(core, times=times, vals=vals, amp=amp, x=x, h=h, clouds=clouds, H_base=H_base, wind=wind,
                     T_edge=T_edge, G=G, tau=tau, temp=temp, mag=mag, side=sd, offset=off, drive=v)
    return rec


@case
def asymmetry_quarter_wave_tube_goalkeeper_shootout_1135hz(seed):
    rng = _rng(seed, 5)
    dt = 1 / 1135

    def make():
        times, vals = s33.shootout(rng, 5)
        t = _grid(dt, times[-1])
        return s33.glide(t, times, vals), t, times, vals
    x, t, times, vals = _balanced(make)
    amp = rng.uniform(44.0, 48.0)
    v = _scale(x, amp)
    core = _armature(rng, amp)
    h = _core_of(core, v)
    c = (h.max() + h.min()) / 2
    X = np.abs(h - c).max()
    asym, sd = rng.uniform(0.10, 0.17), float(rng.choice([-1.0, 1.0]))
    a = brentq(lambda q: m33.quarter_wave_asym(q) - asym, 1e-4, 0.5, xtol=1e-15)
    y = c + sd * X * m33.quarter_wave_reading(sd * (h - c) / X, a)
    rec = finish("holdout33_asymmetry_quarter_wave_tube_goalkeeper_shootout_1135hz", seed, t, v, y, {"asymmetry"},
                 "either",
                 f"a quarter-wave air column tuned by a piston on the stage (+-{a:.1%} of its length) and read by its "
                 f"frequency (the ends' secants {asym:.0%} apart) under a goalkeeper in a penalty shoot-out, "
                 f"+-{amp:.0f} V, 1.135 kHz", rng)
    rec.extra.update(core, times=times, vals=vals, amp=amp, x=x, h=h, centre=c, X=X, asym=asym, side=sd, a_tube=a,
                     drive=v)
    return rec


@case
def saturation_round_beam_interrupter_gold_panning_757hz(seed):
    rng = _rng(seed, 6)
    dt = 1 / 757

    def make():
        segs, T_end = s33.panning(rng, int(rng.integers(3, 5)))
        t = _grid(dt, T_end)
        return s33.pan_position(t, segs), t, segs
    x, t, segs = _balanced(make)
    amp = rng.uniform(44.0, 48.0)
    v = _scale(x, amp)
    core = _armature(rng, amp)
    h = _core_of(core, v)
    c = (h.max() + h.min()) / 2
    X = np.abs(h - c).max()
    comp = rng.uniform(0.10, 0.17)
    b = brentq(lambda q: 1 - float(m33.interrupter_reading(1.0, q)) - comp, 0.05, 0.999, xtol=1e-15)
    y = c + X * m33.interrupter_reading((h - c) / X, b)
    rec = finish("holdout33_saturation_round_beam_interrupter_gold_panning_757hz", seed, t, v, y, {"saturation"},
                 "either",
                 f"a slotted optical interrupter read as an analogue sensor (a round, uniform beam cut by the flag's "
                 f"edge over +-{b:.0%} of its radius: the ends compressed by {comp:.0%}) under a prospector panning "
                 f"for gold ({len(segs)} motions), +-{amp:.0f} V, 757 Hz", rng, monitor_noise=3e-4)
    rec.extra.update(core, segs=segs, amp=amp, x=x, h=h, centre=c, X=X, comp=comp, b=b, drive=v)
    return rec


@case
def delay_silicone_push_rod_butter_churn_443hz(seed):
    rng = _rng(seed, 7)
    dt, R = 1 / 443, 4
    times, vals = s33.churning(rng, 3)
    n = min(max(int(times[-1] / dt), 10_050), 40_000)
    tf = np.arange((n - 1) * R + 1) * (dt / R)
    zf = s33.glide(tf, times, vals)
    top = rng.uniform(88.0, 97.0)
    v_f = top * zf / zf.max()
    v, t = v_f[::R], tf[::R]
    core = _armature(rng, 50.0, bias=_unipolar_bias(rng))
    h_f = _core_of(core, v_f)
    D, r = rng.uniform(2.6, 4.4), float(rng.choice([-1.0, 1.0])) * rng.uniform(0.02, 0.08)
    y = m33.push_rod(t, tf, h_f, D * dt, r)
    rec = finish("holdout33_delay_silicone_push_rod_butter_churn_443hz", seed, t, v, y, {"delay"}, "either",
                 f"a soft silicone push rod between the stage and its sensor (its wave's transit {D:.2f} samples, the "
                 f"far end's dashpot reflecting {r:+.0%}) under a plunger butter churn's dasher, to {top:.0f} V, "
                 f"443 Hz", rng, monitor_noise=2e-4)
    rec.extra.update(core, times=times, vals=vals, top=top, R=R, v_fine=v_f, D=D, r=r, drive=v)
    return rec


@case
def initial_state_ringing_magnetiser_guitar_strumming_952hz(seed):
    rng = _rng(seed, 8)
    dt = 1 / 952
    amp = rng.uniform(44.0, 48.0)
    core = _armature(rng, amp)
    s1 = float(rng.choice([-1.0, 1.0]))
    P1, zeta = s1 * rng.uniform(1.35, 1.6) * amp, rng.uniform(0.3, 0.5)
    path, peaks = m33.ringing_path(P1, zeta)
    _, state = _core_of(core, path, return_state=True)

    def make():
        times, vals, bpm, bars = s33.strumming(rng)
        t = _grid(dt, times[-1])
        return s33.glide(t, times, vals), t, times, vals, bpm, bars
    x, t, times, vals, bpm, bars = _balanced(make)
    v = _scale(x, amp)
    y = _core_of(core, v, state=state)
    rec = finish("holdout33_initial_state_ringing_magnetiser_guitar_strumming_952hz", seed, t, v, y,
                 {"initial_state"}, "either",
                 f"a core left by a magnetiser's ringing capacitor discharge (its first lobe {P1:.0f} V's field, "
                 f"damping {zeta:.2f}: {len(peaks)} lobes) under a guitarist strumming at {bpm:.0f} bpm, "
                 f"+-{amp:.0f} V, 952 Hz", rng)
    rec.extra.update(core, amp=amp, P1=P1, zeta=zeta, path=path, peaks=peaks, state=state, times=times, vals=vals,
                     bpm=bpm, bars=bars, x=x, drive=v)
    return rec


# ---- two effects ----

@case
def pair_initial_state_saturation_knocked_down_magnet_fluidic_jet_welding_weave_1255hz(seed):
    rng = _rng(seed, 9)
    dt = 1 / 1255
    amp = rng.uniform(44.0, 48.0)
    core = _armature(rng, amp)
    s1 = float(rng.choice([-1.0, 1.0]))
    P_s, P_k = s1 * rng.uniform(4.0, 5.0) * core["V_K"], -s1 * rng.uniform(0.75, 0.9) * amp
    path = np.r_[np.linspace(0.0, P_s, 400), np.linspace(P_s, 0.0, 400)[1:], np.linspace(0.0, P_k, 400)[1:],
                 np.linspace(P_k, 0.0, 400)[1:]]
    _, state = _core_of(core, path, return_state=True)

    def make():
        times, vals, widths = s33.weave_passes(rng)
        t = _grid(dt, times[-1])
        return s33.glide(t, times, vals), t, times, vals, widths
    x, t, times, vals, widths = _balanced(make)
    v = _scale(x, amp)
    h = _core_of(core, v, state=state)
    c = (h.max() + h.min()) / 2
    X = np.abs(h - c).max()
    comp = rng.uniform(0.10, 0.17)
    beta = brentq(lambda q: 1 - float(m33.jet_reading(1.0, q)) - comp, 0.05, 2.0, xtol=1e-15)
    y = c + X * m33.jet_reading((h - c) / X, beta)
    rec = finish("holdout33_pair_initial_state_saturation_knocked_down_magnet_fluidic_jet_welding_weave_1255hz", seed,
                 t, v, y, {"initial_state", "saturation"}, "either",
                 f"a core left magnetised by a pulse ({P_s:.0f} V's field) and knocked down ({P_k:.0f} V's), read by "
                 f"a laminar fluidic jet sensor (Bickley's jet, the ends compressed by {comp:.0%}) under a welder "
                 f"weaving four passes, +-{amp:.0f} V, 1.255 kHz", rng)
    rec.extra.update(core, amp=amp, P_s=P_s, P_k=P_k, path=path, state=state, times=times, vals=vals, widths=widths,
                     x=x, h=h, centre=c, X=X, comp=comp, beta=beta, drive=v)
    return rec


# ---- out of vocabulary ----

@case
def oov_transverse_moment_tilted_armature_fish_burst_coast_1375hz(seed):
    rng = _rng(seed, 10)
    dt = 1 / 1375

    def make():
        segs, T_end = s33.burst_and_coast(rng, rng.uniform(18.0, 26.0))
        t = _grid(dt, T_end)
        return s33.tail_tip(t, segs), t, segs
    x, t, segs = _balanced(make)
    amp = rng.uniform(44.0, 48.0)
    v = _scale(x, amp)
    core = _armature(rng, amp, tilt=rng.uniform(0.35, 0.55))
    h = _core_of(core, v)
    My = m33.armature_moment(_field(core, v), _ensemble(core), component="y")
    off = rng.uniform(-4.0, 4.0)
    y = core["gain"] * My + off
    rec = finish("holdout33_oov_transverse_moment_tilted_armature_fish_burst_coast_1375hz", seed, t, v, y, set(),
                 "unexplained",
                 f"the armature's moment across the coil's axis (its texture tilted {core['tilt']:.2f} rad off it) "
                 f"read by a sideways Hall plate, under a fish's tail swimming in bursts and coasts ({len(segs)} "
                 f"bursts), +-{amp:.0f} V, 1.375 kHz", rng)
    rec.extra.update(core, segs=segs, amp=amp, x=x, h=h, My=My, offset=off, drive=v)
    return rec

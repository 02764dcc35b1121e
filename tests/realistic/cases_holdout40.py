"""The HOLDOUT40 set: written after HOLDOUT39 was measured, by a session that did not read how the diagnosis decides,
and run once for round 42's measurement (16 of 30 runs right on commit 7a59e35); part of ALL since.

Mechanisms and signals that the other sets do not have (the laws are in :mod:`.mechanisms40`, the signals in
:mod:`.signals40`, each beside its source; the citations were written from memory, as they say). Every core is a soft
PZT disc whose grains switch by 180 deg, driven by a high-voltage amplifier (its field proportional to the drive) and
read by a charge amplifier (times a drawn gain): 23,040 grains, each a relay of the local field with the thresholds (b
+- E_c) / cos(theta) (the work of the field on the switch against a critical energy, Hwang, Lynch & McMeeking 1995; the
1 / cos(theta) law, Kondorsky's), the polar axes random in space, the coercive fields log-normal (the log's spread 0.25
... 0.35), internal bias fields b normal (spread 0.45 ... 0.6 of the median coercive field); the switched polarisation's
depolarising field in the mean-field approximation, E_loc = E - lambda P (lambda 1.2 ... 1.8), and the lattice's
reversible polarisation eps E (eps 0.15 ... 0.3). The bipolar drive's peak is 2 ... 2.4 median coercive fields, a
unipolar stroke's top 1.2 times that (0 V is zero field). Rate independent, with return-point memory (a Preisach model
of the local field, whose path keeps the drive's turning points), but not a Prandtl-Ishlinskii model (each grain's
thresholds are absolute fields, and the feedback breaks the minor loops' congruence). Its closeness to a PI model is
measured in tests/test_realistic_holdout40.py: a PI model of 12 plays of the drive fitted by NNLS leaves 0.87 ... 1.30
sigma RMS on the clean record (at most 7.9 ... 11.0 sigma), where the core is 76 ... 91 sigma from a straight line.
Every record but the initial-state case's starts at 0 V from the AC-depoled disc (the limit of the rig's slowly
decaying alternating field: the Preisach plane's diagonal staircase, net polarisation 0); nothing else is run before
it.

- a clean core under a windscreen wiper through a shower (intermittent, normal and fast wiping), +-44 ... 48 V, with a
  noisy input monitor, sampled at 1.385 kHz;
- creep from the domain walls' thermally activated after-effect (24 Kelvin elements spread evenly in ln(tau) from 0.05
  to 500 s: the step response linear in ln(t); kappa 0.25 ... 0.35 of every change of the polarisation, switched or
  reversible); under a lift through a morning (trips between 5 ... 8 floors, the doors open 6 ... 20 s), on a unipolar
  stroke, sampled at 235 Hz;
- rate dependence from the domain walls' viscosity (the switched polarisation lagging its quasi-static value with tau
  3 ... 6 ms, the lattice's part at once); under a skipping rope (bouts at 1.8 ... 2.6 turns a second, double-unders
  at 3.2 ... 3.8), +-44 ... 48 V, with a noisy input monitor, sampled at 1.065 kHz;
- an offset drift from the electrometer's JFET gate current doubling every 10 K as it warms by 8 ... 20 K (tau 0.15
  ... 0.5 of the record), integrated on the feedback capacitor: 4 ... 8 % of the span by the end, either sign; under a
  car park's barrier, on a unipolar stroke, sampled at 345 Hz;
- asymmetry of a Sawyer-Tower sense capacitor that is a linearly graded varactor junction (its voltage ((1 + 2 k q /
  3)^(3/2) - 1) / k of the charge: the ends' secants 12 ... 18 % apart, on a drawn side); under a hand saw through
  planks, +-44 ... 48 V, sampled at 790 Hz;
- saturation by the logger's input protection (anti-parallel diodes behind a series resistor: s = u + rho sinh(beta u),
  the ends compressed by 10 ... 17 %); under a violin bow (whole, half and quarter bows at constant speed), +-44 ... 48
  V, with a noisy input monitor, sampled at 830 Hz;
- a delay of the logger's fourth-order Bessel anti-aliasing filter (a group delay of 2.5 ... 5.5 samples), the core on
  a grid four times finer; under a bicycle pump, on a unipolar stroke, with a noisy input monitor, sampled at 470 Hz;
- a core left poled by the previous test (a DC field of 0.6 ... 0.95 of the record's peak, either sign, applied to the
  AC-depoled disc and removed), the record starting there at 0 V; under a playground swing (pushed, pumped, left to
  die out), +-44 ... 48 V, sampled at 640 Hz;
- two effects: the domain walls' viscosity (tau 9 ... 15 ms) and the logger's input protection diodes (the ends
  compressed by 10 ... 17 %, labelled "output_saturation"); under a rowing ergometer (pieces at 18 ... 32 strokes a
  minute), +-44 ... 48 V, sampled at 760 Hz;
- out of vocabulary: the high-voltage amplifier's switching ripple, aliased by the logger to 24 ... 40 Hz and drifting
  by 0.6 ... 1.5 Hz as the switcher warms, the largest at 0 V (1 - (v / V_rail)^2), 3.5 ... 6 % of the span there;
  under a cat's tail (lazy swishes, twitches, thumping), +-44 ... 48 V, sampled at 995 Hz. A tone the input does not
  carry: no map of a PI core draws it, no time-invariant filter of the input makes it, and the labelled drifts are
  slow.

Every bipolar drive is drawn until its weaker side reaches 0.85 of its stronger (a test programme's balance). The
effects' sizes beyond a gain and an offset on the core (seeds 0 ... 2) are stated in the test.
"""

import math

import numpy as np

from . import mechanisms40 as m40
from . import signals40 as s40
from . import set_tools
from .record import case_set, finish
from .set_tools import balanced as _balanced, fits as _fits, grid as _grid, scale as _scale

HOLDOUT40, case, _rng = case_set("holdout40_", 40000)


def _disc(rng, unipolar=False):
    """The core: the coercive fields' log spread ecs (0.25 ... 0.35), the bias fields' spread (0.45 ... 0.6), the
    depolarising feedback lam (1.2 ... 1.8), the lattice's eps (0.15 ... 0.3), the drive's peak field hp (2 ... 2.4
    median coercive fields; 1.2 times that at a unipolar stroke's top) and the reading's gain (0.7 ... 1.4)."""
    return dict(ecs=rng.uniform(0.25, 0.35), bias=rng.uniform(0.45, 0.6), lam=rng.uniform(1.2, 1.8),
                eps=rng.uniform(0.15, 0.3), hp=rng.uniform(2.0, 2.4), gain=rng.uniform(0.7, 1.4), unipolar=unipolar)


def _field(core, v):
    """The field (in median coercive fields) from the drive: hp v over its peak, or 1.2 hp v / top (unipolar)."""
    v = np.asarray(v, float)
    return 1.2 * core["hp"] * v / core["top"] if core["unipolar"] else core["hp"] * v / core["amp"]


def _core_of(core, v, s0=None):
    """The charge amplifier's reading of the rate-independent disc (from the grains' states s0; default AC-depoled)."""
    e = _field(core, v)
    return m40.reading(core, e, m40.polarisation(core, e, s0=s0))


def _viscous_of(core, v, dt, tau):
    """The reading with the switched polarisation lagging its quasi-static value (tau)."""
    e = _field(core, v)
    return m40.reading(core, e, m40.lag(m40.polarisation(core, e), dt, tau))


def _knotted(rng, dt, gen, kind="cyc"):
    """A balanced bipolar drive from a knot programme gen(rng) -> (knots, T_end)."""
    return set_tools.knotted(rng, dt, gen, lambda t, kn: s40.knots_eval(t, kn, kind=kind))


def _unipolar(rng, dt, gen):
    return set_tools.unipolar(rng, dt, gen, s40.knots_eval)


_stroke = set_tools.stroke


# ---- clean ----

@case
def clean_depoled_pzt_grain_switching_windscreen_wiper_1385hz(seed):
    """A clean core under a windscreen wiper, from the AC-depoled disc at 0 V; nothing else is run before it."""
    rng = _rng(seed, 1)
    dt = 1 / 1385
    x, t, kn = _knotted(rng, dt, s40.windscreen_wiper)
    amp = rng.uniform(44.0, 48.0)
    v = _scale(x, amp)
    core = dict(_disc(rng), amp=amp)
    off = rng.uniform(-2.0, 2.0)
    y = _core_of(core, v) + off
    rec = finish("holdout40_clean_depoled_pzt_grain_switching_windscreen_wiper_1385hz", seed, t, v, y, set(),
                 "explained",
                 f"a clean core (a soft PZT disc's grains switching: coercive log spread {core['ecs']:.2f}, bias "
                 f"spread "
                 f"{core['bias']:.2f}, depolarising lambda {core['lam']:.2f}, the field's peak {core['hp']:.2f} Ec) "
                 f"under a windscreen wiper ({len(kn)} knots), +-{amp:.0f} V, 1.385 kHz", rng, monitor_noise=3e-4)
    rec.extra.update(core, offset=off, knots=kn, x=x, drive=v)
    return rec


# ---- one effect ----

@case
def creep_domain_wall_aftereffect_lift_morning_235hz(seed):
    """The domain walls' log-time after-effect under a lift through a morning (unipolar), from the AC-depoled disc at
    0 V; nothing else is run before it (no change of the polarisation, so nothing creeps before the record)."""
    rng = _rng(seed, 2)
    dt = 1 / 235
    t, kn, p, top, v = _unipolar(rng, dt, lambda r: s40.lift_morning(r, int(r.integers(6, 11))))
    core = dict(_disc(rng, unipolar=True), top=top)
    kappa = rng.uniform(0.25, 0.35)
    h = _core_of(core, v)
    y = h + m40.aftereffect(h, dt, kappa)
    rec = finish("holdout40_creep_domain_wall_aftereffect_lift_morning_235hz", seed, t, v, y, {"creep"}, "either",
                 f"the domain walls' after-effect (kappa {kappa:.2f}, relaxation times 0.05 ... 500 s evenly in "
                 f"ln tau) under a lift through a morning, to {top:.0f} V, 235 Hz", rng)
    rec.extra.update(core, knots=kn, p=p, h=h, kappa=kappa, drive=v)
    return rec


@case
def rate_domain_wall_viscosity_skipping_rope_1065hz(seed):
    """The domain walls' viscosity under a skipping rope, from the AC-depoled disc at 0 V; nothing else is run before
    it."""
    rng = _rng(seed, 3)
    dt = 1 / 1065

    def make():
        bouts, T_end = s40.skipping_rope(rng, int(rng.integers(3, 5)))
        if not _fits(dt, T_end):
            return None
        t = _grid(dt, T_end)
        return s40.bouts_eval(t, bouts), t, bouts
    x, t, bouts = _balanced(make)
    amp = rng.uniform(44.0, 48.0)
    v = _scale(x, amp)
    core = dict(_disc(rng), amp=amp)
    tau = rng.uniform(0.003, 0.006)
    y = _viscous_of(core, v, dt, tau)
    rec = finish("holdout40_rate_domain_wall_viscosity_skipping_rope_1065hz", seed, t, v, y, {"rate_dependence"},
                 "either",
                 f"the domain walls' viscosity (the switched polarisation lagging by tau {tau * 1e3:.1f} ms) under a "
                 f"skipping rope ({len(bouts)} bouts), +-{amp:.0f} V, 1.065 kHz", rng, monitor_noise=2.5e-4)
    rec.extra.update(core, bouts=bouts, x=x, tau=tau, drive=v)
    return rec


@case
def drift_jfet_gate_current_warming_car_park_barrier_345hz(seed):
    """The electrometer's JFET gate current as it warms, under a car park's barrier (unipolar), from the AC-depoled
    disc at 0 V; nothing else is run before it; the charge amplifier reset at the record's start."""
    rng = _rng(seed, 4)
    dt = 1 / 345
    t, kn, p, top, v = _unipolar(rng, dt, lambda r: s40.car_park_barrier(r, int(r.integers(4, 7))))
    core = dict(_disc(rng, unipolar=True), top=top)
    h = _core_of(core, v)
    tau = rng.uniform(0.15, 0.5) * t[-1]
    dT = rng.uniform(8.0, 20.0)
    mag, sd = rng.uniform(0.04, 0.08), float(rng.choice([-1.0, 1.0]))
    shape = m40.gate_drift(t, tau, dT)
    off = sd * mag * np.ptp(h) * shape / shape[-1]
    rec = finish("holdout40_drift_jfet_gate_current_warming_car_park_barrier_345hz", seed, t, v, h + off, {"drift"},
                 "either",
                 f"an offset drift from the electrometer's JFET gate current (warming by {dT:.0f} K, tau {tau:.0f} s; "
                 f"{sd * mag:+.1%} of the span by the end) under a car park's barrier, to {top:.0f} V, 345 Hz", rng)
    rec.extra.update(core, knots=kn, p=p, h=h, tau=tau, dT=dT, mag=mag, side=sd, offset=off, drive=v)
    return rec


@case
def asymmetry_graded_varactor_sawyer_tower_hand_saw_790hz(seed):
    """A graded-junction varactor as the Sawyer-Tower sense capacitor under a hand saw, from the AC-depoled disc at 0
    V; nothing else is run before it."""
    rng = _rng(seed, 5)
    dt = 1 / 790
    x, t, kn = _knotted(rng, dt, lambda r: s40.hand_saw(r, 2))
    amp = rng.uniform(44.0, 48.0)
    v = _scale(x, amp)
    core = dict(_disc(rng), amp=amp)
    h = _core_of(core, v)
    c, X = _stroke(h)
    a, sd = rng.uniform(0.12, 0.18), float(rng.choice([-1.0, 1.0]))
    k = m40.varactor_for(a)
    y = c + sd * X * m40.varactor_reading(sd * (h - c) / X, k)
    rec = finish("holdout40_asymmetry_graded_varactor_sawyer_tower_hand_saw_790hz", seed, t, v, y, {"asymmetry"},
                 "either",
                 f"a graded-junction varactor as the Sawyer-Tower sense capacitor (k {k:.3f}: the ends' secants "
                 f"{a:.0%} apart) under a hand saw, +-{amp:.0f} V, 790 Hz", rng)
    rec.extra.update(core, knots=kn, x=x, h=h, centre=c, X=X, a=a, side=sd, k=k, drive=v)
    return rec


@case
def saturation_protection_diodes_logger_input_violin_bow_830hz(seed):
    """The logger's input protection diodes under a violin bow, from the AC-depoled disc at 0 V; nothing else is run
    before it."""
    rng = _rng(seed, 6)
    dt = 1 / 830
    x, t, kn = _knotted(rng, dt, lambda r: s40.violin_bow(r, int(r.integers(2, 4))), kind="trap")
    amp = rng.uniform(44.0, 48.0)
    v = _scale(x, amp)
    core = dict(_disc(rng), amp=amp)
    h = _core_of(core, v)
    c, X = _stroke(h)
    comp, rb = rng.uniform(0.10, 0.17), rng.uniform(0.002, 0.01)
    rho, beta = m40.diodes_for(comp, rb)
    y = c + X * m40.diode_reading((h - c) / X, rho, beta)
    rec = finish("holdout40_saturation_protection_diodes_logger_input_violin_bow_830hz", seed, t, v, y,
                 {"saturation"}, "either",
                 f"the logger's input protection diodes (rho beta {rb:.3f}, beta {beta:.1f}: the ends compressed by "
                 f"{comp:.0%}) under a violin bow, +-{amp:.0f} V, 830 Hz", rng, monitor_noise=3e-4)
    rec.extra.update(core, knots=kn, x=x, h=h, centre=c, X=X, comp=comp, rho=rho, beta=beta, drive=v)
    return rec


@case
def delay_bessel_antialias_filter_bicycle_pump_470hz(seed):
    """The logger's Bessel anti-aliasing filter under a bicycle pump (unipolar), from the AC-depoled disc at 0 V;
    nothing else is run before it; the handle up (0 V) before the record."""
    rng = _rng(seed, 7)
    dt = 1 / 470
    t, kn, p, top, v = _unipolar(rng, dt, lambda r: s40.bicycle_pump(r, 2))
    D = rng.uniform(2.5, 5.5)
    tf = np.arange(m40.R_FINE * (len(t) - 1) + 1) * dt / m40.R_FINE
    v_fine = top * s40.knots_eval(tf, kn) / p.max()
    core = dict(_disc(rng, unipolar=True), top=top)
    y_fine = _core_of(core, v_fine)
    y = m40.bessel_filter(y_fine, dt / m40.R_FINE, D * dt)[::m40.R_FINE]
    rec = finish("holdout40_delay_bessel_antialias_filter_bicycle_pump_470hz", seed, t, v, y, {"delay"}, "either",
                 f"the logger's fourth-order Bessel anti-aliasing filter ({D:.2f} samples' group delay) under a "
                 f"bicycle pump, to {top:.0f} V, 470 Hz", rng, monitor_noise=2e-4)
    rec.extra.update(core, knots=kn, p=p, D=D, tf=tf, v_fine=v_fine, y_fine=y_fine, drive=v)
    return rec


@case
def initial_state_prepoled_disc_playground_swing_640hz(seed):
    """Left poled by the previous test: a DC field v_p applied to the AC-depoled disc and removed (60 steps each way);
    the record starts there at 0 V, under a playground swing."""
    rng = _rng(seed, 8)
    dt = 1 / 640
    amp = rng.uniform(44.0, 48.0)
    core = dict(_disc(rng), amp=amp)
    rho, sd = rng.uniform(0.6, 0.95), float(rng.choice([-1.0, 1.0]))
    v_p = sd * rho * amp
    s0 = m40.poled_state(core, float(_field(core, v_p)))

    def make():
        bouts, T_end = s40.playground_swing(rng)
        if not _fits(dt, T_end):
            return None
        t = _grid(dt, T_end)
        return s40.bouts_eval(t, bouts), t, bouts
    x, t, bouts = _balanced(make)
    v = _scale(x, amp)
    y = _core_of(core, v, s0=s0)
    rec = finish("holdout40_initial_state_prepoled_disc_playground_swing_640hz", seed, t, v, y, {"initial_state"},
                 "either",
                 f"a disc left poled by the previous test ({v_p:+.0f} V applied and removed) under a playground swing, "
                 f"+-{amp:.0f} V, 640 Hz", rng)
    rec.extra.update(core, rho=rho, side=sd, v_p=v_p, s0=s0, bouts=bouts, x=x, drive=v)
    return rec


# ---- two effects ----

@case
def pair_rate_output_saturation_wall_viscosity_diodes_rowing_ergometer_760hz(seed):
    """The domain walls' viscosity and the logger's input protection diodes under a rowing ergometer, from the
    AC-depoled disc at 0 V; nothing else is run before it."""
    rng = _rng(seed, 9)
    dt = 1 / 760
    x, t, kn = _knotted(rng, dt, lambda r: s40.rowing_ergometer(r, 2))
    amp = rng.uniform(44.0, 48.0)
    v = _scale(x, amp)
    core = dict(_disc(rng), amp=amp)
    tau = rng.uniform(0.009, 0.015)
    hv = _viscous_of(core, v, dt, tau)
    c, X = _stroke(hv)
    comp, rb = rng.uniform(0.10, 0.17), rng.uniform(0.002, 0.01)
    rho, beta = m40.diodes_for(comp, rb)
    y = c + X * m40.diode_reading((hv - c) / X, rho, beta)
    rec = finish("holdout40_pair_rate_output_saturation_wall_viscosity_diodes_rowing_ergometer_760hz", seed, t, v, y,
                 {"rate_dependence", "output_saturation"}, "either",
                 f"the domain walls' viscosity (tau {tau * 1e3:.1f} ms) and the logger's input protection diodes (the "
                 f"ends compressed by {comp:.0%}) under a rowing ergometer, +-{amp:.0f} V, 760 Hz", rng)
    rec.extra.update(core, knots=kn, x=x, tau=tau, hv=hv, centre=c, X=X, comp=comp, rho=rho, beta=beta, drive=v)
    return rec


# ---- out of vocabulary ----

@case
def oov_aliased_switcher_ripple_cat_tail_995hz(seed):
    """The high-voltage amplifier's switching ripple, aliased by the logger, under a cat's tail, from the AC-depoled
    disc at 0 V; nothing else is run before it."""
    rng = _rng(seed, 10)
    dt = 1 / 995
    x, t, kn = _knotted(rng, dt, lambda r: s40.cat_tail(r, int(r.integers(4, 7))))
    amp = rng.uniform(44.0, 48.0)
    v = _scale(x, amp)
    core = dict(_disc(rng), amp=amp)
    h = _core_of(core, v)
    f0, df = rng.uniform(24.0, 40.0), rng.uniform(0.6, 1.5)
    tau_w, v_rail = rng.uniform(20.0, 40.0), rng.uniform(1.25, 1.5) * amp
    phase = rng.uniform(0.0, 2 * math.pi)
    share = rng.uniform(0.035, 0.06)
    ripple = share * np.ptp(h) * m40.aliased_ripple(t, v, f0, df, tau_w, v_rail, phase)
    off = rng.uniform(-2.0, 2.0)
    y = h + ripple + off
    rec = finish("holdout40_oov_aliased_switcher_ripple_cat_tail_995hz", seed, t, v, y, set(), "unexplained",
                 f"the high-voltage amplifier's switching ripple aliased to {f0:.1f} Hz (drifting by {df:.1f} Hz; "
                 f"{share:.1%} of the span at 0 V) under a cat's tail, +-{amp:.0f} V, 995 Hz", rng)
    rec.extra.update(core, knots=kn, x=x, h=h, f0=f0, df=df, tau_w=tau_w, v_rail=v_rail, phase=phase, share=share,
                     ripple=ripple, offset=off, drive=v)
    return rec

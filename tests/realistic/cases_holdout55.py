"""The HOLDOUT55 set: written after HOLDOUT54 was measured, by a session that did not read how the diagnosis decides,
and run once for round 57's measurement (16 of 30 runs right on commit 58bc36b); part of ALL since.

Mechanisms and signals that the other sets do not have (the laws are in :mod:`.mechanisms55`, the signals in
:mod:`.signals55`, each beside its source; the citations were written from memory, as they say). Every core is a
ferroelectric-polymer unimorph: a silicon cantilever (2 mm long, 10 um thick) carrying a spin-cast film of the
copolymer P(VDF-TrFE) 70/30, 2 um thick, poled, its tip read by a fibre-optic displacement sensor (nm, zeroed at the
start of every record). The drive sets the film's field (v / 2 um, +-23 MV/m; on the unipolar records the bottom
electrode sits at 47 V). The film's crystallites are single domains, each a relay of the field between its up
threshold E_c - E_b and its down one -E_c - E_b: 4000 classes of soft crystallites (a share 4.5 ... 5.5 % of the film:
coercive fields log-normal, median 6.5 ... 7.5 MV/m; internal fields normal, spread 30 ... 34 MV/m, the trapped
charge's) that the drive switches, and 500 classes of hard ones (coercive fields about 105 MV/m) that hold the film's
remanent polarisation. The polarisation P = P_X m + eps_0 chi E stretches the film electrostrictively (Q P^2) and
Stoney's law bends the beam. Rate independent, with return-point memory; close to a Prandtl-Ishlinskii model but not one
(measured in tests/test_realistic_holdout55.py: a PI model of 12 plays of the drive fitted by NNLS, stated there). The
stroke is about 3 um over +-46 V. Every record but the initial-state case's starts at 0 V of drive from the rest state
the controller's conditioning routine leaves there (after the factory's poling, a slowly decaying cycling of the field
about 0 from the amplifier's swing: every crystallite up that it cannot switch down, down every other that it cannot
switch up, the rest up where their loop's middle lies below 0; then the field brought to the drive's 0 V; the state is
set so, not run), for unipolar and bipolar records alike; nothing else is run before a record.

- a clean core under a fly fisher's cast (the false casts, the presentation, the drift), +-44 ... 48 V, with a noisy
  input monitor, sampled at 1.381 kHz;
- creep from the film's slow interfacial (Maxwell-Wagner) polarisation: ionic residues drifting under the field, a box
  distribution of Debye times from 0.3 to 40 s, its permittivity rising by 6 ... 9; under a barista's tamper, on a
  unipolar stroke, sampled at 227 Hz;
- rate dependence from the cantilever working in silicone oil: overdamped, its tip lagging its quasi-static bend (tau
  20 ... 32 ms); under an orchestra conductor's baton (never still), +-44 ... 48 V, with a noisy input monitor, sampled
  at 1.597 kHz;
- a drift from the room's thermostat: a bang-bang heating's limit cycle (a dead band of 0.8 ... 1.2 K), the beam's
  holder following it (tau 25 ... 40 s) and the film's thermal mismatch with the silicon bending the beam; under a bell
  ringer's rope, on a unipolar stroke, sampled at 211 Hz;
- asymmetry from the tip resting on a micropump's pre-tensioned silicone membrane: pushed as the beam bends up (the
  membrane's linear and cubic force), left as it bends down; under a rower's stroke, +-44 ... 48 V, sampled at 863 Hz;
- saturation from silicone end stops in a slot (Hertz contact of the tip's ruby ball, 0.55 ... 0.7 of the free reach
  each way); under a windscreen wiper, +-44 ... 48 V, with a noisy input monitor, sampled at 1.019 kHz;
- a delay of a wireless link (the command sampled every 7.5 ms and played out 60 ... 90 ms later at the rig's DAC);
  under a blacksmith's bellows, on a unipolar stroke, sampled at 557 Hz;
- a film in another state at the start: straight from the factory's poling (every crystallite up) without the
  conditioning; under an archer's draw (the stance and nocking first), +-44 ... 48 V, sampled at 677 Hz;
- two effects: the clamp's cyanoacrylate bond creeping logarithmically under the bending moment (labelled "creep") and
  the film's alpha_c relaxation, a standard linear solid that stiffens it on quick moves (tau 30 ... 45 ms; labelled
  "rate_dependence"); under a kayaker's paddle, +-44 ... 48 V, sampled at 409 Hz;
- out of vocabulary: a film spun too thin (0.25 um instead of 2): the same drive switches every crystallite through,
  the polarisation changes sign and the electrostrictive strain folds into a butterfly; under a violinist's bow,
  +-44 ... 48 V, sampled at 1.213 kHz.

Every bipolar drive is drawn until its weaker side reaches 0.85 of its stronger (a test programme's balance). The
effects' sizes beyond a gain and an offset on the core (seeds 0 ... 2; RMS and largest) are stated in the test.
"""

import numpy as np

from . import mechanisms55 as m55
from . import signals55 as s55
from . import set_tools
from .record import case_set, finish

HOLDOUT55, case, _rng = case_set("holdout55_", 55000)


def _film(rng, unipolar=False):
    """The core: the crystallites' seed (the Kronecker sequence's shift), the soft crystallites' share fs, their
    coercive fields' median E50 (MV/m), their internal fields' mean Ebm and spread sb (MV/m)."""
    return dict(rseed=int(rng.integers(0, 2**31 - 2)), fs=rng.uniform(0.045, 0.055), E50=rng.uniform(6.5, 7.5),
                Ebm=rng.uniform(0.5, 1.5), sb=rng.uniform(30.0, 34.0), unipolar=unipolar)


def _bipolar(rng, dt, gen):
    return set_tools.bipolar(rng, dt, gen, s55.knots_at)


def _unipolar(rng, dt, gen):
    return set_tools.unipolar(rng, dt, gen, s55.knots_at)


def _note(core):
    return (f"a P(VDF-TrFE) unimorph ({core['fs']:.1%} soft crystallites, E_c {core['E50']:.1f} MV/m, internal fields "
            f"{core['Ebm']:.1f} +- {core['sb']:.0f} MV/m)")


# ---- clean ----

@case
def clean_pvdf_trfe_unimorph_fly_cast_1381hz(seed):
    """A clean core under a fly fisher's cast, from the rest state at 0 V; nothing else is run before it."""
    rng = _rng(seed, 1)
    dt = 1 / 1381
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s55.fly_cast(r, 2))
    core = dict(_film(rng), amp=amp)
    y = m55.core_reading(core, v)
    rec = finish("holdout55_clean_pvdf_trfe_unimorph_fly_cast_1381hz", seed, t, v, y, set(), "explained",
                 f"a clean core ({_note(core)}) under a fly fisher's cast ({len(kn)} knots), +-{amp:.0f} V, 1.381 kHz",
                 rng, monitor_noise=2e-4)
    rec.extra.update(core, knots=kn, x=x, drive=v)
    return rec


# ---- one effect ----

@case
def creep_maxwell_wagner_polarisation_barista_tamp_227hz(seed):
    """The film's slow interfacial polarisation under a barista's tamper (unipolar), from the rest state at 0 V (the
    ions long settled there); nothing else is run before it."""
    rng = _rng(seed, 2)
    dt = 1 / 227
    t, kn, p, top, v = _unipolar(rng, dt, lambda r: s55.barista_tamp(r, 3))
    core = dict(_film(rng, unipolar=True), top=top)
    dchi = rng.uniform(6.0, 9.0)
    E = m55.field(core, v)
    m = m55.switched_share(core, E)
    P_mw = m55.mw_polarisation(E, dt, dchi)
    y = m55.reading(m55.polarisation(E, m, P_mw))
    rec = finish("holdout55_creep_maxwell_wagner_polarisation_barista_tamp_227hz", seed, t, v, y, {"creep"}, "either",
                 f"the film's slow Maxwell-Wagner polarisation (its permittivity rising by {dchi:.1f} over 0.3 ... 40 "
                 f"s) under a barista's tamper, to {top:.0f} V, 227 Hz", rng)
    rec.extra.update(core, knots=kn, p=p, dchi=dchi, P_mw=P_mw, m=m, drive=v)
    return rec


@case
def rate_silicone_oil_drag_conductor_baton_1597hz(seed):
    """The cantilever overdamped in silicone oil under a conductor's baton, from the rest state at 0 V (the tip long
    at rest); nothing else is run before it."""
    rng = _rng(seed, 3)
    dt = 1 / 1597
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s55.conductor(r, 10))
    core = dict(_film(rng), amp=amp)
    tau = rng.uniform(0.02, 0.032)
    h = m55.core_reading(core, v)
    y = m55.lag(h, dt, tau, 0.0)
    rec = finish("holdout55_rate_silicone_oil_drag_conductor_baton_1597hz", seed, t, v, y, {"rate_dependence"},
                 "either",
                 f"the cantilever overdamped in silicone oil (tau {tau * 1e3:.1f} ms) under a conductor's baton, "
                 f"+-{amp:.0f} V, 1.597 kHz", rng, monitor_noise=3e-4)
    rec.extra.update(core, knots=kn, x=x, tau=tau, h=h, drive=v)
    return rec


@case
def drift_room_thermostat_bimorph_bell_ringer_211hz(seed):
    """The room's thermostat cycling under a bell ringer's rope (unipolar), from the rest state at 0 V (the room long
    in its cycle); nothing else is run before it."""
    rng = _rng(seed, 4)
    dt = 1 / 211
    t, kn, p, top, v = _unipolar(rng, dt, lambda r: s55.bell_ringer(r, 4))
    core = dict(_film(rng, unipolar=True), top=top)
    db, dT_on, dT_off = rng.uniform(0.8, 1.2), rng.uniform(3.0, 5.0), rng.uniform(3.0, 5.0)
    tau_r, tau_h, phase = rng.uniform(300.0, 500.0), rng.uniform(25.0, 40.0), rng.uniform(0.0, 1.0)
    T_set = 21.0
    T_on, T_off = T_set + dT_on, T_set - dT_off
    times, temps, ons = m55.thermostat(t[-1], 600.0, T_set, db, T_on, T_off, tau_r, phase)
    Th = m55.holder_temperature(t, times, temps, ons, T_on, T_off, tau_r, tau_h)
    E = m55.field(core, v)
    P = m55.polarisation(E, m55.switched_share(core, E))
    h = m55.reading(P)
    y = m55.reading(P, (m55.ALPHA_F - m55.ALPHA_S) * (Th - Th[0]))
    rec = finish("holdout55_drift_room_thermostat_bimorph_bell_ringer_211hz", seed, t, v, y, {"drift"}, "either",
                 f"the room's thermostat (dead band {db:.2f} K, the room's tau {tau_r:.0f} s: the holder "
                 f"{np.ptp(Th) * 1e3:.0f} mK over the record) under a bell ringer's rope, to {top:.0f} V, 211 Hz", rng)
    rec.extra.update(core, knots=kn, p=p, db=db, T_on=T_on, T_off=T_off, tau_r=tau_r, tau_h=tau_h, phase=phase,
                     times=times, temps=temps, ons=ons, Th=Th, h=h, drive=v)
    return rec


@case
def asymmetry_micropump_membrane_rowing_stroke_863hz(seed):
    """The tip on a micropump's membrane under a rower's stroke, from the rest state at 0 V (the tip just touching the
    membrane there); nothing else is run before it."""
    rng = _rng(seed, 5)
    dt = 1 / 863
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s55.rowing(r, 2))
    core = dict(_film(rng), amp=amp)
    r1, r3 = rng.uniform(0.5, 0.8), rng.uniform(0.3, 0.5)
    ws = m55.core_reading(core, v)
    W = float(ws.max())
    k3 = r3 / W ** 2
    y = m55.membrane_contact(ws, r1, k3)
    rec = finish("holdout55_asymmetry_micropump_membrane_rowing_stroke_863hz", seed, t, v, y, {"asymmetry"}, "either",
                 f"the tip pushing a micropump's membrane as it rises (k_1 / k {r1:.2f}, the cubic {r3:.2f} at the "
                 f"free reach {W:.0f} nm) under a rower's stroke, +-{amp:.0f} V, 863 Hz", rng)
    rec.extra.update(core, knots=kn, x=x, r1=r1, r3=r3, W=W, k3=k3, ws=ws, drive=v)
    return rec


@case
def saturation_silicone_end_stops_wiper_1019hz(seed):
    """The tip between silicone end stops under a windscreen wiper, from the rest state at 0 V; nothing else is run
    before it."""
    rng = _rng(seed, 6)
    dt = 1 / 1019
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s55.wiper(r, 3))
    core = dict(_film(rng), amp=amp)
    f_up, f_dn, kh = rng.uniform(0.55, 0.7), rng.uniform(0.55, 0.7), rng.uniform(0.3, 0.5)
    ws = m55.core_reading(core, v)
    g_up, g_dn = f_up * float(ws.max()), f_dn * float(-ws.min())
    y = m55.two_stops(ws, g_up, g_dn, kh)
    rec = finish("holdout55_saturation_silicone_end_stops_wiper_1019hz", seed, t, v, y, {"saturation"}, "either",
                 f"silicone end stops at +{g_up:.0f} / -{g_dn:.0f} nm ({f_up:.0%} / {f_dn:.0%} of the free reach, "
                 f"K_H / k {kh:.2f} nm^-1/2) under a windscreen wiper, +-{amp:.0f} V, 1.019 kHz", rng,
                 monitor_noise=2.5e-4)
    rec.extra.update(core, knots=kn, x=x, f_up=f_up, f_dn=f_dn, kh=kh, g_up=g_up, g_dn=g_dn, ws=ws, drive=v)
    return rec


@case
def delay_wireless_link_latency_bellows_557hz(seed):
    """A wireless link's latency between the host and the rig's amplifier under a blacksmith's bellows (unipolar), from
    the rest state at 0 V; nothing else is run before it."""
    rng = _rng(seed, 7)
    dt = 1 / 557
    t, kn, p, top, v = _unipolar(rng, dt, lambda r: s55.bellows(r, 3))
    core = dict(_film(rng, unipolar=True), top=top)
    D, phase = rng.uniform(0.06, 0.09), rng.uniform(0.0, m55.P_LINK)
    pmax = float(p.max())
    v_node, tk = m55.link_drive(t, lambda tt: top * s55.knots_at(tt, kn) / pmax, D, phase)
    y = m55.core_reading(core, v_node)
    rec = finish("holdout55_delay_wireless_link_latency_bellows_557hz", seed, t, v, y, {"delay"}, "either",
                 f"a wireless link's latency ({D * 1e3:.0f} ms, packets every 7.5 ms) under a blacksmith's bellows, "
                 f"to {top:.0f} V, 557 Hz", rng, monitor_noise=3e-4)
    rec.extra.update(core, knots=kn, p=p, D=D, phase=phase, v_node=v_node, drive=v)
    return rec


@case
def initial_state_factory_poling_archer_677hz(seed):
    """A film straight from the factory's poling, without the conditioning, under an archer's draw (the stance and the
    nocking first)."""
    rng = _rng(seed, 8)
    dt = 1 / 677
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s55.archer(r, 4, 14.0))
    core = dict(_film(rng), amp=amp)
    a, b, w = m55.crystallites(core)
    s = np.ones(len(a))
    s0 = s.copy()
    y = m55.core_reading(core, v, s)
    n_off = int(np.sum(s0 != m55.rest_state(core, 0.0)))
    rec = finish("holdout55_initial_state_factory_poling_archer_677hz", seed, t, v, y, {"initial_state"}, "either",
                 f"a film straight from the factory's poling ({n_off} of {len(a)} crystallite classes up that the "
                 f"conditioning leaves down) under an archer's draw, +-{amp:.0f} V, 677 Hz", rng)
    rec.extra.update(core, s0=s0, n_off=n_off, knots=kn, x=x, drive=v)
    return rec


# ---- two effects ----

@case
def pair_creep_rate_clamp_log_creep_alpha_c_kayak_409hz(seed):
    """The clamp's bond creeping ("creep") and the film's alpha_c relaxation ("rate_dependence") under a kayaker's
    paddle, from the rest state at 0 V (the bond long at rest); nothing else is run before it."""
    rng = _rng(seed, 9)
    dt = 1 / 409
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s55.kayak(r, 3))
    core = dict(_film(rng), amp=amp)
    ra, tau_a = rng.uniform(0.6, 0.8), rng.uniform(0.03, 0.045)
    c1, tau0 = rng.uniform(0.055, 0.07), rng.uniform(0.5, 1.0)
    ws = m55.core_reading(core, v)
    mb = m55.alpha_c_bend(ws, dt, ra, tau_a)
    y = mb + m55.hereditary(mb, m55.log_creep_kernel(len(t), dt, c1, tau0))
    rec = finish("holdout55_pair_creep_rate_clamp_log_creep_alpha_c_kayak_409hz", seed, t, v, y,
                 {"creep", "rate_dependence"}, "either",
                 f"the clamp's bond creeping (c_1 {c1:.3f} ln(1 + t / {tau0:.2f} s)) and the film's alpha_c "
                 f"relaxation ({ra:.2f}, tau {tau_a * 1e3:.0f} ms) under a kayaker's paddle, +-{amp:.0f} V, 409 Hz",
                 rng)
    rec.extra.update(core, knots=kn, x=x, ra=ra, tau_a=tau_a, c1=c1, tau0=tau0, ws=ws, mb=mb, drive=v)
    return rec


# ---- out of vocabulary ----

@case
def oov_thin_film_butterfly_violin_bow_1213hz(seed):
    """A film spun too thin (0.25 um), switched through by the drive: the butterfly, under a violinist's bow, from the
    rest state at 0 V; nothing else is run before it."""
    rng = _rng(seed, 10)
    dt = 1 / 1213
    x, t, kn, amp, v = _bipolar(rng, dt, lambda r: s55.violin_bow(r, 2))
    core = dict(_film(rng), amp=amp)
    y = m55.core_reading(core, v, t_film=THIN)
    rec = finish("holdout55_oov_thin_film_butterfly_violin_bow_1213hz", seed, t, v, y, set(), "unexplained",
                 f"a film spun {THIN} um thin, switched through (the butterfly) under a violinist's bow, "
                 f"+-{amp:.0f} V, 1.213 kHz", rng)
    rec.extra.update(core, knots=kn, x=x, t_film=THIN, drive=v)
    return rec


#: the out-of-vocabulary case's film thickness (um)
THIN = 0.25

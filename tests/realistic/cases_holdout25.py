"""The HOLDOUT25 set: written after HOLDOUT24 was measured, by a session that did not read how the diagnosis decides,
to be run once for the next round's measurement; kept out of ALL until then.

Mechanisms and signals that the other sets do not have (the laws are in :mod:`.mechanisms25`, the signals in
:mod:`.signals25`, each beside its source; the citations were written from memory, as they say):

- a clean core (100 plays with the Fermi-Dirac occupation as the density of thresholds, 1 / (exp((r - mu) / kT) + 1),
  mu 12 ... 22 V, kT 1.5 ... 4 V, on 0 ... 40 ... 46 V: a smeared step, the low thresholds all populated alike; a drawn
  linear part, gain and offset) under the x of a chaotic Henon-Heiles orbit (a star in a galaxy's meridian plane, E
  0.135 ... 0.16, below the escape energy 1/6; its small oscillations at 0.8 ... 1.2 Hz), centred, faded in from 0 V
  over 1 s, to peaks of +-44 ... 48 V, with a noisy input monitor, sampled at 1.76 kHz;
- creep of the stage's polymer-concrete base by the ACI 209 (Branson) law t^psi / (d + t^psi) (psi 0.5 ... 0.7, half
  the final creep after tau0 = d^(1 / psi) = 3 ... 10 s: a power law at first, an algebraic approach to the end), 8 ...
  12 % of the core's output after 10 s of a held load, by Boltzmann superposition (exact for a load linear between
  samples, an FFT convolution); under a weighbridge's day (6 ... 8 trucks of 2 ... 5 axles 0.3 ... 1.1 s apart, each
  axle's load rising over 0.15 ... 0.3 s as its tyres cross the plate's edge, every truck standing 6 ... 12 s to be
  weighed, the heaviest to 88 ... 97 V, the others 0.3 ... 0.9 of it, the plate empty 3 ... 6 s between), on a
  unipolar stroke, sampled at 225 Hz;
- rate dependence from a piston damper whose oil is compressible beside the stage's flexure (the oil a spring in series
  with the annular gap's dashpot: Zener's standard linear solid, the fast travel 1 / (1.2 ... 1.4) of the slow, tau 2
  ... 5 ms, a relaxation time tau (1 + rho) between); under a cricket's calling song (chirps of 3 ... 5 syllables, each
  a Hann-windowed tone at 24 ... 34 Hz of 0.09 ... 0.13 s, the chirp rate by Dolbear's law as the evening cools from 24
  ... 27 C to 16 ... 19 C, played 1.6 ... 2.2 times slower; each chirp 0.7 ... 1 of +-44 ... 48 V, either sign), with
  a noisy input monitor, sampled at 1.91 kHz;
- an offset drift of a Hall sensor whose axis turns with the indexing table it stands on, reading the Earth's
  horizontal field along it (b_h cos(az - az_field); 3 ... 5 moves of 45 ... 180 degrees either way at least 8 s apart,
  trapezoidal speeds of 30 ... 60 deg/s and 60 ... 120 deg/s^2), 4 ... 8 % of the span at its largest, either sign;
  under a typewriter's carriage (from the centre, 0 V, to the margin at -44 ... -48 V; 6 ... 8 lines of 28 ... 40 keys,
  each escaping one pitch over 20 ... 35 ms, 0.08 ... 0.16 s between keys and 0.25 ... 0.5 s at the word breaks; the
  longest line to the opposite side, each returned over 0.35 ... 0.6 s), with a noisy input monitor, sampled at 580 Hz;
- asymmetry of an eddy-current probe over the conducting target the stage carries (the target a mirror: the coil's
  image 2 g away, the inductance L0 - M(2 g) by Maxwell's elliptic-integral formula for coaxial loops; the gap 0.4 ...
  0.8 of the coil's radius at rest; convex, the ends' secants 10 ... 17 % apart, on a drawn side); under a trombone's
  slide (30 ... 45 notes on positions 1 ... 7, each a semitone lower, the extension (2^((p - 1) / 12) - 1) / 2 of a 2.7
  m tube; shifts of 60 ... 120 ms, notes of 0.25 ... 0.8 s; from half its travel, 0 V, to +-44 ... 48 V at positions 1
  and 7), sampled at 1.11 kHz;
- saturation of a load cell weighing the buoyancy of a horizontal rod that the stage dips about half immersion
  (Archimedes: the circular segment's area, its slope the waterline's width sqrt(1 - u^2); odd, the ends compressed by
  12 ... 20 %); under a Brusselator (a 1 ... 1.5) whose feed B is raised from 0.4 below its Hopf point 1 + a^2 to 1 ...
  1.6 above it and lowered back (the oscillation born late, growing into relaxation spikes and dying away; 0.9 ... 1.3
  Hz near the Hopf point), centred, faded in from 0 V over 1 s, +-44 ... 48 V, sampled at 680 Hz;
- a delay of an asynchronous sample-rate converter (the sensor's ADC on its own crystal 20 ... 100 ppm off, its samples
  re-timed to the logger's ticks by a cubic Lagrange, Farrow, interpolator 2.3 ... 4.6 samples back: a delay that
  passes cubics exactly), the core computed on a 4x finer grid; under 5 ... 7 metronomes of 1.3 ... 1.8 Hz (+-4 %) on a
  board (Kuramoto's model: held, they beat; released at 0.15 ... 0.25 of the record, coupling 2 ... 3 rad/s, they
  synchronise; caught again at 0.7 ... 0.8, they drift apart), the board's swing the mean of their sin(theta), faded in,
  +-44 ... 48 V, with a noisy input monitor, sampled at 495 Hz;
- a core left by a 12-bit DAC's power-on self-test (from the virgin state at 0 V: walking ones up to half scale, all
  ones, 100 V, walking zeros down to just below half, the checkerboards 33.3 and 66.7 V, mid-scale 50.0 V), the record
  starting there; then a spirometry session (tidal breaths 10 ... 16 V above the functional residual capacity at 50 V,
  1.2 ... 1.7 s each, a sigh of 20 ... 27 V, more breaths; from about the middle on, two forced vital capacities: a
  slow inspiration to 88 ... 97 V, the forced expiration of a one-compartment lung, tau 0.35 ... 0.6 s, towards 4 ...
  10 V, a return), on a unipolar stroke, sampled at 870 Hz;
- two effects: a core left by a Robbins-Monro search (a first guess at 84 ... 90 V reached from 0 V, then 10 ... 14
  noisy steps of 0.7 ... 1 / n towards 30 ... 42 V, the measurement's noise 6 ... 10 V), the record starting at its
  last iterate, read through a neutral-density wedge the stage slides across a beam (Beer-Lambert: (exp(kappa x) - 1)
  / kappa, convex, the ends' secants 10 ... 17 % apart, on a drawn side); under the left ventricle's volume through a
  stress test (Wiggers's beat: isovolumic phases, ejection, rapid filling, diastasis, the atrial kick; 4 ... 5 stages
  of 4 ... 6 s, the beat shortening from 0.55 ... 0.65 s by up to 45 %, the end-diastolic volume rising from the start
  to 93 ... 98 V, beyond the history's top late in the record, the stroke from 16 ... 22 V to 61 ... 67 V; a recovery),
  on a unipolar stroke, sampled at 1.04 kHz;
- out of vocabulary: a clamped-clamped beam on the stage whose mid-plane stretching hardens its spring (its first mode
  q'' + 2 zeta w0 q' + w0^2 (q + q^3) = w0^2 F u, damping 2 ... 3 %, forced by the core's output u, its linear peak 0.6
  ... 0.8), the sensor seeing its deflection (4 ... 7 % of the span on the upper branch) beside the stage's travel;
  under a tone of +-44 ... 48 V faded in at 0.75 of the beam's frequency, swept up over 10 ... 14 s to a frequency of an
  exact 110 ... 145 samples a period (2.4 ... 3.2 Hz) inside the band between the jumps (0.3 ... 0.45 of the way from
  the jump up to the jump down, by harmonic balance), held 18 ... 24 periods, swept on past the jump down, then down
  again to the same tone (the glide's length set so that the tone returns on the same samples) and held as long, swept
  down and faded out, sampled at 350 Hz. In both holds the input is the same sample for sample and so is the core;
  the beam rides its upper branch in the first (reached from below) and its lower one in the second (reached from
  above), so the output differs between them by many noise levels beyond any gain and offset. A PI core (any plays
  with non-negative weights and any linear part) draws the same output for the same input from the same state;
  saturation and asymmetry are maps of it; rate dependence and delay are stable causal filters of it (a periodic input
  gives one periodic output, whatever came before); creep settles, and creep, drift and gain drift are slow and smooth
  in time (a gain and an offset between the holds at most); an initial state is forgotten after the first period.
"""

import math

import numpy as np
from scipy.optimize import brentq

from . import mechanisms25 as m25
from . import signals25 as s25
from .record import case_set, finish

HOLDOUT25, case, _rng = case_set("holdout25_", 25000)


def _core(rng, v, r_max=45.0, n=80):
    """The other cases' core: n exponentially weighted plays to r_max, a drawn linear part and gain."""
    w0 = rng.uniform(0.3, 0.45)
    r, weights = m25.exp_plays(n, r_max, rng.uniform(8.0, 16.0), w0)
    gain = rng.uniform(0.7, 1.4)
    return gain * m25.plays(v, r, weights, w0), dict(thresholds=r, weights=weights, linear=w0, gain=gain)


# ---- clean ----

@case
def clean_fermi_dirac_plays_henon_heiles_orbit_1760hz(seed):
    rng = _rng(seed, 1)
    dt = 1 / 1760
    n = int(rng.uniform(12.0, 16.0) / dt)
    t = np.arange(n) * dt
    E, y0, angle = rng.uniform(0.135, 0.16), rng.uniform(-0.1, 0.1), rng.uniform(0, 2 * np.pi)
    units = 2 * np.pi * rng.uniform(0.8, 1.2)
    start = s25.henon_heiles_start(E, y0, angle)
    x, _ = s25.henon_heiles_x(t, units, start)
    xc = x - (x.max() + x.min()) / 2
    fade = m25.raised_cosine(t / 1.0)
    amp = rng.uniform(44.0, 48.0)
    scale = amp / np.abs(fade * xc).max()
    v = scale * fade * xc
    r_max, mu, kT = rng.uniform(40.0, 46.0), rng.uniform(12.0, 22.0), rng.uniform(1.5, 4.0)
    w0 = rng.uniform(0.25, 0.4)
    r, weights = m25.fermi_dirac_plays(100, r_max, mu, kT, w0)
    gain, off = rng.uniform(0.7, 1.4), rng.uniform(-4.0, 4.0)
    y = gain * m25.plays(v, r, weights, w0) + off
    rec = finish("holdout25_clean_fermi_dirac_plays_henon_heiles_orbit_1760hz", seed, t, v, y, set(), "explained",
                 f"a clean core (100 plays, the Fermi-Dirac density of thresholds, mu {mu:.1f} V, kT {kT:.1f} V, on 0 "
                 f"... {r_max:.0f} V) under a Henon-Heiles orbit (E {E:.3f}), faded in from 0 V, +-{amp:.0f} V, "
                 f"1.76 kHz", rng, monitor_noise=3e-4)
    rec.extra.update(thresholds=r, weights=gain * weights, linear=gain * w0, offset=off, r_max=r_max, mu=mu, kT=kT,
                     E=E, start=start, units=units, x=x, xc=xc, scale=scale, amp=amp, drive=v)
    return rec


# ---- one effect ----

@case
def creep_aci209_polymer_concrete_base_weighbridge_axles_225hz(seed):
    rng = _rng(seed, 2)
    dt = 1 / 225
    top = rng.uniform(88.0, 97.0)
    n_tr = int(rng.integers(6, 9))
    heavy = int(rng.integers(1, n_tr - 1))
    ramp = rng.uniform(0.15, 0.3)
    trucks, tc = [], rng.uniform(1.5, 3.0)
    for k in range(n_tr):
        n_ax = int(rng.integers(2, 6))
        gaps = np.r_[0.0, np.cumsum(rng.uniform(0.3, 1.1, n_ax - 1))]
        share = rng.dirichlet(np.full(n_ax, 4.0))
        total = top if k == heavy else top * rng.uniform(0.3, 0.9)
        hold = rng.uniform(6.0, 12.0)
        t_on = tc
        t_off = t_on + gaps[-1] + ramp + hold
        trucks.append((t_on, t_off, gaps, total * share))
        tc = t_off + gaps[-1] + ramp + rng.uniform(3.0, 6.0)
    n = int((tc + rng.uniform(1.0, 2.0)) / dt)
    t = np.arange(n) * dt
    v = s25.weighbridge(t, trucks, ramp)
    h, core = _core(rng, v)
    c, tau0, psi = rng.uniform(0.08, 0.12), rng.uniform(3.0, 10.0), rng.uniform(0.5, 0.7)
    cr = m25.aci_creep(h, dt, c, tau0, psi, 10.0)
    rec = finish("holdout25_creep_aci209_polymer_concrete_base_weighbridge_axles_225hz", seed, t, v, h + cr,
                 {"creep"}, "either",
                 f"creep of a polymer-concrete base by the ACI 209 law ({c:.1%} after 10 s, half its end after "
                 f"{tau0:.1f} s, psi {psi:.2f}) under {n_tr} trucks on a weighbridge, the heaviest {top:.0f} V, 225 Hz",
                 rng)
    rec.extra.update(core, top=top, trucks=trucks, ramp=ramp, h=h, c=c, tau0=tau0, psi=psi, creep=cr)
    return rec


@case
def rate_compressible_oil_damper_zener_cricket_song_1910hz(seed):
    rng = _rng(seed, 3)
    dt = 1 / 1910
    amp = rng.uniform(44.0, 48.0)
    T_rec = rng.uniform(9.0, 13.0)
    t_hot, t_cold = rng.uniform(24.0, 27.0), rng.uniform(16.0, 19.0)
    slow = rng.uniform(1.6, 2.2)
    n_syl, syl, gap = int(rng.integers(3, 6)), rng.uniform(0.09, 0.13), rng.uniform(0.03, 0.05)
    carrier = rng.uniform(24.0, 34.0)

    def temp(s):
        return t_hot + (t_cold - t_hot) * s / T_rec
    starts = s25.chirp_times(rng.uniform(0.4, 0.8), T_rec - 1.0 - n_syl * (syl + gap), temp, slow)
    amps = rng.uniform(0.7, 1.0, len(starts)) * rng.choice([-1.0, 1.0], len(starts))
    amps[int(rng.integers(0, len(starts)))] = 1.0
    chirps = list(zip(starts, amps))
    n = int(T_rec / dt)
    t = np.arange(n) * dt
    x = s25.cricket_song(t, chirps, carrier, n_syl, syl, gap)
    scale = amp / np.abs(x).max()
    v = scale * x
    tau, rho = rng.uniform(2.0, 5.0) * 1e-3, rng.uniform(0.2, 0.4)
    v_z = m25.zener_response(v, dt, tau, rho)
    h, core = _core(rng, v_z)
    rec = finish("holdout25_rate_compressible_oil_damper_zener_cricket_song_1910hz", seed, t, v, h,
                 {"rate_dependence"}, "either",
                 f"a damper of compressible oil beside the flexure (Zener's solid: tau {tau * 1e3:.1f} ms, the fast "
                 f"travel 1 / {1 + rho:.2f} of the slow) under {len(chirps)} chirps of a cricket ({n_syl} syllables at "
                 f"{carrier:.0f} Hz, Dolbear's law from {t_hot:.0f} to {t_cold:.0f} C), +-{amp:.0f} V, 1.91 kHz", rng,
                 monitor_noise=2.5e-4)
    rec.extra.update(core, amp=amp, chirps=chirps, carrier=carrier, n_syl=n_syl, syl=syl, gap=gap, slow=slow,
                     t_hot=t_hot, t_cold=t_cold, T_rec=T_rec, scale=scale, tau=tau, rho=rho, v_z=v_z, h=h, drive=v)
    return rec


@case
def drift_geomagnetic_hall_indexing_table_typewriter_580hz(seed):
    rng = _rng(seed, 4)
    dt = 1 / 580
    amp = rng.uniform(44.0, 48.0)
    n_lines = int(rng.integers(6, 9))
    keys_per = rng.integers(28, 41, n_lines)
    keys_per[int(rng.integers(0, n_lines))] = 40
    pitch = 2 * amp / 40
    ramp, ret = rng.uniform(0.02, 0.035), rng.uniform(0.35, 0.6)
    lead = rng.uniform(0.6, 1.0)
    lines, tc = [], lead + rng.uniform(0.4, 0.8)
    for nk in keys_per:
        keys = []
        for j in range(nk):
            keys.append(tc)
            tc += rng.uniform(0.25, 0.5) if rng.uniform() < 0.18 else rng.uniform(0.08, 0.16)
        t_ret = tc + rng.uniform(0.2, 0.5)
        lines.append((keys, t_ret))
        tc = t_ret + ret + rng.uniform(0.5, 1.0)
    n = int((tc + rng.uniform(0.3, 0.6)) / dt)
    t = np.arange(n) * dt
    v = -amp * m25.raised_cosine(t / lead) + s25.typewriter(t, lines, pitch, ramp, ret)
    h, core = _core(rng, v, r_max=42.0)
    T = t[-1]
    vmax, amax = math.radians(rng.uniform(30.0, 60.0)), math.radians(rng.uniform(60.0, 120.0))
    n_mv = int(rng.integers(3, 6))
    t_mv = np.sort(rng.uniform(0.08, 0.85, n_mv)) * T
    t_mv = t_mv[np.r_[True, np.diff(t_mv) > 8.0]]
    moves = [(float(tm), math.radians(rng.uniform(45.0, 180.0)) * rng.choice([-1.0, 1.0])) for tm in t_mv]
    az0, az_field = rng.uniform(0, 2 * np.pi), rng.uniform(0, 2 * np.pi)
    az = s25.indexing_table(t, moves, vmax, amax, az0)
    raw = m25.geomagnetic_offset(az, az_field, 1.0)
    frac, sign = rng.uniform(0.04, 0.08), rng.choice([-1.0, 1.0])
    k = int(np.argmax(np.abs(raw)))
    scale_off = sign * np.sign(raw[k]) * frac * np.ptp(h) / np.abs(raw).max()
    off = scale_off * raw
    rec = finish("holdout25_drift_geomagnetic_hall_indexing_table_typewriter_580hz", seed, t, v, h + off, {"drift"},
                 "either", f"the Earth's field on a Hall sensor carried by an indexing table ({len(moves)} moves; "
                 f"{sign * frac:+.1%} of the span at its largest) under {n_lines} typed lines, +-{amp:.0f} V, 580 Hz",
                 rng, monitor_noise=2e-4)
    rec.extra.update(core, amp=amp, lead=lead, lines=lines, pitch=pitch, ramp=ramp, ret=ret, h=h, moves=moves,
                     vmax=vmax, amax=amax, az0=az0, az_field=az_field, az=az, frac=frac, sign=sign,
                     scale_off=scale_off, offset=off, drive=v)
    return rec


@case
def asymmetry_eddy_current_probe_image_coil_trombone_slide_1110hz(seed):
    rng = _rng(seed, 5)
    dt = 1 / 1110
    amp = rng.uniform(44.0, 48.0)
    tube = 2.7
    n_notes = int(rng.integers(30, 46))
    pos, p = [], int(rng.integers(2, 7))
    for _ in range(n_notes):
        p = int(np.clip(p + rng.integers(-3, 4), 1, 7))
        pos.append(p)
    pos[int(rng.integers(0, 8))] = 1
    pos[int(rng.integers(8, 16))] = 7
    shift = rng.uniform(0.06, 0.12)
    notes, tc = [], rng.uniform(0.5, 0.9)
    for p in pos:
        notes.append((tc, p))
        tc += rng.uniform(0.25, 0.8)
    ext7 = float(s25.slide_extension(7, tube))
    n = int((tc + rng.uniform(0.5, 1.0)) / dt)
    t = np.arange(n) * dt
    x = s25.trombone(t, notes, tube, shift, ext7 / 2)
    v = amp * (2 * x / ext7 - 1)
    w0 = rng.uniform(0.3, 0.45)
    r, weights = m25.exp_plays(80, 42.0, rng.uniform(8.0, 16.0), w0)
    x_core = m25.plays(v, r, weights, w0)
    c = (x_core.max() + x_core.min()) / 2
    X = np.abs(x_core - c).max()
    asym, side = rng.uniform(0.10, 0.17), rng.choice([-1.0, 1.0])
    gap0 = rng.uniform(0.4, 0.8)

    def spread(dg):
        return float(m25.eddy_probe_reading(1.0, gap0, dg) + m25.eddy_probe_reading(-1.0, gap0, dg)) - asym
    dgap = brentq(spread, 1e-3, 0.9 * gap0, xtol=1e-14)
    gain = rng.uniform(0.7, 1.4)
    y = gain * (c + side * X * m25.eddy_probe_reading(side * (x_core - c) / X, gap0, dgap))
    rec = finish("holdout25_asymmetry_eddy_current_probe_image_coil_trombone_slide_1110hz", seed, t, v, y,
                 {"asymmetry"}, "either",
                 f"an eddy-current probe over the target (its image coil; the gap {gap0:.2f} of the coil's radius at "
                 f"rest, closing by up to {dgap:.2f}; the ends' secants {asym:.0%} apart) under a trombone's slide "
                 f"through {n_notes} notes, +-{amp:.0f} V, 1.11 kHz", rng)
    rec.extra.update(notes=notes, tube=tube, shift=shift, ext7=ext7, amp=amp, thresholds=r, weights=weights,
                     linear=w0, core=x_core, centre=c, X=X, asym=asym, side=side, gap0=gap0, dgap=dgap, gain=gain)
    return rec


@case
def saturation_buoyancy_horizontal_rod_brusselator_hopf_680hz(seed):
    rng = _rng(seed, 6)
    dt = 1 / 680
    amp = rng.uniform(44.0, 48.0)
    T_rec = rng.uniform(16.0, 22.0)
    n = int(T_rec / dt)
    t = np.arange(n) * dt
    a = rng.uniform(1.0, 1.5)
    units = 2 * np.pi * rng.uniform(0.9, 1.3) / a
    B_h = 1 + a * a
    U = T_rec * units
    knots = [(0.0, B_h - 0.4), (rng.uniform(0.3, 0.4) * U, B_h + rng.uniform(1.0, 1.6)),
             (rng.uniform(0.6, 0.7) * U, B_h + rng.uniform(0.3, 0.7)), (U, B_h - 0.4)]
    B = s25.feed_schedule(knots)
    start = (a + rng.uniform(0.05, 0.15), (B_h - 0.4) / a)
    x = s25.brusselator_x(t, units, a, B, start)
    xc = x - (x.max() + x.min()) / 2
    fade = m25.raised_cosine(t / 1.0)
    scale = amp / np.abs(fade * xc).max()
    v = scale * fade * xc
    h, core = _core(rng, v, r_max=42.0)
    c = (h.max() + h.min()) / 2
    X = np.abs(h - c).max()
    comp = rng.uniform(0.12, 0.2)
    u_max = brentq(lambda u: float(m25.buoyancy_reading(1.0, u)) - (1 - comp), 1e-3, 1.0, xtol=1e-14)
    y = c + X * m25.buoyancy_reading((h - c) / X, u_max)
    rec = finish("holdout25_saturation_buoyancy_horizontal_rod_brusselator_hopf_680hz", seed, t, v, y,
                 {"saturation"}, "either",
                 f"the buoyancy of a horizontal rod dipped to +-{u_max:.2f} of its radius (the ends compressed by "
                 f"{comp:.0%}) under a Brusselator (a {a:.2f}) fed through its Hopf bifurcation, +-{amp:.0f} V, 680 Hz",
                 rng)
    rec.extra.update(core, amp=amp, a=a, units=units, knots=knots, start=start, x=x, xc=xc, scale=scale, h=h,
                     centre=c, X=X, comp=comp, u_max=u_max)
    return rec


@case
def delay_farrow_lagrange_asrc_metronome_board_495hz(seed):
    rng = _rng(seed, 7)
    dt, sub = 1 / 495, 4
    amp = rng.uniform(44.0, 48.0)
    n_met = int(rng.integers(5, 8))
    f_bar = rng.uniform(1.3, 1.8)
    omega = 2 * np.pi * f_bar * (1 + 0.04 * rng.standard_normal(n_met))
    T_rec = rng.uniform(26.0, 36.0)
    t_rel, t_catch = rng.uniform(0.15, 0.25) * T_rec, rng.uniform(0.7, 0.8) * T_rec
    k_on = rng.uniform(2.0, 3.0)
    K = s25.step_coupling([(t_rel, k_on), (t_catch, -k_on)])
    th0 = rng.uniform(0, 2 * np.pi, n_met)
    n = int(T_rec / dt)
    tf = np.arange((n - 1) * sub + 1) * (dt / sub)
    x, _ = s25.metronomes(tf, omega, K, th0)
    fade = m25.raised_cosine(tf / 1.0)
    scale = amp / np.abs(fade * x).max()
    v_f = scale * fade * x
    v = v_f[::sub]
    t = tf[::sub]
    h_f, core = _core(rng, v_f, r_max=42.0)
    ratio = 1 + rng.uniform(20.0, 100.0) * 1e-6 * rng.choice([-1.0, 1.0])
    phase, D = rng.uniform(0, 1), rng.uniform(2.3, 4.6)
    y = m25.asrc_sensor(t, tf, h_f, ratio, phase, D)
    rec = finish("holdout25_delay_farrow_lagrange_asrc_metronome_board_495hz", seed, t, v, y, {"delay"}, "either",
                 f"an asynchronous sample-rate converter (a cubic Lagrange interpolator {D:.2f} samples back, the "
                 f"sensor's clock {(ratio - 1) * 1e6:+.0f} ppm off) under {n_met} metronomes on a board released and "
                 f"caught ({f_bar:.2f} Hz), +-{amp:.0f} V, 495 Hz", rng, monitor_noise=2e-4)
    rec.extra.update(core, amp=amp, omega=omega, th0=th0, t_rel=t_rel, t_catch=t_catch, k_on=k_on, scale=scale,
                     sub=sub, ratio=ratio, phase=phase, D=D, drive=v)
    return rec


@case
def initial_state_dac_self_test_spirometry_870hz(seed):
    rng = _rng(seed, 8)
    dt = 1 / 870
    w0 = rng.uniform(0.3, 0.45)
    r, weights = m25.exp_plays(80, 40.0, rng.uniform(10.0, 16.0), w0)
    hist = m25.dac_self_test(12, 100.0)
    _, z0 = m25.plays(hist, r, weights, w0, return_state=True)
    frc = float(hist[-1])
    events, tc = [], rng.uniform(0.4, 0.8)

    def breaths(k, lo=10.0, hi=16.0):
        nonlocal tc
        for _ in range(k):
            T = rng.uniform(1.2, 1.7)
            events.append(("breath", tc, T, frc + rng.uniform(lo, hi)))
            tc += T + rng.uniform(0.0, 0.25)
    breaths(int(rng.integers(4, 7)))
    events.append(("breath", tc, 2.6, frc + rng.uniform(20.0, 27.0)))        # a sigh
    tc += 2.6 + rng.uniform(0.2, 0.4)
    breaths(int(rng.integers(3, 6)))
    tops = []
    for _ in range(2):
        tlc, rv = rng.uniform(88.0, 97.0), rng.uniform(4.0, 10.0)
        tops.append(tlc)
        T_in = rng.uniform(1.2, 2.0)
        events.append(("inspire", tc, T_in, tlc))
        tc += T_in + rng.uniform(0.2, 0.5)
        tau_e = rng.uniform(0.35, 0.6)
        events.append(("blast", tc, tau_e, rv))
        tc += rng.uniform(3.0, 4.0)
        T_r = rng.uniform(1.5, 2.2)
        events.append(("return", tc, T_r, frc))
        tc += T_r + rng.uniform(0.2, 0.4)
        breaths(int(rng.integers(1, 3)))
    n = int((tc + rng.uniform(0.5, 1.0)) / dt)
    t = np.arange(n) * dt
    v = s25.spirometry(t, frc, events)
    gain = rng.uniform(0.7, 1.4)
    y = gain * m25.plays(v, r, weights, w0, state=z0)
    rec = finish("holdout25_initial_state_dac_self_test_spirometry_870hz", seed, t, v, y, {"initial_state"},
                 "either", f"a core left by a 12-bit DAC's power-on self-test (walking ones and zeros, checkerboards, "
                 f"mid-scale: the record starting at {frc:.1f} V), then a spirometry session (tidal breaths, a sigh, "
                 f"two forced vital capacities to {max(tops):.0f} V late), 870 Hz", rng)
    rec.extra.update(thresholds=r, weights=weights, linear=w0, gain=gain, history=hist, state=z0, frc=frc,
                     events=events, tops=tops)
    return rec


# ---- two effects ----

@case
def pair_initial_state_asymmetry_robbins_monro_nd_wedge_ventricle_stress_test_1040hz(seed):
    rng = _rng(seed, 9)
    dt = 1 / 1040
    w0 = rng.uniform(0.3, 0.45)
    r, weights = m25.exp_plays(80, 40.0, rng.uniform(10.0, 16.0), w0)
    x0, target = rng.uniform(84.0, 90.0), rng.uniform(30.0, 42.0)
    n_it = int(rng.integers(10, 15))
    iters = m25.robbins_monro(x0, target, 1.0, rng.uniform(0.7, 1.0), rng.normal(0, rng.uniform(6.0, 10.0), n_it),
                              n_it, lo=5.0, hi=95.0)
    hist = np.r_[0.0, iters]
    _, z0 = m25.plays(hist, r, weights, w0, return_state=True)
    start = float(iters[-1])
    n_st = int(rng.integers(4, 6))
    top = rng.uniform(93.0, 98.0)
    beats, tc = [], rng.uniform(0.3, 0.6)
    edv, T = start, rng.uniform(0.55, 0.65)
    plan = []
    for k in range(n_st):                                   # stages: the rate up, the filling and the stroke up
        s = (k + 1) / n_st
        plan.append((rng.uniform(4.0, 6.0), T * (1 - 0.45 * s), start + (top - start) * s ** 1.5,
                     rng.uniform(16.0, 22.0) + 45.0 * s ** 1.5))
    plan.append((rng.uniform(4.0, 6.0), T * 0.8, start + 0.5 * (top - start), 30.0))   # recovery
    for dur, Tb, edv_to, sv_to in plan:
        t_end = tc + dur
        edv_from, sv_from = edv, (beats[-1][2] - beats[-1][3]) if beats else sv_to
        t_st = tc
        while tc < t_end:
            f = min((tc - t_st) / 2.0, 1.0)
            e = edv_from + (edv_to - edv_from) * f
            sv = sv_from + (sv_to - sv_from) * f
            beats.append((tc, Tb, e, e - sv))
            tc += Tb
        edv = beats[-1][2]
    n = int((tc + rng.uniform(0.5, 1.0)) / dt)
    t = np.arange(n) * dt
    v = s25.stress_test(t, beats)
    gain = rng.uniform(0.7, 1.4)
    h = gain * m25.plays(v, r, weights, w0, state=z0)
    c = (h.max() + h.min()) / 2
    X = np.abs(h - c).max()
    asym, side = rng.uniform(0.10, 0.17), rng.choice([-1.0, 1.0])
    kappa = brentq(lambda k: float(m25.wedge_reading(1.0, k) + m25.wedge_reading(-1.0, k)) - asym, 1e-4, 5.0,
                   xtol=1e-14)
    y = c + side * X * m25.wedge_reading(side * (h - c) / X, kappa)
    rec = finish("holdout25_pair_initial_state_asymmetry_robbins_monro_nd_wedge_ventricle_stress_test_1040hz", seed,
                 t, v, y, {"initial_state", "asymmetry"}, "either",
                 f"a core left by a Robbins-Monro search ({n_it} noisy steps from {x0:.0f} V towards {target:.0f} V, "
                 f"ending at {start:.1f} V, where the record starts) read through a neutral-density wedge (the ends' "
                 f"secants {asym:.0%} apart) under the left ventricle's volume through a stress test ({n_st} stages, "
                 f"{len(beats)} beats, to {top:.0f} V), 1.04 kHz", rng)
    rec.extra.update(thresholds=r, weights=weights, linear=w0, gain=gain, history=hist, state=z0, x0=x0,
                     target=target, start=start, top=top, beats=beats, h=h, centre=c, X=X, asym=asym, side=side,
                     kappa=kappa)
    return rec


# ---- out of vocabulary ----

@case
def oov_stretched_beam_jump_resonance_frequency_sweeps_350hz(seed):
    rng = _rng(seed, 10)
    dt, sub = 1 / 350, 4
    amp = rng.uniform(44.0, 48.0)
    N = int(rng.integers(110, 146))                   # samples per period of the held tone: 2.4 ... 3.2 Hz
    f_h = 1 / (N * dt)
    zeta, gamma = rng.uniform(0.02, 0.03), 1.0
    F = 2 * zeta * rng.uniform(0.6, 0.8)
    om = np.linspace(0.9, 1.4, 2001)
    three = np.array([len(m25.duffing_branches(o, zeta, gamma, F)) == 3 for o in om])
    lo_b, hi_b = om[three][0], om[three][-1]          # the jumps up and down (harmonic balance)
    Om_h = lo_b + rng.uniform(0.3, 0.45) * (hi_b - lo_b)
    f0 = f_h / Om_h
    w0 = 2 * np.pi * f0
    f_lo, f_hi = 0.75 * f0, (hi_b + 0.12) * f0
    t_fade = rng.uniform(1.2, 1.8)
    T_up, M = rng.uniform(10.0, 14.0), int(rng.integers(18, 25))
    t_A = t_fade + T_up
    T_u2, T_top = rng.uniform(3.0, 4.0), rng.uniform(0.8, 1.2)
    # the down-glide's length so that the phase gained over the held tone between the holds is a whole number of
    # samples of it: (f_hi - f_h) (T_u2 / 2 + T_top + T_d / 2) = m / N
    T_d0 = rng.uniform(6.0, 7.0)
    m_int = math.ceil((f_hi - f_h) * (T_u2 / 2 + T_top + T_d0 / 2) * N)
    T_d = 2 * (m_int / (N * (f_hi - f_h)) - T_u2 / 2 - T_top)
    t_B = t_A + M * N * dt + T_u2 + T_top + T_d
    T_dn = rng.uniform(4.0, 6.0)
    t_end = t_B + M * N * dt + T_dn
    segments = [(t_fade, T_up, f_h), (t_A + M * N * dt, T_u2, f_hi), (t_A + M * N * dt + T_u2 + T_top, T_d, f_h),
                (t_B + M * N * dt, T_dn, f_lo)]
    t_out = rng.uniform(1.2, 1.8)
    n = int((t_end + t_out + rng.uniform(0.5, 1.0)) / dt)
    tf = np.arange((n - 1) * sub + 1) * (dt / sub)
    _, ph = s25.sweep_frequency(tf, segments, f_lo)
    env = m25.raised_cosine(tf / t_fade) * (1 - m25.raised_cosine((tf - t_end) / t_out))
    v_f = amp * env * np.sin(ph)
    v = v_f[::sub]
    t = tf[::sub]
    h_f, core = _core(rng, v_f)
    hc = (h_f.max() + h_f.min()) / 2
    X = np.abs(h_f - hc).max()
    u_f = (h_f - hc) / X
    q_f, _ = m25.forced_beam(u_f, dt / sub, w0, zeta, gamma, F)
    q = q_f[::sub]
    kA = int(math.ceil(t_A / dt)) + (M - 4) * N
    kB = int(math.ceil(t_B / dt)) + (M - 4) * N
    shift = next(s for s in range(kA - kB - N, kA - kB + 1)
                 if np.abs(v[kB:kB + 3 * N] - v[kB + s:kB + s + 3 * N]).max() < 1e-9)
    frac = rng.uniform(0.04, 0.07)
    b = frac * np.ptp(h_f) / np.abs(q[kA:kA + 3 * N]).max()
    y = h_f[::sub] + b * q
    rec = finish("holdout25_oov_stretched_beam_jump_resonance_frequency_sweeps_350hz", seed, t, v, y, set(),
                 "unexplained",
                 f"a clamped-clamped beam on the stage, hardening by its mid-plane stretch (f0 {f0:.2f} Hz, damping "
                 f"{zeta:.1%}), forced by the core; the sensor sees its deflection ({frac:.1%} of the span on the "
                 f"upper branch) beside the stage's travel; under a tone swept up to {f_h:.2f} Hz and held, on past "
                 f"the jump, down to {f_h:.2f} Hz and held, +-{amp:.0f} V, 350 Hz", rng)
    rec.extra.update(core, amp=amp, N=N, f_h=f_h, zeta=zeta, gamma=gamma, F=F, band=(lo_b, hi_b), Om_h=Om_h, f0=f0,
                     w0=w0, f_lo=f_lo, f_hi=f_hi, t_fade=t_fade, t_out=t_out, t_end=t_end, segments=segments,
                     M=M, t_A=t_A, t_B=t_B, m_int=m_int, sub=sub, hc=hc, X=X, q=q, kA=kA, kB=kB, shift=shift,
                     frac=frac, b=b)
    return rec

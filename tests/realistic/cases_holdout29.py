"""The HOLDOUT29 set: written after HOLDOUT28 was measured, by a session that did not read how the diagnosis decides,
to be run once for the next round's measurement; kept out of ALL until then.

Mechanisms and signals that the other sets do not have (the laws are in :mod:`.mechanisms29`, the signals in
:mod:`.signals29`, each beside its source; the citations were written from memory, as they say). Every core is the
pre-sliding of a stage on preloaded guide balls, Cattaneo and Mindlin's partial slip of Hertzian contacts under a
constant normal load (Mindlin 1949; Mindlin & Deresiewicz 1953): from the virgin state x = v + c Vs M(v / Vs), M(q) =
(3/2) (1 - (1 - |q|)^(2/3)) sign(q), from every reversal x_r + (v - v_r) + 2 c Vs M((v - v_r) / (2 Vs)), with the
memory rules (a closed inner loop wiped out), computed from a stack of turning points; the contacts' compliance c 0.5
... 1.0 of the actuator's, the peak drive 0.55 ... 0.8 of the sliding drive Vs; a drawn gain. Every record but the
initial-state case's starts at 0 V from the virgin state.

- a clean core under the x of a Foucault pendulum's bob (released on the y axis, swinging at 1.2 ... 1.8 Hz while its
  plane turns 0.6 ... 0.9 of a turn over the record, lightly damped), +-44 ... 48 V, with a noisy input monitor,
  sampled at 1.685 kHz;
- creep of a pad of a dilute polymer gel (Zimm's chain modes tau_p = tau1 p^(-3/2), equal shares, 15 ... 30 modes,
  tau1 3 ... 9 s), 16 ... 22 % of the core's output after 10 s of a held load, by Boltzmann superposition; under a
  batching hopper's load (3 or 4 batches of 4 ... 7 scoops poured in, held, discharged through the gate), on a unipolar
  stroke, sampled at 248 Hz;
- rate dependence from a sphere in a viscous liquid on the stage, held by its flexure (Stokes's drag and the
  Basset-Boussinesq history force: 1 / (1 + tau s + tau sqrt(tau_v) s^(3/2)), tau 3 ... 6 ms, tau_v 20 ... 60 ms);
  under a flag signaller's arm (letters at the five positions from down to up, quick min-jerk moves, holds, the arm
  down between words), on a unipolar stroke, with a noisy input monitor, sampled at 1.59 kHz;
- an offset drift from a radiator switched on behind a thick wall at 10 ... 30 % of the record, its heat diffusing to
  the sensor's bracket (erfc(sqrt(t_d / (t - t_on))), t_d 0.3 ... 0.8 of the rest of the record), 4 ... 8 % of the
  span at the end, either sign; under the x of a quartz clock's seconds hand (6 deg ticks, 8 ... 10 a second, each
  ringing at 18 ... 30 Hz on the detent, 2.5 ... 3.3 revolutions), +-44 ... 48 V, sampled at 618 Hz;
- asymmetry of the flow over a V-notch weir whose head the stage sets about a working level (Q ~ h^(5/2): convex, the
  ends' secants 10 ... 17 % apart, on a drawn side); under the bob of a Wilberforce pendulum (released twisted, the
  energy beating between twisting and bobbing, 1.2 ... 1.8 Hz, beats of 5 ... 9 s), +-44 ... 48 V, with a noisy input
  monitor, sampled at 1.015 kHz;
- saturation of a lock-in's dispersion signal of an optical cavity the stage detunes (delta / (1 + delta^2): odd, the
  ends compressed by 12 ... 20 %); under a playground see-saw (strokes from stop to stop of 0.7 ... 1.3 s, a rebound
  off the tyre, pauses), +-44 ... 48 V, sampled at 772 Hz;
- a delay of a bucket-brigade device (M buckets clocked at 8 times the record's rate, a transfer inefficiency of 0.5
  ... 2 %: a mean delay of 2.6 ... 4.4 samples), the core and the line computed on the clock's grid; under an EAN-13
  barcode scanned to and fro four times (a Gaussian spot of 0.2 ... 0.3 modules, modules of 45 ... 65 ms), the bars at
  88 ... 97 V, on a unipolar stroke, with a noisy input monitor, sampled at 465 Hz;
- a core left by an interrupted demagnetisation (a decaying alternating drive from 50 ... 55 V, cut 0.3 ... 0.45 or
  1.3 ... 1.45 of its periods after it began, past a positive peak), the record starting at the level where it
  stopped; then hammer throws (3 or 4, two warm-up swings at 0.55 ... 0.7 of the full first: the hammer swung in and
  turned 4 or 5 times faster and faster, released), +-44 ... 48 V, sampled at 955 Hz;
- two effects: asymmetry of the light through two circular apertures, one on the stage (the lens-shaped overlap about
  a working distance: convex, the ends' secants 10 ... 17 % apart) and a gain drift of the photomultiplier reading it
  (anode fatigue, G = 1 / (1 + Q / q_f): the gain falls by 6 ... 12 % over the record); under a kayaker's paddle
  (strokes left and right, cruising and sprinting, glides), +-44 ... 48 V, sampled at 1.345 kHz;
- out of vocabulary: a ratchet wheel pushed by a pawl on the stage (the wheel follows every forward move and stays
  while the pawl slides back: the sum of the forward increments); under a baker kneading dough (bursts of push-and-
  pull strokes, the hands still between them), +-44 ... 48 V, sampled at 1.395 kHz. The output never falls while the
  input swings both ways, grows without bound with the strokes (no PI core, whose output stays within the input's
  reach, draws that; maps and stable filters of it neither), and it rises only in the bursts and stands still in the
  rests, by steps set by the bursts' strokes, not by the time (no slow smooth drift draws those steps, and creep
  settles toward the held input).
"""

import math

import numpy as np
from scipy.optimize import brentq

from . import mechanisms29 as m29
from . import signals29 as s29
from .record import case_set, finish

HOLDOUT29, case, _rng = case_set("holdout29_", 29000)


def _mindlin(rng, peak):
    """The core: the contacts' compliance c 0.5 ... 1.0 of the actuator's, the peak drive 0.55 ... 0.8 of the sliding
    drive Vs; a drawn gain."""
    p, c = rng.uniform(0.55, 0.8), rng.uniform(0.5, 1.0)
    return dict(p=p, c=c, Vs=peak / p, gain=rng.uniform(0.7, 1.4))


def _core_of(core, v, state=None, return_state=False):
    out = m29.mindlin_core(v, core["Vs"], core["c"], state=state, return_state=return_state)
    if return_state:
        return core["gain"] * out[0], out[1]
    return core["gain"] * out


# ---- clean ----

@case
def clean_mindlin_contacts_foucault_pendulum_1685hz(seed):
    rng = _rng(seed, 1)
    dt = 1 / 1685
    n = int(rng.uniform(14.0, 20.0) / dt)
    t = np.arange(n) * dt
    w0 = 2 * math.pi * rng.uniform(1.2, 1.8)
    Om = 2 * math.pi * rng.uniform(0.6, 0.9) / t[-1]
    gamma = rng.uniform(0.01, 0.04)
    x = s29.foucault_x(t, w0, Om, gamma)
    amp = rng.uniform(44.0, 48.0)
    v = amp * x / np.abs(x).max()
    core = _mindlin(rng, amp)
    off = rng.uniform(-4.0, 4.0)
    y = _core_of(core, v) + off
    rec = finish("holdout29_clean_mindlin_contacts_foucault_pendulum_1685hz", seed, t, v, y, set(), "explained",
                 f"a clean core (Mindlin's contacts, compliance {core['c']:.2f}, the peak {core['p']:.0%} of sliding) "
                 f"under a Foucault pendulum ({w0 / 2 / math.pi:.2f} Hz, the plane turning "
                 f"{Om * t[-1] / 2 / math.pi:.2f} of a turn), +-{amp:.0f} V, 1.685 kHz", rng, monitor_noise=3e-4)
    rec.extra.update(core, offset=off, w0=w0, Om=Om, gamma=gamma, x=x, amp=amp, drive=v)
    return rec


# ---- one effect ----

@case
def creep_zimm_gel_pad_batching_hopper_248hz(seed):
    rng = _rng(seed, 2)
    dt = 1 / 248
    events, tc, loads = [], rng.uniform(1.0, 2.0), []
    for _ in range(int(rng.integers(3, 5))):
        load = 0.0
        for _ in range(int(rng.integers(4, 8))):
            dw = rng.uniform(0.6, 1.4)
            T = rng.uniform(0.6, 1.0)
            events.append((tc, T, dw))
            load += dw
            tc += T + rng.uniform(1.5, 3.0)
        loads.append(load)
        tc += rng.uniform(2.0, 4.0)                     # held while the batch is checked
        T = rng.uniform(1.5, 2.5)
        events.append((tc, T, -load))
        tc += T + rng.uniform(3.0, 5.0)
    n = min(int(tc / dt), 40_000)
    t = np.arange(n) * dt
    top = rng.uniform(88.0, 97.0)
    scale = top / max(loads)
    v = scale * s29.hopper_load(t, events)
    core = _mindlin(rng, 100.0)
    h = _core_of(core, v)
    tau1, n_m, c = rng.uniform(3.0, 9.0), int(rng.integers(15, 31)), rng.uniform(0.16, 0.22)
    cr = m29.zimm_creep(h, dt, c, tau1, n_m)
    rec = finish("holdout29_creep_zimm_gel_pad_batching_hopper_248hz", seed, t, v, h + cr, {"creep"}, "either",
                 f"creep of a dilute polymer gel pad (Zimm, {n_m} modes, tau1 {tau1:.1f} s; {c:.1%} after 10 s) under "
                 f"a batching hopper ({len(loads)} batches), to {top:.0f} V, 248 Hz", rng)
    rec.extra.update(core, events=events, loads=loads, scale=scale, top=top, h=h, tau1=tau1, n_modes=n_m, c_creep=c,
                     creep=cr, drive=v)
    return rec


@case
def rate_basset_sphere_flag_semaphore_1590hz(seed):
    rng = _rng(seed, 3)
    dt = 1 / 1590
    moves, tc, cur = [], rng.uniform(0.5, 1.0), 0.0
    n_words = int(rng.integers(3, 5))
    up_word = int(rng.integers(0, n_words))
    for w in range(n_words):
        n_let = int(rng.integers(3, 6))
        pos = [float(rng.choice(s29.SEMAPHORE_POS[1:])) for _ in range(n_let)]
        if w == up_word:
            pos[int(rng.integers(0, n_let))] = 180.0
        for j, a1 in enumerate(pos):
            if j > 0 and a1 == cur:
                tc += rng.uniform(0.15, 0.25)           # a repeated letter: a short dip and back
                moves.append((tc, 0.2, cur, cur - 45.0))
                tc += 0.2
                cur -= 45.0
            T = rng.uniform(0.25, 0.4) * max(abs(a1 - cur) / 90.0, 0.6)
            moves.append((tc, T, cur, a1))
            tc += T + rng.uniform(0.5, 0.9)
            cur = a1
        T = rng.uniform(0.35, 0.5)
        moves.append((tc, T, cur, 0.0))
        tc += T + rng.uniform(0.8, 1.4)
        cur = 0.0
    n = int(tc / dt)
    t = np.arange(n) * dt
    top = rng.uniform(88.0, 97.0)
    ang = s29.arm_path(t, moves)
    v = top * ang / 180.0
    core = _mindlin(rng, 100.0)
    h = _core_of(core, v)
    tau, tau_v = rng.uniform(3e-3, 6e-3), rng.uniform(0.02, 0.06)
    y = m29.basset_stage(h, dt, tau, tau_v)
    rec = finish("holdout29_rate_basset_sphere_flag_semaphore_1590hz", seed, t, v, y, {"rate_dependence"}, "either",
                 f"a sphere in a viscous liquid on the stage (Stokes and Basset; tau {tau * 1e3:.1f} ms, tau_v "
                 f"{tau_v * 1e3:.0f} ms) under a flag signaller's arm ({n_words} words), to {top:.0f} V, 1.59 kHz", rng,
                 monitor_noise=2.5e-4)
    rec.extra.update(core, moves=moves, top=top, ang=ang, h=h, tau=tau, tau_v=tau_v, drive=v)
    return rec


@case
def drift_wall_heat_diffusion_quartz_clock_hand_618hz(seed):
    rng = _rng(seed, 4)
    dt = 1 / 618
    period = 1.0 / rng.uniform(8.0, 10.0)
    n_ticks = int(rng.uniform(2.5, 3.3) * 60)
    t0 = rng.uniform(0.3, 0.6)
    n = int((t0 + n_ticks * period + rng.uniform(0.5, 1.0)) / dt)
    n = max(n, 10_050)
    t = np.arange(n) * dt
    wn, zeta = 2 * math.pi * rng.uniform(18.0, 30.0), rng.uniform(0.15, 0.3)
    x, ang = s29.clock_hand_x(t, t0, period, n_ticks, wn, zeta)
    amp = rng.uniform(44.0, 48.0)
    v = amp * x / np.abs(x).max()
    core = _mindlin(rng, amp)
    h = _core_of(core, v)
    t_on = rng.uniform(0.1, 0.3) * t[-1]
    t_d = rng.uniform(0.3, 0.8) * (t[-1] - t_on)
    T = m29.wall_heating(t, t_on, t_d)
    mag, sd = rng.uniform(0.04, 0.08), float(rng.choice([-1.0, 1.0]))
    off = sd * mag * np.ptp(h) * T / T[-1]
    rec = finish("holdout29_drift_wall_heat_diffusion_quartz_clock_hand_618hz", seed, t, v, h + off, {"drift"},
                 "either",
                 f"an offset drift from a radiator behind a wall switched on at {t_on:.1f} s (t_d {t_d:.1f} s; "
                 f"{sd * mag:+.1%} of the span at the end) under a quartz clock's seconds hand ({n_ticks} ticks), "
                 f"+-{amp:.0f} V, 618 Hz", rng)
    rec.extra.update(core, amp=amp, period=period, n_ticks=n_ticks, t0=t0, wn=wn, zeta=zeta, x=x, ang=ang, h=h,
                     t_on=t_on, t_d=t_d, T=T, mag=mag, side=sd, offset=off, drive=v)
    return rec


@case
def asymmetry_vnotch_weir_wilberforce_pendulum_1015hz(seed):
    rng = _rng(seed, 5)
    dt = 1 / 1015
    n = int(rng.uniform(14.0, 22.0) / dt)
    t = np.arange(n) * dt
    w = 2 * math.pi * rng.uniform(1.2, 1.8)
    beat = rng.uniform(5.0, 9.0)
    kappa = 2 * (2 * math.pi / beat) / w              # w+ - w- ~ kappa w = 2 pi / (beat / 2): the envelope's period
    gamma = rng.uniform(0.01, 0.04)
    z = s29.wilberforce_z(t, w, kappa, gamma)
    amp = rng.uniform(44.0, 48.0)
    v = amp * z / np.abs(z).max()
    core = _mindlin(rng, amp)
    h = _core_of(core, v)
    c = (h.max() + h.min()) / 2
    X = np.abs(h - c).max()
    asym, sd = rng.uniform(0.10, 0.17), float(rng.choice([-1.0, 1.0]))
    k = brentq(lambda q: m29.weir_asym(q) - asym, 1e-4, 0.9, xtol=1e-15)
    y = c + sd * X * m29.weir_reading(sd * (h - c) / X, k)
    rec = finish("holdout29_asymmetry_vnotch_weir_wilberforce_pendulum_1015hz", seed, t, v, y, {"asymmetry"}, "either",
                 f"the flow over a V-notch weir whose head the stage moves by {k:.1%} (the ends' secants {asym:.0%} "
                 f"apart) under a Wilberforce pendulum ({w / 2 / math.pi:.2f} Hz, beats of {beat:.1f} s), "
                 f"+-{amp:.0f} V, 1.015 kHz", rng, monitor_noise=3e-4)
    rec.extra.update(core, amp=amp, w=w, beat=beat, kappa=kappa, gamma=gamma, z=z, centre=c, X=X, asym=asym, side=sd,
                     k=k, drive=v)
    return rec


@case
def saturation_cavity_dispersion_seesaw_772hz(seed):
    rng = _rng(seed, 6)
    dt = 1 / 772
    strokes, tc, cur = [], rng.uniform(0.8, 1.5), 0.0
    side = float(rng.choice([-1.0, 1.0]))
    T_rec = rng.uniform(16.0, 26.0)
    while tc < T_rec - 3.0:
        T = rng.uniform(0.7, 1.3) * (0.6 if cur == 0.0 else 1.0)
        strokes.append((tc, T, cur, side))
        tc += T + rng.uniform(0.3, 1.0)
        cur, side = side, -side
    T = rng.uniform(0.8, 1.2)
    strokes.append((tc, T, cur, 0.0))
    tc += T + rng.uniform(1.0, 1.5)
    n = int(tc / dt)
    t = np.arange(n) * dt
    bounce, f_b, tau_b = rng.uniform(0.04, 0.08), rng.uniform(3.0, 5.0), rng.uniform(0.08, 0.15)
    x = s29.seesaw_path(t, strokes, bounce, f_b, tau_b)
    amp = rng.uniform(44.0, 48.0)
    v = amp * x / np.abs(x).max()
    core = _mindlin(rng, amp)
    h = _core_of(core, v)
    c = (h.max() + h.min()) / 2
    X = np.abs(h - c).max()
    comp = rng.uniform(0.12, 0.2)
    dm = math.sqrt(comp / (1 - comp))
    y = c + X * m29.dispersion_reading((h - c) / X, dm)
    rec = finish("holdout29_saturation_cavity_dispersion_seesaw_772hz", seed, t, v, y, {"saturation"}, "either",
                 f"a cavity's dispersion signal, the stage detuning it by {dm:.2f} half-widths (the ends compressed by "
                 f"{comp:.0%}) under a see-saw ({len(strokes)} strokes), +-{amp:.0f} V, 772 Hz", rng)
    rec.extra.update(core, amp=amp, strokes=strokes, bounce=bounce, f_b=f_b, tau_b=tau_b, x=x, h=h, centre=c, X=X,
                     comp=comp, dm=dm, drive=v)
    return rec


@case
def delay_bucket_brigade_ean13_barcode_465hz(seed):
    rng = _rng(seed, 7)
    dt, R = 1 / 465, 8
    d12 = [int(d) for d in rng.integers(0, 10, 12)]
    modules, digits = s29.ean13_modules(d12)
    sigma = rng.uniform(0.2, 0.3)
    scans, tc = [], rng.uniform(0.8, 1.5)
    for j in range(4):
        mod_s = rng.uniform(0.045, 0.065)
        scans.append((tc, mod_s, 1 if j % 2 == 0 else -1))
        tc += 95 * mod_s + rng.uniform(0.8, 1.5)
    n = max(int(tc / dt), 10_050)
    tf = np.arange((n - 1) * R + 1) * (dt / R)
    top = rng.uniform(88.0, 97.0)
    v_f = top * s29.scan_signal(tf, scans, modules, sigma)
    v = v_f[::R]
    t = tf[::R]
    core = _mindlin(rng, 100.0)
    h_f = _core_of(core, v_f)
    D, eps = rng.uniform(2.6, 4.4), rng.uniform(0.005, 0.02)
    M = int(round(D * R * (1 - eps)))
    y = m29.bbd_line(h_f, M, eps)[::R]
    rec = finish("holdout29_delay_bucket_brigade_ean13_barcode_465hz", seed, t, v, y, {"delay"}, "either",
                 f"a bucket-brigade line ({M} buckets at {R} clocks a sample, inefficiency {eps:.1%}: "
                 f"{M / (1 - eps) / R:.2f} samples) under an EAN-13 barcode ({''.join(map(str, digits))}) scanned four "
                 f"times, to {top:.0f} V, 465 Hz", rng, monitor_noise=2e-4)
    rec.extra.update(core, d12=d12, digits=digits, modules=modules, sigma=sigma, scans=scans, top=top, R=R,
                     v_fine=v_f, D=M / (1 - eps) / R, M=M, eps=eps, drive=v)
    return rec


@case
def initial_state_interrupted_degauss_hammer_throws_955hz(seed):
    rng = _rng(seed, 8)
    dt = 1 / 955
    amp = rng.uniform(44.0, 48.0)
    core = _mindlin(rng, 55.0)
    V0, f_dg, tau_dg = rng.uniform(50.0, 55.0), rng.uniform(4.0, 6.0), rng.uniform(1.0, 1.6)
    while True:
        t_cut = rng.uniform(0.3, 0.45) / f_dg + rng.integers(0, 2) / f_dg
        L0 = float(m29.decaying_ac(t_cut, V0, f_dg, tau_dg))
        if abs(L0) > 8.0:
            break
    tp = np.arange(0.0, t_cut, 1e-3)
    path = np.r_[m29.decaying_ac(tp, V0, f_dg, tau_dg), L0]
    _, state = _core_of(core, path, return_state=True)
    lead = rng.uniform(0.3, 0.6)
    throws, tc = [], lead + 0.6 + rng.uniform(0.8, 1.5)
    for _ in range(int(rng.integers(3, 5))):
        a = rng.uniform(0.55, 0.7) if len(throws) < 2 else rng.uniform(0.9, 1.0)      # two warm-up swings first
        th = (tc, int(rng.integers(4, 6)), rng.uniform(0.6, 0.9), rng.uniform(1.8, 2.4), a)
        throws.append(th)
        tc = s29.hammer_end(th) + rng.uniform(1.5, 3.0)
    n = int(tc / dt)
    t = np.arange(n) * dt
    x = s29.hammer_path(t, 0.0, lead, throws)
    v = np.where(t < lead + 0.6, 0.0, amp * x / max(th[4] for th in throws))
    v = v + L0 * np.where(t < lead, 1.0, 1.0 - s29.min_jerk((t - lead) / 0.6))
    y = _core_of(core, v, state=state)
    rec = finish("holdout29_initial_state_interrupted_degauss_hammer_throws_955hz", seed, t, v, y, {"initial_state"},
                 "either",
                 f"a core left by a demagnetisation from {V0:.0f} V ({f_dg:.1f} Hz, tau {tau_dg:.2f} s) cut at "
                 f"{t_cut:.2f} s at {L0:.1f} V, where the record starts, under {len(throws)} hammer throws, "
                 f"+-{amp:.0f} V, 955 Hz", rng)
    rec.extra.update(core, amp=amp, V0=V0, f_dg=f_dg, tau_dg=tau_dg, t_cut=t_cut, L0=L0, path=path, state=state,
                     lead=lead, throws=throws, x=x, drive=v)
    return rec


# ---- two effects ----

@case
def pair_asymmetry_gain_drift_apertures_pmt_fatigue_kayak_paddle_1345hz(seed):
    rng = _rng(seed, 9)
    dt = 1 / 1345
    strokes, tc, side = [], rng.uniform(0.8, 1.2), float(rng.choice([-1.0, 1.0]))
    T_rec = rng.uniform(16.0, 24.0)
    while tc < T_rec - 2.0:
        kind = rng.choice(["cruise", "sprint", "glide"], p=[0.5, 0.3, 0.2])
        if kind == "glide":
            tc += rng.uniform(1.0, 2.5)
            continue
        for _ in range(int(rng.integers(4, 9))):
            T = rng.uniform(0.8, 1.1) if kind == "cruise" else rng.uniform(0.5, 0.7)
            strokes.append((tc, T, side, rng.uniform(0.7, 1.0)))
            tc += T + (rng.uniform(0.1, 0.25) if kind == "cruise" else rng.uniform(0.03, 0.08))
            side = -side
    n = int((tc + rng.uniform(0.8, 1.5)) / dt)
    t = np.arange(n) * dt
    x = s29.paddle_path(t, strokes)
    amp = rng.uniform(44.0, 48.0)
    v = amp * x / np.abs(x).max()
    core = _mindlin(rng, amp)
    h = _core_of(core, v)
    c = (h.max() + h.min()) / 2
    X = np.abs(h - c).max()
    asym, d0 = rng.uniform(0.10, 0.17), rng.uniform(0.8, 1.2)
    k = brentq(lambda q: m29.aperture_asym(d0, q) - asym, 1e-3, min(d0, 2 - d0) - 1e-6, xtol=1e-15)
    light = m29.lens_area(d0 - k * (h - c) / X) / m29.lens_area(d0)
    drop = rng.uniform(0.06, 0.12)
    q_f = float(np.mean(light)) * t[-1] * (1 - drop) / drop       # about the drop at the end for a steady light
    cur, G = m29.pmt_fatigue(light, dt, q_f)
    S = X * m29.lens_area(d0) / (k * math.sqrt(4 - d0 * d0))      # the scale that makes the reading's slope 1 in h
    off = rng.uniform(-4.0, 4.0)
    y = off + S * cur
    rec = finish("holdout29_pair_asymmetry_gain_drift_apertures_pmt_fatigue_kayak_paddle_1345hz", seed, t, v, y,
                 {"asymmetry", "gain_drift"}, "either",
                 f"light through two circular apertures {d0:.2f} radii apart, the stage moving one by {k:.2f} (the "
                 f"ends' secants {asym:.0%} apart), read by a fatiguing photomultiplier (the gain down "
                 f"{1 - G[-1]:.1%} at the end) under a kayak paddle ({len(strokes)} strokes), +-{amp:.0f} V, "
                 f"1.345 kHz", rng)
    rec.extra.update(core, amp=amp, strokes=strokes, x=x, h=h, centre=c, X=X, asym=asym, d0=d0, k=k, light=light,
                     q_f=q_f, G=G, S=S, offset=off, drive=v)
    return rec


# ---- out of vocabulary ----

@case
def oov_pawl_ratchet_wheel_kneading_dough_1395hz(seed):
    rng = _rng(seed, 10)
    dt = 1 / 1395
    bursts, tc = [], rng.uniform(0.8, 1.5)
    for _ in range(int(rng.integers(4, 6))):
        strokes = [(rng.uniform(0.5, 0.8), rng.uniform(0.4, 1.0)) for _ in range(int(rng.integers(2, 7)))]
        bursts.append((tc, strokes))
        tc += sum(T for T, _ in strokes) + rng.uniform(1.5, 3.0)
    n = int(tc / dt)
    t = np.arange(n) * dt
    x = s29.kneading_path(t, bursts)
    amp = rng.uniform(44.0, 48.0)
    v = amp * x / np.abs(x).max()
    core = _mindlin(rng, amp)
    off = rng.uniform(-4.0, 4.0)
    h = _core_of(core, v)
    y = off + m29.ratchet(h)
    rec = finish("holdout29_oov_pawl_ratchet_wheel_kneading_dough_1395hz", seed, t, v, y, set(), "unexplained",
                 f"a ratchet wheel pushed by a pawl on the stage under a baker kneading dough ({len(bursts)} bursts, "
                 f"{sum(len(s) for _, s in bursts)} strokes), +-{amp:.0f} V, 1.395 kHz", rng)
    rec.extra.update(core, amp=amp, bursts=bursts, x=x, h=h, offset=off, drive=v)
    return rec

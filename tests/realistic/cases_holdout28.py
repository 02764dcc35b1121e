"""The HOLDOUT28 set: written after HOLDOUT27 was measured, by a session that did not read how the diagnosis decides,
to be run once for the next round's measurement; kept out of ALL until then.

Mechanisms and signals that the other sets do not have (the laws are in :mod:`.mechanisms28`, the signals in
:mod:`.signals28`, each beside its source; the citations were written from memory, as they say). Every core follows
Rayleigh's law of domain walls pinned in a random potential (Rayleigh 1887; Neel 1942; for piezoceramics Damjanovic
1997): from the demagnetised state x = v + kappa v |v|, from every reversal x_r + kappa (v - v_r) |v - v_r| / 2, the
symmetric loops (1 + kappa A) v +- (kappa / 2) (A^2 - v^2), written as a Preisach plane of constant density (the
staircase's area, a stack of turning points with the wiping-out rule), the coefficient rising by q = 0.25 ... 0.45 at
the stroke's half span; a drawn gain. Every record but the initial-state case's starts at 0 V from the virgin state.

- a clean core (Rayleigh's law above; a drawn gain and offset) under the x of the axis of Lagrange's heavy symmetric
  top (released at 0.6 ... 0.9 rad from the vertical with almost no precession: a slow precession of 0.35 ... 0.6 Hz
  with nutation loops at 4 ... 7 Hz), from 0 V, scaled to peaks of +-44 ... 48 V, with a noisy input monitor, sampled
  at 1.745 kHz;
- creep of the stage's water-saturated pad consolidating through a clogged filter (Terzaghi's layer with an impeded
  drainage boundary, Gray 1945: the modes beta tan(beta) = L, L 0.4 ... 1.5; tau = H^2 / c_v 4 ... 12 s), 9 ... 13 %
  of the core's output after 10 s of a held load, by Boltzmann superposition (a Kelvin element per mode); under the
  load on the target peg of a robot solving the Tower of Hanoi (4 or 5 disks weighing as their diameters squared; each
  move lifts a disk and sets it down, dwells of 1.15 ... 3.4 s; all the disks at 88 ... 97 V in the end), on a unipolar
  stroke, sampled at 238 Hz;
- rate dependence from a sphere the stage drags through oil, held by its flexure (Schiller & Naumann's drag u (1 +
  beta |u|^0.687): a linear lag of 4 ... 7 ms when slow, 1.6 ... 2.4 times longer at the fastest); under a cellist's
  bow (phrases in a drawn order: whole bows legato, detache in the upper half, martele strokes with stops, tremolo at
  the tip; trapezoidal bow speeds), +-44 ... 48 V, with a noisy input monitor, sampled at 1.62 kHz;
- an offset drift from a heat sink filled with paraffin beside the sensor's mount, its heater switched on at 15 ... 35
  % of the record (the enthalpy method's lumped body: a warm-up, a plateau while the paraffin melts, a second warm-up
  toward the steady state), 4 ... 8 % of the span at the end, either sign; under Newton's cradle (2 or 3 sessions: an
  end ball pulled out to 40 ... 57 deg, held and let go; the end balls' exact pendulum swings in turn, each impact
  keeping 0.92 ... 0.96 of the speed, 9 ... 14 impacts, the cradle then stopped), +-44 ... 48 V, sampled at 635 Hz;
- asymmetry of a photodiode behind an analyser the stage turns by 3 ... 6 deg about a working point 18 ... 25 deg
  from extinction (Malus's law sin^2: convex, the ends' secants 10 ... 17 % apart, on a drawn side); under one ball of
  a juggler's three-ball cascade (3 or 4 sessions of 5 ... 9 throws, flights of 0.45 ... 0.8 s straight across, dwells
  of 0.35 ... 0.55 of a flight carrying the ball inward), +-44 ... 48 V, with a noisy input monitor, sampled at
  1.035 kHz;
- saturation of an encoder reading the stage's shaft through a Hooke's (Cardan) joint (tan(psi) = tan(theta) /
  cos(beta), the shaft turned by 49 ... 66 deg at the ends: odd, the ends compressed by 12 ... 20 %); under a golfer's
  club through 8 ... 11 swings (putts, chips, pitches and full swings: a slow backswing, a pause at the top, a
  downswing fastest at impact, a follow-through, the finish held, back to address), +-44 ... 48 V, sampled at 748 Hz;
- a delay of a lumped LC delay line (8 ... 12 constant-k sections between matched resistances, a group delay of 2.6
  ... 4.4 samples at low frequencies), the core and the line computed on a 4x finer grid; under an infrared remote
  control's frames in NEC's protocol (a leader, 32 bits in pulse-distance code, a stop mark, repeat codes; a unit of
  0.07 ... 0.09 s, raised-cosine edges of 0.4 ... 0.55 of a unit), the marks at 88 ... 97 V, on a unipolar stroke,
  with a noisy input monitor, sampled at 455 Hz;
- a core left by a Kiefer-Wolfowitz search for the drive that maximises a noisy response (from the virgin state at 0 V
  up to a first iterate of 72 ... 80 V, then 10 ... 14 iterations probing +-c_n = c0 / n^(1/4), c0 5 ... 8 V, and
  stepping a0 / n times the measured slope toward a maximum at 30 ... 42 V), the record starting at its last iterate;
  then a pole-vault competition (the vaulter's centre of mass: the approach at the start level, the plant, the swing
  up to the apex, a free fall, the mat, the walk back; 4 ... 6 bars from 0.55 ... 0.65 of the top to the top at 93
  ... 98 V, one or two attempts each), on a unipolar stroke, sampled at 915 Hz;
- two effects: saturation of a tyre's lateral force on a flat-track rig whose slip angle the stage sets (Pacejka's
  Magic Formula without shifts, C 1.25 ... 1.45, E -0.6 ... 0.3: odd, the ends compressed by 12 ... 20 %) and an
  offset drift from the dielectric absorption of the sensor's input capacitor, discharged at 15 ... 35 % of the record
  (Dow's three series-RC branches, 0.4 ... 0.8 s, 2.5 ... 5 s and 20 ... 40 s: the soakage's voltage, 4 ... 8 % of the
  span at the end, either sign); under a swinging-ship fairground ride (a pendulum of 0.45 ... 0.6 Hz pumped by its
  drive tyre along its swing until it passes 1.3 ... 1.6 rad, coasting, braked to rest), +-44 ... 48 V, sampled at 1.29 kHz;
- out of vocabulary: the output read through a scanning data logger whose multiplexer visits its channel once a scan,
  every 0.23 ... 0.37 s, holding the reading in between (the input sampled on every tick); under a music box's
  cylinder turning three times (12 ... 16 notes a revolution of 5 ... 6.5 s, an exact number of samples; each note a
  plucked tine's decaying sine at 1.6 ... 6.6 Hz damped out by the next pin), +-44 ... 48 V, sampled at 1.455 kHz. The
  scan does not divide the revolution (it leaves 0.3 ... 0.7 of a scan), so the second and the third revolution, the
  same input sample for sample and the same core output, are read at other instants: the output differs between them
  by many noise levels beyond any gain and offset, and it stands still for a scan while the input swings. A PI core
  (any plays with non-negative weights and any linear part) draws the same output for the same input from the same
  state; saturation and asymmetry are maps of it; rate dependence and delay are time-invariant stable filters of it
  (the same input gives the same output, whatever the clock); creep settles, and creep, drift and gain drift are slow
  and smooth in time (a gain and an offset between the revolutions at most); an initial state is forgotten after the
  first revolution.
"""

import math

import numpy as np
from scipy.optimize import brentq

from . import mechanisms28 as m28
from . import signals28 as s28
from .record import case_set, finish

HOLDOUT28, case, _rng = case_set("holdout28_", 28000)


def _rayleigh(rng, A_ref):
    """The core: Rayleigh's law, its coefficient rising by q 0.25 ... 0.45 at the amplitude A_ref (the stroke's half
    span); a drawn gain."""
    q = rng.uniform(0.25, 0.45)
    return dict(q=q, A_ref=A_ref, kappa=q / A_ref, gain=rng.uniform(0.7, 1.4))


def _core_of(core, v, state=None, return_state=False):
    out = m28.rayleigh_core(v, core["kappa"], state=state, return_state=return_state)
    if return_state:
        return core["gain"] * out[0], out[1]
    return core["gain"] * out


# ---- clean ----

@case
def clean_rayleigh_lagrange_top_1745hz(seed):
    rng = _rng(seed, 1)
    dt = 1 / 1745
    n = int(rng.uniform(14.0, 20.0) / dt)
    t = np.arange(n) * dt
    speed, b = rng.uniform(8.0, 12.0), rng.uniform(3.0, 4.0)
    theta0, phidot0 = rng.uniform(0.6, 0.9), rng.uniform(-0.05, 0.05)
    x, states = s28.lagrange_top(t, speed, b, theta0, phidot0)
    amp = rng.uniform(44.0, 48.0)
    scale = amp / np.abs(x).max()
    v = scale * x
    core = _rayleigh(rng, amp)
    off = rng.uniform(-4.0, 4.0)
    y = _core_of(core, v) + off
    rec = finish("holdout28_clean_rayleigh_lagrange_top_1745hz", seed, t, v, y, set(), "explained",
                 f"a clean core (Rayleigh's law, the coefficient up by {core['q']:.0%} at {amp:.0f} V) under the axis "
                 f"of Lagrange's top (released at {theta0:.2f} rad, spin momentum {b:.2f}, {speed:.1f} time units a "
                 f"second), from 0 V, +-{amp:.0f} V, 1.745 kHz", rng, monitor_noise=3e-4)
    rec.extra.update(core, offset=off, speed=speed, b=b, theta0=theta0, phidot0=phidot0, x=x, states=states,
                     scale=scale, amp=amp, drive=v)
    return rec


# ---- one effect ----

@case
def creep_impeded_drainage_pad_tower_of_hanoi_238hz(seed):
    rng = _rng(seed, 2)
    dt = 1 / 238
    n_d = int(rng.choice([4, 5]))
    moves = s28.hanoi_moves(n_d)
    weights = (np.arange(1, n_d + 1) + 1.0) ** 2
    move_s, lift_s = rng.uniform(0.6, 0.9), rng.uniform(0.2, 0.28)
    dwells = rng.uniform(2.4, 3.4, len(moves)) if n_d == 4 else rng.uniform(1.15, 1.6, len(moves))
    t0 = rng.uniform(1.0, 2.0)
    T_rec = t0 + len(moves) * move_s + dwells[:-1].sum() + rng.uniform(4.0, 6.0)
    n = int(T_rec / dt)
    t = np.arange(n) * dt
    load, starts = s28.hanoi_load(t, t0, moves, weights, move_s, dwells, lift_s)
    top = rng.uniform(88.0, 97.0)
    v = top * load / weights.sum()
    core = _rayleigh(rng, 50.0)
    h = _core_of(core, v)
    tau, L, c = rng.uniform(4.0, 12.0), rng.uniform(0.4, 1.5), rng.uniform(0.09, 0.13)
    cr = m28.impeded_creep(h, dt, c, tau, L, 10.0)
    rec = finish("holdout28_creep_impeded_drainage_pad_tower_of_hanoi_238hz", seed, t, v, h + cr, {"creep"}, "either",
                 f"creep of a pad draining through a clogged filter ({c:.1%} after 10 s; tau {tau:.1f} s, L {L:.2f}) "
                 f"under the load on the target peg of a robot solving the Tower of Hanoi ({n_d} disks, "
                 f"{len(moves)} moves), to {top:.0f} V, 238 Hz", rng)
    rec.extra.update(core, n_d=n_d, moves=moves, weights=weights, move_s=move_s, lift_s=lift_s, dwells=dwells, t0=t0,
                     starts=starts, load=load, top=top, h=h, tau=tau, L=L, c=c, creep=cr)
    return rec


@case
def rate_schiller_naumann_sphere_in_oil_cello_bow_1620hz(seed):
    rng = _rng(seed, 3)
    dt = 1 / 1620
    amp = rng.uniform(44.0, 48.0)
    kinds = list(rng.permutation(["legato", "detache", "martele", "tremolo"])) + list(
        rng.choice(["legato", "detache", "martele", "tremolo"], 2))
    strokes, tc, cur = [], rng.uniform(0.4, 0.8), 0.0
    for kind in kinds:
        if kind == "legato":
            for _ in range(int(rng.integers(3, 5))):
                tgt = -1.0 if cur >= 0 else 1.0
                T = rng.uniform(1.0, 2.0) * abs(tgt - cur) / 2
                strokes.append((tc, T, cur, tgt, rng.uniform(0.12, 0.2)))
                tc, cur = tc + T + 0.02, tgt
        elif kind == "detache":
            ends = (0.05, rng.uniform(0.8, 0.9))
            for j in range(int(rng.integers(6, 11))):
                tgt = ends[(j + (cur < 0.45)) % 2]
                T = rng.uniform(0.22, 0.35) * max(abs(tgt - cur) / 0.8, 0.5)
                strokes.append((tc, T, cur, tgt, 0.3))
                tc, cur = tc + T + 0.01, tgt
        elif kind == "martele":
            ends = (-0.6, 0.2)
            for j in range(int(rng.integers(4, 7))):
                tgt = ends[(j + (cur < -0.2)) % 2]
                T = rng.uniform(0.1, 0.14) * max(abs(tgt - cur) / 0.8, 0.6)
                strokes.append((tc, T, cur, tgt, 0.45))
                tc, cur = tc + T + rng.uniform(0.2, 0.3), tgt
        else:
            c0, a0 = rng.uniform(0.7, 0.85), rng.uniform(0.04, 0.07)
            strokes.append((tc, 0.3, cur, c0 + a0, 0.4))
            tc, cur = tc + 0.3, c0 + a0
            for j in range(int(rng.integers(14, 25))):
                tgt = c0 - a0 if j % 2 == 0 else c0 + a0
                T = rng.uniform(0.045, 0.06)
                strokes.append((tc, T, cur, tgt, 0.5))
                tc, cur = tc + T, tgt
        tc += rng.uniform(0.3, 0.7)
    n = int((tc + rng.uniform(0.3, 0.6)) / dt)
    t = np.arange(n) * dt
    xb = s28.bow_path(t, strokes)
    v = amp * xb
    core = _rayleigh(rng, amp)
    h = _core_of(core, v)
    tau, ratio = rng.uniform(4e-3, 7e-3), rng.uniform(1.6, 2.4)
    u_max = np.abs(np.diff(h)).max() / dt
    beta = (ratio - 1.0) / u_max ** m28.SN_EXP
    y = m28.sn_stage(h, dt, tau, beta)
    rec = finish("holdout28_rate_schiller_naumann_sphere_in_oil_cello_bow_1620hz", seed, t, v, y, {"rate_dependence"},
                 "either",
                 f"a sphere dragged through oil by the stage (Schiller-Naumann; tau {tau * 1e3:.1f} ms, {ratio:.1f} "
                 f"times the Stokes drag at the fastest) under a cellist's bow ({', '.join(kinds)}), +-{amp:.0f} V, "
                 f"1.62 kHz", rng, monitor_noise=2.5e-4)
    rec.extra.update(core, amp=amp, kinds=kinds, strokes=strokes, xb=xb, h=h, tau=tau, ratio=ratio, beta=beta,
                     u_max=u_max, drive=v)
    return rec


@case
def drift_paraffin_heat_sink_newtons_cradle_635hz(seed):
    rng = _rng(seed, 4)
    dt = 1 / 635
    amp = rng.uniform(44.0, 48.0)
    w0, e = 2 * math.pi * rng.uniform(0.6, 0.85), rng.uniform(0.92, 0.96)
    side = float(rng.choice([-1.0, 1.0]))
    sessions, tc = [], rng.uniform(0.5, 1.0)
    for _ in range(int(rng.integers(2, 4))):
        ses = (tc, rng.uniform(0.8, 1.3), rng.uniform(0.3, 0.7), rng.uniform(0.7, 1.0), side, int(rng.integers(9, 15)))
        sessions.append(ses)
        _, imp = s28.cradle_path(np.zeros(1), [ses], w0, e)
        tc = imp[-1] + rng.uniform(1.0, 2.0)
        side = -side
    n = int(tc / dt)
    t = np.arange(n) * dt
    x, impacts = s28.cradle_path(t, sessions, w0, e)
    v = amp * x / np.abs(x).max()
    core = _rayleigh(rng, amp)
    h = _core_of(core, v)
    t_on = rng.uniform(0.15, 0.35) * t[-1]
    tau_s, tau_l = rng.uniform(2.0, 4.0), rng.uniform(1.5, 3.0)
    dT_m = 1.0
    P_R = rng.uniform(1.5, 2.2)
    t1 = tau_s * math.log(P_R / (P_R - dT_m))
    melt = rng.uniform(0.3, 0.5) * (t[-1] - t_on - t1)
    T = m28.pcm_temperature(t, t_on, P_R, dT_m, tau_s, tau_l, melt)
    mag, sd = rng.uniform(0.04, 0.08), float(rng.choice([-1.0, 1.0]))
    off = sd * mag * np.ptp(h) * T / T[-1]
    rec = finish("holdout28_drift_paraffin_heat_sink_newtons_cradle_635hz", seed, t, v, h + off, {"drift"}, "either",
                 f"an offset drift from a paraffin heat sink warmed from {t_on:.1f} s (melting for {melt:.1f} s; "
                 f"{sd * mag:+.1%} of the span at the end) under Newton's cradle ({len(sessions)} sessions, "
                 f"{len(impacts)} impacts), +-{amp:.0f} V, 635 Hz", rng)
    rec.extra.update(core, amp=amp, w0=w0, e=e, sessions=sessions, impacts=impacts, x=x, h=h, t_on=t_on, tau_s=tau_s,
                     tau_l=tau_l, dT_m=dT_m, P_R=P_R, t1=t1, melt=melt, T=T, mag=mag, side=sd, offset=off)
    return rec


@case
def asymmetry_malus_analyser_juggling_cascade_1035hz(seed):
    rng = _rng(seed, 5)
    dt = 1 / 1035
    amp = rng.uniform(44.0, 48.0)
    a = rng.uniform(0.25, 0.4)
    sessions, tc, side = [], rng.uniform(1.0, 1.5), float(rng.choice([-1.0, 1.0]))
    for _ in range(int(rng.integers(3, 5))):
        F = rng.uniform(0.45, 0.8)
        D = F * rng.uniform(0.35, 0.55)
        k = int(rng.integers(5, 10))
        sessions.append((tc, F, D, k, side))
        side = -side if k % 2 == 0 else side
        tc += k * (F + D) + rng.uniform(0.8, 1.5) + 0.5
    n = int((tc - 0.5 + rng.uniform(0.2, 0.5)) / dt)
    t = np.arange(n) * dt
    xb = s28.cascade_path(t, sessions, a)
    v = amp * xb
    core = _rayleigh(rng, amp)
    h = _core_of(core, v)
    c = (h.max() + h.min()) / 2
    X = np.abs(h - c).max()
    asym, sd = rng.uniform(0.10, 0.17), float(rng.choice([-1.0, 1.0]))
    phi0 = rng.uniform(math.radians(18.0), math.radians(25.0))
    kap = brentq(lambda q: m28.malus_asym(phi0, q) - asym, 1e-4, min(phi0, math.pi / 4 - phi0) - 1e-9, xtol=1e-15)
    y = c + sd * X * m28.malus_reading(sd * (h - c) / X, phi0, kap)
    rec = finish("holdout28_asymmetry_malus_analyser_juggling_cascade_1035hz", seed, t, v, y, {"asymmetry"}, "either",
                 f"a photodiode behind an analyser the stage turns by {math.degrees(kap):.1f} deg about "
                 f"{math.degrees(phi0):.0f} deg from extinction (the ends' secants {asym:.0%} apart) under a ball of a "
                 f"three-ball cascade ({len(sessions)} sessions), +-{amp:.0f} V, 1.035 kHz", rng, monitor_noise=3e-4)
    rec.extra.update(core, amp=amp, a=a, sessions=sessions, xb=xb, centre=c, X=X, asym=asym, side=sd, phi0=phi0,
                     kap=kap, drive=v)
    return rec


@case
def saturation_cardan_joint_golf_swings_748hz(seed):
    rng = _rng(seed, 6)
    dt = 1 / 748
    amp = rng.uniform(44.0, 48.0)
    n_sw = int(rng.integers(8, 12))
    kinds = list(rng.choice(["putt", "chip", "pitch", "full"], n_sw, p=[0.2, 0.2, 0.25, 0.35]))
    kinds[int(rng.integers(0, 3))] = "full"
    while kinds.count("full") < 3:
        kinds[int(rng.integers(3, n_sw))] = "full"
    swings, tc = [], rng.uniform(0.8, 1.5)
    for kind in kinds:
        if kind == "putt":
            top = rng.uniform(0.1, 0.2)
            sw = (tc, top, top * rng.uniform(0.9, 1.1), rng.uniform(0.5, 0.7), 0.0, rng.uniform(0.45, 0.6), 0.6, 0.7)
        elif kind == "chip":
            top = rng.uniform(0.3, 0.4)
            sw = (tc, top, top * rng.uniform(0.6, 0.8), rng.uniform(0.6, 0.8), 0.05, rng.uniform(0.35, 0.45), 0.8,
                  0.8)
        elif kind == "pitch":
            top = rng.uniform(0.6, 0.75)
            sw = (tc, top, top * rng.uniform(0.85, 1.0), rng.uniform(0.7, 0.9), 0.08, rng.uniform(0.28, 0.35), 1.0,
                  1.0)
        else:
            top = rng.uniform(0.92, 1.0)
            sw = (tc, top, rng.uniform(0.85, 1.0), rng.uniform(0.8, 1.0), rng.uniform(0.08, 0.2),
                  rng.uniform(0.22, 0.3), rng.uniform(1.0, 1.6), rng.uniform(1.0, 1.3))
        swings.append(sw)
        tc = s28.swing_end(sw) + rng.uniform(0.6, 1.4)
    n = int(tc / dt)
    t = np.arange(n) * dt
    x = s28.golf_path(t, swings)
    v = amp * x / np.abs(x).max()
    core = _rayleigh(rng, amp)
    h = _core_of(core, v)
    c = (h.max() + h.min()) / 2
    X = np.abs(h - c).max()
    comp, theta_m = rng.uniform(0.12, 0.2), rng.uniform(math.radians(49.0), math.radians(66.0))
    beta = brentq(lambda q: 1 - float(m28.cardan_reading(1.0, theta_m, q)) - comp, 1e-3, 1.5, xtol=1e-15)
    y = c + X * m28.cardan_reading((h - c) / X, theta_m, beta)
    rec = finish("holdout28_saturation_cardan_joint_golf_swings_748hz", seed, t, v, y, {"saturation"}, "either",
                 f"an encoder reading the stage's shaft through a Cardan joint bent by {math.degrees(beta):.0f} deg "
                 f"(the shaft to {math.degrees(theta_m):.0f} deg; the ends compressed by {comp:.0%}) under a golfer's "
                 f"{n_sw} swings ({kinds.count('full')} full), +-{amp:.0f} V, 748 Hz", rng)
    rec.extra.update(core, amp=amp, kinds=kinds, swings=swings, x=x, h=h, centre=c, X=X, comp=comp, theta_m=theta_m,
                     beta=beta)
    return rec


@case
def delay_lc_delay_line_nec_ir_remote_455hz(seed):
    rng = _rng(seed, 7)
    dt, R = 1 / 455, 4
    unit, top = rng.uniform(0.07, 0.09), rng.uniform(88.0, 97.0)
    edge = unit * rng.uniform(0.4, 0.55)
    t0 = rng.uniform(0.5, 1.0) / unit
    marks, words = [], []
    for j in range(2):
        addr, cmd = int(rng.integers(0, 256)), int(rng.integers(0, 256))
        n_rep = int(rng.integers(1, 3))
        mk, word = s28.nec_marks(addr, cmd, n_rep, t0)
        marks += mk
        words.append((addr, cmd, n_rep, t0, word))
        t0 = mk[-1][1] + rng.uniform(25.0, 45.0)
    T_rec = (t0 - 25.0) * unit + rng.uniform(0.3, 0.6)
    n = int(T_rec / dt)
    tf = np.arange((n - 1) * R + 1) * (dt / R)
    v_f = top * s28.marks_path(tf, marks, unit, edge)
    v = v_f[::R]
    t = tf[::R]
    core = _rayleigh(rng, 50.0)
    h_f = _core_of(core, v_f)
    n_sec, D = int(rng.integers(8, 13)), rng.uniform(2.6, 4.4)
    y = m28.lc_delay_line(h_f, dt / R, n_sec, R * D)[::R]
    rec = finish("holdout28_delay_lc_delay_line_nec_ir_remote_455hz", seed, t, v, y, {"delay"}, "either",
                 f"a lumped LC delay line ({n_sec} sections, {D:.2f} samples) under an infrared remote's NEC frames "
                 f"(a unit of {unit * 1e3:.0f} ms, marks at {top:.0f} V), 455 Hz", rng, monitor_noise=2e-4)
    rec.extra.update(core, unit=unit, top=top, edge=edge, marks=marks, words=words, R=R, v_fine=v_f, n_sec=n_sec, D=D,
                     drive=v)
    return rec


@case
def initial_state_kiefer_wolfowitz_pole_vault_915hz(seed):
    rng = _rng(seed, 8)
    dt = 1 / 915
    core = _rayleigh(rng, 50.0)
    x1, mu, w = rng.uniform(72.0, 80.0), rng.uniform(30.0, 42.0), rng.uniform(15.0, 25.0)
    c0, n_it, noise = rng.uniform(5.0, 8.0), int(rng.integers(10, 15)), rng.uniform(0.3, 0.6)
    a0 = rng.uniform(0.8, 1.2) * w * w / 20.0

    def response(x):
        return -10.0 * ((x - mu) / w) ** 2

    kw_path, iterates, probes, ys = m28.kiefer_wolfowitz(x1, n_it, a0, c0, response, rng, noise)
    path = np.r_[0.0, kw_path]
    _, state = _core_of(core, path, return_state=True)
    L0 = float(kw_path[-1])
    top = rng.uniform(93.0, 98.0)
    n_bar = int(rng.integers(4, 7))
    bars = np.linspace(rng.uniform(0.55, 0.65) * top, top, n_bar)
    vaults, tc, apexes = [], rng.uniform(0.4, 0.8), []
    for j, bar in enumerate(bars):
        last = j == n_bar - 1
        n_att = 1 if last else int(rng.integers(1, 3))
        for k in range(n_att):
            clear = last or k == n_att - 1 or rng.uniform() < 0.5
            apex = top if last else (bar + rng.uniform(0.5, 2.0) if clear else bar - rng.uniform(0.5, 2.0))
            vt = (tc, rng.uniform(0.6, 1.0), rng.uniform(2.0, 4.0), apex, rng.uniform(8.0, 15.0),
                  rng.uniform(0.9, 1.2), rng.uniform(0.5, 0.7), rng.uniform(0.4, 0.8), rng.uniform(1.0, 1.6))
            vaults.append(vt)
            apexes.append(apex)
            tc = s28.vault_end(vt) + rng.uniform(0.1, 0.3)
    n = int(tc / dt)
    t = np.arange(n) * dt
    v = s28.vault_path(t, L0, vaults)
    y = _core_of(core, v, state=state)
    rec = finish("holdout28_initial_state_kiefer_wolfowitz_pole_vault_915hz", seed, t, v, y, {"initial_state"},
                 "either",
                 f"a core left by a Kiefer-Wolfowitz search ({n_it} iterations from {x1:.0f} V, probes +-{c0:.1f} V / "
                 f"n^(1/4), ending at {L0:.1f} V, where the record starts) under a pole-vault competition "
                 f"({len(vaults)} vaults, {n_bar} bars up to {top:.0f} V), 915 Hz", rng)
    rec.extra.update(core, x1=x1, mu=mu, w=w, c0=c0, n_it=n_it, noise=noise, a0=a0, kw_path=kw_path,
                     iterates=iterates, probes=probes, ys=ys, path=path, state=state, L0=L0, top=top, bars=bars,
                     vaults=vaults, apexes=apexes)
    return rec


# ---- two effects ----

@case
def pair_drift_saturation_soakage_pacejka_tyre_swinging_ship_1290hz(seed):
    rng = _rng(seed, 9)
    dt = 1 / 1290
    amp = rng.uniform(44.0, 48.0)
    w0, zeta = 2 * math.pi * rng.uniform(0.45, 0.6), rng.uniform(0.01, 0.02)
    U_p = rng.uniform(0.09, 0.12) * w0 * w0
    U_b = rng.uniform(1.3, 1.6) * U_p
    target, coast = rng.uniform(1.3, 1.6), rng.uniform(3.0, 5.0)
    t_on = rng.uniform(0.5, 1.0)
    tl = np.arange(int(40.0 / dt)) * dt
    _, ph = s28.ride_path(tl, t_on, w0, zeta, U_p, U_b, target, coast)
    T_rec = min(ph[2][1] + rng.uniform(1.0, 2.0), 30.0)
    n = int(T_rec / dt)
    t = np.arange(n) * dt
    th, phases = s28.ride_path(t, t_on, w0, zeta, U_p, U_b, target, coast)
    v = amp * th / np.abs(th).max()
    core = _rayleigh(rng, amp)
    h = _core_of(core, v)
    c = (h.max() + h.min()) / 2
    X = np.abs(h - c).max()
    comp, C, E = rng.uniform(0.12, 0.2), rng.uniform(1.25, 1.45), rng.uniform(-0.6, 0.3)

    def xi(B):
        return B - E * (B - math.atan(B))
    B_pk = brentq(lambda B: C * math.atan(xi(B)) - math.pi / 2, 1e-3, 1e3, xtol=1e-14)
    B = brentq(lambda q: 1 - float(m28.pacejka_reading(1.0, q, C, E)) - comp, 1e-3, B_pk, xtol=1e-15)
    s = c + X * m28.pacejka_reading((h - c) / X, B, C, E)
    t_s = rng.uniform(0.15, 0.35) * t[-1]
    taus = np.array([rng.uniform(0.4, 0.8), rng.uniform(2.5, 5.0), rng.uniform(20.0, 40.0)])
    wts = np.array([rng.uniform(0.25, 0.35), rng.uniform(0.3, 0.4), 0.0])
    wts[2] = 1.0 - wts[:2].sum()
    mag, sd = rng.uniform(0.04, 0.08), float(rng.choice([-1.0, 1.0]))
    d = m28.soakage(t, t_s, taus, wts)
    off = sd * mag * np.ptp(h) * d / d[-1]
    rec = finish("holdout28_pair_drift_saturation_soakage_pacejka_tyre_swinging_ship_1290hz", seed, t, v, s + off,
                 {"drift", "saturation"}, "either",
                 f"a tyre's lateral force by Pacejka's Magic Formula (C {C:.2f}, E {E:+.2f}; the ends compressed by "
                 f"{comp:.0%}) and the soakage of the sensor's input capacitor discharged at {t_s:.1f} s "
                 f"({sd * mag:+.1%} of the span at the end) under a swinging-ship ride (to {target:.2f} rad), "
                 f"+-{amp:.0f} V, 1.29 kHz", rng)
    rec.extra.update(core, amp=amp, w0=w0, zeta=zeta, U_p=U_p, U_b=U_b, target=target, coast=coast, t_on=t_on,
                     phases=phases, th=th, h=h, centre=c, X=X, comp=comp, C=C, E=E, B=B, B_pk=B_pk, t_s=t_s,
                     taus=taus, wts=wts, mag=mag, side=sd, offset=off)
    return rec


# ---- out of vocabulary ----

@case
def oov_scanning_logger_music_box_1455hz(seed):
    rng = _rng(seed, 10)
    dt = 1 / 1455
    amp = rng.uniform(44.0, 48.0)
    N_rev = int(round(rng.uniform(5.0, 6.5) / dt))
    T_rev = N_rev * dt
    scale_deg = [0, 2, 4, 5, 7, 9, 11, 12, 14, 16, 17, 19]
    f_base = rng.uniform(1.6, 2.2)
    n_notes = int(rng.integers(12, 17))
    beat = (T_rev - 2.6) / n_notes
    damp = 0.2
    n = 3 * N_rev + int(rng.uniform(2.4, 3.0) / dt)
    t = np.arange(n) * dt
    for _ in range(50):                                         # a tune whose swings reach both ways alike
        notes = []
        for j in range(n_notes):
            on = 0.3 + j * beat + rng.uniform(0.0, 0.25 * beat)
            notes.append((on, f_base * 2 ** (scale_deg[int(rng.integers(0, 12))] / 12), rng.uniform(0.5, 1.0),
                          rng.uniform(0.4, 0.8), rng.uniform(1.6, 2.3)))
        x = s28.music_box(t, notes, T_rev, 3, damp)
        if min(x.max(), -x.min()) > 0.85 * np.abs(x).max():
            break
    v = amp * x / np.abs(x).max()
    core = _rayleigh(rng, amp)
    off = rng.uniform(-4.0, 4.0)
    h = _core_of(core, v) + off
    M = int(round(rng.uniform(0.23, 0.37) / dt))
    while not 0.3 * M < N_rev % M < 0.7 * M:
        M += 1
    first = int(rng.integers(0, M))
    y = m28.scanned(h, first, M)
    w2 = v[N_rev:2 * N_rev]
    k_after = max(int(np.argmax(w2)), int(np.argmin(w2))) + 1
    rec = finish("holdout28_oov_scanning_logger_music_box_1455hz", seed, t, v, y, set(), "unexplained",
                 f"the output read by a scanning logger every {M * dt:.3f} s ({M} samples), held between visits, under "
                 f"a music box's cylinder ({n_notes} notes a revolution of {T_rev:.2f} s, three turns), +-{amp:.0f} V, "
                 f"1.455 kHz", rng)
    rec.extra.update(core, amp=amp, N_rev=N_rev, T_rev=T_rev, notes=notes, damp=damp, f_base=f_base, x=x, offset=off,
                     h=h, M=M, first=first, k_after=k_after)
    return rec

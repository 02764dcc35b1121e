"""Excitations of the HOLDOUT38 set (``cases_holdout38.py``), each beside its source; the mechanisms are in
:mod:`.mechanisms38`. Citations written from memory in this session (none was re-read), as in mechanisms38.

Every generator draws a programme from ``rng`` and returns its parameters; its companion evaluates the path on any
times, normalised to about -1 ... 1 (or 0 ... 1 for the unipolar ones), at rest (exactly 0) before the programme starts;
the cases scale it to volts.
"""

import math

import numpy as np
from scipy.interpolate import PchipInterpolator


def smooth_step(s):
    """The half-cosine ramp (1 - cos(pi s)) / 2 on 0 ... 1 (zero slope at both ends), 0 below and 1 above."""
    s = np.clip(np.asarray(s, float), 0.0, 1.0)
    return 0.5 * (1.0 - np.cos(math.pi * s))


def through_points(t, times, values):
    """The path through (times, values), a half-cosine ramp between consecutive points (a hold where two are equal),
    values[0] before the first time and values[-1] after the last."""
    t = np.asarray(t, float)
    out = np.full(len(t), float(values[0]))
    for k in range(len(times) - 1):
        ta, tb, a, b = times[k], times[k + 1], values[k], values[k + 1]
        m = t >= ta
        out[m] = a + (b - a) * smooth_step((t[m] - ta) / (tb - ta))
    return out


def fade(t, t_on, t_off, ramp):
    """1 between t_on + ramp and t_off - ramp, half-cosine ramps at either end, 0 outside t_on ... t_off."""
    t = np.asarray(t, float)
    return smooth_step((t - t_on) / ramp) * smooth_step((t_off - t) / ramp)


# ---- clean: a seiche at a lake's end ----

def lake_seiche(rng, T_min):
    """The water level at one end of a long lake through wind events (replayed, time-compressed): each event's wind
    sets the surface up (or down, the wind from the other end) at the gauge by 0.5 ... 1 (one event 1) over 0.8 ... 1.5
    s, blows 2.5 ... 5 s and drops, releasing the free standing waves (the storm-surge seiche, Forel's observations at
    Lake Geneva; Merian's periods T_n = 2 L / (n sqrt(g h)) of a rectangular basin, here T1 1.4 ... 2.2 s and the
    higher modes off T1 / n by up to 7 % for the basin's irregular shape), each mode ringing down with its damping
    ratio 0.015 ... 0.04 (so slowly that the events overlap), the modes' shares at the gauge 1, 0.2 ... 0.4 and 0.08
    ... 0.18 with drawn signs. Events every 4 ... 9 s, the wind's side alternating with a chance of 0.65. Faded in and
    out over 1.5 s. Returns a dict of the programme."""
    t_on = rng.uniform(0.5, 1.0)
    T1 = rng.uniform(1.4, 2.2)
    modes = [(T1, 1.0, rng.uniform(0.015, 0.04))]
    for n, lo, hi in ((2, 0.2, 0.4), (3, 0.08, 0.18)):
        modes.append((T1 / n * rng.uniform(0.93, 1.07), float(rng.choice([-1.0, 1.0])) * rng.uniform(lo, hi),
                      rng.uniform(0.015, 0.04)))
    events, t = [], t_on + rng.uniform(0.3, 1.0)
    side = float(rng.choice([-1.0, 1.0]))
    while t < t_on + T_min - 6.0:
        events.append([t, side * rng.uniform(0.5, 1.0), rng.uniform(0.8, 1.5), rng.uniform(2.5, 5.0)])
        if rng.uniform() < 0.65:
            side = -side
        t += rng.uniform(4.0, 9.0)
    events[int(rng.integers(len(events)))][1] = math.copysign(1.0, events[0][1])
    t_off = max(t_on + T_min, events[-1][0] + events[-1][3] + 6.0)
    return dict(t_on=t_on, t_off=t_off, T_end=t_off + rng.uniform(0.4, 0.8), modes=modes,
                events=[tuple(e) for e in events])


def ringdown(s, T, zeta):
    """A mode released from rest at unit displacement: exp(-zeta w s) (cos(w_d s) + zeta w / w_d sin(w_d s)), w = 2 pi
    / T (its value 1 and slope 0 at s = 0)."""
    w = 2 * math.pi / T
    wd = w * math.sqrt(1 - zeta * zeta)
    return np.exp(-zeta * w * s) * (np.cos(wd * s) + zeta * w / wd * np.sin(wd * s))


def seiche_level(t, prog):
    """The level on times t: each event's set-up (a half-cosine rise to its height times the sum of the modes' shares,
    held while it blows) and, from the wind's drop, every mode ringing down from its share of it."""
    t = np.asarray(t, float)
    x = np.zeros(len(t))
    share = sum(b for _, b, _ in prog["modes"])
    for t0, A, rise, blow in prog["events"]:
        s = t - t0
        up = (s >= 0) & (s < blow)
        x[up] += A * share * smooth_step(s[up] / rise)
        dn = s >= blow
        for T, b, z in prog["modes"]:
            x[dn] += A * b * ringdown(s[dn] - blow, T, z)
    return x * fade(t, prog["t_on"], prog["t_off"], 1.5)


# ---- creep: a CNC machine's peck-drilling cycle ----

def peck_drilling(rng):
    """A drilling axis's depth through a canned peck-drilling cycle (G83 on a CNC mill: the drill fed down by a peck Q,
    retracted at the rapid rate to the reference plane to clear the chips, returned at the rapid rate to a clearance
    above the last depth, fed the next peck, ...), unipolar 0 (the reference plane) ... 1: 3 ... 5 holes of depths
    0.6 ... 1 (one 1), pecks of 0.22 ... 0.34 of the depth, the clearance 0.03 ... 0.05, feeds at 0.25 ... 0.4 a second,
    rapids over 0.25 ... 0.4 s (each move a half-cosine: the controller's smoothed profile), a dwell of 2 ... 4 s at
    each hole's bottom, the move to the next hole (the drill held at the reference plane) 3 ... 6 s. At rest (0) for 1
    ... 2 s at the start and 2 ... 4 s at the end. Returns (times, values)."""
    times, vals = [0.0, rng.uniform(1.0, 2.0)], [0.0, 0.0]

    def go(v, dur):
        times.append(times[-1] + dur)
        vals.append(float(v))

    n_h = int(rng.integers(3, 6))
    depths = rng.uniform(0.6, 1.0, n_h)
    depths[int(rng.integers(n_h))] = 1.0
    for i, D in enumerate(depths):
        q, c, feed = D * rng.uniform(0.22, 0.34), rng.uniform(0.03, 0.05), rng.uniform(0.25, 0.4)
        reached = 0.0
        while reached < D - 1e-12:
            start = max(reached - c, 0.0)
            if reached > 0:
                go(0.0, rng.uniform(0.25, 0.4))
                go(start, rng.uniform(0.25, 0.4))
            new = min(reached + q, D)
            go(new, (new - start) / feed)
            reached = new
        go(D, rng.uniform(2.0, 4.0))
        go(0.0, rng.uniform(0.25, 0.4))
        go(0.0, rng.uniform(3.0, 6.0) if i < n_h - 1 else rng.uniform(2.0, 4.0))
    return times, vals


# ---- rate: brushing teeth ----

def tooth_brushing(rng, n_regions):
    """A toothbrush's stroke along the dental arch (replayed): n_regions regions in quadrants of 3, each reached by a
    half-cosine move (0.25 ... 0.4 s) to its place c (|c| <= 0.5) and scrubbed with short strokes (the Bass
    technique's vibratory strokes: 3 ... 5 Hz, +-0.25 ... 0.5, for 1.5 ... 3 s, faded over 0.15 s), now and then (a
    chance of 0.5) followed by 2 or 3 sweeping strokes (the roll: 1 ... 1.6 Hz, +-0.8 ... 1 about the arch's middle);
    a pause to rinse (at rest, 0) of 0.8 ... 1.5 s after each quadrant. At rest 0.6 ... 1.2 s at either end. Returns the
    list of segments (kind, t0, T, centre, amplitude, frequency) and T_end."""
    t = rng.uniform(0.6, 1.2)
    segs, here = [], 0.0
    for r in range(n_regions):
        c = rng.uniform(-0.5, 0.5)
        T = rng.uniform(0.25, 0.4)
        segs.append(("move", t, T, here, c, 0.0))
        t += T
        T = rng.uniform(1.5, 3.0)
        segs.append(("scrub", t, T, c, rng.uniform(0.25, 0.5), rng.uniform(3.0, 5.0)))
        t += T
        here = c
        if rng.uniform() < 0.5:
            T = rng.uniform(0.25, 0.4)
            segs.append(("move", t, T, here, 0.0, 0.0))
            t += T
            f = rng.uniform(1.0, 1.6)
            T = int(rng.integers(2, 4)) / f
            segs.append(("sweep", t, T, 0.0, rng.uniform(0.8, 1.0), f))
            t += T
            here = 0.0
        if r % 3 == 2 or r == n_regions - 1:
            T = rng.uniform(0.25, 0.4)
            segs.append(("move", t, T, here, 0.0, 0.0))
            t += T + rng.uniform(0.8, 1.5)
            here = 0.0
    return segs, t + rng.uniform(0.6, 1.2)


def brush_position(t, segs):
    t = np.asarray(t, float)
    x = np.zeros(len(t))
    for kind, t0, T, c, a, f in segs:
        s = t - t0
        m = (s >= 0) & (s < T)
        if kind == "move":
            x[m] = c + (a - c) * smooth_step(s[m] / T)
        elif kind == "scrub":
            x[m] = c + a * np.sin(2 * math.pi * f * s[m]) * smooth_step(s[m] / 0.15) * smooth_step((T - s[m]) / 0.15)
        else:
            x[m] = c + a * np.sin(2 * math.pi * f * s[m])
    return x


# ---- drift: an injection moulding machine's screw ----

def injection_moulding(rng, n_cycles):
    """The screw's position in an injection moulding machine's barrel through its cycles (0 fully forward, unipolar;
    time-compressed about twofold): from rest after the purge (1 ... 2 s) the first recovery (the screw turning, pushed
    back by the melt to the shot size 0.8 ... 0.95 over 1.5 ... 3 s), a decompression (suck-back by 0.03 ... 0.06 over
    0.2 s) and the cooling time (held 2 ... 4 s); then each cycle: the injection (forward to the cushion 0.04 ... 0.08
    in 0.3 ... 0.6 s), the holding pressure (creeping forward by 0.01 ... 0.02 over 1 ... 2 s), the recovery, the
    decompression and the cooling time with the mould opening and ejecting; after the last injection the screw is
    brought to 0 and rests 1 ... 2 s. Each move a half-cosine. Returns (times, values), the largest value 1."""
    times, vals = [0.0, rng.uniform(1.0, 2.0)], [0.0, 0.0]

    def go(v, dur):
        times.append(times[-1] + dur)
        vals.append(float(v))

    shot = rng.uniform(0.8, 0.95)
    for i in range(n_cycles + 1):
        if i > 0:
            cush = rng.uniform(0.04, 0.08)
            go(cush, rng.uniform(0.3, 0.6))
            go(cush - rng.uniform(0.01, 0.02), rng.uniform(1.0, 2.0))
        if i < n_cycles:
            s = shot * rng.uniform(0.98, 1.02)
            go(s, rng.uniform(1.5, 3.0))
            go(s + rng.uniform(0.03, 0.06), 0.2)
            go(vals[-1], rng.uniform(2.0, 4.0))
    go(0.0, 0.5)
    go(0.0, rng.uniform(1.0, 2.0))
    top = max(vals)
    return times, [v / top for v in vals]


# ---- asymmetry: a spinning wheel's treadle ----

def spinning_wheel(rng, n_bouts):
    """A spinning wheel's treadle angle (a foot-driven flywheel: the treadle rocks on its pivot, coupled to the wheel's
    crank by the footman) through n_bouts bouts of spinning: the spinner starts the wheel by hand (its speed rising to
    1 ... 1.6 turns a second over 1.5 ... 3 s), treadles for 4 ... 7 s (the speed wandering by +-8 % through
    smooth random knots every 1.5 s), and lets it coast to a stop over 1 ... 2 s while drafting the fibre (the wheel
    and treadle then rest 1 ... 2 s wherever it stopped, and the next bout starts from there). Within a turn the
    wheel runs faster on the treadle's downstroke (the phase phi = Phi + m sin Phi, m 0.05 ... 0.12) and the footman's
    angularity adds a second harmonic (eps sin 2 phi, eps 0.03 ... 0.08). At rest (0) for 0.8 ... 1.5 s at the start.
    Returns the programme (knot times and speeds, m, eps) and T_end."""
    t = rng.uniform(0.8, 1.5)
    kt, kv = [0.0, t], [0.0, 0.0]
    for _ in range(n_bouts):
        wc = rng.uniform(1.0, 1.6)
        t += rng.uniform(1.5, 3.0)
        kt.append(t)
        kv.append(wc)
        T = rng.uniform(4.0, 7.0)
        for s in np.arange(1.5, T, 1.5):
            kt.append(t + s)
            kv.append(wc * rng.uniform(0.92, 1.08))
        t += T
        kt.append(t)
        kv.append(wc * rng.uniform(0.92, 1.08))
        t += rng.uniform(1.0, 2.0)
        kt.append(t)
        kv.append(0.0)
        t += rng.uniform(1.0, 2.0)
        kt.append(t)
        kv.append(0.0)
    return dict(kt=kt, kv=kv, m=rng.uniform(0.05, 0.12), eps=rng.uniform(0.03, 0.08)), t + rng.uniform(0.3, 0.8)


def treadle_angle(t, prog):
    """The treadle on times t (uniform, starting at 0): the wheel's speed a half-cosine path through the knots, its
    turns Phi the trapezoidal integral of it, phi = Phi + m sin Phi, the angle sin(phi) + eps sin(2 phi)."""
    t = np.asarray(t, float)
    w = through_points(t, prog["kt"], prog["kv"])
    Phi = 2 * math.pi * np.r_[0.0, np.cumsum(0.5 * (w[1:] + w[:-1]) * np.diff(t))]
    phi = Phi + prog["m"] * np.sin(Phi)
    return np.sin(phi) + prog["eps"] * np.sin(2 * phi)


# ---- saturation: a skier's legs through a mogul field ----

def ski_moguls(rng, n_runs):
    """A skier's leg extension (the hip's height over the skis, about its standing height) down n_runs lines of
    moguls (8 ... 16 each): each mogul one cycle of extension into the trough and absorption over the next bump, A (sin
    s + b sin 2 s) over its peak on its phase s (b 0.2 ... 0.35: the legs reach out early and fold late, a skewed
    cycle), A 0.6 ... 1 (one 1), the first two at 0.5 and 0.75 of theirs while the skier gathers speed; the mogul's
    period 0.5 ... 0.8 s, shortening to 0.7 ... 0.85 of it over the first three; now and then (a chance of 0.12) an
    air between two moguls: the legs reaching out to 0.85 A and back (sin^2) over 0.25 ... 0.45 s. The skier stands
    (0) 1.5 ... 3 s between the runs, 0.8 ... 1.5 s at the start. Returns the list of cycles (t0, T, A, b, air) and
    T_end."""
    t = rng.uniform(0.8, 1.5)
    cyc = []
    for _ in range(n_runs):
        n = int(rng.integers(8, 17))
        T0, b = rng.uniform(0.5, 0.8), rng.uniform(0.2, 0.35)
        short = rng.uniform(0.7, 0.85)
        for j in range(n):
            T = T0 / (1.0 + (1.0 / short - 1.0) * min(j, 3) / 3.0)
            A = rng.uniform(0.6, 1.0) * (0.5 if j == 0 else (0.75 if j == 1 else 1.0))
            air = rng.uniform(0.25, 0.45) if (0 < j < n - 1 and rng.uniform() < 0.12) else 0.0
            cyc.append([t, T, A, b, air])
            t += T + air
        t += rng.uniform(1.5, 3.0)
    big = [c for c in cyc if c[2] > 0.55]
    big[int(rng.integers(len(big)))][2] = 1.0
    return [tuple(c) for c in cyc], t + rng.uniform(0.5, 1.0)


def leg_extension(t, cycles):
    """The extension on times t: each cycle A (sin s + b sin 2 s) / (its peak), s = 2 pi (t - t0) / T; an air after a
    cycle a half-cosine rise to 0.85 A and back over its length."""
    t = np.asarray(t, float)
    x = np.zeros(len(t))
    for t0, T, A, b, air in cycles:
        s = 2 * math.pi * (t - t0) / T
        m = (s >= 0) & (s < 2 * math.pi)
        ss = np.linspace(0, 2 * math.pi, 2001)
        peak = np.abs(np.sin(ss) + b * np.sin(2 * ss)).max()
        x[m] = A * (np.sin(s[m]) + b * np.sin(2 * s[m])) / peak
        if air > 0:
            u = t - t0 - T
            m = (u >= 0) & (u < air)
            x[m] = 0.85 * A * np.sin(math.pi * u[m] / air) ** 2
    return x


# ---- delay: a lighthouse's flashes seen from an approaching boat ----

def lighthouse(rng, T_min):
    """A photometer's reading of a lighthouse's group-flashing light from a boat heading for it (unipolar;
    time-compressed about fourfold): the character Fl(n) with n 2 ... 4 flashes a group (the lens's bull's-eye panels
    sweeping past: each flash a raised cosine 0.16 ... 0.3 s wide, the panels' strengths 0.8 ... 1, 0.35 ... 0.6 s
    apart), a group every 2.5 ... 4 s, dark (0) between; the flashes' strength growing as the boat nears, the
    illuminance I0 T^r / r^2 (Allard's law: the atmosphere's transmissivity T 0.6 ... 0.8 per unit range) with the range
    r falling linearly from 1.6 ... 2.2 to 1 ... 1.2. Dark 1 ... 2 s at the start and at the end. Returns a dict of the
    programme."""
    n = int(rng.integers(2, 5))
    P, gap, w = rng.uniform(2.5, 4.0), rng.uniform(0.35, 0.6), rng.uniform(0.08, 0.15)
    panels = rng.uniform(0.8, 1.0, n)
    t_on = rng.uniform(1.0, 2.0)
    groups = list(np.arange(t_on, t_on + T_min, P))
    r0, r1, Tr = rng.uniform(1.6, 2.2), rng.uniform(1.0, 1.2), rng.uniform(0.6, 0.8)
    t_end_fl = groups[-1] + (n - 1) * gap + w
    return dict(n=n, P=P, gap=gap, w=w, panels=panels, groups=groups, r0=r0, r1=r1, Tr=Tr, t_on=t_on,
                t_last=t_end_fl, T_end=t_end_fl + rng.uniform(1.0, 2.0))


def light_reading(t, prog):
    """The reading on times t: each flash a raised cosine (1 + cos(pi s / w)) / 2 for |s| < w, its panel's strength
    times Allard's T^r / r^2 at the range then, over its largest in the programme."""
    t = np.asarray(t, float)
    x = np.zeros(len(t))
    t0, t1 = prog["groups"][0], prog["t_last"]

    def illum(tc):
        r = prog["r0"] + (prog["r1"] - prog["r0"]) * (tc - t0) / (t1 - t0)
        return prog["Tr"] ** r / r ** 2

    peak = 0.0
    for g in prog["groups"]:
        for j in range(prog["n"]):
            tc = g + j * prog["gap"]
            a = prog["panels"][j] * illum(tc)
            peak = max(peak, a)
            s = t - tc
            m = np.abs(s) < prog["w"]
            x[m] += a * 0.5 * (1.0 + np.cos(math.pi * s[m] / prog["w"]))
    return x / peak


# ---- initial state: a tree swaying in a gusty wind ----

def tree_sway(rng, T_min):
    """A tree's crown swaying across the wind (time-compressed about fourfold), the narrow-band response of its lightly
    damped first mode (0.6 ... 1 Hz here, damping ratio 0.05 ... 0.1) to turbulence: 16 sines whose frequencies are
    drawn from the mode's Lorentzian power spectrum (f0 (1 + zeta tan(pi (U - 1/2))), kept within +-30 %), random
    phases, under the gusts' envelope, a monotone cubic through levels every 2 ... 3.5 s: calm at first (0.04 ... 0.15
    over the first quarter of the record), rising to 0.4 ... 1 (one 1) as the wind gets up. The sway faded in over 1 s
    at 0.5 ... 1 s and out over 1 s at the end. Returns a dict of the programme."""
    t_on = rng.uniform(0.5, 1.0)
    f0, zeta = rng.uniform(0.6, 1.0), rng.uniform(0.05, 0.1)
    fr = []
    while len(fr) < 16:
        f = f0 * (1.0 + zeta * math.tan(math.pi * (rng.uniform() - 0.5)))
        if abs(f / f0 - 1.0) <= 0.3:
            fr.append(f)
    t_off = t_on + T_min
    et = np.arange(t_on, t_off + 3.5, rng.uniform(2.0, 3.5))
    calm = et < t_on + 0.25 * T_min
    ev = np.where(calm, rng.uniform(0.04, 0.15, len(et)), rng.uniform(0.4, 1.0, len(et)))
    ev[int(rng.integers(np.sum(calm), len(et)))] = 1.0
    return dict(t_on=t_on, t_off=t_off, T_end=t_off + rng.uniform(0.4, 0.8), f0=f0, zeta=zeta,
                fr=np.array(fr), ph=rng.uniform(0, 2 * math.pi, 16), et=et, ev=ev)


def sway(t, prog):
    t = np.asarray(t, float)
    x = np.sin(2 * math.pi * prog["fr"][None, :] * t[:, None] + prog["ph"][None, :]).sum(axis=1) / 4.0
    env = PchipInterpolator(prog["et"], prog["ev"])(np.clip(t, prog["et"][0], prog["et"][-1]))
    return x * env * fade(t, prog["t_on"], prog["t_off"], 1.0)


# ---- pair: sculling a boat with a yuloh ----

def yuloh(rng, n_bouts):
    """The blade's sweep of a yuloh (the long stern oar of Chinese boats, worked side to side, the blade twisted at each
    end of the sweep: Needham, Science and Civilisation in China IV.3): n_bouts bouts of sculling, each from rest: 3 ...
    5 quick strokes at 1.1 ... 1.5 Hz to get the boat going, easing to the cruising stroke 0.7 ... 0.95 Hz over 2 s (8
    ... 16 strokes), the sweep tanh(k sin Phi) / tanh(k) (k 1 ... 2: the pause at each end while the blade is flipped)
    of amplitude 0.85 ... 1, a steering bias of +-0.08 ... 0.15 on some strokes (a chance of 0.3 a bout, held for 2 ...
    4 strokes), the oar brought to rest (0) at a stroke's middle and trailed 1.5 ... 3 s between bouts. At rest 0.8 ...
    1.5 s at the start. Returns the list of bouts (t0, f_fast, n_fast, f_cruise, n_cruise, k, amp, bias) and T_end."""
    t = rng.uniform(0.8, 1.5)
    bouts = []
    for _ in range(n_bouts):
        ff, nf = rng.uniform(1.1, 1.5), int(rng.integers(3, 6))
        fc, nc = rng.uniform(0.7, 0.95), int(rng.integers(8, 17))
        bias = (float(rng.choice([-1.0, 1.0])) * rng.uniform(0.08, 0.15), int(rng.integers(1, nf + nc - 4)),
                int(rng.integers(2, 5))) if rng.uniform() < 0.3 else (0.0, 0, 0)
        bouts.append((t, ff, nf, fc, nc, rng.uniform(1.0, 2.0), rng.uniform(0.85, 1.0), bias))
        t += _bout_phase(np.zeros(1), ff, nf, fc, nc)[1] + rng.uniform(1.5, 3.0)
    return bouts, t + rng.uniform(0.3, 0.8)


def _bout_phase(s, ff, nf, fc, nc):
    """A bout's turns (in strokes) at its own time s: nf strokes at ff, then the frequency easing to fc over 2 s (a
    half-cosine in frequency), until nf + nc strokes; the bout's length."""
    T1 = nf / ff
    ramp = 2.0
    # the turns gained during the ramp: the integral of ff + (fc - ff) smooth_step(u / ramp) over 0 ... ramp, that is
    # ramp (ff + fc) / 2
    n_ramp = ramp * (ff + fc) / 2
    T = T1 + ramp + max(nc - n_ramp, 0.0) / fc
    u = np.clip(s - T1, 0.0, ramp)
    turns = np.where(s < T1, ff * s,
                     nf + ff * u + (fc - ff) * (u / 2 - ramp / (2 * math.pi) * np.sin(math.pi * u / ramp))
                     + fc * np.clip(s - T1 - ramp, 0.0, None))
    return turns, T


def blade_sweep(t, bouts):
    t = np.asarray(t, float)
    x = np.zeros(len(t))
    for t0, ff, nf, fc, nc, k, amp, (b, b0, bn) in bouts:
        s = t - t0
        turns, T = _bout_phase(s, ff, nf, fc, nc)
        n_all = math.floor(float(_bout_phase(np.array([T]), ff, nf, fc, nc)[0][0]) * 2) / 2
        m = (s >= 0) & (turns < n_all)
        ph = 2 * math.pi * turns[m]
        env = smooth_step(turns[m] / 0.5)
        wave = np.tanh(k * np.sin(ph)) / math.tanh(k)
        x[m] = (amp - abs(b)) * env * wave
        if bn > 0:
            on = m & (turns >= b0) & (turns < b0 + bn)
            x[on] += b * np.sin(math.pi * (turns[on] - b0) / bn) ** 2
    return x


# ---- out of vocabulary: a Lissajous scan ----

def lissajous(rng, T_min):
    """A two-axis scanner tracing Lissajous figures (a microscope's fast non-raster scan: Tuma et al., "high-speed
    multiresolution scanning probe microscopy based on Lissajous scan trajectories", Nanotechnology 23 (2012) 185501):
    X at 0.8 ... 1.6 Hz, Y at p / q of it (3/2, 4/3, 5/4 or 5/3) detuned by 1 ... 2 % so that the figure precesses, both
    under the scan's size: 3 ... 5 plateaus (0.4 ... 1, one 1) joined by 1 s half-cosine zooms. Faded in over 1 s at
    0.6 ... 1.2 s, out over 1 s at the end. Returns a dict of the programme."""
    t_on = rng.uniform(0.6, 1.2)
    fx = rng.uniform(0.8, 1.6)
    p, q = [(3, 2), (4, 3), (5, 4), (5, 3)][int(rng.integers(4))]
    fy = fx * p / q * (1.0 + float(rng.choice([-1.0, 1.0])) * rng.uniform(0.01, 0.02))
    n = int(rng.integers(3, 6))
    lev = rng.uniform(0.4, 1.0, n)
    lev[int(rng.integers(n))] = 1.0
    kt = [t_on]
    kv = [lev[0]]
    edges = np.sort(rng.uniform(0.15, 0.85, n - 1)) * T_min + t_on
    for e, lv in zip(edges, lev[1:]):
        kt += [e, e + 1.0]
        kv += [kv[-1], lv]
    kt.append(t_on + T_min)
    kv.append(kv[-1])
    return dict(t_on=t_on, t_off=t_on + T_min, T_end=t_on + T_min + rng.uniform(0.4, 0.8), fx=fx, fy=fy, pq=(p, q),
                phx=rng.uniform(0, 2 * math.pi), phy=rng.uniform(0, 2 * math.pi), kt=kt, kv=kv)


def lissajous_xy(t, prog):
    """The two axes on times t: the scan's size (a half-cosine path through the plateaus) times sin(2 pi f t + phase),
    faded in and out."""
    t = np.asarray(t, float)
    size = through_points(t, prog["kt"], prog["kv"]) * fade(t, prog["t_on"], prog["t_off"], 1.0)
    return (size * np.sin(2 * math.pi * prog["fx"] * t + prog["phx"]),
            size * np.sin(2 * math.pi * prog["fy"] * t + prog["phy"]))

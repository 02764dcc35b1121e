"""Excitations of the HOLDOUT37 set (``cases_holdout37.py``), each beside its source; the mechanisms are in
:mod:`.mechanisms37`. Citations written from memory in this session (none was re-read), as in mechanisms37.

Every generator draws a programme from ``rng`` and returns its parameters; its companion evaluates the path on any
times, normalised to about -1 ... 1 (or 0 ... 1 for the unipolar ones), at rest (exactly 0) before the programme starts
and after it ends; the cases scale it to volts.
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


# ---- clean: harmonic tremor at a volcano ----

def volcanic_tremor(rng, T_min):
    """Harmonic tremor as a broadband seismometer records it near an active vent (replayed, time-compressed): a
    fundamental whose frequency glides (the "gliding spectral lines" of harmonic tremor, e.g. Hellweg 2000 at Lascar,
    Neuberg 2000 at Soufriere Hills) between 0.8 and 2.6 Hz through 4 ... 6 knots (the glides smooth, a monotone cubic
    through the knots' log frequencies), with 3 ... 5 overtones at integer multiples (amplitudes 0.5 ... 0.9 / n,
    random phases: a random-phase multisine riding the glide), the amplitude surging (a smooth envelope through random
    levels 0.35 ... 1 every 2 ... 4 s), and long-period events (a decaying 0.6 ... 1.2 Hz wavelet, 0.8 ... 1.2 of the
    tremor's level, decaying over 1 ... 2 s) every 5 ... 9 s. Faded in and out over 1.5 s, at rest 0.4 ... 0.8 s at
    either end. Returns a dict of the programme."""
    t_on = rng.uniform(0.4, 0.8)
    t_off = t_on + T_min
    n_k = int(rng.integers(4, 7))
    kt = np.r_[t_on, np.sort(rng.uniform(t_on + 1.0, t_off - 1.0, n_k - 2)), t_off]
    kf = np.log(rng.uniform(0.8, 2.6, n_k))
    n_h = int(rng.integers(3, 6))
    harm = [(n, rng.uniform(0.5, 0.9) / n, rng.uniform(0, 2 * math.pi)) for n in range(1, n_h + 1)]
    et = np.arange(t_on, t_off + 4.0, rng.uniform(2.0, 4.0))
    ev = rng.uniform(0.35, 1.0, len(et))
    lps = []
    tc = t_on + rng.uniform(2.0, 4.0)
    while tc < t_off - 3.0:
        lps.append((tc, rng.uniform(0.6, 1.2), rng.uniform(0.8, 1.2), rng.uniform(1.0, 2.0),
                    rng.uniform(0, 2 * math.pi)))
        tc += rng.uniform(5.0, 9.0)
    return dict(t_on=t_on, t_off=t_off, T_end=t_off + rng.uniform(0.4, 0.8), kt=kt, kf=kf, harm=harm, et=et, ev=ev,
                lps=lps)


def tremor_frequency(t, prog):
    """The fundamental's frequency: the monotone cubic (PCHIP) through the knots' log frequencies, held outside."""
    t = np.clip(np.asarray(t, float), prog["kt"][0], prog["kt"][-1])
    return np.exp(PchipInterpolator(prog["kt"], prog["kf"])(t))


def tremor_ground_velocity(t, prog):
    """The tremor on times t (uniform, starting at 0): the phase the integral of the frequency (the trapezoidal rule on
    t), the overtones on it, under the envelope, plus the long-period events, faded in and out."""
    t = np.asarray(t, float)
    f = tremor_frequency(t, prog)
    phase = 2 * math.pi * np.r_[0.0, np.cumsum(0.5 * (f[1:] + f[:-1]) * np.diff(t))]
    x = sum(a * np.sin(n * phase + p) for n, a, p in prog["harm"])
    env = PchipInterpolator(prog["et"], prog["ev"])(np.clip(t, prog["et"][0], prog["et"][-1]))
    x = x * env
    for t0, fl, amp, dec, ph in prog["lps"]:
        s = t - t0
        m = s >= 0
        x[m] += amp * np.sin(2 * math.pi * fl * s[m] + ph) * np.exp(-s[m] / dec) * smooth_step(s[m] / 0.15)
    return x * fade(t, prog["t_on"], prog["t_off"], 1.5)


# ---- creep: a dental chair through a treatment ----

def dental_chair(rng):
    """A dental chair's seat height through a treatment (unipolar, holds): from its floor position raised in 2 ... 3
    steps (each held 4 ... 7 s while the patient settles) to the working height (0.55 ... 0.75), held while the dentist
    works (8 ... 16 s), fine adjustments of +-0.04 ... 0.12 each held 5 ... 10 s, raised to the top (1) for an
    examination (held 6 ... 12 s), lowered to the rinsing height (0.2 ... 0.4, held 5 ... 9 s), back up to work (held
    8 ... 14 s, adjusted once or twice), and lowered in 2 ... 3 steps to the floor at the end (each held 4 ... 7 s, the
    floor 4 ... 8 s); each move a half-cosine ramp of 1.2 ... 3 s (the chair's hydraulic pump). The chair starts at the
    floor (0) after 1 ... 2 s. Returns (times, values)."""
    def move(v):
        times.append(times[-1] + rng.uniform(1.2, 3.0))
        vals.append(float(v))

    def hold(lo, hi):
        times.append(times[-1] + rng.uniform(lo, hi))
        vals.append(vals[-1])
    times, vals = [0.0, rng.uniform(1.0, 2.0)], [0.0, 0.0]
    work = rng.uniform(0.55, 0.75)
    n_up = int(rng.integers(2, 4))
    for k in range(1, n_up):
        move(work * k / n_up * rng.uniform(0.9, 1.1))
        hold(4.0, 7.0)
    move(work)
    hold(8.0, 16.0)
    for _ in range(int(rng.integers(2, 4))):
        move(np.clip(vals[-1] + rng.choice([-1.0, 1.0]) * rng.uniform(0.04, 0.12), 0.45, 0.9))
        hold(5.0, 10.0)
    move(1.0)
    hold(6.0, 12.0)
    move(rng.uniform(0.2, 0.4))
    hold(5.0, 9.0)
    move(work)
    hold(8.0, 14.0)
    for _ in range(int(rng.integers(1, 3))):
        move(np.clip(vals[-1] + rng.choice([-1.0, 1.0]) * rng.uniform(0.04, 0.12), 0.45, 0.9))
        hold(5.0, 10.0)
    n_dn = int(rng.integers(2, 4))
    top = vals[-1]
    for k in range(n_dn - 1, 0, -1):
        move(top * k / n_dn * rng.uniform(0.9, 1.1))
        hold(4.0, 7.0)
    move(0.0)
    hold(4.0, 8.0)
    return times, vals


# ---- rate: a horse through its gaits ----

#: each gait's stride frequency (Hz) and its limb angle's harmonics (amplitude, phase) on the stride's phase
GAITS = {
    "halt": (0.0, ()),
    "walk": (0.9, ((1.0, 0.0), (0.18, 0.6), (0.1, 1.9), (0.05, 0.4))),
    "trot": (1.45, ((1.0, 0.0), (0.32, 1.2), (0.08, 2.3))),
    "canter": (1.8, ((1.0, 0.0), (0.26, 2.0), (0.2, 0.8), (0.06, 1.1))),
    "gallop": (2.3, ((1.0, 0.0), (0.36, 2.6), (0.12, 0.3))),
}


def horse_gaits(rng, n_changes):
    """A horse's foreleg (its protraction angle) through a schooling session: from a halt, n_changes gait changes up
    and down the ladder walk - trot - canter - gallop (never skipping a gait, mostly one step at a time; each gait held
    3 ... 6 s, each transition 0.6 ... 1.4 s, the stride frequency and the harmonics' blend gliding through it: the
    limb's waveform per gait after the gait studies, e.g. Hildebrand, Science 150 (1965) 701, idealised to a few
    harmonics), and back to a halt; the swing's amplitude grows with speed (0.55 at the walk ... 1 at the gallop, times
    0.9 ... 1.1 per bout). Returns the list of (gait, t_start, t_end_of_transition_into_it, amplitude) and T_end."""
    order = ["walk", "trot", "canter", "gallop"]
    amp_of = {"walk": 0.55, "trot": 0.72, "canter": 0.86, "gallop": 1.0}
    t = rng.uniform(0.8, 1.5)
    seq = [("halt", 0.0, 0.0, 0.0)]
    level = 0
    seq.append(("walk", t, t + rng.uniform(0.6, 1.4), amp_of["walk"] * rng.uniform(0.9, 1.1)))
    for _ in range(n_changes):
        t = seq[-1][2] + rng.uniform(3.0, 6.0)
        if level == 0:
            level = 1
        elif level == 3:
            level = 2
        else:
            level += int(rng.choice([-1, 1], p=[0.35, 0.65]))
        g = order[level]
        seq.append((g, t, t + rng.uniform(0.6, 1.4), amp_of[g] * rng.uniform(0.9, 1.1)))
    while level > 0:
        t = seq[-1][2] + rng.uniform(3.0, 6.0)
        level -= 1
        seq.append((order[level], t, t + rng.uniform(0.6, 1.4), amp_of[order[level]] * rng.uniform(0.9, 1.1)))
    t = seq[-1][2] + rng.uniform(3.0, 6.0)
    seq.append(("halt", t, t + rng.uniform(1.0, 1.6), 0.0))
    return seq, seq[-1][2] + rng.uniform(0.8, 1.5)


def _gait_weights(t, seq):
    """The blend of the gaits at times t: each transition a half-cosine from the previous gait to the next."""
    w = np.zeros((len(seq), len(t)))
    w[0] = 1.0
    for i in range(1, len(seq)):
        s = smooth_step((t - seq[i][1]) / (seq[i][2] - seq[i][1]))
        w[:i] *= (1.0 - s)
        w[i] = s
    return w


def foreleg_angle(t, seq):
    """The foreleg's angle on times t (uniform, starting at 0): the stride's phase the integral of the blended stride
    frequency (trapezoidal), the blended gaits' harmonics on it times the blended amplitude."""
    t = np.asarray(t, float)
    w = _gait_weights(t, seq)
    f = sum(w[i] * GAITS[g][0] for i, (g, *_) in enumerate(seq))
    amp = sum(w[i] * a for i, (_, _, _, a) in enumerate(seq))
    phase = 2 * math.pi * np.r_[0.0, np.cumsum(0.5 * (f[1:] + f[:-1]) * np.diff(t))]
    x = np.zeros(len(t))
    for i, (g, *_) in enumerate(seq):
        if g != "halt":
            x += w[i] * sum(a * np.sin(n * phase + p) for n, (a, p) in enumerate(GAITS[g][1], start=1))
    return amp * x


# ---- drift: labour contractions on a tocodynamometer ----

def labour(rng, T_min):
    """Uterine activity on a tocodynamometer in active labour (replayed, time-compressed about tenfold): a resting
    tone (0.06 ... 0.12), contractions every 11 ... 17 s lasting 6 ... 10 s, each a skewed bell (a raised-cosine rise
    over 0.4 ... 0.5 of it, a slower fall), 0.55 ... 0.95 above the tone (one of them to 1), now and then (a chance of
    0.3) a small coupled contraction (0.2 ... 0.35) right after one, and two slow tone waves (2 ... 5 % of the tone at
    0.03 ... 0.08 Hz). Rests at 0 for 0.8 ... 1.5 s, the
    tone faded in over 2 s; ends faded out over 2 s. Returns a dict of the programme."""
    t_on = rng.uniform(0.8, 1.5)
    tone = rng.uniform(0.06, 0.12)
    cs = []
    tc = t_on + rng.uniform(2.5, 5.0)
    while tc < t_on + T_min - 10.0:
        D = rng.uniform(6.0, 10.0)
        cs.append([tc, D, rng.uniform(0.4, 0.5), rng.uniform(0.55, 0.95)])
        if rng.uniform() < 0.3:
            cs.append([tc + D + rng.uniform(0.5, 1.5), rng.uniform(2.5, 4.0), 0.45, rng.uniform(0.2, 0.35)])
        tc += rng.uniform(11.0, 17.0)
    big = [c for c in cs if c[3] >= 0.5]
    big[int(rng.integers(len(big)))][3] = 1.0 - tone
    waves = [(rng.uniform(0.02, 0.05), rng.uniform(0.03, 0.08), rng.uniform(0, 2 * math.pi)) for _ in range(2)]
    t_off = max(t_on + T_min, cs[-1][0] + cs[-1][1] + 3.0)
    return dict(t_on=t_on, t_off=t_off, T_end=t_off + rng.uniform(0.8, 1.5), tone=tone, cs=[tuple(c) for c in cs],
                waves=waves)


def contraction(s, D, rise):
    """One contraction's shape on its own time s (0 ... D): a half-cosine up over rise D, down over the rest; 0
    outside."""
    s = np.asarray(s, float)
    up = smooth_step(s / (rise * D))
    down = smooth_step((D - s) / ((1.0 - rise) * D))
    return np.where((s > 0) & (s < D), np.minimum(up, down), 0.0)


def uterine_pressure(t, prog):
    t = np.asarray(t, float)
    x = prog["tone"] * (1.0 + sum(a * np.sin(2 * math.pi * f * t + p) for a, f, p in prog["waves"]))
    for t0, D, rise, amp in prog["cs"]:
        x = x + amp * contraction(t - t0, D, rise)
    return x * fade(t, prog["t_on"], prog["t_off"], 2.0)


# ---- asymmetry: a basketball dribbled ----

def dribbling(rng, n_series):
    """A basketball's height against the player's waist while dribbled (the floor at -1, the hand's reach at +1):
    n_series series of dribbles (6 ... 14 each) at 1.5 ... 2.6 bounces a second, either low (0.45 ... 0.7 of the reach,
    faster) or high (0.8 ... 1), a series of crossovers now and then (the bounces alternating 0.75 ... 0.9 and 0.95 ...
    1 as the ball changes hands); within a bounce the ball is pushed down from the hand and falls (a 1.5-power in time
    from the top, zero speed there), strikes the floor (the velocity reverses: a cusp) and rises back symmetrically.
    Between series the ball is held at the waist (0) for 1 ... 3 s, reached by a half-cosine over 0.3 s. Returns the
    list of bounces (t0, T, top, floor) and T_end."""
    t = rng.uniform(0.8, 1.5)
    bounces = []
    for _ in range(n_series):
        kind = rng.choice(["low", "high", "cross"])
        f = rng.uniform(1.9, 2.6) if kind == "low" else rng.uniform(1.5, 2.1)
        n = int(rng.integers(6, 15))
        t += 0.3
        for i in range(n):
            T = 1.0 / (f * rng.uniform(0.95, 1.05))
            if kind == "low":
                top = rng.uniform(0.45, 0.7)
            elif kind == "high":
                top = rng.uniform(0.8, 1.0)
            else:
                top = rng.uniform(0.75, 0.9) if i % 2 else rng.uniform(0.95, 1.0)
            bounces.append((t, T, top, -1.0))
            t += T
        t += 0.3 + rng.uniform(1.0, 3.0)
    return bounces, t + rng.uniform(0.5, 1.0)


def ball_height(t, bounces):
    """The ball's height on times t: in each bounce (s its phase 0 ... 1, u = |2 s - 1| 1 at the hand and 0 at the
    floor) floor + (top - floor) (1 - (1 - u)^1.5): leaving the hand at zero speed, a cusp at the floor at mid-bounce;
    the series entered and left from the waist (0) by half-cosine ramps over 0.3 s."""
    t = np.asarray(t, float)
    x = np.zeros(len(t))
    b = np.asarray(bounces, float)
    i = np.searchsorted(b[:, 0], t, side="right") - 1
    ok = i >= 0
    s = np.zeros(len(t))
    s[ok] = (t[ok] - b[i[ok], 0]) / b[i[ok], 1]
    m = ok & (s < 1.0)
    u = np.abs(2 * s[m] - 1)                          # 1 at the hand, 0 at the floor
    top, floor = b[i[m], 2], b[i[m], 3]
    x[m] = floor + (top - floor) * (1.0 - (1.0 - u) ** 1.5)
    # the approaches from and returns to the waist
    ends = b[:, 0] + b[:, 1]
    first = np.r_[True, np.abs(ends[:-1] - b[1:, 0]) > 1e-9]
    last = np.r_[np.abs(ends[:-1] - b[1:, 0]) > 1e-9, True]
    for t0, top in b[first][:, [0, 2]]:
        w = (t >= t0 - 0.3) & (t < t0)
        x[w] = top * smooth_step((t[w] - t0 + 0.3) / 0.3)
    for te, top in zip(ends[last], b[last, 2]):
        w = (t >= te) & (t < te + 0.3)
        x[w] = top * (1.0 - smooth_step((t[w] - te) / 0.3))
    return x


# ---- saturation: an infant's non-nutritive sucking ----

def suckling(rng, T_min):
    """An infant's jaw excursion while sucking on a pacifier (non-nutritive sucking: Wolff, Pediatrics 42 (1968) 943;
    bursts and pauses): bursts of 6 ... 14 sucks at 1.7 ... 2.4 a second, each suck a skewed cycle (the jaw lowered
    quickly over 0.35 ... 0.45 of it, raised more slowly above its rest, 0.95 of the depth), the amplitude waxing over
    the burst's first three sucks and waning over its last three (0.6 ... 1 at its peak), pauses of 2 ... 5 s at rest,
    and now and then (a chance of 0.4) a swallow ending a burst (the jaw closed firmly: a slower excursion above rest
    over 0.6 ... 0.9 s, 0.9 ... 1.1 high). At rest (0) 0.6 ... 1.2 s at either end. Returns the list of bursts (t0, f,
    n, amp, skew, swallow, its height) and T_end."""
    t = rng.uniform(0.6, 1.2)
    bursts = []
    while True:
        f, n = rng.uniform(1.7, 2.4), int(rng.integers(6, 15))
        sw = rng.uniform(0.6, 0.9) if rng.uniform() < 0.4 else 0.0
        bursts.append((t, f, n, rng.uniform(0.6, 1.0), rng.uniform(0.35, 0.45), sw, rng.uniform(0.9, 1.1)))
        t += n / f + sw + rng.uniform(2.0, 5.0)
        if t > T_min:
            break
    return bursts, t + rng.uniform(0.6, 1.2)


def _suck_cycle(s, skew):
    """One suck on its phase s (0 ... 1): 0 at both ends, down (to -1) over the first skew of it, up to +0.95 and back
    over the rest."""
    s = np.asarray(s, float)
    a = np.where(s < skew, -np.sin(math.pi * s / skew), 0.0)
    b = np.where(s >= skew, 0.95 * np.sin(math.pi * (s - skew) / (1.0 - skew)), 0.0)
    return a + b


def jaw_excursion(t, bursts):
    t = np.asarray(t, float)
    x = np.zeros(len(t))
    for t0, f, n, amp, skew, sw, deep in bursts:
        s = (t - t0) * f
        m = (s >= 0) & (s < n)
        k = np.floor(s[m])
        env = amp * np.minimum(1.0, np.minimum((k + 1) / 3.0, (n - k) / 3.0))
        x[m] = env * _suck_cycle(s[m] - k, skew)
        if sw > 0:
            te = t0 + n / f
            m = (t >= te) & (t < te + sw)
            x[m] = deep * np.sin(math.pi * (t[m] - te) / sw) ** 2
    return x


# ---- delay: swallows on an oesophageal manometry channel ----

def swallows(rng, T_min):
    """A distal channel of oesophageal manometry during a swallow series (time-compressed about twofold): wet swallows
    every 5 ... 9 s, each a peristaltic contraction arriving 1.5 ... 2.5 s after the swallow (a bell: a Gaussian in
    time, 0.5 ... 0.9 s wide, 0.45 ... 1 high, one of them 1) preceded by a small pharyngeal blip (0.08 ... 0.15, 0.15
    s wide) at the swallow; a double-peaked wave now and then (a chance of 0.3: a second peak 0.5 ... 0.8 of the first,
    0.6 ... 1 s later), a failed (weak, 0.15 ... 0.3) one now and then (a chance of 0.15). The channel's baseline held
    at 0 by a window (half-cosine ramps over 0.5 s) from 1 s before the first swallow to 1 s after the last wave; at
    rest (0) for 1 ... 2 s at either end. Returns dict(t_on, t_off, T_end, sw: (t0, latency, width, height, second,
    gap, blip))."""
    t = rng.uniform(2.0, 3.0)
    sw = []
    while True:
        h = rng.uniform(0.45, 1.0) if rng.uniform() > 0.15 else rng.uniform(0.15, 0.3)
        second = rng.uniform(0.5, 0.8) if rng.uniform() < 0.3 else 0.0
        sw.append([t, rng.uniform(1.5, 2.5), rng.uniform(0.5, 0.9), h, second, rng.uniform(0.6, 1.0),
                   rng.uniform(0.08, 0.15)])
        t += rng.uniform(5.0, 9.0)
        if t > T_min:
            break
    sw[int(rng.integers(len(sw)))][3] = 1.0
    t_on = sw[0][0] - 1.0
    t_off = max(s[0] + s[1] + s[5] + 2.0 * s[2] for s in sw) + 1.0
    return dict(t_on=t_on, t_off=t_off, T_end=t_off + rng.uniform(1.0, 2.0), sw=[tuple(s) for s in sw])


def manometry(t, prog):
    t = np.asarray(t, float)
    x = np.zeros(len(t))
    for t0, lat, w, h, second, gap, blip in prog["sw"]:
        x += blip * np.exp(-0.5 * ((t - t0 - 0.3) / 0.15) ** 2)
        x += h * np.exp(-0.5 * ((t - t0 - lat) / (w / 2.355)) ** 2)
        if second > 0:
            x += second * h * np.exp(-0.5 * ((t - t0 - lat - gap) / (w / 2.355)) ** 2)
    return x * fade(t, prog["t_on"], prog["t_off"], 0.5)


# ---- initial state: a rocking chair ----

def rocking_chair(rng, n_pushes):
    """A rocking chair's angle: started by the sitter's push off the floor, rocking at its own period (1.2 ... 1.7 s,
    lengthening slightly with the amplitude: the rocker's arc), decaying between pushes (its amplitude e-folding over
    4 ... 9 s: the rockers' rolling resistance and the sitter's damping), pushed again n_pushes times (each push
    raising the amplitude to 0.6 ... 1 over one cycle), and stopped by the feet at the end (over 0.8 ... 1.5 s). At
    rest (0) 0.8 ... 1.5 s before the first push and at the end. Returns dict(pushes=[(t, level)], T0, chi, tau,
    t_stop, stop) and T_end."""
    t = rng.uniform(0.8, 1.5)
    pushes = []
    for _ in range(n_pushes):
        pushes.append((t, rng.uniform(0.6, 1.0)))
        t += rng.uniform(4.0, 8.0)
    stop = rng.uniform(0.8, 1.5)
    return dict(pushes=pushes, T0=rng.uniform(1.2, 1.7), chi=rng.uniform(0.04, 0.1), tau=rng.uniform(4.0, 9.0),
                t_stop=t, stop=stop), t + stop + rng.uniform(0.8, 1.5)


def chair_amplitude(t, prog):
    """The rocking's amplitude: 0 before the first push; each push a half-cosine rise over one period from the
    decayed amplitude to its level; exponential decay with tau between; brought to 0 over ``stop`` s at t_stop."""
    t = np.asarray(t, float)
    A = np.zeros(len(t))
    prev_t, prev_a = None, 0.0
    T0 = prog["T0"]
    for tp, lev in prog["pushes"]:
        start = prev_a * math.exp(-(tp - prev_t) / prog["tau"]) if prev_t is not None else 0.0
        m = t >= tp
        s = smooth_step((t[m] - tp) / T0)
        A[m] = (start + (lev - start) * s) * np.where(t[m] > tp + T0, np.exp(-(t[m] - tp - T0) / prog["tau"]), 1.0)
        prev_t, prev_a = tp + T0, lev
    A *= 1.0 - smooth_step((t - prog["t_stop"]) / prog["stop"])
    return A


def chair_angle(t, prog):
    """The angle on times t (uniform, starting at 0): A(t) sin(phase), the phase the integral of 1 / (T0 (1 + chi
    A^2)) (the period lengthening with the amplitude), starting at the first push."""
    t = np.asarray(t, float)
    A = chair_amplitude(t, prog)
    f = 1.0 / (prog["T0"] * (1.0 + prog["chi"] * A * A))
    f = np.where(t >= prog["pushes"][0][0], f, 0.0)
    phase = 2 * math.pi * np.r_[0.0, np.cumsum(0.5 * (f[1:] + f[:-1]) * np.diff(t))]
    return A * np.sin(phase)


# ---- pair: kettlebell swings ----

def kettlebell(rng, n_sets):
    """A kettlebell's angle (hanging at 0, forward positive) through n_sets sets of two-handed swings: the bell hiked
    back between the legs (-0.85 ... -1), then 6 ... 12 swings at 0.75 ... 0.95 a second up to chest height (0.85 ...
    1, the first two three quarters of that), each with a float at the top (0.08 ... 0.18 s held) and the hip snap (a
    half-cosine swing, the backswing reaching -0.85 ... -1; the last backswing only to -0.3), parked back at 0 after the
    set and rested 2 ... 4 s. Returns (times, values) and T_end."""
    times, vals = [0.0, rng.uniform(0.8, 1.5)], [0.0, 0.0]
    for _ in range(n_sets):
        times.append(times[-1] + rng.uniform(0.5, 0.8))
        vals.append(-rng.uniform(0.85, 1.0))
        n = int(rng.integers(6, 13))
        f = rng.uniform(0.75, 0.95)
        for i in range(n):
            half = 0.5 / f
            top = rng.uniform(0.85, 1.0) * (0.75 if i < 2 else 1.0)
            times.append(times[-1] + half)
            vals.append(top)
            times.append(times[-1] + rng.uniform(0.08, 0.18))
            vals.append(top)
            times.append(times[-1] + half)
            vals.append(-rng.uniform(0.85, 1.0) if i < n - 1 else -0.3)
        times.append(times[-1] + rng.uniform(0.6, 1.0))
        vals.append(0.0)
        times.append(times[-1] + rng.uniform(2.0, 4.0))
        vals.append(0.0)
    return times, vals, times[-1] + rng.uniform(0.5, 1.0)


# ---- out of vocabulary: hiccups ----

def hiccup_bouts(rng, T_min):
    """Breathing flow through a bout of hiccups (singultus: a sudden inspiratory contraction of the diaphragm cut
    off about 35 ms later by the glottis' closure, Davis, Brain 93 (1970) 851; time-stretched so the
    record resolves it): quiet breathing (0.4 ... 0.6 Hz, +-0.25 ... 0.4, slowly varying) with hiccups every 2 ... 4.5
    s in bouts of 4 ... 8, each an inspiratory spike (0.75 ... 1 in 0.06 ... 0.1 s), cut off abruptly (over 0.03 s) and
    followed by a slower expiratory rebound (0.6 ... 0.95 of the spike, over 0.35 ... 0.6 s); bouts 3 ... 6 s apart.
    At rest (0) 0.6 ... 1.2 s at either end, the breathing faded in and out over 1 s. Returns a dict of the
    programme."""
    t_on = rng.uniform(0.6, 1.2)
    hic = []
    t = t_on + rng.uniform(1.5, 3.0)
    while t < t_on + T_min - 3.0:
        for _ in range(int(rng.integers(4, 9))):
            hic.append((t, rng.uniform(0.75, 1.0), rng.uniform(0.06, 0.1), rng.uniform(0.6, 0.95),
                        rng.uniform(0.35, 0.6)))
            t += rng.uniform(2.0, 4.5)
            if t > t_on + T_min - 3.0:
                break
        t += rng.uniform(3.0, 6.0)
    br = [(rng.uniform(0.4, 0.6), rng.uniform(0.25, 0.4), rng.uniform(0, 2 * math.pi), rng.uniform(0.05, 0.15))]
    t_off = t_on + T_min
    return dict(t_on=t_on, t_off=t_off, T_end=t_off + rng.uniform(0.6, 1.2), hic=hic, br=br)


def hiccup_flow(t, prog):
    t = np.asarray(t, float)
    f, a, p, m = prog["br"][0]
    x = a * (1.0 + 0.3 * np.sin(2 * math.pi * m * f * t)) * np.sin(2 * math.pi * f * t + p)
    x = x * fade(t, prog["t_on"], prog["t_off"], 1.0)
    for t0, amp, rise, reb, dur in prog["hic"]:
        s = t - t0
        up = (s >= 0) & (s < rise)
        x[up] += amp * smooth_step(s[up] / rise)
        cut = (s >= rise) & (s < rise + 0.03)
        x[cut] += amp * (1.0 - smooth_step((s[cut] - rise) / 0.03))
        rb = (s >= rise + 0.03) & (s < rise + 0.03 + dur)
        x[rb] -= reb * amp * np.sin(math.pi * (s[rb] - rise - 0.03) / dur) ** 2
    return x

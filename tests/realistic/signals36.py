"""Excitations of the HOLDOUT36 set (``cases_holdout36.py``), each beside its source; the mechanisms are in
:mod:`.mechanisms36`. Citations written from memory in this session (none was re-read), as in mechanisms36.

Every generator returns a path normalised to about -1 ... 1 (or 0 ... 1 for the unipolar ones) that starts at 0 at
rest; the cases scale it to volts.
"""

import math

import numpy as np


def ease(s):
    """The half-cosine ease (1 - cos(pi s)) / 2 on 0 ... 1 (zero speed at both ends), clipped outside."""
    s = np.clip(np.asarray(s, float), 0.0, 1.0)
    return 0.5 * (1.0 - np.cos(math.pi * s))


def keyframes(t, times, values):
    """The path through (times, values), eased between consecutive points (a hold where two are equal), values[0]
    before the first time and values[-1] after the last."""
    t = np.asarray(t, float)
    out = np.full(len(t), float(values[0]))
    for k in range(len(times) - 1):
        ta, tb, a, b = times[k], times[k + 1], values[k], values[k + 1]
        m = t >= ta
        out[m] = a + (b - a) * ease((t[m] - ta) / (tb - ta))
    return out


def window(t, t0, T, ramp):
    """1 on t0 + ramp ... t0 + T - ramp, eased up and down over ramp at either end, 0 outside t0 ... t0 + T."""
    t = np.asarray(t, float)
    return ease((t - t0) / ramp) * ease((t0 + T - t) / ramp)


# ---- clean: the EEG of stage-2 sleep ----

def sleep_n2(rng, T_min):
    """Stage-2 (N2) sleep EEG as it drives the valve (a replayed recording): a background of theta (4 ... 7 Hz) and
    delta (0.5 ... 2 Hz) rhythms (sums of 6 sines each at random frequencies and phases, each sine 0.1 ... 0.18 and
    0.12 ... 0.2 over sqrt(6)), sleep spindles (Loomis, Harvey & Hobart 1935: 11 ... 15 Hz, 0.5 ... 2 s, waxing and
    waning as sin^2 of their span, amplitude 0.3 ... 0.65) every 2.5 ... 5 s and K-complexes (a sharp negative wave,
    then a slower positive one: two Gaussians, 0.08 ... 0.15 s and 0.2 ... 0.35 s wide, 0.3 ... 0.45 s apart, the
    negative 0.55 ... 0.9 deep (one 1), the positive 0.5 ... 0.8 of it) every 6 ... 11 s; the events' spacing
    compressed, their waveforms as recorded. The whole faded in and out over 1 s, at rest for 0.5 ... 1 s at either
    end. Returns (events, T_end, t_on, t_off): spindles ("spindle", t0, T, f, amp, phase0), K-complexes ("k", t0, amp,
    w1, w2, gap, ratio), the background ("bg", [(f, amp, phase0)]); t_on ... t_off the span faded in and out."""
    t_on = rng.uniform(0.5, 1.0)
    T_end = t_on + T_min + rng.uniform(0.5, 1.0)
    ev = []
    bg = [(f, rng.uniform(0.1, 0.18) / 6 ** 0.5, rng.uniform(0, 2 * math.pi)) for f in rng.uniform(4.0, 7.0, 6)]
    bg += [(f, rng.uniform(0.12, 0.2) / 6 ** 0.5, rng.uniform(0, 2 * math.pi)) for f in rng.uniform(0.5, 2.0, 6)]
    ev.append(("bg", bg))
    tc = t_on + rng.uniform(1.0, 2.5)
    while tc < t_on + T_min - 2.0:
        T = rng.uniform(0.5, 2.0)
        ev.append(("spindle", tc, T, rng.uniform(11.0, 15.0), rng.uniform(0.3, 0.65), rng.uniform(0, 2 * math.pi)))
        tc += T + rng.uniform(2.5, 5.0)
    tc = t_on + rng.uniform(2.0, 5.0)
    ks = []
    while tc < t_on + T_min - 2.0:
        ks.append(["k", tc, rng.uniform(0.55, 0.9), rng.uniform(0.08, 0.15), rng.uniform(0.2, 0.35),
                   rng.uniform(0.3, 0.45), rng.uniform(0.5, 0.8)])
        tc += rng.uniform(6.0, 11.0)
    if ks:
        ks[int(rng.integers(len(ks)))][2] = 1.0
    ev += [tuple(k) for k in ks]
    return ev, T_end, t_on, t_on + T_min


def sleep_eeg(t, events, t_on, t_off):
    """The EEG: the background, the spindles and the K-complexes summed, under a fade in and out over 1 s."""
    t = np.asarray(t, float)
    x = np.zeros(len(t))
    for e in events:
        if e[0] == "bg":
            for f, a, p in e[1]:
                x += a * np.sin(2 * math.pi * f * t + p)
        elif e[0] == "spindle":
            _, t0, T, f, a, p = e
            m = (t >= t0) & (t <= t0 + T)
            s = (t[m] - t0) / T
            x[m] += a * np.sin(math.pi * s) ** 2 * np.sin(2 * math.pi * f * (t[m] - t0) + p)
        else:
            _, t0, a, w1, w2, gap, ratio = e
            x += a * (-np.exp(-((t - t0) / w1) ** 2) + ratio * np.exp(-((t - t0 - gap) / w2) ** 2))
    return x * ease(t - t_on) * ease(t_off - t)


# ---- creep: a hot-air balloon's flight ----

def balloon_flight(rng):
    """A hot-air balloon's altitude over its ceiling through a (time-compressed) flight: from the ground, 6 ... 10
    legs, each a climb or a descent to a new level (0.15 ... 1 of the ceiling; the pilot's burns or the vent: at 0.08
    ... 0.2 of the ceiling a second, the envelope's inertia easing each start and end, plus 0.8 s) held in level flight
    for 2 ... 5 s; one leg to the ceiling; then the landing (to 0) and the basket on the ground. Returns (times,
    values)."""
    n = int(rng.integers(6, 11))
    levels = list(rng.uniform(0.15, 1.0, n))
    levels[int(rng.integers(n))] = 1.0
    times, vals = [0.0, rng.uniform(1.5, 3.0)], [0.0, 0.0]
    cur = 0.0
    for lv in levels + [0.0]:
        rate = rng.uniform(0.08, 0.2)
        move = abs(lv - cur) / rate + 0.8
        hold = rng.uniform(2.0, 5.0)
        times += [times[-1] + move, times[-1] + move + hold]
        vals += [lv, lv]
        cur = lv
    return times, vals


# ---- rate: a hand whisk ----

def whisking(rng, n_bouts):
    """A hand whisk across a bowl (its position, -1 ... 1): bouts of beating (4 ... 7 strokes a second, 0.55 ... 1 of
    the bowl, 1.5 ... 4 s, the stroke a sine with a 0.1 ... 0.25 second harmonic: the faster pull through the batter)
    and of folding (0.5 ... 1 strokes a second, 0.4 ... 0.8, 2 ... 4 strokes), each under an envelope eased over half a
    stroke, with the whisk lifted out (at 0) for 0.5 ... 2 s between; one beating bout across the whole bowl. Returns
    (bouts [(t0, T, f, amp, h2, phase2)], T_end)."""
    bouts, tc = [], rng.uniform(0.8, 1.5)
    beat = []
    for _ in range(n_bouts):
        if rng.random() < 0.6:
            f = rng.uniform(4.0, 7.0)
            T = max(3, round(rng.uniform(1.5, 4.0) * f)) / f
            bouts.append((tc, T, f, rng.uniform(0.55, 1.0), rng.uniform(0.1, 0.25), rng.uniform(0, 2 * math.pi)))
            beat.append(len(bouts) - 1)
        else:
            f = rng.uniform(0.5, 1.0)
            T = int(rng.integers(2, 5)) / f
            bouts.append((tc, T, f, rng.uniform(0.4, 0.8), 0.0, 0.0))
        tc += T + rng.uniform(0.5, 2.0)
    if not beat:
        f = rng.uniform(4.0, 7.0)
        T = max(3, round(rng.uniform(1.5, 4.0) * f)) / f
        bouts.append((tc, T, f, 1.0, rng.uniform(0.1, 0.25), rng.uniform(0, 2 * math.pi)))
        tc += T + rng.uniform(0.5, 2.0)
    else:
        j = beat[int(rng.integers(len(beat)))]
        bouts[j] = bouts[j][:3] + (1.0,) + bouts[j][4:]
    return bouts, tc + rng.uniform(0.5, 1.0)


def whisk_position(t, bouts):
    """The whisk's position: each bout's strokes (sin plus the second harmonic) under its eased envelope."""
    t = np.asarray(t, float)
    x = np.zeros(len(t))
    for t0, T, f, amp, h2, p2 in bouts:
        ph = 2 * math.pi * f * (t - t0)
        x += amp * window(t, t0, T, 0.5 / f) * (np.sin(ph) + h2 * np.sin(2 * ph + p2)) / (1.0 + h2)
    return x


# ---- drift: a geyser's eruptions ----

def geyser(rng, T_min):
    """The height of a cone geyser's water column (over its highest) through its eruptions, time compressed about
    twentyfold: a short eruption (1 ... 1.6 s of play) is followed by a short interval (3 ... 5 s), a long one (2.5 ...
    4 s) by a long interval (6 ... 9 s) (Old Faithful's bimodal intervals, each set by the eruption before it: Rinehart
    1980); each interval quiet at 0 but for 2 ... 5 preplay splashes (to 0.04 ... 0.15 and back in 0.2 ... 0.4 s) in
    its last 3 s; an eruption rises to 0.75 ... 1 in 0.4 ... 0.8 s, surges (+-3 ... 8 % at 1.5 ... 3 Hz) while the
    water lasts and falls into its steam phase (to 0.2 ... 0.35 over 0.3 ... 0.6 s, then to 0 over 1 ... 2 s). The
    highest surge is 1. Returns (times, values)."""
    times, vals = [0.0, rng.uniform(1.0, 2.0)], [0.0, 0.0]
    long_ = bool(rng.random() < 0.5)
    while times[-1] < T_min:
        gap = rng.uniform(6.0, 9.0) if long_ else rng.uniform(3.0, 5.0)
        t_e = times[-1] + gap                          # the eruption's start
        starts = np.sort(t_e - rng.uniform(0.5, min(3.0, gap - 0.5), int(rng.integers(2, 6))))
        for ts in starts:
            d = rng.uniform(0.2, 0.4)
            if ts > times[-1] + 0.05 and ts + d < t_e:
                times += [ts, ts + d / 2, ts + d]
                vals += [0.0, rng.uniform(0.04, 0.15), 0.0]
        times.append(t_e)
        vals.append(0.0)
        top = rng.uniform(0.75, 1.0)
        play = rng.uniform(2.5, 4.0) if rng.random() < 0.5 else rng.uniform(1.0, 1.6)
        long_ = play >= 2.5
        t1 = t_e + rng.uniform(0.4, 0.8)
        times.append(t1)
        vals.append(top)
        f = rng.uniform(1.5, 3.0)
        k = 1
        while k / (2 * f) < play - 0.1:
            times.append(t1 + k / (2 * f))
            vals.append(top * (1 + (-1) ** k * rng.uniform(0.03, 0.08)))
            k += 1
        times.append(t1 + play)
        vals.append(top)
        times.append(times[-1] + rng.uniform(0.3, 0.6))
        vals.append(rng.uniform(0.2, 0.35))
        times.append(times[-1] + rng.uniform(1.0, 2.0))
        vals.append(0.0)
    times.append(times[-1] + rng.uniform(1.0, 2.0))
    vals.append(0.0)
    vals = np.asarray(vals) / max(vals)
    return times, list(vals)


# ---- asymmetry: optokinetic nystagmus ----

def nystagmus(rng, n_trials):
    """The horizontal eye position (over the oculomotor range) of a subject watching a striped drum: each trial the drum
    turns one way (alternating) at 0.35 ... 0.7 of the range a second; the eye follows it (slow phases, gain 0.8 ...
    0.95), from -b to +a of the range on the drum's side (a 0.7 ... 1, b 0.1 ... 0.5), and snaps back by a saccade
    (0.03 ... 0.06 s); 3 ... 6 beats, their ends jittered by 10 %; between trials the drum stops and the eye fixates the
    centre (at 0) for 1 ... 2.5 s. One trial's first beat reaches the range's end. Returns (times, values)."""
    times, vals = [0.0, rng.uniform(0.8, 1.5)], [0.0, 0.0]
    side = float(rng.choice([-1, 1]))
    full = int(rng.integers(n_trials))
    for j in range(n_trials):
        speed = rng.uniform(0.35, 0.7) * rng.uniform(0.8, 0.95)
        a = 1.0 if j == full else rng.uniform(0.7, 1.0)
        b = rng.uniform(0.1, 0.5)
        # into the first slow phase from the centre
        start = -side * b * rng.uniform(0.9, 1.1)
        times.append(times[-1] + rng.uniform(0.03, 0.06))
        vals.append(start)
        for k in range(int(rng.integers(3, 7))):
            end = side * a * (1.0 if (j == full and k == 0) else rng.uniform(0.9, 1.0))
            times.append(times[-1] + abs(end - vals[-1]) / speed)
            vals.append(end)
            back = -side * b * rng.uniform(0.9, 1.1)
            times.append(times[-1] + rng.uniform(0.03, 0.06))
            vals.append(back)
        times.append(times[-1] + rng.uniform(0.03, 0.06))
        vals.append(0.0)
        times.append(times[-1] + rng.uniform(1.0, 2.5))
        vals.append(0.0)
        side = -side
    return times, vals


def piecewise_linear(t, times, values):
    """The path linear between the points (the eye's slow phases at a constant speed, the saccades as quick ramps),
    values[0] before the first time and values[-1] after the last."""
    return np.interp(np.asarray(t, float), times, values)


# ---- saturation: a dolphin's fluke strokes ----

def dolphin_swim(rng, T_min):
    """The heave of a bottlenose dolphin's flukes (over their largest) as it swims, time as recorded: cruising (1.2 ...
    2 strokes a second, 0.4 ... 0.6), sprints (2.2 ... 3.2 strokes a second, 0.8 ... 1: the tail beat's frequency and
    amplitude grow with the speed, Fish 1993), glides (the flukes still, at 0, 1 ... 2.5 s) and porpoising leaps (one
    hard stroke of 0.9 ... 1, then airborne 0.6 ... 1.1 s with the flukes still); each swimming bout 3 ... 8 strokes
    under an envelope eased over half a stroke. One sprint's strokes reach 1. Returns (bouts [(t0, T, f, amp, phase0)],
    T_end)."""
    bouts, tc = [], rng.uniform(0.8, 1.5)
    sprints = []
    while tc < T_min or not sprints:
        r = rng.random()
        if r < 0.4:
            f, amp = rng.uniform(1.2, 2.0), rng.uniform(0.4, 0.6)
        elif r < 0.75:
            f, amp = rng.uniform(2.2, 3.2), rng.uniform(0.8, 1.0)
            sprints.append(len(bouts))
        else:
            f = rng.uniform(1.5, 2.5)
            bouts.append((tc, 1.0 / f, f, rng.uniform(0.9, 1.0), float(rng.choice([0.0, math.pi]))))
            tc += 1.0 / f + rng.uniform(0.6, 1.1)
            continue
        T = int(rng.integers(3, 9)) / f
        bouts.append((tc, T, f, amp, float(rng.choice([0.0, math.pi]))))
        tc += T + (rng.uniform(1.0, 2.5) if rng.random() < 0.5 else rng.uniform(0.1, 0.3))
    j = sprints[int(rng.integers(len(sprints)))]
    bouts[j] = bouts[j][:3] + (1.0,) + bouts[j][4:]
    return bouts, tc + rng.uniform(0.8, 1.5)


def fluke_heave(t, bouts):
    """The flukes' heave: each bout's strokes (sines) under its envelope (a single stroke: the envelope eased over a
    quarter stroke)."""
    t = np.asarray(t, float)
    x = np.zeros(len(t))
    for t0, T, f, amp, p0 in bouts:
        ramp = 0.5 / f if T * f > 1.5 else 0.25 / f
        x += amp * window(t, t0, T, ramp) * np.sin(2 * math.pi * f * (t - t0) + p0)
    return x


# ---- delay: bouts of coughing ----

def cough_bouts(rng, T_min):
    """The expiratory flow of a patient's coughing (a flow meter sees only the expirations): bouts of 1 ... 4 coughs,
    2 ... 5 s of quiet between; each cough's flow rises to its peak in t_p = 0.03 ... 0.08 s (the glottis opening: the
    explosive phase) and decays as the lung empties, as u exp(1 - u) with u = 1 + (s - t_p) / t_d, t_d 0.25 ... 0.5 s
    (a gamma-like flow profile, e.g. the cough peak-flow literature), the coughs of a bout 0.45 ... 0.8 s apart, each
    from a smaller lung volume (0.65 ... 0.9 of the one before); the bouts' first peaks 0.6 ... 1 (one 1). Returns
    (coughs [(t0, t_peak, t_decay, peak)], T_end)."""
    coughs, tc = [], rng.uniform(1.0, 2.0)
    firsts = []
    while tc < T_min or not firsts:
        n = int(rng.integers(1, 5))
        pk = rng.uniform(0.6, 1.0)
        firsts.append(len(coughs))
        for _ in range(n):
            coughs.append((tc, rng.uniform(0.03, 0.08), rng.uniform(0.25, 0.5), pk))
            tc += rng.uniform(0.45, 0.8)
            pk *= rng.uniform(0.65, 0.9)
        tc += rng.uniform(2.0, 5.0)
    j = firsts[int(rng.integers(len(firsts)))]
    scale = 1.0 / coughs[j][3]
    coughs = [(a, b, c, min(d * scale, 1.0)) for a, b, c, d in coughs]
    return coughs, tc


def cough_flow(t, coughs):
    """The flow: each cough's rise (eased over t_p) and decay (u exp(1 - u), u = 1 + (s - t_p) / t_d: continuous at the
    peak, at rest before the cough), the coughs' flows summed."""
    t = np.asarray(t, float)
    x = np.zeros(len(t))
    for t0, tp, td, pk in coughs:
        s = t - t0
        rise = ease(s / tp)
        u = np.maximum(s - tp, 0.0) / td + 1.0            # 1 at the peak, then the gamma-like tail u exp(1 - u)
        x += pk * rise * np.where(s > tp, u * np.exp(1.0 - u), 1.0)
    return x


# ---- the initial state's record: sneezes ----

def sneezes(rng, n):
    """The airflow of a series of sneezes (out positive, in negative): each sneeze's preparatory inspirations, 2 ... 4
    of them growing ("ah... ah... ah": the earlier ones 0.2 ... 0.35 of the last, which is 0.85 ... 1.05 of the
    sneeze's peak, 0.35 ... 0.6 s each, 0.1 ... 0.3 s held between), then the expulsion ("choo!": the peak flow
    reached in 0.04 ... 0.08 s, decaying over 0.25 ... 0.45 s), and 1.5 ... 3.5 s of quiet breathing (at 0) between;
    the sneezes' peaks 0.6 ... 1 (one 1). Returns (phases: ("in", t0, T, -depth) and ("out", t0, t_peak, t_decay,
    peak), T_end)."""
    ph, tc = [], rng.uniform(1.0, 2.0)
    peaks = list(rng.uniform(0.6, 1.0, n))
    peaks[int(rng.integers(n))] = 1.0
    for pk in peaks:
        last = pk * rng.uniform(0.85, 1.05)
        depths = list(np.sort(rng.uniform(0.2, 0.35, int(rng.integers(1, 4))) * last)) + [last]
        for d in depths:
            T = rng.uniform(0.35, 0.6)
            ph.append(("in", tc, T, -d))
            tc += T + rng.uniform(0.1, 0.3)
        tp, td = rng.uniform(0.04, 0.08), rng.uniform(0.25, 0.45)
        ph.append(("out", tc, tp, td, pk))
        tc += tp + 5 * td + rng.uniform(1.5, 3.5)
    return ph, tc


def sneeze_flow(t, phases):
    """The flow: each inspiration a half-sine lobe (negative), each expulsion an eased rise to its peak and a decay
    u exp(1 - u) (u = 1 + (s - t_p) / t_d: continuous)."""
    t = np.asarray(t, float)
    x = np.zeros(len(t))
    for p in phases:
        if p[0] == "in":
            _, t0, T, a = p
            m = (t >= t0) & (t <= t0 + T)
            x[m] += a * np.sin(math.pi * (t[m] - t0) / T)
        else:
            _, t0, tp, td, pk = p
            s = t - t0
            u = np.maximum(s - tp, 0.0) / td + 1.0
            x += pk * ease(s / tp) * np.where(s > tp, u * np.exp(1.0 - u), 1.0)
    return x


# ---- the pair: a hammock swung by its sitter ----

def hammock(rng, T_min):
    """The sideways swing of a hammock (its seat's excursion over its largest): a pendulum of half-period 1.1 ... 1.6 s
    (each half-swing eased from one extreme to the next, as a pendulum's half cosine), losing 9 ... 22 % of its
    amplitude a half-swing to the air and the ropes (damping ratio 0.03 ... 0.08: exp(-pi zeta)), set going from rest
    by a push (a quarter swing to 0.15 ... 0.3) and kept going by the sitter's kicks off the floor (3 ... 6 half-swings
    at a time, each adding 0.12 ... 0.3 at the extreme), coasting between (3 ... 8 half-swings), until the sitter drags
    a foot (each half-swing keeping 0.4 ... 0.6) and gets out (at rest, 1 ... 2 s). Returns (times, values,
    extremes)."""
    half = rng.uniform(1.1, 1.6)
    r = math.exp(-math.pi * rng.uniform(0.03, 0.08))
    times, vals = [0.0, rng.uniform(0.8, 1.5)], [0.0, 0.0]
    side = float(rng.choice([-1, 1]))
    A = rng.uniform(0.15, 0.3)
    times.append(times[-1] + half / 2)
    vals.append(side * A)
    ext = [A]
    kicking = True
    while times[-1] < T_min:
        for _ in range(int(rng.integers(3, 7)) if kicking else int(rng.integers(3, 9))):
            A = A * r + (rng.uniform(0.12, 0.3) if kicking else 0.0)
            side = -side
            times.append(times[-1] + half * rng.uniform(0.98, 1.02))
            vals.append(side * A)
            ext.append(A)
        kicking = not kicking
    while A > 0.05:
        A *= rng.uniform(0.4, 0.6)
        side = -side
        times.append(times[-1] + half)
        vals.append(side * A)
        ext.append(A)
    times.append(times[-1] + half / 2)
    vals.append(0.0)
    times.append(times[-1] + rng.uniform(1.0, 2.0))
    vals.append(0.0)
    top = max(ext)
    return times, [x / top for x in vals], [e / top for e in ext]


# ---- out of vocabulary: planing a board by hand ----

def planing(rng, n_boards):
    """A hand plane's position along a board (its middle 0, its ends -+1): for each board 4 ... 8 strokes, each a push
    from the near end (-0.75 ... -1) to the far end (0.75 ... 1) in 0.6 ... 1.2 s, the plane then lifted and carried
    back (0.3 ... 0.5 s, eased), the near and far ends the same way for a board; between boards the plane set down at
    the middle (0) for 1 ... 2.5 s while the next is clamped, every other board planed from its other end. One board's
    strokes reach both ends. Returns (times, values)."""
    times, vals = [0.0, rng.uniform(0.8, 1.5)], [0.0, 0.0]
    full = int(rng.integers(n_boards))
    side = float(rng.choice([-1, 1]))
    for j in range(n_boards):
        near = 1.0 if j == full else rng.uniform(0.75, 1.0)
        far = 1.0 if j == full else rng.uniform(0.75, 1.0)
        times.append(times[-1] + rng.uniform(0.4, 0.8))
        vals.append(-side * near)
        for _ in range(int(rng.integers(4, 9))):
            times.append(times[-1] + rng.uniform(0.6, 1.2))
            vals.append(side * far)
            times.append(times[-1] + rng.uniform(0.3, 0.5))
            vals.append(-side * near)
        times.append(times[-1] + rng.uniform(0.4, 0.8))
        vals.append(0.0)
        times.append(times[-1] + rng.uniform(1.0, 2.5))
        vals.append(0.0)
        side = -side
    return times, vals

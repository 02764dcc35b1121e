"""Excitations of the HOLDOUT35 set (``cases_holdout35.py``), each beside its source; the mechanisms are in
:mod:`.mechanisms35`. Citations written from memory in this session (none was re-read), as in mechanisms35.

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


def envelope(t, t0, T, ramp):
    """1 on t0 + ramp ... t0 + T - ramp, eased up and down over ramp at either end, 0 outside t0 ... t0 + T."""
    t = np.asarray(t, float)
    return ease((t - t0) / ramp) * ease((t0 + T - t) / ramp)


# ---- clean: Cheyne-Stokes breathing ----

def cheyne_stokes(rng, n_cycles):
    """Cheyne-Stokes respiration (periodic breathing in heart failure: crescendo-decrescendo tidal volumes between
    apnoeas; Cheyne 1818, Stokes 1854), its time compressed about fourfold: each cycle 8 ... 13 breaths of 0.9 ... 1.4
    s, their depths sin(pi (i + 1/2) / n)^1.5 of the cycle's largest (one cycle 1, the others 0.75 ... 1), inspiration
    0.38 ... 0.45 of each breath (the volume above the end-expiratory level on the way in, below on the way out),
    apnoeas of 2.5 ... 5 s at rest between the cycles. Returns (breaths [(t0, T, depth, q)], T_end)."""
    breaths, tc = [], rng.uniform(1.0, 2.0)
    full = int(rng.integers(n_cycles))
    for j in range(n_cycles):
        n = int(rng.integers(8, 14))
        top = 1.0 if j == full else rng.uniform(0.75, 1.0)
        T = rng.uniform(0.9, 1.4)
        for i in range(n):
            Tb = T * rng.uniform(0.93, 1.07)
            breaths.append((tc, Tb, top * math.sin(math.pi * (i + 0.5) / n) ** 1.5, rng.uniform(0.38, 0.45)))
            tc += Tb
        tc += rng.uniform(2.5, 5.0)
    return breaths, tc


def breathing_volume(t, breaths):
    """The chest's volume about the end-expiratory level: each breath one period of a sine whose positive half (the
    inspiration) lasts q of it and negative half the rest (continuous, at rest at either end)."""
    t = np.asarray(t, float)
    x = np.zeros(len(t))
    for t0, T, depth, q in breaths:
        m = (t >= t0) & (t < t0 + T)
        s = (t[m] - t0) / T
        ph = np.where(s < q, math.pi * s / q, math.pi + math.pi * (s - q) / (1.0 - q))
        x[m] += depth * np.sin(ph)
    return x


# ---- creep: set points by Recaman's sequence ----

def recaman(n):
    """The first n terms of Recaman's sequence: a_0 = 0, a_k = a_(k-1) - k if that is positive and not yet in the
    sequence, else a_(k-1) + k (OEIS A005132)."""
    a, seen = [0], {0}
    for k in range(1, n):
        c = a[-1] - k
        if c <= 0 or c in seen:
            c = a[-1] + k
        a.append(c)
        seen.add(c)
    return a


def recaman_programme(rng):
    """A positioning test stepping through 14 ... 22 terms of Recaman's sequence (its jumps back and forth growing),
    each term's level the term over the largest, reached by eased moves at 0.25 ... 0.4 of the travel a second (plus
    0.2 s) and held 2 ... 4 s; then back to 0 and held. Returns (times, values, terms)."""
    terms = recaman(int(rng.integers(14, 23)))
    top = max(terms)
    speed = rng.uniform(0.25, 0.4)
    times, vals = [0.0, rng.uniform(1.5, 3.0)], [0.0, 0.0]
    cur = 0.0
    for a in terms[1:] + [0]:
        nxt = a / top
        move = abs(nxt - cur) / speed + 0.2
        hold = rng.uniform(2.0, 4.0)
        times += [times[-1] + move, times[-1] + move + hold]
        vals += [nxt, nxt]
        cur = nxt
    return times, vals, terms


# ---- rate: a curling sweeper's broom ----

def curling_end(rng, n_throws):
    """A curling sweeper's broom head across the stone's path: for each throw, 2 ... 4 bursts of sweeping ("hurry
    hard": strokes at 3.5 ... 5.5 a second, 0.5 ... 1 of the widest, 1 ... 3 s) with the broom lifted and still (at 0)
    for 0.6 ... 2 s between, and 2.5 ... 4 s at rest between the throws (the next stone delivered); one burst at the
    widest. Returns (bursts [(t0, T, f, amp, phase0)], T_end)."""
    bursts, tc = [], rng.uniform(0.8, 1.5)
    for _ in range(n_throws):
        for _ in range(int(rng.integers(2, 5))):
            f = rng.uniform(3.5, 5.5)
            T = max(2, round(rng.uniform(1.0, 3.0) * f)) / f
            bursts.append((tc, T, f, rng.uniform(0.5, 1.0), float(rng.choice([0.0, math.pi]))))
            tc += T + rng.uniform(0.6, 2.0)
        tc += rng.uniform(2.5, 4.0)
    j = int(rng.integers(len(bursts)))
    bursts[j] = bursts[j][:3] + (1.0,) + bursts[j][4:]
    return bursts, tc


def broom_head(t, bursts):
    """The broom head's lateral position: each burst's strokes under an envelope eased over half a stroke."""
    t = np.asarray(t, float)
    x = np.zeros(len(t))
    for t0, T, f, amp, p0 in bursts:
        x += amp * envelope(t, t0, T, 0.5 / f) * np.sin(2 * math.pi * f * (t - t0) + p0)
    return x


# ---- drift: an ice hockey player's stickhandling drills ----

def stickhandling(rng, n_drills):
    """The puck's lateral position under a hockey player's stickhandling: drills of narrow dribbles (2 ... 3 touches
    a second a side, 0.25 ... 0.45 of the reach), wide dribbles (1.2 ... 1.8 a second, 0.75 ... 1 of it), toe drags (a
    pull to 0.7 ... 1 of the reach on one side in 0.2 ... 0.3 s, a pause of 0.1 ... 0.2 s, back across to 0.3 ... 0.6
    on the other in 0.25 ... 0.35 s and to the middle) and glides (the puck carried in the middle, 1 ... 2.5 s); the
    puck moved between touches by the stick's eased sweeps. Returns (times, values)."""
    times, vals = [0.0, rng.uniform(0.8, 1.5)], [0.0, 0.0]
    kinds = ["narrow", "wide", "drag", "glide"]
    seq = list(rng.permutation(kinds)) + [kinds[int(rng.integers(4))] for _ in range(n_drills - 4)]
    for kind in seq:
        if kind in ("narrow", "wide"):
            rate = rng.uniform(2.0, 3.0) if kind == "narrow" else rng.uniform(1.2, 1.8)
            amp = rng.uniform(0.25, 0.45) if kind == "narrow" else rng.uniform(0.75, 1.0)
            n = int(rng.integers(6, 13))
            side = float(rng.choice([-1, 1]))
            for i in range(n):
                times.append(times[-1] + 0.5 / rate)
                vals.append(side * amp * rng.uniform(0.9, 1.0) * (1 if i % 2 == 0 else -1))
            times.append(times[-1] + 0.25 / rate)
            vals.append(0.0)
        elif kind == "drag":
            side = float(rng.choice([-1, 1]))
            a, back = rng.uniform(0.7, 1.0), rng.uniform(0.3, 0.6)
            t0 = times[-1]
            t1 = t0 + rng.uniform(0.2, 0.3)
            t2 = t1 + rng.uniform(0.1, 0.2)
            t3 = t2 + rng.uniform(0.25, 0.35)
            times += [t1, t2, t3, t3 + rng.uniform(0.2, 0.3)]
            vals += [side * a, side * a, -side * back, 0.0]
        times.append(times[-1] + rng.uniform(1.0, 2.5))
        vals.append(0.0)
    return times, vals


# ---- asymmetry: a diabolo juggler's sticks ----

def diabolo_routine(rng, n_bouts):
    """The height difference of a diabolo juggler's hand sticks: bouts of whipping (the leading hand's stick snapped up
    in 0.3 ... 0.4 of a stroke and let down slowly, 1.4 ... 2.2 strokes a second, 5 ... 10 strokes, 0.5 ... 1 of the
    widest, the leading hand either), each ending in a toss (the sticks snapped apart the other way to 0.6 ... 1 in
    0.12 ... 0.2 s, held taut while the diabolo flies 0.5 ... 1 s, back to level for the catch); 1 ... 2 s of rest
    between the bouts. Returns (times, values)."""
    times, vals = [0.0, rng.uniform(0.8, 1.5)], [0.0, 0.0]
    for j in range(n_bouts):
        side = float(rng.choice([-1, 1]))
        f = rng.uniform(1.4, 2.2)
        amp = 1.0 if j == 0 else rng.uniform(0.5, 1.0)
        up = rng.uniform(0.3, 0.4)
        for _ in range(int(rng.integers(5, 11))):
            a = amp * rng.uniform(0.9, 1.0)
            times += [times[-1] + up / f, times[-1] + 1.0 / f]
            vals += [side * a, 0.0]
        toss = -side * (1.0 if j == 1 else rng.uniform(0.6, 1.0))
        t0 = times[-1]
        t1 = t0 + rng.uniform(0.12, 0.2)
        t2 = t1 + rng.uniform(0.5, 1.0)
        times += [t1, t2, t2 + rng.uniform(0.15, 0.25), t2 + rng.uniform(1.2, 2.2)]
        vals += [toss, toss, 0.0, 0.0]
    return times, vals


# ---- saturation: an aftershock sequence replayed on a shake stage ----

def omori_sequence(rng, T_end):
    """A mainshock and its aftershocks: the aftershocks' rate K / (t + c)^p after the mainshock (Omori 1894, Utsu 1961:
    p 1.0 ... 1.2, c 0.3 ... 1 s, K for 14 ... 24 of them expected in the record, drawn by thinning a Poisson
    process), their magnitudes below the mainshock's by 1 (Bath's law for the largest) plus an exponential of mean 1 /
    (b ln 10), b = 1 (Gutenberg & Richter 1944), the ground's velocity as 10^(M / 2); each shock a ring-down
    sin(2 pi f t) (t / t_p)^2 exp(2 (1 - t / t_p)) (f 1.8 ... 3.5 Hz, t_p 0.35 ... 0.8 s), of a random sign, the
    mainshock 1 at 1 ... 2 s. Returns shocks [(t0, amp, f, t_p)]."""
    tm = rng.uniform(1.0, 2.0)
    p, c = rng.uniform(1.0, 1.2), rng.uniform(0.3, 1.0)
    span = T_end - tm
    if p == 1.0:
        integral = math.log((span + c) / c)
    else:
        integral = (c ** (1 - p) - (span + c) ** (1 - p)) / (p - 1)
    K = rng.uniform(14.0, 24.0) / integral
    shocks = [(tm, 1.0, rng.uniform(1.8, 3.5), rng.uniform(0.35, 0.8))]
    lam_max = K / c ** p
    s = 0.0
    while True:
        s += rng.exponential(1.0 / lam_max)
        if s > span - 3.0:
            break
        if rng.random() < (K / (s + c) ** p) / lam_max:
            dM = 1.0 + rng.exponential(1.0 / math.log(10.0))
            sign = float(rng.choice([-1, 1]))
            shocks.append((tm + s, sign * 10.0 ** (-dM / 2), rng.uniform(1.8, 3.5), rng.uniform(0.35, 0.8)))
    return shocks


def ground_velocity(t, shocks):
    """The sum of the shocks' ring-downs (each 0 before its onset)."""
    t = np.asarray(t, float)
    x = np.zeros(len(t))
    for t0, amp, f, tp in shocks:
        m = t > t0
        s = t[m] - t0
        x[m] += amp * np.sin(2 * math.pi * f * s) * (s / tp) ** 2 * np.exp(2.0 * (1.0 - s / tp))
    return x


# ---- delay: fireflies' flash dialogue ----

def firefly_dialogue(rng, T_min):
    """A flash dialogue of Photinus fireflies, its time compressed twofold: a male's flashes every 2.6 ... 3.2 s (0.25
    ... 0.45 s long: a rise over 0.05 ... 0.1 s and a fade over the rest), a female's answer 0.9 ... 1.1 s after each
    (her fixed delay, the species' key; Lloyd 1966), dimmer (0.4 ... 0.7) and longer (0.3 ... 0.55 s), unanswered now
    and then (one time in five); a rival male's flash (0.6 ... 0.9) one time in four, 0.3 ... 0.6 s after the male's;
    the brightest flash 1. Returns flashes [(t0, rise, fade, level, who)] (who "male", "rival" or "female") and
    T_end."""
    flashes = []
    tc = rng.uniform(0.8, 1.5)
    period = rng.uniform(2.6, 3.2)
    delay = rng.uniform(0.9, 1.1)
    while tc < T_min:
        dur = rng.uniform(0.25, 0.45)
        rise = rng.uniform(0.05, 0.1)
        flashes.append((tc, rise, dur - rise, rng.uniform(0.85, 1.0), "male"))
        if rng.random() < 0.25:
            d2 = rng.uniform(0.25, 0.4)
            flashes.append((tc + rng.uniform(0.3, 0.6), rng.uniform(0.05, 0.1), d2, rng.uniform(0.6, 0.9), "rival"))
        if rng.random() < 0.8:
            d3 = rng.uniform(0.3, 0.55)
            r3 = rng.uniform(0.06, 0.12)
            flashes.append((tc + delay, r3, d3 - r3, rng.uniform(0.4, 0.7), "female"))
        tc += period * rng.uniform(0.95, 1.05)
    j = int(np.argmax([f[3] for f in flashes]))
    flashes[j] = flashes[j][:3] + (1.0, flashes[j][4])
    return flashes, tc + 1.0


def flash_light(t, flashes):
    """The light: each flash eased up over its rise and down over its fade; overlapping flashes add, clipped at 1
    (the sensor's view)."""
    t = np.asarray(t, float)
    x = np.zeros(len(t))
    for t0, rise, fade, level, _ in flashes:
        x += level * ease((t - t0) / rise) * ease((t0 + rise + fade - t) / fade)
    return np.minimum(x, 1.0)


# ---- the initial state's record: turns taken in the Thue-Morse order ----

def thue_morse(n):
    """The first n terms of the Thue-Morse sequence: the parity of the number of ones in k's binary form (Thue 1906,
    Morse 1921; the fair order for taking turns)."""
    return [bin(k).count("1") % 2 for k in range(n)]


def thue_morse_turns(rng, n_turns):
    """Two operators taking turns at a lever in the Thue-Morse order (A B B A B A A B ...), A pushing it one way and B
    the other: each turn a stroke out to 0.5 ... 1 of the throw in 0.25 ... 0.45 s, a hold of 0.1 ... 0.3 s, back in
    0.25 ... 0.45 s, a pause of 0.2 ... 0.6 s; one stroke of each operator at the full throw. Returns (times, values,
    order)."""
    order = thue_morse(n_turns)
    levels = [rng.uniform(0.5, 1.0) for _ in order]
    for who in (0, 1):
        idx = [k for k, o in enumerate(order) if o == who]
        levels[idx[int(rng.integers(len(idx)))]] = 1.0
    side0 = float(rng.choice([-1, 1]))
    times, vals = [0.0, rng.uniform(0.8, 1.5)], [0.0, 0.0]
    for o, lv in zip(order, levels):
        s = side0 if o == 0 else -side0
        t1 = times[-1] + rng.uniform(0.25, 0.45)
        t2 = t1 + rng.uniform(0.1, 0.3)
        t3 = t2 + rng.uniform(0.25, 0.45)
        times += [t1, t2, t3, t3 + rng.uniform(0.2, 0.6)]
        vals += [s * lv, s * lv, 0.0, 0.0]
    times.append(times[-1] + rng.uniform(0.8, 1.5))
    vals.append(0.0)
    return times, vals, order


# ---- the pair: a bicycle's brake lever on a descent; its history, an index shifter's clicks ----

def brake_descent(rng, T_min):
    """A bicycle's brake lever pulled through a descent (0 released, 1 pulled to the bar): feathering (to 0.2 ... 0.45
    over 0.4 ... 0.8 s, modulated by +-0.04 ... 0.1 every 0.5 ... 1 s for 1.5 ... 3 s, released over 0.3 ... 0.6 s),
    hard stops before the hairpins (to 0.8 ... 1 in 0.15 ... 0.3 s, held 0.8 ... 2 s, released over 0.3 ... 0.5 s; one
    to 1) and dabs (to 0.3 ... 0.55 and off within 0.3 ... 0.5 s), rolling free 1 ... 3.5 s between. Returns (times,
    values)."""
    times, vals = [0.0, rng.uniform(1.0, 2.0)], [0.0, 0.0]
    hard = 0
    while times[-1] < T_min or hard == 0:
        r = rng.random()
        if r < 0.3 or (times[-1] > 0.7 * T_min and hard == 0):
            top = 1.0 if hard == 0 else rng.uniform(0.8, 1.0)
            hard += 1
            t1 = times[-1] + rng.uniform(0.15, 0.3)
            t2 = t1 + rng.uniform(0.8, 2.0)
            times += [t1, t2, t2 + rng.uniform(0.3, 0.5)]
            vals += [top, top, 0.0]
        elif r < 0.7:
            lv = rng.uniform(0.2, 0.45)
            times.append(times[-1] + rng.uniform(0.4, 0.8))
            vals.append(lv)
            t_end = times[-1] + rng.uniform(1.5, 3.0)
            while times[-1] < t_end:
                times.append(times[-1] + rng.uniform(0.5, 1.0))
                vals.append(lv + rng.uniform(-1.0, 1.0) * rng.uniform(0.04, 0.1))
            times.append(times[-1] + rng.uniform(0.3, 0.6))
            vals.append(0.0)
        else:
            lv = rng.uniform(0.3, 0.55)
            tt = rng.uniform(0.3, 0.5)
            times += [times[-1] + tt / 2, times[-1] + tt]
            vals += [lv, 0.0]
        times.append(times[-1] + rng.uniform(1.0, 3.5))
        vals.append(0.0)
    return times, vals


def index_shifts(rng):
    """The history of an index shifter's cable: from slack, clicks of one index step each (0.1 s a click, 0.4 ... 1.5 s
    apart): up 5 ... 8, down 2 ... 3, up 1 ... 3, down 1 ... 4 (at least one above the slack), then every click
    released back to slack (a rider's shifts before the cable was taken for the test). Returns (times, clicks)."""
    times, clicks = [0.0], [0]
    cur = 0
    ups = int(rng.integers(5, 9))
    moves = [ups, -int(rng.integers(2, 4)), int(rng.integers(1, 4))]
    moves.append(-min(int(rng.integers(1, 5)), ups + moves[1] + moves[2] - 1))
    for mv in moves:
        for _ in range(abs(mv)):
            cur += 1 if mv > 0 else -1
            t0 = times[-1] + rng.uniform(0.4, 1.5)
            times += [t0, t0 + 0.1]
            clicks += [clicks[-1], cur]
    while cur > 0:
        cur -= 1
        t0 = times[-1] + rng.uniform(0.2, 0.5)
        times += [t0, t0 + 0.1]
        clicks += [clicks[-1], cur]
    return times, clicks


# ---- out of vocabulary: a rattleback's rocking ----

def rattleback_spins(rng, n_spins):
    """A rattleback (a celt whose principal axes are skewed to its keel) spun 3 ... 5 times: spun the wrong way, its
    rocking grows exponentially (over 0.4 ... 0.8 s an e-fold) until the spin stops and reverses, then dies away (0.6
    ... 1.2 s an e-fold) as it spins the other way (Walker 1896; Bondi 1986): the rocking at 2.2 ... 3.5 Hz under the
    envelope 1 / (exp(-(t - t_r) / tau_g) + exp((t - t_r) / tau_d)) scaled to 0.6 ... 1 (one spin to 1), faded in and
    out over a second at either end of the spin's 5 ... 8 s; 1 ... 2.5 s at rest between. Returns (spins [(t0, T,
    t_rev, tau_g, tau_d, f, amp, phase0)], T_end)."""
    spins, tc = [], rng.uniform(0.8, 1.5)
    full = int(rng.integers(n_spins))
    for j in range(n_spins):
        T = rng.uniform(5.0, 8.0)
        spins.append((tc, T, tc + rng.uniform(0.4, 0.6) * T, rng.uniform(0.4, 0.8), rng.uniform(0.6, 1.2),
                      rng.uniform(2.2, 3.5), 1.0 if j == full else rng.uniform(0.6, 1.0),
                      rng.uniform(0, 2 * math.pi)))
        tc += T + rng.uniform(1.0, 2.5)
    return spins, tc


def rattleback_rocking(t, spins):
    """The rocking angle: each spin's rocking under its envelope (normalised to its peak) and the fades."""
    t = np.asarray(t, float)
    x = np.zeros(len(t))
    for t0, T, tr, tg, td, f, amp, p0 in spins:
        m = (t >= t0) & (t <= t0 + T)
        s = t[m]
        # the envelope's peak: where exp(-(s - tr)/tg) / tg = exp((s - tr)/td) / td
        sp = tr + math.log(td / tg) * tg * td / (tg + td)
        pk = 1.0 / (math.exp(-(sp - tr) / tg) + math.exp((sp - tr) / td))
        env = 1.0 / (np.exp(-(s - tr) / tg) + np.exp((s - tr) / td)) / pk
        x[m] += amp * env * envelope(s, t0, T, 1.0) * np.sin(2 * math.pi * f * (s - t0) + p0)
    return x

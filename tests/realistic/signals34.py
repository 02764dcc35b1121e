"""Excitations of the HOLDOUT34 set (``cases_holdout34.py``), each beside its source; the mechanisms are in
:mod:`.mechanisms34`. Citations written from memory in this session (none was re-read), as in mechanisms34.

Every generator returns a path normalised to about -1 ... 1 (or 0 ... 1 for the unipolar ones) that starts at 0 at
rest; the cases scale it to volts.
"""

import math

import numpy as np


def ease(s):
    """The half-cosine ease (1 - cos(pi s)) / 2 on 0 ... 1 (zero speed at both ends: a crank's or a cam's move),
    clipped outside."""
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


# ---- clean: a top-loading washing machine's agitator through a wash programme ----

def agitator_programme(rng):
    """A top-loader's wash programme, compressed: a fill (at rest), then 3 ... 4 bouts of agitation (wash, a gentle
    soak stir, rinses), each of 5 ... 8 strokes at 0.8 ... 1.2 strokes a second, with pauses of 1 ... 2.5 s between
    (soaking, draining, filling). The agitator is rocked through its transmission's crank-and-sector gear, so its
    angle runs as sin(phi) + k sin(2 phi) (k 0.08 ... 0.15, the crank's finite connecting rod), its amplitude per bout
    (a gentle cycle's 0.55 ... 0.8 of the normal one's). Returns (bouts [(t0, T, f, amp, phase0)], k, T_end)."""
    k = rng.uniform(0.08, 0.15)
    tc = rng.uniform(0.8, 1.5)
    bouts = []
    for j in range(int(rng.integers(3, 5))):
        f = rng.uniform(0.8, 1.2)
        T = int(rng.integers(5, 9)) / f
        amp = 1.0 if j == 0 or rng.random() < 0.5 else rng.uniform(0.55, 0.8)
        bouts.append((tc, T, f, amp, float(rng.choice([0.0, math.pi]))))
        tc += T + rng.uniform(1.0, 2.5)
    return bouts, k, tc


def agitator_angle(t, bouts, k):
    """The agitator's angle: each bout's strokes under an envelope eased over a quarter stroke at either end."""
    t = np.asarray(t, float)
    x = np.zeros(len(t))
    for t0, T, f, amp, p0 in bouts:
        ph = 2 * math.pi * f * (t - t0) + p0
        x += amp * envelope(t, t0, T, 0.25 / f) * (np.sin(ph) + k * np.sin(2 * ph))
    return x


# ---- creep: a sit-stand desk through a (compressed) working day ----

def desk_day(rng, T_min=120.0):
    """A sit-stand desk's height from its sitting height (0) to its user's standing height (1): the user switches
    between sitting and standing (the standing preset 0.92 ... 1.0; once in a while a colleague's preset at 0.55 ...
    0.75, or a nudge of 0.03 ... 0.08 by the up/down keys), holding each for 8 ... 25 s; the desk's motors run at
    0.2 ... 0.3 of the travel a second (each move eased over its length over that speed plus 0.3 s, a soft start and
    stop). Starts seated, ends seated after T_min s.
    Returns (times, values)."""
    speed = rng.uniform(0.2, 0.3)
    times, vals = [0.0, rng.uniform(4.0, 8.0)], [0.0, 0.0]
    stand = rng.uniform(0.92, 1.0)
    cur, seated = 0.0, True
    while times[-1] < T_min:
        r = rng.random()
        if seated:
            nxt = stand if r < 0.75 else rng.uniform(0.55, 0.75)
        elif r < 0.25:
            nxt = min(1.0, max(0.3, cur + rng.choice([-1, 1]) * rng.uniform(0.03, 0.08)))
        else:
            nxt = 0.0
        move = abs(nxt - cur) / speed + 0.3
        times += [times[-1] + move, times[-1] + move + rng.uniform(8.0, 25.0)]
        vals += [nxt, nxt]
        cur, seated = nxt, nxt == 0.0
    if cur != 0.0:
        times += [times[-1] + cur / speed + 0.3, times[-1] + cur / speed + 0.3 + rng.uniform(4.0, 8.0)]
        vals += [0.0, 0.0]
    return times, vals


# ---- rate: an accelerator pedal in stop-and-go traffic ----

def stop_and_go(rng, T_min=18.0):
    """A driver's accelerator pedal (0 released, 1 floored) in stop-and-go traffic: gentle tip-ins to 0.25 ... 0.6 over
    0.6 ... 1.5 s, held 0.5 ... 2 s, feathered (+-0.05 ... 0.15 over 0.3 ... 0.6 s), then either lifted quickly (0.12
    ... 0.25 s) for a brake or eased off over 0.6 ... 1.2 s to coast; one time in four a kick-down to 0.95 ... 1.0
    in 0.12 ... 0.2 s for a gap, held 0.6 ... 1.5 s; stopped (released) 0.8 ... 3 s between. Returns (times, values)."""
    times, vals = [0.0, rng.uniform(0.5, 1.0)], [0.0, 0.0]
    kicks = 0
    while times[-1] < T_min or kicks == 0:
        t0 = times[-1]
        if rng.random() < 0.25 or (times[-1] > 0.6 * T_min and kicks == 0):
            top, up, kicks = rng.uniform(0.95, 1.0), rng.uniform(0.12, 0.2), kicks + 1
        else:
            top, up = rng.uniform(0.25, 0.6), rng.uniform(0.6, 1.5)
        hold = rng.uniform(0.5, 2.0)
        fe = min(1.0, max(0.05, top + rng.choice([-1, 1]) * rng.uniform(0.05, 0.15)))
        t1 = t0 + up
        t2 = t1 + hold
        t3 = t2 + rng.uniform(0.3, 0.6)
        down = rng.uniform(0.12, 0.25) if rng.random() < 0.5 else rng.uniform(0.6, 1.2)
        t4 = t3 + down
        t5 = t4 + rng.uniform(0.8, 3.0)
        times += [t1, t2, t3, t4, t5]
        vals += [top, top, fe, 0.0, 0.0]
    return times, vals


# ---- drift: a snake robot's joint under the serpenoid gait ----

def serpenoid_programme(rng, T_min=55.0):
    """One joint of a snake robot crawling by Hirose's serpenoid curve (the joint angles alpha sin(w t + (i - 1) beta)
    + gamma; Hirose, *Biologically Inspired Robots*, 1993): stretches of crawling at 0.3 ... 0.8 Hz, the amplitude
    0.6 ... 1 of the largest, turns held as the offset gamma (+-0.1 ... 0.25) eased in and out over a second, and
    stops (the robot freezes its shape to sense, 2 ... 5 s) between the stretches. Returns stretches [(t0, T, f, a,
    gamma, phase0)] and T_end."""
    out, tc = [], rng.uniform(0.5, 1.5)
    while tc < T_min:
        f = rng.uniform(0.3, 0.8)
        T = rng.uniform(6.0, 14.0)
        gam = float(rng.choice([-1, 1])) * rng.uniform(0.1, 0.25) if rng.random() < 0.5 else 0.0
        out.append((tc, T, f, rng.uniform(0.6, 1.0), gam, rng.uniform(0, 2 * math.pi)))
        tc += T + rng.uniform(2.0, 5.0)
    return out, tc


def serpenoid_joint(t, stretches):
    """The joint's angle: in each stretch the wave a sin(w (t - t0) + phase0) grows and settles under an envelope eased
    over half a cycle (the robot starting and freezing its shape), plus the turn's offset gamma eased in and out over a
    second."""
    t = np.asarray(t, float)
    x = np.zeros(len(t))
    for t0, T, f, a, gam, p0 in stretches:
        env = envelope(t, t0, T, 0.5 / f)
        x += a * env * np.sin(2 * math.pi * f * (t - t0) + p0) + gam * envelope(t, t0, T, 1.0)
    return x


# ---- asymmetry: the centre mark of a tug of war's rope ----

def tug_of_war(rng, n_phases):
    """The rope's centre mark: phases in which one team gains, alternately, to 0.5 ... 1 of the largest excursion on
    its side, by heaves in rhythm (a call every 0.9 ... 1.3 s: the mark pulled 0.1 ... 0.3 in 0.3 ... 0.5 s, then
    slipping back by a sixth to a third of it as the rope stretches and the feet settle), stalemates of 1 ... 3 s
    between; the last phase the winners' run, past their mark. Starts at rest at 0. Returns (times, values)."""
    times, vals = [0.0, rng.uniform(0.8, 1.5)], [0.0, 0.0]
    x, side = 0.0, float(rng.choice([-1, 1]))
    for j in range(n_phases):
        target = side * (1.0 if j == n_phases - 1 else rng.uniform(0.5, 1.0))
        call = rng.uniform(0.9, 1.3)
        while side * (target - x) > 1e-9:
            pull = min(rng.uniform(0.1, 0.3), side * (target - x))
            t0 = times[-1]
            tp = rng.uniform(0.3, 0.5)
            back = pull * rng.uniform(0.17, 0.33) if side * (target - x) > pull else 0.0
            x1 = x + side * pull
            x = x1 - side * back
            times += [t0 + tp, t0 + call]
            vals += [x1, x]
        times.append(times[-1] + rng.uniform(1.0, 3.0))
        vals.append(x)
        side = -side
    return times, vals


# ---- saturation: a windsurfer pumping the sail ----

def windsurf_session(rng, n_legs):
    """The sail's sheeting angle (+ on one tack, - on the other): each leg starts with pumping onto the plane (6 ... 12
    pumps at 1.0 ... 1.5 a second, the boom pulled in hard and let out: 0.3 ... 0.5 about the leg's trim), then sails
    (the trim 0.45 ... 0.7 with gusts: a slow sheeting out and in of 0.1 ... 0.25 over 1.5 ... 3 s, 2 ... 4 of them),
    then tacks (the rig swung across to the other side in 1.2 ... 2 s). Returns legs [(t0, T, side, trim, pumps (t_end,
    f, depth), gusts [(tg, Tg, dg)])] and T_end."""
    legs, tc = [], rng.uniform(0.5, 1.0)
    side = float(rng.choice([-1, 1]))
    for _ in range(n_legs):
        trim = rng.uniform(0.45, 0.7)
        f = rng.uniform(1.0, 1.5)
        n_p = int(rng.integers(6, 13))
        Tp = n_p / f
        gusts, tg = [], tc + Tp + rng.uniform(0.5, 1.5)
        for _ in range(int(rng.integers(2, 5))):
            Tg = rng.uniform(1.5, 3.0)
            gusts.append((tg, Tg, rng.uniform(0.1, 0.25)))
            tg += Tg + rng.uniform(0.5, 2.0)
        T = tg - tc
        legs.append((tc, T, side, trim, (tc + Tp, f, rng.uniform(0.3, 0.5)), gusts))
        tc += T + rng.uniform(1.2, 2.0)
        side = -side
    return legs, tc


def sail_angle(t, legs):
    """The sheeting angle: on each leg the trim eased in over the tack's swing (the time between legs), the pumps'
    strokes (1 - cos) down from the trim under an envelope, the gusts' eased sheeting out (towards 0) and back."""
    t = np.asarray(t, float)
    x = np.zeros(len(t))
    prev_end = 0.0
    for t0, T, side, trim, (tp_end, f, depth), gusts in legs:
        swing = ease((t - prev_end) / (t0 - prev_end)) * ease((t0 + T + 1.2 - t) / 1.2)
        pump = depth * 0.5 * (1 - np.cos(2 * math.pi * f * (t - t0))) * ((t >= t0) & (t <= tp_end))
        g = np.zeros(len(t))
        for tg, Tg, dg in gusts:
            g += dg * np.sin(math.pi * np.clip((t - tg) / Tg, 0.0, 1.0)) ** 2
        x += side * swing * (trim + pump - g)
        prev_end = t0 + T
    return x


# ---- delay: a pogo stick's spring ----

def pogo_sessions(rng, n_sessions):
    """Sessions on a pogo stick: the rider steps on (the spring compressed to its static deflection s0 = m g / k over
    0.4 ... 0.7 s), hops 8 ... 20 times, then steps off (the spring released) and rests 2 ... 5 s. A hop: flight at the
    take-off speed v (apex h = v^2 / 2 g), then the stance x(s) = s0 (1 - cos w s) + (v / w) sin w s (the rider-and-
    stick mass on the spring, w = sqrt(g / s0), from touch-down) until the spring is back at 0; the rider pumps the
    hops from 0.3 ... 0.5 of the session's highest to it and lets them die at the end. Returns (segments, T_end): each
    segment (kind, t0, dur, params) with kind "step" (eased from a to b) or "stance" (s0, v, w)."""
    g = 9.81
    s0 = rng.uniform(0.04, 0.06)                               # m
    w = math.sqrt(g / s0)
    segs, tc = [], rng.uniform(0.5, 1.0)
    for _ in range(n_sessions):
        Ton = rng.uniform(0.4, 0.7)
        segs.append(("step", tc, Ton, (0.0, s0)))
        tc += Ton + rng.uniform(0.3, 0.8)
        n = int(rng.integers(8, 21))
        h_top = rng.uniform(0.05, 0.12)                        # apex, m
        hs = h_top * np.r_[np.linspace(rng.uniform(0.3, 0.5), 1.0, n // 2), np.linspace(1.0, 0.4, n - n // 2)]
        segs.append(("step", tc, 0.25, (s0, 0.0)))          # the first push-off: the spring's last release
        tc += 0.25
        for h in hs:
            v = math.sqrt(2 * g * h)
            tc += 2 * v / g                                   # flight
            s_end = (math.pi + 2 * math.atan2(s0 * w, v)) / w  # the stance's end: x(s) back at 0
            segs.append(("stance", tc, s_end, (s0, v, w)))
            tc += s_end
        segs.append(("step", tc, 0.3, (0.0, s0)))            # lands and stands
        tc += 0.3 + rng.uniform(0.5, 1.0)
        Toff = rng.uniform(0.4, 0.7)
        segs.append(("step", tc, Toff, (s0, 0.0)))
        tc += Toff + rng.uniform(2.0, 5.0)
    return segs, tc


def pogo_compression(t, segs):
    """The spring's compression (0 when it is free) along the segments; held between them at the last one's end."""
    t = np.asarray(t, float)
    x = np.zeros(len(t))
    for kind, t0, dur, p in segs:
        m = t >= t0
        s = t[m] - t0
        if kind == "step":
            a, b = p
            x[m] = a + (b - a) * ease(s / dur)
        else:
            s0, v, w = p
            inside = s <= dur
            val = np.where(inside, s0 * (1 - np.cos(w * s)) + (v / w) * np.sin(w * s), 0.0)
            x[m] = np.maximum(val, 0.0)
    return x


# ---- initial state: a couple's slow waltz ----

def slow_waltz(rng, n_bars):
    """A dancer's sideways sway in a slow waltz (28 ... 31 bars a minute, 3/4): each bar a sway to one side and back
    (the rise on beats 2 and 3 carrying the body over, the fall at the end of 3), sides alternating, the sway 0.5 ...
    0.8 of the largest, a natural or a reverse turn (the sway to 0.9 ... 1.0) every 4 ... 6 bars, a hesitation (the
    bar held on the spot) now and then. Returns (times, values, bar seconds)."""
    bar = 60.0 / rng.uniform(28.0, 31.0)
    times, vals = [0.0, rng.uniform(0.5, 1.0)], [0.0, 0.0]
    side = float(rng.choice([-1, 1]))
    nxt_turn = int(rng.integers(4, 7))
    for b in range(n_bars):
        t0 = times[-1]
        if rng.random() < 0.12:                                 # a hesitation
            times.append(t0 + bar)
            vals.append(0.0)
            continue
        a = rng.uniform(0.9, 1.0) if b == nxt_turn else rng.uniform(0.5, 0.8)
        if b == nxt_turn:
            nxt_turn += int(rng.integers(4, 7))
        times += [t0 + bar * rng.uniform(0.55, 0.7), t0 + bar]
        vals += [side * a, 0.0]
        side = -side
    times.append(times[-1] + rng.uniform(0.5, 1.0))
    vals.append(0.0)
    return times, vals, bar


# ---- two effects: a bartender's cocktail shaker ----

def shaking_rounds(rng, n_rounds):
    """A bartender's shaker: rounds of hard shaking (8 ... 15 s at 2.5 ... 4 shakes a second, the stroke flattened at
    its ends where the ice hits: sin + sin(3 phi) / 6), between which the shaker is carried to the other side of the
    bar, held to pour (+-0.2 ... 0.4 for 2 ... 4 s) and brought back. Returns rounds [(t0, T, f, a)], pours [(t0,
    dur, level)] and T_end."""
    rounds, pours, tc = [], [], rng.uniform(0.5, 1.0)
    for _ in range(n_rounds):
        T = rng.uniform(8.0, 15.0)
        rounds.append((tc, T, rng.uniform(2.5, 4.0), rng.uniform(0.75, 1.0)))
        tc += T + rng.uniform(0.3, 0.6)
        dur = rng.uniform(2.0, 4.0)
        pours.append((tc, dur, float(rng.choice([-1, 1])) * rng.uniform(0.2, 0.4)))
        tc += dur + rng.uniform(0.8, 1.5)
    return rounds, pours, tc


def shaker_position(t, rounds, pours):
    """The shaker's travel: the rounds' strokes under envelopes eased over 0.4 s, the pours as eased carries over 0.6 s
    to the pouring place and back."""
    t = np.asarray(t, float)
    x = np.zeros(len(t))
    for t0, T, f, a in rounds:
        ph = 2 * math.pi * f * (t - t0)
        x += a * envelope(t, t0, T, 0.4) * (np.sin(ph) + np.sin(3 * ph) / 6) / 1.0
    for t0, dur, lev in pours:
        x += lev * envelope(t, t0, dur, 0.6)
    return x


# ---- out of vocabulary: a hula hoop ----

def hula_sessions(rng, n_sessions):
    """The hooper's hip (sideways) while a hoop spins about the waist: a throw to start (the hip's circling growing over
    the first two turns), then the circling at the hoop's 1.5 ... 2.2 turns a second, its amplitude 0.7 ... 1 with a
    slow wander (the hoop rising and sinking: +-10 %, 0.1 ... 0.2 Hz), the rate wandering +-5 %; each session ends in a
    drop (the circling dies in half a turn) and a pick-up pause of 1.5 ... 3 s. Returns sessions [(t0, T, f, a, fm,
    phm)] and T_end."""
    out, tc = [], rng.uniform(0.5, 1.0)
    for _ in range(n_sessions):
        T = rng.uniform(5.0, 9.0)
        out.append((tc, T, rng.uniform(1.5, 2.2), rng.uniform(0.7, 1.0), rng.uniform(0.1, 0.2),
                    rng.uniform(0, 2 * math.pi)))
        tc += T + rng.uniform(1.5, 3.0)
    return out, tc


def hula_hip(t, sessions):
    t = np.asarray(t, float)
    x = np.zeros(len(t))
    for t0, T, f, a, fm, phm in sessions:
        s = t - t0
        wander = 1.0 + 0.1 * np.sin(2 * math.pi * fm * s + phm)
        phase = 2 * math.pi * f * (s + 0.05 / (2 * math.pi * fm) * (np.cos(phm) - np.cos(2 * math.pi * fm * s + phm)))
        env = ease(s * f / 2.0) * ease((T - s) * f * 2.0) * (s >= 0) * (s <= T)
        x += a * wander * env * np.sin(phase)
    return x

"""Excitations of the HOLDOUT33 set (``cases_holdout33.py``), each beside its source; the mechanisms are in
:mod:`.mechanisms33`. Citations written from memory in this session (none was re-read), as in mechanisms33.

Every generator returns a path normalised to about -1 ... 1 (or 0 ... 1 for the unipolar ones) that starts at 0 at
rest; the cases scale it to volts.
"""

import math

import numpy as np
from scipy.integrate import solve_ivp


def smoothstep5(s):
    """The quintic 6 s^5 - 15 s^4 + 10 s^3 on 0 ... 1 (zero speed and acceleration at both ends: the minimum-jerk
    move of Flash & Hogan, J. Neurosci. 5 (1985) 1688), clipped outside."""
    s = np.clip(np.asarray(s, float), 0.0, 1.0)
    return s * s * s * (10.0 + s * (6.0 * s - 15.0))


def glide(t, times, values):
    """The path through (times, values): a minimum-jerk move between consecutive points (a hold where two are equal),
    values[0] before the first time and values[-1] after the last."""
    t = np.asarray(t, float)
    out = np.full(len(t), float(values[0]))
    for k in range(len(times) - 1):
        ta, tb, a, b = times[k], times[k + 1], values[k], values[k + 1]
        m = t >= ta
        out[m] = a + (b - a) * smoothstep5((t[m] - ta) / (tb - ta))
    return out


def hann_edges(t, t0, T, ramp):
    """An envelope that is 1 on t0 + ramp ... t0 + T - ramp and rises and falls as a half Hann window over ramp at
    either end (0 outside t0 ... t0 + T)."""
    t = np.asarray(t, float)
    a = np.clip((t - t0) / ramp, 0.0, 1.0)
    b = np.clip((t0 + T - t) / ramp, 0.0, 1.0)
    return np.sin(0.5 * math.pi * a) ** 2 * np.sin(0.5 * math.pi * b) ** 2


# ---- clean: a footbridge's lateral sway as its crowd locks in ----

def crowd_programme(rng):
    """A footbridge's crowd over an opening (compressed in time): the walkers' number over the lock-in number N_c
    rising from 0 to 2 ... 3 over 5 ... 8 s as they arrive, held 5 ... 8 s, falling to 0.4 ... 0.6 over 2 ... 3 s
    as they stop and hold the railings, then held to the end; the lateral mode at 0.85 ... 1.1 Hz, its damping 4 ... 6 %
    (a light scaled model); the unsynchronised footfalls' lateral force a few sines at 0.8 ... 1.2 Hz (half the pacing
    rate). Returns a dict of the parameters."""
    t1 = rng.uniform(5.0, 8.0)
    t2 = t1 + rng.uniform(5.0, 8.0)
    t3 = t2 + rng.uniform(2.0, 3.0)
    r_max = rng.uniform(2.0, 3.0)
    return dict(fn=rng.uniform(0.85, 1.1), zeta=rng.uniform(0.04, 0.06), knots_t=[0.0, t1, t2, t3],
                knots_r=[0.0, r_max, r_max, rng.uniform(0.4, 0.6)], v_sat=rng.uniform(0.3, 0.6),
                f_foot=rng.uniform(0.05, 0.1), ff=rng.uniform(0.8, 1.2, 5), fa=rng.dirichlet(np.ones(5)),
                fp=rng.uniform(0, 2 * math.pi, 5), T_end=t3 + rng.uniform(3.0, 5.0))


def crowd_ratio(t, p):
    """N(t) / N_c along the programme's knots (linear between them, held after the last)."""
    return np.interp(t, p["knots_t"], p["knots_r"])


def footbridge_rhs(t, s, p):
    """The lateral mode (unit modal mass): x'' + 2 zeta w x' + w^2 x = (N / N_c) 2 zeta w v_s tanh(x' / v_s) + f(t):
    each walker who falls into step pushes in phase with the deck's velocity (Dallard et al., Struct. Eng. 79 (2001) 17:
    a force k v a walker, so N_c = 8 pi zeta f M / k is where the crowd's negative damping cancels the bridge's), the
    push bounded as the walkers' sway is (the tanh); f the unsynchronised walkers' footfalls, sqrt(N) strong (0.05 ...
    0.1 of the locked-in crowd's push at N_c) and faded in over the first second."""
    w = 2 * math.pi * p["fn"]
    rho = float(crowd_ratio(t, p))
    x, v = s
    ff = (p["f_foot"] * 2 * p["zeta"] * w * p["v_sat"] * math.sqrt(rho) * min(t, 1.0)
          * float(np.sum(p["fa"] * np.sin(2 * math.pi * p["ff"] * t + p["fp"]))))
    return [v, -w * w * x - 2 * p["zeta"] * w * v + rho * 2 * p["zeta"] * w * p["v_sat"] * math.tanh(v / p["v_sat"])
            + ff]


def footbridge_sway(t, p):
    """The deck's lateral displacement by solve_ivp (DOP853, rtol 1e-10), at rest at the start."""
    sol = solve_ivp(footbridge_rhs, (t[0], t[-1]), [0.0, 0.0], t_eval=t, args=(p,), method="DOP853", rtol=1e-10,
                    atol=1e-12, max_step=0.02)
    return sol.y[0]


# ---- creep: a theatre's flown batten through a performance's cues ----

def fly_cues(rng):
    """A batten on a counterweight fly system through a play's cues (0 flown out of sight, 1 at its lowest performance
    trim): the flyman hauls it in or out at 0.25 ... 0.4 of its travel a second at the peak (a minimum-jerk pull), to
    full trim, to a half-height trim of 0.45 ... 0.75 for a border, or out; each scene holds it 8 ... 16 s (compressed),
    and now and then a quick reveal flies it in for only 3 ... 5 s (e.g. Glerum, *Stage Rigging Handbook*, on
    counterweight operation). Five to eight cues, at least one to full trim; out at the end. Returns (times, values) for
    :func:`glide`."""
    n = int(rng.integers(5, 9))
    full = int(rng.integers(n - 1))
    times, vals, cur = [0.0, rng.uniform(2.0, 4.0)], [0.0, 0.0], 0.0
    tc = times[-1]
    for j in range(n - 1):
        if j == full or (cur != 1.0 and rng.random() < 0.35):
            tgt = 1.0
        elif cur != 0.0 and rng.random() < 0.5:
            tgt = 0.0
        else:
            tgt = rng.uniform(0.45, 0.75)
        if abs(tgt - cur) < 0.1:
            tgt = 0.0 if cur > 0.3 else 1.0
        tc += 1.875 * abs(tgt - cur) / rng.uniform(0.25, 0.4)
        times.append(tc)
        vals.append(tgt)
        tc += rng.uniform(3.0, 5.0) if rng.random() < 0.2 else rng.uniform(8.0, 16.0)
        times.append(tc)
        vals.append(tgt)
        cur = tgt
    if cur != 0.0:
        tc += 1.875 * cur / rng.uniform(0.25, 0.4)
        times.append(tc)
        vals.append(0.0)
    times.append(tc + rng.uniform(3.0, 6.0))
    vals.append(0.0)
    return times, vals


# ---- rate dependence: a rotary telephone dial ----

def dial_number(rng, n_digits):
    """A number dialled on a rotary dial: for digit d (0 counting as ten) the finger drags the dial from rest to the
    finger stop through d + 1 hole pitches (one pitch of lost motion before the pulses) in 0.25 ... 0.45 s plus 0.02
    s a pitch (a minimum-jerk pull), holds it at the stop 0.05 ... 0.2 s and lets go; the governor returns it at 10
    pitches a second (10 pulses a second, within +-4 %), run up and braked over 25 ms at either end; the next hole is
    found in 0.4 ... 1.1 s (e.g. the Western Electric No. 5 dial's specification: 10 pps, a 61 ... 64 % break). At
    least one 0. Returns events (start, pitches, wind time, hold, return speed) and the end time."""
    digits = [int(d) for d in rng.integers(0, 10, n_digits)]
    if 0 not in digits:
        digits[int(rng.integers(n_digits))] = 0
    ev, tc = [], rng.uniform(0.3, 0.6)
    for d in digits:
        p = (10 if d == 0 else d) + 1
        Tw = rng.uniform(0.25, 0.45) + 0.02 * p
        hold = rng.uniform(0.05, 0.2)
        w = 10.0 * rng.uniform(0.96, 1.04)
        ev.append((tc, p, Tw, hold, w))
        tc += Tw + hold + governed_return(0.0, p, w)[1] + rng.uniform(0.4, 1.1)
    return ev, digits, tc + rng.uniform(0.3, 0.6)


def governed_return(s, p, w, ramp=0.025):
    """The dial's angle s after release, from p pitches back to 0 at the governor's speed w: the speed rises linearly
    over ramp, runs at w and falls linearly over ramp to rest at 0 (trapezoidal speed; the cruise long enough for any
    digit)."""
    s = np.asarray(s, float)
    Tc = p / w - ramp                                   # the cruise's duration (the two ramps cover w ramp)
    T = Tc + 2 * ramp
    back = np.where(s < ramp, 0.5 * w * s * s / ramp,
                    np.where(s < ramp + Tc, 0.5 * w * ramp + w * (s - ramp),
                             np.where(s < T, p - 0.5 * w * (T - s) ** 2 / ramp, p)))
    return p - back, T


def dial_angle(t, events):
    """The dial's angle in pitches (0 at rest) along :func:`dial_number`'s events."""
    t = np.asarray(t, float)
    x = np.zeros(len(t))
    for t0, p, Tw, hold, w in events:
        m = (t >= t0) & (t < t0 + Tw + hold)
        x[m] = p * smoothstep5((t[m] - t0) / Tw)
        tr = t0 + Tw + hold
        _, T = governed_return(0.0, p, w)
        m = (t >= tr) & (t < tr + T)
        x[m] = governed_return(t[m] - tr, p, w)[0]
    return x


# ---- drift: a cow chewing its cud ----

def rumination(rng, n_boli):
    """A cow's lower jaw sideways while ruminating (compressed: real boli take 40 ... 60 chews): each bolus is chewed on
    one side, 12 ... 20 chews of 0.75 ... 0.95 s (each within +-5 %): the jaw swings out to the working side (0.85 ...
    1.0) in 0.35 of the chew, drives back across in the power stroke to the balancing side (0.2 ... 0.4) in 0.45, and
    returns to the middle in 0.2; between boli the jaw rests 3 ... 5 s at the middle while the bolus is swallowed and
    the next regurgitated, chewed on the other side (e.g. Beauchemin, J. Dairy Sci. 74 (1991) 3140, on rumination
    chews). Returns (times, values) for :func:`glide`."""
    times, vals = [0.0, rng.uniform(0.5, 1.0)], [0.0, 0.0]
    tc = times[-1]
    side = float(rng.choice([-1.0, 1.0]))
    for b in range(n_boli):
        P = rng.uniform(0.75, 0.95)
        for _ in range(int(rng.integers(12, 21))):
            Pk = P * rng.uniform(0.95, 1.05)
            for frac, val in ((0.35, side * rng.uniform(0.85, 1.0)), (0.45, -side * rng.uniform(0.2, 0.4)),
                              (0.2, 0.0)):
                tc += frac * Pk
                times.append(tc)
                vals.append(val)
        tc += rng.uniform(3.0, 5.0)
        times.append(tc)
        vals.append(0.0)
        side = -side
    return times, vals


# ---- asymmetry: a goalkeeper in a penalty shoot-out ----

def shootout(rng, n_kicks):
    """A goalkeeper's place along the goal line through a shoot-out (1 a full dive's reach, the line's middle 0;
    compressed): for each kick the keeper bounces lightly on the line (+-0.03 ... 0.1, 1.5 ... 2.5 a second) through the
    taker's run-up of 1.5 ... 2.5 s, dives to a side (0.8 ... 1.0 in 0.35 ... 0.55 s) or, one time in six, steps only
    0.1 ... 0.2 and back, lies 0.6 ... 1.2 s, gets up and walks back to the middle in 1.5 ... 2.5 s and waits 1 ... 2 s.
    Returns (times, values) for :func:`glide`."""
    times, vals = [0.0, rng.uniform(0.5, 1.0)], [0.0, 0.0]
    tc = times[-1]
    for _ in range(n_kicks):
        T_run, f_b, a_b = rng.uniform(1.5, 2.5), rng.uniform(1.5, 2.5), rng.uniform(0.03, 0.1)
        n_b = max(1, int(T_run * f_b))
        for k in range(n_b):
            tc += 0.5 / f_b
            times.append(tc)
            vals.append(a_b * (1 if k % 2 == 0 else -1))
        tc += 0.5 / f_b
        times.append(tc)
        vals.append(0.0)
        side = float(rng.choice([-1.0, 1.0]))
        if rng.random() < 1 / 6:
            tc += rng.uniform(0.3, 0.5)
            times.append(tc)
            vals.append(side * rng.uniform(0.1, 0.2))
            tc += rng.uniform(0.5, 0.9)
        else:
            tc += rng.uniform(0.35, 0.55)
            times.append(tc)
            vals.append(side * rng.uniform(0.8, 1.0))
            tc += rng.uniform(0.6, 1.2)
            times.append(tc)
            vals.append(vals[-1])
            tc += rng.uniform(1.5, 2.5)
        times.append(tc)
        vals.append(0.0)
        tc += rng.uniform(1.0, 2.0)
        times.append(tc)
        vals.append(0.0)
    return times, vals


# ---- saturation: a prospector panning for gold ----

def panning(rng, n_rounds):
    """A gold pan's sideways position (1 the prospector's full swirl): rounds of dipping for water (the pan still, 1 ...
    2 s), shaking to settle the gold (side to side at 3 ... 5 Hz, +-0.25 ... 0.5, 1.5 ... 3 s), swirling the light
    material over the lip (the pan's x on a circle: 0.8 ... 1.4 turns a second, 0.75 ... 1.0, 3 ... 6 s) and rocking the
    water across (0.4 ... 0.7 Hz, 0.5 ... 0.8, 2 ... 4 s), the motions in a drawn order, each faded in and out over
    0.2 ... 0.35 s (e.g. the US Geological Survey's booklet *Prospecting for Gold in the United States*). Returns
    segments (start, duration, frequency, amplitude, ramp, phase sign) and the end time."""
    segs, tc = [], rng.uniform(0.5, 1.0)
    for _ in range(n_rounds):
        tc += rng.uniform(1.0, 2.0)                                         # dipping
        for kind in rng.permutation(["shake", "swirl", "rock"]):
            if kind == "shake":
                f, a, T = rng.uniform(3.0, 5.0), rng.uniform(0.25, 0.5), rng.uniform(1.5, 3.0)
            elif kind == "swirl":
                f, a, T = rng.uniform(0.8, 1.4), rng.uniform(0.75, 1.0), rng.uniform(3.0, 6.0)
            else:
                f, a, T = rng.uniform(0.4, 0.7), rng.uniform(0.5, 0.8), rng.uniform(2.0, 4.0)
            segs.append((tc, T, f, a, rng.uniform(0.2, 0.35), float(rng.choice([-1.0, 1.0]))))
            tc += T + rng.uniform(0.1, 0.4)
    return segs, tc + rng.uniform(1.0, 2.0)


def pan_position(t, segs):
    """The pan along :func:`panning`'s segments: each a sine a sgn sin(2 pi f (t - t0)) under its Hann-edged envelope
    (0 between them)."""
    t = np.asarray(t, float)
    x = np.zeros(len(t))
    for t0, T, f, a, ramp, sg in segs:
        m = (t >= t0) & (t <= t0 + T)
        x[m] += sg * a * np.sin(2 * math.pi * f * (t[m] - t0)) * hann_edges(t[m], t0, T, ramp)
    return x


# ---- delay: a plunger butter churn ----

def churning(rng, n_bouts):
    """A plunger (dash) churn's dasher height (0 resting on the churn's bottom, 1 its highest lift): bouts of 12 ... 22
    strokes of 0.65 ... 1.0 s (60 ... 90 a minute), lifted slowly over 0.5 ... 0.6 of the stroke to 0.85 ... 1.0 and
    plunged fast to 0 ... 0.08; between bouts the churner changes hands, the dasher resting 1.5 ... 3 s on the bottom;
    once the butter comes (the last bout) the strokes slow by 20 ... 40 % and shorten to 0.6 ... 0.8 (e.g. the
    household manuals on churning: the dasher 'heavy' when the butter gathers). Returns (times, values) for
    :func:`glide`."""
    times, vals = [0.0, rng.uniform(0.5, 1.0)], [0.0, 0.0]
    tc = times[-1]
    P = rng.uniform(0.65, 1.0)
    for b in range(n_bouts):
        late = b == n_bouts - 1
        Pb = P * (rng.uniform(1.2, 1.4) if late else 1.0)
        for _ in range(int(rng.integers(12, 23))):
            Pk = Pb * rng.uniform(0.95, 1.05)
            up = rng.uniform(0.5, 0.6)
            tc += up * Pk
            times.append(tc)
            vals.append(rng.uniform(0.6, 0.8) if late else rng.uniform(0.85, 1.0))
            tc += (1 - up) * Pk
            times.append(tc)
            vals.append(rng.uniform(0.0, 0.08))
        tc += 0.2
        times.append(tc)
        vals.append(0.0)
        tc += rng.uniform(1.5, 3.0)
        times.append(tc)
        vals.append(0.0)
    return times, vals


# ---- initial state: a guitarist strumming a song ----

PATTERNS = {"D-DU-UDU": [1, 0, 1, 1, 0, 1, 1, 1], "DDUUDU": [1, 0, 1, 1, 0, 1, 0, 1],
            "D-D-DUDU": [1, 0, 1, 0, 1, 1, 1, 1], "DUDUDUDU": [1, 1, 1, 1, 1, 1, 1, 1]}


def strumming(rng):
    """A guitarist's strumming hand, up and down across the strings (+-1 its full swing): the hand swings down on every
    beat and up on every 'and' whether or not it strikes (the pattern's strokes pass through the strings, 0.85 ... 1.0;
    the missed ones swing short, 0.55 ... 0.7; upstrokes 0.87 ... 0.97 of downstrokes), 84 ... 120 beats a minute; an
    intro of two to four bars swelling from 0.2 to 0.55, verses and a chorus in drawn patterns, a last downstroke let
    ring, the hand at rest in the middle (e.g. any strumming primer's eighth-note patterns). Returns (times, values) for
    :func:`glide`, the tempo and the bars' patterns."""
    bpm = rng.uniform(84.0, 120.0)
    e8 = 30.0 / bpm
    up = rng.uniform(0.87, 0.97)
    times, vals = [0.0, rng.uniform(0.5, 1.0)], [0.0, 0.0]
    tc = times[-1]
    names = sorted(PATTERNS)
    n_intro = int(rng.integers(2, 5))
    bars = ["intro"] * n_intro + [str(rng.choice(names))] * 4 + [str(rng.choice(names))] * 4
    swell = iter(np.linspace(0.2, 0.55, 8 * n_intro))
    for bar in bars:
        pat = PATTERNS["DUDUDUDU"] if bar == "intro" else PATTERNS[bar]
        for k, hit in enumerate(pat):
            tc += e8
            if bar == "intro":
                a = next(swell) * rng.uniform(0.95, 1.05)
            else:
                a = rng.uniform(0.85, 1.0) if hit else rng.uniform(0.55, 0.7)
            times.append(tc)
            vals.append(-a if k % 2 == 0 else a * up)
    tc += e8
    times.append(tc)
    vals.append(-rng.uniform(0.85, 1.0))
    tc += 4 * e8
    times.append(tc)
    vals.append(0.0)
    times.append(tc + rng.uniform(0.5, 1.0))
    vals.append(0.0)
    return times, vals, bpm, bars


# ---- the pair: a welder weaving a multi-pass butt weld ----

def weave_passes(rng):
    """A welding torch's place across a V-groove butt weld (+-1 the cap's toes) through its passes: the root as a
    stringer (a whip of +-0.08 ... 0.15), a hot pass (+-0.35 ... 0.5), a fill (+-0.6 ... 0.8) and the cap (+-0.85 ...
    1.0), each woven at 1.2 ... 2.5 crossings a second (the cap at 0.8 ... 1.4) with a dwell at each toe of 0.1 ... 0.25
    of the crossing (to fuse the sidewalls), 3.5 ... 5.5 s a pass (compressed); between passes the arc is broken and the
    torch brought back to the groove's middle for 1.5 ... 3 s (e.g. the AWS Welding Handbook's weave techniques).
    Returns (times, values) for :func:`glide` and the passes' widths."""
    widths = [rng.uniform(0.08, 0.15), rng.uniform(0.35, 0.5), rng.uniform(0.6, 0.8), rng.uniform(0.85, 1.0)]
    times, vals = [0.0, rng.uniform(0.5, 1.0)], [0.0, 0.0]
    tc = times[-1]
    for j, W in enumerate(widths):
        rate = rng.uniform(0.8, 1.4) if j == 3 else rng.uniform(1.2, 2.5)
        dwell = rng.uniform(0.1, 0.25)
        t_end = tc + rng.uniform(3.5, 5.5)
        side = float(rng.choice([-1.0, 1.0]))
        tc += 0.5 * (1 - dwell) / rate
        times.append(tc)
        vals.append(side * W)
        while tc < t_end:
            tc += dwell / rate
            times.append(tc)
            vals.append(side * W)
            side = -side
            tc += (1 - dwell) / rate
            times.append(tc)
            vals.append(side * W)
        tc += 0.5 * (1 - dwell) / rate
        times.append(tc)
        vals.append(0.0)
        tc += rng.uniform(1.5, 3.0)
        times.append(tc)
        vals.append(0.0)
    return times, vals, widths


# ---- out of vocabulary: a fish swimming in bursts and coasts ----

def burst_and_coast(rng, T_total):
    """A fish's tail tip sideways (+-1 its largest bend) swimming in burst-and-coast (Weihs, J. Theor. Biol. 48 (1974)
    215; Videler & Weihs, J. Exp. Biol. 97 (1982) 169): bursts of 2 ... 5 tail beats at 3 ... 6 a second, +-0.6 ...
    0.95, faded in and out over a quarter beat; one burst in four a fast start instead (a C-bend to 0.9 ... 1.0 in 0.06
    ... 0.1 s, the counter-stroke to 0.6 ... 0.8 the other way and two beats); each followed by a coast with the tail
    straight for 0.4 ... 1.6 s. Returns segments (start, kind, parameters) and the end time."""
    segs, tc = [], rng.uniform(0.5, 1.0)
    while tc < T_total:
        sg = float(rng.choice([-1.0, 1.0]))
        if rng.random() < 0.25:
            Tc, a1, a2, f = rng.uniform(0.06, 0.1), rng.uniform(0.9, 1.0), rng.uniform(0.6, 0.8), rng.uniform(3.0, 6.0)
            segs.append((tc, "fast_start", (sg, Tc, a1, a2, f)))
            tc += 2 * Tc + 1.5 * Tc + 2.0 / f
        else:
            nb, f, a = int(rng.integers(2, 6)), rng.uniform(3.0, 6.0), rng.uniform(0.6, 0.95)
            segs.append((tc, "burst", (sg, nb, f, a)))
            tc += nb / f
        tc += rng.uniform(0.4, 1.6)
    return segs, tc


def tail_tip(t, segs):
    """The tail tip along :func:`burst_and_coast`'s segments: a burst a sgn sin(2 pi f s) for nb beats under a
    Hann-edged envelope (a quarter beat); a fast start glides to sgn a1 in Tc, to -sgn a2 in 2 Tc and back to 0 in
    1.5 Tc (minimum-jerk), then two beats of the burst form at a2."""
    t = np.asarray(t, float)
    x = np.zeros(len(t))
    for t0, kind, p in segs:
        if kind == "burst":
            sg, nb, f, a = p
            T = nb / f
            m = (t >= t0) & (t <= t0 + T)
            x[m] += sg * a * np.sin(2 * math.pi * f * (t[m] - t0)) * hann_edges(t[m], t0, T, 0.25 / f)
        else:
            sg, Tc, a1, a2, f = p
            tt = [t0, t0 + Tc, t0 + 3 * Tc, t0 + 4.5 * Tc]
            m = (t >= t0) & (t <= tt[-1])
            x[m] += glide(t[m], tt, [0.0, sg * a1, -sg * a2, 0.0])
            t1, T = tt[-1], 2.0 / f
            m = (t > t1) & (t <= t1 + T)
            x[m] += sg * a2 * np.sin(2 * math.pi * f * (t[m] - t1)) * hann_edges(t[m], t1, T, 0.25 / f)
    return x

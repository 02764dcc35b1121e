"""Excitations of the HOLDOUT39 set (``cases_holdout39.py``), each beside its source; the mechanisms are in
:mod:`.mechanisms39`. Citations written from memory in this session (none was re-read), as in mechanisms39.

Every generator draws a programme from ``rng`` and returns it; its companion evaluates the path on any times,
normalised to about -1 ... 1 (or 0 ... 1 for the unipolar ones), at rest (exactly 0) before the programme starts; the
cases scale it to volts. Nothing here imports another set's signals.
"""

import math

import numpy as np


def smooth_step(s):
    """The half-cosine ramp (1 - cos(pi s)) / 2 on 0 ... 1 (zero slope at both ends), 0 below and 1 above."""
    s = np.clip(np.asarray(s, float), 0.0, 1.0)
    return 0.5 * (1.0 - np.cos(math.pi * s))


def fade(t, t_on, t_off, ramp):
    """1 between t_on + ramp and t_off - ramp, half-cosine ramps at either end, 0 outside t_on ... t_off."""
    t = np.asarray(t, float)
    return smooth_step((t - t_on) / ramp) * smooth_step((t_off - t) / ramp)


def trapezoid_profile(s, a):
    """A point-to-point move's position (0 ... 1) at its normalised time s (0 ... 1) under a trapezoidal speed profile
    whose ramps take the fraction a (0 < a <= 1/2) of the move at each end: constant acceleration, cruise, constant
    deceleration (the speed's peak 1 / (1 - a)); 0 below and 1 above."""
    s = np.clip(np.asarray(s, float), 0.0, 1.0)
    vmax = 1.0 / (1.0 - a)
    acc = vmax / a
    out = np.where(s < a, 0.5 * acc * s * s,
                   np.where(s <= 1.0 - a, 0.5 * acc * a * a + vmax * (s - a),
                            1.0 - 0.5 * acc * (1.0 - s) ** 2))
    return out


def segments_path(t, segs, start=0.0):
    """The path through segments (t0, T, a, b, kind) in time order: from a to b over T from t0, "cos" a half-cosine
    move, "lin" a straight line (constant speed), "acc" a constant acceleration from rest (a + (b - a) s^2, ending at
    the speed 2 (b - a) / T), "trap" a trapezoidal-speed move (kind ("trap", ramp fraction));
    before the first the value ``start``, between two segments and after the last the previous segment's end (a hold).
    """
    t = np.asarray(t, float)
    out = np.full(len(t), float(start))
    for t0, T, a, b, kind in segs:
        s = (t - t0) / T
        m = t >= t0
        if isinstance(kind, tuple):
            shape = trapezoid_profile(s[m], kind[1])
        elif kind == "lin":
            shape = np.clip(s[m], 0.0, 1.0)
        elif kind == "acc":
            shape = np.clip(s[m], 0.0, 1.0) ** 2
        else:
            shape = smooth_step(s[m])
        out[m] = a + (b - a) * shape
    return out


class _Path:
    """A helper for programmes made of moves and holds: ``go(b, T, kind)`` moves from the present value to b over T,
    ``hold(T)`` holds; ``segs`` the segments, ``t`` the present time, ``x`` the present value."""

    def __init__(self, t0=0.0, x0=0.0):
        self.t, self.x, self.segs = float(t0), float(x0), []

    def go(self, b, T, kind="cos"):
        self.segs.append((self.t, float(T), self.x, float(b), kind))
        self.t += float(T)
        self.x = float(b)

    def hold(self, T):
        self.t += float(T)


# ---- clean: an inkjet printer's carriage ----

def inkjet_carriage(rng, n_pages):
    """The print-head carriage of an inkjet printer printing text pages bidirectionally (replayed slowed down, about
    threefold): the carriage crosses the page at a constant speed between acceleration ramps (a trapezoidal speed
    profile, the ramps 0.12 ... 0.2 of a pass), printing a line on each pass from the left margin (-0.9) to the line's
    end (ragged text: 0.1 ... 0.95, a short last line of a paragraph -0.4 ... 0.1 now and then, a chance of 0.2) and
    back, the overrun beyond the text 0.05; a pause of 0.12 ... 0.3 s at each end while the paper advances (a line feed;
    0.5 ... 0.8 s for a paragraph's blank line). Passes cross 1.85 units in 0.55 ... 0.8 s. Each page of 7 ... 11
    lines starts and ends with the carriage at its service station (-1: capping, a spit and a wipe, 0.8 ... 1.6 s).
    The carriage starts at rest at 0 (where the last job left it) and is parked at the station at the end. Returns the
    segments and T_end."""
    p = _Path(0.0, 0.0)
    p.hold(rng.uniform(0.5, 1.0))
    speed = 1.85 / rng.uniform(0.55, 0.8)
    ramp = rng.uniform(0.12, 0.2)

    def move(b):
        p.go(b, max(abs(b - p.x) / speed, 0.12) / (1.0 - ramp), ("trap", ramp))

    for page in range(n_pages):
        p.go(-1.0, rng.uniform(0.4, 0.6))
        p.hold(rng.uniform(0.8, 1.6))
        p.go(-0.95, 0.2)
        n_lines = int(rng.integers(7, 12))
        right = True
        for k in range(n_lines):
            end = rng.uniform(-0.4, 0.1) if rng.uniform() < 0.2 else rng.uniform(0.1, 0.95)
            move(end + 0.05 if right else -0.95)
            p.hold(rng.uniform(0.5, 0.8) if rng.uniform() < 0.15 else rng.uniform(0.12, 0.3))
            right = not right
        if not right:
            move(-0.95)
    p.go(-1.0, rng.uniform(0.4, 0.6))
    p.hold(rng.uniform(0.5, 1.0))
    return p.segs, p.t


def inkjet_position(t, segs):
    return segments_path(t, segs)


# ---- creep: a toilet cistern ----

def toilet_cistern(rng, n_flushes):
    """The water level in a WC cistern (0 empty, 1 full; time-compressed about fourfold), a new cistern filled for the
    first time and flushed n_flushes times: the float valve fills at its full flow q (the cistern from empty in 2.5
    ... 4 s) until the float lifts within delta (0.03 ... 0.06) of full, then its diaphragm throttles the flow to
    nothing as the float rises (the speed falling as a quarter cosine: the last delta in pi delta / (2 q)); a flush
    empties it through the flush valve by Torricelli's law, sqrt(h + e) falling at k / 2 (e 0.2 ... 0.4 the valve's
    depth below the cistern's floor, the full flush in 0.8 ... 1.4 s), until the flapper drops at 0.06 ... 0.12 (a full
    flush) or the dual-flush valve closes at 0.45 ... 0.6 (a half flush, a chance of 0.4); the cistern then stands full
    for 4 ... 12 s, twice 15 ... 25 s (nobody there). At the end the supply is shut and a last full flush leaves it
    nearly empty for 2 ... 4 s. Returns the programme: q, delta, e, k and the events (kind, t0, from, to): a fill from
    a level, a flush from a level down to another, the shut supply holding a level."""
    q = 1.0 / rng.uniform(2.5, 4.0)
    delta = rng.uniform(0.03, 0.06)
    e = rng.uniform(0.2, 0.4)
    k = 2.0 * (math.sqrt(1.0 + e) - math.sqrt(e)) / rng.uniform(0.8, 1.4)
    t = rng.uniform(1.0, 2.0)
    events = [("fill", t, 0.0, 1.0)]
    t_fill = t
    long_ones = set(rng.choice(np.arange(n_flushes), size=min(2, n_flushes), replace=False).tolist())
    low = 0.0
    t += _fill_time(0.0, q, delta)
    for i in range(n_flushes + 1):
        last = i == n_flushes
        if last:
            t += rng.uniform(3.0, 6.0)
        else:
            t += rng.uniform(15.0, 25.0) if i in long_ones else rng.uniform(4.0, 12.0)
        h0 = float(_fill(np.array([t - t_fill]), low, q, delta)[0])
        low = rng.uniform(0.06, 0.12) if (last or rng.uniform() >= 0.4) else rng.uniform(0.45, 0.6)
        events.append(("flush", t, h0, low))
        t += _flush_time(h0, low, e, k)
        events.append(("shut" if last else "fill", t, low, 1.0))
        t_fill = t
        t += _fill_time(low, q, delta)
    t = events[-1][1]
    return dict(q=q, delta=delta, e=e, k=k, events=events, T_end=t + rng.uniform(2.0, 4.0))


def _fill_time(h0, q, delta):
    """The time the float valve takes from h0 to full."""
    t1 = max(1.0 - delta - h0, 0.0) / q
    return t1 + _close_time(1.0 - max(h0, 1.0 - delta), q)


def _close_time(rest, q):
    """The float valve's closing over the last ``rest`` of the level: the speed q cos(pi s / (2 T)), T = pi rest /
    (2 q)."""
    return math.pi * rest / (2.0 * q)


def _flush_time(h0, low, e, k):
    return 2.0 * (math.sqrt(h0 + e) - math.sqrt(low + e)) / k


def _fill(s, h0, q, delta):
    """The level s after the float valve opens at h0: a straight rise at q to 1 - delta, then the closing valve's
    quarter-cosine speed (the level 1 - delta + delta sin(pi s' / (2 T))) to full at T = pi delta / (2 q), then full."""
    s = np.asarray(s, float)
    t1 = max(1.0 - delta - h0, 0.0) / q
    h1 = max(h0, 1.0 - delta)
    T = _close_time(1.0 - h1, q)
    lin = h0 + q * s
    close = h1 + (1.0 - h1) * np.sin(0.5 * math.pi * np.clip((s - t1) / T, 0.0, 1.0))
    return np.where(s < t1, lin, close)


def _flush(s, h0, low, e, k):
    """The level s after the flush valve opens at h0: (sqrt(h0 + e) - k s / 2)^2 - e, until it reaches low."""
    s = np.asarray(s, float)
    r = np.sqrt(h0 + e) - 0.5 * k * s
    return np.maximum(r * r - e, low)


def cistern_level(t, prog):
    """The level on times t: 0 before the first fill; each event (kind, t0, a, b) a fill from a, a flush from a down to
    b, or (shut) a hold at a."""
    t = np.asarray(t, float)
    x = np.zeros(len(t))
    q, delta, e, k = prog["q"], prog["delta"], prog["e"], prog["k"]
    ev = prog["events"]
    for i, (kind, t0, a, b) in enumerate(ev):
        t1 = ev[i + 1][1] if i + 1 < len(ev) else np.inf
        m = (t >= t0) & (t < t1)
        s = t[m] - t0
        if kind == "fill":
            x[m] = _fill(s, a, q, delta)
        elif kind == "flush":
            x[m] = _flush(s, a, b, e, k)
        else:
            x[m] = a
    return x


# ---- rate: tossing a wok ----

def lanczos_sawtooth(phi, K):
    """A smooth sawtooth of K harmonics with Lanczos's sigma factors: sum (-1)^(k+1) sigma_k sin(k phi) / k, over its
    largest: a slow rise through the middle of each cycle and a quick fall at phi = pi (odd)."""
    phi = np.asarray(phi, float)
    ks = np.arange(1, K + 1)
    sig = np.sinc(ks / (K + 1))
    w = (-1.0) ** (ks + 1) * sig / ks
    ss = np.linspace(0, 2 * math.pi, 4001)
    peak = np.abs(np.sin(ss[:, None] * ks[None, :]) @ w).max()
    return (np.sin(phi[..., None] * ks) @ w) / peak


def wok_tossing(rng, n_bouts):
    """The fore-aft position of a wok in a stir-fry (the chef's toss: the wok pushed forward and jerked back and up so
    the food flips, a smooth sawtooth of 3 ... 5 harmonics, a slow push and a quick pull): n_bouts bouts of 5 ... 12
    tosses at 2.2 ... 3.6 tosses a second (quickening by up to 15 % through a bout), amplitudes 0.6 ... 1 (one bout 1),
    faded in and out over half a toss; between bouts the wok rests on the burner (0) for 0.6 ... 1.5 s while the ladle
    stirs, or (a chance of 0.4) is shuffled gently back and forth (0.15 ... 0.3 at 1.2 ... 1.8 Hz, 1.5 ... 3 s). At rest
    0.5 ... 1 s at the start and the end. Returns the list of bouts (t0, T, f0, f1, amp, K, kind) and T_end."""
    t = rng.uniform(0.5, 1.0)
    bouts = []
    for i in range(n_bouts):
        f0 = rng.uniform(2.2, 3.6)
        f1 = f0 * rng.uniform(1.0, 1.15)
        n = int(rng.integers(5, 13))
        T = n / (0.5 * (f0 + f1))
        bouts.append([t, T, f0, f1, rng.uniform(0.6, 1.0), int(rng.integers(3, 6)), "toss"])
        t += T
        if i < n_bouts - 1:
            if rng.uniform() < 0.4:
                f = rng.uniform(1.2, 1.8)
                Ts = int(rng.integers(2, 5)) / f
                bouts.append([t + 0.2, Ts, f, f, rng.uniform(0.15, 0.3), 1, "shuffle"])
                t += Ts + 0.4
            else:
                t += rng.uniform(0.6, 1.5)
    tosses = [b for b in bouts if b[6] == "toss"]
    tosses[int(rng.integers(len(tosses)))][4] = 1.0
    return [tuple(b) for b in bouts], t + rng.uniform(0.5, 1.0)


def wok_position(t, bouts):
    t = np.asarray(t, float)
    x = np.zeros(len(t))
    for t0, T, f0, f1, amp, K, kind in bouts:
        s = t - t0
        m = (s >= 0) & (s < T)
        ss = s[m]
        phase = 2 * math.pi * (f0 * ss + 0.5 * (f1 - f0) * ss * ss / T)
        if kind == "toss":
            half = 0.5 / f0
            env = smooth_step(ss / half) * smooth_step((T - ss) / half)
            x[m] = amp * env * lanczos_sawtooth(phase, K)
        else:
            x[m] = amp * np.sin(phase) * smooth_step(ss / 0.3) * smooth_step((T - ss) / 0.3)
    return x


# ---- drift: a garage's two-post car lift ----

def car_lift(rng, n_cars):
    """The height of a garage's two-post lift (0 on the floor, 1 its highest working height; unipolar) through n_cars
    cars: each driven in and its arms set (0 for 2 ... 4 s), raised at the lift's speed (full height in 3 ... 4.5 s,
    soft start and stop), either to waist height (0.35 ... 0.5: wheels and brakes) or overhead (0.8 ... 1: exhaust,
    oil; one car 1), lowered onto its safety locks (down 0.02 ... 0.04 in 0.6 s), held while the mechanic works (6
    ... 14 s), sometimes (a chance of 0.4) raised to the other height in between (lifted off the locks first), at
    the end lifted off the locks (back up by the drop in 0.6 s) and lowered (full height in 4 ... 6 s), the car driven
    off (0 for 2 ... 4 s). Returns the segments and T_end."""
    p = _Path(0.0, 0.0)
    rise = rng.uniform(3.0, 4.5)
    fall = rng.uniform(4.0, 6.0)
    tops = [rng.uniform(0.8, 1.0) if rng.uniform() < 0.6 else rng.uniform(0.35, 0.5) for _ in range(n_cars)]
    tops[int(rng.integers(n_cars))] = 1.0

    def to(h, rate_time):
        p.go(h, max(abs(h - p.x) * rate_time, 0.6))

    for i in range(n_cars):
        p.hold(rng.uniform(2.0, 4.0))
        heights = [tops[i]]
        if rng.uniform() < 0.4:
            heights.append(rng.uniform(0.35, 0.5) if tops[i] > 0.6 else rng.uniform(0.8, 0.95))
        drop = 0.0
        for j, hgt in enumerate(heights):
            if j > 0:
                p.go(p.x + drop, 0.6)
            to(hgt, rise if hgt > p.x else fall)
            drop = rng.uniform(0.02, 0.04)
            p.go(p.x - drop, 0.6)
            p.hold(rng.uniform(6.0, 14.0))
        p.go(p.x + drop, 0.6)
        to(0.0, fall)
    p.hold(rng.uniform(2.0, 4.0))
    return p.segs, p.t


def lift_height(t, segs):
    return segments_path(t, segs)


# ---- asymmetry: a mortar and pestle ----

def mortar_and_pestle(rng, n_rounds):
    """The x of a pestle's head in a mortar (grinding spices): n_rounds rounds of grinding in circles (x = rho cos phi;
    1 ... 1.8 turns a second, now and then reversing its sense; the circle's radius wandering between 0.6 and 1, one
    round reaching 1, through smooth knots every 0.8 s; 3 ... 6 s), each followed by pounding at a spot (x held within
    +-0.4 while the pestle strikes straight down: 1.5 ... 3 s) or by scraping the spices down the wall (a slow half
    turn, x from one side to the other and back, 1.5 ... 2.5 s). The pestle starts and ends resting at the bowl's
    centre (0). Returns the list of pieces and T_end."""
    t = rng.uniform(0.5, 1.0)
    pieces = []
    x_end = 0.0
    big = int(rng.integers(n_rounds))
    for i in range(n_rounds):
        T = rng.uniform(3.0, 6.0)
        f = rng.uniform(1.0, 1.8) * float(rng.choice([-1.0, 1.0]))
        kt = np.arange(0.0, T + 0.8, 0.8)
        kv = rng.uniform(0.6, 0.95, len(kt))
        if i == big:
            kv[int(rng.integers(1, len(kt) - 1))] = 1.0
        ph0 = rng.uniform(0, 2 * math.pi)
        pieces.append(("circle", t, T, x_end, f, ph0, kt, kv))
        x_end = float(_circle(np.array([T]), x_end, f, ph0, kt, kv, T)[0])
        t += T
        if rng.uniform() < 0.5:
            spot = rng.uniform(-0.4, 0.4)
            Tm = rng.uniform(0.3, 0.5)
            Tp = rng.uniform(1.5, 3.0)
            pieces.append(("pound", t, Tm + Tp, x_end, spot, Tm))
            x_end = spot
            t += Tm + Tp
        else:
            Ts = rng.uniform(1.5, 2.5)
            side = float(rng.choice([-1.0, 1.0])) * rng.uniform(0.7, 0.9)
            pieces.append(("scrape", t, Ts, x_end, side, 0.0))
            t += Ts
    Tr = rng.uniform(0.4, 0.7)
    pieces.append(("rest", t, Tr, x_end, 0.0, 0.0))
    return pieces, t + Tr + rng.uniform(0.5, 1.0)


def _circle(s, x0, f, ph0, kt, kv, T):
    """A round of circles from x0 (the radius's knots kv at times kt; the first 0.4 s blends in from x0 and the last
    0.4 s holds the phase's end)."""
    s = np.asarray(s, float)
    rho = np.interp(s, kt, kv)
    x = rho * np.cos(2 * math.pi * f * s + ph0)
    w = smooth_step(s / 0.4)
    return x0 * (1.0 - w) + x * w


def pestle_x(t, pieces):
    t = np.asarray(t, float)
    x = np.zeros(len(t))
    for kind, t0, T, x0, a, b, *rest in pieces:
        s = t - t0
        m = s >= 0
        sm = s[m]
        if kind == "circle":
            f, ph0, kt, kv = a, b, rest[0], rest[1]
            x[m] = _circle(np.minimum(sm, T), x0, f, ph0, kt, kv, T)
        elif kind == "pound":
            x[m] = x0 + (a - x0) * smooth_step(sm / b)
        elif kind == "scrape":
            x[m] = np.where(sm < T / 2, x0 + (a - x0) * smooth_step(sm / (T / 2)),
                            a + (x0 - a) * smooth_step((sm - T / 2) / (T / 2)))
        else:
            x[m] = x0 * (1.0 - smooth_step(sm / T))
    return x


# ---- saturation: ironing a shirt ----

def ironing(rng, n_parts):
    """The iron's place along the board (its long axis; 0 the middle) while ironing a shirt: n_parts parts (a sleeve,
    the back, a front panel, the collar, ...) each ironed with strokes pushed and pulled about the part's place (long
    strokes: +-0.55 ... 0.85 about a centre within +-0.15 at 0.6 ... 1.1 Hz, 3 ... 7 of them; a chance of 0.3 of the
    collar's or a cuff's short quick strokes: +-0.12 ... 0.25 about a centre within +-0.6 at 1.6 ... 2.4 Hz, 6 ... 11
    of them); between parts the iron stood on its heel at the board's square end (-0.95 ... -1, or 0.95 ... 1 on a
    left-hander's board) while the garment is rearranged (2 ... 4 s); the strokes' envelope (0.25 s) and the moves (0.4
    ... 0.7 s) half-cosines. The iron starts at rest in the middle (0) and ends on its heel. Returns the list of pieces
    (kind, t0, T, from or centre, to or amplitude, frequency) and T_end."""
    t = rng.uniform(0.5, 1.0)
    heel = float(rng.choice([-1.0, 1.0])) * rng.uniform(0.95, 1.0)
    pieces = []
    x = 0.0
    for i in range(n_parts):
        if rng.uniform() < 0.3:
            a, f, n = rng.uniform(0.12, 0.25), rng.uniform(1.6, 2.4), int(rng.integers(6, 12))
            c = rng.uniform(-0.6, 0.6)
        else:
            a, f, n = rng.uniform(0.55, 0.85), rng.uniform(0.6, 1.1), int(rng.integers(3, 8))
            c = rng.uniform(-0.15, 0.15)
        Tm = rng.uniform(0.4, 0.7)
        pieces.append(("move", t, Tm, x, c, 0.0))
        t += Tm
        T = n / f
        pieces.append(("strokes", t, T, c, a, f))
        t += T
        Tm = rng.uniform(0.4, 0.7)
        pieces.append(("move", t, Tm, c, heel, 0.0))
        t += Tm + rng.uniform(2.0, 4.0)
        x = heel
    return pieces, t


def iron_position(t, pieces):
    t = np.asarray(t, float)
    x = np.zeros(len(t))
    for kind, t0, T, c, a, f in pieces:
        s = t - t0
        m = s >= 0
        sm = s[m]
        if kind == "move":
            x[m] = c + (a - c) * smooth_step(sm / T)
        else:
            inside = sm < T
            env = smooth_step(sm / 0.25) * smooth_step((T - sm) / 0.25)
            x[m] = np.where(inside, c + a * env * np.sin(2 * math.pi * f * sm), c)
    return x


# ---- delay: a door on a hydraulic door closer ----

def door_closer(rng, n_passages):
    """The angle of a door on an overhead hydraulic closer (0 shut, 1 its widest opening; unipolar) through n_passages
    passages: a person pulls it open (a half-cosine to 0.55 ... 1 in 0.6 ... 1.3 s; one passage to 1), holds it for 0.3
    ... 1.5 s while passing, and lets go; the closer's spring shuts it at the sweep speed its valve sets (constant:
    0.2 ... 0.35 a second, reached in 0.15 s) down to the latch angle (0.08 ... 0.14), then at the latch speed (1.8 ...
    3 times faster) onto the stop. Now and then (a chance of 0.25) the door is pushed onto its hold-open arm (0.85 ...
    0.95) and stays 6 ... 12 s before it is pulled off. Shut for 1 ... 5 s between passages, 1 ... 2 s at the start
    and the end. Returns the segments and T_end."""
    p = _Path(0.0, 0.0)
    sweep = rng.uniform(0.2, 0.35)
    latch = rng.uniform(0.08, 0.14)
    lat_speed = sweep * rng.uniform(1.8, 3.0)
    widest = int(rng.integers(n_passages))
    p.hold(rng.uniform(1.0, 2.0))
    for i in range(n_passages):
        hold_open = rng.uniform() < 0.25
        top = 1.0 if i == widest else (rng.uniform(0.85, 0.95) if hold_open else rng.uniform(0.55, 1.0))
        p.go(top, rng.uniform(0.6, 1.3))
        p.hold(rng.uniform(6.0, 12.0) if hold_open else rng.uniform(0.3, 1.5))
        # the closer: a constant acceleration into the sweep (0.15 s), the sweep at constant speed, the latch, the stop
        lead = 0.15 * sweep / 2
        p.go(top - lead, 0.15, "acc")
        p.go(latch, (top - lead - latch) / sweep, "lin")
        p.go(0.0, latch / lat_speed, "lin")
        p.hold(rng.uniform(1.0, 5.0) if i < n_passages - 1 else rng.uniform(1.0, 2.0))
    return p.segs, p.t


def door_angle(t, segs):
    return segments_path(t, segs)


# ---- initial state: rocking a car out of snow ----

def rocking_car(rng):
    """A car's fore-aft place in a snowy rut while its driver rocks it free (forward, then reverse, each swing a little
    further; replayed slowed down): a first attempt of 6 ... 9 swings growing from 0.08 ... 0.15 by 1.25 ... 1.45 times
    a swing up to 0.55 ... 0.75, the car then rolled back into the rut (0) and left 2 ... 4 s (the driver gets out to
    dig); a second attempt of swings growing from 0.15 ... 0.25 to 1 (the last two 0.9 ... 1 either way), each swing a
    half-cosine of 0.7 ... 1.2 s with a pause of 0.15 ... 0.4 s at its end (the gear changed), the car then rolled back
    to 0 and left 1 ... 2 s. At rest 0.8 ... 1.5 s at the start. Returns the segments and T_end."""
    p = _Path(0.0, 0.0)
    p.hold(rng.uniform(0.8, 1.5))
    side = float(rng.choice([-1.0, 1.0]))
    for attempt in range(2):
        if attempt == 0:
            a, top, n_max = rng.uniform(0.08, 0.15), rng.uniform(0.55, 0.75), int(rng.integers(6, 10))
        else:
            a, top, n_max = rng.uniform(0.15, 0.25), 1.0, 30
        g = rng.uniform(1.25, 1.45)
        amps = []
        while len(amps) < n_max and a < top:
            amps.append(a)
            a *= g
        if attempt == 0:
            amps.append(top)
        else:
            amps += [rng.uniform(0.9, 1.0), 1.0]
        for k, A in enumerate(amps):
            p.go(side * A, rng.uniform(0.7, 1.2))
            p.hold(rng.uniform(0.15, 0.4))
            side = -side
        p.go(0.0, rng.uniform(0.8, 1.2))
        p.hold(rng.uniform(2.0, 4.0) if attempt == 0 else rng.uniform(1.0, 2.0))
    return p.segs, p.t


def car_place(t, segs):
    return segments_path(t, segs)


# ---- pair: a paint roller on a wall ----

def paint_roller(rng, n_loads):
    """The height of a paint roller on a wall (0 chest height, -1 the tray on the floor, 1 the top of the painter's
    reach): held at chest height 0.5 ... 1 s, then n_loads loads: down to the tray (0.6 ... 0.9 s), rested in its well
    4 ... 7 s (the painter moving the ladder), rolled on the tray's ramp 3 ... 4 times (+0.04 ... 0.08 from -0.95 at
    1.5 ... 2 Hz), up to the wall, and 6 ... 12 quick strokes up and down in a W (between -0.75 ... -0.5 and 0.85 ... 1
    at 1.2 ... 2 strokes a second), then 2 ... 4 slow laying-off strokes from the top to the bottom of the patch (0.4
    ... 0.6 Hz); at the end the roller is put back in the tray (held 1 ... 2 s). Returns the segments and T_end."""
    p = _Path(0.0, 0.0)
    p.hold(rng.uniform(0.5, 1.0))
    pieces = []
    for i in range(n_loads):
        p.go(-0.95, rng.uniform(0.6, 0.9))
        p.hold(rng.uniform(4.0, 7.0))
        a, f, n = rng.uniform(0.04, 0.08), rng.uniform(1.5, 2.0), int(rng.integers(3, 5))
        for _ in range(n):
            p.go(-0.95 + a, 0.5 / f)
            p.go(-0.95, 0.5 / f)
        lo, hi = rng.uniform(-0.75, -0.5), rng.uniform(0.85, 1.0)
        p.go(lo, rng.uniform(0.5, 0.7))
        f = rng.uniform(1.2, 2.0)
        for k in range(int(rng.integers(6, 13))):
            p.go(hi if k % 2 == 0 else lo, 0.5 / f)
        f = rng.uniform(0.4, 0.6)
        for k in range(int(rng.integers(2, 5))):
            if abs(p.x - hi) > 1e-12:
                p.go(hi, 0.5 / f)
            p.go(lo, 0.5 / f)
        pieces.append((lo, hi))
    p.go(-0.95, rng.uniform(0.6, 0.9))
    p.hold(rng.uniform(1.0, 2.0))
    return p.segs, p.t


def roller_height(t, segs):
    return segments_path(t, segs)


# ---- out of vocabulary: a car's gear lever ----

def gear_lever(rng, n_trips):
    """A manual gearbox's lever along its fore-aft travel (the H pattern's gears forward +1 for 1st, 3rd and 5th,
    back -1 for 2nd and 4th; the neutral plane 0) through n_trips short town trips: from neutral at rest, into 1st,
    up through the gears to 3rd ... 5th (each held 0.8 ... 3 s), down again as the car slows, to neutral at the stop
    (1 ... 3 s). A shift: out of gear to neutral (0.12 ... 0.2 s), across the gate, into the next (0.25 ... 0.4 s, a
    pause of 0.05 ... 0.12 s at 0.6 of the travel while the synchroniser matches the speeds). Returns the segments and
    T_end."""
    p = _Path(0.0, 0.0)
    p.hold(rng.uniform(0.8, 1.5))
    for trip in range(n_trips):
        top = int(rng.integers(3, 6))
        seq = list(range(1, top + 1)) + list(range(top - 1, 1, -1))
        if rng.uniform() < 0.5:
            seq += [1]
        for gear in seq:
            if p.x != 0.0:
                p.go(0.0, rng.uniform(0.12, 0.2))
                p.hold(rng.uniform(0.05, 0.15))
            target = 1.0 if gear % 2 == 1 else -1.0
            Ta = rng.uniform(0.25, 0.4)
            p.go(0.6 * target, 0.6 * Ta)
            p.hold(rng.uniform(0.05, 0.12))
            p.go(target, 0.4 * Ta)
            p.hold(rng.uniform(0.8, 3.0))
        p.go(0.0, rng.uniform(0.12, 0.2))
        p.hold(rng.uniform(1.0, 3.0))
    return p.segs, p.t


def lever_position(t, segs):
    return segments_path(t, segs)


# ---- out of vocabulary: the mains' hum ----

def pump_switching(rng, T_end):
    """A rotary vane pump's motor switched on and off by its vacuum switch over the record: on for 3 ... 8 s, off for
    2 ... 6 s, starting in a drawn state; each switch a ramp of 0.2 ... 0.4 s (the motor's run-up and run-down). Returns
    the switch times, the starting state and the ramp."""
    on = bool(rng.uniform() < 0.5)
    t, times = 0.0, []
    state = on
    while True:
        t += rng.uniform(3.0, 8.0) if state else rng.uniform(2.0, 6.0)
        if t >= T_end:
            break
        times.append(t)
        state = not state
    return dict(times=times, start_on=on, ramp=rng.uniform(0.2, 0.4))


def pump_state(t, prog):
    """The motor's running share (0 off ... 1 on) on times t."""
    t = np.asarray(t, float)
    s = np.full(len(t), 1.0 if prog["start_on"] else 0.0)
    state = prog["start_on"]
    for tk in prog["times"]:
        w = smooth_step((t - tk) / prog["ramp"])
        s = s + (w if not state else -w)
        state = not state
    return s

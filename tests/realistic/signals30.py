"""Excitations of the HOLDOUT30 set (``cases_holdout30.py``), each beside its source; the mechanisms are in
:mod:`.mechanisms30`. Citations written from memory in this session (none was re-read), as in mechanisms30.
"""

import math

import numpy as np
from scipy.special import ellipj, ellipk

from .mechanisms19 import raised_cosine, smoothstep


def min_jerk(s):
    """The minimum-jerk profile 10 s^3 - 15 s^4 + 6 s^5 on 0 ... 1 (Flash & Hogan, J. Neurosci. 5 (1985) 1688),
    clipped outside."""
    s = np.clip(np.asarray(s, float), 0.0, 1.0)
    return s ** 3 * (10 - 15 * s + 6 * s * s)


# ---- clean: a honeybee's waggle dance ----

def waggle_dance_x(t, t0, runs, heading, L, f_w, a_w):
    """A honeybee dancing on the comb (von Frisch, *The Dance Language and Orientation of Bees*, 1967), filmed along
    an axis across its runs tilted by ``heading`` from their perpendicular: waggle runs (T_run, T_ret) each straight
    for L while the body waggles sideways at f_w Hz by a_w (a sine under a half-sine envelope), then a return loop, a
    half circle of diameter L back to the start, alternately to the right and the left. Returns the place along the
    camera's axis, 0 at the start, at rest before t0 and after the last run."""
    t = np.asarray(t, float)
    x = np.zeros_like(t)
    sh, ch = math.sin(heading), math.cos(heading)
    tc, side = t0, 1.0
    for T_run, T_ret in runs:
        m = (t >= tc) & (t < tc + T_run)
        s = (t[m] - tc) / T_run
        d = L * smoothstep(s)
        w = a_w * np.sin(math.pi * s) * np.sin(2 * math.pi * f_w * (t[m] - tc))
        x[m] = d * sh + w * ch
        tc += T_run
        m = (t >= tc) & (t < tc + T_ret)
        th = math.pi * smoothstep((t[m] - tc) / T_ret)   # the loop's angle from the run's end round to its start
        # the loop's centre is the run's middle; from the end (+L/2 along the heading) round to the start (-L/2)
        along = 0.5 * L + 0.5 * L * np.cos(th)
        across = side * 0.5 * L * np.sin(th)
        x[m] = along * sh + across * ch
        tc += T_ret
        side = -side
    return x


# ---- creep: a bicycle tyre pumped up with a floor pump ----

def pump_strokes(p_start, p_max, ratio, n):
    """The tyre's pressure after each of n strokes of a floor pump (isothermal, the pump's swept volume V_p into the
    tyre's V_t through a valve that opens once the barrel's pressure passes the tyre's; the barrel's dead volume
    limits it to p_max): p_{j+1} = p_j + ratio (p_max - p_j), ratio about V_p / V_t. Returns the n + 1 pressures."""
    p = [p_start]
    for _ in range(n):
        p.append(p[-1] + ratio * (p_max - p[-1]))
    return np.array(p)


def tyre_pressure(t, events):
    """The gauge pressure of a tyre: events (t0, T, p0, p1, kind): kind "stroke" a push of T s (a raised cosine from
    p0 to p1), "bleed" air let out through the valve from p0 to p1 (an exponential of time constant T / 4 ending at
    T: p1 + (p0 - p1) (exp(-4 s / T) - e^-4) / (1 - e^-4)), "hold" nothing; between events the pressure held."""
    t = np.asarray(t, float)
    p = np.zeros_like(t)
    for t0, T, p0, p1, kind in events:
        m = t >= t0
        s = t[m] - t0
        if kind == "stroke":
            p[m] = p0 + (p1 - p0) * raised_cosine(s / T)
        elif kind == "bleed":
            q = np.minimum(s, T)
            p[m] = p1 + (p0 - p1) * (np.exp(-4 * q / T) - math.exp(-4)) / (1 - math.exp(-4))
    return p


# ---- rate: a sewing machine's needle bar ----

def needle_depth(theta, r, l):
    """The needle bar's depth below its top position for a crank angle theta (a slider crank, crank r, connecting rod
    l; theta = 0 at the top): r (1 - cos theta) + l - sqrt(l^2 - r^2 sin^2 theta), in units of the stroke 2 r."""
    theta = np.asarray(theta, float)
    return (r * (1 - np.cos(theta)) + l - np.sqrt(l * l - (r * np.sin(theta)) ** 2)) / (2 * r)


def crank_angle(t, seams):
    """The crank's angle under the foot pedal: seams (t0, n_stitches, rate, t_ramp, stop_down) each spinning up over
    t_ramp s (min-jerk on the rate), sewing at ``rate`` stitches a second and slowing so as to stop after n_stitches
    whole turns (needle up, theta a multiple of 2 pi) or half a turn more (needle down, to pivot the cloth); the next
    seam starts from there. Returns theta."""
    t = np.asarray(t, float)
    th = np.zeros_like(t)
    base = 0.0
    for t0, n, rate, t_ramp, down in seams:
        turns = n + (0.5 if down else 0.0)
        # rate profile: up over t_ramp, steady, down over t_ramp; its integral is turns (in turns)
        T = turns / rate + t_ramp                 # the ramps each lose t_ramp / 2 of full speed
        s = t - t0
        m = s > 0
        sm = s[m]
        # the integral of rate * (mj(s / t_ramp) - mj((s - T + t_ramp) / t_ramp)): min-jerk integrals in closed form
        th[m] = base + 2 * math.pi * rate * (_mj_int(sm, t_ramp) - _mj_int(sm - (T - t_ramp), t_ramp))
        base += 2 * math.pi * turns
    return th


def _mj_int(s, T):
    """The integral from 0 to s of min_jerk(u / T) du."""
    s = np.asarray(s, float)
    q = np.clip(s / T, 0.0, 1.0)
    inner = T * (2.5 * q ** 4 - 3 * q ** 5 + q ** 6)
    return np.where(s > T, 0.5 * T + (s - T), inner)


# ---- drift: a fencing bout ----

def fencer_path(t, actions):
    """A fencer's place along the piste (in units of its half length, -1 ... 1): actions (t0, T, x0, x1, kind) each a
    min-jerk move (steps forward and back, a lunge's fast reach and its recovery, the walk back to the en-garde line
    after a touch), held between them."""
    t = np.asarray(t, float)
    x = np.zeros_like(t)
    for t0, T, x0, x1, _ in actions:
        m = t >= t0
        x[m] = x0 + (x1 - x0) * min_jerk((t[m] - t0) / T)
    return x


# ---- asymmetry: a church bell rung up, rung and rung down ----

def pendulum_quarter(s, w0, A, rising):
    """A quarter swing of a rigid pendulum of small-swing frequency w0 and amplitude A (rad), exact: theta = 2
    arcsin(k sn(w0 s, k)) from 0 up to A (rising) or 2 arcsin(k sn(K + w0 s, k)) from A down to 0, k = sin(A / 2), K
    the complete elliptic integral (modulus k, parameter k^2); a quarter lasts K / w0. E.g. Whittaker & Watson, sec.
    22.8; Lawden, *Elliptic Functions and Applications*, 1989."""
    k = math.sin(A / 2)
    K = float(ellipk(k * k))
    arg = w0 * np.asarray(s, float) + (0.0 if rising else K)
    sn = ellipj(arg, k * k)[0]
    return 2 * np.arcsin(k * sn), K / w0


def bell_angle(t, t0, w0, amps):
    """A bell swung by its rope (change ringing: rung up from rest, swinging nearly to the balance at the top for a
    while, rung down): amps the amplitudes of its swings (rad, alternately to either side), each swing two exact
    quarters of a rigid pendulum (:func:`pendulum_quarter`), the ringer's pull changing the amplitude at the bottom
    (the angle continuous, the speed stepping); at rest at 0 before t0 and after the last swing. Returns theta and
    the end time."""
    t = np.asarray(t, float)
    th = np.zeros_like(t)
    tc, side = t0, 1.0
    for A in amps:
        for rising in (True, False):
            k = math.sin(A / 2)
            Tq = float(ellipk(k * k)) / w0
            m = (t >= tc) & (t < tc + Tq)
            th[m] = side * pendulum_quarter(t[m] - tc, w0, A, rising)[0]
            tc += Tq
        side = -side
    return th, tc


# ---- saturation: a tightrope walker's balancing pole ----

def wobble_peak(f, tau):
    """The first (largest) peak of exp(-s / tau) sin(2 pi f s): at s* = atan(2 pi f tau) / (2 pi f)."""
    w = 2 * math.pi * f
    s = math.atan(w * tau) / w
    return math.exp(-s / tau) * math.sin(w * s)


def pole_tilt(t, wobbles):
    """The tilt of a tightrope walker's balancing pole: wobbles (t0, a, f, tau) each a damped swing exp(-(t - t0) /
    tau) sin(2 pi f (t - t0)) scaled so that its first peak is a, started by a gust or a misstep and damped by the
    walker's corrections (the walker, pole and rope an inverted pendulum held upright), summed."""
    t = np.asarray(t, float)
    x = np.zeros_like(t)
    for t0, a, f, tau in wobbles:
        s = t - t0
        m = s > 0
        x[m] += a / wobble_peak(f, tau) * np.exp(-s[m] / tau) * np.sin(2 * math.pi * f * s[m])
    return x


# ---- delay: a piano key ----

def key_travel(t, notes, t_down, t_up, bounce):
    """A piano key's depression (0 at rest, 1 on the key bed): notes (t0, dur, vel) each a min-jerk descent over
    t_down / vel s, a small rebound off the key-bed felt (bounce exp-damped at 25 Hz), held for dur, then a release
    back to rest over t_up s (min-jerk) as the key's weight returns it."""
    t = np.asarray(t, float)
    x = np.zeros_like(t)
    for t0, dur, vel in notes:
        Td = t_down / vel
        s = t - t0
        m = (s >= 0) & (s < dur + t_up)
        sm = s[m]
        dn = min_jerk(sm / Td)
        rb = np.where(sm > Td, bounce * vel * np.exp(-(sm - Td) / 0.03) * np.abs(np.sin(2 * math.pi * 25 * (sm - Td))),
                      0.0)
        up = min_jerk((sm - dur) / t_up)
        x[m] = np.maximum((dn - rb) * (1 - up), x[m])
    return x


# ---- initial state: a skateboarder in a half-pipe ----

def halfpipe_path(t, t0, halves, stall):
    """A skater's place across a half-pipe (-1 ... 1 at the copings): from rest at the bottom, pumping, each half
    swing (T, a) from the last extreme to the other side's extreme a (the energy rising by the pumping), as a half
    cosine; at a coping (|a| = 1) a stall of ``stall`` s (a trick on the lip) before dropping back in."""
    t = np.asarray(t, float)
    x = np.zeros_like(t)
    tc, cur = t0, 0.0
    for T, a in halves:
        m = t >= tc
        s = np.clip((t[m] - tc) / T, 0.0, 1.0)
        x[m] = cur + (a - cur) * 0.5 * (1 - np.cos(math.pi * s))
        tc += T + (stall if abs(a) >= 1.0 else 0.0)
        cur = a
    return x, tc


# ---- the pair: a dog wagging its tail ----

def tail_wag(t, bouts, bias):
    """A dog's tail seen from behind (its angle, -1 ... 1): bouts (t0, n, f, a) of n wags at f Hz and amplitude a,
    faded in and out over a wag each, swinging further to the right (bias > 0) than to the left (Quaranta, Siniscalchi
    & Vallortigara, Curr. Biol. 17 (2007) R199: the asymmetry of wagging with the dog's emotion); held at 0 between
    bouts."""
    t = np.asarray(t, float)
    x = np.zeros_like(t)
    for t0, n, f, a in bouts:
        s = t - t0
        T = n / f
        m = (s >= 0) & (s <= T)
        env = np.minimum(np.minimum(s[m] * f, 1.0), np.minimum((T - s[m]) * f, 1.0))
        w = np.sin(2 * math.pi * f * s[m])
        x[m] = a * env * np.where(w > 0, (1 + bias) * w, (1 - bias) * w)
    return x


# ---- out of vocabulary: an impact sprinkler ----

def sprinkler_angle(t, t0, cycles, n_kicks, kick_T, kick_gap, ret_T):
    """An impact sprinkler's nozzle (its angle over the arc, -1 ... 1): cycles (n of them) each stepping from -1 to 1
    in n_kicks kicks of the swinging arm (each a min-jerk move of kick_T s, kick_gap s apart), then swept back by the
    reversing lever to -1 over ret_T s (the arm's rapid tapping: a smooth raised cosine); from 0 (the nozzle first
    swept to -1 over ret_T / 2). Returns the angle and the end time."""
    t = np.asarray(t, float)
    x = np.zeros_like(t)
    m = t >= t0
    x[m] = -raised_cosine((t[m] - t0) / (0.5 * ret_T))
    tc = t0 + 0.5 * ret_T + kick_gap
    for _ in range(cycles):
        step = 2.0 / n_kicks
        for j in range(n_kicks):
            m = t >= tc
            x[m] = -1 + step * j + step * min_jerk((t[m] - tc) / kick_T)
            tc += kick_gap
        m = t >= tc
        x[m] = 1 - 2 * raised_cosine((t[m] - tc) / ret_T)
        tc += ret_T + kick_gap
    return x, tc

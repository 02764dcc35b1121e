"""Excitation signals of the HOLDOUT21 set (``cases_holdout21.py``), each written from its source; the mechanisms are
in :mod:`.mechanisms21`.

Citations were written from memory in this session (none was re-read); the signals are checked in
tests/test_realistic_holdout21.py against independent solutions (solve_ivp, brentq, closed forms, quadrature).
"""

import math

import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

from .mechanisms19 import raised_cosine


# ---- Ueda's attractor (the clean case) ----

def ueda_rhs(t, s, k=0.05, B=7.5):
    """The forced hardening Duffing oscillator x'' + k x' + x^3 = B cos t in Ueda's chaotic regime (Ueda, J. Stat.
    Phys. 20 (1979) 181; 'the Japanese attractor'): a single well, its x swinging irregularly between about +-3.5."""
    x, u = s
    return [u, -k * u - x ** 3 + B * math.cos(t)]


def ueda_x(t, units, start, settle=200.0):
    """x at the times t (s), `units` of Ueda's time a second, after `settle` units from `start` (DOP853, rtol 1e-11);
    the forcing's phase runs on from the settling. Returns x and the state the record starts from."""
    s0 = np.array(start, float)
    s0 = solve_ivp(ueda_rhs, (0, settle), s0, method="DOP853", rtol=1e-11, atol=1e-12).y[:, -1]
    tau = settle + np.asarray(t, float) * units
    sol = solve_ivp(ueda_rhs, (tau[0], tau[-1]), s0, t_eval=tau, method="DOP853", rtol=1e-11, atol=1e-12)
    return sol.y[0], s0


# ---- a boat through a flight of staircase locks (the creep case) ----

def lock_level(s, lift, k):
    """A chamber's level s seconds after its sluice opens, rising by `lift` toward the upper pound: the head left, D,
    obeys D' = -k sqrt(D) (Torricelli's law through the sluice), so D = (sqrt(lift) - k s / 2)^2 until it vanishes at
    2 sqrt(lift) / k (e.g. Novak et al., *Hydraulic Structures*, 2007, ch. 13 on lock filling). Returns the rise."""
    s = np.clip(np.asarray(s, float), 0, None)
    root = np.clip(math.sqrt(lift) - k * s / 2, 0, None)
    return lift - root * root


def lock_flight(t, lead, steps, holds, k):
    """The boat's level: from 0 for `lead` s, then steps (signed lifts, in V) one after the other, each by
    :func:`lock_level` (emptying mirrors filling), each followed by its hold (the gates, the boat moving on). Returns
    the level and the steps' (start, duration)."""
    t = np.asarray(t, float)
    v = np.zeros_like(t)
    lvl, tc, seg = 0.0, lead, []
    for st, hd in zip(steps, holds):
        T = 2 * math.sqrt(abs(st)) / k
        m = t >= tc
        v[m] = lvl + math.copysign(1.0, st) * lock_level(t[m] - tc, abs(st), k)
        seg.append((tc, T))
        lvl += st
        tc += T + hd
    return v, seg, tc


# ---- voiced speech as Rosenberg glottal pulses (the rate case) ----

def rosenberg_pulse(psi, tp=0.4, tn=0.16):
    """Rosenberg's glottal flow over one period (phase psi in 0 ... 1): 0.5 (1 - cos(pi psi / tp)) opening, cos(pi
    (psi - tp) / (2 tn)) closing, 0 while closed (Rosenberg, J. Acoust. Soc. Am. 49 (1971) 583, his preferred
    trigonometric pulse)."""
    psi = np.mod(np.asarray(psi, float), 1.0)
    op = 0.5 * (1 - np.cos(np.pi * psi / tp))
    cl = np.cos(np.pi * (psi - tp) / (2 * tn))
    return np.where(psi < tp, op, np.where(psi < tp + tn, cl, 0.0))


def syllables(t, syl):
    """Voiced syllables (t0, f_a, f_b, n_cycles, amp): the pitch glides linearly from f_a toward f_b (intonation) and
    the syllable ends after n whole cycles; the flow is amp x the pulse at the phase int f dt. Silence between."""
    t = np.asarray(t, float)
    v = np.zeros_like(t)
    for t0, fa, fb, nc, amp in syl:
        T = syllable_length(fa, fb, nc)
        s = t - t0
        on = (s >= 0) & (s < T)
        ss = s[on]
        ph = fa * ss + 0.5 * (fb - fa) * ss * ss / T
        v[on] = amp * rosenberg_pulse(ph)
    return v


def syllable_length(fa, fb, nc):
    """The time T at which fa T + (fb - fa) T / 2 = nc (the glide from fa reaching fb at T): 2 nc / (fa + fb)."""
    return 2 * nc / (fa + fb)


# ---- a windscreen wiper's four-bar linkage (the drift case) ----

def fourbar_rocker(theta, a, b, c, d):
    """The rocker's angle phi of a crank-rocker four-bar (crank a, coupler b, rocker c, ground d, the open branch) at
    the crank angle theta, by Freudenstein's equation K1 cos phi - K2 cos theta + K3 = cos(theta - phi), K1 = d / a,
    K2 = d / c, K3 = (a^2 - b^2 + c^2 + d^2) / (2 a c) (Freudenstein, Trans. ASME 77 (1955) 853), solved in tan(phi
    / 2): A T^2 + B T + C = 0."""
    th = np.asarray(theta, float)
    K1, K2, K3 = d / a, d / c, (a * a - b * b + c * c + d * d) / (2 * a * c)
    A = np.cos(th) - K1 - K2 * np.cos(th) + K3
    B = -2 * np.sin(th)
    C = K1 - (K2 + 1) * np.cos(th) + K3
    T = (-B - np.sqrt(B * B - 4 * A * C)) / (2 * A)
    return 2 * np.arctan(T)


def crank_runs(t, runs):
    """The crank's angle (revolutions) under runs (t0, n_rev, rate, t_acc): from rest, the speed rising as a raised
    cosine over t_acc to `rate` rev/s, running, and falling likewise so that exactly n_rev turns are made; at rest
    (parked) between runs. Returns the turns made so far."""
    t = np.asarray(t, float)
    turns = np.zeros_like(t)
    done = 0.0
    for t0, n_rev, rate, ta in runs:
        tc = n_rev / rate - ta                         # the cruise (each ramp makes rate ta / 2 turns)
        T = 2 * ta + tc
        s = np.clip(t - t0, 0, T)
        up = rate * (s / 2 - ta / (2 * np.pi) * np.sin(np.pi * s / ta))
        mid = rate * ta / 2 + rate * (s - ta)
        sd = s - ta - tc
        down = rate * ta / 2 + rate * tc + rate * (sd / 2 + ta / (2 * np.pi) * np.sin(np.pi * sd / ta))
        turns += np.where(t <= t0, 0.0, np.where(s < ta, up, np.where(s < ta + tc, mid, down)))
        done += n_rev
    return turns


def run_length(n_rev, rate, ta):
    return n_rev / rate + ta


# ---- flight-test multistep inputs (the asymmetry case) ----

def multistep(t, manoeuvres, edge):
    """Pilot inputs for system identification: manoeuvres (t0, unit, amp, sign, kind), kind '3211' (pulses of 3, 2, 1
    and 1 units of alternating sign; Koehler & Wilhelm, DFVLR report, 1977; Plaetschke & Schulz, AGARD LS-104,
    1979, from memory) or 'doublet' (1, 1); each level change a raised cosine of `edge` s beginning at its nominal
    time; trim (0 V) between."""
    t = np.asarray(t, float)
    v = np.zeros_like(t)
    for t0, unit, amp, sgn, kind in manoeuvres:
        widths = [3, 2, 1, 1] if kind == "3211" else [1, 1]
        levels = [sgn * amp * (-1) ** i for i in range(len(widths))] + [0.0]
        tc, prev = t0, 0.0
        for w, lv in zip([0] + widths, levels):
            tc += w * unit
            v += (lv - prev) * raised_cosine((t - tc) / edge)
            prev = lv
    return v


def multistep_length(unit, kind):
    return (7 if kind == "3211" else 2) * unit


# ---- Kempf's zig-zag manoeuvre of a ship by Nomoto's model (the saturation case) ----

def nomoto_piece(s, psi0, r0, d0, rate, K, T):
    """Nomoto's first-order steering model T r' + r = K delta, psi' = r (Nomoto et al., Int. Shipbuild. Prog. 4
    (1957) 354) over s seconds of a rudder delta = d0 + rate s: the closed form (heading, yaw rate)."""
    s = np.asarray(s, float)
    e = np.exp(-s / T)
    c = r0 - K * d0 + K * rate * T
    r = K * (d0 + rate * s) - K * rate * T + c * e
    psi = psi0 + K * d0 * s + K * rate * s * s / 2 - K * rate * T * s + c * T * (1 - e)
    return psi, r


def zigzag(blocks, K, T, rudder_rate, lead, tail):
    """Kempf's zig-zag test (Kempf, Schiffbau 1932; IMO MSC.137(76), 2002): the rudder put over to +delta_c at its
    rate, held until the heading passes +psi_c, then put over to -delta_c until it passes -psi_c, and so on; blocks
    (delta_c, psi_c, n_reversals) one after the other; then the rudder to midships and `tail` s. Returns pieces (t0,
    psi0, r0, d0, rate, duration) covering lead ... end, and the end."""
    pieces = []
    tc, psi, r, d = lead, 0.0, 0.0, 0.0
    pieces.append((0.0, 0.0, 0.0, 0.0, 0.0, lead))
    sgn = 1.0
    plan = [(dc, pc, nr) for dc, pc, nr in blocks]
    for dc, pc, nr in plan:
        for _ in range(nr + 1):
            target = sgn * dc
            # rudder moving toward the target, then held; a reversal once the heading passes sgn * pc
            rate = math.copysign(rudder_rate, target - d)
            t_move = abs(target - d) / rudder_rate
            hit = None
            for (dur, rt) in ((t_move, rate), (60.0, 0.0)):
                ss = np.linspace(0, dur, 2001)
                ps, _ = nomoto_piece(ss, psi, r, d, rt, K, T)
                cross = np.flatnonzero(sgn * (ps - sgn * pc) >= 0)
                if len(cross) and cross[0] > 0 and sgn * (psi - sgn * pc) < 0:
                    j = cross[0]
                    hit = brentq(lambda x: float(nomoto_piece(x, psi, r, d, rt, K, T)[0]) - sgn * pc, ss[j - 1],
                                 ss[j], xtol=1e-13)
                    pieces.append((tc, psi, r, d, rt, hit))
                    psi, r = (float(z) for z in nomoto_piece(hit, psi, r, d, rt, K, T))
                    d += rt * hit
                    tc += hit
                    break
                pieces.append((tc, psi, r, d, rt, dur))
                psi, r = (float(z) for z in nomoto_piece(dur, psi, r, d, rt, K, T))
                d += rt * dur
                tc += dur
            sgn = -sgn
    # midships and the tail
    rate = math.copysign(rudder_rate, -d) if d else 0.0
    t_move = abs(d) / rudder_rate
    pieces.append((tc, psi, r, d, rate, t_move))
    psi, r = (float(z) for z in nomoto_piece(t_move, psi, r, d, rate, K, T))
    tc += t_move
    pieces.append((tc, psi, r, 0.0, 0.0, tail))
    return pieces, tc + tail


def heading(t, pieces, K, T):
    """The heading and the rudder at the times t from :func:`zigzag`'s pieces."""
    t = np.asarray(t, float)
    psi, dl = np.zeros_like(t), np.zeros_like(t)
    for t0, p0, r0, d0, rt, dur in pieces:
        m = (t >= t0) & (t <= t0 + dur)
        psi[m] = nomoto_piece(t[m] - t0, p0, r0, d0, rt, K, T)[0]
        dl[m] = d0 + rt * (t[m] - t0)
    return psi, dl


# ---- a stepping motor's rotor (the delay case) ----

def step_response(s, wn, zeta):
    """The rotor's response to one step of its detent position, linearised about the detent (a second-order system:
    Kenjo & Sugawara, *Stepping Motors and their Microprocessor Controls*, 1994, ch. 5): 1 - exp(-zeta wn s) (cos
    wd s + zeta / sqrt(1 - zeta^2) sin wd s), 0 before the step."""
    s = np.asarray(s, float)
    wd = wn * math.sqrt(1 - zeta * zeta)
    sp = np.clip(s, 0, None)
    g = 1 - np.exp(-zeta * wn * sp) * (np.cos(wd * sp) + zeta / math.sqrt(1 - zeta * zeta) * np.sin(wd * sp))
    return np.where(s > 0, g, 0.0)


def step_times(t0, n_steps, f_lo, f_hi, n_ramp):
    """The step instants of a move of n_steps with the step rate ramping linearly (in steps) from f_lo to f_hi over
    n_ramp steps and back down over the last n_ramp (a trapezoidal pull-in profile)."""
    times, tc = [], t0
    for i in range(n_steps):
        up = min(i, n_steps - 1 - i)
        f = f_lo + (f_hi - f_lo) * min(up, n_ramp) / max(n_ramp, 1)
        times.append(tc)
        tc += 1.0 / f
    return np.array(times), tc


def rotor_angle(t, steps, wn, zeta, window=None):
    """The rotor's angle: the sum of the steps' (time, size) responses (superposition of the linear model)."""
    t = np.asarray(t, float)
    out = np.zeros_like(t)
    win = window if window is not None else 12.0 / (zeta * wn)
    for tj, dj in steps:
        i0 = np.searchsorted(t, tj, side="right")
        i1 = np.searchsorted(t, tj + win, side="right")
        out[i0:i1] += dj * step_response(t[i0:i1] - tj, wn, zeta)
        out[i1:] += dj
    return out


# ---- a relay auto-tuning history and a seal's dives (the initial-state case) ----

def relay_autotune_history(setpoint, d, n_cycles, park, overshoot, ratio, n_ring):
    """The drive's turning points during an unrecorded relay auto-tuning (Astrom & Hagglund, Automatica 20 (1984)
    645): from rest at 0 V to the set point, then the relay's output setpoint +- d, switched every half period of the
    limit cycle, n_cycles cycles; then the tuned PID moves the stage to `park`, overshooting by `overshoot` (V) and
    ringing out by the ratio `ratio` per half cycle, n_ring turning points. Only the turning points matter to a
    rate-independent core."""
    pts = [0.0, setpoint]
    for _ in range(n_cycles):
        pts += [setpoint + d, setpoint - d]
    sgn = math.copysign(1.0, park - pts[-1])
    o = overshoot
    for _ in range(n_ring):
        pts.append(park + sgn * o)
        sgn, o = -sgn, o * ratio
    pts.append(park)
    return np.array(pts)


def dives(t, start, surface, plan, rng_phases):
    """A diving seal's depth from a time-depth recorder (e.g. Kooyman, *Diverse Divers*, 1989; from memory): from
    `start`, up to the surface, then dives (t0, depth, t_desc, t_bottom, t_asc, wiggle, f_w): a raised-cosine descent,
    a bottom phase with wiggles (the depth shallower by up to `wiggle` at f_w Hz, chasing prey), a raised-cosine
    ascent back to the surface. Returns the depth."""
    t = np.asarray(t, float)
    v = np.full_like(t, surface)
    t_first = plan[0][0]
    m = t < t_first
    v[m] = start + (surface - start) * raised_cosine(t[m] / t_first)
    for (t0, D, td, tb, ta, wg, fw), ph in zip(plan, rng_phases):
        s = t - t0
        on = (s >= 0) & (s < td + tb + ta)
        ss = s[on]
        desc = surface + (D - surface) * raised_cosine(ss / td)
        sb = ss - td
        bottom = D - wg * np.sin(np.pi * np.clip(sb / tb, 0, 1)) * 0.5 * (1 - np.cos(2 * np.pi * fw * sb + ph))
        asc = D + (surface - D) * raised_cosine((ss - td - tb) / ta)
        v[on] = np.where(ss < td, desc, np.where(ss < td + tb, bottom, asc))
    return v


# ---- a flight profile (the pair) ----

def climb_time(h0, h1, ceiling, roc0):
    """The time to climb from h0 to h1 when the rate of climb falls linearly with the altitude, roc0 (1 - h /
    ceiling) (the excess power falling toward the absolute ceiling; e.g. Anderson, *Aircraft Performance and Design*,
    1999, ch. 5): (ceiling / roc0) ln((ceiling - h0) / (ceiling - h1))."""
    return ceiling / roc0 * math.log((ceiling - h0) / (ceiling - h1))


def flight_profile(t, legs):
    """Altitude: legs of (t0, kind, h0, h1, arg, duration): 'climb' exponential toward the ceiling `arg` = (ceiling,
    roc0); 'level' held at h0; 'descend' at a constant rate (linear). Returns the altitude."""
    t = np.asarray(t, float)
    v = np.zeros_like(t)
    for t0, kind, h0, h1, arg, dur in legs:
        s = t - t0
        on = (s >= 0) & (s <= dur)
        if kind == "climb":
            cl, roc0 = arg
            v[on] = cl - (cl - h0) * np.exp(-roc0 * s[on] / cl)
        elif kind == "level":
            v[on] = h0
        else:
            v[on] = h0 + (h1 - h0) * s[on] / dur
    return v


# ---- a washing machine's drum speed (the out-of-vocabulary case) ----

def drum_speed(t, moves, t_end):
    """The drum's speed programme as moves (t0, duration, to): each a cubic move 3 s^2 - 2 s^3 from the previous
    level to `to` (the motor's controlled acceleration; e.g. IEC 60456 programmes: tumbling, distribution,
    intermediate and final spins), held between."""
    t = np.asarray(t, float)
    v = np.zeros_like(t)
    prev = 0.0
    for t0, dur, to in moves:
        s = np.clip((t - t0) / dur, 0, 1)
        v += (to - prev) * s * s * (3 - 2 * s)
        prev = to
    return np.where(t <= t_end, v, prev)


__all__ = ["ueda_rhs", "ueda_x", "lock_level", "lock_flight", "rosenberg_pulse", "syllables", "syllable_length",
           "fourbar_rocker", "crank_runs", "run_length", "multistep", "multistep_length", "nomoto_piece", "zigzag",
           "heading", "step_response", "step_times", "rotor_angle", "relay_autotune_history", "dives", "climb_time",
           "flight_profile", "drum_speed"]

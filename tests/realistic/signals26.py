"""Excitation signals of the HOLDOUT26 set (``cases_holdout26.py``), each written from its source; the mechanisms are
in :mod:`.mechanisms26`.

Citations were written from memory in this session (none was re-read; volumes, pages and years may be off); the
signals are checked in tests/test_realistic_holdout26.py against independent solutions (solve_ivp, brentq, closed
forms, quadrature, scipy's own routines).
"""

import math

import numpy as np
from scipy.integrate import solve_ivp
from scipy.interpolate import PchipInterpolator
from scipy.optimize import brentq

from .mechanisms19 import raised_cosine


# ---- Lorenz's 1996 model of an atmospheric latitude circle (the clean case) ----

def lorenz96_rhs(t, x, F):
    """x_i' = (x_{i+1} - x_{i-2}) x_{i-1} - x_i + F, i cyclic (Lorenz, Proc. ECMWF Seminar on Predictability, 1996;
    Lorenz & Emanuel, J. Atmos. Sci. 55 (1998) 399): advection, damping and forcing of a quantity on a latitude circle;
    chaotic for F = 8 and 8 or more sites. The advection conserves E = sum x_i^2 / 2, so E' = -2 E + F sum x_i."""
    return (np.roll(x, -1) - np.roll(x, 2)) * np.roll(x, 1) - x + F


def lorenz96_x0(t, units, start, F, settle=20.0):
    """x_0 at the times t (s), `units` of the model's time a second, after `settle` units from `start` (LSODA, rtol
    1e-10). Returns x_0 and the state at the record's start."""
    s0 = solve_ivp(lorenz96_rhs, (0.0, settle), np.asarray(start, float), args=(F,), method="LSODA", rtol=1e-10,
                   atol=1e-10).y[:, -1]
    tau = np.asarray(t, float) * units
    sol = solve_ivp(lorenz96_rhs, (tau[0], tau[-1]), s0, t_eval=tau, args=(F,), method="LSODA", rtol=1e-10,
                    atol=1e-10)
    return sol.y[0], s0


# ---- an on-load tap changer under a day's load (the creep case) ----

def required_tap(t, knot_t, knot_r, wiggles):
    """The (continuous) tap at which a transformer's regulated voltage would sit at its set point, through a day's
    load compressed into the record: PCHIP through the knots (night, morning rise, midday, evening peak, night) plus
    the load's fluctuations, a sum of sines (amplitude, frequency, phase)."""
    t = np.asarray(t, float)
    r = PchipInterpolator(knot_t, knot_r)(np.clip(t, knot_t[0], knot_t[-1]))
    for a, f, ph in wiggles:
        r = r + a * np.sin(2 * np.pi * f * t + ph)
    return r


def tap_changer(t, r, tap0, band, t_first, t_next, n_taps):
    """An on-load tap changer's automatic voltage regulator (the definite-time control of IEC 60214 and IEEE C57.131):
    while the voltage stays out of the dead band (the required tap r more than `band` taps from the tap) its timer
    runs; at t_first it steps one tap toward the band, and while the voltage stays out, again every t_next; back in
    the band, the timer resets. Taps 0 ... n_taps. Returns the taps' steps [(time, new tap)], the sample at which each
    timer ran out."""
    t = np.asarray(t, float)
    r = np.asarray(r, float)
    tap, since, first, steps = tap0, None, True, []
    for k in range(len(t)):
        dev = r[k] - tap
        out = 1 if dev > band else (-1 if dev < -band else 0)
        if out == 0 or (out > 0 and tap == n_taps) or (out < 0 and tap == 0):
            since, first = None, True
            continue
        if since is None or since[1] != out:
            since = (t[k], out)
        if t[k] - since[0] >= (t_first if first else t_next) - 1e-12:
            tap += out
            steps.append((float(t[k]), tap))
            since, first = (t[k], out), False
    return steps


def tap_drive(t, tap0, steps, step_v, t_move):
    """The tap's voltage: tap0 steps of step_v, each change of tap a raised cosine over t_move (the diverter switch's
    transition, its resistors carrying the load between the taps)."""
    t = np.asarray(t, float)
    v = np.full_like(t, tap0 * step_v)
    prev = tap0
    for ts, tap in steps:
        v += (tap - prev) * step_v * raised_cosine((t - ts) / t_move)
        prev = tap
    return v


# ---- Euler's disk spun again and again (the rate case) ----

def euler_disk_tilt(s, t0, alpha0):
    """The disk's tilt s seconds into a spin by Moffatt's law (Nature 404 (2000) 833: the air film's viscous
    dissipation against the energy (3/2) M g a alpha), alpha0 (1 - s / t0)^(1/3): zero at the finite time t0."""
    return alpha0 * np.cbrt(np.clip(1 - np.asarray(s, float) / t0, 0.0, None))


def euler_disk_phase(s, t0, omega0):
    """The contact point's azimuth: its rate Omega = omega0 (1 - s / t0)^(-1/6) (Omega^2 alpha = 4 g / a for a thin
    disk rolling without slipping at a small tilt, so Omega grows as alpha^(-1/2): the whirr's rising pitch),
    integrated in closed form: omega0 (6 / 5) t0 (1 - (1 - s / t0)^(5/6))."""
    x = np.clip(1 - np.asarray(s, float) / t0, 0.0, None)
    return omega0 * 1.2 * t0 * (1 - x ** (5 / 6))


def euler_disk_spins(t, spins, glide):
    """The contact point's coordinate along one axis, cos(alpha) cos(phase) (the disk's centre of mass at rest: the
    contact point runs on a circle of radius a cos alpha), through spins (t_start, T, t0, alpha0, omega0, phase0),
    each ending at T < t0 when the disk falls flat; between spins (and from 0 V before the first and back after the
    last) the operator's hand carries it by a raised cosine over `glide` s."""
    t = np.asarray(t, float)
    x = np.zeros_like(t)
    lvl, t_prev = 0.0, None
    for t_s, T, t0, a0, w0, ph0 in spins:
        start = math.cos(a0) * math.cos(ph0)
        m = (t >= t_s - glide) & (t < t_s)
        x[m] = lvl + (start - lvl) * raised_cosine((t[m] - (t_s - glide)) / glide)
        m = (t >= t_s) & (t < t_s + T)
        s = t[m] - t_s
        x[m] = np.cos(euler_disk_tilt(s, t0, a0)) * np.cos(ph0 + euler_disk_phase(s, t0, w0))
        lvl = float(math.cos(euler_disk_tilt(T, t0, a0)) * math.cos(ph0 + euler_disk_phase(T, t0, w0)))
        hold = (t >= t_s + T)
        x[hold] = lvl
        t_prev = t_s + T
    m = (t >= t_prev) & (t < t_prev + glide)
    x[m] = lvl * (1 - raised_cosine((t[m] - t_prev) / glide))
    x[t >= t_prev + glide] = 0.0
    return x


# ---- a lateral harmonograph (the drift case) ----

def released_pendulum(s, A, f, gamma):
    """A damped pendulum released from rest at A: A e^(-gamma s) (cos w s + (gamma / w) sin w s), w = 2 pi f its damped
    frequency (x'' + 2 gamma x' + (w^2 + gamma^2) x = 0, x(0) = A, x'(0) = 0)."""
    s = np.asarray(s, float)
    w = 2 * np.pi * f
    return A * np.exp(-gamma * s) * (np.cos(w * s) + gamma / w * np.sin(w * s))


def harmonograph(t, drawings, pull, hold):
    """The pen's x in a lateral harmonograph (Blackburn's pendulum, 1844; Goold et al., *Harmonic Vibrations and
    Vibration Figures*, 1909): two pendulums' swings added through the pen's linkage, each drawing begun by pulling
    both aside (a raised cosine over `pull` s from where the last left off), holding `hold` s and letting go: drawings
    (t_release, [(A, f, gamma), (A, f, gamma)]) in time order, each until the next one's pull."""
    t = np.asarray(t, float)
    x = np.zeros_like(t)
    lvl = 0.0
    ends = [d[0] - pull - hold for d in drawings[1:]] + [np.inf]
    for (t_r, pend), t_end in zip(drawings, ends):
        start = sum(a for a, _, _ in pend)
        t_p = t_r - pull - hold
        m = (t >= t_p) & (t < t_r)
        x[m] = lvl + (start - lvl) * raised_cosine((t[m] - t_p) / pull)
        m = (t >= t_r) & (t < t_end)
        x[m] = sum(released_pendulum(t[m] - t_r, a, f, gm) for a, f, gm in pend)
        if np.isfinite(t_end):
            lvl = float(sum(released_pendulum(t_end - t_r, a, f, gm) for a, f, gm in pend))
    return x


# ---- a steering wheel through parking manoeuvres (the asymmetry case) ----

def steering(t, moves, start=0.0):
    """The steering wheel's angle through moves in time order: ("grab", t0, target, grab_max, grab_s, regrip_s): hand
    over hand, the turn split into equal grabs of at most grab_max, each a raised cosine over grab_s with regrip_s
    between (the driver's hands re-gripping); ("release", t0, target, tau): the wheel let slip through the hands and
    returned by the tyres' self-aligning torque, an exponential approach with the time constant tau. Returns the
    angle and the moves' end times."""
    t = np.asarray(t, float)
    x = np.full_like(t, start)
    lvl, ends = start, []
    for mv in moves:
        kind, t0, target = mv[0], mv[1], mv[2]
        m = t >= t0
        if kind == "grab":
            grab_max, grab_s, regrip_s = mv[3:]
            n = max(1, math.ceil(abs(target - lvl) / grab_max - 1e-9))
            d = (target - lvl) / n
            x[m] = lvl
            for j in range(n):
                x[m] += d * raised_cosine((t[m] - t0 - j * (grab_s + regrip_s)) / grab_s)
            ends.append(t0 + n * grab_s + (n - 1) * regrip_s)
        else:
            tau = mv[3]
            x[m] = target + (lvl - target) * np.exp(-(t[m] - t0) / tau)
            ends.append(t0 + 5 * tau)
        lvl = target
    return x, ends


# ---- a springboard diver's hurdle, press and take-off (the saturation case) ----

def damped_free(s, y0, v0, w, zeta, y_eq=0.0):
    """y and y' of y'' + 2 zeta w y' + w^2 (y - y_eq) = 0 from (y0, v0), underdamped, in closed form."""
    s = np.asarray(s, float)
    wd = w * math.sqrt(1 - zeta * zeta)
    sig = zeta * w
    a, b = y0 - y_eq, (v0 + sig * (y0 - y_eq)) / wd
    ex, co, si = np.exp(-sig * s), np.cos(wd * s), np.sin(wd * s)
    y = y_eq + ex * (a * co + b * si)
    yd = ex * ((-sig * a + wd * b) * co + (-sig * b - wd * a) * si)
    return y, yd


def dive(k, m, M, zeta, h, g=9.81):
    """One dive off a springboard (the tip: a mass m on a spring k, damping zeta of the bare board; the tip's
    deflection y, down positive), the diver of mass M standing at the end (the static sag M g / k): the hurdle's
    push-off unloads the board at once and the diver flies up at sqrt(2 g h) and falls back while the board rings
    freely; landing (a plastic impact: momentum shared), diver and board move together ((m + M) y'' + c y' + k y = M
    g) through the press until the board pushes no more (N = M (g - y'') = 0, i.e. k y + c y' = -m g: take-off near the
    board's unloaded level; e.g. Miller & Munro, J. Biomech. 17 (1984) 847 on springboard take-offs); then the board
    rings down alone. Returns the events (t_land, t_off) from the push-off and a function y(s), s from the push-off."""
    w_b = math.sqrt(k / m)
    c = 2 * zeta * math.sqrt(k * m)
    w_c = math.sqrt(k / (m + M))
    z_c = c / (2 * math.sqrt(k * (m + M)))
    y_s = M * g / k
    v_h = math.sqrt(2 * g * h)

    def feet_minus_board(s):
        return y_s - v_h * s + 0.5 * g * s * s - float(damped_free(s, y_s, 0.0, w_b, zeta)[0])
    s_top = v_h / g
    t_land = brentq(feet_minus_board, s_top, 3 * s_top + 1.0, xtol=1e-14)
    y_l, yd_l = (float(q) for q in damped_free(t_land, y_s, 0.0, w_b, zeta))
    v_land = (M * (-v_h + g * t_land) + m * yd_l) / (m + M)
    y_eq = M * g / k

    def push(s):
        y, yd = damped_free(s, y_l, v_land, w_c, z_c, y_eq)
        return float(k * y + c * yd + m * g)
    # the bottom of the press comes first (push > 0 there), the take-off where push falls through 0
    grid = np.linspace(0.0, math.pi / w_c * 1.5, 3001)
    vals = np.array([push(s) for s in grid])
    i0 = int(np.argmax(vals > 0))
    i = i0 + int(np.argmax(vals[i0:] < 0))
    t_off = t_land + brentq(push, grid[i - 1], grid[i], xtol=1e-14)
    y_o, yd_o = (float(q) for q in damped_free(t_off - t_land, y_l, v_land, w_c, z_c, y_eq))

    def y_of(s):
        s = np.asarray(s, float)
        out = np.where(s < t_land, damped_free(s, y_s, 0.0, w_b, zeta)[0], 0.0)
        m2 = (s >= t_land) & (s < t_off)
        out = np.where(m2, damped_free(s - t_land, y_l, v_land, w_c, z_c, y_eq)[0], out)
        m3 = s >= t_off
        return np.where(m3, damped_free(s - t_off, y_o, yd_o, w_b, zeta)[0], out)
    return (t_land, t_off, v_land, (y_l, yd_l), (y_o, yd_o)), y_of


def timed_hurdle(k, m, M, zeta, phase, g=9.81):
    """The hurdle's height h at which a diver, pushing off from the sag, lands when the ringing board is at the phase
    3 pi / 2 + 2 pi + phase of its free swing (past its unloaded level, moving down: divers time the hurdle to the
    board): from the feet's parabola meeting the board there."""
    w_b = math.sqrt(k / m)
    wd = w_b * math.sqrt(1 - zeta * zeta)
    y_s = M * g / k
    s_l = (3.5 * math.pi + phase) / wd
    y_b = float(damped_free(s_l, y_s, 0.0, w_b, zeta)[0])
    v_h = (y_s + 0.5 * g * s_l * s_l - y_b) / s_l
    return v_h * v_h / (2 * g)


def springboard(t, dives, k, m, zeta, walk):
    """The tip's deflection through dives (t_walk, M, stand_s, h): each diver walks out (the sag growing to M g / k by a
    raised cosine over `walk` s, the board's own ringing then settled), stands stand_s s, and dives (:func:`dive`);
    the board rings down until the next diver steps on. Returns the deflection and each dive's events."""
    t = np.asarray(t, float)
    y = np.zeros_like(t)
    events = []
    starts = [d[0] for d in dives[1:]] + [np.inf]
    lvl_fn = None
    for (t_w, M, stand, hh), t_next in zip(dives, starts):
        y_s = M * 9.81 / k
        sel = (t >= t_w) & (t < t_w + walk)
        base = 0.0 if lvl_fn is None else lvl_fn(t[sel])
        y[sel] = base + (y_s - base) * raised_cosine((t[sel] - t_w) / walk)
        t_push = t_w + walk + stand
        sel = (t >= t_w + walk) & (t < t_push)
        y[sel] = y_s
        ev, y_of = dive(k, m, M, zeta, hh)
        sel = (t >= t_push) & (t < t_next)
        y[sel] = y_of(t[sel] - t_push)
        events.append((t_push,) + ev)
        lvl_fn = (lambda tt, f=y_of, t0=t_push: f(tt - t0))
    return y, events


# ---- a neon-lamp relaxation oscillator on a variac (the delay case) ----

def neon_rhs(t, V, lit, supply, tau_c, tau_d, v_m):
    """The capacitor's voltage in Pearson & Anson's oscillator (Proc. Phys. Soc. London 34 (1921) 204): charged from
    the supply E(t) through R (tau_c = R C); while the lamp burns it also discharges through the lamp and its series
    resistor towards the burning voltage v_m (tau_d = r C)."""
    E = supply(t)
    return [(E - V[0]) / tau_c - (((V[0] - v_m) / tau_d) if lit else 0.0)]


def _relax(v0, lam, a, b, s):
    """V(s) of V' = -lam V + a + b s from V(0) = v0, in closed form."""
    vp0 = a / lam - b / (lam * lam)
    return vp0 + b * s / lam + (v0 - vp0) * math.exp(-lam * s)


def neon_oscillator(t, supply_t, supply_E, v0, v_strike, v_ext, tau_c, tau_d, v_m):
    """The capacitor's voltage at the times t under a supply linear between the knots (supply_t, supply_E) (a variac
    turned by hand): the lamp strikes when the voltage reaches v_strike and goes out when it has fallen to v_ext (v_m <
    v_ext < v_strike). Between the times both phases are linear first-order equations with a forcing linear in time,
    stepped in closed form (:func:`neon_rhs`); a switching between two times found by brentq (xtol 1e-14 s) on the
    closed form. Returns it and the switchings [(time, lit after)]."""
    t = np.asarray(t, float).tolist()
    kt, kE = np.asarray(supply_t, float), np.asarray(supply_E, float)
    out = np.empty(len(t))
    V, lit, switches = float(v0), False, []
    out[0] = V

    def coeffs(ta, tb, lit):
        Ea, Eb = float(np.interp(ta, kt, kE)), float(np.interp(tb, kt, kE))
        sl = (Eb - Ea) / (tb - ta)
        if lit:
            return 1 / tau_c + 1 / tau_d, Ea / tau_c + v_m / tau_d, sl / tau_c
        return 1 / tau_c, Ea / tau_c, sl / tau_c
    bounds = set(kt.tolist())
    for k in range(len(t) - 1):
        ta, tb = t[k], t[k + 1]
        cuts = [ta] + sorted(x for x in bounds if ta < x < tb) + [tb]     # the supply's knots inside the step
        for a0, b0 in zip(cuts[:-1], cuts[1:]):
            while a0 < b0:
                lam, a, b = coeffs(a0, b0, lit)
                level = v_ext if lit else v_strike
                Vb = _relax(V, lam, a, b, b0 - a0)
                if (Vb - level) * (-1 if lit else 1) < 0:
                    V, a0 = Vb, b0
                    continue
                s = brentq(lambda x: _relax(V, lam, a, b, x) - level, 0.0, b0 - a0, xtol=1e-14)
                V, a0, lit = level, a0 + s, not lit
                switches.append((a0, lit))
        out[k + 1] = V
    return out, switches


def neon_period(E, v_strike, v_ext, tau_c, tau_d, v_m):
    """The closed-form period at a steady supply E: charging from v_ext to v_strike, tau_c ln((E - v_ext) / (E -
    v_strike)), and discharging towards v_inf = (E / tau_c + v_m / tau_d) / (1 / tau_c + 1 / tau_d) from v_strike to
    v_ext, tau_l ln((v_strike - v_inf) / (v_ext - v_inf)), 1 / tau_l = 1 / tau_c + 1 / tau_d."""
    inv = 1 / tau_c + 1 / tau_d
    v_inf = (E / tau_c + v_m / tau_d) / inv
    return tau_c * math.log((E - v_ext) / (E - v_strike)) + math.log((v_strike - v_inf) / (v_ext - v_inf)) / inv


# ---- a bungee-jumping session (the initial-state case) ----

def bungee_jump(s, L, w, zeta, g=9.81):
    """A jumper's depth below the platform (down positive) s seconds after stepping off at rest: free fall to the
    cord's slack length L, then the cord (a linear spring in tension only, k / m = w^2, damping zeta: y'' = g - w^2 (y -
    L) - 2 zeta w y'), slack again (free flight) whenever the jumper rebounds above L; the phases in closed form, the
    crossings of L by brentq. Returns the depth and the crossings."""
    s = np.asarray(s, float)
    y = np.empty_like(s)
    y_eq = L + g / (w * w)
    t1 = math.sqrt(2 * L / g)
    free = s < t1
    y[free] = 0.5 * g * s[free] ** 2
    t_c, v_c, crossings = t1, g * t1, [t1]
    horizon = float(s[-1]) if len(s) else 0.0
    while t_c < horizon:
        # taut: from (L, v_c) at t_c until the depth returns to L moving up (if it does)
        wd = w * math.sqrt(1 - zeta * zeta)

        def depth(u):
            return float(damped_free(u, L, v_c, w, zeta, y_eq)[0]) - L
        period = 2 * math.pi / wd
        grid = np.linspace(1e-9, period, 401)
        vals = np.array([depth(u) for u in grid])
        neg = np.flatnonzero(vals < 0)
        if len(neg) == 0:                                   # never slack again: a damped hang
            m = s >= t_c
            y[m] = damped_free(s[m] - t_c, L, v_c, w, zeta, y_eq)[0]
            break
        i = int(neg[0])
        u_s = brentq(depth, grid[i - 1], grid[i], xtol=1e-14)
        v_s = float(damped_free(u_s, L, v_c, w, zeta, y_eq)[1])      # < 0: moving up
        m = (s >= t_c) & (s < t_c + u_s)
        y[m] = damped_free(s[m] - t_c, L, v_c, w, zeta, y_eq)[0]
        t_s = t_c + u_s
        crossings.append(t_s)
        T_fl = -2 * v_s / g                                 # slack: up and back down to L
        m = (s >= t_s) & (s < t_s + T_fl)
        u = s[m] - t_s
        y[m] = L + v_s * u + 0.5 * g * u * u
        t_c, v_c = t_s + T_fl, -v_s
        crossings.append(t_c)
    return y, crossings


def bungee_session(t, start, scale, jumps, haul, speed=1.0):
    """The drive through a session: the platform at `start` volts, depths `scale` volts a metre; jumps (t_jump, L, w,
    zeta, hang) in time order (w and the jump's own time real, the record's played `speed` times faster), each
    stepping off at t_jump, hanging and bouncing for `hang` s of the record and hauled back up to the platform by a
    raised cosine over `haul` s."""
    t = np.asarray(t, float)
    v = np.full_like(t, start)
    for t_j, L, w, zeta, hang in jumps:
        m = (t >= t_j) & (t < t_j + hang)
        y, _ = bungee_jump(speed * (t[m] - t_j), L, w, zeta)
        v[m] = start + scale * y
        y_end = float(bungee_jump(np.array([0.0, speed * hang]), L, w, zeta)[0][-1])
        m = (t >= t_j + hang) & (t < t_j + hang + haul)
        v[m] = start + scale * y_end * (1 - raised_cosine((t[m] - t_j - hang) / haul))
    return v


# ---- a weightlifting session (the pair) ----

def keyframe_path(t, keys):
    """A path through keys (t_i, x_i) in time order: a raised cosine from each key to the next (a hold where two
    neighbours are equal), held at the ends."""
    t = np.asarray(t, float)
    kt = np.array([k[0] for k in keys], float)
    kx = np.array([k[1] for k in keys], float)
    x = np.full_like(t, kx[0])
    for (t0, x0), (t1, x1) in zip(keys[:-1], keys[1:]):
        m = (t >= t0) & (t < t1)
        x[m] = x0 + (x1 - x0) * raised_cosine((t[m] - t0) / (t1 - t0))
    x[t >= kt[-1]] = kx[-1]
    return x


#: the bar's height (fractions of a 1.75 m lifter's standing overhead height, about 2.1 m) at the phases of the lifts,
#: as remembered from films of the snatch and the clean and jerk (e.g. Garhammer, J. Appl. Biomech. 1985)
KNEE, HIP, SNATCH_PEAK, SNATCH_SQUAT, CLEAN_PEAK, FRONT_SQUAT = 0.24, 0.45, 0.72, 0.62, 0.56, 0.36
RACK, DIP, DRIVE, SPLIT = 0.69, 0.62, 0.75, 0.88


def lift_keys(kind, t0, rng_durations):
    """The keys of one lift from the floor (0) to overhead (1) and back: "snatch" (first pull to the knee, second pull
    past the hip to the bar's peak, the lifter dropping under it to catch it in a squat, the recovery, the hold for
    the referees' signal, the bar lowered) or "clean_jerk" (pulls to the peak, the catch in a front squat, the stand
    to the rack, a pause, the dip and drive, the split, the recovery, the hold, lowered); the durations (s) a dict of
    the phases' lengths."""
    d = rng_durations
    keys, tc = [(t0, 0.0)], t0

    def add(dt_, x):
        nonlocal tc
        tc += dt_
        keys.append((tc, x))
    add(d["first"], KNEE)
    add(d["second"], HIP)
    if kind == "snatch":
        add(d["peak"], SNATCH_PEAK)
        add(d["catch"], SNATCH_SQUAT)
        add(d["recover"], 1.0)
    else:
        add(d["peak"], CLEAN_PEAK)
        add(d["catch"], FRONT_SQUAT)
        add(d["stand"], RACK)
        add(d["pause"], RACK)
        add(d["dip"], DIP)
        add(d["drive"], DRIVE)
        add(d["split"], SPLIT)
        add(d["recover"], 1.0)
    add(d["hold"], 1.0)
    add(d["lower"], 0.0)
    return keys


# ---- a yelp siren (the out-of-vocabulary case) ----

def yelp_phase(t, f_h, t_y, n_y, T_m, depth):
    """The extra phase (in cycles) of a siren's tone at f_h whose pitch, from t_y, is swept n_y times up by the factor
    (1 + depth) and back (a triangle of period T_m: the "yelp" of electronic sirens) and steady otherwise: the
    integral of f_h depth tri(s / T_m), in closed form (the triangle's integral is u^2 up to its peak and 1/2 - (1 -
    u)^2 after it); f_h depth T_m n_y / 2 cycles after the last yelp."""
    t = np.asarray(t, float)
    s = np.clip(t - t_y, 0.0, n_y * T_m)
    j = np.floor(s / T_m)
    u = s / T_m - j                                   # within a triangle, 0 ... 1
    tri_int = np.where(u < 0.5, u * u, 0.5 - (1 - u) ** 2)      # int_0^u (1 - |2x - 1|) dx = u^2, then 1/2 - (1 - u)^2
    return f_h * depth * T_m * (0.5 * j + tri_int)


def yelp_siren(k, N, t_y, n_y, T_m, depth, dt, env):
    """The siren's drive at the samples k (dt apart, the steady tone f_h = 1 / (N dt): N samples a period) under the
    amplitude envelope env: sin(2 pi (k / N mod 1 + the extra phase mod 1)), the extra phase from :func:`yelp_phase`
    (each part reduced mod 1 apart, so that a whole number of extra cycles leaves the samples exactly as they were)."""
    k = np.asarray(k)
    f_h = 1.0 / (N * dt)
    exc = yelp_phase(k * dt, f_h, t_y, n_y, T_m, depth)
    return env * np.sin(2 * np.pi * (np.mod(k, N) / N + np.mod(exc, 1.0)))


__all__ = ["lorenz96_rhs", "lorenz96_x0", "required_tap", "tap_changer", "tap_drive", "euler_disk_tilt",
           "euler_disk_phase", "euler_disk_spins", "released_pendulum", "harmonograph", "steering", "damped_free",
           "dive", "timed_hurdle", "springboard", "neon_rhs", "neon_oscillator", "neon_period", "bungee_jump",
           "bungee_session", "keyframe_path", "KNEE", "HIP", "SNATCH_PEAK", "SNATCH_SQUAT", "CLEAN_PEAK",
           "FRONT_SQUAT", "RACK", "DIP", "DRIVE", "SPLIT", "lift_keys", "yelp_phase", "yelp_siren"]

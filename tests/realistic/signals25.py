"""Excitation signals of the HOLDOUT25 set (``cases_holdout25.py``), each written from its source; the mechanisms are
in :mod:`.mechanisms25`.

Citations were written from memory in this session (none was re-read; volumes, pages and years may be off); the
signals are checked in tests/test_realistic_holdout25.py against independent solutions (solve_ivp, brentq, closed
forms, quadrature, scipy's own routines).
"""

import math

import numpy as np
from scipy.integrate import solve_ivp

from .mechanisms19 import raised_cosine


# ---- the Henon-Heiles galactic potential (the clean case) ----

def henon_heiles_rhs(t, s):
    """A star in the Henon-Heiles potential V = (x^2 + y^2) / 2 + x^2 y - y^3 / 3 (Henon & Heiles, Astron. J. 69 (1964)
    73: an axisymmetric galaxy's meridian plane; chaotic orbits for energies above about 1/8, escape beyond 1/6)."""
    x, y, px, py = s
    return [px, py, -x - 2 * x * y, -y - x * x + y * y]


def henon_heiles_energy(s):
    """The orbit's energy (px^2 + py^2) / 2 + V (conserved)."""
    x, y, px, py = s
    return 0.5 * (px * px + py * py) + 0.5 * (x * x + y * y) + x * x * y - y ** 3 / 3


def henon_heiles_start(E, y0, angle):
    """A start at x = 0, y = y0 with the momentum of energy E at the given angle."""
    V = 0.5 * y0 * y0 - y0 ** 3 / 3
    p = math.sqrt(2 * (E - V))
    return np.array([0.0, y0, p * math.cos(angle), p * math.sin(angle)])


def henon_heiles_x(t, units, start):
    """x of the orbit at the times t (s), `units` of its time a second (DOP853, rtol 1e-11)."""
    tau = np.asarray(t, float) * units
    sol = solve_ivp(henon_heiles_rhs, (tau[0], tau[-1]), np.asarray(start, float), t_eval=tau, method="DOP853",
                    rtol=1e-11, atol=1e-12)
    return sol.y[0], sol.y[:, -1]


# ---- a weighbridge's axle loads (the creep case) ----

def weighbridge(t, trucks, ramp):
    """The load on a weighbridge's plate: trucks (t_on, t_off, gaps, loads) whose axles roll on at t_on + gaps[j] and
    off at t_off + gaps[j], each load growing and falling by a raised cosine over `ramp` s as its tyres cross the
    plate's edge (the truck stopping with all its axles on to be weighed: static weighing, e.g. OIML R 76)."""
    t = np.asarray(t, float)
    x = np.zeros_like(t)
    for t_on, t_off, gaps, loads in trucks:
        for g, L in zip(gaps, loads):
            x += L * (raised_cosine((t - t_on - g) / ramp) - raised_cosine((t - t_off - g) / ramp))
    return x


# ---- a field cricket's calling song (the rate case) ----

def dolbear_rate(temp_c):
    """Chirps a minute of the snowy tree cricket at temp_c degrees Celsius by Dolbear's law (Am. Nat. 31 (1897) 970):
    N = 4 (T_F - 40), T_F = 9 T / 5 + 32."""
    return 4.0 * (9.0 * np.asarray(temp_c, float) / 5.0 + 32.0 - 40.0)


def cricket_song(t, chirps, carrier, n_syl, syl, gap):
    """Chirps (t0, amp) of n_syl syllables each (a syllable: a tone at `carrier` under a Hann window of `syl` s, `gap`
    s between syllables: the file-and-scraper's pulses), silent between chirps."""
    t = np.asarray(t, float)
    x = np.zeros_like(t)
    for t0, amp in chirps:
        for j in range(n_syl):
            s0 = t0 + j * (syl + gap)
            m = (t >= s0) & (t <= s0 + syl)
            s = t[m] - s0
            x[m] += amp * np.sin(np.pi * s / syl) ** 2 * np.sin(2 * np.pi * carrier * s)
    return x


def chirp_times(t_start, t_end, temp, slow):
    """Chirp starts from t_start to t_end, each interval 60 / dolbear_rate(temp(t)) s played `slow` times slower,
    temp a function of time (a cooling evening)."""
    out, tc = [], t_start
    while tc < t_end:
        out.append(tc)
        tc += slow * 60.0 / float(dolbear_rate(temp(tc)))
    return out


# ---- an indexing table's slews and a typewriter (the drift case) ----

def trapezoid_move(s, dist, vmax, amax):
    """The position s seconds into a move of `dist` with a trapezoidal speed (acceleration amax up to vmax, cruise,
    deceleration; a triangle when vmax is not reached). Returns the position and the move's duration."""
    s = np.asarray(s, float)
    d = abs(dist)
    ta = vmax / amax
    if amax * ta * ta > d:                              # a triangle
        ta = math.sqrt(d / amax)
        vmax = amax * ta
    tc = (d - amax * ta * ta) / vmax
    T = 2 * ta + tc
    sc = np.clip(s, 0, T)
    p = np.where(sc < ta, 0.5 * amax * sc * sc,
                 np.where(sc < ta + tc, 0.5 * amax * ta * ta + vmax * (sc - ta),
                          d - 0.5 * amax * (T - sc) ** 2))
    return math.copysign(1.0, dist) * p, T


def indexing_table(t, moves, vmax, amax, az0):
    """The azimuth (rad) of a rotary indexing table: moves (t0, dist) by :func:`trapezoid_move`, held between."""
    t = np.asarray(t, float)
    az = np.full_like(t, az0)
    for t0, dist in moves:
        p, _ = trapezoid_move(t - t0, dist, vmax, amax)
        az += np.where(t >= t0, p, 0.0)
    return az


def typewriter(t, lines, pitch, ramp, ret):
    """A typewriter carriage's position: lines (t_keys, t_return) whose every key (and space) escapes the carriage by
    one pitch over `ramp` s (a raised cosine: the escapement's release and the mainspring's pull), and the carriage
    return back to the margin at 0 over `ret` s."""
    t = np.asarray(t, float)
    x = np.zeros_like(t)
    for keys, t_ret in lines:
        for tk in keys:
            x += pitch * raised_cosine((t - tk) / ramp)
        x -= pitch * len(keys) * raised_cosine((t - t_ret) / ret)
    return x


# ---- a trombone's slide (the asymmetry case) ----

def slide_extension(position, tube):
    """The slide's extension (m) at a position 1 ... 7 (each a semitone lower): the tube's length grows by the factor
    2^((p - 1) / 12) (equal temperament: the pipe's resonances scale inversely with its length), the slide doubled
    back, so it moves by half the growth: tube (2^((p - 1) / 12) - 1) / 2."""
    return tube * (2.0 ** ((np.asarray(position, float) - 1) / 12) - 1) / 2


def trombone(t, notes, tube, shift, x_start):
    """The slide from the extension x_start through notes (t0, position): each shift a raised cosine over `shift` s
    from t0, held between."""
    t = np.asarray(t, float)
    x = np.full_like(t, x_start)
    lvl = x_start
    for t0, pos in notes:
        to = float(slide_extension(pos, tube))
        m = t >= t0
        x[m] = lvl + (to - lvl) * raised_cosine((t[m] - t0) / shift)
        lvl = to
    return x


# ---- the Brusselator through its Hopf bifurcation (the saturation case) ----

def brusselator_rhs(tau, s, a, B):
    """x' = a - (B + 1) x + x^2 y, y' = B x - x^2 y (Prigogine & Lefever, J. Chem. Phys. 48 (1968) 1695): a chemical
    oscillator whose steady state (a, B / a) loses stability at B = 1 + a^2 (a Hopf bifurcation); B(tau) a function of
    the time (the feed of the reactant changed slowly)."""
    x, y = s
    b = B(tau)
    return [a - (b + 1) * x + x * x * y, b * x - x * x * y]


def brusselator_x(t, units, a, B, start):
    """x at the times t (s), `units` of its time a second (DOP853, rtol 1e-10)."""
    tau = np.asarray(t, float) * units
    sol = solve_ivp(brusselator_rhs, (tau[0], tau[-1]), np.asarray(start, float), t_eval=tau, args=(a, B),
                    method="DOP853", rtol=1e-10, atol=1e-12)
    return sol.y[0]


def feed_schedule(knots):
    """B(tau) piecewise linear through the knots (tau_i, B_i), held beyond them."""
    kt = np.array([k[0] for k in knots], float)
    kb = np.array([k[1] for k in knots], float)
    return lambda tau: float(np.interp(tau, kt, kb))


# ---- metronomes on a common board: Kuramoto's synchronisation (the delay case) ----

def kuramoto_rhs(t, th, omega, K):
    """theta_i' = omega_i + (K(t) / n) sum_j sin(theta_j - theta_i) (Kuramoto 1975; metronomes on a board free to roll
    synchronise so: Pantaleone, Am. J. Phys. 70 (2002) 992), K(t) the board's coupling (0 while it is held)."""
    z = np.mean(np.exp(1j * th))
    return omega + K(t) * (np.abs(z) * np.sin(np.angle(z) - th))


def metronomes(t, omega, K, th0):
    """The board's swing: the mean of the metronomes' sin(theta_i) at the times t (DOP853, rtol 1e-10; steps below a
    tenth of the fastest period). Returns it and the phases."""
    t = np.asarray(t, float)
    sol = solve_ivp(kuramoto_rhs, (t[0], t[-1]), np.asarray(th0, float), t_eval=t, args=(omega, K), method="DOP853",
                    rtol=1e-10, atol=1e-10, max_step=0.1 * 2 * np.pi / float(np.max(omega)))
    return np.mean(np.sin(sol.y), axis=0), sol.y


def step_coupling(events):
    """K(t) switched at the events (t_i, K_i) by raised cosines of 0.3 s (the board released and caught again)."""
    def K(t):
        k = 0.0
        for t0, dk in events:
            k += dk * float(raised_cosine((t - t0) / 0.3))
        return k
    return K


# ---- a spirometry session (the initial-state case) ----

def spirometry(t, frc, events):
    """Lung volume through a session: events in time order, each (kind, t0, T, to), from the volume the last left at
    t0: "breath" a tidal breath from frc to `to` and back (a raised cosine up over 0.45 T, down over 0.55 T);
    "inspire" a slow inspiration to `to` (TLC) over T, held; "blast" a forced expiration to `to` (RV) with the time
    constant T (the single-compartment lung: V = RV + (TLC - RV) exp(-t / T), so FEV1 / FVC = 1 - exp(-1 s / T); e.g.
    Miller et al., Eur. Respir. J. 26 (2005) 319 for the manoeuvre); "return" a raised cosine back to `to` over T."""
    t = np.asarray(t, float)
    v = np.full_like(t, frc)
    lvl = frc
    starts = [e[1] for e in events[1:]] + [np.inf]
    for (kind, t0, T, to), t1 in zip(events, starts):
        m = t >= t0
        s = t[m] - t0
        if kind == "breath":
            v[m] = lvl + (to - lvl) * (raised_cosine(s / (0.45 * T)) - raised_cosine((s - 0.45 * T) / (0.55 * T)))
        elif kind == "blast":
            v[m] = to + (lvl - to) * np.exp(-s / T)
            if np.isfinite(t1):
                lvl = to + (lvl - to) * math.exp(-(t1 - t0) / T)
        else:
            v[m] = lvl + (to - lvl) * raised_cosine(s / T)
            lvl = to
    return v


# ---- the left ventricle's volume through a stress test (the pair) ----

def wiggers_beat(s, T, edv, esv):
    """One beat of the left ventricle's volume (Wiggers, *Circulatory Dynamics*, 1952): isovolumic contraction (0.06 T
    at edv), ejection to esv (0.3 T, a raised cosine), isovolumic relaxation (0.08 T at esv), rapid filling (to 80 % of
    the stroke in 0.22 T), diastasis (to 85 % in 0.2 T) and the atrial kick (to edv in the last 0.14 T). 0 <= s <= T."""
    s = np.asarray(s, float) / T
    sv = edv - esv
    v = edv - sv * raised_cosine((s - 0.06) / 0.3)
    v += sv * (0.8 * raised_cosine((s - 0.44) / 0.22) + 0.05 * raised_cosine((s - 0.66) / 0.2)
               + 0.15 * raised_cosine((s - 0.86) / 0.14))
    return v


def stress_test(t, beats):
    """Beats (t0, T, edv, esv) back to back (edv the volume each starts and ends at)."""
    t = np.asarray(t, float)
    v = np.full_like(t, beats[0][2])
    for t0, T, edv, esv in beats:
        m = (t >= t0) & (t < t0 + T)
        v[m] = wiggers_beat(t[m] - t0, T, edv, esv)
    last = beats[-1]
    v[t >= last[0] + last[1]] = last[2]
    return v


# ---- frequency sweeps with holds (the out-of-vocabulary case) ----

def sweep_frequency(t, segments, f_start):
    """An instantaneous frequency through segments (t0, T, f_to): each a raised-cosine glide from the last frequency to
    f_to over T s from t0, held after. Returns it and its phase 2 pi int f, in closed form (the glide's integral is
    the average of its ends times T: a raised cosine's mean is 1/2), from 0 at t = 0."""
    t = np.asarray(t, float)
    f = np.full_like(t, f_start)
    ph = 2 * np.pi * f_start * t
    lvl = f_start
    for t0, T, to in segments:
        s = np.clip(t - t0, 0, None)
        m = t >= t0
        f[m] = lvl + (to - lvl) * raised_cosine(s[m] / T)
        # int_0^s rc(u / T) du = s / 2 - T sin(pi s / T) / (2 pi) within the glide, s - T / 2 after it
        sc = np.minimum(s, T)
        integ = np.where(s < T, sc / 2 - T * np.sin(np.pi * sc / T) / (2 * np.pi), s - T / 2)
        ph += 2 * np.pi * (to - lvl) * integ
        lvl = to
    return f, ph


__all__ = ["henon_heiles_rhs", "henon_heiles_energy", "henon_heiles_start", "henon_heiles_x", "weighbridge",
           "dolbear_rate", "cricket_song", "chirp_times", "trapezoid_move", "indexing_table", "typewriter",
           "slide_extension", "trombone", "brusselator_rhs", "brusselator_x", "feed_schedule", "kuramoto_rhs",
           "metronomes", "step_coupling", "spirometry", "wiggers_beat", "stress_test", "sweep_frequency"]

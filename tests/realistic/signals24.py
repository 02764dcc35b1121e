"""Excitation signals of the HOLDOUT24 set (``cases_holdout24.py``), each written from its source; the mechanisms are
in :mod:`.mechanisms24`.

Citations were written from memory in this session (none was re-read; volumes, pages and years may be off); the
signals are checked in tests/test_realistic_holdout24.py against independent solutions (solve_ivp, brentq, closed
forms, quadrature, scipy's own routines).
"""

import math

import numpy as np
from scipy.integrate import solve_ivp
from scipy.interpolate import CubicSpline

from .mechanisms19 import raised_cosine


# ---- a synthetic electrocardiogram (the clean case) ----

#: McSharry's waves P, Q, R, S, T as remembered: (angle theta_i, amplitude a_i, width b_i) (rad, mV, rad)
ECG_WAVES = [(-math.pi / 3, 1.2, 0.25), (-math.pi / 12, -5.0, 0.1), (0.0, 30.0, 0.1), (math.pi / 12, -7.5, 0.1),
             (math.pi / 2, 0.75, 0.4)]


def ecg_phase(t, hr, rsa, f_resp):
    """The cardiac phase (rad) for a heart rate hr (1 + rsa sin(2 pi f_resp t)) beats a second (respiratory sinus
    arrhythmia: the heart quickening on inspiration), in closed form."""
    t = np.asarray(t, float)
    return 2 * np.pi * hr * (t + rsa * (1 - np.cos(2 * np.pi * f_resp * t)) / (2 * np.pi * f_resp))


def ecg_rhs(t, z, hr, rsa, f_resp, base, waves):
    """z' = -w sum_i a_i dth_i exp(-dth_i^2 / (2 b_i^2)) - (z - z0(t)): McSharry, Clifford, Tarassenko & Smith's
    dynamical model of the ECG (IEEE Trans. Biomed. Eng. 50 (2003) 289) on its limit cycle, dth_i the phase's distance
    to wave i wrapped to (-pi, pi], w the phase's rate (here multiplying the sum, so each wave keeps its angular width
    when the rate changes), z0 = base sin(2 pi f_resp t) the respiratory baseline wander."""
    w = 2 * np.pi * hr * (1 + rsa * math.sin(2 * math.pi * f_resp * t))
    th = float(ecg_phase(t, hr, rsa, f_resp))
    s = 0.0
    for thi, a, b in waves:
        d = (th - thi + math.pi) % (2 * math.pi) - math.pi
        s += a * d * math.exp(-d * d / (2 * b * b))
    return [-w * s - (z[0] - base * math.sin(2 * math.pi * f_resp * t))]


def ecg(t, hr, rsa, f_resp, base, waves=ECG_WAVES, settle=5.0):
    """The model's z at the times t (DOP853, rtol 1e-10, steps below 2 ms so no wave is stepped over), from 0 at
    t[0] - settle (the start's transient, e^-settle, gone)."""
    t = np.asarray(t, float)
    sol = solve_ivp(ecg_rhs, (t[0] - settle, t[-1]), [0.0], t_eval=t, args=(hr, rsa, f_resp, base, waves),
                    method="DOP853", rtol=1e-10, atol=1e-12, max_step=2e-3)
    return sol.y[0]


# ---- a steam steriliser's cycle (the creep case) ----

def vessel_pressure(t, steps, p_start):
    """A vessel's pressure through valves that open in turn onto sources (t0, target, tau): each a first-order approach
    p' = (target - p) / tau from wherever the last left it (a fixed restriction, the flow linear in the pressure
    difference: the vessel as a capacitance behind a resistance), in closed form. Returns the pressure and the levels
    at the steps' starts."""
    t = np.asarray(t, float)
    p = np.full_like(t, p_start)
    lvl, levels = p_start, []
    bounds = [s[0] for s in steps[1:]] + [np.inf]
    for (t0, target, tau), t1 in zip(steps, bounds):
        levels.append(lvl)
        m = t >= t0
        p[m] = target + (lvl - target) * np.exp(-(t[m] - t0) / tau)
        if np.isfinite(t1):
            lvl = target + (lvl - target) * math.exp(-(t1 - t0) / tau)
    return p, levels


# ---- a woodpecker's drumming (the rate case) ----

def drum(s, n, fa, fb, amp, decay):
    """One drum of n beats, the beat rate rising linearly from fa to fb over its T = 2 n / (fa + fb) s (a great spotted
    woodpecker's drum accelerates), each beat the head's swing toward the trunk and back, amp exp(-decay s) (1 - cos
    phi) / 2, phi = 2 pi (fa s + (fb - fa) s^2 / (2 T)): phi(T) = 2 pi n, so the drum starts and ends at rest. 0 outside
    0 <= s <= T."""
    s = np.asarray(s, float)
    T = 2 * n / (fa + fb)
    inside = (s >= 0) & (s <= T)
    sc = np.clip(s, 0, T)
    phi = 2 * np.pi * (fa * sc + (fb - fa) * sc * sc / (2 * T))
    return np.where(inside, amp * np.exp(-decay * sc) * (1 - np.cos(phi)) / 2, 0.0)


def woodpecker(t, postures, drums):
    """The head's position: raised-cosine posture moves (t0, T, to) from 0 (the bird shifting on the trunk) with drums
    (t0, n, fa, fb, amp, decay) on top (amp signed: toward the trunk on either side)."""
    t = np.asarray(t, float)
    x = np.zeros_like(t)
    lvl = 0.0
    for t0, T, to in postures:
        m = t >= t0
        x[m] = lvl + (to - lvl) * raised_cosine((t[m] - t0) / T)
        lvl = to
    for t0, n, fa, fb, amp, decay in drums:
        x += drum(t - t0, n, fa, fb, amp, decay)
    return x


# ---- a yo-yo (the drift case) ----

def yoyo(t, throws, top, a):
    """A yo-yo between the hand at +top and the string's end at -top, its acceleration a (g / (1 + I / (m r^2)): the
    spin takes most of the energy; e.g. Feynman's spool): for each throw (t0, u0, sleep), thrown down at u0 (x = top -
    u0 s - a s^2 / 2), spinning at the string's end for `sleep` s (a sleeper), then tugged so that it climbs back,
    decelerating at a, to reach the hand at rest (launched up at sqrt(4 a top)); held in the hand between throws.
    Returns the path and each throw's (fall, sleep, climb) times."""
    t = np.asarray(t, float)
    x = np.full_like(t, top)
    times = []
    for t0, u0, sleep in throws:
        T1 = (-u0 + math.sqrt(u0 * u0 + 4 * a * top)) / a       # top - u0 T - a T^2 / 2 = -top
        u1 = math.sqrt(4 * a * top)
        T2 = u1 / a
        s = t - t0
        m = (s >= 0) & (s < T1)
        x[m] = top - u0 * s[m] - a * s[m] ** 2 / 2
        m = (s >= T1) & (s < T1 + sleep)
        x[m] = -top
        m = (s >= T1 + sleep) & (s < T1 + sleep + T2)
        q = s[m] - T1 - sleep
        x[m] = -top + u1 * q - a * q * q / 2
        times.append((T1, sleep, T2))
    return x, times


def cable_car(t, legs, z0):
    """The altitude (m) of a cable car from z0: legs (t0, T, dz) each a raised-cosine move (a smooth start and stop at
    the stations and towers), held between."""
    t = np.asarray(t, float)
    z = np.full_like(t, z0)
    lvl = z0
    for t0, T, dz in legs:
        m = t >= t0
        z[m] = lvl + dz * raised_cosine((t[m] - t0) / T)
        lvl += dz
    return z


# ---- a slalom skier (the asymmetry case) ----

def slalom(t, gate_t, gate_x):
    """A slalom skier's lateral position through the gates (gate_t, gate_x), start and finish on the fall line: the
    clamped cubic spline through them (zero lateral speed at the start and the finish; among all paths through the
    gates, the least bending energy int x''^2), 0 before the start and after the finish."""
    t = np.asarray(t, float)
    cs = CubicSpline(gate_t, gate_x, bc_type="clamped")
    x = cs(np.clip(t, gate_t[0], gate_t[-1]))
    return np.where((t < gate_t[0]) | (t > gate_t[-1]), 0.0, x)


# ---- a violinist's pitch (the saturation case) ----

def violin(t, notes, f_vib, depth, onset, ramp, porta):
    """A melody's pitch on a linear scale: notes (t0, T, level), each reached from the last by a portamento (a raised
    cosine over `porta` s from t0), the vibrato depth sin(2 pi f_vib (t - t0 - onset)) fading in over `ramp` s after
    `onset` s and out over the note's last `ramp` s (a violinist's vibrato starts late and stops before the shift); 0
    before the first note; after the last note the level held."""
    t = np.asarray(t, float)
    x = np.zeros_like(t)
    lvl = 0.0
    for t0, T, to in notes:
        m = t >= t0
        x[m] = lvl + (to - lvl) * raised_cosine((t[m] - t0) / porta)
        lvl = to
    for t0, T, to in notes:
        m = (t >= t0) & (t < t0 + T)
        s = t[m] - t0
        env = raised_cosine((s - onset) / ramp) * raised_cosine((T - s) / ramp)
        x[m] += depth * env * np.sin(2 * np.pi * f_vib * (s - onset))
    return x


# ---- a bat's echolocation sequence (the delay case) ----

def lpfm_phase(s, f0, f1, T):
    """The phase (rad) of a linear-period (hyperbolic) FM sweep from f0 to f1 over T s, the period 1 / f0 + (1 / f1 - 1
    / f0) s / T growing linearly (the Doppler-tolerant sweep of FM bats; Altes & Titlebaum, J. Acoust. Soc. Am. 48
    (1970) 1014): 2 pi f0 f1 T / (f0 - f1) ln(1 + (f0 - f1) s / (f1 T))."""
    s = np.asarray(s, float)
    return 2 * np.pi * f0 * f1 * T / (f0 - f1) * np.log1p((f0 - f1) * s / (f1 * T))


def bat_calls(t, calls):
    """Calls (t0, T, f0, f1, amp): each a linear-period FM sweep under a Hann window (sin^2(pi s / T)), silent between;
    the sequence of a hunting bat (search calls, then shorter ones closer together in the approach and the terminal
    buzz; Griffin, Webster & Michael, Anim. Behav. 8 (1960) 141), its frequencies and times scaled."""
    t = np.asarray(t, float)
    x = np.zeros_like(t)
    for t0, T, f0, f1, amp in calls:
        m = (t >= t0) & (t <= t0 + T)
        s = t[m] - t0
        x[m] += amp * np.sin(np.pi * s / T) ** 2 * np.sin(lpfm_phase(s, f0, f1, T))
    return x


# ---- a handwheel jog and an interval session (the initial-state case) ----

def handwheel_history(top, low, target):
    """The turning points a machinist leaves with a handwheel (a manual pulse generator) from power-up at 0 V: rolled
    up on its coarse range past the working zone to `top`, back down on the middle range past the target to `low`,
    then crept up on the fine range to the target (approached from below, as a backlash-aware machinist does)."""
    return np.array([0.0, top, low, target])


def heart_rate(t, bouts, rest, tau_on, tau_off):
    """A heart rate through an interval session, from rest: bouts (t0, T, level), the rate approaching each bout's level
    with the time constant tau_on while working and the resting level with tau_off after it (the first-order
    kinetics of the on- and off-transients; e.g. Hagberg et al., J. Appl. Physiol. 48 (1980) 218), in closed form.
    Returns the rate and its values at the bouts' starts and ends."""
    t = np.asarray(t, float)
    x = np.full_like(t, rest)
    lvl, marks = rest, []
    edges = []
    for t0, T, level in bouts:
        edges += [(t0, level, tau_on), (t0 + T, rest, tau_off)]
    bounds = [e[0] for e in edges[1:]] + [np.inf]
    for (t0, target, tau), t1 in zip(edges, bounds):
        marks.append(lvl)
        m = t >= t0
        x[m] = target + (lvl - target) * np.exp(-(t[m] - t0) / tau)
        if np.isfinite(t1):
            lvl = target + (lvl - target) * math.exp(-(t1 - t0) / tau)
    return x, marks


# ---- a conductor's baton (the two-effect case) ----

#: the baton's horizontal position at the four beats of a 4/4 bar (down, left, right, up), in units of the bar's width
BEAT_X = (0.0, -1.0, 1.0, 0.25)


def baton(t, bars, t_start):
    """A conductor's baton across bars (beat, width): each beat a raised-cosine move to the next beat's point (the
    ictus, where the baton stops for an instant), the beat's length `beat` s (an accelerando shortens it), the width
    the dynamics; from 0 at t_start, back to 0 at the end. Returns the path and the ictus times and points."""
    t = np.asarray(t, float)
    x = np.zeros_like(t)
    tc, lvl, ict = t_start, 0.0, []
    for beat, width in bars:
        for b in BEAT_X[1:] + BEAT_X[:1]:
            to = b * width
            m = t >= tc
            x[m] = lvl + (to - lvl) * raised_cosine((t[m] - tc) / beat)
            lvl = to
            tc += beat
            ict.append((tc, to))
    m = t >= tc
    x[m] = lvl * (1 - raised_cosine((t[m] - tc) / 0.6))
    return x, ict


# ---- a walker's hip (the out-of-vocabulary case) ----

def gait(t, bouts, coeffs):
    """A walker's hip flexion about its standing angle (a Fourier series of the stride, sum_k a_k cos(k phi + p_k), phi
    = 2 pi s / period), in bouts (t0, n_strides, period): standing still (0) between, each bout's first and last stride
    faded in and out by a raised cosine (gait initiation and termination)."""
    t = np.asarray(t, float)
    x = np.zeros_like(t)
    for t0, n, P in bouts:
        s = t - t0
        m = (s >= 0) & (s <= n * P)
        phi = 2 * np.pi * s[m] / P
        y = np.zeros_like(phi)
        for k, (a, p) in enumerate(coeffs, start=1):
            y += a * np.cos(k * phi + p)
        x[m] = y * raised_cosine(s[m] / P) * raised_cosine((n * P - s[m]) / P)
    return x


__all__ = ["ECG_WAVES", "ecg_phase", "ecg_rhs", "ecg", "vessel_pressure", "drum", "woodpecker", "yoyo", "cable_car",
           "slalom", "violin", "lpfm_phase", "bat_calls", "handwheel_history", "heart_rate", "BEAT_X", "baton", "gait"]

"""Excitations of the HOLDOUT29 set (``cases_holdout29.py``), each beside its source; the mechanisms are in
:mod:`.mechanisms29`. Citations written from memory in this session (none was re-read), as in mechanisms29.
"""

import math

import numpy as np
from scipy.special import erf

from .mechanisms19 import raised_cosine


def min_jerk(s):
    """The minimum-jerk profile 10 s^3 - 15 s^4 + 6 s^5 on 0 ... 1 (Flash & Hogan, J. Neurosci. 5 (1985) 1688),
    clipped outside."""
    s = np.clip(np.asarray(s, float), 0.0, 1.0)
    return s ** 3 * (10 - 15 * s + 6 * s * s)


# ---- clean: a Foucault pendulum ----

def foucault_x(t, w0, Om, gamma, A=1.0):
    """The bob of a Foucault pendulum (Foucault 1851) in the small-swing limit, w = x + i y in the floor's frame:
    w'' + (2 gamma + 2 i Om) w' + w0^2 w = 0 (Om = Earth's rate times the sine of the latitude, gamma the air's
    damping; e.g. Landau & Lifshitz, *Mechanics*, sec. 39), released at rest at w = i A (on the y axis, so x starts at
    0). Closed form from the characteristic roots s1, s2: w = i A (s2 e^(s1 t) - s1 e^(s2 t)) / (s2 - s1). Returns x."""
    b = gamma + 1j * Om
    r = np.sqrt(b * b - w0 * w0 + 0j)
    s1, s2 = -b + r, -b - r
    t = np.asarray(t, float)
    w = 1j * A * (s2 * np.exp(s1 * t) - s1 * np.exp(s2 * t)) / (s2 - s1)
    return w.real


# ---- creep: a batching hopper's load ----

def hopper_load(t, events):
    """The load in a batching hopper: events (t0, T, dw) each add dw (a scoop poured in, dw > 0) or take the batch out
    through the gate (dw < 0) along a raised cosine of T s."""
    t = np.asarray(t, float)
    out = np.zeros_like(t)
    for t0, T, dw in events:
        out += dw * raised_cosine((t - t0) / T)
    return out


# ---- rate dependence: a flag signaller's arm ----

SEMAPHORE_POS = np.array([0.0, 45.0, 90.0, 135.0, 180.0])


def arm_path(t, moves):
    """A flag signaller's arm (its elevation from hanging down, in degrees): moves (t0, T, a0, a1) by min-jerk
    profiles, the arm held between them (at a letter's position, or down between words)."""
    t = np.asarray(t, float)
    a = np.zeros_like(t)
    for t0, T, a0, a1 in moves:
        m = t >= t0
        a[m] = a0 + (a1 - a0) * min_jerk((t[m] - t0) / T)
    return a


# ---- drift: a quartz clock's seconds hand ----

def tick_step(s, wn, zeta):
    """The hand's step response to one tick of the stepping motor (a second-order system, its rotor and the hand
    ringing on the detent torque): 1 - exp(-zeta wn s) (cos wd s + zeta / sqrt(1 - zeta^2) sin wd s), 0 before."""
    s = np.asarray(s, float)
    wd = wn * math.sqrt(1 - zeta * zeta)
    sp = np.maximum(s, 0.0)
    r = 1 - np.exp(-zeta * wn * sp) * (np.cos(wd * sp) + zeta / math.sqrt(1 - zeta * zeta) * np.sin(wd * sp))
    return np.where(s > 0, r, 0.0)


def clock_hand_x(t, t0, period, n_ticks, wn, zeta):
    """The x of a quartz clock's seconds hand's tip (a Lavet stepping motor: 6 degrees a tick, every ``period`` s from
    t0), from 12 o'clock (x = 0): sin of the sum of the ticks' step responses. Returns x and the angle (rad)."""
    t = np.asarray(t, float)
    ang = np.zeros_like(t)
    for j in range(n_ticks):
        ang += math.radians(6.0) * tick_step(t - (t0 + j * period), wn, zeta)
    return np.sin(ang), ang


# ---- asymmetry: a Wilberforce pendulum ----

def wilberforce_z(t, w, kappa, gamma):
    """The bob's height of a Wilberforce pendulum (Wilberforce 1894; Berg & Marshall, Am. J. Phys. 59 (1991) 32) tuned
    so that its vertical and torsional frequencies agree: z'' + 2 gamma z' + w^2 z + kappa w^2 p = 0, p'' + 2 gamma p'
    + w^2 p + kappa w^2 z = 0 (p the twist scaled to a length), released twisted (p = 1) at z = 0 at rest: the normal
    modes p +- z at w^2 (1 +- kappa) each q = exp(-gamma t) (cos wd t + gamma / wd sin wd t), z = (q+ - q-) / 2; the
    energy beats between bobbing and twisting. Returns z."""
    t = np.asarray(t, float)

    def q(ws):
        wd = math.sqrt(ws - gamma * gamma)
        return np.exp(-gamma * t) * (np.cos(wd * t) + gamma / wd * np.sin(wd * t))
    return 0.5 * (q(w * w * (1 + kappa)) - q(w * w * (1 - kappa)))


# ---- saturation: a playground see-saw ----

def seesaw_path(t, strokes, bounce, f_b, tau_b):
    """A see-saw's plank (its tilt, -1 ... 1 at the stops): strokes (t0, T, x0, x1) by raised cosines, each landing at
    a stop followed by a rebound off the tyre under the seat, bounce |sin(2 pi f_b s)| exp(-s / tau_b) (toward level),
    the plank held between strokes."""
    t = np.asarray(t, float)
    x = np.zeros_like(t)
    for t0, T, x0, x1 in strokes:
        m = t >= t0
        x[m] = x0 + (x1 - x0) * raised_cosine((t[m] - t0) / T)
        if abs(x1) == 1.0:
            s = t[m] - t0 - T
            x[m] -= np.where(s > 0, x1 * bounce * np.abs(np.sin(2 * math.pi * f_b * s)) * np.exp(-s / tau_b), 0.0)
    return x


# ---- delay: an EAN-13 barcode scanned to and fro ----

_L = ["0001101", "0011001", "0010011", "0111101", "0100011", "0110001", "0101111", "0111011", "0110111", "0001011"]
_PARITY = ["LLLLLL", "LLGLGG", "LLGGLG", "LLGGGL", "LGLLGG", "LGGLLG", "LGGGLL", "LGLGLG", "LGLGGL", "LGGLGL"]


def ean13_check(d12):
    """The check digit of EAN-13: the twelve digits weighted 1, 3, 1, 3, ... from the left, 10 minus the sum mod 10."""
    s = sum(d * (3 if j % 2 else 1) for j, d in enumerate(d12))
    return (10 - s % 10) % 10


def ean13_modules(d12):
    """The 95 modules (1 a bar) of EAN-13 (GS1 General Specifications): the start guard 101, six digits in L or G code
    by the first digit's parity pattern, the centre guard 01010, six in R code, the end guard 101."""
    digits = list(d12) + [ean13_check(d12)]
    R = ["".join("1" if c == "0" else "0" for c in p) for p in _L]
    G = [r[::-1] for r in R]
    s = "101"
    for j, d in enumerate(digits[1:7]):
        s += _L[d] if _PARITY[digits[0]][j] == "L" else G[d]
    s += "01010"
    for d in digits[7:]:
        s += R[d]
    s += "101"
    return np.array([int(c) for c in s]), digits


def scan_signal(t, scans, modules, sigma):
    """The scanner's signal (1 on a bar) as its spot, a Gaussian of std sigma (in modules), crosses the code: scans
    (t0, module_s, direction) each at a constant speed, forward or backward; each bar's edges are erf steps."""
    t = np.asarray(t, float)
    out = np.zeros_like(t)
    n = len(modules)
    for t0, mod_s, direc in scans:
        pos = (t - t0) / mod_s                  # modules passed since the scan's start
        if direc < 0:
            pos = n - pos
        for j in np.flatnonzero(modules):
            out += 0.5 * (erf((pos - j) / (math.sqrt(2) * sigma)) - erf((pos - j - 1) / (math.sqrt(2) * sigma)))
    return out


# ---- initial state: hammer throws ----

def hammer_path(t, L0, lead, throws):
    """The hammer's head seen from the side (its horizontal place, -1 ... 1): from L0 (held for ``lead`` s, then to 0
    by a min-jerk move of 0.6 s) through throws (t0, n_turns, f0, f1, a) each swinging in by a min-jerk radius over
    its first turn and turning n_turns times with its rate rising linearly from f0 to f1 Hz (the thrower's
    acceleration through the turns), released at the front (x = 0 at a whole turn) and gone; the thrower at rest
    between throws."""
    t = np.asarray(t, float)
    x = np.where(t < lead, L0, L0 * (1 - min_jerk((t - lead) / 0.6)))
    for t0, n_turns, f0, f1, a in throws:
        T = 2 * n_turns / (f0 + f1)
        s = t - t0
        m = (s >= 0) & (s <= T)
        ph = 2 * math.pi * (f0 * s[m] + 0.5 * (f1 - f0) / T * s[m] ** 2)
        x[m] = a * min_jerk(ph / (2 * math.pi)) * np.sin(ph)
    return x


def hammer_end(throw):
    t0, n_turns, f0, f1, _ = throw
    return t0 + 2 * n_turns / (f0 + f1)


# ---- the pair: a kayaker's paddle ----

def paddle_path(t, strokes):
    """The tilt of a kayak paddle's shaft: strokes (t0, T, side, peak), the blade on ``side`` dipped and drawn through
    the water as peak sin(pi s) of the stroke's fraction s, level (0) between strokes and during glides."""
    t = np.asarray(t, float)
    x = np.zeros_like(t)
    for t0, T, side, peak in strokes:
        m = (t >= t0) & (t <= t0 + T)
        x[m] = side * peak * np.sin(math.pi * (t[m] - t0) / T)
    return x


# ---- out of vocabulary: kneading dough ----

def kneading_path(t, bursts):
    """The baker's hands kneading dough: bursts (t0, strokes) of push-and-pull strokes (T, peak) each peak sin(2 pi s)
    (pushed forward, drawn back, to rest), one after the other; the hands still at 0 between bursts (the dough turned
    and folded)."""
    t = np.asarray(t, float)
    x = np.zeros_like(t)
    for t0, strokes in bursts:
        tc = t0
        for T, peak in strokes:
            m = (t >= tc) & (t <= tc + T)
            x[m] = peak * np.sin(2 * math.pi * (t[m] - tc) / T)
            tc += T
    return x

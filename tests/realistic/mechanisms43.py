"""Mechanisms of the HOLDOUT43 set (``cases_holdout43.py``), each written from its law; the signals are in
:mod:`.signals43`.

Nothing here imports hystcomp (nor another set's mechanisms). Every mechanism takes the (clean) drive's Lippmann term,
or the core's output, and returns the response; all are causal.

Citations: every source below was written from memory in this session (none was re-read); volumes, pages and years may
be off, and so may the material constants quoted (they are typical values, not a datasheet's). The laws do not rest on
them: each is checked in tests/test_realistic_holdout43.py against an independent solution (the sectors' force balance
solved by a plain bisection with the cap's volume by brentq, solve_ivp of the line's creep, of its friction and of the
lock-in's filter, quad, brentq, closed forms).
"""

import math

import numpy as np
from numba import njit
from scipy.linalg import expm
from scipy.optimize import brentq
from .excitations import on_off_intervals


# ---- the rate-independent core: an electrowetting drop's contact line pinned by the coating's defects ----
#
# A water drop (about 1 uL) sits in silicone oil on a fluoropolymer-coated dielectric over a buried electrode (an
# electrowetting cell, the kind a liquid lens is built on; the oil raises Young's angle to about 160 deg); an AC
# amplifier applies V between the drop (a wire dipped in it) and the electrode. Young-Lippmann: the line's equilibrium
# angle obeys cos theta_L = cos theta_Y + eps V^2 / (2 gamma d) (Lippmann 1875; Berge 1993; Mugele & Baret, J. Phys.:
# Condens. Matter 17 (2005) R705); the amplifier's command sets V^2 linearly (a force-linear drive: its output is the
# square root of an offset plus the command), so the Lippmann term c_L = cos theta_L is linear in the drive: c_L =
# c_mid + dc v / amp (on a unipolar stroke c_mid + dc (2 v / top - 1): 0 V the smallest footprint). The drop keeps its
# volume and is a spherical cap: with tau = tan(theta / 2) its volume is (pi R^3 / 6) (3 tau + tau^3) (the cap's height
# R tau), so the apparent angle at a contact radius R solves tau^3 + 3 tau = omega / R^3 (Cardano's real root).
# The contact line is pinned by the coating's chemical and topographic defects (contact-angle hysteresis: Joanny & de
# Gennes, J. Chem. Phys. 81 (1984) 552): it is N_SECT angular sectors, sector m at radius R_m, its unbalanced force per
# length over gamma f_m = c_L - cos theta(Rbar) - kappa (R_m - Rbar) (the Lippmann pull less the cap's, the line's
# elasticity tying it to the mean radius Rbar in the mean-field approximation, one stiffness kappa), pinned while |f_m|
# <= h_m (its defects' strength, log-normal) and sliding to the threshold beyond it (a sector advances when f_m > h_m,
# recedes when f_m < -h_m; quasi-statically, the line's motion being fast). The footprint's area pi mean(R_m^2) is read
# by a capacitance meter (the dielectric under the drop a parallel-plate capacitor): the reading C_mid mean(R_m^2),
# C_mid the capacitance at R = 1.
#
# Rate independent, with return-point memory (every sector a stop of the common force, the common force monotone in
# the drive at fixed history), close to a Prandtl-Ishlinskii model (the sectors are plays with a mean-field spring: an
# Iwan model) but not one: the cap's geometry makes the restoring force nonlinear in Rbar, and the reading is the area.
# The virgin state: the drop deposited at the middle of the command (every sector at the equilibrium radius) and
# settled by the rig's routine (the command cycled about the middle with amplitudes falling geometrically to nothing).

N_SECT = 360


def sectors(seed, n=N_SECT, h0=0.05, hs=0.5):
    """The sectors' pinning strengths h_m (in units of cos theta): log-normal about h0, the log's spread hs."""
    rng = np.random.default_rng(seed)
    return h0 * np.exp(hs * rng.standard_normal(n))


def omega_for(theta_mid):
    """The drop's volume parameter omega = 6 Omega / pi (R = 1 at the angle theta_mid)."""
    t = math.tan(theta_mid / 2)
    return 3.0 * t + t ** 3


@njit(cache=True)
def _cos_app(Rb, om):
    """The cap's apparent cos theta at contact radius Rb and its derivative in Rb."""
    b = om / (Rb * Rb * Rb)
    p = (0.5 * b + math.sqrt(0.25 * b * b + 1.0)) ** (1.0 / 3.0)
    tau = p - 1.0 / p
    q = 1.0 + tau * tau
    c = (1.0 - tau * tau) / q
    dc = 4.0 * tau * b / (Rb * q * q * q)
    return c, dc


def cos_app(Rb, om):
    """The cap's apparent cos theta at the contact radius Rb (Cardano's root of tau^3 + 3 tau = om / Rb^3)."""
    Rb = np.asarray(Rb, float)
    b = om / Rb ** 3
    p = np.cbrt(0.5 * b + np.sqrt(0.25 * b * b + 1.0))
    tau = p - 1.0 / p
    return (1.0 - tau * tau) / (1.0 + tau * tau)


@njit(cache=True)
def _phi(x, cL, R, h, kap, om, e):
    """The balance mean(R_new(x)) - x at a trial mean radius x and its derivative (e < 0: quasi-static; else the
    backward-Euler weight of a viscous step, dt / tau_c)."""
    c, dc = _cos_app(x, om)
    g = cL - c
    n = R.shape[0]
    tot = 0.0
    nmov = 0
    for m in range(n):
        lo = x + (g - h[m]) / kap
        hi = x + (g + h[m]) / kap
        r = R[m]
        if r < lo:
            nmov += 1
            r = lo if e < 0 else (r + e * lo) / (1.0 + e)
        elif r > hi:
            nmov += 1
            r = hi if e < 0 else (r + e * hi) / (1.0 + e)
        tot += r
    w = 1.0 if e < 0 else e / (1.0 + e)
    return tot / n - x, (nmov / n) * w * (1.0 - dc / kap) - 1.0


@njit(cache=True)
def _settle(x0, cL, R, h, kap, om, e):
    """The mean radius where the balance holds (Newton's method in a bisection's bracket, to 1e-15) and the sectors
    there (R updated in place)."""
    lo, hi = 0.05, 20.0
    x = x0
    for _ in range(200):
        f, df = _phi(x, cL, R, h, kap, om, e)
        if f > 0:
            lo = x
        else:
            hi = x
        if f == 0.0:
            break
        xn = x - f / df
        if not (lo < xn < hi):
            xn = 0.5 * (lo + hi)
        if abs(xn - x) <= 1e-15 * x or hi - lo <= 1e-15 * x:
            x = xn
            break
        x = xn
    c, _ = _cos_app(x, om)
    g = cL - c
    for m in range(R.shape[0]):
        lo_m = x + (g - h[m]) / kap
        hi_m = x + (g + h[m]) / kap
        if R[m] < lo_m:
            R[m] = lo_m if e < 0 else (R[m] + e * lo_m) / (1.0 + e)
        elif R[m] > hi_m:
            R[m] = hi_m if e < 0 else (R[m] + e * hi_m) / (1.0 + e)
    return x


@njit(cache=True)
def _run(cLs, R, h0, kap, om, hsc, tau_c, dt, nsub, F, W, oms):
    """The sectors along the Lippmann terms cLs (R updated in place): quasi-static (tau_c 0), with the line's friction
    (tau_c > 0: nsub backward-Euler substeps a sample, the command linear between samples), or quasi-static and then
    the line's thermally activated creep (F > 0: nsub substeps a sample, each sector's closed form at frozen Rbar);
    the pinning strengths h0 times hsc[k] at sample k and the volume parameter oms[k] (if oms has a length). Returns the
    mean radius and the mean of R^2 at every sample."""
    n = R.shape[0]
    K = cLs.shape[0]
    rb = np.empty(K)
    a2 = np.empty(K)
    h = h0.copy()
    x = R.mean()
    prev = cLs[0]
    for k in range(K):
        for m in range(n):
            h[m] = h0[m] * hsc[k]
        omk = oms[k] if oms.shape[0] > 0 else om
        if tau_c > 0.0:
            e = dt / (nsub * tau_c)
            for j in range(1, nsub + 1):
                c = prev + (cLs[k] - prev) * j / nsub
                x = _settle(x, c, R, h, kap, omk, e)
        else:
            x = _settle(x, cLs[k], R, h, kap, omk, -1.0)
            if F > 0.0:
                ds = dt / nsub
                for j in range(nsub):
                    c0, _ = _cos_app(x, omk)
                    g = cLs[k] - c0
                    for m in range(n):
                        f0 = g - kap * (R[m] - x)
                        d = math.exp(-2.0 * kap * W[m] * ds / F)
                        f1 = 2.0 * F * math.atanh(math.tanh(f0 / (2.0 * F)) * d)
                        R[m] = x + (g - f1) / kap
                    x = R.mean()
        prev = cLs[k]
        rb[k] = R.mean()
        s = 0.0
        for m in range(n):
            s += R[m] * R[m]
        a2[k] = s / n
    return rb, a2


def _arr(v, K):
    return np.full(K, 1.0) if v is None else np.asarray(v, float)


def drop(core, cL, state=None, return_state=False, tau_c=0.0, dt=1.0, nsub=1, F=0.0, hscale=None, omegas=None,
         h=None):
    """The mean radius and the capacitance reading (C_mid mean(R_m^2)) along the Lippmann terms cL, from the sectors'
    radii state (default the virgin drop); tau_c the line's friction time (0: quasi-static), F > 0 the creep's thermal
    force (W the sectors' creep speeds core["W"]), hscale the pinning's factor at every sample, omegas the volume
    parameter at every sample."""
    cL = np.ascontiguousarray(cL, dtype=float)
    hh = core_h(core) if h is None else h
    R = (virgin(core) if state is None else np.array(state, float)).copy()
    W = np.asarray(core.get("W", np.zeros(len(hh))), float) if F > 0 else np.zeros(len(hh))
    oms = np.zeros(0) if omegas is None else np.ascontiguousarray(omegas, dtype=float)
    rb, a2 = _run(cL, R, hh, core["kap"], core["om"], _arr(hscale, len(cL)), float(tau_c), float(dt), int(nsub),
                  float(F), W, oms)
    y = core["C_mid"] * a2
    return (rb, y, R) if return_state else (rb, y)


_H_CACHE = {}


def core_h(core):
    """The core's pinning strengths (cached by their parameters)."""
    key = (core["sseed"], core.get("n", N_SECT), core["h0"], core["hs"])
    if key not in _H_CACHE:
        _H_CACHE[key] = sectors(core["sseed"], core.get("n", N_SECT), core["h0"], core["hs"])
    return _H_CACHE[key]


def r_equilibrium(core, c):
    """The radius where the cap's angle is the Lippmann angle c (the unpinned line's equilibrium)."""
    return brentq(lambda r: float(cos_app(r, core["om"])) - c, 0.2, 5.0, xtol=1e-15)


_V_CACHE = {}


def virgin(core):
    """The virgin drop: deposited at the command's middle (every sector at the equilibrium radius there), settled by
    the command cycled about the middle with amplitudes falling by 0.85 a cycle from the full swing to nothing (60
    cycles); then left at the middle."""
    key = (core["sseed"], core.get("n", N_SECT), core["h0"], core["hs"], core["kap"], core["om"], core["c_mid"],
           core["dc"])
    if key not in _V_CACHE:
        h = core_h(core)
        R = np.full(len(h), r_equilibrium(core, core["c_mid"]))
        amps = core["dc"] * 0.85 ** np.arange(60)
        path = np.r_[[core["c_mid"] + s * a for a in amps for s in (1.0, -1.0)], core["c_mid"]]
        _run(np.ascontiguousarray(path), R, h, core["kap"], core["om"], np.ones(len(path)), 0.0, 1.0, 1, 0.0,
             np.zeros(len(h)), np.zeros(0))
        _V_CACHE[key] = R
    return _V_CACHE[key].copy()


# ---- creep: the contact line's thermally activated creep (below its pinning threshold) ----
#
# A pinned stretch of line still hops over its defects by thermal activation (and the ambient's small vibrations), the
# barrier lowered by the force on it: the molecular-kinetic theory's rate law, dR_m/dt = 2 W_m sinh(f_m / F) (Blake &
# Haynes, J. Colloid Interface Sci. 30 (1969) 421), the speed W_m = w0 exp(-h_m / F) falling with the sector's pinning
# strength (the barrier), F the thermal force scale; the line creeping in the direction of its last move, ever slower
# as its force falls (a logarithmic creep, as Rolley & Guthmann, Phys. Rev. Lett. 98 (2007) 166105, measured for a
# contact line). At frozen Rbar a sector's force decays in closed form: tanh(f / 2F) = tanh(f0 / 2F) exp(-2 kappa W t
# / F).

def creep_speeds(core, F, w0):
    """The sectors' creep speeds W_m = w0 exp(-h_m / F)."""
    return w0 * np.exp(-core_h(core) / F)


#: substeps a sample of the line's creep
CREEP_SUB = 4


# ---- rate dependence: the contact line's friction ----
#
# Beyond its threshold a sector slides at a finite speed set by the line's friction (the molecular-kinetic line
# friction zeta, about 0.1 ... 1 Pa s for water on a fluoropolymer; Blake, J. Colloid Interface Sci. 299 (2006) 1):
# zeta dR_m/dt = gamma (f_m - h_m sign f_m) while |f_m| > h_m, so the line lags a fast command; tau_c = zeta / (gamma
# kappa) the time it takes. Solved by backward Euler in substeps (the quasi-static sectors in the limit tau_c -> 0).

#: substeps a sample of the line's friction
FRICTION_SUB = 2


# ---- drift: the drop dissolving into the oil ----
#
# The oil was not saturated with water, and the drop loses water to it by diffusion (water dissolves to 100 ... 200 ppm
# in silicone oil: a millilitre of oil takes up a tenth of the drop). Diffusion-limited, as a sessile drop evaporates:
# dOmega/dt = -pi R D (c_s - c_inf) f(theta) / rho (Picknett & Bexon, J. Colloid Interface Sci. 61 (1977) 336; f(theta)
# = 0.27 theta^2 + 1.30 as Hu & Larson, J. Phys. Chem. B 106 (2002) 1334, fitted), the rate proportional to the
# contact radius; the volume parameter omega falls with it, the area at a given command shrinking (the line receding
# when its pinning lets it). The constants' product is drawn as a rate (the share of the volume lost by the end).

def dissolution_weight(rb, theta):
    """Picknett and Bexon's rate's shape: R (0.27 theta^2 + 1.30)."""
    return rb * (0.27 * theta * theta + 1.30)


def theta_app(rb, om):
    """The cap's apparent angle (rad) at the mean radius rb."""
    return np.arccos(np.clip(cos_app(rb, om), -1.0, 1.0))


def dissolving(core, cL, rate, state=None):
    """The drop along cL while it dissolves: the volume parameter falls every sample by rate x the Picknett-Bexon
    weight at the last sample's mean radius and angle (omega_{k+1} = omega_k (1 - rate w_k)); returns (rb, y,
    omegas)."""
    cL = np.asarray(cL, float)
    R = (virgin(core) if state is None else np.array(state, float)).copy()
    h = core_h(core)
    om = core["om"]
    K = len(cL)
    oms = np.empty(K)
    rb = np.empty(K)
    a2 = np.empty(K)
    one = np.ones(1)
    W0 = np.zeros(len(h))
    for k in range(K):
        oms[k] = om
        r1, q1 = _run(np.ascontiguousarray(cL[k:k + 1]), R, h, core["kap"], om, one, 0.0, 1.0, 1, 0.0, W0,
                      np.zeros(0))
        rb[k], a2[k] = r1[0], q1[0]
        om = om * (1.0 - rate * float(dissolution_weight(rb[k], theta_app(rb[k], om))))
    return rb, core["C_mid"] * a2, oms


# ---- asymmetry: a relaxation oscillator reading the capacitance ----
#
# The capacitance is read by a relaxation oscillator (a comparator charging the cell in parallel with a fixed timing
# capacitor C_p through a resistor: the period proportional to C_p + C) and a frequency counter, scaled to capacitance
# by a straight line fitted at the middle: the reading follows 1 / (C_p + C), convex, one end stretched. In units of
# the half stroke about the middle (slope 1 at 0): r(s) = q s / (q + s), q = (C_p + C_mid) / the half stroke; the ends'
# secants r(1) + r(-1) = -2 q / (q^2 - 1).

def oscillator_reading(s, q):
    """The oscillator's reading of the normalised stroke s (slope 1 at 0)."""
    s = np.asarray(s, float)
    return q * s / (q + s)


def oscillator_for(a):
    """q for which the ends' secants differ by a: 2 q / (q^2 - 1) = a."""
    return 1.0 / a + math.sqrt(1.0 / a ** 2 + 1.0)


# ---- saturation: the lock-in's synchronous detector overloading ----
#
# The capacitance bridge's unbalance is demodulated by a Gilbert-cell multiplier whose signal port is a bipolar
# differential pair: its output follows tanh(u / 2 V_T) (Gilbert, IEEE J. Solid-State Circuits 3 (1968) 365), the ends
# of the stroke compressed as the pair runs out of its tail current. In units of the half stroke (slope 1 at 0):
# tanh(z s) / z, the ends compressed by 1 - tanh(z) / z.

def gilbert(s, z):
    """The detector's output of the normalised stroke s (slope 1 at 0)."""
    return np.tanh(z * np.asarray(s, float)) / z


def gilbert_for(comp):
    """z for which the ends are compressed by comp."""
    return brentq(lambda z: 1.0 - math.tanh(z) / z - comp, 1e-6, 50.0, xtol=1e-15)


# ---- delay: the lock-in's output filter ----
#
# The lock-in's output filter is two RC sections in cascade (12 dB/octave), each of time constant tau: for the slow
# parts of the signal a delay of 2 tau. Solved exactly for an input linear between the points of a grid R_FINE times
# finer than the logger's (the state-space model's matrix exponential with the input's ramp appended), from rest at the
# first value.

R_FINE = 8


def two_pole(u, dtf, tau):
    """Two cascaded first-order lags (tau each) of u, linear between its points dtf apart, from rest at u[0]."""
    A = np.array([[-1 / tau, 0.0, 1 / tau, 0.0], [1 / tau, -1 / tau, 0.0, 0.0], [0.0, 0.0, 0.0, 1.0],
                  [0.0, 0.0, 0.0, 0.0]])
    E = expm(A * dtf)
    u = np.asarray(u, float)
    x1 = x2 = u[0]
    out = np.empty(len(u))
    out[0] = u[0]
    for k in range(1, len(u)):
        z = E @ np.array([x1, x2, u[k - 1], (u[k] - u[k - 1]) / dtf])
        x1, x2 = z[0], z[1]
        out[k] = x2
    return out


@njit(cache=True)
def _two_pole_run(u, E):
    x1 = u[0]
    x2 = u[0]
    out = np.empty(u.shape[0])
    out[0] = u[0]
    for k in range(1, u.shape[0]):
        u0 = u[k - 1]
        s = u[k] - u[k - 1]
        n1 = E[0, 0] * x1 + E[0, 1] * x2 + E[0, 2] * u0 + E[0, 3] * s
        n2 = E[1, 0] * x1 + E[1, 1] * x2 + E[1, 2] * u0 + E[1, 3] * s
        x1, x2 = n1, n2
        out[k] = x2
    return out


def lockin_filter(u, dtf, tau):
    """two_pole, compiled (the same recursion; the ramp's column scaled by dtf)."""
    A = np.array([[-1 / tau, 0.0, 1 / tau, 0.0], [1 / tau, -1 / tau, 0.0, 0.0], [0.0, 0.0, 0.0, 1.0],
                  [0.0, 0.0, 0.0, 0.0]])
    E = expm(A * dtf)
    E[:, 3] = E[:, 3] / dtf
    return _two_pole_run(np.ascontiguousarray(u, dtype=float), E)


# ---- out of vocabulary: a bench pump's vibration shaking the line loose ----
#
# A diaphragm vacuum pump on the same bench cycles on its own pressure switch; while it runs its vibration helps the
# line over its defects (vibration-assisted depinning: the apparent contact-angle hysteresis shrinks under vibration;
# e.g. Decker & Garoff, Langmuir 12 (1996) 2100): the pinning strengths fall to (1 - s) of theirs and the line
# relaxes toward its equilibrium. The record does not carry the pump.

def pump_cycles(t, on_range, off_range, rng):
    """The pump's runs [(start, duration)] over t (the first after an off time), and a 0/1 mask of the samples in
    them."""
    return on_off_intervals(t, on_range, off_range, rng)

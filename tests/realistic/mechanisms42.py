"""Mechanisms of the HOLDOUT42 set (``cases_holdout42.py``), each written from its law; the signals are in
:mod:`.signals42`.

Nothing here imports hystcomp (nor another set's mechanisms). Every mechanism takes the (clean) drive's bath
temperature, or the core's output, and returns the response; all are causal.

Citations: every source below was written from memory in this session (none was re-read); volumes, pages and years may
be off, and so may the material constants quoted (they are typical values, not a datasheet's). The laws do not rest on
them: each is checked in tests/test_realistic_holdout42.py against an independent solution (the wire's segments
transformed by a brute-force bisection of the stress balance written from its definition, the same for the thermal lag,
quad, brentq, a Biot-Savart integration of the magnet's surface current, the aperture's mean by quad and the chain's
closed form by its ODE).
"""

import math

import numpy as np
from numba import njit
from scipy.optimize import brentq
from .excitations import on_off_intervals


# ---- the rate-independent core: a NiTi wire's martensite fraction against a bias spring ----
#
# A thin NiTi shape-memory wire (a one-way actuator wire) runs through a small oil-filled channel whose temperature a
# Peltier controller sets from the drive (the bath temperature T = T_mid + dT v / amp; on a unipolar stroke 0 V is the
# cold end); a steel bias spring stretches it, and a digital dial indicator reads the load's lift (the wire's
# contraction), times a drawn gain. The wire is N_SEG segments (its grains' clusters), each either austenite or
# martensite (a thermoelastic first-order transformation): a segment turns to martensite when the effective temperature
# u = T - sigma / C falls to its own M_i, and back to austenite when u rises to its own A_i = M_i + w_i (the
# transformation temperatures shift with the stress sigma by the Clausius-Clapeyron slope C, about 6.5 MPa/K in NiTi:
# Otsuka & Wayman, *Shape Memory Materials*, 1998, ch. 2; Tanaka, Res Mechanica 18 (1986) 251; Liang & Rogers, J. Intell.
# Mater. Syst. Struct. 1 (1990) 207, whose cosine kinetics is the mean of such segments; the segments' spread is the
# inhomogeneity of composition and texture along the wire; Ortin, J. Appl. Phys. 71 (1992) 1454, a Preisach description
# of a shape-memory alloy's thermal transformation). The segments share one stress: the wire's strain is eps_L xi +
# sigma / E (xi the martensite fraction, eps_L about 4 %, one compliance for both phases) against the bias spring, so the
# stress falls linearly as martensite lengthens the wire: sigma = sigma_A - dsigma xi, and u = T - sigma_A / C +
# (dsigma / C) xi: a negative feedback that shears the loop. Where the feedback would flip a segment back as it flips
# (the stress rising faster than the segment's threshold is passed) the segment stops part-transformed at its threshold
# (a transformation front stopped inside it): the fraction is continuous in T. The lift: l0 ((eps_L - dsigma / E) xi
# + alpha_t (T - T_mid)) (the martensite's lengthening, the stress's elastic part, the wire's and frame's thermal
# expansion), read as the load's rise: minus that, plus a constant.
#
# M_i normal about M50 (spread s_M 5 ... 7 K), w_i normal about w0 (20 ... 26 K, spread 2.5 K, at least 8 K). Rate
# independent (the bath's temperature sets the state; the wire is taken to follow it), with return-point memory (each
# segment a relay of u, and u monotone in T at fixed history: the feedback is negative), but not a Prandtl-Ishlinskii
# model: the relays' thresholds are absolute temperatures (the loops saturate as the wire runs out of segments to
# transform) and the feedback breaks the minor loops' congruence. The virgin state: the wire annealed and cooled from far
# above A_f (all austenite) to T_mid, then settled by the rig's routine, the bath cycled about T_mid with amplitudes
# falling geometrically to nothing (the state at the loop's middle, as AC demagnetisation leaves a magnet), then taken to
# the record's first temperature.

N_SEG = 1500


def segments(seed, n=N_SEG, M50=45.0, sM=5.0, w0=23.0, sw=2.5):
    """The segments' transformation temperatures at zero stress (M, A), degrees C."""
    rng = np.random.default_rng(seed)
    M = M50 + sM * rng.standard_normal(n)
    w = np.maximum(w0 + sw * rng.standard_normal(n), 8.0)
    return M, M + w


@njit(cache=True)
def _step(Tstar, S0, S1, q, xi, u_old, Asrt, Aord, Msrt, Mord):
    """One move of the wire to the state where u = Tstar - S0 + S1 xi and every segment is at rest (q the segments'
    martensite shares, updated in place); returns (xi, u)."""
    n = q.shape[0]
    u = Tstar - S0 + S1 * xi
    if u >= u_old:
        # heating: segments with A_j <= u turn to austenite, in the order of A_j (each lowers u by S1 q_j / n)
        k = np.searchsorted(Asrt, u_old - 1e-9)
        while k < n:
            Aj = Asrt[k]
            if Aj > u:
                break
            j = Aord[k]
            if q[j] > 0.0:
                xin = xi - q[j] / n
                un = Tstar - S0 + S1 * xin
                if un >= Aj:
                    xi = xin
                    q[j] = 0.0
                    u = un
                else:
                    xs = (Aj - Tstar + S0) / S1
                    q[j] -= (xi - xs) * n
                    xi = xs
                    u = Aj
                    break
            k += 1
    else:
        # cooling: segments with M_j >= u turn to martensite, in the order of M_j falling (each raises u)
        k = np.searchsorted(Msrt, u_old + 1e-9, side="right") - 1
        while k >= 0:
            Mj = Msrt[k]
            if Mj < u:
                break
            j = Mord[k]
            if q[j] < 1.0:
                xin = xi + (1.0 - q[j]) / n
                un = Tstar - S0 + S1 * xin
                if un <= Mj:
                    xi = xin
                    q[j] = 1.0
                    u = un
                else:
                    xs = (Mj - Tstar + S0) / S1
                    q[j] += (xs - xi) * n
                    xi = xs
                    u = Mj
                    break
            k -= 1
    return xi, u


@njit(cache=True)
def _run(Ts, S0, S1, q, Asrt, Aord, Msrt, Mord):
    """The fraction along the temperatures Ts (q updated in place)."""
    xi = q.sum() / q.shape[0]
    u = Ts[0] - S0 + S1 * xi
    out = np.empty(Ts.shape[0])
    for t in range(Ts.shape[0]):
        xi, u = _step(Ts[t], S0, S1, q, xi, u, Asrt, Aord, Msrt, Mord)
        out[t] = xi
    return out


@njit(cache=True)
def _run_lag(Tb, a, lam, S0, S1, q, Tw0, Asrt, Aord, Msrt, Mord, nsub):
    """The fraction and the wire's temperature along the bath's Tb (sampled; linear between samples) with the thermal
    lag dt / tau = a a sample and the latent heat lam (K per unit fraction), backward Euler over nsub substeps."""
    n = q.shape[0]
    xi = q.sum() / n
    Tw = Tw0
    u = Tw - S0 + S1 * xi
    out = np.empty(Tb.shape[0])
    tw = np.empty(Tb.shape[0])
    out[0] = xi
    tw[0] = Tw
    b = a / nsub
    lp = lam / (1.0 + b)
    for t in range(1, Tb.shape[0]):
        for s in range(nsub):
            T_b = Tb[t - 1] + (s + 1.0) / nsub * (Tb[t] - Tb[t - 1])
            # (1 + b) Tw_new = Tw + b T_b + lam (xi_new - xi): u = Tstar + lp (xi_new - xi) - S0 + S1 xi_new
            Tstar = (Tw + b * T_b) / (1.0 + b)
            xi_old = xi
            xi, u = _step(Tstar, S0 + lp * xi_old, S1 + lp, q, xi, u, Asrt, Aord, Msrt, Mord)
            Tw = Tstar + lp * (xi - xi_old)
        out[t] = xi
        tw[t] = Tw
    return out, tw


def wire(core):
    """The core's segments, sorted (A ascending and its order, M ascending and its order), cached on the core's dict."""
    key = (core["sseed"], core.get("n", N_SEG), core["sM"], core["w0"])
    cache = core.setdefault("_seg", {})
    if key not in cache:
        cache.clear()
        M, A = segments(core["sseed"], n=key[1], M50=core.get("M50", 45.0), sM=core["sM"], w0=core["w0"])
        ia, im = np.argsort(A, kind="stable"), np.argsort(M, kind="stable")
        cache[key] = (M, A, A[ia], ia.astype(np.int64), M[im], im.astype(np.int64))
    return cache[key]


def feedback(core):
    """(S0, S1): u = T - S0 + S1 xi, S0 = sigma_A / C, S1 = dsigma / C."""
    return core["sigA"] / core["C"], core["dsig"] / core["C"]


def settling_path(core, n_cycles=60, ratio=0.9):
    """The rig's settling routine after the wire is fitted: the bath from far above A_f down to T_mid, then cycled
    about T_mid with amplitudes falling geometrically from 1.5 dT (by the ratio a cycle) and left at T_mid (the analogue
    of an AC demagnetisation: the state at the loop's middle)."""
    M, A, As, Ao, Ms, Mo = wire(core)
    S0, S1 = feedback(core)
    amps = 1.5 * core["dT"] * ratio ** np.arange(n_cycles)
    turns = np.c_[core["T_mid"] + amps, core["T_mid"] - amps].ravel()
    return np.r_[A.max() + S0 + 50.0, turns, core["T_mid"]]


def virgin(core, T0):
    """The wire's shares after the settling routine (:func:`settling_path`), the bath then taken to T0."""
    M, A, As, Ao, Ms, Mo = wire(core)
    S0, S1 = feedback(core)
    q = np.zeros(len(M))
    _run(np.r_[settling_path(core), float(T0)], S0, S1, q, As, Ao, Ms, Mo)
    return q


def fraction(core, T, state=None, return_state=False):
    """The martensite fraction along the bath temperatures T (from the shares state; default the virgin wire at
    T[0])."""
    M, A, As, Ao, Ms, Mo = wire(core)
    S0, S1 = feedback(core)
    T = np.asarray(T, float)
    q = virgin(core, T[0]) if state is None else np.array(state, float)
    xi = _run(T, S0, S1, q, As, Ao, Ms, Mo)
    return (xi, q) if return_state else xi


def lagged_fraction(core, Tb, dt, tau, lam, nsub=8, state=None):
    """The fraction and the wire's temperature with the wire's thermal lag tau behind the bath and the latent heat lam
    (c dT/dt = h (T_b - T) + L dxi/dt: tau = c / h, lam = L / c), from rest at Tb[0] (the virgin wire by default)."""
    M, A, As, Ao, Ms, Mo = wire(core)
    S0, S1 = feedback(core)
    Tb = np.asarray(Tb, float)
    q = virgin(core, Tb[0]) if state is None else np.array(state, float)
    return _run_lag(Tb, dt / tau, float(lam), S0, S1, q, float(Tb[0]), As, Ao, Ms, Mo, int(nsub))


def lift(core, T, xi):
    """The load's lift read by the dial indicator, times the gain: -gain l0 ((eps_L - dsigma / E) xi + alpha_t (T -
    T_mid)), l0 = 1 (the lift in units of the wire's length)."""
    T = np.asarray(T, float)
    xi = np.asarray(xi, float)
    return -core["gain"] * ((core["epsL"] - core["dsig"] / core["E"]) * xi + core["alpha_t"] * (T - core["T_mid"]))


# ---- creep: the transformation's isothermal after-run (Avrami kinetics) ----
#
# After every change of the martensite fraction a further share kappa of it follows at constant temperature: the
# thermally activated nucleation and growth of the new phase's plates at the stopped fronts (the isothermal martensitic
# transformation; Kurdjumov & Maksimova 1948 from memory), with Avrami's (Johnson-Mehl-Avrami-Kolmogorov) kinetics,
# phi(t) = 1 - exp(-(t / tau)^m) (Avrami, J. Chem. Phys. 7 (1939) 1103, 8 (1940) 212; m 1.3 ... 1.8: a slow start, a
# sigmoid in log t). Superposed over the fraction's increments (Boltzmann), each taken linear between samples: the
# kernel of a sample's ramp is the ramp response R(t) = int_0^t phi, differenced; R(t) = t - tau Gamma(1 + 1/m)
# P(1/m, (t / tau)^m) (P the regularised lower incomplete gamma function).

def avrami_step(t, tau, m):
    """phi(t) = 1 - exp(-(t / tau)^m) (0 at t <= 0)."""
    t = np.maximum(np.asarray(t, float), 0.0)
    return -np.expm1(-(t / tau) ** m)


def avrami_ramp(t, tau, m):
    """int_0^t phi = t - tau Gamma(1 + 1/m) P(1/m, (t / tau)^m)."""
    from scipy.special import gamma, gammainc
    t = np.maximum(np.asarray(t, float), 0.0)
    return t - tau * gamma(1.0 + 1.0 / m) * gammainc(1.0 / m, (t / tau) ** m)


def afterrun(xi, dt, kappa, tau, m):
    """kappa times the superposed Avrami uptake of the increments of xi (linear between samples): 0 at the start."""
    from scipy.signal import fftconvolve
    xi = np.asarray(xi, float)
    n = len(xi)
    R = avrami_ramp(np.arange(n + 1) * dt, tau, m)
    g = np.diff(R) / dt
    c = np.zeros(n)
    if n > 1:
        c[1:] = fftconvolve(np.diff(xi), g)[:n - 1]
    return kappa * c


# ---- drift: the dial indicator's stand post warming (a two-node thermal chain) ----
#
# The indicator hangs from a steel post on the bench beside the Peltier's heat sink; the sink warms the bench plate (time
# constant tau1), the plate the post (tau2): the post's temperature rise, and its growth, follow the step response of
# two first-order lags in series, 1 - (tau1 exp(-t / tau1) - tau2 exp(-t / tau2)) / (tau1 - tau2) (zero slope at the
# start: an S-shape). The indicator's zero moves with the post.

def chain_rise(t, tau1, tau2):
    """1 - (tau1 exp(-t / tau1) - tau2 exp(-t / tau2)) / (tau1 - tau2)."""
    t = np.asarray(t, float)
    return 1.0 - (tau1 * np.exp(-t / tau1) - tau2 * np.exp(-t / tau2)) / (tau1 - tau2)


# ---- asymmetry: a linear Hall sensor facing a cylindrical magnet ----
#
# The lift is read by a linear Hall sensor on the axis of a cylindrical NdFeB magnet (radius a, length L, uniformly
# magnetised along the axis) that the load carries towards it: the on-axis field at a distance z from the near face is
# B = (B_r / 2) ((z + L) / sqrt((z + L)^2 + a^2) - z / sqrt(z^2 + a^2)) (the field of the magnet's surface current, a
# solenoid's sheet; e.g. Jackson, *Classical Electrodynamics*, ch. 5), steeper as the magnet comes near. Here L = a and
# the working gap z0 = 1.5 a; the stroke's half-range d (in a): the reading over the stroke s (-1 ... 1, the magnet
# nearer at +1), slope 1 at 0: f(s) = (B(z0 - d s) - B(z0)) / (-d B'(z0)); the ends' secants f(1) + f(-1) apart.

HALL_L, HALL_Z0 = 1.0, 1.5


def magnet_field(z, L=HALL_L):
    """The on-axis field over B_r / 2 at the distance z (in a) from the near face."""
    z = np.asarray(z, float)
    return (z + L) / np.sqrt((z + L) ** 2 + 1.0) - z / np.sqrt(z * z + 1.0)


def _magnet_slope(z, L=HALL_L):
    return 1.0 / ((z + L) ** 2 + 1.0) ** 1.5 - 1.0 / (z * z + 1.0) ** 1.5


def hall_reading(s, d, z0=HALL_Z0):
    """(B(z0 - d s) - B(z0)) / (-d B'(z0))."""
    s = np.asarray(s, float)
    return (magnet_field(z0 - d * s) - magnet_field(z0)) / (-d * _magnet_slope(z0))


def hall_for(asym, z0=HALL_Z0):
    """The half-range d whose ends' secants are asym apart."""
    return brentq(lambda d: float(hall_reading(1.0, d, z0) + hall_reading(-1.0, d, z0)) - asym, 1e-4, z0 - 1e-3,
                  xtol=1e-15)


# ---- saturation: the isolation amplifier's soft output stage (Rapp's limiter) ----
#
# The indicator's analogue output passes an isolation amplifier whose output stage approaches its rails softly: the
# limiter of Rapp's form x / (1 + |x / x_s|^(2 p))^(1 / (2 p)) (Rapp, Proc. 2nd Eur. Conf. Satellite Commun., 1991, for
# a solid-state amplifier's compression; p the knee's sharpness, 1.5 ... 3 here), the reading's middle nulled at the
# amplifier's middle. Over the stroke s (-1 ... 1, slope 1 at 0): s / (1 + |z s|^(2 p))^(1 / (2 p)), the ends
# compressed by 1 - (1 + z^(2 p))^(-1 / (2 p)).

def rapp(s, z, p):
    """s / (1 + |z s|^(2 p))^(1 / (2 p))."""
    s = np.asarray(s, float)
    return s / (1.0 + np.abs(z * s) ** (2 * p)) ** (1.0 / (2 * p))


def rapp_for(comp, p):
    """The z with 1 - (1 + z^(2 p))^(-1 / (2 p)) = comp."""
    return ((1.0 - comp) ** (-2 * p) - 1.0) ** (1.0 / (2 * p))


# ---- delay: the indicator's integrating converter (its aperture) and its readout latency ----
#
# The indicator's capacitive scale is read by an integrating converter: each reading is the mean of the lift over an
# aperture of A sample intervals (0.6 ... 1 here), and it reaches the logger L whole samples later (the indicator's
# serial frame and the logger's buffer, 1 ... 3): the mean over [t - (L + A) dt, t - L dt], a delay of L + A / 2
# samples. Computed from the lift on a grid R_FINE times finer (the mean of a piecewise-linear signal over the
# aperture, exact by the trapezoidal rule on the fine grid when A dt is a whole number of fine steps).

R_FINE = 10


def aperture_mean(y_fine, A_fine, latency, r=R_FINE):
    """The mean of y_fine (on the fine grid, piecewise linear, at rest before its start) over the A_fine fine steps
    ending latency r fine steps before each r-th fine sample: the reading on the logger's grid."""
    y = np.asarray(y_fine, float)
    pad = np.r_[np.full(A_fine + latency * r, y[0]), y]
    c = np.r_[0.0, np.cumsum((pad[1:] + pad[:-1]) / 2)]       # trapezoid integral to each fine node
    idx = np.arange(A_fine + latency * r, len(pad), r)          # the fine nodes of the logger's samples (in pad)
    hi = idx - latency * r
    lo = hi - A_fine
    return (c[hi] - c[lo]) / A_fine


# ---- out of vocabulary: the enclosure's fan cycling on its thermostat ----
#
# A cooling fan in the rig's enclosure switches on and off on its own thermostat (on for 0.8 ... 2.5 s, off for 1 ...
# 3 s) and blows across the oil channel's thin lid: the wire runs cooler by D (4 ... 7 K) while it runs, reached and lost
# with the wire's thermal time constant (a first-order lag, 40 ... 90 ms). The record carries the controller's set-point,
# not the wire's temperature: no map of the recorded drive draws it.

def fan_cooling(t, D, tau, on_range, off_range, rng):
    """The wire's cooling (K) by the fan, and its on intervals [(start, length)]: a first-order lag of D times the fan's
    on/off state (held over each sample), exact between samples."""
    t = np.asarray(t, float)
    ivs, on = on_off_intervals(t, on_range, off_range, rng)
    target = D * on
    out = np.zeros(len(t))
    x = 0.0
    for k in range(1, len(t)):
        h = t[k] - t[k - 1]
        x = target[k - 1] + (x - target[k - 1]) * math.exp(-h / tau)
        out[k] = x
    return out, ivs


__all__ = ["segments", "wire", "feedback", "virgin", "fraction", "lagged_fraction", "lift", "avrami_step",
           "avrami_ramp", "afterrun", "chain_rise", "magnet_field", "hall_reading", "hall_for", "rapp", "rapp_for",
           "aperture_mean", "fan_cooling"]

"""Mechanisms of the HOLDOUT41 set (``cases_holdout41.py``), each written from its law; the signals are in
:mod:`.signals41`.

Nothing here imports hystcomp (nor another set's mechanisms). Every mechanism takes the (clean) drive's field, or the
core's output, and returns the response; all are causal.

Citations: every source below was written from memory in this session (none was re-read); volumes, pages and years may
be off. The laws do not rest on them: each is checked in tests/test_realistic_holdout41.py against an independent
solution (the walls moved by a brute-force search of their force from its definition, solve_ivp of the walls'
overdamped motion, quad, brentq, Jones matrices, the decimator's integrator-comb structure and the Weiss law's
closed inverse).
"""

import math

import numpy as np
from numba import njit
from scipy.optimize import brentq
from scipy.signal import fftconvolve
from scipy.special import erfcx, lambertw


# ---- the rate-independent core: Neel's pinned domain walls in a Mn-Zn ferrite toroid, read by a fluxmeter ----
#
# A sintered Mn-Zn ferrite toroid with a primary winding fed by a transconductance amplifier (its field proportional to
# the drive) and a secondary winding read by an electronic fluxmeter (an integrator of the winding's EMF), times a drawn
# gain. Every grain holds one 180 deg domain wall; the wall's position x in its grain (in units of the grain's half
# width, 0 its middle) is held by the grain's magnetostatic energy k x^2 / 2 (the demagnetising field of the displaced
# wall, a restoring force -k x) and pinned by the defects it crosses: a random pinning force W(x), stationary, Gaussian,
# with a correlation length ell (Neel, Cahiers Phys. 12 (1942) 1 and 13 (1943) 18: walls in a random potential, the
# origin of Rayleigh's law; Alessandro, Beatrice, Bertotti & Montorsi, J. Appl. Phys. 68 (1990) 2901: a wall in a random
# pinning field with a demagnetising restoring term, the ABBM model, whose quasi-static limit this is). The field h
# pushes the wall: it rests where h - k x - W(x) = 0 with the force falling through zero (a stable rest), and when h
# changes it slides, overdamped, in the direction of the force to the first place where the force vanishes (Barkhausen
# jumps where the landscape's slope beats k). The reading is the grains' mean x plus chi h (the reversible rotation in
# the walls' domains and the winding's own air flux), times a gain.
#
# Each grain's landscape: white noise on a grid of step ell / 10 over -3.5 ... 3.5 (ell 0.04), smoothed by a Gaussian of
# width ell, scaled to the spread sigma_i (log-normal about 1, the log's spread 0.1: fields in units of the median
# pinning spread), linear between the nodes (so the force is piecewise linear and each rest is found exactly); k_i
# log-normal about 3 (the log's spread 0.15). 400 grains (a jump of one wall moves the mean by at most ~1e-4 of its
# span: far below the noise).
#
# Rate independent (the quasi-static limit: each rest depends only on the field's path, not its speed), with
# return-point memory (a single coordinate pushed by a force that rises with h: "no passing", Middleton, Phys. Rev.
# Lett. 68 (1992) 670; Sethna et al., Phys. Rev. Lett. 70 (1993) 3347), but not a Prandtl-Ishlinskii model: the walls'
# thresholds are fixed places of the landscape, not distances from the last reversal, and a wall has many rests. The
# virgin (thermally demagnetised) state: every wall at the first rest from its grain's middle at h = 0.

L_EDGE = 3.5
ELL = 0.04
N_GRAINS = 400


def landscape(seed, n=N_GRAINS, ell=ELL, sig_spread=0.1, k=3.0, k_spread=0.15):
    """The grains' pinning forces on their grid (n x nodes), the grid's step and left end, and their k (n)."""
    rng = np.random.default_rng(seed)
    dx = ell / 10
    m = int(round(2 * L_EDGE / dx)) + 1
    pad = 60
    white = rng.standard_normal((n, m + 2 * pad))
    ker = np.exp(-0.5 * (np.arange(-pad, pad + 1) * dx / ell) ** 2)
    W = fftconvolve(white, ker[None, :], mode="valid", axes=1)
    W /= W.std(axis=1, keepdims=True)
    W *= np.exp(sig_spread * rng.standard_normal(n))[:, None]
    kk = k * np.exp(k_spread * rng.standard_normal(n))
    return np.ascontiguousarray(W), dx, -L_EDGE, kk


@njit(cache=True)
def _walls_run(hs, W, dx, x0, kk, xs, js):
    """Every wall slid to its first rest in the direction of its force at each field of hs (xs the positions, js their
    cells, updated in place); returns the mean position at each field."""
    n, m = W.shape
    out = np.empty(hs.shape[0])
    for t in range(hs.shape[0]):
        h = hs[t]
        acc = 0.0
        for i in range(n):
            x = xs[i]
            j = js[i]
            k = kk[i]
            # the force at x: h - k x - W(x), W linear in the cell [x0 + j dx, x0 + (j + 1) dx]
            xl = x0 + j * dx
            s = (W[i, j + 1] - W[i, j]) / dx
            f = h - k * x - (W[i, j] + s * (x - xl))
            if f > 0.0:
                while True:
                    xr = x0 + (j + 1) * dx
                    fr = h - k * xr - W[i, j + 1]
                    if fr <= 0.0:
                        # the root of the linear force in (x, xr]
                        s = (W[i, j + 1] - W[i, j]) / dx
                        a = k + s                        # the force falls at the rate a (> 0 here)
                        x = x + f / a
                        if x > xr:
                            x = xr
                        if x >= xr and j + 1 < m - 1:
                            j += 1
                        break
                    if j + 2 >= m:
                        x = xr
                        break
                    j += 1
                    x = xr
                    f = fr
            elif f < 0.0:
                while True:
                    xl = x0 + j * dx
                    fl = h - k * xl - W[i, j]
                    if fl >= 0.0:
                        s = (W[i, j + 1] - W[i, j]) / dx
                        a = k + s
                        x = x + f / a
                        if x < xl:
                            x = xl
                        break
                    if j == 0:
                        x = xl
                        break
                    j -= 1
                    x = xl
                    f = fl
            xs[i] = x
            js[i] = j
            acc += x
        out[t] = acc / n
    return out


def core_walls(core):
    """The core's landscape (W, dx, x0, k), cached on the core's dict."""
    key = (core["lseed"], core.get("n", N_GRAINS))
    cache = core.setdefault("_walls", {})
    if key not in cache:
        cache.clear()
        cache[key] = landscape(core["lseed"], n=key[1])
    return cache[key]


def cell_of(x, dx, x0, m):
    """The cells holding the positions x (the left node's index, at most m - 2)."""
    return np.clip(np.floor((np.asarray(x, float) - x0) / dx).astype(np.int64), 0, m - 2)


def virgin(core):
    """The thermally demagnetised walls: each slid from its grain's middle to its first rest at h = 0."""
    W, dx, x0, kk = core_walls(core)
    xs = np.zeros(W.shape[0])
    js = cell_of(xs, dx, x0, W.shape[1])
    _walls_run(np.zeros(1), W, dx, x0, kk, xs, js)
    return xs


def walls(core, h, state=None, return_state=False):
    """The walls' mean position along the fields h (units of the median pinning spread), from the positions state
    (default the virgin walls); with return_state also the positions at the end."""
    W, dx, x0, kk = core_walls(core)
    xs = virgin(core) if state is None else np.array(state, float)
    js = cell_of(xs, dx, x0, W.shape[1])
    out = _walls_run(np.asarray(h, float), W, dx, x0, kk, xs, js)
    return (out, xs) if return_state else out


def reading(core, h, xm):
    """The fluxmeter's reading (before the offset): gain (mean x + chi h)."""
    return core["gain"] * (np.asarray(xm, float) + core["chi"] * np.asarray(h, float))


# ---- rate dependence: the walls' finite mobility (the ABBM model's own dynamics) ----
#
# A moving wall is damped by the eddy currents and spin relaxation it stirs up: it moves at a speed proportional to the
# net force on it, Gamma dx/dt = h - k x - W(x) (Alessandro, Beatrice, Bertotti & Montorsi 1990; Bertotti, *Hysteresis
# in Magnetism*, 1998, ch. 9), so it lags its quasi-static rest by about tau_w = Gamma / k (3 ... 6 ms here) and a
# Barkhausen jump takes a finite time. Solved here exactly for the field held at its midpoint value over each of nsub
# substeps a sample (the force is linear in x within a cell of the landscape: the motion there is an exponential, and
# the time it takes to reach the cell's boundary is found in closed form), from the walls' rests.

@njit(cache=True)
def _mobile_run(hs, W, dx, x0, kk, xs, js, gam, nsub):
    n, m = W.shape
    out = np.empty(hs.shape[0])
    s0 = 0.0
    for i in range(n):
        s0 += xs[i]
    out[0] = s0 / n
    d = 1.0 / nsub
    for t in range(1, hs.shape[0]):
        acc = 0.0
        for i in range(n):
            x = xs[i]
            j = js[i]
            k = kk[i]
            for q in range(nsub):
                h = hs[t - 1] + (q + 0.5) * d * (hs[t] - hs[t - 1])
                left = d                                   # the substep's time left (in samples)
                for _ in range(100000):
                    xl = x0 + j * dx
                    s = (W[i, j + 1] - W[i, j]) / dx
                    f = h - k * x - (W[i, j] + s * (x - xl))
                    if f == 0.0:
                        break
                    a = k + s
                    if f > 0.0:
                        xb = xl + dx
                        if j + 2 >= m:                     # the grid's end: no further
                            break
                    else:
                        xb = xl
                        if j == 0:
                            break
                    # the time to the cell's boundary xb on x(tau) = x_eq + (x - x_eq) exp(-a tau / gam)
                    if a != 0.0:
                        xe = x + f / a
                        if xe == x:                        # at rest to rounding
                            break
                        ratio = (xb - xe) / (x - xe)
                        tb = -gam / a * math.log(ratio) if ratio > 0.0 else 1e300
                    else:
                        tb = (xb - x) * gam / f
                    if tb >= left:
                        if a != 0.0:
                            x = xe + (x - xe) * math.exp(-a * left / gam)
                        else:
                            x += f * left / gam
                        break
                    left -= tb
                    x = xb
                    if f > 0.0:
                        j += 1
                    else:
                        j -= 1
            xs[i] = x
            js[i] = j
            acc += x
        out[t] = acc / n
    return out


def mobile_walls(core, h, dt, tau_w, nsub=16, state=None):
    """The walls' mean position along the fields h (sampled dt apart) with the mobility Gamma = tau_w k_median: from
    the walls' rests at h[0] (default the virgin walls, h[0] = 0)."""
    W, dx, x0, kk = core_walls(core)
    h = np.asarray(h, float)
    xs = virgin(core) if state is None else np.array(state, float)
    js = cell_of(xs, dx, x0, W.shape[1])
    gam = tau_w * float(np.median(kk)) / dt                  # Gamma over the sample interval
    return _mobile_run(h, W, dx, x0, kk, xs, js, gam, int(nsub))


# ---- creep: the diffusion after-effect of the moved walls ----
#
# A wall that has moved is stabilised in its new place by mobile ions (the Fe2+-vacancy pairs of a Mn-Zn ferrite)
# rearranging around it (Neel's diffusion after-effect, J. Phys. Radium 13 (1952) 249; the disaccommodation of ferrites,
# e.g. Ohta, J. Phys. Soc. Japan 18 (1963) 685); here they reach it by diffusion from the grain's interior through the
# wall's surface layer, a half-space behind a surface barrier, whose fractional uptake after a step is phi(t) = 1 -
# exp(t / tau) erfc(sqrt(t / tau)) (Carslaw & Jaeger, *Conduction of Heat in Solids*, 1959, section 2.7, the surface
# under a heat-transfer coefficient): sqrt(t) at first, a 1 / sqrt(t) tail. The walls' mean position creeps on by kappa
# phi times each of its increments (Boltzmann's superposition; kappa 0.25 ... 0.35, tau 0.4 ... 1.5 s), exact for the
# position linear between samples: a sample's kernel is the ramp response R(t) = int_0^t phi = t - tau (erfcx(u) + 2 u /
# sqrt(pi) - 1), u = sqrt(t / tau), differenced.

def diffusion_step(t, tau):
    """phi(t) = 1 - exp(t / tau) erfc(sqrt(t / tau)) (0 at t = 0, 1 at infinity)."""
    return 1.0 - erfcx(np.sqrt(np.maximum(np.asarray(t, float), 0.0) / tau))


def diffusion_ramp(t, tau):
    """int_0^t phi(s) ds = t - tau (erfcx(u) + 2 u / sqrt(pi) - 1), u = sqrt(t / tau)."""
    t = np.maximum(np.asarray(t, float), 0.0)
    u = np.sqrt(t / tau)
    return t - tau * (erfcx(u) + 2.0 * u / math.sqrt(math.pi) - 1.0)


def aftereffect(xm, dt, kappa, tau):
    """kappa times the superposed uptake of the increments of xm (linear between samples): 0 at the start."""
    xm = np.asarray(xm, float)
    n = len(xm)
    R = diffusion_ramp(np.arange(n + 1) * dt, tau)
    g = np.diff(R) / dt                                       # g[k - 1]: a unit ramp over [0, dt], seen k samples on
    du = np.diff(xm)                                          # the ramp over [t_m, t_m+1]
    # at t_n: sum_m du_m (R(t_n - t_m) - R(t_n - t_m+1)) / dt, i.e. du convolved with r_k = (R(k dt) - R((k-1) dt)) / dt
    # for k = n - m >= 1
    c = np.zeros(n)
    if n > 1:
        c[1:] = fftconvolve(du, g)[:n - 1]
    return kappa * c


# ---- drift: the fluxmeter's integrator offset as it warms ----
#
# The fluxmeter integrates the winding's EMF on a capacitor; its input amplifier's offset voltage, trimmed to zero at
# the record's start, drifts by its temperature coefficient (a few uV/K: e.g. Horowitz & Hill, *The Art of
# Electronics*, the precision op-amp chapter) as the instrument warms after switch-on, a two-body warm-up (the chip and
# the case): dT(t) = dT_inf (1 - a exp(-t / tau1) - (1 - a) exp(-t / tau2)). The integrated offset, F(t) = int_0^t dT /
# dT_inf = t - a tau1 (1 - exp(-t / tau1)) - (1 - a) tau2 (1 - exp(-t / tau2)): quadratic at first, then a ramp.

def warmup_integral(t, a, tau1, tau2):
    """F(t) = t - a tau1 (1 - exp(-t / tau1)) - (1 - a) tau2 (1 - exp(-t / tau2))."""
    t = np.asarray(t, float)
    return t - a * tau1 * (-np.expm1(-t / tau1)) - (1 - a) * tau2 * (-np.expm1(-t / tau2))


# ---- asymmetry: the logger's input stage, an emitter-degenerated bipolar transistor ----
#
# The reading enters the logger through a single common-emitter stage with an emitter resistor R_E (Ebers & Moll, Proc.
# IRE 42 (1954) 1761: I_C = I_S exp(V_BE / V_T)): a signal v moves the collector current by i with v / V_T = ln(1 + i /
# I_Q) + r i / I_Q, r = R_E I_Q / V_T. In closed form i / I_Q = W0(r exp(r + v / V_T)) / r - 1 (W0 Lambert's function),
# convex in v. Over the reading's stroke s (-1 ... 1, slope 1 at 0): f(s) = (1 + r) (W0(r exp(r + b s)) / r - 1) / b, b
# the stroke in V_T; the ends' secants f(1) + f(-1) apart (12 ... 18 % here).

def bjt_reading(s, r, b):
    """(1 + r) (W0(r exp(r + b s)) / r - 1) / b."""
    s = np.asarray(s, float)
    return (1.0 + r) * (np.real(lambertw(r * np.exp(r + b * s))) / r - 1.0) / b


def bjt_for(asym, r):
    """The stroke b (in V_T) whose ends' secants are asym apart, at the degeneration r."""
    return brentq(lambda b: float(bjt_reading(1.0, r, b) + bjt_reading(-1.0, r, b)) - asym, 1e-3, 200.0, xtol=1e-14)


# ---- saturation: a balanced Faraday polarimeter reading the flux ----
#
# The flux is read magneto-optically: a garnet film in a slit of the toroid turns a laser's polarisation by theta =
# V_F B (Faraday's effect), and a Wollaston prism at 45 deg splits it on two photodiodes, whose normalised difference is
# (I1 - I2) / (I1 + I2) = sin(2 theta) (Malus's law on either beam). Over the reading's stroke s (-1 ... 1, slope 1 at
# 0): sin(z s) / z, z the stroke's angle 2 theta_max; the ends compressed by 1 - sin(z) / z (10 ... 18 % here).

def polarimeter_reading(s, z):
    """sin(z s) / z."""
    return np.sin(z * np.asarray(s, float)) / z


def polarimeter_for(comp):
    """The z with 1 - sin(z) / z = comp."""
    return brentq(lambda z: 1.0 - math.sin(z) / z - comp, 1e-6, math.pi / 2, xtol=1e-15)


# ---- delay: the fluxmeter's sigma-delta converter, a sinc^3 decimator and a pipeline ----
#
# The fluxmeter digitises with a sigma-delta converter: its modulator runs R_DEC = 8 times the logger's rate, and the
# decimator is a third-order cascaded integrator-comb (sinc^3) filter (Hogenauer, IEEE Trans. ASSP 29 (1981) 155): three
# moving sums of R_DEC modulator samples in cascade, normalised to unit DC gain, taken every R_DEC-th sample; a
# linear-phase filter of group delay 3 (R_DEC - 1) / 2 modulator samples (21 / 16 of a logger sample). The samples then
# wait L whole samples in the converter's and the logger's pipeline (1 ... 4): a delay of L + 21 / 16 samples. The core
# is computed on the modulator's grid.

R_DEC = 8


def sinc3_kernel(r=R_DEC):
    """The sinc^3 filter's impulse response (3 r - 2 taps, unit sum)."""
    box = np.ones(r) / r
    return np.convolve(np.convolve(box, box), box)


def sinc3_decimate(u_fine, latency, r=R_DEC):
    """The decimator's output on the logger's grid: u_fine (on the modulator's grid, from rest at u_fine[0]) filtered by
    the sinc^3 kernel, every r-th sample, then held back latency samples (the first value before)."""
    u = np.asarray(u_fine, float)
    kern = sinc3_kernel(r)
    pad = np.r_[np.full(len(kern) - 1, u[0]), u]
    y = np.convolve(pad, kern, mode="valid")[::r]
    return np.r_[np.full(latency, y[0]), y[:len(y) - latency]]


# ---- gain drift: the ferrite's saturation magnetisation as the core warms ----
#
# The toroid warms by its hysteresis loss and the winding's copper loss: T(t) = T0 + dT (1 - exp(-t / tau_h)). A
# Mn-Zn ferrite's saturation magnetisation falls with temperature towards its Curie point T_c (about 490 K); in the
# mean-field (Weiss) theory with spin 1/2, m = M_s(T) / M_s(0) solves m = tanh(m T_c / T) (Weiss, J. Phys. 6 (1907)
# 661; e.g. Kittel, *Introduction to Solid State Physics*, ch. 11). The flux every wall sweeps scales with M_s, so the
# reading's gain follows m(T(t)) / m(T0) (the walls' rests are taken unchanged: the field is scaled alike).

def weiss_m(T, Tc):
    """The reduced magnetisation m(T) > 0 solving m = tanh(m Tc / T) (T < Tc), by brentq."""
    return np.array([brentq(lambda m: m - math.tanh(m * Tc / x), 1e-9, 1.0, xtol=1e-15) for x in np.atleast_1d(T)])


def weiss_gain(t, T0, dT, tau_h, Tc):
    """m(T(t)) / m(T0) with T(t) = T0 + dT (1 - exp(-t / tau_h)) (tabulated on 400 temperatures and interpolated
    linearly in T)."""
    t = np.asarray(t, float)
    T = T0 + dT * (-np.expm1(-t / tau_h))
    Tg = np.linspace(T0, T0 + dT, 400)
    mg = weiss_m(Tg, Tc)
    return np.interp(T, Tg, mg) / mg[0]


def weiss_dT_for(drop, T0, Tc):
    """The warming dT at which the gain has fallen by drop."""
    m0 = weiss_m(T0, Tc)[0]
    return brentq(lambda d: weiss_m(T0 + d, Tc)[0] / m0 - (1.0 - drop), 1e-6, Tc - T0 - 1e-6, xtol=1e-12)


# ---- out of vocabulary: an intermittent contact in the primary's lead ----
#
# The primary's lead has a worn banana plug: now and then (0.2 ... 0.5 times a second, as the rig's table is jostled)
# it opens for 4 ... 30 ms and the transconductance amplifier's current, and the field, drop to 0 while the amplifier's
# monitor output (what the logger records as the input) keeps the commanded drive. The core sees a field the record does
# not carry: each opening pulls the flux towards its remanence and leaves the walls on a minor loop.

def contact_mask(t, rate, dmin, dmax, rng):
    """A boolean mask of the samples t at which the contact is open (Poisson openings at rate a second, lengths uniform
    in dmin ... dmax s), and the openings [(start, length)]."""
    t = np.asarray(t, float)
    opens, s = [], float(rng.exponential(1.0 / rate))
    while s < t[-1] - dmax:
        d = float(rng.uniform(dmin, dmax))
        opens.append((s, d))
        s += d + float(rng.exponential(1.0 / rate))
    mask = np.zeros(len(t), bool)
    for a, d in opens:
        mask |= (t >= a) & (t < a + d)
    return mask, opens

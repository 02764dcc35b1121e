"""Mechanisms of the HOLDOUT22 set (``cases_holdout22.py``), each written from its law; the signals are in
:mod:`.signals22`.

Nothing here imports hystcomp. Every mechanism takes the (clean) drive, or the core's output, and returns the response;
all are causal. The play, its threshold grid, a path's turning points and the raised cosine are the earlier sets' (the
same laws, imported as mechanisms21 does).

Citations: every source below was written from memory in this session (none was re-read); volumes, pages and years may
be off. The laws do not rest on them: each is checked in tests/test_realistic_holdout22.py against an independent
solution (a closed form, quadrature, brentq, solve_ivp or a finer simulation).
"""

import math

import numpy as np
from numpy.lib.stride_tricks import sliding_window_view
from scipy.signal import fftconvolve
from scipy.special import ndtr

from .mechanisms13 import turning_points  # noqa: F401
from .mechanisms18 import exp_plays, grid, plays  # noqa: F401
from .mechanisms19 import raised_cosine  # noqa: F401


# ---- the rate-independent core ----

def fatiguelife_plays(n, r_max, scale, shape, w0):
    """Thresholds on :func:`grid` weighted by the Birnbaum-Saunders (fatigue-life) density (x + 1) / (2 g sqrt(2 pi
    x^3)) exp(-(x - 1)^2 / (2 x g^2)), x = r / scale, g the shape (Birnbaum & Saunders, J. Appl. Probab. 6 (1969) 319:
    the time for accumulated random increments to cross a threshold; here the strength of a pinning site built up by
    many small obstacles): a hump with a long right tail; summing to 1 - w0."""
    r = grid(n, r_max)
    x = r / scale
    dens = (x + 1) / (2 * shape * np.sqrt(2 * np.pi * x ** 3)) * np.exp(-(x - 1) ** 2 / (2 * x * shape ** 2))
    return r, (1 - w0) * dens / dens.sum()


# ---- creep: the Jeffreys-Lomnitz law ----

def jeffreys_lomnitz(t, tau, alpha):
    """The creep compliance ((1 + t / tau)^alpha - 1) / alpha (Lomnitz, J. Geol. 64 (1956) 473 found ln(1 + t / tau)
    for rocks; Jeffreys, Geophys. J. R. Astron. Soc. 1 (1958) 92 generalised it with a power alpha > 0): linear at
    first, t^alpha later, unbounded; alpha -> 0 gives Lomnitz's logarithm."""
    t = np.clip(np.asarray(t, float), 0, None)
    return np.expm1(alpha * np.log1p(t / tau)) / alpha


def jeffreys_lomnitz_integral(x, tau, alpha):
    """K(x) = int_0^x J: (tau / (alpha + 1) ((1 + x / tau)^(alpha + 1) - 1) - x) / alpha."""
    x = np.clip(np.asarray(x, float), 0, None)
    return (tau / (alpha + 1) * np.expm1((alpha + 1) * np.log1p(x / tau)) - x) / alpha


def jl_creep(h, dt, c, tau, alpha, t_ref):
    """c x the Boltzmann superposition of J / J(t_ref) over the load h (the core's output), exact for h linear between
    samples: creep_i = sum_m w_m (h_{i - m} - h_{i - m - 1}), w_m = (K((m + 1) dt) - K(m dt)) / dt / J(t_ref), by FFT
    convolution; 0 at the first sample (at rest before it)."""
    h = np.asarray(h, float)
    n = len(h)
    x = np.arange(n + 1) * dt
    K = jeffreys_lomnitz_integral(x, tau, alpha)
    w = np.diff(K) / dt / float(jeffreys_lomnitz(t_ref, tau, alpha))
    out = np.zeros(n)
    out[1:] = fftconvolve(np.diff(h), w[:n - 1])[:n - 1]
    return c * out


# ---- rate dependence: a closed air chamber exchanging heat with its walls ----

def air_spring_stage(h, dt, L, kappa, gamma, tau_th):
    """The stage pressed by the stack (its free stroke h, the core's output; stiffness k_s) against a piston closing an
    air chamber (V0 = A L at rest, the air at the wall's temperature and p0). Force: k_s (h - y) = A (p - p0); the
    gas: ideal, its temperature by the first law with Newton's heat exchange, m c_v T' = -p V' + hA (T_w - T) (the
    thermal time constant tau_th = m c_v / hA of pneumatic chambers, e.g. Richer & Hurmuzlu, J. Dyn. Syst. Meas.
    Control 122 (2000) 416): isothermal (stiffness k_i = p0 A / L) when slow, adiabatic (gamma k_i) when fast.
    Dimensionless u = y / L, eta = h / L, P = p / p0, theta = T / T_w, kappa = k_i / k_s: eta - u = kappa (P - 1), P =
    theta / (1 - u), and sigma = ln(theta (1 - u)^(gamma - 1)) obeys sigma' = (1 / theta - 1) / tau_th. Classical
    Runge-Kutta on sigma (eta linear between samples), u by Newton on eta - u - kappa (exp(sigma) (1 - u)^-gamma - 1)
    = 0 (decreasing, concave) at every stage; from the isothermal equilibrium at h[0]. Returns y = L u."""
    eta = (np.asarray(h, float) / L).tolist()
    g1 = gamma - 1

    def solve_u(sig, et, u):
        es = math.exp(sig)
        for _ in range(3):
            q = es * (1 - u) ** -gamma
            u -= (et - u - kappa * (q - 1)) / (-1 - kappa * gamma * q / (1 - u))
        return u

    def rate(sig, u):
        return (math.exp(-sig) * (1 - u) ** g1 - 1) / tau_th

    u = 0.0
    for _ in range(60):                                # the isothermal start: eta - u = kappa u / (1 - u)
        u -= (eta[0] - u - kappa * u / (1 - u)) / (-1 - kappa / (1 - u) ** 2)
    sig = g1 * math.log(1 - u)
    out = [u]
    for k in range(1, len(eta)):
        e0, e1 = eta[k - 1], eta[k]
        em = 0.5 * (e0 + e1)
        k1 = rate(sig, u)
        u2 = solve_u(sig + 0.5 * dt * k1, em, u)
        k2 = rate(sig + 0.5 * dt * k1, u2)
        u3 = solve_u(sig + 0.5 * dt * k2, em, u2)
        k3 = rate(sig + 0.5 * dt * k2, u3)
        u4 = solve_u(sig + dt * k3, e1, u3)
        k4 = rate(sig + dt * k3, u4)
        sig += dt * (k1 + 2 * k2 + 2 * k3 + k4) / 6
        u = solve_u(sig, e1, u4)
        out.append(u)
    return L * np.array(out)


# ---- offset drift: thermoelectric EMFs of a strain-gauge bridge under a heat lamp ----

def lamp_response(s, tau1, tau2):
    """The step response of the junctions' temperature difference: the near solder tab follows the lamp through
    tau1, the far one follows the near one through tau2 (a two-node thermal network), the EMF S (T_near - T_far)
    (Seebeck: copper leads on a constantan foil, about 40 uV/K; e.g. Hoffmann, *An Introduction to Measurements using
    Strain Gages*, 1989, on thermal EMFs): tau2 / (tau2 - tau1) (exp(-s / tau2) - exp(-s / tau1)), 0 before."""
    s = np.asarray(s, float)
    sp = np.clip(s, 0, None)
    return np.where(s > 0, tau2 / (tau2 - tau1) * (np.exp(-sp / tau2) - np.exp(-sp / tau1)), 0.0)


def lamp_offset(t, switches, tau1, tau2):
    """The bridge's offset for the lamp switched on (+1) and off (-1) at the given (time, sign) pairs: the
    superposition of :func:`lamp_response` (each on a rise and a decay back while the lamp stays on or off)."""
    t = np.asarray(t, float)
    out = np.zeros_like(t)
    for ts, sg in switches:
        out += sg * lamp_response(t - ts, tau1, tau2)
    return out


# ---- asymmetry: a photodiode read at open circuit behind a graded filter ----

def photodiode_reading(u, a, rho):
    """The open-circuit voltage of a photodiode, n V_T ln(1 + I / I_s) (Shockley's diode with the photocurrent; Sze,
    *Physics of Semiconductor Devices*, 1981, ch. 14), its light passing a linear graded filter carried by the stage
    (I = I_b (1 + a u), u the stage's travel over its largest, rho = I_b / I_s): (ln(1 + rho (1 + a u)) - ln(1 +
    rho)) / (a rho / (1 + rho)), slope 1 at u = 0; concave (the top compressed)."""
    u = np.asarray(u, float)
    return np.log1p(rho * a * u / (1 + rho)) / (a * rho / (1 + rho))


# ---- saturation: the centroid of a Gaussian spot on a finite detector ----

def spot_centroid(x, s):
    """The centroid read by a line sensor of half-width 1 under a Gaussian spot (standard deviation s) centred at x:
    the mean of the normal law truncated to [-1, 1], x + s (phi(a) - phi(b)) / (Phi(b) - Phi(a)), a = (-1 - x) / s,
    b = (1 - x) / s (Johnson, Kotz & Balakrishnan, *Continuous Univariate Distributions*, 1994, ch. 13): the spot's tail
    falling off the sensor pulls the reading in; odd."""
    x = np.asarray(x, float)
    a, b = (-1 - x) / s, (1 - x) / s
    pa, pb = np.exp(-a * a / 2), np.exp(-b * b / 2)
    return x + s * (pa - pb) / math.sqrt(2 * math.pi) / (ndtr(b) - ndtr(a))


def centroid_slope0(s):
    """d centroid / dx at x = 0: the truncated variance over s^2, 1 - 2 b phi(b) / (2 Phi(b) - 1), b = 1 / s."""
    b = 1 / s
    return 1 - 2 * b * math.exp(-b * b / 2) / math.sqrt(2 * math.pi) / (2 * ndtr(b) - 1)


def centroid_reading(h, centre, F, s):
    """The reading in the core's units, slope 1 at the centre: centre + F / c'(0) centroid((h - centre) / F)."""
    return centre + F / centroid_slope0(s) * spot_centroid((np.asarray(h, float) - centre) / F, s)


# ---- delay: a smart sensor's running median ----

def median_sensor(h_fine, sub, N, D):
    """A sensor sampling the stage `sub` times per record sample (h_fine, the core's output on that grid), rejecting
    spikes by a running median of its last N samples (Tukey, *Exploratory Data Analysis*, 1977; odd N), each result
    delivered D of its samples later; the logger at t_i reads the result of sample i sub - D: the median of h_fine[i
    sub - D - N + 1 ... i sub - D] (h_fine[0] before the start). On a monotone stretch that is the middle sample: a
    delay of (D + (N - 1) / 2) / sub record samples."""
    h_fine = np.asarray(h_fine, float)
    pad = np.r_[np.full(N - 1 + D, h_fine[0]), h_fine]
    n = (len(h_fine) - 1) // sub + 1
    win = sliding_window_view(pad, N)[::sub][:n]
    return np.median(win, axis=1)


# ---- two effects: a hydraulic damper with a blow-off valve, an LVDT's demodulator slipping in phase ----

def blowoff_stage(h, dt, tau1, tau2, v_b):
    """The stage behind the core's flexure (h its free stroke) held back by a hydraulic damper with a blow-off
    (pressure-relief) valve: k (h - y) = F(y'), F = c1 v for |v| <= v_b, +-(c1 v_b + c2 (|v| - v_b)) beyond (the
    digressive characteristic of a valved damper; Dixon, *The Shock Absorber Handbook*, 2007): with e = h - y, y' =
    e / tau1 for |e| <= e_b = v_b tau1, else +-(v_b + (|e| - e_b) / tau2). Exact for h linear between samples: in each
    branch e relaxes exponentially to that branch's fixed point; a crossing of +-e_b is found in closed form and the
    other branch taken from there. From rest at h[0]."""
    h = np.asarray(h, float).tolist()
    e_b = v_b * tau1
    e = 0.0
    out = [h[0]]
    for k in range(1, len(h)):
        s = (h[k] - h[k - 1]) / dt
        ef = s * tau1 if abs(s) <= v_b else math.copysign(e_b + (abs(s) - v_b) * tau2, s)   # G^-1(s): where e heads
        rem = dt
        while rem > 0 and e != ef:
            up = ef > e
            if e > e_b or (e == e_b and up):           # the valve open, pushing
                tau, estar, bound = tau2, e_b + (s - v_b) * tau2, (math.inf if up else e_b)
            elif e < -e_b or (e == -e_b and not up):   # the valve open, pulling
                tau, estar, bound = tau2, -e_b + (s + v_b) * tau2, (-e_b if up else -math.inf)
            else:                                      # the valve shut
                tau, estar, bound = tau1, s * tau1, (e_b if up else -e_b)
            if math.isfinite(bound) and (bound - e) * (estar - bound) > 0:
                tc = tau * math.log((e - estar) / (bound - estar))
                if tc < rem:                           # crosses into the other branch within the step
                    e, rem = bound, rem - tc
                    continue
            e = estar + (e - estar) * math.exp(-rem / tau)
            rem = 0.0
        out.append(h[k] - e)
    return np.array(out)


def demodulator_gain(t, phi0, df):
    """The gain of a carrier sensor (an LVDT) whose synchronous demodulator's reference runs df Hz off the
    excitation: the output scales with cos of the phase error phi0 + 2 pi df t (a lock-in's in-phase output;
    e.g. Meade, *Lock-in Amplifiers*, 1983)."""
    return np.cos(phi0 + 2 * np.pi * df * np.asarray(t, float))


# ---- out of vocabulary: the slider of an inertia (slip-stick) drive ----

def inertia_slider(h_fine, dt, a_s, a_k):
    """The slider clamped by friction on a rod that the core moves (h_fine, the rod's position on a fine grid; Pohl,
    Rev. Sci. Instrum. 58 (1987) 54): it moves with the rod while the rod's acceleration is within the static limit
    a_s; beyond it slips, the kinetic friction accelerating it by a_k (< a_s) toward the rod's speed, and sticks again
    when the speeds meet and the rod's acceleration is within a_s (Coulomb friction on a rigid rod). The rod's speed
    is linear between the grid's midpoints (its acceleration the second difference over dt^2); the relative speed r is
    then linear in time within each half step, and the slip S = int r dt exact. Returns the slider's position h - S
    on the grid and S."""
    h = np.asarray(h_fine, float)
    m = (np.diff(h) / dt).tolist()                     # the rod's speed at the midpoints
    n = len(h)
    S = [0.0] * n
    r, slip = 0.0, 0.0
    half = dt / 2
    for k in range(1, n - 1):
        a = (m[k] - m[k - 1]) / dt                     # constant over [t_k - dt/2, t_k + dt/2]
        for part in (0, 1):
            rem = half
            while rem > 0:
                if r == 0.0:
                    if abs(a) <= a_s:
                        break                          # stuck for the rest of the half step
                    acc = a - math.copysign(a_k, a)    # starts slipping the way the rod accelerates
                    slip += 0.5 * acc * rem * rem
                    r = acc * rem
                    rem = 0.0
                    break
                acc = a - math.copysign(a_k, r)
                if acc * r < 0 and -r / acc < rem:     # the speeds meet within the step
                    tc = -r / acc
                    slip += r * tc / 2
                    r, rem = 0.0, rem - tc
                    continue
                slip += r * rem + 0.5 * acc * rem * rem
                r += acc * rem
                rem = 0.0
            if part == 0:
                S[k] = slip
    S[n - 1] = slip
    S = np.array(S)
    return h - S, S


__all__ = ["turning_points", "exp_plays", "grid", "plays", "raised_cosine", "fatiguelife_plays", "jeffreys_lomnitz",
           "jeffreys_lomnitz_integral", "jl_creep", "air_spring_stage", "lamp_response", "lamp_offset",
           "photodiode_reading", "spot_centroid", "centroid_slope0", "centroid_reading", "median_sensor",
           "blowoff_stage", "demodulator_gain", "inertia_slider"]

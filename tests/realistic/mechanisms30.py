"""Mechanisms of the HOLDOUT30 set (``cases_holdout30.py``), each written from its law; the signals are in
:mod:`.signals30`.

Nothing here imports hystcomp. Every mechanism takes the (clean) drive, or the core's output, and returns the response;
all are causal.

Citations: every source below was written from memory in this session (none was re-read); volumes, pages and years may
be off. The laws do not rest on them: each is checked in tests/test_realistic_holdout30.py against an independent
solution (a closed form, quadrature, solve_ivp, an FFT of the transfer function or a finer simulation).
"""

import math

import numpy as np
from numba import njit
from scipy.linalg import eig
from scipy.signal import lfilter
from scipy.special import exp1


# ---- the rate-independent core: a stage bedded on a granular layer (Kondner's hyperbola, Masing's rules) ----

def hyperbolic_skeleton(q, Vm):
    """The extra compliance of a granular (sand) bedding loaded in shear from rest by a drive q (in drive units, Vm
    the drive at which it would fail): Kondner's hyperbola tau = G gamma / (1 + gamma / gamma_r) for soils (Kondner,
    J. Soil Mech. Found. Div. ASCE 89 (1963) 115; Hardin & Drnevich, ibid. 98 (1972) 667), solved for the strain under
    a given stress: gamma = (tau / G) / (1 - |tau| / tau_max). In units where the small-load slope is 1: q / (1 - |q| /
    Vm), |q| < Vm."""
    q = np.asarray(q, float)
    return q / (1.0 - np.abs(q) / Vm)


@njit(cache=True)
def _kondner(v, Vm, c, tpv, tpx, n_tp, u_prev, x_prev, d):
    out = np.empty(len(v))
    tv = np.empty(len(v) + len(tpv) + 2)
    tx = np.empty(len(v) + len(tpv) + 2)
    for j in range(n_tp):
        tv[j] = tpv[j]
        tx[j] = tpx[j]
    m = n_tp
    for k in range(len(v)):
        u = v[k]
        if u != u_prev:
            s = 1 if u > u_prev else -1
            if d != 0 and s != d:
                tv[m] = u_prev
                tx[m] = x_prev
                m += 1
            d = s
            while m > 0:
                if m >= 2:
                    if (u - tv[m - 2]) * d >= 0:
                        m -= 2
                        continue
                elif (u + tv[0]) * d >= 0:
                    m -= 1
                    continue
                break
            if m == 0:
                x_prev = u + c * u / (1.0 - abs(u) / Vm)
            else:
                e = 0.5 * (u - tv[m - 1])
                x_prev = tx[m - 1] + 2.0 * e + 2.0 * c * e / (1.0 - abs(e) / Vm)
            u_prev = u
        out[k] = x_prev
    return out, tv[:m].copy(), tx[:m].copy(), u_prev, x_prev, d


def kondner_core(v, Vm, c, state=None, return_state=False):
    """The stage's travel x under a drive v that sets the shear load on its granular bedding: the actuator's own
    compliance (x = v) in series with the bedding's (c times it at small loads, Kondner's hyperbola). From the virgin
    state x = v + c v / (1 - |v| / Vm); on unloading and reloading Masing's rule (Masing, 1926; for soils Hardin &
    Drnevich 1972): from a reversal at (v_r, x_r) the branch is x_r + (v - v_r) + 2 c e / (1 - |e| / Vm), e = (v - v_r)
    / 2, with Madelung's memory rules (a branch reaching the turning point before its own start closes its loop and
    the branch left there is resumed; one reaching the mirror image of the first turning point rejoins the virgin
    curve). Computed from a stack of turning points, not from plays. ``state`` is (turning points' v, their x, last
    input, last output, last direction) as returned with ``return_state``; None is the virgin state at 0 V."""
    if state is None:
        tpv, tpx, u_prev, x_prev, d = np.zeros(0), np.zeros(0), 0.0, 0.0, 0
    else:
        tpv, tpx = np.asarray(state[0], float), np.asarray(state[1], float)
        u_prev, x_prev, d = float(state[2]), float(state[3]), int(state[4])
    out, tv, tx, u_prev, x_prev, d = _kondner(np.asarray(v, float), float(Vm), float(c), tpv, tpx, len(tpv),
                                              u_prev, x_prev, d)
    if return_state:
        return out, (tv, tx, u_prev, x_prev, d)
    return out


def kondner_density(r, Vm, c):
    """The density of play thresholds r (0 < r < Vm) of the PI model equal to :func:`kondner_core`: the virgin curve's
    second derivative, 2 c / (Vm (1 - r / Vm)^3) (with a linear part 1 + c); used only by the test."""
    return 2.0 * c / (Vm * (1.0 - np.asarray(r, float) / Vm) ** 3)


# ---- creep: a pad of a rubber network swollen with entangled free chains (reptation) ----

def reptation_modes(tau_d, n_modes):
    """Doi & Edwards's relaxation of entangled chains by reptation (de Gennes, J. Chem. Phys. 55 (1971) 572; Doi &
    Edwards, *The Theory of Polymer Dynamics*, 1986, ch. 6): mu(t) = sum over odd p of (8 / (pi^2 p^2)) exp(-p^2 t /
    tau_d). Returns (taus, weights) of the first n_modes odd p (the weights sum to a little below 1)."""
    p = 2.0 * np.arange(n_modes) + 1.0
    return tau_d / p ** 2, 8.0 / (math.pi ** 2 * p ** 2)


def _reptation_system(tau_d, n_modes, r_n):
    taus, w = reptation_modes(tau_d, n_modes)
    g = r_n * w                                  # the modes' moduli over the network's G_e = 1
    G0 = 1.0 + g.sum()
    A = np.outer(g, 1.0 / taus) / G0 - np.diag(1.0 / taus)
    b = g / G0
    return A, b, G0


def reptation_strain(sigma, dt, tau_d, n_modes, r_n):
    """The strain of a pad whose modulus is a rubber network's (G_e = 1) plus entangled free chains' relaxing by
    reptation (G(t) = 1 + r_n mu(t): a generalised Maxwell solid, Wiechert's form) under a stress sigma given at the
    samples and linear between them (the load the stage's core puts on it), at rest before the record: with sigma_p
    the modes' stresses, sigma = eps + sum sigma_p, sigma_p' = g_p eps' - sigma_p / tau_p, so sigma_p' = A sigma_p + b
    sigma' (A = g (1 / tau)^T / G0 - diag(1 / tau), b = g / G0, G0 = 1 + sum g) and eps = sigma - sum sigma_p; solved
    exactly on the eigenvectors of A (the retardation modes), each a first-order filter of the constant sigma' of a
    step."""
    A, b, G0 = _reptation_system(tau_d, n_modes, r_n)
    lam, V = eig(A)
    lam, V = lam.real, V.real
    beta = np.linalg.solve(V, b)
    ones_V = V.sum(axis=0)                       # sum_p sigma_p = sum_j (1^T V)_j z_j
    sig = np.asarray(sigma, float)
    ds = np.r_[0.0, np.diff(sig)] / dt           # sigma' over the step ending at each sample
    tot = np.zeros_like(sig)
    for j in range(len(lam)):
        a = math.exp(lam[j] * dt)
        z = lfilter([beta[j] * (a - 1.0) / lam[j]], [1.0, -a], ds)
        tot += ones_V[j] * z
    return sig - sig[0] - tot


def reptation_creep(h, dt, c, tau_d, n_modes, r_n, t_ref=10.0):
    """Creep of the stage's pad under the core's force h: the pad's strain beyond its instantaneous part, G0 eps -
    (h - h[0]), scaled so that a step held t_ref s creeps by c of it; 0 at the start."""
    h = np.asarray(h, float)
    A, b, G0 = _reptation_system(tau_d, n_modes, r_n)
    step_t = np.arange(int(round(t_ref / dt)) + 2) * dt
    step = np.minimum(step_t / dt, 1.0)
    ref = G0 * reptation_strain(step, dt, tau_d, n_modes, r_n)[-2] - 1.0
    return c * (G0 * reptation_strain(h, dt, tau_d, n_modes, r_n) - (h - h[0])) / ref


# ---- rate dependence: a fluid inerter between the stage and the frame ----

@njit(cache=True)
def _inerter(h, dt, w2, two_zw, kap, sub):
    n = len(h)
    y = np.empty(n)
    x, u = h[0], 0.0
    y[0] = x
    hs = dt / sub
    for k in range(1, n):
        h0, h1 = h[k - 1], h[k]
        for j in range(sub):
            a0 = h0 + (h1 - h0) * j / sub
            am = h0 + (h1 - h0) * (j + 0.5) / sub
            a1 = h0 + (h1 - h0) * (j + 1.0) / sub
            k1x, k1u = u, w2 * (a0 - x) - two_zw * u - kap * abs(u) * u
            x2, u2 = x + 0.5 * hs * k1x, u + 0.5 * hs * k1u
            k2x, k2u = u2, w2 * (am - x2) - two_zw * u2 - kap * abs(u2) * u2
            x3, u3 = x + 0.5 * hs * k2x, u + 0.5 * hs * k2u
            k3x, k3u = u3, w2 * (am - x3) - two_zw * u3 - kap * abs(u3) * u3
            x4, u4 = x + hs * k3x, u + hs * k3u
            k4x, k4u = u4, w2 * (a1 - x4) - two_zw * u4 - kap * abs(u4) * u4
            x += hs / 6.0 * (k1x + 2 * k2x + 2 * k3x + k4x)
            u += hs / 6.0 * (k1u + 2 * k2u + 2 * k3u + k4u)
        y[k] = x
    return y


def inerter_stage(h, dt, fn, zeta, kap, sub=8):
    """The stage (travel y) held by its flexure (stiffness k) to the core's free stroke h and tied to the frame through
    a fluid inerter, a piston pumping oil through a helical channel (Smith, IEEE Trans. Autom. Control 47 (2002) 1648,
    the inerter; Swift et al., Int. J. Control 86 (2013) 2035, the fluid inerter's model): the oil's inertia in the
    channel gives a force b y'' (the inertance b), its laminar friction c1 y' and the losses at the channel's ends
    c2 |y'| y'. Divided by b: y'' = wn^2 (h - y) - 2 zeta wn y' - kap |y'| y', wn = 2 pi fn. Classical RK4 on ``sub``
    substeps a sample, h linear between samples; at rest at h[0] before the record."""
    wn = 2 * math.pi * fn
    return _inerter(np.asarray(h, float), float(dt), wn * wn, 2 * zeta * wn, float(kap), int(sub))


# ---- drift: a thermocouple's ice-point reference running out of ice ----

def ice_point_reference(t, t_melt, tau):
    """The temperature (over the room's) of a thermocouple's reference junction in a small ice-point cup: held at the
    melting point while ice is left (the room's heat, flowing in at a rate set by the temperature difference, goes
    into the latent heat: Stefan's problem in its lumped form, the ice lasting t_melt), then warming toward the room
    as a lumped body (Newton's law of cooling, time constant tau): 1 - exp(-(t - t_melt) / tau) after t_melt, 0 before
    (the reference's error, an offset on every reading, e.g. ASTM E230's tables assume 0 deg C)."""
    s = np.asarray(t, float) - t_melt
    return np.where(s > 0, -np.expm1(-np.maximum(s, 0.0) / tau), 0.0)


# ---- asymmetry: an eccentric cam read at its flat-faced follower ----

def cam_lift(phi, e):
    """The lift of a flat-faced follower on a circular disc cam of eccentricity e (the disc's centre e from the shaft)
    turned by phi from the lowest position: e (1 - cos phi) (e.g. Shigley & Uicker, *Theory of Machines and
    Mechanisms*: the eccentric is the harmonic cam)."""
    return e * (1.0 - np.cos(np.asarray(phi, float)))


def cam_reading(x, phi0, k):
    """The follower's lift as the stage turns the cam shaft by k x (x in -1 ... 1) about a working angle phi0, scaled
    to slope 1 at x = 0: (cos phi0 - cos(phi0 + k x)) / (k sin phi0); convex for phi0 < pi / 2 (on the rising flank
    below its steepest point), the ends' secants 2 cos phi0 (1 - cos k) / (k sin phi0) apart."""
    x = np.asarray(x, float)
    return (math.cos(phi0) - np.cos(phi0 + k * x)) / (k * math.sin(phi0))


def cam_asym(phi0, k):
    return float(cam_reading(1.0, phi0, k) + cam_reading(-1.0, phi0, k))


# ---- saturation: a magnetic reading through a saturating iron yoke ----

def frolich_reading(x, b):
    """The flux read through an iron yoke whose magnetisation follows Frolich's law B = H / (alpha + beta |H|)
    (Frolich 1881; Kennelly, Trans. AIEE 8 (1891) 485, on the reluctivity rising linearly with H), the stage setting
    H in proportion to its travel (x in -1 ... 1), scaled to slope 1 at x = 0: x / (1 + b |x|); odd, the ends
    compressed by b / (1 + b)."""
    x = np.asarray(x, float)
    return x / (1.0 + b * np.abs(x))


# ---- delay: a tape recorder's read-after-write head ----

def tape_readout(t_read, t_fine, h_fine, D, G, wow, f_wow, n_gl=16):
    """The signal h (given on a fine grid t_fine, at rest at h[0] before it) recorded on a tape by the write head and
    read back by the read head D (in seconds of tape at the nominal speed) downstream, its gap G long (likewise), the
    tape's speed u0 (1 + wow sin(2 pi f_wow t)) (an instrumentation recorder's read-after-write monitoring; wow and gap
    loss as in e.g. Mee & Daniel, *Magnetic Recording*, 1987): the tape's position P(t) = t - wow / (2 pi f_wow) (cos(2
    pi f_wow t) - 1) (units of nominal seconds), the read head at time t averages the track over P(t) - D +- G / 2,
    each point written at the time t_w with P(t_w) = that position (by interpolation on the fine grid);
    Gauss-Legendre with n_gl nodes over the gap."""
    t_fine = np.asarray(t_fine, float)
    om = 2 * math.pi * f_wow
    P_f = t_fine - wow / om * (np.cos(om * t_fine) - 1.0)
    t_read = np.asarray(t_read, float)
    P_r = t_read - wow / om * (np.cos(om * t_read) - 1.0)
    xg, wg = np.polynomial.legendre.leggauss(n_gl)
    out = np.zeros_like(t_read)
    for xi, wi in zip(xg, wg):
        pos = P_r - D + 0.5 * G * xi
        tw = np.interp(pos, P_f, t_fine)                 # P is increasing: its inverse by interpolation
        out += 0.5 * wi * np.interp(tw, t_fine, h_fine, left=h_fine[0])
    return out


# ---- initial state: see the core's ``state`` ----

# ---- the pair: a telemetry link (delay) and a cable heating the bracket (drift) ----

def telemetry_link(t, t_fine, h_fine, period, latency):
    """A wireless telemetry link: the sensor's value is sampled every ``period`` s (at k period) and sent in a packet
    that arrives ``latency`` s later; the receiver holds the last packet it has (a zero-order hold). At time t it shows
    h at floor((t - latency) / period) period (h[0] before the first packet arrives). A mean delay of latency + period
    / 2."""
    t = np.asarray(t, float)
    ts = np.floor((t - latency) / period + 1e-9) * period
    return np.interp(np.maximum(ts, t_fine[0]), t_fine, h_fine)


def line_source_heating(t, t_on, t_r):
    """The temperature rise at a distance r from a line heat source (a cable carrying a heater's current past the
    sensor's bracket) switched on at t_on in an infinite medium: (q / (4 pi k)) E1(r^2 / (4 alpha (t - t_on))) (Carslaw
    & Jaeger, *Conduction of Heat in Solids*, 1959, sec. 10.3; the transient hot-wire method), t_r = r^2 / (4 alpha);
    in units of q / (4 pi k). 0 before t_on; it grows without bound, logarithmically, at late times."""
    s = np.asarray(t, float) - t_on
    out = np.zeros_like(s)
    m = s > 0
    out[m] = exp1(t_r / s[m])
    return out


# ---- out of vocabulary: a single-turn absolute encoder that wraps ----

def wrapped_encoder(x, period, phase):
    """A single-turn absolute encoder on the stage's lead screw: it reads the screw's angle within one turn, so a
    travel x (over the lead ``period`` a turn) is read as (x + phase) mod period; every crossing of a whole turn makes
    the reading jump by one period (the count of turns is lost)."""
    return np.mod(np.asarray(x, float) + phase, period)

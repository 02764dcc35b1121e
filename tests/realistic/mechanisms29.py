"""Mechanisms of the HOLDOUT29 set (``cases_holdout29.py``), each written from its law; the signals are in
:mod:`.signals29`.

Nothing here imports hystcomp. Every mechanism takes the (clean) drive, or the core's output, and returns the response;
all are causal. The exact Kelvin-element recursion is the earlier sets' (the same law, imported as mechanisms28 does).

Citations: every source below was written from memory in this session (none was re-read); volumes, pages and years may
be off. The laws do not rest on them: each is checked in tests/test_realistic_holdout29.py against an independent
solution (a closed form, quadrature, solve_ivp, an FFT of the transfer function, scipy's distributions or a finer
simulation).
"""

import math

import numpy as np
from numba import njit
from scipy.special import erfc

from .mechanisms24 import kelvin_modes_response


# ---- the rate-independent core: pre-sliding of a stage on preloaded balls (Cattaneo-Mindlin-Deresiewicz) ----

def mindlin_virgin(q):
    """Mindlin's tangential compliance of a Hertzian sphere-on-flat contact under a constant normal load P, loaded from
    rest by a tangential force Q = q mu P (Cattaneo, Rend. Accad. Lincei 27 (1938) 342; Mindlin, J. Appl. Mech. 16
    (1949) 259): a slip annulus c < r < a grows inward with c / a = (1 - q)^(1/3), and the displacement is delta =
    (3 mu P / (16 G* a)) (1 - (1 - q)^(2/3)). Here in units where the small-load slope is 1: M(q) = (3 / 2) (1 - (1 -
    |q|)^(2/3)) sign(q), |q| < 1 (full sliding at 1)."""
    q = np.asarray(q, float)
    return 1.5 * np.sign(q) * -np.expm1((2.0 / 3.0) * np.log1p(-np.abs(q)))


def _m_scalar(q):
    return math.copysign(1.5 * -math.expm1((2.0 / 3.0) * math.log1p(-abs(q))), q)


def mindlin_core(v, Vs, c, state=None, return_state=False):
    """The stage's travel x under a drive v that sets the tangential force on its preloaded guide balls, Q = mu P v /
    Vs (Vs the drive at which the balls would slide outright; |v| < Vs throughout): the actuator's own compliance (x =
    v) in series with the contacts' (c Vs M(v / Vs), c their compliance over the actuator's at small loads). From the
    virgin state x = v + c Vs M(v / Vs); on unloading and reloading Mindlin & Deresiewicz (J. Appl. Mech. 20 (1953)
    327) found the contact retracing with twice the load in twice the slip: from a reversal at (v_r, x_r) the branch
    is x_r + (v - v_r) + 2 c Vs M((v - v_r) / (2 Vs)). A branch that reaches the turning point before its own start
    closes its loop and the branch left there is resumed (the slip annuli of the inner loop are overwritten); a branch
    that reaches the mirror image of the first turning point rejoins the virgin curve. ``state`` is (turning points as
    (v, x) pairs, last input, last output, last direction) as returned with ``return_state``; None is the virgin state
    at 0 V."""
    if state is None:
        tp, u_prev, x_prev, d = [], 0.0, 0.0, 0
    else:
        tp, u_prev, x_prev, d = list(state[0]), float(state[1]), float(state[2]), int(state[3])
    cV = c * Vs
    inv = 1.0 / Vs

    def branch(u):
        if not tp:
            return u + cV * _m_scalar(u * inv)
        vr, xr = tp[-1]
        e = u - vr
        return xr + e + 2.0 * cV * _m_scalar(0.5 * e * inv)

    out = np.empty(len(v))
    for k, u in enumerate(np.asarray(v, float).tolist()):
        if u != u_prev:
            s = 1 if u > u_prev else -1
            if d != 0 and s != d:
                tp.append((u_prev, x_prev))
            d = s
            while tp:
                if len(tp) >= 2:
                    if (u - tp[-2][0]) * d >= 0:
                        del tp[-2:]
                        continue
                elif (u + tp[0][0]) * d >= 0:
                    tp.pop()
                    continue
                break
            x_prev = branch(u)
            u_prev = u
        out[k] = x_prev
    if return_state:
        return out, (tuple(tp), u_prev, x_prev, d)
    return out


def mindlin_density(r, Vs, c):
    """The density of play thresholds r (0 < r < Vs) of the PI model equal to :func:`mindlin_core`: its virgin curve's
    second derivative, (c / (3 Vs)) (1 - r / Vs)^(-4/3) (with a unit linear part); used only by the test."""
    return c / (3.0 * Vs) * (1.0 - np.asarray(r, float) / Vs) ** (-4.0 / 3.0)


# ---- creep: a pad of a dilute polymer gel (Zimm's chain modes) ----

def zimm_modes(tau1, n_modes):
    """Zimm's modes of a chain with hydrodynamic interaction (Zimm, J. Chem. Phys. 24 (1956) 269; Doi & Edwards, *The
    Theory of Polymer Dynamics*, 1986, ch. 4): tau_p = tau1 p^(-3/2), p = 1 ... n_modes, every mode the same share
    (kT each) of the creep compliance. Returns (taus, weights summing to 1)."""
    p = np.arange(1, n_modes + 1, dtype=float)
    return tau1 * p ** -1.5, np.full(n_modes, 1.0 / n_modes)


def zimm_compliance(t, tau1, n_modes):
    """The creep compliance J(t) / J(inf) = sum_p w (1 - exp(-t / tau_p))."""
    taus, w = zimm_modes(tau1, n_modes)
    t = np.asarray(t, float)[..., None]
    return np.sum(w * -np.expm1(-t / taus), axis=-1)


def zimm_creep(h, dt, c, tau1, n_modes, t_ref=10.0):
    """Creep of the stage's gel pad under the core's force h: Boltzmann superposition of :func:`zimm_compliance` (a
    Kelvin element per mode, exact for h linear between samples), scaled so that a step held t_ref s creeps by c of it;
    at rest at h[0] before the record."""
    taus, w = zimm_modes(tau1, n_modes)
    h = np.asarray(h, float)
    return c * kelvin_modes_response(h - h[0], dt, taus, w) / float(zimm_compliance(t_ref, tau1, n_modes))


# ---- rate dependence: a sphere in a viscous liquid with the Basset history force ----

@njit(cache=True)
def _basset_stage(h, dt, tau, tau_v):
    n = len(h)
    y = np.empty(n)
    u = np.zeros(n)
    y[0] = h[0]
    K = tau * math.sqrt(tau_v) / (math.gamma(1.5) * math.sqrt(dt))
    b = np.sqrt(np.arange(n + 1.0))
    b = b[1:] - b[:-1]                          # b_m = sqrt(m + 1) - sqrt(m)
    for k in range(1, n):
        S = 0.0                                 # the L1 sum over the earlier increments of u
        for j in range(k - 1):
            S += b[k - 1 - j] * (u[j + 1] - u[j])
        rhs = h[k] - y[k - 1] - 0.5 * dt * u[k - 1] + K * u[k - 1] - K * S
        u[k] = rhs / (0.5 * dt + tau + K)
        y[k] = y[k - 1] + 0.5 * dt * (u[k] + u[k - 1])
    return y


def basset_stage(h, dt, tau, tau_v):
    """The stage (travel y) held by a flexure of stiffness k to the core's free stroke h and carrying a sphere of radius
    a in a liquid (density rho, viscosity mu) at creeping flow: Stokes's drag 6 pi mu a u and the Basset-Boussinesq
    history force 6 a^2 sqrt(pi rho mu) int u'(s) / sqrt(t - s) ds (Basset, *A Treatise on Hydrodynamics*, 1888;
    Maxey & Riley, Phys. Fluids 26 (1983) 883); the added mass neglected. Divided by k: h - y = tau (u + sqrt(tau_v)
    D^(1/2) u), u = y', tau = 6 pi mu a / k, tau_v = a^2 rho / mu, D^(1/2) Caputo's half derivative; the transfer
    function 1 / (1 + tau s + tau sqrt(tau_v) s^(3/2)). The L1 scheme for the half derivative (Oldham & Spanier, *The
    Fractional Calculus*, 1974), the trapezoidal rule for y, h at the samples; at rest at h[0] before the record."""
    return _basset_stage(np.asarray(h, float), float(dt), float(tau), float(tau_v))


def basset_transfer(s, tau, tau_v):
    """The transfer function of :func:`basset_stage` at complex s."""
    s = np.asarray(s, complex)
    return 1.0 / (1.0 + tau * s + tau * math.sqrt(tau_v) * s ** 1.5)


# ---- drift: heat diffusing through a wall into the sensor's bracket ----

def wall_heating(t, t_on, t_d):
    """The temperature rise at depth L inside a thick wall (a semi-infinite solid) whose far face is held at a step
    above the ambient from t_on on (a radiator behind the wall; Carslaw & Jaeger, *Conduction of Heat in Solids*, 1959,
    sec. 2.4): erfc(L / (2 sqrt(alpha (t - t_on)))) = erfc(sqrt(t_d / (t - t_on))), t_d = L^2 / (4 alpha); 0 before."""
    s = np.asarray(t, float) - t_on
    out = np.zeros_like(s)
    m = s > 0
    out[m] = erfc(np.sqrt(t_d / s[m]))
    return out


# ---- asymmetry: a V-notch weir's flow ----

def vnotch_flow(h, theta, Cd=0.58, g=9.81):
    """Thomson's triangular (V-notch) weir (Thomson 1858; e.g. ISO 1438): Q = (8 / 15) Cd sqrt(2 g) tan(theta / 2)
    h^(5/2) for a head h above the notch's vertex and a notch angle theta."""
    return 8.0 / 15.0 * Cd * math.sqrt(2 * g) * math.tan(theta / 2) * np.asarray(h, float) ** 2.5


def weir_reading(x, k):
    """The flow read over the weir as the stage sets the head h0 (1 + k x) (x in -1 ... 1), scaled to slope 1 at x = 0:
    ((1 + k x)^(5/2) - 1) / (5 k / 2); convex, the ends' secants f(1) + f(-1) apart."""
    x = np.asarray(x, float)
    return ((1.0 + k * x) ** 2.5 - 1.0) / (2.5 * k)


def weir_asym(k):
    """The difference of the ends' secants of :func:`weir_reading`."""
    return float(weir_reading(1.0, k) + weir_reading(-1.0, k))


# ---- saturation: the dispersion signal of a cavity the stage detunes ----

def dispersion_reading(x, dm):
    """The error signal of a lock-in (or Pound-Drever-Hall) reading of an optical cavity whose detuning the stage sets
    to dm x half-widths (x in -1 ... 1): the dispersive Lorentzian delta / (1 + delta^2), the Hilbert transform of the
    absorption 1 / (1 + delta^2) (Kramers-Kronig; Black, Am. J. Phys. 69 (2001) 79), scaled to slope 1 at x = 0:
    x / (1 + (dm x)^2). Odd, below its peak (at dm |x| = 1) for dm < 1, the ends compressed by dm^2 / (1 + dm^2)."""
    x = np.asarray(x, float)
    return x / (1.0 + (dm * x) ** 2)


# ---- delay: a bucket-brigade device ----

@njit(cache=True)
def _bbd(h, M, eps):
    b = np.full(M, h[0])
    out = np.empty(len(h))
    for k in range(len(h)):
        for j in range(M - 1, 0, -1):
            b[j] = (1.0 - eps) * b[j - 1] + eps * b[j]
        b[0] = (1.0 - eps) * h[k] + eps * b[0]
        out[k] = b[M - 1]
    return out


def bbd_line(h, M, eps):
    """A bucket-brigade analog delay line (Sangster & Teer, IEEE J. Solid-State Circuits 4 (1969) 131): M capacitors
    (buckets) whose charges advance one bucket every clock, each transfer leaving the fraction eps behind (the charge
    transfer inefficiency); h is sampled into the first bucket every clock and the last bucket is read. Per stage
    (1 - eps) z^-1 / (1 - eps z^-1): a mean delay of M / (1 - eps) clocks. At rest at h[0] before the record."""
    return _bbd(np.asarray(h, float), int(M), float(eps))


# ---- initial state: an interrupted demagnetisation (a decaying alternating drive cut short) ----

def decaying_ac(t, V0, f, tau):
    """A demagnetising (degaussing) cycle: V0 exp(-t / tau) sin(2 pi f t) (e.g. Bozorth, *Ferromagnetism*, 1951, on AC
    demagnetisation; the same in piezo stacks' depoling recovery)."""
    t = np.asarray(t, float)
    return V0 * np.exp(-t / tau) * np.sin(2 * math.pi * f * t)


# ---- the pair: light through two circular apertures, read by a photomultiplier that fatigues ----

def lens_area(d):
    """The overlap of two unit circles d apart (0 <= d <= 2): 2 acos(d / 2) - (d / 2) sqrt(4 - d^2)."""
    d = np.asarray(d, float)
    return 2 * np.arccos(d / 2) - d / 2 * np.sqrt(4 - d * d)


def aperture_reading(x, d0, k):
    """The light through a fixed circular aperture and an equal one on the stage whose centres the stage brings
    together from d0 radii by k x (x in -1 ... 1), scaled to slope 1 at x = 0: (A(d0 - k x) - A(d0)) / (k sqrt(4 -
    d0^2)) (A' = -sqrt(4 - d^2)); convex (A'' = d / sqrt(4 - d^2))."""
    return (lens_area(d0 - k * np.asarray(x, float)) - lens_area(d0)) / (k * math.sqrt(4 - d0 * d0))


def aperture_asym(d0, k):
    return float(aperture_reading(1.0, d0, k) + aperture_reading(-1.0, d0, k))


def pmt_fatigue(light, dt, q_f):
    """A photomultiplier's gain under anode fatigue (the dynodes' secondary emission falling with the charge drawn;
    e.g. Hamamatsu's *Photomultiplier Tubes: Basics and Applications*, on drift and life): G = 1 / (1 + Q / q_f), Q' =
    G L the anode current for a light L >= 0. Q by the trapezoidal rule with G at the step's start and end (implicit,
    solved exactly: a quadratic). Returns (G L, G)."""
    L = np.asarray(light, float)
    G = np.empty_like(L)
    Q = 0.0
    G[0] = 1.0
    for k in range(1, len(L)):
        # Q1 = Q + dt/2 (G0 L0 + L1 / (1 + Q1 / q_f)): a quadratic in Q1
        a0 = Q + 0.5 * dt * G[k - 1] * L[k - 1]
        # (Q1 - a0)(1 + Q1 / q_f) = dt/2 L1  ->  Q1^2 / q_f + Q1 (1 - a0 / q_f) - a0 - dt/2 L1 = 0
        B = 1.0 - a0 / q_f
        C = -(a0 + 0.5 * dt * L[k])
        Q = (-B + math.sqrt(B * B - 4 * C / q_f)) / (2 / q_f)
        G[k] = 1.0 / (1.0 + Q / q_f)
    return G * L, G


# ---- out of vocabulary: a ratchet wheel driven by a pawl ----

def ratchet(h):
    """A ratchet wheel pushed by a pawl on the stage: the wheel advances with the pawl while it moves forward and stays
    (held by its detent) while the pawl slides back over the teeth (fine teeth: the wheel's angle is the sum of the
    forward increments, the positive variation of h). Unbounded under repeated cycles; 0 at the start."""
    h = np.asarray(h, float)
    return np.r_[0.0, np.cumsum(np.maximum(np.diff(h), 0.0))]

"""Mechanisms of the HOLDOUT24 set (``cases_holdout24.py``), each written from its law; the signals are in
:mod:`.signals24`.

Nothing here imports hystcomp. Every mechanism takes the (clean) drive, or the core's output, and returns the response;
all are causal. The play, its threshold grid, a path's turning points and the raised cosine are the earlier sets' (the
same laws, imported as mechanisms23 does).

Citations: every source below was written from memory in this session (none was re-read); volumes, pages and years may
be off. The laws do not rest on them: each is checked in tests/test_realistic_holdout24.py against an independent
solution (a closed form, quadrature, brentq, solve_ivp, scipy's own routines or a finer simulation).
"""

import math

import numpy as np
from scipy.signal import lfilter

from .mechanisms13 import turning_points  # noqa: F401
from .mechanisms18 import exp_plays, grid, plays  # noqa: F401
from .mechanisms19 import raised_cosine  # noqa: F401


# ---- the rate-independent core: a black body's spectrum as the density of thresholds ----

def planck_plays(n, r_max, theta, w0):
    """Thresholds on :func:`grid` weighted by Planck's law in the frequency's form, r^3 / (exp(r / theta) - 1) (Planck,
    Ann. Phys. 4 (1901) 553: the energy density of black-body radiation per unit frequency; theta plays kT / h): a hump
    whose peak sits at x theta, x = 3 (1 - exp(-x)) = 2.8214 (Wien's displacement law), falling as r^2 toward 0 and
    exponentially beyond; summing to 1 - w0."""
    r = grid(n, r_max)
    dens = r ** 3 / np.expm1(r / theta)
    return r, (1 - w0) * dens / dens.sum()


# ---- creep: poroelastic drainage of spherical gel grains ----

def sphere_drainage_modes(n_modes=4000):
    """The modes of diffusion out of a sphere with its surface drained at t = 0: the fraction drained is U(T) = 1 - (6 /
    pi^2) sum_n exp(-n^2 pi^2 T) / n^2, T = D t / a^2 (Crank, *The Mathematics of Diffusion*, 1975, eq. 6.20; Barrer
    1941). Returns (rates n^2 pi^2, weights 6 / (pi^2 n^2)) for n = 1 ... n_modes; the weights of the modes beyond
    n_modes (about 6 / (pi^2 n_modes)) act at once."""
    k = np.arange(1, n_modes + 1, dtype=float)
    return k * k * math.pi ** 2, 6.0 / (math.pi ** 2 * k * k)


def sphere_drainage_fraction(T, n_modes=4000):
    """U(T) of :func:`sphere_drainage_modes`, the modes beyond n_modes counted as drained (U(0+) small, U(inf) = 1)."""
    rates, w = sphere_drainage_modes(n_modes)
    T = np.clip(np.asarray(T, float), 0, None)[..., None]
    return 1.0 - np.sum(w * np.exp(-rates * T), axis=-1)


def kelvin_modes_response(h, dt, taus, weights):
    """sum_i w_i e_i, each e_i' = (h - e_i) / tau_i, exact for h linear between samples (e_{k+1} = a e_k + (1 - c)
    h_{k+1} + (c - a) h_k, a = exp(-dt / tau), c = tau (1 - a) / dt), at rest at h[0] before the record; modes faster
    than dt / 50 follow h at once."""
    h = np.asarray(h, float)
    x = h - h[0]
    out = np.zeros_like(h)
    fast = 0.0
    for tau, w in zip(np.asarray(taus, float), np.asarray(weights, float)):
        if tau < dt / 50:
            fast += w
            continue
        a = math.exp(-dt / tau)
        c = tau * -math.expm1(-dt / tau) / dt
        out += w * lfilter([1 - c, c - a], [1.0, -a], x)
    return out + fast * x + h[0] * float(np.sum(weights))


def gel_pad_creep(h, dt, c, t_d, t_ref=10.0, n_modes=4000):
    """Creep of a pad of hydrogel grains (spheres of radius a, the solvent's diffusivity D, t_d = a^2 / D) between the
    stage and its load: loaded, a grain first deforms at constant volume and then consolidates as its solvent drains
    through its surface (Biot's poroelasticity with a drained surface: the creep follows the drained fraction U(t / t_d)
    of :func:`sphere_drainage_fraction`; e.g. Tanaka & Fillmore, J. Chem. Phys. 70 (1979) 1214 for a gel sphere's
    swelling). Boltzmann superposition over the core's output h (a Kelvin element per mode, exact for h linear between
    samples), scaled so that a step held t_ref s creeps by c of it: c (U * dh)(t) / U(t_ref / t_d). Returns the creep
    (its value at rest is 0: the part of h[0] is removed)."""
    rates, w = sphere_drainage_modes(n_modes)
    h = np.asarray(h, float)
    resp = kelvin_modes_response(h - h[0], dt, t_d / rates, w) + (1.0 - float(np.sum(w))) * (h - h[0])
    return c * resp / float(sphere_drainage_fraction(t_ref / t_d, n_modes))


# ---- rate dependence: the stack's resistive internal electrodes (a distributed RC line) ----

def rc_line_modes(n_modes=400):
    """The modes of the mean voltage along an RC line open at its far end and driven at the other: tanh(sqrt(s tau)) /
    sqrt(s tau) = sum_n 2 / (s tau + lam_n^2), lam_n = (n - 1/2) pi (the poles of tanh, Mittag-Leffler's expansion).
    Returns (tau_n / tau = 1 / lam_n^2, weights 2 / lam_n^2); the weights sum to 1 and their mean time is tau / 3."""
    lam = (np.arange(1, n_modes + 1) - 0.5) * math.pi
    return 1.0 / lam ** 2, 2.0 / lam ** 2


def rc_line_transfer(omega, tau):
    """The closed form tanh(sqrt(i omega tau)) / sqrt(i omega tau) (1 at omega = 0)."""
    s = np.sqrt(1j * np.asarray(omega, float) * tau + 0j)
    return np.where(np.abs(s) < 1e-12, 1.0 + 0j, np.tanh(s) / np.where(np.abs(s) < 1e-12, 1.0, s))


def electrode_line_voltage(v, dt, tau, n_modes=400):
    """The voltage a multilayer stack's ceramic sees when its internal electrodes are thin films of finite resistance:
    the drive enters at one edge and diffuses along each electrode (an RC transmission line, R and C per length, tau =
    R C l^2; the telegrapher's equation without inductance, Kelvin's cable of 1855), the ceramic's strain following the
    voltage averaged over the electrode, the transfer tanh(sqrt(s tau)) / sqrt(s tau) of :func:`rc_line_modes`; each
    mode exact for v linear between samples, the modes beyond n_modes (weights about 2 / (pi^2 n_modes)) following at
    once. At rest at v[0] before the record."""
    tn, wn = rc_line_modes(n_modes)
    v = np.asarray(v, float)
    out = kelvin_modes_response(v, dt, tau * tn, wn)
    return out + (1.0 - float(np.sum(wn))) * v


# ---- offset drift: a sealed sensor's barometric offset in a cable car ----

#: the International Standard Atmosphere's troposphere: sea-level temperature (K), lapse rate (K/m), g (m/s^2), the
#: molar mass of air (kg/mol) and the gas constant (J/(mol K))
ISA = dict(T0=288.15, L=0.0065, g=9.80665, M=0.0289644, R=8.31446)


def isa_pressure(z, p0=101325.0):
    """The pressure (Pa) at the altitude z (m) of the ISA troposphere, p0 (1 - L z / T0)^(g M / (R L)) (the
    hydrostatic law dp/dz = -p g M / (R T) with T = T0 - L z; ICAO Doc 7488, 1993)."""
    a = ISA
    return p0 * (1 - a["L"] * np.asarray(z, float) / a["T0"]) ** (a["g"] * a["M"] / (a["R"] * a["L"]))


def barometric_offset(z, z_ref):
    """The offset of a sensor with a sealed reference cavity (its diaphragm bulging with the outside pressure, linear in
    it): proportional to isa_pressure(z_ref) - isa_pressure(z) (positive when higher), in Pa."""
    return float(isa_pressure(z_ref)) - isa_pressure(z)


# ---- asymmetry: the level in a round-bottomed flask ----

def sphere_level(phi):
    """The level u (over the radius, from the sphere's centre: -1 empty, 1 full) of liquid in a sphere holding the
    volume 3 V / (pi R^3) = phi + 2 (V = pi h^2 (3 R - h) / 3, Archimedes' cap, with h = R (1 + u): u^3 - 3 u + phi =
    0), by the trigonometric root of the cubic (Viete, 1615): u = 2 cos((acos(-phi / 2) + 4 pi) / 3), for |phi| <= 2."""
    phi = np.clip(np.asarray(phi, float), -2.0, 2.0)
    return 2 * np.cos((np.arccos(-phi / 2) + 4 * math.pi) / 3)


def flask_reading(x, u0, dphi):
    """A float reading the level of a round-bottomed flask into which the stage's piston pushes liquid (x its travel
    over its largest, the largest volume dphi in units of pi R^3 / 3), filled to u0 at rest: the level from rest over
    its slope there, (u(phi0 + dphi x) - u0) / (dphi / (3 (1 - u0^2))) (dphi / du = 3 (1 - u^2): the flask's cross
    section): monotone, concave below the equator (the flask widening) and convex above."""
    phi0 = 3 * u0 - u0 ** 3
    slope = 1.0 / (3 * (1 - u0 * u0))
    return (sphere_level(phi0 + dphi * np.asarray(x, float)) - u0) / (slope * dphi)


# ---- saturation: a probe held between two pre-stretched worm-like-chain tethers ----

def wlc_force(z):
    """The force of a worm-like chain at the relative extension z (in units of kT / P, P the persistence length), by
    Marko & Siggia's interpolation (Macromolecules 28 (1995) 8759): 1 / (4 (1 - z)^2) - 1 / 4 + z for 0 <= z < 1, 0
    when slack (z < 0); it diverges as the chain straightens."""
    z = np.asarray(z, float)
    zc = np.clip(z, 0.0, 1 - 1e-15)
    return np.where(z > 0, 1 / (4 * (1 - zc) ** 2) - 0.25 + zc, 0.0)


def wlc_pair_force(x, z0):
    """The net force on a probe between two tethers pre-stretched to z0 when it moves by x (in contour lengths):
    f(z0 + x) - f(z0 - x); odd, stiffening, singular at |x| = 1 - z0."""
    x = np.asarray(x, float)
    return wlc_force(z0 + x) - wlc_force(z0 - x)


def wlc_pair_slope(z0):
    """d/dx of :func:`wlc_pair_force` at 0: 2 f'(z0), f'(z) = 1 / (2 (1 - z)^3) + 1."""
    return 2 * (0.5 / (1 - z0) ** 3 + 1.0)


def wlc_pair_displacement(F, z0, iters=80):
    """The probe's displacement x with wlc_pair_force(x, z0) = F (monotone: bisection on (-(1 - z0), 1 - z0), 80
    halvings, below 1e-16 of the interval)."""
    F = np.asarray(F, float)
    lo = np.full(F.shape, -(1 - z0))
    hi = np.full(F.shape, 1 - z0)
    for _ in range(iters):
        mid = 0.5 * (lo + hi)
        above = wlc_pair_force(mid, z0) > F
        hi = np.where(above, mid, hi)
        lo = np.where(above, lo, mid)
    return 0.5 * (lo + hi)


def tether_reading(h, centre, scale, z0):
    """The sensor reading the probe, its tethers loaded by the core's force (h - centre) / scale (in kT / P): the
    displacement over its slope at rest, centre + scale k0 x, k0 = :func:`wlc_pair_slope` (slope 1 at the centre)."""
    F = (np.asarray(h, float) - centre) / scale
    return centre + scale * wlc_pair_slope(z0) * wlc_pair_displacement(F, z0)


# ---- delay: a smart sensor's real-time Savitzky-Golay smoother ----

def savgol_centre_coeffs(m, order=2):
    """The weights of a least-squares polynomial of the given order fitted to 2 m + 1 equally spaced samples and read at
    the centre (Savitzky & Golay, Anal. Chem. 36 (1964) 1627): the first row of the pseudo-inverse of the Vandermonde
    matrix of -m ... m."""
    k = np.arange(-m, m + 1, dtype=float)
    A = np.vander(k, order + 1, increasing=True)
    return np.linalg.pinv(A)[0]


def savgol_sensor(t, t_fine, h_fine, m, phase, latency, order=2):
    """A smart sensor that samples the stage `phase` record samples before each logger tick (on its own clock), smooths
    its samples by a centred Savitzky-Golay fit over 2 m + 1 of them (m later than the newest: a real-time smoother must
    wait for the window's second half) and delivers it `latency` samples later: the reading at t_i is sum_j c_j
    h(t_{i - latency - m + j} - phase dt), j = 0 ... 2m: a delay of m + latency + phase samples that reproduces
    polynomials of the order exactly. h between the fine samples by linear interpolation; h_fine[0] before the
    record."""
    t = np.asarray(t, float)
    dt = t[1] - t[0]
    s = np.interp(t - phase * dt, t_fine, h_fine)
    c = savgol_centre_coeffs(m, order)
    pad = np.r_[np.full(2 * m + latency, s[0]), s]
    out = np.zeros(len(t))
    for j, cj in enumerate(c):
        out += cj * pad[j:j + len(t)]
    return out


# ---- two effects: a Helmholtz resonator's frequency read by a reciprocal counter ----

def helmholtz_frequency(x, xi):
    """The resonance of a Helmholtz resonator whose cavity the stage's piston shrinks, f = (c / 2 pi) sqrt(A / (V L))
    (Helmholtz 1863; Rayleigh, *The Theory of Sound*, 1896, sec. 303), over its value at rest: (1 - xi x)^(-1/2), x the
    travel over its largest, xi the largest volume change over the cavity's."""
    return (1 - xi * np.asarray(x, float)) ** -0.5


def helmholtz_reading(x, xi):
    """:func:`helmholtz_frequency` from its value at rest over its slope there (xi / 2): convex, monotone."""
    return (helmholtz_frequency(x, xi) - 1) / (xi / 2)


def reciprocal_counter(t, t_fine, f_fine, n_periods, latency):
    """A reciprocal counter time-stamping the oscillator's edges (with an interpolating TDC, so the gate ends at the
    logger's tick): the reading at t_i is n / (t_i' - t_s), t_i' = t_i - latency dt, the gate start t_s where n whole
    periods before t_i' began (int_{t_s}^{t_i'} f = n); f between the fine samples linear, its integral exact (the
    cumulative trapezoid and a quadratic within a step). Before the record the frequency is f_fine[0]. A delay of about
    n / (2 f) + latency (the gate's centre), shorter at high frequency, and a moving average over the gate."""
    t_fine = np.asarray(t_fine, float)
    f = np.asarray(f_fine, float)
    d = t_fine[1] - t_fine[0]
    Phi = np.r_[0.0, np.cumsum((f[1:] + f[:-1]) / 2) * d]
    t = np.asarray(t, float)
    te = t - latency * (t[1] - t[0])

    def phase(x):
        x = np.asarray(x, float)
        xc = np.clip(x, t_fine[0], t_fine[-1])
        k = np.minimum(((xc - t_fine[0]) / d).astype(int), len(f) - 2)
        tau = xc - t_fine[k]
        val = Phi[k] + f[k] * tau + (f[k + 1] - f[k]) * tau * tau / (2 * d)
        return np.where(x < t_fine[0], (x - t_fine[0]) * f[0], val)

    def inverse(P):
        """The time at which the phase reaches P (the phase increases; quadratic within a fine step)."""
        P = np.asarray(P, float)
        out = np.empty_like(P)
        before = P < 0
        out[before] = t_fine[0] + P[before] / f[0]
        Pa = P[~before]
        k = np.clip(np.searchsorted(Phi, Pa, side="right") - 1, 0, len(f) - 2)
        a = (f[k + 1] - f[k]) / (2 * d)
        b = f[k]
        c = Phi[k] - Pa
        disc = np.sqrt(np.maximum(b * b - 4 * a * c, 0.0))
        tau = np.where(np.abs(a) > 1e-14 * np.abs(b), (-2 * c) / (b + disc), -c / b)
        out[~before] = t_fine[k] + tau
        return out
    ts = inverse(phase(te) - n_periods)
    return n_periods / (te - ts)


# ---- out of vocabulary: an unbalanced rotor driven through a torsion spring (a forced damped pendulum) ----

def rotor_rhs(th, om, u, w0, q, F):
    """theta'' = -q w0 theta' - w0^2 sin(theta) + w0^2 F u (an unbalanced rotor, its mass's gravity torque m g l sin
    theta, viscous bearing loss, driven through a soft torsion spring by the core's output u; the forced damped
    pendulum, chaotic for q 0.5, a drive at 2/3 of w0 and F about 1.15 or 1.5: Baker & Gollub, *Chaotic Dynamics*,
    1990, ch. 3)."""
    return -q * w0 * om - w0 * w0 * math.sin(th) + w0 * w0 * F * u


def forced_rotor(u_fine, dt, w0, q, F, th0=0.0, om0=0.0):
    """The rotor's angle on the fine grid of the drive u_fine (linear between its samples), classical Runge-Kutta at the
    grid's step, from (th0, om0)."""
    u = np.asarray(u_fine, float).tolist()
    th, om = th0, om0
    out = [th]
    for k in range(1, len(u)):
        u0, u1 = u[k - 1], u[k]
        um = 0.5 * (u0 + u1)
        a1 = rotor_rhs(th, om, u0, w0, q, F)
        t2, o2 = th + 0.5 * dt * om, om + 0.5 * dt * a1
        a2 = rotor_rhs(t2, o2, um, w0, q, F)
        t3, o3 = th + 0.5 * dt * o2, om + 0.5 * dt * a2
        a3 = rotor_rhs(t3, o3, um, w0, q, F)
        t4, o4 = th + dt * o3, om + dt * a3
        a4 = rotor_rhs(t4, o4, u1, w0, q, F)
        th += dt * (om + 2 * o2 + 2 * o3 + o4) / 6
        om += dt * (a1 + 2 * a2 + 2 * a3 + a4) / 6
        out.append(th)
    return np.array(out)


__all__ = ["turning_points", "exp_plays", "grid", "plays", "raised_cosine", "planck_plays", "sphere_drainage_modes",
           "sphere_drainage_fraction", "kelvin_modes_response", "gel_pad_creep", "rc_line_modes", "rc_line_transfer",
           "electrode_line_voltage", "ISA", "isa_pressure", "barometric_offset", "sphere_level", "flask_reading",
           "wlc_force", "wlc_pair_force", "wlc_pair_slope", "wlc_pair_displacement", "tether_reading",
           "savgol_centre_coeffs", "savgol_sensor", "helmholtz_frequency", "helmholtz_reading", "reciprocal_counter",
           "rotor_rhs", "forced_rotor"]

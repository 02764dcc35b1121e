"""Mechanisms of the HOLDOUT25 set (``cases_holdout25.py``), each written from its law; the signals are in
:mod:`.signals25`.

Nothing here imports hystcomp. Every mechanism takes the (clean) drive, or the core's output, and returns the response;
all are causal. The play, its threshold grid, a path's turning points, the raised cosine and the exact Kelvin-element
recursion are the earlier sets' (the same laws, imported as mechanisms24 does).

Citations: every source below was written from memory in this session (none was re-read); volumes, pages and years may
be off. The laws do not rest on them: each is checked in tests/test_realistic_holdout25.py against an independent
solution (a closed form, quadrature, brentq, solve_ivp, scipy's own routines or a finer simulation).
"""

import math

import numpy as np
from scipy.signal import fftconvolve
from scipy.special import ellipe, ellipk

from .mechanisms13 import turning_points  # noqa: F401
from .mechanisms18 import exp_plays, grid, plays  # noqa: F401
from .mechanisms19 import raised_cosine  # noqa: F401
from .mechanisms24 import kelvin_modes_response


# ---- the rate-independent core: the Fermi-Dirac occupation as the density of thresholds ----

def fermi_dirac_plays(n, r_max, mu, kT, w0):
    """Thresholds on :func:`grid` weighted by the Fermi-Dirac occupation 1 / (exp((r - mu) / kT) + 1) (Fermi, Z. Phys.
    36 (1926) 902; Dirac, Proc. R. Soc. A 112 (1926) 661): flat up to about mu - 2 kT, one half at mu, falling over a
    few kT (a smeared step: the thresholds below mu all populated alike, a soft edge); summing to 1 - w0. Its integral
    over (0, inf) is kT ln(1 + exp(mu / kT))."""
    r = grid(n, r_max)
    dens = 1.0 / (np.exp((r - mu) / kT) + 1.0)
    return r, (1 - w0) * dens / dens.sum()


# ---- creep: the ACI 209 (Branson) hyperbolic-power creep law ----

def aci_creep_function(tau, tau0, psi):
    """The creep coefficient's time function of ACI 209R (Branson & Christiason, ACI SP-27, 1971; ACI Committee 209,
    1992): t^psi / (d + t^psi), psi 0.6 and d 10 days for concrete; here d = tau0^psi, so (tau / tau0)^psi / (1 +
    (tau / tau0)^psi): half of the final creep after tau0, a power law t^psi at first and a slow algebraic approach
    to the end (1 - (tau0 / tau)^psi). 0 for tau <= 0."""
    x = (np.clip(np.asarray(tau, float), 0.0, None) / tau0) ** psi
    return x / (1.0 + x)


_GL_X, _GL_W = np.polynomial.legendre.leggauss(16)


def aci_creep_cell_integrals(n, dt, tau0, psi):
    """D_m = int_{(m - 1) dt}^{m dt} J(s) ds for m = 1 ... n, J = :func:`aci_creep_function`, by 16-point Gauss-Legendre
    in each cell (the first cell's t^psi kink costs below 1e-4 of that cell's tiny integral)."""
    a = (np.arange(n, dtype=float))[:, None] * dt
    s = a + (_GL_X[None, :] + 1.0) * (dt / 2)
    return (aci_creep_function(s, tau0, psi) * _GL_W[None, :]).sum(axis=1) * (dt / 2)


def aci_creep(h, dt, c, tau0, psi, t_ref=10.0):
    """Creep of the stage's frame (a polymer-concrete, or mineral-cast, base that creeps like concrete under the
    reaction of the core's force), by Boltzmann superposition of the ACI 209 function over the core's output h,
    exact for h linear between samples: creep(t_n) = (c / J(t_ref)) sum_k h'_k int_{t_k}^{t_{k+1}} J(t_n - s) ds, so a
    step held t_ref s creeps by c of it. At rest at h[0] before the record (creep 0 there)."""
    h = np.asarray(h, float)
    n = len(h)
    slopes = np.diff(h) / dt
    D = aci_creep_cell_integrals(n - 1, dt, tau0, psi)
    out = np.zeros(n)
    out[1:] = fftconvolve(slopes, D)[:n - 1]
    return c * out / float(aci_creep_function(t_ref, tau0, psi))


# ---- rate dependence: a damper with a compressible fill (Zener's standard linear solid) ----

def zener_response(h, dt, tau, rho):
    """The stage's travel when its flexure (stiffness k) is paralleled by a piston damper whose oil is compressible: the
    oil a spring rho k in series with the annular gap's dashpot c = tau rho k (a Maxwell arm), so k x + F_m = k h and
    F_m' = rho k (x' - F_m / c): Zener's standard linear solid (Zener, *Elasticity and Anelasticity of Metals*, 1948;
    Poynting & Thomson 1902). X / H = (1 + tau s) / (1 + tau (1 + rho) s) = 1 / (1 + rho) + (rho / (1 + rho)) / (1 + tau
    (1 + rho) s): full travel when slow, 1 / (1 + rho) of it when fast, a relaxation time tau (1 + rho) between. The
    first-order part exact for h linear between samples; at rest at h[0] before the record."""
    h = np.asarray(h, float)
    slow = kelvin_modes_response(h, dt, [tau * (1 + rho)], [1.0])
    return (h + rho * slow) / (1 + rho)


def zener_transfer(omega, tau, rho):
    """The closed form (1 + i omega tau) / (1 + i omega tau (1 + rho))."""
    s = 1j * np.asarray(omega, float)
    return (1 + s * tau) / (1 + s * tau * (1 + rho))


# ---- offset drift: the Earth's field on a Hall sensor carried by an indexing table ----

def geomagnetic_offset(az, az_field, b_h):
    """The offset of a Hall (or magnetoresistive) position sensor whose sensitive axis lies horizontal on a turntable:
    it reads the Earth's horizontal field b_h (the field's magnitude times the cosine of its inclination, e.g. 50 uT at
    65 degrees: 21 uT; Gauss 1839) projected on its axis, b_h cos(az - az_field), az the table's azimuth. Returns it
    less its value at the first azimuth (the offset nulled at the start)."""
    az = np.asarray(az, float)
    return b_h * (np.cos(az - az_field) - math.cos(float(az.flat[0]) - az_field))


# ---- asymmetry: an eddy-current probe over the stage's target (a coil and its image) ----

MU0 = 4e-7 * math.pi


def coaxial_loops_mutual(a, b, d):
    """The mutual inductance of two coaxial circular loops of radii a, b, d apart (Maxwell, *Treatise*, 1873, sec. 701):
    mu0 sqrt(a b) ((2 / k - k) K(k) - (2 / k) E(k)), k^2 = 4 a b / ((a + b)^2 + d^2), K and E the complete elliptic
    integrals (scipy's parameter m = k^2)."""
    d = np.asarray(d, float)
    m = 4 * a * b / ((a + b) ** 2 + d * d)
    k = np.sqrt(m)
    return MU0 * math.sqrt(a * b) * ((2 / k - k) * ellipk(m) - (2 / k) * ellipe(m))


def eddy_probe_reading(x, gap0, dgap, a=1.0):
    """An eddy-current proximity probe (a coil of radius a) over the conducting target the stage carries, in the
    skin-depth-small limit: the target acts as a mirror, the eddy currents as the coil's image 2 g away with the
    opposite current, so the probe's inductance is L0 - M(2 g) (M by :func:`coaxial_loops_mutual`; e.g. Dodd & Deeds, J.
    Appl. Phys. 39 (1968) 2829, for the full solution). The stage closes the gap g = gap0 - dgap x (x the travel over
    its largest, lengths over a); the reading is the inductance's fall from rest over its slope there (slope 1 at x =
    0): monotone, convex (the image's field grows ever faster as the gap closes)."""
    x = np.asarray(x, float)
    eps = 1e-6 * gap0

    def drop(g):
        return coaxial_loops_mutual(a, a, 2 * g) - coaxial_loops_mutual(a, a, 2 * gap0)
    slope = float(drop(gap0 - eps) - drop(gap0 + eps)) / (2 * eps)          # dM/d(-g) at rest, central difference
    return drop(gap0 - dgap * x) / (slope * dgap)


# ---- saturation: the buoyancy of a horizontal cylinder dipped by the stage ----

def segment_area(u):
    """The immersed cross section of a horizontal cylinder (radius 1) dipped to u of its radius above its axis (-1 ...
    1): the circular segment, pi / 2 + asin(u) + u sqrt(1 - u^2) (Archimedes' buoyancy is rho g L R^2 times it)."""
    u = np.clip(np.asarray(u, float), -1.0, 1.0)
    return math.pi / 2 + np.arcsin(u) + u * np.sqrt(1 - u * u)


def buoyancy_reading(x, u_max):
    """A load cell weighing the buoyancy on a horizontal rod that the stage dips about its half-immersed position (x the
    travel over its largest, u_max the largest dip over the radius): the segment's area from half over its slope there,
    (segment_area(u_max x) - pi / 2) / (2 u_max): odd, slope 1 at 0, flattening towards the ends where the waterline
    narrows (the slope sqrt(1 - u^2))."""
    return (segment_area(u_max * np.asarray(x, float)) - math.pi / 2) / (2 * u_max)


# ---- delay: an asynchronous sample-rate converter's cubic Lagrange (Farrow) interpolator ----

def lagrange4_weights(mu):
    """The weights of the cubic Lagrange interpolator on the nodes -1, 0, 1, 2 read at mu (0 <= mu < 1) (Lagrange 1795;
    the Farrow structure's polynomial in mu: Farrow, Proc. IEEE ISCAS 1988; Laakso et al., IEEE Signal Process. Mag. 13
    (1996) 30). Returns an array of shape mu.shape + (4,)."""
    mu = np.asarray(mu, float)[..., None]
    nodes = np.array([-1.0, 0.0, 1.0, 2.0])
    w = np.ones(mu.shape[:-1] + (4,))
    for j in range(4):
        for m in range(4):
            if m != j:
                w[..., j] *= (mu[..., 0] - nodes[m]) / (nodes[j] - nodes[m])
    return w


def asrc_sensor(t, t_fine, h_fine, ratio, phase, D):
    """A sensor whose ADC runs on its own crystal (its sample period dt ratio, its first sample phase of its periods
    after the logger's first tick) and whose samples an asynchronous sample-rate converter re-times to the logger's
    ticks: the reading at t_i is the cubic Lagrange interpolant of the sensor's samples at t_i - D dt (its FIFO held D
    samples deep), from the four samples around it (:func:`lagrange4_weights`). A delay of D samples that reproduces
    cubics exactly. h between the fine samples linear; h_fine[0] before the record."""
    t = np.asarray(t, float)
    dt = t[1] - t[0]
    ds = dt * ratio
    target = t - D * dt
    pos = (target - t[0]) / ds - phase
    k = np.floor(pos).astype(int)
    mu = pos - k
    w = lagrange4_weights(mu)
    out = np.zeros(len(t))
    for j in range(4):
        ts = t[0] + (k - 1 + j + phase) * ds
        out += w[:, j] * np.interp(ts, t_fine, h_fine, left=h_fine[0])
    return out


# ---- initial state: a DAC's power-on self-test ----

def dac_self_test(bits, full_scale):
    """The codes a DAC's power-on self-test writes (walking ones 1, 2, 4, ... 2^(b - 1), all ones, walking zeros from
    the least significant bit up, the checkerboards 0101... and 1010..., then mid-scale; the march patterns of memory
    and converter tests, e.g. van de Goor, *Testing Semiconductor Memories*, 1991), in volts from 0 V: the path the core
    is left by."""
    top = (1 << bits) - 1
    codes = [0] + [1 << k for k in range(bits)] + [top] + [top - (1 << k) for k in range(bits)]
    checker = int("01" * (bits // 2), 2)
    codes += [checker, top - checker, 1 << (bits - 1)]
    return np.array(codes, float) * (full_scale / top)


# ---- the pair: a Robbins-Monro search history and a neutral-density wedge ----

def robbins_monro(x0, target, gain, a, noise, n_iter, lo=0.0, hi=100.0):
    """The iterates of a stochastic-approximation search for the drive at which a noisy measurement reaches its
    setpoint (Robbins & Monro, Ann. Math. Stat. 22 (1951) 400): x_{n+1} = x_n - (a / (n + 1)) (gain (x_n - target) +
    noise_n), clipped to the stroke; from x0. Returns the iterates."""
    xs = [float(x0)]
    for n in range(n_iter):
        x = xs[-1] - a / (n + 1) * (gain * (xs[-1] - target) + noise[n])
        xs.append(min(max(x, lo), hi))
    return np.array(xs)


def wedge_reading(x, kappa):
    """A photodiode behind a neutral-density wedge that the stage slides across the beam (the optical density linear in
    the travel; Beer-Lambert: I = I0 10^-OD, Bouguer 1729, Lambert 1760, Beer 1852): the light from rest over its slope
    there, (exp(kappa x) - 1) / kappa, kappa = ln 10 times the density's change over the largest travel (its sign the
    wedge's orientation): monotone, convex for kappa > 0."""
    return np.expm1(kappa * np.asarray(x, float)) / kappa


# ---- out of vocabulary: a clamped-clamped beam's hardening resonance (the jump phenomenon) ----

def beam_rhs(q, p, u, w0, zeta, gamma, F):
    """q'' = -2 zeta w0 q' - w0^2 (q + gamma q^3) + w0^2 F u: the first mode of a clamped-clamped beam on the stage,
    its mid-plane stretching making the spring harden cubically (Woinowsky-Krieger, J. Appl. Mech. 17 (1950) 35;
    Duffing 1918), forced by the core's output u; its resonance bends to higher frequencies and, forced hard enough,
    has two stable responses between the jumps (Nayfeh & Mook, *Nonlinear Oscillations*, 1979, ch. 4)."""
    return -2 * zeta * w0 * p - w0 * w0 * (q + gamma * q * q * q) + w0 * w0 * F * u


def forced_beam(u_fine, dt, w0, zeta, gamma, F, q0=0.0, p0=0.0):
    """The beam's deflection on the fine grid of the drive u_fine (linear between its samples), classical Runge-Kutta at
    the grid's step, from (q0, p0). Returns q and q'."""
    u = np.asarray(u_fine, float).tolist()
    q, p = q0, p0
    qs, ps = [q], [p]
    for k in range(1, len(u)):
        u0, u1 = u[k - 1], u[k]
        um = 0.5 * (u0 + u1)
        a1 = beam_rhs(q, p, u0, w0, zeta, gamma, F)
        q2, p2 = q + 0.5 * dt * p, p + 0.5 * dt * a1
        a2 = beam_rhs(q2, p2, um, w0, zeta, gamma, F)
        q3, p3 = q + 0.5 * dt * p2, p + 0.5 * dt * a2
        a3 = beam_rhs(q3, p3, um, w0, zeta, gamma, F)
        q4, p4 = q + dt * p3, p + dt * a3
        a4 = beam_rhs(q4, p4, u1, w0, zeta, gamma, F)
        q += dt * (p + 2 * p2 + 2 * p3 + p4) / 6
        p += dt * (a1 + 2 * a2 + 2 * a3 + a4) / 6
        qs.append(q)
        ps.append(p)
    return np.array(qs), np.array(ps)


def duffing_branches(omega, zeta, gamma, F):
    """The steady amplitudes A of :func:`beam_rhs` under F cos(omega w0 t) by first-order harmonic balance: the real
    positive roots of ((1 - omega^2 + 3 gamma A^2 / 4)^2 + (2 zeta omega)^2) A^2 = F^2 (a cubic in A^2), ascending;
    three between the jumps (the middle one unstable), one outside."""
    c = 0.75 * gamma
    b = 1 - omega * omega
    e = (2 * zeta * omega) ** 2
    roots = np.roots([c * c, 2 * b * c, b * b + e, -F * F])
    s = sorted(float(r.real) for r in roots if abs(r.imag) < 1e-9 * max(1.0, abs(r)) and r.real > 0)
    return np.sqrt(s)


__all__ = ["turning_points", "exp_plays", "grid", "plays", "raised_cosine", "fermi_dirac_plays", "aci_creep_function",
           "aci_creep_cell_integrals", "aci_creep", "zener_response", "zener_transfer", "geomagnetic_offset", "MU0",
           "coaxial_loops_mutual", "eddy_probe_reading", "segment_area", "buoyancy_reading", "lagrange4_weights",
           "asrc_sensor", "dac_self_test", "robbins_monro", "wedge_reading", "beam_rhs", "forced_beam",
           "duffing_branches"]

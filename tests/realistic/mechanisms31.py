"""Mechanisms of the HOLDOUT31 set (``cases_holdout31.py``), each written from its law; the signals are in
:mod:`.signals31`.

Nothing here imports hystcomp. Every mechanism takes the (clean) drive, or the core's output, and returns the response;
all are causal.

Citations: every source below was written from memory in this session (none was re-read); volumes, pages and years may
be off. The laws do not rest on them: each is checked in tests/test_realistic_holdout31.py against an independent
solution (a closed form, quadrature, an FFT of the transfer function, a simulation of the underlying elements or a
direct sum).
"""

import math

import numpy as np
from numba import njit
from scipy.signal import fftconvolve, lfilter


# ---- the rate-independent core: a strap flexure in its elastic-plastic transition (Richard-Abbott, Masing) ----

def richard_abbott_strain(q, n):
    """The strain of a metal whose stress-strain curve in its elastic-plastic transition is Richard & Abbott's
    'versatile elastic-plastic' formula without hardening, sigma = E eps / (1 + |E eps / sigma0|^n)^(1/n) (Richard &
    Abbott, J. Eng. Mech. Div. ASCE 101 (1975) 511; the same three-parameter form is Kishi & Chen's power model of
    semi-rigid steel connections, 1990), solved for the strain under a given stress: in units of sigma0 and sigma0 / E,
    eps = q / (1 - |q|^n)^(1/n), |q| < 1 (the stress's plastic asymptote at 1). n sets the knee's sharpness (n = 1 would
    be a hyperbola)."""
    q = np.asarray(q, float)
    return q / (1.0 - np.abs(q) ** n) ** (1.0 / n)


@njit(cache=True)
def _ra_skel(q, n):
    a = abs(q)
    return q / (1.0 - a ** n) ** (1.0 / n)


@njit(cache=True)
def _ra_masing(v, V0, c, n, st_v, st_x, m0, u_last, x_last, dirn):
    N = len(v)
    out = np.empty(N)
    sv = np.empty(N + m0 + 2)
    sx = np.empty(N + m0 + 2)
    for j in range(m0):
        sv[j] = st_v[j]
        sx[j] = st_x[j]
    m = m0
    for k in range(N):
        u = v[k]
        if u != u_last:
            new_dir = 1 if u > u_last else -1
            if dirn != 0 and new_dir != dirn:          # a reversal: the last point joins the stack
                sv[m] = u_last
                sx[m] = x_last
                m += 1
            dirn = new_dir
            while m > 0:                               # Madelung's rules: closed inner loops are wiped out
                if m >= 2:
                    if (u - sv[m - 2]) * dirn >= 0.0:
                        m -= 2
                        continue
                elif (u + sv[0]) * dirn >= 0.0:        # past the first reversal's mirror: back on the virgin curve
                    m -= 1
                    continue
                break
            if m == 0:
                x_last = u + c * V0 * _ra_skel(u / V0, n)
            else:
                half = 0.5 * (u - sv[m - 1])
                x_last = sx[m - 1] + 2.0 * (half + c * V0 * _ra_skel(half / V0, n))
            u_last = u
        out[k] = x_last
    return out, sv[:m].copy(), sx[:m].copy(), u_last, x_last, dirn


def strap_core(v, V0, c, n, state=None, return_state=False):
    """The stage's travel x under a drive v that sets the force on a metal strap flexure in series with the actuator:
    the actuator's own compliance (x = v) plus the strap's, c times it at small loads, in its elastic-plastic
    transition by :func:`richard_abbott_strain` (V0 the drive at the strap's plastic asymptote). From the virgin state
    x = v + c V0 eps(v / V0); on unloading and reloading Masing's rule (Masing 1926, on brass: every branch from a
    reversal (v_r, x_r) is the virgin curve doubled, x_r + 2 (e + c V0 eps(e / V0)), e = (v - v_r) / 2) with Madelung's
    memory rules (an inner loop closed is wiped out and the branch left there resumed; passing the mirror image of the
    first reversal rejoins the virgin curve). Computed from a stack of turning points, not from plays. ``state`` is
    (the turning points' v, their x, the last input, the last output, the last direction), as returned with
    ``return_state``; None is the virgin state at 0 V."""
    if state is None:
        sv, sx, u0, x0, d0 = np.zeros(0), np.zeros(0), 0.0, 0.0, 0
    else:
        sv, sx = np.asarray(state[0], float), np.asarray(state[1], float)
        u0, x0, d0 = float(state[2]), float(state[3]), int(state[4])
    out, sv, sx, u0, x0, d0 = _ra_masing(np.asarray(v, float), float(V0), float(c), float(n), sv, sx, len(sv),
                                         float(u0), float(x0), int(d0))
    if return_state:
        return out, (sv, sx, u0, x0, d0)
    return out


def strap_density(r, V0, c, n):
    """The density of play thresholds r (0 < r < V0) of the PI model equal to :func:`strap_core`: the virgin curve's
    second derivative, (c / V0) (n + 1) q^(n - 1) (1 - q^n)^(-(2 n + 1) / n), q = r / V0 (with a linear part 1 + c);
    used only by the test."""
    q = np.asarray(r, float) / V0
    return (c / V0) * (n + 1.0) * q ** (n - 1.0) * (1.0 - q ** n) ** (-(2.0 * n + 1.0) / n)


# ---- creep: anelastic relaxation with a Gaussian spread of activation energies (a log-normal spectrum) ----

def lognormal_spectrum(tau_m, beta, n_nodes=40):
    """Relaxation times whose logarithms are normally distributed about ln tau_m with standard deviation beta: what a
    Gaussian spread of activation energies in an Arrhenius process gives (Wagner, Ann. Phys. 40 (1913) 817, for
    dielectrics; Nowick & Berry, *Anelastic Relaxation in Crystalline Solids*, 1972, ch. 4, for anelasticity). The
    continuous distribution is taken at the nodes of Gauss-Hermite quadrature (probabilists' form): returns (taus,
    weights), the weights summing to 1."""
    x, w = np.polynomial.hermite_e.hermegauss(n_nodes)
    return tau_m * np.exp(beta * x), w / math.sqrt(2.0 * math.pi)


def kelvin_spectrum_strain(sigma, dt, taus, weights):
    """The delayed strain of a solid whose creep compliance is sum_j w_j (1 - exp(-t / tau_j)) (Kelvin elements in
    series) under a stress sigma given at the samples and linear between them, at rest at sigma[0] before the record:
    each element eps' = (sigma - eps) / tau solved exactly over a step (eps_new = b - s tau + (eps - a + s tau)
    exp(-dt / tau), the stress going from a to b with slope s); returns sum_j w_j eps_j - sigma[0]."""
    sig = np.asarray(sigma, float) - float(sigma[0])
    out = np.zeros_like(sig)
    for tau, w in zip(np.asarray(taus, float), np.asarray(weights, float)):
        E = math.exp(-dt / tau)
        g = -math.expm1(-dt / tau) * tau / dt
        out += w * lfilter([1.0 - g, g - E], [1.0, -E], sig)
    return out


def lognormal_creep(h, dt, c, tau_m, beta, t_ref=10.0, n_nodes=40):
    """Creep of the stage's pad under the core's force h: the delayed strain of :func:`kelvin_spectrum_strain` on the
    log-normal spectrum, scaled so that a step held t_ref s creeps by c of it; 0 at the start."""
    taus, w = lognormal_spectrum(tau_m, beta, n_nodes)
    step = np.minimum(np.arange(int(round(t_ref / dt)) + 2), 1.0)
    ref = kelvin_spectrum_strain(step, dt, taus, w)[-2]
    return c * kelvin_spectrum_strain(h, dt, taus, w) / ref


# ---- rate dependence: a piezoelectric patch on the stage shunted by a resistor ----

def shunted_patch_stage(h, dt, k_sc, dk, tau):
    """The stage's travel y when the actuator (stiffness 1, free stroke h from the core) pushes it against a
    piezoelectric patch shunted by a resistor R (Hagood & von Flotow, J. Sound Vib. 146 (1991) 243): the patch's
    stiffness is k_sc [1 + (k^2 / (1 - k^2)) s tau / (1 + s tau)] (short-circuit k_sc at low frequencies, open-circuit
    k_sc / (1 - k^2) at high ones, tau = R C_p^S), a standard linear solid: F = k_sc y + dk z, z' = y' - z / tau.
    With (h - y) = F: y = (h - dk z) / K, K = 1 + k_sc, and z' = (h' - K z / tau) / (K + dk), solved exactly with h
    linear between the samples; at rest at h[0] (z = 0) before the record."""
    h = np.asarray(h, float)
    K = 1.0 + k_sc
    lam = K / ((K + dk) * tau)
    a = 1.0 / (K + dk)
    E = math.exp(-lam * dt)
    dh = np.r_[0.0, np.diff(h)]
    z = lfilter([-a * math.expm1(-lam * dt) / (lam * dt)], [1.0, -E], dh)
    return (h - dk * z) / K


# ---- drift: a stage's support in a spherical dewar of liquid nitrogen boiling off ----

def dewar_level(t, R, d0, q):
    """The depth of liquid nitrogen in a spherical dewar of radius R, filled to d0 at t = 0 and boiling off by the heat
    leaking in through the wetted part of the inner wall (the ullage's wall warms the vapour, not the liquid): the heat
    flux per area q (in depth of liquid evaporated per second) over the wetted zone, whose area is 2 pi R d
    (Archimedes' hat-box theorem), lowers the volume, whose change with depth is the free surface's area pi d (2 R -
    d): d' = -2 q R / (2 R - d), so (2 R - d)^2 = (2 R - d0)^2 + 4 q R t. The level falls fast while the surface is
    small near the top and ever more slowly after."""
    return 2.0 * R - np.sqrt((2.0 * R - d0) ** 2 + 4.0 * q * R * np.asarray(t, float))


# ---- asymmetry: a tilting parallel plate (an optical micrometer) in a laser beam ----

def plate_shift(theta, n):
    """The lateral shift of a ray through a plane-parallel plate of index n and thickness 1 tilted by theta (the
    parallel-plate micrometer of surveying levels; e.g. Jenkins & White, *Fundamentals of Optics*, 1976, ch. 2): sin
    theta (1 - cos theta / sqrt(n^2 - sin^2 theta)); odd, steepening with the tilt."""
    th = np.asarray(theta, float)
    s = np.sin(th)
    return s * (1.0 - np.cos(th) / np.sqrt(n * n - s * s))


def plate_slope(theta, n):
    """The derivative of :func:`plate_shift`: cos theta - cos 2 theta / sqrt(n^2 - s^2) - s^2 cos^2 theta / (n^2 -
    s^2)^(3/2), s = sin theta."""
    th = np.asarray(theta, float)
    s2 = np.sin(th) ** 2
    r = n * n - s2
    return np.cos(th) - np.cos(2 * th) / np.sqrt(r) - s2 * np.cos(th) ** 2 / r ** 1.5


def plate_reading(u, theta0, k, n):
    """The beam's shift read on a position-sensitive detector as the stage tilts the plate, pre-tilted by theta0, by k u
    (u in -1 ... 1), scaled to slope 1 at u = 0: (shift(theta0 + k u) - shift(theta0)) / (k shift'(theta0)); convex
    for theta0 > 0."""
    u = np.asarray(u, float)
    return (plate_shift(theta0 + k * u, n) - float(plate_shift(theta0, n))) / (k * float(plate_slope(theta0, n)))


def plate_asym(theta0, k, n):
    """The ends' secants' difference, reading(1) + reading(-1)."""
    return float(plate_reading(1.0, theta0, k, n) + plate_reading(-1.0, theta0, k, n))


# ---- saturation: an LED on the stage between two photodiodes, read ratiometrically ----

def ratiometric_pair(u):
    """An LED carried by the stage between two photodiodes facing it along the travel, each d from the middle, u the
    travel over d: the irradiances go as the inverse square of the distances, 1 / (1 - u)^2 and 1 / (1 + u)^2, and the
    reading is their normalised difference (P1 - P2) / (P1 + P2) = 2 u / (1 + u^2) (a ratiometric position sensor,
    insensitive to the LED's brightness), halved to slope 1 at the middle: u / (1 + u^2); odd, the ends compressed by
    u^2 / (1 + u^2)."""
    u = np.asarray(u, float)
    return u / (1.0 + u * u)


# ---- delay: a programmable logic controller's scan cycle ----

def plc_register(t, t_fine, h_fine, scan_starts):
    """The value a data logger reads from a programmable logic controller's output register at times t: scan i runs
    from scan_starts[i] to scan_starts[i + 1], latching the input image at its start and writing the output image at
    its end (IEC 61131-3's cyclic execution: read inputs, execute, write outputs). At t in scan j the register holds the
    input latched at the start of scan j - 1 (h[0] before the first scan's end)."""
    t = np.asarray(t, float)
    s = np.asarray(scan_starts, float)
    j = np.searchsorted(s, t, side="right") - 1                # the scan running at t
    latched = np.where(j >= 1, s[np.maximum(j - 1, 0)], t_fine[0])
    return np.interp(latched, t_fine, h_fine)


# ---- the pair: cold flow of a PTFE slide pad (Findley) and a warming ferrite magnet read by a Hall sensor (gain) ----

def findley_creep(h, dt, c, n_exp, t_ref=10.0):
    """Creep of a PTFE slide pad under the core's force h by Findley's power law, J(t) = J0 (1 + c (t / t_ref)^n)
    (Findley, Lai & Onaran, *Creep and Relaxation of Nonlinear Viscoelastic Materials*, 1976; n about 0.2 ... 0.5 for
    thermoplastics), superposed after Boltzmann with h linear between the samples: the step's increment dh_j spread
    over its sample gives c (dt / t_ref)^n ((m + 1)^(n + 1) - m^(n + 1)) / (n + 1) m samples later. A convolution, done
    by FFT; 0 at the start, a step held t_ref s creeps by c of it (up to the spreading over one sample)."""
    h = np.asarray(h, float)
    m = np.arange(len(h), dtype=float)
    kern = ((m + 1.0) ** (n_exp + 1.0) - m ** (n_exp + 1.0)) / (n_exp + 1.0)
    dh = np.r_[0.0, np.diff(h)]
    return c * (dt / t_ref) ** n_exp * fftconvolve(dh, kern)[:len(h)]


def magnet_warmup_gain(t, t_on, tau, dT, alpha):
    """The gain of a Hall sensor reading the field of a hard ferrite (ceramic) magnet on the stage as the magnet warms:
    its remanence falls by the reversible temperature coefficient alpha (about -0.2 % per K for ferrite, against
    -0.12 for NdFeB and -0.03 for SmCo; e.g. the magnet makers' data sheets, MMPA standard 0100) as a lumped body heated
    from t_on (the drive coil's bias switched on) warms by dT (1 - exp(-(t - t_on) / tau)) (Newton's law); 1 before
    t_on."""
    s = np.maximum(np.asarray(t, float) - t_on, 0.0)
    return 1.0 + alpha * dT * (-np.expm1(-s / tau))


# ---- out of vocabulary: an LVDT read without its phase ----

def unphased_lvdt(x, x_null, e_q):
    """An LVDT whose secondaries' difference, (x - x_null) sin(w t) in phase with the excitation plus a residual
    quadrature null voltage e_q cos(w t), is read by an AC voltmeter (its amplitude, not a phase-sensitive
    demodulator): sqrt((x - x_null)^2 + e_q^2). The reading folds at the null: the same reading on both sides of it
    (e.g. Herceg, *Handbook of Measurement and Control*, 1976, on the LVDT's null and why it needs synchronous
    demodulation)."""
    x = np.asarray(x, float)
    return np.hypot(x - x_null, e_q)

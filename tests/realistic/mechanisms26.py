"""Mechanisms of the HOLDOUT26 set (``cases_holdout26.py``), each written from its law; the signals are in
:mod:`.signals26`.

Nothing here imports hystcomp. Every mechanism takes the (clean) drive, or the core's output, and returns the response;
all are causal. The play, its threshold grid, a path's turning points, the raised cosine and the exact Kelvin-element
recursion are the earlier sets' (the same laws, imported as mechanisms25 does).

Citations: every source below was written from memory in this session (none was re-read); volumes, pages and years may
be off. The laws do not rest on them: each is checked in tests/test_realistic_holdout26.py against an independent
solution (a closed form, quadrature, brentq, solve_ivp, scipy's own routines or a finer simulation).
"""

import math

import numpy as np
from scipy.linalg import expm

from .mechanisms13 import turning_points  # noqa: F401
from .mechanisms18 import grid, plays  # noqa: F401
from .mechanisms19 import raised_cosine  # noqa: F401
from .mechanisms24 import kelvin_modes_response


# ---- the rate-independent core: a bolted joint's microslip (Segalman's four-parameter Iwan model) ----

def segalman_iwan(n, phi_max, chi, beta, k_t):
    """The Jenkins elements (a spring in series with a Coulomb slider) of Segalman's four-parameter Iwan model of a
    lap joint (Segalman, J. Appl. Mech. 72 (2005) 752; Iwan, J. Appl. Mech. 33 (1966) 893): the density of the
    sliders' slip displacements R phi^chi on (0, phi_max) (-1 < chi <= 0) plus a lump S delta(phi - phi_max) (the
    macroslip), S / (R phi_max^(chi + 1) / (chi + 1)) = beta, the stiffnesses summing to k_t. The joint's force under
    a displacement u is sum_i w_i stop_{phi_i}(u). Returns (phi, w): n cells of equal width, each a slider at its cell's
    mean slip displacement with the cell's exact stiffness R (b^(chi + 1) - a^(chi + 1)) / (chi + 1), and the lump at
    phi_max."""
    edges = np.linspace(0.0, phi_max, n + 1)
    e1 = edges ** (chi + 1)
    e2 = edges ** (chi + 2)
    cell_w = (e1[1:] - e1[:-1]) / (chi + 1)
    cell_m = (e2[1:] - e2[:-1]) / (chi + 2)
    R = k_t / (1 + beta) / (phi_max ** (chi + 1) / (chi + 1))
    phi = np.r_[cell_m / cell_w, phi_max]
    w = np.r_[R * cell_w, beta * k_t / (1 + beta)]
    return phi, w


def iwan_inverse_plays(phi, w, k0):
    """The play-type Prandtl-Ishlinskii operator that inverts the stop-type one F = k0 u + sum_i w_i stop_{phi_i}(u)
    (Krasnosel'skii & Pokrovskii 1989; Brokate & Sprekels, *Hysteresis and Phase Transitions*, 1996, sec. 2.3: the
    inverse of a stop-type operator with the initial loading curve p is the play-type operator with the loading curve
    p^-1). p(u) = k0 u + sum w_i min(u, phi_i) is concave and piecewise linear; its inverse has the slope 1 / (k0 +
    sum of the stiffnesses not yet slipping) between the forces p(phi_i). Returns (thresholds r, weights, linear part
    w0) for :func:`plays` driven by the force."""
    order = np.argsort(phi)
    phi, w = np.asarray(phi, float)[order], np.asarray(w, float)[order]
    stuck = k0 + np.r_[np.cumsum(w[::-1])[::-1], 0.0]           # stiffness before each breakpoint, and after all
    r = k0 * phi + np.cumsum(w * phi) + phi * (stuck[1:] - k0)  # p(phi_j): the force at each slider's slip
    weights = 1.0 / stuck[1:] - 1.0 / stuck[:-1]
    return r, weights, 1.0 / stuck[0]


def iwan_displacement(force, phi, w, k0):
    """The displacement u of a stage held by a flexure (stiffness k0) in parallel with an Iwan joint (the sliders phi,
    stiffnesses w), pushed by `force` from the virgin state (every slider at 0): at each sample the force balance k0 u
    + sum_i w_i e_i = F, e_i = u - p_i the elastic stretch of element i, clipped to +-phi_i as its slider p_i moves
    (Jenkins elements in parallel: the parallel Iwan model). On a rising force the balance g(u) = k0 u + sum_i w_i
    min(u - p_i, phi_i) is concave and piecewise linear in u, so Newton's steps from the last u never pass the root
    and end on it once no element starts to slip within a step (exact but for rounding); a falling force is the
    mirror image. Returns u."""
    F = np.asarray(force, float).tolist()
    phi = np.asarray(phi, float)
    w = np.asarray(w, float)
    p = np.zeros_like(phi)
    u, f_prev = 0.0, 0.0
    out = np.empty(len(F))
    for k, f in enumerate(F):
        if f != f_prev:
            s = 1.0 if f > f_prev else -1.0
            ps, target, um = s * p, s * f, s * u                # mirror a falling force into a rising one
            c = ps + phi                                        # where each element starts to slip
            for _ in range(len(phi) + 2):
                g = k0 * um + float(w @ np.minimum(um - ps, phi))
                if g >= target:
                    break
                step = (target - g) / (k0 + float(w @ (c > um)))
                if step <= 1e-15 * (abs(um) + 1.0):
                    break
                um += step
            u = s * um
            p = s * np.maximum(ps, um - phi)
            f_prev = f
        out[k] = u
    return out


# ---- creep: the Gorsky effect (hydrogen diffusing across a bent flexure) ----

def gorsky_modes(n_modes=400):
    """The Gorsky relaxation of a bent plate of thickness d (Gorsky, Phys. Z. Sowjetunion 8 (1935) 457; Alefeld,
    Voelkl & Schaumann, Phys. Status Solidi 37 (1970) 337): the bending stress is linear across the thickness, so the
    interstitial hydrogen's equilibrium concentration is too; after a step of the load the hydrogen diffuses (Fick,
    the surfaces closed: no flux through them) from the compressed side to the stretched one, and its expansion adds
    a curvature of the first moment of the profile. The antisymmetric Neumann modes sin(k pi z / d), k odd, decay at
    k^2 / tau, tau = d^2 / (pi^2 D), and carry 96 / (pi^4 k^4) of the first moment (their sum is 1: sum over odd k of
    k^-4 = pi^4 / 96; the first mode carries 98.6 %, as in Zener's thermoelastic relaxation of a reed). Returns (k^2,
    96 / (pi^4 k^4)) for the first n_modes odd k."""
    k = 2.0 * np.arange(n_modes) + 1.0
    return k * k, 96.0 / (math.pi ** 4 * k ** 4)


def gorsky_function(t, tau, n_modes=400):
    """The creep function 1 - sum_k w_k exp(-k^2 t / tau) of :func:`gorsky_modes` (0 at t = 0, 1 at the end; the modes
    beyond n_modes, 3e-10 of the whole, counted as done)."""
    rates, w = gorsky_modes(n_modes)
    t = np.clip(np.asarray(t, float), 0.0, None)[..., None]
    return 1.0 - np.sum(w * np.exp(-rates * t / tau), axis=-1)


def gorsky_creep(h, dt, c, tau, t_ref=10.0, n_modes=400):
    """The creep of a hydrogen-charged niobium flexure under the core's force (its output h): Boltzmann superposition
    of :func:`gorsky_function`, a Kelvin element per mode (exact for h linear between samples), scaled so that a step
    held t_ref s creeps by c of it; at rest at h[0] before the record (creep 0 there)."""
    rates, w = gorsky_modes(n_modes)
    h = np.asarray(h, float)
    resp = kelvin_modes_response(h - h[0], dt, tau / rates, w) + (1.0 - float(np.sum(w))) * (h - h[0])
    return c * resp / float(gorsky_function(t_ref, tau, n_modes))


# ---- rate dependence: a plate sheared through an oil gap (unsteady Couette flow) ----

def couette_matrices(tau_c, t_nu, n_modes=40):
    """A stage (stiffness k) whose damper is a plate of area A sliding past a wall H away across an oil of viscosity mu
    and kinematic viscosity nu: the oil's velocity obeys u_t = nu u_yy, the plate's velocity at y = 0, the wall's 0 at
    y = H (Stokes's second problem in a gap: Stokes, Trans. Camb. Phil. Soc. 9 (1851) 8; Batchelor, *An Introduction to
    Fluid Dynamics*, 1967, sec. 4.3); the drag on the plate is A mu q coth(q H) times its velocity, q = sqrt(s / nu):
    Couette's mu A / H when slow, growing as sqrt(s) when fast (the oil's inertia: the shear wave's depth sqrt(nu / s)).
    The balance k (h - x) = drag gives X / H = 1 / (1 + tau_c s F(s t_nu)), tau_c = mu A / (k H), t_nu = H^2 / nu,
    F(z) = sqrt(z) coth(sqrt(z)) = 1 + sum_n 2 z / (z + n^2 pi^2) (Mittag-Leffler's series of the cotangent). The
    first n_modes terms are states g_n' = lam_n (x' - g_n), lam_n = n^2 pi^2 / t_nu; the rest, for |s| t_nu << (n_modes
    pi)^2, a mass 2 t_nu T tau_c, T = sum_{n > n_modes} 1 / (n pi)^2 = psi_1(n_modes + 1) / pi^2. Returns (A, B, C) of
    x' = A x + B h, y = C x, the state (x, x', g_1 ... g_n)."""
    from scipy.special import polygamma
    N = n_modes
    lam = (np.arange(1, N + 1) * math.pi) ** 2 / t_nu
    T = float(polygamma(1, N + 1)) / math.pi ** 2
    m = 2 * t_nu * T
    A = np.zeros((N + 2, N + 2))
    A[0, 1] = 1.0
    A[1, 0] = -1.0 / (tau_c * m)
    A[1, 1] = -(1 + 2 * N) / m
    A[1, 2:] = 2.0 / m
    A[2:, 1] = lam
    A[2:, 2:] = -np.diag(lam)
    B = np.zeros((N + 2, 1))
    B[1, 0] = 1.0 / (tau_c * m)
    C = np.zeros((1, N + 2))
    C[0, 0] = 1.0
    return A, B, C


def couette_transfer(omega, tau_c, t_nu):
    """The closed form X / H = 1 / (1 + tau_c s sqrt(s t_nu) coth(sqrt(s t_nu))), s = i omega."""
    s = 1j * np.asarray(omega, float)
    q = np.sqrt(s * t_nu)
    return 1.0 / (1.0 + tau_c * s * q / np.tanh(q))


def couette_stage(h, dt, tau_c, t_nu, n_modes=40):
    """The stage's travel under the core's output h (linear between samples: exact by the first-order hold), at rest
    at h[0] before the record."""
    A, B, C = couette_matrices(tau_c, t_nu, n_modes)
    h = np.asarray(h, float)
    x0 = np.zeros(A.shape[0])
    x0[0] = h[0]
    return foh_response(A, B, C, h, dt, x0)


def foh_response(A, B, C, u, dt, x0):
    """The exact response of x' = A x + B u, y = C x to u linear between samples (the first-order hold: x1 = Phi x0 +
    G0 u0 + G1 (u1 - u0), the blocks of expm([[A dt, B dt, 0], [0, 0, 1], [0, 0, 0]]); Van Loan, IEEE TAC 23 (1978)
    395), from the state x0."""
    n = A.shape[0]
    M = np.zeros((n + 2, n + 2))
    M[:n, :n] = A * dt
    M[:n, n] = B[:, 0] * dt
    M[n, n + 1] = 1.0
    E = expm(M)
    Phi, G0, G1 = E[:n, :n], E[:n, n], E[:n, n + 1]
    u = np.asarray(u, float)
    x = np.array(x0, float)
    out = np.empty(len(u))
    c = C[0]
    out[0] = c @ x
    for k in range(1, len(u)):
        x = Phi @ x + G0 * u[k - 1] + G1 * (u[k] - u[k - 1])
        out[k] = c @ x
    return out


# ---- offset drift: a solvent droplet evaporating on a capacitive sensor's target ----

def cap_volume_factor(theta):
    """A spherical cap's volume over pi R^3, R its contact radius and theta its contact angle: (2 + cos theta) (1 -
    cos theta)^2 / (3 sin^3 theta); at fixed R its derivative in theta is 1 / (1 + cos theta)^2."""
    c, s = np.cos(theta), np.sin(theta)
    return (2 + c) * (1 - c) ** 2 / (3 * s ** 3)


def hu_larson_flux(theta):
    """Hu & Larson's fit (J. Phys. Chem. B 106 (2002) 1334) of a sessile drop's diffusion-limited evaporation, dm/dt =
    -pi R D c_v (1 - H) (0.27 theta^2 + 1.30): the factor 0.27 theta^2 + 1.30 (theta in radians, up to pi / 2)."""
    return 0.27 * np.asarray(theta, float) ** 2 + 1.30


def droplet_stages(theta0, theta_r):
    """The durations, in units of R0^2 / K (K = D c_v (1 - H) / rho_liquid), of a drop's two stages (Picknett & Bexon,
    J. Colloid Interface Sci. 61 (1977) 336): pinned at its contact radius R0 while its angle falls from theta0 to the
    receding angle theta_r (dtheta/dT = -f(theta) (1 + cos theta)^2 from dV/dt = -pi K R f(theta)), then shrinking at
    theta_r (R^2 falling linearly, at 2 f(theta_r) / (3 G(theta_r)), G = :func:`cap_volume_factor`) to nothing.
    Returns (T1, T2); T1 by 64-point Gauss-Legendre."""
    x, wq = np.polynomial.legendre.leggauss(64)
    th = theta_r + (theta0 - theta_r) * (x + 1) / 2
    T1 = float(np.sum(wq / (hu_larson_flux(th) * (1 + np.cos(th)) ** 2))) * (theta0 - theta_r) / 2
    T2 = 3 * float(cap_volume_factor(theta_r)) / (2 * float(hu_larson_flux(theta_r)))
    return T1, T2


def droplet_volume(T, theta0, theta_r):
    """The drop's volume over its first, V / V0, at the times T (units of R0^2 / K, from its deposition): the pinned
    stage by solve_ivp (DOP853, rtol 1e-12) of the angle, then the shrinking stage in closed form, (R / R0)^3 G(theta_r)
    / G(theta0) with (R / R0)^2 = 1 - (T - T1) / T2; 0 once it is gone."""
    from scipy.integrate import solve_ivp
    T = np.asarray(T, float)
    T1, T2 = droplet_stages(theta0, theta_r)
    G0, Gr = float(cap_volume_factor(theta0)), float(cap_volume_factor(theta_r))
    out = np.zeros_like(T)
    m1 = T < T1
    if np.any(m1):
        sol = solve_ivp(lambda s, th: [-float(hu_larson_flux(th[0])) * (1 + math.cos(th[0])) ** 2], (0.0, T1),
                        [theta0], method="DOP853", rtol=1e-12, atol=1e-14, dense_output=True)
        th = sol.sol(np.clip(T[m1], 0.0, None))[0]
        out[m1] = cap_volume_factor(th) / G0
    m2 = (T >= T1) & (T < T1 + T2)
    out[m2] = (1 - (T[m2] - T1) / T2) ** 1.5 * Gr / G0
    return out


# ---- asymmetry: a lab jack's scissor linkage ----

def scissor_reading(x, s0, ds):
    """The platform of a scissor lab jack (n crossed pairs of bars of length L pinned at their middles, each pair's
    sliding foot s from its fixed one: the height n sqrt(L^2 - s^2); lengths over L) that the stage raises by pushing
    the sliding feet in, s = s0 - ds x (x the stage's travel over its largest): the rise from rest over its slope
    there, (sqrt(1 - s^2) - sqrt(1 - s0^2)) / (ds s0 / sqrt(1 - s0^2)): monotone, concave (the rise per push falls as
    the jack opens: its slope is s / sqrt(1 - s^2); e.g. any text on linkages' kinematics)."""
    s = s0 - ds * np.asarray(x, float)
    return (np.sqrt(1 - s * s) - math.sqrt(1 - s0 * s0)) / (ds * s0 / math.sqrt(1 - s0 * s0))


# ---- saturation: a Hall probe in a gradient (anti-Helmholtz) coil pair ----

def loop_axial_field(z, R=1.0):
    """The field on the axis of a circular loop of radius R, z from its plane, over mu0 I: R^2 / (2 (R^2 + z^2)^(3/2))
    (Biot-Savart)."""
    z = np.asarray(z, float)
    return R * R / (2 * (R * R + z * z) ** 1.5)


def gradient_pair_field(z, d):
    """Two coaxial loops of radius 1 at z = -d and z = +d carrying opposite currents (an anti-Helmholtz, or Maxwell
    gradient, pair): B(z) = b(z - d) - b(z + d), b = :func:`loop_axial_field`; odd, its slope at the centre 3 d / (1 +
    d^2)^(5/2), its third derivative zero there at Maxwell's spacing d = sqrt(3) / 2 (Maxwell, *Treatise*, 1873, sec.
    715)."""
    z = np.asarray(z, float)
    return loop_axial_field(z - d) - loop_axial_field(z + d)


def gradient_reading(x, d, z_max):
    """A Hall probe carried by the stage along the pair's axis (x its travel over the largest, z_max the largest in
    loop radii): B(x z_max) over its slope at the centre times z_max: odd, slope 1 at 0, compressed towards the coils
    (the field peaks near them)."""
    return gradient_pair_field(np.asarray(x, float) * z_max, d) / (3 * d / (1 + d * d) ** 2.5 * z_max)


# ---- delay: a Bessel-Thomson anti-aliasing filter ----

def reverse_bessel(n):
    """The coefficients a_k (of s^k, k = 0 ... n) of the reverse Bessel polynomial theta_n(s) = sum_k (2n - k)! /
    (2^(n - k) k! (n - k)!) s^k (Thomson, Proc. IEE 96 (1949) 487; Storch 1954): theta_4 = s^4 + 10 s^3 + 45 s^2 +
    105 s + 105."""
    return np.array([math.factorial(2 * n - k) / (2 ** (n - k) * math.factorial(k) * math.factorial(n - k))
                     for k in range(n + 1)])


def bessel_sensor(h_fine, dt_fine, tau, n=4):
    """A sensor whose conditioning ends in an n-pole Bessel-Thomson low-pass of group delay tau at DC, H(s) = theta_n(0)
    / theta_n(s tau): the flattest group delay of its order, a delay of tau for everything well below its corner
    (about 2.1 / tau rad/s for n = 4) (Thomson 1949). The controllable canonical form in the time t / tau, exact for
    h linear between the fine samples; at rest at h[0] before the record."""
    a = reverse_bessel(n)
    A = np.zeros((n, n))
    A[:-1, 1:] = np.eye(n - 1)
    A[-1, :] = -a[:n] / a[n]
    B = np.zeros((n, 1))
    B[-1, 0] = 1.0
    C = np.zeros((1, n))
    C[0, 0] = a[0] / a[n]
    h = np.asarray(h_fine, float)
    x0 = np.zeros(n)
    x0[0] = h[0] * a[n] / a[0]
    return foh_response(A, B, C, h, dt_fine / tau, x0)


# ---- the pair: Wiechert's log-normal retardation spectrum and an equisolid-angle fisheye ----

def wiechert_prony(tau_m, s, du=0.05, width=8.0):
    """Wiechert's log-normal distribution of retardation times (Wiechert, Ann. Phys. 286 (1893) 335, for the elastic
    after-effect; K. W. Wagner, Ann. Phys. 345 (1913) 817, for dielectrics): ln tau normal about ln tau_m with the
    deviation s. Returns (taus, weights) on a grid of du in ln tau over +-width s (the weights the normal density times
    du, normalised to 1: the trapezoid rule on a smooth integrand)."""
    u = np.arange(-width * s, width * s + du / 2, du)
    w = np.exp(-0.5 * (u / s) ** 2)
    return tau_m * np.exp(u), w / w.sum()


def wiechert_function(t, tau_m, s):
    """The creep function sum_i w_i (1 - exp(-t / tau_i)) of :func:`wiechert_prony`."""
    taus, w = wiechert_prony(tau_m, s)
    t = np.clip(np.asarray(t, float), 0.0, None)[..., None]
    return np.sum(w * -np.expm1(-t / taus), axis=-1)


def wiechert_creep(h, dt, c, tau_m, s, t_ref=10.0):
    """Creep of the stage's elastomer mounts by Boltzmann superposition of :func:`wiechert_function` over the core's
    output h (a Kelvin element per retardation time, exact for h linear between samples), scaled so that a step held
    t_ref s creeps by c of it; at rest at h[0] before the record."""
    taus, w = wiechert_prony(tau_m, s)
    h = np.asarray(h, float)
    return c * kelvin_modes_response(h - h[0], dt, taus, w) / float(wiechert_function(t_ref, tau_m, s))


def fisheye_reading(x, a):
    """A camera with an equisolid-angle fisheye lens (image radius 2 f sin(theta / 2), so that equal solid angles get
    equal image areas: Miyamoto, J. Opt. Soc. Am. 54 (1964) 1060) looking down at a target that the stage carries
    across its view, a = (largest travel) / (the target's distance D) (theta = atan(a x)): the image's position over
    its slope at the axis, 2 sin(atan(a x) / 2) / a: odd, slope 1 at 0, compressed towards the edges of the view."""
    return 2 * np.sin(np.arctan(a * np.asarray(x, float)) / 2) / a


# ---- out of vocabulary: a loose ball rattling on the stage's sprung platform ----

def _osc_step(p, pd, a, c, u0, sl, tau):
    """The exact state after tau of x'' + c x' + a x = u0 + sl t (underdamped: c^2 < 4 a) from (p, pd): the particular
    ramp solution plus the damped free oscillation."""
    pp0 = u0 / a - c * sl / (a * a)
    vp = sl / a
    y0, y1 = p - pp0, pd - vp
    sig = 0.5 * c
    wd = math.sqrt(a - sig * sig)
    ex, co, si = math.exp(-sig * tau), math.cos(wd * tau), math.sin(wd * tau)
    y = ex * (y0 * co + (y1 + sig * y0) / wd * si)
    yd = ex * (y1 * co - (sig * y1 + a * y0) / wd * si)
    return pp0 + vp * tau + y, vp + yd


def rattling_platform(h, dt, w_p, zeta, mu, e, g, v_stick, p0=None):
    """A platform of mass M on a spring and damper (w_p, zeta) to the stage, whose travel is h (metres, linear between
    the fine samples dt apart), with a loose ball of mass mu M on it, falling under g and struck with the restitution
    e (Newton's law of impact; momentum conserved with the platform). Resting, the ball moves with the platform ((1 +
    mu) p'' = w_p^2 (h - p) + 2 zeta w_p (h' - p') - mu g) until the platform's acceleration falls below -g (its
    contact force m (g + p'') would turn negative: it is thrown); in flight it falls freely (b'' = -g) while the
    platform rings on its own (p'' = w_p^2 (h - p) + 2 zeta w_p (h' - p')) until they meet; an impact slower than
    v_stick ends in rest (the bounces' geometric series, summed; a ball on a vibrating table: Holmes, J. Sound Vib. 84
    (1982) 173; Luck & Mehta, Phys. Rev. E 48 (1993) 3988 on the ball's coming to rest). The platform between events
    by the exact step of its linear dynamics; the impacts and lift-offs located by brentq (xtol 1e-15 s). From rest on
    the static sag unless p0 = (p, p') is given, the ball resting. Returns (p, b, flying, impacts): the platform and
    the ball at the samples, whether it flies, and a list of (time, relative speed) of the impacts."""
    from scipy.optimize import brentq
    h = np.asarray(h, float).tolist()
    a_f, c_f = w_p * w_p, 2 * zeta * w_p
    a_r, c_r = a_f / (1 + mu), c_f / (1 + mu)

    def step(p, pd, fly, u0, sl, tau):                    # u = w_p^2 h + 2 zeta w_p h' (- mu g at rest), linear
        if fly:
            return _osc_step(p, pd, a_f, c_f, u0, sl, tau)
        return _osc_step(p, pd, a_r, c_r, u0 / (1 + mu), sl / (1 + mu), tau)

    def accel_rest(p, pd, u):
        return (-a_f * p - c_f * pd + u) / (1 + mu)

    n = len(h)
    if p0 is None:
        p, pd = h[0] - mu * g / a_f, 0.0
    else:
        p, pd = float(p0[0]), float(p0[1])
    fly, b, bd = False, p, pd
    P_out, B_out, F_out, impacts = np.empty(n), np.empty(n), np.zeros(n, bool), []
    P_out[0], B_out[0] = p, p
    for k in range(n - 1):
        hd = (h[k + 1] - h[k]) / dt
        sl = a_f * hd
        base = c_f * hd
        ta, events = 0.0, 0
        while ta < dt:
            tau = dt - ta
            u0 = a_f * (h[k] + hd * ta) + base - (0.0 if fly else mu * g)
            if fly:
                def gap(s):
                    return b + bd * s - 0.5 * g * s * s - step(p, pd, True, u0, sl, s)[0]
                if gap(tau) >= 0.0:
                    b, bd = b + bd * tau - 0.5 * g * tau * tau, bd - g * tau
                    p, pd = step(p, pd, True, u0, sl, tau)
                    ta = dt
                    continue
                lo = 1e-6 * tau if events else 0.0
                if events and gap(lo) <= 0.0:
                    s, grazing = lo, True                         # met again at once: the bounces have died out
                else:
                    s, grazing = brentq(gap, lo, tau, xtol=1e-15), False
                ps, pds = step(p, pd, True, u0, sl, s)
                bds = bd - g * s
                w = bds - pds                                     # relative speed (< 0: closing)
                u_now = u0 + sl * s - mu * g
                events += 1
                ta += s
                impacts.append((k * dt + ta, w))
                if grazing or e * abs(w) < v_stick:
                    v_common = (mu * bds + pds) / (1 + mu)        # a plastic impact: the ball comes to rest
                    p, pd, b, bd = ps, v_common, ps, v_common
                    if accel_rest(p, pd, u_now) > -g:
                        fly = False
                    continue
                p, pd = ps, pds + mu * (1 + e) * w / (1 + mu)
                b, bd = ps, pd - e * w
            else:
                def lift(s):
                    pp, ppd = step(p, pd, False, u0, sl, s)
                    return accel_rest(pp, ppd, u0 + sl * s) + g
                if lift(tau) >= 0.0:
                    p, pd = step(p, pd, False, u0, sl, tau)
                    ta = dt
                    continue
                s = brentq(lift, 0.0, tau, xtol=1e-15) if lift(0.0) > 0 else 0.0
                if s > 0:
                    p, pd = step(p, pd, False, u0, sl, s)
                b, bd = p, pd
                fly = True
                ta += s
        P_out[k + 1] = p
        B_out[k + 1] = b if fly else p
        F_out[k + 1] = fly
    return P_out, B_out, F_out, impacts


# ---- initial state: a regula falsi (Illinois) search run on the stage ----

def illinois_search(r, w, w0, gain, target, lo, hi, n_iter):
    """The drives a regula falsi search visits while it looks for the one that brings the stage's output (the core's
    gain times :func:`plays`, from the virgin state at 0) to `target`: the bracket's ends lo and hi first, then the
    secant's root of the bracket, the end whose value kept its sign halved each time it is kept twice (the Illinois
    variant: Dowell & Jarratt, BIT 11 (1971) 168); each drive reached by a monotone move from the last (a play's state
    after a monotone move is its last value clipped to the new drive +- r). Returns the path (from lo) and the outputs
    measured at its points."""
    z = np.zeros(len(r))

    def measure(x):
        nonlocal z
        z = np.minimum(np.maximum(z, x - r), x + r)
        return gain * (w0 * x + float(w @ z)) - target
    a, fa = lo, measure(lo)
    path, meas = [lo], [fa]
    b, fb = hi, measure(hi)
    path.append(hi)
    meas.append(fb)
    side = 0
    for _ in range(n_iter):
        c = (a * fb - b * fa) / (fb - fa)
        fc = measure(c)
        path.append(c)
        meas.append(fc)
        if fc * fb > 0:
            b, fb = c, fc
            if side == -1:
                fa /= 2
            side = -1
        elif fa * fc > 0:
            a, fa = c, fc
            if side == 1:
                fb /= 2
            side = 1
        else:
            break
    return np.array(path), np.array(meas)


def platform_rest_accel(h, dt, w_p, zeta, mu):
    """The platform's acceleration with the ball resting on it throughout (no lift-off), exact for h linear between
    the samples: to set the drive's scale from the largest downward acceleration it asks of the ball."""
    h = np.asarray(h, float).tolist()
    a_r, c_r = w_p * w_p / (1 + mu), 2 * zeta * w_p / (1 + mu)
    p, pd = h[0], 0.0
    acc = np.empty(len(h))
    acc[0] = 0.0
    for k in range(len(h) - 1):
        hd = (h[k + 1] - h[k]) / dt
        u0 = (w_p * w_p * h[k] + 2 * zeta * w_p * hd) / (1 + mu)
        sl = w_p * w_p * hd / (1 + mu)
        p, pd = _osc_step(p, pd, a_r, c_r, u0, sl, dt)
        acc[k + 1] = -a_r * p - c_r * pd + u0 + sl * dt
    return acc


__all__ = ["turning_points", "grid", "plays", "raised_cosine", "kelvin_modes_response", "segalman_iwan",
           "iwan_inverse_plays", "iwan_displacement", "gorsky_modes", "gorsky_function", "gorsky_creep",
           "couette_matrices", "couette_transfer", "couette_stage", "foh_response", "cap_volume_factor",
           "hu_larson_flux", "droplet_stages", "droplet_volume", "scissor_reading", "loop_axial_field",
           "gradient_pair_field", "gradient_reading", "reverse_bessel", "bessel_sensor", "wiechert_prony",
           "wiechert_function", "wiechert_creep", "fisheye_reading", "rattling_platform", "platform_rest_accel",
           "illinois_search"]

"""Mechanisms of the HOLDOUT33 set (``cases_holdout33.py``), each written from its law; the signals are in
:mod:`.signals33`.

Nothing here imports hystcomp (nor another set's mechanisms). Every mechanism takes the (clean) drive, or the core's
output, and returns the response; all are causal.

Citations: every source below was written from memory in this session (none was re-read); volumes, pages and years may
be off. The laws do not rest on them: each is checked in tests/test_realistic_holdout33.py against an independent
solution (solve_ivp of the underlying equations, quad, brentq, a finite-difference or eigenvalue solution of a
discretised model, the transfer function solved in the frequency domain, a per-particle loop, or a direct sum).
"""

import math

import numpy as np
from numba import njit
from scipy.integrate import quad
from scipy.optimize import brentq
from scipy.signal import fftconvolve
from scipy.special import ndtri


# ---- the rate-independent core: an armature of Stoner-Wohlfarth particles ----
#
# Every particle is a single-domain grain with a uniaxial anisotropy (its shape's: an elongated grain) whose moment
# turns in the plane holding the coil's field and its easy axis (Stoner & Wohlfarth, Phil. Trans. R. Soc. A 240 (1948)
# 599). With theta the moment's angle from the field, psi the easy axis's, and u the field in units of the grain's
# anisotropy field H_K, the energy over 2 K V is E = (1/2) sin^2(theta - psi) - u cos(theta); its minima are the
# moment's states.

N_PSI = 48                       # easy-axis angles on 0 ... pi/2 (midpoints); the ensemble folds or mirrors onto them
U_MAX, N_Z = 60.0, 4097          # the branch tables reach u = 60, on a grid uniform in z = sqrt(u + h_sw)


def sw_energy(theta, psi, u):
    """E / (2 K V) = (1/2) sin^2(theta - psi) - u cos(theta) (Stoner & Wohlfarth 1948)."""
    theta = np.asarray(theta, float)
    return 0.5 * np.sin(theta - psi) ** 2 - u * np.cos(theta)


def sw_branch_field(theta, psi):
    """The field at which theta is an equilibrium, dE/dtheta = (1/2) sin 2(theta - psi) + u sin(theta) = 0, solved for
    u: -sin 2(theta - psi) / (2 sin theta). Along the branch that holds the moment near +psi (theta in 0 ... theta_sw,
    0 < psi < pi/2) it falls from +inf (theta -> 0) to -h_sw at the switching angle theta_sw, where the minimum
    merges with the barrier and the moment jumps to the other branch."""
    theta = np.asarray(theta, float)
    return -np.sin(2 * (theta - psi)) / (2 * np.sin(theta))


def sw_switching(psi):
    """(h_sw, theta_sw): the branch's turning point, d u / d theta = 0, i.e. 2 cos 2(theta - psi) sin theta =
    sin 2(theta - psi) cos theta, on psi ... psi + pi/2 (brentq). h_sw is Stoner & Wohlfarth's astroid, (cos^(2/3) psi +
    sin^(2/3) psi)^(-3/2) (checked in the tests)."""
    def q(th):
        return 2 * math.cos(2 * (th - psi)) * math.sin(th) - math.sin(2 * (th - psi)) * math.cos(th)
    ths = brentq(q, psi, psi + math.pi / 2 - 1e-15, xtol=1e-15, rtol=1e-15)
    return -float(sw_branch_field(ths, psi)), ths


def _branch_table(psi):
    """The branch theta(u), u >= -h_sw, on a grid uniform in z = sqrt(u + h_sw) (the fold's square root is smooth in
    z), by bisection of sw_branch_field (monotone on the branch), with dtheta/dz = 2 z / (du/dtheta) (at z = 0 the
    fold's limit -sqrt(2 / u''(theta_sw))); returned as cos theta and sin theta with their z-derivatives, for cubic
    Hermite interpolation."""
    hsw, ths = sw_switching(psi)
    Z = math.sqrt(U_MAX + hsw)
    z = np.linspace(0.0, Z, N_Z)
    u = z * z - hsw
    lo = np.full(N_Z, min(1e-3, math.sin(2 * psi) / (4 * U_MAX + 4)))
    hi = np.full(N_Z, ths)
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        above = sw_branch_field(mid, psi) > u
        lo, hi = np.where(above, mid, lo), np.where(above, hi, mid)
    th = 0.5 * (lo + hi)
    th[0] = ths
    ph = th - psi
    du = -(2 * np.cos(2 * ph) * np.sin(th) - np.sin(2 * ph) * np.cos(th)) / (2 * np.sin(th) ** 2)
    d = np.empty(N_Z)
    d[1:] = 2 * z[1:] / du[1:]
    e = 1e-4
    upp = float(sw_branch_field(ths + e, psi) - 2 * sw_branch_field(ths, psi) + sw_branch_field(ths - e, psi)) / e ** 2
    d[0] = -math.sqrt(2.0 / upp)
    return hsw, Z / (N_Z - 1), np.array([np.cos(th), -np.sin(th) * d, np.sin(th), np.cos(th) * d])


PSI_NODES = (np.arange(N_PSI) + 0.5) * (math.pi / 2) / N_PSI
_TABLES = [_branch_table(p) for p in PSI_NODES]
HSW = np.array([t[0] for t in _TABLES])
_DZ = np.array([t[1] for t in _TABLES])
_TAB = np.array([t[2] for t in _TABLES])                 # (N_PSI, 4, N_Z): cos, dcos/dz, sin, dsin/dz


@njit(cache=True)
def _on_branch(u, i, comp, hsw, dz, tab):
    """cos theta (comp 0) or sin theta (comp 1) on node i's branch near +psi at the field u >= -h_sw."""
    z2 = u + hsw[i]
    z = math.sqrt(z2) if z2 > 0.0 else 0.0
    t = z / dz[i]
    j = int(t)
    if j >= tab.shape[2] - 1:
        j = tab.shape[2] - 2
    f = t - j
    g = 1.0 - f
    a = 2 * comp
    return ((1 + 2 * f) * g * g * tab[i, a, j] + f * g * g * dz[i] * tab[i, a + 1, j]
            + f * f * (3 - 2 * f) * tab[i, a, j + 1] - f * f * g * dz[i] * tab[i, a + 1, j + 1])


@njit(cache=True)
def _armature_run(h, node, sgn, w, kinv, state, comp, hsw, dz, tab):
    n_psi, n_k = state.shape
    out = np.empty(len(h))
    for k in range(len(h)):
        acc = 0.0
        for i in range(n_psi):
            ii = node[i]
            hs = hsw[ii]
            sg = sgn[i] if comp == 1 else 1.0
            for j in range(n_k):
                u = h[k] * kinv[j]
                s = state[i, j]
                if u >= hs:
                    s = 1
                elif u <= -hs:
                    s = -1
                state[i, j] = s
                if s == 1:
                    m = _on_branch(u, ii, comp, hsw, dz, tab)
                elif s == -1:                                   # the other branch: theta + pi at -u
                    m = -_on_branch(-u, ii, comp, hsw, dz, tab)
                else:                                           # virgin: half the grains either way
                    m = 0.5 * (_on_branch(u, ii, comp, hsw, dz, tab) - _on_branch(-u, ii, comp, hsw, dz, tab))
                acc += w[i, j] * sg * m
        out[k] = acc
    return out


def armature_ensemble(spread, sigma_K, tilt=0.0, n_K=80):
    """The armature's grains: easy axes in the plane of the coil's axis (a calendered sheet of a bonded magnet of
    elongated grains, their axes spread about the rolling direction by a Gaussian of standard deviation ``spread``
    rad, centred ``tilt`` rad off the coil's axis), anisotropy fields log-normal (median 1, the unit of the field;
    sigma_K the standard deviation of their log, from the grains' spread of elongations). Untilted, the axes +-psi give
    the same moment along the field and fold onto 48 angles on 0 ... pi/2; tilted, 96 angles on -pi/2 ... pi/2 (the
    negative ones mirror the positive ones: the same moment along the field, the opposite across it). n_K
    equal-probability anisotropy fields (the log-normal's midpoint quantiles). Returns dict(node, sgn, w, kinv, psi)."""
    if tilt == 0.0:
        psi = PSI_NODES.copy()
        node = np.arange(N_PSI)
        sgn = np.ones(N_PSI)
        wp = np.exp(-0.5 * (psi / spread) ** 2)
    else:
        psi = (np.arange(2 * N_PSI) + 0.5) * math.pi / (2 * N_PSI) - math.pi / 2
        node = np.r_[np.arange(N_PSI)[::-1], np.arange(N_PSI)]
        sgn = np.sign(psi)
        wp = np.exp(-0.5 * ((psi - tilt) / spread) ** 2)
    wp = wp / wp.sum()
    K = np.exp(sigma_K * ndtri((np.arange(n_K) + 0.5) / n_K))
    return dict(node=node, sgn=sgn, w=np.outer(wp, np.full(n_K, 1.0 / n_K)), kinv=1.0 / K, psi=psi, K=K)


def armature_moment(h, ens, state=None, component="x", return_state=False):
    """The armature's moment (in units of its saturation) along the coil's field h (component "x") or across it
    ("y"), h in units of the median anisotropy field: the grains' moments summed with their weights. Each grain is in
    one of its two minima (state +1: the one near +psi, -1: near psi + pi) and jumps when the field passes its
    astroid switching field (h K h_sw(psi) either way); within a branch its moment follows the field reversibly. So
    the ensemble is rate independent with return-point memory (a grain's state is a symmetric relay's), but it is not
    a Prandtl-Ishlinskii model: a grain switches at fixed fields +-K h_sw, not at a distance from the last reversal, so
    the branches are not Masing's, and loops that stay within the smallest switching fields are reversible. ``state``
    (int8 per grain class: +1, -1, or 0 for the virgin, thermally demagnetised state, half the grains either way) as
    returned with ``return_state``; None is virgin."""
    st = np.zeros(ens["w"].shape, np.int8) if state is None else np.array(state, np.int8)
    comp = {"x": 0, "y": 1}[component]
    out = _armature_run(np.asarray(h, float), ens["node"], ens["sgn"].astype(float), ens["w"], ens["kinv"], st, comp,
                        HSW, _DZ, _TAB)
    return (out, st) if return_state else out


def grain_state_after(peaks, ens):
    """The grains' states after a history whose successive extremes (fields, in the units of armature_moment) are
    ``peaks``: each grain holds the sign of the last extreme that reached its switching field, and stays virgin (0)
    if none did (the relay's rule, written here for the tests and the cases' bookkeeping)."""
    hs = HSW[ens["node"]][:, None] / ens["kinv"][None, :]
    st = np.zeros(hs.shape, np.int8)
    for p in peaks:
        st[hs <= abs(p)] = 1 if p > 0 else -1
    return st


# ---- creep: an epoxy-grout bed by Bazant & Chern's log-double-power law ----

def log_double_power(t, lam, n):
    """The basic creep compliance's delayed part of Bazant & Chern's log-double-power law (Bazant & Chern, ACI J.
    82 (1985) 665; the q3 term of model B3, Bazant & Baweja 1995): ln(1 + (t / lam)^n): a power law t^n at
    times short against lam, logarithmic (n ln(t / lam)) at long ones."""
    s = np.maximum(np.asarray(t, float), 0.0) / lam
    return np.log1p(s ** n)


def log_double_power_creep(f, dt, c, lam, n, t_ref=10.0):
    """Creep of the bed under the core's force f, superposed after Boltzmann with f linear between the samples: the
    increment df_j spread over its sample gives, m samples later, the compliance averaged over that sample,
    (1 / dt) int_{m dt}^{(m + 1) dt} J (quad on the first sample, whose integrand has J's t^n at 0; 16-point
    Gauss-Legendre on the others, where J is smooth). A convolution, done by FFT; scaled so that a step held t_ref s
    creeps by c of it; 0 at the start."""
    f = np.asarray(f, float)
    N = len(f)
    x, wg = np.polynomial.legendre.leggauss(16)
    x, wg = (x + 1) / 2, wg / 2
    m = np.arange(N, dtype=float)
    kern = (log_double_power((m[:, None] + x[None, :]) * dt, lam, n) * wg[None, :]).sum(axis=1)
    kern[0] = quad(lambda s: float(log_double_power(s, lam, n)), 0.0, dt, epsabs=1e-15, epsrel=1e-13,
                   limit=200)[0] / dt
    df = np.r_[0.0, np.diff(f)]
    return c * fftconvolve(df, kern)[:N] / float(log_double_power(t_ref, lam, n))


# ---- rate dependence: a dashpot whose bypass tube runs laminar or turbulent ----

RE_CRIT = 2300.0


def pipe_friction(Re):
    """Darcy's friction factor of a smooth tube: Hagen-Poiseuille's 64 / Re below Re = 2300, Blasius's 0.3164
    Re^(-1/4) above (Blasius 1913; e.g. White, *Fluid Mechanics*, ch. 6): the factor jumps up by 1.64 at the
    transition."""
    Re = np.asarray(Re, float)
    return np.where(Re < RE_CRIT, 64.0 / np.maximum(Re, 1e-300), 0.3164 * Re ** -0.25)


def bypass_force(speed, c_lam, v_crit):
    """The dashpot's force for the stage's speed: the piston's flow through a smooth bypass tube, Delta p = f (L / D)
    rho u^2 / 2 (Darcy-Weisbach), so with pipe_friction the force is c_lam y' while the tube's Reynolds number is below
    2300 (at |y'| < v_crit) and grows as |y'|^(7/4) beyond, continuing from gamma c_lam v_crit (gamma = 0.3164
    2300^(3/4) / 64, the friction factor's jump)."""
    s = np.asarray(speed, float)
    a = np.abs(s)
    gam = 0.3164 * RE_CRIT ** 0.75 / 64.0
    return np.sign(s) * np.where(a < v_crit, c_lam * a, gam * c_lam * v_crit * (a / v_crit) ** 1.75)


@njit(cache=True)
def _bypass_speed(e, c_lam, v_crit, gam):
    """The speed whose force is e (the force law's inverse: continuous, with the speed held at v_crit while the force
    crosses its jump)."""
    a = abs(e)
    if a <= c_lam * v_crit:
        s = a / c_lam
    elif a <= gam * c_lam * v_crit:
        s = v_crit
    else:
        s = v_crit * (a / (gam * c_lam * v_crit)) ** (4.0 / 7.0)
    return s if e >= 0.0 else -s


@njit(cache=True)
def _bypass_run(hf, d, K, c_lam, v_crit, gam):
    out = np.empty(len(hf))
    y = hf[0] / K
    out[0] = y
    for j in range(1, len(hf)):
        e0 = 0.5 * (hf[j - 1] + hf[j]) - K * y            # the implicit midpoint: D = d G(h_mid - K (y + D / 2))
        lo, hi = 0.0, d * _bypass_speed(e0, c_lam, v_crit, gam)
        if hi < lo:
            lo, hi = hi, lo
        for _ in range(100):
            D = 0.5 * (lo + hi)
            if D - d * _bypass_speed(e0 - 0.5 * K * D, c_lam, v_crit, gam) > 0.0:
                hi = D
            else:
                lo = D
            if hi - lo <= 1e-15 * (1.0 + abs(y)):
                break
        y += 0.5 * (lo + hi)
        out[j] = y
    return out


def bypass_dashpot_stage(h, dt, K, c_lam, v_crit, sub=8):
    """The stage's travel y when the actuator (stiffness 1, free stroke h) pushes it against its flexure (K - 1) and the
    bypass dashpot: K y + F(y') = h, F = bypass_force. y' = F^-1(h - K y), stepped ``sub`` times a sample by the
    implicit midpoint rule (each step's equation monotone in the step, solved by bisection), h linear between the
    samples; at rest at h[0] / K."""
    h = np.asarray(h, float)
    hf = np.interp(np.arange((len(h) - 1) * sub + 1) / sub, np.arange(len(h)), h)
    gam = 0.3164 * RE_CRIT ** 0.75 / 64.0
    return _bypass_run(hf, dt / sub, float(K), float(c_lam), float(v_crit), gam)[::sub]


# ---- drift: a sunlit sensor bracket under passing cumulus clouds ----

def disc_covered(d):
    """The fraction of a uniform disc (the Sun's, limb darkening neglected) covered by a half-plane whose straight edge
    lies d radii from the disc's centre, the centre outside for d > 0: (acos d - d sqrt(1 - d^2)) / pi, 0 beyond d =
    1, 1 below d = -1 (the circular segment's area)."""
    d = np.clip(np.asarray(d, float), -1.0, 1.0)
    return (np.arccos(d) - d * np.sqrt(1.0 - d * d)) / math.pi


def cloud_irradiance(t, clouds, T_edge):
    """The direct irradiance on the bracket over its clear-sky value: each cloud (start, duration, transmission) is a
    band whose straight leading edge crosses the solar disc in T_edge s (the Sun's 0.53 deg times the cloud base's
    height over the wind's speed) from its start, and whose trailing edge does so from start + duration; the covered
    fraction disc_covered(lead) - disc_covered(trail) dims the Sun to the cloud's transmission."""
    t = np.asarray(t, float)
    G = np.ones(len(t))
    for t0, T, tr in clouds:
        cov = disc_covered(1 - 2 * (t - t0) / T_edge) - disc_covered(1 - 2 * (t - t0 - T) / T_edge)
        G -= (1.0 - tr) * cov
    return G


def lumped_lag(t, G, tau, T0):
    """A lumped body's temperature, tau T' = G - T (the absorbed sunlight against the convective loss to the air,
    in units where clear sun holds T = 1), from T0, exact for G linear between the samples: T_k+1 = a T_k + b0 G_k+1
    + b1 G_k, a = exp(-dt / tau), b0 = 1 - (tau / dt)(1 - a), b1 = 1 - a - b0."""
    dt = float(t[1] - t[0])
    a = math.exp(-dt / tau)
    b0 = 1.0 - (tau / dt) * (1.0 - a)
    b1 = 1.0 - a - b0
    out = np.empty(len(G))
    T = float(T0)
    out[0] = T
    for k in range(1, len(G)):
        T = a * T + b0 * G[k] + b1 * G[k - 1]
        out[k] = T
    return out


# ---- asymmetry: a quarter-wave air column tuned by a piston on the stage, read by its frequency ----

def quarter_wave_frequency(L, a, c=343.0):
    """The fundamental of a tube closed at one end (the piston) and open at the other: f = c / (4 (L + delta)), delta =
    0.6133 a the end correction of an unflanged open end of radius a (Levine & Schwinger, Phys. Rev. 73 (1948) 383;
    e.g. Kinsler et al., *Fundamentals of Acoustics*, ch. 10)."""
    return c / (4.0 * (np.asarray(L, float) + 0.6133 * a))


def quarter_wave_reading(u, a):
    """The frequency's change for the piston's travel u (-1 ... 1 of its stroke, the stroke a of the effective length
    L + delta, the column shortening for u > 0), scaled to slope 1 at u = 0: (1 / (1 - a u) - 1) / a = u / (1 - a u);
    convex."""
    u = np.asarray(u, float)
    return u / (1.0 - a * u)


def quarter_wave_asym(a):
    """The ends' secants' difference, reading(1) + reading(-1) = 2 a / (1 - a^2)."""
    return float(quarter_wave_reading(1.0, a) + quarter_wave_reading(-1.0, a))


# ---- saturation: a slotted optical interrupter with a round, uniform beam ----

def interrupter_reading(u, b):
    """A slotted optical switch read as an analogue sensor: a flag on the stage cuts a round beam of uniform irradiance
    (radius r) with its straight edge, and the photocurrent goes with the area left open: the disc's area on one side of
    a chord e from its centre, r^2 (pi / 2 + asin(e / r) + (e / r) sqrt(1 - (e / r)^2)). About the half-cut point, for
    the edge at u (-1 ... 1 of its stroke, the stroke b r), scaled to slope 1 at u = 0: (asin(b u) + b u sqrt(1 - b^2
    u^2)) / (2 b); the ends compressed by 1 - reading(1)."""
    x = b * np.asarray(u, float)
    return (np.arcsin(x) + x * np.sqrt(1.0 - x * x)) / (2.0 * b)


# ---- delay: a soft silicone push rod between the stage and its sensor ----

def push_rod_transfer(s, tau, r):
    """The sensor's travel over the stage's when the stage drives one end of a slender elastic rod (longitudinal waves
    at c = sqrt(E / rho), tau = L / c) whose far end carries the light sensor and a dashpot d to the frame: with the
    rod's impedance Z = A sqrt(E rho), the far end reflects r = (Z - d) / (Z + d) of each wave, so u(0) = F + G, u(L)
    = (1 + r) F e^(-s tau), G = r F e^(-2 s tau): u(L) / u(0) = (1 + r) e^(-s tau) / (1 + r e^(-2 s tau)) (d'Alembert;
    e.g. Graff, *Wave Motion in Elastic Solids*, 1975, ch. 2). The rod's own losses are neglected."""
    e = np.exp(-np.asarray(s, complex) * tau)
    return (1 + r) * e / (1 + r * e * e)


def push_rod(t, tf, xf, tau, r):
    """push_rod_transfer in time: y(t) = (1 + r) sum_k (-r)^k x(t - (2 k + 1) tau), x the stage's travel given on the
    grid tf (linear between its samples; at rest at xf[0] before it), the sum taken until |r|^k < 1e-16."""
    t = np.asarray(t, float)
    y = np.zeros(len(t))
    k, w = 0, 1.0
    while abs(w) >= 1e-16:
        y += w * np.interp(t - (2 * k + 1) * tau, tf, xf, left=xf[0])
        k, w = k + 1, -r * w
    return (1 + r) * y


# ---- saturation (the pair): a laminar fluidic jet sensor (Bickley's plane jet) ----

def bickley_profile(eta):
    """The velocity across Bickley's plane laminar jet over its centreline value, sech^2(eta) (Bickley, Phil. Mag. 23
    (1937) 727; e.g. Schlichting, *Boundary-Layer Theory*): the similarity stream function tanh(eta) solves f''' +
    2 (f f')' = 0."""
    return 1.0 / np.cosh(np.asarray(eta, float)) ** 2


def jet_reading(u, beta):
    """A proportional fluidic sensor: a plane jet issuing from a slot on the stage onto a splitter between two
    receiver ports, read as the difference of their recovered pressures, which go with the momentum flux each port
    catches, int u^2 = int sech^4 over its side of the splitter. For the jet's centre at u (-1 ... 1 of its stroke, the
    stroke beta jet half-widths): int_{-beta u}^{beta u} sech^4 = 2 (tanh - tanh^3 / 3)(beta u), scaled to slope 1 at
    u = 0: (tanh(beta u) - tanh^3(beta u) / 3) / beta; odd, the ends compressed."""
    q = np.tanh(beta * np.asarray(u, float))
    return (q - q ** 3 / 3.0) / beta


# ---- the magnetisers' histories (initial states) ----

def ringing_peaks(P1, zeta, floor=1e-3):
    """The extremes of a capacitor discharge through the magnetising coil left without its crowbar diode, which rings:
    an under-damped series R-L-C current, i ~ exp(-zeta w t) sin(w_d t), whose successive lobes alternate in sign and
    fall by exp(-pi zeta / sqrt(1 - zeta^2)) each (e.g. Montgomery, *Solenoid Magnet Design*, 1969, on capacitor-bank
    magnetisers). The first lobe is P1; lobes down to floor |P1|."""
    q = math.exp(-math.pi * zeta / math.sqrt(1 - zeta * zeta))
    peaks, p = [], float(P1)
    while abs(p) >= floor * abs(P1):
        peaks.append(p)
        p *= -q
    return peaks


def ringing_path(P1, zeta, per_lobe=400, floor=1e-3):
    """The discharge's field, sampled per_lobe times a lobe with every extreme and zero on the grid: P1 exp(-zeta / s
    x) sin(x) / (its value at the first extreme), x = w_d t, s = sqrt(1 - zeta^2), over the lobes of ringing_peaks;
    it ends at a zero of the current (the last lobe's end). Returns (path, peaks)."""
    s = math.sqrt(1 - zeta * zeta)
    x0 = math.atan2(s, zeta)                                    # w_d t of the first extreme
    peaks = ringing_peaks(P1, zeta, floor)
    xs = [np.r_[np.linspace(k * math.pi, x0 + k * math.pi, per_lobe // 2, endpoint=False),
                np.linspace(x0 + k * math.pi, (k + 1) * math.pi, per_lobe // 2, endpoint=False)]
          for k in range(len(peaks))]
    x = np.r_[np.concatenate(xs), len(peaks) * math.pi]
    path = P1 * np.exp(-zeta / s * (x - x0)) * np.sin(x) / math.sin(x0)
    path[-1] = 0.0
    return path, peaks

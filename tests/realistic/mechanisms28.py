"""Mechanisms of the HOLDOUT28 set (``cases_holdout28.py``), each written from its law; the signals are in
:mod:`.signals28`.

Nothing here imports hystcomp. Every mechanism takes the (clean) drive, or the core's output, and returns the response;
all are causal. The exact Kelvin-element recursion is the earlier sets' (the same law, imported as mechanisms27
does).

Citations: every source below was written from memory in this session (none was re-read); volumes, pages and years may
be off. The laws do not rest on them: each is checked in tests/test_realistic_holdout28.py against an independent
solution (a closed form, quadrature, brentq, solve_ivp, scipy's own routines or a finer simulation).
"""

import math

import numpy as np
from scipy.linalg import expm
from numba import njit
from scipy.optimize import brentq

from .mechanisms24 import kelvin_modes_response


# ---- the rate-independent core: Rayleigh's law of sub-switching domain-wall motion ----

def rayleigh_core(v, kappa, state=None, return_state=False):
    """Rayleigh's law (Rayleigh, Phil. Mag. 23 (1887) 225; for piezoceramics Damjanovic & Demartin, J. Phys.: Condens.
    Matter 9 (1997) 4943): domain walls pinned in a random potential (Neel, Cahiers Phys. 12 (1942) 1) give, from the
    demagnetised (virgin) state, x = v + kappa v |v| (the coefficient d (1 + kappa A) growing linearly with the
    amplitude A), and symmetric loops x = (1 + kappa A) v +- (kappa / 2) (A^2 - v^2). Written as a Preisach model of
    constant density (every switching field pair alike) on the half plane: the output is the signed area of the
    plane's up and down parts, computed from the staircase's vertices (a stack of turning points: from a reversal at
    v_r the area changes by (v - v_r) |v - v_r| / 2, from the virgin line by v |v|); an inner loop closing wipes its
    two vertices out, and a branch reaching the mirror image of the first vertex rejoins the virgin curve. ``state``
    is (turning points, areas at them, last input, last direction) as returned with ``return_state``; None is the
    virgin state at 0 V."""
    if state is None:
        tp, ar, u_prev, d = [], [], 0.0, 0
    else:
        tp, ar, u_prev, d = list(state[0]), list(state[1]), float(state[2]), int(state[3])

    def area(u):
        if not tp:
            return u * abs(u)
        e = u - tp[-1]
        return ar[-1] + 0.5 * e * abs(e)

    a_prev = area(u_prev)
    out = np.empty(len(v))
    for k, u in enumerate(np.asarray(v, float).tolist()):
        if u != u_prev:
            s = 1 if u > u_prev else -1
            if d != 0 and s != d:
                tp.append(u_prev)
                ar.append(a_prev)
            d = s
            while tp:
                if len(tp) >= 2:
                    if (u - tp[-2]) * d >= 0:
                        del tp[-2:]
                        del ar[-2:]
                        continue
                elif (u + tp[0]) * d >= 0:
                    tp.pop()
                    ar.pop()
                    continue
                break
            a_prev = area(u)
            u_prev = u
        out[k] = u_prev + kappa * a_prev
    if return_state:
        return out, (tuple(tp), tuple(ar), u_prev, d)
    return out


# ---- creep: consolidation of a pad drained through a clogged filter (an impeded drainage boundary) ----

def impeded_modes(L, n_modes=600):
    """The modes of Terzaghi's consolidation of a layer on an impermeable base drained at its top through a filter of
    finite permeability (a Robin condition -du/dz = L u at the top, L the filter's Biot number: Gray, Geotechnique 1945;
    the same as Crank's plane sheet with surface evaporation, *The Mathematics of Diffusion*, 1975, sec. 4.3.4): beta_n
    tan beta_n = L (brentq in ((n - 1) pi, (n - 1/2) pi)), the mean degree of consolidation U(T) = 1 - sum w_n exp(-
    beta_n^2 T), w_n = 2 L^2 / (beta_n^2 (beta_n^2 + L^2 + L)). Returns (beta_n^2, w_n)."""
    b = np.empty(n_modes)
    for j in range(n_modes):
        lo, hi = j * math.pi, j * math.pi + math.pi / 2
        b[j] = brentq(lambda x: x * math.sin(x) - L * math.cos(x), lo + 1e-15 if j == 0 else lo, hi, xtol=1e-15,
                      rtol=4 * np.finfo(float).eps)
    return b * b, 2 * L * L / (b * b * (b * b + L * L + L))


def impeded_degree(t, tau, L, n_modes=600):
    """U(t / tau) of :func:`impeded_modes` (tau = H^2 / c_v)."""
    rates, w = impeded_modes(L, n_modes)
    t = np.asarray(t, float)[..., None]
    return 1.0 - np.sum(w * np.exp(-rates * t / tau), axis=-1)


def impeded_creep(h, dt, c, tau, L, t_ref=10.0, n_modes=600):
    """Creep of the stage's water-saturated pad consolidating under the core's force h through its clogged filter:
    Boltzmann superposition of :func:`impeded_degree` (a Kelvin element per mode, exact for h linear between samples;
    the modes' missing tail at once), scaled so that a step held t_ref s creeps by c of it; at rest at h[0] before the
    record (the creep's value there is 0)."""
    rates, w = impeded_modes(L, n_modes)
    h = np.asarray(h, float)
    resp = kelvin_modes_response(h - h[0], dt, tau / rates, w) + (1.0 - float(np.sum(w))) * (h - h[0])
    return c * resp / float(impeded_degree(t_ref, tau, L, n_modes))


# ---- rate dependence: a sphere dragged through oil by Schiller & Naumann's law ----

SN_EXP = 0.687


def sn_drag(u, beta):
    """Schiller & Naumann's drag of a sphere (Z. Ver. Dtsch. Ing. 77 (1933) 318): Stokes's 3 pi mu d u times 1 + 0.15
    Re^0.687, here u (1 + beta |u|^0.687) in units where Stokes's part is u (beta = 0.15 (rho d / mu)^0.687)."""
    u = np.asarray(u, float)
    return u * (1.0 + beta * np.abs(u) ** SN_EXP)


@njit(cache=True)
def _sn_speed(f, beta):
    if f == 0.0:
        return 0.0
    a = abs(f)
    u = a / (1.0 + beta * a ** SN_EXP) ** (1.0 / (1.0 + SN_EXP))
    for _ in range(60):
        g = u * (1.0 + beta * u ** SN_EXP) - a
        dg = 1.0 + beta * (1.0 + SN_EXP) * u ** SN_EXP
        du = g / dg
        u -= du
        if abs(du) <= 1e-15 * u:
            break
    return u if f > 0 else -u


def sn_speed(f, beta):
    """The speed at which :func:`sn_drag` equals f (odd, increasing; Newton's method from a guess between Stokes's and
    the power law's, to machine precision)."""
    return _sn_speed(float(f), float(beta))


@njit(cache=True)
def _sn_stage(h, dt, tau, beta, n_sub):
    y = np.empty_like(h)
    y[0] = h[0]
    hs = dt / n_sub
    cur = h[0]
    for k in range(1, len(h)):
        h0, h1 = h[k - 1], h[k]
        for j in range(n_sub):
            a0 = h0 + (h1 - h0) * j / n_sub
            am = h0 + (h1 - h0) * (j + 0.5) / n_sub
            a1 = h0 + (h1 - h0) * (j + 1) / n_sub
            k1 = _sn_speed((a0 - cur) / tau, beta)
            k2 = _sn_speed((am - cur - 0.5 * hs * k1) / tau, beta)
            k3 = _sn_speed((am - cur - 0.5 * hs * k2) / tau, beta)
            k4 = _sn_speed((a1 - cur - hs * k3) / tau, beta)
            cur += hs * (k1 + 2 * k2 + 2 * k3 + k4) / 6
        y[k] = cur
    return y


def sn_stage(h, dt, tau, beta, n_sub=16):
    """The stage (travel y) held by a flexure of stiffness k to the core's free stroke h and carrying a sphere dragged
    through oil: k (h - y) = c sn_drag(y'), i.e. y' = sn_speed((h - y) / tau) with tau = c / k (a linear lag tau when
    slow, longer when fast: the drag grows as u^1.687 beyond Re ~ 1). Classical RK4 on n_sub steps a sample, h linear
    between samples; at rest at h[0] before the record. ``beta`` is in units of (V/s)^-0.687."""
    return _sn_stage(np.asarray(h, float), float(dt), float(tau), float(beta), int(n_sub))


# ---- drift: a heat sink filled with paraffin (a phase-change material) warming the sensor's mount ----

def pcm_temperature(t, t_on, P_R, dT_m, tau_s, tau_l, melt):
    """The mount's temperature rise above the ambient after a heater of power P switched on at t_on beside a paraffin
    heat sink (a lumped body: heat capacity C_s solid, C_l liquid, R to the ambient; the enthalpy method, e.g. Voller,
    1990; the melt at dT_m above the ambient absorbs the latent heat Lh): solid, dT/dt = (P R - T) / tau_s (tau_s = R
    C_s) up to dT_m; a plateau at dT_m while Lh is absorbed at the net rate P - dT_m / R, lasting melt = Lh R / (P R -
    dT_m) (in s: ``melt``); liquid, (P R - T) / tau_l from there. P_R = P R > dT_m. Closed form by phases."""
    t = np.asarray(t, float)
    s = np.maximum(t - t_on, 0.0)
    t1 = tau_s * math.log(P_R / (P_R - dT_m))
    T = np.where(s <= t1, P_R * -np.expm1(-s / tau_s), dT_m)
    liquid = s > t1 + melt
    T = np.where(liquid, P_R - (P_R - dT_m) * np.exp(-(s - t1 - melt) / tau_l), T)
    return T


# ---- asymmetry: Malus's law of an analyser the stage turns ----

def malus_reading(x, phi0, kap):
    """A photodiode behind a polariser and an analyser the stage turns by kap x (x in -1 ... 1) about a working point
    phi0 from extinction (Malus, 1809: I = I0 sin^2(phi)), scaled to slope 1 at x = 0: (sin^2(phi0 + kap x) -
    sin^2(phi0)) / (kap sin(2 phi0)). Convex for 0 < phi0 - kap, phi0 + kap < pi / 4; the ends' secants differ by 2
    sin^2(kap) cos(2 phi0) / (kap sin(2 phi0))."""
    x = np.asarray(x, float)
    return (np.sin(phi0 + kap * x) ** 2 - math.sin(phi0) ** 2) / (kap * math.sin(2 * phi0))


def malus_asym(phi0, kap):
    """The difference of the ends' secants of :func:`malus_reading`."""
    return 2 * math.sin(kap) ** 2 * math.cos(2 * phi0) / (kap * math.sin(2 * phi0))


# ---- saturation: a shaft angle read through a Hooke's (Cardan) joint ----

def cardan_reading(x, theta_m, beta):
    """An encoder on the output shaft of a Hooke's (Cardan) joint bent by beta whose input shaft the stage turns by
    theta_m x (x in -1 ... 1): tan(psi) = tan(theta) / cos(beta) (e.g. Mabie & Reinholtz, *Mechanisms and Dynamics of
    Machinery*, 1987), scaled to slope 1 at x = 0: cos(beta) atan(tan(theta_m x) / cos(beta)) / theta_m. Odd and
    compressive (its slope falls from 1 to cos^2(beta) at 90 deg)."""
    x = np.asarray(x, float)
    cb = math.cos(beta)
    return cb * np.arctan(np.tan(theta_m * x) / cb) / theta_m


# ---- delay: a lumped LC delay line ----

def lc_ladder(n_sec):
    """The state-space form (A, B, C) of a ladder of n_sec constant-k low-pass sections (series L, shunt C), driven
    through a source resistance Z0 = sqrt(L / C) and terminated in Z0 (the lumped delay line of analog instruments,
    e.g. the oscilloscope's vertical delay line; Zobel, Bell Syst. Tech. J. 2 (1923) 1), in units of sqrt(L C): the
    states are the inductors' currents (times Z0) and the capacitors' voltages; the output twice the last voltage
    (the terminations' 1/2 made up)."""
    n = n_sec
    A = np.zeros((2 * n, 2 * n))
    B = np.zeros(2 * n)
    for k in range(n):
        i, u = k, n + k                         # Z0 i_k and u_k
        # L di_k / dt = u_{k-1} - u_k (u_{-1} = e - Z0 i_0)
        if k == 0:
            A[i, i] = -1.0
            B[i] = 1.0
        else:
            A[i, n + k - 1] = 1.0
        A[i, u] = -1.0
        # C du_k / dt = i_k - i_{k+1} (i_n = u_{n-1} / Z0)
        A[u, i] = 1.0
        if k < n - 1:
            A[u, k + 1] = -1.0
        else:
            A[u, u] = -1.0
    C = np.zeros(2 * n)
    C[2 * n - 1] = 2.0
    return A, B, C


def lc_dc_delay(n_sec):
    """The ladder's group delay at zero frequency in units of sqrt(L C): -H'(0) / H(0) with H(s) = C (s - A)^-1 B."""
    A, B, C = lc_ladder(n_sec)
    x1 = np.linalg.solve(A, B)
    x2 = np.linalg.solve(A, x1)
    return float(C @ x2) / float(-(C @ x1))


def lc_delay_line(h, dt, n_sec, D):
    """The core's output through :func:`lc_ladder`, its sections' sqrt(L C) chosen so that the DC group delay is D
    samples of dt; exact for h linear between samples (the first-order hold's discretisation by a matrix exponential of
    the augmented system); at rest at h[0] before the record."""
    A, B, C = lc_ladder(n_sec)
    T = D / lc_dc_delay(n_sec)                  # sqrt(L C) in samples
    m = 2 * n_sec
    M = np.zeros((m + 2, m + 2))
    M[:m, :m] = A * (1.0 / T)
    M[:m, m] = B * (1.0 / T)
    M[m, m + 1] = 1.0
    E = expm(M)
    Phi, G0, G1 = E[:m, :m], E[:m, m], E[:m, m + 1]
    h = np.asarray(h, float)
    x = -np.linalg.solve(A, B) * h[0]
    out = np.empty_like(h)
    out[0] = C @ x
    for k in range(1, len(h)):
        x = Phi @ x + G0 * h[k - 1] + G1 * (h[k] - h[k - 1])
        out[k] = C @ x
    return out


# ---- initial state: a Kiefer-Wolfowitz search ----

def kiefer_wolfowitz(x1, n_iter, a0, c0, response, rng, noise, lo=2.0, hi=98.0):
    """Kiefer & Wolfowitz's stochastic approximation of a maximum (Ann. Math. Stat. 23 (1952) 462): at the iterate x_n
    the response is measured at x_n + c_n and x_n - c_n (c_n = c0 / n^(1/4)), each with a noise of std ``noise``, and
    x_{n+1} = x_n + a_n (y+ - y-) / (2 c_n), a_n = a0 / n, kept within lo ... hi. Returns the stage's path (the probes
    in the order visited, then the last iterate) and the iterates, probes and measurements."""
    xs, probes, ys = [x1], [], []
    path = []
    x = x1
    for n in range(1, n_iter + 1):
        cn = c0 / n ** 0.25
        p, m = min(x + cn, hi), max(x - cn, lo)
        yp = response(p) + noise * rng.standard_normal()
        ym = response(m) + noise * rng.standard_normal()
        path += [p, m]
        probes.append((p, m))
        ys.append((yp, ym))
        x = min(max(x + (a0 / n) * (yp - ym) / (2 * cn), lo), hi)
        xs.append(x)
    path.append(x)
    return np.array(path), np.array(xs), probes, ys


# ---- saturation of the pair: a tyre's lateral force by Pacejka's Magic Formula ----

def pacejka_reading(x, B, C, E):
    """The lateral force of a tyre on a flat-track rig whose slip angle the stage sets (Pacejka's Magic Formula: D sin(C
    atan(B a - E (B a - atan(B a)))); Bakker, Nyborg & Pacejka, SAE 870421, 1987), D = 1 / (B C): slope 1 at x = 0,
    odd (no shifts), below the peak within x in -1 ... 1."""
    x = np.asarray(x, float)
    bx = B * x
    return np.sin(C * np.arctan(bx - E * (bx - np.arctan(bx)))) / (B * C)


# ---- drift of the pair: dielectric absorption (soakage) of the sensor's input capacitor ----

def soakage(t, t_s, taus, weights):
    """The voltage a film capacitor recovers after it was discharged at t_s (dielectric absorption; Dow's model of
    series-RC branches in parallel with it, IRE Trans. Compon. Parts 5 (1958) 139; Pease, 'Understand capacitor
    soakage', Electronic Design 1982): sum_i w_i (1 - exp(-(t - t_s) / tau_i)) from t_s on, 0 before."""
    s = np.maximum(np.asarray(t, float) - t_s, 0.0)[..., None]
    return np.sum(np.asarray(weights) * -np.expm1(-s / np.asarray(taus)), axis=-1)


# ---- out of vocabulary: a scanning data logger ----

def scanned(y, first, every):
    """The reading of a channel that a scanning logger's multiplexer visits at the samples first, first + every, ...,
    holding each reading until the next visit (the value before the first visit: the first reading)."""
    y = np.asarray(y, float)
    k = np.arange(len(y))
    j = np.maximum((k - first) // every, 0)
    return y[first + j * every]

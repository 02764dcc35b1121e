"""Mechanisms of the HOLDOUT32 set (``cases_holdout32.py``), each written from its law; the signals are in
:mod:`.signals32`.

Nothing here imports hystcomp (nor another set's mechanisms). Every mechanism takes the (clean) drive, or the core's
output, and returns the response; all are causal.

Citations: every source below was written from memory in this session (none was re-read); volumes, pages and years may
be off. The laws do not rest on them: each is checked in tests/test_realistic_holdout32.py against an independent
solution (solve_ivp of the underlying equations, quad, an FFT of the transfer function, a finite-difference or
resistor-ladder solution, or a direct sum).
"""

import math

import numpy as np
from numba import njit
from scipy.signal import fftconvolve, lsim
from scipy.special import gamma as gamma_fn


# ---- the rate-independent core: a stage on a preloaded rolling guide with Dahl's pre-sliding friction ----

def dahl_branch(u0, delta, a, kappa):
    """Dahl's solid-friction law along one direction of travel (Dahl, 'A solid friction model', Aerospace Corp.
    TOR-0158(3107-18)-1, 1968; Dahl, AIAA J. 14 (1976) 1675): dF/dx = sigma0 (1 - s F / Fc)^a, s the direction of
    travel. With u = 1 - s F / Fc and delta = s (x - x_r) >= 0 the travel since the last reversal, du / d delta = -kappa
    u^a, kappa = sigma0 / Fc, so for a != 1 u = (u0^(1 - a) + (a - 1) kappa delta)^(-1 / (a - 1)) (u0 = 1 - s F_r /
    Fc); for a > 1 the force approaches s Fc without reaching it (Dahl's 'ductile' exponent)."""
    d = np.asarray(delta, float)
    return (u0 ** (1.0 - a) + (a - 1.0) * kappa * d) ** (-1.0 / (a - 1.0))


@njit(cache=True)
def _dahl_run(v, K, Fc, sigma0, a, x0, F0, d0, xr0, ur0, v0):
    N = len(v)
    out = np.empty(N)
    kap = sigma0 / Fc
    x, F, dirn, xr, ur, u_last = x0, F0, d0, xr0, ur0, v0
    for k in range(N):
        u = v[k]
        if u != u_last:
            s = 1 if u > u_last else -1
            if s != dirn:                                   # a reversal: a new branch from the present state
                xr = x
                ur = 1.0 - s * F / Fc
                dirn = s
            # (K x + F(x) = u) along the branch: increasing in x, concave for s = 1 (convex for s = -1), so Newton's
            # steps from the last x approach the root monotonically
            for _ in range(60):
                dl = s * (x - xr)
                if dl < 0.0:
                    dl = 0.0
                w = (ur ** (1.0 - a) + (a - 1.0) * kap * dl) ** (-1.0 / (a - 1.0))
                Fx = s * Fc * (1.0 - w)
                g = K * x + Fx - u
                dx = -g / (K + sigma0 * w ** a)
                x += dx
                if abs(dx) <= 1e-13 * (1.0 + abs(x)):
                    break
            dl = s * (x - xr)
            if dl < 0.0:
                dl = 0.0
            w = (ur ** (1.0 - a) + (a - 1.0) * kap * dl) ** (-1.0 / (a - 1.0))
            F = s * Fc * (1.0 - w)
            u_last = u
        out[k] = x
    return out, x, F, dirn, xr, ur, u_last


def dahl_stage(v, K, Fc, sigma0, a, state=None, return_state=False):
    """The travel x of a stage pushed by the actuator (stiffness 1, free stroke v) against a return flexure (K - 1)
    and the pre-sliding friction F of a preloaded rolling guide by Dahl's law (:func:`dahl_branch`): v = K x + F(x),
    x solved at each sample by Newton's method on the present branch. Rate independent (a Duhem model: the state is
    x, F and the direction, no stack of turning points; a reversal starts its branch from the present force, so minor
    loops are not Masing's). ``state`` is (x, F, direction, the branch's x_r, its u0, the last input) as returned with
    ``return_state``; None is the virgin state at 0 V (x = F = 0)."""
    st = (0.0, 0.0, 0, 0.0, 1.0, 0.0) if state is None else state
    out, *rest = _dahl_run(np.asarray(v, float), float(K), float(Fc), float(sigma0), float(a), float(st[0]),
                           float(st[1]), int(st[2]), float(st[3]), float(st[4]), float(st[5]))
    if return_state:
        return out, tuple(rest)
    return out


# ---- creep: a bituminous (mastic asphalt) damping pad by Huet's two parabolic elements ----

def huet_function(t, tau, delta, k, h):
    """The delayed part of Huet's creep compliance of bituminous materials, a spring in series with two parabolic
    ('springpot') elements (Huet, thesis, Paris 1963; Sayegh 1965; e.g. Olard & Di Benedetto, Road Mater. Pavement
    Des. 4 (2003) 185): E_inf J(t) = 1 + delta (t / tau)^k / Gamma(k + 1) + (t / tau)^h / Gamma(h + 1), 0 < k < h < 1
    (the complex modulus E_inf / (1 + delta (i w tau)^-k + (i w tau)^-h)). Returns the part beyond 1."""
    s = np.maximum(np.asarray(t, float), 0.0) / tau
    return delta * s ** k / gamma_fn(k + 1.0) + s ** h / gamma_fn(h + 1.0)


def huet_creep(f, dt, c, tau, delta, k, h, t_ref=10.0):
    """Creep of the pad under the core's force f, superposed after Boltzmann with f linear between the samples: the
    increment df_j spread over its sample gives, m samples later, sum over the two terms of w_p (dt / tau)^p ((m +
    1)^(p + 1) - m^(p + 1)) / Gamma(p + 2) (the power law integrated over the sample), w_k = delta, w_h = 1. A
    convolution, done by FFT; scaled so that a step held t_ref s creeps by c of it (huet_function(t_ref)); 0 at the
    start."""
    f = np.asarray(f, float)
    m = np.arange(len(f), dtype=float)
    kern = np.zeros(len(f))
    for w, p in ((delta, k), (1.0, h)):
        kern += w * (dt / tau) ** p * ((m + 1.0) ** (p + 1.0) - m ** (p + 1.0)) / gamma_fn(p + 2.0)
    df = np.r_[0.0, np.diff(f)]
    return c * fftconvolve(df, kern)[:len(f)] / float(huet_function(t_ref, tau, delta, k, h))


# ---- rate dependence: a voice-coil transducer on the stage closed by a resonant R-L-C shunt ----

def rlc_shunt_transfer(s, K, kappa, f_e, zeta):
    """The stage's travel over the actuator's free stroke, Y / H, when a voice-coil transducer on the stage (force
    factor Bl) is shunted by a series R-L-C circuit (resonant electromagnetic shunt damping: Behrens, Fleming &
    Moheimani, Smart Mater. Struct. 12 (2003) 18). With the stage quasi-static, H - Y = (K - 1) Y + Bl i, and the loop
    L di/dt + R i + q / C = Bl Y' (the motional EMF): (L + Bl^2 / K) q'' + R q' + q / C = Bl H' / K, so Y / H = (1 / K)
    (1 - kappa s^2 / (s^2 + 2 zeta w s + w^2)), kappa = (Bl^2 / K) / (L + Bl^2 / K) < 1, w^2 = 1 / ((L + Bl^2 / K) C),
    2 zeta w = R / (L + Bl^2 / K): 1 / K at low frequencies (the capacitor blocks), (1 - kappa) / K at high ones (the
    inductance's share), a dip and a phase lead between."""
    w = 2 * math.pi * f_e
    s = np.asarray(s, complex)
    return (1.0 - kappa * s * s / (s * s + 2 * zeta * w * s + w * w)) / K


def rlc_shunt_stage(h, dt, K, kappa, f_e, zeta):
    """:func:`rlc_shunt_transfer` applied to the free stroke h (linear between the samples: lsim's first-order hold
    with the matrix exponential, exact), at rest before the record: Y = ((1 - kappa) H + kappa (2 zeta w s + w^2) /
    (s^2 + 2 zeta w s + w^2) H) / K."""
    h = np.asarray(h, float)
    w = 2 * math.pi * f_e
    A = np.array([[0.0, 1.0], [-w * w, -2 * zeta * w]])
    B = np.array([[0.0], [1.0]])
    C = np.array([[w * w, 2 * zeta * w]])
    t = np.arange(len(h)) * dt
    _, yo, _ = lsim((A, B, C, np.zeros((1, 1))), h, t, X0=[h[0] / (w * w), 0.0], interp=True)
    return ((1.0 - kappa) * h + kappa * yo) / K


# ---- rate dependence (the pair): a vane on the stage in air, Newton's quadratic drag ----

def vane_drag_stage(h, dt, K, c, sub=8):
    """The stage's travel y when the actuator (stiffness 1, free stroke h) pushes it against its flexure (K - 1) and
    the drag of a flat vane it carries through still air, (1/2) rho C_d A |y'| y' (Newton's drag; C_d about 1.2 for a
    plate broadside, e.g. Hoerner, *Fluid-Dynamic Drag*, 1965): K y + c |y'| y' = h. Stepped ``sub`` times a sample by
    the implicit midpoint rule, each step's quadratic solved in closed form (h linear between the samples); at rest at
    h[0] / K."""
    h = np.asarray(h, float)
    hf = np.interp(np.arange((len(h) - 1) * sub + 1) / sub, np.arange(len(h)), h)
    return _vane(hf, dt / sub, float(K), float(c))[::sub]


@njit(cache=True)
def _vane(hf, d, K, c):
    out = np.empty(len(hf))
    y = hf[0] / K
    out[0] = y
    q = c / (d * d)
    for j in range(1, len(hf)):
        e = 0.5 * (hf[j - 1] + hf[j]) - K * y       # K (y + D / 2) + q |D| D = h_mid, D the step's travel
        ae = abs(e)
        D = (-0.5 * K + math.sqrt(0.25 * K * K + 4.0 * q * ae)) / (2.0 * q)
        y += D if e >= 0.0 else -D
        out[j] = y
    return out


# ---- drift: an interferometer's dead path in an enclosure warmed by an operator ----

def edlen_refractivity(t_c, p_pa, lam_um):
    """n - 1 of dry air by the modified Edlen equation (Birch & Downs, Metrologia 30 (1993) 155; 31 (1994) 315): the
    standard air's dispersion (8342.54 + 2406147 / (130 - S) + 15998 / (38.9 - S)) 1e-8, S = 1 / lam^2 (lam in um),
    times p / 96095.43 (1 + 1e-8 (0.601 - 0.00972 t) p) / (1 + 0.0036610 t) (t in C, p in Pa)."""
    S = 1.0 / lam_um ** 2
    ns = (8342.54 + 2406147.0 / (130.0 - S) + 15998.0 / (38.9 - S)) * 1e-8
    t_c = np.asarray(t_c, float)
    return p_pa * ns / 96095.43 * (1.0 + 1e-8 * (0.601 - 0.00972 * t_c) * p_pa) / (1.0 + 0.0036610 * t_c)


def enclosure_air_temperature(t, t_in, t_out, tau_a, tau_w, g, share):
    """The air temperature rise in a stage's enclosure while an operator stands in it (t_in ... t_out; the body's heat
    a step on and off): two lumped capacities, the air (fast: tau_a its own time constant to the walls and outside)
    and the walls (slow, tau_w), coupled: T_a' = (q - (T_a - T_w) - g T_a) / tau_a ... in units where the air's
    conductance to the walls is 1 and to outside g, and T_w' = (share (T_a - T_w) - T_w) / tau_w. Solved exactly: the
    2x2 system's eigen-decomposition for a unit step, superposed on at t_in and off at t_out; 0 before t_in."""
    A = np.array([[-(1.0 + g) / tau_a, 1.0 / tau_a], [share / tau_w, -(share + 1.0) / tau_w]])
    b = np.array([1.0 / tau_a, 0.0])
    lam, V = np.linalg.eig(A)
    x_inf = -np.linalg.solve(A, b)
    coef = np.linalg.solve(V, -x_inf)            # x(t) = x_inf + V diag(exp(lam t)) coef, x(0) = 0

    def step(s):
        s = np.maximum(s, 0.0)
        return np.where(s > 0, x_inf[0] + (V[0] * coef * np.exp(np.outer(s, lam))).sum(axis=1).real, 0.0)
    t = np.asarray(t, float)
    return step(t - t_in) - step(t - t_out)


# ---- drift (the pair): a ground slab settling under an operator walking about (Boussinesq) ----

def boussinesq_settlement(r, P, E, nu):
    """The surface settlement of an elastic half-space at distance r from a point load P (Boussinesq 1885; e.g.
    Timoshenko & Goodier, *Theory of Elasticity*, 1951, sec. 135): P (1 - nu^2) / (pi E r)."""
    return P * (1.0 - nu * nu) / (math.pi * E * np.asarray(r, float))


def walking_tilt(path_xy, foot_a, foot_b):
    """The differential settlement of the stage's pier (foot_a) and its sensor's reference pier (foot_b) under an
    operator at path_xy (N x 2), in units of P (1 - nu^2) / (pi E): 1 / r_a - 1 / r_b, zeroed at the first sample (the
    reading set to zero when the record starts)."""
    p = np.asarray(path_xy, float)
    ra = np.hypot(p[:, 0] - foot_a[0], p[:, 1] - foot_a[1])
    rb = np.hypot(p[:, 0] - foot_b[0], p[:, 1] - foot_b[1])
    d = 1.0 / ra - 1.0 / rb
    return d - d[0]


# ---- asymmetry: a vibrating-wire gauge read by its frequency ----

def vibrating_wire_reading(u, a):
    """A vibrating-wire gauge tensioned by the stage: the wire's fundamental f = (1 / 2 L) sqrt(T / mu) (Mersenne and
    Taylor), the tension T0 (1 + a u) for the travel u in -1 ... 1, read as the frequency itself (not its square, the
    'digits' that are linear in strain): f / f0 - 1 = sqrt(1 + a u) - 1, scaled to slope 1 at u = 0: 2 (sqrt(1 + a u)
    - 1) / a; concave."""
    u = np.asarray(u, float)
    return 2.0 * (np.sqrt(1.0 + a * u) - 1.0) / a


def vibrating_wire_asym(a):
    """The ends' secants' difference, -(reading(1) + reading(-1))."""
    return -float(vibrating_wire_reading(1.0, a) + vibrating_wire_reading(-1.0, a))


# ---- saturation: a lateral-effect position-sensitive detector with a leaky junction ----

def leaky_psd_ratio(x, alpha_L):
    """The position reading (I2 - I1) / (I1 + I2) of a one-dimensional lateral-effect photodiode (electrodes at -+L
    on a resistive layer) for a light spot at x, when the junction's shunt conductance leaks the photocurrent along the
    way (Lucovsky's equation with leakage, V'' = alpha^2 V: e.g. Woltring, IEEE Trans. Electron Devices 22 (1975)
    581): the layer's potential is sinh-shaped either side of the spot, the currents reaching the electrodes go as
    sinh(alpha (L -+ x)), and the ratio is tanh(alpha x) / tanh(alpha L); x in units of L, alpha_L = alpha L."""
    return np.tanh(alpha_L * np.asarray(x, float)) / math.tanh(alpha_L)


def psd_reading(u, b):
    """The reading for the spot at u (-1 ... 1 of the spot's travel), scaled to slope 1 at the middle: tanh(b u) / b
    (b = alpha times the travel); the ends compressed by 1 - tanh(b) / b."""
    return np.tanh(b * np.asarray(u, float)) / b


# ---- delay: a wireless sensor's jitter buffer ----

def jitter_buffer(t, t_s, x_s, arrived, latency):
    """The signal a base station rebuilds on the logger's clock t from a wireless sensor's time-stamped samples
    (t_s, x_s): each packet is held in a jitter buffer and played out at its stamp plus a fixed latency, and the
    output interpolates linearly between the samples played out (packets lost in the air, arrived False, are bridged
    by the interpolation; e.g. the playout buffers of RFC 3550's receivers). y(t) = interp(t - latency) over the
    samples that arrived; x_s[0] before the first."""
    ts, xs = np.asarray(t_s, float)[arrived], np.asarray(x_s, float)[arrived]
    return np.interp(np.asarray(t, float) - latency, ts, xs)


# ---- out of vocabulary: a magnet on the stage sliding past a Hall sensor ----

def slide_by_field(x, d):
    """The field component normal to the travel at a Hall sensor a gap d from the line along which a magnet (a point
    dipole, magnetised toward the sensor) slides by, x its offset along the line: (2 d^2 - x^2) / (x^2 + d^2)^(5/2)
    in units of mu0 m / (4 pi) (the dipole's field, B = (mu0 / 4 pi) (3 (m.r) r / r^5 - m / r^3); e.g. Jackson,
    *Classical Electrodynamics*, 1999, eq. 5.56): greatest with the magnet over the sensor, zero at x = +-sqrt(2) d
    and reversed beyond ('slide-by' sensing)."""
    x = np.asarray(x, float)
    return (2 * d * d - x * x) / (x * x + d * d) ** 2.5

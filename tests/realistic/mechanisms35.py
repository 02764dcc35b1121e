"""Mechanisms of the HOLDOUT35 set (``cases_holdout35.py``), each written from its law; the signals are in
:mod:`.signals35`.

Nothing here imports hystcomp (nor another set's mechanisms). Every mechanism takes the (clean) drive, or the core's
output, and returns the response; all are causal.

Citations: every source below was written from memory in this session (none was re-read); volumes, pages and years may
be off. The laws do not rest on them: each is checked in tests/test_realistic_holdout35.py against an independent
solution (solve_ivp of the underlying equations, quad, brentq, a per-node loop, a closed form or a direct sum).
"""

import math

import numpy as np
from numba import njit


# ---- the rate-independent core: a push-pull cable in a curved conduit (capstan friction) ----
#
# A voice coil (its force proportional to the drive: a current drive) pushes and pulls the proximal end of a push-pull
# (Bowden) cable whose solid core runs through a curved conduit to a tool held by a return spring; the output is the
# proximal end's travel (the only position such tendon-sheath drives measure). The core slides on the conduit's liner
# with Coulomb friction, per unit length mu (n0 + kappa |P|): a constant drag from the liner's grip (n0) and the
# capstan term, the wrap's normal force kappa |P| of the axial force P on the curvature kappa (Euler and Eytelwein's
# belt friction; for tendon-sheath drives Kaneko, Wada, Maekawa & Tanie, ICRA 1991, and Palli & Melchiorri, ICRA 2006).
# In a slipping stretch dP/ds = -+ (f0 + b |P|) (f0 = mu n0, b = mu kappa, the length 1); where the core sticks its
# force stays. With c = f0 / b and g(P) = sign(P) ln(1 + |P| / c) the slipping fronts are straight lines of slope -+b in
# g, and since a front never crosses another (they solve one ODE), pulling or pushing the end to a force F clamps every
# point's g(P(s)) into [g(F) - b s, g(F) + b s]: g(P(s)) is a play of g(F) of threshold b s. The proximal travel, with
# the cable's compliance 1 (per unit length and unit force) and the tool's spring K, is P(1) / K + int_0^1 P ds.
# Quasi-static Coulomb friction: rate independent, with return-point memory (every point a play of g(F)); NOT a
# Prandtl-Ishlinskii model of F: the thresholds in F grow with the force (the capstan), so the branches are not
# Masing's. For b -> 0 at a fixed f0 it becomes a cable with a constant drag: a PI model (a rod on a rough floor).

@njit(cache=True)
def _g(P, c):
    z = math.log1p(abs(P) / c)
    return z if P >= 0.0 else -z


@njit(cache=True)
def _ginv(z, c):
    p = c * math.expm1(abs(z))
    return p if z >= 0.0 else -p


def capstan_g(P, c):
    """The capstan's transform g(P) = sign(P) ln(1 + |P| / c), in which the slipping fronts are straight lines."""
    P = np.asarray(P, float)
    return np.sign(P) * np.log1p(np.abs(P) / c)


def capstan_ginv(z, c):
    """The inverse of :func:`capstan_g`: sign(z) c (exp|z| - 1)."""
    z = np.asarray(z, float)
    return np.sign(z) * c * np.expm1(np.abs(z))


def cable_nodes(n):
    """The n + 1 nodes s_j = j / n along the cable (0 the proximal end) and the trapezoid rule's weights on them."""
    s = np.arange(n + 1) / n
    w = np.full(n + 1, 1.0 / n)
    w[0] = w[-1] = 0.5 / n
    return s, w


@njit(cache=True)
def _cable_eval(u, z, r, w, wend, c, znew):
    acc = 0.0
    m = len(z)
    for j in range(m):
        zj = z[j]
        lo = u - r[j]
        hi = u + r[j]
        if zj < lo:
            zj = lo
        elif zj > hi:
            zj = hi
        znew[j] = zj
        acc += w[j] * _ginv(zj, c)
    return acc + wend * _ginv(znew[m - 1], c)


@njit(cache=True)
def _cable_run(F, z, r, w, wend, c):
    n = len(F)
    out = np.empty(n)
    znew = np.empty(len(z))
    for k in range(n):
        out[k] = _cable_eval(_g(F[k], c), z, r, w, wend, c, znew)
        z[:] = znew
    return out


def cable_travel(F, b, K, c=1.0, n=96, state=None, return_state=False):
    """The proximal travel for the coil's force F (units: forces in f0 / b, travel in the cable's stretch under a unit
    force): every node's g(P) clamped into [g(F) - b s, g(F) + b s] at each sample (the exact continuum profile at the
    nodes), the travel P(1) / K + the trapezoid rule of P over n segments. ``state`` (the nodes' g(P)) as returned with
    ``return_state``; None is the virgin cable (no force anywhere)."""
    s, w = cable_nodes(n)
    z = np.zeros(n + 1) if state is None else np.array(state, float)
    out = _cable_run(np.asarray(F, float), z, b * s, w, 1.0 / K, float(c))
    return (out, z) if return_state else out


def cable_front(F, s, b, c, sign):
    """The slipping front from the end's force F: the solution of dP/ds = -sign (f0 + b |P|), P(0) = F (sign +1: the end
    pulled up, the force falling along the cable), in closed form through g."""
    return capstan_ginv(capstan_g(F, c) - sign * b * np.asarray(s, float), c)


def cable_peak_force(ratio, b, c=1.0):
    """The end's force whose front from the virgin cable reaches g = (ratio - 1) b at the far end: g(F) = ratio b."""
    return c * math.expm1(ratio * b)


# ---- creep: the voice coil's I^2 R heat expanding the sensor's bracket ----

def two_node_thermal(tau_c, tau_f, m):
    """The state matrix of a coil (heat capacity 1) coupled to the frame (capacity m) by a conductance 1 / tau_c, the
    frame losing heat to the room by m / tau_f: d/dt [T_c, T_f] = A [T_c, T_f] + [p, 0] (a lumped Cauer network;
    e.g. Incropera & DeWitt, *Fundamentals of Heat and Mass Transfer*, the lumped capacitance method)."""
    g = 1.0 / tau_c
    return np.array([[-g, g], [g / m, -(g + m / tau_f) / m]])


def thermal_response(p, dt, A):
    """The frame's temperature under the heating p (sampled, linear between the samples), from the room's temperature:
    the exact first-order-hold discretisation of the linear network (the matrix exponential of the augmented system)."""
    from scipy.linalg import expm
    M = np.zeros((4, 4))
    M[:2, :2] = A * dt
    M[0, 2] = dt                                        # the heating at the step's start enters the coil
    M[2, 3] = 1.0                                       # ... and its slope over the step
    E = expm(M)
    Phi, G0, G1 = E[:2, :2], E[:2, 2], E[:2, 3]
    p = np.asarray(p, float)
    return _thermal_run(p, Phi, G0, G1)


@njit(cache=True)
def _thermal_run(p, Phi, G0, G1):
    n = len(p)
    out = np.empty(n)
    a, b = 0.0, 0.0
    out[0] = 0.0
    for k in range(1, n):
        dp = p[k] - p[k - 1]
        a2 = Phi[0, 0] * a + Phi[0, 1] * b + G0[0] * p[k - 1] + G1[0] * dp
        b2 = Phi[1, 0] * a + Phi[1, 1] * b + G0[1] * p[k - 1] + G1[1] * dp
        a, b = a2, b2
        out[k] = b
    return out


def coil_heat_creep(v, v_top, dt, c, h_top, tau_c, tau_f, m, t_ref=10.0):
    """The bracket's thermal growth under the coil's heat (I^2 R, the current proportional to the drive: p = (v /
    v_top)^2), read as travel: the frame's temperature scaled so that the top drive held t_ref s from cold adds c h_top.
    """
    A = two_node_thermal(tau_c, tau_f, m)
    n_ref = int(round(t_ref / dt))
    step = thermal_response(np.r_[0.0, np.ones(n_ref)], dt, A)
    return c * h_top * thermal_response((np.asarray(v, float) / v_top) ** 2, dt, A) / step[-1]


# ---- rate dependence: the voice coil driven by a voltage amplifier (the motional EMF's damping) ----
#
# With a voltage drive the coil's current is (V - Bl x') / R (its inductance neglected), so the force is Bl V / R -
# (Bl)^2 x' / R: the drive's force less a viscous damping D x' of the proximal travel (e.g. Beranek, *Acoustics*, on the
# moving-coil loudspeaker's electrical damping). The travel follows the cable: x = X(F), so F solves F = F_v - D dX/dt.

@njit(cache=True)
def _emf_run(Fv, z, r, w, wend, c, D, h):
    n = len(Fv)
    out = np.empty(n)
    znew = np.empty(len(z))
    F = Fv[0]
    x = _cable_eval(_g(F, c), z, r, w, wend, c, znew)
    z[:] = znew
    out[0] = x
    for k in range(1, n):
        target = Fv[k]
        if target != F:
            # phi(q) = q + D (X(q) - x) / h - target rises with q (X, the travel after clamping at q, does); phi(F) =
            # F - target and phi(target) = D (X(target) - x) / h have opposite signs: Illinois regula falsi between
            a, fa = F, F - target
            bb = target
            fb = D * (_cable_eval(_g(target, c), z, r, w, wend, c, znew) - x) / h
            for _ in range(200):
                if fb == 0.0 or abs(bb - a) <= 1e-14 * (1.0 + abs(bb)):
                    break
                q = (a * fb - bb * fa) / (fb - fa)
                fq = q + D * (_cable_eval(_g(q, c), z, r, w, wend, c, znew) - x) / h - target
                if fq * fb < 0.0:
                    a, fa = bb, fb
                else:
                    fa *= 0.5
                bb, fb = q, fq
            F = bb
        x = _cable_eval(_g(F, c), z, r, w, wend, c, znew)
        z[:] = znew
        out[k] = x
    return out, F


def voltage_driven_cable(Fv, dt, D, b, K, c=1.0, n=96, sub=32):
    """The proximal travel when the coil's force is F_v - D x' (F_v the force the drive would give at rest: the drive
    over V_F), stepped ``sub`` times a sample by the implicit Euler rule (F_v linear between the samples; each step's
    force solved by regula falsi to 1e-14), from the virgin cable at rest. Returns the travel at the samples."""
    Fv = np.asarray(Fv, float)
    Ff = np.interp(np.arange((len(Fv) - 1) * sub + 1) / sub, np.arange(len(Fv)), Fv)
    s, w = cable_nodes(n)
    z = np.zeros(n + 1)
    x, _ = _emf_run(Ff, z, b * s, w, 1.0 / K, float(c), float(D), dt / sub)
    return x[::sub]


# ---- drift: the sensor's target floats on an aerostatic pad fed from a cycling air receiver ----
#
# The pad's fly height rises with its supply pressure; over the pressure switch's narrow band it is taken as linear in
# the pressure (the case scales it), so the reading's offset follows the receiver's pressure.

def receiver_pressure(t, p_lo, p_hi, p_inf, tau, p0, pumping):
    """The shop air receiver's (absolute) pressure: drawn down by the consumers through fixed (choked) orifices, so
    dp/dt = -p / tau while the compressor rests, and the compressor's constant delivery added while it runs, dp/dt =
    (p_inf - p) / tau; its pressure switch starts it at p_lo and stops it at p_hi (e.g. any compressed-air handbook on
    receiver sizing). Piecewise exponential in closed form from p0 (``pumping`` the compressor's state at t = 0)."""
    t = np.asarray(t, float)
    out = np.empty(len(t))
    ts, ps, on = 0.0, float(p0), bool(pumping)
    segs = []
    while ts <= t[-1]:
        if on:
            te = ts + tau * math.log((p_inf - ps) / (p_inf - p_hi))
        else:
            te = ts + tau * math.log(ps / p_lo)
        segs.append((ts, te, ps, on))
        ts, ps, on = te, (p_hi if on else p_lo), not on
    for ta, tb, pa, on in segs:
        m = (t >= ta) & (t < tb)
        if on:
            out[m] = p_inf + (pa - p_inf) * np.exp(-(t[m] - ta) / tau)
        else:
            out[m] = pa * np.exp(-(t[m] - ta) / tau)
    return out, segs


# ---- asymmetry: a liquid-metal strain gauge stretched by the stage ----

def whitney_resistance(lam, R0):
    """The resistance of a liquid-metal (mercury-in-rubber, Whitney 1949) gauge stretched lam times its rest length: the
    metal's volume kept, every element's length times lam and its section over lam, so R = R0 lam^2 whatever the
    channel's profile."""
    return R0 * np.asarray(lam, float) ** 2


def whitney_reading(u, a):
    """The gauge read at a constant current, the stage's travel u (-1 ... 1) stretching it by 1 + a u about its rest
    stretch, scaled to slope 1 at u = 0: ((1 + a u)^2 - 1) / (2 a); the ends' secants 1 + a / 2 and 1 - a / 2 (a
    apart)."""
    u = np.asarray(u, float)
    return ((1.0 + a * u) ** 2 - 1.0) / (2.0 * a)


# ---- saturation: a balanced slope (Travis) discriminator reading a variable-inductance oscillator ----

def tank_envelope(x):
    """A high-Q parallel tank's relative response at the detuning x (in half-bandwidths, 2 Q df / f0): the universal
    resonance curve 1 / sqrt(1 + x^2) (e.g. Terman, *Radio Engineers' Handbook*, 1943)."""
    x = np.asarray(x, float)
    return 1.0 / np.sqrt(1.0 + x * x)


def travis_output(x, d):
    """The balanced slope (Travis) discriminator: two tanks tuned d half-bandwidths above and below the carrier's rest
    frequency, each envelope-detected, their difference: A(x - d) - A(x + d) (odd in the detuning x)."""
    x = np.asarray(x, float)
    return tank_envelope(x - d) - tank_envelope(x + d)


def travis_reading(u, m, d):
    """The discriminator's reading for the stage's travel u (-1 ... 1), the oscillator's coil's slug detuning it by m u
    half-bandwidths, scaled to slope 1 at u = 0: D(m u) / (m D'(0)), D'(0) = 2 d / (1 + d^2)^(3/2)."""
    return travis_output(m * np.asarray(u, float), d) / (m * 2.0 * d / (1.0 + d * d) ** 1.5)


# ---- delay: a dispensed bead read downstream on a conveyor ----

def conveyor_reading(hf, R, M):
    """A dispenser on the stage lays a bead on a belt running at a constant speed; a laser line profiler a distance
    downstream reads the bead's lateral position at each record sample: the stage's position when that bit of bead was
    laid, M fine steps (the belt's transit time over the core's grid, R fine steps a record sample) earlier. ``hf`` is
    the travel on the fine grid (every R-th a record's sample); before the first bead arrives the reading is hf[0]."""
    hf = np.asarray(hf, float)
    k = np.arange(0, len(hf), R) - M
    return hf[np.maximum(k, 0)]


# ---- the initial state: a perturb-and-observe tracker tuning a vibration energy harvester ----

def harvester_power(x, x_opt, width):
    """A resonant vibration harvester's power as the stage tunes it (its frequency linear in the travel near the
    machine's): a Lorentzian peak 1 / (1 + ((x - x_opt) / width)^2) (the resonance's power curve, e.g. Williams & Yates,
    Sens. Actuators A 52 (1996) 8)."""
    return 1.0 / (1.0 + ((np.asarray(x, float) - x_opt) / width) ** 2)


def perturb_and_observe(travel, x_opt, width, step, n_iter, n_per=40, n_down=400):
    """A perturb-and-observe tracker (the hill climbing of photovoltaic MPPT; e.g. Femia, Petrone, Spagnuolo & Vitelli,
    IEEE Trans. Power Electron. 20 (2005) 963): from 0 V it steps the drive by ``step``, ramping over n_per points,
    reads the harvester's power at the step's end and reverses the direction when the power fell; after n_iter steps
    the session stops, the drive ramped to 0 V over n_down points. ``travel(path, state) ->
    (travel, state)`` runs the core. Returns (path, levels, powers, state)."""
    state = None
    v, direction = 0.0, 1.0
    path = [np.zeros(1)]
    x, state = travel(np.zeros(1), state)
    p_old = float(harvester_power(x[-1], x_opt, width))
    levels, powers = [0.0], [p_old]
    for _ in range(n_iter):
        seg = np.linspace(v, v + direction * step, n_per + 1)[1:]
        x, state = travel(seg, state)
        v = float(seg[-1])
        p = float(harvester_power(x[-1], x_opt, width))
        if p < p_old:
            direction = -direction
        p_old = p
        levels.append(v)
        powers.append(p)
        path.append(seg)
    down = np.linspace(v, 0.0, n_down + 1)[1:]
    _, state = travel(down, state)
    path.append(down)
    return np.concatenate(path), levels, powers, state


# ---- the pair: a Wien-bridge oscillator's amplitude bounce (a thermistor's AGC) exciting the LVDT ----

def wien_envelope_rhs(a, theta, k, gamma, tau):
    """The amplitude envelope a of a Wien-bridge oscillator stabilised by an NTC thermistor in its feedback arm
    (Hewlett's 1939 oscillator used a lamp; the thermistor's version is the same loop) and the thermistor's heating
    theta, both 1 at the operating point: a' = k (G(theta) - 1) a with the loop gain G = 1 + gamma (1 - theta) (the
    bead's resistance falling as it warms), theta' = (a^2 - theta) / tau (its heat balance: the power as a^2). The
    slow thermal loop makes the amplitude bounce about its final value (a damped oscillation)."""
    return k * gamma * (1.0 - theta) * a, (a * a - theta) / tau


def wien_envelope(t, a0, th0, k, gamma, tau, sub=20):
    """:func:`wien_envelope_rhs` integrated by the classical Runge-Kutta rule, ``sub`` steps a sample of t (uniform),
    from (a0, th0) at t[0]. Returns (a, theta)."""
    t = np.asarray(t, float)
    h = (t[1] - t[0]) / sub
    return _wien_run(len(t), float(a0), float(th0), k, gamma, tau, h, sub)


@njit(cache=True)
def _wien_run(n, a, th, k, gamma, tau, h, sub):
    A = np.empty(n)
    TH = np.empty(n)
    A[0], TH[0] = a, th
    for i in range(1, n):
        for _ in range(sub):
            a1 = k * gamma * (1.0 - th) * a
            t1 = (a * a - th) / tau
            aa, tt = a + 0.5 * h * a1, th + 0.5 * h * t1
            a2 = k * gamma * (1.0 - tt) * aa
            t2 = (aa * aa - tt) / tau
            aa, tt = a + 0.5 * h * a2, th + 0.5 * h * t2
            a3 = k * gamma * (1.0 - tt) * aa
            t3 = (aa * aa - tt) / tau
            aa, tt = a + h * a3, th + h * t3
            a4 = k * gamma * (1.0 - tt) * aa
            t4 = (aa * aa - tt) / tau
            a += h * (a1 + 2 * a2 + 2 * a3 + a4) / 6.0
            th += h * (t1 + 2 * t2 + 2 * t3 + t4) / 6.0
        A[i], TH[i] = a, th
    return A, TH


# ---- out of vocabulary: a reflective fibre-optic displacement probe whose stroke crosses its peak ----

def fibre_probe(d, D, a, tan_na):
    """A two-fibre reflective displacement probe (an emitting and a receiving fibre, D apart, facing a mirror at d): the
    emitted cone reflected back is a spot of radius w = a + 2 d tan(NA) (a the core's radius) with a Gaussian profile,
    received by a small core at the distance D from its centre: (a / w)^2 exp(-2 D^2 / w^2) (the Gaussian model of
    the fibre-optic lever; e.g. Cook & Hamm, Appl. Opt. 18 (1979) 3230). It rises on the front slope (the spot
    reaching the receiver) to its peak at w = sqrt(2) D and falls as 1 / w^2 on the back slope."""
    w = a + 2.0 * np.asarray(d, float) * tan_na
    return (a / w) ** 2 * np.exp(-2.0 * D * D / (w * w))


def fibre_peak_distance(D, a, tan_na):
    """The mirror's distance at the probe's peak: w = sqrt(2) D."""
    return (math.sqrt(2.0) * D - a) / (2.0 * tan_na)

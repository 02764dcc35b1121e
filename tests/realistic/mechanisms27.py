"""Mechanisms of the HOLDOUT27 set (``cases_holdout27.py``), each written from its law; the signals are in
:mod:`.signals27`.

Nothing here imports hystcomp. Every mechanism takes the (clean) drive, or the core's output, and returns the response;
all are causal. The play, a path's turning points, the raised cosine, the exact Kelvin-element recursion and the
first-order-hold response are the earlier sets' (the same laws, imported as mechanisms26 does).

Citations: every source below was written from memory in this session (none was re-read); volumes, pages and years may
be off. The laws do not rest on them: each is checked in tests/test_realistic_holdout27.py against an independent
solution (a closed form, quadrature, brentq, solve_ivp, scipy's own routines or a finer simulation).
"""

import math

import numpy as np
from scipy.special import jn_zeros

from .mechanisms13 import turning_points  # noqa: F401
from .mechanisms18 import grid, plays  # noqa: F401
from .mechanisms19 import raised_cosine  # noqa: F401
from .mechanisms24 import kelvin_modes_response
from .mechanisms26 import foh_response  # noqa: F401


# ---- the rate-independent core: a Ramberg-Osgood skeleton with Masing's branches and the memory rules ----

def ro_skeleton(v, a, n, S):
    """The Ramberg-Osgood skeleton (virgin) curve (Ramberg & Osgood, NACA TN 902, 1943), the stage's travel under the
    drive v (in volts, as the load): phi(v) = v + a S |v / S|^n sign(v): linear at first, softening (the travel growing
    faster than the load) toward the stroke's ends; odd."""
    v = np.asarray(v, float)
    return v + a * S * np.sign(v) * np.abs(v / S) ** n


def masing_core(v, a, n, S, state=None, return_state=False):
    """A Masing-type hysteresis (Masing 1926; Jennings, J. Eng. Mech. Div. ASCE 90 (1964) 131; Pyke 1979's extended
    rules), written with a stack of turning points instead of plays: from the virgin state the travel follows the
    skeleton phi (:func:`ro_skeleton`); from every reversal (v_r, x_r) it follows x_r + 2 phi((v - v_r) / 2) (the
    skeleton doubled: Masing's rule); when a branch reaches the turning point before its own start, the loop closes
    and the branch that was left there is resumed (Madelung's rules: the inner loop is wiped out), and a branch that
    reaches the skeleton (at the mirror image of the skeleton's last turning point) follows it again. The rules make
    the core rate independent with return-point memory. ``state`` is (turning points, last input, last output, last
    direction) as returned with ``return_state``; None is the virgin state at 0."""
    if state is None:
        tp, u_prev, x_prev, d = [], 0.0, 0.0, 0
    else:
        tp, u_prev, x_prev, d = list(state[0]), float(state[1]), float(state[2]), int(state[3])
    aS = a * S
    inv_s = 1.0 / S

    def phi(u):
        return u + aS * math.copysign(abs(u * inv_s) ** n, u)

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
            if tp:
                vr, xr = tp[-1]
                x_prev = xr + 2.0 * phi((u - vr) / 2.0)
            else:
                x_prev = phi(u)
            u_prev = u
        out[k] = x_prev
    if return_state:
        return out, (tuple(tp), u_prev, x_prev, d)
    return out


def masing_plays(a, n, S, r_max, n_plays=4000):
    """The Prandtl-Ishlinskii plays equal to :func:`masing_core` (a PI operator's loading curve phi and its branches
    x_r + 2 phi((v - v_r) / 2) are Masing's: Iwan 1967, Brokate & Sprekels 1996): the linear part phi'(0) = 1 and the
    density phi''(r) = a n (n - 1) S^(1 - n) r^(n - 2) on :func:`grid` cells of (0, r_max), each cell's exact weight
    a n S^(1 - n) (b^(n - 1) - a^(n - 1)). For the tests (an independent solution of the same law)."""
    edges = np.linspace(0.0, r_max, n_plays + 1)
    w = a * n * S ** (1 - n) * (edges[1:] ** (n - 1) - edges[:-1] ** (n - 1))
    return grid(n_plays, r_max), w, 1.0


# ---- creep: radial consolidation of a cylindrical pad drained through its jacket ----

def cylinder_modes(n_modes=1000):
    """The radial drainage of a long cylinder (Carslaw & Jaeger, *Conduction of Heat in Solids*, 1959, sec. 7.4; in soil
    mechanics Rendulic 1935 and Barron 1948's free-strain radial consolidation): the excess pore pressure u_t = c (u_rr
    + u_r / r), u = 0 at the drained jacket r = a; the mean pressure after a load step is sum_n (4 / alpha_n^2) exp(-
    alpha_n^2 t / tau), alpha_n the zeros of J0, tau = a^2 / c. Returns (alpha_n^2, 4 / alpha_n^2) (their sum 1 - the
    tail beyond n_modes, 4 / (pi^2 n_modes) at most, which drains at once)."""
    al = jn_zeros(0, n_modes)
    return al * al, 4.0 / (al * al)


def radial_function(t, tau, n_modes=1000):
    """The consolidation 1 - sum_n w_n exp(-alpha_n^2 t / tau) (0 at t = 0 but for the tail, 1 at the end)."""
    rates, w = cylinder_modes(n_modes)
    t = np.clip(np.asarray(t, float), 0.0, None)[..., None]
    return 1.0 - np.sum(w * np.exp(-rates * t / tau), axis=-1)


def radial_creep(h, dt, c, tau, t_ref=10.0, n_modes=1000):
    """Creep of the stage's cylindrical wet-felt pad, consolidating as its water drains radially through its jacket
    under the core's force h: Boltzmann superposition of :func:`radial_function` (a Kelvin element per mode, exact for h
    linear between samples; the undrained tail at once), scaled so that a step held t_ref s creeps by c of it; at rest
    at h[0] before the record."""
    rates, w = cylinder_modes(n_modes)
    h = np.asarray(h, float)
    resp = kelvin_modes_response(h - h[0], dt, tau / rates, w) + (1.0 - float(np.sum(w))) * (h - h[0])
    return c * resp / float(radial_function(t_ref, tau, n_modes))


# ---- rate dependence: a hydraulic engine mount's inertia track ----

def mount_transfer(omega, beta, f_t, zeta):
    """The stage on a hydraulically damped mount (Flower, SAE 850975, 1985; Kim & Singh, J. Sound Vib. 1993): a rubber
    spring beside a piston of area A into a chamber of compliance C, emptied through an inertia track (the liquid
    column's inertance I and resistance R) to a free bellows; the core's output h pulls the stage through the flexure
    k_f. The force balance k_f (h - y) = k_r y + A p, C p' = A y' - q, I q' = p - R q gives y / h = g0 ((1 - beta) +
    beta / (s^2 / w_t^2 + 2 zeta s / w_t + 1)), g0 = k_f / (k_f + k_r), beta = (A^2 / C) / (k_f + k_r + A^2 / C), w_t
    the liquid column's resonance: soft when slow, stiffer by 1 / (1 - beta) when fast, the track's resonance
    between. Returns it with g0 = 1 at s = i omega."""
    s = 1j * np.asarray(omega, float)
    w = 2 * math.pi * f_t
    return (1 - beta) + beta / (s * s / (w * w) + 2 * zeta * s / w + 1)


def mount_stage(h, dt, beta, f_t, zeta):
    """The stage's travel under h (linear between samples: the liquid column's states by the exact first-order hold),
    at rest at h[0] before the record."""
    w = 2 * math.pi * f_t
    A = np.array([[0.0, 1.0], [-w * w, -2 * zeta * w]])
    B = np.array([[0.0], [w * w]])
    C = np.array([[1.0, 0.0]])
    h = np.asarray(h, float)
    lp = foh_response(A, B, C, h, dt, np.array([h[0], 0.0]))
    return (1 - beta) * h + beta * lp


# ---- offset drift: a leaking pneumatic clamp (the blowdown of a vessel through an orifice) ----

GAMMA_AIR = 1.4


def critical_ratio(gamma=GAMMA_AIR):
    """The critical pressure ratio (2 / (gamma + 1))^(gamma / (gamma - 1)) = 0.528 for air."""
    return (2 / (gamma + 1)) ** (gamma / (gamma - 1))


def orifice_factor(pr, gamma=GAMMA_AIR):
    """The mass flow through an orifice from a vessel at p to the ambient at p_a = pr p over its choked value (Saint-
    Venant & Wantzel, J. Ec. Polytech. 16 (1839) 85; isentropic nozzle flow): 1 while pr is at or below the critical
    ratio, else sqrt(pr^(2 / gamma) - pr^((gamma + 1) / gamma)) over its value at the critical ratio (continuous
    there, 0 at pr = 1)."""
    pr = np.clip(np.asarray(pr, float), 0.0, 1.0)
    bc = critical_ratio(gamma)

    def psi(x):
        return np.sqrt(np.clip(x ** (2 / gamma) - x ** ((gamma + 1) / gamma), 0.0, None))
    return np.where(pr <= bc, 1.0, psi(pr) / psi(bc))


def blowdown(t, t_s, p0, pa, tau_b, gamma=GAMMA_AIR):
    """The clamp's pressure (absolute) at the times t: p0 until t_s, when the supply is shut off and it leaks, kept at
    room temperature by the cylinder's walls (isothermal: dp/dt = -(R T / V) m'): dp/dt = -(p / tau_b) F(pa / p), F
    :func:`orifice_factor`; choked, an exponential decay, then the subsonic tail, reaching pa in a finite time. By
    solve_ivp (DOP853, rtol 1e-11) from t_s; pa once reached."""
    from scipy.integrate import solve_ivp
    t = np.asarray(t, float)
    out = np.full_like(t, p0)
    m = t > t_s

    def rhs(_, p):
        return [-(p[0] / tau_b) * float(orifice_factor(pa / max(p[0], pa)))]

    def done(_, p):
        return p[0] - pa * (1 + 1e-12)
    done.terminal = True
    if np.any(m):
        sol = solve_ivp(rhs, (t_s, t[-1]), [p0], method="DOP853", rtol=1e-11, atol=1e-12 * p0, dense_output=True,
                        events=done)
        t_end = sol.t[-1]
        tt = t[m]
        out[m] = np.where(tt < t_end, sol.sol(np.minimum(tt, t_end))[0], pa)
    return out


# ---- asymmetry: a float in a conical vessel ----

def cone_reading(x, xi):
    """The level of a liquid in a conical vessel standing on its apex (the volume pi tan^2(half angle) h^3 / 3), into
    which the stage's piston pushes liquid (the volume V0 (1 + xi x), x the stage's travel over its largest): h = h0 (1
    + xi x)^(1/3), read by a float and scaled to slope 1 at rest: 3 ((1 + xi x)^(1/3) - 1) / xi: monotone, concave (the
    vessel widens as it fills)."""
    return 3.0 * (np.cbrt(1.0 + xi * np.asarray(x, float)) - 1.0) / xi


# ---- saturation: a taut wire under a constant tension, pushed sideways at its middle ----

def wire_reading(x, z):
    """A wire over two pulleys 2 L apart, tensioned by a hanging weight (a constant tension T), pushed sideways at its
    middle by the stage; a load cell reads the wire's restoring force 2 T sin(theta) = 2 T u / sqrt(L^2 + u^2) (e.g. any
    statics text). With the travel x over its largest and z = (largest travel) / L, scaled to slope 1 at rest: x /
    sqrt(1 + (z x)^2): odd, compressed toward the ends."""
    x = np.asarray(x, float)
    return x / np.sqrt(1.0 + (z * x) ** 2)


# ---- delay: a Thiran allpass fractional-delay filter ----

def thiran_coeffs(D, N):
    """The denominator a_0 ... a_N (a_0 = 1) of Thiran's allpass of order N with the maximally flat group delay D at DC
    (Thiran, IEEE Trans. Circuit Theory 18 (1971) 659; Laakso et al., IEEE Signal Process. Mag. 13 (1996) 30): a_k =
    (-1)^k C(N, k) prod_{i=0}^{N} (D - N + i) / (D - N + k + i); stable for D > N - 1. H(z) = z^-N A(1 / z) / A(z)."""
    a = np.empty(N + 1)
    for k in range(N + 1):
        p = 1.0
        for i in range(N + 1):
            p *= (D - N + i) / (D - N + k + i)
        a[k] = (-1) ** k * math.comb(N, k) * p
    return a


def thiran_sensor(h, D, N, latency):
    """A sensor whose DSP aligns its channel with a Thiran allpass (:func:`thiran_coeffs`) and delivers each value
    `latency` samples later: a delay of D + latency samples at low frequencies, the magnitude untouched; at rest at
    h[0] before the record."""
    from scipy.signal import lfilter, lfiltic
    a = thiran_coeffs(D, N)
    b = a[::-1]
    h = np.asarray(h, float)
    zi = lfiltic(b, a, np.full(N, h[0]), np.full(N, h[0]))
    y = lfilter(b, a, h, zi=zi)[0]
    return np.r_[np.full(latency, h[0]), y[:len(h) - latency]]


# ---- initial state: Levitt's transformed up-down staircase run on the stage ----

def levitt_staircase(start, step0, n_rev, mu, s, rng, floor=2.0, top=None):
    """The levels of a two-down one-up staircase (Levitt, J. Acoust. Soc. Am. 49 (1971) 467: converging on the level
    detected 70.7 % of the time) run with the stage as the stimulus: an observer answers a two-alternative trial
    correctly with the probability 1/2 + 1/2 / (1 + exp(-(L - mu) / s)); two correct answers in a row lower the level
    by the step, a wrong one raises it; the step halves at each of the first three reversals; it stops after n_rev
    reversals. Returns the levels held, trial by trial, and the answers."""
    L, step, levels, answers = float(start), float(step0), [], []
    run, last_dir, n_r = 0, 0, 0
    while n_r < n_rev:
        levels.append(L)
        ok = rng.uniform() < 0.5 + 0.5 / (1 + math.exp(-(L - mu) / s))
        answers.append(bool(ok))
        move = 0
        if ok:
            run += 1
            if run == 2:
                move, run = -1, 0
        else:
            move, run = 1, 0
        if move:
            if last_dir and move != last_dir:
                n_r += 1
                if n_r <= 3:
                    step /= 2
            last_dir = move
            L = min(max(L + move * step, floor), top if top is not None else np.inf)
    return np.array(levels), np.array(answers)


# ---- the pair: a Kaiser-windowed sinc decimator and a flat plate in a free-streamline flow ----

def kaiser_sinc(numtaps, cutoff, beta):
    """A linear-phase low-pass FIR: the ideal impulse response sin(2 pi f_c n) / (pi n) (f_c in cycles a sample) times
    Kaiser's window I0(beta sqrt(1 - (2 n / (N - 1))^2)) / I0(beta) (Kaiser, in *System Analysis by Digital Computer*,
    1966), n centred, normalised to a DC gain of 1; its group delay (N - 1) / 2 at every frequency."""
    m = np.arange(numtaps) - (numtaps - 1) / 2
    ideal = 2 * cutoff * np.sinc(2 * cutoff * m)
    win = np.i0(beta * np.sqrt(np.clip(1 - (2 * m / (numtaps - 1)) ** 2, 0.0, None))) / np.i0(beta)
    h = ideal * win
    return h / h.sum()


def decimating_sensor(h_fine, R, numtaps, cutoff, beta, latency):
    """A delta-sigma converter's decimator: the core's output at the modulator's rate (R times the record's) through
    :func:`kaiser_sinc`, every R-th value kept (on the record's ticks), delivered `latency` samples later: a delay of
    (numtaps - 1) / (2 R) + latency record samples; at rest at h[0] before the record."""
    from scipy.signal import lfilter
    g = kaiser_sinc(numtaps, cutoff, beta)
    h = np.asarray(h_fine, float)
    y = lfilter(g, [1.0], h - h[0]) + h[0]
    y = y[::R]
    return np.r_[np.full(latency, h[0]), y[:len(y) - latency]]


def rayleigh_normal(alpha):
    """The normal-force coefficient of a flat plate at the incidence alpha in Kirchhoff's free-streamline flow (a wake
    of dead air behind it: Rayleigh, Phil. Mag. 2 (1876) 430): C_N = 2 pi sin(alpha) / (4 + pi |sin(alpha)|); 2 pi / (4
    + pi) = 0.88 broadside on, its slope pi / 2 at zero incidence."""
    s = np.sin(np.asarray(alpha, float))
    return 2 * math.pi * s / (4 + math.pi * np.abs(s))


def plate_reading(x, alpha_m):
    """A vane the stage turns (its incidence alpha_m x, x the travel over its largest) read by a balance's normal force,
    scaled to slope 1 at rest: C_N(alpha_m x) / (pi alpha_m / 2): odd, compressed toward the ends."""
    return rayleigh_normal(alpha_m * np.asarray(x, float)) / (math.pi * alpha_m / 2)


# ---- out of vocabulary: a resettable PTC fuse (polyfuse) in series with the stack ----

def ptc_resistance(T, R0, ratio, T_c, width):
    """A polymeric PTC's resistance: R0 cold, rising by the factor `ratio` across a few kelvin about T_c (the polymer's
    melting swells it apart and breaks its carbon chains: e.g. Doljack, IEEE Trans. CHMT 4 (1981) 372): R0 ratio^S, S
    the logistic step 1 / (1 + exp(-(T - T_c) / width))."""
    return R0 * ratio ** (1.0 / (1.0 + np.exp(-(np.asarray(T, float) - T_c) / width)))


def polyfuse_stack(v, dt, C, R0, ratio, T_c, width, G, tau_th, T_a=25.0, T0=None, n_sub=1):
    """The stack's voltage v_s behind the fuse, driven by the amplifier's v (linear between samples dt apart): v_s' = (v
    - v_s) / (R(T) C), and the fuse's temperature, tau_th T' = (v - v_s)^2 / (R(T) G) - (T - T_a) (its heat capacity
    tau_th G, its loss G). A step at a time: v_s exactly for R held at its value at the step's middle (predicted), T by
    the exact exponential step under the mean of the Joule heat over the step (the trapezoid rule): second order in
    dt, on n_sub steps per sample (v linear between the samples). From v_s = v[0] and T = T0 (T_a if None). Returns
    (v_s, T) at the samples."""
    v = np.asarray(v, float)
    if n_sub > 1:
        VS, TT = polyfuse_stack(np.interp(np.arange((len(v) - 1) * n_sub + 1) / n_sub, np.arange(len(v)), v),
                                dt / n_sub, C, R0, ratio, T_c, width, G, tau_th, T_a, T0)
        return VS[::n_sub], TT[::n_sub]
    v = v.tolist()
    vs, T = v[0], T_a if T0 is None else float(T0)
    VS, TT = np.empty(len(v)), np.empty(len(v))
    VS[0], TT[0] = vs, T
    lnr = math.log(ratio)
    e_th = math.exp(-dt / tau_th)

    def res(x):
        return R0 * math.exp(lnr / (1.0 + math.exp(-(x - T_c) / width)))

    def heat(e, R):
        return e * e / (R * G)

    for k in range(len(v) - 1):
        va, vb = v[k], v[k + 1]
        R1 = res(T)
        # predict the temperature at the middle of the step with the heat at its start
        Tm = T_a + (T - T_a) * math.exp(-0.5 * dt / tau_th) + heat(va - vs, R1) * -math.expm1(-0.5 * dt / tau_th)
        R = res(Tm)
        lam = 1.0 / (R * C)
        sl = (vb - va) / dt
        # v_s' = lam (va + sl s - v_s): the particular solution va + sl s - sl / lam, plus the decay
        ex = math.exp(-lam * dt)
        vs_new = vb - sl / lam + (vs - va + sl / lam) * ex
        P = 0.5 * (heat(va - vs, R) + heat(vb - vs_new, R))
        T = T_a + (T - T_a) * e_th + P * (1.0 - e_th)
        vs = vs_new
        VS[k + 1], TT[k + 1] = vs, T
    return VS, TT


__all__ = ["turning_points", "grid", "plays", "raised_cosine", "kelvin_modes_response", "foh_response",
           "ro_skeleton", "masing_core", "masing_plays", "cylinder_modes", "radial_function", "radial_creep",
           "mount_transfer", "mount_stage", "GAMMA_AIR", "critical_ratio", "orifice_factor", "blowdown",
           "cone_reading", "wire_reading", "thiran_coeffs", "thiran_sensor", "levitt_staircase", "kaiser_sinc",
           "decimating_sensor", "rayleigh_normal", "plate_reading", "ptc_resistance", "polyfuse_stack"]

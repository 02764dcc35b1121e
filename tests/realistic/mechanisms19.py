"""Mechanisms and signals of the HOLDOUT19 set (``cases_holdout19.py``), each written from its law.

Nothing here imports hystcomp (nor the other sets' mechanisms). Every mechanism takes the (clean) drive, or the
core's output, and returns the response; all are causal. The sources of the laws are beside each function and in
``cases_holdout19``'s docstring.

Citations: every source below was written from memory in this session (none was re-read): the papers' volumes,
pages and years, the books' chapters and the standards' clauses may be off. The laws themselves do not rest on them:
each is checked in tests/test_realistic_holdout19.py against an independent solution (Terzaghi's consolidation
against a finite-difference solution of the pore-pressure equation by solve_ivp and its early-time limit, the oil
film against its closed-form (coth) impedance and solve_ivp, the self-heating against solve_ivp, the double pendulum
against a mass-matrix formulation and its energy, the pinhole triangulation and the inclinometer against ray and
vector geometry, the time of flight against brentq, the Mathieu swing against its Floquet growth rate, the galloping
prism against its averaged amplitude, and so on).
"""

import math

import numpy as np
from scipy.integrate import solve_ivp
from scipy.linalg import expm

# the play, the threshold grid and exponentially weighted plays are HOLDOUT18's, a path's turning points
# HOLDOUT13's: the same laws (the cases and tests use them from here)
from .mechanisms13 import turning_points  # noqa: F401
from .mechanisms18 import exp_plays, grid, plays  # noqa: F401

# ---- rate-independent cores ----


def maxwell_plays(n, r_max, a, w0):
    """Thresholds on :func:`grid` weighted by the Maxwell density sqrt(2 / pi) r^2 exp(-r^2 / (2 a^2)) / a^3 (the
    length of a vector of three independent Gaussian components of deviation a: the magnitude of a random local
    field acting on a domain wall segment; Maxwell, Phil. Mag. 19 (1860) 19), summing to 1 - w0."""
    r = grid(n, r_max)
    dens = r * r * np.exp(-r * r / (2 * a * a))
    return r, (1 - w0) * dens / dens.sum()


# ---- signals ----

def raised_cosine(x):
    """0 for x <= 0, (1 - cos(pi x)) / 2 between, 1 for x >= 1."""
    return 0.5 - 0.5 * np.cos(np.pi * np.clip(np.asarray(x, float), 0.0, 1.0))


def smoothstep(x):
    """The cubic move 3 s^2 - 2 s^3 (s clipped to 0 ... 1): zero speed at both ends."""
    s = np.clip(np.asarray(x, float), 0.0, 1.0)
    return s * s * (3 - 2 * s)


def rossler_rhs(t, s, a, b, c):
    """Roessler's attractor, x' = -y - z, y' = x + a y, z' = b + z (x - c) (Roessler, Phys. Lett. A 57 (1976) 397;
    a = b = 0.2, c = 5.7 the classic chaotic band, its x oscillating with a period near 6 time units)."""
    x, y, z = s
    return [-y - z, x + a * y, b + z * (x - c)]


def rossler_x(t, units, start, a=0.2, b=0.2, c=5.7, settle=100.0):
    """The x of Roessler's system at the times t (s), at `units` time units a second, after `settle` units from
    `start` (DOP853, rtol 1e-11)."""
    s0 = np.array(start, float)
    if settle > 0:
        s0 = solve_ivp(rossler_rhs, (0, settle), s0, args=(a, b, c), method="DOP853", rtol=1e-11,
                       atol=1e-12).y[:, -1]
    tau = np.asarray(t, float) * units
    sol = solve_ivp(rossler_rhs, (tau[0], tau[-1]), s0, t_eval=tau, args=(a, b, c), method="DOP853", rtol=1e-11,
                    atol=1e-12)
    return sol.y[0], s0


def collatz(n0):
    """The hailstone orbit n0, ..., 1 (n / 2 if even, 3 n + 1 if odd; Collatz's problem, Lagarias, Amer. Math.
    Monthly 92 (1985) 3)."""
    out = [int(n0)]
    while out[-1] != 1:
        n = out[-1]
        out.append(n // 2 if n % 2 == 0 else 3 * n + 1)
    return np.array(out)


def held_levels(t, lead, levels, holds, moves):
    """From 0 V at rest for `lead` s, a smoothstep move of moves[i] s to each level in turn, each held holds[i] s;
    the move starts of every level and the end are returned too."""
    t = np.asarray(t, float)
    v = np.zeros_like(t)
    prev, tc, starts = 0.0, lead, []
    for lv, hd, mv in zip(levels, holds, np.broadcast_to(moves, len(levels))):
        starts.append(tc)
        v = np.where(t >= tc, prev + (lv - prev) * smoothstep((t - tc) / mv), v)
        prev, tc = lv, tc + mv + hd
    return v, np.array(starts), tc


def hypotrochoid_x(theta, R, r, d):
    """The x of a spirograph's pen (a hypotrochoid: a circle of radius r rolling inside one of radius R, the pen d
    from its centre): (R - r) cos theta + d cos((R - r) theta / r)."""
    return (R - r) * np.cos(theta) + d * np.cos((R - r) / r * theta)


def fibonacci_word(n):
    """The first n letters of the Fibonacci word (a -> ab, b -> a from a: abaababaabaab...), a Sturmian sequence
    (Berstel, 1980s surveys)."""
    w = "a"
    while len(w) < n:
        w = "".join("ab" if ch == "a" else "a" for ch in w)
    return w[:n]


def word_cycles(t, lead, word, seg):
    """Whole sine cycles, one segment per letter: seg[letter] = (cycles, frequency, amplitude); returns the drive,
    its exact time derivative and the segments' start times."""
    t = np.asarray(t, float)
    v, dv = np.zeros_like(t), np.zeros_like(t)
    tc, starts = lead, []
    for ch in word:
        n_c, f, a = seg[ch]
        T = n_c / f
        sel = (t >= tc) & (t < tc + T)
        ph = 2 * np.pi * f * (t[sel] - tc)
        v[sel] = a * np.sin(ph)
        dv[sel] = 2 * np.pi * f * a * np.cos(ph)
        starts.append(tc)
        tc += T
    return v, dv, np.array(starts), tc


def double_pendulum_rhs(t, s, mu, lam):
    """A double pendulum (angles from the vertical; the upper rod 1 long, the lower lam; the lower bob's mass over
    both mu = m2 / (m1 + m2); g = 1), from its Lagrangian (e.g. Goldstein, *Classical Mechanics*, ch. 1 problems):
    the classic explicit form of the two coupled equations."""
    t1, t2, w1, w2 = s
    d = t1 - t2
    m1, m2 = 1 - mu, mu
    den = 2 * m1 + m2 - m2 * math.cos(2 * d)
    a1 = (-(2 * m1 + m2) * math.sin(t1) - m2 * math.sin(t1 - 2 * t2)
          - 2 * math.sin(d) * m2 * (w2 * w2 * lam + w1 * w1 * math.cos(d))) / den
    a2 = 2 * math.sin(d) * (w1 * w1 * (m1 + m2) + (m1 + m2) * math.cos(t1) + w2 * w2 * lam * m2 * math.cos(d)) / (
        lam * den)
    return [w1, w2, a1, a2]


def double_pendulum_energy(s, mu, lam):
    """Its energy (per unit of total mass, g = 1, the pivot at height 0)."""
    t1, t2, w1, w2 = s
    kin = 0.5 * w1 ** 2 + 0.5 * mu * lam ** 2 * w2 ** 2 + mu * lam * w1 * w2 * np.cos(t1 - t2)
    return kin - np.cos(t1) - mu * lam * np.cos(t2)


def double_pendulum(t, units, start, mu, lam):
    """The lower bob's x, sin t1 + lam sin t2, and the states at the times t (s), `units` time units a second
    (DOP853, rtol 1e-12)."""
    tau = np.asarray(t, float) * units
    sol = solve_ivp(double_pendulum_rhs, (tau[0], tau[-1]), start, t_eval=tau, args=(mu, lam), method="DOP853",
                    rtol=1e-12, atol=1e-12)
    s = sol.y
    return np.sin(s[0]) + lam * np.sin(s[1]), s, tau


def henon_orbit(x0, y0, n, a=1.4, b=0.3, skip=50):
    """n points of Henon's map x' = 1 - a x^2 + y, y' = b x (Henon, Commun. Math. Phys. 50 (1976) 69), after `skip`
    iterations from (x0, y0)."""
    x, y = x0, y0
    out = []
    for k in range(skip + n):
        x, y = 1 - a * x * x + y, b * x
        if k >= skip:
            out.append(x)
    return np.array(out)


def takagi(s, level):
    """Takagi's blancmange function to `level`: sum_{k=0}^{level} 2^-k dist(2^k s, Z), period 1, in 0 ... 2/3
    (Takagi, Proc. Phys.-Math. Soc. Japan 1 (1903) 176): a path of 2^(level+1) straight pieces per period."""
    s = np.asarray(s, float)
    out = np.zeros_like(s)
    for k in range(level + 1):
        q = (2.0 ** k) * s
        out += np.abs(q - np.round(q)) / 2.0 ** k
    return out


def gibbs_square(phase, n_odd):
    """A square wave's Fourier series to its n_odd-th odd harmonic, (4 / pi) sum sin(2 pi k phase) / k, k = 1, 3,
    ..., 2 n_odd - 1: the Gibbs overshoot of about 9 % of the jump at every edge (Gibbs, Nature 59 (1899) 606)."""
    phase = np.asarray(phase, float)
    return 4 / np.pi * sum(np.sin(2 * np.pi * k * phase) / k for k in range(1, 2 * n_odd, 2))


def fitts_history(targets, overshoots, start=0.0):
    """The turning points of a teleoperator's point-to-point moves: each aimed move overshoots its target by a
    fraction of its distance, then a corrective sub-movement lands on it (Meyer et al.'s optimised sub-movements,
    Psych. Rev. 95 (1988) 340; the moves' durations follow Fitts, J. Exp. Psych. 47 (1954) 381, MT = a + b log2(2 D
    / W), which does not matter to a rate-independent core)."""
    pts, cur = [start], start
    for tg, os_ in zip(targets, overshoots):
        pts.append(tg + os_ * (tg - cur))
        pts.append(tg)
        cur = tg
    return np.array(pts)


def iso376_history(top, n_steps, preloads, d0):
    """The turning points of a force-proving instrument's calibration (ISO 376: `preloads` preloadings from 0 to
    the top, a series of n_steps rising loads to the top and the same falling back to 0, which is where the
    instrument's reversibility is read), then a set point d0 approached from below: 0, top, 0, ..., top, 0, d0."""
    pts = [0.0]
    for _ in range(preloads):
        pts += [top, 0.0]
    pts += [top, 0.0, d0]                              # the stepped series, its rises and falls monotone
    return np.array(pts), top * np.arange(1, n_steps + 1) / n_steps


def mathieu_rhs(t, s, zeta, eps):
    """A parametrically pumped swing: x'' + 2 zeta x' + (1 + eps cos 2 t) x = 0 in units of its natural frequency
    (Mathieu, J. Math. Pures Appl. 13 (1868) 137; the principal resonance, growing as exp((eps / 4 - zeta) t) for
    small eps and zeta: Landau & Lifshitz, *Mechanics*, sec. 27)."""
    x, u = s
    return [u, -2 * zeta * u - (1 + eps * math.cos(2 * t)) * x]


def mathieu_swing(t, units, zeta, eps, push):
    """The pumped swing's x from rest at 0 with a speed `push`, at the times t (s), `units` time units a second
    (DOP853, rtol 1e-11)."""
    tau = np.asarray(t, float) * units
    sol = solve_ivp(mathieu_rhs, (tau[0], tau[-1]), [0.0, push], t_eval=tau, args=(zeta, eps), method="DOP853",
                    rtol=1e-11, atol=1e-14)
    return sol.y[0]


def speed_schedule(t, lead, levels, ramp, holds):
    """A wind tunnel's fan set points: from 0 after `lead` s, a raised-cosine ramp of `ramp` s to each level, each
    held holds[i] s."""
    t = np.asarray(t, float)
    v = np.zeros_like(t)
    prev, tc = 0.0, lead
    for lv, hd in zip(levels, holds):
        v = np.where(t >= tc, prev + (lv - prev) * raised_cosine((t - tc) / ramp), v)
        prev, tc = lv, tc + ramp + hd
    return v, tc


# ---- creep: Terzaghi's consolidation of a saturated pad ----

def terzaghi_terms(T_v, dt, n_max=400, fast=60.0):
    """The degree of consolidation U(T) = 1 - sum_m (2 / M^2) exp(-M^2 T), M = pi (2 m + 1) / 2, T = t / T_v
    (Terzaghi, *Erdbaumechanik*, 1925; Terzaghi, *Theoretical Soil Mechanics*, 1943, ch. 13: a layer drained on one
    face, T_v = H^2 / c_v): the weights 2 / M^2 and rates M^2 / T_v of the terms slow enough to follow (rate x dt <
    `fast`); the others, settled within a sample, are lumped into the weight of the instantaneous part."""
    M = np.pi * (2 * np.arange(n_max) + 1) / 2
    lam = M * M / T_v
    keep = lam * dt < fast
    b = 2 / (M * M)
    return b[keep], lam[keep], 1.0 - b[keep].sum()


def terzaghi_creep(h, dt, c, T_v):
    """The consolidation of a water-saturated pad under the load h (the core's output): the settlement follows each
    load change by U, c x the change in the end (Boltzmann's superposition of Terzaghi's U). Each term w_m' = lam_m
    (h - w_m) is integrated exactly for h linear between samples; the settlement is c (b_rest h + sum b_m w_m), c U
    convolved with dh (from rest at h[0] settled)."""
    h = np.asarray(h, float)
    b, lam, b_rest = terzaghi_terms(T_v, dt)
    e = np.exp(-lam * dt)
    g = (1 - e) / (lam * dt)                           # for h linear: w1 = h1 - (h1 - h0) g + (w0 - h0) e
    w = np.full(len(lam), h[0])
    out = np.empty(len(h))
    out[0] = b @ w + b_rest * h[0]
    for k in range(1, len(h)):
        h0, h1 = h[k - 1], h[k]
        w = h1 - (h1 - h0) * g + (w - h0) * e
        out[k] = b @ w + b_rest * h1
    return c * out


# ---- rate dependence: a stage shearing a layer of viscous oil ----

def oil_film_matrices(f_n, zeta_s, m_ratio, f_film, n_modes=60):
    """A stage (mass 1, natural frequency f_n, structural damping zeta_s) pulled by its spring toward the core's
    output h and gliding on a layer of oil (its mass m_ratio; its first shear mode relaxing at a_1 = nu pi^2 / d^2 =
    2 pi f_film). The oil obeys the diffusion of momentum u_t = nu u_yy, u = x' at the stage and 0 at the floor
    (Stokes, Trans. Camb. Phil. Soc. 9 (1851) 8; Couette flow at low frequencies, Stokes's oscillating layer at high
    ones): its shear force is c0 (q d) coth(q d) x', q d = pi sqrt(s / a_1), c0 = mu A / d = m_ratio a_1 / pi^2. The
    partial fractions c0 + sum_n 2 c0 s / (s + n^2 a_1) give n_modes Maxwell elements (g_n' = -a_n g_n - a_n 2 c0
    x'), the rest lumped as the added mass sum_{n > N} 2 c0 / a_n. States (x, x', g_1 ... g_N), input h, output x."""
    w_n = 2 * np.pi * f_n
    a1 = 2 * np.pi * f_film
    c0 = m_ratio * a1 / np.pi ** 2
    n = np.arange(1, n_modes + 1)
    an = a1 * n * n
    m_rest = 2 * c0 / a1 * (np.pi ** 2 / 6 - np.sum(1.0 / (n * n)))
    m = 1.0 + m_rest
    k = w_n * w_n
    N = n_modes
    A = np.zeros((N + 2, N + 2))
    B = np.zeros((N + 2, 1))
    A[0, 1] = 1.0
    A[1, 0] = -k / m
    A[1, 1] = -(2 * zeta_s * w_n + c0 + 2 * c0 * N) / m
    A[1, 2:] = -1.0 / m
    B[1, 0] = k / m
    A[2:, 1] = -an * 2 * c0
    A[2:, 2:] = np.diag(-an)
    C = np.zeros((1, N + 2))
    C[0, 0] = 1.0
    return A, B, C


def film_impedance(s, f_n, zeta_s, m_ratio, f_film):
    """The stage's closed-form response x / h = k / (s^2 + 2 zeta_s w_n s + k + s c0 (q d) coth(q d)) (mass 1)."""
    w_n = 2 * np.pi * f_n
    a1 = 2 * np.pi * f_film
    c0 = m_ratio * a1 / np.pi ** 2
    qd = np.pi * np.sqrt(s / a1)
    return w_n ** 2 / (s * s + 2 * zeta_s * w_n * s + w_n ** 2 + s * c0 * qd / np.tanh(qd))


def foh_response(A, B, C, u, dt, x0=None):
    """The exact response of x' = A x + B u, y = C x to u linear between samples (first-order hold), from rest at
    u[0] unless x0 is given: x1 = Phi x0 + G0 u0 + G1 (u1 - u0), the blocks of expm([[A dt, B dt, 0], [0, 0, 1],
    [0, 0, 0]]) (Van Loan, IEEE TAC 23 (1978) 395)."""
    n = A.shape[0]
    M = np.zeros((n + 2, n + 2))
    M[:n, :n] = A * dt
    M[:n, n] = B[:, 0] * dt
    M[n, n + 1] = 1.0
    E = expm(M)
    Phi, G0, G1 = E[:n, :n], E[:n, n], E[:n, n + 1]
    u = np.asarray(u, float)
    x = np.linalg.solve(A, -B[:, 0] * u[0]) if x0 is None else np.array(x0, float)
    out = np.empty(len(u))
    c = C[0]
    out[0] = c @ x
    for k in range(1, len(u)):
        x = Phi @ x + G0 * u[k - 1] + G1 * (u[k] - u[k - 1])
        out[k] = c @ x
    return out


# ---- gain drift: a piezo stack heated by its displacement current ----

def esr_heating(p, dt, tau):
    """The temperature rise theta' = (p - theta) / tau of a stack whose loss p (in kelvin at equilibrium: R_th R_s
    C^2 v'^2, the displacement current C v' through its equivalent series resistance; e.g. Uchino & Hirose, IEEE
    UFFC 48 (2001) 307 on heat generation in piezo actuators) is linear between samples: exact per sample."""
    p = np.asarray(p, float)
    e = math.exp(-dt / tau)
    th = np.empty(len(p))
    th[0] = 0.0
    for k in range(1, len(p)):
        s = (p[k] - p[k - 1]) / dt
        th[k] = p[k] - s * tau + (th[k - 1] - p[k - 1] + s * tau) * e
    return th


# ---- asymmetry: a laser triangulation sensor ----

def triangulation_reading(x, D):
    """A laser along the axis of motion hits the target at distance D + x; a pinhole camera beside the laser (its
    axis parallel, a base b off, the sensor f behind) images the spot at p = f b / (D + x) (similar triangles; e.g.
    Blais, J. Electron. Imaging 13 (2004) 231). The reading, calibrated to the slope at rest: (p0 - p) D^2 / (f b) =
    D x / (D + x); far targets compress, near ones stretch."""
    x = np.asarray(x, float)
    return D * x / (D + x)


# ---- saturation: an inclinometer on a tilt stage ----

def inclinometer_reading(x, L):
    """The stage's output x tilts a platform by x / L rad; an inclinometer (a MEMS accelerometer along the platform)
    reads g sin(x / L), scaled to the slope at rest: L sin(x / L). Odd, compressing both ends."""
    return L * np.sin(np.asarray(x, float) / L)


# ---- delay: ultrasonic time of flight ----

def speed_of_sound(T_c):
    """The speed of sound in dry air, 331.3 sqrt(1 + T / 273.15) m/s (the ideal gas, gamma R T / M)."""
    return 331.3 * math.sqrt(1 + T_c / 273.15)


def ultrasonic_readings(t, tf, xf, D0, metres, c, latency):
    """An ultrasonic range finder pinging at every sample t_k: the ping meets the target (the core's output xf on
    the fine grid tf, `metres` per output unit, D0 away at rest) at t_r with c (t_r - t_k) = D0 + metres x(t_r), the
    echo returns after the same distance, and the reading c (t_a - t_k) / 2 = D0 + metres x(t_r), that is x(t_r), is
    delivered `latency` samples after the ping (x linear between the fine points; the fixed point iterated from
    D0 / c, contracting by metres x' / c < 1e-4). Returns the readings and their delays in samples."""
    dt = t[1] - t[0]
    tp = np.asarray(t, float) - latency * dt           # the ping of the reading delivered at t
    tr = tp + D0 / c
    for _ in range(8):
        tr = tp + (D0 + metres * np.interp(tr, tf, xf)) / c
    y = np.interp(tr, tf, xf)
    y = np.where(tp < 0, xf[0], y)
    return y, (np.asarray(t) - tr) / dt


# ---- delay: a magnetostrictive waveguide sensor read asynchronously ----

def magnetostrictive_readings(t, tf, xf, L0, metres, c_w, f_u, phase, proc):
    """A magnetostrictive position sensor (Wiedemann effect: a current pulse launches a torsional wave at the
    magnet riding on the stage, which reaches the head after (L0 + metres x) / c_w; e.g. Seco et al., Sensors 9
    (2009) 3678), interrogated at its own rate f_u (times phase / f_u + j / f_u); the logger at t takes the newest
    reading ready (launch + flight + `proc`) by then: the position at the launch. Returns the readings and their
    delays in samples."""
    t = np.asarray(t, float)
    dt = t[1] - t[0]
    j = np.arange(int((t[-1] + 1.0) * f_u) + 2)
    tl = (phase + j) / f_u                             # launches from t = phase / f_u on
    xl = np.interp(tl, tf, xf)
    ready = tl + (L0 + metres * xl) / c_w + proc
    assert np.all(np.diff(ready) > 0)
    idx = np.searchsorted(ready, t, side="right") - 1
    ok = idx >= 0
    y = np.where(ok, xl[np.maximum(idx, 0)], xf[0])
    delay = np.where(ok, (t - tl[np.maximum(idx, 0)]) / dt, 0.0)
    return y, delay


# ---- out of vocabulary: a galloping prism in a wind tunnel ----

def galloping_rhs(t, s, w, zeta, beta, A1, A3, U_of_t, buffet):
    """The cross-wind tip y of a prism on a cantilever in a wind of speed U: y'' + 2 zeta w y' + w^2 y = beta U^2
    C(y' / U) + buffet(t) U^2, C(a) = A1 a - A3 a^3, Parkinson & Smith's quasi-steady galloping (Q. J. Mech. Appl.
    Math. 17 (1964) 225; Den Hartog's criterion for the onset: beta U A1 > 2 zeta w)."""
    y, u = s
    U = U_of_t(t)
    lift = beta * (A1 * U * u - A3 * u ** 3 / max(U, 1e-9))
    return [u, -2 * zeta * w * u - w * w * y + lift + buffet(t) * U * U]


def galloping_amplitude(U, w, zeta, beta, A1, A3):
    """The averaged limit cycle (Krylov-Bogoliubov): a^2 = 4 c1 / (3 c3 w^2), c1 = beta A1 U - 2 zeta w, c3 = beta
    A3 / U, when c1 > 0 (0 otherwise)."""
    c1 = beta * A1 * U - 2 * zeta * w
    return math.sqrt(max(c1, 0.0) * 4 / (3 * beta * A3 / U * w * w))


def fan_speed(v, dt, tau, U_max, v_max=100.0):
    """The wind speed of a fan whose rotor follows its voltage through a first-order lag tau (its inertia against
    the drag torque, linearised): U' = (U_max v / v_max - U) / tau, exact per sample for v linear between samples."""
    e = math.exp(-dt / tau)
    u = np.asarray(v, float) * U_max / v_max
    out = np.empty(len(u))
    out[0] = u[0]
    for k in range(1, len(u)):
        s = (u[k] - u[k - 1]) / dt
        out[k] = u[k] - s * tau + (out[k - 1] - u[k - 1] + s * tau) * e
    return out

"""Mechanisms and signals of the HOLDOUT18 set (``cases_holdout18.py``), each written from its law.

Nothing here imports hystcomp (nor the other sets' mechanisms). Every mechanism takes the (clean) drive, or the
core's output, and returns the response; all are causal. The sources of the laws are beside each function and in
``cases_holdout18``'s docstring.

Citations: every source below was written from memory in this session (none was re-read): the papers' volumes,
pages and years, the books' chapters, the golden car's constants (Sayers), the ISO 8608 and IEC 61400-1 clauses and
the DTMF and call-progress frequencies may be off. The laws themselves do not rest on them: each is checked in
tests/test_realistic_holdout18.py against an independent solution (the two-level creep, the tuned-mass stage, the
quarter car and the self-heated thermistor against solve_ivp, the beam under a carriage against the unit-load method by
quadrature, Den Hartog's fixed points, the inverse maps against brentq on their forward laws, the swept-laser
interrogator against brentq and a finer simulation, the magnetoelastic beam against a Runge-Kutta solution and its
energy balance, Lotka-Volterra against its invariant, the billiard against the reflection law at every bounce, and so
on).
"""

import math

import numpy as np
from scipy.integrate import solve_ivp
from scipy.signal import cont2discrete, dlsim, lfilter

# ---- rate-independent cores ----


def plays(v, r, w, w0, state=0.0, return_state=False):
    """y = w0 v + sum_i w_i z_i, z_i the play (backlash) of threshold r_i >= 0, z_i(t) = min(max(z_i(t-), v(t) -
    r_i), v(t) + r_i) (Krasnosel'skii & Pokrovskii, *Systems with Hysteresis*, 1989; Visintin, *Differential Models
    of Hysteresis*, 1994, ch. 3), from the given state (a number or one per play; 0: virgin)."""
    v = np.asarray(v, float)
    r = np.asarray(r, float)
    w = np.asarray(w, float)
    z = np.zeros(r.shape) + np.asarray(state, float)
    s = np.empty(len(v))
    for k, x in enumerate(v.tolist()):
        z = np.minimum(np.maximum(z, x - r), x + r)
        s[k] = w @ z
    y = w0 * v + s
    return (y, z) if return_state else y


def grid(n, r_max):
    """n thresholds at the midpoints of n equal cells of (0, r_max)."""
    return (np.arange(n) + 0.5) * (r_max / n)


def wald_plays(n, r_max, mean, shape, w0):
    """Thresholds on :func:`grid` weighted by the inverse Gaussian (Wald) density sqrt(lam / (2 pi r^3)) exp(-lam (r -
    mu)^2 / (2 mu^2 r)) of mean mu and shape lam, summing to 1 - w0: the first-passage distance of a drifting random
    walk (Schroedinger, Phys. Z. 16 (1915) 289; Tweedie, Ann. Math. Stat. 28 (1957) 362), a wall segment depinning
    where the random pinning force it has crossed first exceeds its drive; a hump with a heavy right tail."""
    r = grid(n, r_max)
    dens = np.sqrt(shape / (2 * np.pi * r ** 3)) * np.exp(-shape * (r - mean) ** 2 / (2 * mean ** 2 * r))
    return r, (1 - w0) * dens / dens.sum()


def exp_plays(n, r_max, scale, w0):
    """Thresholds on :func:`grid` weighted by exp(-r / scale), summing to 1 - w0."""
    r = grid(n, r_max)
    dens = np.exp(-r / scale)
    return r, (1 - w0) * dens / dens.sum()


# ---- signals ----

def raised_cosine(x):
    """0 for x <= 0, (1 - cos(pi x)) / 2 between, 1 for x >= 1."""
    return 0.5 - 0.5 * np.cos(np.pi * np.clip(np.asarray(x, float), 0.0, 1.0))


def duffing_rhs(t, s, delta, gamma, omega):
    """The magnetoelastic beam of Moon & Holmes (J. Sound Vib. 65 (1979) 275): a steel cantilever buckled by two
    magnets into two wells, forced sideways, in Holmes's normal form x'' + delta x' - x + x^3 = gamma cos(omega t)
    (Phil. Trans. R. Soc. A 292 (1979) 419; Guckenheimer & Holmes, *Nonlinear Oscillations*, 1983, sec. 2.2)."""
    x, u = s
    return [u, -delta * u + x - x ** 3 + gamma * math.cos(omega * t)]


def duffing_energy(x, u):
    """The beam's energy u^2 / 2 - x^2 / 2 + x^4 / 4 (its rate is gamma cos(omega t) u - delta u^2)."""
    return 0.5 * u * u - 0.5 * x * x + 0.25 * x ** 4


def magnetoelastic_beam(t, f_force, delta, gamma, start, settle=60.0):
    """The beam's tip x(t) at the times t (s), the forcing at f_force Hz (omega = 1 in the normal form, so one time
    unit is 1 / (2 pi f_force) s), from the state start after settle time units; DOP853 at rtol 1e-10. Returns x,
    x' (per time unit) and the time units of t."""
    tau = settle + 2 * np.pi * f_force * np.asarray(t, float)
    sol = solve_ivp(duffing_rhs, (0.0, tau[-1]), list(start), args=(delta, gamma, 1.0), method="DOP853", rtol=1e-10,
                    atol=1e-12, dense_output=True)
    x, u = sol.sol(tau)
    return x, u, tau


#: the International Morse code (ITU-R M.1677) of the letters
MORSE = {"A": ".-", "B": "-...", "C": "-.-.", "D": "-..", "E": ".", "F": "..-.", "G": "--.", "H": "....", "I": "..",
         "J": ".---", "K": "-.-", "L": ".-..", "M": "--", "N": "-.", "O": "---", "P": ".--.", "Q": "--.-", "R": ".-.",
         "S": "...", "T": "-", "U": "..-", "V": "...-", "W": ".--", "X": "-..-", "Y": "-.--", "Z": "--.."}


def morse_marks(words):
    """The marks (key down) of a message in Morse timing (ITU-R M.1677): a dot 1 unit, a dash 3, 1 unit between the
    elements of a letter, 3 between letters, 7 between words. Returns (start, length) in units and the index of each
    mark's letter, and the message's length in units."""
    marks, letters, pos, li = [], [], 0, 0
    for wi, word in enumerate(words):
        if wi:
            pos += 7
        for ci, ch in enumerate(word):
            if ci:
                pos += 3
            for ei, el in enumerate(MORSE[ch]):
                if ei:
                    pos += 1
                n = 1 if el == "." else 3
                marks.append((pos, n))
                letters.append(li)
                pos += n
            li += 1
    return np.array(marks, float), np.array(letters), pos


def keyed_levels(t, starts, ends, levels, edge_s):
    """Marks keyed from 0 V to levels[i] over [starts[i], ends[i]), each edge a raised cosine of edge_s beginning at
    the mark's start or end (a shaped keying envelope, which keeps the key clicks out)."""
    t = np.asarray(t, float)
    out = np.zeros_like(t)
    for a, b, lv in zip(starts, ends, levels):
        i, j = np.searchsorted(t, [a, b + edge_s])
        tt = t[i:j]
        out[i:j] += lv * (raised_cosine((tt - a) / edge_s) - raised_cosine((tt - b) / edge_s))
    return out


#: the DTMF keypad's frequencies (Hz): rows and columns (ITU-T Q.23), and the call-progress tones of the North
#: American precise tone plan (dial 350 + 440 Hz, ring-back 440 + 480 Hz)
DTMF_ROWS = (697.0, 770.0, 852.0, 941.0)
DTMF_COLS = (1209.0, 1336.0, 1477.0)
DIAL_TONE = (350.0, 440.0)
RINGBACK = (440.0, 480.0)
KEYPAD = "123456789*0#"


def dtmf_pair(key):
    """The two frequencies (row, column) of a key of :data:`KEYPAD`."""
    i = KEYPAD.index(key)
    return DTMF_ROWS[i // 3], DTMF_COLS[i % 3]


def tone_bursts(t, bursts, ramp_s):
    """Two-tone bursts (f1, f2, t_on, t_off): (sin 2 pi f1 (t - t_on) + sin 2 pi f2 (t - t_on)) / 2 under a
    raised-cosine envelope rising over ramp_s from t_on and falling over ramp_s to t_off."""
    t = np.asarray(t, float)
    out = np.zeros_like(t)
    for f1, f2, a, b in bursts:
        i, j = np.searchsorted(t, [a, b])
        s = t[i:j] - a
        env = raised_cosine(s / ramp_s) * raised_cosine((b - t[i:j]) / ramp_s)
        out[i:j] += env * 0.5 * (np.sin(2 * np.pi * f1 * s) + np.sin(2 * np.pi * f2 * s))
    return out


def cantor(s, level):
    """The Cantor function (the devil's staircase; Cantor 1884) of a finite construction level: for s in the middle
    third 1/2, in the outer thirds C(3 s) / 2 and 1/2 + C(3 s - 2) / 2, and s itself at level 0 (so each of the 2^level
    rises is linear, 3^-level wide). Monotone from C(0) = 0 to C(1) = 1, flat over the removed middle thirds."""
    s = np.clip(np.asarray(s, float), 0.0, 1.0)
    out = np.zeros_like(s)
    weight = 1.0
    live = np.ones(s.shape, bool)
    for _ in range(level):
        lo, hi = s < 1 / 3, s > 2 / 3
        mid = live & ~lo & ~hi
        out[mid] += weight / 2
        live &= ~mid
        up = live & hi
        out[up] += weight / 2
        s = np.where(lo, 3 * s, np.where(hi, 3 * s - 2, 0.0))
        weight /= 2
    return out + np.where(live, weight * s, 0.0)


def cantor_passes(dt, tops, levels, pass_s, lead_s):
    """From lead_s at 0 V, passes up the devil's staircase to tops[i] and back down it to 0 V (top C_level(s), s
    running at a uniform rate over pass_s[i] each way: the steps steep, the flats self-similar, the longest a third
    of the pass). Returns the path and the first sample of each pass."""
    out, starts = [np.zeros(int(round(lead_s / dt)))], []
    pos = len(out[0])
    for top, lv, T in zip(tops, levels, pass_s):
        m = int(round(T / dt))
        s = np.arange(1, m + 1) / m
        up = top * cantor(s, lv)
        out += [up, up[::-1][1:], [0.0]]
        starts.append(pos)
        pos += 2 * m
    return np.concatenate(out), np.array(starts)


def logistic_orbit(x0, rho, n):
    """n iterates x_{k+1} = rho x_k (1 - x_k) of the logistic map from x0 (May, Nature 261 (1976) 459; at rho = 4
    Ulam & von Neumann's pseudo-random generator, its iterates spread with the arcsine density)."""
    out = np.empty(n)
    x = x0
    for k in range(n):
        out[k] = x
        x = rho * x * (1 - x)
    return out


def set_point_moves(dt, points, holds, speed, t_min, lead_s):
    """From lead_s at rest at 0 V, raised-cosine moves to each point in turn (t_min + |step| / speed each), each
    followed by its hold. Returns the path and the first sample of each hold."""
    out, starts, cur = [np.zeros(int(round(lead_s / dt)))], [], 0.0
    pos = len(out[0])
    for p, h in zip(points, holds):
        m = max(int(round((t_min + abs(p - cur) / speed) / dt)), 1)
        nh = int(round(h / dt))
        out.append(cur + (p - cur) * raised_cosine(np.arange(1, m + 1) / m))
        out.append(np.full(nh, p))
        starts.append(pos + m)
        pos += m + nh
        cur = p
    m = max(int(round((t_min + abs(cur) / speed) / dt)), 1)
    out.append(cur - cur * raised_cosine(np.arange(1, m + 1) / m))
    out.append(np.zeros(int(round(lead_s / dt))))
    return np.concatenate(out), np.array(starts)


#: Sayers's golden car (the quarter car of the International Roughness Index, World Bank Technical Paper 46, 1986):
#: per unit sprung mass the tyre stiffness k1 and the suspension's k2 (s^-2), c (s^-1), and the mass ratio mu
GOLDEN_CAR = {"k1": 653.0, "k2": 63.3, "c": 6.0, "mu": 0.15}


def quarter_car_matrices(k1, k2, c, mu):
    """The quarter car's state space: states (z_s, z_s', z_u, z_u'), input the road's height z_r under the tyre (a
    spring, no damping), output the suspension's travel z_s - z_u: z_s'' = -k2 (z_s - z_u) - c (z_s' - z_u'), mu
    z_u'' = k2 (z_s - z_u) + c (z_s' - z_u') - k1 (z_u - z_r)."""
    A = np.array([[0.0, 1.0, 0.0, 0.0], [-k2, -c, k2, c], [0.0, 0.0, 0.0, 1.0],
                  [k2 / mu, c / mu, -(k1 + k2) / mu, -c / mu]])
    B = np.array([[0.0], [0.0], [0.0], [k1 / mu]])
    C = np.array([[1.0, 0.0, -1.0, 0.0]])
    return A, B, C


def foh_filter(A, B, C, x, h):
    """The output of the linear system (A, B, C) from rest for an input linear between the points of x, spaced h:
    exact (the first-order-hold discretisation, a matrix exponential, run as a state-space recursion)."""
    return dlsim(cont2discrete((A, B, C, np.zeros((1, 1))), h, method="foh"), np.asarray(x, float))[1][:, 0]


def iso8608_road(X, n_waves, rng, n_lo=0.011, n_hi=2.83, n0=0.1):
    """A road profile of ISO 8608's displacement spectrum G(n) = G(n0) (n / n0)^-2 (n the spatial frequency in
    cycles per metre, n0 = 0.1; here G(n0) = 1, the class only scales it) as a sum of n_waves cosines at spatial
    frequencies log-spaced over n_lo ... n_hi, each of amplitude sqrt(2 G(n) dn) and a random phase (the harmonic
    superposition of ISO 8608 annex; Agostinacchio, Ciampa & Olita, Eur. Transp. Res. Rev. 6 (2014) 267), at the
    distances X (m). Returns the heights, the frequencies and the amplitudes."""
    edges = np.geomspace(n_lo, n_hi, n_waves + 1)
    n = np.sqrt(edges[1:] * edges[:-1])
    amps = np.sqrt(2 * (n / n0) ** -2 * np.diff(edges))
    ph = rng.uniform(0, 2 * np.pi, n_waves)
    X = np.asarray(X, float)
    return np.cos(2 * np.pi * np.outer(X, n) + ph) @ amps, n, amps


def manchester_levels(bits, amps):
    """The half-bit levels of bits in Manchester code (IEEE 802.3: a 0 high then low, a 1 low then high), bit k at
    the amplitude amps[k]."""
    bits = np.asarray(bits)
    first = np.where(bits == 0, 1.0, -1.0) * np.asarray(amps, float)
    return np.ravel(np.c_[first, -first])


def level_path(t, t0, half_s, levels, edge_s):
    """From 0 V, the levels held for half_s each from t0 on and back to 0 V after the last, every change a raised
    cosine of edge_s centred on its boundary (edge_s < half_s: the edges never overlap)."""
    t = np.asarray(t, float)
    lv = np.r_[0.0, levels, 0.0]
    out = np.zeros_like(t)
    for j, step in enumerate(np.diff(lv)):
        if step == 0.0:
            continue
        tb = t0 + j * half_s
        i = np.searchsorted(t, tb - edge_s / 2)
        out[i:] += step * raised_cosine((t[i:] - tb) / edge_s + 0.5)
    return out


def lotka_volterra(t, g, x0, y0, switches):
    """Prey x and predators y of Lotka-Volterra (Lotka, *Elements of Physical Biology*, 1925; Volterra, Nature 118
    (1926) 558) in units of their equilibrium, x' = x (1 - y), y' = g y (x - 1) (t in time units), which keeps H = g
    (x - ln x) + (y - ln y) (each orbit a closed cycle, the prey's peaks sharp and its troughs long); at each time of
    switches (t_k, H_k) the predators are set, at the same prey, onto the orbit H_k (a culling or a restocking; the
    prey's path stays continuous). DOP853 at rtol 1e-11 between switches. Returns x and y at the times t."""
    t = np.asarray(t, float)
    x, y = np.empty_like(t), np.empty_like(t)
    s, ta = [x0, y0], 0.0
    for tb, H in list(switches) + [(t[-1] + 1e-9, None)]:
        sol = solve_ivp(lambda _, q: [q[0] * (1 - q[1]), g * q[1] * (q[0] - 1)], (ta, tb), s, method="DOP853",
                        rtol=1e-11, atol=1e-13, dense_output=True)
        sel = (t >= ta) & (t < tb)
        x[sel], y[sel] = sol.sol(t[sel])
        xe = sol.y[0, -1]
        if H is not None:
            s = [xe, lv_predators(xe, H, g, sol.y[1, -1] < 1)]
        ta = tb
    return x, y


def lv_invariant(x, y, g):
    """The Lotka-Volterra invariant g (x - ln x) + (y - ln y)."""
    return g * (x - np.log(x)) + (y - np.log(y))


def lv_predators(x, H, g, low):
    """The predators y on the orbit H at the prey x: the root of y - ln y = H - g (x - ln x) below 1 (low) or above,
    by bisection on the monotone branch."""
    c = H - g * (x - math.log(x))
    lo, hi = (1e-300, 1.0) if low else (1.0, c + 2.0)
    for _ in range(200):
        m = 0.5 * (lo + hi)
        f = m - math.log(m) - c
        if (f > 0) == low:
            lo = m
        else:
            hi = m
    return 0.5 * (lo + hi)


def lv_peak_orbit(peak, g):
    """The invariant H of the orbit whose prey peaks at `peak` (there y = 1)."""
    return g * (peak - math.log(peak)) + 1.0


def stadium_hit(p, d, a, R):
    """The first wall of Bunimovich's stadium (straight sides y = +-R for |x| <= a, semicircular caps of radius R
    about (+-a, 0); Bunimovich, Commun. Math. Phys. 65 (1979) 295) met by the ray p + s d (|d| = 1) for s > 0: the
    distance s and the wall's unit normal there."""
    best, nrm = math.inf, None
    for side in (1.0, -1.0):
        if d[1] * side > 1e-15:                        # a straight side
            s = (side * R - p[1]) / d[1]
            if 1e-12 < s < best and abs(p[0] + s * d[0]) <= a + 1e-9:
                best, nrm = s, np.array([0.0, side])
        c = np.array([side * a, 0.0])                  # a cap: |p + s d - c| = R, the far root from inside
        q = p - c
        bq = q @ d
        disc = bq * bq - (q @ q - R * R)
        if disc > 0:
            s = -bq + math.sqrt(disc)
            h = p + s * d
            if 1e-12 < s < best and side * (h[0] - c[0]) >= -1e-9:
                best, nrm = s, (h - c) / math.hypot(*(h - c))
    return best, nrm


def stadium_billiard(t, a, R, speed, p0, angle):
    """A ball rolling at a constant speed in the stadium, reflected specularly (d - 2 (d . n) n) at every wall, from
    p0 in the direction angle: a chaotic billiard (its x reverses only on the caps). Returns x and y at the times t
    (exact: straight lines between the bounces) and the bounce times."""
    t = np.asarray(t, float)
    p, d = np.array(p0, float), np.array([math.cos(angle), math.sin(angle)])
    knots_t, knots_p, tc = [0.0], [p.copy()], 0.0
    while tc < t[-1]:
        s, nrm = stadium_hit(p, d, a, R)
        p = p + s * d
        d = d - 2 * (d @ nrm) * nrm
        d /= math.hypot(*d)
        tc += s / speed
        knots_t.append(tc)
        knots_p.append(p.copy())
    kt, kp = np.array(knots_t), np.array(knots_p)
    return np.interp(t, kt, kp[:, 0]), np.interp(t, kt, kp[:, 1]), kt[1:]


def eog_gust(t, t0, T, v_gust):
    """The extreme operating gust of IEC 61400-1 (sec. 6.3.2.2): -0.37 v_gust sin(3 pi s / T) (1 - cos(2 pi s / T))
    for s = t - t0 in [0, T], 0 outside: a dip, a rise to 0.74 v_gust at T / 2 and a dip."""
    s = np.asarray(t, float) - t0
    on = (s >= 0) & (s <= T)
    return np.where(on, -0.37 * v_gust * np.sin(3 * np.pi * s / T) * (1 - np.cos(2 * np.pi * s / T)), 0.0)


def generator_emf(t, wind, tau_r, poles, k_e):
    """A small permanent-magnet wind generator's open-circuit EMF k_e w sin(p theta) (Faraday; the EMF in proportion
    to the speed, its electrical frequency p w / 2 pi), the rotor's speed w following the wind's w_target(t) (rad/s
    of the rotor at the optimal tip-speed ratio) through the rotor's inertia, tau_r w' = w_target - w (exact for
    w_target linear between samples), theta the integral of w (trapezoid rule). From rest. Returns the EMF, w and
    theta."""
    t = np.asarray(t, float)
    dt = t[1] - t[0]
    a = math.exp(-dt / tau_r)
    g = -math.expm1(-dt / tau_r) * tau_r / dt
    w = lfilter([1 - g, g - a], [1.0, -a], np.asarray(wind, float) - wind[0]) + wind[0]
    theta = np.r_[0.0, np.cumsum(0.5 * (w[1:] + w[:-1]) * dt)]
    return k_e * w * np.sin(poles * theta), w, theta


# ---- mechanisms ----

def two_level_creep(h, dt, c, tau0, h_s):
    """Creep of units hopping between two sites biased by the load (Nowick & Berry, *Anelastic Relaxation in
    Crystalline Solids*, 1972, ch. 3 and 8: the rates nu exp(+-h / h_s) up and down the bias): their strain e =
    c h_s m, m the difference of the sites' populations, obeys e' = (c h_s tanh(h / h_s) - e) cosh(h / h_s) / tau0
    (tau0 = 1 / 2 nu): c h for small loads relaxing in tau0, but under large loads toward less (the equilibrium
    saturates as tanh) and faster (cosh). Per sample the exact exponential with h at the step's midpoint (second
    order), at rest (0) at the first sample. Returns the creep."""
    h = np.asarray(h, float)
    hm = 0.5 * (h[1:] + h[:-1]) / h_s
    e_inf = c * h_s * np.tanh(hm)
    a = np.exp(-dt * np.cosh(hm) / tau0)
    out = np.zeros_like(h)
    e = 0.0
    for k in range(1, len(h)):
        e = e_inf[k - 1] + (e - e_inf[k - 1]) * a[k - 1]
        out[k] = e
    return out


def tmd_matrices(f1, zeta1, mu, f2, zeta2):
    """A stage (mass m1 on its flexure, f1, zeta1) loaded by the core's free stroke h through the flexure (at rest the
    stage sits at h) and carrying a tuned mass damper (mass mu m1 on a spring and dashpot, f2, zeta2; Den Hartog,
    *Mechanical Vibrations*, 1956, sec. 3.3): x1'' = w1^2 (h - x1) - 2 zeta1 w1 x1' - mu (w2^2 (x1 - x2) + 2 zeta2 w2
    (x1' - x2')), x2'' = w2^2 (x1 - x2) + 2 zeta2 w2 (x1' - x2'). States (x1, x1', x2, x2'), output the stage x1."""
    w1, w2 = 2 * np.pi * f1, 2 * np.pi * f2
    k2, c2 = w2 * w2, 2 * zeta2 * w2
    A = np.array([[0.0, 1.0, 0.0, 0.0], [-w1 * w1 - mu * k2, -2 * zeta1 * w1 - mu * c2, mu * k2, mu * c2],
                  [0.0, 0.0, 0.0, 1.0], [k2, c2, -k2, -c2]])
    B = np.array([[0.0], [w1 * w1], [0.0], [0.0]])
    C = np.array([[1.0, 0.0, 0.0, 0.0]])
    return A, B, C


def den_hartog_tuning(mu):
    """Den Hartog's optimal absorber for a force on an undamped primary: f2 / f1 = 1 / (1 + mu), zeta2 = sqrt(3 mu /
    (8 (1 + mu)^3))."""
    return 1 / (1 + mu), math.sqrt(3 * mu / (8 * (1 + mu) ** 3))


def tmd_stage(h, dt, f1, zeta1, mu, f2, zeta2):
    """The stage x1 of :func:`tmd_matrices` for h linear between samples, at rest at h[0] (exact, first-order hold)."""
    h = np.asarray(h, float)
    return foh_filter(*tmd_matrices(f1, zeta1, mu, f2, zeta2), h - h[0], dt) + h[0]


def beam_influence(x, u, L=1.0):
    """The deflection at x of a simply supported beam of span L under a unit load at u, in units of L^3 / EI times
    L^-3 (Euler-Bernoulli; e.g. Timoshenko & Gere, *Mechanics of Materials*, 1972, app. G): for x <= u, (L - u) x (L^2
    - (L - u)^2 - x^2) / (6 L); for x >= u the same with x and u mirrored (Maxwell's reciprocity: the influence line
    of the deflection at x is the deflected shape under a load at x)."""
    x, u = np.broadcast_arrays(np.asarray(x, float), np.asarray(u, float))
    left = x <= u
    b = L - u
    d1 = b * x * (L * L - b * b - x * x) / (6 * L)
    xm, um = L - x, L - u
    bm = L - um
    d2 = bm * xm * (L * L - bm * bm - xm * xm) / (6 * L)
    return np.where(left, d1, d2)


def carriage_path(t, stations, move_starts, move_s):
    """A gantry's cross carriage at stations[0], moved by raised-cosine moves of move_s[i] starting at move_starts[i]
    to stations[i + 1] (its position along the bridge as a fraction of the span)."""
    t = np.asarray(t, float)
    xi = np.full_like(t, stations[0])
    for a, b, t0, T in zip(stations[:-1], stations[1:], move_starts, move_s):
        xi += (b - a) * raised_cosine((t - t0) / T)
    return xi


def slider_crank_angle(u, r, l):
    """The crank's angle psi (from the crank at right angles to the slider's line) of an in-line slider-crank (crank r,
    rod l) whose slider has moved u from that position: the slider sits at -r sin psi + sqrt(l^2 - r^2 cos^2 psi)
    (Norton, *Design of Machinery*, 2004, ch. 4), so sin psi = u (u + 2 c0) / (2 r (u + c0)) up to the sign,
    c0 = sqrt(l^2 - r^2): -asin of that. Monotone; the rod's obliquity makes it asymmetric (the angle per unit slide
    falls as the slider moves out)."""
    u = np.asarray(u, float)
    c0 = math.sqrt(l * l - r * r)
    return -np.arcsin(u * (u + 2 * c0) / (2 * r * (u + c0)))


def crank_reading(x, k, r, l, side):
    """The crank's angle read by an encoder, scaled to slope 1 at rest: the core's output x moves the slider by side k
    x (side +-1: which way the mechanism is built), read as -side (r / k) psi (psi' = -1 / r at rest)."""
    return -side * r / k * slider_crank_angle(side * k * np.asarray(x, float), r, l)


def invert_odd_stiffening(force, slope, target, u_max, iters=60):
    """The u in (-u_max, u_max) with force(u) = target for an odd, increasing force law convex for u > 0 (a
    stiffening spring): Newton's method on |target| from the right of the root (target / slope(0) bounds it from
    above; Newton from there converges monotonically on a convex function), the sign restored."""
    tgt = np.abs(np.asarray(target, float))
    u = np.minimum(tgt / slope(0.0), u_max * (1 - 1e-9))
    for _ in range(iters):
        u = np.maximum(u - (force(u) - tgt) / slope(u), 0.0)
    return np.sign(target) * u


def magnet_force(u, m):
    """The restoring force of a stage on a flexure between two fixed magnets repelling the magnet it carries (coaxial
    dipoles, the repulsion 3 mu0 m1 m2 / (2 pi s^4) at the distance s: e.g. Jackson, *Classical Electrodynamics*,
    1999, sec. 5.7; a passive magnetic spring: Yonnet, IEEE Trans. Magn. 17 (1981) 1169), u the displacement over the
    gap d: u + (m / 8) ((1 - u)^-4 - (1 + u)^-4), the magnets' stiffness m times the flexure's at rest."""
    u = np.asarray(u, float)
    return u + m / 8 * ((1 - u) ** -4.0 - (1 + u) ** -4.0)


def magnet_slope(u, m):
    """d/du of :func:`magnet_force`."""
    u = np.asarray(u, float)
    return 1 + m / 2 * ((1 - u) ** -5.0 + (1 + u) ** -5.0)


def magnet_stage(h, d, m):
    """The stage's displacement under the core's force (its free stroke h through the flexure, scaled to slope 1 at
    rest): u solves magnet_force(u) = (1 + m) h / d, the output d u."""
    u = invert_odd_stiffening(lambda x: magnet_force(x, m), lambda x: magnet_slope(x, m),
                              (1 + m) * np.asarray(h, float) / d, 1.0)
    return d * u


def neo_hookean(lam):
    """The nominal stress of an incompressible neo-Hookean rubber in uniaxial stretch lam, over its shear modulus:
    lam - lam^-2 (Treloar, Trans. Faraday Soc. 39 (1943) 241; *The Physics of Rubber Elasticity*, 1975, ch. 5)."""
    lam = np.asarray(lam, float)
    return lam - lam ** -2.0


def pads_force(xi, lam_p):
    """The restoring force of a stage between two rubber pads preloaded to the stretch lam_p < 1 (compressed), xi the
    displacement over a pad's thickness: neo_hookean(lam_p + xi) - neo_hookean(lam_p - xi) (odd, stiffening as a pad
    is squeezed)."""
    return neo_hookean(lam_p + np.asarray(xi, float)) - neo_hookean(lam_p - np.asarray(xi, float))


def pads_slope(xi, lam_p):
    """d/dxi of :func:`pads_force`."""
    xi = np.asarray(xi, float)
    return 2 + 2 * (lam_p + xi) ** -3.0 + 2 * (lam_p - xi) ** -3.0


def pads_stage(h, L0, lam_p):
    """The stage's displacement between the pads under the core's force (scaled to slope 1 at rest): xi solves
    pads_force(xi) = pads_slope(0) h / L0, the output L0 xi."""
    xi = invert_odd_stiffening(lambda x: pads_force(x, lam_p), lambda x: pads_slope(x, lam_p),
                               pads_slope(0.0, lam_p) * np.asarray(h, float) / L0, lam_p)
    return L0 * xi


def air_gauge(g, g_c):
    """The back pressure over the supply's of a nozzle-flapper air gauge at the gap g: the supply orifice and the
    nozzle's curtain (pi d_n g) pass the same flow, incompressibly, so p / p_s = 1 / (1 + (g / g_c)^2), g_c = d_o^2 /
    (4 d_n) for equal discharge coefficients (Merritt, *Hydraulic Control Systems*, 1967, sec. 5.4; air gauging: e.g.
    Crnojevic, Roy, Bettahar & Florin, Measurement 20 (1997) 51)."""
    return 1 / (1 + (np.asarray(g, float) / g_c) ** 2)


def air_gauge_reading(x, g0, g_c, side):
    """The air gauge's reading of the stage's displacement x, the stage closing the gap g0 by side x (side +-1),
    converted to a displacement with the slope at g0: (p(g0 - side x) - p(g0)) / (side p'(g0) (-1))."""
    x = np.asarray(x, float)
    u0 = g0 / g_c
    slope = 2 * u0 / (g_c * (1 + u0 * u0) ** 2)       # -dp/dg at g0
    return side * (air_gauge(g0 - side * x, g_c) - air_gauge(g0, g_c)) / slope


def fbg_readings(t, t_fine, h_fine, latency, p_lo, rho, h_lo, h_hi, iters=30):
    """A fibre Bragg grating read by a swept-laser interrogator (Kersey et al., J. Lightwave Technol. 15 (1997) 1442):
    the laser sweeps the band once per sample, the k-th sweep over [t_k - (1 + latency) dt, t_k - latency dt); the
    grating's wavelength, linear in the stage's position h, sits at the fraction p(t) = p_lo + rho (h(t) - h_lo) /
    (h_hi - h_lo) of the band, and the sweep finds it at the instant s (from the sweep's start) where s / dt = p(t0 +
    s); the reading, h at that instant, is delivered latency samples after the sweep: a delay of 1 + latency - p
    samples, shorter for the readings late in the band. h between the points of the fine grid linear; s by
    fixed-point iteration (a contraction: the sweep outruns the grating). Returns the readings and the delays in
    samples."""
    t = np.asarray(t, float)
    dt = t[1] - t[0]
    t0 = t - (1 + latency) * dt
    s = np.full_like(t, 0.5 * dt)
    for _ in range(iters):
        hh = np.interp(t0 + s, t_fine, h_fine)
        s = dt * (p_lo + rho * (hh - h_lo) / (h_hi - h_lo))
    return np.interp(t0 + s, t_fine, h_fine), (t - t0 - s) / dt


def alignment_history(r, w, w0, top, n_coarse, x_opt, width, s0, s_max, tol, v_max=100.0):
    """The search that aligned a fibre to a waveguide with the stage before the record (the coupled power a Gaussian
    mode overlap exp(-2 (x - x_opt)^2 / width^2) of the stage's settled position x, the output of plays (r, w, w0)
    at unit gain): from the virgin state at 0 V a coarse scan up to top in n_coarse steps, a return to the best
    coarse point from above, then Rosenbrock's rule in one dimension (Comput. J. 3 (1960) 175): a trial step s from
    the best point, kept and tripled (up to +-s_max, the routine's largest step) when the power grows, else undone
    (the stage goes back) and s times -1/2, until |s| < tol. Returns the turning points (from 0 V), the plays' final
    state, the best voltage and the trials' count."""
    z = np.zeros(len(r))
    path = [0.0]

    def go(v):
        nonlocal z
        z = np.clip(z, v - r, v + r)
        path.append(v)
        x = w0 * v + w @ z
        return math.exp(-2 * (x - x_opt) ** 2 / width ** 2)

    coarse = top * np.arange(1, n_coarse + 1) / n_coarse
    p_c = [go(v) for v in coarse]
    best_v = coarse[int(np.argmax(p_c))]
    best = go(best_v)
    s, trials = s0, 0
    while abs(s) >= tol:
        v = min(max(best_v + s, 0.0), v_max)
        p = go(v)
        trials += 1
        if p > best:
            best_v, best = v, p
            s = max(min(3.0 * s, s_max), -s_max)
        else:
            go(best_v)
            s *= -0.5
    pts = np.array(path)
    keep = np.r_[True, np.diff(pts) != 0]
    return pts[keep], z, best_v, trials


def ntc_resistance(T, r25, B):
    """An NTC thermistor's resistance by the B-parameter law r25 exp(B (1 / T - 1 / 298.15)) (Steinhart & Hart,
    Deep-Sea Res. 15 (1968) 497, to first order; T in K)."""
    return r25 * np.exp(B * (1 / np.asarray(T, float) - 1 / 298.15))


def ntc_rhs(T, v, r25, B, r_s, delta, tau, T_a):
    """The bead's temperature rate: (P - delta (T - T_a)) / C, P = v^2 R / (R + r_s)^2 the Joule heat of the drive
    across the bead in series with the sense resistor r_s, C = delta tau its heat capacity (the dissipation constant
    delta in W/K; the self-heated thermistor: Macklen, *Thermistors*, 1979, ch. 3)."""
    R = ntc_resistance(T, r25, B)
    return (v * v * R / (R + r_s) ** 2 - delta * (T - T_a)) / (delta * tau)


def ntc_sense(v, dt, r25, B, r_s, delta, tau, T_a=298.15, sub=4):
    """The voltage across the sense resistor, r_s v / (R(T) + r_s), of the drive v across the bead and the resistor in
    series, the bead's temperature by the classical Runge-Kutta method on sub steps per sample (v linear between
    samples), from the ambient. Its loops are pinched: zero output whenever v = 0 (Chua & Kang, Proc. IEEE 64 (1976)
    209: the thermistor as a memristive system). Returns the output and the temperature."""
    v = np.asarray(v, float)
    h = dt / sub
    T = np.empty_like(v)
    Tk = T_a
    T[0] = Tk
    for k in range(1, len(v)):
        a, b = v[k - 1], v[k]
        for j in range(sub):
            va, vm, vb = a + (b - a) * j / sub, a + (b - a) * (j + 0.5) / sub, a + (b - a) * (j + 1) / sub
            k1 = ntc_rhs(Tk, va, r25, B, r_s, delta, tau, T_a)
            k2 = ntc_rhs(Tk + 0.5 * h * k1, vm, r25, B, r_s, delta, tau, T_a)
            k3 = ntc_rhs(Tk + 0.5 * h * k2, vm, r25, B, r_s, delta, tau, T_a)
            k4 = ntc_rhs(Tk + h * k3, vb, r25, B, r_s, delta, tau, T_a)
            Tk = Tk + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
        T[k] = Tk
    return r_s * v / (ntc_resistance(T, r25, B) + r_s), T

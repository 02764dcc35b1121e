"""Mechanisms and signals of the HOLDOUT17 set (``cases_holdout17.py``), each written from its law.

Nothing here imports hystcomp (nor the other sets' mechanisms). Every mechanism takes the (clean) drive, or the
core's output, and returns the response; all are causal. The sources of the laws are beside each function and in
``cases_holdout17``'s docstring.

Citations: every source below was written from memory in this session (none was re-read): the papers' volumes,
pages and years, the books' chapters and the tidal constituents' equilibrium amplitudes may be off. The laws
themselves do not rest on them: each is checked in tests/test_realistic_holdout17.py against an independent solution
(the box-spectrum creep against quadrature of its distribution, the elastica against a shooting solution of its
boundary-value problem, the slab's field against the diffusion equation solved by the method of lines, the radiative
cooling against its implicit closed form, the Kepler orbits against the two-body problem, and so on).
"""

import math

import numpy as np
from scipy.integrate import solve_ivp
from scipy.signal import cont2discrete, lfilter, ss2tf
from scipy.special import ellipeinc, ellipkinc, exp1

# ---- rate-independent cores ----


def plays(v, r, w, w0, state=0.0, return_state=False):
    """y = w0 v + sum_i w_i z_i, z_i the play (backlash) of threshold r_i >= 0: z_i(t) = min(max(z_i(t-), v(t) - r_i),
    v(t) + r_i) (Krasnosel'skii & Pokrovskii, *Systems with Hysteresis*, 1989; Brokate & Sprekels, *Hysteresis and
    Phase Transitions*, 1996, sec. 2.3), from the given state (a number or one per play; 0: virgin)."""
    v = np.asarray(v, float)
    r = np.asarray(r, float)
    w = np.asarray(w, float)
    z = np.broadcast_to(np.asarray(state, float), r.shape).copy()
    y = np.empty_like(v)
    for k, vk in enumerate(v.tolist()):
        np.maximum(z, vk - r, out=z)
        np.minimum(z, vk + r, out=z)
        y[k] = w0 * vk + w @ z
    return (y, z) if return_state else y


def gumbel_plays(n, r_max, mu, beta, w0):
    """n thresholds evenly spaced in (0, r_max) with weights of a Gumbel (largest extreme value) density exp(-(x +
    exp(-x))) / beta, x = (r - mu) / beta, summing to 1 - w0: a wall segment breaks away at the largest of many pinning
    barriers it meets (extreme-value statistics: Gumbel, *Statistics of Extremes*, 1958), a skewed hump with its mode
    at mu and a long tail of wide plays."""
    r = (np.arange(n) + 0.5) * r_max / n
    x = (r - mu) / beta
    dens = np.exp(-(x + np.exp(-x)))
    return r, (1 - w0) * dens / dens.sum()


def exp_plays(n, r_max, lam, w0):
    """n thresholds evenly spaced in (0, r_max) with weights of an exponential density exp(-r / lam), summing to
    1 - w0."""
    r = (np.arange(n) + 0.5) * r_max / n
    dens = np.exp(-r / lam)
    return r, (1 - w0) * dens / dens.sum()


def bakeout_state(r, bias, f_t):
    """The plays' state after a bake-out with the stack held at a bias: from the virgin state at 0 V the bias is
    applied (thresholds r), the stack heated (the coercive field, so every threshold, falls to f_t r: the plays are
    dragged to within f_t r of the bias), cooled under the bias (the thresholds grow back, nothing moves) and the bias
    ramped to 0 V (thresholds r): z = min(r, max(0, bias - f_t r)) for bias > 0, a profile no excursion at room
    temperature leaves (its falling side has the slope -f_t, not -1). The coercive field of a poled ceramic falls
    with the temperature toward the Curie point (Jaffe, Cook & Jaffe, *Piezoelectric Ceramics*, 1971, ch. 7; the
    field-cooled memory is Neel's thermoremanence, Ann. Geophys. 5 (1949) 99)."""
    r = np.asarray(r, float)
    z = np.zeros_like(r)
    z = np.clip(z, bias - r, bias + r)                 # the bias applied at room temperature
    z = np.clip(z, bias - f_t * r, bias + f_t * r)     # heated: the bands shrink around the bias
    return np.clip(z, 0.0 - r, 0.0 + r)                # cooled (no motion), the bias ramped to 0 V


# ---- signals ----

def raised_cosine(x):
    """0 for x <= 0, (1 - cos(pi x)) / 2 between, 1 for x >= 1."""
    x = np.clip(np.asarray(x, float), 0.0, 1.0)
    return (1 - np.cos(np.pi * x)) / 2


#: tidal constituents: name, angular speed (degrees per mean solar hour) and equilibrium amplitude relative to M2
#: (Doodson 1921; Schureman, *Manual of Harmonic Analysis and Prediction of Tides*, 1958; Pugh, *Tides, Surges and
#: Mean Sea-Level*, 1987, ch. 3 and 4)
TIDES = (("M2", 28.9841042, 1.0), ("S2", 30.0, 0.4656), ("N2", 28.4397295, 0.1937), ("K2", 30.0821373, 0.1267),
         ("K1", 15.0410686, 0.5842), ("O1", 13.9430356, 0.4151), ("P1", 14.9589314, 0.1933))


def tide(t_h, amps, phases):
    """The harmonic tide sum_i amps_i cos(speed_i t_h - phases_i), t_h in hours, the speeds of :data:`TIDES` (the
    harmonic method of tidal prediction, Pugh 1987, ch. 4): semidiurnal groups beating over the spring-neap cycle
    (M2 - S2, 14.8 days) and a diurnal inequality from K1, O1 and P1."""
    t_h = np.asarray(t_h, float)
    out = np.zeros_like(t_h)
    for (_, speed, _), a, g in zip(TIDES, amps, phases):
        out += a * np.cos(np.radians(speed) * t_h - g)
    return out


def ramps_and_holds(dt, levels, holds, edge_s, lead_s):
    """From lead_s at 0 V, each level in turn reached by a raised-cosine step of edge_s and held for holds[i]. Returns
    the path and the first sample of each hold."""
    me_ = max(int(round(edge_s / dt)), 1)
    out, starts, cur = [np.zeros(int(round(lead_s / dt)))], [], 0.0
    pos = len(out[0])
    for lv, h in zip(levels, holds):
        m = int(round(h / dt))
        out.append(np.r_[cur + (lv - cur) * raised_cosine(np.arange(1, me_ + 1) / me_), np.full(m, lv)])
        starts.append(pos + me_)
        pos += me_ + m
        cur = lv
    return np.concatenate(out), np.array(starts)


def load_doubling_levels(top, k_first):
    """An oedometer's incremental loading with a load-increment ratio of 1 (each load twice the last: Terzaghi's
    consolidation test, ASTM D2435): top / 2^k_first ... top / 2, an unloading to top / 8 and 0, a reloading by
    doubling from top / 4 to top, and an unloading to top / 4, top / 16 and 0."""
    first = top * 2.0 ** -np.arange(k_first, 0, -1)
    return np.r_[first, top / 8, 0.0, top / 4, top / 2, top, top / 4, top / 16, 0.0]


def rotor_speed(t, w_a, w_b, t_up, tau_c):
    """A rotor's speed, acceleration and angle: a run-up at constant angular acceleration from w_a to w_b over t_up,
    then a coast-down against viscous drag, w_b exp(-(t - t_up) / tau_c)."""
    t = np.asarray(t, float)
    al = (w_b - w_a) / t_up
    up = t < t_up
    s = np.maximum(t - t_up, 0.0)
    w = np.where(up, w_a + al * t, w_b * np.exp(-s / tau_c))
    wd = np.where(up, al, -w_b / tau_c * np.exp(-s / tau_c))
    phi_up = w_a * t_up + al * t_up * t_up / 2
    phi = np.where(up, w_a * t + al * t * t / 2, phi_up + w_b * tau_c * -np.expm1(-s / tau_c))
    return w, wd, phi


def jeffcott_rhs(t, s, wn, zeta, speed):
    """The Jeffcott rotor's lateral motion in one axis, x'' + 2 zeta wn x' + wn^2 x = e (w^2 cos phi + w' sin phi)
    (the unbalance e of the mass centre, e = 1; Jeffcott, Phil. Mag. 37 (1919) 304; the passage through the critical
    speed under acceleration: Lewis, Trans. ASME 54 (1932) 253); speed(t) -> (w, w', phi)."""
    w, wd, phi = speed(t)
    return np.array([s[1], -2 * zeta * wn * s[1] - wn * wn * s[0] + w * w * math.cos(phi) + wd * math.sin(phi)])


def jeffcott_runup(dt, n, wn, zeta, w_a, w_b, t_up, tau_c, sub=4):
    """x of :func:`jeffcott_rhs` from rest: the oscillator discretised exactly for a forcing linear between the
    points of a grid dt / sub (a first-order hold: within 1e-4 of the largest swing of solve_ivp's solution), the
    forcing e (w^2 cos phi + w' sin phi) from the exact speed law. Returns n samples."""
    h = dt / sub
    tt = np.arange((n - 1) * sub + 1) * h
    w, wd, phi = rotor_speed(tt, w_a, w_b, t_up, tau_c)
    f = w * w * np.cos(phi) + wd * np.sin(phi)
    A = np.array([[0.0, 1.0], [-wn * wn, -2 * zeta * wn]])
    Ad, Bd, Cd, Dd, _ = cont2discrete((A, np.array([[0.0], [1.0]]), np.array([[1.0, 0.0]]), np.zeros((1, 1))), h,
                                      method="foh")
    b, a = ss2tf(Ad, Bd, Cd, Dd)
    return lfilter(b[0], a, f)[::sub]


#: the golden section's ratio, (sqrt 5 - 1) / 2
GOLD = (math.sqrt(5.0) - 1) / 2


def golden_section(f, a, b, tol):
    """Kiefer's golden-section search for the maximum of a unimodal f on [a, b] (Proc. Amer. Math. Soc. 4 (1953) 502):
    interior points c = b - g (b - a) and d = a + g (b - a), g the golden ratio's inverse; [a, d] is kept when f(c) >
    f(d), else [c, b], and one new point is evaluated per step until the bracket is under tol. Returns the points in
    the order evaluated and the bracket's midpoint."""
    c, d = b - GOLD * (b - a), a + GOLD * (b - a)
    fc, fd = f(c), f(d)
    pts = [c, d]
    while b - a > tol:
        if fc > fd:
            b, d, fd = d, c, fc
            c = b - GOLD * (b - a)
            fc = f(c)
            pts.append(c)
        else:
            a, c, fc = c, d, fd
            d = a + GOLD * (b - a)
            fd = f(d)
            pts.append(d)
    return np.array(pts), (a + b) / 2


def autofocus_points(focus, width, top, n_coarse, tol):
    """The positions a z stage visits to focus one field: a coarse sweep top j / n_coarse (j = 1 ... n_coarse) scoring
    the image's sharpness, a Lorentzian 1 / (1 + ((x - focus) / width)^2), then a golden-section search in the
    bracket around the best coarse point, then the focus found. Returns the points (the last the focus found)."""
    def sharp(x):
        return 1 / (1 + ((x - focus) / width) ** 2)

    coarse = top * np.arange(1, n_coarse + 1) / n_coarse
    j = int(np.argmax(sharp(coarse)))
    lo, hi = top * j / n_coarse, top * min(j + 2, n_coarse) / n_coarse
    pts, best = golden_section(sharp, lo, hi, tol)
    return np.r_[coarse, pts, best]


def moves_and_dwells(dt, start, points, dwells, speed, t_min):
    """From rest at start, raised-cosine moves to each point in turn (each taking t_min + |step| / speed), each
    followed by a dwell. Returns the path and the first sample of each dwell."""
    out, starts, cur, pos = [], [], start, 0
    for p, d in zip(points, dwells):
        m = max(int(round((t_min + abs(p - cur) / speed) / dt)), 1)
        hold = int(round(d / dt))
        out.append(np.r_[cur + (p - cur) * raised_cosine(np.arange(1, m + 1) / m), np.full(hold, p)])
        starts.append(pos + m)
        pos += m + hold
        cur = p
    return np.concatenate(out), np.array(starts)


def star_scan(dt, stars, speed, dwell_s, jump_s, lead_s):
    """One axis of a vector scan (a laser marker's galvanometer or a tip-tilt mirror) tracing star polygons {n/k}
    (vertex j at R (cos, sin)(theta0 + 2 pi j k / n); Coxeter, *Regular Polytopes*, 1973, sec. 2.8) edge by edge at
    a constant speed in the plane (x linear in time along each edge), dwelling dwell_s at each vertex (the corner
    delay), each star closed; raised-cosine jumps of jump_s from 0 V to the first star, between stars and back to
    0 V, with lead_s at rest before and after. Returns the path and the vertices' x."""
    out, verts, cur = [np.zeros(int(round(lead_s / dt)))], [], 0.0
    mj = max(int(round(jump_s / dt)), 1)
    md = max(int(round(dwell_s / dt)), 1)
    for n_, k_, R, th0 in stars:
        ang = th0 + 2 * np.pi * np.arange(n_ + 1) * k_ / n_
        P = R * np.c_[np.cos(ang), np.sin(ang)]
        out.append(cur + (P[0, 0] - cur) * raised_cosine(np.arange(1, mj + 1) / mj))
        out.append(np.full(md, P[0, 0]))
        verts.append(P[0, 0])
        for a_, b_ in zip(P[:-1], P[1:]):
            m = max(int(round(np.hypot(*(b_ - a_)) / speed / dt)), 1)
            out.append(a_[0] + (b_[0] - a_[0]) * np.arange(1, m + 1) / m)
            out.append(np.full(md, b_[0]))
            verts.append(b_[0])
        cur = P[-1, 0]
    out.append(cur - cur * raised_cosine(np.arange(1, mj + 1) / mj))
    out.append(np.zeros(int(round(lead_s / dt))))
    return np.concatenate(out), np.array(verts)


def kepler_E(M, e, iters=40):
    """The eccentric anomaly E of Kepler's equation M = E - e sin E, by Newton's method from E = M + e sin M (or pi
    for e > 0.8), which converges for every M and e < 1 (Danby, *Fundamentals of Celestial Mechanics*, 1988, ch. 6)."""
    M = np.asarray(M, float)
    E = np.where(e > 0.8, np.pi + 0 * M, M + e * np.sin(M))
    for _ in range(iters):
        E = E - (E - e * np.sin(E) - M) / (1 - e * np.cos(E))
    return E


def kepler_orbits(dt, periods, eccs, amps, cycles, lead_s):
    """One coordinate of bodies on Keplerian ellipses, a cos E (the distance from the ellipse's centre along the major
    axis: fast through the periapsis at +a, slow round the apoapsis at -a), orbit i of semi-major axis amps[i] (signed:
    the periapsis on that side), eccentricity eccs[i] and period periods[i] for cycles[i] whole periods from E = pi / 2
    (a cos E = 0), one after another; from lead_s at rest. Returns the path and each orbit's first sample."""
    parts, starts, pos = [np.zeros(int(round(lead_s / dt)))], [], int(round(lead_s / dt))
    for T, e, a, c in zip(periods, eccs, amps, cycles):
        tt = np.arange(int(round(c * T / dt))) * dt
        M = np.pi / 2 - e + 2 * np.pi * tt / T
        parts.append(a * np.cos(kepler_E(M, e)))
        starts.append(pos)
        pos += len(tt)
    parts.append(np.zeros(1))
    return np.concatenate(parts), np.array(starts)


def alpha_pulses(t, times, heights, tau):
    """Shot noise of alpha-function pulses: sum_k heights_k u_k e^(1 - u_k), u_k = (t - times_k) / tau > 0 (each
    peaking at its height tau after its arrival; Rall, J. Neurophysiol. 30 (1967) 1138; shot noise by Campbell's
    theorem: Rice, Bell Syst. Tech. J. 23 (1944) 282), arrivals at the times of a Poisson process."""
    t = np.asarray(t, float)
    out = np.zeros_like(t)
    for t0, h in zip(times, heights):
        u = np.clip((t - t0) / tau, 0.0, None)
        out += h * u * np.exp(1 - u)
    return out


def shepard_risset(t, f_low, n_oct, glide_s, sigma, up=True):
    """A Shepard-Risset glissando (Shepard, J. Acoust. Soc. Am. 36 (1964) 2346; Risset 1969): n_oct sines an octave
    apart gliding by an octave every glide_s (up or down) under a fixed Gaussian envelope over the log-frequency
    (centred n_oct / 2 octaves above f_low, sigma octaves wide), each wrapping round to the bottom, where its weight is
    small, when it passes the top. The phases are the running integrals of the frequencies (trapezoid rule)."""
    t = np.asarray(t, float)
    out = np.zeros_like(t)
    sgn = 1.0 if up else -1.0
    for k in range(n_oct):
        p = np.mod(k + sgn * t / glide_s, n_oct)
        f = f_low * 2.0 ** p
        phase = 2 * np.pi * np.r_[0.0, np.cumsum((f[1:] + f[:-1]) / 2 * np.diff(t))]
        out += np.exp(-((p - n_oct / 2) ** 2) / (2 * sigma * sigma)) * np.sin(phase)
    return out


def bazett_beats(dt, rr, amps, fills, k_qt, fill_frac):
    """A pulsatile pump's strokes after the heart's: beat i of RR interval rr[i] ejects as a half-sine +amps[i] over
    the systole QT = k_qt sqrt(RR) (Bazett's formula, Heart 7 (1920) 353), fills as a half-sine -fills[i] over
    fill_frac of the rest, and rests at 0 V for the remainder (diastasis). Returns the path and each beat's first
    sample."""
    parts, starts, pos = [], [], 0
    for RR, a, f in zip(rr, amps, fills):
        ts = k_qt * math.sqrt(RR)
        ms, mf = int(round(ts / dt)), int(round(fill_frac * (RR - ts) / dt))
        mr = int(round(RR / dt)) - ms - mf
        parts += [a * np.sin(np.pi * np.arange(ms) / ms), -f * np.sin(np.pi * np.arange(mf) / mf), np.zeros(mr)]
        starts.append(pos)
        pos += ms + mf + mr
    return np.concatenate(parts), np.array(starts)


def sar_history(r, w, w0, target, lo, hi, n_bits):
    """A successive-approximation (bisection) search by a calibration routine for the input whose settled output
    reaches target, on an actuator with plays (r, w, w0): from the virgin state at 0 V a range check to hi and lo,
    then n_bits trials each at the middle of the bracket, the bracket's upper end moved there when the output is at
    or above target, else its lower end (Kester, *Data Conversion Handbook*, 2005, ch. 3: the SAR converter's
    algorithm), ending at the bracket's middle. Returns the turning points (from 0 V), the plays' final state and
    the trials' outputs."""
    z = np.zeros(len(r))
    pts, outs = [0.0, hi, lo], []
    for p in pts[1:]:
        z = np.clip(z, p - r, p + r)
    a, b = lo, hi
    for _ in range(n_bits):
        m = (a + b) / 2
        z = np.clip(z, m - r, m + r)
        y = w0 * m + w @ z
        pts.append(m)
        outs.append(y)
        if y >= target:
            b = m
        else:
            a = m
    m = (a + b) / 2
    pts.append(m)
    z = np.clip(z, m - r, m + r)
    return np.array(pts), z, np.array(outs)


def shuttle(dt, amp, dwells, move_s, lead_s):
    """A pick-and-place shuttle between two stations at -amp and +amp: from lead_s at rest at 0 V a move to +amp, then
    moves back and forth, every one a raised-cosine of move_s (the harmonic motion law: Biagiotti & Melchiorri,
    *Trajectory Planning for Automatic Machines and Robots*, 2008, sec. 2.1), each followed by a dwell dwells[i] (parts
    arriving at random). Returns the path and the first sample of every move."""
    m = max(int(round(move_s / dt)), 1)
    out, starts, cur, pos = [np.zeros(int(round(lead_s / dt)))], [], 0.0, int(round(lead_s / dt))
    for i, d in enumerate(dwells):
        nxt = amp if i % 2 == 0 else -amp
        out.append(np.r_[cur + (nxt - cur) * raised_cosine(np.arange(1, m + 1) / m), np.full(int(round(d / dt)), nxt)])
        starts.append(pos)
        pos += m + int(round(d / dt))
        cur = nxt
    return np.concatenate(out), np.array(starts)


# ---- mechanisms ----

def ramp_lag(x, dt, tau, x0=None):
    """A first-order lag tau dy/dt = x - y of an input linear between samples, exact (ramp-invariant): y_k = a y_{k-1}
    + (g - a) x_{k-1} + (1 - g) x_k, a = exp(-dt / tau), g = (1 - a) tau / dt; at rest at x0 (x[0] by default)."""
    x = np.asarray(x, float)
    x0 = x[0] if x0 is None else x0
    a = math.exp(-dt / tau)
    g = -math.expm1(-dt / tau) * tau / dt
    return lfilter([1 - g, g - a], [1.0, -a], x - x0) + x0


def box_prony(tau1, tau2, m=240):
    """Retardation times log-uniform between tau1 and tau2 (the box spectrum) with equal weights: the midpoint rule in
    u = ln tau of the box distribution 1 / ln(tau2 / tau1)."""
    u = math.log(tau1) + (np.arange(m) + 0.5) * math.log(tau2 / tau1) / m
    return np.exp(u), np.full(m, 1.0 / m)


def box_step(t, tau1, tau2):
    """The step response of the box spectrum, 1 - (E1(t / tau2) - E1(t / tau1)) / ln(tau2 / tau1) (E1 the exponential
    integral): the magnetic after-effect of a flat distribution of activation energies (Neel, J. Phys. Radium 12
    (1951) 339; the box distribution: Becker & Doering, *Ferromagnetismus*, 1939; Chikazumi, *Physics of
    Ferromagnetism*, 1997, ch. 20), linear in ln t between tau1 and tau2 and flat beyond."""
    t = np.asarray(t, float)
    pos = t > 0
    tp = np.where(pos, t, 1.0)
    return np.where(pos, 1 - (exp1(tp / tau2) - exp1(tp / tau1)) / math.log(tau2 / tau1), 0.0)


def prony_creep(h, dt, c, taus, weights):
    """Creep by Boltzmann superposition of Kelvin elements (Findley, Lai & Onaran, *Creep and Relaxation of Nonlinear
    Viscoelastic Materials*, 1976, ch. 5): c sum_i weights_i lag_{taus_i}[h], at rest at h[0]."""
    h = np.asarray(h, float)
    out = np.zeros_like(h)
    for tau, w in zip(taus, weights):
        out += w * ramp_lag(h, dt, tau)
    return c * (out - h[0] * np.sum(weights))


def latent_heat_plays(v, dt, r, w, w0, lam, tau):
    """A ferroic transformation (an SMA wire's martensite) as plays of the effective stress u = v - theta, its latent
    heat warming the wire as it transforms and the wire cooling to the air: d theta / dt = lam d xi / dt - theta / tau
    (theta the temperature rise times the Clausius-Clapeyron slope d sigma / dT, in input units; xi = sum w z the
    transformation), so that the transformation lags at fast rates and the loop widens and tilts (Shaw & Kyriakides,
    J. Mech. Phys. Solids 43 (1995) 1243; the Clausius-Clapeyron relation for SMA: Wollants, Roos & Delaey, Prog.
    Mater. Sci. 37 (1993) 227). Per sample: theta_k = a theta_{k-1} + lam g (xi_k - xi_{k-1}) (exact for xi linear in
    the step, a = exp(-dt / tau), g = (1 - a) tau / dt) and xi_k = the plays at u_k = v_k - theta_k, solved exactly
    (the plays are piecewise linear in u within a step). From the virgin state at rest. Returns w0 v + xi (the elastic
    strain sees the stress itself)."""
    v = np.asarray(v, float)
    r = np.asarray(r, float)
    w = np.asarray(w, float)
    a = math.exp(-dt / tau)
    lg = lam * -math.expm1(-dt / tau) * tau / dt
    z = np.clip(np.zeros_like(r), v[0] - r, v[0] + r)
    xi, th = float(w @ z), 0.0
    out = np.empty_like(v)
    out[0] = w0 * v[0] + xi
    for k in range(1, len(v)):
        C = v[k] - a * th
        F0 = v[k - 1] - th - C                           # F(u_prev): the plays unmoved
        if F0 != 0.0:
            up = F0 < 0                                  # the effective input rises: upper edges z + r
            b = z + r if up else z - r
            order = np.argsort(b if up else -b)
            bs, ws = b[order], w[order]
            W = np.cumsum(ws) - ws
            S = np.cumsum(ws * bs) - ws * bs
            Fb = bs * (1 + lg * W) - lg * S - C          # F at each edge in the order met; F increases with u
            na = int(np.sum(Fb < 0)) if up else int(np.sum(Fb > 0))   # the plays the solution has moved
            u = (C + lg * np.sum(ws[:na] * bs[:na])) / (1 + lg * np.sum(ws[:na]))
            z = np.clip(z, u - r, u + r)
        xn = float(w @ z)
        th = a * th + lg * (xn - xi)
        xi = xn
        out[k] = w0 * v[k] + xi
    return out


def radiative_temperature(t, T_a, k, q, t_on, t_off):
    """A thin part in vacuum heated at q (K/s) from t_on to t_off and cooling only by radiation, dT/dt = q [t_on <= t <
    t_off] - k (T^4 - T_a^4) (the Stefan-Boltzmann law, k = eps sigma A / (m c); a grey body facing a black
    enclosure at T_a: e.g. Incropera & DeWitt, *Fundamentals of Heat and Mass Transfer*, 2002, ch. 12), from T_a;
    solved by DOP853 (rtol 1e-11) piecewise. Returns T at the times t."""
    t = np.asarray(t, float)
    T = np.full_like(t, T_a)
    T1 = T_a
    for a_, b_, qq in ((t_on, t_off, q), (t_off, t[-1] + 1e-9, 0.0)):
        sel = (t >= a_) & (t < b_)
        sol = solve_ivp(lambda _, y, qq=qq: [qq - k * (y[0] ** 4 - T_a ** 4)], (a_, b_), [T1], method="DOP853",
                        rtol=1e-11, atol=1e-9, dense_output=True)
        T[sel] = sol.sol(t[sel])[0]
        T1 = sol.y[0, -1]
    return T


def tangent_lever(theta, phi0):
    """A beam reflected by a mirror tilted by theta turns by 2 theta (the optical lever: Poggendorff 1826) and meets a
    flat detector, its normal phi0 from the beam at rest, at D tan(phi0 + 2 theta) (units of D): the tangent error
    that f-theta lenses correct (Smith, *Modern Optical Engineering*, 2008, ch. 10). Returns the spot's travel from
    rest."""
    return np.tan(phi0 + 2 * np.asarray(theta, float)) - math.tan(phi0)


def lever_reading(x, phi0, k):
    """The mirror's tilt k x (x the core's output) read on the flat detector, scaled to slope 1 at rest: (tan(phi0 + 2
    k x) - tan phi0) cos^2(phi0) / (2 k)."""
    return tangent_lever(k * np.asarray(x, float), phi0) * math.cos(phi0) ** 2 / (2 * k)


def elastica_tip(alpha, iters=80):
    """The transverse tip deflection over the length of a cantilever under a transverse end load, alpha = P L^2 / EI
    (the elastica, large deflections; Bisshopp & Drucker, Q. Appl. Math. 3 (1945) 272; Howell, *Compliant
    Mechanisms*, 2001, ch. 5): the tip angle psi0 from sqrt(alpha) = K(m) - F(phi1 | m), m = (1 + sin psi0) / 2,
    sin phi1 = 1 / sqrt(2 m), and y / L = 1 - 2 (E(m) - E(phi1 | m)) / sqrt(alpha) (K, F, E the complete and
    incomplete elliptic integrals), alpha / 3 below alpha = 1e-5 (the linear beam). Vectorised bisection on psi0."""
    alpha = np.abs(np.asarray(alpha, float))
    sa = np.sqrt(alpha)
    lo, hi = np.zeros_like(alpha), np.full_like(alpha, np.pi / 2 * (1 - 1e-12))

    def parts(psi):
        m = (1 + np.sin(psi)) / 2
        phi1 = np.arcsin(np.minimum(1 / np.sqrt(2 * m), 1.0))
        return m, phi1

    for _ in range(iters):
        mid = (lo + hi) / 2
        m, phi1 = parts(mid)
        g = ellipkinc(np.pi / 2, m) - ellipkinc(phi1, m) - sa
        lo, hi = np.where(g < 0, mid, lo), np.where(g < 0, hi, mid)
    m, phi1 = parts((lo + hi) / 2)
    big = alpha >= 1e-5
    y = 1 - 2 * (ellipeinc(np.pi / 2, m) - ellipeinc(phi1, m)) / np.where(big, sa, 1.0)
    return np.where(big, y, alpha / 3)


def elastica_stage(x, x_t, alpha_t):
    """A stage carried at the tip of a long blade flexure loaded by the core's force x: the tip's deflection at the
    load alpha_t x / x_t, scaled to slope 1 at rest (3 x_t / alpha_t): linear for small loads, the ends compressed as
    the blade bends into an elastica (odd)."""
    x = np.asarray(x, float)
    return np.sign(x) * 3 * x_t / alpha_t * elastica_tip(alpha_t * x / x_t)


def slab_modes(tau, n_modes):
    """The partial fractions of 1 / cosh(sqrt(s tau)) = sum_n c_n / (1 + s tau_n): tau_n = 4 tau / ((2n + 1)^2 pi^2),
    c_n = 4 (-1)^n / ((2n + 1) pi) (Mittag-Leffler's expansion over the zeros of cosh; the c_n sum to 1)."""
    n = np.arange(n_modes)
    return 4 * tau / ((2 * n + 1) ** 2 * np.pi ** 2), 4 * (-1.0) ** n / ((2 * n + 1) * np.pi)


def slab_filter(x, dt, tau, n_modes=300):
    """The tangential magnetic field at the mid-plane of a conducting slab (half thickness a) whose faces see the field
    x(t): magnetic diffusion, dH/dt = (1 / mu sigma) d2H/dz2, gives H_c / H_s = 1 / cosh(sqrt(s tau)), tau = mu sigma
    a^2 (the skin effect of a plate: Knoepfel, *Magnetic Fields*, 2000, ch. 4; the same as heat into a slab: Carslaw
    & Jaeger, *Conduction of Heat in Solids*, 1959, sec. 3.3), a delay of tau / 2 at low frequencies with a diffusive
    roll-off above. Per mode a ramp-invariant lag (exact for x linear between samples); the modes past n_modes
    (tau_n < 1.2e-6 tau) taken as instantaneous; at rest at x[0]."""
    x = np.asarray(x, float)
    taus, cs = slab_modes(tau, n_modes)
    out = x * (1 - cs.sum())
    for tn, cn in zip(taus, cs):
        out = out + cn * (x if tn < 1e-6 * dt else ramp_lag(x, dt, tn))
    return out


def healing_plays(v, dt, r, w, w0, beta, t_c, d_c, iters=12):
    """Plays whose sliders heal at rest and weaken as they slip (frictional contacts of a precision guide as
    Maxwell-slip elements: Al-Bender, Lampaert & Swevers, IEEE Trans. Autom. Control 50 (2005) 1883): a play's
    threshold is r (1 + beta ln(1 + theta / t_c)), theta its contact's age, which grows with the time the play stands
    still (Dieterich's static friction growing with the log of the hold time, J. Geophys. Res. 77 (1972) 3690) and
    falls as exp(-s / d_c) with the slip s (the slip-weakening of Palmer & Rice, Proc. R. Soc. Lond. A 332 (1973) 527);
    rate independent while moving (a simplification of Ruina's rate-and-state laws, J. Geophys. Res. 88 (1983) 10359,
    without their rate term). A slipping play solves z = v -+ r (1 + beta ln(1 + theta0 exp(-s / d_c) / t_c)) for its
    slip s in the step by Newton's method (monotone when beta r < d_c). From the virgin state, every age 0."""
    v = np.asarray(v, float)
    r = np.asarray(r, float)
    w = np.asarray(w, float)
    z = np.zeros_like(r)
    th = np.zeros_like(r)
    y = np.empty_like(v)
    vl = v.tolist()
    for k, vk in enumerate(vl):
        if k and vk == vl[k - 1]:                      # the input stands still: every contact ages, nothing moves
            th += dt
            y[k] = y[k - 1]
            continue
        rho = r * (1 + beta * np.log1p(th / t_c))
        up, dn = vk - rho > z, vk + rho < z
        mv = up | dn
        th[~mv] += dt
        if mv.any():
            sg = np.where(up[mv], 1.0, -1.0)
            D = sg * (vk - z[mv])                      # the distance to travel against a threshold r
            rr, t0 = r[mv], th[mv]
            s = D - rr
            for _ in range(iters):
                q = t0 * np.exp(-s / d_c) / t_c
                g = s - D + rr * (1 + beta * np.log1p(q))
                gp = 1 - rr * beta * q / (1 + q) / d_c
                s = s - g / gp
            z[mv] += sg * s
            th[mv] = t0 * np.exp(-s / d_c)
        y[k] = w0 * vk + w @ z
    return y

"""Mechanisms and signals of the HOLDOUT20 set (``cases_holdout20.py``), each written from its law.

Nothing here imports hystcomp. Every mechanism takes the (clean) drive, or the core's output, and returns the response;
all are causal. The sources of the laws are beside each function and in ``cases_holdout20``'s docstring. The play, its
threshold grid, exponentially weighted plays and a path's turning points are the earlier sets' (imported, the same
laws), as are the raised cosine, the exact first-order-hold response of a linear system and the Prony (Kelvin-chain)
creep.

Citations: every source below was written from memory in this session (none was re-read): the papers' volumes, pages and
years, the books' chapters and the standards' clauses may be off. The laws themselves do not rest on them: each is
checked in tests/test_realistic_holdout20.py against an independent solution (Chua's circuit against the matrix
exponential of its linear pieces and its odd symmetry, the switching-time spectrum against quadrature of its defining
integral and a Duhamel sum, the lift's and the engine's paths against quadrature of their speeds, the piston against
brentq on its rod's length, the pen's strokes against quadrature of their lognormal speed profiles, the braked stage
against solve_ivp, the cure against the closed form of its m = n = 1 case and quadrature of its inverse, the neuron
against LSODA, the tendon, the isolator and the arch against the derivatives of their energies and brentq, the strip's
transit time against brentq on the quadrature of its speed, the recoiling base against solve_ivp on its equation of
motion and its closed-form frequency response, the late logger against a finer run, the siphon against the closed form
of its draining time, and so on).
"""

import math

import numpy as np
from scipy.integrate import solve_ivp
from scipy.special import i0e, ndtr

# the play, the threshold grid, a path's turning points, the raised cosine, the first-order-hold response and the
# Prony creep are the earlier sets' (the same laws; the cases and tests use them from here)
from .mechanisms13 import turning_points  # noqa: F401
from .mechanisms17 import prony_creep  # noqa: F401
from .mechanisms18 import exp_plays, grid, plays  # noqa: F401
from .mechanisms19 import foh_response, raised_cosine  # noqa: F401


# ---- the rate-independent core ----

def rice_plays(n, r_max, nu, sigma, w0):
    """Thresholds on :func:`grid` weighted by the Rice density (r / s^2) exp(-(r^2 + nu^2) / (2 s^2)) I0(r nu / s^2)
    (Rice, Bell Syst. Tech. J. 23 (1944) 282): the magnitude of a two-component local field made of a coherent part
    nu and random Gaussian parts of deviation s; a hump near nu, not at 0, with a Gaussian tail. Summing to 1 - w0.
    (exp(-(r - nu)^2 / 2 s^2) i0e(r nu / s^2) is the same product, without overflow.)"""
    r = grid(n, r_max)
    dens = r * np.exp(-(r - nu) ** 2 / (2 * sigma * sigma)) * i0e(r * nu / (sigma * sigma))
    return r, (1 - w0) * dens / dens.sum()


# ---- signals ----

def chua_rhs(t, s, alpha=15.6, beta=28.0, m0=-8.0 / 7.0, m1=-5.0 / 7.0):
    """Chua's circuit in its dimensionless form, x' = alpha (y - x - f(x)), y' = x - y + z, z' = -beta y, with the
    diode's piecewise-linear characteristic f(x) = m1 x + (m0 - m1) (|x + 1| - |x - 1|) / 2 (Chua, Komuro & Matsumoto,
    IEEE Trans. Circuits Syst. 33 (1986) 1072; Matsumoto, IEEE TCAS 31 (1984) 1055): the double scroll, x turning
    about +-1.5 and jumping between the scrolls at irregular times."""
    x, y, z = s
    f = m1 * x + 0.5 * (m0 - m1) * (abs(x + 1) - abs(x - 1))
    return [alpha * (y - x - f), x - y + z, -beta * y]


def chua_x(t, units, start, settle=100.0):
    """The x of Chua's circuit at the times t (s), at `units` time units a second, after `settle` units from `start`
    (DOP853, rtol 1e-11); returns x and the state it starts from."""
    s0 = np.array(start, float)
    if settle > 0:
        s0 = solve_ivp(chua_rhs, (0, settle), s0, method="DOP853", rtol=1e-11, atol=1e-12).y[:, -1]
    tau = np.asarray(t, float) * units
    sol = solve_ivp(chua_rhs, (tau[0], tau[-1]), s0, t_eval=tau, method="DOP853", rtol=1e-11, atol=1e-12)
    return sol.y[0], s0


def lift_trip(s, dist, v_max, t_acc):
    """The car's travel s seconds into a trip of `dist` (either sign): its speed rises as a raised cosine over t_acc
    to v_max, cruises and falls likewise (a trip too short to cruise peaks at |dist| / t_acc); returns the travel and
    the trip's duration. The raised-cosine speed (a sine-squared jerk-free start) is a common lift motion profile
    (e.g. Barney & Al-Sharif, *Elevator Traffic Handbook*, 2016, ch. on kinematics)."""
    s = np.asarray(s, float)
    D = abs(dist)
    V = min(v_max, D / t_acc)
    t_c = D / V - t_acc                                # cruise (0 for a short trip)
    T = 2 * t_acc + t_c
    acc = V * (s / 2 - t_acc / (2 * np.pi) * np.sin(np.pi * s / t_acc))
    sd = s - t_acc - t_c
    dec = V * t_acc / 2 + V * t_c + V * (sd / 2 + t_acc / (2 * np.pi) * np.sin(np.pi * sd / t_acc))
    x = np.where(s < t_acc, acc, np.where(s < t_acc + t_c, V * t_acc / 2 + V * (s - t_acc), dec))
    x = np.where(s <= 0, 0.0, np.where(s >= T, D, x))
    return math.copysign(1.0, dist) * x, T


def lift_path(t, lead, levels, dwells, v_max, t_acc):
    """A lift's car from the ground floor (0 V) at rest for `lead` s, then trips to each level in turn, the doors open
    dwells[i] s at each; returns the path, each trip's start and duration and the end."""
    t = np.asarray(t, float)
    v = np.zeros_like(t)
    prev, tc, starts, durs = 0.0, lead, [], []
    for lv, dw in zip(levels, dwells):
        x, T = lift_trip(t - tc, lv - prev, v_max, t_acc)
        v = np.where(t >= tc, prev + x, v)
        starts.append(tc)
        durs.append(T)
        prev, tc = lv, tc + T + dw
    return v, np.array(starts), np.array(durs), tc


def lognormal_progress(t, t0, mu, sigma):
    """The fraction of a stroke done: the lognormal CDF Phi((ln(t - t0) - mu) / sigma), 0 before t0 (the kinematic
    theory of rapid movements: a stroke's speed is the lognormal impulse response of a chain of neuromuscular
    systems; Plamondon, Biol. Cybern. 72 (1995) 295)."""
    s = np.asarray(t, float) - t0
    pos = s > 0
    return np.where(pos, ndtr((np.log(np.where(pos, s, 1.0)) - mu) / sigma), 0.0)


def sigma_lognormal_y(t, strokes):
    """The pen's vertical position by the sigma-lognormal model (O'Reilly & Plamondon, Pattern Recognit. 42 (2009)
    3324): strokes (t0, mu, sigma, D, theta_s, dtheta) each moving the pen by D along a direction theta_s + dtheta
    Lambda(t) turning with its progress Lambda, so its vertical travel is D (cos theta_s - cos(theta_s + dtheta
    Lambda)) / dtheta (D Lambda sin theta_s for a straight stroke); the strokes overlap and add."""
    t = np.asarray(t, float)
    y = np.zeros_like(t)
    for t0, mu, sg, D, th, dth in strokes:
        lam = lognormal_progress(t, t0, mu, sg)
        if abs(dth) < 1e-9:
            y += D * lam * math.sin(th)
        else:
            y += D * (math.cos(th) - np.cos(th + dth * lam)) / dth
    return y


def sigma_lognormal_vy(t, strokes):
    """The pen's vertical speed: sum D Lambda'(t) sin(theta_s + dtheta Lambda), Lambda' the lognormal density."""
    t = np.asarray(t, float)
    out = np.zeros_like(t)
    for t0, mu, sg, D, th, dth in strokes:
        s = t - t0
        pos = s > 0
        sp = np.where(pos, s, 1.0)
        dens = np.where(pos, np.exp(-(np.log(sp) - mu) ** 2 / (2 * sg * sg)) / (sp * sg * math.sqrt(2 * np.pi)), 0.0)
        out += D * dens * np.sin(th + dth * lognormal_progress(t, t0, mu, sg))
    return out


def engine_speed(t, f_idle, blips):
    """An engine's speed (rev/s): idling at f_idle, each throttle blip (t_k, T_k, df_k, tau_r, tau_f) raising it toward
    f_idle + df_k with the time constant tau_r for T_k s, then letting it fall back with tau_f (a first-order speed
    response of the engine's inertia to its torque, e.g. Heywood, *Internal Combustion Engine Fundamentals*, 1988)."""
    t = np.asarray(t, float)
    f = np.full_like(t, f_idle)
    for tk, Tk, df, tr, tf in blips:
        s = t - tk
        top = df * (1 - math.exp(-Tk / tr))
        f += np.where(s <= 0, 0.0, np.where(s < Tk, df * -np.expm1(-np.clip(s, 0, None) / tr),
                                             top * np.exp(-np.clip(s - Tk, 0, None) / tf)))
    return f


def engine_angle(t, f_idle, blips):
    """The crank angle 2 pi int f dt of :func:`engine_speed`, in closed form."""
    t = np.asarray(t, float)
    rev = f_idle * t
    for tk, Tk, df, tr, tf in blips:
        s = np.clip(t - tk, 0, None)
        sa = np.minimum(s, Tk)
        rev += df * (sa + tr * np.expm1(-sa / tr))
        top = df * (1 - math.exp(-Tk / tr))
        sb = np.clip(s - Tk, 0, None)
        rev += top * tf * -np.expm1(-sb / tf)
    return 2 * np.pi * rev


def piston_x(theta, lam):
    """A piston's position from mid-stroke in half strokes: the in-line slider-crank, r cos theta + sqrt(l^2 - r^2
    sin^2 theta) - l over r with lam = r / l (the rod's obliquity: the piston lingers near bottom dead centre and
    hurries through top; e.g. Heywood 1988, ch. 2): +1 at top dead centre (theta = 0), -1 at bottom."""
    th = np.asarray(theta, float)
    return np.cos(th) + (np.sqrt(1 - lam * lam * np.sin(th) ** 2) - 1) / lam


def hindmarsh_rose_rhs(t, s, I, r, a=1.0, b=3.0, c=1.0, d=5.0, s_=4.0, x_r=-1.6):
    """The Hindmarsh-Rose neuron (Hindmarsh & Rose, Proc. R. Soc. Lond. B 221 (1984) 87): x' = y - a x^3 + b x^2 - z
    + I, y' = c - d x^2 - y, z' = r (s (x - x_r) - z); for r about 0.006 and I about 3.1 ... 3.3 it bursts: a few
    spikes, then a quiet spell while the slow current z recovers."""
    x, y, z = s
    return [y - a * x ** 3 + b * x * x - z + I, c - d * x * x - y, r * (s_ * (x - x_r) - z)]


def hindmarsh_rose_x(t, units, start, I, r, settle=150.0):
    """The membrane potential x at the times t (s), at `units` time units a second, after `settle` units (DOP853)."""
    s0 = np.array(start, float)
    if settle > 0:
        s0 = solve_ivp(hindmarsh_rose_rhs, (0, settle), s0, args=(I, r), method="DOP853", rtol=1e-11,
                       atol=1e-12).y[:, -1]
    tau = np.asarray(t, float) * units
    sol = solve_ivp(hindmarsh_rose_rhs, (tau[0], tau[-1]), s0, t_eval=tau, args=(I, r), method="DOP853",
                    rtol=1e-11, atol=1e-12)
    return sol.y[0], s0


def cuff_pressure(t, t0, top, t_inf, hold, rate, dump_at, tau_dump):
    """An oscillometric cuff's pressure without the pulses: from 0 at t0 inflated to `top` in t_inf s (a raised
    cosine), held `hold` s, bled linearly at `rate` V/s down to `dump_at`, then dumped through the valve (exponential,
    tau_dump); returns it and the end of the bleed."""
    t = np.asarray(t, float)
    t1 = t0 + t_inf + hold
    t2 = t1 + (top - dump_at) / rate
    p = np.where(t < t0 + t_inf, top * raised_cosine((t - t0) / t_inf), top)
    p = np.where(t >= t1, top - rate * (t - t1), p)
    p = np.where(t >= t2, dump_at * np.exp(-np.clip(t - t2, 0, None) / tau_dump), p)
    return np.where(t < t0, 0.0, p), t2


def cuff_pulses(t, p, f_hr, phase, map_, w_lo, w_hi, a_max):
    """The arterial pulses the cuff picks up: one beat every 1 / f_hr s (a systolic peak and a dicrotic wave, peak 1),
    scaled by the oscillometric envelope a_max exp(-((p - MAP) / w)^2), w = w_lo below MAP and w_hi above (largest
    where the cuff pressure equals the mean arterial pressure; Posey, Geddes et al., Cardiovasc. Res. Cent. Bull. 8
    (1969) 15; Drzewiecki, Hood & Apple, Ann. Biomed. Eng. 22 (1994) 88); none while the cuff is empty."""
    ph = np.mod(f_hr * np.asarray(t, float) + phase, 1.0)
    beat = np.exp(-((ph - 0.12) / 0.07) ** 2) + 0.4 * np.exp(-((ph - 0.42) / 0.09) ** 2)
    w = np.where(p < map_, w_lo, w_hi)
    return np.where(p > 0, a_max * np.exp(-((p - map_) / w) ** 2) * beat, 0.0)


def plain_hunt(n):
    """The rows of a plain course of Plain Hunt on n bells from rounds back to rounds (2 n changes): the bells in
    pairs swap places, (1 2)(3 4)... and (2 3)(4 5)... alternately, so each bell hunts from the front to the back and
    back (Stedman, *Campanalogia*, 1677; Duckworth & Stedman, *Tintinnalogia*, 1668). Bell 1 is the treble."""
    row = list(range(1, n + 1))
    rows = [row[:]]
    for k in range(2 * n):
        start = 0 if k % 2 == 0 else 1
        for i in range(start, n - 1, 2):
            row[i], row[i + 1] = row[i + 1], row[i]
        rows.append(row[:])
    return rows


#: a bell's partials (hum, prime, tierce, quint, nominal) as multiples of its prime (the strike note), their
#: amplitudes and decay times relative to the hum's; the tuning of a true-harmonic English bell (e.g. Rossing,
#: *Science of Percussion Instruments*, 2000, ch. 13: 0.5, 1, 1.2, 1.5, 2)
BELL_RATIOS = np.array([0.5, 1.0, 1.2, 1.5, 2.0])
BELL_AMPS = np.array([0.5, 0.6, 0.5, 0.25, 1.0])
BELL_DECAYS = np.array([1.0, 0.6, 0.45, 0.35, 0.3])


def bell_strikes(t, rows, interval, primes, tau_hum, attack, phases):
    """Rows rung one blow every `interval` s, with a one-blow pause before every handstroke (odd-numbered) row (an
    open handstroke lead); each blow the bell's five partials from a common attack (a raised cosine of `attack` s),
    each decaying with its time (BELL_DECAYS x tau_hum); phases[bell] its partials' starting phases. Returns the
    signal and the blows' (time, bell)."""
    t = np.asarray(t, float)
    v = np.zeros_like(t)
    blows = []
    tc = 0.0
    for k, row in enumerate(rows):
        if k % 2 == 0 and k > 0:
            tc += interval
        for b in row:
            blows.append((tc, b))
            tc += interval
    for tb, b in blows:
        s = t - tb
        on = s > 0
        if not on.any():
            continue
        ss = s[on]
        env = raised_cosine(ss / attack)
        f = primes[b - 1] * BELL_RATIOS
        part = np.exp(-ss[:, None] / (BELL_DECAYS * tau_hum)) * np.sin(2 * np.pi * f * ss[:, None] + phases[b - 1])
        v[on] += env * (part @ BELL_AMPS)
    return v, blows


def wing_elevation(t, bursts, e_fold, down_frac):
    """A bird's wing elevation in flap-bounding flight (bursts of wingbeats between bounds with the wings folded;
    Tobalske, Peacock & Dial, J. Exp. Biol. 202 (1999) 1725): a burst (start, beats, frequency, amplitude) sweeps
    between +-amplitude as cos(2 pi psi), the downstroke taking `down_frac` of each beat (psi warped), eased in and out
    of the folded level e_fold over half a beat; the wings held folded between the bursts."""
    t = np.asarray(t, float)
    e = np.full_like(t, e_fold)
    for t0, n_b, f, amp in bursts:
        T = n_b / f
        s = t - t0
        on = (s >= 0) & (s <= T)
        ph = np.mod(f * s[on], 1.0)
        psi = np.where(ph < down_frac, ph / (2 * down_frac), 0.5 + (ph - down_frac) / (2 * (1 - down_frac)))
        beat = amp * np.cos(2 * np.pi * psi)
        ease = raised_cosine(2 * f * s[on]) * raised_cosine(2 * f * (T - s[on]))
        e[on] = e_fold + ease * (beat - e_fold)
    return e


def afm_history(contacts, trigger, ramp, park):
    """The z piezo's turning points through an AFM force-volume map (Radmacher et al., Biophys. J. 70 (1996) 556):
    from the virgin state at 0 V, at each point of the grid an approach until the cantilever's deflection reaches the
    trigger (the contact level there plus `trigger`) and a retraction by `ramp`; then to the park level."""
    pts = [0.0]
    for c in contacts:
        pts += [c + trigger, c + trigger - ramp]
    return np.array(pts + [park])


def indentation_path(t, start, lead, peaks, unload, rate, hold_top, hold_low, tail):
    """A nanoindenter's multi-cycle load function with partial unloading (ISO 14577-1; Oliver & Pharr, J. Mater. Res.
    7 (1992) 1564): from `start`, after `lead` s, constant-rate ramps (`rate` V/s) to each peak, a hold of hold_top s
    there, an unloading to unload[i] x the peak, a hold of hold_low s; after the last peak a full unloading to 0 V and
    `tail` s at rest. Returns the path and the knots (time, level)."""
    knots = [(0.0, start), (lead, start)]
    tc, cur = lead, start
    for k, (pk, fr) in enumerate(zip(peaks, unload)):
        low = 0.0 if k == len(peaks) - 1 else fr * pk
        for lv, hd in ((pk, hold_top), (low, hold_low if k < len(peaks) - 1 else tail)):
            tc += abs(lv - cur) / rate
            knots.append((tc, lv))
            tc += hd
            knots.append((tc, lv))
            cur = lv
    kt, kv = np.array(knots).T
    return np.interp(np.asarray(t, float), kt, kv), (kt, kv)


def siphon_drain_time(h, h_on, q, k, H):
    """The time a bell siphon takes to drain its tank from h_on to h against the inflow q: the level obeys h' = q - k
    sqrt(h + H) (Torricelli's law, the outlet H below the tank's floor), so with s = sqrt(h + H) the time is (2 / k)
    ((s_on - s) + (q / k) ln((k s_on - q) / (k s - q)))."""
    s = np.sqrt(np.asarray(h, float) + H)
    s_on = math.sqrt(h_on + H)
    return (2 / k) * ((s_on - s) + (q / k) * np.log((k * s_on - q) / (k * s - q)))


def bell_siphon(t, lead, fills, h_on, h_off, k, H):
    """A tank drained by a bell siphon (an auto-siphon of ebb-and-flow hydroponics): from empty, after `lead` s, it
    fills at fills[i] (level units a second) up to h_on, where the siphon primes and drains it by Torricelli's law
    (solve_ivp, the inflow going on) to h_off, where air breaks the siphon; then it fills again. Returns the level and
    the cycles' (fill start, drain start, drain end)."""
    t = np.asarray(t, float)
    v = np.zeros_like(t)
    tc, lev, cycles = lead, 0.0, []
    for q in fills:
        t_fill = (h_on - lev) / q
        m = (t >= tc) & (t < tc + t_fill)
        v[m] = lev + q * (t[m] - tc)
        td = tc + t_fill

        def rhs(_, y, q=q):
            return [q - k * math.sqrt(max(y[0], 0.0) + H)]

        def low(_, y):
            return y[0] - h_off
        low.terminal, low.direction = True, -1
        sol = solve_ivp(rhs, (0, 60.0), [h_on], events=low, dense_output=True, method="DOP853", rtol=1e-11,
                        atol=1e-12)
        T_d = sol.t_events[0][0]
        m = (t >= td) & (t < td + T_d)
        if m.any():
            v[m] = sol.sol(t[m] - td)[0]
        cycles.append((tc, td, td + T_d))
        tc, lev = td + T_d, h_off
    m = t >= tc
    v[m] = h_off
    return v, cycles


# ---- creep: domain switching with a Lorentzian spectrum of log switching times ----

def nls_prony(tau_m, w, tau_lo=1e-3, tau_hi=1e4, du=0.05):
    """Switching times whose logarithms u = ln tau follow a Lorentzian, (w / pi) / ((u - ln tau_m)^2 + w^2): the
    nucleation-limited switching of a disordered ferroelectric (Tagantsev et al., Phys. Rev. B 66 (2002) 214109; the
    Lorentzian: Jo et al., Phys. Rev. Lett. 99 (2007) 267602), each region relaxing exponentially (the KAI law with n
    = 1). The regions faster than tau_lo are the elastic part (in the core's gain), those slower than tau_hi frozen;
    between, cells of about du in u, each of the Lorentzian's mass in it (arctan differences) at its midpoint. Returns
    the times and weights (summing to under 1)."""
    u0 = math.log(tau_m)
    lo, hi = math.log(tau_lo), math.log(tau_hi)
    edges = np.linspace(lo, hi, int(math.ceil((hi - lo) / du)) + 1)
    mass = np.diff(np.arctan((edges - u0) / w)) / np.pi
    return np.exp((edges[:-1] + edges[1:]) / 2), mass


def nls_compliance(t, tau_m, w, tau_lo=1e-3, tau_hi=1e4):
    """The step response of :func:`nls_prony` (per unit c), the defining integral by the Prony sum."""
    taus, wts = nls_prony(tau_m, w, tau_lo, tau_hi)
    t = np.asarray(t, float)
    return -np.expm1(-np.clip(t, 0, None)[..., None] / taus) @ wts


def nls_creep(h, dt, c, tau_m, w):
    """The creep of a ferroelectric stack by nucleation-limited switching under the core's output h (its
    polarisation's load): c x the Boltzmann superposition of :func:`nls_compliance` (the Kelvin chain of
    :func:`nls_prony`, each element exact for h linear between samples), settled at h[0] at first."""
    taus, wts = nls_prony(tau_m, w)
    return prony_creep(np.asarray(h, float), dt, c, taus, wts)


# ---- rate dependence: a stage braked by eddy currents ----

def wouterse_drag(u, a_c, v_c):
    """The drag (per unit mass) of an eddy-current brake at the speed u: 2 a_c (u / v_c) / (1 + (u / v_c)^2), viscous
    at low speeds, peaking at a_c at the critical speed v_c and falling beyond as the eddy currents' own field expels
    the magnet's (Wouterse, IEE Proc. B 138 (1991) 153)."""
    q = u / v_c
    return 2 * a_c * q / (1 + q * q)


def brake_stage(h, dt, f_n, a_c, v_c, sub=4):
    """A stage (natural frequency f_n) pulled toward the core's output h by its flexure and braked by an eddy-current
    damper: y'' = w^2 (h - y) - drag(y'); classical Runge-Kutta, `sub` steps a sample, h linear between samples;
    from rest at h[0]."""
    h = np.asarray(h, float)
    w2 = (2 * np.pi * f_n) ** 2
    hs = dt / sub
    y, u = float(h[0]), 0.0
    out = np.empty(len(h))
    out[0] = y
    two_a, vc = 2 * a_c, v_c
    for k in range(1, len(h)):
        h0, dh = float(h[k - 1]), float(h[k] - h[k - 1]) / sub
        for j in range(sub):
            ha, hm, hb = h0 + j * dh, h0 + (j + 0.5) * dh, h0 + (j + 1) * dh
            q = u / vc
            a1 = w2 * (ha - y) - two_a * q / (1 + q * q)
            u2, y2 = u + 0.5 * hs * a1, y + 0.5 * hs * u
            q = u2 / vc
            a2 = w2 * (hm - y2) - two_a * q / (1 + q * q)
            u3, y3 = u + 0.5 * hs * a2, y + 0.5 * hs * u2
            q = u3 / vc
            a3 = w2 * (hm - y3) - two_a * q / (1 + q * q)
            u4, y4 = u + hs * a3, y + hs * u3
            q = u4 / vc
            a4 = w2 * (hb - y4) - two_a * q / (1 + q * q)
            y += hs * (u + 2 * u2 + 2 * u3 + u4) / 6
            u += hs * (a1 + 2 * a2 + 2 * a3 + a4) / 6
        out[k] = y
    return out


# ---- offset drift: the cure shrinkage of a UV-curing adhesive ----

def kamal_rhs(t, a, k1, k2, m, n):
    """Kamal & Sourour's autocatalytic cure, da/dt = (k1 + k2 a^m) (1 - a)^n (Polym. Eng. Sci. 13 (1973) 59; used for
    photopolymerisation under constant irradiance, e.g. Maffezzoli & Terzi, Thermochim. Acta 321 (1998) 111)."""
    x = min(max(a[0], 0.0), 1.0)
    return [(k1 + k2 * x ** m) * (1 - x) ** n]


def kamal_cure(t, t_on, k1, k2, m, n):
    """The degree of cure a(t) of an adhesive whose UV lamp is switched on at t_on (0 before; DOP853, rtol 1e-11)."""
    t = np.asarray(t, float)
    a = np.zeros_like(t)
    on = t > t_on
    if on.any():
        sol = solve_ivp(kamal_rhs, (t_on, t[-1]), [0.0], t_eval=t[on], args=(k1, k2, m, n), method="DOP853",
                        rtol=1e-11, atol=1e-13)
        a[on] = sol.y[0]
    return a


def gel_shrinkage(a, a_gel):
    """The share of the final shrinkage that moves the mount: only after the gel point a_gel (before it the resin
    flows and takes up its shrinkage; Flory, *Principles of Polymer Chemistry*, 1953, ch. 9), linear in the cure
    beyond it."""
    return np.clip((np.asarray(a, float) - a_gel) / (1 - a_gel), 0.0, None)


# ---- asymmetry: a tendon's exponential stiffening ----

def fung_force(x, q):
    """The force beyond its preload of a tendon stretched further by x (in units of the stage's stroke): Fung's
    exponential law sigma = A (exp(B eps) - 1) (Fung, Am. J. Physiol. 213 (1967) 1532), so F - F_p = (A + F_p)
    (exp(B x) - 1); scaled to slope 1 at the preload: q (exp(x / q) - 1), q = 1 / B."""
    return q * np.expm1(np.asarray(x, float) / q)


# ---- saturation: a quasi-zero-stiffness isolator ----

def qzs_force(xh, kappa, gamma):
    """The restoring force (over k_v a) of a mount with a vertical spring k_v and two horizontal springs k_o = kappa
    k_v precompressed from their length L0 = gamma a to a (Carrella, Brennan & Waters, J. Sound Vib. 301 (2007)
    678): xh + 2 kappa xh (1 - gamma / sqrt(1 + xh^2)), xh = x / a; soft at the centre (slope 1 + 2 kappa (1 -
    gamma)), stiffening to 1 + 2 kappa outside."""
    xh = np.asarray(xh, float)
    return xh + 2 * kappa * xh * (1 - gamma / np.sqrt(1 + xh * xh))


def qzs_slope(xh, kappa, gamma):
    xh = np.asarray(xh, float)
    return 1 + 2 * kappa * (1 - gamma / (1 + xh * xh) ** 1.5)


def qzs_stage(f, kappa, gamma, iters=60):
    """The deflection xh where :func:`qzs_force` equals f (odd, increasing and convex for xh > 0): Newton from f /
    slope(0), which lies beyond the root, converging monotonically."""
    f = np.asarray(f, float)
    s0 = 1 + 2 * kappa * (1 - gamma)
    x = np.abs(f) / s0
    af = np.abs(f)
    for _ in range(iters):
        x = x - (qzs_force(x, kappa, gamma) - af) / qzs_slope(x, kappa, gamma)
    return np.sign(f) * x


# ---- delay: a strip's transit from a roll gap to a thickness gauge ----

def strip_travel(t, V0, a, f_m, phi):
    """The strip's travel int v dt with the speed V0 (1 + a sin(2 pi f_m t + phi)) (the mill's speed regulator
    hunting slowly)."""
    t = np.asarray(t, float)
    return V0 * (t - a / (2 * np.pi * f_m) * (np.cos(2 * np.pi * f_m * t + phi) - math.cos(phi)))


def strip_transit(t, d, V0, a, f_m, phi, iters=30):
    """The time t_g at which the strip now under the gauge, d downstream, passed the roll gap: travel(t) -
    travel(t_g) = d (Newton; the travel increases); the gauge reads the gap set then (the mass flow's transport delay
    of automatic gauge control: e.g. Ginzburg, *Steel-Rolling Technology*, 1989)."""
    t = np.asarray(t, float)
    target = strip_travel(t, V0, a, f_m, phi) - d
    tg = t - d / V0
    for _ in range(iters):
        tg = tg - (strip_travel(tg, V0, a, f_m, phi) - target) / (V0 * (1 + a * np.sin(2 * np.pi * f_m * tg + phi)))
    return tg


# ---- rate dependence: a base recoiling on its isolators ----

def recoil_matrices(mu, f_iso, zeta):
    """The stage's position over the ground (read by a ground-fixed interferometer) when the actuator's stroke u
    pushes it off a base of mass ratio mu = m_s / (m_s + m_b) floating on isolators (f_iso, zeta): the base obeys
    x_b'' + 2 zeta w x_b' + w^2 x_b = -mu u'' (momentum), so with x_b = -mu u + q the reading is (1 - mu) u + q, q''
    + 2 zeta w q' + w^2 q = mu (2 zeta w u' + w^2 u): returns (A, B, C) of q (input u) and the feed-through 1 - mu
    (e.g. Schmidt, Schitter, Rankers & van Eijk, *The Design of High Performance Mechatronics*, 2014, on reaction
    forces and frames)."""
    w = 2 * np.pi * f_iso
    A = np.array([[0.0, 1.0], [-w * w, -2 * zeta * w]])
    B = np.array([[0.0], [1.0]])
    C = np.array([[mu * w * w, mu * 2 * zeta * w]])
    return A, B, C, 1 - mu


def recoil_reading(u, dt, mu, f_iso, zeta):
    """The ground-fixed reading of :func:`recoil_matrices` for the stroke u linear between samples (exact), the
    base at rest at first."""
    A, B, C, d = recoil_matrices(mu, f_iso, zeta)
    return d * np.asarray(u, float) + foh_response(A, B, C, u, dt)


# ---- out of vocabulary: a shallow arch snapping through under displacement control ----

def mises_force(x, h0, a, k=1.0):
    """The force pressing the apex of a von Mises truss (two bars of stiffness k from supports 2 a apart to an apex
    h0 above them; the lumped model of a shallow arch or a snap dome: von Mises, Z. Angew. Math. Mech. 3 (1923) 406;
    Bazant & Cedolin, *Stability of Structures*, 1991, ch. 2) down by x: 2 k (L0 / L - 1) (h0 - x), L = sqrt(a^2 +
    (h0 - x)^2); it rises to a limit point, falls through 0 where the bars are flat (x = h0), pulls (negative) and
    rises again through 0 at the inverted shape (x = 2 h0)."""
    x = np.asarray(x, float)
    L0 = math.hypot(a, h0)
    L = np.hypot(a, h0 - x)
    return 2 * k * (L0 / L - 1) * (h0 - x)


__all__ = ["turning_points", "prony_creep", "grid", "plays", "exp_plays", "foh_response", "raised_cosine",
           "rice_plays", "chua_rhs", "chua_x", "lift_trip", "lift_path", "lognormal_progress", "sigma_lognormal_y",
           "sigma_lognormal_vy", "engine_speed", "engine_angle", "piston_x", "hindmarsh_rose_rhs",
           "hindmarsh_rose_x", "cuff_pressure", "cuff_pulses", "plain_hunt", "BELL_RATIOS", "BELL_AMPS",
           "BELL_DECAYS", "bell_strikes", "wing_elevation", "afm_history", "indentation_path", "siphon_drain_time",
           "bell_siphon", "nls_prony", "nls_compliance", "nls_creep", "wouterse_drag", "brake_stage", "kamal_rhs",
           "kamal_cure", "gel_shrinkage", "fung_force", "qzs_force", "qzs_slope", "qzs_stage", "strip_travel",
           "strip_transit", "recoil_matrices", "recoil_reading", "mises_force"]

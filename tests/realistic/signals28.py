"""Excitations of the HOLDOUT28 set (``cases_holdout28.py``), each beside its source; the mechanisms are in
:mod:`.mechanisms28`. Citations written from memory in this session (none was re-read), as in mechanisms28.
"""

import math

import numpy as np
from scipy.integrate import solve_ivp
from scipy.special import ellipj, ellipk

from .mechanisms19 import raised_cosine


def min_jerk(s):
    """The minimum-jerk profile 10 s^3 - 15 s^4 + 6 s^5 on 0 ... 1 (Flash & Hogan, J. Neurosci. 5 (1985) 1688),
    clipped outside."""
    s = np.clip(np.asarray(s, float), 0.0, 1.0)
    return s ** 3 * (10 - 15 * s + 6 * s * s)


# ---- clean: the tip of a heavy symmetric top's axis (Lagrange's top) ----

def top_rhs(tau, s, b, p_phi):
    """Lagrange's heavy symmetric top (I1 = 1, M g l = 1, the spin's momentum I3 w3 = b; Goldstein, *Classical
    Mechanics*, 1980, sec. 5.7): s = (theta, theta', phi), theta from the upward vertical; phi' = (p_phi - b cos theta) /
    sin^2 theta, theta'' = phi'^2 sin cos - b phi' sin + sin."""
    th, thd, _ = s
    sn, cs = math.sin(th), math.cos(th)
    phd = (p_phi - b * cs) / (sn * sn)
    return [thd, phd * phd * sn * cs - b * phd * sn + sn, phd]


def lagrange_top(t, speed, b, theta0, phidot0):
    """The x of the top's axis, sin(theta) cos(phi), released at theta0 with theta' = 0 and phi' = phidot0 at phi =
    pi / 2 (so x starts at 0): precessing slowly (about 1 / b a time unit) with nutation loops (at about b), played
    ``speed`` time units a second (DOP853, rtol 1e-11). Returns x and the states (theta, theta', phi)."""
    p_phi = phidot0 * math.sin(theta0) ** 2 + b * math.cos(theta0)
    tau = np.asarray(t, float) * speed
    sol = solve_ivp(top_rhs, (0.0, tau[-1]), [theta0, 0.0, math.pi / 2], t_eval=tau, method="DOP853", rtol=1e-11,
                    atol=1e-12, args=(b, p_phi))
    th, ph = sol.y[0], sol.y[2]
    x = np.sin(th) * np.cos(ph)
    x[0] = 0.0
    return x, sol.y


# ---- creep: the load on the target peg of a robot solving the Tower of Hanoi ----

def hanoi_moves(n, src=0, dst=2, via=1):
    """The 2^n - 1 moves (disk, from, to) of the recursive solution (Lucas, 1883), disk 1 the smallest."""
    if n == 0:
        return []
    return hanoi_moves(n - 1, src, via, dst) + [(n, src, dst)] + hanoi_moves(n - 1, via, dst, src)


def hanoi_load(t, t0, moves, weights, move_s, dwells, lift_s, peg=2):
    """The load on one peg: every move lifts its disk off its peg over the first lift_s of the move and sets it down
    over the last lift_s (raised cosines), the moves move_s long with the dwells between. Returns the load and the
    moves' start times."""
    t = np.asarray(t, float)
    out = np.zeros_like(t)
    starts, tc = [], t0
    for (d, a, b), dw in zip(moves, dwells):
        starts.append(tc)
        if a == peg:
            out -= weights[d - 1] * raised_cosine((t - tc) / lift_s)
        if b == peg:
            out += weights[d - 1] * raised_cosine((t - (tc + move_s - lift_s)) / lift_s)
        tc += move_s + dw
    return out, starts


# ---- rate dependence: a cellist's bow ----

def trapezoid_profile(s, r):
    """The position 0 ... 1 of a move whose speed rises over the fraction r of it as a raised cosine, stays, and falls
    over the last r (s in 0 ... 1)."""
    s = np.clip(np.asarray(s, float), 0.0, 1.0)
    V = 1.0 / (1.0 - r)

    def up(q):
        return V * (q / 2 - r / (2 * math.pi) * np.sin(math.pi * q / r))
    return np.where(s < r, up(s), np.where(s > 1 - r, 1.0 - up(1.0 - s), V * (r / 2 + (s - r))))


def bow_path(t, strokes, x_start=0.0):
    """The bow's position along its length: strokes (t0, T, x0, x1, r) each by :func:`trapezoid_profile`, the bow held
    between them (on the string, or lifted at a phrase's end)."""
    t = np.asarray(t, float)
    x = np.full_like(t, x_start)
    for t0, T, x0, x1, r in strokes:
        m = t >= t0
        x[m] = x0 + (x1 - x0) * trapezoid_profile((t[m] - t0) / T, r)
    return x


# ---- drift: Newton's cradle ----

def pendulum_release(tau, w0, theta0):
    """The exact pendulum theta'' = -w0^2 sin(theta) released from rest at theta0 > 0: theta = 2 asin(k sn(K - w0 tau |
    k^2)), k = sin(theta0 / 2), K = K(k^2) (Jacobi; e.g. Lawden, *Elliptic Functions and Applications*, 1989)."""
    m = math.sin(theta0 / 2) ** 2
    K = float(ellipk(m))
    sn = ellipj(K - w0 * np.asarray(tau, float), m)[0]
    return 2 * np.arcsin(math.sqrt(m) * sn)


def cradle_path(t, sessions, w0, e):
    """The horizontal place (in rod lengths, sin theta) of the moving end ball of Newton's cradle (Mariotte 1671; the
    desk toy of 1967): per session (t_pull, pull_s, hold_s, theta0, side, n_imp) the end ball on ``side`` (-1: left) is
    pulled out to theta0 by a raised cosine, held and released; it swings down (a quarter of its exact swing), strikes,
    and the ball at the other end leaves with e times its speed (sin(theta / 2) scaled by e), swings out and back (half
    its own exact period), strikes, and so on for n_imp impacts; the last ball back stops at the bottom (caught).
    Returns x and the impacts' times."""
    t = np.asarray(t, float)
    x = np.zeros_like(t)
    impacts = []
    for t_pull, pull_s, hold_s, theta0, side, n_imp in sessions:
        m = (t >= t_pull) & (t < t_pull + pull_s + hold_s)
        x[m] = side * math.sin(theta0) * raised_cosine((t[m] - t_pull) / pull_s)
        t_rel = t_pull + pull_s + hold_s
        K = float(ellipk(math.sin(theta0 / 2) ** 2))
        t_imp = t_rel + K / w0
        m = (t >= t_rel) & (t < t_imp)
        x[m] = side * np.sin(pendulum_release(t[m] - t_rel, w0, theta0))
        impacts.append(t_imp)
        k = math.sin(theta0 / 2)
        s = -side
        for j in range(n_imp - 1):
            k *= e
            Kj = float(ellipk(k * k))
            t_end = t_imp + 2 * Kj / w0
            m = (t >= t_imp) & (t < t_end)
            # out and back: theta(tau) = 2 asin(k sn(w0 tau)), the release from theta at the far end mirrored
            x[m] = s * np.sin(2 * np.arcsin(k * ellipj(w0 * (t[m] - t_imp), k * k)[0]))
            impacts.append(t_end)
            t_imp = t_end
            s = -s
    return x, impacts


# ---- asymmetry: one ball of a juggler's three-ball cascade ----

def cascade_path(t, sessions, a, x_start=0.0):
    """The horizontal place of one ball of a three-ball cascade (Shannon's juggling theorem (F + D) H = (V + D) N; e.g.
    Beek & Lewbel, Sci. Am. 273 (1995) 92), in units of the catch's distance from the centre: per session (t0, F, D,
    n_throws, start_side) the ball, held at the inner point -+a, is thrown across (a straight line in x at a constant
    speed over the flight F), caught at the other side's outer point +-1 and carried inward to +-a along a raised
    cosine over the dwell D, thrown back, and so on; after the last catch it is carried in and held. Before the first
    session the ball is moved from x_start to the first inner point over 0.5 s."""
    t = np.asarray(t, float)
    x = np.full_like(t, x_start)
    prev = x_start
    for t0, F, D, n_thr, side in sessions:
        xi = side * a
        m = (t >= t0 - 0.5) & (t < t0)
        x[m] = prev + (xi - prev) * raised_cosine((t[m] - (t0 - 0.5)) / 0.5)
        tc, cur = t0, xi
        for _ in range(n_thr):
            xo = -math.copysign(1.0, cur)
            m = (t >= tc) & (t < tc + F)
            x[m] = cur + (xo - cur) * (t[m] - tc) / F
            tc += F
            xn = xo * a
            m = (t >= tc) & (t < tc + D)
            x[m] = xo + (xn - xo) * raised_cosine((t[m] - tc) / D)
            tc += D
            cur = xn
        x[t >= tc] = cur
        prev = cur
    return x


# ---- saturation: a golfer's club through swings ----

def golf_path(t, swings):
    """The club shaft's angle in the swing plane (0 at address): per swing (t0, top, fin, T_back, T_top, T_down, T_hold,
    T_ret) a minimum-jerk backswing to -top, a pause at the top, a downswing -top cos(pi s / 2) (fastest at impact),
    a follow-through fin sin(pi s / 2) over T_down fin / top (the speed continuous through impact), the finish held,
    and a minimum-jerk return to address (e.g. Jorgensen, *The Physics of Golf*, 1994, for the downswing's timing)."""
    t = np.asarray(t, float)
    x = np.zeros_like(t)
    for t0, top, fin, Tb, Tt, Td, Th, Tr in swings:
        t1 = t0 + Tb
        t2 = t1 + Tt
        t3 = t2 + Td
        Tf = Td * fin / top
        t4 = t3 + Tf
        t5 = t4 + Th
        t6 = t5 + Tr
        m = (t >= t0) & (t < t1)
        x[m] = -top * min_jerk((t[m] - t0) / Tb)
        x[(t >= t1) & (t < t2)] = -top
        m = (t >= t2) & (t < t3)
        x[m] = -top * np.cos(math.pi / 2 * (t[m] - t2) / Td)
        m = (t >= t3) & (t < t4)
        x[m] = fin * np.sin(math.pi / 2 * (t[m] - t3) / Tf)
        x[(t >= t4) & (t < t5)] = fin
        m = (t >= t5) & (t < t6)
        x[m] = fin * (1 - min_jerk((t[m] - t5) / Tr))
    return x


def swing_end(sw):
    """The time a swing of :func:`golf_path` ends."""
    t0, top, fin, Tb, Tt, Td, Th, Tr = sw
    return t0 + Tb + Tt + Td + Td * fin / top + Th + Tr


# ---- delay: an infrared remote control's frames (NEC protocol) ----

def nec_marks(address, command, n_repeats, t0=0.0):
    """The marks (start, end) in units of 562.5 us of NEC's infrared protocol (as remembered): a leader mark of 16
    units and a space of 8; 32 bits, least significant first, of the address, its complement, the command and its
    complement, each a mark of 1 unit and a space of 1 (a 0) or 3 (a 1); a stop mark; then repeat codes every 192
    units (108 ms) from the frame's start (a mark of 16, a space of 4, a mark of 1)."""
    marks = [(t0, t0 + 16)]
    tc = t0 + 24
    word = [(address >> i) & 1 for i in range(8)] + [((~address) >> i) & 1 for i in range(8)]
    word += [(command >> i) & 1 for i in range(8)] + [((~command) >> i) & 1 for i in range(8)]
    for bit in word:
        marks.append((tc, tc + 1))
        tc += 2 + 2 * bit
    marks.append((tc, tc + 1))
    for r in range(1, n_repeats + 1):
        ts = t0 + 192 * r
        marks += [(ts, ts + 16), (ts + 20, ts + 21)]
    return marks, word


def marks_path(t, marks, unit, edge):
    """Marks as raised-cosine pulses of height 1 (each edge ``edge`` s long, starting at the mark's edges)."""
    t = np.asarray(t, float)
    x = np.zeros_like(t)
    for a, b in marks:
        x += raised_cosine((t - a * unit) / edge) - raised_cosine((t - b * unit) / edge)
    return x


# ---- initial state: a pole-vault competition ----

def vault_path(t, L0, vaults, r_mat=0.3):
    """The vaulter's centre of mass (run-up level L0): per vault (t0, run, dip, apex, mat, T_rise, T_fall, T_lie,
    T_back): the approach at L0, the pole's plant dipping it by ``dip`` over 0.15 s, the swing and extension up to the
    apex (minimum jerk over T_rise), a free fall from rest (quadratic in time over T_fall), the mat's deceleration
    (uniform, over r_mat T_fall, to rest at ``mat``), lying there T_lie, and a walk back to L0 (minimum jerk over
    T_back)."""
    t = np.asarray(t, float)
    x = np.full_like(t, L0)
    for t0, run, dip, apex, mat, Tr, Tf, Tl, Tb in vaults:
        t1 = t0 + run
        t2 = t1 + 0.15
        t3 = t2 + Tr
        t4 = t3 + Tf
        Tm = r_mat * Tf
        t5 = t4 + Tm
        t6 = t5 + Tl
        t7 = t6 + Tb
        h_land = (mat + apex * r_mat) / (1 + r_mat)
        v_l = 2 * (apex - h_land) / Tf
        m = (t >= t1) & (t < t2)
        x[m] = L0 - dip * min_jerk((t[m] - t1) / 0.15)
        m = (t >= t2) & (t < t3)
        x[m] = L0 - dip + (apex - L0 + dip) * min_jerk((t[m] - t2) / Tr)
        m = (t >= t3) & (t < t4)
        x[m] = apex - (apex - h_land) * ((t[m] - t3) / Tf) ** 2
        m = (t >= t4) & (t < t5)
        q = t[m] - t4
        x[m] = h_land - v_l * q + v_l / (2 * Tm) * q * q
        x[(t >= t5) & (t < t6)] = mat
        m = (t >= t6) & (t < t7)
        x[m] = mat + (L0 - mat) * min_jerk((t[m] - t6) / Tb)
    return x


def vault_end(v, r_mat=0.3):
    t0, run, dip, apex, mat, Tr, Tf, Tl, Tb = v
    return t0 + run + 0.15 + Tr + Tf * (1 + r_mat) + Tl + Tb


# ---- pair: a swinging-ship fairground ride ----

def ride_rhs(t, s, w0, zeta, U, eps):
    """theta'' + 2 zeta w0 theta' + w0^2 sin(theta) = U tanh(theta' / eps): the ship's pendulum pushed along its swing
    by the drive tyre's torque (U > 0 pumping, U < 0 braking; tanh a smooth slip)."""
    th, om = s
    return [om, -2 * zeta * w0 * om - w0 * w0 * math.sin(th) + U * math.tanh(om / eps)]


def ride_path(t, t_on, w0, zeta, U_p, U_b, target, coast_s, eps=0.05):
    """A swinging-ship ride: at rest until t_on, pumped (a tiny initial push) until its swing first reaches ``target``
    rad, coasting coast_s, braked until it swings under 0.03 rad, then coasting to rest (DOP853, rtol 1e-10, phase by
    phase). Returns theta and the phases' switching times."""
    t = np.asarray(t, float)
    th = np.zeros_like(t)
    phases = []
    s0, tc = [0.0, 1e-3], t_on
    t_end = t[-1]

    def hit(tt, s, *a):
        return abs(s[0]) - target
    hit.terminal = True

    def calm(tt, s, *a):
        return 0.5 * s[1] ** 2 / (w0 * w0) + (1 - math.cos(s[0])) - (1 - math.cos(0.03))
    calm.terminal = True
    calm.direction = -1
    plan = [(U_p, hit, None), (0.0, None, coast_s), (-U_b, calm, None), (0.0, None, None)]
    for U, ev, dur in plan:
        t1 = t_end if dur is None else min(tc + dur, t_end)
        if tc >= t_end:
            break
        sol = solve_ivp(ride_rhs, (tc, t1), s0, method="DOP853", rtol=1e-10, atol=1e-12, dense_output=True,
                        events=ev, args=(w0, zeta, U, eps))
        te = sol.t[-1]
        m = (t >= tc) & (t <= te)
        th[m] = sol.sol(t[m])[0]
        phases.append((tc, te, U))
        s0, tc = list(sol.y[:, -1]), te
    return th, phases


# ---- out of vocabulary: a music box's cylinder ----

def music_box(t, notes, t_rev, n_rev, damp):
    """A music box's comb (Swiss, 1796): every note (onset within the revolution, frequency, amplitude, decay, length)
    a plucked tine's decaying sine a sin(2 pi f s) exp(-s / tau), damped out by a raised cosine over its last ``damp``
    s (the next pin's damper), repeated every revolution t_rev of the cylinder, n_rev times."""
    t = np.asarray(t, float)
    x = np.zeros_like(t)
    for r in range(n_rev):
        for on, f, a, tau, dur in notes:
            t0 = r * t_rev + on
            m = (t >= t0) & (t < t0 + dur)
            s = t[m] - t0
            x[m] += a * np.sin(2 * np.pi * f * s) * np.exp(-s / tau) * (1 - raised_cosine((s - (dur - damp)) / damp))
    return x

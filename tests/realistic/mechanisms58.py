"""Mechanisms of the HOLDOUT58 set (``cases_holdout58.py``), each written from its law; the signals are in
:mod:`.signals58`.

Nothing here imports hystcomp (nor another set's mechanisms but the Kronecker sequence ``r2_points`` of HOLDOUT52's and
the exact relaxation step ``relax`` of HOLDOUT50's, imported). Every mechanism takes the drive (or the force it sets,
or the stage's travel) and returns the response; all are causal.

Citations: every source below was written from memory in this session (none was re-read); volumes, pages and years may
be off, and so may the constants quoted (typical values as remembered, not a datasheet's). The laws do not rest on them:
each is checked in tests/test_realistic_holdout58.py against an independent solution (the beams' branches by numpy's
roots of the cubic and their states by the last threshold the travel crossed, the stage's balance by its residual and
brentq, the rest state by an explicit decaying dither, the flexure's arms by solve_ivp, the damped beams by solve_ivp,
the enclosure's air by its exponentials written out and solve_ivp, the converter's filter by a direct sum, the link's
delay written out, the detector from its phasors, and finer grids).
"""

import math

import numpy as np
from numba import njit
from scipy.special import ndtri

from .mechanisms50 import relax  # y relaxing toward x with a time constant, exact per step
from .mechanisms52 import r2_points  # the three-dimensional R2 (Kronecker) sequence

# ---- the rate-independent core: a voice-coil stage pressing a chip of bistable buckled beams ----
#
# The actuator is a multistable "metamaterial" stage: a moving-coil (voice-coil) motor on a flexure guide (its return
# stiffness K) pushes a shuttle that presses, each through its own soft serpentine spring (k_s), the middles of N_BEAMS
# = 400 pre-buckled silicon beams on a MEMS chip (a bistable-beam array, as in the bistable MEMS switches and the
# multistable mechanical memories; Vangbo, Sens. Actuators A 69 (1998) 212, for the buckled beam's snap; Qiu, Lang &
# Slocum, J. MEMS 13 (2004) 137, for curved bistable beams; Puglisi & Truskinovsky, J. Mech. Phys. Solids 48 (2000) 1,
# for bistable elements in parallel under a soft device; all as remembered). A capacitive gauge reads the shuttle's
# travel x (um, zeroed at the start of every record). The coil's force is the drive's (a transconductance amplifier:
# the current and the Lorentz force B l i linear in the drive).
#
# * A beam buckled to the amplitude a (its first mode's Galerkin reduction: the axial stretching's cubic; Vangbo's
#   model as remembered) resists its middle's deflection w with f(w) = k (w^3 / a^2 - w) - b: stable at about +-a, a
#   negative stiffness -k through its middle, b the force of its imperfection (the etch leaves it bowed a little to one
#   side). Pressed through its spring, k_s (x - w) = f(w): in omega = w / a, xi = x / a, kappa = k_s / k and beta = b /
#   (k a), omega^3 - (1 - kappa) omega - (kappa xi + beta) = 0. With kappa < 1 (a soft spring) the beam has two stable
#   branches (the roots below -omega_s and above omega_s, omega_s = sqrt((1 - kappa) / 3)) while |kappa xi + beta| <=
#   q_c = 2 ((1 - kappa) / 3)^(3/2); it snaps up where kappa xi + beta passes q_c and down where it passes -q_c (each
#   branch's fold): a hysteron with reversible branches (Cardano's trigonometric roots), rate independent (the snap
#   takes microseconds in air).
# * The beams differ (the chip's process spread, a choice of laws): their amplitudes a log-normal (median a_50 7.5 ...
#   8.5 um, log spread 0.1), their thicknesses uniform within +-12 % (kappa = kappa_50 (t_50 / t)^3, kappa_50 0.28 ...
#   0.32), their imperfections normal (beta's spread s_b 0.22 ... 0.28). N_BEAMS classes on a three-dimensional R2
#   sequence over the three quantiles, shifted by the core's seed.
# * The shuttle's balance (quasi-static: its resonance some 300 Hz, far above the programmes' moves): F = K x + k_s
#   sum_i (x - w_i), so x = u + rho mean_i(w_i), u = F / (K + N k_s) = g v (g 0.22 um a volt of the drive; on the
#   unipolar records u = g (v - 47): the drive's 0 V is the stage pulled back), rho = N k_s / (K + N k_s) = 0.3 (a
#   choice). The beams share x: a beam's snap moves the shuttle and may snap others (an avalanche); the shared travel's
#   feedback is positive (ferromagnetic), so the balance keeps return-point memory (Sethna et al., Phys. Rev. Lett. 70
#   (1993) 3347, no-passing, as remembered). Solved by Newton's method on the balance from the last sample's travel
#   (its steps never passing the root: the balance is convex or concave toward it, checked), the beams' branches
#   switching where their folds are passed.
#
# Rate independent, with return-point memory; close to a Prandtl-Ishlinskii model but not one (measured in the test and
# stated there): the beams' snaps are a Preisach density whose widths and centres move together with a / kappa (not a
# uniform density of centres times one of widths), their branches curve (a cube root's), and the avalanches shear it.
#
# The rest state: before every record but the initial-state case's the controller's conditioning routine dithers the
# stage about the drive's 0 V with a slowly decaying amplitude; its limit leaves every beam up whose loop's middle (its
# snap points' mean in x) lies below the stage's travel there and down otherwise, the travel at the balance with them:
# the state is set so, not run (checked in the test against an explicit decaying dither).

N_BEAMS = 400
A_SPREAD = 0.1
T_SPREAD = 0.12
RHO = 0.3
GAIN = 0.22
V_MID = 47.0
NEWTON_TOL = 1e-11


def beams(core):
    """The core's beams: (kappa, beta, a (um)) of N_BEAMS classes, from the core's seed."""
    shift = np.random.default_rng(core["rseed"]).uniform(size=3)
    u = np.clip(r2_points(N_BEAMS, shift), 1e-12, 1.0 - 1e-12)
    kap = core["kap50"] * (1.0 + T_SPREAD * (2.0 * u[:, 0] - 1.0)) ** -3
    bet = core["sb"] * ndtri(u[:, 1])
    a = core["a50"] * np.exp(A_SPREAD * ndtri(u[:, 2]))
    return kap, bet, a


def snap_points(core):
    """Every beam's snap points in the travel x (um): (up, down), a (+-h(kappa) - beta / kappa), h = q_c / kappa."""
    kap, bet, a = beams(core)
    h = 2.0 * ((1.0 - kap) / 3.0) ** 1.5 / kap
    return a * (h - bet / kap), a * (-h - bet / kap)


def force_travel(core, v):
    """The coil's force as a travel, u = g v (um; on the unipolar records g (v - 47))."""
    v = np.asarray(v, float)
    return GAIN * (v - V_MID if core["unipolar"] else v)


@njit(cache=True)
def _beams_at(x, kap, bet, a, s):
    """The beams' mean deflection (um) and its slope in x at the travel x, their branches s switched where a fold is
    passed (s updated in place)."""
    m = kap.shape[0]
    tot = 0.0
    dtot = 0.0
    for k in range(m):
        p = 1.0 - kap[k]
        q = kap[k] * x / a[k] + bet[k]
        qc = 2.0 * (p / 3.0) ** 1.5
        r = 2.0 * math.sqrt(p / 3.0)
        if q > qc:
            s[k] = 1.0
        elif q < -qc:
            s[k] = 0.0
        if abs(q) <= qc:
            th = math.acos(max(-1.0, min(1.0, q / qc))) / 3.0
            w = r * math.cos(th) if s[k] > 0.5 else r * math.cos(th + 2.0 * math.pi / 3.0)
        else:
            w = math.copysign(r * math.cosh(math.acosh(abs(q) / qc) / 3.0), q)
        tot += a[k] * w
        den = 3.0 * w * w - p
        dtot += kap[k] / den if den > 1e-9 else 1e9
    return tot / m, dtot / m


@njit(cache=True)
def _stage(u, dt, rho, kap, bet, a, s, x0, phi, tau, mu, xc, ix2, xo):
    """The shuttle's travel on the samples of u: the balance x (D + mu [x < xc]) - mu xc [x < xc] - u b(x) - rho
    wbar(x) + c = 0, b(x) = 1 - ix2 (x - xo)^2 the coil's force factor, D and c from the flexure's relaxing arms
    (fractions phi, times tau; exact per step for x linear between samples), solved by Newton from the last travel."""
    n = u.shape[0]
    nm = phi.shape[0]
    out = np.empty(n)
    z = np.full(nm, x0)
    xp = x0
    A = np.zeros(nm)
    W = np.zeros(nm)
    for i in range(n):
        D = 1.0
        c = 0.0
        for m in range(nm):
            r = dt / tau[m]
            e = math.exp(-r)
            W[m] = (1.0 - e) / r
            A[m] = (xp - z[m]) * e
            D += phi[m] * W[m]
            c += phi[m] * (A[m] - xp * W[m])
        x = xp
        for it in range(200):
            wb, dw = _beams_at(x, kap, bet, a, s)
            on = 1.0 if x < xc else 0.0
            b = 1.0 - ix2 * (x - xo) ** 2
            G = x * (D + mu * on) - mu * xc * on - u[i] * b - rho * wb + c
            dG = D + mu * on + u[i] * 2.0 * ix2 * (x - xo) - rho * dw
            dG = max(dG, 0.2 * D)
            step = G / dG
            if abs(step) < NEWTON_TOL:
                break
            x -= step
        _beams_at(x, kap, bet, a, s)
        for m in range(nm):
            z[m] = x - (A[m] + (x - xp) * W[m])
        out[i] = x
        xp = x
    return out


NO_ARMS = np.zeros(0)


def balance_at(core, u0, s, b=1.0):
    """The travel x (um) at the force u0 with the beams in the branches s (kept): the fixed point of x = u0 b + rho
    wbar(x), iterated (the branches s updated where a fold is passed)."""
    kap, bet, a = beams(core)
    x = u0 * b
    for _ in range(200):
        wb, _ = _beams_at(x, kap, bet, a, s)
        x_new = u0 * b + RHO * wb
        if abs(x_new - x) < 1e-13:
            return x_new
        x = x_new
    return x


def rest_state(core, u0=None):
    """The conditioning's limit at the force u0 (default the drive's 0 V): every beam up (1) whose snap points' middle
    lies below the travel there, the travel at the balance with them (iterated to a fixed point). Returns (s, x0)."""
    u0 = float(force_travel(core, np.zeros(1))[0]) if u0 is None else u0
    up, dn = snap_points(core)
    mid = 0.5 * (up + dn)
    x0 = u0
    for _ in range(100):
        s = (mid < x0).astype(float)
        x_new = balance_at(core, u0, s.copy())
        if x_new == x0:
            break
        x0 = x_new
    s = (mid < x0).astype(float)
    return s, balance_at(core, u0, s.copy())


def travel(core, u, s=None, x0=None, dt=1e-3, phi=NO_ARMS, tau=NO_ARMS, mu=0.0, xc=-1e300, ix2=0.0, xo=0.0):
    """The shuttle's travel (um, not zeroed) for the force travel u, from the branches s at the travel x0 (default the
    rest state; s updated in place when given)."""
    kap, bet, a = beams(core)
    if s is None:
        s, x0 = rest_state(core)
    elif x0 is None:
        x0 = balance_at(core, float(u[0]), s.copy())
    return _stage(np.asarray(u, float), dt, RHO, kap, bet, a, s, x0, np.asarray(phi, float), np.asarray(tau, float),
                  mu, xc, ix2, xo)


def core_reading(core, v, s=None, x0=None):
    """The rate-independent stage's reading (um, zeroed at the first sample) for the drive v."""
    x = travel(core, force_travel(core, v), s, x0)
    return x - x[0]


# ---- creep: the flexure guide's polymer hinges relaxing (a generalised Maxwell solid) ----
#
# The creep record's stage had its steel flexure guide replaced by one printed in an acetal (POM) copolymer. A polymer's
# stiffness relaxes: its force is a generalised Maxwell (Wiechert) solid's, K_inf x + sum_m K_m (x - z_m), each arm's
# dashpot letting its spring's stretch relax, tau_m z_m' = x - z_m (Wiechert 1893; Findley, Lai & Onaran 1976, as
# remembered; two arms: tau_1 1.5 ... 3 s and tau_2 15 ... 30 s, their stiffnesses phi_1 0.06 ... 0.09 and phi_2 0.08
# ... 0.12 of K + N k_s: a choice for an acetal at room temperature). Under a held force the flexure softens and the
# shuttle creeps on toward the force, a second and then half a minute later; after a fall it creeps back (labelled
# "creep"). The arms exact per step for x linear between samples (the relaxation step of HOLDOUT50), the balance with
# them solved per sample; the arms relaxed at the start (the stage long at rest).

# ---- rate dependence: the chip under silicone oil ----
#
# The rate record's chip and shuttle are immersed in a silicone oil (as damped MEMS arrays are, to kill the snaps'
# ringing). A beam's middle moves against the oil's squeeze film with a viscous force eta w' (overdamped: its mass's
# time against it some microseconds), eta w' = k_s (x - w) - f(w): tau omega' = kappa (xi - omega) - (omega^3 - omega -
# beta), tau = eta / k (tau_50 0.1 ... 0.15 s for the median beam, a viscous oil of some 5e4 cSt; tau = tau_50 kappa /
# kappa_50 for the others: the same oil, stiffer beams quicker). The shuttle's plate shears the oil in its guide's gap
# (Couette drag c x'): c x' = F - K x - k_s sum (x - w_i), tau_s x' = u + rho mean(w) - x, tau_s = c / (K + N k_s) 15
# ... 25 ms. The snaps take a few tau, the folds are passed late (a delayed bifurcation), the shuttle lags its force,
# and the loop widens with the drive's speed (labelled "rate_dependence"). Stepped by RK4 on SUB_RATE sub-steps a sample
# (the force linear between the samples' sub-steps); from the rest state (its branches' roots and its travel).

SUB_RATE = 4


@njit(cache=True)
def _oil_rhs(st, u, rho, kap, bet, a, tau, tau_s, out):
    """The damped system's rates: st = (omega_1 ... omega_m, x); returns nothing (out filled)."""
    m = kap.shape[0]
    x = st[m]
    wb = 0.0
    for k in range(m):
        wb += a[k] * st[k]
        w = st[k]
        out[k] = (kap[k] * (x / a[k] - w) - (w * w * w - w - bet[k])) / tau[k]
    out[m] = (u + rho * wb / m - x) / tau_s


@njit(cache=True)
def _oil(u_fine, h, sub, rho, kap, bet, a, tau, tau_s, st):
    """RK4 of the damped beams and shuttle (st in and out) on the sub-steps h of u_fine; the travel at every sub-th
    sub-step."""
    nf = u_fine.shape[0]
    m = st.shape[0]
    k1, k2, k3, k4, tmp = np.empty(m), np.empty(m), np.empty(m), np.empty(m), np.empty(m)
    out = np.empty((nf - 1) // sub + 1)
    out[0] = st[m - 1]
    for j in range(nf - 1):
        u0, u1 = u_fine[j], u_fine[j + 1]
        um = 0.5 * (u0 + u1)
        _oil_rhs(st, u0, rho, kap, bet, a, tau, tau_s, k1)
        for k in range(m):
            tmp[k] = st[k] + 0.5 * h * k1[k]
        _oil_rhs(tmp, um, rho, kap, bet, a, tau, tau_s, k2)
        for k in range(m):
            tmp[k] = st[k] + 0.5 * h * k2[k]
        _oil_rhs(tmp, um, rho, kap, bet, a, tau, tau_s, k3)
        for k in range(m):
            tmp[k] = st[k] + h * k3[k]
        _oil_rhs(tmp, u1, rho, kap, bet, a, tau, tau_s, k4)
        for k in range(m):
            st[k] += h * (k1[k] + 2.0 * k2[k] + 2.0 * k3[k] + k4[k]) / 6.0
        if (j + 1) % sub == 0:
            out[(j + 1) // sub] = st[m - 1]
    return out


def branch_roots(core, x, s):
    """Every beam's deflection over its a (omega) at the travel x on the branches s (s not changed)."""
    kap, bet, a = beams(core)
    p = 1.0 - kap
    q = kap * x / a + bet
    qc = 2.0 * (p / 3.0) ** 1.5
    r = 2.0 * np.sqrt(p / 3.0)
    th = np.arccos(np.clip(q / qc, -1.0, 1.0)) / 3.0
    inside = np.where(s > 0.5, r * np.cos(th), r * np.cos(th + 2.0 * math.pi / 3.0))
    outside = np.sign(q) * r * np.cosh(np.arccosh(np.maximum(np.abs(q) / qc, 1.0)) / 3.0)
    return np.where(np.abs(q) <= qc, inside, outside)


def oil_travel(core, u_fine, h, tau50, tau_s, sub=SUB_RATE):
    """The shuttle's travel (um) on the samples with the beams (tau = tau50 kappa / kappa_50) and the shuttle (tau_s)
    damped by the oil, from the rest state."""
    kap, bet, a = beams(core)
    s, x0 = rest_state(core)
    st = np.r_[branch_roots(core, x0, s), x0]
    tau = tau50 * kap / core["kap50"]
    return _oil(np.asarray(u_fine, float), h, sub, RHO, kap, bet, a, tau, tau_s, st)


# ---- drift: the enclosure's thermostat cycling the gauge's bracket ----
#
# The drift record's stage stands in a small heated enclosure (a draught shield, held above the room by a heater under
# an on-off thermostat with a dead band: Newton's cooling of the air toward the room with its time tau_a 40 ... 70 s,
# the heater lifting its steady temperature by Delta_h 4 ... 6 K above the set point's 2 K over the room; the thermostat
# switching on at the set point's -db / 2 and off at +db / 2, db 1.6 ... 2.4 K: a limit cycle of exponential arcs, some
# one to two minutes). The gauge's aluminium bracket (a column, L 80 ... 120 mm, 23e-6 / K) follows the air with its own
# time constant tau_b 8 ... 15 s (exact per step for the air linear between 0.05 s steps) and carries the gauge away
# from the shuttle as it warms: the reading falls by alpha L (T_b - T_b(0)) (labelled "drift"). The thermostat ran 600 s
# before the record from the set point: it is in its limit cycle.

H_AIR = 0.05


def thermostat(t_end, lead, tau_a, dh, db, h=H_AIR):
    """The enclosure's air (K about the set point) on steps h from -lead: heater on, T -> T_on = -2 + dh; off, T -> -2
    (the room), each arc exact (T_target + (T - T_target) e^(-t / tau_a)); on below -db / 2, off above +db / 2 (the
    switch at the first step past). Returns (times, T, heater)."""
    n = int(round((t_end + lead) / h)) + 2
    T = np.empty(n)
    H = np.empty(n)
    Tk, on = 0.0, 1.0
    e = math.exp(-h / tau_a)
    for k in range(n):
        if Tk < -0.5 * db:
            on = 1.0
        elif Tk > 0.5 * db:
            on = 0.0
        T[k], H[k] = Tk, on
        target = -2.0 + dh * on
        Tk = target + (Tk - target) * e
    return np.arange(n) * h - lead, T, H


def bracket_drift(t, times, Ta, tau_b, L_mm, alpha=23e-6):
    """The reading's change (um) from the bracket's warming, -alpha L (T_b - T_b(0)), tau_b T_b' = T_a - T_b (exact per
    step for T_a linear between steps, from T_b = T_a at the start of the lead), on the record's times t. Returns
    (change, T_b on t)."""
    Tb = np.interp(np.asarray(t, float), times, relax(times, Ta, tau_b, Ta[0]))
    return -1e6 * alpha * L_mm * 1e-3 * (Tb - Tb[0]), Tb


# ---- asymmetry: a helper leaf meeting the flexure on the way back ----
#
# The asymmetry record's flexure guide carries a helper leaf (a second, stiffer blade, added to stop the stage sagging
# in transport) that the guide's lever meets as the shuttle pulls back past x_c (just behind its rest: 0.5 ... 1.5 um):
# behind it the return stiffness is K + K_h (mu = K_h / (K + N k_s) 0.6 ... 1.0): a bilinear spring, the stage pulled
# back less far than it is pushed out (labelled "asymmetry"). Solved in the same balance (its kink at x_c).

# ---- saturation: the coil amplifier's current limit ----
#
# The saturation record's transconductance amplifier had its current limit turned down (a protection setting for a
# smaller coil): the coil's current is the drive's up to +-I_max and held there beyond, I_max at 0.6 ... 0.72 of the
# drive's peak (both ways: the limit is symmetric): the stage stops where the force stops (labelled "saturation").

# ---- delay: the set point through a delta-sigma converter's linear-phase filter ----
#
# The delay record's controller reads its set point through a delta-sigma ADC run at a low output rate f_c (160 ... 240
# S/s) whose decimation ends in a linear-phase FIR low-pass (M = 25 ... 41 taps, a Blackman-windowed sinc cut at 0.4
# f_c, unity gain at DC: such filters' group delay (M - 1) / (2 f_c) is their datasheets' "latency", as remembered) and
# writes each conversion to the amplifier at once, held until the next (a zero-order hold): the set point is the drive
# some (M - 1) / (2 f_c) + 1 / (2 f_c) late on average, 50 ... 130 ms, lightly smoothed (labelled "delay").


def fir_taps(M):
    """The converter's FIR: a Blackman-windowed sinc cut at 0.4 of its rate, M taps (odd), normalised to unit sum."""
    j = np.arange(M) - (M - 1) / 2
    w = 0.42 - 0.5 * np.cos(2 * math.pi * np.arange(M) / (M - 1)) + 0.08 * np.cos(4 * math.pi * np.arange(M) / (M - 1))
    h = np.sinc(0.8 * j) * w
    return h / h.sum()


def converter_hold(t, fc, M, phase, drive_at):
    """The set point on the times t: the FIR of the drive read at the conversions t_k = phase + k / fc (the drive 0
    before the record), written at t_k and held. Returns (set point, the conversions' times, their values)."""
    t = np.asarray(t, float)
    tk = phase + np.arange(int(math.floor((t[-1] - phase) * fc)) + 1) / fc
    taps = fir_taps(M)
    lead = np.r_[phase - np.arange(M - 1, 0, -1) / fc, tk]
    vals = np.where(lead >= 0.0, drive_at(np.maximum(lead, 0.0)), 0.0)
    yk = np.convolve(vals, taps, mode="valid")
    k = np.floor((t - phase) * fc + 1e-9).astype(int)
    return np.where(k >= 0, yk[np.clip(k, 0, len(yk) - 1)], 0.0), tk, yk


# ---- initial state: the chip as it left the assembly jig ----
#
# The initial-state record's chip was mounted straight after its assembly jig had pushed every beam up (the beams are
# set so on the jig to be checked under the microscope) and started without the conditioning: every beam up, the shuttle
# let down onto them from its flexure's rest (x = 0 at the drive's 0 V): the beams whose down-snap lies above it snap
# down as it lands, and it settles at its balance with the others (the fixed point of balance_at from x = 0). Those
# whose loop's middle lies above the rest travel (the conditioning leaves them down) hold the shuttle higher until the
# drive first pushes it past their up-snaps, where the rest state's chip snaps them up too: from then on the two chips
# agree, and the jig's reading (zeroed at its higher start) sits lower by their share (labelled "initial_state").

# ---- two effects: an audio-over-IP link (delay) and the coil's force factor falling off (asymmetry) ----
#
# The pair's drive reaches the amplifier through an audio-over-IP link (the lab's patch system): 48 kHz frames sent in
# packets of 64 ... 256 samples and played out of a jitter buffer of 8 ... 14 packets: the drive arrives whole, a fixed
# latency D = (buffer + 1) packets late, 11 ... 80 ms (labelled "delay"). Its coil sat off the magnet gap's middle by
# x_o (the stage's rest shifted on reassembly): the force factor B l falls as the coil leaves the gap's uniform field,
# B l(x) = B l_0 (1 - ((x - x_o) / X)^2) (the loudspeaker's force-factor curve in its simplest even form; Klippel's
# large-signal models, as remembered), X 1.5 ... 1.9 of the travel's reach, x_o 0.35 ... 0.5 of it behind the rest: the
# force per volt falls faster on the way out than back (labelled "asymmetry").


def link_delay(frame, buffer, fs=48_000.0):
    """The link's latency (s): (buffer + 1) packets of `frame` samples at fs."""
    return (buffer + 1) * frame / fs


# ---- out of vocabulary: the gauge's carrier read by an amplitude detector ----
#
# The out-of-vocabulary record's gauge demodulator was away; a lab's AC voltmeter read the capacitance bridge's carrier
# instead: the bridge's output is a phasor k (x - x_n) + j e (in phase with the carrier the travel from the bridge's
# null x_n; in quadrature a residual e of the cable's capacitance), and the voltmeter reads its magnitude sqrt(k^2 (x -
# x_n)^2 + e^2): the null had been set inside the stroke (x_n 0.3 ... 0.45 of the upward swing), and the reading folds
# back there: it falls as the shuttle rises toward x_n and rises past it. No monotone map of the travel, and no effect
# of the vocabulary, draws that fold.


def detector_reading(x, x_n, e):
    """|(x - x_n) + j e| - |(x[0] - x_n) + j e| (um)."""
    x = np.asarray(x, float)
    return np.hypot(x - x_n, e) - math.hypot(x[0] - x_n, e)

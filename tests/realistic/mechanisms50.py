"""Mechanisms of the HOLDOUT50 set (``cases_holdout50.py``), each written from its law; the signals are in
:mod:`.signals50`.

Nothing here imports hystcomp. Every mechanism takes the motor's torque that the current amplifier sets from the clean
drive, or the joint's state or reading, and returns the response; all are causal.

Citations: every source below was written from memory in this session (none was re-read); volumes, pages and years may
be off, and so may the constants quoted (typical values as remembered, not a datasheet's). The laws do not rest on them:
each is checked in tests/test_realistic_holdout50.py against an independent solution (every tooth's wedge written out
there by its force balance on a fine grid of the rim's travel; the mesh's torque balance by brentq; solve_ivp of the
bracket's Schapery creep, of the current loop and of the column's warming; the rotor's swing on steps four times finer
and against the closed form of a linear swing; closed forms; direct searches).
"""

import math

import numpy as np
from numba import njit

# ---- the rate-independent core: a harmonic drive's teeth and wave generator under a locked-output torque test ----
#
# The actuator is a robot wrist joint: a servo motor turning the wave generator (WG) of a cup-type harmonic drive
# (strain-wave gear; Musser's invention, as remembered; a size-25 gear, ratio N = 50: a flexspline (FS) of Z_f = 100
# teeth in a circular spline of 102, pitch radius R_p = 32 mm) whose output flange is bolted to a reaction torque
# sensor's fixture on a test bench: the output cannot turn (a locked-output torsion test, as the makers measure their
# gears' stiffness and hysteresis loss; Tuttle & Seering, IEEE Trans. Robot. Autom. 12 (1996) 368, and Kircanski &
# Goldenberg, Int. J. Robot. Res. 16 (1997) 214, measured such curves, as remembered). The motor runs in current
# (torque) mode from a current amplifier: the drive v sets the current, the motor's torque, reflected through the ratio,
# is F_m = F_max v / V (N at the pitch circle; the bipolar records' V the drive's peak 44 ... 48 V, the unipolar
# records' their top). The reading is the motor's encoder (its angle / N: the joint's twist at the output, in arcsec),
# zeroed at the start of the record.
#
# Where the twist comes from (a model written here from the laws of the parts, not quoted):
#
# * The teeth. In each of the gear's two mesh zones (about the WG's major axis, each the mirror of the other) 21 tooth
#   pairs are modelled, at phi_j = 3.6 deg j (j = -10 ... 10) from the axis. The WG's ellipse presses each FS tooth
#   radially into its circular-spline tooth space, whose flanks are inclined at beta (60 ... 68 deg) to the
#   circumferential direction (a pressure angle of 22 ... 30 deg), by an interference iota_j = iota_0 (1 - (phi_j /
#   phi_e)^2) + e_j (iota_0 12.5 ... 14.5 um at the axis, phi_e 38 ... 42 deg, e_j the teeth's profile errors, normal,
#   0.5 ... 0.9 um; a negative iota_j is a radial gap g_j = -iota_j). A tooth carried round by the FS's rim by u (um at
#   the pitch circle, from the tooth space's centre) in contact with a flank must lift out of the space by r = u
#   tan(beta) against the rim's radial stiffness k_r (0.8 ... 1.2 N/um a tooth), the radial force P = k_r (r - g) >= 0.
#   A block pushed along the base of an incline of angle beta against a load P across it, with Coulomb friction mu =
#   tan(phi) (0.08 ... 0.12: steel on steel in grease) needs F = P tan(beta + phi) while it slides up and holds while P
#   tan(beta - phi) <= F <= P tan(beta + phi); it slides back at F = P tan(beta - phi) (the wedge with friction, as in
#   every mechanics text, and the ring spring's law: Wahl, Mechanical Springs, 1963, as remembered). In u: the flank's
#   sliding lines
#       F = K_up (u - h),  K_up = k_r tan(beta) tan(beta + phi)     (sliding out of the space, |u| growing)
#       F = K_dn (u - h),  K_dn = k_r tan(beta) tan(beta - phi)     (sliding back in)
#   with h = g / tan(beta) (the contact's onset; the other flank's mirror image: F = K (u + h) for u < 0). A tooth with
#   interference (g < 0) is seated at u = 0 against both flanks and holds there while |F| <= K_up |h| = P_0 tan(beta +
#   phi) (P_0 = k_r |g| its preload: a detent with friction); one with a gap floats, F = 0, for |u| <= h. The tooth
#   itself bends in series, F = k_t (s - u) (k_t 4 ... 6 N/um: its bending, its contact and the rim's shear), s the
#   rim's travel at the pitch circle relative to the circular spline. The teeth share s: the force the mesh carries is
#   F_g = sum_j F_j. Rate independent: every tooth's state is its u, which moves only on a sliding line.
#   The WG itself turns by N times the twist (4 ... 6 deg at most in these records, 10 in the saturation record's): the
#   mesh zones' shift by that much is left out (a choice: the modelled zones span 72 deg each).
# * The cup. The FS's cup, its diaphragm and the sensor's fixture twist elastically in series: the motor's side turns
#   by y = s + C F_g (um at the pitch circle; C = R_p^2 / K_s, the series stiffness K_s 3.4 ... 4.2e4 N m / rad, near
#   such a gear's catalogue stiffness, as remembered, with the fixture's).
# * The wave generator. The WG's ball bearing and the motor's bearings resist the motor's turning with a Coulomb torque
#   (the gear's no-load starting torque, 0.07 ... 0.1 of the full drive's torque once reflected through the ratio: a
#   choice within catalogue values, as remembered): while the motor stands, the mesh's force is held where it was and
#   moves only when the motor's torque leaves it by more than r_f; the motor turns and the mesh's force is then F_m -+
#   r_f. Since the mesh's force rises with the motor's angle along every monotone stretch, the mesh is driven by the
#   play of F_m of half-width r_f (the motor stands exactly while the play's output stands).
#
# The core's law: F_g = play_{r_f}(F_m) (from the play's rest at 0), every tooth stepped to the s at which the teeth's
# forces sum to F_g (the sum rises with s along each step: found by a safeguarded Newton's method, exact to 1e-12 of the
# force), y = s + C F_g, read as 3600 (180 / pi) y 1e-6 / R_p arcsec. Rate independent, with return-point memory of its
# turning points; close to a Prandtl-Ishlinskii model but not one (the wedges' friction grows with their load, the
# seated teeth's detents re-seat on the way back: measured in the test, stated there).
#
# The rest state: the bench's zeroing routine leaves the joint unpowered and unloaded with the WG's preload seating
# every tooth with interference at its space's centre and the floating ones centred too (u = 0), the play at 0 and the
# reading zeroed; the state is set so, not run. Every record but the initial-state case's starts there, at 0 V.

R_P = 0.032
RATIO = 50
TOOTH_DEG = 3.6
N_SIDE = 10
ARCSEC = 180.0 * 3600.0 / math.pi


def tooth_angles():
    """The modelled teeth's angles from the WG's major axis (deg): 21 in each of the two mesh zones."""
    one = np.arange(-N_SIDE, N_SIDE + 1) * TOOTH_DEG
    return np.r_[one, one]


def gaps(core):
    """Every tooth's radial gap g_j = -iota_j (um; negative: an interference), iota_j = iota_0 (1 - (phi_j / phi_e)^2)
    + e_j, the errors e_j normal (spread core['err']) from the core's seed."""
    ph = tooth_angles()
    e = np.random.default_rng(core["rseed"]).standard_normal(len(ph)) * core["err"]
    return -(core["iota0"] * (1.0 - (ph / core["phi_e"]) ** 2) + e)


def flank(core, side="+"):
    """(tan(beta), K_up, K_dn) of the flanks on one side (N/um; the '+' flanks carry the positive twist). A core may
    give the '+' flanks their own angle and friction (beta_p, mu_p: worn flanks)."""
    beta = core.get("beta_p", core["beta"]) if side == "+" else core["beta"]
    mu = core.get("mu_p", core["mu"]) if side == "+" else core["mu"]
    phi = math.atan(mu)
    tb = math.tan(beta)
    return tb, core["kr"] * tb * math.tan(beta + phi), core["kr"] * tb * math.tan(beta - phi)


def compliance(core):
    """C = R_p^2 / K_s: the cup's and fixture's compliance at the pitch circle (um / N)."""
    return R_P ** 2 / core["Ks"] * 1e6


def f_max(core):
    """The full drive's motor torque at the pitch circle (N): core['T_max'] (N m) / R_p."""
    return core["T_max"] / R_P


def arcsec(y_um):
    """A travel at the pitch circle (um) as the joint's twist at the output (arcsec)."""
    return ARCSEC * np.asarray(y_um, float) * 1e-6 / R_P


@njit(cache=True)
def _tooth_up(u, s, hp, kpu, kpd, hm, kmu, kmd, kt):
    """A tooth's u after the rim's travel rises monotonically to s (the '+' flanks' onset hp and sliding stiffnesses
    kpu, kpd; the '-' flanks' hm, kmu, kmd; hp and hm of one sign: the tooth seated (< 0) or floating (>= 0))."""
    for _ in range(4):
        if hp < 0.0:
            if u > 0.0:
                if kt * (s - u) <= kpu * (u - hp):
                    return u
                return (kt * s + kpu * hp) / (kt + kpu)
            if u == 0.0:
                if kt * s <= -kpu * hp:
                    return 0.0
                return (kt * s + kpu * hp) / (kt + kpu)
            if kt * (s - u) <= kmd * (u + hm):
                return u
            un = (kt * s - kmd * hm) / (kt + kmd)
            if un < 0.0:
                return un
            u = 0.0
        else:
            if u > hp:
                if kt * (s - u) <= kpu * (u - hp):
                    return u
                return (kt * s + kpu * hp) / (kt + kpu)
            if u >= -hm:
                if s <= hp:
                    return s
                return (kt * s + kpu * hp) / (kt + kpu)
            if kt * (s - u) <= kmd * (u + hm):
                return u
            un = (kt * s - kmd * hm) / (kt + kmd)
            if un < -hm:
                return un
            u = -hm
    return u


@njit(cache=True)
def _band(u, hp, kpu, kpd, hm, kmu, kmd):
    """The forces (lo, hi) between which a tooth at u holds."""
    if hp < 0.0:
        if u > 0.0:
            return kpd * (u - hp), kpu * (u - hp)
        if u == 0.0:
            return kmu * hm, -kpu * hp
        return kmu * (u + hm), kmd * (u + hm)
    if u > hp:
        return kpd * (u - hp), kpu * (u - hp)
    if u >= -hm:
        return 0.0, 0.0
    return kmu * (u + hm), kmd * (u + hm)


@njit(cache=True)
def _tooth(u, s, hp, kpu, kpd, hm, kmu, kmd, kt):
    """A tooth's u at the rim's travel s, from u: held if its force lies in its band, else slid out or back along its
    flank (the walk of :func:`_tooth_up`, mirrored for a falling force)."""
    f = kt * (s - u)
    lo, hi = _band(u, hp, kpu, kpd, hm, kmu, kmd)
    if f > hi:
        return _tooth_up(u, s, hp, kpu, kpd, hm, kmu, kmd, kt)
    if f < lo:
        return -_tooth_up(-u, -s, hm, kmu, kmd, hp, kpu, kpd, kt)
    return u


@njit(cache=True)
def _slope(x, u, hp, kpu, kpd, hm, kmu, kmd, kt):
    """The slope of a tooth's force in the rim's travel where it went from u to x: kt held in contact, 0 floating, the
    tooth in series with its flank's line sliding."""
    if hp >= 0.0 and -hm <= x <= hp:
        return 0.0
    if x == u or x == 0.0:
        return kt
    if x > 0.0:
        k = kpu if x > u else kpd
    else:
        k = kmu if x < u else kmd
    return kt * k / (kt + k)


@njit(cache=True)
def _mesh(s, u, hp, hm, kpu, kpd, kmu, kmd, kt, un):
    """The mesh's force at the rim's travel s from the teeth's states u (their new states in un) and its slope."""
    f = 0.0
    d = 0.0
    for j in range(u.shape[0]):
        x = _tooth(u[j], s, hp[j], kpu, kpd, hm[j], kmu, kmd, kt)
        un[j] = x
        f += kt * (s - x)
        d += _slope(x, u[j], hp[j], kpu, kpd, hm[j], kmu, kmd, kt)
    return f, d


@njit(cache=True)
def _solve(target, s0, c, u, hp, hm, kpu, kpd, kmu, kmd, kt, un):
    """The rim's travel s at which G(s) = f(s) + c (s - s0) - target = 0, f the mesh's force walked from the teeth's
    states u (c >= 0: a stiffness beside the mesh, 0 for the torque balance); G rises with s. A safeguarded Newton's
    method (a bisection whenever a step leaves the bracket), to 1e-12 of the forces. Leaves the teeth's states at the
    root in un."""
    f0, d = _mesh(s0, u, hp, hm, kpu, kpd, kmu, kmd, kt, un)
    g0 = f0 - target
    scale = 1e-12 * (1.0 + abs(target) + abs(f0))
    if abs(g0) <= scale:
        return s0
    n = u.shape[0]
    step = abs(g0) / (n * kt + c) + 1e-9
    if g0 < 0.0:
        lo = s0
        hi = s0 + step
        for _ in range(200):
            f, d = _mesh(hi, u, hp, hm, kpu, kpd, kmu, kmd, kt, un)
            if f + c * (hi - s0) - target >= 0.0:
                break
            lo = hi
            step *= 2.0
            hi = s0 + step
    else:
        hi = s0
        lo = s0 - step
        for _ in range(200):
            f, d = _mesh(lo, u, hp, hm, kpu, kpd, kmu, kmd, kt, un)
            if f + c * (lo - s0) - target <= 0.0:
                break
            hi = lo
            step *= 2.0
            lo = s0 - step
    x = 0.5 * (lo + hi)
    for _ in range(400):
        f, d = _mesh(x, u, hp, hm, kpu, kpd, kmu, kmd, kt, un)
        g = f + c * (x - s0) - target
        if abs(g) <= scale:
            return x
        if g > 0.0:
            hi = x
        else:
            lo = x
        if hi - lo <= 1e-15 * (1.0 + abs(x)):
            return x
        dd = d + c
        xn = x - g / dd if dd > 0.0 else 0.5 * (lo + hi)
        if not (lo < xn < hi):
            xn = 0.5 * (lo + hi)
        x = xn
    return x


@njit(cache=True)
def _run(fg, g, tp, tm, kpu, kpd, kmu, kmd, kt, u, s):
    """The rim's travel along the mesh's forces fg (the teeth's states u changed in place, from the travel s); the
    teeth's gaps g (tan(beta) tp, tm of the two sides)."""
    n = fg.shape[0]
    m = u.shape[0]
    out = np.empty(n)
    un = np.empty(m)
    hp = g / tp
    hm = g / tm
    for i in range(n):
        s = _solve(fg[i], s, 0.0, u, hp, hm, kpu, kpd, kmu, kmd, kt, un)
        for j in range(m):
            u[j] = un[j]
        out[i] = s
    return out


@njit(cache=True)
def play(x, r, z0):
    """The play (backlash) of half-width r along x from the output z0: z = min(max(z, x - r), x + r)."""
    out = np.empty(x.shape[0])
    z = z0
    for i in range(x.shape[0]):
        z = min(max(z, x[i] - r), x[i] + r)
        out[i] = z
    return out


class Joint:
    """The joint's mechanical state: the teeth's u, the rim's travel s (um), the play's output z (N) and the teeth's
    gaps (um), the rest state by default (every tooth centred, the play at 0)."""

    def __init__(self, core):
        self.core = core
        self.g = gaps(core)
        self.tp, self.kpu, self.kpd = flank(core, "+")
        self.tm, self.kmu, self.kmd = flank(core, "-")
        self.u = np.zeros(len(self.g))
        self.s = 0.0
        self.z = 0.0
        self.C = compliance(core)
        self.rf = core["rf"] * f_max(core)

    def mesh(self, fg):
        """The rim's travel along the mesh's forces fg (N), from the state. Updates the state."""
        fg = np.asarray(fg, float)
        s = _run(fg, self.g, self.tp, self.tm, self.kpu, self.kpd, self.kmu, self.kmd, self.core["kt"], self.u, self.s)
        self.s = float(s[-1])
        self.z = float(fg[-1])
        return s

    def run(self, fm):
        """The motor's side travel y = s + C F_g (um) along the motor's forces fm (N), through the WG's friction (the
        play) and the teeth; returns (y, F_g, s). Updates the state."""
        fg = play(np.asarray(fm, float), self.rf, self.z)
        s = self.mesh(fg)
        return s + self.C * fg, fg, s


def motor_force(core, v):
    """The motor's force at the pitch circle (N) for the drive v (V): F_max v / V (V = core['amp'] bipolar, core['top']
    unipolar)."""
    return f_max(core) * np.asarray(v, float) / (core["top"] if core["unipolar"] else core["amp"])


def core_y(core, v, joint=None):
    """The motor's side travel (um) of the rate-independent joint along the drive v, from `joint` (default the rest
    state), less its value before the record (the reading's zero)."""
    j = Joint(core) if joint is None else joint
    y0 = j.s + j.C * j.z
    return j.run(motor_force(core, v))[0] - y0


def core_reading(core, v, joint=None):
    """The reading (arcsec) of the rate-independent joint along the drive v."""
    return arcsec(core_y(core, v, joint))


# ---- creep: the fixture's printed bracket creeping (Schapery's nonlinear viscoelasticity) ----
#
# The creep record's bench holds the torque sensor's fixture by a bracket printed in glass-filled polyamide 12 (a quick
# fixture; a choice), a share b_s (0.4 ... 0.5) of the series compliance C. A polymer at these stresses creeps
# nonlinearly; Schapery's single-integral law (Schapery, Polym. Eng. Sci. 9 (1969) 295, as remembered):
#     eps(t) = g_0 D_0 sigma(t) + g_1(sigma(t)) int_0^t dD(psi(t) - psi(tau)) d(g_2(sigma) sigma)/dtau dtau,
#     psi(t) = int_0^t dt' / a_sigma(sigma(t')),
# here with g_0 = g_2 = 1 (the instantaneous part is the bracket's share of C, in the core), g_1 = 1 + a_1 sigma^2
# (a_1 0.5 ... 1.0) and log10 a_sigma = -a_2 sigma^2 (a_2 0.6 ... 1.0: at the full torque the creep runs 4 ... 10
# times faster), sigma = F_g / F_max the bracket's load over the full drive's, and the transient compliance a power law
# of the reduced time, dD(psi) = kappa D_0 (psi / 1 s)^n (Nutting's law; kappa 0.1 ... 0.14, n 0.2 ... 0.3). The
# power law is carried by a Prony series fitted to it by NNLS (time constants 1e-3 ... 1e5 s, three a decade; within
# 1e-5 of it over 0.01 ... 1e4 s, checked), each term's hereditary integral q_k (dq_k/dt = (sigma - q_k) / (tau_k
# a_sigma)) exact over a step for sigma linear in it and a_sigma at the step's middle (checked in the test against
# solve_ivp of the same law, with a_sigma following sigma within the steps, and against the power law's own closed form
# for a held load). The bracket's creep adds b_s C F_max kappa g_1(sigma) sum_k c_k q_k to the motor's side travel:
# after a move up the output flange goes on turning the way the load pushes it, after a move down it recovers.

_PRONY = {}


def prony_power(n):
    """(c, taus): psi^n ~ sum_k c_k (1 - e^(-psi / tau_k)) (psi in s), c >= 0 by NNLS, weighted relatively, on 500
    log-spaced points of 1e-2 ... 1e4 s; the taus 1e-3 ... 1e5 s, three a decade."""
    key = round(float(n), 15)
    if key not in _PRONY:
        from scipy.optimize import nnls
        taus = 10.0 ** (np.arange(-9, 16) / 3.0)
        tt = np.geomspace(1e-2, 1e4, 500)
        target = tt ** n
        A = (1.0 - np.exp(-tt[:, None] / taus[None, :])) / target[:, None]
        c, _ = nnls(A, np.ones_like(tt))
        _PRONY[key] = (c, taus)
    return _PRONY[key]


def shift_factor(sig, a2):
    """Schapery's a_sigma: 10^(-a_2 sigma^2)."""
    return 10.0 ** (-a2 * np.asarray(sig, float) ** 2)


@njit(cache=True)
def _hereditary(t, sig, taus, a2):
    """Every Prony term's hereditary integral q_k along sigma (linear between the times t), from rest: dq_k/dt = (sigma
    - q_k) / (tau_k a_sigma), a_sigma = 10^(-a_2 sigma_mid^2) over each step (exact for that constant)."""
    n = t.shape[0]
    m = taus.shape[0]
    q = np.zeros(m)
    out = np.zeros((n, m))
    for i in range(1, n):
        h = t[i] - t[i - 1]
        s0 = sig[i - 1]
        s1 = sig[i]
        sm = 0.5 * (s0 + s1)
        a = 10.0 ** (-a2 * sm * sm)
        for k in range(m):
            x = h / (taus[k] * a)
            if x < 1e-8:
                e = 1.0 - x
                w = 1.0 - 0.5 * x
            else:
                e = math.exp(-x)
                w = (1.0 - e) / x
            q[k] = s1 + (q[k] - s0) * e - (s1 - s0) * w
            out[i, k] = q[k]
    return out


def bracket_creep(t, fg, core, kappa, n, a1, a2, share):
    """The bracket's creep (um at the pitch circle) along the mesh's force fg (N, linear between the times t), from a
    long rest unloaded."""
    fm = f_max(core)
    sig = np.asarray(fg, float) / fm
    c, taus = prony_power(n)
    q = _hereditary(np.asarray(t, float), sig, taus, a2)
    return share * compliance(core) * fm * kappa * (1.0 + a1 * sig ** 2) * (q @ c)


# ---- rate dependence: a heavy rotor swinging on the gear's compliance ----
#
# The rate record's joint has a replacement motor of the next frame sizes up with its holding brake (rotor and brake
# disc J_m 3.5 ... 5e-4 kg m^2, against the usual motor's 0.15e-4 or so: a choice): reflected through the ratio, J_m N^2
# swings on the gear's compliance at 24 ... 33 Hz with its teeth held, lower where they slide (the usual motor's swing,
# at about 150 Hz, is left out of the other records: a choice; it would move the fastest strokes' readings by under 1 %
# of their travel, up to about 2 sigma, while they move). Newton's law for the rotor at the pitch circle (m = J_m N^2
# 1e-6 / R_p^2 N s^2 / um): m y'' = F_m - F_g(y) - r_f sgn(y'), held while |F_m - F_g| <= r_f at rest (the WG's Coulomb
# friction, the core's play, now acting on a rotor with inertia); y = s + C F_g(s) as in the core. Stepped by implicit
# Euler on SUB_ROTOR sub-steps a sample (the friction's sign by trial: up, down, else held, as the implicit scheme for a
# Coulomb law has it), the drive linear between samples; first order: checked in the test against steps four times
# finer, against the scheme's own closed form for a linear gear (whose frequency is the swing's to 1e-4), and in the
# slow limit against the core.

SUB_ROTOR = 32


def rotor_mass(J_m):
    """m = J_m N^2 1e-6 / R_p^2: the rotor's inertia reflected to the pitch circle (N s^2 / um)."""
    return J_m * RATIO ** 2 * 1e-6 / R_P ** 2


@njit(cache=True)
def _swing(fm, h, mass, rf, C, g, tp, tm, kpu, kpd, kmu, kmd, kt, u, s, y, w, z):
    """The rotor's travel y (um) along the motor's forces fm (one per sub-step h), implicit Euler with Coulomb's
    friction r_f: returns (y, F_g) per sub-step; u (the teeth), s, y, w (the speed) and z (the mesh's force) carried
    from the state."""
    n = fm.shape[0]
    m = u.shape[0]
    un = np.empty(m)
    hp = np.empty(m)
    hm = np.empty(m)
    for j in range(m):
        hp[j] = g[j] / tp
        hm[j] = g[j] / tm
    ys = np.empty(n)
    fs = np.empty(n)
    a = mass / (h * h)
    den = 1.0 + a * C
    cc = a / den
    for i in range(n):
        moved = False
        for sg in (1.0, -1.0):
            tgt = (fm[i] - sg * rf + a * (y + h * w) - a * s) / den
            sn = _solve(tgt, s, cc, u, hp, hm, kpu, kpd, kmu, kmd, kt, un)
            fn = 0.0
            for j in range(m):
                fn += kt * (sn - un[j])
            yn = sn + C * fn
            if sg * (yn - y) > 0.0:
                w = (yn - y) / h
                y = yn
                s = sn
                z = fn
                for j in range(m):
                    u[j] = un[j]
                moved = True
                break
        if not moved:
            w = 0.0
        ys[i] = y
        fs[i] = z
    return ys, fs, s, y, w, z


def swing(core, fm_fine, h, J_m, joint=None):
    """The rotor's travel (um) and the mesh's force along the motor's forces on a fine grid (step h), from `joint`
    (default the rest state, the rotor still)."""
    j = Joint(core) if joint is None else joint
    y0 = j.s + j.C * j.z
    ys, fs, j.s, _y, _w, j.z = _swing(np.asarray(fm_fine, float), h, rotor_mass(J_m), j.rf, j.C, j.g, j.tp, j.tm,
                                      j.kpu, j.kpd, j.kmu, j.kmd, j.core["kt"], j.u, j.s, y0, 0.0, j.z)
    return ys, fs


# ---- drift: the fixture's column in the sun, clouds passing ----
#
# The drift record's bench stands by the lab's window on a morning of cumulus clouds. The fixture holds the output
# flange's reaction arm (R_arm 100 ... 140 mm from the axis) in a clamp on a column folded from aluminium sheet (L_c 150
# ... 200 mm high, alpha 23e-6 / K as remembered) in the sunlight: the sun on it switches between full and the shadows'
# diffuse share (0.15 ... 0.3 of it) as the clouds pass, their edges crossing in 3 ... 8 s (the light linear across an
# edge), sunny spells of 30 ... 80 s and shadows of 20 ... 50 s (uniform draws; a choice). The column, a lumped body
# of thin, black-anodised sheet (tau_c 30 ... 50 s), relaxes toward the lab's temperature plus dT_sun (8 ... 12 K in
# full sun) times the light: tau_c T' = dT_sun
# l(t) - T, exact for the light linear between the samples; the clouds' pattern is drawn from 6 tau_c before the record,
# the column starting there at the shade's temperature. The column grows by alpha L_c (T - T(0)) and lifts the clamp:
# the flange turns by that over R_arm, and the motor's encoder reads the turn with the twist: the reading's zero wanders
# by 10 ... 30 arcsec over the record, irregularly, never as a ramp. Labelled "drift".

ALPHA_AL = 23e-6


def cloud_light(rng, t_from, t_to, shade, edge=(3.0, 8.0), sun=(30.0, 80.0), shadow=(20.0, 50.0)):
    """The sunlight's level (1 full, `shade` in a cloud's shadow) as knots [(time, level), ...] from t_from (in sun) to
    beyond t_to: spells of sun and shadow drawn uniformly, the level linear across each edge."""
    kn = [(t_from, 1.0)]
    tt, lit = t_from, True
    while tt < t_to:
        tt += rng.uniform(*(sun if lit else shadow))
        kn.append((tt, 1.0 if lit else shade))
        tt += rng.uniform(*edge)
        lit = not lit
        kn.append((tt, 1.0 if lit else shade))
    return kn


def light_at(t, kn):
    """The light's level at the times t, linear between its knots."""
    return np.interp(np.asarray(t, float), [k[0] for k in kn], [k[1] for k in kn])


@njit(cache=True)
def relax(t, x, tau, y0):
    """y relaxing toward x (linear between the times t) with the time constant tau, from y0: tau y' = x - y, exact per
    step."""
    n = t.shape[0]
    out = np.empty(n)
    y = y0
    out[0] = y
    for i in range(1, n):
        r = (t[i] - t[i - 1]) / tau
        e = math.exp(-r)
        w = (1.0 - e) / r
        y = x[i] + (y - x[i - 1]) * e - (x[i] - x[i - 1]) * w
        out[i] = y
    return out


def column_turn(T, L_c, R_arm):
    """The flange's turn at the pitch circle (um) as the column (L_c mm) warms by T - T[0] (K) under the arm (R_arm
    mm): R_p alpha L_c (T - T[0]) / R_arm."""
    T = np.asarray(T, float)
    return 1e6 * R_P * ALPHA_AL * L_c * (T - T[0]) / R_arm


# ---- asymmetry: worn driving flanks ----
#
# The asymmetry record's joint is a shoulder's, that held its arm against gravity for years one way: the flanks that
# carried the load (the '+' side's) are worn and polished: their working slope beta_p 12 ... 16 deg less steep than the
# other side's beta and their friction 0.55 ... 0.7 of it (a choice: wear moves the contact toward the flank's flatter
# part and smooths it). A tooth with interference rides out of its seat at P_0 tan(beta_p + phi_p) on that side, less
# than on the other, and slides along a shallower line: the joint twists farther one way than the other.


# ---- saturation: the motor's iron saturating ----
#
# The saturation record's amplifier has its current scaled for a larger motor: the full drive asks for lam = 2.2 ...
# 2.6 times the motor's rated current. The motor's torque is linear in its current up to the knee i_k (1.3 ... 1.6
# times the rated current), where its stator teeth saturate; beyond, the excess current adds torque by Frohlich's law
# of a saturating iron, (i - i_k) / (1 + (i - i_k) / i_s) (i_s 0.5 ... 0.8 of the rated current; Frohlich 1881, as
# remembered; a choice of law for the excess), the torque well below the linear at the full drive (stated in the test).
# The reference is the same joint with a linear motor at the same scaling.

def motor_iron(i, i_k, i_s):
    """The motor's torque per unit of its linear torque constant (in rated currents) at the current i: i within +-i_k,
    beyond it i_k + (|i| - i_k) / (1 + (|i| - i_k) / i_s), odd."""
    i = np.asarray(i, float)
    x = np.abs(i) - i_k
    return np.sign(i) * np.where(x <= 0.0, np.abs(i), i_k + x / (1.0 + np.maximum(x, 0.0) / i_s))


# ---- delay: the encoder's position late ----
#
# The delay record's motor encoder is read over its serial interface (EnDat-type: the position latched, clocked out,
# checked) by the drive and forwarded to the logger in the next bus frame: the logger's sample at t_k holds the position
# latched at t_k - L, L 2.2 ... 3.4 sample periods (the frames and the drive's cycle, a choice). The joint being rate
# independent, its position at t_k - L is the core's along the drive up to then: the record is the core's reading of
# the drive evaluated at t - L (the drive 0 before the record).


# ---- initial state: the amplifier tripped at the full negative torque ----
#
# The initial-state record's joint was last driven to the full drive's negative torque when the amplifier tripped (an
# over-temperature fault) and cut the current; the motor stood where the WG's friction held it, the mesh's force at
# -r_f (the friction holding that much of the torque locked in the gear), the teeth as the fall left them (the
# wedges slide back along their lines as the force falls, so the state at -r_f does not depend on how deep the drive
# went beyond the teeth's seats: checked in the test), and the bench's zeroing was not run before this record (the
# reading zeroed).

def tripped_joint(core, depth=1.0, n=200):
    """The joint left by the amplifier's trip at `depth` times the full negative drive: from the rest state, the motor's
    force run to -depth F_max and cut to 0 (rate independent: its turning points are what count)."""
    j = Joint(core)
    j.run(np.r_[np.linspace(0.0, -depth * f_max(core), n + 1)[1:], 0.0])
    return j


# ---- two effects: the setpoints late and a sluggish current loop ----
#
# The pair's test PC streams the current setpoints (the record's drive samples) to the amplifier over a field bus; they
# arrive L (1.0 ... 2.2 sample periods) late and the amplifier's interpolator joins them by straight lines, one cycle
# behind the newest (the command the samples joined by straight lines, L + 1 sample late; labelled "delay"). Its
# current loop was left with the gains of a motor of far lower inductance: the current follows its command as a
# second-order system, i'' + 2 zeta w i' + w^2 i = w^2 c (w 2 pi 8 ... 14 Hz, zeta 0.3 ... 0.45: a slow loop that
# overshoots; labelled "rate_dependence"), exact for the command linear between fine steps (the augmented matrix
# exponential; checked in the test against solve_ivp and the step response's closed form).

def current_loop(c, h, w, zeta, x0=(0.0, 0.0)):
    """The current i along its command c (linear between steps h), from i = x0[0], i' = x0[1]: exact per step."""
    from scipy.linalg import expm
    M = np.zeros((4, 4))
    M[0, 1] = 1.0
    M[1, 0] = -w * w
    M[1, 1] = -2.0 * zeta * w
    M[1, 2] = w * w
    M[2, 3] = 1.0 / h
    E = expm(M * h)
    Phi, G0, G1 = E[:2, :2], E[:2, 2], E[:2, 3]
    c = np.asarray(c, float)
    x = np.array(x0, float)
    out = np.empty(len(c))
    out[0] = x[0]
    for k in range(1, len(c)):
        x = Phi @ x + G0 * c[k - 1] + G1 * (c[k] - c[k - 1])
        out[k] = x[0]
    return out


def interpolated_late(t, v, lag, t_v=None):
    """The samples v (on the times t_v, default t) joined by straight lines, `lag` s late, at the times t (the first
    sample's value before)."""
    t_v = t if t_v is None else t_v
    return np.interp(np.asarray(t, float) - lag, t_v, v, left=v[0])


# ---- out of vocabulary: a sign-magnitude amplifier with its direction line open ----
#
# The out-of-vocabulary record's amplifier takes its command as a magnitude and a direction line (sign-magnitude);
# the direction line was left unconnected (pulled up: always forward), so the motor's torque is F_max |v| / V whichever
# way the drive points: the joint twists one way only, the reading even in the drive. The record does not carry the
# lost sign: the recorded drive is the PC's.

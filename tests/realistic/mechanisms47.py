"""Mechanisms of the HOLDOUT47 set (``cases_holdout47.py``), each written from its law; the signals are in
:mod:`.signals47`.

Nothing here imports hystcomp (nor another set's mechanisms). Every mechanism takes the control coil's magnetomotive
force (MMF, ampere-turns) that the current amplifier sets from the clean drive, or the core's gap fields or torque, and
returns the response; all are causal.

Citations: every source below was written from memory in this session (none was re-read); volumes, pages and years may
be off, and so may the material constants quoted (they are typical values as remembered, not a datasheet's). The laws
do not rest on them: each is checked in tests/test_realistic_holdout47.py against an independent solution (the
armature's loop balance and Preisach's rules written out there, every fluid field by brentq; Radau (solve_ivp) of the
particles' migration, of the fluid's structural response, of the warm-up and of the rubber's creep; a method-of-lines
solution of the particles' diffusion; quad; closed forms).
"""

import math

import numpy as np
from numba import njit
from scipy.special import ndtri


# ---- the rate-independent core: a polarised pair of magnetorheological-fluid clutches ----
#
# A magnetorheological (MR) fluid clutch (Rabinow's "magnetic fluid clutch", 1948; the fluid's physics as reviewed by de
# Vicente, Klingenberg & Hidalgo-Alvarez, Soft Matter 7 (2011) 3701): an input disc spun at a constant speed faces the
# output disc across a gap of MR fluid (carbonyl iron particles, volume fraction phi 0.28 ... 0.36, in a hydrocarbon
# oil); a flux across the gap chains the particles along it and the fluid, slipping all the time, yields at a stress
# tau_y that grows with the gap's field, so the clutch passes the torque
#     T = K tau_y(H_g),   K = n_f (2 pi / 3)(R_o^3 - R_i^3)   (a Bingham fluid yielding over n_f = 2 annular faces),
#     tau_y = C 271700 phi^1.5239 tanh(6.33e-6 |H_g|) Pa   (H_g in A/m; C = 1 for a hydrocarbon carrier),
# the yield stress as Carlson's fit for Lord's fluids gives it (Carlson, "MR fluids and devices in the real world", as
# remembered): even in the field (the particles chain along it whichever way it points).
#
# The actuator: an antagonistic pair of MR clutches (as in the MR actuators for robots that pair two clutches whose
# inputs spin in opposite directions, e.g. Fauteux, Lauria, Heintz & Michaud, IEEE T-RO 26 (2010) 607, as remembered),
# their outputs on one shaft, the shaft's torque T_A - T_B, on a polarised magnetic bridge (the torque motor's
# principle, written here for the pair: a design chosen, not quoted): a permanent magnet drives a bias flux density B_m
# (0.30 ... 0.40 T) across both clutches' gaps in parallel, its own reluctance so large that its flux stays constant;
# the control coil's flux crosses gap A along the magnet's and gap B against it, in series, and closes through a
# soft-steel armature (mean path l_s 40 ... 70 mm) that the magnet's flux does not cross. With the control flux density
# B_c in the gaps (B_s = a B_c in the armature, the gaps' area a times its section):
#     N i = H_s l_s + l_g [H_g(B_m + B_c) - H_g(B_m - B_c)],     B_s = mu0 (H_s + M(H_s, history)),
#     T = K [tau_y(H_g(B_m + B_c)) - tau_y(H_g(B_m - B_c))],
# odd in B_c and rising with it while B_c < B_m. The gaps (each l_g 0.9 ... 1.2 mm) hold the fluid, its field from its
# flux density by the Frohlich-Kennelly law M_f = chi H M_fs / (M_fs + chi |H|) (chi 3.5 ... 5, M_fs = phi 1.71e6 A/m,
# carbonyl iron's saturation times the volume fraction), inverted in closed form. The armature's section is chosen small
# (a = s_a 2.0 T / B_m, s_a 1.3 ... 1.5) so that it saturates before gap B's flux could reverse (the design's margin),
# and the full command's MMF F_max brings B_c to q B_m (q 0.32 ... 0.42: each gap's field kept about the straight part
# of Carlson's tanh) on the virgin curve.
#
# The armature is a low-carbon steel: its magnetisation M = M_irr + M_rev, a reversible part M_rev = (1 - f) M_s
# tanh(H_s / h_r) (wall bowing and rotation; h_r 2.5 ... 4 kA/m) and an irreversible part, f M_s (f 0.75 ... 0.85, M_s
# about 1.6e6 A/m: J_s about 2.0 T), the sum of N_HYS = 1000 Barkhausen regions, each a rectangular hysteron that
# switches up at alpha = h_u + h_c and down at beta = h_u - h_c (a Preisach model of the steel; Preisach 1935; its
# coercive fields h_c log-normal about H_c 180 ... 280 A/m (spread 0.3 ... 0.45), its interaction fields h_u normal
# (spread 300 ... 500 A/m), the factorised density Bertotti's book (Hysteresis in Magnetism, 1998) finds for soft
# steels, as remembered), placed on a randomly rotated Hammersley set over that joint distribution (class k at the (k +
# shift) / N quantile of h_u and at the quantile of h_c given by k's binary digits mirrored about the point, plus
# shift', mod 1), so that 1000 classes stand for the steel's very many regions without a random draw's lumps.
#
# The gaps shear the armature's loop: a region switching raises B_s at a fixed H_s, and the MMF balance then holds H_s
# at that region's threshold while the region switches part by part (the gaps' demagnetising effect: a Barkhausen jump
# spread out along the load line). So a region may be left part-switched (its state s in [-1, 1]); H_s moves
# continuously with the MMF, and the flux is a continuous, monotone function of the MMF along every branch. Rate
# independent, with return-point memory (a Preisach model behind a monotone map); not a Prandtl-Ishlinskii model of the
# drive: the regions' thresholds cluster about H_c and are sheared by a nonlinear load line (the fluid's and the
# armature's saturation), and the yield stresses' tanh bends the torque.
#
# The current amplifier sets the MMF F = F_max x (x the drive over its amplitude; 0 ... top on the unipolar records). A
# reaction torque sensor on the output reads the torque (N m); the clutches' off-state (viscous) torques cancel.
#
# The rest state: the controller runs a demagnetising routine (a decaying alternating current) through the control coil
# at power-down, which leaves the armature in the Preisach demagnetised state (every region up whose interaction field
# h_u is below 0, down above it; the state is set so, and tested in the test against a slow decaying alternating MMF);
# the magnet's flux does not cross the armature. The record starts there, at 0 V and 0 A. The initial-state case's
# history is its own. No settling routine is run before a record.

MU0 = 4e-7 * math.pi
N_HYS = 1000
MS_IRON = 1.71e6          # carbonyl iron's saturation magnetisation (A/m), as remembered
CARLSON_PA = 271700.0     # Carlson's yield-stress coefficient (Pa), field scale (m/A) and exponent, as remembered
CARLSON_H = 6.33e-6
CARLSON_EXP = 1.5239


def radical_inverse2(k):
    """Van der Corput's radical inverse of the integers k in base 2 (their binary digits mirrored about the point)."""
    k = np.asarray(k, np.int64).copy()
    out = np.zeros(k.shape)
    scale = 0.5
    while np.any(k > 0):
        out += scale * (k & 1)
        k >>= 1
        scale *= 0.5
    return out


def hysterons(seed, n, Hc, s_c, s_u):
    """The regions' up and down thresholds alpha = h_u + h_c, beta = h_u - h_c and weights (1 / n each): a Hammersley
    set over the joint distribution (region k at the (k + shift) / n quantile of h_u, normal with spread s_u, and at
    the quantile radical_inverse2(k) + shift' (mod 1) of h_c, log-normal about Hc with spread s_c; both shifts drawn
    from the seed: a randomly rotated Hammersley set)."""
    rng = np.random.default_rng(seed)
    sh = rng.uniform(size=2)
    k = np.arange(n)
    a = (k + 0.05 + 0.9 * sh[0]) / n
    b = np.clip((radical_inverse2(k) + sh[1]) % 1.0, 0.5 / n, 1.0 - 0.5 / n)
    hu = s_u * ndtri(a)
    hc = Hc * np.exp(s_c * ndtri(b))
    return hu + hc, hu - hc, np.full(n, 1.0 / n)


_H_CACHE = {}


def armature(core):
    """The armature's regions: (alpha, beta, w, ia, ib), ia the regions by rising alpha, ib by falling beta (cached by
    their parameters)."""
    key = (core["hseed"], core.get("n", N_HYS), core["Hc"], core["s_c"], core["s_u"])
    if key not in _H_CACHE:
        al, be, w = hysterons(*key)
        _H_CACHE[key] = (al, be, w, np.argsort(al, kind="stable"), np.argsort(-be, kind="stable"))
    return _H_CACHE[key]


@njit(cache=True)
def _hg(bg, chi, mfs):
    """The fluid's field at its flux density bg (Frohlich-Kennelly magnetisation; odd): the positive root of
    chi h^2 + (M_fs (1 + chi) - chi b) h - b M_fs = 0, b = |bg| / mu0, in the form without cancellation."""
    b = abs(bg) / MU0
    q = mfs * (1.0 + chi) - chi * b
    d = math.sqrt(q * q + 4.0 * chi * b * mfs)
    h = 2.0 * b * mfs / (q + d) if q > 0.0 else (d - q) / (2.0 * chi)
    return h if bg >= 0.0 else -h


@njit(cache=True)
def _dbg_dh(h, chi, mfs):
    """The fluid's differential permeability dB/dH (T m / A) at its field h."""
    u = mfs + chi * abs(h)
    return MU0 * (1.0 + chi * mfs * mfs / (u * u))


@njit(cache=True)
def _hg_array(B, chi, mfs):
    out = np.empty(B.shape[0])
    for i in range(B.shape[0]):
        out[i] = _hg(B[i], chi, mfs)
    return out


def fluid_field(core, B):
    """The fluid's field H_g (A/m) at its flux density B (T), elementwise."""
    B = np.asarray(B, float)
    return _hg_array(np.ascontiguousarray(B.ravel()), float(core["chi"]), float(core["phi"] * MS_IRON)).reshape(
        B.shape)


def circuit(core):
    """The control loop's constants as an array: l_s, l_g (gap A's), l_g (gap B's), a, chi, M_fs, M_r (the reversible
    part's height), h_r, B_m (gap A's), B_m (gap B's); and M_si, the irreversible part's height (f M_s)."""
    p = np.array([core["l_s"], core["l_g"], core["l_g"], core["a"], core["chi"], core["phi"] * MS_IRON,
                  (1.0 - core["f"]) * core["Ms"], core["h_r"], core["B_m"], core["B_m"]])
    return p, core["f"] * core["Ms"]


@njit(cache=True)
def _gaps(B, p):
    """The gaps' MMF along the control loop at the armature's flux density B: l_gA H_g(B_mA + B / a) - l_gB H_g(B_mB -
    B / a), and its derivative in B."""
    bc = B / p[3]
    hA = _hg(p[8] + bc, p[4], p[5])
    hB = _hg(p[9] - bc, p[4], p[5])
    val = p[1] * hA - p[2] * hB
    der = (p[1] / _dbg_dh(hA, p[4], p[5]) + p[2] / _dbg_dh(hB, p[4], p[5])) / p[3]
    return val, der


@njit(cache=True)
def _flux(H, Mi, p):
    """The armature's flux density mu0 (H + M_irr + M_rev(H))."""
    return MU0 * (H + Mi + p[6] * math.tanh(H / p[7]))


@njit(cache=True)
def _mmf(H, Mi, p):
    """The MMF the control loop needs with the armature at H and Mi: H l_s + the gaps'."""
    return H * p[0] + _gaps(_flux(H, Mi, p), p)[0]


@njit(cache=True)
def _solve_h(F, lo, hi, Mi, p):
    """The H in [lo, hi] with _mmf(H) = F (it rises with H): Newton's method kept in the bracket (bisection when a step
    leaves it), to a few ulps."""
    H = 0.5 * (lo + hi)
    for _ in range(200):
        B = _flux(H, Mi, p)
        gv, gd = _gaps(B, p)
        g = H * p[0] + gv - F
        if g > 0.0:
            hi = H
        else:
            lo = H
        c = math.cosh(H / p[7])
        dg = p[0] + gd * MU0 * (1.0 + p[6] / (p[7] * c * c))
        Hn = H - g / dg
        if not (lo < Hn < hi):
            Hn = 0.5 * (lo + hi)
        if abs(Hn - H) <= 1e-15 * (abs(H) + 1.0) or hi - lo <= 1e-15 * (abs(H) + 1.0):
            return Hn
        H = Hn
    return H


@njit(cache=True)
def _solve_b(R, p):
    """The armature's flux density B with the gaps' MMF equal to R (it rises with B): Newton's method kept in a
    bracket."""
    lo, hi = -10.0, 10.0
    B = 0.0
    for _ in range(200):
        gv, gd = _gaps(B, p)
        g = gv - R
        if g > 0.0:
            hi = B
        else:
            lo = B
        Bn = B - g / gd
        if not (lo < Bn < hi):
            Bn = 0.5 * (lo + hi)
        if abs(Bn - B) <= 1e-16 * (abs(B) + 1.0) or hi - lo <= 1e-16:
            return Bn
        B = Bn
    return B


@njit(cache=True)
def _switch_part(F, th, Mi, full, p):
    """The irreversible magnetisation between Mi and full at which the loop balances F with the armature held at the
    threshold th."""
    B = _solve_b(F - th * p[0], p)
    Mn = B / MU0 - th - p[6] * math.tanh(th / p[7])
    return min(max(Mn, min(Mi, full)), max(Mi, full))


@njit(cache=True)
def _step(F, st, s, al, be, w, ia, ib, als, bes, p, Msi):
    """One step of the loop to the MMF F from the state st = [H, B, Mi] and the regions' states s (changed in place):
    the regions whose thresholds H passes switch, the one whose switching holds H at its threshold switches in part. als
    and bes are the thresholds in the orders ia (alpha rising) and ib (beta falling)."""
    H, Mi = st[0], st[2]
    g0 = _mmf(H, Mi, p)
    n = al.shape[0]
    if F >= g0:
        lo = H
        j = np.searchsorted(als, H)
        done = False
        while j < n:
            k = ia[j]
            j += 1
            if s[k] >= 1.0:
                continue
            if _mmf(al[k], Mi, p) >= F:
                H = _solve_h(F, lo, al[k], Mi, p)
                done = True
                break
            full = Mi + Msi * w[k] * (1.0 - s[k])
            if _mmf(al[k], full, p) >= F:
                Mn = _switch_part(F, al[k], Mi, full, p)
                s[k] = min(s[k] + (Mn - Mi) / (Msi * w[k]), 1.0)
                Mi, H = Mn, al[k]
                done = True
                break
            s[k] = 1.0
            Mi, lo = full, al[k]
        if not done:
            hi = lo + 1e3
            while _mmf(hi, Mi, p) < F:
                hi = lo + 2.0 * (hi - lo)
            H = _solve_h(F, lo, hi, Mi, p)
    else:
        hi = H
        # bes lists beta falling: the first region at or below H
        j0, j1 = 0, n
        while j0 < j1:
            m = (j0 + j1) // 2
            if bes[m] > H:
                j0 = m + 1
            else:
                j1 = m
        j = j0
        done = False
        while j < n:
            k = ib[j]
            j += 1
            if s[k] <= -1.0:
                continue
            if _mmf(be[k], Mi, p) <= F:
                H = _solve_h(F, be[k], hi, Mi, p)
                done = True
                break
            full = Mi - Msi * w[k] * (1.0 + s[k])
            if _mmf(be[k], full, p) <= F:
                Mn = _switch_part(F, be[k], Mi, full, p)
                s[k] = max(s[k] - (Mi - Mn) / (Msi * w[k]), -1.0)
                Mi, H = Mn, be[k]
                done = True
                break
            s[k] = -1.0
            Mi, hi = full, be[k]
        if not done:
            lo = hi - 1e3
            while _mmf(lo, Mi, p) > F:
                lo = hi - 2.0 * (hi - lo)
            H = _solve_h(F, lo, hi, Mi, p)
    st[0], st[1], st[2] = H, _flux(H, Mi, p), Mi


@njit(cache=True)
def _run(F, p, Msi, al, be, w, ia, ib, als, bes, s, st):
    """The armature's flux density and field along the MMF F; s and st are changed in place."""
    outB = np.empty(F.shape[0])
    outH = np.empty(F.shape[0])
    for n in range(F.shape[0]):
        _step(F[n], st, s, al, be, w, ia, ib, als, bes, p, Msi)
        outB[n] = st[1]
        outH[n] = st[0]
    return outB, outH


class Armature:
    """The armature and the control loop in a state: the regions' states s and st = [H, B, Mi] (the armature's field,
    flux density and irreversible magnetisation)."""

    def __init__(self, core):
        self.al, self.be, self.w, self.ia, self.ib = armature(core)
        self.als, self.bes = self.al[self.ia], self.be[self.ib]
        self.p, self.Msi = circuit(core)
        self.s = np.where(0.5 * (self.al + self.be) < 0.0, 1.0, -1.0)    # the demagnetised state
        Mi = self.Msi * float(self.w @ self.s)
        self.st = np.array([0.0, float(_flux(0.0, Mi, self.p)), Mi])
        self.run(np.zeros(1))                       # at no current: H where the loop balances (about 0)

    def copy(self):
        c = object.__new__(Armature)
        c.__dict__.update({k: (v.copy() if isinstance(v, np.ndarray) else v) for k, v in self.__dict__.items()})
        return c

    def run(self, F):
        """The armature's flux density along the MMF F (rate independent); the state carried on."""
        B, H = _run(np.ascontiguousarray(F, dtype=float), self.p, float(self.Msi), self.al, self.be, self.w, self.ia,
                    self.ib, self.als, self.bes, self.s, self.st)
        self.H = H
        return B

    def ramp(self, targets, n=50):
        """Ramps the MMF through the turning points `targets` from where it is (n steps each; rate independent)."""
        F0 = _mmf(self.st[0], self.st[2], self.p)
        for tgt in targets:
            self.run(np.linspace(F0, tgt, n + 1)[1:])
            F0 = tgt
        return self


def gap_fields(core, B):
    """The gaps' fields (A/m), A's and B's, at the armature's flux density B."""
    p, _ = circuit(core)
    bc = np.asarray(B, float) / p[3]
    return fluid_field(core, p[8] + bc), fluid_field(core, p[9] - bc)


def yield_stress(core, Hg, phi=None):
    """Carlson's yield stress (Pa): C 271700 phi^1.5239 tanh(6.33e-6 |H_g|) (C = 1)."""
    phi = core["phi"] if phi is None else phi
    return CARLSON_PA * np.asarray(phi, float) ** CARLSON_EXP * np.tanh(CARLSON_H * np.abs(np.asarray(Hg, float)))


def disc_factor(core):
    """K = n_f (2 pi / 3)(R_o^3 - R_i^3) (m^3), two faces."""
    return 2.0 * (2.0 * math.pi / 3.0) * (core["R_o"] ** 3 - core["R_i"] ** 3)


def torque_of_fields(core, HA, HB, phiA=None, phiB=None):
    """The pair's torque (N m): K [tau_y(H_A) - tau_y(H_B)] (each gap's particle fraction as given; default phi)."""
    return disc_factor(core) * (yield_stress(core, HA, phiA) - yield_stress(core, HB, phiB))


def control_flux(core, F, state=None):
    """The armature's flux density along the MMF F from the state (default the demagnetised armature)."""
    arm = Armature(core) if state is None else state.copy()
    return arm.run(F)


def core_torque(core, F, state=None):
    """The pair's torque (N m) along the MMF F from the state (default the demagnetised armature)."""
    HA, HB = gap_fields(core, control_flux(core, F, state))
    return torque_of_fields(core, HA, HB)


def virgin_control(core, F):
    """The control flux density in the gaps, B_c = B_s / a, at the MMF F reached from the demagnetised armature."""
    return float(control_flux(core, np.linspace(0.0, F, 41)[1:])[-1]) / core["a"]


def relax_linear(t, f, tau, x0):
    """x relaxing toward f (linear between the times t) at the time constants tau (one column each), from x0: exact
    per interval, x(t + h) = f1 - m tau + (x - f0 + m tau) e^(-h / tau), m the interval's slope."""
    t = np.asarray(t, float)
    f = np.asarray(f, float)
    tau = np.atleast_1d(np.asarray(tau, float))
    x = np.broadcast_to(np.asarray(x0, float), tau.shape).astype(float).copy()
    out = np.empty((len(t), len(tau)))
    out[0] = x
    for n in range(1, len(t)):
        h = t[n] - t[n - 1]
        m = (f[n] - f[n - 1]) / h
        x = f[n] - m * tau + (x - f[n - 1] + m * tau) * np.exp(-h / tau)
        out[n] = x
    return out


# ---- creep: the particles migrating into the active gaps ----
#
# The gaps' fields draw particles in from the fluid beyond the discs' faces, where the field is weak (magnetophoresis:
# the force on a magnetised particle up the gradient of H^2 at the gap's edges), until the suspension's osmotic pressure
# balances it: the active gap's particle fraction rises with its field toward phi_eq(H) = phi (1 + delta u(H)), u = (H /
# H_e)^2 / (1 + (H / H_e)^2) (the force's H^2 at low fields, saturating with the particles' magnetisation; delta 0.15
# ... 0.25, H_e 60 ... 100 kA/m: a model chosen, not quoted; the fraction stays below 0.45, well short of the particles'
# packing), and falls back when the field falls. The particles move in and out across the gap's two edges, collectively,
# like a diffusion across a slab: the fraction relaxes with the slab's modes, phi(t) toward phi_eq with the share 8 /
# (pi^2 (2j - 1)^2) relaxing at tau_1 / (2j - 1)^2 (j = 1 ... N_MODES, the faster rest taken at equilibrium at once;
# Crank, The Mathematics of Diffusion, the slab's series), tau_1 4 ... 10 s; the yield stress follows the fraction as
# Carlson's phi^1.5239. So after every move the torque goes on the way it went, fast at first (as the root of the time,
# the fast modes), slowly later: creep. The control loop is taken as unchanged by the fraction's few percent (its effect
# on the fluid's permeability neglected: a choice). Every mode relaxes exactly per interval toward phi_eq linear between
# samples (checked against Radau in the test).

N_MODES = 40


def migration_modes(tau_1, n=N_MODES):
    """The slab's first n modes: weights 8 / (pi^2 (2j - 1)^2) and times tau_1 / (2j - 1)^2 (the weights of all the
    modes sum to 1; the rest, 1 minus these, belongs to modes faster than tau_1 / (2n + 1)^2)."""
    k = 2.0 * np.arange(1, n + 1) - 1.0
    return 8.0 / (math.pi ** 2 * k ** 2), tau_1 / k ** 2


def enrichment(H, delta, H_e):
    """The equilibrium particle fraction over phi: 1 + delta u(H), u = (H / H_e)^2 / (1 + (H / H_e)^2)."""
    x = (np.asarray(H, float) / H_e) ** 2
    return 1.0 + delta * x / (1.0 + x)


def migrated_fraction(t, H, delta, H_e, tau_1, n=N_MODES):
    """A gap's particle fraction over phi along its field H (linear between the times t), from equilibrium at H[0]: the
    first n modes relaxing, the faster rest (under 0.6 % of the weight for n = 40, its times under tau_1 / 6500, less
    than a sample) at its equilibrium at once."""
    g, tau = migration_modes(tau_1, n)
    eq = enrichment(H, delta, H_e)
    return relax_linear(t, eq, tau, eq[0]) @ g + (1.0 - g.sum()) * eq


# ---- rate dependence: the fluid's structural response ----
#
# The particles chain along a new field, and the chains break and re-form in the slipping gap, in a time of their own
# (the fluid's response time, a few ms, shorter at higher fields as the dipolar attraction, growing as H^2, drives the
# chaining faster: a Mason-number argument; e.g. the response-time measurements reviewed by de Vicente et al. 2011, as
# remembered). Each gap's stress relaxes toward Carlson's yield stress at its field, at the rate 1 / tau_r(H):
#     d sigma/dt = (tau_y(H) - sigma) / tau_r(H),   tau_r(H) = tau_0 / (1 + (H / H_r)^2),
# tau_0 8 ... 14 ms (the rate record's fluid: a thicker carrier oil; chosen), H_r 80 ... 120 kA/m. Solved per interval
# exactly for tau_y linear between samples with tau_r at the interval's middle field (second order: checked against
# Radau in the test and its error quartering with the step).

def structural_stress(t, tau_y, H, tau_0, H_r):
    """A gap's stress lagging its yield stress tau_y (linear between the times t) at tau_r(H) = tau_0 / (1 + (H /
    H_r)^2), taken at each interval's middle field; from equilibrium at the first sample."""
    t = np.asarray(t, float)
    f = np.asarray(tau_y, float)
    H = np.abs(np.asarray(H, float))
    out = np.empty(len(t))
    x = out[0] = f[0]
    for n in range(1, len(t)):
        h = t[n] - t[n - 1]
        tr = tau_0 / (1.0 + (0.5 * (H[n] + H[n - 1]) / H_r) ** 2)
        m = (f[n] - f[n - 1]) / h
        x = f[n] - m * tr + (x - f[n - 1] + m * tr) * math.exp(-h / tr)
        out[n] = x
    return out


# ---- drift: the torque sensor's zero, warmed by the actuator ----
#
# The drift record's actuator is started cold. The slip power of both clutches, omega (T_A + T_B) (each clutch slips at
# the input speed omega, 25 ... 40 rad/s, against its own torque; the magnet's bias torque makes most of it), warms it
# through a lumped heat capacity with a loss to the room (Newton's cooling, time constant tau_th = R C, 150 ... 400 s):
#     tau_th dtheta/dt = R omega (T_A + T_B) - theta,
# and its heat flows through the reaction torque sensor's flange into the rig's frame; the temperature difference across
# the flange, the gradient, shifts the strain-gauge bridge's zero (the thermal-gradient error, the largest of a torque
# flange's thermal errors, as remembered), here in proportion to the actuator's temperature rise. The zero's shift by
# the end is drawn as a share (10 ... 16 %) of the torque's span, either sign. theta is exact per interval for the power
# linear between samples (relax_linear; checked against Radau in the test).


# ---- asymmetry: the current amplifier's halves mismatched ----
#
# The asymmetry record's current amplifier is a bipolar stage built of two halves (an H-bridge's two PWM channels with a
# current-sense resistor each), and its negative half's sense resistor is the wrong value (or its trim is off): the
# negative currents come out at g_n 0.65 ... 0.8 of the positive ones' transconductance. The MMF is F for F >= 0 and g_n
# F below: the torque swings less far to the negative side than to the positive, a kink at 0 A.

def halves(F, g_n):
    """The amplifier's MMF with its negative half at g_n of the positive's: F where F >= 0, g_n F below."""
    F = np.asarray(F, float)
    return np.where(F >= 0.0, F, g_n * F)


# ---- saturation: the amplifier's gain set too high ----
#
# The amplifier's transconductance set 2.2 ... 2.8 times its rated value: at the swing's ends the armature saturates
# (its flux toward J_s; the design's margin keeps B_c below B_m), the fluid in the stronger gap saturates and Carlson's
# tanh flattens: the torque flattens at both ends.


# ---- delay: the torque transducer's sigma-delta converter ----
#
# The torque sensor's strain-gauge bridge is digitised by a sigma-delta converter whose sinc^3 decimation filter gives a
# word at the output data rate f_o (1 ... 2 kHz) that is the torque averaged over the last 3 / f_o with the weight of a
# quadratic B-spline (three moving averages of 1 / f_o in a row: the filter's impulse response; its group delay 1.5 /
# f_o; the converters' datasheets, as remembered), and the transducer's analogue output updates to each word a
# processing latency T_lat (3.5 ... 6 ms: its signal processor's own averaging and the output stage, as a datasheet's
# order of magnitude, as remembered) after the word's instant and holds it: the logged sample at t holds the word of the
# last instant t_m = m / f_o + phase with t_m + T_lat <= t: a dead time 2 / f_o + T_lat on average. Computed from the
# core on a grid SD_FINE times finer than 1 / f_o (the trapezoidal rule on the B-spline; checked in the test against a
# grid twice as fine).

SD_FINE = 32


def bspline3(u):
    """The quadratic B-spline on [0, 3] (the sinc^3 filter's impulse response in units of 1 / f_o; area 1)."""
    u = np.asarray(u, float)
    return np.where((u >= 0) & (u < 1), 0.5 * u * u,
                    np.where((u >= 1) & (u < 2), 0.5 * (-2 * u * u + 6 * u - 3),
                             np.where((u >= 2) & (u <= 3), 0.5 * (3 - u) ** 2, 0.0)))


def sd_words(t_fine, y_fine, fine):
    """The sinc^3 words at the instants t_fine[3 fine], t_fine[4 fine], ... (the grid `fine` points a word period,
    aligned to the instants): the trapezoidal rule of the B-spline's weight over the last three word periods."""
    k = np.arange(3 * fine + 1)
    wts = bspline3(k / fine) / fine
    wts[0] *= 0.5
    wts[-1] *= 0.5
    idx = np.arange(3 * fine, len(t_fine), fine)
    words = np.zeros(len(idx))
    for j, wj in enumerate(wts):
        words += wj * y_fine[idx - j]
    return t_fine[idx], words


def sd_reading(t, t_words, words, T_lat, rest):
    """The logged reading at t: the last word whose instant plus T_lat is at or before t (the rest value before the
    first)."""
    m = np.searchsorted(t_words + T_lat, np.asarray(t, float) + 1e-12, side="right") - 1
    return np.where(m >= 0, words[np.maximum(m, 0)], rest)


# ---- initial state: the armature left magnetised by the maker's torque check ----
#
# The initial-state record's actuator came from the maker's end-of-line proof check, which held it at rho (1 ... 1.2)
# times its full torque one way (the side drawn) and cut the power without the demagnetising routine: the armature was
# left at its remanence from that peak (a residual control flux: a residual torque at 0 A). The record starts there, at
# 0 V.

def checked_armature(core, rho, side):
    """The armature after the maker's check: demagnetised, to side rho F_max and back to 0."""
    return Armature(core).ramp([side * rho * core["F_max"], 0.0])


# ---- two effects: a rubber series-elastic element's creep, read over a fieldbus ----
#
# The pair record's actuator drives a robot joint through a rubber torsion spring (a series-elastic element of
# polyurethane bonded between two hubs) and the joint's encoder reads the spring's twist (deg). The rubber creeps: its
# compliance is a Prony series J(t) = J_0 [1 + sum_k c_k (1 - e^(-t / tau_k))] (tau_k 0.4, 4 and 40 s, the c_k summing
# to 0.26 ... 0.36: a soft filled polyurethane's creep over those decades, as remembered; Boltzmann's superposition,
# Ferry's Viscoelastic Properties of Polymers), so the twist is theta = J_0 (T + sum_k c_k q_k), dq_k/dt = (T - q_k) /
# tau_k, exact per interval for the torque linear between instants (relax_linear).
#
# The encoder's position is latched at every cycle of the joint's fieldbus (a CANopen-like SYNC cycle T_c 2 ... 3.5 ms,
# its phase against the logger's clock drawn) and reaches the logger L cycles later (4 ... 6: the bus's frames and the
# controller's tasks), which holds the latest it has: the logged sample at t is the twist at the last latch instant s_k
# <= t - L T_c (a dead time of L T_c plus up to a cycle).

def rubber_twist(t, T, J0, c, tau):
    """The twist J_0 (T + sum_k c_k q_k), q_k relaxing toward the torque T (linear between the times t) at tau_k, from
    rest at T[0]."""
    q = relax_linear(t, T, tau, T[0])
    return J0 * (np.asarray(T, float) + q @ np.asarray(c, float))


def bus_instants(t, T_c, phase, L):
    """The latch instant whose position the logger holds at each time t: the last k T_c + phase <= t - L T_c; -inf
    before the first."""
    k = np.floor((np.asarray(t, float) - L * T_c - phase) / T_c + 1e-9)
    return np.where(k >= 0, phase + k * T_c, -np.inf)


# ---- out of vocabulary: clutch B's input belt crossed ----
#
# The out-of-vocabulary record's actuator was rebuilt with clutch B's input belt crossed the wrong way: both inputs now
# spin the same way, so both clutches drag the output the same way and the sensor reads T_A + T_B = K [tau_y(H_g(B_m +
# B_c)) + tau_y(H_g(B_m - B_c))], even in the control flux: the magnet's torque of both at rest, and toward both ends of
# the swing the reading departs from it the same way (down where Carlson's tanh bends the stronger gap's stress, up
# where the fluid's saturation steepens its field), with the armature's hysteresis in it: a fold that no monotone map of
# the core draws. The record carries only the drive.

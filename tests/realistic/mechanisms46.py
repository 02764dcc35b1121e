"""Mechanisms of the HOLDOUT46 set (``cases_holdout46.py``), each written from its law; the signals are in
:mod:`.signals46`.

Nothing here imports hystcomp (nor another set's mechanisms). Every mechanism takes the potential the potentiostat sets
(from the clean drive), or the core's charge or reading, and returns the response; all are causal.

Citations: every source below was written from memory in this session (none was re-read); volumes, pages and years may
be off, and so may the material constants quoted (they are typical values as remembered, not a datasheet's). The laws
do not rest on them: each is checked in tests/test_realistic_holdout46.py against an independent solution (brentq of
every domain's isotherm, quad of its free energy, Radau (solve_ivp) of the domains' thermally activated switching and
of their electron-transfer kinetics, a method-of-lines solution of the water's diffusion, Radau of the overoxidation,
closed forms).
"""

import math

import numpy as np
from numba import njit
from scipy.special import ndtri


# ---- the rate-independent core: a polypyrrole bilayer bender under a potentiostat ----
#
# A polypyrrole film doped with dodecylbenzenesulfonate, PPy(DBS), 1.5 ... 3 um thick, grown electrochemically on the
# gold-coated face of a polyimide strip (100 ... 130 um, 10 ... 14 mm free), the classic conducting-polymer bilayer
# bender (Pei & Inganas, Adv. Mater. 4 (1992) 277; Smela, Inganas & Lundstrom, Science 268 (1995) 1735), stands in an
# aqueous NaDBS electrolyte in a three-electrode cell: a potentiostat sets the film's potential against an Ag/AgCl
# reference from the drive, and a laser triangulation sensor reads the strip's deflection (um) at x_m, 0.85 ... 0.95 of
# its free length. Potentials are in units of kT/e (25.69 mV at 25 C), measured from the potential at 0 V, E_mid.
#
# Redox: the big DBS anion is held in the film, so oxidising it expels Na+ (with its water) and reducing it takes Na+
# in: the film's volume, and so the bilayer's curvature, follows its charge (the strain-to-charge ratio is about
# constant; the film is stiff against the electrolyte's pressure). The film's charge is a capacitive (double-layer)
# part, c E, and a faradaic part, the mean oxidation of its domains. The domains: regions of chains that oxidise and
# reduce together, each a lattice gas of redox sites with an attraction between oxidised neighbours (the Frumkin
# isotherm; Frumkin 1925, in the form Laviron used for surface-bound redox couples with interactions, J. Electroanal.
# Chem. 52 (1974) 395): in the mean field, domain i at potential E holds the oxidised fraction theta where
#     E - E_i = ln(theta / (1 - theta)) + g_i (1 - 2 theta),
# E_i its formal potential, g_i > 2 its interaction (in kT). For g > 2 the right side is not monotone: between its
# spinodal points theta_-+ = (1 -+ s) / 2, s = sqrt(1 - 2 / g), three roots, and the domain, a small system that
# switches as a whole, keeps its branch until the branch ends at a spinodal, then jumps to the other (the hysteresis
# of a many-particle insertion electrode: Dreyer, Jamnik, Guhlke, Huth, Moskon & Gaberscek, Nature Mater. 9 (2010)
# 448). It jumps up at x = E - E_i = +Delta and down at -Delta,
#     Delta(g) = g s - 2 artanh(s),
# and along a branch theta moves reversibly. The film is many domains, their formal potentials spread (the broad
# voltammogram of polypyrrole) as a normal distribution of spread sig (9.5 ... 12 kT/e: 240 ... 310 mV) about mu (-1
# ... 1), their g - 2 log-normal (median 1.8 ... 2.6, the log's spread 0.4 ... 0.5; Delta from about 0.2 to 3 kT/e).
# The model represents them by 600 classes of equal weight, a quasi-random sample of that joint distribution (a
# golden-ratio lattice, randomly shifted: class k at the (k + shift) / 600 quantile of E_i and the fractional part of
# k 0.618... + shift' of g), so that 600 classes stand for the film's very many domains without a random draw's lumps.
# The capacitive share c is 0.02 ... 0.035 of the faradaic capacity per kT/e.
#
# The bilayer: a film much thinner than its substrate, so Stoney's limit of Timoshenko's bimetal formula (Timoshenko, J.
# Opt. Soc. Am. 11 (1925) 233; Stoney 1909) gives the curvature kappa = 6 n t_f eps / t_s^2 (n the film's modulus over
# the substrate's, 0.25 ... 0.45; eps the film's free strain, beta (q - q_0), beta 0.8 ... 1.5 % between fully reduced
# and fully oxidised), and the reading at x_m is the small deflection kappa x_m^2 / 2: y = Y (q - q_0), Y = 3 n t_f beta
# x_m^2 / t_s^2, a few hundred um per unit charge; its sign set so that oxidation reads positive. (The strip's slope at
# the spot stays under 0.04 rad on the bipolar records, under 0.08 on the unipolar and 0.12 on the water-bent strip of
# the drift record; the small deflection is then within 0.4 % of the circular arc's, (kappa x)^2 / 4 at most: a
# simplification kept.)
#
# Rate independent, with return-point memory (every domain a hysteron of E; the film a Preisach model). Not a
# Prandtl-Ishlinskii model: the domains' switching potentials are spread as a normal distribution, not uniformly, and
# their branches are curved.
#
# The rest state: the film was grown at the potential E_mid (the set's 0 V) and every domain formed there in its stable
# state (the branch of lower free energy; by the isotherm's symmetry, oxidised if E_mid > E_i: the Maxwell rule); the
# cell then rests at its open-circuit potential, E_mid, and the potentiostat is switched on there, at 0 V, with no
# current: the record starts from that state (the Preisach "demagnetised" state), unipolar and bipolar records alike.
# No settling routine is run.

N_DOM = 600
KT_E_MV = 25.69
GOLDEN = (math.sqrt(5.0) - 1.0) / 2.0


def domains(seed, n=N_DOM, sig=10.0, mu=0.0, g_med=2.2, g_spread=0.45):
    """The domains' formal potentials E_i, interactions g_i and weights (1 / n each): a golden-ratio lattice over the
    joint distribution (E_i normal about mu with spread sig, g_i - 2 log-normal about g_med with spread g_spread),
    randomly shifted by the seed."""
    rng = np.random.default_rng(seed)
    sh = rng.uniform(size=2)
    k = np.arange(n)
    a = (k + 0.05 + 0.9 * sh[0]) / n
    b = (k * GOLDEN + sh[1]) % 1.0
    b = np.clip(b, 0.5 / n, 1.0 - 0.5 / n)
    Ei = mu + sig * ndtri(a)
    gi = 2.0 + g_med * np.exp(g_spread * ndtri(b))
    return Ei, gi, np.full(n, 1.0 / n)


def spinodal(g):
    """The lower spinodal point theta_- = (1 - s) / 2 and the switching half-width Delta = g s - 2 artanh(s), s = sqrt(1
    - 2 / g) (g > 2)."""
    g = np.asarray(g, float)
    s = np.sqrt(1.0 - 2.0 / g)
    return (1.0 - s) / 2.0, g * s - 2.0 * np.arctanh(s)


def isotherm(theta, g):
    """The potential above E_i at which a domain holds theta: ln(theta / (1 - theta)) + g (1 - 2 theta)."""
    theta = np.asarray(theta, float)
    return np.log(theta / (1.0 - theta)) + g * (1.0 - 2.0 * theta)


_D_CACHE = {}


def core_domains(core):
    """The core's domains (E_i, g_i, w_i, Delta_i), cached by their parameters."""
    key = (core["dseed"], core.get("n", N_DOM), core["sig"], core["mu"], core["g_med"], core["g_spread"])
    if key not in _D_CACHE:
        Ei, gi, w = domains(*key)
        _D_CACHE[key] = (Ei, gi, w, spinodal(gi)[1])
    return _D_CACHE[key]


@njit(cache=True)
def _bracketed_root(x, g, lo, hi, z, rising):
    """The logit z of a root of F(z) = z + g (1 - 2 theta) - x in [lo, hi], where F rises (`rising`, a stable branch)
    or falls (the unstable middle): Newton's method from z, kept inside the bracket (bisection when a step leaves it).
    Where the bracket holds no root, the end it closes on."""
    for _ in range(200):
        sg = 1.0 / (1.0 + math.exp(-z))
        F = z + g * (1.0 - 2.0 * sg) - x
        if abs(F) <= 4e-16 * (abs(z) + g + abs(x)):
            return z
        if (F > 0) == rising:
            hi = z
        else:
            lo = z
        dF = 1.0 - 2.0 * g * sg * (1.0 - sg)
        zn = z - F / dF if (dF > 0.0 if rising else dF < 0.0) else 0.5 * (lo + hi)
        if not (lo <= zn <= hi) or zn == z:
            zn = 0.5 * (lo + hi)
            if zn == lo or zn == hi:
                return z
        z = zn
    return z


@njit(cache=True)
def _branch_root(x, g, branch, z0):
    """The logit z = ln(theta / (1 - theta)) of the root of z + g (1 - 2 theta) = x on the branch (0 the reduced, below
    theta_-; 1 the oxidised, above theta_+): Newton's method from z0, kept inside a bracket (bisection when a step
    leaves it). Where the branch has no root, the end of the bracket at the spinodal."""
    s = math.sqrt(1.0 - 2.0 / g)
    zs = math.log((1.0 - s) / (1.0 + s))
    if branch == 0:
        lo, hi = x - g, zs
    else:
        lo, hi = -zs, x + g
    return _bracketed_root(x, g, lo, hi, min(max(z0, lo), hi), True)


@njit(cache=True)
def _run_qs(E, Ei, gi, wi, Dl, st, z):
    out = np.empty(E.shape[0])
    for k in range(E.shape[0]):
        acc = 0.0
        for i in range(Ei.shape[0]):
            x = E[k] - Ei[i]
            if x > Dl[i]:
                st[i] = 1
            elif x < -Dl[i]:
                st[i] = 0
            z[i] = _branch_root(x, gi[i], st[i], z[i])
            acc += wi[i] / (1.0 + math.exp(-z[i]))
        out[k] = acc
    return out


def ground_state(core, E0=0.0):
    """Every domain in its stable state at E0 (oxidised if E0 > E_i, the Maxwell rule): the branches and their
    logits."""
    Ei, gi, _, _ = core_domains(core)
    st = (E0 > Ei).astype(np.int64)
    z = np.array([_branch_root(E0 - e, g, s, 0.0) for e, g, s in zip(Ei, gi, st)])
    return st, z


def film_path(core, E, state=None, return_state=False):
    """The faradaic charge (the domains' mean oxidation) along the potential E (rate independent) from the state (the
    branches and logits; default the rest state, :func:`ground_state` at 0)."""
    Ei, gi, w, Dl = core_domains(core)
    st, z = ground_state(core) if state is None else state
    st, z = np.array(st, np.int64), np.array(z, float)
    q = _run_qs(np.ascontiguousarray(E, dtype=float), Ei, gi, w, Dl, st, z)
    return (q, (st, z)) if return_state else q


def potential(core, v):
    """The film's potential above E_mid (kT/e) for the drive v: dE v / amp (bipolar), dE_top v / top (unipolar)."""
    v = np.asarray(v, float)
    if core["unipolar"]:
        return core["dE_top"] * v / core["top"]
    return core["dE"] * v / core["amp"]


def charge(core, E, qF):
    """The film's charge (in units of its faradaic capacity): the faradaic part and the double layer's c E."""
    return np.asarray(qF, float) + core["c"] * np.asarray(E, float)


def q_rest(core):
    """The charge of the rest state at 0 V (the as-grown film, flat)."""
    st, z = ground_state(core)
    _, _, w, _ = core_domains(core)
    return float(w @ (1.0 / (1.0 + np.exp(-z))))


def reading(core, q):
    """The laser's reading (um): Y (q - q_0)."""
    return core["Y"] * (np.asarray(q, float) - q_rest(core))


def bilayer_gain(t_f, t_s, n_mod, beta, x_m):
    """Y (um per unit charge): Stoney's curvature 6 n t_f beta / t_s^2 read as the deflection at x_m (lengths in m)."""
    return 1e6 * 3.0 * n_mod * t_f * beta * x_m ** 2 / t_s ** 2


def core_of(core, v, state=None):
    """The laser's reading of the rate-independent film for the drive v (from the state; default the rest state)."""
    E = potential(core, v)
    return reading(core, charge(core, E, film_path(core, E, state=state)))


# ---- creep: thermally activated switching of the domains ----
#
# A domain on a branch that is no longer its stable one is metastable: it can cross to the other over the free-energy
# barrier between them, thermally (nucleation in a small system; the barrier vanishes at the spinodal as the distance
# to it to the 3/2). In the mean field a domain of n_s sites has the free energy n_s f(theta), in kT,
#     f(theta) = theta ln theta + (1 - theta) ln(1 - theta) + g theta (1 - theta) - x theta,   x = E - E_i,
# whose stationary points are the isotherm's three roots theta_a < theta_b < theta_c: the barriers from the reduced and
# the oxidised minimum are B_a = n_s (f(theta_b) - f(theta_a)) and B_c = n_s (f(theta_b) - f(theta_c)). Each class of
# domains then holds a share p on its oxidised branch that obeys the master equation
#     dp/dt = nu e^-B_a (1 - p) - nu e^-B_c p
# (Arrhenius with an attempt rate nu; Kramers' prefactor folded into nu), exact per sample with the potential held over
# it (the potentiostat's DAC holds it): p relaxes toward its equilibrium share at the rate the sum of the two. Outside
# the bistable range p is 1 above it and 0 below (the metastable branch has ended). With a spread of distances to the
# spinodals, the share that has crossed after a move grows about as ln t at first (after Street & Woolley's magnetic
# viscosity, Proc. Phys. Soc. A 62 (1949) 562, here for a redox film), then slower as the classes near their
# equilibrium shares (the barriers are bounded by their height at the Maxwell point, a few kT for these domains). The
# creep record's film is grown thin at a low current density: small cooperative domains, n_s 20 ... 30 sites; nu 10 /s
# (a cooperative rearrangement of the chains; chosen, not quoted). The rest state is the same as the core's.

NU_CREEP = 10.0


@njit(cache=True)
def _mid_root(x, g):
    """The logit of the unstable (middle) root of the isotherm, between the spinodal points (Newton's method kept in a
    bracket)."""
    s = math.sqrt(1.0 - 2.0 / g)
    zs = math.log((1.0 - s) / (1.0 + s))
    return _bracketed_root(x, g, zs, -zs, 0.0, False)      # from the bracket's middle


@njit(cache=True)
def _f(z, g, x):
    """The free energy per site (kT) at the logit z."""
    th = 1.0 / (1.0 + math.exp(-z))
    if z >= 0.0:
        mix = -math.log1p(math.exp(-z)) - (1.0 - th) * z
    else:
        mix = th * z - math.log1p(math.exp(z))
    return mix + g * th * (1.0 - th) - x * th


@njit(cache=True)
def _creep_step(x, g, Dl, ns, nu, dt, p, za, zc):
    """One sample of a class held at x: its share p on the oxidised branch, the logits of both branches; returns the
    class's mean oxidation, p, za, zc."""
    if x > Dl:
        zc = _branch_root(x, g, 1, zc)
        return 1.0 / (1.0 + math.exp(-zc)), 1.0, za, zc
    if x < -Dl:
        za = _branch_root(x, g, 0, za)
        return 1.0 / (1.0 + math.exp(-za)), 0.0, za, zc
    za = _branch_root(x, g, 0, za)
    zc = _branch_root(x, g, 1, zc)
    fb = _f(_mid_root(x, g), g, x)
    kab = nu * math.exp(-ns * (fb - _f(za, g, x)))
    kcb = nu * math.exp(-ns * (fb - _f(zc, g, x)))
    ks = kab + kcb
    if ks > 0.0:
        peq = kab / ks
        p = peq + (p - peq) * math.exp(-ks * dt)
    tha = 1.0 / (1.0 + math.exp(-za))
    thc = 1.0 / (1.0 + math.exp(-zc))
    return (1.0 - p) * tha + p * thc, p, za, zc


@njit(cache=True)
def _run_creep(E, dt, Ei, gi, wi, Dl, ns, nu, p, za, zc):
    out = np.empty(E.shape[0])
    for k in range(E.shape[0]):
        acc = 0.0
        for i in range(Ei.shape[0]):
            th, p[i], za[i], zc[i] = _creep_step(E[k] - Ei[i], gi[i], Dl[i], ns, nu, dt, p[i], za[i], zc[i])
            acc += wi[i] * th
        out[k] = acc
    return out


def creep_path(core, E, dt, ns, nu=NU_CREEP, return_state=False):
    """The faradaic charge along E (held over every sample of dt) with thermally activated switching (n_s sites a
    domain, attempt rate nu), from the rest state."""
    Ei, gi, w, Dl = core_domains(core)
    st, z = ground_state(core)
    p = st.astype(float)
    za = np.where(st == 0, z, -10.0)
    zc = np.where(st == 1, z, 10.0)
    q = _run_creep(np.ascontiguousarray(E, dtype=float), float(dt), Ei, gi, w, Dl, float(ns), float(nu), p, za, zc)
    return (q, (p, za, zc)) if return_state else q


# ---- rate dependence: the domains' finite electron-transfer rate ----
#
# Each domain exchanges electrons with the gold at a finite rate: Butler-Volmer kinetics with the Frumkin interaction
# in the activation (symmetric, alpha = 1/2; Laviron's kinetics of surface-bound couples, J. Electroanal. Chem. 101
# (1979) 19, with the interaction as in his 1974 paper):
#     dtheta/dt = k0 [(1 - theta) e^(y / 2) - theta e^(-y / 2)],   y = E - E_i - g (1 - 2 theta),
# whose rest points are the isotherm's roots (stable on its rising branches, unstable between). Driven slowly a domain
# follows its branch and jumps at the spinodal, the core; driven fast it lags (most near its switching, where its
# relaxation slows), so the loops widen with the drive's speed (the peak separation of a quasi-reversible
# voltammogram). The rate record's film: k0 25 ... 50 /s (a thick, compact film; chosen). Solved per domain with the
# potential linear between samples, in RATE_SUB substeps of the two-stage, second-order, L-stable singly diagonally
# implicit Runge-Kutta method (gamma = 1 - 1 / sqrt(2); Alexander 1977, as remembered), each stage's implicit equation
# by Newton's method kept inside (0, 1).

RATE_SUB = 2
GAMMA = 1.0 - 1.0 / math.sqrt(2.0)


@njit(cache=True)
def _be_solve(base, x0, g, kh):
    """The theta in (0, 1) with theta - base - kh [(1 - theta) e^(y/2) - theta e^(-y/2)] = 0, y = x0 - g (1 - 2
    theta): Newton's method from base, kept inside a bracket."""
    lo, hi = 0.0, 1.0
    th = min(max(base, 0.0), 1.0)
    for _ in range(200):
        y = x0 - g * (1.0 - 2.0 * th)
        ep = math.exp(0.5 * y)
        em = 1.0 / ep
        G = th - base - kh * ((1.0 - th) * ep - th * em)
        if G > 0.0:
            hi = th
        else:
            lo = th
        dG = 1.0 - kh * (-ep + (1.0 - th) * g * ep - em + th * g * em)
        tn = th - G / dG if dG > 0.0 else 0.5 * (lo + hi)
        if not (lo <= tn <= hi):
            tn = 0.5 * (lo + hi)
        if abs(tn - th) <= 1e-16 + 1e-14 * th:
            return tn
        th = tn
    return th


@njit(cache=True)
def _run_kinetics(E, E_before, dt, nsub, Ei, gi, wi, k0, th):
    out = np.empty(E.shape[0])
    h = dt / nsub
    gm = 1.0 - 1.0 / math.sqrt(2.0)
    c = (1.0 - gm) / gm
    Ep = E_before
    for k in range(E.shape[0]):
        for j in range(nsub):
            e1 = Ep + (E[k] - Ep) * (j + gm) / nsub
            e2 = Ep + (E[k] - Ep) * (j + 1.0) / nsub
            for i in range(Ei.shape[0]):
                y0 = th[i]
                Y1 = _be_solve(y0, e1 - Ei[i], gi[i], k0 * gm * h)
                th[i] = _be_solve(y0 + c * (Y1 - y0), e2 - Ei[i], gi[i], k0 * gm * h)
        Ep = E[k]
        acc = 0.0
        for i in range(Ei.shape[0]):
            acc += wi[i] * th[i]
        out[k] = acc
    return out


def kinetic_path(core, E, dt, k0, nsub=RATE_SUB, return_state=False):
    """The faradaic charge along E (linear between samples, at rest at E[0] before the first) with the domains'
    electron-transfer rate k0 (/s), from the rest state."""
    Ei, gi, w, _ = core_domains(core)
    _, z = ground_state(core)
    th = 1.0 / (1.0 + np.exp(-z))
    E = np.ascontiguousarray(E, dtype=float)
    q = _run_kinetics(E, float(E[0]), float(dt), int(nsub), Ei, gi, w, float(k0), th)
    return (q, th) if return_state else q


# ---- drift: the polyimide strip taking up water ----
#
# The strip was put into the electrolyte t0 (3 ... 8 min) before the record; its polyimide takes up water through its
# bare face (the gold seals the other) by Fickian diffusion (D 2e-13 ... 4e-13 m^2/s as remembered for water in a
# polyimide film; Crank, The Mathematics of Diffusion, 1975, for the slab's series) and swells where the water is
# (strain alpha_w c / c_inf). A swelling that varies through the thickness bends the strip: for a free strip of
# uniform modulus (the thin film's stiffness neglected), kappa = -(12 / t_s) alpha_w int_0^1 (c / c_inf) (zeta - 1/2)
# dzeta, zeta = z / t_s from the sealed face. In the slab sealed at zeta = 0 and wet at zeta = 1,
#     c / c_inf = 1 - sum_p (2 (-1)^p / a_p) cos(a_p zeta) e^(-a_p^2 tau),   a_p = (2p + 1) pi / 2,   tau = D t / t_s^2,
# so the moment is M(tau) = -sum_p (1 / a_p^2 - 2 (-1)^p / a_p^3) e^(-a_p^2 tau) (0 dry and 0 saturated, positive in
# between). The reading, kappa x_m^2 / 2, drifts by -A (M(tau(t)) - M(tau(0))), A = 6 alpha_w x_m^2 / t_s (the swelling
# face, away from the film, bends the strip away from the laser); alpha_w solved in the case so that the drift by the
# end is its drawn share of the core's stroke (0.1 ... 0.2 % in these records: about the saturated swelling of a
# polyimide, 0.2 % as remembered). An offset drift: the film's charge is untouched.

def uptake_moment(tau, n_modes=400):
    """M(tau) = int_0^1 (c / c_inf)(zeta - 1/2) dzeta for the slab sealed at 0 and wet at 1 from tau = 0 (tau >= 1e-4
    here: the series converges to 1e-15 with 400 modes)."""
    tau = np.asarray(tau, float)
    a = (2.0 * np.arange(n_modes) + 1.0) * math.pi / 2.0
    b = 1.0 / a ** 2 - 2.0 * (-1.0) ** np.arange(n_modes) / a ** 3
    return -np.exp(-np.multiply.outer(tau, a ** 2)) @ b


# ---- asymmetry: the film's modulus following its oxidation ----
#
# Polypyrrole's Young's modulus changes with its oxidation state (stiffer oxidised: reported by several groups from in
# situ tensile and bending tests, by a factor up to 2 ... 3 in some electrolytes; as remembered). The asymmetry record's
# film is run in an electrolyte where it does (its oxidised state E_ox = r_E E_red, r_E 1.8 ... 2.6; the other records'
# films are taken as of constant modulus: a choice), the modulus by the rule of mixtures in the oxidised fraction,
# E_f(q_F) = E_red (1 + (r_E - 1) q_F). In Stoney's limit the curvature is proportional to the film's modulus times its
# free strain, so the reading is y = Y (E_f(q_F) / E_f(q_F0)) (q - q_0): steeper on the oxidised side than on the
# reduced, a monotone (for these r_E) but skewed map of the charge.

def stiffening_reading(core, q, qF, r_E):
    """The reading with the modulus r_E times higher oxidised than reduced (rule of mixtures in q_F), scaled to the rest
    state's."""
    qF0 = q_rest(core)
    return core["Y"] * (1.0 + (r_E - 1.0) * np.asarray(qF, float)) / (1.0 + (r_E - 1.0) * qF0) * (
        np.asarray(q, float) - qF0)


# ---- saturation: the film's redox capacity exhausted ----
#
# Driven 2.2 ... 2.8 times its rated swing, the film runs out of domains to oxidise at the top and to reduce at the
# bottom (the normal distribution's tails): its charge flattens but for the double layer (the swing kept inside the
# electrolyte's window: chosen).


# ---- delay: the laser sensor's sampling and latency ----
#
# The laser triangulation sensor samples the strip at its own rate f_L (2 ... 5 kHz; the phase of its clock against the
# data acquisition's drawn) and updates its analogue output a processing latency T_p (6 ... 10 ms, its averaging and
# output stage as a datasheet's order of magnitude, as remembered) later, holding it until the next update: the
# recorded sample at t holds the strip's position at the last sensor instant s <= t - T_p, a dead time of T_p plus a
# hold of up to 1 / f_L (T_p + 1 / (2 f_L) on average).

def sensor_instants(t, T_p, f_L, phase):
    """The sensor's sampling instant whose value the output holds at each time t: the last k / f_L + phase <= t - T_p
    (phase in [0, 1 / f_L)); before the first, the first instant's value is not yet out and the output holds the rest
    value (returned as -inf)."""
    t = np.asarray(t, float)
    TL = 1.0 / f_L
    k = np.floor((t - T_p - phase) / TL)
    s = phase + k * TL
    return np.where(k >= 0, s, -np.inf)


# ---- initial state: a film grown above the record's middle ----
#
# The initial-state record's film was grown at E_g = rho dE above the middle (rho 1.15 ... 1.45: a higher growth
# potential), every domain formed in its stable state there; the potentiostat was then switched to the record's 0 V:
# the potential stepped down from E_g to E_mid, and the domains oxidised at E_g whose lower spinodal lies below E_mid
# stay oxidised. The record starts there at 0 V.

def grown_at(core, E_g, n=400):
    """The state (branches, logits) of a film grown at E_g and then taken down to 0 (n steps)."""
    st, z = ground_state(core, E_g)
    _, state = film_path(core, np.linspace(E_g, 0.0, n + 1)[1:], state=(st, z), return_state=True)
    return state


# ---- two effects: the clamp's pad creeping (drift) and the film overoxidised (gain drift) ----
#
# Drift: the strip's root is held between a steel jaw and a PTFE pad by a screw tightened t_c (20 ... 60 s) before the
# record; the pad creeps under the screw's force as PTFE does, logarithmically in time after the load (a choice of
# law, the polymer's log creep; e.g. Struik, Physical Aging in Amorphous Polymers, 1978, as remembered), and the jaw
# follows it, carrying the strip's root, and the whole strip, sideways toward the pad:
#     delta(t) = d_c [ln(1 + (t + t_c) / tau_c) - ln(1 + t_c / tau_c)],   tau_c 5 ... 20 s,
# d_c solved so that the drift by the end is its drawn share of the core's stroke (15 ... 25 um in these records: a
# 1 mm pad creeping by about 2 %, an order of magnitude PTFE reaches under a clamping stress, as remembered).
#
# Gain drift: the top of the swing lies close to polypyrrole's overoxidation (an irreversible oxidation that takes the
# polymer's conjugation and with it its electroactivity; Pud's review of the stability of conducting polymers, Synth.
# Met. 66 (1994) 1, as remembered); the active fraction a falls at a rate exponential in the potential (Tafel-like),
#     da/dt = -k_ox a exp((E - dE) / b_ox),   b_ox 1.5 ... 2.5 kT/e,
# so a(t) = exp(-k_ox I(t)), I the integral of the exponential (exact for E linear between samples), k_ox solved so
# that 18 ... 28 % of the film is lost by the end. The overoxidised polymer no longer swells or shrinks: its share's
# strain stays at the grown film's (a choice; its dopant's loss ignored), so the reading is a(t) Y (q - q_0): a gain
# falling with the time spent near the top.

def overoxidation_integral(t, E, dE, b_ox):
    """I(t) = int_0^t exp((E - dE) / b_ox) ds with E linear between samples (exact per interval)."""
    t = np.asarray(t, float)
    u = (np.asarray(E, float) - dE) / b_ox
    du = np.diff(u)
    eu = np.exp(u)
    small = np.abs(du) < 1e-8
    seg = np.where(small, eu[:-1] * (1.0 + du / 2.0), (eu[1:] - eu[:-1]) / np.where(small, 1.0, du)) * np.diff(t)
    return np.r_[0.0, np.cumsum(seg)]


def clamp_creep(t, t_c, tau_c):
    """The clamp's log creep shape ln(1 + (t + t_c) / tau_c) - ln(1 + t_c / tau_c) (d_c = 1)."""
    t = np.asarray(t, float)
    return np.log1p((t + t_c) / tau_c) - math.log1p(t_c / tau_c)


# ---- out of vocabulary: the film exchanging anions above its as-grown charge ----
#
# Run in NaCl instead of NaDBS, the film takes in the small Cl- anion when it is oxidised beyond its as-grown charge q_0
# (the DBS it holds compensates only that much), and anions entering swell it as cations entering do on reduction
# (mixed ion transport; the bending-beam studies of polypyrrole's ion exchange, e.g. Pei & Inganas, J. Phys. Chem. 97
# (1993) 6034, as remembered): the free strain falls with the charge below q_0 and rises above it, a V rounded over w
# by the gradual exclusion of the anion, the anions' swelling r times the cations' (r 0.6 ... 1.1):
#     y = Y [((1 - r) / 2)(q - q_0) - ((1 + r) / 2)(sqrt((q - q_0)^2 + w^2) - w)],
# so the reading is highest at the as-grown charge and falls on both sides: a fold no monotone map of the charge draws.
# The record does not carry the exchange: nothing of it is in the drive.

def mixed_ion_reading(core, q, r, w):
    """The reading of a film exchanging cations below its as-grown charge and anions (r times the swelling) above."""
    d = np.asarray(q, float) - q_rest(core)
    return core["Y"] * ((1.0 - r) / 2.0 * d - (1.0 + r) / 2.0 * (np.sqrt(d * d + w * w) - w))

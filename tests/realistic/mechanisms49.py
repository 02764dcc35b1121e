"""Mechanisms of the HOLDOUT49 set (``cases_holdout49.py``), each written from its law; the signals are in
:mod:`.signals49`.

Nothing here imports hystcomp (the one relaxation exact per interval, :func:`relax_linear`, is imported from
:mod:`.mechanisms47`, not copied). Every mechanism takes the coil's field that the current amplifier sets from the clean
drive, or the rod's state or reading, and returns the response; all are causal.

Citations: every source below was written from memory in this session (none was re-read); volumes, pages and years may
be off, and so may the material constants quoted (they are typical values as remembered, not a datasheet's). The laws
do not rest on them: each is checked in tests/test_realistic_holdout49.py against an independent solution (the domains'
energy minimised over the magnetisation's angle, the walls' thresholds by brentq, the rod's step written out there from
its definition; Radau (solve_ivp) of the shorted turn, of the coil's heat and of the bracket's warming; the power law's
own closed form for the carrier's creep; direct searches).
"""

import math

import numpy as np
from numba import njit
from scipy.special import ndtri

from .mechanisms47 import relax_linear

# ---- the rate-independent core: a Galfenol rod in a magnetostrictive actuator ----
#
# Galfenol (Clark, Wun-Fogle, Restorff and co-workers at NSWC Carderock, e.g. Clark et al., J. Appl. Phys. 93 (2003)
# 8621, as remembered) is a body-centred cubic iron-gallium alloy (Fe about 81, Ga about 19 at.%) whose tetragonal
# magnetostriction (3/2) lambda_100 reaches 250 ... 300 ppm (lambda_100 170 ... 200 ppm) at a small cubic anisotropy K_1
# (here 0.75 ... 0.9e4 J/m^3) and a saturation J_s = mu0 M_s of 1.50 ... 1.60 T (as remembered). The actuator's rod is
# grown <100>-textured along its axis (z), its cubic axes x, y, z; it is held in compression by a Belleville spring
# stack at sigma_0 (the stack set on its flat, so that the prestress hardly changes over the rod's few micrometres of
# stroke: taken as constant). The compression makes the in-plane easy axes [100] and [010] the rod's rest directions; a
# field H along z rotates a domain's magnetisation m = (sin theta, 0, cos theta) out of the plane against the energy
# density
#     E(theta) = K_1 sin^2(theta) cos^2(theta) + K_sigma cos^2(theta) - J_s H cos(theta),
#     K_sigma = (3/2) lambda_100 |sigma|
# (the cubic anisotropy restricted to the x-z plane, the magnetoelastic energy of a uniaxial compression along [001] and
# the Zeeman energy: the energy of Atulasimha & Flatau's and Armstrong's models of Fe-Ga, restricted to the plane the
# rotation stays in; Atulasimha & Flatau, Smart Mater. Struct. 20 (2011) 043001; Armstrong, J. Magn. Magn. Mater. 263
# (2003) 208; as remembered). In K_1's units, with c = cos theta, k = K_sigma / K_1 and h = J_s H / K_1,
#     e(c) = (1 - c^2) c^2 + k c^2 - h c,
# and an in-plane domain sits in the well about the plane, where de/dc = -4 c^3 + 2 (1 + k) c - h = 0: its c the middle
# root of that cubic, in closed form (the trigonometric roots)
#     c_m(h) = 2 c_s cos((arccos(-h / h_up) - 2 pi) / 3),  c_s = sqrt((1 + k) / 6),  h_up = (4 / 3) (1 + k) c_s,
# which exists while |h| <= h_up (the well's spinodal). An axial domain (c = 1, along z) has e_1 = k - h and is a
# minimum while h >= h_dn = 2 (k - 1). The strain along the rod is lambda = (3/2) lambda_100 (c^2 - 1/3) in each domain.
#
# Hysteresis (Armstrong's energy criterion for the walls, as remembered; written here as a Preisach ensemble): the walls
# between in-plane and axial domains are pinned. The rod is N_REG = 4000 regions, each swept from in-plane to axial
# by its wall when the driving force f(h) = e_m(h) - e_1(h) (the energy an axial domain saves, per volume) exceeds its
# pinning energy kappa_i above its internal bias u_i, f > u_i + kappa_i, and back when f < u_i - kappa_i; and at the
# spinodals at once (h > h_up: no in-plane well; h < h_dn: no axial one). f rises with h (df/dh = 1 - c_m > 0), so each
# region is a rectangular hysteron in h with the thresholds a_i (up) and b_i (down) found from f (by bisection, once per
# rod). The regions lie in N_CLASS = 32 classes of local stress (the rod's residual stresses about sigma_0: k = k_0 (1 +
# s_k z) at the 32 mid-quantiles z of a normal; k_0 1.9 ... 2.1, s_k 0.22 ... 0.28: sigma_0 = k_0 K_1 / ((3/2)
# lambda_100), about 47 ... 74 MPa), 125 regions a class, their pinning energies log-normal about kappa_m (0.06 ...
# 0.075 K_1, spread 0.4 ... 0.6) and their internal biases normal (spread s_u 0.02 ... 0.05 K_1), drawn on a Latin
# hypercube (each variable's 4000 quantile strata taken once, paired at random). The rod's mean axial magnetisation is
# m = sum_i w_i (xi_i + (1 - xi_i) c_m,i), xi_i in [0, 1] the share of region i that is axial.
#
# The magnetic circuit (a design chosen, not quoted): the rod, two steel end caps and a steel return tube, with the bias
# magnets (two NdFeB rings) in the return path. Their recoil permeability is about 1.05, so the circuit has an effective
# gap of their thickness: the rod's internal field is
#     h = h_src - gamma m,   gamma = N_eff J_s^2 / (mu0 K_1),   N_eff = g_eff / (l_rod + g_eff)
# (h_src the magnets' bias plus the coil's field, gamma 5.5 ... 6.5: N_eff about 0.02 ... 0.03). This shears the
# ensemble: a region switching raises m, lowers h and holds h at its threshold while it switches in part (xi_i in (0,
# 1)). The equilibrium at every drive: every region with xi_i < 1 has a_i >= h, every region with xi_i > 0 has b_i <= h,
# and h + gamma m(h) = h_src, solved per step by following the thresholds h passes in order (Newton with a bracket
# between them). Rate independent, with return-point memory (a Preisach model behind a monotone feedback).
#
# The drive: a current amplifier feeds the coil; the coil's field in h units is dh v / amp about the bias h_b on the
# bipolar records (dh 1.2 ... 1.5 at the full drive), and -dh + 2 dh v / top about it on the unipolar records (the
# unipolar build's magnets weaker: it rests at the swing's bottom). The bias is set so that the rod at rest sits at the
# median of the regions' centres (a_i + b_i) / 2: the middle of its burst region.
#
# The reading: a capacitive displacement gauge on the push rod's end (um), zeroed at the rod's rest before the record
# (the first sample's reading, the drive starting at 0): y = 1e3 L_0 (3/2) lambda_100 (q - q_rest), q = sum_i w_i (xi_i
# + (1 - xi_i) c_m,i^2) the mean c^2 (L_0 40 ... 60 mm).
#
# The rest state: the controller runs a demagnetising routine at power-up (a decaying alternating coil current about
# the bias), which leaves the rod in the Preisach demagnetised state about the rest field: every region axial whose
# centre (a_i + b_i) / 2 lies below the internal field h it then feels, the rest in plane, h + gamma m = h_src
# self-consistent (one region part-switched at h = its centre); the state is set so, not run, and tested in the test
# against a slow decaying alternating drive. Every record but the initial-state cases' starts there, at 0 V and 0 A.

N_CLASS = 32
N_PER = 125
N_REG = N_CLASS * N_PER
MU0 = 4e-7 * math.pi


def cm(h, k):
    """The in-plane domain's c = cos theta at the field h (the middle root of -4 c^3 + 2 (1 + k) c - h = 0), in
    closed form; h clipped to the well's spinodals +-h_up."""
    h = np.asarray(h, float)
    k = np.asarray(k, float)
    cs = np.sqrt((1.0 + k) / 6.0)
    hup = 4.0 / 3.0 * (1.0 + k) * cs
    return 2.0 * cs * np.cos((np.arccos(np.clip(-h / hup, -1.0, 1.0)) - 2.0 * math.pi) / 3.0)


def spinodals(k):
    """(h_up, h_dn): the in-plane well's end and the axial one's, in h units."""
    k = np.asarray(k, float)
    return 4.0 / 3.0 * (1.0 + k) * np.sqrt((1.0 + k) / 6.0), 2.0 * (k - 1.0)


def energy(c, h, k):
    """e(c) = (1 - c^2) c^2 + k c^2 - h c (K_1's units)."""
    c = np.asarray(c, float)
    return (1.0 - c * c) * c * c + k * c * c - h * c


def wall_force(h, k):
    """The driving force on the walls, f = e_m - e_1 (K_1's units): the in-plane well's energy less the axial one's."""
    return energy(cm(h, k), h, k) - (np.asarray(k, float) - np.asarray(h, float))


def _bisect_force(target, lo, hi, k, n_iter=80):
    """The h in [lo, hi] with wall_force(h, k) = target (vectorised bisection; f rises with h)."""
    lo = np.array(lo, float)
    hi = np.array(hi, float)
    for _ in range(n_iter):
        mid = 0.5 * (lo + hi)
        below = wall_force(mid, k) < target
        lo = np.where(below, mid, lo)
        hi = np.where(below, hi, mid)
    return 0.5 * (lo + hi)


def thresholds(k, u, kap):
    """Each region's thresholds in h: a (up: f = u + kappa, or the in-plane well's end h_up) and b (down: f = u -
    kappa, or the axial well's end h_dn), b <= a."""
    k = np.asarray(k, float)
    hup, hdn = spinodals(k)
    eu, ed = u + kap, u - kap
    a = np.where(wall_force(hup, k) <= eu, hup, _bisect_force(eu, -hup, hup, k))
    lo = np.maximum(hdn, -hup)
    b = np.where(wall_force(lo, k) >= ed, lo, _bisect_force(ed, lo, hup, k))
    return a, np.minimum(b, a)


def regions(seed, k0, s_k, kap_m, s_kap, s_u, n_class=N_CLASS, n_per=N_PER):
    """The rod's regions: the classes' k (k_0 (1 + s_k z) at the normal's mid-quantiles), each region's class, internal
    bias u and pinning energy kappa (a Latin hypercube from the seed: each variable's n quantile strata taken once, at
    a uniform point inside, paired by random permutations), thresholds a and b and weight (1 / n each)."""
    rng = np.random.default_rng(seed)
    n = n_class * n_per
    kc = k0 * (1.0 + s_k * ndtri((np.arange(n_class) + 0.5) / n_class))
    cls = np.repeat(np.arange(n_class), n_per)
    u1 = (rng.permutation(n) + rng.uniform(size=n)) / n
    u2 = (rng.permutation(n) + rng.uniform(size=n)) / n
    kap = kap_m * np.exp(s_kap * ndtri(u1))
    u = s_u * ndtri(u2)
    a, b = thresholds(kc[cls], u, kap)
    return kc, cls, u, kap, a, b, np.full(n, 1.0 / n)


_R_CACHE = {}


def rod_regions(core):
    """The rod's regions (cached by their parameters): dict of kc, cls, u, kap, a, b, w, ia (by rising a), ib (by
    falling b)."""
    key = (core["rseed"], core["k0"], core["s_k"], core["kap_m"], core["s_kap"], core["s_u"],
           core.get("n_class", N_CLASS), core.get("n_per", N_PER))
    if key not in _R_CACHE:
        kc, cls, u, kap, a, b, w = regions(*key)
        _R_CACHE[key] = dict(kc=kc, cls=cls, u=u, kap=kap, a=a, b=b, w=w, ia=np.argsort(a, kind="stable"),
                             ib=np.argsort(-b, kind="stable"))
    return _R_CACHE[key]


@njit(cache=True)
def _cm1(h, k):
    """c_m(h) for one class (clipped at the spinodals)."""
    cs = math.sqrt((1.0 + k) / 6.0)
    hup = 4.0 / 3.0 * (1.0 + k) * cs
    z = -h / hup
    if z > 1.0:
        z = 1.0
    elif z < -1.0:
        z = -1.0
    return 2.0 * cs * math.cos((math.acos(z) - 2.0 * math.pi) / 3.0)


@njit(cache=True)
def _force1(h, k):
    """The wall force f = e_m - e_1 for one class."""
    c = _cm1(h, k)
    return (1.0 - c * c) * c * c + k * c * c - h * c - (k - h)


@njit(cache=True)
def _sums(h, nax, nin, kc):
    """m, dm/dh (the in-plane domains' rotation) and the mean c^2 at the field h; nin the in-plane share of every class,
    nax the axial share."""
    m = nax
    c2 = nax
    dm = 0.0
    for j in range(kc.shape[0]):
        if nin[j] > 0.0:
            c = _cm1(h, kc[j])
            m += nin[j] * c
            c2 += nin[j] * c * c
            d = 2.0 * (1.0 + kc[j]) - 12.0 * c * c
            dm += nin[j] / (d if d > 1e-9 else 1e-9)
    return m, dm, c2


@njit(cache=True)
def _gval(h, H, gam, nax, nin, kc):
    """The balance h + gam m(h) - H, the regions' shares fixed."""
    m, _dm, _c2 = _sums(h, nax, nin, kc)
    return h + gam * m - H


@njit(cache=True)
def _root(lo, hi, H, gam, nax, nin, kc):
    """The h in [lo, hi] with h + gam m(h) = H, the regions' shares fixed (Newton's method kept in the bracket, a
    bisection wherever its step would leave it or fail to halve the bracket's last change: Numerical Recipes'
    rtsafe)."""
    h = 0.5 * (lo + hi)
    dx_old = hi - lo
    dx = dx_old
    for _ in range(300):
        m, dm, _c2 = _sums(h, nax, nin, kc)
        g = h + gam * m - H
        if g > 0.0:
            hi = h
        else:
            lo = h
        if abs(g) <= 1e-14 or hi - lo <= 1e-15:
            break
        d = 1.0 + gam * dm
        hn = h - g / d
        if not (lo < hn < hi) or abs(2.0 * g) > abs(dx_old * d):
            dx_old = dx
            dx = 0.5 * (hi - lo)
            hn = lo + dx
        else:
            dx_old = dx
            dx = abs(hn - h)
        h = hn
    return h


@njit(cache=True)
def _balance(H, gam, kc, cls, a, b, w, xi, nin, st, ia, ib, als, nbes):
    """One step of the rod to the source field H with the feedback gam: the regions whose thresholds h passes switch,
    the one whose switching holds h at its threshold switches in part (xi, nin, st = [h, nax] changed in place)."""
    n = a.shape[0]
    h = st[0]
    nax = st[1]
    g0 = _gval(h, H, gam, nax, nin, kc)
    if g0 < 0.0:
        j = np.searchsorted(als, h - 1e-12)
        done = False
        while j < n:
            r = ia[j]
            j += 1
            if xi[r] >= 1.0:
                continue
            gr = _gval(a[r], H, gam, nax, nin, kc)
            if gr >= 0.0:
                h = _root(h, a[r], H, gam, nax, nin, kc)
                done = True
                break
            c = cls[r]
            jump = gam * w[r] * (1.0 - _cm1(a[r], kc[c]))
            if gr + jump * (1.0 - xi[r]) >= 0.0:
                dx = -gr / jump
                xi[r] += dx
                nin[c] -= w[r] * dx
                nax += w[r] * dx
                h = a[r]
                done = True
                break
            nin[c] -= w[r] * (1.0 - xi[r])
            nax += w[r] * (1.0 - xi[r])
            xi[r] = 1.0
            h = a[r]
        if not done:
            hi = h + 1.0
            while _gval(hi, H, gam, nax, nin, kc) < 0.0:
                hi += 1.0
            h = _root(h, hi, H, gam, nax, nin, kc)
    elif g0 > 0.0:
        j = np.searchsorted(nbes, -(h + 1e-12))
        done = False
        while j < n:
            r = ib[j]
            j += 1
            if xi[r] <= 0.0:
                continue
            gr = _gval(b[r], H, gam, nax, nin, kc)
            if gr <= 0.0:
                h = _root(b[r], h, H, gam, nax, nin, kc)
                done = True
                break
            c = cls[r]
            jump = gam * w[r] * (1.0 - _cm1(b[r], kc[c]))
            if gr - jump * xi[r] <= 0.0:
                dx = gr / jump
                xi[r] -= dx
                nin[c] += w[r] * dx
                nax -= w[r] * dx
                h = b[r]
                done = True
                break
            nin[c] += w[r] * xi[r]
            nax -= w[r] * xi[r]
            xi[r] = 0.0
            h = b[r]
        if not done:
            lo = h - 1.0
            while _gval(lo, H, gam, nax, nin, kc) > 0.0:
                lo -= 1.0
            h = _root(lo, h, H, gam, nax, nin, kc)
    st[0] = h
    st[1] = nax


@njit(cache=True)
def _run(hs, gam, Gam, tb, kc, cls, a, b, w, xi, nin, st, ia, ib, als, nbes):
    """The rod along the source fields hs (one step each): returns the mean c^2, the mean magnetisation m and the field
    h. With tb > 0 a shorted turn (its time constant over the step, tb = tau_b / dt) opposing the flux phi = h + Gam m
    (implicit Euler: the balance h (1 + tb) + (gam + Gam tb) m = hs + tb phi_prev)."""
    N = hs.shape[0]
    out_c2 = np.empty(N)
    out_m = np.empty(N)
    out_h = np.empty(N)
    m0, _dm, _c2 = _sums(st[0], st[1], nin, kc)
    phi = st[0] + Gam * m0
    for i in range(N):
        if tb > 0.0:
            g2 = (gam + Gam * tb) / (1.0 + tb)
            H = (hs[i] + tb * phi) / (1.0 + tb)
        else:
            g2 = gam
            H = hs[i]
        _balance(H, g2, kc, cls, a, b, w, xi, nin, st, ia, ib, als, nbes)
        m, _dm, c2 = _sums(st[0], st[1], nin, kc)
        phi = st[0] + Gam * m
        out_c2[i] = c2
        out_m[i] = m
        out_h[i] = st[0]
    return out_c2, out_m, out_h


def mean_state(R, xi, h):
    """(m, mean c^2, nin, nax) of the regions' shares xi at the field h."""
    nin = np.bincount(R["cls"], R["w"] * (1.0 - xi), minlength=len(R["kc"]))
    nax = float(R["w"] @ xi)
    m, _dm, c2 = _sums(float(h), nax, nin, R["kc"])
    return m, c2, nin, nax


def rest_state(R, gam, H):
    """The Preisach demagnetised state at the source field H with the feedback gam: every region axial whose centre
    (a + b) / 2 lies below the field h, the rest in plane, h + gam m = H self-consistent (the region at h = its centre
    part-switched). Returns (xi, h)."""
    mid = 0.5 * (R["a"] + R["b"])
    o = np.argsort(mid, kind="stable")

    def G(h, xi):
        return h + gam * mean_state(R, xi, h)[0] - H

    def xi_at(h):
        return (mid < h).astype(float)
    lo, hi = -20.0, 20.0
    for _ in range(200):
        hm = 0.5 * (lo + hi)
        if G(hm, xi_at(hm)) > 0:
            hi = hm
        else:
            lo = hm
        if hi - lo < 1e-13:
            break
    # a centre between lo and hi: the region there part-switched; else a smooth root
    between = o[(mid[o] >= lo) & (mid[o] <= hi)]
    if len(between):
        r = between[0]
        h = float(mid[r])
        xi = xi_at(h)
        xi[r] = 0.0
        g = G(h, xi)
        c = R["cls"][r]
        jump = gam * R["w"][r] * (1.0 - float(cm(h, R["kc"][c])))
        xi[r] = min(max(-g / jump, 0.0), 1.0)
        return xi, h
    xi = xi_at(lo)
    nin = np.bincount(R["cls"], R["w"] * (1.0 - xi), minlength=len(R["kc"]))
    h = _root(lo - 1e-9, hi + 1e-9, float(H), float(gam), float(R["w"] @ xi), nin, R["kc"])
    return xi, h


class Rod:
    """The rod's regions and their state (xi; st = [h, nax]; nin per class), by default in the demagnetised state at
    the source field H (default the core's rest field); state="virgin": every region in plane at H = 0."""

    def __init__(self, core, H=None, state="demagnetised"):
        self.core = core
        self.R = R = rod_regions(core)
        self.gam = core["gamma"]
        self.als = np.ascontiguousarray(R["a"][R["ia"]])
        self.nbes = np.ascontiguousarray(-R["b"][R["ib"]])
        H = rest_field(core) if H is None else H
        if state == "demagnetised":
            self.xi, h = rest_state(R, self.gam, H)
        elif state == "virgin":
            if H != 0.0:
                raise ValueError("the virgin rod rests at H = 0")
            self.xi = np.zeros(len(R["a"]))
            h = 0.0
        else:
            raise ValueError(state)
        _m, _c2, self.nin, nax = mean_state(R, self.xi, h)
        self.st = np.array([h, nax])

    def copy(self):
        c = object.__new__(Rod)
        c.__dict__.update({k: (v.copy() if isinstance(v, np.ndarray) else v) for k, v in self.__dict__.items()})
        return c

    def state(self):
        """(m, mean c^2) now."""
        m, c2, _nin, _nax = mean_state(self.R, self.xi, self.st[0])
        return m, c2

    def run(self, hs, dt=0.0, tau_b=0.0, Gam=0.0):
        """The rod along the source fields hs: (mean c^2, m, h) per step, its state carried on. With a shorted turn of
        time constant tau_b over steps dt (Gam = J_s^2 / (mu0 K_1))."""
        R = self.R
        if tau_b > 0 and not dt > 0:
            raise ValueError("a shorted turn needs the step dt")
        hs = np.ascontiguousarray(np.atleast_1d(np.asarray(hs, float)))
        return _run(hs, float(self.gam), float(Gam), float(tau_b / dt) if tau_b > 0 else 0.0, R["kc"], R["cls"],
                    R["a"], R["b"], R["w"], self.xi, self.nin, self.st, R["ia"], R["ib"], self.als, self.nbes)


def bias(core):
    """The bias h_b (h units): the source field at which the demagnetised rod's internal field is the median of its
    regions' centres (the middle of its burst region)."""
    R = rod_regions(core)
    h0 = float(np.median(0.5 * (R["a"] + R["b"])))
    mid = 0.5 * (R["a"] + R["b"])
    m, _c2, _nin, _nax = mean_state(R, (mid < h0).astype(float), h0)
    return h0 + core["gamma"] * m


def rest_field(core):
    """The source field at rest (0 V): the bias h_b (bipolar) or the swing's bottom h_b - dh (unipolar)."""
    return core["hb"] - (core["dh"] if core["unipolar"] else 0.0)


def source_field(core, v, coil=1.0, magnets=1.0):
    """The source field (h units) for the drive v: the magnets' bias (times `magnets`) and the coil's field, dh v / amp
    (bipolar) or -dh + 2 dh v / top (unipolar), times `coil`."""
    v = np.asarray(v, float)
    if core["unipolar"]:
        return magnets * (core["hb"] - core["dh"]) + coil * 2.0 * core["dh"] * v / core["top"]
    return magnets * core["hb"] + coil * core["dh"] * v / core["amp"]


def travel(core, c2, c2_0):
    """The gauge's reading (um) of the mean c^2, zeroed at c2_0: 1e3 L_0 (3/2) lambda_100 (c2 - c2_0)."""
    return 1e3 * core["L0"] * 1.5 * core["lam100"] * (np.asarray(c2, float) - c2_0)


def core_c2(core, v, rod=None, coil=1.0, magnets=1.0):
    """The rod's mean c^2 along the drive v (rate independent) from `rod` (default demagnetised at the rest field; a
    copy is run)."""
    rd = Rod(core) if rod is None else rod.copy()
    return rd.run(source_field(core, v, coil, magnets))[0]


def core_reading(core, v, rod=None, coil=1.0):
    """The gauge's reading (um) of the rate-independent actuator along the drive v, zeroed at its start."""
    rd = Rod(core) if rod is None else rod
    return travel(core, core_c2(core, v, rd, coil), rd.state()[1])


def big_gamma(core):
    """Gamma = J_s^2 / (mu0 K_1): the magnetisation's share of the flux density, B / (mu0 K_1 / J_s) = h + Gamma m."""
    return core["Js"] ** 2 / (MU0 * core["K1"])


# ---- creep: the bias magnets' carrier creeping ----

# The creep record's bias magnets (two NdFeB rings) sit in a glass-filled polymer carrier, drawn toward the steel end
# caps across a thin air gap by their own attraction, F proportional to the square of the circuit's flux (Maxwell's
# stress B^2 / 2 mu0; the flux taken as the source field sets it, the rod's own share left out: a choice). The carrier
# creeps under that force as polymers do, by Findley's power law J(t) = J_c (j_0 + (t / tau_0)^n) (j_0 = 0.2; Findley
# & Khosla, as remembered: n 0.22 ... 0.32 for a filled thermoplastic, tau_0 = 1 s), the gap narrowing by Boltzmann's
# superposition of the force's changes since the long rest, delta(t) = J_c (j_0 f(t) + int ((t - s) / tau_0)^n df(s)),
# f = (h_src / h_rest)^2 - 1 the force's change over its rest value. The narrower gap strengthens the bias: the rod's
# source field is h_src + eps h_rest (delta / J_c), eps 0.03 ... 0.04 (the carrier's compression under its rest force
# over the circuit's effective gap, a choice). So after a move up the force stays raised, the carrier goes on yielding
# and the field on rising (the rod the way the move went), and after a move down the carrier recovers: creep, fast at
# first and ever slower (as t^n). The power law is carried by a Prony series fitted to it by NNLS (time constants 1e-3
# ... 1e5 s, three a decade; within 1e-4 of it over 0.05 ... 2000 s, checked), each term exact per interval for the
# force linear between the samples (:func:`.mechanisms47.relax_linear`); checked in the test against the power law's own
# closed form for a ramp and a hold.

CREEP_J0 = 0.2
CREEP_TAU0 = 1.0
_PRONY = {}


def findley_prony(n, tau0=CREEP_TAU0):
    """(c, taus): (t / tau0)^n ~ sum_j c_j (1 - e^(-t / tau_j)), c >= 0 by NNLS on a logarithmic grid of t (1e-3 ...
    1e5 tau0 for the taus, three a decade; the fit over 1e-2 ... 1e4 tau0)."""
    key = (round(float(n), 15), float(tau0))
    if key not in _PRONY:
        from scipy.optimize import nnls
        taus = tau0 * 10.0 ** (np.arange(-9, 16) / 3.0)
        tt = tau0 * np.geomspace(1e-2, 1e4, 400)
        A = 1.0 - np.exp(-tt[:, None] / taus[None, :])
        target = (tt / tau0) ** n
        # relative weighting: every decade alike
        c, _ = nnls(A / target[:, None], np.ones_like(tt))
        _PRONY[key] = (c, taus)
    return _PRONY[key]


def carrier_shift(t, hs, h_rest, eps, n):
    """The bias's rise (h units) as the magnets' carrier creeps: eps h_rest (j_0 f + the power law's creep of f), f =
    (hs / h_rest)^2 - 1 linear between the times t, from a long rest (f = 0 before)."""
    f = (np.asarray(hs, float) / h_rest) ** 2 - 1.0
    c, taus = findley_prony(n)
    z = relax_linear(t, f, taus, 0.0)
    return eps * h_rest * (CREEP_J0 * f + z @ c)


# ---- rate dependence: a shorted turn around the rod ----
#
# The rate record's actuator (a larger rod, r_rod 7 ... 9.5 mm) has its coil wound on a copper former, chosen to carry
# the coil's heat away and not slit (a design slip: formers of such coils are slit for this): a closed turn of
# resistance R_s = rho_Cu 2 pi r_b / (l t_b) around the rod (r_b its mean radius, 1.5 ... 2.5 mm beyond the rod's, t_b
# its wall 1.2 ... 2.0 mm, l the rod's length, rho_Cu 1.7e-8 Ohm m as remembered). Lenz's law: the flux's change drives
# a current in it, i_s = -A (dB/dt) / R_s, whose field opposes the coil's: in h units
#     h + gamma m = h_src - tau_b d(h + Gamma m)/dt,   tau_b = mu0 r_rod^2 t_b / (2 rho_Cu r_b)
# (Gamma = J_s^2 / (mu0 K_1): h + Gamma m is the flux density in h units; tau_b 0.18 ... 0.6 ms; the air between the rod
# and the former left out). So the field lags the coil by tau_b (1 + Gamma chi) / (1 + gamma chi), chi = dm/dh: most in
# the burst region, where the walls move (several ms), least out of it: a lag that depends on the rod's state, inside
# the hysteresis. Solved by implicit Euler with the rod (:func:`_run`) on SUB_TURN steps a sample on the drive's own
# finer grid; first order: checked in the test against Radau for a rod whose walls are held, and on twice as many
# steps.

SUB_TURN = 4
RHO_CU = 1.7e-8


def tau_bobbin(r_rod, r_b, t_b, rho=RHO_CU):
    """tau_b = mu0 r_rod^2 t_b / (2 rho r_b) (s; lengths in m)."""
    return MU0 * r_rod ** 2 * t_b / (2.0 * rho * r_b)


# ---- drift: the air conditioning's cycle moving the gauge ----
#
# The drift record's lab is cooled by an air conditioner cycling on its thermostat: the air near the rig falls at a
# steady rate while the compressor runs and rises while it rests (a triangle wave, its swing 1.0 ... 1.6 K peak to peak
# and its period 200 ... 300 s, the run 35 ... 50 % of it: a small unit short-cycling on a bang-bang thermostat, a
# choice). The gauge's probe is held over the push rod's end by a thin aluminium bracket (L_br 100 ... 140 mm from the
# base, alpha 23e-6 / K) that follows the air with its time constant tau_br (60 ... 120 s), while the actuator's steel
# housing (L_h 70 ... 100 mm from the base to the rod's end, alpha 12e-6 / K) follows it with tau_h (15 ... 30 min): the
# reading moves by alpha_St L_h T_h - alpha_Al L_br T_br (um, the temperatures' changes from the record's start), about
# half a micrometre over a record. Each temperature is exact per interval for the air linear between the samples
# (:func:`.mechanisms47.relax_linear`), from the cycle's periodic state (the rig has stood in the room for hours: one
# period's response from rest, x(P) = e^(-P / tau) x(0) + F, solved for x(P) = x(0); checked in the test against Radau
# over many periods).

ALPHA_AL = 23e-6
ALPHA_ST = 12e-6


def air_temperature(t, period, swing, run_share, phase):
    """The air's temperature (K, about its mean) at the times t: a triangle wave falling over run_share of the period
    and rising over the rest, its swing peak to peak, at the phase (0 ... 1 of a period) at t = 0."""
    s = np.mod(np.asarray(t, float) / period + phase, 1.0)
    fall = s < run_share
    return np.where(fall, swing / 2 - swing * s / run_share, -swing / 2 + swing * (s - run_share) / (1 - run_share))


def periodic_start(period, swing, run_share, phase, tau, n_per=20000):
    """A lagged temperature's value at t = 0 on the cycle's periodic state: over the period before the start, from 0,
    it reaches F = x(0) - e^(-P / tau) x(-P); periodic, x(0) = F / (1 - e^(-P / tau)) (the air linear between n_per
    points a period)."""
    tt = np.linspace(-period, 0.0, n_per + 1)
    F = float(relax_linear(tt, air_temperature(tt, period, swing, run_share, phase), tau, 0.0)[-1, 0])
    return F / (1.0 - math.exp(-period / tau))


def lagged(t, air, tau, x0):
    """The temperature relaxing toward the air (linear between the times t) at tau from x0: exact per interval."""
    return relax_linear(t, air, tau, x0)[:, 0]


def gauge_drift(T_h, T_br, L_h, L_br):
    """The reading's move (um) as the housing (steel over L_h mm) and the bracket (aluminium over L_br mm) change by
    T_h and T_br from the start."""
    return 1e3 * (ALPHA_ST * L_h * (np.asarray(T_h) - T_h[0]) - ALPHA_AL * L_br * (np.asarray(T_br) - T_br[0]))


# ---- asymmetry: the bias magnets weakened ----
#
# The asymmetry record's actuator has bias magnets that lost part of their remanence (overheated when the coil was once
# run hot, far above their working temperature: they keep 45 ... 55 % of it; NdFeB's irreversible loss, a choice): the
# rod rests low in its burst region (a tenth or less of its regions axial), the drive's positive half sweeping the
# steep middle of it and its negative half the in-plane domains' slow rotation below it: the response grows far more
# one way than the other (:func:`source_field` with `magnets`). The controller's routine still demagnetises it about its
# (weaker) rest field.


# ---- saturation: a coil of too many turns ----
#
# The saturation record's actuator has a replacement coil of 2.1 ... 2.5 times the turns (the same current at the full
# drive): the field swings that much farther about the bias, past the burst region both ways: at the top 94 ... 97 % of
# the regions axial (toward the strain's limit, lambda_100; the highest-stress class's last thresholds out of reach) and
# the reading's slope falling to a third ... a half of its middle's, at the bottom all but 10 ... 15 % back in plane
# (the low-stress classes' axial wells reach far down), their rotation's slope falling with the field
# (:func:`source_field` with `coil`); the internal field stays positive (checked in the test).


# ---- delay: the setpoint over a field bus ----
#
# The delay record's controller sends the drive (its setpoint, the record's samples) to the current amplifier over a
# field bus once a sample; the amplifier, in its interpolating mode, moves linearly from the last setpoint received to
# the newest over one cycle (CANopen's interpolated mode, as remembered), a setpoint arriving L (1.2 ... 2.4 sample
# periods: the bus's cycle and the amplifier's sync, a choice) after it was sent: the coil's current is the drive's
# samples joined by straight lines, L + one sample late. The rod being rate independent, its state at a sample is that
# of the late drive there (the extremes of a polyline lie at its vertices).

def interpolated_late(t, v, lag):
    """The amplifier's input at the times t: the samples v (on t) joined by straight lines, `lag` s late (the first
    sample's value before)."""
    return np.interp(np.asarray(t, float) - lag, t, v, left=v[0])


# ---- initial state: a rod slid in fresh ----
#
# The initial-state record's rod is a replacement slid into the assembled actuator (its magnets in place) fresh from its
# supplier's anneal, and the record was started without the controller's demagnetising routine. Annealed with no field
# on it, every region lies in plane (the wall force is negative there); as the rod slides into the magnets'
# field the source field rises from 0 to the bias, the regions whose up thresholds it passes turning axial: the rod
# starts on the ascending branch from zero field, fewer of its regions axial than the routine would leave.

def slid_in_rod(core, n=200):
    """The rod slid in: every region in plane at zero field, the source field then raised to the rest field (rate
    independent: its turning points are what count)."""
    rod = Rod(core, H=0.0, state="virgin")
    rod.run(np.linspace(0.0, rest_field(core), n + 1)[1:])
    return rod


# ---- two effects: the coil's heat and a power cut at the full drive ----

# The pair record's actuator is the unipolar build. Its coil's Joule heat, P = P_full (v / top)^2, warms the coil and,
# through the former, the rod (two heat capacities; the coil losing heat to the air and the rod to the frame: a lumped
# model, a choice), and the rod lengthens by its expansion, alpha_G L_0 T_rod (alpha_G 11 ... 12e-6 / K for Fe-Ga, as
# remembered; the push rod and housing held at the room's temperature by the frame: a choice): the time constants a few
# seconds to some tens (the coil's own 4 ... 8 s, the rod's 3 ... 6 s through the former), the rod's rise at the full
# current held 1.5 ... 2.5 K. So after a move up the reading goes on rising as the rod warms and after a move down goes
# on falling as it cools (the current's square rising with the unipolar drive): labelled "creep". The alloy's
# constants' change over these few kelvin is left out (a choice). Exact per interval for the power linear between the
# samples (the augmented matrix exponential; checked in the test against Radau).
# And the actuator's last session ended in a power cut while it was held at the full drive: the coil's current decayed
# to 0 with the rod on its descending branch from the top of its swing, and at the next power-up the controller's
# routine did not run (labelled "initial_state"): more of its regions axial than the routine would leave, the ones whose
# down thresholds the falling field did not pass. The coil had long cooled.

ALPHA_G = 11.5e-6


def heat_matrices(tau_c, tau_r, loss_c, loss_r, dt):
    """The thermal model x = (T_coil, T_rod) (K over the room), x' = A x + b p (p the power over its full value, in
    K / s of the coil): tau_c T_c' = p_K - (T_c - T_r) - loss_c T_c, tau_r T_r' = (T_c - T_r) - loss_r T_r. Returns
    (Phi, G0, G1): x(t + dt) = Phi x + G0 p(t) + G1 (p(t + dt) - p(t)) for p linear over the step (exact)."""
    from scipy.linalg import expm
    A = np.array([[-(1.0 + loss_c) / tau_c, 1.0 / tau_c], [1.0 / tau_r, -(1.0 + loss_r) / tau_r]])
    b = np.array([1.0 / tau_c, 0.0])
    M = np.zeros((4, 4))
    M[:2, :2] = A
    M[:2, 2] = b
    M[2, 3] = 1.0 / dt
    E = expm(M * dt)
    return E[:2, :2], E[:2, 2], E[:2, 3]


def heat_up(p, dt, tau_c, tau_r, loss_c, loss_r, p_K):
    """(T_coil, T_rod) (K over the room) along the power p (its full value p_K K of the coil's equilibrium drive,
    linear between samples dt apart), from the room's temperature."""
    Phi, G0, G1 = heat_matrices(tau_c, tau_r, loss_c, loss_r, dt)
    u = p_K * np.asarray(p, float)
    x = np.zeros(2)
    out = np.empty((len(u), 2))
    out[0] = x
    for i in range(1, len(u)):
        x = Phi @ x + G0 * u[i - 1] + G1 * (u[i] - u[i - 1])
        out[i] = x
    return out


def rod_rise_full(tau_c, tau_r, loss_c, loss_r, p_K):
    """The rod's rise (K) at the full power held (the steady state of the thermal model)."""
    A = np.array([[-(1.0 + loss_c) / tau_c, 1.0 / tau_c], [1.0 / tau_r, -(1.0 + loss_r) / tau_r]])
    return float(np.linalg.solve(A, -np.array([p_K / tau_c, 0.0]))[1])


def cut_at_top_rod(core, n=200):
    """The rod left by a power cut at the full drive: demagnetised, the source field then raised to the full drive's
    and let fall back to the rest field (rate independent)."""
    rod = Rod(core)
    H0 = rest_field(core)
    H1 = float(source_field(core, core["top"] if core["unipolar"] else core["amp"]))
    rod.run(np.r_[np.linspace(H0, H1, n + 1)[1:], np.linspace(H1, H0, n + 1)[1:]])
    return rod


# ---- out of vocabulary: no bias magnets ----
#
# The out-of-vocabulary record's actuator was reassembled with brass spacers where its bias magnets belong (the same
# thickness: the circuit's gap unchanged, its bias gone). At zero field the rod's domains lie in plane; the coil's field
# turns them toward the rod's axis whichever way it points, so the strain (c^2) rises both ways: the reading is even in
# the drive (twice its frequency), and the regions' walls are never reached at this field (every region stays in
# plane): no map of the biased core, monotone or not, draws it.

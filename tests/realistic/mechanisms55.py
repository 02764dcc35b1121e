"""Mechanisms of the HOLDOUT55 set (``cases_holdout55.py``), each written from its law; the signals are in
:mod:`.signals55`.

Nothing here imports hystcomp (nor another set's mechanisms). Every mechanism takes the film's field (set by the drive),
its crystallites' polarisation or its reading, and returns the response; all are causal.

Citations: every source below was written from memory in this session (none was re-read); volumes, pages and years may
be off, and so may the constants quoted (typical values as remembered, not a datasheet's). The laws do not rest on them:
each is checked in tests/test_realistic_holdout55.py against an independent solution (the crystallites' states by the
last threshold the field crossed, from the running extremes; the rest state by an explicit decaying cycling; the lags
by solve_ivp; the thermostat's switching times by brentq; the contacts' balances by brentq; the link's delay written
out; the creep kernel's means by quad and its hereditary sum summed directly; finer grids).
"""

import math

import numpy as np
from numba import njit
from scipy.special import ndtri

# ---- the rate-independent core: a P(VDF-TrFE) film on a silicon cantilever (a unimorph) ----
#
# The actuator is a unimorph cantilever: a silicon beam (L = 2 mm long, t_s = 10 um thick) carrying a spin-cast film of
# the ferroelectric copolymer P(VDF-TrFE) 70/30 (t_f = 2 um, annealed to grow its crystallites, poled), between an
# aluminium bottom electrode and a gold top one; the tip's deflection is read by a fibre-optic displacement sensor (nm,
# zeroed at the start of every record). The drive v (V) across the film sets the field E = v / t_f (MV/m); on the
# unipolar records the bottom electrode sits at V_MID = 47 V, so E = (v - 47) / t_f (the drive's 0 V the negative end).
#
# The film's polarisation (Furukawa, Phase Transitions 18 (1989) 143, for the copolymers' switching; the crystallites'
# distribution of coercive and internal fields as in the ferroelectric-polymer literature's Preisach-type readings,
# e.g. Naber, Blom & de Leeuw's reviews of ferroelectric-polymer memories, Adv. Mater. 2010; all as remembered):
#
# * The film holds N_SOFT + N_HARD classes of crystallites, each a single domain polarised up (+1) or down (-1) along
#   the film's normal, switching up when the field exceeds E_c - E_b and down when it falls below -E_c - E_b: E_c its
#   coercive field, E_b its internal field (the charge trapped at its faces). The hard crystallites, the lamellae grown
#   in the anneal (N_HARD = 500 classes, a share 1 - fs of the film): E_c log-normal, median 105 MV/m, log spread 0.12;
#   E_b normal, 12 +- 6 MV/m (the poling's trapped charge, favouring the poled direction); far beyond the drive's +-23.5
#   MV/m, they hold the film's remanent polarisation. The soft ones, small and defective crystallites at the film's
#   interfaces and grain boundaries (N_SOFT = 4000 classes, a share fs = 4.5 ... 5.5 %): E_c log-normal, median 6.5 ...
#   7.5 MV/m, log spread LC_SOFT = 0.35; E_b normal, mean 0.5 ... 1.5 MV/m, spread 30 ... 34 MV/m (space charge at the
#   interfaces, of either sign). A relay of the field (rate independent: at these fields a thin copolymer film's
#   crystallites switch in some microseconds to a millisecond, Merz's law as remembered, against the programmes'
#   quickest moves of 0.2 s: a choice that leaves the switching's kinetics out). Each kind's classes lie on its own
#   stretch of one two-dimensional Kronecker sequence (the plastic number's, Roberts 2018, as remembered) over the two
#   quantiles, shifted by the core's seed.
# * The film's polarisation P = P_X m + eps_0 chi E (C/m^2): m the crystallites' mean state, P_X = 0.075 C/m^2 (a
#   crystallinity of 0.6 of the beta phase's 0.125), chi = 11 (the film's lattice and amorphous permittivity, 12, less
#   one).
# * The film's in-plane strain is electrostrictive, S = Q P^2 (Q = 0.45 m^4/C^2 for the in-plane coefficient, as
#   remembered for the copolymers' order of size; its sign taken so the film stretches with P^2): the same in both
#   in-plane directions, a biaxial mismatch strain on the beam. Stoney's law bends the beam: curvature kappa = 6 Y_f'
#   t_f S / (Y_s' t_s^2) (Y_f' = 5 GPa the film's biaxial modulus, Y_s' = 180 GPa silicon's), the tip w = kappa L^2 /
#   2: w = STONEY_NM * (S - S(start)) nm, STONEY_NM = 1e9 * 3 Y_f' t_f L^2 / (Y_s' t_s^2) = 6.7e6 nm.
#
# Rate independent (every crystallite changes only at its thresholds), with return-point memory (relays); close to a
# Prandtl-Ishlinskii model but not one (measured in the test and stated there): the relays' thresholds are not a product
# of a uniform density of centres and a density of widths (the centres are normal, the widths log-normal), and the
# strain is the square of the polarisation (the loop's slope grows with P).
#
# The rest state: after the factory's poling (every crystallite up), before every record but the initial-state case's,
# the controller's conditioning routine cycles the film's field about 0 with an amplitude decaying from the amplifier's
# swing (47 V over the film); its limit leaves up every crystallite that cannot be switched down, down every other one
# that cannot be switched up, and the rest up where their loop's middle (-E_b) lies below 0; then the field is brought
# to the drive's 0 V (0 on the bipolar rigs, -23.5 MV/m on the unipolar ones): the state is set so, not run (checked
# in the test against an explicit decaying cycling).

N_SOFT, N_HARD = 4000, 500
T_FILM = 2.0           # um: the field in MV/m is the film's voltage over T_FILM
V_MID = 47.0
P_X = 0.075            # C/m^2
CHI = 11.0
EPS0 = 8.8541878128e-12
Q_ES = 0.45            # m^4/C^2
Y_F, Y_S, L_BEAM, T_S = 5e9, 180e9, 2e-3, 10e-6
STONEY_NM = 1e9 * 3 * Y_F * T_FILM * 1e-6 * L_BEAM ** 2 / (Y_S * T_S ** 2)
LC_SOFT = 0.35
HARD = (105.0, 0.12, 12.0, 6.0)  # the hard crystallites' E_c median (MV/m), log spread, E_b mean and spread (MV/m)
PLASTIC = 1.324717957244746  # the real root of x^3 = x + 1: the two-dimensional Kronecker sequence's ratio


def kronecker_points(n, shift):
    """n points of the two-dimensional Kronecker sequence (shift + k (1 / g, 1 / g^2)) mod 1, k = 1 ... n, g the plastic
    number."""
    a = np.array([1.0 / PLASTIC, 1.0 / PLASTIC ** 2])
    return (np.asarray(shift, float)[None, :] + np.arange(1, n + 1)[:, None] * a[None, :]) % 1.0


_CRYST = {}


def crystallites(core):
    """The core's crystallite classes: their up and down thresholds (alpha, beta) in MV/m and their volume shares w,
    from the core's seed and its distributions: N_SOFT soft classes (a share fs of the crystallites: their coercive
    fields' median E50 and log spread LC_SOFT, their internal fields' mean Ebm and spread sb), then N_HARD hard ones
    (HARD: the same four), each set on its own stretch of one Kronecker sequence."""
    key = (core["rseed"], core["fs"], core["E50"], core["Ebm"], core["sb"])
    if key not in _CRYST:
        shift = np.random.default_rng(core["rseed"]).uniform(size=2)
        u = np.clip(kronecker_points(N_SOFT + N_HARD, shift), 1e-12, 1.0 - 1e-12)
        soft = np.arange(N_SOFT + N_HARD) < N_SOFT
        e50 = np.where(soft, core["E50"], HARD[0])
        lc = np.where(soft, LC_SOFT, HARD[1])
        ebm = np.where(soft, core["Ebm"], HARD[2])
        sb = np.where(soft, core["sb"], HARD[3])
        ec = e50 * np.exp(lc * ndtri(u[:, 0]))
        eb = ebm + sb * ndtri(u[:, 1])
        w = np.where(soft, core["fs"] / N_SOFT, (1.0 - core["fs"]) / N_HARD)
        _CRYST[key] = (ec - eb, -ec - eb, w)
    return _CRYST[key]


def field(core, v, t_film=T_FILM):
    """The film's field (MV/m) for the drive v (V): v / t_f, on the unipolar records (v - 47) / t_f."""
    v = np.asarray(v, float)
    return (v - V_MID if core["unipolar"] else v) / t_film


def rest_state(core, E, a0=V_MID / T_FILM):
    """The conditioning's limit, then the field brought to E: from the poling (every crystallite up) the field cycled
    about 0 with an amplitude decaying from a0 (the amplifier's swing, 47 V over the film) leaves up every crystallite
    that cannot be switched down (beta < -a0), down every other one that cannot be switched up (alpha > a0), and the
    rest up where their loop's middle lies below 0; then the field brought from 0 to E switches up those with alpha <
    E (E > 0) or down those with beta > E (E < 0)."""
    a, b, _ = crystallites(core)
    s = np.where(b < -a0, 1.0, np.where(a > a0, -1.0, np.where(0.5 * (a + b) < 0.0, 1.0, -1.0)))
    s = np.where((E > 0) & (a < E), 1.0, s)
    return np.where((E < 0) & (b > E), -1.0, s)


@njit(cache=True)
def _relays(E, a, b, w, s):
    """The crystallites' mean state along the fields E: each a relay up at a, down at b, of share w (s carried in and
    out)."""
    n = E.shape[0]
    m = a.shape[0]
    out = np.empty(n)
    for i in range(n):
        Ei = E[i]
        tot = 0.0
        for k in range(m):
            if s[k] > 0.0:
                if Ei < b[k]:
                    s[k] = -1.0
            elif Ei > a[k]:
                s[k] = 1.0
            tot += w[k] * s[k]
        out[i] = tot
    return out


def switched_share(core, E, s=None, a0=V_MID / T_FILM):
    """The crystallites' mean state m along the fields E, from the state s (default the rest state at E[0], the
    conditioning's swing a0); s is updated in place when given."""
    E = np.asarray(E, float)
    a, b, w = crystallites(core)
    s = rest_state(core, E[0], a0) if s is None else s
    return _relays(E, a, b, w, s)


def polarisation(E, m, extra=0.0):
    """The film's polarisation (C/m^2): P_X m + eps_0 chi E (E in MV/m), plus any extra (a slow polarisation)."""
    return P_X * np.asarray(m, float) + EPS0 * CHI * 1e6 * np.asarray(E, float) + extra


def reading(P, strain=0.0):
    """The tip's deflection (nm, zeroed at the first sample) for the polarisations P: STONEY_NM (Q P^2 + strain), strain
    any other in-plane mismatch strain of the film (thermal)."""
    P = np.asarray(P, float)
    w = STONEY_NM * (Q_ES * P * P + strain)
    return w - w[0]


def core_reading(core, v, s=None, t_film=T_FILM):
    """The rate-independent film's reading (nm) for the drive v, from the state s (default the rest state)."""
    E = field(core, v, t_film)
    return reading(polarisation(E, switched_share(core, E, s, V_MID / t_film)))


# ---- a first-order lag, exact for an input linear between samples ----

@njit(cache=True)
def lag(x, dt, tau, y0):
    """y with tau y' + y = x(t), x linear between the samples (step dt), from y0: per step y_(n+1) = x_(n+1) - tau s +
    (y_n - x_n + tau s) exp(-dt / tau), s the input's slope over the step (exact)."""
    n = x.shape[0]
    out = np.empty(n)
    y = y0
    out[0] = y
    a = math.exp(-dt / tau)
    for i in range(1, n):
        sl = (x[i] - x[i - 1]) / dt
        y = x[i] - tau * sl + (y - x[i - 1] + tau * sl) * a
        out[i] = y
    return out


# ---- creep: the film's slow (Maxwell-Wagner) polarisation ----
#
# The creep record's film was cast from a lot with ionic residues (the synthesis' initiator, as remembered a usual
# impurity of the copolymers): under a field the ions drift to the crystallites' and the electrodes' interfaces and
# build a slow interfacial (Maxwell-Wagner-Sillars) polarisation, the low-frequency rise of the copolymers' permittivity
# (as remembered: from 12 to some 20 below 0.1 Hz). It is written as a box distribution of Debye relaxations: N_MW = 8
# modes, their times log-spaced from 0.3 to 40 s, each P_k relaxing toward eps_0 dchi E / N_MW (tau_k P_k' = eps_0 dchi
# E / N_MW - P_k), dchi 6 ... 9; the slow polarisation adds to P before the strain's square. After a rise of the drive
# the film goes on stretching for seconds, after a fall it goes on shrinking (labelled "creep"). At the start the modes
# sit at the first field's equilibrium (the film long at rest there).

N_MW = 8
TAU_MW = np.geomspace(0.3, 40.0, N_MW)


def mw_polarisation(E, dt, dchi):
    """The slow polarisation (C/m^2) along the fields E (MV/m, linear between samples): the sum of N_MW Debye modes,
    each exact per step, from their equilibrium at E[0]."""
    x = EPS0 * dchi * 1e6 * np.asarray(E, float) / N_MW
    return sum(lag(x, dt, float(tau), float(x[0])) for tau in TAU_MW)


# ---- rate dependence: the cantilever in silicone oil ----
#
# The rate-dependence record's cantilever works immersed in a silicone oil (a damped micro-valve flap; a 3000 ... 4000
# cSt oil, some 3 ... 4 Pa s): the beam's motion is overdamped, its tip obeying c w' + k w = k w_s, w_s the film's
# quasi-static bend (the reading of the core), and tau = c / k. For a beam in a viscous liquid far below its resonance
# the drag per length is some 20 ... 40 times the liquid's viscosity (Sader's hydrodynamic function, J. Appl. Phys. 84
# (1998) 64, as remembered, in its low-Reynolds limit); lumped at the tip (a third of the beam's drag, the first mode's
# share: a choice) and with the beam's tip stiffness k = 2.6 N/m it gives tau = 20 ... 32 ms: drawn. The beam's
# inertia is left out (its resonance in the oil overdamped). Labelled "rate_dependence".

# ---- drift: the room's thermostat, the film's thermal mismatch ----
#
# The drift record's rig sits in a room whose heating is switched by a thermostat with a dead band: the air relaxes
# toward T_on (heating on) or T_off (off) with the room's time constant tau_r, the heating switched off at T_set + db /
# 2 and on at T_set - db / 2 (a bang-bang loop's limit cycle: two exponentials, their switching times in closed form);
# the beam's holder follows the air with the time constant tau_h (first order). The film expands 130e-6 / K and the
# silicon 2.6e-6 / K (as remembered): the mismatch strain (alpha_f - alpha_s) (T - T_start) bends the beam through the
# same Stoney factor as the film's own strain (a bimorph's thermal bending, Timoshenko 1925, as remembered). Labelled
# "drift".

ALPHA_F, ALPHA_S = 130e-6, 2.6e-6


def thermostat(T_end, t_pre, T_set, db, T_on, T_off, tau_r, phase):
    """The room's air (C) under a bang-bang thermostat from -t_pre to T_end: the knots (times, temperatures, heating on)
    at every switching, the cycle started at a fraction `phase` (0 ... 1) of its heating leg. Between knots the air
    relaxes exponentially toward T_on or T_off with tau_r; returns (times, temperatures, on)."""
    lo, hi = T_set - db / 2, T_set + db / 2
    t_heat = tau_r * math.log((T_on - lo) / (T_on - hi))
    t0 = -t_pre
    T0 = T_on - (T_on - lo) * math.exp(-phase * t_heat / tau_r)
    times, temps, ons = [t0], [T0], [True]
    on, T, t = True, T0, t0
    while t < T_end:
        if on:
            dt_ = tau_r * math.log((T_on - T) / (T_on - hi))
            T = hi
        else:
            dt_ = tau_r * math.log((T - T_off) / (lo - T_off))
            T = lo
        t += dt_
        on = not on
        times.append(t)
        temps.append(T)
        ons.append(on)
    return np.array(times), np.array(temps), np.array(ons)


def air_at(t, times, temps, ons, T_on, T_off, tau_r):
    """The air's temperature at the times t from the thermostat's knots: the exponential leg each time falls in."""
    t = np.asarray(t, float)
    i = np.clip(np.searchsorted(times, t, side="right") - 1, 0, len(times) - 1)
    target = np.where(ons[i], T_on, T_off)
    return target + (temps[i] - target) * np.exp(-(t - times[i]) / tau_r)


def holder_temperature(t, times, temps, ons, T_on, T_off, tau_r, tau_h, sub=20):
    """The holder's temperature at the times t (uniform): tau_h T_h' = T_air - T_h, the air evaluated on a grid `sub`
    times finer from -t_pre (linear between its points; started at the air's temperature there: the holder long
    followed the cycle before, and t_pre several tau_h)."""
    dt = (t[1] - t[0]) / sub
    n_pre = int(math.ceil(-times[0] / dt))
    tf = (np.arange(-n_pre, (len(t) - 1) * sub + 1)) * dt
    air = air_at(tf, times, temps, ons, T_on, T_off, tau_r)
    Th = lag(air, dt, tau_h, float(air[0]))
    return Th[n_pre::sub]


# ---- asymmetry: the tip on a micropump's membrane ----
#
# The asymmetry record's beam is a micropump's actuator: its tip rests, just touching, on the centre of the pump
# chamber's pre-tensioned silicone membrane above it. As the film bends the tip up it pushes the membrane, whose
# restoring force is a point-loaded pre-tensioned membrane's, F = k_1 d + k_3 d^3 (the tension's linear term, 2 pi N_0 /
# ln(a / r_0), and the stretching's cubic one, of order E h / a^2; Timoshenko's plates and shells, as remembered); as it
# bends down the tip leaves the membrane. The tip's balance k (w_s - w) = F(w) for w > 0, w = w_s below (k the beam's
# tip stiffness, w_s the free bend): a cubic with one real root (Cardano). In the units used: k_1 / k = r1 (0.5 ...
# 0.8) and k_3 / k = r3 / W^2 with W the free stroke's upward reach (r3 0.3 ... 0.5). Labelled "asymmetry".

def membrane_contact(ws, r1, k3):
    """The tip's deflection with the membrane above it (nm): w = ws for ws <= 0; for ws > 0 the real root of k3 w^3 +
    (1 + r1) w - ws = 0 (Cardano's formula for a depressed cubic with a positive linear term)."""
    ws = np.asarray(ws, float)
    p = (1.0 + r1) / k3
    q = -np.maximum(ws, 0.0) / k3
    d = np.sqrt(q * q / 4 + p ** 3 / 27)
    w = np.cbrt(-q / 2 + d) + np.cbrt(-q / 2 - d)
    return np.where(ws > 0.0, w, ws)


# ---- saturation: the tip between two silicone end stops ----
#
# The saturation record's beam is a valve flap in a slot: silicone bumpers above and below its tip stop it at g_up and
# g_dn (0.55 ... 0.7 of the free stroke's reach each way). The tip's ruby ball presses a bumper with Hertz's force F =
# K_H d^(3/2) (K_H = 4/3 E* sqrt(R), a ball of R = 0.15 mm on a silicone of E* some 2 MPa: K_H = 3.3e4 N/m^1.5; Hertz
# 1882, as remembered), the beam's tip stiffness k = 2.6 N/m: k (w_s - w) = K_H (w - g)^(3/2) past a stop, the free bend
# w_s below it. In nm: d + (K_H / k) d^(3/2) = w_s - g with K_H / k in nm^-1/2 (3.3e4 x (1e-9)^1.5 / (2.6 x 1e-9) =
# 0.40, drawn 0.3 ... 0.5). Labelled "saturation".

def stop_contact(ws, g, kh):
    """The tip's deflection past a stop at g > 0 (nm): w = ws below it, else g + d with d + kh d^(3/2) = ws - g (a cubic
    in sqrt(d), its positive root by Cardano)."""
    ws = np.asarray(ws, float)
    e = np.maximum(ws - g, 0.0)
    # u = sqrt(d): kh u^3 + u^2 - e = 0; solved by Newton from a bracketing start (monotone in u >= 0), to rounding
    u = np.minimum(np.sqrt(e), np.cbrt(e / kh))
    for _ in range(60):
        f = kh * u ** 3 + u * u - e
        fp = 3 * kh * u * u + 2 * u
        u = np.where(fp > 0, u - f / np.where(fp > 0, fp, 1.0), u)
    return np.where(ws > g, g + u * u, ws)


def two_stops(ws, g_up, g_dn, kh):
    """The tip between the stops at +g_up and -g_dn (nm)."""
    w = stop_contact(ws, g_up, kh)
    return -stop_contact(-w, g_dn, kh)


# ---- delay: a wireless link's latency ----
#
# The delay record's amplifier sits on the rig, driven over a wireless link (a Bluetooth Low Energy link's isochronous
# channel, as remembered): the host's command, as recorded, is sampled every connection interval p = 7.5 ms, sent, and
# played out at the node's DAC a fixed latency D later (its jitter buffer: 60 ... 90 ms, drawn), linearly interpolated
# between the packets' samples (a first-order hold); before the first packet is played the DAC holds 0 V. Labelled
# "delay".

P_LINK = 7.5e-3


def link_drive(t, command_at, D, phase, p=P_LINK):
    """The node's drive at the times t: the command sampled at phase + k p (k >= 0), played D later, linear between
    packets, 0 before the first is played."""
    t = np.asarray(t, float)
    k_max = int(math.ceil((t[-1] - D - phase) / p)) + 1
    tk = phase + np.arange(max(k_max, 1) + 1) * p
    vk = command_at(tk)
    return np.interp(t - D, tk, vk, left=0.0), tk


# ---- initial state: the factory's poling, without the conditioning ----
#
# The initial-state record's film comes straight from the factory's poling (a field far beyond every crystallite's up
# threshold, then 0 V): every crystallite up, none of the conditioning's cycling done. Its state differs from the rest
# state in the crystallites the conditioning leaves down (their internal field against the poling); the programme's
# first strong negative swing switches those whose down threshold it passes, and from there on the film follows the
# rest state's path. Labelled "initial_state".

# ---- the pair: the clamp's logarithmic creep and the film's alpha_c relaxation ----
#
# The pair's beam is clamped by a cyanoacrylate bond to its holder. (1) The film's own modulus relaxes: the copolymer's
# alpha_c relaxation (chain motion within the crystallites, some 5 ... 10 Hz at room temperature, as remembered from
# dielectric and mechanical spectra) gives a standard linear solid, Y(t) = Y_inf + dY exp(-t / tau_a): the film's stress
# under its own strain S(t) is Y_inf S + dY (S - lag_tau_a(S)), so the beam's bend is the quasi-static one plus r_a (w_s
# - lag(w_s)) (r_a = dY / Y_inf, 0.6 ... 0.8, tau_a 30 ... 45 ms): the film stiffer on quick moves (labelled
# "rate_dependence"). (2) The bond creeps under the bending moment (proportional to the film's stress, so to the bend):
# its rotation follows a logarithmic creep compliance, J(t) = J_0 + J_1 ln(1 + t / tau_0) (a glassy polymer's
# thermally activated creep, Struik's physical ageing book, 1978, as remembered), read at the tip as L theta: the tip
# w = m + c_1 int ln(1 + (t - s) / tau_0) dm(s), m the bend (c_1 0.055 ... 0.07, tau_0 0.5 ... 1 s; J_0's instant part
# is a gain, left in the bend's scale). Labelled "creep".

def log_creep_kernel(n, dt, c1, tau0):
    """c_1 ln(1 + t / tau_0)'s means over the sample intervals [j dt, (j + 1) dt], j = 0 ... n - 1 (closed form of its
    integral: (t + tau_0) ln(1 + t / tau_0) - t)."""
    t = np.arange(n + 1) * dt

    def F(x):
        return (x + tau0) * np.log1p(x / tau0) - x
    return c1 * np.diff(F(t)) / dt


def hereditary(m, kern):
    """sum_(j <= i) (m_j - m_(j-1)) kern_(i-j) (m_(-1) = m_0): a hereditary integral of the increments, by FFT."""
    dm = np.diff(m, prepend=m[0])
    n = len(m)
    L = 1 << int(math.ceil(math.log2(2 * n)))
    return np.fft.irfft(np.fft.rfft(dm, L) * np.fft.rfft(kern, L), L)[:n]


def alpha_c_bend(ws, dt, ra, tau_a):
    """The bend with the film's alpha_c relaxation: ws + ra (ws - lag(ws)), lag exact per step from ws[0]."""
    ws = np.asarray(ws, float)
    return ws + ra * (ws - lag(ws, dt, tau_a, float(ws[0])))

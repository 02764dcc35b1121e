"""The HOLDOUT34 set: written after HOLDOUT33 was measured, by a session that did not read how the diagnosis decides,
to be run once for the next round's measurement; kept out of ALL until then.

Mechanisms and signals that the other sets do not have (the laws are in :mod:`.mechanisms34`, the signals in
:mod:`.signals34`, each beside its source; the citations were written from memory, as they say). Every core is a stage
pushed by a voice coil (its force proportional to the drive) against a flexure (0.25 ... 0.5 of the pads' small-strain
stiffness) and resting on 64 filled-rubber pads bonded to it whose feet stick to the base plate and slip: each pad a
Gent rubber block in simple shear (tau = mu gamma J_m / (J_m - gamma^2), Gent 1996) in series with Coulomb friction,
the pads' slip strains log-normal (the log's spread 0.35 ... 0.55, from their different normal loads), the locking
parameter J_m such that the last pad to slip reaches 0.55 ... 0.75 of it in gamma^2 (its stress 2.2 ... 4 times the
linear law's when its foot slips). The drive's peak pushes the virgin stage to 1.8 ... 2.6 times the median slip
strain; the travel, times a drawn gain, is the output. Quasi-static: rate independent, with return-point memory (every
pad's strain a stop operator of the travel), but NOT a Prandtl-Ishlinskii model: a pad's force is not linear in its
strain, so the branches depend on where the pads sat at a reversal, not only on the distance from it (not Masing's).
Its closeness to one is measured in tests/test_realistic_holdout34.py: a PI model of 12 plays of the drive fitted by
NNLS leaves 1.4 ... 1.8 sigma RMS on the clean record (at most 4.6 ... 7.5 sigma). Every record starts at 0 V from the
virgin bed (every pad unstrained) except the initial-state case's.

- a clean core under a top-loading washing machine's agitator through a wash programme (bouts of crank-and-sector
  strokes, gentle and normal), +-44 ... 48 V, with a noisy input monitor, sampled at 1.785 kHz;
- creep of a lead shim under the sensor's mount by Andrade's law (beta t^(1/3) + kappa t, the viscous flow 0.15 ...
  0.4 of the transient at 10 s), 5 ... 8 % of the core's output after 10 s of a held load; under a sit-stand desk
  through a compressed working day, on a unipolar stroke, sampled at 241 Hz;
- rate dependence from a twin-tube damper valved harder in rebound than in compression (linear bleeds, the time
  constants 2.5 ... 5 ms in compression and 2 ... 3.5 times that in rebound); under an accelerator pedal in stop-and-go
  traffic (gentle tip-ins, quick lifts, kick-downs), on a unipolar stroke, with a noisy input monitor, sampled at
  1.595 kHz;
- an offset drift from the stage's sand-filled legs compacting under a compressor's vibration in the next room (Knight
  et al.'s inverse-logarithmic law in the running time, B 0.6 ... 1.5, tau 0.5 ... 3 s; still while the compressor
  stops), 4 ... 8 % of the span at the end, either sign; under a snake robot's joint crawling by Hirose's serpenoid
  curve (stretches with turns and sensing stops), +-44 ... 48 V, sampled at 612 Hz;
- asymmetry of a CdS photoresistor behind a shutter edge on the stage (the photocurrent as the light^gamma, Rose's
  gamma = T_c / (T + T_c) 0.6 ... 0.85; the ends' secants 10 ... 17 % apart, on a drawn side); under a tug of war's
  rope mark (heaves in rhythm, slips, stalemates, the winners' run), +-44 ... 48 V, sampled at 1.145 kHz;
- saturation of a pre-tensioned membrane bulged by the oil the stage's plunger displaces, read at its apex (a spherical
  cap by Laplace's law: the volume (pi h / 6)(3 a^2 + h^2), the ends compressed by 10 ... 17 %); under a windsurfer
  pumping onto the plane, sailing through gusts and tacking, +-44 ... 48 V, with a noisy input monitor, sampled at
  767 Hz;
- a delay of a smart sensor's firmware (an exponential moving average s += (x - s) >> k, k 4 or 5, at 6, 8 or 10
  times the record's rate, reported one record sample late: 2.5 ... 6.2 samples in all at low frequency), the core on
  the sensor's finer grid; under a pogo stick's spring (sessions of hops pumped up and let die, stepping on and off),
  on a unipolar stroke, with a noisy input monitor, sampled at 451 Hz;
- a core left by an emergency stop during a swept-sine test at 1.15 ... 1.4 times the record's peak force (a linear
  chirp cut at a drawn instant, the coil's current then decaying through its freewheel diode), the record starting
  there at 0 V; under a dancer's sway in a slow waltz (bars of sway, turns, hesitations), +-44 ... 48 V, sampled at
  968 Hz;
- two effects: the gain drift of a helium-neon laser lighting the sensor, sweeping its longitudinal modes through the
  neon line's gain as its tube warms (2 ... 5 sweeps over the record), and saturation of the transimpedance amplifier
  reading the bicell's difference current through antiparallel diodes (asinh, the ends compressed by 10 ... 17 %);
  under a bartender's cocktail shaker (rounds of hard shaking, pours between), +-44 ... 48 V, sampled at 1.215 kHz;
- out of vocabulary: the stage read through a sensor follower dragged by a soft spring over a magnetic detent rack
  (the Prandtl-Tomlinson model: eta = 2 pi F0 / (K p) 2 ... 4, the pitch 1/14 ... 1/9 of the stroke): the follower
  sticks in a detent and slips to the next, so the reading is a hysteretic staircase of the core; under a hula hoop's
  hip (sessions of circling, throws and drops), +-44 ... 48 V, sampled at 1.385 kHz.

Every bipolar drive is drawn until its weaker side reaches 0.85 of its stronger (a test programme's balance).
"""

import math

import numpy as np
from scipy.optimize import brentq

from . import mechanisms34 as m34
from . import signals34 as s34
from .record import case_set, finish
from .set_tools import fits as _fits, grid as _grid, scale as _scale
from .set_tools import balanced


def _balanced(make, lo=0.85, tries=200):
    """:func:`.set_tools.balanced` with the 200 tries this set drew with."""
    return balanced(make, lo, tries)


HOLDOUT34, case, _rng = case_set("holdout34_", 34000)

N_PADS = 64


def _pads(rng, half):
    """The core: a bed of N_PADS Gent pads (the log slip strains' spread 0.35 ... 0.55, their median the unit of
    travel; the locking such that the largest slip strain reaches 0.55 ... 0.75 of J_m in gamma^2), a flexure of 0.25
    ... 0.5 of the bed's small-strain stiffness, the drive over V_F the force, the half-span ``half`` pushing the virgin
    stage to 1.8 ... 2.6 times the median slip strain; the travel times a drawn gain."""
    sig, lock = rng.uniform(0.35, 0.55), rng.uniform(0.55, 0.75)
    kf, r_pk = rng.uniform(0.25, 0.5), rng.uniform(1.8, 2.6)
    bed = m34.pad_bed(N_PADS, 1.0, sig, lock)
    F_pk = float(m34.pad_virgin_force(r_pk, bed, kf))
    return dict(sigma_s=sig, lock=lock, kf=kf, r_pk=r_pk, V_F=half / F_pk, gain=rng.uniform(0.7, 1.4))


_BEDS = {}


def _bed(core):
    key = (core["sigma_s"], core["lock"])
    if key not in _BEDS:
        _BEDS[key] = m34.pad_bed(N_PADS, 1.0, *key)
    return _BEDS[key]


def _core_of(core, v, state=None, return_state=False):
    F = np.asarray(v, float) / core["V_F"]
    x, st = m34.pad_stage(F, _bed(core), core["kf"], state=state, return_state=True)
    out = core["gain"] * x
    return (out, st) if return_state else out


# ---- clean ----

@case
def clean_gent_pads_washing_machine_agitator_1785hz(seed):
    rng = _rng(seed, 1)
    dt = 1 / 1785

    def make():
        bouts, k, T_end = s34.agitator_programme(rng)
        if not _fits(dt, T_end):
            return None
        t = _grid(dt, T_end)
        return s34.agitator_angle(t, bouts, k), t, bouts, k
    x, t, bouts, k = _balanced(make)
    amp = rng.uniform(44.0, 48.0)
    v = _scale(x, amp)
    core = _pads(rng, amp)
    off = rng.uniform(-4.0, 4.0)
    y = _core_of(core, v) + off
    rec = finish("holdout34_clean_gent_pads_washing_machine_agitator_1785hz", seed, t, v, y, set(), "explained",
                 f"a clean core (a voice-coil stage on {N_PADS} Gent rubber pads that stick and slip, slip strains' "
                 f"spread {core['sigma_s']:.2f}, locking {core['lock']:.2f}, flexure {core['kf']:.2f}, peak "
                 f"{core['r_pk']:.2f} of the median slip) under a washing machine's agitator ({len(bouts)} bouts), "
                 f"+-{amp:.0f} V, 1.785 kHz", rng, monitor_noise=3e-4)
    rec.extra.update(core, offset=off, bouts=bouts, k_crank=k, x=x, amp=amp, drive=v)
    return rec


# ---- one effect ----

@case
def creep_andrade_lead_shim_sit_stand_desk_241hz(seed):
    rng = _rng(seed, 2)
    dt = 1 / 241
    times, vals = s34.desk_day(rng)
    while not _fits(dt, times[-1]):
        times, vals = s34.desk_day(rng)
    t = _grid(dt, times[-1])
    p = s34.keyframes(t, times, vals)
    top = rng.uniform(88.0, 97.0)
    v = top * p / p.max()
    core = _pads(rng, 50.0)
    h = _core_of(core, v)
    c, beta, fl = rng.uniform(0.05, 0.08), 1.0, rng.uniform(0.15, 0.4)
    kappa = fl * beta * 10.0 ** (1 / 3) / 10.0                     # the flow fl of the transient at 10 s
    cr = m34.andrade_creep(h, dt, c, beta, kappa)
    rec = finish("holdout34_creep_andrade_lead_shim_sit_stand_desk_241hz", seed, t, v, h + cr, {"creep"}, "either",
                 f"creep of a lead shim by Andrade's law (the viscous flow {fl:.0%} of the transient at 10 s; {c:.1%} "
                 f"after 10 s) under a sit-stand desk through a working day ({len(times)} keys), to {top:.0f} V, "
                 f"241 Hz", rng)
    rec.extra.update(core, times=times, vals=vals, top=top, p=p, h=h, c_creep=c, beta=beta, kappa=kappa, flow=fl,
                     creep=cr, drive=v)
    return rec


@case
def rate_rebound_valved_damper_stop_and_go_pedal_1595hz(seed):
    rng = _rng(seed, 3)
    dt = 1 / 1595
    times, vals = s34.stop_and_go(rng)
    while not _fits(dt, times[-1]):
        times, vals = s34.stop_and_go(rng)
    t = _grid(dt, times[-1])
    p = s34.keyframes(t, times, vals)
    top = rng.uniform(88.0, 97.0)
    v = top * p / p.max()
    core = _pads(rng, 50.0)
    h = _core_of(core, v)
    tau_c = rng.uniform(2.5e-3, 5e-3)
    ratio = rng.uniform(2.0, 3.5)
    y = m34.valved_damper_stage(h, dt, ratio * tau_c, tau_c)
    rec = finish("holdout34_rate_rebound_valved_damper_stop_and_go_pedal_1595hz", seed, t, v, y, {"rate_dependence"},
                 "either",
                 f"a twin-tube damper valved {ratio:.1f} times harder in rebound ({ratio * tau_c * 1e3:.1f} ms) than "
                 f"in compression ({tau_c * 1e3:.1f} ms) under an accelerator pedal in stop-and-go traffic, to "
                 f"{top:.0f} V, 1.595 kHz", rng, monitor_noise=2.5e-4)
    rec.extra.update(core, times=times, vals=vals, top=top, p=p, h=h, tau_c=tau_c, tau_e=ratio * tau_c, ratio=ratio,
                     drive=v)
    return rec


@case
def drift_sand_leg_compaction_serpenoid_snake_612hz(seed):
    rng = _rng(seed, 4)
    dt = 1 / 612

    def make():
        stretches, T_end = s34.serpenoid_programme(rng)
        if not _fits(dt, T_end):
            return None
        t = _grid(dt, T_end)
        return s34.serpenoid_joint(t, stretches), t, stretches
    x, t, stretches = _balanced(make)
    amp = rng.uniform(44.0, 48.0)
    v = _scale(x, amp)
    core = _pads(rng, amp)
    h = _core_of(core, v)
    T = t[-1]
    runs, tc = [], rng.uniform(0.05, 0.2) * T
    while tc < 0.9 * T:
        dur = rng.uniform(5.0, 15.0)
        runs.append((tc, dur))
        tc += dur + rng.uniform(4.0, 12.0)
    B, tau = rng.uniform(0.6, 1.5), rng.uniform(0.5, 3.0)
    ts = m34.shaking_time(t, runs)
    comp = m34.knight_compaction(ts, B, tau)
    mag, sd = rng.uniform(0.04, 0.08), float(rng.choice([-1.0, 1.0]))
    off = sd * mag * np.ptp(h) * comp / comp[-1]
    rec = finish("holdout34_drift_sand_leg_compaction_serpenoid_snake_612hz", seed, t, v, h + off, {"drift"},
                 "either",
                 f"an offset drift from sand-filled legs compacting under a compressor's {len(runs)} runs (Knight's "
                 f"law, B {B:.2f}, tau {tau:.1f} s; {sd * mag:+.1%} of the span at the end) under a snake robot's "
                 f"serpenoid joint ({len(stretches)} stretches), +-{amp:.0f} V, 612 Hz", rng)
    rec.extra.update(core, stretches=stretches, amp=amp, x=x, h=h, runs=runs, B=B, tau=tau, t_shake=ts, comp=comp,
                     mag=mag, side=sd, offset=off, drive=v)
    return rec


@case
def asymmetry_cds_photoresistor_tug_of_war_1145hz(seed):
    rng = _rng(seed, 5)
    dt = 1 / 1145

    def make():
        times, vals = s34.tug_of_war(rng, int(rng.integers(3, 5)))
        if not _fits(dt, times[-1]):
            return None
        t = _grid(dt, times[-1])
        return s34.keyframes(t, times, vals), t, times, vals
    x, t, times, vals = _balanced(make)
    amp = rng.uniform(44.0, 48.0)
    v = _scale(x, amp)
    core = _pads(rng, amp)
    h = _core_of(core, v)
    c = (h.max() + h.min()) / 2
    X = np.abs(h - c).max()
    gamma = m34.rose_exponent(300.0, rng.uniform(450.0, 1700.0))
    asym, sd = rng.uniform(0.10, 0.17), float(rng.choice([-1.0, 1.0]))
    a = brentq(lambda q: -m34.ldr_asym(q, gamma) - asym, 1e-4, 0.95, xtol=1e-15)
    y = c + sd * X * m34.ldr_reading(sd * (h - c) / X, a, gamma)
    rec = finish("holdout34_asymmetry_cds_photoresistor_tug_of_war_1145hz", seed, t, v, y, {"asymmetry"}, "either",
                 f"a CdS photoresistor behind a shutter on the stage (gamma {gamma:.2f}, the light +-{a:.0%}: the "
                 f"ends' secants {asym:.0%} apart) under a tug of war's rope mark, +-{amp:.0f} V, 1.145 kHz", rng)
    rec.extra.update(core, times=times, vals=vals, amp=amp, x=x, h=h, centre=c, X=X, asym=asym, side=sd, a_light=a,
                     gamma=gamma, drive=v)
    return rec


@case
def saturation_oil_bulged_membrane_windsurf_pumping_767hz(seed):
    rng = _rng(seed, 6)
    dt = 1 / 767

    def make():
        legs, T_end = s34.windsurf_session(rng, int(rng.integers(3, 5)))
        if not _fits(dt, T_end):
            return None
        t = _grid(dt, T_end)
        return s34.sail_angle(t, legs), t, legs
    x, t, legs = _balanced(make)
    amp = rng.uniform(44.0, 48.0)
    v = _scale(x, amp)
    core = _pads(rng, amp)
    h = _core_of(core, v)
    c = (h.max() + h.min()) / 2
    X = np.abs(h - c).max()
    comp = rng.uniform(0.10, 0.17)
    b = brentq(lambda q: 1 - float(m34.membrane_reading(1.0, q)) - comp, 0.01, 20.0, xtol=1e-15)
    y = c + X * m34.membrane_reading((h - c) / X, b)
    rec = finish("holdout34_saturation_oil_bulged_membrane_windsurf_pumping_767hz", seed, t, v, y, {"saturation"},
                 "either",
                 f"a pre-tensioned membrane bulged by the oil the stage's plunger displaces, read at its apex (a "
                 f"spherical cap; the ends compressed by {comp:.0%}) under a windsurfer's {len(legs)} legs, "
                 f"+-{amp:.0f} V, 767 Hz", rng, monitor_noise=3e-4)
    rec.extra.update(core, legs=legs, amp=amp, x=x, h=h, centre=c, X=X, comp=comp, b=b, drive=v)
    return rec


@case
def delay_ema_smart_sensor_pogo_stick_451hz(seed):
    rng = _rng(seed, 7)
    dt = 1 / 451
    R, k = int(rng.choice([6, 8, 10])), int(rng.choice([4, 5]))
    segs, T_end = s34.pogo_sessions(rng, int(rng.integers(3, 5)))
    while not _fits(dt, T_end):
        segs, T_end = s34.pogo_sessions(rng, int(rng.integers(3, 5)))
    n = min(max(int(T_end / dt), 10_050), 40_000)
    tf = np.arange((n - 1) * R + 1) * (dt / R)
    zf = s34.pogo_compression(tf, segs)
    top = rng.uniform(88.0, 97.0)
    v_f = top * zf / zf.max()
    v, t = v_f[::R], tf[::R]
    core = _pads(rng, 50.0)
    h_f = _core_of(core, v_f)
    y = m34.ema_sensor(h_f, R, k)
    lag = (2.0 ** k - 1) / R + 1.0
    rec = finish("holdout34_delay_ema_smart_sensor_pogo_stick_451hz", seed, t, v, y, {"delay"}, "either",
                 f"a smart sensor's exponential moving average (alpha 2^-{k} at {R} times the record's rate, reported "
                 f"a sample late: {lag:.2f} samples at low frequency) under a pogo stick's spring, to {top:.0f} V, "
                 f"451 Hz", rng, monitor_noise=2e-4)
    rec.extra.update(core, segs=segs, top=top, R=R, k=k, lag=lag, v_fine=v_f, drive=v)
    return rec


@case
def initial_state_estop_swept_sine_slow_waltz_968hz(seed):
    rng = _rng(seed, 8)
    dt = 1 / 968
    amp = rng.uniform(44.0, 48.0)
    core = _pads(rng, amp)
    A = rng.uniform(1.15, 1.4) * amp
    f0, f1, Tsw = rng.uniform(0.5, 1.0), rng.uniform(5.0, 8.0), rng.uniform(20.0, 30.0)
    t_cut = rng.uniform(0.3, 0.8) * Tsw
    tau_L = rng.uniform(0.005, 0.02)
    _, path = m34.estop_path(A, f0, f1, Tsw, t_cut, tau_L)
    p_cut = A * math.sin(2 * math.pi * (f0 * t_cut + (f1 - f0) * t_cut ** 2 / (2 * Tsw)))
    _, state = _core_of(core, path, return_state=True)

    def make():
        times, vals, bar = s34.slow_waltz(rng, int(rng.integers(16, 22)))
        if not _fits(dt, times[-1]):
            return None
        t = _grid(dt, times[-1])
        return s34.keyframes(t, times, vals), t, times, vals, bar
    x, t, times, vals, bar = _balanced(make)
    v = _scale(x, amp)
    y = _core_of(core, v, state=state)
    rec = finish("holdout34_initial_state_estop_swept_sine_slow_waltz_968hz", seed, t, v, y, {"initial_state"},
                 "either",
                 f"a core left by an emergency stop during a swept-sine test at {A:.0f} V ({f0:.2f} -> {f1:.1f} Hz, "
                 f"cut at {t_cut:.1f} s at {p_cut:.0f} V) under a slow waltz "
                 f"({60 / bar:.1f} bars a minute), +-{amp:.0f} V, 968 Hz", rng)
    rec.extra.update(core, amp=amp, A=A, f0=f0, f1=f1, T_sweep=Tsw, t_cut=t_cut, p_cut=p_cut, tau_L=tau_L, path=path,
                     state=state, times=times, vals=vals, bar=bar, x=x, drive=v)
    return rec


# ---- two effects ----

@case
def pair_gain_drift_saturation_hene_mode_sweep_diode_tia_cocktail_shaker_1215hz(seed):
    rng = _rng(seed, 9)
    dt = 1 / 1215

    def make():
        rounds, pours, T_end = s34.shaking_rounds(rng, int(rng.integers(2, 4)))
        if not _fits(dt, T_end):
            return None
        t = _grid(dt, T_end)
        return s34.shaker_position(t, rounds, pours), t, rounds, pours
    x, t, rounds, pours = _balanced(make)
    amp = rng.uniform(44.0, 48.0)
    v = _scale(x, amp)
    core = _pads(rng, amp)
    h = _core_of(core, v)
    fwhm = 1.5
    fsr, thresh = rng.uniform(0.8, 1.1), rng.uniform(0.3, 0.45)
    sweeps, tau_w = rng.uniform(2.0, 5.0), rng.uniform(300.0, 900.0)
    t_on = rng.uniform(60.0, 240.0)
    n_sw = sweeps / (1 - math.exp(-t[-1] / tau_w))                 # the warm-up's sweeps, sweeps of them in the record
    phase = m34.tube_phase(t, n_sw, tau_w, t_on) + rng.uniform(0, 1)
    P = m34.hene_power(phase, fsr, fwhm, thresh)
    gain = P / P[0]
    c = (h.max() + h.min()) / 2
    X = np.abs(h - c).max()
    comp = rng.uniform(0.10, 0.17)
    b = brentq(lambda q: 1 - float(m34.tia_reading(1.0, q)) - comp, 0.01, 20.0, xtol=1e-15)
    u = gain * (h - c) / X
    y = c + X * m34.tia_reading(u, b)
    rec = finish("holdout34_pair_gain_drift_saturation_hene_mode_sweep_diode_tia_cocktail_shaker_1215hz", seed, t, v,
                 y, {"gain_drift", "saturation"}, "either",
                 f"a helium-neon laser sweeping its modes as it warms ({sweeps:.1f} sweeps, the power "
                 f"{gain.min():.2f} ... {gain.max():.2f} of its start) read through antiparallel diodes (asinh, the "
                 f"ends compressed by {comp:.0%}) under a bartender's {len(rounds)} rounds of shaking, +-{amp:.0f} V, "
                 f"1.215 kHz", rng)
    rec.extra.update(core, rounds=rounds, pours=pours, amp=amp, x=x, h=h, fsr=fsr, fwhm=fwhm, thresh=thresh,
                     sweeps=sweeps, tau_w=tau_w, t_on=t_on, phase=phase, P=P, gain_t=gain, centre=c, X=X, comp=comp,
                     b=b, drive=v)
    return rec


# ---- out of vocabulary ----

@case
def oov_tomlinson_detent_follower_hula_hoop_1385hz(seed):
    rng = _rng(seed, 10)
    dt = 1 / 1385

    def make():
        sessions, T_end = s34.hula_sessions(rng, int(rng.integers(3, 5)))
        if not _fits(dt, T_end):
            return None
        t = _grid(dt, T_end)
        return s34.hula_hip(t, sessions), t, sessions
    x, t, sessions = _balanced(make)
    amp = rng.uniform(44.0, 48.0)
    v = _scale(x, amp)
    core = _pads(rng, amp)
    h = _core_of(core, v)
    eta, pitch = rng.uniform(2.0, 4.0), np.ptp(h) / rng.uniform(9.0, 14.0)
    yf = m34.tomlinson_follower(h, eta, pitch)
    off = rng.uniform(-4.0, 4.0)
    rec = finish("holdout34_oov_tomlinson_detent_follower_hula_hoop_1385hz", seed, t, v, yf + off, set(),
                 "unexplained",
                 f"the stage read through a follower dragged by a soft spring over a magnetic detent rack "
                 f"(Prandtl-Tomlinson, eta {eta:.1f}, the pitch {pitch / np.ptp(h):.0%} of the stroke) under a hula "
                 f"hoop's hip ({len(sessions)} sessions), +-{amp:.0f} V, 1.385 kHz", rng)
    rec.extra.update(core, sessions=sessions, amp=amp, x=x, h=h, eta=eta, pitch=pitch, follower=yf, offset=off,
                     drive=v)
    return rec

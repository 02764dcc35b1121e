"""Controllers designed to a specification, on the nominal linear loop.

The hysteretic actuator is replaced, for design, by its nominal gain
``k_nom`` (the mean slope of :func:`hystcomp.iosys.mean_gain`, which is
exactly the gain of the compensated actuator ``model o C`` of
:func:`hystcomp.iosys.compensator_system` with ``nominal_gain="auto"``): the
nominal loop is ``L = C k_nom P``.

* :func:`design_pid` tunes a PID with a filtered derivative and a notch (or a
  low-pass roll-off) for the stage resonance to a gain crossover frequency
  and a phase margin; :func:`pid_gains` returns the gains and filters.
* :func:`design_state_feedback` is state feedback with integral action
  through python-control (:func:`control.lqr` / :func:`control.dlqr`,
  :func:`control.create_statefbk_iosystem`), with an observer-based output
  feedback form for the loop builders of :mod:`hystcomp.loops`.
* :func:`loop_margins` reads the achieved margins with
  :func:`control.stability_margins`, named.

Every controller comes back as a python-control system (discrete when `dt`
is given) that :func:`hystcomp.loops.build_loop` takes as ``controller=``.

Examples
--------
>>> from hystcomp.iosys import piezo_stage
>>> c = design_pid(piezo_stage(), crossover_hz=40.0, phase_margin_deg=60.0,
...                actuator_gain=2.7, dt=1e-4, filter="lowpass", filter_hz=80.0)
>>> m = loop_margins(c, piezo_stage(), actuator_gain=2.7)
>>> round(m.crossover_hz, 3), round(m.phase_margin_deg, 3)
(40.0, 60.0)
"""

import warnings
from dataclasses import dataclass

import numpy as np
from scipy.optimize import brentq

import control as ct

from ._validation import as_scalar, check_choice
from .iosys import discretize, pid

__all__ = ["PIDGains", "pid_gains", "design_pid", "Margins", "loop_margins", "resonance",
           "StateFeedbackDesign", "design_state_feedback"]


def _siso(sys, name):
    if not isinstance(sys, ct.LTI):
        raise TypeError(f"Parameter {name} is {type(sys).__name__}; expected a python-control LTI system")
    if sys.ninputs != 1 or sys.noutputs != 1:
        raise ValueError(f"Parameter {name} has {sys.ninputs} inputs and {sys.noutputs} outputs; "
                         "expected a single-input single-output system")
    return sys


def resonance(plant):
    """The least-damped complex pole pair of a plant: ``(frequency_hz, damping)``.

    Parameters
    ----------
    plant : control.LTI
        SISO, continuous or discrete (discrete poles are mapped back with
        ``s = log(z) / dt``).

    Returns
    -------
    (float, float) or None
        Natural frequency in Hz and damping ratio, None without complex poles.

    Examples
    --------
    >>> from hystcomp.iosys import piezo_stage
    >>> [round(x, 6) for x in resonance(piezo_stage(natural_freq_hz=250.0, damping=0.02))]
    [250.0, 0.02]
    """
    _siso(plant, "plant")
    p = np.asarray(ct.poles(plant), dtype=complex)
    if plant.isdtime(strict=True):
        p = np.log(p[p != 0]) / plant.dt
    p = p[np.abs(p.imag) > 1e-9 * np.maximum(np.abs(p), 1.0)]
    if p.size == 0:
        return None
    wn = np.abs(p)
    zeta = -p.real / wn
    i = int(np.argmin(zeta))
    return float(wn[i] / (2 * np.pi)), float(zeta[i])


def _response(sys, omega):
    """Complex frequency response of a SISO LTI at `omega` [rad/s]."""
    from ._circle import _response as response

    return response(sys, np.atleast_1d(np.asarray(omega, dtype=float)))


@dataclass(frozen=True)
class PIDGains:
    """Gains and filters of a PID designed by :func:`pid_gains`.

    ``C = (kp + ki/s + kd s/(tau_d s + 1)) F(s)`` with F the resonance
    filter: a notch ``(s^2 + 2 zeta_z wn s + wn^2)/(s^2 + 2 zeta_p wn s +
    wn^2)``, a low-pass ``wn^2/(s^2 + 2 zeta_p wn s + wn^2)``, or 1.

    Parameters
    ----------
    kp, ki, kd : float
        Proportional, integral and derivative gains (as in
        :func:`hystcomp.iosys.pid`).
    tau_d : float or None
        Derivative filter time constant in s (None when ``kd = 0``).
    filter : {"notch", "lowpass", None}
        The resonance filter.
    filter_hz : float or None
        Its frequency in Hz.
    filter_damping : (float, float) or None
        ``(zeta_z, zeta_p)`` of the notch (zeta_z unused by the low-pass).
    dt : float or None
        Sampling time of :attr:`system` (None: continuous).
    crossover_hz, phase_margin_deg : float
        The specification the gains were tuned to.

    Examples
    --------
    >>> from hystcomp.iosys import piezo_stage
    >>> g = pid_gains(piezo_stage(), 150.0, 60.0, dt=1e-4)
    >>> g.filter, round(g.filter_hz, 1), g.system().dt
    ('notch', 300.0, 0.0001)
    """

    kp: float
    ki: float
    kd: float
    tau_d: object
    filter: object
    filter_hz: object
    filter_damping: object
    dt: object
    crossover_hz: float
    phase_margin_deg: float

    def filter_system(self):
        """The resonance filter F as a python-control system (1 if none).

        Discrete filters are the Tustin transform prewarped at the filter
        frequency, so the notch sits exactly on the resonance.

        Examples
        --------
        >>> from hystcomp.iosys import piezo_stage
        >>> f = pid_gains(piezo_stage(), 150.0, 60.0).filter_system()
        >>> round(abs(complex(f(2j * 3.141592653589793 * 300.0))), 3)   # zeta_z / zeta_p
        0.071
        """
        if self.filter is None:
            return ct.ss([], [], [], [[1.0]], dt=self.dt if self.dt else 0)
        wn = 2 * np.pi * self.filter_hz
        zz, zp = self.filter_damping
        den = [1.0, 2 * zp * wn, wn * wn]
        num = [1.0, 2 * zz * wn, wn * wn] if self.filter == "notch" else [wn * wn]
        f = ct.tf(num, den)
        if self.dt:
            f = ct.sample_system(f, self.dt, method="tustin", prewarp_frequency=wn)
        return ct.ss(f)

    def system(self, name="controller", inputs="e", outputs="u"):
        """The controller as a python-control system (discrete when `dt` is set).

        The PID part is :func:`hystcomp.iosys.pid` (backward-Euler integral,
        zero-order-hold derivative filter) when discrete.

        Parameters
        ----------
        name, inputs, outputs : str
            System and signal names.

        Returns
        -------
        control.StateSpace

        Examples
        --------
        >>> g = PIDGains(1.0, 10.0, 0.0, None, None, None, None, 1e-3, 5.0, 60.0)
        >>> c = g.system()
        >>> c.dt, c.input_labels, c.output_labels
        (0.001, ['e'], ['u'])
        """
        if self.dt:
            core = pid(self.kp, self.ki, self.kd, self.dt, tau_d=self.tau_d or None)
        else:
            tau = self.tau_d or 1.0
            core = ct.ss(ct.tf([self.kp * tau + self.kd, self.kp + self.ki * tau, self.ki], [tau, 1.0, 0.0])
                         if self.kd else ct.tf([self.kp, self.ki], [1.0, 0.0]))
        c = ct.ss(core) if self.filter is None else ct.series(ct.ss(core), self.filter_system())
        c = ct.ss(c)
        return ct.ss(c.A, c.B, c.C, c.D, c.dt, name=name, inputs=inputs, outputs=outputs)


def _pid_from_phase(phi, wc, ratio):
    """Series PID of unit gain adding about `phi` rad at `wc`:
    ``(1 + wi/s)(1 + s/wd)/(1 + s/(n wd))``; returns (ki, kp, kd, tau) for K=1."""
    if phi >= 0:
        wi = wc / ratio
        s = np.sin(phi)
        n = (1 + s) / (1 - s)
        wd = wc / np.sqrt(n)
    else:
        wi = wc * np.tan(np.arctan(1.0 / ratio) - phi)
        n, wd = 1.0, np.inf
    if n <= 1.0 + 1e-12:
        return wi, 1.0, 0.0, None
    tau = 1.0 / (n * wd)
    ki = wi
    kp = 1.0 + wi / wd - ki * tau
    kd = 1.0 / wd - kp * tau
    return ki, kp, kd, tau


def pid_gains(plant, crossover_hz, phase_margin_deg, actuator_gain=1.0, dt=None, filter="notch",
              resonance_hz=None, resonance_damping=None, filter_hz=None, filter_damping=0.7,
              integral_ratio=5.0, max_lead_deg=70.0):
    """Tune a PID with derivative filter and resonance filter to a crossover
    and a phase margin on the nominal loop ``C k P``.

    The controller is ``K (1 + wi/s) (1 + s/wd)/(1 + s/(n wd)) F(s)``: the
    integral corner ``wi = wc / integral_ratio``, the lead (derivative with
    its filter) centred on the crossover ``wc`` with the ratio ``n`` that
    gives the phase still missing, then ``K`` for ``|L(j wc)| = 1``; when
    the loop has more phase than needed there is no derivative and the
    integral corner moves up instead.  The phase is solved on the exact
    (discrete when `dt` is given) loop, so the specification holds for the
    sampled loop, not only its continuous approximation.

    Parameters
    ----------
    plant : control.LTI
        SISO plant (e.g. :func:`hystcomp.iosys.piezo_stage`); continuous,
        or discrete with sampling time `dt`.
    crossover_hz : float
        Gain crossover frequency f_c in Hz, ``|L(j 2 pi f_c)| = 1``.
    phase_margin_deg : float
        Phase margin at f_c in degrees (0 < PM < 90 + lead).
    actuator_gain : float, optional
        Nominal actuator gain k (default 1): the compensated actuator's
        ``nominal_gain`` or the raw actuator's mean slope.
    dt : float, optional
        Sampling time: the controller is then discrete and the plant is
        discretised by zero-order hold.
    filter : {"notch", "lowpass", None}, optional
        Resonance filter (default a notch on the least-damped pole pair).
    resonance_hz, resonance_damping : float, optional
        The resonance to filter; default from the plant's poles
        (:func:`resonance`).  The notch's zeros take the resonance damping.
    filter_hz : float, optional
        Frequency of the filter in Hz; default the resonance (a low-pass
        roll-off is usually placed lower, e.g. at twice the crossover).
    filter_damping : float, optional
        Damping of the filter's poles (default 0.7).
    integral_ratio : float, optional
        ``wc / wi`` (default 5).
    max_lead_deg : float, optional
        Largest phase the lead may add, below 90 degrees (default 70).

    Returns
    -------
    PIDGains

    Raises
    ------
    ValueError
        If the specification cannot be met: more phase needed than the lead
        gives, or less than a pure integral leaves; or the loop crosses
        0 dB again (the resonance peak) or is unstable.

    Examples
    --------
    >>> from hystcomp.iosys import piezo_stage
    >>> g = pid_gains(piezo_stage(), 500.0, 60.0, actuator_gain=2.7)
    >>> bool(g.kd > 0), bool(g.tau_d > 0)     # above the notch the loop needs a lead
    (True, True)
    >>> pid_gains(piezo_stage(), 40.0, 60.0, filter=None)
    Traceback (most recent call last):
    ...
    ValueError: Parameters crossover_hz = 40.0 and phase_margin_deg = 60.0 cannot be met: the nominal plant has phase -0.8 deg at 40.0 Hz, and the PID adds between -89.5 and +70 deg (lower the crossover, the phase margin, or raise max_lead_deg)
    """
    _siso(plant, "plant")
    fc = as_scalar(crossover_hz, "crossover_hz", positive=True)
    pm = as_scalar(phase_margin_deg, "phase_margin_deg", positive=True)
    k = as_scalar(actuator_gain, "actuator_gain")
    if k == 0:
        raise ValueError("Parameter actuator_gain is 0 but should be nonzero")
    check_choice(filter, "filter", ("notch", "lowpass", None))
    ratio = as_scalar(integral_ratio, "integral_ratio", positive=True)
    if dt is not None:
        dt = as_scalar(dt, "dt", positive=True)
        if fc >= 0.5 / dt:
            raise ValueError(f"Parameter crossover_hz is {fc} but should be below the Nyquist frequency "
                             f"{0.5 / dt:g} Hz of dt = {dt}")
        pd = discretize(plant, dt)
    else:
        if plant.isdtime(strict=True):
            raise ValueError(f"Parameter plant is discrete (dt = {plant.dt}) but dt is None; pass dt")
        pd = plant
    fdamp = (None, None)
    fhz = None
    if filter is not None:
        res = resonance(plant)
        if resonance_hz is None and res is None:
            raise ValueError("Parameter filter is set but the plant has no complex poles; pass resonance_hz")
        fhz = as_scalar(resonance_hz, "resonance_hz", positive=True) if resonance_hz is not None else res[0]
        if filter_hz is not None:
            fhz = as_scalar(filter_hz, "filter_hz", positive=True)
        zz = (as_scalar(resonance_damping, "resonance_damping", nonnegative=True)
              if resonance_damping is not None else (res[1] if res is not None else 0.05))
        fdamp = (zz, as_scalar(filter_damping, "filter_damping", positive=True))
    wc = 2 * np.pi * fc
    target = -np.pi + np.radians(pm)

    def make(phi, gain=1.0):
        ki, kp, kd, tau = _pid_from_phase(phi, wc, ratio)
        return PIDGains(gain * kp, gain * ki, gain * kd, tau, filter, fhz,
                        fdamp if filter is not None else None, dt, fc, pm)

    p_wc = complex(_response(pd, wc)[0]) * k
    f_wc = complex(_response(make(0.0).filter_system(), wc)[0]) if filter is not None else 1.0
    if dt:
        z = np.exp(1j * wc * dt)

    def pid_response(g):
        # iosys.pid: kp + ki dt z/(z - 1) + (kd/tau) (z - 1)/(z - a), a = exp(-dt/tau); or continuous
        if dt:
            c = g.kp + g.ki * dt * z / (z - 1)
            if g.kd:
                c += g.kd / g.tau_d * (z - 1) / (z - np.exp(-dt / g.tau_d))
            return c
        s_ = 1j * wc
        return g.kp + g.ki / s_ + (g.kd * s_ / (g.tau_d * s_ + 1) if g.kd else 0.0)

    def phase_error(phi):
        return np.angle(pid_response(make(phi)) * f_wc * p_wc / np.exp(1j * target))

    lead = as_scalar(max_lead_deg, "max_lead_deg", positive=True)
    if lead >= 90.0:
        raise ValueError(f"Parameter max_lead_deg is {lead} but should be below 90 (the most phase a "
                         "PID's derivative can add)")
    lo, hi = -np.radians(89.5) + np.arctan(1.0 / ratio), np.radians(lead)
    grid = np.linspace(lo, hi, 60)
    errs = np.array([phase_error(x) for x in grid])
    sign_change = np.nonzero((np.sign(errs[:-1]) != np.sign(errs[1:])) & (np.abs(errs[:-1] - errs[1:]) < np.pi))[0]
    if sign_change.size == 0:
        have = np.degrees(np.angle(p_wc))
        raise ValueError(
            f"Parameters crossover_hz = {fc} and phase_margin_deg = {pm} cannot be met: the nominal plant has "
            f"phase {have:.1f} deg at {fc} Hz, and the PID adds between -89.5 and +{np.degrees(hi):.0f} deg "
            "(lower the crossover, the phase margin, or raise max_lead_deg)"
            + (f"; actuator_gain = {k} is negative and turns the plant's phase by 180 deg" if k < 0 else ""))
    j = int(sign_change[0])
    phi = brentq(phase_error, grid[j], grid[j + 1], xtol=1e-12)
    gains = make(phi, 1.0 / abs(pid_response(make(phi)) * f_wc * p_wc))
    # one gain crossover only, and a stable loop (python-control's stability_margins is slow here)
    from ._circle import _frequency_grid

    ctrl = gains.system()
    loop1 = ct.series(ct.ss(pd), ctrl) * k
    w = _frequency_grid(loop1, 4000)
    mag = np.abs(_response(loop1, w))
    other = w[((w > 1.001 * wc) & (mag >= 1.0)) | ((w < 0.999 * wc) & (mag <= 1.0))]
    cl = ct.feedback(loop1, 1)
    stable = np.all(np.abs(ct.poles(cl)) < 1) if dt else np.all(np.real(ct.poles(cl)) < 0)
    if not stable or other.size:
        where = f"crosses 0 dB again near {other[0] / (2 * np.pi):.4g} Hz" if other.size else "is unstable"
        raise ValueError(
            f"Parameters crossover_hz = {fc} and phase_margin_deg = {pm} give a loop that {where}: the "
            "resonance peak reaches the crossover; lower the crossover, or filter the resonance "
            "(filter='notch', or a lower filter_hz)")
    return gains


def design_pid(plant, crossover_hz, phase_margin_deg, actuator_gain=1.0, dt=None, filter="notch",
               resonance_hz=None, resonance_damping=None, filter_hz=None, name="controller", **options):
    """A PID tuned to a crossover and a phase margin, as a python-control system.

    ``pid_gains(...).system(name)``: see :func:`pid_gains` for the design;
    the result plugs into :func:`hystcomp.loops.build_loop` as
    ``controller=`` and runs in the compiled loops.

    Parameters
    ----------
    plant : control.LTI
        SISO plant.
    crossover_hz : float
        Gain crossover frequency in Hz.
    phase_margin_deg : float
        Phase margin in degrees.
    actuator_gain : float, optional
        Nominal actuator gain (default 1).
    dt : float, optional
        Sampling time (discrete controller); default continuous.
    filter : {"notch", "lowpass", None}, optional
        Resonance filter (default "notch").
    resonance_hz, resonance_damping : float, optional
        Resonance to filter; default from the plant's poles.
    filter_hz : float, optional
        Filter frequency (default the resonance).
    name : str, optional
        Name of the system (default "controller"); signals ``e`` -> ``u``.
    **options
        ``filter_damping``, ``integral_ratio``, ``max_lead_deg`` of
        :func:`pid_gains`.

    Returns
    -------
    control.StateSpace

    Examples
    --------
    >>> from hystcomp.iosys import piezo_stage
    >>> c = design_pid(piezo_stage(), 150.0, 60.0, dt=1e-4)
    >>> c.dt, c.nstates       # PID (integral, derivative filter) + notch
    (0.0001, 4)
    """
    unknown = set(options) - {"filter_damping", "integral_ratio", "max_lead_deg"}
    if unknown:
        raise TypeError(f"design_pid got unexpected keyword arguments {sorted(unknown)}")
    if not isinstance(name, str):
        raise TypeError(f"Parameter name is {name!r} but should be a string")
    g = pid_gains(plant, crossover_hz, phase_margin_deg, actuator_gain=actuator_gain, dt=dt, filter=filter,
                  resonance_hz=resonance_hz, resonance_damping=resonance_damping, filter_hz=filter_hz,
                  **options)
    return g.system(name=name)


@dataclass(frozen=True)
class Margins:
    """Named result of :func:`control.stability_margins`.

    python-control returns ``(gm, pm, sm, wpc, wgc, wms)``: gain margin,
    phase margin [deg], stability margin, phase crossover, gain crossover
    and the frequency of the stability margin (rad/s); here in Hz.

    Parameters
    ----------
    gain_margin : float
        Factor by which the loop gain may grow (inf if the phase never
        crosses -180 deg).
    phase_margin_deg : float
        Phase margin in degrees.
    stability_margin : float
        Smallest distance of the Nyquist curve to -1.
    phase_crossover_hz : float
        Where the phase crosses -180 deg (the gain margin's frequency).
    crossover_hz : float
        Gain crossover, where ``|L| = 1`` (the phase margin's frequency).
    stability_margin_hz : float
        Where the stability margin is attained.

    Examples
    --------
    >>> Margins(2.0, 45.0, 0.5, 300.0, 20.0, 250.0).crossover_hz
    20.0
    """

    gain_margin: float
    phase_margin_deg: float
    stability_margin: float
    phase_crossover_hz: float
    crossover_hz: float
    stability_margin_hz: float


def loop_margins(controller, plant, actuator_gain=1.0):
    """Margins of the nominal loop ``L = C k P`` (:func:`control.stability_margins`).

    Parameters
    ----------
    controller : control.LTI
        SISO controller (discrete: the plant is discretised at its dt).
    plant : control.LTI
        SISO plant.
    actuator_gain : float, optional
        Nominal actuator gain k (default 1).

    Returns
    -------
    Margins

    Examples
    --------
    >>> from hystcomp.iosys import pid, piezo_stage
    >>> m = loop_margins(pid(0.0, 40.0, 0.0, 1e-4), piezo_stage(), actuator_gain=2.712)
    >>> round(m.crossover_hz, 1), round(m.phase_crossover_hz)     # the old demo loop
    (17.3, 300)
    """
    _siso(controller, "controller")
    _siso(plant, "plant")
    k = as_scalar(actuator_gain, "actuator_gain")
    if k == 0:
        raise ValueError("Parameter actuator_gain is 0 but should be nonzero (no loop without the actuator)")
    p = discretize(plant, controller.dt) if controller.isdtime(strict=True) else plant
    loop = ct.series(ct.ss(p), ct.ss(controller)) * k
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # python-control's note on its 'frd' fallback
        gm, pm, sm, wpc, wgc, wms = ct.stability_margins(loop)
    hz = 1.0 / (2 * np.pi)
    return Margins(float(gm), float(pm), float(sm), float(wpc) * hz, float(wgc) * hz, float(wms) * hz)


class StateFeedbackDesign:
    """State feedback with integral action (:func:`design_state_feedback`).

    Every parameter is kept as the attribute of the same name.

    Parameters
    ----------
    plant : control.StateSpace
        The nominal plant ``k P`` the gains were computed for (discrete when
        designed with `dt`), input ``u``, output ``y``.
    gain : ndarray, shape (1, n + 1)
        LQR gain ``[K_x, K_i]`` on the plant states and the integral of
        ``y - r``: ``u = -K_x x - K_i z``.
    controller : control.NonlinearIOSystem
        From :func:`control.create_statefbk_iosystem`: inputs desired state,
        desired input and the measured state.
    closed_loop : control.NonlinearIOSystem
        The nominal closed loop from the same call.
    observer_gain : ndarray, shape (n, 1)
        Gain of the state observer used by :meth:`output_feedback`.

    Examples
    --------
    >>> from hystcomp.iosys import piezo_stage
    >>> d = design_state_feedback(piezo_stage(), bandwidth_hz=30.0, actuator_gain=2.7, dt=1e-4)
    >>> d.gain.shape, d.controller.ninputs
    ((1, 3), 5)
    """

    def __init__(self, plant, gain, controller, closed_loop, observer_gain):
        self.plant = plant
        self.gain = gain
        self.controller = controller
        self.closed_loop = closed_loop
        self.observer_gain = observer_gain

    def output_feedback(self, name="controller", inputs="e", outputs="u"):
        """The design as a one-degree-of-freedom LTI controller from the
        tracking error ``e = r - y`` to the command ``u``.

        A full-order observer estimates the plant states from ``-e``
        (deviation coordinates: the reference shifts the estimate and the
        integral sees ``e``); ``u = -K_x x_hat - K_i z`` with z the
        integral of ``y - r = -e`` (a sum in discrete time, as in
        :func:`control.create_statefbk_iosystem`).  The loop builders of
        :mod:`hystcomp.loops` take it as ``controller=``.

        Parameters
        ----------
        name, inputs, outputs : str
            System and signal names.

        Returns
        -------
        control.StateSpace

        Examples
        --------
        >>> from hystcomp.iosys import piezo_stage
        >>> d = design_state_feedback(piezo_stage(), bandwidth_hz=30.0, dt=1e-4)
        >>> c = d.output_feedback()
        >>> c.nstates, c.dt
        (3, 0.0001)
        """
        P = self.plant
        A, B, C = np.asarray(P.A), np.asarray(P.B), np.asarray(P.C)
        n = A.shape[0]
        Kx, Ki = self.gain[:, :n], self.gain[:, n:]
        L = self.observer_gain
        dtime = P.isdtime(strict=True)
        h = 1.0  # python-control's integrator: dz/dt = y - r, or the sum z[k+1] = z[k] + y[k] - r[k]
        # states [x_hat, z]; input e (y = -e in deviation coordinates); u = -Kx x_hat - Ki z
        # with z the integral of y - r = -e
        Ao = np.block([[A - B @ Kx - L @ C, -B @ Ki], [np.zeros((1, n)), np.eye(1) if dtime else np.zeros((1, 1))]])
        Bo = np.vstack([-L, -h * np.ones((1, 1))])
        Co = np.hstack([-Kx, -Ki])
        Do = np.zeros((1, 1))
        return ct.ss(Ao, Bo, Co, Do, P.dt, name=name, inputs=inputs, outputs=outputs)


def design_state_feedback(plant, bandwidth_hz, actuator_gain=1.0, dt=None, integral_weight=None,
                          control_weight=1.0, observer_speed=4.0):
    """State feedback with integral action, by LQR, on the nominal plant ``k P``.

    The plant is augmented with the integral ``z`` of ``y - r``
    (:func:`control.lqr` / :func:`control.dlqr` with ``integral_action``);
    the weights are ``Q = diag(q_y C^T C, q_z)``, ``R = control_weight``,
    with ``q_z = R (w_b / |k P(j w_b)|)^2`` (the symmetric root locus of the
    integral channel ``k P(s)/s`` then puts the slow closed-loop pole near
    ``w_b = 2 pi bandwidth_hz``) and ``q_y = q_z / (10 w_b^2)``.  The controller and the
    nominal closed loop are python-control's
    :func:`control.create_statefbk_iosystem`.

    Parameters
    ----------
    plant : control.LTI
        SISO plant (states as given: for :func:`hystcomp.iosys.piezo_stage`
        position and velocity).
    bandwidth_hz : float
        Rough closed-loop bandwidth in Hz: sets the output weight, and the
        integral weight unless given.
    actuator_gain : float, optional
        Nominal actuator gain k (default 1).
    dt : float, optional
        Sampling time (discrete design on the zero-order-hold plant).
    integral_weight : float, optional
        Weight q_z of the integral state; default ``R (w_b / |k P(j w_b)|)^2``
        (times ``dt^2`` in discrete time, where the integral is a sum).
    control_weight : float, optional
        R (default 1).
    observer_speed : float, optional
        The observer (for :meth:`StateFeedbackDesign.output_feedback`) is
        placed this many times faster than the state-feedback poles
        (default 4).

    Returns
    -------
    StateFeedbackDesign

    Examples
    --------
    >>> from hystcomp.iosys import piezo_stage
    >>> d = design_state_feedback(piezo_stage(), bandwidth_hz=30.0, dt=1e-4)
    >>> bool(abs(d.closed_loop.linearize(0, 0).dcgain()[0][0] - 1) < 1e-9)  # integral action: no static error
    True
    """
    _siso(plant, "plant")
    k = as_scalar(actuator_gain, "actuator_gain")
    if k == 0:
        raise ValueError("Parameter actuator_gain is 0 but should be nonzero (the plant is not controllable)")
    wb = 2 * np.pi * as_scalar(bandwidth_hz, "bandwidth_hz", positive=True)
    r = as_scalar(control_weight, "control_weight", positive=True)
    speed = as_scalar(observer_speed, "observer_speed", positive=True)
    p = ct.ss(plant)
    p = ct.ss(p.A, p.B * k, p.C, p.D, p.dt, inputs="u", outputs="y", name="plant",
              states=[f"x{i}" for i in range(p.nstates)])
    if dt is not None:
        p = discretize(p, as_scalar(dt, "dt", positive=True))
    C = np.asarray(p.C)
    g = abs(complex(_response(p, wb)[0])) or 1.0
    # symmetric root locus of the integral channel k P(s)/s: |k P(j wb)/wb|^2 q_z = R puts the slow
    # closed-loop pole near wb; y itself gets a small weight (1/10 of the integral's at wb)
    qz = r * (wb / g) ** 2 if integral_weight is None else as_scalar(integral_weight, "integral_weight",
                                                                        positive=True)
    qy = 0.1 * qz / (wb * wb)
    if p.isdtime(strict=True) and integral_weight is None:
        qz *= p.dt ** 2  # python-control's discrete integrator is a sum, z[k+1] = z[k] + (y - r)
    n = p.nstates
    Q = np.zeros((n + 1, n + 1))
    Q[:n, :n] = qy * C.T @ C
    Q[n, n] = qz
    # the integrator of y - r: python-control integrates C x - r
    if p.isdtime(strict=True):
        K, _, _ = ct.dlqr(p, Q, [[r]], integral_action=C)
    else:
        K, _, _ = ct.lqr(p, Q, [[r]], integral_action=C)
    K = np.atleast_2d(np.asarray(K, dtype=float))
    full = ct.ss(p.A, p.B, np.eye(n), np.zeros((n, 1)), p.dt, inputs="u", outputs=p.state_labels,
                 states=p.state_labels, name="plant")
    ctrl, clsys = ct.create_statefbk_iosystem(full, K, integral_action=C, name="statefbk")
    # observer: poles `speed` times faster than the state-feedback poles of the plant part
    Acl = np.asarray(p.A) - np.asarray(p.B) @ K[:, :n]
    poles = np.linalg.eigvals(Acl)
    if p.isdtime(strict=True):
        obs = np.exp(np.log(poles.astype(complex)) * speed)
    else:
        obs = poles * speed
    obs = np.where(np.abs(obs.imag) < 1e-12, obs.real, obs)
    Lg = ct.place(np.asarray(p.A).T, C.T, obs).T
    return StateFeedbackDesign(p, K, ctrl, clsys, np.asarray(Lg, dtype=float).reshape(n, 1))

"""Hysteresis models and their inverses as python-control systems.

Every model (PI, StopPI, GPI, mGPI, ...) and every compensator (analytic
inverse, :class:`~hystcomp.inverses.ExactInverse`, ...) becomes a discrete
:class:`control.NonlinearIOSystem` subclass whose state is the model's
explicit state (play positions ``play[i]``, operator outputs
``operator[i]``, ...) minus its virgin state, so that python-control's
default ``X0 = 0`` is the virgin state:

* :func:`hysteresis_system` -- a :class:`HysteresisBlock`,
  ``w[k] = actuator_gain * model(v[k]; x[k])``, ``x[k+1]`` the state after
  ``v[k]`` (feedthrough: the output answers the current input);
* :func:`compensator_system` -- a :class:`CompensatorBlock`,
  ``v[k] = inverse(nominal_gain * u[k]; x[k])``;
* :func:`piezo_stage`, :func:`pid`, :func:`discretize` -- a plant and a
  controller for the loops of :mod:`hystcomp.loops`;
* :func:`interconnect` -- :func:`control.interconnect` after a wiring check
  (:func:`check_wiring`) that names the blocks at fault for timebase
  mismatches, algebraic loops and unknown signal names.

The blocks work through the model protocol only (``simulate(v,
initial_state, return_state)``, ``n_states``, ``default_state()``), so any
model that follows it works; PI, mGPI, StopPI and exact inverses call the
compiled kernels directly (fast paths that run the same kernel with the same
arguments as ``simulate``, hence the same numbers).

Model data stay in the blocks, never in python-control's ``params`` (an
interconnection merges the params of all its subsystems into one dict); the
params hold only gains worth sweeping: ``actuator_gain`` of the hysteresis
blocks and ``nominal_gain`` of the compensators, as in
``ct.input_output_response(loop, t, r, params={"actuator_gain": 1.1})``.
Blocks, loops and their results pickle with plain :mod:`pickle` (so an
executor can run them in other processes): the blocks' update and output
are methods of module-level classes, and, because python-control 0.10's
:class:`control.StateSpace` stores two lambdas and so cannot be pickled,
importing this module registers :mod:`copyreg` reducers that rebuild a
StateSpace from its matrices, timebase and signal names and an
InterconnectedSystem from its attributes (only when python-control's own
pickling fails).

Examples
--------
>>> import numpy as np, control as ct
>>> from hystcomp import PI
>>> model = PI([1.0, 2.0], [0.5, 0.25], p0=1.0)
>>> block = hysteresis_system(model, dt=0.01, name="actuator")
>>> t = np.arange(200) * 0.01
>>> v = 3 * np.sin(2 * np.pi * t)
>>> resp = ct.input_output_response(block, t, v)
>>> bool(np.allclose(resp.outputs, model.simulate(v), rtol=0, atol=1e-12))
True
>>> block.state_labels
['play[0]', 'play[1]']
"""

import copyreg
import pickle

import numpy as np

import control as ct

from ._blocks import CompensatorBlock, HysteresisBlock, SaturatedPID, _check_protocol
from ._validation import as_scalar, check_choice
from .models import HysteresisModel

__all__ = [
    "hysteresis_system", "compensator_system", "mean_gain", "initial_state",
    "piezo_stage", "pid", "discretize", "check_wiring", "interconnect",
    "WiringError", "HysteresisBlock", "CompensatorBlock", "SaturatedPID",
]


def _rebuild_state_space(A, B, C, D, dt, name, inputs, outputs, states, attributes):
    sys = ct.ss(A, B, C, D, dt, name=name, inputs=inputs, outputs=outputs, states=states)
    sys.__dict__.update(attributes)
    return sys


def _reduce_state_space(sys):
    attributes = {k: v for k, v in vars(sys).items() if not callable(v)}
    return _rebuild_state_space, (sys.A, sys.B, sys.C, sys.D, sys.dt, sys.name, sys.input_labels,
                                  sys.output_labels, sys.state_labels, attributes)


class _InterconnectedUpdate:
    """python-control's InterconnectedSystem update/output (``_rhs``/``_out``
    after ``_update_params``), as a picklable object bound to the system."""

    def __init__(self, sys, method):
        self.sys, self.method = sys, method

    def __call__(self, t, x, u, params):
        self.sys._update_params(params)
        return getattr(self.sys, self.method)(t, x, u)


def _rebuild_interconnected(cls, attributes):
    sys = cls.__new__(cls)
    sys.__dict__.update(attributes)
    sys.updfcn = _InterconnectedUpdate(sys, "_rhs")
    sys.outfcn = _InterconnectedUpdate(sys, "_out")
    return sys


def _reduce_interconnected(sys):
    attributes = {k: v for k, v in vars(sys).items() if k not in ("updfcn", "outfcn")}
    return _rebuild_interconnected, (type(sys), attributes)


def _register_state_space_pickling():
    """Register the reducers if python-control's systems do not pickle."""
    try:
        pickle.dumps(ct.ss([[0.0]], [[1.0]], [[1.0]], [[0.0]], 0.1))
    except (AttributeError, pickle.PicklingError, TypeError):
        copyreg.pickle(ct.StateSpace, _reduce_state_space)
    a = ct.nlsys(None, _static_gain_output, inputs="u", outputs="y", name="a", dt=0.1)
    try:
        pickle.dumps(ct.interconnect([a], inplist="u", outlist="y"))
    except (AttributeError, pickle.PicklingError, TypeError):
        copyreg.pickle(ct.InterconnectedSystem, _reduce_interconnected)


def _static_gain_output(t, x, u, params):
    return u


_register_state_space_pickling()


class WiringError(ValueError):
    """A loop is wired wrongly (timebases, algebraic loop, unknown signal).

    Raised by :func:`check_wiring`, :func:`interconnect` and
    :func:`discretize`; a subclass of ``ValueError`` whose message names the
    blocks at fault.

    Examples
    --------
    >>> import control as ct
    >>> a = ct.ss([], [], [], [[1.0]], 0.01, inputs="u", outputs="y", name="a")
    >>> b = ct.ss([], [], [], [[1.0]], 0.02, inputs="y", outputs="z", name="b")
    >>> try:
    ...     check_wiring([a, b], ["u"], ["z"])
    ... except WiringError as err:
    ...     print(err)
    timebase mismatch: ['a'] have dt = 0.01; ['b'] have dt = 0.02; build every block with the same sampling time
    """


def hysteresis_system(model, dt=True, name=None, inputs="v", outputs="w", actuator_gain=1.0):
    """A hysteresis model as a discrete python-control system (a :class:`HysteresisBlock`).

    ``w[k]`` is the model's output for the input ``v[k]`` from the state
    ``x[k]`` (the model's explicit state, e.g. the play positions of eq. 49,
    minus its virgin state), and ``x[k+1]`` is the state after ``v[k]``; so
    ``ct.input_output_response(block, t, v).outputs == model.simulate(v)``
    from python-control's default ``X0 = 0``.

    Parameters
    ----------
    model : HysteresisModel
        Any model with the protocol ``simulate(v, initial_state=None,
        return_state=False)``, ``n_states``, ``default_state()``.  PI, mGPI
        and StopPI with compiled envelopes run their kernel directly.
    dt : True or float
        Sampling time; True inherits the loop's.
    name : str, optional
        Block name (python-control makes one up if None).
    inputs, outputs : str
        Signal names of the actuator input and output.
    actuator_gain : float
        Gain on the output, the default of ``params["actuator_gain"]``
        (sweep it with ``input_output_response(..., params=...)``).

    Returns
    -------
    HysteresisBlock
        A :class:`control.NonlinearIOSystem`.

    Examples
    --------
    >>> from hystcomp import MGPI
    >>> from hystcomp.envelopes import Tanh
    >>> import numpy as np
    >>> m = MGPI.from_density(lambda r: np.exp(-0.1 * r), 0.25 * np.arange(1, 21), p0=1.0,
    ...                       envelope=Tanh(10.0, 0.2))
    >>> sys = hysteresis_system(m, name="actuator")
    >>> sys.nstates, sys.input_labels, sys.output_labels
    (20, ['v'], ['w'])
    >>> sys.model is m, sys.state_labels[:2]
    (True, ['play[0]', 'play[1]'])
    """
    _check_protocol(model, "model")
    return HysteresisBlock(model, actuator_gain=actuator_gain, dt=dt, name=name, inputs=inputs, outputs=outputs)


def mean_gain(model, input_range, n_samples=2001):
    """Mean slope of a hysteresis model over an input range.

    The input sweeps from 0 to the lower end, up to the upper end, down and
    up again (``n_samples`` samples per leg, dense for rate-dependent
    models); the slope of the chord of the last (major) loop branch is
    ``(w(hi) - w(lo)) / (hi - lo)``.

    Parameters
    ----------
    model : object with ``simulate``
        The hysteresis model (any object following the model protocol).
    input_range : (float, float)
        (lo, hi) with lo < hi: the actuator input range of the study.
    n_samples : int
        Samples per leg of the sweep.

    Examples
    --------
    >>> from hystcomp import PI
    >>> round(mean_gain(PI([1.0], [1.0], p0=1.0), (-2.0, 2.0)), 6)  # 2 - 1 (play width) / 2
    1.5
    """
    try:
        lo, hi = float(input_range[0]), float(input_range[1])
    except (TypeError, IndexError, ValueError):
        raise ValueError(f"Parameter input_range is {input_range!r} but should be (lo, hi)") from None
    if not (np.isfinite(lo) and np.isfinite(hi) and lo < hi):
        raise ValueError(f"Parameter input_range is {input_range!r} but should be finite with lo < hi")
    if not callable(getattr(model, "simulate", None)):
        raise TypeError(f"Parameter model is {model!r} but should be a hysteresis model")
    if isinstance(n_samples, (bool, np.bool_)) or not isinstance(n_samples, (int, np.integer)):
        raise TypeError(f"Parameter n_samples is {n_samples!r} but should be an integer")
    if n_samples < 2:
        raise ValueError(f"Parameter n_samples is {n_samples} but should be >= 2")
    n = int(n_samples)
    up = np.linspace(lo, hi, n)
    v = np.concatenate([np.linspace(0.0, lo, n), up[1:], up[::-1][1:], up[1:]])
    w = np.asarray(model.simulate(v))
    return float((w[-1] - w[-n]) / (hi - lo))


def compensator_system(model, method="exact", nominal_gain=None, dt=True, name=None, inputs="u",
                       outputs="v", input_range=None, compensator=None):
    """An inverse compensator as a discrete python-control system (a :class:`CompensatorBlock`).

    ``v[k] = C(k_nom * u[k]; x[k])`` with C the inverse of `model` (exact or
    analytic) and ``k_nom`` the nominal gain: the compensated actuator
    ``model o C`` maps u to ``k_nom * u``.

    Parameters
    ----------
    model : HysteresisModel
        The model to invert (an identified one to study a mismatch).
    method : {"exact", "analytic"}
        ``model.exact_inverse()`` (per-sample solve) or ``model.inverse()``
        (Krejci-Kuhnen for PI, the thesis's eqs. 54-58 for mGPI).
    nominal_gain : None, float or "auto"
        ``k_nom``, the default of ``params["nominal_gain"]``; None means 1.  A bare inverse turns the actuator into a
        unit gain, while the raw actuator has its own mean gain (about 2.5 in
        the demo): at equal controller gains the compensated loop would then
        be slower.  "auto" uses :func:`mean_gain` over `input_range`, so
        the compensated and the raw loop have the same nominal loop gain.
    dt : True or float
        Sampling time; True inherits the loop's.
    name : str, optional
        Block name (python-control makes one up if None).
    inputs, outputs : str
        Signal names (compensator input, actuator command).
    input_range : (float, float), optional
        Actuator input range for ``nominal_gain="auto"`` (required then).
    compensator : object, optional
        A ready compensator (``simulate``, ``n_states``, ``default_state``)
        used instead of building one with `method`.

    Returns
    -------
    CompensatorBlock
        A :class:`control.NonlinearIOSystem` with the read-only attributes
        ``compensator``, ``model``, ``method`` and ``nominal_gain``.

    Targets the model cannot reach are clipped (actuator saturation) without
    a warning per step.

    Examples
    --------
    >>> import numpy as np, control as ct
    >>> from hystcomp import PI
    >>> m = PI([1.0, 2.0], [0.5, 0.25], p0=1.0)
    >>> comp = compensator_system(m, nominal_gain=2.0, dt=0.01)
    >>> u = np.sin(np.linspace(0, 6, 300))
    >>> v = ct.input_output_response(comp, np.arange(300) * 0.01, u).outputs
    >>> bool(np.allclose(m.simulate(v), 2.0 * u, atol=1e-12))
    True
    """
    check_choice(method, "method", ("exact", "analytic"))
    if compensator is None:
        if not isinstance(model, HysteresisModel) and not hasattr(model, "exact_inverse"):
            raise TypeError(f"Parameter model is {model!r}; expected an hystcomp hysteresis model")
        compensator = model.exact_inverse() if method == "exact" else model.inverse()
        method_used = method
    else:
        method_used = "given"
    _check_protocol(compensator, "compensator")
    if nominal_gain is None:
        k = 1.0
    elif isinstance(nominal_gain, str):
        check_choice(nominal_gain, "nominal_gain", ("auto",))
        if input_range is None:
            raise ValueError(
                "Parameter nominal_gain is 'auto' but input_range is None; pass the actuator input "
                "range (lo, hi) over which the mean slope is taken"
            )
        if not callable(getattr(model, "simulate", None)):
            raise TypeError(f"Parameter model is {model!r}; nominal_gain='auto' needs a hysteresis model")
        k = mean_gain(model, input_range)
    else:
        k = as_scalar(nominal_gain, "nominal_gain", positive=True)
    return CompensatorBlock(compensator, nominal_gain=k, model=model, method=method_used, dt=dt, name=name,
                            inputs=inputs, outputs=outputs)


def initial_state(sys):
    """X0 for ``ct.input_output_response``: every hystcomp block in its
    virgin state, every other state 0.

    In the blocks' coordinates the virgin state is 0, so this is all zeros
    except where a model parks its plays at +-inf (an envelope whose range
    does not contain 0); python-control's default ``X0 = 0`` is then right
    too.

    Parameters
    ----------
    sys : control.InputOutputSystem
        A block or an interconnection of blocks (searched recursively, in
        the order of its ``syslist``).

    Returns
    -------
    ndarray, shape (sys.nstates,)

    Examples
    --------
    >>> from hystcomp import PI
    >>> initial_state(hysteresis_system(PI([1.0], [1.0], p0=1.0))).tolist()
    [0.0]
    """
    if not isinstance(sys, ct.InputOutputSystem):
        raise TypeError(f"Parameter sys is {sys!r} but should be a control.InputOutputSystem")
    subs = getattr(sys, "syslist", None)
    if subs is None:
        if isinstance(sys, (HysteresisBlock, CompensatorBlock)):
            return sys.initial_state()
        return np.zeros(sys.nstates)
    if not subs:
        return np.zeros(0)
    return np.concatenate([initial_state(s) for s in subs])


# ----------------------------------------------------------------------------
# plant and controller
# ----------------------------------------------------------------------------
def discretize(sys, dt, name=None):
    """Zero-order-hold discretisation of a continuous LTI system, keeping
    its signal names (and its name unless `name` is given).

    Parameters
    ----------
    sys : control.LTI
        A continuous-time system (a discrete one with the same `dt` is
        returned as it is).
    dt : float
        Sampling time, > 0.
    name : str, optional
        Name of the discrete system; default the name of `sys`.

    Returns
    -------
    control.StateSpace

    Raises
    ------
    WiringError
        If `sys` is already discrete with another sampling time.

    Examples
    --------
    >>> p = discretize(piezo_stage(), 1e-4)
    >>> p.dt, p.input_labels, p.output_labels, p.state_labels, p.name
    (0.0001, ['w'], ['y'], ['position', 'velocity'], 'stage')
    """
    dt = as_scalar(dt, "dt", positive=True)
    if not isinstance(sys, ct.LTI):
        raise TypeError(f"Parameter sys is {type(sys).__name__}; expected a python-control LTI system")
    if sys.isdtime(strict=True):
        if np.isclose(sys.dt, dt, rtol=1e-12, atol=0):
            return sys
        raise WiringError(
            f"System {sys.name!r} is already discrete with dt = {sys.dt}, not {dt}; "
            "build it in continuous time and discretise it once"
        )
    # python-control's zero-order hold (scipy's cont2discrete), signal and
    # state names copied
    return ct.sample_system(ct.ss(sys), dt, method="zoh", name=name or sys.name, copy_names=True)


def piezo_stage(gain=1.0, natural_freq_hz=300.0, damping=0.05, dt=None, name="stage", inputs="w",
                outputs="y"):
    """A piezo positioning stage: ``G(s) = gain wn^2 / (s^2 + 2 zeta wn s + wn^2)``.

    Parameters
    ----------
    gain : float
        DC gain (position per actuator output unit).
    natural_freq_hz : float
        Resonance frequency in Hz (real stages: a few hundred Hz).
    damping : float
        Damping ratio zeta (light: a few percent).
    dt : float, optional
        Sampling time: the stage discretised by zero-order hold; None for
        the continuous system.
    name, inputs, outputs : str
        Block and signal names.

    Returns
    -------
    control.StateSpace
        States: position and velocity.

    Examples
    --------
    >>> g = piezo_stage()
    >>> float(ct.dcgain(g)), g.input_labels, g.output_labels
    (1.0, ['w'], ['y'])
    """
    k = as_scalar(gain, "gain")
    fn = as_scalar(natural_freq_hz, "natural_freq_hz", positive=True)
    z = as_scalar(damping, "damping", nonnegative=True)
    wn = 2 * np.pi * fn
    A = [[0.0, 1.0], [-wn * wn, -2 * z * wn]]
    B = [[0.0], [k * wn * wn]]
    sys = ct.ss(A, B, [[1.0, 0.0]], [[0.0]], inputs=inputs, outputs=outputs, name=name,
                states=["position", "velocity"])
    return sys if dt is None else discretize(sys, dt)


def pid(kp, ki, kd, dt, tau_d=None, output_limits=None, name="pid", inputs="e", outputs="u"):
    """A discrete PID controller with a filtered derivative.

    ``u[k] = kp e[k] + ki (I[k] + dt e[k]) + kd (e[k] - f[k]) / tau_d`` with
    the integral ``I[k+1] = I[k] + dt e[k]`` (backward Euler: the current
    error counts) and the low-pass ``f[k+1] = a f[k] + (1 - a) e[k]``,
    ``a = exp(-dt/tau_d)`` (the zero-order-hold form of
    ``kd s / (tau_d s + 1)``).

    Parameters
    ----------
    kp, ki, kd : float
        Proportional, integral and derivative gains.
    dt : float
        Sampling time.
    tau_d : float, optional
        Derivative filter time constant; default ``10 dt``.
    output_limits : (float, float), optional
        Saturation of u.  The integral then stops when u is saturated and
        the error would drive it further (conditional integration, an
        anti-windup scheme); the controller becomes a NonlinearIOSystem.
    name, inputs, outputs : str
        Block name and signal names (error in, command out).

    Returns
    -------
    control.StateSpace or SaturatedPID
        States ``[I, f]``; a :class:`SaturatedPID` (a
        :class:`control.NonlinearIOSystem`) with `output_limits`.

    Examples
    --------
    >>> c = pid(1.0, 10.0, 0.0, dt=1e-3)
    >>> c.dt, c.nstates, float(c.D[0, 0])
    (0.001, 2, 1.01)
    """
    kp, ki, kd = (as_scalar(x, n) for x, n in ((kp, "kp"), (ki, "ki"), (kd, "kd")))
    dt = as_scalar(dt, "dt", positive=True)
    tau = 10.0 * dt if tau_d is None else as_scalar(tau_d, "tau_d", positive=True)
    a = float(np.exp(-dt / tau))
    if output_limits is None:
        A = np.array([[1.0, 0.0], [0.0, a]])
        B = np.array([[dt], [1.0 - a]])
        C = np.array([[ki, -kd / tau]])
        D = np.array([[kp + ki * dt + kd / tau]])
        return ct.ss(A, B, C, D, dt, inputs=inputs, outputs=outputs, name=name, states=["I", "f"])
    return SaturatedPID(kp, ki, kd, dt, tau, output_limits, name=name, inputs=inputs, outputs=outputs)


# ----------------------------------------------------------------------------
# wiring checks
# ----------------------------------------------------------------------------
def _feedthrough(sys):
    if isinstance(sys, (HysteresisBlock, CompensatorBlock)):
        return True
    if isinstance(sys, SaturatedPID):
        return bool(np.any(sys.D != 0))
    if isinstance(sys, ct.LTI):
        d = ct.ss(sys).D
        return bool(np.any(np.asarray(d) != 0))
    # probe: does the output move with the input at a zero state?
    try:
        x = np.zeros(sys.nstates)
        y0 = np.asarray(sys._out(0.0, x, np.zeros(sys.ninputs)), dtype=float)
        y1 = np.asarray(sys._out(0.0, x, np.full(sys.ninputs, 0.5)), dtype=float)
        return not np.array_equal(y0, y1)
    except Exception:
        return True


def _timebase(sys):
    dt = sys.dt
    if dt is None:
        return None
    if dt is True:
        return True
    return float(dt)


def _signal_base(spec, syslist, kind):
    """The plain signal name of an inplist/outlist entry, or None.

    Accepts python-control's forms ``"sig"``, ``"-sig"``, ``"sys.sig"``,
    ``"-sys.sig"`` and ``"sys.sig[i]"``; a ``"sys.sig"`` whose block does not
    have that signal raises :class:`WiringError`.  Other forms (tuples,
    lists, indices) return None and are left to python-control.
    """
    if not isinstance(spec, str):
        return None
    name = spec.lstrip("-").split("[")[0]
    blocks = {s.name: s for s in syslist}
    if "." in name and name.split(".", 1)[0] in blocks:
        bname, sig = name.split(".", 1)
        blk = blocks[bname]
        labels = blk.input_labels if kind == "input" else blk.output_labels + blk.input_labels
        if sig not in labels:
            raise WiringError(f"{kind} {spec!r}: block {bname!r} has no signal {sig!r}; its "
                              f"{'inputs' if kind == 'input' else 'signals'} are {labels}")
        return sig
    return name


def check_wiring(syslist, inplist, outlist, connections=None):
    """Check a loop before python-control sees it.

    Without `connections`, signals with equal names are connected
    (python-control's ``interconnect`` without ``connections``).  Entries of
    `inplist` and `outlist` may be python-control's ``"sys.sig"`` names.
    Raises :class:`WiringError`
    naming the blocks for: duplicate block names, continuous blocks among
    discrete ones, different sampling times, an input no block drives, an
    unknown name in `inplist` / `outlist`, and an algebraic loop (a cycle of
    blocks with feedthrough, which python-control reports late and vaguely).

    Parameters
    ----------
    syslist : list of control.InputOutputSystem
        The blocks, each with its own name.
    inplist : str or list of str
        External inputs of the loop (signal names; a leading "-" is allowed).
    outlist : str or list of str
        Outputs of the loop (signal names; a leading "-" is allowed).
    connections : list or False, optional
        python-control's explicit connections.  When given, the blocks are
        not connected by name, so the name-based checks (undriven inputs,
        algebraic loops) are left to python-control; block names,
        timebases and the `inplist`/`outlist` names are still checked.

    Raises
    ------
    WiringError
        Naming the blocks and signals at fault.

    Examples
    --------
    >>> import control as ct
    >>> from hystcomp import PI
    >>> act = hysteresis_system(PI([1.0], [1.0], p0=1.0), name="act", inputs="u", outputs="y")
    >>> err = ct.summing_junction(["r", "-y"], "e", name="err")
    >>> ctrl = ct.ss([], [], [], [[2.0]], 0.01, inputs="e", outputs="u", name="ctrl")
    >>> check_wiring([act, err, ctrl], ["r"], ["y"])
    Traceback (most recent call last):
    ...
    hystcomp.iosys.WiringError: algebraic loop: the blocks 'act' -> 'err' -> 'ctrl' form a cycle in which every block has feedthrough (its output depends on its input at the same sample), so no sample can be computed; put a block without feedthrough in the cycle (a discretised plant with D = 0, or a one-sample delay)
    """
    if isinstance(syslist, (str, bytes)) or not hasattr(syslist, "__iter__"):
        raise TypeError(f"Parameter syslist is {syslist!r} but should be a list of control.InputOutputSystem")
    syslist = list(syslist)
    for j, s in enumerate(syslist):
        if not isinstance(s, ct.InputOutputSystem):
            raise TypeError(f"Parameter syslist[{j}] is {s!r} ({type(s).__name__}) but should be a "
                            "control.InputOutputSystem")
    for pname, lst in (("inplist", inplist), ("outlist", outlist)):
        if lst is not None and not isinstance(lst, str) and not hasattr(lst, "__iter__"):
            raise TypeError(f"Parameter {pname} is {lst!r} but should be a signal name or a list of them")
    inplist = [inplist] if isinstance(inplist, str) else list(inplist or [])
    outlist = [outlist] if isinstance(outlist, str) else list(outlist or [])
    names = [s.name for s in syslist]
    dup = sorted({n for n in names if names.count(n) > 1})
    if dup:
        raise WiringError(f"blocks share the names {dup}; give every block its own name")
    # timebases
    cont = [s.name for s in syslist if _timebase(s) == 0.0 and s.nstates > 0]
    disc = [(s.name, _timebase(s)) for s in syslist if _timebase(s) not in (None, True, 0.0)]
    if cont and disc:
        raise WiringError(
            f"timebase mismatch: the blocks {cont} are continuous-time but {[n for n, _ in disc]} are "
            f"discrete (dt = {disc[0][1]}); discretise the continuous ones with "
            f"hystcomp.iosys.discretize(sys, {disc[0][1]}) (zero-order hold)"
        )
    dts = {}
    for n, d in disc:
        dts.setdefault(d, []).append(n)
    if len(dts) > 1:
        desc = "; ".join(f"{v} have dt = {k}" for k, v in dts.items())
        raise WiringError(f"timebase mismatch: {desc}; build every block with the same sampling time")
    if not disc and not cont:
        pass
    # signals
    drivers = {}
    for s in syslist:
        for sig in s.output_labels:
            drivers.setdefault(sig, []).append(s.name)
    known = sorted(set(drivers) | {sig for s in syslist for sig in s.input_labels})
    in_bases = [b for b in (_signal_base(sig, syslist, "input") for sig in inplist) if b is not None]
    out_specs = [(sig, _signal_base(sig, syslist, "output")) for sig in outlist]
    for sig, base in zip(inplist, [_signal_base(sig, syslist, "input") for sig in inplist]):
        if base is None:
            continue
        if not any(base in s.input_labels for s in syslist):
            raise WiringError(
                f"external input {sig!r} is not an input of any block; block inputs are "
                f"{sorted({x for s in syslist for x in s.input_labels})}"
            )
    for sig, base in out_specs:
        if base is None:
            continue
        if base not in drivers and not any(base in s.input_labels for s in syslist):
            raise WiringError(f"output {sig!r} is not a signal of the loop; known signals are {known}")
    if connections is not None:
        return
    for s in syslist:
        for sig in s.input_labels:
            if sig not in drivers and sig not in in_bases:
                raise WiringError(
                    f"input {sig!r} of block {s.name!r} is driven by no block output and is not an "
                    f"external input; block outputs are {sorted(drivers)} (rename a signal or add "
                    f"{sig!r} to inplist)"
                )
    # algebraic loops: cycles among feedthrough blocks
    ft = {s.name: _feedthrough(s) for s in syslist}
    succ = {s.name: [] for s in syslist}
    for s in syslist:
        for sig in s.output_labels:
            for d in syslist:
                if sig in d.input_labels and ft[s.name] and ft[d.name]:
                    succ[s.name].append(d.name)
    state = {}
    stack = []

    def visit(n):
        state[n] = 1
        stack.append(n)
        for m in succ[n]:
            if state.get(m) == 1:
                cyc = stack[stack.index(m):]
                raise WiringError(
                    "algebraic loop: the blocks " + " -> ".join(repr(c) for c in cyc)
                    + " form a cycle in which every block has feedthrough (its output depends on its "
                    "input at the same sample), so no sample can be computed; put a block without "
                    "feedthrough in the cycle (a discretised plant with D = 0, or a one-sample delay)"
                )
            if m not in state:
                visit(m)
        stack.pop()
        state[n] = 2

    for s in syslist:
        if s.name not in state:
            visit(s.name)


def interconnect(syslist, inplist, outlist, name=None, **kwargs):
    """:func:`control.interconnect` of name-connected blocks after
    :func:`check_wiring`.

    Parameters
    ----------
    syslist : list of control.InputOutputSystem
        The blocks; signals with equal names are connected unless
        ``connections=`` is passed (python-control's explicit form).
    inplist, outlist : str or list of str
        External inputs and outputs of the interconnection (signal names,
        or python-control's ``"sys.sig"`` names).
    name : str, optional
        Name of the interconnected system.
    **kwargs
        Passed on to :func:`control.interconnect` (``connections=``,
        ``params=``, ...).

    Returns
    -------
    control.InterconnectedSystem or control.StateSpace
        A StateSpace system when every block is linear (python-control's
        choice).

    Raises
    ------
    WiringError
        From :func:`check_wiring`.

    Examples
    --------
    >>> from hystcomp import PI
    >>> act = hysteresis_system(PI([1.0], [1.0], p0=1.0), name="act")
    >>> stage = piezo_stage(dt=1e-4)
    >>> sys = interconnect([act, stage], inplist=["v"], outlist=["y"], name="open")
    >>> sys.dt, sys.nstates
    (0.0001, 3)
    """
    check_wiring(syslist, inplist, outlist, connections=kwargs.get("connections"))
    return ct.interconnect(list(syslist), inplist=inplist, outlist=outlist, name=name, **kwargs)

"""Closed-loop studies: hysteresis, compensator, plant, PID and feedforward.

Five scenarios, built with :func:`control.interconnect` from the blocks of
:mod:`hystcomp.iosys` (signals: reference r, actuator command v, actuator
output w, stage position y):

========================  ==================================================
``open_loop``             r -> gain -> hysteresis -> plant (thesis fig. 1.2)
``feedforward``           r -> gain -> compensator -> hysteresis -> plant
                          (inverse feedforward, fig. 5.1/5.2)
``feedback``              PID on e = r - y -> hysteresis -> plant
``feedback_compensated``  PID -> compensator -> hysteresis -> plant (fig. 2.9)
``two_dof``               (gain r + PID) -> compensator -> hysteresis -> plant
========================  ==================================================

The feedforward gain is ``1 / (k_nom * G(1))``: the plant's DC gain G(1)
and the nominal gain ``k_nom`` of the compensator (``compensator_system(...,
nominal_gain=...)``, 1 without one), which is also the linear calibration of
the uncompensated open loop.

:func:`compare` runs scenarios on one reference and tabulates the tracking
errors; :func:`simulate_loop` runs a loop in compiled code (the same kernels
as the models), about a thousand times faster than python-control's
per-step simulation, and :func:`plot_comparison` draws the result.

Examples
--------
>>> import numpy as np
>>> from hystcomp import PI
>>> from hystcomp.iosys import piezo_stage, pid, compensator_system
>>> act = PI(0.5 * np.arange(1, 6), 0.2 * np.ones(5), p0=1.0)
>>> dt = 1e-4
>>> loops = build_scenarios(act, piezo_stage(), controller=pid(0.0, 300.0, 0.0, dt),
...                        compensator=compensator_system(act), dt=dt)
>>> sorted(loops)
['feedback', 'feedback_compensated', 'feedforward', 'open_loop', 'two_dof']
>>> t = np.arange(2000) * dt
>>> result = compare(loops, t, 2 * np.sin(2 * np.pi * 5 * t))
>>> bool(result.row("feedforward")["rms"] < result.row("open_loop")["rms"] / 10)
True
"""

import warnings

import numpy as np

import control as ct

from . import _loop_kernels as _lk
from ._validation import as_choices, as_float_array, as_scalar, as_signal, check_choice
from .iosys import (
    CompensatorBlock, SaturatedPID, WiringError, compensator_system, discretize, hysteresis_system,
    initial_state, interconnect, pid,
)
from ._block_specs import _NONE_SPEC, _spec, _ss_arrays
from ._fast_loops import fast_response

__all__ = [
    "SCENARIOS", "Loop", "build_loop", "build_scenarios", "simulate_loop", "compare", "Comparison",
    "loop_width", "plot_comparison", "fast_response",
]

SCENARIOS = ("open_loop", "feedforward", "feedback", "feedback_compensated", "two_dof")

_NEEDS = {
    "open_loop": (False, False),            # (controller, compensator)
    "feedforward": (False, True),
    "feedback": (True, False),
    "feedback_compensated": (True, True),
    "two_dof": (True, True),
}

_LABELS = {
    "open_loop": "open loop",
    "feedforward": "inverse feedforward",
    "feedback": "PID",
    "feedback_compensated": "PID + compensator",
    "two_dof": "feedforward + PID",
}


class Loop:
    """One scenario: the python-control system and its ingredients.

    Made by :func:`build_loop` and :func:`build_scenarios`; every parameter
    is kept as the attribute of the same name.

    Parameters
    ----------
    scenario : str
        One of :data:`SCENARIOS`.
    name : str
        Name of the loop (and of its interconnected system).
    system : control.InterconnectedSystem
        Input: the reference ``r``; outputs: ``y`` (plant output), ``w``
        (actuator output) and ``v`` (actuator input), in this order and
        named, so responses can be indexed by signal name.
    dt : float
        Sampling time of every block.
    hysteresis : HysteresisModel
        The actuator model.
    compensator : hystcomp.iosys.CompensatorBlock or None
        The compensator block (``.compensator``, ``.nominal_gain``).
    controller, plant : python-control systems or None
        Discrete; signals renamed to the loop's.
    feedforward_gain : float
        Gain of the reference path (``1 / (k_nom G(1))`` by default).

    Examples
    --------
    >>> from hystcomp import PI
    >>> from hystcomp.iosys import piezo_stage
    >>> loop = build_loop("open_loop", PI([1.0], [0.5], p0=1.0), piezo_stage(), dt=1e-4)
    >>> loop
    Loop('open_loop', name='open_loop', dt=0.0001)
    >>> loop.system.ninputs, loop.system.noutputs        # r in; y, w, v out
    (1, 3)
    >>> loop.initial_state().tolist()       # play output, stage position and velocity
    [0.0, 0.0, 0.0]
    """

    def __init__(self, scenario, name, system, dt, hysteresis, compensator, controller, plant,
                 feedforward_gain):
        self.scenario = scenario
        self.name = name
        self.system = system
        self.dt = dt
        self.hysteresis = hysteresis
        self.compensator = compensator
        self.controller = controller
        self.plant = plant
        self.feedforward_gain = feedforward_gain

    def initial_state(self):
        """X0 of :attr:`system`: blocks in their virgin states."""
        return initial_state(self.system)

    def simulate(self, timepts=None, inputs=None, initial_state=None, params=None, engine="python-control",
                 **deprecated):
        """Response to a reference, in python-control's argument order:
        ``engine="python-control"`` runs :func:`control.input_output_response`,
        ``"compiled"`` :func:`simulate_loop`.

        Parameters
        ----------
        timepts : array_like, shape (n,)
            Uniform time vector with the loop's step `dt`.
        inputs : array_like, shape (n,)
            Reference samples r[k].  (The old keywords ``t=`` and
            ``reference=`` still work, with a DeprecationWarning.)
        initial_state : array_like, optional
            X0 of :attr:`system`; default the virgin state
            (:meth:`initial_state`).
        params : dict, optional
            python-control's parameters, e.g. ``{"actuator_gain": 1.1}`` or
            ``{"nominal_gain": 2.0}`` for sweeps.
        engine : {"python-control", "compiled"}, optional
            Who simulates; both give the same numbers to rounding, the
            compiled loop about a thousand times faster.

        Returns
        -------
        control.TimeResponseData
            Outputs ``y``, ``w``, ``v``.

        Examples
        --------
        >>> import numpy as np
        >>> from hystcomp import PI
        >>> from hystcomp.iosys import piezo_stage
        >>> loop = build_loop("open_loop", PI([1.0], [0.5], p0=1.0), piezo_stage(), dt=1e-4)
        >>> t = np.arange(40) * 1e-4
        >>> r = np.sin(2 * np.pi * 50 * t)
        >>> a = loop.simulate(t, r).outputs
        >>> b = loop.simulate(t, r, engine="compiled").outputs
        >>> a.shape, bool(np.allclose(a, b, rtol=0, atol=1e-12))
        ((3, 40), True)
        >>> c = loop.simulate(t, r, params={"actuator_gain": 1.2}).outputs   # w scaled by 1.2
        >>> bool(np.allclose(c[1], 1.2 * a[1], rtol=0, atol=1e-12))
        True
        """
        check_choice(engine, "engine", ("python-control", "compiled"))
        t, r = _time_and_reference(self, timepts, inputs, deprecated, "Loop.simulate")
        if engine == "compiled":
            return simulate_loop(self, t, r, initial_state=initial_state, params=params)
        x0 = self.initial_state() if initial_state is None else initial_state
        return ct.input_output_response(self.system, t, r, initial_state=x0, params=params)

    def __repr__(self):
        return f"Loop({self.scenario!r}, name={self.name!r}, dt={self.dt})"


def _is_time(t, n, dt):
    return t.size == n and (n < 2 or np.allclose(np.diff(t), dt, rtol=1e-9, atol=0))


def _time_and_reference(loop, timepts, inputs, deprecated, where):
    """(t, r) from python-control's order ``(timepts, inputs)``, accepting the
    old forms ``(reference)``, ``(reference, t)`` and the keywords ``t=``,
    ``reference=`` with a DeprecationWarning."""
    old = {k: deprecated.pop(k) for k in ("t", "reference") if k in deprecated}
    if deprecated:
        raise TypeError(f"{where}() got unexpected keyword arguments {sorted(deprecated)}")
    msg = (f"{where}: the order is now python-control's (timepts, inputs[, initial_state]); "
           "{what} is deprecated")
    if old:
        if "reference" in old:
            if inputs is not None:
                raise TypeError(f"{where}() got both inputs and the old keyword reference")
            if "t" not in old and timepts is not None:
                old["t"] = timepts
            inputs = old["reference"]
            timepts = old.get("t")
        else:
            timepts = old["t"]
        warnings.warn(msg.format(what="the keywords t= and reference="), DeprecationWarning, stacklevel=3)
    elif inputs is None and timepts is not None:
        warnings.warn(msg.format(what="passing the reference alone"), DeprecationWarning, stacklevel=3)
        inputs, timepts = timepts, None
    if inputs is None:
        raise TypeError(f"{where}() missing the arguments timepts and inputs (the time vector and the "
                        "reference samples)")
    r = as_signal(inputs, "inputs")
    if timepts is None:
        return np.arange(r.size) * loop.dt, r
    t = as_signal(timepts, "timepts")
    if t.size != r.size:
        raise ValueError(f"Parameter timepts has {t.size} samples but inputs has {r.size}")
    if not _is_time(t, t.size, loop.dt) and _is_time(r, r.size, loop.dt):
        # the old order (reference, t): unambiguous since the first is no time vector
        warnings.warn(msg.format(what="the order (reference, t)"), DeprecationWarning, stacklevel=3)
        t, r = r, t
    if t.size > 1 and not _is_time(t, t.size, loop.dt):
        raise ValueError(f"Parameter timepts has steps from {np.diff(t).min()!r} to {np.diff(t).max()!r} "
                         f"but the loop's dt is {loop.dt}")
    return t, r


def _rename_lti(sys, dt, inputs, outputs, name):
    if not isinstance(sys, ct.LTI):
        raise TypeError(f"Parameter {name} is {type(sys).__name__}; expected a python-control LTI system")
    if sys.ninputs != 1 or sys.noutputs != 1:
        raise ValueError(f"Parameter {name} has {sys.ninputs} inputs and {sys.noutputs} outputs; "
                         "expected a single-input single-output system")
    if sys.isctime(strict=True):
        sys = discretize(sys, dt)
    elif sys.isdtime(strict=True) and not np.isclose(sys.dt, dt, rtol=1e-12, atol=0):
        raise WiringError(
            f"timebase mismatch: the {name} {sys.name!r} has dt = {sys.dt} but the loop runs at dt = {dt}; "
            f"build it at dt = {dt} (continuous systems are discretised automatically)"
        )
    s = ct.ss(sys)
    return ct.ss(s.A, s.B, s.C, s.D, dt, inputs=inputs, outputs=outputs, name=name, states=s.state_labels)


def _controller_block(controller, dt, outputs):
    if isinstance(controller, SaturatedPID):
        if not np.isclose(controller.dt, dt, rtol=1e-12, atol=0):
            raise WiringError(
                f"timebase mismatch: the controller {controller.name!r} has dt = {controller.dt} but the "
                f"loop runs at dt = {dt}; build it with pid(..., dt={dt})"
            )
        return pid(controller.kp, controller.ki, controller.kd, controller.dt, tau_d=controller.tau_d,
                   output_limits=controller.output_limits, name="controller", inputs="e", outputs=outputs)
    if isinstance(controller, ct.LTI):
        return _rename_lti(controller, dt, "e", outputs, "controller")
    raise TypeError(
        f"Parameter controller is {type(controller).__name__}; expected hystcomp.iosys.pid(...) or a "
        "python-control LTI system"
    )


def _compensator_block(compensator):
    if compensator is None:
        return None
    if isinstance(compensator, CompensatorBlock):
        return CompensatorBlock(compensator.compensator, nominal_gain=compensator.nominal_gain,
                                model=compensator.model, method=compensator.method, name="compensator")
    if hasattr(compensator, "simulate"):
        return compensator_system(None, compensator=compensator, name="compensator")
    raise TypeError(
        f"Parameter compensator is {compensator!r}; expected hystcomp.iosys.compensator_system(...) "
        "or a compensator object (simulate, n_states, default_state)"
    )


def _loop_dt(dt, plant, controller):
    if dt is not None:
        return as_scalar(dt, "dt", positive=True)
    for sys in (controller, plant):
        if sys is not None and isinstance(sys.dt, float) and sys.dt > 0:
            return float(sys.dt)
    raise ValueError("Parameter dt is None and neither the controller nor the plant is discrete; "
                     "pass the loop's sampling time dt")


def build_loop(scenario, hysteresis, plant, controller=None, compensator=None, dt=None,
               feedforward_gain="auto", name=None):
    """Build one scenario with :func:`control.interconnect`.

    Parameters
    ----------
    scenario : str
        One of :data:`SCENARIOS`.
    hysteresis : HysteresisModel
        The actuator (any model with the simulate protocol).
    plant : python-control LTI system
        SISO; continuous ones are discretised (zero-order hold) at `dt`.
    controller : LTI system or :func:`hystcomp.iosys.pid`, optional
        Needed by the feedback scenarios.
    compensator : compensator_system block or compensator object, optional
        Needed by the compensated scenarios (an inverse of an identified
        model studies a mismatch).
    dt : float, optional
        Sampling time; default the controller's or the plant's.
    feedforward_gain : "auto" or float
        Gain of the reference path; "auto" is ``1 / (k_nom G(1))``.
    name : str, optional
        Default the scenario name.

    Returns
    -------
    Loop

    Raises
    ------
    ValueError
        If the scenario needs a controller or a compensator that is missing.
    WiringError
        For mismatched sampling times or a plant with feedthrough in a
        feedback scenario (an algebraic loop).

    Examples
    --------
    >>> from hystcomp import PI
    >>> from hystcomp.iosys import compensator_system, piezo_stage, pid
    >>> act = PI([1.0, 2.0], [0.5, 0.25], p0=1.0)
    >>> loop = build_loop("feedback_compensated", act, piezo_stage(),
    ...                   controller=pid(0.0, 300.0, 0.0, dt=1e-4),
    ...                   compensator=compensator_system(act), dt=1e-4)
    >>> loop.scenario, loop.system.nstates     # plays 2, stage 2, PID 2, inverse 3
    ('feedback_compensated', 9)
    """
    check_choice(scenario, "scenario", SCENARIOS)
    need_ctrl, need_comp = _NEEDS[scenario]
    if need_ctrl and controller is None:
        raise ValueError(f"Scenario {scenario!r} needs a controller; pass controller=pid(...)")
    if need_comp and compensator is None:
        raise ValueError(f"Scenario {scenario!r} needs a compensator; pass compensator=compensator_system(model)")
    if not hasattr(hysteresis, "simulate"):
        raise TypeError(f"Parameter hysteresis is {hysteresis!r}; expected an hystcomp hysteresis model")
    if controller is not None and not isinstance(controller, (SaturatedPID, ct.LTI)):
        # checked even where the scenario has no controller: a wrong object is a mistake, not an option
        raise TypeError(f"Parameter controller is {controller!r} ({type(controller).__name__}); expected "
                        "hystcomp.iosys.pid(...) or a python-control LTI system")
    if compensator is not None and not (isinstance(compensator, CompensatorBlock)
                                        or callable(getattr(compensator, "simulate", None))):
        raise TypeError(f"Parameter compensator is {compensator!r}; expected "
                        "hystcomp.iosys.compensator_system(...) or a compensator object (simulate)")
    dt = _loop_dt(dt, plant, controller)
    stage = _rename_lti(plant, dt, "w", "y", "plant")
    if np.any(stage.D != 0) and need_ctrl:
        raise WiringError(
            "algebraic loop: the plant has feedthrough (D != 0), and with the PID, the compensator and "
            "the hysteresis every block of the feedback cycle answers at the same sample; use a strictly "
            "proper plant (a zero-order-hold discretisation of a continuous plant has D = 0)"
        )
    comp = _compensator_block(compensator)
    k_nom = comp.nominal_gain if comp is not None else 1.0
    if isinstance(feedforward_gain, str):
        check_choice(feedforward_gain, "feedforward_gain", ("auto",))
        g = float(np.real(ct.dcgain(stage)))
        ff = 1.0 / (k_nom * g)
    else:
        ff = as_scalar(feedforward_gain, "feedforward_gain")
    act = hysteresis_system(hysteresis, name="actuator", inputs="v", outputs="w")
    blocks = [act, stage]
    ctrl = None
    if scenario == "open_loop":
        blocks.append(ct.ss([], [], [], [[ff]], dt, inputs="r", outputs="v", name="prefilter"))
    elif scenario == "feedforward":
        blocks += [ct.ss([], [], [], [[ff]], dt, inputs="r", outputs="u", name="prefilter"), comp]
    elif scenario == "feedback":
        ctrl = _controller_block(controller, dt, "v")
        blocks += [ct.summing_junction(["r", "-y"], "e", name="error"), ctrl]
    elif scenario == "feedback_compensated":
        ctrl = _controller_block(controller, dt, "u")
        blocks += [ct.summing_junction(["r", "-y"], "e", name="error"), ctrl, comp]
    else:
        ctrl = _controller_block(controller, dt, "uc")
        blocks += [ct.ss([], [], [], [[ff]], dt, inputs="r", outputs="uff", name="prefilter"),
                   ct.summing_junction(["r", "-y"], "e", name="error"), ctrl,
                   ct.summing_junction(["uff", "uc"], "u", name="sum"), comp]
    name = name or scenario
    system = interconnect(blocks, inplist=["r"], outlist=["y", "w", "v"], name=name,
                          inputs=["r"], outputs=["y", "w", "v"])
    return Loop(scenario, name, system, dt, hysteresis, comp if _NEEDS[scenario][1] else None, ctrl, stage, ff)


def build_scenarios(hysteresis, plant, controller=None, compensator=None, dt=None,
                    feedforward_gain="auto", scenarios=None):
    """Every scenario the given blocks allow (or those named in `scenarios`).

    Parameters
    ----------
    hysteresis : HysteresisModel
        The actuator (any model with the simulate protocol).
    plant : python-control LTI system
        SISO; continuous ones are discretised (zero-order hold) at `dt`.
    controller : LTI system or :func:`hystcomp.iosys.pid`, optional
        Enables the feedback scenarios.
    compensator : compensator_system block or compensator object, optional
        Enables the compensated scenarios.
    dt : float, optional
        Sampling time; default the controller's or the plant's.
    feedforward_gain : "auto" or float
        Gain of the reference path; "auto" is ``1 / (k_nom G(1))``.
    scenarios : iterable of str, optional
        Scenarios to build (each must have its blocks); default every
        scenario the given blocks allow.

    Returns
    -------
    dict
        scenario name -> :class:`Loop`, in the order of :data:`SCENARIOS`.

    See Also
    --------
    build_loop

    Examples
    --------
    >>> from hystcomp import PI
    >>> from hystcomp.iosys import compensator_system, piezo_stage
    >>> act = PI([1.0], [0.5], p0=1.0)
    >>> loops = build_scenarios(act, piezo_stage(), compensator=compensator_system(act), dt=1e-4)
    >>> list(loops)                            # no controller: no feedback scenarios
    ['open_loop', 'feedforward']
    """
    names = as_choices(scenarios, "scenarios", SCENARIOS)
    out = {}
    for s in names:
        need_ctrl, need_comp = _NEEDS[s]
        if scenarios is None and ((need_ctrl and controller is None) or (need_comp and compensator is None)):
            continue
        out[s] = build_loop(s, hysteresis, plant, controller, compensator, dt, feedforward_gain)
    return out


# ----------------------------------------------------------------------------
# compiled loops
# ----------------------------------------------------------------------------
def compiled_support(loop):
    """None if :func:`simulate_loop` can run `loop`, else the reason."""
    if _spec(loop.hysteresis, "hysteresis") is None:
        return (f"the hysteresis model {loop.hysteresis!r} has no compiled kernel (PI, MGPI and StopPI with "
                "built-in envelopes have one)")
    if loop.compensator is not None and _spec(loop.compensator.compensator, "compensator") is None:
        return (f"the compensator {loop.compensator.compensator!r} has no compiled kernel (exact inverses "
                "and PI / MGPI / StopPI models have one)")
    return None


def simulate_loop(loop, timepts=None, inputs=None, initial_state=None, params=None, **deprecated):
    """Run a loop in compiled code: the same numbers as
    ``loop.simulate(timepts, inputs)`` (python-control) to rounding.

    The hysteresis and compensator steps call the kernels of the models
    (:mod:`hystcomp._kernels`) one sample at a time, the plant and the
    controller are discrete state-space recursions; all in one numba loop.
    With `initial_state` or `params` the loop runs through
    :func:`fast_response` (also compiled).

    Parameters
    ----------
    loop : Loop
        The loop to run.
    timepts : array_like, shape (n,)
        Time vector, uniformly spaced by the loop's dt (python-control's
        order: ``timepts, inputs``).  The old calls ``simulate_loop(loop,
        reference)``, ``simulate_loop(loop, reference, t)`` and the keywords
        ``reference=``, ``t=`` still work with a DeprecationWarning.
    inputs : array_like, shape (n,)
        Reference samples r[k] at timepts[k].
    initial_state : array_like, optional
        X0 of ``loop.system``; default the virgin state.
    params : dict, optional
        python-control's parameters (``actuator_gain``, ``nominal_gain``).

    Returns
    -------
    control.TimeResponseData
        Outputs ``y``, ``w``, ``v`` (as python-control returns them).

    Raises
    ------
    NotImplementedError
        For blocks without a compiled kernel (e.g. a GPI actuator or a
        :class:`~hystcomp.inverses.GPIInverse`): there is no Python
        fallback here; run ``loop.simulate(timepts, inputs)`` (python-control).

    Examples
    --------
    >>> import numpy as np
    >>> from hystcomp import PI
    >>> from hystcomp.iosys import compensator_system, piezo_stage
    >>> act = PI([1.0, 2.0], [0.5, 0.25], p0=1.0)
    >>> loop = build_loop("feedforward", act, piezo_stage(), compensator=compensator_system(act), dt=1e-4)
    >>> t = np.arange(5000) * 1e-4
    >>> r = 2 * np.sin(2 * np.pi * 20 * t)
    >>> resp = simulate_loop(loop, t, r)
    >>> resp.output_labels, resp.outputs.shape
    (['y', 'w', 'v'], (3, 5000))
    >>> w = resp.outputs[1]                    # the compensated actuator follows r exactly
    >>> bool(np.max(np.abs(w - r)) < 1e-9)
    True
    """
    if not isinstance(loop, Loop):
        raise TypeError(f"Parameter loop is {type(loop).__name__}; expected an hystcomp.loops.Loop")
    t, r = _time_and_reference(loop, timepts, inputs, deprecated, "simulate_loop")
    why = compiled_support(loop)
    if why is not None:
        raise NotImplementedError(f"simulate_loop cannot compile loop {loop.name!r}: {why}; run "
                                  "loop.simulate(timepts, inputs) (python-control) instead")
    if initial_state is not None:
        x0 = as_float_array(initial_state, "initial_state")
        if not np.all(np.isfinite(x0)):
            raise ValueError(f"Parameter initial_state is {initial_state!r}; expected finite numbers")
    if initial_state is not None or params:
        resp = fast_response(loop.system, t, r, loop.initial_state() if initial_state is None else initial_state,
                             params=params)
        return ct.TimeResponseData(t, resp.outputs, resp.states, r, output_labels=["y", "w", "v"],
                                   state_labels=resp.state_labels, input_labels=["r"], sysname=loop.name,
                                   issiso=False, title=f"Compiled loop {loop.name}")
    need_ctrl, need_comp = _NEEDS[loop.scenario]
    h = _spec(loop.hysteresis, "hysteresis")
    c = _spec(loop.compensator.compensator, "compensator") if need_comp else _NONE_SPEC
    kcomp = float(loop.compensator.nominal_gain) if need_comp else 1.0
    Ap, Bp, Cp, Dp = _ss_arrays(loop.plant)
    xp = np.zeros(Ap.shape[0])
    limited, ulo, uhi, pid_dt = False, 0.0, 0.0, 0.0
    if need_ctrl:
        if isinstance(loop.controller, SaturatedPID):
            Ac, Bc, Cc, Dc = loop.controller.A, loop.controller.B, loop.controller.C, loop.controller.D
            limited = True
            ulo, uhi = loop.controller.output_limits
            pid_dt = loop.controller.dt
        else:
            Ac, Bc, Cc, Dc = _ss_arrays(loop.controller)
    else:
        Ac, Bc, Cc, Dc = np.zeros((1, 1)), np.zeros((1, 1)), np.zeros((1, 1)), np.zeros((1, 1))
    xc = np.zeros(Ac.shape[0])
    use_ff = loop.scenario in ("open_loop", "feedforward", "two_dof")
    n = r.size
    y, w, v = np.empty(n), np.empty(n), np.empty(n)
    info_arr = np.zeros(1, dtype=np.int64)
    _lk.loop_kernel(h, c)(r, float(loop.feedforward_gain), use_ff, need_ctrl, need_comp, kcomp,
                          Ap, Bp, Cp, Dp, xp,
                          np.ascontiguousarray(Ac, dtype=np.float64), np.ascontiguousarray(Bc, dtype=np.float64),
                          np.ascontiguousarray(Cc, dtype=np.float64), np.ascontiguousarray(Dc, dtype=np.float64),
                          xc, limited, float(ulo), float(uhi), float(pid_dt),
                          *h[:17], *c[:17], y, w, v, info_arr)
    return ct.TimeResponseData(t, np.vstack([y, w, v]), None, r, output_labels=["y", "w", "v"],
                               input_labels=["r"], sysname=loop.name, issiso=False,
                               title=f"Compiled loop {loop.name}")


# the comparison lives in its own module (imported last: it imports from this one)
from ._comparison import Comparison, compare, loop_width, plot_comparison  # noqa: E402,F401
from ._doctest_home import method_examples  # noqa: E402

# Comparison's methods live in _comparison: name their examples here so that doctest runs them
__test__ = method_examples(Comparison)

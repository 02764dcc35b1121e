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
>>> result = compare(loops, 2 * np.sin(2 * np.pi * 5 * t), t)
>>> bool(result.row("feedforward")["rms"] < result.row("open_loop")["rms"] / 10)
True
"""

import csv
import sys
import time
from concurrent.futures import as_completed

import numpy as np

import control as ct

from . import _loop_kernels as _lk
from ._validation import as_scalar, as_signal, check_choice
from .iosys import (
    WiringError, _feedthrough, compensator_system, discretize, hysteresis_system, initial_state,
    interconnect, pid,
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
    compensator : control.NonlinearIOSystem or None
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

    def simulate(self, t, reference, engine="python-control"):
        """Response to a reference: ``engine="python-control"`` runs
        :func:`control.input_output_response`, ``"compiled"``
        :func:`simulate_loop`.

        Parameters
        ----------
        t : array_like, shape (n,)
            Uniform time vector with the loop's step `dt`.
        reference : array_like, shape (n,)
            Reference samples r[k].
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
        """
        check_choice(engine, "engine", ("python-control", "compiled"))
        if engine == "compiled":
            return simulate_loop(self, reference, t)
        t = as_signal(t, "t")
        r = as_signal(reference, "reference")
        return ct.input_output_response(self.system, t, r, X0=self.initial_state())

    def __repr__(self):
        return f"Loop({self.scenario!r}, name={self.name!r}, dt={self.dt})"


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
    return ct.ss(s.A, s.B, s.C, s.D, dt, inputs=inputs, outputs=outputs, name=name)


def _controller_block(controller, dt, outputs):
    info = getattr(controller, "_hystcomp", None)
    if info is not None and info.get("kind") == "pid":
        if not np.isclose(info["dt"], dt, rtol=1e-12, atol=0):
            raise WiringError(
                f"timebase mismatch: the controller {controller.name!r} has dt = {info['dt']} but the "
                f"loop runs at dt = {dt}; build it with pid(..., dt={dt})"
            )
        return pid(info["kp"], info["ki"], info["kd"], info["dt"], tau_d=info["tau_d"],
                   output_limits=info["limits"], name="controller", inputs="e", outputs=outputs)
    if isinstance(controller, ct.LTI):
        return _rename_lti(controller, dt, "e", outputs, "controller")
    raise TypeError(
        f"Parameter controller is {type(controller).__name__}; expected hystcomp.iosys.pid(...) or a "
        "python-control LTI system"
    )


def _compensator_block(compensator):
    if compensator is None:
        return None
    if isinstance(compensator, ct.NonlinearIOSystem) and hasattr(compensator, "compensator"):
        return compensator_system(None, compensator=compensator.compensator,
                                  nominal_gain=compensator.nominal_gain, name="compensator")
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
    names = SCENARIOS if scenarios is None else list(scenarios)
    out = {}
    for s in names:
        check_choice(s, "scenarios", SCENARIOS)
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


def simulate_loop(loop, reference, t=None):
    """Run a loop in compiled code: the same numbers as
    ``loop.simulate(t, reference)`` (python-control) to rounding.

    The hysteresis and compensator steps call the kernels of the models
    (:mod:`hystcomp._kernels`) one sample at a time, the plant and the
    controller are discrete state-space recursions; all in one numba loop.

    Parameters
    ----------
    loop : Loop
        The loop to run.
    reference : array_like, shape (n,)
        Reference samples r[k] at t[k] = t0 + k dt.
    t : array_like, optional
        Time vector (for the result; its step must be the loop's dt).

    Returns
    -------
    control.TimeResponseData
        Outputs ``y``, ``w``, ``v`` (as python-control returns them).

    Raises
    ------
    NotImplementedError
        For blocks without a compiled kernel (e.g. a GPI actuator or a
        :class:`~hystcomp.inverses.GPIInverse`): there is no Python
        fallback here; run ``loop.simulate(t, reference)`` (python-control).

    Examples
    --------
    >>> import numpy as np
    >>> from hystcomp import PI
    >>> from hystcomp.iosys import compensator_system, piezo_stage
    >>> act = PI([1.0, 2.0], [0.5, 0.25], p0=1.0)
    >>> loop = build_loop("feedforward", act, piezo_stage(), compensator=compensator_system(act), dt=1e-4)
    >>> r = 2 * np.sin(2 * np.pi * 20 * np.arange(5000) * 1e-4)
    >>> resp = simulate_loop(loop, r)
    >>> resp.output_labels, resp.outputs.shape
    (['y', 'w', 'v'], (3, 5000))
    >>> w = resp.outputs[1]                    # the compensated actuator follows r exactly
    >>> bool(np.max(np.abs(w - r)) < 1e-9)
    True
    """
    if not isinstance(loop, Loop):
        raise TypeError(f"Parameter loop is {type(loop).__name__}; expected an hystcomp.loops.Loop")
    r = as_signal(reference, "reference")
    if t is None:
        t = np.arange(r.size) * loop.dt
    else:
        t = as_signal(t, "t")
        if t.size != r.size:
            raise ValueError(f"Parameter t has {t.size} samples but reference has {r.size}")
        if t.size > 1 and not np.allclose(np.diff(t), loop.dt, rtol=1e-9, atol=0):
            raise ValueError(f"Parameter t has steps {np.diff(t)[:1]} but the loop's dt is {loop.dt}")
    why = compiled_support(loop)
    if why is not None:
        raise NotImplementedError(f"simulate_loop cannot compile loop {loop.name!r}: {why}; run "
                                  "loop.simulate(t, reference) (python-control) instead")
    need_ctrl, need_comp = _NEEDS[loop.scenario]
    h = _spec(loop.hysteresis, "hysteresis")
    c = _spec(loop.compensator.compensator, "compensator") if need_comp else _NONE_SPEC
    kcomp = float(loop.compensator.nominal_gain) if need_comp else 1.0
    Ap, Bp, Cp, Dp = _ss_arrays(loop.plant)
    xp = np.zeros(Ap.shape[0])
    limited, ulo, uhi, pid_dt = False, 0.0, 0.0, 0.0
    if need_ctrl:
        info = getattr(loop.controller, "_hystcomp", None)
        if info is not None and info.get("limits") is not None:
            Ac, Bc, Cc, Dc = info["A"], info["B"], info["C"], info["D"]
            limited = True
            ulo, uhi = info["limits"]
            pid_dt = info["dt"]
        else:
            Ac, Bc, Cc, Dc = _ss_arrays(loop.controller)
    else:
        Ac, Bc, Cc, Dc = np.zeros((1, 1)), np.zeros((1, 1)), np.zeros((1, 1)), np.zeros((1, 1))
    xc = np.zeros(Ac.shape[0])
    use_ff = loop.scenario in ("open_loop", "feedforward", "two_dof")
    n = r.size
    y, w, v = np.empty(n), np.empty(n), np.empty(n)
    info_arr = np.zeros(1, dtype=np.int64)
    _lk.run_loop(r, float(loop.feedforward_gain), use_ff, need_ctrl, need_comp, kcomp,
                 Ap, Bp, Cp, Dp, xp,
                 np.ascontiguousarray(Ac, dtype=np.float64), np.ascontiguousarray(Bc, dtype=np.float64),
                 np.ascontiguousarray(Cc, dtype=np.float64), np.ascontiguousarray(Dc, dtype=np.float64),
                 xc, limited, float(ulo), float(uhi), float(pid_dt),
                 *h[:16], *c[:16], y, w, v, info_arr)
    return ct.TimeResponseData(t, np.vstack([y, w, v]), None, r, output_labels=["y", "w", "v"],
                               input_labels=["r"], sysname=loop.name, issiso=False,
                               title=f"Compiled loop {loop.name}")


# ----------------------------------------------------------------------------
# comparison
# ----------------------------------------------------------------------------
def loop_width(reference, output, n_bins=100):
    """Width of the output-vs-reference loop.

    The largest spread of the tracking error ``y - r`` among samples whose
    reference values fall in the same bin (`n_bins` bins over the
    reference's span): 0 for perfect tracking, the vertical width of the
    hysteresis loop for an uncompensated actuator (a pure lag also opens
    the loop).

    Parameters
    ----------
    reference : array_like, shape (n,)
        Reference samples r.
    output : array_like, shape (n,)
        Output samples y.
    n_bins : int, optional
        Number of bins over the reference's span (default 100).

    Returns
    -------
    float
        The loop width, in output units.

    Examples
    --------
    >>> import numpy as np
    >>> r = np.sin(np.linspace(0, 4 * np.pi, 4001))
    >>> round(loop_width(r, r + 0.1 * np.sign(np.gradient(r))), 6)
    0.2
    """
    r = as_signal(reference, "reference")
    e = as_signal(output, "output") - r
    span = r.max() - r.min()
    if span == 0:
        return float(e.max() - e.min())
    idx = np.minimum(((r - r.min()) / span * n_bins).astype(np.int64), n_bins - 1)
    hi = np.full(n_bins, -np.inf)
    lo = np.full(n_bins, np.inf)
    np.maximum.at(hi, idx, e)
    np.minimum.at(lo, idx, e)
    ok = np.isfinite(hi)
    return float(np.max(hi[ok] - lo[ok]))


_FIELDS = ("scenario", "label", "engine", "rms", "max", "rms_percent", "max_percent", "loop_width",
           "loop_width_percent", "seconds")


class Comparison:
    """Result of :func:`compare`.

    Printing it shows the table; every parameter is kept as the attribute
    of the same name.

    Parameters
    ----------
    rows : list of dict
        One per scenario: ``scenario``, ``label``, ``engine``, ``rms``,
        ``max`` (tracking error y - r), ``rms_percent``, ``max_percent`` (of
        the reference span), ``loop_width`` (:func:`loop_width`),
        ``loop_width_percent``, ``seconds`` (simulation wall time).
    responses : dict
        scenario name -> :class:`control.TimeResponseData`.
    reference, t : ndarray
        The reference and its time vector.

    Examples
    --------
    >>> import numpy as np
    >>> from hystcomp import PI
    >>> from hystcomp.iosys import piezo_stage
    >>> loop = build_loop("open_loop", PI([1.0], [0.5], p0=1.0), piezo_stage(), dt=1e-4)
    >>> t = np.arange(2000) * 1e-4
    >>> result = compare([loop], 2 * np.sin(2 * np.pi * 5 * t), t)
    >>> isinstance(result, Comparison), [row["scenario"] for row in result.rows]
    (True, ['open_loop'])
    >>> print(str(result).splitlines()[0])
    scenario               engine                RMS       max    RMS %    max %     width  width %
    """

    def __init__(self, rows, responses, reference, t):
        self.rows = rows
        self.responses = responses
        self.reference = reference
        self.t = t

    def row(self, name):
        """The table row of one scenario.

        Parameters
        ----------
        name : str
            Scenario (loop) name.

        Returns
        -------
        dict
            See :class:`Comparison`'s `rows`.

        Raises
        ------
        KeyError
            If no row has that name (the message lists the names).

        Examples
        --------
        >>> c = Comparison([{"scenario": "open_loop", "rms": 0.5}], {}, None, None)
        >>> c.row("open_loop")["rms"]
        0.5
        """
        for row in self.rows:
            if row["scenario"] == name:
                return row
        raise KeyError(f"no scenario {name!r}; have {[r['scenario'] for r in self.rows]}")

    def __str__(self):
        head = (f"{'scenario':22s} {'engine':15s} {'RMS':>9s} {'max':>9s} {'RMS %':>8s} {'max %':>8s} "
                f"{'width':>9s} {'width %':>8s}")
        lines = [head, "-" * len(head)]
        for row in self.rows:
            lines.append(
                f"{row['scenario']:22s} {row['engine']:15s} {row['rms']:9.4g} {row['max']:9.4g} "
                f"{row['rms_percent']:8.3g} {row['max_percent']:8.3g} {row['loop_width']:9.4g} "
                f"{row['loop_width_percent']:8.3g}"
            )
        return "\n".join(lines)

    def to_csv(self, path, extra=None):
        """Write the table as CSV.

        Parameters
        ----------
        path : str or path-like
            The CSV file to write (overwritten).
        extra : dict, optional
            Constant columns put before the table's (e.g. the model's name).

        Examples
        --------
        >>> import os, tempfile
        >>> row = dict(scenario="open_loop", label="open loop", engine="compiled", rms=0.1,
        ...            max=0.2, rms_percent=2.5, max_percent=5.0, loop_width=0.3,
        ...            loop_width_percent=7.5, seconds=0.01)
        >>> path = os.path.join(tempfile.mkdtemp(), "loops.csv")
        >>> Comparison([row], {}, None, None).to_csv(path, extra={"model": "PI"})
        >>> print(open(path).read().splitlines()[1])
        PI,open_loop,open loop,compiled,0.1,0.2,2.5,5.0,0.3,7.5,0.01
        """
        extra = dict(extra or {})
        with open(path, "w", newline="") as fh:
            writer = csv.DictWriter(fh, fieldnames=list(extra) + list(_FIELDS))
            writer.writeheader()
            for row in self.rows:
                writer.writerow({**extra, **{k: row[k] for k in _FIELDS}})


def _run_scenario(loop, t, r, engine, span):
    """One row of :func:`compare` and its response (module level, so that
    an executor can run it in another process)."""
    eng = engine
    if eng == "auto":
        eng = "compiled" if compiled_support(loop) is None else "python-control"
    t0 = time.perf_counter()
    resp = loop.simulate(t, r, engine=eng)
    secs = time.perf_counter() - t0
    y = np.asarray(resp.outputs)[0]
    e = y - r
    rms = float(np.sqrt(np.mean(e * e)))
    mx = float(np.max(np.abs(e)))
    width = loop_width(r, y)
    row = dict(scenario=loop.name, label=_LABELS.get(loop.scenario, loop.scenario), engine=eng,
               rms=rms, max=mx, rms_percent=100 * rms / span, max_percent=100 * mx / span,
               loop_width=width, loop_width_percent=100 * width / span, seconds=secs)
    return row, resp


def compare(scenarios, reference, t, engine="auto", progress=None, executor=None):
    """Run scenarios on one reference and tabulate their tracking.

    Parameters
    ----------
    scenarios : dict of Loop, or iterable of Loop
        The loops to run (a dict from :func:`build_scenarios`).
    reference : array_like, shape (n,)
        Reference samples r.
    t : array_like, shape (n,)
        Uniform time vector with the loops' step.
    engine : {"auto", "compiled", "python-control"}
        "auto": :func:`simulate_loop` where the blocks have compiled
        kernels, python-control's simulation otherwise.
    progress : callable, optional
        Called as ``progress(done, total, name)`` after each scenario.
    executor : concurrent.futures.Executor, optional
        Runs the scenarios in parallel (a ``ProcessPoolExecutor``, or
        ``distributed.Client(...).get_executor()`` for dask); None runs them
        one after the other.  The loops and results pickle, and the rows are
        identical either way (in the scenarios' order).

    Returns
    -------
    Comparison
        Table rows and each scenario's :class:`control.TimeResponseData`.

    Examples
    --------
    >>> import numpy as np
    >>> from hystcomp import PI
    >>> from hystcomp.iosys import compensator_system, piezo_stage
    >>> act = PI([1.0, 2.0], [0.5, 0.25], p0=1.0)
    >>> loops = build_scenarios(act, piezo_stage(), compensator=compensator_system(act), dt=1e-4)
    >>> t = np.arange(2000) * 1e-4
    >>> result = compare(loops, 2 * np.sin(2 * np.pi * 5 * t), t)
    >>> [row["engine"] for row in result.rows]
    ['compiled', 'compiled']
    >>> bool(result.row("feedforward")["loop_width"] < result.row("open_loop")["loop_width"] / 10)
    True
    """
    check_choice(engine, "engine", ("auto", "compiled", "python-control"))
    if isinstance(scenarios, (str, bytes)) or not hasattr(scenarios, "__iter__"):
        raise TypeError(f"Parameter scenarios is {scenarios!r} but should be a dict or list of Loop")
    loops = list(scenarios.values()) if isinstance(scenarios, dict) else list(scenarios)
    keys = list(scenarios) if isinstance(scenarios, dict) else range(len(loops))
    for key, loop in zip(keys, loops):
        if not isinstance(loop, Loop):
            raise TypeError(f"Parameter scenarios[{key!r}] is {loop!r} ({type(loop).__name__}) "
                            "but should be a Loop (see build_scenarios)")
    r = as_signal(reference, "reference")
    t = as_signal(t, "t")
    if t.size != r.size:
        raise ValueError(f"Parameter t has {t.size} samples but reference has {r.size}")
    span = float(r.max() - r.min()) or 1.0
    if executor is None:
        results = []
        for j, loop in enumerate(loops):
            results.append(_run_scenario(loop, t, r, engine, span))
            if progress is not None:
                progress(j + 1, len(loops), loop.name)
    else:
        if not hasattr(executor, "submit"):
            raise TypeError(f"Parameter executor is {executor!r}; expected a concurrent.futures.Executor "
                            "(an object with submit()) or None")
        futures = [executor.submit(_run_scenario, loop, t, r, engine, span) for loop in loops]
        index = {f: j for j, f in enumerate(futures)}
        done = 0
        for f in as_completed(futures):
            done += 1
            if progress is not None:
                progress(done, len(loops), loops[index[f]].name)
        results = [f.result() for f in futures]
    rows = [row for row, _ in results]
    responses = {loop.name: resp for loop, (_, resp) in zip(loops, results)}
    return Comparison(rows, responses, r, t)


def plot_comparison(comparison, title=None, scenarios=None, time_window=None):
    """Tracking, tracking error and y-vs-r loops of a :class:`Comparison`.

    Parameters
    ----------
    comparison : Comparison
        The result of :func:`compare`.
    title : str, optional
        Figure title.
    scenarios : iterable of str, optional
        Scenarios to draw, in this order; default every row.
    time_window : (float, float), optional
        (t0, t1) limits of the two time panels (the loops panel shows every
        sample).

    Returns
    -------
    matplotlib.figure.Figure
        Three panels: reference and outputs in time, errors y - r in time,
        output against reference.

    Examples
    --------
    >>> import numpy as np
    >>> from hystcomp import PI
    >>> from hystcomp.iosys import piezo_stage
    >>> loop = build_loop("open_loop", PI([1.0], [0.5], p0=1.0), piezo_stage(), dt=1e-4)
    >>> t = np.arange(1000) * 1e-4
    >>> fig = plot_comparison(compare([loop], np.sin(2 * np.pi * 10 * t), t), title="open loop")
    >>> [ax.get_title() for ax in fig.axes]
    ['tracking', 'tracking error', 'y against r']
    """
    from .plotting import new_figure

    fig, axes = new_figure(1, 3, size=(15, 4.6))
    t, r = comparison.t, comparison.reference
    names = [row["scenario"] for row in comparison.rows] if scenarios is None else list(scenarios)
    axes[0].plot(t, r, "k--", lw=1.2, label="reference r")
    for name in names:
        row = comparison.row(name)
        y = np.asarray(comparison.responses[name].outputs)[0]
        lab = f"{row['label']} ({row['rms_percent']:.2g} % RMS)"
        axes[0].plot(t, y, lw=0.9, label=lab)
        axes[1].plot(t, y - r, lw=0.9, label=row["label"])
        axes[2].plot(r, y, lw=0.7, label=row["label"])
    lim = [r.min(), r.max()]
    axes[2].plot(lim, lim, "k--", lw=1, label="y = r")
    axes[0].set(xlabel="time t [s]", ylabel="position y", title="tracking")
    axes[1].set(xlabel="time t [s]", ylabel="error y - r", title="tracking error")
    axes[2].set(xlabel="reference r", ylabel="position y", title="y against r")
    axes[0].legend(fontsize=7, loc="upper right")
    axes[2].legend(fontsize=7, loc="upper left")
    for ax in axes:
        ax.grid(True, alpha=0.3)
    if time_window is not None:
        axes[0].set_xlim(*time_window)
        axes[1].set_xlim(*time_window)
    if title:
        fig.suptitle(title)
    return fig


def _stderr_progress(done, total, name):  # pragma: no cover - cosmetic
    bar = "#" * int(30 * done / total)
    sys.stderr.write(f"\r[{bar:30s}] {done}/{total} {name:24s}")
    if done == total:
        sys.stderr.write("\n")
    sys.stderr.flush()

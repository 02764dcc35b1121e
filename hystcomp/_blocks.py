"""The python-control block classes of :mod:`hystcomp.iosys`.

:class:`HysteresisBlock` (a hysteresis model), :class:`CompensatorBlock` (an
inverse compensator) and :class:`SaturatedPID` (the PID of
:func:`hystcomp.iosys.pid` with output limits) are subclasses of
:class:`control.NonlinearIOSystem` whose update and output are methods of
module-level classes, so the blocks pickle with plain :mod:`pickle` and copy
with :func:`copy.deepcopy`.  :func:`hystcomp.iosys.hysteresis_system`,
:func:`hystcomp.iosys.compensator_system` and :func:`hystcomp.iosys.pid` are
the factories in front of them (python-control's ``nlsys`` style).

State coordinates: a block's state is the explicit state of its model (the
play positions of eq. 49, the operator outputs of eq. 63, ...) minus the
model's virgin state, so ``X0 = 0`` (python-control's default) is the virgin
state.  Where a virgin entry is infinite (an envelope whose range does not
contain 0 parks the plays at +-inf) that entry is kept as it is, and
:func:`hystcomp.iosys.initial_state` gives the infinite value to pass.
"""

import math
import warnings

import numpy as np

import control as ct

from . import _kernels as _k
from ._validation import as_scalar
from .models import MGPI, HysteresisModel, StopPI

__all__ = ["HysteresisBlock", "CompensatorBlock", "SaturatedPID"]


# ----------------------------------------------------------------------------
# step objects: run(x, u) -> (y, new_state) on a model's explicit state
# ----------------------------------------------------------------------------
def _scalar_input(u):
    return float(np.asarray(u).reshape(-1)[0])


class _GenericSteps:
    """Any object with the simulate protocol, one sample at a time."""

    def __init__(self, obj):
        self.obj = obj

    def run(self, x, u):
        with warnings.catch_warnings():
            # clipped targets are actuator saturation inside a loop; a warning
            # per step would flood the console
            warnings.simplefilter("ignore")
            return self.obj.simulate(np.array([u]), initial_state=x, return_state=True)


class _KernelSteps:
    """Models with a compiled forward kernel (symmetric and asymmetric mGPI,
    PI, StopPI): the same kernel with the same arguments as
    ``model.simulate`` on a one-sample record, so the block equals the model
    bit for bit."""

    def __init__(self, model):
        self.model = model
        if isinstance(model, MGPI) and model.symmetric:
            self.mode = "play"
            self.args = (model._r, model._p, model.p0) + tuple(model.envelope_left.kernel_spec())
        elif isinstance(model, MGPI):
            kl, pl = model.envelope_left.kernel_spec()
            kr, pr = model.envelope_right.kernel_spec()
            self.mode = "mplay"
            self.args = (np.concatenate([[0.0], model._r]), np.concatenate([[model.p0], model._p]),
                         kl, pl, kr, pr)
        else:
            self.mode = "stop"
            self.args = (model._r, model._p, model.p0)

    @staticmethod
    def supports(model):
        """True when `model` has a compiled forward kernel this class runs."""
        if isinstance(model, MGPI):
            kinds = [model.envelope_left.kernel_spec()[0]]
            if not model.symmetric:
                kinds.append(model.envelope_right.kernel_spec()[0])
            return _k.CUSTOM not in kinds
        return isinstance(model, StopPI)

    def run(self, x, u):
        y = np.empty(1)
        v = np.array([float(u)])
        s = np.array(x, dtype=np.float64)
        if self.mode == "play":
            r, p, p0, kind, prm = self.args
            _k.run_play_sum(v, r, p, p0, s, kind, prm, y)   # compiles only this kind's copy
        elif self.mode == "mplay":
            r, p, kl, pl, kr, pr = self.args
            _k.mplay_sum_kernel(kl, kr)(v, r, p, s, kl, pl, kr, pr, y)
        else:
            r, p, p0 = self.args
            w = s[:-1].copy()
            s[-1] = _k.stop_sum(v, r, p, p0, w, s[-1], y)
            s[:-1] = w
        if not np.isfinite(y[0]):
            # the kernels count inputs outside an envelope's domain as +-inf;
            # say so here rather than let python-control see NaN (which it
            # reports as an algebraic loop)
            self.model._check_input_domain(v)
            raise ValueError(f"Block input {u!r} gives the non-finite output {y[0]} from the state {x!r} "
                             f"of {self.model!r}")
        return y, s


class _ExactInverseSteps:
    """An ExactInverse: the compiled solver on one sample, with the
    arguments ``ExactInverse.simulate`` passes it."""

    def __init__(self, comp):
        self.comp = comp

    def run(self, x, u):
        comp = self.comp
        fam = comp._fam
        lo, hi = comp.input_limits
        st = np.array(x, dtype=np.float64)
        xprev = st[0]
        kstate = st[1:-1].copy() if fam == _k.FAM_STOP else st[1:].copy()
        out = np.empty(1)
        info = np.zeros(3, dtype=np.int64)
        # the copy this compensator needs, with ExactInverse.simulate's tolerance (same numbers)
        xlast = _k.inverse_kernel(fam, comp._kl)(fam, np.array([u]), comp._r, comp._p, comp._p0, kstate, xprev,
                                                 comp._kl, comp._pl, comp._kr, comp._pr, comp._kh, comp._ph,
                                                 comp._hscale, lo, hi, comp._output_rtol(), out, info)
        if fam == _k.FAM_STOP:
            new = np.concatenate([[xlast], kstate, [xlast]])
        else:
            new = np.concatenate([[xlast], kstate])
        return out, new


def _steps_for(obj):
    """The fastest step object for a model or compensator."""
    from .inverses import ExactInverse

    if isinstance(obj, ExactInverse):
        return _ExactInverseSteps(obj)
    if isinstance(obj, HysteresisModel) and _KernelSteps.supports(obj):
        return _KernelSteps(obj)
    return _GenericSteps(obj)


# ----------------------------------------------------------------------------
# checks and state names
# ----------------------------------------------------------------------------
def _check_dt(dt):
    """A block's sampling time: True (inherit) or a positive finite float.

    hystcomp blocks are discrete: their update is the state after one
    sample, which python-control would take as a derivative if dt were 0.
    """
    if dt is True:
        return dt
    bad = dt is None or isinstance(dt, (bool, str)) or not np.isscalar(dt)
    if not bad:
        try:
            bad = not (np.isfinite(float(dt)) and float(dt) > 0)
        except (TypeError, ValueError):
            bad = True
    if bad:
        raise ValueError(
            f"Parameter dt is {dt!r} but should be True (inherit the loop's sampling time) or a positive "
            "finite sampling time in seconds; hystcomp blocks are discrete-time (dt = 0 or None would make "
            "python-control read the state update as a derivative)"
        )
    return float(dt)


def _check_protocol(obj, name):
    for attr in ("simulate", "n_states", "default_state"):
        if not hasattr(obj, attr):
            raise TypeError(
                f"Parameter {name} is {obj!r}, which has no {attr!r}; expected an object with "
                "simulate(x, initial_state=None, return_state=False), n_states and default_state()"
            )


def _state_labels(obj, n):
    """Physical names of the explicit state of a model or compensator."""
    from .inverses import ExactInverse, GPIInverse

    if isinstance(obj, ExactInverse):
        return ["command_prev"] + ["model_" + s for s in _state_labels(obj.model, n - 1)]
    if isinstance(obj, GPIInverse):
        return _state_labels(obj.pi_inverse, n)
    if isinstance(obj, MGPI) and obj.symmetric and n == obj._r.size:
        return [f"play[{i}]" for i in range(n)]                 # play positions z_i (eq. 49)
    if isinstance(obj, MGPI) and n == obj._r.size + 1:
        return [f"operator[{i}]" for i in range(n)]             # operator outputs w_0..w_N (eq. 63)
    if isinstance(obj, StopPI) and n == obj._r.size + 1:
        return [f"stop[{i}]" for i in range(n - 1)] + ["input_prev"]
    return [f"x[{i}]" for i in range(n)]


def _check_gain(value, key, positive):
    # runs once per step and block inside an interconnection: plain floats
    try:
        g = float(value)
    except (TypeError, ValueError):
        g = math.nan
    if not math.isfinite(g) or (positive and g <= 0):
        raise ValueError(f"Parameter params[{key!r}] is {value!r} but should be a finite "
                         f"{'positive ' if positive else ''}number")
    return g


# ----------------------------------------------------------------------------
# the blocks
# ----------------------------------------------------------------------------
class _ModelBlock(ct.NonlinearIOSystem):
    """A model or compensator as a discrete NonlinearIOSystem whose state is
    the object's explicit state minus its virgin state."""

    _gain_key = None
    _gain_positive = False

    def __init__(self, obj, gain, dt, name, inputs, outputs):
        virgin = np.asarray(obj.default_state(), dtype=np.float64).reshape(-1)
        n = int(obj.n_states)
        if virgin.size != n:
            raise ValueError(f"{obj!r}.default_state() has {virgin.size} values but n_states is {n}")
        offset = np.where(np.isfinite(virgin), virgin, 0.0)
        self._virgin = virgin
        self._offset = offset if np.any(offset != 0.0) else None
        self._steps = _steps_for(obj)
        gain = _check_gain(gain, self._gain_key, self._gain_positive)
        super().__init__(self._step_update, self._step_output, params={self._gain_key: gain},
                         states=_state_labels(obj, n), inputs=inputs, outputs=outputs,
                         dt=_check_dt(dt), name=name)
        if self.ninputs != 1 or self.noutputs != 1:
            raise ValueError(f"Parameters inputs and outputs are {inputs!r} and {outputs!r}; a hystcomp "
                             "block has one input and one output")

    def _update_params(self, params):
        super()._update_params(params)
        key = self._gain_key
        self._current_params[key] = _check_gain(self._current_params.get(key), key, self._gain_positive)

    def initial_state(self):
        """The virgin state in the block's coordinates (for ``X0``).

        Zeros, except where the model's virgin state is infinite (plays
        parked at +-inf by an envelope whose range excludes 0).

        Returns
        -------
        ndarray, shape (nstates,)

        Examples
        --------
        >>> from hystcomp import PI
        >>> from hystcomp.iosys import hysteresis_system
        >>> hysteresis_system(PI([1.0, 2.0], [0.5, 0.25], p0=1.0)).initial_state().tolist()
        [0.0, 0.0]
        """
        return np.where(np.isfinite(self._virgin), 0.0, self._virgin)

    def to_model_state(self, x):
        """The model's explicit state for a block state `x`.

        Parameters
        ----------
        x : array_like, shape (nstates,)
            A state of this block (``X0`` or a column of a response's
            ``states``).

        Returns
        -------
        ndarray
            ``x`` plus the model's virgin state: what ``simulate(...,
            initial_state=...)`` of the model (or compensator) takes.

        Examples
        --------
        >>> from hystcomp import MGPI
        >>> from hystcomp.envelopes import Tanh
        >>> from hystcomp.iosys import hysteresis_system
        >>> block = hysteresis_system(MGPI([1.0], [0.5], p0=1.0, envelope=Tanh(2.0, 0.5, 0.25)))
        >>> block.to_model_state([0.0]).tolist()      # virgin play at gamma^-1(0) = -0.25 / 0.5
        [-0.5]
        """
        x = np.asarray(x, dtype=np.float64).reshape(-1)
        if x.size != self.nstates:
            raise ValueError(f"Parameter x has {x.size} values but the block has {self.nstates} states")
        return x.copy() if self._offset is None else x + self._offset

    def from_model_state(self, state):
        """The block state for an explicit state of the model (or compensator).

        Parameters
        ----------
        state : array_like, shape (nstates,)
            A state as ``simulate(..., return_state=True)`` returns it.

        Returns
        -------
        ndarray
            The state in the block's coordinates (pass it as ``X0``).

        Examples
        --------
        >>> import numpy as np, control as ct
        >>> from hystcomp import PI
        >>> from hystcomp.iosys import hysteresis_system
        >>> m = PI([1.0], [0.5], p0=1.0)
        >>> _, s = m.simulate([0.0, 3.0], return_state=True)
        >>> block = hysteresis_system(m, dt=0.1)
        >>> resp = ct.input_output_response(block, np.array([0.0, 0.1]), [1.0, 1.0], block.from_model_state(s))
        >>> bool(np.allclose(resp.outputs, m.simulate([1.0, 1.0], initial_state=s)))
        True
        """
        s = np.asarray(state, dtype=np.float64).reshape(-1)
        if s.size != self.nstates:
            raise ValueError(f"Parameter state has {s.size} values but the block has {self.nstates} states")
        return s.copy() if self._offset is None else s - self._offset

    def _run(self, x, u):
        if self._offset is not None:
            x = x + self._offset
        return self._steps.run(x, u)

    def _step_update(self, t, x, u, params):
        new = self._run(x, self._input_gain(params) * _scalar_input(u))[1]
        return new if self._offset is None else new - self._offset


class HysteresisBlock(_ModelBlock):
    """A hysteresis model as a discrete python-control system.

    ``w[k] = actuator_gain * model(v[k]; x[k])``: the model's output for the
    input ``v[k]`` from the state ``x[k]`` (feedthrough), and ``x[k+1]`` the
    state after ``v[k]``.  The state is the model's explicit state (the play
    positions of eq. 49, named ``play[i]``; the operator outputs of eq. 63,
    ``operator[i]``; the stops and the last input of a StopPI) minus the
    virgin state, so ``X0 = 0`` starts from the virgin state and
    ``ct.input_output_response(block, t, v).outputs == model.simulate(v)``.

    Build it with :func:`hystcomp.iosys.hysteresis_system`.

    Parameters
    ----------
    model : HysteresisModel
        Any object with ``simulate(v, initial_state=None,
        return_state=False)``, ``n_states`` and ``default_state()``.  PI,
        mGPI and StopPI with built-in envelopes run their compiled kernel.
    actuator_gain : float
        Default of ``params["actuator_gain"]``, a gain on the output (the
        actuator's sensitivity); ``input_output_response(..., params=
        {"actuator_gain": k})`` sweeps it.  In an interconnection every
        hysteresis block reads the same ``actuator_gain`` (python-control
        merges the parameters of all blocks).
    dt : True or float
        Sampling time; True inherits the loop's.
    name : str or None
        Block name (python-control makes one up if None).
    inputs, outputs : str
        Signal names of the actuator input and output.

    Attributes
    ----------
    model : HysteresisModel
        The model (read only).

    Examples
    --------
    >>> import numpy as np, control as ct
    >>> from hystcomp import MGPI
    >>> from hystcomp.envelopes import Tanh
    >>> m = MGPI([1.0, 2.0], [0.5, 0.25], p0=1.0, envelope=Tanh(5.0, 0.4, 0.2))
    >>> block = HysteresisBlock(m, dt=0.01, name="actuator")
    >>> block.state_labels, block.params
    (['play[0]', 'play[1]'], {'actuator_gain': 1.0})
    >>> t = np.arange(300) * 0.01
    >>> v = 3 * np.sin(2 * np.pi * t)
    >>> resp = ct.input_output_response(block, t, v, params={"actuator_gain": 2.0})
    >>> bool(np.allclose(resp.outputs, 2.0 * m.simulate(v), rtol=0, atol=1e-12))
    True
    """

    _gain_key = "actuator_gain"

    def __init__(self, model, actuator_gain=1.0, dt=True, name=None, inputs="v", outputs="w"):
        _check_protocol(model, "model")
        self._model = model
        super().__init__(model, actuator_gain, dt, name, inputs, outputs)

    @property
    def model(self):
        """The hysteresis model (read only)."""
        return self._model

    @staticmethod
    def _input_gain(params):
        return 1.0

    def _step_output(self, t, x, u, params):
        return params["actuator_gain"] * self._run(x, _scalar_input(u))[0]


class CompensatorBlock(_ModelBlock):
    """An inverse compensator as a discrete python-control system.

    ``v[k] = C(nominal_gain * u[k]; x[k])`` with C a compensator (the exact
    or analytic inverse of a model), so that the compensated actuator
    ``model o C`` maps u to ``nominal_gain * u``.  The state is the
    compensator's explicit state minus its virgin state (``X0 = 0`` is
    virgin).  Targets the model cannot reach are clipped (actuator
    saturation) without a warning per step.

    Build it with :func:`hystcomp.iosys.compensator_system`.

    Parameters
    ----------
    compensator : object
        ``simulate``, ``n_states``, ``default_state()``: an
        :class:`~hystcomp.inverses.ExactInverse` (compiled solver), an
        analytic inverse model, ...
    nominal_gain : float
        Default of ``params["nominal_gain"]`` (> 0); sweeps pass
        ``params={"nominal_gain": k}``.
    model : HysteresisModel or None
        The model `compensator` inverts (kept for reference).
    method : str
        How `compensator` was made ("exact", "analytic" or "given").
    dt : True or float
        Sampling time; True inherits the loop's.
    name : str or None
        Block name.
    inputs, outputs : str
        Signal names (compensator input, actuator command).

    Attributes
    ----------
    compensator, model, method
        As given (read only).
    nominal_gain : float
        The default nominal gain, ``params["nominal_gain"]`` (read only).

    Examples
    --------
    >>> import numpy as np, control as ct
    >>> from hystcomp import PI
    >>> m = PI([1.0, 2.0], [0.5, 0.25], p0=1.0)
    >>> comp = CompensatorBlock(m.exact_inverse(), nominal_gain=2.0, model=m, dt=0.01)
    >>> comp.nominal_gain, comp.state_labels[:2]
    (2.0, ['command_prev', 'model_play[0]'])
    >>> u = np.sin(np.linspace(0, 6, 300))
    >>> v = ct.input_output_response(comp, np.arange(300) * 0.01, u).outputs
    >>> bool(np.allclose(m.simulate(v), 2.0 * u, atol=1e-12))
    True
    """

    _gain_key = "nominal_gain"
    _gain_positive = True

    def __init__(self, compensator, nominal_gain=1.0, model=None, method="given", dt=True, name=None,
                 inputs="u", outputs="v"):
        _check_protocol(compensator, "compensator")
        self._compensator, self._model, self._method = compensator, model, method
        super().__init__(compensator, nominal_gain, dt, name, inputs, outputs)

    @property
    def compensator(self):
        """The compensator object (read only)."""
        return self._compensator

    @property
    def model(self):
        """The model the compensator inverts, or None (read only)."""
        return self._model

    @property
    def method(self):
        """"exact", "analytic" or "given" (read only)."""
        return self._method

    @property
    def nominal_gain(self):
        """Default nominal gain, ``params["nominal_gain"]`` (read only)."""
        return self.params["nominal_gain"]

    @staticmethod
    def _input_gain(params):
        return params["nominal_gain"]

    def _step_output(self, t, x, u, params):
        return self._run(x, params["nominal_gain"] * _scalar_input(u))[0]


class SaturatedPID(ct.NonlinearIOSystem):
    """The PID of :func:`hystcomp.iosys.pid` with output limits.

    ``u = clip(C x + D e, lo, hi)`` with the states ``[I, f]`` of the linear
    PID (integral and derivative filter); the integral stops while u is
    saturated and the error drives it further (conditional integration,
    an anti-windup scheme).

    Parameters
    ----------
    kp, ki, kd : float
        Proportional, integral and derivative gains.
    dt : float
        Sampling time.
    tau_d : float
        Derivative filter time constant.
    output_limits : (float, float)
        (lo, hi) with lo < hi.
    name : str
        Block name.
    inputs, outputs : str
        Signal names (error in, command out).

    Attributes
    ----------
    A, B, C, D : ndarray
        The linear PID (the matrices of ``pid`` without limits).

    Examples
    --------
    >>> c = SaturatedPID(1.0, 10.0, 0.0, 1e-3, 1e-2, (-1.0, 1.0))
    >>> c.state_labels, c.output_limits
    (['I', 'f'], (-1.0, 1.0))
    """

    def __init__(self, kp, ki, kd, dt, tau_d, output_limits, name="pid", inputs="e", outputs="u"):
        self.kp, self.ki, self.kd = (as_scalar(x, n) for x, n in ((kp, "kp"), (ki, "ki"), (kd, "kd")))
        dt = as_scalar(dt, "dt", positive=True)
        self.tau_d = as_scalar(tau_d, "tau_d", positive=True)
        try:
            lo, hi = as_scalar(output_limits[0], "output_limits"), as_scalar(output_limits[1], "output_limits")
        except (TypeError, IndexError, KeyError):
            raise ValueError(f"Parameter output_limits is {output_limits!r} but should be (lo, hi)") from None
        if not lo < hi:
            raise ValueError(f"Parameter output_limits is {output_limits!r} but should satisfy lo < hi")
        self.output_limits = (lo, hi)
        a = float(np.exp(-dt / self.tau_d))
        self.A = np.array([[1.0, 0.0], [0.0, a]])
        self.B = np.array([[dt], [1.0 - a]])
        self.C = np.array([[self.ki, -self.kd / self.tau_d]])
        self.D = np.array([[self.kp + self.ki * dt + self.kd / self.tau_d]])
        self._c0, self._c1, self._d, self._a = float(self.C[0, 0]), float(self.C[0, 1]), float(self.D[0, 0]), a
        super().__init__(self._step_update, self._step_output, states=["I", "f"], inputs=inputs,
                         outputs=outputs, dt=float(dt), name=name)

    def _raw(self, x, e):
        return self._c0 * x[0] + self._c1 * x[1] + self._d * e

    def _step_output(self, t, x, u, params):
        lo, hi = self.output_limits
        return np.array([min(max(self._raw(x, _scalar_input(u)), lo), hi)])

    def _step_update(self, t, x, u, params):
        e = _scalar_input(u)
        uu = self._raw(x, e)
        lo, hi = self.output_limits
        hold = (uu > hi and e > 0.0) or (uu < lo and e < 0.0)
        integ = x[0] if hold else x[0] + self.dt * e
        return np.array([integ, self._a * x[1] + (1.0 - self._a) * e])


# documented, pickled and shown as hystcomp.iosys.* (their public home)
for _cls in (HysteresisBlock, CompensatorBlock, SaturatedPID):
    _cls.__module__ = "hystcomp.iosys"
del _cls

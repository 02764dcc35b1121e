"""Bad-input harness (issue 12): every covered public callable, every
argument, a table of bad values.

Each call must either raise ``ValueError``/``TypeError`` whose message names
the argument, or return a result without NaN.  Values that are never
meaningful (NaN, inf, strings, complex, 2-D where 1-D is expected, wrong
types) must raise.  Never an AttributeError, a numba error, a ZeroDivisionError
or a NaN output.

``PUBLIC`` walks ``__all__`` of the public modules; every callable there is
either exercised (``CASES``) or listed in ``NOT_COVERED`` with the reason, so
that a new public function cannot slip past unnoticed.
"""

import importlib
import warnings

import numpy as np
import pytest

import hystcomp
import hystcomp.signals
from hystcomp import (GPI, KP, MGPI, PI, Atanh, BacklashLike, BoucWen, Linear, Polynomial, Preisach,
                      StopPI, Tanh)

MODULES = ["hystcomp", "hystcomp.envelopes", "hystcomp.operators", "hystcomp.models", "hystcomp.signals",
           "hystcomp.preisach", "hystcomp.differential", "hystcomp.inverses", "hystcomp.iosys",
           "hystcomp.identify"]

# --------------------------------------------------------------------------
# bad values by kind of argument
# --------------------------------------------------------------------------
NEVER = "never"          # must raise: never a meaningful value
MAYBE = "maybe"          # may be valid: raise naming the argument, or a NaN-free result

_SIGNAL = [
    ([0.0, np.nan, 1.0], NEVER), ([0.0, np.inf], NEVER), ("abc", NEVER), ([[0.0, 1.0], [2.0, 3.0]], NEVER),
    ([1 + 1j, 2.0], NEVER), (object(), NEVER), ([], MAYBE), ([0.5], MAYBE), ([1e18, -1e18], MAYBE),
    ([1e-300, 0.0], MAYBE),
]
# models simulate a 2-D input (samples x signals) as a batch: only 3-D is bad
_SIGNAL_OR_BATCH = [x for x in _SIGNAL if np.ndim(x[0]) != 2] + [(np.zeros((2, 2, 2)), NEVER)]
_THRESHOLDS = [
    ([1.0, np.nan], NEVER), ([np.inf], NEVER), ("abc", NEVER), ([[1.0, 2.0]], MAYBE), ([1j], NEVER),
    ([], NEVER), ([2.0, 1.0], NEVER), ([1.0, 1.0], NEVER), ([-1.0], NEVER), ([0.0], MAYBE), (None, NEVER),
]
_SCALAR = [
    (np.nan, NEVER), (np.inf, NEVER), (-np.inf, NEVER), ("abc", NEVER), (1 + 1j, NEVER), ([1.0, 2.0], NEVER),
    (object(), NEVER), (0.0, MAYBE), (-1.0, MAYBE), (1e300, MAYBE), (1e-300, MAYBE),
]
_POSITIVE = _SCALAR   # 0 / -1 are "maybe": the callable decides, but must name the argument
_COUNT = [
    (np.nan, NEVER), ("abc", NEVER), (2.5, NEVER), (-1, NEVER), (None, NEVER), (0, MAYBE), (1, MAYBE),
]
_RANGE = [
    ((1.0, -1.0), NEVER), ((0.0, 0.0), NEVER), ((0.0, np.nan), NEVER), ((-np.inf, 1.0), NEVER),
    ("ab", NEVER), (1.0, NEVER), (None, NEVER), ((1.0,), NEVER), ((0.0, 1.0, 2.0), MAYBE),
]
_ENVELOPE = [("tanh", NEVER), (1.0, NEVER), (np.tanh, NEVER), (object(), NEVER)]
_MODEL = [("PI", NEVER), (1.0, NEVER), (None, NEVER), (object(), NEVER)]
_WEIGHTS = [
    ([np.nan], NEVER), ([np.inf], NEVER), ("a", NEVER), ([], NEVER), ([1.0, 2.0, 3.0], NEVER), ([1j], NEVER),
    ([-1.0], MAYBE), ([0.0], MAYBE),
]
_PLANE = [
    (np.full((2, 2), np.nan), NEVER), ([[1.0, 0.0], [np.inf, 1.0]], NEVER), ("ab", NEVER),
    ([1.0, 2.0], NEVER), (np.zeros((2, 3)), NEVER), ([[1j, 0], [0, 1]], NEVER), (np.zeros((0, 0)), NEVER),
    (-np.tril(np.ones((2, 2))), MAYBE),
]

_v = np.sin(np.linspace(0.0, 12.0, 400))
_t = np.linspace(0.0, 4.0, 400)


def _pi():
    return PI([0.5, 1.0], [0.4, 0.2], 1.0)


# name -> (callable, valid keyword arguments, {argument: bad-value table})
CASES = {
    "Linear": (Linear, dict(k=2.0), dict(k=_POSITIVE)),
    "Tanh": (Tanh, dict(a=2.0, b=1.0, c=0.0), dict(a=_POSITIVE, b=_POSITIVE, c=_SCALAR)),
    "Atanh": (Atanh, dict(a=2.0, b=0.5, offset=0.0), dict(a=_POSITIVE, b=_POSITIVE, offset=_SCALAR)),
    "Polynomial": (Polynomial, dict(coeffs=[0.0, 1.0, 0.0, 0.5], interval=(-2.0, 2.0)),
                   dict(coeffs=_WEIGHTS[:6] + [([0.0, -1.0], NEVER)], interval=_RANGE)),
    "play": (hystcomp.play, dict(v=_v, thresholds=[0.5, 1.0]), dict(v=_SIGNAL, thresholds=_THRESHOLDS)),
    "stop": (hystcomp.stop, dict(v=_v, thresholds=[0.5, 1.0]), dict(v=_SIGNAL, thresholds=_THRESHOLDS)),
    "generalized_play": (hystcomp.generalized_play,
                         dict(v=_v, thresholds=[0.5], envelope_left=Tanh(2.0, 1.0), envelope_right=Tanh(3.0, 1.0)),
                         dict(v=_SIGNAL, thresholds=_THRESHOLDS, envelope_left=_ENVELOPE,
                              envelope_right=_ENVELOPE)),
    "modified_play": (hystcomp.modified_play, dict(v=_v, thresholds=[0.5], envelope_left=Tanh(2.0, 1.0)),
                      dict(v=_SIGNAL, thresholds=_THRESHOLDS, envelope_left=_ENVELOPE)),
    "PI": (PI, dict(thresholds=[0.5], weights=[0.4], p0=1.0),
           dict(thresholds=_THRESHOLDS, weights=_WEIGHTS, p0=_SCALAR)),
    "StopPI": (StopPI, dict(thresholds=[0.5], weights=[0.4], p0=1.0),
               dict(thresholds=_THRESHOLDS, weights=_WEIGHTS, p0=_SCALAR)),
    "MGPI": (MGPI, dict(thresholds=[0.5], weights=[0.4], p0=1.0, envelope=Tanh(2.0, 1.0)),
             dict(thresholds=_THRESHOLDS, weights=_WEIGHTS, p0=_SCALAR, envelope=_ENVELOPE)),
    "GPI": (GPI, dict(thresholds=[0.5], weights=[0.4], envelope_left=Tanh(2.0, 1.0), envelope_right=Tanh(3.0, 1.0)),
            dict(thresholds=_THRESHOLDS, weights=_WEIGHTS, envelope_left=_ENVELOPE, envelope_right=_ENVELOPE)),
    "PI.simulate": (lambda v, initial_state=None: _pi().simulate(v, initial_state=initial_state),
                    dict(v=_v), dict(v=_SIGNAL_OR_BATCH, initial_state=[([np.nan, 0.0], NEVER), ([np.inf, 0.0], NEVER),
                                                                ([0.0], NEVER), ("ab", NEVER),
                                                                ([0.0, 0.0, 0.0], NEVER)])),
    "PI.exact_inverse().simulate": (lambda u: _pi().exact_inverse().simulate(u), dict(u=_v), dict(u=_SIGNAL)),
    "PI.loading_curve": (lambda r: _pi().loading_curve(r), dict(r=1.0), dict(r=_SCALAR[:5])),
    "model_from_dict": (hystcomp.model_from_dict, dict(d=_pi().to_dict()),
                        dict(d=[("{", NEVER), ({}, NEVER), ([], NEVER), (None, NEVER), ({"model": []}, NEVER),
                                ({"model": "PI"}, NEVER)])),
    "tracking_error": (hystcomp.tracking_error, dict(model=_pi(), compensator=_pi().exact_inverse(), u=_v),
                       dict(model=_MODEL, compensator=_MODEL, u=_SIGNAL)),
    "Preisach": (Preisach, dict(input_range=(-1.0, 1.0), weights=np.tril(np.ones((3, 3)))),
                 dict(input_range=_RANGE, weights=_PLANE, offset=_SCALAR)),
    "KP": (KP, dict(input_range=(-1.0, 1.0), weights=np.tril(np.ones((3, 3)))),
           dict(input_range=_RANGE, weights=_PLANE, offset=_SCALAR)),
    "Preisach.simulate": (lambda v: Preisach.from_density(lambda a, b: np.ones_like(a), (-1, 1), 4).simulate(v),
                          dict(v=_v), dict(v=_SIGNAL)),
    "KP.simulate": (lambda v: KP.from_density(lambda a, b: np.ones_like(a), (-1, 1), 4).simulate(v),
                    dict(v=_v), dict(v=_SIGNAL)),
    "preisach_grid": (importlib.import_module("hystcomp.preisach").preisach_grid,
                      dict(input_range=(-1.0, 1.0), n=4), dict(input_range=_RANGE, n=_COUNT)),
    "BoucWen": (BoucWen, dict(A=1.0, alpha=0.6, beta=0.2, n=1.0, gain=0.5),
                dict(A=_SCALAR, alpha=_SCALAR, beta=_SCALAR, n=_SCALAR, gain=_SCALAR)),
    "BacklashLike": (BacklashLike, dict(alpha=1.0, c=3.0, B1=1.0), dict(alpha=_SCALAR, c=_SCALAR, B1=_SCALAR)),
    "BoucWen.simulate": (lambda v: BoucWen(A=1.0, alpha=0.6, beta=0.2, n=1.0, gain=0.5).simulate(v),
                         dict(v=_v), dict(v=_SIGNAL)),
    "staircase": (hystcomp.signals.staircase, dict(n=10, levels=[0.0, 1.0]),
                  dict(n=_COUNT, levels=[([np.nan], NEVER), ([], NEVER), ("ab", NEVER), ([[1.0]], NEVER)])),
    "multisine": (hystcomp.signals.multisine, dict(t=_t, frequencies=[1.0, 2.0]),
                  dict(t=_SIGNAL[:6] + [(_t[::-1], NEVER)], frequencies=_SIGNAL[:6] + [([], NEVER), ([-1.0], NEVER)],
                       amplitude=_SCALAR[:7], taper=_SCALAR)),
    "decaying_sine": (hystcomp.signals.decaying_sine, dict(t=_t, frequency=1.0),
                      dict(t=_SIGNAL[:6], frequency=_SCALAR, amplitude=_SCALAR[:7], final_fraction=_SCALAR)),
    "identification_experiment": (hystcomp.signals.identification_experiment, dict(dt=0.01, duration=8.0),
                                  dict(dt=_SCALAR, duration=_SCALAR, amplitude=_SCALAR[:7], steps=_COUNT,
                                       tail=_SCALAR[:7], frequencies=_SIGNAL[:6] + [([], NEVER)])),
}

import hystcomp.envelopes as _env  # noqa: E402
import hystcomp.identify as _idf  # noqa: E402
import hystcomp.inverses as _inv  # noqa: E402
import hystcomp.iosys as _io  # noqa: E402

_DT = [(np.nan, NEVER), (-1.0, NEVER), ("x", NEVER), (np.inf, NEVER), (1 + 1j, NEVER)]
_LIMITS = [((1.0, -1.0), NEVER), ((0.0, np.nan), NEVER), ("ab", NEVER), (1.0, NEVER), ((1.0,), NEVER)]
_CHOICE = [("nonsense", NEVER), (None, NEVER), (1.0, NEVER)]
_FUNCTION = [("x", NEVER), (1.0, NEVER)]
_SYS = [("x", NEVER), (None, NEVER), (1.0, NEVER), (_pi(), NEVER)]
_y = _pi().simulate(_v)

CASES.update({
    "Custom": (hystcomp.Custom, dict(f=np.tanh, df=lambda x: 1.0 - np.tanh(x) ** 2),
               dict(f=_FUNCTION, df=_FUNCTION, finv=_FUNCTION,
                    domain=[((1.0, -1.0), NEVER), ((0.0, np.nan), NEVER), ("ab", NEVER), (1.0, NEVER)])),
    "envelope_from_dict": (_env.envelope_from_dict, dict(d=Tanh(2.0, 1.0).to_dict()),
                           dict(d=[("x", NEVER), ({}, NEVER), ({"type": "Tanh"}, NEVER), (None, NEVER),
                                   ({"type": "Tanh", "a": "x", "b": 1.0}, NEVER)])),
    "extended_values": (_env.extended_values, dict(env=Tanh(2.0, 1.0), x=_v),
                        dict(env=_ENVELOPE, x=[([0.0, np.nan], NEVER), ("abc", NEVER), ([1j], NEVER),
                                              (object(), NEVER), ([np.inf, -np.inf], MAYBE), ([], MAYBE)])),
    "ExactInverse": (hystcomp.ExactInverse, dict(model=_pi()),
                     dict(model=_MODEL, on_unreachable=_CHOICE, input_limits=_LIMITS)),
    "GPIInverse": (hystcomp.GPIInverse, dict(model=GPI([0.5], [0.4], Tanh(2.0, 1.0), Tanh(2.0, 1.0),
                                                      H=Tanh(2.0, 1.0))),
                   dict(model=_MODEL)),
    "NumericalInverse": (hystcomp.NumericalInverse, dict(model=BacklashLike(alpha=1.0, c=3.0, B1=1.0)),
                         dict(model=_MODEL, on_unreachable=_CHOICE, input_limits=_LIMITS, tol=_SCALAR[:7])),
    "Duhem": (hystcomp.Duhem, dict(f1=lambda w, v, p: 1.0 - w, f2=lambda w, v, p: 1.0 + w),
              dict(f1=_FUNCTION, f2=_FUNCTION, max_step=_SCALAR, gain=_SCALAR[:7], offset=_SCALAR[:7])),
    "mgpi_inverse_parameters": (_inv.mgpi_inverse_parameters,
                                dict(thresholds=[0.5, 1.0], weights=[0.4, 0.2], p0=1.0, envelope=Tanh(2.0, 1.0)),
                                dict(thresholds=_THRESHOLDS, weights=_WEIGHTS, p0=_SCALAR[:7],
                                     envelope=_ENVELOPE)),
    "hysteresis_system": (_io.hysteresis_system, dict(model=_pi()), dict(model=_MODEL, dt=_DT)),
    "compensator_system": (_io.compensator_system, dict(model=_pi()),
                           dict(model=_MODEL, method=_CHOICE, dt=_DT, nominal_gain=_SCALAR[:7],
                                compensator=_MODEL[:2] + _MODEL[3:])),
    "mean_gain": (_io.mean_gain, dict(model=_pi(), input_range=(-1.0, 1.0)),
                  dict(model=_MODEL, input_range=_LIMITS, n_samples=_COUNT)),
    "initial_state": (_io.initial_state, dict(sys=_io.hysteresis_system(_pi())), dict(sys=_SYS)),
    "piezo_stage": (_io.piezo_stage, dict(),
                    dict(gain=_SCALAR[:7], natural_freq_hz=_SCALAR, damping=_SCALAR, dt=_DT)),
    "pid": (_io.pid, dict(kp=1.0, ki=10.0, kd=0.001, dt=1e-3),
            dict(kp=_SCALAR[:7], ki=_SCALAR[:7], kd=_SCALAR[:7], dt=_DT, tau_d=_SCALAR[:7],
                 output_limits=_LIMITS)),
    "discretize": (_io.discretize, dict(sys=_io.piezo_stage(), dt=1e-4), dict(sys=_SYS, dt=_DT)),
    "check_wiring": (_io.check_wiring, dict(syslist=[_io.hysteresis_system(_pi())], inplist=["v"],
                                            outlist=["w"]),
                     dict(syslist=_SYS + [([1, 2], NEVER)], inplist=[(5, NEVER)], outlist=[(5, NEVER)])),
    "interconnect": (_io.interconnect, dict(syslist=[_io.hysteresis_system(_pi())], inplist=["v"],
                                            outlist=["w"]),
                     dict(syslist=_SYS + [([1, 2], NEVER)], inplist=[(5, NEVER)], outlist=[(5, NEVER)])),
    "fit_weights": (_idf.fit_weights, dict(v=_v, y=_y, thresholds=[0.5, 0.9], model="pi"),
                    dict(v=_SIGNAL[:6], y=_SIGNAL[:6], thresholds=_THRESHOLDS[:-1], model=_CHOICE)),
    "validate": (_idf.validate, dict(model=_pi(), v=_v, y=_y),
                 dict(model=_MODEL, v=_SIGNAL[:6], y=_SIGNAL[:6], offset=_SCALAR[:7])),
    "HysteresisBlock": (_io.HysteresisBlock, dict(model=_pi()),
                        dict(model=_MODEL, actuator_gain=_SCALAR[:7], dt=_DT)),
    "CompensatorBlock": (_io.CompensatorBlock, dict(compensator=_pi().exact_inverse()),
                         dict(compensator=_MODEL, nominal_gain=_SCALAR[:7], dt=_DT)),
    "SaturatedPID": (_io.SaturatedPID, dict(kp=1.0, ki=10.0, kd=0.001, dt=1e-3, tau_d=1e-3,
                                            output_limits=(-1.0, 1.0)),
                     dict(kp=_SCALAR[:7], ki=_SCALAR[:7], kd=_SCALAR[:7], dt=_DT, tau_d=_SCALAR[:7],
                          output_limits=_LIMITS)),
    "compensation_error": (_idf.compensation_error, dict(true_model=_pi(), estimated_model=_pi(), u=_v),
                           dict(true_model=_MODEL, estimated_model=_MODEL, u=_SIGNAL[:6])),
})

NOT_COVERED = {
    # callables of the walked modules that CASES does not exercise yet, and why
    "Identity": "takes no argument",
    "Envelope": "abstract base class",
    "HysteresisModel": "abstract base class",
    "Invertibility": "result object (built by is_invertible)",
    "Inverse": "built by envelope.inverse_envelope(); its argument is an Envelope",
    "TrackingError": "result named tuple",
    "Experiment": "result named tuple",
    "FitResult": "result object", "EnvelopeFitResult": "result object", "ModelFit": "result object",
    "ModelComparison": "result object",
    "HysteresisRegressor": "scikit-learn style estimator: its fit() calls fit_weights (covered)",
    "fit": "seconds per call (envelope search): too slow for a table of bad values; fit_weights covered",
    "fit_preisach": "seconds per call (QP)", "fit_kp": "seconds per call (QP)",
    "fit_bouc_wen": "seconds per call (least squares)", "fit_backlash_like": "seconds per call",
    "fit_duhem": "seconds per call", "compare_models": "tens of seconds per call",
}


# --------------------------------------------------------------------------
# the rest of the public modules: loops, analysis, design, mismatch, datasets,
# effects, numerical_inverse, differential, data, plotting, demo, thesis
# --------------------------------------------------------------------------
import control as ct  # noqa: E402
import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import hystcomp.analysis as _an  # noqa: E402
import hystcomp.data as _data  # noqa: E402
import hystcomp.datasets as _ds  # noqa: E402
import hystcomp.demo as _demo  # noqa: E402
import hystcomp.design as _des  # noqa: E402
import hystcomp.effects as _eff  # noqa: E402
import hystcomp.loops as _loops  # noqa: E402
import hystcomp.mismatch as _mm  # noqa: E402
import hystcomp.plotting as _plot  # noqa: E402
import hystcomp.thesis as _th  # noqa: E402

MODULES += ["hystcomp.loops", "hystcomp.analysis", "hystcomp.design", "hystcomp.mismatch", "hystcomp.datasets",
            "hystcomp.effects", "hystcomp.numerical_inverse", "hystcomp.data", "hystcomp.plotting",
            "hystcomp.demo", "hystcomp.thesis"]

_STAGE = _io.piezo_stage()
_DSTAGE = _io.discretize(_STAGE, 1e-4)
_PID = _io.pid(0.0, 300.0, 0.0, 1e-4)
_tl = np.arange(200) * 1e-4
_rl = np.sin(2 * np.pi * 50 * _tl)
_LOOP = _loops.build_loop("open_loop", _pi(), _STAGE, dt=1e-4)
_SCEN = _loops.build_scenarios(_pi(), _STAGE, controller=_PID, compensator=_io.compensator_system(_pi()), dt=1e-4)
_PLANT = [("x", NEVER), (None, NEVER), (1.0, NEVER), (_pi(), NEVER), (ct.tf([1], [1, 1, 1, 1]), MAYBE)]
_LOOPARG = [("x", NEVER), (None, NEVER), (1.0, NEVER), (_pi(), NEVER)]
_SECTOR = [((2.0, 1.0), NEVER), ((np.nan, 1.0), NEVER), ("ab", NEVER), (1.0, NEVER), ((1.0,), NEVER),
           ((-1.0, 1.0), MAYBE)]
_FREQ = _SCALAR[:7] + [(0.0, NEVER), (-1.0, NEVER)]
_GAIN = _SCALAR[:7] + [(0.0, NEVER), (-1.0, MAYBE)]     # a negative actuator gain is a sign, not an error
_PHASE = _SCALAR[:7] + [(0.0, NEVER), (-10.0, NEVER), (200.0, NEVER)]
_ORDER = [("abc", NEVER), (np.nan, NEVER), ([1.0, 2.0], NEVER), (object(), NEVER)]
_BLOCK = [("PI", NEVER), (1.0, NEVER), (None, NEVER), (object(), NEVER)]
_TIMES = [([np.nan], NEVER), ([np.inf], NEVER), ("ab", NEVER), ([], MAYBE), ([-1.0], NEVER), ([0.0], NEVER),
          ([1j], NEVER)]
# a NaN in a plotted curve is a gap (matplotlib's convention), not an error
_FIGURE_ARRAY = [(x, MAYBE if isinstance(x, list) and len(x) < 4 and not isinstance(x[0], complex)
                  and not isinstance(x[0], list) else kind) for x, kind in _SIGNAL[:6]]


def _closing(f):
    """`f` closing every figure it opened (many calls per case)."""
    def call(**kw):
        try:
            return f(**kw)
        finally:
            plt.close("all")
    return call


def _lag():
    return _eff.LinearStage.lag(0.01, dt=1e-3)


_case = {
    # loops
    "build_loop": (_loops.build_loop, dict(scenario="open_loop", hysteresis=_pi(), plant=_STAGE, dt=1e-4),
                   dict(scenario=_CHOICE, hysteresis=_MODEL, plant=_PLANT[:4], controller=_PLANT[:1] + _PLANT[2:4],
                        compensator=_PLANT[:1] + _PLANT[2:3], dt=_DT, feedforward_gain=_SCALAR[:7])),
    "build_scenarios": (_loops.build_scenarios, dict(hysteresis=_pi(), plant=_STAGE, dt=1e-4),
                        dict(hysteresis=_MODEL, plant=_PLANT[:4], controller=_PLANT[:1] + _PLANT[2:4], dt=_DT,
                             scenarios=[("nonsense", NEVER), (1.0, NEVER), (["nonsense"], NEVER)])),
    "simulate_loop": (_loops.simulate_loop, dict(loop=_LOOP, timepts=_tl, inputs=_rl),
                      dict(loop=_LOOPARG, timepts=_SIGNAL[:6] + [(_tl[::-1], NEVER)], inputs=_SIGNAL[:6],
                           initial_state=[([np.nan], NEVER), ("ab", NEVER), ([0.0] * 9, NEVER)])),
    "Loop.simulate": (lambda timepts, inputs, engine="python-control": _LOOP.simulate(timepts, inputs, engine=engine),
                      dict(timepts=_tl, inputs=_rl),
                      dict(timepts=_SIGNAL[:6], inputs=_SIGNAL[:6], engine=_CHOICE)),
    "compare": (_loops.compare, dict(scenarios={"open_loop": _LOOP}, timepts=_tl, inputs=_rl),
                dict(scenarios=[("x", NEVER), (None, NEVER), ({}, NEVER), ({"a": 1.0}, NEVER), ([1.0], NEVER)],
                     timepts=_SIGNAL[:6], inputs=_SIGNAL[:6], engine=_CHOICE)),
    "loop_width": (_loops.loop_width, dict(reference=_v, output=_y),
                   dict(reference=_SIGNAL, output=_SIGNAL, n_bins=_COUNT)),
    "plot_comparison": (_closing(_loops.plot_comparison),
                        dict(comparison=_loops.compare({"open_loop": _LOOP}, _tl, _rl)),
                        dict(comparison=[("x", NEVER), (None, NEVER), (1.0, NEVER)],
                             scenarios=[(["nonsense"], NEVER), (1.0, NEVER)],
                             time_window=_LIMITS)),
    "fast_response": (_loops.fast_response, dict(sys=_LOOP.system, timepts=_tl, inputs=_rl),
                      dict(sys=_SYS, timepts=_SIGNAL[:6], inputs=_SIGNAL[:6])),
    # analysis
    "describing_function": (_an.describing_function, dict(model=_pi(), amplitudes=[0.25, 2.0],
                                                          samples_per_cycle=256, cycles=2),
                            dict(model=_MODEL, amplitudes=_SIGNAL[:6] + [([-1.0], MAYBE), ([0.0], MAYBE)],
                                 samples_per_cycle=_COUNT, cycles=_COUNT)),
    "DescribingFunction": (_an.DescribingFunction, dict(model=_pi(), samples_per_cycle=256, cycles=2),
                           dict(model=_MODEL, samples_per_cycle=_COUNT, cycles=_COUNT)),
    "DescribingFunction()": (lambda A: _an.DescribingFunction(_pi(), 256, 2).describing_function(A),
                             dict(A=1.0), dict(A=_SCALAR[:7])),
    "limit_cycles": (_an.limit_cycles, dict(loop=ct.series(_DSTAGE, _PID), model=_pi(),
                                            amplitudes=np.geomspace(0.01, 10, 20)),
                     dict(loop=_LOOPARG, model=_MODEL, amplitudes=_SIGNAL[:6], omega=_SIGNAL[:6])),
    "Sector": (_an.Sector, dict(lower=1.0, upper=2.0, exact=True),
               dict(lower=_SCALAR[:7], upper=_SCALAR[:7])),
    "slope_bounds": (_an.slope_bounds, dict(model=_pi(), input_range=(-2.0, 2.0), n_samples=200),
                     dict(model=_MODEL, input_range=_LIMITS, compensator=_MODEL[:2] + _MODEL[3:], n_samples=_COUNT)),
    "CircleCriterion": (_an.CircleCriterion, dict(stable=True, sector=(0.0, 1.0), upper_limit=2.0, gain_margin=2.0,
                                                  worst_frequency_hz=1.0, message="ok"), dict()),
    "circle_criterion": (_an.circle_criterion, dict(loop=ct.tf([1], [1, 1]), bounds=(0.0, 100.0), n_frequencies=500),
                         dict(loop=_LOOPARG, bounds=_SECTOR, n_frequencies=_COUNT)),
    # design
    "pid_gains": (_des.pid_gains, dict(plant=_STAGE, crossover_hz=150.0, phase_margin_deg=60.0, dt=1e-4),
                  dict(plant=_PLANT[:4], crossover_hz=_FREQ, phase_margin_deg=_PHASE, actuator_gain=_GAIN, dt=_DT,
                       filter=[("nonsense", NEVER), (1.0, NEVER)], resonance_hz=_FREQ,
                       resonance_damping=_SCALAR[:7] + [(-1.0, NEVER)], filter_hz=_FREQ,
                       filter_damping=_SCALAR[:7] + [(-1.0, NEVER)],
                       integral_ratio=_SCALAR[:7] + [(0.0, NEVER), (-1.0, NEVER)],
                       max_lead_deg=_PHASE)),
    "design_pid": (_des.design_pid, dict(plant=_STAGE, crossover_hz=150.0, phase_margin_deg=60.0, dt=1e-4),
                   dict(plant=_PLANT[:4], crossover_hz=_FREQ, phase_margin_deg=_PHASE, actuator_gain=_GAIN, dt=_DT,
                        filter=[("nonsense", NEVER), (1.0, NEVER)], name=[(1.0, NEVER)])),
    "PIDGains": (_des.PIDGains, dict(kp=1.0, ki=10.0, kd=0.0, tau_d=None, filter=None, filter_hz=None,
                                     filter_damping=None, dt=1e-3, crossover_hz=5.0, phase_margin_deg=60.0),
                 dict()),
    "PIDGains.system": (lambda kp: _des.PIDGains(kp, 10.0, 0.0, None, None, None, None, 1e-3, 5.0, 60.0).system(),
                        dict(kp=1.0), dict(kp=_SCALAR[:7])),
    "Margins": (_des.Margins, dict(gain_margin=2.0, phase_margin_deg=45.0, stability_margin=0.5,
                                   phase_crossover_hz=300.0, crossover_hz=20.0, stability_margin_hz=250.0), dict()),
    "loop_margins": (_des.loop_margins, dict(controller=_PID, plant=_STAGE, actuator_gain=2.7),
                     dict(controller=_PLANT[:4], plant=_PLANT[:4], actuator_gain=_GAIN)),
    "resonance": (_des.resonance, dict(plant=_STAGE), dict(plant=_PLANT)),
    "design_state_feedback": (_des.design_state_feedback, dict(plant=_STAGE, bandwidth_hz=30.0, dt=1e-4),
                              dict(plant=_PLANT[:4], bandwidth_hz=_FREQ, actuator_gain=_GAIN, dt=_DT,
                                   integral_weight=_SCALAR[:7] + [(-1.0, NEVER)],
                                   control_weight=_FREQ, observer_speed=_FREQ)),
    "StateFeedbackDesign": (lambda: _des.design_state_feedback(_STAGE, 30.0, dt=1e-4), dict(), dict()),
    # mismatch
    "identification_input": (_mm.identification_input, dict(input_range=(-2.0, 2.0), n_samples=1000),
                             dict(input_range=_LIMITS, n_samples=_COUNT, n_cycles=_COUNT)),
    "MismatchStudy": (_mm.MismatchStudy, dict(rows=[dict(seed=0, model_rms=0.1, feedforward=0.5)],
                                              nominal=dict(feedforward=0.1), noise=0.01),
                      dict(rows=[("x", NEVER), (1.0, NEVER), ([1.0], NEVER)], nominal=[("x", NEVER), (1.0, NEVER)],
                           noise=_SCALAR[:7] + [(-1.0, NEVER)])),
    "mismatch_study": (_mm.mismatch_study,
                       dict(true_model=PI([0.5, 1.0], [0.3, 0.2], 1.0), plant=_STAGE, controller=_PID,
                            reference=_rl, t=_tl, input_range=(-2.0, 2.0), n_seeds=1, noise=0.0,
                            identification=2.0 * _v[:200]),
                       dict(true_model=_MODEL, plant=_PLANT[:4], controller=_PLANT[:1] + _PLANT[2:4],
                            reference=_SIGNAL[:6], t=_SIGNAL[:6], input_range=_LIMITS, n_seeds=_COUNT[:5],
                            noise=_SCALAR[:7] + [(-1.0, NEVER)], identification=_SIGNAL[:6],
                            fit_options=[("x", NEVER), (1.0, NEVER)])),
    # datasets
    "hidden_effect_data": (_ds.hidden_effect_data, dict(effect="creep", seed=1, dt=0.01, duration=4.0),
                           dict(effect=[("nonsense", NEVER), (1.0, NEVER)], seed=[("x", NEVER), (np.nan, NEVER),
                                                                                  (-1, NEVER), (2.5, NEVER)],
                                dt=_DT + [(0.0, NEVER), (10.0, NEVER)], duration=_DT + [(0.0, NEVER)],
                                noise=_SCALAR[:7] + [(-1.0, NEVER)], amplitude=_FREQ,
                                mechanism=[("nonsense", NEVER), (1.0, NEVER)],
                                experiment=[("x", NEVER), (1.0, NEVER)])),
    "HiddenEffectData": (lambda: _ds.hidden_effect_data("creep", seed=1, dt=0.01, duration=4.0), dict(), dict()),
    # effects
    "lag_bank": (_eff.lag_bank, dict(v=_v, time_constants=[0.1, 1.0], dt=0.01),
                 dict(v=_SIGNAL, time_constants=_TIMES, dt=_DT + [(0.0, NEVER)],
                      state=[([np.nan, 0.0], NEVER), ("ab", NEVER), ([0.0], NEVER), ([np.inf, 0.0], NEVER)])),
    "LinearStage": (_eff.LinearStage, dict(A=[[0.5]], B=[0.5], C=[1.0], D=0.0, dt=1e-3),
                    dict(A=_PLANE[:6] + [([[np.nan]], NEVER)], B=_SIGNAL[:6] + [([1.0, 2.0], NEVER)],
                         C=_SIGNAL[:6] + [([1.0, 2.0], NEVER)], D=_SCALAR[:7], dt=_DT + [(0.0, NEVER)],
                         kind=[(1.0, NEVER)], parameters=[("x", NEVER), (1.0, NEVER)])),
    "LinearStage.lag": (_eff.LinearStage.lag, dict(time_constant=0.01, dt=1e-3),
                        dict(time_constant=_DT + [(0.0, NEVER)], dt=_DT + [(0.0, NEVER)])),
    "LinearStage.resonance": (_eff.LinearStage.resonance, dict(frequency=100.0, damping=0.05, dt=1e-4),
                              dict(frequency=_FREQ, damping=_SCALAR[:7] + [(-1.0, NEVER)],
                                   dt=_DT + [(0.0, NEVER)])),
    "LinearStage.simulate": (lambda v, initial_state=None: _lag().simulate(v, initial_state=initial_state),
                             dict(v=_v), dict(v=_SIGNAL, initial_state=[([np.nan], NEVER), ("ab", NEVER),
                                                                          ([0.0, 0.0, 0.0], NEVER)])),
    "RateDependentPI": (_eff.RateDependentPI, dict(thresholds=[0.5, 1.0], weights=[0.5, 0.25], p0=1.0,
                                                   rate_coefficient=0.01, dt=1e-3),
                        dict(thresholds=_THRESHOLDS, weights=_WEIGHTS, p0=_SCALAR[:7],
                             rate_coefficient=_SCALAR[:7] + [(-1.0, NEVER)], dt=_DT + [(0.0, NEVER)])),
    "RateDependentPI.simulate": (lambda v, initial_state=None: _eff.RateDependentPI(
        [0.5, 1.0], [0.5, 0.25], 1.0, 0.01, 1e-3).simulate(v, initial_state=initial_state),
        dict(v=_v), dict(v=_SIGNAL, initial_state=[([np.nan] * 4, NEVER), ("ab", NEVER), ([0.0], NEVER)])),
    "CreepOperator": (_eff.CreepOperator, dict(time_constants=[0.1, 1.0], coefficients=[0.01, 0.01], dt=0.01),
                      dict(time_constants=_TIMES, coefficients=_WEIGHTS[:6], dt=_DT + [(0.0, NEVER)])),
    "CreepOperator.simulate": (lambda v: _eff.CreepOperator([0.1, 1.0], [0.01, 0.01], 0.01).simulate(v),
                               dict(v=_v), dict(v=_SIGNAL)),
    "DriftTerm": (_eff.DriftTerm, dict(dt=0.5, polynomial=[0.1], amplitudes=[0.1], time_constants=[1.0]),
                  dict(dt=_DT + [(0.0, NEVER)], polynomial=_WEIGHTS[:3] + [([1j], NEVER), ([[1.0]], MAYBE)],
                       amplitudes=_WEIGHTS[:3] + [([1j], NEVER)], time_constants=_TIMES)),
    "DriftTerm.simulate": (lambda v: _eff.DriftTerm(0.5, polynomial=[0.1]).simulate(v), dict(v=_v),
                           dict(v=_SIGNAL)),
    "Series": (lambda a, b: _eff.Series(a, b), dict(a=_pi(), b=_lag()), dict(a=_BLOCK, b=_BLOCK)),
    "Series.simulate": (lambda v: _eff.Series(_pi(), _lag()).simulate(v), dict(v=_v), dict(v=_SIGNAL)),
    "Parallel": (lambda a, b, offset=0.0: _eff.Parallel(a, b, offset=offset), dict(a=_pi(), b=_lag()),
                 dict(a=_BLOCK, b=_BLOCK, offset=_SCALAR[:7])),
    "Parallel.simulate": (lambda v: _eff.Parallel(_pi(), _lag()).simulate(v), dict(v=_v), dict(v=_SIGNAL)),
    # numerical inverse, data
    "NumericalInverse.simulate": (lambda u: hystcomp.NumericalInverse(BacklashLike(1.0, 3.0, 1.0)).simulate(u),
                                  dict(u=_v[:50]), dict(u=_SIGNAL)),
    "load_piezo": (_data.load_piezo, dict(), dict()),
    # plotting
    "new_figure": (_closing(_plot.new_figure), dict(), dict(nrows=_COUNT[:5], ncols=_COUNT[:5],
                                                            size=_LIMITS[1:] + [((0.0, 1.0), NEVER)])),
    "plot_loop": (_closing(_plot.plot_loop), dict(v=_v, w=_y), dict(v=_FIGURE_ARRAY, w=_FIGURE_ARRAY + [(_y[:5], NEVER)],
                                                                     ax=[("x", NEVER), (1.0, NEVER)])),
    "plot_operators": (_closing(_plot.plot_operators), dict(v=_v, W=np.c_[_v, _v], thresholds=[0.5, 1.0]),
                       dict(v=_FIGURE_ARRAY, W=_PLANE[:3] + [(np.zeros((3, 2)), NEVER)],
                            thresholds=_THRESHOLDS[:5], select=[("x", NEVER), ([5], NEVER)])),
    "plot_compensation": (_closing(_plot.plot_compensation), dict(t=_t, u=_v, v=_v, w=_y),
                          dict(t=_FIGURE_ARRAY, u=_FIGURE_ARRAY, v=_FIGURE_ARRAY, w=_FIGURE_ARRAY + [(_y[:5], NEVER)])),
    "plot_loading_curve": (_closing(_plot.plot_loading_curve), dict(r=_t, simulated=_v, analytic=_v),
                           dict(r=_FIGURE_ARRAY, simulated=_FIGURE_ARRAY, analytic=_FIGURE_ARRAY)),
    # demo
    "demo_actuator": (_demo.demo_actuator, dict(), dict()),
    "reference": (_demo.reference, dict(t=_t), dict(t=_SIGNAL[:3] + _SIGNAL[4:6], freq_hz=_SCALAR[:7], amplitude=_SCALAR[:7])),
    "stability_table": (_demo.stability_table, dict(kp=0.0, ki=150.0, kd=0.0, dt=1e-4, gains=[1.0, 2.7],
                                                    plant=_STAGE),
                        dict(kp=_SCALAR[:7], ki=_SCALAR[:7], kd=_SCALAR[:7], dt=_DT, gains=_SIGNAL[:6] + [([], NEVER)],
                             plant=_PLANT[:4])),
    "crossover_scan": (_demo.crossover_scan, dict(plant=_STAGE, dt=1e-4, nominal_gain=2.7,
                                                  sectors={"PI": (1.0, 3.0)}, crossovers_hz=[20.0, 40.0],
                                                  n_frequencies=400),
                       dict(plant=_PLANT[:4], dt=_DT, nominal_gain=_GAIN,
                            sectors=[("x", NEVER), (1.0, NEVER), ({"PI": (3.0, 1.0)}, NEVER)],
                            crossovers_hz=_SIGNAL[:6] + [([], NEVER), ([-1.0], NEVER)], phase_margin_deg=_PHASE,
                            rolloff_factor=_FREQ, n_frequencies=_COUNT)),
    # thesis
    "time_vector": (_th.time_vector, dict(t_end=1.0, dt=0.01), dict(t_end=_SCALAR[:7] + [(-1.0, NEVER)],
                                                                     dt=_DT + [(0.0, NEVER)])),
    "density": (_th.density, dict(r=[0.5, 1.0]), dict(r=_SIGNAL[:3] + _SIGNAL[4:6])),
    "loading_curve_error_bound": (_th.loading_curve_error_bound, dict(spacing=0.5, r=1.0),
                                  dict(spacing=_FREQ, r=_SCALAR[:7] + [(-1.0, NEVER)])),
    "mgpi_bound": (_th.mgpi_bound, dict(), dict(spacing=_FREQ, R=_FREQ + [(0.1, NEVER)], U=_SCALAR[:7],
                                              p0=_SCALAR[:7])),
    "mgpi_bound_limit": (_th.mgpi_bound_limit, dict(), dict(R=_SCALAR[:7] + [(-1.0, NEVER)], U=_SCALAR[:7],
                                                          p0=_SCALAR[:7])),
    "section_4_1": (_th.section_4_1, dict(spacing=0.5, R=2.0, dt=0.05), dict(spacing=_FREQ, R=_FREQ,
                                                                           dt=_DT + [(0.0, NEVER)])),
    "figure_2_1": (_th.figure_2_1, dict(dt=0.05), dict(dt=_DT + [(0.0, NEVER)])),
    "section_5": (_th.section_5, dict(name="5.2", dt=0.05), dict(name=_CHOICE, dt=_DT + [(0.0, NEVER)])),
    "loading_curve_deviation": (_th.loading_curve_deviation,
                                dict(case=_th.section_4_1(spacing=0.5, R=2.0, dt=0.05), n_points=101),
                                dict(case=[("x", NEVER), (None, NEVER), (1.0, NEVER)], n_points=_COUNT)),
}
CASES.update(_case)

NOT_COVERED.update({
    "Comparison": "result object (built by compare)",
    "Loop": "result object (built by build_loop; Loop.simulate covered)",
    "add_arguments": "CLI plumbing: tests/test_cli_errors.py drives it with bad options",
    "run": "CLI plumbing: tests/test_cli_errors.py drives it with bad options",
    "main": "CLI entry: tests/test_cli_errors.py drives it with bad options and files",
    "thesis_figures": "2-3 s per call even at dt = 0.05 (every thesis figure); its dt goes to the covered "
                      "thesis sections",
    "compensation_errors": "about 3 s per call even at dt = 0.05 (every chapter-5 section); section_5 covered",
    "ThesisCase": "result object (built by the section functions)",
})
_THESIS_DT = _DT + [(0.0, NEVER)]
CASES.update({
    "section_3_4_3": (_th.section_3_4_3, dict(envelope_set=1, dt=0.05),
                      dict(envelope_set=[(0, NEVER), ("1", NEVER), (None, NEVER), (1.5, NEVER)], dt=_THESIS_DT)),
    "section_3_5": (_th.section_3_5, dict(dt=0.05), dict(dt=_THESIS_DT)),
    "section_5_2": (_th.section_5_2, dict(dt=0.05), dict(dt=_THESIS_DT)),
    "section_5_3": (_th.section_5_3, dict(dt=0.05), dict(dt=_THESIS_DT)),
    "section_5_4": (_th.section_5_4, dict(dt=0.05), dict(dt=_THESIS_DT)),
})


# methods of the model parts, envelopes and plane models (beyond constructors and simulate)
_BOUNDS = [((1.0, -1.0), NEVER), ((0.0, np.nan), NEVER), ("ab", NEVER), (1.0, NEVER), ((1.0,), NEVER),
           ((-np.inf, np.inf), MAYBE)]
CASES.update({
    "LinearStage.output_bounds": (lambda input_bounds: _lag().output_bounds(input_bounds),
                                  dict(input_bounds=(-1.0, 1.0)), dict(input_bounds=_BOUNDS)),
    "LinearStage.l1_gain": (lambda n=None: _lag().l1_gain(n), dict(), dict(n=_COUNT[:4] + _COUNT[5:])),
    "LinearStage.filter_columns": (lambda U, states=None: _lag().filter_columns(U, states), dict(U=np.ones((5, 2))),
                                   dict(U=_PLANE[:4] + _PLANE[5:6], states=[("ab", NEVER), ([[np.nan], [0.0]], NEVER),
                                                              ([1.0], NEVER), (np.zeros((3, 1)), NEVER)])),
    "CreepOperator.output_bounds": (lambda input_bounds: _eff.CreepOperator([0.1], [0.01], 0.01).output_bounds(
        input_bounds), dict(input_bounds=(-1.0, 1.0)), dict(input_bounds=_BOUNDS)),
    "DriftTerm.trend": (lambda t: _eff.DriftTerm(0.5, [0.1]).trend(t), dict(t=[0.0, 1.0]),
                        dict(t=[_SIGNAL[k] for k in (0, 2, 4, 5)])),     # t = inf is the final value
    "Series.simulate(initial_state)": (lambda initial_state: _eff.Series(_pi(), _lag()).simulate(
        [0.0, 1.0], initial_state=initial_state), dict(initial_state=None),
        dict(initial_state=[([np.nan, 0.0, 0.0], NEVER), ("ab", NEVER), ([0.0], NEVER)])),
    "RateDependentPI.play_positions": (lambda v: _eff.RateDependentPI([0.5], [0.5], 1.0, 0.01, 1e-3).play_positions(v),
                                       dict(v=_v), dict(v=_SIGNAL)),
    "PI.simulate_batch": (lambda weights, p0=None: _pi().simulate_batch(_v, weights, p0), dict(weights=[[0.4, 0.2]]),
                          dict(weights=_PLANE[:3] + _PLANE[4:6], p0=_SCALAR[:5] + _SCALAR[6:7])),
    "Preisach.level": (lambda v: Preisach((-1.0, 1.0), np.tril(np.ones((3, 3)))).level(v), dict(v=0.0),
                       dict(v=[(np.nan, NEVER), ("abc", NEVER), (1 + 1j, NEVER), (object(), NEVER),
                               (np.inf, MAYBE), ([1.0, 2.0], MAYBE)])),
    "Envelope.__call__": (lambda v: Atanh(1.0, 0.5)(v), dict(v=[0.5]), dict(v=_SIGNAL[:6] + [([3.0], NEVER)])),
    "Envelope.derivative": (lambda v: Atanh(1.0, 0.5).derivative(v), dict(v=[0.5]),
                            dict(v=_SIGNAL[:6] + [([3.0], NEVER)])),
    "Envelope.inverse": (lambda y: Tanh(2.0, 1.0).inverse(y), dict(y=[0.5]),
                         dict(y=_SIGNAL[:3] + _SIGNAL[4:6] + [([3.0], NEVER)])),
    "Polynomial.inverse": (lambda y: Polynomial([0.0, 1.0], interval=(0.0, 10.0)).inverse(y), dict(y=[0.5]),
                           dict(y=_SIGNAL[:3] + _SIGNAL[4:6] + [([11.0], NEVER)])),
})


def _public_callables():
    names = set()
    for modname in MODULES:
        mod = importlib.import_module(modname)
        for name in getattr(mod, "__all__", []):
            obj = getattr(mod, name)
            if callable(obj) and not (isinstance(obj, type) and issubclass(obj, BaseException)):
                names.add(f"{modname}.{name}")
    return sorted(names)


def _has_nan(x):
    if isinstance(x, (float, np.floating)):
        return bool(np.isnan(x))
    if isinstance(x, np.ndarray) and x.dtype.kind in "fc":
        return bool(np.isnan(x).any())
    if isinstance(x, (tuple, list)):
        return any(_has_nan(e) for e in x)
    return False


def _check(call, kwargs, arg, bad, kind):
    """'' when the behaviour is right, else what went wrong."""
    kw = dict(kwargs)
    kw[arg] = bad
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            out = call(**kw)
    except (ValueError, TypeError) as exc:
        msg = str(exc)
        if arg in msg:
            return ""
        return f"{type(exc).__name__} not naming {arg!r}: {msg[:120]}"
    except Exception as exc:  # noqa: BLE001 - any other type is the defect being looked for
        return f"{type(exc).__name__}: {str(exc)[:120]}"
    if kind == NEVER:
        return "accepted"
    if _has_nan(out):
        return "NaN in the result"
    return ""


@pytest.mark.parametrize("name", sorted(CASES))
def test_bad_values_raise_naming_the_argument(name):
    call, kwargs, table = CASES[name]
    call(**kwargs)   # the valid call works
    problems = []
    for arg, values in table.items():
        for bad, kind in values:
            what = _check(call, kwargs, arg, bad, kind)
            if what:
                problems.append(f"{name}({arg}={bad!r}): {what}")
    known = KNOWN_DEFECTS.get(name, set())
    found = {p.split(": ", 1)[0] for p in problems}
    # a listed defect that is fixed must leave the list; a new one must not appear
    assert found == known, "\n".join(problems) or f"fixed, remove from KNOWN_DEFECTS: {sorted(known)}"


def test_every_public_callable_is_covered_or_listed():
    covered = set(NOT_COVERED)
    for name in CASES:
        covered.add(name.split(".")[0])
    missing = [n for n in _public_callables() if n.rsplit(".", 1)[1] not in covered]
    assert not missing, f"public callables neither in CASES nor in NOT_COVERED: {missing}"


#: defects the harness finds that are not fixed yet (listed in the report of
#: issue 12; each entry is "name(arg=value)"): the test fails when one is
#: fixed (remove it here) or a new one appears
KNOWN_DEFECTS = {}

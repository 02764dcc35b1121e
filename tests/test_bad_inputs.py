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
    "fit_weights": (_idf.fit_weights, dict(v=_v, y=_y, thresholds=[0.5, 1.0], model="pi"),
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

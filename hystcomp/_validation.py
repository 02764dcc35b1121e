"""Input checking shared by every public entry point.

Gathered here (as SciPy does) so that the numerical code reads cleanly and
every error names the argument, the value received and what was expected.
"""

import numpy as np

__all__ = []


def as_float_array(x, name):
    """`x` as a float64 array; TypeError naming `name` for strings, complex
    numbers or objects that are not numbers (instead of numpy's message)."""
    if isinstance(x, (str, bytes)):
        raise TypeError(f"Parameter {name} is {x!r} but should be numbers, not a string")
    try:
        if np.iscomplexobj(x):
            raise TypeError(f"Parameter {name} holds complex numbers but should be real numbers")
        return np.asarray(x, dtype=np.float64)
    except (TypeError, ValueError) as exc:
        if str(exc).startswith(f"Parameter {name}"):
            raise
        raise TypeError(
            f"Parameter {name} is {x!r} but should be real numbers ({exc})"
        ) from None


def as_signal(x, name="v", min_length=1, finite=True):
    """Return `x` as a contiguous 1-D float64 array with finite samples.

    `finite` False skips the test of the samples: for a caller whose
    compiled kernel finds the first non-finite sample in its own pass and
    raises `non_finite_error` before returning anything.

    Raises
    ------
    ValueError
        If `x` is not 1-D, too short, or holds NaN or inf (the message names
        the first offending sample index).
    """
    arr = np.ascontiguousarray(as_float_array(x, name))
    if arr.ndim == 0:
        arr = arr.reshape(1)
    if arr.ndim != 1:
        raise ValueError(
            f"Parameter {name} has shape {arr.shape} but should be a 1-D array of samples"
        )
    if arr.size < min_length:
        raise ValueError(
            f"Parameter {name} has {arr.size} samples but at least {min_length} are needed"
        )
    if finite:
        bad = ~np.isfinite(arr)
        if bad.any():
            raise non_finite_error(arr, int(np.argmax(bad)), name)
    return arr


def non_finite_error(arr, k, name="v"):
    """The ValueError of `as_signal` for the non-finite sample ``arr[k]``."""
    return ValueError(
        f"Parameter {name} holds a non-finite value ({arr[k]}) at sample index {k}; "
        "expected finite numbers"
    )


def as_thresholds(thresholds, name="thresholds", allow_zero=False):
    """Thresholds r_1 < ... < r_N, all > 0 (or >= 0 when `allow_zero`)."""
    r = np.ascontiguousarray(as_float_array(thresholds, name).reshape(-1))
    if r.size == 0:
        raise ValueError(f"Parameter {name} is empty; expected at least one threshold")
    if not np.all(np.isfinite(r)):
        k = int(np.argmax(~np.isfinite(r)))
        raise ValueError(f"Parameter {name} holds a non-finite value ({r[k]}) at index {k}")
    if allow_zero:
        if r[0] < 0:
            raise ValueError(f"Parameter {name} starts at {r[0]} but thresholds must be >= 0")
    elif r[0] <= 0:
        raise ValueError(
            f"Parameter {name} starts at {r[0]} but thresholds r_1..r_N must be > 0 "
            "(the r = 0 operator is weighted by p0, eq. 49)"
        )
    d = np.diff(r)
    if np.any(d <= 0):
        k = int(np.argmax(d <= 0)) + 1
        raise ValueError(
            f"Parameter {name} is not strictly increasing: {name}[{k}] = {r[k]} "
            f"follows {name}[{k - 1}] = {r[k - 1]}"
        )
    return r


def as_weights(weights, n, name="weights"):
    """Weights p_1..p_N: finite, one per threshold."""
    p = np.ascontiguousarray(as_float_array(weights, name).reshape(-1))
    if p.size != n:
        raise ValueError(
            f"Parameter {name} has {p.size} entries but there are {n} thresholds; "
            "expected one weight per threshold"
        )
    if not np.all(np.isfinite(p)):
        k = int(np.argmax(~np.isfinite(p)))
        raise ValueError(f"Parameter {name} holds a non-finite value ({p[k]}) at index {k}")
    return p


def as_scalar(x, name, positive=False, nonnegative=False):
    try:
        val = float(x)
    except (TypeError, ValueError):
        raise TypeError(f"Parameter {name} is {x!r} but should be a real number") from None
    if not np.isfinite(val):
        raise ValueError(f"Parameter {name} is {val} but should be finite")
    if positive and val <= 0:
        raise ValueError(f"Parameter {name} is {val} but should be > 0")
    if nonnegative and val < 0:
        raise ValueError(f"Parameter {name} is {val} but should be >= 0")
    return val


def as_state(state, n, name="initial_state", virgin=None):
    """An explicit operator state: a finite 1-D array of length `n` (copied).

    An infinite entry is accepted only where the model's own virgin state
    `virgin` holds the same value (a symmetric mGPI's play sitting at an
    infinite end of gamma's domain), so that ``default_state()`` passed
    back is accepted.
    """
    s = np.array(as_float_array(state, name), dtype=np.float64).reshape(-1)
    if s.size != n:
        raise ValueError(
            f"Parameter {name} has {s.size} entries but this model has {n} states"
        )
    if np.isnan(s).any():
        k = int(np.argmax(np.isnan(s)))
        raise ValueError(f"Parameter {name} holds NaN at index {k}")
    bad = np.isinf(s)
    if virgin is not None and bad.any():
        bad &= ~(np.asarray(virgin, dtype=np.float64).reshape(-1) == s)
    if bad.any():
        k = int(np.argmax(bad))
        raise ValueError(
            f"Parameter {name} holds {s[k]} at index {k}; expected finite numbers"
        )
    return s


def check_choice(value, name, choices):
    if value not in choices:
        raise ValueError(
            f"Parameter {name} is {value!r} but should be one of "
            + ", ".join(repr(c) for c in choices)
        )
    return value


def as_choices(value, name, choices):
    """A list of names, each one of `choices`: a single name or an iterable of
    them; None gives every choice, in order.

    Examples
    --------
    >>> as_choices("a", "names", ("a", "b")), as_choices(None, "names", ("a", "b"))
    (['a'], ['a', 'b'])
    """
    if value is None:
        return list(choices)
    if isinstance(value, str):
        value = [value]
    try:
        names = list(value)
    except TypeError:
        raise TypeError(f"Parameter {name} is {value!r} but should be a name or an iterable of names "
                        f"from {list(choices)}") from None
    for n in names:
        check_choice(n, name, choices)
    return names


def check_output_folder(path, name="out"):
    """Make sure `path` is (or can be created as) a writable folder; created if missing.

    Called before long work starts, so that a bad output folder fails at once.

    Raises
    ------
    ValueError
        If `path` is an existing file, cannot be created or is not writable
        (the message names the argument and the path).
    """
    import os

    path = os.fspath(path)
    if not path:
        raise ValueError(f"Parameter {name} is an empty path; expected a folder")
    if os.path.exists(path) and not os.path.isdir(path):
        raise ValueError(
            f"Parameter {name} is {path!r}, an existing file; expected a folder "
            "(created if missing)"
        )
    try:
        os.makedirs(path, exist_ok=True)
    except OSError as exc:
        raise ValueError(
            f"Parameter {name} is {path!r}: cannot create the folder ({exc.strerror or exc})"
        ) from None
    if not os.access(path, os.W_OK | os.X_OK):
        raise ValueError(f"Parameter {name} is {path!r}: the folder is not writable")
    return path


def check_simulates(obj, name):
    """TypeError naming `name` unless `obj` has a callable ``simulate`` (a model
    or compensator of this package, or one following its protocol)."""
    if not callable(getattr(obj, "simulate", None)):
        raise TypeError(
            f"Parameter {name} is {obj!r} ({type(obj).__name__}) but should be a model or "
            "compensator with a simulate(x) method"
        )
    return obj


def as_count(x, name, minimum=0):
    """`x` as an int >= `minimum`; TypeError for non-integers (2.5, NaN,
    strings, None), ValueError naming `name` below `minimum`.  An integral
    float (``2048.0``) is accepted."""
    if isinstance(x, (bool, np.bool_)):
        raise TypeError(f"Parameter {name} is {x!r} but should be an integer")
    if isinstance(x, (int, np.integer)):
        val = int(x)
    elif isinstance(x, (float, np.floating)) and np.isfinite(x) and float(x).is_integer():
        val = int(x)
    else:
        raise TypeError(f"Parameter {name} is {x!r} but should be an integer")
    if val < minimum:
        raise ValueError(f"Parameter {name} is {val} but should be >= {minimum}")
    return val


def as_vector(x, name, min_length=1, positive=False, nonnegative=False, increasing=False):
    """`x` as a finite 1-D float64 array (a scalar becomes length 1), with
    optional sign and ordering checks; errors name `name`."""
    arr = as_signal(x, name, min_length=min_length)
    if positive and np.any(arr <= 0):
        k = int(np.argmax(arr <= 0))
        raise ValueError(f"Parameter {name} holds {arr[k]} at index {k} but should hold values > 0")
    if nonnegative and np.any(arr < 0):
        k = int(np.argmax(arr < 0))
        raise ValueError(f"Parameter {name} holds {arr[k]} at index {k} but should hold values >= 0")
    if increasing and np.any(np.diff(arr) <= 0):
        k = int(np.argmax(np.diff(arr) <= 0)) + 1
        raise ValueError(f"Parameter {name} is not strictly increasing: {name}[{k}] = {arr[k]} "
                         f"follows {name}[{k - 1}] = {arr[k - 1]}")
    return arr


def as_pair(x, name, increasing=True):
    """`x` as two finite floats (lo, hi), lo < hi when `increasing`."""
    if isinstance(x, (str, bytes)):
        raise TypeError(f"Parameter {name} is {x!r} but should be a pair of numbers (lo, hi)")
    try:
        items = list(x)
    except TypeError:
        raise TypeError(f"Parameter {name} is {x!r} but should be a pair of numbers (lo, hi)") from None
    if len(items) != 2:
        raise ValueError(f"Parameter {name} is {x!r} but should be a pair of numbers (lo, hi)")
    lo, hi = (as_scalar(v, name) for v in items)
    if increasing and not lo < hi:
        raise ValueError(f"Parameter {name} is {x!r} but should have lo < hi")
    return lo, hi


def as_bounds(x, name):
    """`x` as (lo, hi) with lo <= hi, each a float that may be infinite but not NaN."""
    if isinstance(x, (str, bytes)):
        raise TypeError(f"Parameter {name} is {x!r} but should be a pair of numbers (lo, hi)")
    try:
        items = list(x)
    except TypeError:
        raise TypeError(f"Parameter {name} is {x!r} but should be a pair of numbers (lo, hi)") from None
    if len(items) != 2:
        raise ValueError(f"Parameter {name} is {x!r} but should be a pair of numbers (lo, hi)")
    try:
        lo, hi = float(items[0]), float(items[1])
    except (TypeError, ValueError):
        raise TypeError(f"Parameter {name} is {x!r} but should be a pair of real numbers (lo, hi)") from None
    if np.isnan(lo) or np.isnan(hi) or lo > hi:
        raise ValueError(f"Parameter {name} is {x!r} but should be (lo, hi) with lo <= hi, not NaN")
    return lo, hi

"""Input checking of identification records (one or several (v, y) records, weights, held-out masks)."""


import datetime

import numpy as np

from .._validation import as_scalar, as_signal


#: samples per block when accumulating the Gram matrix
_BLOCK = 8192
#: lower bound of p0 (and of the partial sums) in scaled units: the p0
#: operator's contribution must be at least this fraction of the output RMS
_EPS = 1e-6


# ----------------------------------------------------------------------------
# input checking
# ----------------------------------------------------------------------------
def _is_record_list(x):
    if isinstance(x, (list, tuple)) and len(x) > 0:
        return all(np.ndim(e) == 1 for e in x)
    return False


def _records(v, y, sample_weight):
    """Lists of checked records (v_j, y_j, w_j)."""
    multi = _is_record_list(v)
    if multi != _is_record_list(y):
        raise ValueError(
            "Parameters v and y must both be arrays or both be lists of records; got "
            f"{type(v).__name__} and {type(y).__name__}"
        )
    vs = list(v) if multi else [v]
    ys = list(y) if multi else [y]
    if len(vs) != len(ys):
        raise ValueError(f"Parameter y has {len(ys)} records but v has {len(vs)}; expected one per record")
    if sample_weight is None:
        ws = [None] * len(vs)
    else:
        ws = list(sample_weight) if multi else [sample_weight]
        if len(ws) != len(vs):
            raise ValueError(
                f"Parameter sample_weight has {len(ws)} records but v has {len(vs)}; expected one per record"
            )
    out = []
    for j, (vj, yj, wj) in enumerate(zip(vs, ys, ws)):
        sfx = f"[{j}]" if multi else ""
        vj = as_signal(vj, "v" + sfx, min_length=1)
        yj = as_signal(yj, "y" + sfx, min_length=1)
        if vj.size != yj.size:
            raise ValueError(
                f"Parameter y{sfx} has {yj.size} samples but v{sfx} has {vj.size}; expected equal lengths"
            )
        if wj is not None:
            wj = as_signal(wj, "sample_weight" + sfx)
            if wj.size != vj.size:
                raise ValueError(
                    f"Parameter sample_weight{sfx} has {wj.size} samples but v{sfx} has {vj.size}; "
                    "expected equal lengths"
                )
            if np.any(wj < 0):
                k = int(np.argmax(wj < 0))
                raise ValueError(
                    f"Parameter sample_weight{sfx} is {wj[k]} at sample index {k}; expected weights >= 0"
                )
        out.append([vj, yj, wj])
    return out, multi


def _apply_validation(recs, validation, multi):
    """Zero the training weight of held-out samples; return the held-out masks
    (or separate validation records)."""
    if validation is None:
        return None, None
    if isinstance(validation, tuple) and len(validation) == 2:
        return None, validation
    if np.ndim(validation) == 0 and not isinstance(validation, (bool, np.bool_)):
        frac = as_scalar(validation, "validation")
        if not 0.0 < frac < 1.0:
            raise ValueError(
                f"Parameter validation is {frac} but a fraction must be in (0, 1) "
                "(the last part of each record is held out)"
            )
        masks = []
        for vj, _, _ in recs:
            m = np.zeros(vj.size, bool)
            m[int(round(vj.size * (1.0 - frac))):] = True
            masks.append(m)
    else:
        ms = list(validation) if multi else [validation]
        if len(ms) != len(recs):
            raise ValueError(f"Parameter validation has {len(ms)} masks but there are {len(recs)} records")
        masks = []
        for j, (m, (vj, _, _)) in enumerate(zip(ms, recs)):
            m = np.asarray(m)
            if m.dtype != bool or m.shape != vj.shape:
                raise ValueError(
                    f"Parameter validation[{j}] has dtype {m.dtype} and shape {m.shape}; expected a "
                    f"boolean mask of shape {vj.shape} (True = held out), a fraction or (v, y)"
                )
            masks.append(m)
    for rec, m in zip(recs, masks):
        w = np.ones(rec[0].size) if rec[2] is None else rec[2].copy()
        w[m] = 0.0
        rec[2] = w
    return masks, None


# ----------------------------------------------------------------------------


# ----------------------------------------------------------------------------
# pandas data in and out (imported lazily: array calls never load pandas)
# ----------------------------------------------------------------------------
def _is_frame(x):
    """True for a pandas DataFrame (checked without importing pandas)."""
    return type(x).__module__.startswith("pandas") and hasattr(x, "columns") and hasattr(x, "index")


def _is_series(x):
    """True for a pandas Series or Index (checked without importing pandas)."""
    return (type(x).__module__.startswith("pandas") and getattr(x, "ndim", 0) == 1
            and not hasattr(x, "columns"))


def _seconds(t, name="t"):
    """A datetime or timedelta time axis as float seconds from its first
    sample (numpy datetime64/timedelta64 arrays, pandas Series/Index, with or
    without a time zone); anything else is returned unchanged.

    Raises
    ------
    ValueError
        For a missing time (NaT), naming the sample.
    """
    if t is None:
        return None
    dtype = getattr(t, "dtype", None)
    kind = getattr(dtype, "kind", None)
    tz = getattr(dtype, "tz", None)
    if kind == "O" and np.ndim(t) == 1 and len(t) and _is_time_object(t[0]):
        import pandas as pd       # datetime objects (e.g. tz-aware timestamps in an object array)

        conv = pd.to_timedelta if isinstance(t[0], datetime.timedelta) else pd.to_datetime
        t = conv(np.asarray(t)) if conv is pd.to_timedelta else conv(np.asarray(t), utc=True)
        dtype, kind, tz = t.dtype, t.dtype.kind, getattr(t.dtype, "tz", None)
    if kind not in ("M", "m") and tz is None:
        return t
    if _is_series(t):
        t = t.to_numpy()    # tz-aware values become UTC datetime64
        if t.dtype.kind == "O":          # tz-aware Index -> Timestamp objects
            import pandas as pd

            t = pd.to_datetime(t, utc=True).tz_localize(None).to_numpy()
    t = np.asarray(t)
    if t.ndim != 1 or t.size == 0:
        raise ValueError(f"Parameter {name} has shape {t.shape} but should be a 1-D array of times")
    bad = np.isnat(t)
    if bad.any():
        k = int(np.argmax(bad))
        raise ValueError(f"Parameter {name} holds a missing time (NaT) at sample index {k}; "
                         "expected a time for every sample")
    return (t - t[0]) / np.timedelta64(1, "s")


def _is_time_object(x):
    return isinstance(x, (datetime.datetime, datetime.timedelta, np.datetime64, np.timedelta64))


def _column(data, key, arg, what="data"):
    """Column `key` of a DataFrame (`arg` names the keyword that chose it);
    the index when `key` is the index's name and not a column."""
    if key in data.columns:
        return data[key]
    if key is not None and key == data.index.name:
        return data.index.to_series(index=data.index)
    raise ValueError(f"Parameter {arg} is {key!r} but the DataFrame {what} has no such column "
                     f"(columns: {', '.join(map(str, data.columns))})")


def _frame_record(data, time, input, output, v=None, y=None, what="data"):
    """(t, v, y, index) of a DataFrame record: the columns named by
    `time` (None: no time axis; a datetime or timedelta column becomes
    seconds from the first sample), `input` and `output`, as float arrays.
    A frame excludes separate v and y arguments."""
    if v is not None or y is not None:
        raise TypeError(f"Parameter {what} is a DataFrame, so v and y must not be given; name its "
                        "columns with input= and output= instead")
    t = None if time is None else _numbers(_seconds(_column(data, time, "time", what), "time"), "time", time)
    vv = _numbers(_column(data, input, "input", what), "input", input)
    yy = _numbers(_column(data, output, "output", what), "output", output)
    return t, vv, yy, data.index


def _numbers(col, arg, key):
    """A column as float64 (missing values as NaN, which the checks then
    name); TypeError naming the column for text."""
    if not _is_series(col):
        return col
    try:
        return col.to_numpy(dtype=np.float64, na_value=np.nan)
    except (TypeError, ValueError):
        raise TypeError(f"Parameter {arg} is {key!r} but that column holds {col.dtype} values; expected "
                        "numbers") from None


def _index_of(*xs):
    """The index of the first pandas Series/DataFrame among `xs` (None if none)."""
    for x in xs:
        if _is_frame(x) or (_is_series(x) and hasattr(x, "index") and not hasattr(x, "levels")
                            and type(x).__name__ == "Series"):
            return x.index
    return None


def _with_index(arr, index, name=None):
    """`arr` as a pandas Series on `index` (unchanged without an index or on
    a length mismatch)."""
    if index is None or np.ndim(arr) != 1 or len(index) != len(arr):
        return arr
    import pandas as pd

    return pd.Series(arr, index=index, name=name)


def _frame_arguments(v, y, input, output):
    """(v, y, index) with DataFrame records unpacked: a frame (or a list
    of frames, one per record) as `v` gives its `input` and `output`
    columns; Series keep their index (returned, None for plain arrays;
    a list of indexes for several records)."""
    if _is_frame(v):
        _, vv, yy, index = _frame_record(v, None, input, output, None, y, what="v")
        return vv, yy, index
    if isinstance(v, (list, tuple)) and v and all(_is_frame(e) for e in v):
        if y is not None:
            raise TypeError("Parameter v is a list of DataFrames, so y must not be given; name the "
                            "columns with input= and output= instead")
        recs = [_frame_record(e, None, input, output, what=f"v[{j}]") for j, e in enumerate(v)]
        return [r[1] for r in recs], [r[2] for r in recs], [r[3] for r in recs]
    if y is None:
        raise TypeError("Parameter y is missing; pass (v, y) arrays or a DataFrame with input= and "
                        "output= columns")
    if _is_record_list(v) and isinstance(y, (list, tuple)):
        idx = [_index_of(a, b) for a, b in zip(v, y)]
        return v, y, (idx if any(i is not None for i in idx) else None)
    return v, y, _index_of(v, y)

"""Input checking of identification records (one or several (v, y) records, weights, held-out masks)."""


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

"""Batch simulation: many signals through one model, or one signal through
many models that differ only in their weights (a Monte Carlo over the
density).

The operator states of the Prandtl-Ishlinskii family do not depend on the
weights: the output is a weighted sum of operator outputs (eq. 18, 25).  So a
batch of models that differ only in weights runs the plays once, block by
block in a compiled kernel, and forms every model's output with one
matrix product per block (BLAS).  Memory stays O(block x (operators +
models)) besides the (samples x models) result.
"""

import numpy as np

from ._validation import as_signal, as_state

_BLOCK = 4096


def simulate_columns(model, v, initial_state=None, return_state=False):
    """``model.simulate`` for a 2-D input, one signal per column.

    Each column starts from its own state: `initial_state` of shape
    ``(m, n_states)`` or None (virgin state for every column).
    """
    V = np.asarray(v, dtype=np.float64)
    n, m = V.shape
    if m == 0 or n == 0:
        raise ValueError(f"Parameter v has shape {V.shape} but should hold at least one sample "
                         "and one signal (samples x signals)")
    if initial_state is not None:
        S0 = np.asarray(initial_state, dtype=np.float64)
        if S0.shape != (m, model.n_states):
            raise ValueError(
                f"Parameter initial_state has shape {S0.shape} but a {V.shape} input (samples x signals) "
                f"needs shape ({m}, {model.n_states}): one state per signal")
    Y = np.empty((n, m))
    states = np.empty((m, model.n_states))
    for j in range(m):
        x = as_signal(V[:, j], f"v[:, {j}]")
        model._check_input_domain(x, finite=True)
        st = model.default_state() if initial_state is None else as_state(S0[j], model.n_states, f"initial_state[{j}]")
        Y[:, j] = model._simulate(x, st)
        states[j] = st
    return (Y, states) if return_state else Y


def batch_weights(model, weights, p0):
    """Validated ``(W, p0s)``: W of shape (m, N) and p0s of shape (m,)."""
    N = model._p.size
    W = np.asarray(weights, dtype=np.float64)
    if W.ndim == 1 and W.size == N:
        W = W.reshape(1, N)
    if W.ndim != 2 or W.shape[1] != N:
        raise ValueError(f"Parameter weights has shape {np.shape(weights)} but should have shape "
                         f"(models, {N}): one row of {N} operator weights per model")
    if W.shape[0] == 0:
        raise ValueError("Parameter weights has no rows but should hold at least one model's weights")
    if not np.isfinite(W).all():
        raise ValueError("Parameter weights holds NaN or inf but should be finite")
    m = W.shape[0]
    has_p0 = getattr(model, "p0", None) is not None
    if p0 is None:
        p0s = np.full(m, float(model.p0) if has_p0 else 1.0)  # GPI: H enters with weight 1
    else:
        if not has_p0:
            raise ValueError(f"Parameter p0 is {p0!r} but {type(model).__name__} has no p0 weight")
        p0s = np.asarray(p0, dtype=np.float64)
        if p0s.ndim == 0:
            p0s = np.full(m, float(p0s))
        if p0s.shape != (m,):
            raise ValueError(f"Parameter p0 has shape {np.shape(p0)} but should be a scalar or have "
                             f"shape ({m},): one p0 per row of weights")
        if not np.isfinite(p0s).all():
            raise ValueError("Parameter p0 holds NaN or inf but should be finite")
    return np.ascontiguousarray(W), p0s


def simulate_batch(model, v, weights, p0=None, initial_state=None, return_state=False):
    """Outputs of the models ``model`` with weights replaced by each row of
    `weights` (and p0 by `p0`), shape (n, m).  See
    :meth:`hystcomp.models.HysteresisModel.simulate_batch`."""
    x = as_signal(v, "v")
    model._check_input_domain(x, finite=True)
    W, p0s = batch_weights(model, weights, p0)
    state = model.default_state() if initial_state is None else as_state(initial_state, model.n_states)
    Y = np.empty((x.size, W.shape[0]))
    # one product per block: [memoryless column, operator outputs] @ [p0; W^T]
    WT = np.ascontiguousarray(np.vstack([p0s[None, :], W.T]))
    ext = np.empty((min(_BLOCK, x.size), W.shape[1] + 1))
    for s in range(0, x.size, _BLOCK):
        xs = x[s:s + _BLOCK]
        first, ops = model._operator_block(xs, state)
        e = ext[:xs.size]
        e[:, 0] = 0.0 if first is None else first
        e[:, 1:] = ops
        np.matmul(e, WT, out=Y[s:s + xs.size])
    return (Y, state) if return_state else Y

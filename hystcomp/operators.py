"""Elementary hysteresis operators on explicit state.

Each function takes the input samples, the thresholds and a state (or None
for the thesis's initial condition) and returns the outputs of every
operator, shape (n, N), with the final state, like a streaming filter::

    w, state = play(v[:500], r)
    w2, state = play(v[500:], r, state=state)   # continues exactly

* :func:`play` F_r, eq. 12-13: ``max{v - r, min{v + r, w}}``;
* :func:`stop` E_r, eq. 15-16: ``e_r(v - v(t_i) + w(t_i))``, ``e_r = min{r, max{-r, .}}``;
* :func:`generalized_play` F^gamma_lr, eq. 20: ``max{gl(v) - r, min{gr(v) + r, w}}``;
* :func:`modified_play` F^gamma_mr, eq. 23: ``max{gl(v - r), min{gr(v + r), w}}``.

(The thesis's eqs. 19, 22 and 60 print v(0) where v(t) is meant.)  The
initial condition of the thesis is w(0) = f(v(0), 0): the state before the
first sample is 0.  All share the compiled kernels of the models.
"""

import numpy as np

from . import _kernels as _k
from ._validation import as_signal, as_state, as_thresholds
from .envelopes import Envelope, extended_values as _extended

__all__ = ["play", "stop", "generalized_play", "modified_play"]


def _initial(state, n, name="state"):
    return np.zeros(n) if state is None else as_state(state, n, name)


def play(v, thresholds, state=None):
    """Classical play operators F_r (eq. 12-13).

    Parameters
    ----------
    v : array_like, shape (n,)
        Input samples.
    thresholds : array_like, shape (N,)
        r_1 < ... < r_N, all >= 0.
    state : array_like, shape (N,), optional
        Operator outputs before the first sample; default 0.

    Returns
    -------
    w : ndarray, shape (n, N)
        Output of every operator at every sample.
    state : ndarray, shape (N,)
        Outputs after the last sample.

    Examples
    --------
    >>> w, s = play([0.0, 2.0, 1.0], [1.0])
    >>> w[:, 0].tolist(), s.tolist()
    ([0.0, 1.0, 1.0], [1.0])
    """
    x = as_signal(v, "v")
    r = as_thresholds(thresholds, allow_zero=True)
    z = _initial(state, r.size)
    out = np.empty((x.size, r.size))
    _k.play_states(x, r, z, out)
    return out, z


def stop(v, thresholds, state=None):
    """Stop operators E_r (eq. 15-16), the elastic-plastic element.

    ``e <- e_r(v - v_prev + e)`` with ``e_r(x) = min{r, max{-r, x}}``.

    Parameters
    ----------
    v : array_like, shape (n,)
        Input samples.
    thresholds : array_like, shape (N,)
        r_1 < ... < r_N, all >= 0 (the stops saturate at +-r).
    state : array_like, shape (N + 1,), optional
        ``[e_1, ..., e_N, v_prev]``: the stop outputs and the input before
        the first sample; default zeros (e(0) = e_r(v(0))).

    Returns
    -------
    e : ndarray, shape (n, N)
        Output of every operator at every sample.
    state : ndarray, shape (N + 1,)
        ``[e_1, ..., e_N, v_last]`` after the last sample.

    Examples
    --------
    >>> e, s = stop([0.0, 2.0, 1.0], [1.0])
    >>> e[:, 0].tolist()
    [0.0, 1.0, 0.0]
    """
    x = as_signal(v, "v")
    r = as_thresholds(thresholds, allow_zero=True)
    st = _initial(state, r.size + 1)
    w = st[:-1].copy()
    out = np.empty((x.size, r.size))
    vprev = _k.stop_states(x, r, w, st[-1], out)
    return out, np.concatenate([w, [vprev]])


def _check_envelopes(gl, gr):
    for name, g in (("envelope_left", gl), ("envelope_right", gr)):
        if not isinstance(g, Envelope):
            raise TypeError(f"Parameter {name} is {g!r} but should be an hystcomp Envelope")


def generalized_play(v, thresholds, envelope_left, envelope_right=None, state=None):
    """Generalized play operators of the GPI model (eq. 20).

    ``w <- max{gl(v) - r, min{gr(v) + r, w}}``; `envelope_right` defaults to
    `envelope_left`.

    Parameters
    ----------
    v : array_like, shape (n,)
        Input samples (inside the envelopes' domains).
    thresholds : array_like, shape (N,)
        r_1 < ... < r_N, all >= 0.
    envelope_left : Envelope
        gl, of the lower boundary, which the output follows while the
        input rises.
    envelope_right : Envelope, optional
        gr, of the upper boundary, which the output follows while the input
        falls; default `envelope_left`.
    state : array_like, shape (N,), optional
        Operator outputs w before the first sample; default 0.

    Returns
    -------
    w : ndarray, shape (n, N)
        Output of every operator at every sample.
    state : ndarray, shape (N,)
        Outputs after the last sample.

    Examples
    --------
    >>> from hystcomp.envelopes import Linear
    >>> w, _ = generalized_play([0.0, 2.0], [1.0], Linear(2.0))
    >>> w[:, 0].tolist()
    [0.0, 3.0]
    """
    gr = envelope_left if envelope_right is None else envelope_right
    _check_envelopes(envelope_left, gr)
    x = as_signal(v, "v")
    r = as_thresholds(thresholds, allow_zero=True)
    a = envelope_left(x)
    b = gr(x)
    w = _initial(state, r.size)
    out = np.empty((x.size, r.size))
    _k.two_input_play_states(a, b, r, w, out)
    return out, w


def modified_play(v, thresholds, envelope_left, envelope_right=None, state=None, _allow_zero=True):
    """Modified generalized play operators of the mGPI model (eq. 23).

    ``w <- max{gl(v - r), min{gr(v + r), w}}``; `envelope_right` defaults to
    `envelope_left`.  The state is the operator outputs w.

    Parameters
    ----------
    v : array_like, shape (n,)
        Input samples (inside the envelopes' domains).
    thresholds : array_like, shape (N,)
        r_1 < ... < r_N, all >= 0.
    envelope_left : Envelope
        gl, of the lower boundary, which the output follows while the
        input rises.
    envelope_right : Envelope, optional
        gr, of the upper boundary, which the output follows while the input
        falls; default `envelope_left`.
    state : array_like, shape (N,), optional
        Operator outputs w before the first sample; default 0.

    Returns
    -------
    w : ndarray, shape (n, N)
        Output of every operator at every sample.
    state : ndarray, shape (N,)
        Outputs after the last sample.

    Examples
    --------
    >>> from hystcomp.envelopes import Tanh
    >>> w, _ = modified_play([0.0, 3.0, 1.0], [1.0], Tanh(5.0, 0.5))
    >>> w[:, 0].round(4).tolist()        # 5 tanh(0.5 (3 - 1)) = 3.808
    [0.0, 3.808, 3.808]
    """
    gr = envelope_left if envelope_right is None else envelope_right
    _check_envelopes(envelope_left, gr)
    x = as_signal(v, "v")
    envelope_left.check_domain(x, "v")
    gr.check_domain(x, "v")
    r = as_thresholds(thresholds, allow_zero=_allow_zero)
    w = _initial(state, r.size)
    out = np.empty((x.size, r.size))
    kl, pl = envelope_left.kernel_spec()
    kr, pr = gr.kernel_spec()
    if kl != _k.CUSTOM and kr != _k.CUSTOM:
        _k.mplay_states(x, r, w, kl, pl, kr, pr, out)
        return out, w
    lower = _extended(envelope_left, x[:, None] - r[None, :])
    upper = _extended(gr, x[:, None] + r[None, :])
    _k.bounded_play_states(lower, upper, w, out)
    return out, w

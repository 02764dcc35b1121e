"""Compiled closed loops (numba, ``cache=True``).

The hysteresis and compensator steps call the kernels of
:mod:`hystcomp._kernels` on one-sample arrays: the same kernels, with the
same arguments, as ``model.simulate`` and ``ExactInverse.simulate`` (one
kernel serves simulate, inverses, regressors and loops).  The linear blocks
(plant, controller) are discrete state-space systems.

Per step k, with feedthrough everywhere but in the plant (D = 0 under
feedback)::

    y0 = Cp xp                      (plant output before the actuator acts)
    e  = r - y0                     (feedback scenarios)
    uc = Cc xc + Dc e;  xc <- Ac xc + Bc e    (PID with limits: clipped,
                                               conditional integration)
    u  = ff r + uc                  (terms present in the scenario)
    v  = C(k_nom u)                 (compensator, or v = u)
    w  = H(v)                       (hysteresis)
    y  = y0 + Dp w;  xp <- Ap xp + Bp w

Cold start: `block_step` (and `run_loop`, which calls it) dispatch on the
block kind at run time, so their first call compiles every kernel copy.
`loop_kernel` returns a copy of the loop compiled for the two blocks it runs
(`step_kernel` picks each block's step: one kernel copy), so a loop compiles
only the kernels it calls; each copy has its own on-disk cache entry.
"""

import numpy as np
from numba import njit

from . import _kernels as _k
from ._kernels import _specialise

B_NONE = -1
B_PLAY = 0    # PI / symmetric mGPI forward (play_sum)
B_MPLAY = 1   # asymmetric mGPI forward (mplay_sum)
B_STOP = 2    # stop-type PI forward (stop_sum)
B_EXACT = 3   # exact inverse (inverse_solve)


@njit(cache=True, no_cfunc_wrapper=True, nogil=True)
def block_step(code, fam, x, r, p, p0, kl, pl, kr, pr, kh, ph, hscale, lo, hi, rtol, state,
               xprev, bin_, bout, info):
    """One sample of a hysteresis or compensator block; `state` is updated
    in place, returns (output, new xprev)."""
    bin_[0] = x
    if code == B_PLAY:
        _k.play_sum(bin_, r, p, p0, state, kl, pl, bout)
    elif code == B_MPLAY:
        _k.mplay_sum(bin_, r, p, state, kl, pl, kr, pr, bout)
    elif code == B_STOP:
        xprev = _k.stop_sum(bin_, r, p, p0, state, xprev, bout)
    else:
        xprev = _k.inverse_solve(fam, bin_, r, p, p0, state, xprev, kl, pl, kr, pr, kh, ph, hscale,
                                 lo, hi, rtol, bout, info)
    return bout[0], xprev


# One step function per kernel copy, with `block_step`'s arguments (the
# arguments a step does not need are ignored).  Inlined by numba into the
# loop: a wrapper compiled on its own would have LLVM optimise the kernel it
# calls once more (first-call compilation time).
@njit(cache=True, no_cfunc_wrapper=True, nogil=True, inline="always")
def step_none(code, fam, x, r, p, p0, kl, pl, kr, pr, kh, ph, hscale, lo, hi, rtol, state, xprev, bin_, bout, info):
    """No block (never called: the loops test ``use_comp``)."""
    return x, xprev


@njit(cache=True, no_cfunc_wrapper=True, nogil=True, inline="always")
def step_pi(code, fam, x, r, p, p0, kl, pl, kr, pr, kh, ph, hscale, lo, hi, rtol, state, xprev, bin_, bout, info):
    """PI forward (identity or linear envelope)."""
    bin_[0] = x
    _k.pi_sum(bin_, r, p, p0, state, 1.0 if kl == _k.IDENTITY else pl[0], bout)
    return bout[0], xprev


@njit(cache=True, no_cfunc_wrapper=True, nogil=True, inline="always")
def step_play_closed(code, fam, x, r, p, p0, kl, pl, kr, pr, kh, ph, hscale, lo, hi, rtol, state, xprev, bin_, bout,
                     info):
    """Symmetric mGPI with a Tanh or Atanh envelope: the forward, one sample
    per step (the scalar `play_sum_closed`: same envelope values as
    `MGPI.simulate`'s SIMD kernel, ordered sum), and the exact inverse of a
    tanh mGPI (`play_solve_tanh`, the kernel of `ExactInverse.simulate`).
    One step for both, so that a tanh actuator's loops without a compensator,
    with the analytic one (Atanh) and with the exact one share one compiled
    loop copy (the demo's loops: one loop compilation instead of two)."""
    bin_[0] = x
    if code == B_EXACT:
        xprev = _k.play_solve_tanh(bin_, r, p, p0, state, xprev, kl, pl, lo, hi, rtol, bout, info)
    else:
        _k.play_sum_closed(bin_, r, p, p0, state, kl, pl, bout)
    return bout[0], xprev


@njit(cache=True, no_cfunc_wrapper=True, nogil=True, inline="always")
def step_play_general(code, fam, x, r, p, p0, kl, pl, kr, pr, kh, ph, hscale, lo, hi, rtol, state, xprev, bin_, bout,
                      info):
    """Symmetric mGPI forward, any compiled envelope."""
    bin_[0] = x
    _k.play_sum_general(bin_, r, p, p0, state, kl, pl, bout)
    return bout[0], xprev


@njit(cache=True, no_cfunc_wrapper=True, nogil=True, inline="always")
def step_mplay_closed(code, fam, x, r, p, p0, kl, pl, kr, pr, kh, ph, hscale, lo, hi, rtol, state, xprev, bin_, bout,
                      info):
    """Asymmetric mGPI forward, closed-form envelopes."""
    bin_[0] = x
    _k.mplay_sum_closed(bin_, r, p, state, kl, pl, kr, pr, bout)
    return bout[0], xprev


@njit(cache=True, no_cfunc_wrapper=True, nogil=True, inline="always")
def step_mplay_general(code, fam, x, r, p, p0, kl, pl, kr, pr, kh, ph, hscale, lo, hi, rtol, state, xprev, bin_, bout,
                       info):
    """Asymmetric mGPI forward, any compiled envelopes."""
    bin_[0] = x
    _k.mplay_sum_general(bin_, r, p, state, kl, pl, kr, pr, bout)
    return bout[0], xprev


@njit(cache=True, no_cfunc_wrapper=True, nogil=True, inline="always")
def step_stop(code, fam, x, r, p, p0, kl, pl, kr, pr, kh, ph, hscale, lo, hi, rtol, state, xprev, bin_, bout, info):
    """Stop-type PI forward."""
    bin_[0] = x
    xprev = _k.stop_sum(bin_, r, p, p0, state, xprev, bout)
    return bout[0], xprev


@njit(cache=True, no_cfunc_wrapper=True, nogil=True, inline="always")
def step_exact_pi(code, fam, x, r, p, p0, kl, pl, kr, pr, kh, ph, hscale, lo, hi, rtol, state, xprev, bin_, bout,
                  info):
    """Exact inverse of a PI model."""
    bin_[0] = x
    xprev = _k.play_solve_pi(bin_, r, p, p0, state, xprev, kl, pl, lo, hi, rtol, bout, info)
    return bout[0], xprev


@njit(cache=True, no_cfunc_wrapper=True, nogil=True, inline="always")
def step_exact_closed(code, fam, x, r, p, p0, kl, pl, kr, pr, kh, ph, hscale, lo, hi, rtol, state, xprev, bin_, bout,
                      info):
    """Exact inverse of a symmetric mGPI with a Linear or Atanh envelope."""
    bin_[0] = x
    xprev = _k.play_solve_closed(bin_, r, p, p0, state, xprev, kl, pl, lo, hi, rtol, bout, info)
    return bout[0], xprev


@njit(cache=True, no_cfunc_wrapper=True, nogil=True, inline="always")
def step_exact_general(code, fam, x, r, p, p0, kl, pl, kr, pr, kh, ph, hscale, lo, hi, rtol, state, xprev, bin_, bout,
                       info):
    """Exact inverse of a symmetric mGPI with any compiled envelope."""
    bin_[0] = x
    xprev = _k.play_solve_general(bin_, r, p, p0, state, xprev, kl, pl, lo, hi, rtol, bout, info)
    return bout[0], xprev


@njit(cache=True, no_cfunc_wrapper=True, nogil=True, inline="always")
def step_exact_other(code, fam, x, r, p, p0, kl, pl, kr, pr, kh, ph, hscale, lo, hi, rtol, state, xprev, bin_, bout,
                     info):
    """Exact inverse of the other families (asymmetric mGPI, GPI, stop)."""
    bin_[0] = x
    xprev = _k.inverse_solve_other(fam, bin_, r, p, p0, state, xprev, kl, pl, kr, pr, kh, ph, hscale,
                                   lo, hi, rtol, bout, info)
    return bout[0], xprev


def step_kernel(code, fam, kl, kr):
    """The step function that runs a block (`block_step`'s arguments), chosen
    in Python so that a loop compiles only the kernel copy it calls."""
    if code == B_NONE:
        return step_none
    if code == B_PLAY:
        if kl == _k.IDENTITY or kl == _k.LINEAR:
            return step_pi
        return step_play_closed if kl in (_k.TANH, _k.ATANH) else step_play_general
    if code == B_MPLAY:
        return step_mplay_closed if _k.mplay_sum_kernel(kl, kr) is _k.mplay_sum_closed else step_mplay_general
    if code == B_STOP:
        return step_stop
    if fam != _k.FAM_PLAY:
        return step_exact_other
    if kl == _k.IDENTITY:
        return step_exact_pi
    if kl == _k.TANH:
        return step_play_closed   # with the tanh forward (one loop copy for both)
    return step_exact_closed if kl in (_k.LINEAR, _k.ATANH) else step_exact_general


@njit(cache=True, no_cfunc_wrapper=True, no_cpython_wrapper=True, nogil=True)
def _matvec_add(A, x, B, u, out):
    n = A.shape[0]
    for i in range(n):
        s = 0.0
        for j in range(A.shape[1]):
            s += A[i, j] * x[j]
        out[i] = s + B[i, 0] * u


@njit(cache=True, no_cfunc_wrapper=True, no_cpython_wrapper=True, nogil=True)
def _copy(src, dst):
    # element by element: a slice assignment compiles numba's shape-mismatch
    # error message (string formatting), seconds of first-call compilation
    for i in range(dst.size):
        dst[i] = src[i]


@njit(cache=True, no_cfunc_wrapper=True, no_cpython_wrapper=True, nogil=True)
def _dot(C, x):
    s = 0.0
    for j in range(C.shape[1]):
        s += C[0, j] * x[j]
    return s


# The names `_run_loop_template` calls and each of its compiled copies binds
# to a step function (see `loop_kernel`); None here.
_h_step = None
_c_step = None


def _run_loop_template(ref, ff, use_ff, use_fb, use_comp, kcomp,
             Ap, Bp, Cp, Dp, xp,
             Ac, Bc, Cc, Dc, xc, limited, ulo, uhi, pid_dt,
             h_code, h_fam, h_r, h_p, h_p0, h_kl, h_pl, h_kr, h_pr, h_kh, h_ph, h_hs, h_lo, h_hi,
             h_rtol, h_state, h_xprev,
             c_code, c_fam, c_r, c_p, c_p0, c_kl, c_pl, c_kr, c_pr, c_kh, c_ph, c_hs, c_lo, c_hi,
             c_rtol, c_state, c_xprev,
             y_out, w_out, v_out, info):
    """Run a loop over the reference samples; states are updated in place.
    Returns the final (h_xprev, c_xprev); info[0] counts clipped
    compensator targets."""
    bin_ = np.empty(1)
    bout = np.empty(1)
    binfo = np.zeros(3, dtype=np.int64)
    xp_new = np.empty(xp.size)
    xc_new = np.empty(xc.size)
    n_clip = 0
    for k in range(ref.size):
        rk = ref[k]
        y0 = _dot(Cp, xp)
        u = 0.0
        if use_ff:
            u = ff * rk
        if use_fb:
            e = rk - y0
            uc = _dot(Cc, xc) + Dc[0, 0] * e
            if limited:
                hold = (uc > uhi and e > 0.0) or (uc < ulo and e < 0.0)
                uc_sat = min(max(uc, ulo), uhi)
                # PID states [I, f]: A = diag(1, a), B = [dt, 1 - a]
                xc_new[0] = xc[0] if hold else xc[0] + pid_dt * e
                xc_new[1] = Ac[1, 1] * xc[1] + Bc[1, 0] * e
                uc = uc_sat
            else:
                _matvec_add(Ac, xc, Bc, e, xc_new)
            _copy(xc_new, xc)
            u = u + uc if use_ff else uc
        if use_comp:
            v, c_xprev = _c_step(c_code, c_fam, kcomp * u, c_r, c_p, c_p0, c_kl, c_pl, c_kr, c_pr,
                                 c_kh, c_ph, c_hs, c_lo, c_hi, c_rtol, c_state, c_xprev, bin_, bout, binfo)
            if c_code == B_EXACT:
                n_clip += binfo[0]
        else:
            v = u
        w, h_xprev = _h_step(h_code, h_fam, v, h_r, h_p, h_p0, h_kl, h_pl, h_kr, h_pr,
                             h_kh, h_ph, h_hs, h_lo, h_hi, h_rtol, h_state, h_xprev, bin_, bout, binfo)
        y_out[k] = y0 + Dp[0, 0] * w
        w_out[k] = w
        v_out[k] = v
        _matvec_add(Ap, xp, Bp, w, xp_new)
        _copy(xp_new, xp)
    info[0] = n_clip
    return h_xprev, c_xprev


#: the loop for any blocks (dispatches on the block kind at run time: its
#: first call compiles every kernel copy; `loop_kernel` compiles only those
#: of the given blocks)
run_loop = _specialise(_run_loop_template, "run_loop", _h_step=block_step, _c_step=block_step)

_LOOPS = {}


def loop_kernel(h_spec, c_spec):
    """`run_loop` compiled for the hysteresis block `h_spec` and the
    compensator `c_spec` (kernel arguments from ``_block_specs._spec``): a
    copy that calls the two blocks' step functions directly, so that its first
    call compiles only their kernels.  Copies are kept per combination (and
    cached on disk by numba under their own names)."""
    h_step = step_kernel(h_spec[0], h_spec[1], h_spec[5], h_spec[7])
    # without a compensator (never called: use_comp is False) reuse the
    # hysteresis step, so that the copy is shared with a loop that has one
    c_step = h_step if c_spec[0] == B_NONE else step_kernel(c_spec[0], c_spec[1], c_spec[5], c_spec[7])
    key = (h_step.__name__, c_step.__name__)
    if key not in _LOOPS:
        _LOOPS[key] = _specialise(_run_loop_template, "run_loop__%s__%s" % key, doc=_run_loop_template.__doc__,
                                  _h_step=h_step, _c_step=c_step)
    return _LOOPS[key]

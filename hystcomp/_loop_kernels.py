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
"""

import numpy as np
from numba import njit

from . import _kernels as _k

B_NONE = -1
B_PLAY = 0    # PI / symmetric mGPI forward (play_sum)
B_MPLAY = 1   # asymmetric mGPI forward (mplay_sum)
B_STOP = 2    # stop-type PI forward (stop_sum)
B_EXACT = 3   # exact inverse (inverse_solve)


@njit(cache=True, nogil=True)
def block_step(code, fam, x, r, p, p0, kl, pl, kr, pr, kh, ph, hscale, lo, hi, state, xprev,
               bin_, bout, info):
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
                                 lo, hi, 1e-14, bout, info)
    return bout[0], xprev


@njit(cache=True, nogil=True)
def _matvec_add(A, x, B, u, out):
    n = A.shape[0]
    for i in range(n):
        s = 0.0
        for j in range(A.shape[1]):
            s += A[i, j] * x[j]
        out[i] = s + B[i, 0] * u


@njit(cache=True, nogil=True)
def _dot(C, x):
    s = 0.0
    for j in range(C.shape[1]):
        s += C[0, j] * x[j]
    return s


@njit(cache=True, nogil=True)
def run_loop(ref, ff, use_ff, use_fb, use_comp, kcomp,
             Ap, Bp, Cp, Dp, xp,
             Ac, Bc, Cc, Dc, xc, limited, ulo, uhi, pid_dt,
             h_code, h_fam, h_r, h_p, h_p0, h_kl, h_pl, h_kr, h_pr, h_kh, h_ph, h_hs, h_lo, h_hi,
             h_state, h_xprev,
             c_code, c_fam, c_r, c_p, c_p0, c_kl, c_pl, c_kr, c_pr, c_kh, c_ph, c_hs, c_lo, c_hi,
             c_state, c_xprev,
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
            xc[:] = xc_new
            u = u + uc if use_ff else uc
        if use_comp:
            v, c_xprev = block_step(c_code, c_fam, kcomp * u, c_r, c_p, c_p0, c_kl, c_pl, c_kr, c_pr,
                                    c_kh, c_ph, c_hs, c_lo, c_hi, c_state, c_xprev, bin_, bout, binfo)
            if c_code == B_EXACT:
                n_clip += binfo[0]
        else:
            v = u
        w, h_xprev = block_step(h_code, h_fam, v, h_r, h_p, h_p0, h_kl, h_pl, h_kr, h_pr,
                                h_kh, h_ph, h_hs, h_lo, h_hi, h_state, h_xprev, bin_, bout, binfo)
        y_out[k] = y0 + Dp[0, 0] * w
        w_out[k] = w
        v_out[k] = v
        _matvec_add(Ap, xp, Bp, w, xp_new)
        xp[:] = xp_new
    info[0] = n_clip
    return h_xprev, c_xprev

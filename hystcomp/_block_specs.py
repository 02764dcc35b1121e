"""Kernel arguments of hystcomp blocks for the compiled loops.

:func:`_spec` turns a hysteresis model or a compensator into the arguments of
:func:`hystcomp._loop_kernels.block_step`; :func:`_ss_arrays` a discrete LTI
system into contiguous (A, B, C, D).  Shared by :func:`hystcomp.loops.simulate_loop`
and :func:`hystcomp.loops.fast_response`.
"""

import numpy as np

import control as ct

from . import _kernels as _k
from . import _loop_kernels as _lk
from .models import MGPI, StopPI

_EMPTY = np.zeros(1)


def _spec(obj, role):
    """Kernel arguments of a block: (code, fam, r, p, p0, kl, pl, kr, pr, kh,
    ph, hscale, lo, hi, rtol, state, xprev, pack) or None; `pack(state,
    xprev)` rebuilds the explicit state.  rtol is the exact inverse's output
    tolerance (``ExactInverse._output_rtol``, the one its ``simulate`` and
    python-control block use; 0 for the forward blocks, which do not solve)."""
    from .inverses import ExactInverse

    st = np.asarray(obj.default_state(), dtype=np.float64)
    if isinstance(obj, ExactInverse):
        fam = obj._fam
        lo, hi = obj.input_limits
        common = (_lk.B_EXACT, fam, obj._r, obj._p, float(obj._p0), obj._kl, obj._pl, obj._kr, obj._pr,
                  obj._kh, obj._ph, float(obj._hscale), float(lo), float(hi), float(obj._output_rtol()))
        if fam == _k.FAM_STOP:
            return common + (st[1:-1].copy(), float(st[0]),
                             lambda s, x: np.concatenate([[x], s, [x]]))
        return common + (st[1:].copy(), float(st[0]), lambda s, x: np.concatenate([[x], s]))
    if isinstance(obj, MGPI):
        if obj.symmetric:
            kind, prm = obj.envelope_left.kernel_spec()
            if kind == _k.CUSTOM:
                return None
            return (_lk.B_PLAY, 0, obj._r, obj._p, float(obj.p0), kind, prm, 0, _EMPTY, 0, _EMPTY, 0.0,
                    0.0, 0.0, 0.0, st.copy(), 0.0, lambda s, x: s.copy())
        kl, pl = obj.envelope_left.kernel_spec()
        kr, pr = obj.envelope_right.kernel_spec()
        if _k.CUSTOM in (kl, kr):
            return None
        r = np.concatenate([[0.0], obj._r])
        p = np.concatenate([[obj.p0], obj._p])
        return (_lk.B_MPLAY, 0, r, p, 0.0, kl, pl, kr, pr, 0, _EMPTY, 0.0, 0.0, 0.0, 0.0, st.copy(), 0.0,
                lambda s, x: s.copy())
    if isinstance(obj, StopPI):
        return (_lk.B_STOP, 0, obj._r, obj._p, float(obj.p0), 0, _EMPTY, 0, _EMPTY, 0, _EMPTY, 0.0, 0.0, 0.0, 0.0,
                st[:-1].copy(), float(st[-1]), lambda s, x: np.concatenate([s, [x]]))
    return None


_NONE_SPEC = (_lk.B_NONE, 0, _EMPTY, _EMPTY, 0.0, 0, _EMPTY, 0, _EMPTY, 0, _EMPTY, 0.0, 0.0, 0.0, 0.0,
              np.zeros(1), 0.0, None)


def _ss_arrays(sys):
    s = ct.ss(sys)
    return (np.ascontiguousarray(s.A, dtype=np.float64).reshape(s.nstates, s.nstates),
            np.ascontiguousarray(s.B, dtype=np.float64).reshape(s.nstates, 1),
            np.ascontiguousarray(s.C, dtype=np.float64).reshape(1, s.nstates),
            np.ascontiguousarray(s.D, dtype=np.float64).reshape(1, 1))



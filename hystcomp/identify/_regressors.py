"""Regressor columns of PI, mGPI and GPI models and their Gram matrix, accumulated block by block."""


import numpy as np

from .. import _kernels as _k
from ..envelopes import Identity
from ..envelopes import extended_values as _extended
from ..models import MGPI
from ..operators import modified_play
from ._records import _BLOCK

# regressors and Gram matrix
# ----------------------------------------------------------------------------
def _initial_positions(r, env):
    """Virgin play positions: gamma(z0) = 0 (models.MGPI.default_state)."""
    return MGPI(r, np.zeros(r.size), 1.0, envelope=env).default_state()


class _SymmetricRegressors:
    """PI / symmetric mGPI columns: gamma(v) (p0), gamma(F_{r_i}[v]) (p_i).

    The plays run in input coordinates (compiled classical play); a column
    is "unreached" when its play position never moves.
    """

    lead = 1

    def __init__(self, r, env):
        self.r, self.env = r, env
        self.N = r.size
        self._z0 = _initial_positions(r, env)

    def start(self):
        return self._z0.copy()

    def raw(self, vs, state, A):
        _k.play_states(vs, self.r, state, A[:, 1:self.N + 1])

    def finish(self, vs, A):
        N = self.N
        if isinstance(self.env, Identity):
            A[:, 0] = vs
        else:
            A[:, 0] = _extended(self.env, vs)
            A[:, 1:N + 1] = _extended(self.env, A[:, 1:N + 1])


class _AsymmetricRegressors:
    """Asymmetric mGPI columns: the modified plays w_0 (r = 0, weight p0) ..
    w_N with two envelopes (eq. 23), state w carried between blocks."""

    lead = 1

    def __init__(self, r, gl, gr):
        self.r, self.gl, self.gr = r, gl, gr
        self.N = r.size
        self.r_all = np.concatenate([[0.0], r])
        self.kl, self.pl = gl.kernel_spec()
        self.kr, self.pr = gr.kernel_spec()
        self.compiled = self.kl != _k.CUSTOM and self.kr != _k.CUSTOM

    def start(self):
        return np.zeros(self.N + 1)

    def raw(self, vs, state, A):
        if self.compiled:
            _k.mplay_states(vs, self.r_all, state, self.kl, self.pl, self.kr, self.pr, A[:, :self.N + 1])
        else:
            out, new = modified_play(vs, self.r_all, self.gl, self.gr, state=state)
            A[:, :self.N + 1] = out
            state[:] = new

    def finish(self, vs, A):
        pass


class _GPIRegressors:
    """GPI columns: H(v) (its coefficient, only when H is fitted) and the
    generalized plays of eq. 20 with a = gl(v), b = gr(v)."""

    def __init__(self, r, gl, gr, H):
        self.r, self.gl, self.gr, self.H = r, gl, gr, H
        self.N = r.size
        self.lead = 0 if H is None else 1

    def start(self):
        return np.zeros(self.N)

    def raw(self, vs, state, A):
        L = self.lead
        _k.two_input_play_states(self.gl._value(vs), self.gr._value(vs), self.r, state,
                                 A[:, L:L + self.N])

    def finish(self, vs, A):
        if self.lead:
            A[:, 0] = self.H._value(vs)


def _gram(recs, reg, offset):
    """Accumulate G = A^T W A, b = A^T W y, y^T W y over all records.

    Columns: ``reg.lead`` leading column(s) (p0 or H), the N operator columns
    of `reg`, and 1 (offset) -- built block by block, never the whole
    samples x operators matrix.  Also returns the range of every operator's
    raw output (play position or play output) over the training samples.
    """
    N, L = reg.N, reg.lead
    m = L + N + int(offset)
    G = np.zeros((m, m))
    b = np.zeros(m)
    yy = 0.0
    wsum = 0.0
    n_train = 0
    zmin = np.full(N, np.inf)
    zmax = np.full(N, -np.inf)
    block = np.empty((min(_BLOCK, max(rec[0].size for rec in recs)), m))
    for vj, yj, wj in recs:
        z = reg.start()
        for s in range(0, vj.size, _BLOCK):
            vs = vj[s:s + _BLOCK]
            ys = yj[s:s + _BLOCK]
            A = block[: vs.size]
            reg.raw(vs, z, A)
            if wj is not None:
                ws = wj[s:s + _BLOCK]
                keep = ws > 0
                if not keep.any():
                    continue
                if not keep.all():
                    A = A[keep]
                    vs, ys, ws = vs[keep], ys[keep], ws[keep]
            else:
                ws = None
            zmin = np.minimum(zmin, A[:, L:L + N].min(axis=0))
            zmax = np.maximum(zmax, A[:, L:L + N].max(axis=0))
            reg.finish(vs, A)
            if offset:
                A[:, L + N] = 1.0
            if ws is None:
                G += A.T @ A
                b += A.T @ ys
                yy += float(ys @ ys)
                wsum += vs.size
            else:
                Aw = A * ws[:, None]
                G += A.T @ Aw
                b += Aw.T @ ys
                yy += float(ys @ (ws * ys))
                wsum += float(ws.sum())
            n_train += vs.size
    return G, b, yy, wsum, n_train, zmin, zmax


# ----------------------------------------------------------------------------

"""Benchmark: identify a 40-operator PI model from 100,000 samples.

Times :func:`hystcomp.identify.fit_weights` (regressors built block by block
in the compiled play kernel, Gram matrix, cvxpy QP; everything included)
against a plain baseline: the full (n, N+2) regressor matrix in NumPy (one
play recursion vectorised over operators, a Python loop over samples is far
too slow, so the baseline also uses the compiled kernel for the plays) and an
unconstrained ``np.linalg.lstsq``.  The issue's target: under 1 s.

Run: ``python benchmarks/bench_identify.py``
"""

import time
import warnings

import numpy as np

from hystcomp import GPI, MGPI, PI
from hystcomp import _kernels as _k
from hystcomp.envelopes import Tanh
from hystcomp.identify import fit, fit_weights


def _best(f, repeat=5):
    times = []
    out = None
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = f()
        times.append(time.perf_counter() - t0)
    return min(times), float(np.median(times)), out


def main(n=100_000, N=40):
    rng = np.random.default_rng(0)
    t = np.linspace(0.0, 20.0, n)
    v = 10 * np.sin(2 * np.pi * t) * (1 + 0.5 * np.sin(0.3 * t)) + rng.normal(0, 0.05, n)
    r = (v.max() - v.min()) / 2 * np.arange(1, N + 1) / (N + 1)
    true = PI(r, 0.5 * np.exp(-r / r[-1] * 3) * (r[1] - r[0]), p0=0.8)
    y = true.simulate(v) + 0.3 + rng.normal(0, 0.01, n)

    with warnings.catch_warnings():  # warm-up (numba cache, cvxpy import); short: unreached thresholds
        warnings.simplefilter("ignore", UserWarning)
        fit_weights(v[:5000], y[:5000], thresholds=r, model="pi")

    def ours():
        return fit_weights(v, y, thresholds=r, model="pi")

    def baseline():
        A = np.empty((n, N + 2))
        z = np.zeros(N)
        _k.play_states(v, r, z, A[:, 1:N + 1])
        A[:, 0] = v
        A[:, N + 1] = 1.0
        return np.linalg.lstsq(A, y, rcond=None)[0]

    t_ours, m_ours, res = _best(ours)
    t_base, m_base, theta = _best(baseline)
    err = np.max(np.abs(res.weights - true.weights)) / np.max(true.weights)
    print(f"n = {n} samples, N = {N} operators")
    print(f"fit_weights (blocks + Gram + cvxpy {res.solver}, constrained): "
          f"best {t_ours:.3f} s, median {m_ours:.3f} s  [target < 1 s]")
    print(f"baseline (full matrix {n}x{N + 2} + np.linalg.lstsq, unconstrained): "
          f"best {t_base:.3f} s, median {m_base:.3f} s")
    print(f"max weight error / max weight: fit_weights {err:.2e}, "
          f"lstsq {np.max(np.abs(theta[1:N + 1] - true.weights)) / np.max(true.weights):.2e}")

    # the new paths: asymmetric mGPI (modified plays, compiled kernel) and GPI
    gl, gr = Tanh(12.0, 0.08, 0.1), Tanh(12.0, 0.12, -0.05)
    ya = MGPI(r, true.weights, 0.8, envelope_left=gl, envelope_right=gr).simulate(v) + rng.normal(0, 0.01, n)
    t_a, m_a, res_a = _best(lambda: fit_weights(v, ya, thresholds=r, envelope_left=gl, envelope_right=gr))
    print(f"asymmetric mGPI fit_weights (N + 1 = {N + 1} modified plays): best {t_a:.3f} s, "
          f"median {m_a:.3f} s  [target < 1 s]")
    yg = GPI(r, true.weights, gl, gr, H=0.8).simulate(v) + rng.normal(0, 0.01, n)
    t_g, m_g, res_g = _best(lambda: fit_weights(v, yg, thresholds=r, model="gpi", envelope_left=gl,
                                                envelope_right=gr, H=1.0))
    print(f"GPI fit_weights (H = c v fitted): best {t_g:.3f} s, median {m_g:.3f} s  [target < 1 s]")
    # envelope fitting (variable projection), 20,000 samples, 10 operators
    m = 20_000
    vs = v[:m]
    rs = r[::4]
    truth = MGPI(rs, np.full(rs.size, 0.2), 0.8, envelope_left=gl, envelope_right=gr)
    ys = truth.simulate(vs) + rng.normal(0, 0.01, m)
    print("envelope fitting on data from an asymmetric tanh mGPI (noise 0.01): the symmetric family "
          "cannot follow the asymmetry, so its rmse stays well above the noise")
    for asym in (False, True):
        t0 = time.perf_counter()
        res = fit(vs, ys, envelope="tanh", asymmetric=asym, thresholds=rs)
        sec = time.perf_counter() - t0
        print(f"fit(envelope='tanh', asymmetric={asym}), {m} samples, {rs.size} operators: {sec:.2f} s, "
              f"{res.nfev} evaluations, converged={res.converged}, rmse={res.rmse:.4g}  [target < 20 s]")


if __name__ == "__main__":
    main()

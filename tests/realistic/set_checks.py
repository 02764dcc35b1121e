"""Small tools the later sets' law tests (``tests/test_realistic_holdoutNN.py``, HOLDOUT31 on)
share: every play's output written from the play's definition, the closeness of a record to a
Prandtl-Ishlinskii model (12 plays fitted by NNLS), how far an effect moves a reading beyond a gain
and an offset on its core, a dead time checked on a finer grid, a segment of a branch, the holds
of a drive and whether a never-still programme's knots ever repeat a position. Written once here (they had been copied into every set's test); each test binds them under
its old private names.
"""

import numpy as np
from scipy.optimize import nnls


def rms(x):
    """The root mean square of x (a float)."""
    return float(np.sqrt(np.mean(np.square(x))))


def play_matrix(v, r):
    """Every play's output (columns) for thresholds r, from the virgin state (written here from the play's
    definition)."""
    z = np.zeros(len(r))
    out = np.empty((len(v), len(r)))
    for k, x in enumerate(np.asarray(v, float).tolist()):
        z = np.minimum(np.maximum(z, x - r), x + r)
        out[k] = z
    return out


def pi_fit_rms(y, v, n_plays=12):
    """The RMS and largest residual of a PI model of n_plays plays of v (thresholds evenly spaced from 0 to the drive's
    half-span, the first the linear term) and an offset fitted to y by NNLS."""
    R = np.abs(v).max()
    r = np.arange(n_plays) * R / n_plays
    A = np.c_[play_matrix(v, r), np.ones(len(v)), -np.ones(len(v))]
    w, _ = nnls(A, y)
    d = y - A @ w
    return rms(d), float(np.abs(d).max())


def beyond_gain_and_offset(y, h):
    """The largest and the RMS residual of y beyond a gain and an offset on h (least squares): how far an effect
    moves a reading from its core's."""
    A = np.c_[h, np.ones_like(h)]
    d = y - A @ np.linalg.lstsq(A, y, rcond=None)[0]
    return float(np.abs(d).max()), rms(d)


def read_late_misfit(t, y, delay, core_of_drive, drive_at, fine=8):
    """The RMS difference between y on the uniform times t (from 0) and the core run on a grid `fine` times finer and
    read `delay` late (linear interpolation; the core's first value before it starts): a dead time checked apart
    from how the record delays its drive. `drive_at(times)` gives the drive, `core_of_drive(drive)` the core's
    output."""
    dt = t[1] - t[0]
    tf = np.arange(fine * (len(t) - 1) + 1) * dt / fine
    yf = core_of_drive(drive_at(tf))
    return rms(np.interp(t - delay, tf, yf, left=yf[0]) - y)


def seg(a, b, n=60):
    """n points from a (excluded) to b (included)."""
    return np.linspace(a, b, n + 1)[1:]


def never_still(extra):
    """Whether a programme's knots (``extra["knots"]``: (time, position) pairs) never give two neighbours the same
    position: a never-still programme, which moves from every knot to the next."""
    kx = [k[1] for k in extra["knots"]]
    return all(a != b for a, b in zip(kx, kx[1:]))


def holds(v, min_len):
    """The runs (start, stop) of at least min_len samples over which v stays exactly constant."""
    same = np.r_[False, np.diff(v) == 0.0, False]
    edges = np.flatnonzero(np.diff(same.astype(int)))
    runs = [(a, b + 1) for a, b in zip(edges[::2], edges[1::2])]
    return [(a, b) for a, b in runs if b - a >= min_len]


def assert_relay_core(reading, drive, min_gap):
    """A core read by ``reading(v)`` (from its rest state) has return-point memory, is a loop and is rate independent:
    a minor loop from a turning point (up to 40, down to -25, up to 20 and back) closes there and leaves no trace
    (1e-12 of the output unit); at 0 V the minor loop's rising branch lies more than `min_gap` below its falling one;
    and the first 4000 samples of `drive` played on another time grid (every sample twice) read the same."""
    up = np.r_[np.linspace(0, 40, 200), np.linspace(40, -25, 200)]
    v_up, v_dn = np.linspace(-25, 20, 100), np.linspace(20, -25, 100)
    a_ = reading(np.r_[up, v_up, v_dn, np.linspace(-25, 45, 240)])
    b_ = reading(np.r_[up, np.linspace(-25, 45, 240)])
    np.testing.assert_allclose(a_[600:], b_[400:], rtol=0, atol=1e-12)
    assert abs(a_[599] - b_[399]) <= 1e-12
    rising = float(np.interp(0.0, v_up, a_[400:500]))
    falling = float(np.interp(0.0, v_dn[::-1], a_[500:600][::-1]))
    assert falling - rising > min_gap
    v = drive[:4000]
    np.testing.assert_array_equal(reading(np.repeat(v, 2))[::2], reading(v))


def assert_knots_evaluator(reach, knots_at):
    """A programme's knot evaluator ``knots_at(t, knots)`` against a direct search of its knots, each move between
    two knots following ``reach`` (0 ... 1 over the move): on 71 times from before the first knot to after the last,
    within 1e-12 (rounding), the first knot's value before it and the last's after it."""
    kn = [(0.0, 0.0), (1.0, 0.5), (1.5, 0.5), (2.5, -1.0)]
    for tt in np.linspace(-0.5, 3.0, 71):
        if tt <= 0.0:
            ref = 0.0
        elif tt >= 2.5:
            ref = -1.0
        else:
            i = max(k for k in range(3) if kn[k][0] <= tt)
            (t0, x0), (t1, x1) = kn[i], kn[i + 1]
            ref = x0 + (x1 - x0) * float(reach((tt - t0) / (t1 - t0)))
        got = float(knots_at(np.array([tt]), kn)[0])
        assert abs(got - ref) <= 1e-12, (tt, got, ref)


def assert_minimum_jerk(reach, reach_speed):
    """A programme's minimum-jerk move (:func:`realistic.set_tools.minimum_jerk` and its speed) against quad of its
    speed 30 s^2 (1 - s)^2 (1e-13: quad's own tolerance is 1e-15 absolute), 0 before and 1 after the move; its speed
    by central differences (1e-6, the difference's truncation at a step of 1e-6), its peak at mid-move (1e-5, the
    grid's step) and 1.875 there (1e-12, rounding)."""
    from scipy.integrate import quad

    for sv in np.linspace(0.0, 1.0, 41):
        ref = quad(lambda u: 30.0 * u * u * (1 - u) ** 2, 0.0, sv, epsabs=1e-15, epsrel=1e-13)[0]
        assert abs(float(reach(sv)) - ref) <= 1e-13, (sv, float(reach(sv)), ref)
    assert reach(0.0) == 0.0 and reach(1.0) == 1.0 and reach(-0.5) == 0.0 and reach(1.5) == 1.0
    si = np.linspace(0.01, 0.99, 99)
    sp = (reach(si + 1e-6) - reach(si - 1e-6)) / 2e-6
    np.testing.assert_allclose(sp, reach_speed(si), rtol=0, atol=1e-6)
    fine = np.linspace(0.4, 0.6, 200001)
    assert abs(fine[np.argmax(reach_speed(fine))] - 0.5) <= 1e-5
    assert abs(float(reach_speed(0.5)) - 1.875) <= 1e-12

"""The PI forward kernel `pi_sum` (issue 13 point 3: two threads).

* The finiteness test of the input is inside the kernel: ``PI.simulate``
  (and a symmetric mGPI with a Linear envelope) does not scan the record for
  NaN and inf before the kernel runs; `pi_sum` tests each sample's exponent
  bits in its own pass and reports the first non-finite one, and
  ``simulate`` raises the same ValueError as every other model before
  anything is returned.
* `run_play_sum` runs a record of at least ``_ALIGN_MIN`` samples on 32-byte
  aligned copies of the operator arrays: results must not depend on where
  the caller's arrays sit nor on how a record is cut around that length, and
  the caller's state must still be updated in place.

(The time both save on two threads is measured in
benchmarks/bench_models.py, not timed here.)
"""

import numpy as np
import pytest
from numba import njit

from hystcomp import MGPI, PI
from hystcomp import _kernels as _k
from hystcomp.envelopes import Linear, Tanh

R = 0.5 * np.arange(1, 21)
P = 0.5 * np.exp(-0.1 * R)

SPECIAL = np.array([
    0.0, -0.0, 1.0, -1.0, np.finfo(float).max, -np.finfo(float).max, np.finfo(float).tiny,
    5e-324, -5e-324, 1e300, np.nan, -np.nan, np.inf, -np.inf,
])


@njit(fastmath=True)
def _finite_under_fastmath(x, out):
    # full fastmath (nnan, ninf): a float test such as x - x == 0 may be
    # folded to True here; the exponent-bit test must not be
    for k in range(x.size):
        out[k] = _k._is_finite(x[k])


def test_is_finite_matches_numpy_even_under_fastmath():
    x = np.concatenate([SPECIAL, np.frombuffer(np.array([0x7FF8000000000001, 0xFFF0000000000001],
                                                         dtype=np.uint64).tobytes(), dtype=np.float64)])
    got = np.empty(x.size, dtype=np.bool_)
    _finite_under_fastmath(x, got)
    assert got.tolist() == np.isfinite(x).tolist()


def _pi_sum(v):
    z = np.zeros(R.size)
    out = np.empty(v.size)
    bad = _k.pi_sum(v, R, P, 1.0, z, 1.0, out)
    return bad, out


@pytest.mark.parametrize("where", [0, 1, 2500, 4999])
@pytest.mark.parametrize("value", [np.nan, np.inf, -np.inf])
def test_pi_sum_reports_the_first_non_finite_sample(where, value):
    v = 8.0 * np.sin(np.linspace(0.0, 40.0, 5000))
    bad, y_clean = _pi_sum(v)
    assert bad == -1
    w = v.copy()
    w[where] = value
    w[min(where + 7, w.size - 1)] = np.nan   # a later one is not the one reported
    bad, y = _pi_sum(w)
    assert bad == where
    # the samples before it are simulated as usual
    assert np.array_equal(y[:where], y_clean[:where])


def test_pi_sum_finite_extremes_are_not_reported():
    v = SPECIAL[np.isfinite(SPECIAL)]
    assert _pi_sum(v)[0] == -1


KERNEL_CHECKED = {
    "PI": PI(R, P, p0=1.0),
    "MGPI_linear": MGPI(R, P, p0=0.7, envelope=Linear(1.5)),
}


@pytest.mark.parametrize("name", list(KERNEL_CHECKED))
@pytest.mark.parametrize("where, value", [(0, np.nan), (49_999, -np.inf), (99_999, np.inf)])
def test_simulate_raises_before_returning(name, where, value):
    m = KERNEL_CHECKED[name]
    assert m._kernel_checks_finite()   # the path under test: no pass in as_signal
    v = 8.0 * np.sin(np.linspace(0.0, 400.0, 100_000))
    v[where] = value
    s0 = np.linspace(-1.0, 1.0, m.n_states)
    s0_before = s0.copy()
    msg = rf"^Parameter v holds a non-finite value \({value}\) at sample index {where}; expected finite numbers$"
    with pytest.raises(ValueError, match=msg):
        m.simulate(v)
    with pytest.raises(ValueError, match=msg):
        m.simulate(v, initial_state=s0, return_state=True)
    assert np.array_equal(s0, s0_before)   # the caller's state is untouched


def test_same_message_as_the_models_that_check_in_python():
    v = np.array([0.0, 1.0, 2.0, np.nan, 1.0])
    tanh = MGPI(R, P, p0=1.0, envelope=Tanh(10.0, 0.2))
    assert not tanh._kernel_checks_finite()
    messages = []
    for m in (KERNEL_CHECKED["PI"], tanh):
        with pytest.raises(ValueError) as info:
            m.simulate(v)
        messages.append(str(info.value))
    assert messages[0] == messages[1]


def test_two_dimensional_input_names_the_column():
    # simulate_columns keeps as_signal's test, naming the column
    V = np.zeros((10, 3))
    V[4, 2] = np.inf
    with pytest.raises(ValueError, match=r"Parameter v\[:, 2\] holds a non-finite value \(inf\) at sample index 4"):
        KERNEL_CHECKED["PI"].simulate(V)


def _at_page_end(values, into, lead):
    """`values` copied into `into` so that the copy starts `lead` bytes
    before a 4 KiB page boundary (so its SIMD loads straddle the page)."""
    base = into.ctypes.data
    start = ((-base) % 4096 + 4096 - lead) // 8
    a = into[start:start + values.size]
    assert (a.ctypes.data + lead) % 4096 == 0
    a[:] = values
    return a


def test_aligned_copy():
    buf = np.arange(40.0)
    for k in range(4):
        a = buf[k:k + 21]
        c = _k._aligned_copy(a)
        assert c.__array_interface__["data"][0] % 32 == 0
        assert np.array_equal(c, a) and c.dtype == np.float64
        assert not np.shares_memory(c, a)


@pytest.mark.parametrize("n", [10, 3000])   # below and above _ALIGN_MIN
@pytest.mark.parametrize("lead", [8, 16, 24, 40, 64])
def test_run_play_sum_does_not_depend_on_where_the_arrays_sit(lead, n):
    v = 8.0 * np.sin(np.linspace(0.0, 40.0, n))
    z0 = np.linspace(-0.5, 0.5, R.size)
    z_ref, y_ref = z0.copy(), np.empty(v.size)
    _k.pi_sum(v, R, P, 1.0, z_ref, 1.0, y_ref)
    buf = np.zeros((3, 1536))
    r, p, z = (_at_page_end(a, buf[j], lead) for j, a in enumerate((R, P, z0)))
    y = np.empty(v.size)
    assert _k.run_play_sum(v, r, p, 1.0, z, _k.IDENTITY, np.zeros(0), y) == -1
    assert np.array_equal(y, y_ref)
    assert np.array_equal(z, z_ref)   # the caller's state, updated in place
    assert np.array_equal(r, R) and np.array_equal(p, P)   # read only


@pytest.mark.parametrize("name", list(KERNEL_CHECKED))
def test_chunks_around_the_copy_length_equal_one_shot(name):
    # pieces shorter than, equal to and longer than _ALIGN_MIN (aligned
    # copies or not) must give the one-shot result bit for bit
    m = KERNEL_CHECKED[name]
    assert _k._ALIGN_MIN == 64   # the sizes below straddle it
    v = 9.0 * np.sin(np.linspace(0.0, 60.0, 4000)) + 0.3 * np.cos(np.linspace(0.0, 700.0, 4000))
    y_one = m.simulate(v)
    sizes = [1, 63, 64, 65, 5, 200, 2, 1000]
    parts, state, k = [], None, 0
    while k < v.size:
        step = sizes[len(parts) % len(sizes)]
        y, state = m.simulate(v[k:k + step], initial_state=state, return_state=True)
        parts.append(y)
        k += step
    assert np.array_equal(np.concatenate(parts), y_one)

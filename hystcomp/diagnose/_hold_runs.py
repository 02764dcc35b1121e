"""Compiled scan for the runs in which an input stays put
(:func:`hystcomp.diagnose.record.find_holds`).

The scan restarts at every sample whose run is too short, so its cost is the
record's length times the shortest hold's on an input that stays within the
tolerance for just under the shortest hold (a fast staircase whose stairs are
one shortest hold long).  Compiled, that worst case is about a nanosecond per
sample and step; in Python it was a minute for 100,000 samples.  The
arithmetic is the Python loop's, in the same order (a running sum from the
run's first sample, divided by the run's length), so the runs are the same to
the last bit.
"""

import numpy as np
from numba import njit


@njit(cache=True, nogil=True)
def hold_runs(vs, tol, min_len):
    """Runs ``[k, j)`` of at least `min_len` samples in which every sample of
    `vs` stays within `tol` of the mean of the run's samples before it,
    scanned from the record's start: a run that is too short moves the start
    one sample on; a long enough run is kept and the scan goes on at its end.

    Parameters
    ----------
    vs : ndarray of float64
        The smoothed input.
    tol : float
        The tolerance about the running mean.
    min_len : int
        The shortest run kept [samples].

    Returns
    -------
    starts, ends : ndarray of int64
        The runs' first samples and the samples after their last.
    """
    n = vs.size
    cap = n // max(min_len, 1) + 1
    starts = np.empty(cap, np.int64)
    ends = np.empty(cap, np.int64)
    m = 0
    k = 0
    while k < n - 1:
        total = vs[k]
        j = k + 1
        while j < n and abs(vs[j] - total / (j - k)) <= tol:
            total += vs[j]
            j += 1
        if j - k >= min_len and m < cap:
            starts[m] = k
            ends[m] = j
            m += 1
            k = j
        else:
            k += 1
    return starts[:m], ends[:m]

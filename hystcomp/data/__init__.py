"""Measured data shipped with hystcomp (with its licence and source note).

Only one record for now: a piezo actuator driven by a 1 Hz, +-150 V sine
(A. Chandra et al. 2023, MIT licence; see ``SOURCE.md`` and ``LICENSE`` in
this folder).
"""

import gzip
from pathlib import Path

import numpy as np

__all__ = ["load_piezo"]

_HERE = Path(__file__).resolve().parent


def load_piezo():
    """The measured piezo record of Chandra et al. (2023), 5 kHz, t = 0 ... 10 s.

    Returns
    -------
    t : ndarray, shape (50001,)
        Time [s].
    v : ndarray
        Voltage [V] (the commanded sine; 0 V until t = 3.2572 s).
    y : ndarray
        Measured displacement [um].

    Examples
    --------
    >>> t, v, y = load_piezo()
    >>> t.size, float(v.max()) <= 150.0
    (50001, True)
    """
    with gzip.open(_HERE / "hysteresis_v_150_1hz.csv.gz", "rt") as f:
        raw = np.loadtxt(f, delimiter=",", usecols=(1, 2, 3))
    return raw[:, 0].copy(), raw[:, 2].copy(), raw[:, 1].copy()

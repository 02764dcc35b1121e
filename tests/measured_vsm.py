"""Measured VSM hysteresis loops (tests/data/hystlab_vsm, HystLab's example data: BSD-3 plus
citation, see its SOURCE.md): a reader of Princeton Measurements MicroMag files and the list of
the loops.

Each file holds one major loop of a rock, sediment or magnetosome specimen, from +Hmax down to
-Hmax and back, as quasi-static points (no time axis): the applied field mu0 H [T] and the
moment [A m^2] as measured (not slope-corrected).
"""

import gzip
import os

import numpy as np

FOLDER = os.path.join(os.path.dirname(os.path.abspath(__file__)), "data", "hystlab_vsm")

#: file -> (what the specimen is, the publication its ReadMe names)
LOOPS = {
    "A4.hys": ("specimen A4 (pseudo-Thellier calibration set)", "Paterson, Heslop & Pan 2016, GJI 207"),
    "A1c_d200_100.hys": ("specimen A1c, discrete sweep, 200 ms averaging, 100 ms settling", "Paterson et al. 2018"),
    "A1c_d200_200.hys": ("specimen A1c, discrete sweep, 200 ms averaging, 200 ms settling", "Paterson et al. 2018"),
    "A1c_d200_400.hys": ("specimen A1c, discrete sweep, 200 ms averaging, 400 ms settling", "Paterson et al. 2018"),
    "CP4Q.hyst": ("lithic clast from a pyroclastic deposit", "Paterson et al. 2010, JGR 115"),
    "Conc_40_C2A.hys": ("magnetosome chains (bacterial culture)", "Paterson, Wang & Pan 2013, EPSL 383"),
    "Conc_40_C3B.hys": ("magnetosome chains (bacterial culture)", "Paterson, Wang & Pan 2013, EPSL 383"),
    "Conc_40_C4A.hys": ("magnetosome chains (bacterial culture)", "Paterson, Wang & Pan 2013, EPSL 383"),
    "DL362.hys": ("Holocene loess-palaeosol sediment", "Liu et al. 2015, Sci. Rep. 5"),
    "H11.hys": ("specimen H11 (domain-state study)", "Paterson et al. 2017, PNAS 114"),
    "Helderberg_Ls_H2-4.4b2.hys": ("remagnetised Helderberg limestone", "Jackson & Swanson-Hysell 2012"),
    "LV23C.hyst": ("specimen LV23C", "Paterson et al. 2018 (fig. 10)"),
    "LV6B.hyst": ("specimen LV6B", "Paterson et al. 2018 (fig. 7)"),
    "PIOX.loop": ("synthetic specimen PIOX (Preisach palaeointensity tests)", "Muxworthy et al. 2011, JGR 116"),
    "VM1BX.loop": ("synthetic specimen VM1BX (Preisach palaeointensity tests)", "Muxworthy et al. 2011, JGR 116"),
}


def _number(text):
    """float(text), or None when `text` is not a number (MicroMag writes +1.5E-03 and, for 0, a space)."""
    try:
        return float(text)
    except ValueError:
        return None


def read_micromag(name):
    """The field [T] and moment [A m^2] of one loop file of :data:`LOOPS`, as measured.

    The data block is the rows of comma-separated numbers after the line that names the
    columns (``Field``, ``Moment``, ...), blank lines between the segments skipped, up to the
    file's last line; the segment table above it is not read.  The first two columns are the raw field and moment.

    Returns
    -------
    field, moment : ndarray
    columns : list of str
        The data block's column names (``Field``, ``Moment``, and any further ones).
    """
    if name not in LOOPS:
        raise ValueError(f"Parameter name is {name!r} but should be one of {sorted(LOOPS)}")
    with gzip.open(os.path.join(FOLDER, name + ".gz"), "rt", encoding="latin-1") as fh:
        lines = [line.strip() for line in fh.read().replace("\r", "").split("\n")]
    head = next(i for i, line in enumerate(lines) if line.split()[:2] in (["Field", "Moment"], ["Raw", "Raw"]))
    names = lines[head].split() if lines[head].startswith("Field") else lines[head + 1].split()
    rows = []
    for line in lines[head + 1:]:
        values = [_number(p) for p in line.split(",")]
        if len(values) == len(names) and None not in values:
            rows.append(values)
        elif rows and line:
            break            # "MicroMag 2900/3900 Data File ends" (blank lines part the segments)
    a = np.array(rows)
    return a[:, 0], a[:, 1], names

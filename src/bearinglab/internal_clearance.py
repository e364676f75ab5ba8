r"""Radial internal clearance classes of deep-groove ball bearings (ISO 5753-1).

Functions
---------
radial_clearance_range   the (minimum, maximum) radial internal clearance of a class for a bore
clearance_table          the rows of the table as read from ``data/iso5753_radial_clearance.csv``

Constants
---------
CLEARANCE_CLASSES        the class names, smallest clearance first: C2, CN, C3, C4, C5

The values apply to unmounted bearings under zero measuring load. The table is stored in
``data/iso5753_radial_clearance.csv`` (bore in mm, clearance in um, the source in every row); the
functions return SI values (m).

References
----------
.. [1] ISO 5753-1:2009, *Rolling bearings -- Internal clearance -- Part 1: Radial internal clearance
   for radial bearings*, table of single-row deep groove ball bearings.
.. [2] SKF General Catalogue 6000/I RU (2006), deep groove ball bearings, Table 4 "Radial internal
   clearance of deep groove ball bearings", p. 297 (values of ISO 5753).
.. [3] NSK Rolling Bearings, CAT. No. E1102e, Table 9.9 "Radial internal clearances in deep groove
   ball bearings", p. A89. Identical to [2] for bores up to 200 mm, the range stored here.
"""

from __future__ import annotations

import csv
import functools
from importlib import resources
from typing import NamedTuple

import numpy as np

from ._validate import check_positive
from .errors import InputError

__all__ = ["CLEARANCE_CLASSES", "ClearanceRow", "RadialClearanceRange", "clearance_table",
           "radial_clearance_range"]

CLEARANCE_CLASSES = ("C2", "CN", "C3", "C4", "C5")
_MM = 1e-3


class RadialClearanceRange(NamedTuple):
    """Radial internal clearance range of a class. [m]"""

    minimum: float | np.ndarray
    maximum: float | np.ndarray


class ClearanceRow(NamedTuple):
    """One row of the stored table: bore range (over, incl] [mm], class, clearance [um], source."""

    bore_over: float
    bore_incl: float
    clearance_class: str
    minimum: float
    maximum: float
    source: str


@functools.cache
def clearance_table():
    """The ISO 5753-1 deep-groove ball bearing table as stored, one row per bore range and class.

    Returns
    -------
    tuple of ClearanceRow
        Bore limits in mm and clearances in um, as printed in the source; ``source`` names it.

    Examples
    --------
    >>> row = clearance_table()[0]
    >>> row.clearance_class, row.bore_incl, row.minimum, row.maximum
    ('C2', 6.0, 0.0, 7.0)
    """
    ref = resources.files("bearinglab") / "data" / "iso5753_radial_clearance.csv"
    lines = [line for line in ref.read_text(encoding="utf-8").splitlines() if not line.startswith("#")]
    return tuple(ClearanceRow(float(r["bore_over_mm"]), float(r["bore_incl_mm"]), r["clearance_class"],
                              float(r["minimum_um"]), float(r["maximum_um"]), r["source"])
                 for r in csv.DictReader(lines))


def _class_name(clearance_class):
    """'/C3', 'c3', 'Normal' -> 'C3', 'CN'; InputError for anything else."""
    key = str(clearance_class).strip().lstrip("/").upper()
    key = {"NORMAL": "CN", "N": "CN", "C0": "CN"}.get(key, key)
    if key not in CLEARANCE_CLASSES:
        raise InputError(f"clearance_class must be one of {', '.join(CLEARANCE_CLASSES)}, "
                         f"got {clearance_class!r}")
    return key


@functools.cache
def _arrays(name):
    rows = [r for r in clearance_table() if r.clearance_class == name]
    return tuple(np.array([getattr(r, f) for r in rows]) for f in ("bore_over", "bore_incl", "minimum", "maximum"))


def radial_clearance_range(bore, clearance_class="CN"):
    r"""Radial internal clearance range of a deep-groove ball bearing, ISO 5753-1.

    Parameters
    ----------
    bore : array_like
        Bearing bore diameter :math:`d`. [m]
    clearance_class : str
        ``"C2"``, ``"CN"`` (normal; also ``"Normal"``), ``"C3"``, ``"C4"`` or ``"C5"``; a leading
        slash as in a designation (``"/C3"``) and lower case are accepted.

    Returns
    -------
    RadialClearanceRange
        ``minimum`` and ``maximum`` radial internal clearance. [m]

    Raises
    ------
    InputError
        An unknown class, a bore that is not positive, a bore above 200 mm (the range stored), or C4 /
        C5 for a bore of 6 mm or less (not given in the table).

    Notes
    -----
    A bore :math:`d` belongs to the range "over :math:`d_1` incl. :math:`d_2`", :math:`d_1 < d \le
    d_2`. Values for unmounted bearings under zero measuring load [1]_, as reproduced in [2]_ and [3]_.

    References
    ----------
    .. [1] ISO 5753-1:2009, *Rolling bearings -- Internal clearance -- Part 1: Radial internal
       clearance for radial bearings*.
    .. [2] SKF General Catalogue 6000/I RU (2006), Table 4, p. 297.
    .. [3] NSK Rolling Bearings, CAT. No. E1102e, Table 9.9, p. A89.

    Examples
    --------
    >>> r = radial_clearance_range(0.040, "C3")   # 6208/C3: 40 mm is in "over 30 incl. 40"
    >>> round(r.minimum * 1e6), round(r.maximum * 1e6)
    (15, 33)
    """
    name = _class_name(clearance_class)
    d = check_positive("bore", bore, "m")
    over, incl, lo, hi = _arrays(name)
    d_mm = d / _MM
    # (over, incl]: a bore on a limit belongs to the lower range; rounding of the mm conversion kept out
    d_key = np.round(d_mm, 9)
    index = np.searchsorted(incl, d_key, side="left")
    outside = (index >= incl.size) | (d_key <= over[np.minimum(index, incl.size - 1)])
    if np.any(outside):
        first = float(np.asarray(d_mm)[outside].flat[0]) if np.ndim(d_mm) else float(d_mm)
        raise InputError(f"bore must be in ({over[0] * _MM:g}, {incl[-1] * _MM:g}] m for clearance class "
                         f"{name} (ISO 5753-1 table as stored), got {first * _MM!r}")
    return RadialClearanceRange(lo[index][()] / 1e6, hi[index][()] / 1e6)

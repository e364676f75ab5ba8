"""Tolerance tables of the bearing seats: ISO 286 fields of shafts and housings, ISO 492 bearing tolerances.

Fields of shafts and housings (ISO 286)
---------------------------------------
SHAFT_FIELDS, HOUSING_FIELDS   the fields bearinglab computes (the usual bearing seats)
standard_tolerance             the standard tolerance ITn of a size [m]
field_limits                   the lower and upper deviation of a field such as ``k5`` or ``H7`` [m]

Bearing tolerances (ISO 492)
----------------------------
TOLERANCE_CLASSES              Normal, P6, P5, P4
tolerance_class                a class name as written (``P0``, ``normal``, ``p5``) -> its canonical name
bore_limits                    Delta_dmp of the inner ring: lower and upper deviation of the mean bore [m]
outside_diameter_limits        Delta_Dmp of the outer ring [m]

The numbers are in ``data/iso286.csv``, ``data/iso286_special.csv`` and ``data/iso492.csv``, each row with
its source. A field is computed the ISO 286-1 way, from the standard tolerance grade and the fundamental
deviation (with the Delta of table 3 for K, M, N and P): the limits ISO 286-2 tabulates follow from that
rule, and the tests compare several sizes with the tables read by hand.
"""

from __future__ import annotations

import csv
import functools
import re
from importlib import resources
from typing import NamedTuple

import numpy as np

from ..errors import InputError

__all__ = [
    "HOUSING_FIELDS", "SHAFT_FIELDS", "TOLERANCE_CLASSES", "Limits", "bore_limits", "field_limits",
    "outside_diameter_limits", "standard_tolerance", "tolerance_class",
]

_UM, _MM = 1e-6, 1e-3  # m per um, per mm

SHAFT_FIELDS = ("g6", "h5", "h6", "j5", "j6", "js5", "js6", "k5", "k6", "m5", "m6", "n6", "p6")
HOUSING_FIELDS = ("F7", "G6", "G7", "H6", "H7", "H8", "J6", "J7", "JS6", "JS7", "K6", "K7", "M6", "M7",
                  "N6", "N7", "P6", "P7")
TOLERANCE_CLASSES = ("Normal", "P6", "P5", "P4")
# how a class is also written: ISO 492 "Normal" is P0 (DIN 620) and PN; class 6 is P6 and so on
_CLASS_ALIASES = {"normal": "Normal", "p0": "Normal", "pn": "Normal", "0": "Normal", "cln": "Normal",
                  "p6": "P6", "6": "P6", "p5": "P5", "5": "P5", "p4": "P4", "4": "P4",
                  # SKF super-precision P4A: dimensions to ISO 492 class 4 (running accuracy better)
                  "p4a": "P4"}


class Limits(NamedTuple):
    """The two limit deviations of a tolerance field from the nominal size."""

    lower: np.ndarray
    """Lower deviation (ei, EI, or the low deviation of Delta_dmp). [m]"""
    upper: np.ndarray
    """Upper deviation (es, ES). [m]"""


def _rows(name):
    text = (resources.files("bearinglab") / "data" / name).read_text(encoding="utf-8")
    lines = [line for line in text.splitlines() if line.strip() and not line.startswith("#")]
    return list(csv.DictReader(lines))


@functools.cache
def _iso286():
    rows = _rows("iso286.csv")
    table = {key: np.array([float(r[key]) for r in rows]) for key in rows[0] if key != "source"}
    special = {(r["field"], float(r["over_mm"]), float(r["up_to_mm"]), r["which"]): float(r["value_um"])
               for r in _rows("iso286_special.csv")}
    return table, special


@functools.cache
def _iso492():
    out = {}
    for r in _rows("iso492.csv"):
        out.setdefault((r["ring"], r["class"]), []).append(
            (float(r["over_mm"]), float(r["up_to_mm"]), float(r["upper_um"]), float(r["lower_um"])))
    return out


def _range_index(size_mm, over, up_to, what):
    """Index of the range over < size <= up_to of each size; InputError outside the table."""
    size_mm = np.round(np.asarray(size_mm, dtype=float), 9)  # 0.05 m / 1e-3 = 50.00000000000001 mm
    k = np.searchsorted(up_to, size_mm, side="left")  # up_to[k-1] < size <= up_to[k]
    bad = ~((size_mm > over[0]) & (k < len(up_to)))
    if bad.any():
        raise InputError(f"{what} must be in ({over[0]:g}, {up_to[-1]:g}] [mm], got "
                         f"{float(size_mm[bad].flat[0]):g} mm")
    return k


def standard_tolerance(grade, size):
    """The ISO 286-1 standard tolerance IT\\ *n* of a nominal size.

    Parameters
    ----------
    grade : int
        5, 6, 7 or 8. [-]
    size : array_like
        Nominal size, 0 < size <= 500 mm. [m]

    Returns
    -------
    ndarray
        IT\\ *n*. [m]

    References
    ----------
    .. [1] ISO 286-1:2010, Geometrical product specifications (GPS) - ISO code system for tolerances on
       linear sizes - Part 1, table 1.

    Examples
    --------
    >>> print(f"{standard_tolerance(6, 0.040) * 1e6:g} um")
    16 um
    """
    if grade not in (5, 6, 7, 8):
        raise InputError(f"grade must be one of [5, 6, 7, 8], got {grade!r}")
    t, _ = _iso286()
    k = _range_index(np.asarray(size, dtype=float) / _MM, t["over_mm"], t["up_to_mm"], "size")
    return (t[f"IT{grade}"][k] * _UM)[()]


_FIELD = re.compile(r"^(js|JS|[a-zA-Z])([0-9]+)$")


def field_limits(field, size):
    """The limit deviations of an ISO 286 tolerance field of a shaft (``k5``) or a housing bore (``H7``).

    Parameters
    ----------
    field : str
        One of :data:`SHAFT_FIELDS` (lower case) or :data:`HOUSING_FIELDS` (upper case).
    size : array_like
        Nominal diameter of the seat, 0 < size <= 500 mm. [m]

    Returns
    -------
    Limits
        Lower and upper deviation from the nominal size. [m]

    Notes
    -----
    The ISO 286-1 rule: one deviation is the fundamental deviation of the letter (table 2 for shafts,
    table 3 for holes), the other follows from the standard tolerance IT\\ *n* of table 1. For K, M, N
    (grades up to IT8) and P (up to IT7) the upper deviation is the tabulated value plus Delta of
    table 3; js and JS are symmetric, +-IT\\ *n*/2; the special case of table 3 (M6 over 250 up to
    315 mm) is in ``data/iso286_special.csv``.

    References
    ----------
    .. [1] ISO 286-1:2010, tables 1, 2 and 3.

    Examples
    --------
    >>> lim = field_limits("k5", 0.040)
    >>> print(f"{lim.lower * 1e6:+.0f} / {lim.upper * 1e6:+.0f} um")
    +2 / +13 um
    >>> lim = field_limits("N7", 0.090)
    >>> print(f"{lim.lower * 1e6:+.0f} / {lim.upper * 1e6:+.0f} um")
    -45 / -10 um
    """
    if field not in SHAFT_FIELDS + HOUSING_FIELDS:
        raise InputError(f"field must be one of the shaft fields {list(SHAFT_FIELDS)} or the housing fields "
                         f"{list(HOUSING_FIELDS)}, got {field!r}")
    letter, grade = _FIELD.match(field).groups()
    grade = int(grade)
    t, special = _iso286()
    size_mm = np.round(np.asarray(size, dtype=float) / _MM, 9)
    k = _range_index(size_mm, t["over_mm"], t["up_to_mm"], "size")
    it = t[f"IT{grade}"][k]
    if letter in ("js", "JS"):
        lower, upper = -it / 2, it / 2
    elif letter == "h" or letter == "H":
        lower, upper = (-it, 0.0 * it) if letter == "h" else (0.0 * it, it)
    elif letter == "g":
        upper = t["g_es"][k]
        lower = upper - it
    elif letter in ("j", "k", "m", "n", "p"):
        lower = t[f"{letter}_ei"][k]
        upper = lower + it
    elif letter in ("F", "G"):
        lower = t[f"{letter}_EI"][k]
        upper = lower + it
    elif letter == "J":
        upper = t[f"J{grade}_ES"][k]
        lower = upper - it
    else:  # K, M, N, P: ES = -x + Delta (table 3)
        upper = t[f"{letter}_ES"][k] + t[f"delta{grade}"][k]
        for (name, over, up_to, which), value in special.items():
            if name == field and which == "ES":
                upper = np.where((size_mm > over) & (size_mm <= up_to), value, upper)
        lower = upper - it
    return Limits(np.asarray(lower * _UM)[()], np.asarray(upper * _UM)[()])


def tolerance_class(name):
    """The canonical name of an ISO 492 tolerance class (``"P0"``, ``"normal"`` -> ``"Normal"``).

    Parameters
    ----------
    name : str
        ``Normal`` (also ``P0``, ``PN``), ``P6``, ``P5`` or ``P4``, in any case.

    Returns
    -------
    str
        One of :data:`TOLERANCE_CLASSES`.

    Examples
    --------
    >>> tolerance_class("p5"), tolerance_class("P0")
    ('P5', 'Normal')
    """
    key = str(name).strip().lower()
    if key not in _CLASS_ALIASES:
        raise InputError(f"tolerance-class must be one of {list(TOLERANCE_CLASSES)}, got {name!r}")
    return _CLASS_ALIASES[key]


def _bearing_limits(ring, size, klass, what):
    klass = tolerance_class(klass)
    rows = _iso492()[(ring, klass)]
    over = np.array([r[0] for r in rows])
    up_to = np.array([r[1] for r in rows])
    k = _range_index(np.asarray(size, dtype=float) / _MM, over, up_to, f"{what} (ISO 492 class {klass})")
    upper = np.array([r[2] for r in rows])[k] * _UM
    lower = np.array([r[3] for r in rows])[k] * _UM
    return Limits(np.asarray(lower)[()], np.asarray(upper)[()])


def bore_limits(bore, klass="Normal"):
    """Delta_dmp: the deviations of the mean bore diameter of a radial bearing's inner ring (ISO 492).

    Parameters
    ----------
    bore : array_like
        Nominal bore d, 0.6 < d <= 500 mm (P4: <= 250 mm). [m]
    klass : str
        Tolerance class, one of :data:`TOLERANCE_CLASSES` (or an alias such as ``"P0"``).

    Returns
    -------
    Limits
        Lower and upper deviation (the upper is 0). [m]

    References
    ----------
    .. [1] ISO 492:2014, Rolling bearings - Radial bearings - Geometrical product specifications (GPS)
       and tolerance values, tables 2, 4, 6 and 8.

    Examples
    --------
    >>> print(f"{bore_limits(0.050).lower * 1e6:g} um")
    -12 um
    """
    return _bearing_limits("inner", bore, klass, "bore")


def outside_diameter_limits(outside_diameter, klass="Normal"):
    """Delta_Dmp: the deviations of the mean outside diameter of a radial bearing's outer ring (ISO 492).

    Parameters
    ----------
    outside_diameter : array_like
        Nominal outside diameter D, 2.5 < D <= 630 mm (P4: <= 400 mm). [m]
    klass : str
        Tolerance class, one of :data:`TOLERANCE_CLASSES` (or an alias such as ``"P0"``).

    Returns
    -------
    Limits
        Lower and upper deviation (the upper is 0). [m]

    References
    ----------
    .. [1] ISO 492:2014, tables 3, 5, 7 and 9.

    Examples
    --------
    >>> print(f"{outside_diameter_limits(0.090).lower * 1e6:g} um")
    -15 um
    """
    return _bearing_limits("outer", outside_diameter, klass, "outside-diameter")

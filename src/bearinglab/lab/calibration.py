"""Calibration tables of the rig's microammeter (spec 001 section 5.2) and the conversion of readings.

Tables
------
CalibrationTable    readings and the values they stand for (one curve of the source's Figs. 5 and 6)
calibration_table   build and check a table: >= 2 points, strictly increasing readings and values
Calibration         the speed table and one torque table per sensitivity-switch position (1, 2)

Conversion
----------
convert             piecewise-linear interpolation between the table points, no extrapolation
convert_torque      torque readings taken at switch positions 1 or 2 -> torque

Values are in SI (speed in rad/s, torque in N*m); readings are in the instrument's own unit
(microamperes or scale divisions), which must be the one the table was made in.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from .._validate import as_float, check_finite
from ..errors import InputError

__all__ = [
    "SWITCH_POSITIONS",
    "Calibration",
    "CalibrationTable",
    "calibration_table",
    "convert",
    "convert_torque",
]

SWITCH_POSITIONS = (1, 2)  # spec 001 section 4: position 1 is the more sensitive one


class CalibrationTable(NamedTuple):
    """One calibration curve entered as a table."""

    readings: np.ndarray
    """Instrument readings I, strictly increasing. [-]"""
    values: np.ndarray
    """The quantity each reading stands for, strictly increasing (SI). [rad/s or N*m]"""
    name: str = "calibration"
    """Name used in messages, e.g. ``"torque position 1"``."""


class Calibration(NamedTuple):
    """All calibration tables of a session (spec 001 section 5.2)."""

    speed: CalibrationTable | None
    """Speed-mode table (reading -> rad/s), or None when every row gives the speed directly."""
    torque: dict
    """``{1: table, 2: table}`` torque-mode tables (reading -> N*m), per switch position."""


def _bad_point(message, point):
    exc = InputError(message)
    exc.point = point  # 0-based index of the offending point, for file-level messages
    return exc


def calibration_table(readings, values, *, name="calibration", unit="-"):
    """Build a calibration table and check it (spec 001 sections 5.2 and 9).

    Parameters
    ----------
    readings : array_like
        Instrument readings I of the table points. [-]
    values : array_like
        The values the readings stand for, in SI. [rad/s or N*m]
    name : str
        Name of the table for messages, e.g. ``"speed"`` or ``"torque position 2"``.
    unit : str
        Unit of ``values`` for messages. [-]

    Returns
    -------
    CalibrationTable

    Raises
    ------
    InputError
        Fewer than 2 points, unequal lengths, non-finite entries, or readings or values that are not
        strictly increasing. The exception carries ``point``, the 0-based index of the offending
        point (or None).

    Examples
    --------
    >>> calibration_table([0, 10, 20], [0.0, 0.5, 0.5], name="torque position 1", unit="N*m")
    Traceback (most recent call last):
    ...
    bearinglab.errors.InputError: calibration torque position 1: values must be strictly increasing [N*m], point 3 (reading 20) has 0.5 after 0.5
    """
    i = as_float(f"calibration {name} readings", readings).ravel()
    v = as_float(f"calibration {name} values", values).ravel()
    if i.size != v.size:
        raise _bad_point(f"calibration {name}: {i.size} readings but {v.size} values", None)
    if i.size < 2:
        raise _bad_point(f"calibration {name}: needs at least 2 points, got {i.size}", None)
    for arr, what, unit_ in ((i, "readings", "-"), (v, "values", unit)):
        bad = ~np.isfinite(arr)
        if bad.any():
            k = int(np.argmax(bad))
            raise _bad_point(
                f"calibration {name}: {what} must be finite [{unit_}], point {k + 1} has {arr[k]!r}",
                k,
            )
    for arr, what, unit_ in ((i, "readings", "-"), (v, "values", unit)):
        bad = ~(np.diff(arr) > 0)
        if bad.any():
            k = int(np.argmax(bad)) + 1
            raise _bad_point(
                f"calibration {name}: {what} must be strictly increasing [{unit_}], point {k + 1} "
                f"(reading {i[k]:g}) has {arr[k]:g} after {arr[k - 1]:g}",
                k,
            )
    return CalibrationTable(i, v, name)


def convert(reading, table):
    """Convert readings with a calibration table: piecewise-linear, no extrapolation.

    Parameters
    ----------
    reading : array_like
        Instrument readings; each must lie in [first, last] reading of the table (the ends are
        valid). [-]
    table : CalibrationTable
        The calibration curve.

    Returns
    -------
    float or ndarray
        The values, in the unit of the table (SI). [rad/s or N*m]

    Raises
    ------
    InputError
        A reading outside the calibrated range (spec 001 section 9).

    Notes
    -----
    Linear interpolation between neighbouring table points, the natural way to read a digitised
    curve (spec 001 section 5.2).

    Examples
    --------
    >>> t = calibration_table([0, 10, 20], [0.0, 455.0, 920.0], name="speed")
    >>> float(convert(15.0, t))
    687.5
    >>> convert(21.0, t)
    Traceback (most recent call last):
    ...
    bearinglab.errors.InputError: speed reading must be in [0, 20] (the calibrated range, no extrapolation), got 21.0
    """
    r = check_finite(f"{table.name} reading", reading, "-")
    lo, hi = table.readings[0], table.readings[-1]
    bad = ~((r >= lo) & (r <= hi))
    if bad.any():
        count = f" ({int(bad.sum())} of {r.size} values)" if r.size > 1 else ""
        raise InputError(
            f"{table.name} reading must be in [{lo:g}, {hi:g}] (the calibrated range, no "
            f"extrapolation), got {float(r[bad].flat[0]) if r.ndim else float(r)!r}{count}"
        )
    return np.interp(r, table.readings, table.values)[()]


def convert_torque(reading, switch, calibration):
    """Convert torque-mode readings taken at sensitivity-switch positions 1 or 2.

    Parameters
    ----------
    reading : array_like
        Torque-mode readings. [-]
    switch : array_like of int
        Sensitivity-switch position of each reading, 1 or 2. [-]
    calibration : Calibration
        The session's tables; the torque table of every position used must be present.

    Returns
    -------
    float or ndarray
        Friction torque. [N*m]

    Raises
    ------
    InputError
        An unknown switch position, a missing table, or a reading outside its table's range.

    Examples
    --------
    >>> t1 = calibration_table([0, 100], [0.0, 1.2e-4], name="torque position 1")
    >>> t2 = calibration_table([0, 100], [0.0, 5.0e-4], name="torque position 2")
    >>> cal = Calibration(None, {1: t1, 2: t2})
    >>> (convert_torque([50.0, 50.0], [1, 2], cal) * 1e3).tolist()
    [0.06, 0.25]
    """
    r = check_finite("torque reading", reading, "-")
    p = as_float("switch position", switch)
    r, p = np.broadcast_arrays(r, p)
    bad = ~np.isin(p, SWITCH_POSITIONS)
    if bad.any():
        raise InputError(f"switch position must be 1 or 2 [-], got {float(p[bad].flat[0])!r}")
    out = np.full(r.shape, np.nan)
    for pos in SWITCH_POSITIONS:
        use = p == pos
        if not use.any():
            continue
        table = calibration.torque.get(pos)
        if table is None:
            raise InputError(
                f"switch position {pos}: readings taken at position {pos} need the torque "
                f"calibration table of position {pos}"
            )
        out[use] = convert(r[use], table)
    return out[()]

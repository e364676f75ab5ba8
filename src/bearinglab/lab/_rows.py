"""The measurement rows of a session file (the CSV table of spec 001 section 5.3): columns, validation.

read_rows       the ``[measurements]`` table (inline ``csv`` or a ``file``) -> (Rows, file the rows are in)
parse_rows      CSV text -> Rows; every error names the file, the line and the field
Rows            the rows as arrays (SI), with their file line numbers
SERIES          the row series: T4 (load series at fixed tilt), T5 (speed series at fixed Q)

:mod:`bearinglab.lab.measurement` re-exports ``Rows`` and ``SERIES``, their public home.
"""

from __future__ import annotations

import csv
import math
import re
from pathlib import Path
from typing import NamedTuple

import numpy as np

from .._bounds import read_input_bytes
from ..errors import InputError
from ..units import parse_quantity

__all__ = ["SERIES", "Rows", "parse_rows", "read_rows"]

SERIES = (
    "T4",
    "T5",
)  # spec 001 section 5.3: T4 = load series at fixed tilt, T5 = speed series at fixed Q

# CSV columns: name -> (kind for parse_quantity or None, needs a unit in the header)
_COLUMNS = {
    "series": None,
    "tilt": "angle",
    "mass": "mass",
    "column": None,
    "speed_reading": "dimensionless",
    "torque_reading": "dimensionless",
    "switch": "dimensionless",
    "speed": "speed",
    "torque": "torque",
    "note": None,
}
_REQUIRED_COLUMNS = ("series", "tilt", "mass")
_UNIT_EXAMPLES = {"angle": "deg", "mass": "kg", "speed": "rpm", "torque": "N*mm"}


class Rows(NamedTuple):
    """Measurement rows of a session as arrays (one element per row, SI)."""

    series: np.ndarray
    """``"T4"`` or ``"T5"``."""
    tilt: np.ndarray
    """Tilt beta of the spindle axis from the vertical. [rad]"""
    mass: np.ndarray
    """Hung mass Q (without the tare). [kg]"""
    column: np.ndarray
    """Speed-column label of a T4 row (``""`` for T5)."""
    speed_reading: np.ndarray
    """Speed-mode reading, NaN when the speed is given directly. [-]"""
    torque_reading: np.ndarray
    """Torque-mode reading, NaN when the torque is given directly. [-]"""
    switch: np.ndarray
    """Sensitivity-switch position 1 or 2 of the torque reading, 0 when not given. [-]"""
    speed: np.ndarray
    """Directly given spindle speed, NaN when read. [rad/s]"""
    torque: np.ndarray
    """Directly given friction torque, NaN when read. [N*m]"""
    line: np.ndarray
    """Line of the row in :attr:`Session.rows_source`. [-]"""
    note: np.ndarray
    """Free-text note of the row."""


_DTYPES = {"series": object, "column": object, "note": object, "switch": int, "line": int}


def read_rows(table, calibration, ctx, base_dir):
    """The rows of the ``[measurements]`` table and the name of the file they are in.

    ``ctx`` locates the fields of the session file in its text (``error``, ``line``, ``loc``, ``source``).
    """
    if "csv" in table and "file" in table:
        raise ctx.error(
            ("measurements", "file"),
            "give the rows inline (csv = '''...''') or in a file, not both",
        )
    if "file" in table:
        rel = Path(str(table["file"]))
        path = rel if rel.is_absolute() else Path(base_dir or ".") / rel
        try:
            text = read_input_bytes(path).decode("utf-8")  # a regular file of bounded size
        except FileNotFoundError:
            raise ctx.error(("measurements", "file"), f"no such file: {path}") from None
        except (OSError, UnicodeDecodeError) as exc:
            raise ctx.error(("measurements", "file"), f"cannot read {path}: {exc}") from None
        return parse_rows(text, calibration, str(path), first_line=1, field_prefix=""), str(path)
    if "csv" in table:
        text = table["csv"]
        if not isinstance(text, str):
            raise ctx.error(("measurements", "csv"), "expected the rows as CSV text in ''' quotes")
        first = ctx.loc.strings.get(("measurements", "csv"), ctx.line(("measurements", "csv")) or 1)
        return parse_rows(
            text, calibration, ctx.source, first_line=first, field_prefix="measurements.csv: "
        ), ctx.source
    raise ctx.error(
        ("measurements",), "no measurement rows: give csv = '''...''' or file = \"rows.csv\""
    )


def parse_rows(text, calibration, source, *, first_line, field_prefix):
    """Rows of the CSV ``text`` whose first line is line ``first_line`` of ``source``."""
    header, header_line, data = None, None, []
    for offset, raw in enumerate(text.splitlines()):
        line_no = first_line + offset
        stripped = raw.strip()
        if not stripped or stripped.startswith("#"):
            continue
        cells = [c.strip() for c in next(csv.reader([raw], skipinitialspace=True))]
        if header is None:
            header, header_line = cells, line_no
        else:
            data.append((line_no, cells))
    if header is None:
        raise InputError(
            f"{source}, line {first_line}, field {field_prefix + 'header'!r}: no CSV header; "
            f"expected e.g. 'series, tilt [deg], mass [kg], column, speed_reading, "
            f"torque_reading, switch, speed [rpm], torque [N*mm]'"
        )
    columns = _columns(header, source, header_line)
    if not data:
        raise InputError(
            f"{source}, line {header_line}, field {field_prefix.rstrip(': ') or 'rows'!r}: "
            f"no measurement rows (only the header)"
        )
    out = {k: [] for k in Rows._fields}
    for row_no, (line_no, cells) in enumerate(data, start=1):
        row = _Row(cells, columns, source, line_no, row_no)
        for key, value in row.values(calibration).items():
            out[key].append(value)
    return Rows(**{k: np.array(v, dtype=_DTYPES.get(k)) for k, v in out.items()})


def _columns(header, source, line):
    """Header cells -> {name: (cell index, SI value of one header unit or None, unit text)}."""

    def fail(name, message):
        return InputError(f"{source}, line {line}, field {name!r}: {message}")

    columns = {}
    for index, cell in enumerate(header):
        m = re.fullmatch(r"\s*([A-Za-z_][A-Za-z0-9_ ]*?)\s*(?:\[(.*)\])?\s*", cell)
        name = m.group(1).strip().lower().replace(" ", "_") if m else cell
        unit = m.group(2).strip() if m and m.group(2) else None
        if not m or name not in _COLUMNS:
            raise fail(cell, f"unknown column (known: {', '.join(_COLUMNS)})")
        if name in columns:
            raise fail(name, "column given twice")
        kind = _COLUMNS[name]
        scale = None
        if kind in _UNIT_EXAMPLES:
            if unit is None:
                raise fail(
                    name, f"the header needs the unit, e.g. '{name} [{_UNIT_EXAMPLES[kind]}]'"
                )
            try:
                scale = parse_quantity(f"1 {unit}", kind, name)
            except InputError as exc:
                raise fail(name, str(exc)) from None
        elif unit is not None:
            raise fail(name, f"a {name} column has no unit, got [{unit}]")
        columns[name] = (index, scale, unit)
    for name in _REQUIRED_COLUMNS:
        if name not in columns:
            raise fail(name, "required column missing from the header")
    if "speed_reading" not in columns and "speed" not in columns:
        raise fail("speed", "the header needs speed_reading or speed [rpm]")
    if "torque_reading" not in columns and "torque" not in columns:
        raise fail("torque", "the header needs torque_reading or torque [N*mm]")
    return columns


class _Row:
    """One data row: its cells by column name, read and checked; errors name file, line and field."""

    def __init__(self, cells, columns, source, line, row):
        self.columns, self.source, self.line, self.row = columns, source, line, row
        width = max(i for i, _s, _u in columns.values()) + 1
        if len(cells) > len(columns) and any(cells[len(columns) :]):
            raise self.fail("row", f"{len(cells)} cells but the header has {len(columns)} columns")
        self.cells = cells + [""] * (width - len(cells))

    def fail(self, column, message):
        where = f"{self.source}, line {self.line}" + (f" (row {self.row})" if self.row else "")
        return InputError(f"{where}, field {column!r}: {message}")

    def text(self, name):
        return self.cells[self.columns[name][0]] if name in self.columns else ""

    def number(self, name):
        t = self.text(name)
        if t == "":
            return None
        try:
            v = float(t)
        except ValueError:
            raise self.fail(name, f"cannot read {t!r} as a number") from None
        if not math.isfinite(v):
            raise self.fail(name, f"must be a finite number, got {t!r}")
        return v

    def scale(self, name):
        return self.columns[name][1]

    def values(self, calibration):
        """The row as {Rows field: value} (SI; NaN / 0 / "" for what is not given)."""
        series, tilt, mass, label = self._keys()
        speed_reading, speed = self._speed(calibration)
        torque_reading, torque, switch = self._torque(calibration)
        return {
            "series": series,
            "tilt": tilt,
            "mass": mass,
            "column": label if series == "T4" else "",
            "speed_reading": np.nan if speed_reading is None else speed_reading,
            "torque_reading": np.nan if torque_reading is None else torque_reading,
            "switch": 0 if switch is None else int(switch),
            "speed": np.nan if speed is None else speed,
            "torque": np.nan if torque is None else torque,
            "line": self.line,
            "note": self.text("note"),
        }

    def _keys(self):
        """Series, tilt [rad], mass [kg] and speed-column label."""
        series = self.text("series").upper()
        if series not in SERIES:
            raise self.fail(
                "series",
                f"must be T4 (load series at fixed tilt) or T5 (speed series at fixed Q), "
                f"got {self.text('series')!r}",
            )
        tilt_v = self.number("tilt")
        if tilt_v is None:
            raise self.fail("tilt", "missing")
        tilt = tilt_v * self.scale("tilt")
        tilt_deg = math.degrees(tilt)
        if not -1e-9 <= tilt_deg <= 90.0 + 1e-9:
            raise self.fail("tilt", f"must be in [0, 90] [deg], got {tilt_deg:g}")
        tilt = min(max(tilt, 0.0), math.pi / 2)
        mass_v = self.number("mass")
        if mass_v is None:
            raise self.fail("mass", "missing")
        mass = mass_v * self.scale("mass")
        if not mass > 0:
            raise self.fail("mass", f"must be > 0 [kg], got {mass:g}")
        label = self.text("column")
        if series == "T4" and not label:
            raise self.fail(
                "column",
                "a T4 row needs its speed-column label (rows taken at the same speed setting "
                "share a label)",
            )
        return series, tilt, mass, label

    def _speed(self, calibration):
        """Speed reading (checked against its calibration) or direct speed [rad/s]."""
        speed_reading, speed = self.number("speed_reading"), self.number("speed")
        if speed_reading is not None and speed is not None:
            raise self.fail(
                "speed", "give the speed reading or the speed, not both"
            )
        if speed_reading is None and speed is None:
            raise self.fail("speed", "missing: give speed_reading or speed")
        if speed is not None:
            speed *= self.scale("speed")
            if speed < 0:
                raise self.fail("speed", f"must be >= 0 [rpm], got {speed / (2 * math.pi / 60):g}")
        else:
            if calibration.speed is None:
                raise self.fail(
                    "speed_reading",
                    "a speed reading needs the speed calibration table ([calibration.speed] points)",
                )
            self._check_range(speed_reading, calibration.speed, "speed_reading")
        return speed_reading, speed

    def _torque(self, calibration):
        """Torque reading with its switch position (checked against its table) or direct torque."""
        torque_reading, torque = self.number("torque_reading"), self.number("torque")
        switch = self.number("switch")
        if torque_reading is not None and torque is not None:
            raise self.fail(
                "torque", "give the torque reading or the torque, not both"
            )
        if torque_reading is None and torque is None:
            raise self.fail("torque", "missing: give torque_reading (with switch) or torque")
        if switch is not None and switch not in (1.0, 2.0):
            raise self.fail(
                "switch", f"the switch position must be 1 or 2, got {self.text('switch')}"
            )
        if torque is not None:
            torque *= self.scale("torque")
            if torque < 0:
                raise self.fail("torque", f"must be >= 0 [N*mm], got {torque * 1e3:g}")
        else:
            if switch is None:
                raise self.fail(
                    "switch",
                    "a torque reading needs its switch position (1 or 2)",
                )
            table = calibration.torque.get(int(switch))
            if table is None:
                raise self.fail(
                    "torque_reading",
                    f"a reading at switch position {int(switch)} needs the table "
                    f"[calibration.torque_{int(switch)}]",
                )
            self._check_range(torque_reading, table, "torque_reading")
        return torque_reading, torque, switch

    def _check_range(self, reading, table, column):
        lo, hi = table.readings[0], table.readings[-1]
        if not lo <= reading <= hi:
            raise self.fail(
                column,
                f"{reading:g} is outside the calibrated range [{lo:g}, {hi:g}] of the "
                f"{table.name} table (no extrapolation)",
            )


def _by_tilt(tilt):
    """Row indices grouped by their tilt (in order of first appearance): tilt -> [k, ...]."""
    out = {}
    for k, t in enumerate(tilt):
        out.setdefault(float(t), []).append(k)
    return out

r"""The measurement-session file of the friction-rig lab: format, reader, validation and blank template.

Reading
-------
read_session       a session file (TOML; rows inline as CSV text or in a separate CSV file) -> Session
parse_session      the same from text already in memory (``source`` names it in messages)

Writing
-------
template           the text of a blank, commented session file
write_template     write it to a new file (never over an existing one unless asked; written whole)

Data
----
Session            everything a session holds: bearing, handbook constants, rig, calibration, rows
Handbook           the handbook constants in force (Table 1, Table 2, mu), with the overrides named
Rows               the measurement rows as arrays (SI), with their file line numbers
FORMAT             the format identifier written by :func:`template`

Format (one file; quantities are strings with units; see ``examples/friction/README.md``)::

    format = "bearinglab-friction-session/1"
    [session]      title, date, operator, rig, lubricant, notes (free text, shown in the report)
    [bearing]      catalog = "18"  and/or  designation, type, contact_angle, bore,
                   mean_diameter or outside_diameter, static_load_rating
    [handbook]     optional overrides: x0, y0, mu, f, c (plain numbers)
    [rig]          tare_mass = "0 kg", gravity = "9.81 m/s^2"
    [calibration.speed], [calibration.torque_1], [calibration.torque_2]
                   unit = "rpm" | "N*mm" ...;  points = [[reading, value], ...]
    [measurements] csv = '''...'''  (inline)  or  file = "rows.csv"  (next to the TOML file)

The CSV header names the columns, with the unit of every dimensional column in brackets::

    series, tilt [deg], mass [kg], column, speed_reading, torque_reading, switch, speed [rpm], torque [N*mm], note

A row carries a speed reading *or* a direct speed, and a torque reading (with its switch position)
*or* a direct torque (spec 001 section 5.3). Every error names the file, the line and the field.
The input files are only read, never written.
"""

from __future__ import annotations

import csv
import dataclasses
import math
import re
import tomllib
from dataclasses import dataclass, field
from pathlib import Path
from typing import NamedTuple

import numpy as np

from .. import catalog as _catalog
from .. import friction
from .._io import atomic_output
from ..bearing import BallBearing
from ..errors import CatalogError, InputError
from ..units import parse_quantity
from .calibration import Calibration, calibration_table
from .rig import GRAVITY

__all__ = [
    "FORMAT",
    "SERIES",
    "Handbook",
    "Rows",
    "Session",
    "parse_session",
    "read_session",
    "template",
    "write_template",
]

FORMAT = "bearinglab-friction-session/1"
SERIES = (
    "T4",
    "T5",
)  # spec 001 section 5.3: T4 = load series at fixed tilt, T5 = speed series at fixed Q

_KNOWN = {
    (): {"format", "session", "bearing", "handbook", "rig", "calibration", "measurements"},
    ("session",): {"title", "date", "operator", "rig", "lubricant", "notes"},
    ("bearing",): {
        "catalog",
        "designation",
        "type",
        "contact_angle",
        "bore",
        "mean_diameter",
        "outside_diameter",
        "static_load_rating",
    },
    ("handbook",): {"x0", "y0", "mu", "f", "c"},
    ("rig",): {"tare_mass", "gravity"},
    ("calibration",): {"speed", "torque_1", "torque_2"},
    ("calibration", "speed"): {"unit", "points"},
    ("calibration", "torque_1"): {"unit", "points"},
    ("calibration", "torque_2"): {"unit", "points"},
    ("measurements",): {"csv", "file"},
}
_CALIBRATIONS = {
    "speed": ("speed", "speed"),
    "torque_1": ("torque", "torque position 1"),
    "torque_2": ("torque", "torque position 2"),
}
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


class Handbook(NamedTuple):
    """Handbook constants in force for a session (Tables 1 and 2, section 3.2, or overrides)."""

    radial_factor: float
    """x0. [-]"""
    axial_factor: float
    """y0. [-]"""
    friction_coefficient: float
    """mu_hb. [-]"""
    load_term_factor: float
    """f_hb. [-]"""
    load_term_exponent: float
    """c (= e). [-]"""
    overridden: tuple
    """Names (x0, y0, mu, f, c) given in the file instead of taken from the tables."""


@dataclass(frozen=True)
class Session:
    """One measurement session: the bearing, the handbook constants, the rig, calibration and rows."""

    bearing: BallBearing
    """The test bearing (type, contact angle, bore, outside diameter, C0)."""
    handbook: Handbook
    """Handbook constants in force."""
    calibration: Calibration
    """Calibration tables (missing tables are None / absent)."""
    rows: Rows
    """The measurement rows."""
    tare_mass: float = 0.0
    """Mass added to every Q. [kg]"""
    gravity: float = GRAVITY
    """Acceleration of gravity. [m/s^2]"""
    info: dict = field(default_factory=dict, compare=False)
    """Free-text session data: title, date, operator, rig, lubricant, notes."""
    source: str = "<session>"
    """The session file."""
    rows_source: str = "<session>"
    """The file the rows are in (the session file or its CSV)."""


# ----------------------------------------------------------------------------- locating keys in TOML text
_KEY = r'(?:[A-Za-z0-9_-]+|"(?:[^"\\]|\\.)*"|\'[^\']*\')'
_KEY_RE = re.compile(rf"[ \t]*({_KEY}(?:[ \t]*\.[ \t]*{_KEY})*)[ \t]*=")
_HEADER_RE = re.compile(rf"[ \t]*\[\[?[ \t]*({_KEY}(?:[ \t]*\.[ \t]*{_KEY})*)[ \t]*\]\]?")


def _split_key(text):
    parts = re.findall(_KEY, text)
    return tuple(p[1:-1] if p[:1] in "\"'" else p for p in parts)


class _Locations(NamedTuple):
    keys: dict  # full key path -> line
    items: dict  # full key path -> lines where the elements of a nested array start
    strings: dict  # full key path -> line of the first content line of a multi-line string


def _locate(text):
    """Line numbers of the tables, keys, nested-array elements and multi-line strings of valid TOML."""
    keys, items, strings = {}, {}, {}
    table, key = (), ()
    i, n, line, depth, line_start = 0, len(text), 1, 0, True
    while i < n:
        c = text[i]
        if c == "\n":
            line, line_start = line + 1, True
            i += 1
            continue
        if c in " \t\r":
            i += 1
            continue
        if c == "#":
            j = text.find("\n", i)
            i = n if j < 0 else j
            continue
        if depth == 0 and line_start:
            line_start = False
            m = _HEADER_RE.match(text, i) if c == "[" else None
            if m:
                table = _split_key(m.group(1))
                keys[table] = line
                i = m.end()
                continue
            m = _KEY_RE.match(text, i)
            if m:
                key = table + _split_key(m.group(1))
                keys[key] = line
                i = m.end()
                continue
        line_start = False
        for delim in ('"""', "'''"):
            if text.startswith(delim, i):
                j = i + 3
                strings[key] = (
                    line + 1 if text.startswith("\n", j) or text.startswith("\r\n", j) else line
                )
                end = j
                while True:
                    end = text.find(delim, end)
                    if end < 0 or delim == "'''" or text[end - 1] != "\\":
                        break
                    end += 1
                end = n if end < 0 else end + 3
                while text.startswith(delim[0], end) and end < n:  # up to two quotes may close it
                    end += 1
                line += text.count("\n", i, end)
                i = end
                break
        else:
            if c in "\"'":
                j = i + 1
                while j < n and text[j] != c and text[j] != "\n":
                    j += 2 if (c == '"' and text[j] == "\\") else 1
                i = j + 1
                continue
            if c in "[{":
                depth += 1
                if depth == 2 and c == "[":
                    items.setdefault(key, []).append(line)
            elif c in "]}":
                depth -= 1
            i += 1
    return _Locations(keys, items, strings)


class _Context:
    """Builds messages that name the file, the line and the field."""

    def __init__(self, source, locations):
        self.source = source
        self.loc = locations

    def line(self, path):
        path = tuple(path)
        while path:
            if path in self.loc.keys:
                return self.loc.keys[path]
            path = path[:-1]
        return None

    def error(self, path, message, *, line=None):
        line = self.line(path) if line is None else line
        where = f"{self.source}, line {line}" if line else f"{self.source}"
        return InputError(f"{where}, field {'.'.join(path)!r}: {message}")


# ----------------------------------------------------------------------------- reading
def read_session(path):
    """Read and validate a measurement-session file.

    Parameters
    ----------
    path : str or Path
        The session TOML file. Its ``[measurements] file`` (if any) is read relative to it.

    Returns
    -------
    Session

    Raises
    ------
    InputError
        Anything invalid; the message names the file, the line and the field (spec 001 section 9).

    Examples
    --------
    >>> s = parse_session(template(bearing="18"), source="new.toml")
    Traceback (most recent call last):
    ...
    bearinglab.errors.InputError: new.toml, line 64, field 'measurements.csv': no measurement rows (only the header)
    """
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8")
    except FileNotFoundError:
        raise InputError(f"{path}: no such file") from None
    except UnicodeDecodeError as exc:
        raise InputError(
            f"{path}: not a UTF-8 text file ({exc.reason} at byte {exc.start})"
        ) from None
    except OSError as exc:
        raise InputError(f"{path}: cannot read: {exc.strerror}") from None
    return parse_session(text, source=str(path), base_dir=path.parent)


def parse_session(text, *, source="<session>", base_dir=None):
    """Parse and validate the text of a measurement-session file.

    Parameters
    ----------
    text : str
        The TOML text.
    source : str
        Name of the file, used in messages.
    base_dir : str or Path, optional
        Directory against which ``[measurements] file`` is resolved (default: the current one).

    Returns
    -------
    Session

    Raises
    ------
    InputError
        Naming the file, the line and the field.
    """
    try:
        doc = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise InputError(f"{source}: not valid TOML: {exc}") from None
    ctx = _Context(source, _locate(text))
    _check_known(doc, (), ctx)
    fmt = doc.get("format", FORMAT)
    if fmt != FORMAT:
        raise ctx.error(("format",), f"unknown format {fmt!r}; this version reads {FORMAT!r}")
    info = {k: str(v) for k, v in _table(doc, ("session",), ctx).items()}
    bearing = _bearing(_table(doc, ("bearing",), ctx), ctx)
    handbook = _handbook(_table(doc, ("handbook",), ctx), bearing, ctx)
    rig = _table(doc, ("rig",), ctx)
    tare = _quantity(rig, ("rig", "tare_mass"), "mass", ctx, default=0.0)
    if tare < 0:
        raise ctx.error(("rig", "tare_mass"), f"must be >= 0 [kg], got {tare!r}")
    gravity = GRAVITY
    if "gravity" in rig:
        gravity = _acceleration(rig["gravity"], ("rig", "gravity"), ctx)
    calibration = _calibration(_table(doc, ("calibration",), ctx), ctx)
    rows, rows_source = _rows(_table(doc, ("measurements",), ctx), calibration, ctx, base_dir)
    return Session(
        bearing=bearing,
        handbook=handbook,
        calibration=calibration,
        rows=rows,
        tare_mass=tare,
        gravity=gravity,
        info=info,
        source=source,
        rows_source=rows_source,
    )


def _check_known(doc, path, ctx):
    known = _KNOWN.get(path)
    if known is None:
        return
    for key, value in doc.items():
        if key not in known:
            raise ctx.error(
                path + (key,), f"unknown field (known here: {', '.join(sorted(known))})"
            )
        if isinstance(value, dict):
            _check_known(value, path + (key,), ctx)


def _table(doc, path, ctx):
    value = doc
    for key in path:
        value = value.get(key, {}) if isinstance(value, dict) else {}
    if not isinstance(value, dict):
        raise ctx.error(path, f"expected a table, got {type(value).__name__}")
    return value


def _quantity(table, path, kind, ctx, *, default=None):
    key = path[-1]
    if key not in table:
        return default
    if table[key] == "":
        raise ctx.error(path, "is empty; fill it in (a number with its unit) or delete the line")
    try:
        return parse_quantity(table[key], kind, key)
    except InputError as exc:
        raise ctx.error(path, str(exc)) from None


def _acceleration(value, path, ctx):
    if not isinstance(value, str):
        raise ctx.error(
            path, f"expected an acceleration with its unit, e.g. '9.81 m/s^2', got {value!r}"
        )
    try:
        g = parse_quantity(
            f"{value} * kg", "force", path[-1]
        )  # an acceleration times 1 kg is a force in N
    except InputError:
        raise ctx.error(
            path, f"expected an acceleration with its unit, e.g. '9.81 m/s^2', got {value!r}"
        ) from None
    if not g > 0:
        raise ctx.error(path, f"must be > 0 [m/s^2], got {g!r}")
    return g


def _bearing(table, ctx):
    if "catalog" in table:
        try:
            base = _catalog.get(str(table["catalog"]))
        except CatalogError as exc:
            raise ctx.error(("bearing", "catalog"), str(exc)) from None
    elif not table:
        raise ctx.error(
            ("bearing",),
            'give catalog = "NAME" (e.g. "18") or the bearing\'s type, bore, '
            "mean_diameter (or outside_diameter) and static_load_rating",
        )
    elif "type" not in table:
        raise ctx.error(
            ("bearing",), 'give the bearing\'s type = "radial" or "angular" (or a catalog name)'
        )
    else:
        base = BallBearing(designation="inline", type="radial")
    kw = {}
    if "designation" in table:
        kw["designation"] = str(table["designation"])
    if "type" in table:
        if table["type"] not in friction.BEARING_TYPES:
            raise ctx.error(
                ("bearing", "type"),
                f"must be one of {list(friction.BEARING_TYPES)}, got {table['type']!r}",
            )
        kw["type"] = table["type"]
    if "mean_diameter" in table and "outside_diameter" in table:
        raise ctx.error(
            ("bearing", "mean_diameter"), "give mean_diameter or outside_diameter, not both"
        )
    for key, kind in (
        ("contact_angle", "angle"),
        ("bore", "length"),
        ("outside_diameter", "length"),
        ("static_load_rating", "force"),
    ):
        if key in table:
            kw[key] = _quantity(table, ("bearing", key), kind, ctx)
    bore = kw.get("bore", base.bore)
    if "mean_diameter" in table:
        dm = _quantity(table, ("bearing", "mean_diameter"), "length", ctx)
        if bore is None:
            raise ctx.error(
                ("bearing", "mean_diameter"), "needs bore as well (d_m = (d + D)/2 gives D)"
            )
        if not dm > bore:
            raise ctx.error(
                ("bearing", "mean_diameter"),
                f"must be > bore [mm], got {dm * 1e3:g} mm with bore {bore * 1e3:g} mm",
            )
        kw["outside_diameter"] = 2.0 * dm - bore
    if "contact_angle" in kw:
        kw["radial_clearance"] = None
    elif kw.get("type", base.type) != base.type:
        kw["contact_angle"], kw["radial_clearance"] = (
            None,
            None,
        )  # the catalog angle belongs to the old type
    try:
        bearing = dataclasses.replace(base, **kw)
    except InputError as exc:
        msg = str(exc)
        name = msg.split(" ", 1)[0]
        if name == "outside_diameter" and "mean_diameter" in table:
            name = "mean_diameter"
        raise ctx.error(
            ("bearing", name if name in _KNOWN[("bearing",)] else "type"), msg
        ) from None
    for key, label in (
        ("bore", "bore"),
        ("outside_diameter", "mean_diameter (or outside_diameter)"),
        ("static_load_rating", "static_load_rating"),
    ):
        if getattr(bearing, key) is None:
            raise ctx.error(
                ("bearing",), f"the bearing's {label} is not known; give it in [bearing]"
            )
    if bearing.type == "angular" and bearing.contact_angle is None:
        raise ctx.error(("bearing",), "an angular-contact bearing needs contact_angle")
    return bearing


def _handbook(table, bearing, ctx):
    values = {}
    for key in ("x0", "y0", "mu", "f", "c"):
        if key in table:
            v = table[key]
            if (
                isinstance(v, bool)
                or not isinstance(v, (int, float))
                or not math.isfinite(v)
                or v < 0
            ):
                raise ctx.error(("handbook", key), f"must be a plain number >= 0 [-], got {v!r}")
            values[key] = float(v)
    angle = bearing.contact_angle if bearing.type == "angular" else None
    if "x0" not in values or "y0" not in values:
        try:
            x0, y0 = friction.static_load_factors(bearing.type, angle)
        except InputError as exc:
            raise ctx.error(
                ("bearing", "contact_angle"), f"{exc}; or give x0 and y0 in [handbook]"
            ) from None
        values.setdefault("x0", float(x0))
        values.setdefault("y0", float(y0))
    if "f" not in values or "c" not in values:
        f, c = friction.load_term_constants(bearing.type, angle)
        values.setdefault("f", float(f))
        values.setdefault("c", float(c))
    values.setdefault("mu", friction.handbook_friction_coefficient(bearing.type))
    given = tuple(k for k in ("x0", "y0", "mu", "f", "c") if k in table)
    return Handbook(values["x0"], values["y0"], values["mu"], values["f"], values["c"], given)


def _calibration(table, ctx):
    tables = {}
    for key, (kind, name) in _CALIBRATIONS.items():
        sub = table.get(key)
        if sub is None:
            continue
        path = ("calibration", key)
        points = sub.get("points", [])
        if not isinstance(points, list):
            raise ctx.error(
                path + ("points",), f"expected a list of [reading, value] pairs, got {points!r}"
            )
        if not points:
            continue  # an empty table (as in the template) is a table not given
        if "unit" not in sub:
            raise ctx.error(
                path + ("unit",),
                f"give the unit of the values, e.g. unit = "
                f'"{"rpm" if kind == "speed" else "N*mm"}"',
                line=ctx.line(path),
            )
        try:
            scale = parse_quantity(f"1 {sub['unit']}", kind, "unit")
        except InputError as exc:
            raise ctx.error(path + ("unit",), str(exc)) from None
        lines = ctx.loc.items.get(path + ("points",), [])
        readings, values = [], []
        for k, point in enumerate(points):
            line = lines[k] if k < len(lines) else ctx.line(path + ("points",))
            ok = (
                isinstance(point, list)
                and len(point) == 2
                and all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in point)
            )
            if not ok:
                raise ctx.error(
                    path + ("points",),
                    f"point {k + 1} must be [reading, value] (two numbers), got {point!r}",
                    line=line,
                )
            readings.append(float(point[0]))
            values.append(float(point[1]) * scale)
        try:
            tables[key] = calibration_table(readings, values, name=name, unit=str(sub["unit"]))
        except InputError as exc:
            k = getattr(exc, "point", None)
            line = lines[k] if k is not None and k < len(lines) else ctx.line(path + ("points",))
            msg = str(exc)
            if k is not None:  # show the values in the file's unit
                msg = _table_message(
                    readings, [v / scale for v in values], k, name, sub["unit"], msg
                )
            raise ctx.error(path + ("points",), msg, line=line) from None
    return Calibration(
        tables.get("speed"), {p: tables[f"torque_{p}"] for p in (1, 2) if f"torque_{p}" in tables}
    )


def _table_message(readings, values, k, name, unit, fallback):
    if k > 0 and not readings[k] > readings[k - 1]:
        return (
            f"calibration {name}: readings must be strictly increasing, point {k + 1} has reading "
            f"{readings[k]:g} after {readings[k - 1]:g}"
        )
    if k > 0 and not values[k] > values[k - 1]:
        return (
            f"calibration {name}: values must be strictly increasing [{unit}], point {k + 1} (reading "
            f"{readings[k]:g}) has {values[k]:g} after {values[k - 1]:g}"
        )
    return fallback


# ----------------------------------------------------------------------------- rows
def _rows(table, calibration, ctx, base_dir):
    if "csv" in table and "file" in table:
        raise ctx.error(
            ("measurements", "file"),
            "give the rows inline (csv = '''...''') or in a file, not both",
        )
    if "file" in table:
        rel = Path(str(table["file"]))
        path = rel if rel.is_absolute() else Path(base_dir or ".") / rel
        try:
            text = path.read_text(encoding="utf-8")
        except FileNotFoundError:
            raise ctx.error(("measurements", "file"), f"no such file: {path}") from None
        except (OSError, UnicodeDecodeError) as exc:
            raise ctx.error(("measurements", "file"), f"cannot read {path}: {exc}") from None
        return _parse_rows(text, calibration, str(path), first_line=1, field_prefix=""), str(path)
    if "csv" in table:
        text = table["csv"]
        if not isinstance(text, str):
            raise ctx.error(("measurements", "csv"), "expected the rows as CSV text in ''' quotes")
        first = ctx.loc.strings.get(("measurements", "csv"), ctx.line(("measurements", "csv")) or 1)
        return _parse_rows(
            text, calibration, ctx.source, first_line=first, field_prefix="measurements.csv: "
        ), ctx.source
    raise ctx.error(
        ("measurements",), "no measurement rows: give csv = '''...''' or file = \"rows.csv\""
    )


def _row_error(source, line, row, column, message):
    where = f"{source}, line {line}" + (f" (row {row})" if row else "")
    return InputError(f"{where}, field {column!r}: {message}")


def _parse_rows(text, calibration, source, *, first_line, field_prefix):
    lines = text.splitlines()
    header, header_line, data = None, None, []
    for offset, raw in enumerate(lines):
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
        _parse_row(cells, columns, calibration, source, line_no, row_no, out)
    return Rows(
        series=np.array(out["series"], dtype=object),
        tilt=np.array(out["tilt"]),
        mass=np.array(out["mass"]),
        column=np.array(out["column"], dtype=object),
        speed_reading=np.array(out["speed_reading"]),
        torque_reading=np.array(out["torque_reading"]),
        switch=np.array(out["switch"], dtype=int),
        speed=np.array(out["speed"]),
        torque=np.array(out["torque"]),
        line=np.array(out["line"], dtype=int),
        note=np.array(out["note"], dtype=object),
    )


def _columns(header, source, line):
    columns = {}
    for index, cell in enumerate(header):
        m = re.fullmatch(r"\s*([A-Za-z_][A-Za-z0-9_ ]*?)\s*(?:\[(.*)\])?\s*", cell)
        name = m.group(1).strip().lower().replace(" ", "_") if m else cell
        unit = m.group(2).strip() if m and m.group(2) else None
        if not m or name not in _COLUMNS:
            raise InputError(
                f"{source}, line {line}, field {cell!r}: unknown column (known: "
                f"{', '.join(_COLUMNS)})"
            )
        if name in columns:
            raise InputError(f"{source}, line {line}, field {name!r}: column given twice")
        kind = _COLUMNS[name]
        scale = None
        if kind in ("angle", "mass", "speed", "torque"):
            if unit is None:
                example = {"angle": "deg", "mass": "kg", "speed": "rpm", "torque": "N*mm"}[kind]
                raise InputError(
                    f"{source}, line {line}, field {name!r}: the header needs the unit, "
                    f"e.g. '{name} [{example}]'"
                )
            try:
                scale = parse_quantity(f"1 {unit}", kind, name)
            except InputError as exc:
                raise InputError(f"{source}, line {line}, field {name!r}: {exc}") from None
        elif unit is not None:
            raise InputError(
                f"{source}, line {line}, field {name!r}: a {name} column has no unit, got [{unit}]"
            )
        columns[name] = (index, scale, unit)
    for name in _REQUIRED_COLUMNS:
        if name not in columns:
            raise InputError(
                f"{source}, line {line}, field {name!r}: required column missing from the header"
            )
    if "speed_reading" not in columns and "speed" not in columns:
        raise InputError(
            f"{source}, line {line}, field 'speed': the header needs speed_reading or speed [rpm]"
        )
    if "torque_reading" not in columns and "torque" not in columns:
        raise InputError(
            f"{source}, line {line}, field 'torque': the header needs torque_reading or torque [N*mm]"
        )
    return columns


def _parse_row(cells, columns, calibration, source, line, row, out):
    def fail(column, message):
        return _row_error(source, line, row, column, message)

    width = max(i for i, _s, _u in columns.values()) + 1
    if len(cells) > len(columns) and any(cells[len(columns) :]):
        raise fail("row", f"{len(cells)} cells but the header has {len(columns)} columns")
    cells = cells + [""] * (width - len(cells))

    def text(name):
        return cells[columns[name][0]] if name in columns else ""

    def number(name):
        t = text(name)
        if t == "":
            return None
        try:
            v = float(t)
        except ValueError:
            raise fail(name, f"cannot read {t!r} as a number") from None
        if not math.isfinite(v):
            raise fail(name, f"must be a finite number, got {t!r}")
        return v

    series = text("series").upper()
    if series not in SERIES:
        raise fail(
            "series",
            f"must be T4 (load series at fixed tilt) or T5 (speed series at fixed Q), "
            f"got {text('series')!r}",
        )
    tilt_v = number("tilt")
    if tilt_v is None:
        raise fail("tilt", "missing")
    tilt = tilt_v * columns["tilt"][1]
    tilt_deg = math.degrees(tilt)
    if not -1e-9 <= tilt_deg <= 90.0 + 1e-9:
        raise fail("tilt", f"must be in [0, 90] [deg], got {tilt_deg:g}")
    tilt = min(max(tilt, 0.0), math.pi / 2)
    mass_v = number("mass")
    if mass_v is None:
        raise fail("mass", "missing")
    mass = mass_v * columns["mass"][1]
    if not mass > 0:
        raise fail("mass", f"must be > 0 [kg], got {mass:g}")
    label = text("column")
    if series == "T4" and not label:
        raise fail(
            "column",
            "a T4 row needs its speed-column label (rows taken at the same speed setting "
            "share a label)",
        )
    speed_reading, speed = number("speed_reading"), number("speed")
    if speed_reading is not None and speed is not None:
        raise fail("speed", "give the speed reading or the speed, not both (spec 001 section 5.3)")
    if speed_reading is None and speed is None:
        raise fail("speed", "missing: give speed_reading or speed")
    if speed is not None:
        speed *= columns["speed"][1]
        if speed < 0:
            raise fail("speed", f"must be >= 0 [rpm], got {speed / (2 * math.pi / 60):g}")
    else:
        if calibration.speed is None:
            raise fail(
                "speed_reading",
                "a speed reading needs the speed calibration table ([calibration.speed] points)",
            )
        _check_range(speed_reading, calibration.speed, fail, "speed_reading")
    torque_reading, torque = number("torque_reading"), number("torque")
    switch = number("switch")
    if torque_reading is not None and torque is not None:
        raise fail(
            "torque", "give the torque reading or the torque, not both (spec 001 section 5.3)"
        )
    if torque_reading is None and torque is None:
        raise fail("torque", "missing: give torque_reading (with switch) or torque")
    if switch is not None and switch not in (1.0, 2.0):
        raise fail("switch", f"the switch position must be 1 or 2, got {text('switch')}")
    if torque is not None:
        torque *= columns["torque"][1]
        if torque < 0:
            raise fail("torque", f"must be >= 0 [N*mm], got {torque * 1e3:g}")
    else:
        if switch is None:
            raise fail(
                "switch",
                "a torque reading needs its switch position (1 or 2; spec 001 section 8.12)",
            )
        table = calibration.torque.get(int(switch))
        if table is None:
            raise fail(
                "torque_reading",
                f"a reading at switch position {int(switch)} needs the table "
                f"[calibration.torque_{int(switch)}]",
            )
        _check_range(torque_reading, table, fail, "torque_reading")
    out["series"].append(series)
    out["tilt"].append(tilt)
    out["mass"].append(mass)
    out["column"].append(label if series == "T4" else "")
    out["speed_reading"].append(np.nan if speed_reading is None else speed_reading)
    out["torque_reading"].append(np.nan if torque_reading is None else torque_reading)
    out["switch"].append(0 if switch is None else int(switch))
    out["speed"].append(np.nan if speed is None else speed)
    out["torque"].append(np.nan if torque is None else torque)
    out["line"].append(line)
    out["note"].append(text("note"))


def _check_range(reading, table, fail, column):
    lo, hi = table.readings[0], table.readings[-1]
    if not lo <= reading <= hi:
        raise fail(
            column,
            f"{reading:g} is outside the calibrated range [{lo:g}, {hi:g}] of the "
            f"{table.name} table (no extrapolation)",
        )


# ----------------------------------------------------------------------------- template
_TEMPLATE = """\
# bearinglab friction-rig measurement session (spec 001; DP11A-type rig).
# Fill in the bearing, the calibration tables and the rows, then run
#     bearinglab friction lab THIS_FILE --out report-dir
# Quantities are strings with units ("8 mm", "1354 N", "0 kg"). Lines starting with # are comments.
# The format is documented in examples/friction/README.md.
format = "{format}"

[session]
title = ""
date = ""                 # e.g. "2024-03-14"
operator = ""
rig = "DP11A"
lubricant = ""            # oil or grease, and the temperature if known
notes = ""

[bearing]
{bearing_block}

[handbook]
# Optional overrides of the handbook constants (plain numbers). Without them the tables of spec 001
# section 3 apply: Table 1 (x0, y0), mu of section 3.2, Table 2 (f, c).
# x0 = 0.6
# y0 = 0.5
# mu = 0.0015
# f = 0.0009
# c = 0.55

[rig]
tare_mass = "0 kg"        # added to every Q (housing, holder); the source uses 0
gravity = "9.81 m/s^2"    # the source's value

# Calibration tables (spec 001 section 5.2): [reading, value] pairs with strictly increasing readings
# and values, at least 2 points. Conversion is piecewise linear; a reading outside a table is an
# error. Leave a table empty if no row uses it (rows may give speed and torque directly).
[calibration.speed]
unit = "rpm"
points = [
    # [0, 0],
    # [10, 455],
]

[calibration.torque_1]    # switch position 1 (the more sensitive one)
unit = "N*mm"
points = [
    # [0, 0.0],
    # [10, 0.0102],
]

[calibration.torque_2]    # switch position 2
unit = "N*mm"
points = [
    # [0, 0.0],
    # [10, 0.041],
]

[measurements]
# One row per measurement. series: T4 = load series at fixed tilt (Table 4; give the speed-column
# label, rows with the same label share a speed setting), T5 = speed series at fixed Q (Table 5).
# Give speed_reading or speed, and torque_reading with its switch position (1 or 2) or torque.
# Empty cells are "not given". The rows may instead live in a CSV file: file = "rows.csv".
csv = \'\'\'
series, tilt [deg], mass [kg], column, speed_reading, torque_reading, switch, speed [rpm], torque [N*mm], note
\'\'\'
"""

_BEARING_BLANK = '''\
# A catalog bearing (bearinglab catalog list), e.g. one of the lab's 1000095, 18, 101:
# catalog = "18"
# or the bearing's data:
designation = ""
type = "radial"           # radial | angular
# contact_angle = "26 deg"  # angular contact only
bore = ""                 # d, e.g. "8 mm"
mean_diameter = ""        # d_m = (d + D)/2, e.g. "13.5 mm" (or outside_diameter = "19 mm")
static_load_rating = ""   # C0, e.g. "1354 N"'''


def template(*, bearing=None):
    """Text of a blank, commented measurement-session file.

    Parameters
    ----------
    bearing : str, optional
        Catalog name to fill in (e.g. ``"18"``); otherwise the inline bearing fields are left blank.

    Returns
    -------
    str
        Valid TOML. Run as it is, it stops at the first thing left to fill in.

    Examples
    --------
    >>> "[calibration.torque_2]" in template()
    True
    """
    if bearing is None:
        block = _BEARING_BLANK
    else:
        b = _catalog.get(bearing)
        block = (
            f'catalog = "{bearing}"          # {b.type}, d = {b.bore * 1e3:g} mm, d_m = '
            f"{b.mean_diameter * 1e3:g} mm, C0 = {b.static_load_rating:g} N\n"
            "# Fields given here override the catalog (type, contact_angle, bore, mean_diameter,\n"
            "# outside_diameter, static_load_rating)."
        )
    return _TEMPLATE.format(format=FORMAT, bearing_block=block)


def write_template(path, *, bearing=None, overwrite=False):
    """Write a blank session file (whole, via a temporary file and a rename).

    Parameters
    ----------
    path : str or Path
        The new file.
    bearing : str, optional
        Catalog name to fill in.
    overwrite : bool
        Replace an existing file; by default an existing file is an error (it may hold data).

    Returns
    -------
    Path
        The file written.

    Raises
    ------
    InputError
        The file exists (and ``overwrite`` is false), or the bearing is unknown.
    """
    path = Path(path)
    text = template(bearing=bearing)
    if path.exists() and not overwrite:
        raise InputError(f"{path}: file exists; choose a new name (or --force to replace it)")
    if path.is_dir():
        raise InputError(f"{path}: is a directory")
    with atomic_output(path) as tmp:
        tmp.write_text(text, encoding="utf-8")
    return path

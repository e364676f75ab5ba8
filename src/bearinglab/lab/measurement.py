r"""The measurement-session file of the friction-rig lab: reading and validation.

Reading
-------
read_session       a session file (TOML; rows inline as CSV text or in a separate CSV file) -> Session
parse_session      the same from text already in memory (``source`` names it in messages)

Data
----
Session            everything a session holds: bearing, handbook constants, rig, calibration, rows
Handbook           the handbook constants in force (Table 1, Table 2, mu), with the overrides named
SKFSettings        the optional [skf] table: lubricant and model options of task 4 (the SKF model fit)
Rows               the measurement rows as arrays (SI), with their file line numbers
SERIES             the row series, T4 and T5

The blank session file (``template``, ``write_template``, ``FORMAT``) is written by
:mod:`bearinglab.lab.template` and re-exported here; the rows table is read by a private module.

Format (one file; quantities are strings with units; see ``examples/friction/README.md``)::

    format = "bearinglab-friction-session/1"
    [session]      title, date, operator, rig, lubricant, notes (free text, shown in the report)
    [bearing]      catalog = "18"  and/or  designation, type, contact_angle, bore,
                   mean_diameter or outside_diameter, static_load_rating
    [handbook]     optional overrides: x0, y0, mu, f, c (plain numbers)
    [skf]          optional, turns on task 4: viscosity = "30 mm^2/s", lubrication, fit,
                   series (or r1, r2, s1, s2 [, r3, s3]), ehl (mu_EHL)
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

import dataclasses
import math
import re
import tomllib
from dataclasses import dataclass, field
from pathlib import Path
from typing import NamedTuple

from .. import catalog as _catalog
from .. import friction
from .._bounds import read_input_bytes
from ..bearing import BallBearing
from ..errors import CatalogError, InputError
from ..units import parse_quantity
from ._compat import renamed_field
from ._rows import SERIES, Rows, read_rows
from .calibration import Calibration, calibration_table
from .fits import SKF_FIT_PARAMETERS
from .rig import GRAVITY
from .template import FORMAT, template, write_template

__all__ = [
    "FORMAT",
    "SERIES",
    "Handbook",
    "Rows",
    "SKFSettings",
    "Session",
    "parse_session",
    "read_session",
    "template",
    "write_template",
]

_SKF_CONSTANT_KEYS = ("r1", "r2", "s1", "s2", "r3", "s3")
_KNOWN = {
    (): {"format", "session", "bearing", "handbook", "skf", "rig", "calibration", "measurements"},
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
    ("skf",): {"viscosity", "lubrication", "fit", "series", "ehl", *_SKF_CONSTANT_KEYS},
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


class Handbook(NamedTuple):
    """Handbook constants in force for a session (Tables 1 and 2, section 3.2, or overrides)."""

    radial_factor: float
    """x0. [-]"""
    axial_factor: float
    """y0. [-]"""
    reduced_friction_coefficient: float
    """mu_hb, the reduced friction coefficient of the one-term model (section 3.2). [-]"""
    load_term_factor: float
    """f_hb. [-]"""
    load_term_exponent: float
    """c (= e). [-]"""
    overridden: tuple
    """Names (x0, y0, mu, f, c) given in the file instead of taken from the tables."""

    friction_coefficient = renamed_field(
        "Handbook", "friction_coefficient", "reduced_friction_coefficient"
    )


class SKFSettings(NamedTuple):
    """The ``[skf]`` table of a session: what task 4 (the fit of the SKF four-term model) needs."""

    kinematic_viscosity: float
    """nu at the test temperature (of the base oil for grease). [m^2/s]"""
    lubrication: str
    """``"grease"``, ``"oil-air"`` or ``"oil-jet"`` (K_rs of the model)."""
    fit: str
    """What is fitted: ``"sliding"`` (mu_sl), ``"rolling"`` (a scale on M_rr) or ``"both"``."""
    series: str | None
    """Deep-groove series of the SKF constants (None when ``constants`` are given)."""
    constants: object | None
    """:class:`bearinglab.friction.SKFConstants` given in the file, or None."""
    ehl_coefficient: float
    """mu_EHL of the lubricant (0.05 for mineral oils). [-]"""

    def model_options(self, bearing):
        """Keyword arguments of :func:`bearinglab.friction.skf.skf` for ``bearing``."""
        kw = {"bearing_type": bearing.type, "lubrication": self.lubrication,
              "ehl_coefficient": self.ehl_coefficient}
        if bearing.static_load_rating is not None:
            kw["static_load_rating"] = bearing.static_load_rating
        if self.constants is not None:
            kw["constants"] = self.constants
        else:
            kw["series"] = self.series
        return kw


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
    skf: SKFSettings | None = None
    """The ``[skf]`` table (task 4), or None when the file has none."""


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
    bearinglab.errors.InputError: new.toml, line 71, field 'measurements.csv': no measurement rows (only the header)
    """
    path = Path(path)
    try:
        text = read_input_bytes(path).decode("utf-8")  # a regular file of bounded size
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
    skf = _skf_settings(doc["skf"], bearing, ctx) if "skf" in doc else None
    rig = _table(doc, ("rig",), ctx)
    tare = _quantity(rig, ("rig", "tare_mass"), "mass", ctx, default=0.0)
    if tare < 0:
        raise ctx.error(("rig", "tare_mass"), f"must be >= 0 [kg], got {tare!r}")
    gravity = GRAVITY
    if "gravity" in rig:
        gravity = _acceleration(rig["gravity"], ("rig", "gravity"), ctx)
    calibration = _calibration(_table(doc, ("calibration",), ctx), ctx)
    rows, rows_source = read_rows(_table(doc, ("measurements",), ctx), calibration, ctx, base_dir)
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
        skf=skf,
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
    """The [bearing] table -> BallBearing: a catalog bearing with the fields given, or an inline one."""
    base = _bearing_base(table, ctx)
    kw = _bearing_fields(table, base, ctx)
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


def _bearing_base(table, ctx):
    """The catalog bearing named in [bearing], or a blank radial one for inline data."""
    if "catalog" in table:
        try:
            return _catalog.get(str(table["catalog"]))
        except CatalogError as exc:
            raise ctx.error(("bearing", "catalog"), str(exc)) from None
    if not table:
        raise ctx.error(
            ("bearing",),
            'give catalog = "NAME" (e.g. "18") or the bearing\'s type, bore, '
            "mean_diameter (or outside_diameter) and static_load_rating",
        )
    if "type" not in table:
        raise ctx.error(
            ("bearing",), 'give the bearing\'s type = "radial" or "angular" (or a catalog name)'
        )
    return BallBearing(designation="inline", type="radial")


def _bearing_fields(table, base, ctx):
    """The fields of [bearing] (SI) that replace those of ``base``."""
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
    elif kw.get("type", base.type) != base.type:  # the catalog angle belongs to the old type
        kw["contact_angle"], kw["radial_clearance"] = None, None
    return kw


def _skf_settings(table, bearing, ctx):
    """The [skf] table -> SKFSettings (task 4)."""
    table = _table({"skf": table}, ("skf",), ctx)
    if "viscosity" not in table:
        raise ctx.error(("skf", "viscosity"), 'is required for task 4, e.g. viscosity = "30 mm^2/s"')
    nu = _quantity(table, ("skf", "viscosity"), "kinematic_viscosity", ctx)
    if not nu > 0:
        raise ctx.error(("skf", "viscosity"), f"must be > 0 [mm^2/s], got {nu * 1e6!r}")
    # an oil bath needs its level and drag-loss factor, which a rig session does not describe
    lab_methods = [m for m in friction.LUBRICATION_METHODS if m != "oil-bath"]
    choices = {"lubrication": (lab_methods, "grease"),
               "fit": (SKF_FIT_PARAMETERS, "sliding")}
    picked = {}
    for key, (valid, default) in choices.items():
        picked[key] = table.get(key, default)
        if picked[key] not in valid:
            raise ctx.error(("skf", key), f"must be one of {list(valid)}, got {picked[key]!r}")
    numbers = {}
    for key in (*_SKF_CONSTANT_KEYS, "ehl"):
        if key in table:
            v = table[key]
            if isinstance(v, bool) or not isinstance(v, (int, float)) or not (v >= 0 and math.isfinite(v)):
                raise ctx.error(("skf", key), f"must be a plain number >= 0 [-], got {v!r}")
            numbers[key] = float(v)
    given = [k for k in _SKF_CONSTANT_KEYS[:4] if k in numbers]
    constants, series = None, None
    if given:
        if len(given) < 4 or "series" in table:
            raise ctx.error(("skf", given[0]), "give all of r1, r2, s1, s2 (and r3, s3 for angular "
                                               "contact), or a series, not both")
        constants = friction.SKFConstants(*(numbers.get(k, 0.0) for k in _SKF_CONSTANT_KEYS[:4]),
                                          r3=numbers.get("r3", 0.0), s3=numbers.get("s3", 0.0))
    else:
        if "series" in table:
            series = str(table["series"]).strip()
            if series.upper() not in friction.DEEP_GROOVE_CONSTANTS:  # the message names the file's keys
                raise ctx.error(("skf", "series"), f"must be one of {list(friction.DEEP_GROOVE_CONSTANTS)} "
                                                   f"(deep groove), got {table['series']!r}; or give r1, r2, s1, s2")
        else:
            try:
                series = friction.bearing_series(bearing.designation)
            except InputError as exc:
                raise ctx.error(("skf", "series"), f"{exc}; or give r1, r2, s1, s2") from None
    return SKFSettings(nu, picked["lubrication"], picked["fit"], series, constants, numbers.get("ehl", 0.05))


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

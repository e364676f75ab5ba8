"""Runout files: the TOML error file of spec 003 (format: ``examples/runout/README.md``), read and written.

Reading
-------
load_error_file             (geometry, errors) of one bearing from an error file
read_error_document         the same from an error file's content already read (a posted document)
load_geometry_file          the [geometry] table of a file (an error file or a geometry-only file)

Writing
-------
write_error_file            one bearing's geometry and errors as an error file; reading it back gives
                            the same numbers bit for bit
write_sample_error_files    the error files of chosen Monte Carlo samples (e.g. the worst ones), so that
                            ``bearinglab runout --errors FILE`` reproduces each sample exactly

Boundary code: it parses quantities with units (:mod:`bearinglab.units`, pint on first use) and builds
the SI objects of the other runout modules. Every problem in a file raises
:class:`~bearinglab.errors.CatalogError` naming the file, the table and the key; a file read is never
modified, and a file written is written whole or not at all.
"""

from __future__ import annotations

import io
import json
import math
from pathlib import Path

import numpy as np

from .. import _bounds
from .._io import write_text
from ..catalog import read_toml
from ..errors import CatalogError, InputError
from ..units import parse_quantity
from .deviations import (
    FourierSeries,
    ManufacturingErrors,
    RacewayErrors,
    fourier_series,
    manufacturing_errors,
    roundness_coefficients,
)
from .geometry import (
    SpindleGeometry,
    geometry_from_bearing,
    geometry_from_catalog,
    geometry_from_radii,
)
from .rotation import METRICS
from .tolerances import MonteCarloResult, monte_carlo_errors

__all__ = [
    "load_error_file",
    "load_geometry_file",
    "profile_files",
    "read_error_document",
    "write_error_file",
    "write_sample_error_files",
]

_TOP = {"title", "description", "source", "geometry", "errors", "tilt"}
_GEOMETRY = {
    "bearing",
    "balls",
    "ball_diameter",
    "ball_radius",
    "pitch_diameter",
    "outer_conformity",
    "inner_conformity",
    "outer_groove_radius",
    "inner_groove_radius",
    "inner_bottom_radius",
    "outer_bottom_radius",
    "contact_angle",
    "first_ball_angle",
    "designation",
    "source",
}
_RINGS = ("outer", "inner")
_SERIES = ("radial", "axial", "groove", "normal")
_SERIES_KEYS = {"cos", "sin", "unit", "profile", "angle", "deviation", "max_order", "angle_unit"}
_BALL_KEYS = {"diameter", "outer_deficit", "inner_deficit", "unit"}
_LENGTH_UNITS = {"nm": 1e-9, "um": 1e-6, "µm": 1e-6, "mm": 1e-3, "m": 1.0}
_ANGLE_UNITS = {"deg": math.pi / 180, "rad": 1.0}


class _Ctx:
    def __init__(self, path, files=True):
        self.path = Path(path)
        self.files = files  # whether the document may name files (a posted document may not)

    def fail(self, table, key, msg):
        where = f"{self.path}, [{table}]" + (f", key {key!r}" if key else "")
        raise CatalogError(f"{where}: {msg}")

    def known(self, table, mapping, allowed):
        if not isinstance(mapping, dict):
            self.fail(table, None, f"expected a table, got {type(mapping).__name__}")
        for key in mapping:
            if key not in allowed:
                self.fail(table, key, f"unknown key (known: {', '.join(sorted(allowed))})")

    def quantity(self, table, key, value, kind, default_unit=None):
        try:
            return parse_quantity(value, kind, key, default_unit=default_unit)
        except InputError as exc:
            self.fail(table, key, str(exc))

    def unit(self, table, mapping, key="unit", units=_LENGTH_UNITS, default="um"):
        u = mapping.get(key, default)
        if u not in units:
            self.fail(table, key, f"unit must be one of {sorted(units)}, got {u!r}")
        return units[u]

    def number(self, table, key, value, scale, kind="length"):
        """A bare number in the table's unit, or a string with its own unit."""
        if isinstance(value, bool):
            self.fail(table, key, f"expected a number, got {value!r}")
        if isinstance(value, (int, float)):
            if not math.isfinite(value):
                self.fail(table, key, f"must be finite, got {value!r}")
            return float(value) * scale
        if isinstance(value, str):
            return self.quantity(table, key, value, kind)
        self.fail(table, key, f"expected a number or a quantity string, got {value!r}")


def _load(ctx):
    """The parsed TOML document of ``ctx.path``; every failure is a CatalogError naming the file."""
    return read_toml(ctx.path)


def load_error_file(path, geometry=None):
    """Read a TOML error file (format: ``examples/runout/README.md``).

    Parameters
    ----------
    path : str or Path
        The file; it is never modified.
    geometry : SpindleGeometry, optional
        Use this geometry instead of the file's ``[geometry]`` table (which is then optional, and still
        checked when present).

    Returns
    -------
    tuple
        ``(geometry, errors)``: a SpindleGeometry and a ManufacturingErrors.

    Raises
    ------
    CatalogError
        Naming the file, the table and the key of a bad entry.
    """
    ctx = _Ctx(path)
    return _read_error_document(_load(ctx), geometry, ctx)


def read_error_document(doc, geometry=None, *, source="the posted document"):
    """The content of an error file already read (a posted document), as :func:`load_error_file`.

    Parameters
    ----------
    doc : dict
        The tables of an error file (format: ``examples/runout/README.md``), e.g. from JSON or TOML.
    geometry : SpindleGeometry, optional
        As for :func:`load_error_file`.
    source : str
        What the messages call the document.

    Returns
    -------
    tuple
        ``(geometry, errors)``.

    Raises
    ------
    CatalogError
        Naming ``source``, the table and the key of a bad entry; a ``profile`` key, which names a file,
        is refused: nothing is read from the disk.
    """
    return _read_error_document(doc, geometry, _Ctx(source, files=False))


def _read_error_document(doc, geometry, ctx):
    ctx.known("top level", doc, _TOP)
    if geometry is None:
        if "geometry" not in doc:
            how = "(--geometry FILE or --bearing NAME)" if ctx.files else "(a catalog bearing)"
            raise CatalogError(f"{ctx.path}: no [geometry] table; add one or give the geometry {how}")
        geometry = _read_geometry(doc["geometry"], ctx)
    elif "geometry" in doc:
        _read_geometry(doc["geometry"], ctx)  # still checked, so that a broken file is reported
    errors = _read_errors(doc, geometry.n_balls, ctx)
    return geometry, errors


def profile_files(path):
    """The measured-profile files an error file names (its ``profile`` keys), resolved next to it.

    They are inputs of a run as much as the error file: an output must not replace them.

    Parameters
    ----------
    path : str or Path
        The error file (read, never modified).

    Returns
    -------
    list of Path
        The profile files named, in the order of the file; empty when it names none or cannot be read
        (:func:`load_error_file` reports what is wrong with it).
    """
    try:
        doc = read_toml(path)
    except InputError:
        return []
    found = []

    def walk(table):
        for key, value in table.items():
            if isinstance(value, dict):
                walk(value)
            elif key == "profile" and isinstance(value, str):
                found.append(Path(path).parent / value)

    errors = doc.get("errors")
    if isinstance(errors, dict):
        walk(errors)
    return found


def load_geometry_file(path):
    """The [geometry] table of a file (an error file or a geometry-only file).

    Parameters
    ----------
    path : str or Path
        The file; it is never modified.

    Returns
    -------
    SpindleGeometry

    Raises
    ------
    CatalogError
        The file has no [geometry] table, or an entry of it is bad (named with file, table and key).
    """
    ctx = _Ctx(path)
    doc = _load(ctx)
    if "geometry" not in doc:
        raise CatalogError(f"{ctx.path}: no [geometry] table")
    return _read_geometry(doc["geometry"], ctx)


def _read_geometry(table, ctx):
    """A [geometry] table -> SpindleGeometry (catalogue form, radii form, or a catalog bearing)."""
    ctx.known("geometry", table, _GEOMETRY)
    t = "geometry"
    theta1 = (
        ctx.quantity(t, "first_ball_angle", table["first_ball_angle"], "angle")
        if "first_ball_angle" in table
        else 0.0
    )
    tau = (
        ctx.quantity(t, "contact_angle", table["contact_angle"], "angle")
        if "contact_angle" in table
        else None
    )
    h10 = _length(table, "outer_bottom_radius", ctx)
    try:
        if "bearing" in table:
            return _bearing_geometry(table, ctx, theta1, h10)
        n, r30, radii = _balls_and_grooves(table, ctx)
        if ("pitch_diameter" in table) == ("inner_bottom_radius" in table):
            ctx.fail(
                t,
                "pitch_diameter",
                "give pitch_diameter (catalogue form) or inner_bottom_radius "
                "(radii form), exactly one",
            )
        if "pitch_diameter" in table:
            return geometry_from_catalog(
                n,
                2.0 * r30,
                _length(table, "pitch_diameter", ctx),
                radii["outer"] / (2 * r30),
                radii["inner"] / (2 * r30),
                tau,
                outer_bottom_radius=h10,
                first_ball_angle=theta1,
            )
        return geometry_from_radii(
            n,
            r30,
            radii["outer"],
            radii["inner"],
            _length(table, "inner_bottom_radius", ctx),
            tau,
            outer_bottom_radius=h10,
            first_ball_angle=theta1,
        )
    except CatalogError:
        raise
    except InputError as exc:
        ctx.fail(t, None, str(exc))


def _length(table, key, ctx):
    """A length of the [geometry] table, or None when the key is absent."""
    return ctx.quantity("geometry", key, table[key], "length") if key in table else None


def _bearing_geometry(table, ctx, theta1, h10):
    """The geometry of ``bearing = "NAME"``: a catalog bearing, with theta1 and H10 only besides."""
    extra = sorted(
        set(table) - {"bearing", "first_ball_angle", "outer_bottom_radius", "source", "designation"}
    )
    if extra:
        ctx.fail(
            "geometry",
            extra[0],
            "with 'bearing' only first_ball_angle and outer_bottom_radius may be given",
        )
    from .. import catalog

    return geometry_from_bearing(
        catalog.get(str(table["bearing"])), first_ball_angle=theta1, outer_bottom_radius=h10
    )


def _balls_and_grooves(table, ctx):
    """(n, r30, {"outer": rho10, "inner": rho20}) of a catalogue- or radii-form [geometry] table."""
    t = "geometry"
    if "balls" not in table:
        ctx.fail(t, "balls", "missing: the number of balls")
    n = table["balls"]
    if isinstance(n, bool) or not isinstance(n, int):
        ctx.fail(t, "balls", f"must be a whole number, got {n!r}")
    if n > _bounds.MAX_BALLS:  # before any per-ball array is allocated
        ctx.fail(t, "balls", f"must be <= {_bounds.MAX_BALLS} (bearinglab's size limit), got {n}")
    if "ball_diameter" in table and "ball_radius" in table:
        ctx.fail(t, "ball_radius", "give ball_diameter or ball_radius, not both")
    r30 = _length(table, "ball_radius", ctx)
    if r30 is None:
        dw = _length(table, "ball_diameter", ctx)
        if dw is None:
            ctx.fail(t, "ball_diameter", "missing")
        r30 = dw / 2.0
    radii = {}
    for race in ("outer", "inner"):
        rk, fk = f"{race}_groove_radius", f"{race}_conformity"
        if rk in table and fk in table:
            ctx.fail(t, rk, f"give {rk} or {fk}, not both")
        if rk in table:
            radii[race] = _length(table, rk, ctx)
        elif fk in table:
            radii[race] = ctx.quantity(t, fk, table[fk], "dimensionless") * 2.0 * r30
        else:
            ctx.fail(t, fk, "missing (or give the groove radius)")
    return n, r30, radii


def _read_series(table, name, ctx):
    ctx.known(name, table, _SERIES_KEYS)
    scale = ctx.unit(name, table)
    measured = {"profile", "angle", "deviation"} & set(table)
    if measured:
        if {"cos", "sin"} & set(table):
            ctx.fail(
                name,
                "profile",
                "give Fourier coefficients (cos/sin) or a measured profile, not both",
            )
        if "max_order" not in table:
            ctx.fail(
                name, "max_order", "missing: the highest Fourier order to keep from the profile"
            )
        k = table["max_order"]
        if isinstance(k, bool) or not isinstance(k, int) or k < 0:
            ctx.fail(name, "max_order", f"must be a whole number >= 0, got {k!r}")
        if k > _bounds.MAX_ORDER:
            ctx.fail(name, "max_order", f"must be <= {_bounds.MAX_ORDER} (bearinglab's size limit), got {k}")
        ang_scale = ctx.unit(name, table, "angle_unit", _ANGLE_UNITS, "deg")
        if "profile" in table:
            if {"angle", "deviation"} & set(table):
                ctx.fail(
                    name,
                    "profile",
                    "give a profile file or inline angle/deviation arrays, not both",
                )
            if not ctx.files:
                ctx.fail(name, "profile", "names a profile file; a posted document cannot refer to "
                         "files: give the inline 'angle' and 'deviation' arrays")
            file = ctx.path.parent / str(table["profile"])
            try:  # a regular file of bounded size (not /dev/zero), then parsed
                text = _bounds.read_input_bytes(file).decode("utf-8-sig")
                data = np.loadtxt(io.StringIO(text), delimiter=",", comments="#", ndmin=2)
            except FileNotFoundError:
                ctx.fail(name, "profile", f"no such file: {file}")
            except (IsADirectoryError, PermissionError) as exc:
                ctx.fail(name, "profile", f"{file}: {exc.strerror}")
            except UnicodeDecodeError:
                ctx.fail(name, "profile", f"{file}: not a UTF-8 text file")
            except InputError as exc:
                ctx.fail(name, "profile", str(exc))
            except ValueError as exc:
                ctx.fail(
                    name,
                    "profile",
                    f"{file}: expected two numeric columns 'angle, deviation'{_bad_line(file, exc)}",
                )
            if data.shape[1] != 2:
                ctx.fail(
                    name,
                    "profile",
                    f"{file}: expected two columns 'angle, deviation', got {data.shape[1]}",
                )
            ang, dev = data[:, 0], data[:, 1]
        else:
            if not ("angle" in table and "deviation" in table):
                ctx.fail(
                    name, "angle", "a measured profile needs both 'angle' and 'deviation' arrays"
                )
            ang, dev = table["angle"], table["deviation"]
            for key, arr in (("angle", ang), ("deviation", dev)):
                if not isinstance(arr, list) or not all(
                    isinstance(v, (int, float)) and not isinstance(v, bool) for v in arr
                ):
                    ctx.fail(name, key, "must be an array of numbers")
        try:
            return roundness_coefficients(
                np.asarray(ang, float) * ang_scale, np.asarray(dev, float) * scale, k
            )
        except InputError as exc:
            ctx.fail(name, "max_order", str(exc))
    parts = {}
    for key in ("cos", "sin"):
        raw = table.get(key, {})
        if not isinstance(raw, dict):
            ctx.fail(name, key, "expected a table of order = value, e.g. { 1 = 0.5, 2 = 0.12 }")
        _check_orders(name, key, raw, ctx)
        parts[key] = {k: ctx.number(name, f"{key}.{k}", v, scale) for k, v in raw.items()}
    if 0 in parts["sin"] or "0" in parts["sin"]:
        ctx.fail(name, "sin.0", "sin has no order 0")
    try:
        return fourier_series(parts["cos"], parts["sin"])
    except InputError as exc:
        ctx.fail(name, None, str(exc))


def _check_orders(name, key, raw, ctx):
    """The Fourier orders of a series table, bounded before its coefficient arrays are allocated."""
    for k in raw:
        try:
            order = int(k)
        except (TypeError, ValueError):  # not a whole number: fourier_series says so
            continue
        if order > _bounds.MAX_ORDER:
            ctx.fail(name, f"{key}.{k}", f"Fourier order must be <= {_bounds.MAX_ORDER} (bearinglab's size "
                     f"limit), got {order}")


def _per_ball(table, key, n, scale, ctx):
    arr = table[key]
    if not isinstance(arr, list):
        ctx.fail("errors.balls", key, f"expected an array with one value per ball ({n})")
    if len(arr) != n:
        ctx.fail("errors.balls", key, f"needs one value per ball: {n} balls, got {len(arr)} values")
    return np.array(
        [ctx.number("errors.balls", f"{key}[{i + 1}]", v, scale) for i, v in enumerate(arr)]
    )


def _read_tilt(value, name, ctx):
    if isinstance(value, dict):
        ctx.known(name, value, {"cos", "sin", "unit"})
        scale = ctx.unit(
            name, value, units={"urad": 1e-6, "mrad": 1e-3, "rad": 1.0}, default="urad"
        )
        parts = {}
        for key in ("cos", "sin"):
            raw = value.get(key, {})
            if not isinstance(raw, dict):
                ctx.fail(
                    name,
                    key,
                    "expected a table of order = value (orders of the rotation angle psi)",
                )
            _check_orders(name, key, raw, ctx)
            parts[key] = {
                k: ctx.number(name, f"{key}.{k}", v, scale, "angle") for k, v in raw.items()
            }
        try:
            return fourier_series(parts["cos"], parts["sin"])
        except InputError as exc:
            ctx.fail(name, None, str(exc))
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        return float(value) * 1e-6  # a bare number is in urad
    if isinstance(value, str):
        return ctx.quantity(name, None, value, "angle")
    ctx.fail(
        name,
        None,
        f"expected a quantity such as '20 urad' or a table of Fourier coefficients, got {value!r}",
    )


def _read_errors(doc, n, ctx):
    errors = doc.get("errors", {})
    ctx.known("errors", errors, {"outer", "inner", "balls"})
    rings = {}
    for ring in _RINGS:
        table = errors.get(ring, {})
        ctx.known(f"errors.{ring}", table, set(_SERIES))
        rings[ring] = RacewayErrors(
            **{s: _read_series(table[s], f"errors.{ring}.{s}", ctx) for s in _SERIES if s in table}
        )
    balls = errors.get("balls", {})
    ctx.known("errors.balls", balls, _BALL_KEYS)
    scale = ctx.unit("errors.balls", balls)
    kw = {}
    if "diameter" in balls:
        if {"outer_deficit", "inner_deficit"} & set(balls):
            ctx.fail(
                "errors.balls", "diameter", "give diameter deviations or the two deficits, not both"
            )
        kw["ball_diameter_deviation"] = _per_ball(balls, "diameter", n, scale, ctx)
    for key in ("outer_deficit", "inner_deficit"):
        if key in balls:
            kw[f"ball_{key}"] = _per_ball(balls, key, n, scale, ctx)
    tilt = doc.get("tilt", {})
    ctx.known("tilt", tilt, {"alpha", "beta"})
    for key, arg in (("alpha", "tilt_x"), ("beta", "tilt_y")):
        if key in tilt:
            kw[arg] = _read_tilt(tilt[key], f"tilt.{key}", ctx)
    try:
        return manufacturing_errors(n, outer=rings["outer"], inner=rings["inner"], **kw)
    except InputError as exc:
        ctx.fail("errors", None, str(exc))


# ----------------------------------------------------------------------------- writing
def _bad_line(file, exc):
    """Where a profile file stops being two numeric columns: its line, counted from 1 as an editor shows it
    (numpy's own message counts the data rows from 0)."""
    try:
        for number, line in enumerate(Path(file).read_text(encoding="utf-8").splitlines(), 1):
            text = line.split("#", 1)[0].strip()
            if not text:
                continue
            try:
                [float(x) for x in text.split(",")]
            except ValueError:
                return f", got {line.strip()!r} on line {number}"
    except (OSError, UnicodeDecodeError):
        pass
    return f": {exc}"


def _toml_float(value):
    """A float as TOML, to the last bit (Python's repr is the shortest string that reads back equal)."""
    return repr(float(value))


def _series_table(name, series, unit):
    """Lines of the table of one Fourier series; every order is written, so its length survives."""
    cos = np.asarray(series.cos, float)
    sin = np.asarray(series.sin, float)
    if cos.ndim != 1 or sin.ndim != 1:
        raise InputError(
            f"{name}: a file holds one bearing, so its Fourier series must be 1-D, got shapes "
            f"{cos.shape} and {sin.shape}"
        )
    lines = ["", f"[{name}]", f'unit = "{unit}"', "", f"[{name}.cos]"]
    lines += [f"{k} = {_toml_float(v)}" for k, v in enumerate(cos)]
    if sin.size > 1:  # sin has no order 0
        lines += ["", f"[{name}.sin]"] + [f"{k} = {_toml_float(v)}" for k, v in enumerate(sin) if k]
    return lines


def _array(values):
    items = [_toml_float(v) for v in values]
    rows = [", ".join(items[i : i + 4]) for i in range(0, len(items), 4)]
    return "[\n" + "".join(f"    {r},\n" for r in rows) + "]"


def _geometry_table(g):
    """The radii form of a geometry: geometry_from_radii gives back the same numbers bit for bit."""
    m = {
        "ball_radius": g.ball_radius,
        "outer_groove_radius": g.outer_groove_radius,
        "inner_groove_radius": g.inner_groove_radius,
        "inner_bottom_radius": g.inner_bottom_radius,
    }
    return (
        ["", "[geometry]", f"balls = {int(g.n_balls)}"]
        + [f'{k} = "{_toml_float(v)} m"' for k, v in m.items()]
        + [
            f'contact_angle = "{_toml_float(g.contact_angle)} rad"',
            f'first_ball_angle = "{_toml_float(g.first_ball_angle)} rad"',
        ]
    )


def _tilt_lines(errors):
    constants, tables = [], []
    for key, value in (("alpha", errors.tilt_x), ("beta", errors.tilt_y)):
        if isinstance(value, FourierSeries):
            tables += _series_table(f"tilt.{key}", value, "rad")
        elif callable(value):
            raise InputError(
                f"tilt_{'x' if key == 'alpha' else 'y'}: a function of the rotation angle cannot be "
                f"written to a file; give a number or a FourierSeries"
            )
        elif float(value) != 0.0:
            constants.append(f'{key} = "{_toml_float(value)} rad"')
    return (["", "[tilt]"] + constants if constants else []) + tables


def write_error_file(path, errors, geometry=None, *, title=None, description=None):
    """Write one bearing's errors (and geometry) as a TOML error file, whole or not at all.

    Parameters
    ----------
    path : str or Path
        The file to write (its directory is created); an existing file is replaced.
    errors : ManufacturingErrors
        Errors of one bearing (1-D series and per-ball arrays); tilts constant or Fourier series.
    geometry : SpindleGeometry, optional
        Written as the ``[geometry]`` table (radii form); without it the file needs ``--geometry``.
    title, description : str, optional
        Free text of the file.

    Returns
    -------
    Path

    Notes
    -----
    Numbers are written in m and rad with all their digits, so :func:`load_error_file` gives back the
    same floats and ``bearinglab runout --errors FILE`` the same results bit for bit. The geometry is
    written in the radii form (r30, rho10, rho20, H20, tau0, theta^1), from which
    :func:`~bearinglab.runout.geometry_from_radii` derives the rest exactly as it was derived before
    (for any geometry built by the ``geometry_from_*`` functions).

    Examples
    --------
    >>> import tempfile
    >>> from bearinglab.runout import geometry_from_catalog, manufacturing_errors
    >>> g = geometry_from_catalog(16, 7.144e-3, 54e-3, 0.53, 0.52, math.radians(15))
    >>> e = manufacturing_errors(16, ball_diameter_deviation=np.r_[2e-6, np.zeros(15)])
    >>> with tempfile.TemporaryDirectory() as tmp:
    ...     g2, e2 = load_error_file(write_error_file(Path(tmp) / "e.toml", e, g))
    >>> g2 == g and bool(np.array_equal(e2.ball_outer_deficit, e.ball_outer_deficit))
    True
    """
    if not isinstance(errors, ManufacturingErrors):
        raise InputError(f"errors must be a ManufacturingErrors, got {type(errors).__name__}")
    if geometry is not None and not isinstance(geometry, SpindleGeometry):
        raise InputError(f"geometry must be a SpindleGeometry, got {type(geometry).__name__}")
    lines = [
        "# bearinglab runout error file (format: examples/runout/README.md); lengths in m and",
        "# angles in rad with all their digits, so that reading it back gives the same numbers",
    ]
    for key, text in (("title", title), ("description", description)):
        if text is not None:
            lines.append(f"{key} = {json.dumps(str(text), ensure_ascii=False)}")
    if geometry is not None:
        lines += _geometry_table(geometry)
    for ring in _RINGS:
        for name in _SERIES:
            series = getattr(getattr(errors, ring), name)
            if series is not None:
                lines += _series_table(f"errors.{ring}.{name}", series, "m")
    n = geometry.n_balls if geometry is not None else np.shape(errors.ball_outer_deficit)[-1]
    lines += ["", "[errors.balls]", 'unit = "m"']
    for key in ("outer_deficit", "inner_deficit"):
        v = np.asarray(getattr(errors, f"ball_{key}"), float)
        if v.shape != (n,):
            raise InputError(f"ball_{key} must have one value per ball ({n}), got shape {v.shape}")
        lines.append(f"{key} = {_array(v)}")
    lines += _tilt_lines(errors)
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    return write_text(path, "\n".join(lines) + "\n")


def write_sample_error_files(directory, result, geometry, sample_index, *, seed=None):
    """Write the error files of chosen samples of a Monte Carlo study, to reproduce them one by one.

    Parameters
    ----------
    directory : str or Path
        Where to write ``sample_<index>.toml`` (created if missing).
    result : MonteCarloResult
        The study (its grade, class, seed, K_max, rotation and per-sample metrics).
    geometry : SpindleGeometry
        The nominal geometry the study was run with.
    sample_index : array_like of int
        Global sample indices, e.g. from :func:`~bearinglab.runout.worst_samples`. [-]
    seed : int or numpy.random.SeedSequence, optional
        The study's root seed when it was a SeedSequence with a spawn key (``result.seed`` keeps only
        its entropy); default ``result.seed``.

    Returns
    -------
    tuple of Path
        One file per index, in the order given.

    Notes
    -----
    The errors are regenerated from the seed (:func:`~bearinglab.runout.monte_carlo_errors`).
    ``bearinglab runout --errors FILE --revolutions R --steps-per-rev N`` with the study's R and N (the
    file's description says them, with the sample's metrics) gives the sample's metrics bit for bit; a
    study run with a cage-ratio override needs the same ``--cage-ratio`` again.
    """
    if not isinstance(result, MonteCarloResult):
        raise InputError(f"result must be a MonteCarloResult, got {type(result).__name__}")
    seed = result.seed if seed is None else seed
    grade, rings = result.ball_grade.name, result.ring_class.name
    drawn = monte_carlo_errors(
        geometry,
        result.ball_grade,
        result.ring_class,
        sample_index,
        seed,
        max_order=result.max_order,
    )
    where = {int(i): k for k, i in enumerate(result.samples.sample_index)}
    paths = []
    for s in drawn:  # a few files
        k = where.get(s.sample_index)
        metrics = (
            ""
            if k is None
            else "; its metrics: "
            + ", ".join(f"{m} = {getattr(result.samples, m)[k] / 1e-6:.6f} um" for m in METRICS)
        )
        text = (
            f"Sample {s.sample_index} of a runout Monte Carlo study ({grade} balls, {rings} rings, "
            f"K_max {result.max_order}, seed {seed}), regenerated from the seed{metrics}. Reproduce: "
            f"bearinglab runout --errors sample_{s.sample_index}.toml --revolutions "
            f"{result.revolutions} --steps-per-rev {result.steps_per_revolution}"
        )
        paths.append(
            write_error_file(
                Path(directory) / f"sample_{s.sample_index}.toml",
                s.errors,
                s.geometry,
                title=f"Monte Carlo sample {s.sample_index} ({grade} / {rings}, seed {seed})",
                description=text,
            )
        )
    return tuple(paths)

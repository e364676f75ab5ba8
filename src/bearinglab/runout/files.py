"""Reading the TOML error file of spec 003 (format documented in ``examples/runout/README.md``).

Boundary code: it parses quantities with units (:mod:`bearinglab.units`, pint on first use) and builds
the SI objects of :mod:`bearinglab.runout`. Every problem raises :class:`~bearinglab.errors.CatalogError`
naming the file, the table and the key. The file is only read.
"""

from __future__ import annotations

import math
import tomllib
from pathlib import Path

import numpy as np

from . import runout
from .errors import CatalogError, InputError
from .units import parse_quantity

__all__: list[str] = []

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
    def __init__(self, path):
        self.path = Path(path)

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
    try:
        with open(ctx.path, "rb") as fh:
            return tomllib.load(fh)
    except FileNotFoundError:
        raise CatalogError(f"{ctx.path}: no such file") from None
    except tomllib.TOMLDecodeError as exc:
        raise CatalogError(f"{ctx.path}: not valid TOML: {exc}") from None
    except OSError as exc:
        raise CatalogError(f"{ctx.path}: cannot read: {exc.strerror}") from None


def read_error_file(path, geometry=None):
    """(geometry, errors) from an error file; ``geometry`` overrides the file's [geometry] table."""
    ctx = _Ctx(path)
    doc = _load(ctx)
    ctx.known("top level", doc, _TOP)
    if geometry is None:
        if "geometry" not in doc:
            raise CatalogError(
                f"{ctx.path}: no [geometry] table; add one or give the geometry "
                f"(--geometry FILE or --bearing NAME)"
            )
        geometry = read_geometry(doc["geometry"], ctx)
    elif "geometry" in doc:
        read_geometry(doc["geometry"], ctx)  # still checked, so that a broken file is reported
    errors = _read_errors(doc, geometry.n_balls, ctx)
    return geometry, errors


def read_geometry_file(path):
    """The [geometry] table of a file (an error file or a geometry-only file)."""
    ctx = _Ctx(path)
    doc = _load(ctx)
    if "geometry" not in doc:
        raise CatalogError(f"{ctx.path}: no [geometry] table")
    return read_geometry(doc["geometry"], ctx)


def read_geometry(table, ctx):
    """A [geometry] table -> SpindleGeometry (catalogue form, radii form, or a catalog bearing)."""
    ctx.known("geometry", table, _GEOMETRY)
    t = "geometry"

    def length(key):
        return ctx.quantity(t, key, table[key], "length") if key in table else None

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
    h10 = length("outer_bottom_radius")
    try:
        if "bearing" in table:
            extra = sorted(
                set(table)
                - {"bearing", "first_ball_angle", "outer_bottom_radius", "source", "designation"}
            )
            if extra:
                ctx.fail(
                    t,
                    extra[0],
                    "with 'bearing' only first_ball_angle and outer_bottom_radius may be given",
                )
            from . import catalog

            return runout.geometry_from_bearing(
                catalog.get(str(table["bearing"])), first_ball_angle=theta1, outer_bottom_radius=h10
            )
        if "balls" not in table:
            ctx.fail(t, "balls", "missing: the number of balls")
        n = table["balls"]
        if isinstance(n, bool) or not isinstance(n, int):
            ctx.fail(t, "balls", f"must be a whole number, got {n!r}")
        if "ball_diameter" in table and "ball_radius" in table:
            ctx.fail(t, "ball_radius", "give ball_diameter or ball_radius, not both")
        r30 = length("ball_radius")
        if r30 is None:
            dw = length("ball_diameter")
            if dw is None:
                ctx.fail(t, "ball_diameter", "missing")
            r30 = dw / 2.0
        radii = {}
        for race in ("outer", "inner"):
            rk, fk = f"{race}_groove_radius", f"{race}_conformity"
            if rk in table and fk in table:
                ctx.fail(t, rk, f"give {rk} or {fk}, not both")
            if rk in table:
                radii[race] = length(rk)
            elif fk in table:
                radii[race] = ctx.quantity(t, fk, table[fk], "dimensionless") * 2.0 * r30
            else:
                ctx.fail(t, fk, "missing (or give the groove radius)")
        if ("pitch_diameter" in table) == ("inner_bottom_radius" in table):
            ctx.fail(
                t,
                "pitch_diameter",
                "give pitch_diameter (catalogue form) or inner_bottom_radius "
                "(radii form), exactly one",
            )
        if "pitch_diameter" in table:
            return runout.geometry_from_catalog(
                n,
                2.0 * r30,
                length("pitch_diameter"),
                radii["outer"] / (2 * r30),
                radii["inner"] / (2 * r30),
                tau,
                outer_bottom_radius=h10,
                first_ball_angle=theta1,
            )
        return runout.geometry_from_radii(
            n,
            r30,
            radii["outer"],
            radii["inner"],
            length("inner_bottom_radius"),
            tau,
            outer_bottom_radius=h10,
            first_ball_angle=theta1,
        )
    except CatalogError:
        raise
    except InputError as exc:
        ctx.fail(t, None, str(exc))


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
        ang_scale = ctx.unit(name, table, "angle_unit", _ANGLE_UNITS, "deg")
        if "profile" in table:
            if {"angle", "deviation"} & set(table):
                ctx.fail(
                    name,
                    "profile",
                    "give a profile file or inline angle/deviation arrays, not both",
                )
            file = ctx.path.parent / str(table["profile"])
            try:
                data = np.loadtxt(file, delimiter=",", comments="#", ndmin=2)
            except FileNotFoundError:
                ctx.fail(name, "profile", f"no such file: {file}")
            except ValueError as exc:
                ctx.fail(
                    name,
                    "profile",
                    f"{file}: expected two numeric columns 'angle, deviation': {exc}",
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
            return runout.roundness_coefficients(
                np.asarray(ang, float) * ang_scale, np.asarray(dev, float) * scale, k
            )
        except InputError as exc:
            ctx.fail(name, "max_order", str(exc))
    parts = {}
    for key in ("cos", "sin"):
        raw = table.get(key, {})
        if not isinstance(raw, dict):
            ctx.fail(name, key, "expected a table of order = value, e.g. { 1 = 0.5, 2 = 0.12 }")
        parts[key] = {k: ctx.number(name, f"{key}.{k}", v, scale) for k, v in raw.items()}
    if 0 in parts["sin"] or "0" in parts["sin"]:
        ctx.fail(name, "sin.0", "sin has no order 0")
    try:
        return runout.fourier_series(parts["cos"], parts["sin"])
    except InputError as exc:
        ctx.fail(name, None, str(exc))


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
            parts[key] = {
                k: ctx.number(name, f"{key}.{k}", v, scale, "angle") for k, v in raw.items()
            }
        try:
            return runout.fourier_series(parts["cos"], parts["sin"])
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
        rings[ring] = runout.RacewayErrors(
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
        return runout.manufacturing_errors(n, outer=rings["outer"], inner=rings["inner"], **kw)
    except InputError as exc:
        ctx.fail("errors", None, str(exc))

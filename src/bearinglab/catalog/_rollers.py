"""The built-in roller bearings (``data/roller_series.csv``) and roller entries of user TOML catalogs (private).

Rows and bearings
-----------------
records          the CSV rows, parsed once, keyed by designation
lookup           the designation of a name as written (``"NU208ECP"``, ``"nu 208 ecp"``), or None
build            the RollerBearing of a row, with its sources
from_table       a ``type = "cylindrical" | "tapered" | "spherical"`` table of a user catalog -> RollerBearing
ROLLER_KEYS      the keys of such a table

The rows carry no internal roller set (no maker publishes it): the models that need one estimate it
(:mod:`bearinglab.rollers.estimation`) and say so. No units library is imported to read the CSV.
"""

from __future__ import annotations

import csv
import functools
import io
import math
from importlib import resources

from ..errors import CatalogError, InputError

__all__ = ["ROLLER_KEYS", "build", "from_table", "lookup", "records"]

_MM, _KN = 1e-3, 1e3
_LENGTH_COLUMNS = {"bore_mm": "bore", "outside_diameter_mm": "outside_diameter", "width_mm": "width",
                   "inner_ring_width_mm": "inner_ring_width", "pressure_centre_mm": "pressure_centre"}
_FORCE_COLUMNS = {"dynamic_load_rating_kN": "dynamic_load_rating", "static_load_rating_kN": "static_load_rating",
                  "fatigue_load_limit_kN": "fatigue_load_limit"}
_FACTOR_COLUMNS = ("ratio_limit", "axial_factor_below", "axial_factor", "static_axial_factor")

#: Keys of a roller-bearing table in a user catalog (quantities as strings with units; ``e``, ``Y``, ``Y0``
#: (and ``Y1``, ``Y2`` of a spherical bearing) as the catalogues print them).
ROLLER_KEYS = {
    "type", "design", "rollers", "roller_diameter", "roller_length", "pitch_diameter", "contact_angle",
    "radial_clearance", "rows", "profile", "crown_drop", "edge_radius", "edge_length", "designation", "bore",
    "outside_diameter", "width", "inner_ring_width", "dynamic_load_rating", "static_load_rating",
    "fatigue_load_limit", "e", "Y", "Y0", "Y1", "Y2", "pressure_centre", "series", "full_complement", "source",
    "aliases", "estimated",
}
_LENGTH_KEYS = ("roller_diameter", "roller_length", "pitch_diameter", "radial_clearance", "crown_drop", "edge_radius",
                "edge_length", "bore", "outside_diameter", "width", "inner_ring_width", "pressure_centre")
_FORCE_KEYS = ("dynamic_load_rating", "static_load_rating", "fatigue_load_limit")
_FACTOR_KEYS = {"e": "ratio_limit", "Y": "axial_factor", "Y2": "axial_factor", "Y1": "axial_factor_below",
                "Y0": "static_axial_factor"}


def _fold(name):
    return str(name).lower().replace(" ", "").replace("-", "")


@functools.cache
def records():
    """The rows of ``data/roller_series.csv``, ``{designation: row}`` (strings as read)."""
    text = (resources.files("bearinglab") / "data" / "roller_series.csv").read_text(encoding="utf-8")
    body = io.StringIO("".join(line for line in text.splitlines(keepends=True) if not line.startswith("#")))
    return {row["designation"]: row for row in csv.DictReader(body)}


@functools.cache
def _folded():
    return {_fold(k): k for k in records()}


def lookup(name):
    """The designation of a built-in roller bearing as written (spaces, case and hyphens ignored), or None.

    Parameters
    ----------
    name : str
        E.g. ``"NU 208 ECP"``, ``"nu208ecp"``, ``"30208 J2/Q"``.

    Returns
    -------
    str or None

    Examples
    --------
    >>> lookup("nu208ecp"), lookup("6208")
    ('NU 208 ECP', None)
    """
    return _folded().get(_fold(name))


def build(designation):
    """The :class:`~bearinglab.rollers.bearing.RollerBearing` of a built-in row, with its sources.

    Parameters
    ----------
    designation : str
        A key of :func:`records` (see :func:`lookup`).

    Returns
    -------
    RollerBearing
        Envelope, ratings and factors from the catalogue; no roller set (estimated where a model needs it).

    Examples
    --------
    >>> b = build("30208 J2/Q")
    >>> b.type, b.static_load_rating, b.axial_factor
    ('tapered', 68000.0, 1.6)
    """
    from ..rollers.bearing import RollerBearing

    row = records()[designation]
    kw = {"type": row["type"], "design": row["design"], "series": row["series"]}
    for col, name in _LENGTH_COLUMNS.items():
        if row[col]:
            kw[name] = float(row[col]) * _MM
    for col, name in _FORCE_COLUMNS.items():
        if row[col]:
            kw[name] = float(row[col]) * _KN
    for name in _FACTOR_COLUMNS:
        if row[name]:
            kw[name] = float(row[name])
    f, e = row["inner_raceway_diameter_mm"], row["outer_raceway_diameter_mm"]
    sources = {name: row["source"] for name in (*kw, "designation") if name not in ("type", "design")}
    if f and e:  # the printed raceway diameters fix the roller diameter and the pitch diameter exactly
        kw["roller_diameter"] = 0.5 * (float(e) - float(f)) * _MM
        kw["pitch_diameter"] = 0.5 * (float(e) + float(f)) * _MM
        note = f"(E - F)/2 and (E + F)/2 of the printed raceway diameters F = {f} mm, E = {e} mm: {row['source']}"
        sources["roller_diameter"] = sources["pitch_diameter"] = note
    return RollerBearing(designation=designation, sources=sources, source=row["source"], **kw)


def from_table(table, *, name="", where=""):
    """A roller bearing from one table of a user catalog (``type = "cylindrical"``, ``"tapered"``, ``"spherical"``).

    Parameters
    ----------
    table : dict
        Keys of :data:`ROLLER_KEYS`; lengths, angles and forces as strings with units (``"11 mm"``,
        ``"14 deg"``, ``"62 kN"``); ``rollers`` and ``rows`` whole numbers; ``e``, ``Y``, ``Y0``, ``Y1``,
        ``Y2`` plain numbers; ``profile`` a name or a list of ``["x", "drop"]`` pairs with units.
    name : str
        The entry's name.
    where : str
        File and entry, for the messages.

    Returns
    -------
    RollerBearing

    Raises
    ------
    CatalogError
        Naming the file, the entry and the field.

    Examples
    --------
    >>> b = from_table({"type": "cylindrical", "design": "NU", "rollers": 14, "roller_diameter": "11 mm",
    ...                 "roller_length": "9.6 mm", "pitch_diameter": "60.5 mm"}, name="my NU 208")
    >>> b.rollers, round(b.roller_length * 1e3, 1)
    (14, 9.6)
    """
    from ..rollers.bearing import RollerBearing
    from ..units import parse_quantity

    where = where or name or "<table>"
    unknown = sorted(set(table) - ROLLER_KEYS)
    if unknown:
        raise CatalogError(f"{where}, field {unknown[0]!r}: unknown field of a roller bearing (known: "
                           f"{', '.join(sorted(ROLLER_KEYS))})")

    def q(key, kind):
        try:
            return parse_quantity(table[key], kind, key)
        except InputError as exc:
            raise CatalogError(f"{where}, field {key!r}: {exc}") from None

    kw = {"type": str(table["type"])}
    for key in ("design", "series", "source"):
        if key in table:
            kw[key] = str(table[key])
    for key in ("rollers", "rows"):
        if key in table:
            v = table[key]
            if isinstance(v, bool) or not isinstance(v, int):
                raise CatalogError(f"{where}, field {key!r}: must be a whole number, got {v!r}")
            kw[key] = v
    for key in _LENGTH_KEYS:
        if key in table:
            kw[key] = q(key, "length")
    if "contact_angle" in table:
        kw["contact_angle"] = q("contact_angle", "angle")
    for key in _FORCE_KEYS:
        if key in table:
            kw[key] = q(key, "force")
    for key, field_name in _FACTOR_KEYS.items():
        if key in table:
            v = table[key]
            if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(v):
                raise CatalogError(f"{where}, field {key!r}: must be a number, got {v!r}")
            kw[field_name] = float(v)
    if "full_complement" in table:
        kw["full_complement"] = bool(table["full_complement"])
    if "profile" in table:
        p = table["profile"]
        if isinstance(p, str):
            kw["profile"] = p
        elif isinstance(p, list) and all(isinstance(r, list) and len(r) == 2 for r in p):
            try:
                kw["profile"] = tuple((parse_quantity(x, "length", "profile"), parse_quantity(h, "length", "profile"))
                                      for x, h in p)
            except InputError as exc:
                raise CatalogError(f"{where}, field 'profile': {exc}") from None
        else:
            raise CatalogError(f"{where}, field 'profile': a name (logarithmic, crowned, flat) or a list of "
                               f"[position, drop] pairs, got {p!r}")
    if "estimated" in table:
        est = table["estimated"]
        if not (isinstance(est, list) and all(isinstance(e, str) for e in est)):
            raise CatalogError(f"{where}, field 'estimated': expected a list of field names, got {est!r}")
        kw["estimated_fields"] = tuple(est)
    try:
        return RollerBearing(designation=str(table.get("designation", name)), **kw)
    except InputError as exc:
        msg = str(exc)
        field = msg.split(" ", 1)[0]
        key = {v: k for k, v in _FACTOR_KEYS.items()}.get(field, field)
        raise CatalogError(f"{where}, field {key!r}: {msg}") from None

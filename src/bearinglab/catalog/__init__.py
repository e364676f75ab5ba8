"""Bearing catalogs: the built-in entries and user TOML files.

Functions
---------
load_catalog        read a catalog file into ``{name: BallBearing}``
bearing_from_table  one ``[bearings."NAME"]`` table (or a single-bearing file) -> BallBearing
load_bearing_file   a single-bearing TOML file -> BallBearing
builtin             the built-in catalog
get                 look a bearing up by name, alias or designation (user catalogs, then built-ins)
names               the names of all bearings visible
provenance_notes    the warnings a result computed from a bearing carries (estimated fields, overrides)
search              the standard-series bearings of given dimensions, type and series
details             catalog data of a standard-series bearing that is no BallBearing field (chamfer, speeds, mass)
aliases             the aliases of each name (for listings)
read_toml           any TOML input file: UTF-8 (a byte-order mark is skipped), errors naming the file

File format (quantities are strings with units)::

    [bearings."B218"]
    aliases = ["7218B"]                       # optional
    balls = 16
    ball_diameter = "22.23 mm"
    pitch_diameter = "125.3 mm"
    inner_groove_radius = "11.63 mm"          # or inner_conformity = 0.5232
    outer_groove_radius = "11.63 mm"          # or outer_conformity = 0.5232
    contact_angle = "40 deg"                  # or radial_clearance = "10 um"
    bore = "90 mm"                            # optional: bore, outside_diameter, width,
    type = "angular"                          # type (radial|angular), static_load_rating,
    ball_material = "steel"                   # ball_material (steel|silicon_nitride), source
    dynamic_load_rating = "124 kN"            # optional catalog ratings: dynamic_load_rating,
    fatigue_load_limit = "3.9 kN"             # static_load_rating, fatigue_load_limit
    series = "72B"                            # optional: series (SKF friction constants),
    seal = "RS1"                              # seal type, seals (sealed sides, 0-2),
    seals = 2                                 # seal_diameter (seal counterface d_s)
    seal_diameter = "59.5 mm"
    inner_shoulder_height = "6.7 mm"          # optional: shoulder heights above the groove bottom, for
    outer_shoulder_height = "6.7 mm"          # the truncation check (bearinglab.limits)

The other types (``type`` four-point, double-row-angular, double-row-radial, self-aligning, thrust) take the
same fields (``balls``: per row); their ``contact_angle`` is the nominal angle built into the rings, given
with their ``radial_clearance`` (not instead of it), and a double-row bearing needs ``row_distance``, the
axial distance between the ball centres of its rows (``row_distance = "22 mm"``)::

    [bearings."QJ 208 (measured)"]
    type = "four-point"
    balls = 13
    ball_diameter = "12.7 mm"
    pitch_diameter = "60 mm"
    inner_conformity = 0.52
    outer_conformity = 0.53
    contact_angle = "35 deg"
    radial_clearance = "40 um"

Materials: ``ball_material`` / ``ring_material`` name a built-in material (steel, silicon_nitride) or a
``[materials."NAME"]`` table of the same file (``elastic_modulus``, ``poisson_ratio``, ``density``);
or ``elastic_modulus`` and ``poisson_ratio`` in the entry set both parts at once (steel's density).

    estimated = ["balls", "ball_diameter"]    # optional: the fields that are estimates, not measured

A user catalog is given by ``--catalog FILE`` or the environment variable ``BEARINGLAB_CATALOG``
(several files separated by ``os.pathsep``); its entries take precedence over the built-ins (an entry
with a built-in's name overrides it, and says so in its ``sources``).

The built-in catalog has two parts: ``data/catalog.toml`` (the bearings of the specs and validation
cases) and the standard series of ``data/catalog_series.csv`` (read by :mod:`bearinglab.catalog._series`),
which are found by designation: ``get("6208-2RS1/C3")``, ``get("7205 BECBP")``.
"""

from __future__ import annotations

import dataclasses
import difflib
import functools
import os
import tomllib
from importlib import resources
from pathlib import Path

from .. import _bounds
from ..errors import CatalogError, InputError

__all__ = [
    "ENV_VAR", "aliases", "bearing_from_table", "builtin", "details", "get", "load_bearing_file", "load_catalog",
    "names", "provenance_notes", "read_toml", "search",
]

ENV_VAR = "BEARINGLAB_CATALOG"

_LENGTHS = ("ball_diameter", "pitch_diameter", "bore", "outside_diameter", "width", "radial_clearance",
            "seal_diameter", "inner_shoulder_height", "outer_shoulder_height", "row_distance")
_FORCES = ("static_load_rating", "dynamic_load_rating", "fatigue_load_limit")
_KNOWN = {
    "balls", "ball_diameter", "pitch_diameter", "inner_groove_radius", "outer_groove_radius",
    "inner_conformity", "outer_conformity", "contact_angle", "radial_clearance", "bore",
    "outside_diameter", "width", "type", "static_load_rating", "ball_material", "ring_material",
    "source", "aliases", "hertz_table", "designation", "dynamic_load_rating", "fatigue_load_limit",
    "series", "seal", "seals", "seal_diameter", "elastic_modulus", "poisson_ratio", "inner_shoulder_height",
    "outer_shoulder_height", "estimated", "row_distance",
}
# a file key of the `estimated` list -> the BallBearing field it sets
_ESTIMABLE = {"balls": "n_balls", "ball_diameter": "ball_diameter", "pitch_diameter": "pitch_diameter",
              "inner_groove_radius": "inner_conformity", "outer_groove_radius": "outer_conformity",
              "inner_conformity": "inner_conformity", "outer_conformity": "outer_conformity",
              "contact_angle": "contact_angle", "radial_clearance": "radial_clearance",
              "static_load_rating": "static_load_rating", "dynamic_load_rating": "dynamic_load_rating",
              "fatigue_load_limit": "fatigue_load_limit", "row_distance": "row_distance"}
_MATERIAL_KEYS = {"elastic_modulus": "pressure", "poisson_ratio": "dimensionless", "density": "density"}


def _where(file, entry):
    loc = f"{file}" if file else "<table>"
    return f"{loc}, entry {entry!r}" if entry else loc


def _material_table(table, name, where):
    """A ``[materials."NAME"]`` table -> Material."""
    from ..bearing import Material
    from ..units import parse_quantity

    if not isinstance(table, dict):
        raise CatalogError(f"{where}, material {name!r}: expected a table of fields, got {type(table).__name__}")
    unknown = sorted(set(table) - set(_MATERIAL_KEYS))
    missing = sorted(set(_MATERIAL_KEYS) - set(table))
    if unknown or missing:
        raise CatalogError(f"{where}, material {name!r}: fields must be {sorted(_MATERIAL_KEYS)}, "
                           f"{'unknown ' + repr(unknown[0]) if unknown else 'missing ' + repr(missing[0])}")
    try:
        values = {k: parse_quantity(table[k], kind, k) for k, kind in _MATERIAL_KEYS.items()}
        return Material(name, **values)
    except InputError as exc:
        raise CatalogError(f"{where}, material {name!r}: {exc}") from None


def _materials(table, kw, where, materials, q):
    """Ball and ring materials of an entry: named, or from elastic_modulus and poisson_ratio."""
    from ..bearing import MATERIALS, STEEL, Material

    known = {**MATERIALS, **{k.lower(): m for k, m in (materials or {}).items()}}
    for key in ("ball_material", "ring_material"):
        if key in table:
            mat = str(table[key]).lower().replace(" ", "_").replace("-", "_")
            if mat not in known:
                raise CatalogError(f"{where}, field {key!r}: unknown material {table[key]!r} "
                                   f"(known: {', '.join(known)})")
            kw[key] = known[mat]
    elastic = [k for k in ("elastic_modulus", "poisson_ratio") if k in table]
    if not elastic:
        return
    if len(elastic) == 1:
        other = ({"elastic_modulus", "poisson_ratio"} - set(elastic)).pop()
        raise CatalogError(f"{where}, field {elastic[0]!r}: needs {other} too")
    if "ball_material" in kw or "ring_material" in kw:
        raise CatalogError(f"{where}, field 'elastic_modulus': give elastic_modulus / poisson_ratio or "
                           "ball_material / ring_material, not both")
    try:
        mat = Material(f"{where} material", q("elastic_modulus", "pressure"), q("poisson_ratio", "dimensionless"),
                       STEEL.density)
    except InputError as exc:
        raise CatalogError(f"{where}, field 'elastic_modulus': {exc}") from None
    kw["ball_material"] = kw["ring_material"] = mat


def bearing_from_table(table, *, name="", file=None, materials=None):
    """Build a :class:`~bearinglab.bearing.BallBearing` from one catalog table.

    Parameters
    ----------
    table : dict
        The keys of the file format (see the module docstring); quantities as strings with units.
    name : str
        Designation of the entry.
    file : str or Path, optional
        The file it came from, for error messages.
    materials : dict, optional
        ``{name: Material}`` of the file's ``[materials."NAME"]`` tables, for ``ball_material`` and
        ``ring_material``.

    Returns
    -------
    BallBearing

    Raises
    ------
    CatalogError
        Naming the file, the entry and the field.

    Examples
    --------
    >>> b = bearing_from_table({"balls": 9, "ball_diameter": "7.94 mm", "pitch_diameter": "39.04 mm",
    ...                         "contact_angle": "0 deg"}, name="6205")
    >>> b.n_balls, round(b.ball_diameter * 1e3, 2)
    (9, 7.94)
    """
    from ..bearing import BallBearing
    from ..units import parse_quantity

    where = _where(file, name)
    if not isinstance(table, dict):
        raise CatalogError(f"{where}: expected a table of fields, got {type(table).__name__}")
    if table.get("type") in ("cylindrical", "tapered", "spherical"):  # a roller bearing (issue 32)
        from . import _rollers

        return _rollers.from_table(table, name=name, where=where)
    unknown = sorted(set(table) - _KNOWN)
    if unknown:
        raise CatalogError(f"{where}, field {unknown[0]!r}: unknown field (known: {', '.join(sorted(_KNOWN))})")
    kw = {}

    def q(key, kind):
        try:
            return parse_quantity(table[key], kind, key)
        except InputError as exc:
            raise CatalogError(f"{where}, field {key!r}: {exc}") from None

    try:
        if "balls" in table:
            z = table["balls"]
            if isinstance(z, bool) or not isinstance(z, int):
                raise CatalogError(f"{where}, field 'balls': must be a whole number, got {z!r}")
            if z > _bounds.MAX_BALLS:  # before any per-ball array (bearinglab._bounds)
                raise CatalogError(f"{where}, field 'balls': must be <= {_bounds.MAX_BALLS} (bearinglab's size "
                                   f"limit), got {z}")
            kw["n_balls"] = z
        for key in _LENGTHS:
            if key in table:
                kw[key] = q(key, "length")
        for race in ("inner", "outer"):
            r_key, f_key = f"{race}_groove_radius", f"{race}_conformity"
            if r_key in table and f_key in table:
                raise CatalogError(f"{where}, field {r_key!r}: give {r_key} or {f_key}, not both")
            if r_key in table:
                if "ball_diameter" not in kw:
                    raise CatalogError(f"{where}, field {r_key!r}: needs ball_diameter")
                kw[f_key] = q(r_key, "length") / kw["ball_diameter"]
            elif f_key in table:
                kw[f_key] = q(f_key, "dimensionless")
        if "contact_angle" in table:
            kw["contact_angle"] = q("contact_angle", "angle")
        for key in _FORCES:
            if key in table:
                kw[key] = q(key, "force")
        _materials(table, kw, where, materials, q)
        for key in ("type", "source", "series", "seal"):
            if key in table:
                kw[key] = str(table[key])
        if "seals" in table:
            if isinstance(table["seals"], bool) or table["seals"] not in (0, 1, 2):
                raise CatalogError(f"{where}, field 'seals': must be 0, 1 or 2 (sealed sides), got {table['seals']!r}")
            kw["seals"] = int(table["seals"])
        if "hertz_table" in table:
            ht = table["hertz_table"]
            if not (isinstance(ht, dict) and set(ht) <= {"inner", "outer"} and all(isinstance(v, (int, float)) for v in ht.values())):
                raise CatalogError(f"{where}, field 'hertz_table': expected {{ inner = 0.63, outer = 0.852 }}, got {ht!r}")
            kw["hertz_table"] = {k: float(v) for k, v in ht.items()}
        if "estimated" in table:
            est = table["estimated"]
            if not (isinstance(est, list) and all(isinstance(e, str) and e in _ESTIMABLE for e in est)):
                raise CatalogError(f"{where}, field 'estimated': expected a list of field names from "
                                   f"{sorted(_ESTIMABLE)}, got {est!r}")
            kw["estimated_fields"] = tuple(dict.fromkeys(_ESTIMABLE[e] for e in est))
            kw["sources"] = {_ESTIMABLE[e]: f"estimated ({_where(file, name)})" for e in est}
        designation = str(table.get("designation", name))
        return BallBearing(designation=designation, **kw)
    except CatalogError:
        raise
    except InputError as exc:
        msg = str(exc)
        field = msg.split(" ", 1)[0]
        # name the key as written in the file (balls, inner_groove_radius), not the dataclass field
        file_key = {"n_balls": "balls"}.get(field, field)
        if field.endswith("_conformity") and field.replace("_conformity", "_groove_radius") in table:
            file_key = field.replace("_conformity", "_groove_radius")
        raise CatalogError(f"{where}, field {file_key!r}: {msg}") from None


def read_toml(path):
    """Read a TOML input file: UTF-8 text, with or without a byte-order mark.

    Parameters
    ----------
    path : str or Path
        The file; it is only read.

    Returns
    -------
    dict
        The parsed document.

    Raises
    ------
    CatalogError
        Naming the file: it does not exist, cannot be read, is not UTF-8 text (Latin-1, UTF-16, binary)
        or is not valid TOML.

    Examples
    --------
    >>> read_toml("no-such-file.toml")
    Traceback (most recent call last):
    ...
    bearinglab.errors.CatalogError: no-such-file.toml: no such file
    """
    path = Path(path)
    try:  # a regular file of bounded size: not /dev/zero, a FIFO or a 10 GB log (bearinglab._bounds)
        data = _bounds.read_input_bytes(path)
    except InputError as exc:
        raise CatalogError(str(exc)) from None
    except FileNotFoundError:
        raise CatalogError(f"{path}: no such file") from None
    except IsADirectoryError:
        raise CatalogError(f"{path}: is a directory, not a file") from None
    except OSError as exc:
        raise CatalogError(f"{path}: cannot read: {exc.strerror}") from None
    if data.startswith((b"\xff\xfe", b"\xfe\xff")):
        raise CatalogError(f"{path}: the file is UTF-16 text; save it as UTF-8")
    try:
        text = data.decode("utf-8-sig")  # a byte-order mark is simply skipped
    except UnicodeDecodeError as exc:
        raise CatalogError(f"{path}: not a UTF-8 text file (byte {exc.start} is {data[exc.start]:#04x}); "
                           "save it as UTF-8") from None
    if "\x00" in text:
        raise CatalogError(f"{path}: not a text file (it holds NUL bytes)")
    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise CatalogError(f"{path}: not valid TOML: {exc}") from None


_read_toml = read_toml


def _entries(doc, file):
    bearings = doc.get("bearings")
    if not isinstance(bearings, dict) or not bearings:
        raise CatalogError(f"{file}: no [bearings.\"NAME\"] tables")
    tables = doc.get("materials", {})
    if not isinstance(tables, dict):
        raise CatalogError(f"{file}: [materials] must hold [materials.\"NAME\"] tables")
    materials = {k: _material_table(v, k, file) for k, v in tables.items()}
    out, aliases = {}, {}
    for name, table in bearings.items():
        out[name] = bearing_from_table(table, name=name, file=file, materials=materials)
        names = table.get("aliases", [])
        if not (isinstance(names, list) and all(isinstance(a, str) for a in names)):
            raise CatalogError(f"{_where(file, name)}, field 'aliases': expected a list of names such as "
                               f"[\"7218B\"], got {names!r}")
        for alias in names:
            aliases[alias] = name
    return out, aliases


def load_catalog(path):
    """Read a catalog file.

    Parameters
    ----------
    path : str or Path
        TOML file with ``[bearings."NAME"]`` tables.

    Returns
    -------
    dict
        ``{name: BallBearing}``, aliases included as extra keys.
    """
    entries, aliases = _entries(_read_toml(path), path)
    entries.update({alias: entries[name] for alias, name in aliases.items()})
    return entries


def load_bearing_file(path):
    """Read a single-bearing file: the keys of one catalog table at the top level, or one ``[bearings."NAME"]``.

    Parameters
    ----------
    path : str or Path
        The TOML file; it is only read.

    Returns
    -------
    BallBearing
        Named by its ``designation`` key, else by the file's stem.

    Raises
    ------
    CatalogError
        Naming the file, the entry and the field.
    """
    doc = _read_toml(path)
    if "bearings" in doc:
        entries, _ = _entries(doc, path)
        if len(entries) != 1:
            raise CatalogError(f"{path}: a bearing file holds one bearing, found {len(entries)}")
        return next(iter(entries.values()))
    name = str(doc.get("designation", Path(path).stem))
    doc = dict(doc)
    tables = doc.pop("materials", {})
    if not isinstance(tables, dict):
        raise CatalogError(f"{path}: [materials] must hold [materials.\"NAME\"] tables")
    materials = {k: _material_table(v, k, path) for k, v in tables.items()}
    return bearing_from_table(doc, name=name, file=path, materials=materials)


@functools.cache
def builtin():
    """The built-in catalog, ``{name: BallBearing}`` with aliases."""
    ref = resources.files("bearinglab") / "data" / "catalog.toml"
    with resources.as_file(ref) as p:
        return load_catalog(p)


@functools.cache
def _builtin_keys():
    """The names and aliases of ``data/catalog.toml``, read without building its bearings."""
    doc = tomllib.loads((resources.files("bearinglab") / "data" / "catalog.toml").read_text(encoding="utf-8"))
    keys = set(doc["bearings"])
    for table in doc["bearings"].values():
        keys.update(table.get("aliases", []))
    return frozenset(keys)


def _is_builtin_entry(name):
    """Whether ``name`` is a name or alias of ``data/catalog.toml`` (not a standard-series designation)."""
    return _lookup(dict.fromkeys(_builtin_keys()), str(name).strip()) is not None


def _user_files(catalog):
    files = []
    env = os.environ.get(ENV_VAR, "")
    files += [f for f in env.split(os.pathsep) if f]
    if catalog:
        files += [catalog] if isinstance(catalog, (str, Path)) else list(catalog)
    return files


def _all(catalog=None):
    entries = dict(builtin())
    for f in _user_files(catalog):
        entries.update(load_catalog(f))
    return entries


def _lookup(entries, name):
    """The key of ``name`` in ``entries`` (exact, then case-folded and without spaces), or None."""
    if name in entries:
        return name
    folded = {k.lower().replace(" ", ""): k for k in entries}
    return folded.get(str(name).lower().replace(" ", ""))


def _user_entries(catalog):
    entries = {}
    for f in _user_files(catalog):
        entries.update(load_catalog(f))
    return entries


def get(name, *, catalog=None, clearance="mean"):
    """Look a bearing up by name, alias or designation.

    Parameters
    ----------
    name : str
        Name, alias or designation: ``"B218"``, ``"7218B"``, ``"6208-2RS1/C3"``, ``"7205 BECBP"``.
    catalog : str, Path or list, optional
        User catalog file(s), searched before the built-ins (after ``BEARINGLAB_CATALOG``).
    clearance : {"mean", "min", "max"}
        The value of a deep-groove bearing's ISO 5753-1 clearance range that the models use.

    Returns
    -------
    BallBearing
        A standard-series bearing carries its seals (``seal``, ``seals``), ``clearance_class``,
        ``tolerance_class``, ``sources`` (field -> source) and ``estimated_fields``.

    Raises
    ------
    CatalogError
        Unknown name (the message suggests close ones), a suffix that is not known (the message names the
        valid ones) or a malformed catalog file.

    Examples
    --------
    >>> get("7218B").n_balls
    16
    >>> b = get("6208-2RS1/C3")
    >>> b.seal, b.seals, b.clearance_class, round(b.radial_clearance * 1e6)
    ('RS1', 2, 'C3', 24)
    """
    from . import _series

    key = str(name).strip()
    user = _user_entries(catalog)
    hit = _lookup(user, key)
    if hit is not None:
        b = user[hit]
        if _is_builtin_entry(hit) or hit in _series.records():
            note = f"a user catalog entry named {hit!r}: it overrides the built-in bearing of that name"
            b = dataclasses.replace(b, sources={**b.sources, "catalog": note})
        return b
    if _lookup(dict.fromkeys(_builtin_keys()), key) is not None:  # read the TOML entries (and pint) only then
        return builtin()[_lookup(builtin(), key)]
    from . import _rollers

    roller = _rollers.lookup(key)  # the built-in roller bearings (data/roller_series.csv), as written
    if roller is not None and _rollers.lookup(roller) == roller and roller == _rollers.lookup(key) and \
            key.lower().replace(" ", "").replace("-", "") == roller.lower().replace(" ", ""):  # not an alias
        return _rollers.build(roller)
    resolved = _rollers.resolve(key)  # a roller designation with SKF's suffixes (NU 208 ECJ/C3, 22208 EK)
    if resolved is not None:
        return _rollers.build(*resolved)
    if key in _series.records():
        return _series.build(key, clearance=clearance)
    try:
        return _series.resolve(key, clearance=clearance)
    except CatalogError:
        raise
    except InputError as exc:
        if "is not a designation" not in str(exc):
            raise
    known = sorted(set(user) | set(builtin()) | set(_series.records()) | set(_rollers.records()))
    raise CatalogError(f"bearing: unknown name {key!r}; {_suggestions(key, known)}")


def provenance_notes(bearing):
    """The warnings every result computed from this bearing carries.

    Parameters
    ----------
    bearing : BallBearing
        A bearing from :func:`get` (or any bearing: one without estimated fields gives none).

    Returns
    -------
    list of str
        One note naming the estimated fields once and how to give measured values (at most two lines of
        80 columns after ``warning:``), one where another maker's data answers the designation, one for
        a user entry that overrides a built-in bearing; empty when there is nothing to say.

    Examples
    --------
    >>> provenance_notes(get("B218"))
    []
    >>> print(provenance_notes(get("6208"))[0])
    6208: ball set, conformities, contact angle estimated, not published (docs: 'Estimated internal geometry'); measured values: --bearing-file
    """
    notes = []
    est = [f for f in getattr(bearing, "estimated_fields", ()) if f]
    if est and hasattr(bearing, "rollers"):  # a RollerBearing: rules and measured error of its own
        name = bearing.designation if len(bearing.designation or "") <= 20 else "the bearing"
        notes.append(f"{name}: {_estimated_words(est)} estimated or derived by a rule, not published (docs: "
                     "'Roller bearings, estimated internal geometry'); measured values: a user catalog")
    elif est:
        # at most two lines of 80 columns after "warning: " (issue 30): a long name (a designation with the
        # inline values that changed it) is said once, in the result's title, not here
        name = bearing.designation if len(bearing.designation or "") <= 20 else "the bearing"
        notes.append(f"{name}: {_estimated_words(est)} estimated, not published (docs: 'Estimated internal "
                     "geometry'); measured values: --bearing-file")
    sources = getattr(bearing, "sources", {})
    for key in ("maker", "catalog"):
        if sources.get(key):
            notes.append(f"{bearing.designation}: {sources[key]}")
    return notes


# groups of estimated fields named once in the note (the whole ball set, both conformities)
_FIELD_GROUPS = ((("n_balls", "ball_diameter", "pitch_diameter"), "ball set"),
                 (("inner_conformity", "outer_conformity"), "conformities"),
                 (("contact_angle",), "contact angle"), (("radial_clearance",), "clearance"))


def _estimated_words(fields):
    """The estimated fields, a whole group by its name (``ball set``), the others by their own."""
    left, words = list(dict.fromkeys(fields)), []
    for group, word in _FIELD_GROUPS:
        if all(f in left for f in group) and (len(group) > 1 or word != "clearance" or "contact_angle" not in fields):
            words.append(word)
            left = [f for f in left if f not in group]
    # the clearance of an angular bearing follows from its estimated angle and conformities: named once
    words += [f for f in left if f != "radial_clearance" or "contact angle" not in words]
    return ", ".join(words)


def details(name):
    """Catalog data of a standard-series bearing that is no BallBearing field.

    Parameters
    ----------
    name : str
        A designation of the standard series (``"6208"``, ``"6208-2RS1/C3"``, ``"7205 BECBP"``).

    Returns
    -------
    dict or None
        ``row`` (the catalog row's name), ``chamfer_mm``, ``reference_speed_rpm``, ``limiting_speed_rpm``,
        ``mass_kg`` (None where the maker gives none), ``maker_designation``; a roller bearing adds its
        widths, raceway diameters, ISO 355 series, cages and aliases (:func:`_rollers.details`); None for a
        bearing that is not in the standard series.

    Examples
    --------
    >>> details("6208-2Z")["chamfer_mm"]
    1.1
    """
    from . import _rollers, _series

    roller = _rollers.lookup(name)
    if roller is None:
        try:
            resolved = _rollers.resolve(name)
        except (CatalogError, InputError):
            resolved = None
        roller = resolved and resolved[0]
    if roller is not None:  # a built-in roller bearing (data/roller_series.csv)
        return _rollers.details(roller)
    row = str(name).strip() if str(name).strip() in _series.records() else _series.row_name(name)
    return None if row is None else {"row": row, **_series.details(row)}


def search(*, bore=None, outside_diameter=None, width=None, type=None, series=None, tolerance=1e-6):
    """The standard-series bearings of given boundary dimensions, type and series.

    Parameters
    ----------
    bore, outside_diameter, width : float, optional
        d, D, B to match (within ``tolerance``). [m]
    type : str, optional
        Bearing type as listings show it: ``deep-groove`` (or ``radial``), ``angular``, ``four-point``,
        ``double-row-angular``, ``double-row-radial``, ``self-aligning``, ``thrust``, ``cylindrical``,
        ``tapered``, ``spherical`` (the types of the rows); None: every type.
    series : str, optional
        Series such as ``"62"``, ``"618"``, ``"72"`` (every angle code), ``"72B"``, ``"79C"``; of roller
        bearings ``"2"``, ``"22"`` (cylindrical), ``"302"``, ``"322"`` (tapered), ``"222"`` (spherical).
    tolerance : float
        Allowed difference of each dimension. [m]

    Returns
    -------
    list of dict
        One per bearing: ``name``, ``type`` (``deep-groove``, ``angular``, ``thrust`` ...,
        ``cylindrical``, ``tapered``, ``spherical``), ``series``, ``bore_mm``, ``outside_diameter_mm``, ``width_mm`` (T of a tapered
        bearing), ``contact_angle_deg`` (a tapered bearing's derived from its e), ``dynamic_load_rating_kN``,
        ``static_load_rating_kN``, ``maker_designation``; ordered by bore, then outside diameter, ball
        bearings before roller bearings of one size.

    Examples
    --------
    >>> [r["name"] for r in search(bore=0.040, outside_diameter=0.080, type="angular")]
    ['7208 BE', '7208 A', '7208 B', '7208 C', '7208 ACD', 'S 6208 C', 'S 6208 E']
    >>> [(r["name"], r["type"]) for r in search(bore=0.040, outside_diameter=0.080, width=0.018, series="QJ2")]
    [('QJ 208', 'four-point')]
    >>> [(r["name"], r["type"]) for r in search(bore=0.040, outside_diameter=0.080, series="22")][:2]
    [('2208', 'self-aligning'), ('NU 2208 ECP', 'cylindrical')]
    """
    from . import _rollers, _series

    roller_types = (None, *_rollers.TYPES)
    ball_types = _series.types()
    if type not in roller_types and type not in ball_types:
        valid = [t for t in ball_types if t != "radial"] + list(_rollers.TYPES)
        raise InputError(f"type must be one of {valid}, got {type!r}")
    rollers = [] if type not in roller_types else [  # the built-in roller bearings (data/roller_series.csv)
        _rollers.entry(n) for n in _rollers.search(bore=bore, outside_diameter=outside_diameter, width=width,
                                                   type=type, series=series, tolerance=tolerance)]
    if type in _rollers.TYPES:
        return sorted(rollers, key=lambda r: (r["bore_mm"], r["outside_diameter_mm"]))
    out = []
    for name in _series.search(bore=bore, outside_diameter=outside_diameter, width=width, type=type,
                               series=series, tolerance=tolerance):
        r = _series.records()[name]
        out.append({"name": name, "type": _series.display_type(r["type"]),
                    "series": r["series"], "bore_mm": r["bore_mm"], "outside_diameter_mm": r["outside_diameter_mm"],
                    "width_mm": r["width_mm"], "contact_angle_deg": r["contact_angle_deg"],
                    "dynamic_load_rating_kN": r["dynamic_load_rating_kN"],
                    "static_load_rating_kN": r["static_load_rating_kN"], "maker_designation": r["maker_designation"]})
    order = {n: i for i, n in enumerate(_series.records())}
    order.update({r["name"]: len(order) + i for i, r in enumerate(rollers)})
    return sorted(out + rollers, key=lambda r: (r["bore_mm"], r["outside_diameter_mm"], order[r["name"]]))


def _suggestions(name, known):
    """The end of an unknown-name message: close names first (a designation typed without its suffix,
    such as 6205 for 6205-2RS, or a typo), then every name while the list is short."""
    key = name.lower()
    close = [k for k in known if k.lower().startswith(key) or key.startswith(k.lower())]
    close = close or difflib.get_close_matches(name, known, n=3, cutoff=0.6)
    hint = f"did you mean {' or '.join(close[:3])}? " if close else ""
    if len(known) <= 20:
        return f"{hint}known: {', '.join(known)}"
    return f"{hint}`bearinglab catalog list` shows the {len(known)} names"


def aliases(*, catalog=None):
    """The aliases of the bearings visible, and the name each stands for.

    Parameters
    ----------
    catalog : str, Path or list, optional
        User catalog file(s), in addition to ``BEARINGLAB_CATALOG`` and the built-ins.

    Returns
    -------
    dict
        ``{name: [alias, ...]}`` for the names that have aliases, the aliases sorted.

    Examples
    --------
    >>> aliases()["B218"]
    ['7218B']
    """
    entries = _all(catalog)
    first = {}
    for name in names(catalog=catalog):
        if name in entries:  # the standard series have no aliases
            first[id(entries[name])] = name
    out = {}
    for key, b in entries.items():
        name = first.get(id(b))
        if name is not None and key != name:
            out.setdefault(name, []).append(key)
    return {k: sorted(v) for k, v in out.items()}


def names(*, catalog=None):
    """Names of all bearings visible (built-ins and user catalogs), aliases excluded.

    Parameters
    ----------
    catalog : str, Path or list, optional
        User catalog file(s), in addition to ``BEARINGLAB_CATALOG`` and the built-ins.

    Returns
    -------
    list of str
        Sorted names.

    Examples
    --------
    >>> "B218" in names() and "7218B" not in names()
    True
    """
    from . import _rollers, _series

    seen = {}
    for name, b in _all(catalog).items():
        seen.setdefault(id(b), name)
    return sorted(set(seen.values()) | set(_series.records()) | set(_rollers.records()))

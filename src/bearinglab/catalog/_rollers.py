"""The built-in roller bearings (``data/roller_series.csv``) and roller entries of user TOML catalogs (private).

Rows and bearings
-----------------
records          the CSV rows, parsed once, keyed by designation (numbers as floats)
lookup           the designation of a name as written exactly (``"NU208ECP"``, ``"nu 208 ecp"``, an alias), or None
resolve          a designation with SKF's suffixes (``"NU 208 ECJ/C3"``, ``"30208"``, ``"22208 EK"``) -> its row
build            the RollerBearing of a row, with its sources and what a written designation adds
from_table       a ``type = "cylindrical" | "tapered" | "spherical"`` table of a user catalog -> RollerBearing
ROLLER_KEYS      the keys of such a table

Catalog views (no bearing built, no numpy: ``catalog search`` stays light)
-------------------------------------------------------------------------
search           the rows of given dimensions, type and series
entry            the catalog-search row of a designation (name, type, series, dimensions, C, C0)
listing          the ``catalog list`` row of a designation: the roller set as printed or estimated
details          catalog data that is no RollerBearing field (chamfers, widths, speeds, mass, cages, aliases)
summary          every field of a RollerBearing in engineering units, for ``catalog show``
TYPES            the types of the rows

A row carries the catalogue's envelope, ratings and factors; a cylindrical bearing's printed raceway diameters
F and E fix its roller and pitch diameters; a tapered bearing's cup angle is derived from its e (ISO 281:
e = 1.5 tan alpha) and says so. No row carries Z or L_we (no maker publishes them): the models that need
them estimate them (:mod:`bearinglab.rollers.estimation`) and say so.
"""

from __future__ import annotations

import csv
import functools
import io
import math
from importlib import resources

from ..errors import CatalogError, InputError

__all__ = ["ROLLER_KEYS", "TYPES", "build", "details", "entry", "from_table", "listing", "lookup", "records",
           "resolve", "search", "summary"]

_MM, _KN = 1e-3, 1e3
TYPES = ("cylindrical", "tapered", "spherical")
_NUMBER_COLUMNS = (
    "bore_mm", "outside_diameter_mm", "width_mm", "inner_ring_width_mm", "outer_ring_width_mm", "chamfer_mm",
    "chamfer_small_mm", "dynamic_load_rating_kN", "static_load_rating_kN", "fatigue_load_limit_kN",
    "reference_speed_rpm", "limiting_speed_rpm", "mass_kg", "ratio_limit", "axial_factor_below", "axial_factor",
    "static_axial_factor", "pressure_centre_mm", "contact_angle_deg", "inner_raceway_diameter_mm",
    "outer_raceway_diameter_mm")
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
    """The rows of ``data/roller_series.csv``, ``{designation: row}``: numbers as floats (None where empty)."""
    text = (resources.files("bearinglab") / "data" / "roller_series.csv").read_text(encoding="utf-8")
    body = io.StringIO("".join(line for line in text.splitlines(keepends=True) if not line.startswith("#")))
    out = {}
    for row in csv.DictReader(body):
        r = dict(row)
        for key in _NUMBER_COLUMNS:
            r[key] = float(row[key]) if row[key] else None
        r["cages"] = tuple(c.strip() for c in row["cages"].split(",") if c.strip())
        r["aliases"] = tuple(a.strip() for a in row["aliases"].split(";") if a.strip())
        r["explorer"] = row["explorer"] == "yes"
        out[row["designation"]] = r
    return out


@functools.cache
def _folded():
    out = {}
    for key, row in records().items():
        out[_fold(key)] = key
        for alias in row["aliases"]:
            out[_fold(alias)] = key
    return out


@functools.cache
def _parts():
    """``{designation: (type, prefix, base, design, cage, other)}`` of the rows, from their own designations."""
    from ..designation import parse_roller

    out = {}
    for key in records():
        d = parse_roller(key)
        out[key] = (d.type, d.prefix, d.base, d.design, d.cage, d.other)
    return out


def lookup(name):
    """The designation of a built-in roller bearing written exactly (spaces, case and hyphens ignored), or None.

    Parameters
    ----------
    name : str
        E.g. ``"NU 208 ECP"``, ``"nu208ecp"``, ``"30208 J2/Q"``, an alias such as ``"22208 EK"``.

    Returns
    -------
    str or None

    Examples
    --------
    >>> lookup("nu208ecp"), lookup("22208 ek"), lookup("6208")
    ('NU 208 ECP', '22208 E', None)
    """
    return _folded().get(_fold(name))


def _suggest(d):
    """'did you mean ...' for a parsed roller designation: the rows of its base (any design), else of its series."""
    same = [k for k, p in _parts().items() if p[0] == d.type and p[2] == d.base]
    if same:
        return f"did you mean {' or '.join(same[:6])}?"
    near = sorted((abs(records()[k]["bore_mm"] - d.bore), k) for k, p in _parts().items()
                  if p[0] == d.type and p[1] == d.prefix and records()[k]["series"].split()[0] == d.series)
    if near:
        return f"did you mean {' or '.join(k for _, k in near[:3])} (series {d.series})?"
    return "`bearinglab catalog search --type " + d.type + "` lists the built-in ones"


def resolve(text):
    """The catalog row of a roller-bearing designation with SKF's suffixes, and what the suffixes say.

    Parameters
    ----------
    text : str
        A designation (``"NU 208 ECJ/C3"``, ``"NJ2208EC"``, ``"30208"``, ``"32310 BJ2/Q"``, ``"22208 EK/C3"``).

    Returns
    -------
    tuple of (str, RollerDesignation) or None
        The row's designation and the parsed text; None when the text is no roller-bearing designation.

    Raises
    ------
    CatalogError
        A roller bearing that is not in the catalog (the message suggests the nearest rows), or a cage,
        design or tapered bore that SKF does not make for that size (the message names what it makes).
    InputError
        An unknown suffix (:func:`bearinglab.designation.parse_roller`).

    Examples
    --------
    >>> resolve("NU 208 ECJ/C3")[0], resolve("30208")[0], resolve("22208 EK")[0]
    ('NU 208 ECP', '30208 J2/Q', '22208 E')
    """
    from ..designation import parse_roller

    d = parse_roller(text)
    if d is None:
        return None
    raw = d.text.strip()
    rows = [k for k, p in _parts().items() if p[0] == d.type and p[2] == d.base and p[1] == d.prefix]
    if not rows:
        raise CatalogError(f"bearing: unknown name {raw!r}: no {d.type} roller bearing {d.prefix or ''}"
                           f"{' ' if d.prefix else ''}{d.base} in the built-in catalog; {_suggest(d)}")
    parts = _parts()
    listed = rows
    if d.design is not None:
        rows = [k for k in rows if parts[k][3] == d.design]
    elif d.type == "tapered":  # no B written: the standard angle (X, the ISO boundary dimensions, is implied)
        rows = [k for k in rows if parts[k][3] != "B"]
    if not rows:
        raise CatalogError(f"bearing: {raw!r}: the catalogue lists {' and '.join(listed)} of this size, none with "
                           f"the internal design {d.design or '(standard)'} written")
    if d.cage is not None:
        own = [k for k in rows if parts[k][4] == d.cage]
        alt = [k for k in rows if d.cage in records()[k]["cages"]]
        if own or alt:
            rows = own or alt
        else:
            made = "; ".join(f"{k} (cage {parts[k][4] or 'none written'}" + (
                f", or the alternatives {', '.join(records()[k]['cages'])})" if records()[k]["cages"] else ")")
                for k in rows)
            raise CatalogError(f"bearing: {raw!r}: the catalogue lists {made}, not the cage {d.cage}")
    if d.tapered_bore is not None:
        rows = [k for k in rows if any(parse_roller(a).tapered_bore == d.tapered_bore for a in records()[k]["aliases"])]
        if not rows:
            raise CatalogError(f"bearing: {raw!r}: the catalogue lists no tapered bore ({d.tapered_bore}) of this size; "
                               f"{_suggest(d)}")
    # the row whose own other suffixes (Q, CL7C ...) share most with those written, else the catalogue's first
    order = {k: i for i, k in enumerate(records())}
    rows.sort(key=lambda k: (-len(set(parts[k][5]) & set(d.other)), order[k]))
    return rows[0], d


def _derived_fields(row):
    """The RollerBearing fields a row derives by a rule (its ``derived`` column names them)."""
    text = row["derived"]
    out = []
    if "contact_angle_deg" in text:
        out.append("contact_angle")
    if "outer_raceway_diameter_mm" in text or "inner_raceway_diameter_mm" in text:
        out += ["roller_diameter", "pitch_diameter"]
    return tuple(out)


def _note(text, clause):
    """The ``derived`` text of a row about one column (a row derives one column at most)."""
    return text if text.startswith(clause) else ""


def build(designation, parsed=None):
    """The :class:`~bearinglab.rollers.bearing.RollerBearing` of a built-in row, with its sources.

    Parameters
    ----------
    designation : str
        A key of :func:`records` (see :func:`lookup`, :func:`resolve`).
    parsed : RollerDesignation, optional
        The designation as written (:func:`resolve`): the bearing takes its text as designation, and its
        sources say which row it is, and what the cage, tapered bore, clearance and tolerance suffixes are.

    Returns
    -------
    RollerBearing
        Envelope, ratings and factors from the catalogue; the roller and pitch diameters of a cylindrical
        bearing from its printed F and E; the cup angle of a tapered one derived from e (``estimated_fields``
        lists what a rule gave); no roller count or length (estimated where a model needs them).

    Examples
    --------
    >>> b = build("30208 J2/Q")
    >>> b.type, b.static_load_rating, b.axial_factor, round(math.degrees(b.contact_angle), 2)
    ('tapered', 68000.0, 1.6, 13.86)
    >>> b.estimated_fields
    ('contact_angle',)
    """
    from ..rollers.bearing import RollerBearing

    row = records()[designation]
    kw = {"type": row["type"], "design": row["design"], "series": row["series"]}
    for col, name in _LENGTH_COLUMNS.items():
        if row[col] is not None:
            kw[name] = row[col] * _MM
    for col, name in _FORCE_COLUMNS.items():
        if row[col] is not None:
            kw[name] = row[col] * _KN
    for name in _FACTOR_COLUMNS:
        if row[name] is not None:
            kw[name] = row[name]
    src = row["source"]
    sources = {name: src for name in (*kw, "designation") if name not in ("type", "design")}
    derived = _derived_fields(row)
    if row["contact_angle_deg"] is not None:
        kw["contact_angle"] = math.radians(row["contact_angle_deg"])
        sources["contact_angle"] = "derived by a rule, " + _note(row["derived"], "contact_angle_deg")
    f, e = row["inner_raceway_diameter_mm"], row["outer_raceway_diameter_mm"]
    if f is not None and e is not None:  # the printed raceway diameters fix the roller and the pitch diameter
        kw["roller_diameter"] = 0.5 * (e - f) * _MM
        kw["pitch_diameter"] = 0.5 * (e + f) * _MM
        how = f"(E - F)/2 and (E + F)/2 of the raceway diameters F = {f:g} mm, E = {e:g} mm: {src}"
        if "roller_diameter" in derived:
            how += "; " + _note(row["derived"], "outer_raceway_diameter_mm")
        sources["roller_diameter"] = sources["pitch_diameter"] = how
    label, notes = designation, {}
    if parsed is not None:
        label = parsed.text.strip()
        if _fold(label) != _fold(designation):
            notes["catalog"] = f"the catalog row {designation!r}, for {label!r} as written"
        if parsed.cage is not None and parsed.cage in row["cages"]:
            notes["cage"] = (f"cage {parsed.cage}: an alternative cage the catalogue lists for {designation}, with the "
                             f"same data ({src.split(':')[0]})")
        if parsed.tapered_bore is not None:
            notes["tapered_bore"] = (f"{parsed.tapered_bore}: tapered bore (taper 1:12; K30 1:30), the same data as the "
                                     f"cylindrical bore ({src.split(':')[0]})")
        if parsed.clearance_class is not None:
            notes["clearance_class"] = (f"{parsed.clearance_class} as written: bearinglab holds no ISO 5753-1 table of "
                                        "roller bearings, so no clearance follows from it; give radial_clearance")
        if parsed.tolerance_class is not None:
            notes["tolerance_class"] = f"{parsed.tolerance_class} as written"
        if parsed.other:
            notes["suffixes"] = f"{' '.join(parsed.other)} as written: they change no value bearinglab uses"
    return RollerBearing(designation=label, sources={**sources, **notes}, source=src, estimated_fields=derived,
                         **kw)


# ------------------------------------------------------------------ catalog views (no numpy)
def _within(value, target, tolerance):
    return target is None or (value is not None and abs(value * _MM - target) <= tolerance)


def search(*, bore=None, outside_diameter=None, width=None, type=None, series=None, tolerance=1e-6):
    """The designations of the rows of given dimensions [m], type and series, in the file's order.

    Parameters
    ----------
    bore, outside_diameter, width : float, optional
        d, D and B (T of a tapered bearing) to match within ``tolerance``. [m]
    type : {"cylindrical", "tapered", "spherical"}, optional
        The type.
    series : str, optional
        A dimension series as the rows give it (``"2"``, ``"22"``, ``"302"``, ``"322"`` (and its ``322 B``),
        ``"222"`` (and ``222 E``)).
    tolerance : float
        Allowed difference of each dimension. [m]

    Returns
    -------
    list of str

    Examples
    --------
    >>> search(bore=0.040, outside_diameter=0.080, type="tapered")
    ['30208 J2/Q', '32208 J2/Q']
    """
    if type is not None and type not in TYPES:
        raise InputError(f"type must be one of {list(TYPES)}, got {type!r}")
    out = []
    for name, r in records().items():
        if not (_within(r["bore_mm"], bore, tolerance) and _within(r["outside_diameter_mm"], outside_diameter, tolerance)
                and _within(r["width_mm"], width, tolerance)):
            continue
        if type is not None and r["type"] != type:
            continue
        s = r["series"]
        if series is not None and not (s == series or s.startswith(series) and not s[len(series):len(series) + 1].isdigit()):
            continue
        out.append(name)
    return out


def entry(name):
    """The ``catalog search`` row of a designation (the keys of the ball-bearing rows; mm, deg, kN).

    Examples
    --------
    >>> entry("NU 208 ECP")["type"], entry("NU 208 ECP")["static_load_rating_kN"]
    ('cylindrical', 53.0)
    """
    r = records()[name]
    angle = 0.0 if r["type"] == "cylindrical" else r["contact_angle_deg"]
    return {"name": name, "type": r["type"], "series": r["series"], "bore_mm": r["bore_mm"],
            "outside_diameter_mm": r["outside_diameter_mm"], "width_mm": r["width_mm"], "contact_angle_deg": angle,
            "dynamic_load_rating_kN": r["dynamic_load_rating_kN"], "static_load_rating_kN": r["static_load_rating_kN"],
            "maker_designation": f"SKF {name}"}


def listing(name):
    """The ``catalog list`` row of a designation: its roller set as printed, or estimated and marked so.

    Returns
    -------
    dict
        ``name``, ``type``, ``rollers``, ``roller_diameter_mm``, ``pitch_diameter_mm``, ``contact_angle_deg``,
        ``bore_mm``, ``outside_diameter_mm``, ``aliases``, ``estimated`` (True when Z is estimated: always
        for a roller set), ``diameter_estimated`` (D_we and D_pw estimated: F and E are not both printed); a
        spherical bearing has no roller set here (its load distribution is not modelled).

    Examples
    --------
    >>> r = listing("NU 208 ECP")
    >>> r["rollers"], r["roller_diameter_mm"], r["pitch_diameter_mm"], r["estimated"]
    (14, 11.0, 60.5, True)
    """
    from ..rollers.estimation import estimate_roller_set

    r = records()[name]
    out = {"name": name, "type": r["type"], "rollers": None, "roller_diameter_mm": None, "pitch_diameter_mm": None,
           "contact_angle_deg": 0.0 if r["type"] == "cylindrical" else r["contact_angle_deg"],
           "bore_mm": r["bore_mm"], "outside_diameter_mm": r["outside_diameter_mm"], "aliases": list(r["aliases"]),
           "estimated": False}
    if r["type"] == "spherical":
        return out
    f, e = r["inner_raceway_diameter_mm"], r["outer_raceway_diameter_mm"]
    known = f is not None and e is not None
    s = estimate_roller_set(r["bore_mm"] * _MM, r["outside_diameter_mm"] * _MM, r["static_load_rating_kN"] * _KN,
                            width=r["width_mm"] * _MM, bearing_type=r["type"], axial_factor=r["axial_factor"],
                            ratio_limit=r["ratio_limit"],
                            contact_angle=None if r["contact_angle_deg"] is None else math.radians(r["contact_angle_deg"]),
                            roller_diameter=0.5 * (e - f) * _MM if known else None,
                            pitch_diameter=0.5 * (e + f) * _MM if known else None)
    out.update(rollers=s.rollers, roller_diameter_mm=round(s.roller_diameter / _MM, 3),
               pitch_diameter_mm=round(s.pitch_diameter / _MM, 3), estimated=True, diameter_estimated=not known)
    return out


def details(name):
    """Catalog data of a built-in roller bearing that is no RollerBearing field.

    Returns
    -------
    dict
        ``row``, ``maker_designation``, ``outer_ring_width_mm`` (C of a tapered bearing's cup),
        ``chamfer_mm`` (r1,2 min), ``chamfer_small_mm`` (r3,4 min), ``inner_raceway_diameter_mm`` (F),
        ``outer_raceway_diameter_mm`` (E), ``iso355_series``, ``reference_speed_rpm``, ``limiting_speed_rpm``,
        ``mass_kg``, ``cages`` (the alternatives), ``aliases``, ``performance_class`` (``"SKF Explorer"``,
        whose ratings exceed ISO 281's); None where the catalogue gives none.

    Examples
    --------
    >>> details("30208 J2/Q")["iso355_series"], details("NU 208 ECP")["cages"]
    ('3DB', ['J', 'M', 'ML'])
    """
    r = records()[name]
    return {"row": name, "maker_designation": f"SKF {name}", "outer_ring_width_mm": r["outer_ring_width_mm"],
            "chamfer_mm": r["chamfer_mm"], "chamfer_small_mm": r["chamfer_small_mm"],
            "inner_raceway_diameter_mm": r["inner_raceway_diameter_mm"],
            "outer_raceway_diameter_mm": r["outer_raceway_diameter_mm"], "iso355_series": r["iso355_series"] or None,
            "reference_speed_rpm": r["reference_speed_rpm"], "limiting_speed_rpm": r["limiting_speed_rpm"],
            "mass_kg": r["mass_kg"], "cages": list(r["cages"]), "aliases": list(r["aliases"]),
            "performance_class": "SKF Explorer" if r["explorer"] else None}


def summary(bearing):
    """Every field of a roller bearing in engineering units (mm, deg, N), for ``catalog show``.

    Parameters
    ----------
    bearing : RollerBearing
        A bearing; the roller set shown is its own or, where a model would estimate it, the estimate
        (listed in the result's ``estimated_fields`` by the caller's bearing).

    Returns
    -------
    dict
        Field name with its unit -> value; None for a field the bearing does not give.
    """
    b = bearing

    def mm(x):
        return None if x is None else x / _MM

    return {"designation": b.designation, "type": b.type, "design": b.design, "series": b.series,
            "rows": b.rows, "rollers": b.rollers, "roller_diameter_mm": mm(b.roller_diameter),
            "roller_length_mm": mm(b.roller_length), "pitch_diameter_mm": mm(b.pitch_diameter),
            "contact_angle_deg": None if b.contact_angle is None else math.degrees(b.contact_angle),
            "radial_clearance_um": None if b.radial_clearance is None else b.radial_clearance * 1e6,
            "bore_mm": mm(b.bore), "outside_diameter_mm": mm(b.outside_diameter), "width_mm": mm(b.width),
            "inner_ring_width_mm": mm(b.inner_ring_width), "pressure_centre_mm": mm(b.pressure_centre),
            "e": b.ratio_limit, "Y1": b.axial_factor_below, "Y": b.axial_factor, "Y0": b.static_axial_factor,
            "profile": b.profile if isinstance(b.profile, str) else "table",
            "roller_material": b.roller_material.name, "ring_material": b.ring_material.name, "source": b.source}


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

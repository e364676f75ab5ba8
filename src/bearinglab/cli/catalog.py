"""Command line of the catalogs: ``catalog list``, ``catalog show NAME`` and ``catalog search``.

Commands
--------
COMMANDS   the ``catalog`` command group, by name (the application adds it)
"""

import re
from typing import Annotated

import typer

from ..errors import InputError
from ._common import (
    CatalogFile,
    JsonFlag,
    add_notes,
    check_input,
    emit_json,
    print_warnings,
    table,
)
from ._options import command

__all__ = ["COMMANDS"]

catalog_app = typer.Typer(help="Bearings in the built-in and user catalogs.", no_args_is_help=True)

# info keys of `catalog show` -> the BallBearing fields they come from (to mark estimated values)
_FIELD_OF_KEY = {
    "balls": "n_balls", "ball_diameter_mm": "ball_diameter", "pitch_diameter_mm": "pitch_diameter",
    "inner_conformity": "inner_conformity", "outer_conformity": "outer_conformity",
    "inner_groove_radius_mm": "inner_conformity", "outer_groove_radius_mm": "outer_conformity",
    "total_curvature_B": "inner_conformity", "groove_distance_A_mm": "inner_conformity",
    "gamma": "ball_diameter", "contact_angle_deg": "contact_angle", "axial_play_mm": "inner_conformity",
    "radial_clearance_um": "radial_clearance",
    "rollers": "rollers", "roller_diameter_mm": "roller_diameter", "roller_length_mm": "roller_length",
}
_LENGTH = re.compile(r"^\s*([0-9]*\.?[0-9]+(?:[eE][-+]?[0-9]+)?)\s*(mm|m|um|µm|in)?\s*$")
_TO_M = {"mm": 1e-3, None: 1e-3, "m": 1.0, "um": 1e-6, "µm": 1e-6, "in": 0.0254}


def _fmt(x, spec="g"):
    return "" if x is None else format(x, spec)


def _length(text, name):
    """A length option [m]: '40 mm', '40' (mm), '1.5 in'; other spellings through bearinglab.units."""
    if text is None:
        return None
    m = _LENGTH.match(str(text))
    if m:  # the usual spellings without loading the units library (catalog search answers fast)
        value = float(m.group(1)) * _TO_M[m.group(2)]
        if not value > 0:
            raise InputError(f"{name} must be > 0 [mm], got {text!r}")
        return value
    from ._common import parse_length
    return parse_length(text, name)


def _two_lines(word):
    """A long type word broken after its last hyphen (``double-row-`` over ``angular``), so that the
    list's table fits 80 columns."""
    head, hyphen, tail = word.rpartition("-")
    return f"{head}-\n{tail}" if hyphen and len(word) > 10 else word


_TYPE_HELP = ("deep-groove, angular, four-point, double-row-angular, double-row-radial, self-aligning or "
              "thrust (any type word of the catalog).")


@catalog_app.command("list")
def catalog_list(catalog: CatalogFile = None, json_out: JsonFlag = False,
                 type: Annotated[str | None, typer.Option("--type", help=_TYPE_HELP)] = None):
    """List the bearings known (of one type with --type)."""
    from .. import catalog as _catalog
    from .. import tables
    from ..catalog import _series
    if catalog is not None:
        check_input(catalog, "catalog")
    known_types = _series.types()
    if type is not None and type not in known_types:
        raise InputError(f"type must be one of {[t for t in known_types if t != 'radial']}, got {type!r}")
    known = _catalog.aliases(catalog=catalog)
    listing = _series.listing()
    user = set(_catalog._user_entries(catalog))
    rows = []
    from ..catalog import _rollers
    for name in _catalog.names(catalog=catalog):
        if name in _rollers.records() and name not in user:  # built-in roller bearings: the set as estimated
            rows.append(_rollers.listing(name))
        elif name in listing and name not in user and not _catalog._is_builtin_entry(name):
            r = _series.records()[name]
            z, dw, dm, est = listing[name]
            rows.append({"name": name, "type": r["type"], "balls": z, "ball_diameter_mm": dw, "pitch_diameter_mm": dm,
                         "contact_angle_deg": r["contact_angle_deg"], "bore_mm": r["bore_mm"],
                         "outside_diameter_mm": r["outside_diameter_mm"], "aliases": [], "estimated": est})
        else:
            b = _catalog.get(name, catalog=catalog)
            entry = (tables.catalog_entry(name, b) if not hasattr(b, "rollers") else  # a user's roller bearing
                     {"name": name, "type": b.type, "rollers": b.rollers,
                      "roller_diameter_mm": b.roller_diameter and b.roller_diameter * 1e3,
                      "pitch_diameter_mm": b.pitch_diameter and b.pitch_diameter * 1e3,
                      "contact_angle_deg": None if b.contact_angle is None else b.contact_angle * 57.29577951308232,
                      "bore_mm": b.bore and b.bore * 1e3, "outside_diameter_mm": b.outside_diameter and
                      b.outside_diameter * 1e3})
            rows.append(dict(entry, aliases=known.get(name, []), estimated=False))
    if type is not None:  # the row's own word (radial) or its listing word (deep-groove)
        rows = [r for r in rows if known_types[type] in (r["type"], known_types.get(r["type"], r["type"]))]
    if json_out:
        emit_json(rows)
        return
    balls = [r for r in rows if "rollers" not in r]
    if balls:
        # the aliases beside the name, in brackets: eight columns fit 80 (--json lists them apart)
        table("Bearings", ["name (aliases)", "type", "Z", "D [mm]", "d_m [mm]", "α0 [deg]", "bore × OD [mm]"], [
            [" ".join([r["name"], *(f"({', '.join(r['aliases'])})" for _ in r["aliases"][:1])]), _two_lines(r["type"]),
             f"{r['balls']}*" if r["estimated"] else (r["balls"] or ""),
             _fmt(r["ball_diameter_mm"]) + ("*" if r["estimated"] else ""), _fmt(r["pitch_diameter_mm"]),
             _fmt(r["contact_angle_deg"]), f"{_fmt(r['bore_mm'])} × {_fmt(r['outside_diameter_mm'])}"] for r in balls],
              caption="* estimated ball set; catalog show NAME (or a designation) for every field and the ratings")
    for kind in ("cylindrical", "tapered", "spherical"):  # one table per roller type: long designations fit 80
        these = [r for r in rows if "rollers" in r and r["type"] == kind]
        if not these:
            continue
        if kind == "spherical":  # no roller set: its load distribution is not modelled
            table("Spherical roller bearings", ["name", "d × D [mm]", "tapered bore"], [
                [r["name"], f"{_fmt(r['bore_mm'])} × {_fmt(r['outside_diameter_mm'])}", ", ".join(r["aliases"])]
                for r in these], caption="ratings, life and friction only; catalog show NAME for every field")
            continue
        angle = ["α [deg]"] if kind == "tapered" else []
        table(f"{kind.capitalize()} roller bearings", ["name", "Z", "D_we [mm]", "D_pw [mm]", *angle, "d × D [mm]"], [
            [r["name"], f"{r['rollers']}*" if r["estimated"] and r["rollers"] else (r["rollers"] or ""),
             _fmt(r["roller_diameter_mm"]) + ("*" if r.get("diameter_estimated", r["estimated"]) else ""),
             _fmt(r["pitch_diameter_mm"]) + ("*" if r.get("diameter_estimated", r["estimated"]) else ""),
             *([_fmt(r["contact_angle_deg"])] if angle else []),
             f"{_fmt(r['bore_mm'])} × {_fmt(r['outside_diameter_mm'])}"] for r in these],
              caption="* estimated (the models say so); catalog show NAME for every field and its source")


def catalog_show(given, *, catalog: CatalogFile = None, json_out: JsonFlag = False):
    """Show one bearing: geometry, ratings C, C0, Cu (catalog or computed), limits and where each comes from."""
    from .. import catalog as _catalog
    from ..calculations.documents import catalog_document
    if catalog is not None:
        check_input(catalog, "catalog")
    info, b = catalog_document(given["name"], catalog=catalog, clearance=given.get("clearance"),
                               radial_clearance=given.get("radial_clearance"))
    add_notes(_catalog.provenance_notes(b))
    if json_out:
        emit_json(info)
        return
    estimated = set(b.estimated_fields)
    table(f"Bearing {info['designation']}", ["quantity", "value"],
          [[k, _value(k, v, info.get("rating_source") or {}, estimated)] for k, v in info.items()
           if v is not None and k not in ("rating_source", "inputs", "warnings", "sources", "estimated_fields",
                                          "source")],
          caption=("(estimated): no public source gives the value; catalog show --json lists every source"
                   if estimated else "catalog show --json lists the source of every value"))
    print_warnings(info["warnings"])


def _value(key, value, sources, estimated):
    """A cell of ``catalog show``; a rating carries its source (catalog, ISO 76, ISO 281 ...), an estimated
    value says so."""
    if key == "iso5753_clearance":
        return (f"{value['class']}: {_fmt(value['minimum_um'])} - {_fmt(value['maximum_um'])} um; "
                f"the models use {value['used']}")
    if isinstance(value, float):
        text = _fmt(value, ".6g")
    elif isinstance(value, list):
        text = " - ".join(_fmt(v, ".6g") if isinstance(v, float) else str(v) for v in value)
    else:
        text = str(value)
    src = sources.get(key.removesuffix("_N"))
    if src is not None:
        return f"{text} ({src})"
    field = _FIELD_OF_KEY.get(key)
    if field is not None and field in estimated:
        return f"{text} (estimated)"
    return text


def catalog_search(given, *, json_out: JsonFlag = False):
    """Find standard-series bearings by boundary dimensions, type and series."""
    from .. import catalog as _catalog
    bore, outside_diameter, width, type, series = (given.get(k) for k in _SEARCH)
    if all(x is None for x in (bore, outside_diameter, width, type, series)):
        raise InputError("search: give at least one of --bore, --outside-diameter, --width, --type, --series")
    hits = _catalog.search(bore=_length(bore, "bore"), outside_diameter=_length(outside_diameter, "outside-diameter"),
                           width=_length(width, "width"), type=type, series=series)
    if json_out:
        emit_json({"bearings": hits, "inputs": {"bore": bore, "outside_diameter": outside_diameter, "width": width,
                                                 "type": type, "series": series}, "warnings": []})
        return
    if not hits:
        print_warnings(["no bearing of the standard series matches; `catalog list` shows them all"])
        return
    table("Bearings found", ["name", "type", "d × D × B [mm]", "α0 [deg]", "C [kN]", "C0 [kN]"], [
        [h["name"], h["type"], f"{_fmt(h['bore_mm'])} × {_fmt(h['outside_diameter_mm'])} × {_fmt(h['width_mm'])}",
         _fmt(h["contact_angle_deg"]), _fmt(h["dynamic_load_rating_kN"]), _fmt(h["static_load_rating_kN"])]
        for h in hits], caption="catalog show NAME for every field and its source")


_SEARCH = ("bore", "outside_diameter", "width", "type", "series")  # the fields of catalog-search it takes
catalog_app.command("show")(command("catalog", catalog_show))
catalog_app.command("search")(command("catalog-search", catalog_search))

#: The ``catalog`` command group, as the application adds it.
COMMANDS = {"catalog": catalog_app}

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
    Clearance,
    JsonFlag,
    add_notes,
    check_input,
    emit_json,
    print_warnings,
    table,
)

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


@catalog_app.command("list")
def catalog_list(catalog: CatalogFile = None, json_out: JsonFlag = False):
    """List the bearings known."""
    from .. import catalog as _catalog
    from .. import tables
    from ..catalog import _series
    if catalog is not None:
        check_input(catalog, "catalog")
    known = _catalog.aliases(catalog=catalog)
    listing = _series.listing()
    user = set(_catalog._user_entries(catalog))
    rows = []
    for name in _catalog.names(catalog=catalog):
        if name in listing and name not in user and not _catalog._is_builtin_entry(name):
            r = _series.records()[name]
            z, dw, dm, est = listing[name]
            rows.append({"name": name, "type": r["type"], "balls": z, "ball_diameter_mm": dw, "pitch_diameter_mm": dm,
                         "contact_angle_deg": r["contact_angle_deg"], "bore_mm": r["bore_mm"],
                         "outside_diameter_mm": r["outside_diameter_mm"], "aliases": [], "estimated": est})
        else:
            rows.append(dict(tables.catalog_entry(name, _catalog.get(name, catalog=catalog)),
                             aliases=known.get(name, []), estimated=False))
    if json_out:
        emit_json(rows)
        return
    # the aliases beside the name, in brackets: eight columns fit 80 (--json lists them apart)
    table("Bearings", ["name (aliases)", "type", "Z", "D [mm]", "d_m [mm]", "α0 [deg]", "bore × OD [mm]"], [
        [" ".join([r["name"], *(f"({', '.join(r['aliases'])})" for _ in r["aliases"][:1])]), r["type"],
         f"{r['balls']}*" if r["estimated"] else (r["balls"] or ""),
         _fmt(r["ball_diameter_mm"]) + ("*" if r["estimated"] else ""), _fmt(r["pitch_diameter_mm"]),
         _fmt(r["contact_angle_deg"]), f"{_fmt(r['bore_mm'])} × {_fmt(r['outside_diameter_mm'])}"] for r in rows],
          caption="* estimated ball set; catalog show NAME (or a designation) for every field and the ratings")


_ClearanceChoice = Annotated[str | None, typer.Option(
    "--clearance", help="Value of the ISO 5753-1 clearance range the models use: mean (default), min or max.")]


@catalog_app.command("show")
def catalog_show(name: Annotated[str, typer.Argument(help="Bearing name, alias or designation (6208-2RS1/C3).")],
                 catalog: CatalogFile = None, clearance: _ClearanceChoice = None,
                 radial_clearance: Clearance = None, json_out: JsonFlag = False):
    """Show one bearing: geometry, ratings C, C0, Cu (catalog or computed), limits and where each comes from."""
    from .. import catalog as _catalog
    from ..calculations.documents import catalog_document
    if catalog is not None:
        check_input(catalog, "catalog")
    info, b = catalog_document(name, catalog=catalog, clearance=clearance, radial_clearance=radial_clearance)
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


_SearchLength = Annotated[str | None, typer.Option(help="e.g. '40 mm' (a number alone is in mm).")]


@catalog_app.command("search")
def catalog_search(bore: _SearchLength = None, outside_diameter: _SearchLength = None,
                   width: _SearchLength = None,
                   type: Annotated[str | None, typer.Option("--type", help="deep-groove | angular.")] = None,
                   series: Annotated[str | None, typer.Option(help="Series, e.g. 62, 618, 72, 72B, 79C.")] = None,
                   json_out: JsonFlag = False):
    """Find standard-series bearings by boundary dimensions, type and series."""
    from .. import catalog as _catalog
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


#: The ``catalog`` command group, as the application adds it.
COMMANDS = {"catalog": catalog_app}

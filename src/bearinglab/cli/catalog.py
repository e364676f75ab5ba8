"""Command line of the catalogs: ``catalog list``, ``catalog show NAME`` and ``catalog search``.

Commands
--------
COMMANDS   the ``catalog`` command group, by name (the application adds it)
"""

import re
import warnings
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
_LENGTH = re.compile(r"^\s*([0-9]*\.?[0-9]+(?:[eE][-+]?\d+)?)\s*(mm|m|um|µm|in)?\s*$")
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
    from .. import tables
    if catalog is not None:
        check_input(catalog, "catalog")
    if clearance is not None and radial_clearance is not None:
        raise InputError("clearance: give --clearance or --radial-clearance, not both")
    if clearance is not None and clearance not in ("mean", "min", "max"):
        raise InputError(f"clearance must be one of ['mean', 'min', 'max'], got {clearance!r}")
    b = _catalog.get(name, catalog=catalog, clearance=clearance or "mean")
    if radial_clearance is not None:
        from ._common import parse_length
        value = parse_length(radial_clearance, "radial-clearance", "um")
        est = tuple(f for f in b.estimated_fields if f not in ("radial_clearance",))
        b = b.replace(radial_clearance=value, estimated_fields=est,
                      sources={**b.sources, "radial_clearance": "given (--radial-clearance)"})
    add_notes(_catalog.provenance_notes(b))
    info = tables.bearing_summary(b)
    extra = _catalog.details(name) if not _catalog._is_builtin_entry(name) else None
    if extra:
        info.update({k: v for k, v in extra.items() if k != "row"})
    for key in ("seal", "seals", "tolerance_class"):
        info[key] = getattr(b, key)
    info["iso5753_clearance"] = _clearance_range(b, clearance, radial_clearance)
    given = {k: getattr(b, k) for k in ("dynamic_load_rating", "static_load_rating", "fatigue_load_limit")}
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        if None not in given.values():  # the catalog's three ratings, as ratings.bearing_ratings gives them,
            # without its f0 (not shown), whose Hertz contact imports scipy: show answers within 0.5 s
            info.update({f"{k}_N": float(v) for k, v in given.items()})
            info["rating_source"] = dict.fromkeys(given, "catalog")
        else:
            _computed_ratings(b, given, info, caught)
    if b.estimated_fields:  # a rating computed from the geometry is computed from an estimate
        info["rating_source"] = {k: (f"{v}, from the estimated geometry" if v != "catalog" else v)
                                 for k, v in (info.get("rating_source") or {}).items()}
    notes = list(dict.fromkeys(str(c.message) for c in caught))
    info.update(sources=dict(b.sources), estimated_fields=list(b.estimated_fields),
                inputs={"name": name, "catalog": None if catalog is None else str(catalog),
                        "clearance": clearance, "radial_clearance": radial_clearance}, warnings=notes)
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
    print_warnings(notes)


def _computed_ratings(b, given, info, caught):
    """The ratings the catalog lacks, by ISO 281 / ISO 76 from the ball set (ratings.bearing_ratings: one
    set of ratings per bearing, whichever command asks)."""
    from .. import ratings, tables
    try:
        info.update(tables.ratings(ratings.bearing_ratings(b)))
    except InputError as exc:  # neither catalog ratings nor the ball set to compute them
        info.update({f"{k}_N": v for k, v in given.items()})
        info["rating_source"] = {k: "catalog" for k, v in given.items() if v is not None}
        caught.append(warnings.WarningMessage(f"ratings: not computed ({exc})", UserWarning, "", 0))


def _clearance_range(b, choice, given):
    """The ISO 5753-1 range of a deep-groove bearing and the value the models use, for `catalog show`."""
    from .. import internal_clearance
    if b.type != "radial" or b.bore is None or b.clearance_class is None and "radial_clearance" not in b.sources:
        return None
    cls = b.clearance_class or "CN"
    try:
        r = internal_clearance.radial_clearance_range(b.bore, cls)
    except InputError:
        return None
    used = "given (--radial-clearance)" if given else (choice or "mean")
    return {"class": cls, "minimum_um": r.minimum * 1e6, "maximum_um": r.maximum * 1e6, "used": used}


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

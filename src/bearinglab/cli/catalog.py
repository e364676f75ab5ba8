"""Command line of the catalogs: ``catalog list`` and ``catalog show NAME``.

Commands
--------
COMMANDS   the ``catalog`` command group, by name (the application adds it)
"""

import warnings
from typing import Annotated

import typer

from ..errors import InputError
from ._common import CatalogFile, JsonFlag, check_input, emit_json, print_warnings, table

__all__ = ["COMMANDS"]

catalog_app = typer.Typer(help="Bearings in the built-in and user catalogs.", no_args_is_help=True)


def _fmt(x, spec="g"):
    return "" if x is None else format(x, spec)


@catalog_app.command("list")
def catalog_list(catalog: CatalogFile = None, json_out: JsonFlag = False):
    """List the bearings known."""
    from .. import catalog as _catalog
    from .. import tables
    if catalog is not None:
        check_input(catalog, "catalog")
    known = _catalog.aliases(catalog=catalog)
    rows = [dict(tables.catalog_entry(name, _catalog.get(name, catalog=catalog)), aliases=known.get(name, []))
            for name in _catalog.names(catalog=catalog)]
    if json_out:
        emit_json(rows)
        return
    # the aliases beside the name, in brackets: eight columns fit 80 (--json lists them apart)
    table("Bearings", ["name (aliases)", "type", "Z", "D [mm]", "d_m [mm]", "α0 [deg]", "bore × OD [mm]"], [
        [" ".join([r["name"], *(f"({', '.join(r['aliases'])})" for _ in r["aliases"][:1])]), r["type"],
         r["balls"] or "", _fmt(r["ball_diameter_mm"]),
         _fmt(r["pitch_diameter_mm"]), _fmt(r["contact_angle_deg"]),
         f"{_fmt(r['bore_mm'])} × {_fmt(r['outside_diameter_mm'])}"] for r in rows],
          caption="catalog show NAME (or an alias) for every field and the ratings")


@catalog_app.command("show")
def catalog_show(name: Annotated[str, typer.Argument(help="Bearing name or alias.")],
                 catalog: CatalogFile = None, json_out: JsonFlag = False):
    """Show one bearing with its derived geometry and its ratings C, C0, Cu (catalog or computed)."""
    from .. import catalog as _catalog
    from .. import ratings, tables
    if catalog is not None:
        check_input(catalog, "catalog")
    b = _catalog.get(name, catalog=catalog)
    info = tables.bearing_summary(b)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:  # one set of ratings per bearing, whichever command asks (ratings.bearing_ratings)
            info.update(tables.ratings(ratings.bearing_ratings(b)))
        except InputError as exc:  # neither catalog ratings nor the ball set to compute them
            given = {k: getattr(b, k) for k in ("dynamic_load_rating", "static_load_rating", "fatigue_load_limit")}
            info.update({f"{k}_N": v for k, v in given.items()})
            info["rating_source"] = {k: "catalog" for k, v in given.items() if v is not None}
            caught.append(warnings.WarningMessage(f"ratings: not computed ({exc})", UserWarning, "", 0))
    notes = list(dict.fromkeys(str(c.message) for c in caught))
    info.update(inputs={"name": name, "catalog": None if catalog is None else str(catalog)}, warnings=notes)
    if json_out:
        emit_json(info)
        return
    table(f"Bearing {info['designation']}", ["quantity", "value"],
          [[k, _value(k, v, info.get("rating_source") or {})] for k, v in info.items()
           if v is not None and k not in ("rating_source", "inputs", "warnings")])
    print_warnings(notes)


def _value(key, value, sources):
    """A cell of ``catalog show``; a rating carries its source (catalog, ISO 76, ISO 281 ...)."""
    text = _fmt(value, ".6g") if isinstance(value, float) else value
    src = sources.get(key.removesuffix("_N"))
    return text if src is None else f"{text} ({src})"


#: The ``catalog`` command group, as the application adds it.
COMMANDS = {"catalog": catalog_app}

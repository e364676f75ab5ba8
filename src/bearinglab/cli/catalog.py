"""Command line of the catalogs: ``catalog list`` and ``catalog show NAME``.

Commands
--------
COMMANDS   the ``catalog`` command group, by name (the application adds it)
"""

from __future__ import annotations

from typing import Annotated

import typer

from .. import catalog as _catalog
from .. import tables
from ._common import CatalogFile, JsonFlag, emit_json, table

__all__ = ["COMMANDS"]

catalog_app = typer.Typer(help="Bearings in the built-in and user catalogs.", no_args_is_help=True)


def _fmt(x, spec="g"):
    return "" if x is None else format(x, spec)


@catalog_app.command("list")
def catalog_list(catalog: CatalogFile = None, json_out: JsonFlag = False):
    """List the bearings known."""
    rows = [tables.catalog_entry(name, _catalog.get(name, catalog=catalog))
            for name in _catalog.names(catalog=catalog)]
    if json_out:
        emit_json(rows)
        return
    table("Bearings", ["name", "type", "Z", "D [mm]", "d_m [mm]", "α0 [deg]", "bore × OD [mm]"], [
        [r["name"], r["type"], r["balls"] or "", _fmt(r["ball_diameter_mm"]), _fmt(r["pitch_diameter_mm"]),
         _fmt(r["contact_angle_deg"]), f"{_fmt(r['bore_mm'])} × {_fmt(r['outside_diameter_mm'])}"] for r in rows])


@catalog_app.command("show")
def catalog_show(name: Annotated[str, typer.Argument(help="Bearing name or alias.")],
                 catalog: CatalogFile = None, json_out: JsonFlag = False):
    """Show one bearing with its derived geometry."""
    info = tables.bearing_summary(_catalog.get(name, catalog=catalog))
    if json_out:
        emit_json(info)
        return
    table(f"Bearing {info['designation']}", ["quantity", "value"],
          [[k, _fmt(v, ".6g") if isinstance(v, float) else v] for k, v in info.items() if v is not None])


#: The ``catalog`` command group, as the application adds it.
COMMANDS = {"catalog": catalog_app}

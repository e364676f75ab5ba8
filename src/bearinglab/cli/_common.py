"""The ``bearinglab`` command line. It calls public functions only; every number it prints can be had
from Python.

Commands
--------
catalog list | show NAME       the bearings known (built-in and user catalogs)
axial-angle                    operating contact angle under axial load (spec 000)
stand-load                     minimum axial load on a test stand (spec 000 section 3)
frequencies                    characteristic frequencies and the spectral mask
high-speed                     high-speed quasi-static model under thrust (spec 004)
friction torque | lab | template   friction torque models and the friction-rig lab (spec 001)
runout | runout monte-carlo    manufacturing errors -> inner-ring displacement and runout (spec 003)

Errors in the input print one line on stderr and exit with code 2; a solver that does not converge
prints one line and exits with code 3. No traceback reaches the user.

The commands of each capability live in a private module ``_cli_<topic>.py`` that registers them on
:data:`app` (one file per capability keeps the command line readable; STYLE.md names ``cli.py`` as the
entry point, which this module remains).
"""

from __future__ import annotations

import contextlib
import importlib
import json
import math
import sys
from pathlib import Path
from typing import Annotated

import click
import numpy as np
import typer
from rich.console import Console
from rich.markup import escape
from rich.table import Table

from . import catalog as _catalog
from .bearing import MATERIALS, BallBearing
from .errors import ConvergenceError, InputError
from .units import parse_quantity

try:  # typer >= 0.20 vendors click as typer._click and raises its own exception classes, not click's
    from typer._click import exceptions as _typer_click_exceptions
except ImportError:  # older typer uses click itself
    _typer_click_exceptions = click.exceptions
_USAGE_ERRORS = (click.exceptions.UsageError, _typer_click_exceptions.UsageError)
_EXITS = (click.exceptions.Exit, typer.Exit)
_ABORTS = (click.exceptions.Abort, typer.Abort)

__all__ = ["app", "main", "run"]

app = typer.Typer(
    name="bearinglab",
    help="Ball-bearing mechanics: test-stand contact angles, Hertz contact, friction torque, runout, high-speed model.",
    no_args_is_help=True,
    pretty_exceptions_enable=False,
    add_completion=False,
    context_settings={"help_option_names": ["-h", "--help"]},
)
console = Console()

# ----------------------------------------------------------------------------- shared options
# Bearing given by name, by file, or inline. Commands that need a bearing take these parameters and
# call resolve_bearing(...) with them.
BearingName = Annotated[str | None, typer.Option("--bearing", "-b", help="Catalog name, e.g. B218, 4-1006095, 6205-2RS.", rich_help_panel="Bearing")]
BearingFile = Annotated[Path | None, typer.Option("--bearing-file", help="TOML file with one bearing table.", rich_help_panel="Bearing")]
CatalogFile = Annotated[Path | None, typer.Option("--catalog", help="User catalog TOML (also $BEARINGLAB_CATALOG).", rich_help_panel="Bearing")]
Balls = Annotated[int | None, typer.Option("--balls", help="Number of balls.", rich_help_panel="Inline geometry")]
BallDiameter = Annotated[str | None, typer.Option("--ball-diameter", help="e.g. '2 mm'.", rich_help_panel="Inline geometry")]
PitchDiameter = Annotated[str | None, typer.Option("--pitch-diameter", help="e.g. '8.7355 mm'.", rich_help_panel="Inline geometry")]
InnerRadius = Annotated[str | None, typer.Option("--inner-groove-radius", help="e.g. '1.05 mm'.", rich_help_panel="Inline geometry")]
OuterRadius = Annotated[str | None, typer.Option("--outer-groove-radius", help="e.g. '1.16 mm'.", rich_help_panel="Inline geometry")]
InnerConformity = Annotated[float | None, typer.Option("--inner-conformity", help="f_i = r_i / D.", rich_help_panel="Inline geometry")]
OuterConformity = Annotated[float | None, typer.Option("--outer-conformity", help="f_o = r_o / D.", rich_help_panel="Inline geometry")]
ContactAngle = Annotated[str | None, typer.Option("--contact-angle", help="Nominal (free) angle, e.g. '12 deg'.", rich_help_panel="Inline geometry")]
Clearance = Annotated[str | None, typer.Option("--radial-clearance", help="Diametral clearance, e.g. '9 um'.", rich_help_panel="Inline geometry")]
BallMaterial = Annotated[str | None, typer.Option("--ball-material", help="steel | silicon_nitride.", rich_help_panel="Inline geometry")]
JsonFlag = Annotated[bool, typer.Option("--json", help="Print one JSON document on stdout.")]
# Batch execution (bearinglab.parallel): every batch command takes these three.
ExecutorOpt = Annotated[str | None, typer.Option("--executor", help="serial | local | tcp://host:8786 (a running dask scheduler).", rich_help_panel="Execution")]
WorkersOpt = Annotated[int | None, typer.Option("--workers", help="Workers of the local dask cluster.", rich_help_panel="Execution")]
ChunkSizeOpt = Annotated[int | None, typer.Option("--chunk-size", help="Cases per chunk (task).", rich_help_panel="Execution")]


def resolve_bearing(bearing=None, bearing_file=None, catalog=None, balls=None, ball_diameter=None,
                    pitch_diameter=None, inner_groove_radius=None, outer_groove_radius=None,
                    inner_conformity=None, outer_conformity=None, contact_angle=None,
                    radial_clearance=None, ball_material=None) -> BallBearing:
    """The bearing named, read from a file, or given inline; inline options override named fields."""
    if bearing and bearing_file:
        raise InputError("bearing: give --bearing or --bearing-file, not both")
    if bearing:
        base = _catalog.get(bearing, catalog=catalog)
    elif bearing_file:
        base = _catalog.load_bearing_file(bearing_file)
    else:
        base = BallBearing(designation="inline")
    changes = {}
    if balls is not None:
        changes["n_balls"] = balls
    for key, text in (("ball_diameter", ball_diameter), ("pitch_diameter", pitch_diameter)):
        if text is not None:
            changes[key] = parse_quantity(text, "length", key.replace("_", "-"))
    d = changes.get("ball_diameter", base.ball_diameter)
    for race, radius, conf in (("inner", inner_groove_radius, inner_conformity), ("outer", outer_groove_radius, outer_conformity)):
        if radius is not None and conf is not None:
            raise InputError(f"{race}-groove-radius: give the radius or the conformity, not both")
        if radius is not None:
            if d is None:
                raise InputError(f"{race}-groove-radius: needs --ball-diameter")
            changes[f"{race}_conformity"] = parse_quantity(radius, "length", f"{race}-groove-radius") / d
        elif conf is not None:
            changes[f"{race}_conformity"] = conf
    if contact_angle is not None and radial_clearance is not None:
        raise InputError("contact-angle: give --contact-angle or --radial-clearance, not both")
    if contact_angle is not None:
        changes["contact_angle"] = parse_quantity(contact_angle, "angle", "contact-angle")
        changes["radial_clearance"] = None
    elif radial_clearance is not None:
        changes["radial_clearance"] = parse_quantity(radial_clearance, "length", "radial-clearance")
        changes["contact_angle"] = None
    elif "inner_conformity" in changes or "outer_conformity" in changes:
        # new conformities keep the angle and re-derive the clearance
        changes["radial_clearance"] = None
    if ball_material is not None:
        key = ball_material.lower().replace("-", "_")
        if key not in MATERIALS:
            raise InputError(f"ball-material must be one of {sorted(MATERIALS)}, got {ball_material!r}")
        changes["ball_material"] = MATERIALS[key]
    if not changes:
        if not (bearing or bearing_file):
            raise InputError("bearing: give --bearing NAME, --bearing-file FILE or the inline geometry (--balls, --ball-diameter, ...)")
        return base
    import dataclasses

    return dataclasses.replace(base, **changes)


def _stderr_console():
    """Progress goes to stderr, so that stdout stays one JSON document or one table."""
    return Console(stderr=True)


@contextlib.contextmanager
def progress_bar(description, executor="serial"):
    """The ``progress`` argument of :mod:`bearinglab.parallel` for a command: a rich bar (serial) or dask's
    progress bar (distributed) on an interactive terminal, nothing otherwise (pipes, tests, CI)."""
    err = _stderr_console()
    if not err.is_terminal:
        yield None
        return
    if executor not in (None, "serial"):
        yield "dask"
        return
    from rich.progress import BarColumn, MofNCompleteColumn, Progress, TimeRemainingColumn

    with Progress("[progress.description]{task.description}", BarColumn(), MofNCompleteColumn(),
                  TimeRemainingColumn(), console=err, transient=True) as bar:
        task = bar.add_task(description, total=None)
        yield lambda done, total: bar.update(task, completed=done, total=total)


def quantity(text, kind, name, *, default_unit=None):
    """Parse an option value with units (thin wrapper kept for the command modules)."""
    return parse_quantity(text, kind, name, default_unit=default_unit)


def _jsonable(obj):
    if isinstance(obj, dict):
        return {str(k): _jsonable(v) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [_jsonable(v) for v in obj]
    if isinstance(obj, np.ndarray):
        return _jsonable(obj.tolist())
    if isinstance(obj, (np.bool_, bool)):
        return bool(obj)
    if isinstance(obj, (np.integer,)):
        return int(obj)
    if isinstance(obj, (np.floating, float)):
        v = float(obj)
        return v if math.isfinite(v) else None
    return obj


def emit_json(obj):
    """Print one JSON document on stdout (NaN and inf become null)."""
    sys.stdout.write(json.dumps(_jsonable(obj), indent=2, ensure_ascii=False) + "\n")


def table(title, columns, rows, *, caption=None):
    """Print a rich table; ``columns`` are header strings, ``rows`` lists of already formatted cells."""
    t = Table(title=escape(title), caption=caption and escape(caption), header_style="bold")
    for i, col in enumerate(columns):
        t.add_column(escape(col), justify="left" if i == 0 else "right")
    for row in rows:
        t.add_row(*[escape(str(c)) for c in row])
    console.print(t)


# ----------------------------------------------------------------------------- catalog commands
catalog_app = typer.Typer(help="Bearings in the built-in and user catalogs.", no_args_is_help=True)
app.add_typer(catalog_app, name="catalog")


def _mm(x):
    return "" if x is None else f"{x * 1e3:g}"


@catalog_app.command("list")
def catalog_list(catalog: CatalogFile = None, json_out: JsonFlag = False):
    """List the bearings known."""
    rows = []
    for name in _catalog.names(catalog=catalog):
        b = _catalog.get(name, catalog=catalog)
        rows.append({
            "name": name, "type": b.type, "balls": b.n_balls,
            "ball_diameter_mm": None if b.ball_diameter is None else b.ball_diameter * 1e3,
            "pitch_diameter_mm": None if b.pitch_diameter is None else b.pitch_diameter * 1e3,
            "contact_angle_deg": None if b.contact_angle is None else math.degrees(b.contact_angle),
            "bore_mm": None if b.bore is None else b.bore * 1e3,
            "outside_diameter_mm": None if b.outside_diameter is None else b.outside_diameter * 1e3,
        })
    if json_out:
        emit_json(rows)
        return
    table("Bearings", ["name", "type", "Z", "D [mm]", "d_m [mm]", "α0 [deg]", "bore × OD [mm]"], [
        [r["name"], r["type"], r["balls"] or "", _fmt(r["ball_diameter_mm"]), _fmt(r["pitch_diameter_mm"]),
         _fmt(r["contact_angle_deg"]), f"{_fmt(r['bore_mm'])} × {_fmt(r['outside_diameter_mm'])}"] for r in rows])


def _fmt(x, spec="g"):
    return "" if x is None else format(x, spec)


def bearing_summary(b: BallBearing):
    """Every known field of a bearing and its derived quantities, in engineering units."""
    out = {"designation": b.designation, "type": b.type, "balls": b.n_balls,
           "ball_diameter_mm": b.ball_diameter and b.ball_diameter * 1e3,
           "pitch_diameter_mm": b.pitch_diameter and b.pitch_diameter * 1e3,
           "inner_conformity": b.inner_conformity, "outer_conformity": b.outer_conformity,
           "contact_angle_deg": None if b.contact_angle is None else math.degrees(b.contact_angle),
           "radial_clearance_um": b.radial_clearance and b.radial_clearance * 1e6,
           "bore_mm": b.bore and b.bore * 1e3, "outside_diameter_mm": b.outside_diameter and b.outside_diameter * 1e3,
           "width_mm": b.width and b.width * 1e3, "static_load_rating_N": b.static_load_rating,
           "ball_material": b.ball_material.name, "ring_material": b.ring_material.name, "source": b.source}
    if b.inner_conformity is not None and b.outer_conformity is not None and b.ball_diameter is not None:
        out["inner_groove_radius_mm"] = b.inner_groove_radius * 1e3
        out["outer_groove_radius_mm"] = b.outer_groove_radius * 1e3
        out["total_curvature_B"] = b.total_curvature
        out["groove_distance_A_mm"] = b.groove_distance * 1e3
        if b.contact_angle is not None and b.pitch_diameter is not None:
            out["gamma"] = b.gamma
            if b.contact_angle > 0:
                out["axial_play_mm"] = b.axial_play() * 1e3
    if b.hertz_table:
        out["hertz_table"] = dict(b.hertz_table)
    return out


@catalog_app.command("show")
def catalog_show(name: Annotated[str, typer.Argument(help="Bearing name or alias.")],
                 catalog: CatalogFile = None, json_out: JsonFlag = False):
    """Show one bearing with its derived geometry."""
    info = bearing_summary(_catalog.get(name, catalog=catalog))
    if json_out:
        emit_json(info)
        return
    table(f"Bearing {info['designation']}", ["quantity", "value"],
          [[k, _fmt(v, ".6g") if isinstance(v, float) else v] for k, v in info.items() if v is not None])


# ----------------------------------------------------------------------------- capability modules
# Each module defines register(app). Listed here so that the command line is complete on import.
_COMMAND_MODULES: tuple[str, ...] = ("_cli_stand", "_cli_frequencies", "_cli_sweep", "_cli_highspeed", "_cli_friction", "_cli_runout")


_registered = False


def _register_all():
    """Add the capability commands to :data:`app` once. Called by :func:`main`, not at import: the
    command modules import this module for the shared options, so importing them here would be circular."""
    global _registered
    if not _registered:
        for name in _COMMAND_MODULES:
            importlib.import_module(f"{__package__}.{name}").register(app)
        _registered = True


def main(argv=None) -> int:
    """Run the command line; return the exit code instead of raising (tests call this).

    Parameters
    ----------
    argv : list of str, optional
        The arguments after the program name; ``None`` reads ``sys.argv``.

    Returns
    -------
    int
        0 on success, 2 for invalid input (one line on stderr), 3 for a solve that did not converge.
    """
    _register_all()
    try:
        rv = app(args=argv, prog_name="bearinglab", standalone_mode=False)
    except _USAGE_ERRORS as exc:
        if exc.format_message():  # empty after no_args_is_help has printed the help
            print(f"bearinglab: error: {exc.format_message()}", file=sys.stderr)
        return 2
    except _EXITS as exc:
        return exc.exit_code
    except _ABORTS:
        print("bearinglab: aborted", file=sys.stderr)
        return 1
    except ConvergenceError as exc:
        print(f"bearinglab: error: {exc}", file=sys.stderr)
        return 3
    except InputError as exc:
        print(f"bearinglab: error: {exc}", file=sys.stderr)
        return 2
    except OSError as exc:
        print(f"bearinglab: error: {exc.filename or ''}: {exc.strerror}", file=sys.stderr)
        return 2
    return rv if isinstance(rv, int) else 0


def run():
    """Console-script entry point."""
    sys.exit(main())


if __name__ == "__main__":
    run()

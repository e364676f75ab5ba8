"""Command line of the high-speed model under thrust (spec 004): ``high-speed``.

One case prints a table of every output (or one JSON object with ``--json``); lists or ranges of loads
and speeds make a grid that is solved in one batched call and printed as a table (or one JSON array),
written with ``--csv`` and drawn with ``--plot`` (the paper's figures 2-4 and delta_a against thrust).
The columns are :func:`bearinglab.tables.high_speed`; the figure is
:func:`bearinglab.plots.high_speed.plot_map`.

Commands
--------
COMMANDS   the ``high-speed`` command, by name (the application adds it)
"""

import dataclasses
import sys
import warnings
from pathlib import Path
from typing import Annotated

import typer

from ..errors import ConvergenceError, InputError, ValidityWarning
from . import _mounting as mo
from ._common import (
    FIGURE_SUFFIXES,
    BallDiameter,
    BallMaterial,
    Balls,
    BearingFile,
    BearingName,
    CatalogFile,
    ChunkSizeOpt,
    Clearance,
    ContactAngle,
    ExecutorOpt,
    InnerConformity,
    InnerRadius,
    JsonFlag,
    OuterConformity,
    OuterRadius,
    PitchDiameter,
    WorkersOpt,
    check_output,
    choice,
    console,
    emit_csv,
    emit_json,
    execution,
    inputs_echo,
    parse_speeds,
    print_warnings,
    resolve_bearing,
    table,
)

__all__ = ["COMMANDS"]

_PROGRESS_MIN_CASES = 5000  # serial sweeps at least this large are cut finer, so the bar moves
# A command runs in a fresh process, where loading the compiled kernel costs about 0.8 s (numba's import
# and its cache) against 2e-5 s a case saved: the numpy path (the same answers to 1e-12) is quicker below
# about 50 000 cases. The choice depends on the whole request only, never on the chunk size.
_COMPILED_MIN_CASES = 50_000
_CHUNK = 2500  # cases per batched call then


@mo.mounting_options
def high_speed(
    axial_load: Annotated[str, typer.Option("--axial-load", "-A", "-F", help="Thrust (-F is the same option): '20 kN', or a list/range '2.5kN:45kN:2.5kN'.")],
    speed: Annotated[str, typer.Option("--speed", "-n", help="Inner-ring speed: '10000 rpm', or a list/range '0,3000,6000rpm'.")],
    bearing: BearingName = None, bearing_file: BearingFile = None, catalog: CatalogFile = None,
    balls: Balls = None, ball_diameter: BallDiameter = None, pitch_diameter: PitchDiameter = None,
    inner_groove_radius: InnerRadius = None, outer_groove_radius: OuterRadius = None,
    inner_conformity: InnerConformity = None, outer_conformity: OuterConformity = None,
    contact_angle: ContactAngle = None, radial_clearance: Clearance = None, ball_material: BallMaterial = None,
    solver: Annotated[str, typer.Option("--solver", help="newton (batched Newton-Raphson) | angle-iteration (the paper's search).")] = "newton",
    raceway_control: Annotated[str, typer.Option("--raceway-control", help="outer (default, the paper's) | inner.")] = "outer",
    constants: Annotated[str, typer.Option("--constants", help="mass (F_c, M_g from the ball mass; default) | harris (2.26e-11, 4.47e-12: Harris's printed constants) | paper (2.26e-11, 4.5e-12).")] = "mass",
    gyroscopic_sign: Annotated[str, typer.Option("--gyroscopic-sign", help="physical (default) | reversed (for comparison only).")] = "physical",
    reduced_modulus: Annotated[str | None, typer.Option("--reduced-modulus", help="E' of the contact pair, e.g. '228.04 GPa' (default: from the materials).")] = None,
    csv_file: Annotated[Path | None, typer.Option("--csv", help="Write the table of all cases to this CSV file.")] = None,
    plot: Annotated[Path | None, typer.Option("--plot", help="Draw the map (figures 2-4 and δ_a) into this PNG/PDF/SVG file.")] = None,
    executor: ExecutorOpt = None, workers: WorkersOpt = None, chunk_size: ChunkSizeOpt = None,
    json_out: JsonFlag = False,
):
    """High-speed angular-contact bearing under thrust (the high-speed quasi-static model): α_i, α_e, δ_a, loads, F_c, M_g, speeds."""
    from .. import limits, plots, tables
    from ..plots import high_speed as high_speed_plots
    from ..units import RPM
    b = resolve_bearing(bearing, bearing_file, catalog, balls, ball_diameter, pitch_diameter, inner_groove_radius,
                        outer_groove_radius, inner_conformity, outer_conformity, contact_angle, radial_clearance,
                        ball_material)
    options = _model_options(solver, raceway_control, constants, gyroscopic_sign, reduced_modulus)
    loads, speeds = _grid(axial_load, speed)
    limits.check_speed(speeds, b.require("pitch_diameter"))
    b, mounted = mo.operating_bearing(b, speeds.max())  # issue 23: the operating clearance (highest speed)
    if plot is not None and (loads.size < 2 or speeds.size < 1):
        raise InputError("plot: needs a sweep over at least two thrusts (e.g. --axial-load 2.5kN:45kN:2.5kN)")
    if csv_file is not None:
        check_output(csv_file, "csv", (".csv",), inputs=(bearing_file, catalog))
    if plot is not None:
        check_output(plot, "plot", FIGURE_SUFFIXES, inputs=(bearing_file, catalog))
    single = loads.size == 1 and speeds.size == 1
    with execution("solving", executor, workers, chunk_size, progress=not single) as ex:
        state, notes = _solve(b, loads, speeds, options, ex)
    notes += limits.high_speed_warnings(b, state)
    cols = tables.high_speed(state)
    if csv_file is not None:
        emit_csv(csv_file, cols)
    if plot is not None:
        fig = high_speed_plots.plot_map(state, title=f"Bearing {b.designation}: high-speed contact angles under thrust",
                                        sign_change=_sign_change(b, speeds, options, notes))
        plots.save(fig, plot)
    rows = tables.rows(cols)
    if json_out:
        for note in notes:  # stdout stays one JSON document
            print(f"bearinglab: warning: {note}", file=sys.stderr)
        echo = inputs_echo(b, constants=constants, raceway_control=raceway_control, gyroscopic_sign=gyroscopic_sign,
                           solver=solver, reduced_modulus_GPa=None if reduced_modulus is None else
                           options["reduced_modulus"] / 1e9)
        if single:  # the inputs as given, without the noise of the unit conversions
            echo.update(inputs_echo(b, axial_load_N=float(loads[0]), speed_rpm=float(speeds[0]) / RPM))
            emit_json(dict(rows[0], **echo, **mounted, warnings=notes))
        else:
            emit_json(dict(echo, **inputs_echo(b, axial_load_N=loads.tolist(), speed_rpm=(speeds / RPM).tolist()),
                           **mounted, cases=rows,
                           warnings=notes))
        return
    if single:
        _print_single(b, rows[0], options)
    else:
        _print_sweep(b, rows, options)
    print_warnings(notes)
    for path in (csv_file, plot):
        if path is not None:
            console.print(f"wrote {path}", highlight=False)


def _model_options(solver, raceway_control, constants, gyroscopic_sign, reduced_modulus):
    """The options of :func:`bearinglab.quasistatic.high_speed_analysis`, checked."""
    from .. import quasistatic
    from ..units import parse_quantity
    choice("solver", solver, ("newton", "angle-iteration"))
    choice("raceway-control", raceway_control, tuple(quasistatic.RACEWAY_CONTROLS))
    choice("constants", constants, tuple(quasistatic.CONSTANTS))
    sign = {"physical": 1, "reversed": -1}.get(choice("gyroscopic-sign", gyroscopic_sign, ("physical", "reversed")))
    ep = None
    if reduced_modulus is not None:
        ep = parse_quantity(reduced_modulus, "pressure", "reduced-modulus")
        if not ep > 0:
            raise InputError(f"reduced-modulus must be > 0 [GPa], got {ep / 1e9:g} GPa")
    return {"method": solver, "raceway_control": raceway_control, "constants": constants, "gyroscopic_sign": sign,
            "reduced_modulus": ep}


def _grid(axial_load, speed):
    """The thrusts and speeds given (SI), checked."""
    import numpy as np

    from .._bounds import MAX_CASES, check_cases
    from ..units import parse_values
    loads = parse_values(axial_load, "force", "axial-load", limit=MAX_CASES)
    if np.any(~(loads > 0)):
        raise InputError(f"axial-load must be > 0 [N], got {float(loads[~(loads > 0)][0]):g} N")
    speeds = parse_speeds(speed)
    check_cases(loads.size * speeds.size, f"{loads.size} thrusts x {speeds.size} speeds")  # before the map
    return loads, speeds


def _solve(bearing, loads, speeds, options, ex):
    """One case (:func:`quasistatic.high_speed_analysis`) or the grid (:func:`quasistatic.sweep`) in chunks on
    the chosen executor; returns the state and the validity warnings raised on the way."""
    from .. import quasistatic
    if loads.size * speeds.size < _COMPILED_MIN_CASES:
        options = {**options, "engine": "numpy"}
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", ValidityWarning)
        if loads.size == 1 and speeds.size == 1:
            state = quasistatic.high_speed_analysis(bearing, loads[0], speeds[0], **options)
        else:
            if ex.chunk_size is None and ex.executor == "serial" and loads.size * speeds.size >= _PROGRESS_MIN_CASES:
                ex = dataclasses.replace(ex, chunk_size=_CHUNK)  # small enough chunks for the bar to move
            state = quasistatic.sweep(bearing, loads, speeds, execution=ex, **options)
    return state, [str(c.message) for c in caught if issubclass(c.category, ValidityWarning)]


def _sign_change(bearing, speeds, options, notes):
    """The thrust at which delta_a changes sign per speed, from the library's solve (not the grid); None
    (the figure then interpolates on the grid) with a note if it does not converge."""
    from .. import quasistatic
    try:
        return quasistatic.sign_change_thrust(
            bearing, speeds, reduced_modulus=options["reduced_modulus"], constants=options["constants"],
            raceway_control=options["raceway_control"], gyroscopic_sign=options["gyroscopic_sign"])
    except (ConvergenceError, InputError) as exc:
        notes.append(f"plot: the delta_a sign change is interpolated on the grid ({exc})")
        return None


def _f(x, spec):
    return "—" if x is None else format(x, spec)


def _print_single(b, r, options):
    caption = (f"{options['raceway_control']}-raceway control, constants {options['constants']}, "
               f"{'physical' if options['gyroscopic_sign'] > 0 else 'reversed'} gyroscopic sign, "
               f"solver {options['method']} ({r['method']}, {r['iterations']} iterations, residual {_f(r['residual'], '.2e')})")
    fa = r["axial_load_N"]  # in kN from 1 kN up, else in N: "F_a = 19.6133 N", not "0.0196133 kN"
    fa_text = f"{fa / 1e3:g} kN" if fa >= 1e3 else f"{fa:g} N"
    table(f"Bearing {b.designation}: F_a = {fa_text} at {r['speed_rpm']:g} rpm", ["quantity", "inner", "outer"], [
        ["contact angle [deg]", _f(r["contact_angle_inner_deg"], ".4f"), _f(r["contact_angle_outer_deg"], ".4f")],
        ["static contact angle α_s [deg]", _f(r["static_contact_angle_deg"], ".4f"), ""],
        ["ball load Q [N]", _f(r["ball_load_inner_N"], ".1f"), _f(r["ball_load_outer_N"], ".1f")],
        ["deflection δ [µm]", _f(r["deflection_inner_um"], ".3f"), _f(r["deflection_outer_um"], ".3f")],
        ["max contact pressure [MPa]", _f(r["max_pressure_inner_MPa"], ".0f"), _f(r["max_pressure_outer_MPa"], ".0f")],
        ["ball-pass frequency [Hz]", _f(r["bpfi_hz"], ".2f"), _f(r["bpfo_hz"], ".2f")],
    ], caption=caption)
    table("Ball and ring", ["quantity", "value"], [
        # printed tables give displacements in µm in every command (JSON and CSV keep the _mm column)
        ["axial displacement δ_a [µm]", _f(r["axial_displacement_um"], ".2f")],
        ["axial stiffness dF_a/dδ_a [N/µm]", _f(r["axial_stiffness_N_per_um"], ".2f")],
        ["centrifugal force F_c [N]", _f(r["centrifugal_force_N"], ".1f")],
        ["gyroscopic moment M_g [N·mm]", _f(r["gyroscopic_moment_Nmm"], ".1f")],
        ["attitude angle β [deg]", _f(r["attitude_angle_deg"], ".3f")],
        ["cage speed [rpm]", _f(r["cage_speed_rpm"], ".1f")],
        ["ball spin speed [rpm]", _f(r["ball_spin_speed_rpm"], ".0f")],
        ["friction coefficient 2M_g/(D Q) [-]", _f(r["friction_coefficient"], ".4f")],
        ["converged", str(r["converged"]).lower()],
    ])


def _print_sweep(b, rows, options):
    failed = sum(1 for r in rows if not r["converged"])
    caption = (f"{len(rows)} cases, {failed} failed; {options['raceway_control']}-raceway control, constants "
               f"{options['constants']}, solver {options['method']}; --json or --csv for every output")
    table(f"Bearing {b.designation}: high-speed contact angles under thrust",
          ["F_a kN", "n rpm", "α_i °", "α_e °", "δ_a µm", "Q_i N", "Q_e N", "M_g N·mm", "status"],
          [[f"{r['axial_load_N'] / 1e3:g}", f"{r['speed_rpm']:g}", _f(r["contact_angle_inner_deg"], ".3f"),
            _f(r["contact_angle_outer_deg"], ".3f"),
            _f(r["axial_displacement_um"], ".2f"),
            _f(r["ball_load_inner_N"], ".0f"), _f(r["ball_load_outer_N"], ".0f"),
            _f(r["gyroscopic_moment_Nmm"], ".0f"), r["status"]] for r in rows], caption=caption)


#: The ``high-speed`` command, as the application adds it.
COMMANDS = {"high-speed": high_speed}

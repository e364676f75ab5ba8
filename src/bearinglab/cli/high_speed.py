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

import sys

from ..errors import InputError
from ._common import (
    FIGURE_SUFFIXES,
    BearingFile,
    CatalogFile,
    ChunkSizeOpt,
    ExecutorOpt,
    FileOption,
    JsonFlag,
    WorkersOpt,
    check_output,
    console,
    emit_csv,
    emit_json,
    execution,
    print_warnings,
    table,
)
from ._options import command

__all__ = ["COMMANDS"]


def high_speed(
    given, *, bearing_file: BearingFile = None, catalog: CatalogFile = None,
    csv_file: FileOption("--csv", "Write the table of all cases to this CSV file.") = None,
    plot: FileOption("--plot", "Draw the map (figures 2-4 and δ_a) into this PNG/PDF/SVG file.") = None,
    executor: ExecutorOpt = None, workers: WorkersOpt = None, chunk_size: ChunkSizeOpt = None,
    json_out: JsonFlag = False,
):
    """High-speed angular-contact bearing under thrust (the high-speed quasi-static model): α_i, α_e, δ_a, loads, F_c, M_g, speeds."""
    from .. import plots
    from ..calculations import _reading as _inputs
    from ..calculations import high_speed as calculation

    def check(loads, speeds):  # the output files, before anything is solved
        if plot is not None and (loads.size < 2 or speeds.size < 1):
            raise InputError("plot: needs a sweep over at least two thrusts (e.g. --axial-load 2.5kN:45kN:2.5kN)")
        if csv_file is not None:
            check_output(csv_file, "csv", (".csv",), inputs=(bearing_file, catalog))
        if plot is not None:
            check_output(plot, "plot", FIGURE_SUFFIXES, inputs=(bearing_file, catalog))

    r = calculation.compute(_inputs.request("high-speed", given), bearing_file=bearing_file, catalog=catalog,
                            execution=lambda single: execution("solving", executor, workers, chunk_size,
                                                               progress=not single), check=check)
    out, notes = r.document, list(r.notes)
    if csv_file is not None:
        emit_csv(csv_file, r.columns)
    if plot is not None:
        fig, more = calculation.figure(r)
        plots.save(fig, plot)
        notes += more
        out["warnings"] = [*notes, *[n for n in out.get("warnings", []) if n not in notes]]
    if json_out:
        for note in notes:  # stdout stays one JSON document
            print(f"bearinglab: warning: {note}", file=sys.stderr)
        emit_json(out)
        return
    rows = out.get("cases", [out])
    if "cases" not in out:
        _print_single(out["bearing"], rows[0], r.options)
    else:
        _print_sweep(out["bearing"], rows, r.options)
    print_warnings(out.get("warnings", []))
    for path in (csv_file, plot):
        if path is not None:
            console.print(f"wrote {path}", highlight=False)


def _f(x, spec):
    return "—" if x is None else format(x, spec)


def _print_single(designation, r, options):
    caption = (f"{options['raceway_control']}-raceway control, constants {options['constants']}, "
               f"{'physical' if options['gyroscopic_sign'] > 0 else 'reversed'} gyroscopic sign, "
               f"solver {options['method']} ({r['method']}, {r['iterations']} iterations, residual {_f(r['residual'], '.2e')})")
    fa = r["axial_load_N"]  # in kN from 1 kN up, else in N: "F_a = 19.6133 N", not "0.0196133 kN"
    fa_text = f"{fa / 1e3:g} kN" if fa >= 1e3 else f"{fa:g} N"
    table(f"Bearing {designation}: F_a = {fa_text} at {r['speed_rpm']:g} rpm", ["quantity", "inner", "outer"], [
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


def _print_sweep(designation, rows, options):
    failed = sum(1 for r in rows if not r["converged"])
    caption = (f"{len(rows)} cases, {failed} failed; {options['raceway_control']}-raceway control, constants "
               f"{options['constants']}, solver {options['method']}; --json or --csv for every output")
    table(f"Bearing {designation}: high-speed contact angles under thrust",
          ["F_a kN", "n rpm", "α_i °", "α_e °", "δ_a µm", "Q_i N", "Q_e N", "M_g N·mm", "status"],
          [[f"{r['axial_load_N'] / 1e3:g}", f"{r['speed_rpm']:g}", _f(r["contact_angle_inner_deg"], ".3f"),
            _f(r["contact_angle_outer_deg"], ".3f"),
            _f(r["axial_displacement_um"], ".2f"),
            _f(r["ball_load_inner_N"], ".0f"), _f(r["ball_load_outer_N"], ".0f"),
            _f(r["gyroscopic_moment_Nmm"], ".0f"), r["status"]] for r in rows], caption=caption)


#: The ``high-speed`` command, as the application adds it.
COMMANDS = {"high-speed": command("high-speed", high_speed)}

"""Command line of the friction capability (spec 001): ``friction torque``, ``friction lab``, ``friction template``.

torque     friction torque of a bearing under combined load (one-term, two-term, Palmgren; SKF four-term)
lab        a measurement-session file -> the three tasks, cross-checks, conclusions and the HTML report
template   a blank, commented measurement-session file to start a new session

Commands
--------
COMMANDS   the ``friction`` command group, by name (the application adds it)
"""

import sys
from pathlib import Path
from typing import Annotated

import typer

from . import _mounting as mo
from ._common import (
    BearingFile,
    BearingName,
    CatalogFile,
    ContactAngle,
    JsonFlag,
    OilOpt,
    TemperatureOpt,
    Viscosity100Opt,
    ViscosityIndexOpt,
    check_not_input,
    check_output_directory,
    console,
    emit_json,
    print_warnings,
    table,
)

__all__ = ["COMMANDS"]

friction_app = typer.Typer(
    help="Friction torque: handbook models and the friction-rig lab.",
    no_args_is_help=True,
)
_MODELS = ("one-term", "two-term", "palmgren", "skf")
_PANEL = "Bearing data (override the catalog)"


def torque(
    radial_load: Annotated[
        str,
        typer.Option(
            "--radial-load", "-R", help="F_r, e.g. '10 N', '1 kgf', or a list/range '0N:50N:10N'."
        ),
    ] = "0 N",
    axial_load: Annotated[
        str, typer.Option("--axial-load", "-A", help="F_a, e.g. '5 N' (list/range allowed).")
    ] = "0 N",
    speed: Annotated[
        str,
        typer.Option(
            "--speed", "-n", help="Inner-ring speed, e.g. '3000 rpm' (list/range allowed)."
        ),
    ] = "0 rpm",
    model: Annotated[
        str,
        typer.Option(
            "--model",
            "-m",
            help="one-term (default) | two-term (needs --f0) | palmgren (needs --viscosity, --palmgren-f0) | "
            "skf (needs --viscosity; --lubrication).",
        ),
    ] = "one-term",
    bearing: BearingName = None,
    bearing_file: BearingFile = None,
    catalog: CatalogFile = None,
    bearing_type: Annotated[
        str | None, typer.Option("--type", help="radial | angular.", rich_help_panel=_PANEL)
    ] = None,
    contact_angle: ContactAngle = None,
    bore: Annotated[
        str | None, typer.Option("--bore", help="d, e.g. '12 mm'.", rich_help_panel=_PANEL)
    ] = None,
    outside_diameter: Annotated[
        str | None,
        typer.Option("--outside-diameter", help="D, e.g. '28 mm'.", rich_help_panel=_PANEL),
    ] = None,
    mean_diameter: Annotated[
        str | None,
        typer.Option(
            "--mean-diameter", help="d_m = (d + D)/2, e.g. '20 mm'.", rich_help_panel=_PANEL
        ),
    ] = None,
    static_load_rating: Annotated[
        str | None,
        typer.Option("--static-load-rating", help="C0, e.g. '2227 N'.", rich_help_panel=_PANEL),
    ] = None,
    mu: Annotated[
        float | None,
        typer.Option(
            "--mu",
            help="Override of the handbook μ (0.0015 radial, 0.0020 angular).",
            rich_help_panel="Handbook constants",
        ),
    ] = None,
    x0: Annotated[
        float | None,
        typer.Option(
            "--x0", help="Override of x0 (Table 1).", rich_help_panel="Handbook constants"
        ),
    ] = None,
    y0: Annotated[
        float | None,
        typer.Option(
            "--y0", help="Override of y0 (Table 1).", rich_help_panel="Handbook constants"
        ),
    ] = None,
    f: Annotated[
        float | None,
        typer.Option("--f", help="Override of f (Table 2).", rich_help_panel="Handbook constants"),
    ] = None,
    c: Annotated[
        float | None,
        typer.Option("--c", help="Override of c (Table 2).", rich_help_panel="Handbook constants"),
    ] = None,
    f0: Annotated[
        float | None,
        typer.Option(
            "--f0",
            help="Speed-term factor of T0 = f0·d_m³·n^(2/3) in N·mm⁻²·min^(2/3) (e.g. 2e-7; from `friction lab`, task 2).",
            rich_help_panel="Handbook constants",
        ),
    ] = None,
    viscosity: Annotated[
        str | None,
        typer.Option(
            "--viscosity",
            help="Lubricant kinematic viscosity for --model palmgren, e.g. '20 cSt'.",
            rich_help_panel="Handbook constants",
        ),
    ] = None,
    palmgren_f0: Annotated[
        float | None,
        typer.Option(
            "--palmgren-f0",
            help="Palmgren's f0 (about 0.7-2 for deep-groove bearings) for --model palmgren.",
            rich_help_panel="Handbook constants",
        ),
    ] = None,
    lubrication: Annotated[
        str | None,
        typer.Option(
            "--lubrication",
            help="For --model skf: grease | oil-air | oil-jet | oil-bath (with --oil-level). Default grease; "
            "oil-jet when an oil grade (--oil) is given.",
            rich_help_panel="Handbook constants",
        ),
    ] = None,
    oil: OilOpt = None,
    temperature: TemperatureOpt = None,
    viscosity_index: ViscosityIndexOpt = None,
    viscosity_100: Viscosity100Opt = None,
    oil_level: Annotated[
        str | None,
        typer.Option(
            "--oil-level",
            help="For --model skf --lubrication oil-bath: H from the lowest point of the outer raceway, "
            "e.g. '5 mm' (at most to the bearing's centre).",
            rich_help_panel="Handbook constants",
        ),
    ] = None,
    drag_loss_factor: Annotated[
        float | None,
        typer.Option(
            "--drag-loss-factor",
            help="For --lubrication oil-bath: V_M in place of SKF's drag loss diagram at H/d_m (default: "
            "the diagram, digitised).",
            rich_help_panel="Handbook constants",
        ),
    ] = None,
    series: Annotated[
        str | None,
        typer.Option(
            "--series",
            help="For --model skf: the deep-groove series of SKF's constants, e.g. 62 (default: the "
            "bearing's series, else read from its designation).",
            rich_help_panel="Handbook constants",
        ),
    ] = None,
    json_out: JsonFlag = False,
):
    """Friction torque under combined load: the handbook models of the friction-rig lab (P0, T, T0 and T_F) or SKF's."""
    options = dict(locals(), type=bearing_type, **mo.given_options())  # the options as typed: the fields
    from ..calculations import _reading as _inputs
    from ..calculations import friction_torque as calculation

    r = calculation.compute(_inputs.request("friction", options), bearing_file=bearing_file, catalog=catalog)
    out = r.document
    if json_out:
        emit_json(out)
        return
    if r.skf is not None:
        _print_skf(out, r.skf)
    else:
        _print_torque(out, model)
    if "operating_clearance_um" in out:  # issue 23: the mounted bearing's clearance, for information
        console.print(f"operating clearance {out['operating_clearance_um']:.3g} um (least "
                      f"{out['operating_clearance_min_um']:.3g}, largest {out['operating_clearance_max_um']:.3g} um)",
                      highlight=False)
    print_warnings([*out.get("warnings", []), *out.get("mounting_warnings", [])])


def _print_skf(out, m):
    """The SKF model's moments: one case on lines of its own, several as two tables (80 columns)."""
    cases = out.get("cases", [out])
    title = f"Friction torque of {out['bearing']} ({out['type']}), SKF model, {out['lubrication']}"
    caption = f"ν = {out['viscosity_cSt']:g} mm²/s; SKF {_skf_terms(m)}"
    inputs = ["F_r [N]", "F_a [N]", "n [rpm]"]
    parts = [("rolling_moment_Nmm", "M_rr"), ("sliding_moment_Nmm", "M_sl"), ("seal_moment_Nmm", "M_seal"),
             ("drag_moment_Nmm", "M_drag")]
    totals = [("total_moment_Nmm", "M [N·mm]", ".6g"), ("power_loss_W", "P [W]", ".6g"),
              ("sliding_friction_coefficient", "μ_sl", ".5f")]

    def given(r):
        return [f"{r['radial_load_N']:.6g}", f"{r['axial_load_N']:.6g}", f"{r['speed_rpm']:.6g}"]

    if len(cases) == 1:  # one case: every quantity on a line of its own (80 columns)
        r = cases[0]
        table(title, ["quantity", "value"],
              [*zip(inputs, given(r)), *((f"{name} [N·mm]", f"{r[k]:.6g}") for k, name in parts),
               *((name, f"{r[k]:{fmt}}") for k, name, fmt in totals)], caption=caption)
    else:  # several: the totals, then the four moments (two tables of 80 columns)
        table(title, [*inputs, *(name for _, name, _ in totals)],
              [[*given(r), *(f"{r[k]:{fmt}}" for k, _, fmt in totals)] for r in cases], caption=caption)
        table("The four moments [N·mm]", [*inputs, *(name for _, name in parts)],
              [[*given(r), *(f"{r[k]:.6g}" for k, _ in parts)] for r in cases])


def _skf_terms(m):
    """The moments the SKF result holds, for the caption: the seal moment only where it was computed."""
    import numpy as np

    if np.any(np.asarray(m.seal_moment) > 0):  # the result says whether the model had seal data
        return "rolling, sliding, seal and drag moments"
    why = "not included, see the warnings" if m.warnings else "open bearing"
    return f"rolling, sliding and drag moments (no seal moment: {why})"


def _print_torque(out, model):
    """The torque table, with the constants used in the caption."""
    import itertools

    cases = out.get("cases", [out])
    # the model's constants: the document's entries before the cases (or the first case's loads)
    info = dict(itertools.takewhile(lambda kv: kv[0] not in ("cases", "radial_load_N"), out.items()))
    consts = ", ".join(
        f"{k} = {v:g}"
        for k, v in info.items()
        if isinstance(v, float) and not k.endswith(("_mm", "_N", "_cSt"))
    )
    table(
        f"Friction torque of {out['bearing']} ({out['type']}), {model} model",
        [
            "F_r [N]",
            "F_a [N]",
            "n [rpm]",
            "P0 [N]",
            "branch",
            "T [N·mm]",
            "T0 [N·mm]",
            "T_F [N·mm]",
        ],
        [
            [
                f"{r['radial_load_N']:.6g}",
                f"{r['axial_load_N']:.6g}",
                f"{r['speed_rpm']:.6g}",
                f"{r['equivalent_static_load_N']:.6g}",
                r["branch"],
                f"{r['torque_Nmm']:.6g}",
                f"{r['torque_speed_term_Nmm']:.6g}",
                f"{r['torque_load_term_Nmm']:.6g}",
            ]
            for r in cases
        ],
        caption=consts + ("; the one-term model has no speed term" if model == "one-term" else ""),
    )


def lab(
    file: Annotated[
        Path,
        typer.Argument(help="Measurement-session file (TOML; see `bearinglab friction template`)."),
    ],
    out: Annotated[
        Path | None,
        typer.Option(
            "--out", "-o", help="Report directory (created; a previous report there is replaced)."
        ),
    ] = None,
    json_out: JsonFlag = False,
):
    """Reduce a session of the friction-rig lab: tasks 1-3, cross-checks, conclusions, and the HTML report."""
    from .. import report
    from ..lab import analysis, measurement

    if out is not None:
        check_output_directory(out, "out")
    session = measurement.read_session(file)
    result = analysis.analyse(session)
    files = report.write_report(result, out) if out is not None else None
    d = analysis.to_dict(result)
    if json_out:
        d["report"] = None if files is None else str(files.html)
        emit_json(d)
        return
    b = d["bearing"]
    console.print(
        f"[bold]Bearing {b['designation']}[/bold] ({b['type']}, d = {b['bore_mm']:g} mm, d_m = "
        f"{b['mean_diameter_mm']:g} mm, C0 = {b['static_load_rating_N']:g} N); {len(d['rows'])} rows from "
        f"{session.rows_source}"
    )
    if d["task1"]:
        table(
            "Task 1: μ (through the origin)",
            ["β [deg]", "n [rpm]", "μ", "± s.e.", "RMS [N·mm]", "μ/μ_hb − 1"],
            [
                [
                    f"{r['tilt_deg']:g}",
                    f"{r['speed_rpm']:.6g}",
                    f"{r['mu']:.6e}",
                    _se(r["mu_standard_error"]),
                    f"{r['residual_rms_Nmm']:.4e}",
                    f"{r['mu_relative_to_handbook']:+.1%}",
                ]
                for r in d["task1"]
            ],
        )
    if d["task2"]:
        table(
            "Task 2: f0 and T_F (f0 in N·mm⁻²·min^(2/3))",
            ["β [deg]", "Q [kg]", "f0", "± s.e.", "T_F [N·mm]", "± s.e.", "handbook T_F [N·mm]"],
            [
                [
                    f"{r['tilt_deg']:g}",
                    f"{r['mass_kg']:g}",
                    f"{r['f0']:.6e}",
                    _se(r["f0_standard_error"]),
                    f"{r['torque_load_term_Nmm']:.6e}",
                    _se(r["torque_load_term_standard_error_Nmm"]),
                    f"{r['handbook_torque_load_term_Nmm']:.4e}",
                ]
                for r in d["task2"]
            ],
        )
    if d["task3"]:
        table(
            "Task 3: f and T0",
            ["β [deg]", "n [rpm]", "f", "± s.e.", "T0 [N·mm]", "± s.e.", "f/f_hb − 1"],
            [
                [
                    f"{r['tilt_deg']:g}",
                    f"{r['speed_rpm']:.6g}",
                    f"{r['f']:.6e}",
                    _se(r["f_standard_error"]),
                    f"{r['torque_speed_term_Nmm']:.6e}",
                    _se(r["torque_speed_term_standard_error_Nmm"]),
                    f"{r['f_relative_to_handbook']:+.1%}",
                ]
                for r in d["task3"]
            ],
        )
    console.print("[bold]Conclusions[/bold]")
    for k, text in enumerate(d["conclusions"], start=1):
        console.print(f"{k}. {text}", highlight=False, markup=False)
    if files is None:
        console.print("No --out given: no report written.")
    else:
        console.print(f"Report: {files.html}", highlight=False, markup=False)


def _se(x):
    return "n/a" if x is None else f"{x:.2g}"


def template(
    file: Annotated[
        Path | None, typer.Argument(help="New session file to write (default: print on stdout).")
    ] = None,
    bearing: Annotated[
        str | None, typer.Option("--bearing", "-b", help="Catalog bearing to fill in, e.g. 18.")
    ] = None,
    force: Annotated[bool, typer.Option("--force", help="Replace an existing file.")] = False,
):
    """Write a blank, commented measurement-session file for a new session."""
    from ..lab import measurement

    if file is None or str(file) == "-":
        sys.stdout.write(measurement.template(bearing=bearing))
        return
    check_not_input(file, "file")  # not even with --force: the user catalog is an input
    path = measurement.write_template(file, bearing=bearing, overwrite=force)
    console.print(
        f"Wrote {path}. Fill in the bearing, the calibration tables and the rows, then run:\n"
        f"  bearinglab friction lab {path} --out {path.with_suffix('')}-report",
        highlight=False,
        markup=False,
    )


friction_app.command("torque")(mo.mounting_options(torque))
friction_app.command("lab")(lab)
friction_app.command("template")(template)

#: The ``friction`` command group, as the application adds it.
COMMANDS = {"friction": friction_app}

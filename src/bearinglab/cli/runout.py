"""Command line of spec 003: ``runout`` (one angle or a rotation sequence) and ``runout monte-carlo``.

``runout`` is a sub-application whose callback does the single-angle / sequence computation when no
subcommand is given; ``monte-carlo`` is its subcommand. Options of the callback written before the
subcommand are rejected rather than silently ignored.

Commands
--------
COMMANDS   the ``runout`` command group (with ``monte-carlo``), by name (the application adds it)
"""

import math
from pathlib import Path
from typing import Annotated

import typer

from .. import _bounds
from ..errors import InputError
from ._common import (
    CatalogFile,
    ChunkSizeOpt,
    ExecutorOpt,
    FileOption,
    JsonFlag,
    WorkersOpt,
    check_not_input,
    check_output,
    check_output_directory,
    console,
    emit_json,
    execution,
    print_warnings,
    table,
)
from ._options import command

__all__ = ["COMMANDS"]

UM = 1e-6
# bearinglab.runout.METRICS, spelled out for the help text (the help is built without importing the
# model; tests/cli/test_cli_startup.py checks that the two agree)
_METRICS = ("radial_ptp_x", "radial_ptp_y", "radial_ptp_max", "axial_ptp", "dz_mean")

GeometryFile = FileOption("--geometry", "TOML file with a 'geometry' table (or a bearing file); default: the "
                          "'geometry' table of the errors file.", "Bearing", "-g")
PlotDir = FileOption("--plot", "Write the figures (PNG) into this directory.")


def _runout_figures():
    from ..plots import runout as figures  # imports matplotlib: loaded only when --plot is given

    return figures


# ----------------------------------------------------------------------------- helpers
def _atomic_write(path, text):
    """Write a whole file or nothing; its directory must exist (checked before the computation)."""
    from .._io import write_text
    write_text(path, text)


def _um(v):
    return float(v) / UM


def _trajectory_csv(t):
    import numpy as np

    from .._io import csv_text
    d = t.displacement
    rows = [
        [
            f"{math.degrees(p):.6f}",
            f"{x / UM:.9f}",
            f"{y / UM:.9f}",
            f"{z / UM:.9f}",
            " ".join(str(int(i) + 1) for i in np.flatnonzero(c)),
            int(dg),
            f"{fp / UM:.9f}",
        ]
        for p, x, y, z, c, dg, fp in zip(
            t.rotation_angle, d.x, d.y, d.z, d.contact.contact, d.contact.degenerate, d.free_play
        )
    ]
    return csv_text(
        ["psi_deg", "dx_um", "dy_um", "dz_um", "contact_balls", "degenerate", "free_play_um"],
        rows,
        [
            "bearinglab runout: inner-ring centre trajectory",
            "units: psi in deg, displacements in um; contact_balls 1-based",
        ],
    )


def _print_single(info):
    table(
        f"Inner-ring displacement at psi = {info['psi_deg']:g} deg",
        ["quantity", "value"],
        [
            ["a0 [µm]", f"{info['a0_um']:.6f}"],
            ["B [µm]", f"{info['B_um']:.6f}"],
            ["D [µm]", f"{info['D_um']:.6f}"],
            ["A [µm], φ [deg]", f"{info['A_um']:.6f}, {info['phi_deg']:.4f}"],
            ["Δx [µm]", f"{info['dx_um']:.6f}"],
            ["Δy [µm]", f"{info['dy_um']:.6f}"],
            ["Δz [µm]", f"{info['dz_um']:.6f}"],
            ["contact balls", ", ".join(map(str, info["contact_balls"]))],
            ["degenerate (free play [µm])", f"{info['degenerate']} ({info['free_play_um']:.6f})"],
            ["refinement passes (converged)", f"{info['passes']} ({info['converged']})"],
        ],
    )
    table(
        "Balls",
        ["ball", "θ [deg]", "Δk [µm]", "s(θ) [µm]", "slack [µm]", "contact", "λ"],
        [
            [
                b["ball"],
                f"{b['theta_deg']:.4f}",
                f"{b['dk_um']:.6f}",
                f"{b['s_um']:.6f}",
                f"{b['slack_um']:.6f}",
                "●" if b["contact"] else "",
                f"{b['load_share']:.6f}" if b["load_share"] else "",
            ]
            for b in info["balls"]
        ],
    )


def _print_metrics(title, rows):
    from .. import runout
    table(
        title,
        ["metric", *[r[0] for r in rows]],
        [
            [name.replace("_", " ") + " [µm]", *[f"{r[1][f'{name}_um']:.6f}" for r in rows]]
            for name in runout.METRICS
        ],
    )


# ----------------------------------------------------------------------------- runout
runout_app = typer.Typer(
    help="Initial inner-ring displacement and runout from manufacturing errors (manufacturing-error runout).",
    invoke_without_command=True,
    no_args_is_help=False,
    context_settings={"help_option_names": ["-h", "--help"]},
)


def runout_command(
    given, *, ctx: typer.Context, geometry: GeometryFile = None, catalog: CatalogFile = None,
    json_out: JsonFlag = False, plot: PlotDir = None,
    csv_out: FileOption("--csv", "Write the trajectory (sequence) as CSV.") = None,
):
    """Inner-ring displacement at one angle, or the trajectory and runout over revolutions.

    Give the errors with --errors FILE and the geometry in that file's [geometry] table, with --geometry
    FILE or with --bearing NAME. `runout monte-carlo --help` for the tolerance-class study.
    """
    from .. import runout
    from ..calculations import parse
    from ..calculations import runout as calculation

    if ctx.invoked_subcommand is not None:
        _reject_options_before(ctx)
        return
    errors, revolutions, steps_per_rev = (given.get(k) for k in ("errors", "revolutions", "steps_per_rev"))
    cage_ratio = given.get("cage_ratio")
    if errors is None:
        raise InputError(
            "errors: give the error file with --errors FILE (see examples/runout/README.md)"
        )
    if csv_out is not None:
        check_output(csv_out, "csv", (".csv",), inputs=(errors, geometry, catalog))
        check_not_input(csv_out, "csv", runout.files.profile_files(errors))  # nor a measured profile
    if plot is not None:
        check_output_directory(plot, "plot")
    sequence = revolutions is not None or steps_per_rev is not None
    if csv_out is not None and not sequence:
        raise InputError(
            "csv: --csv writes a trajectory; give --revolutions N (and --steps-per-rev M)"
        )
    if sequence:  # the model's words for its limits, before the fields' ranges
        calculation.check_sequence(3 if revolutions is None else revolutions,
                                   360 if steps_per_rev is None else steps_per_rev, cage_ratio)
    else:
        calculation.check_sequence(1, 360, cage_ratio)
    for key in ("angle", "start_angle", "first_ball_angle"):  # a bare number is in degrees here
        if key in given and _is_number(given[key]):
            given[key] = f"{given[key]} deg"
    given["errors"] = str(errors)  # read as the file below, with its profiles
    result = calculation.compute(parse("runout", given, limit=_bounds.MAX_POSITIONS), errors_file=errors,
                                 geometry_file=geometry, catalog=catalog)
    info = result.document
    if not sequence:
        if plot is not None:
            info["figures"] = [str(p) for p in _runout_figures().save_single(result.displacement, plot)]
        if json_out:
            emit_json(info)
            return
        _print_single(info)
        if plot is not None:
            console.print(f"figures: {', '.join(info['figures'])}")
        print_warnings(info["warnings"])
        return
    t = result.trajectory
    if csv_out is not None:
        _atomic_write(csv_out, _trajectory_csv(t))
        info["csv"] = str(csv_out)
    if plot is not None:
        info["figures"] = [str(p) for p in _runout_figures().save_sequence(t, result.spectrum, result.lines,
                                                                              plot)]
    if json_out:
        emit_json(info)
        return
    _print_sequence(info, t, result.lines, info["revolutions"], info["steps_per_rev"], info["refine"])
    print_warnings(info["warnings"])


def _is_number(text):
    try:
        float(str(text))
    except ValueError:
        return False
    return True


def _reject_options_before(ctx):
    """Options of ``runout`` written before its subcommand would be ignored: an error instead."""
    given = [
        f"--{k.replace('_', '-')}"
        for k, v in ctx.params.items()
        if v not in (None, False) and not (k == "start_angle" and v == "0 deg")
    ]
    if given:
        raise InputError(
            f"runout: {', '.join(given)} given before '{ctx.invoked_subcommand}'; write the "
            f"options after the subcommand"
        )


def _print_sequence(info, t, lines, revs, steps, refine):
    """The runout metrics, the spectral lines and the files written, of a rotation sequence."""
    _print_metrics(
        f"Runout over {revs} revolutions, {steps} steps per revolution (µm)",
        [
            ("whole", info),
            ("synchronous", info["synchronous"]),
            ("asynchronous", info["asynchronous"]),
        ],
    )
    console.print(
        f"degenerate positions: {100 * t.degenerate_fraction:.1f} %   cage ratio κ = {t.cage_ratio:.6f}"
        + (f"   refined, at most {info['passes_max']} passes" if refine else "")
    )
    if lines:
        table(
            "Spectral lines",
            ["component", "order", "bin", "amplitude [µm]", "line", "source"],
            [
                [ln.component, f"{ln.order:.4f}", f"{ln.bin_order:.4f}", f"{_um(ln.amplitude):.6f}", ln.label,
                 ln.source]
                for ln in lines
            ],
            caption=f"order: the line's true order p·κ + q; bin: the spectrum bin it was found in "
                    f"(resolution 1/revolutions = {lines[0].resolution:.4g})",
        )
    for key in ("csv", "figures"):
        if key in info:
            console.print(f"{key}: {info[key] if key == 'csv' else ', '.join(info[key])}")


def monte_carlo_command(
    given, *, geometry: GeometryFile = None, catalog: CatalogFile = None,
    chunk_size: ChunkSizeOpt = 100, executor: ExecutorOpt = None, workers: WorkersOpt = None,
    samples_csv: FileOption("--samples-csv", "Write the per-sample metrics as CSV.") = None,
    write_worst: Annotated[int | None, typer.Option(
        "--write-worst", help="Write the error files of the N worst samples (by --worst-by) into --worst-dir; "
        "the runout command re-runs each exactly (see the file's description).")] = None,
    worst_by: Annotated[str, typer.Option(
        "--worst-by", help="Metric ranking --write-worst: " + ", ".join(_METRICS))] = "radial_ptp_max",
    worst_dir: FileOption("--worst-dir", "Directory of the --write-worst files (default: .).") = None,
    progress: Annotated[bool, typer.Option(
        "--progress/--no-progress", help="Progress bar on stderr (terminals only).")] = True,
    json_out: JsonFlag = False,
    plot: PlotDir = None,
):
    """Runout statistics over random bearings of a ball grade and a ring class (Monte Carlo)."""
    from .. import runout
    from ..calculations import parse
    from ..calculations import runout as calculation

    samples, seed, revolutions, steps_per_rev, max_order = (
        given[k] for k in ("samples", "seed", "revolutions", "steps_per_rev", "max_order"))
    if geometry is None and given.get("bearing") is None:
        raise InputError("geometry: give --geometry FILE or --bearing NAME")
    if samples_csv is not None:
        check_output(samples_csv, "samples-csv", (".csv",), inputs=(geometry, catalog))
    if plot is not None:
        check_output_directory(plot, "plot")
    _check_write_worst(write_worst, worst_by, worst_dir)
    if write_worst is not None:  # the files written there are checked against the run's inputs, named so
        from .._io import name_output
        name_output(worst_dir or Path("."), "worst-dir")
    if worst_dir is not None and not worst_dir.is_dir():  # never created: a typo must not make a tree
        if worst_dir.exists():
            raise InputError(f"worst-dir: {str(worst_dir)!r} is a file; give a directory")
        raise InputError(f"worst-dir: directory {str(worst_dir)!r} does not exist (it is never created; "
                         f"create it first)")
    calculation.check_study(samples, steps_per_rev, revolutions, max_order, given.get("cage_ratio"))  # the model's words
    parsed = parse("runout-monte-carlo", given, limit=_bounds.MAX_SAMPLES)
    # rich for serial, dask's progress bar on a cluster; none off a terminal
    with execution("Monte Carlo", executor, workers, chunk_size, progress=progress) as ex:
        info, r, g, grade, rings = calculation.compute_monte_carlo(parsed, geometry_file=geometry,
                                                                   catalog=catalog, execution=ex)
    if samples_csv is not None:
        _atomic_write(samples_csv, _samples_csv(r, grade, rings, seed, samples, revolutions, steps_per_rev,
                                                max_order))
        info["samples_csv"] = str(samples_csv)
    if write_worst is not None:
        worst = runout.worst_samples(r, worst_by, write_worst)
        for index in worst:  # the names write_sample_error_files gives: none may replace an input
            check_not_input((worst_dir or Path(".")) / f"sample_{int(index)}.toml",
                            "worst-dir", (geometry, catalog))
        files = runout.write_sample_error_files(worst_dir or Path("."), r, g, worst)
        info["worst_error_files"] = [str(p) for p in files]
    if plot is not None:
        info["figures"] = [str(p) for p in _runout_figures().save_monte_carlo(r, plot)]
    if json_out:
        emit_json(info)
        return
    _print_monte_carlo(info, grade, rings, samples, seed)


def _samples_csv(r, grade, rings, seed, samples, revolutions, steps_per_rev, max_order):
    """The per-sample metrics as CSV text."""
    from .. import runout
    from .._io import csv_text
    s = r.samples
    rows = [
        [
            int(i),
            f"{math.degrees(t1):.6f}",
            *[f"{getattr(s, m)[k] / UM:.9f}" for m in runout.METRICS],
            f"{s.degenerate_fraction[k]:.6f}",
        ]
        for k, (i, t1) in enumerate(zip(s.sample_index, s.first_ball_angle))
    ]
    return csv_text(
        [
            "sample",
            "first_ball_angle_deg",
            *[f"{m}_um" for m in runout.METRICS],
            "degenerate_fraction",
        ],
        rows,
        [
            (
                f"bearinglab runout monte-carlo: {grade.name} / {rings.name}, seed {seed}, {samples} samples, "
                f"{revolutions} rev x {steps_per_rev} steps, K_max {max_order}"
            ),
            "units: um",
        ],
    )


def _print_monte_carlo(info, grade, rings, samples, seed):
    """The summary table and the files written."""
    from .. import runout
    table(
        f"Monte Carlo {grade.name} / {rings.name}: {samples} samples, seed {seed} (µm)",
        ["metric", "mean", "std", "median", "p95", "max"],
        [
            [
                name.replace("_", " "),
                *[f"{info[f'{name}_um'][k]:.3f}" for k in ("mean", "std", "median", "p95", "max")],
            ]
            for name in runout.METRICS
        ],
    )
    for key in ("samples_csv", "worst_error_files", "figures"):
        if key in info:
            console.print(f"{key}: {info[key] if key == 'samples_csv' else ', '.join(info[key])}")


def _check_write_worst(count, metric, directory):
    """The --write-worst options, checked before the study runs."""
    from .. import runout
    if count is not None and count < 1:
        raise InputError(f"write-worst must be >= 1 [-], got {count}")
    if count is not None and count > _bounds.MAX_SAMPLES:  # files of samples the study cannot hold
        raise InputError(f"write-worst must be <= {_bounds.MAX_SAMPLES} [-] (the most samples), got {count}")
    if metric not in runout.METRICS:
        raise InputError(f"worst-by must be one of {list(runout.METRICS)}, got {metric!r}")
    if directory is not None and count is None:
        raise InputError("worst-dir: give --write-worst N too (the number of samples to write)")


# the group's callback: no option is required, so that `runout monte-carlo` runs without --errors
runout_app.callback(invoke_without_command=True)(command("runout", runout_command, required=False,
                                                             documents="path"))  # its profiles lie next to it
runout_app.command("monte-carlo")(command("runout-monte-carlo", monte_carlo_command))

#: The ``runout`` command group (with ``monte-carlo``), as the application adds it.
COMMANDS = {"runout": runout_app}

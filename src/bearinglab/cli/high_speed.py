"""Command line of the high-speed model under thrust (spec 004): ``high-speed``.

One case prints a table of every output (or one JSON object with ``--json``); lists or ranges of loads
and speeds make a grid that is solved in one batched call and printed as a table (or one JSON array),
written with ``--csv`` and drawn with ``--plot`` (the paper's figures 2-4 and delta_a against thrust).
"""

from __future__ import annotations

import csv
import math
import os
import sys
import warnings
from pathlib import Path
from typing import Annotated

import numpy as np
import typer

from . import quasistatic
from ._io import atomic_output
from .cli import (
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
    console,
    emit_json,
    progress_bar,
    resolve_bearing,
    table,
)
from .errors import InputError, ValidityWarning
from .units import RPM, parse_quantity, parse_values

__all__ = ["plot_map", "register", "write_csv"]

_PROGRESS_MIN_CASES = 5000  # serial sweeps at least this large are cut finer, so the bar moves
_CHUNK = 2500  # cases per batched call then


def _check_directory(path: Path, what: str) -> None:
    if not path.parent.is_dir():
        raise InputError(f"{what}: directory {str(path.parent)!r} does not exist")


def write_csv(path, columns):
    """Write ``columns`` (name -> 1-D array) as CSV, whole or not at all (temporary file, then rename)."""
    path = Path(path)
    _check_directory(path, "csv")
    names = list(columns)
    with atomic_output(path) as tmp, open(tmp, "w", newline="", encoding="utf-8") as fh:
        writer = csv.writer(fh)
        writer.writerow(names)
        for row in zip(*(columns[n] for n in names)):
            writer.writerow([_cell(v) for v in row])


def _cell(v):
    if isinstance(v, (float, np.floating)):
        return "" if not math.isfinite(v) else repr(float(v))
    if isinstance(v, (np.bool_, bool)):
        return str(bool(v)).lower()
    if isinstance(v, np.integer):
        return int(v)
    return v


def plot_map(state, path, *, title="", sign_change=None):
    """Draw the map of a :func:`bearinglab.quasistatic.sweep` result (loads x speeds) into ``path``.

    Four panels, as the paper's figures 2-4 plus the axial displacement: the outer and the inner
    contact angle against thrust (one curve per speed), the increments from the static angle
    (inner solid, outer dashed) and delta_a against thrust with its sign change marked: at the thrusts
    ``sign_change`` [N] (one per speed, e.g. from :func:`bearinglab.quasistatic.zero_displacement_thrust`)
    or, if not given, interpolated between grid loads. Written whole or not at all.
    """
    import matplotlib

    if "MPLBACKEND" not in os.environ:
        matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    path = Path(path)
    _check_directory(path, "plot")
    fa = np.asarray(state.axial_load)[:, 0] * 1e-3
    speeds = np.asarray(state.shaft_speed)[0] / RPM
    deg = 180.0 / math.pi
    ai = np.asarray(state.contact_angle_inner) * deg
    ae = np.asarray(state.contact_angle_outer) * deg
    a_s = np.asarray(state.static_contact_angle) * deg
    da = np.asarray(state.axial_displacement) * 1e6
    fig, axes = plt.subplots(2, 2, figsize=(11, 8.5), constrained_layout=True)
    colors = plt.cm.viridis(np.linspace(0.0, 0.9, len(speeds)))
    many = len(speeds) > 8
    for j, (n, c) in enumerate(zip(speeds, colors)):
        label = None if many and j not in (0, len(speeds) - 1) else f"{n:g} rpm"
        axes[0, 0].plot(fa, ae[:, j], color=c, label=label)
        axes[0, 1].plot(fa, ai[:, j], color=c, label=label)
        if n > 0:
            axes[1, 0].plot(fa, ai[:, j] - a_s[:, j], color=c, label=label)
            axes[1, 0].plot(fa, a_s[:, j] - ae[:, j], color=c, ls="--")
        axes[1, 1].plot(fa, da[:, j], color=c, label=label)
        if sign_change is not None:
            f0s = [float(sign_change[j]) * 1e-3] if fa[0] <= sign_change[j] * 1e-3 <= fa[-1] and n > 0 else []
        else:  # linear interpolation of the sign change between grid loads
            f0s = [fa[k] - da[k, j] * (fa[k + 1] - fa[k]) / (da[k + 1, j] - da[k, j])
                   for k in np.flatnonzero(np.diff(np.sign(da[:, j])) > 0)]
        for f0 in f0s:
            axes[1, 1].plot([f0], [0.0], "o", color=c, mfc="white")
            if not many:
                axes[1, 1].annotate(f"{f0:.2f} kN", (f0, 0.0), textcoords="offset points", xytext=(4, -12),
                                    fontsize=8, color=c)
    axes[0, 0].set(title="outer contact angle (paper fig. 2)", ylabel="α_e [deg]")
    axes[0, 1].set(title="inner contact angle (paper fig. 3)", ylabel="α_i [deg]")
    axes[1, 0].set(title="increments from α_s (fig. 4): Δα_i solid, Δα_e dashed",
                   ylabel="Δα [deg]")
    axes[1, 1].axhline(0.0, color="0.5", lw=0.8)
    axes[1, 1].set(title="axial displacement (○ sign change)", ylabel="δ_a [µm]")
    for ax in axes.flat:
        ax.set_xlabel("thrust F_a [kN]")
        ax.grid(alpha=0.3)
    axes[0, 0].legend(fontsize=8)
    if title:
        fig.suptitle(title)
    suffix = path.suffix.lower().lstrip(".") or "png"
    try:
        with atomic_output(path, suffix=f".{suffix}") as tmp:
            fig.savefig(tmp, format=suffix, dpi=120)
    finally:
        plt.close(fig)


def _choice(name, value, choices):
    if value not in choices:
        raise InputError(f"{name} must be one of {list(choices)}, got {value!r}")
    return value


def high_speed(
    axial_load: Annotated[str, typer.Option("--axial-load", "-F", help="Thrust: '20 kN', or a list/range '2.5kN:45kN:2.5kN'.")],
    speed: Annotated[str, typer.Option("--speed", "-n", help="Inner-ring speed: '10000 rpm', or a list/range '0,3000,6000rpm'.")],
    bearing: BearingName = None, bearing_file: BearingFile = None, catalog: CatalogFile = None,
    balls: Balls = None, ball_diameter: BallDiameter = None, pitch_diameter: PitchDiameter = None,
    inner_groove_radius: InnerRadius = None, outer_groove_radius: OuterRadius = None,
    inner_conformity: InnerConformity = None, outer_conformity: OuterConformity = None,
    contact_angle: ContactAngle = None, radial_clearance: Clearance = None, ball_material: BallMaterial = None,
    solver: Annotated[str, typer.Option("--solver", help="newton (batched Newton-Raphson, §5.1) | angle-iteration (the paper's search, §5.2).")] = "newton",
    raceway_control: Annotated[str, typer.Option("--raceway-control", help="outer (default, the paper's) | inner.")] = "outer",
    constants: Annotated[str, typer.Option("--constants", help="mass (F_c, M_g from the ball mass; default) | harris (2.26e-11, 4.47e-12: spec 004 §7) | paper (2.26e-11, 4.5e-12).")] = "mass",
    gyroscopic_sign: Annotated[str, typer.Option("--gyroscopic-sign", help="physical (default, spec 004 §4) | reversed (for comparison only).")] = "physical",
    reduced_modulus: Annotated[str | None, typer.Option("--reduced-modulus", help="E' of the contact pair, e.g. '228.04 GPa' (default: from the materials).")] = None,
    csv_file: Annotated[Path | None, typer.Option("--csv", help="Write the table of all cases to this CSV file.")] = None,
    plot: Annotated[Path | None, typer.Option("--plot", help="Draw the map (figures 2-4 and δ_a) into this PNG/PDF/SVG file.")] = None,
    executor: ExecutorOpt = None, workers: WorkersOpt = None, chunk_size: ChunkSizeOpt = None,
    json_out: JsonFlag = False,
):
    """High-speed angular-contact bearing under thrust (spec 004): α_i, α_e, δ_a, loads, F_c, M_g, speeds."""
    b = resolve_bearing(bearing, bearing_file, catalog, balls, ball_diameter, pitch_diameter, inner_groove_radius,
                        outer_groove_radius, inner_conformity, outer_conformity, contact_angle, radial_clearance,
                        ball_material)
    _choice("solver", solver, ("newton", "angle-iteration"))
    _choice("raceway-control", raceway_control, tuple(quasistatic.RACEWAY_CONTROLS))
    _choice("constants", constants, tuple(quasistatic.CONSTANTS))
    sign = {"physical": 1, "reversed": -1}.get(_choice("gyroscopic-sign", gyroscopic_sign, ("physical", "reversed")))
    loads = parse_values(axial_load, "force", "axial-load")
    speeds = parse_values(speed, "speed", "speed")
    if np.any(~(loads > 0)):
        raise InputError(f"axial-load must be > 0 [N], got {float(loads[~(loads > 0)][0])!r} N")
    if np.any(~(speeds >= 0)):
        raise InputError(f"speed must be >= 0 [rpm] (the inner-ring speed as a magnitude), got "
                         f"{float(speeds[~(speeds >= 0)][0]) / RPM:g} rpm")
    if plot is not None and (loads.size < 2 or speeds.size < 1):
        raise InputError("plot: needs a sweep over at least two thrusts (e.g. --axial-load 2.5kN:45kN:2.5kN)")
    ep = None
    if reduced_modulus is not None:
        ep = parse_quantity(reduced_modulus, "pressure", "reduced-modulus")
        if not ep > 0:
            raise InputError(f"reduced-modulus must be > 0 [GPa], got {ep / 1e9:g} GPa")
    options = {"method": solver, "raceway_control": raceway_control, "constants": constants, "gyroscopic_sign": sign,
                   "reduced_modulus": ep}
    single = loads.size == 1 and speeds.size == 1
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", ValidityWarning)
        if single:
            state = quasistatic.high_speed_analysis(b, loads[0], speeds[0], **options)
        else:
            state = _sweep(b, loads, speeds, options, executor=executor or "serial", workers=workers,
                           chunk_size=chunk_size)
    cols = quasistatic.result_table(state)
    if csv_file is not None:
        write_csv(csv_file, cols)
    if plot is not None:
        plot_map(state, plot, title=f"Bearing {b.designation}: high-speed contact angles under thrust")
    notes = [str(c.message) for c in caught if issubclass(c.category, ValidityWarning)]
    rows = [{k: _jsonable(v[i]) for k, v in cols.items()} for i in range(len(cols["converged"]))]
    if json_out:
        for note in notes:  # stdout stays one JSON document
            print(f"bearinglab: warning: {note}", file=sys.stderr)
        if single:
            emit_json(dict(rows[0], bearing=b.designation, constants=constants, raceway_control=raceway_control,
                           gyroscopic_sign=gyroscopic_sign, solver=solver, warnings=notes))
        else:
            emit_json(rows)
        return
    if single:
        _print_single(b, rows[0], options)
    else:
        _print_sweep(b, rows, options)
    for note in notes:
        console.print(f"[yellow]warning:[/yellow] {note}", highlight=False)
    if csv_file is not None:
        console.print(f"wrote {csv_file}", highlight=False)
    if plot is not None:
        console.print(f"wrote {plot}", highlight=False)


def _jsonable(v):
    if isinstance(v, (np.bool_, bool)):
        return bool(v)
    if isinstance(v, np.integer):
        return int(v)
    if isinstance(v, (float, np.floating)):
        return float(v) if math.isfinite(v) else None
    return v


def _sweep(bearing, loads, speeds, options, *, executor="serial", workers=None, chunk_size=None):
    """The grid in chunks on the chosen executor, with a progress bar on a terminal (rich for serial,
    dask's for a cluster)."""
    kw = {} if chunk_size is None else {"chunk_size": chunk_size}
    if chunk_size is None and executor == "serial" and loads.size * speeds.size >= _PROGRESS_MIN_CASES:
        kw["chunk_size"] = _CHUNK  # small enough chunks for the bar to move
    with progress_bar("solving", executor) as progress:
        return quasistatic.sweep(bearing, loads, speeds, executor=executor, workers=workers, progress=progress,
                                 **kw, **options)


def _f(x, spec):
    return "—" if x is None else format(x, spec)


def _print_single(b, r, options):
    caption = (f"{options['raceway_control']}-raceway control, constants {options['constants']}, "
               f"{'physical' if options['gyroscopic_sign'] > 0 else 'reversed'} gyroscopic sign, "
               f"solver {options['method']} ({r['method']}, {r['iterations']} iterations, residual {_f(r['residual'], '.2e')})")
    table(f"Bearing {b.designation}: F_a = {r['axial_load_kN']:g} kN at {r['speed_rpm']:g} rpm", ["quantity", "inner", "outer"], [
        ["contact angle [deg]", _f(r["contact_angle_inner_deg"], ".4f"), _f(r["contact_angle_outer_deg"], ".4f")],
        ["static contact angle α_s [deg]", _f(r["static_contact_angle_deg"], ".4f"), ""],
        ["ball load Q [N]", _f(r["ball_load_inner_N"], ".1f"), _f(r["ball_load_outer_N"], ".1f")],
        ["deflection δ [µm]", _f(r["deflection_inner_um"], ".3f"), _f(r["deflection_outer_um"], ".3f")],
        ["max contact pressure [MPa]", _f(r["max_pressure_inner_MPa"], ".0f"), _f(r["max_pressure_outer_MPa"], ".0f")],
        ["ball-pass frequency [Hz]", _f(r["bpfi_Hz"], ".2f"), _f(r["bpfo_Hz"], ".2f")],
    ], caption=caption)
    table("Ball and ring", ["quantity", "value"], [
        ["axial displacement δ_a [mm]", _f(r["axial_displacement_mm"], ".5f")],
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
          [[f"{r['axial_load_kN']:g}", f"{r['speed_rpm']:g}", _f(r["contact_angle_inner_deg"], ".3f"),
            _f(r["contact_angle_outer_deg"], ".3f"),
            _f(None if r["axial_displacement_mm"] is None else r["axial_displacement_mm"] * 1e3, ".2f"),
            _f(r["ball_load_inner_N"], ".0f"), _f(r["ball_load_outer_N"], ".0f"),
            _f(r["gyroscopic_moment_Nmm"], ".0f"), r["status"]] for r in rows], caption=caption)


def register(app: typer.Typer) -> None:
    """Add the ``high-speed`` command to ``app``."""
    app.command("high-speed")(high_speed)

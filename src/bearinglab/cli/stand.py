"""Command line of the test-stand method (spec 000): ``axial-angle`` and ``stand-load``.

Commands
--------
COMMANDS   the ``axial-angle`` and ``stand-load`` commands, by name (the application adds them)
"""

import math
from typing import Annotated

import typer

from ..errors import InputError
from ._common import (
    BallDiameter,
    BallMaterial,
    Balls,
    BearingFile,
    BearingName,
    CatalogFile,
    Clearance,
    ContactAngle,
    InnerConformity,
    InnerRadius,
    JsonFlag,
    OuterConformity,
    OuterRadius,
    PitchDiameter,
    console,
    emit_json,
    inputs_echo,
    parse_speeds,
    print_warnings,
    resolve_bearing,
    table,
)

__all__ = ["COMMANDS"]


def _angle_row(row, legacy):
    from ..units import format_dms, to_dms
    d, m, s = to_dms(row.contact_angle, truncate=legacy)
    dms = f"{d}°{m:02d}'{s:02.0f}\"" if legacy else format_dms(row.contact_angle)
    return dms


def axial_angle(
    axial_load: Annotated[str, typer.Option("--axial-load", "-F", help="Axial load: '2 kgf', '19.6 N', or a list/range '1kgf:5kgf:1kgf'.")],
    bearing: BearingName = None, bearing_file: BearingFile = None, catalog: CatalogFile = None,
    balls: Balls = None, ball_diameter: BallDiameter = None, pitch_diameter: PitchDiameter = None,
    inner_groove_radius: InnerRadius = None, outer_groove_radius: OuterRadius = None,
    inner_conformity: InnerConformity = None, outer_conformity: OuterConformity = None,
    contact_angle: ContactAngle = None, radial_clearance: Clearance = None, ball_material: BallMaterial = None,
    hertz: Annotated[str, typer.Option("--hertz", help="exact (default) | table (the bearing's tabulated 2K/(πμ)).")] = "exact",
    elastic_constant: Annotated[str, typer.Option("--elastic-constant", help="materials (default: from the bearing's E, ν) | paper (the source's 0.592e-4 (cm²/kgf)^(2/3)).")] = "materials",
    legacy: Annotated[bool, typer.Option("--legacy", help="Reproduce the paper's printed rounding (π = 3.14, F cut to 3 decimals).")] = False,
    x0: Annotated[float | None, typer.Option("--x0", help="Start of the iteration table \\[rad] (the paper printed 0.0433985).")] = None,
    rows: Annotated[int | None, typer.Option("--rows", help="Rows of the iteration table (default: to convergence).")] = None,
    json_out: JsonFlag = False,
):
    """Operating contact angle under axial load (the test-stand method): C*, x0, Newton iterations, displacement."""
    import numpy as np

    from .. import limits, stand, tables
    from .._bounds import MAX_CASES, MAX_ROWS, check_count
    from ..units import KGF, format_dms, parse_values
    b = resolve_bearing(bearing, bearing_file, catalog, balls, ball_diameter, pitch_diameter, inner_groove_radius,
                        outer_groove_radius, inner_conformity, outer_conformity, contact_angle, radial_clearance,
                        ball_material)
    if hertz not in ("exact", "table"):
        raise InputError(f"hertz must be one of ['exact', 'table'], got {hertz!r}")
    if elastic_constant not in ("materials", "paper"):
        raise InputError(f"elastic-constant must be one of ['materials', 'paper'], got {elastic_constant!r}")
    if rows is not None:
        check_count("rows", rows, MAX_ROWS)
    loads = parse_values(axial_load, "force", "axial-load", limit=MAX_CASES)
    if np.any(~(loads > 0)):
        bad = float(loads[~(loads > 0)][0])
        raise InputError(f"axial-load must be > 0 [N], got {bad:g} N ({bad / KGF:g} kgf)")
    scalar = loads.size == 1
    # the paper prints two rows; legacy mode reproduces exactly those unless --rows says otherwise
    max_rows = rows if rows is not None else (2 if legacy else None)
    r = stand.stand_analysis(b, loads[0] if scalar else loads, hertz=hertz, reproduce_print=legacy, x0=x0,
                              max_rows=max_rows, elastic_constant=elastic_constant)
    c = r.constants
    notes = limits.contact_warnings(b, r.axial_load, r.ball_load, r.ball_load, r.contact_angle, r.contact_angle)
    base = inputs_echo(b, axial_load_N=list(map(float, np.atleast_1d(loads))) if not scalar else float(loads[0]),
                       hertz=hertz, elastic_constant=elastic_constant, legacy=legacy, x0_rad=x0, rows=rows)
    base.update({
        "elastic_constant_cm2_per_kgf_2_3": c.elastic_constant_paper,
        "contact_angle_initial_deg": math.degrees(r.free_angle),
        "gamma": c.gamma,
        "curvature_sum_inner_per_mm": c.curvature_sum_inner * 1e-3,
        "curvature_sum_outer_per_mm": c.curvature_sum_outer * 1e-3,
        "cos_tau_inner": c.curvature_difference_inner,
        "cos_tau_outer": c.curvature_difference_outer,
        "delta_star_inner": c.hertz_inner.delta_star,
        "delta_star_outer": c.hertz_outer.delta_star,
        "c_inner_cm2_per_kgf_2_3": c.approach_inner_paper,
        "c_outer_cm2_per_kgf_2_3": c.approach_outer_paper,
        "load_deflection_constant_kgf": c.force_characteristic_kgf,
        "load_deflection_constant_N": c.force_characteristic,
    })
    if scalar:
        out = dict(base)
        out.update({
            "axial_load_N": float(r.axial_load), "axial_load_kgf": float(r.axial_load) / KGF,
            "series_coefficients": list(np.asarray(r.series).ravel()),
            "first_approximation_rad": float(r.first_approximation),
            "operating_contact_angle_deg": math.degrees(r.contact_angle),
            "operating_contact_angle_dms": format_dms(r.contact_angle),
            "contact_angle_increment_deg": math.degrees(r.contact_angle - r.free_angle),
            "axial_displacement_ratio": float(r.axial_displacement_ratio),
            "axial_displacement_um": float(r.axial_displacement) * 1e6,
            "ball_load_N": float(r.ball_load), "ball_load_kgf": float(r.ball_load) / KGF,
            "converged": True,
            "legacy": legacy,
            "warnings": notes,
            "iterations": [{"k": row.k, "x_rad": row.x, "contact_angle_deg": math.degrees(row.contact_angle),
                            "contact_angle_dms": _angle_row(row, legacy),
                            "axial_displacement_ratio": row.axial_displacement_ratio,
                            "axial_load_kgf": row.axial_load / KGF, "axial_load_N": row.axial_load,
                            "error_percent": row.error_percent} for row in r.iterations],
        })
        if json_out:
            emit_json(out)
            return
        _print_single(b, c, out, hertz, legacy)
        print_warnings(notes)
        return
    cases = [dict(row, converged=True) for row in tables.rows(tables.columns(r, tables.AXIAL_ANGLE))]
    if json_out:
        emit_json(dict(base, cases=cases, warnings=notes))
        return
    cstar = np.broadcast_to(c.force_characteristic_kgf, len(cases))
    if np.ndim(c.force_characteristic_kgf) == 0:  # C* at alpha0: one value for all loads, in the title
        title, head, extra = f"{hertz} Hertz, C* = {float(cstar[0]):.2f} kgf", [], [[] for _ in cases]
    else:  # C* at each load's operating angle: a column
        title, head, extra = f"{hertz} Hertz, C* at the operating angle", ["C* [kgf]"], [[f"{v:.2f}"] for v in cstar]
    table(f"Bearing {b.designation}: operating contact angle ({title})",
          ["F_a [kgf]", "F_a [N]", "α [deg]", "ξ_a", "δ_a [µm]", "ball load [N]", *head],
          [[f"{x['axial_load_kgf']:.4g}", f"{x['axial_load_N']:.4g}", f"{x['operating_contact_angle_deg']:.5f}",
            f"{x['axial_displacement_ratio']:.6f}", f"{x['axial_displacement_um']:.3f}", f"{x['ball_load_N']:.4g}",
            *e] for x, e in zip(cases, extra)])
    print_warnings(notes)


def _print_single(b, c, out, hertz, legacy):
    """The tables of one load: contact constants, iterations, and the result line."""
    table(f"Bearing {b.designation}: contact constants ({hertz} Hertz)", ["quantity", "inner", "outer"], [
        ["Σρ [1/mm]", f"{out['curvature_sum_inner_per_mm']:.7f}", f"{out['curvature_sum_outer_per_mm']:.7f}"],
        ["cos τ", f"{out['cos_tau_inner']:.7f}", f"{out['cos_tau_outer']:.7f}"],
        ["2K/(πμ)", f"{out['delta_star_inner']:.5f}", f"{out['delta_star_outer']:.5f}"],
        ["c [(cm²/kgf)^(2/3)]", f"{out['c_inner_cm2_per_kgf_2_3']:.6e}", f"{out['c_outer_cm2_per_kgf_2_3']:.6e}"],
    ], caption=f"α0 = {out['contact_angle_initial_deg']:g}°, γ = {c.gamma:.6f}, C* = {c.force_characteristic_kgf:.2f} kgf = {c.force_characteristic:.1f} N")
    table(f"Iterations at F_a = {out['axial_load_kgf']:.4g} kgf ({out['axial_load_N']:.4g} N)" + (" — legacy rounding" if legacy else ""),
          ["k", "x_k [rad]", "α [deg]", "α [D°M′S″]", "ξ_a", "F_a,k [kgf]", "Δ [%]"],
          [[i["k"], f"{i['x_rad']:.7f}", f"{i['contact_angle_deg']:.6f}", i["contact_angle_dms"],
            f"{i['axial_displacement_ratio']:.7f}", f"{i['axial_load_kgf']:.5f}", f"{i['error_percent']:.3g}"]
           for i in out["iterations"]])
    console.print(f"operating contact angle {out['operating_contact_angle_deg']:.6f}° ({out['operating_contact_angle_dms']}), "
                  f"+{out['contact_angle_increment_deg']:.4f}° over α0; axial displacement {out['axial_displacement_um']:.3f} µm; "
                  f"ball load {out['ball_load_N']:.4g} N ({out['ball_load_kgf']:.4g} kgf)", highlight=False)


def stand_load(
    speed: Annotated[str, typer.Option("--speed", "-n", help="Inner-ring speed: '3000 rpm', or a list '1000,3000,10000rpm'.")],
    bearing: BearingName = None, bearing_file: BearingFile = None, catalog: CatalogFile = None,
    balls: Balls = None, ball_diameter: BallDiameter = None, pitch_diameter: PitchDiameter = None,
    inner_groove_radius: InnerRadius = None, outer_groove_radius: OuterRadius = None,
    inner_conformity: InnerConformity = None, outer_conformity: OuterConformity = None,
    contact_angle: ContactAngle = None, radial_clearance: Clearance = None, ball_material: BallMaterial = None,
    json_out: JsonFlag = False,
):
    """Minimum axial load against gyroscopic slip on a test stand, and the +20 % maximum (the test-stand method)."""

    from .. import stand, tables
    b = resolve_bearing(bearing, bearing_file, catalog, balls, ball_diameter, pitch_diameter, inner_groove_radius,
                        outer_groove_radius, inner_conformity, outer_conformity, contact_angle, radial_clearance,
                        ball_material)
    z, d, dm, a = b.require("n_balls", "ball_diameter", "pitch_diameter", "contact_angle")
    speeds = parse_speeds(speed, pitch_diameter=dm)
    res = stand.min_axial_load(speeds, z, d, dm, a)
    rows = tables.rows(tables.stand_load(speeds, res))
    if json_out:
        echo = inputs_echo(b, contact_angle_deg=math.degrees(a))
        emit_json(dict(echo, **rows[0]) if len(rows) == 1 else dict(echo, cases=rows))
        return
    table(f"Bearing {b.designation}: axial load on the stand (α = {math.degrees(a):g}°)",
          ["speed [rpm]", "min [kgf]", "min [N]", "max +20 % [kgf]", "max [N]"],
          [[f"{r['speed_rpm']:g}", f"{r['min_axial_load_kgf']:.4g}", f"{r['min_axial_load_N']:.4g}",
            f"{r['max_axial_load_kgf']:.4g}", f"{r['max_axial_load_N']:.4g}"] for r in rows])


#: The ``axial-angle`` and ``stand-load`` commands, as the application adds them.
COMMANDS = {"axial-angle": axial_angle, "stand-load": stand_load}

"""Command line of the test-stand method (spec 000): ``axial-angle`` and ``stand-load``.

Commands
--------
COMMANDS   the ``axial-angle`` and ``stand-load`` commands, by name (the application adds them)
"""

from ._common import (
    BearingFile,
    CatalogFile,
    JsonFlag,
    console,
    emit_json,
    print_warnings,
    table,
)
from ._options import command

__all__ = ["COMMANDS"]


def axial_angle(given, *, bearing_file: BearingFile = None, catalog: CatalogFile = None,
                json_out: JsonFlag = False):
    """Operating contact angle under axial load (the test-stand method): C*, x0, Newton iterations, displacement."""
    import numpy as np

    from ..calculations import _reading as _inputs
    from ..calculations import stand as calculation
    out = calculation.document(_inputs.request("axial-angle", given), bearing_file=bearing_file,
                               catalog=catalog)
    hertz, legacy = given["hertz"], given["legacy"]
    if json_out:
        emit_json(out)
        return
    if "cases" not in out:
        _print_single(out, hertz, legacy)
        print_warnings(out.get("warnings", []))
        return
    cases = out["cases"]
    cstar = np.broadcast_to(out["load_deflection_constant_kgf"], len(cases))
    if np.ndim(out["load_deflection_constant_kgf"]) == 0:  # C* at alpha0: one value for all loads, in the title
        title, head, extra = f"{hertz} Hertz, C* = {float(cstar[0]):.2f} kgf", [], [[] for _ in cases]
    else:  # C* at each load's operating angle: a column
        title, head, extra = f"{hertz} Hertz, C* at the operating angle", ["C* [kgf]"], [[f"{v:.2f}"] for v in cstar]
    table(f"Bearing {out['bearing']}: operating contact angle ({title})",
          ["F_a [kgf]", "F_a [N]", "α [deg]", "ξ_a", "δ_a [µm]", "ball load [N]", *head],
          [[f"{x['axial_load_kgf']:.4g}", f"{x['axial_load_N']:.4g}", f"{x['operating_contact_angle_deg']:.5f}",
            f"{x['axial_displacement_ratio']:.6f}", f"{x['axial_displacement_um']:.3f}", f"{x['ball_load_N']:.4g}",
            *e] for x, e in zip(cases, extra)])
    print_warnings(out.get("warnings", []))


def _print_single(out, hertz, legacy):
    """The tables of one load: contact constants, iterations, and the result line."""
    table(f"Bearing {out['bearing']}: contact constants ({hertz} Hertz)", ["quantity", "inner", "outer"], [
        ["Σρ [1/mm]", f"{out['curvature_sum_inner_per_mm']:.7f}", f"{out['curvature_sum_outer_per_mm']:.7f}"],
        ["cos τ", f"{out['cos_tau_inner']:.7f}", f"{out['cos_tau_outer']:.7f}"],
        ["2K/(πμ)", f"{out['delta_star_inner']:.5f}", f"{out['delta_star_outer']:.5f}"],
        ["c [(cm²/kgf)^(2/3)]", f"{out['c_inner_cm2_per_kgf_2_3']:.6e}", f"{out['c_outer_cm2_per_kgf_2_3']:.6e}"],
    ], caption=f"α0 = {out['contact_angle_initial_deg']:g}°, γ = {out['gamma']:.6f}, C* = {out['load_deflection_constant_kgf']:.2f} kgf = {out['load_deflection_constant_N']:.1f} N")
    table(f"Iterations at F_a = {out['axial_load_kgf']:.4g} kgf ({out['axial_load_N']:.4g} N)" + (" — legacy rounding" if legacy else ""),
          ["k", "x_k [rad]", "α [deg]", "α [D°M′S″]", "ξ_a", "F_a,k [kgf]", "Δ [%]"],
          [[i["k"], f"{i['x_rad']:.7f}", f"{i['contact_angle_deg']:.6f}", i["contact_angle_dms"],
            f"{i['axial_displacement_ratio']:.7f}", f"{i['axial_load_kgf']:.5f}", f"{i['error_percent']:.3g}"]
           for i in out["iterations"]])
    console.print(f"operating contact angle {out['operating_contact_angle_deg']:.6f}° ({out['operating_contact_angle_dms']}), "
                  f"+{out['contact_angle_increment_deg']:.4f}° over α0; axial displacement {out['axial_displacement_um']:.3f} µm; "
                  f"ball load {out['ball_load_N']:.4g} N ({out['ball_load_kgf']:.4g} kgf)", highlight=False)


def stand_load(given, *, bearing_file: BearingFile = None, catalog: CatalogFile = None,
               json_out: JsonFlag = False):
    """Minimum axial load against gyroscopic slip on a test stand, and the +20 % maximum (the test-stand method)."""
    from ..calculations import _reading as _inputs
    from ..calculations import stand as calculation
    out = calculation.document(_inputs.request("stand-load", given), bearing_file=bearing_file,
                               catalog=catalog)
    if json_out:
        emit_json(out)
        return
    rows = out.get("cases", [out])
    table(f"Bearing {out['bearing']}: axial load on the stand (α = {out['contact_angle_deg']:g}°)",
          ["speed [rpm]", "min [kgf]", "min [N]", "max +20 % [kgf]", "max [N]"],
          [[f"{r['speed_rpm']:g}", f"{r['min_axial_load_kgf']:.4g}", f"{r['min_axial_load_N']:.4g}",
            f"{r['max_axial_load_kgf']:.4g}", f"{r['max_axial_load_N']:.4g}"] for r in rows])
    print_warnings(out.get("warnings", []))


#: The ``axial-angle`` and ``stand-load`` commands, as the application adds them.
COMMANDS = {"axial-angle": command("axial-angle", axial_angle), "stand-load": command("stand-load", stand_load)}

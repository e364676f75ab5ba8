"""Worked example of spec 000: bearing 4-1006095 on a vibration test stand at F_a = 2 kgf.

Writes under OUT/stand/: the contact constants and the iteration table (printed-table Hertz and exact
Hertz), the operating angle over a load range, the minimum stand load over speed, and a figure.
The elastic constant is the source's printed one (``elastic_constant="paper"``), so the numbers are the
paper's; the library's default takes it from the bearing's materials (0.1 % softer for its steel).
Usage: python examples/demo_stand.py OUT
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np

from bearinglab import catalog, kinematics, stand, tables
from bearinglab.units import KGF, RPM, format_dms


def write_csv(path, header, rows):
    """Write a CSV whole or not at all (rows -> columns for :func:`bearinglab.tables.write_table`)."""
    tables.write_table(dict(zip(header, zip(*rows))), path)


def main(out):
    out = Path(out) / "stand"
    out.mkdir(parents=True, exist_ok=True)
    b = catalog.get("4-1006095")
    fa = 2.0 * KGF
    runs = {mode: stand.stand_analysis(b, fa, hertz=mode, elastic_constant="paper", stiffness_at="free")
            for mode in ("table", "exact")}  # the paper's two columns: both at alpha0
    const_rows = []
    for mode, r in runs.items():
        c = r.constants
        const_rows.append([mode, c.curvature_difference_inner, c.curvature_difference_outer, c.curvature_sum_inner * 1e-3,
                           c.curvature_sum_outer * 1e-3, c.hertz_inner.delta_star, c.hertz_outer.delta_star,
                           c.approach_inner_paper, c.approach_outer_paper, c.force_characteristic_kgf,
                           math.degrees(r.contact_angle), format_dms(r.contact_angle)])
    write_csv(out / "constants.csv", ["hertz", "cos_tau_inner", "cos_tau_outer", "sum_rho_inner_per_mm",
                                      "sum_rho_outer_per_mm", "delta_star_inner", "delta_star_outer",
                                      "c_inner_cm2_per_kgf_2_3", "c_outer_cm2_per_kgf_2_3", "C_star_kgf",
                                      "operating_angle_deg", "operating_angle_dms"], const_rows)
    iter_rows = [[mode, row.k, row.x, math.degrees(row.contact_angle), format_dms(row.contact_angle),
                  row.axial_displacement_ratio, row.axial_load / KGF, row.error_percent]
                 for mode, r in runs.items() for row in r.iterations]
    write_csv(out / "iterations.csv", ["hertz", "k", "x_rad", "angle_deg", "angle_dms", "xi_a", "F_kgf", "delta_percent"],
              iter_rows)

    loads = np.linspace(0.05, 20.0, 400) * KGF
    sweep = stand.stand_analysis(b, loads, elastic_constant="paper")
    nominal = kinematics.characteristic_frequencies(1.0, b.ball_diameter, b.pitch_diameter, b.n_balls, b.contact_angle)
    operating = kinematics.characteristic_frequencies(1.0, b.ball_diameter, b.pitch_diameter, b.n_balls, sweep.contact_angle)
    write_csv(out / "angle_vs_load.csv", ["F_kgf", "F_N", "angle_deg", "axial_displacement_um", "ball_load_N",
                                          "bpfi_order", "bpfo_order", "ftf_order", "bsf_order"],
              [[f / KGF, f, math.degrees(a), d * 1e6, q, bi, bo, ft, bs] for f, a, d, q, bi, bo, ft, bs in
               zip(loads, sweep.contact_angle, sweep.axial_displacement, sweep.ball_load, operating.bpfi,
                   operating.bpfo, operating.ftf, operating.bsf)])
    speeds = np.linspace(0, 20000, 81) * RPM
    load_range = stand.min_axial_load(speeds, b.n_balls, b.ball_diameter, b.pitch_diameter, b.contact_angle)
    write_csv(out / "stand_load.csv", ["speed_rpm", "min_kgf", "max_kgf", "min_N", "max_N"],
              [[n / RPM, lo / KGF, hi / KGF, lo, hi] for n, lo, hi in zip(speeds, load_range.minimum, load_range.maximum)])

    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(1, 3, figsize=(13, 4), constrained_layout=True)
    ax[0].plot(loads / KGF, np.degrees(sweep.contact_angle), color="C0")
    ax[0].axhline(math.degrees(b.contact_angle), color="0.5", ls="--", lw=1, label="free angle α0")
    ax[0].plot([2.0], [math.degrees(runs["exact"].contact_angle)], "o", color="C3", label="worked example, 2 kgf")
    ax[0].set(xlabel="axial load F_a [kgf]", ylabel="operating contact angle [deg]", title="Bearing 4-1006095")
    ax[0].legend()
    ax[1].plot(loads / KGF, (operating.bpfi / nominal.bpfi - 1) * 100, label="BPFI")
    ax[1].plot(loads / KGF, (operating.bpfo / nominal.bpfo - 1) * 100, label="BPFO")
    ax[1].plot(loads / KGF, (operating.bsf / nominal.bsf - 1) * 100, label="BSF")
    ax[1].set(xlabel="axial load F_a [kgf]", ylabel="shift from the nominal-angle value [%]",
              title="Characteristic frequencies move with the load")
    ax[1].legend()
    ax[2].plot(speeds / RPM, load_range.minimum / KGF * 1e3, label="minimum (no gyroscopic slip)")
    ax[2].plot(speeds / RPM, load_range.maximum / KGF * 1e3, "--", label="maximum (+20 %)")
    ax[2].set(xlabel="shaft speed [rpm]", ylabel="axial load [gf]", title="Stand load range")
    ax[2].legend()
    fig.savefig(out / "stand.png", dpi=120)
    plt.close(fig)

    t, e = runs["table"], runs["exact"]
    print(f"bearing 4-1006095, F_a = 2 kgf: C* = {t.constants.force_characteristic_kgf:.2f} kgf (table Hertz), "
          f"{e.constants.force_characteristic_kgf:.2f} kgf (exact)")
    print(f"operating angle {format_dms(t.contact_angle)} (table), {format_dms(e.contact_angle)} (exact); "
          f"x0 = {t.first_approximation:.7f} rad; {len(t.iterations)} rows to 1e-12 rad")
    print(f"BPFI shifts by {(operating.bpfi[np.searchsorted(loads, fa)] / nominal.bpfi - 1) * 100:+.2f} % at 2 kgf")
    print(f"wrote {', '.join(sorted(p.name for p in out.iterdir()))} in {out}")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "out")

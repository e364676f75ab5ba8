"""Friction torque (spec 001): handbook torque of the lab bearings, and the friction-rig lab on data sets S0, S1.

Usage::

    python examples/demo_friction.py OUT

writes under OUT/friction/:

* ``handbook_torque.csv`` and ``handbook_torque.png``: P0, the one-term torque and the two-term torque
  (T0 at 3000 rpm with f0 = 1.5e-7, T_F with the handbook f, c) of the lab bearings 1000095, 18 and 101
  under Q = 2 kg over the tilts 0..90 deg of the rig;
* ``s0/`` and ``s1/``: the full lab reports (report.html, results.json, PNG and SVG plots, CSV tables)
  of the example sessions in ``examples/friction``.
"""

from __future__ import annotations

import csv
import math
import sys
from pathlib import Path

import numpy as np

from bearinglab import catalog, friction, report
from bearinglab.lab import analysis, measurement, rig

HERE = Path(__file__).resolve().parent
RPM = 2 * math.pi / 60


def handbook_table(out):
    tilts = np.arange(0.0, 91.0, 15.0)
    rows = []
    loads = rig.rig_equivalent_load(2.0, np.radians(tilts))  # same for all: radial, Q = 2 kg
    for name in ("1000095", "18", "101"):
        b = catalog.get(name)
        one = friction.one_term(loads.equivalent_load, b.bore)
        two = friction.two_term(
            loads.equivalent_load, 3000 * RPM, b.mean_diameter, b.static_load_rating, 1.5e-7
        )
        for k, beta in enumerate(tilts):
            rows.append(
                [
                    name,
                    beta,
                    float(loads.axial_load[k]),
                    float(loads.radial_load[k]),
                    float(loads.equivalent_load[k]),
                    "x0*Fr+y0*Fa" if loads.combined[k] else "Fr",
                    float(one[k]) * 1e3,
                    float(two.speed_term[k]) * 1e3,
                    float(two.load_term[k]) * 1e3,
                    float(two.torque[k]) * 1e3,
                ]
            )
    path = out / "handbook_torque.csv"
    with open(path, "w", newline="", encoding="utf-8") as fh:
        w = csv.writer(fh)
        w.writerow(
            [
                "bearing",
                "tilt [deg]",
                "F_a [N]",
                "F_r [N]",
                "P0 [N]",
                "P0 branch",
                "T one-term [N*mm]",
                "T0 (3000 rpm, f0 = 1.5e-7) [N*mm]",
                "T_F handbook [N*mm]",
                "T two-term [N*mm]",
            ]
        )
        w.writerows(rows)

    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(figsize=(6.4, 4.2), dpi=150, layout="constrained")
    FigureCanvasAgg(fig)
    ax = fig.add_subplot()
    for colour, name in zip(("#1f5fa8", "#c0392b", "#2e8b57"), ("1000095", "18", "101")):
        sel = [r for r in rows if r[0] == name]
        ax.plot(
            [r[1] for r in sel],
            [r[6] for r in sel],
            "--",
            color=colour,
            label=f"{name}: one-term, μ = 0.0015",
        )
        ax.plot(
            [r[1] for r in sel],
            [r[9] for r in sel],
            "-o",
            color=colour,
            ms=4,
            label=f"{name}: two-term",
        )
    ax.axvline(math.degrees(rig.branch_switch_tilt()), color="0.5", lw=0.8, ls=":")
    ax.set_xlabel("tilt β [deg]")
    ax.set_ylabel("T [N·mm]")
    ax.set_title("Handbook friction torque, Q = 2 kg, n = 3000 rpm (f0 = 1.5e-7)", fontsize=10)
    ax.set_xlim(0, 90)
    ax.set_ylim(0, 1.45 * max(r[9] for r in rows))  # room for the legend above the curves
    ax.grid(True, color="0.88")
    ax.legend(fontsize=7, ncol=2, frameon=False, loc="upper left")
    fig.savefig(out / "handbook_torque.png")
    return rows


def main(argv):
    if len(argv) != 2:
        print(__doc__.split("\n\n")[1].strip(), file=sys.stderr)
        return 2
    out = Path(argv[1]) / "friction"
    out.mkdir(parents=True, exist_ok=True)
    rows = handbook_table(out)
    p0_90 = next(r for r in rows if r[0] == "1000095" and r[1] == 90.0)
    print(
        f"handbook, bearing 1000095, Q = 2 kg, beta = 90 deg: P0 = {p0_90[4]:.2f} N, "
        f"T(one-term) = {p0_90[6]:.6f} N*mm, T_F = {p0_90[8]:.6f} N*mm"
    )
    for name, file in (("s0", "s0_direct.toml"), ("s1", "s1_readings.toml")):
        result = analysis.analyse(measurement.read_session(HERE / "friction" / file))
        files = report.write_report(result, out / name)
        t1, t2, t3 = result.task1, result.task2, result.task3
        print(
            f"{name} ({result.session.bearing.designation}): "
            + ", ".join(
                f"mu({n / RPM:.6g} rpm) = {mu:.6e}"
                for n, mu in zip(t1.shaft_speed, t1.reduced_friction_coefficient)
            )
        )
        print(
            "    "
            + ", ".join(
                f"f0(beta {math.degrees(b):g}) = {f0:.6e}, T_F = {tf * 1e3:.6e} N*mm"
                for b, f0, tf in zip(t2.tilt, t2.speed_term_factor, t2.load_term)
            )
        )
        print(
            "    "
            + ", ".join(
                f"f({n / RPM:.6g} rpm) = {f:.6e}, T0 = {t0 * 1e3:.6e} N*mm"
                for n, f, t0 in zip(t3.shaft_speed, t3.load_term_factor, t3.speed_term)
            )
        )
        print(f"    report: {files.html}")
    print(f"tables and figures are in {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

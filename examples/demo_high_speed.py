"""Worked example of spec 004: Harris's 218 angular-contact ball bearing at high speed under thrust.

Solves the map of spec 004 section 7 (thrust 2.5-45 kN, here from 1.25 kN, speeds 0-15 000 rpm) in one
batched call with the
constants of the reference (2.26e-11, 4.47e-12, K prefactor 2.15e5), compares it with the printed table,
finds the thrust at which the axial displacement changes sign for each speed, and writes under
OUT/high_speed/:

* ``map_218.csv``                 every output of every case (engineering units)
* ``table_7_1.csv``               alpha_i / alpha_e at the printed loads and speeds, with the printed values
* ``sign_change.csv``             the thrust at which delta_a changes sign, per speed
* ``fig2_outer_angle.png``        alpha_e against thrust, one curve per speed (paper fig. 2)
* ``fig3_inner_angle.png``        alpha_i against thrust (paper fig. 3)
* ``fig4_increments.png``         the increments from the static angle, inner and outer (paper fig. 4)
* ``axial_displacement.png``      delta_a against thrust with its sign change marked
* ``map_218.png``                 the four panels together (as ``bearinglab high-speed --plot``)

Usage: python examples/demo_high_speed.py OUT
"""

from __future__ import annotations

import math
import os
import sys
import time
from pathlib import Path

import matplotlib

matplotlib.use(os.environ.get("MPLBACKEND", "Agg"))
import matplotlib.pyplot as plt
import numpy as np

from bearinglab import catalog, plots, quasistatic, tables
from bearinglab.plots.high_speed import plot_map
from bearinglab.units import RPM

#: E' of the rounded K prefactor 2.15e5 N/mm^1.5 of spec 004 eq. (16) [Pa]
E_ROUNDED = 2.15e5 * 1e6 * 3.0 / 2.0**1.5
OPTIONS = {"constants": "harris", "reduced_modulus": E_ROUNDED}
#: spec 004 section 7.1, alpha_i / alpha_e [deg] (rows 2.5, 5, 10, 20, 30, 45 kN; columns 3000-15 000 rpm)
PRINTED = {
    2.5: [(45.796, 34.366), (55.576, 17.206), (58.796, 6.007), (59.935, 2.546)],
    5: [(43.450, 37.695), (50.706, 27.947), (57.710, 12.376), (59.813, 5.204)],
    10: [(42.466, 39.553), (46.565, 34.795), (54.062, 23.139), (59.064, 10.778)],
    20: [(42.344, 40.854), (44.512, 38.504), (49.308, 32.514), (56.099, 21.121)],
    30: [(42.571, 41.558), (44.056, 39.981), (47.455, 36.025), (53.256, 27.808)],
    45: [(42.994, 42.303), (44.013, 41.234), (46.382, 38.596), (50.746, 33.085)],
}
PRINTED_SIGN_CHANGE = {3000: 2.31, 6000: 6.61, 10000: 14.42, 15000: 26.81}  # kN, section 7.2


def save(fig, path):
    """Write a pyplot figure whole or not at all, and close it."""
    plots.save(fig, path)
    plt.close(fig)


def curves(state, speeds_rpm, y, ylabel, title, path, *, static=None, dashed=None, marks=None):
    fa = state.axial_load[:, 0] * 1e-3
    fig, ax = plt.subplots(figsize=(7, 5), constrained_layout=True)
    for j, n in enumerate(speeds_rpm):
        line, = ax.plot(fa, y[:, j], label=f"{n:g} rpm")
        if dashed is not None and n > 0:
            ax.plot(fa, dashed[:, j], ls="--", color=line.get_color())
        if marks is not None and n > 0 and fa[0] <= marks[j] <= fa[-1]:
            ax.plot([marks[j]], [0.0], "o", mfc="white", color=line.get_color())
            ax.annotate(f"{marks[j]:.2f} kN", (marks[j], 0.0), textcoords="offset points", xytext=(4, -13),
                        fontsize=8, color=line.get_color())
    if static is not None:
        ax.plot(fa, static, color="k", lw=0.8, ls=":", label="static α_s")
    if marks is not None:
        ax.axhline(0.0, color="0.5", lw=0.8)
    ax.set(xlabel="thrust F_a [kN]", ylabel=ylabel, title=title)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    save(fig, path)


def main(out):
    out = Path(out) / "high_speed"
    out.mkdir(parents=True, exist_ok=True)
    b218 = catalog.get("B218")
    speeds_rpm = np.array([0.0, 3000.0, 6000.0, 10000.0, 15000.0])
    # every 0.625 kN from 1.25 kN (the map of section 7 starts at 2.5 kN; below it is the 3000-rpm sign change)
    loads = np.linspace(1.25e3, 45e3, 71)
    t = time.perf_counter()
    state = quasistatic.sweep(b218, loads, speeds_rpm * RPM, **OPTIONS)
    elapsed = time.perf_counter() - t
    tables.write_table(tables.high_speed(state), out / "map_218.csv")

    # the printed table of section 7.1
    printed_loads = np.array(sorted(PRINTED)) * 1e3
    ref = quasistatic.sweep(b218, printed_loads, speeds_rpm[1:] * RPM, **OPTIONS)
    rows = {"axial_load_kN": [], "speed_rpm": [], "contact_angle_inner_deg": [], "printed_inner_deg": [],
            "contact_angle_outer_deg": [], "printed_outer_deg": []}
    worst = 0.0
    for i, fa in enumerate(sorted(PRINTED)):
        for j, n in enumerate(speeds_rpm[1:]):
            ai, ae = math.degrees(ref.contact_angle_inner[i, j]), math.degrees(ref.contact_angle_outer[i, j])
            pi_, pe = PRINTED[fa][j]
            worst = max(worst, abs(ai - pi_), abs(ae - pe))
            for key, val in zip(rows, (fa, n, ai, pi_, ae, pe)):
                rows[key].append(val)
    tables.write_table({k: np.array(v) for k, v in rows.items()}, out / "table_7_1.csv")

    # thrust at which delta_a changes sign
    moving = speeds_rpm[1:]
    sign_change = quasistatic.sign_change_thrust(b218, moving * RPM, **OPTIONS)
    tables.write_table({"speed_rpm": moving, "axial_load_kN": sign_change * 1e-3,
                        "printed_kN": np.array([PRINTED_SIGN_CHANGE[int(n)] for n in moving])}, out / "sign_change.csv")

    deg = 180.0 / math.pi
    ai, ae, a_s = state.contact_angle_inner * deg, state.contact_angle_outer * deg, state.static_contact_angle * deg
    curves(state, speeds_rpm, ae, "α_e [deg]", "Outer contact angle (paper fig. 2)", out / "fig2_outer_angle.png",
           static=a_s[:, 0])
    curves(state, speeds_rpm, ai, "α_i [deg]", "Inner contact angle (paper fig. 3)", out / "fig3_inner_angle.png",
           static=a_s[:, 0])
    curves(state, speeds_rpm, ai - a_s, "Δα [deg]",
           "Increments (fig. 4): Δα_i = α_i − α_s solid, Δα_e = α_s − α_e dashed",
           out / "fig4_increments.png", dashed=a_s - ae)
    marks = np.concatenate([[np.nan], sign_change * 1e-3])
    curves(state, speeds_rpm, state.axial_displacement * 1e6, "δ_a [µm]",
           "Axial displacement of the inner ring (○: sign change)", out / "axial_displacement.png", marks=marks)
    plots.save(plot_map(state, title="Bearing 218: high-speed contact angles under thrust (spec 004)",
                        sign_change=np.concatenate([[0.0], sign_change])), out / "map_218.png")

    print(f"218 bearing, {state.converged.size} cases ({len(loads)} thrusts x {len(speeds_rpm)} speeds) in "
          f"{elapsed * 1e3:.0f} ms, {int((~state.converged).sum())} failed")
    print(f"section 7.1 table: largest difference from the printed angles {worst:.1e} deg (tolerance 1e-3)")
    print("sign change of delta_a: " + ", ".join(f"{s * 1e-3:.2f} kN at {n:g} rpm (printed {PRINTED_SIGN_CHANGE[int(n)]})"
                                                 for n, s in zip(moving, sign_change)))
    k = int(np.argmin(np.abs(loads - 20e3)))
    print(f"20 kN, 15000 rpm: alpha_i = {ai[k, -1]:.3f} deg, alpha_e = {ae[k, -1]:.3f} deg, "
          f"friction needed 2M_g/(D Q_e) = {state.friction_coefficient[k, -1]:.3f}")
    print(f"tables and figures in {out}")
    return 0 if worst < 1e-3 and state.converged.all() else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else "out"))

"""Worked examples of the combined-load model, rating life and the SKF friction model.

Usage: python examples/demo_combined.py OUT

1. The deep-groove bearing that MASTA results are published for (Z = 7, D_w = 11.5 mm, D_pw = 43.5 mm,
   f_i = 0.52, f_e = 0.53, E = 210 GPa): displacements, maximum ball load and the ISO/TS 16281 reference
   rating life of the four published cases, next to MASTA's numbers.
2. B218 under a combined radial, axial and moment load, at rest and at 12 000 rpm: load distribution and
   the 5 x 5 stiffness matrix.
3. A back-to-back (DB) and a face-to-face (DF) pair of B218 with the same preload: tilt stiffness.
4. An SKF 61811-2RS1 on grease: the four terms of the SKF model against the measured pair torque.

Writes CSV tables under OUT/combined/.
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np

from bearinglab import catalog, friction, tables
from bearinglab.bearing import BallBearing, Material
from bearinglab.life import rating_life
from bearinglab.quasistatic import combined, sets
from bearinglab.units import RPM

# MASTA's results as quoted by minzhun/ISO16281 (the numbers the validation tests reproduce)
MASTA = [  # case, clearance [m], loads (Fx, Fy, Fz, Mx, My), published delta [um], published L10r [Mrev]
    (1, 0.0, (1000.0, 0, 0, 0, 0), 15.1101, 13163.019),
    (2, 0.0, (0, 0, 1000.0, 0, 0), 133.5381, 2222.7318),
    (3, 10e-6, (1000.0, 0, 0, 0, 0), 21.223, 10795.7948),
    (4, 10e-6, (0, 0, 1000.0, 0, 0), 149.1717, 3115.8781),
]
STEEL_210 = Material("steel (E = 210 GPa)", 210e9, 0.3, 7850.0)


def masta_bearing(clearance):
    extra = {"radial_clearance": clearance} if clearance > 0 else {"contact_angle": 0.0}
    return BallBearing(designation="MASTA deep groove", n_balls=7, ball_diameter=11.5e-3, pitch_diameter=43.5e-3,
                       inner_conformity=0.52, outer_conformity=0.53, type="radial", ball_material=STEEL_210,
                       ring_material=STEEL_210, dynamic_load_rating=23.4e3, **extra)


def masta_cases(out):
    rows = []
    for case, clearance, loads, delta_pub, life_pub in MASTA:
        b = masta_bearing(clearance)
        r = combined.combined_analysis(b, loads)
        axial = loads[2] != 0
        delta = abs(r.displacement[2] if axial else math.hypot(r.displacement[0], r.displacement[1])) * 1e6
        life = rating_life(b, loads, 1000 * RPM, kinematic_viscosity=20e-6, load_distribution=r)
        l10r = float(life.reference_rating_life) / 1e6
        rows.append((case, clearance * 1e6, "delta_z" if axial else "delta_r", delta, delta_pub,
                     float(r.max_ball_load), l10r, life_pub))
        print(f"case {case}: {rows[-1][2]} = {delta:.4f} um (MASTA {delta_pub}), "
              f"L10r = {l10r:.1f} Mrev (MASTA {life_pub})")
    names = ["case", "clearance_um", "displacement", "displacement_um", "masta_displacement_um",
             "max_ball_load_N", "reference_rating_life_Mrev", "masta_reference_rating_life_Mrev"]
    tables.write_table(dict(zip(names, map(np.array, zip(*rows)))), out / "masta_deep_groove.csv")


def b218_distribution(out):
    b = catalog.get("B218")
    loads = np.array([[5e3, 0.0, 10e3, 0.0, 50.0]] * 2)  # Fx, Fy, Fz [N], Mx, My [N m]
    r = combined.combined_analysis(b, loads, np.array([0.0, 12000 * RPM]))
    for k, label in enumerate(("at rest", "12 000 rpm")):
        print(f"B218 {label}: max ball load {float(r.max_ball_load[k]):.0f} N, "
              f"k_xx = {r.stiffness[k, 0, 0] / 1e6:.1f} N/um, k_zz = {r.stiffness[k, 2, 2] / 1e6:.1f} N/um")
    cols = {"azimuth_deg": np.degrees(r.azimuth)}
    for k, label in enumerate(("rest", "12000rpm")):
        cols[f"load_inner_{label}_N"] = r.ball_load_inner[k]
        cols[f"contact_angle_inner_{label}_deg"] = np.degrees(r.contact_angle_inner[k])
        cols[f"contact_angle_outer_{label}_deg"] = np.degrees(r.contact_angle_outer[k])
    tables.write_table(cols, out / "b218_load_distribution.csv")
    tables.write_table({f"row{i}": r.stiffness[0, i] for i in range(5)}, out / "b218_stiffness_at_rest_SI.csv")


def pairs(out):
    b = catalog.get("B218")
    rows = []
    for kind in ("DB", "DF"):
        s = sets.set_analysis(b, [0.0, 0.0, 0.0, 0.0, 0.0], arrangement_kind=kind, spacing=0.1, preload=2e3)
        rows.append((kind, s.stiffness[0, 0] / 1e6, s.stiffness[2, 2] / 1e6, s.stiffness[3, 3]))
        print(f"B218 pair {kind}, 2 kN preload, 100 mm spacing: tilt stiffness {s.stiffness[3, 3]:.3g} N m/rad")
    names = ["arrangement", "k_radial_N_per_um", "k_axial_N_per_um", "k_tilt_Nm_per_rad"]
    tables.write_table(dict(zip(names, map(np.array, zip(*rows)))), out / "b218_pairs.csv")


def skf_61811(out):
    b = catalog.get("61811-2RS1")
    t = friction.skf_for_bearing(b, 6.51, 0.0, 2000 * RPM, 30e-6, lubrication="grease")
    parts = {"rolling": t.rolling_moment, "sliding": t.sliding_moment, "seal": t.seal_moment,
             "drag": t.drag_moment, "total": t.total_moment}
    print(f"SKF 61811-2RS1, 2000 rpm, grease: pair torque {2 * float(t.total_moment):.3f} N m "
          "(measured 0.387 +/- 0.025 N m)")
    tables.write_table({"term": np.array(list(parts)), "moment_Nmm": np.array([float(v) * 1e3 for v in parts.values()])},
                       out / "skf_61811_2rs1.csv")


def main(out):
    out = Path(out) / "combined"
    out.mkdir(parents=True, exist_ok=True)
    masta_cases(out)
    b218_distribution(out)
    pairs(out)
    skf_61811(out)
    print(f"wrote masta_deep_groove.csv, b218_load_distribution.csv, b218_stiffness_at_rest_SI.csv, "
          f"b218_pairs.csv, skf_61811_2rs1.csv in {out}")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "out")

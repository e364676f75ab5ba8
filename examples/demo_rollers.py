"""Worked examples of roller bearings (issue 32): the slice model, a tapered pair, life and friction.

Usage: python examples/demo_rollers.py OUT

1. An NU 208 ECP (the catalog's, its roller set estimated from C0 and the printed raceway diameters) under
   F_r = 15 kN with 30 um clearance, square and misaligned by theta = (-1, 2) mrad: roller loads, lamina pressures (the figure
   docs/img/roller_slice_pressures.png), stiffness and the ISO/TS 16281 reference life.
2. A back-to-back pair of 30208 J2/Q, 120 mm apart, preloaded to 2 kN, under a radial and an axial load.
3. SKF's worked example of a 22208 E in an oil bath (General Catalogue 6000, pp. 104-105).

Writes OUT/rollers/slice_pressures.png and prints the numbers the user guide quotes.
"""

from __future__ import annotations

import sys
import warnings
from pathlib import Path

import numpy as np

from bearinglab import catalog, friction, life, plots
from bearinglab.errors import ValidityWarning
from bearinglab.plots import rollers as roller_plots
from bearinglab.rollers import pair_analysis, roller_analysis
from bearinglab.units import RPM


def misaligned(out):
    b = catalog.get("NU 208 ECP")
    loads = [15e3, 0, 0, 0, 0]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)
        square = roller_analysis(b, loads, radial_clearance=30e-6, prescribed_displacement=[np.nan, np.nan, 0, 0, 0])
        tilted = roller_analysis(b, loads, radial_clearance=30e-6,
                                 prescribed_displacement=[np.nan, np.nan, 0, -1e-3, 2e-3])
        l_square = life.rating_life(b, loads, 1500 * RPM, load_distribution=square)
        l_tilted = life.rating_life(b, loads, 1500 * RPM, load_distribution=tilted)
    for name, r, lf in (("square", square, l_square), ("misaligned", tilted, l_tilted)):
        print(f"{name}: delta_r = {r.displacement[0] * 1e6:.2f} um, Q_max = {r.max_roller_load:.0f} N, "
              f"p_max = {np.max(r.max_pressure) / 1e6:.0f} MPa, k_xx = {r.stiffness[0, 0] / 1e6:.0f} N/um, "
              f"L10 = {lf.basic_rating_life / 1e6:.0f} Mrev, L10r = {lf.reference_rating_life / 1e6:.0f} Mrev")
    print(f"misaligned: the moment that holds it M_x = {tilted.reactions[3]:.1f} N m, M_y = {tilted.reactions[4]:.1f} N m")
    fig = roller_plots.slice_pressures(tilted, title="NU 208 ECP, F_r = 15 kN, 30 um clearance, "
                                                     "misaligned by theta = (-1, 2) mrad")
    plots.save(fig, out / "slice_pressures.png")


def pair():
    b = catalog.get("30208 J2/Q")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)
        r = pair_analysis(b, b, [[0, 0, 0, 0, 0], [8e3, 0, 3e3, 0, 0]], distance=0.12, preload=2000.0)
    print(f"pair: interference {-r.axial_play * 1e6:.2f} um, effective spread {r.effective_spread * 1e3:.1f} mm")
    for k, name in enumerate(("at rest", "F_r 8 kN, F_a 3 kN")):
        print(f"  {name}: F_a = {r.axial_loads[k].round(0)} N, F_r = {r.radial_loads[k].round(0)} N, "
              f"k_zz = {r.stiffness[k, 2, 2] / 1e6:.0f} N/um, k_tilt = {r.stiffness[k, 4, 4] / 1e3:.0f} kN m/rad")


def skf_example():
    m = friction.skf_roller_for_bearing(catalog.get("22208 E"), 2990.0, 100.0, 3500 * RPM, 68e-6,
                                        lubrication="oil-bath", drag_loss_factor=0.3e-4)
    print(f"22208 E: M_rr = {m.rolling_moment * 1e3:.1f}, M_sl = {m.sliding_moment * 1e3:.1f}, "
          f"M_drag = {m.drag_moment * 1e3:.1f}, M = {m.total_moment * 1e3:.1f} N mm")


def main(argv):
    out = Path(argv[1] if len(argv) > 1 else "out") / "rollers"
    out.mkdir(parents=True, exist_ok=True)
    misaligned(out)
    pair()
    skf_example()
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

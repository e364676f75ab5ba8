"""
Operating contact angle on a test stand
=======================================

Bearing 4-1006095 (the worked example of Zaitsev and Voronkin 2009, see :doc:`/theory/test_stand`):
the contact angle under the 2 kgf stand load, first with the handbook Hertz coefficients and the
elastic constant the paper used, then with the library's defaults (exact Hertz, the bearing's
materials, C* at the operating angle), and the angle over a range of loads in one vectorized call.
"""

import math

import matplotlib.pyplot as plt
import numpy as np

from bearinglab import catalog, stand
from bearinglab.units import KGF, to_dms

bearing = catalog.get("4-1006095")
for hertz, elastic_constant in (("table", "paper"), ("exact", None)):
    r = stand.stand_analysis(bearing, 2 * KGF, hertz=hertz, elastic_constant=elastic_constant)
    d, m, s = to_dms(float(r.contact_angle))
    print(f"{hertz:5s} Hertz: C* = {r.constants.force_characteristic_kgf:.2f} kgf, "
          f"alpha = {math.degrees(r.contact_angle):.6f} deg = {d:.0f} deg {m:.0f}' {s:.2f}\"")

# %%
# The batch path solves many loads at once (Newton on all elements together).
r = stand.stand_analysis(bearing, 2 * KGF)
loads = np.linspace(0.05, 10.0, 200) * KGF  # N
alpha = stand.operating_contact_angle(loads, r.constants.force_characteristic, r.free_angle)

fig, ax = plt.subplots(figsize=(6, 3.5), layout="constrained")
ax.plot(loads / KGF, np.degrees(alpha))
ax.axhline(12.0, color="0.6", lw=0.8, ls="--", label="free angle 12°")
ax.plot([2.0], [math.degrees(r.contact_angle)], "o", label="worked example, 2 kgf")
ax.set_xlabel("axial load [kgf]")
ax.set_ylabel("operating contact angle [deg]")
ax.set_title("4-1006095: contact angle under the stand load")
ax.legend()
plt.show()

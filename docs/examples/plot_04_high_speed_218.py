"""
High-speed contact angles of the 218 bearing
============================================

Harris's 218 angular-contact bearing under thrust at speed (see :doc:`/theory/high_speed`): one
batched solve of a thrust × speed grid gives both contact angles and the axial displacement.
"""

import math

import matplotlib.pyplot as plt
import numpy as np

from bearinglab import catalog, quasistatic
from bearinglab.units import RPM

b = catalog.get("B218")
s = quasistatic.high_speed_analysis(b, 20e3, 15000 * RPM)  # steel ball mass, exact E'
print(f"20 kN, 15000 rpm: alpha_i = {math.degrees(s.contact_angle_inner):.3f} deg, "
      f"alpha_e = {math.degrees(s.contact_angle_outer):.3f} deg, "
      f"delta_a = {s.axial_displacement * 1e6:.2f} um")

# %%
# A grid of 40 thrusts × 4 speeds, solved together (each case with its own convergence test).
thrust = np.linspace(2.5e3, 45e3, 40)
speeds = np.array([3000.0, 6000.0, 10000.0, 15000.0]) * RPM
m = quasistatic.sweep(b, thrust, speeds)
print("all converged:", bool(m.converged.all()))

fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(9, 3.5), layout="constrained")
for j, n in enumerate(speeds):
    line, = ax1.plot(thrust / 1e3, np.degrees(m.contact_angle_inner[:, j]),
                     label=f"{n / RPM:.0f} rpm")
    ax1.plot(thrust / 1e3, np.degrees(m.contact_angle_outer[:, j]), color=line.get_color(), ls="--")
    ax2.plot(thrust / 1e3, m.axial_displacement[:, j] * 1e6, color=line.get_color())
ax1.plot(thrust / 1e3, np.degrees(m.static_contact_angle[:, 0]), color="0.4", lw=0.8, label="static")
ax1.set_xlabel("thrust [kN]")
ax1.set_ylabel("α_i (solid), α_e (dashed) [deg]")
ax1.legend(fontsize="small")
ax2.axhline(0.0, color="0.6", lw=0.8)
ax2.set_xlabel("thrust [kN]")
ax2.set_ylabel("axial displacement δ_a [µm]")
plt.show()

"""
Mounted clearance: a DB pair with warm inner rings, and life against the shaft fit
==================================================================================

Two worked examples of :mod:`bearinglab.mounting` (theory: :doc:`/theory/clearance`).

1. A back-to-back (DB) pair of 7218 B bearings (the ``B218`` of the catalog), 100 mm apart, assembled
   with 1 kN of preload on js5 / JS6 seats (P4). In the running spindle the inner rings and shaft are
   warmer than the outer rings and housing: the rings' radial growth takes clearance, the spacers keep
   the rings' axial positions, so the preload rises; the shaft's axial growth between the bearings
   gives some of it back (in DB). The axial stiffness rises with it.
2. A 6205 of clearance class C3 under 2 kN radial load at 3000 rpm: the probable operating clearance
   after the shaft fit (h5 ... m5) and 10 K between the rings, and the ISO/TS 16281 reference life
   L10r the load distribution gives at that clearance (groove radii assumed, see below).
"""

import matplotlib.pyplot as plt
import numpy as np

from bearinglab import catalog, internal_clearance
from bearinglab.life import rating_life
from bearinglab.mounting import chain, fits, preload, tables
from bearinglab.quasistatic import sets

T0 = chain.T_REF
b = catalog.get("B218")
d, big = b.bore, b.outside_diameter
inner = fits.inner_interference(tables.field_limits("js5", d), tables.bore_limits(d, "P4"))
outer = fits.outer_interference(tables.outside_diameter_limits(big, "P4"), tables.field_limits("JS6", big))
m = chain.mounting_of(b)
assembled = sets.set_analysis(b, [0.0] * 5, arrangement_kind="DB", spacing=0.1, preload=1000.0)

warmer = np.arange(0.0, 21.0, 2.5)  # inner ring and shaft above the outer ring and housing [K]
force, stiffness = [], []
for dt in warmer:
    c = chain.Conditions(inner_temperature=T0 + 20 + dt, outer_temperature=T0 + 20)
    r = chain.operating_range((b.radial_clearance, b.radial_clearance), inner, outer, m, c).probable
    loss = float(r.fit_reduction + r.thermal_reduction + r.centrifugal_reduction)
    e, clr = preload.operating_interference(b, assembled.preload_displacement, loss, arrangement_kind="DB",
                                            spacing=0.1, shaft_temperature=T0 + 20 + dt,
                                            housing_temperature=T0 + 20)
    st = sets.set_analysis(b.replace(radial_clearance=clr), [0.0] * 5, arrangement_kind="DB", spacing=0.1,
                           preload_displacement=e)
    force.append(abs(float(np.asarray(st.bearing_loads)[0][2])))
    stiffness.append(float(np.asarray(st.stiffness)[2, 2]) * 1e-6)
for dt, f, k in zip(warmer, force, stiffness):
    print(f"inner rings +{dt:4.1f} K: preload {f:7.0f} N, axial stiffness {k:6.1f} N/um")

# %%
# The preload and the set's axial stiffness against the temperature difference.
fig, ax = plt.subplots(figsize=(6, 3.5), layout="constrained")
ax.plot(warmer, force, "o-", label="preload [N]")
ax.set_xlabel("inner rings warmer than outer rings [K]")
ax.set_ylabel("preload [N]")
ax2 = ax.twinx()
ax2.plot(warmer, stiffness, "s--", color="C1", label="axial stiffness [N/µm]")
ax2.set_ylabel("axial stiffness k_zz [N/µm]")
ax.set_title("DB pair of 7218 B, js5/JS6, P4, 1 kN assembled")

# %%
# Life against the shaft fit: the probable operating clearance of a 6205 C3 and its reference life.
# the catalog gives no groove radii for the 6205: this example ASSUMES f_i = 0.52, f_o = 0.53, inside the usual
# design range of deep-groove conformities (0.515-0.54, Harris & Kotzalas ch. 2)
g = catalog.get("6205-2RS").replace(inner_conformity=0.52, outer_conformity=0.53, contact_angle=0.0)
lo, hi = internal_clearance.radial_clearance_range(g.bore, "C3")
mg = chain.mounting_of(g)
og = fits.outer_interference(tables.outside_diameter_limits(g.outside_diameter),
                             tables.field_limits("H7", g.outside_diameter))
cond = chain.Conditions(inner_temperature=T0 + 50, outer_temperature=T0 + 40, speed=3000 * np.pi / 30)
names, clearance, life = ["h5", "j5", "k5", "m5"], [], []
for f in names:
    ig = fits.inner_interference(tables.field_limits(f, g.bore), tables.bore_limits(g.bore))
    e = float(chain.operating_range((lo, hi), ig, og, mg, cond).probable.operating_clearance)
    clearance.append(e * 1e6)
    r = rating_life(g.replace(radial_clearance=e), [2000.0, 0, 0, 0, 0], 3000 * np.pi / 30,
                            kinematic_viscosity=20e-6)  # 20 cSt at the operating temperature
    life.append(float(r.reference_rating_life) / 1e6)  # revolutions -> Mrev
    print(f"{f}: operating clearance {e * 1e6:5.2f} um, L10r {life[-1]:8.1f} Mrev")

fig, ax = plt.subplots(figsize=(6, 3.5), layout="constrained")
ax.bar(names, life)
for x, (e, l10) in enumerate(zip(clearance, life)):
    ax.annotate(f"{e:.1f} µm", (x, l10), ha="center", va="bottom")
ax.set_xlabel("shaft fit (6205 C3, H7 housing, inner ring +10 K)")
ax.set_ylabel("reference life L10r [Mrev]")
plt.show()

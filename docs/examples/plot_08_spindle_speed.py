"""
A spindle bearing at rising speed: temperature, viscosity, film, kappa and life
===============================================================================

An SKF 7210 BECBP (the ``7210 BE`` of the catalog: 50 x 90 x 20 mm, 40 deg) carries 6 kN radial and
3 kN axial, lubricated by an oil jet of ISO VG 32 (viscosity index 95) at
0.3 l/min entering at 30 degC; the housing sheds heat to a 20 degC ambient through ISO 15312's reference
conductance of the bearing. As the speed rises from 1000 to 12 000 rpm:

1. the thermal balance (:func:`bearinglab.thermal.thermal_balance`) gives the steady temperature where
   the SKF friction power equals the heat carried away (theory: :doc:`/theory/thermal`);
2. the oil's viscosity follows that temperature (ASTM D341);
3. the Hamrock-Dowson film at every ball contact (:func:`bearinglab.film.film_analysis`, loads solved at
   speed) uses the viscosity at that temperature (theory: :doc:`/theory/film`);
4. kappa = nu / nu1 and L_nm of ISO 281 (:func:`bearinglab.life.rating_life`) follow.

The film thickens with speed at first (the entrainment speed), then the warmer, thinner oil takes the
gain back: h_min peaks near 4000 rpm. kappa peaks earlier (nu1 falls only as n^-0.5, nu faster once the
bearing warms) and falls below 1 above 10 000 rpm, where a_ISO drops and L_nm falls much faster than the
1/n of the revolutions. The ISO 15312 thermal reference speed of the bearing by the same SKF model (an
oil bath, no drag loss: 6241 rpm against SKF's rating of 9000 rpm, within the 0.64-0.83 band of the
model over SKF's 72 B / 73 B rows) is marked for scale.

The SKF geometry constants of 40 deg single-row angular-contact bearings are given here explicitly (SKF
General Catalogue 6000/I RU (2006), table 3 of the frictional moment: R1 = 5.03e-7, R2 = 1.97,
R3 = 1.90e-12, S1 = 1.30e-2, S2 = 0.68, S3 = 1.91e-12); the internal geometry of the catalog's bearing is
an estimate (a warning says so).
"""

import warnings

import matplotlib.pyplot as plt
import numpy as np

from bearinglab import catalog, film, thermal
from bearinglab.friction import SKFConstants
from bearinglab.life import rating_life
from bearinglab.ratings import lubrication
from bearinglab.units import RPM

warnings.simplefilter("ignore")  # estimated internal geometry, pressure-viscosity estimate: said above

b = catalog.get("7210 BE")
constants = SKFConstants(r1=5.03e-7, r2=1.97, s1=1.30e-2, s2=0.68, r3=1.90e-12, s3=1.91e-12)
fr, fa = 6000.0, 3000.0
rpm = np.array([1000.0, 2000.0, 3000.0, 4500.0, 6000.0, 8000.0, 10000.0, 12000.0])
w = rpm * RPM
nu40 = lubrication.iso_vg_viscosity(32)
nu100 = lubrication.viscosity_100_from_index(nu40, 95.0)
density, heat_capacity = 870.0, 1950.0  # a mineral oil: typical values, estimates
jet = thermal.oil_flow_conductance(0.3e-3 / 60, density, heat_capacity)

bal = thermal.thermal_balance(b, fr, fa, w, 293.15, nu40, nu100, oil_flow_conductance=jet,
                              oil_inlet_temperature=303.15, lubrication="oil-jet", constants=constants)
nu = bal.kinematic_viscosity
films = film.film_analysis(b, [fr, 0.0, fa, 0.0, 0.0], w, nu * density)
life = rating_life(b, [fr, 0.0, fa, 0.0, 0.0], w, kinematic_viscosity=nu, load_distribution=False)
ref = thermal.thermal_reference_speed(b, constants=constants)

for k in range(rpm.size):
    print(f"{rpm[k]:6.0f} rpm: T {bal.temperature[k] - 273.15:5.1f} degC, nu {nu[k] * 1e6:5.1f} mm2/s, "
          f"h_min {films.minimum_film[k] * 1e6:5.3f} um, kappa {life.viscosity_ratio[k]:5.2f}, "
          f"L_nm {life.modified_rating_life_duration[k] / 3600:8.0f} h")
print(f"ISO 15312 thermal reference speed (SKF model, no bath drag): {ref.speed / RPM:.0f} rpm "
      f"(SKF's catalogue: 9000 rpm)")

# %%
# Temperature and viscosity, then film and kappa, then life, against the speed.
fig, axes = plt.subplots(3, 1, figsize=(6.5, 8), sharex=True, layout="constrained")
ax = axes[0]
ax.plot(rpm, bal.temperature - 273.15, "o-", color="C3")
ax.set_ylabel("bearing temperature [°C] (o)", color="C3")
ax2 = ax.twinx()
ax2.plot(rpm, nu * 1e6, "s--", color="C0")
ax2.set_ylabel("viscosity ν [mm²/s] (□)", color="C0")
ax.set_title("7210 BE, 6 kN radial + 3 kN axial, VG 32 oil jet 0.3 l/min")
ax = axes[1]
ax.plot(rpm, films.minimum_film * 1e6, "o-", color="C2")
ax.set_ylabel("minimum film h_min [µm] (o)", color="C2")
ax2 = ax.twinx()
ax2.plot(rpm, life.viscosity_ratio, "s--", color="C1")
ax2.set_ylabel("κ = ν/ν₁ (□)", color="C1")
ax = axes[2]
ax.semilogy(rpm, life.modified_rating_life_duration / 3600, "o-", color="C4")
ax.set_ylabel("L_nm [h]")
ax.set_xlabel("shaft speed [rpm]")
for a in axes:
    a.axvline(ref.speed / RPM, color="0.6", lw=0.8, ls=":")
axes[0].annotate("ISO 15312 n_θr", (ref.speed / RPM, 0.05), xycoords=("data", "axes fraction"), fontsize=8,
                 color="0.4")

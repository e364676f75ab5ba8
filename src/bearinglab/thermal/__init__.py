r"""Steady bearing temperature: the friction power of the SKF model against the heat carried away.

Modules
-------
heat             the heat shed: ISO 15312's reference surface and heat flow, conductances, P_d(T)
balance          the steady temperature (thermal_balance) and thermal runaway
reference_speed  the thermal reference speed of ISO 15312
rings            ring temperatures from the bearing temperature (the mounted-clearance coupling)

Every public name of these modules is reachable here: ``bearinglab.thermal.thermal_balance``.

Heat carried away
-----------------
reference_surface              A_r = pi B (D + d), the reference heat-emitting surface of a radial bearing
reference_heat_flow_density    q_r of ISO 15312 from A_r
reference_conductance          q_r A_r / (70 - 20) K: the housing's heat conductance of ISO 15312's
                               reference conditions, taken as linear in the temperature rise
oil_flow_conductance           rho Q c_p of an oil jet or circulation
heat_dissipated                P_d = G (T - T_ambient) + G_oil (T - T_oil,in)

Balance
-------
thermal_balance                T where M(nu(T)) omega = P_d(T), batched; runaway when there is none
ThermalBalance                 its result

Thermal reference speed (ISO 15312)
-----------------------------------
reference_heat_flow            q_r A_r: the heat a bearing sheds at ISO 15312's reference conditions
thermal_reference_speed        n_theta_r where the SKF friction power at the reference load and viscosity
                               equals that heat flow
ThermalReferenceSpeed          its result

Ring temperatures (coupling to the mounted clearance)
-----------------------------------------------------
ring_temperatures              inner and outer ring from the lumped bearing temperature and a split
clearance_conditions           the same as :class:`bearinglab.mounting.chain.Conditions`
RingTemperatures               their result

The friction moment is :func:`bearinglab.friction.skf_for_bearing` at the viscosity nu(T) of the oil
(ASTM D341 through nu40 and nu100, :mod:`bearinglab.ratings.lubrication`); M rises as the oil cools,
P_d as the bearing heats, so the balance has one root between the ambient and a safe maximum when it
has any.

References
----------
.. [1] ISO 15312:2003, *Rolling bearings - Thermal speed rating - Calculation and coefficients*:
   the reference conditions (bearing 70 degC, ambient 20 degC), the reference heat-emitting surface
   A_r = pi B (D + d) of radial bearings and the reference heat flow density q_r = 16 kW/m^2 for
   A_r <= 50 000 mm^2, q_r = 16 (A_r / 50 000 mm^2)^-0.34 kW/m^2 above.
.. [2] SKF, *Rolling bearings*, catalogue PUB BU/P1 17000 EN, 2018, "Friction" (the frictional moment)
   and "Speeds" (the thermal reference speed and its heat balance).
.. [3] T. A. Harris and M. N. Kotzalas, *Advanced Concepts of Bearing Technology*, 5th ed., CRC Press,
   2006, ch. 6 (friction heat generation and the thermal balance of a bearing).
.. [4] Schaeffler, *Rolling bearings*, catalogue HR 1, 2006, pp. 62-65, "Speeds": ISO 15312's reference
   conditions (ambient 20 degC, outer ring 70 degC, P_1r = 0.05 C_0r, 12 mm^2/s (ISO VG 32) for radial
   bearings), q_r = 0.016 W/mm^2 for A_r <= 50 000 mm^2 and 0.016 (A_r/50 000)^-0.34 W/mm^2 above
   (radial bearings), A_r = pi B (D + d); DIN 732's heat flow through the seats Q_S = k_q A_r dT
   (linear in the temperature rise; k_q 0.2-1.0e-6 kW/(mm^2 K) for A_r up to 25 000 mm^2).
.. [5] SKF, "Reference speeds" (skf.com, rolling bearings, principles, speeds): ISO 15312:2003's reference
   conditions, the bearing temperature "measured on the bearing stationary outer ring", oil bath up to
   the middle of the lowest rolling element; bearings with contact seals are not rated.
.. [6] KRW, *Rolling bearings* catalogue, "Bearing clearance", p. 95: the radial clearance is reduced "when
   the inner ring becomes warmer than the outer ring, which is usually the case"; a temperature
   difference above 10 K calls for a larger clearance group than Normal.
"""


from . import balance, heat, reference_speed, rings
from .balance import ThermalBalance, thermal_balance
from .heat import (
    REFERENCE_CONDITIONS,
    heat_dissipated,
    oil_flow_conductance,
    reference_conductance,
    reference_heat_flow,
    reference_heat_flow_density,
    reference_surface,
)
from .reference_speed import ThermalReferenceSpeed, thermal_reference_speed
from .rings import (
    RING_TEMPERATURE_DIFFERENCE,
    RingTemperatures,
    clearance_conditions,
    ring_temperatures,
)

__all__ = [
    "REFERENCE_CONDITIONS",
    "RING_TEMPERATURE_DIFFERENCE",
    "RingTemperatures",
    "ThermalBalance",
    "ThermalReferenceSpeed",
    "balance",
    "clearance_conditions",
    "heat",
    "heat_dissipated",
    "oil_flow_conductance",
    "reference_conductance",
    "reference_heat_flow",
    "reference_heat_flow_density",
    "reference_speed",
    "reference_surface",
    "ring_temperatures",
    "rings",
    "thermal_balance",
    "thermal_reference_speed",
]

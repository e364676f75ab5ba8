r"""The heat a bearing sheds: ISO 15312's reference surface and heat flow, the housing's conductance, oil flow.

Heat carried away
-----------------
reference_surface              A_r = pi B (D + d), the reference heat-emitting surface of a radial bearing
reference_heat_flow_density    q_r of ISO 15312 from A_r
reference_heat_flow            q_r A_r: the heat a bearing sheds at ISO 15312's reference conditions
reference_conductance          q_r A_r / (70 - 20) K: the housing's heat conductance of ISO 15312's
                               reference conditions, taken as linear in the temperature rise
oil_flow_conductance           rho Q c_p of an oil jet or circulation
heat_dissipated                P_d = G (T - T_ambient) + G_oil (T - T_oil,in)

Constants
---------
REFERENCE_CONDITIONS           ISO 15312's reference conditions

References are those of :mod:`bearinglab.thermal`.
"""

from __future__ import annotations

import numpy as np

from .._validate import check_nonnegative, check_positive

__all__ = [
    "REFERENCE_CONDITIONS",
    "heat_dissipated",
    "oil_flow_conductance",
    "reference_conductance",
    "reference_heat_flow",
    "reference_heat_flow_density",
    "reference_surface",
]

#: ISO 15312 [1]: reference bearing temperature and ambient [K], the limit of A_r of the constant heat
#: flow density [m^2], that density [W/m^2] and the exponent of its decrease above the limit (radial
#: bearings); the reference load of a radial bearing as a fraction of C_0r [-] and the oil's kinematic
#: viscosity at the reference temperature [m^2/s]. All checked against Schaeffler HR 1 (2006), p. 62 [4]
#: (q_r = 0.016 W/mm^2, 0.016 (A_r/50 000)^-0.34 W/mm^2, P_1r = 0.05 C_0r, 12 mm^2/s, ISO VG 32) and
#: SKF's "Reference speeds" [5] (70 degC bearing, 20 degC ambient, 0.05 C0, 12 mm^2/s at 70 degC).
REFERENCE_CONDITIONS = {"bearing_temperature": 343.15, "ambient": 293.15, "surface_limit": 50_000e-6,
                        "heat_flow_density": 16e3, "exponent": -0.34, "load_ratio": 0.05,
                        "viscosity": 12e-6}


def reference_surface(bore, outside_diameter, width):
    r"""Reference heat-emitting surface A_r = pi B (D + d) of a radial bearing (ISO 15312 [1]).

    Parameters
    ----------
    bore, outside_diameter, width : array_like
        d, D and B. [m]

    Returns
    -------
    ndarray
        A_r. [m^2]

    Examples
    --------
    >>> print(f"{reference_surface(0.025, 0.052, 0.015) * 1e6:.1f} mm^2")
    3628.5 mm^2
    """
    d = check_positive("bore", bore, "m")
    big = check_positive("outside_diameter", outside_diameter, "m")
    b = check_positive("width", width, "m")
    return (np.pi * b * (big + d))[()]


def reference_heat_flow_density(reference_surface):
    r"""Reference heat flow density q_r of ISO 15312 [1] for a reference surface A_r.

    Parameters
    ----------
    reference_surface : array_like
        A_r. [m^2]

    Returns
    -------
    ndarray
        q_r: 16 kW/m^2 up to A_r = 50 000 mm^2, then 16 (A_r / 50 000 mm^2)^-0.34 kW/m^2. [W/m^2]

    Examples
    --------
    >>> print(reference_heat_flow_density([0.01, 0.2]).round(1).tolist())
    [16000.0, 9986.6]
    """
    a = check_positive("reference_surface", reference_surface, "m^2")
    c = REFERENCE_CONDITIONS
    return np.where(a <= c["surface_limit"], c["heat_flow_density"],
                    c["heat_flow_density"] * (a / c["surface_limit"]) ** c["exponent"])[()]


def reference_conductance(bore, outside_diameter, width):
    r"""Heat conductance from the bearing to the ambient of ISO 15312's reference conditions.

    Parameters
    ----------
    bore, outside_diameter, width : array_like
        d, D and B. [m]

    Returns
    -------
    ndarray
        G = q_r A_r / (70 degC - 20 degC). [W/K]

    Notes
    -----
    ISO 15312 [1] fixes the heat flow q_r A_r that a bearing in a reference housing carries away at
    70 degC with a 20 degC ambient. Dividing by those 50 K makes it a conductance, which assumes the
    heat flow proportional to the temperature rise (conduction through the housing and shaft;
    convection and radiation are not quite linear). This is the model's assumption, not the
    standard's: a measured conductance or thermal resistance of the real housing is better.

    Examples
    --------
    >>> print(f"{reference_conductance(0.025, 0.052, 0.015):.4f} W/K")
    1.1611 W/K
    """
    a = reference_surface(bore, outside_diameter, width)
    c = REFERENCE_CONDITIONS
    return (reference_heat_flow_density(a) * a / (c["bearing_temperature"] - c["ambient"]))[()]


def oil_flow_conductance(volume_flow, density, specific_heat):
    r"""Heat carried by an oil flow per kelvin of its temperature rise, rho Q c_p.

    Parameters
    ----------
    volume_flow : array_like
        Q >= 0. [m^3/s]
    density : array_like
        rho. [kg/m^3]
    specific_heat : array_like
        c_p of the oil, about 1.9-2.1 kJ/(kg K) for mineral oils. [J/(kg K)]

    Returns
    -------
    ndarray
        G_oil. [W/K]

    Examples
    --------
    >>> print(f"{oil_flow_conductance(1e-3 / 60, 870.0, 1950.0):.3f} W/K")
    28.275 W/K
    """
    q = check_nonnegative("volume_flow", volume_flow, "m^3/s")
    rho = check_positive("density", density, "kg/m^3")
    cp = check_positive("specific_heat", specific_heat, "J/(kg K)")
    return (rho * q * cp)[()]


def heat_dissipated(temperature, ambient, conductance, *, oil_flow_conductance=0.0, oil_inlet_temperature=None):
    r"""Heat carried away from a bearing at a temperature.

    Parameters
    ----------
    temperature : array_like
        Bearing temperature T. [K]
    ambient : array_like
        T_ambient. [K]
    conductance : array_like
        G to the ambient (1 / thermal resistance). [W/K]
    oil_flow_conductance : array_like, optional
        G_oil = rho Q c_p of an oil flow through the bearing. [W/K]
    oil_inlet_temperature : array_like, optional
        T_oil,in; the ambient when not given. [K]

    Returns
    -------
    ndarray
        P_d = G (T - T_ambient) + G_oil (T - T_oil,in): the oil leaves at the bearing's temperature. [W]

    Examples
    --------
    >>> print(f"{heat_dissipated(343.15, 293.15, 1.2, oil_flow_conductance=10.0):.1f} W")
    560.0 W
    """
    t = check_positive("temperature", temperature, "K")
    ta = check_positive("ambient", ambient, "K")
    g = check_nonnegative("conductance", conductance, "W/K")
    go = check_nonnegative("oil_flow_conductance", oil_flow_conductance, "W/K")
    tin = ta if oil_inlet_temperature is None else check_positive("oil_inlet_temperature", oil_inlet_temperature, "K")
    return (g * (t - ta) + go * (t - tin))[()]


def reference_heat_flow(bore, outside_diameter, width):
    r"""Heat flow a radial bearing sheds at ISO 15312's reference conditions, q_r A_r.

    Parameters
    ----------
    bore, outside_diameter, width : array_like
        d, D and B. [m]

    Returns
    -------
    ndarray
        :math:`\Phi_r = q_r A_r` (:func:`reference_heat_flow_density`, :func:`reference_surface`) at
        70 degC on the outer ring with a 20 degC ambient [1] [4]. [W]

    Examples
    --------
    >>> print(f"{reference_heat_flow(0.025, 0.052, 0.015):.2f} W")
    58.06 W
    """
    a = reference_surface(bore, outside_diameter, width)
    return (reference_heat_flow_density(a) * a)[()]

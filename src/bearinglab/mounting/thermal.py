"""Thermal expansion in the mounted-clearance chain: free growth of rings and balls, and of the fits.

REFERENCE_TEMPERATURE      20 degC, the temperature of tolerances and clearances (ISO 1)
expansion                  growth of a diameter from the reference temperature
clearance_loss             loss of diametral clearance by the free expansion of rings and balls
inner_interference_change  change of the inner fit's interference with the shaft and ring temperatures
outer_interference_change  change of the outer fit's interference with the ring and housing temperatures

Temperatures are absolute, in kelvin. Each part expands freely and uniformly with its own coefficient;
the fits then act on the new diameters (:mod:`bearinglab.mounting.chain`).
"""

from __future__ import annotations

import numpy as np

__all__ = ["REFERENCE_TEMPERATURE", "clearance_loss", "expansion", "inner_interference_change",
           "outer_interference_change"]

#: ISO 1:2016: the standard reference temperature of geometrical product specifications, 20 degC. [K]
REFERENCE_TEMPERATURE = 293.15


def expansion(diameter, temperature, thermal_expansion, *, reference=REFERENCE_TEMPERATURE):
    """The free thermal growth of a diameter, alpha (T - T_ref) D.

    Parameters
    ----------
    diameter : array_like
        The diameter at the reference temperature. [m]
    temperature : array_like
        Temperature of the part. [K]
    thermal_expansion : array_like
        Linear expansion coefficient alpha. [1/K]
    reference : float, optional
        Temperature at which ``diameter`` holds. [K]

    Returns
    -------
    ndarray
        Growth of the diameter (negative when colder). [m]

    Examples
    --------
    >>> print(f"{expansion(0.1, 293.15 + 50, 12.5e-6) * 1e6:.1f} um")
    62.5 um
    """
    return (np.asarray(thermal_expansion, dtype=float) * (np.asarray(temperature, dtype=float) - reference)
            * np.asarray(diameter, dtype=float))[()]


def clearance_loss(inner_raceway, outer_raceway, ball_diameter, inner_temperature, outer_temperature,
                   ball_temperature, ring_expansion, ball_expansion):
    r"""The loss of diametral clearance when rings and balls expand freely from the reference temperature.

    Parameters
    ----------
    inner_raceway, outer_raceway : array_like
        Raceway diameters d_i and d_o of the radial clearance e = d_o - d_i - 2 D. [m]
    ball_diameter : array_like
        D. [m]
    inner_temperature, outer_temperature, ball_temperature : array_like
        T_i, T_o, T_b. [K]
    ring_expansion, ball_expansion : array_like
        alpha of the rings and of the balls. [1/K]

    Returns
    -------
    ndarray
        :math:`\Delta d_i + 2\Delta D - \Delta d_o` (positive: less clearance). [m]

    Notes
    -----
    With rings and balls of one material and balls at the mean ring temperature, d_i = d_m - D and
    d_o = d_m + D give the handbook's :math:`\alpha (T_i - T_o) d_m` ([1]_ eq. 8.3 uses the outer
    raceway diameter instead of d_m, a bound).

    References
    ----------
    .. [1] NTN, Ball and Roller Bearings catalogue, section 8 "Bearing internal clearance and
       preload", eq. (8.3).

    Examples
    --------
    >>> t = 293.15
    >>> loss = clearance_loss(0.05, 0.07, 0.01, t + 10, t, t + 5, 12.5e-6, 12.5e-6)
    >>> print(f"{loss * 1e6:.2f} um")  # alpha * 10 K * d_m
    7.50 um
    """
    di = expansion(inner_raceway, inner_temperature, ring_expansion)
    do = expansion(outer_raceway, outer_temperature, ring_expansion)
    db = expansion(ball_diameter, ball_temperature, ball_expansion)
    return (np.asarray(di) + 2.0 * np.asarray(db) - np.asarray(do))[()]


def inner_interference_change(bore, shaft_temperature, shaft_expansion, ring_temperature, ring_expansion):
    """The change of the inner fit's interference: the shaft seat grows with the shaft, the bore with the ring.

    Parameters
    ----------
    bore : array_like
        Bore d. [m]
    shaft_temperature, ring_temperature : array_like
        Temperatures of shaft and inner ring. [K]
    shaft_expansion, ring_expansion : array_like
        Their alpha. [1/K]

    Returns
    -------
    ndarray
        (alpha_s (T_s - 20 degC) - alpha_r (T_i - 20 degC)) d: positive tightens the fit. [m]

    Examples
    --------
    >>> t = 293.15  # an aluminium shaft 30 K warmer than 20 degC in a steel ring at 20 degC
    >>> print(f"{inner_interference_change(0.05, t + 30, 23e-6, t, 12.5e-6) * 1e6:.2f} um")
    34.50 um
    """
    return (np.asarray(expansion(bore, shaft_temperature, shaft_expansion))
            - expansion(bore, ring_temperature, ring_expansion))[()]


def outer_interference_change(outside_diameter, ring_temperature, ring_expansion, housing_temperature,
                              housing_expansion):
    """The change of the outer fit's interference: the ring grows with the ring, the housing bore with the housing.

    Parameters
    ----------
    outside_diameter : array_like
        D. [m]
    ring_temperature, housing_temperature : array_like
        Temperatures of outer ring and housing. [K]
    ring_expansion, housing_expansion : array_like
        Their alpha. [1/K]

    Returns
    -------
    ndarray
        (alpha_r (T_o - 20 degC) - alpha_h (T_h - 20 degC)) D: positive tightens the fit. [m]

    Examples
    --------
    >>> t = 293.15  # a steel ring in an aluminium housing, both at 70 degC: the fit loosens
    >>> print(f"{outer_interference_change(0.09, t + 50, 12.5e-6, t + 50, 23e-6) * 1e6:.2f} um")
    -47.25 um
    """
    return (np.asarray(expansion(outside_diameter, ring_temperature, ring_expansion))
            - expansion(outside_diameter, housing_temperature, housing_expansion))[()]

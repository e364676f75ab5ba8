"""Thick cylinders (Lamé): the pressure of an interference fit and the change of the raceway diameters.

fit_pressure_inner     pressure between an inner ring and a solid or hollow shaft
fit_pressure_outer     pressure between an outer ring and a housing of finite or infinite outside diameter
inner_raceway_growth   growth of the inner ring's modelling diameter under its fit pressure
outer_raceway_shrink   shrink of the outer ring's modelling diameter under its fit pressure

Each ring is a thick cylinder in plane stress: the inner ring from its bore d to the diameter d_1 that
models it, the outer ring from the diameter D_1 that models it to its outside diameter D (see
:mod:`bearinglab.mounting.chain` for which diameters those are). A clearance fit (negative interference)
has no pressure: the formulas are applied to max(interference, 0).
"""

from __future__ import annotations

import numpy as np

from .._validate import check_nonnegative, check_positive

__all__ = ["fit_pressure_inner", "fit_pressure_outer", "inner_raceway_growth", "outer_raceway_shrink"]


def fit_pressure_inner(interference, bore, ring_diameter, shaft_bore, ring_modulus, ring_poisson,
                       shaft_modulus, shaft_poisson):
    r"""The contact pressure of an inner ring fitted on a shaft with a diametral interference.

    Parameters
    ----------
    interference : array_like
        Effective diametral interference; <= 0 gives no pressure. [m]
    bore : array_like
        Bore d of the ring = seat diameter of the shaft. [m]
    ring_diameter : array_like
        Outside diameter d_1 > d of the cylinder that models the ring. [m]
    shaft_bore : array_like
        Bore d_0 of a hollow shaft, 0 <= d_0 < d (0: solid). [m]
    ring_modulus, ring_poisson : array_like
        E and nu of the ring. [Pa], [-]
    shaft_modulus, shaft_poisson : array_like
        E and nu of the shaft. [Pa], [-]

    Returns
    -------
    ndarray
        Fit pressure p >= 0. [Pa]

    Notes
    -----
    Lamé's thick cylinders with the compatibility of the two radial displacements at d ([1]_):

    .. math:: \delta = p\,d\left[\frac{1}{E_r}\left(\frac{d_1^2+d^2}{d_1^2-d^2}+\nu_r\right)
              + \frac{1}{E_s}\left(\frac{d^2+d_0^2}{d^2-d_0^2}-\nu_s\right)\right]

    References
    ----------
    .. [1] R. G. Budynas and J. K. Nisbett, Shigley's Mechanical Engineering Design, 10th ed.,
       McGraw-Hill, 2015, section 3-16 "Press and shrink fits", eq. 3-56.

    Examples
    --------
    >>> p = fit_pressure_inner(20e-6, 0.050, 0.060, 0.0, 2.075e11, 0.3, 2.075e11, 0.3)
    >>> print(f"{p / 1e6:.1f} MPa")
    12.7 MPa
    """
    d = check_positive("bore", bore, "m")
    d1 = check_positive("ring_diameter", ring_diameter, "m")
    d0 = check_nonnegative("shaft_bore", shaft_bore, "m")
    delta = np.maximum(np.asarray(interference, dtype=float), 0.0)
    ring = ((d1**2 + d**2) / (d1**2 - d**2) + ring_poisson) / ring_modulus
    shaft = ((d**2 + d0**2) / (d**2 - d0**2) - shaft_poisson) / shaft_modulus
    return (delta / (d * (ring + shaft)))[()]


def fit_pressure_outer(interference, outside_diameter, ring_diameter, housing_outside_diameter,
                       ring_modulus, ring_poisson, housing_modulus, housing_poisson):
    r"""The contact pressure of an outer ring fitted in a housing with a diametral interference.

    Parameters
    ----------
    interference : array_like
        Effective diametral interference; <= 0 gives no pressure. [m]
    outside_diameter : array_like
        Outside diameter D of the ring = housing bore. [m]
    ring_diameter : array_like
        Inside diameter D_1 < D of the cylinder that models the ring. [m]
    housing_outside_diameter : array_like
        Outside diameter D_h > D of the housing; ``numpy.inf`` for a housing of unbounded wall. [m]
    ring_modulus, ring_poisson : array_like
        E and nu of the ring. [Pa], [-]
    housing_modulus, housing_poisson : array_like
        E and nu of the housing. [Pa], [-]

    Returns
    -------
    ndarray
        Fit pressure p >= 0. [Pa]

    Notes
    -----
    As :func:`fit_pressure_inner`, with the ring inside:

    .. math:: \delta = p\,D\left[\frac{1}{E_h}\left(\frac{D_h^2+D^2}{D_h^2-D^2}+\nu_h\right)
              + \frac{1}{E_r}\left(\frac{D^2+D_1^2}{D^2-D_1^2}-\nu_r\right)\right]

    and (D_h^2 + D^2)/(D_h^2 - D^2) -> 1 for an unbounded housing.

    References
    ----------
    .. [1] R. G. Budynas and J. K. Nisbett, Shigley's Mechanical Engineering Design, 10th ed., 2015,
       eq. 3-56.

    Examples
    --------
    >>> p = fit_pressure_outer(20e-6, 0.090, 0.080, float("inf"), 2.075e11, 0.3, 2.075e11, 0.3)
    >>> print(f"{p / 1e6:.2f} MPa")
    4.84 MPa
    """
    big = check_positive("outside_diameter", outside_diameter, "m")
    d1 = check_positive("ring_diameter", ring_diameter, "m")
    dh = check_positive("housing_outside_diameter", housing_outside_diameter, "m")
    delta = np.maximum(np.asarray(interference, dtype=float), 0.0)
    with np.errstate(invalid="ignore"):
        wall = np.where(np.isinf(dh), 1.0, (dh**2 + big**2) / (dh**2 - big**2))
    housing = (wall + housing_poisson) / housing_modulus
    ring = ((big**2 + d1**2) / (big**2 - d1**2) - ring_poisson) / ring_modulus
    return (delta / (big * (housing + ring)))[()]


def inner_raceway_growth(pressure, bore, ring_diameter, ring_modulus):
    r"""The diametral growth of the outside of a ring pressed from inside (the inner ring on its shaft).

    Parameters
    ----------
    pressure : array_like
        Fit pressure at the bore. [Pa]
    bore : array_like
        Bore d. [m]
    ring_diameter : array_like
        Outside diameter d_1 of the cylinder that models the ring. [m]
    ring_modulus : array_like
        E of the ring. [Pa]

    Returns
    -------
    ndarray
        Increase of d_1, :math:`2 p d^2 d_1 / (E (d_1^2 - d^2))` (Lamé, [1]_). [m]

    References
    ----------
    .. [1] S. P. Timoshenko and J. N. Goodier, Theory of Elasticity, 3rd ed., McGraw-Hill, 1970,
       ch. 4, the thick cylinder under internal pressure.

    Examples
    --------
    >>> p = fit_pressure_inner(20e-6, 0.050, 0.060, 0.0, 2.075e11, 0.3, 2.075e11, 0.3)
    >>> print(f"{inner_raceway_growth(p, 0.050, 0.060, 2.075e11) * 1e6:.3f} um")  # 20 um * 50/60
    16.667 um
    """
    p = np.asarray(pressure, dtype=float)
    d, d1 = np.asarray(bore, dtype=float), np.asarray(ring_diameter, dtype=float)
    return (2.0 * p * d**2 * d1 / (ring_modulus * (d1**2 - d**2)))[()]


def outer_raceway_shrink(pressure, outside_diameter, ring_diameter, ring_modulus):
    r"""The diametral shrink of the inside of a ring pressed from outside (the outer ring in its housing).

    Parameters
    ----------
    pressure : array_like
        Fit pressure at the outside diameter. [Pa]
    outside_diameter : array_like
        Outside diameter D. [m]
    ring_diameter : array_like
        Inside diameter D_1 of the cylinder that models the ring. [m]
    ring_modulus : array_like
        E of the ring. [Pa]

    Returns
    -------
    ndarray
        Decrease of D_1, :math:`2 p D^2 D_1 / (E (D^2 - D_1^2))` (Lamé, [1]_). [m]

    References
    ----------
    .. [1] S. P. Timoshenko and J. N. Goodier, Theory of Elasticity, 3rd ed., 1970, ch. 4.

    Examples
    --------
    >>> p = fit_pressure_outer(20e-6, 0.090, 0.080, float("inf"), 2.075e11, 0.3, 2.075e11, 0.3)
    >>> print(f"{outer_raceway_shrink(p, 0.090, 0.080, 2.075e11) * 1e6:.3f} um")  # 20 um * 80/90
    17.778 um
    """
    p = np.asarray(pressure, dtype=float)
    big, d1 = np.asarray(outside_diameter, dtype=float), np.asarray(ring_diameter, dtype=float)
    return (2.0 * p * big**2 * d1 / (ring_modulus * (big**2 - d1**2)))[()]

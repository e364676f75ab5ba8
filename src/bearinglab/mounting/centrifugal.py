"""Speed: the centrifugal growth of a rotating ring or shaft (rotating-disc elasticity).

disc_growth         diametral growth of a rotating annular (or solid) disc at a given diameter
inner_fit_loss      the interference the inner fit loses at speed (ring bore grows more than the shaft)

Rings and shafts are discs in plane stress; growth goes as the square of the speed.
"""

from __future__ import annotations

import numpy as np

__all__ = ["disc_growth", "inner_fit_loss"]


def disc_growth(speed, inner_diameter, outer_diameter, at_diameter, density, elastic_modulus, poisson_ratio):
    r"""The diametral growth of a free rotating disc (a ring, or a solid or hollow shaft) at one diameter.

    Parameters
    ----------
    speed : array_like
        Angular speed omega. [rad/s]
    inner_diameter : array_like
        Bore of the disc, 0 for a solid disc. [m]
    outer_diameter : array_like
        Outside diameter. [m]
    at_diameter : array_like
        Where the growth is wanted, between the two. [m]
    density, elastic_modulus, poisson_ratio : array_like
        rho, E, nu. [kg/m^3], [Pa], [-]

    Returns
    -------
    ndarray
        2 u(r) with r = at_diameter / 2. [m]

    Notes
    -----
    Timoshenko and Goodier [1]_ section 32, the rotating disc of uniform thickness in plane stress
    with free edges (a the inner, b the outer radius):

    .. math:: u(r) = \frac{\rho\omega^2 r}{8E}\left[(3+\nu)(1-\nu)(a^2+b^2)
              + (3+\nu)(1+\nu)\frac{a^2 b^2}{r^2} - (1-\nu^2) r^2\right]

    which for a = 0 is the solid disc.

    References
    ----------
    .. [1] S. P. Timoshenko and J. N. Goodier, Theory of Elasticity, 3rd ed., McGraw-Hill, 1970,
       section 32 "Rotating disks of uniform thickness", eqs. (f), (g) and (h).

    Examples
    --------
    >>> g = disc_growth(1047.2, 0.05, 0.06, 0.06, 7850.0, 2.075e11, 0.3)  # 10 000 rpm
    >>> print(f"{g * 1e6:.3f} um")
    1.676 um
    """
    w2 = np.asarray(speed, dtype=float) ** 2
    a, b = np.asarray(inner_diameter, dtype=float) / 2, np.asarray(outer_diameter, dtype=float) / 2
    r = np.asarray(at_diameter, dtype=float) / 2
    nu = np.asarray(poisson_ratio, dtype=float)
    with np.errstate(invalid="ignore", divide="ignore"):
        hole = np.where(a > 0, (3 + nu) * (1 + nu) * a**2 * b**2 / np.where(r > 0, r, 1.0) ** 2, 0.0)
    u = density * w2 * r / (8 * np.asarray(elastic_modulus)) * (
        (3 + nu) * (1 - nu) * (a**2 + b**2) + hole - (1 - nu**2) * r**2)
    return (2.0 * u)[()]


def inner_fit_loss(speed, bore, ring_diameter, shaft_bore, ring, shaft):
    """The diametral interference an inner fit loses at speed: the ring bore grows more than the shaft seat.

    Parameters
    ----------
    speed : array_like
        Angular speed of shaft and inner ring. [rad/s]
    bore : array_like
        Bore d = shaft seat diameter. [m]
    ring_diameter : array_like
        Outside diameter d_1 of the cylinder that models the ring. [m]
    shaft_bore : array_like
        Bore of a hollow shaft (0: solid). [m]
    ring, shaft : MountingMaterial
        Materials (density, E, nu are used).

    Returns
    -------
    ndarray
        Growth of the free ring's bore minus growth of the free shaft's seat (>= 0 for one steel). [m]

    Notes
    -----
    Each part rotates as a free disc (:func:`disc_growth`); the difference is the interference lost,
    by superposition with the fit's Lamé solution while the fit holds (pressure > 0). The balls' own
    growth and the ring width's axial stresses are left out.

    Examples
    --------
    >>> from bearinglab.mounting.materials import material
    >>> s = material("steel")
    >>> print(f"{inner_fit_loss(1047.2, 0.05, 0.06, 0.0, s, s) * 1e6:.3f} um")
    1.540 um
    """
    ring_bore = disc_growth(speed, bore, ring_diameter, bore, ring.density, ring.elastic_modulus,
                            ring.poisson_ratio)
    seat = disc_growth(speed, shaft_bore, bore, bore, shaft.density, shaft.elastic_modulus,
                       shaft.poisson_ratio)
    return (np.asarray(ring_bore) - seat)[()]

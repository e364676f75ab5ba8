r"""Elastohydrodynamic film of one elliptical (ball-raceway) contact.

Contact geometry
----------------
contact_radii                 R_x, R_y of a ball-raceway contact (rolling along x)
ellipticity                   k = a/b from R_x, R_y by the exact Hertz solution (:mod:`bearinglab.hertz`)

Film thickness (Hamrock and Dowson, 1977)
-----------------------------------------
dimensionless_groups          U = eta0 u / (E' R_x), G = alpha E', W = Q / (E' R_x^2)
hamrock_dowson                central and minimum film h_c, h_min of a fully flooded isothermal contact
thermal_reduction_factor      inlet shear heating, phi_T of Gupta et al. (1992); optional

Lubricant and surfaces
----------------------
pressure_viscosity_coefficient   alpha from the dynamic viscosity (Wooster's estimate for mineral oils)
film_parameter                Lambda = h_min / sqrt(Rq_ball^2 + Rq_race^2)
lubrication_regime            "full film" (Lambda >= 3), "mixed" (1 <= Lambda < 3), "boundary" (< 1)
REGIME_THRESHOLDS, REGIMES

All inputs and outputs are SI (N, m, m/s, Pa, Pa s, 1/Pa). The film formulas are curve fits of
numerical isothermal EHL solutions; their range is k = 1 to 8, the speed parameter U over two orders of
magnitude and W over one [1]_.

References
----------
.. [1] B. J. Hamrock and D. Dowson, "Isothermal elastohydrodynamic lubrication of point contacts,
   part III - fully flooded results," J. Lubr. Technol., vol. 99, no. 2, pp. 264-275, 1977,
   doi:10.1115/1.3453074 (eqs. for H_c and H_min).
.. [2] B. J. Hamrock, S. R. Schmid and B. O. Jacobson, *Fundamentals of Fluid Film Lubrication*,
   2nd ed., Marcel Dekker, 2004, ch. 18 (film parameter Lambda and the lubrication regimes) and ch. 24
   (rolling-element bearings: R_x, R_y and the entrainment velocity of a ball bearing).
.. [3] P. K. Gupta, H. S. Cheng, D. Zhu, N. H. Forster and J. B. Schrand, "Viscoelastic effects in
   MIL-L-7808-type lubricant, part I: analytical formulation," Tribol. Trans., vol. 35, no. 2,
   pp. 269-274, 1992, doi:10.1080/10402009208982117 (the inlet shear heating factor, as quoted by
   T. A. Harris and M. N. Kotzalas, *Advanced Concepts of Bearing Technology*, 5th ed., CRC Press,
   2006, ch. 4).
.. [4] G. W. Stachowiak and A. W. Batchelor, *Engineering Tribology*, 4th ed., Butterworth-Heinemann,
   2014, section 2.6 (pressure-viscosity coefficient; the estimate of Wooster, 1957).
"""

from __future__ import annotations

import warnings
from typing import NamedTuple

import numpy as np

from .. import hertz
from .._validate import check_nonnegative, check_positive
from ..errors import InputError, ValidityWarning

__all__ = [
    "REGIMES",
    "REGIME_THRESHOLDS",
    "ContactRadii",
    "DimensionlessGroups",
    "FilmThickness",
    "contact_radii",
    "dimensionless_groups",
    "ellipticity",
    "film_parameter",
    "hamrock_dowson",
    "lubrication_regime",
    "pressure_viscosity_coefficient",
    "thermal_reduction_factor",
]

#: Lambda at which the regime changes: below 1 boundary, 1 to 3 mixed, from 3 full film (Hamrock et
#: al. [2] ch. 18; Harris and Kotzalas use the same bounds).
REGIME_THRESHOLDS = (1.0, 3.0)
#: The regimes, from the thinnest film.
REGIMES = ("boundary", "mixed", "full film")
_K_RANGE = (1.0, 8.0)  # ellipticity over which [1] fitted its formulas


class ContactRadii(NamedTuple):
    """Effective radii of a ball-raceway contact."""

    rx: np.ndarray  # along the rolling direction [m]
    ry: np.ndarray  # across it [m]


class DimensionlessGroups(NamedTuple):
    """The groups of Hamrock and Dowson's formulas."""

    speed: np.ndarray  # U = eta0 u / (E' R_x) [-]
    material: np.ndarray  # G = alpha E' [-]
    load: np.ndarray  # W = Q / (E' R_x^2) [-]


class FilmThickness(NamedTuple):
    """Central and minimum film thickness of a contact."""

    central: np.ndarray  # h_c [m]
    minimum: np.ndarray  # h_min [m]


def contact_radii(ball_diameter, pitch_diameter, conformity, contact_angle, *, race):
    r"""Effective radii R_x (rolling direction) and R_y (across) of a ball-raceway contact.

    Parameters
    ----------
    ball_diameter : array_like
        D. [m]
    pitch_diameter : array_like
        d_m > D. [m]
    conformity : array_like
        f = r / D of that raceway, > 0.5. [-]
    contact_angle : array_like
        alpha of that contact. [rad]
    race : {"inner", "outer"}
        Which raceway.

    Returns
    -------
    ContactRadii
        ``rx``, ``ry``. [m]

    Notes
    -----
    Hamrock et al. [2] ch. 24: :math:`R_x = D (d_m \mp D\cos\alpha) / (2 d_m)` (inner: minus, outer:
    plus) and :math:`R_y = f D / (2f - 1)`.

    Examples
    --------
    >>> r = contact_radii(12.7e-3, 65e-3, 0.52, 0.0, race="inner")
    >>> print(f"{r.rx * 1e3:.4f} {r.ry * 1e3:.4f} mm")
    5.1093 165.1000 mm
    """
    d = check_positive("ball_diameter", ball_diameter, "m")
    dm = check_positive("pitch_diameter", pitch_diameter, "m")
    if np.any(~(dm > d)):
        raise InputError("pitch_diameter must be > ball_diameter [m]")
    f = check_positive("conformity", conformity, "-")
    if np.any(~(f > 0.5)):
        raise InputError(f"conformity must be > 0.5 [-], got {float(np.min(f))!r}")
    sign = {"inner": -1.0, "outer": 1.0}.get(race)
    if sign is None:
        raise InputError(f"race must be one of ['inner', 'outer'], got {race!r}")
    c = np.cos(np.asarray(contact_angle, dtype=float))
    rx = d * (dm + sign * d * c) / (2.0 * dm)
    ry = f * d / (2.0 * f - 1.0)
    rx, ry = np.broadcast_arrays(rx, ry)
    return ContactRadii(rx[()], ry[()])


def ellipticity(rx, ry):
    r"""Ellipticity k = a/b of the Hertz contact of radii R_x <= R_y, from the exact solution.

    Parameters
    ----------
    rx, ry : array_like
        Effective radii along and across the rolling direction, ``ry >= rx``. [m]

    Returns
    -------
    ndarray
        k >= 1 (the semi-axis across rolling over the one along it). [-]

    Notes
    -----
    The curvature difference :math:`F = (1/R_x - 1/R_y)/(1/R_x + 1/R_y)` goes into
    :func:`bearinglab.hertz.ellipticity` (complete elliptic integrals), not into the approximation
    :math:`k = 1.03 (R_y/R_x)^{0.64}` of [1]; the two differ by about 1 % in ball bearings.

    Examples
    --------
    >>> print(f"{ellipticity(5.1093e-3, 165.1e-3):.3f}")
    9.285
    """
    rx = check_positive("rx", rx, "m")
    ry = check_positive("ry", ry, "m")
    if np.any(ry < rx):
        raise InputError("ry must be >= rx [m] (the x axis is the rolling direction of the flatter pair)")
    f = (1.0 / rx - 1.0 / ry) / (1.0 / rx + 1.0 / ry)
    return hertz.ellipticity(f)


def dimensionless_groups(load, entrainment_velocity, rx, dynamic_viscosity, pressure_viscosity_coefficient,
                         reduced_modulus):
    r"""Speed, material and load parameters U, G, W of Hamrock and Dowson.

    Parameters
    ----------
    load : array_like
        Contact load Q >= 0. [N]
    entrainment_velocity : array_like
        Mean rolling velocity u = (u_a + u_b)/2 >= 0. [m/s]
    rx : array_like
        Effective radius along the rolling direction. [m]
    dynamic_viscosity : array_like
        eta0 at the inlet temperature and atmospheric pressure. [Pa s]
    pressure_viscosity_coefficient : array_like
        alpha of Barus' law eta = eta0 exp(alpha p). [1/Pa]
    reduced_modulus : array_like
        E' = 2 / [(1 - nu_a^2)/E_a + (1 - nu_b^2)/E_b]. [Pa]

    Returns
    -------
    DimensionlessGroups

    Examples
    --------
    >>> g = dimensionless_groups(1000.0, 10.0, 5e-3, 0.04, 2.3e-8, 2.2e11)
    >>> print(f"{g.speed:.4e} {g.material:.0f} {g.load:.4e}")
    3.6364e-10 5060 1.8182e-04
    """
    q = check_nonnegative("load", load, "N")
    u = check_nonnegative("entrainment_velocity", entrainment_velocity, "m/s")
    rx = check_positive("rx", rx, "m")
    eta = check_positive("dynamic_viscosity", dynamic_viscosity, "Pa s")
    alpha = check_positive("pressure_viscosity_coefficient", pressure_viscosity_coefficient, "1/Pa")
    ep = check_positive("reduced_modulus", reduced_modulus, "Pa")
    return DimensionlessGroups((eta * u / (ep * rx))[()], (alpha * ep)[()], (q / (ep * rx * rx))[()])


def hamrock_dowson(load, entrainment_velocity, rx, ellipticity, dynamic_viscosity, pressure_viscosity_coefficient,
                   reduced_modulus):
    r"""Central and minimum film thickness of a fully flooded, isothermal elliptical contact.

    Parameters
    ----------
    load : array_like
        Contact load Q > 0: an unloaded contact (Q = 0) has no film by this fit, whose W^-0.067 has no limit
        there, and is refused (:func:`bearinglab.film.distribution_films` leaves it out, NaN). [N]
    entrainment_velocity : array_like
        Mean rolling velocity u >= 0. [m/s]
    rx : array_like
        Effective radius along the rolling direction. [m]
    ellipticity : array_like
        k = a/b >= 1, the semi-axis across rolling over the one along it. [-]
    dynamic_viscosity : array_like
        eta0 at the inlet temperature. [Pa s]
    pressure_viscosity_coefficient : array_like
        alpha. [1/Pa]
    reduced_modulus : array_like
        E'. [Pa]

    Returns
    -------
    FilmThickness
        ``central`` h_c and ``minimum`` h_min. [m]

    Notes
    -----
    Hamrock and Dowson [1], with :func:`dimensionless_groups`:

    .. math::
        H_c = h_c/R_x = 2.69\,U^{0.67} G^{0.53} W^{-0.067} (1 - 0.61 e^{-0.73 k}),\qquad
        H_{min} = h_{min}/R_x = 3.63\,U^{0.68} G^{0.49} W^{-0.073} (1 - e^{-0.68 k}).

    An ellipticity outside the fitted 1 <= k <= 8 gives a :class:`~bearinglab.errors.ValidityWarning`
    (deep-groove inner contacts reach 9-10; the formulas are smooth there and commonly used).

    Examples
    --------
    >>> h = hamrock_dowson(1000.0, 10.0, 5e-3, 6.0, 0.04, 2.3e-8, 2.2e11)
    >>> print(f"{h.central * 1e6:.4f} {h.minimum * 1e6:.4f} um")
    1.0348 0.8333 um
    """
    groups = dimensionless_groups(load, entrainment_velocity, rx, dynamic_viscosity, pressure_viscosity_coefficient,
                                  reduced_modulus)
    check_positive("load", load, "N")  # Q = 0: no film by the fit (it returned NaN; issue 29)
    k = check_positive("ellipticity", ellipticity, "-")
    if np.any(k < 1.0):
        raise InputError(f"ellipticity must be >= 1 [-] (a/b with a across rolling), got {float(np.min(k))!r}")
    if np.any(k > _K_RANGE[1]):
        warnings.warn(f"ellipticity k = {float(np.max(k)):.3g} is beyond the k <= 8 of Hamrock and Dowson's fit",
                      ValidityWarning, stacklevel=2)
    u, g, w = groups
    rx = np.asarray(rx, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        w_c = np.where(w > 0, w, np.nan) ** -0.067  # W underflowed to 0 (Q ~ 1e-300 N): no film formula, NaN
        w_m = np.where(w > 0, w, np.nan) ** -0.073
    hc = 2.69 * u**0.67 * g**0.53 * w_c * (1.0 - 0.61 * np.exp(-0.73 * k)) * rx
    hm = 3.63 * u**0.68 * g**0.49 * w_m * (1.0 - np.exp(-0.68 * k)) * rx
    hc, hm = np.broadcast_arrays(hc, hm)
    return FilmThickness(hc[()], hm[()])


def thermal_reduction_factor(entrainment_velocity, dynamic_viscosity, temperature_viscosity_coefficient,
                             thermal_conductivity, max_pressure, reduced_modulus, *, slide_roll_ratio=0.0):
    r"""Inlet shear heating factor phi_T <= 1 that multiplies the isothermal film.

    Parameters
    ----------
    entrainment_velocity : array_like
        u. [m/s]
    dynamic_viscosity : array_like
        eta0 at the inlet temperature. [Pa s]
    temperature_viscosity_coefficient : array_like
        beta = -(1/eta) d eta / dT at the inlet temperature, > 0. [1/K]
    thermal_conductivity : array_like
        Of the lubricant, about 0.12-0.15 W/(m K) for mineral oils. [W/(m K)]
    max_pressure : array_like
        Hertz pressure p_max of the contact. [Pa]
    reduced_modulus : array_like
        E'. [Pa]
    slide_roll_ratio : array_like, optional
        s = abs(u_a - u_b) / u, 0 in pure rolling. [-]

    Returns
    -------
    ndarray
        phi_T. [-]

    Notes
    -----
    Gupta et al. [3]: with the thermal loading factor :math:`L = \beta \eta_0 u^2 / K`,

    .. math::
        \phi_T = \frac{1 - 13.2 (p_{max}/E') L^{0.42}}{1 + 0.213 (1 + 2.23 s^{0.83}) L^{0.64}}.

    Examples
    --------
    >>> print(f"{thermal_reduction_factor(20.0, 0.01, 0.03, 0.14, 2e9, 2.3e11):.4f}")
    0.7480
    """
    u = check_nonnegative("entrainment_velocity", entrainment_velocity, "m/s")
    eta = check_positive("dynamic_viscosity", dynamic_viscosity, "Pa s")
    beta = check_positive("temperature_viscosity_coefficient", temperature_viscosity_coefficient, "1/K")
    k = check_positive("thermal_conductivity", thermal_conductivity, "W/(m K)")
    p = check_nonnegative("max_pressure", max_pressure, "Pa")
    ep = check_positive("reduced_modulus", reduced_modulus, "Pa")
    s = check_nonnegative("slide_roll_ratio", slide_roll_ratio, "-")
    load_factor = beta * eta * u * u / k
    phi = (1.0 - 13.2 * (p / ep) * load_factor**0.42) / (1.0 + 0.213 * (1.0 + 2.23 * s**0.83) * load_factor**0.64)
    return np.clip(phi, 0.0, 1.0)[()]


def pressure_viscosity_coefficient(dynamic_viscosity):
    r"""An estimate of the pressure-viscosity coefficient of a mineral oil from its viscosity.

    Parameters
    ----------
    dynamic_viscosity : array_like
        eta0 at the temperature of interest. [Pa s]

    Returns
    -------
    ndarray
        alpha. [1/Pa]

    Notes
    -----
    Wooster's estimate, as given by Stachowiak and Batchelor [4]:
    :math:`\alpha = (0.6 + 0.965 \log_{10}\eta_0) \times 10^{-8}` m^2/N with eta0 in centipoise
    (mPa s). It is an estimate for mineral oils, good to perhaps 20-30 %: a measured alpha of the oil
    (its data sheet) should be preferred. Below 1 mPa s it would fall under 0.6e-8 m^2/N and is not
    used (:class:`~bearinglab.errors.InputError`).

    Examples
    --------
    >>> print(f"{pressure_viscosity_coefficient(0.04):.4e}")
    2.1460e-08
    """
    eta = check_positive("dynamic_viscosity", dynamic_viscosity, "Pa s")
    if np.any(eta < 1e-3):
        raise InputError(f"dynamic_viscosity must be >= 1 mPa s for the pressure-viscosity estimate [Pa s], "
                         f"got {float(np.min(eta))!r}; give the coefficient")
    return ((0.6 + 0.965 * np.log10(eta * 1e3)) * 1e-8)[()]


def film_parameter(minimum_film, roughness_ball, roughness_race):
    r"""Film parameter Lambda = h_min / sqrt(Rq_ball^2 + Rq_race^2).

    Parameters
    ----------
    minimum_film : array_like
        h_min. [m]
    roughness_ball, roughness_race : array_like
        RMS roughness R_q of the ball and of the raceway; not both zero. [m]

    Returns
    -------
    ndarray
        Lambda. [-]

    Examples
    --------
    >>> print(f"{film_parameter(0.3e-6, 0.0625e-6, 0.175e-6):.4f}")
    1.6144
    """
    h = np.asarray(minimum_film, dtype=float)
    rb = check_nonnegative("roughness_ball", roughness_ball, "m")
    rr = check_nonnegative("roughness_race", roughness_race, "m")
    composite = np.sqrt(rb * rb + rr * rr)
    if np.any(composite == 0):
        raise InputError("roughness_ball and roughness_race must not both be 0 [m] (Lambda would be infinite)")
    return (h / composite)[()]


def lubrication_regime(film_parameter):
    """The lubrication regime of a film parameter: "boundary", "mixed" or "full film".

    Parameters
    ----------
    film_parameter : array_like
        Lambda; NaN gives "" (no loaded contact). [-]

    Returns
    -------
    ndarray of str or str
        Lambda < 1 boundary, 1 <= Lambda < 3 mixed, Lambda >= 3 full film (:data:`REGIME_THRESHOLDS`).

    Examples
    --------
    >>> print(lubrication_regime([0.5, 1.0, 2.9, 3.0]).tolist())
    ['boundary', 'mixed', 'mixed', 'full film']
    """
    lam = np.asarray(film_parameter, dtype=float)
    lo, hi = REGIME_THRESHOLDS
    out = np.where(lam < lo, REGIMES[0], np.where(lam < hi, REGIMES[1], REGIMES[2])).astype(object)
    out = np.where(np.isnan(lam), "", out)
    return out.astype(str)[()] if out.ndim else str(out[()])

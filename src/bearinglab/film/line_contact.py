r"""Elastohydrodynamic film of line (roller-raceway) contacts, and of every roller of a roller bearing.

Film thickness of one line contact
----------------------------------
LINE_MODELS                  ``"pan-hamrock"`` (Pan and Hamrock 1989, the default) and ``"dowson-higginson"``
line_film                    central and minimum film h_c, h_min of a fully flooded isothermal line contact

Rollers of a bearing
--------------------
roller_entrainment_velocity  u = (d_m omega / 4)(1 - gamma^2) of the roller-raceway contacts (outer ring fixed)
roller_films                 the films and Lambda of every roller of a load distribution (inner and outer contact)
RollerFilms                  its result

The dimensionless groups are those of a line contact: :math:`U = \eta_0 u/(E' R_x)`, :math:`G = \alpha E'`
and the load per unit length :math:`W' = w'/(E' R_x)` (w' = Q / L_we of a uniformly loaded roller).
SI throughout. The film parameter and the regime are those of :mod:`bearinglab.film.ehl`.

References
----------
.. [1] P. Pan and B. J. Hamrock, "Simple formulas for performance parameters used in elastohydrodynamically
   lubricated line contacts," J. Tribol., vol. 111, no. 2, pp. 246-251, 1989, doi:10.1115/1.3261906
   (H_min = 1.714 W'^-0.128 U^0.694 G^0.568, H_c = 2.922 W'^-0.166 U^0.692 G^0.470).
.. [2] D. Dowson and G. R. Higginson, *Elasto-hydrodynamic Lubrication*, SI ed., Pergamon, 1977
   (H_min = 2.65 U^0.70 G^0.54 W'^-0.13, as quoted in [3]).
.. [3] B. J. Hamrock, S. R. Schmid and B. O. Jacobson, *Fundamentals of Fluid Film Lubrication*, 2nd ed.,
   Marcel Dekker, 2004, ch. 21 (rectangular conjunctions) and ch. 24 (rolling-element bearings: the
   entrainment velocity of a roller, R_x = (D/2)(1 -+ gamma)).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from .._validate import as_float, check_nonnegative, check_positive
from ..errors import InputError
from .ehl import FilmThickness, film_parameter, lubrication_regime

__all__ = ["LINE_MODELS", "RollerFilms", "line_film", "roller_entrainment_velocity", "roller_films"]

#: The line-contact film formulas.
LINE_MODELS = ("pan-hamrock", "dowson-higginson")


def line_film(load_per_length, entrainment_velocity, radius, dynamic_viscosity, pressure_viscosity_coefficient,
              reduced_modulus, *, model="pan-hamrock"):
    r"""Central and minimum film thickness of a fully flooded isothermal EHL line contact.

    Parameters
    ----------
    load_per_length : array_like
        w', the load per unit length, > 0. [N/m]
    entrainment_velocity : array_like
        u, the mean surface velocity, > 0. [m/s]
    radius : array_like
        R_x, the effective radius in the rolling direction. [m]
    dynamic_viscosity : array_like
        eta_0 at the inlet. [Pa s]
    pressure_viscosity_coefficient : array_like
        alpha. [1/Pa]
    reduced_modulus : array_like
        E'. [Pa]
    model : {"pan-hamrock", "dowson-higginson"}
        The formula (:data:`LINE_MODELS`); Dowson and Higginson give the minimum film only (``central`` NaN).

    Returns
    -------
    FilmThickness
        ``central``, ``minimum``. [m]

    Notes
    -----
    Pan and Hamrock [1]: :math:`H_{min} = h_{min}/R_x = 1.714\,W'^{-0.128} U^{0.694} G^{0.568}`,
    :math:`H_c = 2.922\,W'^{-0.166} U^{0.692} G^{0.470}`; Dowson and Higginson [2]:
    :math:`H_{min} = 2.65\,U^{0.70} G^{0.54} W'^{-0.13}`.

    Examples
    --------
    >>> f = line_film(1.0e6, 5.0, 4.6e-3, 0.02, 2.0e-8, 2.28e11)
    >>> print(f"h_c = {f.central * 1e6:.3f} um, h_min = {f.minimum * 1e6:.3f} um")
    h_c = 0.260 um, h_min = 0.255 um
    """
    w = check_positive("load_per_length", load_per_length, "N/m")
    u = check_positive("entrainment_velocity", entrainment_velocity, "m/s")
    r = check_positive("radius", radius, "m")
    eta = check_positive("dynamic_viscosity", dynamic_viscosity, "Pa s")
    alpha = check_positive("pressure_viscosity_coefficient", pressure_viscosity_coefficient, "1/Pa")
    ep = check_positive("reduced_modulus", reduced_modulus, "Pa")
    big_u, big_g, big_w = eta * u / (ep * r), alpha * ep, w / (ep * r)
    if model == "pan-hamrock":
        hmin = 1.714 * big_w**-0.128 * big_u**0.694 * big_g**0.568
        hc = 2.922 * big_w**-0.166 * big_u**0.692 * big_g**0.470
    elif model == "dowson-higginson":
        hmin = 2.65 * big_u**0.70 * big_g**0.54 * big_w**-0.13
        hc = np.full_like(hmin, np.nan)  # not part of the formula
    else:
        raise InputError(f"model must be one of {list(LINE_MODELS)}, got {model!r}")
    return FilmThickness((hc * r)[()], (hmin * r)[()])


def roller_entrainment_velocity(shaft_speed, roller_diameter, pitch_diameter, contact_angle=0.0):
    r"""Entrainment velocity of the roller-raceway contacts, inner ring turning, outer ring fixed.

    Parameters
    ----------
    shaft_speed : array_like
        omega of the inner ring. [rad/s]
    roller_diameter : array_like
        D_we. [m]
    pitch_diameter : array_like
        D_pw. [m]
    contact_angle : array_like
        alpha. [rad]

    Returns
    -------
    ndarray or float
        :math:`u = \frac{d_m |\omega|}{4}(1 - \gamma^2)`, :math:`\gamma = D_{we}\cos\alpha/d_m`: the same at
        both contacts in pure rolling ([3] ch. 24). [m/s]

    Examples
    --------
    >>> print(f"{roller_entrainment_velocity(157.08, 11e-3, 60.5e-3):.4f} m/s")
    2.2973 m/s
    """
    w = np.abs(as_float("shaft_speed", shaft_speed))
    d = check_positive("roller_diameter", roller_diameter, "m")
    dm = check_positive("pitch_diameter", pitch_diameter, "m")
    gamma = d * np.cos(as_float("contact_angle", contact_angle)) / dm
    return (0.25 * dm * w * (1.0 - gamma**2))[()]


class RollerFilms(NamedTuple):
    """The film of every roller of a roller bearing (NaN for an unloaded roller)."""

    central_inner: np.ndarray
    """(..., Z) h_c at the inner raceway. [m]"""
    minimum_inner: np.ndarray
    """(..., Z) h_min at the inner raceway. [m]"""
    central_outer: np.ndarray
    """(..., Z) h_c at the outer raceway. [m]"""
    minimum_outer: np.ndarray
    """(..., Z) h_min at the outer raceway. [m]"""
    film_parameter: np.ndarray
    """(..., Z) Lambda of the thinner contact. [-]"""
    regime: np.ndarray
    """(..., Z) "boundary", "mixed", "full film" ("" for an unloaded roller)."""
    entrainment_velocity: np.ndarray
    """(...) u. [m/s]"""


def roller_films(roller_load, shaft_speed, roller_diameter, roller_length, pitch_diameter, dynamic_viscosity,
                 pressure_viscosity_coefficient, reduced_modulus, *, contact_angle=0.0, roughness_roller=0.1e-6,
                 roughness_race=0.2e-6, model="pan-hamrock"):
    r"""EHL films and Lambda of every roller of a roller bearing from its roller loads.

    Parameters
    ----------
    roller_load : array_like
        (..., Z) Q_j (:attr:`bearinglab.rollers.RollerLoadDistribution.roller_load`). [N]
    shaft_speed : array_like
        omega of the inner ring (outer fixed), broadcast against the leading axes. [rad/s]
    roller_diameter : float
        D_we. [m]
    roller_length : float
        L_we: the load per unit length is Q / L_we. [m]
    pitch_diameter : float
        D_pw. [m]
    dynamic_viscosity : array_like
        eta_0. [Pa s]
    pressure_viscosity_coefficient : array_like
        alpha. [1/Pa]
    reduced_modulus : float
        E'. [Pa]
    contact_angle : float
        alpha. [rad]
    roughness_roller, roughness_race : float
        R_q of the roller and of the raceways (0.1 and 0.2 um by default, the film module's). [m]
    model : {"pan-hamrock", "dowson-higginson"}
        :func:`line_film`.

    Returns
    -------
    RollerFilms

    Notes
    -----
    Each roller is a line contact of its mean load per unit length at both raceways (R_x = (D_we/2)(1 -+
    gamma)); the film of a tilted roller's most loaded end is thinner than this mean (the slices are not
    solved for their own films). Unloaded rollers (Q = 0) have no film: NaN.

    Examples
    --------
    >>> f = roller_films([3000.0, 0.0], 157.08, 11e-3, 9.6e-3, 60.5e-3, 0.02, 2.0e-8, 2.28e11)
    >>> print(np.round(f.minimum_inner * 1e6, 3), f.regime)
    [0.171   nan] ['boundary' '']
    """
    q = check_nonnegative("roller_load", roller_load, "N")
    length = check_positive("roller_length", roller_length, "m")
    u = roller_entrainment_velocity(shaft_speed, roller_diameter, pitch_diameter, contact_angle)
    u = np.asarray(u, dtype=float)
    if np.any(u <= 0):
        raise InputError("shaft_speed must be != 0 for a film [rad/s]")
    d = float(roller_diameter)
    gamma = d * np.cos(contact_angle) / float(pitch_diameter)
    loaded = q > 0
    w = np.where(loaded, q, 1.0) / length
    ue = u[..., None] if u.ndim else u
    films = [line_film(w, ue, 0.5 * d * (1.0 + sign * gamma), dynamic_viscosity, pressure_viscosity_coefficient,
                       reduced_modulus, model=model) for sign in (-1.0, 1.0)]
    nan = lambda a: np.where(loaded, a, np.nan)
    hi, ho = (nan(f.minimum) for f in films)
    lam = film_parameter(np.minimum(hi, ho), roughness_roller, roughness_race)
    return RollerFilms(nan(films[0].central), hi, nan(films[1].central), ho, lam, lubrication_regime(lam), u)

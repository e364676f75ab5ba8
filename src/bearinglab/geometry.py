"""Internal geometry of a ball bearing: conformity, curvature sums, clearance and contact angle.

Conformity and clearance
------------------------
total_curvature             B = f_i + f_o - 1
pitch_ratio                 gamma = D cos(alpha) / d_m
free_contact_angle          alpha0 from the diametral clearance (exact, spec 000 section 4)
free_contact_angle_052      alpha0 with both groove radii 0.52 D (spec 000 section 4)
radial_clearance            the inverse: clearance from the free contact angle
axial_play                  total axial play of the free bearing
groove_centre_diameters     T_i, T_o and the paper's m_v, m_n (spec 000 section 5.1)

Curvature
---------
raceway_curvature           curvature sum and curvature difference F(rho) = cos(tau) of one contact
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from ._validate import as_float, check_greater, check_open_interval, check_positive
from .errors import InputError

__all__ = [
    "Curvature",
    "GrooveCentres",
    "axial_play",
    "free_contact_angle",
    "free_contact_angle_052",
    "groove_centre_diameters",
    "pitch_ratio",
    "raceway_curvature",
    "radial_clearance",
    "total_curvature",
]


def _conformity(name, value):
    return check_open_interval(name, value, 0.5, np.inf, "-")


def _free_angle(value):
    a0 = as_float("free_angle", value)
    bad = ~((a0 >= 0.0) & (a0 < np.pi / 2))
    if bad.any():
        first = a0[bad].flat[0] if a0.ndim else a0
        raise InputError(f"free_angle must be in [0, 90) [deg], got {float(np.degrees(first))!r}")
    return a0


def total_curvature(inner_conformity, outer_conformity):
    """Total curvature B = f_i + f_o - 1 (spec 000 symbol xi; Harris B).

    Parameters
    ----------
    inner_conformity, outer_conformity : array_like
        Groove radius over ball diameter, f_i and f_o; each > 0.5. [-]

    Returns
    -------
    ndarray
        B; B times the ball diameter is the distance between the groove-curvature centres. [-]

    Examples
    --------
    >>> print(round(float(total_curvature(0.525, 0.58)), 12))
    0.105
    """
    fi = _conformity("inner_conformity", inner_conformity)
    fo = _conformity("outer_conformity", outer_conformity)
    return (fi + fo - 1.0)[()]


def pitch_ratio(ball_diameter, pitch_diameter, contact_angle):
    """gamma = D cos(alpha) / d_m (spec 000 section 5.1; spec 004 eq. 11).

    Parameters
    ----------
    ball_diameter : array_like
        Ball diameter D. [m]
    pitch_diameter : array_like
        Pitch (ball-centre circle) diameter d_m; must exceed D. [m]
    contact_angle : array_like
        Contact angle alpha. [rad]

    Returns
    -------
    ndarray
        gamma. [-]
    """
    d = check_positive("ball_diameter", ball_diameter, "m")
    dm = check_greater("pitch_diameter", pitch_diameter, "ball_diameter", d, "m")
    return (d * np.cos(np.asarray(contact_angle, dtype=float)) / dm)[()]


def free_contact_angle(radial_clearance, ball_diameter, inner_conformity, outer_conformity):
    r"""Free contact angle from the diametral clearance, exact form (spec 000 section 4).

    .. math:: \alpha_0 = \arccos\left[1 - \frac{e}{2 (r_i + r_o - D)}\right]

    Parameters
    ----------
    radial_clearance : array_like
        Mean radial (diametral) clearance e, 0 < e < 4 B D. [m]
    ball_diameter : array_like
        Ball diameter D. [m]
    inner_conformity, outer_conformity : array_like
        f_i, f_o. [-]

    Returns
    -------
    ndarray
        alpha0. [rad]

    Notes
    -----
    Harris: cos alpha0 = 1 - P_d / (2 B D). The argument of arccos must lie in (-1, 1).

    Examples
    --------
    >>> import math
    >>> a = free_contact_angle(9.178e-6, 2e-3, 0.525, 0.58)
    >>> print(f"{math.degrees(a):.3f}")
    12.000
    """
    d = check_positive("ball_diameter", ball_diameter, "m")
    groove_distance = total_curvature(inner_conformity, outer_conformity) * d
    e = check_positive("radial_clearance", radial_clearance, "m")
    cos_a = 1.0 - e / (2.0 * groove_distance)
    _check_clearance(e, 4.0 * groove_distance, cos_a)
    return np.arccos(cos_a)[()]


def free_contact_angle_052(radial_clearance, ball_diameter):
    """Free contact angle with both groove radii 0.52 D: alpha0 = arccos(1 - 12.5 e / D) (spec 000 section 4).

    Parameters
    ----------
    radial_clearance : array_like
        Diametral clearance e, 0 < e < 0.16 D. [m]
    ball_diameter : array_like
        Ball diameter D. [m]

    Returns
    -------
    ndarray
        alpha0. [rad]

    Notes
    -----
    The shortcut can differ strongly from :func:`free_contact_angle` when the real conformities are
    not 0.52: for bearing 4-1006095 the clearance that gives 12 degrees exactly gives 19.50 degrees here.

    Examples
    --------
    >>> import math
    >>> print(f"{math.degrees(free_contact_angle_052(9.178e-6, 2e-3)):.2f}")
    19.50
    """
    d = check_positive("ball_diameter", ball_diameter, "m")
    e = check_positive("radial_clearance", radial_clearance, "m")
    cos_a = 1.0 - 12.5 * e / d
    _check_clearance(e, 0.16 * d, cos_a)
    return np.arccos(cos_a)[()]


def _check_clearance(e, limit, cos_a):
    bad = ~(cos_a > -1.0)
    if np.any(bad):
        e_b, lim_b = np.broadcast_arrays(e, limit)
        raise InputError(
            f"radial_clearance must be in (0, {float(lim_b[bad].flat[0]) * 1e3:.6g}) [mm] to give a real "
            f"contact angle, got {float(e_b[bad].flat[0]) * 1e3:.6g} mm"
        )


def radial_clearance(free_angle, ball_diameter, inner_conformity, outer_conformity):
    """Diametral clearance that gives a free contact angle: e = 2 B D (1 - cos alpha0).

    Parameters
    ----------
    free_angle : array_like
        Free contact angle alpha0, in [0, 90 deg). [rad]
    ball_diameter : array_like
        Ball diameter D. [m]
    inner_conformity, outer_conformity : array_like
        f_i, f_o. [-]

    Returns
    -------
    ndarray
        e. [m]

    Examples
    --------
    >>> import math
    >>> print(f"{radial_clearance(math.radians(12), 2e-3, 0.525, 0.58) * 1e6:.3f} um")
    9.178 um
    """
    d = check_positive("ball_diameter", ball_diameter, "m")
    a0 = _free_angle(free_angle)
    return (2.0 * total_curvature(inner_conformity, outer_conformity) * d * (1.0 - np.cos(a0)))[()]


def axial_play(free_angle, ball_diameter, inner_conformity, outer_conformity):
    """Total axial play of the free bearing: P_e = 2 B D sin(alpha0) (Harris, Rolling Bearing Analysis, eq. 2.13).

    Parameters
    ----------
    free_angle : array_like
        Free contact angle alpha0. [rad]
    ball_diameter : array_like
        Ball diameter D. [m]
    inner_conformity, outer_conformity : array_like
        f_i, f_o. [-]

    Returns
    -------
    ndarray
        Axial play, from one contact position to the other. [m]
    """
    d = check_positive("ball_diameter", ball_diameter, "m")
    a0 = _free_angle(free_angle)
    return (2.0 * total_curvature(inner_conformity, outer_conformity) * d * np.sin(a0))[()]


class GrooveCentres(NamedTuple):
    """Diameters of the circles of groove-curvature centres in the free position and the paper's m."""

    inner_diameter: np.ndarray  # T_v [m]
    outer_diameter: np.ndarray  # T_n [m]
    m_inner: np.ndarray  # m_v = T_v / (D cos alpha0) [-]
    m_outer: np.ndarray  # m_n = T_n / (D cos alpha0) [-]


def groove_centre_diameters(ball_diameter, pitch_diameter, inner_conformity, outer_conformity, free_angle):
    """Circles of the groove-curvature centres in the free position (spec 000 section 5.1).

    T_v = d_m + (2 r_i - D) cos alpha0 and T_n = d_m - (2 r_o - D) cos alpha0; m = T / (D cos alpha0).

    Parameters
    ----------
    ball_diameter : array_like
        Ball diameter D. [m]
    pitch_diameter : array_like
        Pitch diameter d_m. [m]
    inner_conformity, outer_conformity : array_like
        f_i, f_o. [-]
    free_angle : array_like
        Free contact angle alpha0. [rad]

    Returns
    -------
    GrooveCentres
        T_v, T_n [m] and m_v, m_n [-].
    """
    d = check_positive("ball_diameter", ball_diameter, "m")
    dm = check_greater("pitch_diameter", pitch_diameter, "ball_diameter", d, "m")
    fi = _conformity("inner_conformity", inner_conformity)
    fo = _conformity("outer_conformity", outer_conformity)
    c = np.cos(np.asarray(free_angle, dtype=float))
    t_i = dm + (2.0 * fi - 1.0) * d * c
    t_o = dm - (2.0 * fo - 1.0) * d * c
    return GrooveCentres(t_i[()], t_o[()], (t_i / (d * c))[()], (t_o / (d * c))[()])


class Curvature(NamedTuple):
    """Curvature of one ball-raceway contact."""

    curvature_sum: np.ndarray  # Sigma rho [1/m]
    curvature_difference: np.ndarray  # F(rho) = cos(tau) [-]


def raceway_curvature(ball_diameter, pitch_diameter, conformity, contact_angle, *, race):
    r"""Curvature sum and curvature difference of a ball-raceway contact.

    Parameters
    ----------
    ball_diameter : array_like
        Ball diameter D. [m]
    pitch_diameter : array_like
        Pitch diameter d_m. [m]
    conformity : array_like
        Groove conformity f of that raceway, > 0.5. [-]
    contact_angle : array_like
        Contact angle at which the curvature is evaluated. [rad]
    race : {"inner", "outer"}
        Which raceway.

    Returns
    -------
    Curvature
        ``curvature_sum`` [1/m] and ``curvature_difference`` F(rho) = cos(tau) [-].

    Notes
    -----
    Spec 000 section 5.1 (corrected sign pattern of the source) and spec 004 eqs. (17)-(21), with
    gamma = D cos(alpha) / d_m:

    .. math::
        \Sigma\rho_i = \frac{1}{D}\left[4 - \frac{1}{f_i} + \frac{2\gamma}{1-\gamma}\right],\qquad
        F_i = \frac{1/f_i + 2\gamma/(1-\gamma)}{4 - 1/f_i + 2\gamma/(1-\gamma)}

    and for the outer raceway the 2 gamma term changes sign with the denominator 1 + gamma.

    Examples
    --------
    >>> import math
    >>> c = raceway_curvature(2e-3, 8.7355e-3, 0.525, math.radians(12), race="inner")
    >>> print(f"{c.curvature_difference:.9f} {c.curvature_sum * 1e-3:.9f}")
    0.928724244 1.336192009
    """
    d = check_positive("ball_diameter", ball_diameter, "m")
    dm = check_greater("pitch_diameter", pitch_diameter, "ball_diameter", d, "m")
    f = _conformity("conformity", conformity)
    g = d * np.cos(np.asarray(contact_angle, dtype=float)) / dm
    if race == "inner":
        race_term = 2.0 * g / (1.0 - g)
    elif race == "outer":
        race_term = -2.0 * g / (1.0 + g)
    else:
        raise InputError(f"race must be one of ['inner', 'outer'], got {race!r}")
    total = 4.0 - 1.0 / f + race_term
    return Curvature((total / d)[()], ((1.0 / f + race_term) / total)[()])

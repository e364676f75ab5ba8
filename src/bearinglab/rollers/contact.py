r"""Line contact of a roller, sliced: the ISO/TS 16281 lamina stiffness and the Hertz line-contact pressure.

Stiffness of the slices (ISO/TS 16281)
--------------------------------------
SLICE_CONSTANT        c = 35948 N/mm^(10/9) per mm^(8/9) of effective length (steel, both raceways)
slice_stiffness       c_s = c L_we^(8/9) / n_s of one lamina, in SI
slice_loads           q = c_s delta^(10/9) of every lamina with a positive approach, and dq/d delta

Line contact (Hertz)
--------------------
contact_radii         R of the inner and outer contact in the rolling direction
LineContact           half width b and maximum pressure p_max of a line contact
line_contact          b and p_max from the load per unit length, R and E'

The slice model cuts each roller into n_s laminae of width L_we / n_s. Each lamina is a nonlinear spring
between the raceways carrying the approach of its two contacts together; its load is the ISO/TS 16281
law, so a uniformly loaded roller carries Q = c L_we^(8/9) delta^(10/9) whatever n_s is. The pressure of a
lamina is the Hertz line-contact pressure of its load per unit length.

References
----------
.. [1] ISO/TS 16281:2008, *Rolling bearings -- Methods for calculating the modified reference rating life
   for universally loaded bearings*, clause 8: lamina load q_jk = c_L / n_s delta_jk^(10/9) with
   c_L = 35948 L_we^(8/9) (N, mm; steel) (eqs. (38)-(41), (45)-(46) as transcribed in the open repository
   github.com/minzhun/ISO16281, RollerBearing.py).
.. [2] A. Palmgren, *Ball and Roller Bearing Engineering*, 3rd ed., SKF Industries, 1959: the approach of
   a steel line contact delta = 3.84e-5 Q^0.9 / l^0.8 (mm, N), from which the 10/9 power law comes.
.. [3] K. L. Johnson, *Contact Mechanics*, Cambridge University Press, 1985, section 4.2 (two cylinders
   with parallel axes: b = sqrt(4 w R / (pi E*)), p0 = 2 w / (pi b)), doi:10.1017/CBO9781139171731.
.. [4] T. A. Harris and M. N. Kotzalas, *Essential Concepts of Bearing Technology*, 5th ed., CRC Press,
   2006, ch. 2 (curvature sums of roller-raceway contacts, gamma = D cos(alpha) / d_m).
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from .._validate import as_float, check_integer, check_nonnegative, check_positive
from ..errors import InputError

__all__ = ["SLICE_CONSTANT", "LineContact", "contact_radii", "line_contact", "slice_loads", "slice_stiffness"]

#: ISO/TS 16281:2008 line-contact constant of steel rollers and rings, both contacts in series:
#: 35948 N/mm^(10/9) per mm^(8/9) of effective roller length (reference [1]).
SLICE_CONSTANT = 35948.0
_MM = 1e-3
# 35948 (L/mm)^(8/9) (delta/mm)^(10/9) N = 35948e6 L^(8/9) delta^(10/9) N with L, delta in m (8/9 + 10/9 = 2)
_SI = SLICE_CONSTANT / _MM**2


def slice_stiffness(roller_length, n_slices):
    r"""Load constant c_s of one lamina: q = c_s delta^(10/9) (ISO/TS 16281, steel).

    Parameters
    ----------
    roller_length : array_like
        L_we, the effective roller length. [m]
    n_slices : int
        n_s. [-]

    Returns
    -------
    ndarray or float
        :math:`c_s = 35948\, L_{we}^{8/9}/n_s` in N/mm^(10/9) with L_we in mm, converted to SI:
        :math:`3.5948\times10^{10}\, L_{we}^{8/9}/n_s` [N/m^(10/9)].

    Examples
    --------
    >>> print(f"{slice_stiffness(10e-3, 1) * (1e-6) ** (10 / 9):.2f} N at 1 um")
    129.19 N at 1 um
    """
    length = check_positive("roller_length", roller_length, "m")
    n = int(check_integer("n_slices", n_slices, 1))
    return (_SI * length ** (8.0 / 9.0) / n)[()]


def slice_loads(approach, stiffness):
    r"""Loads of the laminae and their derivative with the approach: q = c_s <delta>^(10/9).

    Parameters
    ----------
    approach : array_like
        delta of each lamina: the approach of the raceways there less the gap and twice the profile drop;
        <= 0 is no contact. [m]
    stiffness : array_like
        c_s, broadcast against ``approach``. [N/m^(10/9)]

    Returns
    -------
    load : ndarray
        q >= 0. [N]
    derivative : ndarray
        dq / d delta = (10/9) c_s delta^(1/9), 0 out of contact. [N/m]

    Notes
    -----
    delta^(1/9) is computed as two cube roots (cheaper than a power and exact to rounding), so the load
    q = delta delta^(1/9) and its derivative share it. The law is continuous with a continuous derivative
    at delta = 0, which the ring Newton needs.

    Examples
    --------
    >>> q, k = slice_loads([-1e-6, 1e-6, 2e-6], 1.0)
    >>> print(q / (1e-6) ** (10 / 9))
    [0.         1.         2.16011948]
    """
    d = np.maximum(as_float("approach", approach), 0.0)
    c = np.asarray(stiffness, dtype=float)
    ninth = np.cbrt(np.cbrt(d))
    return c * d * ninth, (10.0 / 9.0) * c * ninth


def _slice_loads_into(delta, c):
    """:func:`slice_loads` of a scalar c_s, overwriting ``delta`` (a float array the caller owns): the same
    operations in the same order (the same bits), without temporaries. For the ring Newton's inner loop."""
    np.maximum(delta, 0.0, out=delta)
    ninth = np.cbrt(delta)
    np.cbrt(ninth, out=ninth)
    np.multiply(delta, c, out=delta)
    np.multiply(delta, ninth, out=delta)
    np.multiply(ninth, (10.0 / 9.0) * c, out=ninth)
    return delta, ninth


def contact_radii(roller_diameter, pitch_diameter, contact_angle=0.0):
    r"""Radii of the inner and outer roller-raceway contacts in the rolling direction.

    Parameters
    ----------
    roller_diameter : array_like
        D_we. [m]
    pitch_diameter : array_like
        D_pw. [m]
    contact_angle : array_like
        alpha (0 for a cylindrical roller bearing). [rad]

    Returns
    -------
    inner, outer : ndarray
        :math:`R_i = \tfrac{D_{we}}{2}(1 - \gamma)`, :math:`R_o = \tfrac{D_{we}}{2}(1 + \gamma)` with
        :math:`\gamma = D_{we}\cos\alpha/D_{pw}` ([4] ch. 2: the roller against a convex inner and a
        concave outer raceway). [m]

    Examples
    --------
    >>> ri, ro = contact_radii(10e-3, 60e-3)
    >>> print(f"{ri * 1e3:.4f} {ro * 1e3:.4f} mm")
    4.1667 5.8333 mm
    """
    d = check_positive("roller_diameter", roller_diameter, "m")
    dpw = check_positive("pitch_diameter", pitch_diameter, "m")
    gamma = d * np.cos(as_float("contact_angle", contact_angle)) / dpw
    if np.any(gamma >= 1.0):
        raise InputError("pitch_diameter must be > roller_diameter cos(contact_angle) [mm]")
    return (0.5 * d * (1.0 - gamma))[()], (0.5 * d * (1.0 + gamma))[()]


class LineContact(NamedTuple):
    """Hertz contact of two cylinders with parallel axes."""

    half_width: np.ndarray
    """b, the semi-width of the contact strip. [m]"""
    max_pressure: np.ndarray
    """p_max = 2 w / (pi b) in its middle. [Pa]"""


def line_contact(load_per_length, radius, reduced_modulus):
    r"""Half width and maximum pressure of a Hertz line contact.

    Parameters
    ----------
    load_per_length : array_like
        w, the load per unit length of contact, >= 0. [N/m]
    radius : array_like
        R, the effective radius in the rolling direction (:func:`contact_radii`). [m]
    reduced_modulus : array_like
        E' = 2 / [(1 - nu1^2)/E1 + (1 - nu2^2)/E2]. [Pa]

    Returns
    -------
    LineContact

    Notes
    -----
    Johnson [3] eqs. (4.43), (4.45) with :math:`E^* = E'/2`:
    :math:`b = \sqrt{8 w R/(\pi E')}` and :math:`p_{max} = \sqrt{w E'/(2\pi R)}`.

    Examples
    --------
    >>> c = line_contact(1e6, 5e-3, 2.28e11)
    >>> print(f"b = {c.half_width * 1e6:.2f} um, p = {c.max_pressure / 1e6:.0f} MPa")
    b = 236.31 um, p = 2694 MPa
    """
    w = check_nonnegative("load_per_length", load_per_length, "N/m")
    r = check_positive("radius", radius, "m")
    ep = check_positive("reduced_modulus", reduced_modulus, "Pa")
    return LineContact(np.sqrt(8.0 * w * r / (math.pi * ep))[()], np.sqrt(w * ep / (2.0 * math.pi * r))[()])

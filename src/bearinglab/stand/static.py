r"""Static contact angle of a ball bearing under pure thrust (zero speed, rigid rings).

Under a thrust F_a every ball carries Q = F_a/(Z sin alpha) and the groove-curvature centres move apart
axially: the contact angle grows from the free angle alpha0 until the elastic approach of the two
contacts matches the geometry. These relations are shared by the test-stand method of spec 000
(:mod:`bearinglab.stand`, stiffness held at alpha0) and by the high-speed model of spec 004 (its
zero-speed start and limit, stiffness at the loaded angle).

Load-angle relation, constant stiffness (spec 000 section 6)
-------------------------------------------------------------
thrust_from_angle            F_a = C* (cos a0 / cos a - 1)^1.5 sin a                        eq. (1)
first_approximation          x0 of eq. (3) (corrected prefactor sin 2 alpha0)
axial_displacement_ratio     xi_a = delta_a / (B D) = cos a0 (tan a - tan a0): ring geometry only

Stiffness at the loaded angle (spec 004 section 5.3)
----------------------------------------------------
contact_angle_under_thrust   the static angle, deflections and ball load with K_i, K_e at the loaded angle
ThrustContact

The axial displacement ratio is static-generic: it is the geometry of the two groove-curvature centres
(their distance B D cos alpha0 / cos alpha, the inner one shifted axially), whatever the stiffness model,
so it holds for both methods and belongs here.

References
----------
.. [1] V. A. Zaitsev and V. A. Voronkin, "Calculation of axial loads and operating contact angles of
   rolling bearings when assessing their quality on test stands," 2009 (spec 000 of this project).
.. [2] Zhao Chunjiang, Cui Guohua, Wang Guoqiang, Huang Qingxue and Zhang Fangping, "Precise definition
   of the contact-angle field of a high-speed angular-contact ball bearing under axial load,"
   Transactions of the CSAM, vol. 39, no. 12, pp. 154-156, 209, 2008 (spec 004 of this project).
.. [3] T. A. Harris and M. N. Kotzalas, *Essential Concepts of Bearing Technology*, 5th ed., CRC Press,
   2006, doi:10.1201/9781420006599.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from .. import _solve, geometry, hertz
from .._validate import check_integer, check_open_interval, check_positive
from ..errors import ConvergenceError, InputError

__all__ = [
    "ThrustContact",
    "axial_displacement_ratio",
    "contact_angle_under_thrust",
    "first_approximation",
    "thrust_from_angle",
]


def _angle(name, value):
    return check_open_interval(name, value, 0.0, np.pi / 2, "deg", scale=180.0 / np.pi)

# --------------------------------------------------------------------------- constant stiffness
def thrust_from_angle(contact_angle, force_characteristic, free_angle):
    r"""Axial load at which the operating contact angle is ``contact_angle``: eq. (1) of spec 000 section 6.1.

    Parameters
    ----------
    contact_angle : array_like
        Operating contact angle alpha >= alpha0. [rad]
    force_characteristic : array_like
        C*. [N]
    free_angle : array_like
        Free contact angle alpha0. [rad]

    Returns
    -------
    ndarray
        :math:`F_a = C^* (\cos\alpha_0/\cos\alpha - 1)^{3/2} \sin\alpha`. [N]
    """
    a = np.asarray(contact_angle, dtype=float)
    a0 = np.asarray(free_angle, dtype=float)
    c = np.maximum(np.cos(a0) / np.cos(a) - 1.0, 0.0)
    return (np.asarray(force_characteristic, dtype=float) * c**1.5 * np.sin(a))[()]


def first_approximation(thrust_ratio, free_angle):
    r"""First approximation x0 of the angle increment, eq. (3) of spec 000 (corrected).

    Parameters
    ----------
    thrust_ratio : array_like
        F_a / C*. [-]
    free_angle : array_like
        Free contact angle alpha0, in (0, 90 deg). [rad]

    Returns
    -------
    ndarray
        x0 = alpha - alpha0, the positive root of the quadratic truncation of eq. (2). [rad]

    Notes
    -----
    .. math::
        x_0 = \frac{3\sin\alpha_0\cos\alpha_0}{6 + \cos^2\alpha_0}
        \left[\sqrt{1 + \frac{2}{3}\,\frac{6 + \cos^2\alpha_0}{\sin^2\alpha_0}
        \left(\frac{F_a}{C^*\sin\alpha_0}\right)^{2/3}} - 1\right]

    The source prints the prefactor as (3/2) sin^2 alpha0/(6 + cos^2 alpha0); it is (3/2) sin 2 alpha0
    (spec 000 section 9.6).

    Examples
    --------
    >>> import math
    >>> print(f"{first_approximation(2 / 7792.357, math.radians(12)):.7f}")
    0.0434005
    """
    t_ratio = check_positive("thrust_ratio", thrust_ratio, "-")
    a0 = _angle("free_angle", free_angle)
    s, c = np.sin(a0), np.cos(a0)
    root = np.sqrt(1.0 + (2.0 / 3.0) * (6.0 + c**2) / s**2 * (t_ratio / s) ** (2.0 / 3.0))
    return (3.0 * s * c / (6.0 + c**2) * (root - 1.0))[()]


def axial_displacement_ratio(contact_angle, free_angle):
    r"""Dimensionless axial displacement xi_a = delta_a / (xi d) = cos a0 (tan a - tan a0) (spec 000 section 6.1).

    Parameters
    ----------
    contact_angle : array_like
        Operating contact angle alpha. [rad]
    free_angle : array_like
        Free contact angle alpha0. [rad]

    Returns
    -------
    ndarray
        xi_a; multiply by B D for the axial displacement of the rings. [-]
    """
    a = np.asarray(contact_angle, dtype=float)
    a0 = np.asarray(free_angle, dtype=float)
    return (np.cos(a0) * (np.tan(a) - np.tan(a0)))[()]


# --------------------------------------------------------------------------- stiffness at the loaded angle
class ThrustContact(NamedTuple):
    """Static state of a ball bearing under pure thrust (spec 004 section 5.3)."""

    contact_angle: np.ndarray  # alpha_s [rad]
    axial_displacement: np.ndarray  # delta_a from the unloaded position with both contacts touching [m]
    ball_load: np.ndarray  # Q = F_a/(Z sin alpha) [N]
    deflection_inner: np.ndarray  # delta_i [m]
    deflection_outer: np.ndarray  # delta_e [m]
    iterations: int


def _contact_stiffness(ball_diameter, pitch_diameter, inner_conformity, outer_conformity, angle, reduced_modulus):
    inner = geometry.raceway_curvature(ball_diameter, pitch_diameter, inner_conformity, angle, race="inner")
    outer = geometry.raceway_curvature(ball_diameter, pitch_diameter, outer_conformity, angle, race="outer")
    k_i = hertz.load_deflection_constant(inner.curvature_sum, inner.curvature_difference, reduced_modulus)
    k_e = hertz.load_deflection_constant(outer.curvature_sum, outer.curvature_difference, reduced_modulus)
    return np.asarray(k_i), np.asarray(k_e)


def _series_stiffness(k_i, k_e):
    return (k_i ** (-2.0 / 3.0) + k_e ** (-2.0 / 3.0)) ** -1.5


def contact_angle_under_thrust(axial_load, n_balls, ball_diameter, pitch_diameter, inner_conformity,
                               outer_conformity, free_angle, reduced_modulus, *, stiffness_at="operating",
                               xtol=1e-13, max_iter=_solve.AXIAL_ANGLE_MAX_ITER):
    r"""Static contact angle, deflections and ball load under pure thrust (spec 004 section 5.3).

    Parameters
    ----------
    axial_load : array_like
        Thrust F_a > 0. [N]
    n_balls : array_like
        Number of balls Z. [-]
    ball_diameter : array_like
        Ball diameter D. [m]
    pitch_diameter : array_like
        Pitch diameter d_m. [m]
    inner_conformity, outer_conformity : array_like
        f_i, f_e. [-]
    free_angle : array_like
        alpha0, in (0, 90 deg). [rad]
    reduced_modulus : array_like
        E' of the ball-ring pair. [Pa]
    stiffness_at : {"operating", "free"}, optional
        Evaluate K_i, K_e at the loaded angle (spec 004, the default) or at alpha0 (which is spec 000's
        force characteristic C* = Z K_n (B D)^1.5 with exact Hertz).
    xtol : float, optional
        Converged where abs(Delta alpha) < xtol. [rad]
    max_iter : int, optional
        Iteration limit.

    Returns
    -------
    ThrustContact
        alpha_s [rad], delta_a [m], Q [N], delta_i and delta_e [m], iterations.

    Raises
    ------
    ConvergenceError
        If the Newton iteration does not converge in ``max_iter`` steps.

    Notes
    -----
    .. math:: F_a = Z\,K_n(\alpha)\,[B D(\cos\alpha_0/\cos\alpha - 1)]^{3/2}\sin\alpha,\quad
              K_n = (K_i^{-2/3} + K_e^{-2/3})^{-3/2}

    K_j from :func:`bearinglab.hertz.load_deflection_constant` at the curvature of the loaded angle.
    Newton on (F/F_a)^(2/3) - 1 with the slope of spec 000 section 6.3 plus the derivative of
    (2/3) ln K_n by central differences; started from spec 000's x0. delta_a = (B D + delta_n) sin alpha
    - B D sin alpha0.
    """
    fa = check_positive("axial_load", axial_load, "N")
    z = check_integer("n_balls", n_balls, 1)
    d = check_positive("ball_diameter", ball_diameter, "m")
    dm = check_positive("pitch_diameter", pitch_diameter, "m")
    a0 = _angle("free_angle", free_angle)
    ep = check_positive("reduced_modulus", reduced_modulus, "Pa")
    if stiffness_at not in ("operating", "free"):
        raise InputError(f"stiffness_at must be one of ['operating', 'free'], got {stiffness_at!r}")
    bd = geometry.total_curvature(inner_conformity, outer_conformity) * d
    fa, z, d, dm, fi, fo, a0, ep, bd = np.broadcast_arrays(fa, z, d, dm, np.asarray(inner_conformity, float),
                                                           np.asarray(outer_conformity, float), a0, ep, bd)

    def stiffness(angle):
        return _series_stiffness(*_contact_stiffness(d, dm, fi, fo, angle, ep))

    k0 = _contact_stiffness(d, dm, fi, fo, a0, ep)  # K_i, K_e at alpha0 (reused for "free")
    kn0 = _series_stiffness(*k0)
    alpha = a0 + first_approximation(fa / (z * kn0 * bd**1.5), a0)
    alpha = np.minimum(alpha, 0.5 * (a0 + np.pi / 2))
    h = 1e-7
    # converged cases are frozen while the others go on: a case's angle does not depend on its batch or chunk
    live = np.ones(np.shape(alpha), dtype=bool)
    for it in range(1, max_iter + 1):
        if stiffness_at == "free":
            kn, dlnk = kn0, 0.0
        else:
            kn = stiffness(alpha)
            dlnk = (np.log(stiffness(alpha + h)) - np.log(stiffness(alpha - h))) / (2 * h)
        c = np.cos(a0) / np.cos(alpha) - 1.0
        thrust = z * kn * (bd * c) ** 1.5 * np.sin(alpha)
        gap = np.cos(a0) - np.cos(alpha)
        slope = np.tan(alpha) + (2.0 / 3.0) / np.tan(alpha) + np.sin(alpha) / gap + (2.0 / 3.0) * dlnk
        dx = ((fa / thrust) ** (2.0 / 3.0) - 1.0) / slope
        new = alpha + dx
        new = np.where(new <= a0, 0.5 * (alpha + a0), new)
        new = np.where(new >= np.pi / 2, 0.5 * (alpha + np.pi / 2), new)
        alpha = np.where(live, new, alpha)
        live &= np.abs(dx) >= xtol
        if not live.any():
            break
    else:
        raise ConvergenceError("static.contact_angle_under_thrust", iterations=max_iter,
                               residual=(thrust - fa) / fa, estimate=alpha)
    k_i, k_e = k0 if stiffness_at == "free" else _contact_stiffness(d, dm, fi, fo, alpha, ep)
    q = fa / (z * np.sin(alpha))
    delta_n = bd * (np.cos(a0) / np.cos(alpha) - 1.0)
    delta_a = (bd + delta_n) * np.sin(alpha) - bd * np.sin(a0)
    return ThrustContact(alpha[()], delta_a[()], q[()], ((q / k_i) ** (2.0 / 3.0))[()], ((q / k_e) ** (2.0 / 3.0))[()], it)

r"""One ball at speed: body forces and kinematics of spec 004 eqs. (8)-(13).

Constants of the printed equations
----------------------------------
printed_constants              the constants of eqs. (8) and (12), in N, mm, rpm, from a ball density
HARRIS_CENTRIFUGAL_CONSTANT, HARRIS_GYROSCOPIC_CONSTANT, PAPER_GYROSCOPIC_CONSTANT, CONSTANTS

Body forces
-----------
centrifugal_force              F_c = m (d_m/2) omega_m^2                                   eq. (8)
gyroscopic_moment              M_g = J omega_R omega_m sin(beta), J = m D^2/10              eq. (12)

Kinematics
----------
attitude_angle                 ball attitude angle beta, outer- or inner-raceway control    eq. (10)
ball_speeds                    cage (orbital) and ball-spin speeds, outer ring fixed        eqs. (9), (13)
RACEWAY_CONTROLS               lambda_i, lambda_e of each raceway-control assumption

Raceway control
---------------
required_friction_coefficient  2 M_g / (D Q_e), the friction outer-raceway control needs
FRICTION_WARNING_LIMIT         the coefficient above which that control is implausible
friction_coefficient           deprecated alias of required_friction_coefficient

These functions take arrays and broadcast; they are the pieces the pure-thrust model
(:mod:`bearinglab.quasistatic.thrust`) and the combined-load model assemble.

References
----------
.. [1] Zhao Chunjiang, Cui Guohua, Wang Guoqiang, Huang Qingxue and Zhang Fangping, "Precise definition
   of the contact-angle field of a high-speed angular-contact ball bearing under axial load,"
   Transactions of the CSAM, vol. 39, no. 12, pp. 154-156, 209, 2008 (spec 004 of this project).
.. [2] A. B. Jones, "A general theory for elastically constrained ball and radial roller bearings under
   arbitrary load and speed conditions," J. Basic Eng., vol. 82, no. 2, pp. 309-320, 1960,
   doi:10.1115/1.3662587.
.. [3] T. A. Harris and M. N. Kotzalas, *Advanced Concepts of Bearing Technology*, 5th ed., CRC Press,
   2006, ch. 3 (high-speed ball bearings), doi:10.1201/9781420006582.
"""

from __future__ import annotations

import math  # noqa: F401  (the doctests use it)
import warnings
from typing import NamedTuple

import numpy as np

from .._validate import (
    as_float,
    check_greater,
    check_nonnegative,
    check_open_interval,
    check_positive,
)
from ..errors import InputError
from ..units import MM, RPM

__all__ = [
    "CONSTANTS",
    "FRICTION_WARNING_LIMIT",
    "HARRIS_CENTRIFUGAL_CONSTANT",
    "HARRIS_GYROSCOPIC_CONSTANT",
    "PAPER_GYROSCOPIC_CONSTANT",
    "RACEWAY_CONTROLS",
    "BallSpeeds",
    "PrintedConstants",
    "attitude_angle",
    "ball_speeds",
    "centrifugal_force",
    "friction_coefficient",
    "gyroscopic_moment",
    "printed_constants",
    "required_friction_coefficient",
]

#: Constant of eq. (8), F_c = C d_m D^3 n_m^2 [N; mm; rpm] (Harris; the paper prints the same).
HARRIS_CENTRIFUGAL_CONSTANT = 2.26e-11
#: Constant of eq. (12), M_g = C D^5 n_b n_m sin(beta) [N mm; mm; rpm], Harris's value.
HARRIS_GYROSCOPIC_CONSTANT = 4.47e-12
#: The paper's constant of eq. (12) (OCR "415 @ 10-12").
PAPER_GYROSCOPIC_CONSTANT = 4.5e-12
#: Named sets of (centrifugal, gyroscopic) constants; "mass" derives both from the ball's mass.
CONSTANTS = {
    "mass": None,
    "harris": (HARRIS_CENTRIFUGAL_CONSTANT, HARRIS_GYROSCOPIC_CONSTANT),
    "paper": (HARRIS_CENTRIFUGAL_CONSTANT, PAPER_GYROSCOPIC_CONSTANT),
}
#: Raceway-control assumptions: lambda_i, lambda_e of eqs. (5)-(7).
RACEWAY_CONTROLS = {"outer": (0.0, 2.0), "inner": (2.0, 0.0)}
#: Implied friction coefficient 2 M_g/(D Q_e) above which outer-raceway control is implausible: lubricated
#: (EHL) traction coefficients rarely exceed about 0.1 (Harris and Kotzalas, module reference [3], ch. 4).
FRICTION_WARNING_LIMIT = 0.1


def _angle(name, value):
    return check_open_interval(name, value, 0.0, np.pi / 2, "deg", scale=180.0 / np.pi)


def _speed(name, value):
    w = as_float(name, value)
    bad = ~(w >= 0) | ~np.isfinite(w)
    if bad.any():
        first = float(np.asarray(w)[bad].flat[0]) if np.ndim(w) else float(w)
        raise InputError(f"{name} must be >= 0 and finite [rpm], got {first / RPM:g} rpm: give the speed of the inner "
                         "ring as a magnitude (the model is symmetric in the direction of rotation)")
    return w


def _control(raceway_control):
    if raceway_control not in RACEWAY_CONTROLS:
        raise InputError(f"raceway_control must be one of {list(RACEWAY_CONTROLS)}, got {raceway_control!r}")
    return RACEWAY_CONTROLS[raceway_control]


# --------------------------------------------------------------------------- body forces
class PrintedConstants(NamedTuple):
    """The constants of eqs. (8) and (12) for a ball density, in the printed units."""

    centrifugal: float  # F_c = C d_m D^3 n_m^2 [N; mm; rpm]
    gyroscopic: float  # M_g = C D^5 n_b n_m sin(beta) [N mm; mm; rpm]


def printed_constants(density):
    r"""The constants of spec 004 eqs. (8) and (12) that follow from the ball density.

    Parameters
    ----------
    density : array_like
        Ball density rho. [kg/m^3]

    Returns
    -------
    PrintedConstants
        ``centrifugal`` = (pi rho/12) (2 pi/60)^2 in N, mm, rpm and ``gyroscopic`` = (pi rho/60) (2 pi/60)^2
        in N mm, mm, rpm.

    Notes
    -----
    F_c = m (d_m/2) omega_m^2 and M_g = (m D^2/10) omega_R omega_m sin(beta) with m = rho pi D^3/6. For
    steel at 7850 kg/m^3 they are 2.2537e-11 and 4.5074e-12: the paper's 4.5e-12 is this value; Harris's
    2.26e-11 corresponds to 7872 kg/m^3 and his 4.47e-12 to 7785 kg/m^3 (no one density gives both).

    Examples
    --------
    >>> c = printed_constants(7850.0)
    >>> print(f"{c.centrifugal:.4e} {c.gyroscopic:.4e}")
    2.2537e-11 4.5074e-12
    """
    rho = check_positive("density", density, "kg/m^3")
    mass_per_mm3 = rho * np.pi / 6.0 * MM**3  # kg per mm^3 of D^3
    fc = mass_per_mm3 * (MM / 2.0) * RPM**2  # N per (mm^4 rpm^2)
    mg = mass_per_mm3 / 10.0 * MM**2 * RPM**2 / MM  # N mm per (mm^5 rpm^2)
    return PrintedConstants(fc[()], mg[()])


def centrifugal_force(cage_speed, ball_mass, pitch_diameter):
    r"""Centrifugal force of a ball orbiting on the pitch circle, eq. (8).

    Parameters
    ----------
    cage_speed : array_like
        Ball orbital (cage) speed omega_m. [rad/s]
    ball_mass : array_like
        Mass of one ball m. [kg]
    pitch_diameter : array_like
        Pitch diameter d_m. [m]

    Returns
    -------
    ndarray
        F_c = m (d_m/2) omega_m^2. [N]

    Notes
    -----
    Eq. (8) prints F_c = 2.26e-11 d_m D^3 n_m^2 [N; mm; rpm] for steel; see :func:`printed_constants`.

    Examples
    --------
    >>> from bearinglab.units import RPM
    >>> m = 7850 * math.pi * 22.23e-3**3 / 6
    >>> print(f"{centrifugal_force(4518.0 * RPM, m, 125.3e-3):.1f} N")
    633.2 N
    """
    w = as_float("cage_speed", cage_speed)
    m = check_nonnegative("ball_mass", ball_mass, "kg")
    dm = check_positive("pitch_diameter", pitch_diameter, "m")
    return (m * dm / 2.0 * w**2)[()]


def gyroscopic_moment(ball_spin_speed, cage_speed, attitude_angle, ball_mass, ball_diameter):
    r"""Gyroscopic moment on a ball, eq. (12), as a magnitude.

    Parameters
    ----------
    ball_spin_speed : array_like
        Ball speed about its own axis omega_R (magnitude). [rad/s]
    cage_speed : array_like
        Orbital (cage) speed omega_m. [rad/s]
    attitude_angle : array_like
        Ball attitude angle beta. [rad]
    ball_mass : array_like
        Mass of one ball m. [kg]
    ball_diameter : array_like
        Ball diameter D. [m]

    Returns
    -------
    ndarray
        M_g = J abs(omega_R omega_m) sin(beta), J = m D^2/10. [N m]

    Notes
    -----
    Eq. (12) prints M_g = C D^5 n_b n_m sin(beta) [N mm; mm; rpm] with C = 4.5e-12 (paper) or 4.47e-12
    (Harris); see :func:`printed_constants`.

    Examples
    --------
    >>> from bearinglab.units import RPM
    >>> m = 7850 * math.pi * 22.23e-3**3 / 6
    >>> mg = gyroscopic_moment(29376 * RPM, 4518.0 * RPM, math.radians(27.772), m, 22.23e-3)
    >>> print(f"{mg * 1e3:.1f} N mm")
    1513.2 N mm
    """
    wr = as_float("ball_spin_speed", ball_spin_speed)
    wm = as_float("cage_speed", cage_speed)
    beta = as_float("attitude_angle", attitude_angle)
    m = check_nonnegative("ball_mass", ball_mass, "kg")
    d = check_positive("ball_diameter", ball_diameter, "m")
    return (m * d**2 / 10.0 * np.abs(wr * wm) * np.sin(beta))[()]


# --------------------------------------------------------------------------- kinematics
def _beta(si, ci, se, ce, g, control):
    """Attitude angle (eq. 10) and its derivatives with respect to alpha_i and alpha_e."""
    if control == "outer":
        beta = np.arctan2(se, ce + g)  # tan beta = sin a_e / (cos a_e + D/d_m)
        return beta, 0.0, (1.0 + g * ce) / (1.0 + 2.0 * g * ce + g * g)
    beta = np.arctan2(si, ci - g)  # inner-raceway control: tan beta = sin a_i / (cos a_i - D/d_m)
    return beta, (1.0 - g * ci) / (1.0 - 2.0 * g * ci + g * g), 0.0


def attitude_angle(contact_angle_inner, contact_angle_outer, ball_diameter, pitch_diameter, *,
                   raceway_control="outer"):
    r"""Ball attitude angle beta (spin axis against the bearing axis), eq. (10).

    Parameters
    ----------
    contact_angle_inner, contact_angle_outer : array_like
        alpha_i, alpha_e. [rad]
    ball_diameter : array_like
        D. [m]
    pitch_diameter : array_like
        d_m. [m]
    raceway_control : {"outer", "inner"}, optional
        Which raceway controls the ball (no spin at that contact).

    Returns
    -------
    ndarray
        beta. [rad]

    Notes
    -----
    Outer-raceway control: :math:`\tan\beta = \sin\alpha_e/(\cos\alpha_e + D/d_m)`, equal to the
    paper's :math:`\sin\alpha_e\cos\alpha_e/(\cos^2\alpha_e + \gamma_e)`. Inner-raceway control (Harris,
    module reference [3]): :math:`\tan\beta = \sin\alpha_i/(\cos\alpha_i - D/d_m)`.

    Examples
    --------
    >>> b = attitude_angle(math.radians(49.308), math.radians(32.514), 22.23e-3, 125.3e-3)
    >>> print(f"{math.degrees(b):.3f}")
    27.772
    """
    ai = as_float("contact_angle_inner", contact_angle_inner)
    ae = as_float("contact_angle_outer", contact_angle_outer)
    d = check_positive("ball_diameter", ball_diameter, "m")
    dm = check_greater("pitch_diameter", pitch_diameter, "ball_diameter", d, "m")
    _control(raceway_control)
    beta = _beta(np.sin(ai), np.cos(ai), np.sin(ae), np.cos(ae), d / dm, raceway_control)[0]
    return np.asarray(beta)[()]


class BallSpeeds(NamedTuple):
    """Cage and ball-spin speeds of a ball under thrust at speed."""

    cage_speed: np.ndarray  # orbital speed omega_m [rad/s]
    ball_spin_speed: np.ndarray  # omega_R about the ball's own axis, magnitude [rad/s]


def _kinematics(si, ci, se, ce, ai, ae, g, control, deriv):
    """beta, omega_m/omega, omega_R/omega (eqs. 9, 10, 13) and, if ``deriv``, their partials."""
    beta, db_i, db_e = _beta(si, ci, se, ce, g, control)
    gi, ge = g * ci, g * ce
    ceb, seb = np.cos(ae - beta), np.sin(ae - beta)
    cib, sib = np.cos(ai - beta), np.sin(ai - beta)
    p = (1.0 - gi) * ceb
    r = (1.0 + ge) * cib
    den = p + r
    n = (1.0 - gi) * (1.0 + ge)
    cage = p / den  # eq. (9), n_e = 0
    spin = n / (g * den)  # eq. (13) divided by n_i; d_m/D = 1/g
    out = {"beta": beta, "cage": cage, "spin": spin}
    if deriv:
        dp_i = g * si * ceb + (1.0 - gi) * seb * db_i
        dp_e = -(1.0 - gi) * seb * (1.0 - db_e)
        dr_i = -(1.0 + ge) * sib * (1.0 - db_i)
        dr_e = -g * se * cib + (1.0 + ge) * sib * db_e
        dn_i = g * si * (1.0 + ge)
        dn_e = -(1.0 - gi) * g * se
        den2 = den * den
        out["cage_i"] = (dp_i * r - p * dr_i) / den2
        out["cage_e"] = (dp_e * r - p * dr_e) / den2
        out["spin_i"] = (dn_i * den - n * (dp_i + dr_i)) / (g * den2)
        out["spin_e"] = (dn_e * den - n * (dp_e + dr_e)) / (g * den2)
        out["beta_i"], out["beta_e"] = db_i, db_e
    return out


def ball_speeds(shaft_speed, contact_angle_inner, contact_angle_outer, attitude_angle, ball_diameter, pitch_diameter):
    r"""Cage (orbital) speed and ball-spin speed with the outer ring fixed, eqs. (9) and (13).

    Parameters
    ----------
    shaft_speed : array_like
        Inner-ring speed omega_i >= 0. [rad/s]
    contact_angle_inner, contact_angle_outer : array_like
        alpha_i, alpha_e. [rad]
    attitude_angle : array_like
        beta (see :func:`attitude_angle`). [rad]
    ball_diameter : array_like
        D. [m]
    pitch_diameter : array_like
        d_m. [m]

    Returns
    -------
    BallSpeeds
        ``cage_speed`` omega_m and ``ball_spin_speed`` omega_R. [rad/s]

    Notes
    -----
    With gamma_j = D cos(alpha_j)/d_m and :math:`\Delta = (1+\gamma_e)\cos(\alpha_i-\beta) +
    (1-\gamma_i)\cos(\alpha_e-\beta)`: :math:`\omega_m = \omega_i (1-\gamma_i)\cos(\alpha_e-\beta)/\Delta`
    and :math:`\omega_R = (d_m/D)(1-\gamma_i)(1+\gamma_e)\,\omega_i/\Delta`.

    Examples
    --------
    >>> from bearinglab.units import RPM
    >>> s = ball_speeds(10000 * RPM, math.radians(49.308), math.radians(32.514), math.radians(27.772),
    ...                 22.23e-3, 125.3e-3)
    >>> print(f"{s.cage_speed / RPM:.1f} {s.ball_spin_speed / RPM:.0f}")
    4518.0 29376
    """
    w = _speed("shaft_speed", shaft_speed)
    ai = as_float("contact_angle_inner", contact_angle_inner)
    ae = as_float("contact_angle_outer", contact_angle_outer)
    beta = as_float("attitude_angle", attitude_angle)
    d = check_positive("ball_diameter", ball_diameter, "m")
    dm = check_positive("pitch_diameter", pitch_diameter, "m")
    g = d / dm
    gi, ge = g * np.cos(ai), g * np.cos(ae)
    den = (1.0 + ge) * np.cos(ai - beta) + (1.0 - gi) * np.cos(ae - beta)
    cage = w * (1.0 - gi) * np.cos(ae - beta) / den
    spin = w * (1.0 - gi) * (1.0 + ge) / (g * den)
    return BallSpeeds(np.asarray(cage)[()], np.asarray(spin)[()])


def required_friction_coefficient(gyroscopic_moment, ball_load_outer, ball_diameter):
    r"""Friction coefficient that outer-raceway control needs, mu = 2 M_g / (D Q_e).

    Parameters
    ----------
    gyroscopic_moment : array_like
        M_g. [N m]
    ball_load_outer : array_like
        Q_e. [N]
    ball_diameter : array_like
        D. [m]

    Returns
    -------
    ndarray
        mu. [-]

    Notes
    -----
    The outer contact alone resists the gyroscopic moment (spec 004 section 4): the friction force there
    is 2 M_g/D. Above about 0.1 (:data:`FRICTION_WARNING_LIMIT`) a lubricated contact cannot supply it
    and the balls spin or skid instead; :func:`bearinglab.quasistatic.contact_angles` warns. This is a
    *required* coefficient, an output of the model; the ball-race sliding friction coefficient of the
    test-stand criterion is an input (:func:`bearinglab.stand.min_axial_load_gyroscopic`).

    Examples
    --------
    >>> print(f"{required_friction_coefficient(2.7200, 2835.4, 22.23e-3):.3f}")
    0.086
    """
    mg = as_float("gyroscopic_moment", gyroscopic_moment)
    q = as_float("ball_load_outer", ball_load_outer)
    d = check_positive("ball_diameter", ball_diameter, "m")
    with np.errstate(divide="ignore", invalid="ignore"):
        return (2.0 * mg / (d * q))[()]




def friction_coefficient(gyroscopic_moment, ball_load_outer, ball_diameter):
    """Deprecated alias of :func:`required_friction_coefficient` (the name said too little).

    Parameters
    ----------
    gyroscopic_moment : array_like
        M_g. [N m]
    ball_load_outer : array_like
        Q_e. [N]
    ball_diameter : array_like
        D. [m]

    Returns
    -------
    ndarray
        mu. [-]
    """
    warnings.warn("quasistatic.friction_coefficient is deprecated, use quasistatic.required_friction_coefficient",
                  DeprecationWarning, stacklevel=2)
    return required_friction_coefficient(gyroscopic_moment, ball_load_outer, ball_diameter)


# --------------------------------------------------------------------------- for the combined-load model
def _dynamics(si, ci, so, co, g, control, inertia, mass, dm):
    """Centrifugal force and gyroscopic moment per omega^2 and their partials in (alpha_i, alpha_o).

    Outer ring fixed: attitude (eq. 10), cage and spin speeds (eqs. 9, 13), F_c = m (d_m/2) omega_m^2
    (eq. 8), M_g = J omega_R omega_m sin(beta) (eq. 12), signed with beta so that a ball loaded on the
    other shoulder (negative angles) is the mirror image; :func:`bearinglab.quasistatic.ball_speeds`.
    """
    if control == "outer":  # tan beta = sin a_o / (cos a_o + D/d_m)
        y, x = so, co + g
        b_i, b_o = 0.0, (1.0 + g * co) / (1.0 + 2.0 * g * co + g * g)
    else:  # tan beta = sin a_i / (cos a_i - D/d_m)
        y, x = si, ci - g
        b_i, b_o = (1.0 - g * ci) / (1.0 - 2.0 * g * ci + g * g), 0.0
    r = np.hypot(y, x)
    sb, cb = y / r, x / r  # sin and cos of beta = atan2(y, x)
    c_ob, s_ob = co * cb + so * sb, so * cb - co * sb  # cos, sin(alpha_o - beta)
    c_ib, s_ib = ci * cb + si * sb, si * cb - ci * sb
    p, r = (1.0 - g * ci) * c_ob, (1.0 + g * co) * c_ib
    p_i, p_o = g * si * c_ob + (1.0 - g * ci) * s_ob * b_i, -(1.0 - g * ci) * s_ob * (1.0 - b_o)
    r_i, r_o = -(1.0 + g * co) * s_ib * (1.0 - b_i), -g * so * c_ib + (1.0 + g * co) * s_ib * b_o
    nn = (1.0 - g * ci) * (1.0 + g * co)
    n_i, n_o = g * si * (1.0 + g * co), -(1.0 - g * ci) * g * so
    den = p + r
    cage, spin = p / den, nn / (g * den)
    cage_i, cage_o = (p_i * r - p * r_i) / den**2, (p_o * r - p * r_o) / den**2
    spin_i = (n_i * den - nn * (p_i + r_i)) / (g * den**2)
    spin_o = (n_o * den - nn * (p_o + r_o)) / (g * den**2)
    fc = mass * dm / 2.0 * cage**2
    mg = inertia * spin * cage * sb
    mg_i = inertia * (spin_i * cage * sb + spin * cage_i * sb + spin * cage * cb * b_i)
    mg_o = inertia * (spin_o * cage * sb + spin * cage_o * sb + spin * cage * cb * b_o)
    return fc, mass * dm * cage * cage_i, mass * dm * cage * cage_o, mg, mg_i, mg_o

r"""High-speed angular-contact ball bearing under pure thrust: the quasi-static model of spec 004.

Ball centrifugal force and gyroscopic moment pull the inner and outer contact angles apart at speed.
Under pure thrust every ball is in the same state, so the model is one ball plus the ring (spec 004
section 3): five equations in the ball-centre position, the two contact deflections and the axial
displacement of the inner ring.

Ball dynamics (spec 004 eqs. 8-13)
----------------------------------
printed_constants         the constants of eqs. (8) and (12), in N, mm, rpm, from a ball density
centrifugal_force         F_c = m (d_m/2) omega_m^2                                   eq. (8)
gyroscopic_moment         M_g = J omega_R omega_m sin(beta), J = m D^2/10              eq. (12)
attitude_angle            ball attitude angle beta, outer- or inner-raceway control    eq. (10)
ball_speeds               cage (orbital) and ball-spin speeds, outer ring fixed        eqs. (9), (13)
friction_coefficient      2 M_g / (D Q_e), the friction outer-raceway control needs

Contact (spec 004 eqs. 14-21)
-----------------------------
contact_stiffness         K_i, K_e at the operating angles, exact Hertz (:mod:`bearinglab.hertz`)

Equilibrium and solvers (spec 004 section 5)
--------------------------------------------
residual                  scaled residuals and Jacobian of the five equations (section 5.1)
angle_residual            E3 and E7 of the paper's contact-angle iteration for trial angles (section 5.2)
contact_angles            the solution for arrays of loads and speeds: batched Newton-Raphson with
                          continuation in speed (5.1), or the paper's contact-angle search (5.2)
zero_displacement_thrust  the thrust at which the axial displacement changes sign, per speed

Analyses on a :class:`~bearinglab.bearing.BallBearing`
------------------------------------------------------
high_speed_analysis       one bearing, loads and speeds broadcast against each other
sign_change_thrust        the thrust at which delta_a changes sign, for one bearing and its speeds
sweep                     a loads x speeds grid in one batched call; failures flagged per case
result_table              the result as columns in engineering units (CSV, JSON)

Conventions: the outer ring is fixed and the inner ring turns at ``shaft_speed`` >= 0 (the model is
symmetric in the direction of rotation); the thrust acts on the inner ring. The gyroscopic moment M_g
is a magnitude (>= 0) and the friction that resists it enters eqs. (5)-(7) with the physical sign of
spec 004 section 4.

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

import math
import warnings
from typing import NamedTuple

import numpy as np
from numpy.polynomial import chebyshev as _cheb

from .. import _solve, geometry, hertz, parallel, static
from .._validate import (
    as_float,
    check_greater,
    check_integer,
    check_nonnegative,
    check_open_interval,
    check_positive,
)
from ..errors import ConvergenceError, InputError, ValidityWarning
from ..units import MM, RPM

__all__ = [
    "CONSTANTS",
    "FRICTION_WARNING_LIMIT",
    "HARRIS_CENTRIFUGAL_CONSTANT",
    "HARRIS_GYROSCOPIC_CONSTANT",
    "PAPER_GYROSCOPIC_CONSTANT",
    "RACEWAY_CONTROLS",
    "STATUS",
    "AngleResidual",
    "BallSpeeds",
    "HighSpeedState",
    "PrintedConstants",
    "Residual",
    "Stiffness",
    "angle_residual",
    "attitude_angle",
    "ball_speeds",
    "centrifugal_force",
    "contact_angles",
    "contact_stiffness",
    "friction_coefficient",
    "gyroscopic_moment",
    "high_speed_analysis",
    "printed_constants",
    "residual",
    "result_table",
    "sign_change_thrust",
    "sweep",
    "zero_displacement_thrust",
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
#: Per-case status codes of :class:`HighSpeedState` (index = code).
STATUS = ("ok", "no_convergence", "inner_contact_lost", "outer_contact_lost", "angle_out_of_range",
          "search_not_root")
#: Implied friction coefficient 2 M_g/(D Q_e) above which outer-raceway control is implausible: lubricated
#: (EHL) traction coefficients rarely exceed about 0.1 (Harris and Kotzalas [3]_, ch. 4).
FRICTION_WARNING_LIMIT = 0.1

_OK, _NOCONV, _INNER_LOST, _OUTER_LOST, _ANGLE_OUT, _NOT_ROOT = range(6)
_STATUS_TEXT = {
    _NOCONV: "no convergence",
    _INNER_LOST: "the ball leaves the inner raceway (delta_i <= 0 or Q_i < 0): thrust too small for the speed",
    _OUTER_LOST: "the ball leaves the outer raceway (delta_e <= 0)",
    _ANGLE_OUT: "a contact angle leaves (0, 90) deg: thrust too small for the speed",
    _NOT_ROOT: "the minimum of the contact-angle search is not a root (sum E^2 >= 1e-20)",
}
_N_CHEB = 16  # Chebyshev nodes of ln K(cos alpha); reproduces hertz to ~1e-13 (tests/test_quasistatic.py)
_ROOT_TOL = 1e-20  # scaled sum of squares below which a search minimum is a root (spec 004 section 5.2)
_GRID = 61  # search grid of section 5.2


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


# --------------------------------------------------------------------------- ball dynamics
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
        M_g = J |omega_R omega_m| sin(beta), J = m D^2/10. [N m]

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
    paper's :math:`\sin\alpha_e\cos\alpha_e/(\cos^2\alpha_e + \gamma_e)`. Inner-raceway control (Harris
    [3]_): :math:`\tan\beta = \sin\alpha_i/(\cos\alpha_i - D/d_m)`.

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


def friction_coefficient(gyroscopic_moment, ball_load_outer, ball_diameter):
    r"""Friction coefficient that outer-raceway control implies, mu = 2 M_g / (D Q_e).

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
    and the balls spin or skid instead; :func:`contact_angles` warns.

    Examples
    --------
    >>> print(f"{friction_coefficient(2.7200, 2835.4, 22.23e-3):.3f}")
    0.086
    """
    mg = as_float("gyroscopic_moment", gyroscopic_moment)
    q = as_float("ball_load_outer", ball_load_outer)
    d = check_positive("ball_diameter", ball_diameter, "m")
    with np.errstate(divide="ignore", invalid="ignore"):
        return (2.0 * mg / (d * q))[()]


# --------------------------------------------------------------------------- contact stiffness
class Stiffness(NamedTuple):
    """Load-deflection constants of the two contacts, Q = K delta^1.5."""

    inner: np.ndarray  # K_i [N/m^1.5]
    outer: np.ndarray  # K_e [N/m^1.5]


def contact_stiffness(contact_angle_inner, contact_angle_outer, ball_diameter, pitch_diameter, inner_conformity,
                      outer_conformity, reduced_modulus):
    r"""Load-deflection constants K_i, K_e at the operating contact angles, eqs. (16)-(21).

    Parameters
    ----------
    contact_angle_inner, contact_angle_outer : array_like
        alpha_i, alpha_e at which the curvatures are evaluated. [rad]
    ball_diameter : array_like
        D. [m]
    pitch_diameter : array_like
        d_m. [m]
    inner_conformity, outer_conformity : array_like
        f_i, f_e. [-]
    reduced_modulus : array_like
        E' of the ball-ring pair. [Pa]

    Returns
    -------
    Stiffness
        K_i and K_e. [N/m^1.5]

    Notes
    -----
    Curvature sums and F(rho) from :func:`bearinglab.geometry.raceway_curvature`, K from
    :func:`bearinglab.hertz.load_deflection_constant` (exact delta*). Eq. (16)'s 2.15e5 N/mm^1.5 is
    (2^1.5/3) E' for E = 2.075e5 MPa, nu = 0.3, rounded (exact: 2.1498e5).

    Examples
    --------
    >>> k = contact_stiffness(math.radians(40), math.radians(40), 22.23e-3, 125.3e-3, 0.5232, 0.5232,
    ...                       2.15e5 * 1e6 * 3 / 2**1.5)
    >>> print(f"{k.inner * 1e-3**1.5:.5e} {k.outer * 1e-3**1.5:.5e}")
    1.29673e+06 1.34883e+06
    """
    inner = geometry.raceway_curvature(ball_diameter, pitch_diameter, inner_conformity, contact_angle_inner,
                                       race="inner")
    outer = geometry.raceway_curvature(ball_diameter, pitch_diameter, outer_conformity, contact_angle_outer,
                                       race="outer")
    return Stiffness(hertz.load_deflection_constant(inner.curvature_sum, inner.curvature_difference, reduced_modulus),
                     hertz.load_deflection_constant(outer.curvature_sum, outer.curvature_difference, reduced_modulus))


def _hertz_tables(d, dm, fi, fo, ep):
    """Chebyshev series in x = 2 cos(alpha) - 1 of the exact Hertz quantities, one row per geometry.

    The exact Hertz solution (an iterative inversion of elliptic integrals, :mod:`bearinglab.hertz`) is
    computed once per bearing on _N_CHEB nodes instead of at every Newton iteration. Per race the result
    holds the coefficients of ln K and of its derivative in cos(alpha), and those of ln kappa, ln a*,
    ln b*, ln delta* (shape (4, G, n)). The interpolants reproduce :func:`contact_stiffness` and
    :func:`bearinglab.hertz.coefficients` to ~1e-13 relative (all are analytic in cos alpha on [0, 1]);
    tests/test_quasistatic.py checks it.
    """
    k = np.arange(_N_CHEB)
    x = np.cos(np.pi * (k + 0.5) / _N_CHEB)
    alpha = np.arccos((x + 1.0) / 2.0)
    shape = (len(d), _N_CHEB)
    d_, dm_, fi_, fo_, ep_ = (np.broadcast_to(v[:, None], shape).ravel() for v in (d, dm, fi, fo, ep))
    a = np.broadcast_to(alpha[None, :], shape).ravel()
    inner = geometry.raceway_curvature(d_, dm_, fi_, a, race="inner")
    outer = geometry.raceway_curvature(d_, dm_, fo_, a, race="outer")
    both = hertz.coefficients(np.concatenate([inner.curvature_difference, outer.curvature_difference]))
    m = a.size
    tables = []
    for j, curv in enumerate((inner, outer)):
        c = hertz.HertzCoefficients(*(np.asarray(f)[j * m:(j + 1) * m] for f in both))
        kk = hertz.load_deflection_constant(curv.curvature_sum, curv.curvature_difference, ep_, hertz=c)
        vals = np.log(np.stack([kk, c.ellipticity, c.a_star, c.b_star, c.delta_star]).reshape((5,) + shape))
        coef = np.stack([_cheb.chebfit(x, v.T, _N_CHEB - 1).T for v in vals])  # (5, G, n)
        dcoef = 2.0 * _cheb.chebder(coef[0], axis=1)  # d ln K / d cos(alpha) = 2 d/dx
        if len(d) == 1:
            coef, dcoef = coef[:, 0], dcoef[0]
        tables.append({"k": (coef[0], dcoef), "hertz": coef[1:]})
    return tables


def _cheb_eval(coef, x):
    """Clenshaw sum of Chebyshev series; ``coef`` is (n,) or one row per element of ``x`` (m, n)."""
    if coef.ndim == 1:
        return _cheb.chebval(x, coef)
    b1 = np.zeros_like(x)
    b2 = np.zeros_like(x)
    for j in range(coef.shape[1] - 1, 0, -1):  # over the series degree, not over cases
        b1, b2 = coef[:, j] + 2.0 * x * b1 - b2, b1
    return coef[:, 0] + x * b1 - b2


# --------------------------------------------------------------------------- the model
class _Model(NamedTuple):
    fa: np.ndarray  # per case (N,)
    z: np.ndarray
    d: np.ndarray
    dm: np.ndarray
    fi: np.ndarray
    fo: np.ndarray
    a0: np.ndarray
    ep: np.ndarray
    ax0: np.ndarray  # B D sin a0
    az: np.ndarray  # B D cos a0
    mass_c: np.ndarray  # mass in F_c = m (d_m/2) w_m^2
    inertia: np.ndarray  # J in M_g = J w_R w_m sin beta
    fs: np.ndarray  # force scale of the residuals
    lam_i: float
    lam_e: float
    sign: float
    control: str
    gid: np.ndarray  # geometry index into the stiffness tables
    t_inner: dict  # Chebyshev tables of the exact Hertz quantities, see _hertz_tables
    t_outer: dict


def _control(raceway_control):
    if raceway_control not in RACEWAY_CONTROLS:
        raise InputError(f"raceway_control must be one of {list(RACEWAY_CONTROLS)}, got {raceway_control!r}")
    return RACEWAY_CONTROLS[raceway_control]


def _constants(constants):
    if isinstance(constants, str):
        if constants not in CONSTANTS:
            raise InputError(f"constants must be one of {list(CONSTANTS)} or a pair (C_c, C_g), got {constants!r}")
        return CONSTANTS[constants]
    try:
        cc, cg = (float(c) for c in constants)
    except (TypeError, ValueError) as exc:
        raise InputError(f"constants must be one of {list(CONSTANTS)} or a pair (C_c, C_g), got {constants!r}") from exc
    if not (cc >= 0 and cg >= 0 and math.isfinite(cc) and math.isfinite(cg)):
        raise InputError(f"constants: C_c and C_g must be >= 0 and finite [N; mm; rpm], got ({cc!r}, {cg!r})")
    return cc, cg


def _prepare(axial_load, n_balls, ball_diameter, pitch_diameter, inner_conformity, outer_conformity, free_angle,
             reduced_modulus, density, raceway_control, gyroscopic_sign, constants, shape=None):
    """Check inputs and broadcast them to flat per-case arrays."""
    fa = check_positive("axial_load", axial_load, "N")
    z = check_integer("n_balls", n_balls, 1)
    d = check_positive("ball_diameter", ball_diameter, "m")
    dm = check_positive("pitch_diameter", pitch_diameter, "m")
    geometry.pitch_ratio(d, dm, 0.0)  # d_m > D
    fi = check_open_interval("inner_conformity", inner_conformity, 0.5, np.inf, "-")
    fo = check_open_interval("outer_conformity", outer_conformity, 0.5, np.inf, "-")
    a0 = _angle("free_angle", free_angle)
    ep = check_positive("reduced_modulus", reduced_modulus, "Pa")
    rho = check_positive("density", density, "kg/m^3")
    lam_i, lam_e = _control(raceway_control)
    if gyroscopic_sign not in (1, -1):
        raise InputError(f"gyroscopic_sign must be +1 (physical, spec 004 section 4) or -1 (reversed), "
                         f"got {gyroscopic_sign!r}")
    consts = _constants(constants)
    arrays = np.broadcast_arrays(fa, z, d, dm, fi, fo, a0, ep, rho, *(() if shape is None else (np.empty(shape),)))
    out_shape = arrays[0].shape
    fa, z, d, dm, fi, fo, a0, ep, rho = (np.ascontiguousarray(a, dtype=float).ravel() for a in arrays[:9])
    bd = (fi + fo - 1.0) * d
    if consts is None:
        mass = rho * np.pi * d**3 / 6.0
        mass_c, inertia = mass, mass * d**2 / 10.0
    else:  # the printed constants in N, mm, rpm (steel only), as an equivalent mass and inertia
        mass_c = consts[0] * (d / MM) ** 3 * 2.0 / (MM * RPM**2)
        inertia = consts[1] * (d / MM) ** 5 * MM / RPM**2
    geo = np.stack([d, dm, fi, fo, ep], axis=1)
    if geo.size == 0 or np.all(geo == geo[:1]):  # one bearing: skip the sort of np.unique
        uniq, gid = geo[:1], np.zeros(len(geo), dtype=int)
    else:
        uniq, gid = np.unique(geo, axis=0, return_inverse=True)
    t_in, t_out = _hertz_tables(*uniq.T)
    model = _Model(fa, z.astype(float), d, dm, fi, fo, a0, ep, bd * np.sin(a0), bd * np.cos(a0), mass_c, inertia,
                   np.maximum(fa / z, 1.0), lam_i, lam_e, float(gyroscopic_sign), raceway_control,
                   gid.ravel(), t_in, t_out)
    return model, out_shape


def _take(model, idx):
    """Per-case parameters of the cases ``idx``."""
    names = ("fa", "z", "d", "dm", "fi", "fo", "a0", "ep", "ax0", "az", "mass_c", "inertia", "fs", "gid")
    return {n: getattr(model, n)[idx] for n in names}


def _k(table, gid, c):
    """K and d ln K / d cos(alpha) from the tables."""
    coef, dcoef = table["k"]
    x = 2.0 * c - 1.0
    if coef.ndim == 1:
        return np.exp(_cheb_eval(coef, x)), _cheb_eval(dcoef, x)
    return np.exp(_cheb_eval(coef[gid], x)), _cheb_eval(dcoef[gid], x)


def _hertz_coefficients(table, gid, c):
    """kappa, a*, b*, delta* (exact, through the tables) at cos(alpha) = c."""
    x = 2.0 * c - 1.0
    coef = table["hertz"]
    vals = [np.exp(_cheb_eval(cf if cf.ndim == 1 else cf[gid], x)) for cf in coef]
    return hertz.HertzCoefficients(*vals)


def _forces(model, p, si, ci, se, ce, ai, ae, di, de, w2, deriv):
    """Contact loads, dynamics and the force residuals (5)-(7) at given angles and deflections."""
    g = p["d"] / p["dm"]
    kin = _kinematics(si, ci, se, ce, ai, ae, g, model.control, deriv)
    ki, dlki = _k(model.t_inner, p["gid"], ci)
    ke, dlke = _k(model.t_outer, p["gid"], ce)
    dip, dep = np.maximum(di, 0.0), np.maximum(de, 0.0)
    qi, qe = ki * dip**1.5, ke * dep**1.5
    fc_hat = p["mass_c"] * p["dm"] / 2.0 * kin["cage"] ** 2  # F_c / omega^2
    sb = np.sin(kin["beta"])
    mg_hat = p["inertia"] * kin["spin"] * kin["cage"] * sb  # M_g / omega^2
    m_hat = model.sign * mg_hat / p["d"]
    li, le = model.lam_i, model.lam_e
    ax_t = li * ci - le * ce
    rad_t = li * si - le * se
    fs = p["fs"]
    out = {"kin": kin, "qi": qi, "qe": qe, "ki": ki, "ke": ke, "fc_hat": fc_hat, "mg_hat": mg_hat}
    m = w2 * m_hat
    out["f"] = np.stack([(qi * si - qe * se + m * ax_t) / fs,  # eq. (5)
                         (qi * ci - qe * ce - m * rad_t + w2 * fc_hat) / fs,  # eq. (6)
                         (qi * si + m * li * ci - p["fa"] / p["z"]) / fs], axis=-1)  # eq. (7) / Z
    out["f_w2"] = np.stack([m_hat * ax_t / fs, (-m_hat * rad_t + fc_hat) / fs, m_hat * li * ci / fs], axis=-1)
    if deriv:
        cage, spin = kin["cage"], kin["spin"]
        cb = np.cos(kin["beta"])
        mg_i = p["inertia"] * (kin["spin_i"] * cage * sb + spin * kin["cage_i"] * sb + spin * cage * cb * kin["beta_i"])
        mg_e = p["inertia"] * (kin["spin_e"] * cage * sb + spin * kin["cage_e"] * sb + spin * cage * cb * kin["beta_e"])
        m_i = w2 * model.sign * mg_i / p["d"]
        m_e = w2 * model.sign * mg_e / p["d"]
        fc_i = w2 * p["mass_c"] * p["dm"] * cage * kin["cage_i"]
        fc_e = w2 * p["mass_c"] * p["dm"] * cage * kin["cage_e"]
        qi_a = -qi * si * dlki  # dK/dalpha = K dlnK/dc (-sin alpha)
        qe_a = -qe * se * dlke
        qi_d = 1.5 * ki * np.sqrt(dip)
        qe_d = 1.5 * ke * np.sqrt(dep)
        zero = np.zeros_like(qi)
        # partials of (f3, f4, f5) with respect to (alpha_i, alpha_e, delta_i, delta_e)
        f3 = [qi_a * si + qi * ci + m_i * ax_t - m * li * si,
              -qe_a * se - qe * ce + m_e * ax_t + m * le * se, qi_d * si, -qe_d * se]
        f4 = [qi_a * ci - qi * si - m_i * rad_t - m * li * ci + fc_i,
              -qe_a * ce + qe * se - m_e * rad_t + m * le * ce + fc_e, qi_d * ci, -qe_d * ce]
        f5 = [qi_a * si + qi * ci + m_i * li * ci - m * li * si, m_e * li * ci, qi_d * si, zero]
        out["df"] = np.stack([np.stack(row, axis=-1) for row in (f3, f4, f5)], axis=-2) / fs[..., None, None]
    return out


class Residual(NamedTuple):
    """Scaled residuals of spec 004 section 5.1 (and their Jacobian)."""

    residual: np.ndarray  # (..., 5) [-]
    jacobian: np.ndarray  # (..., 5, 5) d residual / d unknowns (unknowns scaled by D) [-]
    valid: np.ndarray  # delta_i, delta_e > 0 and both angles in (0, 90 deg)


def _equations(model, idx, v, w2, deriv):
    """Residuals r (n, 5), Jacobian (n, 5, 5) w.r.t. v = u / D, validity and the force details."""
    p = _take(model, idx)
    d = p["d"]
    x1, x2, di, de, da = (v[:, k] * d for k in range(5))
    px = p["ax0"] + da - x1  # inner groove centre minus ball centre, eq. (1)
    pz = p["az"] - x2  # eq. (2)
    rho_i = np.hypot(px, pz)
    rho_e = np.hypot(x1, x2)
    si, ci = px / rho_i, pz / rho_i
    se, ce = x1 / rho_e, x2 / rho_e
    ai, ae = np.arctan2(px, pz), np.arctan2(x1, x2)
    li_len = (p["fi"] - 0.5) * d + di
    le_len = (p["fo"] - 0.5) * d + de
    fr = _forces(model, p, si, ci, se, ce, ai, ae, di, de, w2, deriv)
    r = np.concatenate([((rho_i - li_len) / d)[:, None], ((rho_e - le_len) / d)[:, None], fr["f"]], axis=1)
    code = np.full(len(idx), _OK)
    code[~((ae > 0) & (ae < np.pi / 2) & (ai > 0) & (ai < np.pi / 2))] = _ANGLE_OUT
    code[~(de > 0)] = _OUTER_LOST
    code[~(di > 0)] = _INNER_LOST
    jac = None
    if deriv:
        jac = np.zeros((len(idx), 5, 5))
        jac[:, 0, :] = np.stack([-si, -ci, -np.ones_like(si), np.zeros_like(si), si], axis=1)  # d rho_i - d L_i
        jac[:, 1, :] = np.stack([se, ce, np.zeros_like(si), -np.ones_like(si), np.zeros_like(si)], axis=1)
        # d alpha / d (x1, x2, delta_a): alpha_i = atan2(px, pz), alpha_e = atan2(x1, x2)
        dai = np.stack([-ci / rho_i, si / rho_i, ci / rho_i], axis=1)
        dae = np.stack([ce / rho_e, -se / rho_e, np.zeros_like(se)], axis=1)
        df = fr["df"]  # (n, 3, 4): d/d(alpha_i, alpha_e, delta_i, delta_e)
        jac[:, 2:, 0] = df[:, :, 0] * dai[:, None, 0] + df[:, :, 1] * dae[:, None, 0]
        jac[:, 2:, 1] = df[:, :, 0] * dai[:, None, 1] + df[:, :, 1] * dae[:, None, 1]
        jac[:, 2:, 2] = df[:, :, 2] * d[:, None]
        jac[:, 2:, 3] = df[:, :, 3] * d[:, None]
        jac[:, 2:, 4] = df[:, :, 0] * dai[:, None, 2]
        jac[:, 2:, 0:2] *= d[:, None, None]
        jac[:, 2:, 4] *= d[:, None]
    r_w2 = np.concatenate([np.zeros((len(idx), 2)), fr["f_w2"]], axis=1)
    extra = {"ai": ai, "ae": ae, "di": di, "de": de, "da": da, "fr": fr, "p": p, "r_w2": r_w2}
    return r, jac, code, extra


def residual(unknowns, axial_load, shaft_speed, n_balls, ball_diameter, pitch_diameter, inner_conformity,
             outer_conformity, free_angle, reduced_modulus, density, *, raceway_control="outer",
             gyroscopic_sign=1, constants="mass"):
    r"""Scaled residuals and Jacobian of the equilibrium equations of spec 004 section 5.1.

    Parameters
    ----------
    unknowns : array_like
        Shape (..., 5): ball-centre position (X1, X2) from the outer groove-curvature centre, deflections
        delta_i, delta_e and axial displacement delta_a, all divided by the ball diameter D. [-]
    axial_load : array_like
        Thrust F_a. [N]
    shaft_speed : array_like
        Inner-ring speed omega_i >= 0. [rad/s]
    n_balls : array_like
        Z. [-]
    ball_diameter : array_like
        D. [m]
    pitch_diameter : array_like
        d_m. [m]
    inner_conformity, outer_conformity : array_like
        f_i, f_e. [-]
    free_angle : array_like
        alpha0. [rad]
    reduced_modulus : array_like
        E'. [Pa]
    density : array_like
        Density of the balls. [kg/m^3]
    raceway_control : {"outer", "inner"}, optional
        lambda_i, lambda_e = (0, 2) or (2, 0).
    gyroscopic_sign : {1, -1}, optional
        +1 physical (spec 004 section 4); -1 the reversed convention, for comparison only.
    constants : {"mass", "harris", "paper"} or (float, float), optional
        How F_c and M_g are computed (see :func:`contact_angles`).

    Returns
    -------
    Residual
        ``residual`` (..., 5): geometric residuals (distance between ball and groove centres minus
        (f - 0.5) D + delta, divided by D) and eqs. (5), (6), (7)/Z divided by max(F_a/Z, 1 N);
        ``jacobian`` (..., 5, 5) with respect to ``unknowns``; ``valid``.

    Notes
    -----
    :func:`contact_angles` drives these residuals below 1e-12 (Euclidean norm). The Jacobian is
    analytic: the kinematics (9), (10), (13) differentiated in closed form, d ln K/d cos(alpha) from the
    Chebyshev interpolant of the exact Hertz stiffness.
    """
    w = _speed("shaft_speed", shaft_speed)
    v = as_float("unknowns", unknowns)
    if v.shape[-1:] != (5,):
        raise InputError(f"unknowns must have a last axis of length 5 (X1, X2, delta_i, delta_e, delta_a), got shape {v.shape}")
    model, shape = _prepare(axial_load, n_balls, ball_diameter, pitch_diameter, inner_conformity, outer_conformity,
                            free_angle, reduced_modulus, density, raceway_control, gyroscopic_sign, constants,
                            shape=np.broadcast_shapes(v.shape[:-1], np.shape(w)))
    n = model.fa.size
    vv = np.broadcast_to(v, shape + (5,)).reshape(n, 5)
    w2 = np.broadcast_to(w, shape).ravel() ** 2
    r, jac, code, _ = _equations(model, np.arange(n), vv, w2, True)
    return Residual(r.reshape(shape + (5,)), jac.reshape(shape + (5, 5)), (code == _OK).reshape(shape))


class AngleResidual(NamedTuple):
    """The paper's sequence (spec 004 section 5.2, steps 1-5) for trial contact angles."""

    radial: np.ndarray  # E3, radial compatibility, divided by D [-]
    ring: np.ndarray  # E7, ring equilibrium, divided by Z max(F_a/Z, 1 N) [-]
    ball_load_inner: np.ndarray  # Q_i [N]
    ball_load_outer: np.ndarray  # Q_e [N]
    deflection_inner: np.ndarray  # delta_i [m]
    deflection_outer: np.ndarray  # delta_e [m]
    axial_displacement: np.ndarray  # delta_a [m]
    valid: np.ndarray  # Q_i, Q_e >= 0 and the system (5)-(6) not singular


def _angle_sequence(model, idx, ai, ae, w2):
    p = _take(model, idx)
    si, ci, se, ce = np.sin(ai), np.cos(ai), np.sin(ae), np.cos(ae)
    g = p["d"] / p["dm"]
    kin = _kinematics(si, ci, se, ce, ai, ae, g, model.control, False)
    ki = _k(model.t_inner, p["gid"], ci)[0]
    ke = _k(model.t_outer, p["gid"], ce)[0]
    fc = w2 * p["mass_c"] * p["dm"] / 2.0 * kin["cage"] ** 2
    m = w2 * model.sign * p["inertia"] * kin["spin"] * kin["cage"] * np.sin(kin["beta"]) / p["d"]
    li, le = model.lam_i, model.lam_e
    b1 = -m * (li * ci - le * ce)  # eq. (5): Q_i s_i - Q_e s_e = b1
    b2 = m * (li * si - le * se) - fc  # eq. (6): Q_i c_i - Q_e c_e = b2
    det = se * ci - si * ce  # sin(alpha_e - alpha_i)
    with np.errstate(divide="ignore", invalid="ignore"):
        qi = (se * b2 - ce * b1) / det
        qe = (si * b2 - ci * b1) / det
    valid = (np.abs(det) > 1e-12) & (qi >= 0) & (qe >= 0)
    qi_p, qe_p = np.where(valid, qi, 0.0), np.where(valid, qe, 0.0)
    di, de = (qi_p / ki) ** (2.0 / 3.0), (qe_p / ke) ** (2.0 / 3.0)  # eqs. (14), (15)
    d = p["d"]
    li_len = (p["fi"] - 0.5) * d + di
    le_len = (p["fo"] - 0.5) * d + de
    vx = li_len * si  # eq. (22)
    vz = p["az"] - le_len * ce  # eq. (23)
    da = vx + le_len * se - p["ax0"]  # axial closure, A_x = V_x + L_e sin a_e
    e3 = (li_len * ci - vz) / d  # eq. (3): V_z = L_i cos a_i
    e7 = (p["z"] * (qi_p * si + m * li * ci) - p["fa"]) / (p["z"] * p["fs"])  # eq. (7)
    return AngleResidual(e3, e7, qi, qe, di, de, da, valid)


def angle_residual(contact_angle_inner, contact_angle_outer, axial_load, shaft_speed, n_balls, ball_diameter,
                   pitch_diameter, inner_conformity, outer_conformity, free_angle, reduced_modulus, density, *,
                   raceway_control="outer", gyroscopic_sign=1, constants="mass"):
    r"""The paper's sequence for trial contact angles: loads, deflections, delta_a and residuals E3, E7.

    Parameters
    ----------
    contact_angle_inner, contact_angle_outer : array_like
        Trial alpha_i, alpha_e. [rad]
    axial_load : array_like
        F_a. [N]
    shaft_speed : array_like
        omega_i > 0 (at zero speed eqs. (5)-(6) are homogeneous). [rad/s]
    n_balls : array_like
        Z. [-]
    ball_diameter : array_like
        D. [m]
    pitch_diameter : array_like
        d_m. [m]
    inner_conformity, outer_conformity : array_like
        f_i, f_e. [-]
    free_angle : array_like
        alpha0. [rad]
    reduced_modulus : array_like
        E'. [Pa]
    density : array_like
        Density of the balls. [kg/m^3]
    raceway_control : {"outer", "inner"}, optional
        See :func:`residual`.
    gyroscopic_sign : {1, -1}, optional
        See :func:`residual`.
    constants : {"mass", "harris", "paper"} or (float, float), optional
        See :func:`contact_angles`.

    Returns
    -------
    AngleResidual
        E3 and E7 (E4-E6 vanish by construction), Q_i, Q_e [N], delta_i, delta_e, delta_a [m], validity.

    Notes
    -----
    Spec 004 section 5.2: beta, n_m, n_b, F_c, M_g, K from (8)-(21) at the trial angles; Q_i, Q_e from the
    linear system (5)-(6) (singular where alpha_i = alpha_e); delta from (14)-(15); V_x, V_z from (22),
    (23); delta_a from the axial closure; E3 is eq. (3) and E7 eq. (7). The sum E3^2 + E7^2 is the
    criterion (24).
    """
    ai = _angle("contact_angle_inner", contact_angle_inner)
    ae = _angle("contact_angle_outer", contact_angle_outer)
    w = _speed("shaft_speed", shaft_speed)
    model, shape = _prepare(axial_load, n_balls, ball_diameter, pitch_diameter, inner_conformity, outer_conformity,
                            free_angle, reduced_modulus, density, raceway_control, gyroscopic_sign, constants,
                            shape=np.broadcast_shapes(np.shape(ai), np.shape(ae), np.shape(w)))
    n = model.fa.size
    flat = [np.broadcast_to(a, shape).ravel() for a in (ai, ae, w)]
    out = _angle_sequence(model, np.arange(n), flat[0], flat[1], flat[2] ** 2)
    return AngleResidual(*(np.asarray(f).reshape(shape)[()] for f in out))


# --------------------------------------------------------------------------- results
class HighSpeedState(NamedTuple):
    """Quasi-static state of a high-speed angular-contact ball bearing under thrust (SI units).

    Failed cases (``converged`` False) carry NaN in every physical field and the reason in ``status``.
    """

    axial_load: np.ndarray  # F_a [N]
    shaft_speed: np.ndarray  # omega_i [rad/s]
    contact_angle_inner: np.ndarray  # alpha_i [rad]
    contact_angle_outer: np.ndarray  # alpha_e [rad]
    static_contact_angle: np.ndarray  # alpha_s at the same thrust, zero speed [rad]
    axial_displacement: np.ndarray  # delta_a [m]
    ball_load_inner: np.ndarray  # Q_i [N]
    ball_load_outer: np.ndarray  # Q_e [N]
    deflection_inner: np.ndarray  # delta_i [m]
    deflection_outer: np.ndarray  # delta_e [m]
    centrifugal_force: np.ndarray  # F_c [N]
    gyroscopic_moment: np.ndarray  # M_g >= 0 [N m]
    attitude_angle: np.ndarray  # beta [rad]
    cage_speed: np.ndarray  # omega_m [rad/s]
    ball_spin_speed: np.ndarray  # omega_R [rad/s]
    bpfo: np.ndarray  # Z omega_m, ball-pass frequency of the fixed outer ring [rad/s]
    bpfi: np.ndarray  # Z (omega_i - omega_m) [rad/s]
    max_pressure_inner: np.ndarray  # p_max at the inner contact [Pa]
    max_pressure_outer: np.ndarray  # p_max at the outer contact [Pa]
    axial_stiffness: np.ndarray  # dF_a / d delta_a [N/m]
    friction_coefficient: np.ndarray  # 2 M_g / (D Q) at the controlling raceway (Q_e for outer control) [-]
    converged: np.ndarray  # bool
    residual: np.ndarray  # Euclidean norm of the scaled residuals at the solution [-]
    iterations: np.ndarray  # Newton iterations (all continuation steps) or refinement steps
    status: np.ndarray  # "ok" or the reason of failure, one of STATUS
    method: np.ndarray  # "static", "newton", "search-triangle", "search-quadrant"


def _static_start(model, idx):
    """Static solution (spec 004 section 5.3) at the loads of ``idx``, computed once per distinct case."""
    keys = np.stack([model.fa[idx], model.z[idx], model.d[idx], model.dm[idx], model.fi[idx], model.fo[idx],
                     model.a0[idx], model.ep[idx]], axis=1)
    if keys.size and np.all(keys[:, 1:] == keys[:1, 1:]):  # one bearing: distinct loads only
        loads, inv = np.unique(keys[:, 0], return_inverse=True)
        uniq = np.column_stack([loads, np.broadcast_to(keys[:1, 1:], (len(loads), 7))])
    else:
        uniq, inv = np.unique(keys, axis=0, return_inverse=True)
    s = static.contact_angle_under_thrust(uniq[:, 0], uniq[:, 1], uniq[:, 2], uniq[:, 3], uniq[:, 4], uniq[:, 5],
                                          uniq[:, 6], uniq[:, 7], stiffness_at="operating")
    inv = inv.ravel()
    return (np.atleast_1d(s.contact_angle)[inv], np.atleast_1d(s.deflection_inner)[inv],
            np.atleast_1d(s.deflection_outer)[inv], np.atleast_1d(s.axial_displacement)[inv])


def _unknowns_from(model, idx, ae, di, de, da):
    d = model.d[idx]
    le_len = (model.fo[idx] - 0.5) * d + de
    return np.stack([le_len * np.sin(ae), le_len * np.cos(ae), di, de, da], axis=1) / d[:, None]


def _newton(model, idx, w_target, v0, *, tol, max_iter, speed_step):
    """Batched Newton-Raphson with per-case continuation in speed and step control (spec 004 section 5.1).

    All unfinished cases are updated together; each has its own current speed, continuation step and
    line-search fraction. Returns the unknowns, the status codes, the Newton iterations, the residual
    norm at convergence and the last converged speed of each case.
    """
    n = len(idx)
    v = v0.copy()
    v_ok = v0.copy()
    w_ok = np.zeros(n)
    w_cur = np.zeros(n)  # the static start is the first continuation point
    tangent = np.zeros((n, 5))
    h_max = np.inf if speed_step is None else speed_step
    h = np.minimum(w_target, h_max)
    k_stage = np.zeros(n, dtype=int)
    iters = np.zeros(n, dtype=int)
    norm_prev = np.full(n, np.inf)
    v_base = v0.copy()
    step = np.zeros((n, 5))
    t = np.ones(n)
    status = np.full(n, -1)  # -1 running
    last_bad = np.full(n, _NOCONV)
    norm_out = np.full(n, np.nan)
    h_min = np.maximum(w_target * 1e-6, 1e-3)
    stage_max = _solve.QUASISTATIC_STAGE_MAX_ITER
    for _ in range(_solve.QUASISTATIC_MAX_LOOPS):
        act = np.flatnonzero(status < 0)
        if act.size == 0:
            break
        r, jac, code, ex = _equations(model, idx[act], v[act], w_cur[act] ** 2, True)
        norm = np.sqrt(np.einsum("ij,ij->i", r, r))
        valid = (code == _OK) & np.isfinite(norm)
        last_bad[act[~valid]] = code[~valid]
        conv = valid & (norm < tol)
        # an iterate is accepted when it is valid and decreases the residual (Armijo on the norm)
        accept = valid & ~conv & (norm <= norm_prev[act] * (1.0 - 1e-4 * t[act]))
        retry = ~conv & ~accept & (k_stage[act] > 0)  # step halving from the previous iterate
        fresh_bad = ~conv & ~accept & (k_stage[act] == 0)  # a predictor that is not usable
        # ---- converged at the current speed
        if conv.any():
            a = act[conv]
            norm_out[a] = norm[conv]
            final = w_cur[a] >= w_target[a]
            status[a[final]] = _OK
            go = a[~final]
            if go.size:
                sel = conv.copy()
                sel[conv] = ~final
                tan = np.linalg.solve(jac[sel], -ex["r_w2"][sel][:, :, None])[:, :, 0]  # dv/d(omega^2)
                tangent[go] = tan
                v_ok[go] = v[go]
                w_ok[go] = w_cur[go]
                easy = (k_stage[go] <= 4) & (w_cur[go] > 0)
                h[go] = np.minimum(np.where(easy, 2.0 * h[go], h[go]), h_max)  # grow after an easy step
                _advance(go, v, v_ok, w_ok, w_cur, w_target, h, tangent, k_stage, norm_prev, t)
        # ---- accepted: a new Newton step
        if accept.any():
            a = act[accept]
            too_many = (k_stage[a] >= stage_max) | (iters[a] >= max_iter)
            ok = a[~too_many]
            if ok.size:
                sel = accept.copy()
                sel[accept] = ~too_many
                try:
                    dv = np.linalg.solve(jac[sel], -r[sel][:, :, None])[:, :, 0]
                except np.linalg.LinAlgError:  # a singular Jacobian in the batch: solve one by one
                    dv = _robust_solve(jac[sel], -r[sel])
                bad_step = ~np.all(np.isfinite(dv), axis=1)
                good = ok[~bad_step]
                v_base[good] = v[good]
                step[good] = dv[~bad_step]
                norm_prev[good] = norm[sel][~bad_step]
                t[good] = 1.0
                v[good] = v[good] + dv[~bad_step]
                k_stage[good] += 1
                iters[good] += 1
                _cut(ok[bad_step], status, last_bad, iters, max_iter, v, v_ok, w_ok, w_cur, w_target, h, h_min,
                     tangent, k_stage, norm_prev, t)
            _cut(a[too_many], status, last_bad, iters, max_iter, v, v_ok, w_ok, w_cur, w_target, h, h_min, tangent,
                 k_stage, norm_prev, t)
        # ---- rejected: halve the step, or cut the speed step
        if retry.any():
            a = act[retry]
            t[a] *= 0.5
            small = t[a] < 1.0 / 1024.0
            ls = a[~small]
            v[ls] = v_base[ls] + t[ls, None] * step[ls]
            _cut(a[small], status, last_bad, iters, max_iter, v, v_ok, w_ok, w_cur, w_target, h, h_min, tangent,
                 k_stage, norm_prev, t)
        if fresh_bad.any():
            _cut(act[fresh_bad], status, last_bad, iters, max_iter, v, v_ok, w_ok, w_cur, w_target, h, h_min, tangent,
                 k_stage, norm_prev, t)
    else:
        status[status < 0] = _NOCONV
    return v, status, iters, norm_out, w_ok


def _robust_solve(a, b):
    out = np.full(b.shape, np.nan)
    for k in range(len(a)):  # only reached when a batch contains a singular Jacobian
        try:
            out[k] = np.linalg.solve(a[k], b[k])
        except np.linalg.LinAlgError:
            pass
    return out


def _advance(a, v, v_ok, w_ok, w_cur, w_target, h, tangent, k_stage, norm_prev, t):
    """Start the next continuation step of cases ``a`` from their last converged point (tangent predictor).

    The predictor is linear in omega^2, except for X1 = L_e sin(alpha_e) > 0, which is extrapolated
    multiplicatively (the same to first order): at low thrust and high speed alpha_e falls like
    1/omega^2 and a linear predictor would overshoot to alpha_e < 0 and force tiny steps.
    """
    w_new = np.minimum(w_ok[a] + h[a], w_target[a])
    w_cur[a] = w_new
    inc = (w_new**2 - w_ok[a] ** 2)[:, None] * tangent[a]
    pred = v_ok[a] + inc
    x1 = v_ok[a, 0]
    with np.errstate(over="ignore", divide="ignore", invalid="ignore"):
        pred[:, 0] = np.where(x1 > 0, x1 * np.exp(np.minimum(inc[:, 0] / x1, 50.0)), pred[:, 0])
    v[a] = pred
    k_stage[a] = 0
    norm_prev[a] = np.inf
    t[a] = 1.0


def _cut(a, status, last_bad, iters, max_iter, v, v_ok, w_ok, w_cur, w_target, h, h_min, tangent, k_stage, norm_prev,
         t):
    """A continuation step failed: retry with a quarter of the speed step, or give up.

    Out of iterations the reason is "no_convergence"; out of speed step it is the last invalid state met
    (the ball leaving a raceway, an angle leaving (0, 90 deg)) if any.
    """
    if a.size == 0:
        return
    h[a] = 0.25 * (w_cur[a] - w_ok[a])
    exhausted = iters[a] >= max_iter
    stalled = ~exhausted & (h[a] < h_min[a])
    status[a[exhausted]] = _NOCONV
    status[a[stalled]] = last_bad[a[stalled]]
    give_up = exhausted | stalled
    go = a[~give_up]
    if go.size:
        _advance(go, v, v_ok, w_ok, w_cur, w_target, h, tangent, k_stage, norm_prev, t)


def _refine_angles(model, idx, ai, ae, w2, lo_i, hi_i, lo_e, hi_e, line=None, max_iter=60):
    """Bounded damped Newton (least squares) on E3, E7 in (alpha_i, alpha_e), all cases at once.

    Iterates stay in the box [lo, hi] and, if ``line`` is given, below alpha_i + alpha_e = line (the
    triangle of section 5.2: a point above the line is projected onto it).
    """
    x = np.stack([ai, ae], axis=1)
    lo = np.stack([lo_i, lo_e], axis=1)
    hi = np.stack([hi_i, hi_e], axis=1)

    def project(xx, sel):
        xx = np.clip(xx, lo[sel], hi[sel])
        if line is not None:
            excess = np.maximum(xx[:, 0] + xx[:, 1] - line[sel], 0.0)
            xx = np.clip(xx - 0.5 * excess[:, None], lo[sel], hi[sel])
        return xx

    iters = np.zeros(len(idx), dtype=int)

    def obj(sel, xx):
        s = _angle_sequence(model, idx[sel], xx[:, 0], xx[:, 1], w2[sel])
        e = np.stack([s.radial, s.ring], axis=1)
        val = np.where(s.valid, np.einsum("ij,ij->i", e, e), np.inf)
        return e, val

    e, f = obj(np.arange(len(idx)), x)
    h = 1e-7
    active = np.flatnonzero(f >= 1e-28)
    for _ in range(max_iter):
        if active.size == 0:
            break
        xa = x[active]
        cols = []
        for k in range(2):  # central differences in the two angles
            dx = np.zeros(2)
            dx[k] = h
            ep_, _v1 = obj(active, xa + dx)
            em_, _v2 = obj(active, xa - dx)
            cols.append((ep_ - em_) / (2 * h))
        jac = np.stack(cols, axis=2)
        det = jac[:, 0, 0] * jac[:, 1, 1] - jac[:, 0, 1] * jac[:, 1, 0]
        ok = np.isfinite(det) & (np.abs(det) > 0)
        step = np.zeros_like(xa)
        ea = e[active]
        with np.errstate(divide="ignore", invalid="ignore"):
            step[:, 0] = -(jac[:, 1, 1] * ea[:, 0] - jac[:, 0, 1] * ea[:, 1]) / det
            step[:, 1] = -(-jac[:, 1, 0] * ea[:, 0] + jac[:, 0, 0] * ea[:, 1]) / det
        step[~ok | ~np.all(np.isfinite(step), axis=1)] = 0.0
        tt = np.ones(len(active))
        improved = np.zeros(len(active), dtype=bool)
        pending = np.arange(len(active))
        for _ls in range(30):  # step halving until the sum of squares decreases
            if pending.size == 0:
                break
            xt = project(xa[pending] + tt[pending, None] * step[pending], active[pending])
            et, ft = obj(active[pending], xt)
            better = ft < f[active[pending]]
            good = pending[better]
            x[active[good]] = xt[better]
            e[active[good]] = et[better]
            f[active[good]] = ft[better]
            improved[good] = True
            pending = pending[~better]
            tt[pending] *= 0.5
        iters[active] += 1
        active = active[improved & (f[active] >= 1e-28)]
    return x[:, 0], x[:, 1], f, iters


def _grid_search(model, idx, w2, lo_i, hi_i, lo_e, hi_e, triangle_sum):
    """Best point of a 61 x 61 grid per case (vectorized, in chunks of cases to bound memory)."""
    u = np.linspace(0.0, 1.0, _GRID)
    gi, ge = np.meshgrid(u, u, indexing="ij")
    gi, ge = gi.ravel(), ge.ravel()
    best_i = np.empty(len(idx))
    best_e = np.empty(len(idx))
    chunk = max(1, 200_000 // gi.size)
    for s in range(0, len(idx), chunk):  # chunks of cases, each solved for its whole grid at once
        sl = slice(s, s + chunk)
        ai = lo_i[sl, None] + (hi_i[sl] - lo_i[sl])[:, None] * gi[None, :]
        ae = hi_e[sl, None] - (hi_e[sl] - lo_e[sl])[:, None] * ge[None, :]
        m = ai.shape[1]
        res = _angle_sequence(model, np.repeat(idx[sl], m), ai.ravel(), ae.ravel(), np.repeat(w2[sl], m))
        f = np.where(res.valid, res.radial**2 + res.ring**2, np.inf).reshape(ai.shape)
        if triangle_sum is not None:
            f = np.where(ai + ae <= triangle_sum[sl, None] + 1e-12, f, np.inf)
        k = np.argmin(f, axis=1)
        rows = np.arange(ai.shape[0])
        best_i[sl], best_e[sl] = ai[rows, k], ae[rows, k]
    return best_i, best_e


def _angle_iteration(model, idx, w_target, alpha_s):
    """The paper's method (spec 004 section 5.2) for cases with omega > 0; returns angles, f, iters, method."""
    w2 = w_target**2
    deg = np.pi / 180.0
    span = np.minimum.reduce([np.full_like(alpha_s, 45.0 * deg), alpha_s - 0.5 * deg, 89.5 * deg - alpha_s])
    lo_i, hi_i = alpha_s, alpha_s + span
    lo_e, hi_e = alpha_s - span, alpha_s
    ai, ae = _grid_search(model, idx, w2, lo_i, hi_i, lo_e, hi_e, 2.0 * alpha_s)
    ai, ae, f, iters = _refine_angles(model, idx, ai, ae, w2, lo_i, hi_i, lo_e, hi_e, line=2.0 * alpha_s)
    method = np.full(len(idx), "search-triangle", dtype=object)
    miss = np.flatnonzero(~(f < _ROOT_TOL))
    if miss.size:  # the triangle heuristic failed: search the whole quadrant (and say so)
        q_lo, q_hi = np.full(miss.size, 0.5 * deg), np.full(miss.size, 89.5 * deg)
        qi, qe = _grid_search(model, idx[miss], w2[miss], q_lo, q_hi, q_lo, q_hi, None)
        tiny, top = np.full(miss.size, 1e-9), np.full(miss.size, np.pi / 2 - 1e-9)
        qi, qe, qf, qit = _refine_angles(model, idx[miss], qi, qe, w2[miss], tiny, top, tiny, top)
        ai[miss], ae[miss], f[miss] = qi, qe, qf
        iters[miss] += qit
        method[miss] = "search-quadrant"
    return ai, ae, f, iters, method


def _assemble(model, idx, v, w, alpha_s, ok):
    """Every output of a converged case from the unknowns, through the public functions."""
    n = len(idx)
    out = {k: np.full(n, np.nan) for k in HighSpeedState._fields[2:21]}
    out["static_contact_angle"] = alpha_s
    out["residual"] = np.full(n, np.nan)
    if not ok.any():
        return out
    sel = np.flatnonzero(ok)
    ii = idx[sel]
    r, jac, _code, ex = _equations(model, ii, v[sel], w[sel] ** 2, True)
    p = ex["p"]
    ai, ae = ex["ai"], ex["ae"]
    d, dm = p["d"], p["dm"]
    beta = attitude_angle(ai, ae, d, dm, raceway_control=model.control)
    speeds = ball_speeds(w[sel], ai, ae, beta, d, dm)
    fc = centrifugal_force(speeds.cage_speed, p["mass_c"], dm)
    mg = gyroscopic_moment(speeds.ball_spin_speed, speeds.cage_speed, beta, 10.0 * p["inertia"] / d**2, d)
    fr = ex["fr"]
    inner = geometry.raceway_curvature(d, dm, p["fi"], ai, race="inner")
    outer = geometry.raceway_curvature(d, dm, p["fo"], ae, race="outer")
    h_i = _hertz_coefficients(model.t_inner, p["gid"], np.cos(ai))
    h_o = _hertz_coefficients(model.t_outer, p["gid"], np.cos(ae))
    pc_i = hertz.point_contact(fr["qi"], inner.curvature_sum, inner.curvature_difference, p["ep"], hertz=h_i)
    pc_o = hertz.point_contact(fr["qe"], outer.curvature_sum, outer.curvature_difference, p["ep"], hertz=h_o)
    # axial stiffness by implicit differentiation: J dv = -dr/dF_a dF_a, dr5/dF_a = -1/(Z fs)
    rhs = np.zeros((len(sel), 5))
    rhs[:, 4] = 1.0 / (p["z"] * p["fs"])
    dv = np.linalg.solve(jac, rhs[:, :, None])[:, :, 0]
    vals = {
        "contact_angle_inner": ai, "contact_angle_outer": ae, "axial_displacement": ex["da"],
        "ball_load_inner": fr["qi"], "ball_load_outer": fr["qe"], "deflection_inner": ex["di"],
        "deflection_outer": ex["de"], "centrifugal_force": fc, "gyroscopic_moment": mg, "attitude_angle": beta,
        "cage_speed": speeds.cage_speed, "ball_spin_speed": speeds.ball_spin_speed,
        "bpfo": p["z"] * speeds.cage_speed, "bpfi": p["z"] * (w[sel] - speeds.cage_speed),
        "max_pressure_inner": pc_i.p_max, "max_pressure_outer": pc_o.p_max, "axial_stiffness": 1.0 / (dv[:, 4] * d),
        "friction_coefficient": friction_coefficient(mg, fr["qe"], d) if model.lam_e > 0 else
        friction_coefficient(mg, fr["qi"], d),
        "residual": np.sqrt(np.einsum("ij,ij->i", r, r)),
    }
    for k, val in vals.items():
        out[k][sel] = val
    return out


def contact_angles(axial_load, shaft_speed, n_balls, ball_diameter, pitch_diameter, inner_conformity,
                   outer_conformity, free_angle, reduced_modulus, density, *, method="newton",
                   raceway_control="outer", gyroscopic_sign=1, constants="mass", on_failure="raise",
                   tol=_solve.QUASISTATIC_TOL, max_iter=_solve.QUASISTATIC_MAX_ITER,
                   speed_step=None, friction_limit=FRICTION_WARNING_LIMIT):
    r"""Inner and outer contact angles and the full quasi-static state of a ball bearing under thrust at speed.

    Parameters
    ----------
    axial_load : array_like
        Thrust F_a > 0 on the inner ring. [N]
    shaft_speed : array_like
        Inner-ring speed omega_i >= 0, outer ring fixed. [rad/s]
    n_balls : array_like
        Number of balls Z. [-]
    ball_diameter : array_like
        D. [m]
    pitch_diameter : array_like
        d_m > D. [m]
    inner_conformity, outer_conformity : array_like
        f_i, f_e, each > 0.5. [-]
    free_angle : array_like
        Free contact angle alpha0, in (0, 90 deg). [rad]
    reduced_modulus : array_like
        E' of the ball-ring pair (:func:`bearinglab.hertz.reduced_modulus`). [Pa]
    density : array_like
        Density of the balls (steel 7850, silicon nitride 3200). [kg/m^3]
    method : {"newton", "angle-iteration"}, optional
        Batched Newton-Raphson on the full set (spec 004 section 5.1, default) or the paper's
        contact-angle search (section 5.2).
    raceway_control : {"outer", "inner"}, optional
        Outer-raceway control (lambda_i = 0, lambda_e = 2; the paper's and Harris's assumption, default)
        or inner-raceway control (lambda_i = 2, lambda_e = 0).
    gyroscopic_sign : {1, -1}, optional
        Sign of the gyroscopic friction: +1 is the physical one of spec 004 section 4 (default); -1 is the
        reversed convention of Harris's printed equations with a positive M_g, for comparison only.
    constants : {"mass", "harris", "paper"} or (float, float), optional
        "mass" (default): F_c and M_g from the ball mass rho pi D^3/6 and J = m D^2/10, valid for any
        ball material. "harris": the printed constants 2.26e-11 and 4.47e-12 [N; mm; rpm], with which
        the reference results of spec 004 section 7 were computed; "paper": 2.26e-11 and 4.5e-12. A pair
        (C_c, C_g) gives both constants in those units (C_g = 0 drops the gyroscopic moment). The printed
        constants hold for steel balls only.
    on_failure : {"raise", "flag"}, optional
        Raise :class:`~bearinglab.errors.ConvergenceError` if any case fails (default), or return NaN and
        the reason in ``status`` for the failed cases while the others complete.
    tol : float, optional
        Euclidean norm of the scaled residuals below which a case is converged. [-]
    max_iter : int, optional
        Newton iterations per case over all continuation steps.
    speed_step : float, optional
        Largest continuation step in speed (e.g. ``bearinglab._solve.QUASISTATIC_SPEED_STEP_RPM`` = 1500
        rpm, the step of the spec's reference computation). Default None: go to the target speed at once
        and cut the step where Newton fails. [rad/s]
    friction_limit : float, optional
        Warn (:class:`~bearinglab.errors.ValidityWarning`) where the friction coefficient that the raceway
        control needs exceeds this. [-]

    Returns
    -------
    HighSpeedState
        Angles, displacement, loads, dynamics, speeds, pressures, stiffness, friction, per-case
        ``converged``, ``residual``, ``iterations``, ``status`` and ``method``; arrays of the broadcast
        shape of the inputs (scalars for scalar inputs).

    Raises
    ------
    ConvergenceError
        With ``on_failure="raise"``, if a case does not converge or has no physical solution (the reason
        is in the message: no convergence, the ball leaving a raceway, an angle leaving (0, 90 deg), a
        search minimum that is not a root).

    Notes
    -----
    Spec 004 section 3, eqs. (1)-(23): outer groove-curvature centre fixed, inner one at
    (B D sin alpha0 + delta_a, B D cos alpha0); ball equilibrium (5)-(6) and ring equilibrium (7) with the
    gyroscopic friction at the controlling raceway; F_c (8), kinematics (9), (10), (13), M_g (12);
    K_i, K_e (16)-(21) from the exact Hertz solution at the operating angles.

    Newton (section 5.1): unknowns (X1, X2, delta_i, delta_e, delta_a)/D; start from the static solution
    of :func:`bearinglab.static.contact_angle_under_thrust` at the same thrust (section 5.3); per-case
    continuation in omega^2 with a tangent predictor: the first step goes to the target speed (or to
    ``speed_step``), steps are cut by 4 where Newton fails and double again after quick convergence; per-case step halving when an iterate is invalid
    (delta <= 0, an angle outside (0, 90 deg)) or does not decrease the residual. All cases are updated
    together (5 x 5 systems solved on stacked arrays). At zero speed the result is the static solution.

    Angle iteration (section 5.2): a 61 x 61 grid over the triangle alpha_s <= alpha_i <= alpha_s + Delta,
    alpha_s - Delta <= alpha_e <= alpha_s, alpha_i + alpha_e <= 2 alpha_s, then a bounded damped Newton
    least-squares refinement; a minimum with sum E^2 >= 1e-20 is not a root, and the whole quadrant is
    searched instead (``method`` "search-quadrant"); if that fails too, the case fails with status
    "search_not_root".

    Examples
    --------
    >>> from bearinglab import bearing
    >>> from bearinglab.units import RPM
    >>> s = contact_angles(20e3, 10000 * RPM, 16, 22.23e-3, 125.3e-3, 0.5232, 0.5232, math.radians(40),
    ...                    bearing.STEEL.elastic_modulus / (1 - 0.3**2), 7850.0, constants="harris")
    >>> print(f"{math.degrees(s.contact_angle_inner):.3f} / {math.degrees(s.contact_angle_outer):.3f} deg")
    49.308 / 32.514 deg
    """
    w = _speed("shaft_speed", shaft_speed)
    if method not in ("newton", "angle-iteration"):
        raise InputError(f"method must be one of ['newton', 'angle-iteration'], got {method!r}")
    if on_failure not in ("raise", "flag"):
        raise InputError(f"on_failure must be one of ['raise', 'flag'], got {on_failure!r}")
    check_positive("tol", tol, "-")
    check_integer("max_iter", max_iter, 1)
    if speed_step is not None:
        speed_step = float(check_positive("speed_step", speed_step, "rad/s"))
    model, shape = _prepare(axial_load, n_balls, ball_diameter, pitch_diameter, inner_conformity, outer_conformity,
                            free_angle, reduced_modulus, density, raceway_control, gyroscopic_sign, constants,
                            shape=np.shape(w))
    n = model.fa.size
    wf = np.broadcast_to(w, shape).ravel().astype(float)
    idx = np.arange(n)
    alpha_s, di0, de0, da0 = _static_start(model, idx)
    v0 = _unknowns_from(model, idx, alpha_s, di0, de0, da0)
    status = np.zeros(n, dtype=int)
    iters = np.zeros(n, dtype=int)
    meth = np.full(n, "newton", dtype=object)
    if method == "newton":
        v, status, iters, _norm, _w_ok = _newton(model, idx, wf, v0, tol=tol, max_iter=int(max_iter),
                                                 speed_step=speed_step)
    else:
        v = v0.copy()
        moving = np.flatnonzero(wf > 0)
        if moving.size:
            ai, ae, f, it, how = _angle_iteration(model, idx[moving], wf[moving], alpha_s[moving])
            seq = _angle_sequence(model, idx[moving], ai, ae, wf[moving] ** 2)
            v[moving] = _unknowns_from(model, idx[moving], ae, seq.deflection_inner, seq.deflection_outer,
                                       seq.axial_displacement)
            status[moving] = np.where(f < _ROOT_TOL, _OK, _NOT_ROOT)
            iters[moving] = it
            meth[moving] = how
    meth[wf == 0] = "static"
    ok = status == _OK
    out = _assemble(model, idx, v, wf, alpha_s, ok)
    failed = np.flatnonzero(~ok)
    if failed.size and on_failure == "raise":
        k = failed[0]
        raise ConvergenceError("quasistatic.contact_angles", iterations=int(iters[k]),
                               residual=out["residual"][k] if np.isfinite(out["residual"][k]) else np.inf,
                               estimate=v[k] * model.d[k],
                               reason=f"{_STATUS_TEXT[status[k]]} at F_a = {model.fa[k]:g} N, "
                                      f"{wf[k] / RPM:g} rpm ({failed.size} of {n} cases failed)")
    high = ok & (out["friction_coefficient"] > friction_limit)
    if high.any():
        k = np.flatnonzero(high)[0]
        warnings.warn(f"{high.sum()} of {n} cases need a friction coefficient above {friction_limit:g} for "
                      f"{raceway_control}-raceway control (e.g. {out['friction_coefficient'][k]:.3g} at "
                      f"F_a = {model.fa[k]:g} N, {wf[k] / RPM:g} rpm): the balls would spin or skid, the model "
                      "is not valid there", ValidityWarning, stacklevel=2)
    fields = dict(out)
    fields["axial_load"] = model.fa
    fields["shaft_speed"] = wf
    fields["converged"] = ok
    fields["iterations"] = iters
    fields["status"] = np.array([STATUS[s] for s in status], dtype=object) if n else np.array([], dtype=object)
    fields["method"] = meth
    return HighSpeedState(**{k: np.asarray(fields[k]).reshape(shape)[()] for k in HighSpeedState._fields})


def zero_displacement_thrust(shaft_speed, n_balls, ball_diameter, pitch_diameter, inner_conformity, outer_conformity,
                             free_angle, reduced_modulus, density, *, rtol=1e-10, max_iter=60, **options):
    r"""Thrust at which the axial displacement delta_a changes sign, for each speed (spec 004 section 7.2).

    Parameters
    ----------
    shaft_speed : array_like
        Inner-ring speeds omega_i >= 0. [rad/s]
    n_balls : array_like
        Z. [-]
    ball_diameter : array_like
        D. [m]
    pitch_diameter : array_like
        d_m. [m]
    inner_conformity, outer_conformity : array_like
        f_i, f_e. [-]
    free_angle : array_like
        alpha0. [rad]
    reduced_modulus : array_like
        E'. [Pa]
    density : array_like
        Density of the balls. [kg/m^3]
    rtol : float, optional
        Relative tolerance on the thrust. [-]
    max_iter : int, optional
        Iterations of the outer (thrust) solve.

    Other Parameters
    ----------------
    **options
        ``raceway_control``, ``gyroscopic_sign``, ``constants`` as in :func:`contact_angles`.

    Returns
    -------
    ndarray
        F_a with delta_a(F_a) = 0 (0 at zero speed, where delta_a > 0 for every thrust). [N]

    Notes
    -----
    delta_a rises with the thrust at fixed speed; below the returned thrust the centrifugal force pushes
    the inner ring against the load direction (delta_a < 0). Safeguarded Newton on F_a with the axial
    stiffness dF_a/d delta_a of :func:`contact_angles` as slope, all speeds at once, bracketed between
    0.01 and 100 times Z F_c at the nominal cage speed (the bracket is widened if needed).
    """
    w = _speed("shaft_speed", shaft_speed)
    shape = np.shape(w)
    wf = np.ravel(w).astype(float)
    geo = (n_balls, ball_diameter, pitch_diameter, inner_conformity, outer_conformity, free_angle, reduced_modulus,
           density)
    out = np.zeros(wf.size)
    moving = np.flatnonzero(wf > 0)
    if moving.size == 0:
        return out.reshape(shape)[()]
    ws = wf[moving]
    model, _ = _prepare(1.0, *geo, options.get("raceway_control", "outer"), options.get("gyroscopic_sign", 1),
                        options.get("constants", "mass"))
    g0 = model.d[0] / model.dm[0] * math.cos(model.a0[0])
    scale = model.z[0] * model.mass_c[0] * model.dm[0] / 2.0 * (ws * (1.0 - g0) / 2.0) ** 2

    def solve(fa):
        s = contact_angles(fa, ws, *geo, on_failure="flag", friction_limit=np.inf, **options)
        return s.axial_displacement, s.axial_stiffness

    lo, hi = 0.01 * scale, 100.0 * scale
    da_lo, _ = solve(lo)
    da_hi, _ = solve(hi)
    for _ in range(10):  # widen the bracket where the sign does not change (or the solve failed)
        bad_lo, bad_hi = ~(da_lo < 0), ~(da_hi > 0)
        if not (bad_lo.any() or bad_hi.any()):
            break
        lo = np.where(bad_lo, lo * 0.1, lo)
        hi = np.where(bad_hi, hi * 10.0, hi)
        da_lo, _ = solve(lo)
        da_hi, _ = solve(hi)
    else:
        raise ConvergenceError("quasistatic.zero_displacement_thrust", iterations=10, residual=np.inf, estimate=lo,
                               reason="no thrust bracket with delta_a < 0 below and > 0 above")
    fa = np.sqrt(lo * hi)
    for it in range(1, max_iter + 1):
        da, k = solve(fa)
        lo = np.where(da < 0, fa, lo)
        hi = np.where(da > 0, fa, hi)
        new = fa - da * k
        outside = ~((new > lo) & (new < hi)) | ~np.isfinite(new)
        new = np.where(outside, np.sqrt(lo * hi), new)
        done = np.abs(new - fa) <= rtol * fa
        fa = new
        if np.all(done):
            break
    else:
        raise ConvergenceError("quasistatic.zero_displacement_thrust", iterations=max_iter, residual=da, estimate=fa)
    out[moving] = fa
    return out.reshape(shape)[()]


# --------------------------------------------------------------------------- analyses
def _bearing_args(bearing, reduced_modulus=None):
    z, d, dm, fi, fo, a0 = bearing.require("n_balls", "ball_diameter", "pitch_diameter", "inner_conformity",
                                           "outer_conformity", "contact_angle")
    if not 0.0 < a0 < math.pi / 2:
        raise InputError(f"contact_angle of {bearing.designation or 'the bearing'!r} must be in (0, 90) [deg] for the "
                         f"high-speed model under thrust, got {math.degrees(a0):g}")
    ep = bearing.reduced_modulus if reduced_modulus is None else reduced_modulus
    return z, d, dm, fi, fo, a0, ep, bearing.ball_material.density


def high_speed_analysis(bearing, axial_load, shaft_speed, *, reduced_modulus=None, **options):
    """The quasi-static high-speed state of a bearing under thrust (spec 004).

    Parameters
    ----------
    bearing : BallBearing
        Needs n_balls, ball_diameter, pitch_diameter, both conformities and the free contact angle in
        (0, 90 deg); materials give E' and the ball density.
    axial_load : array_like
        F_a > 0. [N]
    shaft_speed : array_like
        Inner-ring speed >= 0, broadcast against ``axial_load``. [rad/s]
    reduced_modulus : float, optional
        E' to use instead of the one of the bearing's materials (e.g. 2.15e5 * 3 / 2**1.5 MPa, the
        rounded constant of spec 004 eq. (16)). [Pa]

    Other Parameters
    ----------------
    **options
        Passed to :func:`contact_angles` (``method``, ``raceway_control``, ``gyroscopic_sign``,
        ``constants``, ``on_failure``, ...).

    Returns
    -------
    HighSpeedState

    Examples
    --------
    >>> from bearinglab import catalog
    >>> from bearinglab.units import RPM
    >>> s = high_speed_analysis(catalog.get("B218"), 20e3, 15000 * RPM, constants="harris")
    >>> print(f"{math.degrees(s.contact_angle_inner):.3f} / {math.degrees(s.contact_angle_outer):.3f} deg, "
    ...       f"mu = {s.friction_coefficient:.3f}")
    56.099 / 21.121 deg, mu = 0.086
    """
    return contact_angles(axial_load, shaft_speed, *_bearing_args(bearing, reduced_modulus), **options)


def sign_change_thrust(bearing, shaft_speed, *, reduced_modulus=None, **options):
    """The thrust at which the axial displacement of a bearing changes sign, per speed (spec 004 section 7.2).

    Parameters
    ----------
    bearing : BallBearing
        See :func:`high_speed_analysis`.
    shaft_speed : array_like
        Inner-ring speeds >= 0. [rad/s]
    reduced_modulus : float, optional
        See :func:`high_speed_analysis`. [Pa]

    Other Parameters
    ----------------
    **options
        Passed to :func:`zero_displacement_thrust` (``constants``, ``raceway_control``, ...).

    Returns
    -------
    ndarray
        F_a with delta_a = 0 (0 at zero speed). [N]

    Examples
    --------
    >>> from bearinglab import catalog
    >>> from bearinglab.units import RPM
    >>> f = sign_change_thrust(catalog.get("B218"), [3000 * RPM, 15000 * RPM], constants="harris",
    ...                        reduced_modulus=2.15e11 * 3 / 2**1.5)
    >>> print(np.round(f / 1e3, 2))
    [ 2.31 26.81]
    """
    return zero_displacement_thrust(shaft_speed, *_bearing_args(bearing, reduced_modulus), **options)


def _sweep_chunk(axial_load, shaft_speed, bearing, reduced_modulus, options):
    """One chunk of a sweep (a pure function of its inputs, so it can run on a dask worker): the state's
    fields per case, and the chunk's first ValidityWarning message on its first case."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", ValidityWarning)
        state = high_speed_analysis(bearing, axial_load, shaft_speed, reduced_modulus=reduced_modulus, **options)
    out = {k: np.atleast_1d(getattr(state, k)) for k in HighSpeedState._fields}
    notes = np.full(np.size(axial_load), "", dtype=object)
    msgs = [str(c.message) for c in caught if issubclass(c.category, ValidityWarning)]
    if msgs:
        notes[0] = msgs[0]
    out["_warning"] = notes
    return out


def sweep(bearing, axial_loads, shaft_speeds, *, progress=None, chunk_size=20_000, reduced_modulus=None,
          executor="serial", workers=None, memory_limit=None, processes=True, **options):
    """Solve a grid of thrusts x speeds for one bearing; failed cases are flagged, the others complete.

    Parameters
    ----------
    bearing : BallBearing
        See :func:`high_speed_analysis`.
    axial_loads : array_like
        1-D thrusts F_a. [N]
    shaft_speeds : array_like
        1-D inner-ring speeds. [rad/s]
    progress : callable or "dask", optional
        Called as ``progress(done, total)`` after each chunk of cases, or ``"dask"`` for dask's bar.
    chunk_size : int, optional
        Cases solved per batched call (all cases of a chunk are updated together).
    reduced_modulus : float, optional
        See :func:`high_speed_analysis`. [Pa]
    executor : str, optional
        ``"serial"`` (default), ``"local"`` (a dask LocalCluster for this call) or a scheduler address
        ``"tcp://host:8786"``; see :mod:`bearinglab.parallel`. The chunks are the same on every executor,
        so the results are bit-identical.
    workers : int, optional
        Workers of the local cluster. [-]
    memory_limit : str, optional
        Memory limit per local worker, e.g. ``"4GiB"``.
    processes : bool, optional
        Local workers as processes (default) or threads.

    Other Parameters
    ----------------
    **options
        Passed to :func:`contact_angles`; ``on_failure`` defaults to "flag".

    Returns
    -------
    HighSpeedState
        Fields of shape (len(axial_loads), len(shaft_speeds)).

    Examples
    --------
    >>> from bearinglab import catalog
    >>> from bearinglab.units import RPM
    >>> s = sweep(catalog.get("B218"), [5e3, 20e3], [0.0, 6000 * RPM], constants="harris")
    >>> print(np.degrees(s.contact_angle_outer).round(3))
    [[40.662 27.947]
     [41.609 38.504]]
    """
    fa = np.atleast_1d(check_positive("axial_loads", axial_loads, "N"))
    w = np.atleast_1d(_speed("shaft_speeds", shaft_speeds))
    if fa.ndim != 1 or w.ndim != 1:
        raise InputError("axial_loads and shaft_speeds must be 1-D (a grid is built from them)")
    options.setdefault("on_failure", "flag")
    check_integer("chunk_size", chunk_size, 1)
    grid_f, grid_w = np.meshgrid(fa, w, indexing="ij")
    # chunks of cases, each one batched call, run by the execution layer (serial or on dask)
    res = parallel.run_cases(_sweep_chunk, {"axial_load": grid_f.ravel(), "shaft_speed": grid_w.ravel()},
                             constants={"bearing": bearing, "reduced_modulus": reduced_modulus, "options": options},
                             chunk_size=int(chunk_size), executor=executor, workers=workers,
                             memory_limit=memory_limit, processes=processes, progress=progress)
    msgs = [m for m in res.pop("_warning") if m]
    if msgs:
        warnings.warn(msgs[0] if len(msgs) == 1 else f"{msgs[0]} (and in {len(msgs) - 1} more chunks)",
                      ValidityWarning, stacklevel=2)
    merged = {k: v.reshape(grid_f.shape) for k, v in res.items()}
    return HighSpeedState(**merged)


#: Columns of :func:`result_table`: (name, field, factor from SI).
_COLUMNS = (
    ("axial_load_kN", "axial_load", 1e-3),
    ("speed_rpm", "shaft_speed", 1.0 / RPM),
    ("contact_angle_inner_deg", "contact_angle_inner", 180.0 / math.pi),
    ("contact_angle_outer_deg", "contact_angle_outer", 180.0 / math.pi),
    ("static_contact_angle_deg", "static_contact_angle", 180.0 / math.pi),
    ("axial_displacement_mm", "axial_displacement", 1e3),
    ("ball_load_inner_N", "ball_load_inner", 1.0),
    ("ball_load_outer_N", "ball_load_outer", 1.0),
    ("deflection_inner_um", "deflection_inner", 1e6),
    ("deflection_outer_um", "deflection_outer", 1e6),
    ("centrifugal_force_N", "centrifugal_force", 1.0),
    ("gyroscopic_moment_Nmm", "gyroscopic_moment", 1e3),
    ("attitude_angle_deg", "attitude_angle", 180.0 / math.pi),
    ("cage_speed_rpm", "cage_speed", 1.0 / RPM),
    ("ball_spin_speed_rpm", "ball_spin_speed", 1.0 / RPM),
    ("bpfo_Hz", "bpfo", 1.0 / (2.0 * math.pi)),
    ("bpfi_Hz", "bpfi", 1.0 / (2.0 * math.pi)),
    ("max_pressure_inner_MPa", "max_pressure_inner", 1e-6),
    ("max_pressure_outer_MPa", "max_pressure_outer", 1e-6),
    ("axial_stiffness_N_per_um", "axial_stiffness", 1e-6),
    ("friction_coefficient", "friction_coefficient", 1.0),
    ("converged", "converged", None),
    ("residual", "residual", 1.0),
    ("iterations", "iterations", None),
    ("status", "status", None),
    ("method", "method", None),
)


def result_table(state):
    """The state as flat columns in engineering units (kN, rpm, deg, mm, um, N, N mm, Hz, MPa, N/um).

    Parameters
    ----------
    state : HighSpeedState
        A result of :func:`contact_angles`, :func:`high_speed_analysis` or :func:`sweep`.

    Returns
    -------
    dict
        Column name -> 1-D ndarray; the names carry the unit (``contact_angle_inner_deg``,
        ``axial_displacement_mm``, ``gyroscopic_moment_Nmm``, ...).
    """
    cols = {}
    for name, field, factor in _COLUMNS:
        val = np.ravel(np.asarray(getattr(state, field)))
        cols[name] = val if factor is None else val.astype(float) * factor
    for name in ("axial_load_kN", "speed_rpm"):  # inputs: drop the last-bit noise of the unit round trip
        cols[name] = np.array([float(f"{x:.12g}") for x in cols[name]])
    return cols

r"""Friction torque of single-row ball bearings: the handbook models of spec 001 section 3 (classic models).

Static equivalent load
----------------------
static_load_factors        x0, y0 of Table 1 (radial bearing, or angular contact at a tabulated angle)
equivalent_static_load     P0 = max(x0 Fr + y0 Fa, Fr), eq. (3.1)
combined_branch_governs    True where x0 Fr + y0 Fa (not Fr) is the larger term of (3.1)

One-term model
--------------
handbook_friction_coefficient   the reduced friction coefficient mu of section 3.2
one_term                   T = mu P0 d / 2, eq. (3.2)

Two-term model
--------------
load_term_constants        f and c of Table 2
load_term                  T_F = f P0 (P0/C0)^c d_m, eq. (3.4)
speed_term                 T0 = f0 d_m^3 n^(2/3), eq. (3.5)
two_term                   T = T0 + T_F, eq. (3.3)

Palmgren's viscosity form of the speed term
-------------------------------------------
palmgren                   M0 = 1e-7 f0 (nu n)^(2/3) d_m^3 (nu n >= 2000), else 160e-7 f0 d_m^3
speed_term_factor_from_palmgren   the f0 of (3.5) that equals Palmgren's M0 for a given oil

Units: the API is SI (N, m, rad/s, m^2/s, N*m). Two published fits are not dimensionally
homogeneous and keep their published units for the *coefficient*: the speed-term factor f0 of
(3.5) is in N*mm^-2*min^(2/3) (T0 in N*mm with d_m in mm and n in rpm) and Palmgren's f0 is the
dimensionless number of his N*mm / cSt / rpm / mm fit. Their inputs and outputs are converted once,
in plain sight, in :func:`speed_term` and :func:`palmgren` (STYLE.md section 6). The load term and
the one-term model are dimensionally homogeneous and need no conversion.

Relation between the two speed terms. For nu*n >= 2000 (nu in cSt, n in rpm) Palmgren's form is

.. math:: M_0 = 10^{-7} f_{0,P} (\nu n)^{2/3} d_m^3
              = \underbrace{\left(10^{-7} f_{0,P}\, \nu^{2/3}\right)}_{f_0} d_m^3 n^{2/3},

i.e. the seed's (3.5) with the viscosity folded into its f0:
``f0 = 1e-7 * f0_palmgren * nu_cSt**(2/3)`` [N*mm^-2*min^(2/3)]. A measured f0 (lab task 2) is
therefore tied to the oil and its temperature; Palmgren's f0 (about 0.7-2 for deep-groove bearings,
by type and lubrication) is not. Below nu*n = 2000 Palmgren's torque no longer falls with speed:
it is the constant 160e-7 f0 d_m^3, where (3.5) keeps falling towards 0 at n -> 0 (2000^(2/3) =
158.7, so the two branches of Palmgren's fit differ by 0.8 % at the switch).

References
----------
.. [1] Spec 001 (this project), restating E. P. Zhilnikov and V. P. Tukmakov, "Study of the friction
   torque in ball bearings under combined loading," laboratory manual, Samara State Aerospace
   University, 2016 (Tables 1 and 2 after L. Ya. Perel', Rolling bearings, Mashinostroenie, 1983).
.. [2] A. Palmgren, Ball and Roller Bearing Engineering, 3rd ed., Philadelphia: SKF Industries /
   Burbank, 1959, ch. 3 (load-independent friction torque M0).
"""

from __future__ import annotations

import math
import warnings
from typing import NamedTuple

import numpy as np

from .._validate import check_finite, check_nonnegative, check_positive
from ..errors import InputError, ValidityWarning

__all__ = [
    "ANGULAR_LOAD_TERM_BELOW_30",
    "ANGULAR_LOAD_TERM_FROM_30",
    "ANGULAR_STATIC_FACTORS",
    "BEARING_TYPES",
    "HANDBOOK_FRICTION_COEFFICIENTS",
    "RADIAL_LOAD_TERM",
    "RADIAL_STATIC_FACTORS",
    "LoadTermConstants",
    "StaticLoadFactors",
    "TwoTermTorque",
    "combined_branch_governs",
    "equivalent_static_load",
    "handbook_friction_coefficient",
    "load_term",
    "load_term_constants",
    "one_term",
    "palmgren",
    "speed_term",
    "speed_term_factor_from_palmgren",
    "static_load_factors",
    "two_term",
]

_MM, _CST, _RPM = 1e-3, 1e-6, 2.0 * math.pi / 60.0  # m per mm, m^2/s per cSt, rad/s per rpm
_ANGLE_TOL_DEG = 1e-6  # deg: an angle read from "18 deg" is 18 within rounding, not within this

BEARING_TYPES = ("radial", "angular")

# spec 001 section 3.1, Table 1: (x0, y0) of single-row ball bearings
RADIAL_STATIC_FACTORS = (0.6, 0.50)
ANGULAR_STATIC_FACTORS = {  # contact angle [deg] -> (x0, y0); no interpolation between rows
    18.0: (0.5, 0.43),
    20.0: (0.5, 0.42),
    26.0: (0.5, 0.37),
    30.0: (0.5, 0.33),
    36.0: (0.5, 0.28),
}
# spec 001 section 3.2: handbook reduced friction coefficient mu of the one-term model
HANDBOOK_FRICTION_COEFFICIENTS = {"radial": 0.0015, "angular": 0.0020}
# spec 001 section 3.3, Table 2: (f, c); section 8.5 closes the gap at 30 deg as alpha >= 30 deg
RADIAL_LOAD_TERM = (0.0009, 0.55)
ANGULAR_LOAD_TERM_BELOW_30 = (0.0010, 0.33)
ANGULAR_LOAD_TERM_FROM_30 = (0.0013, 0.33)


class StaticLoadFactors(NamedTuple):
    """Static radial and axial load factors of Table 1."""

    radial_factor: float | np.ndarray
    """x0. [-]"""
    axial_factor: float | np.ndarray
    """y0. [-]"""


class LoadTermConstants(NamedTuple):
    """Factor and exponent of the load term, Table 2."""

    load_term_factor: float | np.ndarray
    """f. [-]"""
    load_term_exponent: float | np.ndarray
    """c (called e in task 3, spec 001 section 8.1). [-]"""


class TwoTermTorque(NamedTuple):
    """Friction torque of the two-term model (3.3), all in N*m."""

    torque: float | np.ndarray
    """T = T0 + T_F. [N*m]"""
    speed_term: float | np.ndarray
    """T0, the speed-dependent torque. [N*m]"""
    load_term: float | np.ndarray
    """T_F, the load-dependent torque. [N*m]"""


# ----------------------------------------------------------------------------- helpers
def _check_type(bearing_type):
    if bearing_type not in BEARING_TYPES:
        raise InputError(f"bearing_type must be one of {list(BEARING_TYPES)}, got {bearing_type!r}")


def _contact_angle_deg(bearing_type, contact_angle, table):
    if contact_angle is None:
        raise InputError(
            f"contact_angle: an angular-contact bearing needs its contact angle for {table} "
            f"(or give the constants explicitly)"
        )
    a = check_finite("contact_angle", contact_angle, "rad")
    deg = np.degrees(a)
    bad = ~((deg > 0.0) & (deg < 90.0))
    if bad.any():
        raise InputError(
            f"contact_angle must be in (0, 90) [deg] for an angular-contact bearing, "
            f"got {float(deg[bad].flat[0])!r}"
        )
    return deg


def _scalar(x):
    x = np.asarray(x, dtype=float)
    return x[()]


# ----------------------------------------------------------------------------- static equivalent load
def static_load_factors(bearing_type="radial", contact_angle=None):
    """Static radial and axial load factors x0, y0 of Table 1.

    Parameters
    ----------
    bearing_type : {"radial", "angular"}
        Deep-groove (radial) or angular-contact single-row ball bearing. [-]
    contact_angle : array_like, optional
        Contact angle of an angular-contact bearing; one of the tabulated 18, 20, 26, 30 or 36 deg of
        Table 1, or one of the standard angles 15, 25, 35, 40, 45 deg of ISO 76:2006 table 1. Ignored
        for a radial bearing. [rad]

    Returns
    -------
    StaticLoadFactors
        ``radial_factor`` x0 and ``axial_factor`` y0. [-]

    Raises
    ------
    InputError
        Unknown type, or an angular-contact angle in neither table (spec 001 section 3.1 forbids
        interpolation; give x0 and y0 explicitly to the load functions instead).

    Notes
    -----
    Spec 001 section 3.1, Table 1; the angles it lacks from ISO 76:2006 table 1 (X0 = 0.5 and
    Y0 = 0.46, 0.38, 0.29, 0.26, 0.22 at 15, 25, 35, 40, 45 deg).

    Examples
    --------
    >>> static_load_factors("radial")
    StaticLoadFactors(radial_factor=0.6, axial_factor=0.5)
    >>> [float(v) for v in static_load_factors("angular", np.radians(26.0))]
    [0.5, 0.37]
    >>> [float(v) for v in static_load_factors("angular", np.radians(40.0))]
    [0.5, 0.26]
    """
    _check_type(bearing_type)
    if bearing_type == "radial":
        return StaticLoadFactors(*RADIAL_STATIC_FACTORS)
    deg = _contact_angle_deg(bearing_type, contact_angle, "Table 1")
    x0 = np.full(deg.shape, np.nan)
    y0 = np.full(deg.shape, np.nan)
    for angle, (x, y) in ANGULAR_STATIC_FACTORS.items():
        hit = np.abs(deg - angle) <= _ANGLE_TOL_DEG
        x0 = np.where(hit, x, x0)
        y0 = np.where(hit, y, y0)
    # the standard angles of ISO 76:2006 table 1 that spec 001's table lacks (15, 25, 35, 40, 45 deg;
    # at 20 and 30 deg both tables agree): the ISO row, not an interpolation
    from ..ratings.static import _ANGULAR_ANGLES_DEG, _ANGULAR_X0, _ANGULAR_Y0

    for angle, y in zip(_ANGULAR_ANGLES_DEG, _ANGULAR_Y0):
        hit = np.isnan(x0) & (np.abs(deg - angle) <= _ANGLE_TOL_DEG)
        x0 = np.where(hit, _ANGULAR_X0, x0)
        y0 = np.where(hit, y, y0)
    missing = np.isnan(x0)
    if missing.any():
        rows = ", ".join(f"{a:g}" for a in sorted({*ANGULAR_STATIC_FACTORS, *_ANGULAR_ANGLES_DEG}))
        raise InputError(
            f"contact_angle must be one of the Table 1 or ISO 76 angles ({rows}) [deg] unless x0 and y0 "
            f"are given explicitly, got {float(deg[missing].flat[0])!r}"
        )
    return StaticLoadFactors(_scalar(x0), _scalar(y0))


def _branches(radial_load, axial_load, bearing_type, contact_angle, radial_factor, axial_factor):
    """The two terms of the max rule (3.1): (x0 F_r + y0 F_a, F_r), inputs checked."""
    fr = check_nonnegative("radial_load", radial_load, "N")
    fa = check_nonnegative("axial_load", axial_load, "N")
    _check_type(bearing_type)
    if radial_factor is None or axial_factor is None:
        x_tab, y_tab = static_load_factors(bearing_type, contact_angle)
        radial_factor = x_tab if radial_factor is None else radial_factor
        axial_factor = y_tab if axial_factor is None else axial_factor
    x0 = check_nonnegative("radial_factor", radial_factor, "-")
    y0 = check_nonnegative("axial_factor", axial_factor, "-")
    return x0 * fr + y0 * fa, fr


def equivalent_static_load(
    radial_load,
    axial_load,
    *,
    bearing_type="radial",
    contact_angle=None,
    radial_factor=None,
    axial_factor=None,
):
    """Static equivalent load P0 by the max rule (3.1).

    Parameters
    ----------
    radial_load : array_like
        Radial load F_r. [N]
    axial_load : array_like
        Axial load F_a. [N]
    bearing_type : {"radial", "angular"}
        Selects the row of Table 1. [-]
    contact_angle : array_like, optional
        Contact angle of an angular-contact bearing (a Table 1 angle unless both factors are
        given). [rad]
    radial_factor : array_like, optional
        Override of x0. [-]
    axial_factor : array_like, optional
        Override of y0. [-]

    Returns
    -------
    float or ndarray
        P0 = max(x0 F_r + y0 F_a, F_r). [N]

    Notes
    -----
    Spec 001 eq. (3.1). Pure axial load on a radial bearing gives P0 = 0.5 F_a, not F_a.

    Examples
    --------
    >>> float(equivalent_static_load(0.0, 19.62))
    9.81
    >>> float(equivalent_static_load(19.62, 0.0))
    19.62
    """
    combined, fr = _branches(
        radial_load, axial_load, bearing_type, contact_angle, radial_factor, axial_factor
    )
    return _scalar(np.maximum(combined, fr))  # (3.1)


def combined_branch_governs(
    radial_load,
    axial_load,
    *,
    bearing_type="radial",
    contact_angle=None,
    radial_factor=None,
    axial_factor=None,
):
    """Which branch of (3.1) gives P0: True where x0 F_r + y0 F_a >= F_r.

    Parameters
    ----------
    radial_load : array_like
        Radial load F_r. [N]
    axial_load : array_like
        Axial load F_a. [N]
    bearing_type : {"radial", "angular"}
        Selects the row of Table 1. [-]
    contact_angle : array_like, optional
        Contact angle of an angular-contact bearing. [rad]
    radial_factor : array_like, optional
        Override of x0. [-]
    axial_factor : array_like, optional
        Override of y0. [-]

    Returns
    -------
    bool or ndarray of bool
        True where the combined term governs (ties count as combined: both terms are equal there).

    Examples
    --------
    >>> bool(combined_branch_governs(np.sin(np.radians(45)), np.cos(np.radians(45))))
    True
    >>> bool(combined_branch_governs(np.sin(np.radians(60)), np.cos(np.radians(60))))
    False
    """
    combined, fr = _branches(
        radial_load, axial_load, bearing_type, contact_angle, radial_factor, axial_factor
    )
    return np.asarray(combined >= fr)[()]


# ----------------------------------------------------------------------------- one-term model
def handbook_friction_coefficient(bearing_type="radial"):
    """Handbook reduced friction coefficient mu of the one-term model (section 3.2).

    Parameters
    ----------
    bearing_type : {"radial", "angular"}
        0.0015 for radial, 0.0020 for angular-contact single-row ball bearings. [-]

    Returns
    -------
    float
        mu. [-]

    Examples
    --------
    >>> handbook_friction_coefficient("angular")
    0.002
    """
    _check_type(bearing_type)
    return HANDBOOK_FRICTION_COEFFICIENTS[bearing_type]


def one_term(equivalent_load, bore, *, bearing_type="radial", reduced_friction_coefficient=None,
             friction_coefficient=None):
    """Friction torque of the one-term model, T = mu P0 d / 2 (3.2).

    Parameters
    ----------
    equivalent_load : array_like
        Static equivalent load P0 of (3.1). [N]
    bore : array_like
        Bore diameter d (not the mean diameter, spec 001 section 8.15). [m]
    bearing_type : {"radial", "angular"}
        Selects the handbook mu when ``reduced_friction_coefficient`` is not given. [-]
    reduced_friction_coefficient : array_like, optional
        Override of mu, the friction coefficient referred to the bore. [-]
    friction_coefficient : array_like, optional
        Deprecated name of ``reduced_friction_coefficient`` (warns with DeprecationWarning). [-]

    Returns
    -------
    float or ndarray
        T. [N*m]

    Notes
    -----
    Spec 001 eq. (3.2); handbook mu = 0.0015 (radial), 0.0020 (angular contact).

    Examples
    --------
    Spec 001 section 3.5 (bearing 1000095, Q = 2 kg, beta = 90 deg):

    >>> print(f"{one_term(19.62, 5e-3) * 1e3:.6f} N*mm")
    0.073575 N*mm
    """
    if friction_coefficient is not None:
        if reduced_friction_coefficient is not None:
            raise InputError("give reduced_friction_coefficient only (friction_coefficient is its old name)")
        warnings.warn("one_term(friction_coefficient=) is deprecated; use reduced_friction_coefficient=",
                      DeprecationWarning, stacklevel=2)
        reduced_friction_coefficient = friction_coefficient
    p0 = check_nonnegative("equivalent_load", equivalent_load, "N")
    d = check_positive("bore", bore, "m")
    mu = (
        handbook_friction_coefficient(bearing_type)
        if reduced_friction_coefficient is None
        else reduced_friction_coefficient
    )
    mu = check_nonnegative("reduced_friction_coefficient", mu, "-")
    return _scalar(mu * p0 * d / 2.0)  # (3.2)


# ----------------------------------------------------------------------------- two-term model
def load_term_constants(bearing_type="radial", contact_angle=None):
    """Factor f and exponent c of the load term, Table 2.

    Parameters
    ----------
    bearing_type : {"radial", "angular"}
        Deep-groove or angular-contact single-row ball bearing. [-]
    contact_angle : array_like, optional
        Contact angle of an angular-contact bearing: alpha < 30 deg gives f = 0.0010, alpha >= 30 deg
        gives f = 0.0013 (spec 001 section 8.5). Ignored for a radial bearing. [rad]

    Returns
    -------
    LoadTermConstants
        ``load_term_factor`` f and ``load_term_exponent`` c. [-]

    Examples
    --------
    >>> load_term_constants("radial")
    LoadTermConstants(load_term_factor=0.0009, load_term_exponent=0.55)
    >>> float(load_term_constants("angular", np.radians(30.0)).load_term_factor)
    0.0013
    """
    _check_type(bearing_type)
    if bearing_type == "radial":
        return LoadTermConstants(*RADIAL_LOAD_TERM)
    deg = _contact_angle_deg(bearing_type, contact_angle, "Table 2")
    from_30 = deg >= 30.0 - _ANGLE_TOL_DEG  # "30 deg" read in radians is 29.999999999999996 deg
    f = np.where(from_30, ANGULAR_LOAD_TERM_FROM_30[0], ANGULAR_LOAD_TERM_BELOW_30[0])
    c = np.where(from_30, ANGULAR_LOAD_TERM_FROM_30[1], ANGULAR_LOAD_TERM_BELOW_30[1])
    return LoadTermConstants(_scalar(f), _scalar(c))


def load_term(
    equivalent_load,
    mean_diameter,
    static_load_rating,
    *,
    bearing_type="radial",
    contact_angle=None,
    load_term_factor=None,
    load_term_exponent=None,
):
    """Load-dependent friction torque T_F = f P0 (P0/C0)^c d_m (3.4).

    Parameters
    ----------
    equivalent_load : array_like
        Static equivalent load P0 of (3.1). [N]
    mean_diameter : array_like
        Mean diameter d_m = (d + D)/2. [m]
    static_load_rating : array_like
        Basic static load rating C0. [N]
    bearing_type : {"radial", "angular"}
        Selects the row of Table 2 for the constants not given. [-]
    contact_angle : array_like, optional
        Contact angle of an angular-contact bearing (Table 2 rows). [rad]
    load_term_factor : array_like, optional
        Override of f. [-]
    load_term_exponent : array_like, optional
        Override of c. [-]

    Returns
    -------
    float or ndarray
        T_F. [N*m]

    Warns
    -----
    ValidityWarning
        Where P0 > C0: the handbook fit is for loads below the static rating.

    Notes
    -----
    Spec 001 eq. (3.4), with P0 as the load (section 8.16). The formula is dimensionally
    homogeneous, so it is evaluated in SI directly.

    Examples
    --------
    Spec 001 section 3.5:

    >>> print(f"{load_term(19.62, 9e-3, 392.0) * 1e3:.6f} N*mm")
    0.030610 N*mm
    """
    p0 = check_nonnegative("equivalent_load", equivalent_load, "N")
    dm = check_positive("mean_diameter", mean_diameter, "m")
    c0 = check_positive("static_load_rating", static_load_rating, "N")
    if load_term_factor is None or load_term_exponent is None:
        f_tab, c_tab = load_term_constants(bearing_type, contact_angle)
        load_term_factor = f_tab if load_term_factor is None else load_term_factor
        load_term_exponent = c_tab if load_term_exponent is None else load_term_exponent
    else:
        _check_type(bearing_type)
    f = check_nonnegative("load_term_factor", load_term_factor, "-")
    c = check_finite("load_term_exponent", load_term_exponent, "-")
    ratio = p0 / c0
    if np.any(ratio > 1.0):
        warnings.warn(
            f"equivalent_load exceeds static_load_rating (P0/C0 up to {float(np.max(ratio)):.3g}); "
            "the handbook load term (3.4) is extrapolated",
            ValidityWarning,
            stacklevel=2,
        )
    return _scalar(f * p0 * ratio**c * dm)  # (3.4)


def speed_term(shaft_speed, mean_diameter, speed_term_factor):
    """Speed-dependent friction torque T0 = f0 d_m^3 n^(2/3) (3.5).

    Parameters
    ----------
    shaft_speed : array_like
        Inner-ring (spindle) speed n; the sense of rotation does not matter. [rad/s]
    mean_diameter : array_like
        Mean diameter d_m = (d + D)/2. [m]
    speed_term_factor : array_like
        f0 in the published unit N*mm^-2*min^(2/3) (T0 in N*mm with d_m in mm and n in rpm); order
        1e-7 to 1e-6. It has no handbook value: it depends on the bearing type, the lubrication
        and the lubricant viscosity, and is measured (lab task 2) or derived from Palmgren's f0 with
        :func:`speed_term_factor_from_palmgren`. [N*mm^-2*min^(2/3)]

    Returns
    -------
    float or ndarray
        T0. [N*m]

    Notes
    -----
    Spec 001 eq. (3.5). The fit is not dimensionally homogeneous: its inputs are converted to mm
    and rpm and its output from N*mm to N*m here, once.

    Examples
    --------
    Spec 001 section 3.5 (d_m = 9 mm, f0 = 2e-7, n = 3000 rpm):

    >>> print(f"{speed_term(3000 * 2 * np.pi / 60, 9e-3, 2.0e-7) * 1e3:.6f} N*mm")
    0.030328 N*mm
    """
    n = check_finite("shaft_speed", shaft_speed, "rad/s")
    dm = check_positive("mean_diameter", mean_diameter, "m")
    f0 = check_nonnegative("speed_term_factor", speed_term_factor, "N*mm^-2*min^(2/3)")
    n_rpm = np.abs(n) / _RPM
    dm_mm = dm / _MM
    t0_nmm = f0 * dm_mm**3 * n_rpm ** (2.0 / 3.0)  # (3.5), N*mm
    return _scalar(t0_nmm * _MM)  # N*mm -> N*m


def two_term(
    equivalent_load,
    shaft_speed,
    mean_diameter,
    static_load_rating,
    speed_term_factor,
    *,
    bearing_type="radial",
    contact_angle=None,
    load_term_factor=None,
    load_term_exponent=None,
):
    """Friction torque of the two-term model, T = T0 + T_F (3.3)-(3.5).

    Parameters
    ----------
    equivalent_load : array_like
        Static equivalent load P0 of (3.1). [N]
    shaft_speed : array_like
        Inner-ring speed n. [rad/s]
    mean_diameter : array_like
        Mean diameter d_m = (d + D)/2. [m]
    static_load_rating : array_like
        Basic static load rating C0. [N]
    speed_term_factor : array_like
        f0 of (3.5). [N*mm^-2*min^(2/3)]
    bearing_type : {"radial", "angular"}
        Selects the row of Table 2. [-]
    contact_angle : array_like, optional
        Contact angle of an angular-contact bearing. [rad]
    load_term_factor : array_like, optional
        Override of f. [-]
    load_term_exponent : array_like, optional
        Override of c. [-]

    Returns
    -------
    TwoTermTorque
        ``torque`` T, ``speed_term`` T0 and ``load_term`` T_F. [N*m]

    Examples
    --------
    >>> t = two_term(19.62, 3000 * 2 * np.pi / 60, 9e-3, 392.0, 2.0e-7)
    >>> print(f"{t.torque * 1e3:.6f} = {t.speed_term * 1e3:.6f} + {t.load_term * 1e3:.6f} N*mm")
    0.060937 = 0.030328 + 0.030610 N*mm
    """
    t_f = load_term(
        equivalent_load,
        mean_diameter,
        static_load_rating,
        bearing_type=bearing_type,
        contact_angle=contact_angle,
        load_term_factor=load_term_factor,
        load_term_exponent=load_term_exponent,
    )
    t_0 = speed_term(shaft_speed, mean_diameter, speed_term_factor)
    t_0, t_f = np.broadcast_arrays(np.asarray(t_0), np.asarray(t_f))
    return TwoTermTorque(_scalar(t_0 + t_f), _scalar(t_0), _scalar(t_f))  # (3.3)


# ----------------------------------------------------------------------------- Palmgren
def palmgren(kinematic_viscosity, shaft_speed, mean_diameter, palmgren_factor):
    r"""Palmgren's load-independent friction torque M0 from the lubricant viscosity.

    Parameters
    ----------
    kinematic_viscosity : array_like
        Kinematic viscosity nu of the lubricant at the operating temperature (for grease, of the
        base oil). [m^2/s]
    shaft_speed : array_like
        Inner-ring speed n; the sense of rotation does not matter. [rad/s]
    mean_diameter : array_like
        Mean diameter d_m = (d + D)/2. [m]
    palmgren_factor : array_like
        Palmgren's f0 (dimensionless in his fit; about 0.7-2 for single-row deep-groove bearings,
        higher for oil bath and grease). [-]

    Returns
    -------
    float or ndarray
        M0. [N*m]

    Notes
    -----
    Palmgren (module reference [2]): M0 = 1e-7 f0 (nu n)^(2/3) d_m^3 for nu n >= 2000 and 160e-7 f0 d_m^3 below, with
    M0 in N*mm, nu in cSt (mm^2/s), n in rpm and d_m in mm; the inputs and the output are converted
    here, once. For nu n >= 2000 it equals the speed term (3.5) of spec 001 with
    ``speed_term_factor = speed_term_factor_from_palmgren(palmgren_factor, kinematic_viscosity)``.

    Examples
    --------
    Bearing 101 (d_m = 20 mm) at 3000 rpm in a 20 cSt oil with f0 = 2:

    >>> print(f"{palmgren(20e-6, 3000 * 2 * np.pi / 60, 20e-3, 2.0) * 1e3:.4f} N*mm")
    2.4522 N*mm
    """
    nu = check_nonnegative("kinematic_viscosity", kinematic_viscosity, "m^2/s")
    n = check_finite("shaft_speed", shaft_speed, "rad/s")
    dm = check_positive("mean_diameter", mean_diameter, "m")
    f0 = check_nonnegative("palmgren_factor", palmgren_factor, "-")
    vn = nu / _CST * np.abs(n) / _RPM  # cSt * rpm
    dm3 = (dm / _MM) ** 3  # mm^3
    m0 = np.where(vn >= 2000.0, 1e-7 * f0 * vn ** (2.0 / 3.0) * dm3, 160e-7 * f0 * dm3)  # N*mm
    return _scalar(m0 * _MM)  # N*mm -> N*m


def speed_term_factor_from_palmgren(palmgren_factor, kinematic_viscosity):
    r"""The f0 of (3.5) equivalent to Palmgren's f0 in a lubricant of viscosity nu.

    Parameters
    ----------
    palmgren_factor : array_like
        Palmgren's f0. [-]
    kinematic_viscosity : array_like
        Kinematic viscosity nu of the lubricant. [m^2/s]

    Returns
    -------
    float or ndarray
        f0 = 1e-7 f0_P nu^(2/3), nu in cSt. [N*mm^-2*min^(2/3)]

    Notes
    -----
    Valid where Palmgren's fit is in its speed-dependent branch, nu n >= 2000 cSt*rpm; see the
    module docstring for the derivation.

    Examples
    --------
    >>> print(f"{speed_term_factor_from_palmgren(2.0, 20e-6):.4e}")
    1.4736e-06
    """
    f0 = check_nonnegative("palmgren_factor", palmgren_factor, "-")
    nu = check_nonnegative("kinematic_viscosity", kinematic_viscosity, "m^2/s")
    return _scalar(1e-7 * f0 * (nu / _CST) ** (2.0 / 3.0))

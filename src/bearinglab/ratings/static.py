r"""Static load rating (ISO 76), fatigue load limit (ISO 281) and static safety of ball bearings.

Ratings from the geometry
-------------------------
static_load_factor          f0 of ISO 76 from the Hertz contact at 4200 MPa (both raceways)
static_load_rating          C0 = f0 i Z Dw^2 cos(alpha), ISO 76:2006 eq. (2)
fatigue_load_limit          Cu by the precise method (contact stress 1500 MPa), ISO 281:2007 annex B
fatigue_load_limit_simplified   Cu = C0 / 22, times (100 mm / Dpw)^0.5 above Dpw = 100 mm

Static equivalent load and safety
---------------------------------
static_load_factors         X0, Y0 of ISO 76:2006 table 1 (single- and double-row, self-aligning; thrust P0 = Fa)
static_equivalent_load      P0 = max(X0 Fr + Y0 Fa, Fr), ISO 76:2006 eqs. (3)-(4)
static_safety_factor        s0 = C0 / P0, with a warning below the usual minimum

All arguments in SI (m, N, rad). The ISO factor f0 is tabulated in N/mm^2; it is computed here in Pa
and the conversion is in :func:`static_load_rating`.

References
----------
.. [1] ISO 76:2006, *Rolling bearings -- Static load ratings*, clauses 3.1, 5.1 (eq. (2), table 2 of
   f0) and 5.2 (table 1 of X0, Y0); ISO/TR 10657 (explanatory notes) for the derivation of f0.
.. [2] ISO 281:2007, *Rolling bearings -- Dynamic load ratings and rating life*, annex B.3 (fatigue load
   limit Cu).
.. [3] EPK (European Bearing Corporation), General catalogue 2011, table 13, p. 36: X0 and Y0 of radial
   and angular contact ball bearings after ISO 76 -- single row and double row (double row radial 0.6,
   0.5; angular contact 15-45 deg X0 = 1, Y0 = 0.92, 0.84, 0.76, 0.66, 0.58, 0.52, 0.44; self-aligning
   X0 = 1, Y0 = 0.44 cot(alpha)). SKF General Catalogue 6000/I RU (2006) prints the same: 32 A (30 deg)
   Y0 0.66 and 33 D (45 deg) 0.44, p. 440; four-point (35 deg) P0 = Fr + 0.58 Fa, p. 455; double row deep
   groove P0 = 0.6 Fr + 0.5 Fa, p. 393; thrust ball bearings P0 = Fa, p. 841.
"""

from __future__ import annotations

import warnings
from typing import NamedTuple

import numpy as np

from .. import hertz
from .._validate import check_nonnegative, check_positive
from ..errors import InputError

__all__ = [
    "FATIGUE_CONTACT_STRESS",
    "ISO76_ELASTIC_MODULUS",
    "ISO76_POISSON_RATIO",
    "MINIMUM_STATIC_SAFETY",
    "STATIC_CONTACT_STRESS",
    "RatingWarning",
    "StaticLoadFactors",
    "fatigue_load_limit",
    "fatigue_load_limit_simplified",
    "static_equivalent_load",
    "static_load_factor",
    "static_load_factors",
    "static_load_rating",
    "static_safety_factor",
]


class RatingWarning(UserWarning):
    """A rating or life that is outside the standard's range, clamped, or not defined."""


# ISO 76:2006 clause 3.1: contact stress at the centre of the most heavily loaded contact, radial ball
# bearings (self-aligning ones excepted), at the basic static load rating. [Pa]
STATIC_CONTACT_STRESS = 4.2e9
# ISO 281:2007 annex B.3.1: contact stress at the fatigue load limit. [Pa]
FATIGUE_CONTACT_STRESS = 1.5e9
# ISO/TR 10657: the f0 values of ISO 76 table 2 assume steel, E = 207000 N/mm^2 and nu = 0.3
# (with these the Hertz solution below gives the tabulated f0 to their printed digit).
ISO76_ELASTIC_MODULUS = 2.07e11
ISO76_POISSON_RATIO = 0.3
# Stribeck's load-distribution factor: Q_max = 5 Fr / (Z cos alpha), the basis of ISO 76 (and of the
# ratio Cu / C0 = (1500 / 4200)^3 = 1 / 21.95 behind the simplified Cu = C0 / 22 of ISO 281).
_STRIBECK = 5.0
# ISO 281:2007 annex B.3.2: size factor of Cu above a pitch diameter of 100 mm. [m]
_CU_SIZE_PITCH = 0.1
_ISO_INNER, _ISO_OUTER = 0.52, 0.53  # ISO 76 table 2 footnote: groove radii 0.52 Dw and 0.53 Dw
# usual minimum s0 of ball bearings under normal conditions (ISO 76:2006 annex A, guideline values)
MINIMUM_STATIC_SAFETY = 1.0

# ISO 76:2006 table 1, single-row ball bearings: (X0, Y0); angular contact by contact angle [deg].
# Checked (issue 12): X0 = 0.6, Y0 = 0.5 of deep groove also in SKF's catalogue (P0 = 0.6 Fr + 0.5 Fa,
# P0 >= Fr) and in an independent implementation; X0 = 0.5 of angular contact likewise. The Y0 of angular
# contact by angle are not confirmed by a public source (one public implementation uses 0.22 cot(alpha),
# the rule of tapered roller bearings, which agrees only at 40-45 deg).
_RADIAL_X0_Y0 = (0.6, 0.5)
_ANGULAR_ANGLES_DEG = np.array([15.0, 20.0, 25.0, 30.0, 35.0, 40.0, 45.0])
_ANGULAR_Y0 = np.array([0.46, 0.42, 0.38, 0.33, 0.29, 0.26, 0.22])
_ANGULAR_X0 = 0.5
# ISO 76:2006 table 1, double-row angular contact (and four-point, which SKF rates so) by angle: X0 = 1 and
# twice the single-row Y0 (module reference [3]); self-aligning X0 = 1, Y0 = 0.44 cot(alpha).
_DOUBLE_ROW_Y0 = 2.0 * _ANGULAR_Y0
_SELF_ALIGNING_Y0 = 0.44


def _contact_load_at_stress(stress, ball_diameter, pitch_diameter, conformity, contact_angle, race):
    """Normal load [N] at which the Hertz pressure of one raceway contact reaches ``stress``."""
    from ..geometry import raceway_curvature

    curv = raceway_curvature(ball_diameter, pitch_diameter, conformity, contact_angle, race=race)
    c = hertz.coefficients(curv.curvature_difference)
    e_red = ISO76_ELASTIC_MODULUS / (1.0 - ISO76_POISSON_RATIO**2)  # E' of the steel pair
    # p_max = 1.5 Q / (pi a b), a = a* (3 Q / (E' sum rho))^(1/3), b likewise (Harris & Kotzalas ch. 6)
    return (stress * np.pi * c.a_star * c.b_star / 1.5) ** 3 * (3.0 / (curv.curvature_sum * e_red)) ** 2


def _rating_at_stress(stress, ball_diameter, pitch_diameter, contact_angle, inner, outer):
    """min(Q_i, Q_e) / (5 Dw^2) at the given contact stress. [Pa]"""
    q_i = _contact_load_at_stress(stress, ball_diameter, pitch_diameter, inner, contact_angle, "inner")
    q_o = _contact_load_at_stress(stress, ball_diameter, pitch_diameter, outer, contact_angle, "outer")
    return np.minimum(q_i, q_o) / (_STRIBECK * np.asarray(ball_diameter) ** 2)


def static_load_factor(ball_diameter, pitch_diameter, contact_angle=0.0, *,
                       inner_conformity=_ISO_INNER, outer_conformity=_ISO_OUTER):
    r"""The factor f0 of the basic static load rating of radial ball bearings.

    Parameters
    ----------
    ball_diameter : array_like
        Ball diameter Dw. [m]
    pitch_diameter : array_like
        Pitch diameter Dpw, > Dw. [m]
    contact_angle : array_like
        Nominal contact angle alpha. [rad]
    inner_conformity, outer_conformity : array_like
        Groove radius over ball diameter; ISO 76 table 2 is for 0.52 and 0.53. [-]

    Returns
    -------
    ndarray or float
        f0 in N/mm^2 (the unit of ISO 76 table 2). [N/mm^2]

    Notes
    -----
    ISO 76:2006 clause 3.1 defines C0 as the radial load giving 4200 MPa at the centre of the most
    heavily loaded contact; with Stribeck's distribution :math:`Q_{max} = 5 F_r / (Z \cos\alpha)`,

    .. math:: f_0 = \frac{\min(Q_i, Q_e)}{5 D_w^2},

    where :math:`Q_i, Q_e` are the loads at which the exact Hertz pressure of the inner and outer
    raceway contacts reaches 4200 MPa (steel, E = 207 GPa, nu = 0.3). With the conformities 0.52 /
    0.53 this reproduces all 26 rows of ISO 76 table 2 (gamma = 0 to 0.40; 14.7 at 0, 16.4 at 0.10,
    14.0 at 0.20, 9.4 at 0.40) to its printed digit (tests/data/iso76_f0.csv), and SKF's calculation
    factor f0 = 14 of the 6205.

    Examples
    --------
    >>> print(f"{static_load_factor(7.94e-3, 39.04e-3):.2f}")
    13.87
    """
    d = check_positive("ball_diameter", ball_diameter, "m")
    q = _rating_at_stress(STATIC_CONTACT_STRESS, d, pitch_diameter, contact_angle,
                          inner_conformity, outer_conformity)
    return (q * 1e-6)[()]  # Pa -> N/mm^2


def static_load_rating(n_balls, ball_diameter, pitch_diameter, contact_angle=0.0, *, n_rows=1,
                       inner_conformity=_ISO_INNER, outer_conformity=_ISO_OUTER):
    r"""Basic static radial load rating C0 of a radial or angular-contact ball bearing.

    Parameters
    ----------
    n_balls : array_like
        Balls per row Z. [-]
    ball_diameter : array_like
        Ball diameter Dw. [m]
    pitch_diameter : array_like
        Pitch diameter Dpw. [m]
    contact_angle : array_like
        Nominal contact angle alpha. [rad]
    n_rows : int
        Number of rows i. [-]
    inner_conformity, outer_conformity : array_like
        Groove radius over ball diameter. [-]

    Returns
    -------
    ndarray or float
        C0. [N]

    Notes
    -----
    ISO 76:2006 eq. (2): :math:`C_{0r} = f_0\, i\, Z\, D_w^2 \cos\alpha` with f0 of
    :func:`static_load_factor`.

    Examples
    --------
    >>> print(f"{static_load_rating(9, 7.94e-3, 39.04e-3) / 1e3:.2f} kN")
    7.87 kN
    """
    z = check_positive("n_balls", n_balls, "-")
    d = check_positive("ball_diameter", ball_diameter, "m")
    f0 = static_load_factor(d, pitch_diameter, contact_angle, inner_conformity=inner_conformity,
                            outer_conformity=outer_conformity)
    return (f0 * 1e6 * n_rows * z * d**2 * np.cos(contact_angle))[()]


def fatigue_load_limit(n_balls, ball_diameter, pitch_diameter, contact_angle=0.0, *, n_rows=1,
                       inner_conformity=_ISO_INNER, outer_conformity=_ISO_OUTER):
    r"""Fatigue load limit Cu by the precise method: the load giving 1500 MPa at the heaviest contact.

    Parameters
    ----------
    n_balls : array_like
        Balls per row Z. [-]
    ball_diameter : array_like
        Ball diameter Dw. [m]
    pitch_diameter : array_like
        Pitch diameter Dpw. [m]
    contact_angle : array_like
        Nominal contact angle alpha. [rad]
    n_rows : int
        Number of rows i. [-]
    inner_conformity, outer_conformity : array_like
        Groove radius over ball diameter. [-]

    Returns
    -------
    ndarray or float
        Cu. [N]

    Notes
    -----
    ISO 281:2007 annex B.3: the load at which the contact stress of the most heavily loaded contact
    reaches 1500 MPa, computed as C0 of ISO 76 (Hertz contact of both raceways, Stribeck's factor 5)
    at 1500 MPa in place of 4200 MPa; for pitch diameters above 100 mm it is multiplied by the size
    factor :math:`(100/D_{pw})^{0.5}` of annex B.3.2. With the conformities of ISO 76 it equals
    :math:`C_0 (1500/4200)^3 = C_0 / 21.95`, which the simplified method rounds to :math:`C_0/22`.

    Examples
    --------
    >>> print(f"{fatigue_load_limit(9, 7.94e-3, 39.04e-3):.1f} N")
    358.6 N
    """
    z = check_positive("n_balls", n_balls, "-")
    d = check_positive("ball_diameter", ball_diameter, "m")
    dpw = check_positive("pitch_diameter", pitch_diameter, "m")
    q = _rating_at_stress(FATIGUE_CONTACT_STRESS, d, dpw, contact_angle, inner_conformity, outer_conformity)
    cu = q * n_rows * z * d**2 * np.cos(contact_angle)
    return (cu * _size_factor(dpw))[()]


def _size_factor(pitch_diameter):
    return np.where(pitch_diameter > _CU_SIZE_PITCH, np.sqrt(_CU_SIZE_PITCH / pitch_diameter), 1.0)


def fatigue_load_limit_simplified(static_load_rating, pitch_diameter):
    r"""Fatigue load limit by the simplified method of ISO 281:2007 annex B.3.2 for ball bearings.

    Parameters
    ----------
    static_load_rating : array_like
        C0. [N]
    pitch_diameter : array_like
        Pitch diameter Dpw (or (d + D)/2). [m]

    Returns
    -------
    ndarray or float
        :math:`C_u = C_0/22` for :math:`D_{pw} \le 100` mm, else :math:`C_0/22\,(100/D_{pw})^{0.5}`. [N]

    Examples
    --------
    >>> print(f"{fatigue_load_limit_simplified(22000.0, 0.05):.0f} N")
    1000 N
    """
    c0 = check_positive("static_load_rating", static_load_rating, "N")
    dpw = check_positive("pitch_diameter", pitch_diameter, "m")
    return (c0 / 22.0 * _size_factor(dpw))[()]


class StaticLoadFactors(NamedTuple):
    """Static radial and axial load factors of ISO 76."""

    radial_factor: float | np.ndarray
    """X0. [-]"""
    axial_factor: float | np.ndarray
    """Y0. [-]"""


def _angular_degrees(contact_angle, table, instead, *, lowest=15.0):
    """Contact angle in degrees, required in [lowest, 45] (the angular-contact rows of the ISO tables
    tabulated here); the message says what to use ``instead`` (e.g. the maker's factors) for an angle outside."""
    deg = np.degrees(np.asarray(contact_angle, dtype=float))
    bad = ~((deg >= lowest - 1e-9) & (deg <= 45.0 + 1e-9))
    if bad.any():
        got = float(deg[bad].flat[0])
        # ISO 281 table 3 also has rows for 5 and 10 deg: not carried over, as no published source that
        # confirms them (and the column of relative axial load they are read by) was found (issue 15)
        why = (f"angles below {lowest:g} deg are not tabulated here" if got < lowest
               else "above 45 deg the bearing is a thrust bearing, not covered")
        raise InputError(f"contact_angle must be in [{lowest:g}, 45] [deg] for {table} (angular contact), "
                         f"got {got:.6g} deg: {why}; check the bearing's nominal contact angle, or {instead}")
    return deg


def static_load_factors(contact_angle=0.0, *, bearing_type="radial"):
    """X0 and Y0 of ISO 76:2006 table 1 for radial ball bearings (and a thrust ball bearing's P0 = Fa).

    Parameters
    ----------
    contact_angle : array_like
        Nominal contact angle; angular-contact bearings 15 to 45 deg, linear between the rows;
        self-aligning ones below 45 deg; thrust ball bearings 90 deg. [rad]
    bearing_type : str
        ``radial`` and ``double-row-radial`` (X0 = 0.6, Y0 = 0.5 at any angle), ``angular``,
        ``double-row-angular`` and ``four-point`` (by angle), ``self-aligning`` (X0 = 1,
        Y0 = 0.44 cot(alpha)), ``thrust`` (X0 = 0, Y0 = 1: P0 = Fa).

    Returns
    -------
    StaticLoadFactors

    Examples
    --------
    >>> print(static_load_factors(np.radians(40.0), bearing_type="angular").axial_factor)
    0.26
    >>> print(static_load_factors(np.radians(35.0), bearing_type="four-point").axial_factor)
    0.58
    """
    if bearing_type in ("radial", "double-row-radial"):
        return StaticLoadFactors(*_RADIAL_X0_Y0)
    if bearing_type == "self-aligning":
        a = np.asarray(contact_angle, dtype=float)
        if not np.all((a > 0) & (a < np.pi / 4)):
            raise InputError(f"contact_angle must be in (0, 45) [deg] for a self-aligning ball bearing, got "
                             f"{float(np.degrees(np.min(a))):.6g} deg")
        return StaticLoadFactors(1.0, (_SELF_ALIGNING_Y0 / np.tan(a))[()])
    if bearing_type == "thrust":
        if not np.allclose(np.asarray(contact_angle, dtype=float), np.pi / 2, rtol=0.0, atol=1e-9):
            raise InputError(f"bearing_type 'thrust': the factors here are those of thrust ball bearings of 90 deg "
                             f"(P0 = Fa), got a contact angle of {float(np.degrees(np.min(contact_angle))):.6g} deg")
        return StaticLoadFactors(0.0, 1.0)
    if bearing_type not in ("angular", "double-row-angular", "four-point"):
        raise InputError(f"bearing_type must be one of ['radial', 'angular', 'four-point', 'double-row-angular', "
                         f"'double-row-radial', 'self-aligning', 'thrust'], got {bearing_type!r}")
    deg = _angular_degrees(contact_angle, "ISO 76 table 1",
                           "give P0 from the maker's X0 and Y0 (static_safety_factor(C0, P0))")
    if bearing_type == "angular":
        return StaticLoadFactors(_ANGULAR_X0, np.interp(deg, _ANGULAR_ANGLES_DEG, _ANGULAR_Y0)[()])
    return StaticLoadFactors(1.0, np.interp(deg, _ANGULAR_ANGLES_DEG, _DOUBLE_ROW_Y0)[()])


def static_equivalent_load(radial_load, axial_load, contact_angle=0.0, *, bearing_type="radial"):
    r"""Static equivalent radial load P0 of ISO 76.

    Parameters
    ----------
    radial_load, axial_load : array_like
        Fr and Fa, >= 0. [N]
    contact_angle : array_like
        Nominal contact angle (angular contact bearings). [rad]
    bearing_type : str
        See :func:`static_load_factors`.

    Returns
    -------
    ndarray or float
        :math:`P_0 = \max(X_0 F_r + Y_0 F_a, F_r)`, ISO 76:2006 eqs. (3) and (4); of a thrust ball
        bearing :math:`P_{0a} = F_a` (a radial load is refused). [N]

    Examples
    --------
    >>> print(static_equivalent_load(1000.0, 1000.0))
    1100.0
    """
    fr = check_nonnegative("radial_load", radial_load, "N")
    fa = check_nonnegative("axial_load", axial_load, "N")
    if bearing_type == "thrust":
        static_load_factors(contact_angle, bearing_type="thrust")
        if np.any(fr > 0):
            raise InputError(f"radial_load must be 0 [N] for a thrust ball bearing (P0 = Fa), got "
                             f"{float(np.max(fr)):g} N")
        return np.broadcast_to(fa, np.broadcast(fr, fa).shape).copy()[()]
    if bearing_type in ("angular", "double-row-angular", "four-point", "self-aligning") and not np.any(fa):
        # Fa = 0: P0 = max(X0 Fr, Fr) = Fr (X0 <= 1 on every row), so an angle outside the tabulated rows
        # needs no row
        return np.broadcast_to(fr, np.broadcast(fr, fa).shape).copy()[()]
    x0, y0 = static_load_factors(contact_angle, bearing_type=bearing_type)
    return np.maximum(x0 * fr + y0 * fa, fr)[()]


def static_safety_factor(static_load_rating, static_equivalent_load, *, minimum=MINIMUM_STATIC_SAFETY):
    """Static safety factor s0 = C0 / P0, with a warning below ``minimum``.

    Parameters
    ----------
    static_load_rating : array_like
        C0. [N]
    static_equivalent_load : array_like
        P0, >= 0 (0 gives an infinite s0). [N]
    minimum : float
        Usual lower limit of s0 for ball bearings under normal conditions (ISO 76:2006 annex A gives
        guideline values from 0.5 for smooth, quiet running to 2 for shock loads). [-]

    Returns
    -------
    ndarray or float
        s0. [-]

    Examples
    --------
    >>> print(static_safety_factor(7800.0, 1950.0))
    4.0
    """
    c0 = check_positive("static_load_rating", static_load_rating, "N")
    p0 = check_nonnegative("static_equivalent_load", static_equivalent_load, "N")
    with np.errstate(divide="ignore"):
        s0 = np.where(p0 > 0, c0 / np.where(p0 > 0, p0, 1.0), np.inf)
    low = s0 < minimum
    if low.any():
        warnings.warn(f"static safety factor s0 = {float(s0[low].min()):.3g} is below {minimum:g} "
                      f"({int(low.sum())} of {s0.size} cases): permanent deformation of the raceways is "
                      "likely (ISO 76:2006 annex A)", RatingWarning, stacklevel=2)
    return s0[()]


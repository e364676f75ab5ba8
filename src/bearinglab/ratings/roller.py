r"""Load ratings, equivalent loads and rating life of roller bearings (ISO 76, ISO 281), and paired tapered bearings.

Ratings
-------
ROLLER_MATERIAL_FACTOR       b_m of ISO 281 table 1 for roller bearings
roller_load_rating_factor    f_c of ISO 281 table 7 (radial roller bearings)
roller_dynamic_load_rating   C = b_m f_c (i L_we cos alpha)^(7/9) Z^(3/4) D_we^(29/27) (radial), and the thrust form
roller_static_load_rating    C0 = 44 (1 - D_we cos alpha / D_pw) i Z L_we D_we cos alpha (ISO 76), and thrust
roller_fatigue_load_limit    Cu = C0 / 8.2 (ISO 281 annex B, roller bearings), size factor above D_pw = 100 mm

Equivalent loads and life
-------------------------
roller_load_factors          X, Y, e (ISO 281 table 8; the catalogue's e and Y where given)
roller_equivalent_load       P = X F_r + Y F_a
roller_static_equivalent_load  P0 = max(X0 F_r + Y0 F_a, F_r) (ISO 76)
roller_rating_life           L10 = 10^6 (C/P)^(10/3) (ISO 281 eq. (15), roller bearings)
roller_life_modification_factor   a_ISO of radial roller bearings (ISO 281 eq. (B.5) constants)

Paired tapered roller bearings
------------------------------
INDUCED_AXIAL_FACTORS        the makers' factors of the induced axial load (SKF 0.5, NSK 0.6)
induced_axial_load           F_a = f F_r / Y of a single-row tapered bearing under radial load
paired_axial_loads           the axial loads of two tapered bearings adjusted against each other

SI throughout (N, m, rad); lives in revolutions. The ISO factors are tabulated for N and mm; the functions
convert once.

References
----------
.. [1] ISO 281:2007, *Rolling bearings -- Dynamic load ratings and rating life*: table 1 (b_m), clause 6
   (roller bearings: eqs. (7)-(11), table 7 of f_c, table 8 of X, Y, e), eq. (15) with the exponent 10/3,
   annex B (fatigue load limit, the life modification factor a_ISO of roller bearings).
.. [2] ISO 76:2006, *Rolling bearings -- Static load ratings*, clause 6 (radial roller bearings: C0 at
   4000 MPa, X0 = 0.5, Y0 = 0.22 cot alpha single row, X0 = 1, Y0 = 0.44 cot alpha double row) and 7.
.. [3] ISO/TR 1281-1:2008, *Explanatory notes on ISO 281* (f_c of radial roller bearings as a function of
   gamma with lambda nu = 0.83), which reproduces table 7 of [1] to its printed rounding.
.. [4] SKF, *General Catalogue* 6000/I RU, 2006: p. 208 (the induced axial load F_a = 0.5 F_r / Y of a single
   row tapered roller bearing) and p. 613, table 3 (axial loads of two tapered bearings by load case).
.. [5] NSK, *Rolling Bearings*, CAT. No. E1102e: section 5.4.2, eq. (5.27) (F_a = 0.6 F_r / Y) and section
   5.7, example 5 (HR30305DJ and HR30206J back to back).
"""

from __future__ import annotations

import warnings
from typing import NamedTuple

import numpy as np

from .._validate import as_float, check_nonnegative, check_positive
from ..errors import InputError
from .lubrication import a_iso_inputs
from .static import RatingWarning

__all__ = [
    "INDUCED_AXIAL_FACTORS",
    "ROLLER_MATERIAL_FACTOR",
    "PairedAxialLoads",
    "RollerLoadFactors",
    "induced_axial_load",
    "paired_axial_loads",
    "roller_dynamic_load_rating",
    "roller_equivalent_load",
    "roller_fatigue_load_limit",
    "roller_life_modification_factor",
    "roller_load_factors",
    "roller_load_rating_factor",
    "roller_rating_life",
    "roller_static_equivalent_load",
    "roller_static_load_rating",
]

_MM = 1e-3
#: ISO 281:2007 table 1, b_m of roller bearings: radial cylindrical, tapered and needle (machined rings) 1.1,
#: spherical 1.15; thrust cylindrical 1.0, tapered 1.1, spherical 1.15.
ROLLER_MATERIAL_FACTOR = {"cylindrical": 1.1, "tapered": 1.1, "spherical": 1.15, "thrust-cylindrical": 1.0,
                          "thrust-tapered": 1.1, "thrust-spherical": 1.15}

# ISO 281:2007 table 7, f_c of radial roller bearings against gamma = D_we cos(alpha) / D_pw, linear between the
# rows. Checked (tests/ratings/test_roller_ratings.py): every row equals the formula of ISO/TR 1281-1 (reference [3],
# lambda nu = 0.83) to within its printed rounding (0.05).
_FC_GAMMA = np.array([0.01, 0.02, 0.03, 0.04, 0.05, 0.06, 0.07, 0.08, 0.09, 0.10, 0.12, 0.14, 0.16, 0.18, 0.20,
                      0.22, 0.24, 0.26, 0.28, 0.30])
_FC = np.array([52.1, 60.8, 66.5, 70.7, 74.1, 76.9, 79.2, 81.2, 82.8, 84.2, 86.4, 87.7, 88.5, 88.8, 88.7,
                88.2, 87.5, 86.4, 85.2, 83.8])
_C0_RADIAL, _C0_THRUST = 44.0, 220.0  # ISO 76:2006 eqs. for roller bearings, at 4000 MPa [N, mm]
_CU_RATIO, _CU_PITCH, _CU_EXPONENT = 8.2, 0.1, 0.3  # ISO 281:2007 annex B: Cu = C0/8.2, (100 mm / D_pw)^0.3 above
# ISO 281:2007 annex B, a_ISO of radial roller bearings: a = 0.1 [1 - (1.5859 - c / kappa^p) (e_C Cu / P)^0.4]^-9.185
# with (c, p) per kappa range (0.1-0.4, 0.4-1, 1-4). Checked: a_ISO is continuous at kappa = 0.4 (1.3993 / 0.4^0.054381
# = 1.2348 / 0.4^0.19087 to 6e-5) and at kappa = 1, as the ball-bearing constants of ratings.lubrication are.
_AISO_ROLLER = ((1.3993, 0.054381), (1.2348, 0.19087), (1.2348, 0.071739))

#: Factor f of the induced axial load F_a = f F_r / Y of a single-row tapered roller bearing: SKF 0.5
#: (General Catalogue 6000, p. 208; the default), NSK 0.6 (CAT. No. E1102e, eq. (5.27)).
INDUCED_AXIAL_FACTORS = {"SKF": 0.5, "NSK": 0.6}


def roller_load_rating_factor(roller_diameter, pitch_diameter, contact_angle=0.0):
    """The factor f_c of ISO 281:2007 table 7 for radial roller bearings.

    Parameters
    ----------
    roller_diameter : array_like
        D_we. [m]
    pitch_diameter : array_like
        D_pw. [m]
    contact_angle : array_like
        alpha. [rad]

    Returns
    -------
    ndarray or float
        f_c for C in N with D_we and L_we in mm, linear between the rows; gamma = D_we cos(alpha) / D_pw
        must be in [0.01, 0.30]. [-]

    Examples
    --------
    >>> print(f"{roller_load_rating_factor(11e-3, 60.5e-3):.2f}")
    88.79
    """
    d = check_positive("roller_diameter", roller_diameter, "m")
    dpw = check_positive("pitch_diameter", pitch_diameter, "m")
    gamma = d * np.cos(as_float("contact_angle", contact_angle)) / dpw
    bad = ~((gamma >= _FC_GAMMA[0]) & (gamma <= _FC_GAMMA[-1]))
    if bad.any():
        raise InputError(f"D_we cos(alpha) / D_pw must be in [0.01, 0.30] [-] for ISO 281 table 7, got "
                         f"{float(np.asarray(gamma)[bad].flat[0])!r}")
    return np.interp(gamma, _FC_GAMMA, _FC)[()]


def roller_dynamic_load_rating(rollers, roller_diameter, roller_length, pitch_diameter, contact_angle=0.0, *,
                               rows=1, bearing_type="cylindrical", load_rating_factor=None):
    r"""Basic dynamic load rating C of a radial (or thrust) roller bearing, ISO 281.

    Parameters
    ----------
    rollers : array_like
        Z per row. [-]
    roller_diameter : array_like
        D_we. [m]
    roller_length : array_like
        L_we. [m]
    pitch_diameter : array_like
        D_pw. [m]
    contact_angle : array_like
        alpha. [rad]
    rows : int
        i. [-]
    bearing_type : str
        A key of :data:`ROLLER_MATERIAL_FACTOR`; ``"thrust-..."`` gives the axial rating C_a.
    load_rating_factor : float, optional
        f_c; by default ISO 281 table 7 for a radial bearing. A thrust bearing needs it (ISO 281 table 9,
        not tabulated here). [-]

    Returns
    -------
    ndarray or float
        C (radial) or C_a (thrust). [N]

    Notes
    -----
    ISO 281:2007 clause 6, with D_we and L_we in mm: radial
    :math:`C_r = b_m f_c (i L_{we}\cos\alpha)^{7/9} Z^{3/4} D_{we}^{29/27}`; thrust with alpha = 90 deg
    :math:`C_a = b_m f_c L_{we}^{7/9} Z^{3/4} D_{we}^{29/27}`, otherwise
    :math:`C_a = b_m f_c (L_{we}\cos\alpha)^{7/9}\tan\alpha\, Z^{3/4} D_{we}^{29/27}`.

    Examples
    --------
    >>> print(f"{roller_dynamic_load_rating(14, 11e-3, 9.55e-3, 60.5e-3) / 1e3:.2f} kN")
    53.72 kN
    """
    if bearing_type not in ROLLER_MATERIAL_FACTOR:
        raise InputError(f"bearing_type must be one of {list(ROLLER_MATERIAL_FACTOR)}, got {bearing_type!r}")
    z = check_positive("rollers", rollers, "-")
    d = check_positive("roller_diameter", roller_diameter, "m")
    length = check_positive("roller_length", roller_length, "m")
    a = as_float("contact_angle", contact_angle)
    bm = ROLLER_MATERIAL_FACTOR[bearing_type]
    thrust = bearing_type.startswith("thrust")
    if load_rating_factor is None:
        if thrust:
            raise InputError("load_rating_factor (f_c of ISO 281 table 9) is needed for a thrust roller bearing")
        fc = roller_load_rating_factor(d, pitch_diameter, a)
    else:
        fc = check_positive("load_rating_factor", load_rating_factor, "-")
    dw, lw = d / _MM, length / _MM
    base = bm * fc * z**0.75 * dw ** (29.0 / 27.0)
    if not thrust:
        return (base * (rows * lw * np.cos(a)) ** (7.0 / 9.0))[()]
    right = np.isclose(a, np.pi / 2)
    with np.errstate(invalid="ignore"):
        inclined = (lw * np.cos(a)) ** (7.0 / 9.0) * np.tan(a)
    return (base * np.where(right, lw ** (7.0 / 9.0), inclined))[()]


def roller_static_load_rating(rollers, roller_diameter, roller_length, pitch_diameter, contact_angle=0.0, *,
                              rows=1, thrust=False):
    r"""Basic static load rating C0 of a roller bearing, ISO 76.

    Parameters
    ----------
    rollers : array_like
        Z per row. [-]
    roller_diameter : array_like
        D_we. [m]
    roller_length : array_like
        L_we. [m]
    pitch_diameter : array_like
        D_pw. [m]
    contact_angle : array_like
        alpha. [rad]
    rows : int
        i. [-]
    thrust : bool
        The axial rating C_0a of a thrust bearing.

    Returns
    -------
    ndarray or float
        C0. [N]

    Notes
    -----
    ISO 76:2006 (contact stress 4000 MPa at the most heavily loaded roller), with D_we, L_we in mm:
    :math:`C_{0r} = 44 (1 - D_{we}\cos\alpha/D_{pw})\, i Z L_{we} D_{we}\cos\alpha` and
    :math:`C_{0a} = 220 (1 - D_{we}\cos\alpha/D_{pw}) Z L_{we} D_{we}\sin\alpha` (220 Z L_we D_we at
    alpha = 90 deg).

    Examples
    --------
    >>> print(f"{roller_static_load_rating(14, 11e-3, 9.55e-3, 60.5e-3) / 1e3:.2f} kN")
    52.95 kN
    """
    z = check_positive("rollers", rollers, "-")
    d = check_positive("roller_diameter", roller_diameter, "m")
    length = check_positive("roller_length", roller_length, "m")
    dpw = check_positive("pitch_diameter", pitch_diameter, "m")
    a = as_float("contact_angle", contact_angle)
    gamma = d * np.cos(a) / dpw
    dw, lw = d / _MM, length / _MM
    if thrust:
        return (_C0_THRUST * np.where(np.isclose(a, np.pi / 2), 1.0, (1.0 - gamma) * np.sin(a)) * z * lw * dw)[()]
    return (_C0_RADIAL * (1.0 - gamma) * rows * z * lw * dw * np.cos(a))[()]


def roller_fatigue_load_limit(static_load_rating, pitch_diameter):
    r"""Fatigue load limit Cu of a roller bearing by the simplified rule of ISO 281 annex B.

    Parameters
    ----------
    static_load_rating : array_like
        C0. [N]
    pitch_diameter : array_like
        D_pw (or the mean diameter (d + D)/2 where D_pw is not known). [m]

    Returns
    -------
    ndarray or float
        :math:`C_u = C_0/8.2` up to D_pw = 100 mm, times :math:`(100\,\mathrm{mm}/D_{pw})^{0.3}` above. [N]

    Examples
    --------
    >>> print(f"{roller_fatigue_load_limit(53e3, 60.5e-3):.0f} N")
    6463 N
    """
    c0 = check_positive("static_load_rating", static_load_rating, "N")
    dpw = check_positive("pitch_diameter", pitch_diameter, "m")
    return (c0 / _CU_RATIO * np.where(dpw > _CU_PITCH, (_CU_PITCH / dpw) ** _CU_EXPONENT, 1.0))[()]


class RollerLoadFactors(NamedTuple):
    """X, Y and e of a radial roller bearing."""

    radial_factor: np.ndarray
    """X. [-]"""
    axial_factor: np.ndarray
    """Y. [-]"""
    limit: np.ndarray
    """e. [-]"""


def roller_load_factors(radial_load, axial_load, contact_angle=0.0, *, rows=1, ratio_limit=None, axial_factor=None,
                        axial_factor_below=None):
    r"""X, Y and e of a radial roller bearing (ISO 281 table 8), or from the catalogue's e and Y.

    Parameters
    ----------
    radial_load, axial_load : array_like
        F_r, F_a >= 0. [N]
    contact_angle : array_like
        alpha (0: P = F_r, no axial load carried by the raceways). [rad]
    rows : int
        1 or 2. [-]
    ratio_limit : float, optional
        The catalogue's e (else 1.5 tan alpha). [-]
    axial_factor : float, optional
        The catalogue's Y beyond e (single row: 0.4 cot alpha; double row Y2: 0.67 cot alpha). [-]
    axial_factor_below : float, optional
        The catalogue's Y1 up to e of a double-row bearing (else 0.45 cot alpha). [-]

    Returns
    -------
    RollerLoadFactors

    Notes
    -----
    ISO 281:2007 table 8, alpha != 0: single row X = 1, Y = 0 for F_a/F_r <= e and X = 0.4,
    Y = 0.4 cot alpha beyond; double row X = 1, Y = 0.45 cot alpha and X = 0.67, Y = 0.67 cot alpha;
    e = 1.5 tan alpha. The catalogue's e and Y (SKF prints them per bearing) take precedence.

    Examples
    --------
    >>> f = roller_load_factors(1000.0, 800.0, ratio_limit=0.37, axial_factor=1.6)
    >>> print(f.radial_factor, f.axial_factor, f.limit)
    0.4 1.6 0.37
    """
    fr = check_nonnegative("radial_load", radial_load, "N")
    fa = check_nonnegative("axial_load", axial_load, "N")
    a = as_float("contact_angle", contact_angle)
    if rows not in (1, 2):
        raise InputError(f"rows must be 1 or 2 [-], got {rows!r}")
    with np.errstate(divide="ignore"):
        cot = np.where(a > 0, 1.0 / np.tan(np.where(a > 0, a, 1.0)), np.inf)
    e = np.asarray(1.5 * np.tan(a) if ratio_limit is None else ratio_limit, dtype=float)
    if rows == 1:
        y_hi = 0.4 * cot if axial_factor is None else axial_factor
        x_lo, y_lo, x_hi = 1.0, 0.0, 0.4
    else:
        y_hi = 0.67 * cot if axial_factor is None else axial_factor
        y_lo = 0.45 * cot if axial_factor_below is None else axial_factor_below
        x_lo, x_hi = 1.0, 0.67
    if np.any(a == 0) and ratio_limit is None and np.any(fa > 0):
        warnings.warn("a radial roller bearing with alpha = 0 carries no axial load on its raceways: ISO 281 takes "
                      "P = F_r (the axial load on the ribs is not in P)", RatingWarning, stacklevel=2)
    with np.errstate(divide="ignore", invalid="ignore"):
        beyond = np.where(fr > 0, fa / np.where(fr > 0, fr, 1.0) > e, fa > 0) & (a > 0 if ratio_limit is None else True)
    x = np.where(beyond, x_hi, x_lo)
    y = np.where(beyond, y_hi, y_lo)
    y = np.where(np.isfinite(y), y, 0.0)
    return RollerLoadFactors(x[()], y[()], np.broadcast_to(e, np.shape(x))[()])


def roller_equivalent_load(radial_load, axial_load, contact_angle=0.0, **factors):
    """Dynamic equivalent load P = X F_r + Y F_a of a radial roller bearing (ISO 281 eq. (9)).

    Parameters
    ----------
    radial_load, axial_load : array_like
        F_r, F_a. [N]
    contact_angle : array_like
        alpha. [rad]
    **factors
        ``rows``, ``ratio_limit``, ``axial_factor``, ``axial_factor_below`` of :func:`roller_load_factors`.

    Returns
    -------
    ndarray or float
        P. [N]

    Examples
    --------
    >>> print(f"{roller_equivalent_load(1569.0, 3474.0, ratio_limit=0.83, axial_factor=0.73):.0f} N")  # NSK example 5
    3164 N
    """
    x, y, _ = roller_load_factors(radial_load, axial_load, contact_angle, **factors)
    return (x * np.asarray(radial_load, dtype=float) + y * np.asarray(axial_load, dtype=float))[()]


def roller_static_equivalent_load(radial_load, axial_load, contact_angle=0.0, *, rows=1, static_axial_factor=None):
    r"""Static equivalent load of a radial roller bearing (ISO 76).

    Parameters
    ----------
    radial_load, axial_load : array_like
        F_r, F_a. [N]
    contact_angle : array_like
        alpha. [rad]
    rows : int
        1 or 2. [-]
    static_axial_factor : float, optional
        The catalogue's Y0 (else 0.22 cot alpha single row, 0.44 cot alpha double row). [-]

    Returns
    -------
    ndarray or float
        Single row :math:`P_0 = \max(0.5 F_r + Y_0 F_a, F_r)`, double row :math:`F_r + Y_0 F_a`;
        :math:`F_r` at alpha = 0. [N]

    Examples
    --------
    >>> print(roller_static_equivalent_load(1000.0, 1000.0, static_axial_factor=0.9))
    1400.0
    """
    fr = check_nonnegative("radial_load", radial_load, "N")
    fa = check_nonnegative("axial_load", axial_load, "N")
    a = as_float("contact_angle", contact_angle)
    with np.errstate(divide="ignore"):
        cot = np.where(a > 0, 1.0 / np.tan(np.where(a > 0, a, 1.0)), 0.0)
    if static_axial_factor is None:
        y0 = (0.22 if rows == 1 else 0.44) * cot
    else:
        y0 = np.asarray(static_axial_factor, dtype=float)
    if rows == 1:
        p0 = np.maximum(0.5 * fr + y0 * fa, fr)
    else:
        p0 = fr + y0 * fa
    return np.where((a == 0) & (static_axial_factor is None), fr, p0)[()]


def roller_rating_life(dynamic_load_rating, equivalent_dynamic_load):
    """Basic rating life L10 of a roller bearing, ISO 281:2007 eq. (15) with p = 10/3.

    Parameters
    ----------
    dynamic_load_rating : array_like
        C. [N]
    equivalent_dynamic_load : array_like
        P >= 0 (0: infinite). [N]

    Returns
    -------
    ndarray or float
        :math:`L_{10} = 10^6 (C/P)^{10/3}`. [revolutions]

    Examples
    --------
    The SKF 24026 duty-cycle example (General Catalogue 6000/I RU, p. 80): C = 540 kN, P = 200 kN at 50 rpm
    prints L10h = 9 136 h:

    >>> print(f"{roller_rating_life(540e3, 200e3) / (60 * 50):.0f} h")
    9136 h
    """
    c = check_positive("dynamic_load_rating", dynamic_load_rating, "N")
    p = check_nonnegative("equivalent_dynamic_load", equivalent_dynamic_load, "N")
    with np.errstate(divide="ignore"):
        return (1e6 * (c / p) ** (10.0 / 3.0))[()]


def roller_life_modification_factor(viscosity_ratio, contamination_factor, fatigue_load_limit,
                                    equivalent_dynamic_load, *, ep_additives=False):
    r"""Life modification factor a_ISO of radial roller bearings, ISO 281:2007 annex B.

    Parameters
    ----------
    viscosity_ratio : array_like
        kappa = nu / nu1 > 0 (clamped to [0.1, 4]; a warning below 0.1). [-]
    contamination_factor : array_like
        e_C in [0, 1]. [-]
    fatigue_load_limit : array_like
        Cu. [N]
    equivalent_dynamic_load : array_like
        P > 0. [N]
    ep_additives : bool
        The EP-additive rule of ISO 281 clause 9.3.3 (kappa = 1 where kappa < 1 and e_C >= 0.2, a_ISO <= 3).

    Returns
    -------
    ndarray or float
        a_ISO in (0, 50]. [-]

    Notes
    -----
    .. math:: a_{ISO} = 0.1\left[1 - \left(1.5859 - \frac{c}{\kappa^{p}}\right)
              \left(\frac{e_C C_u}{P}\right)^{0.4}\right]^{-9.185}

    with (c, p) = (1.3993, 0.054381) for 0.1 <= kappa < 0.4, (1.2348, 0.19087) for 0.4 <= kappa < 1 and
    (1.2348, 0.071739) for 1 <= kappa <= 4; capped at 50, also where the bracket is <= 0.

    Examples
    --------
    >>> print(f"{roller_life_modification_factor(1.0, 0.5, 6700.0, 10000.0):.4f}")
    1.0605
    """
    # the checks, the warning below kappa = 0.1, the cap and the EP rule are those of the ball bearings' a_ISO
    k, ec, cu, p, cap = a_iso_inputs(viscosity_ratio, contamination_factor, fatigue_load_limit,
                                     equivalent_dynamic_load, ep_additives=ep_additives)
    c = np.where(k < 0.4, _AISO_ROLLER[0][0], _AISO_ROLLER[1][0])
    pw = np.select([k < 0.4, k < 1.0], [_AISO_ROLLER[0][1], _AISO_ROLLER[1][1]], _AISO_ROLLER[2][1])
    inner = 1.0 - (1.5859 - c / k**pw) * (ec * cu / p) ** 0.4
    with np.errstate(divide="ignore", over="ignore"):
        a_iso = np.where(inner > 0, 0.1 * np.where(inner > 0, inner, 1.0) ** -9.185, np.inf)
    return np.minimum(a_iso, cap)[()]


def induced_axial_load(radial_load, axial_factor, *, factor=INDUCED_AXIAL_FACTORS["SKF"]):
    """Induced axial load of a single-row tapered roller bearing under a radial load.

    Parameters
    ----------
    radial_load : array_like
        F_r >= 0. [N]
    axial_factor : array_like
        The bearing's Y. [-]
    factor : float
        f: 0.5 (SKF, General Catalogue 6000 p. 208: half the rollers loaded; the default) or 0.6 (NSK,
        CAT. No. E1102e eq. (5.27)); :data:`INDUCED_AXIAL_FACTORS`. [-]

    Returns
    -------
    ndarray or float
        F_a = f F_r / Y. [N]

    Examples
    --------
    >>> print(f"{induced_axial_load(3931.0, 1.6, factor=0.6):.0f} N")  # NSK example 5, bearing 2
    1474 N
    """
    fr = check_nonnegative("radial_load", radial_load, "N")
    y = check_positive("axial_factor", axial_factor, "-")
    f = float(check_positive("factor", factor, "-"))
    return (f * fr / y)[()]


class PairedAxialLoads(NamedTuple):
    """Axial loads of two tapered bearings adjusted against each other."""

    axial_load_a: np.ndarray
    """F_a of bearing A. [N]"""
    axial_load_b: np.ndarray
    """F_a of bearing B (the one the external axial load pushes into). [N]"""


def paired_axial_loads(radial_load_a, radial_load_b, axial_factor_a, axial_factor_b, external_axial_load=0.0, *,
                       factor=INDUCED_AXIAL_FACTORS["SKF"]):
    r"""Axial loads of two single-row tapered bearings (A, B) adjusted to zero clearance, without preload.

    Parameters
    ----------
    radial_load_a, radial_load_b : array_like
        F_rA, F_rB >= 0 at the pressure centres. [N]
    axial_factor_a, axial_factor_b : array_like
        Y_A, Y_B. [-]
    external_axial_load : array_like
        K_a >= 0, the external axial force on the shaft, pushing it into bearing B (name the bearings so). [N]
    factor : float
        f of :func:`induced_axial_load`. [-]

    Returns
    -------
    PairedAxialLoads

    Notes
    -----
    With the induced loads :math:`S = f F_r / Y` of both bearings (SKF General Catalogue 6000, p. 613,
    table 3, every load case of it): :math:`F_{aB} = \max(S_B, S_A + K_a)` and
    :math:`F_{aA} = F_{aB} - K_a`. The bearing not pushed by K_a sees its own induced load, or more; NSK's
    example 5 writes F_a = 0 for that bearing, which gives the same P wherever f/Y <= e (P = F_r then).

    Examples
    --------
    NSK CAT. No. E1102e, example 5 (HR30305DJ A, HR30206J B back to back, K_a = 2000 N into the first):

    >>> a = paired_axial_loads(3931.0, 1569.0, 1.60, 0.73, 2000.0, factor=0.6)
    >>> print(f"{a.axial_load_b:.0f} N on HR30305DJ")
    3474 N on HR30305DJ
    """
    s_a = induced_axial_load(radial_load_a, axial_factor_a, factor=factor)
    s_b = induced_axial_load(radial_load_b, axial_factor_b, factor=factor)
    ka = check_nonnegative("external_axial_load", external_axial_load, "N")
    fb = np.maximum(s_b, s_a + ka)
    return PairedAxialLoads((fb - ka)[()], fb[()])

r"""Lubricant viscosity, viscosity ratio, contamination and the life modification factor a_ISO (ISO 281).

Viscosity
---------
iso_vg_viscosity           kinematic viscosity at 40 degC of an ISO VG grade (ISO 3448 mid-point)
walther_constants          A, B of ASTM D341 (Walther) through two reference viscosities
walther_viscosity          nu(T) from A, B
kinematic_viscosity        nu at a temperature from a VG grade or nu40, and nu100 or a viscosity index
                           (ASTM D2270, ASTM D341)
viscosity_index            VI of an oil from nu40 and nu100 (ASTM D2270 procedures A and B)
viscosity_100_from_index   nu100 of an oil from nu40 and its VI (ASTM D2270 solved for nu100)
DEFAULT_VISCOSITY_INDEX    95, the VI of SKF's viscosity-temperature diagram of mineral oils

Lubrication condition
---------------------
rated_viscosity            nu1 of ISO 281:2007 eqs. (14)-(15) (reference kinematic viscosity)
viscosity_ratio            kappa = nu / nu1
contamination_factor       e_C of ISO 281:2007 table 13 from a cleanliness class
life_modification_factor   a_ISO of ISO 281:2007 eq. (B.4) for ball bearings, capped at 50

SI in the API (m^2/s, K, rad/s, m, N). The published fits use mm^2/s, rpm and mm; each function
converts once, in plain sight.

References
----------
.. [1] ISO 281:2007, *Rolling bearings -- Dynamic load ratings and rating life*, clause 9.3 (a_ISO,
   table 13 of e_C, eqs. (14)-(15) of nu1) and annex B.
.. [2] ASTM D341-09, *Standard practice for viscosity-temperature charts for liquid petroleum
   products*, eqs. (1)-(2): log log (nu + 0.7) = A - B log T.
.. [3] ISO 3448:1992, *Industrial liquid lubricants -- ISO viscosity classification* (VG mid-points).
.. [4] ASTM D2270-10 (reapproved 2016), *Standard practice for calculating viscosity index from kinematic
   viscosity at 40 and 100 degC*, doi:10.1520/D2270-10R16: table 1 (L, H for nu100 <= 70 mm^2/s; in
   ``data/viscosity_index.toml`` with its source), eqs. (3)-(4) (L, H above 70 mm^2/s), procedure A
   (VI <= 100) and procedure B (VI > 100).
.. [5] SKF, *Rolling bearings*, PUB BU/P1 17000 EN, 2018, "Selecting lubricating oils": the
   viscosity-temperature diagram of the ISO VG grades "is compiled for a viscosity index of 95", and
   oils with VI >= 95 are recommended for rolling bearings (also on skf.com, "Selecting lubricating oils").
"""

from __future__ import annotations

import tomllib
import warnings
from functools import cache
from importlib import resources

import numpy as np

from .. import _solve
from .._validate import check_nonnegative, check_positive
from ..errors import ConvergenceError, InputError
from .static import RatingWarning

__all__ = [
    "CONTAMINATION_CLASSES",
    "DEFAULT_VISCOSITY_INDEX",
    "ISO_VG_GRADES",
    "contamination_factor",
    "iso_vg_viscosity",
    "kinematic_viscosity",
    "life_modification_factor",
    "rated_viscosity",
    "viscosity_100_from_index",
    "viscosity_index",
    "viscosity_ratio",
    "walther_constants",
    "walther_viscosity",
]

_CST, _RPM, _MM = 1e-6, 2.0 * np.pi / 60.0, 1e-3  # m^2/s per mm^2/s, rad/s per rpm, m per mm
_T40, _T100 = 313.15, 373.15  # K
_WALTHER_MIN_CST = 2.0  # ASTM D341: the plain Z = nu + 0.7 holds down to 2 mm^2/s

#: The viscosity index assumed for an oil given by its grade alone: 95, the VI for which SKF's
#: viscosity-temperature diagram of the ISO VG grades of mineral oils is compiled ([5]; SKF recommends
#: VI >= 95 for rolling bearings). A paraffinic mineral oil; give the oil's own VI or nu100 where known.
DEFAULT_VISCOSITY_INDEX = 95.0

# ISO 3448 viscosity grades (mid-point kinematic viscosity at 40 degC in mm^2/s = the grade number)
ISO_VG_GRADES = (2, 3, 5, 7, 10, 15, 22, 32, 46, 68, 100, 150, 220, 320, 460, 680, 1000, 1500, 2200, 3200)

# ISO 281:2007 table 13: cleanliness class -> e_C range (low, high) for Dpw < 100 mm and Dpw >= 100 mm.
# Checked (issue 12): identical in two independent public implementations (one of them SKF's eta_c table,
# which has the same classes and ranges).
CONTAMINATION_CLASSES = {
    "extreme_cleanliness": ((1.0, 1.0), (1.0, 1.0)),
    "high_cleanliness": ((0.6, 0.8), (0.8, 0.9)),
    "normal_cleanliness": ((0.5, 0.6), (0.6, 0.8)),
    "slight_contamination": ((0.3, 0.5), (0.4, 0.6)),
    "typical_contamination": ((0.1, 0.3), (0.2, 0.4)),
    "severe_contamination": ((0.0, 0.1), (0.0, 0.1)),
    "very_severe_contamination": ((0.0, 0.0), (0.0, 0.0)),
}
_CLASS_PITCH = 0.1  # m: the two columns of table 13

# ISO 281:2007 eq. (B.4) (ball bearings): (kappa range, c, p) of a_ISO (checked, issue 12: the pieces meet at
# kappa = 0.4 and 1 to 1e-4, tests/ratings/test_lubrication.py) = 0.1 [1 - (2.5671 - c/kappa^p)^0.83
# (e_C Cu / P)^(1/3)]^-9.3
_AISO_BALL = ((0.1, 0.4, 2.2649, 0.054381), (0.4, 1.0, 1.9987, 0.19087), (1.0, 4.0, 1.9987, 0.071739))
AISO_CAP = 50.0


def iso_vg_viscosity(grade):
    """Kinematic viscosity at 40 degC of an ISO viscosity grade (the mid-point of ISO 3448).

    Parameters
    ----------
    grade : int
        ISO VG number, one of :data:`ISO_VG_GRADES`.

    Returns
    -------
    float
        nu40. [m^2/s]

    Examples
    --------
    >>> iso_vg_viscosity(68)
    6.8e-05
    """
    if grade not in ISO_VG_GRADES:
        raise InputError(f"iso_vg must be one of {list(ISO_VG_GRADES)}, got {grade!r}")
    return float(grade) * _CST


def walther_constants(temperatures, viscosities):
    r"""Constants A and B of the ASTM D341 (Walther) relation through two reference points.

    Parameters
    ----------
    temperatures : tuple of 2 float
        T1, T2 (distinct). [K]
    viscosities : tuple of 2 float
        nu(T1), nu(T2), each >= 2 mm^2/s. [m^2/s]

    Returns
    -------
    tuple of float
        (A, B) of :math:`\log_{10}\log_{10}(\nu + 0.7) = A - B\log_{10} T`, nu in mm^2/s and T in K.

    Examples
    --------
    >>> a, b = walther_constants((313.15, 373.15), (68e-6, 8.7e-6))
    >>> print(f"{a:.4f} {b:.4f}")
    9.3097 3.6244
    """
    t1, t2 = (float(check_positive("temperatures", t, "K")) for t in temperatures)
    v1, v2 = (float(check_positive("viscosities", v, "m^2/s")) / _CST for v in viscosities)
    if t1 == t2:
        raise InputError(f"temperatures must be distinct [K], got {t1!r} twice")
    if min(v1, v2) < _WALTHER_MIN_CST:
        raise InputError(f"viscosities must be >= {_WALTHER_MIN_CST:g} [mm^2/s] for ASTM D341, got "
                         f"{min(v1, v2)!r}")
    z1, z2 = np.log10(np.log10(v1 + 0.7)), np.log10(np.log10(v2 + 0.7))
    b = (z1 - z2) / (np.log10(t2) - np.log10(t1))
    return float(z1 + b * np.log10(t1)), float(b)


def walther_viscosity(temperature, a, b):
    r"""Kinematic viscosity from the ASTM D341 relation.

    Parameters
    ----------
    temperature : array_like
        Temperature. [K]
    a, b : float
        Constants of :func:`walther_constants`. [-]

    Returns
    -------
    ndarray or float
        :math:`\nu = 10^{10^{A - B \log_{10} T}} - 0.7` (mm^2/s, here in SI). [m^2/s]

    Examples
    --------
    >>> print(f"{walther_viscosity(313.15, *walther_constants((313.15, 373.15), (68e-6, 8.7e-6))):.4g}")
    6.8e-05
    """
    t = check_positive("temperature", temperature, "K")
    return ((10.0 ** (10.0 ** (a - b * np.log10(t))) - 0.7) * _CST)[()]


@cache
def _d2270_table():
    """nu100, L and H of ASTM D2270 table 1 [mm^2/s] (``data/viscosity_index.toml``)."""
    with (resources.files("bearinglab") / "data" / "viscosity_index.toml").open("rb") as f:
        t = tomllib.load(f)["astm_d2270_table1"]
    return tuple(np.array(t[k], dtype=float) for k in ("nu100_mm2_s", "L_mm2_s", "H_mm2_s"))


def _d2270_l_h(nu100):
    """L and H of ASTM D2270 at nu100 [mm^2/s]: table 1 interpolated linearly up to 70 mm^2/s (as the
    standard says), eqs. (3)-(4) above."""
    y, l_tab, h_tab = _d2270_table()
    big = nu100 > y[-1]
    l_eq = 0.8353 * nu100**2 + 14.67 * nu100 - 216.0  # eq. (3)
    h_eq = 0.1684 * nu100**2 + 11.85 * nu100 - 97.0  # eq. (4)
    return (np.where(big, l_eq, np.interp(nu100, y, l_tab)), np.where(big, h_eq, np.interp(nu100, y, h_tab)))


def _d2270_index(u, y):
    """VI of ASTM D2270 from nu40 = u and nu100 = y [mm^2/s] (y >= 2), unrounded: procedure A where
    u >= H (VI <= 100), procedure B below."""
    lo, hi = _d2270_l_h(y)
    a = (lo - u) / (lo - hi) * 100.0  # procedure A, eq. (1)
    with np.errstate(divide="ignore", invalid="ignore"):
        n = (np.log10(hi) - np.log10(u)) / np.log10(y)  # procedure B, eq. (5)
        b = (10.0**n - 1.0) / 0.00715 + 100.0  # eq. (6)
    return np.where(u >= hi, a, b)


def viscosity_index(viscosity_40, viscosity_100):
    r"""Viscosity index of an oil from its kinematic viscosities at 40 and 100 degC (ASTM D2270).

    Parameters
    ----------
    viscosity_40 : array_like
        nu40, > 0. [m^2/s]
    viscosity_100 : array_like
        nu100, >= 2 mm^2/s (the lower end of the standard's table) and < nu40. [m^2/s]

    Returns
    -------
    ndarray or float
        VI, unrounded (the standard rounds the reported value to a whole number). [-]

    Notes
    -----
    With L and H the nu40 of the reference oils of VI 0 and 100 having the oil's nu100 (table 1 of [4]_,
    linear interpolation; eqs. (3)-(4) above 70 mm^2/s), U = nu40 and Y = nu100 in mm^2/s:
    :math:`VI = 100 (L - U)/(L - H)` where U >= H (procedure A, VI <= 100), else
    :math:`VI = (10^N - 1)/0.00715 + 100` with :math:`N = (\log H - \log U)/\log Y` (procedure B).

    References
    ----------
    .. [4] ASTM D2270-10(2016), doi:10.1520/D2270-10R16.

    Examples
    --------
    The standard's example of procedure A (nu40 = 73.30, nu100 = 8.86 mm^2/s, VI 92):

    >>> print(round(float(viscosity_index(73.30e-6, 8.86e-6))))
    92
    """
    u = check_positive("viscosity_40", viscosity_40, "m^2/s") / _CST
    y = check_positive("viscosity_100", viscosity_100, "m^2/s") / _CST
    if (y < _WALTHER_MIN_CST).any():
        raise InputError(f"viscosity_100 must be >= {_WALTHER_MIN_CST:g} [mm^2/s] (ASTM D2270), got "
                         f"{float(y[y < _WALTHER_MIN_CST].flat[0])!r} mm^2/s")
    if np.broadcast_to(y >= u, np.broadcast(u, y).shape).any():
        raise InputError("viscosity_100 must be below viscosity_40 (an oil thins when heated)")
    return _d2270_index(u, y)[()]


def viscosity_100_from_index(viscosity_40, viscosity_index, *, rtol=_solve.VISCOSITY_INDEX_RTOL,
                             max_iter=_solve.VISCOSITY_INDEX_MAX_ITER):
    """Kinematic viscosity at 100 degC of an oil of known nu40 and viscosity index (ASTM D2270 solved).

    Parameters
    ----------
    viscosity_40 : array_like
        nu40 (for an ISO VG grade, the mid-point: :func:`iso_vg_viscosity`). [m^2/s]
    viscosity_index : array_like
        VI. [-]
    rtol : float
        Relative width of the bracket on nu100 at which the bisection stops. [-]
    max_iter : int
        Bisection steps before :class:`~bearinglab.errors.ConvergenceError`.

    Returns
    -------
    ndarray or float
        nu100 with :func:`viscosity_index` (nu40, nu100) = VI. [m^2/s]

    Notes
    -----
    At fixed nu40 the VI of [4]_ rises monotonically with nu100 (a flatter oil), so the root is bracketed
    in [2 mm^2/s, nu40) and found by bisection on log nu100 (the table's linear pieces make the function
    only piecewise smooth). An oil whose VI is below what nu100 = 2 mm^2/s gives is refused.

    References
    ----------
    .. [4] ASTM D2270-10(2016), doi:10.1520/D2270-10R16.

    Examples
    --------
    An ISO VG 68 mineral oil of VI 95:

    >>> print(f"{viscosity_100_from_index(68e-6, 95.0) * 1e6:.3f} mm^2/s")
    8.530 mm^2/s
    """
    u = check_positive("viscosity_40", viscosity_40, "m^2/s") / _CST
    vi = np.asarray(viscosity_index, dtype=float)
    if not np.isfinite(vi).all():
        raise InputError(f"viscosity_index must be finite [-], got {float(vi[~np.isfinite(vi)].flat[0])!r}")
    u, vi = np.broadcast_arrays(u, vi)
    if (u <= _WALTHER_MIN_CST).any():
        raise InputError(f"viscosity_40 must be > {_WALTHER_MIN_CST:g} [mm^2/s] for a viscosity index, got "
                         f"{float(u[u <= _WALTHER_MIN_CST].flat[0])!r} mm^2/s")
    lo = np.full(u.shape, np.log(_WALTHER_MIN_CST))
    hi = np.log(u) - 1e-12
    low_vi = _d2270_index(u, np.exp(lo))
    if (low_vi > vi).any():
        k = np.flatnonzero((low_vi > vi).ravel())[0]
        raise InputError(f"viscosity_index {float(vi.flat[k]):g} is too low for nu40 = {float(u.flat[k]):g} "
                         f"mm^2/s: even nu100 = 2 mm^2/s gives VI {float(low_vi.flat[k]):.4g}")
    for it in range(1, max_iter + 1):
        mid = 0.5 * (lo + hi)
        above = _d2270_index(u, np.exp(mid)) > vi
        hi, lo = np.where(above, mid, hi), np.where(above, lo, mid)
        if np.all(hi - lo < rtol):
            return (np.exp(0.5 * (lo + hi)) * _CST)[()]
    raise ConvergenceError("lubrication.viscosity_100_from_index", iterations=it, residual=hi - lo,
                           estimate=np.exp(0.5 * (lo + hi)) * _CST)


def kinematic_viscosity(temperature, *, iso_vg=None, viscosity_40=None, viscosity_100=None,
                        viscosity_index=None):
    """Kinematic viscosity of an oil at the operating temperature (ASTM D341 through 40 and 100 degC).

    Parameters
    ----------
    temperature : array_like
        Operating temperature. [K]
    iso_vg : int, optional
        ISO VG grade, giving nu40 (or give ``viscosity_40``).
    viscosity_40 : float, optional
        nu at 40 degC. [m^2/s]
    viscosity_100 : float, optional
        nu at 100 degC (the second reference point), from the oil's data sheet. [m^2/s]
    viscosity_index : float, optional
        The oil's viscosity index, giving nu100 by ASTM D2270 (:func:`viscosity_100_from_index`); not
        with ``viscosity_100``. Without either, :data:`DEFAULT_VISCOSITY_INDEX` (95, a mineral oil). [-]

    Returns
    -------
    ndarray or float
        nu(T). [m^2/s]

    Notes
    -----
    nu100 is the data sheet's, or the one of the given (default 95) VI by ASTM D2270 [4]_; ASTM D341
    (Walther) [2]_ then runs through (40 degC, nu40) and (100 degC, nu100).

    References
    ----------
    .. [2] ASTM D341-09, eqs. (1)-(2).
    .. [4] ASTM D2270-10(2016), doi:10.1520/D2270-10R16.

    Examples
    --------
    >>> print(f"{kinematic_viscosity(343.15, iso_vg=68, viscosity_100=8.7e-6) * 1e6:.2f} mm^2/s")
    20.12 mm^2/s
    >>> print(f"{kinematic_viscosity(343.15, iso_vg=68) * 1e6:.2f} mm^2/s")
    19.86 mm^2/s
    """
    if (iso_vg is None) == (viscosity_40 is None):
        raise InputError("give exactly one of iso_vg and viscosity_40")
    if viscosity_100 is not None and viscosity_index is not None:
        raise InputError("give viscosity_100 or viscosity_index, not both (the index fixes nu100)")
    nu40 = iso_vg_viscosity(iso_vg) if iso_vg is not None else viscosity_40
    if viscosity_100 is None:
        vi = DEFAULT_VISCOSITY_INDEX if viscosity_index is None else viscosity_index
        viscosity_100 = float(viscosity_100_from_index(nu40, vi))
    a, b = walther_constants((_T40, _T100), (nu40, viscosity_100))
    return walther_viscosity(temperature, a, b)


def rated_viscosity(shaft_speed, mean_diameter):
    r"""Reference (rated) kinematic viscosity nu1 of ISO 281:2007 eqs. (14) and (15).

    Parameters
    ----------
    shaft_speed : array_like
        Rotational speed n, > 0. [rad/s]
    mean_diameter : array_like
        The bearing's mean diameter d_m = (d + D)/2 of ISO 281 (its fig. 7 writes D_pw = 0.5 (d + D); SKF's
        d_m is the same), or the pitch diameter where bore and outside diameter are not known. [m]

    Returns
    -------
    ndarray or float
        :math:`\nu_1 = 45000\, n^{-0.83} d_m^{-0.5}` for n < 1000 rpm, else
        :math:`4500\, n^{-0.5} d_m^{-0.5}` (mm^2/s, rpm, mm; here in SI). [m^2/s]

    Examples
    --------
    >>> print(f"{rated_viscosity(3000 * 2 * np.pi / 60, 0.0635) * 1e6:.3f} mm^2/s")
    10.310 mm^2/s
    """
    n = check_positive("shaft_speed", shaft_speed, "rad/s") / _RPM
    dm = check_positive("mean_diameter", mean_diameter, "m") / _MM
    # eqs. (14)-(15); the same two branches in an independent public ISO 281 implementation (issue 12)
    nu1 = np.where(n < 1000.0, 45000.0 * n**-0.83 * dm**-0.5, 4500.0 * n**-0.5 * dm**-0.5)
    return (nu1 * _CST)[()]


def viscosity_ratio(kinematic_viscosity, shaft_speed, mean_diameter):
    """Viscosity ratio kappa = nu / nu1 of ISO 281:2007 eq. (13).

    Parameters
    ----------
    kinematic_viscosity : array_like
        nu at the operating temperature. [m^2/s]
    shaft_speed : array_like
        n. [rad/s]
    mean_diameter : array_like
        d_m = (d + D)/2 (or the pitch diameter), as in :func:`rated_viscosity`. [m]

    Returns
    -------
    ndarray or float
        kappa (not clamped). [-]

    Examples
    --------
    >>> print(f"{viscosity_ratio(20.62e-6, 3000 * 2 * np.pi / 60, 0.0635):.3f}")
    2.000
    """
    nu = check_positive("kinematic_viscosity", kinematic_viscosity, "m^2/s")
    return (nu / rated_viscosity(shaft_speed, mean_diameter))[()]


def contamination_factor(cleanliness, pitch_diameter, *, bound="mid"):
    """Contamination factor e_C of a cleanliness class of ISO 281:2007 table 13.

    Parameters
    ----------
    cleanliness : str
        One of :data:`CONTAMINATION_CLASSES` (spaces or hyphens read as underscores).
    pitch_diameter : array_like
        Dpw; table 13 has a column below and one from 100 mm. [m]
    bound : {"mid", "low", "high"}
        Which value of the class's range.

    Returns
    -------
    ndarray or float
        e_C. [-]

    Examples
    --------
    >>> print(contamination_factor("normal cleanliness", 0.0635))
    0.55
    """
    key = str(cleanliness).strip().lower().replace(" ", "_").replace("-", "_")
    if key not in CONTAMINATION_CLASSES:
        raise InputError(f"cleanliness must be one of {list(CONTAMINATION_CLASSES)}, got {cleanliness!r}")
    pick = {"low": lambda lo, hi: lo, "high": lambda lo, hi: hi, "mid": lambda lo, hi: 0.5 * (lo + hi)}
    if bound not in pick:
        raise InputError(f"bound must be one of {list(pick)}, got {bound!r}")
    dpw = check_positive("pitch_diameter", pitch_diameter, "m")
    small, large = (pick[bound](*r) for r in CONTAMINATION_CLASSES[key])
    return np.where(dpw < _CLASS_PITCH, small, large)[()]


def a_iso_inputs(viscosity_ratio, contamination_factor, fatigue_load_limit, equivalent_dynamic_load, *,
                 ep_additives=False, say_ep=False):
    """The checked inputs of ISO 281:2007's a_ISO (ball and roller bearings alike): kappa clamped to [0.1, 4]
    (a warning below 0.1, where clause 9.3 does not apply), e_C, C_u, P and the cap of a_ISO (50; 3 where the
    EP-additive rule of clause 9.3.3 sets kappa = 1, for kappa < 1 and e_C >= 0.2; ``say_ep`` warns where it
    does). The warnings point at the caller of the public function that calls this one.

    Returns
    -------
    kappa, e_C, C_u, P, cap : ndarray
        [-, -, N, N, -]
    """
    kappa = check_positive("viscosity_ratio", viscosity_ratio, "-")
    ec = check_nonnegative("contamination_factor", contamination_factor, "-")
    if (ec > 1).any():
        raise InputError(f"contamination_factor must be in [0, 1] [-], got {float(ec[ec > 1].flat[0])!r}")
    cu = check_nonnegative("fatigue_load_limit", fatigue_load_limit, "N")
    p = check_positive("equivalent_dynamic_load", equivalent_dynamic_load, "N")
    low = kappa < 0.1
    if low.any():
        warnings.warn(f"viscosity ratio kappa = {float(kappa[low].min()):.3g} is below 0.1, outside ISO "
                      "281:2007 clause 9.3; a_ISO is evaluated at kappa = 0.1", RatingWarning, stacklevel=3)
    cap = np.full(np.broadcast(kappa, ec).shape, AISO_CAP)
    if ep_additives:
        ep = (kappa < 1.0) & (ec >= 0.2)
        if say_ep and ep.any():
            warnings.warn("EP-additive rule of ISO 281:2007 clause 9.3.3 applied: kappa = 1 used where "
                          "kappa < 1 and e_C >= 0.2, with a_ISO limited to 3", RatingWarning, stacklevel=3)
        kappa = np.where(ep, 1.0, kappa)
        cap = np.where(ep, 3.0, cap)
    return np.clip(kappa, 0.1, 4.0), ec, cu, p, cap


def life_modification_factor(viscosity_ratio, contamination_factor, fatigue_load_limit,
                             equivalent_dynamic_load, *, ep_additives=False):
    r"""Life modification factor a_ISO of ball bearings, ISO 281:2007 eq. (B.4) and clause 9.3.

    Parameters
    ----------
    viscosity_ratio : array_like
        kappa = nu / nu1, > 0. [-]
    contamination_factor : array_like
        e_C in [0, 1]. [-]
    fatigue_load_limit : array_like
        Cu. [N]
    equivalent_dynamic_load : array_like
        P, > 0. [N]
    ep_additives : bool
        The lubricant has EP additives proven effective for the bearing: ISO 281 then allows
        kappa = 1 where kappa < 1 and e_C >= 0.2, with a_ISO limited to 3.

    Returns
    -------
    ndarray or float
        a_ISO in (0, 50]. [-]

    Notes
    -----
    .. math:: a_{ISO} = 0.1\left[1 - \left(2.5671 - \frac{c}{\kappa^{p}}\right)^{0.83}
              \left(\frac{e_C C_u}{P}\right)^{1/3}\right]^{-9.3}

    with (c, p) = (2.2649, 0.054381) for 0.1 <= kappa < 0.4, (1.9987, 0.19087) for 0.4 <= kappa < 1
    and (1.9987, 0.071739) for 1 <= kappa <= 4. kappa is clamped to [0.1, 4] (a warning below 0.1,
    where the standard does not apply); a_ISO is capped at 50, also where the bracket is <= 0.

    Examples
    --------
    >>> print(f"{life_modification_factor(1.0, 0.5, 300.0, 3000.0):.4f}")
    1.1437
    """
    k, ec, cu, p, cap = a_iso_inputs(viscosity_ratio, contamination_factor, fatigue_load_limit,
                                     equivalent_dynamic_load, ep_additives=ep_additives, say_ep=True)
    c = np.where(k < 0.4, _AISO_BALL[0][2], _AISO_BALL[1][2])
    pw = np.select([k < 0.4, k < 1.0], [_AISO_BALL[0][3], _AISO_BALL[1][3]], _AISO_BALL[2][3])
    inner = 1.0 - (2.5671 - c / k**pw) ** 0.83 * np.cbrt(ec * cu / p)
    with np.errstate(divide="ignore", over="ignore"):
        a_iso = np.where(inner > 0, 0.1 * np.where(inner > 0, inner, 1.0) ** -9.3, np.inf)
    return np.minimum(a_iso, cap)[()]

r"""The SKF four-term friction model of cylindrical, tapered and spherical roller bearings.

Model
-----
skf_roller                   M = Phi_ish Phi_rs M_rr + M_sl + M_seal + M_drag from loads, speed and viscosity
skf_roller_for_bearing       the same for a RollerBearing (type, series, Y, widths read from it)

Parts and tables
----------------
RollerConstants              R1-R4, S1-S4 of a series (the forms of SKF's table 2a use what they need)
roller_series_constants      the constants of a series of a type
roller_drag_moment           M_drag = 10 V_M K_roll B d_m^4 n^2 of an oil bath (V_M from the oil level:
                             :func:`bearinglab.friction.drag.drag_loss_factor`, roller-bearing curve)
CYLINDRICAL_CONSTANTS, TAPERED_CONSTANTS, SPHERICAL_CONSTANTS, ROLLER_TYPE_CONSTANTS,
ROLLER_EHL_COEFFICIENTS, ROLLER_SEAL_CONSTANTS   the tables

The published model is in N, mm, rpm and mm^2/s with moments in N mm; the API is SI and
:func:`skf_roller` converts once. The inlet shear heating factor and the sliding friction coefficient are
those of the ball-bearing model (:mod:`bearinglab.friction.skf`), shared.

References
----------
.. [1] SKF, *General Catalogue* 6000/I RU (Russian edition, 2006), section "Friction": table 2a, p. 91 (G_rr
   and G_sl of cylindrical, tapered and spherical roller bearings), table 3c, p. 93 (cylindrical: R1, S1,
   S2 by series), table 3d, p. 94 (tapered: R1, R2, S1, S2 by series), table 3e, p. 94 (spherical: R1-R4,
   S1-S4 by series), table 4, p. 96 (seal constants), table 5, p. 98 (K_Z, K_L), p. 99 (the drag moment of
   roller bearings, M_drag = 10 V_M K_roll B d_m^4 n^2), p. 101 (mu_EHL 0.02 cylindrical, 0.002 tapered),
   and the worked example of a 22208 E in an oil bath, pp. 104-105. Read from the text copy in the public
   repository github.com/ArtemFilin1990/Mar (folder 07).
"""

from __future__ import annotations

import math
import warnings
from typing import NamedTuple

import numpy as np

from .._validate import check_nonnegative, check_positive
from ..errors import InputError, ValidityWarning
from . import skf
from .drag import drag_loss_factor as _drag_loss_factor

__all__ = [
    "CYLINDRICAL_CONSTANTS",
    "ROLLER_EHL_COEFFICIENTS",
    "ROLLER_SEAL_CONSTANTS",
    "ROLLER_TYPE_CONSTANTS",
    "SPHERICAL_CONSTANTS",
    "TAPERED_CONSTANTS",
    "RollerConstants",
    "roller_drag_moment",
    "roller_series_constants",
    "skf_roller",
    "skf_roller_for_bearing",
]

_MM, _CST, _RPM = 1e-3, 1e-6, 2.0 * math.pi / 60.0


class RollerConstants(NamedTuple):
    """Geometry constants of SKF's rolling (R) and sliding (S) frictional moments of a roller bearing series."""

    r1: float
    r2: float = 0.0
    r3: float = 0.0
    r4: float = 0.0
    s1: float = 0.0
    s2: float = 0.0
    s3: float = 0.0
    s4: float = 0.0


def _cyl(r1, s1, s2):
    return RollerConstants(r1, s1=s1, s2=s2)


def _tap(r1, r2, s1, s2):
    return RollerConstants(r1, r2, s1=s1, s2=s2)


# GC 6000/I RU (2006), table 3c, p. 93: cylindrical roller bearings with cage (N, NU, NJ, NUP) by series, and the
# full-complement bearings (NCF, NJG, NNCL, NNCF, NNC, NNF), all series: (R1, S1, S2) in N, mm.
CYLINDRICAL_CONSTANTS = {
    "2": _cyl(1.09e-6, 0.16, 0.0015), "3": _cyl(1.09e-6, 0.16, 0.0015), "4": _cyl(1.00e-6, 0.16, 0.0015),
    "10": _cyl(1.12e-6, 0.17, 0.0015), "12": _cyl(1.23e-6, 0.16, 0.0015), "20": _cyl(1.23e-6, 0.16, 0.0015),
    "22": _cyl(1.40e-6, 0.16, 0.0015), "23": _cyl(1.48e-6, 0.16, 0.0015),
    "full complement": _cyl(2.13e-6, 0.16, 0.0015),
}
# GC 6000/I RU (2006), table 3d, p. 94: tapered roller bearings by series: (R1, R2, S1, S2); "other" is the
# table's row for all other series.
TAPERED_CONSTANTS = {
    "302": _tap(1.76e-6, 10.9, 0.017, 2), "303": _tap(1.69e-6, 10.9, 0.017, 2), "313": _tap(1.84e-6, 10.9, 0.048, 2),
    "320": _tap(2.38e-6, 10.9, 0.014, 2), "322": _tap(2.27e-6, 10.9, 0.018, 2), "322 B": _tap(2.38e-6, 10.9, 0.026, 2),
    "323": _tap(2.38e-6, 10.9, 0.019, 2), "323 B": _tap(2.79e-6, 10.9, 0.030, 2), "329": _tap(2.31e-6, 10.9, 0.009, 2),
    "330": _tap(2.71e-6, 11.3, 0.010, 2), "331": _tap(2.71e-6, 10.9, 0.015, 2), "332": _tap(2.71e-6, 10.9, 0.018, 2),
    "LL": _tap(1.72e-6, 10.9, 0.0057, 2), "L": _tap(2.19e-6, 10.9, 0.0093, 2), "LM": _tap(2.25e-6, 10.9, 0.011, 2),
    "M": _tap(2.48e-6, 10.9, 0.015, 2), "HM": _tap(2.60e-6, 10.9, 0.020, 2), "H": _tap(2.66e-6, 10.9, 0.025, 2),
    "HH": _tap(2.51e-6, 10.9, 0.027, 2), "other": _tap(2.31e-6, 10.9, 0.019, 2),
}
# GC 6000/I RU (2006), table 3e, p. 94: spherical roller bearings by series: (R1, R2, R3, R4, S1, S2, S3, S4).
SPHERICAL_CONSTANTS = {
    "213 E": RollerConstants(1.6e-6, 5.84, 2.81e-6, 5.8, 3.62e-3, 508, 8.8e-3, 117),
    "222 E": RollerConstants(1.6e-6, 5.84, 2.81e-6, 5.8, 3.62e-3, 508, 8.8e-3, 117),
    "222": RollerConstants(2.0e-6, 5.54, 2.92e-6, 5.5, 5.10e-3, 414, 9.7e-3, 100),
    "223": RollerConstants(1.7e-6, 4.1, 3.13e-6, 4.05, 6.92e-3, 124, 1.7e-2, 41),
    "223 E": RollerConstants(1.6e-6, 4.1, 3.14e-6, 4.05, 6.23e-3, 124, 1.7e-2, 41),
    "230": RollerConstants(2.4e-6, 6.44, 3.76e-6, 6.4, 4.13e-3, 755, 1.1e-2, 160),
    "231": RollerConstants(2.4e-6, 4.7, 4.04e-6, 4.72, 6.70e-3, 231, 1.7e-2, 65),
    "232": RollerConstants(2.3e-6, 4.1, 4.00e-6, 4.05, 8.66e-3, 126, 2.1e-2, 41),
    "238": RollerConstants(3.1e-6, 12.1, 3.82e-6, 12, 1.74e-3, 9495, 5.9e-3, 1057),
    "239": RollerConstants(2.7e-6, 8.53, 3.87e-6, 8.47, 2.77e-3, 2330, 8.5e-3, 371),
    "240": RollerConstants(2.9e-6, 4.87, 4.78e-6, 4.84, 6.95e-3, 240, 2.1e-2, 68),
    "241": RollerConstants(2.6e-6, 3.8, 4.79e-6, 3.7, 1.00e-2, 86.7, 2.9e-2, 31),
    "248": RollerConstants(3.8e-6, 9.4, 5.09e-6, 9.3, 2.80e-3, 3415, 1.2e-2, 486),
    "249": RollerConstants(3.0e-6, 6.67, 5.09e-6, 6.62, 3.90e-3, 887, 1.7e-2, 180),
}
_TABLES = {"cylindrical": CYLINDRICAL_CONSTANTS, "tapered": TAPERED_CONSTANTS, "spherical": SPHERICAL_CONSTANTS}
#: GC 6000/I RU (2006), table 5, p. 98: (K_Z, K_L) by type: cylindrical with cage 5.1, 0.65; full complement
#: 6.2, 0.7; tapered 6, 0.7; spherical 5.5, 0.8.
ROLLER_TYPE_CONSTANTS = {"cylindrical": (5.1, 0.65), "full complement": (6.2, 0.7), "tapered": (6.0, 0.7),
                         "spherical": (5.5, 0.8)}
#: GC 6000/I RU (2006), p. 101: mu_EHL of full-film lubrication; cylindrical and tapered roller bearings have their
#: own values in place of the lubricant's (0.05 for mineral oils, 0.04 synthetic, 0.1 transmission fluids).
ROLLER_EHL_COEFFICIENTS = {"cylindrical": 0.02, "tapered": 0.002, "spherical": 0.05}
#: GC 6000/I RU (2006), table 4, p. 96: seals of roller bearings: type -> (D range [mm], SealConstants, counterface):
#: LS seals of cylindrical roller bearings (42 < D <= 360 mm, d_s = E), CS, CS2, CS5 of spherical ones
#: (62 < D <= 300 mm, d_s = d2).
ROLLER_SEAL_CONSTANTS = {
    "LS": ((42.0, 360.0), skf.SealConstants(0.032, 2.0, 50.0), "E"),
    "CS": ((62.0, 300.0), skf.SealConstants(0.057, 2.0, 50.0), "d2"),
    "CS2": ((62.0, 300.0), skf.SealConstants(0.057, 2.0, 50.0), "d2"),
    "CS5": ((62.0, 300.0), skf.SealConstants(0.057, 2.0, 50.0), "d2"),
}


def roller_series_constants(bearing_type, series):
    """SKF's geometry constants of a roller bearing series.

    Parameters
    ----------
    bearing_type : {"cylindrical", "tapered", "spherical"}
        The type.
    series : str
        A key of its table (``"2"``, ``"22"``, ``"full complement"``; ``"302"``, ``"322 B"``, ``"other"``;
        ``"222 E"``, ``"223"`` ...).

    Returns
    -------
    RollerConstants

    Examples
    --------
    >>> roller_series_constants("spherical", "222 E").s1
    0.00362
    """
    if bearing_type not in _TABLES:
        raise InputError(f"bearing_type must be one of {list(_TABLES)}, got {bearing_type!r}")
    key = str(series).strip().upper().replace("FULL COMPLEMENT", "full complement").replace("OTHER", "other")
    table = _TABLES[bearing_type]
    if key not in table:
        raise InputError(f"series must be one of {list(table)} for a {bearing_type} roller bearing (SKF General "
                         f"Catalogue 6000, tables 3c-3e; or give constants=RollerConstants(...)), got {series!r}")
    return table[key]


def _load_variables(fr, fa, dm, c, bearing_type, axial_factor):
    """G_rr and G_sl of SKF's table 2a (N, mm)."""
    if bearing_type == "cylindrical":
        return c.r1 * dm**2.41 * fr**0.31, c.s1 * dm**0.9 * fa + c.s2 * dm * fr
    if bearing_type == "tapered":
        return (c.r1 * dm**2.38 * (fr + c.r2 * axial_factor * fa) ** 0.31,
                c.s1 * dm**0.82 * (fr + c.s2 * axial_factor * fa))
    g_rr_e = c.r1 * dm**1.85 * (fr + c.r2 * fa) ** 0.54
    g_rr_l = c.r3 * dm**2.3 * (fr + c.r4 * fa) ** 0.31
    g_sl_e = c.s1 * dm**0.25 * (fr**4 + c.s2 * fa**4) ** (1.0 / 3.0)
    g_sl_l = c.s3 * dm**0.94 * (fr**3 + c.s4 * fa**3) ** (1.0 / 3.0)
    # the table's rule: each pair's smaller value (G_rr.e < G_rr.l -> G_rr.e; G_sl.e < G_sl.l -> G_sl.e)
    return np.minimum(g_rr_e, g_rr_l), np.minimum(g_sl_e, g_sl_l)


def roller_drag_moment(shaft_speed, bore, outside_diameter, width, drag_loss_factor=None, *, bearing_type="cylindrical",
                       full_complement=False, oil_level=None):
    r"""Drag moment of a roller bearing in an oil bath (SKF General Catalogue 6000).

    Parameters
    ----------
    shaft_speed : array_like
        n (its sign does not matter). [rad/s]
    bore, outside_diameter : array_like
        d, D; d_m = (d + D)/2. [m]
    width : array_like
        B, the width of the inner ring. [m]
    drag_loss_factor : array_like, optional
        V_M in place of SKF's diagram 2 (the roller-bearing curve) at H/d_m. [-]
    bearing_type : {"cylindrical", "tapered", "spherical"}
        Sets K_Z and K_L (:data:`ROLLER_TYPE_CONSTANTS`).
    full_complement : bool
        A cylindrical roller bearing without cage.
    oil_level : array_like, optional
        H from the lowest point of the outer ring raceway, for V_M of SKF's diagram
        (:func:`bearinglab.friction.drag.drag_loss_factor`); needed unless ``drag_loss_factor`` is given. [m]

    Returns
    -------
    ndarray or float
        M_drag. [N m]

    Notes
    -----
    GC 6000/I RU (2006), p. 99, in N mm, mm, rpm: :math:`M_{drag} = 10 V_M K_{roll} B d_m^4 n^2` with
    :math:`K_{roll} = K_L K_Z (d + D)/(D - d) \times 10^{-12}`.

    Examples
    --------
    The catalogue's 22208 E (d 40, D 80, B 23 mm, 3500 rpm, V_M = 0.3e-4), printed 14.5 N mm:

    >>> print(f"{roller_drag_moment(3500 * 2 * np.pi / 60, 40e-3, 80e-3, 23e-3, 0.3e-4, bearing_type='spherical') * 1e3:.2f} N mm")
    14.46 N mm

    The same with V_M of the digitised diagram at its oil level H = 2.5 mm:

    >>> print(f"{roller_drag_moment(3500 * 2 * np.pi / 60, 40e-3, 80e-3, 23e-3, bearing_type='spherical', oil_level=2.5e-3) * 1e3:.2f} N mm")
    14.90 N mm
    """
    kz, kl = _type_constants(bearing_type, full_complement)
    n = np.abs(np.asarray(shaft_speed, dtype=float)) / _RPM
    d = check_positive("bore", bore, "m") / _MM
    big = check_positive("outside_diameter", outside_diameter, "m") / _MM
    b = check_positive("width", width, "m") / _MM
    dm = 0.5 * (d + big)
    if drag_loss_factor is None:
        if oil_level is None:
            raise InputError("oil_level: the drag moment needs the oil level H (V_M of SKF's diagram) or drag_loss_factor")
        drag_loss_factor = _drag_loss_factor(oil_level, dm * _MM, "roller")
    vm = check_nonnegative("drag_loss_factor", drag_loss_factor, "-")
    k_roll = kl * kz * (d + big) / (big - d) * 1e-12
    return (10.0 * vm * k_roll * b * dm**4 * n**2 * _MM)[()]


def _type_constants(bearing_type, full_complement):
    if bearing_type not in ROLLER_EHL_COEFFICIENTS:
        raise InputError(f"bearing_type must be one of {list(ROLLER_EHL_COEFFICIENTS)}, got {bearing_type!r}")
    key = "full complement" if bearing_type == "cylindrical" and full_complement else bearing_type
    return ROLLER_TYPE_CONSTANTS[key]


def skf_roller(radial_load, axial_load, shaft_speed, kinematic_viscosity, bore, outside_diameter, *,
               bearing_type="cylindrical", series=None, constants=None, axial_factor=None, full_complement=False,
               lubrication="grease", width=None, drag_loss_factor=None, ehl_coefficient=None,
               sliding_friction_coefficient=None, seal=None, seals=2, seal_diameter=None, oil_level=None):
    r"""Frictional moment of a cylindrical, tapered or spherical roller bearing by the SKF model.

    Parameters
    ----------
    radial_load, axial_load : array_like
        F_r and F_a >= 0 (of a tapered bearing the external axial load, SKF's footnote to table 2a). [N]
    shaft_speed : array_like
        n. [rad/s]
    kinematic_viscosity : array_like
        nu at the operating temperature (of the base oil for grease). [m^2/s]
    bore, outside_diameter : array_like
        d, D; d_m = (d + D)/2. [m]
    bearing_type : {"cylindrical", "tapered", "spherical"}
        The type.
    series : str, optional
        The series of :func:`roller_series_constants`.
    constants : RollerConstants, optional
        The constants directly. [-]
    axial_factor : float, optional
        Y of a single-row tapered bearing (its catalogue value), needed for a tapered bearing. [-]
    full_complement : bool
        A cylindrical roller bearing without cage (its constants and K_Z, K_L).
    lubrication : {"grease", "oil-air", "oil-jet", "oil-bath"}
        Sets K_rs; an oil bath adds the drag moment (needs ``width`` and ``oil_level``).
    width : float, optional
        B of the inner ring, for the drag moment. [m]
    drag_loss_factor : float, optional
        V_M in place of SKF's diagram at H/d_m (roller-bearing curve, :func:`bearinglab.friction.drag.drag_loss_factor`). [-]
    ehl_coefficient : float, optional
        mu_EHL; by default SKF's value of the type (:data:`ROLLER_EHL_COEFFICIENTS`). [-]
    sliding_friction_coefficient : array_like, optional
        mu_sl in place of the model's. [-]
    seal : {"LS", "CS", "CS2", "CS5"}, optional
        Contact seals (:data:`ROLLER_SEAL_CONSTANTS`), with ``seal_diameter``.
    seals : int
        Sealed sides, 0, 1 or 2. [-]
    seal_diameter : float, optional
        The seal counterface d_s (E of a cylindrical bearing, d2 of a spherical one). [m]
    oil_level : float, optional
        Oil bath: H from the lowest point of the outer ring raceway, for V_M of SKF's diagram. [m]

    Returns
    -------
    SKFTorque

    Notes
    -----
    GC 6000/I RU (2006), pp. 89-101 (module reference [1]), in N, mm, rpm, mm^2/s:
    :math:`M = \Phi_{ish}\Phi_{rs} G_{rr}(\nu n)^{0.6} + \mu_{sl} G_{sl} + M_{seal} + M_{drag}` with, by type,
    cylindrical :math:`G_{rr} = R_1 d_m^{2.41} F_r^{0.31}`, :math:`G_{sl} = S_1 d_m^{0.9} F_a + S_2 d_m F_r`;
    tapered :math:`G_{rr} = R_1 d_m^{2.38}(F_r + R_2 Y F_a)^{0.31}`, :math:`G_{sl} = S_1 d_m^{0.82}(F_r + S_2 Y
    F_a)`; spherical the smaller of :math:`R_1 d_m^{1.85}(F_r + R_2 F_a)^{0.54}` and :math:`R_3 d_m^{2.3}(F_r +
    R_4 F_a)^{0.31}`, and of :math:`S_1 d_m^{0.25}(F_r^4 + S_2 F_a^4)^{1/3}` and :math:`S_3 d_m^{0.94}(F_r^3 +
    S_4 F_a^3)^{1/3}`. :math:`\Phi_{ish}` and :math:`\mu_{sl}` as for ball bearings;
    :math:`\Phi_{rs} = \exp(-K_{rs}\nu n (d + D)\sqrt{K_Z/(2(D - d))})` with the type's K_Z.

    Examples
    --------
    The catalogue's worked example, a 22208 E in an oil bath (pp. 104-105):

    >>> m = skf_roller(2990.0, 100.0, 3500 * 2 * np.pi / 60, 68e-6, 40e-3, 80e-3, bearing_type="spherical",
    ...                series="222 E", lubrication="oil-bath", width=23e-3, drag_loss_factor=0.3e-4)
    >>> print(f"M_sl = {m.sliding_moment * 1e3:.1f}, M_drag = {m.drag_moment * 1e3:.1f}, M = {m.total_moment * 1e3:.0f} N mm")
    M_sl = 21.7, M_drag = 14.5, M = 331 N mm
    """
    if lubrication not in skf.LUBRICATION_METHODS:
        raise InputError(f"lubrication must be one of {list(skf.LUBRICATION_METHODS)}, got {lubrication!r}")
    kz, _ = _type_constants(bearing_type, full_complement)
    bath = lubrication == "oil-bath"
    if bath and (width is None or (drag_loss_factor is None and oil_level is None)):
        raise InputError("oil_level: an oil bath needs the oil level H (V_M follows from SKF's diagram at H/d_m; "
                         "drag_loss_factor= overrides it) and the inner-ring width B for the drag moment of a roller bearing")
    if not bath and (oil_level is not None or drag_loss_factor is not None):
        raise InputError(f"oil_level: the oil level and drag loss factor belong to lubrication='oil-bath', not "
                         f"{lubrication!r}")
    if constants is None:
        if series is None:
            raise InputError("give the bearing series (series=) or its constants (constants=)")
        constants = roller_series_constants(bearing_type, "full complement" if full_complement and
                                            bearing_type == "cylindrical" else series)
    fr = check_nonnegative("radial_load", radial_load, "N")
    fa = check_nonnegative("axial_load", axial_load, "N")
    y = 0.0
    if bearing_type == "tapered":
        if axial_factor is None:
            raise InputError("axial_factor (Y of the tapered bearing, its catalogue value) is needed for G_rr and G_sl")
        y = float(check_positive("axial_factor", axial_factor, "-"))
    omega = np.abs(np.asarray(shaft_speed, dtype=float))
    n = omega / _RPM
    nu = check_positive("kinematic_viscosity", kinematic_viscosity, "m^2/s") / _CST
    d = check_positive("bore", bore, "m") / _MM
    big = check_positive("outside_diameter", outside_diameter, "m") / _MM
    dm = 0.5 * (d + big)
    g_rr, g_sl = _load_variables(fr, fa, dm, constants, bearing_type, y)
    phi_ish = skf.inlet_shear_heating_factor(nu * _CST, omega, dm * _MM)
    phi_rs = np.exp(-skf.LUBRICATION_METHODS[lubrication] * nu * n * (d + big) * np.sqrt(kz / (2 * (big - d))))
    m_rr = phi_ish * phi_rs * g_rr * (nu * n) ** 0.6
    mu_ehl = ROLLER_EHL_COEFFICIENTS[bearing_type] if ehl_coefficient is None else ehl_coefficient
    mu = (skf.sliding_friction_coefficient(nu * _CST, omega, dm * _MM, ehl_coefficient=mu_ehl)
          if sliding_friction_coefficient is None
          else check_nonnegative("sliding_friction_coefficient", sliding_friction_coefficient, "-"))
    m_sl = g_sl * mu
    m_seal = _seal(seal, seals, seal_diameter, big)
    vm = None
    if bath:  # the V_M used: the one given, else SKF's diagram at H/d_m (roller-bearing curve)
        vm = (_drag_loss_factor(oil_level, dm * _MM, "roller") if drag_loss_factor is None
              else np.asarray(drag_loss_factor, dtype=float)[()])
    m_drag = (roller_drag_moment(omega, d * _MM, big * _MM, width, vm, bearing_type=bearing_type,
                                 full_complement=full_complement) / _MM if bath else 0.0)
    total = m_rr + m_sl + m_seal + m_drag
    shape = np.broadcast(total, mu).shape
    out = [np.broadcast_to(x * _MM, shape)[()] for x in (m_rr, m_sl, m_seal, m_drag, total)]
    return skf.SKFTorque(*out, np.broadcast_to(total * _MM * omega, shape)[()], np.broadcast_to(mu, shape)[()],
                         drag_loss_factor=vm)


def _seal(seal, seals, seal_diameter, big):
    """K_S1 d_s^beta + K_S2 for two sealed sides, half for one [N mm]."""
    if seals not in (0, 1, 2) or isinstance(seals, bool):
        raise InputError(f"seals must be 0, 1 or 2 [-], got {seals!r}")
    if seal is None or seals == 0:
        return 0.0
    if seal not in ROLLER_SEAL_CONSTANTS:
        raise InputError(f"seal must be one of {list(ROLLER_SEAL_CONSTANTS)} for a roller bearing, got {seal!r}")
    (lo, hi), k, counterface = ROLLER_SEAL_CONSTANTS[seal]
    dmax = float(np.max(big))
    if not lo < dmax <= hi:
        raise InputError(f"outside_diameter {dmax:g} mm is outside the tabulated range of seal {seal!r} ({lo:g} < D <= "
                         f"{hi:g} mm)")
    if seal_diameter is None:
        raise InputError(f"seal_diameter (the counterface d_s = {counterface} of the bearing table) is needed with a "
                         "contact seal")
    ds = check_positive("seal_diameter", seal_diameter, "m") / _MM
    return (k.ks1 * ds**k.beta + k.ks2) * seals / 2.0


def skf_roller_for_bearing(bearing, radial_load, axial_load, shaft_speed, kinematic_viscosity, *,
                           lubrication="grease", **options):
    """The SKF model for a RollerBearing: type, series, Y, envelope and inner-ring width read from it.

    Parameters
    ----------
    bearing : RollerBearing
        Needs bore, outside_diameter and its series (or ``constants=``); a tapered one its Y.
    radial_load, axial_load : array_like
        F_r, F_a. [N]
    shaft_speed : array_like
        n. [rad/s]
    kinematic_viscosity : array_like
        nu. [m^2/s]
    lubrication : {"grease", "oil-air", "oil-jet", "oil-bath"}
        See :func:`skf_roller`.
    **options : optional
        Passed to :func:`skf_roller` (``oil_level``, ``drag_loss_factor``, ``constants``, ...).

    Returns
    -------
    SKFTorque
        With a warning where the series is not in SKF's tables and the table's "other" row is used
        (tapered bearings).

    Examples
    --------
    >>> from bearinglab import catalog
    >>> m = skf_roller_for_bearing(catalog.get("NU 208 ECP"), 5000.0, 0.0, 3000 * np.pi / 30, 20e-6)
    >>> print(f"{m.total_moment * 1e3:.1f} N mm")
    191.4 N mm
    """
    d, big = bearing.require("bore", "outside_diameter")
    kw = {"bearing_type": bearing.type, "lubrication": lubrication, "full_complement": bearing.full_complement}
    note = None
    if "constants" not in options:
        series = bearing.series
        if bearing.type == "tapered" and series not in TAPERED_CONSTANTS:
            note = (f"{bearing.designation or 'this bearing'}: series {series!r} is not in SKF's table 3d; its row "
                    "'all other series' is used")
            series = "other"
        kw["series"] = bearing.require("series") if series is None else series
    if bearing.type == "tapered":
        kw["axial_factor"] = bearing.require("axial_factor")
    if lubrication == "oil-bath":
        kw["width"] = bearing.inner_ring_width or bearing.require("width")
    kw.update(options)
    result = skf_roller(radial_load, axial_load, shaft_speed, kinematic_viscosity, d, big, **kw)
    if note is None:
        return result
    warnings.warn(note, ValidityWarning, stacklevel=2)
    return result._replace(warnings=(note,))

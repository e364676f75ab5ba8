r"""Estimated internal geometry of a roller bearing known only by its boundary dimensions and catalogue values.

Estimation
----------
estimate_roller_set      Z, D_we, L_we, D_pw (and the contact angle of a tapered bearing) from d, D, the width,
                         C0 (and the cup angle, e or Y)
with_estimated_geometry  the bearing with those fields filled in and listed in ``estimated_fields``
EstimatedRollerSet       its result
RULES                    the rule constants, each with where it comes from

The rules (docs/user_guide/roller_bearings.md, "Estimated internal geometry", with their measured error):

1. Pitch diameter :math:`D_{pw} = k_p (d + D)/2` and roller diameter :math:`D_{we} = k_D (D - d)`, with
   :math:`k_p` = 1.010 and :math:`k_D` = 0.275 the medians over 24 single row cylindrical roller bearings of
   SKF's series 2 and 3 whose raceway diameters F and E are printed (D_we = (E - F)/2, D_pw = (E + F)/2; the
   46 sizes of the built-in catalog that print both give 1.0105 and 0.2743). Measured error over those 46:
   D_we -2.9 % to +11.7 % (+5.1 % without N 232 ECM), D_pw -0.5 % to +0.6 %.
2. Rollers :math:`Z = \lfloor \pi D_{pw} / (1.2 D_{we}) \rfloor` (a cage bar a fifth of a roller diameter
   between neighbours). Against the published sets of ``data/roller_sets.csv``: N204 exact (11), NU 330 one
   roller short (13 for 14), 30204 four short (11 for 15: a tapered bearing's rollers are smaller).
3. Effective length from the catalogue's C0 by ISO 76 inverted,
   :math:`L_{we} = C_0 / [44 (1 - \gamma) Z D_{we}\cos\alpha]` (N, mm), at most the width: the estimate
   reproduces C0 exactly, and :math:`Z L_{we}` is what ISO 76 and ISO 281 depend on most.
4. The contact angle of a tapered bearing as given (the catalog's, derived from its e), else from e,
   :math:`\alpha = \arctan(e/1.5)`, else from Y, :math:`\arctan(0.4/Y)` (ISO 281 table 8: e = 1.5 tan alpha,
   Y = 0.4 cot alpha for a single row roller bearing beyond e): e, printed to two decimals, fixes the angle
   more closely. The 30204 of ``data/roller_sets.csv``: 13.13 deg from SKF's e for 12.6 deg published. A
   tapered bearing takes the cylindrical rules 1-3 (D_we 20 % too large, D_pw 5 % too small for that 30204).

Results built on an estimate carry a warning (:func:`bearinglab.catalog.provenance_notes`).
"""

from __future__ import annotations

import math
from typing import NamedTuple

from ..errors import InputError

__all__ = ["RULES", "EstimatedRollerSet", "estimate_roller_set", "with_estimated_geometry"]

#: The rule constants: (value, where it comes from).
RULES = {
    "pitch_factor": (1.010, ("median of (E + F)/(d + D) over 24 SKF sizes of series 2 and 3 that print F and "
                             "E (1.0105 over the catalog's 46)")),
    "diameter_factor": (0.275, "median of (E - F)/(2 (D - d)) over the same 24 SKF sizes (0.2743 over the 46)"),
    "pitch_per_roller": (1.2, "assumption: a cage bar of a fifth of a roller diameter between rollers"),
}
_ISO76 = 44.0  # ISO 76:2006, radial roller bearings: C0 = 44 (1 - gamma) i Z L_we D_we cos(alpha) [N, mm]


class EstimatedRollerSet(NamedTuple):
    """An estimated roller set (SI)."""

    rollers: int
    """Z. [-]"""
    roller_diameter: float
    """D_we. [m]"""
    roller_length: float
    """L_we. [m]"""
    pitch_diameter: float
    """D_pw. [m]"""
    contact_angle: float
    """alpha (0 cylindrical). [rad]"""
    rule: str
    """How each value was estimated."""


def estimate_roller_set(bore, outside_diameter, static_load_rating, *, width=None, bearing_type="cylindrical",
                        axial_factor=None, ratio_limit=None, rows=1, roller_diameter=None, pitch_diameter=None,
                        contact_angle=None):
    r"""Estimate the roller set of a roller bearing from d, D, C0 (and Y or e of a tapered bearing).

    Parameters
    ----------
    bore, outside_diameter : float
        d, D. [m]
    static_load_rating : float
        The catalogue's C0 (ISO 76). [N]
    width : float, optional
        B (T of a tapered bearing): the estimated L_we must fit in it. [m]
    bearing_type : {"cylindrical", "tapered"}
        The type.
    axial_factor, ratio_limit : float, optional
        Y or e of a tapered bearing, for its contact angle (one is needed unless ``contact_angle`` is given;
        e first: printed to two decimals it fixes the angle more closely than Y). [-]
    rows : int
        Rows of rollers. [-]
    roller_diameter, pitch_diameter : float, optional
        D_we and D_pw where they are known (from printed raceway diameters): used instead of rule 1. [m]
    contact_angle : float, optional
        The cup angle of a tapered bearing where it is known: used instead of rule 4. [rad]

    Returns
    -------
    EstimatedRollerSet

    Examples
    --------
    >>> s = estimate_roller_set(40e-3, 80e-3, 53e3)  # NU 208 ECP
    >>> print(s.rollers, f"{s.roller_diameter * 1e3:.2f} {s.roller_length * 1e3:.2f} {s.pitch_diameter * 1e3:.2f} mm")
    14 11.00 9.56 60.60 mm
    """
    d, big, c0 = float(bore), float(outside_diameter), float(static_load_rating)
    if not (d > 0 and big > d and c0 > 0):
        raise InputError("bore, outside_diameter and static_load_rating must be > 0 with outside_diameter > bore, to "
                         "estimate the roller set [mm, kN]")
    if bearing_type == "tapered":
        if contact_angle is not None:
            alpha, how = float(contact_angle), "alpha the bearing's own (a catalog row's from its e = 1.5 tan alpha)"
        elif ratio_limit is not None:
            alpha, how = math.atan(float(ratio_limit) / 1.5), "alpha = atan(e / 1.5)"
        elif axial_factor is not None:
            alpha, how = math.atan(0.4 / float(axial_factor)), "alpha = atan(0.4 / Y)"
        else:
            raise InputError("axial_factor (Y) or ratio_limit (e) of the tapered bearing is needed to estimate its "
                             "contact angle")
    elif bearing_type == "cylindrical":
        alpha, how = 0.0, ""
    else:
        raise InputError(f"bearing_type must be 'cylindrical' or 'tapered' to estimate a roller set (a spherical "
                         f"roller bearing's load distribution is not modelled), got {bearing_type!r}")
    dpw = RULES["pitch_factor"][0] * 0.5 * (d + big) if pitch_diameter is None else float(pitch_diameter)
    dw = RULES["diameter_factor"][0] * (big - d) if roller_diameter is None else float(roller_diameter)
    z = math.floor(math.pi * dpw / (RULES["pitch_per_roller"][0] * dw))
    gamma = dw * math.cos(alpha) / dpw
    mm = 1e3
    length = c0 / (_ISO76 * (1.0 - gamma) * rows * z * dw * mm * math.cos(alpha)) / mm
    if width is not None and length * math.cos(alpha) > float(width):
        length = float(width) / math.cos(alpha)
        how += "; L_we limited to the width"
    given = "D_pw and D_we as given" if pitch_diameter is not None and roller_diameter is not None else \
        "D_pw = 1.010 (d + D)/2, D_we = 0.275 (D - d)"
    rule = f"{given}, Z = floor(pi D_pw / (1.2 D_we)), L_we from C0 by ISO 76" + (f"; {how}" if how else "")
    return EstimatedRollerSet(z, dw, length, dpw, alpha, rule)


def with_estimated_geometry(bearing):
    """The bearing with its missing roller set estimated (:func:`estimate_roller_set`) and labelled.

    Parameters
    ----------
    bearing : RollerBearing
        Needs bore, outside_diameter and static_load_rating (and Y or e when tapered).

    Returns
    -------
    RollerBearing
        The same bearing where it already has rollers, roller_diameter, roller_length and pitch_diameter;
        else with the estimates filled in, listed in ``estimated_fields`` and their rule in ``sources``.

    Examples
    --------
    >>> from bearinglab import catalog
    >>> b = with_estimated_geometry(catalog.get("NU 208 ECP"))
    >>> b.rollers, b.estimated_fields[:2]
    (14, ('rollers', 'roller_length'))
    """
    if bearing.has_internal_geometry and bearing.contact_angle is not None:
        return bearing
    if bearing.type == "spherical":
        raise InputError(f"{bearing.designation or 'this bearing'!r} is a spherical roller bearing: its load "
                         "distribution is not modelled (ratings, life and friction only)")
    missing = [n for n in ("bore", "outside_diameter", "static_load_rating") if getattr(bearing, n) is None]
    if missing:
        raise InputError(f"{missing[0]} of {bearing.designation or 'this bearing'!r} is needed to estimate its roller set "
                         "(or give rollers, roller_diameter, roller_length, pitch_diameter)")
    s = estimate_roller_set(bearing.bore, bearing.outside_diameter, bearing.static_load_rating, width=bearing.width,
                            bearing_type=bearing.type, axial_factor=bearing.axial_factor,
                            ratio_limit=bearing.ratio_limit, rows=bearing.rows,
                            contact_angle=bearing.contact_angle if bearing.type == "tapered" else None,
                            roller_diameter=bearing.roller_diameter if bearing.pitch_diameter is not None else None,
                            pitch_diameter=bearing.pitch_diameter if bearing.roller_diameter is not None else None)
    changes, est = {}, []
    for name in ("rollers", "roller_diameter", "roller_length", "pitch_diameter", "contact_angle"):
        if getattr(bearing, name) is None or (name == "contact_angle" and bearing.type == "tapered"
                                              and bearing.contact_angle is None):
            changes[name] = getattr(s, name)
            est.append(name)
    if not est:
        return bearing
    sources = {**bearing.sources, **{n: f"estimated: {s.rule}" for n in est}}
    return bearing.replace(**changes, estimated_fields=tuple(dict.fromkeys((*est, *bearing.estimated_fields))),
                           sources=sources)

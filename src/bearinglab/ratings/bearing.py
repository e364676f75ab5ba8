"""The load ratings of one bearing: the catalog's values where given, else ISO 76 / ISO 281 from the geometry.

One set of ratings per bearing, whichever command asks: the life analysis (:mod:`bearinglab.life`), the
friction model's C0, the thermal reference speed and the plausibility limits all read them here.

Ratings
-------
bearing_ratings    C, C0, Cu and f0 of a BallBearing or a RollerBearing, each with where it comes from
BearingRatings     its result
"""

from __future__ import annotations

from typing import NamedTuple

from ..errors import InputError
from . import dynamic, roller, static

__all__ = ["BearingRatings", "bearing_ratings"]


class BearingRatings(NamedTuple):
    """Load ratings of a bearing and where each comes from."""

    dynamic_load_rating: float
    """C. [N]"""
    static_load_rating: float
    """C0. [N]"""
    fatigue_load_limit: float
    """Cu. [N]"""
    static_load_factor: float
    """f0 of ISO 76 (NaN where the ball set is unknown). [N/mm^2]"""
    rating_source: dict
    """Quantity name -> ``"catalog"``, ``"ISO 76"``, ``"ISO 281"``, ``"ISO 281 annex B (precise)"`` or
    ``"ISO 281 annex B (C0/22)"``."""


def _geometry(bearing):
    return (bearing.n_balls, bearing.ball_diameter, bearing.pitch_diameter,
            bearing.contact_angle if bearing.contact_angle is not None else 0.0)


def _conformities(bearing):
    fi = bearing.inner_conformity if bearing.inner_conformity is not None else 0.52  # ISO 76 table 2
    fo = bearing.outer_conformity if bearing.outer_conformity is not None else 0.53
    return fi, fo


# the types whose ratings bearinglab computes from the geometry, and what it cannot compute for the others
# (ISO 281 table 2's columns of double-row deep groove and self-aligning bearings, ISO 76's f0 of
# self-aligning (4600 MPa, spherical raceway) and thrust ball bearings, and four-point bearings, which
# neither standard covers, are not in bearinglab): the catalog's ratings are then needed
_DYNAMIC_FROM_GEOMETRY = ("radial", "angular", "double-row-angular", "thrust")
_STATIC_FROM_GEOMETRY = ("radial", "angular", "double-row-angular", "double-row-radial")


def bearing_ratings(bearing, *, fatigue_method="precise"):
    """C, C0 and Cu of a bearing: the catalog's values where given, else ISO 76 / ISO 281 from the geometry.

    Parameters
    ----------
    bearing : BallBearing
        With catalog ratings, or with ``n_balls``, ``ball_diameter`` and ``pitch_diameter`` (groove
        conformities 0.52 / 0.53 of ISO 76 when not known). Double-row types rate both rows (i = 2);
        a thrust ball bearing's C is Ca of ISO 281 table 4 (90 deg).
    fatigue_method : {"precise", "simplified"}
        Cu by ISO 281 annex B.3 from the contact stress (needs the ball set), or C0/22.

    Returns
    -------
    BearingRatings

    Raises
    ------
    InputError
        A rating that is neither in the catalog nor computable: the ball set is unknown, or the standards'
        tables of the bearing's type are not in bearinglab (double-row deep groove and self-aligning C;
        self-aligning and thrust C0; four-point C and C0).

    Examples
    --------
    >>> from bearinglab.bearing import BallBearing
    >>> r = bearing_ratings(BallBearing(9, 7.94e-3, 39.04e-3, 0.52, 0.53, contact_angle=0.0, type="radial"))
    >>> print(f"{r.dynamic_load_rating:.0f} {r.static_load_rating:.0f} {r.fatigue_load_limit:.1f}", r.rating_source["dynamic_load_rating"])
    14023 7872 358.6 ISO 281
    """
    if fatigue_method not in ("precise", "simplified"):
        raise InputError(f"fatigue_method must be one of ['precise', 'simplified'], got {fatigue_method!r}")
    if hasattr(bearing, "roller_diameter"):  # a RollerBearing (issue 32)
        return _roller_ratings(bearing)
    z, d, dpw, alpha = _geometry(bearing)
    fi, fo = _conformities(bearing)
    has_set = None not in (z, d, dpw)
    kind, rows = bearing.type, bearing.rows
    source = {}
    label = bearing.designation or "this bearing"

    def need(what, computable):
        if kind not in computable:
            raise InputError(f"{what} of {label!r} is not in its catalog entry, and bearinglab does not compute it "
                             f"for a {kind} bearing (the standard's table for the type is not in bearinglab); give "
                             f"{what} (catalog entry, bearing file)")
        if not has_set:
            raise InputError(f"{what} of {label!r} is not in its catalog entry and the ball set (n_balls, "
                             "ball_diameter, pitch_diameter) needed to compute it is not known")

    if bearing.static_load_factor is not None:
        f0 = float(bearing.static_load_factor)  # the maker's printed f0
    elif has_set and kind in _STATIC_FROM_GEOMETRY:
        f0 = float(static.static_load_factor(d, dpw, alpha, inner_conformity=fi, outer_conformity=fo))
    else:
        f0 = float("nan")
    if bearing.dynamic_load_rating is not None:
        c, source["dynamic_load_rating"] = bearing.dynamic_load_rating, "catalog"
    else:
        need("dynamic_load_rating", _DYNAMIC_FROM_GEOMETRY)
        c = float(dynamic.dynamic_axial_load_rating(z, d, dpw) if kind == "thrust"
                  else dynamic.dynamic_load_rating(z, d, dpw, alpha, n_rows=rows))
        source["dynamic_load_rating"] = "ISO 281"
    if bearing.static_load_rating is not None:
        c0, source["static_load_rating"] = bearing.static_load_rating, "catalog"
    else:
        need("static_load_rating", _STATIC_FROM_GEOMETRY)
        c0 = float(static.static_load_rating(z, d, dpw, alpha, n_rows=rows, inner_conformity=fi,
                                             outer_conformity=fo))
        source["static_load_rating"] = "ISO 76"
    if bearing.fatigue_load_limit is not None:
        cu, source["fatigue_load_limit"] = bearing.fatigue_load_limit, "catalog"
    elif fatigue_method == "precise" and has_set and kind in _STATIC_FROM_GEOMETRY:
        cu = float(static.fatigue_load_limit(z, d, dpw, alpha, n_rows=rows, inner_conformity=fi,
                                             outer_conformity=fo))
        source["fatigue_load_limit"] = "ISO 281 annex B (precise)"
    else:
        cu = float(static.fatigue_load_limit_simplified(c0, dpw if dpw is not None else bearing.mean_diameter))
        source["fatigue_load_limit"] = "ISO 281 annex B (C0/22)"
    return BearingRatings(float(c), float(c0), float(cu), f0, source)


def _roller_ratings(bearing):
    """C, C0, Cu of a RollerBearing: the catalogue's values, else ISO 281 / ISO 76 / ISO 281 annex B (C0/8.2)."""
    source = {}
    has_set = bearing.has_internal_geometry
    label = bearing.designation or f"this {bearing.type} roller bearing"

    def need(what):
        if not has_set:
            raise InputError(f"{what} of {label!r} is not in its catalog entry and the roller set (rollers, "
                             "roller_diameter, roller_length, pitch_diameter) needed to compute it is not known")

    alpha = bearing.contact_angle or 0.0
    if bearing.dynamic_load_rating is not None:
        c, source["dynamic_load_rating"] = bearing.dynamic_load_rating, "catalog"
    else:
        need("dynamic_load_rating")
        c = float(roller.roller_dynamic_load_rating(bearing.rollers, bearing.roller_diameter, bearing.roller_length,
                                                    bearing.pitch_diameter, alpha, rows=bearing.rows,
                                                    bearing_type=bearing.type))
        source["dynamic_load_rating"] = "ISO 281"
    if bearing.static_load_rating is not None:
        c0, source["static_load_rating"] = bearing.static_load_rating, "catalog"
    else:
        need("static_load_rating")
        c0 = float(roller.roller_static_load_rating(bearing.rollers, bearing.roller_diameter, bearing.roller_length,
                                                    bearing.pitch_diameter, alpha, rows=bearing.rows))
        source["static_load_rating"] = "ISO 76"
    if bearing.fatigue_load_limit is not None:
        cu, source["fatigue_load_limit"] = bearing.fatigue_load_limit, "catalog"
    else:
        pitch = bearing.pitch_diameter if bearing.pitch_diameter is not None else bearing.mean_diameter
        cu = float(roller.roller_fatigue_load_limit(c0, pitch))
        source["fatigue_load_limit"] = "ISO 281 annex B (C0/8.2)"
    estimated = set(bearing.estimated_fields) & {"rollers", "roller_diameter", "roller_length", "pitch_diameter"}
    for name in ("dynamic_load_rating", "static_load_rating"):
        if estimated and source[name] in ("ISO 281", "ISO 76"):
            source[name] += " (from an estimated roller set)"
    return BearingRatings(float(c), float(c0), float(cu), float("nan"), source)

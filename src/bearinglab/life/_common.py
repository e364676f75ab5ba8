"""The result and the inputs the life analyses of ball and roller bearings share (private).

RatingLife       every life quantity of one analysis (re-exported by :mod:`bearinglab.life.analysis`)
_viscosity       nu from kinematic_viscosity or the oil
_contamination   e_C from a factor or a cleanliness class
"""

from __future__ import annotations

import warnings
from typing import NamedTuple

import numpy as np

from .._validate import check_nonnegative, check_positive
from ..errors import InputError
from ..ratings import lubrication
from ..ratings.static import RatingWarning

__all__ = ["RatingLife"]


class RatingLife(NamedTuple):
    """Every life quantity of one analysis (arrays over the load cases); lives in revolutions."""

    dynamic_load_rating: float
    """C. [N]"""
    static_load_rating: float
    """C0. [N]"""
    fatigue_load_limit: float
    """Cu. [N]"""
    rating_source: dict
    """Where C, C0 and Cu come from (see :class:`BearingRatings`)."""
    equivalent_dynamic_load: np.ndarray
    """P of ISO 281 (NaN where not defined, as under a moment). [N]"""
    basic_rating_life: np.ndarray
    """L10. [revolutions]"""
    basic_rating_life_duration: np.ndarray
    """L10 at the given speed. [s]"""
    reliability_factor: float
    """a1. [-]"""
    viscosity_ratio: np.ndarray | None
    """kappa = nu / nu1 (not clamped); None without a lubricant. [-]"""
    life_modification_factor: np.ndarray | None
    """a_ISO; None without a lubricant. [-]"""
    modified_rating_life: np.ndarray | None
    """L_nm = a1 a_ISO L10; None without a lubricant. [revolutions]"""
    modified_rating_life_duration: np.ndarray | None
    """L_nm at the given speed; None without a lubricant. [s]"""
    reference_rating_life: np.ndarray
    """L10r of ISO/TS 16281 (NaN without a load distribution). [revolutions]"""
    modified_reference_rating_life: np.ndarray | None
    """L_nmr = a1 a_ISO(P_ref) L10r, P_ref = C L10r^(-1/3); None without a lubricant. [revolutions]"""
    static_safety_factor: np.ndarray
    """s0 = C0 / P0 (NaN where P0 is not defined). [-]"""
    warnings: tuple
    """The warnings raised during the analysis, as messages."""
    kinematic_viscosity: np.ndarray | None = None
    """nu at the operating temperature, as used; None without a lubricant. [m^2/s]"""
    rated_viscosity: np.ndarray | None = None
    """nu1 of ISO 281 eqs. (14)-(15) at the speed and :attr:`rated_viscosity_diameter`. [m^2/s]"""
    rated_viscosity_diameter: float | None = None
    """The diameter nu1 is evaluated at: d_m = (d + D)/2 where bore and outside diameter are known, else
    the pitch diameter (:attr:`rated_viscosity_diameter_source` says which). [m]"""
    rated_viscosity_diameter_source: str = ""
    """``"mean diameter (d + D)/2"`` or ``"pitch diameter"``."""
    contamination_factor: float | None = None
    """e_C used for a_ISO (the factor given, or the value of the cleanliness class at the pitch diameter); None
    without a lubricant. [-]"""


def _viscosity(kinematic_viscosity, lubricant):
    """nu [m^2/s] from kinematic_viscosity or the oil (**lubricant); None when neither is given."""
    if kinematic_viscosity is not None:
        if lubricant:
            raise InputError(f"give kinematic_viscosity or the oil ({', '.join(lubricant)}), not both")
        return check_positive("kinematic_viscosity", kinematic_viscosity, "m^2/s")
    if not lubricant:
        return None
    if "temperature" not in lubricant:
        raise InputError("give kinematic_viscosity, or temperature with iso_vg / viscosity_40 (and viscosity_100 "
                         "or viscosity_index)")
    t = lubricant.pop("temperature")
    return lubrication.kinematic_viscosity(t, **lubricant)


def _contamination(contamination, pitch):
    if isinstance(contamination, str):
        return lubrication.contamination_factor(contamination, pitch)
    ec = check_nonnegative("contamination", contamination, "-")
    if (ec > 1).any():
        raise InputError(f"contamination must be a factor e_C in [0, 1] [-] or a class name, got "
                         f"{float(ec[ec > 1].flat[0])!r}")
    return ec


def _untilted(p, p0, moment):
    """P and P0 with NaN for the load cases that carry a tilting moment, where ISO 281 and ISO 76 do not define
    them (one warning for them all, pointing at the caller of the public life function)."""
    tilted = moment > 0
    if tilted.any():
        warnings.warn(f"{int(tilted.sum())} of {tilted.size} load cases carry a tilting moment: ISO 281's "
                      "equivalent load P (and ISO 76's P0) is not defined there, and neither are the ISO 281 "
                      "lives and s0; the ISO/TS 16281 reference life covers them", RatingWarning, stacklevel=4)
    return np.where(tilted, np.nan, p), np.where(tilted, np.nan, p0)


def _result(r, n, fr, p, l10, l10r, s0, a1, nu, nu1, kappa, ec, a_iso, a_ref, dm, dm_source, messages):
    """The :class:`RatingLife` of ball and roller bearings alike: the lives in revolutions and in time at the
    speed n [rad/s], and without a lubricant (``nu`` None) None, not NaN, for what needs kappa."""
    speed = np.broadcast_to(n, np.broadcast(n, fr).shape)
    duration = 2 * np.pi / speed
    if nu is None:
        kappa_out = a_iso_out = lnm_out = lnm_time = lnmr = nu_out = None
    else:
        lnm = a1 * a_iso * l10
        kappa_out, a_iso_out, lnm_out = np.broadcast_to(kappa, speed.shape)[()], a_iso[()], lnm[()]
        lnm_time, lnmr = (lnm * duration)[()], (a1 * a_ref * l10r)[()]
        nu_out = np.broadcast_to(nu, speed.shape)[()]
    return RatingLife(
        r.dynamic_load_rating, r.static_load_rating, r.fatigue_load_limit, r.rating_source, p[()], l10[()],
        (l10 * duration)[()], a1, kappa_out, a_iso_out, lnm_out, lnm_time, l10r[()], lnmr, s0[()], messages,
        nu_out, np.broadcast_to(nu1, speed.shape)[()], float(dm), dm_source, None if nu is None else float(ec))

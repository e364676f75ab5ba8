"""Mounted bearing sets: how fits, temperatures and speed change the preload of a set with rigid spacers.

first_contact_offset     axial offset A sin(alpha0) at which a bearing's balls first touch, from its clearance
operating_interference   the set's axial interference in operation, from the assembled one

A set is preloaded by an axial interference between its opposed bearings, measured from the position
where the balls first touch (:mod:`bearinglab.quasistatic.sets`). The spacers fix the rings' axial
positions; when the fits, temperatures and speed take diametral clearance e away, the free contact angle
falls and the balls touch at a smaller axial offset A sin(alpha0), so the same spacers give a larger
interference: each bearing's offset is kept, s(e) + e_int/2 = s(e') + e_int'/2.

The axial growth of shaft and housing between the bearings acts too: with the inner assembly (shaft,
inner spacer) growing by alpha_s (T_s - 20 degC) L and the outer (housing, outer spacer) by
alpha_h (T_h - 20 degC) L over the bearing centre distance L, a back-to-back (DB) set loses that
difference of interference (the inner rings are pushed apart), a face-to-face (DF) set gains it; a
tandem set has no interference. The spacers are taken at the temperature and of the material of the
part they sit on: an approximation (labelled so in the theory page).
"""

from __future__ import annotations

import numpy as np

from .. import geometry
from ..errors import InputError
from . import thermal

__all__ = ["first_contact_offset", "operating_interference"]


def first_contact_offset(bearing, radial_clearance):
    """The axial offset A sin(alpha0) of the groove-curvature centres at first contact.

    Parameters
    ----------
    bearing : bearinglab.bearing.BallBearing
        Needs the ball diameter and both conformities.
    radial_clearance : array_like
        Diametral clearance e. [m]

    Returns
    -------
    ndarray
        A sin(alpha0(e)), A = (f_i + f_o - 1) D; 0 for e <= 0, where the balls touch both raceways (and
        are compressed by -e/2) in the concentric position already. [m]

    Examples
    --------
    >>> from bearinglab import catalog
    >>> b = catalog.get("B218")
    >>> print(f"{first_contact_offset(b, b.radial_clearance) * 1e6:.1f} um")
    663.0 um
    """
    d, fi, fo = bearing.require("ball_diameter", "inner_conformity", "outer_conformity")
    e = np.asarray(radial_clearance, dtype=float)
    if np.any(~np.isfinite(e)):
        raise InputError(f"radial_clearance must be finite [um], got {radial_clearance!r}")
    out = np.zeros(e.shape)
    play = e > 0  # none left: first contact in the concentric position (issue 30)
    if play.any():
        out[play] = (fi + fo - 1.0) * d * np.sin(geometry.free_contact_angle(e[play], d, fi, fo))
    return out[()]


def operating_interference(bearing, assembled_interference, clearance_reduction, *, arrangement_kind="DB",
                           spacing=0.0, shaft_temperature=thermal.REFERENCE_TEMPERATURE,
                           housing_temperature=thermal.REFERENCE_TEMPERATURE, shaft_expansion=12.5e-6,
                           housing_expansion=12.5e-6):
    """The axial interference of a set of like bearings in operation.

    Parameters
    ----------
    bearing : bearinglab.bearing.BallBearing
        The set's bearing (all alike), with its unmounted clearance ``radial_clearance``.
    assembled_interference : float
        The interference at assembly (20 degC, unmounted clearance), as ``preload_displacement`` of
        :func:`bearinglab.quasistatic.sets.set_analysis`. [m]
    clearance_reduction : float
        Diametral clearance taken by fits, temperatures and speed (the chain's sum). [m]
    arrangement_kind : {"DB", "DF", "DT"}
    spacing : float
        Distance L between the bearing centres. [m]
    shaft_temperature, housing_temperature : float
        [K]
    shaft_expansion, housing_expansion : float
        [1/K]

    Returns
    -------
    tuple of float
        (operating interference [m], operating clearance e' [m]).

    Examples
    --------
    >>> from bearinglab import catalog
    >>> b = catalog.get("B218")
    >>> e, clr = operating_interference(b, 0.0, 10e-6)
    >>> print(f"{e * 1e6:.2f} um")
    12.01 um
    """
    e0 = bearing.require("radial_clearance")
    e1 = e0 - float(clearance_reduction)
    s0, s1 = first_contact_offset(bearing, e0), first_contact_offset(bearing, e1)
    e = float(assembled_interference) + 2.0 * float(s0 - s1)
    if arrangement_kind in ("DB", "DF"):
        axial = (float(thermal.expansion(spacing, shaft_temperature, shaft_expansion))
                 - float(thermal.expansion(spacing, housing_temperature, housing_expansion)))
        e += -axial if arrangement_kind == "DB" else axial
    return e, e1

"""The slice model of a RollerBearing: its roller set and its load distribution.

Analysis
--------
bearing_roller_set   the RollerSet of a RollerBearing (profile drops at the slices, gap from the clearance,
                     axial support from the design, E' from the materials)
roller_analysis      the load distribution of a RollerBearing for a batch of load cases, with the warnings its
                     inputs call for (estimated roller set, materials other than steel)
N_SLICES             the default number of slices (30, ISO/TS 16281's recommended minimum)

Every number it reports comes from :mod:`bearinglab.rollers.distribution` with the fields of the bearing;
a bearing known only by its boundary dimensions gets an estimated roller set
(:mod:`bearinglab.rollers.estimation`) and every result built on it says so.
"""

from __future__ import annotations

import math
import warnings

from ..bearing import STEEL
from ..errors import InputError, ValidityWarning
from . import distribution, geometry
from .estimation import with_estimated_geometry

__all__ = ["N_SLICES", "bearing_roller_set", "provenance", "roller_analysis"]

#: Default slices per roller: ISO/TS 16281 asks for at least 30 (issue 32).
N_SLICES = 30
_AXIAL = {"NU": "none", "N": "none", "NJ": "ribs-positive", "NUP": "ribs"}


def provenance(bearing):
    """The warnings a result built on this bearing carries (estimated fields, materials the model is not for).

    Parameters
    ----------
    bearing : RollerBearing
        The bearing as the model used it.

    Returns
    -------
    list of str

    Examples
    --------
    >>> from bearinglab.rollers.bearing import RollerBearing
    >>> provenance(RollerBearing("cylindrical", 14, 11e-3, 9.6e-3, 60.5e-3))
    []
    """
    notes = []
    est = [f for f in bearing.estimated_fields if f]
    if est:
        rule = bearing.sources.get(est[0], "bearinglab.rollers.estimation")
        notes.append(f"{bearing.designation or 'this bearing'}: {', '.join(est)} estimated, not published ({rule}); "
                     "the load distribution, stiffness, pressures and ISO/TS 16281 life built on them are estimates: "
                     "give the maker's roller set (rollers, roller_diameter, roller_length, pitch_diameter) for "
                     "measured values")
    if bearing.roller_material != STEEL or bearing.ring_material != STEEL:
        notes.append("the lamina stiffness is ISO/TS 16281's constant of steel rollers and rings (35948 N/mm^(10/9)); "
                     "the materials given set only the pressures (E'): give slice_constant= for another pairing")
    return notes


def bearing_roller_set(bearing, *, n_slices=N_SLICES, first_roller_angle=0.0, radial_clearance=None,
                       normal_gap=None, slice_constant=None):
    """The :class:`~bearinglab.rollers.distribution.RollerSet` of a roller bearing.

    Parameters
    ----------
    bearing : RollerBearing
        Cylindrical or tapered, with its roller set (see :func:`roller_analysis` for the estimate).
    n_slices : int, optional
        Slices per roller. [-]
    first_roller_angle : float, optional
        phi0. [rad]
    radial_clearance : float, optional
        The operating diametral clearance e in place of the bearing's (0 when neither is given). [m]
    normal_gap : float, optional
        g_0 directly (a bearing in a pair; overrides the clearance). [m]
    slice_constant : float, optional
        c_s in place of ISO/TS 16281's steel constant. [N/m^(10/9)]

    Returns
    -------
    RollerSet

    Examples
    --------
    >>> from bearinglab.rollers.bearing import RollerBearing
    >>> rs = bearing_roller_set(RollerBearing("cylindrical", 14, 11e-3, 9.6e-3, 60.5e-3, radial_clearance=20e-6))
    >>> print(f"{rs.normal_gap * 1e6:.1f} um, {rs.drop[0] * 1e6:.2f} um drop at the edge slice")
    10.0 um, 10.49 um drop at the edge slice
    """
    if bearing.type == "spherical":
        raise InputError(f"{bearing.designation or 'this bearing'!r} is a spherical roller bearing: its load distribution "
                         "is not modelled (two rows of barrel rollers on a spherical raceway); ratings, life (ISO 281) "
                         "and friction are")
    z, d, length, dpw = bearing.require("rollers", "roller_diameter", "roller_length", "pitch_diameter")
    alpha = bearing.require("contact_angle")
    if normal_gap is None:
        e = radial_clearance if radial_clearance is not None else (bearing.radial_clearance or 0.0)
        normal_gap = 0.5 * e * math.cos(alpha)
    s = geometry.slice_positions(length, n_slices)
    support = "raceways" if bearing.type == "tapered" else _AXIAL[bearing.design]
    return distribution.roller_set(z, d, length, dpw, contact_angle=alpha, normal_gap=normal_gap,
                                   drop=bearing.profile_drop(s), n_slices=n_slices,
                                   reduced_modulus=bearing.reduced_modulus, first_roller_angle=first_roller_angle,
                                   axial_support=support, slice_constant=slice_constant)


def roller_analysis(bearing, loads, *, n_slices=N_SLICES, first_roller_angle=0.0, radial_clearance=None,
                    estimate=True, **options):
    """Load distribution, roller and lamina loads, pressures and stiffness of a RollerBearing, batched.

    Parameters
    ----------
    bearing : RollerBearing
        Cylindrical or tapered. Without its roller set it is estimated (``estimate``) from d, D, the width and
        C0 (and Y or e of a tapered bearing), and the result carries a warning.
    loads : array_like
        (..., 5) F_x, F_y, F_z [N], M_x, M_y [N m] on the inner ring.
    n_slices : int, optional
        Slices per roller. [-]
    first_roller_angle : float, optional
        phi0. [rad]
    radial_clearance : float, optional
        The operating diametral clearance e (negative: preload) in place of the bearing's. [m]
    estimate : bool, optional
        Estimate a missing roller set (True) or raise :class:`~bearinglab.errors.InputError` naming what is
        missing.

    Other Parameters
    ----------------
    **options
        ``prescribed_displacement``, ``on_failure``, ``tol``, ``max_iter`` of
        :func:`bearinglab.rollers.distribution.load_distribution`; ``slice_constant``.

    Returns
    -------
    RollerLoadDistribution
        Its ``warnings`` start with the bearing's provenance notes (also raised as
        :class:`~bearinglab.errors.ValidityWarning`).

    Examples
    --------
    >>> from bearinglab import catalog
    >>> r = roller_analysis(catalog.get("NU 208 ECP"), [10e3, 0, 0, 0, 0], radial_clearance=30e-6)
    >>> print(f"Q_max = {r.max_roller_load:.0f} N, p_max = {r.max_pressure.max() / 1e6:.0f} MPa")
    Q_max = 3605 N, p_max = 1942 MPa
    """
    if estimate and not bearing.has_internal_geometry:
        bearing = with_estimated_geometry(bearing)
    rs = bearing_roller_set(bearing, n_slices=n_slices, first_roller_angle=first_roller_angle,
                            radial_clearance=radial_clearance, slice_constant=options.pop("slice_constant", None))
    notes = provenance(bearing)
    for note in notes:
        warnings.warn(note, ValidityWarning, stacklevel=2)
    result = distribution.load_distribution(loads, rs, **options)
    return result._replace(warnings=tuple(notes) + result.warnings)

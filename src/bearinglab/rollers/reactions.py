"""Loads and stiffness of roller bearings at given ring displacements, batched: the roller branch of
:func:`bearinglab.reactions.bearing_reactions`.

Reactions
---------
roller_reactions   (n, 5) displacements of one roller bearing -> (n, 5) loads, (n, 5, 5) stiffness, (n,) ok

The conventions are those of :mod:`bearinglab.reactions` (and of the slice model,
:mod:`bearinglab.rollers.distribution`): the displacement of the inner ring relative to the outer ring, from
the concentric position, and the load the bearing carries there. A tapered bearing carries axial load in +z
(its cup narrows towards +z: mount the other one of a pair mirrored). A cylindrical roller bearing carries no
axial load on its raceways and its ribs are not modelled: F_z = 0 and no axial stiffness, whatever its
design; a shaft model locates the shaft axially with another bearing (or models the ribs itself). The rollers
carry no centrifugal force (the slice model is at rest): the reactions do not depend on the speed. A spherical
roller bearing has no load-distribution model (InputError).
"""

from __future__ import annotations

import numpy as np

from ..errors import InputError
from . import distribution
from .analysis import N_SLICES, bearing_roller_set
from .estimation import with_estimated_geometry

__all__ = ["roller_reactions"]


def roller_reactions(bearing, displacement, *, n_slices=N_SLICES, first_roller_angle=0.0):
    """Loads and tangent stiffness of one roller bearing at given displacements (no solve), batched.

    Parameters
    ----------
    bearing : RollerBearing
        Cylindrical or tapered; its radial clearance is its operating clearance (a missing roller set is
        estimated, as :func:`bearinglab.rollers.analysis.roller_analysis` does).
    displacement : array_like
        (n, 5) delta_x, delta_y, delta_z [m], theta_x, theta_y [rad].
    n_slices : int, optional
        Slices per roller. [-]
    first_roller_angle : float, optional
        phi0. [rad]

    Returns
    -------
    force : ndarray
        (n, 5) the load the bearing carries. [N, N m]
    stiffness : ndarray
        (n, 5, 5) d force / d displacement.
    converged : ndarray
        (n,) all True (no internal solve).

    Examples
    --------
    >>> from bearinglab.rollers.bearing import RollerBearing
    >>> f, k, ok = roller_reactions(RollerBearing("cylindrical", 14, 11e-3, 9.6e-3, 60.5e-3), [[10e-6, 0, 0, 0, 0]])
    >>> print(f"{f[0, 0]:.0f} N, k_xx = {k[0, 0, 0] / 1e6:.0f} N/um")
    3212 N, k_xx = 469 N/um
    """
    if bearing.type == "spherical":
        raise InputError(f"{bearing.designation or 'this bearing'!r}: a spherical roller bearing has no load-distribution "
                         "model (ratings, life and friction only), so no reactions")
    if not bearing.has_internal_geometry:
        bearing = with_estimated_geometry(bearing)
    rs = bearing_roller_set(bearing, n_slices=n_slices, first_roller_angle=first_roller_angle)
    u = np.ascontiguousarray(np.asarray(displacement, dtype=float).reshape(-1, 5))
    force, stiff, _, _, _ = distribution._evaluate(distribution._kernel(rs), u)
    return force, stiff, np.ones(len(u), dtype=bool)

r"""Forces and stiffness of bearings at given ring displacements, batched: the one entry point other models call.

A system model (a shaft on several bearings, a bearing set, a housing) moves each bearing's inner ring
relative to its outer ring and needs back the load that bearing carries and its tangent stiffness. This
module answers that for many cases and many bearings at once, at rest or at speed, whatever the bearing
type: the system model never calls the command-level analyses (``combined_analysis``, ``set_analysis``)
and never needs to know how a bearing computes its contacts.

Entry point
-----------
bearing_reactions   (cases, bearings, 5) displacements -> (cases, bearings, 5) loads and (.., 5, 5) stiffness
Reactions           its result

Conventions (those of :mod:`bearinglab.quasistatic.combined`): each bearing has its own frame, z along
its axis and x, y radial; the displacement is (delta_x, delta_y, delta_z [m], theta_x, theta_y [rad]) of
the inner ring relative to the outer ring, from the concentric position; ``force`` is the load
(F_x, F_y, F_z [N], M_x, M_y [N m]) that must act on the inner ring to hold it there, i.e. the load the
bearing carries (the bearing pushes back on the shaft with ``-force``); ``stiffness`` is
d force / d displacement. A bearing's operating clearance is the one it carries (``radial_clearance`` or
``contact_angle`` of a :class:`~bearinglab.bearing.BallBearing`, ``radial_clearance`` of a
:class:`~bearinglab.rollers.bearing.RollerBearing`): give the bearing with its mounted
clearance (:mod:`bearinglab.mounting`) to have it here.

Bit-identity: a case gives the same bits alone, in any batch and with any other bearings beside it.
"""

from __future__ import annotations

import functools
from typing import NamedTuple

import numpy as np

from . import _solve
from ._validate import as_float
from .errors import InputError

__all__ = ["Reactions", "bearing_reactions"]


class Reactions(NamedTuple):
    """Loads and stiffness of the bearings at the given displacements."""

    force: np.ndarray
    """(..., n_bearings, 5) the load each bearing carries: F_x, F_y, F_z [N], M_x, M_y [N m]."""
    stiffness: np.ndarray
    """(..., n_bearings, 5, 5) d force / d displacement [N/m, N/rad, N m/m, N m/rad]."""
    converged: np.ndarray
    """(..., n_bearings) False where a bearing's internal solve (the balls at speed) did not converge."""


@functools.lru_cache(maxsize=256)
def _prepared(bearing, first_ball_angle, stiffness_at, raceway_control):
    """A ball bearing's checked geometry (its operating clearance included), kept for the next call: a
    system solver asks for the same bearings in every iteration."""
    from .quasistatic import combined as cb

    return cb._bearing_geometry(bearing, first_ball_angle, stiffness_at, raceway_control)


def _ball_reactions(bearing, u, w, options, compiled):
    """One ball bearing, flat (n, 5) displacements and (n,) speeds."""
    from .quasistatic import combined as cb

    geo = _prepared(bearing, float(options.get("first_ball_angle", 0.0)), options.get("stiffness_at", "operating"),
                    options.get("raceway_control", "outer"))
    return cb._reactions(geo, u, w * w, compiled)


def bearing_reactions(bearings, displacement, shaft_speed=0.0, **options):
    """Loads and tangent stiffness of bearings at given ring displacements, batched over cases and bearings.

    Parameters
    ----------
    bearings : BallBearing, RollerBearing or a sequence of them
        One bearing, or the ``n_bearings`` bearings of a system. A roller bearing is the slice model at rest
        (:func:`bearinglab.rollers.reactions.roller_reactions`: a cylindrical one carries no axial load, a
        tapered one carries F_z > 0). Every ball-bearing type (``BallBearing.type``) is the 5-DOF model of
        :mod:`bearinglab.quasistatic.combined`: a self-aligning bearing carries no moment (zero tilt
        stiffness), a thrust ball bearing no radial load (zero radial stiffness; its delta_z counts from
        first contact), and four-point and thrust bearings, whose model has no speed terms, are evaluated
        at rest at any speed.
    displacement : array_like
        (..., n_bearings, 5), or (..., 5) for one bearing: delta_x, delta_y, delta_z [m], theta_x,
        theta_y [rad] of each inner ring relative to its outer ring.
    shaft_speed : array_like, optional
        Inner-ring speed of each case, broadcast over the leading axes. [rad/s]

    Other Parameters
    ----------------
    **options
        ``first_ball_angle``, ``stiffness_at``, ``raceway_control`` and ``engine`` as in
        :func:`bearinglab.quasistatic.combined.load_distribution` (``engine="auto"``: the compiled kernel
        when numba is installed); ``n_slices``, ``first_roller_angle`` of roller bearings.

    Returns
    -------
    Reactions
        ``force`` (..., n_bearings, 5), ``stiffness`` (..., n_bearings, 5, 5), ``converged``
        (..., n_bearings); without the bearing axis for a single bearing.

    Examples
    --------
    >>> from bearinglab import catalog
    >>> r = bearing_reactions(catalog.get("B218"), [0.0, 0.0, 0.7e-3, 0.0, 0.0])  # 0.663 mm take up the play
    >>> print(f"F_z = {r.force[2]:.0f} N, k_zz = {r.stiffness[2, 2] / 1e6:.1f} N/um")
    F_z = 18618 N, k_zz = 781.7 N/um
    """
    single = not isinstance(bearings, (list, tuple))
    group = [bearings] if single else list(bearings)
    u = as_float("displacement", displacement)
    if single:
        u = u[..., None, :]
    if u.shape[-2:] != (len(group), 5):
        raise InputError(f"displacement must have the shape (..., {len(group)}, 5) for {len(group)} "
                         f"bearing(s), got {np.shape(displacement)}")
    lead = u.shape[:-2]
    w = np.broadcast_to(as_float("shaft_speed", shaft_speed), lead)
    if np.any(~np.isfinite(w)) or np.any(w < 0):
        raise InputError("shaft_speed must be finite and >= 0 [rad/s]")
    compiled = _solve.use_compiled(options.get("engine", "auto"), auto=True)
    n = int(np.prod(lead, dtype=np.int64))
    flat = u.reshape(n, len(group), 5)
    ww = np.ascontiguousarray(w.reshape(n), dtype=float)
    force = np.empty((n, len(group), 5))
    stiff = np.empty((n, len(group), 5, 5))
    ok = np.empty((n, len(group)), dtype=bool)
    from .bearing import BallBearing
    from .rollers.bearing import RollerBearing

    for j, b in enumerate(group):
        if isinstance(b, BallBearing):
            f, k, c = _ball_reactions(b, np.ascontiguousarray(flat[:, j]), ww, options, compiled)
        elif isinstance(b, RollerBearing):  # the slice model (issue 32); at rest, so the speed does not enter
            from .rollers.reactions import roller_reactions

            f, k, c = roller_reactions(b, np.ascontiguousarray(flat[:, j]), **{
                key: options[key] for key in ("n_slices", "first_roller_angle") if key in options})
        else:
            raise InputError(f"bearings[{j}]: no reaction model for {type(b).__name__}")
        force[:, j], stiff[:, j], ok[:, j] = f, k, c
    force, stiff, ok = (force.reshape(lead + (len(group), 5)), stiff.reshape(lead + (len(group), 5, 5)),
                        ok.reshape(lead + (len(group),)))
    if single:
        return Reactions(force[..., 0, :], stiff[..., 0, :, :], ok[..., 0])
    return Reactions(force, stiff, ok)

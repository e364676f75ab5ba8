r"""A single ball bearing with zero or negative operating clearance: its radial preload (issue 30).

A fit with interference and an inner ring warmer than the outer one take a bearing's diametral
clearance e away; below zero the balls are squeezed between the raceways before any load acts. The
combined-load model solves such a bearing as it is (:func:`bearinglab.quasistatic.combined.load_distribution`
with ``radial_clearance`` e <= 0, which every command passes on); this module states what the preload
is and what it changes.

Preload
-------
preload           the ball load, interference and stiffness at zero external load, from the clearance
Preload           its result
stiffness_gain    the stiffness under given loads against the same bearing at zero clearance
preload_note      the warning of a negative clearance, with its numbers

At zero external load every ball sits at alpha = 0, compressed by delta_0 = -e/2, and carries
Q_0 = K_n delta_0^1.5 (K_n of both contacts at alpha = 0; Harris and Kotzalas, *Essential Concepts of
Bearing Technology*, 5th ed., CRC Press, 2006, ch. 7, the load-deflection relation of a ball between two
raceways). The ring is in equilibrium (the ball loads cancel), and it is stiff in every direction:
radially k_r = 1.5 K_n delta_0^0.5 sum_j cos^2 psi_j (= 0.75 Z K_n delta_0^0.5 for Z >= 3), axially
k_a = Z Q_0 / g_0 with g_0 = A - e/2 the distance of the groove-curvature centres (an axial shift turns
every compressed ball by z / g_0), in tilt k_theta = (d_m/2)^2 (Z/2) Q_0 / g_0. A bearing with clearance
has none of these at zero load.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from ..errors import InputError
from . import combined

__all__ = ["Preload", "preload", "preload_note", "stiffness_gain"]


class Preload(NamedTuple):
    """The preload of a bearing with zero or negative clearance, at rest and without external load (SI)."""

    clearance: float  # e, the diametral operating clearance [m]
    interference: float  # delta_0 = max(-e/2, 0), the compression of every ball (the other types: along
    #                       its contact line, |g_0| - A) [m]
    ball_load: float  # Q_0 [N]
    ball_load_sum: float  # Z Q_0, the sum of the ball loads (they cancel on the ring) [N]
    stiffness: np.ndarray  # (5, 5) at zero external load [N/m, N/rad, N m/m, N m/rad]


def preload(bearing, *, first_ball_angle=0.0, stiffness_at="operating"):
    """The preload of a bearing from its clearance: ball load, interference and stiffness at zero load.

    Parameters
    ----------
    bearing : BallBearing
        With its operating ``radial_clearance`` (e <= 0 for a preload; a positive clearance gives zeros).
    first_ball_angle : float, optional
        phi0. [rad]
    stiffness_at : {"operating", "free"}, optional
        As in :func:`~bearinglab.quasistatic.combined.load_distribution`.

    Returns
    -------
    Preload

    Examples
    --------
    >>> from bearinglab import catalog
    >>> p = preload(catalog.get("6208").replace(radial_clearance=-10e-6))
    >>> print(f"Q_0 = {p.ball_load:.1f} N, k_r = {p.stiffness[0, 0] / 1e6:.1f} N/um")
    Q_0 = 116.7 N, k_r = 157.6 N/um
    """
    e = bearing.radial_clearance
    if e is None:
        raise InputError(f"radial_clearance of {bearing.designation or 'the bearing'!r} is not known; the preload "
                         "comes from a zero or negative operating clearance")
    geo = combined._bearing_geometry(bearing, first_ball_angle, stiffness_at)
    _force, stiff, balls = combined._evaluate(geo, np.zeros((1, 5)), np.zeros(1))
    q = float(np.max(balls["qi"][0]))
    if geo.elements is None:
        interference = geo.interference
    else:  # the other types: each contact pair compressed along its line at the built-in angle
        el = geo.elements
        interference = max(float(np.max(np.hypot(el.ga0, el.gr0))) - geo.big_a, 0.0) if geo.kind != "thrust" else 0.0
    return Preload(float(e), interference, q, float(np.sum(balls["qi"][0])), stiff[0])


def stiffness_gain(bearing, loads, shaft_speed=0.0, **options):
    """The diagonal stiffness under given loads, with the bearing's preload and at zero clearance.

    Parameters
    ----------
    bearing : BallBearing
        With a zero or negative ``radial_clearance``.
    loads : array_like
        (..., 5): F_x, F_y, F_z [N], M_x, M_y [N m].
    shaft_speed : array_like, optional
        [rad/s]
    **options
        Passed to :func:`~bearinglab.quasistatic.combined.combined_analysis` (``on_failure`` defaults to
        "flag").

    Returns
    -------
    preloaded, zero_clearance : ndarray
        (..., 5) the diagonal of the stiffness matrix with the preload and at e = 0 (NaN where a solve
        failed; at zero load the bearing at e = 0 has no stiffness). [N/m, N/rad, N m/m, N m/rad]

    Notes
    -----
    The gain is largest at light loads. Once a load unloads the balls opposite it, a ball's stiffness
    at a given ball load no longer depends on how it got there (1.5 K_n^(2/3) Q^(1/3)), so the preloaded
    and the zero-clearance bearing approach each other (6208 at -10 um: 1.6x k_xx at 500 N, the same at
    2000 N); in between, where the opposite balls lift off, the preloaded k_xx dips.

    Examples
    --------
    >>> from bearinglab import catalog
    >>> b = catalog.get("6208").replace(radial_clearance=-10e-6)
    >>> k, k0 = stiffness_gain(b, [500.0, 0, 0, 0, 0])
    >>> print(f"k_xx: {k[0] / 1e6:.0f} N/um preloaded, {k0[0] / 1e6:.0f} N/um at zero clearance")
    k_xx: 151 N/um preloaded, 92 N/um at zero clearance
    """
    options.setdefault("on_failure", "flag")
    with_preload = combined.combined_analysis(bearing, loads, shaft_speed, **options)
    zero = combined.combined_analysis(bearing.replace(radial_clearance=0.0), loads, shaft_speed, **options)
    return (np.diagonal(with_preload.stiffness, axis1=-2, axis2=-1),
            np.diagonal(zero.stiffness, axis1=-2, axis2=-1))


def preload_note(bearing, source="the operating clearance"):
    """The warning of a bearing with zero or negative clearance: how far the clearance is negative, the
    ball load and stiffness it gives at zero load, and how it is solved.

    Parameters
    ----------
    bearing : BallBearing
        With its operating ``radial_clearance``.
    source : str, optional
        How the clearance was given, the warning's subject ("the given radial clearance", ...).

    Returns
    -------
    str or None
        The warning; None for a positive (or unknown) clearance.

    Examples
    --------
    >>> from bearinglab import catalog
    >>> print(preload_note(catalog.get("6208").replace(radial_clearance=-10e-6))[:75])
    the operating clearance is negative, -10 um: the bearing runs preloaded, ev
    """
    e = bearing.radial_clearance
    if e is None or e > 0:
        return None
    p = preload(bearing)
    what = "zero" if e == 0 else "negative"
    if e == 0:
        return (f"{source} is 0 um: every ball touches both raceways with no play and no preload; solved as a "
                "bearing without clearance (no stiffness at zero load)")
    return (f"{source} is {what}, {e * 1e6:.3g} um: the bearing runs preloaded, every ball compressed by "
            f"{p.interference * 1e6:.3g} um and loaded with {p.ball_load:.4g} N at no external load (radial "
            f"stiffness there {p.stiffness[0, 0] / 1e6:.4g} N/um, axial {p.stiffness[2, 2] / 1e6:.4g} N/um); "
            "solved as a preloaded bearing (more friction and heat than with clearance)")

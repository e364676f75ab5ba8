r"""Loads too light for the speed: below the maker's minimum load, gyroscopic slip, an outer contact angle
driven to zero.

Criteria
--------
light_load             per-case flags and the test-stand minimum axial load
light_load_warnings    messages for the combined-load and the high-speed models: the minimum load of a
                       running bearing (SKF's 0.01 C, :mod:`bearinglab.ratings.minimum_load`) and the
                       outer contact angle driven to zero

All apply at speed only. The test-stand minimum axial load against gyroscopic slip (spec 000 section 3, at
mu = 0.02) stays a flag of :func:`light_load` and the subject of ``bearinglab stand-load``: it is the least
load of a test stand, and for a large bearing at speed it exceeds C, so it is not the minimum load of a
bearing in service (issue 20). Used by :mod:`bearinglab.quasistatic.combined`; the high-speed model
(:func:`bearinglab.quasistatic.contact_angles`) can call :func:`light_load_warnings` with its per-case
thrust and angles.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from .. import stand
from .._validate import as_float, check_nonnegative

__all__ = ["OUTER_ANGLE_FRACTION", "STAND_FRICTION", "LightLoad", "light_load", "light_load_warnings"]

#: Outer contact angle, as a fraction of the free angle, below which it counts as driven to zero.
OUTER_ANGLE_FRACTION = 0.1
#: Friction coefficient of the test-stand minimum-load criterion (spec 000 section 3).
STAND_FRICTION = 0.02


class LightLoad(NamedTuple):
    """Flags of a load too light for the speed."""

    gyroscopic_slip: np.ndarray  # axial load below the test-stand minimum (bool)
    outer_angle_lost: np.ndarray  # outer contact angle below OUTER_ANGLE_FRACTION x alpha0 (bool)
    minimum_axial_load: np.ndarray  # the test-stand minimum [N]


def light_load(axial_load, contact_angle_inner, contact_angle_outer, shaft_speed, n_balls, ball_diameter,
               pitch_diameter, free_angle, *, density=7850.0, sliding_friction_coefficient=STAND_FRICTION,
               outer_angle_fraction=OUTER_ANGLE_FRACTION):
    r"""Is the load too light for the speed? Gyroscopic slip and an outer contact angle driven to zero.

    Parameters
    ----------
    axial_load : array_like
        Axial load the bearing carries, sum of Q_i sin(alpha_i) over the balls. [N]
    contact_angle_inner, contact_angle_outer : array_like
        Contact angles of a loaded ball (or of every ball, broadcast against the other inputs). [rad]
    shaft_speed : array_like
        Inner-ring speed. [rad/s]
    n_balls : int
        Z. [-]
    ball_diameter : float
        D. [m]
    pitch_diameter : float
        d_m. [m]
    free_angle : float
        alpha0. [rad]
    density : float, optional
        Ball density. [kg/m^3]
    sliding_friction_coefficient : float, optional
        Friction coefficient of the slip criterion (spec 000 section 3: 0.02). [-]
    outer_angle_fraction : float, optional
        The outer angle counts as lost below this fraction of alpha0. [-]

    Returns
    -------
    LightLoad
        ``gyroscopic_slip``, ``outer_angle_lost`` and the ``minimum_axial_load`` [N].

    Notes
    -----
    Gyroscopic slip: the test-stand minimum axial load of spec 000 section 3,
    :func:`bearinglab.stand.min_axial_load_gyroscopic` at the free angle (friction at the two contacts
    resists the gyroscopic moment while M_g <= mu Q D). The outer angle: at light thrust and high speed the
    centrifugal force turns the outer contact towards the groove bottom while the inner contact angle
    grows (spec 004 section 7.1): flagged where abs(alpha_o) < ``outer_angle_fraction`` alpha0 while
    abs(alpha_i) > alpha0 (so that a small angle from a radial load is not flagged). Neither applies at
    rest, nor the angle criterion to a bearing with alpha0 = 0.

    Examples
    --------
    >>> import math
    >>> from bearinglab.units import RPM
    >>> f = light_load(50.0, math.radians(60.0), math.radians(0.05), 15000 * RPM, 16, 22.23e-3, 125.3e-3, math.radians(40))
    >>> print(bool(f.gyroscopic_slip), bool(f.outer_angle_lost), f"{f.minimum_axial_load / 1e3:.0f} kN")
    True True 113 kN
    """
    fa = as_float("axial_load", axial_load)
    ai = as_float("contact_angle_inner", contact_angle_inner)
    ao = as_float("contact_angle_outer", contact_angle_outer)
    w = check_nonnegative("shaft_speed", shaft_speed, "rad/s")
    a0 = float(free_angle)
    minimum = stand.min_axial_load_gyroscopic(w, n_balls, ball_diameter, pitch_diameter, a0,
                                               sliding_friction_coefficient=sliding_friction_coefficient, density=density)
    moving = w > 0
    slip = moving & (np.abs(fa) < minimum)
    lost = moving & (a0 > 0) & (np.abs(ao) < outer_angle_fraction * a0) & (np.abs(ai) > a0)
    return LightLoad(np.asarray(slip)[()], np.asarray(lost)[()], np.asarray(minimum)[()])


def light_load_warnings(axial_load, contact_angle_inner, contact_angle_outer, shaft_speed, n_balls, ball_diameter,
                        pitch_diameter, free_angle, *, density=7850.0, case_index=None, radial_load=0.0,
                        bearing_type=None, inner_conformity=0.52, outer_conformity=0.53, dynamic_load_rating=None,
                        static_load_rating=None):
    """Warning messages for loads too light for the speed: below the maker's minimum load, and the outer
    contact angle driven to zero (see :func:`light_load`).

    Parameters
    ----------
    axial_load : array_like
        Axial load of the bearing, one per case. [N]
    contact_angle_inner, contact_angle_outer : array_like
        Contact angles, one per case or (cases, balls) for loaded balls (NaN for unloaded ones). [rad]
    shaft_speed : array_like
        Inner-ring speed. [rad/s]
    n_balls : int
        Z. [-]
    ball_diameter : float
        D. [m]
    pitch_diameter : float
        d_m. [m]
    free_angle : float
        alpha0. [rad]
    density : float, optional
        Ball density. [kg/m^3]
    case_index : array_like, optional
        Case numbers to quote in the messages (default 0, 1, ...).
    radial_load : array_like, optional
        Radial load of the bearing, one per case (0: pure thrust). [N]
    bearing_type : {"radial", "angular"}, optional
        For ISO 281's X and Y (default: "angular" where ``free_angle`` > 0).
    inner_conformity, outer_conformity : float, optional
        For C0 and f0 of ISO 76 from the geometry (defaults of ISO 76 table 2). [-]
    dynamic_load_rating, static_load_rating : float, optional
        C and C0 (the catalog's); by default ISO 281 / ISO 76 from the geometry (said in the message). [N]

    Returns
    -------
    list of str
        At most one message per criterion, with the number of cases and the first one.

    Notes
    -----
    The minimum load is SKF's general rule for ball bearings, 0.01 C
    (:func:`bearinglab.ratings.minimum_load.minimum_load_warnings`), against ISO 281's equivalent load
    P = X F_r + Y F_a (C0 and f0 of ISO 76 for X and Y; the resultant load where ISO 281 has no row for the
    angle).

    Examples
    --------
    >>> import math
    >>> from bearinglab.units import RPM
    >>> m = light_load_warnings(50.0, math.radians(60.0), math.radians(0.05), 15000 * RPM, 16, 22.23e-3, 125.3e-3, math.radians(40))
    >>> print(len(m), m[0][:60])
    2 minimum load: 1 of 1 case(s) at speed below 0.01 C (ISO 281,
    >>> print(m[1][:38])
    light load: the outer contact angle is
    """
    fa = np.ravel(as_float("axial_load", axial_load))
    w = np.ravel(as_float("shaft_speed", shaft_speed))
    ai, ao = (np.reshape(as_float(n, v), (max(fa.size, w.size), -1)) for n, v in
              (("contact_angle_inner", contact_angle_inner), ("contact_angle_outer", contact_angle_outer)))
    flags = light_load(fa[:, None], ai, ao, w[:, None], n_balls, ball_diameter, pitch_diameter, free_angle,
                       density=density)
    fa = np.broadcast_to(fa, w.shape) if fa.size < w.size else fa
    lost = np.any(flags.outer_angle_lost, axis=1)
    idx = np.arange(fa.size) if case_index is None else np.ravel(case_index)
    msgs = _minimum_load_notes(fa, np.broadcast_to(as_float("radial_load", radial_load), fa.shape), w, n_balls,
                               ball_diameter, pitch_diameter, float(free_angle), idx, bearing_type,
                               inner_conformity, outer_conformity, dynamic_load_rating, static_load_rating)
    if lost.any():
        k = int(np.flatnonzero(lost)[0])
        msgs.append(f"light load: the outer contact angle is driven to zero in {int(lost.sum())} case(s) (below "
                    f"{OUTER_ANGLE_FRACTION:g} x the free angle), e.g. case {idx[k]}: the thrust is too small for "
                    "the speed")
    return msgs


def _minimum_load_notes(fa, fr, w, z, d, dm, a0, idx, kind, fi, fo, c, c0):
    """SKF's minimum load 0.01 C against ISO 281's P of each case at speed (see :func:`light_load_warnings`)."""
    from ..errors import InputError
    from ..ratings import dynamic, minimum_load, static

    kind = kind or ("angular" if a0 > 0 else "radial")
    alpha = a0 if kind == "angular" else 0.0  # a deep-groove bearing is rated at alpha = 0 (ISO 281)
    where = "" if c is not None else " (ISO 281, from the geometry)"
    c = float(dynamic.dynamic_load_rating(z, d, dm, alpha)) if c is None else float(c)
    if c0 is None:
        c0 = float(static.static_load_rating(z, d, dm, alpha, inner_conformity=fi, outer_conformity=fo))
    f0 = float(static.static_load_factor(d, dm, alpha, inner_conformity=fi, outer_conformity=fo))
    fa, fr = np.abs(fa), np.abs(fr)
    try:
        p = dynamic.equivalent_dynamic_load(fr, fa, c0, alpha, bearing_type=kind,
                                            static_load_factor=f0 if kind == "radial" else None)
        load = "P = X F_r + Y F_a (ISO 281)"
    except InputError:  # an angle without a row in ISO 281 table 3: the resultant load
        p, load = np.hypot(fr, fa), "the resultant load (ISO 281 has no X, Y for this angle)"
    return minimum_load.minimum_load_warnings(np.broadcast_to(p, w.shape), w, c, rating=f"C{where}", load=load,
                                              case_index=idx)

"""Model of the DP11A-type friction rig (spec 001 section 4): loads from the hung mass and the tilt.

Constants
---------
GRAVITY               9.81 m/s^2, the value the source uses (not standard gravity)
RIG_MASSES            the masses supplied with the rig, 0.5, 1.0 and 2.0 kg (descriptive)
TILT_STEP             the tilt detents, every 15 deg (descriptive; any tilt in [0, 90] deg is accepted)

Functions
---------
rig_loads             F_a = g Q cos(beta), F_r = g Q sin(beta), eq. (4.1), exact zeros at 0 and 90 deg
rig_equivalent_load   the loads and P0 of (3.1), with the branch of the max rule that governs
branch_switch_tilt    beta* = arctan(y0 / (1 - x0)), the tilt where the branch of (3.1) switches

The tilt beta is measured from the vertical: beta = 0 is a vertical spindle (pure axial load),
beta = 90 deg a horizontal one (pure radial load). Q includes an optional tare mass (the housing or
holder, spec 001 section 8.13; the source ignores it, so it defaults to 0).
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from .. import friction
from .._validate import as_float, check_nonnegative, check_positive
from ..errors import InputError

__all__ = [
    "GRAVITY",
    "RIG_MASSES",
    "TILT_STEP",
    "RigEquivalentLoad",
    "RigLoads",
    "branch_switch_tilt",
    "check_tilt",
    "rig_equivalent_load",
    "rig_loads",
]

GRAVITY = 9.81  # m/s^2, spec 001 section 2 (the source's value)
RIG_MASSES = (0.5, 1.0, 2.0)  # kg, spec 001 section 4
TILT_STEP = math.radians(15.0)  # rad, spec 001 section 4
_SNAP = (
    1e-12  # rad: a tilt this close to 0 or 90 deg is that end, so the vanishing load is exactly 0
)


class RigLoads(NamedTuple):
    """Axial and radial load on the test bearing, eq. (4.1)."""

    axial_load: float | np.ndarray
    """F_a (the source's "F0", spec 001 section 8.2). [N]"""
    radial_load: float | np.ndarray
    """F_r. [N]"""


class RigEquivalentLoad(NamedTuple):
    """Loads on the test bearing and its static equivalent load."""

    axial_load: float | np.ndarray
    """F_a. [N]"""
    radial_load: float | np.ndarray
    """F_r. [N]"""
    equivalent_load: float | np.ndarray
    """P0 of (3.1). [N]"""
    combined: bool | np.ndarray
    """True where x0 F_r + y0 F_a governs (3.1), False where F_r does."""


def check_tilt(tilt, name="tilt"):
    """Require 0 <= tilt <= 90 deg and return the tilt in radians, snapped onto the ends.

    Parameters
    ----------
    tilt : array_like
        Tilt of the spindle axis from the vertical. [rad]
    name : str
        Name used in the error message.

    Returns
    -------
    ndarray
        The tilt, with values within 1e-12 rad of 0 or pi/2 set to exactly 0 or pi/2. [rad]

    Examples
    --------
    >>> check_tilt(math.radians(95.0))
    Traceback (most recent call last):
    ...
    bearinglab.errors.InputError: tilt must be in [0, 90] [deg], got 95.0
    """
    b = as_float(name, tilt)
    bad = ~((b >= -_SNAP) & (b <= math.pi / 2 + _SNAP))
    if bad.any():
        first = float(np.degrees(b[bad].flat[0]) if b.ndim else math.degrees(float(b)))
        count = f" ({int(bad.sum())} of {b.size} values)" if b.size > 1 else ""
        raise InputError(f"{name} must be in [0, 90] [deg], got {round(first, 9)!r}{count}")
    b = np.where(np.abs(b) <= _SNAP, 0.0, b)
    return np.where(np.abs(b - math.pi / 2) <= _SNAP, math.pi / 2, b)


def rig_loads(mass, tilt, *, tare_mass=0.0, gravity=GRAVITY):
    """Axial and radial load on the test bearing from the hung mass and the tilt, eq. (4.1).

    Parameters
    ----------
    mass : array_like
        Mass Q hung on the bearing housing. [kg]
    tilt : array_like
        Tilt beta of the spindle axis from the vertical, in [0, pi/2]. [rad]
    tare_mass : array_like, optional
        Mass added to every Q (housing, holder); default 0 as in the source. [kg]
    gravity : float, optional
        Acceleration of gravity; 9.81 as in the source. [m/s^2]

    Returns
    -------
    RigLoads
        ``axial_load`` F_a = g (Q + Q_tare) cos(beta) and ``radial_load`` F_r = g (Q + Q_tare)
        sin(beta). [N]

    Notes
    -----
    Spec 001 eq. (4.1). At beta = 0 and beta = 90 deg the vanishing component is exactly 0 (floating
    point gives cos(pi/2) = 6e-17, which is replaced by 0).

    Examples
    --------
    >>> rig_loads(2.0, math.radians(90.0))
    RigLoads(axial_load=np.float64(0.0), radial_load=np.float64(19.62))
    """
    q = check_positive("mass", mass, "kg")
    tare = check_nonnegative("tare_mass", tare_mass, "kg")
    g = check_positive("gravity", gravity, "m/s^2")
    b = check_tilt(tilt)
    cos_b = np.where(b == math.pi / 2, 0.0, np.cos(b))  # exact zero at 90 deg
    sin_b = np.where(b == 0.0, 0.0, np.sin(b))
    w = g * (q + tare)
    return RigLoads((w * cos_b)[()], (w * sin_b)[()])  # (4.1)


def rig_equivalent_load(
    mass,
    tilt,
    *,
    tare_mass=0.0,
    gravity=GRAVITY,
    bearing_type="radial",
    contact_angle=None,
    radial_factor=None,
    axial_factor=None,
):
    """Loads and static equivalent load P0 on the test bearing of the rig.

    Parameters
    ----------
    mass : array_like
        Mass Q hung on the bearing housing. [kg]
    tilt : array_like
        Tilt beta of the spindle axis from the vertical. [rad]
    tare_mass : array_like, optional
        Mass added to every Q. [kg]
    gravity : float, optional
        Acceleration of gravity. [m/s^2]
    bearing_type : {"radial", "angular"}
        Selects the row of Table 1. [-]
    contact_angle : array_like, optional
        Contact angle of an angular-contact bearing. [rad]
    radial_factor : array_like, optional
        Override of x0. [-]
    axial_factor : array_like, optional
        Override of y0. [-]

    Returns
    -------
    RigEquivalentLoad
        F_a, F_r and P0 [N], and ``combined`` (which branch of (3.1) governs).

    Examples
    --------
    P0 / (g Q) for a radial bearing at 45 deg (spec 001 section 4 table: 0.777817):

    >>> r = rig_equivalent_load(1.0, math.radians(45.0), gravity=1.0)
    >>> print(f"{r.equivalent_load:.6f}", bool(r.combined))
    0.777817 True
    """
    fa, fr = rig_loads(mass, tilt, tare_mass=tare_mass, gravity=gravity)
    kw = {
        "bearing_type": bearing_type,
        "contact_angle": contact_angle,
        "radial_factor": radial_factor,
        "axial_factor": axial_factor,
    }
    p0 = friction.equivalent_static_load(fr, fa, **kw)
    combined = friction.combined_branch_governs(fr, fa, **kw)
    return RigEquivalentLoad(fa, fr, p0, combined)


def branch_switch_tilt(radial_factor=0.6, axial_factor=0.5):
    """Tilt at which the branch of (3.1) switches from x0 F_r + y0 F_a to F_r.

    Parameters
    ----------
    radial_factor : float
        x0, < 1. [-]
    axial_factor : float
        y0, >= 0. [-]

    Returns
    -------
    float
        beta* = arctan(y0 / (1 - x0)): below it the combined branch governs. [rad]

    Notes
    -----
    From x0 sin(beta) + y0 cos(beta) = sin(beta) (spec 001 section 4).

    Examples
    --------
    >>> print(f"{math.degrees(branch_switch_tilt(0.6, 0.5)):.4f} deg")
    51.3402 deg
    """
    x0 = float(check_nonnegative("radial_factor", radial_factor, "-"))
    y0 = float(check_nonnegative("axial_factor", axial_factor, "-"))
    if not x0 < 1.0:
        raise InputError(f"radial_factor must be < 1 [-] for the branch to switch, got {x0!r}")
    return math.atan2(y0, 1.0 - x0)

r"""Internal geometry of roller bearings: tapered-roller angles, slices and roller profiles.

Tapered roller bearings
-----------------------
tapered_angles        cone (inner raceway) angle, roller half angle and roller-axis angle from the cup angle
TaperedAngles         its result

Slices (ISO/TS 16281)
---------------------
slice_positions       the centres x_k of the n_s laminae of an effective roller length

Roller profiles (the drop of the roller radius at a position along the roller)
-------------------------------------------------------------------------------
logarithmic_drop      ISO/TS 16281's logarithmic profile (cylindrical and tapered rollers)
crowned_drop          a circular crown with a given drop at the ends of the effective length
flat_drop             a straight roller, with circular edge radii over an end zone if given
table_drop            a user table of drop against position, linear between its points
PROFILES              the profile names

Positions are measured along the roller from its middle, in metres; a drop is the reduction of the
roller radius there, >= 0. The load-distribution model loses it at both raceway contacts (2 x drop), as
ISO/TS 16281 does with its profile (eq. (41) as transcribed in [2]).

References
----------
.. [1] T. A. Harris and M. N. Kotzalas, *Essential Concepts of Bearing Technology*, 5th ed., CRC Press,
   2006, ch. 2 (tapered roller bearing geometry: the roller and raceway cones share one apex on the
   bearing axis), doi:10.1201/9781420006599.
.. [2] ISO/TS 16281:2008, *Rolling bearings -- Methods for calculating the modified reference rating life
   for universally loaded bearings*, clause 8 (roller bearings: laminae, eqs. (38)-(46); the roller
   profile, eqs. (42)-(44)); the equations are transcribed in the open repository
   github.com/minzhun/ISO16281 (RollerBearing.py), whose facts (not code) are used here.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from .._validate import as_float, check_integer, check_nonnegative, check_positive
from ..errors import ConvergenceError, InputError

__all__ = [
    "PROFILES",
    "TaperedAngles",
    "crowned_drop",
    "flat_drop",
    "logarithmic_drop",
    "slice_positions",
    "table_drop",
    "tapered_angles",
]

#: Roller profile names (a user table is given as a sequence of (position, drop) pairs instead).
PROFILES = ("logarithmic", "crowned", "flat")

# ISO/TS 16281:2008 eqs. (42)-(44): coefficients of the logarithmic profile, times D_we. Cylindrical
# rollers with L_we <= 2.5 D_we: 0.00035; longer ones: 0.0005 over an end zone of 1.25 D_we at each end;
# tapered rollers: 0.00045.
_LOG_SHORT, _LOG_LONG, _LOG_TAPERED, _LONG_RATIO = 0.00035, 0.0005, 0.00045, 2.5
_ANGLE_TOL, _ANGLE_MAX_ITER = 1e-15, 20  # Newton on the roller half angle [rad]


class TaperedAngles(NamedTuple):
    """Angles of a tapered roller bearing whose roller and raceway cones meet on the bearing axis."""

    cup_angle: float | np.ndarray
    """alpha = alpha_o, the outer raceway (cup) to the bearing axis: the nominal contact angle. [rad]"""
    cone_angle: float | np.ndarray
    """alpha_i = alpha - 2 phi, the inner raceway (cone) to the bearing axis. [rad]"""
    roller_angle: float | np.ndarray
    """phi, half the included angle of the roller cone. [rad]"""
    roller_axis_angle: float | np.ndarray
    """alpha - phi, the roller axis to the bearing axis. [rad]"""


def tapered_angles(contact_angle, roller_diameter, pitch_diameter):
    r"""Cone angle, roller half angle and roller-axis angle of a tapered roller bearing from its cup angle.

    Parameters
    ----------
    contact_angle : array_like
        alpha, the cup angle: the outer raceway to the bearing axis (its normal to the radial plane), the
        nominal contact angle of ISO 281, in (0, 45 deg]. [rad]
    roller_diameter : array_like
        D_we, the roller diameter in the middle of its effective length. [m]
    pitch_diameter : array_like
        D_pw, the diameter of the circle through the middles of the rollers. [m]

    Returns
    -------
    TaperedAngles

    Notes
    -----
    The cup, the cone and every roller are cones with one apex on the bearing axis (true rolling, [1]
    ch. 2). A roller whose axis makes the angle :math:`\alpha_r` with the bearing axis has its middle at
    :math:`\ell = D_{pw} / (2\sin\alpha_r)` from the apex, so its half angle :math:`\varphi` satisfies
    :math:`\tan\varphi = (D_{we}/2)/\ell = (D_{we}/D_{pw})\sin\alpha_r`. The cup raceway is the roller's
    outer generatrix, :math:`\alpha = \alpha_r + \varphi`, the cone raceway its inner one,
    :math:`\alpha_i = \alpha_r - \varphi`. With :math:`k = D_{we}/D_{pw}`,

    .. math:: \tan\varphi = k\sin(\alpha - \varphi),\qquad \alpha_i = \alpha - 2\varphi,

    solved by Newton's method from :math:`\tan\varphi_0 = k\sin\alpha/(1 + k\cos\alpha)` (the root when
    :math:`\cos\varphi \approx 1`) to 1e-15 rad.

    Examples
    --------
    >>> a = tapered_angles(math.radians(15.0), 10e-3, 60e-3)
    >>> print(f"{math.degrees(a.cone_angle):.3f} deg cone, {math.degrees(a.roller_angle):.3f} deg roller half angle")
    10.747 deg cone, 2.127 deg roller half angle
    """
    alpha = as_float("contact_angle", contact_angle)
    bad = ~((alpha > 0) & (alpha <= math.radians(45.0) + 1e-12))
    if bad.any():
        first = float(np.degrees(alpha[bad] if alpha.ndim else alpha).flat[0])
        raise InputError(f"contact_angle must be in (0, 45] [deg] for a tapered roller bearing, got {first!r}")
    d = check_positive("roller_diameter", roller_diameter, "m")
    dpw = check_positive("pitch_diameter", pitch_diameter, "m")
    k = d / dpw
    phi = np.arctan(k * np.sin(alpha) / (1.0 + k * np.cos(alpha)))
    for it in range(1, _ANGLE_MAX_ITER + 1):
        residual = np.tan(phi) - k * np.sin(alpha - phi)
        step = residual / (1.0 / np.cos(phi) ** 2 + k * np.cos(alpha - phi))
        phi = phi - step
        if np.all(np.abs(step) < _ANGLE_TOL):
            return TaperedAngles(alpha[()], (alpha - 2.0 * phi)[()], phi[()], (alpha - phi)[()])
    raise ConvergenceError("rollers.geometry.tapered_angles", iterations=it, residual=residual, estimate=phi)


def slice_positions(roller_length, n_slices):
    r"""Centres of the n_s laminae (slices) of equal width along an effective roller length.

    Parameters
    ----------
    roller_length : float
        L_we, the effective roller length. [m]
    n_slices : int
        n_s, >= 1 (ISO/TS 16281 recommends at least 30). [-]

    Returns
    -------
    ndarray
        :math:`x_k = (k + 1/2 - n_s/2)\, L_{we}/n_s`, k = 0 ... n_s - 1, from the middle of the roller. [m]

    Examples
    --------
    >>> print(slice_positions(10e-3, 4) * 1e3)
    [-3.75 -1.25  1.25  3.75]
    """
    length = float(check_positive("roller_length", roller_length, "m"))
    n = int(check_integer("n_slices", n_slices, 1))
    return (np.arange(n) + 0.5 - n / 2.0) * (length / n)


def _inside(position, roller_length):
    x = as_float("position", position)
    length = float(check_positive("roller_length", roller_length, "m"))
    half = 0.5 * length
    bad = ~(np.abs(x) < half)
    if bad.any():
        raise InputError(f"position must be inside the effective roller length, |x| < {half * 1e3:g} mm [mm], got "
                         f"{float(np.asarray(x)[bad].flat[0]) * 1e3 if x.ndim else float(x) * 1e3:g} mm")
    return x, length


def logarithmic_drop(position, roller_length, roller_diameter, *, tapered=False):
    r"""Drop of ISO/TS 16281's logarithmic roller profile at a position along the roller.

    Parameters
    ----------
    position : array_like
        x from the middle of the effective length, abs(x) < L_we/2. [m]
    roller_length : float
        L_we. [m]
    roller_diameter : float
        D_we. [m]
    tapered : bool
        The profile of a tapered roller (eq. (44)) instead of a cylindrical one.

    Returns
    -------
    ndarray
        The drop of the roller radius, >= 0 (infinite at the ends of L_we, which no slice centre reaches). [m]

    Notes
    -----
    ISO/TS 16281:2008 eqs. (42)-(44) (module reference [2]):

    .. math::
        P(x) = 0.00035\,D_{we}\ln\frac{1}{1 - (2x/L_{we})^2} \quad (L_{we} \le 2.5 D_{we}),

    for longer cylindrical rollers :math:`0.0005\,D_{we}\ln\{1/[1 - ((2|x| - L_{we} + 2.5D_{we})/
    (2.5 D_{we}))^2]\}` over the end zones :math:`|x| > (L_{we} - 2.5 D_{we})/2` and 0 between them, and
    for tapered rollers :math:`0.00045\,D_{we}\ln[1/(1 - (2x/L_{we})^2)]`. The long-roller form is written
    so that the drop is 0 where the end zone begins and infinite at the end of L_we; the transcription in
    the repository quoted there has a sign slip (``- Lwe - 2.5 Dwe``) that would make it negative.

    Examples
    --------
    >>> print(f"{logarithmic_drop(4.5e-3, 10e-3, 10e-3) * 1e6:.3f} um")
    5.813 um
    """
    x, length = _inside(position, roller_length)
    d = float(check_positive("roller_diameter", roller_diameter, "m"))
    if tapered:
        return (_LOG_TAPERED * d * -np.log1p(-(2.0 * x / length) ** 2))[()]
    if length <= _LONG_RATIO * d:
        return (_LOG_SHORT * d * -np.log1p(-(2.0 * x / length) ** 2))[()]
    edge = _LONG_RATIO * d
    u = np.clip((2.0 * np.abs(x) - (length - edge)) / edge, 0.0, None)
    return (_LOG_LONG * d * -np.log1p(-u**2))[()]


def crowned_drop(position, roller_length, crown_drop):
    r"""Drop of a circular crown with a given drop at the ends of the effective length.

    Parameters
    ----------
    position : array_like
        x, abs(x) < L_we/2. [m]
    roller_length : float
        L_we. [m]
    crown_drop : float
        The drop at x = +-L_we/2, >= 0. [m]

    Returns
    -------
    ndarray
        :math:`R - \sqrt{R^2 - x^2}` with the crown radius :math:`R = ((L_{we}/2)^2 + h^2)/(2h)`. [m]

    Examples
    --------
    >>> print(f"{crowned_drop(2.5e-3, 10e-3, 8e-6) * 1e6:.4f} um")
    2.0000 um
    """
    x, length = _inside(position, roller_length)
    h = float(check_nonnegative("crown_drop", crown_drop, "m"))
    if h == 0.0:
        return np.zeros_like(x)[()]
    radius = ((0.5 * length) ** 2 + h * h) / (2.0 * h)
    return (x * x / (radius + np.sqrt(radius * radius - x * x)))[()]  # R - sqrt(R^2 - x^2), without cancellation


def flat_drop(position, roller_length, *, edge_radius=None, edge_length=0.0):
    r"""Drop of a straight roller, with a circular edge radius over an end zone if given.

    Parameters
    ----------
    position : array_like
        x, abs(x) < L_we/2. [m]
    roller_length : float
        L_we. [m]
    edge_radius : float, optional
        r_e, the radius of the circular edge zones (with ``edge_length``). [m]
    edge_length : float
        The length of each edge zone, 0 <= l_e < L_we/2 and <= r_e: the profile is straight over
        abs(x) <= L_we/2 - l_e. [m]

    Returns
    -------
    ndarray
        0 on the straight part, :math:`r_e - \sqrt{r_e^2 - (|x| - x_0)^2}` beyond
        :math:`x_0 = L_{we}/2 - l_e`. [m]

    Examples
    --------
    >>> print(flat_drop([0.0, 4.9e-3], 10e-3, edge_radius=1e-3, edge_length=0.5e-3) * 1e6)
    [ 0.         83.48486101]
    """
    x, length = _inside(position, roller_length)
    le = float(check_nonnegative("edge_length", edge_length, "m"))
    if le == 0.0:
        return np.zeros_like(x)[()]
    if edge_radius is None:
        raise InputError("edge_radius is needed with an edge_length > 0 [mm]")
    r = float(check_positive("edge_radius", edge_radius, "m"))
    if not le < 0.5 * length or le > r:
        raise InputError(f"edge_length must be in [0, min(L_we/2, edge_radius)) = [0, {min(0.5 * length, r) * 1e3:g}) "
                         f"[mm], got {le * 1e3:g} mm")
    u = np.clip(np.abs(x) - (0.5 * length - le), 0.0, None)
    return (u * u / (r + np.sqrt(r * r - u * u)))[()]


def table_drop(position, table):
    r"""Drop of a user profile given as a table of drop against position, linear between its points.

    Parameters
    ----------
    position : array_like
        x along the roller from its middle. [m]
    table : array_like
        (m, 2): positions [m] in rising order and the drops there [m], >= 0; the positions must cover
        every x asked for (no extrapolation).

    Returns
    -------
    ndarray
        The drop. [m]

    Examples
    --------
    >>> print(table_drop([0.0, 4e-3], [[-5e-3, 10e-6], [0.0, 0.0], [5e-3, 10e-6]]) * 1e6)
    [0. 8.]
    """
    t = as_float("profile", table)
    if t.ndim != 2 or t.shape[1] != 2 or t.shape[0] < 2:
        raise InputError(f"profile table must be (position, drop) pairs, at least two, got shape {t.shape}")
    pos, drop = t[:, 0], t[:, 1]
    if not np.all(np.isfinite(t)):
        raise InputError("profile table must hold finite numbers [mm]")
    if not np.all(np.diff(pos) > 0):
        raise InputError("profile table positions must rise strictly [mm]")
    if np.any(drop < 0):
        raise InputError(f"profile drop must be >= 0 [um], got {float(drop[drop < 0][0]) * 1e6:g} um")
    x = as_float("position", position)
    outside = (x < pos[0]) | (x > pos[-1])
    if np.any(outside):
        raise InputError(f"profile table must cover the effective roller length: it spans [{pos[0] * 1e3:g}, "
                         f"{pos[-1] * 1e3:g}] mm, a slice lies at {float(np.asarray(x)[outside].flat[0]) * 1e3:g} mm")
    return np.interp(x, pos, drop)[()]

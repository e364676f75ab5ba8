r"""Nominal geometry of an angular-contact spindle bearing for the runout model (spec 003 section 2).

Geometry
--------
SpindleGeometry         nominal geometry with the derived A0, S, R_b, R_c2, gamma, kappa
geometry_from_catalog   from D_w, d_m, f_o, f_i, tau0, n (catalogue form), optional H10 consistency check
geometry_from_radii     from r30, rho10, rho20, H20, tau0, n (radii form), optional H10 consistency check
geometry_from_bearing   from a :class:`~bearinglab.bearing.BallBearing`

Units: SI (m, rad).
"""

from __future__ import annotations

import math
from typing import NamedTuple

from .._validate import as_float, check_finite, check_integer, check_positive
from ..errors import InputError

__all__ = [
    "SpindleGeometry",
    "geometry_from_bearing",
    "geometry_from_catalog",
    "geometry_from_radii",
]


class SpindleGeometry(NamedTuple):
    """Nominal geometry of the bearing (spec 003 sections 1-2); all lengths [m], angles [rad]."""

    n_balls: int  # n
    ball_radius: float  # r30
    outer_groove_radius: float  # rho10
    inner_groove_radius: float  # rho20
    outer_bottom_radius: float  # H10 = R1, groove-bottom radius of the outer raceway
    inner_bottom_radius: float  # H20 = R2, groove-bottom radius of the inner raceway
    contact_angle: float  # tau0
    first_ball_angle: float  # theta^1, azimuth of ball 1 at psi = 0
    groove_distance: float  # A0 = rho10 + rho20 - 2 r30
    axial_offset: float  # S = A0 sin tau0
    ball_centre_radius: float  # R_b = d_m / 2
    inner_centre_radius: float  # R_c2 = H20 + rho20
    pitch_ratio: float  # gamma = r30 cos tau0 / R_b
    cage_ratio: float  # kappa = (1 - gamma) / 2, cage speed / inner-ring speed


def _build_geometry(n, r30, rho1, rho2, h20, tau0, theta1, h10, where):
    n = int(check_integer("n_balls", n, 3))
    r30 = float(check_positive("ball_radius", r30, "m"))
    rho1 = float(check_positive("outer_groove_radius", rho1, "m"))
    rho2 = float(check_positive("inner_groove_radius", rho2, "m"))
    if not rho1 > r30:
        raise InputError(
            f"outer_groove_radius must be > ball_radius [mm], got {rho1 * 1e3:.6g} mm "
            f"with ball_radius = {r30 * 1e3:.6g} mm (outer conformity must exceed 0.5)"
        )
    if not rho2 > r30:
        raise InputError(
            f"inner_groove_radius must be > ball_radius [mm], got {rho2 * 1e3:.6g} mm "
            f"with ball_radius = {r30 * 1e3:.6g} mm (inner conformity must exceed 0.5)"
        )
    a0 = rho1 + rho2 - 2.0 * r30
    theta1 = float(check_finite("first_ball_angle", theta1, "rad"))
    if h20 is None:
        raise InputError(f"{where}: the inner groove-bottom radius is missing")
    h20 = float(check_positive("inner_bottom_radius", h20, "m"))
    tau_radii = None
    if h10 is not None:
        h10 = float(check_positive("outer_bottom_radius", h10, "m"))
        cos_t = ((h20 + rho2) - (h10 - rho1)) / a0  # (2.1)
        if not -1.0 < cos_t < 1.0:
            raise InputError(
                f"outer_bottom_radius {h10 * 1e3:.6g} mm is inconsistent with the other radii: "
                f"cos(tau0) from (2.1) would be {cos_t:.6g}, outside (-1, 1)"
            )
        tau_radii = math.acos(cos_t)
    if tau0 is None:
        if tau_radii is None:
            raise InputError(
                f"{where}: give contact_angle (or the outer groove-bottom radius to derive it)"
            )
        tau0 = tau_radii
    tau0 = float(as_float("contact_angle", tau0))
    if not 0.0 < tau0 < math.pi / 2:
        raise InputError(
            f"contact_angle must be in (0, 90) [deg], got {math.degrees(tau0):.6g} deg"
        )
    if tau_radii is not None and abs(tau_radii - tau0) > 1e-6:
        raise InputError(
            f"outer_bottom_radius is inconsistent with contact_angle: the radii give tau0 = "
            f"{math.degrees(tau_radii):.7f} deg, the input says {math.degrees(tau0):.7f} deg "
            f"(they must agree within 1e-6 rad)"
        )
    h10 = h20 + rho2 + rho1 - a0 * math.cos(tau0)  # (2.1)
    r_b = h20 + rho2 - (rho2 - r30) * math.cos(tau0)
    gamma = r30 * math.cos(tau0) / r_b
    return SpindleGeometry(
        n,
        r30,
        rho1,
        rho2,
        h10,
        h20,
        tau0,
        theta1,
        a0,
        a0 * math.sin(tau0),
        r_b,
        h20 + rho2,
        gamma,
        (1.0 - gamma) / 2.0,
    )


def geometry_from_catalog(
    n_balls,
    ball_diameter,
    pitch_diameter,
    outer_conformity,
    inner_conformity,
    contact_angle=None,
    *,
    outer_bottom_radius=None,
    first_ball_angle=0.0,
):
    """Nominal geometry from the catalogue form (spec 003 section 2).

    Parameters
    ----------
    n_balls : int
        Number of balls n, >= 3. [-]
    ball_diameter : float
        D_w = 2 r30. [m]
    pitch_diameter : float
        d_m = 2 R_b. [m]
    outer_conformity, inner_conformity : float
        f_o = rho10 / D_w and f_i = rho20 / D_w, each > 0.5. [-]
    contact_angle : float, optional
        Nominal contact angle tau0 in (0, 90 deg); may be omitted when ``outer_bottom_radius`` is
        given. [rad]
    outer_bottom_radius : float, optional
        H10; when given with ``contact_angle`` the two must agree within 1e-6 rad. [m]
    first_ball_angle : float
        theta^1, azimuth of ball 1 at zero rotation. [rad]

    Returns
    -------
    SpindleGeometry

    Notes
    -----
    r30 = D_w/2, rho10 = f_o D_w, rho20 = f_i D_w, H20 = d_m/2 - rho20 + (rho20 - r30) cos tau0; H10 and
    S from (2.1). Without tau0, cos tau0 = (d_m/2 - H10 + rho10) / (rho10 - r30).

    Examples
    --------
    >>> g = geometry_from_catalog(16, 7.144e-3, 54e-3, 0.53, 0.52, math.radians(15))
    >>> print(f"{g.inner_bottom_radius * 1e3:.6f} {g.outer_bottom_radius * 1e3:.6f} {g.cage_ratio:.6f}")
    23.423131 30.579303 0.436106
    """
    dw = float(check_positive("ball_diameter", ball_diameter, "m"))
    dm = float(check_positive("pitch_diameter", pitch_diameter, "m"))
    if not dm > dw:
        raise InputError(
            f"pitch_diameter must be > ball_diameter [mm], got {dm * 1e3:.6g} mm with "
            f"ball_diameter = {dw * 1e3:.6g} mm"
        )
    fo = float(as_float("outer_conformity", outer_conformity))
    fi = float(as_float("inner_conformity", inner_conformity))
    for name, f in (("outer_conformity", fo), ("inner_conformity", fi)):
        if not f > 0.5:
            raise InputError(f"{name} must be > 0.5 [-], got {f!r}")
    r30, rho1, rho2 = dw / 2.0, fo * dw, fi * dw
    tau0 = contact_angle
    if tau0 is None and outer_bottom_radius is not None:
        c = (dm / 2.0 - float(outer_bottom_radius) + rho1) / (rho1 - r30)
        if not -1.0 < c < 1.0:
            raise InputError(
                f"outer_bottom_radius {float(outer_bottom_radius) * 1e3:.6g} mm does not fit "
                f"the catalogue geometry (cos tau0 would be {c:.6g})"
            )
        tau0 = math.acos(c)
    if tau0 is None:
        raise InputError("contact_angle: give the nominal contact angle (or outer_bottom_radius)")
    tau_chk = float(as_float("contact_angle", tau0))
    if not 0.0 < tau_chk < math.pi / 2:
        raise InputError(
            f"contact_angle must be in (0, 90) [deg], got {math.degrees(tau_chk):.6g} deg"
        )
    h20 = dm / 2.0 - rho2 + (rho2 - r30) * math.cos(tau_chk)
    return _build_geometry(
        n_balls,
        r30,
        rho1,
        rho2,
        h20,
        tau_chk,
        first_ball_angle,
        outer_bottom_radius,
        "catalogue geometry",
    )


def geometry_from_radii(
    n_balls,
    ball_radius,
    outer_groove_radius,
    inner_groove_radius,
    inner_bottom_radius,
    contact_angle=None,
    *,
    outer_bottom_radius=None,
    first_ball_angle=0.0,
):
    """Nominal geometry from the radii form (r30, rho10, rho20, H20, tau0, n) of spec 003 section 2.

    Parameters
    ----------
    n_balls : int
        Number of balls n, >= 3. [-]
    ball_radius : float
        r30. [m]
    outer_groove_radius, inner_groove_radius : float
        rho10 and rho20, each > r30. [m]
    inner_bottom_radius : float
        H20, groove-bottom radius of the inner raceway. [m]
    contact_angle : float, optional
        tau0 in (0, 90 deg); may be omitted when ``outer_bottom_radius`` is given. [rad]
    outer_bottom_radius : float, optional
        H10; tau0 from (2.1) must then equal ``contact_angle`` within 1e-6 rad. [m]
    first_ball_angle : float
        theta^1. [rad]

    Returns
    -------
    SpindleGeometry

    Examples
    --------
    >>> g = geometry_from_radii(16, 3.572e-3, 3.78632e-3, 3.71488e-3, 23.4231314821e-3,
    ...                         outer_bottom_radius=30.5793027769e-3)
    >>> print(f"{math.degrees(g.contact_angle):.6f} {g.ball_centre_radius * 1e3:.6f}")
    15.000000 27.000000

    The angle is very sensitive to the radii (A0 is small): H20 and H10 rounded to 1e-6 mm already
    move it by 0.0004 deg, more than the 1e-6 rad that the consistency check allows.
    """
    return _build_geometry(
        n_balls,
        ball_radius,
        outer_groove_radius,
        inner_groove_radius,
        inner_bottom_radius,
        contact_angle,
        first_ball_angle,
        outer_bottom_radius,
        "radii geometry",
    )


def geometry_from_bearing(bearing, *, first_ball_angle=0.0, outer_bottom_radius=None):
    """Nominal geometry of a catalog bearing (its conformities, angle, pitch and ball diameters).

    Parameters
    ----------
    bearing : BallBearing
        Needs n_balls, ball_diameter, pitch_diameter, both conformities and contact_angle.
    first_ball_angle : float
        theta^1. [rad]
    outer_bottom_radius : float, optional
        H10 for the consistency check. [m]

    Returns
    -------
    SpindleGeometry

    Examples
    --------
    >>> from bearinglab import catalog
    >>> geometry_from_bearing(catalog.get("B218")).n_balls
    16
    """
    from ..bearing import check_model

    check_model(bearing, "runout")
    n, dw, dm, fo, fi, tau = bearing.require(
        "n_balls",
        "ball_diameter",
        "pitch_diameter",
        "outer_conformity",
        "inner_conformity",
        "contact_angle",
    )
    return geometry_from_catalog(
        n,
        dw,
        dm,
        fo,
        fi,
        tau,
        outer_bottom_radius=outer_bottom_radius,
        first_ball_angle=first_ball_angle,
    )

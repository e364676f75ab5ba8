r"""Manufacturing errors of an angular-contact spindle bearing -> initial inner-ring displacement and runout.

The method of spec 003 (a rigid, pre-deformation model, first order in the errors): raceway form
errors, ball-size scatter and a prescribed ring tilt push the inner ring off its nominal position; the
ring rests on the two or three balls of the lowest enveloping sinusoid of the generalized errors.

Geometry (spec 003 section 2)
-----------------------------
SpindleGeometry         nominal geometry with the derived A0, S, R_b, R_c2, gamma, kappa
geometry_from_catalog   from D_w, d_m, f_o, f_i, tau0, n (catalogue form), optional H10 consistency check
geometry_from_radii     from r30, rho10, rho20, H20, tau0, n (radii form), optional H10 consistency check
geometry_from_bearing   from a :class:`~bearinglab.bearing.BallBearing`

Errors (section 3)
------------------
FourierSeries           cos/sin coefficients of one error function, by order [m]
fourier_series          build one from ``{order: value}`` mappings or arrays
evaluate_series         sum of a Fourier series at angles
roundness_coefficients  Fourier coefficients of a measured roundness profile (least squares)
RacewayErrors           delta-H, delta-S, delta-rho (and optionally the normal deviation) of one ring
ManufacturingErrors     both rings, the balls, the tilt
manufacturing_errors    build and check a ManufacturingErrors
normal_deviation        Delta_1, Delta_2 at a contact point, eqs. (3.1) and (3.2)

One position (sections 4-9)
---------------------------
ball_angles             ball azimuths over rotation, eq. (10.1)
generalized_error       Delta k of every ball, eq. (4.1)
sinusoid_from_pose      (a0, B, D) of a displaced, tilted ring, eq. (5.1)
pose_from_sinusoid      (dx, dy, dz) from (a0, B, D) and the tilt, eq. (5.2)
tie_break_centre        the point c of the normative tie-break, section 7.5
solve_contact           the contact problem (6.1): a0, B, D, contact set, load shares, degenerate face
contact_point_shifts    refinement shifts d tau1, d tau2, d theta2, eqs. (9.1)-(9.3)
initial_displacement    all of it at one or many rotation angles, optionally refined (section 9)

Rotation and runout (section 10)
--------------------------------
rotation_sequence       the centre trajectory over revolutions, all positions in one batch
runout_metrics          radial peak-to-peak in x, y and over all directions, axial peak-to-peak, mean dz
synchronous_part        average at equal rotation angle over the revolutions
runout_spectrum         spectrum of the radial (forward/backward whirl) and axial motion, in orders
spectrum_lines          the spectral lines, labelled as cage, ring or combination lines

Exact geometry (section 15, example 4)
--------------------------------------
exact_reduction         the same s(theta) without linearisation: largest ball between the ideal tori

Monte Carlo over tolerance classes (section 11)
-----------------------------------------------
BallGrade, RingClass    ISO 3290 ball grades and ring-class presets (``data/tolerance_classes.toml``)
tolerance_classes       all grades and classes, with their sources
ball_grade, ring_class  one of them by name
monte_carlo_chunk       per-sample metrics of a chunk of samples (seeded per sample)
monte_carlo             a whole study, with an optional progress callback
summarize               mean, std, median, p95 and max of per-sample metrics

Files
-----
load_error_file         the TOML error file of ``examples/runout/README.md``

Units: SI throughout (m, rad). The spec states its tolerances in micrometres; the solvers scale them.
"""

from __future__ import annotations

import math
import tomllib
from collections.abc import Callable
from importlib import resources
from typing import NamedTuple

import numpy as np

from . import _runout_contact as _contact
from . import parallel
from ._solve import (
    RUNOUT_CONTACT_TOL_UM,
    RUNOUT_EXACT_MAX_ITER,
    RUNOUT_EXACT_XTOL,
    RUNOUT_REFINE_MAX_ITER,
    RUNOUT_REFINE_TOL,
)
from ._validate import as_float, check_finite, check_integer, check_positive
from .errors import ConvergenceError, InputError

__all__ = [
    "METRICS",
    "BallGrade",
    "ContactSolution",
    "Displacement",
    "FourierSeries",
    "ManufacturingErrors",
    "MonteCarloResult",
    "MonteCarloSamples",
    "Pose",
    "RacewayErrors",
    "RingClass",
    "RunoutMetrics",
    "Shifts",
    "Sinusoid",
    "Spectrum",
    "SpectrumLine",
    "SpindleGeometry",
    "Summary",
    "Trajectory",
    "ball_angles",
    "ball_grade",
    "contact_point_shifts",
    "evaluate_series",
    "exact_reduction",
    "fourier_series",
    "generalized_error",
    "geometry_from_bearing",
    "geometry_from_catalog",
    "geometry_from_radii",
    "initial_displacement",
    "load_error_file",
    "manufacturing_errors",
    "monte_carlo",
    "monte_carlo_chunk",
    "normal_deviation",
    "pose_from_sinusoid",
    "ring_class",
    "rotation_sequence",
    "roundness_coefficients",
    "runout_metrics",
    "runout_spectrum",
    "sinusoid_from_pose",
    "solve_contact",
    "spectrum_lines",
    "summarize",
    "synchronous_part",
    "tie_break_centre",
    "tolerance_classes",
]

_UM = 1e-6  # m per um: the contact solver works in um, the unit of the spec's tolerances
METRICS = ("radial_ptp_x", "radial_ptp_y", "radial_ptp_max", "axial_ptp", "dz_mean")
_METHODS = ("dual", "triples", "lp")
_TIE_BREAKS = ("centre", "midpoint")


# ============================================================================ geometry (section 2)
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


# ============================================================================ errors (section 3)
class FourierSeries(NamedTuple):
    """delta X(theta) = sum_k cos[k] cos(k theta) + sin[k] sin(k theta), k = 0..K. [m]

    ``cos`` and ``sin`` have the same length K + 1 (``sin[0]`` is ignored); leading axes, if any, index
    independent series (one per Monte Carlo sample).
    """

    cos: np.ndarray
    sin: np.ndarray


def fourier_series(cos=None, sin=None, *, scale=1.0):
    """Build a :class:`FourierSeries` from ``{order: value}`` mappings or arrays indexed by order.

    Parameters
    ----------
    cos, sin : dict or array_like, optional
        Coefficients of cos(k theta) and sin(k theta); a mapping gives them by order (k >= 0). [m]
    scale : float
        Multiplies every coefficient (e.g. ``1e-6`` to give them in um). [-]

    Returns
    -------
    FourierSeries

    Examples
    --------
    >>> s = fourier_series({1: 0.5, 2: 0.12}, {2: -0.08}, scale=1e-6)
    >>> s.cos * 1e6, s.sin * 1e6
    (array([0.  , 0.5 , 0.12]), array([ 0.  ,  0.  , -0.08]))
    """
    parts = []
    for name, value in (("cos", cos), ("sin", sin)):
        if value is None:
            parts.append(np.zeros(1))
        elif isinstance(value, dict):
            orders = {}
            for k, v in value.items():
                try:
                    kk = int(k)
                except (TypeError, ValueError):
                    raise InputError(
                        f"{name}: Fourier order must be a whole number >= 0, got {k!r}"
                    ) from None
                if kk < 0 or str(k).strip() not in (str(kk), f"+{kk}"):
                    raise InputError(
                        f"{name}: Fourier order must be a whole number >= 0, got {k!r}"
                    )
                orders[kk] = float(check_finite(f"{name}[{kk}]", v, "m"))
            arr = np.zeros(max(orders, default=0) + 1)
            for kk, v in orders.items():
                arr[kk] = v
            parts.append(arr)
        else:
            parts.append(np.atleast_1d(check_finite(name, value, "m")))
    size = max(parts[0].shape[-1], parts[1].shape[-1])
    out = []
    for p in parts:
        pad = [(0, 0)] * (p.ndim - 1) + [(0, size - p.shape[-1])]
        out.append(np.pad(p, pad) * scale)
    return FourierSeries(out[0], out[1])


def _horner(cos, sin, angle):
    """sum_k cos_k cos(k a) + sin_k sin(k a) by Horner's rule in z = exp(i a) (no loop over angles).

    cos/sin: (..., K+1) broadcastable against angle[..., None] without the last axis.
    """
    c = np.asarray(cos, float) - 1j * np.asarray(sin, float)
    z = np.exp(1j * np.asarray(angle, float))
    k_max = c.shape[-1] - 1
    acc = np.broadcast_to(c[..., k_max], np.broadcast_shapes(c.shape[:-1], z.shape)).astype(complex)
    for k in range(k_max - 1, -1, -1):  # loop over orders, not over angles
        acc = acc * z + c[..., k]
    return acc.real


def evaluate_series(series, angle):
    """Value of a Fourier series at ``angle``.

    Parameters
    ----------
    series : FourierSeries
        Coefficients [m].
    angle : array_like
        Angle in the ring's own frame. [rad]

    Returns
    -------
    ndarray
        delta X(angle). [m]

    Examples
    --------
    >>> s = fourier_series({0: 1.0, 2: 0.5})
    >>> evaluate_series(s, [0.0, math.pi / 2]).round(12)
    array([1.5, 0.5])
    """
    if series is None:
        return np.zeros(np.shape(angle))[()]
    a = check_finite("angle", angle, "rad")
    return _horner(series.cos, series.sin, a)[()]


def roundness_coefficients(angle, deviation, max_order):
    r"""Fourier coefficients of a measured roundness profile, by least squares.

    Parameters
    ----------
    angle : array_like
        Measurement angles in the ring's own frame (any spacing, at least 2 K + 1 distinct). [rad]
    deviation : array_like
        Measured radius deviation at each angle, positive = larger radius. [m]
    max_order : int
        Highest order K kept. [-]

    Returns
    -------
    FourierSeries
        Orders 0..K; order 0 is the mean deviation.

    Notes
    -----
    Minimises :math:`\sum_j [\delta(\theta_j) - \sum_k a_k \cos k\theta_j + b_k \sin k\theta_j]^2`; for
    N equally spaced samples and K < N/2 this equals the discrete Fourier transform.

    Examples
    --------
    >>> th = np.linspace(0, 2 * np.pi, 36, endpoint=False)
    >>> s = roundness_coefficients(th, 0.3 * np.cos(2 * th) - 0.1 * np.sin(3 * th), 4)
    >>> print(s.cos.round(12) + 0.0, s.sin.round(12) + 0.0)
    [0.  0.  0.3 0.  0. ] [ 0.   0.   0.  -0.1  0. ]
    """
    th = np.ravel(check_finite("angle", angle, "rad"))
    dev = np.ravel(check_finite("deviation", deviation, "m"))
    if th.size != dev.size:
        raise InputError(
            f"deviation must have one value per angle, got {dev.size} values for {th.size} angles"
        )
    k = int(check_integer("max_order", max_order, 0))
    distinct = np.unique(np.round(np.mod(th, 2 * np.pi), 12)).size
    if distinct < 2 * k + 1:
        raise InputError(
            f"max_order must be <= (distinct angles - 1) / 2 = {(distinct - 1) // 2} [-], got {k} "
            f"({distinct} distinct angles)"
        )
    orders = np.arange(k + 1)
    cols = np.concatenate([np.cos(np.outer(th, orders)), np.sin(np.outer(th, orders[1:]))], axis=1)
    coef, *_ = np.linalg.lstsq(cols, dev, rcond=None)
    return FourierSeries(coef[: k + 1], np.concatenate([[0.0], coef[k + 1 :]]))


class RacewayErrors(NamedTuple):
    """Form errors of one raceway, each a :class:`FourierSeries` in the ring's own angle, or None.

    ``radial`` is delta H, ``axial`` delta S, ``groove`` delta rho (spec 003 section 3.1); ``normal`` is
    the normal deviation Delta itself (clearance-positive, no tau dependence), which section 3.1 allows
    instead of or in addition to the three.
    """

    radial: FourierSeries | None = None
    axial: FourierSeries | None = None
    groove: FourierSeries | None = None
    normal: FourierSeries | None = None


class ManufacturingErrors(NamedTuple):
    """All errors of one bearing (spec 003 section 3).

    ``ball_outer_deficit`` and ``ball_inner_deficit`` are Delta r31 and Delta r32 per ball [m] (positive =
    undersize). ``tilt_x`` (alpha, about X1) and ``tilt_y`` (beta, about Y1) [rad] are numbers, a
    :class:`FourierSeries` in the rotation angle psi, or callables of psi.
    """

    outer: RacewayErrors
    inner: RacewayErrors
    ball_outer_deficit: np.ndarray
    ball_inner_deficit: np.ndarray
    tilt_x: float | FourierSeries | Callable = 0.0
    tilt_y: float | FourierSeries | Callable = 0.0


def manufacturing_errors(
    n_balls,
    *,
    outer=None,
    inner=None,
    ball_diameter_deviation=None,
    ball_outer_deficit=None,
    ball_inner_deficit=None,
    tilt_x=0.0,
    tilt_y=0.0,
):
    """Build and check the errors of a bearing with ``n_balls`` balls.

    Parameters
    ----------
    n_balls : int
        Number of balls. [-]
    outer, inner : RacewayErrors, optional
        Raceway errors of the outer (1) and inner (2) ring.
    ball_diameter_deviation : array_like, optional
        delta D per ball, positive = oversize; gives Delta r31 = Delta r32 = -delta D / 2. [m]
    ball_outer_deficit, ball_inner_deficit : array_like, optional
        Delta r31, Delta r32 per ball, positive = undersize (instead of ``ball_diameter_deviation``). [m]
    tilt_x, tilt_y : float, FourierSeries or callable
        alpha and beta, constant or functions of the rotation angle. [rad]

    Returns
    -------
    ManufacturingErrors

    Examples
    --------
    >>> e = manufacturing_errors(3, ball_diameter_deviation=[2e-6, -0.5e-6, 0.25e-6])
    >>> e.ball_outer_deficit * 1e6
    array([-1.   ,  0.25 , -0.125])
    """
    n = int(check_integer("n_balls", n_balls, 1))

    def per_ball(name, value):
        v = np.atleast_1d(check_finite(name, value, "m"))
        if v.shape[-1] != n:
            raise InputError(f"{name} must have one value per ball ({n}), got {v.shape[-1]}")
        return v

    if ball_diameter_deviation is not None:
        if ball_outer_deficit is not None or ball_inner_deficit is not None:
            raise InputError(
                "ball_diameter_deviation: give the diameter deviations or the two deficits, not both"
            )
        dd = per_ball("ball_diameter_deviation", ball_diameter_deviation)
        r31 = r32 = -0.5 * dd
    else:
        zero = np.zeros(n)
        r31 = (
            zero
            if ball_outer_deficit is None
            else per_ball("ball_outer_deficit", ball_outer_deficit)
        )
        r32 = (
            zero
            if ball_inner_deficit is None
            else per_ball("ball_inner_deficit", ball_inner_deficit)
        )
    for name, r in (("outer", outer), ("inner", inner)):
        if r is not None and not isinstance(r, RacewayErrors):
            raise InputError(f"{name} must be a RacewayErrors, got {type(r).__name__}")
    for name, t in (("tilt_x", tilt_x), ("tilt_y", tilt_y)):
        if not (callable(t) or isinstance(t, FourierSeries)):
            check_finite(name, t, "rad")
    return ManufacturingErrors(
        outer or RacewayErrors(), inner or RacewayErrors(), r31, r32, tilt_x, tilt_y
    )


def _tilt(value, psi):
    if isinstance(value, FourierSeries):
        return _horner(value.cos, value.sin, psi)
    if callable(value):
        out = check_finite("tilt", value(np.asarray(psi, float)), "rad")
        return np.broadcast_to(out, np.shape(psi)).astype(float)
    return np.broadcast_to(np.asarray(value, float), np.shape(psi)).astype(float)


def normal_deviation(angle, contact_angle, errors, *, ring):
    r"""Normal deviation of a raceway at (theta, tau), clearance-positive: eqs. (3.1) and (3.2).

    Parameters
    ----------
    angle : array_like
        theta in the ring's own frame. [rad]
    contact_angle : array_like
        tau at which the raceway is touched. [rad]
    errors : RacewayErrors
        The ring's errors.
    ring : {"outer", "inner"}
        Which ring (the signs of delta H and delta S differ).

    Returns
    -------
    ndarray
        Delta_1 or Delta_2; positive when the real surface lies farther from the ball. [m]

    Notes
    -----
    .. math::
        \Delta_1 = \cos\tau\,\delta H_1 + \sin\tau\,\delta S_1 + (1-\cos\tau)\,\delta\rho_1,\qquad
        \Delta_2 = -\cos\tau\,\delta H_2 - \sin\tau\,\delta S_2 + (1-\cos\tau)\,\delta\rho_2

    plus the directly given normal deviation, if any.

    Examples
    --------
    >>> e = RacewayErrors(radial=fourier_series({1: 1e-6}))
    >>> print(f"{normal_deviation(0.0, math.radians(15), e, ring='inner') * 1e6:.6f}")
    -0.965926
    """
    if ring not in ("outer", "inner"):
        raise InputError(f"ring must be one of ['outer', 'inner'], got {ring!r}")
    th = check_finite("angle", angle, "rad")
    tau = check_finite("contact_angle", contact_angle, "rad")
    sign = 1.0 if ring == "outer" else -1.0
    out = np.zeros(np.broadcast_shapes(th.shape, tau.shape))
    if errors.radial is not None:
        out = out + sign * np.cos(tau) * _horner(errors.radial.cos, errors.radial.sin, th)
    if errors.axial is not None:
        out = out + sign * np.sin(tau) * _horner(errors.axial.cos, errors.axial.sin, th)
    if errors.groove is not None:
        out = out + (1.0 - np.cos(tau)) * _horner(errors.groove.cos, errors.groove.sin, th)
    if errors.normal is not None:
        out = out + _horner(errors.normal.cos, errors.normal.sin, th)
    return out[()]


def _combined(errors, tau0, sign):
    """The normal deviation at tau = tau0 as one Fourier series (first approximation: one evaluation)."""
    parts = [
        (errors.radial, sign * math.cos(tau0)),
        (errors.axial, sign * math.sin(tau0)),
        (errors.groove, 1.0 - math.cos(tau0)),
        (errors.normal, 1.0),
    ]
    parts = [(s, w) for s, w in parts if s is not None]
    if not parts:
        return None
    size = max(s.cos.shape[-1] for s, _ in parts)
    lead = np.broadcast_shapes(*[s.cos.shape[:-1] for s, _ in parts])
    cos = np.zeros(lead + (size,))
    sin = np.zeros(lead + (size,))
    for s, w in parts:
        cos[..., : s.cos.shape[-1]] += w * s.cos
        sin[..., : s.sin.shape[-1]] += w * s.sin
    return FourierSeries(cos, sin)


# ============================================================================ one position
def ball_angles(rotation_angle, geometry, *, cage_ratio=None, first_ball_angle=None):
    r"""Azimuth of every ball in the outer-ring frame, eq. (10.1).

    Parameters
    ----------
    rotation_angle : array_like
        psi, rotation of the inner ring about +Z1. [rad]
    geometry : SpindleGeometry
        Gives n, theta^1 and kappa.
    cage_ratio : float, optional
        kappa, cage speed over inner-ring speed (default the geometry's (1 - gamma)/2). [-]
    first_ball_angle : array_like, optional
        theta^1 instead of the geometry's (broadcast against ``rotation_angle``). [rad]

    Returns
    -------
    ndarray
        theta^i(psi) = theta^1 + 2 pi (i - 1)/n + kappa psi, shape ``psi.shape + (n,)``. [rad]

    Examples
    --------
    >>> g = geometry_from_catalog(16, 7.144e-3, 54e-3, 0.53, 0.52, math.radians(15))
    >>> print(f"{math.degrees(ball_angles(math.radians(90), g)[0]):.6f}")
    39.249522
    """
    psi = check_finite("rotation_angle", rotation_angle, "rad")
    kappa = (
        geometry.cage_ratio
        if cage_ratio is None
        else float(check_finite("cage_ratio", cage_ratio, "-"))
    )
    t1 = (
        geometry.first_ball_angle
        if first_ball_angle is None
        else check_finite("first_ball_angle", first_ball_angle, "rad")
    )
    n = geometry.n_balls
    return np.asarray(t1)[..., None] + 2.0 * np.pi * np.arange(n) / n + kappa * psi[..., None]


class Shifts(NamedTuple):
    """Refinement shifts of the contact points, eqs. (9.1)-(9.3); [rad], shape (..., n)."""

    outer_angle_shift: np.ndarray  # d tau1
    inner_angle_shift: np.ndarray  # d tau2
    inner_azimuth_shift: np.ndarray  # d theta2


def _generalized_error(psi, theta, geometry, errors, shifts=None):
    """Delta k (4.1) at ball azimuths theta (..., n) for rotation psi (...); no input checks."""
    tau0 = geometry.contact_angle
    inner_angle = theta - np.asarray(psi)[..., None]
    dk = np.broadcast_to(errors.ball_outer_deficit + errors.ball_inner_deficit, theta.shape).astype(
        float
    )
    if shifts is None:
        for ring, th, sign in (("outer", theta, 1.0), ("inner", inner_angle, -1.0)):
            series = _combined(getattr(errors, ring), tau0, sign)
            if series is not None:
                dk = dk + _horner(series.cos, series.sin, th)
        return dk
    dk = dk + normal_deviation(theta, tau0 + shifts.outer_angle_shift, errors.outer, ring="outer")
    dk = dk + normal_deviation(
        inner_angle + shifts.inner_azimuth_shift,
        tau0 + shifts.inner_angle_shift,
        errors.inner,
        ring="inner",
    )
    return dk


def generalized_error(rotation_angle, geometry, errors, *, cage_ratio=None, shifts=None):
    r"""Generalized error Delta k of every ball, eq. (4.1).

    Parameters
    ----------
    rotation_angle : array_like
        psi. [rad]
    geometry : SpindleGeometry
        Nominal geometry.
    errors : ManufacturingErrors
        Raceway, ball and tilt errors.
    cage_ratio : float, optional
        kappa override. [-]
    shifts : Shifts, optional
        Contact-point shifts of the refinement (default: first approximation, tau = tau0).

    Returns
    -------
    ndarray
        Delta k^i = Delta_1 + Delta_2 + Delta r31 + Delta r32, shape ``psi.shape + (n,)``;
        clearance-positive. [m]

    Notes
    -----
    Outer-ring errors at theta^i, inner-ring errors at the inner ring's own angle theta^i - psi
    (+ d theta2 when refining), ball errors carried by the balls (spec 003 sections 4 and 10).

    Examples
    --------
    >>> g = geometry_from_catalog(16, 7.144e-3, 54e-3, 0.53, 0.52, math.radians(15))
    >>> e = manufacturing_errors(16, inner=RacewayErrors(radial=fourier_series({2: 1e-6})))
    >>> print(f"{generalized_error(0.0, g, e)[0] * 1e6:.6f}")
    -0.965926
    """
    psi = check_finite("rotation_angle", rotation_angle, "rad")
    theta = ball_angles(psi, geometry, cage_ratio=cage_ratio)
    _check_errors(errors, geometry)
    return _generalized_error(psi, theta, geometry, errors, shifts)[()]


def _check_errors(errors, geometry):
    if not isinstance(errors, ManufacturingErrors):
        raise InputError(f"errors must be a ManufacturingErrors, got {type(errors).__name__}")
    for name in ("ball_outer_deficit", "ball_inner_deficit"):
        v = np.asarray(getattr(errors, name))
        if v.shape[-1:] != (geometry.n_balls,):
            raise InputError(
                f"{name} must have one value per ball ({geometry.n_balls}), got shape {v.shape}"
            )


class Sinusoid(NamedTuple):
    """Enveloping sinusoid s(theta) = constant + sine sin(theta) + cosine cos(theta), eq. (5.1). [m]"""

    constant: np.ndarray  # a0
    sine: np.ndarray  # B
    cosine: np.ndarray  # D


class Pose(NamedTuple):
    """Displacement of the inner-ring centre from its nominal position (0, 0, S). [m]"""

    x: np.ndarray  # dx
    y: np.ndarray  # dy
    z: np.ndarray  # dz


def sinusoid_from_pose(x, y, z, geometry, *, tilt_x=0.0, tilt_y=0.0):
    r"""Sinusoid of the reduced bearing for a displaced, tilted inner ring, eq. (5.1).

    Parameters
    ----------
    x, y, z : array_like
        Centre displacement dx, dy, dz. [m]
    geometry : SpindleGeometry
        Nominal geometry.
    tilt_x, tilt_y : array_like
        alpha (about X1) and beta (about Y1). [rad]

    Returns
    -------
    Sinusoid
        a0 = dz sin tau0, B = dy cos tau0 + alpha R_c2 sin tau0, D = dx cos tau0 - beta R_c2 sin tau0. [m]

    Examples
    --------
    >>> g = geometry_from_catalog(16, 7.144e-3, 54e-3, 0.53, 0.52, math.radians(15))
    >>> s = sinusoid_from_pose(0.8e-6, -0.5e-6, 2.0e-6, g, tilt_x=20e-6, tilt_y=-10e-6)
    >>> print(" ".join(f"{v * 1e6:.6f}" for v in s))
    0.517638 -0.342486 0.842979
    """
    x, y, z = (check_finite(n, v, "m") for n, v in (("x", x), ("y", y), ("z", z)))
    a = check_finite("tilt_x", tilt_x, "rad")
    b = check_finite("tilt_y", tilt_y, "rad")
    st, ct, rc = (
        math.sin(geometry.contact_angle),
        math.cos(geometry.contact_angle),
        geometry.inner_centre_radius,
    )
    return Sinusoid((z * st)[()], (y * ct + a * rc * st)[()], (x * ct - b * rc * st)[()])


def pose_from_sinusoid(constant, sine, cosine, geometry, *, tilt_x=0.0, tilt_y=0.0):
    r"""Inner-ring centre displacement from the sinusoid and the prescribed tilt, eq. (5.2).

    Parameters
    ----------
    constant, sine, cosine : array_like
        a0, B, D. [m]
    geometry : SpindleGeometry
        Nominal geometry.
    tilt_x, tilt_y : array_like
        alpha, beta. [rad]

    Returns
    -------
    Pose
        dz = a0 / sin tau0, dx = (D + beta R_c2 sin tau0)/cos tau0, dy = (B - alpha R_c2 sin tau0)/cos tau0. [m]

    Notes
    -----
    The source's eq. 27 loses the signs (``A/sqrt(1 + ctg^2 phi) = A |sin phi|``); this is the corrected form
    (spec 003 section 13.7).

    Examples
    --------
    >>> g = geometry_from_catalog(16, 7.144e-3, 54e-3, 0.53, 0.52, math.radians(15))
    >>> p = pose_from_sinusoid(-1e-6, 0.0, -1e-6, g)
    >>> print(f"{p.x * 1e6:.6f} {p.z * 1e6:.6f}")
    -1.035276 -3.863703
    """
    a0 = check_finite("constant", constant, "m")
    bb = check_finite("sine", sine, "m")
    dd = check_finite("cosine", cosine, "m")
    a = check_finite("tilt_x", tilt_x, "rad")
    b = check_finite("tilt_y", tilt_y, "rad")
    st, ct, rc = (
        math.sin(geometry.contact_angle),
        math.cos(geometry.contact_angle),
        geometry.inner_centre_radius,
    )
    return Pose(((dd + b * rc * st) / ct)[()], ((bb - a * rc * st) / ct)[()], (a0 / st)[()])


def tie_break_centre(geometry, *, tilt_x=0.0, tilt_y=0.0):
    """The point c = (alpha R_c2 sin tau0, -beta R_c2 sin tau0) of the (B, D) plane (section 7.5).

    Among optimal (B, D) the one closest to c gives the smallest lateral displacement dx^2 + dy^2.

    Parameters
    ----------
    geometry : SpindleGeometry
        Nominal geometry.
    tilt_x, tilt_y : array_like
        alpha, beta. [rad]

    Returns
    -------
    tuple of ndarray
        (c_B, c_D). [m]

    Examples
    --------
    >>> g = geometry_from_catalog(16, 7.144e-3, 54e-3, 0.53, 0.52, math.radians(15))
    >>> print([f"{c * 1e6:.6f}" for c in tie_break_centre(g, tilt_x=20e-6, tilt_y=-10e-6)])
    ['0.140477', '0.070238']
    """
    a = check_finite("tilt_x", tilt_x, "rad")
    b = check_finite("tilt_y", tilt_y, "rad")
    k = geometry.inner_centre_radius * math.sin(geometry.contact_angle)
    return (a * k)[()], (-b * k)[()]


class ContactSolution(NamedTuple):
    """Solution of the contact problem (6.1) at one or many positions (leading axes = positions)."""

    constant: np.ndarray  # a0 [m]
    sine: np.ndarray  # B [m]
    cosine: np.ndarray  # D [m]
    amplitude: np.ndarray  # A = sqrt(B^2 + D^2) [m]
    phase: np.ndarray  # phi = atan2(D, B) [rad]
    slack: np.ndarray  # Delta k - s(theta) per ball, >= 0 [m]
    contact: np.ndarray  # ball touches both rings (slack <= 1e-7 um, scaled) [bool]
    load_share: np.ndarray  # dual weights lambda per ball: share of a small axial preload [-]
    degenerate: np.ndarray  # the optimal face is a segment: the ring can slide sideways [bool]
    face_diameter: np.ndarray  # length of that segment in the (B, D) plane [m]


def _check_balls(angles):
    n = angles.shape[-1]
    if n < 3:
        raise InputError(
            f"n_balls must be >= 3 [-], got {n}: with 1 ball a0 is unbounded, with 2 the "
            f"lateral motion perpendicular to the pair is free (spec 003 section 7.1)"
        )
    srt = np.sort(np.mod(angles, 2 * np.pi), axis=-1)
    gaps = np.diff(np.concatenate([srt, srt[..., :1] + 2 * np.pi], axis=-1), axis=-1)
    big = gaps.max(axis=-1)
    bad = big >= np.pi - 1e-12
    if np.any(bad):
        g = float(np.max(big))
        raise InputError(
            f"ball_angle: all balls lie within a closed half-circle (largest gap between "
            f"neighbouring balls {math.degrees(g):.4g} deg >= 180 deg); the inner ring is not held "
            f"and the contact problem (6.1) is unbounded"
        )
    if np.any(gaps < 1e-12):
        raise InputError("ball_angle: two balls have the same azimuth")


def _solve_um(dk_um, theta, cb_um, cd_um, method, tie_break):
    """Solve (6.1) for (P, n) arrays in um; returns a0, B, D, lam, degenerate, diameter (um)."""
    if method == "dual":
        return _contact.solve_dual(dk_um, theta, cb_um, cd_um, tie_break)
    if tie_break != "centre":
        raise InputError(f"tie_break={tie_break!r} is only available with method='dual'")
    if method == "triples":
        a0, b, d, diam = _contact.solve_triples(dk_um, theta, cb_um, cd_um)
    else:
        a0, b, d, diam = _contact.solve_lp(dk_um, theta, cb_um, cd_um)
    # dual weights (load shares) are a by-product of the dual method only: take them from it
    lam = _contact.solve_dual(dk_um, theta, cb_um, cd_um)[3]
    degenerate = diam > RUNOUT_CONTACT_TOL_UM * _contact.scale(dk_um)
    return a0, b, d, lam, degenerate, np.where(degenerate, diam, 0.0)


def _contact_solution(dk, theta, cb, cd, method, tie_break):
    """SI wrapper over flattened positions; returns ContactSolution with the input's leading shape."""
    lead = dk.shape[:-1]
    n = dk.shape[-1]
    theta = np.broadcast_to(theta, dk.shape)
    flat_dk = dk.reshape(-1, n) / _UM
    flat_th = theta.reshape(-1, n)
    cb_um = np.broadcast_to(np.asarray(cb, float), lead).reshape(-1) / _UM
    cd_um = np.broadcast_to(np.asarray(cd, float), lead).reshape(-1) / _UM
    a0, b, d, lam, degenerate, diam = _solve_um(flat_dk, flat_th, cb_um, cd_um, method, tie_break)
    slack_um = flat_dk - a0[:, None]
    slack_um -= b[:, None] * np.sin(flat_th)
    slack_um -= d[:, None] * np.cos(flat_th)
    contact = slack_um <= (RUNOUT_CONTACT_TOL_UM * _contact.scale(flat_dk))[:, None]

    def r(v, extra=()):
        return v.reshape(lead + extra)[()]

    return ContactSolution(
        r(a0 * _UM),
        r(b * _UM),
        r(d * _UM),
        r(np.hypot(b, d) * _UM),
        r(np.arctan2(d, b)),
        r(slack_um * _UM, (n,)),
        r(contact, (n,)),
        r(lam, (n,)),
        r(degenerate),
        r(diam * _UM),
    )


def solve_contact(
    generalized_error, ball_angle, *, centre=(0.0, 0.0), method="dual", tie_break="centre"
):
    r"""Solve the contact problem (6.1): the highest sinusoid on or below all generalized errors.

    Parameters
    ----------
    generalized_error : array_like
        Delta k, shape (..., n); leading axes are independent positions. [m]
    ball_angle : array_like
        theta^i, broadcastable to ``generalized_error``. [rad]
    centre : tuple of array_like
        Tie-break point c = (c_B, c_D) of section 7.5 (see :func:`tie_break_centre`). [m]
    method : {"dual", "triples", "lp"}
        ``"dual"`` (default): exact, vectorized dual-vertex enumeration; ``"triples"``: the primal
        enumeration of section 8.2; ``"lp"``: scipy's HiGHS LP, one position at a time (cross-check).
    tie_break : {"centre", "midpoint"}
        The normative rule (closest to c) or, for comparison only, the midpoint of the face.

    Returns
    -------
    ContactSolution

    Raises
    ------
    InputError
        n < 3, all balls within a closed half-circle (the problem is unbounded), two balls at the same
        azimuth, non-finite input, unknown method.

    Notes
    -----
    maximise a0 subject to a0 + B sin theta^i + D cos theta^i <= Delta k^i (clearance-signed Delta k: the
    sinusoid lies *below* the points and a0 is *maximised*; spec 003 section 13.6). The dual is the
    lowest point, above the origin, of the convex hull of (sin theta^i, cos theta^i, Delta k^i); its
    vertices are the ball triangles that contain the origin and the diametral pairs. A pair makes the
    optimal face a segment ("degenerate"); the tie-break then takes its point closest to c.
    Tolerances (1e-9 um for ties, 1e-7 um for contacts) scale with ``max(1, max |Delta k| / 1 um)``.

    Examples
    --------
    >>> th = 2 * np.pi * np.arange(16) / 16
    >>> dk = np.zeros(16); dk[0] = -2e-6
    >>> s = solve_contact(dk, th)
    >>> print(f"{s.constant * 1e6:.6f} {s.sine * 1e6:.6f} {s.cosine * 1e6:.6f}", np.flatnonzero(s.contact) + 1)
    -1.000000 0.000000 -1.000000 [1 9]
    >>> print(bool(s.degenerate), f"{s.face_diameter * 1e6:.6f}")
    True 0.397825
    """
    if method not in _METHODS:
        raise InputError(f"method must be one of {list(_METHODS)}, got {method!r}")
    if tie_break not in _TIE_BREAKS:
        raise InputError(f"tie_break must be one of {list(_TIE_BREAKS)}, got {tie_break!r}")
    dk = np.atleast_1d(check_finite("generalized_error", generalized_error, "m"))
    th = check_finite("ball_angle", ball_angle, "rad")
    shape = np.broadcast_shapes(dk.shape, th.shape)
    dk = np.broadcast_to(dk, shape)
    th = np.broadcast_to(th, shape)
    flat = th.reshape(-1, shape[-1])
    # equally spaced or rigidly turned ball sets: one row stands for all
    _check_balls(flat[:1] if _contact.same_pattern(flat) else flat)
    cb = check_finite("centre", centre[0], "m")
    cd = check_finite("centre", centre[1], "m")
    return _contact_solution(dk, th, cb, cd, method, tie_break)


def contact_point_shifts(x, y, z, ball_angle, geometry, *, tilt_x=0.0, tilt_y=0.0):
    r"""Shifts of the contact points for the refinement, eqs. (9.1)-(9.3).

    Parameters
    ----------
    x, y, z : array_like
        Pose dx, dy, dz, shape (...). [m]
    ball_angle : array_like
        theta^i, shape (..., n). [rad]
    geometry : SpindleGeometry
        Nominal geometry.
    tilt_x, tilt_y : array_like
        alpha, beta, shape (...). [rad]

    Returns
    -------
    Shifts
        d tau1, d tau2, d theta2 per ball. [rad]

    Notes
    -----
    With m_i = alpha sin theta^i - beta cos theta^i:

    .. math::
        \Delta\tau_1 = [\Delta z\cos\tau_0 - \sin\tau_0(\Delta x\cos\theta + \Delta y\sin\theta)
                        + R_{c2}\cos\tau_0\, m] / A_0, \quad \Delta\tau_2 = \Delta\tau_1 - m,

        \Delta\theta_2 = [\Delta x\sin\theta - \Delta y\cos\theta
                          - (\rho_{20} - r_{30})\sin\tau_0(\alpha\cos\theta + \beta\sin\theta)] / R_b

    (9.1) is the source's eq. 30 with its 2 Delta r33 read as s(theta) (spec 003 section 13.9).

    Examples
    --------
    >>> g = geometry_from_catalog(16, 7.144e-3, 54e-3, 0.53, 0.52, math.radians(15))
    >>> sh = contact_point_shifts(0.0, 0.0, -3.741978e-6, [0.0], g)
    >>> print(f"{sh.outer_angle_shift[0]:.6f}")
    -0.010119
    """
    x, y, z = (
        np.asarray(check_finite(n, v, "m"))[..., None] for n, v in (("x", x), ("y", y), ("z", z))
    )
    th = check_finite("ball_angle", ball_angle, "rad")
    a = np.asarray(check_finite("tilt_x", tilt_x, "rad"))[..., None]
    b = np.asarray(check_finite("tilt_y", tilt_y, "rad"))[..., None]
    st, ct = math.sin(geometry.contact_angle), math.cos(geometry.contact_angle)
    s, c = np.sin(th), np.cos(th)
    m = a * s - b * c
    dt1 = (
        z * ct - st * (x * c + y * s) + geometry.inner_centre_radius * ct * m
    ) / geometry.groove_distance
    dt2 = dt1 - m
    lever = (geometry.inner_groove_radius - geometry.ball_radius) * st
    dth2 = (x * s - y * c - lever * (a * c + b * s)) / geometry.ball_centre_radius
    return Shifts(dt1[()], dt2[()], dth2[()])


class Displacement(NamedTuple):
    """Initial displacement of the inner ring at one or many rotation angles (leading axes)."""

    rotation_angle: np.ndarray  # psi [rad]
    ball_angle: np.ndarray  # theta^i (..., n) [rad]
    generalized_error: np.ndarray  # Delta k (..., n) at the final contact points [m]
    contact: ContactSolution  # the sinusoid, contact set, load shares, degenerate face
    x: np.ndarray  # dx [m]
    y: np.ndarray  # dy [m]
    z: np.ndarray  # dz [m]
    free_play: np.ndarray  # face diameter / cos tau0: sideways travel without changing dz [m]
    tilt_x: np.ndarray  # alpha [rad]
    tilt_y: np.ndarray  # beta [rad]
    passes: np.ndarray  # refinement passes (0 without refinement) [-]
    converged: np.ndarray  # refinement converged (True without refinement) [bool]
    shifts: Shifts  # contact-point shifts used for Delta k (zeros without refinement) [rad]
    first_approximation: Pose  # the pose before refinement [m]
    last_change: (
        np.ndarray
    )  # largest change of (dx, dy, dz) in the last refinement pass (0 without) [m]


def _positions(psi, theta, geometry, errors, *, refine, method, tie_break, tol, max_iter):
    """Solve sections 6-9 at all positions at once. psi (P,), theta (P, n). Returns Displacement."""
    alpha = _tilt(errors.tilt_x, psi)
    beta = _tilt(errors.tilt_y, psi)
    cb, cd = tie_break_centre(geometry, tilt_x=alpha, tilt_y=beta)
    dk = _generalized_error(psi, theta, geometry, errors)
    sol = _contact_solution(dk, theta, cb, cd, method, tie_break)
    pose = pose_from_sinusoid(
        sol.constant, sol.sine, sol.cosine, geometry, tilt_x=alpha, tilt_y=beta
    )
    first = Pose(*(np.asarray(v, float) for v in pose))
    P, n = theta.shape
    zeros = np.zeros((P, n))
    shifts = Shifts(zeros, zeros, zeros)
    passes = np.zeros(P, dtype=int)
    converged = np.ones(P, dtype=bool)
    change = np.zeros(P)
    if refine:
        sol, pose, shifts, dk, passes, converged, change = _refine(
            psi,
            theta,
            geometry,
            errors,
            alpha,
            beta,
            cb,
            cd,
            sol,
            first,
            method,
            tie_break,
            tol,
            max_iter,
        )
    free_play = sol.face_diameter / math.cos(geometry.contact_angle)
    return Displacement(
        psi,
        theta,
        dk,
        sol,
        np.asarray(pose.x, float),
        np.asarray(pose.y, float),
        np.asarray(pose.z, float),
        free_play,
        alpha,
        beta,
        passes,
        converged,
        shifts,
        first,
        change,
    )


def _take(sol, idx):
    return ContactSolution(*(np.asarray(v)[idx] for v in sol))


def _refine(
    psi, theta, geometry, errors, alpha, beta, cb, cd, sol, first, method, tie_break, tol, max_iter
):
    """Iterate shifts -> Delta k -> solve -> pose (section 9) for all positions together.

    A position stops when the largest change of (dx, dy, dz) falls below ``tol``; ``passes`` counts the
    solves after the first approximation, including the one that met the tolerance.
    """
    P, n = theta.shape
    x, y, z = (np.array(v, float, ndmin=1) for v in first)
    fields = [np.array(v, ndmin=1, copy=True) for v in sol]
    dk = np.empty((P, n))
    sh = [np.zeros((P, n)) for _ in range(3)]
    passes = np.zeros(P, dtype=int)
    converged = np.zeros(P, dtype=bool)
    active = np.arange(P)
    change = np.zeros(P)
    for it in range(1, max_iter + 1):
        ia = active
        shifts = contact_point_shifts(
            x[ia], y[ia], z[ia], theta[ia], geometry, tilt_x=alpha[ia], tilt_y=beta[ia]
        )
        k = _generalized_error(psi[ia], theta[ia], geometry, errors, shifts)
        s = _contact_solution(
            k,
            theta[ia],
            cb[ia] if np.ndim(cb) else cb,
            cd[ia] if np.ndim(cd) else cd,
            method,
            tie_break,
        )
        p = pose_from_sinusoid(
            s.constant, s.sine, s.cosine, geometry, tilt_x=alpha[ia], tilt_y=beta[ia]
        )
        change[ia] = np.maximum.reduce(
            [np.abs(p.x - x[ia]), np.abs(p.y - y[ia]), np.abs(p.z - z[ia])]
        )
        x[ia], y[ia], z[ia] = p.x, p.y, p.z
        for f, v in zip(fields, s):
            f[ia] = v
        dk[ia] = k
        for f, v in zip(sh, shifts):
            f[ia] = v
        passes[ia] = it
        done = change[ia] < tol
        converged[ia[done]] = True
        active = ia[~done]
        if active.size == 0:
            break
    return (ContactSolution(*fields), Pose(x, y, z), Shifts(*sh), dk, passes, converged, change)


def initial_displacement(
    rotation_angle,
    geometry,
    errors,
    *,
    refine=False,
    method="dual",
    tie_break="centre",
    cage_ratio=None,
    tol=RUNOUT_REFINE_TOL,
    max_iter=RUNOUT_REFINE_MAX_ITER,
    raise_on_failure=True,
):
    r"""Initial (pre-deformation) displacement of the inner ring at rotation angle(s) psi (sections 4-9).

    Parameters
    ----------
    rotation_angle : array_like
        psi; an array solves all positions in one batch. [rad]
    geometry : SpindleGeometry
        Nominal geometry.
    errors : ManufacturingErrors
        Raceway, ball and tilt errors.
    refine : bool
        Iterate the contact-point shifts of section 9 until the pose changes by less than ``tol``.
    method : {"dual", "triples", "lp"}
        Contact solver (see :func:`solve_contact`).
    tie_break : {"centre", "midpoint"}
        Normative tie-break or the face midpoint (comparison only).
    cage_ratio : float, optional
        kappa override. [-]
    tol : float
        Refinement tolerance on the largest change of dx, dy, dz (spec: 1e-9 um). [m]
    max_iter : int
        Most refinement passes (spec: 30). [-]
    raise_on_failure : bool
        Raise :class:`~bearinglab.errors.ConvergenceError` when a position does not converge; with
        False the ``converged`` flags report it.

    Returns
    -------
    Displacement

    Examples
    --------
    Spec 003 example 2 (inner-raceway ovality of 1 um) at psi = 0:

    >>> g = geometry_from_catalog(16, 7.144e-3, 54e-3, 0.53, 0.52, math.radians(15))
    >>> e = manufacturing_errors(16, inner=RacewayErrors(radial=fourier_series({2: 1e-6})))
    >>> r = initial_displacement(0.0, g, e, refine=True)
    >>> print(f"{r.first_approximation.z * 1e6:.6f} {r.z * 1e6:.6f}")
    -3.732051 -3.741978
    """
    psi = check_finite("rotation_angle", rotation_angle, "rad")
    if method not in _METHODS:
        raise InputError(f"method must be one of {list(_METHODS)}, got {method!r}")
    if tie_break not in _TIE_BREAKS:
        raise InputError(f"tie_break must be one of {list(_TIE_BREAKS)}, got {tie_break!r}")
    check_positive("tol", tol, "m")
    max_iter = int(check_integer("max_iter", max_iter, 1))
    _check_errors(errors, geometry)
    shape = psi.shape
    flat = psi.reshape(-1)
    theta = ball_angles(flat, geometry, cage_ratio=cage_ratio)
    _check_balls(theta[:1])
    r = _positions(
        flat,
        theta,
        geometry,
        errors,
        refine=refine,
        method=method,
        tie_break=tie_break,
        tol=tol,
        max_iter=max_iter,
    )
    if refine and raise_on_failure and not np.all(r.converged):
        bad = np.flatnonzero(~r.converged)
        raise ConvergenceError(
            "runout.initial_displacement (refinement)",
            iterations=max_iter,
            residual=r.last_change[bad],
            estimate=np.stack([r.x[bad], r.y[bad], r.z[bad]], axis=-1),
            reason=f"{bad.size} of {flat.size} positions, first at psi = "
            f"{math.degrees(flat[bad[0]]):.6g} deg",
        )
    return _reshape_displacement(r, shape)


def _reshape_displacement(r, shape):
    n = r.ball_angle.shape[-1]

    def f(v, per_ball=False):
        v = np.asarray(v)
        return v.reshape(shape + ((n,) if per_ball else ()))[()]

    c = r.contact
    contact = ContactSolution(
        f(c.constant),
        f(c.sine),
        f(c.cosine),
        f(c.amplitude),
        f(c.phase),
        f(c.slack, True),
        f(c.contact, True),
        f(c.load_share, True),
        f(c.degenerate),
        f(c.face_diameter),
    )
    return Displacement(
        f(r.rotation_angle),
        f(r.ball_angle, True),
        f(r.generalized_error, True),
        contact,
        f(r.x),
        f(r.y),
        f(r.z),
        f(r.free_play),
        f(r.tilt_x),
        f(r.tilt_y),
        f(r.passes),
        f(r.converged),
        Shifts(*(f(v, True) for v in r.shifts)),
        Pose(*(f(v) for v in r.first_approximation)),
        f(r.last_change),
    )


# ============================================================================ rotation (section 10)
class RunoutMetrics(NamedTuple):
    """Runout metrics of a trajectory (section 10) [m]; arrays when computed per sample."""

    radial_ptp_x: np.ndarray  # max dx - min dx
    radial_ptp_y: np.ndarray  # max dy - min dy
    radial_ptp_max: np.ndarray  # largest peak-to-peak over all radial directions (set diameter)
    axial_ptp: np.ndarray  # max dz - min dz
    dz_mean: np.ndarray  # mean dz


def _diameter(x, y):
    """Largest distance between two points of each trajectory, exactly, in memory-bounded blocks.

    x, y: (S, N) -> (S,).
    """
    S, N = x.shape
    out = np.empty(S)
    block = max(1, int(4e6 // max(N * N, 1)))
    for s in range(0, S, block):  # blocks of trajectories, not single cases
        xs, ys = x[s : s + block], y[s : s + block]
        d2 = (xs[:, :, None] - xs[:, None, :]) ** 2 + (ys[:, :, None] - ys[:, None, :]) ** 2
        out[s : s + block] = np.sqrt(d2.max(axis=(1, 2)))
    return out


def runout_metrics(x, y, z):
    """Runout metrics of centre trajectories (spec 003 section 10).

    Parameters
    ----------
    x, y, z : array_like
        dx, dy, dz along the last axis (positions); leading axes are independent trajectories. [m]

    Returns
    -------
    RunoutMetrics
        radial_ptp_x, radial_ptp_y, radial_ptp_max (the largest distance between two trajectory
        points), axial_ptp, dz_mean. [m]

    Examples
    --------
    >>> t = np.linspace(0, 2 * np.pi, 6, endpoint=False)
    >>> m = runout_metrics(np.cos(t), np.sin(t), 0 * t)
    >>> print(f"{m.radial_ptp_x:.6f} {m.radial_ptp_y:.6f} {m.radial_ptp_max:.6f}")
    2.000000 1.732051 2.000000
    """
    x = np.atleast_1d(check_finite("x", x, "m"))
    y = np.atleast_1d(check_finite("y", y, "m"))
    z = np.atleast_1d(check_finite("z", z, "m"))
    x, y, z = np.broadcast_arrays(x, y, z)
    lead = x.shape[:-1]
    n = x.shape[-1]
    diam = _diameter(x.reshape(-1, n), y.reshape(-1, n)).reshape(lead)
    return RunoutMetrics(
        np.ptp(x, axis=-1)[()],
        np.ptp(y, axis=-1)[()],
        diam[()],
        np.ptp(z, axis=-1)[()],
        z.mean(axis=-1)[()],
    )


def synchronous_part(values, steps_per_revolution):
    """Synchronous part of a signal sampled at equal steps over whole revolutions.

    Parameters
    ----------
    values : array_like
        Samples along the last axis, a whole number of revolutions long.
    steps_per_revolution : int
        Samples per revolution. [-]

    Returns
    -------
    ndarray
        The average at equal psi mod 2 pi over the revolutions, repeated to the input length; the
        asynchronous part is ``values - synchronous_part(values, ...)``.

    Examples
    --------
    >>> synchronous_part([1.0, 2.0, 3.0, 6.0], 2)
    array([2., 4., 2., 4.])
    """
    v = np.atleast_1d(check_finite("values", values, "-"))
    m = int(check_integer("steps_per_revolution", steps_per_revolution, 1))
    if v.shape[-1] % m:
        raise InputError(
            f"values must hold whole revolutions: {v.shape[-1]} samples is not a multiple of "
            f"steps_per_revolution = {m}"
        )
    revs = v.shape[-1] // m
    mean = v.reshape(v.shape[:-1] + (revs, m)).mean(axis=-2)
    return np.tile(mean, (1,) * (v.ndim - 1) + (revs,))


class Trajectory(NamedTuple):
    """Centre trajectory over a rotation sequence and its runout (spec 003 section 10)."""

    rotation_angle: np.ndarray  # psi_k [rad]
    displacement: Displacement  # all positions
    metrics: RunoutMetrics  # of the whole motion [m]
    synchronous: RunoutMetrics  # of the synchronous part [m]
    asynchronous: RunoutMetrics  # of the asynchronous part [m]
    steps_per_revolution: int
    revolutions: int
    cage_ratio: float  # kappa used [-]
    degenerate_fraction: float  # share of positions with a degenerate face [-]


def rotation_sequence(
    geometry,
    errors,
    *,
    revolutions=3,
    steps_per_revolution=360,
    start_angle=0.0,
    cage_ratio=None,
    refine=False,
    method="dual",
    tie_break="centre",
    tol=RUNOUT_REFINE_TOL,
    max_iter=RUNOUT_REFINE_MAX_ITER,
    raise_on_failure=False,
):
    r"""Centre trajectory over inner-ring revolutions with cage kinematics, and its runout (section 10).

    Parameters
    ----------
    geometry : SpindleGeometry
        Nominal geometry.
    errors : ManufacturingErrors
        Raceway, ball and tilt errors.
    revolutions : int
        Number of inner-ring revolutions N_revs. [-]
    steps_per_revolution : int
        N_steps. [-]
    start_angle : float
        psi_start. [rad]
    cage_ratio : float, optional
        kappa override. [-]
    refine : bool
        Refine every position (section 9).
    method, tie_break : str
        As for :func:`solve_contact`.
    tol, max_iter : float, int
        Refinement tolerance [m] and passes [-].
    raise_on_failure : bool
        Raise when a refined position does not converge (default: flag it in ``displacement.converged``).

    Returns
    -------
    Trajectory

    Notes
    -----
    psi_k = psi_start + 2 pi k / N_steps, k = 0 .. N_steps N_revs - 1; all positions are solved as one
    batch. Ball features repeat with the cage (period 2 pi / kappa in psi), inner-ring features every
    2 pi; the synchronous part is the average at equal psi mod 2 pi.

    Examples
    --------
    Spec 003 example 1 (ball 1 oversize by 2 um): the centre runs on a circle of radius 1/cos tau0 um.

    >>> g = geometry_from_catalog(16, 7.144e-3, 54e-3, 0.53, 0.52, math.radians(15))
    >>> e = manufacturing_errors(16, ball_diameter_deviation=np.r_[2e-6, np.zeros(15)])
    >>> t = rotation_sequence(g, e)
    >>> print(f"{t.metrics.radial_ptp_x * 1e6:.6f} {t.metrics.dz_mean * 1e6:.6f}")
    2.070550 -3.863703
    """
    revs = int(check_integer("revolutions", revolutions, 1))
    steps = int(check_integer("steps_per_revolution", steps_per_revolution, 1))
    start = float(check_finite("start_angle", start_angle, "rad"))
    psi = start + 2.0 * np.pi * np.arange(steps * revs) / steps
    kappa = (
        geometry.cage_ratio
        if cage_ratio is None
        else float(check_finite("cage_ratio", cage_ratio, "-"))
    )
    disp = initial_displacement(
        psi,
        geometry,
        errors,
        refine=refine,
        method=method,
        tie_break=tie_break,
        cage_ratio=kappa,
        tol=tol,
        max_iter=max_iter,
        raise_on_failure=raise_on_failure,
    )
    x, y, z = disp.x, disp.y, disp.z
    metrics = runout_metrics(x, y, z)
    sx, sy, sz = (synchronous_part(v, steps) for v in (x, y, z))
    return Trajectory(
        psi,
        disp,
        metrics,
        runout_metrics(sx[:steps], sy[:steps], sz[:steps]),
        runout_metrics(x - sx, y - sy, z - sz),
        steps,
        revs,
        kappa,
        float(np.mean(disp.contact.degenerate)),
    )


class Spectrum(NamedTuple):
    """Amplitude spectrum of the centre motion in orders of shaft speed (cycles per revolution)."""

    order: np.ndarray  # 0, 1/N_revs, 2/N_revs, ... up to the Nyquist order [-]
    radial_forward: np.ndarray  # radius of the forward (with the shaft) whirl component [m]
    radial_backward: np.ndarray  # radius of the backward whirl component [m]
    radial_x: np.ndarray  # amplitude of dx [m]
    radial_y: np.ndarray  # amplitude of dy [m]
    axial: np.ndarray  # amplitude of dz [m]


def runout_spectrum(x, y, z, steps_per_revolution):
    r"""Spectrum of the radial and axial motion of a trajectory sampled over whole revolutions.

    Parameters
    ----------
    x, y, z : array_like
        dx, dy, dz at psi_k = psi_0 + 2 pi k / N_steps. [m]
    steps_per_revolution : int
        N_steps. [-]

    Returns
    -------
    Spectrum
        One-sided amplitudes (the DC line is the mean); the radial motion is also split into forward
        and backward whirl: dx + i dy = sum r_f e^{i f psi} + r_b e^{-i f psi}.

    Examples
    --------
    >>> psi = 2 * np.pi * np.arange(64) / 32
    >>> sp = runout_spectrum(np.cos(3 * psi), np.sin(3 * psi), 0.2 * np.cos(psi), 32)
    >>> print(sp.order[6], sp.radial_forward[6].round(12), sp.radial_backward[6].round(12), sp.axial[2].round(12))
    3.0 1.0 0.0 0.2
    """
    x = np.atleast_1d(check_finite("x", x, "m"))
    y = np.atleast_1d(check_finite("y", y, "m"))
    z = np.atleast_1d(check_finite("z", z, "m"))
    m = int(check_integer("steps_per_revolution", steps_per_revolution, 2))
    npts = x.shape[-1]
    if npts % m:
        raise InputError(
            f"x must hold whole revolutions: {npts} samples is not a multiple of "
            f"steps_per_revolution = {m}"
        )
    revs = npts // m
    half = npts // 2 + 1
    order = np.arange(half) / revs

    def one_sided(v):
        a = np.abs(np.fft.rfft(v, axis=-1)) / npts
        a[..., 1:] *= 2.0
        if npts % 2 == 0:
            a[..., -1] /= 2.0  # the Nyquist line is not doubled
        return a

    w = np.fft.fft(x + 1j * y, axis=-1) / npts
    fwd = np.abs(w[..., :half])
    bwd = np.abs(w[..., (-np.arange(half)) % npts])
    bwd[..., 0] = 0.0  # the mean is counted once, as forward
    if npts % 2 == 0:
        bwd[..., -1] = 0.0  # so is the Nyquist line
    return Spectrum(order, fwd, bwd, one_sided(x), one_sided(y), one_sided(z))


class SpectrumLine(NamedTuple):
    """A line of the runout spectrum and the kinematic combination it belongs to."""

    component: str  # "radial forward", "radial backward" or "axial"
    order: float  # cycles per shaft revolution [-]
    amplitude: float  # [m]
    cage_harmonic: int  # p in p kappa + q
    shaft_harmonic: int  # q in p kappa + q
    source: str  # "cage" (q = 0), "ring" (p = 0, synchronous), "cage+ring" or "unassigned"
    label: str  # e.g. "16κ", "1×", "16κ−1×"


def _label(p, q):
    def term(k, sym):
        if k == 0:
            return ""
        return ("−" if k < 0 else "+") + (f"{abs(k)}" if abs(k) != 1 or sym == "×" else "") + sym

    text = (term(p, "κ") + term(q, "×")).lstrip("+")
    return text or "0"


def spectrum_lines(
    spectrum,
    cage_ratio,
    *,
    threshold=0.02,
    max_cage_harmonic=64,
    max_shaft_harmonic=64,
    max_lines=12,
):
    r"""The main lines of a runout spectrum, each labelled with the combination p kappa + q it sits on.

    Parameters
    ----------
    spectrum : Spectrum
        From :func:`runout_spectrum`.
    cage_ratio : float
        kappa. [-]
    threshold : float
        Lines below this fraction of the largest non-DC amplitude of all components are dropped. [-]
    max_cage_harmonic, max_shaft_harmonic : int
        Largest absolute values of p and q tried. [-]
    max_lines : int
        Most lines per component, largest first. [-]

    Returns
    -------
    tuple of SpectrumLine

    Notes
    -----
    The motion is a function of the cage angle kappa psi and of psi, so its lines lie at p kappa + q.
    Cage lines (q = 0) come from the balls and from the fixed outer ring; ring lines (p = 0) are
    synchronous (inner-ring errors carried round with the shaft); the others mix both. A line is
    assigned to the simplest combination within half the resolution 1/N_revs; with few revolutions
    several combinations can fit and the simplest is taken, so use many revolutions for spectra.

    Examples
    --------
    >>> psi = 2 * np.pi * np.arange(40 * 64) / 64
    >>> sp = runout_spectrum(np.cos(psi), np.sin(psi), 0.1 * np.cos(0.25 * psi), 64)
    >>> [(l.component, l.label, l.source) for l in spectrum_lines(sp, 0.25)]
    [('radial forward', '1×', 'ring'), ('axial', 'κ', 'cage')]
    """
    kappa = float(check_finite("cage_ratio", cage_ratio, "-"))
    order = np.asarray(spectrum.order)
    if order.size < 3:
        return ()
    res = order[1] - order[0]
    p = np.arange(-max_cage_harmonic, max_cage_harmonic + 1)[:, None]
    q = np.arange(-max_shaft_harmonic, max_shaft_harmonic + 1)[None, :]
    comb = p * kappa + q
    cost = np.abs(p) + np.abs(q)
    out = []
    comps = (
        ("radial forward", spectrum.radial_forward),
        ("radial backward", spectrum.radial_backward),
        ("axial", spectrum.axial),
    )
    ref = max(float(np.max(np.asarray(a)[1:], initial=0.0)) for _, a in comps)
    if not ref > 0:
        return ()
    for name, amp in comps:
        a = np.asarray(amp)
        peak = np.zeros(a.size, bool)
        peak[1:-1] = (a[1:-1] >= a[:-2]) & (a[1:-1] >= a[2:])
        peak[-1] = a[-1] >= a[-2]
        peak &= a >= threshold * ref
        peak[0] = False
        idx = np.flatnonzero(peak)
        idx = idx[np.argsort(-a[idx])][:max_lines]
        for i in idx:
            f = order[i]
            ok = (np.abs(comb - f) <= res / 2 + 1e-12) & (comb >= 0)
            if ok.any():
                c = np.where(ok, cost + np.abs(comb - f) / max(res, 1e-12) * 1e-3, np.inf)
                pi, qi = np.unravel_index(c.argmin(), c.shape)
                pp, qq = int(p[pi, 0]), int(q[0, qi])
                src = "cage" if qq == 0 else ("ring" if pp == 0 else "cage+ring")
                out.append(SpectrumLine(name, float(f), float(a[i]), pp, qq, src, _label(pp, qq)))
            else:
                out.append(
                    SpectrumLine(name, float(f), float(a[i]), 0, 0, "unassigned", f"{f:.4g}×")
                )
    return tuple(out)


# ============================================================================ exact geometry
def _rotation(alpha, beta):
    """Rotation matrices for the small-rotation vector (alpha, beta, 0) (Rodrigues), shape (..., 3, 3)."""
    a = np.asarray(alpha, float)
    b = np.asarray(beta, float)
    ang = np.hypot(a, b)
    safe = np.where(ang > 0, ang, 1.0)
    kx, ky = np.where(ang > 0, a / safe, 1.0), np.where(ang > 0, b / safe, 0.0)
    s, c = np.sin(ang), np.cos(ang)
    v = 1.0 - c
    r = np.empty(ang.shape + (3, 3))
    r[..., 0, 0] = c + kx * kx * v
    r[..., 0, 1] = kx * ky * v
    r[..., 0, 2] = ky * s
    r[..., 1, 0] = kx * ky * v
    r[..., 1, 1] = c + ky * ky * v
    r[..., 1, 2] = -kx * s
    r[..., 2, 0] = -ky * s
    r[..., 2, 1] = kx * s
    r[..., 2, 2] = c
    return r


def exact_reduction(
    ball_angle,
    x,
    y,
    z,
    geometry,
    *,
    tilt_x=0.0,
    tilt_y=0.0,
    xtol=RUNOUT_EXACT_XTOL,
    max_iter=RUNOUT_EXACT_MAX_ITER,
):
    r"""s(theta) without linearisation: how much smaller than nominal the largest ideal ball is.

    Parameters
    ----------
    ball_angle : array_like
        Azimuth theta of the ball centre. [rad]
    x, y, z : float
        Inner-ring centre displacement from (0, 0, S). [m]
    geometry : SpindleGeometry
        Nominal geometry.
    tilt_x, tilt_y : float
        Rotation of the inner ring about X1 and Y1 (about its own centre). [rad]
    xtol : float
        Newton step below which the ball-centre position is converged. [m]
    max_iter : int
        Most Newton iterations. [-]

    Returns
    -------
    ndarray
        2 r30 - d, d the diameter of the largest ball with its centre in the half-plane at azimuth theta
        that fits between the ideal outer torus and the displaced, tilted ideal inner torus. [m]

    Raises
    ------
    ConvergenceError
        The Newton iteration on the ball centre did not converge.

    Notes
    -----
    The ball radius that fits at centre C is min(rho10 - d1(C), rho20 - d2(C)), d_r the distance from C
    to the groove-centre circle of ring r. Its maximum over the half-plane has rho10 - d1 = rho20 - d2
    and the in-plane gradients of d1 and d2 opposed (analytic); both conditions are solved by Newton
    (finite-difference Jacobian) for all balls at once. Used to check (5.1): the difference is second order,
    about ``|delta_perp|^2 / (2 A0)`` (spec 003 sections 9 and 15, example 4).

    Examples
    --------
    >>> g = geometry_from_catalog(16, 7.144e-3, 54e-3, 0.53, 0.52, math.radians(15))
    >>> print(f"{exact_reduction(0.0, 0.0, 0.0, 1e-6, g) * 1e6:.6f}")
    0.260124
    """
    th_in = check_finite("ball_angle", ball_angle, "rad")
    th = np.atleast_1d(th_in)
    x, y, z = (float(check_finite(n, v, "m")) for n, v in (("x", x), ("y", y), ("z", z)))
    rot = _rotation(
        float(check_finite("tilt_x", tilt_x, "rad")), float(check_finite("tilt_y", tilt_y, "rad"))
    )
    g = geometry
    o2 = np.array([x, y, g.axial_offset + z])
    a2 = rot @ np.array([0.0, 0.0, 1.0])
    r1c = g.outer_bottom_radius - g.outer_groove_radius
    r2c = g.inner_centre_radius
    st = math.sin(g.contact_angle)
    er = np.stack([np.cos(th), np.sin(th), np.zeros_like(th)], axis=-1)
    ez = np.array([0.0, 0.0, 1.0])

    def dist(c, o, a, rc):
        """Distance from points c to a circle (centre o, unit axis a, radius rc) and its in-plane gradient."""
        w = c - o
        h = w @ a
        q = w - h[..., None] * a
        rho = np.linalg.norm(q, axis=-1)
        d = np.sqrt((rho - rc) ** 2 + h**2)
        grad = (((rho - rc) / rho)[..., None] * q + h[..., None] * a) / d[..., None]
        return d, np.stack([np.sum(grad * er, axis=-1), grad @ ez], axis=-1)

    def residual(u):
        # u = (radial, axial) offsets of the ball centre from its nominal position [m]
        c = er * (g.ball_centre_radius + u[..., :1]) + ez * (
            (g.outer_groove_radius - g.ball_radius) * st + u[..., 1:]
        )
        d1, g1 = dist(c, np.zeros(3), ez, r1c)
        d2, g2 = dist(c, o2, a2, r2c)
        f1, f2 = g.outer_groove_radius - d1, g.inner_groove_radius - d2
        cross = g1[..., 0] * g2[..., 1] - g1[..., 1] * g2[..., 0]  # gradients of f1, f2 opposed
        return np.stack([f1 - f2, cross * g.groove_distance], axis=-1), f1, f2

    u = np.zeros(th.shape + (2,))
    hj = 1e-8  # m, step of the Jacobian of the residual
    for it in range(1, max_iter + 1):
        res, f1, f2 = residual(u)
        jac = np.empty(th.shape + (2, 2))
        for j in range(2):
            du = np.zeros(2)
            du[j] = hj
            jac[..., :, j] = (residual(u + du)[0] - residual(u - du)[0]) / (2 * hj)
        step = np.linalg.solve(jac, res[..., None])[..., 0]
        u = u - step
        if np.all(np.abs(step) < xtol):
            _, f1, f2 = residual(u)
            r = 0.5 * (f1 + f2)
            return (2.0 * (g.ball_radius - r)).reshape(th_in.shape)[()]
    raise ConvergenceError(
        "runout.exact_reduction", iterations=max_iter, residual=res[..., 0], estimate=u
    )


# ============================================================================ Monte Carlo (section 11)
class BallGrade(NamedTuple):
    """An ISO 3290-1 steel-ball grade. [m]"""

    name: str
    single_diameter_variation: float  # V_DWS
    lot_diameter_variation: float  # V_DWL
    source: str


class RingClass(NamedTuple):
    """A ring tolerance-class preset of spec 003 section 11. [m]"""

    name: str
    radial_runout: float  # K_ia, inner ring of the assembled bearing
    axial_runout: float  # S_ia
    waviness_rms: float  # w_rms of orders 2..K_max (an assumption, not a standard value)
    source: str


def tolerance_classes():
    """Ball grades and ring classes of ``data/tolerance_classes.toml``, each with its source.

    Returns
    -------
    tuple of dict
        ``({name: BallGrade}, {name: RingClass})``.

    Examples
    --------
    >>> grades, classes = tolerance_classes()
    >>> print(sorted(classes), f"{grades['G5'].lot_diameter_variation * 1e6:.2f}")
    ['P2', 'P4', 'P5'] 0.25
    """
    ref = resources.files("bearinglab") / "data" / "tolerance_classes.toml"
    doc = tomllib.loads(ref.read_text(encoding="utf-8"))
    unit = _UM
    grades = {
        k: BallGrade(
            k,
            v["single_diameter_variation"] * unit,
            v["lot_diameter_variation"] * unit,
            v["source"],
        )
        for k, v in doc["ball_grades"].items()
    }
    classes = {
        k: RingClass(
            k,
            v["radial_runout"] * unit,
            v["axial_runout"] * unit,
            v["waviness_rms"] * unit,
            v["source"],
        )
        for k, v in doc["ring_classes"].items()
    }
    return grades, classes


def ball_grade(name):
    """An ISO 3290-1 ball grade by name (``"G5"``); the message lists the known ones.

    Parameters
    ----------
    name : str or BallGrade
        Grade name, case-insensitive.

    Returns
    -------
    BallGrade

    Examples
    --------
    >>> print(f"{ball_grade('g10').single_diameter_variation * 1e6:.2f}")
    0.25
    """
    return _tolerance_lookup("ball_grade", name, BallGrade, 0)


def ring_class(name):
    """A ring-class preset by name (``"P4"``); the message lists the known ones.

    Parameters
    ----------
    name : str or RingClass
        Class name, case-insensitive.

    Returns
    -------
    RingClass

    Examples
    --------
    >>> print(f"{ring_class('P4').radial_runout * 1e6:.1f}")
    4.0
    """
    return _tolerance_lookup("ring_class", name, RingClass, 1)


def _tolerance_lookup(param, name, cls, which):
    """``name`` itself if already a ``cls``, else the preset of that name (case-insensitive) in
    ``tolerance_classes()[which]``; the data file is read only when a name is given."""
    if isinstance(name, cls):
        return name
    presets = tolerance_classes()[which]
    key = str(name).upper()
    if key not in presets:
        raise InputError(f"{param} must be one of {list(presets)}, got {name!r}")
    return presets[key]


class MonteCarloSamples(NamedTuple):
    """Per-sample results of a Monte Carlo chunk (arrays over samples)."""

    sample_index: np.ndarray  # global index of each sample [-]
    first_ball_angle: np.ndarray  # theta^1 drawn [rad]
    radial_ptp_x: np.ndarray  # [m]
    radial_ptp_y: np.ndarray  # [m]
    radial_ptp_max: np.ndarray  # [m]
    axial_ptp: np.ndarray  # [m]
    dz_mean: np.ndarray  # [m]
    degenerate_fraction: np.ndarray  # share of degenerate positions [-]


class Summary(NamedTuple):
    """Summary statistics of one per-sample metric. [m]"""

    mean: float
    std: float  # sample standard deviation (ddof = 1)
    median: float
    p95: float  # 95th percentile (linear interpolation)
    max: float


class MonteCarloResult(NamedTuple):
    """A Monte Carlo study: the per-sample metrics and their summary statistics."""

    samples: MonteCarloSamples
    summary: dict  # metric name -> Summary
    ball_grade: BallGrade
    ring_class: RingClass
    seed: int
    steps_per_revolution: int
    revolutions: int
    max_order: int


def _seed(seed):
    """(entropy, spawn-key prefix) of a root seed: a whole number >= 0 or a SeedSequence."""
    if isinstance(seed, np.random.SeedSequence):
        return seed.entropy, tuple(seed.spawn_key)
    if isinstance(seed, (bool, np.bool_)) or not isinstance(seed, (int, np.integer)) or seed < 0:
        raise InputError(
            f"seed must be a whole number >= 0 or a numpy.random.SeedSequence, got {seed!r}"
        )
    return int(seed), ()


def _uniforms(seed, index, count):
    """``count`` uniforms per sample from the sample's own generator.

    Sample i uses ``SeedSequence(entropy, spawn_key=prefix + (i,))``, i.e. the i-th child that
    ``SeedSequence(seed).spawn`` would give, so a sample's numbers do not depend on how the samples are
    split into chunks.
    """
    entropy, prefix = _seed(seed)
    # a loop over samples for the draws only (one generator call each); the physics below is batched
    return np.stack(
        [
            np.random.default_rng(
                np.random.SeedSequence(entropy, spawn_key=prefix + (int(i),))
            ).random(count)
            for i in index
        ]
    ).reshape(len(index), count)


def _sampled_errors(u, n, grade, rings, k_max):
    """Map per-sample uniforms (S, M) to raceway series and ball deficits (section 11)."""
    S = u.shape[0]
    pos = 0

    def take(m):
        nonlocal pos
        out = u[:, pos : pos + m]
        pos += m
        return out

    theta1 = 2 * np.pi * take(1)[:, 0]
    dd = (take(n) - 0.5) * grade.lot_diameter_variation + (
        take(n) - 0.5
    ) * grade.single_diameter_variation
    orders = np.arange(2, k_max + 1)
    c = rings.waviness_rms / math.sqrt(float(np.sum(orders**-2.0))) if k_max >= 2 else 0.0
    sigma = c / orders

    def waviness():
        amp = sigma * np.sqrt(-2.0 * np.log1p(-take(k_max - 1)))  # Rayleigh(sigma_k) by inversion
        ph = 2 * np.pi * take(k_max - 1)
        return amp, ph

    inner = np.zeros((S, k_max + 1), complex)  # a_k - i b_k of A cos(k theta + phi)
    a1 = take(1)[:, 0] * rings.radial_runout / 2
    inner[:, 1] = a1 * np.exp(1j * 2 * np.pi * take(1)[:, 0])
    if k_max >= 2:
        amp, ph = waviness()
        inner[:, 2:] = amp * np.exp(1j * ph)
    wob = np.zeros((S, 2), complex)
    s1 = take(1)[:, 0] * rings.axial_runout / 2
    wob[:, 1] = s1 * np.exp(1j * 2 * np.pi * take(1)[:, 0])
    outer = np.zeros((S, k_max + 1), complex)
    if k_max >= 2:
        amp, ph = waviness()
        outer[:, 2:] = amp * np.exp(1j * ph)
    assert pos == u.shape[1]
    # A cos(k t + phi) = A cos(phi) cos(k t) - A sin(phi) sin(k t): cos = Re, sin = -Im
    series = {
        name: FourierSeries(v.real, -v.imag)
        for name, v in (("inner", inner), ("wobble", wob), ("outer", outer))
    }
    return theta1, dd, series


def _series_on_grid(series, base, rate, psi):
    """Fourier series (S, K+1) at the angles base[s, i] + rate * psi[p], as (S, P, n).

    exp(i k (base + rate psi)) factors into exp(i k base) exp(i k rate psi), so the sum over orders is
    one complex matrix product per sample block instead of an evaluation at every angle.
    """
    k = np.arange(series.cos.shape[-1])
    c = series.cos - 1j * series.sin  # (S, K+1)
    left = c[:, None, :] * np.exp(1j * base[..., None] * k)  # (S, n, K+1)
    right = np.exp(1j * rate * np.outer(k, psi))  # (K+1, P)
    return np.ascontiguousarray(np.swapaxes((left @ right).real, 1, 2))


def _draw_count(n, k_max):
    return 1 + 2 * n + 2 + 2 * max(k_max - 1, 0) + 2 + 2 * max(k_max - 1, 0)


def monte_carlo_chunk(
    geometry,
    grade,
    rings,
    sample_index,
    seed,
    *,
    steps_per_revolution=180,
    revolutions=2,
    max_order=15,
    cage_ratio=None,
):
    r"""Per-sample runout metrics of a chunk of random bearings (spec 003 section 11).

    Parameters
    ----------
    geometry : SpindleGeometry
        Nominal geometry (its first-ball angle is replaced by the random one).
    grade : str or BallGrade
        Ball grade, e.g. ``"G5"``.
    rings : str or RingClass
        Ring-class preset, e.g. ``"P4"``.
    sample_index : array_like of int
        Global indices of the samples of this chunk.
    seed : int or numpy.random.SeedSequence
        Root seed; sample i draws from its own child sequence, so results do not depend on chunking.
    steps_per_revolution, revolutions : int
        Rotation sequence of each sample. [-]
    max_order : int
        K_max, highest waviness order. [-]
    cage_ratio : float, optional
        kappa override. [-]

    Returns
    -------
    MonteCarloSamples

    Notes
    -----
    Per sample (first approximation): theta^1 ~ U(0, 2 pi); ball i: delta D = U(-V_DWL/2, V_DWL/2) +
    U(-V_DWS/2, V_DWS/2), Delta r31 = Delta r32 = -delta D/2; inner delta H2 order 1 with amplitude
    U(0, K_ia/2), orders 2..K_max with Rayleigh(c/k) amplitudes, c = w_rms / sqrt(sum k^-2); inner delta
    S2 order 1 with amplitude U(0, S_ia/2); outer delta H1 orders 2..K_max as for the inner ring; all
    phases uniform. All positions of all samples of the chunk are solved in one batch.

    Examples
    --------
    >>> g = geometry_from_catalog(16, 7.144e-3, 54e-3, 0.53, 0.52, math.radians(15))
    >>> a = monte_carlo_chunk(g, "G5", "P4", [0, 1, 2, 3], 7, steps_per_revolution=36)
    >>> b = monte_carlo_chunk(g, "G5", "P4", [2, 3], 7, steps_per_revolution=36)
    >>> bool(np.array_equal(a.axial_ptp[2:], b.axial_ptp))  # bit for bit
    True
    """
    grade = ball_grade(grade)
    rings = ring_class(rings)
    idx = np.atleast_1d(check_integer("sample_index", sample_index, 0))
    steps = int(check_integer("steps_per_revolution", steps_per_revolution, 1))
    revs = int(check_integer("revolutions", revolutions, 1))
    k_max = int(check_integer("max_order", max_order, 1))
    kappa = (
        geometry.cage_ratio
        if cage_ratio is None
        else float(check_finite("cage_ratio", cage_ratio, "-"))
    )
    n = geometry.n_balls
    if idx.size == 0:
        empty = np.zeros(0)
        return MonteCarloSamples(idx, *(empty,) * 7)
    u = _uniforms(seed, idx, _draw_count(n, k_max))
    theta1, dd, series = _sampled_errors(u, n, grade, rings, k_max)
    S = idx.size
    psi = 2.0 * np.pi * np.arange(steps * revs) / steps
    theta = (
        theta1[:, None, None] + 2.0 * np.pi * np.arange(n) / n + kappa * psi[None, :, None]
    )  # (S, P, n)
    tau0 = geometry.contact_angle
    ct, st = math.cos(tau0), math.sin(tau0)
    base = theta1[:, None] + 2.0 * np.pi * np.arange(n) / n  # (S, n): ball azimuths at psi = 0
    # outer errors at theta = base + kappa psi, inner errors at theta - psi = base + (kappa - 1) psi
    dk = -ct * _series_on_grid(series["inner"], base, kappa - 1.0, psi)
    dk -= st * _series_on_grid(series["wobble"], base, kappa - 1.0, psi)
    dk += ct * _series_on_grid(series["outer"], base, kappa, psi)
    dk += (-dd)[:, None, :]  # Delta r31 + Delta r32 = -delta D
    P = psi.size
    a0, b, d, _lam, degenerate, _diam = _contact.solve_dual(
        dk.reshape(S * P, n) / _UM, theta.reshape(S * P, n), 0.0, 0.0
    )
    pose = pose_from_sinusoid(a0 * _UM, b * _UM, d * _UM, geometry)
    m = runout_metrics(*(np.asarray(v).reshape(S, P) for v in pose))
    return MonteCarloSamples(
        idx, theta1, *(np.atleast_1d(v) for v in m), degenerate.reshape(S, P).mean(axis=1)
    )


def summarize(values):
    """Mean, standard deviation (ddof = 1), median, 95th percentile and maximum.

    Parameters
    ----------
    values : array_like
        Per-sample values of one metric.

    Returns
    -------
    Summary

    Examples
    --------
    >>> print(" ".join(f"{v:.4f}" for v in summarize([1.0, 2.0, 3.0, 4.0])))
    2.5000 1.2910 2.5000 3.8500 4.0000
    """
    v = np.ravel(check_finite("values", values, "-"))
    if v.size < 2:
        raise InputError(
            f"values must hold at least 2 samples for a standard deviation, got {v.size}"
        )
    return Summary(
        float(v.mean()),
        float(v.std(ddof=1)),
        float(np.median(v)),
        float(np.percentile(v, 95)),
        float(v.max()),
    )


def _monte_carlo_task(sample_index, geometry, grade, rings, seed, **options):
    """:func:`monte_carlo_chunk` as a mapping of per-sample arrays (the chunk function of the execution layer)."""
    return monte_carlo_chunk(geometry, grade, rings, sample_index, seed, **options)._asdict()


def monte_carlo(
    geometry,
    grade,
    rings,
    n_samples,
    seed,
    *,
    steps_per_revolution=180,
    revolutions=2,
    max_order=15,
    cage_ratio=None,
    chunk_size=100,
    progress=None,
    executor="serial",
    workers=None,
    memory_limit=None,
    processes=True,
):
    """Monte Carlo runout study over a ball grade and a ring class (spec 003 section 11).

    Parameters
    ----------
    geometry : SpindleGeometry
        Nominal geometry.
    grade : str or BallGrade
        Ball grade (``"G3"`` ... ``"G40"``).
    rings : str or RingClass
        Ring class (``"P5"``, ``"P4"``, ``"P2"``).
    n_samples : int
        Number of random bearings, >= 2. [-]
    seed : int or numpy.random.SeedSequence
        Root seed; the result is reproducible and independent of ``chunk_size``.
    steps_per_revolution, revolutions : int
        Rotation sequence of each sample (spec: 180 and 2). [-]
    max_order : int
        K_max (spec: 15). [-]
    cage_ratio : float, optional
        kappa override. [-]
    chunk_size : int
        Samples solved per batch (memory: about 3 kB per sample and position). [-]
    progress : callable or "dask", optional
        Called as ``progress(done, total)`` after each chunk, or ``"dask"`` for dask's progress bar.
    executor : str, optional
        ``"serial"`` (default), ``"local"`` (a dask LocalCluster for this study) or a scheduler address
        ``"tcp://host:8786"`` (:mod:`bearinglab.parallel`). Each sample has its own seed, so the result
        is the same on every executor and for every chunk size.
    workers : int, optional
        Workers of the local cluster. [-]
    memory_limit : str, optional
        Memory limit per local worker, e.g. ``"4GiB"``.
    processes : bool, optional
        Local workers as processes (default) or threads.

    Returns
    -------
    MonteCarloResult

    Examples
    --------
    >>> g = geometry_from_catalog(16, 7.144e-3, 54e-3, 0.53, 0.52, math.radians(15))
    >>> r = monte_carlo(g, "G5", "P4", 8, 1, steps_per_revolution=36)
    >>> sorted(r.summary)
    ['axial_ptp', 'dz_mean', 'radial_ptp_max', 'radial_ptp_x', 'radial_ptp_y']
    """
    total = int(check_integer("n_samples", n_samples, 2))
    _seed(seed)
    chunk = int(check_integer("chunk_size", chunk_size, 1))
    grade = ball_grade(grade)
    rings = ring_class(rings)
    # chunks of samples, each one batch, run by the execution layer (serial or on dask)
    fields = parallel.run_cases(
        _monte_carlo_task,
        {"sample_index": np.arange(total)},
        constants={
            "geometry": geometry,
            "grade": grade,
            "rings": rings,
            "seed": seed,
            "steps_per_revolution": steps_per_revolution,
            "revolutions": revolutions,
            "max_order": max_order,
            "cage_ratio": cage_ratio,
        },
        chunk_size=chunk,
        executor=executor,
        workers=workers,
        memory_limit=memory_limit,
        processes=processes,
        progress=progress,
    )
    samples = MonteCarloSamples(**fields)
    summary = {name: summarize(getattr(samples, name)) for name in METRICS}
    seed_out = _seed(seed)[0]
    return MonteCarloResult(
        samples,
        summary,
        grade,
        rings,
        seed_out,
        int(steps_per_revolution),
        int(revolutions),
        int(max_order),
    )


# ============================================================================ files
def load_error_file(path, geometry=None):
    """Read a TOML error file (format: ``examples/runout/README.md``).

    Parameters
    ----------
    path : str or Path
        The file; it is never modified.
    geometry : SpindleGeometry, optional
        Use this geometry instead of the file's ``[geometry]`` table (which is then optional).

    Returns
    -------
    tuple
        ``(geometry, errors)``: a SpindleGeometry and a ManufacturingErrors.

    Raises
    ------
    CatalogError
        Naming the file, the table and the key of a bad entry.
    """
    from . import _runout_io  # reads quantities with units (pint), so imported on use

    return _runout_io.read_error_file(path, geometry)

r"""The inner ring at one position (spec 003 sections 4-9): generalized errors, the contact problem, the pose.

The method of spec 003 (a rigid, pre-deformation model, first order in the errors): raceway form
errors, ball-size scatter and a prescribed ring tilt push the inner ring off its nominal position; the
ring rests on the two or three balls of the lowest enveloping sinusoid of the generalized errors.

Balls and generalized errors (sections 4, 10)
---------------------------------------------
ball_angles             ball azimuths over rotation, eq. (10.1)
generalized_error       Delta k of every ball, eq. (4.1)

Reduced bearing (section 5)
---------------------------
Sinusoid, Pose          the enveloping sinusoid (a0, B, D) and the centre displacement (dx, dy, dz)
sinusoid_from_pose      (a0, B, D) of a displaced, tilted ring, eq. (5.1)
pose_from_sinusoid      (dx, dy, dz) from (a0, B, D) and the tilt, eq. (5.2)

Contact problem (sections 6-8)
------------------------------
tie_break_centre        the point c of the normative tie-break, section 7.5
solve_contact           the contact problem (6.1): a0, B, D, contact set, load shares, degenerate face

Refinement and the whole position (section 9)
---------------------------------------------
contact_point_shifts    refinement shifts d tau1, d tau2, d theta2, eqs. (9.1)-(9.3)
initial_displacement    all of it at one or many rotation angles, optionally refined
MAX_BALL_POSITIONS      the most positions x balls of one call (memory is linear in both)

The solvers of (6.1) themselves, in micrometres, are in the private module ``_solver``.
Units: SI (m, rad); the spec states its tolerances in micrometres and the solvers scale them.
"""

from __future__ import annotations

import math
import warnings
from typing import NamedTuple

import numpy as np

from .. import _bounds
from .._solve import RUNOUT_CONTACT_TOL_UM, RUNOUT_REFINE_MAX_ITER, RUNOUT_REFINE_TOL, use_compiled
from .._validate import check_finite, check_integer, check_positive
from ..errors import ConvergenceError, InputError, ValidityWarning
from . import _solver, plausibility
from .deviations import ManufacturingErrors, _combined, _horner, _tilt, normal_deviation

__all__ = [
    "MAX_BALL_POSITIONS",
    "ContactSolution",
    "Displacement",
    "Pose",
    "Shifts",
    "Sinusoid",
    "ball_angles",
    "contact_point_shifts",
    "generalized_error",
    "initial_displacement",
    "pose_from_sinusoid",
    "sinusoid_from_pose",
    "solve_contact",
    "tie_break_centre",
]

_UM = 1e-6  # m per um: the contact solver works in um, the unit of the spec's tolerances
#: Most ball-positions (positions x balls) of one :func:`initial_displacement`: memory is linear in both,
#: about 144 bytes a ball-position for the result and the solver's blocks (2.3 kB a position at 16 balls,
#: bearinglab._bounds), so 16 x 10^6 (the 10^6 positions of ``_bounds.MAX_POSITIONS`` at 16 balls) hold
#: about 2.3 GB whatever the number of balls: 16 000 positions of a 1000-ball bearing.
MAX_BALL_POSITIONS = 16 * _bounds.MAX_POSITIONS
_METHODS = ("dual", "triples", "lp")
_TIE_BREAKS = ("centre", "midpoint")


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
    >>> from bearinglab.runout import geometry_from_catalog
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
    >>> from bearinglab.runout import (RacewayErrors, fourier_series, geometry_from_catalog,
    ...                                manufacturing_errors)
    >>> g = geometry_from_catalog(16, 7.144e-3, 54e-3, 0.53, 0.52, math.radians(15))
    >>> e = manufacturing_errors(16, inner=RacewayErrors(radial=fourier_series({2: 1e-6})))
    >>> print(f"{generalized_error(0.0, g, e)[0] * 1e6:.6f}")
    -0.965926
    """
    psi = check_finite("rotation_angle", rotation_angle, "rad")
    theta = ball_angles(psi, geometry, cage_ratio=cage_ratio)
    _check_errors(errors, geometry)
    return _generalized_error(psi, theta, geometry, errors, shifts)[()]


def _check_size(positions, n_balls):
    """Refuse a call whose arrays would exceed :data:`MAX_BALL_POSITIONS`, before they are allocated."""
    if positions * n_balls > MAX_BALL_POSITIONS:
        raise InputError(
            f"rotation_angle: {positions} positions x {n_balls} balls = {positions * n_balls} ball-positions "
            f"is more than bearinglab's limit of {MAX_BALL_POSITIONS} (about 144 bytes each): use at most "
            f"{MAX_BALL_POSITIONS // n_balls} positions for {n_balls} balls (fewer steps or revolutions)"
        )


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
    >>> from bearinglab.runout import geometry_from_catalog
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
    >>> from bearinglab.runout import geometry_from_catalog
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
    >>> from bearinglab.runout import geometry_from_catalog
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
            f"lateral motion perpendicular to the pair is free"
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


def _engine(engine, method):
    """"compiled" or "numpy": the engine that solves the contact problem (the compiled walk implements the
    dual method; engine "auto" takes it whenever numba is installed, whatever the size of the batch, so that
    a position gives the same bits alone or in any batch)."""
    if engine == "compiled" and method != "dual":
        raise InputError(f"engine='compiled' implements method='dual' only, got method={method!r}")
    return "compiled" if use_compiled(engine, auto=method == "dual") else "numpy"


def _kernel(engine):
    """The compiled contact solver for engine "compiled", else None (numba is imported only then)."""
    if engine != "compiled":
        return None
    from . import _compiled  # imports numba: only when the compiled path runs

    return _compiled.solve


def _solve_um(dk_um, theta, cb_um, cd_um, method, tie_break, engine="numpy"):
    """Solve (6.1) for (P, n) arrays in um; returns a0, B, D, lam, degenerate, diameter (um)."""
    if method == "dual":
        return _solver.solve_dual(dk_um, theta, cb_um, cd_um, tie_break, _kernel(engine))
    if tie_break != "centre":
        raise InputError(f"tie_break={tie_break!r} is only available with method='dual'")
    if method == "triples":
        a0, b, d, diam = _solver.solve_triples(dk_um, theta, cb_um, cd_um)
    else:
        a0, b, d, diam = _solver.solve_lp(dk_um, theta, cb_um, cd_um)
    # dual weights (load shares) are a by-product of the dual method only: take them from it
    lam = _solver.solve_dual(dk_um, theta, cb_um, cd_um, kernel=_kernel(engine))[3]
    degenerate = diam > RUNOUT_CONTACT_TOL_UM * _solver.scale(dk_um)
    return a0, b, d, lam, degenerate, np.where(degenerate, diam, 0.0)


def _contact_solution(dk, theta, cb, cd, method, tie_break, engine="numpy", *, dk_um=None, solved=None):
    """SI wrapper over flattened positions; returns ContactSolution with the input's leading shape.

    ``dk_um`` and ``solved`` (a0, B, D, lam, degenerate, diameter in um) are given when the compiled
    rotation-sequence kernel has already computed them; the slacks and contacts are computed here alike.
    """
    lead = dk.shape[:-1]
    n = dk.shape[-1]
    theta = np.broadcast_to(theta, dk.shape)
    flat_dk = dk.reshape(-1, n) / _UM if dk_um is None else dk_um.reshape(-1, n)
    flat_th = theta.reshape(-1, n)
    cb_um = np.broadcast_to(np.asarray(cb, float), lead).reshape(-1) / _UM
    cd_um = np.broadcast_to(np.asarray(cd, float), lead).reshape(-1) / _UM
    if solved is None:
        solved = _solve_um(flat_dk, flat_th, cb_um, cd_um, method, tie_break, engine)
    a0, b, d, lam, degenerate, diam = solved
    slack_um = flat_dk - a0[:, None]
    slack_um -= b[:, None] * np.sin(flat_th)
    slack_um -= d[:, None] * np.cos(flat_th)
    contact = slack_um <= (RUNOUT_CONTACT_TOL_UM * _solver.scale(flat_dk))[:, None]

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
    generalized_error,
    ball_angle,
    *,
    centre=(0.0, 0.0),
    method="dual",
    tie_break="centre",
    engine="auto",
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
    engine : {"auto", "numpy", "compiled"}
        ``"compiled"``: the numba kernel of the dual method (:mod:`bearinglab.runout._compiled`);
        ``"numpy"``: the same method vectorized over positions; ``"auto"`` (default): compiled for
        ``method="dual"`` when numba is installed. One engine gives the same bits for a position alone or
        in any batch; the two agree to rounding.

    Returns
    -------
    ContactSolution

    Raises
    ------
    InputError
        n < 3, all balls within a closed half-circle (the problem is unbounded), two balls at the same
        azimuth, non-finite input, unknown method or engine, ``method="triples"`` with more than 64 balls.
    ConvergenceError
        The dual walk did not end (never seen: it takes a few pivots).

    Notes
    -----
    maximise a0 subject to a0 + B sin theta^i + D cos theta^i <= Delta k^i (clearance-signed Delta k: the
    sinusoid lies *below* the points and a0 is *maximised*; spec 003 section 13.6). The dual is the
    lowest point, above the origin, of the convex hull of (sin theta^i, cos theta^i, Delta k^i); its
    vertices are the ball triangles that contain the origin and the diametral pairs. The dual method walks
    from triangle to lower triangle (the simplex method on the dual: a few pivots of O(n) each, memory
    O(n) per position, any number of balls). A pair makes the optimal face a segment ("degenerate"); the
    tie-break then takes its point closest to c.
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
    engine = _engine(engine, method)
    dk = np.atleast_1d(check_finite("generalized_error", generalized_error, "m"))
    th = check_finite("ball_angle", ball_angle, "rad")
    shape = np.broadcast_shapes(dk.shape, th.shape)
    dk = np.broadcast_to(dk, shape)
    th = np.broadcast_to(th, shape)
    flat = th.reshape(-1, shape[-1])
    # equally spaced or rigidly turned ball sets: one row stands for all
    _check_balls(flat[:1] if _solver.same_pattern(flat) else flat)
    cb = check_finite("centre", centre[0], "m")
    cd = check_finite("centre", centre[1], "m")
    return _contact_solution(dk, th, cb, cd, method, tie_break, engine)


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
    >>> from bearinglab.runout import geometry_from_catalog
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


def _first_approximation(psi, theta, geometry, errors, cb, cd, method, tie_break, engine, kappa):
    """Delta k (4.1) at tau = tau0 and the solution of (6.1) at every position: (dk [m], ContactSolution).

    The compiled engine computes both in one kernel (:func:`bearinglab.runout._compiled.sequences`), the
    one the Monte Carlo runs, so that a sample's rotation sequence gives the study's bits.
    """
    if engine != "compiled" or any(
        np.ndim(v) > 1 for v in (errors.ball_outer_deficit, errors.ball_inner_deficit)
    ):
        dk = _generalized_error(psi, theta, geometry, errors)
        return dk, _contact_solution(dk, theta, cb, cd, method, tie_break, engine)
    tau0 = geometry.contact_angle
    rings = (_combined(errors.outer, tau0, 1.0), _combined(errors.inner, tau0, -1.0))
    if any(r is not None and np.ndim(r.cos) > 1 for r in rings):  # series per position: numpy's Horner
        dk = _generalized_error(psi, theta, geometry, errors)
        return dk, _contact_solution(dk, theta, cb, cd, method, tie_break, engine)
    from . import _compiled  # imports numba: only when the compiled path runs

    series = [None if r is None else (r.cos / _UM, r.sin / _UM) for r in rings]
    deficit = (errors.ball_outer_deficit + errors.ball_inner_deficit) / _UM
    P = psi.size
    cb_um, cd_um = (np.broadcast_to(np.asarray(v, float), (P,)) / _UM for v in (cb, cd))
    a0, b, d, deg, diam, status, dk_um, lam = _compiled.sequences(
        geometry.first_ball_angle, kappa, psi, *series, deficit, cb_um, cd_um, tie_break == "midpoint", True
    )
    _solver.check_status(status, dk_um, theta.shape[-1])
    dk = dk_um * _UM
    solved = (a0[0], b[0], d[0], lam, deg[0], diam[0])
    sol = _contact_solution(dk, theta, cb, cd, method, tie_break, engine, dk_um=dk_um, solved=solved)
    return dk, sol


def _positions(psi, theta, geometry, errors, *, refine, method, tie_break, tol, max_iter, engine, kappa):
    """Solve sections 6-9 at all positions at once. psi (P,), theta (P, n). Returns Displacement."""
    alpha = _tilt(errors.tilt_x, psi)
    beta = _tilt(errors.tilt_y, psi)
    cb, cd = tie_break_centre(geometry, tilt_x=alpha, tilt_y=beta)
    dk, sol = _first_approximation(psi, theta, geometry, errors, cb, cd, method, tie_break, engine, kappa)
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
            engine,
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
    psi, theta, geometry, errors, alpha, beta, cb, cd, sol, first, method, tie_break, tol, max_iter, engine
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
            engine,
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
    engine="auto",
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
    engine : {"auto", "numpy", "compiled"}
        As for :func:`solve_contact`. The compiled engine computes the generalized errors of the first
        approximation and the contact problem in one kernel, the one of the Monte Carlo
        (:func:`~bearinglab.runout.monte_carlo_chunk`), so that with one engine a sample's rotation
        sequence gives the study's bits. The engines agree to rounding.

    Returns
    -------
    Displacement

    Raises
    ------
    InputError
        Errors no bearing can have: one of 5 % of the ball diameter or more, or a tilt beyond 2 pi
        (:func:`bearinglab.runout.plausibility.check_errors`).

    Warns
    -----
    ValidityWarning
        Displacements (or tilts) of 5 % of the groove distance A0 or more, beyond the range of the
        first-order model (:mod:`bearinglab.runout.plausibility`).

    Examples
    --------
    Spec 003 example 2 (inner-raceway ovality of 1 um) at psi = 0:

    >>> from bearinglab.runout import (RacewayErrors, fourier_series, geometry_from_catalog,
    ...                                manufacturing_errors)
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
    engine = _engine(engine, method)
    _check_errors(errors, geometry)
    shape = psi.shape
    flat = psi.reshape(-1)
    _check_size(flat.size, geometry.n_balls)
    doubtful = plausibility.check_errors(geometry, errors, flat)  # refuses the absurd (issue 20 item 8)
    theta = ball_angles(flat, geometry, cage_ratio=cage_ratio)
    _check_balls(theta[:1])
    kappa = geometry.cage_ratio if cage_ratio is None else float(cage_ratio)
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
        engine=engine,
        kappa=kappa,
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
    doubtful += plausibility.displacement_warnings(geometry, r.x, r.y, r.z)
    for msg in doubtful:
        warnings.warn(msg, ValidityWarning, stacklevel=2)
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

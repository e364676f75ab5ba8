r"""The runout reduction without linearisation (spec 003 sections 9 and 15, example 4).

Exact geometry
--------------
exact_reduction         s(theta) exactly: how much smaller than nominal the largest ideal ball between
                        the ideal outer torus and the displaced, tilted ideal inner torus is

Used to check the first-order reduction (5.1) of :mod:`bearinglab.runout.contact`.
Units: SI (m, rad).
"""

from __future__ import annotations

import math

import numpy as np

from .._solve import RUNOUT_EXACT_MAX_ITER, RUNOUT_EXACT_XTOL
from .._validate import check_finite
from ..errors import ConvergenceError

__all__ = ["exact_reduction"]


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
    >>> from bearinglab.runout import geometry_from_catalog
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
        try:
            step = np.linalg.solve(jac, res[..., None])[..., 0]
        except np.linalg.LinAlgError:  # no ball fits: the ring displaced by more than the gaps (x = 1 m)
            raise ConvergenceError("runout.exact_reduction", iterations=it, residual=res[..., 0], estimate=u,
                                   reason="no ball fits between the rings at this displacement (the Jacobian "
                                          "of the ball centre is singular)", physical=True) from None
        u = u - step
        if np.all(np.abs(step) < xtol):
            _, f1, f2 = residual(u)
            r = 0.5 * (f1 + f2)
            return (2.0 * (g.ball_radius - r)).reshape(th_in.shape)[()]
    raise ConvergenceError(
        "runout.exact_reduction", iterations=max_iter, residual=res[..., 0], estimate=u
    )

r"""Manufacturing errors of a spindle bearing (spec 003 section 3): Fourier series, ring and ball errors.

Fourier series
--------------
FourierSeries           cos/sin coefficients of one error function, by order [m]
fourier_series          build one from ``{order: value}`` mappings or arrays
evaluate_series         sum of a Fourier series at angles
roundness_coefficients  Fourier coefficients of a measured roundness profile (least squares)

Ring and ball errors
--------------------
RacewayErrors           delta-H, delta-S, delta-rho (and optionally the normal deviation) of one ring
ManufacturingErrors     both rings, the balls, the tilt
manufacturing_errors    build and check a ManufacturingErrors
normal_deviation        Delta_1, Delta_2 at a contact point, eqs. (3.1) and (3.2)

Units: SI (m, rad).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import NamedTuple

import numpy as np

from .._validate import check_finite, check_integer
from ..errors import InputError

__all__ = [
    "FourierSeries",
    "ManufacturingErrors",
    "RacewayErrors",
    "evaluate_series",
    "fourier_series",
    "manufacturing_errors",
    "normal_deviation",
    "roundness_coefficients",
]


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


_HORNER_BLOCK = (
    32768  # elements per block of the Horner sums (the complex temporaries stay in cache)
)


def _horner(cos, sin, angle):
    """sum_k cos_k cos(k a) + sin_k sin(k a) by Horner's rule in z = exp(i a) (no loop over angles).

    cos/sin: (..., K+1) broadcastable against angle[..., None] without the last axis. Every element is
    computed by the same operations in the same order whatever the shape and blocking (element-wise
    ufuncs only, no BLAS), so a value does not depend on the batch it is computed in.
    """
    c = np.asarray(cos, float) - 1j * np.asarray(sin, float)
    a = np.asarray(angle, float)
    shape = np.broadcast_shapes(c.shape[:-1], a.shape)
    if not shape:
        return _horner_block(c, a)
    c = np.broadcast_to(c, shape + c.shape[-1:])
    a = np.broadcast_to(a, shape)
    out = np.empty(shape)
    step = max(1, _HORNER_BLOCK // max(1, math.prod(shape[1:])))
    for i in range(0, shape[0], step):  # blocks of the leading axis, not single elements
        out[i : i + step] = _horner_block(c[i : i + step], a[i : i + step])
    return out


def _horner_block(c, a):
    z = np.exp(1j * a)
    acc = np.empty(np.broadcast_shapes(c.shape[:-1], z.shape), complex)
    acc[...] = c[..., -1]
    for k in range(c.shape[-1] - 2, -1, -1):  # loop over orders, in place
        acc *= z
        acc += c[..., k]
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

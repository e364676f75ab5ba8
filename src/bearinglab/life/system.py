r"""The life of a system of bearings: the life at which the first of them fails, at a reliability.

Functions
---------
weibull_slope   the Weibull slope e of a bearing type: 10/9 for ball, 9/8 for roller bearings
system_life     the system's life from its bearings' lives (all at one reliability)

Every bearing's life L_i is the life that a fraction S (90 % for L10) of such bearings reaches, and the
lives scatter as Weibull distributions of slope e_i, S_i(L) = S^((L / L_i)^e_i). A system works while all
of its bearings do, S_sys(L) = prod_i S_i(L), so its life at the same reliability S solves

.. math::

   \sum_i (L / L_i)^{e_i} = 1, \qquad L = \Big(\sum_i L_i^{-e}\Big)^{-1/e} \text{ for one slope } e,

Lundberg and Palmgren's rule [1]_, as Harris and Kotzalas [2]_ give it for a set of bearings, with the
slopes of ISO 281 (10/9 for ball, 9/8 for roller bearings [3]_). It holds for any life of the same
reliability: L10, L_nm, L10r or the Palmgren-Miner life of a duty cycle.

References
----------
.. [1] G. Lundberg and A. Palmgren, "Dynamic capacity of rolling bearings," Acta Polytechnica,
   Mechanical Engineering Series, vol. 1, no. 3, 1947 (the Weibull dispersion of bearing lives, e = 10/9
   for point and 9/8 for line contact).
.. [2] T. A. Harris and M. N. Kotzalas, *Essential Concepts of Bearing Technology*, 5th ed., CRC Press,
   2006, ch. 11 ("Fatigue life: basic theory and rating standards"), the life of a bearing system.
.. [3] ISO/TR 1281-1:2008, Rolling bearings - Explanatory notes on ISO 281 - Part 1: Basic dynamic load
   rating and basic rating life, clause 5 (the Weibull slopes 10/9 and 9/8 behind the ratings and a1).
"""

from __future__ import annotations

import numpy as np

from .._validate import as_float
from ..errors import InputError

__all__ = ["BALL_SLOPE", "ROLLER_SLOPE", "system_life", "weibull_slope"]

#: Weibull slope of ball bearings (point contact), [1] and [3]
BALL_SLOPE = 10.0 / 9.0
#: Weibull slope of roller bearings (line contact)
ROLLER_SLOPE = 9.0 / 8.0


def weibull_slope(bearing):
    """The Weibull slope e of a bearing: 10/9 for a ball bearing, 9/8 for a roller bearing.

    Parameters
    ----------
    bearing : object
        A :class:`~bearinglab.bearing.BallBearing`, or a roller bearing (any object whose class name
        holds "Roller", or with ``rolling_element == "roller"``).

    Returns
    -------
    float

    Examples
    --------
    >>> from bearinglab import catalog
    >>> weibull_slope(catalog.get("6206"))
    1.1111111111111112
    """
    kind = getattr(bearing, "rolling_element", None)
    if kind == "roller" or "Roller" in type(bearing).__name__:
        return ROLLER_SLOPE
    return BALL_SLOPE


def system_life(lives, weibull_slopes=BALL_SLOPE, *, axis=-1, tol=1e-14, max_iter=100):
    r"""The life of a system of bearings from their lives at one reliability.

    Parameters
    ----------
    lives : array_like
        The bearings' lives along ``axis`` (inf for a bearing that carries nothing; NaN gives NaN).
        [revolutions or h]
    weibull_slopes : array_like, optional
        e of each bearing (broadcast against ``lives``). [-]
    axis : int, optional
        The axis of the bearings.
    tol : float, optional
        Relative tolerance of the root for mixed slopes. [-]
    max_iter : int, optional

    Returns
    -------
    ndarray or float
        The system's life, in the unit of ``lives``.

    Notes
    -----
    One slope: the closed form of the module notes. Mixed slopes: Newton on
    :math:`g(\ln L) = \ln \sum_i (L/L_i)^{e_i} = 0`, which is convex and increasing in ln L, from the
    closed form with the smallest slope (below the root).

    Examples
    --------
    >>> print(f"{system_life([20000.0, 20000.0]):.0f}")
    10718
    >>> print(f"{system_life([1e4, 3e4], [10 / 9, 9 / 8]):.1f}")
    7953.9
    """
    life = as_float("lives", lives)
    if life.ndim == 0:
        life = life[None]
        axis = 0
    life = np.moveaxis(life, axis, -1)
    e = np.broadcast_to(np.moveaxis(np.broadcast_to(as_float("weibull_slopes", weibull_slopes),
                                                    np.moveaxis(life, -1, axis).shape), axis, -1), life.shape)
    if np.any(life <= 0):
        raise InputError(f"lives must be > 0, got {float(life[life <= 0].flat[0])!r}")
    if np.any(~(e > 0)):
        raise InputError("weibull_slopes must be > 0 [-]")
    with np.errstate(divide="ignore"):
        if np.all(e == e[..., :1]):
            e0 = e[..., 0]
            return (np.sum(life ** -e, axis=-1) ** (-1.0 / e0))[()]
        x = np.log(np.sum(life ** -e.min(axis=-1, keepdims=True), axis=-1) ** (-1.0 / e.min(axis=-1)))
        finite = np.where(np.isfinite(life), life, np.nan)
        for _ in range(max_iter):
            terms = np.where(np.isfinite(life), np.exp(e * (x[..., None] - np.log(finite))), 0.0)
            s = np.sum(terms, axis=-1)
            step = np.log(s) / (np.sum(e * terms, axis=-1) / s)
            x = x - step
            if np.all(np.abs(step[np.isfinite(step)]) <= tol):
                return np.exp(x)[()]
    from ..errors import ConvergenceError

    raise ConvergenceError("life.system_life", iterations=max_iter, residual=step, estimate=np.exp(x))

r"""Reference rating life of ISO/TS 16281 from the loads on the individual balls.

Functions
---------
contact_dynamic_loads      Qci, Qce: the ball loads of the basic dynamic load rating of each ring
equivalent_contact_loads   Qei, Qee: cubic (rotating ring) and 10/3-power (stationary ring) means
reference_rating_life      L10r = [(Qci/Qei)^(-10/3) + (Qce/Qee)^(-10/3)]^(-9/10) million revolutions
rows_rating_life           the bearing's L10r from its rows' (or a four-point bearing's diagonals'), raceway by raceway

The per-ball contact loads come from a load-distribution model (the rigid-ring model of the combined
loads, with clearance and tilt); arrays hold the balls on their last axis, so a batch of load cases
is one call. SI in the API (N, m, rad); lives in revolutions.

References
----------
.. [1] ISO/TS 16281:2008, *Rolling bearings -- Methods for calculating the modified reference rating
   life for universally loaded bearings*, clause 7 (ball bearings): eqs. for Qci and Qce from C,
   the equivalent ball loads and the reference life; its worked cases as computed by MASTA are
   quoted in the repository github.com/minzhun/ISO16281 (Test_BallBearing.py), whose BallBearing.py
   also holds the TS's Qci and Qce of thrust ball bearings (eqs. (19)-(24): C_a / (Z sin alpha) and no
   constants 0.407, 0.389, 1.044) and the r_e = D_w (1 + 1/gamma) / 2 of self-aligning ones.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from .._validate import check_nonnegative, check_positive
from ..errors import InputError

__all__ = [
    "ContactDynamicLoads",
    "EquivalentContactLoads",
    "contact_dynamic_loads",
    "equivalent_contact_loads",
    "reference_rating_life",
    "rows_rating_life",
]


class ContactDynamicLoads(NamedTuple):
    """Ball loads of the basic dynamic load rating of the two rings (ISO/TS 16281)."""

    inner: float | np.ndarray
    """Qci. [N]"""
    outer: float | np.ndarray
    """Qce. [N]"""


class EquivalentContactLoads(NamedTuple):
    """Dynamic equivalent ball loads of the two rings (ISO/TS 16281)."""

    inner: float | np.ndarray
    """Qei. [N]"""
    outer: float | np.ndarray
    """Qee. [N]"""


def contact_dynamic_loads(dynamic_load_rating, n_balls, ball_diameter, pitch_diameter, inner_conformity,
                          outer_conformity, contact_angle=0.0, *, n_rows=1, thrust=False):
    r"""Basic dynamic ball loads Qci and Qce of the inner and outer raceway of a radial ball bearing.

    Parameters
    ----------
    dynamic_load_rating : array_like
        C of the bearing. [N]
    n_balls : array_like
        Balls per row Z. [-]
    ball_diameter : array_like
        Dw. [m]
    pitch_diameter : array_like
        Dpw. [m]
    inner_conformity, outer_conformity : array_like
        r_i / Dw and r_e / Dw. [-]
    contact_angle : array_like
        Nominal contact angle alpha. [rad]
    n_rows : int
        Rows i. [-]
    thrust : bool
        A thrust ball bearing: ``dynamic_load_rating`` is C_a and the rings are the shaft washer (inner)
        and the housing washer (outer).

    Returns
    -------
    ContactDynamicLoads

    Notes
    -----
    ISO/TS 16281:2008, radial ball bearings, with :math:`\gamma = D_w\cos\alpha/D_{pw}` and
    :math:`\rho = \frac{r_i}{r_e}\frac{2r_e - D_w}{2r_i - D_w}`:

    .. math::
        Q_{ci} = \frac{C}{0.407\, Z\, i^{0.7}\cos^{0.7}\alpha}
                 \left[1 + \left(1.044\left(\frac{1-\gamma}{1+\gamma}\right)^{1.72}\rho^{0.41}
                 \right)^{10/3}\right]^{0.3},\qquad
        Q_{ce} = \frac{C}{0.389\, Z\, i^{0.7}\cos^{0.7}\alpha}
                 \left[1 + \left(1.044\left(\frac{1-\gamma}{1+\gamma}\right)^{1.72}\rho^{0.41}
                 \right)^{-10/3}\right]^{0.3}.

    The nominal contact angle is used, as in the standard and in MASTA (whose reference lives of
    axially loaded deep-groove bearings, running at 13 to 15 deg, are reproduced this way).

    Thrust ball bearings (module reference [1], eqs. (19)-(24) as there):

    .. math::
        Q_{ci} = \frac{C_a}{Z\sin\alpha}\left[1 + \left(\left(\frac{1-\gamma}{1+\gamma}\right)^{1.72}
                 \rho^{0.41}\right)^{10/3}\right]^{0.3},\qquad
        Q_{ce} = \frac{C_a}{Z\sin\alpha}\left[1 + \left(\left(\frac{1-\gamma}{1+\gamma}\right)^{1.72}
                 \rho^{0.41}\right)^{-10/3}\right]^{0.3},

    so that Z equal ball loads F_a/Z give L10r = (C_a/F_a)^3, ISO 281's L10 of a thrust bearing, exactly.

    Examples
    --------
    >>> q = contact_dynamic_loads(23400.0, 7, 11.5e-3, 43.5e-3, 0.52, 0.53)
    >>> print(f"{q.inner:.1f} {q.outer:.1f}")
    8423.2 18288.7
    """
    c = check_positive("dynamic_load_rating", dynamic_load_rating, "N")
    z = check_positive("n_balls", n_balls, "-")
    dw = check_positive("ball_diameter", ball_diameter, "m")
    dpw = check_positive("pitch_diameter", pitch_diameter, "m")
    fi = np.asarray(inner_conformity, dtype=float)
    fe = np.asarray(outer_conformity, dtype=float)
    if not (np.all(fi > 0.5) and np.all(fe > 0.5)):
        raise InputError("inner_conformity and outer_conformity must be > 0.5 [-]")
    gamma = dw * np.cos(contact_angle) / dpw
    rho = (fi / fe) * (2.0 * fe - 1.0) / (2.0 * fi - 1.0)  # r_i/r_e (2 r_e - Dw)/(2 r_i - Dw)
    if thrust:
        base = c / (z * np.sin(contact_angle))
        ratio = ((1.0 - gamma) / (1.0 + gamma)) ** 1.72 * rho**0.41
        return ContactDynamicLoads((base * (1.0 + ratio ** (10.0 / 3.0)) ** 0.3)[()],
                                   (base * (1.0 + ratio ** (-10.0 / 3.0)) ** 0.3)[()])
    ratio = 1.044 * ((1.0 - gamma) / (1.0 + gamma)) ** 1.72 * rho**0.41
    base = c / (z * (n_rows * np.cos(contact_angle)) ** 0.7)
    q_ci = base / 0.407 * (1.0 + ratio ** (10.0 / 3.0)) ** 0.3
    q_ce = base / 0.389 * (1.0 + ratio ** (-10.0 / 3.0)) ** 0.3
    return ContactDynamicLoads(q_ci[()], q_ce[()])


def equivalent_contact_loads(contact_loads, *, rotating="inner"):
    r"""Dynamic equivalent ball loads of the two rings from the ball loads of one row.

    Parameters
    ----------
    contact_loads : array_like
        Normal load of each ball, >= 0, balls on the last axis. [N]
    rotating : {"inner", "outer"}
        The rotating ring (relative to the load), whose equivalent load is the cubic mean.

    Returns
    -------
    EquivalentContactLoads

    Notes
    -----
    ISO/TS 16281:2008: a ring rotating relative to the load sees every ball load once per
    revolution, :math:`Q_e = (\frac{1}{Z}\sum Q_j^3)^{1/3}`; a ring standing relative to the load
    carries each load at a fixed point, :math:`Q_e = (\frac{1}{Z}\sum Q_j^{10/3})^{3/10}`.

    Examples
    --------
    >>> q = equivalent_contact_loads([1000.0, 0.0, 0.0, 0.0])
    >>> print(f"{q.inner:.2f} {q.outer:.2f}")
    629.96 659.75
    """
    q = check_nonnegative("contact_loads", contact_loads, "N")
    if q.ndim == 0 or q.shape[-1] < 1:
        raise InputError("contact_loads must hold one load per ball on its last axis")
    cubic = np.cbrt(np.mean(q**3, axis=-1))
    power = np.mean(q ** (10.0 / 3.0), axis=-1) ** 0.3
    if rotating == "inner":
        return EquivalentContactLoads(cubic[()], power[()])
    if rotating == "outer":
        return EquivalentContactLoads(power[()], cubic[()])
    raise InputError(f"rotating must be one of ['inner', 'outer'], got {rotating!r}")


def reference_rating_life(contact_loads, dynamic_load_rating, ball_diameter, pitch_diameter,
                          inner_conformity, outer_conformity, contact_angle=0.0, *, n_rows=1,
                          rotating="inner", outer_contact_loads=None, thrust=False):
    r"""Basic reference rating life L10r of ISO/TS 16281 from the ball loads.

    Parameters
    ----------
    contact_loads : array_like
        Normal load of each ball of a row, >= 0, balls on the last axis (Z = its length). [N]
    dynamic_load_rating : array_like
        C. [N]
    ball_diameter : array_like
        Dw. [m]
    pitch_diameter : array_like
        Dpw. [m]
    inner_conformity, outer_conformity : array_like
        r_i / Dw and r_e / Dw. [-]
    contact_angle : array_like
        Nominal contact angle. [rad]
    n_rows : int
        Rows i (identically loaded). [-]
    rotating : {"inner", "outer"}
        Ring rotating relative to the load.
    outer_contact_loads : array_like, optional
        Ball loads on the outer raceway where they differ from the inner ones (at speed, by the
        centrifugal force); by default ``contact_loads``. [N]
    thrust : bool
        A thrust ball bearing (:func:`contact_dynamic_loads`).

    Returns
    -------
    ndarray or float
        :math:`L_{10r} = 10^6\left[(Q_{ci}/Q_{ei})^{-10/3} + (Q_{ce}/Q_{ee})^{-10/3}\right]^{-9/10}`;
        infinite where no ball carries load. [revolutions]

    Examples
    --------
    >>> print(f"{reference_rating_life([500.0] * 7, 23400.0, 11.5e-3, 43.5e-3, 0.52, 0.53) / 1e6:.1f}")
    4478.1
    """
    q = check_nonnegative("contact_loads", contact_loads, "N")
    qc = contact_dynamic_loads(dynamic_load_rating, q.shape[-1], ball_diameter, pitch_diameter,
                               inner_conformity, outer_conformity, contact_angle, n_rows=n_rows, thrust=thrust)
    qe = equivalent_contact_loads(q, rotating=rotating)
    if outer_contact_loads is not None:
        qo = check_nonnegative("outer_contact_loads", outer_contact_loads, "N")
        if qo.shape[-1:] != q.shape[-1:]:
            raise InputError(f"outer_contact_loads must have {q.shape[-1]} balls on its last axis like "
                             f"contact_loads, got shape {qo.shape}")
        qe = EquivalentContactLoads(qe.inner, equivalent_contact_loads(qo, rotating=rotating).outer)
    with np.errstate(divide="ignore"):
        s = (qe.inner / qc.inner) ** (10.0 / 3.0) + (qe.outer / qc.outer) ** (10.0 / 3.0)
        return (1e6 * s ** -0.9)[()]


def rows_rating_life(lives):
    r"""The reference rating life of a bearing from those of its rows, raceway by raceway.

    Parameters
    ----------
    lives : array_like
        L10r of each row, rows on the last axis (each from :func:`reference_rating_life` with the
        bearing's rows i in its Q_c; a four-point bearing's two diagonals, each with i = 1; inf for an
        unloaded row). [revolutions]

    Returns
    -------
    ndarray or float
        :math:`L_{10r} = \left(\sum_k L_{10r,k}^{-10/9}\right)^{-9/10}`: every raceway of every row in
        series, the Weibull slope 10/9 of ball raceways by which :func:`reference_rating_life` already
        combines the two raceways of one row. With i equally loaded rows this is i^(-0.9) L_row, and with
        Q_c of a row carrying i^(-0.7) of the bearing's C it reproduces ISO 281's C = i^0.7 C_row. [revolutions]

    Examples
    --------
    >>> print(f"{rows_rating_life([2e9, 2e9]) / 1e6:.1f}")
    1071.8
    """
    life = np.asarray(lives, dtype=float)
    least = np.min(life, axis=-1, keepdims=True)  # in units of the shortest row: one loaded row gives its life
    with np.errstate(divide="ignore", invalid="ignore"):
        ratio = np.where(np.isinf(life), np.inf, life / least)
        out = least[..., 0] * np.sum(ratio ** (-10.0 / 9.0), axis=-1) ** -0.9
    return np.where(np.isinf(least[..., 0]), np.inf, out)[()]

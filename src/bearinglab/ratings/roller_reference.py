r"""Reference rating life of ISO/TS 16281 for roller bearings, summed over the laminae of the rollers.

Functions
---------
roller_contact_dynamic_loads      Q_ci, Q_ce of the rollers and q_ci, q_ce of a lamina, from C
lamina_equivalent_loads           q_kei, q_kee: 4th-power (rotating ring) and 9/2-power (standing ring) means
roller_reference_rating_life      L10r = [sum_k (q_kei/q_ci)^(9/2) + (q_kee/q_ce)^(9/2)]^(-8/9) million revolutions

The lamina loads come from the slice model (:mod:`bearinglab.rollers.distribution`), rollers on the axis
before the last, laminae on the last: a batch of load cases is one call. SI in the API; lives in
revolutions. The profile and the ring tilt enter through the lamina loads.

References
----------
.. [1] ISO/TS 16281:2008, *Rolling bearings -- Methods for calculating the modified reference rating
   life for universally loaded bearings*, clause 8 (roller bearings), eqs. (47)-(65): the roller loads of
   the basic dynamic load rating of each ring, the lamina ratings q_c = Q_c n_s^(-7/9), the equivalent
   lamina loads and the reference life; lambda nu
   = 0.83 for radial roller bearings. The equations are transcribed in the open repository
   github.com/minzhun/ISO16281 (RollerBearing.py), whose facts (not code) are used.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from .._validate import check_integer, check_nonnegative, check_positive
from ..errors import InputError

__all__ = [
    "LaminaEquivalentLoads",
    "RollerContactDynamicLoads",
    "lamina_equivalent_loads",
    "roller_contact_dynamic_loads",
    "roller_reference_rating_life",
]

_LAMBDA_NU = 0.83  # ISO/TS 16281 (and ISO/TR 1281-1): reduction factor lambda nu of radial roller bearings
_KI, _KE = 0.378, 0.364  # ISO/TS 16281 eqs. (47)-(48): constants of Q_ci and Q_ce
_RATIO, _EXP = 1.038, 143.0 / 108.0  # the ratio of the inner to the outer rating, (1.038 ((1 - g)/(1 + g))^(143/108))


class RollerContactDynamicLoads(NamedTuple):
    """Roller and lamina loads of the basic dynamic load rating of the two rings (ISO/TS 16281)."""

    inner: np.ndarray
    """Q_ci of a whole roller. [N]"""
    outer: np.ndarray
    """Q_ce. [N]"""
    lamina_inner: np.ndarray
    """q_ci = Q_ci n_s^(-7/9). [N]"""
    lamina_outer: np.ndarray
    """q_ce. [N]"""


def roller_contact_dynamic_loads(dynamic_load_rating, rollers, roller_diameter, pitch_diameter, contact_angle=0.0,
                                 *, n_slices=30, rows=1):
    r"""Roller loads Q_ci, Q_ce of the basic dynamic load rating and their lamina values q_ci, q_ce.

    Parameters
    ----------
    dynamic_load_rating : array_like
        C of the bearing. [N]
    rollers : array_like
        Z per row. [-]
    roller_diameter : array_like
        D_we. [m]
    pitch_diameter : array_like
        D_pw. [m]
    contact_angle : array_like
        alpha. [rad]
    n_slices : int
        n_s. [-]
    rows : int
        i. [-]

    Returns
    -------
    RollerContactDynamicLoads

    Notes
    -----
    ISO/TS 16281:2008 eqs. (47)-(57) for radial roller bearings, :math:`\gamma = D_{we}\cos\alpha/D_{pw}`,
    :math:`\lambda\nu = 0.83`:

    .. math::
        Q_{ci} = \frac{C}{0.378\,\lambda\nu\, Z i^{7/9}\cos\alpha}
                 \left[1 + \left(1.038\left(\tfrac{1-\gamma}{1+\gamma}\right)^{143/108}\right)^{9/2}\right]^{2/9},
        \qquad
        Q_{ce} = \frac{C}{0.364\,\lambda\nu\, Z i^{7/9}\cos\alpha}
                 \left[1 + \left(1.038\left(\tfrac{1-\gamma}{1+\gamma}\right)^{143/108}\right)^{-9/2}\right]^{2/9}

    and :math:`q_c = Q_c\, n_s^{-7/9}` of a lamina.

    Examples
    --------
    >>> q = roller_contact_dynamic_loads(62e3, 14, 11e-3, 60.5e-3)
    >>> print(f"{q.inner:.0f} {q.outer:.0f} N")
    14510 23623 N
    """
    c = check_positive("dynamic_load_rating", dynamic_load_rating, "N")
    z = check_positive("rollers", rollers, "-")
    d = check_positive("roller_diameter", roller_diameter, "m")
    dpw = check_positive("pitch_diameter", pitch_diameter, "m")
    a = np.asarray(contact_angle, dtype=float)
    n = int(check_integer("n_slices", n_slices, 1))
    gamma = d * np.cos(a) / dpw
    ratio = _RATIO * ((1.0 - gamma) / (1.0 + gamma)) ** _EXP
    base = c / (_LAMBDA_NU * z * rows ** (7.0 / 9.0) * np.cos(a))
    qi = base / _KI * (1.0 + ratio**4.5) ** (2.0 / 9.0)
    qe = base / _KE * (1.0 + ratio**-4.5) ** (2.0 / 9.0)
    scale = n ** (-7.0 / 9.0)
    return RollerContactDynamicLoads(qi[()], qe[()], (qi * scale)[()], (qe * scale)[()])



class LaminaEquivalentLoads(NamedTuple):
    """Dynamic equivalent loads of each lamina on the two rings (ISO/TS 16281)."""

    inner: np.ndarray
    """(..., n_s) q_kei. [N]"""
    outer: np.ndarray
    """(..., n_s) q_kee. [N]"""


def lamina_equivalent_loads(slice_loads, *, rotating="inner"):
    r"""Equivalent loads of each lamina on the two rings from the lamina loads of one row.

    Parameters
    ----------
    slice_loads : array_like
        (..., Z, n_s) q_jk >= 0: rollers on the axis before the last, laminae on the last. [N]
    rotating : {"inner", "outer"}
        The ring rotating relative to the load: it sees every roller, q_ke = (mean q^4)^(1/4); the standing one
        carries each load at a fixed place, (mean q^(9/2))^(2/9) (eqs. (61)-(64)).

    Returns
    -------
    LaminaEquivalentLoads

    Examples
    --------
    >>> q = lamina_equivalent_loads([[100.0, 100.0], [0.0, 0.0]])
    >>> print(np.round(q.inner, 2), np.round(q.outer, 2))
    [84.09 84.09] [85.72 85.72]
    """
    q = check_nonnegative("slice_loads", slice_loads, "N")
    if q.ndim < 2:
        raise InputError("slice_loads must hold rollers and laminae on its last two axes")
    four = np.mean(q**4, axis=-2) ** 0.25
    nine = np.mean(q**4.5, axis=-2) ** (2.0 / 9.0)
    if rotating == "inner":
        return LaminaEquivalentLoads(four, nine)
    if rotating == "outer":
        return LaminaEquivalentLoads(nine, four)
    raise InputError(f"rotating must be one of ['inner', 'outer'], got {rotating!r}")


def roller_reference_rating_life(slice_loads, dynamic_load_rating, roller_diameter, pitch_diameter, contact_angle=0.0,
                                 *, rows=1, rotating="inner"):
    r"""Basic reference rating life L10r of ISO/TS 16281 of a roller bearing from its lamina loads.

    Parameters
    ----------
    slice_loads : array_like
        (..., Z, n_s) lamina loads of one row (:attr:`RollerLoadDistribution.slice_load`). [N]
    dynamic_load_rating : array_like
        C. [N]
    roller_diameter : array_like
        D_we. [m]
    pitch_diameter : array_like
        D_pw. [m]
    contact_angle : array_like
        alpha. [rad]
    rows : int
        i (identically loaded rows). [-]
    rotating : {"inner", "outer"}
        The ring rotating relative to the load.

    Returns
    -------
    ndarray or float
        :math:`L_{10r} = 10^6\left[\sum_k (q_{kei}/q_{ci})^{9/2} + (q_{kee}/q_{ce})^{9/2}\right]^{-8/9}`
        (eq. (65)); infinite where no lamina carries load. [revolutions]

    Notes
    -----
    The sum runs over the laminae, so a roller loaded at its edge (tilt, a short crown) wears its life there:
    the profile and the tilt enter through the lamina loads. With every lamina of every roller loaded alike
    the result does not depend on n_s. The stress concentration factors of eq. (60) for laminae at the roller
    ends are not applied: the lamina loads carry the edge loading of the profile and the tilt, and the
    transcription of eq. (60) available could not be checked against the standard's text.

    Examples
    --------
    >>> q = np.full((14, 30), 2000.0 / 30)
    >>> print(f"{roller_reference_rating_life(q, 62e3, 11e-3, 60.5e-3) / 1e6:.1f}")
    2522.1
    """
    q = check_nonnegative("slice_loads", slice_loads, "N")
    if q.ndim < 2:
        raise InputError("slice_loads must hold rollers and laminae on its last two axes")
    z, n = q.shape[-2], q.shape[-1]
    qc = roller_contact_dynamic_loads(dynamic_load_rating, z, roller_diameter, pitch_diameter, contact_angle,
                                      n_slices=n, rows=rows)
    qe = lamina_equivalent_loads(q, rotating=rotating)
    s = np.sum((qe.inner / qc.lamina_inner) ** 4.5 + (qe.outer / qc.lamina_outer) ** 4.5, axis=-1)
    with np.errstate(divide="ignore"):
        return (1e6 * s ** (-8.0 / 9.0))[()]

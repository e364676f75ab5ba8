r"""Contact stiffness of the two raceway contacts at the operating angles: spec 004 eqs. (14)-(21).

Stiffness
---------
contact_stiffness   K_i, K_e in Q = K delta^1.5 at the operating angles, exact Hertz (:mod:`bearinglab.hertz`)
Stiffness           the pair (K_i, K_e)

The solvers of :mod:`bearinglab.quasistatic` evaluate the same exact Hertz quantities through Chebyshev
interpolants in cos(alpha), built once per bearing (private ``_hertz_tables``, ``_k``,
``_hertz_coefficients``), so that no elliptic integral is inverted inside a Newton iteration.

References
----------
.. [1] Zhao Chunjiang, Cui Guohua, Wang Guoqiang, Huang Qingxue and Zhang Fangping, "Precise definition
   of the contact-angle field of a high-speed angular-contact ball bearing under axial load,"
   Transactions of the CSAM, vol. 39, no. 12, pp. 154-156, 209, 2008 (spec 004 of this project).
"""

from __future__ import annotations

import math  # noqa: F401  (the doctests use it)
from typing import NamedTuple

import numpy as np
from numpy.polynomial import chebyshev as _cheb

from .. import geometry, hertz

__all__ = ["Stiffness", "contact_stiffness"]

_N_CHEB = 16  # Chebyshev nodes of ln K(cos alpha); reproduces hertz to ~1e-13 (tests/quasistatic/test_contact.py)



class Stiffness(NamedTuple):
    """Load-deflection constants of the two contacts, Q = K delta^1.5."""

    inner: np.ndarray  # K_i [N/m^1.5]
    outer: np.ndarray  # K_e [N/m^1.5]


def contact_stiffness(contact_angle_inner, contact_angle_outer, ball_diameter, pitch_diameter, inner_conformity,
                      outer_conformity, reduced_modulus):
    r"""Load-deflection constants K_i, K_e at the operating contact angles, eqs. (16)-(21).

    Parameters
    ----------
    contact_angle_inner, contact_angle_outer : array_like
        alpha_i, alpha_e at which the curvatures are evaluated. [rad]
    ball_diameter : array_like
        D. [m]
    pitch_diameter : array_like
        d_m. [m]
    inner_conformity, outer_conformity : array_like
        f_i, f_e. [-]
    reduced_modulus : array_like
        E' of the ball-ring pair. [Pa]

    Returns
    -------
    Stiffness
        K_i and K_e. [N/m^1.5]

    Notes
    -----
    Curvature sums and F(rho) from :func:`bearinglab.geometry.raceway_curvature`, K from
    :func:`bearinglab.hertz.load_deflection_constant` (exact delta*). Eq. (16)'s 2.15e5 N/mm^1.5 is
    (2^1.5/3) E' for E = 2.075e5 MPa, nu = 0.3, rounded (exact: 2.1498e5).

    Examples
    --------
    >>> k = contact_stiffness(math.radians(40), math.radians(40), 22.23e-3, 125.3e-3, 0.5232, 0.5232,
    ...                       2.15e5 * 1e6 * 3 / 2**1.5)
    >>> print(f"{k.inner * 1e-3**1.5:.5e} {k.outer * 1e-3**1.5:.5e}")
    1.29673e+06 1.34883e+06
    """
    inner = geometry.raceway_curvature(ball_diameter, pitch_diameter, inner_conformity, contact_angle_inner,
                                       race="inner")
    outer = geometry.raceway_curvature(ball_diameter, pitch_diameter, outer_conformity, contact_angle_outer,
                                       race="outer")
    return Stiffness(hertz.load_deflection_constant(inner.curvature_sum, inner.curvature_difference, reduced_modulus),
                     hertz.load_deflection_constant(outer.curvature_sum, outer.curvature_difference, reduced_modulus))


def _hertz_tables(d, dm, fi, fo, ep):
    """Chebyshev series in x = 2 cos(alpha) - 1 of the exact Hertz quantities, one row per geometry.

    The exact Hertz solution (an iterative inversion of elliptic integrals, :mod:`bearinglab.hertz`) is
    computed once per bearing on _N_CHEB nodes instead of at every Newton iteration. Per race the result
    holds the coefficients of ln K and of its derivative in cos(alpha), and those of ln kappa, ln a*,
    ln b*, ln delta* (shape (4, G, n)). The interpolants reproduce :func:`contact_stiffness` and
    :func:`bearinglab.hertz.coefficients` to ~1e-13 relative (all are analytic in cos alpha on [0, 1]);
    tests/quasistatic/test_contact.py checks it.
    """
    k = np.arange(_N_CHEB)
    x = np.cos(np.pi * (k + 0.5) / _N_CHEB)
    alpha = np.arccos((x + 1.0) / 2.0)
    shape = (len(d), _N_CHEB)
    d_, dm_, fi_, fo_, ep_ = (np.broadcast_to(v[:, None], shape).ravel() for v in (d, dm, fi, fo, ep))
    a = np.broadcast_to(alpha[None, :], shape).ravel()
    inner = geometry.raceway_curvature(d_, dm_, fi_, a, race="inner")
    outer = geometry.raceway_curvature(d_, dm_, fo_, a, race="outer")
    both = hertz.coefficients(np.concatenate([inner.curvature_difference, outer.curvature_difference]))
    m = a.size
    tables = []
    for j, curv in enumerate((inner, outer)):
        c = hertz.HertzCoefficients(*(np.asarray(f)[j * m:(j + 1) * m] for f in both))
        kk = hertz.load_deflection_constant(curv.curvature_sum, curv.curvature_difference, ep_, hertz=c)
        vals = np.log(np.stack([kk, c.ellipticity, c.a_star, c.b_star, c.delta_star]).reshape((5,) + shape))
        coef = np.stack([_cheb.chebfit(x, v.T, _N_CHEB - 1).T for v in vals])  # (5, G, n)
        dcoef = 2.0 * _cheb.chebder(coef[0], axis=1)  # d ln K / d cos(alpha) = 2 d/dx
        if len(d) == 1:
            coef, dcoef = coef[:, 0], dcoef[0]
        tables.append({"k": (coef[0], dcoef), "hertz": coef[1:]})
    return tables


def _cheb_eval(coef, x):
    """Clenshaw sum of Chebyshev series; ``coef`` is (n,) or one row per element of ``x`` (m, n)."""
    if coef.ndim == 1:
        return _cheb.chebval(x, coef)
    b1 = np.zeros_like(x)
    b2 = np.zeros_like(x)
    for j in range(coef.shape[1] - 1, 0, -1):  # over the series degree, not over cases
        b1, b2 = coef[:, j] + 2.0 * x * b1 - b2, b1
    return coef[:, 0] + x * b1 - b2




def _k(table, gid, c):
    """K and d ln K / d cos(alpha) from the tables."""
    coef, dcoef = table["k"]
    x = 2.0 * c - 1.0
    if coef.ndim == 1:
        return np.exp(_cheb_eval(coef, x)), _cheb_eval(dcoef, x)
    return np.exp(_cheb_eval(coef[gid], x)), _cheb_eval(dcoef[gid], x)


def _hertz_coefficients(table, gid, c):
    """kappa, a*, b*, delta* (exact, through the tables) at cos(alpha) = c."""
    x = 2.0 * c - 1.0
    coef = table["hertz"]
    vals = [np.exp(_cheb_eval(cf if cf.ndim == 1 else cf[gid], x)) for cf in coef]
    return hertz.HertzCoefficients(*vals)

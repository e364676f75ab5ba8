r"""Hertz point contact: the one Hertz module of the library.

Dimensionless coefficients (exact, from complete elliptic integrals)
--------------------------------------------------------------------
ellipticity              kappa = a/b from the curvature difference F(rho) = cos(tau), vectorized
coefficients             kappa, a* (= mu), b* (= nu), delta* (= 2K/(pi mu)) from F(rho)
tabulated                the same tuple from tabulated values (the handbook mode of spec 000 section 8)

Contact of given load and materials
-----------------------------------
reduced_modulus          E' = 2 / [(1 - nu1^2)/E1 + (1 - nu2^2)/E2]
point_contact            semi-axes, approach, maximum pressure
load_deflection_constant K in Q = K delta^1.5
approach_coefficient     c in delta / D = c (Q / D^2)^(2/3) (spec 000 section 5.3)
elastic_constant         c_E = (3/E')^(2/3) / 2, the material factor of c (spec 000 section 5.3)

Curvature sums and F(rho) of the two raceway contacts are in :func:`bearinglab.geometry.raceway_curvature`.
The exact relations are those of Harris and Kotzalas [1]_; the start of the ellipticity solve is the fit
of Hamrock and Brewe [2]_.

References
----------
.. [1] T. A. Harris and M. N. Kotzalas, *Essential Concepts of Bearing Technology*, 5th ed.,
   CRC Press, 2006, ch. 6, doi:10.1201/9781420006599.
.. [2] B. J. Hamrock and D. E. Brewe, "Simplified solution for stresses and deformations,"
   J. Lubr. Technol., vol. 105, no. 2, pp. 171-177, 1983, doi:10.1115/1.3254558.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from . import _solve
from ._validate import as_float, check_nonnegative, check_positive
from .errors import ConvergenceError, InputError

__all__ = [
    "HertzCoefficients",
    "PointContact",
    "approach_coefficient",
    "coefficients",
    "elastic_constant",
    "ellipticity",
    "load_deflection_constant",
    "point_contact",
    "reduced_modulus",
    "tabulated",
]


class HertzCoefficients(NamedTuple):
    """Dimensionless Hertz coefficients of a point contact."""

    ellipticity: np.ndarray  # kappa = a/b >= 1 [-]
    a_star: np.ndarray  # mu of the Russian handbooks [-]
    b_star: np.ndarray  # nu [-]
    delta_star: np.ndarray  # 2K/(pi mu) [-]


class PointContact(NamedTuple):
    """Hertz contact of given load."""

    a: np.ndarray  # semi-major axis (across rolling) [m]
    b: np.ndarray  # semi-minor axis [m]
    delta: np.ndarray  # approach of the two bodies [m]
    p_max: np.ndarray  # maximum pressure [Pa]


_SMALL_F = 1e-5  # below this F(rho) the series m = 8F/3 (+O(F^2)) is used: the closed form is 0/0
_F_NOISE_ULPS = 8.0  # K and E carry a few ulps each; 3.9e-15 was seen against the 4.9e-15 of one ulp


def _f_of_m(m):
    """F(rho) as a function of the elliptic parameter m = 1 - 1/kappa^2, dF/dm, and the rounding error
    of F (a bound: the numerator cancels, so F is known to ~eps ((kappa^2+1)E + 2K) / |den|, about 5e-15
    at F = 0.07, not to eps)."""
    from scipy.special import ellipe, ellipk  # here, not at import: a catalog lookup needs no scipy

    k = ellipk(m)
    e = ellipe(m)
    k2 = 1.0 / (1.0 - m)  # kappa^2
    num = (k2 + 1.0) * e - 2.0 * k
    den = (k2 - 1.0) * e
    f = num / den
    # derivatives: dK/dm = (E - (1-m)K) / (2m(1-m)), dE/dm = (E - K) / (2m), dk2/dm = k2^2
    dk = (e - (1.0 - m) * k) / (2.0 * m * (1.0 - m))
    de = (e - k) / (2.0 * m)
    dk2 = k2 * k2
    dnum = dk2 * e + (k2 + 1.0) * de - 2.0 * dk
    dden = dk2 * e + (k2 - 1.0) * de
    noise = _F_NOISE_ULPS * np.finfo(float).eps * ((k2 + 1.0) * e + 2.0 * k) / np.abs(den)
    return f, (dnum * den - num * dden) / (den * den), noise


def ellipticity(curvature_difference, *, rtol=_solve.ELLIPTICITY_RTOL, max_iter=_solve.ELLIPTICITY_MAX_ITER):
    r"""Ellipticity kappa = a/b of a Hertz point contact from its curvature difference.

    Parameters
    ----------
    curvature_difference : array_like
        F(rho) = cos(tau), in [0, 1). [-]
    rtol : float, optional
        Relative tolerance on the elliptic parameter m.
    max_iter : int, optional
        Iteration limit of the safeguarded Newton solve.

    Returns
    -------
    ndarray
        kappa >= 1. [-]

    Notes
    -----
    Solves :math:`F = [(\kappa^2+1)E(e) - 2K(e)] / [(\kappa^2-1)E(e)]`, :math:`e^2 = 1 - 1/\kappa^2`
    (spec 000 section 5.2; Harris and Kotzalas 2006, eq. 6.26), for all elements at once: Newton in the parameter
    m = e^2 with a bisection bracket, started from the Hamrock-Brewe (1983) fit. For F < 1e-5 the
    limit m = 8F/3 is used (the closed form is 0/0 at F = 0, where kappa = 1).

    Examples
    --------
    >>> print(np.round(ellipticity([0.9287242, 0.7111269]), 4))
    [8.3368 3.2238]
    """
    f_target = check_nonnegative("curvature_difference", curvature_difference, "-")
    if np.any(f_target >= 1.0):
        bad = f_target[f_target >= 1.0].flat[0]
        raise InputError(f"curvature_difference must be in [0, 1) [-], got {float(bad)!r}")
    f_t = np.atleast_1d(f_target).astype(float)
    small = f_t < _SMALL_F
    m = np.where(small, 8.0 * f_t / 3.0, 0.0)
    big = ~small
    if big.any():
        fb = f_t[big]
        kappa0 = 1.0339 * ((1.0 + fb) / (1.0 - fb)) ** 0.636  # Hamrock-Brewe [2]
        mb = np.clip(1.0 - 1.0 / kappa0**2, 1e-12, 1.0 - 1e-16)
        lo = np.zeros_like(mb)
        hi = np.ones_like(mb)
        active = np.ones(mb.shape, dtype=bool)
        for it in range(1, max_iter + 1):
            f, df, noise = _f_of_m(mb)
            resid = f - fb
            lo = np.where(resid < 0, np.maximum(lo, mb), lo)  # F rises with m
            hi = np.where(resid > 0, np.minimum(hi, mb), hi)
            with np.errstate(invalid="ignore", divide="ignore"):
                new = mb - resid / df
            outside = ~((new >= lo) & (new <= hi)) | ~np.isfinite(new)  # closed: a converged step may land on a bound
            new = np.where(outside, 0.5 * (lo + hi), new)
            # Newton may cycle between two neighbours whose residuals are +-(rounding of F) (F = 0.0683:
            # 8.6e-15 apart, 5e-14 relative > rtol). A step back onto the other bracket end (a point already
            # evaluated) with a residual within the rounding is such a cycle: m is a root as far as F can tell
            at_root = (np.abs(resid) <= noise) & ((new == lo) | (new == hi))
            stepped = np.abs(new - mb) <= rtol * np.maximum(new, 1e-300)
            mb = np.where(active & ~at_root, new, mb)
            active &= ~(at_root | stepped)
            if not active.any():
                break
        else:
            raise ConvergenceError(
                "hertz.ellipticity", iterations=max_iter, residual=resid, estimate=1.0 / np.sqrt(1.0 - mb)
            )
        m[big] = mb
    kappa = 1.0 / np.sqrt(1.0 - m)
    return kappa.reshape(np.shape(f_target))[()]


def coefficients(curvature_difference):
    r"""Exact dimensionless Hertz coefficients from the curvature difference.

    Parameters
    ----------
    curvature_difference : array_like
        F(rho) = cos(tau), in [0, 1). [-]

    Returns
    -------
    HertzCoefficients
        kappa, a* (mu), b* (nu) and delta* (2K/(pi mu)). [-]

    Notes
    -----
    Spec 000 section 5.2: :math:`\mu = (2\kappa^2 E/\pi)^{1/3}`, :math:`\nu = (2E/(\pi\kappa))^{1/3}`,
    :math:`\delta^* = (2K/\pi)(\pi/(2\kappa^2 E))^{1/3}`. The handbooks the source papers used
    tabulate these to 2-3 digits; see :func:`tabulated`.

    Examples
    --------
    >>> c = coefficients(0.9287242)
    >>> print(f"{c.a_star:.4f} {c.b_star:.4f} {c.delta_star:.5f}")
    3.5624 0.4273 0.62834
    """
    kappa = np.asarray(ellipticity(curvature_difference))
    m = 1.0 - 1.0 / kappa**2
    from scipy.special import ellipe, ellipk  # here, not at import: a catalog lookup needs no scipy

    k = ellipk(m)
    e = ellipe(m)
    a_star = np.cbrt(2.0 * kappa**2 * e / np.pi)
    b_star = np.cbrt(2.0 * e / (np.pi * kappa))
    delta_star = (2.0 * k / np.pi) * np.cbrt(np.pi / (2.0 * kappa**2 * e))
    return HertzCoefficients(kappa[()], a_star[()], b_star[()], delta_star[()])


def tabulated(delta_star, a_star_b_star=np.nan):
    """Hertz coefficients taken from a handbook table instead of computed (spec 000 section 8).

    Parameters
    ----------
    delta_star : array_like
        Tabulated 2K/(pi mu). [-]
    a_star_b_star : array_like, optional
        Tabulated product mu nu, if known. [-]

    Returns
    -------
    HertzCoefficients
        ``delta_star`` as given; ``a_star`` and ``b_star`` NaN (a table of the product does not
        give them separately) and ``ellipticity`` NaN.

    Notes
    -----
    The source of spec 000 reads 2K/(pi mu) = 0.63 (inner) and 0.852 (outer) from a table; the exact
    values are 0.62834 and 0.85245. Tabulated coefficients reproduce the printed numbers; the exact
    ones move the operating angle of the worked example by 6.6 arc seconds.
    """
    ds = check_positive("delta_star", delta_star, "-")
    nan = np.full(np.shape(ds), np.nan)
    del a_star_b_star  # kept for the record only; the methods need delta* alone
    return HertzCoefficients(nan[()], nan[()], nan[()], ds[()])


def reduced_modulus(elastic_modulus_1, poisson_ratio_1, elastic_modulus_2, poisson_ratio_2):
    r"""Effective modulus of a contact pair, :math:`E' = 2 / [(1-\nu_1^2)/E_1 + (1-\nu_2^2)/E_2]`.

    Parameters
    ----------
    elastic_modulus_1, elastic_modulus_2 : array_like
        Young's moduli. [Pa]
    poisson_ratio_1, poisson_ratio_2 : array_like
        Poisson's ratios, in (-1, 0.5). [-]

    Returns
    -------
    ndarray
        E'. [Pa]

    Examples
    --------
    >>> print(f"{reduced_modulus(2.08e11, 0.3, 2.08e11, 0.3) / 1e9:.2f} GPa")
    228.57 GPa
    """
    e1 = check_positive("elastic_modulus_1", elastic_modulus_1, "Pa")
    e2 = check_positive("elastic_modulus_2", elastic_modulus_2, "Pa")
    n1 = as_float("poisson_ratio_1", poisson_ratio_1)
    n2 = as_float("poisson_ratio_2", poisson_ratio_2)
    for name, nu in (("poisson_ratio_1", n1), ("poisson_ratio_2", n2)):
        bad = ~((nu > -1.0) & (nu < 0.5))
        if np.any(bad):
            first = nu[bad].flat[0] if nu.ndim else nu
            raise InputError(f"{name} must be in (-1, 0.5) [-], got {float(first)!r}")
    return (2.0 / ((1.0 - n1**2) / e1 + (1.0 - n2**2) / e2))[()]


def _coeffs(curvature_difference, hertz):
    return coefficients(curvature_difference) if hertz is None else hertz


def point_contact(load, curvature_sum, curvature_difference, reduced_modulus, *, hertz=None):
    r"""Hertz contact of two convex bodies touching at a point.

    Parameters
    ----------
    load : array_like
        Normal load Q on the contact, >= 0. [N]
    curvature_sum : array_like
        Sigma rho. [1/m]
    curvature_difference : array_like
        F(rho) = cos(tau). [-]
    reduced_modulus : array_like
        E' of the pair (see :func:`reduced_modulus`). [Pa]
    hertz : HertzCoefficients, optional
        Coefficients to use instead of the exact ones (e.g. from :func:`tabulated`).

    Returns
    -------
    PointContact
        Semi-axes ``a``, ``b`` and approach ``delta`` [m]; ``p_max`` [Pa].

    Notes
    -----
    Harris and Kotzalas (2006) eqs. 6.38-6.43 with :math:`\eta = 2/E'`:
    :math:`a = a^* [3Q/(E'\Sigma\rho)]^{1/3}`, :math:`b = b^*[\ldots]^{1/3}`,
    :math:`\delta = \delta^* [3Q/(E'\Sigma\rho)]^{2/3}\,\Sigma\rho/2`, :math:`p_{max} = 3Q/(2\pi a b)`.
    Linear-elastic, frictionless, small contact.

    Examples
    --------
    >>> c = point_contact(1000.0, 108.108, 0.926196, 2.28e11)
    >>> print(f"{c.p_max / 1e9:.3f} GPa, delta = {c.delta * 1e6:.2f} um")
    1.286 GPa, delta = 8.41 um
    """
    q = check_nonnegative("load", load, "N")
    s = check_positive("curvature_sum", curvature_sum, "1/m")
    ep = check_positive("reduced_modulus", reduced_modulus, "Pa")
    c = _coeffs(curvature_difference, hertz)
    base = np.cbrt(3.0 * q / (ep * s))
    a = c.a_star * base
    b = c.b_star * base
    delta = c.delta_star * base**2 * s / 2.0
    with np.errstate(invalid="ignore", divide="ignore"):
        p_max = np.where(q > 0, 3.0 * q / (2.0 * np.pi * a * b), 0.0)
    return PointContact(np.asarray(a)[()], np.asarray(b)[()], np.asarray(delta)[()], p_max[()])


def load_deflection_constant(curvature_sum, curvature_difference, reduced_modulus, *, hertz=None):
    r"""Load-deflection constant K of a point contact, Q = K delta^(3/2).

    Parameters
    ----------
    curvature_sum : array_like
        Sigma rho. [1/m]
    curvature_difference : array_like
        F(rho). [-]
    reduced_modulus : array_like
        E'. [Pa]
    hertz : HertzCoefficients, optional
        Coefficients to use instead of the exact ones.

    Returns
    -------
    ndarray
        K. [N/m^1.5]

    Notes
    -----
    Inverting :func:`point_contact`: :math:`K = (2^{3/2}/3)\,E'\,\Sigma\rho^{-1/2}\,\delta^{*-3/2}`.
    For steel (E = 2.075e5 MPa, nu = 0.3) the prefactor is 2.15e5 in N and mm, as in Harris and spec 004
    eq. (16).

    Examples
    --------
    >>> k = load_deflection_constant(108.108, 0.926196, reduced_modulus(2.075e11, 0.3, 2.075e11, 0.3))
    >>> print(f"{k * 1e-3**1.5:.4e} N/mm^1.5")
    1.2966e+06 N/mm^1.5
    """
    s = check_positive("curvature_sum", curvature_sum, "1/m")
    ep = check_positive("reduced_modulus", reduced_modulus, "Pa")
    c = _coeffs(curvature_difference, hertz)
    return (2.0**1.5 / 3.0 * ep / np.sqrt(s) * np.asarray(c.delta_star) ** -1.5)[()]


def elastic_constant(reduced_modulus):
    r"""Elastic constant c_E of the approach coefficient, :math:`c_E = (3/E')^{2/3}/2`.

    Parameters
    ----------
    reduced_modulus : array_like
        E' of the ball-ring pair (see :func:`reduced_modulus`). [Pa]

    Returns
    -------
    ndarray
        c_E. [(m^2/N)^(2/3)]

    Notes
    -----
    The approach of :func:`point_contact`, :math:`\delta = \delta^* [3Q/(E'\Sigma\rho)]^{2/3}\,\Sigma\rho/2`
    (Harris and Kotzalas 2006, eqs. 6.38-6.43 with :math:`\eta = 2/E'`), written per ball diameter D:

    .. math:: \frac{\delta}{D} = c_E\,\delta^*\,\sqrt[3]{D\Sigma\rho}\,\Big(\frac{Q}{D^2}\Big)^{2/3},
              \qquad c_E = \frac12\Big(\frac{3}{E'}\Big)^{2/3}

    which is the form of spec 000 section 5.3, :math:`c_j = c_E (2K/\pi\mu)_j \sqrt[3]{d\Sigma\rho_j}`. With
    this c_E the force characteristic C* of the test-stand method is exactly :math:`Z K_n (B D)^{3/2}` with
    the K of :func:`load_deflection_constant` at the free angle. The source prints
    c_E = 0.592e-4 (cm^2/kgf)^(2/3), which is this value for E' = 2.2836e5 MPa (steel with E = 2.078e5 MPa,
    nu = 0.3); the library's steel (E = 2.075e5 MPa, nu = 0.3) gives 0.59258e-4.

    Examples
    --------
    >>> ce = elastic_constant(reduced_modulus(2.075e11, 0.3, 2.075e11, 0.3))
    >>> print(f"{ce / (1e-2**(4 / 3) / 9.80665**(2 / 3)):.5e} (cm^2/kgf)^(2/3)")
    5.92580e-05 (cm^2/kgf)^(2/3)
    """
    ep = check_positive("reduced_modulus", reduced_modulus, "Pa")
    return ((3.0 / ep) ** (2.0 / 3.0) / 2.0)[()]


def approach_coefficient(ball_diameter, curvature_sum, curvature_difference, reduced_modulus, *, hertz=None):
    r"""Elastic approach coefficient c of spec 000 section 5.3: delta / D = c (Q / D^2)^(2/3).

    Parameters
    ----------
    ball_diameter : array_like
        Ball diameter D. [m]
    curvature_sum : array_like
        Sigma rho. [1/m]
    curvature_difference : array_like
        F(rho). [-]
    reduced_modulus : array_like
        E'. [Pa]
    hertz : HertzCoefficients, optional
        Coefficients to use instead of the exact ones.

    Returns
    -------
    ndarray
        c. [(m^2/N)^(2/3)]

    Notes
    -----
    :math:`c = \delta^*\,\sqrt[3]{D\Sigma\rho}\;c_E` with :math:`c_E = (3/E')^{2/3}/2`
    (:func:`elastic_constant`). The source's constant 0.592e-4 (cm^2/kgf)^(2/3) is c_E for steel with
    E = 2.078e5 MPa, nu = 0.3.
    """
    d = check_positive("ball_diameter", ball_diameter, "m")
    s = check_positive("curvature_sum", curvature_sum, "1/m")
    ep = check_positive("reduced_modulus", reduced_modulus, "Pa")
    c = _coeffs(curvature_difference, hertz)
    return (np.asarray(c.delta_star) * np.cbrt(d * s) * elastic_constant(ep))[()]

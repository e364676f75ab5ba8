r"""The three data-reduction tasks of the friction-rig lab (spec 001 section 6), for any number of points.

Generic least squares (grouped, vectorized over any number of groups)
---------------------------------------------------------------------
through_origin            y = k x through the origin, with standard error and residual RMS
straight_line             y = a + b x, with standard errors and residual RMS

Tasks
-----
reduced_friction_coefficient  task 1: mu of T = mu P0 d / 2 through the origin, eq. (6.1)
speed_dependence              task 2: f0 and T_F of T = f0 d_m^3 n^(2/3) + T_F, eq. (6.2)
load_dependence               task 3: f and T0 of T = T0 + f P0 (P0/C0)^e d_m, eqs. (6.2)-(6.3)
skf_friction                  task 4: mu_sl and/or a scale on M_rr of the SKF four-term model

Deprecated names (they warn; removed after one release): ``friction_coefficient`` (now
:func:`reduced_friction_coefficient`), ``FrictionCoefficientFit`` (now
:class:`ReducedFrictionCoefficientFit`) and its field ``friction_coefficient``.

Every function takes an optional ``groups`` array that labels the points; one fit is made per
distinct label (outputs ordered like ``numpy.unique(groups)``), all groups at once with
``numpy.bincount`` sums and no Python loop over groups. The sums are centred on the group means
(two passes), which is the numerically stable form of the closed forms (6.1)-(6.2): the results are
the same to rounding.

Statistics reported for each fit: the residual RMS sqrt(mean(r_i^2)) over the m points of the group
(spec 001 section 6.2), and the standard errors of the coefficients from the usual OLS covariance,
s^2 = sum(r_i^2)/(m - p) with p = 1 (through the origin) or 2 (line). With m = p points there is no
redundancy and the standard errors are NaN ("not available"), never 0.

Units: torque, loads and lengths are SI. The speed-term factor f0 is returned in its published unit
N*mm^-2*min^(2/3) (spec 001 section 8.10); the conversion to N*mm, mm and rpm is done once, in
:func:`speed_dependence`.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from .._validate import check_finite, check_nonnegative, check_positive
from ..errors import InputError
from ._compat import renamed_field, warn_renamed

__all__ = [
    "SKF_FIT_PARAMETERS",
    "LineFit",
    "LoadDependenceFit",
    "ReducedFrictionCoefficientFit",
    "SKFFrictionFit",
    "SpeedDependenceFit",
    "ThroughOriginFit",
    "load_dependence",
    "reduced_friction_coefficient",
    "skf_friction",
    "speed_dependence",
    "straight_line",
    "through_origin",
]

_MM, _RPM = 1e-3, 2.0 * math.pi / 60.0  # m per mm, rad/s per rpm


class ThroughOriginFit(NamedTuple):
    """Least-squares line through the origin, y = k x, per group."""

    slope: float | np.ndarray
    """k = sum(x y) / sum(x^2)."""
    slope_standard_error: float | np.ndarray
    """Standard error of k; NaN for a single point."""
    residual_rms: float | np.ndarray
    """sqrt(mean((y - k x)^2)), in the unit of y."""
    count: int | np.ndarray
    """Number of points m."""
    residuals: np.ndarray
    """y - k x at every point (input order)."""


class LineFit(NamedTuple):
    """Ordinary least-squares straight line, y = a + b x, per group."""

    slope: float | np.ndarray
    """b."""
    intercept: float | np.ndarray
    """a."""
    slope_standard_error: float | np.ndarray
    """Standard error of b; NaN for two points."""
    intercept_standard_error: float | np.ndarray
    """Standard error of a; NaN for two points."""
    residual_rms: float | np.ndarray
    """sqrt(mean((y - a - b x)^2)), in the unit of y."""
    count: int | np.ndarray
    """Number of points m."""
    residuals: np.ndarray
    """y - a - b x at every point (input order)."""


class ReducedFrictionCoefficientFit(NamedTuple):
    """Task 1: reduced friction coefficient of the one-term model (referred to the bore), per group."""

    reduced_friction_coefficient: float | np.ndarray
    """mu of (6.1). [-]"""
    standard_error: float | np.ndarray
    """Standard error of mu; NaN for a single point. [-]"""
    residual_rms: float | np.ndarray
    """sqrt(mean((T_i - mu P0_i d/2)^2)). [N*m]"""
    count: int | np.ndarray
    """Number of points m. [-]"""
    residuals: np.ndarray
    """T_i - mu P0_i d/2 at every point (input order). [N*m]"""

    friction_coefficient = renamed_field(
        "ReducedFrictionCoefficientFit", "friction_coefficient", "reduced_friction_coefficient"
    )


class SpeedDependenceFit(NamedTuple):
    """Task 2: speed-term factor and load term, per group."""

    speed_term_factor: float | np.ndarray
    """f0 = b / d_m^3 of (6.2). [N*mm^-2*min^(2/3)]"""
    load_term: float | np.ndarray
    """T_F, the intercept at n -> 0 (an extrapolation; may come out negative). [N*m]"""
    speed_term_factor_standard_error: float | np.ndarray
    """Standard error of f0; NaN for two points. [N*mm^-2*min^(2/3)]"""
    load_term_standard_error: float | np.ndarray
    """Standard error of T_F; NaN for two points. [N*m]"""
    residual_rms: float | np.ndarray
    """RMS of the residuals. [N*m]"""
    count: int | np.ndarray
    """Number of points m. [-]"""
    residuals: np.ndarray
    """Residual torque at every point (input order). [N*m]"""


class LoadDependenceFit(NamedTuple):
    """Task 3: load-term factor and speed term, per group."""

    load_term_factor: float | np.ndarray
    """f = b C0^e / d_m of (6.3). [-]"""
    speed_term: float | np.ndarray
    """T0, the intercept at P0 -> 0 (an extrapolation; may come out negative). [N*m]"""
    load_term_factor_standard_error: float | np.ndarray
    """Standard error of f; NaN for two points. [-]"""
    speed_term_standard_error: float | np.ndarray
    """Standard error of T0; NaN for two points. [N*m]"""
    residual_rms: float | np.ndarray
    """RMS of the residuals. [N*m]"""
    count: int | np.ndarray
    """Number of points m. [-]"""
    residuals: np.ndarray
    """Residual torque at every point (input order). [N*m]"""


# ----------------------------------------------------------------------------- grouping
def _prepare(x, y, groups, x_name, y_name):
    x = check_finite(x_name, x, "-")
    y = check_finite(y_name, y, "-")
    x, y = np.broadcast_arrays(np.atleast_1d(x), np.atleast_1d(y))
    x, y = x.ravel(), y.ravel()
    if groups is None:
        index = np.zeros(x.size, dtype=np.intp)
        labels = None
    else:
        g = np.asarray(groups).ravel()
        if g.size != x.size:
            raise InputError(f"groups must label every point: {g.size} labels for {x.size} points")
        labels, index = np.unique(g, return_inverse=True)
        index = index.ravel()
    n_groups = 1 if labels is None else labels.size
    return x, y, index, n_groups, labels


def _degenerate(message, labels, k):
    lab = None if labels is None else labels[k]
    lab = lab.item() if isinstance(lab, np.generic) else lab
    label = "the data" if labels is None else f"group {lab!r}"
    exc = InputError(message.format(group=label))
    exc.group = lab  # the offending label, for file-level messages
    return exc


def _out(value, labels):
    value = np.asarray(value)
    return value[0] if labels is None else value


def _pack(cls, labels, *values, residuals):
    """``cls`` of the per-group ``values`` (scalars without groups) and the per-point residuals."""
    return cls(*(_out(v, labels) for v in values), residuals)


def _stats(x, y, index, n_groups, labels, *, intercept, what, x_name, shown=None, shown_unit=""):
    """Centred least-squares sums per group -> (slope, intercept, se_slope, se_intercept, rms, m, r)."""
    m = np.bincount(index, minlength=n_groups).astype(float)
    if np.any(m == 0):
        raise InputError("groups: every label must have at least one point")
    if intercept:
        xmin = np.full(n_groups, np.inf)
        xmax = np.full(n_groups, -np.inf)
        np.minimum.at(xmin, index, x)
        np.maximum.at(xmax, index, x)
        flat = ~(xmax > xmin)
        if flat.any():
            k = int(np.argmax(flat))
            at = xmin[k] if shown is None else np.ravel(shown)[np.argmax(index == k)]
            raise _degenerate(
                f"{what}: {{group}} needs at least two distinct values of {x_name}, got "
                f"{int(m[k])} point(s) all at {at:.10g}{shown_unit}",
                labels,
                k,
            )
        xbar = np.bincount(index, weights=x, minlength=n_groups) / m
        ybar = np.bincount(index, weights=y, minlength=n_groups) / m
        dx = x - xbar[index]
        dy = y - ybar[index]
        sxx = np.bincount(index, weights=dx * dx, minlength=n_groups)
        sxy = np.bincount(index, weights=dx * dy, minlength=n_groups)
        slope = sxy / sxx
        icpt = ybar - slope * xbar
        r = y - (icpt[index] + slope[index] * x)
        dof = m - 2.0
    else:
        sxx = np.bincount(index, weights=x * x, minlength=n_groups)
        zero = ~(sxx > 0)
        if zero.any():
            k = int(np.argmax(zero))
            raise _degenerate(
                f"{what}: {{group}} has all {x_name} = 0; a line through the origin needs "
                f"a non-zero abscissa",
                labels,
                k,
            )
        sxy = np.bincount(index, weights=x * y, minlength=n_groups)
        slope = sxy / sxx
        icpt = np.zeros(n_groups)
        r = y - slope[index] * x
        dof = m - 1.0
        xbar = None
    ssr = np.bincount(index, weights=r * r, minlength=n_groups)
    rms = np.sqrt(ssr / m)
    with np.errstate(divide="ignore", invalid="ignore"):
        s2 = np.where(dof > 0, ssr / np.where(dof > 0, dof, 1.0), np.nan)
        se_slope = np.sqrt(s2 / sxx)
        se_icpt = (
            np.sqrt(s2 * (1.0 / m + xbar**2 / sxx)) if intercept else np.full(n_groups, np.nan)
        )
    return slope, icpt, se_slope, se_icpt, rms, m.astype(int), r


# ----------------------------------------------------------------------------- generic fits
def through_origin(x, y, *, groups=None):
    """Least-squares line through the origin, y = k x, for one or many groups of points.

    Parameters
    ----------
    x : array_like
        Abscissae. [any]
    y : array_like
        Ordinates. [any]
    groups : array_like, optional
        Group label of every point; one fit per distinct label. [-]

    Returns
    -------
    ThroughOriginFit
        Scalars without ``groups``, arrays ordered like ``numpy.unique(groups)`` with it.

    Raises
    ------
    InputError
        A group whose abscissae are all 0. The exception carries ``group``, the offending label.

    Examples
    --------
    >>> fit = through_origin([1.0, 2.0, 3.0], [2.0, 4.0, 6.0])
    >>> float(fit.slope), float(fit.residual_rms)
    (2.0, 0.0)
    """
    x, y, index, n, labels = _prepare(x, y, groups, "x", "y")
    k, _a, se, _sa, rms, m, r = _stats(
        x, y, index, n, labels, intercept=False, what="fit through the origin", x_name="x"
    )
    return _pack(ThroughOriginFit, labels, k, se, rms, m, residuals=r)


def straight_line(x, y, *, groups=None):
    """Ordinary least-squares straight line, y = a + b x, for one or many groups of points.

    Parameters
    ----------
    x : array_like
        Abscissae. [any]
    y : array_like
        Ordinates. [any]
    groups : array_like, optional
        Group label of every point; one fit per distinct label. [-]

    Returns
    -------
    LineFit
        Scalars without ``groups``, arrays ordered like ``numpy.unique(groups)`` with it.

    Raises
    ------
    InputError
        A group with fewer than two distinct abscissae (spec 001 section 8.6). The exception carries
        ``group``, the offending label.

    Examples
    --------
    >>> fit = straight_line([0.0, 1.0, 2.0, 3.0], [1.0, 3.0, 5.0, 7.0])
    >>> float(fit.slope), float(fit.intercept)
    (2.0, 1.0)
    """
    x, y, index, n, labels = _prepare(x, y, groups, "x", "y")
    b, a, sb, sa, rms, m, r = _stats(
        x, y, index, n, labels, intercept=True, what="straight line", x_name="x"
    )
    return _pack(LineFit, labels, b, a, sb, sa, rms, m, residuals=r)


# ----------------------------------------------------------------------------- the three tasks
def reduced_friction_coefficient(torque, equivalent_load, bore, *, groups=None):
    """Task 1: reduced friction coefficient mu by least squares through the origin, eq. (6.1).

    Parameters
    ----------
    torque : array_like
        Measured friction torque T_i. [N*m]
    equivalent_load : array_like
        Static equivalent load P0_i of each point. [N]
    bore : array_like
        Bore diameter d of the test bearing. [m]
    groups : array_like, optional
        Group label of every point (in the lab: one group per tilt and speed column of Table 4). [-]

    Returns
    -------
    ReducedFrictionCoefficientFit
        mu, its standard error, the residual RMS [N*m], the count and the residuals.

    Raises
    ------
    InputError
        A group whose P0 are all zero (spec 001 section 9).

    Notes
    -----
    mu = 2 sum(T_i P0_i) / (d sum(P0_i^2)), eq. (6.1): the least-squares estimate of the one-term
    model (3.2), not an average of T_i/P0_i (spec 001 section 8.9). Any m >= 1 is accepted.

    Examples
    --------
    Spec 001 section 10.1, n = 1500 rpm (T in N*m):

    >>> t = np.array([0.025055204, 0.036527822, 0.070121614]) * 1e-3
    >>> fit = reduced_friction_coefficient(t, [4.905, 9.81, 19.62], 5e-3)
    >>> print(f"{fit.reduced_friction_coefficient:.6e}")
    1.470209e-03
    """
    d = check_positive("bore", bore, "m")
    p0 = check_nonnegative("equivalent_load", equivalent_load, "N")
    x, y, index, n, labels = _prepare(p0 * d / 2.0, torque, groups, "equivalent_load", "torque")
    mu, _a, se, _sa, rms, m, r = _stats(
        x, y, index, n, labels, intercept=False, what="task 1", x_name="equivalent_load"
    )  # (6.1) with abscissa P0 d/2
    return _pack(ReducedFrictionCoefficientFit, labels, mu, se, rms, m, residuals=r)


# ----------------------------------------------------------------------------- deprecated names
def friction_coefficient(torque, equivalent_load, bore, *, groups=None):
    """Deprecated name of :func:`reduced_friction_coefficient` (warns with DeprecationWarning)."""
    warn_renamed("bearinglab.lab.fits.friction_coefficient", "reduced_friction_coefficient")
    return reduced_friction_coefficient(torque, equivalent_load, bore, groups=groups)


def __getattr__(name):
    if name == "FrictionCoefficientFit":
        warn_renamed("bearinglab.lab.fits.FrictionCoefficientFit", "ReducedFrictionCoefficientFit")
        return ReducedFrictionCoefficientFit
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def speed_dependence(torque, shaft_speed, mean_diameter, *, groups=None):
    """Task 2: speed-term factor f0 and load term T_F by least squares in N = n^(2/3), eq. (6.2).

    Parameters
    ----------
    torque : array_like
        Measured friction torque T_i. [N*m]
    shaft_speed : array_like
        Spindle speed n_i. [rad/s]
    mean_diameter : array_like
        Mean diameter d_m of the test bearing. [m]
    groups : array_like, optional
        Group label of every point (in the lab: one group per tilt of Table 5). [-]

    Returns
    -------
    SpeedDependenceFit
        f0 [N*mm^-2*min^(2/3)] and T_F [N*m] with standard errors, residual RMS [N*m], count and
        residuals.

    Raises
    ------
    InputError
        A group with fewer than two distinct speeds (spec 001 sections 8.6 and 9).

    Notes
    -----
    With N_i = n_i^(2/3) (n in rpm) the model T = b N + T_F is fitted by ordinary least squares and
    f0 = b / d_m^3 (d_m in mm, T in N*mm), eq. (6.2); the conversion to those published units is done
    here, once. T_F is the value at n -> 0, an extrapolation (spec 001 section 8.14).

    Examples
    --------
    Spec 001 section 10.1, Table 5, beta = 0:

    >>> n = np.array([500, 1000, 1500, 2000, 2500, 3000]) * 2 * np.pi / 60
    >>> t = np.array([0.026607442, 0.032002617, 0.036527822, 0.040566924, 0.044279207, 0.047750239]) * 1e-3
    >>> fit = speed_dependence(t, n, 9e-3)
    >>> print(f"{fit.speed_term_factor:.6e} {fit.load_term * 1e3:.6e}")
    2.000000e-07 1.742262e-02
    """
    dm = check_positive("mean_diameter", mean_diameter, "m")
    n = check_finite("shaft_speed", shaft_speed, "rad/s")
    t_nmm = check_finite("torque", torque, "N*m") / _MM  # N*mm
    n_rpm = np.abs(n) / _RPM
    x = (dm / _MM) ** 3 * n_rpm ** (2.0 / 3.0)  # d_m^3 N, mm^3 min^(-2/3): slope is f0 directly
    shown = np.broadcast_arrays(n_rpm, x, t_nmm)[0].ravel()
    x, y, index, k, labels = _prepare(x, t_nmm, groups, "shaft_speed", "torque")
    f0, tf, se_f0, se_tf, rms, m, r = _stats(
        x,
        y,
        index,
        k,
        labels,
        intercept=True,
        what="task 2",
        x_name="shaft_speed",
        shown=shown,
        shown_unit=" rpm",
    )  # (6.2)
    tf, se_tf, rms, r = tf * _MM, se_tf * _MM, rms * _MM, r * _MM  # N*mm -> N*m
    return _pack(SpeedDependenceFit, labels, f0, tf, se_f0, se_tf, rms, m, residuals=r)


def load_dependence(
    torque,
    equivalent_load,
    mean_diameter,
    static_load_rating,
    *,
    load_term_exponent=0.55,
    groups=None,
):
    """Task 3: load-term factor f and speed term T0 by least squares in N = P0^(1+e), eqs. (6.2)-(6.3).

    Parameters
    ----------
    torque : array_like
        Measured friction torque T_i. [N*m]
    equivalent_load : array_like
        Static equivalent load P0_i. [N]
    mean_diameter : array_like
        Mean diameter d_m of the test bearing. [m]
    static_load_rating : array_like
        Basic static load rating C0. [N]
    load_term_exponent : array_like, optional
        e = c of Table 2 (0.55 for radial bearings, spec 001 section 8.1). [-]
    groups : array_like, optional
        Group label of every point (in the lab: one group per tilt and speed column of Table 4). [-]

    Returns
    -------
    LoadDependenceFit
        f [-] and T0 [N*m] with standard errors, residual RMS [N*m], count and residuals.

    Raises
    ------
    InputError
        A group with fewer than two distinct P0 (spec 001 sections 8.6 and 9).

    Notes
    -----
    With N_i = P0_i^(1+e) the model T = T0 + b N is fitted by ordinary least squares and
    f = b C0^e / d_m, eq. (6.3). The model is dimensionally homogeneous, so it is fitted in SI. T0 is
    the value at P0 -> 0, an extrapolation (spec 001 section 8.14).

    Examples
    --------
    Spec 001 section 10.1, n = 3000 rpm:

    >>> t = np.array([0.036277621, 0.047750239, 0.081344031]) * 1e-3
    >>> fit = load_dependence(t, [4.905, 9.81, 19.62], 9e-3, 392.0)
    >>> print(f"{fit.load_term_factor:.6e} {fit.speed_term * 1e3:.6e}")
    1.500000e-03 3.032762e-02
    """
    dm = check_positive("mean_diameter", mean_diameter, "m")
    c0 = check_positive("static_load_rating", static_load_rating, "N")
    e = check_finite("load_term_exponent", load_term_exponent, "-")
    p0 = check_nonnegative("equivalent_load", equivalent_load, "N")
    x = dm / c0**e * p0 ** (1.0 + e)  # (d_m / C0^e) N: slope is f directly, (6.3)
    shown = np.broadcast_arrays(p0, x, np.asarray(torque, dtype=float))[0].ravel()
    x, y, index, k, labels = _prepare(x, torque, groups, "equivalent_load", "torque")
    f, t0, se_f, se_t0, rms, m, r = _stats(
        x,
        y,
        index,
        k,
        labels,
        intercept=True,
        what="task 3",
        x_name="equivalent_load",
        shown=shown,
        shown_unit=" N",
    )  # (6.2)
    return _pack(LoadDependenceFit, labels, f, t0, se_f, se_t0, rms, m, residuals=r)


# ----------------------------------------------------------------------------- task 4: the SKF model
SKF_FIT_PARAMETERS = ("sliding", "rolling", "both")


class SKFFrictionFit(NamedTuple):
    """Fit of the SKF four-term model T = k M_rr + mu_sl G_sl + M_seal + M_drag, per group."""

    sliding_friction_coefficient: float | np.ndarray
    """mu_sl fitted (``fit="sliding"`` or ``"both"``); NaN with ``fit="rolling"``, where the model's own
    mu_sl of every point is used. [-]"""
    rolling_scale: float | np.ndarray
    """k, the factor on the model's rolling moment Phi_ish Phi_rs M_rr (``fit="rolling"`` or
    ``"both"``); 1 with ``fit="sliding"``. [-]"""
    sliding_friction_coefficient_standard_error: float | np.ndarray
    """Standard error of mu_sl; NaN where not fitted or without redundancy. [-]"""
    rolling_scale_standard_error: float | np.ndarray
    """Standard error of k; NaN where not fitted or without redundancy. [-]"""
    model_sliding_friction_coefficient: float | np.ndarray
    """Mean over the group's points of the model's mu_sl = phi_bl mu_bl + (1 - phi_bl) mu_EHL. [-]"""
    residual_rms: float | np.ndarray
    """sqrt(mean(r_i^2)). [N*m]"""
    count: int | np.ndarray
    """Number of points m."""
    residuals: np.ndarray
    """Measured minus fitted torque at every point (input order). [N*m]"""
    model_residuals: np.ndarray | None = None
    """Measured minus the model's own torque (mu_sl and M_rr unfitted) at every point (input order). [N*m]"""


def _two_regressors(x, z, y, index, n_groups, labels):
    """Least squares y = a x + b z (no intercept) per group -> (a, b, se_a, se_b, rms, m, r)."""
    m = np.bincount(index, minlength=n_groups).astype(float)

    def total(w):
        return np.bincount(index, weights=w, minlength=n_groups)

    sxx, szz, sxz, sxy, szy = total(x * x), total(z * z), total(x * z), total(x * y), total(z * y)
    det = sxx * szz - sxz**2
    flat = ~(det > 1e-12 * sxx * szz)  # G_sl and M_rr proportional over the group: not separable
    if flat.any():
        k = int(np.argmax(flat))
        raise _degenerate(
            "task 4: {group} cannot separate mu_sl from the scale on M_rr: the sliding variable G_sl "
            f"and the rolling moment M_rr are proportional over its {int(m[k])} point(s); vary the "
            "load and the speed, or fit one of them (fit='sliding' or 'rolling')",
            labels,
            k,
        )
    a = (szz * sxy - sxz * szy) / det
    b = (sxx * szy - sxz * sxy) / det
    r = y - a[index] * x - b[index] * z
    ssr = total(r * r)
    dof = m - 2.0
    with np.errstate(divide="ignore", invalid="ignore"):
        s2 = np.where(dof > 0, ssr / np.where(dof > 0, dof, 1.0), np.nan)
        se_a, se_b = np.sqrt(s2 * szz / det), np.sqrt(s2 * sxx / det)
    return a, b, se_a, se_b, np.sqrt(ssr / m), m.astype(int), r


def skf_friction(torque, radial_load, axial_load, shaft_speed, kinematic_viscosity, bore,
                 outside_diameter, *, fit="sliding", groups=None, **model):
    r"""Task 4: fit mu_sl and/or a scale on the rolling moment of the SKF four-term model to rig data.

    Parameters
    ----------
    torque : array_like
        Measured friction torque T_i. [N*m]
    radial_load, axial_load : array_like
        Fr and Fa of each point. [N]
    shaft_speed : array_like
        n of each point. [rad/s]
    kinematic_viscosity : array_like
        nu at the operating temperature (of the base oil for grease). [m^2/s]
    bore, outside_diameter : array_like
        d and D of the test bearing. [m]
    fit : {"sliding", "rolling", "both"}
        What is fitted: mu_sl (with the model's rolling moment), a factor k on the rolling moment (with
        the model's mu_sl), or both. [-]
    groups : array_like, optional
        Group label of every point; one fit per distinct label. [-]
    **model : optional
        The model's options, passed to :func:`bearinglab.friction.skf.skf` (``series`` or
        ``constants``, ``bearing_type``, ``lubrication``, ``static_load_rating``, seals, ...).

    Returns
    -------
    SKFFrictionFit
        Scalars without ``groups``, arrays ordered like ``numpy.unique(groups)`` with it.

    Raises
    ------
    InputError
        An unknown ``fit``; with ``fit="both"``, a group whose G_sl and M_rr are proportional (the two
        cannot be told apart). The exception carries ``group``, the offending label.

    Notes
    -----
    The SKF model is linear in both unknowns:
    :math:`T = k\,\Phi_{ish}\Phi_{rs} G_{rr}(\nu n)^{0.6} + \mu_{sl} G_{sl} + M_{seal} + M_{drag}`
    (SKF Rolling bearings catalogue, Friction). The model's parts are computed by
    :func:`bearinglab.friction.skf.skf`, evaluated once (G_sl as its sliding moment at mu_sl = 1; the
    model's mu_sl by :func:`bearinglab.friction.skf.sliding_friction_coefficient`) and the unknowns
    found by ordinary least squares without intercept, all groups at once. Standard errors come from
    the OLS covariance with s^2 = sum(r_i^2)/(m - p), p the number of fitted parameters; NaN where
    m = p.

    Examples
    --------
    Torques made by the model itself with mu_sl = 0.08 are fitted back to it:

    >>> from bearinglab.friction.skf import skf
    >>> fr, n = np.array([50.0, 100.0, 200.0]), np.array([100.0, 200.0, 300.0])
    >>> t = skf(fr, 0.0, n, 30e-6, 25e-3, 52e-3, series="62", sliding_friction_coefficient=0.08)
    >>> fit = skf_friction(t.total_moment, fr, 0.0, n, 30e-6, 25e-3, 52e-3, series="62")
    >>> print(f"{fit.sliding_friction_coefficient:.6f}")
    0.080000
    """
    from ..friction.skf import skf as _skf  # the lab's physics lives in bearinglab.friction
    from ..friction.skf import sliding_friction_coefficient

    if fit not in SKF_FIT_PARAMETERS:
        raise InputError(f"fit must be one of {list(SKF_FIT_PARAMETERS)}, got {fit!r}")
    if "sliding_friction_coefficient" in model:
        raise InputError("sliding_friction_coefficient is what task 4 fits; do not give it")
    t = check_finite("torque", torque, "N*m")
    args = (radial_load, axial_load, shaft_speed, kinematic_viscosity, bore, outside_diameter)
    # one evaluation of the model: at mu_sl = 1 its sliding moment is G_sl (M_sl = mu_sl G_sl); the model's
    # own mu_sl is the SKF formula, with the same mu_EHL
    unit = _skf(*args, sliding_friction_coefficient=1.0, **model)
    ehl = {"ehl_coefficient": model["ehl_coefficient"]} if "ehl_coefficient" in model else {}
    mu_of_model = sliding_friction_coefficient(kinematic_viscosity, shaft_speed,
                                               0.5 * (np.asarray(bore) + np.asarray(outside_diameter)), **ehl)
    parts = (t, unit.rolling_moment, unit.sliding_moment, unit.seal_moment + unit.drag_moment, mu_of_model)
    shape = np.broadcast(*parts).shape
    t, m_rr, g_sl, other, mu_model = (np.broadcast_to(p, shape).ravel() for p in parts)
    _x, y, index, n, labels = _prepare(g_sl, t - other, groups, "sliding_variable", "torque")
    count = np.bincount(index, minlength=n)
    mu_mean = np.bincount(index, weights=mu_model, minlength=n) / count
    nan = np.full(n, np.nan)
    if fit == "both":
        mu, k, se_mu, se_k, rms, m, r = _two_regressors(g_sl, m_rr, y, index, n, labels)
    elif fit == "sliding":
        mu, _a, se_mu, _sa, rms, m, r = _stats(
            g_sl, y - m_rr, index, n, labels, intercept=False, what="task 4", x_name="load"
        )
        k, se_k = np.ones(n), nan
    else:
        k, _a, se_k, _sa, rms, m, r = _stats(
            m_rr, y - mu_model * g_sl, index, n, labels, intercept=False, what="task 4",
            x_name="speed (a rolling moment)"
        )
        mu, se_mu = nan, nan
    fit = _pack(SKFFrictionFit, labels, mu, k, se_mu, se_k, mu_mean, rms, m, residuals=r)
    return fit._replace(model_residuals=t - (m_rr + mu_model * g_sl + other))

r"""The equilibrium equations of one ball and the ring under thrust at speed: spec 004 sections 3 and 5.

Under pure thrust every ball is in the same state, so the model is one ball plus the ring: five
equations in the ball-centre position, the two contact deflections and the axial displacement of the
inner ring.

Residuals
---------
residual         scaled residuals and analytic Jacobian of the five equations (section 5.1)
Residual         residual, Jacobian and validity
angle_residual   E3 and E7 of the paper's contact-angle iteration for trial angles (section 5.2)
AngleResidual    E3, E7, ball loads, deflections, delta_a and validity
STATUS           per-case status codes of the solution (index = code)

The private kernel (``_prepare`` checks and flattens the inputs into a ``_Model``; ``_equations`` and
``_angle_sequence`` evaluate it for a batch of cases) is shared by the solvers of
:mod:`bearinglab.quasistatic.continuation` and :mod:`bearinglab.quasistatic.search`.

Conventions: the outer ring is fixed and the inner ring turns at ``shaft_speed`` >= 0 (the model is
symmetric in the direction of rotation); the thrust acts on the inner ring. The gyroscopic moment M_g
is a magnitude (>= 0) and the friction that resists it enters eqs. (5)-(7) with the physical sign of
spec 004 section 4.

References
----------
.. [1] Zhao Chunjiang, Cui Guohua, Wang Guoqiang, Huang Qingxue and Zhang Fangping, "Precise definition
   of the contact-angle field of a high-speed angular-contact ball bearing under axial load,"
   Transactions of the CSAM, vol. 39, no. 12, pp. 154-156, 209, 2008 (spec 004 of this project).
.. [2] A. B. Jones, "A general theory for elastically constrained ball and radial roller bearings under
   arbitrary load and speed conditions," J. Basic Eng., vol. 82, no. 2, pp. 309-320, 1960,
   doi:10.1115/1.3662587.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from .. import _bounds, geometry
from .._validate import (
    as_float,
    check_integer,
    check_open_interval,
    check_positive_finite,
)
from ..errors import InputError
from ..units import MM, RPM
from .ball import CONSTANTS, _angle, _control, _kinematics, _speed
from .contact import _hertz_tables, _k

__all__ = ["STATUS", "AngleResidual", "Residual", "angle_residual", "residual"]

#: Per-case status codes of :class:`~bearinglab.quasistatic.HighSpeedState` (index = code).
STATUS = ("ok", "no_convergence", "inner_contact_lost", "outer_contact_lost", "angle_out_of_range",
          "search_not_root")

_OK, _NOCONV, _INNER_LOST, _OUTER_LOST, _ANGLE_OUT, _NOT_ROOT = range(6)
_STATUS_TEXT = {
    _NOCONV: "no convergence",
    _INNER_LOST: "the ball leaves the inner raceway (delta_i <= 0 or Q_i < 0): thrust too small for the speed",
    _OUTER_LOST: "the ball leaves the outer raceway (delta_e <= 0)",
    _ANGLE_OUT: "a contact angle leaves (0, 90) deg: thrust too small for the speed",
    _NOT_ROOT: "the minimum of the contact-angle search is not a root (sum E^2 >= 1e-20)",
}


# --------------------------------------------------------------------------- the model
class _Model(NamedTuple):
    fa: np.ndarray  # per case (N,)
    z: np.ndarray
    d: np.ndarray
    dm: np.ndarray
    fi: np.ndarray
    fo: np.ndarray
    a0: np.ndarray
    ep: np.ndarray
    ax0: np.ndarray  # B D sin a0
    az: np.ndarray  # B D cos a0
    mass_c: np.ndarray  # mass in F_c = m (d_m/2) w_m^2
    inertia: np.ndarray  # J in M_g = J w_R w_m sin beta
    fs: np.ndarray  # force scale of the residuals
    lam_i: float
    lam_e: float
    sign: float
    control: str
    gid: np.ndarray  # geometry index into the stiffness tables
    t_inner: dict  # Chebyshev tables of the exact Hertz quantities, see _hertz_tables
    t_outer: dict


def _constants(constants):
    if isinstance(constants, str):
        if constants not in CONSTANTS:
            raise InputError(f"constants must be one of {list(CONSTANTS)} or a pair (C_c, C_g), got {constants!r}")
        return CONSTANTS[constants]
    try:
        cc, cg = (float(c) for c in constants)
    except (TypeError, ValueError) as exc:
        raise InputError(f"constants must be one of {list(CONSTANTS)} or a pair (C_c, C_g), got {constants!r}") from exc
    if not (cc >= 0 and cg >= 0 and math.isfinite(cc) and math.isfinite(cg)):
        raise InputError(f"constants: C_c and C_g must be >= 0 and finite [N; mm; rpm], got ({cc!r}, {cg!r})")
    return cc, cg


# Numerical floors of the solve, not physical limits: a dimensionless ball load F_a / (Z E' B_d^2) below
# 1e-20 gives a deflection (~ load^(2/3) B_d, ~1e-13 of it) that the angle cannot resolve in double precision
# (the first approximation returns alpha0 exactly and the Newton step divides by zero); a free angle below
# 1e-100 rad has a sine whose square underflows.
_SMALLEST_LOAD = 1e-20
_SMALLEST_ANGLE = 1e-100


def _prepare(axial_load, n_balls, ball_diameter, pitch_diameter, inner_conformity, outer_conformity, free_angle,
             reduced_modulus, density, raceway_control, gyroscopic_sign, constants, shape=None):
    """Check inputs and broadcast them to flat per-case arrays."""
    fa = check_positive_finite("axial_load", axial_load, "N")
    z = check_integer("n_balls", n_balls, 1, _bounds.MAX_BALLS)
    d = check_positive_finite("ball_diameter", ball_diameter, "m")
    dm = check_positive_finite("pitch_diameter", pitch_diameter, "m")
    geometry.pitch_ratio(d, dm, 0.0)  # d_m > D
    fi = check_open_interval("inner_conformity", inner_conformity, 0.5, np.inf, "-")
    fo = check_open_interval("outer_conformity", outer_conformity, 0.5, np.inf, "-")
    a0 = _angle("free_angle", free_angle)
    if np.any(np.asarray(a0) < _SMALLEST_ANGLE):  # sin^2 alpha0 of the first approximation underflows
        raise InputError(f"free_angle must be >= {_SMALLEST_ANGLE:g} [rad], got {float(np.min(a0))!r}")
    ep = check_positive_finite("reduced_modulus", reduced_modulus, "Pa")
    rho = check_positive_finite("density", density, "kg/m^3")
    lam_i, lam_e = _control(raceway_control)
    if gyroscopic_sign not in (1, -1):
        raise InputError(f"gyroscopic_sign must be +1 (physical) or -1 (reversed), "
                         f"got {gyroscopic_sign!r}")
    consts = _constants(constants)
    arrays = np.broadcast_arrays(fa, z, d, dm, fi, fo, a0, ep, rho, *(() if shape is None else (np.empty(shape),)))
    out_shape = arrays[0].shape
    fa, z, d, dm, fi, fo, a0, ep, rho = (np.ascontiguousarray(a, dtype=float).ravel() for a in arrays[:9])
    bd = (fi + fo - 1.0) * d
    load = fa / (z * ep * bd**2)  # the ball load over the Hertz scale of the groove distance, [-]
    if not np.all(load >= _SMALLEST_LOAD):
        k = int(np.flatnonzero(~(load >= _SMALLEST_LOAD))[0])
        least = _SMALLEST_LOAD * z[k] * ep[k] * bd[k] ** 2
        raise InputError(f"axial_load must be >= {least:.3g} [N] to be resolved (axial_load / (n_balls E' "
                         f"((f_i + f_o - 1) D)^2) >= {_SMALLEST_LOAD:g}: below it the contact deflection is lost to "
                         f"rounding and the angles cannot move), got {fa[k]:g} N")
    if consts is None:
        mass = rho * np.pi * d**3 / 6.0
        mass_c, inertia = mass, mass * d**2 / 10.0
    else:  # the printed constants in N, mm, rpm (steel only), as an equivalent mass and inertia
        mass_c = consts[0] * (d / MM) ** 3 * 2.0 / (MM * RPM**2)
        inertia = consts[1] * (d / MM) ** 5 * MM / RPM**2
    geo = np.stack([d, dm, fi, fo, ep], axis=1)
    if geo.size == 0 or np.all(geo == geo[:1]):  # one bearing: skip the sort of np.unique
        uniq, gid = geo[:1], np.zeros(len(geo), dtype=int)
    else:
        uniq, gid = np.unique(geo, axis=0, return_inverse=True)
    t_in, t_out = _hertz_tables(*uniq.T)
    model = _Model(fa, z.astype(float), d, dm, fi, fo, a0, ep, bd * np.sin(a0), bd * np.cos(a0), mass_c, inertia,
                   np.maximum(fa / z, 1.0), lam_i, lam_e, float(gyroscopic_sign), raceway_control,
                   gid.ravel(), t_in, t_out)
    return model, out_shape


def _take(model, idx):
    """Per-case parameters of the cases ``idx``."""
    names = ("fa", "z", "d", "dm", "fi", "fo", "a0", "ep", "ax0", "az", "mass_c", "inertia", "fs", "gid")
    return {n: getattr(model, n)[idx] for n in names}


def _forces(model, p, si, ci, se, ce, ai, ae, di, de, w2, deriv):
    """Contact loads, dynamics and the force residuals (5)-(7) at given angles and deflections."""
    g = p["d"] / p["dm"]
    kin = _kinematics(si, ci, se, ce, ai, ae, g, model.control, deriv)
    ki, dlki = _k(model.t_inner, p["gid"], ci)
    ke, dlke = _k(model.t_outer, p["gid"], ce)
    dip, dep = np.maximum(di, 0.0), np.maximum(de, 0.0)
    qi, qe = ki * dip**1.5, ke * dep**1.5
    fc_hat = p["mass_c"] * p["dm"] / 2.0 * kin["cage"] ** 2  # F_c / omega^2
    sb = np.sin(kin["beta"])
    mg_hat = p["inertia"] * kin["spin"] * kin["cage"] * sb  # M_g / omega^2
    m_hat = model.sign * mg_hat / p["d"]
    li, le = model.lam_i, model.lam_e
    ax_t = li * ci - le * ce
    rad_t = li * si - le * se
    fs = p["fs"]
    out = {"kin": kin, "qi": qi, "qe": qe, "ki": ki, "ke": ke, "fc_hat": fc_hat, "mg_hat": mg_hat}
    m = w2 * m_hat
    out["f"] = np.stack([(qi * si - qe * se + m * ax_t) / fs,  # eq. (5)
                         (qi * ci - qe * ce - m * rad_t + w2 * fc_hat) / fs,  # eq. (6)
                         (qi * si + m * li * ci - p["fa"] / p["z"]) / fs], axis=-1)  # eq. (7) / Z
    out["f_w2"] = np.stack([m_hat * ax_t / fs, (-m_hat * rad_t + fc_hat) / fs, m_hat * li * ci / fs], axis=-1)
    if deriv:
        cage, spin = kin["cage"], kin["spin"]
        cb = np.cos(kin["beta"])
        mg_i = p["inertia"] * (kin["spin_i"] * cage * sb + spin * kin["cage_i"] * sb + spin * cage * cb * kin["beta_i"])
        mg_e = p["inertia"] * (kin["spin_e"] * cage * sb + spin * kin["cage_e"] * sb + spin * cage * cb * kin["beta_e"])
        m_i = w2 * model.sign * mg_i / p["d"]
        m_e = w2 * model.sign * mg_e / p["d"]
        fc_i = w2 * p["mass_c"] * p["dm"] * cage * kin["cage_i"]
        fc_e = w2 * p["mass_c"] * p["dm"] * cage * kin["cage_e"]
        qi_a = -qi * si * dlki  # dK/dalpha = K dlnK/dc (-sin alpha)
        qe_a = -qe * se * dlke
        qi_d = 1.5 * ki * np.sqrt(dip)
        qe_d = 1.5 * ke * np.sqrt(dep)
        zero = np.zeros_like(qi)
        # partials of (f3, f4, f5) with respect to (alpha_i, alpha_e, delta_i, delta_e)
        f3 = [qi_a * si + qi * ci + m_i * ax_t - m * li * si,
              -qe_a * se - qe * ce + m_e * ax_t + m * le * se, qi_d * si, -qe_d * se]
        f4 = [qi_a * ci - qi * si - m_i * rad_t - m * li * ci + fc_i,
              -qe_a * ce + qe * se - m_e * rad_t + m * le * ce + fc_e, qi_d * ci, -qe_d * ce]
        f5 = [qi_a * si + qi * ci + m_i * li * ci - m * li * si, m_e * li * ci, qi_d * si, zero]
        out["df"] = np.stack([np.stack(row, axis=-1) for row in (f3, f4, f5)], axis=-2) / fs[..., None, None]
    return out


class Residual(NamedTuple):
    """Scaled residuals of spec 004 section 5.1 (and their Jacobian)."""

    residual: np.ndarray  # (..., 5) [-]
    jacobian: np.ndarray  # (..., 5, 5) d residual / d unknowns (unknowns scaled by D) [-]
    valid: np.ndarray  # delta_i, delta_e > 0 and both angles in (0, 90 deg)


def _equations(model, idx, v, w2, deriv):
    """Residuals r (n, 5), Jacobian (n, 5, 5) w.r.t. v = u / D, validity and the force details."""
    p = _take(model, idx)
    d = p["d"]
    x1, x2, di, de, da = (v[:, k] * d for k in range(5))
    px = p["ax0"] + da - x1  # inner groove centre minus ball centre, eq. (1)
    pz = p["az"] - x2  # eq. (2)
    rho_i = np.hypot(px, pz)
    rho_e = np.hypot(x1, x2)
    si, ci = px / rho_i, pz / rho_i
    se, ce = x1 / rho_e, x2 / rho_e
    ai, ae = np.arctan2(px, pz), np.arctan2(x1, x2)
    li_len = (p["fi"] - 0.5) * d + di
    le_len = (p["fo"] - 0.5) * d + de
    fr = _forces(model, p, si, ci, se, ce, ai, ae, di, de, w2, deriv)
    r = np.concatenate([((rho_i - li_len) / d)[:, None], ((rho_e - le_len) / d)[:, None], fr["f"]], axis=1)
    code = np.full(len(idx), _OK)
    code[~((ae > 0) & (ae < np.pi / 2) & (ai > 0) & (ai < np.pi / 2))] = _ANGLE_OUT
    code[~(de > 0)] = _OUTER_LOST
    code[~(di > 0)] = _INNER_LOST
    jac = None
    if deriv:
        jac = np.zeros((len(idx), 5, 5))
        jac[:, 0, :] = np.stack([-si, -ci, -np.ones_like(si), np.zeros_like(si), si], axis=1)  # d rho_i - d L_i
        jac[:, 1, :] = np.stack([se, ce, np.zeros_like(si), -np.ones_like(si), np.zeros_like(si)], axis=1)
        # d alpha / d (x1, x2, delta_a): alpha_i = atan2(px, pz), alpha_e = atan2(x1, x2)
        dai = np.stack([-ci / rho_i, si / rho_i, ci / rho_i], axis=1)
        dae = np.stack([ce / rho_e, -se / rho_e, np.zeros_like(se)], axis=1)
        df = fr["df"]  # (n, 3, 4): d/d(alpha_i, alpha_e, delta_i, delta_e)
        jac[:, 2:, 0] = df[:, :, 0] * dai[:, None, 0] + df[:, :, 1] * dae[:, None, 0]
        jac[:, 2:, 1] = df[:, :, 0] * dai[:, None, 1] + df[:, :, 1] * dae[:, None, 1]
        jac[:, 2:, 2] = df[:, :, 2] * d[:, None]
        jac[:, 2:, 3] = df[:, :, 3] * d[:, None]
        jac[:, 2:, 4] = df[:, :, 0] * dai[:, None, 2]
        jac[:, 2:, 0:2] *= d[:, None, None]
        jac[:, 2:, 4] *= d[:, None]
    r_w2 = np.concatenate([np.zeros((len(idx), 2)), fr["f_w2"]], axis=1)
    extra = {"ai": ai, "ae": ae, "di": di, "de": de, "da": da, "fr": fr, "p": p, "r_w2": r_w2}
    return r, jac, code, extra


def residual(unknowns, axial_load, shaft_speed, n_balls, ball_diameter, pitch_diameter, inner_conformity,
             outer_conformity, free_angle, reduced_modulus, density, *, raceway_control="outer",
             gyroscopic_sign=1, constants="mass"):
    r"""Scaled residuals and Jacobian of the equilibrium equations of spec 004 section 5.1.

    Parameters
    ----------
    unknowns : array_like
        Shape (..., 5): ball-centre position (X1, X2) from the outer groove-curvature centre, deflections
        delta_i, delta_e and axial displacement delta_a, all divided by the ball diameter D. [-]
    axial_load : array_like
        Thrust F_a. [N]
    shaft_speed : array_like
        Inner-ring speed omega_i >= 0. [rad/s]
    n_balls : array_like
        Z. [-]
    ball_diameter : array_like
        D. [m]
    pitch_diameter : array_like
        d_m. [m]
    inner_conformity, outer_conformity : array_like
        f_i, f_e. [-]
    free_angle : array_like
        alpha0. [rad]
    reduced_modulus : array_like
        E'. [Pa]
    density : array_like
        Density of the balls. [kg/m^3]
    raceway_control : {"outer", "inner"}, optional
        lambda_i, lambda_e = (0, 2) or (2, 0).
    gyroscopic_sign : {1, -1}, optional
        +1 physical (spec 004 section 4); -1 the reversed convention, for comparison only.
    constants : {"mass", "harris", "paper"} or (float, float), optional
        How F_c and M_g are computed (see :func:`~bearinglab.quasistatic.contact_angles`).

    Returns
    -------
    Residual
        ``residual`` (..., 5): geometric residuals (distance between ball and groove centres minus
        (f - 0.5) D + delta, divided by D) and eqs. (5), (6), (7)/Z divided by max(F_a/Z, 1 N);
        ``jacobian`` (..., 5, 5) with respect to ``unknowns``; ``valid``.

    Notes
    -----
    :func:`~bearinglab.quasistatic.contact_angles` drives these residuals below 1e-12 (Euclidean norm). The Jacobian is
    analytic: the kinematics (9), (10), (13) differentiated in closed form, d ln K/d cos(alpha) from the
    Chebyshev interpolant of the exact Hertz stiffness.
    """
    w = _speed("shaft_speed", shaft_speed)
    v = as_float("unknowns", unknowns)
    if v.shape[-1:] != (5,):
        raise InputError(f"unknowns must have a last axis of length 5 (X1, X2, delta_i, delta_e, delta_a), got shape {v.shape}")
    model, shape = _prepare(axial_load, n_balls, ball_diameter, pitch_diameter, inner_conformity, outer_conformity,
                            free_angle, reduced_modulus, density, raceway_control, gyroscopic_sign, constants,
                            shape=np.broadcast_shapes(v.shape[:-1], np.shape(w)))
    n = model.fa.size
    vv = np.broadcast_to(v, shape + (5,)).reshape(n, 5)
    w2 = np.broadcast_to(w, shape).ravel() ** 2
    r, jac, code, _ = _equations(model, np.arange(n), vv, w2, True)
    return Residual(r.reshape(shape + (5,)), jac.reshape(shape + (5, 5)), (code == _OK).reshape(shape))


class AngleResidual(NamedTuple):
    """The paper's sequence (spec 004 section 5.2, steps 1-5) for trial contact angles."""

    radial: np.ndarray  # E3, radial compatibility, divided by D [-]
    ring: np.ndarray  # E7, ring equilibrium, divided by Z max(F_a/Z, 1 N) [-]
    ball_load_inner: np.ndarray  # Q_i [N]
    ball_load_outer: np.ndarray  # Q_e [N]
    deflection_inner: np.ndarray  # delta_i [m]
    deflection_outer: np.ndarray  # delta_e [m]
    axial_displacement: np.ndarray  # delta_a [m]
    valid: np.ndarray  # Q_i, Q_e >= 0 and the system (5)-(6) not singular


def _angle_sequence(model, idx, ai, ae, w2):
    p = _take(model, idx)
    si, ci, se, ce = np.sin(ai), np.cos(ai), np.sin(ae), np.cos(ae)
    g = p["d"] / p["dm"]
    kin = _kinematics(si, ci, se, ce, ai, ae, g, model.control, False)
    ki = _k(model.t_inner, p["gid"], ci)[0]
    ke = _k(model.t_outer, p["gid"], ce)[0]
    fc = w2 * p["mass_c"] * p["dm"] / 2.0 * kin["cage"] ** 2
    m = w2 * model.sign * p["inertia"] * kin["spin"] * kin["cage"] * np.sin(kin["beta"]) / p["d"]
    li, le = model.lam_i, model.lam_e
    b1 = -m * (li * ci - le * ce)  # eq. (5): Q_i s_i - Q_e s_e = b1
    b2 = m * (li * si - le * se) - fc  # eq. (6): Q_i c_i - Q_e c_e = b2
    det = se * ci - si * ce  # sin(alpha_e - alpha_i)
    with np.errstate(divide="ignore", invalid="ignore"):
        qi = (se * b2 - ce * b1) / det
        qe = (si * b2 - ci * b1) / det
    valid = (np.abs(det) > 1e-12) & (qi >= 0) & (qe >= 0)
    qi_p, qe_p = np.where(valid, qi, 0.0), np.where(valid, qe, 0.0)
    di, de = (qi_p / ki) ** (2.0 / 3.0), (qe_p / ke) ** (2.0 / 3.0)  # eqs. (14), (15)
    d = p["d"]
    li_len = (p["fi"] - 0.5) * d + di
    le_len = (p["fo"] - 0.5) * d + de
    vx = li_len * si  # eq. (22)
    vz = p["az"] - le_len * ce  # eq. (23)
    da = vx + le_len * se - p["ax0"]  # axial closure, A_x = V_x + L_e sin a_e
    e3 = (li_len * ci - vz) / d  # eq. (3): V_z = L_i cos a_i
    e7 = (p["z"] * (qi_p * si + m * li * ci) - p["fa"]) / (p["z"] * p["fs"])  # eq. (7)
    return AngleResidual(e3, e7, qi, qe, di, de, da, valid)


def angle_residual(contact_angle_inner, contact_angle_outer, axial_load, shaft_speed, n_balls, ball_diameter,
                   pitch_diameter, inner_conformity, outer_conformity, free_angle, reduced_modulus, density, *,
                   raceway_control="outer", gyroscopic_sign=1, constants="mass"):
    r"""The paper's sequence for trial contact angles: loads, deflections, delta_a and residuals E3, E7.

    Parameters
    ----------
    contact_angle_inner, contact_angle_outer : array_like
        Trial alpha_i, alpha_e. [rad]
    axial_load : array_like
        F_a. [N]
    shaft_speed : array_like
        omega_i > 0 (at zero speed eqs. (5)-(6) are homogeneous). [rad/s]
    n_balls : array_like
        Z. [-]
    ball_diameter : array_like
        D. [m]
    pitch_diameter : array_like
        d_m. [m]
    inner_conformity, outer_conformity : array_like
        f_i, f_e. [-]
    free_angle : array_like
        alpha0. [rad]
    reduced_modulus : array_like
        E'. [Pa]
    density : array_like
        Density of the balls. [kg/m^3]
    raceway_control : {"outer", "inner"}, optional
        See :func:`residual`.
    gyroscopic_sign : {1, -1}, optional
        See :func:`residual`.
    constants : {"mass", "harris", "paper"} or (float, float), optional
        See :func:`~bearinglab.quasistatic.contact_angles`.

    Returns
    -------
    AngleResidual
        E3 and E7 (E4-E6 vanish by construction), Q_i, Q_e [N], delta_i, delta_e, delta_a [m], validity.

    Notes
    -----
    Spec 004 section 5.2: beta, n_m, n_b, F_c, M_g, K from (8)-(21) at the trial angles; Q_i, Q_e from the
    linear system (5)-(6) (singular where alpha_i = alpha_e); delta from (14)-(15); V_x, V_z from (22),
    (23); delta_a from the axial closure; E3 is eq. (3) and E7 eq. (7). The sum E3^2 + E7^2 is the
    criterion (24).
    """
    ai = _angle("contact_angle_inner", contact_angle_inner)
    ae = _angle("contact_angle_outer", contact_angle_outer)
    w = _speed("shaft_speed", shaft_speed)
    model, shape = _prepare(axial_load, n_balls, ball_diameter, pitch_diameter, inner_conformity, outer_conformity,
                            free_angle, reduced_modulus, density, raceway_control, gyroscopic_sign, constants,
                            shape=np.broadcast_shapes(np.shape(ai), np.shape(ae), np.shape(w)))
    n = model.fa.size
    flat = [np.broadcast_to(a, shape).ravel() for a in (ai, ae, w)]
    out = _angle_sequence(model, np.arange(n), flat[0], flat[1], flat[2] ** 2)
    return AngleResidual(*(np.asarray(f).reshape(shape)[()] for f in out))



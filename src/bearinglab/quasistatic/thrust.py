r"""The bearing under pure thrust at speed: solutions and analyses of spec 004.

Ball centrifugal force and gyroscopic moment pull the inner and outer contact angles apart at speed.

Solutions for arrays of loads and speeds
----------------------------------------
contact_angles            the full quasi-static state: batched Newton-Raphson with continuation in
                          speed (section 5.1), or the paper's contact-angle search (section 5.2)
zero_displacement_thrust  the thrust at which the axial displacement changes sign, per speed
HighSpeedState            the result (SI units), with per-case convergence and status

Analyses on a :class:`~bearinglab.bearing.BallBearing`
------------------------------------------------------
high_speed_analysis       one bearing, loads and speeds broadcast against each other
sign_change_thrust        the thrust at which delta_a changes sign, for one bearing and its speeds
sweep                     a loads x speeds grid in chunks (``execution=parallel.Execution(...)``);
                          failures flagged per case
result_table              the result as columns in engineering units (CSV, JSON)

References
----------
.. [1] Zhao Chunjiang, Cui Guohua, Wang Guoqiang, Huang Qingxue and Zhang Fangping, "Precise definition
   of the contact-angle field of a high-speed angular-contact ball bearing under axial load,"
   Transactions of the CSAM, vol. 39, no. 12, pp. 154-156, 209, 2008 (spec 004 of this project).
.. [2] T. A. Harris and M. N. Kotzalas, *Advanced Concepts of Bearing Technology*, 5th ed., CRC Press,
   2006, ch. 3 (high-speed ball bearings), doi:10.1201/9781420006582.
"""

from __future__ import annotations

import math
import warnings
from typing import NamedTuple

import numpy as np

from .. import _solve, geometry, hertz, parallel
from .._validate import check_integer, check_positive
from ..errors import ConvergenceError, InputError, ValidityWarning
from ..units import RPM
from .ball import (
    FRICTION_WARNING_LIMIT,
    _speed,
    attitude_angle,
    ball_speeds,
    centrifugal_force,
    gyroscopic_moment,
    required_friction_coefficient,
)
from .contact import _hertz_coefficients, _k
from .continuation import _newton, _static_start, _unknowns_from
from .equations import (
    _NOCONV,
    _NOT_ROOT,
    _OK,
    _STATUS_TEXT,
    STATUS,
    _angle_sequence,
    _equations,
    _prepare,
)
from .search import _ROOT_TOL, _angle_iteration

__all__ = [
    "HighSpeedState",
    "contact_angles",
    "high_speed_analysis",
    "result_table",
    "sign_change_thrust",
    "sweep",
    "zero_displacement_thrust",
]

_SWEEP_CHUNK_SIZE = 20_000
# statuses that mean the inputs have no physical solution (not a weak solver): the ball leaves a raceway
_NO_SOLUTION = ("inner_contact_lost", "outer_contact_lost", "angle_out_of_range")  # cases per chunk of sweep() when the execution does not say

# --------------------------------------------------------------------------- results
class HighSpeedState(NamedTuple):
    """Quasi-static state of a high-speed angular-contact ball bearing under thrust (SI units).

    Failed cases (``converged`` False) carry NaN in every physical field and the reason in ``status``.
    """

    axial_load: np.ndarray  # F_a [N]
    shaft_speed: np.ndarray  # omega_i [rad/s]
    contact_angle_inner: np.ndarray  # alpha_i [rad]
    contact_angle_outer: np.ndarray  # alpha_e [rad]
    static_contact_angle: np.ndarray  # alpha_s at the same thrust, zero speed [rad]
    axial_displacement: np.ndarray  # delta_a [m]
    ball_load_inner: np.ndarray  # Q_i [N]
    ball_load_outer: np.ndarray  # Q_e [N]
    deflection_inner: np.ndarray  # delta_i [m]
    deflection_outer: np.ndarray  # delta_e [m]
    centrifugal_force: np.ndarray  # F_c [N]
    gyroscopic_moment: np.ndarray  # M_g >= 0 [N m]
    attitude_angle: np.ndarray  # beta [rad]
    cage_speed: np.ndarray  # omega_m [rad/s]
    ball_spin_speed: np.ndarray  # omega_R [rad/s]
    bpfo: np.ndarray  # Z omega_m, ball-pass frequency of the fixed outer ring [rad/s]
    bpfi: np.ndarray  # Z (omega_i - omega_m) [rad/s]
    max_pressure_inner: np.ndarray  # p_max at the inner contact [Pa]
    max_pressure_outer: np.ndarray  # p_max at the outer contact [Pa]
    axial_stiffness: np.ndarray  # dF_a / d delta_a [N/m]
    friction_coefficient: np.ndarray  # 2 M_g / (D Q) at the controlling raceway (Q_e for outer control) [-]
    converged: np.ndarray  # bool
    residual: np.ndarray  # Euclidean norm of the scaled residuals at the solution [-]
    iterations: np.ndarray  # Newton iterations (all continuation steps) or refinement steps
    status: np.ndarray  # "ok" or the reason of failure, one of STATUS
    method: np.ndarray  # "static", "newton", "search-triangle", "search-quadrant"




def _assemble(model, idx, v, w, alpha_s, ok):
    """Every output of a converged case from the unknowns, through the public functions."""
    n = len(idx)
    out = {k: np.full(n, np.nan) for k in HighSpeedState._fields[2:21]}
    out["static_contact_angle"] = alpha_s
    out["residual"] = np.full(n, np.nan)
    if not ok.any():
        return out
    sel = np.flatnonzero(ok)
    ii = idx[sel]
    r, jac, _code, ex = _equations(model, ii, v[sel], w[sel] ** 2, True)
    p = ex["p"]
    ai, ae = ex["ai"], ex["ae"]
    d, dm = p["d"], p["dm"]
    beta = attitude_angle(ai, ae, d, dm, raceway_control=model.control)
    speeds = ball_speeds(w[sel], ai, ae, beta, d, dm)
    fc = centrifugal_force(speeds.cage_speed, p["mass_c"], dm)
    mg = gyroscopic_moment(speeds.ball_spin_speed, speeds.cage_speed, beta, 10.0 * p["inertia"] / d**2, d)
    fr = ex["fr"]
    inner = geometry.raceway_curvature(d, dm, p["fi"], ai, race="inner")
    outer = geometry.raceway_curvature(d, dm, p["fo"], ae, race="outer")
    h_i = _hertz_coefficients(model.t_inner, p["gid"], np.cos(ai))
    h_o = _hertz_coefficients(model.t_outer, p["gid"], np.cos(ae))
    pc_i = hertz.point_contact(fr["qi"], inner.curvature_sum, inner.curvature_difference, p["ep"], hertz=h_i)
    pc_o = hertz.point_contact(fr["qe"], outer.curvature_sum, outer.curvature_difference, p["ep"], hertz=h_o)
    # axial stiffness by implicit differentiation: J dv = -dr/dF_a dF_a, dr5/dF_a = -1/(Z fs)
    rhs = np.zeros((len(sel), 5))
    rhs[:, 4] = 1.0 / (p["z"] * p["fs"])
    dv = np.linalg.solve(jac, rhs[:, :, None])[:, :, 0]
    vals = {
        "contact_angle_inner": ai, "contact_angle_outer": ae, "axial_displacement": ex["da"],
        "ball_load_inner": fr["qi"], "ball_load_outer": fr["qe"], "deflection_inner": ex["di"],
        "deflection_outer": ex["de"], "centrifugal_force": fc, "gyroscopic_moment": mg, "attitude_angle": beta,
        "cage_speed": speeds.cage_speed, "ball_spin_speed": speeds.ball_spin_speed,
        "bpfo": p["z"] * speeds.cage_speed, "bpfi": p["z"] * (w[sel] - speeds.cage_speed),
        "max_pressure_inner": pc_i.p_max, "max_pressure_outer": pc_o.p_max, "axial_stiffness": 1.0 / (dv[:, 4] * d),
        "friction_coefficient": required_friction_coefficient(mg, fr["qe"] if model.lam_e > 0 else fr["qi"], d),
        "residual": np.sqrt(np.einsum("ij,ij->i", r, r)),
    }
    for k, val in vals.items():
        out[k][sel] = val
    return out


def _solve_numpy(model, wf, method, *, tol, max_iter, speed_step):
    """The numpy engine: static starts, batched Newton (or the angle iteration) and the full state."""
    n = model.fa.size
    idx = np.arange(n)
    alpha_s, di0, de0, da0 = _static_start(model, idx)
    v0 = _unknowns_from(model, idx, alpha_s, di0, de0, da0)
    status = np.zeros(n, dtype=int)
    iters = np.zeros(n, dtype=int)
    meth = np.full(n, "newton", dtype=object)
    if method == "newton":
        v, status, iters, _norm, _w_ok = _newton(model, idx, wf, v0, tol=tol, max_iter=max_iter, speed_step=speed_step)
    else:
        v = v0.copy()
        moving = np.flatnonzero(wf > 0)
        if moving.size:
            ai, ae, f, it, how = _angle_iteration(model, idx[moving], wf[moving], alpha_s[moving])
            seq = _angle_sequence(model, idx[moving], ai, ae, wf[moving] ** 2)
            v[moving] = _unknowns_from(model, idx[moving], ae, seq.deflection_inner, seq.deflection_outer,
                                       seq.axial_displacement)
            status[moving] = np.where(f < _ROOT_TOL, _OK, _NOT_ROOT)
            iters[moving] = it
            meth[moving] = how
    return v, status, iters, meth, _assemble(model, idx, v, wf, alpha_s, status == _OK)


def _compiled_engine(engine, method):
    """True if the compiled kernel runs the Newton solve: engine "compiled", or "auto" with numba installed."""
    if engine == "compiled" and method != "newton":
        raise InputError(f"engine='compiled' implements method='newton' only, got method={method!r}")
    return _solve.use_compiled(engine, auto=method == "newton")


def contact_angles(axial_load, shaft_speed, n_balls, ball_diameter, pitch_diameter, inner_conformity,
                   outer_conformity, free_angle, reduced_modulus, density, *, method="newton",
                   raceway_control="outer", gyroscopic_sign=1, constants="mass", on_failure="raise",
                   tol=_solve.QUASISTATIC_TOL, max_iter=_solve.QUASISTATIC_MAX_ITER,
                   speed_step=None, friction_limit=FRICTION_WARNING_LIMIT, engine="auto"):
    r"""Inner and outer contact angles and the full quasi-static state of a ball bearing under thrust at speed.

    Parameters
    ----------
    axial_load : array_like
        Thrust F_a > 0 on the inner ring. [N]
    shaft_speed : array_like
        Inner-ring speed omega_i >= 0, outer ring fixed. [rad/s]
    n_balls : array_like
        Number of balls Z. [-]
    ball_diameter : array_like
        D. [m]
    pitch_diameter : array_like
        d_m > D. [m]
    inner_conformity, outer_conformity : array_like
        f_i, f_e, each > 0.5. [-]
    free_angle : array_like
        Free contact angle alpha0, in (0, 90 deg). [rad]
    reduced_modulus : array_like
        E' of the ball-ring pair (:func:`bearinglab.hertz.reduced_modulus`). [Pa]
    density : array_like
        Density of the balls (steel 7850, silicon nitride 3200). [kg/m^3]
    method : {"newton", "angle-iteration"}, optional
        Batched Newton-Raphson on the full set (spec 004 section 5.1, default) or the paper's
        contact-angle search (section 5.2).
    raceway_control : {"outer", "inner"}, optional
        Outer-raceway control (lambda_i = 0, lambda_e = 2; the paper's and Harris's assumption, default)
        or inner-raceway control (lambda_i = 2, lambda_e = 0).
    gyroscopic_sign : {1, -1}, optional
        Sign of the gyroscopic friction: +1 is the physical one of spec 004 section 4 (default); -1 is the
        reversed convention of Harris's printed equations with a positive M_g, for comparison only.
    constants : {"mass", "harris", "paper"} or (float, float), optional
        "mass" (default): F_c and M_g from the ball mass rho pi D^3/6 and J = m D^2/10, valid for any
        ball material. "harris": the printed constants 2.26e-11 and 4.47e-12 [N; mm; rpm], with which
        the reference results of spec 004 section 7 were computed; "paper": 2.26e-11 and 4.5e-12. A pair
        (C_c, C_g) gives both constants in those units (C_g = 0 drops the gyroscopic moment). The printed
        constants hold for steel balls only.
    on_failure : {"raise", "flag"}, optional
        Raise :class:`~bearinglab.errors.ConvergenceError` if any case fails (default), or return NaN and
        the reason in ``status`` for the failed cases while the others complete.
    tol : float, optional
        Euclidean norm of the scaled residuals below which a case is converged. [-]
    max_iter : int, optional
        Newton iterations per case over all continuation steps.
    speed_step : float, optional
        Largest continuation step in speed (e.g. ``bearinglab._solve.QUASISTATIC_SPEED_STEP_RPM`` = 1500
        rpm, the step of the spec's reference computation). Default None: go to the target speed at once
        and cut the step where Newton fails. [rad/s]
    friction_limit : float, optional
        Warn (:class:`~bearinglab.errors.ValidityWarning`) where the friction coefficient that the raceway
        control needs exceeds this. [-]
    engine : {"auto", "numpy", "compiled"}, optional
        How the Newton solve runs: "compiled" by the numba kernel of
        :mod:`~bearinglab.quasistatic._compiled` (the same steps case by case, in parallel over the cases,
        static start and full state included), "numpy" by the batched numpy path, "auto" (default)
        compiled when numba imports and numpy otherwise. Both give the same angles to ~1e-15 rad and
        every output to 1e-12 relative; ``method="angle-iteration"`` always runs on numpy ("compiled"
        then raises).

    Returns
    -------
    HighSpeedState
        Angles, displacement, loads, dynamics, speeds, pressures, stiffness, friction, per-case
        ``converged``, ``residual``, ``iterations``, ``status`` and ``method``; arrays of the broadcast
        shape of the inputs (scalars for scalar inputs).

    Raises
    ------
    ConvergenceError
        With ``on_failure="raise"``, if a case does not converge or has no physical solution (the reason
        is in the message: no convergence, the ball leaving a raceway, an angle leaving (0, 90 deg), a
        search minimum that is not a root).

    Notes
    -----
    Spec 004 section 3, eqs. (1)-(23): outer groove-curvature centre fixed, inner one at
    (B D sin alpha0 + delta_a, B D cos alpha0); ball equilibrium (5)-(6) and ring equilibrium (7) with the
    gyroscopic friction at the controlling raceway; F_c (8), kinematics (9), (10), (13), M_g (12);
    K_i, K_e (16)-(21) from the exact Hertz solution at the operating angles.

    Newton (section 5.1): unknowns (X1, X2, delta_i, delta_e, delta_a)/D; start from the static solution
    of :func:`bearinglab.static.contact_angle_under_thrust` at the same thrust (section 5.3); per-case
    continuation in omega^2 with a tangent predictor: the first step goes to the target speed (or to
    ``speed_step``), steps are cut by 4 where Newton fails and double again after quick convergence; per-case step halving when an iterate is invalid
    (delta <= 0, an angle outside (0, 90 deg)) or does not decrease the residual. All cases are updated
    together (5 x 5 systems solved on stacked arrays). At zero speed the result is the static solution.

    Angle iteration (section 5.2): a 61 x 61 grid over the triangle alpha_s <= alpha_i <= alpha_s + Delta,
    alpha_s - Delta <= alpha_e <= alpha_s, alpha_i + alpha_e <= 2 alpha_s, then a bounded damped Newton
    least-squares refinement; a minimum with sum E^2 >= 1e-20 is not a root, and the whole quadrant is
    searched instead (``method`` "search-quadrant"); if that fails too, the case fails with status
    "search_not_root".

    Examples
    --------
    >>> from bearinglab import bearing
    >>> from bearinglab.units import RPM
    >>> s = contact_angles(20e3, 10000 * RPM, 16, 22.23e-3, 125.3e-3, 0.5232, 0.5232, math.radians(40),
    ...                    bearing.STEEL.elastic_modulus / (1 - 0.3**2), 7850.0, constants="harris")
    >>> print(f"{math.degrees(s.contact_angle_inner):.3f} / {math.degrees(s.contact_angle_outer):.3f} deg")
    49.308 / 32.514 deg
    """
    w = _speed("shaft_speed", shaft_speed)
    if method not in ("newton", "angle-iteration"):
        raise InputError(f"method must be one of ['newton', 'angle-iteration'], got {method!r}")
    if on_failure not in ("raise", "flag"):
        raise InputError(f"on_failure must be one of ['raise', 'flag'], got {on_failure!r}")
    check_positive("tol", tol, "-")
    check_integer("max_iter", max_iter, 1)
    if speed_step is not None:
        speed_step = float(check_positive("speed_step", speed_step, "rad/s"))
    model, shape = _prepare(axial_load, n_balls, ball_diameter, pitch_diameter, inner_conformity, outer_conformity,
                            free_angle, reduced_modulus, density, raceway_control, gyroscopic_sign, constants,
                            shape=np.shape(w))
    n = model.fa.size
    wf = np.broadcast_to(w, shape).ravel().astype(float)
    over = _thrust_bounds(model, wf, on_failure)
    fa_given = model.fa
    if over.any():  # flagged below, not solved: the solve runs at a harmless thrust instead (a ball deflection
        # of 1e-4 D), whose results are dropped
        model = model._replace(fa=np.where(over, 1e-6 * _upper_thrust(model), model.fa))
    if _compiled_engine(engine, method):
        from . import _compiled  # imports numba: only when the compiled path runs

        # the kernel computes each case's static start, solve and full state (what _assemble computes)
        v, status, iters, out = _compiled.solve(model, wf, tol=float(tol), max_iter=int(max_iter),
                                                speed_step=speed_step)
        meth = np.full(n, "newton", dtype=object)
    else:
        v, status, iters, meth, out = _solve_numpy(model, wf, method, tol=tol, max_iter=int(max_iter),
                                                   speed_step=speed_step)
    meth[wf == 0] = "static"
    if over.any():
        status = np.where(over, _NOCONV, status)
        for key in out:
            out[key] = np.where(over, np.nan, out[key])
        model = model._replace(fa=fa_given)
    ok = status == _OK
    failed = np.flatnonzero(~ok)
    if failed.size and on_failure == "raise":
        k = failed[0]
        raise ConvergenceError("quasistatic.contact_angles", iterations=int(iters[k]),
                               residual=out["residual"][k] if np.isfinite(out["residual"][k]) else np.inf,
                               estimate=v[k] * model.d[k],
                               reason=f"{_STATUS_TEXT[status[k]]} at F_a = {model.fa[k]:g} N, "
                                      f"{wf[k] / RPM:g} rpm ({failed.size} of {n} cases failed)",
                               physical=STATUS[status[k]] in _NO_SOLUTION)
    high = ok & (out["friction_coefficient"] > friction_limit)
    if high.any():
        k = np.flatnonzero(high)[0]
        warnings.warn(f"{high.sum()} of {n} cases need a friction coefficient above {friction_limit:g} for "
                      f"{raceway_control}-raceway control (e.g. {out['friction_coefficient'][k]:.3g} at "
                      f"F_a = {model.fa[k]:g} N, {wf[k] / RPM:g} rpm): the balls would spin or skid, the model "
                      "is not valid there", ValidityWarning, stacklevel=2)
    fields = dict(out)
    fields["axial_load"] = model.fa
    fields["shaft_speed"] = wf
    fields["converged"] = ok
    fields["iterations"] = iters
    fields["status"] = np.array(STATUS, dtype=object)[status]
    fields["method"] = meth
    return HighSpeedState(**{k: np.asarray(fields[k]).reshape(shape)[()] for k in HighSpeedState._fields})


#: A thrust below this many times the rounding of the groove geometry (eps A) in ball deflection cannot be
#: resolved; beyond a ball diameter of deflection it is the solver's bound (issue 29).
_RESOLVABLE_DEFLECTION = 1e4
_MAX_DEFLECTION = 1.0


def _upper_thrust(model):
    """Per case, Z max_alpha max(K_i, K_e) D^1.5: the thrust that would compress a ball by its diameter."""
    c = np.linspace(0.0, 1.0, 65)
    k = np.zeros(model.fa.size)
    for table in (model.t_inner, model.t_outer):
        for cj in c:
            k = np.maximum(k, _k(table, model.gid, np.full(model.fa.size, cj))[0])
    return model.z * k * (_MAX_DEFLECTION * model.d) ** 1.5


def _thrust_bounds(model, w, on_failure):
    """Issue 29: a thrust too light to resolve is an InputError; one beyond the solver's bound (a ball
    compressed by more than its diameter) a ConvergenceError, before any work (with ``on_failure="flag"``
    the case is flagged). Returns the cases beyond the bound."""
    bd = (model.fi + model.fo - 1.0) * model.d
    kn = _k(model.t_inner, model.gid, np.cos(model.a0))[0]  # the softer contact bounds the deflection
    kn = np.minimum(kn, _k(model.t_outer, model.gid, np.cos(model.a0))[0])
    deflection = np.cbrt(model.fa / (model.z * kn * np.sin(model.a0))) ** 2
    light = deflection < _RESOLVABLE_DEFLECTION * np.finfo(float).eps * bd
    if light.any():
        k = int(np.flatnonzero(light)[0])
        least = model.z[k] * kn[k] * np.sin(model.a0[k]) * (_RESOLVABLE_DEFLECTION * np.finfo(float).eps * bd[k]) ** 1.5
        raise InputError(f"axial_load must be >= {least:.3g} [N] to be resolved (ball deflections of at least "
                         f"{_RESOLVABLE_DEFLECTION:g} times the rounding of the groove geometry), got {model.fa[k]:g} N")
    over = model.fa > _upper_thrust(model)
    if over.any() and on_failure == "raise":
        k = int(np.flatnonzero(over)[0])
        raise ConvergenceError("quasistatic.contact_angles", iterations=0, residual=np.inf, estimate=np.nan,
                               reason=f"F_a = {model.fa[k]:g} N at {w[k] / RPM:g} rpm: beyond what the bearing can "
                                      f"carry, a thrust above {_upper_thrust(model)[k]:.4g} N would compress a ball by "
                                      "more than its diameter, the solver's bound (a unit mistake?)")
    return over


def zero_displacement_thrust(shaft_speed, n_balls, ball_diameter, pitch_diameter, inner_conformity, outer_conformity,
                             free_angle, reduced_modulus, density, *, rtol=1e-10, max_iter=60, **options):
    r"""Thrust at which the axial displacement delta_a changes sign, for each speed (spec 004 section 7.2).

    Parameters
    ----------
    shaft_speed : array_like
        Inner-ring speeds omega_i >= 0. [rad/s]
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
    rtol : float, optional
        Relative tolerance on the thrust. [-]
    max_iter : int, optional
        Iterations of the outer (thrust) solve.

    Other Parameters
    ----------------
    **options
        ``raceway_control``, ``gyroscopic_sign``, ``constants`` as in :func:`contact_angles`.

    Returns
    -------
    ndarray
        F_a with delta_a(F_a) = 0 (0 at zero speed, where delta_a > 0 for every thrust). [N]

    Notes
    -----
    delta_a rises with the thrust at fixed speed; below the returned thrust the centrifugal force pushes
    the inner ring against the load direction (delta_a < 0). Safeguarded Newton on F_a with the axial
    stiffness dF_a/d delta_a of :func:`contact_angles` as slope, all speeds at once, bracketed between
    0.01 and 100 times Z F_c at the nominal cage speed (the bracket is widened if needed).
    """
    w = _speed("shaft_speed", shaft_speed)
    shape = np.shape(w)
    wf = np.ravel(w).astype(float)
    geo = (n_balls, ball_diameter, pitch_diameter, inner_conformity, outer_conformity, free_angle, reduced_modulus,
           density)
    out = np.zeros(wf.size)
    moving = np.flatnonzero(wf > 0)
    if moving.size == 0:
        return out.reshape(shape)[()]
    ws = wf[moving]
    model, _ = _prepare(1.0, *geo, options.get("raceway_control", "outer"), options.get("gyroscopic_sign", 1),
                        options.get("constants", "mass"))
    g0 = model.d[0] / model.dm[0] * math.cos(model.a0[0])
    scale = model.z[0] * model.mass_c[0] * model.dm[0] / 2.0 * (ws * (1.0 - g0) / 2.0) ** 2

    def solve(fa):
        s = contact_angles(fa, ws, *geo, on_failure="flag", friction_limit=np.inf, **options)
        return s.axial_displacement, s.axial_stiffness

    lo, hi = 0.01 * scale, 100.0 * scale
    da_lo, _ = solve(lo)
    da_hi, _ = solve(hi)
    for _ in range(10):  # widen the bracket where the sign does not change (or the solve failed)
        bad_lo, bad_hi = ~(da_lo < 0), ~(da_hi > 0)
        if not (bad_lo.any() or bad_hi.any()):
            break
        lo = np.where(bad_lo, lo * 0.1, lo)
        hi = np.where(bad_hi, hi * 10.0, hi)
        da_lo, _ = solve(lo)
        da_hi, _ = solve(hi)
    else:
        raise ConvergenceError("quasistatic.zero_displacement_thrust", iterations=10, residual=np.inf, estimate=lo,
                               reason="no thrust bracket with delta_a < 0 below and > 0 above")
    fa = np.sqrt(lo * hi)
    for it in range(1, max_iter + 1):
        da, k = solve(fa)
        lo = np.where(da < 0, fa, lo)
        hi = np.where(da > 0, fa, hi)
        new = fa - da * k
        outside = ~((new > lo) & (new < hi)) | ~np.isfinite(new)
        new = np.where(outside, np.sqrt(lo * hi), new)
        done = np.abs(new - fa) <= rtol * fa
        fa = new
        if np.all(done):
            break
    else:
        raise ConvergenceError("quasistatic.zero_displacement_thrust", iterations=max_iter, residual=da, estimate=fa)
    out[moving] = fa
    return out.reshape(shape)[()]


# --------------------------------------------------------------------------- analyses
def _bearing_args(bearing, reduced_modulus=None):
    z, d, dm, fi, fo, a0 = bearing.require("n_balls", "ball_diameter", "pitch_diameter", "inner_conformity",
                                           "outer_conformity", "contact_angle")
    if _preloaded(bearing):
        raise InputError(f"radial_clearance of {bearing.designation or 'the bearing'!r} is "
                         f"{bearing.radial_clearance * 1e6:.4g} um: no free contact angle for spec 004's model; "
                         "high_speed_analysis solves a preloaded bearing by the 5-DOF model")
    if not 0.0 < a0 < math.pi / 2:
        raise InputError(f"contact_angle of {bearing.designation or 'the bearing'!r} must be in (0, 90) [deg] for the "
                         f"high-speed model under thrust, got {math.degrees(a0):g}")
    ep = bearing.reduced_modulus if reduced_modulus is None else reduced_modulus
    return z, d, dm, fi, fo, a0, ep, bearing.ball_material.density


def _preloaded(bearing):
    """True for a bearing with a zero or negative clearance (issue 30): no free contact angle, every ball
    touching both raceways in the concentric position."""
    e = bearing.radial_clearance
    return e is not None and e <= 0


def _preloaded_analysis(bearing, axial_load, shaft_speed, reduced_modulus, options):
    """:func:`high_speed_analysis` of a bearing with zero or negative clearance, by the 5-DOF model.

    Spec 004's unknowns start from the free contact angle, which such a bearing does not have: its balls
    sit at alpha = 0, compressed by -e/2, before any thrust. Under pure thrust the 5-DOF model with the
    rings held concentric and square (radial and tilt displacements 0, the symmetric solution) is the same
    ball equilibrium (eqs. 5-6 with F_c, M_g and the raceway control, tests/quasistatic/test_combined.py
    checks it ball by ball against this model at positive clearance); the state is assembled from its
    ball 0 through the public functions, as for the other cases. delta_a counts from the concentric
    position, where such a bearing's balls first touch.
    """
    from . import combined

    unsupported = {"method": "newton", "gyroscopic_sign": 1, "constants": "mass"}
    for key, want in unsupported.items():
        if options.get(key, want) != want:
            raise InputError(f"{key}={options[key]!r}: a bearing with zero or negative clearance is solved by the "
                             f"5-DOF model, which takes {key}={want!r} only")
    control = options.get("raceway_control", "outer")
    on_failure = options.get("on_failure", "raise")
    friction_limit = options.get("friction_limit", FRICTION_WARNING_LIMIT)
    fa = check_positive("axial_load", axial_load, "N")
    w = _speed("shaft_speed", shaft_speed)
    shape = np.broadcast_shapes(np.shape(fa), np.shape(w))
    fa, w = (np.broadcast_to(x, shape).ravel().astype(float) for x in (fa, w))
    loads = np.zeros((fa.size, 5))
    loads[:, 2] = fa
    held = [0.0, 0.0, np.nan, 0.0, 0.0]
    kw = {"reduced_modulus": reduced_modulus, "raceway_control": control, "prescribed_displacement": held,
          "on_failure": "flag"}
    r = combined.combined_analysis(bearing, loads, w, **kw)
    rest = combined.combined_analysis(bearing, loads, 0.0, **kw)
    z, d, dm, fi, fo = bearing.require("n_balls", "ball_diameter", "pitch_diameter", "inner_conformity",
                                       "outer_conformity")
    ep = bearing.reduced_modulus if reduced_modulus is None else reduced_modulus
    ai, ae = r.contact_angle_inner[:, 0], r.contact_angle_outer[:, 0]
    qi, qe = r.ball_load_inner[:, 0], r.ball_load_outer[:, 0]
    from .contact import contact_stiffness

    k = contact_stiffness(np.nan_to_num(ai), np.nan_to_num(ae), d, dm, fi, fo, ep)
    beta = attitude_angle(ai, ae, d, dm, raceway_control=control)
    speeds = ball_speeds(w, ai, ae, beta, d, dm)
    mg = np.abs(r.gyroscopic_moment[:, 0])
    with np.errstate(invalid="ignore", divide="ignore"):
        fields = {"axial_load": fa, "shaft_speed": w, "contact_angle_inner": ai, "contact_angle_outer": ae,
                  "static_contact_angle": rest.contact_angle_inner[:, 0], "axial_displacement": r.displacement[:, 2],
                  "ball_load_inner": qi, "ball_load_outer": qe, "deflection_inner": np.cbrt(qi / k.inner) ** 2,
                  "deflection_outer": np.cbrt(qe / k.outer) ** 2, "centrifugal_force": r.centrifugal_force[:, 0],
                  "gyroscopic_moment": mg, "attitude_angle": beta, "cage_speed": speeds.cage_speed,
                  "ball_spin_speed": speeds.ball_spin_speed, "bpfo": z * speeds.cage_speed,
                  "bpfi": z * (w - speeds.cage_speed), "max_pressure_inner": r.max_pressure_inner[:, 0],
                  "max_pressure_outer": r.max_pressure_outer[:, 0], "axial_stiffness": r.stiffness[:, 2, 2],
                  "friction_coefficient": required_friction_coefficient(mg, qe if control == "outer" else qi, d),
                  "converged": r.converged, "residual": r.residual, "iterations": r.iterations,
                  "status": np.where(r.converged, "ok", "no_convergence").astype(object),
                  "method": np.where(w > 0, "newton", "static").astype(object)}
    ok = r.converged
    if not ok.all() and on_failure == "raise":
        j = int(np.flatnonzero(~ok)[0])
        raise ConvergenceError("quasistatic.high_speed_analysis", iterations=int(r.iterations[j]), residual=np.inf,
                               estimate=np.nan, reason=f"preloaded bearing (5-DOF model) at F_a = {fa[j]:g} N, "
                                                       f"{w[j] / RPM:g} rpm: {'; '.join(r.warnings)}")
    high = ok & (fields["friction_coefficient"] > friction_limit)
    if high.any():
        j = int(np.flatnonzero(high)[0])
        warnings.warn(f"{high.sum()} of {fa.size} cases need a friction coefficient above {friction_limit:g} for "
                      f"{control}-raceway control (e.g. {fields['friction_coefficient'][j]:.3g} at F_a = {fa[j]:g} N, "
                      f"{w[j] / RPM:g} rpm): the balls would spin or skid, the model is not valid there",
                      ValidityWarning, stacklevel=3)
    return HighSpeedState(**{k: np.asarray(fields[k]).reshape(shape)[()] for k in HighSpeedState._fields})


def high_speed_analysis(bearing, axial_load, shaft_speed, *, reduced_modulus=None, **options):
    """The quasi-static high-speed state of a bearing under thrust (spec 004).

    Parameters
    ----------
    bearing : BallBearing
        Needs n_balls, ball_diameter, pitch_diameter, both conformities and the free contact angle in
        (0, 90 deg); materials give E' and the ball density. A bearing with zero or negative
        ``radial_clearance`` (no free contact angle: a preload) is solved by the 5-DOF model of
        :mod:`bearinglab.quasistatic.combined` with the rings held concentric and square, the same ball
        equilibrium (``method`` "newton", ``constants`` "mass" and the physical gyroscopic sign only).
    axial_load : array_like
        F_a > 0. [N]
    shaft_speed : array_like
        Inner-ring speed >= 0, broadcast against ``axial_load``. [rad/s]
    reduced_modulus : float, optional
        E' to use instead of the one of the bearing's materials (e.g. 2.15e5 * 3 / 2**1.5 MPa, the
        rounded constant of spec 004 eq. (16)). [Pa]

    Other Parameters
    ----------------
    **options
        Passed to :func:`contact_angles` (``method``, ``raceway_control``, ``gyroscopic_sign``,
        ``constants``, ``on_failure``, ...).

    Returns
    -------
    HighSpeedState

    Examples
    --------
    >>> from bearinglab import catalog
    >>> from bearinglab.units import RPM
    >>> s = high_speed_analysis(catalog.get("B218"), 20e3, 15000 * RPM, constants="harris")
    >>> print(f"{math.degrees(s.contact_angle_inner):.3f} / {math.degrees(s.contact_angle_outer):.3f} deg, "
    ...       f"mu = {s.friction_coefficient:.3f}")
    56.099 / 21.121 deg, mu = 0.086
    """
    from ..bearing import check_model

    check_model(bearing, "high-speed")
    if _preloaded(bearing):  # issue 30: no free contact angle; the 5-DOF model solves it
        return _preloaded_analysis(bearing, axial_load, shaft_speed, reduced_modulus, options)
    return contact_angles(axial_load, shaft_speed, *_bearing_args(bearing, reduced_modulus), **options)


def sign_change_thrust(bearing, shaft_speed, *, reduced_modulus=None, **options):
    """The thrust at which the axial displacement of a bearing changes sign, per speed (spec 004 section 7.2).

    Parameters
    ----------
    bearing : BallBearing
        See :func:`high_speed_analysis`.
    shaft_speed : array_like
        Inner-ring speeds >= 0. [rad/s]
    reduced_modulus : float, optional
        See :func:`high_speed_analysis`. [Pa]

    Other Parameters
    ----------------
    **options
        Passed to :func:`zero_displacement_thrust` (``constants``, ``raceway_control``, ...).

    Returns
    -------
    ndarray
        F_a with delta_a = 0 (0 at zero speed). [N]

    Examples
    --------
    >>> from bearinglab import catalog
    >>> from bearinglab.units import RPM
    >>> f = sign_change_thrust(catalog.get("B218"), [3000 * RPM, 15000 * RPM], constants="harris",
    ...                        reduced_modulus=2.15e11 * 3 / 2**1.5)
    >>> print(np.round(f / 1e3, 2))
    [ 2.31 26.81]
    """
    from ..bearing import check_model

    check_model(bearing, "high-speed")
    if _preloaded(bearing):  # balls at alpha = 0 without thrust: delta_a(0) = 0 at any speed, rising with F_a
        return np.zeros(np.shape(_speed("shaft_speed", shaft_speed)))[()]
    return zero_displacement_thrust(shaft_speed, *_bearing_args(bearing, reduced_modulus), **options)


def _sweep_chunk(axial_load, shaft_speed, bearing, reduced_modulus, options):
    """One chunk of a sweep (a pure function of its inputs, so it can run on a dask worker): the state's
    fields per case, and the chunk's first ValidityWarning message on its first case."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", ValidityWarning)
        state = high_speed_analysis(bearing, axial_load, shaft_speed, reduced_modulus=reduced_modulus, **options)
    out = {k: np.atleast_1d(getattr(state, k)) for k in HighSpeedState._fields}
    notes = np.full(np.size(axial_load), "", dtype=object)
    msgs = [str(c.message) for c in caught if issubclass(c.category, ValidityWarning)]
    if msgs:
        notes[0] = msgs[0]
    out["_warning"] = notes
    return out


def sweep(bearing, axial_loads, shaft_speeds, *, execution=None, reduced_modulus=None, progress=None,
          chunk_size=None, executor=None, workers=None, memory_limit=None, processes=None, **options):
    """Solve a grid of thrusts x speeds for one bearing; failed cases are flagged, the others complete.

    Parameters
    ----------
    bearing : BallBearing
        See :func:`high_speed_analysis`.
    axial_loads : array_like
        1-D thrusts F_a. [N]
    shaft_speeds : array_like
        1-D inner-ring speeds. [rad/s]
    execution : bearinglab.parallel.Execution, optional
        Where and in which chunks the cases run (executor, workers, chunk size, memory limit, processes,
        progress, timeout); default serial, in chunks of 20 000 cases (each chunk one batched call, all
        its cases updated together). The chunks are the same on every executor, so the results are
        bit-identical.
    reduced_modulus : float, optional
        See :func:`high_speed_analysis`. [Pa]
    progress : callable or "dask", optional
        Older spelling of ``execution=Execution(progress=...)``; still accepted.
    chunk_size : int, optional
        Older spelling of ``execution=Execution(chunk_size=...)``; still accepted. [-]
    executor : str, optional
        Older spelling of ``execution=Execution(executor=...)``; still accepted.
    workers : int, optional
        Older spelling of ``execution=Execution(workers=...)``; still accepted. [-]
    memory_limit : str, optional
        Older spelling of ``execution=Execution(memory_limit=...)``; still accepted.
    processes : bool, optional
        Older spelling of ``execution=Execution(processes=...)``; still accepted.

    Other Parameters
    ----------------
    **options
        Passed to :func:`contact_angles`; ``on_failure`` defaults to "flag".

    Returns
    -------
    HighSpeedState
        Fields of shape (len(axial_loads), len(shaft_speeds)).

    Raises
    ------
    InputError
        If both ``execution`` and one of the older keyword arguments are given.

    Examples
    --------
    >>> from bearinglab import catalog
    >>> from bearinglab.units import RPM
    >>> s = sweep(catalog.get("B218"), [5e3, 20e3], [0.0, 6000 * RPM], constants="harris")
    >>> print(np.degrees(s.contact_angle_outer).round(3))
    [[40.662 27.947]
     [41.609 38.504]]
    """
    from ..bearing import check_model

    check_model(bearing, "high-speed")
    fa = np.atleast_1d(check_positive("axial_loads", axial_loads, "N"))
    w = np.atleast_1d(_speed("shaft_speeds", shaft_speeds))
    if fa.ndim != 1 or w.ndim != 1:
        raise InputError("axial_loads and shaft_speeds must be 1-D (a grid is built from them)")
    if chunk_size is not None:
        check_integer("chunk_size", chunk_size, 1)
    ex = parallel._execution(execution, chunk_size=chunk_size, executor=executor, workers=workers,
                             memory_limit=memory_limit, processes=processes, progress=progress)
    options.setdefault("on_failure", "flag")
    grid_f, grid_w = np.meshgrid(fa, w, indexing="ij")
    # chunks of cases, each one batched call, run by the execution layer (serial or on dask)
    res = parallel.run_cases(_sweep_chunk, {"axial_load": grid_f.ravel(), "shaft_speed": grid_w.ravel()},
                             constants={"bearing": bearing, "reduced_modulus": reduced_modulus, "options": options},
                             execution=ex.with_default_chunk_size(_SWEEP_CHUNK_SIZE))
    msgs = [m for m in res.pop("_warning") if m]
    if msgs:
        warnings.warn(msgs[0] if len(msgs) == 1 else f"{msgs[0]} (and in {len(msgs) - 1} more chunks)",
                      ValidityWarning, stacklevel=2)
    merged = {k: v.reshape(grid_f.shape) for k, v in res.items()}
    return HighSpeedState(**merged)



def result_table(state):
    """The state as flat columns in engineering units (kN, rpm, deg, mm, um, N, N mm, Hz, MPa, N/um).

    Parameters
    ----------
    state : HighSpeedState
        A result of :func:`contact_angles`, :func:`high_speed_analysis` or :func:`sweep`.

    Returns
    -------
    dict
        Column name -> 1-D ndarray; the names carry the unit (``contact_angle_inner_deg``,
        ``axial_displacement_um``, ``gyroscopic_moment_Nmm``, ...).
    """
    from .. import tables  # the one place where results become engineering-unit columns

    return tables.high_speed(state)

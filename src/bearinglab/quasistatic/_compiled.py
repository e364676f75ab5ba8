r"""The compiled fast path of the high-speed Newton solve (spec 004 section 5.1), one case at a time.

The same equations and the same solver as :mod:`~bearinglab.quasistatic.equations` and
:mod:`~bearinglab.quasistatic.continuation`, written in scalar form (``math``, tuples) so that numba can
compile them, and run over the cases in parallel:

- unknowns v = (X1, X2, delta_i, delta_e, delta_a) / D; groove-curvature centres eqs. (1)-(2), the two
  geometric closures and the force balances (5), (6), (7)/Z, scaled as in the batched path;
- kinematics eqs. (9), (10), (13) (outer- or inner-raceway control), F_c eq. (8), M_g eq. (12);
- K_i, K_e from the exact Hertz solution through the same Chebyshev interpolants in cos(alpha) that the
  batched path builds once per bearing (:func:`~bearinglab.quasistatic.contact._hertz_tables`), summed by
  Clenshaw's recurrence;
- the analytic Jacobian and a 5 x 5 Gaussian elimination with partial pivoting;
- the same continuation in omega^2: tangent predictor (X1 extrapolated multiplicatively), first step to
  the target speed (or ``speed_step``), steps cut by 4 where Newton fails and doubled after an easy step,
  Armijo step halving, the same tolerance and iteration limits, the same status codes;
- then, for a converged case, the full state that the batched path assembles from the public functions
  (``thrust._assemble``): loads, dynamics, speeds, pressures, axial stiffness, friction, residual.

Nothing allocates inside a case's solve: the 5 x 5 eliminations work in one scratch array per case.

It takes the same Newton steps as the batched path, case by case (tests/quasistatic/test_compiled.py
checks the iterations, the statuses and the unknowns to 1e-12). Each case is independent of the others,
so the result does not depend on the batch or the chunk it is solved in. Nothing here is public:
:func:`bearinglab.quasistatic.contact_angles` calls :func:`solve` when its ``engine`` allows it.
numba is imported by this module only; without it the functions run as plain Python.

Functions
---------
available        True if numba imports (the compiled path can run)
scalar_helpers   ``(cheb, gauss5)`` in plain Python, each wrapped by a given ``jit``
plain_solver     ``solve_from_rest`` (static start, solve, state of one case) in plain Python (the fair baseline)
case_parameters  the per-case constants and Hertz tables of a prepared model, as the kernel takes them
solve            all cases of a prepared model by the compiled kernel: ``(v, status, iterations, state)``
OUTPUTS          the names of the state's quantities, in the order :func:`state` gives them

References
----------
.. [1] Zhao Chunjiang, Cui Guohua, Wang Guoqiang, Huang Qingxue and Zhang Fangping, "Precise definition
   of the contact-angle field of a high-speed angular-contact ball bearing under axial load,"
   Transactions of the CSAM, vol. 39, no. 12, pp. 154-156, 209, 2008 (spec 004 of this project).
.. [2] W. H. Press, S. A. Teukolsky, W. T. Vetterling and B. P. Flannery, *Numerical Recipes*, 3rd ed.,
   Cambridge University Press, 2007, sections 2.1 (Gaussian elimination) and 5.8 (Clenshaw's recurrence).
"""

from __future__ import annotations

import math
import types

import numpy as np

from .. import _numba, _solve
from ..errors import ConvergenceError
from .equations import _ANGLE_OUT, _INNER_LOST, _NOCONV, _OK, _OUTER_LOST

try:
    import numba
except ImportError:  # the numpy path is used instead (contact_angles(engine="auto"))
    numba = None

__all__ = ["OUTPUTS", "available", "case_parameters", "plain_solver", "scalar_helpers", "solve"]


def available():
    """True if numba imports, so that the compiled kernel can run."""
    return numba is not None


def _jit(func):
    """numba.njit with the compiled code cached next to this module (one compilation per install); a
    division by zero gives inf or NaN as in numpy, so that the case's validity checks fail it (a light
    thrust at speed) instead of the process raising."""
    return func if numba is None else numba.njit(cache=True, error_model="numpy")(func)


def _py(func):
    return getattr(func, "py_func", func)


@_jit
def cheb(c, x):
    """Sum of the Chebyshev series ``c`` at x (Clenshaw's recurrence)."""
    b1 = 0.0
    b2 = 0.0
    for j in range(len(c) - 1, 0, -1):
        b1, b2 = c[j] + 2.0 * x * b1 - b2, b1
    return c[0] + x * b1 - b2


@_jit
def cheb2(c, e, x):
    """The sums of two Chebyshev series ``c`` and ``e`` at the same x, each exactly as :func:`cheb` sums it.

    One loop carries both recurrences, so that their chains of dependent operations overlap.
    """
    b1 = 0.0
    b2 = 0.0
    d1 = 0.0
    d2 = 0.0
    nc, ne = len(c), len(e)
    for j in range(max(nc, ne) - 1, 0, -1):
        if j < nc:
            b1, b2 = c[j] + 2.0 * x * b1 - b2, b1
        if j < ne:
            d1, d2 = e[j] + 2.0 * x * d1 - d2, d1
    return c[0] + x * b1 - b2, e[0] + x * d1 - d2


@_jit
def gauss5_into(a, b, m):
    """x (a 5-tuple) with a x = b; a flat row-major 5 x 5, partial pivoting; NaN if singular.

    ``m`` is scratch space of at least 35 floats (a list, or an array in compiled code), overwritten: the
    compiled kernel passes one array per case, so that no solve allocates.
    """
    for i in range(5):
        for j in range(5):
            m[6 * i + j] = a[5 * i + j]
        m[6 * i + 5] = b[i]
    for c in range(5):
        p = c
        for r in range(c + 1, 5):
            if abs(m[6 * r + c]) > abs(m[6 * p + c]):
                p = r
        if m[6 * p + c] == 0.0:
            return (math.nan, math.nan, math.nan, math.nan, math.nan)
        if p != c:
            for k in range(6):
                m[6 * c + k], m[6 * p + k] = m[6 * p + k], m[6 * c + k]
        for r in range(c + 1, 5):
            f = m[6 * r + c] / m[6 * c + c]
            for k in range(c, 6):
                m[6 * r + k] -= f * m[6 * c + k]
    for r in range(4, -1, -1):  # back substitution, x in m[30:35]
        s = m[6 * r + 5]
        for k in range(r + 1, 5):
            s -= m[6 * r + k] * m[30 + k]
        m[30 + r] = s / m[6 * r + r]
    return (m[30], m[31], m[32], m[33], m[34])


@_jit
def gauss5(a, b):
    """x (a 5-tuple) with a x = b; a flat row-major 5 x 5, partial pivoting; NaN if singular."""
    return gauss5_into(a, b, [0.0] * 35)


def scalar_helpers(jit):
    """Clenshaw's sum of a Chebyshev series and a 5 x 5 Gaussian elimination, each wrapped by ``jit``."""
    space = _rebind(("cheb", "gauss5_into", "gauss5"), jit)
    return space["cheb"], space["gauss5"]


@_jit
def kinematics(si, ci, se, ce, ai, ae, g, inner_control):
    """beta, cage and spin ratios of eqs. (9), (10), (13), and their partials in (alpha_i, alpha_e)."""
    if inner_control > 0.0:
        beta = math.atan2(si, ci - g)
        db_i, db_e = (1.0 - g * ci) / (1.0 - 2.0 * g * ci + g * g), 0.0
    else:
        beta = math.atan2(se, ce + g)
        db_i, db_e = 0.0, (1.0 + g * ce) / (1.0 + 2.0 * g * ce + g * g)
    gi, ge = g * ci, g * ce
    ceb, seb = math.cos(ae - beta), math.sin(ae - beta)
    cib, sib = math.cos(ai - beta), math.sin(ai - beta)
    pp, rr = (1.0 - gi) * ceb, (1.0 + ge) * cib
    den = pp + rr
    nn = (1.0 - gi) * (1.0 + ge)
    cage, spin = pp / den, nn / (g * den)
    dp_i = g * si * ceb + (1.0 - gi) * seb * db_i
    dp_e = -(1.0 - gi) * seb * (1.0 - db_e)
    dr_i = -(1.0 + ge) * sib * (1.0 - db_i)
    dr_e = -g * se * cib + (1.0 + ge) * sib * db_e
    den2 = den * den
    cage_i, cage_e = (dp_i * rr - pp * dr_i) / den2, (dp_e * rr - pp * dr_e) / den2
    spin_i = (g * si * (1.0 + ge) * den - nn * (dp_i + dr_i)) / (g * den2)
    spin_e = (-(1.0 - gi) * g * se * den - nn * (dp_e + dr_e)) / (g * den2)
    return beta, db_i, db_e, cage, spin, cage_i, cage_e, spin_i, spin_e


@_jit
def evaluate(v, w2, fa, par, kti, dti, kto, dto):
    """Residuals r (5), Jacobian (25, row-major, w.r.t. v), dr/d(omega^2) (5), status, alpha_i, alpha_e, Q_i, Q_e."""
    z, d, dm, fi, fo, ax0, az, mass_c, inertia = par[0], par[1], par[2], par[3], par[4], par[5], par[6], \
        par[7], par[8]
    li, le, sign, inner_control = par[9], par[10], par[11], par[12]
    fs = max(fa / z, 1.0)
    x1, x2, di, de, da = v[0] * d, v[1] * d, v[2] * d, v[3] * d, v[4] * d
    px, pz = ax0 + da - x1, az - x2  # inner groove centre minus ball centre, eqs. (1)-(2)
    rho_i, rho_e = math.hypot(px, pz), math.hypot(x1, x2)
    si, ci, se, ce = px / rho_i, pz / rho_i, x1 / rho_e, x2 / rho_e
    ai, ae = math.atan2(px, pz), math.atan2(x1, x2)
    code = _OK
    if not (0.0 < ai < 0.5 * math.pi and 0.0 < ae < 0.5 * math.pi):
        code = _ANGLE_OUT
    if not de > 0.0:
        code = _OUTER_LOST
    if not di > 0.0:
        code = _INNER_LOST
    beta, db_i, db_e, cage, spin, cage_i, cage_e, spin_i, spin_e = kinematics(si, ci, se, ce, ai, ae, d / dm,
                                                                              inner_control)
    # contact loads, eqs. (14)-(21), through the Hertz interpolants
    lki, dlki = cheb2(kti, dti, 2.0 * ci - 1.0)
    lke, dlke = cheb2(kto, dto, 2.0 * ce - 1.0)
    ki, ke = math.exp(lki), math.exp(lke)
    dip, dep = max(di, 0.0), max(de, 0.0)
    qi, qe = ki * dip * math.sqrt(dip), ke * dep * math.sqrt(dep)
    fc_hat = mass_c * dm / 2.0 * cage * cage  # F_c / omega^2, eq. (8)
    sb, cb = math.sin(beta), math.cos(beta)
    m_hat = sign * inertia * spin * cage * sb / d  # M_g / (D omega^2), eq. (12)
    ax_t, rad_t = li * ci - le * ce, li * si - le * se
    m = w2 * m_hat
    r = ((rho_i - (fi - 0.5) * d - di) / d, (rho_e - (fo - 0.5) * d - de) / d,
         (qi * si - qe * se + m * ax_t) / fs,  # eq. (5)
         (qi * ci - qe * ce - m * rad_t + w2 * fc_hat) / fs,  # eq. (6)
         (qi * si + m * li * ci - fa / z) / fs)  # eq. (7) / Z
    r_w2 = (0.0, 0.0, m_hat * ax_t / fs, (-m_hat * rad_t + fc_hat) / fs, m_hat * li * ci / fs)
    # partials of the force balances in (alpha_i, alpha_e, delta_i, delta_e)
    m_i = w2 * sign * inertia * (spin_i * cage * sb + spin * cage_i * sb + spin * cage * cb * db_i) / d
    m_e = w2 * sign * inertia * (spin_e * cage * sb + spin * cage_e * sb + spin * cage * cb * db_e) / d
    fc_i, fc_e = w2 * mass_c * dm * cage * cage_i, w2 * mass_c * dm * cage * cage_e
    qi_a, qe_a = -qi * si * dlki, -qe * se * dlke
    qi_d, qe_d = 1.5 * ki * math.sqrt(dip), 1.5 * ke * math.sqrt(dep)
    # rows (alpha_i, alpha_e, delta_i, delta_e) of eqs. (5), (6), (7), times D / fs
    sd = d / fs
    a3 = (qi_a * si + qi * ci + m_i * ax_t - m * li * si) * sd
    b3 = (-qe_a * se - qe * ce + m_e * ax_t + m * le * se) * sd
    a4 = (qi_a * ci - qi * si - m_i * rad_t - m * li * ci + fc_i) * sd
    b4 = (-qe_a * ce + qe * se - m_e * rad_t + m * le * ce + fc_e) * sd
    a5, b5 = (qi_a * si + qi * ci + m_i * li * ci - m * li * si) * sd, m_e * li * ci * sd
    dai0, dai1, dai2 = -ci / rho_i, si / rho_i, ci / rho_i  # d alpha_i / d(x1, x2, delta_a)
    dae0, dae1 = ce / rho_e, -se / rho_e
    jac = (-si, -ci, -1.0, 0.0, si, se, ce, 0.0, -1.0, 0.0,
           a3 * dai0 + b3 * dae0, a3 * dai1 + b3 * dae1, qi_d * si * sd, -qe_d * se * sd, a3 * dai2,
           a4 * dai0 + b4 * dae0, a4 * dai1 + b4 * dae1, qi_d * ci * sd, -qe_d * ce * sd, a4 * dai2,
           a5 * dai0 + b5 * dae0, a5 * dai1 + b5 * dae1, qi_d * si * sd, 0.0, a5 * dai2)
    return r, jac, r_w2, code, ai, ae, qi, qe


_NO_EVALUATION = ((math.nan,) * 5, (math.nan,) * 25, math.nan, math.nan)  # what solve_one gives a failed case


@_jit
def solve_one(fa, w_target, v0, par, kti, dti, kto, dto, tol, max_iter, h_max, scratch):
    """One case: (v (5-tuple), status, Newton iterations, alpha_i, alpha_e, (r, J, Q_i, Q_e) at v).

    ``h_max`` inf: no largest step. The last item is the evaluation at the solution (NaN if the case
    failed), from which :func:`state` computes the outputs.

    ``scratch``: 35 floats for the 5 x 5 solves (:func:`gauss5_into`).
    """
    v = (v0[0], v0[1], v0[2], v0[3], v0[4])
    v_ok, v_base, step, tangent = v, v, (0.0, 0.0, 0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 0.0, 0.0)
    w_ok, w_cur, h = 0.0, 0.0, min(w_target, h_max)
    h_min = max(w_target * 1e-6, 1e-3)
    iters, k_stage, t, norm_prev, last_bad = 0, 0, 1.0, math.inf, _NOCONV
    for _loop in range(_solve.QUASISTATIC_MAX_LOOPS):
        r, jac, r_w2, code, ai, ae, qi, qe = evaluate(v, w_cur * w_cur, fa, par, kti, dti, kto, dto)
        norm = math.sqrt(r[0] ** 2 + r[1] ** 2 + r[2] ** 2 + r[3] ** 2 + r[4] ** 2)
        valid = code == _OK and math.isfinite(norm)
        if not valid:
            last_bad = code
        cut, advance = False, False
        if valid and norm < tol:
            if w_cur >= w_target:
                return v, _OK, iters, ai, ae, (r, jac, qi, qe)
            tangent = gauss5_into(jac, (-r_w2[0], -r_w2[1], -r_w2[2], -r_w2[3], -r_w2[4]), scratch)  # dv / d(omega^2)
            v_ok, w_ok = v, w_cur
            if k_stage <= 4 and w_cur > 0:
                h = 2.0 * h  # grow after an easy step
            h = min(h, h_max)
            advance = True
        elif valid and norm <= norm_prev * (1.0 - 1e-4 * t):
            if k_stage >= _solve.QUASISTATIC_STAGE_MAX_ITER or iters >= max_iter:
                cut = True
            else:
                dv = gauss5_into(jac, (-r[0], -r[1], -r[2], -r[3], -r[4]), scratch)
                if not (math.isfinite(dv[0]) and math.isfinite(dv[1]) and math.isfinite(dv[2])
                        and math.isfinite(dv[3]) and math.isfinite(dv[4])):
                    cut = True
                else:
                    v_base, step, norm_prev, t = v, dv, norm, 1.0
                    v = (v[0] + dv[0], v[1] + dv[1], v[2] + dv[2], v[3] + dv[3], v[4] + dv[4])
                    k_stage += 1
                    iters += 1
        elif k_stage > 0:  # step halving from the previous iterate
            t *= 0.5
            if t < 1.0 / 1024.0:
                cut = True
            else:
                v = (v_base[0] + t * step[0], v_base[1] + t * step[1], v_base[2] + t * step[2],
                     v_base[3] + t * step[3], v_base[4] + t * step[4])
        else:  # the predictor is not usable
            cut = True
        if cut:  # retry with a quarter of the speed step, or give up
            h = 0.25 * (w_cur - w_ok)
            if iters >= max_iter:
                return v, _NOCONV, iters, math.nan, math.nan, _NO_EVALUATION
            if h < h_min:
                return v, last_bad, iters, math.nan, math.nan, _NO_EVALUATION
            advance = True
        if advance:  # next continuation step from the last converged point, tangent predictor
            w_new = min(w_ok + h, w_target)
            inc = w_new * w_new - w_ok * w_ok
            x1 = v_ok[0] + inc * tangent[0]
            if v_ok[0] > 0:  # X1 > 0 extrapolated multiplicatively
                x1 = v_ok[0] * math.exp(min(inc * tangent[0] / v_ok[0], 50.0))
            v = (x1, v_ok[1] + inc * tangent[1], v_ok[2] + inc * tangent[2], v_ok[3] + inc * tangent[3],
                 v_ok[4] + inc * tangent[4])
            w_cur, k_stage, norm_prev, t = w_new, 0, math.inf, 1.0
    return v, _NOCONV, iters, math.nan, math.nan, _NO_EVALUATION


@_jit
def _series_stiffness(c, kti, dti, kto, dto):
    """K_n = (K_i^(-2/3) + K_e^(-2/3))^(-3/2) at cos(alpha) = c, d ln K_n / d cos(alpha), K_i, K_e."""
    lki, dki = cheb2(kti, dti, 2.0 * c - 1.0)
    lke, dke = cheb2(kto, dto, 2.0 * c - 1.0)
    ui, ue = math.exp(-2.0 / 3.0 * lki), math.exp(-2.0 / 3.0 * lke)  # K^(-2/3)
    return (ui + ue) ** -1.5, (ui * dki + ue * dke) / (ui + ue), math.exp(lki), math.exp(lke)


@_jit
def static_start(fa, par, kti, dti, kto, dto, xtol, max_iter):
    """The static solution at the thrust ``fa`` (spec 004 section 5.3): (alpha_s, unknowns v0 (5-tuple)).

    The algorithm of :func:`bearinglab.static.contact_angle_under_thrust` (``stiffness_at="operating"``):
    Newton on (F / F_a)^(2/3) - 1 from spec 000's first approximation, with K_i, K_e at the loaded angle,
    here through the Chebyshev interpolants of the exact Hertz solution that the high-speed solve uses
    (the same to ~1e-13, with d ln K_n / d alpha from the series instead of central differences). alpha_s
    is NaN if the iteration does not converge in ``max_iter`` steps.
    """
    z, d, fo, a0 = par[0], par[1], par[4], par[14]
    bd = (par[3] + fo - 1.0) * d
    s0, c0 = math.sin(a0), math.cos(a0)
    t_ratio = fa / (z * _series_stiffness(c0, kti, dti, kto, dto)[0] * bd**1.5)
    root = math.sqrt(1.0 + (2.0 / 3.0) * (6.0 + c0**2) / s0**2 * (t_ratio / s0) ** (2.0 / 3.0))
    alpha = min(a0 + 3.0 * s0 * c0 / (6.0 + c0**2) * (root - 1.0), 0.5 * (a0 + 0.5 * math.pi))  # spec 000 eq. (3)
    done = False
    for _it in range(max_iter):
        ca, sa = math.cos(alpha), math.sin(alpha)
        kn, dlnk, _ki, _ke = _series_stiffness(ca, kti, dti, kto, dto)
        thrust = z * kn * (bd * (c0 / ca - 1.0)) ** 1.5 * sa
        slope = sa / ca + (2.0 / 3.0) * ca / sa + sa / (c0 - ca) - (2.0 / 3.0) * sa * dlnk
        dx = ((fa / thrust) ** (2.0 / 3.0) - 1.0) / slope
        new = alpha + dx
        if new <= a0:
            new = 0.5 * (alpha + a0)
        if new >= 0.5 * math.pi:
            new = 0.5 * (alpha + 0.5 * math.pi)
        alpha = new
        if abs(dx) < xtol:
            done = True
            break
    ca, sa = math.cos(alpha), math.sin(alpha)
    _kn, _dlnk, ki, ke = _series_stiffness(ca, kti, dti, kto, dto)
    q = fa / (z * sa)
    da = (bd + bd * (c0 / ca - 1.0)) * sa - bd * s0
    di, de = (q / ki) ** (2.0 / 3.0), (q / ke) ** (2.0 / 3.0)
    le_len = (fo - 0.5) * d + de  # the unknowns as continuation._unknowns_from gives them
    v0 = (le_len * sa / d, le_len * ca / d, di / d, de / d, da / d)
    return (alpha if done else math.nan), v0


#: The outputs of :func:`state`, in its order (fields of :class:`~bearinglab.quasistatic.HighSpeedState`).
OUTPUTS = ("contact_angle_inner", "contact_angle_outer", "axial_displacement", "ball_load_inner", "ball_load_outer",
           "deflection_inner", "deflection_outer", "centrifugal_force", "gyroscopic_moment", "attitude_angle",
           "cage_speed", "ball_spin_speed", "bpfo", "bpfi", "max_pressure_inner", "max_pressure_outer",
           "axial_stiffness", "friction_coefficient", "residual")


@_jit
def state(v, w, fa, par, ai, ae, last, ati, bti, ato, bto, scratch):
    """The full state of one converged case at the unknowns v, in the order of :data:`OUTPUTS` (SI units).

    ``ai``, ``ae`` and ``last`` = (r, J, Q_i, Q_e) are the solve's last evaluation, at v (:func:`solve_one`).
    The same quantities as the batched path's ``thrust._assemble``, which computes them through the public
    functions: beta (eq. 10, :func:`~bearinglab.quasistatic.attitude_angle`), the cage and spin speeds
    (eqs. 9, 13), F_c (8) and M_g (12) from the speeds, p_max = 3Q / (2 pi a b) with a*, b* through the
    Chebyshev interpolants of the exact Hertz solution, dF_a / d delta_a by implicit differentiation
    (J dv = -dr/dF_a dF_a, dr5/dF_a = -1 / (Z fs)), and mu = 2 M_g / (D Q) at the controlling raceway.
    """
    z, d, dm, fi, fo, mass_c, inertia, ep = par[0], par[1], par[2], par[3], par[4], par[7], par[8], par[13]
    r, jac, qi, qe = last
    g = d / dm
    si, ci, se, ce = math.sin(ai), math.cos(ai), math.sin(ae), math.cos(ae)
    if par[12] > 0.0:  # eq. (10), inner-raceway control
        beta = math.atan2(si, ci - g)
    else:
        beta = math.atan2(se, ce + g)
    gi, ge = g * ci, g * ce
    den = (1.0 + ge) * math.cos(ai - beta) + (1.0 - gi) * math.cos(ae - beta)
    cage = w * (1.0 - gi) * math.cos(ae - beta) / den  # eq. (9)
    spin = w * (1.0 - gi) * (1.0 + ge) / (g * den)  # eq. (13)
    fc = mass_c * dm / 2.0 * cage**2  # eq. (8)
    mg = inertia * abs(spin * cage) * math.sin(beta)  # eq. (12), J = m D^2 / 10
    p_in = _max_pressure(qi, d, fi, 2.0 * gi / (1.0 - gi), ep, ati, bti, 2.0 * ci - 1.0)
    p_out = _max_pressure(qe, d, fo, -2.0 * ge / (1.0 + ge), ep, ato, bto, 2.0 * ce - 1.0)
    dv = gauss5_into(jac, (0.0, 0.0, 0.0, 0.0, 1.0 / (z * max(fa / z, 1.0))), scratch)
    q_c = qe if par[10] > 0.0 else qi
    mu = 2.0 * mg / (d * q_c) if q_c != 0.0 else (math.inf if mg != 0.0 else math.nan)
    res = math.sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2] + r[3] * r[3] + r[4] * r[4])
    return (ai, ae, v[4] * d, qi, qe, v[2] * d, v[3] * d, fc, mg, beta, cage, spin, z * cage, z * (w - cage), p_in,
            p_out, 1.0 / (dv[4] * d), mu, res)


@_jit
def _max_pressure(q, d, f, race_term, ep, a_star, b_star, x):
    """p_max = 3 Q / (2 pi a b) of a raceway contact, a = a* (3 Q / (E' Sigma rho))^(1/3) (0 without load)."""
    if not q > 0.0:
        return 0.0
    curvature_sum = (4.0 - 1.0 / f + race_term) / d  # eqs. (17)-(21)
    base = (3.0 * q / (ep * curvature_sum)) ** (1.0 / 3.0)  # numba has no math.cbrt; the same to ~1 ulp
    a = math.exp(cheb(a_star, x)) * base
    b = math.exp(cheb(b_star, x)) * base
    return 3.0 * q / (2.0 * math.pi * a * b)


_JITTED = ("cheb", "cheb2", "gauss5_into", "gauss5", "kinematics", "evaluate", "solve_one", "_series_stiffness",
           "static_start", "_max_pressure", "state", "solve_case", "solve_from_rest")


def _rebind(names, wrap):
    """A copy of this module's namespace where the functions ``names`` are plain Python wrapped by ``wrap``."""
    space = dict(globals())
    for name in names:
        func = _py(space[name])
        space[name] = wrap(types.FunctionType(func.__code__, space, name, func.__defaults__))
    return space


def plain_solver():
    """``solve_from_rest`` with every helper it calls in plain Python (numba or not): the fair scalar baseline."""
    return _rebind(_JITTED, lambda f: f)["solve_from_rest"]


_prange = range if numba is None else numba.prange
_thread_id = (lambda: 0) if numba is None else numba.get_thread_id  # the scratch row of the running thread
_STATIC_XTOL = 1e-13  # [rad], the default xtol of bearinglab.static.contact_angle_under_thrust


@_jit
def solve_case(fa, w, v0, par, kti, dti, kto, dto, ati, bti, ato, bto, tol, max_iter, h_max, scratch):
    """One case, solve and state: (v, status, Newton iterations, :data:`OUTPUTS` (NaN if the case failed))."""
    v, code, it, ai, ae, last = solve_one(fa, w, v0, par, kti, dti, kto, dto, tol, max_iter, h_max, scratch)
    if code == _OK:
        return v, code, it, state(v, w, fa, par, ai, ae, last, ati, bti, ato, bto, scratch)
    nan = math.nan
    return v, code, it, (nan, nan, nan, nan, nan, nan, nan, nan, nan, nan, nan, nan, nan, nan, nan, nan, nan, nan,
                         nan)


@_jit
def solve_from_rest(fa, w, par, kti, dti, kto, dto, ati, bti, ato, bto, tol, max_iter, h_max, scratch):
    """One case from its static start: (alpha_s, v, status, Newton iterations, :data:`OUTPUTS`).

    alpha_s is NaN if the static solution did not converge (the caller raises).
    """
    alpha_s, v0 = static_start(fa, par, kti, dti, kto, dto, _STATIC_XTOL, _solve.AXIAL_ANGLE_MAX_ITER)
    v, code, it, o = solve_case(fa, w, v0, par, kti, dti, kto, dto, ati, bti, ato, bto, tol, max_iter, h_max, scratch)
    return alpha_s, v, code, it, o


def _loop(fa, w, v0, par, pid, gid, kti, dti, kto, dto, ati, bti, ato, bto, tol, max_iter, h_max, v, status, iters,
          out, scratch):
    for k in _prange(fa.size):  # parallel over the cases (each case is independent of the others)
        g = gid[k]
        vk, status[k], iters[k], o = solve_case(fa[k], w[k], v0[k], par[pid[k]], kti[g], dti[g], kto[g], dto[g], ati[g],
                                                bti[g], ato[g], bto[g], tol, max_iter, h_max, scratch[_thread_id()])
        for j in range(5):
            v[k, j] = vk[j]
        for j in range(len(o)):
            out[k, j] = o[j]


def _starts(fa, par, pid, gid, kti, dti, kto, dto, alpha_s, v0):
    for k in _prange(fa.size):  # parallel over the cases
        g = gid[k]
        alpha_s[k], vk = static_start(fa[k], par[pid[k]], kti[g], dti[g], kto[g], dto[g], _STATIC_XTOL,
                                      _solve.AXIAL_ANGLE_MAX_ITER)
        for j in range(5):
            v0[k, j] = vk[j]


_starts_serial = _starts
if numba is not None:
    _loop = numba.njit(parallel=True, cache=True, error_model="numpy")(_loop)
    _starts = numba.njit(parallel=True, cache=True, error_model="numpy")(_starts)
    _starts_serial = numba.njit(cache=True, error_model="numpy")(_starts_serial)  # prange runs as range
_PARALLEL_STARTS = 2000  # static starts below which one thread is quicker than waking the others


def _threads():
    """Threads the kernel may run on (rows of scratch space it needs)."""
    return 1 if numba is None else numba.config.NUMBA_NUM_THREADS


_LOCK = _numba.LOCK  # numba's default (workqueue) threading layer does not allow concurrent launches


def _parameters(model):
    """``(par, pid, gid, tables)``: constants (P, 15) with the row ``pid`` of each case, geometry index, series.

    One row for all cases when they share one bearing (the usual map), else one row per case. The tables
    are the Chebyshev series of ln K and d ln K / d cos(alpha) (inner, then outer), then those of ln a*
    and ln b* (inner, then outer), each (G, m).
    """
    cols = [model.z, model.d, model.dm, model.fi, model.fo, model.ax0, model.az, model.mass_c, model.inertia]
    n = model.fa.size
    extra = (model.lam_i, model.lam_e, model.sign, 1.0 if model.control == "inner" else 0.0)
    per_case = cols[:5] + [model.ep, model.a0] + cols[5:]
    if n and all(c.min() == c.max() for c in per_case):
        par, pid = np.array([[c[0] for c in cols] + list(extra) + [model.ep[0], model.a0[0]]]), np.zeros(n, np.int64)
    else:
        par = np.column_stack(cols + [np.full(n, x) for x in extra] + [model.ep, model.a0])
        pid = np.arange(n, dtype=np.int64)
    series = (*model.t_inner["k"], *model.t_outer["k"], *model.t_inner["hertz"][1:3], *model.t_outer["hertz"][1:3])
    tables = [np.ascontiguousarray(np.atleast_2d(t), dtype=float) for t in series]
    return np.ascontiguousarray(par, dtype=float), pid, np.ascontiguousarray(model.gid, dtype=np.int64), tables


def case_parameters(model):
    """``(par, gid, tables)``: per-case constants (n, 15), geometry index (n,), Hertz series (8 x (G, m)).

    See :func:`_parameters` for the tables.
    """
    par, pid, gid, tables = _parameters(model)
    return par[pid], gid, tables


def _static_starts(fa, par, pid, gid, tables):
    """alpha_s (n,) and the unknowns v0 (n, 5) of each case's static start, by :func:`static_start`.

    A static start is a function of the thrust and the bearing only: where all cases share one bearing
    (the usual map), it is computed once per distinct thrust and copied, which gives the same numbers.
    """
    n = fa.size
    if n and len(par) == 1 and np.all(gid == gid[0]):
        loads, inv = np.unique(fa, return_inverse=True)
        rep = np.zeros(loads.size, dtype=np.int64)
        rep[inv] = np.arange(n)  # a case of each distinct thrust
    else:
        rep, inv = np.arange(n), np.arange(n)
    alpha_s, v0 = np.empty(rep.size), np.empty((rep.size, 5))
    starts = _starts if rep.size >= _PARALLEL_STARTS else _starts_serial
    starts(fa[rep], par, pid[rep], gid[rep], *tables[:4], alpha_s, v0)
    if np.isnan(alpha_s).any():
        k = int(rep[np.flatnonzero(np.isnan(alpha_s))[0]])
        raise ConvergenceError("static.contact_angle_under_thrust", iterations=_solve.AXIAL_ANGLE_MAX_ITER,
                               residual=np.inf, estimate=np.nan, reason=f"static start at F_a = {fa[k]:g} N")
    return alpha_s[inv], v0[inv]


def solve(model, w_target, v0=None, *, tol, max_iter, speed_step):
    """All cases of ``model`` by the compiled kernel: unknowns (n, 5), status codes, Newton iterations, state.

    The counterpart of ``continuation._static_start`` (when ``v0`` is None: each case starts from its
    static solution, :func:`static_start`), :func:`~bearinglab.quasistatic.continuation._newton` on
    ``idx = arange(n)`` and ``thrust._assemble``: the state is a dict of the :data:`OUTPUTS` (n,), NaN
    where a case failed, and of ``static_contact_angle`` (NaN if ``v0`` is given).

    Raises
    ------
    ConvergenceError
        If a static start does not converge (as :func:`bearinglab.static.contact_angle_under_thrust`).
    """
    par, pid, gid, tables = _parameters(model)
    fa = np.ascontiguousarray(model.fa, dtype=float)
    n = fa.size
    v, out = np.empty((n, 5)), np.empty((n, len(OUTPUTS)))
    status, iters = np.empty(n, dtype=np.int64), np.empty(n, dtype=np.int64)
    h_max = math.inf if speed_step is None else float(speed_step)
    with _LOCK:
        if v0 is None:
            alpha_s, v0 = _static_starts(fa, par, pid, gid, tables)
        else:
            alpha_s, v0 = np.full(n, np.nan), np.ascontiguousarray(v0, dtype=float)
        _loop(fa, np.ascontiguousarray(w_target, dtype=float), v0, par, pid, gid, *tables, float(tol), int(max_iter),
              h_max, v, status, iters, out, np.empty((_threads(), 35)))
    state = {name: out[:, j] for j, name in enumerate(OUTPUTS)}
    state["static_contact_angle"] = alpha_s
    return v, status, iters, state

r"""The high-speed thrust model (spec 004) for one case at a time: the fair scalar baseline and its compiled kernel.

Not part of the library. The equations are those of spec 004 sections 3 and 5.1, written again here in
scalar form (``math``, flat Python lists) from the spec, not by calling the library's kernel:

- unknowns v = (X1, X2, delta_i, delta_e, delta_a) / D; groove-curvature centres eqs. (1)-(2), the two
  geometric closures and the force balances (5), (6), (7)/Z, scaled as in the batched path;
- kinematics eqs. (9), (10), (13) (outer- or inner-raceway control), F_c eq. (8), M_g eq. (12);
- K_i, K_e from the exact Hertz solution through the same Chebyshev interpolants in cos(alpha) that the
  batched path builds once per bearing (evaluated here by Clenshaw's recurrence in plain Python);
- the analytic Jacobian, a 5 x 5 Gaussian elimination with partial pivoting;
- the same solver: start from the static solution at the same thrust, continuation in omega^2 with a
  tangent predictor (X1 extrapolated multiplicatively), first step to the target speed, steps cut by 4
  where Newton fails and doubled after an easy step, Armijo step halving, the same tolerance (Euclidean
  norm of the scaled residuals < 1e-12), the same iteration limits.

Functions
---------
bearing_parameters   the per-bearing constants and Hertz tables, from the library's own set-up
solver               ``solve(fa, w, v0) -> (v, status, iterations)`` in plain Python (the fair baseline)
compiled             the same per-case algorithm compiled by numba, ``@njit(parallel=True)`` over cases
"""

from __future__ import annotations

import math

import numpy as np
from _kernels_common import scalar_helpers

from bearinglab import _solve, quasistatic

__all__ = ["bearing_parameters", "compiled", "solver"]

# per-bearing constants, in this order (``fa`` and ``fs`` are per case)
_NAMES = ("z", "d", "dm", "fi", "fo", "ax0", "az", "mass_c", "inertia")
_OK, _NOCONV, _INNER_LOST, _OUTER_LOST, _ANGLE_OUT = range(5)  # the status codes of quasistatic.STATUS


def bearing_parameters(geometry_args, *, raceway_control="outer", gyroscopic_sign=1, constants="harris"):
    """(par, tables): the constants of one bearing as floats, and (K_i, dlnK_i, K_e, dlnK_e) Chebyshev series."""
    model, _ = quasistatic._prepare(1.0, *geometry_args, raceway_control, gyroscopic_sign, constants)
    par = [float(getattr(model, n)[0]) for n in _NAMES]
    par += [model.lam_i, model.lam_e, model.sign, 1.0 if raceway_control == "inner" else 0.0]
    tables = [np.asarray(t, dtype=float) for t in (*model.t_inner["k"], *model.t_outer["k"])]
    return np.asarray(par), tables


def _functions(jit):
    """The per-case functions, each wrapped by ``jit`` (identity: plain Python; numba.njit: compiled)."""

    cheb, gauss5 = scalar_helpers(jit)

    @jit
    def evaluate(v, w2, fa, par, kti, dti, kto, dto):
        """Residuals r (5), Jacobian (25, row-major, w.r.t. v), dr/d(omega^2) (5), status, alpha_i, alpha_e."""
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
        # kinematics, eqs. (9), (10), (13), and their partials in alpha_i, alpha_e
        g = d / dm
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
        # contact loads, eqs. (14)-(21), through the Hertz interpolants
        ki, dlki = math.exp(cheb(kti, 2.0 * ci - 1.0)), cheb(dti, 2.0 * ci - 1.0)
        ke, dlke = math.exp(cheb(kto, 2.0 * ce - 1.0)), cheb(dto, 2.0 * ce - 1.0)
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
        a3, b3 = (qi_a * si + qi * ci + m_i * ax_t - m * li * si) * sd, (-qe_a * se - qe * ce + m_e * ax_t
                                                                          + m * le * se) * sd
        a4 = (qi_a * ci - qi * si - m_i * rad_t - m * li * ci + fc_i) * sd
        b4 = (-qe_a * ce + qe * se - m_e * rad_t + m * le * ce + fc_e) * sd
        a5, b5 = (qi_a * si + qi * ci + m_i * li * ci - m * li * si) * sd, m_e * li * ci * sd
        dai0, dai1, dai2 = -ci / rho_i, si / rho_i, ci / rho_i  # d alpha_i / d(x1, x2, delta_a)
        dae0, dae1 = ce / rho_e, -se / rho_e
        jac = (-si, -ci, -1.0, 0.0, si, se, ce, 0.0, -1.0, 0.0,
               a3 * dai0 + b3 * dae0, a3 * dai1 + b3 * dae1, qi_d * si * sd, -qe_d * se * sd, a3 * dai2,
               a4 * dai0 + b4 * dae0, a4 * dai1 + b4 * dae1, qi_d * ci * sd, -qe_d * ce * sd, a4 * dai2,
               a5 * dai0 + b5 * dae0, a5 * dai1 + b5 * dae1, qi_d * si * sd, 0.0, a5 * dai2)
        return r, jac, r_w2, code, ai, ae

    @jit
    def solve_one(fa, w_target, v0, par, kti, dti, kto, dto, tol, max_iter, stage_max, max_loops):
        """One case: (v (5-tuple), status, Newton iterations, alpha_i, alpha_e)."""
        v = (v0[0], v0[1], v0[2], v0[3], v0[4])
        v_ok, v_base, step, tangent = v, v, (0.0, 0.0, 0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 0.0, 0.0)
        w_ok, w_cur, h = 0.0, 0.0, w_target
        h_min = max(w_target * 1e-6, 1e-3)
        iters, k_stage, t, norm_prev, last_bad = 0, 0, 1.0, math.inf, _NOCONV
        status = -1
        for _loop in range(max_loops):
            r, jac, r_w2, code, ai, ae = evaluate(v, w_cur * w_cur, fa, par, kti, dti, kto, dto)
            norm = math.sqrt(r[0] ** 2 + r[1] ** 2 + r[2] ** 2 + r[3] ** 2 + r[4] ** 2)
            valid = code == _OK and math.isfinite(norm)
            if not valid:
                last_bad = code
            cut = False
            if valid and norm < tol:
                if w_cur >= w_target:
                    return v, _OK, iters, ai, ae
                tangent = gauss5(jac, (-r_w2[0], -r_w2[1], -r_w2[2], -r_w2[3], -r_w2[4]))  # dv / d(omega^2)
                v_ok, w_ok = v, w_cur
                if k_stage <= 4 and w_cur > 0:
                    h = 2.0 * h  # no largest speed step (speed_step None)
                advance = True
            elif valid and norm <= norm_prev * (1.0 - 1e-4 * t):
                advance = False
                if k_stage >= stage_max or iters >= max_iter:
                    cut = True
                else:
                    dv = gauss5(jac, (-r[0], -r[1], -r[2], -r[3], -r[4]))
                    if not (math.isfinite(dv[0]) and math.isfinite(dv[1]) and math.isfinite(dv[2])
                            and math.isfinite(dv[3]) and math.isfinite(dv[4])):
                        cut = True
                    else:
                        v_base, step, norm_prev, t = v, dv, norm, 1.0
                        v = (v[0] + dv[0], v[1] + dv[1], v[2] + dv[2], v[3] + dv[3], v[4] + dv[4])
                        k_stage += 1
                        iters += 1
            elif k_stage > 0:  # step halving from the previous iterate
                advance = False
                t *= 0.5
                if t < 1.0 / 1024.0:
                    cut = True
                else:
                    v = (v_base[0] + t * step[0], v_base[1] + t * step[1], v_base[2] + t * step[2],
                         v_base[3] + t * step[3], v_base[4] + t * step[4])
            else:  # the predictor is not usable
                advance = False
                cut = True
            if cut:
                h = 0.25 * (w_cur - w_ok)
                if iters >= max_iter:
                    status = _NOCONV
                elif h < h_min:
                    status = last_bad
                else:
                    advance = True
                if status >= 0:
                    return v, status, iters, math.nan, math.nan
            if advance:  # next continuation step from the last converged point, tangent predictor
                w_new = min(w_ok + h, w_target)
                inc = w_new * w_new - w_ok * w_ok
                x1 = v_ok[0] + inc * tangent[0]
                if v_ok[0] > 0:  # X1 > 0 extrapolated multiplicatively
                    x1 = v_ok[0] * math.exp(min(inc * tangent[0] / v_ok[0], 50.0))
                v = (x1, v_ok[1] + inc * tangent[1], v_ok[2] + inc * tangent[2], v_ok[3] + inc * tangent[3],
                     v_ok[4] + inc * tangent[4])
                w_cur, k_stage, norm_prev, t = w_new, 0, math.inf, 1.0
        return v, _NOCONV, iters, math.nan, math.nan

    return solve_one


_SOLVE_ONE = _functions(lambda f: f)
_COMPILED = None


def solver(par, tables, *, tol=_solve.QUASISTATIC_TOL, max_iter=_solve.QUASISTATIC_MAX_ITER):
    """``solve(fa, w, v0) -> (v, status, iterations, alpha_i, alpha_e)``, one case, plain Python."""
    p = [float(x) for x in par]
    t = [[float(x) for x in c] for c in tables]
    lim = (tol, max_iter, _solve.QUASISTATIC_STAGE_MAX_ITER, _solve.QUASISTATIC_MAX_LOOPS)

    def solve(fa, w, v0):
        return _SOLVE_ONE(fa, w, v0, p, *t, *lim)

    return solve


def compiled(fa, w, v0, par, tables, *, tol=_solve.QUASISTATIC_TOL, max_iter=_solve.QUASISTATIC_MAX_ITER):
    """All cases (flat arrays; v0 (n, 5)) by the compiled kernel: (alpha_i, alpha_e, status, iterations)."""
    global _COMPILED
    if _COMPILED is None:
        import numba

        one = _functions(numba.njit(cache=False))

        @numba.njit(parallel=True)
        def kernel(fa, w, v0, par, kti, dti, kto, dto, tol, max_iter, stage_max, max_loops, ai, ae, status, iters):
            for k in numba.prange(fa.size):
                _v, status[k], iters[k], ai[k], ae[k] = one(fa[k], w[k], v0[k], par, kti, dti, kto, dto, tol,
                                                            max_iter, stage_max, max_loops)

        _COMPILED = kernel
    n = fa.size
    ai, ae, status, iters = np.empty(n), np.empty(n), np.empty(n, dtype=np.int64), np.empty(n, dtype=np.int64)
    _COMPILED(np.ascontiguousarray(fa, dtype=float), np.ascontiguousarray(w, dtype=float),
              np.ascontiguousarray(v0, dtype=float), np.asarray(par, dtype=float), *tables, float(tol), int(max_iter),
              _solve.QUASISTATIC_STAGE_MAX_ITER, _solve.QUASISTATIC_MAX_LOOPS, ai, ae, status, iters)
    return ai, ae, status, iters

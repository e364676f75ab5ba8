r"""The 5-DOF combined-load model at rest, one case at a time, compiled: the compiled limit of bench/combined.py.

Not part of the library. The per-case algorithm is the fair scalar baseline of bench/combined.py
(``scalar_solver``) written so that numba compiles it (flat lists and tuples, no closures over Python
objects): each ball a spring between the groove-curvature centres, Q = K_n (rho - A)^1.5 with K_n from
the exact Hertz interpolants at the line's angle; ring Newton with the analytic tangent stiffness (sum
over balls of J^T H J), Levenberg-Marquardt damping, a trust region of A/2 per step, a line search of 8
cuts by 4, the same tolerance (relative residual 1e-12, moments divided by d_m/2), the same start.

Functions
---------
compiled   all cases (loads (n, 5), starts (n, 5)) by ``@njit(parallel=True)`` over cases
"""

from __future__ import annotations

import math

import numpy as np

__all__ = ["compiled"]

_COMPILED = None


def _functions(jit):
    """The per-case functions, each wrapped by ``jit`` (numba.njit)."""

    @jit
    def cheb(c, x):  # Clenshaw's recurrence
        b1 = 0.0
        b2 = 0.0
        for j in range(len(c) - 1, 0, -1):
            b1, b2 = c[j] + 2.0 * x * b1 - b2, b1
        return c[0] + x * b1 - b2

    @jit
    def gauss5(a, b):
        """x with a x = b; a flat row-major 5 x 5 list, b a 5-list; partial pivoting."""
        m = [0.0] * 30
        for i in range(5):
            for j in range(5):
                m[6 * i + j] = a[5 * i + j]
            m[6 * i + 5] = b[i]
        for c in range(5):
            p = c
            for r in range(c + 1, 5):
                if abs(m[6 * r + c]) > abs(m[6 * p + c]):
                    p = r
            if p != c:
                for k in range(6):
                    m[6 * c + k], m[6 * p + k] = m[6 * p + k], m[6 * c + k]
            for r in range(c + 1, 5):
                f = m[6 * r + c] / m[6 * c + c]
                for k in range(c, 6):
                    m[6 * r + k] -= f * m[6 * c + k]
        x = [0.0] * 5
        for r in range(4, -1, -1):
            s = m[6 * r + 5]
            for k in range(r + 1, 5):
                s -= m[6 * r + k] * x[k]
            x[r] = s / m[6 * r + r]
        return x

    @jit
    def evaluate(u, cs, sn, arm, big_a, gr0, ci, dci, co, dco):
        """Ring reaction f (5), tangent stiffness k (25, row-major) and the sum of ball loads."""
        f = [0.0] * 5
        k = [0.0] * 25
        total = 0.0
        for b in range(cs.size):
            c, s = cs[b], sn[b]
            ga = u[2] + arm * (u[3] * s - u[4] * c)
            gr = gr0 + u[0] * c + u[1] * s
            rho = math.hypot(ga, gr)
            if rho <= big_a:
                continue
            sa, ca = ga / rho, gr / rho
            x = 2.0 * ca - 1.0
            ki, ko = math.exp(cheb(ci, x)), math.exp(cheb(co, x))
            wi, wo = ki ** (-2.0 / 3.0), ko ** (-2.0 / 3.0)
            kn = (wi + wo) ** -1.5
            dl = (wi * 2.0 * cheb(dci, x) + wo * 2.0 * cheb(dco, x)) / (wi + wo)
            d = rho - big_a
            q, dq = kn * d**1.5, 1.5 * kn * math.sqrt(d)
            qa = -q * sa * dl
            h00 = dq * sa * sa + qa / rho * sa * ca + q / rho * ca * ca
            h01 = dq * sa * ca - qa / rho * sa * sa - q / rho * ca * sa
            h10 = dq * ca * sa + qa / rho * ca * ca - q / rho * sa * ca
            h11 = dq * ca * ca - qa / rho * ca * sa + q / rho * sa * sa
            ja = (0.0, 0.0, 1.0, arm * s, -arm * c)
            jr = (c, s, 0.0, 0.0, 0.0)
            for i in range(5):
                f[i] += q * sa * ja[i] + q * ca * jr[i]
                ai, ri = ja[i], jr[i]
                for j in range(5):
                    k[5 * i + j] += (ai * (h00 * ja[j] + h01 * jr[j]) + ri * (h10 * ja[j] + h11 * jr[j]))
            total += q
        return f, k, total

    @jit
    def norms(loads, f, total, sc):
        res = 0.0
        ref = 0.0
        for i in range(5):
            res += ((loads[i] - f[i]) * sc[i]) ** 2
            ref += (loads[i] * sc[i]) ** 2
        res = math.sqrt(res)
        scale = max(math.sqrt(ref), total)
        return res, (res / scale if scale > 0 else res)

    @jit
    def solve_one(loads, start, cs, sn, arm, big_a, gr0, ci, dci, co, dco, tol, max_iter):
        """One case: (u (5-list), Newton iterations; NaN and -1 if not converged)."""
        sc = (1.0, 1.0, 1.0, 1.0 / arm, 1.0 / arm)
        u = [start[0], start[1], start[2], start[3], start[4]]
        f, k, total = evaluate(u, cs, sn, arm, big_a, gr0, ci, dci, co, dco)
        norm, rel = norms(loads, f, total, sc)
        lam = 0.0
        for it in range(max_iter):
            if rel <= tol:
                return u, it
            dmax = 0.0
            for i in range(5):
                dmax = max(dmax, abs(k[6 * i] * sc[i] * sc[i]))
            if dmax == 0.0:
                dmax = 1.0
            a = [0.0] * 25
            for i in range(5):
                for j in range(5):
                    a[5 * i + j] = k[5 * i + j] * sc[i] * sc[j]
                a[6 * i] += max(lam, 1e-14) * dmax
            rhs = [(loads[i] - f[i]) * sc[i] for i in range(5)]
            du = gauss5(a, rhs)
            for i in range(5):
                du[i] *= sc[i]
            move = 0.0
            for b in range(cs.size):
                c, s = cs[b], sn[b]
                move = max(move, abs(du[2] + arm * (du[3] * s - du[4] * c)), abs(du[0] * c + du[1] * s))
            t = min(1.0, 0.5 * big_a / move) if move > 0 else 1.0
            full = t == 1.0
            accepted = False
            for _ls in range(8):
                trial = [u[i] + t * du[i] for i in range(5)]
                f_t, k_t, tot_t = evaluate(trial, cs, sn, arm, big_a, gr0, ci, dci, co, dco)
                n_t, r_t = norms(loads, f_t, tot_t, sc)
                if n_t < norm * (1.0 - 1e-4 * t) or r_t <= tol:
                    u, f, k, norm, rel = trial, f_t, k_t, n_t, r_t
                    accepted = True
                    break
                t *= 0.25
                full = False
            if not accepted:
                lam = max(100.0 * lam, 1e-3)
                continue
            lam = 0.1 * lam if full else max(10.0 * lam, 1e-6)
            lam = 0.0 if lam < 1e-12 else lam
        return [math.nan] * 5, -1

    return solve_one


def compiled(geo, loads, starts, *, tol, max_iter):
    """All cases: (u (n, 5), iterations (n,), -1 if not converged); ``geo`` from ``combined._geometry``."""
    global _COMPILED
    if _COMPILED is None:
        import numba

        one = _functions(numba.njit)

        @numba.njit(parallel=True)
        def kernel(loads, starts, cs, sn, arm, big_a, gr0, ci, dci, co, dco, tol, max_iter, out, iters):
            for n in numba.prange(loads.shape[0]):
                u, iters[n] = one(loads[n], starts[n], cs, sn, arm, big_a, gr0, ci, dci, co, dco, tol, max_iter)
                for i in range(5):
                    out[n, i] = u[i]

        _COMPILED = kernel
    cheb = np.polynomial.chebyshev
    ci, co = (np.asarray(t, dtype=float) for t in geo.tables[:2])
    loads, starts = np.ascontiguousarray(loads, dtype=float), np.ascontiguousarray(starts, dtype=float)
    out, iters = np.empty_like(loads), np.empty(len(loads), dtype=np.int64)
    _COMPILED(loads, starts, np.cos(geo.psi), np.sin(geo.psi), geo.dm / 2.0, geo.big_a, geo.gr0, ci,
              cheb.chebder(ci), co, cheb.chebder(co), float(tol), int(max_iter), out, iters)
    return out, iters

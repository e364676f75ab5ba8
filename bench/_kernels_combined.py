r"""The 5-DOF combined-load model one case at a time: the fair scalar baseline and the compiled limit.

Not part of the library. The per-case algorithms, written once in plain Python with ``math`` so that
numba also compiles them (flat lists and tuples): run by CPython they are the fair scalar baselines of
bench/combined.py, compiled (``@njit(parallel=True)`` over cases) the compiled limits.

At rest: each ball a spring between the groove-curvature centres, Q = K_n (rho - A)^1.5 with K_n from
the exact Hertz interpolants at the line's angle; ring Newton with the analytic tangent stiffness (sum
over balls of J^T H J), Levenberg-Marquardt damping, a trust region of A/2 per step, a line search of 8
cuts by 4, the same tolerance (relative residual 1e-12, moments divided by d_m/2), the same start.
At speed: the rest solution, then continuation in omega^2 (1, 4 or 16 steps); every ball's equilibrium
(spec 004 eqs. (5)-(6) with F_c, M_g and the raceway control) by a 2 x 2 Newton, the ball's ring
stiffness as the Schur complement p_g - p_x b_x^-1 b_g, the same ring Newton.

Functions
---------
rest_solver      one case at rest in plain Python: the fair scalar baseline at rest
speed_solver     one case at speed in plain Python: the fair scalar baseline at speed
compiled         all cases at rest (loads (n, 5), starts (n, 5)) by ``@njit(parallel=True)`` over cases
compiled_speed   all cases at speed, the same way
"""

from __future__ import annotations

import math

import numpy as np

from bearinglab.quasistatic._compiled import scalar_helpers

__all__ = ["compiled", "compiled_speed", "rest_solver", "speed_solver"]

_COMPILED = _COMPILED_SPEED = None


def _functions(jit):
    """The per-case functions, each wrapped by ``jit`` (numba.njit)."""

    cheb, gauss5 = scalar_helpers(jit)

    @jit
    def lm_step(k, f, loads, lam, sc, cs, sn, arm, big_a):
        """Levenberg-Marquardt step (K + lam max|diag K| I) du = F - f in scaled variables, and its
        trust-region fraction t (no groove centre moves by more than A/2)."""
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
        g = gauss5(a, [(loads[i] - f[i]) * sc[i] for i in range(5)])
        du = [g[i] * sc[i] for i in range(5)]
        move = 0.0
        for b in range(len(cs)):
            c, s = cs[b], sn[b]
            move = max(move, abs(du[2] + arm * (du[3] * s - du[4] * c)), abs(du[0] * c + du[1] * s))
        return du, (min(1.0, 0.5 * big_a / move) if move > 0 else 1.0)

    @jit
    def evaluate(u, cs, sn, arm, big_a, gr0, ci, dci, co, dco):
        """Ring reaction f (5), tangent stiffness k (25, row-major) and the sum of ball loads."""
        f = [0.0] * 5
        k = [0.0] * 25
        total = 0.0
        for b in range(len(cs)):
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
            du, t = lm_step(k, f, loads, lam, sc, cs, sn, arm, big_a)
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

    @jit
    def dynamics(si, ci, so, co, g, inner_control, inertia, mass, dm):
        """F_c, M_g per omega^2 (eqs. 8, 12) and their partials in (alpha_i, alpha_o); kinematics eqs. 9, 10, 13."""
        if inner_control:  # tan beta = sin a_i / (cos a_i - D/d_m)
            beta = math.atan2(si, ci - g)
            b_i, b_o = (1.0 - g * ci) / (1.0 - 2.0 * g * ci + g * g), 0.0
        else:  # tan beta = sin a_o / (cos a_o + D/d_m)
            beta = math.atan2(so, co + g)
            b_i, b_o = 0.0, (1.0 + g * co) / (1.0 + 2.0 * g * co + g * g)
        sb, cb = math.sin(beta), math.cos(beta)
        c_ob, s_ob = co * cb + so * sb, so * cb - co * sb  # cos, sin(alpha_o - beta)
        c_ib, s_ib = ci * cb + si * sb, si * cb - ci * sb
        p, r = (1.0 - g * ci) * c_ob, (1.0 + g * co) * c_ib
        p_i, p_o = g * si * c_ob + (1.0 - g * ci) * s_ob * b_i, -(1.0 - g * ci) * s_ob * (1.0 - b_o)
        r_i, r_o = -(1.0 + g * co) * s_ib * (1.0 - b_i), -g * so * c_ib + (1.0 + g * co) * s_ib * b_o
        nn = (1.0 - g * ci) * (1.0 + g * co)
        n_i, n_o = g * si * (1.0 + g * co), -(1.0 - g * ci) * g * so
        den = p + r
        cage, spin = p / den, nn / (g * den)
        cage_i, cage_o = (p_i * r - p * r_i) / den**2, (p_o * r - p * r_o) / den**2
        spin_i = (n_i * den - nn * (p_i + r_i)) / (g * den**2)
        spin_o = (n_o * den - nn * (p_o + r_o)) / (g * den**2)
        mg = inertia * spin * cage * sb
        mg_i = inertia * (spin_i * cage * sb + spin * cage_i * sb + spin * cage * cb * b_i)
        mg_o = inertia * (spin_o * cage * sb + spin * cage_o * sb + spin * cage * cb * b_o)
        return mass * dm / 2.0 * cage**2, mass * dm * cage * cage_i, mass * dm * cage * cage_o, mg, mg_i, mg_o

    @jit
    def ball(ea, er, ga, gr, w2, par, ci_t, dci_t, co_t, dco_t):
        """Ball residual (eqs. 5-6), ring reaction (pa, pr), loads and the 2 x 2 partials
        b_x, b_g, p_x, p_g (flat, row-major) for a ball centre (ea, er) and inner groove centre (ga, gr)."""
        d, dm, ri, ro, mass, inertia, lam_i0, lam_o, inner_control = par[0], par[1], par[2], par[3], par[4], \
            par[5], par[6], par[7], par[8] > 0
        ia, ir = ga - ea, gr - er
        rho_o, rho_i = math.hypot(ea, er), math.hypot(ia, ir)
        so, co, si, ci = ea / rho_o, er / rho_o, ia / rho_i, ir / rho_i
        di, do = rho_i - ri, rho_o - ro
        ki, dli = math.exp(cheb(ci_t, 2.0 * ci - 1.0)), 2.0 * cheb(dci_t, 2.0 * ci - 1.0)
        ko, dlo = math.exp(cheb(co_t, 2.0 * co - 1.0)), 2.0 * cheb(dco_t, 2.0 * co - 1.0)
        dip, dop = max(di, 0.0), max(do, 0.0)
        qi, qo = ki * dip**1.5, ko * dop**1.5
        lam_i = lam_i0 if di > 0 else 0.0  # friction at the inner contact needs contact
        fc, fc_i, fc_o, mg, mg_i, mg_o = dynamics(si, ci, so, co, d / dm, inner_control, inertia, mass, dm)
        fc, fc_i, fc_o, mg, mg_i, mg_o = w2 * fc, w2 * fc_i, w2 * fc_o, w2 * mg, w2 * mg_i, w2 * mg_o
        m = mg / d
        ni, no, ti, to = (si, ci), (so, co), (ci, -si), (co, -so)
        v = (lam_i * ti[0] - lam_o * to[0], lam_i * ti[1] - lam_o * to[1])
        b = (qi * si - qo * so + m * v[0], qi * ci - qo * co + m * v[1] + fc)
        pa, pr = qi * si + m * lam_i * ci, qi * ci - m * lam_i * si
        qi_a, qo_a = -qi * si * dli, -qo * so * dlo
        qi_d, qo_d = 1.5 * ki * math.sqrt(dip), 1.5 * ko * math.sqrt(dop)
        mi, mo = mg_i / d, mg_o / d
        bx, bg, px, pg = [0.0] * 4, [0.0] * 4, [0.0] * 4, [0.0] * 4
        for k in range(2):  # partials in (alpha_i, alpha_o, delta_i, delta_o), chained to x and g
            bp0 = qi_a * ni[k] + qi * ti[k] + mi * v[k] - m * lam_i * ni[k] + (fc_i if k else 0.0)
            bp1 = -qo_a * no[k] - qo * to[k] + mo * v[k] + m * lam_o * no[k] + (fc_o if k else 0.0)
            bp2, bp3 = qi_d * ni[k], -qo_d * no[k]
            pp0 = qi_a * ni[k] + qi * ti[k] + lam_i * (mi * ti[k] - m * ni[k])
            pp1, pp2 = lam_i * mo * ti[k], qi_d * ni[k]
            for j in range(2):
                dx0, dx1, dx2, dx3 = -ti[j] / rho_i, to[j] / rho_o, -ni[j], no[j]
                dg0, dg2 = ti[j] / rho_i, ni[j]
                bx[2 * k + j] = bp0 * dx0 + bp1 * dx1 + bp2 * dx2 + bp3 * dx3
                bg[2 * k + j] = bp0 * dg0 + bp2 * dg2
                px[2 * k + j] = pp0 * dx0 + pp1 * dx1 + pp2 * dx2
                pg[2 * k + j] = pp0 * dg0 + pp2 * dg2
        return b, pa, pr, qi, qo, bx, bg, px, pg

    @jit
    def ball_equilibrium(ea, er, ga, gr, w2, par, ci_t, dci_t, co_t, dco_t, ball_tol, ball_max_iter):
        """Newton on one ball's (ea, er) with halving that keeps it on the outer raceway; returns the
        centre, (pa, pr), the 2 x 2 ring stiffness of the ball (Schur complement) and whether it converged."""
        active = True
        for _ in range(ball_max_iter):
            b, _pa, _pr, _qi, _qo, bx, _bg, _px, _pg = ball(ea, er, ga, gr, w2, par, ci_t, dci_t, co_t, dco_t)
            det = bx[0] * bx[3] - bx[1] * bx[2]
            s0 = -(bx[3] / det * b[0] - bx[1] / det * b[1])
            s1 = -(-bx[2] / det * b[0] + bx[0] / det * b[1])
            if not (math.isfinite(s0) and math.isfinite(s1)):
                s0, s1 = 0.0, 0.0
            t = 1.0
            for _h in range(20):
                if math.hypot(ea + t * s0, er + t * s1) > par[3]:
                    break
                t *= 0.5
            ea, er = ea + t * s0, er + t * s1
            if max(abs(s0), abs(s1)) <= ball_tol * par[0]:
                active = False
                break
        b, pa, pr, qi, qo, bx, bg, px, pg = ball(ea, er, ga, gr, w2, par, ci_t, dci_t, co_t, dco_t)
        det = bx[0] * bx[3] - bx[1] * bx[2]
        i00, i01, i10, i11 = bx[3] / det, -bx[1] / det, -bx[2] / det, bx[0] / det
        s00, s01 = i00 * bg[0] + i01 * bg[2], i00 * bg[1] + i01 * bg[3]
        s10, s11 = i10 * bg[0] + i11 * bg[2], i10 * bg[1] + i11 * bg[3]
        h = (pg[0] - (px[0] * s00 + px[1] * s10), pg[1] - (px[0] * s01 + px[1] * s11),
             pg[2] - (px[2] * s00 + px[3] * s10), pg[3] - (px[2] * s01 + px[3] * s11))
        fs = max(max(qo, qi), 1e-300)
        ok = not active and abs(b[0]) <= 1e-9 * fs and abs(b[1]) <= 1e-9 * fs
        return ea, er, pa, pr, h, ok

    @jit
    def evaluate_speed(u, w2, xa, xr, cs, sn, arm, gr0, par, ci, dci, co, dco, ball_tol, ball_max_iter):
        """Ring reaction, tangent stiffness, sum of ball reactions, all balls converged, new ball centres."""
        f = [0.0] * 5
        k = [0.0] * 25
        total = 0.0
        ok = True
        na, nr = [0.0] * len(cs), [0.0] * len(cs)
        for j in range(len(cs)):
            c, s = cs[j], sn[j]
            ga = u[2] + arm * (u[3] * s - u[4] * c)
            gr = gr0 + u[0] * c + u[1] * s
            na[j], nr[j], pa, pr, h, okb = ball_equilibrium(xa[j], xr[j], ga, gr, w2, par, ci, dci, co, dco,
                                                            ball_tol, ball_max_iter)
            ok = ok and okb
            ja = (0.0, 0.0, 1.0, arm * s, -arm * c)
            jr = (c, s, 0.0, 0.0, 0.0)
            for i in range(5):
                f[i] += pa * ja[i] + pr * jr[i]
                for m in range(5):
                    k[5 * i + m] += ja[i] * (h[0] * ja[m] + h[1] * jr[m]) + jr[i] * (h[2] * ja[m] + h[3] * jr[m])
            total += math.hypot(pa, pr)
        return f, k, total, ok, na, nr

    @jit
    def ring_newton(loads, w2, u, xa, xr, cs, sn, arm, big_a, gr0, par, ci, dci, co, dco, tol, max_iter,
                    lam_max, ball_tol, ball_max_iter):
        """Damped Newton (Levenberg-Marquardt) on the ring at speed w2: (u, converged, iterations, xa, xr)."""
        sc = (1.0, 1.0, 1.0, 1.0 / arm, 1.0 / arm)
        f, k, total, ok, xa, xr = evaluate_speed(u, w2, xa, xr, cs, sn, arm, gr0, par, ci, dci, co, dco,
                                                 ball_tol, ball_max_iter)
        norm, rel = norms(loads, f, total, sc)
        done = rel <= tol and ok
        lam = 0.0
        it = 0
        while not done and it < max_iter and lam <= lam_max:
            it += 1
            du, t = lm_step(k, f, loads, lam, sc, cs, sn, arm, big_a)
            full = t == 1.0
            accepted = False
            for _ls in range(8):
                trial = [u[i] + t * du[i] for i in range(5)]
                f_t, k_t, tot_t, ok_t, xa_t, xr_t = evaluate_speed(trial, w2, xa, xr, cs, sn, arm, gr0, par, ci,
                                                                   dci, co, dco, ball_tol, ball_max_iter)
                n_t, r_t = norms(loads, f_t, tot_t, sc)
                if (n_t < norm * (1.0 - 1e-4 * t) or r_t <= tol) and ok_t:
                    u, f, k, norm, rel, xa, xr = trial, f_t, k_t, n_t, r_t, xa_t, xr_t
                    accepted = True
                    break
                t *= 0.25
                full = False
            lam = 0.1 * lam if full else max(10.0 * lam, 1e-6)
            if not accepted:
                lam = max(100.0 * lam, 1e-3)
            lam = 0.0 if lam < 1e-12 else lam
            done = rel <= tol
        return u, done, it, xa, xr

    @jit
    def solve_speed(loads, start, w2, cs, sn, arm, big_a, gr0, par, ci, dci, co, dco, tol, max_iter,
                    lam_max, ball_tol, ball_max_iter, steps_list):
        """One case at speed: the rest solution, then continuation in omega^2 (1, 4 or 16 equal steps)."""
        u0, it0 = solve_one(loads, start, cs, sn, arm, big_a, gr0, ci, dci, co, dco, tol, max_iter)
        if it0 < 0:
            return u0, -1
        it = it0
        for steps in steps_list:
            us = u0[:]
            good = True
            xa, xr = [0.0] * len(cs), [0.0] * len(cs)
            for n in range(1, steps + 1):
                wk = w2 * n / steps
                if n == 1:  # ball start: on the line between the groove centres, pressed out by F_c
                    for j in range(len(cs)):
                        c, s = cs[j], sn[j]
                        ga = us[2] + arm * (us[3] * s - us[4] * c)
                        gr = gr0 + us[0] * c + us[1] * s
                        rho = math.hypot(ga, gr)
                        x = 2.0 * gr / rho - 1.0
                        wi, wo = math.exp(cheb(ci, x)) ** (-2.0 / 3.0), math.exp(cheb(co, x)) ** (-2.0 / 3.0)
                        fc = wk * par[4] * par[1] / 2.0 * 0.25  # cage at about half the shaft speed
                        do = max((rho - big_a) * wo / (wi + wo), (fc / math.exp(cheb(co, x))) ** (2.0 / 3.0))
                        xa[j], xr[j] = ga / rho * (par[3] + do), gr / rho * (par[3] + do)
                us, conv, itk, xa, xr = ring_newton(loads, wk, us, xa, xr, cs, sn, arm, big_a, gr0, par, ci, dci,
                                                    co, dco, tol, max_iter, lam_max, ball_tol, ball_max_iter)
                it += itk
                good = good and conv
            if good:
                return us, it
        return [math.nan] * 5, -1

    return solve_one, solve_speed


_PY_REST, _PY_SPEED = _functions(lambda f: f)


def _speed_parameters(geo):
    """Per-bearing floats of the ball model at speed, in the order ``ball`` reads them."""
    return np.array([geo.d, geo.dm, geo.ri, geo.ro, geo.mass, geo.inertia, geo.lam[0], geo.lam[1],
                     1.0 if geo.control == "inner" else 0.0])


def _tables(geo):
    cheb = np.polynomial.chebyshev
    ci, co = (np.asarray(t, dtype=float) for t in geo.tables[:2])
    return ci, cheb.chebder(ci), co, cheb.chebder(co)


def rest_solver(geo, *, tol, max_iter):
    """``solve(loads, start) -> (u, iterations)`` for one case at rest, in plain Python (the fair baseline)."""
    args = (list(np.cos(geo.psi)), list(np.sin(geo.psi)), geo.dm / 2.0, geo.big_a, geo.gr0,
            *([float(x) for x in t] for t in _tables(geo)))

    def solve(loads, start):
        return _PY_REST(loads, start, *args, tol, max_iter)

    return solve


def speed_solver(geo, *, tol, max_iter, lam_max, ball_tol, ball_max_iter, continuation):
    """``solve(loads, start, w2) -> (u, iterations)`` for one case at speed, in plain Python (the fair baseline).

    ``start`` is the library's rest start for the case; the rest solve, the ball equilibria and the
    continuation in omega^2 are all done here, one case at a time.
    """
    args = (list(np.cos(geo.psi)), list(np.sin(geo.psi)), geo.dm / 2.0, geo.big_a, geo.gr0,
            [float(x) for x in _speed_parameters(geo)], *([float(x) for x in t] for t in _tables(geo)))

    class _Sized(list):  # the kernels read ``len(cs)`` (numpy arrays); give the lists one
        size = property(len)

    args = (_Sized(args[0]), _Sized(args[1])) + args[2:]
    lim = (tol, max_iter, lam_max, ball_tol, ball_max_iter, tuple(continuation))

    def solve(loads, start, w2):
        return _PY_SPEED(loads, start, w2, *args, *lim)

    return solve


def compiled(geo, loads, starts, *, tol, max_iter):
    """All cases: (u (n, 5), iterations (n,), -1 if not converged); ``geo`` from ``combined._geometry``."""
    global _COMPILED
    if _COMPILED is None:
        import numba

        one, _speed = _functions(numba.njit)

        @numba.njit(parallel=True)
        def kernel(loads, starts, cs, sn, arm, big_a, gr0, ci, dci, co, dco, tol, max_iter, out, iters):
            for n in numba.prange(loads.shape[0]):
                u, iters[n] = one(loads[n], starts[n], cs, sn, arm, big_a, gr0, ci, dci, co, dco, tol, max_iter)
                for i in range(5):
                    out[n, i] = u[i]

        _COMPILED = kernel
    ci, dci, co, dco = _tables(geo)
    loads, starts = np.ascontiguousarray(loads, dtype=float), np.ascontiguousarray(starts, dtype=float)
    out, iters = np.empty_like(loads), np.empty(len(loads), dtype=np.int64)
    _COMPILED(loads, starts, np.cos(geo.psi), np.sin(geo.psi), geo.dm / 2.0, geo.big_a, geo.gr0, ci, dci, co, dco,
              float(tol), int(max_iter), out, iters)
    return out, iters


def compiled_speed(geo, loads, starts, w2, *, tol, max_iter, lam_max, ball_tol, ball_max_iter, continuation):
    """All cases at speed (loads, starts (n, 5), w2 (n,)) by the compiled kernel: (u (n, 5), iterations)."""
    global _COMPILED_SPEED
    if _COMPILED_SPEED is None:
        import numba

        _one, one = _functions(numba.njit)

        @numba.njit(parallel=True)
        def kernel(loads, starts, w2, cs, sn, arm, big_a, gr0, par, ci, dci, co, dco, tol, max_iter, lam_max,
                   ball_tol, ball_max_iter, steps, out, iters):
            for n in numba.prange(loads.shape[0]):
                u, iters[n] = one(loads[n], starts[n], w2[n], cs, sn, arm, big_a, gr0, par, ci, dci, co, dco, tol,
                                  max_iter, lam_max, ball_tol, ball_max_iter, steps)
                for i in range(5):
                    out[n, i] = u[i]

        _COMPILED_SPEED = kernel
    loads, starts = np.ascontiguousarray(loads, dtype=float), np.ascontiguousarray(starts, dtype=float)
    out, iters = np.empty_like(loads), np.empty(len(loads), dtype=np.int64)
    _COMPILED_SPEED(loads, starts, np.ascontiguousarray(w2, dtype=float), np.cos(geo.psi), np.sin(geo.psi),
                    geo.dm / 2.0, geo.big_a, geo.gr0, _speed_parameters(geo), *_tables(geo), float(tol),
                    int(max_iter), float(lam_max), float(ball_tol), int(ball_max_iter), tuple(continuation), out, iters)
    return out, iters

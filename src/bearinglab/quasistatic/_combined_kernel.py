r"""The compiled 5-DOF solve, one case at a time: the kernel of :mod:`bearinglab.quasistatic.combined` (private).

The same model, algorithm, start, tolerances and iteration limits as the batched numpy path, written in
scalar form (``math``, small arrays allocated once per case) so that numba compiles it, and run over the
cases in parallel (issue 31):

- at rest, the damped ring Newton of :func:`bearinglab.quasistatic.combined._newton`: each ball a Hertz
  spring between the groove-curvature centres, the analytic tangent stiffness sum_j J_j^T H_j J_j,
  Levenberg-Marquardt damping with its update rule, the trust region of A/2, the line search of 8 cuts by
  4, the relative residual 1e-12 or its rounding floor, held freedoms;
- at speed, from the rest solution, every ball solved alone at the rest rings (2 x 2 Newton with the
  halving that keeps it on its outer raceway), then the block Newton on ring and balls of
  :mod:`bearinglab.quasistatic._combined_speed` (Schur complement per ball), with the continuation in
  omega^2 (4, then 16 steps) for a case that fails at once;
- at given ring displacements (:func:`bearinglab.reactions.bearing_reactions`), the ring load and
  stiffness: the closed form at rest, every ball solved alone at speed.

The 5 x 5 systems are solved with partial pivoting (numpy without, LAPACK for a weak pivot), a ball at
rest takes K_n from one Chebyshev series of ln K_n (fitted to both contacts' series on their nodes, the
same interpolation error of ~1e-14; numpy combines K_i and K_o), and the pressures at the solution are
computed here with the other outputs: the two engines agree to rounding, not bit for bit, while each
gives a case the same bits in any batch (every case is computed from its own inputs alone). Without numba the functions run as plain Python (:func:`plain`, the fair scalar baseline of
bench/combined.py).

Functions
---------
available       True if numba imports (the kernel can run)
solve           every case of a batch: u, converged, iterations and the outputs at the solution
reactions       ring load and stiffness at given displacements (at rest or at speed), every case
plain           the per-case functions in plain Python: ``(solve_case, react_case)``
PARAMETERS      the order of the per-bearing constants of :func:`parameters`
parameters      those constants of a prepared geometry

References: those of :mod:`bearinglab.quasistatic.combined` and :mod:`bearinglab.quasistatic._compiled`
(Clenshaw's recurrence, Gaussian elimination).
"""

from __future__ import annotations

import math
import types

import numpy as np

from .. import _numba
from ._compiled import gauss5_into

try:
    import numba
except ImportError:  # combined.load_distribution(engine="auto") stays on numpy
    numba = None

__all__ = ["PARAMETERS", "available", "parameters", "plain", "reactions", "solve"]

#: The per-bearing constants the kernel takes, in order.
PARAMETERS = ("z", "d", "dm", "big_a", "gr0", "ri", "ro", "mass", "inertia", "lam_i", "lam_o", "inner_control",
              "tol", "max_iter", "lam_max", "noise", "resolvable", "ball_tol", "ball_max_iter", "fi", "fo", "ep",
              "cos_free")
_EPS = 2.220446049250313e-16
_LINE_SEARCH = 8
_PIVOT = 1e-300  # gauss5_into pivots; a zero pivot gives NaN (the step is then rejected)


def available():
    """True if numba imports, so that the compiled kernel can run."""
    return numba is not None


def _jit(func):
    """numba.njit, cached; a division by zero gives inf or NaN as in numpy (the step is then rejected)."""
    return func if numba is None else numba.njit(cache=True, error_model="numpy")(func)


# --------------------------------------------------------------------------- Hertz constants
def _norm2(a, b):
    """sqrt(a^2 + b^2): the C library's hypot guards against overflow at several times the cost, and no
    length here comes near it."""
    return math.sqrt(a * a + b * b)



def hertz_n(ser, c):
    """ln K_n and d ln K_n / d cos(alpha) of the ball between both contacts at cos(alpha) = c, from rows 4
    and 5 of the series (:func:`parameters`): one Clenshaw pass instead of both contacts' four."""
    x = 2.0 * c - 1.0
    a1 = a2 = b1 = b2 = 0.0
    for j in range(len(ser[0]) - 1, 0, -1):
        a1, a2 = ser[4][j] + 2.0 * x * a1 - a2, a1
        b1, b2 = ser[5][j] + 2.0 * x * b1 - b2, b1
    return ser[4][0] + x * a1 - a2, ser[5][0] + x * b1 - b2


def hertz4(ser, ci, co):
    """ln K_i, d ln K_i / d cos(alpha_i), ln K_o, d ln K_o / d cos(alpha_o) at cos(alpha) = ci and co, from
    the (4, N) series of combined._series: the four sums of Clenshaw's recurrence in one loop."""
    xi, xo = 2.0 * ci - 1.0, 2.0 * co - 1.0
    a1 = a2 = b1 = b2 = c1 = c2 = d1 = d2 = 0.0
    for j in range(len(ser[0]) - 1, 0, -1):
        a1, a2 = ser[0][j] + 2.0 * xi * a1 - a2, a1
        b1, b2 = ser[1][j] + 2.0 * xi * b1 - b2, b1
        c1, c2 = ser[2][j] + 2.0 * xo * c1 - c2, c1
        d1, d2 = ser[3][j] + 2.0 * xo * d1 - d2, d1
    return (ser[0][0] + xi * a1 - a2, ser[1][0] + xi * b1 - b2, ser[2][0] + xo * c1 - c2,
            ser[3][0] + xo * d1 - d2)


# --------------------------------------------------------------------------- at rest
def rest_eval(u, loads, free, par, cs, sn, ser, force, k, out_q, out_a):
    """Ring load (into ``force``), stiffness (``k``, 25 row-major) and (norm, rel, floor) at u, at rest.

    With ``out_q`` of length Z the ball loads and angles go to ``out_q``, ``out_a``.
    """
    z, arm, big_a, gr0 = len(cs), 0.5 * par[2], par[3], par[4]
    f0 = f1 = f2 = f3 = f4 = 0.0
    s11cc = s11cs = s11ss = 0.0
    s00 = s00s = s00c = s00ss = s00sc = s00cc = 0.0
    s01c = s01s = s01sc = s01ss = s01cc = 0.0
    s10c = s10s = s10sc = s10ss = s10cc = 0.0
    total = noise = 0.0
    for j in range(z):
        c, s = cs[j], sn[j]
        ga = u[2] + arm * (u[3] * s - u[4] * c)
        gr = gr0 + (u[0] * c + u[1] * s)
        rho = _norm2(ga, gr)
        sa, ca = ga / rho, gr / rho
        lkn, dlkn = hertz_n(ser, ca)
        kn = math.exp(lkn)
        defl = max(rho - big_a, 0.0)
        root = math.sqrt(defl)
        q = kn * defl * root
        dq = 1.5 * kn * root
        qa_r, q_r = -q * sa * dlkn / rho, q / rho
        h00 = dq * sa * sa + qa_r * sa * ca + q_r * ca * ca
        h01 = dq * sa * ca - qa_r * sa * sa - q_r * ca * sa
        h10 = dq * ca * sa + qa_r * ca * ca - q_r * sa * ca
        h11 = dq * ca * ca - qa_r * ca * sa + q_r * sa * sa
        pa, pr = q * sa, q * ca
        f0 += pr * c
        f1 += pr * s
        f2 += pa
        f3 += pa * s
        f4 += pa * c
        cc, cs_, ss = c * c, c * s, s * s
        s11cc += h11 * cc
        s11cs += h11 * cs_
        s11ss += h11 * ss
        s00 += h00
        s00s += h00 * s
        s00c += h00 * c
        s00ss += h00 * ss
        s00sc += h00 * cs_
        s00cc += h00 * cc
        s01c += h01 * c
        s01s += h01 * s
        s01sc += h01 * cs_
        s01ss += h01 * ss
        s01cc += h01 * cc
        s10c += h10 * c
        s10s += h10 * s
        s10sc += h10 * cs_
        s10ss += h10 * ss
        s10cc += h10 * cc
        total += _norm2(pa, pr)
        noise += dq * _EPS * rho
        if len(out_q):
            out_q[j] = q
            out_a[j] = math.atan2(ga, gr)
    force[0], force[1], force[2], force[3], force[4] = f0, f1, f2, arm * f3, -arm * f4
    _assemble(k, arm, s11cc, s11cs, s11ss, s00, s00s, s00c, s00ss, s00sc, s00cc, s01c, s01s, s01sc, s01ss, s01cc,
              s10c, s10s, s10sc, s10ss, s10cc)
    return _norms(loads, force, free, total, noise, arm, par[15], par[16])


def _assemble(k, arm, s11cc, s11cs, s11ss, s00, s00s, s00c, s00ss, s00sc, s00cc, s01c, s01s, s01sc, s01ss, s01cc,
              s10c, s10s, s10sc, s10ss, s10cc):
    """The 5 x 5 ring stiffness (row-major into ``k``) from the weighted sums over the balls
    (:func:`bearinglab.quasistatic._ring.assemble`)."""
    a2 = arm * arm
    k[0], k[1], k[5], k[6] = s11cc, s11cs, s11cs, s11ss
    k[12], k[13], k[14] = s00, arm * s00s, -arm * s00c
    k[17], k[22] = k[13], k[14]
    k[18], k[19], k[23], k[24] = a2 * s00ss, -a2 * s00sc, -a2 * s00sc, a2 * s00cc
    k[10], k[11] = s01c, s01s
    k[15], k[16], k[20], k[21] = arm * s01sc, arm * s01ss, -arm * s01cc, -arm * s01sc
    k[2], k[7] = s10c, s10s
    k[3], k[8], k[4], k[9] = arm * s10sc, arm * s10ss, -arm * s10cc, -arm * s10sc


def _norms(loads, force, free, total, noise, arm, noise_factor, resolvable):
    """(|F - F(u)| scaled, relative, rounding floor), as combined._measure."""
    res = 0.0
    ref = 0.0
    for i in range(5):
        sc = 1.0 if i < 3 else 1.0 / arm
        res += ((loads[i] - force[i]) * free[i] * sc) ** 2
        ref += (loads[i] * sc) ** 2
    res = math.sqrt(res)
    scale = max(math.sqrt(ref), total)
    if scale > 0:
        return res, res / scale, min(noise_factor * noise / scale, resolvable)
    return res, res, 0.0


def lm_step(k, r, free, lam, arm, m, du):
    """Levenberg-Marquardt step (K + lam max|diag K| I) du = r in scaled variables, held freedoms kept
    (their rows and columns zeroed, their diagonal kept): ``du`` (5) is written; ``m`` is scratch (35+25+5)."""
    a = m[35:60]
    dmax = 0.0
    for i in range(5):
        dmax = max(dmax, abs(k[6 * i]))
    fill = dmax if dmax > 0 else 1.0
    dsc = 0.0
    for i in range(5):
        si = 1.0 if i < 3 else 1.0 / arm
        for j in range(5):
            sj = 1.0 if j < 3 else 1.0 / arm
            a[5 * i + j] = k[5 * i + j] * free[i] * free[j] * si * sj
        if free[i] == 0.0:
            d = abs(k[6 * i])
            a[6 * i] = (d if d > 0 else fill) * si * si
        dsc = max(dsc, abs(a[6 * i]))
    if not dsc > 0:
        dsc = 1.0
    shift = max(lam, 1e-14) * dsc
    for i in range(5):
        a[6 * i] += shift
    b = m[60:65]
    for i in range(5):
        b[i] = r[i] * free[i] * (1.0 if i < 3 else 1.0 / arm)
    x = gauss5_into(a, b, m)
    for i in range(5):
        du[i] = x[i] * (1.0 if i < 3 else 1.0 / arm)


def _move(du, arm):
    """Largest move of a groove-curvature centre for the ring step du (bounded over the balls)."""
    return max(abs(du[2]) + arm * _norm2(du[3], du[4]), _norm2(du[0], du[1]))


def rest_newton(loads, u, free, par, cs, sn, ser, w):
    """The ring Newton at rest from u (updated in place): (converged, iterations, rel, floor).

    ``w`` is the case's work space (:func:`_work`); its rows 0 (force), 1 (stiffness) hold the last
    accepted evaluation.
    """
    tol, max_iter, lam_max = par[12], int(par[13]), par[14]
    arm, big_a = 0.5 * par[2], par[3]
    force, k, ft, kt, du, trial, m, none = w[0], w[1], w[2], w[3], w[4], w[5], w[6], w[7][:0]
    norm, rel, floor = rest_eval(u, loads, free, par, cs, sn, ser, force, k, none, none)
    lam = 0.0
    it = 0
    while not rel <= max(tol, floor):
        if it >= max_iter or lam > lam_max:
            break
        it += 1
        lm_step(k, _diff(loads, force, m), free, lam, arm, m, du)
        move = _move(du, arm)
        t = min(1.0, 0.5 * big_a / move) if move > 0 else 1.0
        full = t == 1.0
        accepted = False
        for _ls in range(_LINE_SEARCH):
            for i in range(5):
                trial[i] = u[i] + t * du[i]
            n_t, r_t, fl_t = rest_eval(trial, loads, free, par, cs, sn, ser, ft, kt, none, none)
            if n_t < norm * (1.0 - 1e-4 * t) or r_t <= max(tol, fl_t):
                for i in range(5):
                    u[i] = trial[i]
                    force[i] = ft[i]
                for i in range(25):
                    k[i] = kt[i]
                norm, rel, floor = n_t, r_t, fl_t
                accepted = True
                break
            t *= 0.25
            full = False
        if full:
            lam = 0.1 * lam
        if not accepted:
            lam = max(100.0 * lam, 1e-3)
        if lam < 1e-12:
            lam = 0.0
    return rel <= max(tol, floor), it, rel, floor


def _diff(loads, force, m):
    r = m[65:70]
    for i in range(5):
        r[i] = loads[i] - force[i]
    return r


# --------------------------------------------------------------------------- balls at speed
def dynamics(si, ci, so, co, g, inner_control, inertia, mass, dm):
    """F_c, its partials in (alpha_i, alpha_o), M_g and its partials, per omega^2 (ball._dynamics)."""
    if inner_control > 0.0:  # tan beta = sin a_i / (cos a_i - D/d_m)
        y, x = si, ci - g
        b_i, b_o = (1.0 - g * ci) / (1.0 - 2.0 * g * ci + g * g), 0.0
    else:  # tan beta = sin a_o / (cos a_o + D/d_m)
        y, x = so, co + g
        b_i, b_o = 0.0, (1.0 + g * co) / (1.0 + 2.0 * g * co + g * g)
    rb = _norm2(y, x)
    sb, cb = y / rb, x / rb  # sin and cos of beta = atan2(y, x)
    c_ob, s_ob = co * cb + so * sb, so * cb - co * sb
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
    fc = mass * dm / 2.0 * cage**2
    mg = inertia * spin * cage * sb
    mg_i = inertia * (spin_i * cage * sb + spin * cage_i * sb + spin * cage * cb * b_i)
    mg_o = inertia * (spin_o * cage * sb + spin * cage_o * sb + spin * cage * cb * b_o)
    return fc, mass * dm * cage * cage_i, mass * dm * cage * cage_o, mg, mg_i, mg_o


def ball(xa, xr, ga, gr, w2, par, ser, full, o):
    """One ball at speed (combined._ball_state): writes into ``o`` (length 30) b0, b1, pa, pr, qi, qo, mg,
    fc, do, noise, noise_b, then bx (4) and, with ``full``, bg, px, pg (4 each)."""
    d, dm, ri, ro, mass, inertia = par[1], par[2], par[5], par[6], par[7], par[8]
    ia, ir = ga - xa, gr - xr
    rho_o, rho_i = _norm2(xa, xr), _norm2(ia, ir)
    so, co = xa / rho_o, xr / rho_o
    si, ci = ia / rho_i, ir / rho_i
    di, do = rho_i - ri, rho_o - ro
    lki, dli, lko, dlo = hertz4(ser, ci, co)
    ki, ko = math.exp(lki), math.exp(lko)
    dip, dop = max(di, 0.0), max(do, 0.0)
    rti, rto = math.sqrt(dip), math.sqrt(dop)
    qi, qo = ki * dip * rti, ko * dop * rto
    lam_i = par[9] if di > 0 else 0.0
    lam_o = par[10]
    fc, fc_i, fc_o, mg, mg_i, mg_o = dynamics(si, ci, so, co, d / dm, par[11], inertia, mass, dm)
    fc, fc_i, fc_o, mg, mg_i, mg_o = w2 * fc, w2 * fc_i, w2 * fc_o, w2 * mg, w2 * mg_i, w2 * mg_o
    m = mg / d
    v0, v1 = lam_i * ci - lam_o * co, -lam_i * si + lam_o * so
    o[0] = qi * si - qo * so + m * v0
    o[1] = qi * ci - qo * co + m * v1 + fc
    o[2] = qi * si + m * lam_i * ci
    o[3] = qi * ci - m * lam_i * si
    o[4], o[5], o[6], o[7], o[8] = qi, qo, mg, fc, do
    o[9] = 1.5 * ki * rti * _EPS * rho_i
    o[10] = 1.5 * (ki * rti * rho_i + ko * rto * rho_o) * _EPS
    qi_a, qo_a = -qi * si * dli, -qo * so * dlo
    qi_d, qo_d = 1.5 * ki * rti, 1.5 * ko * rto
    mi, mo = mg_i / d, mg_o / d
    ba_i = qi_a * si + qi * ci + mi * v0 - m * lam_i * si
    ba_o = -qo_a * so - qo * co + mo * v0 + m * lam_o * so
    br_i = qi_a * ci - qi * si + mi * v1 - m * lam_i * ci + fc_i
    br_o = -qo_a * co + qo * so + mo * v1 + m * lam_o * co + fc_o
    ai_a, ai_r, ao_a, ao_r = -ci / rho_i, si / rho_i, co / rho_o, -so / rho_o
    o[11] = ba_i * ai_a + ba_o * ao_a - qi_d * si * si + (-qo_d) * so * so
    o[12] = ba_i * ai_r + ba_o * ao_r - qi_d * si * ci + (-qo_d) * so * co
    o[13] = br_i * ai_a + br_o * ao_a - qi_d * ci * si + (-qo_d) * co * so
    o[14] = br_i * ai_r + br_o * ao_r - qi_d * ci * ci + (-qo_d) * co * co
    if not full:
        return
    pa_i = qi_a * si + qi * ci + lam_i * (mi * ci - m * si)
    pr_i = qi_a * ci - qi * si + lam_i * (-mi * si - m * ci)
    pa_o, pr_o = lam_i * mo * ci, -lam_i * mo * si
    gi_a, gi_r = ci / rho_i, -si / rho_i
    o[15] = ba_i * gi_a + qi_d * si * si
    o[16] = ba_i * gi_r + qi_d * si * ci
    o[17] = br_i * gi_a + qi_d * ci * si
    o[18] = br_i * gi_r + qi_d * ci * ci
    o[19] = pa_i * ai_a + pa_o * ao_a - qi_d * si * si
    o[20] = pa_i * ai_r + pa_o * ao_r - qi_d * si * ci
    o[21] = pr_i * ai_a + pr_o * ao_a - qi_d * ci * si
    o[22] = pr_i * ai_r + pr_o * ao_r - qi_d * ci * ci
    o[23] = pa_i * gi_a + qi_d * si * si
    o[24] = pa_i * gi_r + qi_d * si * ci
    o[25] = pr_i * gi_a + qi_d * ci * si
    o[26] = pr_i * gi_r + qi_d * ci * ci


def ball_start(ga, gr, w2, par, ser):
    """(xa, xr): the ball on the line between its groove centres, pressed out by F_c (combined._ball_start)."""
    rho = _norm2(ga, gr)
    na, nr = ga / rho, gr / rho
    lki, _dli, lko, _dlo = hertz4(ser, nr, nr)
    wi, wo = math.exp(lki * (-2.0 / 3.0)), math.exp(lko * (-2.0 / 3.0))
    fc = w2 * par[7] * par[2] / 2.0 * 0.25
    do = par[6] + max((rho - par[3]) * wo / (wi + wo), fc ** (2.0 / 3.0) * wo)
    return na * do, nr * do


def ball_newton(xa, xr, ga, gr, w2, par, ser, o):
    """One ball's equilibrium at fixed rings from (xa, xr) (combined._speed_balls): (xa, xr, converged)."""
    ro, tol = par[6], par[17] * par[1]
    for _ in range(int(par[18])):
        ball(xa, xr, ga, gr, w2, par, ser, False, o)
        det = o[11] * o[14] - o[12] * o[13]
        s0 = -(o[14] / det * o[0] + (-o[12] / det) * o[1])
        s1 = -((-o[13] / det) * o[0] + o[11] / det * o[1])
        if not (math.isfinite(s0) and math.isfinite(s1)):
            s0, s1 = 0.0, 0.0
        t = 1.0
        for _h in range(20):  # keep the ball on the outer raceway
            if _norm2(xa + t * s0, xr + t * s1) > ro:
                break
            t *= 0.5
        xa, xr = xa + t * s0, xr + t * s1
        if not max(abs(s0), abs(s1)) > tol:
            return xa, xr, True
    return xa, xr, False


def schur(o):
    """(dxb0, dxb1, dxdg00, dxdg01, dxdg10, dxdg11, h00, h01, h10, h11, relaxed pa, relaxed pr) of a ball
    state ``o`` of :func:`ball` (combined._schur)."""
    det = o[11] * o[14] - o[12] * o[13]
    i0, i1, i2, i3 = o[14] / det, -o[12] / det, -o[13] / det, o[11] / det
    dxb0, dxb1 = -(i0 * o[0] + i1 * o[1]), -(i2 * o[0] + i3 * o[1])
    g0, g1, g2, g3 = (-(i0 * o[15] + i1 * o[17]), -(i0 * o[16] + i1 * o[18]), -(i2 * o[15] + i3 * o[17]),
                      -(i2 * o[16] + i3 * o[18]))
    h0 = o[23] + (o[19] * g0 + o[20] * g2)
    h1 = o[24] + (o[19] * g1 + o[20] * g3)
    h2 = o[25] + (o[21] * g0 + o[22] * g2)
    h3 = o[26] + (o[21] * g1 + o[22] * g3)
    ra = o[2] + (o[19] * dxb0 + o[20] * dxb1)
    rr = o[3] + (o[21] * dxb0 + o[22] * dxb1)
    return dxb0, dxb1, g0, g1, g2, g3, h0, h1, h2, h3, ra, rr


def speed_eval(u, xa, xr, w2, loads, free, par, cs, sn, ser, o, bs, force, relaxed, k):
    """Ring and balls at (u, x) at speed (_combined_speed._measure): the ring load (``force``), the
    relaxed reaction, the stiffness ``k``, every ball's Schur parts and outputs in ``bs`` (rows dxb0, dxb1,
    dxdg (4), qi, qo, mg, fc); returns (merit, rel, floor, converged, valid)."""
    z, arm, gr0, tol, noise_factor = len(cs), 0.5 * par[2], par[4], par[12], par[15]
    f0 = f1 = f2 = f3 = f4 = 0.0
    r0 = r1 = r2 = r3 = r4 = 0.0
    s11cc = s11cs = s11ss = 0.0
    s00 = s00s = s00c = s00ss = s00sc = s00cc = 0.0
    s01c = s01s = s01sc = s01ss = s01cc = 0.0
    s10c = s10s = s10sc = s10ss = s10cc = 0.0
    total = noise = bsq = 0.0
    balls_ok = True
    valid = True
    for j in range(z):
        c, s = cs[j], sn[j]
        ga = u[2] + arm * (u[3] * s - u[4] * c)
        gr = gr0 + (u[0] * c + u[1] * s)
        ball(xa[j], xr[j], ga, gr, w2, par, ser, True, o)
        dxb0, dxb1, g0, g1, g2, g3, h00, h01, h10, h11, ra, rr = schur(o)
        bs[0][j], bs[1][j], bs[2][j], bs[3][j], bs[4][j], bs[5][j] = dxb0, dxb1, g0, g1, g2, g3
        bs[6][j], bs[7][j], bs[8][j], bs[9][j] = o[4], o[5], o[6], o[7]
        pa, pr = o[2], o[3]
        f0 += pr * c
        f1 += pr * s
        f2 += pa
        f3 += pa * s
        f4 += pa * c
        r0 += rr * c
        r1 += rr * s
        r2 += ra
        r3 += ra * s
        r4 += ra * c
        cc, cs_, ss = c * c, c * s, s * s
        s11cc += h11 * cc
        s11cs += h11 * cs_
        s11ss += h11 * ss
        s00 += h00
        s00s += h00 * s
        s00c += h00 * c
        s00ss += h00 * ss
        s00sc += h00 * cs_
        s00cc += h00 * cc
        s01c += h01 * c
        s01s += h01 * s
        s01sc += h01 * cs_
        s01ss += h01 * ss
        s01cc += h01 * cc
        s10c += h10 * c
        s10s += h10 * s
        s10sc += h10 * cs_
        s10ss += h10 * ss
        s10cc += h10 * cc
        total += _norm2(pa, pr)
        noise += o[9]
        b2 = o[0] * o[0] + o[1] * o[1]
        bsq += b2
        if not math.sqrt(b2) <= max(tol * max(o[4], o[5]), noise_factor * o[10]):
            balls_ok = False
        if not o[8] > 0:
            valid = False
    force[0], force[1], force[2], force[3], force[4] = f0, f1, f2, arm * f3, -arm * f4
    relaxed[0], relaxed[1], relaxed[2], relaxed[3], relaxed[4] = r0, r1, r2, arm * r3, -arm * r4
    _assemble(k, arm, s11cc, s11cs, s11ss, s00, s00s, s00c, s00ss, s00sc, s00cc, s01c, s01s, s01sc, s01ss, s01cc,
              s10c, s10s, s10sc, s10ss, s10cc)
    ring, rel, floor = _norms(loads, force, free, total, noise, arm, noise_factor, par[16])
    merit = math.sqrt(ring * ring + bsq)
    if not math.isfinite(merit):
        valid = False
    return merit, rel, floor, rel <= max(tol, floor) and balls_ok and valid, valid


def block_newton(loads, u, xa, xr, w2, free, par, cs, sn, ser, w, bs, bt):
    """Block Newton on ring and balls from (u, x) (updated in place), _combined_speed._newton case by
    case: (converged, iterations, rel, floor); ``bs`` (10, Z) holds the last accepted ball state."""
    max_iter, lam_max = int(par[13]), par[14]
    z, arm, big_a = len(cs), 0.5 * par[2], par[3]
    force, k, ft, kt, du, trial, m, o, relaxed, rt = w[0], w[1], w[2], w[3], w[4], w[5], w[6], w[7], w[8], w[9]
    xt, yt = w[10], w[11]
    merit, rel, floor, conv, valid = speed_eval(u, xa, xr, w2, loads, free, par, cs, sn, ser, o, bs,
                                                force, relaxed, k)
    lam = 0.0
    it = 0
    while not conv and it < max_iter and lam <= lam_max and valid:
        it += 1
        lm_step(k, _diff(loads, relaxed, m), free, lam, arm, m, du)
        move = _move(du, arm)
        for j in range(z):
            c, s = cs[j], sn[j]
            dga = du[2] + arm * (du[3] * s - du[4] * c)
            dgr = du[0] * c + du[1] * s
            da = bs[0][j] + (bs[2][j] * dga + bs[3][j] * dgr)
            dr = bs[1][j] + (bs[4][j] * dga + bs[5][j] * dgr)
            bt[10][j], bt[11][j] = da, dr  # the balls' steps
            move = max(move, _norm2(da, dr))
        t = min(1.0, 0.5 * big_a / move) if move > 0 else 1.0
        if not math.isfinite(t):
            t = 0.0
        full = t == 1.0
        accepted = False
        for _ls in range(_LINE_SEARCH):
            for i in range(5):
                trial[i] = u[i] + t * du[i]
            for j in range(z):
                xt[j] = xa[j] + t * bt[10][j]
                yt[j] = xr[j] + t * bt[11][j]
            m_t, r_t, f_t, c_t, v_t = speed_eval(trial, xt, yt, w2, loads, free, par, cs, sn, ser, o,
                                                 bt, ft, rt, kt)
            if v_t and (m_t < merit * (1.0 - 1e-4 * t) or c_t):
                for i in range(5):
                    u[i] = trial[i]
                    force[i] = ft[i]
                    relaxed[i] = rt[i]
                for i in range(25):
                    k[i] = kt[i]
                for j in range(z):
                    xa[j], xr[j] = xt[j], yt[j]
                    for r in range(10):
                        bs[r][j] = bt[r][j]
                merit, rel, floor, conv = m_t, r_t, f_t, c_t
                accepted = True
                break
            t *= 0.25
            full = False
        if full:
            lam = 0.1 * lam
        if not accepted:
            lam = max(100.0 * lam, 1e-3)
        if lam < 1e-12:
            lam = 0.0
    return conv, it, rel, floor


def pressure(q, c, race, par, ser):
    """p_max = 3 Q / (2 pi a b) of the inner (race 0) or outer (1) contact at cos(alpha) = c (combined._pressure):
    a b = (a* b*) (3 Q / (E' sum rho))^(2/3), the curvature sum of spec 004 eqs. (17)-(21), a* b* from rows 6
    and 7 of the series; at the free angle with ``stiffness_at="free"`` (``cos_free`` not NaN)."""
    if not q > 0.0:
        return 0.0
    if par[22] == par[22]:  # not NaN: the free angle
        c = par[22]
    d = par[1]
    g = d * c / par[2]
    race_term = 2.0 * g / (1.0 - g) if race == 0 else -2.0 * g / (1.0 + g)
    curvature_sum = (4.0 - 1.0 / par[19 + race] + race_term) / d
    x = 2.0 * c - 1.0
    a1 = a2 = 0.0
    row = ser[6 + race]
    for j in range(len(row) - 1, 0, -1):
        a1, a2 = row[j] + 2.0 * x * a1 - a2, a1
    ab = math.exp(row[0] + x * a1 - a2) * (3.0 * q / (par[21] * curvature_sum)) ** (2.0 / 3.0)
    return 3.0 * q / (2.0 * math.pi * ab)


_STEPS = (1, 4, 16)  # continuation in omega^2 (_combined_speed._CONTINUATION)


def solve_case(loads, start, free, w2, par, cs, sn, ser, u, out, stiff, force, w, bs, bt):
    """One case: u (from ``start``), then the rest solve and, at speed, the speed solve. Writes u, the
    outputs ``out`` (8, Z: qi, qo, ai, ao, mg, fc, p_i, p_o), ``stiff`` (25) and ``force`` (5); returns (converged,
    iterations, rel, floor)."""
    z, arm, gr0 = len(cs), 0.5 * par[2], par[4]
    for i in range(5):
        u[i] = start[i]
    ok, it, rel, floor = rest_newton(loads, u, free, par, cs, sn, ser, w)
    if ok and w2 == 0.0:
        rest_eval(u, loads, free, par, cs, sn, ser, force, stiff, out[0], out[2])
        for j in range(z):
            out[1][j], out[3][j], out[4][j], out[5][j] = out[0][j], out[2][j], 0.0, 0.0
            c = math.cos(out[2][j])
            out[6][j], out[7][j] = pressure(out[0][j], c, 0, par, ser), pressure(out[0][j], c, 1, par, ser)
        return True, it, rel, floor
    if not ok:
        return False, it, rel, floor
    rest_u = w[12]
    for i in range(5):
        rest_u[i] = u[i]
    xa, xr, o = w[13], w[14], w[7]
    for steps in _STEPS:
        for i in range(5):
            u[i] = rest_u[i]
        good = True
        for n in range(1, steps + 1):
            wk = w2 * n / steps
            if n == 1:  # every ball in equilibrium at the rest rings
                for j in range(z):
                    c, s = cs[j], sn[j]
                    ga = u[2] + arm * (u[3] * s - u[4] * c)
                    gr = gr0 + (u[0] * c + u[1] * s)
                    x0, x1 = ball_start(ga, gr, wk, par, ser)
                    xa[j], xr[j], _ok = ball_newton(x0, x1, ga, gr, wk, par, ser, o)
            conv, itk, rel, floor = block_newton(loads, u, xa, xr, wk, free, par, cs, sn, ser, w, bs, bt)
            it += itk
            good = good and conv
        if good:
            for i in range(5):
                force[i] = w[0][i]
            for i in range(25):
                stiff[i] = w[1][i]
            for j in range(z):
                c, s = cs[j], sn[j]
                ga = u[2] + arm * (u[3] * s - u[4] * c)
                gr = gr0 + (u[0] * c + u[1] * s)
                out[0][j], out[1][j], out[4][j], out[5][j] = bs[6][j], bs[7][j], bs[8][j], bs[9][j]
                out[2][j], out[3][j] = math.atan2(ga - xa[j], gr - xr[j]), math.atan2(xa[j], xr[j])
                out[6][j] = pressure(out[0][j], math.cos(out[2][j]), 0, par, ser)
                out[7][j] = pressure(out[1][j], math.cos(out[3][j]), 1, par, ser)
            return True, it, rel, floor
    for i in range(5):
        u[i] = math.nan
    return False, it, rel, floor


def _work(z):
    """A case's work space: 15 rows of max(Z, 70) floats (force, stiffness, trial force, trial stiffness,
    step, trial u, solver scratch, ball state, relaxed, trial relaxed, trial xa, trial xr, rest u, xa, xr)."""
    return np.zeros((15, max(z, 70)))


def react_case(u, w2, par, cs, sn, ser, force, k, o):
    """Ring load (``force``) and stiffness (``k``) at the displacement u: the closed form at rest, every
    ball solved alone at speed (combined._evaluate); returns whether every ball converged."""
    z, arm, gr0 = len(cs), 0.5 * par[2], par[4]
    none = force[:0]
    if w2 == 0.0:
        rest_eval(u, np.zeros(5), np.ones(5), par, cs, sn, ser, force, k, none, none)
        return True
    f0 = f1 = f2 = f3 = f4 = 0.0
    s11cc = s11cs = s11ss = 0.0
    s00 = s00s = s00c = s00ss = s00sc = s00cc = 0.0
    s01c = s01s = s01sc = s01ss = s01cc = 0.0
    s10c = s10s = s10sc = s10ss = s10cc = 0.0
    ok = True
    for j in range(z):
        c, s = cs[j], sn[j]
        ga = u[2] + arm * (u[3] * s - u[4] * c)
        gr = gr0 + (u[0] * c + u[1] * s)
        x0, x1 = ball_start(ga, gr, w2, par, ser)
        xa, xr, conv = ball_newton(x0, x1, ga, gr, w2, par, ser, o)
        ball(xa, xr, ga, gr, w2, par, ser, True, o)
        fs = max(max(o[5], o[4]), 1e-300)
        ok = ok and conv and abs(o[0]) <= 1e-9 * fs and abs(o[1]) <= 1e-9 * fs
        _dxb0, _dxb1, _g0, _g1, _g2, _g3, h00, h01, h10, h11, _ra, _rr = schur(o)
        pa, pr = o[2], o[3]
        f0 += pr * c
        f1 += pr * s
        f2 += pa
        f3 += pa * s
        f4 += pa * c
        cc, cs_, ss = c * c, c * s, s * s
        s11cc += h11 * cc
        s11cs += h11 * cs_
        s11ss += h11 * ss
        s00 += h00
        s00s += h00 * s
        s00c += h00 * c
        s00ss += h00 * ss
        s00sc += h00 * cs_
        s00cc += h00 * cc
        s01c += h01 * c
        s01s += h01 * s
        s01sc += h01 * cs_
        s01ss += h01 * ss
        s01cc += h01 * cc
        s10c += h10 * c
        s10s += h10 * s
        s10sc += h10 * cs_
        s10ss += h10 * ss
        s10cc += h10 * cc
    force[0], force[1], force[2], force[3], force[4] = f0, f1, f2, arm * f3, -arm * f4
    _assemble(k, arm, s11cc, s11cs, s11ss, s00, s00s, s00c, s00ss, s00sc, s00cc, s01c, s01s, s01sc, s01ss, s01cc,
              s10c, s10s, s10sc, s10ss, s10cc)
    return ok


_SCALAR = ("_norm2", "hertz_n", "hertz4", "pressure", "rest_eval", "_assemble", "_norms", "lm_step", "_move", "rest_newton", "_diff", "dynamics", "ball",
           "ball_start", "ball_newton", "schur", "speed_eval", "block_newton", "solve_case", "_work", "react_case")
for _name in _SCALAR:
    globals()[_name] = _jit(globals()[_name])


def _solve_loop(loads, starts, free, w2, par, cs, sn, ser, u, ok, it, rel, floor, out, stiff, force):
    for n in _prange(loads.shape[0]):  # parallel over the cases (each case is independent of the others)
        w = _work(len(cs))
        bs = np.zeros((10, len(cs)))
        bt = np.zeros((12, len(cs)))
        ok[n], it[n], rel[n], floor[n] = solve_case(loads[n], starts[n], free[n], w2[n], par, cs, sn, ser,
                                                    u[n], out[n], stiff[n], force[n], w, bs, bt)


def _react_loop(u, w2, par, cs, sn, ser, force, stiff, ok):
    for n in _prange(u.shape[0]):
        o = np.zeros(30)
        ok[n] = react_case(u[n], w2[n], par, cs, sn, ser, force[n], stiff[n], o)


_prange = range if numba is None else numba.prange
if numba is not None:
    _solve_loop = numba.njit(parallel=True, cache=True, error_model="numpy")(_solve_loop)
    _react_loop = numba.njit(parallel=True, cache=True, error_model="numpy")(_react_loop)


# --------------------------------------------------------------------------- the calls
def parameters(geo, tol, max_iter, lam_max, noise, resolvable, ball_tol, ball_max_iter):
    """The constants of :data:`PARAMETERS` of a geometry (``combined._geometry``) and the solver's limits,
    and its Hertz series (4, N) (``_combined_balls._series``)."""
    vals = {"z": geo.z, "d": geo.d, "dm": geo.dm, "big_a": geo.big_a, "gr0": geo.gr0, "ri": geo.ri, "ro": geo.ro,
            "mass": geo.mass, "inertia": geo.inertia, "lam_i": geo.lam[0], "lam_o": geo.lam[1],
            "inner_control": 1.0 if geo.control == "inner" else 0.0, "tol": tol, "max_iter": max_iter,
            "lam_max": lam_max, "noise": noise, "resolvable": resolvable, "ball_tol": ball_tol,
            "ball_max_iter": ball_max_iter, "fi": geo.fi, "fo": geo.fo, "ep": geo.ep,
            "cos_free": math.cos(geo.a0) if geo.stiffness_at == "free" else math.nan}
    par = np.array([float(vals[k]) for k in PARAMETERS])
    return par, _series8(geo.series, geo.tables[2:4])


def _series8(series, ab):
    """The (4, N) series of both contacts (``_combined_balls._series``); as rows 4 and 5 those of
    ln K_n = -3/2 ln(K_i^(-2/3) + K_o^(-2/3)) and its derivative in cos(alpha), fitted on the Chebyshev
    nodes to the values of the first four rows (the same interpolation error, ~1e-14 in ln K_n), so that
    the ball at rest costs one series and one exponential; as rows 6 and 7 ln(a* b*) of the inner and
    outer contact (the pressures), without their rounding-level tail; every row padded to one length."""
    n = series.shape[1]
    rows = _series6(series)
    ab = [np.asarray(t, dtype=float) for t in ab]
    if ab[0].size > 1:
        keep = 1 + max(int(np.flatnonzero(np.abs(t) > 8.0 * _EPS * np.max(np.abs(t)))[-1]) for t in ab)
        ab = [t[:keep] for t in ab]
    width = max(n, ab[0].size)
    out = np.zeros((8, width))
    out[:6, :n] = rows
    out[6, :ab[0].size], out[7, :ab[1].size] = ab
    return out


def _series6(series):
    n = series.shape[1]
    out = np.zeros((6, n))
    out[:4] = series
    if n == 1:
        lkn = -1.5 * np.log(np.exp(-2.0 / 3.0 * series[0]) + np.exp(-2.0 / 3.0 * series[2]))
        out[4] = lkn
        return out
    x = np.cos(np.pi * (np.arange(n) + 0.5) / n)
    cheb = np.polynomial.chebyshev
    li, lo = cheb.chebval(x, series[0]), cheb.chebval(x, series[2])
    lkn = -1.5 * np.log(np.exp(-2.0 / 3.0 * li) + np.exp(-2.0 / 3.0 * lo))
    out[4] = cheb.chebfit(x, lkn, n - 1)
    out[5, :-1] = 2.0 * cheb.chebder(out[4])
    return out


def solve(geo, loads, starts, free, w2, par, tables):
    """Every case by the kernel: u (n, 5; NaN at speed if failed), converged, iterations, relative residual,
    rounding floor and the outputs at the solution (``qi``, ``qo``, ``ai``, ``ao``, ``mg``, ``fc`` (n, Z),
    ``stiffness`` (n, 5, 5), ``force`` (n, 5))."""
    n, z = len(loads), geo.z
    u = np.empty((n, 5))
    ok = np.zeros(n, dtype=np.bool_)
    it = np.zeros(n, dtype=np.int64)
    rel, floor = np.full(n, np.nan), np.zeros(n)
    out = np.full((n, 8, z), np.nan)
    stiff, force = np.full((n, 25), np.nan), np.full((n, 5), np.nan)
    free = np.ones((n, 5)) if free is None else np.ascontiguousarray(free, dtype=float)
    with _LOCK:
        _solve_loop(np.ascontiguousarray(loads, dtype=float), np.ascontiguousarray(starts, dtype=float), free,
                    np.ascontiguousarray(w2, dtype=float), par, np.ascontiguousarray(geo.cos_psi),
                    np.ascontiguousarray(geo.sin_psi), tables, u, ok, it, rel, floor, out, stiff, force)
    res = {k: out[:, j] for j, k in enumerate(("qi", "qo", "ai", "ao", "mg", "fc", "pi", "po"))}
    res.update(stiffness=stiff.reshape(n, 5, 5), force=force, residual=rel, floor=floor)
    return u, ok, it, res


def reactions(geo, u, w2, par, tables):
    """Ring load (n, 5), stiffness (n, 5, 5) and whether every ball converged (n,), at displacements u."""
    n = len(u)
    force, stiff = np.empty((n, 5)), np.empty((n, 25))
    ok = np.zeros(n, dtype=np.bool_)
    with _LOCK:
        _react_loop(np.ascontiguousarray(u, dtype=float), np.ascontiguousarray(w2, dtype=float), par,
                    np.ascontiguousarray(geo.cos_psi), np.ascontiguousarray(geo.sin_psi), tables, force, stiff, ok)
    return force, stiff.reshape(n, 5, 5), ok


_LOCK = _numba.LOCK  # numba's default (workqueue) threading layer does not allow concurrent launches


def plain():
    """``(solve_case, react_case, work)`` with every helper they call in plain Python (numba or not)."""
    space = dict(globals())
    names = _SCALAR + ("gauss5_into",)
    for name in names:
        func = getattr(space[name], "py_func", space[name])
        space[name] = types.FunctionType(func.__code__, space, name, func.__defaults__)
    return space["solve_case"], space["react_case"], space["_work"]

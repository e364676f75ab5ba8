"""The roller slice model of one case in plain Python and ``math``: the fair baseline of bench/rollers.py.

The same model and solver as :func:`bearinglab.rollers.distribution.load_distribution` for one load case,
written as an engineer would write it without numpy: the laminae in loops, the analytic 5 x 5 stiffness,
the same start, the Levenberg-Marquardt step in the same scaled variables with the same damping rules,
trust region and line search, the same tolerance, and a 5 x 5 Gaussian elimination with partial pivoting.
"""

from __future__ import annotations

import math

from bearinglab.rollers import distribution as _d

EPS = 2.220446049250313e-16


def _geometry(rs):
    ca, sa = math.cos(rs.contact_angle), math.sin(rs.contact_angle)
    half = 0.5 * rs.pitch_diameter
    rows = []
    for psi in rs.azimuth:
        cp, sp = math.cos(psi), math.sin(psi)
        rows.append(([ca * cp, ca * sp, sa, half * sa * sp, -half * sa * cp], [0.0, 0.0, 0.0, -sp, cp]))
    s = [float(x) for x in rs.slice_position]
    base = [-rs.normal_gap - 2.0 * float(p) for p in rs.drop]
    size = max(abs(rs.normal_gap), 2.0 * max(float(p) for p in rs.drop), 2.2250738585072014e-308)
    resolution = _d._NOISE * rs.rollers * len(s) * rs.slice_constant * (EPS * size) ** (10.0 / 9.0)
    return rows, s, base, resolution


def _evaluate(rows, s, base, c, u):
    s_max, base_abs = max(abs(x) for x in s), max(abs(x) for x in base)
    force = [0.0] * 5
    k = [[0.0] * 5 for _ in range(5)]
    total = noise = 0.0
    for g, t in rows:
        gu = sum(gi * ui for gi, ui in zip(g, u))
        tu = sum(ti * ui for ti, ui in zip(t, u))
        q0 = q1 = k0 = k1 = k2 = 0.0
        for sk, bk in zip(s, base):
            d = gu + tu * sk + bk
            if d > 0:
                ninth = math.cbrt(math.cbrt(d))
                q = c * d * ninth
                kk = (10.0 / 9.0) * c * ninth
                q0 += q
                q1 += q * sk
                k0 += kk
                k1 += kk * sk
                k2 += kk * sk * sk
        noise += k0 * (abs(gu) + abs(tu) * s_max + base_abs) * EPS
        total += q0
        for i in range(5):
            force[i] += q0 * g[i] + q1 * t[i]
            for j in range(5):
                k[i][j] += k0 * g[i] * g[j] + k1 * (g[i] * t[j] + t[i] * g[j]) + k2 * t[i] * t[j]
    return force, k, total, noise


def _measure(arm, loads, force, total, noise, free, resolution):
    res = math.sqrt(sum(((loads[i] - force[i]) * free[i] * arm[i]) ** 2 for i in range(5)))
    scale = max(math.sqrt(sum((loads[i] * arm[i]) ** 2 for i in range(5))), total)
    rel = 0.0 if res <= resolution else (res / scale if scale > 0 else res)
    floor = _d._NOISE * noise / scale if scale > 0 else 0.0
    return res, rel, min(floor, _d._RESOLVABLE)


def _solve(a, b):
    """Gaussian elimination with partial pivoting of a 5 x 5 system."""
    m = [row[:] + [bi] for row, bi in zip(a, b)]
    n = len(b)
    for col in range(n):
        p = max(range(col, n), key=lambda r: abs(m[r][col]))
        m[col], m[p] = m[p], m[col]
        for r in range(col + 1, n):
            f = m[r][col] / m[col][col]
            for j in range(col, n + 1):
                m[r][j] -= f * m[col][j]
    x = [0.0] * n
    for r in range(n - 1, -1, -1):
        x[r] = (m[r][n] - sum(m[r][j] * x[j] for j in range(r + 1, n))) / m[r][r]
    return x


def _step(k, residual, free, lam, dm):
    sc = [1.0, 1.0, 1.0, 2.0 / dm, 2.0 / dm]
    diag_raw = [abs(k[i][i]) for i in range(5)]
    big = max(diag_raw)
    held = [[k[i][j] * free[i] * free[j] for j in range(5)] for i in range(5)]
    for i in range(5):
        if not free[i]:
            held[i][i] = diag_raw[i] if diag_raw[i] > 0 else (big if big > 0 else 1.0)
    m = [[held[i][j] * sc[i] * sc[j] for j in range(5)] for i in range(5)]
    diag = max(abs(m[i][i]) for i in range(5))
    diag = diag if diag > 0 else 1.0
    shift = max(lam, 1e-14) * diag
    for i in range(5):
        m[i][i] += shift
    x = _solve(m, [residual[i] * free[i] * sc[i] for i in range(5)])
    return [x[i] * sc[i] for i in range(5)]


def _start(rs, loads):
    big_k = rs.slice_constant * len(rs.slice_position)
    a, z = rs.contact_angle, rs.rollers
    fr, mm = math.hypot(loads[0], loads[1]), math.hypot(loads[3], loads[4])
    gap = rs.normal_gap + 2.0 * min(float(p) for p in rs.drop)
    u = [0.0] * 5
    if fr > 0:
        dr = (max(gap, 0.0) + (4.08 * fr / (z * math.cos(a) * big_k)) ** 0.9) / (math.cos(a) * math.cos(math.pi / z))
        u[0], u[1] = loads[0] / fr * dr, loads[1] / fr * dr
    if a > 0:
        fz = max(loads[2], 0.0)
        u[2] = (gap + (fz / (z * math.sin(a) * big_k)) ** 0.9) / math.sin(a) if fz > 0 else gap / math.sin(a)
    ref = max(max(abs(x) for x in u[:3]), 1e-6)
    k_lin = (10.0 / 9.0) * big_k * ref ** (1.0 / 9.0)
    arm2 = (0.5 * rs.pitch_diameter * math.sin(a)) ** 2 + rs.roller_length**2 / 12.0
    k_tilt = 0.5 * z * k_lin * arm2
    lever = 0.5 * rs.pitch_diameter * math.sin(a) + 0.5 * rs.roller_length
    closing = (max(rs.normal_gap, 0.0) + 2.0 * max(float(rs.drop[0]), float(rs.drop[-1]))) / lever if mm > fr * lever else 0.0
    cap = 0.05 * rs.roller_diameter / rs.roller_length
    if mm > 0:
        for i in (3, 4):
            u[i] = min(max(loads[i] / mm * (mm / k_tilt + closing), -cap), cap)
    return u


def solve_one(rs, loads, tol=_d.TOL, max_iter=_d.MAX_ITER):
    """The displacement of one case (held axial freedom of a cylindrical bearing at 0). [m, rad]"""
    rows, s, base, resolution = _geometry(rs)
    loads = [float(x) for x in loads]
    c, dm = rs.slice_constant, rs.pitch_diameter
    arm = [1.0, 1.0, 1.0, 2.0 / dm, 2.0 / dm]
    free = [1.0, 1.0, 1.0 if rs.axial_support == "raceways" else 0.0, 1.0, 1.0]
    u = _start(rs, loads)
    if not free[2]:
        u[2] = 0.0
    limit, span = 0.1 * rs.roller_diameter, 0.5 * rs.pitch_diameter + 0.5 * rs.roller_length
    force, k, total, noise = _evaluate(rows, s, base, c, u)
    norm, rel, floor = _measure(arm, loads, force, total, noise, free, resolution)
    lam = 0.0
    loaded = any(loads[i] * free[i] != 0 for i in range(5))
    for _ in range(max_iter):
        if rel <= max(tol, floor) or lam > _d._LAM_MAX:
            break
        du = _step(k, [loads[i] - force[i] for i in range(5)], free, lam, dm)
        move = math.hypot(du[0], du[1]) + abs(du[2]) + span * math.hypot(du[3], du[4])
        t = min(1.0, limit / move) if move > 0 else 1.0
        full, accepted = t == 1.0, False
        for _ls in range(_d._LINE_SEARCH):
            trial = [u[i] + t * du[i] for i in range(5)]
            f_t, k_t, tot_t, n_t = _evaluate(rows, s, base, c, trial)
            nm_t, rel_t, fl_t = _measure(arm, loads, f_t, tot_t, n_t, free, resolution)
            if (nm_t < norm * (1.0 - 1e-4 * t) or rel_t <= max(tol, fl_t)) and (tot_t > 0 or not loaded):
                u, force, k, norm, rel, floor, accepted = trial, f_t, k_t, nm_t, rel_t, fl_t, True
                break
            t *= 0.25
            full = False
        if accepted:
            lam = 0.1 * lam if full else lam
        else:
            lam = max(100.0 * lam, 1e-3)
        if lam < 1e-12:
            lam = 0.0
    if not rel <= max(tol, floor):
        raise RuntimeError(f"case {loads} did not converge")
    return u

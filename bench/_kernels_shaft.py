r"""The shaft system one case at a time in plain Python: the fair per-case baseline of bench/shaft.py.

Not part of the library. The same algorithm as :func:`bearinglab.shaft.statics._newton`, for one case,
as an engineer would write it without numpy: the condensed shaft (K_c, computed once, as the batched
path does, outside the timing), each bearing's reaction and 5 x 5 tangent stiffness at rest ball by ball
(the 5-DOF kernel's own per-case reaction run by CPython, as bench/combined.py's baseline), the tangent of
the condensed system, a Gaussian elimination, Levenberg-Marquardt damping, the trust region of half the
groove-centre distance per step, the line search of 8 cuts by 4, the same convergence test (relative
residual and the rounding floor of K_c u_B), then the shaft's other nodes and the supports' loads.
"""

from __future__ import annotations

import math

import numpy as np

from bearinglab.quasistatic import _combined_kernel, combined

__all__ = ["case_solver"]


def _ball_evaluate():
    """The plain-Python ring reaction and tangent stiffness of the 5-DOF model's kernel
    (``quasistatic._combined_kernel.react_case`` run by CPython), taken from the fair scalar baseline of the
    5-DOF model (bench/combined.py) so that both baselines are one code."""
    _solve, react, _work = _combined_kernel.plain()

    def evaluate(u, w2, par, cs, sn, ser):
        force, k, o = [0.0] * 5, [0.0] * 25, [0.0] * 30
        react(u, w2, par, cs, sn, ser, force, k, o)
        return force, k, None

    return evaluate


def _gauss(a, b):
    """Solve a x = b (lists, a row-major n x n) by Gaussian elimination with partial pivoting."""
    n = len(b)
    m = [a[i * n:(i + 1) * n] + [b[i]] for i in range(n)]
    for c in range(n):
        p = max(range(c, n), key=lambda r: abs(m[r][c]))
        m[c], m[p] = m[p], m[c]
        piv = m[c][c]
        for r in range(c + 1, n):
            f = m[r][c] / piv
            if f != 0.0:
                row, top = m[r], m[c]
                for k in range(c, n + 1):
                    row[k] -= f * top[k]
    x = [0.0] * n
    for r in range(n - 1, -1, -1):
        s = m[r][n]
        for k in range(r + 1, n):
            s -= m[r][k] * x[k]
        x[r] = s / m[r][r]
    return x


def case_solver(asm):
    """``solve(f) -> (u_B + u_H list, iterations, every node's displacement list)`` for one case's nodal loads
    ``f`` (list of 6 n_nodes), in plain Python, for an assembled shaft system at rest (no housing springs
    but a floating bearing's free axial freedom)."""
    from bearinglab.shaft import statics

    evaluate = _ball_evaluate()
    rows = asm.rows
    nb, m = len(asm.coupled), asm.n_unknowns
    kc = asm.condensed.tolist()
    kc_abs = np.abs(asm.condensed).tolist()
    transfer_t = asm.transfer.T.tolist()  # (nb, n_I)
    transfer = asm.transfer.tolist()      # (n_I, nb)
    flex = asm.flexibility.tolist()
    coupled, internal = asm.coupled.tolist(), asm.internal.tolist()
    hk = asm.housing_stiffness.tolist()
    sc = statics._scale(asm, m).tolist()
    eps64 = statics._NOISE * np.finfo(float).eps
    tol, max_iter = statics.TOL, statics.MAX_ITER
    bearings = []
    for j, r in enumerate(rows):
        geo = combined._geometry(*combined._bearing_args(r.bearing), 0.0, "operating", "outer", r.bearing.type)
        par, ser = combined._kernel_parameters(geo, combined.TOL, combined.MAX_ITER)
        bearings.append({"args": (0.0, par.tolist(), [float(x) for x in geo.cos_psi], [float(x) for x in geo.sin_psi],
                                  ser.tolist()),
                         "t": r.transform.tolist(), "o": r.offset, "slot": int(asm.slot[j]),
                         "h": asm.housing_index[j].tolist(), "trust": float(asm.trust[j])})
    ell = asm.length_scale

    def residual(x, fc):
        res = [fc[i] - sum(kc[i][k] * x[k] for k in range(nb)) for i in range(nb)] + \
              [-hk[i - nb] * x[i] for i in range(nb, m)]
        a = [0.0] * (m * m)
        for i in range(nb):
            a[i * m:i * m + nb] = kc[i][:]
        for i in range(nb, m):
            a[i * m + i] = hk[i - nb]
        loads = 0.0
        for b in bearings:
            t, s, h = b["t"], b["slot"], b["h"]
            d = [t[c] * (x[5 * s + c] - (x[h[c]] if h[c] >= 0 else 0.0)) for c in range(5)]
            d[2] += b["o"]
            f, k, _ = evaluate(d, *b["args"])
            tf = [t[c] * f[c] for c in range(5)]
            loads += math.sqrt(sum((tf[c] * sc[c]) ** 2 for c in range(5)))
            idx = [5 * s + c for c in range(5)]
            for c in range(5):
                res[idx[c]] -= tf[c]
                if h[c] >= 0:
                    res[h[c]] += tf[c]
            for r in range(5):
                for c in range(5):
                    kt = k[5 * r + c] * t[r] * t[c]
                    a[idx[r] * m + idx[c]] += kt
                    if h[c] >= 0:
                        a[idx[r] * m + h[c]] -= kt
                    if h[r] >= 0:
                        a[h[r] * m + idx[c]] -= kt
                    if h[r] >= 0 and h[c] >= 0:
                        a[h[r] * m + h[c]] += kt
        norm = math.sqrt(sum((res[i] * sc[i]) ** 2 for i in range(m)))
        loads += math.sqrt(sum((fc[i] * sc[i]) ** 2 for i in range(nb)))
        loads = max(loads, 1e-300)
        terms = math.sqrt(sum((sum(kc_abs[i][k] * abs(x[k]) for k in range(nb)) * sc[i]) ** 2 for i in range(nb)))
        return res, a, norm, norm / loads, eps64 * terms / loads

    def limit(dx):
        frac = 1.0
        for b in bearings:
            s, h = b["slot"], b["h"]
            dd = [dx[5 * s + c] - (dx[h[c]] if h[c] >= 0 else 0.0) for c in range(5)]
            move = max(max(abs(v) for v in dd[:3]), ell * max(abs(v) for v in dd[3:]))
            if move > 0:
                frac = min(frac, b["trust"] / move)
        return frac

    def solve(f):
        fi = [f[i] for i in internal]
        fc = [f[coupled[i]] - sum(transfer_t[i][k] * fi[k] for k in range(len(fi))) for i in range(nb)]
        x = [0.0] * m
        res, a, norm, rel, floor = residual(x, fc)
        lam, it = statics._LAM_MIN, 0
        while rel > max(tol, floor):
            if it == max_iter or lam > statics._LAM_MAX:
                return None, it, None
            it += 1
            dmax = max(abs(a[i * m + i] * sc[i] * sc[i]) for i in range(m)) or 1.0
            As = [a[i * m + k] * sc[i] * sc[k] for i in range(m) for k in range(m)]
            for i in range(m):
                As[i * m + i] += lam * dmax
            y = _gauss(As, [res[i] * sc[i] for i in range(m)])
            dx = [y[i] * sc[i] for i in range(m)]
            frac = limit(dx)
            dx = [v * frac for v in dx]
            step, done = 1.0, False
            for _cut in range(statics._LINE_SEARCH):
                xt = [x[i] + step * dx[i] for i in range(m)]
                r_t, a_t, n_t, rel_t, fl_t = residual(xt, fc)
                if n_t < norm or rel_t <= max(tol, fl_t):
                    x, res, a, norm, rel, floor, done = xt, r_t, a_t, n_t, rel_t, fl_t, True
                    break
                step *= 0.25
            lam = max(lam * 0.25, statics._LAM_MIN) if done else lam * 16.0
        u0 = [sum(flex[i][k] * fi[k] for k in range(len(fi))) for i in range(len(fi))]
        u = [0.0] * len(f)
        for i, dof in enumerate(coupled):
            u[dof] = x[i]
        for i, dof in enumerate(internal):
            u[dof] = u0[i] - sum(transfer[i][k] * x[k] for k in range(nb))
        return x, it, u

    return solve

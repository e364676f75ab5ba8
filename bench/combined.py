"""Benchmark (issue 11): combined-load distribution, batched vs a per-case scalar Newton, at rest and at speed.

At rest: 10 000 random combined load cases (F_x, F_y, F_z, M_x, M_y) on the MASTA deep-groove bearing of
tests/validation (Z = 7, 10 um clearance), one call of ``quasistatic.combined.load_distribution``.
Baseline: the same model and equations solved case by case as an engineer would write them in plain
Python (``math``, no numpy on scalars): Newton on the five ring unknowns with the analytic Jacobian
(sum over balls of J^T H J), a 5 x 5 Gaussian elimination, step halving on the residual norm, the same
start (the library's start formula, computed outside the baseline's timing, which favours it), the same
tolerance and the same Hertz interpolants (Chebyshev series in cos alpha, evaluated by Clenshaw in
Python). Best of k runs for both paths; the answers are compared case by case.

At speed: 2000 combined cases on the 218 bearing at 12 000 rpm, batched vs the library called one case
at a time (the nested ball equilibrium at speed has no scalar re-implementation here: this baseline is
numpy on single cases, so its ratio overstates what a hand-written scalar solver would lose).

Also printed: the whole batched solve in units of one batched residual-plus-Jacobian evaluation of all
cases at the solution.
"""

from __future__ import annotations

import math
import sys

import _kernels
import _kernels_combined
import numpy as np
from _timing import best_of

from bearinglab import catalog
from bearinglab.bearing import BallBearing, Material
from bearinglab.quasistatic import combined
from bearinglab.units import RPM

N_REST, N_BASE = 10_000, 1000
N_SPEED, N_SPEED_BASE = 2000, 50
STEEL = Material("steel", 210e9, 0.3, 7850.0)
DEEP = BallBearing(n_balls=7, ball_diameter=11.5e-3, pitch_diameter=43.5e-3, inner_conformity=0.52,
                   outer_conformity=0.53, radial_clearance=10e-6, type="radial", ball_material=STEEL,
                   ring_material=STEEL)
B218 = catalog.get("B218")


def cases(n, scale, seed=0):
    """Random combined loads (N, N m); thrust of either sign, moments in and out of the load plane."""
    rng = np.random.default_rng(seed)
    return rng.normal(size=(n, 5)) * np.asarray(scale)


def batched(bearing, loads, speed=0.0):
    return combined.combined_analysis(bearing, loads, speed, on_failure="flag")


# ------------------------------------------------------------------ scalar baseline (plain Python)
def _cheb(coef, x):
    b1 = b2 = 0.0
    for c in reversed(coef[1:]):
        b1, b2 = c + 2.0 * x * b1 - b2, b1
    return coef[0] + x * b1 - b2


def _cheb_der(coef):
    return [float(v) for v in np.polynomial.chebyshev.chebder(coef)]


def _gauss(a, b):
    """Solve a 5 x 5 system by elimination with partial pivoting (lists)."""
    n = len(b)
    m = [row[:] + [b[i]] for i, row in enumerate(a)]
    for c in range(n):
        p = max(range(c, n), key=lambda r: abs(m[r][c]))
        m[c], m[p] = m[p], m[c]
        for r in range(c + 1, n):
            f = m[r][c] / m[c][c]
            for k in range(c, n + 1):
                m[r][k] -= f * m[c][k]
    x = [0.0] * n
    for r in range(n - 1, -1, -1):
        x[r] = (m[r][n] - sum(m[r][k] * x[k] for k in range(r + 1, n))) / m[r][r]
    return x


def scalar_solver(bearing, tol=combined.TOL, max_iter=combined.MAX_ITER):
    """A per-case solver of the rest model, built once per bearing."""
    geo = combined._geometry(*combined._bearing_args(bearing), 0.0, "operating", "outer", "radial")
    ci, co = [float(v) for v in geo.tables[0]], [float(v) for v in geo.tables[1]]
    dci, dco = _cheb_der(geo.tables[0]), _cheb_der(geo.tables[1])
    arm, big_a, gr0 = geo.dm / 2.0, geo.big_a, geo.gr0
    balls = [(math.cos(p), math.sin(p)) for p in geo.psi]
    sc = [1.0, 1.0, 1.0, 1.0 / arm, 1.0 / arm]

    def evaluate(u):
        f, k, total = [0.0] * 5, [[0.0] * 5 for _ in range(5)], 0.0
        for c, s in balls:
            ga = u[2] + arm * (u[3] * s - u[4] * c)
            gr = gr0 + u[0] * c + u[1] * s
            rho = math.hypot(ga, gr)
            if rho <= big_a:
                continue
            sa, ca = ga / rho, gr / rho
            x = 2.0 * ca - 1.0
            ki, ko = math.exp(_cheb(ci, x)), math.exp(_cheb(co, x))
            wi, wo = ki ** (-2.0 / 3.0), ko ** (-2.0 / 3.0)
            kn = (wi + wo) ** -1.5
            dl = (wi * 2.0 * _cheb(dci, x) + wo * 2.0 * _cheb(dco, x)) / (wi + wo)
            d = rho - big_a
            q, dq = kn * d**1.5, 1.5 * kn * math.sqrt(d)
            qa = -q * sa * dl
            h = [[dq * sa * sa + qa / rho * sa * ca + q / rho * ca * ca,
                  dq * sa * ca - qa / rho * sa * sa - q / rho * ca * sa],
                 [dq * ca * sa + qa / rho * ca * ca - q / rho * sa * ca,
                  dq * ca * ca - qa / rho * ca * sa + q / rho * sa * sa]]
            ja = (0.0, 0.0, 1.0, arm * s, -arm * c)
            jr = (c, s, 0.0, 0.0, 0.0)
            rows = (ja, jr)
            for i in range(5):
                f[i] += q * sa * ja[i] + q * ca * jr[i]
                for j in range(5):
                    k[i][j] += sum(rows[p][i] * h[p][r] * rows[r][j] for p in range(2) for r in range(2))
            total += q
        return f, k, total

    def norms(loads, f, total):
        res = math.sqrt(sum(((loads[i] - f[i]) * sc[i]) ** 2 for i in range(5)))
        scale = max(math.sqrt(sum((loads[i] * sc[i]) ** 2 for i in range(5))), total)
        return res, res / scale if scale > 0 else res

    def solve(loads, start):
        u = list(start)
        f, k, total = evaluate(u)
        norm, rel = norms(loads, f, total)
        lam = 0.0
        for _ in range(max_iter):
            if rel <= tol:
                return u
            dmax = max(abs(k[i][i] * sc[i] * sc[i]) for i in range(5)) or 1.0
            a = [[k[i][j] * sc[i] * sc[j] + (max(lam, 1e-14) * dmax if i == j else 0.0) for j in range(5)]
                 for i in range(5)]
            du = [v * sc[i] for i, v in enumerate(_gauss(a, [(loads[i] - f[i]) * sc[i] for i in range(5)]))]
            move = max(max(abs(du[2] + arm * (du[3] * s - du[4] * c)), abs(du[0] * c + du[1] * s)) for c, s in balls)
            t = min(1.0, 0.5 * big_a / move) if move > 0 else 1.0
            full = t == 1.0
            for _ls in range(8):
                trial = [u[i] + t * du[i] for i in range(5)]
                f_t, k_t, tot_t = evaluate(trial)
                n_t, r_t = norms(loads, f_t, tot_t)
                if n_t < norm * (1.0 - 1e-4 * t) or r_t <= tol:
                    u, f, k, norm, rel = trial, f_t, k_t, n_t, r_t
                    break
                t *= 0.25
                full = False
            else:
                lam = max(100.0 * lam, 1e-3)
                continue
            lam = 0.1 * lam if full else max(10.0 * lam, 1e-6)
            lam = 0.0 if lam < 1e-12 else lam
        return [math.nan] * 5

    return geo, solve


def baseline(bearing, loads):
    """Per-case scalar solves; starts computed outside the timed loop."""
    geo, solve = scalar_solver(bearing)
    starts = combined._start(geo, np.asarray(loads, dtype=float)).tolist()
    rows = np.asarray(loads, dtype=float).tolist()

    def run():
        return np.array([solve(f, s) for f, s in zip(rows, starts, strict=True)])

    return run


def compiled(bearing, loads):
    """The compiled limit at rest: the same per-case algorithm as ``scalar_solver``, numba over cases.

    The starts (the library's start formula, numpy) are computed inside, as in the batched path.
    """
    geo = combined._geometry(*combined._bearing_args(bearing), 0.0, "operating", "outer", "radial")
    loads = np.asarray(loads, dtype=float)
    u, it = _kernels_combined.compiled(geo, loads, combined._start(geo, loads), tol=combined.TOL,
                                       max_iter=combined.MAX_ITER)
    return u, it


def baseline_speed(bearing, loads, speed):
    def run():  # numpy on one case at a time (see the module docstring)
        return np.array([combined.combined_analysis(bearing, f, speed).displacement for f in loads])

    return run


def evaluation_cost(bearing, state, speed):
    geo = combined._geometry(*combined._bearing_args(bearing), 0.0, "operating", "outer", "radial")
    u = np.asarray(state.displacement).reshape(-1, 5)
    w2 = np.full(len(u), speed**2)
    return best_of(lambda: combined._evaluate(geo, u, w2), 5)[0]


def main(n_rest=N_REST, n_base=N_BASE, n_speed=N_SPEED, n_speed_base=N_SPEED_BASE, repeat=3):
    loads = cases(n_rest, [1500, 1500, 1500, 15.0, 15.0])
    t_batch, state = best_of(lambda: batched(DEEP, loads), repeat)
    t_base, ref = best_of(baseline(DEEP, loads[:n_base]), repeat)
    diff = np.nanmax(np.abs(state.displacement[:n_base] - ref) / [1e-6, 1e-6, 1e-6, 1e-3, 1e-3])
    rate, base_rate = n_rest / t_batch, n_base / t_base
    t_eval = evaluation_cost(DEEP, state, 0.0)
    print(f"rest : {n_rest} cases, {int((~state.converged).sum())} failed, iterations mean "
          f"{state.iterations.mean():.2f} max {state.iterations.max()}")
    print(f"  batched {rate:10.4g} cases/s, scalar baseline {base_rate:10.4g} cases/s ({n_base} cases, "
          f"{int(np.isnan(ref[:, 0]).sum())} failed): ratio {rate / base_rate:.4g}")
    print(f"  max difference {diff:.2e} (um / mrad); solve = {t_batch / t_eval:.1f} x one batched evaluation")
    extra = ""
    if _kernels.available():
        compiled(DEEP, loads[:4])  # compile outside the clock
        t_comp, (fast, _it) = best_of(lambda: compiled(DEEP, loads), repeat)
        c_diff = np.nanmax(np.abs(state.displacement - fast) / [1e-6, 1e-6, 1e-6, 1e-3, 1e-3])
        frac = rate / (n_rest / t_comp)
        print(f"  compiled limit (numba) {n_rest / t_comp:10.4g} cases/s, {int(np.isnan(fast[:, 0]).sum())} failed; "
              f"numpy path = {frac:.3g} of it; max difference {c_diff:.2e} (um / mrad)")
        extra = f" compiled_cases_per_s={n_rest / t_comp:.4g} numpy_over_compiled={frac:.3g}"
        diff = max(diff, c_diff)
    w = 12000 * RPM
    sl = cases(n_speed, [4e3, 4e3, 4e3, 80.0, 80.0], seed=1)
    sl[:, 2] = np.abs(sl[:, 2]) + 5e3  # an angular-contact bearing at speed needs its thrust
    t_sb, s_state = best_of(lambda: batched(B218, sl, w), repeat)
    t_sbase, s_ref = best_of(baseline_speed(B218, sl[:n_speed_base], w), repeat)
    s_diff = np.nanmax(np.abs(s_state.displacement[:n_speed_base] - s_ref) / [1e-6, 1e-6, 1e-6, 1e-3, 1e-3])
    s_rate, s_base = n_speed / t_sb, n_speed_base / t_sbase
    s_eval = evaluation_cost(B218, s_state, w)
    print(f"speed: {n_speed} cases at 12 000 rpm, {int((~s_state.converged).sum())} failed, iterations mean "
          f"{s_state.iterations.mean():.2f}; batched {s_rate:.4g} cases/s, per-case library calls {s_base:.4g} "
          f"cases/s: ratio {s_rate / s_base:.4g}; max difference {s_diff:.2e}; solve = {t_sb / s_eval:.1f} x "
          "one batched evaluation")
    print(f"RESULT combined_rest cases_per_s={rate:.4g} baseline_cases_per_s={base_rate:.4g} "
          f"ratio={rate / base_rate:.4g} solve_over_residual_eval={t_batch / t_eval:.3g} "
          f"baseline_label=fair_scalar_Newton_(math){extra}")
    print(f"RESULT combined_speed cases_per_s={s_rate:.4g} baseline_cases_per_s={s_base:.4g} "
          f"ratio={s_rate / s_base:.4g} solve_over_residual_eval={t_sb / s_eval:.3g} "
          "baseline_label=per-case_library_calls_(not_a_fair_scalar_baseline)")
    ok = state.converged.all() and s_state.converged.all() and diff < 1e-6 and s_diff < 1e-6
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())

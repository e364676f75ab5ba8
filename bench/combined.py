"""Benchmark (issue 11): combined-load distribution, batched vs a per-case scalar Newton, at rest and at speed.

At rest: 10 000 random combined load cases (F_x, F_y, F_z, M_x, M_y) on the MASTA deep-groove bearing of
tests/validation (Z = 7, 10 um clearance), one call of ``quasistatic.combined.load_distribution``.
Baseline: the same model and equations solved case by case as an engineer would write them in plain
Python (``math``, no numpy on scalars): Newton on the five ring unknowns with the analytic Jacobian
(sum over balls of J^T H J), a 5 x 5 Gaussian elimination, step halving on the residual norm, the same
start (the library's start formula, computed outside the baseline's timing, which favours it), the same
tolerance and the same Hertz interpolants (Chebyshev series in cos alpha, evaluated by Clenshaw in
Python). Best of k runs for both paths; the answers are compared case by case.

At speed: 2000 combined cases on the 218 bearing at 12 000 rpm, batched, against the fair scalar baseline
at speed (bench/_kernels_combined.py ``speed_solver``): the same model written for one case in plain
Python (the rest solve above, then every ball's equilibrium eqs. (5)-(6) by a 2 x 2 Newton with its
analytic Jacobian, the ring stiffness per ball as the Schur complement, the same Levenberg-Marquardt ring
Newton, the same continuation in omega^2, tolerances and starts). It is a stronger baseline than a
per-case ``scipy.optimize.root`` (which would add a finite-difference or Python-callback Jacobian). For
reference only, the former baseline, labelled as what it is: the library called one case at a time.

The compiled limit: the same per-case algorithms compiled by numba, parallel over cases, at rest and at
speed (skipped when numba is missing; the starts are computed inside its timing, as for the batched
path).

Also printed (issue 11 item 8: at most 20): the whole batched solve in units of one batched
residual-plus-Jacobian evaluation of all cases at the solution, ``quasistatic.combined._evaluate``, the
very function the ring Newton calls for every trial (ball loads, reaction and the analytic 5 x 5
stiffness). Solve and evaluation are timed alternately, best of each, so that both see the same machine;
the load average is printed with them.
"""

from __future__ import annotations

import os
import sys
import time

import _kernels
import _kernels_combined
import numpy as np
from _timing import best_of

from bearinglab import catalog
from bearinglab.bearing import BallBearing, Material
from bearinglab.quasistatic import combined
from bearinglab.units import RPM

N_REST, N_BASE = 10_000, 1000
N_SPEED, N_SPEED_BASE, N_SPEED_FORMER = 2000, 50, 20
SCALE_REST, SCALE_SPEED = [1500, 1500, 1500, 15.0, 15.0], [4e3, 4e3, 4e3, 80.0, 80.0]
SPEED = 12000 * RPM
UM_MRAD = np.array([1e-6, 1e-6, 1e-6, 1e-3, 1e-3])  # differences in um and mrad
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


def baseline(bearing, loads):
    """Per-case scalar solves; starts computed outside the timed loop."""
    geo = combined._geometry(*combined._bearing_args(bearing), 0.0, "operating", "outer", "radial")
    solve = _kernels_combined.rest_solver(geo, tol=combined.TOL, max_iter=combined.MAX_ITER)
    starts = combined._start(geo, np.asarray(loads, dtype=float)).tolist()
    rows = np.asarray(loads, dtype=float).tolist()

    def run():
        return np.array([solve(f, s)[0] for f, s in zip(rows, starts, strict=True)])

    return run


def compiled(bearing, loads):
    """The compiled limit at rest: the same per-case algorithm as ``baseline``, numba over cases.

    The starts (the library's start formula, numpy) are computed inside, as in the batched path.
    """
    geo = combined._geometry(*combined._bearing_args(bearing), 0.0, "operating", "outer", "radial")
    loads = np.asarray(loads, dtype=float)
    u, it = _kernels_combined.compiled(geo, loads, combined._start(geo, loads), tol=combined.TOL,
                                       max_iter=combined.MAX_ITER)
    return u, it


def _speed_limits():
    return {"tol": combined.TOL, "max_iter": combined.MAX_ITER, "lam_max": combined._LAM_MAX,
            "ball_tol": combined._BALL_TOL, "ball_max_iter": combined._BALL_MAX_ITER,
            "continuation": combined._CONTINUATION}


def speed_cases(n, seed=1):
    """Random combined loads at speed; an angular-contact bearing at speed needs its thrust."""
    loads = cases(n, SCALE_SPEED, seed=seed)
    loads[:, 2] = np.abs(loads[:, 2]) + 5e3
    return loads


def baseline_speed(bearing, loads, speed):
    """The fair scalar baseline at speed, one plain-Python solve per case; starts outside the timed loop."""
    geo = combined._geometry(*combined._bearing_args(bearing), 0.0, "operating", "outer", "radial")
    solve = _kernels_combined.speed_solver(geo, **_speed_limits())
    loads = np.asarray(loads, dtype=float)
    starts, rows = combined._start(geo, loads).tolist(), loads.tolist()

    def run():
        return np.array([solve(f, s, speed**2)[0] for f, s in zip(rows, starts, strict=True)])

    return run


def compiled_speed(bearing, loads, speed):
    """The compiled limit at speed (numba over cases); the starts are computed inside."""
    geo = combined._geometry(*combined._bearing_args(bearing), 0.0, "operating", "outer", "radial")
    loads = np.asarray(loads, dtype=float)
    return _kernels_combined.compiled_speed(geo, loads, combined._start(geo, loads), np.full(len(loads), speed**2),
                                            **_speed_limits())


def library_speed(bearing, loads, speed):
    """The former baseline at speed (reference only): the library called one case at a time."""
    def run():  # numpy on one case at a time
        return np.array([combined.combined_analysis(bearing, f, speed).displacement for f in loads])

    return run


def evaluation_cost(bearing, state, speed):
    """Best of 5 wall times [s] of one batched residual-plus-Jacobian evaluation at the solution."""
    geo = combined._geometry(*combined._bearing_args(bearing), 0.0, "operating", "outer", "radial")
    u = np.asarray(state.displacement).reshape(-1, 5)
    w2 = np.full(len(u), speed**2)
    return best_of(lambda: combined._evaluate(geo, u, w2), 5)[0]


def solve_and_evaluation(bearing, loads, speed, repeat):
    """Best wall times [s] of the batched solve and of one evaluation (:func:`evaluation_cost`), timed in
    turns (a solve, then the evaluations) so that a machine that gets busier or quieter affects both; and
    the solved state."""
    solves, evals, state = [], [], None
    for _ in range(repeat):
        start = time.perf_counter()
        state = batched(bearing, loads, speed)
        solves.append(time.perf_counter() - start)
        evals.append(evaluation_cost(bearing, state, speed))
    return min(solves), min(evals), state


def measure_rest(n_rest=N_REST, n_base=N_BASE, repeat=3):
    """Timings [s], rates [cases/s] and largest differences (um, mrad) at rest."""
    loads = cases(n_rest, SCALE_REST)
    t_batch, t_eval, state = solve_and_evaluation(DEEP, loads, 0.0, repeat)
    t_base, ref = best_of(baseline(DEEP, loads[:n_base]), repeat)
    m = {"n": n_rest, "rate": n_rest / t_batch, "base_rate": n_base / t_base, "state": state,
         "failed_base": int(np.isnan(ref[:, 0]).sum()), "solve_over_eval": t_batch / t_eval,
         "diff": float(np.nanmax(np.abs(state.displacement[:n_base] - ref) / UM_MRAD))}
    if _kernels.available():
        compiled(DEEP, loads[:4])  # compile outside the clock
        t_comp, (fast, _it) = best_of(lambda: compiled(DEEP, loads), repeat)
        m["compiled_rate"] = n_rest / t_comp
        m["diff_compiled"] = float(np.nanmax(np.abs(state.displacement - fast) / UM_MRAD))
    return m


def measure_speed(n_speed=N_SPEED, n_base=N_SPEED_BASE, n_former=N_SPEED_FORMER, repeat=3):
    """The same at speed (12 000 rpm, the 218 bearing), with the former baseline for reference."""
    loads = speed_cases(n_speed)
    t_batch, t_eval, state = solve_and_evaluation(B218, loads, SPEED, repeat)
    t_base, ref = best_of(baseline_speed(B218, loads[:n_base], SPEED), repeat)
    t_old, old = best_of(library_speed(B218, loads[:n_former], SPEED), repeat)
    m = {"n": n_speed, "rate": n_speed / t_batch, "base_rate": n_base / t_base, "former_rate": n_former / t_old,
         "state": state, "failed_base": int(np.isnan(ref[:, 0]).sum()),
         "solve_over_eval": t_batch / t_eval,
         "diff": float(np.nanmax(np.abs(state.displacement[:n_base] - ref) / UM_MRAD)),
         "diff_former": float(np.nanmax(np.abs(state.displacement[:n_former] - old) / UM_MRAD))}
    if _kernels.available():
        compiled_speed(B218, loads[:2], SPEED)  # compile outside the clock
        t_comp, (fast, _it) = best_of(lambda: compiled_speed(B218, loads, SPEED), repeat)
        m["compiled_rate"] = n_speed / t_comp
        m["diff_compiled"] = float(np.nanmax(np.abs(state.displacement - fast) / UM_MRAD))
    return m


def _report(name, m):
    """Print one model's lines and its RESULT line; True if every path agrees and converged."""
    state, rate, base = m["state"], m["rate"], m["base_rate"]
    print(f"{name}: {m['n']} cases, {int((~state.converged).sum())} failed, ring iterations mean "
          f"{state.iterations.mean():.2f} max {state.iterations.max()}")
    print(f"  batched numpy          {rate:10.4g} cases/s; solve = {m['solve_over_eval']:.1f} x one batched evaluation "
          f"(residual + Jacobian, combined._evaluate; load average {os.getloadavg()[0]:.2f})")
    print(f"  fair scalar baseline   {base:10.4g} cases/s ({m['failed_base']} failed): ratio {rate / base:.4g}; "
          f"max difference {m['diff']:.2e} (um / mrad)")
    ok = state.converged.all() and m["failed_base"] == 0 and m["diff"] < 1e-6
    extra = ""
    if "former_rate" in m:
        print(f"  library per case (former, reference only) {m['former_rate']:10.4g} cases/s: ratio "
              f"{rate / m['former_rate']:.4g}; max difference {m['diff_former']:.2e}")
        extra += f" former_library_per_case_ratio={rate / m['former_rate']:.4g}"
        ok = ok and m["diff_former"] < 1e-6
    if "compiled_rate" in m:
        frac = rate / m["compiled_rate"]
        print(f"  compiled limit (numba) {m['compiled_rate']:10.4g} cases/s; numpy path = {frac:.3g} of it; "
              f"max difference {m['diff_compiled']:.2e} (um / mrad)")
        extra += f" compiled_cases_per_s={m['compiled_rate']:.4g} numpy_over_compiled={frac:.3g}"
        ok = ok and m["diff_compiled"] < 1e-9
    print(f"RESULT {name} cases_per_s={rate:.4g} baseline_cases_per_s={base:.4g} ratio={rate / base:.4g} "
          f"solve_over_residual_eval={m['solve_over_eval']:.3g} baseline_label=fair_scalar_Newton_(math){extra}")
    return ok


def main(n_rest=N_REST, n_base=N_BASE, n_speed=N_SPEED, n_speed_base=N_SPEED_BASE, n_speed_former=N_SPEED_FORMER,
         repeat=3):
    ok = _report("combined_rest", measure_rest(n_rest, n_base, repeat))
    ok = _report("combined_speed", measure_speed(n_speed, n_speed_base, n_speed_former, repeat)) and ok
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())

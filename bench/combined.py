"""Benchmark (issues 11 and 31): the 5-DOF combined-load solve, at rest and at speed, against a per-case scalar
baseline of the same algorithm.

At rest: 10 000 random combined load cases (F_x, F_y, F_z, M_x, M_y) on the MASTA deep-groove bearing of
tests/validation (Z = 7, 10 um clearance), one call of ``quasistatic.combined.load_distribution``.
At speed: 2000 combined cases on the 218 bearing at 12 000 rpm (the thrust made positive: an angular-contact
bearing at speed needs it).

Paths, each timed as the best of k runs, in the same run:

- shipped: ``engine="auto"``, the compiled kernel (``quasistatic._combined_kernel``) parallel over the
  cases on every core when numba is installed;
- numpy: ``engine="numpy"``, the batched path (the 3x rule of issue 14: the kernel ships where it is more
  than 3x faster than numpy); its solve is also given in units of one batched residual-plus-Jacobian
  evaluation at the solution (``combined._evaluate``, issue 11 item 8), the two timed in turns;
- fair scalar baseline (BENCHMARKS.md): the kernel's per-case functions run by CPython
  (``_combined_kernel.plain()``): the same algorithm as both paths (the rest Newton with the analytic
  stiffness, Levenberg-Marquardt damping, trust region and line search; at speed every ball solved at the
  rest rings, then the block Newton on ring and balls with the Schur complement per ball, the same
  continuation), the same start (computed outside its timing, which favours it), tolerances and Hertz
  interpolants, in plain Python with ``math``; stronger than a per-case ``scipy.optimize.root``. The
  answers are compared case by case.

The goals of issue 31 (>= 1e5 cases/s at rest, >= 1e4 at speed, on the project machine's two cores) are
printed with the load average of the run, and the CPU time per case of the shipped path (what the code
costs when the wall time shows what it got on a shared machine).
"""

from __future__ import annotations

import os
import sys
import time

import numpy as np
from _timing import best_of, best_of_wall_and_cpu

from bearinglab import catalog
from bearinglab.bearing import BallBearing, Material
from bearinglab.quasistatic import _combined_kernel, combined
from bearinglab.units import RPM

N_REST, N_BASE = 10_000, 500
N_SPEED, N_SPEED_BASE = 2000, 20
SCALE_REST, SCALE_SPEED = [1500, 1500, 1500, 15.0, 15.0], [4e3, 4e3, 4e3, 80.0, 80.0]
SPEED = 12000 * RPM
GOALS = {"combined_rest": 1e5, "combined_speed": 1e4}  # issue 31, cases/s on the project machine's 2 cores
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


def speed_cases(n, seed=1):
    """Random combined loads at speed; an angular-contact bearing at speed needs its thrust."""
    loads = cases(n, SCALE_SPEED, seed=seed)
    loads[:, 2] = np.abs(loads[:, 2]) + 5e3
    return loads


def batched(bearing, loads, speed=0.0, engine="auto"):
    return combined.combined_analysis(bearing, loads, speed, on_failure="flag", engine=engine)


def _geometry(bearing):
    return combined._geometry(*combined._bearing_args(bearing), 0.0, "operating", "outer", bearing.type)


def baseline(bearing, loads, speed=0.0):
    """The fair scalar baseline: the kernel's per-case solve in plain Python, one case after the other.

    Returns ``run() -> displacements (n, 5)`` (NaN where a case failed); starts computed outside.
    """
    geo = _geometry(bearing)
    solve_case, _react, _work = _combined_kernel.plain()
    par, ser = combined._kernel_parameters(geo, combined.TOL, combined.MAX_ITER)
    loads = np.asarray(loads, dtype=float)
    starts = combined._start(geo, loads)
    cs, sn, w2 = [float(x) for x in geo.cos_psi], [float(x) for x in geo.sin_psi], float(speed) ** 2
    par_l, ser_l = par.tolist(), ser.tolist()
    rows, starts = loads.tolist(), starts.tolist()
    z = geo.z

    def run():
        out = []
        for f, s in zip(rows, starts, strict=True):
            u, res, stiff, force = [0.0] * 5, [[0.0] * z for _ in range(8)], [0.0] * 25, [0.0] * 5
            w = [[0.0] * max(z, 70) for _ in range(15)]
            ok, _it, _r, _fl = solve_case(f, s, [1.0] * 5, w2, par_l, cs, sn, ser_l, u, res, stiff, force, w,
                                          [[0.0] * z for _ in range(10)], [[0.0] * z for _ in range(12)])
            out.append(u if ok else [np.nan] * 5)
        return np.array(out)

    return run


def evaluation_cost(bearing, state, speed):
    """Best of 5 wall times [s] of one batched residual-plus-Jacobian evaluation at the solution (numpy)."""
    geo = _geometry(bearing)
    u = np.asarray(state.displacement).reshape(-1, 5)
    w2 = np.full(len(u), speed**2)
    return best_of(lambda: combined._evaluate(geo, u, w2), 5)[0]


def numpy_and_evaluation(bearing, loads, speed, repeat):
    """Best wall times [s] of the numpy solve and of one evaluation, timed in turns; the CPU time [s] of the
    best solve; and the state."""
    solves, evals, state = [], [], None
    for _ in range(repeat):
        start, cpu = time.perf_counter(), time.process_time()
        state = batched(bearing, loads, speed, engine="numpy")
        solves.append((time.perf_counter() - start, time.process_time() - cpu))
        evals.append(evaluation_cost(bearing, state, speed))
    wall, cpu = min(solves)
    return wall, min(evals), cpu, state


def measure(name, bearing, loads, speed, n_base, repeat=3):
    """Rates [cases/s], the load average, and the largest differences between the paths (um, mrad)."""
    n = len(loads)
    batched(bearing, loads[:4], speed)  # load the compiled kernel outside the clock
    load_before = os.getloadavg()[0]
    t_ship, cpu_ship, state = best_of_wall_and_cpu(lambda: batched(bearing, loads, speed), repeat)
    t_numpy, t_eval, cpu_numpy, slow = numpy_and_evaluation(bearing, loads, speed, repeat)
    t_base, ref = best_of(baseline(bearing, loads[:n_base], speed), repeat)
    load = max(load_before, os.getloadavg()[0])
    ok = state.converged
    return {"name": name, "n": n, "state": state, "rate": n / t_ship, "cpu_us": cpu_ship / n * 1e6,
            "numpy_cpu_us": cpu_numpy / n * 1e6,
            "numpy_rate": n / t_numpy, "solve_over_eval": t_numpy / t_eval, "base_rate": n_base / t_base,
            "load": load, "failed_base": int(np.isnan(ref[:, 0]).sum()),
            "diff": float(np.nanmax(np.abs(state.displacement[:n_base] - ref) / UM_MRAD)),
            "diff_numpy": float(np.nanmax(np.abs(state.displacement[ok] - slow.displacement[ok]) / UM_MRAD)),
            "numpy_failed": int((~slow.converged).sum()),
            "engine": "compiled" if _combined_kernel.available() else "numpy"}


def measure_rest(n_rest=N_REST, n_base=N_BASE, repeat=3):
    return measure("combined_rest", DEEP, cases(n_rest, SCALE_REST), 0.0, n_base, repeat)


def measure_speed(n_speed=N_SPEED, n_base=N_SPEED_BASE, repeat=3):
    return measure("combined_speed", B218, speed_cases(n_speed), SPEED, n_base, repeat)


def _report(m):
    """Print one model's lines and its RESULT line; True if every path agrees and converged."""
    state, rate, base, name = m["state"], m["rate"], m["base_rate"], m["name"]
    goal = GOALS[name]
    print(f"{name}: {m['n']} cases, {int((~state.converged).sum())} failed, ring iterations mean "
          f"{state.iterations.mean():.2f} max {state.iterations.max()}; load average {m['load']:.2f}")
    print(f"  shipped ({m['engine']})     {rate:10.4g} cases/s ({m['cpu_us']:.1f} us of CPU a case); goal {goal:.0e}: "
          f"{'met' if rate >= goal else 'not met'}")
    print(f"  numpy                  {m['numpy_rate']:10.4g} cases/s ({m['numpy_cpu_us']:.1f} us of CPU a case): shipped "
          f"/ numpy = {rate / m['numpy_rate']:.3g}, in CPU a case {m['numpy_cpu_us'] / m['cpu_us']:.3g}; "
          f"solve = {m['solve_over_eval']:.1f} x one batched evaluation; max difference {m['diff_numpy']:.2e} "
          "(um / mrad)")
    print(f"  fair scalar baseline   {base:10.4g} cases/s ({m['failed_base']} failed): ratio {rate / base:.4g}; "
          f"max difference {m['diff']:.2e} (um / mrad)")
    ok = (state.converged.all() and m["failed_base"] == 0 and m["numpy_failed"] == 0 and m["diff"] < 1e-6
          and m["diff_numpy"] < 1e-6)
    print(f"RESULT {name} cases_per_s={rate:.4g} baseline_cases_per_s={base:.4g} ratio={rate / base:.4g} "
          f"batched_label=shipped_({m['engine']}) baseline_label=fair_scalar_Newton_(math) goal_cases_per_s={goal:.0e} "
          f"goal_met={'yes' if rate >= goal else 'no'} load_average={m['load']:.2f} cpu_us_per_case={m['cpu_us']:.3g} "
          f"numpy_cases_per_s={m['numpy_rate']:.4g} numpy_over_compiled={m['numpy_rate'] / rate:.3g} "
          f"numpy_cpu_us_per_case={m['numpy_cpu_us']:.3g} "
          f"solve_over_residual_eval={m['solve_over_eval']:.3g} mean_iterations={state.iterations.mean():.3g}")
    return ok


def main(n_rest=N_REST, n_base=N_BASE, n_speed=N_SPEED, n_speed_base=N_SPEED_BASE, repeat=3):
    ok = _report(measure_rest(n_rest, n_base, repeat))
    ok = _report(measure_speed(n_speed, n_speed_base, repeat)) and ok
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())

"""Benchmark (issue 33): 1000 load cases of a spindle on three bearings, one batch against a per-case baseline.

The spindle: a hollow shaft of four sections on 31 Timoshenko elements, a DB pair of 7014 C at the front
(500 N of preload), a 6012 floating at the rear, a random load at the nose (F_x, F_y in +-2 kN, F_z in
+-1 kN), at rest. Batched: ``bearinglab.shaft.solve`` with all 1000 cases in one call (the shaft
assembled and condensed once, outside the timing; every bearing of every case in one call of
``bearinglab.reactions.bearing_reactions`` per Newton trial). Baseline (BENCHMARKS.md rules): the same
algorithm one case at a time in plain Python (bench/_kernels_shaft.py): the same condensed shaft, the same
ball-by-ball bearing evaluation as the 5-DOF model's fair baseline, the same damped Newton, trust region,
line search and tolerance, the shaft's other nodes recovered; best of k runs for both; the two answers
compared case by case (every node's displacement to 1e-9 of the largest).

Goal of the issue: >= 1000 system solves/s on 2 cores and >= 30x the baseline.
"""

from __future__ import annotations

import os
import sys
import time

import _kernels_shaft
import numpy as np
from _timing import best_of

from bearinglab import catalog, shaft

N, N_BASE = 1000, 40


def spindle():
    front, rear = catalog.get("7014 C"), catalog.get("6012")
    secs = (shaft.Section(0.06, 0.07, 0.03), shaft.Section(0.09, 0.07, 0.03), shaft.Section(0.2, 0.065, 0.03),
            shaft.Section(0.05, 0.06, 0.03))
    sup = (shaft.BearingSetSupport("front", 0.1, (front,), "DB", preload=500.0),
           shaft.BearingSupport("rear", 0.375, rear))
    return shaft.ShaftSystem(shaft.Shaft(secs), sup, loads=(shaft.PointLoad(0.0, fx=1.0, name="nose"),), elements=28)


def cases(system, n, seed=0):
    rng = np.random.default_rng(seed)
    loads = np.zeros((n, 1, 6))
    loads[:, 0, 0] = rng.uniform(-2000.0, 2000.0, n)
    loads[:, 0, 1] = rng.uniform(-2000.0, 2000.0, n)
    loads[:, 0, 2] = rng.uniform(-1000.0, 1000.0, n)
    return shaft.load_cases(system, point_loads=loads)


def measure(n=N, n_base=N_BASE, repeat=3):
    system = spindle()
    asm = shaft.assemble(system)
    c = cases(system, n)
    t_batch, state = best_of(lambda: shaft.solve(system, c, assembly=asm, on_failure="flag"), repeat)
    f = shaft.mesh.load_vectors(system, asm.mesh, c.speed[:n_base], c.factor[:n_base], c.point_loads[:n_base])
    rows = f.tolist()
    solve_one = _kernels_shaft.case_solver(asm)
    t_base, base = best_of(lambda: [solve_one(r) for r in rows], repeat)
    u_batch = state.displacement[:n_base].reshape(n_base, -1)
    u_base = np.array([b[2] for b in base])
    diff = float(np.max(np.abs(u_base - u_batch)) / np.max(np.abs(u_batch)))
    return {"n": n, "elements": len(asm.mesh.z) - 1, "bearings": len(asm.rows), "t_batch": t_batch,
            "t_base": t_base, "n_base": n_base, "converged": bool(state.converged.all()),
            "base_converged": all(b[0] is not None for b in base), "diff": diff,
            "iterations": float(state.iterations.mean()),
            "base_iterations": float(np.mean([b[1] for b in base]))}


def main():
    m = measure()
    rate, base_rate = m["n"] / m["t_batch"], m["n_base"] / m["t_base"]
    load = os.getloadavg()[0] if hasattr(os, "getloadavg") else float("nan")
    print(f"spindle: {m['elements']} elements, {m['bearings']} bearings, {m['n']} cases at rest (load average "
          f"{load:.2f}, {time.strftime('%Y-%m-%d %H:%M:%S')})")
    print(f"batched   : {m['t_batch']:.3f} s = {rate:.0f} solves/s, {m['iterations']:.2f} Newton iterations per case")
    print(f"per case  : {m['t_base'] / m['n_base'] * 1e3:.2f} ms per case = {base_rate:.1f} solves/s (plain Python, "
          f"{m['base_iterations']:.2f} iterations per case)")
    print(f"agreement : every node's displacement within {m['diff']:.1e} of the largest")
    ok = m["converged"] and m["base_converged"] and m["diff"] < 1e-9
    if not ok:
        print("FAILED: the paths disagree or a case did not converge", file=sys.stderr)
        return 1
    print(f"RESULT shaft cases_per_s={rate:.0f} baseline_cases_per_s={base_rate:.1f} ratio={rate / base_rate:.0f} "
          f"elements={m['elements']} bearings={m['bearings']} goal_cases_per_s=1000 goal_ratio=30")
    return 0


if __name__ == "__main__":
    sys.exit(main())

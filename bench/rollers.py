"""Benchmark: the roller load distribution of 10 000 cases, 30 slices per roller, batched vs per case.

The batched path is :func:`bearinglab.rollers.distribution.load_distribution` on an NU 208-type bearing
(Z = 14, D_we = 11 mm, L_we = 9.6 mm, D_pw = 60.5 mm, ISO/TS 16281's logarithmic profile, 20 um diametral
clearance, 30 slices) for 10 000 random combined loads (F_x, F_y, M_x, M_y; the axial freedom of a
cylindrical bearing held). The baseline is the same solver as an engineer would write it for one case, in
plain Python and ``math`` (``bench/_kernels_rollers.py``): the same start, the same Levenberg-Marquardt
steps with the same damping rules, trust region and line search, the same analytic stiffness and the same
tolerance, a 5 x 5 Gaussian elimination by hand. Both are timed best-of-k; every baseline case is compared
with the batched answer (displacements to 1e-9 relative of the largest) and the script fails if one differs.
"""

from __future__ import annotations

import sys

import numpy as np
from _kernels_rollers import solve_one
from _timing import best_of

from bearinglab.rollers import distribution, geometry

N_BATCH = 10_000
N_BASELINE = 300
GOAL_RATIO, GOAL_RATE = 30.0, 2000.0  # issue 32


def roller_set():
    s = geometry.slice_positions(9.6e-3, 30)
    return distribution.roller_set(14, 11e-3, 9.6e-3, 60.5e-3, normal_gap=10e-6,
                                   drop=geometry.logarithmic_drop(s, 9.6e-3, 11e-3))


def cases(n, seed=0):
    rng = np.random.default_rng(seed)
    loads = np.zeros((n, 5))
    phi = rng.uniform(0.0, 2 * np.pi, n)
    fr = rng.uniform(500.0, 30e3, n)
    loads[:, 0], loads[:, 1] = fr * np.cos(phi), fr * np.sin(phi)
    loads[:, 3:5] = rng.uniform(-40.0, 40.0, (n, 2)) * (rng.random((n, 1)) < 0.5)  # half the cases tilted
    return loads


def batched(rs, loads):
    return distribution.load_distribution(loads, rs).displacement


def baseline(rs, loads):
    return np.array([solve_one(rs, f) for f in loads])


def measure(n_batch=N_BATCH, n_baseline=N_BASELINE, repeat=3):
    rs = roller_set()
    loads = cases(n_batch)
    t_batch, u = best_of(lambda: batched(rs, loads), repeat)
    t_base, u_base = best_of(lambda: baseline(rs, loads[:n_baseline]), max(1, repeat - 1))
    scale = np.abs(u[:n_baseline]).max(axis=0)
    diff = float(np.max(np.abs(u_base - u[:n_baseline]) / np.where(scale > 0, scale, 1.0)))
    return {"rate": n_batch / t_batch, "base_rate": n_baseline / t_base, "diff": diff, "t_batch": t_batch}


def main():
    m = measure()
    ratio = m["rate"] / m["base_rate"]
    print(f"batched: {m['rate']:.0f} cases/s ({N_BATCH} cases in {m['t_batch']:.3f} s); per-case plain Python: "
          f"{m['base_rate']:.1f} cases/s; ratio {ratio:.1f}x; max difference {m['diff']:.2e} (relative)")
    if m["diff"] > 1e-9:
        print("the two paths disagree", file=sys.stderr)
        return 1
    print(f"goal: >= {GOAL_RATIO:g}x and >= {GOAL_RATE:g} cases/s: "
          f"{'met' if ratio >= GOAL_RATIO and m['rate'] >= GOAL_RATE else 'not met'}")
    print(f"RESULT rollers cases_per_s={m['rate']:.0f} baseline_cases_per_s={m['base_rate']:.1f} ratio={ratio:.1f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())

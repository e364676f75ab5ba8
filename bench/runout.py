"""Benchmark: the contact problem (6.1) of spec 003, batched exact dual solver vs per-case linprog.

Solves 10^5 positions of a 16-ball bearing (the reference geometry, random ball-set rotation and random
generalized errors of a few tenths of a micrometre, every tenth case rounded to 0.1 um to create ties)
with :func:`bearinglab.runout.solve_contact` (the dual walk, tie-break, contact set and load shares
included; the shipped engine, "auto": compiled where numba is installed, and the numpy engine) and, in the
same run, a sample of the same cases one by one with ``scipy.optimize.linprog`` (HiGHS, stage 1 only:
maximise a0; the tie-break of section 7.5 would add four more LPs per case, so the baseline is favourable
to the LP). Prints solves/s, the ratio, the largest difference in a0 between the paths and the load
average.
"""

from __future__ import annotations

import os
import sys

import numpy as np
from _timing import best_of
from scipy.optimize import linprog

from bearinglab import runout

N_BATCH = 100_000
N_BASELINE = 1_000
UM = 1e-6


def cases(n, n_balls=16, seed=0):
    """(generalized errors [m], ball azimuths [rad]) of n positions."""
    rng = np.random.default_rng(seed)
    theta = rng.uniform(0, 2 * np.pi, n)[:, None] + 2 * np.pi * np.arange(n_balls) / n_balls
    dk = rng.normal(0.0, 0.3, (n, n_balls))
    dk[::10] = np.round(dk[::10], 1)  # ties: degenerate faces and several optimal vertices
    return dk * UM, theta


def solve_batch(dk, theta, engine="auto"):
    """The batched path: all positions in one call."""
    return runout.solve_contact(dk, theta, engine=engine)


def solve_one_by_one(dk, theta):
    """The baseline: stage 1 of section 8.1 with scipy's LP solver, per position; returns a0 [m]."""
    out = np.empty(dk.shape[0])
    for p in range(dk.shape[0]):
        rows = np.column_stack([np.ones(dk.shape[1]), np.sin(theta[p]), np.cos(theta[p])])
        res = linprog(
            [-1.0, 0.0, 0.0], A_ub=rows, b_ub=dk[p] / UM, bounds=[(None, None)] * 3, method="highs"
        )
        if res.status != 0:
            raise RuntimeError(res.message)
        out[p] = res.x[0] * UM
    return out



def main():
    dk, theta = cases(N_BATCH)
    for engine in ("auto", "numpy"):
        solve_batch(dk[:100], theta[:100], engine)  # warm-up (imports, the compiled kernel's load)
    load = os.getloadavg()[0]
    t_batch, sol = best_of(lambda: solve_batch(dk, theta), 3)
    t_numpy, sol_np = best_of(lambda: solve_batch(dk, theta, "numpy"), 3)
    t_base, a0_lp = best_of(lambda: solve_one_by_one(dk[:N_BASELINE], theta[:N_BASELINE]), 3)
    rate, base_rate, numpy_rate = N_BATCH / t_batch, N_BASELINE / t_base, N_BATCH / t_numpy
    diff = np.max(np.abs(sol.constant[:N_BASELINE] - a0_lp)) / UM
    engines = np.max(np.abs(sol.constant - sol_np.constant)) / UM
    print(
        f"batched dual solver : {N_BATCH:>7d} positions (n = 16) in {t_batch:7.3f} s = {rate:10.4g} solves/s"
    )
    print(
        f"numpy engine        : {N_BATCH:>7d} positions          in {t_numpy:7.3f} s = {numpy_rate:10.4g} solves/s"
    )
    print(
        f"per-case linprog    : {N_BASELINE:>7d} positions          in {t_base:7.3f} s = {base_rate:10.4g} solves/s"
    )
    print(
        f"degenerate positions: {100 * np.mean(sol.degenerate):.1f} %;  max |a0_dual - a0_linprog| = {diff:.2e} um; "
        f"between the engines {engines:.2e} um; load average (1 min) {load:.2f} at the start, "
        f"{os.getloadavg()[0]:.2f} at the end"
    )
    print(
        f"RESULT runout cases_per_s={rate:.4g} baseline_cases_per_s={base_rate:.4g} ratio={rate / base_rate:.4g} "
        f"numpy_cases_per_s={numpy_rate:.4g} load_avg_1min={load:.2f}"
    )
    return 0 if diff < 1e-6 and engines < 1e-12 else 1


if __name__ == "__main__":
    sys.exit(main())

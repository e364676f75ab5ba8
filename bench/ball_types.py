"""Benchmark (issue 30 item 4): the 5-DOF model of the other ball-bearing types, batched against case by case.

Four-point (at rest: each ball solved between its four contacts inside every evaluation), double-row
angular, self-aligning (at rest and at 12 000 rpm) and thrust bearings, 2000 random combined cases each
(the loads a type cannot carry left out: a self-aligning bearing's moments, a thrust bearing's radial
loads), solved in one call of ``quasistatic.combined.combined_analysis`` (the batched numpy path: these
types are not in the compiled kernel).

Baseline, labelled as what it is (BENCHMARKS.md): the same library call case by case (one case an
array), the same algorithm, start and tolerance; not a plain-Python scalar solver, so the ratio is the
gain of the batch over numpy called per case. Each case's answer is the same bits either way (the model
computes a case from its own row), which the script checks. Timing: the best of 3 runs of each path.
"""

from __future__ import annotations

import math
import os
import sys

import numpy as np
from _timing import best_of

from bearinglab.bearing import BallBearing, Material
from bearinglab.quasistatic import combined
from bearinglab.units import RPM

N, N_BASE = 2000, 100
STEEL = Material("steel", 210e9, 0.3, 7850.0)
BASE = {"n_balls": 12, "ball_diameter": 12.7e-3, "pitch_diameter": 60e-3, "inner_conformity": 0.52,
        "outer_conformity": 0.53, "ball_material": STEEL, "ring_material": STEEL}
BEARINGS = {
    "four-point": BallBearing(**BASE, type="four-point", contact_angle=math.radians(35), radial_clearance=30e-6),
    "double-row-angular": BallBearing(**BASE, type="double-row-angular", contact_angle=math.radians(30),
                                      radial_clearance=10e-6, row_distance=20e-3),
    "self-aligning": BallBearing(**{**BASE, "outer_conformity": None}, type="self-aligning",
                                 contact_angle=math.radians(10), radial_clearance=15e-6),
    "thrust": BallBearing(**{**BASE, "inner_conformity": 0.54, "outer_conformity": 0.54}, type="thrust",
                          contact_angle=math.pi / 2),
}
CASES = (("four-point", 0.0), ("double-row-angular", 0.0), ("double-row-angular", 12000 * RPM),
         ("self-aligning", 0.0), ("self-aligning", 12000 * RPM), ("thrust", 0.0))


def cases(kind, n, seed=0):
    """Random combined loads of the type (N, N m)."""
    rng = np.random.default_rng(seed)
    loads = rng.normal(size=(n, 5)) * np.array([2000.0, 2000.0, 2000.0, 20.0, 20.0])
    if kind == "self-aligning":
        loads[:, 3:] = 0.0
    if kind == "thrust":  # a thrust with its line of action within half the pitch radius
        loads[:, :2] = 0.0
        loads[:, 2] = np.abs(loads[:, 2]) + 500.0
        loads[:, 3:] = rng.uniform(-1, 1, size=(n, 2)) * loads[:, 2:3] * 0.25 * 30e-3 / math.sqrt(2)
    loads[:, 2] += np.where(loads[:, 2] >= 0, 300.0, -300.0)  # no case at the mechanism of a ring in its play
    return loads


def measure(kind, speed, n=N, n_base=N_BASE, repeat=3):
    """Rates [cases/s] of the batch and of the same calls case by case, and whether they agree bit for bit."""
    b = BEARINGS[kind]
    loads = cases(kind, n)
    t_batch, state = best_of(lambda: combined.combined_analysis(b, loads, speed, on_failure="flag"), repeat)

    def one_by_one():
        return [combined.combined_analysis(b, f, speed, on_failure="flag") for f in loads[:n_base]]

    t_base, singles = best_of(one_by_one, repeat)
    same = all(np.array_equal(s.displacement, state.displacement[k], equal_nan=True) for k, s in enumerate(singles))
    return {"kind": kind, "speed": speed, "n": n, "rate": n / t_batch, "base_rate": n_base / t_base,
            "failed": int((~state.converged).sum()), "same": same, "load": os.getloadavg()[0]}


def main():
    ok = True
    for kind, speed in CASES:
        m = measure(kind, speed)
        name = f"types_{kind.replace('-', '_')}_{'speed' if speed else 'rest'}"
        print(f"{name}: {m['n']} cases, {m['failed']} failed, batch {m['rate']:.4g} cases/s, case by case "
              f"{m['base_rate']:.4g} cases/s, the same bits: {m['same']}; load average {m['load']:.2f}")
        if not m["same"] or m["failed"]:
            ok = False
            continue
        print(f"RESULT {name} cases_per_s={m['rate']:.4g} baseline_cases_per_s={m['base_rate']:.4g} "
              f"ratio={m['rate'] / m['base_rate']:.3g} batched_label=numpy_batch "
              f"baseline_label=the_library_case_by_case load_average={m['load']:.2f}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())

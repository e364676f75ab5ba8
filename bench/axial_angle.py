"""Benchmark: operating contact angle under axial load (spec 000), the shipped solve vs a fair scalar solver.

Solves 10^6 loads on bearing 4-1006095 with :func:`bearinglab.stand.operating_contact_angle` as shipped
(``engine="auto"``: the compiled numba kernel for a batch this large when numba is installed, else numpy)
and, in the same run:

* the numpy path (``engine="numpy"``), the library's tested fallback;
* the fair scalar baseline: the same algorithm written as an engineer writes a one-case solver, plain
  Python and ``math`` (``_kernels.solve_one``): the same start (Halley on eq. (1) squared, in the gap
  cos alpha0 - cos alpha), the load test and Newton increment of section 6.3, the same tolerances, one case
  at a time;
* for reference only, the former baseline, labelled as what it is: ``scipy.optimize.brentq`` per case
  on the library's array function at a tighter tolerance (1e-14).

Every path is timed by the same rule (best of ``REPEAT`` runs) and compared case by case. The shipped and
numpy paths are also timed at ``N_SMALL`` cases, and their CPU time is reported next to the wall time (the
compiled kernel runs on every core, the numpy path on one; on a shared machine the CPU time per case is
the comparison that other work does not distort). The load average is printed with the figures.
"""

from __future__ import annotations

import math
import os
import sys

import _kernels
import numpy as np
from _timing import best_of, best_of_wall_and_cpu
from scipy.optimize import brentq

from bearinglab import _solve, catalog, stand, static
from bearinglab.units import KGF

N_BATCH = 1_000_000
N_SMALL = 100_000
N_BASELINE = 20_000
N_BRENTQ = 2_000
REPEAT = 3
TOL = (_solve.AXIAL_ANGLE_XTOL, _solve.AXIAL_ANGLE_FTOL_PERCENT, _solve.AXIAL_ANGLE_MAX_ITER)


def cases(n, seed=0):
    rng = np.random.default_rng(seed)
    return rng.uniform(0.05, 50.0, n) * KGF  # loads from 0.05 to 50 kgf


def batched(loads, cs, a0, engine="auto"):
    return stand.operating_contact_angle(loads, cs, a0, engine=engine)


def baseline(loads, cs, a0):
    """The fair scalar baseline: one plain-Python solve per case, same algorithm and tolerance."""
    out = np.empty(len(loads))
    c, s = math.cos(a0), math.sin(a0)  # once per bearing, as the batched path
    for k, fa in enumerate(loads.tolist()):  # one case at a time by design
        alpha, it, _ = _kernels.solve_one(fa, cs, a0, c, s, *TOL)
        if it < 0:
            raise RuntimeError(f"scalar Newton did not converge for F_a = {fa} N")
        out[k] = alpha
    return out


def library_brentq(loads, cs, a0):
    """The former baseline (reference only): brentq on the array function, tolerance 1e-14."""

    def f(alpha, fa):
        return static.thrust_from_angle(alpha, cs, a0) / fa - 1.0

    return np.array([brentq(f, a0 + 1e-15, math.pi / 2 - 1e-12, args=(fa,), xtol=1e-14, rtol=1e-14)
                     for fa in loads])


def measure(n_batch=N_BATCH, n_baseline=N_BASELINE, n_brentq=N_BRENTQ, repeat=REPEAT, n_small=N_SMALL):
    """All timings of one run; a dict of rates [cases/s], CPU time per case [ns] and largest differences [rad]."""
    b = catalog.get("4-1006095")
    c = stand.stand_constants(b.n_balls, b.ball_diameter, b.pitch_diameter, b.inner_conformity,
                              b.outer_conformity, b.contact_angle)
    cs, a0 = float(c.force_characteristic), b.contact_angle
    loads = cases(n_batch)
    engine = "compiled" if _kernels.available() else "numpy"  # what engine="auto" runs for a large batch
    batched(loads[:1000], cs, a0, engine)  # load the kernel (compiled or from the cache) outside the clock
    load_before = os.getloadavg()[0]
    t_ship, cpu_ship, alpha = best_of_wall_and_cpu(lambda: batched(loads, cs, a0, "auto"), repeat)
    t_ship_small, _, _ = best_of_wall_and_cpu(lambda: batched(loads[:n_small], cs, a0, "auto"), repeat)
    t_np, cpu_np, alpha_np = best_of_wall_and_cpu(lambda: batched(loads, cs, a0, "numpy"), repeat)
    t_np_small, _, _ = best_of_wall_and_cpu(lambda: batched(loads[:n_small], cs, a0, "numpy"), repeat)
    t_base, ref = best_of(lambda: baseline(loads[:n_baseline], cs, a0), repeat)
    t_old, old = best_of(lambda: library_brentq(loads[:n_brentq], cs, a0), repeat)
    return {"engine": engine,  # with the kernel loaded, engine="auto" runs it for any batch
            "rate": n_batch / t_ship, "cpu_ns": cpu_ship / n_batch * 1e9, "small_rate": n_small / t_ship_small,
            "numpy_rate": n_batch / t_np, "numpy_cpu_ns": cpu_np / n_batch * 1e9,
            "numpy_small_rate": n_small / t_np_small, "base_rate": n_baseline / t_base,
            "brentq_rate": n_brentq / t_old, "diff": float(np.max(np.abs(alpha[:n_baseline] - ref))),
            "diff_brentq": float(np.max(np.abs(alpha[:n_brentq] - old))),
            "diff_numpy": float(np.max(np.abs(alpha - alpha_np))), "identical": float(np.mean(alpha == alpha_np)),
            "load": (load_before, os.getloadavg()[0])}


def main(**sizes):
    m = measure(**sizes)
    n_small = sizes.get("n_small", N_SMALL)
    rate, base, np_rate = m["rate"], m["base_rate"], m["numpy_rate"]
    print(f"load average {m['load'][0]:.2f} before, {m['load'][1]:.2f} after (2 cores)")
    print(f"shipped (engine auto -> {m['engine']}): {rate:10.4g} cases/s ({m['small_rate']:.4g} for {n_small} cases; "
          f"{m['cpu_ns']:.1f} ns of CPU a case)")
    print(f"numpy (the fallback)      : {np_rate:10.4g} cases/s ({m['numpy_small_rate']:.4g} for {n_small} cases; "
          f"{m['numpy_cpu_ns']:.1f} ns of CPU a case); shipped / numpy = {rate / np_rate:.3g} "
          f"(CPU {m['numpy_cpu_ns'] / m['cpu_ns']:.3g}); {100 * m['identical']:.2f} % identical, "
          f"max difference {m['diff_numpy']:.2e} rad")
    print(f"fair scalar solve         : {base:10.4g} cases/s  (plain Python + math, same algorithm and tolerance)")
    print(f"library brentq (former)   : {m['brentq_rate']:10.4g} cases/s  (numpy on scalars, tol 1e-14; reference)")
    print(f"max |alpha_shipped - alpha_scalar| = {m['diff']:.2e} rad, - alpha_brentq = {m['diff_brentq']:.2e} rad")
    print(f"shipped / fair scalar = {rate / base:.4g}x (numpy fallback {np_rate / base:.4g}x)")
    ok = m["diff"] < 1e-12 and m["diff_brentq"] < 1e-10 and m["diff_numpy"] < 1e-12
    print(f"RESULT axial_angle cases_per_s={rate:.4g} baseline_cases_per_s={base:.4g} ratio={rate / base:.4g} "
          f"baseline_label=fair_scalar_Newton_(math) former_brentq_ratio={rate / m['brentq_rate']:.4g} "
          f"compiled_cases_per_s={rate if m['engine'] == 'compiled' else float('nan'):.4g} "
          f"numpy_over_compiled={np_rate / rate:.3g} numpy_over_compiled_cpu={m['cpu_ns'] / m['numpy_cpu_ns']:.3g} "
          f"engine={m['engine']} numpy_cases_per_s={np_rate:.4g} numpy_ratio={np_rate / base:.4g} "
          f"cpu_ns_per_case={m['cpu_ns']:.3g} numpy_cpu_ns_per_case={m['numpy_cpu_ns']:.3g} "
          f"load_average={m['load'][0]:.2f} batched_label=shipped_(engine_auto:_{m['engine']})")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())

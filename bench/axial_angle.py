"""Benchmark: operating contact angle under axial load (spec 000), batched Newton vs a fair scalar solver.

Solves 10^6 loads on bearing 4-1006095 with :func:`bearinglab.stand.operating_contact_angle` (numpy,
batched) and, in the same run:

* the fair scalar baseline: the same algorithm written as an engineer writes a one-case solver, plain
  Python and ``math`` (``_kernels.solve_one``): the same start (Newton on eq. (1) squared, in the gap
  cos alpha0 - cos alpha), the Newton increment of section 6.3, the same tolerances, one case at a time;
* the compiled limit: the same per-case algorithm as a numba kernel, parallel over cases
  (``_kernels.operating_angle``; skipped when numba is missing);
* for reference only, the former baseline, labelled as what it is: ``scipy.optimize.brentq`` per case
  on the library's array function at a tighter tolerance (1e-14).

Every path is timed by the same rule (best of ``REPEAT`` runs) and compared case by case. The batched and
compiled paths are also timed at ``N_SMALL`` cases, and their CPU time is reported next to the wall time
(the compiled kernel runs on every core, the numpy path on one).
"""

from __future__ import annotations

import math
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


def batched(loads, cs, a0):
    return stand.operating_contact_angle(loads, cs, a0)


def baseline(loads, cs, a0):
    """The fair scalar baseline: one plain-Python Newton per case, same start and tolerance."""
    out = np.empty(len(loads))
    c, s = math.cos(a0), math.sin(a0)  # once per bearing, as the batched path
    for k, fa in enumerate(loads.tolist()):  # one case at a time by design
        alpha, it, _ = _kernels.solve_one(fa, cs, a0, c, s, *TOL)
        if it < 0:
            raise RuntimeError(f"scalar Newton did not converge for F_a = {fa} N")
        out[k] = alpha
    return out


def compiled(loads, cs, a0):
    """The compiled limit: the same per-case algorithm, numba, parallel over cases."""
    n = loads.size  # one bearing: stride-0 views, no per-case copies of C* and alpha0
    alpha, it, _ = _kernels.operating_angle(loads, np.broadcast_to(cs, n), np.broadcast_to(a0, n), *TOL)
    if (it < 0).any():
        raise RuntimeError("compiled Newton did not converge")
    return alpha


def library_brentq(loads, cs, a0):
    """The former baseline (reference only): brentq on the array function, tolerance 1e-14."""

    def f(alpha, fa):
        return static.thrust_from_angle(alpha, cs, a0) / fa - 1.0

    return np.array([brentq(f, a0 + 1e-15, math.pi / 2 - 1e-12, args=(fa,), xtol=1e-14, rtol=1e-14)
                     for fa in loads])


def measure(n_batch=N_BATCH, n_baseline=N_BASELINE, n_brentq=N_BRENTQ, repeat=REPEAT, n_small=N_SMALL):
    """All timings of one run; a dict of rates [cases/s] and largest differences [rad]."""
    b = catalog.get("4-1006095")
    c = stand.stand_constants(b.n_balls, b.ball_diameter, b.pitch_diameter, b.inner_conformity,
                              b.outer_conformity, b.contact_angle)
    cs, a0 = float(c.force_characteristic), b.contact_angle
    loads = cases(n_batch)
    t_batch, cpu_batch, alpha = best_of_wall_and_cpu(lambda: batched(loads, cs, a0), repeat)
    t_small, _, _ = best_of_wall_and_cpu(lambda: batched(loads[:n_small], cs, a0), repeat)
    t_base, ref = best_of(lambda: baseline(loads[:n_baseline], cs, a0), repeat)
    t_old, old = best_of(lambda: library_brentq(loads[:n_brentq], cs, a0), repeat)
    out = {"rate": n_batch / t_batch, "cpu_rate": n_batch / cpu_batch, "small_rate": n_small / t_small,
           "base_rate": n_baseline / t_base, "brentq_rate": n_brentq / t_old,
           "diff": float(np.max(np.abs(alpha[:n_baseline] - ref))),
           "diff_brentq": float(np.max(np.abs(alpha[:n_brentq] - old)))}
    if _kernels.available():
        compiled(loads[:1000], cs, a0)  # compile (or load the cache) outside the clock
        t_comp, cpu_comp, fast = best_of_wall_and_cpu(lambda: compiled(loads, cs, a0), repeat)
        t_csmall, _, _ = best_of_wall_and_cpu(lambda: compiled(loads[:n_small], cs, a0), repeat)
        out.update(compiled_rate=n_batch / t_comp, compiled_cpu_rate=n_batch / cpu_comp,
                   compiled_small_rate=n_small / t_csmall, diff_compiled=float(np.max(np.abs(alpha - fast))),
                   identical=float(np.mean(alpha == fast)))
    return out


def main(**sizes):
    m = measure(**sizes)
    n_small = sizes.get("n_small", N_SMALL)
    rate, base = m["rate"], m["base_rate"]
    print(f"batched numpy Newton   : {rate:12.4g} cases/s ({m['small_rate']:.4g} for {n_small} cases; "
          f"{m['cpu_rate']:.4g} per CPU second)")
    print(f"fair scalar Newton     : {base:12.4g} cases/s  (plain Python + math, same start and tolerance)")
    print(f"library brentq (former): {m['brentq_rate']:12.4g} cases/s  (numpy on scalars, tol 1e-14; reference)")
    print(f"max |alpha_batched - alpha_scalar| = {m['diff']:.2e} rad, - alpha_brentq = {m['diff_brentq']:.2e} rad")
    extra = ""
    ok = m["diff"] < 1e-12 and m["diff_brentq"] < 1e-10
    if "compiled_rate" in m:
        frac = rate / m["compiled_rate"]
        print(f"compiled limit (numba) : {m['compiled_rate']:12.4g} cases/s ({m['compiled_small_rate']:.4g} for the "
              f"small batch; {m['compiled_cpu_rate']:.4g} per CPU second); numpy path = {frac:.3g} of it; "
              f"max difference {m['diff_compiled']:.2e} rad, {100 * m['identical']:.2f} % identical")
        extra = (f" compiled_cases_per_s={m['compiled_rate']:.4g} numpy_over_compiled={frac:.3g}"
                 f" numpy_over_compiled_cpu={m['cpu_rate'] / m['compiled_cpu_rate']:.3g}")
        ok = ok and m["diff_compiled"] < 1e-12
    print(f"RESULT axial_angle cases_per_s={rate:.4g} baseline_cases_per_s={base:.4g} ratio={rate / base:.4g} "
          f"baseline_label=fair_scalar_Newton_(math) former_brentq_ratio={rate / m['brentq_rate']:.4g}{extra}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())

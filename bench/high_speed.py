"""Benchmark: the 218 bearing's high-speed map (spec 004), batched Newton vs a fair scalar solver.

Solves 100 thrusts (2.5-45 kN) x 100 speeds (0-15 000 rpm) in one call of
:func:`bearinglab.quasistatic.contact_angles` (batched Newton with continuation in speed) and, in the same
run, a random sample of the same cases by:

* the fair scalar baseline (``baseline``): the compiled path's per-case source (bench/_kernels_highspeed.py,
  ``_compiled.plain_solver``) run by CPython with ``math`` and tuples: static start, continuation in
  omega^2, analytic Jacobian, the same tolerance (1e-12 on the scaled residual norm), the same Hertz
  interpolants, then the full state of the case. It does the same work per case as the compiled path,
  static start and outputs included, all inside its timing;
* the compiled path: the library's own fast path, the same per-case source compiled by numba and run
  in parallel over the cases (``contact_angles(engine="compiled")``, skipped when numba is missing); the
  batched numpy path is ``engine="numpy"``. Both time the whole map: static starts, solve, full state,
  result assembly. The compiled path's CPU time (both threads) is printed next to its wall time: on a
  machine shared with other work it shows what the code costs when the wall time shows what it got;
* for reference only, the former baseline, labelled as what it is (``library_fsolve``): per-case
  ``scipy.optimize.fsolve`` on the library's batched kernel called with one-element arrays (about
  0.5 ms a call, mostly numpy overhead on tiny arrays).

Prints cases/s, the ratios, the largest differences case by case, and the cost of the whole solve in
units of one batched residual-plus-Jacobian evaluation of all cases. Every path: best of ``REPEAT`` runs.
"""

from __future__ import annotations

import sys

import _kernels
import _kernels_highspeed as _hs
import numpy as np
from _timing import best_of, best_of_wall_and_cpu
from scipy.optimize import fsolve

from bearinglab import catalog, quasistatic
from bearinglab.quasistatic import _compiled
from bearinglab.units import RPM

N_LOADS = N_SPEEDS = 100
N_BASELINE = 1000
N_FORMER = 100
REPEAT = 3
OPTIONS = {"constants": "harris", "on_failure": "flag", "friction_limit": np.inf}
B218 = catalog.get("B218")
GEO = quasistatic._bearing_args(B218)


def grid(n_loads=N_LOADS, n_speeds=N_SPEEDS):
    """The map's thrusts and speeds (SI), shape (n_loads, n_speeds) each."""
    fa = np.linspace(2.5e3, 45e3, n_loads)
    n = np.linspace(0.0, 15000.0, n_speeds) * RPM
    return np.meshgrid(fa, n, indexing="ij")


def batched(fa, n):
    """All cases in one batched call of the numpy path."""
    return quasistatic.contact_angles(fa, n, *GEO, engine="numpy", **OPTIONS)


def static_starts(fa):
    """The static solutions the solvers start from, (X1, X2, delta_i, delta_e, delta_a)/D per case."""
    fa = np.asarray(fa, float).ravel()
    model, _ = quasistatic._prepare(fa, *GEO, "outer", 1, OPTIONS["constants"])
    idx = np.arange(fa.size)
    return quasistatic._unknowns_from(model, idx, *quasistatic._static_start(model, idx))


def baseline(fa, n):
    """The fair scalar baseline, one plain-Python solve from rest per case, static start and full state included.

    Returns the state per case (n, 20): the outputs ``_compiled.OUTPUTS`` (alpha_i, alpha_e first), then
    alpha_s; NaN where a case fails.
    """
    fa, n = np.asarray(fa, float).ravel(), np.asarray(n, float).ravel()
    solve = _hs.solver(*_hs.bearing_parameters(GEO, constants=OPTIONS["constants"]))
    out = np.full((fa.size, 1 + len(_compiled.OUTPUTS)), np.nan)
    for k, (f, w) in enumerate(zip(fa.tolist(), n.tolist(), strict=True)):  # one at a time
        alpha_s, _v, status, _it, state = solve(f, w)
        if status == 0:
            out[k] = *state, alpha_s
    return out


def compiled(fa, n):
    """The library's compiled path (numba), all cases in one call; the whole state."""
    return quasistatic.contact_angles(fa, n, *GEO, engine="compiled", **OPTIONS)


def _columns(state, sample=slice(None)):
    """The ``_compiled.OUTPUTS`` and alpha_s of a state, (cases, 20), in the baseline's order."""
    names = (*_compiled.OUTPUTS, "static_contact_angle")
    return np.stack([np.ravel(getattr(state, k))[sample] for k in names], axis=1)


def _largest_difference(got, ref):
    """Largest difference per column, relative to the column's largest value (angles: absolute, rad)."""
    scale = np.nanmax(np.abs(ref), axis=0)
    scale[[0, 1, 9, 19]] = 1.0  # alpha_i, alpha_e, beta, alpha_s: absolute [rad]
    scale[18] = np.inf  # the residual at the solution is rounding noise below the tolerance
    return float(np.nanmax(np.abs(got - ref) / scale))


def library_fsolve(fa, n, starts=None):
    """The former baseline (reference only): per-case fsolve on the library kernel with one-element arrays.

    ``starts`` (from :func:`static_starts`) are computed outside the timed loop, so that the baseline
    times the solver alone: this understates the per-case cost, and the ratio, on purpose.
    """
    fa, n = np.asarray(fa, float).ravel(), np.asarray(n, float).ravel()
    model, _ = quasistatic._prepare(fa, *GEO, "outer", 1, OPTIONS["constants"])
    starts = static_starts(fa) if starts is None else starts
    out = np.full((fa.size, 2), np.nan)
    for k in range(fa.size):  # the baseline is one case at a time by design
        idx = np.array([k])
        v = starts[k]

        def f(x, w2, idx=idx):
            return quasistatic._equations(model, idx, x[None, :], np.array([w2]), False)[0][0]

        def jac(x, w2, idx=idx):
            return quasistatic._equations(model, idx, x[None, :], np.array([w2]), True)[1][0]

        x, info, ier, _msg = fsolve(f, v, args=(n[k] ** 2,), fprime=jac, xtol=1e-13, full_output=True)
        if ier != 1 or np.linalg.norm(info["fvec"]) > 1e-10:  # continuation in 1500-rpm steps
            x = v
            steps = max(1, int(np.ceil(n[k] / (1500 * RPM))))
            for w in np.linspace(0.0, n[k], steps + 1)[1:]:
                x, info, ier, _msg = fsolve(f, x, args=(w**2,), fprime=jac, xtol=1e-13, full_output=True)
        if ier == 1 and np.linalg.norm(info["fvec"]) < 1e-10:
            ex = quasistatic._equations(model, idx, x[None, :], np.array([n[k] ** 2]), False)[3]
            out[k] = ex["ai"][0], ex["ae"][0]
    return out



def measure(n_loads=N_LOADS, n_speeds=N_SPEEDS, n_baseline=N_BASELINE, n_former=N_FORMER, repeat=REPEAT):
    """All timings of one run: a dict of times [s], rates [cases/s] and largest differences.

    ``diff*`` are the largest differences of (alpha_i, alpha_e) [rad]; ``diff_state*`` those of the whole
    state (:func:`_largest_difference`).
    """
    fa, n = grid(n_loads, n_speeds)
    total = fa.size
    t_batch, state = best_of(lambda: batched(fa, n), repeat)
    # one batched residual + Jacobian evaluation of the same cases, at the solution
    model, _ = quasistatic._prepare(fa.ravel(), *GEO, "outer", 1, OPTIONS["constants"])
    idx = np.arange(total)
    v = quasistatic._unknowns_from(model, idx, state.contact_angle_outer.ravel(), state.deflection_inner.ravel(),
                                   state.deflection_outer.ravel(), state.axial_displacement.ravel())
    t_eval, _ = best_of(lambda: quasistatic._equations(model, idx, v, n.ravel() ** 2, True), 10)
    got = _columns(state)
    sample = np.random.default_rng(0).choice(total, min(n_baseline, total), replace=False)
    fs, ns = fa.ravel()[sample], n.ravel()[sample]
    t_base, ref = best_of(lambda: baseline(fs, ns), repeat)
    former = sample[:n_former]
    starts = static_starts(fa.ravel()[former])  # outside the former baseline's timing (reference only)
    t_old, old = best_of(lambda: library_fsolve(fa.ravel()[former], n.ravel()[former], starts), repeat)
    ang = slice(0, 2)  # alpha_i, alpha_e in _columns
    m = {"total": total, "t_batch": t_batch, "rate": total / t_batch, "t_eval": t_eval,
         "base_rate": sample.size / t_base, "former_rate": former.size / t_old,
         "failed": int((~state.converged).sum()), "failed_base": int(np.isnan(ref[:, 0]).sum()),
         "failed_former": int(np.isnan(old[:, 0]).sum()), "iterations": state.iterations,
         "diff": float(np.nanmax(np.abs(got[sample, ang] - ref[:, ang]))),
         "diff_state": _largest_difference(ref, got[sample]),
         "diff_former": float(np.nanmax(np.abs(got[former, ang] - old)))}
    if _kernels.available():
        compiled(fa.ravel()[:4], n.ravel()[:4])  # compile outside the clock
        t_comp, cpu_comp, fast = best_of_wall_and_cpu(lambda: compiled(fa, n), repeat)
        m["t_compiled"], m["cpu_compiled"], m["compiled_rate"] = t_comp, cpu_comp, total / t_comp
        fast = _columns(fast)
        m["diff_compiled"] = float(np.max(np.abs(got[:, ang] - fast[:, ang])))
        m["diff_state_compiled"] = _largest_difference(fast, got)
        m["diff_state_compiled_scalar"] = _largest_difference(ref, fast[sample])
    return m


def main(n_loads=N_LOADS, n_speeds=N_SPEEDS, n_baseline=N_BASELINE, n_former=N_FORMER, repeat=REPEAT):
    m = measure(n_loads, n_speeds, n_baseline, n_former, repeat)
    rate, base, it = m["rate"], m["base_rate"], m["iterations"]
    print(f"218 map: {n_loads} thrusts x {n_speeds} speeds = {m['total']} cases, {m['failed']} failed, "
          f"Newton iterations per case: mean {it.mean():.2f}, max {it.max()}")
    print(f"batched numpy Newton   : {m['total']:>6d} cases in {m['t_batch']:8.3f} s = {rate:10.4g} cases/s")
    print(f"fair scalar Newton     : {base:10.4g} cases/s (plain Python + math, the compiled path's source: static "
          f"start, solve and full state per case, all timed; {m['failed_base']} failed)")
    print(f"library fsolve (former): {m['former_rate']:10.4g} cases/s (numpy on one-element arrays; reference only; "
          f"{m['failed_former']} failed)")
    print(f"whole solve = {m['t_batch'] / m['t_eval']:.1f} x one batched residual+Jacobian evaluation "
          f"({m['t_eval'] * 1e3:.2f} ms)")
    print(f"max |alpha_batched - alpha_scalar| = {m['diff']:.2e} rad, - alpha_fsolve = {m['diff_former']:.2e} rad; "
          f"whole state batched vs scalar {m['diff_state']:.2e} (relative to each quantity's largest value)")
    ok = (m["diff"] < 1e-12 and m["diff_former"] < 1e-9 and m["diff_state"] < 1e-12
          and m["failed"] == m["failed_base"] == m["failed_former"] == 0)
    extra = ""
    if "compiled_rate" in m:
        frac = rate / m["compiled_rate"]
        print(f"compiled path (numba)  : {m['compiled_rate']:10.4g} cases/s ({m['t_compiled']:.4f} s wall, "
              f"{m['cpu_compiled']:.4f} s CPU on all threads) = {m['compiled_rate'] / base:.3g} x the fair scalar "
              f"baseline; numpy path = {frac:.3g} of it; max difference {m['diff_compiled']:.2e} rad, whole state "
              f"{m['diff_state_compiled']:.2e} (vs numpy), {m['diff_state_compiled_scalar']:.2e} (vs scalar)")
        extra = (f" compiled_cases_per_s={m['compiled_rate']:.4g} numpy_over_compiled={frac:.3g}"
                 f" compiled_map_seconds={m['t_compiled']:.3g} compiled_cpu_seconds={m['cpu_compiled']:.3g}"
                 f" compiled_ratio={m['compiled_rate'] / base:.4g} state_diff_compiled={m['diff_state_compiled']:.2g}")
        ok = ok and m["diff_compiled"] < 1e-12 and m["diff_state_compiled"] < 1e-12
    # the table's first row is the shipped path: engine="auto" runs the compiled kernel where numba imports
    shipped, seconds, label = rate, m["t_batch"], "batched_numpy"
    if "compiled_rate" in m:
        shipped, seconds, label = m["compiled_rate"], m["t_compiled"], "shipped_(engine_auto:_compiled)"
        extra += f" numpy_cases_per_s={rate:.4g} numpy_ratio={rate / base:.4g} numpy_map_seconds={m['t_batch']:.3g}"
    print(f"shipped / fair scalar = {shipped / base:.4g}x (numpy fallback {rate / base:.4g}x)")
    print(f"RESULT high_speed cases_per_s={shipped:.4g} baseline_cases_per_s={base:.4g} ratio={shipped / base:.4g} "
          f"map_seconds={seconds:.3g} solve_over_residual_eval={m['t_batch'] / m['t_eval']:.3g} "
          f"baseline_label=fair_scalar_Newton_(math) former_fsolve_ratio={shipped / m['former_rate']:.4g}{extra}"
          f" batched_label={label} baseline_work=static_start+solve+state")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())

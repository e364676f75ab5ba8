"""Benchmark: the 218 bearing's high-speed map (spec 004), batched Newton vs a fair scalar solver.

Solves 100 thrusts (2.5-45 kN) x 100 speeds (0-15 000 rpm) in one call of
:func:`bearinglab.quasistatic.contact_angles` (batched Newton with continuation in speed) and, in the same
run, a random sample of the same cases by:

* the fair scalar baseline (``baseline``): the same equations and the same solver written for one case
  in plain Python and ``math`` (bench/_kernels_highspeed.py): same static start, same continuation in
  omega^2, analytic Jacobian, same tolerance (1e-12 on the scaled residual norm), same Hertz
  interpolants. Its static starts are computed outside its timing (the batched path's timing includes
  them), which favours the baseline;
* the compiled path: the library's own fast path, the same per-case algorithm compiled by numba and run
  in parallel over the cases (``contact_angles(engine="compiled")``, skipped when numba is missing); the
  batched numpy path is ``engine="numpy"``. Both time the whole map: static starts, solve, full state;
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
from _timing import best_of
from scipy.optimize import fsolve

from bearinglab import catalog, quasistatic
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


def baseline(fa, n, starts=None):
    """The fair scalar baseline, one plain-Python solve per case; returns (alpha_i, alpha_e) per case [rad].

    ``starts`` (from :func:`static_starts`) are computed outside the timed loop: this favours the
    baseline. A case that fails gives NaN.
    """
    fa, n = np.asarray(fa, float).ravel(), np.asarray(n, float).ravel()
    starts = static_starts(fa) if starts is None else starts
    solve = _hs.solver(*_hs.bearing_parameters(GEO, constants=OPTIONS["constants"]))
    out = np.full((fa.size, 2), np.nan)
    for k, (f, w, v) in enumerate(zip(fa.tolist(), n.tolist(), starts.tolist(), strict=True)):  # one at a time
        _v, status, _it, ai, ae = solve(f, w, v)
        if status == 0:
            out[k] = ai, ae
    return out


def compiled(fa, n):
    """The library's compiled path (numba), all cases in one call; (alpha_i, alpha_e) per case, NaN if failed."""
    state = quasistatic.contact_angles(fa, n, *GEO, engine="compiled", **OPTIONS)
    return np.stack([np.ravel(state.contact_angle_inner), np.ravel(state.contact_angle_outer)], axis=1)


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
    """All timings of one run: a dict of times [s], rates [cases/s] and largest differences [rad]."""
    fa, n = grid(n_loads, n_speeds)
    total = fa.size
    t_batch, state = best_of(lambda: batched(fa, n), repeat)
    # one batched residual + Jacobian evaluation of the same cases, at the solution
    model, _ = quasistatic._prepare(fa.ravel(), *GEO, "outer", 1, OPTIONS["constants"])
    idx = np.arange(total)
    v = quasistatic._unknowns_from(model, idx, state.contact_angle_outer.ravel(), state.deflection_inner.ravel(),
                                   state.deflection_outer.ravel(), state.axial_displacement.ravel())
    t_eval, _ = best_of(lambda: quasistatic._equations(model, idx, v, n.ravel() ** 2, True), 10)
    got = np.stack([state.contact_angle_inner.ravel(), state.contact_angle_outer.ravel()], axis=1)
    sample = np.random.default_rng(0).choice(total, min(n_baseline, total), replace=False)
    fs, ns = fa.ravel()[sample], n.ravel()[sample]
    starts = static_starts(fs)
    t_base, ref = best_of(lambda: baseline(fs, ns, starts), repeat)
    former = sample[:n_former]
    t_old, old = best_of(lambda: library_fsolve(fa.ravel()[former], n.ravel()[former], starts[:n_former]), repeat)
    m = {"total": total, "t_batch": t_batch, "rate": total / t_batch, "t_eval": t_eval,
         "base_rate": sample.size / t_base, "former_rate": former.size / t_old,
         "failed": int((~state.converged).sum()), "failed_base": int(np.isnan(ref[:, 0]).sum()),
         "failed_former": int(np.isnan(old[:, 0]).sum()), "iterations": state.iterations,
         "diff": float(np.nanmax(np.abs(got[sample] - ref))), "diff_former": float(np.nanmax(np.abs(got[former] - old)))}
    if _kernels.available():
        compiled(fa.ravel()[:4], n.ravel()[:4])  # compile outside the clock
        t_comp, fast = best_of(lambda: compiled(fa, n), repeat)
        m["compiled_rate"] = total / t_comp
        m["diff_compiled"] = float(np.max(np.abs(got - fast)))
    return m


def main(n_loads=N_LOADS, n_speeds=N_SPEEDS, n_baseline=N_BASELINE, n_former=N_FORMER, repeat=REPEAT):
    m = measure(n_loads, n_speeds, n_baseline, n_former, repeat)
    rate, base, it = m["rate"], m["base_rate"], m["iterations"]
    print(f"218 map: {n_loads} thrusts x {n_speeds} speeds = {m['total']} cases, {m['failed']} failed, "
          f"Newton iterations per case: mean {it.mean():.2f}, max {it.max()}")
    print(f"batched numpy Newton   : {m['total']:>6d} cases in {m['t_batch']:8.3f} s = {rate:10.4g} cases/s")
    print(f"fair scalar Newton     : {base:10.4g} cases/s (plain Python + math, same start, solver and tolerance; "
          f"{m['failed_base']} failed)")
    print(f"library fsolve (former): {m['former_rate']:10.4g} cases/s (numpy on one-element arrays; reference only; "
          f"{m['failed_former']} failed)")
    print(f"whole solve = {m['t_batch'] / m['t_eval']:.1f} x one batched residual+Jacobian evaluation "
          f"({m['t_eval'] * 1e3:.2f} ms)")
    print(f"max |alpha_batched - alpha_scalar| = {m['diff']:.2e} rad, - alpha_fsolve = {m['diff_former']:.2e} rad")
    ok = m["diff"] < 1e-12 and m["diff_former"] < 1e-9 and m["failed"] == m["failed_base"] == m["failed_former"] == 0
    extra = ""
    if "compiled_rate" in m:
        frac = rate / m["compiled_rate"]
        print(f"compiled path (numba)  : {m['compiled_rate']:10.4g} cases/s; numpy path = {frac:.3g} of it; "
              f"max difference {m['diff_compiled']:.2e} rad")
        extra = f" compiled_cases_per_s={m['compiled_rate']:.4g} numpy_over_compiled={frac:.3g}"
        ok = ok and m["diff_compiled"] < 1e-12
    print(f"RESULT high_speed cases_per_s={rate:.4g} baseline_cases_per_s={base:.4g} ratio={rate / base:.4g} "
          f"map_seconds={m['t_batch']:.3g} solve_over_residual_eval={m['t_batch'] / m['t_eval']:.3g} "
          f"baseline_label=fair_scalar_Newton_(math) former_fsolve_ratio={rate / m['former_rate']:.4g}{extra}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())

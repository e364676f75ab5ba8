"""Benchmark: the 218 bearing's high-speed map (spec 004), batched Newton vs per-case scipy fsolve.

Solves 100 thrusts (2.5-45 kN) x 100 speeds (0-15 000 rpm) in one call of
:func:`bearinglab.quasistatic.contact_angles` (batched Newton with continuation in speed) and, in the same
run, a random sample of the same cases one at a time with ``scipy.optimize.fsolve`` on the same residual
and analytic Jacobian (:func:`bearinglab.quasistatic.residual`'s kernel), started from the same static
solution (with continuation in 1500-rpm steps where the direct solve fails; the static starts of the
baseline are computed outside its timing, which favours the baseline). Prints cases/s, the ratio,
the largest difference between the two, and the cost of the whole solve in units of one batched
residual-plus-Jacobian evaluation of all cases. Both paths: best of ``REPEAT`` runs.

The baseline is labelled as what it is: it calls the library's batched kernel on one-element arrays
(about 0.5 ms a call, mostly Chebyshev evaluations of the Hertz coefficients), so it is slower than a
scalar solver written in plain ``math`` would be; that fair baseline is still to be written (issue 14).
"""

from __future__ import annotations

import sys

import numpy as np
from _timing import best_of
from scipy.optimize import fsolve

from bearinglab import catalog, quasistatic
from bearinglab.units import RPM

N_LOADS = N_SPEEDS = 100
N_BASELINE = 300
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
    """All cases in one batched call."""
    return quasistatic.contact_angles(fa, n, *GEO, **OPTIONS)


def static_starts(fa):
    """The static solutions the solvers start from, (X1, X2, delta_i, delta_e, delta_a)/D per case."""
    fa = np.asarray(fa, float).ravel()
    model, _ = quasistatic._prepare(fa, *GEO, "outer", 1, OPTIONS["constants"])
    idx = np.arange(fa.size)
    return quasistatic._unknowns_from(model, idx, *quasistatic._static_start(model, idx))


def baseline(fa, n, starts=None):
    """Per-case fsolve on the same residual and Jacobian; returns (alpha_i, alpha_e) per case [rad].

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



def main(n_loads=N_LOADS, n_speeds=N_SPEEDS, n_baseline=N_BASELINE, repeat=REPEAT):
    fa, n = grid(n_loads, n_speeds)
    total = fa.size
    t_batch, state = best_of(lambda: batched(fa, n), repeat)
    # one batched residual + Jacobian evaluation of the same cases, at the solution
    model, _ = quasistatic._prepare(fa.ravel(), *GEO, "outer", 1, OPTIONS["constants"])
    idx = np.arange(total)
    v = quasistatic._unknowns_from(model, idx, state.contact_angle_outer.ravel(), state.deflection_inner.ravel(),
                                   state.deflection_outer.ravel(), state.axial_displacement.ravel())
    t_eval, _ = best_of(lambda: quasistatic._equations(model, idx, v, n.ravel() ** 2, True), 10)
    t_public, _ = best_of(lambda: quasistatic.residual(v.reshape(fa.shape + (5,)), fa, n, *GEO,
                                                       constants=OPTIONS["constants"]), 5)
    rng = np.random.default_rng(0)
    sample = rng.choice(total, n_baseline, replace=False)
    starts = static_starts(fa.ravel()[sample])
    t_base, ref = best_of(lambda: baseline(fa.ravel()[sample], n.ravel()[sample], starts), repeat)
    rate, base_rate = total / t_batch, n_baseline / t_base
    got = np.stack([state.contact_angle_inner.ravel()[sample], state.contact_angle_outer.ravel()[sample]], axis=1)
    diff = np.nanmax(np.abs(got - ref))
    failed_base = int(np.isnan(ref[:, 0]).sum())
    print(f"218 map: {n_loads} thrusts x {n_speeds} speeds = {total} cases, {int((~state.converged).sum())} failed, "
          f"Newton iterations per case: mean {state.iterations.mean():.2f}, max {state.iterations.max()}")
    print(f"batched Newton    : {total:>6d} cases in {t_batch:8.3f} s = {rate:10.4g} cases/s")
    print(f"per-case fsolve   : {n_baseline:>6d} cases in {t_base:8.3f} s = {base_rate:10.4g} cases/s "
          f"({failed_base} not converged)")
    print(f"one batched residual+Jacobian of all cases: {t_eval * 1e3:.2f} ms (kernel), "
          f"{t_public * 1e3:.2f} ms (public quasistatic.residual incl. input checks and Hertz tables)")
    print(f"whole solve = {t_batch / t_eval:.1f} x kernel evaluation = {t_batch / t_public:.1f} x public evaluation")
    print(f"max |alpha_newton - alpha_fsolve| = {diff:.2e} rad")
    print(f"RESULT high_speed cases_per_s={rate:.4g} baseline_cases_per_s={base_rate:.4g} ratio={rate / base_rate:.4g} "
          f"solve_over_residual_eval={t_batch / t_eval:.3g} baseline_label=per-case_fsolve_on_the_library_kernel")
    return 0 if diff < 1e-9 and failed_base == 0 and state.converged.all() else 1


if __name__ == "__main__":
    sys.exit(main())

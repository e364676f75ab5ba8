"""Benchmark: friction-lab task 2 (spec 001 eq. 6.2), grouped least squares vs a fair per-group fit.

Fits T = f0 d_m^3 n^(2/3) + T_F to 200 000 groups of 6 noisy points each (a group = one tilt of Table 5)
with :func:`bearinglab.lab.fits.speed_dependence` (all groups at once, bincount sums) and, in the same
run, a sample of the same groups one by one with the closed-form least-squares line in plain Python
(the fair baseline: the same sums the batched path forms, nothing more). For reference only, the former
baseline ``scipy.stats.linregress`` (which also computes r, p and standard errors) is timed too.
Every path: best of ``REPEAT`` runs. Prints groups/s, the ratios and the largest relative difference.
"""

from __future__ import annotations

import sys

import numpy as np
from _timing import best_of
from scipy import stats

from bearinglab.lab import fits

N_GROUPS = 200_000
POINTS = 6
N_BASELINE = 20_000
N_LINREGRESS = 5_000
REPEAT = 3
DM = 13.5e-3  # m, bearing 18
RPM = 2 * np.pi / 60


def cases(n_groups, seed=0):
    rng = np.random.default_rng(seed)
    speed = np.tile(np.linspace(500.0, 3000.0, POINTS), n_groups) * RPM
    f0 = rng.uniform(1e-7, 3e-7, n_groups)
    tf = rng.uniform(0.005, 0.05, n_groups) * 1e-3
    groups = np.repeat(np.arange(n_groups), POINTS)
    t = (f0[groups] * (DM * 1e3) ** 3 * (speed / RPM) ** (2 / 3)) * 1e-3 + tf[groups]
    t += rng.normal(0.0, 0.0008e-3, t.size)
    return t, speed, groups


def batched(t, speed, groups):
    fit = fits.speed_dependence(t, speed, DM, groups=groups)
    return fit.speed_term_factor, fit.load_term


def baseline(t, speed, n_groups):
    """The fair baseline: the closed-form least-squares line per group, plain Python."""
    n23 = ((speed / RPM) ** (2 / 3)).tolist()
    tm = (t * 1e3).tolist()  # N*mm, as the published fit
    dm3 = (DM * 1e3) ** 3
    f0, tf = np.empty(n_groups), np.empty(n_groups)
    for g in range(n_groups):  # one group at a time by design
        x, y = n23[g * POINTS:(g + 1) * POINTS], tm[g * POINTS:(g + 1) * POINTS]
        sx, sy = sum(x), sum(y)
        sxx = sum(v * v for v in x)
        sxy = sum(u * v for u, v in zip(x, y, strict=True))
        slope = (POINTS * sxy - sx * sy) / (POINTS * sxx - sx * sx)
        f0[g], tf[g] = slope / dm3, (sy - slope * sx) / POINTS * 1e-3
    return f0, tf


def linregress_baseline(t, speed, n_groups):
    """The former baseline (reference only): scipy.stats.linregress per group."""
    n23 = (speed / RPM) ** (2 / 3)
    f0, tf = np.empty(n_groups), np.empty(n_groups)
    for g in range(n_groups):
        sl = slice(g * POINTS, (g + 1) * POINTS)
        r = stats.linregress(n23[sl], t[sl] * 1e3)
        f0[g], tf[g] = r.slope / (DM * 1e3) ** 3, r.intercept * 1e-3
    return f0, tf



def main(n_groups=N_GROUPS, n_baseline=N_BASELINE, n_linregress=N_LINREGRESS, repeat=REPEAT):
    t, speed, groups = cases(n_groups)
    t_batch, (f0, tf) = best_of(lambda: batched(t, speed, groups), repeat)
    t_base, (f0_ref, tf_ref) = best_of(lambda: baseline(t, speed, n_baseline), repeat)
    t_lin, (f0_lin, tf_lin) = best_of(lambda: linregress_baseline(t, speed, n_linregress), repeat)
    rate, base_rate, lin_rate = n_groups / t_batch, n_baseline / t_base, n_linregress / t_lin

    def rel(a, b):
        return float(np.max(np.abs(a[: b.size] / b - 1)))

    diff = max(rel(f0, f0_ref), rel(tf, tf_ref))
    diff_lin = max(rel(f0, f0_lin), rel(tf, tf_lin))
    print(f"grouped bincount fit     : {n_groups:>8d} groups of {POINTS} in {t_batch:8.3f} s = {rate:12.4g} groups/s")
    print(f"per-group closed form    : {n_baseline:>8d} groups of {POINTS} in {t_base:8.3f} s = {base_rate:12.4g} groups/s")
    print(f"per-group linregress (former, reference): {lin_rate:12.4g} groups/s")
    print(f"max relative difference in f0 and T_F: {diff:.2e} (closed form), {diff_lin:.2e} (linregress)")
    print(f"RESULT friction_fits cases_per_s={rate:.4g} baseline_cases_per_s={base_rate:.4g} ratio={rate / base_rate:.4g} "
          f"baseline_label=per-group_closed-form_line former_linregress_ratio={rate / lin_rate:.4g}")
    return 0 if max(diff, diff_lin) < 1e-9 else 1


if __name__ == "__main__":
    sys.exit(main())

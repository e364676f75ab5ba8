"""Benchmark: friction-lab task 2 (spec 001 eq. 6.2), grouped least squares vs per-group scipy.

Fits T = f0 d_m^3 n^(2/3) + T_F to 200 000 groups of 6 noisy points each (a group = one tilt of Table 5)
with :func:`bearinglab.lab.fits.speed_dependence` (all groups at once, bincount sums) and, in the same
run, a sample of the same groups one by one with ``scipy.stats.linregress``. Prints groups/s, the ratio
and the largest relative difference in f0 and T_F between the two.
"""

from __future__ import annotations

import sys

import numpy as np
from _timing import best_of
from scipy import stats

from bearinglab.lab import fits

N_GROUPS = 200_000
POINTS = 6
N_BASELINE = 5_000
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
    n23 = (speed / RPM) ** (2 / 3)
    f0, tf = np.empty(n_groups), np.empty(n_groups)
    for g in range(n_groups):
        sl = slice(g * POINTS, (g + 1) * POINTS)
        r = stats.linregress(n23[sl], t[sl] * 1e3)
        f0[g], tf[g] = r.slope / (DM * 1e3) ** 3, r.intercept * 1e-3
    return f0, tf



def main():
    t, speed, groups = cases(N_GROUPS)
    t_batch, (f0, tf) = best_of(lambda: batched(t, speed, groups), 3)
    t_base, (f0_ref, tf_ref) = best_of(lambda: baseline(t, speed, N_BASELINE), 1)
    rate, base_rate = N_GROUPS / t_batch, N_BASELINE / t_base
    diff = max(
        np.max(np.abs(f0[:N_BASELINE] / f0_ref - 1)), np.max(np.abs(tf[:N_BASELINE] / tf_ref - 1))
    )
    print(
        f"grouped bincount fit : {N_GROUPS:>8d} groups of {POINTS} in {t_batch:8.3f} s = {rate:12.4g} groups/s"
    )
    print(
        f"per-group linregress : {N_BASELINE:>8d} groups of {POINTS} in {t_base:8.3f} s = {base_rate:12.4g} groups/s"
    )
    print(f"max relative difference in f0 and T_F: {diff:.2e}")
    print(
        f"RESULT friction_fits cases_per_s={rate:.4g} baseline_cases_per_s={base_rate:.4g} ratio={rate / base_rate:.4g}"
    )
    return 0 if diff < 1e-9 else 1


if __name__ == "__main__":
    sys.exit(main())

"""Benchmark: ISO 281 rating life of 10^5 load cases in one call vs an engineer's per-case loop.

The batched path is :func:`bearinglab.life.rating_life` on the 6205-2RS of the catalog (catalog C,
C0, Cu; f0 from its ball set) for 10^5 random (Fr, Fa, speed) cases: P from the X, Y, e table, L10,
kappa, a_ISO, L_nm and s0 (ISO 281; not ISO/TS 16281's reference life, whose load distribution
``bench/combined.py`` times). The baseline computes the same quantities case by case with plain ``math``
on Python floats (``bisect`` for the table), as an engineer's script would. Both are timed best-of-k on
the same cases, and every baseline case is compared with the batched answer.
"""

from __future__ import annotations

import bisect
import math
import sys
import warnings

import numpy as np
from _timing import best_of

from bearinglab import catalog, life, ratings

N_BATCH = 100_000
N_BASELINE = 20_000
NU = 20e-6  # m^2/s
EC, RELIABILITY = 0.5, 0.99
# ISO 281:2007 table 3, deep groove (the baseline's own copy of the table)
RATIO = [0.172, 0.345, 0.689, 1.03, 1.38, 2.07, 3.45, 5.17, 6.89]
E_TAB = [0.19, 0.22, 0.26, 0.28, 0.30, 0.34, 0.38, 0.42, 0.44]
Y_TAB = [2.30, 1.99, 1.71, 1.55, 1.45, 1.31, 1.15, 1.04, 1.00]


def cases(n, seed=0):
    rng = np.random.default_rng(seed)
    loads = np.zeros((n, 5))
    loads[:, 0] = rng.uniform(100.0, 5000.0, n)  # Fx
    loads[:, 2] = rng.uniform(0.0, 2000.0, n) * (rng.random(n) < 0.7)  # Fz (30 % pure radial)
    rpm = rng.uniform(50.0, 8000.0, n)
    return loads, rpm * math.pi / 30


def batched(bearing, loads, speeds):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ratings.RatingWarning)  # no load distribution; low s0
        # load_distribution=False: ISO 281 alone, the work the baseline does (the ISO/TS 16281 reference life
        # solves each case's load distribution first; bench/combined.py times that solve)
        r = life.rating_life(bearing, loads, speeds, kinematic_viscosity=NU, contamination=EC,
                             reliability=RELIABILITY, load_distribution=False)
    return np.stack([r.equivalent_dynamic_load, r.basic_rating_life, r.modified_rating_life,
                     r.static_safety_factor])


def _interp(x, xs, ys):
    x = min(max(x, xs[0]), xs[-1])
    k = min(max(bisect.bisect_right(xs, x) - 1, 0), len(xs) - 2)
    return ys[k] + (ys[k + 1] - ys[k]) * (x - xs[k]) / (xs[k + 1] - xs[k])


def one_case(fr, fa, omega, c, c0, cu, f0, dm_mm, a1):
    """ISO 281 life of one case, in plain floats (N, mm, rpm, mm^2/s)."""
    ratio = f0 * fa / c0
    e = _interp(ratio, RATIO, E_TAB)
    if fa > e * fr:
        p = 0.56 * fr + _interp(ratio, RATIO, Y_TAB) * fa
    else:
        p = fr
    l10 = 1e6 * (c / p) ** 3
    n = omega * 30 / math.pi
    nu1 = 45000 * n**-0.83 * dm_mm**-0.5 if n < 1000 else 4500 * n**-0.5 * dm_mm**-0.5
    k = min(max(NU * 1e6 / nu1, 0.1), 4.0)
    cc, pw = (2.2649, 0.054381) if k < 0.4 else (1.9987, 0.19087) if k < 1 else (1.9987, 0.071739)
    inner = 1 - (2.5671 - cc / k**pw) ** 0.83 * (EC * cu / p) ** (1 / 3)
    a_iso = min(0.1 * inner**-9.3, 50.0) if inner > 0 else 50.0
    p0 = max(0.6 * fr + 0.5 * fa, fr)
    return p, l10, a1 * a_iso * l10, c0 / p0


def baseline(bearing, loads, speeds):
    c, c0, cu = bearing.dynamic_load_rating, bearing.static_load_rating, bearing.fatigue_load_limit
    f0 = float(ratings.static_load_factor(bearing.ball_diameter, bearing.pitch_diameter))
    a1 = float(ratings.reliability_factor(RELIABILITY))
    dm = 0.5 * (bearing.bore + bearing.outside_diameter) * 1e3  # ISO 281's d_m = (d + D)/2 of nu1
    out = [one_case(math.hypot(f[0], f[1]), abs(f[2]), w, c, c0, cu, f0, dm, a1)
           for f, w in zip(loads.tolist(), speeds.tolist(), strict=True)]
    return np.array(out).T


def main():
    bearing = catalog.get("6205-2RS")
    loads, speeds = cases(N_BATCH)
    t_batch, got = best_of(lambda: batched(bearing, loads, speeds), 3)
    t_base, ref = best_of(lambda: baseline(bearing, loads[:N_BASELINE], speeds[:N_BASELINE]), 3)
    rate, base_rate = N_BATCH / t_batch, N_BASELINE / t_base
    diff = float(np.max(np.abs(got[:, :N_BASELINE] / ref - 1.0)))
    print(f"batched rating_life : {N_BATCH:>7d} cases in {t_batch:8.3f} s = {rate:12.4g} cases/s")
    print(f"per-case math loop  : {N_BASELINE:>7d} cases in {t_base:8.3f} s = {base_rate:12.4g} cases/s")
    print(f"max relative difference (P, L10, L_nm, s0), case by case: {diff:.2e}")
    print(f"RESULT rating_life cases_per_s={rate:.4g} baseline_cases_per_s={base_rate:.4g} ratio={rate / base_rate:.4g}")
    return 0 if diff < 1e-12 else 1


if __name__ == "__main__":
    sys.exit(main())

"""Benchmark: SKF four-term frictional moment of 10^5 cases in one call vs an engineer's per-case loop.

The batched path is :func:`bearinglab.friction.skf` for a 6205 (series 62, C0 = 7.8 kN) at 10^5 random
(Fr, Fa, speed, viscosity) cases, grease lubricated. The baseline evaluates the catalogue's equations
case by case with plain ``math`` on Python floats (N, mm, rpm, mm^2/s), as an engineer's script would.
Both are timed best-of-k on the same cases, and every baseline case is compared with the batched answer.
"""

from __future__ import annotations

import math
import sys

import numpy as np
from _timing import best_of

from bearinglab import friction

N_BATCH = 100_000
N_BASELINE = 20_000
D, BIG, C0 = 25.0, 52.0, 7800.0  # mm, mm, N
R1, R2, S1, S2 = 3.9e-7, 1.7, 3.23e-3, 36.5  # series 62 (SKF catalogue 2018)
KRS, KZ = 6e-8, 3.1  # grease, deep groove


def cases(n, seed=0):
    rng = np.random.default_rng(seed)
    fr = rng.uniform(10.0, 5000.0, n)
    fa = rng.uniform(0.0, 2000.0, n) * (rng.random(n) < 0.7)
    rpm = rng.uniform(10.0, 10000.0, n)
    nu = rng.uniform(5.0, 300.0, n)  # mm^2/s
    return fr, fa, rpm, nu


def batched(fr, fa, rpm, nu):
    return friction.skf(fr, fa, rpm * math.pi / 30, nu * 1e-6, D * 1e-3, BIG * 1e-3, series="62",
                        static_load_rating=C0, lubrication="grease").total_moment


def one_case(fr, fa, n, nu, krs=KRS):
    """M [N m] of one case in the catalogue's units (``krs``: K_rs of the lubrication, grease by default;
    bench/thermal.py calls it with the oil jet's)."""
    dm = 0.5 * (D + BIG)
    if fa > 0:
        s = math.sin(math.radians(24.6 * (fa / C0) ** 0.24))
        grr = R1 * dm**1.96 * (fr + R2 * fa / s) ** 0.54
        gsl = S1 * dm**-0.145 * (fr**5 + S2 * dm**1.5 * fa**4 / s) ** (1 / 3)
    else:
        grr = R1 * dm**1.96 * fr**0.54
        gsl = S1 * dm**-0.26 * fr ** (5 / 3)
    ish = 1 / (1 + 1.84e-9 * (n * dm) ** 1.28 * nu**0.64)
    rs = math.exp(-krs * nu * n * (D + BIG) * math.sqrt(KZ / (2 * (BIG - D))))
    phi_bl = math.exp(-2.6e-8 * (n * nu) ** 1.4 * dm)
    mu = phi_bl * 0.15 + (1 - phi_bl) * 0.05
    return (ish * rs * grr * (nu * n) ** 0.6 + gsl * mu) * 1e-3


def baseline(fr, fa, rpm, nu):
    return np.array([one_case(*c) for c in zip(fr.tolist(), fa.tolist(), rpm.tolist(), nu.tolist(), strict=True)])


def main():
    fr, fa, rpm, nu = cases(N_BATCH)
    t_batch, got = best_of(lambda: batched(fr, fa, rpm, nu), 3)
    m = slice(0, N_BASELINE)
    t_base, ref = best_of(lambda: baseline(fr[m], fa[m], rpm[m], nu[m]), 3)
    rate, base_rate = N_BATCH / t_batch, N_BASELINE / t_base
    diff = float(np.max(np.abs(got[m] / ref - 1.0)))
    print(f"batched friction.skf: {N_BATCH:>7d} cases in {t_batch:8.3f} s = {rate:12.4g} cases/s")
    print(f"per-case math loop  : {N_BASELINE:>7d} cases in {t_base:8.3f} s = {base_rate:12.4g} cases/s")
    print(f"max relative difference, case by case: {diff:.2e}")
    print(f"RESULT skf_friction cases_per_s={rate:.4g} baseline_cases_per_s={base_rate:.4g} ratio={rate / base_rate:.4g}")
    return 0 if diff < 1e-12 else 1


if __name__ == "__main__":
    sys.exit(main())

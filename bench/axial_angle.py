"""Benchmark: operating contact angle under axial load (spec 000), batched Newton vs per-case brentq.

Solves 10^6 loads on bearing 4-1006095 with :func:`bearinglab.stand.operating_contact_angle` and, in the
same run, a sample of the same cases one by one with ``scipy.optimize.brentq`` on the same equation (1).
Prints cases/s, the ratio and the largest difference between the two.
"""

from __future__ import annotations

import math
import sys

import numpy as np
from _timing import best_of
from scipy.optimize import brentq

from bearinglab import catalog, stand, static
from bearinglab.units import KGF

N_BATCH = 1_000_000
N_BASELINE = 2_000


def cases(n, seed=0):
    rng = np.random.default_rng(seed)
    return rng.uniform(0.05, 50.0, n) * KGF  # loads from 0.05 to 50 kgf


def batched(loads, cs, a0):
    return stand.operating_contact_angle(loads, cs, a0)


def baseline(loads, cs, a0):
    def f(alpha, fa):
        return static.thrust_from_angle(alpha, cs, a0) / fa - 1.0

    return np.array([brentq(f, a0 + 1e-15, math.pi / 2 - 1e-12, args=(fa,), xtol=1e-14, rtol=1e-14) for fa in loads])



def main():
    b = catalog.get("4-1006095")
    c = stand.stand_constants(b.n_balls, b.ball_diameter, b.pitch_diameter, b.inner_conformity, b.outer_conformity,
                              b.contact_angle)
    cs, a0 = float(c.force_characteristic), b.contact_angle
    loads = cases(N_BATCH)
    t_batch, alpha = best_of(lambda: batched(loads, cs, a0), 3)
    t_base, ref = best_of(lambda: baseline(loads[:N_BASELINE], cs, a0), 1)
    rate, base_rate = N_BATCH / t_batch, N_BASELINE / t_base
    diff = np.max(np.abs(alpha[:N_BASELINE] - ref))
    print(f"batched Newton : {N_BATCH:>9d} cases in {t_batch:8.3f} s = {rate:12.4g} cases/s")
    print(f"per-case brentq: {N_BASELINE:>9d} cases in {t_base:8.3f} s = {base_rate:12.4g} cases/s")
    print(f"max |alpha_newton - alpha_brentq| = {diff:.2e} rad")
    print(f"RESULT axial_angle cases_per_s={rate:.4g} baseline_cases_per_s={base_rate:.4g} ratio={rate / base_rate:.4g}")
    return 0 if diff < 1e-10 else 1


if __name__ == "__main__":
    sys.exit(main())

"""Benchmark: the steady temperature of 10 000 cases, batched against a per-case plain-Python solve.

The cases: a 6205 (series 62, C0 = 7.8 kN, width 15 mm), random F_r, F_a, speed and ambient, a VG32
oil (VI 95), oil-jet lubrication, ISO 15312's reference conductance. The batched path is
:func:`bearinglab.thermal.thermal_balance` over all cases at once. The baseline solves case by case in
plain Python with ``math``: the SKF moment in the catalogue's units, nu(T) by ASTM D341, and the same
bracketed Illinois iteration (same bracket, bisection every 8th step, same tolerances). Best of 3 each,
in the same run; every baseline case is compared with the batched temperature.
"""

from __future__ import annotations

import math
import sys

import numpy as np
import skf_friction
from _timing import best_of

from bearinglab import _solve, catalog, thermal
from bearinglab.ratings import lubrication

N_BATCH = 10_000
N_BASELINE = 1000
BEARING = catalog.get("6205-2RS").replace(designation="6205", series="62", seal=None, seals=0)
NU40 = 32e-6
NU100 = float(lubrication.viscosity_100_from_index(NU40, 95.0))
KRS = 3e-8  # K_rs of an oil jet (SKF catalogue 2018); the rest of the baseline is bench/skf_friction.py's
T_MAX = 423.15


def cases(n, seed=0):
    rng = np.random.default_rng(seed)
    fr = rng.uniform(100.0, 4000.0, n)
    fa = rng.uniform(0.0, 1500.0, n) * (rng.random(n) < 0.7)
    rpm = rng.uniform(500.0, 12000.0, n)
    ta = rng.uniform(273.15, 313.15, n)
    return fr, fa, rpm, ta


def batched(fr, fa, rpm, ta):
    return thermal.thermal_balance(BEARING, fr, fa, rpm * math.pi / 30, ta, NU40, NU100, maximum_temperature=T_MAX)


def _power(fr, fa, n, nu):
    """M n [W] of the SKF model for one case: bench/skf_friction.py's per-case moment, oil jet."""
    return skf_friction.one_case(fr, fa, n, nu, krs=KRS) * n * math.pi / 30


def solve_one(fr, fa, n, ta, a, b, g):
    """The steady temperature of one case [K], the library's bracketed Illinois iteration."""
    def f(t):
        nu = 10.0 ** (10.0 ** (a - b * math.log10(t))) - 0.7  # ASTM D341, mm^2/s
        return _power(fr, fa, n, nu) - g * (t - ta)

    lo, hi = ta, T_MAX
    f_lo, f_hi = f(lo), f(hi)
    if f_hi >= 0:
        return math.nan
    side = 0
    for k in range(1, _solve.THERMAL_MAX_ITER + 1):
        sec = hi - f_hi * (hi - lo) / (f_hi - f_lo) if f_hi != f_lo else math.nan
        x = 0.5 * (lo + hi) if (not lo < sec < hi) or k % 8 == 0 else sec
        fx = f(x)
        if fx > 0:
            lo, f_lo = x, fx
            if side == 1:
                f_hi *= 0.5
            side = 1
        else:
            hi, f_hi = x, fx
            if side == -1:
                f_lo *= 0.5
            side = -1
        if abs(fx) <= _solve.THERMAL_RTOL * abs(g * (x - ta)) or hi - lo <= _solve.THERMAL_XTOL:
            return x
    raise RuntimeError("not converged")


def baseline(fr, fa, rpm, ta):
    a, b = lubrication.walther_constants((313.15, 373.15), (NU40, NU100))
    g = float(thermal.reference_conductance(BEARING.bore, BEARING.outside_diameter, BEARING.width))
    return np.array([solve_one(*c, a, b, g) for c in zip(fr.tolist(), fa.tolist(), rpm.tolist(), ta.tolist(),
                                                          strict=True)])


def main(n_batch=N_BATCH, n_base=N_BASELINE, repeat=3):
    fr, fa, rpm, ta = cases(n_batch)
    t_batch, got = best_of(lambda: batched(fr, fa, rpm, ta), repeat)
    m = slice(0, min(n_base, n_batch))
    t_base, ref = best_of(lambda: baseline(fr[m], fa[m], rpm[m], ta[m]), repeat)
    rate, base_rate = n_batch / t_batch, len(ref) / t_base
    diff = float(np.nanmax(np.abs(got.temperature[m] - ref)))
    same_nan = bool(np.array_equal(np.isnan(got.temperature[m]), np.isnan(ref)))
    closes = float(np.nanmax(np.abs(got.friction_power / got.heat_dissipated - 1.0)))
    print(f"batched thermal_balance: {n_batch:>6d} cases in {t_batch:8.3f} s = {rate:12.4g} cases/s "
          f"({int(np.sum(~got.steady))} runaway)")
    print(f"per-case Python solve  : {len(ref):>6d} cases in {t_base:8.3f} s = {base_rate:12.4g} cases/s")
    print(f"max |T difference| case by case {diff:.1e} K; balance closes to {closes:.1e} (relative)")
    print(f"RESULT thermal cases_per_s={rate:.4g} baseline_cases_per_s={base_rate:.4g} ratio={rate / base_rate:.4g}")
    return 0 if diff < 1e-8 and same_nan and closes < 1e-9 else 1


if __name__ == "__main__":
    sys.exit(main())

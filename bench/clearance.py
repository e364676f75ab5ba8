"""Benchmark: a 10^6-sample Monte Carlo of the mounted-clearance chain vs a plain per-sample Python loop.

The batched path is :func:`bearinglab.mounting.monte_carlo.monte_carlo` (serial executor, seeded blocks)
for a 6208 on a k5 shaft in an N7 housing, ISO 5753-1 CN, inner ring 15 K warmer than the outer, an
aluminium housing, at 6000 rpm: every sample goes through the nonlinear chain (Lamé fits with the
clearance-fit cut-off, thermal growth, rotating-disc growth). The baseline is what an engineer would
write: the same equations per sample with plain ``math`` on Python floats (fairness rules of
BENCHMARKS.md), fed with the batched path's own sampled inputs; it excludes the sampling, so its rate is
if anything flattering. Every baseline sample is compared with the batched answer.
"""

from __future__ import annotations

import math
import sys

import numpy as np
from _timing import best_of

from bearinglab import catalog, internal_clearance
from bearinglab.mounting import chain, monte_carlo, tables

N_BATCH = 1_000_000
N_BASELINE = 100_000
T0 = chain.T_REF


def setup():
    b = catalog.get("6208") if _known("6208") else catalog.get("6205-2RS")
    d, big = b.bore, b.outside_diameter
    m = chain.mounting_of(b, housing_material="aluminium")
    lo, hi = internal_clearance.radial_clearance_range(d, "CN")
    shaft, bore = tables.field_limits("k5", d), tables.bore_limits(d)
    od, housing = tables.outside_diameter_limits(big), tables.field_limits("N7", big)
    limits = {"unmounted_clearance": (float(lo), float(hi)), "shaft": (float(shaft.lower), float(shaft.upper)),
              "bore": (float(bore.lower), float(bore.upper)), "outside_diameter": (float(od.lower), float(od.upper)),
              "housing": (float(housing.lower), float(housing.upper))}
    cond = chain.Conditions(T0 + 50.0, T0 + 35.0, speed=6000 * math.pi / 30)
    return m, limits, cond


def _known(name):
    try:
        catalog.get(name)
    except Exception:  # noqa: BLE001 -- the catalog of this checkout may not have it yet
        return False
    return True


def one_sample(e0, ii, io, m, c):
    """The chain of one sample in plain floats (the equations of bearinglab.mounting, written out)."""
    d, big, di, do, dw, d0 = m.bore, m.outside_diameter, m.inner_raceway, m.outer_raceway, m.ball_diameter, m.shaft_bore
    r, s, h = m.ring, m.shaft, m.housing
    ti, to = c.inner_temperature, c.outer_temperature
    tb, ts, th = 0.5 * (ti + to), ti, to
    ring_in = ((di * di + d * d) / (di * di - d * d) + r.poisson_ratio) / r.elastic_modulus
    shaft_c = ((d * d + d0 * d0) / (d * d - d0 * d0) - s.poisson_ratio) / s.elastic_modulus
    housing_c = (1.0 + h.poisson_ratio) / h.elastic_modulus  # thick housing
    ring_out = ((big * big + do * do) / (big * big - do * do) - r.poisson_ratio) / r.elastic_modulus

    def grow(i):
        p = max(i, 0.0) / (d * (ring_in + shaft_c))
        return 2 * p * d * d * di / (r.elastic_modulus * (di * di - d * d))

    def shrink(i):
        p = max(i, 0.0) / (big * (housing_c + ring_out))
        return 2 * p * big * big * do / (r.elastic_modulus * (big * big - do * do))

    fit = grow(ii) + shrink(io)
    a = r.thermal_expansion
    it = ii + (s.thermal_expansion * (ts - T0) - a * (ti - T0)) * d
    ot = io + (a * (to - T0) - h.thermal_expansion * (th - T0)) * big
    free = a * (ti - T0) * di + 2 * m.ball.thermal_expansion * (tb - T0) * dw - a * (to - T0) * do
    therm = free + grow(it) + shrink(ot) - fit
    w2, nu, rho, e = c.speed ** 2, r.poisson_ratio, r.density, r.elastic_modulus
    ra, rb = d / 2, di / 2
    ring_bore = 2 * rho * w2 * ra / (4 * e) * ((3 + nu) * rb * rb + (1 - nu) * ra * ra)
    nus = s.poisson_ratio
    seat = 2 * (1 - nus) * s.density * w2 * ra ** 3 / (4 * s.elastic_modulus)  # solid shaft
    raceway = 2 * rho * w2 * rb / (4 * e) * ((3 + nu) * ra * ra + (1 - nu) * rb * rb)
    cent = raceway + grow(it - (ring_bore - seat)) - grow(it)
    return e0 - fit - therm - cent


def measure(n_batch=N_BATCH, n_baseline=N_BASELINE, repeat=3):
    m, limits, cond = setup()
    t_batch, study = best_of(lambda: monte_carlo.monte_carlo(n_batch, 1, limits, m, cond), repeat)
    s = study.samples
    e0 = s["unmounted_clearance"][:n_baseline].tolist()
    ii = s["inner_interference"][:n_baseline].tolist()
    io = s["outer_interference"][:n_baseline].tolist()
    t_base, ref = best_of(lambda: [one_sample(a, b, c, m, cond) for a, b, c in zip(e0, ii, io, strict=True)],
                          repeat)
    diff = float(np.max(np.abs(s["operating_clearance"][:n_baseline] - np.array(ref))))
    return {"t_batch": t_batch, "t_base": t_base, "rate": n_batch / t_batch, "base_rate": n_baseline / t_base,
            "diff": diff, "p_negative": study.probability_preload, "n_batch": n_batch, "n_baseline": n_baseline}


def main():
    r = measure()
    print(f"batched Monte Carlo : {r['n_batch']:>8d} samples in {r['t_batch']:8.3f} s = {r['rate']:12.4g} samples/s")
    print(f"per-sample loop     : {r['n_baseline']:>8d} samples in {r['t_base']:8.3f} s = {r['base_rate']:12.4g} samples/s")
    print(f"max difference of the operating clearance, sample by sample: {r['diff']:.2e} m; "
          f"P(clearance < 0) = {r['p_negative']:.4f}")
    print(f"RESULT clearance_monte_carlo cases_per_s={r['rate']:.4g} baseline_cases_per_s={r['base_rate']:.4g} "
          f"ratio={r['rate'] / r['base_rate']:.4g} seconds_for_1e6={r['t_batch'] * 1e6 / r['n_batch']:.4g}")
    return 0 if r["diff"] < 1e-15 else 1


if __name__ == "__main__":
    sys.exit(main())

"""Benchmark: the EHL film of a 10 000-case map at speed, batched against a per-case plain-Python loop.

The map: B218 (16 balls), thrust 2-40 kN with a radial load of a fifth of it, inner-ring speed
1000-12 000 rpm, 100 x 100 cases, quasi-static ball loads at speed. The load distribution is solved once
by :func:`bearinglab.quasistatic.combined.combined_analysis` (its own benchmark is bench/combined.py);
its wall time and that of the whole :func:`bearinglab.film.film_analysis` are printed for reference.

Timed against each other is the film stage (:func:`bearinglab.film.distribution_films`: per contact
the radii, the exact Hertz ellipticity, the entrainment velocity, Hamrock and Dowson's films, Lambda,
the smallest film): batched over all cases and balls, and case by case in plain Python with ``math``
(the ellipticity by the library's algorithm: Newton in the elliptic parameter from the Hamrock-Brewe
start, rtol 1e-14, K and E by the arithmetic-geometric mean). Best of 3 each, in the same run; every
baseline case is compared with the batched answer.
"""

from __future__ import annotations

import math
import sys
import time

import numpy as np
from _timing import best_of

from bearinglab import catalog, film
from bearinglab.quasistatic.combined import combined_analysis
from bearinglab.units import RPM

N_SIDE = 100  # 100 x 100 = 10 000 cases
N_BASELINE = 2000
ETA, ALPHA, RQ = 0.01, 2e-8, 0.1e-6
B218 = catalog.get("B218")


def the_map(n_side=N_SIDE):
    fa = np.linspace(2e3, 40e3, n_side)
    n = np.linspace(1000.0, 12000.0, n_side) * RPM
    f, w = (x.ravel() for x in np.meshgrid(fa, n, indexing="ij"))
    loads = np.zeros((f.size, 5))
    loads[:, 0], loads[:, 2] = 0.2 * f, f
    return loads, w


def batched(ld, w):
    return film.distribution_films(ld, B218, w, ETA, ALPHA, roughness_ball=RQ, roughness_race=RQ)


def _ke(m):
    """K(m), E(m) by the arithmetic-geometric mean."""
    a, b, s, p = 1.0, math.sqrt(1.0 - m), 0.5 * m, 0.5
    for _ in range(40):  # quadratic convergence: a few steps; the last ulp may never close
        if abs(a - b) <= 4e-16 * a:
            break
        c = 0.5 * (a - b)
        a, b = 0.5 * (a + b), math.sqrt(a * b)
        p *= 2.0
        s += p * c * c
    k = math.pi / (2.0 * a)
    return k, k * (1.0 - s)


def _kappa(f_t):
    """Ellipticity from F by Newton in m with a bisection bracket (the library's algorithm)."""
    if f_t < 1e-5:
        return 1.0 / math.sqrt(1.0 - 8.0 * f_t / 3.0)
    k0 = 1.0339 * ((1.0 + f_t) / (1.0 - f_t)) ** 0.636
    m = min(max(1.0 - 1.0 / k0**2, 1e-12), 1.0 - 1e-16)
    lo, hi = 0.0, 1.0
    for _ in range(100):
        k, e = _ke(m)
        k2 = 1.0 / (1.0 - m)
        num, den = (k2 + 1.0) * e - 2.0 * k, (k2 - 1.0) * e
        r = num / den - f_t
        if r < 0:
            lo = max(lo, m)
        elif r > 0:
            hi = min(hi, m)
        dk, de, dk2 = (e - (1.0 - m) * k) / (2.0 * m * (1.0 - m)), (e - k) / (2.0 * m), k2 * k2
        dnum, dden = dk2 * e + (k2 + 1.0) * de - 2.0 * dk, dk2 * e + (k2 - 1.0) * de
        new = m - r / ((dnum * den - num * dden) / (den * den))
        if not lo <= new <= hi:
            new = 0.5 * (lo + hi)
        if abs(new - m) <= 1e-14 * m:
            m = new
            break
        m = new
    return 1.0 / math.sqrt(1.0 - m)


def one_case(qi, qo, ai, ao, w, d, dm, fi, fo, ep):
    """Smallest h_min [m] and Lambda of one case from its ball loads and angles, plain Python."""
    best = math.inf
    for j in range(len(qi)):
        beta = math.atan2(math.sin(ao[j]), math.cos(ao[j]) + d / dm)  # outer-raceway control
        gi, go = d * math.cos(ai[j]) / dm, d * math.cos(ao[j]) / dm
        ci, co = math.cos(ai[j] - beta), math.cos(ao[j] - beta)
        common = w * 0.5 * dm * (1.0 - gi) * (1.0 + go) / ((1.0 + go) * ci + (1.0 - gi) * co)
        for q, a, f, sign, u in ((qi[j], ai[j], fi, -1.0, common * ci), (qo[j], ao[j], fo, 1.0, common * co)):
            if q <= 0:
                continue
            rx = d * (dm + sign * d * math.cos(a)) / (2.0 * dm)
            ry = f * d / (2.0 * f - 1.0)
            k = _kappa((1.0 / rx - 1.0 / ry) / (1.0 / rx + 1.0 / ry))
            h = (3.63 * (ETA * u / (ep * rx)) ** 0.68 * (ALPHA * ep) ** 0.49 * (q / (ep * rx * rx)) ** -0.073
                 * (1.0 - math.exp(-0.68 * k)) * rx)
            best = min(best, h)
    return best, best / math.sqrt(2.0 * RQ * RQ)


def baseline(ld, w, n):
    b = B218
    args = (b.ball_diameter, b.pitch_diameter, b.inner_conformity, b.outer_conformity, b.reduced_modulus)
    rows = zip(ld.ball_load_inner[:n].tolist(), ld.ball_load_outer[:n].tolist(), ld.contact_angle_inner[:n].tolist(),
               ld.contact_angle_outer[:n].tolist(), w[:n].tolist(), strict=True)
    return np.array([one_case(*r, *args) for r in rows])


def main(n_side=N_SIDE, n_base=N_BASELINE, repeat=3):
    loads, w = the_map(n_side)
    start = time.perf_counter()
    ld = combined_analysis(B218, loads, w)
    t_ld = time.perf_counter() - start
    t_batch, got = best_of(lambda: batched(ld, w), repeat)
    n_base = min(n_base, len(w))
    t_base, ref = best_of(lambda: baseline(ld, w, n_base), repeat)
    n = len(w)
    rate, base_rate = n / t_batch, n_base / t_base
    diff = float(np.max(np.abs(got.minimum_film[:n_base] / ref[:, 0] - 1.0)))
    diff_lam = float(np.max(np.abs(got.minimum_film_parameter[:n_base] / ref[:, 1] - 1.0)))
    print(f"load distribution at speed (shared stage): {n:>6d} cases in {t_ld:8.3f} s")
    print(f"film stage, batched     : {n:>6d} cases in {t_batch:8.4f} s = {rate:12.4g} cases/s")
    print(f"film stage, per-case loop: {n_base:>5d} cases in {t_base:8.4f} s = {base_rate:12.4g} cases/s")
    print(f"whole film_analysis map : {t_ld + t_batch:8.3f} s; max relative difference h_min {diff:.1e}, "
          f"Lambda {diff_lam:.1e}")
    print(f"RESULT film cases_per_s={rate:.4g} baseline_cases_per_s={base_rate:.4g} ratio={rate / base_rate:.4g} "
          f"map_s={t_ld + t_batch:.4g}")
    return 0 if max(diff, diff_lam) < 1e-11 and bool(np.all(ld.converged)) else 1


if __name__ == "__main__":
    sys.exit(main())

r"""Compiled (numba) kernels: the compiled limit the benchmarks hold the batched numpy paths against.

Not part of the library: measured against the numpy path of
:func:`bearinglab.stand.operating_contact_angle` it was less than 3x faster on the 2-core project
machine (BENCHMARKS.md), so the library ships numpy only. numba comes from the ``bench`` extra; the
kernels are compiled on first use and cached on disk (``cache=True``).

Kernels
-------
available          whether numba can be imported here
solve_one          one case in plain Python (math): the fair scalar baseline
operating_angle    x0 of spec 000 eq. (3), then the Newton of section 6.3, one case per thread

The algorithm is the one of :func:`bearinglab.stand.operating_contact_angle`, element by element:
the same first approximation, the same increment, the same halving of a step that leaves
(alpha0, 90 deg), the same tolerances; a case stops as soon as it has converged (the numpy path
iterates every case until the last one has), so the two agree to the tolerance (checked by
bench/axial_angle.py and tests/test_bench_scripts.py).
"""

from __future__ import annotations

import math

import numpy as np

_KERNEL = None
_AVAILABLE = None


def available():
    """True if numba imports here (the fast path can be used)."""
    global _AVAILABLE
    if _AVAILABLE is None:
        try:
            import numba  # noqa: F401
        except ImportError:  # the bench extra is not installed: the scripts skip the compiled limit
            _AVAILABLE = False
        else:
            _AVAILABLE = True
    return _AVAILABLE


def solve_one(fa, cs, a0, xtol, ftol_percent, max_iter):
    """One case: (alpha [rad], iterations; -iterations if not converged, last 1/ratio - 1)."""
    s, c = math.sin(a0), math.cos(a0)
    t = fa / cs
    root = math.sqrt(1.0 + (2.0 / 3.0) * (6.0 + c * c) / (s * s) * (t / s) ** (2.0 / 3.0))  # eq. (3)
    alpha = min(a0 + 3.0 * s * c / (6.0 + c * c) * (root - 1.0), 0.5 * (a0 + math.pi / 2))
    ratio = 1.0
    for it in range(1, max_iter + 1):
        ca, sa = math.cos(alpha), math.sin(alpha)
        gap = c - ca
        q = gap / ca
        ratio = fa / (cs * q * math.sqrt(q) * sa)  # eq. (1)
        tan = sa / ca
        dx = ((ratio * ratio) ** (1.0 / 3.0) - 1.0) / (tan + (2.0 / 3.0) / tan + sa / gap)  # section 6.3
        new = alpha + dx
        if new <= a0:  # a step out of (alpha0, 90 deg) is halved toward the boundary
            new = 0.5 * (alpha + a0)
        elif new >= math.pi / 2:
            new = 0.5 * (alpha + math.pi / 2)
        alpha = new
        if abs(dx) < xtol or abs(ratio - 1.0) * 100.0 < ftol_percent:
            return alpha, it, 0.0
    return alpha, -max_iter, 1.0 / ratio - 1.0


def _build():
    import numba

    one = numba.njit(cache=True, fastmath=False)(solve_one)

    @numba.njit(parallel=True, cache=True)
    def kernel(fa, cs, a0, xtol, ftol_percent, max_iter, alpha, iterations, residual):
        for k in numba.prange(fa.size):
            alpha[k], iterations[k], residual[k] = one(fa[k], cs[k], a0[k], xtol, ftol_percent, max_iter)

    return kernel


def operating_angle(fa, cs, a0, xtol, ftol_percent, max_iter):
    """Solve flat float arrays of equal size; returns (alpha, iterations, residual) per case.

    ``iterations`` is negative for a case that did not converge in ``max_iter`` iterations.
    """
    global _KERNEL
    if _KERNEL is None:
        _KERNEL = _build()
    n = fa.size
    alpha, iterations, residual = np.empty(n), np.empty(n, dtype=np.int64), np.empty(n)
    _KERNEL(fa, cs, a0, float(xtol), float(ftol_percent), int(max_iter), alpha, iterations, residual)
    return alpha, iterations, residual

r"""The compiled fast path of the test-stand solve (spec 000 section 6.3), in blocks of cases over the threads.

The same operations, case by case, as the numpy path of :func:`bearinglab.stand.operating_contact_angle`:

- the start (``stand.method._gap_start``): Halley's iteration on eq. (1) squared, a polynomial in the gap
  y = cos alpha0 - cos alpha, from the smaller root of its two leading-order truncations, each case
  stopping after its own step below the start's tolerance;
- the load test of section 6.3 at the start (``stand.method._start_test``), then alpha (``stand.method._angle_of``:
  arcsin(sin alpha) below 45 deg, arccos(cos alpha) above);
- for a case that fails the test, the Newton of section 6.3 (``stand.method._section_newton``) with its halving
  of a step that leaves (alpha0, 90 deg) and its convergence test.

A thread advances a block of ``_LANES`` cases together, so that the cases' chains of dependent divisions
interleave and the arithmetic loops (Halley's steps, the load test) compile to vector instructions; the
cube root and the arc sine or cosine are calls to the C library. numpy may call its own SIMD versions
(AVX-512 hosts), which round differently, so the angles are the numpy path's to 4 ulp, bit for bit where
both round alike (tests/test_stand_compiled.py checks the ulps and the convergence flags case by case). Each case is independent of the others, so the result does not depend on
the batch or the chunk it is solved in. Nothing here is public: ``stand.operating_contact_angle`` calls
:func:`solve` when its ``engine`` allows it. This module imports numba, and is imported only then.

Functions
---------
solve    flat arrays of loads, C* and free angles (scalars for one bearing): (alpha, iterations, residual,
         number not converged)

References
----------
.. [1] V. A. Zaitsev and V. A. Voronkin, "Calculation of axial loads and operating contact angles of
   rolling bearings when assessing their quality on test stands," 2009 (spec 000 of this project).
.. [2] E. Halley, "Methodus nova accurata & facilis inveniendi radices aequationum quarumcumque
   generaliter, sine praevia reductione," Phil. Trans. R. Soc., vol. 18, pp. 136-148, 1694,
   doi:10.1098/rstl.1694.0029.
"""

from __future__ import annotations

import math

import numba
import numpy as np

from .. import _numba, _solve
from ._gap import _SQRT_HALF, _gap_step

__all__ = ["solve"]

_LANES = 256  # cases a thread advances together (its arrays stay in the L1 cache)
_HALF_PI = math.pi / 2
# error_model="numpy": a division by zero gives inf or nan as in numpy, with no check that would keep the
# loops from vectorizing. numba's on-disk cache is keyed on this file only: a change to stand._gap._gap_step or
# _SQRT_HALF needs the cache cleared (tests/test_stand_compiled.py compares the engines to a few ulp).
_step = numba.njit(inline="always", error_model="numpy")(_gap_step)


@numba.njit(cache=True, error_model="numpy")
def _section_newton(fa, cs, a0, c, alpha, xtol, ftol_percent, max_iter):
    """The Newton of section 6.3 for one case from ``alpha``: (alpha, iterations, residual); not converged:
    iterations -max_iter (-1 for max_iter = 0) and the residual 1/ratio - 1 of the last step."""
    ratio = math.nan
    for it in range(1, max_iter + 1):
        ca, sa = math.cos(alpha), math.sin(alpha)
        gap = c - ca
        q = gap / ca
        ratio = fa / (cs * q * math.sqrt(q) * sa)  # F_a / F_a,k, eq. (1)
        tan = sa / ca
        dx = (np.cbrt(ratio * ratio) - 1.0) / (tan + (2.0 / 3.0) / tan + sa / gap)
        new = alpha + dx
        if new <= a0:  # a step out of (alpha0, 90 deg) is halved toward the boundary
            new = 0.5 * (alpha + a0)
        if new >= _HALF_PI:
            new = 0.5 * (alpha + _HALF_PI)
        alpha = new
        if abs(dx) < xtol or abs(ratio - 1.0) * 100.0 < ftol_percent:
            return alpha, it, 0.0
    return alpha, -max(max_iter, 1), 1.0 / ratio - 1.0


@numba.njit(parallel=True, cache=True, error_model="numpy")
def _kernel(fa, cs, a0, c, s, xtol, ftol_percent, max_iter, start_rtol, start_max_iter, alpha, iterations,
            residual, bad):
    """Solve all cases into ``alpha``; ``iterations`` and ``residual`` (zeros on entry) are written only for
    the cases that fail the load test at the start; ``bad[block]``: the block's cases that did not converge."""
    n = alpha.size
    # a value shared by all cases (one bearing) is an array of one element: index 0 for every case
    i_fa, i_cs, i_a0 = int(fa.size > 1), int(cs.size > 1), int(a0.size > 1)
    for blk in numba.prange((n + _LANES - 1) // _LANES):
        lo = blk * _LANES
        m = min(_LANES, n - lo)
        # the block's per-case values in contiguous arrays, so that the loops below compile to vector code
        t, tt, cb, s2, y, q = np.empty(m), np.empty(m), np.empty(m), np.empty(m), np.empty(m), np.empty(m)
        live = np.empty(m, dtype=np.bool_)
        n_cbrt = 0
        for j in range(m):  # the start (stand.method._gap_start): the smaller root of the two truncations of P(y)
            k = lo + j
            tj = fa[i_fa * k] / cs[i_cs * k]
            ck, sk = c[i_a0 * k], s[i_a0 * k]
            t[j], tt[j], cb[j], s2[j] = tj, tj * tj, ck, sk * sk
            q[j] = tj * tj / (sk * sk)
            arg = tj * (ck * _SQRT_HALF)
            small_angle = math.sqrt(arg)
            y[j] = small_angle
            small_load = ck * ck * ck * q[j] < small_angle * arg  # the cube root only where it is the smaller
            live[j] = small_load
            n_cbrt += small_load
        if n_cbrt:
            for j in range(m):  # a call to the C library: apart from the vector loops
                if live[j]:
                    y[j] = cb[j] * np.cbrt(q[j])
        for j in range(m):
            y[j] = min(y[j], cb[j])
            live[j] = True
        for _ in range(start_max_iter):  # Halley's steps, branch-free over the block
            n_live = 0  # an integer count: a floating-point sum would keep the loop from vectorizing
            for j in range(m):
                yj = y[j]
                dy = _step(yj, cb[j], s2[j], tt[j])
                on = live[j]
                new = yj - dy if on else yj
                y[j] = new
                on = on and abs(dy) > start_rtol * new
                live[j] = on
                n_live += on
            if n_live == 0:
                break
        n_fail = 0
        for j in range(m):  # the load test of section 6.3 at the start (stand.method._start_test)
            ck = cb[j]
            yj = y[j]
            u = ck - yj
            w = s2[j] + (2.0 * ck - yj) * yj
            qj = yj / u
            ratio = t[j] / (qj * math.sqrt(qj * w))
            fail = not abs(ratio - 1.0) * 100.0 < ftol_percent
            live[j] = fail
            n_fail += fail
            y[j] = u  # from here on: cos alpha and sin^2 alpha
            q[j] = w
        for j in range(m):  # stand.method._angle_of, a call to the C library
            alpha[lo + j] = math.asin(math.sqrt(q[j])) if y[j] > _SQRT_HALF else math.acos(y[j])
        n_bad = 0
        if n_fail:  # the cases that fail the test (none among the loads tried) take the Newton of section 6.3
            for j in range(m):
                if live[j]:
                    k = lo + j
                    fk, csk, a0k, ck = fa[i_fa * k], cs[i_cs * k], a0[i_a0 * k], c[i_a0 * k]
                    a = alpha[k] if alpha[k] < _HALF_PI else 0.5 * (a0k + _HALF_PI)
                    alpha[k], iterations[k], residual[k] = _section_newton(fk, csk, a0k, ck, a, xtol, ftol_percent,
                                                                           max_iter)
                    n_bad += iterations[k] < 0
        bad[blk] = n_bad  # a count per block (a reduction over prange would need its own care)


# numba's default (workqueue) threading layer aborts the process on concurrent launches of parallel kernels:
# this kernel takes the lock of the high-speed kernel, so that no two of them run at once
_LOCK = _numba.LOCK


def solve(fa, cs, a0, n, xtol, ftol_percent, max_iter):
    """``n`` cases (flat arrays of size n, or 0-d for a value shared by all): (alpha, iterations, residual,
    the number of cases that did not converge).

    ``iterations`` is the number of Newton steps of section 6.3 (0 where the start passed the load test),
    negative (``-max_iter``, -1 for max_iter = 0) for a case that did not converge, whose ``residual`` is 1/ratio - 1 of its last
    step (0 elsewhere). cos alpha0 and sin alpha0 are taken by numpy, once per bearing.
    """
    c, s = np.cos(a0), np.sin(a0)
    # contiguous arrays of n elements, or of one for a value shared by all cases: one compiled signature
    args = [np.ascontiguousarray(np.reshape(x, -1), dtype=float) for x in (fa, cs, a0, c, s)]
    alpha, iterations, residual = np.empty(n), np.zeros(n, dtype=np.int64), np.zeros(n)
    bad = np.zeros((n + _LANES - 1) // _LANES, dtype=np.int64)
    with _LOCK:
        _kernel(*args, float(xtol), float(ftol_percent), int(max_iter), float(_solve.AXIAL_ANGLE_START_RTOL),
                int(_solve.AXIAL_ANGLE_START_MAX_ITER), alpha, iterations, residual, bad)
    return alpha, iterations, residual, int(bad.sum())

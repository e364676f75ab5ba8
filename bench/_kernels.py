r"""The test-stand solve (spec 000 section 6) one case at a time: the fair scalar baseline and the compiled limit.

Not part of the library: :func:`bearinglab.stand.operating_contact_angle` is the batched numpy path, and
measured against it this kernel was less than 3x faster on the 2-core project machine (BENCHMARKS.md), so
the library ships numpy only for this solve. The kernel is compiled on first use and cached on disk
(``cache=True``).

Kernels
-------
available          whether numba can be imported here
solve_one          one case in plain Python (math): the fair scalar baseline
operating_angle    the same per-case algorithm compiled by numba, blocks of cases over the threads (prange)

The algorithm is the one of :func:`bearinglab.stand.operating_contact_angle`, operation by operation:
the start of ``stand._gap_start`` (Newton on eq. (1) squared, a polynomial in the gap
y = cos alpha0 - cos alpha, each case stopping on its own test), then the Newton of section 6.3 with the
same halving of a step that leaves (alpha0, 90 deg) and the same convergence test. With the same libm
(cbrt, not pow, for the cube roots) the compiled kernel gives the numpy path's angles bit for bit on
this machine; bench/axial_angle.py and tests/test_bench_scripts.py check them to 1e-12 rad.
"""

from __future__ import annotations

import math

import numpy as np

from bearinglab import _solve
from bearinglab.stand import _gap_step

_KERNEL = None
_AVAILABLE = None
_HALF_PI = math.pi / 2
_START_RTOL, _START_MAX_ITER = _solve.AXIAL_ANGLE_START_RTOL, _solve.AXIAL_ANGLE_START_MAX_ITER
_cbrt = math.cbrt  # the same libm cube root as np.cbrt (numba knows only np.cbrt)


def available():
    """True if numba imports here (the compiled limit can be measured)."""
    global _AVAILABLE
    if _AVAILABLE is None:
        try:
            import numba  # noqa: F401
        except ImportError:  # the scripts skip the compiled limit
            _AVAILABLE = False
        else:
            _AVAILABLE = True
    return _AVAILABLE


def solve_one(fa, cs, a0, c, s, xtol, ftol_percent, max_iter):
    """One case: (alpha [rad], Newton iterations; -max_iter if not converged, last 1/ratio - 1).

    ``c``, ``s``: cos alpha0 and sin alpha0, taken once per bearing (as the batched path does).
    """
    s2 = s * s
    t = fa / cs
    tt = t * t
    y = min(c * _cbrt(tt / s2), c)  # the start: Newton on P(y) of eq. (1) squared, from above
    for _ in range(_START_MAX_ITER):
        dy = _gap_step(y, c, s2, tt)
        y = y - dy
        if not abs(dy) > _START_RTOL * y:
            break
    alpha = math.acos(c - y)
    if not alpha < _HALF_PI:
        alpha = 0.5 * (a0 + _HALF_PI)
    ratio = 1.0
    for it in range(1, max_iter + 1):  # the Newton of section 6.3
        ca, sa = math.cos(alpha), math.sin(alpha)
        gap = c - ca
        q = gap / ca
        ratio = fa / (cs * q * math.sqrt(q) * sa)  # eq. (1)
        tan = sa / ca
        dx = (_cbrt(ratio * ratio) - 1.0) / (tan + (2.0 / 3.0) / tan + sa / gap)
        new = alpha + dx
        if new <= a0:  # a step out of (alpha0, 90 deg) is halved toward the boundary
            new = 0.5 * (alpha + a0)
        elif new >= _HALF_PI:
            new = 0.5 * (alpha + _HALF_PI)
        alpha = new
        if abs(dx) < xtol or abs(ratio - 1.0) * 100.0 < ftol_percent:
            return alpha, it, 0.0
    return alpha, -max_iter, 1.0 / ratio - 1.0


_LANES = 512  # cases a thread advances together (its arrays stay in the L1/L2 cache)


def _build():
    import numba

    step = numba.njit(inline="always")(_gap_step)

    @numba.njit(parallel=True, cache=True)
    def kernel(fa, cs, a0, c, s, xtol, ftol_percent, max_iter, alpha, iterations, residual):
        # Each thread takes blocks of _LANES cases and advances them together, each case stopping on its own
        # test: the same operations per case as solve_one, but the cases' chains of dependent divisions
        # interleave (one case alone waits on each division; a block keeps the pipeline full).
        n = fa.size
        for blk in numba.prange((n + _LANES - 1) // _LANES):
            lo = blk * _LANES
            m = min(_LANES, n - lo)
            y = np.empty(m)
            tt = np.empty(m)
            live = np.ones(m, dtype=np.bool_)
            for j in range(m):
                k = lo + j
                t = fa[k] / cs[k]
                tt[j] = t * t
                y[j] = min(c[k] * np.cbrt(tt[j] / (s[k] * s[k])), c[k])
            for _ in range(_START_MAX_ITER):  # the start, branch-free over the block
                n_live = 0
                for j in range(m):
                    k = lo + j
                    yj = y[j]
                    dy = step(yj, c[k], s[k] * s[k], tt[j])
                    new = yj - dy
                    on = live[j]
                    y[j] = new if on else yj
                    on = on and abs(dy) > _START_RTOL * new
                    live[j] = on
                    n_live += on
                if n_live == 0:
                    break
            for j in range(m):
                k = lo + j
                a = math.acos(c[k] - y[j])
                alpha[k] = a if a < _HALF_PI else 0.5 * (a0[k] + _HALF_PI)
                live[j] = True
                iterations[k] = -max_iter
            for it in range(1, max_iter + 1):  # the Newton of section 6.3
                n_live = 0
                for j in range(m):
                    if live[j]:
                        k = lo + j
                        a = alpha[k]
                        ca, sa = math.cos(a), math.sin(a)
                        gap = c[k] - ca
                        q = gap / ca
                        ratio = fa[k] / (cs[k] * q * math.sqrt(q) * sa)  # eq. (1)
                        tan = sa / ca
                        dx = (np.cbrt(ratio * ratio) - 1.0) / (tan + (2.0 / 3.0) / tan + sa / gap)
                        new = a + dx
                        if new <= a0[k]:
                            new = 0.5 * (a + a0[k])
                        elif new >= _HALF_PI:
                            new = 0.5 * (a + _HALF_PI)
                        alpha[k] = new
                        residual[k] = 1.0 / ratio - 1.0
                        if abs(dx) < xtol or abs(ratio - 1.0) * 100.0 < ftol_percent:
                            live[j] = False
                            iterations[k] = it
                            residual[k] = 0.0
                        else:
                            n_live += 1
                if n_live == 0:
                    break

    return kernel


def operating_angle(fa, cs, a0, xtol, ftol_percent, max_iter):
    """Solve flat float arrays of equal size (``np.broadcast_to`` views are fine); (alpha, iterations, residual).

    ``iterations`` is negative for a case that did not converge in ``max_iter`` iterations. cos alpha0 and
    sin alpha0 are taken by numpy on ``a0`` as given (once per bearing for a broadcast view).
    """
    global _KERNEL
    if _KERNEL is None:
        _KERNEL = _build()
    n = fa.size
    alpha, iterations, residual = np.empty(n), np.empty(n, dtype=np.int64), np.empty(n)
    if n and a0.strides[0] == 0:  # one bearing (a broadcast view): its cosine and sine once
        c, s = np.broadcast_to(math.cos(a0[0]), n), np.broadcast_to(math.sin(a0[0]), n)
    else:
        c, s = np.cos(a0), np.sin(a0)
    _KERNEL(fa, cs, a0, c, s, float(xtol), float(ftol_percent), int(max_iter), alpha, iterations, residual)
    return alpha, iterations, residual

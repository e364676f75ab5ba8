r"""The test-stand solve (spec 000 section 6) one case at a time in plain Python: the fair scalar baseline.

Not part of the library. :func:`bearinglab.stand.operating_contact_angle` is the shipped path: by default
(``engine="auto"``, large batches) the compiled kernel of ``bearinglab.stand._compiled``, otherwise the
batched numpy path (``engine="numpy"``, the tested fallback).

Kernels
-------
available          whether numba can be imported here (the compiled engine can run)
solve_one          one case in plain Python (math): the fair scalar baseline

The algorithm is the library's, operation by operation: the start of ``stand.method._gap_start`` (Halley's
iteration on eq. (1) squared, a polynomial in the gap y = cos alpha0 - cos alpha, from the smaller root of
its two leading-order truncations, the cube root taken only where it is the smaller; each case stopping on
its own test), the load test of section 6.3 at the start (``stand.method._start_test``), and for a case that fails
it the Newton of section 6.3 (the compiled kernel's ``_section_newton`` run as plain Python). With the same libm (cbrt, not pow, for the cube roots) it gives the library's angles to a
few ulp (bit for bit where numpy does not use its own SIMD functions, which round differently on AVX-512
hosts); bench/axial_angle.py and tests/test_bench_scripts.py check them to 1e-12 rad and 4 ulp.
"""

from __future__ import annotations

import math

from bearinglab import _solve
from bearinglab.stand._gap import _SQRT_HALF, _gap_step

_AVAILABLE = None
_HALF_PI = math.pi / 2
_START_RTOL, _START_MAX_ITER = _solve.AXIAL_ANGLE_START_RTOL, _solve.AXIAL_ANGLE_START_MAX_ITER
_cbrt = math.cbrt  # the same libm cube root as np.cbrt


def available():
    """True if numba imports here (the compiled engine can be measured)."""
    global _AVAILABLE
    if _AVAILABLE is None:
        try:
            import numba  # noqa: F401
        except ImportError:  # the scripts skip the compiled engine
            _AVAILABLE = False
        else:
            _AVAILABLE = True
    return _AVAILABLE


def solve_one(fa, cs, a0, c, s, xtol, ftol_percent, max_iter):
    """One case: (alpha [rad], Newton iterations of section 6.3 (0: the start passed the load test);
    -max_iter (-1 for max_iter = 0) if not converged, last 1/ratio - 1).

    ``c``, ``s``: cos alpha0 and sin alpha0, taken once per bearing (as the batched path does).
    """
    s2 = s * s
    t = fa / cs
    tt = t * t
    q = tt / s2
    arg = t * (c * _SQRT_HALF)
    y = math.sqrt(arg)  # the start: the smaller root of the two truncations of P(y)
    if c * c * c * q < y * arg:  # compared as cubes: the cube root only where it is the smaller
        y = c * _cbrt(q)
    y = min(y, c)
    for _ in range(_START_MAX_ITER):  # Halley's steps on P(y) of eq. (1) squared
        dy = _gap_step(y, c, s2, tt)
        y = y - dy
        if not abs(dy) > _START_RTOL * y:
            break
    u = c - y  # the load test of section 6.3 at the start
    w = s2 + (2.0 * c - y) * y
    q = y / u if u else math.inf
    ratio = t / (q * math.sqrt(q * w)) if q > 0.0 else math.nan
    alpha = math.asin(math.sqrt(w)) if u > _SQRT_HALF else math.acos(u)  # stand.method._angle_of
    if abs(ratio - 1.0) * 100.0 < ftol_percent:
        return alpha, 0, 0.0
    if not alpha < _HALF_PI:
        alpha = 0.5 * (a0 + _HALF_PI)
    # The Newton of section 6.3, for a case that fails the load test (none of the bench's loads does, so
    # it is never timed): the compiled kernel's scalar source, run by CPython (its np.cbrt is the libm
    # cube root of math.cbrt, so the bits are the same).
    from bearinglab.stand import _compiled as _stand_compiled

    return _stand_compiled._section_newton.py_func(fa, cs, a0, c, alpha, xtol, ftol_percent, max_iter)

"""Scalar helpers shared by the per-case kernels of bench/ (plain Python, or compiled by numba).

Functions
---------
scalar_helpers   ``(cheb, gauss5)`` wrapped by a ``jit`` (identity for plain Python, numba.njit)
"""

from __future__ import annotations

import math

__all__ = ["scalar_helpers"]


def scalar_helpers(jit):
    """Clenshaw's sum of a Chebyshev series and a 5 x 5 Gaussian elimination, each wrapped by ``jit``."""

    @jit
    def cheb(c, x):
        """Sum of the Chebyshev series ``c`` at x (Clenshaw's recurrence)."""
        b1 = 0.0
        b2 = 0.0
        for j in range(len(c) - 1, 0, -1):
            b1, b2 = c[j] + 2.0 * x * b1 - b2, b1
        return c[0] + x * b1 - b2

    @jit
    def gauss5(a, b):
        """x (a 5-tuple) with a x = b; a flat row-major 5 x 5, partial pivoting; NaN if singular."""
        m = [0.0] * 30
        for i in range(5):
            for j in range(5):
                m[6 * i + j] = a[5 * i + j]
            m[6 * i + 5] = b[i]
        for c in range(5):
            p = c
            for r in range(c + 1, 5):
                if abs(m[6 * r + c]) > abs(m[6 * p + c]):
                    p = r
            if m[6 * p + c] == 0.0:
                return (math.nan, math.nan, math.nan, math.nan, math.nan)
            if p != c:
                for k in range(6):
                    m[6 * c + k], m[6 * p + k] = m[6 * p + k], m[6 * c + k]
            for r in range(c + 1, 5):
                f = m[6 * r + c] / m[6 * c + c]
                for k in range(c, 6):
                    m[6 * r + k] -= f * m[6 * c + k]
        x = [0.0] * 5
        for r in range(4, -1, -1):
            s = m[6 * r + 5]
            for k in range(r + 1, 5):
                s -= m[6 * r + k] * x[k]
            x[r] = s / m[6 * r + r]
        return (x[0], x[1], x[2], x[3], x[4])

    return cheb, gauss5

"""Halley's step on the test stand's gap polynomial, shared by the numpy path and the compiled kernel.

Kept apart from :mod:`bearinglab.stand.method` so that the compiled kernel (:mod:`bearinglab.stand._compiled`)
takes the same arithmetic without importing the method that imports it.

Functions
---------
_gap_step    Halley's step 2 P P' / (2 P'^2 - P P'') on the polynomial in the gap y = cos alpha0 - cos alpha
"""

from __future__ import annotations

import math

__all__: list = []

_SQRT_HALF = math.sqrt(0.5)


def _gap_step(y, cos_a0, sin2_a0, thrust_ratio2):
    """Halley's step 2 P P' / (2 P'^2 - P P'') on P(y) of :func:`_gap_start`, for floats or arrays (arithmetic)."""
    u = cos_a0 - y
    y2 = y * y
    y3 = y2 * y
    w = sin2_a0 + (2.0 * cos_a0 - y) * y  # 1 - u^2 = sin^2 alpha
    tu = thrust_ratio2 * u
    tu2 = tu * u
    p = y3 * w - tu2 * u
    p1 = 3.0 * y2 * w + 2.0 * y3 * u + 3.0 * tu2
    p2 = 6.0 * y * w + 12.0 * y2 * u - 2.0 * y3 - 6.0 * tu
    return 2.0 * p * p1 / (2.0 * p1 * p1 - p * p2)

"""Spec 000's axial displacement delta_a checked by value (the worked example of section 7).

delta_a = xi_a * xi * d (section 6.1: xi_a = delta_a / (xi d), tan alpha = tan alpha0 + xi_a / cos alpha0),
with xi d = r_v + r_n - d the distance between the groove centres. The reference value is computed
here from the spec's inputs and its converged angle (section 8: 14 deg 28' 03.38"), not through the
library.
"""

import math

import pytest

from bearinglab import catalog, stand
from bearinglab.units import KGF

# spec 000 section 7: r_v = 1.05 mm, r_n = 1.16 mm, d = 2 mm, alpha0 = 12 deg; section 8: converged angle
GROOVE_DISTANCE = (1.05 + 1.16 - 2.0) * 1e-3  # xi d [m]
ALPHA0 = math.radians(12.0)
ALPHA = math.radians(14 + 28 / 60 + 3.38 / 3600)


def test_axial_displacement_of_the_worked_example():
    r = stand.stand_analysis(catalog.get("4-1006095"), 2 * KGF, hertz="table", elastic_constant="paper")
    expected = GROOVE_DISTANCE * math.cos(ALPHA0) * (math.tan(ALPHA) - math.tan(ALPHA0))
    # the angle is printed to 0.01 arc second (4.8e-8 rad): d(delta_a)/d(alpha) = 0.22 mm/rad -> 1.1e-11 m
    assert float(r.axial_displacement) == pytest.approx(expected, abs=2e-11)  # 9.3376 um


def test_axial_displacement_is_the_ratio_times_the_groove_distance():
    r = stand.stand_analysis(catalog.get("4-1006095"), [0.5 * KGF, 5 * KGF], hertz="exact")
    for fa_angle, got in zip(r.contact_angle, r.axial_displacement, strict=True):
        ratio = math.cos(ALPHA0) * (math.tan(fa_angle) - math.tan(ALPHA0))
        assert got == pytest.approx(ratio * GROOVE_DISTANCE, rel=1e-12)

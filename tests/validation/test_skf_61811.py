"""SKF four-term model against a measured frictional moment (issue 12).

A pair of SKF 61811-2RS1 (55 x 72 x 9 mm, d_m = 63.5 mm, series 618: R1 = 4.7e-7, S1 = 6.5e-3;
RS1 contact seals on d_s = 59.5 mm), grease lubricated, base-oil viscosity 30 mm^2/s, Fr = 6.51 N per
bearing, 2000 rpm, was measured at 0.387 +- 0.025 N m for the pair. The model must land in that band.
"""

import math

import pytest

from bearinglab import catalog, friction

MEASURED, SPREAD = 0.387, 0.025  # N m, the pair
N = 2000 * 2 * math.pi / 60


def test_pair_inside_measured_band():
    one = friction.skf(6.51, 0.0, N, 30e-6, 55e-3, 72e-3, series="618", lubrication="grease", seal="RS1",
                       seals=2, seal_diameter=59.5e-3)
    assert MEASURED - SPREAD <= 2 * one.total_moment <= MEASURED + SPREAD


def test_catalog_entry_gives_the_same():
    via = friction.skf_for_bearing(catalog.get("61811-2RS1"), 6.51, 0.0, N, 30e-6)
    direct = friction.skf(6.51, 0.0, N, 30e-6, 55e-3, 72e-3, series="618", seal="RS1", seal_diameter=59.5e-3)
    assert via.total_moment == pytest.approx(direct.total_moment, rel=1e-15)
    assert via.seal_moment > 0.9 * via.total_moment  # at this light load the two contact seals dominate

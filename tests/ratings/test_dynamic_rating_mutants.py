"""Tests that kill surviving mutants of bearinglab.ratings.dynamic found by `make mutants` (TESTING.md)."""

import pytest

from bearinglab.ratings import dynamic


@pytest.mark.parametrize("dw_mm", [25.5, 26.0, 26.4])
def test_large_balls_scale_with_dw_to_the_power_1_4_just_above_25_4_mm(dw_mm):
    """ISO 281 eq. (2): C ~ 3.647 Dw^1.4 above Dw = 25.4 mm. With Dpw scaled with Dw, f_c stays the same,
    so C(Dw) / C(30 mm) is (Dw / 30)^1.4 exactly; a limit moved above 25.4 mm breaks it."""
    def rating(dw):
        return dynamic.dynamic_load_rating(12, dw * 1e-3, 5.0 * dw * 1e-3, 0.0)

    assert rating(dw_mm) / rating(30.0) == pytest.approx((dw_mm / 30.0) ** 1.4, rel=1e-12)


def test_small_balls_scale_with_dw_to_the_power_1_8_up_to_25_4_mm():
    def rating(dw):
        return dynamic.dynamic_load_rating(12, dw * 1e-3, 5.0 * dw * 1e-3, 0.0)

    assert rating(25.4) / rating(10.0) == pytest.approx((25.4 / 10.0) ** 1.8, rel=1e-12)

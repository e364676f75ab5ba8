"""The life of a system of bearings: Lundberg and Palmgren's rule with the Weibull slopes of ISO 281."""

import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from bearinglab import catalog
from bearinglab.errors import InputError
from bearinglab.life import system_life, weibull_slope


def test_two_equal_ball_bearings_live_two_to_the_minus_nine_tenths_as_long():
    assert system_life([1000.0, 1000.0]) == pytest.approx(1000.0 * 2 ** (-0.9), rel=1e-15)


@given(lives=st.lists(st.floats(1.0, 1e9), min_size=1, max_size=6),
       slopes=st.lists(st.sampled_from([10 / 9, 9 / 8]), min_size=6, max_size=6))
def test_the_system_survives_with_the_reliability_of_each_bearing_at_its_life(lives, slopes):
    e = np.array(slopes[:len(lives)])
    life = system_life(lives, e)
    # S_sys(L) = prod S_i(L) = 0.9^(sum (L/L_i)^e_i) = 0.9 at the system's life
    assert np.sum((life / np.array(lives)) ** e) == pytest.approx(1.0, rel=1e-10)
    assert life <= min(lives) * (1 + 1e-12)


def test_a_bearing_that_carries_nothing_does_not_shorten_the_system():
    assert system_life([5000.0, math.inf]) == pytest.approx(5000.0, rel=1e-14)
    assert system_life([math.inf, math.inf]) == math.inf


def test_slopes_of_ball_and_roller_bearings():
    assert weibull_slope(catalog.get("6206")) == 10 / 9
    assert weibull_slope(type("CylindricalRollerBearing", (), {})()) == 9 / 8
    with pytest.raises(InputError, match="lives must be > 0"):
        system_life([0.0, 1.0])

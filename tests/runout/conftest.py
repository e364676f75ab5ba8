"""Fixtures of the runout tests: the reference geometry of spec 003 (section 2)."""

import math

import pytest

from bearinglab import runout as R


@pytest.fixture(scope="module")
def g():
    """The reference geometry: 16 balls of 7.144 mm on 54 mm pitch, f_o 0.53, f_i 0.52, 15 deg."""
    return R.geometry_from_catalog(16, 7.144e-3, 54e-3, 0.53, 0.52, math.radians(15))

"""Tests written for the survivors of the sixth mutation run (TESTING.md, "Sixth run").

Each pins a contract the other mounting tests left open: the error messages of the Lamé and smoothing
input checks name the parameter and the unit, the fit interference of arbitrary tolerance fields
(ISO 492 bores always have an upper deviation of 0, which hid a sign error), no numerical warning
for the unbounded housing, and float results from the rotating disc.
"""

import math
import warnings

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from bearinglab.errors import InputError
from bearinglab.mounting import centrifugal, fits, lame
from bearinglab.mounting.tables import Limits

E, NU = 2.075e11, 0.3

INNER = {"interference": 20e-6, "bore": 0.05, "ring_diameter": 0.06, "shaft_bore": 0.0,
         "ring_modulus": E, "ring_poisson": NU, "shaft_modulus": E, "shaft_poisson": NU}
OUTER = {"interference": 20e-6, "outside_diameter": 0.09, "ring_diameter": 0.08,
         "housing_outside_diameter": math.inf, "ring_modulus": E, "ring_poisson": NU,
         "housing_modulus": E, "housing_poisson": NU}


@pytest.mark.parametrize(("name", "value", "rule"), [
    ("bore", 0.0, "> 0"), ("ring_diameter", -0.06, "> 0"), ("shaft_bore", -0.01, ">= 0"),
])
def test_inner_fit_checks_name_parameter_and_unit(name, value, rule):
    with pytest.raises(InputError, match=rf"^{name} must be {rule} \[m\], got"):
        lame.fit_pressure_inner(**{**INNER, name: value})


@pytest.mark.parametrize(("name", "value"), [
    ("outside_diameter", 0.0), ("ring_diameter", -0.08), ("housing_outside_diameter", 0.0),
])
def test_outer_fit_checks_name_parameter_and_unit(name, value):
    with pytest.raises(InputError, match=rf"^{name} must be > 0 \[m\], got"):
        lame.fit_pressure_outer(**{**OUTER, name: value})


@pytest.mark.parametrize("which", ["roughness_a", "roughness_b"])
def test_smoothing_checks_name_parameter_and_unit(which):
    args = {"roughness_a": 1e-6, "roughness_b": 1e-6, which: -1e-6}
    with pytest.raises(InputError, match=rf"^{which} must be >= 0 \[m\], got"):
        fits.smoothing(**args)


limits = st.tuples(st.floats(-60e-6, 60e-6), st.floats(0.0, 60e-6)).map(
    lambda t: Limits(np.float64(t[0]), np.float64(t[0] + t[1])))


@given(a=limits, b=limits)
def test_interference_of_any_fields_is_the_extreme_differences(a, b):
    """least / largest = the smallest / largest a - b over the corners of the two fields."""
    corners = [x - y for x in (a.lower, a.upper) for y in (b.lower, b.upper)]
    for got in (fits.inner_interference(a, b), fits.outer_interference(a, b)):
        assert got.least == pytest.approx(min(corners), abs=1e-18)
        assert got.largest == pytest.approx(max(corners), abs=1e-18)


def test_unbounded_housing_raises_no_numerical_warning():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        p = lame.fit_pressure_outer(**OUTER)
    assert p > 0


def test_disc_growth_returns_floats():
    g = centrifugal.disc_growth(np.array([500.0, 1000.0]), 0.05, 0.06, np.array([0.05, 0.06]), 7850.0,
                                E, NU)
    assert g.dtype == np.float64
    assert isinstance(centrifugal.disc_growth(1000.0, 0.05, 0.06, 0.06, 7850.0, E, NU), np.float64)

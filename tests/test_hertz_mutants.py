"""Tests that kill surviving mutants of bearinglab.hertz found by `make mutants` (TESTING.md).

Each reference value is computed here from the formula of the docstring, independently of the module.
"""

import math

import numpy as np
import pytest

from bearinglab import hertz


def test_tabulated_coefficients_keep_the_shape_and_leave_the_semi_axes_undefined():
    c = hertz.tabulated(np.array([0.63, 0.852]))
    np.testing.assert_array_equal(c.delta_star, [0.63, 0.852])
    for field in (c.ellipticity, c.a_star, c.b_star):
        assert np.shape(field) == (2,) and np.all(np.isnan(field))


def test_approach_coefficient_uses_the_coefficients_it_is_given():
    d, s, ep = 7.144e-3, 350.0, 2.28e11
    got = hertz.approach_coefficient(d, s, 0.9, ep, hertz=hertz.tabulated(0.63))
    expected = 0.63 * (d * s) ** (1 / 3) * (3.0 / ep) ** (2 / 3) / 2.0  # c = delta* (D sum rho)^1/3 c_E
    assert got == pytest.approx(expected, rel=1e-14)
    exact = hertz.approach_coefficient(d, s, 0.9, ep)
    assert not math.isclose(exact, expected, rel_tol=1e-3)  # the exact delta* at F(rho) = 0.9 is not 0.63


@pytest.mark.parametrize("arg,match", [
    ({"curvature_sum": -1.0}, r"curvature_sum must be > 0 \[1/m\], got -1\.0"),
    ({"reduced_modulus": 0.0}, r"reduced_modulus must be > 0 \[Pa\], got 0\.0"),
    ({"ball_diameter": -2e-3}, r"ball_diameter must be > 0 \[m\]"),
])
def test_approach_coefficient_names_the_bad_input_and_its_unit(arg, match):
    kwargs = {"ball_diameter": 7.144e-3, "curvature_sum": 350.0, "curvature_difference": 0.9,
              "reduced_modulus": 2.28e11} | arg
    with pytest.raises(ValueError, match=match):
        hertz.approach_coefficient(**kwargs)

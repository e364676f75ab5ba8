"""Manufacturing errors of spec 003 section 3 (``runout.deviations``): Fourier series, roundness fits,
input checks."""

import numpy as np
import pytest
from numpy.testing import assert_allclose

from bearinglab import runout as R
from bearinglab.errors import InputError


def test_roundness_profile_fit(g):
    rng = np.random.default_rng(3)
    th = np.sort(rng.uniform(0, 2 * np.pi, 50))  # uneven spacing
    true = R.fourier_series({0: 0.1, 1: 0.5, 4: -0.2}, {2: 0.3, 4: 0.05})
    dev = R.evaluate_series(true, th)
    fit = R.roundness_coefficients(th, dev, 6)
    assert_allclose(fit.cos, np.r_[true.cos, 0, 0], atol=1e-12)
    assert_allclose(fit.sin, np.r_[true.sin, 0, 0], atol=1e-12)
    with pytest.raises(InputError, match="max_order must be <="):
        R.roundness_coefficients(th[:7], dev[:7], 4)
    with pytest.raises(InputError, match="one value per angle"):
        R.roundness_coefficients(th, dev[:-1], 3)


def test_fourier_series_input_checks():
    assert_allclose(R.fourier_series({"2": 1.0}).cos, [0, 0, 1])
    with pytest.raises(InputError, match="whole number >= 0"):
        R.fourier_series({-1: 1.0})
    with pytest.raises(InputError, match="whole number >= 0"):
        R.fourier_series({"1.5": 1.0})
    with pytest.raises(InputError, match="must be finite"):
        R.fourier_series({1: float("inf")})


def test_manufacturing_errors_checks():
    with pytest.raises(InputError, match="one value per ball"):
        R.manufacturing_errors(16, ball_diameter_deviation=np.zeros(15))
    with pytest.raises(InputError, match="not both"):
        R.manufacturing_errors(
            3, ball_diameter_deviation=np.zeros(3), ball_outer_deficit=np.zeros(3)
        )
    with pytest.raises(InputError, match="tilt_x must be finite"):
        R.manufacturing_errors(3, tilt_x=float("nan"))
    with pytest.raises(InputError, match="RacewayErrors"):
        R.manufacturing_errors(3, inner={"radial": 1})

"""Calibration tables of the friction lab (bearinglab.lab.calibration): checks, piecewise-linear conversion."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from numpy.testing import assert_allclose

from bearinglab.errors import InputError
from bearinglab.lab import calibration

FAST = settings(max_examples=40, deadline=None)


def test_calibration_table_checks():
    with pytest.raises(InputError, match="needs at least 2 points, got 1") as exc:
        calibration.calibration_table([0.0], [0.0], name="speed")
    assert exc.value.point is None
    with pytest.raises(
        InputError,
        match=r"values must be strictly increasing .* point 3 \(reading 20\) has 0.5 after 0.5",
    ) as exc:
        calibration.calibration_table(
            [0, 10, 20], [0.0, 0.5, 0.5], name="torque position 1", unit="N*m"
        )
    assert exc.value.point == 2
    with pytest.raises(InputError, match=r"readings must be strictly increasing .* point 2") as exc:
        calibration.calibration_table([0, 0, 20], [0.0, 0.5, 0.7])
    assert exc.value.point == 1
    with pytest.raises(InputError, match="3 readings but 2 values"):
        calibration.calibration_table([0, 1, 2], [0, 1])
    with pytest.raises(InputError, match="values must be finite"):
        calibration.calibration_table([0, 1], [0, float("nan")])


def test_piecewise_linear_conversion_without_extrapolation():
    t = calibration.calibration_table([0, 10, 20, 30], [0.0, 455.0, 920.0, 1395.0], name="speed")
    assert (
        calibration.convert(0.0, t) == 0.0 and calibration.convert(30.0, t) == 1395.0
    )  # table ends are valid
    assert calibration.convert(15.0, t) == pytest.approx(687.5, rel=1e-15)
    assert_allclose(calibration.convert([5.0, 25.0], t), [227.5, 1157.5], rtol=1e-15)
    # spec 001 section 10.3: a reading of 101 with a 0-100 table is an error
    t100 = calibration.calibration_table([0, 100], [0.0, 1.0], name="torque position 2")
    with pytest.raises(
        InputError, match=r"torque position 2 reading must be in \[0, 100\] .*got 101\.0"
    ):
        calibration.convert(101.0, t100)
    with pytest.raises(InputError, match=r"got -0\.5 \(1 of 2 values\)"):
        calibration.convert([1.0, -0.5], t100)


@FAST
@given(a=st.floats(0.0, 1.0), k=st.integers(0, 9))
def test_conversion_is_linear_between_points_and_monotonic(a, k):
    readings = np.arange(0.0, 101.0, 10.0)
    values = np.array([0, 455, 920, 1395, 1880, 2375, 2880, 3395, 3920, 4455, 5000.0])
    t = calibration.calibration_table(readings, values)
    r = readings[k] + a * 10.0
    assert calibration.convert(r, t) == pytest.approx(
        values[k] + a * (values[k + 1] - values[k]), rel=1e-12, abs=1e-12
    )
    assert calibration.convert(min(r + 0.1, 100.0), t) >= calibration.convert(r, t)


def test_convert_torque_by_switch_position():
    t1 = calibration.calibration_table([0, 100], [0.0, 1.2e-4], name="torque position 1")
    t2 = calibration.calibration_table([0, 100], [0.0, 5.0e-4], name="torque position 2")
    cal = calibration.Calibration(None, {1: t1, 2: t2})
    assert_allclose(
        calibration.convert_torque([50.0, 50.0, 100.0], [1, 2, 1], cal),
        [6e-5, 2.5e-4, 1.2e-4],
        rtol=1e-15,
    )
    with pytest.raises(InputError, match=r"switch position must be 1 or 2 \[-\], got 3\.0"):
        calibration.convert_torque(10.0, 3, cal)
    with pytest.raises(InputError, match="need the torque calibration table of position 2"):
        calibration.convert_torque(10.0, 2, calibration.Calibration(None, {1: t1}))

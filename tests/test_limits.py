"""The plausibility limits of bearinglab.limits (issue 15 item 6)."""

import math

import pytest

from bearinglab import catalog, limits, quasistatic
from bearinglab.units import RPM


def test_pressure_limit_is_iso76():
    assert limits.contact_pressure_warnings([4.2e9]) == []
    assert "4300 MPa" in limits.contact_pressure_warnings([4.3e9])[0]


def test_truncation_edge_is_the_shoulder_angle():
    # h = r (1 - cos 60 deg): the edge is at 60 deg; a contact reaching 59.9 deg passes, 60.1 deg warns
    r = 10e-3
    h = r * (1 - math.cos(math.radians(60)))
    assert limits.truncation_warnings(math.radians(50), r * math.radians(9.9), r, h) == []
    assert limits.truncation_warnings(math.radians(50), r * math.radians(10.1), r, h)


def test_viscosity_ratio_below_tenth_warns():
    assert limits.viscosity_ratio_warnings([0.1, 1.0]) == []
    assert "0.05" in limits.viscosity_ratio_warnings([0.05])[0]


def test_catalog_shoulder_heights_are_used(tmp_path):
    b = catalog.get("B218")
    s = quasistatic.high_speed_analysis(b, 20e3, 15000 * RPM)
    low = b.replace(inner_shoulder_height=0.1 * b.ball_diameter, contact_angle=b.contact_angle)
    msgs = limits.high_speed_warnings(low, s)
    assert any("inner contact: the contact ellipse" in m and "assumed" not in m for m in msgs)


def test_shoulder_above_the_groove_centre_rejected():
    b = catalog.get("B218")
    with pytest.raises(ValueError, match="inner_shoulder_height must be <"):
        b.replace(inner_shoulder_height=b.ball_diameter, contact_angle=b.contact_angle)

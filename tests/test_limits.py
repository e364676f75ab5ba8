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


def test_combined_warnings_of_a_pure_thrust_equal_those_under_thrust():
    """Under a pure thrust every ball carries F_a / (Z sin alpha): the combined-load checks (per ball, P0 from
    F_r and F_a) must say what the thrust checks say, case for case."""
    b = catalog.get("7218B")
    alpha, fa = math.radians(40.0), 400e3
    q = fa / (b.n_balls * math.sin(alpha))
    thrust = limits.contact_warnings(b, [fa], [q], [q], [alpha], [alpha])
    balls = [q] * b.n_balls
    combined = limits.combined_warnings(b, [0.0, 0.0, fa, 0.0, 0.0], balls, balls, [alpha] * b.n_balls,
                                        [alpha] * b.n_balls)
    assert thrust and [m.split("(")[0] for m in combined] == [m.split("(")[0] for m in thrust]
    assert any("ISO 76" in m for m in combined) and any("C0" in m for m in combined)


def test_combined_warnings_skip_unloaded_balls_and_light_loads():
    b = catalog.get("7218B")
    z = b.n_balls
    q = [100.0] + [0.0] * (z - 1)
    assert limits.combined_warnings(b, [100.0, 0, 0, 0, 0], q, q, [0.7] + [math.nan] * (z - 1), [0.7] * z) == []


def test_combined_warnings_count_loaded_balls_and_can_leave_out_p0():
    # the counts name what they count (balls here, cases under thrust), and static=False leaves the P0
    # check to a caller that reports the static safety itself (the life analysis)
    b = catalog.get("7218B")
    alpha, fa = math.radians(40.0), 400e3
    q = [fa / (b.n_balls * math.sin(alpha))] * b.n_balls
    args = (b, [0.0, 0.0, fa, 0.0, 0.0], q, q, [alpha] * b.n_balls, [alpha] * b.n_balls)
    full, no_p0 = limits.combined_warnings(*args), limits.combined_warnings(*args, static=False)
    assert [m for m in full if "C0" in m] and not [m for m in no_p0 if "C0" in m]
    assert no_p0 == [m for m in full if "C0" not in m]
    assert all(f"{b.n_balls} of {b.n_balls} loaded balls" in m for m in no_p0)
    assert "(1 of 1 case(s)" in next(m for m in full if "C0" in m)
    thrust = limits.contact_warnings(b, [fa], q[:1], q[:1], [alpha], [alpha])
    assert thrust and all("1 of 1 case(s)" in m for m in thrust)


def test_static_check_needs_a_c0_and_an_iso76_angle():
    b = catalog.get("4-1006095")  # 12 deg: no X0, Y0 in ISO 76 table 1 for angular contact
    q = [50.0] * b.n_balls
    warned = limits.combined_warnings(b, [0.0, 0.0, 1e6, 0.0, 0.0], q, q, [0.3] * b.n_balls, [0.3] * b.n_balls)
    assert not [m for m in warned if "C0" in m]
    from bearinglab.bearing import BallBearing

    bare = BallBearing(designation="bare", type="radial", contact_angle=0.0)  # no ball set, no C0
    assert limits._static_checks(bare, 1e9, 0.0) == []
    rated = BallBearing(designation="rated", type="radial", contact_angle=0.0, static_load_rating=1e3)
    assert "C0 = 1 kN" in limits._static_checks(rated, 2e3, 0.0)[0]

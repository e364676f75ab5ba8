"""The Newton continuation of the high-speed model (spec 004 section 5.1): the zero-speed limit, path
independence, scalar/array agreement, the axial stiffness, several bearings in one call."""


import numpy as np
import pytest
from b218_cases import B218, GEO, _solve
from numpy.testing import assert_allclose

from bearinglab import bearing, kinematics, quasistatic, static
from bearinglab.units import RPM


# --------------------------------------------------------------------------- limits, consistency
@pytest.mark.parametrize("ball_material", [bearing.STEEL, bearing.SILICON_NITRIDE], ids=["steel", "Si3N4"])
def test_zero_speed_limit_is_the_static_solution(ball_material):
    """At n = 0 (and as n -> 0) both angles equal the static angle of the test-stand method to 1e-9 rad."""
    b = B218.replace(ball_material=ball_material, contact_angle=B218.contact_angle)
    fa = np.geomspace(10.0, 1e5, 25)
    ref = static.contact_angle_under_thrust(fa, *quasistatic._bearing_args(b)[:7])
    for n_rpm in (0.0, 1e-3):
        s = quasistatic.high_speed_analysis(b, fa, n_rpm * RPM)
        assert np.all(s.converged)
        assert np.abs(s.contact_angle_inner - ref.contact_angle).max() < 1e-9
        assert np.abs(s.contact_angle_outer - ref.contact_angle).max() < 1e-9
        assert_allclose(s.static_contact_angle, ref.contact_angle, rtol=0, atol=1e-15)
        assert_allclose(s.axial_displacement, ref.axial_displacement, rtol=1e-9)
        assert_allclose(s.ball_load_inner, ref.ball_load, rtol=1e-9)
    zero = quasistatic.high_speed_analysis(b, fa, 0.0)
    assert np.all(zero.centrifugal_force == 0) and np.all(zero.gyroscopic_moment == 0)
    assert np.all(zero.method == "static")


def test_continuation_path_does_not_change_the_solution():
    fa = np.array([200.0, 2.5e3, 10e3, 45e3])[:, None]
    n = np.array([1000.0, 6000.0, 15000.0, 30000.0])
    a = _solve(fa, n)
    b = _solve(fa, n, speed_step=1500 * RPM, max_iter=400)
    for name in ("contact_angle_inner", "contact_angle_outer"):
        assert np.abs(getattr(a, name) - getattr(b, name)).max() < 1e-10


def test_scalar_and_array_results_agree():
    fa, n = np.array([5e3, 20e3]), np.array([6000.0, 15000.0])
    arr = _solve(fa[:, None], n[None, :])
    assert arr.contact_angle_inner.shape == (2, 2)
    one = _solve(20e3, 6000.0)
    assert np.ndim(one.contact_angle_inner) == 0 and isinstance(one.status, str)
    for name in ("contact_angle_inner", "contact_angle_outer", "axial_displacement", "gyroscopic_moment"):
        assert getattr(one, name) == pytest.approx(getattr(arr, name)[1, 0], rel=1e-12, abs=1e-18)


@pytest.mark.parametrize("n", [0.0, 6000.0, 15000.0])
def test_axial_stiffness_is_the_slope_of_the_displacement(n):
    fa, h = 20e3, 1.0
    s = _solve(np.array([fa - h, fa, fa + h]), n)
    slope = (2 * h) / (s.axial_displacement[2] - s.axial_displacement[0])
    assert s.axial_stiffness[1] == pytest.approx(slope, rel=1e-6)
    assert s.axial_stiffness[1] > 0


def test_characteristic_frequencies_at_speed():
    s = _solve(20e3, 10000.0)
    z = GEO[0]
    assert s.bpfo == pytest.approx(z * s.cage_speed, rel=1e-14)
    assert s.bpfi == pytest.approx(z * (10000 * RPM - s.cage_speed), rel=1e-14)
    # the operating angles move the cage speed away from the pure-rolling value at the static angle
    nominal = kinematics.cage_speed(10000 * RPM, GEO[1], GEO[2], s.static_contact_angle)
    assert abs(s.cage_speed / nominal - 1) > 1e-3


def test_free_angle_is_not_the_reference_of_the_increments():
    """Section 8: with alpha0 instead of alpha_s the claim "alpha_e < alpha0" is false at high thrust and
    low speed (45 kN, 3000 rpm: alpha_e = 42.30 deg > 40 deg), while alpha_e < alpha_s holds."""
    s = _solve(45e3, 3000.0)
    assert s.contact_angle_outer > GEO[5]
    assert s.contact_angle_outer < s.static_contact_angle


def test_several_bearings_in_one_call():
    """Geometry broadcasts too: two ball sizes (and so two Hertz tables) in one batched solve."""
    z, d, dm, fi, fo, a0, ep, rho = GEO
    balls = np.array([d, 0.8 * d])[:, None]
    both = quasistatic.contact_angles(np.array([5e3, 20e3]), 10000 * RPM, z, balls, dm, fi, fo, a0, ep, rho)
    assert both.contact_angle_inner.shape == (2, 2)
    for k in range(2):
        one = quasistatic.contact_angles(np.array([5e3, 20e3]), 10000 * RPM, z, balls[k, 0], dm, fi, fo, a0, ep, rho)
        assert_allclose(both.contact_angle_inner[k], one.contact_angle_inner, rtol=0, atol=1e-13)
        assert_allclose(both.axial_stiffness[k], one.axial_stiffness, rtol=1e-10)
    assert np.all(both.contact_angle_outer[1] > both.contact_angle_outer[0])  # lighter balls, less spread

"""Geometry of roller bearings: tapered-roller angles, slices, profiles (bearinglab.rollers.geometry)."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from bearinglab.errors import InputError
from bearinglab.rollers import geometry


@settings(deadline=None)
@given(alpha=st.floats(math.radians(5.0), math.radians(30.0)), d=st.floats(3e-3, 30e-3),
       ratio=st.floats(0.08, 0.3))
def test_tapered_cones_share_one_apex_on_the_bearing_axis(alpha, d, ratio):
    # independent of the closed form: build the roller from its axis and half angle, then check that the cup line,
    # the cone line and the roller axis cross the bearing axis at one point
    dpw = d / ratio
    a = geometry.tapered_angles(alpha, d, dpw)
    axis = a.roller_axis_angle
    ell = 0.5 * dpw / math.sin(axis)  # middle of the roller from the apex along its axis
    # the apex is at z = 0 on the axis, the roller middle at (r, z) = (dpw/2, ell cos(axis))
    z_mid = ell * math.cos(axis)
    for line_angle, sign in ((a.cup_angle, 1.0), (a.cone_angle, -1.0)):
        # the generatrix touches the roller cone: it passes through the middle of the roller displaced by the
        # roller radius perpendicular to the axis, with the angle of the line to the bearing axis
        nr, nz = math.cos(axis), -math.sin(axis)  # unit normal to the roller axis in the (r, z) plane
        r0, z0 = 0.5 * dpw + sign * 0.5 * d * nr, z_mid + sign * 0.5 * d * nz
        z_at_axis = z0 - r0 / math.tan(line_angle)
        assert z_at_axis == pytest.approx(0.0, abs=1e-9 * ell)
    assert a.cup_angle - a.cone_angle == pytest.approx(2.0 * a.roller_angle, rel=1e-12)


def test_tapered_angle_above_45_deg_is_refused_naming_the_field():
    with pytest.raises(InputError, match=r"^contact_angle must be in \(0, 45\]"):
        geometry.tapered_angles(math.radians(46.0), 10e-3, 60e-3)


def test_slices_cover_the_length_evenly():
    s = geometry.slice_positions(12e-3, 30)
    assert len(s) == 30
    assert np.diff(s) == pytest.approx(np.full(29, 12e-3 / 30))
    assert s[0] == pytest.approx(-s[-1]) and s[0] - 0.2e-3 == pytest.approx(-6e-3)


def test_logarithmic_profile_is_iso_ts_16281s():
    # eq. (42) typed out again: 0.00035 D ln(1 / (1 - (2x/L)^2)) for L <= 2.5 D
    x, length, d = np.array([0.0, 2e-3, 4.5e-3]), 10e-3, 10e-3
    want = 0.00035 * d * np.log(1.0 / (1.0 - (2 * x / length) ** 2))
    assert geometry.logarithmic_drop(x, length, d) == pytest.approx(want, rel=1e-12, abs=0)
    assert geometry.logarithmic_drop(x, length, d, tapered=True) == pytest.approx(want * 0.00045 / 0.00035, rel=1e-12)


def test_long_roller_profile_is_flat_in_the_middle_and_continuous():
    length, d = 40e-3, 10e-3  # L > 2.5 D: end zones of 1.25 D
    x = np.linspace(-19.9e-3, 19.9e-3, 399)
    p = geometry.logarithmic_drop(x, length, d)
    assert np.all(p[np.abs(x) <= 7.5e-3] == 0)
    assert np.all(p[np.abs(x) > 7.6e-3] > 0)
    assert np.all(np.diff(p[x >= 0]) >= 0)  # rises towards the end


def test_crowned_profile_reaches_its_drop_at_the_ends():
    length, h = 10e-3, 8e-6
    x = np.array([-4.999999e-3, 0.0, 2.5e-3])
    p = geometry.crowned_drop(x, length, h)
    radius = ((length / 2) ** 2 + h**2) / (2 * h)
    assert p == pytest.approx(radius - np.sqrt(radius**2 - x**2), rel=1e-9)
    assert p[0] == pytest.approx(h, rel=1e-5)


def test_flat_profile_with_edge_radius():
    p = geometry.flat_drop([0.0, 4.4e-3, 4.9e-3], 10e-3, edge_radius=1e-3, edge_length=0.5e-3)
    assert p[0] == 0 and p[1] == 0
    assert p[2] == pytest.approx(1e-3 - math.sqrt(1e-6 - 0.4e-3**2), rel=1e-12)


def test_table_profile_interpolates_and_refuses_what_it_does_not_cover():
    t = [[-5e-3, 10e-6], [0.0, 0.0], [5e-3, 10e-6]]
    assert geometry.table_drop(2.5e-3, t) == pytest.approx(5e-6)
    with pytest.raises(InputError, match="^profile table must cover"):
        geometry.table_drop(6e-3, t)
    with pytest.raises(InputError, match="^profile drop must be >= 0"):
        geometry.table_drop(0.0, [[-5e-3, -1e-6], [5e-3, 0.0]])

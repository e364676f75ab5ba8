"""RollerBearing: checked on creation, one InputError line naming the field (issue 32 item 8)."""

import math

import pytest

from bearinglab.errors import InputError
from bearinglab.rollers import RollerBearing


def one_line(exc):
    msg = str(exc.value)
    assert "\n" not in msg
    return msg


def test_a_roller_longer_than_the_ring_is_wide():
    with pytest.raises(InputError) as exc:
        RollerBearing("cylindrical", 14, 11e-3, 19e-3, 60.5e-3, width=18e-3)
    assert one_line(exc).startswith("roller_length must be <= the ring width 18 mm")


def test_a_negative_profile_drop():
    with pytest.raises(InputError) as exc:
        RollerBearing("cylindrical", 14, 11e-3, 9.6e-3, 60.5e-3, profile="crowned", crown_drop=-2e-6)
    assert one_line(exc).startswith("crown_drop must be >= 0")
    with pytest.raises(InputError) as exc:
        RollerBearing("cylindrical", 14, 11e-3, 9.6e-3, 60.5e-3, profile=[[-5e-3, 1e-6], [5e-3, -1e-6]])
    assert one_line(exc).startswith("profile drop must be >= 0")


def test_a_cup_angle_over_45_deg():
    with pytest.raises(InputError) as exc:
        RollerBearing("tapered", 17, 10e-3, 14e-3, 60e-3, math.radians(47.0))
    assert one_line(exc).startswith("contact_angle must be in (0, 45] [deg]")


@pytest.mark.parametrize("kw, field", [
    ({"rollers": 40}, "rollers must be <= "),
    ({"rollers": 2}, "rollers must be an integer >= 3"),
    ({"design": "NF"}, "design must be one of"),
    ({"pitch_diameter": 10e-3}, "pitch_diameter must be > roller_diameter"),
    ({"bore": 52e-3}, "pitch_diameter - roller_diameter must be > bore"),
    ({"radial_clearance": 12e-3}, "radial_clearance must be in"),
    ({"profile": "barrel"}, "profile must be one of"),
    ({"profile": "crowned"}, "crown_drop is needed"),
    ({"contact_angle": 0.1}, "contact_angle must be 0 [deg] for a cylindrical"),
])
def test_each_bad_field_is_named(kw, field):
    base = {"type": "cylindrical", "rollers": 14, "roller_diameter": 11e-3, "roller_length": 9.6e-3,
            "pitch_diameter": 60.5e-3}
    with pytest.raises(InputError) as exc:
        RollerBearing(**{**base, **kw})
    assert one_line(exc).startswith(field)


def test_profiles_and_derived_quantities():
    b = RollerBearing("cylindrical", 14, 11e-3, 9.6e-3, 60.5e-3, profile=[[-4.8e-3, 6e-6], [4.8e-3, 6e-6]],
                      bore=40e-3, outside_diameter=80e-3)
    assert b.profile_drop(0.0) == pytest.approx(6e-6)
    assert b.mean_diameter == pytest.approx(60e-3) and b.design == "NU" and b.rows == 1
    s = RollerBearing("spherical", dynamic_load_rating=96.5e3)
    assert s.rows == 2 and s.design == "double" and not s.has_internal_geometry
    with pytest.raises(InputError, match="^roller_length of 'this spherical roller bearing' is not known"):
        s.require("roller_length")

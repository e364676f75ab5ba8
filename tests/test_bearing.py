"""Tests of bearinglab.bearing: materials, the frozen BallBearing, derived quantities, validation."""

import dataclasses
import math

import pytest

from bearinglab import geometry, hertz
from bearinglab.bearing import MATERIALS, SILICON_NITRIDE, STEEL, BallBearing, Material
from bearinglab.errors import InputError


@pytest.fixture
def example():
    """Bearing 4-1006095 of spec 000 section 7, from its groove radii."""
    return BallBearing.from_groove_radii(
        7,
        2e-3,
        8.7355e-3,
        1.05e-3,
        1.16e-3,
        contact_angle=math.radians(12),
        designation="4-1006095",
        bore=5e-3,
        outside_diameter=13e-3,
        width=4e-3,
    )


def test_derived_quantities_of_the_example(example):
    b = example
    assert b.inner_conformity == pytest.approx(0.525, rel=1e-15)
    assert b.outer_conformity == pytest.approx(0.58, rel=1e-15)
    assert b.total_curvature == pytest.approx(0.105, rel=1e-13)  # spec 000 section 7: xi = 0.105
    assert b.groove_distance == pytest.approx(0.21e-3, rel=1e-13)  # A = B D
    assert b.gamma == pytest.approx(2 * math.cos(math.radians(12)) / 8.7355, rel=1e-15)
    assert f"{b.radial_clearance * 1e6:.3f}" == "9.178"  # spec 000 section 4
    assert b.inner_groove_radius == pytest.approx(1.05e-3, rel=1e-15)
    assert b.outer_groove_radius == pytest.approx(1.16e-3, rel=1e-15)
    assert b.mean_diameter == pytest.approx(9e-3, rel=1e-15)
    assert b.ball_mass == pytest.approx(7850 * math.pi * 8e-9 / 6, rel=1e-15)
    assert b.axial_play() == pytest.approx(2 * 0.21e-3 * math.sin(math.radians(12)), rel=1e-13)
    assert b.free_contact_angle_052() == pytest.approx(math.radians(19.50), abs=math.radians(0.005))


def test_methods_pass_fields_to_the_functions(example):
    b = example
    for race, f in (("inner", b.inner_conformity), ("outer", b.outer_conformity)):
        assert b.curvature(race) == geometry.raceway_curvature(
            2e-3, 8.7355e-3, f, math.radians(12), race=race
        )
        assert b.curvature(race, 0.3) == geometry.raceway_curvature(
            2e-3, 8.7355e-3, f, 0.3, race=race
        )
    assert b.groove_centres() == geometry.groove_centre_diameters(
        2e-3, 8.7355e-3, b.inner_conformity, b.outer_conformity, math.radians(12)
    )
    assert b.reduced_modulus == pytest.approx(
        float(hertz.reduced_modulus(2.075e11, 0.3, 2.075e11, 0.3))
    )


def test_clearance_gives_the_angle_and_back(example):
    b = BallBearing(7, 2e-3, 8.7355e-3, 0.525, 0.58, radial_clearance=example.radial_clearance)
    assert b.contact_angle == pytest.approx(math.radians(12), rel=1e-12)
    # replace re-derives the other one
    c = example.replace(contact_angle=math.radians(20))
    assert c.radial_clearance == pytest.approx(
        geometry.radial_clearance(math.radians(20), 2e-3, 0.525, 0.58)
    )
    d = example.replace(radial_clearance=20e-6)
    assert d.contact_angle == pytest.approx(geometry.free_contact_angle(20e-6, 2e-3, 0.525, 0.58))
    assert example.contact_angle == pytest.approx(math.radians(12))  # the original is unchanged


def test_frozen_and_comparable(example):
    with pytest.raises(dataclasses.FrozenInstanceError):
        example.n_balls = 8
    twin = BallBearing.from_groove_radii(
        7,
        2e-3,
        8.7355e-3,
        1.05e-3,
        1.16e-3,
        contact_angle=math.radians(12),
        designation="4-1006095",
        bore=5e-3,
        outside_diameter=13e-3,
        width=4e-3,
    )
    assert twin == example


def test_zero_angle_keeps_clearance_unknown():
    b = BallBearing(9, 7.94e-3, 39.04e-3, 0.52, 0.52, contact_angle=0.0)
    assert b.radial_clearance is None and b.gamma == pytest.approx(7.94 / 39.04)


def test_partial_bearing_and_require():
    b = BallBearing(
        pitch_diameter=9e-3, bore=5e-3, outside_diameter=13e-3, designation="1000095", type="radial"
    )
    assert b.require("pitch_diameter") == 9e-3
    assert b.require("bore", "outside_diameter") == (5e-3, 13e-3)
    with pytest.raises(InputError, match=r"n_balls of '1000095' is not known; give it"):
        b.require("pitch_diameter", "n_balls")
    with pytest.raises(InputError, match=r"ball_diameter of '1000095' is not known"):
        _ = b.ball_mass
    with pytest.raises(InputError, match=r"inner_conformity of 'this bearing' is not known.*usually 0.515 to 0.53"):
        _ = BallBearing().total_curvature


def test_materials():
    assert (
        MATERIALS["steel"] is STEEL
        and MATERIALS["silicon_nitride"] is MATERIALS["si3n4"] is SILICON_NITRIDE
    )
    assert (STEEL.elastic_modulus, STEEL.poisson_ratio, STEEL.density) == (2.075e11, 0.3, 7850.0)
    hybrid = BallBearing(
        9, 7.94e-3, 39.04e-3, 0.52, 0.52, contact_angle=0.0, ball_material=SILICON_NITRIDE
    )
    assert hybrid.ball_mass == pytest.approx(3200 * math.pi * 7.94e-3**3 / 6, rel=1e-15)
    assert hybrid.reduced_modulus == pytest.approx(
        2 / ((1 - 0.26**2) / 3.1e11 + 0.91 / 2.075e11), rel=1e-14
    )
    assert (
        hybrid.reduced_modulus
        > BallBearing(9, 7.94e-3, 39.04e-3, 0.52, 0.52, contact_angle=0.0).reduced_modulus
    )


@pytest.mark.parametrize(
    "kw, match",
    [
        ({"elastic_modulus": 0.0}, r"elastic_modulus must be > 0 \[Pa\], got 0.0"),
        ({"poisson_ratio": 0.5}, r"poisson_ratio must be in \(-1, 0.5\) \[-\], got 0.5"),
        ({"density": -1.0}, r"density must be > 0 \[kg/m\^3\], got -1.0"),
    ],
)
def test_bad_material(kw, match):
    args = {"name": "x", "elastic_modulus": 2e11, "poisson_ratio": 0.3, "density": 7800.0} | kw
    with pytest.raises(InputError, match=match):
        Material(**args)


GOOD = {
    "n_balls": 7,
    "ball_diameter": 2e-3,
    "pitch_diameter": 8.7355e-3,
    "inner_conformity": 0.525,
    "outer_conformity": 0.58,
    "contact_angle": math.radians(12),
}


@pytest.mark.parametrize(
    "kw, match",
    [
        ({"n_balls": 0}, r"n_balls must be an integer >= 1 \[-\], got 0"),
        ({"n_balls": 7.5}, r"n_balls must be an integer >= 1 \[-\], got 7.5"),
        ({"n_balls": True}, r"n_balls must be an integer >= 1"),
        ({"ball_diameter": -2e-3}, r"ball_diameter must be > 0 \[m\], got -0.002"),
        ({"ball_diameter": float("nan")}, r"ball_diameter must be > 0 \[m\], got nan"),
        ({"pitch_diameter": float("inf")}, r"pitch_diameter must be > 0 \[m\], got inf"),
        ({"width": 0.0}, r"width must be > 0 \[m\], got 0.0"),
        ({"static_load_rating": -5.0}, r"static_load_rating must be > 0 \[N\]"),
        ({"inner_conformity": 0.5}, r"inner_conformity must be in \(0.5, 10\) \[-\], got 0.5"),
        ({"outer_conformity": 0.45}, r"outer_conformity must be in \(0.5, 10\) \[-\], got 0.45"),
        (
            {"pitch_diameter": 2e-3},
            r"pitch_diameter must be > ball_diameter \[mm\], got 2 mm with ball_diameter = 2 mm",
        ),
        (
            {"bore": 13e-3, "outside_diameter": 5e-3},
            r"outside_diameter must be > bore \[mm\], got 5 mm with bore = 13 mm",
        ),
        ({"type": "magneto"}, (r"type must be one of \['radial', 'angular', 'four-point', 'double-row-angular', "
                               r"'double-row-radial', 'self-aligning', 'thrust'\], got 'magneto'")),
        (
            {"contact_angle": math.radians(90)},
            r"contact_angle must be in \[0, 90\) \[deg\], got 90.0",
        ),
        ({"contact_angle": -0.1}, r"contact_angle must be in \[0, 90\) \[deg\], got -5.7"),
        (
            {"contact_angle": None, "radial_clearance": 1e-3},
            r"radial_clearance must be in \(0, 0.84\) \[mm\] to give a real contact angle, got 1 mm",
        ),
        (  # -1e-6 is a preload since issue 30; beyond an interference of a ball diameter it is refused
            {"contact_angle": None, "radial_clearance": -5e-3},
            r"radial_clearance must be >= -4 \[mm\] \(an interference of one ball diameter per ball; .*\), got -5 mm",
        ),
        ({"contact_angle": None, "radial_clearance": float("nan")}, r"radial_clearance must be a finite length"),
        (
            {"contact_angle": None, "radial_clearance": 9e-6, "inner_conformity": None},
            r"radial_clearance needs both groove conformities and the ball diameter",
        ),
    ],
)
def test_bad_bearing(kw, match):
    with pytest.raises(InputError, match=match):
        BallBearing(**(GOOD | kw))


def test_from_groove_radii_validates_radii():
    with pytest.raises(InputError, match=r"inner_groove_radius must be > 0 \[m\], got -1.0"):
        BallBearing.from_groove_radii(7, 2e-3, 8.7355e-3, -1.0, 1.16e-3, contact_angle=0.2)
    with pytest.raises(
        InputError, match=r"inner_conformity must be in \(0.5, 10\) \[-\], got 0.4[45]"
    ):
        BallBearing.from_groove_radii(7, 2e-3, 8.7355e-3, 0.9e-3, 1.16e-3, contact_angle=0.2)

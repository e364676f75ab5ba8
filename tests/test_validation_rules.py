"""Issue 15: geometry that cannot exist is rejected with the physical reason (items 4 and 5)."""

import math

import pytest

from bearinglab import catalog
from bearinglab.bearing import BallBearing, max_balls
from bearinglab.errors import CatalogError, InputError

B218 = {"n_balls": 16, "ball_diameter": 22.23e-3, "pitch_diameter": 125.3e-3, "inner_conformity": 0.5232,
            "outer_conformity": 0.5232}


def _chord_fits(z, d, dm):
    """Independent check: neighbouring ball centres on the pitch circle are at least D apart."""
    return dm * math.sin(math.pi / z) >= d


@pytest.mark.parametrize("d, dm", [(7.938e-3, 38.5e-3), (22.23e-3, 125.3e-3), (2e-3, 8.7355e-3), (1e-3, 1.01e-3)])
def test_max_balls_is_the_largest_count_whose_chord_fits(d, dm):
    z = max_balls(d, dm)
    assert _chord_fits(z, d, dm) and not _chord_fits(z + 1, d, dm)


def test_too_many_balls_rejected():
    with pytest.raises(InputError, match=r"n_balls must be <= 15 .*7.938 mm on a 38.5 mm pitch diameter.*got 40"):
        BallBearing(n_balls=40, ball_diameter=7.938e-3, pitch_diameter=38.5e-3)
    assert BallBearing(n_balls=15, ball_diameter=7.938e-3, pitch_diameter=38.5e-3).n_balls == 15


def test_ball_set_must_fit_between_bore_and_outside_diameter():
    with pytest.raises(InputError, match="must be > bore"):
        BallBearing(ball_diameter=10e-3, pitch_diameter=30e-3, bore=25e-3)
    with pytest.raises(InputError, match="must be < outside_diameter"):
        BallBearing(ball_diameter=10e-3, pitch_diameter=30e-3, outside_diameter=38e-3)


def test_groove_radius_smaller_than_the_ball_rejected():
    with pytest.raises(InputError, match=r"inner_conformity must be in .*got 0.495 \(the groove radius f D must exceed the ball radius"):
        BallBearing.from_groove_radii(7, 2e-3, 8.7355e-3, 0.99e-3, 1.16e-3)


def test_angle_and_clearance_that_disagree_are_rejected():
    with pytest.raises(InputError, match=r"disagree: the clearance 100 um gives 17.9\d deg .* not 40 deg"):
        BallBearing(**B218, contact_angle=math.radians(40), radial_clearance=100e-6)


def test_angle_and_clearance_that_agree_to_rounding_are_accepted():
    e = BallBearing(**B218, contact_angle=math.radians(40)).radial_clearance
    b = BallBearing(**B218, contact_angle=math.radians(40), radial_clearance=round(e * 1e6) * 1e-6)  # um
    assert b.contact_angle == math.radians(40)
    BallBearing(**B218, contact_angle=math.radians(40.04), radial_clearance=e)  # angle within 0.05 deg


def test_catalog_entry_with_disagreeing_angle_and_clearance(tmp_path):
    path = tmp_path / "c.toml"
    path.write_text('[bearings."X"]\nballs = 16\nball_diameter = "22.23 mm"\npitch_diameter = "125.3 mm"\n'
                    'inner_conformity = 0.5232\nouter_conformity = 0.5232\ncontact_angle = "40 deg"\n'
                    'radial_clearance = "100 um"\n', encoding="utf-8")
    with pytest.raises(CatalogError, match=r"entry 'X', field 'contact_angle': contact_angle and radial_clearance disagree"):
        catalog.load_catalog(path)


def test_builtin_catalog_passes_every_rule():
    for name in catalog.names():
        assert catalog.get(name).designation

"""Nominal geometry of spec 003 section 2 (``runout.geometry``): the catalogue, radii and catalog forms
and their checks."""

import math

import pytest

from bearinglab import runout as R
from bearinglab.errors import InputError


def test_geometry_forms_and_checks(g):
    h = R.geometry_from_catalog(
        16, 7.144e-3, 54e-3, 0.53, 0.52, outer_bottom_radius=g.outer_bottom_radius
    )
    assert h.contact_angle == pytest.approx(g.contact_angle, abs=1e-12)
    with pytest.raises(InputError, match="inconsistent with contact_angle"):
        R.geometry_from_radii(
            16,
            g.ball_radius,
            g.outer_groove_radius,
            g.inner_groove_radius,
            g.inner_bottom_radius,
            g.contact_angle,
            outer_bottom_radius=g.outer_bottom_radius + 1e-6,
        )
    with pytest.raises(InputError, match="n_balls must be an integer >= 3"):
        R.geometry_from_catalog(2, 7.144e-3, 54e-3, 0.53, 0.52, 0.26)
    with pytest.raises(InputError, match="outer_conformity must be > 0.5"):
        R.geometry_from_catalog(16, 7.144e-3, 54e-3, 0.5, 0.52, 0.26)
    with pytest.raises(InputError, match="inner_groove_radius must be > ball_radius"):
        R.geometry_from_radii(16, 3.572e-3, 3.8e-3, 3.5e-3, 23.4e-3, 0.26)
    with pytest.raises(InputError, match=r"contact_angle must be in \(0, 90\)"):
        R.geometry_from_catalog(16, 7.144e-3, 54e-3, 0.53, 0.52, 0.0)
    with pytest.raises(InputError, match=r"contact_angle must be in \(0, 90\)"):
        R.geometry_from_catalog(16, 7.144e-3, 54e-3, 0.53, 0.52, math.radians(95))
    with pytest.raises(InputError, match="pitch_diameter must be > ball_diameter"):
        R.geometry_from_catalog(16, 7.144e-3, 5e-3, 0.53, 0.52, 0.26)
    with pytest.raises(InputError, match="give contact_angle"):
        R.geometry_from_radii(
            16, g.ball_radius, g.outer_groove_radius, g.inner_groove_radius, g.inner_bottom_radius
        )


def test_geometry_from_a_catalog_bearing():
    from bearinglab import catalog

    b = catalog.get("B218")
    h = R.geometry_from_bearing(b, first_ball_angle=0.1)
    assert h.n_balls == 16 and h.first_ball_angle == 0.1
    assert 2 * h.ball_centre_radius == pytest.approx(b.pitch_diameter, rel=1e-14)
    with pytest.raises(InputError, match="n_balls of '1000095' is not known"):
        R.geometry_from_bearing(catalog.get("1000095"))

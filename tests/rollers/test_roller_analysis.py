"""The slice model of a RollerBearing, its reactions, the estimated roller set and the built-in roller bearings."""

import math

import numpy as np
import pytest

from bearinglab import catalog, reactions
from bearinglab.bearing import BallBearing
from bearinglab.errors import CatalogError, InputError, ValidityWarning
from bearinglab.rollers import (
    RollerBearing,
    bearing_roller_set,
    distribution,
    estimate_roller_set,
    roller_analysis,
    roller_reactions,
    with_estimated_geometry,
)

NU = RollerBearing("cylindrical", 14, 11e-3, 9.6e-3, 60.5e-3, radial_clearance=20e-6, bore=40e-3,
                   outside_diameter=80e-3, width=18e-3)


def test_the_bearing_sets_gap_profile_and_axial_support():
    rs = bearing_roller_set(NU.replace(design="NJ"), n_slices=40)
    assert rs.normal_gap == pytest.approx(10e-6) and rs.axial_support == "ribs-positive"
    assert rs.drop == pytest.approx(NU.profile_drop(rs.slice_position))
    tap = bearing_roller_set(RollerBearing("tapered", 17, 10e-3, 14e-3, 60e-3, math.radians(14.0),
                                           radial_clearance=10e-6))
    assert tap.normal_gap == pytest.approx(5e-6 * math.cos(math.radians(14.0)))
    with pytest.raises(InputError, match="spherical roller bearing: its load distribution is not modelled"):
        bearing_roller_set(catalog.get("22208 E"))


def test_an_estimated_roller_set_is_labelled_and_warned_about():
    with pytest.warns(ValidityWarning, match="estimated, not published"):
        r = roller_analysis(catalog.get("NU 208 ECP"), [8e3, 0, 0, 0, 0])
    assert "rollers, roller_length estimated" in r.warnings[0]
    with pytest.raises(InputError, match="^rollers of 'x' is not known"):
        roller_analysis(RollerBearing("cylindrical", designation="x"), [1e3, 0, 0, 0, 0], estimate=False)


def test_reactions_dispatch_to_the_slice_model():
    u = np.array([[20e-6, 3e-6, 0, 1e-4, 0], [0, 15e-6, 0, 0, -2e-4]])
    rs = bearing_roller_set(NU)
    got = reactions.bearing_reactions(NU, u)
    want = distribution.equilibrium(u, np.zeros(5), rs)
    assert np.array_equal(got.force, want.reaction) and np.array_equal(got.stiffness, want.stiffness)
    # a system of a ball bearing and a roller bearing: each bearing as alone
    ball = BallBearing(9, 7.94e-3, 39.04e-3, 0.52, 0.53, contact_angle=0.0, type="radial")
    both = reactions.bearing_reactions([ball, NU], np.stack([np.zeros((2, 5)), u], axis=1))
    assert np.array_equal(both.force[:, 1], got.force) and both.force.shape == (2, 2, 5)
    assert np.array_equal(roller_reactions(NU, u)[0], got.force)
    with pytest.raises(InputError, match="spherical roller bearing has no load-distribution model"):
        reactions.bearing_reactions(catalog.get("22208 E"), np.zeros(5))


def _raceways():
    """The built-in cylindrical bearings whose F and E are both printed for the size (an N and its NU)."""
    from bearinglab.catalog import _rollers

    return [r for r in _rollers.records().values() if r["design"] == "N" and r["inner_raceway_diameter_mm"]]


def test_the_estimation_error_on_published_raceway_diameters():
    # docs/user_guide/roller_bearings.md quotes these bands: over the 46 sizes of SKF's series 2 and 3 that print F
    # and E, D_we -2.9 % to +11.7 % (+5.1 % without N 232 ECM), D_pw -0.5 % to +0.6 %
    errors_d, errors_p = [], []
    for row in _raceways():
        f, e = row["inner_raceway_diameter_mm"], row["outer_raceway_diameter_mm"]
        s = estimate_roller_set(row["bore_mm"] * 1e-3, row["outside_diameter_mm"] * 1e-3,
                                row["static_load_rating_kN"] * 1e3, width=row["width_mm"] * 1e-3)
        errors_d.append(s.roller_diameter / ((e - f) / 2 * 1e-3) - 1)
        errors_p.append(s.pitch_diameter / ((e + f) / 2 * 1e-3) - 1)
        assert s.roller_length <= row["width_mm"] * 1e-3
    assert len(errors_d) == 46
    assert f"{min(errors_d):+.1%}" == "-2.9%" and f"{max(errors_d):+.1%}" == "+11.7%"
    assert f"{sorted(errors_d)[-2]:+.1%}" == "+5.1%"
    assert f"{min(errors_p):+.1%}" == "-0.5%" and f"{max(errors_p):+.1%}" == "+0.6%"


def test_the_estimate_reproduces_the_catalogue_c0():
    from bearinglab.ratings import roller_static_load_rating

    for name in ("NU 208 ECP", "NU 2208 ECP", "30208 J2/Q", "31308 J2/QCL7C"):
        b = with_estimated_geometry(catalog.get(name))
        c0 = roller_static_load_rating(b.rollers, b.roller_diameter, b.roller_length, b.pitch_diameter,
                                       b.contact_angle)
        assert c0 == pytest.approx(b.static_load_rating, rel=1e-12)
        assert b.sources["rollers"].startswith("estimated")


def test_built_in_roller_bearings_and_user_tables(tmp_path):
    b = catalog.get("nu208ecp")
    assert isinstance(b, RollerBearing) and b.designation == "NU 208 ECP"
    assert b.roller_diameter == pytest.approx(11e-3) and b.pitch_diameter == pytest.approx(60.5e-3)
    assert "p. 526" in b.sources["dynamic_load_rating"]
    t = catalog.get("30208 J2/Q")
    assert (t.ratio_limit, t.axial_factor, t.static_axial_factor) == (0.37, 1.6, 0.9)
    s = catalog.get("22208 E")
    assert (s.axial_factor_below, s.axial_factor) == (2.4, 3.6)
    f = tmp_path / "mine.toml"
    f.write_text('[bearings."my 30208"]\ntype = "tapered"\nrollers = 17\nroller_diameter = "9.5 mm"\n'
                 'roller_length = "14 mm"\npitch_diameter = "60.8 mm"\ncontact_angle = "14.5 deg"\n'
                 'e = 0.37\nY = 1.6\nY0 = 0.9\nprofile = "crowned"\ncrown_drop = "4 um"\n', encoding="utf-8")
    mine = catalog.get("my 30208", catalog=f)
    assert mine.type == "tapered" and mine.axial_factor == 1.6 and mine.crown_drop == pytest.approx(4e-6)
    f.write_text('[bearings."bad"]\ntype = "tapered"\ncontact_angle = "50 deg"\n', encoding="utf-8")
    with pytest.raises(CatalogError, match=r"entry 'bad', field 'contact_angle': contact_angle must be in \(0, 45\]"):
        catalog.get("bad", catalog=f)

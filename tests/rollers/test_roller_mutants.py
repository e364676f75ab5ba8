"""Gaps that mutation testing of the roller geometry and line contact found (TESTING.md, eighth run).

Each test pins what a surviving mutant changed: a boundary of an input check, the parameter and unit a
message names, a value a message prints, the derivative of the lamina law, the shape of a zero profile.
"""

import math
import re

import numpy as np
import pytest

from bearinglab.errors import InputError
from bearinglab.rollers import contact, geometry


def test_the_lamina_tangent_is_the_derivative_of_the_lamina_load():
    # q = c delta^(10/9): dq/ddelta = (10/9) c delta^(1/9), checked by a central difference
    c, delta, h = 3.7e9, np.array([0.4e-6, 2.0e-6, 9.0e-6]), 1e-12
    q, k = contact.slice_loads(delta, c)
    up, _ = contact.slice_loads(delta + h, c)
    down, _ = contact.slice_loads(delta - h, c)
    assert k == pytest.approx((up - down) / (2 * h), rel=1e-6)
    assert q == pytest.approx(c * delta ** (10 / 9), rel=1e-14)
    q0, k0 = contact.slice_loads(-1e-6, c)  # no approach, no load and no stiffness
    assert q0 == 0.0 and k0 == 0.0


def test_a_roller_as_large_as_its_pitch_circle_is_refused():
    with pytest.raises(InputError, match="roller_diameter"):
        contact.contact_radii(0.01, 0.01)  # gamma = 1: the inner raceway would have no radius
    r = contact.contact_radii(0.01, 0.0100001)  # just below 1: still a bearing
    assert np.all(np.isfinite(np.asarray(r, dtype=float)))


def test_the_cup_angle_of_a_tapered_bearing_is_in_zero_to_45_degrees():
    with pytest.raises(InputError, match=r"^contact_angle must be in \(0, 45\] \[deg\].*got 0\.0$"):
        geometry.tapered_angles(0.0, 10e-3, 60e-3)
    a = geometry.tapered_angles(math.radians(45.0), 10e-3, 60e-3)  # the limit itself is a tapered bearing
    # the cone and cup lines meet the roller's sides: alpha = cone + 2 phi, roller half angle phi
    assert a.cone_angle + 2 * a.roller_angle == pytest.approx(math.radians(45.0), rel=1e-14)
    with pytest.raises(InputError, match=r"got 46\.0"):
        geometry.tapered_angles(math.radians(46.0), 10e-3, 60e-3)


@pytest.mark.parametrize(("call", "name", "unit"), [
    (lambda: geometry.tapered_angles(0.2, -1e-3, 60e-3), "roller_diameter", "m"),
    (lambda: geometry.tapered_angles(0.2, 10e-3, 0.0), "pitch_diameter", "m"),
    (lambda: geometry.slice_positions(0.0, 30), "roller_length", "m"),
    (lambda: geometry.logarithmic_drop(0.0, 10e-3, -1.0), "roller_diameter", "m"),
    (lambda: geometry.crowned_drop(0.0, 10e-3, -1e-6), "crown_drop", "m"),
    (lambda: geometry.flat_drop(0.0, 10e-3, edge_length=-1e-3), "edge_length", "m"),
    (lambda: geometry.flat_drop(0.0, 10e-3, edge_radius=0.0, edge_length=1e-3), "edge_radius", "m"),
    (lambda: contact.slice_stiffness(-1e-3, 30), "roller_length", "m"),
    (lambda: contact.contact_radii(0.0, 60e-3), "roller_diameter", "m"),
    (lambda: contact.contact_radii(10e-3, -60e-3), "pitch_diameter", "m"),
    (lambda: contact.line_contact(-1.0, 5e-3, 2.3e11), "load_per_length", "N/m"),
    (lambda: contact.line_contact(1e5, 0.0, 2.3e11), "radius", "m"),
    (lambda: contact.line_contact(1e5, 5e-3, 0.0), "reduced_modulus", "Pa"),
])
def test_a_bad_value_is_named_with_its_unit(call, name, unit):
    with pytest.raises(InputError, match=rf"^{name} must be [^\[]*\[{re.escape(unit)}\]"):
        call()


@pytest.mark.parametrize(("call", "name"), [
    (lambda: geometry.tapered_angles("x", 10e-3, 60e-3), "contact_angle"),
    (lambda: geometry.slice_positions(10e-3, "many"), "n_slices"),
    (lambda: geometry.table_drop(0.0, "flat"), "profile"),
    (lambda: geometry.table_drop("middle", [[-1e-3, 0.0], [1e-3, 0.0]]), "position"),
    (lambda: contact.slice_loads("deep", 1e9), "approach"),
])
def test_a_value_that_is_no_number_is_named(call, name):
    with pytest.raises(InputError, match=rf"^{name}"):
        call()


def test_zero_drops_keep_the_shape_of_the_positions():
    x = np.array([[-4e-3, 0.0], [1e-3, 4.9e-3]])
    for drop in (geometry.crowned_drop(x, 10e-3, 0.0), geometry.flat_drop(x, 10e-3)):
        assert np.shape(drop) == x.shape and np.all(drop == 0.0)


def test_the_edge_zone_is_shorter_than_half_the_roller_and_its_radius():
    x = np.array([0.0, 4.9e-3])
    # l_e = r_e is the largest zone a radius of r_e can round off: taken
    d = geometry.flat_drop(x, 10e-3, edge_radius=1e-3, edge_length=1e-3)
    u = 4.9e-3 - (5e-3 - 1e-3)
    assert d[1] == pytest.approx(1e-3 - math.sqrt(1e-3**2 - u * u), rel=1e-12) and d[0] == 0.0
    # l_e = L/2 (no straight part left) and l_e > r_e are refused, each with the value in mm
    with pytest.raises(InputError, match=r"\[0, 5\) \[mm\], got 5 mm$"):
        geometry.flat_drop(x, 10e-3, edge_radius=20e-3, edge_length=5e-3)
    with pytest.raises(InputError, match=r"\[0, 1\) \[mm\], got 1\.5 mm$"):
        geometry.flat_drop(x, 10e-3, edge_radius=1e-3, edge_length=1.5e-3)
    with pytest.raises(InputError, match=r"got 8 mm$"):  # longer than half the roller, within the radius
        geometry.flat_drop(x, 10e-3, edge_radius=50e-3, edge_length=8e-3)


def test_a_profile_table_is_pairs_rising_strictly_and_covers_the_roller():
    good = [[-5e-3, 10e-6], [0.0, 0.0], [5e-3, 10e-6]]
    # a position at either end of the table is inside it
    assert geometry.table_drop([-5e-3, 5e-3], good) == pytest.approx([10e-6, 10e-6], rel=1e-15)
    for bad in ([[0.0, 0.0, 0.0], [1e-3, 0.0, 0.0]],  # three columns
                [[0.0, 0.0]],  # one row
                [0.0, 0.0]):  # not a table
        with pytest.raises(InputError, match=r"^profile table must be \(position, drop\) pairs"):
            geometry.table_drop(0.0, bad)
    with pytest.raises(InputError, match="rise strictly"):
        geometry.table_drop(0.0, [[-5e-3, 0.0], [0.0, 0.0], [0.0, 1e-6], [5e-3, 0.0]])
    with pytest.raises(InputError, match=r"spans \[-5, 5\] mm, a slice lies at 6 mm$"):
        geometry.table_drop(6e-3, good)


def test_the_bad_value_of_an_array_of_cup_angles_is_the_one_named():
    with pytest.raises(InputError, match=r"got 50\.0$"):
        geometry.tapered_angles(np.radians([15.0, 50.0]), 10e-3, 60e-3)


def test_roller_angles_that_do_not_converge_say_so(monkeypatch):
    from bearinglab.errors import ConvergenceError

    converged = geometry.tapered_angles(math.radians(15.0), 10e-3, 60e-3).roller_angle
    monkeypatch.setattr(geometry, "_ANGLE_MAX_ITER", 1)  # one Newton step from the start is not enough
    with pytest.raises(ConvergenceError) as caught:
        geometry.tapered_angles(math.radians(15.0), 10e-3, 60e-3)
    e = caught.value
    assert e.where == "rollers.geometry.tapered_angles" and e.iterations == 1
    # the estimate is the roller half angle after the one step, near the converged one but not it; the residual
    # is that of the start: small, not zero
    assert float(e.estimate) == pytest.approx(converged, rel=1e-3) and float(e.estimate) != converged
    assert 0.0 < abs(float(e.residual)) < 1e-2


@pytest.mark.parametrize(("call", "message"), [
    (lambda: contact.contact_radii(10e-3, 60e-3, "steep"), r"^contact_angle must be a number"),
    (lambda: contact.contact_radii(0.01, 0.01), (r"^pitch_diameter must be > roller_diameter cos\(contact_angle\) "
                                                r"\[mm\]$")),
    (lambda: geometry.flat_drop(0.0, 10e-3, edge_length=1e-3), (r"^edge_radius is needed with an edge_length > 0 "
                                                               r"\[mm\]$")),
    (lambda: geometry.table_drop(0.0, [[-1e-3, 0.0], [1e-3, np.nan]]), (r"^profile table must hold finite numbers "
                                                                      r"\[mm\]$")),
    (lambda: geometry.table_drop(0.0, [[1e-3, 0.0], [-1e-3, 0.0]]), (r"^profile table positions must rise strictly "
                                                                    r"\[mm\]$")),
    (lambda: geometry.table_drop(0.0, [[-1e-3, 0.5e-6], [0.0, 0.0], [1e-3, -2e-6]]),
     r"^profile drop must be >= 0 \[um\], got -2 um$"),
])
def test_the_hand_worded_messages(call, message):
    with pytest.raises(InputError, match=message):
        call()


def _iso_drop(x, length, d, kind):
    """ISO/TS 16281:2008 eqs. (42)-(44), written from the printed formulas (math, one point)."""
    if kind == "tapered":
        return 0.00045 * d * math.log(1.0 / (1.0 - (2.0 * x / length) ** 2))
    if length <= 2.5 * d:
        return 0.00035 * d * math.log(1.0 / (1.0 - (2.0 * x / length) ** 2))
    start = (length - 2.5 * d) / 2.0  # the end zones begin here; the drop is 0 between them
    if abs(x) <= start:
        return 0.0
    r = (2.0 * abs(x) - length + 2.5 * d) / (2.5 * d)
    return 0.0005 * d * math.log(1.0 / (1.0 - r * r))


@pytest.mark.parametrize(("length", "d", "kind"), [
    (10e-3, 10e-3, "cylindrical"),  # short: L <= 2.5 D
    (25e-3, 10e-3, "cylindrical"),  # the limit L = 2.5 D takes the short form
    (40e-3, 10e-3, "cylindrical"),  # long: flat middle, logarithmic end zones
    (18e-3, 9e-3, "tapered"),
])
def test_the_logarithmic_profile_is_iso_ts_16281s(length, d, kind):
    xs = [s * 0.5 * length for s in (-0.999, -0.9, -0.62, -0.3, 0.0, 0.1, 0.45, 0.8, 0.97, 0.9999)]
    got = geometry.logarithmic_drop(np.array(xs), length, d, tapered=kind == "tapered")
    want = [_iso_drop(x, length, d, kind) for x in xs]
    assert got == pytest.approx(want, rel=1e-12, abs=1e-18)


def test_a_position_at_or_beyond_the_end_of_the_roller_is_refused():
    # the profile is infinite at |x| = L_we/2: slices lie inside it, and anything else is an input error
    for x in (5e-3, -5e-3, 7e-3):
        with pytest.raises(InputError, match=r"^position must be inside the effective roller length, \|x\| < 5 mm "
                                             r"\[mm\], got -?[57] mm$"):
            geometry.logarithmic_drop(x, 10e-3, 10e-3)
    assert np.isfinite(geometry.logarithmic_drop(4.999e-3, 10e-3, 10e-3))
    with pytest.raises(InputError, match=r"got 6 mm$"):
        geometry.crowned_drop(np.array([0.0, 6e-3]), 10e-3, 5e-6)
    with pytest.raises(InputError, match=r"^position must be a number"):
        geometry.crowned_drop("middle", 10e-3, 5e-6)
    with pytest.raises(InputError, match=r"^roller_length must be > 0 \[m\]"):
        geometry.crowned_drop(0.0, 0.0, 5e-6)


def test_a_roller_is_cut_into_one_slice_or_more():
    assert geometry.slice_positions(10e-3, 1) == pytest.approx([0.0])
    with pytest.raises(InputError, match="^n_slices"):
        geometry.slice_positions(10e-3, 0)
    with pytest.raises(InputError, match="^n_slices"):
        contact.slice_stiffness(10e-3, 0)

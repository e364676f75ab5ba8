"""The ball attitude angle checked against an independent construction, not through the same helper.

Raceway control (Jones; Harris and Kotzalas, *Advanced Concepts of Bearing Technology*, 5th ed., 2006,
section 8.5): the ball rolls without spin on the controlling raceway, so its spin axis passes through
the point where the tangent to the ball at that contact meets the bearing axis. The construction
below intersects the two lines in the meridian plane with a linear solve; it shares no formula with
:func:`bearinglab.quasistatic.attitude_angle`.
"""

import math

import numpy as np
import pytest
from hypothesis import example, given
from hypothesis import strategies as st

from bearinglab import quasistatic


def _construction(contact_angle, ball_diameter, pitch_diameter, race):
    """beta from the meridian-plane geometry: axis = x, radius = y, ball centre at (0, d_m/2)."""
    centre = np.array([0.0, pitch_diameter / 2])
    sign = -1.0 if race == "inner" else 1.0  # the inner contact lies toward the axis, the outer away
    normal = sign * np.array([math.sin(contact_angle), math.cos(contact_angle)])
    point = centre + ball_diameter / 2 * normal
    tangent = np.array([normal[1], -normal[0]])
    # point + s tangent = (x, 0): two unknowns (s, x)
    _, x = np.linalg.solve(np.array([[tangent[0], -1.0], [tangent[1], 0.0]]), -point)
    # the spin axis runs from (x, 0) to the ball centre; beta is its angle from the +x (bearing) axis,
    # above 90 deg when the inner contact's tangent meets the axis behind the ball (cos a_i < D/d_m)
    return math.atan2(centre[1], x - centre[0])  # measured toward the side of the contact


@given(ai=st.floats(0.15, 1.3), ae=st.floats(0.15, 1.3), ratio=st.floats(0.08, 0.3))
@example(ai=1.28125, ae=1.0, ratio=0.296875)  # cos a_i < D/d_m: beta above 90 deg
def test_inner_raceway_control_matches_the_geometric_construction(ai, ae, ratio):
    d, dm = ratio * 0.1, 0.1
    got = quasistatic.attitude_angle(ai, ae, d, dm, raceway_control="inner")
    assert got == pytest.approx(_construction(ai, d, dm, "inner"), abs=1e-12)


@given(ai=st.floats(0.15, 1.3), ae=st.floats(0.15, 1.3), ratio=st.floats(0.08, 0.3))
def test_outer_raceway_control_matches_the_geometric_construction(ai, ae, ratio):
    d, dm = ratio * 0.1, 0.1
    got = quasistatic.attitude_angle(ai, ae, d, dm, raceway_control="outer")
    assert got == pytest.approx(_construction(ae, d, dm, "outer"), abs=1e-12)


def test_inner_control_uses_the_inner_angle_and_differs_from_outer_control():
    ai, ae, d, dm = math.radians(40.0), math.radians(30.0), 22.23e-3, 125.3e-3
    inner = quasistatic.attitude_angle(ai, ae, d, dm, raceway_control="inner")
    outer = quasistatic.attitude_angle(ai, ae, d, dm, raceway_control="outer")
    # by hand: tan(beta) = sin 40 deg / (cos 40 deg - 22.23/125.3) = 0.642788 / 0.588630 = 1.092006
    assert math.tan(inner) == pytest.approx(1.092006, abs=2e-6)
    assert inner > math.radians(45.0) > outer

"""Tapered pairs on a rigid shaft (bearinglab.rollers.pairs)."""

import math

import numpy as np
import pytest

from bearinglab.errors import InputError
from bearinglab.rollers import RollerBearing, pairs

B = RollerBearing("tapered", 17, 10e-3, 14e-3, 60e-3, math.radians(14.0))


def test_a_preloaded_pair_carries_its_preload_at_rest():
    r = pairs.pair_analysis(B, B, [0, 0, 0, 0, 0], distance=0.1, preload=1500.0)
    assert r.axial_loads == pytest.approx([1500.0, 1500.0], rel=1e-8)
    assert r.displacement == pytest.approx(np.zeros(5), abs=1e-15) and r.axial_play < 0


@pytest.mark.parametrize("arrangement", pairs.ARRANGEMENTS)
def test_the_shaft_is_in_equilibrium_and_the_thrust_goes_to_one_bearing(arrangement):
    loads = np.array([4e3, -1e3, 3e3, 20.0, -10.0])
    r = pairs.pair_analysis(B, B, loads, distance=0.12, arrangement=arrangement, axial_play=30e-6)
    # the two bearings' reactions moved to the reference point balance the loads (independent statics)
    total = np.zeros(5)
    for res, z, sign in ((r.bearing_a, 0.06, -1 if arrangement == "back-to-back" else 1),
                         (r.bearing_b, -0.06, 1 if arrangement == "back-to-back" else -1)):
        f = np.array(res.loads, dtype=float) * [1, 1, sign, sign, sign]  # back into the shaft's frame
        total += [f[0], f[1], f[2], f[3] - z * f[1], f[4] + z * f[0]]
    assert total == pytest.approx(loads, rel=1e-9, abs=1e-9)
    thrust_bearing = 1 if arrangement == "back-to-back" else 0  # whose cup narrows towards +z
    # the axial loads differ by the thrust (the radial loads induce more on both)
    assert r.axial_loads[thrust_bearing] - r.axial_loads[1 - thrust_bearing] == pytest.approx(3e3, rel=1e-9)
    alone = pairs.pair_analysis(B, B, [0, 0, 3e3, 0, 0], distance=0.12, arrangement=arrangement, axial_play=30e-6)
    assert alone.axial_loads[thrust_bearing] == pytest.approx(3e3, rel=1e-9)  # a thrust alone, with end play
    assert alone.axial_loads[1 - thrust_bearing] == 0


def test_the_o_arrangement_is_stiffer_against_tilt():
    o = pairs.pair_analysis(B, B, [0, 0, 0, 0, 0], distance=0.05, preload=1000.0)
    x = pairs.pair_analysis(B, B, [0, 0, 0, 0, 0], distance=0.05, arrangement="face-to-face", preload=1000.0)
    assert o.effective_spread == pytest.approx(0.05 + 60e-3 * math.tan(math.radians(14.0)))
    assert x.effective_spread == pytest.approx(0.05 - 60e-3 * math.tan(math.radians(14.0)))
    assert o.stiffness[3, 3] > 1.5 * x.stiffness[3, 3]


def test_pairs_take_tapered_bearings_and_one_clearance():
    cyl = RollerBearing("cylindrical", 14, 11e-3, 9.6e-3, 60.5e-3)
    with pytest.raises(InputError, match="^pair_analysis takes tapered roller bearings"):
        pairs.pair_analysis(cyl, B, [0, 0, 0, 0, 0], distance=0.1)
    with pytest.raises(InputError, match="^preload: give axial_play or preload"):
        pairs.pair_analysis(B, B, [0, 0, 0, 0, 0], distance=0.1, preload=100.0, axial_play=1e-6)

"""Natural frequencies against ROSS for the same rotor, and the export's bearing coefficients."""

import warnings

import numpy as np
import pytest

from bearinglab import catalog, shaft
from bearinglab.bearing import Material
from bearinglab.units import RPM

STEEL = Material("steel", 211e9, 0.3, 7810.0)


def _rotor(speed=0.0):
    """ROSS's classic rotor: a 1.5 m shaft of 50 mm, a disk in the middle, two isotropic bearings."""
    secs = (shaft.Section(0.25, 0.05), shaft.Section(1.0, 0.05), shaft.Section(0.25, 0.05))
    sup = (shaft.LinearSupport("A", 0.25, 1e7, axial_stiffness=1e7), shaft.LinearSupport("B", 1.25, 1e7))
    return shaft.ShaftSystem(shaft.Shaft(secs, STEEL), sup, masses=(shaft.Mass(0.75, 32.6, 0.33, 0.17),),
                             speed=speed, elements=12)


def _ross_frequencies(state, speed, count=24):
    ross = pytest.importorskip("ross")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        rotor = shaft.to_ross(state)
        return np.sort(rotor.run_modal(speed, num_modes=count, sparse=False).wn) / (2 * np.pi), ross


@pytest.mark.parametrize("speed", [0.0, 400.0])
def test_ross_and_bearinglab_give_the_same_natural_frequencies(speed):
    state = shaft.solve(_rotor(speed))
    ours = shaft.natural_modes(state, 6)
    theirs, _ = _ross_frequencies(state, speed)
    # ROSS's list holds the axial mode (ours sets it apart) and torsion; every bending mode of ours is in it
    for f in ours.frequency:
        assert np.min(np.abs(theirs - f)) / f < 1e-8, (f, theirs)
    assert any(np.min(np.abs(theirs - a)) / a < 1e-8 for a in ours.axial)
    if speed:
        assert ours.whirl[:2] == ("backward", "forward") and ours.frequency[1] > ours.frequency[0]


def test_the_exported_bearings_carry_bearinglabs_stiffness_over_speed():
    b = catalog.get("7010 C")
    secs = (shaft.Section(0.3, 0.05),)
    s = shaft.ShaftSystem(shaft.Shaft(secs), (shaft.BearingSetSupport("front", 0.05, (b,), "DB", preload=300.0),
                                              shaft.BearingSetSupport("rear", 0.25, (b,), "DB", preload=300.0,
                                                                      axial=False)),
                          loads=(shaft.PointLoad(0.15, fy=-500.0),))
    speeds = np.array([0.0, 8000.0, 16000.0]) * RPM
    state = shaft.solve(s, shaft.load_cases(s, speed=speeds))
    data = shaft.ross_elements(state)
    assert len(data["bearings"]) == 4 and len(data["shaft"]) == len(state.assembly.mesh.z) - 1
    first = data["bearings"][0]
    key = "speed" if "speed" in first else "frequency"
    np.testing.assert_allclose(first[key], speeds)
    # kxx of bearing 0 at each speed: its tangent stiffness (own frame = shaft frame for x)
    np.testing.assert_allclose(first["kxx"], state.row_stiffness[:, 0, 0, 0], rtol=1e-12)
    assert first["kxx"][2] < first["kxx"][0]  # centrifugal forces soften a ball bearing at speed
    assert any("tilt" in w for w in data["warnings"])

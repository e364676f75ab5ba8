"""Issue 11 section 5: export of the bearing stiffness to a ROSS BearingElement (needs the ``ross`` extra)."""

import importlib
import json
import math
import os

import numpy as np
import pytest
from numpy.testing import assert_allclose

from bearinglab.bearing import BallBearing
from bearinglab.errors import InputError
from bearinglab.quasistatic import combined, rotordynamics, sets
from bearinglab.units import RPM

# `make test` installs the ross extra; under CI a missing ross is a failure, never a skip
ross = importlib.import_module("ross") if os.environ.get("CI") else pytest.importorskip("ross")

SPINDLE = BallBearing(n_balls=15, ball_diameter=7.938e-3, pitch_diameter=52.5e-3, inner_conformity=0.52,
                      outer_conformity=0.53, contact_angle=math.radians(15), type="angular")
SPEEDS = np.array([0.0, 6000.0, 12000.0, 18000.0]) * RPM
LOADS = [300.0, 0.0, 400.0, 0.0, 0.0]


ROSS3 = "speed" in __import__("inspect").signature(ross.BearingElement).parameters


def test_the_export_uses_the_keyword_of_the_installed_ross():
    coef = rotordynamics.bearing_coefficients(SPINDLE, LOADS, SPEEDS)
    key = "speed" if ROSS3 else "frequency"  # ROSS 3.0 renamed the rotor-speed table (petrobras/ross #1371)
    assert rotordynamics.speed_keyword() == key and set(coef) & {"speed", "frequency"} == {key}
    assert_allclose(coef[key], SPEEDS)


def test_bearing_element_coefficients_follow_the_rotor_speed_not_the_whirl_frequency():
    coef = rotordynamics.bearing_coefficients(SPINDLE, LOADS, SPEEDS)
    element = ross.BearingElement(n=0, **coef)
    ref = combined.combined_analysis(SPINDLE, np.broadcast_to(LOADS, (4, 5)), SPEEDS).stiffness[:, 0, 0]
    assert np.all(np.diff(ref) < 0) and ref[0] > 1.5 * ref[-1]  # the speeds make a difference to see
    if not ROSS3:  # ROSS 2: one axis, ``frequency``, which meant the rotor speed
        assert_allclose([element.kxx_interpolated(w) for w in SPEEDS], ref, rtol=1e-9)
        assert_allclose(element.K(SPEEDS[2])[0, 0], ref[2], rtol=1e-9)
        return
    whirl = np.array([0.0, 0.3, 1.0, 3.0]) * SPEEDS[-1]  # sub- to super-synchronous whirl
    for k, speed in enumerate(SPEEDS):
        # at a rotor speed, the same coefficient for any whirl frequency: the tabulated one
        got = [float(element.kxx_interpolated(frequency=f, speed=speed)) for f in whirl]
        assert_allclose(got, ref[k], rtol=1e-9)
        assert_allclose(element.K(whirl[1], speed)[0, 0], ref[k], rtol=1e-9)
    # at one whirl frequency, the coefficient changes with the rotor speed as the table does
    assert_allclose([float(element.kxx_interpolated(frequency=whirl[1], speed=w)) for w in SPEEDS], ref, rtol=1e-9)


def test_the_keyword_of_each_ross_version_and_its_checks():
    assert rotordynamics.speed_keyword("2.3.0") == "frequency"
    assert rotordynamics.speed_keyword("3.0.0") == rotordynamics.speed_keyword("3.1.0rc1") == "speed"
    stiff = np.repeat(np.diag([2e8, 2e8, 5e7, 1e4, 1e4])[None], 2, axis=0)
    assert "frequency" in rotordynamics.from_stiffness(stiff, [0.0, 1.0], speed_key="frequency")
    with pytest.raises(InputError, match="speed_key must be one of"):
        rotordynamics.from_stiffness(stiff, [0.0, 1.0], speed_key="whirl")
    with pytest.raises(InputError, match="strictly increasing"):
        rotordynamics.from_stiffness(stiff, [1.0, 0.0])
    with pytest.raises(InputError, match="version must be"):
        rotordynamics.speed_keyword("latest")


def test_bearing_element_from_the_exported_dictionary():
    coef = rotordynamics.bearing_coefficients(SPINDLE, LOADS, SPEEDS)
    element = ross.BearingElement(n=0, **coef)
    ref = combined.combined_analysis(SPINDLE, np.broadcast_to(LOADS, (4, 5)), SPEEDS).stiffness
    for k, speed in enumerate(SPEEDS):  # one argument: the synchronous value (speed = whirl) in ROSS 2 and 3
        assert float(element.kxx_interpolated(speed)) == pytest.approx(ref[k, 0, 0], rel=1e-9)
        assert float(element.kyy_interpolated(speed)) == pytest.approx(ref[k, 1, 1], rel=1e-9)
        assert float(element.kxy_interpolated(speed)) == pytest.approx(ref[k, 0, 1], rel=1e-9,
                                                                       abs=1e-6 * ref[k, 0, 0])
    assert_allclose(coef["kzz"], ref[:, 2, 2])
    assert np.all(np.diff(coef["kxx"]) < 0)  # centrifugal softening of the radial stiffness


def test_set_stiffness_round_trip_through_a_file(tmp_path):
    stiff = np.stack([sets.set_analysis(SPINDLE, np.zeros(5), w, spacing=0.05, preload=300.0).stiffness
                      for w in SPEEDS])
    coef = rotordynamics.from_stiffness(stiff, SPEEDS)
    path = rotordynamics.write_coefficients(coef, tmp_path / "spindle.json")
    element = ross.BearingElement(n=3, **json.loads(path.read_text()))
    assert float(element.kxx_interpolated(SPEEDS[2])) == pytest.approx(stiff[2, 0, 0], rel=1e-12)
    assert float(element.kzz_interpolated(SPEEDS[1])) == pytest.approx(stiff[1, 2, 2], rel=1e-12)


def test_from_stiffness_checks_its_input():
    with pytest.raises(InputError, match="stiffness must have shape"):
        rotordynamics.from_stiffness(np.eye(5), [0.0])
    with pytest.raises(InputError, match="finite"):
        rotordynamics.from_stiffness(np.full((1, 5, 5), np.nan), [0.0])

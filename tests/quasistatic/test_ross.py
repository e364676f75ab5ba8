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


def test_bearing_element_from_the_exported_dictionary():
    coef = rotordynamics.bearing_coefficients(SPINDLE, LOADS, SPEEDS)
    element = ross.BearingElement(n=0, **coef)
    ref = combined.combined_analysis(SPINDLE, np.broadcast_to(LOADS, (4, 5)), SPEEDS).stiffness
    for k, speed in enumerate(SPEEDS):
        assert element.kxx_interpolated(speed) == pytest.approx(ref[k, 0, 0], rel=1e-9)
        assert element.kyy_interpolated(speed) == pytest.approx(ref[k, 1, 1], rel=1e-9)
        assert element.kxy_interpolated(speed) == pytest.approx(ref[k, 0, 1], rel=1e-9, abs=1e-6 * ref[k, 0, 0])
    assert_allclose(coef["kzz"], ref[:, 2, 2])
    assert np.all(np.diff(coef["kxx"]) < 0)  # centrifugal softening of the radial stiffness


def test_set_stiffness_round_trip_through_a_file(tmp_path):
    stiff = np.stack([sets.set_analysis(SPINDLE, np.zeros(5), w, spacing=0.05, preload=300.0).stiffness
                      for w in SPEEDS])
    coef = rotordynamics.from_stiffness(stiff, SPEEDS)
    path = rotordynamics.write_coefficients(coef, tmp_path / "spindle.json")
    element = ross.BearingElement(n=3, **json.loads(path.read_text()))
    assert element.kxx_interpolated(SPEEDS[2]) == pytest.approx(stiff[2, 0, 0], rel=1e-12)
    assert element.kzz_interpolated(SPEEDS[1]) == pytest.approx(stiff[1, 2, 2], rel=1e-12)


def test_from_stiffness_checks_its_input():
    with pytest.raises(InputError, match="stiffness must have shape"):
        rotordynamics.from_stiffness(np.eye(5), [0.0])
    with pytest.raises(InputError, match="finite"):
        rotordynamics.from_stiffness(np.full((1, 5, 5), np.nan), [0.0])

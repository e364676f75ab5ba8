"""Rig loads of the friction lab (bearinglab.lab.rig): the hung mass and the tilt -> F_a, F_r, P0."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from bearinglab import friction
from bearinglab.errors import InputError
from bearinglab.lab import rig

FAST = settings(max_examples=40, deadline=None)


def test_vanishing_load_component_is_exactly_zero():
    fa, fr = rig.rig_loads(2.0, math.radians(90.0))
    assert fa == 0.0 and fr == 2 * 9.81
    fa, fr = rig.rig_loads(2.0, 0.0)
    assert fr == 0.0 and fa == 2 * 9.81
    fa, fr = rig.rig_loads([0.5, 1.0], np.radians([90.0, 0.0]))
    assert fa[0] == 0.0 and fr[1] == 0.0


@FAST
@given(q=st.floats(0.01, 50.0), beta=st.floats(0.0, 90.0), tare=st.floats(0.0, 2.0))
def test_rig_loads_resolve_the_weight(q, beta, tare):
    fa, fr = rig.rig_loads(q, math.radians(beta), tare_mass=tare)
    assert math.hypot(fa, fr) == pytest.approx(9.81 * (q + tare), rel=1e-12)
    assert fa >= 0 and fr >= 0
    p = rig.rig_equivalent_load(q, math.radians(beta), tare_mass=tare)
    assert p.equivalent_load == friction.equivalent_static_load(fr, fa)
    switch = math.degrees(rig.branch_switch_tilt())
    if abs(beta - switch) > 1e-9:  # the two branches are equal at the switch itself
        assert bool(p.combined) == (beta < switch)


def test_tare_and_gravity_options():
    assert rig.rig_loads(1.0, math.pi / 2, tare_mass=0.25).radial_load == pytest.approx(
        1.25 * 9.81, rel=1e-15
    )
    assert rig.rig_loads(1.0, math.pi / 2, gravity=9.80665).radial_load == 9.80665
    with pytest.raises(InputError, match=r"tare_mass must be >= 0 \[kg\]"):
        rig.rig_loads(1.0, 0.0, tare_mass=-0.1)


def test_rig_rejects_zero_mass_and_tilt_outside_0_90():
    # spec 001 section 10.3: Q = 0 or beta = 95 -> error
    with pytest.raises(InputError, match=r"mass must be > 0 \[kg\], got 0\.0"):
        rig.rig_loads(0.0, 0.0)
    with pytest.raises(InputError, match=r"tilt must be in \[0, 90\] \[deg\], got 95\.0"):
        rig.rig_loads(1.0, math.radians(95.0))
    with pytest.raises(InputError, match=r"tilt must be in \[0, 90\] \[deg\], got -1\.0"):
        rig.rig_equivalent_load(1.0, math.radians(-1.0))


def test_branch_switch_tilt_errors_and_angular_rows():
    with pytest.raises(InputError, match="radial_factor must be < 1"):
        rig.branch_switch_tilt(1.0, 0.5)
    p = rig.rig_equivalent_load(
        1.0, 0.0, gravity=1.0, bearing_type="angular", contact_angle=math.radians(26)
    )
    assert p.equivalent_load == pytest.approx(0.37, rel=1e-15)

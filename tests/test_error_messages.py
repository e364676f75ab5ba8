"""Every checked input of the rating and high-speed models names itself, its rule, its unit and the bad value.

Mutation testing (TESTING.md, issue 14) found that the error paths of ``ratings.dynamic``,
``ratings.lubrication`` and ``quasistatic.equations`` were tested for raising but not for what they say:
a mutant that dropped the parameter's name or changed its unit survived. These tests call each function
with valid inputs, spoil one input at a time, and read the whole message.
"""

from __future__ import annotations

import math
import re

import pytest

from bearinglab import quasistatic
from bearinglab.errors import InputError
from bearinglab.ratings import dynamic, lubrication

DEG = math.pi / 180.0

# The B218 of spec 004 (table 1): Z, D, d_m, f_i, f_e, alpha0, E', density.
B218 = {"n_balls": 16, "ball_diameter": 22.225e-3, "pitch_diameter": 125.26e-3, "inner_conformity": 0.52,
        "outer_conformity": 0.52, "free_angle": 40.0 * DEG, "reduced_modulus": 2.275e11, "density": 7850.0}


def _message(call, **spoiled):
    with pytest.raises(InputError) as info:
        call(**spoiled)
    return str(info.value)


def _expect(message, name, rule, unit, shown):
    """The message reads '<name> must be <rule> [<unit>], got <value>' (the project's check format)."""
    pattern = rf"^{re.escape(name)} must be {re.escape(rule)} \[{re.escape(unit)}\], got {re.escape(shown)}"
    assert re.match(pattern, message), message


def _dynamic(**over):
    args = {"radial_load": 1000.0, "axial_load": 500.0, "static_load_rating": 7800.0, "static_load_factor": 13.9}
    args.update(over)
    return dynamic.dynamic_load_factors(**args)


@pytest.mark.parametrize(("name", "bad", "rule", "unit", "shown"), [
    ("radial_load", -1.0, ">= 0", "N", "-1.0"),
    ("axial_load", -2.5, ">= 0", "N", "-2.5"),
    ("static_load_rating", 0.0, "> 0", "N", "0.0"),
    ("static_load_factor", -13.9, "> 0", "N/mm^2", "-13.9"),
])
def test_dynamic_load_factors_names_the_bad_input(name, bad, rule, unit, shown):
    _expect(_message(_dynamic, **{name: bad}), name, rule, unit, shown)


def test_dynamic_load_factors_names_the_missing_f0_and_the_bearing_types():
    assert "static_load_factor" in _message(_dynamic, static_load_factor=None)
    message = _message(_dynamic, bearing_type="taper")
    assert message == ("bearing_type must be one of ['radial', 'angular', 'four-point', 'double-row-angular', "
                       "'double-row-radial', 'self-aligning', 'thrust'], got 'taper'")  # the types of issue 30


def _aiso(**over):
    args = {"viscosity_ratio": 1.0, "contamination_factor": 0.5, "fatigue_load_limit": 300.0,
            "equivalent_dynamic_load": 3000.0}
    args.update(over)
    return lubrication.life_modification_factor(**args)


@pytest.mark.parametrize(("name", "bad", "rule", "unit", "shown"), [
    ("viscosity_ratio", 0.0, "> 0", "-", "0.0"),
    ("contamination_factor", -0.1, ">= 0", "-", "-0.1"),
    ("contamination_factor", 1.5, "in [0, 1]", "-", "1.5"),
    ("fatigue_load_limit", -300.0, ">= 0", "N", "-300.0"),
    ("equivalent_dynamic_load", 0.0, "> 0", "N", "0.0"),
])
def test_life_modification_factor_names_the_bad_input(name, bad, rule, unit, shown):
    _expect(_message(_aiso, **{name: bad}), name, rule, unit, shown)


def _residual(**over):
    args = {"contact_angle_inner": 41.0 * DEG, "contact_angle_outer": 39.0 * DEG, "axial_load": 20e3,
            "shaft_speed": 1000.0, **B218}
    args.update(over)
    return quasistatic.angle_residual(**args)


def test_angle_residual_accepts_the_valid_inputs_it_is_spoiled_from():
    # the spoiled calls below fail for the one input they change, not for the others
    r = _residual()
    assert bool(r.valid) and math.isfinite(float(r.radial)) and math.isfinite(float(r.ring))


@pytest.mark.parametrize(("name", "bad", "rule", "unit", "shown"), [
    ("contact_angle_inner", 0.0, "in (0, 90)", "deg", "0.0"),
    ("contact_angle_outer", 95.0 * DEG, "in (0, 90)", "deg", "95.0"),
    ("axial_load", -1.0, "> 0", "N", "-1.0"),
    ("n_balls", 16.5, "an integer >= 1", "-", "16.5"),
    ("ball_diameter", 0.0, "> 0", "m", "0.0"),
    ("pitch_diameter", -0.1, "> 0", "m", "-0.1"),
    ("inner_conformity", 0.5, "in (0.5, inf)", "-", "0.5"),
    ("outer_conformity", 0.4, "in (0.5, inf)", "-", "0.4"),
    ("free_angle", -DEG, "in (0, 90)", "deg", "-1.0"),
    ("reduced_modulus", 0.0, "> 0", "Pa", "0.0"),
    ("density", -7850.0, "> 0", "kg/m^3", "-7850.0"),
])
def test_angle_residual_names_the_bad_input(name, bad, rule, unit, shown):
    _expect(_message(_residual, **{name: bad}), name, rule, unit, shown)


def test_angle_residual_names_a_negative_speed_in_rpm():
    message = _message(_residual, shaft_speed=-10.0)
    assert message.startswith("shaft_speed must be >= 0 and finite [rpm], got ")
    assert "-95.49" in message  # -10 rad/s shown in rpm, the unit engineers read

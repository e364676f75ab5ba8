"""Issue 28 item 2: one function turns an InputError into a RunFailure that names its field
(``calculations._failures.run_failure``); each boundary words it its own way."""

import pytest

from bearinglab.calculations import CALCULATIONS, RequestError, RunFailure, parse
from bearinglab.calculations._failures import failures, run_failure
from bearinglab.cli._common import request_message
from bearinglab.errors import ConvergenceError, InputError

LIFE = CALCULATIONS["life"]


def test_the_field_a_message_opens_with_and_the_options_it_names():
    f = run_failure(InputError("radial-load: give --fx or --radial-load, not both"), LIFE)
    assert (f.parameter, f.template) == ("radial_load", "{name}: give {field:fx} or {field:radial_load}, not both")
    assert f.worded(lambda n: n) == "radial_load: give fx or radial_load, not both"  # the API
    assert request_message(f) == "radial-load: give --fx or --radial-load, not both"  # the command line
    assert f.worded(lambda n: LIFE.field(n).title) == (  # the page
        "Radial load F_r: give F_x or Radial load F_r, not both")


@pytest.mark.parametrize("message, parameter", [
    ("viscosity-index must be <= 400, got 500", "viscosity_index"),  # the longer name first
    ("viscosity must be > 0 [cSt], got -1 cSt", "viscosity"),
    ("speed: '3 kN' is not a speed", "speed"),
    ("speedy: no such thing", None),  # a name must end where the field's does
    ("the bearing has no ratings", None),
])
def test_the_head_names_the_field_only_where_it_is_one(message, parameter):
    assert run_failure(message, LIFE).parameter == parameter


def test_a_library_name_names_a_field_only_where_the_request_gives_it():
    # pitch_diameter of a catalog bearing is not an input of the request; n_balls is the field balls
    given = {"bearing": "6208", "balls": 9}
    assert run_failure("pitch_diameter of '6208' is not known", LIFE, given).parameter is None
    assert run_failure("pitch_diameter of '6208' is not known", LIFE).parameter == "pitch_diameter"
    f = run_failure("n_balls must be <= 15, got 16", LIFE, given)
    assert (f.parameter, f.value, f.template) == ("balls", 9, "{name} must be <= 15, got 16")
    assert run_failure("n_balls must be <= 15, got 16", LIFE, {"bearing": "6208"}).parameter is None


def test_a_usage_error_names_the_option_it_quotes():
    f = run_failure("Invalid value for '--axial-load' / '-A' / '-F': '2 m'", CALCULATIONS["high-speed"])
    assert (f.parameter, f.template) == ("axial_load", "Invalid value for {field:axial_load}: '2 m'")
    f = run_failure("Missing option '--speed' / '-n'.", CALCULATIONS["high-speed"])
    assert (f.parameter, f.template) == ("speed", "Missing {field:speed}.")


def test_options_kept_as_written_and_a_default_field():
    friction = CALCULATIONS["friction"]
    f = run_failure("oil-level: --lubrication oil-bath needs --oil-level", friction, options=False)
    assert (f.parameter, f.template) == ("oil_level", "{name}: --lubrication oil-bath needs --oil-level")
    f = run_failure("no such grade", friction, field="oil")
    assert (f.parameter, f.template) == ("oil", "{name}: no such grade")


def test_convergence_and_a_request_error_pass_through_with_their_kind():
    exc = ConvergenceError("contact_angles", iterations=30, residual=1.0, estimate=0.0)
    assert run_failure(exc, LIFE).kind == "convergence"
    physical = ConvergenceError("contact_angles", iterations=3, residual=1.0, estimate=0.0, reason="ball leaves",
                                physical=True)
    assert run_failure(physical, LIFE).kind == "input"
    error = RequestError("speed", "x", "a speed", "{name}: x")
    assert run_failure(error, LIFE) is error


def test_failures_of_a_request():
    parsed = parse("life", {"bearing": "6208", "radial_load": "5 kN"})
    with pytest.raises(RunFailure) as err, failures(parsed):
        raise InputError("fx: give --fx or --radial-load, not both")
    assert err.value.parameter == "fx" and err.value.value is None  # fx was not given
    with pytest.raises(RunFailure) as err, failures(LIFE, field="speed"):
        raise InputError("negative")
    assert (err.value.parameter, err.value.template) == ("speed", "{name}: negative")

"""The native documents of clearance, film, temperature, runout and runout-monte-carlo (issue 22 item 1;
life, load-distribution and bearing-set: ``test_native.py``): ``run(parse(...))`` computes what
``bearinglab ... --json`` prints without running the command line, and a bad input names its field."""

import json
import tomllib
from pathlib import Path

import pytest

from bearinglab import calculations, cli
from bearinglab.calculations import RequestError, RunFailure, documents, parse, run

#: calculation, request, the command line's words for the same request
CASES = [
    ("clearance", {"bearing": "6205-2RS", "shaft_fit": "k5", "housing_fit": "H7",
                   "inner_ring_temperature": "50 degC", "speed": "6000 rpm"}, None),
    ("clearance", {"bearing": "6208", "shaft_interference": "5 um, 20 um", "housing_fit": "J7",
                   "shaft_roughness": "4 um", "clearance_class": "C3", "monte_carlo": "300",
                   "seed": "7", "distribution": "normal"}, None),
    ("clearance", {"bearing": "6205-2RS", "radial_clearance": "6 um, 20 um", "shaft_fit": "m6",
                   "housing_material": "aluminium", "outer_ring_temperature": "60 degC"}, None),
    ("film", {"bearing": "B218", "fz": "10 kN", "speed": "3000, 6000 rpm", "viscosity": "20 cSt"}, None),
    ("film", {"bearing": "6208", "radial_load": "1 kN", "speed": "6000 rpm", "oil": "VG68",
              "temperature": "70 degC", "loads_at": "rest", "lubrication": "grease",
              "roughness_ball": "0.05 um", "roughness_race": "0.2 um", "density": "880 kg/m^3"}, None),
    ("film", {"bearing": "6208", "radial_load": "500 N", "speed": "3000, 9000 rpm", "oil": "VG32",
              "temperature": "auto", "thermal_resistance": "2 K/W"}, None),
    ("film", {"balls": "9", "ball_diameter": "7.938 mm", "pitch_diameter": "39 mm",
              "inner_conformity": "0.52", "outer_conformity": "0.53", "radial_clearance": "10 um",
              "fx": "2 kN", "my": "1 N*m", "speed": "4000 rpm", "dynamic_viscosity": "30 cP",
              "pressure_viscosity_coefficient": "20 1/GPa"}, None),
    ("temperature", {"bearing": "6205-2RS", "radial_load": "1 kN", "speed": "6000 rpm", "oil": "VG32",
                     "thermal_resistance": "1 K/W"}, None),
    ("temperature", {"bearing": "6208", "radial_load": "2 kN", "axial_load": "300 N",
                     "speed": "3000, 6000 rpm", "oil": "VG68", "viscosity_index": "120",
                     "lubrication": "oil-air", "oil_flow": "0.5 l/min", "oil_inlet_temperature": "35 degC",
                     "ambient": "25 degC"}, None),
    ("temperature", {"bearing": "B218", "axial_load": "5 kN", "speed": "3000 rpm", "oil": "VG46",
                     "viscosity_100": "6.5 cSt", "skf_constants": "5e-7,1.9,1.9e-12,0.013,0.7,1.9e-12",
                     "max_temperature": "200 degC"}, None),
    ("temperature", {"bearing": "6208", "radial_load": "1 kN", "speed": "3000, 6000 rpm", "oil": "VG46",
                     "reference_speed": "true"}, None),
]


@pytest.fixture
def no_command_line():
    """The layer cannot run the command line: every calculation has a document function of its own
    (the runner that called the command's function and read its output is gone for good)."""
    from bearinglab.calculations import CALCULATIONS

    assert not [n for n in ("_call_command", "_run_command", "_command_document") if hasattr(documents, n)]
    assert set(CALCULATIONS) - {"catalog", "catalog-search"} <= set(documents._NATIVE)


def _printed(name, given, words):
    words = words or calculations.argv(parse(name, given))
    printed = cli.run_json(words)
    assert printed.exit_code == 0, printed.error
    return printed.document


@pytest.mark.parametrize("name, given, words", CASES, ids=[f"{n}-{i}" for i, (n, _, _) in enumerate(CASES)])
def test_the_native_document_is_what_the_command_line_prints(name, given, words, no_command_line):
    assert name in documents._NATIVE
    printed = _printed(name, given, words)  # the command computes it by the same function
    assert json.loads(json.dumps(run(parse(name, given)))) == printed


#: calculation, request, the field at fault, words of the message
FAILURES = [
    ("clearance", {"bearing": "6205-2RS", "shaft_fit": "k9"}, "shaft_fit", "must be one of"),
    ("clearance", {"bearing": "6205-2RS", "shaft_fit": "k5", "shaft_interference": "5 um"},
     "shaft_interference", "give {field:shaft_fit} or {field:shaft_interference}"),
    ("clearance", {"bearing": "6205-2RS", "shaft_fit": "k5", "shaft_bore": "25 mm"}, "shaft_bore",
     "must be < the bearing bore"),
    ("film", {"bearing": "6208", "radial_load": "1 kN", "speed": "6000 rpm", "viscosity": "20 cSt",
              "dynamic_viscosity": "13 cP"}, "dynamic_viscosity", "give {field:dynamic_viscosity}"),
    ("film", {"bearing": "6208", "radial_load": "1 kN", "speed": "6000 rpm", "oil": "VG33",
              "temperature": "60 degC"}, "oil", "must be an ISO VG grade"),
    ("temperature", {"bearing": "6208", "radial_load": "1 kN", "speed": "6000 rpm", "oil": "VG32",
                     "oil_inlet_temperature": "40 degC"}, "oil_flow", "{field:oil_inlet_temperature}"),
]


@pytest.mark.parametrize("name, given, parameter, words", FAILURES)
def test_a_failure_names_its_field_with_no_option(name, given, parameter, words, no_command_line):
    with pytest.raises(RunFailure) as err:
        run(parse(name, given))
    assert err.value.parameter == parameter
    assert words in err.value.template and "--" not in err.value.template
    assert err.value.template.startswith("{name}")


def test_an_angular_bearing_without_skf_constants_names_no_field(no_command_line):
    # SKF publishes its angular-contact constants for 40 deg bearings only (B218 runs): a 12 deg bearing's
    # missing constants are data the user did not give, not a field at fault (the page leaves it out)
    doc = run(parse("temperature", {"bearing": "B218", "axial_load": "5 kN", "speed": "6000 rpm",
                                    "oil": "VG32"}))
    assert doc["inputs"]["bearing"] == "B218"  # computed (here a thermal runaway), not refused
    with pytest.raises(RunFailure) as err:
        run(parse("temperature", {"bearing": "4-1006095", "axial_load": "20 N", "speed": "3000 rpm",
                                  "oil": "VG68"}))
    assert err.value.parameter is None and "12 deg is not covered" in err.value.template


_EXAMPLES = Path(__file__).resolve().parents[2] / "examples" / "runout"


@pytest.mark.parametrize("example, given, words", [
    ("example1_oversize_ball.toml", {"angle": "30 deg"}, ["--angle=30 deg"]),
    ("example3_mixed.toml", {"bearing": "7218B", "refine": "true"}, ["--bearing=7218B", "--refine"]),
    ("example2_inner_ovality.toml", {"revolutions": "2", "steps_per_rev": "36", "start_angle": "5 deg"},
     ["--revolutions=2", "--steps-per-rev=36", "--start-angle=5 deg"]),
    ("example4_tilt.toml", {"revolutions": "1", "steps_per_rev": "24", "cage_ratio": "0.4"},
     ["--revolutions=1", "--steps-per-rev=24", "--cage-ratio=0.4"]),
])
def test_runout_of_a_posted_error_set_is_what_the_command_prints_for_its_file(example, given, words,
                                                                               no_command_line):
    path = _EXAMPLES / example
    printed = cli.run_json(["runout", f"--errors={path}", *words])
    assert printed.exit_code == 0, printed.error
    text = path.read_text(encoding="utf-8")
    doc = json.loads(json.dumps(run(parse("runout", {"errors": text, **given}))))
    assert doc["errors_file"] == "(posted document)"
    assert doc == dict(printed.document, errors_file="(posted document)")
    as_json = json.dumps(tomllib.loads(text))  # the same error set posted as JSON
    assert json.loads(json.dumps(run(parse("runout", {"errors": as_json, **given})))) == doc


def test_a_posted_error_set_names_no_file_and_a_bad_one_names_the_field(no_command_line):
    text = (_EXAMPLES / "measured_profile.toml").read_text(encoding="utf-8")
    with pytest.raises(RequestError) as err:  # it names its profile file: refused, nothing read
        run(parse("runout", {"errors": text}))
    assert err.value.parameter == "errors" and "cannot refer to files" in err.value.template
    bad = (_EXAMPLES / "example1_oversize_ball.toml").read_text(encoding="utf-8") + "\n[bogus]\nx = 1\n"
    with pytest.raises(RequestError) as err:
        run(parse("runout", {"errors": bad}))
    assert err.value.parameter == "errors" and "the posted document" in err.value.template
    assert "bogus" in err.value.template


MC = {"bearing": "7218B", "samples": "4", "steps_per_rev": "12", "revolutions": "1", "seed": "3"}


def test_runout_monte_carlo_is_what_the_command_prints(no_command_line):
    printed = cli.run_json(["runout", "monte-carlo", "--bearing=7218B", "--samples=4", "--steps-per-rev=12",
                            "--revolutions=1", "--seed=3"])
    assert printed.exit_code == 0, printed.error
    assert json.loads(json.dumps(run(parse("runout-monte-carlo", MC)))) == printed.document
    assert printed.document["samples"] == 4 and printed.document["seed"] == 3


def test_runout_monte_carlo_is_bit_identical_for_a_seed_and_differs_for_another(no_command_line):
    first, again = run(parse("runout-monte-carlo", MC)), run(parse("runout-monte-carlo", MC))
    assert json.dumps(first) == json.dumps(again)
    other = run(parse("runout-monte-carlo", {**MC, "seed": "4"}))
    assert other["radial_ptp_max_um"] != first["radial_ptp_max_um"]


def test_runout_monte_carlo_samples_are_the_cases():
    assert parse("runout-monte-carlo", MC).cases == 4
    assert parse("runout-monte-carlo", {"bearing": "7218B"}).cases == 200  # the default
    with pytest.raises(RequestError, match="more than the limit") as err:
        parse("runout-monte-carlo", {"bearing": "7218B", "samples": str(calculations.CASE_LIMIT + 1)})
    assert err.value.parameter == "samples"
    assert parse("runout-monte-carlo", {"bearing": "7218B", "samples": "10"}, limit=10).cases == 10
    with pytest.raises(RequestError):
        parse("runout-monte-carlo", {"bearing": "7218B", "samples": "11"}, limit=10)


def test_a_runout_sequence_counts_its_positions_with_steps_alone():
    # steps_per_rev alone runs 3 revolutions: the positions are bounded, not only with revolutions
    assert parse("runout", {"errors": "x", "steps_per_rev": "100"}).cases == 300
    with pytest.raises(RequestError, match="more than the limit"):
        parse("runout", {"errors": "x", "steps_per_rev": "50000"})


def test_a_posted_error_set_without_geometry_asks_for_a_bearing_in_web_words(no_command_line):
    text = '[errors.balls]\nunit = "um"\ndiameter = [1.0, 0.0, 0.0]\n'
    with pytest.raises(RequestError) as err:
        run(parse("runout", {"errors": text}))
    assert err.value.parameter == "errors" and "no [geometry] table" in err.value.template
    assert "--" not in err.value.template and "a catalog bearing" in err.value.template

"""frequencies, stand-load, axial-angle and high-speed are native calculations: their documents are
computed by ``bearinglab.calculations`` (no command line runs), and equal what the command prints."""

import json

import pytest

from bearinglab import calculations, cli
from bearinglab.calculations import RunFailure, documents, parse, run

CASES = [
    ("frequencies", {"bearing": "6205-2RS", "speed": "1797 rpm"}),
    ("frequencies", {"bearing": "6205-2RS", "speed": "1797 rpm", "mask": "true", "harmonics": "2",
                     "sidebands": "2", "band": "1 %"}),
    ("frequencies", {"bearing": "4-1006095", "speed": "3000 rpm", "axial_load": "2 kgf", "hertz": "table",
                     "outer_speed": "-100 rpm", "mask": "true"}),
    ("frequencies", {"balls": "9", "ball_diameter": "7.94 mm", "pitch_diameter": "39.04 mm",
                     "inner_conformity": "0.52", "outer_conformity": "0.53", "contact_angle": "0 deg",
                     "speed": "50 Hz"}),
    ("stand-load", {"bearing": "4-1006095", "speed": "3000 rpm"}),
    ("stand-load", {"bearing": "4-1006095", "speed": "1000, 3000, 10000 rpm", "balls": "8"}),
    ("axial-angle", {"bearing": "4-1006095", "axial_load": "2 kgf"}),
    ("axial-angle", {"bearing": "4-1006095", "axial_load": "2 kgf", "legacy": "true"}),
    ("axial-angle", {"bearing": "4-1006095", "axial_load": "1kgf:3kgf:1kgf", "hertz": "table",
                     "elastic_constant": "paper"}),
    ("axial-angle", {"bearing": "4-1006095", "axial_load": "2 kgf", "rows": "3", "x0": "0.04"}),
    ("high-speed", {"bearing": "B218", "axial_load": "20 kN", "speed": "10000 rpm"}),
    ("high-speed", {"bearing": "B218", "axial_load": "5kN:15kN:5kN", "speed": "0, 6000 rpm",
                    "constants": "harris", "raceway_control": "inner"}),
    ("high-speed", {"bearing": "6208", "axial_load": "2 kN", "speed": "3000 rpm", "shaft_fit": "j5",
                    "clearance_class": "C3", "inner_ring_temperature": "40 degC"}),
    ("high-speed", {"bearing": "B218", "axial_load": "20 kN", "speed": "1000 rpm", "solver": "angle-iteration",
                    "reduced_modulus": "228.04 GPa", "balls": "16"}),
]


@pytest.fixture
def no_command_line():
    """The layer cannot run the command line: every calculation has a document function of its own
    (the runner that called the command's function and read its output is gone for good)."""
    from bearinglab.calculations import CALCULATIONS

    assert not [n for n in ("_call_command", "_run_command", "_command_document") if hasattr(documents, n)]
    assert set(CALCULATIONS) - {"catalog", "catalog-search"} <= set(documents._NATIVE)


@pytest.mark.parametrize("name, given", CASES, ids=[f"{n}-{i}" for i, (n, _) in enumerate(CASES)])
def test_the_native_document_is_what_the_command_prints(name, given, no_command_line):
    parsed = parse(name, given)
    doc = run(parsed)
    printed = cli.run_json(calculations.argv(parsed))
    assert printed.exit_code == 0, printed.error
    assert json.loads(json.dumps(doc)) == printed.document


@pytest.mark.parametrize("name, given, parameter, words", [
    ("frequencies", {"bearing": "6205-2RS", "speed": "100 rpm", "outer_speed": "100 rpm"}, "speed",
     "speed: the rings must turn relative to each other"),
    ("frequencies", {"bearing": "6205-2RS", "speed": "100 rpm", "band": "wide"}, "band",
     "band: cannot read 'wide'"),
    ("stand-load", {"bearing": "4-1006095", "speed": "-5 rpm"}, "speed", "speed must be >= 0 [rpm]"),
    ("axial-angle", {"bearing": "NOPE-1", "axial_load": "2 kgf"}, "bearing", "bearing"),
])
def test_a_failure_names_the_field_and_the_command_line_the_option(name, given, parameter, words,
                                                                   no_command_line, capsys):
    parsed = parse(name, given)
    with pytest.raises(RunFailure) as err:
        run(parsed)
    assert err.value.parameter == parameter
    assert err.value.worded(lambda n: f"<{n}>").startswith(f"<{parameter}>")
    assert words in err.value.worded(lambda n: n.replace("_", "-"))
    code = cli.main([*calculations.argv(parsed), "--json"])
    line = capsys.readouterr().err.strip()
    assert code == 2 and line == "bearinglab: error: " + err.value.worded(lambda n: n.replace("_", "-"))


def test_the_high_speed_figure_is_drawn_from_the_solve_without_the_command_line(no_command_line):
    parsed = parse("high-speed", {"bearing": "B218", "axial_load": "5kN:15kN:5kN", "speed": "0, 6000 rpm"})
    svg = calculations.figure_svg(parsed)
    assert svg.startswith("<svg") and "high-speed contact angles under thrust" in svg
    one = parse("high-speed", {"bearing": "B218", "axial_load": "5 kN", "speed": "6000 rpm"})
    assert calculations.figure_svg(one) == ""  # one thrust: no map


def test_the_mounting_inputs_give_the_operating_clearance_of_the_clearance_calculation():
    """high-speed at the probable operating clearance that ``clearance`` computes for the same inputs."""
    mounting = {"bearing": "6208", "shaft_fit": "j5", "housing_fit": "H7", "clearance_class": "C3",
                "inner_ring_temperature": "40 degC"}
    doc = run(parse("high-speed", {**mounting, "axial_load": "2 kN", "speed": "3000 rpm"}))
    chain = run(parse("clearance", {**mounting, "speed": "3000 rpm"}))
    assert doc["operating_clearance_um"] == pytest.approx(chain["operating_clearance_probable_um"], rel=1e-12)
    assert doc["geometry"]["radial_clearance_um"] == pytest.approx(doc["operating_clearance_um"], rel=1e-12)

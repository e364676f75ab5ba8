"""friction (``friction torque``, every model) is a native calculation: its document is computed by
``bearinglab.calculations.friction_torque`` (no command line runs) and equals what the command prints."""

import json

import pytest

from bearinglab import calculations, cli
from bearinglab.calculations import RunFailure, documents, parse, run

CASES = [
    ("friction", {"bearing": "101", "radial_load": "10 N", "axial_load": "5 N", "speed": "3000 rpm"}),
    ("friction", {"bearing": "101", "radial_load": "0N:20N:10N", "speed": "3000 rpm", "mu": "0.002"}),
    ("friction", {"type": "angular", "contact_angle": "15 deg", "bore": "12 mm", "mean_diameter": "20 mm",
                  "static_load_rating": "2227 N", "radial_load": "10 N", "axial_load": "20 N",
                  "speed": "1000 rpm", "model": "two-term", "f0": "2e-7"}),
    ("friction", {"bearing": "101", "radial_load": "10 N", "speed": "3000 rpm", "model": "palmgren",
                  "viscosity": "20 cSt", "palmgren_f0": "1.5", "f": "0.001", "c": "1"}),
    ("friction", {"bearing": "6205-2RS", "radial_load": "0N:100N:50N", "speed": "3000 rpm", "model": "skf",
                  "lubrication": "oil-jet", "viscosity": "30 cSt"}),
    ("friction", {"bearing": "6205-2RS", "radial_load": "100 N", "speed": "3000 rpm", "model": "skf",
                  "lubrication": "oil-bath", "oil_level": "3 mm", "drag_loss_factor": "0.0003",
                  "oil": "VG68", "temperature": "60 degC"}),
    ("friction", {"bearing": "6208", "radial_load": "1 kN", "axial_load": "200 N", "speed": "6000 rpm",
                  "model": "skf", "oil": "VG32", "temperature": "70 degC", "viscosity_index": "120",
                  "series": "62"}),
]


@pytest.fixture
def no_command_line(monkeypatch):
    def refuse(*args, **kwargs):
        raise AssertionError("the layer ran the command line")

    monkeypatch.setattr(documents, "_call_command", refuse)
    monkeypatch.setattr(documents, "_run_command", refuse)


@pytest.mark.parametrize("name, given", CASES, ids=[f"{g.get('model', 'one-term')}-{i}"
                                                   for i, (_, g) in enumerate(CASES)])
def test_the_native_document_is_what_the_command_prints(name, given, no_command_line):
    parsed = parse(name, given)
    doc = run(parsed)
    printed = cli.run_json(calculations.argv(parsed))
    assert printed.exit_code == 0, printed.error
    assert json.loads(json.dumps(doc)) == printed.document


@pytest.mark.parametrize("given, parameter, words", [
    ({"bearing": "101", "radial_load": "10 N", "model": "two-term"}, "f0", "f0: the two-term model needs"),
    ({"bearing": "6205-2RS", "radial_load": "10 N", "model": "skf"}, "viscosity", "viscosity: the skf model"),
    ({"bearing": "6205-2RS", "radial_load": "10 N", "model": "skf", "viscosity": "30 cSt",
      "lubrication": "oil-bath"}, "oil_level", "needs --oil-level"),
    ({"bearing": "101", "radial_load": "10 N", "series": "62"}, "series", "only the skf model"),
    ({"bearing": "101", "radial_load": "10 N, 20 N", "speed": "1, 2, 3 rpm"}, "radial_load",
     "lists are paired element by element"),
])
def test_a_failure_names_the_field_and_the_command_line_the_option(given, parameter, words, no_command_line,
                                                                   capsys):
    parsed = parse("friction", given)
    with pytest.raises(RunFailure) as err:
        run(parsed)
    assert err.value.parameter == parameter
    cli_words = err.value.worded(lambda n: n.replace("_", "-"))
    assert words in cli_words
    code = cli.main([*calculations.argv(parsed), "--json"])
    assert code == 2 and capsys.readouterr().err.strip() == "bearinglab: error: " + cli_words

"""The layer's documents are the command line's: ``run(parse(...))`` equals ``bearinglab ... --json``."""

import json

import pytest

from bearinglab import calculations, cli
from bearinglab.calculations import RequestError, RunFailure, parse, run

CASES = [
    ("high-speed", {"bearing": "B218", "axial_load": "20 kN", "speed": "10000 rpm", "constants": "harris"}),
    ("high-speed", {"bearing": "B218", "axial_load": "5kN:15kN:5kN", "speed": "0, 6000 rpm"}),
    ("axial-angle", {"bearing": "4-1006095", "axial_load": "2 kgf"}),
    ("stand-load", {"bearing": "4-1006095", "speed": "3000 rpm"}),
    ("frequencies", {"bearing": "6205-2RS", "speed": "1797 rpm", "mask": "true"}),
    ("life", {"bearing": "6205-2RS", "radial_load": "2 kN", "speed": "1797 rpm", "oil": "VG68",
              "temperature": "70 degC", "contamination": "normal", "reliability": "99"}),
    ("load-distribution", {"bearing": "B218", "axial_load": "5 kN", "radial_load": "10 kN", "my": "2 N*m"}),
    ("bearing-set", {"bearing": "7218B", "arrangement": "DF", "preload": "500 N", "fx": "1 kN"}),
    ("friction", {"bearing": "101", "radial_load": "10 N", "axial_load": "5 N", "speed": "3000 rpm"}),
    ("friction", {"bearing": "6205-2RS", "radial_load": "0N:100N:50N", "speed": "3000 rpm", "model": "skf",
                  "lubrication": "oil-jet", "viscosity": "30 cSt"}),
    ("friction", {"bearing": "101", "radial_load": "10 N", "speed": "3000 rpm", "model": "palmgren",
                  "viscosity": "20 cSt", "palmgren_f0": "1.5"}),
    ("catalog", {"name": "B218"}),
    ("catalog", {"name": "6205-2RS"}),
    ("catalog", {"name": "6208-2RS1/C3", "clearance": "max"}),
    ("catalog", {"name": "B218", "radial_clearance": "9 um"}),
    ("clearance", {"bearing": "6205-2RS", "shaft_fit": "k5", "housing_fit": "H7",
                   "inner_ring_temperature": "50 degC", "speed": "6000 rpm"}),
    ("clearance", {"bearing": "6205-2RS", "shaft_interference": "5 um, 20 um", "monte_carlo": "200",
                   "seed": "3", "distribution": "normal"}),
    ("film", {"bearing": "B218", "fz": "10 kN", "speed": "3000, 6000 rpm", "viscosity": "20 cSt"}),
    ("film", {"bearing": "6208", "radial_load": "1 kN", "speed": "6000 rpm", "oil": "VG68",
              "temperature": "70 degC", "loads_at": "rest", "lubrication": "grease"}),
    ("temperature", {"bearing": "6205-2RS", "radial_load": "1 kN", "speed": "6000 rpm", "oil": "VG32",
                     "thermal_resistance": "1 K/W"}),
    ("life", {"bearing": "6208", "radial_load": "2 kN", "speed": "1797 rpm", "shaft_fit": "j5",
              "clearance_class": "C3", "inner_ring_temperature": "30 degC"}),
    ("load-distribution", {"bearing": "B218", "dz": "700 um", "tilt_x": "0 mrad", "tilt_y": "0 mrad"}),
    ("bearing-set", {"bearing": "7208 BE", "arrangement": "DB", "preload": "500 N", "fx": "1 kN",
                     "shaft_fit": "k5", "housing_fit": "H7"}),  # the default spacing: side by side
    ("high-speed", {"bearing": "6208", "axial_load": "2 kN", "speed": "3000 rpm", "shaft_fit": "j5",
                    "clearance_class": "C3"}),
    ("friction", {"bearing": "6205-2RS", "radial_load": "100 N", "speed": "3000 rpm", "model": "skf",
                  "lubrication": "oil-bath", "oil_level": "3 mm", "drag_loss_factor": "0.0003",
                  "oil": "VG68", "temperature": "60 degC"}),
]


@pytest.mark.parametrize("name, given", CASES, ids=[f"{n}-{i}" for i, (n, _) in enumerate(CASES)])
def test_the_document_is_what_the_command_line_prints(name, given):
    parsed = parse(name, given)
    words = calculations.argv(parsed)
    printed = cli.run_json(words)
    assert printed.exit_code == 0, printed.error
    assert json.loads(json.dumps(run(parsed))) == printed.document


def test_the_runout_error_set_is_posted_as_toml_or_json(tmp_path):
    from pathlib import Path

    example = Path(__file__).resolve().parents[2] / "examples" / "runout" / "example1_oversize_ball.toml"
    text = example.read_text(encoding="utf-8")
    doc = run(parse("runout", {"errors": text}))
    assert doc["errors_file"] == "(posted document)"  # never the server's temporary file
    printed = cli.run_json(["runout", f"--errors={example}"]).document
    assert dict(printed, errors_file=doc["errors_file"]) == json.loads(json.dumps(doc))
    import tomllib

    as_json = json.dumps(tomllib.loads(text))
    assert json.loads(json.dumps(run(parse("runout", {"errors": as_json})))) == json.loads(json.dumps(doc))


def test_a_posted_error_set_never_reads_a_file():
    text = '[geometry]\nballs = 3\n[inner.waviness]\nprofile = "/etc/passwd"\nmax_order = 3\n'
    with pytest.raises(RequestError, match="cannot refer to files") as err:
        run(parse("runout", {"errors": text}))
    assert err.value.parameter == "errors"


def test_a_failure_of_the_calculation_names_the_field():
    with pytest.raises(RunFailure) as err:
        run(parse("life", {"bearing": "6205-2RS", "radial_load": "2 kN", "speed": "1 rpm",
                           "contamination": "normal", "contamination_factor": "0.5"}))
    e = err.value
    assert e.parameter == "contamination"
    assert e.worded(lambda n: n) == "contamination: give contamination_factor or contamination, not both"
    assert "--" not in e.worded(lambda n: n)


def test_catalog_search_filters_by_designation_bore_and_outside_diameter():
    doc = run(parse("catalog-search", {"query": "62"}))
    assert {"6205-2RS"} <= {m["name"] for m in doc["matches"]}
    assert all("62" in m["name"] or any("62" in a for a in m["aliases"]) for m in doc["matches"])
    by_size = run(parse("catalog-search", {"bore": "25 mm", "outside_diameter": "52 mm"}))
    names = [m["name"] for m in by_size["matches"]]
    assert names[0] == "6205-2RS" and "6205" in names  # the named bearing, then the standard series
    assert all(m["bore_mm"] == pytest.approx(25) and m["outside_diameter_mm"] == pytest.approx(52)
               for m in by_size["matches"])
    assert run(parse("catalog-search", {"bore": "26 mm"}))["count"] == 0


@pytest.mark.parametrize("given, words", [
    ({"bore": "40 mm", "outside_diameter": "80 mm"}, ["--bore=40 mm", "--outside-diameter=80 mm"]),
    ({"series": "72B", "type": "angular", "width": "18 mm"}, ["--series=72B", "--type=angular",
                                                               "--width=18 mm"]),
])
def test_catalog_search_bearings_are_what_catalog_search_prints(given, words):
    doc = run(parse("catalog-search", given))
    printed = cli.run_json(["catalog", "search", *words])
    assert printed.exit_code == 0, printed.error
    assert {k: doc[k] for k in ("bearings", "inputs", "warnings")} == printed.document

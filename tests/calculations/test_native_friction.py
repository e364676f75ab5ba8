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
def no_command_line():
    """The layer cannot run the command line: every calculation has a document function of its own
    (the runner that called the command's function and read its output is gone for good)."""
    from bearinglab.calculations import CALCULATIONS

    assert not [n for n in ("_call_command", "_run_command", "_command_document") if hasattr(documents, n)]
    assert set(CALCULATIONS) - {"catalog", "catalog-search"} <= set(documents._NATIVE)


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


# ----------------------------------------------------------------------------- issue 23 item 6: mounting
MOUNTING = {"shaft_fit": "k5", "housing_fit": "H7", "clearance_class": "C3", "inner_ring_temperature": "40 degC"}
MODELS = {
    "one-term": {"bearing": "6205-2RS", "radial_load": "100 N", "speed": "3000 rpm"},
    "palmgren": {"bearing": "6205-2RS", "radial_load": "100 N", "speed": "3000 rpm", "model": "palmgren",
                 "viscosity": "20 cSt", "palmgren_f0": "2"},
    "skf": {"bearing": "6205-2RS", "radial_load": "100 N, 200 N", "speed": "3000 rpm", "model": "skf",
            "viscosity": "20 cSt", "lubrication": "oil-jet"},
}
TORQUES = ("torque_Nmm", "torque_speed_term_Nmm", "total_moment_Nmm", "rolling_moment_Nmm")


def _torques(doc):
    return [{k: c[k] for k in TORQUES if k in c} for c in doc.get("cases", [doc])]


@pytest.mark.parametrize("model", MODELS)
def test_the_mounting_inputs_report_the_operating_clearance_and_leave_the_torque(model):
    plain = run(parse("friction", MODELS[model]))
    mounted = run(parse("friction", {**MODELS[model], **MOUNTING}))
    # the clearance chain of `clearance` for the same bearing, fits, temperatures and speed
    chain = run(parse("clearance", {"bearing": "6205-2RS", **MOUNTING, "speed": "3000 rpm"}))
    assert mounted["operating_clearance_um"] == pytest.approx(chain["operating_clearance_probable_um"], rel=1e-12)
    assert mounted["operating_clearance_min_um"] == pytest.approx(chain["operating_clearance_min_um"], rel=1e-12)
    assert mounted["operating_clearance_max_um"] == pytest.approx(chain["operating_clearance_max_um"], rel=1e-12)
    assert _torques(mounted) == _torques(plain)  # no friction model depends on the clearance ...
    assert any(f"the {model} friction model does not depend on the clearance" in w
               for w in mounted["warnings"])  # ... and the document says so
    assert "operating_clearance_um" not in plain


def test_the_mounting_options_of_friction_torque_are_the_command_lines_and_the_webs(no_command_line):
    parsed = parse("friction", {**MODELS["skf"], **MOUNTING})
    printed = cli.run_json(calculations.argv(parsed))
    assert printed.exit_code == 0, printed.error
    assert json.loads(json.dumps(run(parsed))) == printed.document


def test_a_preloaded_mounting_is_reported_not_refused():
    """A negative operating clearance (a preload) is a result for a model that does not use it."""
    doc = run(parse("friction", {**MODELS["one-term"], "shaft_fit": "p6", "clearance_class": "C2"}))
    assert doc["operating_clearance_um"] < 0 and doc["torque_Nmm"] > 0
    # issue 30: the preload is reported, and that the friction model leaves it out
    assert doc["preload"]["operating_clearance_um"] == pytest.approx(doc["operating_clearance_um"], rel=1e-12)
    assert doc["preload"]["ball_load_N"] > 0
    assert any("preloaded" in w and "leaves the preload's ball loads out" in w for w in doc["warnings"])


def test_a_bad_fit_names_the_field():
    with pytest.raises(RunFailure) as err:
        run(parse("friction", {**MODELS["one-term"], "shaft_fit": "zz9"}))
    assert err.value.parameter == "shaft_fit"


def test_the_table_shows_the_operating_clearance_and_says_the_model_ignores_it(capsys):
    words = ["friction", "torque", "-b", "6205-2RS", "-R", "100 N", "-n", "3000 rpm", "--shaft-fit", "k5",
             "--clearance-class", "C3"]
    assert cli.main(words) == 0
    out = " ".join(capsys.readouterr().out.split())
    doc = cli.run_json(words).document
    assert f"operating clearance {doc['operating_clearance_um']:.3g} um" in out
    assert "does not depend on the clearance" in out

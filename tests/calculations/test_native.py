"""Native calculations (issue 22 item 1): their document is computed by a function of
:mod:`bearinglab.calculations`, which the command line calls too; the web never runs the command line.

For each native calculation, ``bearinglab <command> ... --json`` (run through ``cli.main``) equals
``calculations.run(calculations.parse(...))`` computed with the command line's entry points disabled.
"""

import json
import subprocess
import sys

import pytest

from bearinglab import calculations, cli
from bearinglab.calculations import RunFailure, documents, parse, run

DUTY = ('[[step]]\nfx = "1 kN"\nfz = "3 kN"\nspeed = "1000 rpm"\ntime = 0.5\n\n'
        '[[step]]\nfx = "2 kN"\nfz = "3 kN"\nspeed = "3000 rpm"\ntime = 0.5\n')

LIFE = [
    {"bearing": "6205-2RS", "radial_load": "2 kN", "speed": "1797 rpm", "oil": "VG68", "temperature": "70 degC",
     "contamination": "normal", "reliability": "99"},
    {"bearing": "B218", "fx": "10 kN", "fz": "5 kN", "my": "200 N*m", "speed": "3000 rpm",
     "viscosity": "20 cSt", "contamination_factor": "0.5"},
    {"bearing": "6208", "radial_load": "2 kN", "speed": "1000 rpm"},  # estimated: the provenance note
    {"bearing": "6205-2RS", "balls": "10", "radial_load": "2 kN", "speed": "1000 rpm", "viscosity": "20 cSt"},
    {"bearing": "6208", "radial_load": "2 kN", "speed": "1797 rpm", "shaft_fit": "j5", "clearance_class": "C3",
     "inner_ring_temperature": "30 degC"},
    {"bearing": "B218", "fz": "0 N", "speed": "3000 rpm", "viscosity": "20 cSt"},  # unbounded lives
]


@pytest.fixture
def no_command_line():
    """The layer cannot run the command line: every calculation has a document function of its own
    (the runner that called the command's function and read its output is gone for good)."""
    from bearinglab.calculations import CALCULATIONS

    assert not [n for n in ("_call_command", "_run_command", "_command_document") if hasattr(documents, n)]
    assert set(CALCULATIONS) - {"catalog", "catalog-search"} <= set(documents._NATIVE)


def _printed(words):
    printed = cli.run_json(words)
    assert printed.exit_code == 0, printed.error
    return printed.document


@pytest.mark.parametrize("given", LIFE, ids=range(len(LIFE)))
def test_life_is_what_the_command_line_prints(given, request):
    parsed = parse("life", given)
    printed = _printed(calculations.argv(parsed))
    request.getfixturevalue("no_command_line")
    assert run(parsed) == printed


@pytest.mark.parametrize("text", [DUTY, json.dumps({"step": [
    {"fx": "1 kN", "fz": "3 kN", "speed": "1000 rpm", "time": 0.5},
    {"fx": "2 kN", "fz": "3 kN", "speed": "3000 rpm", "time": 0.5}]})], ids=["toml", "json"])
def test_a_posted_duty_cycle_is_the_duty_cycle_file(tmp_path, text, request):
    path = tmp_path / "duty.toml"
    path.write_text(DUTY, encoding="utf-8")
    printed = _printed(["life", "--bearing=B218", "--viscosity=20 cSt", f"--duty-cycle={path}"])
    request.getfixturevalue("no_command_line")
    doc = run(parse("life", {"bearing": "B218", "viscosity": "20 cSt", "duty_cycle": text}))
    assert doc == printed
    assert [s["speed_rpm"] for s in doc["inputs"]["steps"]] == [1000, 3000]


@pytest.mark.parametrize("given, parameter, words", [
    ({"bearing": "6205-2RS", "radial_load": "2 kN"}, "speed", "speed: missing"),
    ({"bearing": "6205-2RS", "radial_load": "2 kN", "speed": "0 rpm"}, "speed", "speed must be > 0 [rpm]"),
    ({"bearing": "6205-2RS", "speed": "1 rpm", "contamination": "normal", "contamination_factor": "0.5"},
     "contamination", "contamination: give contamination_factor or contamination, not both"),
    ({"bearing": "6205-2RS", "fx": "1 kN", "radial_load": "1 kN", "speed": "1 rpm"}, "radial_load",
     "radial_load: give fx or radial_load, not both"),
    ({"bearing": "6205-2RS", "speed": "1 rpm", "oil": "VG68"}, "temperature", "also needs temperature"),
    ({"bearing": "NOPE", "speed": "1 rpm"}, "bearing", "NOPE"),
    ({"bearing": "B218", "duty_cycle": "[[step]]\nfz = '1 kN'\nspeed = '0 rpm'\ntime = 1.0\n"},
     "duty_cycle", "duty_cycle step 1 speed must be > 0 [rpm]"),
    ({"bearing": "B218", "duty_cycle": "step = 3"}, "duty_cycle",
     "duty_cycle: the posted document: needs [[step]] tables"),
    ({"bearing": "B218", "duty_cycle": "{not json"}, "duty_cycle", "duty_cycle: the posted document: "),
    ({"bearing": "B218", "speed": "1 rpm", "duty_cycle": DUTY}, "duty_cycle",
     "the loads and speeds are in the duty cycle; give no fx ... speed"),
])
def test_life_failures_name_the_field(given, parameter, words, no_command_line):
    with pytest.raises(RunFailure) as err:
        run(parse("life", given))
    assert err.value.parameter == parameter
    text = err.value.worded(lambda name: name)
    assert words in text and "--" not in text


@pytest.mark.parametrize("args, line", [
    (["--fx=1 kN", "--radial-load=1 kN", "--speed=1 rpm"], "radial-load: give --fx or --radial-load, not both"),
    (["--radial-load=1 kN"], "speed: missing; give the inner-ring speed, e.g. '3000 rpm' (or --duty-cycle)"),
    (["--speed=1 rpm", "--contamination=normal", "--contamination-factor=0.5"],
     "contamination: give --contamination-factor or --contamination, not both"),
])
def test_the_command_line_words_the_same_failures_with_its_options(capsys, args, line):
    assert cli.main(["life", "--bearing=6205-2RS", *args]) == 2
    assert capsys.readouterr().err.strip() == f"bearinglab: error: {line}"


LOAD = [
    {"bearing": "B218", "axial_load": "5 kN", "radial_load": "10 kN", "my": "2 N*m"},
    {"bearing": "B218", "fz": "5 kN", "speed": "12000 rpm", "stiffness_at": "free", "first_ball_angle": "10 deg"},
    {"bearing": "B218", "dz": "700 um", "tilt_x": "0 mrad", "tilt_y": "0 mrad"},  # held freedoms
    {"bearing": "6208", "fx": "2 kN", "speed": "3000 rpm", "shaft_fit": "k5", "housing_fit": "H7"},
    {"bearing": "B218", "balls": "15", "fz": "5 kN"},  # inline override
]
SETS = [
    {"bearing": "7218B", "arrangement": "DF", "preload": "500 N", "fx": "1 kN"},
    {"bearing": "7218B, 7218B", "arrangement": "DB", "preload": "1 kN", "fy": "2 kN", "spacing": "100 mm"},
    {"bearing": "7208 BE", "arrangement": "DB", "preload": "500 N", "fx": "1 kN", "shaft_fit": "k5",
     "housing_fit": "H7"},
    {"bearing": "7218B", "arrangement": "DB", "preload_offset": "5 um", "fz": "2 kN", "speed": "3000 rpm"},
    {"bearing": "7218B", "arrangement": "DT", "fz": "2 kN", "fx": "500 N"},
]


@pytest.mark.parametrize("name, given", [*(("load-distribution", g) for g in LOAD),
                                         *(("bearing-set", g) for g in SETS)],
                         ids=[*(f"load-{i}" for i in range(len(LOAD))), *(f"set-{i}" for i in range(len(SETS)))])
def test_load_distribution_and_sets_are_what_the_command_line_prints(name, given, request):
    parsed = parse(name, given)
    printed = _printed(calculations.argv(parsed))
    request.getfixturevalue("no_command_line")
    assert run(parsed) == printed


@pytest.mark.parametrize("name, given, parameter, words", [
    ("load-distribution", {"bearing": "B218", "fz": "1 kN", "dz": "5 um"}, "dz", "dz: give fz or dz, not both"),
    ("load-distribution", {"bearing": "B218", "fz": "1 kN", "speed": "1e7 rpm"}, "speed",
     "speed must be <= "),
    ("load-distribution", {"bearing": "B218", "fz": "1 kN", "shaft_fit": "zz9"}, "shaft_fit",
     "shaft_fit must be one of"),
    ("bearing-set", {"bearing": "7218B", "preload": "1 kN", "preload_offset": "5 um"}, "preload",
     "preload: give preload or preload_offset, not both"),
    ("bearing-set", {"bearing": "7218B, 7208 BE", "preload": "1 kN", "shaft_fit": "k5"}, "bearing",
     "the mounting options need one bearing type"),
    ("bearing-set", {"bearing": "NOPE", "preload": "1 kN"}, "bearing", "NOPE"),
    # a field of the bearing, not an input given: named as the library names it, no parameter
    ("load-distribution", {"balls": "9", "ball_diameter": "8 mm", "pitch_diameter": "39 mm",
                           "contact_angle": "0 deg", "fx": "1 kN"}, None,
     "inner_conformity of 'inline' is not known"),
])
def test_load_failures_name_the_field(name, given, parameter, words, no_command_line):
    with pytest.raises(RunFailure) as err:
        run(parse(name, given))
    assert err.value.parameter == parameter
    text = err.value.worded(lambda n: n)
    assert words in text and "--" not in text


@pytest.mark.parametrize("name, given, title", [
    ("load-distribution", LOAD[1], "Bearing B218: ball loads at 12000 rpm"),
    ("bearing-set", SETS[0], "Set DF: ball loads of bearing 0 (7218B)"),
])
def test_the_figure_is_drawn_from_the_document(name, given, title, no_command_line):
    svg = calculations.figure_svg(parse(name, given))
    assert svg.startswith("<svg") and svg.rstrip().endswith("</svg>")
    assert title.replace(" ", "") in svg.replace(" ", "") or "ball loads" in svg or "<path" in svg


def test_the_ball_loads_of_the_figure_are_the_documents():
    from bearinglab.calculations import load_distribution

    doc = run(parse("load-distribution", LOAD[0]))
    fig = load_distribution.figure(doc)
    ax = fig.axes[0]
    outer = ax.lines[-2] if len(ax.lines) > 1 else ax.lines[0]  # the markers of the outer contacts
    shown = sorted(y for line in ax.lines for y in line.get_ydata())
    for ball in doc["balls"]:
        assert ball["load_inner_N"] in shown or ball["load_inner_N"] == pytest.approx(0.0)
    assert outer is not None and fig.axes[0].get_title() == "Bearing B218: ball loads at 0 rpm"


def test_the_calculations_do_not_import_the_command_line():
    code = ("import sys, bearinglab.calculations as c\n"
            "c.run(c.parse('life', {'bearing': 'B218', 'fz': '5 kN', 'speed': '3000 rpm', 'viscosity': '20 cSt'}))\n"
            "assert not [m for m in sys.modules if m.startswith('bearinglab.cli')], 'bearinglab.cli imported'\n"
            "assert 'typer' not in sys.modules and 'rich' not in sys.modules\n")
    done = subprocess.run([sys.executable, "-c", code], check=False, capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr


# ----------------------------------------------------------------------------- life with temperature auto
AUTO = {"bearing": "6205-2RS", "radial_load": "1 kN", "speed": "6000 rpm", "oil": "VG32", "temperature": "auto",
        "thermal_resistance": "1 K/W"}


def test_life_at_temperature_auto_takes_the_viscosity_of_the_thermal_balance(request):
    from bearinglab.ratings import lubrication

    parsed = parse("life", AUTO)
    printed = _printed(calculations.argv(parsed))
    balance = _printed(["temperature", "--bearing=6205-2RS", "--radial-load=1 kN", "--speed=6000 rpm",
                        "--oil=VG32", "--thermal-resistance=1 K/W"])
    request.getfixturevalue("no_command_line")
    doc = run(parsed)
    assert doc == printed
    t = doc["bearing_temperature_degC"]
    assert t == pytest.approx(balance["bearing_temperature_degC"], rel=1e-12)
    assert doc["viscosity_mm2_s"] == pytest.approx(balance["viscosity_mm2_s"], rel=1e-12)
    # the viscosity used is the oil's at the balance temperature (ASTM D341 through VG32 at 40 degC and its
    # nu100 at VI 95), and the life's kappa is computed with it
    nu100 = lubrication.viscosity_100_from_index(32e-6, 95.0)
    nu = lubrication.kinematic_viscosity(t + 273.15, viscosity_40=32e-6, viscosity_100=nu100)
    assert doc["viscosity_mm2_s"] == pytest.approx(float(nu) * 1e6, rel=1e-9)
    assert doc["viscosity_ratio"] == pytest.approx(doc["viscosity_mm2_s"] / doc["rated_viscosity_mm2_s"], rel=1e-12)
    assert doc["inputs"]["temperature"] == "auto" and doc["inputs"]["bearing_temperature_degC"] == pytest.approx(t)
    assert 20.0 < t < 150.0


def test_a_hotter_ambient_gives_a_hotter_bearing_and_a_thinner_oil(no_command_line):
    cool = run(parse("life", AUTO))
    hot = run(parse("life", {**AUTO, "ambient": "50 degC"}))
    assert hot["bearing_temperature_degC"] > cool["bearing_temperature_degC"]
    assert hot["viscosity_mm2_s"] < cool["viscosity_mm2_s"]
    assert hot["modified_rating_life_Mrev"] <= cool["modified_rating_life_Mrev"]


@pytest.mark.parametrize("given, words", [
    ({**AUTO, "temperature": "70 degC"}, "thermal_resistance, lubrication and skf_constants go with temperature auto"),
    ({**AUTO, "oil": None, "viscosity": "20 cSt"}, "'auto' needs the oil by grade"),
    ({**AUTO, "my": "10 N*m"}, "'auto' takes the SKF friction model, which has no tilting moment"),
    ({**{k: v for k, v in AUTO.items() if k not in ("speed", "radial_load")}, "duty_cycle": DUTY},
     "'auto' takes the loads and speed of one case, not a duty cycle"),
])
def test_temperature_auto_failures_name_the_temperature(given, words, no_command_line):
    with pytest.raises(RunFailure) as err:
        run(parse("life", {k: v for k, v in given.items() if v is not None}))
    assert err.value.parameter == "temperature"
    assert words in err.value.worded(lambda n: n)

"""``bearinglab life`` (issue 12): JSON keys, MASTA's ISO/TS 16281 lives through the CLI, moments, duty
cycles, one set of ratings with ``catalog show``, and bad inputs."""

import json
import math
import re

import numpy as np
import pytest

from bearinglab import catalog, ratings
from bearinglab.cli import main
from bearinglab.life import rating_life
from bearinglab.units import RPM

KEYS = ["dynamic_load_rating_N", "static_load_rating_N", "fatigue_load_limit_N", "rating_source",
        "equivalent_dynamic_load_N", "basic_rating_life_Mrev", "basic_rating_life_h", "reliability_factor",
        "viscosity_mm2_s", "rated_viscosity_mm2_s", "rated_viscosity_diameter_mm", "viscosity_ratio",
        "contamination_factor",  # issue 30: the e_C used, whenever a_ISO is computed
        "life_modification_factor", "modified_rating_life_Mrev", "modified_rating_life_h",
        "reference_rating_life_Mrev", "modified_reference_rating_life_Mrev", "static_safety_factor", "inputs", "warnings"]

#: the MASTA deep-groove bearing of tests/data/masta_iso16281.csv (E = 210 GPa, nu = 0.3, C = 23.4 kN)
MASTA = """
[materials."masta"]
elastic_modulus = "210 GPa"
poisson_ratio = 0.3
density = "7850 kg/m^3"

[bearings."MASTA-DG"]
type = "radial"
balls = 7
ball_diameter = "11.5 mm"
pitch_diameter = "43.5 mm"
inner_conformity = 0.52
outer_conformity = 0.53
contact_angle = "0 deg"
ball_material = "masta"
ring_material = "masta"
dynamic_load_rating = "23.4 kN"
"""


def run(capsys, *args):
    code = main(list(args))
    out, err = capsys.readouterr()
    return code, out, err


def _one_line_error(err):
    lines = err.strip().splitlines()
    assert len(lines) == 1, err
    assert lines[0].startswith("bearinglab: error:") and "Traceback" not in err
    return lines[0]


@pytest.fixture
def masta(tmp_path):
    path = tmp_path / "masta.toml"
    path.write_text(MASTA, encoding="utf-8")
    return str(path)


# MASTA's L10r [10^6 rev] (tests/data/masta_iso16281.csv, printed to 8 digits)
MASTA_CASES = [("--fx", None, 13163.019), ("--fz", None, 2222.7318), ("--fx", "10 um", 10795.7948),
               ("--fz", "10 um", 3115.8781)]


@pytest.mark.parametrize("option, clearance, l10r", MASTA_CASES, ids=["case1", "case2", "case3", "case4"])
def test_reference_life_matches_masta_through_the_combined_model(capsys, masta, option, clearance, l10r):
    extra = [] if clearance is None else ["--radial-clearance", clearance]
    code, out, err = run(capsys, "life", "--catalog", masta, "-b", "MASTA-DG", option, "1 kN", "--speed", "1000 rpm",
                         "--viscosity", "20 cSt", *extra, "--json")
    assert code == 0, err
    doc = json.loads(out)
    assert list(doc) == KEYS
    # the acceptance band is 1 %; the library's combined model gives 6e-5
    assert doc["reference_rating_life_Mrev"] == pytest.approx(l10r, rel=0.01)
    assert doc["rating_source"]["dynamic_load_rating"] == "catalog" and doc["dynamic_load_rating_N"] == 23400.0


def test_json_equals_the_library(capsys):
    code, out, err = run(capsys, "life", "-b", "B218", "--fx", "2 kN", "--fz", "5 kN", "--speed", "3000 rpm",
                         "--viscosity", "20 cSt", "--contamination", "normal", "--reliability", "99", "--json")
    assert code == 0, err
    doc = json.loads(out)
    assert list(doc) == KEYS
    b = catalog.get("B218")
    r = rating_life(b, [2000.0, 0, 5000.0, 0, 0], 3000 * RPM, kinematic_viscosity=20e-6,
                            contamination="normal_cleanliness", reliability=0.99)
    assert doc["basic_rating_life_Mrev"] == pytest.approx(r.basic_rating_life / 1e6, rel=1e-12)
    assert doc["modified_rating_life_h"] == pytest.approx(r.modified_rating_life_duration / 3600, rel=1e-12)
    assert doc["reference_rating_life_Mrev"] == pytest.approx(r.reference_rating_life / 1e6, rel=1e-12)
    assert doc["reliability_factor"] == pytest.approx(0.25) and doc["warnings"] == []


def test_pure_moment_gives_null_iso281_fields_and_a_reference_life(capsys, masta):
    code, out, err = run(capsys, "life", "--catalog", masta, "-b", "MASTA-DG", "--mx", "20 N*m", "--speed",
                         "1000 rpm", "--viscosity", "20 cSt", "--json")
    assert code == 0, err
    doc = json.loads(out)
    for key in ("equivalent_dynamic_load_N", "basic_rating_life_Mrev", "basic_rating_life_h",
                "life_modification_factor", "modified_rating_life_Mrev", "modified_rating_life_h",
                "static_safety_factor"):
        assert doc[key] is None, key
    assert doc["reference_rating_life_Mrev"] > 0 and doc["modified_reference_rating_life_Mrev"] > 0
    assert any("tilting moment" in w and "not defined" in w for w in doc["warnings"])


def test_oil_grade_and_temperature(capsys):
    code, out, err = run(capsys, "life", "-b", "6205-2RS", "--fx", "1 kN", "--speed", "3000 rpm", "--oil", "VG68",
                         "--viscosity-100", "8.7 cSt", "--temperature", "70 degC", "--json")
    assert code == 0, err
    nu = ratings.kinematic_viscosity(343.15, iso_vg=68, viscosity_100=8.7e-6)
    # nu1 of ISO 281 eq. (15) at d_m = (d + D)/2 = (25 + 52)/2 = 38.5 mm, by hand (issue 20: not Dpw 39.04)
    nu1 = 4500.0 * 3000.0**-0.5 * 38.5**-0.5 * 1e-6
    doc = json.loads(out)
    assert doc["viscosity_ratio"] == pytest.approx(nu / nu1, rel=1e-12)
    assert doc["viscosity_mm2_s"] == pytest.approx(nu * 1e6, rel=1e-12)
    assert doc["rated_viscosity_mm2_s"] == pytest.approx(nu1 * 1e6, rel=1e-12)
    assert doc["rated_viscosity_diameter_mm"] == pytest.approx(38.5, rel=1e-12)


def test_duty_cycle_is_palmgren_miner(capsys, tmp_path):
    f = tmp_path / "duty.toml"
    f.write_text('[[step]]\nfx = "1 kN"\nfz = "3 kN"\nspeed = "1000 rpm"\ntime = 0.5\n\n'
                 '[[step]]\nfx = "2 kN"\nfz = "3 kN"\nspeed = "3000 rpm"\ntime = 0.5\n', encoding="utf-8")
    code, out, err = run(capsys, "life", "-b", "B218", "--viscosity", "20 cSt", "--duty-cycle", str(f), "--json")
    assert code == 0, err
    doc = json.loads(out)
    l1, l2 = (doc["steps"][k]["basic_rating_life_Mrev"] for k in (0, 1))
    u = np.array([1000.0, 3000.0]) / 4000.0  # revolution shares of equal times
    assert doc["basic_rating_life_Mrev"] == pytest.approx(1.0 / (u[0] / l1 + u[1] / l2), rel=1e-12)
    assert doc["basic_rating_life_h"] == pytest.approx(doc["basic_rating_life_Mrev"] * 1e6 / 2000.0 / 60, rel=1e-12)
    assert math.isfinite(doc["reference_rating_life_Mrev"])


def test_catalog_show_and_life_give_the_same_ratings(capsys):
    code, out, _ = run(capsys, "catalog", "show", "B218", "--json")
    assert code == 0
    shown = json.loads(out)
    code, out, err = run(capsys, "life", "-b", "B218", "--fz", "10 kN", "--speed", "3000 rpm", "--viscosity",
                         "20 cSt", "--json")
    assert code == 0, err
    life = json.loads(out)
    for key in ("dynamic_load_rating_N", "static_load_rating_N", "fatigue_load_limit_N", "rating_source"):
        assert shown[key] == life[key], key


@pytest.mark.parametrize("args, name", [
    (["--reliability", "80"], "reliability"),
    (["--oil", "VG67", "--viscosity-100", "8 cSt", "--temperature", "70 degC"], "oil"),
    (["--oil", "VG68", "--viscosity-100", "8.7 cSt", "--temperature", "-300 degC"], "temperature"),
    (["--contamination", "dirty"], "contamination"),
    (["--viscosity-100", "8.7 cSt"], "viscosity"),  # with --viscosity: never silently ignored
    (["--fx", "1 kg"], "fx"),
])
def test_bad_input_is_one_line_and_exit_2(capsys, args, name):
    base = ["life", "-b", "6205-2RS", "--speed", "3000 rpm"]
    if not any(a in ("--oil",) for a in args):
        base += ["--viscosity", "20 cSt"]
    if "--fx" not in args:
        base += ["--fx", "1 kN"]
    code, _, err = run(capsys, *base, *args)
    assert code == 2
    assert name in _one_line_error(err)


# ----------------------------------------------------------------------------- guard-rails (issue 15, review)
def _duty_file(tmp_path, speed, fz="2 kN", time=1.0):
    path = tmp_path / "duty.toml"
    path.write_text(f'[[step]]\nfz = "{fz}"\nspeed = {speed}\ntime = {time}\n', encoding="utf-8")
    return str(path)


@pytest.mark.parametrize("speed, words", [
    ('"1e8 rpm"', ["duty-cycle step 1 speed must be <= 279330 [rpm] for d_m = 125.3 mm", "got 1e+08 rpm"]),
    ('"-300 rpm"', ["duty-cycle step 1 speed must be > 0 [rpm]", "got -300 rpm"]),
    ('"0 rpm"', ["duty-cycle step 1 speed must be > 0 [rpm]", "got 0 rpm"]),
    ('"3000, 4000 rpm"', ["duty-cycle step 1 speed: give one speed, got 2 values"]),
])
def test_duty_cycle_speeds_follow_the_speed_option_rules(capsys, tmp_path, speed, words):
    # the same parsing and guard-rails as --speed: the d_m n limit, > 0, in rpm (never rad/s), one value
    code, _, err = run(capsys, "life", "-b", "B218", "--duty-cycle", _duty_file(tmp_path, speed),
                       "--viscosity", "20 cSt")
    line = _one_line_error(err)
    assert code == 2 and all(w in line for w in words), line
    assert "rad/s" not in line


@pytest.mark.parametrize("time", ['"half"', "[0.5]", "true", "-0.5", "1.5"])
def test_duty_cycle_time_share_is_checked(capsys, tmp_path, time):
    code, _, err = run(capsys, "life", "-b", "B218", "--duty-cycle", _duty_file(tmp_path, '"3000 rpm"', time=time),
                       "--viscosity", "20 cSt")
    assert code == 2 and "duty-cycle step 1 time must be a share in [0, 1]" in _one_line_error(err)


def test_speed_list_gives_one_document_per_speed_never_its_first_value(capsys):
    # issue 30: life takes a speed list like film (before: refused); each document is that speed's alone
    code, out, err = run(capsys, "life", "-b", "B218", "--fz", "2 kN", "--speed", "3000, 6000 rpm",
                         "--viscosity", "20 cSt", "--json")
    assert code == 0, err
    docs = json.loads(out)
    assert [d["inputs"]["speed_rpm"] for d in docs] == [3000.0, 6000.0]
    for d, rpm in zip(docs, (3000, 6000)):
        code, out, err = run(capsys, "life", "-b", "B218", "--fz", "2 kN", "--speed", f"{rpm} rpm",
                             "--viscosity", "20 cSt", "--json")
        assert json.loads(out) == d


def test_negative_thrust_on_one_angular_bearing_gives_every_life_with_a_warning(capsys):
    # the 5-DOF model solves it with the full groove and warns that the balls run against the low shoulder
    args = ["life", "-b", "B218", "--fx", "1 kN", "--fz", "-2 kN", "--speed", "3000 rpm", "--viscosity", "20 cSt"]
    code, out, err = run(capsys, *args, "--json")
    assert code == 0, err
    doc = json.loads(out)
    b = catalog.get("B218")
    with pytest.warns(ratings.RatingWarning):
        lib = rating_life(b, [1e3, 0, -2e3, 0, 0], 3000 * RPM, kinematic_viscosity=20e-6,
                                  load_distribution=False)
    assert doc["basic_rating_life_Mrev"] == pytest.approx(lib.basic_rating_life / 1e6, rel=1e-12)
    assert doc["static_safety_factor"] == pytest.approx(float(lib.static_safety_factor), rel=1e-12)
    assert doc["reference_rating_life_Mrev"] > 0
    assert any("low shoulder" in w for w in doc["warnings"])
    assert not any(re.search(r"\bnan\b", w, flags=re.IGNORECASE) for w in doc["warnings"])


def test_without_equilibrium_iso281_is_kept_and_the_reference_lives_say_why(capsys):
    # a load so light that rounding alone leaves the equilibrium residual above 1e-9: the 5-DOF model
    # flags it; the ISO 281 lives do not need the distribution
    args = ["life", "-b", "B218", "--fx", "1e-9 N", "--fz", "1e-9 N", "--speed", "3000 rpm", "--viscosity", "20 cSt"]
    code, out, err = run(capsys, *args, "--json")
    assert code == 0, err
    doc = json.loads(out)
    assert doc["basic_rating_life_Mrev"] > 0
    assert doc["reference_rating_life_Mrev"] is None and doc["modified_reference_rating_life_Mrev"] is None
    why = [w for w in doc["warnings"] if w.startswith("ISO/TS 16281 reference lives not available")]
    assert len(why) == 1 and "too light to resolve" in why[0]
    assert not any(re.search(r"\bnan\b", w, flags=re.IGNORECASE) for w in doc["warnings"])
    code, out, err = run(capsys, *args)
    assert code == 0 and err == ""
    text = " ".join(out.split())
    assert "reference lives not available" in text and "basic rating life L10 [10^6 rev]" in text


def test_a_duty_cycle_step_without_equilibrium_keeps_iso281(capsys, tmp_path):
    path = tmp_path / "duty.toml"
    path.write_text('[[step]]\nfz = "2 kN"\nspeed = "3000 rpm"\ntime = 0.5\n'
                    '[[step]]\nfx = "1e-9 N"\nfz = "1e-9 N"\nspeed = "3000 rpm"\ntime = 0.5\n', encoding="utf-8")
    code, out, err = run(capsys, "life", "-b", "B218", "--json", "--viscosity", "20 cSt", "--duty-cycle", path)
    assert code == 0, err
    doc = json.loads(out)
    assert doc["basic_rating_life_Mrev"] > 0 and doc["reference_rating_life_Mrev"] is None
    assert doc["steps"][0]["reference_rating_life_Mrev"] > 0 and doc["steps"][1]["reference_rating_life_Mrev"] is None
    why = [w for w in doc["warnings"] if w.startswith("ISO/TS 16281 reference lives not available")]
    assert len(why) == 1 and "at 1 of 2 steps (first: step 2)" in why[0] and "too light" in why[0]


def test_static_safety_is_warned_once(capsys):
    code, out, _ = run(capsys, "life", "-b", "B218", "--fz", "400 kN", "--speed", "3000 rpm",
                         "--viscosity", "20 cSt", "--json")
    doc = json.loads(out)
    assert code == 0 and doc["static_safety_factor"] < 1
    static = [w for w in doc["warnings"] if "s0" in w or "C0" in w]
    assert len(static) == 1, static


def test_an_assumed_cleanliness_is_said_and_a_given_one_is_not(capsys):
    base = ["life", "-b", "B218", "--fx", "5 kN", "--fz", "3 kN", "--speed", "3000 rpm", "--viscosity", "20 cSt"]
    code, out, _ = run(capsys, *base, "--json")
    doc = json.loads(out)
    assert code == 0 and doc["inputs"]["contamination"] == 1.0
    assert any(w.startswith("contamination: none given, so e_C = 1") for w in doc["warnings"])
    for extra in (["--contamination", "normal"], ["--contamination-factor", "1"]):
        code, out, _ = run(capsys, *base, *extra, "--json")
        assert code == 0 and not any(w.startswith("contamination:") for w in json.loads(out)["warnings"])


def test_the_table_names_quantities_by_their_symbols_not_by_json_keys(capsys):
    code, out, _ = run(capsys, "life", "-b", "B218", "--fx", "5 kN", "--fz", "3 kN", "--speed", "3000 rpm",
                       "--viscosity", "20 cSt", "--contamination", "normal")
    text = " ".join(out.split())
    assert code == 0
    for label in ("basic dynamic load rating C [N]", "basic rating life L10h [h]", "viscosity ratio κ [-]",
                  "life modification factor a_ISO [-]", "static safety factor s0 [-]"):
        assert label in text, label
    assert not re.search(r"\b[a-z]+(_[a-z0-9]+)+_(N|h|Mrev)\b", text), text


# ----------------------------------------------------------------------------- review of issue 15
def test_no_load_says_why_the_lives_and_s0_are_not_shown(capsys):
    # P = 0: L10, L_nm and s0 are infinite (null in JSON, '—' in the table); a warning says so
    args = ["life", "-b", "6205-2RS", "-R", "0 N", "-n", "3000 rpm", "--viscosity", "20 cSt"]
    code, out, err = run(capsys, *args, "--json")
    assert code == 0, err
    doc = json.loads(out)
    assert doc["equivalent_dynamic_load_N"] == 0.0
    assert doc["basic_rating_life_Mrev"] is None and doc["static_safety_factor"] is None
    notes = [w for w in doc["warnings"] if w.startswith("P = 0")]
    assert notes == ["P = 0: no equivalent load, so L10, L_nm, L10r, L_nmr and s0 are unbounded (shown as —, null in --json)"]
    code, out, err = run(capsys, *args)
    assert code == 0, err
    assert "— (see the warnings)" in out and "warning: P = 0: no equivalent load" in out


def test_a_loaded_bearing_has_no_unbounded_warning(capsys):
    code, out, err = run(capsys, "life", "-b", "6205-2RS", "-R", "1 kN", "-n", "3000 rpm", "--viscosity", "20 cSt",
                         "--json")
    assert code == 0, err
    assert not [w for w in json.loads(out)["warnings"] if "unbounded" in w]


def test_an_unloaded_duty_cycle_says_why_its_lives_are_not_shown(capsys, tmp_path):
    code, out, err = run(capsys, "life", "-b", "B218", "--duty-cycle", _duty_file(tmp_path, '"3000 rpm"', fz="0 N"),
                         "--viscosity", "20 cSt", "--json")
    assert code == 0, err
    doc = json.loads(out)
    assert doc["basic_rating_life_Mrev"] is None
    assert [w for w in doc["warnings"] if w.startswith("P = 0 at every step: no equivalent load, so L10, L_nm")]


def test_help_shows_the_duty_cycle_tables_literally(capsys):
    # '[[step]]' is rich markup unless escaped: the help printed '[]' (issue 15)
    code, out, err = run(capsys, "life", "--help")
    assert code == 0, err
    out = " ".join(out.split())
    assert "TOML file of [[step]] loads" in out and "[]" not in out


def test_an_angle_below_the_tabulated_rows_is_refused_without_float_noise(capsys):
    # 4-1006095 has a 12 deg nominal angle: ISO 281 table 3 is tabulated here from 15 deg
    code, _, err = run(capsys, "life", "-b", "4-1006095", "-A", "2 kgf", "-n", "3000 rpm", "--viscosity", "20 cSt")
    line = _one_line_error(err)
    assert code == 2
    assert "contact_angle must be in [15, 45] [deg] for ISO 281 table 3 (angular contact), got 12 deg: " in line
    assert "00000" not in line and "maker's X and Y" in line and "reference_rating_life" in line


def test_the_test_stand_bearing_gets_a_life_under_a_radial_load(capsys):
    # 12 deg is outside the ISO tables carried here, but with Fa = 0 no row is needed: P = P0 = Fr
    code, out, err = run(capsys, "life", "-b", "4-1006095", "-R", "2 kgf", "--speed", "3000 rpm",
                         "--viscosity", "20 cSt", "--contamination", "normal", "--json")
    assert code == 0, err
    doc = json.loads(out)
    assert doc["equivalent_dynamic_load_N"] == pytest.approx(2 * 9.80665, rel=1e-12)
    assert doc["basic_rating_life_Mrev"] == pytest.approx((doc["dynamic_load_rating_N"] / (2 * 9.80665)) ** 3,
                                                          rel=1e-12)
    assert doc["static_safety_factor"] == pytest.approx(doc["static_load_rating_N"] / (2 * 9.80665), rel=1e-12)


# ----------------------------------------------------------------------------- issue 20: no lubricant, oil by grade
LUBRICATED = ("viscosity_mm2_s", "viscosity_ratio", "contamination_factor", "life_modification_factor",
              "modified_rating_life_Mrev",
              "modified_rating_life_h", "modified_reference_rating_life_Mrev")


def test_life_without_lubricant_gives_the_basic_lives(capsys):
    # the command: P, L10, L10h and s0 (and L10r where the geometry allows); the rest null
    code, out, err = run(capsys, "life", "--bearing", "6205-2RS", "--radial-load", "2 kN", "--speed", "3000 rpm",
                         "--json")
    assert code == 0, err
    doc = json.loads(out)
    assert list(doc) == KEYS
    for key in LUBRICATED:
        assert doc[key] is None, key
    # by hand: P = Fr = 2000 N (pure radial), L10 = (C/P)^3 = (14800/2000)^3 Mrev, at 3000 rpm; s0 = C0/P0
    assert doc["equivalent_dynamic_load_N"] == 2000.0
    assert doc["basic_rating_life_Mrev"] == pytest.approx(7.4**3, rel=1e-12)
    assert doc["basic_rating_life_h"] == pytest.approx(7.4**3 * 1e6 / 3000 / 60, rel=1e-12)
    assert doc["static_safety_factor"] == pytest.approx(7800 / 2000, rel=1e-12)
    assert any(w.startswith("lubricant: none given") for w in doc["warnings"])
    assert not any(w.startswith("contamination:") for w in doc["warnings"])  # e_C matters only with a_ISO


def test_life_without_lubricant_reference_life_where_the_geometry_allows(capsys, masta):
    code, out, err = run(capsys, "life", "--catalog", masta, "-b", "MASTA-DG", "-R", "1 kN", "--speed",
                         "1000 rpm", "--json")
    assert code == 0, err
    doc = json.loads(out)
    assert doc["reference_rating_life_Mrev"] > 0 and doc["modified_reference_rating_life_Mrev"] is None


def test_life_table_says_needs_viscosity(capsys, monkeypatch):
    monkeypatch.setenv("COLUMNS", "80")
    code, out, err = run(capsys, "life", "-b", "6205-2RS", "-R", "2 kN", "-n", "3000 rpm")
    assert code == 0, err
    rows = {line.split("│")[1].strip(): line.split("│")[2].strip() for line in out.splitlines()
            if line.count("│") == 3}
    needs = [label for label, value in rows.items() if value == "needs viscosity"]
    assert len(needs) == len(LUBRICATED), rows
    assert rows["basic rating life L10 [10^6 rev]"] == "405.224"


def test_oil_grade_and_temperature_are_enough(capsys):
    code, out, err = run(capsys, "life", "-b", "6205-2RS", "-R", "2 kN", "-n", "3000 rpm", "--oil", "VG68",
                         "--temperature", "70 degC", "--json")
    assert code == 0, err
    doc = json.loads(out)
    nu = ratings.kinematic_viscosity(343.15, iso_vg=68, viscosity_index=ratings.DEFAULT_VISCOSITY_INDEX)
    assert doc["viscosity_mm2_s"] == pytest.approx(nu * 1e6, rel=1e-12)
    assert doc["inputs"]["viscosity_index"] == 95 and doc["inputs"]["viscosity_index_assumed"] is True
    assert any(w.startswith("viscosity: VG68 at 70 degC, VI 95 (assumed") for w in doc["warnings"])
    for key in LUBRICATED[:-1]:  # L_nmr needs L10r, which needs the conformities this catalog entry lacks
        assert doc[key] is not None, key
    # a higher VI keeps the oil thicker at 70 degC
    code, out, err = run(capsys, "life", "-b", "6205-2RS", "-R", "2 kN", "-n", "3000 rpm", "--oil", "VG68",
                         "--temperature", "70 degC", "--viscosity-index", "140", "--json")
    assert code == 0, err
    assert json.loads(out)["viscosity_mm2_s"] > doc["viscosity_mm2_s"]


@pytest.mark.parametrize("args, start", [
    (["--oil", "VG68", "--temperature", "70 degC", "--viscosity-index", "95", "--viscosity-100", "8.7 cSt"],
     "viscosity-index: give --viscosity-index or --viscosity-100, not both"),
    (["--viscosity-index", "95"], "oil: --viscosity-index also needs --oil"),
    (["--oil", "VG68"], "temperature: --oil also needs --temperature"),
])
def test_oil_option_conflicts_are_exit_2(capsys, args, start):
    code, _, err = run(capsys, "life", "-b", "6205-2RS", "-R", "2 kN", "-n", "3000 rpm", *args)
    assert code == 2 and _one_line_error(err).startswith(f"bearinglab: error: {start}")


def test_duty_cycle_without_lubricant(capsys, tmp_path):
    f = tmp_path / "duty.toml"
    f.write_text('[[step]]\nfx = "1 kN"\nspeed = "1000 rpm"\ntime = 0.5\n\n'
                 '[[step]]\nfx = "2 kN"\nspeed = "3000 rpm"\ntime = 0.5\n', encoding="utf-8")
    code, out, err = run(capsys, "life", "-b", "6205-2RS", "--duty-cycle", str(f), "--json")
    assert code == 0, err
    doc = json.loads(out)
    assert doc["modified_rating_life_Mrev"] is None and doc["basic_rating_life_Mrev"] > 0
    assert all(s["viscosity_ratio"] is None for s in doc["steps"])

"""``bearinglab shaft FILE`` (issue 33 item 5): the file read as the document, its JSON, tables, CSV,
figure and errors."""

import csv
import json
import math
from pathlib import Path

import pytest

from bearinglab import calculations, cli
from bearinglab.cli import main

ROOT = Path(__file__).resolve().parents[2]
SPINDLE = ROOT / "examples" / "shaft" / "spindle.toml"

# two deep-groove bearings 260 mm apart, a load in the middle, a thrust on the locating bearing A
TWO = (ROOT / "tests" / "data" / "two_bearing_shaft.toml").read_text(encoding="utf-8")


def _run(capsys, *args):
    code = main([str(a) for a in args])
    out, err = capsys.readouterr()
    return code, out, err


def _error(err):
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("bearinglab: error: ") and "Traceback" not in err, err
    return lines[0][len("bearinglab: error: "):]


@pytest.fixture
def two(tmp_path):
    path = tmp_path / "two.toml"
    path.write_text(TWO, encoding="utf-8")
    return path


def test_the_json_is_the_document_of_the_files_text(capsys):
    code, out, err = _run(capsys, "shaft", SPINDLE, "--stiffness-at", "0 mm", "--modes", "2", "--json")
    assert code == 0, err
    doc = json.loads(out)
    text = SPINDLE.read_text(encoding="utf-8")  # the web posts the same text
    posted = calculations.run(calculations.parse("shaft", {"model": text, "stiffness_at": "0 mm", "modes": "2"}))
    assert doc == json.loads(json.dumps(posted))
    assert [s["name"] for s in doc["supports"]] == ["front", "rear"]
    assert len(doc["natural_frequencies_Hz"]) == 2 and doc["stiffness_at"]["position_mm"] == 0.0


def test_the_tables_show_loads_displacements_lives_and_the_system(capsys, two):
    code, out, err = _run(capsys, "shaft", two, "--stiffness-at", "150 mm", "--modes", "1")
    assert code == 0, err
    code, js, _ = _run(capsys, "shaft", two, "--stiffness-at", "150 mm", "--modes", "1", "--json")
    doc = json.loads(js)
    a, b = doc["supports"]
    assert a["force_y_N"] + b["force_y_N"] == pytest.approx(-2000.0, rel=1e-9)  # they carry the load
    for title in ("Shaft system: 300 mm, 1 sections", "Support loads", "Support displacements and tilts",
                  "Bearings (ISO 281, ISO/TS 16281)", "system life L10h [h]", "stiffness at z = 150 mm",
                  "natural frequencies [Hz]", "converged (iterations, residual)"):
        assert title in out, title
    # the loads in kN to the newton, the lives and the system life as computed
    row_a = next(line for line in out.splitlines() if line.startswith("│ A ") and "0.300" in line)
    assert f"{a['force_y_N'] / 1e3:.3f}" in row_a  # A locates the shaft axially: F_z
    assert f"{round(doc['system_life_h']):d}" in out
    assert f"{round(a['basic_rating_life_h']):d}" in out
    assert f"{doc['stiffness_at']['stiffness_x_N_per_um']:.4g}" in out
    assert not any(len(line) > 80 for line in out.splitlines())  # COLUMNS=80 off a terminal


def test_csv_holds_the_rows_along_the_shaft_and_plot_draws_them(capsys, two, tmp_path):
    rows, figure = tmp_path / "rows.csv", tmp_path / "shaft.png"
    code, out, err = _run(capsys, "shaft", two, "--csv", rows, "--plot", figure)
    assert code == 0, err
    compact = "".join(out.split())  # a long path wraps at 80 columns
    assert f"wrote{rows}" in compact and f"wrote{figure}" in compact
    assert figure.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    code, js, _ = _run(capsys, "shaft", two, "--json")
    deflection = json.loads(js)["deflection"]
    with rows.open(encoding="utf-8", newline="") as f:
        read = list(csv.DictReader(f))
    assert len(read) == len(deflection) and list(read[0]) == list(deflection[0])
    for got, want in zip(read, deflection):
        assert got["at"] == want["at"]
        for key in ("z_mm", "displacement_y_um", "slope_y_mrad", "bending_moment_x_Nm", "shear_force_y_N"):
            assert float(got[key]) == want[key], key  # every digit: floats written as repr
    assert {r["at"] for r in read} >= {"A", "B", "F"}  # every support and load is a row


def test_an_output_never_replaces_the_input_file(capsys, tmp_path):
    source = tmp_path / "two.csv"  # a shaft file with the suffix of the CSV output
    source.write_text(TWO, encoding="utf-8")
    code, _, err = _run(capsys, "shaft", source, "--csv", source)
    assert code == 2 and "is an input file of this command" in _error(err)
    assert source.read_text(encoding="utf-8") == TWO


@pytest.mark.parametrize("edit, message", [
    (None, "model: {path}: no such file"),
    ('position = "280 mm"', "model: supports[1].position: B at 500 mm lies outside the shaft"),
    ("[[loads]]", "model: document: not valid TOML"),
    ('fy = "-2 kN"', "model: loads[0].fy: '-2 m' is a length, expected a force"),
])
def test_errors_are_one_line_naming_the_field_and_the_file(capsys, tmp_path, edit, message):
    path = tmp_path / "s.toml"
    if edit is not None:
        replacement = {'position = "280 mm"': 'position = "500 mm"', "[[loads]]": "[[loads]\n",
                       'fy = "-2 kN"': 'fy = "-2 m"'}[edit]
        path.write_text(TWO.replace(edit, replacement), encoding="utf-8")
    code, _, err = _run(capsys, "shaft", path)
    assert code == 2
    assert _error(err).startswith(message.format(path=path)), err


def test_a_file_that_is_no_text_is_refused_naming_it(capsys, tmp_path):
    path = tmp_path / "s.toml"
    path.write_bytes(b"\xff\xfe\x00x")
    code, _, err = _run(capsys, "shaft", path)
    assert code == 2 and _error(err) == f"model: {path}: not a UTF-8 text file"
    code, _, err = _run(capsys, "shaft", tmp_path)
    assert code == 2 and _error(err).startswith(f"model: {str(tmp_path)!r} is a directory")


def test_a_solve_that_does_not_converge_exits_with_3(capsys, tmp_path):
    # a thrust alone: the floating bearing B carries nothing inside its clearance, so the shaft is free
    # to move radially there and the Newton solve of the system finds no equilibrium
    path = tmp_path / "free.toml"
    path.write_text(TWO.replace('fy = "-2 kN"\n', "").replace('fz = "300 N"', 'fz = "1 kN"'), encoding="utf-8")
    code, _, err = _run(capsys, "shaft", path)
    assert code == 3 and _error(err).startswith("model: no convergence")


def test_user_bearings_come_from_the_catalog_option(capsys, tmp_path):
    catalog = tmp_path / "mine.toml"
    catalog.write_text('[bearings."MY-6206"]\ntype = "radial"\nbore = "30 mm"\noutside_diameter = "62 mm"\n'
                       'width = "16 mm"\nballs = 9\nball_diameter = "9.525 mm"\npitch_diameter = "46 mm"\n'
                       'inner_conformity = 0.515\nouter_conformity = 0.525\ncontact_angle = "0 deg"\n'
                       'dynamic_load_rating = "20.3 kN"\nstatic_load_rating = "11.2 kN"\n', encoding="utf-8")
    path = tmp_path / "s.toml"
    path.write_text(TWO.replace('bearing = "6206"', 'bearing = "MY-6206"'), encoding="utf-8")
    code, _, err = _run(capsys, "shaft", path)
    assert code == 2 and "MY-6206" in _error(err)  # not in the built-in catalog
    code, out, err = _run(capsys, "shaft", path, "--catalog", catalog, "--json")
    assert code == 0, err
    doc = json.loads(out)
    assert [s["bearing"] for s in doc["supports"]] == ["MY-6206", "MY-6206"]
    # ISO 281: L10 = (C/P)^3 10^6 rev for the one bearing that takes no thrust (P = F_r = 1 kN)
    b = doc["supports"][1]
    p = b["equivalent_dynamic_load_N"]
    assert p == pytest.approx(math.hypot(b["force_x_N"], b["force_y_N"]), rel=1e-12)
    assert b["basic_rating_life_Mrev"] == pytest.approx((20.3e3 / p) ** 3, rel=1e-12)


def test_the_help_names_the_file(capsys):
    code, out, _ = _run(capsys, "shaft", "--help")
    assert code == 0
    text = " ".join(out.split())
    assert "FILE" in text and "TOML file of the shaft system" in text
    assert "never a file path" not in text and "posted" not in text
    for option in ("--catalog", "--csv", "--plot", "--json", "--stiffness-at", "--modes", "--speed"):
        assert option in text, option


def test_run_json_is_the_webs_adapter(two):
    printed = cli.run_json(["shaft", str(two)])
    assert printed.exit_code == 0 and printed.document["supports"][0]["name"] == "A"

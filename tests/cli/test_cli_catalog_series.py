"""Every command takes every catalog bearing (issue 21 item 6): a sample of designations of each family
through every command, with the warning that the geometry is estimated; catalog show and search."""

import json

import pytest

from bearinglab.cli import main, run_json

DESIGNATIONS = ["6208-2RS1/C3", "623-2Z", "16008", "7205 BECBP", "7014 CD/P4A", "71914 ACD", "71810 ACD"]
COMMANDS = {
    "life": ["life", "--radial-load", "2 kN", "--axial-load", "0.5 kN", "--speed", "3000 rpm",
             "--viscosity", "20 cSt"],
    "load-distribution": ["load-distribution", "--radial-load", "1 kN", "--axial-load", "0.3 kN"],
    "bearing-set": ["bearing-set", "--arrangement", "DB", "--preload", "200 N", "--radial-load", "1 kN"],
    "friction torque": ["friction", "torque", "--radial-load", "500 N", "--axial-load", "100 N",
                        "--speed", "3000 rpm"],
    "frequencies": ["frequencies", "--speed", "3000 rpm"],
    "high-speed": ["high-speed", "--axial-load", "1 kN", "--speed", "6000 rpm"],
    "axial-angle": ["axial-angle", "--axial-load", "200 N"],
    "stand-load": ["stand-load", "--speed", "3000 rpm"],
}


@pytest.mark.parametrize("command", list(COMMANDS))
@pytest.mark.parametrize("name", DESIGNATIONS)
def test_every_command_takes_the_bearing_and_says_the_geometry_is_estimated(name, command):
    argv = COMMANDS[command] + ["-b", name, "--json"]
    r = run_json(argv)
    assert r.exit_code == 0, r.error
    docs = r.document if isinstance(r.document, list) else [r.document]
    for doc in docs:
        assert any("estimated, not published" in w and "--bearing-file" in w for w in doc["warnings"])


def test_sweep_takes_a_designation(tmp_path):
    f = tmp_path / "s.toml"
    f.write_text('model = "axial-angle"\nbearing = "7205 BECBP"\n[parameters]\naxial_load = ["100 N", "200 N"]\n',
                 encoding="utf-8")
    r = run_json(["sweep", str(f), "--out", str(tmp_path / "o.csv")])
    assert r.exit_code == 0, r.error
    assert any("estimated" in w for w in r.document["warnings"])


def test_the_skf_friction_model_says_what_it_cannot_do(capsys):
    # the SKF model's angular-contact constants are published for 40 deg bearings: a 15 deg one is refused
    code = main(["friction", "torque", "-b", "7005 C", "--model", "skf", "--radial-load", "500 N",
                 "--speed", "3000 rpm", "--viscosity", "32 cSt"])
    err = capsys.readouterr().err
    assert code == 2 and "15 deg is not covered by SKF's published friction constants" in err


def test_show_json_sources_and_estimated_fields(capsys):
    code = main(["catalog", "show", "6208-2RS1/C3", "--json"])
    doc = json.loads(capsys.readouterr().out)
    assert code == 0
    iso = doc["iso5753_clearance"]
    assert (iso["class"], iso["minimum_um"], iso["maximum_um"], iso["used"]) == ("C3", 15, 33, "mean")
    assert doc["radial_clearance_um"] == pytest.approx(24)
    assert "n_balls" in doc["estimated_fields"] and "SKF General Catalogue" in doc["sources"]["dynamic_load_rating"]
    assert doc["seal"] == "RS1" and doc["seals"] == 2
    assert doc["chamfer_mm"] == 1.1 and doc["limiting_speed_rpm"] == 11000


@pytest.mark.parametrize(("option", "expected"), [(["--clearance", "max"], 33), (["--clearance", "min"], 15),
                                                   (["--radial-clearance", "20 um"], 20)])
def test_show_clearance_options(capsys, option, expected):
    code = main(["catalog", "show", "6208/C3", "--json", *option])
    doc = json.loads(capsys.readouterr().out)
    assert code == 0 and doc["radial_clearance_um"] == pytest.approx(expected)


def test_show_table_marks_estimated_values(capsys, monkeypatch):
    monkeypatch.setenv("COLUMNS", "80")
    code = main(["catalog", "show", "7205 BECBP"])
    out = capsys.readouterr().out
    assert code == 0 and "(estimated)" in out and "15600 (catalog)" in out
    assert max(len(line) for line in out.splitlines()) <= 80


def test_unknown_suffix_exit_2_naming_the_valid_ones(capsys):
    code = main(["catalog", "show", "6208-2XX"])
    err = capsys.readouterr().err
    assert code == 2 and "unknown suffix '2XX'" in err and "clearance C2, CN, C3, C4, C5" in err
    assert len(err.strip().splitlines()) == 1


def test_search_command(capsys, monkeypatch):
    monkeypatch.setenv("COLUMNS", "80")
    code = main(["catalog", "search", "--bore", "40 mm", "--type", "deep-groove"])
    out = capsys.readouterr().out
    assert code == 0 and "6208" in out and "7208" not in out
    assert max(len(line) for line in out.splitlines()) <= 80
    code = main(["catalog", "search", "--bore", "40", "--series", "72", "--json"])
    doc = json.loads(capsys.readouterr().out)
    assert code == 0 and [b["name"] for b in doc["bearings"]] == ["7208 BE", "7208 A", "7208 B", "7208 C", "7208 ACD"]


def test_search_needs_a_criterion(capsys):
    assert main(["catalog", "search"]) == 2

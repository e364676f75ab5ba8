"""The ``bearinglab catalog`` commands, run in-process through ``bearinglab.cli.main``."""

import json
import math

import pytest

from bearinglab import catalog
from bearinglab.cli import main


def run(capsys, *argv):
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def test_list_json(capsys):
    code, out, err = run(capsys, "catalog", "list", "--json")
    assert code == 0 and err == ""
    rows = json.loads(out)
    assert [r["name"] for r in rows] == catalog.names()
    by_name = {r["name"]: r for r in rows}
    assert by_name["B218"]["balls"] == 16 and by_name["B218"]["contact_angle_deg"] == pytest.approx(
        40.0
    )
    assert by_name["6205-2RS"]["ball_diameter_mm"] == pytest.approx(7.94)
    assert by_name["18"]["balls"] is None and by_name["18"]["pitch_diameter_mm"] == pytest.approx(
        13.5
    )


def test_list_table(capsys):
    code, out, err = run(capsys, "catalog", "list")
    assert code == 0 and err == ""
    for name in catalog.names():
        assert name in out
    assert "8.7355" in out


def test_show_json_example_bearing(capsys):
    code, out, err = run(capsys, "catalog", "show", "4-1006095", "--json")
    assert code == 0 and err == ""
    doc = json.loads(out)
    assert doc["designation"] == "4-1006095" and doc["balls"] == 7
    assert doc["inner_groove_radius_mm"] == pytest.approx(1.05) and doc[
        "outer_groove_radius_mm"
    ] == pytest.approx(1.16)
    assert doc["total_curvature_B"] == pytest.approx(0.105)
    assert f"{doc['radial_clearance_um']:.3f}" == "9.178"  # spec 000 section 4
    assert doc["gamma"] == pytest.approx(2 * math.cos(math.radians(12)) / 8.7355, rel=1e-12)
    assert doc["hertz_table"] == {"inner": 0.63, "outer": 0.852}
    assert doc["axial_play_mm"] == pytest.approx(2 * 0.21 * math.sin(math.radians(12)), rel=1e-12)


def test_show_alias_and_table(capsys):
    code, out, err = run(capsys, "catalog", "show", "7218B")
    assert code == 0 and err == ""
    assert "B218" in out and "125.3" in out and "0.5232" in out


def test_show_partial_entry(capsys):
    code, out, _err = run(capsys, "catalog", "show", "1000095", "--json")
    assert code == 0
    doc = json.loads(out)
    assert doc["balls"] is None and doc["static_load_rating_N"] == pytest.approx(392.0)


def _one_line_exit_2(code, out, err):
    assert code == 2
    assert out == ""
    assert "Traceback" not in err
    assert len(err.strip().splitlines()) == 1, err
    assert err.startswith("bearinglab: error: ")


def test_unknown_name(capsys):
    code, out, err = run(capsys, "catalog", "show", "6299")
    _one_line_exit_2(code, out, err)
    assert "unknown name '6299'; did you mean 6240 or 6238 or 6236 (series 62)?" in err


def test_missing_catalog_file(capsys, tmp_path):
    code, out, err = run(capsys, "catalog", "list", "--catalog", str(tmp_path / "none.toml"))
    _one_line_exit_2(code, out, err)
    assert "none.toml: no such file" in err


def test_malformed_catalog_file(capsys, tmp_path):
    path = tmp_path / "bad.toml"
    path.write_text('[bearings."Q"]\nballs = 7\nball_diameter = "2 mm"\npitch_diameter = "1 mm"\n')
    code, out, err = run(capsys, "catalog", "show", "Q", "--catalog", str(path))
    _one_line_exit_2(code, out, err)
    assert (
        f"{path}, entry 'Q', field 'pitch_diameter': pitch_diameter must be > ball_diameter" in err
    )


def test_invalid_toml(capsys, tmp_path):
    path = tmp_path / "bad.toml"
    path.write_text("[bearings.\n")
    code, out, err = run(capsys, "catalog", "list", "--catalog", str(path))
    _one_line_exit_2(code, out, err)
    assert f"{path}: not valid TOML" in err


@pytest.mark.parametrize(
    "argv, text",
    [
        (["catalog", "show"], "Missing argument"),
        (["catalog", "remove", "B218"], "No such command 'remove'"),
        (["catalog", "list", "--colour"], "No such option"),
        # a bearing typed as a word, not as the option the commands take, is named with the option
        (["life", "6205-2RS", "--radial-load", "2 kN"], "(6205-2RS): give the bearing as an option, --bearing 6205-2RS"),
        (["axial-angle", "7218b", "-F", "2 kN"], "--bearing 7218b"),
    ],
)
def test_usage_errors(capsys, argv, text):
    code, out, err = run(capsys, *argv)
    _one_line_exit_2(code, out, err)
    assert text in err


def test_an_extra_word_that_is_no_bearing_gets_no_hint(capsys):
    code, out, err = run(capsys, "life", "7205Q", "--radial-load", "2 kN")
    _one_line_exit_2(code, out, err)
    assert err.rstrip().endswith("(7205Q)")


def test_help(capsys):
    code, out, _err = run(capsys, "catalog", "--help")
    assert code == 0 and "list" in out and "show" in out


def test_show_lists_the_ratings_with_their_source(capsys):
    from bearinglab import ratings

    code, out, err = run(capsys, "catalog", "show", "B218", "--json")
    assert code == 0 and err == ""
    doc = json.loads(out)
    r = ratings.bearing_ratings(catalog.get("B218"))
    assert doc["dynamic_load_rating_N"] == r.dynamic_load_rating
    assert doc["static_load_rating_N"] == r.static_load_rating
    assert doc["fatigue_load_limit_N"] == r.fatigue_load_limit
    assert doc["rating_source"] == r.rating_source
    code, out, err = run(capsys, "catalog", "show", "B218")
    assert code == 0 and "dynamic_load_rating_N" in out


def test_show_without_ball_set_keeps_catalog_ratings(capsys):
    code, out, err = run(capsys, "catalog", "show", "18", "--json")
    assert code == 0 and err == ""
    doc = json.loads(out)
    assert doc["static_load_rating_N"] == pytest.approx(1354.0)
    assert doc["rating_source"] == {"static_load_rating": "catalog"} and doc["dynamic_load_rating_N"] is None

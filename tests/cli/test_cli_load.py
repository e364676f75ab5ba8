"""``bearinglab load-distribution`` and ``bearing-set`` (issue 11): JSON keys, equality with the library,
plots, the ROSS file and bad inputs."""

import json
import math
import re

import numpy as np
import pytest

from bearinglab import catalog
from bearinglab.cli import main
from bearinglab.quasistatic import combined, sets
from bearinglab.units import RPM

KEYS = ["displacement_x_um", "displacement_y_um", "displacement_z_um", "tilt_x_mrad", "tilt_y_mrad",
        "axial_play_takeup_um", "reactions", "stiffness_matrix", "max_ball_load_N", "converged", "residual", "iterations", "balls", "inputs", "warnings"]
BALL_KEYS = ["azimuth_deg", "load_inner_N", "load_outer_N", "contact_angle_inner_deg", "contact_angle_outer_deg",
             "max_pressure_inner_MPa", "max_pressure_outer_MPa"]


def run(capsys, *args):
    code = main(list(args))
    out, err = capsys.readouterr()
    return code, out, err


def _one_line_error(err):
    lines = err.strip().splitlines()
    assert len(lines) == 1, err
    assert lines[0].startswith("bearinglab: error:") and "Traceback" not in err
    return lines[0]


def test_json_keys_and_the_library(capsys):
    code, out, err = run(capsys, "load-distribution", "-b", "B218", "--fx", "5 kN", "--fz", "10 kN", "--my",
                         "100000 N*mm", "--speed", "6000 rpm", "--first-ball-angle", "5 deg", "--json")
    assert code == 0, err
    doc = json.loads(out)
    assert list(doc) == KEYS
    assert len(doc["balls"]) == 16 and all(list(b) == BALL_KEYS for b in doc["balls"])
    r = combined.combined_analysis(catalog.get("B218"), [5e3, 0, 10e3, 0, 100.0], 6000 * RPM,
                                   first_ball_angle=math.radians(5))
    assert doc["displacement_x_um"] == pytest.approx(r.displacement[0] * 1e6, rel=1e-12)
    assert doc["tilt_y_mrad"] == pytest.approx(r.displacement[4] * 1e3, rel=1e-12)
    np.testing.assert_allclose(doc["stiffness_matrix"], r.stiffness, rtol=1e-12)
    got = [b["load_inner_N"] for b in doc["balls"]]
    np.testing.assert_allclose(got, r.ball_load_inner, rtol=1e-12)
    assert doc["balls"][1]["azimuth_deg"] == pytest.approx(5 + 22.5)
    assert doc["max_ball_load_N"] == pytest.approx(r.max_ball_load, rel=1e-12)
    assert doc["converged"] is True and doc["residual"] < 1e-12
    inputs = doc["inputs"]
    assert inputs["bearing"] == "B218" and inputs["my_Nmm"] == pytest.approx(1e5) and inputs["speed_rpm"] == 6000
    assert inputs["first_ball_angle_deg"] == pytest.approx(5.0) and inputs["geometry"]["balls"] == 16
    # 10 kN at 6000 rpm is above SKF's minimum load 0.01 C (issue 20; the test-stand criterion flagged it)
    assert not any("minimum load" in w or "light load" in w for w in doc["warnings"])


def test_radial_load_is_fx_and_clearance_override(capsys):
    args = ("load-distribution", "-b", "B218", "--speed", "0 rpm", "--radial-clearance", "50 um", "--json")
    code, out, err = run(capsys, *args, "--radial-load", "3 kN", "--axial-load", "2 kN")
    assert code == 0, err
    code, out2, err = run(capsys, *args, "--fx", "3 kN", "--fz", "2 kN")
    assert code == 0 and json.loads(out) == json.loads(out2)
    assert json.loads(out)["inputs"]["radial_clearance_um"] == pytest.approx(50.0)


def test_plot_and_ross_file(capsys, tmp_path):
    png, ross = tmp_path / "loads.png", tmp_path / "ross.json"
    code, out, err = run(capsys, "load-distribution", "-b", "B218", "--fz", "10 kN", "--fx", "2 kN", "--speed",
                         "0, 6000, 12000 rpm", "--plot", str(png), "--ross", str(ross), "--json")
    assert code == 0, err
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    docs = json.loads(out)
    assert [d["inputs"]["speed_rpm"] for d in docs] == [0, 6000, 12000]
    coef = json.loads(ross.read_text())
    from bearinglab.quasistatic import rotordynamics

    key = rotordynamics.speed_keyword()  # "speed" (ROSS 3, or none installed), "frequency" (ROSS 2)
    assert set(coef) & {"speed", "frequency"} == {key}
    assert coef[key] == pytest.approx([0.0, 6000 * RPM, 12000 * RPM])
    assert coef["kxx"] == pytest.approx([d["stiffness_matrix"][0][0] for d in docs], rel=1e-12)


def test_table_output(capsys):
    code, out, err = run(capsys, "load-distribution", "-b", "B218", "--fx", "5 kN", "--fz", "10 kN")
    assert code == 0, err
    assert "ball loads" in out and "max ball load" in out


@pytest.mark.parametrize("args, name", [
    (["--fx", "5 kg"], "fx"),
    (["--mx", "5 N"], "mx"),
    (["--fx", "1 kN", "--radial-load", "1 kN"], "radial-load"),
    (["--fx", "1 kN", "--speed", "0, 100 rpm"], "speed"),
    (["--fx", "1 kN", "--stiffness-at", "later"], "stiffness-at"),
])
def test_bad_input_is_one_line_and_exit_2(capsys, args, name):
    code, _, err = run(capsys, "load-distribution", "-b", "B218", *args)
    assert code == 2
    assert name in _one_line_error(err)


def test_bearing_set_json_and_the_library(capsys, tmp_path):
    png = tmp_path / "set.png"
    code, out, err = run(capsys, "bearing-set", "-b", "B218", "--arrangement", "DB", "--spacing", "100 mm",
                         "--preload", "2 kN", "--fx", "3 kN", "--my", "50 N*m", "--plot", str(png), "--json")
    assert code == 0, err
    doc = json.loads(out)
    s = sets.set_analysis(catalog.get("B218"), [3e3, 0, 0, 0, 50.0], arrangement_kind="DB", spacing=0.1,
                          preload=2e3)
    np.testing.assert_allclose(doc["stiffness_matrix"], s.stiffness, rtol=1e-12)
    assert doc["displacement_x_um"] == pytest.approx(s.displacement[0] * 1e6, rel=1e-12)
    assert len(doc["bearings"]) == 2 and [b["orientation"] for b in doc["bearings"]] == [1, -1]
    q = [b["load_inner_N"] for b in doc["bearings"][1]["balls"]]
    np.testing.assert_allclose(q, s.bearings[1]["ball_load_inner"], rtol=1e-12)
    assert png.read_bytes()[:4] == b"\x89PNG"


def test_bearing_set_by_offset_and_bad_preload(capsys):
    code, out, err = run(capsys, "bearing-set", "-b", "B218", "-b", "B218", "--preload-offset", "5 um", "--json")
    assert code == 0, err
    assert json.loads(out)["preload_offset_um"] == pytest.approx(5.0)
    code, _, err = run(capsys, "bearing-set", "-b", "B218", "--preload", "1 kN", "--preload-offset", "5 um")
    assert code == 2 and "preload" in _one_line_error(err)
    code, _, err = run(capsys, "bearing-set", "-b", "B218", "--arrangement", "XX")
    assert code == 2 and "arrangement" in _one_line_error(err)


# ----------------------------------------------------------------------------- guard-rails (issue 15, review)
@pytest.mark.parametrize("order", [["4-1006095", "B218"], ["B218", "4-1006095"]])
def test_bearing_set_speed_guard_uses_the_largest_bearing(capsys, order):
    # 1e6 rpm is within d_m n for the 8.7 mm bearing but not for B218 (125.3 mm), whichever comes first
    code, _, err = run(capsys, "bearing-set", "-b", order[0], "-b", order[1], "--speed", "1e6 rpm", "--fz", "10 N")
    line = _one_line_error(err)
    assert code == 2 and "speed must be <= 279330 [rpm] for d_m = 125.3 mm" in line


@pytest.mark.parametrize("option, words", [
    ("--spacing=-5 mm", "spacing must be >= 0 [mm], got -5 mm"),
    ("--preload=-3 kN", "preload must be >= 0 [N] (an axial force at rest), got -3000 N"),
])
def test_bearing_set_messages_in_engineering_units(capsys, option, words):
    code, _, err = run(capsys, "bearing-set", "-b", "B218", option, "--fz", "1 kN")
    assert code == 2 and words in _one_line_error(err)


def test_bearing_set_prints_no_negative_zero(capsys):
    code, out, err = run(capsys, "bearing-set", "-b", "B218", "--fz", "1 kN", "--preload", "500 N", "--spacing",
                         "0 mm")
    assert code == 0, err
    assert "z = 0 mm" in out and not re.search(r"(?<![\w.])-0(?:\.0*)?(?![\w.])", out)
    code, out, _ = run(capsys, "bearing-set", "-b", "B218", "--fz", "1 kN", "--preload", "500 N", "--spacing",
                       "0 mm", "--json")
    assert [math.copysign(1.0, m["position_mm"]) for m in json.loads(out)["bearings"]] == [1.0, 1.0]


def test_light_loads_and_soft_stiffnesses_keep_four_significant_digits(capsys):
    code = main(["load-distribution", "-b", "4-1006095", "--fz", "0.1 N"])
    out = " ".join(capsys.readouterr().out.split())
    assert code == 0
    doc = json.loads(_json_of(capsys, ["load-distribution", "-b", "4-1006095", "--fz", "0.1 N", "--json"]))
    q = doc["max_ball_load_N"]
    assert q < 0.1 and f"max ball load [N] │ {q:.5f} │" in out
    k = doc["stiffness_matrix"][3][3] * 1e-3
    assert f"{k:.6f}" in out and "0.00, 0.00" not in out


def test_a_set_prints_no_empty_ball_table_and_the_largest_ball_load(capsys):
    args = ["bearing-set", "-b", "B218", "--preload", "2 kN", "--fx", "5 kN", "--spacing", "100 mm"]
    code = main(args)
    out = capsys.readouterr().out
    assert code == 0 and "Set DB of 2: ball loads" not in out and "Set DB of 2: shaft" in out
    doc = json.loads(_json_of(capsys, [*args, "--json"]))
    worst = max(m["max_ball_load_N"] for m in doc["bearings"])
    tail = " ".join(out[out.index("Set DB of 2: shaft"):].split())
    assert f"max ball load [N] │ {worst:.2f} │" in tail and "—" not in tail


def _json_of(capsys, args):
    assert main(args) == 0
    return capsys.readouterr().out


# ----------------------------------------------------------------------------- issue 20 items 10 and 11
def test_bearing_set_default_spacing_is_one_width_and_said(capsys):
    """Without --spacing a duplex pair sits side by side (B218: B = 30 mm); JSON and table say so; a DB
    pair is then stiffer in tilt than a DF pair (a default of 0 mm gave both the same)."""
    docs = {}
    for kind in ("DB", "DF"):
        docs[kind] = json.loads(_json_of(capsys, ["bearing-set", "-b", "B218", "--arrangement", kind, "--preload",
                                                  "2 kN", "--json"]))
        inputs = docs[kind]["inputs"]
        assert inputs["spacing_mm"] == pytest.approx(30.0) and inputs["spacing_default"] is True
        assert [m["position_mm"] for m in docs[kind]["bearings"]] == pytest.approx([-15.0, 15.0])
    assert docs["DB"]["stiffness_matrix"][4][4] > 2 * docs["DF"]["stiffness_matrix"][4][4]
    given = json.loads(_json_of(capsys, ["bearing-set", "-b", "B218", "--spacing", "30 mm", "--preload", "2 kN",
                                         "--json"]))
    assert given["inputs"]["spacing_default"] is False
    assert given["stiffness_matrix"] == docs["DB"]["stiffness_matrix"]
    assert main(["bearing-set", "-b", "B218", "--preload", "2 kN"]) == 0
    out = " ".join(capsys.readouterr().out.split())
    assert "spacing [mm] │ 30 (default: side by side, one width) │" in out


def test_bearing_set_without_width_needs_spacing(capsys, tmp_path):
    cat = tmp_path / "cat.toml"
    cat.write_text('[bearings."NOWIDTH"]\ntype = "angular"\nballs = 15\nball_diameter = "7.938 mm"\n'
                   'pitch_diameter = "52.5 mm"\ninner_conformity = 0.52\nouter_conformity = 0.53\n'
                   'contact_angle = "15 deg"\n', encoding="utf-8")
    code, _, err = run(capsys, "bearing-set", "--catalog", str(cat), "-b", "NOWIDTH", "--preload", "100 N")
    line = _one_line_error(err)
    assert code == 2 and "spacing" in line and "NOWIDTH" in line and "no width" in line
    code, _, err = run(capsys, "bearing-set", "--catalog", str(cat), "-b", "NOWIDTH", "--preload", "100 N",
                       "--spacing", "20 mm")
    assert code == 0, err


def test_displacements_say_what_they_include(capsys):
    """delta_z is counted from the concentric position: half the axial play, A sin(alpha0), is inside it.
    B218 (catalog: D = 22.23 mm, f_i = f_o = 0.5232, alpha0 = 40 deg): s_a/2 = 0.0464 x 22.23 mm x sin 40 deg
    = 0.6630 mm, computed here by hand."""
    hand_um = (0.5232 + 0.5232 - 1.0) * 22.23e3 * math.sin(math.radians(40.0))
    assert hand_um == pytest.approx(663.0, abs=0.1)
    doc = json.loads(_json_of(capsys, ["load-distribution", "-b", "B218", "--fz", "10 kN", "--json"]))
    assert doc["axial_play_takeup_um"] == pytest.approx(hand_um, rel=1e-12)
    elastic = doc["displacement_z_um"] - doc["axial_play_takeup_um"]
    # the elastic part is the static thrust model's delta_a, which is measured from first contact
    from bearinglab import static
    b = catalog.get("B218")
    ref = static.contact_angle_under_thrust(10e3, b.n_balls, b.ball_diameter, b.pitch_diameter, b.inner_conformity,
                                            b.outer_conformity, b.contact_angle, b.reduced_modulus)
    assert elastic == pytest.approx(ref.axial_displacement * 1e6, rel=1e-8)
    assert main(["load-distribution", "-b", "B218", "--fz", "10 kN"]) == 0
    out = " ".join(capsys.readouterr().out.split())
    assert "(from concentric)" in out and f"half axial play in δ_z [µm] │ {hand_um:.4f} │" in out
    # a set of opposed bearings counts the shaft from the assembled set: no play inside; each bearing's own
    # displacement (in its frame, from concentric) has its half play
    doc = json.loads(_json_of(capsys, ["bearing-set", "-b", "B218", "--preload", "2 kN", "--json"]))
    assert doc["axial_play_takeup_um"] == 0.0
    assert [m["axial_play_takeup_um"] for m in doc["bearings"]] == pytest.approx([hand_um] * 2, rel=1e-12)
    assert all(m["displacement_z_um"] > hand_um for m in doc["bearings"])


def test_prescribed_displacements_and_reactions(capsys):
    """--tilt-x/--tilt-y '0 mrad' hold the ring square; the reactions are in the JSON (N, N mm) and the
    table, and equal the library's (issue 20 item 18)."""
    args = ["load-distribution", "-b", "B218", "--fx", "5 kN", "--fz", "10 kN", "--tilt-x", "0 mrad", "--tilt-y",
            "0 mrad"]
    doc = json.loads(_json_of(capsys, [*args, "--json"]))
    nan = float("nan")
    r = combined.combined_analysis(catalog.get("B218"), [5e3, 0, 10e3, 0, 0],
                                   prescribed_displacement=[nan, nan, nan, 0.0, 0.0])
    assert list(doc["reactions"]) == ["mx_Nmm", "my_Nmm"]
    assert doc["reactions"]["my_Nmm"] == pytest.approx(r.reactions[4] * 1e3, rel=1e-12)
    assert doc["tilt_x_mrad"] == 0.0 and doc["tilt_y_mrad"] == 0.0
    assert doc["inputs"]["prescribed"] == {"tilt_x_mrad": 0.0, "tilt_y_mrad": 0.0}
    assert main(args) == 0
    out = " ".join(capsys.readouterr().out.split())
    assert f"reaction M_y [N·mm] (held) │ {r.reactions[4] * 1e3:.2f} │" in out
    # the axial displacement held: its thrust comes back as the reaction
    dz = f"{doc['displacement_z_um']!r} um"
    doc2 = json.loads(_json_of(capsys, ["load-distribution", "-b", "B218", "--fx", "5 kN", "--dz", dz, "--tilt-x",
                                        "0 mrad", "--tilt-y", "0 mrad", "--json"]))
    assert doc2["reactions"]["fz_N"] == pytest.approx(10e3, rel=1e-8)
    free = json.loads(_json_of(capsys, ["load-distribution", "-b", "B218", "--fx", "5 kN", "--fz", "10 kN", "--json"]))
    assert free["reactions"] == {} and free["tilt_y_mrad"] == pytest.approx(3.0, rel=0.05)  # the free ring tilts


@pytest.mark.parametrize("args, words", [
    (["--fz", "10 kN", "--dz", "700 um"], "dz: give --fz or --dz, not both"),
    (["--axial-load", "10 kN", "--dz", "700 um"], "dz: give --fz or --dz, not both"),
    (["--fz", "10 kN", "--tilt-y", "5 N"], "tilt-y"),
])
def test_prescribed_displacement_errors(capsys, args, words):
    code, _, err = run(capsys, "load-distribution", "-b", "B218", "--fx", "1 kN", *args)
    assert code == 2 and words in _one_line_error(err)

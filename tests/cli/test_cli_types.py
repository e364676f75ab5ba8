"""Issue 30 item 4 at the boundaries: four-point, double-row, self-aligning and thrust ball bearings through
``load-distribution``, ``life`` (ISO/TS 16281 L10r from the contact loads), ``film`` and ``bearing-set``,
given by a bearing file (the catalog has no ball set of these types)."""

import json
import math
import re
import warnings

import numpy as np
import pytest

from bearinglab import catalog
from bearinglab.cli import main
from bearinglab.life import rating_life
from bearinglab.quasistatic import combined
from bearinglab.ratings import reference

ENTRIES = {
    "qj": ('type = "four-point"\nballs = 13\nball_diameter = "12.7 mm"\npitch_diameter = "60 mm"\n'
           'inner_conformity = 0.52\nouter_conformity = 0.53\ncontact_angle = "35 deg"\nradial_clearance = "40 um"\n'
           'bore = "40 mm"\noutside_diameter = "80 mm"\nwidth = "18 mm"\ndynamic_load_rating = "56 kN"\n'
           'static_load_rating = "49 kN"\n'),
    "dra": ('type = "double-row-angular"\nballs = 13\nball_diameter = "11 mm"\npitch_diameter = "60 mm"\n'
            'inner_conformity = 0.52\nouter_conformity = 0.53\ncontact_angle = "30 deg"\nradial_clearance = "10 um"\n'
            'row_distance = "15 mm"\nbore = "40 mm"\noutside_diameter = "80 mm"\nwidth = "30.2 mm"\n'
            'dynamic_load_rating = "48 kN"\nstatic_load_rating = "40 kN"\n'),
    "sa": ('type = "self-aligning"\nballs = 14\nball_diameter = "9.5 mm"\npitch_diameter = "60 mm"\n'
           'inner_conformity = 0.53\ncontact_angle = "8 deg"\nradial_clearance = "20 um"\nbore = "40 mm"\n'
           'outside_diameter = "80 mm"\nwidth = "18 mm"\ndynamic_load_rating = "19.9 kN"\nstatic_load_rating = "6.95 kN"\n'),
    "th": ('type = "thrust"\nballs = 15\nball_diameter = "11 mm"\npitch_diameter = "55 mm"\ninner_conformity = 0.54\n'
           'outer_conformity = 0.54\ncontact_angle = "90 deg"\nbore = "40 mm"\noutside_diameter = "68 mm"\n'
           'width = "19 mm"\ndynamic_load_rating = "46.2 kN"\nstatic_load_rating = "98 kN"\n'),
}
LOADS = {"qj": ["--fx", "2 kN", "--fz", "1 kN"], "dra": ["--fx", "2 kN", "--fz", "1 kN"],
         "sa": ["--fx", "2 kN", "--fz", "300 N"], "th": ["--fz", "3 kN", "--my", "20 N*m"]}


@pytest.fixture
def files(tmp_path):
    out = {}
    for key, body in ENTRIES.items():
        p = tmp_path / f"{key}.toml"
        p.write_text(f'[bearings."{key}"]\n{body}', encoding="utf-8")
        out[key] = p
    return out


def _json(capsys, *args):
    assert main([*args, "--json"]) == 0, capsys.readouterr().err
    return json.loads(capsys.readouterr().out)


@pytest.mark.parametrize("key", list(ENTRIES))
def test_load_distribution_of_every_type_matches_the_library(key, files, capsys):
    doc = _json(capsys, "load-distribution", "--bearing-file", str(files[key]), *LOADS[key])
    b = catalog.load_bearing_file(files[key])
    fx = 2000.0 if key != "th" else 0.0
    fz = {"qj": 1000.0, "dra": 1000.0, "sa": 300.0, "th": 3000.0}[key]
    r = combined.combined_analysis(b, [fx, 0.0, fz, 0.0, 20.0 if key == "th" else 0.0])
    assert doc["converged"] is True and doc["inputs"]["geometry"]["type"] == b.type
    assert doc["displacement_z_um"] == pytest.approx(r.displacement[2] * 1e6, rel=1e-12)
    rows = [ball["row"] for ball in doc["balls"]]
    assert len(doc["balls"]) == np.size(r.ball_load_inner) and rows == list(np.ravel(r.row))
    assert [ball["load_inner_N"] for ball in doc["balls"]] == pytest.approx(list(r.ball_load_inner), abs=1e-9)
    assert doc["axial_play_takeup_um"] == pytest.approx(combined._takeup(b) * 1e6, rel=1e-12)


def test_the_take_up_of_a_four_point_bearing(files, capsys):
    """Half its axial play: the diagonal's groove centres A sin(alpha0) apart axially and A cos(alpha0) - e/2
    radially first touch at sqrt(A^2 - (A cos(alpha0) - e/2)^2) - A sin(alpha0)."""
    doc = _json(capsys, "load-distribution", "--bearing-file", str(files["qj"]), "--fz", "1 kN")
    big_a, a, e = 0.05 * 12.7, math.radians(35), 40e-3
    play = math.sqrt(big_a**2 - (big_a * math.cos(a) - e / 2) ** 2) - big_a * math.sin(a)
    assert doc["axial_play_takeup_um"] == pytest.approx(play * 1e3, rel=1e-12)
    assert doc["inputs"]["geometry"]["axial_play_mm"] == pytest.approx(2 * play, rel=1e-12)


@pytest.mark.parametrize("key", list(ENTRIES))
def test_life_gives_the_reference_life_of_every_type(key, files, capsys):
    doc = _json(capsys, "life", "--bearing-file", str(files[key]), *LOADS[key][:4], "--speed", "3000 rpm")
    case = doc if "reference_rating_life_Mrev" in doc else doc["cases"][0]
    assert case["reference_rating_life_Mrev"] > 0 and math.isfinite(case["reference_rating_life_Mrev"])


def test_film_of_a_four_point_bearing_at_rest_loads(files, capsys):
    doc = _json(capsys, "film", "--bearing-file", str(files["qj"]), "--fx", "2 kN", "--fz", "1 kN", "--speed",
                "3000 rpm", "--oil", "VG68", "--temperature", "60 degC")
    assert any("ball loads at rest: the four-point model has no speed terms" in w for w in doc["warnings"])
    assert doc["film_min_um"] > 0


def test_film_of_a_self_aligning_bearing_at_speed(files, capsys):
    doc = _json(capsys, "film", "--bearing-file", str(files["sa"]), "--fx", "2 kN", "--speed", "3000 rpm", "--oil",
                "VG68", "--temperature", "60 degC")
    assert doc["film_min_um"] > 0


def test_bearing_set_of_double_row_bearings(files, capsys, monkeypatch):
    monkeypatch.setenv("BEARINGLAB_CATALOG", str(files["dra"]))
    doc = _json(capsys, "bearing-set", "-b", "dra", "--fx", "2 kN", "--fz", "1 kN")
    assert doc["converged"] is True and len(doc["bearings"]) == 2
    assert "row" in doc["bearings"][0]["balls"][0]


def test_the_table_shows_the_rows(files, capsys):
    assert main(["load-distribution", "--bearing-file", str(files["dra"]), "--fx", "2 kN"]) == 0
    out = capsys.readouterr().out
    assert re.search(r"┃ row ┃ ball ┃", out)  # a column of the rows before the ball's number
    assert re.search(r"│ 1 +│ +12 │", out)  # the last ball of the second row (13 a row, numbered from 0)


def test_a_thrust_bearing_refuses_a_radial_load_in_one_line(files, capsys):
    assert main(["load-distribution", "--bearing-file", str(files["th"]), "--fx", "1 kN", "--fz", "1 kN"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "carries no radial load" in err[0]


def test_the_angle_of_a_four_point_bearing_stays_with_a_clearance_given(files, capsys):
    doc = _json(capsys, "load-distribution", "--bearing-file", str(files["qj"]), "--radial-clearance", "-5 um",
                "--fx", "1 kN")
    assert doc["inputs"]["geometry"]["contact_angle_deg"] == pytest.approx(35.0)
    assert doc["preload"]["operating_clearance_um"] == pytest.approx(-5.0)


# --------------------------------------------------------------------------- the reference life itself
def _life(b, loads):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return rating_life(b, loads, 3000 * math.pi / 30)


def test_thrust_reference_life_is_iso_281_under_pure_thrust(files):
    """Z equal ball loads F_a/Z: ISO/TS 16281's Q_ci, Q_ce of thrust bearings give L10r = (C_a/F_a)^3, ISO
    281's L10, exactly."""
    b = catalog.load_bearing_file(files["th"])
    r = _life(b, [0, 0, 5000.0, 0, 0])
    assert float(r.reference_rating_life) == pytest.approx(1e6 * (46.2e3 / 5000.0) ** 3, rel=1e-12)
    assert float(r.reference_rating_life) == pytest.approx(float(r.basic_rating_life), rel=1e-12)


def test_four_point_reference_life_under_pure_thrust_is_the_angular_rows(files):
    """One diagonal carries the thrust: the life of that row of contacts, the bearing's C for it (i = 1)."""
    b = catalog.load_bearing_file(files["qj"])
    big_a = (b.inner_conformity + b.outer_conformity - 1.0) * b.ball_diameter
    free = math.acos(math.cos(b.contact_angle) - b.radial_clearance / (2 * big_a))
    ld = combined.combined_analysis(b, [0, 0, 6000.0, 0, 0], stiffness_at="free")
    q = ld.ball_load_inner[:13]
    expected = reference.reference_rating_life(q, 56e3, b.ball_diameter, b.pitch_diameter, 0.52, 0.53,
                                               b.contact_angle)
    assert float(_life(b, [0, 0, 6000.0, 0, 0]).reference_rating_life) == pytest.approx(expected, rel=1e-12)
    assert free > b.contact_angle  # the clearance opens the angle the loads run at; Q_c stays at the nominal


def test_double_row_reference_life_combines_the_rows(files):
    """Rows in series: L10r = (L_1^-10/9 + L_2^-10/9)^-9/10, each row's Q_c with the bearing's i = 2."""
    b = catalog.load_bearing_file(files["dra"])
    loads = [2000.0, 0, 1500.0, 0, 0]
    ld = combined.combined_analysis(b, loads, stiffness_at="free")
    rows = [reference.reference_rating_life(ld.ball_load_inner[ld.row == k], 48e3, b.ball_diameter, b.pitch_diameter,
                                            0.52, 0.53, b.contact_angle, n_rows=2) for k in (0, 1)]
    expected = 1e6 * ((rows[0] / 1e6) ** (-10 / 9) + (rows[1] / 1e6) ** (-10 / 9)) ** (-0.9)
    assert float(_life(b, loads).reference_rating_life) == pytest.approx(expected, rel=1e-12)


def test_two_equal_rows_reproduce_iso_281s_row_factor():
    """i equal rows, each Q_c from the bearing's C = i^0.7 C_row with i in it, in series: i^-0.9 times one
    row's life at the same per-row loads, so under a total load P (P/i a row, i^3 the life) i^2.1 = (i^0.7)^3
    times a row's life under P, ISO 281's C = i^0.7 C_row."""
    q = np.full(12, 400.0)
    single = reference.reference_rating_life(q, 30e3, 12e-3, 60e-3, 0.52, 0.53, math.radians(30))
    double = reference.rows_rating_life([reference.reference_rating_life(q, 30e3 * 2**0.7, 12e-3, 60e-3, 0.52, 0.53,
                                                                         math.radians(30), n_rows=2)] * 2)
    assert double == pytest.approx(single * 2 ** (-0.9), rel=1e-12)
    assert double * 2**3 == pytest.approx(single * 2**2.1, rel=1e-12)

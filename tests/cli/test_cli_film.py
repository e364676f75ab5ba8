"""``bearinglab film`` (issue 24): JSON keys, the numbers of the library, the lubricant and roughness
options, 80 columns, and bad inputs (exit 2, one line)."""

import json

import pytest

from bearinglab import catalog, film
from bearinglab.cli import main
from bearinglab.units import RPM

BALL_KEYS = {"load_inner_N", "load_outer_N", "contact_angle_inner_deg", "contact_angle_outer_deg",
             "film_central_inner_um", "film_min_inner_um", "film_central_outer_um", "film_min_outer_um",
             "lambda_inner", "lambda_outer"}
BASE = ["film", "-b", "B218", "--fz", "20 kN", "--fx", "5 kN", "--speed", "6000 rpm"]


def _json(capsys, *args):
    code = main([*args, "--json"])
    out = capsys.readouterr()
    assert code == 0, out.err
    return json.loads(out.out)


def test_json_has_the_keys_and_the_numbers_of_the_library(capsys):
    doc = _json(capsys, *BASE, "--dynamic-viscosity", "13 mPa*s", "--pressure-viscosity-coefficient",
                "20 1/GPa", "--roughness-ball", "0.05 um", "--roughness-race", "0.15 um")
    assert BALL_KEYS <= set(doc["balls"][0])
    assert {"film_min_um", "lambda_min", "regime", "warnings", "inputs"} <= set(doc)
    r = film.film_analysis(catalog.get("B218"), [5e3, 0, 20e3, 0, 0], 6000 * RPM, 0.013, 20e-9,
                           roughness_ball=0.05e-6, roughness_race=0.15e-6)
    assert doc["film_min_um"] == pytest.approx(r.minimum_film * 1e6, rel=1e-12)
    assert doc["lambda_min"] == pytest.approx(r.minimum_film_parameter, rel=1e-12)
    assert doc["balls"][3]["film_min_outer_um"] == pytest.approx(r.minimum_film_outer[3] * 1e6, rel=1e-12)
    assert doc["regime"] == r.regime
    assert not any("Wooster" in w or "density" in w for w in doc["warnings"])


def test_oil_grade_density_and_assumptions_are_said(capsys):
    doc = _json(capsys, *BASE, "--oil", "VG32", "--temperature", "60 degC", "--roughness", "0.1 um")
    assert doc["inputs"]["density_assumed"] is True
    assert any("density" in w for w in doc["warnings"]) and any("Wooster" in w for w in doc["warnings"])
    given = _json(capsys, *BASE, "--oil", "VG32", "--temperature", "60 degC", "--density", "870 kg/m^3")
    assert given["film_min_um"] == pytest.approx(doc["film_min_um"], rel=1e-12)
    assert not any("density" in w for w in given["warnings"])


def test_speed_list_gives_one_document_per_speed_and_films_grow_with_speed(capsys):
    docs = _json(capsys, "film", "-b", "B218", "--fz", "10 kN", "--speed", "3000, 9000 rpm", "--viscosity",
                 "20 cSt", "--density", "870 kg/m^3", "--pressure-viscosity-coefficient", "2e-8 m^2/N")
    assert len(docs) == 2 and docs[1]["film_min_um"] > docs[0]["film_min_um"]


def test_unloaded_balls_are_null(capsys):
    doc = _json(capsys, "film", "-b", "B218", "--fx", "5 kN", "--fz", "1 kN", "--speed", "3000 rpm",
                "--dynamic-viscosity", "20 cP", "--pressure-viscosity-coefficient", "20 1/GPa")
    films = [b["film_min_inner_um"] for b in doc["balls"]]
    assert any(f is None for f in films) and any(f is not None for f in films)
    assert doc["film_min_um"] == pytest.approx(min(f for f in films + [b["film_min_outer_um"]
                                                                       for b in doc["balls"]] if f is not None))


def test_table_fits_80_columns(monkeypatch):
    import io

    from rich.console import Console

    from bearinglab.cli import _common

    buf = io.StringIO()
    monkeypatch.setattr(_common, "console", Console(file=buf, width=80, force_terminal=False))
    assert main([*BASE, "--dynamic-viscosity", "13 cP", "--pressure-viscosity-coefficient", "20 1/GPa"]) == 0
    out = buf.getvalue()
    assert max(len(line) for line in out.splitlines()) <= 80
    assert "Λ_min" in out and "full film" in out


@pytest.mark.parametrize("extra, message", [
    (["--dynamic-viscosity", "-1 Pa*s"], "dynamic-viscosity must be in"),
    (["--dynamic-viscosity", "1e9 Pa*s"], "dynamic-viscosity must be in"),
    (["--viscosity", "-5 cSt"], "viscosity must be > 0"),
    (["--viscosity", "20 cSt", "--density", "-870 kg/m^3"], "density must be in"),
    (["--viscosity", "20 cSt", "--density", "87000 kg/m^3"], "density must be in"),
    (["--oil", "VG33", "--temperature", "60 degC"], "oil must be an ISO VG grade"),
    (["--dynamic-viscosity", "13 cP", "--roughness", "-0.1 um"], "roughness must be >= 0"),
    (["--dynamic-viscosity", "13 cP", "--roughness", "50 um"], "roughness must be in"),
    (["--dynamic-viscosity", "13 cP", "--roughness", "0 um"], "roughness must not be 0"),
    (["--dynamic-viscosity", "13 cP", "--pressure-viscosity-coefficient", "-2e-8 m^2/N"],
     "pressure-viscosity-coefficient must be in"),
    (["--dynamic-viscosity", "13 cP", "--loads-at", "now"], "loads-at must be one of"),
    (["--dynamic-viscosity", "13 cP", "--viscosity", "20 cSt"], "dynamic-viscosity: give"),
])
def test_bad_input_exits_2_with_one_line(capsys, extra, message):
    assert main([*BASE, *extra]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and message in err, err


def test_no_speed_is_an_error(capsys):
    assert main(["film", "-b", "B218", "--fz", "1 kN", "--viscosity", "20 cSt"]) == 2
    assert "speed" in capsys.readouterr().err




def test_temperature_auto_takes_the_steady_temperature_and_its_viscosity(capsys):
    import warnings

    import numpy as np

    from bearinglab import thermal
    from bearinglab.ratings import lubrication

    docs = _json(capsys, "film", "-b", "B218", "--fx", "3 kN", "--fz", "10 kN", "--speed", "3000, 9000 rpm",
                 "--oil", "VG32", "--viscosity-index", "100", "--temperature", "auto", "--thermal-resistance",
                 "0.05 K/W", "--skf-constants", "5e-7,1.9,0,0.013,0.7,0", "--density", "870 kg/m^3",
                 "--pressure-viscosity-coefficient", "20 1/GPa")
    from bearinglab.friction import SKFConstants  # constants of this test only, not SKF's table

    b = catalog.get("B218")
    nu100 = lubrication.viscosity_100_from_index(32e-6, 100.0)
    w = np.array([3000.0, 9000.0]) * RPM
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        t = thermal.thermal_balance(b, 3e3, 10e3, w, 293.15, 32e-6, nu100, conductance=20.0,
                                    constants=SKFConstants(5e-7, 1.9, 0.013, 0.7, 0.0, 0.0))
        r = film.film_analysis(b, [3e3, 0, 10e3, 0, 0], w, t.kinematic_viscosity * 870.0, 20e-9)
    for k in range(2):
        assert docs[k]["inputs"]["bearing_temperature_degC"] == pytest.approx(t.temperature[k] - 273.15, rel=1e-12)
        assert docs[k]["film_min_um"] == pytest.approx(r.minimum_film[k] * 1e6, rel=1e-10)
    assert docs[1]["inputs"]["bearing_temperature_degC"] > docs[0]["inputs"]["bearing_temperature_degC"]


def test_temperature_auto_needs_the_oil_grade(capsys):
    assert main([*BASE, "--viscosity", "20 cSt", "--temperature", "auto"]) == 2
    assert "oil by grade" in capsys.readouterr().err
    assert main([*BASE, "--viscosity", "20 cSt", "--ambient", "30 degC"]) == 2
    assert "go with --temperature auto" in capsys.readouterr().err


def test_lubrication_gives_the_starvation_check(capsys):
    args = ["film", "-b", "6205-2RS", "--inner-conformity", "0.52", "--outer-conformity", "0.53", "-R", "1 kN",
            "--viscosity", "68 cSt", "--density", "870 kg/m^3", "--pressure-viscosity-coefficient", "20 1/GPa"]
    fast = _json(capsys, *args, "--speed", "15000 rpm", "--lubrication", "grease")
    assert any(w.startswith("starvation risk (grease)") for w in fast["warnings"])
    assert main([*args, "--speed", "1000 rpm", "--lubrication", "splash"]) == 2
    assert "lubrication must be one of" in capsys.readouterr().err

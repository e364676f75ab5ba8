"""``bearinglab temperature`` (issue 24): the JSON of the library, the balance closes, the oil options,
runaway, 80 columns, and bad inputs (exit 2, one line)."""

import io
import json
import warnings

import pytest

from bearinglab import catalog, thermal
from bearinglab.cli import main
from bearinglab.ratings import lubrication
from bearinglab.units import RPM

KEYS = {"bearing_temperature_degC", "viscosity_mm2_s", "friction_power_W", "heat_dissipated_W", "kappa",
        "iterations", "warnings", "inputs"}
BASE = ["temperature", "-b", "6205-2RS", "-R", "1 kN", "--speed", "6000 rpm", "--oil", "VG32"]


def _json(capsys, *args):
    code = main([*args, "--json"])
    out = capsys.readouterr()
    assert code == 0, out.err
    return json.loads(out.out)


def test_json_is_the_library_and_the_balance_closes(capsys):
    doc = _json(capsys, *BASE, "--thermal-resistance", "1 K/W", "--viscosity-index", "100")
    assert KEYS <= set(doc)
    nu100 = lubrication.viscosity_100_from_index(32e-6, 100.0)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        r = thermal.thermal_balance(catalog.get("6205-2RS"), 1000.0, 0.0, 6000 * RPM, 293.15, 32e-6, nu100,
                                    conductance=1.0)
    assert doc["bearing_temperature_degC"] == pytest.approx(r.temperature - 273.15, rel=1e-12)
    assert doc["friction_power_W"] == pytest.approx(doc["heat_dissipated_W"], rel=1e-10)
    assert doc["viscosity_mm2_s"] == pytest.approx(r.kinematic_viscosity * 1e6, rel=1e-12)
    assert doc["heat_dissipated_W"] == pytest.approx(doc["bearing_temperature_degC"] - 20.0, rel=1e-9)


def test_oil_flow_cools_and_estimates_are_said(capsys):
    still = _json(capsys, *BASE)
    jet = _json(capsys, *BASE, "--oil-flow", "0.2 l/min")
    assert jet["bearing_temperature_degC"] < still["bearing_temperature_degC"]
    assert any("ISO 15312" in w for w in still["warnings"])
    assert any(w.startswith("density") for w in jet["warnings"])
    assert any(w.startswith("oil-heat-capacity") for w in jet["warnings"])


def test_runaway_is_a_warning_and_no_number(capsys):
    doc = _json(capsys, *BASE[:5], "--speed", "30000 rpm", "--oil", "VG32", "--thermal-resistance", "20 K/W",
                "--max-temperature", "100 degC")
    assert doc["bearing_temperature_degC"] is None and doc["steady"] is False
    assert any(w.startswith("thermal runaway") for w in doc["warnings"])


def test_table_fits_80_columns(monkeypatch):
    from rich.console import Console

    from bearinglab.cli import _common

    buf = io.StringIO()
    monkeypatch.setattr(_common, "console", Console(file=buf, width=80, force_terminal=False))
    assert main([*BASE[:5], "--speed", "1000, 6000, 20000 rpm", "--oil", "VG32"]) == 0
    assert max(len(line) for line in buf.getvalue().splitlines()) <= 80


@pytest.mark.parametrize("extra, message", [
    (["--oil", "VG33"], "oil must be an ISO VG grade"),
    (["--thermal-resistance", "-1 K/W"], "thermal-resistance must be in"),
    (["--oil-flow", "-1 l/min"], "oil-flow must be in"),
    (["--oil-flow", "1 l/min", "--density", "-870 kg/m^3"], "density must be in"),
    (["--oil-flow", "1 l/min", "--oil-heat-capacity", "-1 J/(kg*K)"], "oil-heat-capacity must be in"),
    (["--oil-inlet-temperature", "40 degC"], "oil-flow: --oil-inlet-temperature"),
    # issue 30: an oil bath is taken with its oil level (V_M from SKF's diagram); without it, refused
    (["--lubrication", "oil-bath"], "oil-level: --lubrication oil-bath needs the oil level"),
    (["--lubrication", "oil-bath", "--oil-level", "30 mm"], "oil-level must be <= d_m/2"),
    (["--oil-level", "5 mm"], "oil-level: --oil-level goes with --lubrication oil-bath"),
    (["--max-temperature", "10 degC"], "max-temperature must be above the ambient"),
    (["--viscosity-index", "900"], "viscosity-index must be in"),
])
def test_bad_input_exits_2_with_one_line(capsys, extra, message):
    args = [*BASE, *extra]
    if extra[0] == "--oil":
        args = [*BASE[:-2], *extra]
    assert main(args) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and message in err, err


def test_angular_contact_without_constants_is_refused_in_one_line(capsys):
    # issue 24: SKF's single-row constants cover its 40 deg bearings; a 15 deg spindle bearing is refused
    assert main(["temperature", "-b", "7008 C", "-A", "500 N", "--speed", "6000 rpm", "--oil", "VG32"]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "skf-constants" in err and "15 deg is not covered" in err
    assert main(["temperature", "-b", "B218", "-A", "5 kN", "--speed", "6000 rpm", "--oil", "VG32"]) == 0


def test_film_and_temperature_are_web_api_endpoints():
    from bearinglab import calculations
    from bearinglab.web import api

    def call(endpoint, query):
        try:
            return 200, calculations.run(calculations.parse(api.ENDPOINTS[endpoint], query))
        except calculations.RequestError as exc:
            return api.web_error(exc)

    status, doc = call("temperature", {"bearing": "6205-2RS", "radial_load": "1 kN", "speed": "6000 rpm",
                                       "oil": "VG32", "thermal_resistance": "1 K/W"})
    assert status == 200 and doc["friction_power_W"] == pytest.approx(doc["heat_dissipated_W"], rel=1e-10)
    status, doc = call("film", {"bearing": "B218", "fz": "10 kN", "speed": "6000 rpm", "viscosity": "20 cSt"})
    assert status == 200 and doc["regime"] in ("boundary", "mixed", "full film")
    status, doc = call("temperature", {"bearing": "6205-2RS", "speed": "6000 rpm", "oil": "VG33"})
    assert status == 422 and doc["parameter"] == "oil"


def test_reference_speed_option_adds_iso_15312_thermal_reference_speed(capsys):
    doc = _json(capsys, *BASE, "--reference-speed")
    r = thermal.thermal_reference_speed(catalog.get("6205-2RS"))
    assert doc["thermal_reference_speed_rpm"] == pytest.approx(r.speed / RPM, rel=1e-12)
    assert doc["reference_heat_flow_W"] == pytest.approx(r.reference_heat_flow, rel=1e-12)
    assert any("drag moment is left out" in w for w in doc["warnings"])
    assert "thermal_reference_speed_rpm" not in _json(capsys, *BASE)
    code = main([*BASE, "--reference-speed"])
    out = capsys.readouterr().out
    assert code == 0 and "Thermal reference speed (ISO 15312, SKF model): 35400 rpm" in out


def test_oil_bath_adds_the_drag_of_skfs_diagram(capsys):
    # issue 30: --lubrication oil-bath --oil-level: the balance with SKF's drag moment, V_M of its diagram at
    # H/d_m; the same as the library's balance with that oil level, and warmer than without the bath's drag
    from bearinglab.friction.drag import drag_loss_factor

    doc = _json(capsys, *BASE, "--thermal-resistance", "1 K/W", "--lubrication", "oil-bath", "--oil-level", "6 mm")
    b = catalog.get("6205-2RS")
    assert doc["inputs"]["oil_level_mm"] == pytest.approx(6.0)
    assert doc["inputs"]["drag_loss_factor"] == pytest.approx(float(drag_loss_factor(6e-3, b.mean_diameter, "ball")),
                                                             rel=1e-12)
    nu100 = lubrication.viscosity_100_from_index(32e-6, 95.0)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        r = thermal.thermal_balance(b, 1000.0, 0.0, 6000 * RPM, 293.15, 32e-6, nu100, conductance=1.0,
                                    lubrication="oil-bath", oil_level=6e-3)
        jet = thermal.thermal_balance(b, 1000.0, 0.0, 6000 * RPM, 293.15, 32e-6, nu100, conductance=1.0,
                                      lubrication="oil-jet")
    assert doc["bearing_temperature_degC"] == pytest.approx(r.temperature - 273.15, rel=1e-12)
    assert r.temperature > jet.temperature  # the same K_rs (3e-8): the difference is the bath's drag

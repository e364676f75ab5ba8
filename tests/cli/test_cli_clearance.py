"""``bearinglab clearance`` (issue 23): the JSON keys, the chain's bookkeeping, 80 columns, bad input."""

import io
import json

import pytest
from rich.console import Console

from bearinglab import internal_clearance
from bearinglab.cli import _common, main

KEYS = ["interference_inner_min_um", "interference_inner_max_um", "interference_outer_min_um",
        "interference_outer_max_um", "fit_reduction_min_um", "fit_reduction_max_um", "thermal_reduction_um",
        "centrifugal_reduction_um", "unmounted_clearance_min_um", "unmounted_clearance_max_um",
        "operating_clearance_min_um", "operating_clearance_max_um", "operating_clearance_probable_um",
        "fit_pressure_inner_MPa", "fit_pressure_outer_MPa", "warnings"]


def run(capsys, *args):
    code = main(list(args))
    out, err = capsys.readouterr()
    return code, out, err


def test_json_keys_and_the_chain_adds_up(capsys):
    code, out, err = run(capsys, "clearance", "-b", "6205-2RS", "--shaft-fit", "k5", "--housing-fit", "H7",
                         "--inner-ring-temperature", "60 degC", "--outer-ring-temperature", "50 degC",
                         "--speed", "6000 rpm", "--json")
    assert code == 0, err
    doc = json.loads(out)
    assert set(KEYS) <= set(doc)
    # 6205: k5 on 25 mm is +2/+11 um, the bore -10/0 (ISO 492 Normal); H7 on 52 mm 0/+30, the OD -13/0
    assert (doc["interference_inner_min_um"], doc["interference_inner_max_um"]) == pytest.approx((2, 21))
    assert (doc["interference_outer_min_um"], doc["interference_outer_max_um"]) == pytest.approx((-43, 0))
    lo, hi = internal_clearance.radial_clearance_range(0.025, "CN")
    assert doc["unmounted_clearance_min_um"] == pytest.approx(lo * 1e6)
    assert doc["unmounted_clearance_max_um"] == pytest.approx(hi * 1e6)
    least = doc["chain"]["least"]
    total = (least["unmounted_clearance"] - least["fit_reduction"] - least["thermal_reduction"]
             - least["centrifugal_reduction"])
    assert doc["operating_clearance_min_um"] == pytest.approx(total, rel=1e-12)
    # one steel, shaft and housing at their rings' temperatures: thermal loss alpha * 10 K * d_m
    assert doc["thermal_reduction_um"] == pytest.approx(12.5e-6 * 10 * 39.04e-3 * 1e6, rel=1e-9)
    # the inner fit at its largest interference, solid shaft of the ring's steel: 21 um * d / d_i
    assert doc["fit_reduction_max_um"] == pytest.approx(21 * 25 / (39.04 - 7.94), rel=1e-9)
    assert doc["operating_clearance_min_um"] < doc["operating_clearance_probable_um"] < doc["operating_clearance_max_um"]


def test_interferences_and_clearance_given_directly(capsys):
    code, out, err = run(capsys, "clearance", "-b", "6205-2RS", "--shaft-interference", "10 um",
                         "--housing-interference", "-5 um, 5 um", "--radial-clearance", "15 um", "--json")
    assert code == 0, err
    doc = json.loads(out)
    assert doc["unmounted_clearance_min_um"] == doc["unmounted_clearance_max_um"] == pytest.approx(15)
    assert doc["fit_reduction_min_um"] == pytest.approx(10 * 25 / 31.1, rel=1e-9)  # the outer fit at -5 um: 0


def test_negative_operating_clearance_is_allowed_with_a_warning(capsys):
    code, out, err = run(capsys, "clearance", "-b", "6205-2RS", "--shaft-fit", "p6", "--clearance-class", "C2",
                         "--json")
    assert code == 0, err
    doc = json.loads(out)
    assert doc["operating_clearance_max_um"] < 0
    assert any("preload" in w for w in doc["warnings"])


def test_monte_carlo_in_json(capsys):
    code, out, err = run(capsys, "clearance", "-b", "6205-2RS", "--shaft-fit", "k5", "--housing-fit", "K7",
                         "--monte-carlo", "2000", "--seed", "4", "--distribution", "normal", "--json")
    assert code == 0, err
    m = json.loads(out)["monte_carlo"]
    doc = json.loads(out)
    assert doc["operating_clearance_min_um"] <= m["percentiles_um"]["p0.1"] <= m["percentiles_um"]["p99.9"] \
        <= doc["operating_clearance_max_um"]
    assert 0.0 <= m["probability_negative_clearance"] <= 1.0


def test_table_fits_80_columns(capsys, monkeypatch):
    buf = io.StringIO()
    monkeypatch.setattr(_common, "console", Console(file=buf, width=80, color_system=None))
    code = main(["clearance", "-b", "6205-2RS", "--shaft-fit", "m5", "--housing-fit", "J7", "--speed", "3000 rpm",
                 "--monte-carlo", "500"])
    assert code == 0
    text = buf.getvalue()
    assert max(len(line) for line in text.splitlines()) <= 80
    assert "operating clearance" in text and "…" not in text


@pytest.mark.parametrize("args, message", [
    (["--shaft-fit", "k9"], "shaft-fit must be one of ['g6'"),
    (["--housing-fit", "Q7"], "housing-fit must be one of ['F7'"),
    (["--shaft-fit", "k5", "--shaft-bore", "25 mm"], "shaft-bore must be < the bearing bore d = 25 [mm]"),
    (["--inner-ring-temperature", "-300 degC"], "inner-ring-temperature must be >= -273.15 [degC]"),
    (["--housing-temperature", "-1 K"], "housing-temperature must be >= -273.15"),
    (["--housing-material", "wood"], "housing-material must be one of steel, "),
    (["--housing-outside-diameter", "50 mm"], "housing-outside-diameter must be > the bearing outside"),
    (["--tolerance-class", "P3"], "tolerance-class must be one of ['Normal', 'P6', 'P5', 'P4']"),
    (["--shaft-fit", "k5", "--shaft-interference", "5 um"], "give --shaft-fit or --shaft-interference"),
    (["--distribution", "beta"], "distribution must be one of uniform, normal"),
])
def test_bad_input_exits_2_naming_the_choices(capsys, args, message):
    code, _out, err = run(capsys, "clearance", "-b", "6205-2RS", *args)
    assert code == 2
    assert message in err and err.count("\n") == 1


MOUNTING = ["--shaft-fit", "k5", "--housing-fit", "J7", "--inner-ring-temperature", "40 degC",
            "--outer-ring-temperature", "30 degC"]


@pytest.mark.parametrize("command", [
    ["load-distribution", "--fx", "5 kN", "--fz", "10 kN", "--speed", "3000 rpm"],
    ["life", "--fx", "5 kN", "--fz", "10 kN", "--speed", "3000 rpm", "--viscosity", "20 cSt"],
    ["high-speed", "-F", "20 kN", "-n", "3000 rpm"],
])
def test_models_take_the_mounting_options_and_run_at_the_operating_clearance(capsys, command):
    code, out, err = run(capsys, "clearance", "-b", "B218", *MOUNTING, "--speed", "3000 rpm", "--json")
    assert code == 0, err
    probable = json.loads(out)["operating_clearance_probable_um"]
    code, out, err = run(capsys, *command, "-b", "B218", *MOUNTING, "--json")
    assert code == 0, err
    doc = json.loads(out)
    assert doc["operating_clearance_um"] == pytest.approx(probable, rel=1e-12)
    inputs = doc.get("inputs", doc)  # the model ran with it: the bearing as used is echoed
    used = inputs.get("radial_clearance_um", inputs["geometry"].get("radial_clearance_um"))
    assert used == pytest.approx(probable, rel=1e-9)
    code, out, err = run(capsys, *command, "-b", "B218", "--json")
    assert code == 0 and "operating_clearance_um" not in json.loads(out)


def test_a_preloaded_single_bearing_is_solved_as_preloaded(capsys):
    """Issue 30 item 1 (this test refused the case before): a p6 fit on a C2 bearing takes all the clearance;
    the bearing is solved preloaded, every ball loaded at zero load, and the document says so."""
    code, out, err = run(capsys, "load-distribution", "-b", "6205-2RS", "--fx", "1 kN", "--inner-conformity", "0.52",
                         "--outer-conformity", "0.53", "--contact-angle", "0 deg", "--shaft-fit", "p6",
                         "--clearance-class", "C2", "--json")
    assert code == 0, err
    doc = json.loads(out)
    e = doc["operating_clearance_um"]
    assert e < 0 and doc["inputs"]["geometry"]["radial_clearance_um"] == pytest.approx(e, rel=1e-12)
    assert doc["preload"]["operating_clearance_um"] == pytest.approx(e, rel=1e-12)
    assert doc["preload"]["interference_per_ball_um"] == pytest.approx(-e / 2, rel=1e-12)
    assert doc["preload"]["ball_load_N"] > 0 and doc["preload"]["stiffness_at_zero_load"]["k_xx_N_per_um"] > 0
    assert any(f"{e:.3g} um" in w and "preloaded" in w for w in doc["warnings"])


def _api(endpoint, query):
    """The web API's answer, computed in this process: (status, document or error body)."""
    from bearinglab import calculations
    from bearinglab.web import api

    try:
        return 200, calculations.run(calculations.parse(api.ENDPOINTS[endpoint], dict(query)))
    except calculations.RequestError as exc:
        return api.web_error(exc)


def test_web_api_runs_the_clearance_chain():
    status, doc = _api("clearance", {"bearing": "6205-2RS", "shaft_fit": "k5", "housing_fit": "H7",
                                     "inner_ring_temperature": "50 degC"})
    assert status == 200 and set(KEYS) <= set(doc)
    status, bad = _api("clearance", {"bearing": "6205-2RS", "shaft_fit": "k9"})
    assert status == 422 and "shaft_fit" in bad["detail"]

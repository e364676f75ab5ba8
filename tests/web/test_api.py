"""The JSON API (bearinglab.web): every endpoint by GET and POST, its errors in web words, its schema.

Answers must be exactly what the command line prints with ``--json``; bad input is 422 with
``{"detail", "parameter", "error"}`` naming API parameters; a 500 is a bug, searched for by fuzzing.
"""

import json
import subprocess
import sys
import urllib.parse

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from bearinglab import cli
from bearinglab.calculations import CALCULATIONS
from bearinglab.web import api

B218 = {"bearing": "B218", "axial_load": "20 kN", "speed": "10000 rpm"}
STAND = {"bearing": "4-1006095", "axial_load": "2 kgf"}
CWRU = {"bearing": "6205-2RS", "speed": "1797 rpm"}
FRICTION = {"bearing": "101", "radial_load": "10 N", "axial_load": "5 N", "speed": "3000 rpm"}
LIFE = {"bearing": "6205-2RS", "radial_load": "2 kN", "speed": "3000 rpm"}

#: endpoint, query, the command line's words for the same request
CASES = [
    ("high-speed", B218, ["high-speed", "--bearing=B218", "--axial-load=20 kN", "--speed=10000 rpm"]),
    ("high-speed", {**B218, "axial_load": "10kN; 20kN", "speed": "0 rpm; 1e4 rpm"},
     ["high-speed", "--bearing=B218", "--axial-load=10kN; 20kN", "--speed=0 rpm; 1e4 rpm"]),
    ("axial-angle", {**STAND, "legacy": "true"},
     ["axial-angle", "--bearing=4-1006095", "--axial-load=2 kgf", "--legacy"]),
    ("stand-load", {"bearing": "4-1006095", "speed": "1000, 3000 rpm"},
     ["stand-load", "--bearing=4-1006095", "--speed=1000, 3000 rpm"]),
    ("frequencies", {**CWRU, "mask": "true", "harmonics": "2"},
     ["frequencies", "--bearing=6205-2RS", "--speed=1797 rpm", "--mask", "--harmonics=2"]),
    ("friction", FRICTION, ["friction", "torque", "--bearing=101", "--radial-load=10 N",
                            "--axial-load=5 N", "--speed=3000 rpm"]),
    ("friction", {**FRICTION, "model": "palmgren", "viscosity": "20 cSt", "palmgren_f0": "1.5"},
     ["friction", "torque", "--bearing=101", "--radial-load=10 N", "--axial-load=5 N",
      "--speed=3000 rpm", "--model=palmgren", "--viscosity=20 cSt", "--palmgren-f0=1.5"]),
    ("friction", {"bearing": "6205-2RS", "radial_load": "100 N", "speed": "3000 rpm", "model": "skf",
                  "viscosity": "30 cSt", "lubrication": "oil-air"},
     ["friction", "torque", "--bearing=6205-2RS", "--radial-load=100 N", "--speed=3000 rpm",
      "--model=skf", "--viscosity=30 cSt", "--lubrication=oil-air"]),
    ("life", {**LIFE, "oil": "VG68", "temperature": "70 degC", "contamination": "normal"},
     ["life", "--bearing=6205-2RS", "--radial-load=2 kN", "--speed=3000 rpm", "--oil=VG68",
      "--temperature=70 degC", "--contamination=normal"]),
    ("load-distribution", {"bearing": "B218", "fx": "10 kN", "fz": "5 kN", "mx": "100 N*m"},
     ["load-distribution", "--bearing=B218", "--fx=10 kN", "--fz=5 kN", "--mx=100 N*m"]),
    ("bearing-set", {"bearing": "7218B, 7218B", "arrangement": "DB", "preload": "1 kN", "fy": "2 kN",
                     "spacing": "100 mm"},
     ["bearing-set", "--bearing=7218B", "--bearing=7218B", "--arrangement=DB", "--preload=1 kN",
      "--fy=2 kN", "--spacing=100 mm"]),
    ("catalog", {"name": "B218"}, ["catalog", "show", "B218"]),
    ("catalog", {"name": "6208-2RS1/C3", "clearance": "min"},
     ["catalog", "show", "6208-2RS1/C3", "--clearance=min"]),
    ("clearance", {"bearing": "6205-2RS", "shaft_fit": "k5", "housing_fit": "H7",
                   "inner_ring_temperature": "50 degC"},
     ["clearance", "--bearing=6205-2RS", "--shaft-fit=k5", "--housing-fit=H7",
      "--inner-ring-temperature=50 degC"]),
    ("film", {"bearing": "B218", "fz": "10 kN", "speed": "6000 rpm", "viscosity": "20 cSt"},
     ["film", "--bearing=B218", "--fz=10 kN", "--speed=6000 rpm", "--viscosity=20 cSt"]),
    ("temperature", {"bearing": "6205-2RS", "radial_load": "1 kN", "speed": "6000 rpm", "oil": "VG32"},
     ["temperature", "--bearing=6205-2RS", "--radial-load=1 kN", "--speed=6000 rpm", "--oil=VG32"]),
]


@pytest.mark.parametrize("endpoint, query, words", CASES, ids=[c[0] for c in CASES])
def test_get_and_post_answer_what_the_command_line_prints(client, endpoint, query, words):
    printed = cli.run_json(words)
    assert printed.exit_code == 0, printed.error
    got = client.get(f"/api/{endpoint}", params=query)
    assert got.status_code == 200, got.text
    assert got.headers["content-type"].startswith("application/json")
    assert got.json() == printed.document
    posted = client.post(f"/api/{endpoint}", json=query)
    assert posted.status_code == 200 and posted.json() == printed.document


def test_todays_documented_url_keeps_working(client):
    r = client.get("/api/high-speed?bearing=B218&axial_load=20%20kN&speed=10000%20rpm&constants=harris")
    doc = r.json()
    assert r.status_code == 200
    assert doc["contact_angle_inner_deg"] == pytest.approx(49.308, abs=5e-4)  # spec 004 section 7.1
    assert doc["contact_angle_outer_deg"] == pytest.approx(32.514, abs=5e-4)


def test_post_takes_numbers_and_flags_as_json(client):
    r = client.post("/api/frequencies", json={**CWRU, "harmonics": 2, "mask": True})
    assert r.status_code == 200 and r.json()["mask"]


def test_catalog_search(client):
    r = client.get("/api/catalog/search", params={"bore": "25 mm", "outside_diameter": "52 mm"})
    assert r.status_code == 200
    names = [m["name"] for m in r.json()["matches"]]
    assert names[0] == "6205-2RS" and "6205" in names  # the named bearing, then the standard series
    bearings = r.json()["bearings"]  # `catalog search --json` (tests/calculations/test_documents.py)
    assert "6205" in [b["name"] for b in bearings]
    assert all((b["bore_mm"], b["outside_diameter_mm"]) == (25, 52) for b in bearings)
    r = client.post("/api/catalog/search", json={"query": "B2"})
    assert "B218" in [m["name"] for m in r.json()["matches"]]


def test_runout_takes_the_error_set_posted_as_text(client):
    from pathlib import Path

    text = (Path(__file__).resolve().parents[2] / "examples" / "runout" /
            "example1_oversize_ball.toml").read_text(encoding="utf-8")
    r = client.post("/api/runout", json={"errors": text, "angle": "30 deg"})
    assert r.status_code == 200, r.text
    assert r.json()["errors_file"] == "(posted document)"
    r = client.post("/api/runout", json={"errors": "/etc/passwd"})
    assert r.status_code == 422 and r.json()["parameter"] == "errors"


@pytest.mark.parametrize("query, parameter, words", [
    ({**B218, "axial_load": "2,5 kN"}, "axial_load", "ambiguous"),
    ({**B218, "axial_load": "1.2.3 kN"}, "axial_load", "malformed number"),
    ({**B218, "axial_load": "2 m"}, "axial_load", "is a length"),
    ({**B218, "speed": "fast"}, "speed", "cannot read 'fast'"),
    ({**B218, "colour": "red"}, "colour", "not an input of high-speed"),
    ({"bearing": "B218", "speed": "1 rpm"}, "axial_load", "axial_load: missing"),
    ({**B218, "axial_load": "1N:1e9N:1N"}, "axial_load", "more than the limit"),
    ({**B218, "csv": "/tmp/x.csv"}, "csv", "not an input"),
    ({**B218, "bearing_file": "/etc/passwd"}, "bearing_file", "not an input"),
])
def test_bad_input_is_422_in_web_words(client, query, parameter, words):
    for r in (client.get("/api/high-speed", params=query), client.post("/api/high-speed", json=query)):
        assert r.status_code == 422, r.text
        body = r.json()
        assert set(body) == {"detail", "parameter", "error"}
        assert body["parameter"] == parameter and words in body["detail"]
        assert "--" not in body["detail"] and "Traceback" not in r.text


def test_a_repeated_parameter_is_422_not_its_last_value(client):
    r = client.get("/api/high-speed?bearing=B218&axial_load=1kN&axial_load=2kN&speed=1rpm")
    assert r.status_code == 422 and r.json()["parameter"] == "axial_load"
    assert "more than once" in r.json()["detail"]


@pytest.mark.parametrize("endpoint, query, parameter", [
    ("axial-angle", {**STAND, "rows": "1000000000"}, "rows"),
    ("frequencies", {**CWRU, "harmonics": "100000000"}, "harmonics"),
    ("high-speed", {**B218, "axial_load": "1kN:1000kN:1kN", "speed": "0rpm:1000rpm:1rpm"}, "axial_load"),
])
def test_sizes_over_the_limits_are_422_before_any_work(client, endpoint, query, parameter):
    r = client.get(f"/api/{endpoint}", params=query)
    assert r.status_code == 422 and r.json()["parameter"] == parameter


def test_a_failure_of_the_calculation_names_parameters_not_options(client):
    r = client.get("/api/life", params={**LIFE, "contamination": "normal", "contamination_factor": "0.5"})
    assert r.status_code == 422
    assert r.json() == {"detail": "contamination: give contamination_factor or contamination, not both",
                        "parameter": "contamination", "error": "input"}


def test_a_body_that_is_not_an_object_or_too_large(client):
    assert client.post("/api/life", content=b"[1, 2]").status_code == 422
    assert client.post("/api/life", content=b"{not json").json()["detail"].startswith("the body is not JSON")
    assert client.post("/api/life", json={"speed": {"deep": 1}}).json()["parameter"] == "speed"
    r = client.post("/api/life", content=b" " * (2 << 20), headers={"content-type": "application/json"})
    assert r.status_code == 413 and r.json()["error"] == "limit"


def test_unknown_endpoint_is_404(client):
    r = client.get("/api/warp-drive")
    assert r.status_code == 404 and "/api/high-speed" in r.json()["detail"]


def test_openapi_documents_every_endpoint_and_field_with_unit_and_range(client):
    spec = client.get("/openapi.json").json()
    from bearinglab.calculations import CASE_LIMIT

    assert f"{CASE_LIMIT} cases" in spec["info"]["description"] and "120 s" in spec["info"]["description"]
    for path, name in api.ENDPOINTS.items():
        ops = spec["paths"][f"/api/{path}"]
        assert set(ops) == {"get", "post"}
        params = {p["name"]: p for p in ops["get"]["parameters"]}
        body = ops["post"]["requestBody"]["content"]["application/json"]["schema"]["properties"]
        for f in CALCULATIONS[name].fields:
            assert f.help in params[f.name]["description"] and f.help in body[f.name]["description"]
            if f.unit and f.unit != "-":
                assert f"[{f.unit}]" in params[f.name]["description"]
                assert body[f.name]["x-unit"] == f.unit
            if f.minimum is not None or f.maximum is not None:
                assert f"Valid: {f.valid()}." in params[f.name]["description"]
    assert client.get("/docs").status_code == 200


def test_the_web_package_does_not_import_the_command_line():
    code = ("import sys, bearinglab.web.app, bearinglab.web.page; "
            "print(sorted(m for m in sys.modules if m.startswith('bearinglab.cli')))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "[]"


_TEXT = st.one_of(
    st.text(max_size=25),
    st.from_regex(r"-?[0-9.eE+]{1,10} ?(kN|N|rpm|mm|um|deg|cSt|GPa|kgf|%)?([:;,][0-9.e]{1,6}){0,2}",
                  fullmatch=True),
    st.sampled_from(["nan", "inf", "-0", "1e308 N", "1e-308 N", "0:1e9:1", "true", "B218", ""]),
)


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(endpoint=st.sampled_from(sorted(api.ENDPOINTS)), data=st.data())
def test_fuzz_no_answer_is_a_500(client, endpoint, data):
    """Any parameter values: 200, 404 or 422 (or 503 for the limits), never a 500."""
    fields = [f.name for f in CALCULATIONS[api.ENDPOINTS[endpoint]].fields if f.kind != "document"]
    names = data.draw(st.lists(st.sampled_from([*fields, "bogus"]), max_size=4, unique=True))
    query = {n: data.draw(_TEXT) for n in names}
    if "bearing" in fields and "bearing" not in query:
        query["bearing"] = "B218"
    r = client.get(f"/api/{endpoint}?" + urllib.parse.urlencode(query))
    assert r.status_code in (200, 404, 422, 503), (query, r.text)
    if r.status_code != 200:
        assert set(r.json()) == {"detail", "parameter", "error"}
    else:
        json.loads(r.text)

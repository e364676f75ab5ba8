"""Roller bearings on the JSON API and the page (issue 32 item 7): the endpoints follow from the registry, answer what
the command line prints, and refuse a bad roller input with 422 naming the parameter in web words."""

import pytest

from bearinglab import calculations
from bearinglab.cli import run_json

LOAD = {"bearing": "NU 208 ECP", "fx": "10 kN", "radial_clearance": "20 um", "slices": "30"}


def test_load_distribution_of_a_roller_bearing_is_what_the_command_prints(client):
    printed = run_json(["load-distribution", "--bearing=NU 208 ECP", "--fx=10 kN", "--radial-clearance=20 um"])
    assert printed.exit_code == 0, printed.error
    for r in (client.get("/api/load-distribution", params=LOAD), client.post("/api/load-distribution", json=LOAD)):
        assert r.status_code == 200, r.text
        doc = r.json()
        assert doc["rollers"] == printed.document["rollers"]
        assert doc["stiffness_matrix"] == printed.document["stiffness_matrix"]
        assert doc["max_roller_load_N"] == max(x["load_N"] for x in doc["rollers"])


@pytest.mark.parametrize("endpoint, query, key", [
    ("life", {"bearing": "30208 J2/Q", "fx": "10 kN", "fz": "4 kN", "speed": "1000 rpm", "viscosity": "30 cSt",
              "tilt_y": "1 mrad"}, "reference_rating_life_Mrev"),
    ("film", {"bearing": "NU 208 ECP", "fx": "10 kN", "speed": "1500 rpm", "viscosity": "20 cSt"}, "lambda_min"),
    ("friction", {"bearing": "22208 E", "model": "skf", "radial_load": "2990 N", "axial_load": "100 N",
                  "speed": "3500 rpm", "viscosity": "68 cSt"}, "total_moment_Nmm"),
    ("frequencies", {"bearing": "NU 208 ECP", "speed": "1500 rpm"}, "bpfo_hz"),
    ("temperature", {"bearing": "NU 208 ECP", "radial_load": "5 kN", "speed": "3000 rpm", "oil": "VG68"},
     "bearing_temperature_degC"),
    ("clearance", {"bearing": "NU 208 ECP", "shaft_fit": "m5", "radial_clearance": "25 um, 50 um"},
     "operating_clearance_probable_um"),
    ("bearing-set", {"bearing": "30208 J2/Q, 30208 J2/Q", "spacing": "135 mm", "preload": "2 kN", "fx": "8 kN",
                     "induced_axial_factor": "NSK"}, "iso281"),
])
def test_every_roller_endpoint_answers_the_calculation(client, endpoint, query, key):
    r = client.get(f"/api/{endpoint}", params=query)
    assert r.status_code == 200, r.text
    doc = r.json()
    assert doc[key] is not None
    assert doc == calculations.run(calculations.parse(endpoint, query))


#: endpoint, query, the parameter at fault, words of the detail (web words: no option spelled with dashes)
FAILURES = [
    ("load-distribution", {**LOAD, "roller_length": "20 mm"}, "roller_length",
     "roller_length must be <= the ring width 18 mm"),
    ("load-distribution", {**LOAD, "crown_drop": "-3 um"}, "crown_drop", "crown_drop must be"),
    ("life", {"bearing": "30208 J2/Q", "fx": "10 kN", "fz": "4 kN", "speed": "1000 rpm", "contact_angle": "50 deg"},
     "contact_angle", "contact_angle must be in (0, 45] [deg] for a tapered roller bearing"),
    ("load-distribution", {**LOAD, "balls": "12"}, "balls", "balls: 'NU 208 ECP' is a cylindrical roller bearing"),
    ("load-distribution", {"bearing": "6208", "fx": "1 kN", "rollers": "12"}, "rollers",
     "rollers: '6208' is a ball bearing; rollers is an input of roller bearings"),
    ("high-speed", {"bearing": "NU 208 ECP", "axial_load": "5 kN", "speed": "3000 rpm"}, "bearing",
     "is a cylindrical roller bearing: the high-speed model"),
    ("axial-angle", {"bearing": "30208 J2/Q", "axial_load": "5 kN"}, "bearing", "is a tapered roller bearing"),
    ("film", {"bearing": "22208 E", "fx": "1 kN", "speed": "1000 rpm", "viscosity": "20 cSt"}, "bearing",
     "spherical roller bearings have ratings, life (ISO 281) and friction only"),
    ("bearing-set", {"bearing": "30208 J2/Q", "fx": "1 kN"}, "spacing", "a tapered pair needs the distance"),
]


@pytest.mark.parametrize("endpoint, query, parameter, words", FAILURES,
                         ids=[f"{e}-{i}" for i, (e, *_rest) in enumerate(FAILURES)])
def test_a_bad_roller_input_is_422_naming_the_parameter(client, endpoint, query, parameter, words):
    r = client.get(f"/api/{endpoint}", params=query)
    assert r.status_code == 422, r.text
    body = r.json()
    assert body["parameter"] == parameter and words in body["detail"], body
    if endpoint not in ("high-speed", "axial-angle"):  # the ball models keep the command line's words
        assert "--" not in body["detail"]


def test_the_picker_finds_roller_bearings(client):
    r = client.get("/api/catalog/search", params={"query": "208", "limit": "50"})
    names = {m["name"]: m for m in r.json()["matches"]}
    assert {"NU 208 ECP", "30208 J2/Q", "22208 E"} <= set(names)
    assert names["30208 J2/Q"]["type"] == "tapered" and names["NU 208 ECP"]["bore_mm"] == 40.0
    r = client.get("/api/catalog/search", params={"bore": "40 mm", "outside_diameter": "90 mm"})
    assert "NU 308 ECP" in {m["name"] for m in r.json()["matches"]}
    r = client.get("/api/catalog/search", params={"query": "NU 2"})
    assert {m["name"] for m in r.json()["matches"]} >= {"NU 208 ECP", "NU 2208 ECP"}


def test_the_page_shows_the_rollers_and_leaves_out_the_ball_models(client):
    r = client.get("/", params={"bearing": "NU 208 ECP", "fx": "10 kN", "speed": "1500 rpm", "viscosity": "20 cSt",
                                "radial_clearance": "20 um", "model": "skf"})
    assert r.status_code == 200
    page = r.text
    assert 'id="rollers-load-distribution-1"' in page and 'id="rollers-film-1"' in page
    load = page.split('id="section-load-distribution"')[1].split("</article>")[0]
    assert "<svg" in load and "Rollers (14, 30 slices each" in load
    high = page.split('id="section-high-speed"')[1].split("</article>")[0]
    assert "left-out-high-speed" in high and "a model of ball bearings" in high
    friction = page.split('id="section-friction"')[1].split("</article>")[0]
    assert "total moment" in friction
    assert "Traceback" not in page and 'class="error"' not in page


def test_the_page_with_a_tapered_bearing_its_pair_and_a_thrust(client):
    r = client.get("/", params={"bearing": "30208 J2/Q", "fx": "8 kN", "axial_load": "3 kN", "speed": "1000 rpm",
                                "viscosity": "30 cSt", "arrangement": "DB", "preload": "2 kN", "spacing": "135 mm"})
    page = r.text
    assert r.status_code == 200 and 'class="error"' not in page  # the thrust is no error of the frequencies
    freq = page.split('id="section-frequencies"')[1].split("</article>")[0]
    assert "Left out" not in freq and "BPFO" in freq.upper()
    pair = page.split('id="section-bearing-set"')[1].split("</article>")[0]
    assert 'id="rollers-bearing-set-3"' in pair and "ISO 281&#39;s method" in pair  # A, B and ISO 281's table
    clearance = client.get("/", params={"bearing": "30208 J2/Q", "shaft_fit": "m5"}).text
    assert "its play is set by adjusting it against the other bearing" in clearance

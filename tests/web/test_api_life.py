"""The API of the native rating life, load distribution and bearing set (issue 22 item 1): errors in web
words naming the parameter, and the life's duty cycle posted as a document (TOML or JSON text)."""

import json

import pytest

from bearinglab import cli

DUTY = ('[[step]]\nfx = "1 kN"\nfz = "3 kN"\nspeed = "1000 rpm"\ntime = 0.5\n\n'
        '[[step]]\nfx = "2 kN"\nfz = "3 kN"\nspeed = "3000 rpm"\ntime = 0.5\n')


@pytest.mark.parametrize("text", [DUTY, json.dumps({"step": [
    {"fx": "1 kN", "fz": "3 kN", "speed": "1000 rpm", "time": 0.5},
    {"fx": "2 kN", "fz": "3 kN", "speed": "3000 rpm", "time": 0.5}]})], ids=["toml", "json"])
def test_life_takes_a_duty_cycle_posted_as_toml_or_json(client, tmp_path, text):
    path = tmp_path / "duty.toml"
    path.write_text(DUTY, encoding="utf-8")
    printed = cli.run_json(["life", "--bearing=B218", "--viscosity=20 cSt", f"--duty-cycle={path}"])
    assert printed.exit_code == 0, printed.error
    r = client.post("/api/life", json={"bearing": "B218", "viscosity": "20 cSt", "duty_cycle": text})
    assert r.status_code == 200, r.text
    assert r.json() == printed.document
    assert len(r.json()["steps"]) == 2


def test_a_duty_cycle_is_never_a_path(client, tmp_path):
    path = tmp_path / "duty.toml"
    path.write_text(DUTY, encoding="utf-8")
    r = client.post("/api/life", json={"bearing": "B218", "viscosity": "20 cSt", "duty_cycle": str(path)})
    assert r.status_code == 422 and r.json()["parameter"] == "duty_cycle"
    assert str(path) not in r.json()["detail"] or "the posted document" in r.json()["detail"]


@pytest.mark.parametrize("endpoint, query, parameter, words", [
    ("life", {"bearing": "6205-2RS", "radial_load": "2 kN"}, "speed", "speed: missing"),
    ("life", {"bearing": "6205-2RS", "radial_load": "2 kN", "speed": "1 rpm", "oil": "VG8",
              "temperature": "40 degC"}, "oil", "oil must be an ISO VG grade"),
    ("life", {"bearing": "B218", "viscosity": "20 cSt",
              "duty_cycle": "[[step]]\nfz = '1 kN'\nspeed = '3000 rpm'\ntime = 2\n"},
     "duty_cycle", "duty_cycle step 1 time must be a share in [0, 1]"),
    ("load-distribution", {"bearing": "B218", "fz": "1 kN", "dz": "5 um"}, "dz", "dz: give fz or dz, not both"),
    ("load-distribution", {"bearing": "B218", "fz": "1 kN", "speed": "1e7 rpm"}, "speed", "speed must be <= "),
    ("bearing-set", {"bearing": "7218B", "preload": "1 kN", "preload_offset": "5 um"}, "preload",
     "preload: give preload or preload_offset, not both"),
    ("bearing-set", {"bearing": "7218B, 7208 BE", "preload": "1 kN", "shaft_fit": "k5"}, "bearing",
     "the mounting options need one bearing type"),
])
def test_native_failures_are_422_in_web_words(client, endpoint, query, parameter, words):
    for r in (client.get(f"/api/{endpoint}", params=query), client.post(f"/api/{endpoint}", json=query)):
        assert r.status_code == 422, r.text
        body = r.json()
        assert body["parameter"] == parameter and words in body["detail"], body
        assert "--" not in body["detail"] and body["error"] == "input"


def test_life_takes_temperature_auto(client):
    query = {"bearing": "6205-2RS", "radial_load": "1 kN", "speed": "6000 rpm", "oil": "VG32",
             "temperature": "auto", "thermal_resistance": "1 K/W", "lubrication": "oil-air"}
    printed = cli.run_json(["life", "--bearing=6205-2RS", "--radial-load=1 kN", "--speed=6000 rpm", "--oil=VG32",
                            "--temperature=auto", "--thermal-resistance=1 K/W", "--lubrication=oil-air"])
    assert printed.exit_code == 0, printed.error
    r = client.get("/api/life", params=query)
    assert r.status_code == 200, r.text
    assert r.json() == printed.document and r.json()["bearing_temperature_degC"] > 20
    r = client.post("/api/life", json={**query, "lubrication": "oil-bath"})
    assert r.status_code == 422 and r.json()["parameter"] == "lubrication"

"""The API's failures of the native calculations (frequencies, stand-load, axial-angle, high-speed) are
422 naming the API parameter, in web words (no command-line option)."""

import pytest

CASES = [
    ("frequencies", {"bearing": "6205-2RS", "speed": "100 rpm", "outer_speed": "100 rpm"}, "speed",
     "the rings must turn relative to each other"),
    ("stand-load", {"bearing": "4-1006095", "speed": "-5 rpm"}, "speed", "must be >= 0 [rpm]"),
    ("axial-angle", {"bearing": "NOPE-1", "axial_load": "2 kgf"}, "bearing", "NOPE-1"),
    ("high-speed", {"bearing": "B218", "axial_load": "20 kN", "speed": "1 rpm", "shaft_fit": "zz9"},
     "shaft_fit", "must be one of"),
]


@pytest.mark.parametrize("endpoint, query, parameter, words", CASES, ids=[c[0] for c in CASES])
def test_a_failure_of_the_calculation_is_422_naming_the_parameter(client, endpoint, query, parameter, words):
    for r in (client.get(f"/api/{endpoint}", params=query), client.post(f"/api/{endpoint}", json=query)):
        assert r.status_code == 422, r.text
        body = r.json()
        assert body["parameter"] == parameter and body["error"] == "input", body
        assert words in body["detail"] and "--" not in body["detail"], body


def test_a_friction_failure_is_422_naming_the_parameter(client):
    query = {"bearing": "101", "radial_load": "10 N", "model": "two-term"}
    r = client.get("/api/friction", params=query)
    assert r.status_code == 422, r.text
    assert r.json()["parameter"] == "f0" and r.json()["detail"].startswith("f0: the two-term model needs")

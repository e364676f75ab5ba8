"""The native calculations on the API (issue 22): a bad input is 422 naming the field in web words."""

import pytest

#: endpoint, query, the parameter at fault, words of the detail
FAILURES = [
    ("clearance", {"bearing": "6205-2RS", "shaft_fit": "k5", "shaft_interference": "5 um"},
     "shaft_interference", "give shaft_fit or shaft_interference"),
    ("clearance", {"bearing": "6205-2RS", "monte_carlo": "1"}, "monte_carlo", "monte_carlo must be"),
    ("film", {"bearing": "6208", "radial_load": "1 kN", "speed": "6000 rpm", "oil": "VG33",
              "temperature": "60 degC"}, "oil", "oil must be an ISO VG grade"),
    ("film", {"bearing": "6208", "radial_load": "1 kN", "speed": "6000 rpm", "viscosity": "20 cSt",
              "ambient": "30 degC"}, "temperature", "ambient, thermal_resistance and skf_constants go with"),
    ("temperature", {"bearing": "6208", "radial_load": "1 kN", "speed": "6000 rpm", "oil": "VG32",
                     "oil_heat_capacity": "2000 J/(kg*K)"}, "oil_flow", "give oil_flow"),
    ("temperature", {"bearing": "6208", "speed": "6000 rpm", "oil": "VG32",
                     "lubrication": "oil-bath"}, "oil_level", "needs the oil level"),  # issue 30: with its level
]


@pytest.mark.parametrize("endpoint, query, parameter, words", FAILURES,
                         ids=[f"{e}-{i}" for i, (e, *_rest) in enumerate(FAILURES)])
def test_a_bad_input_is_422_naming_the_field(client, endpoint, query, parameter, words):
    for r in (client.get(f"/api/{endpoint}", params=query), client.post(f"/api/{endpoint}", json=query)):
        assert r.status_code == 422, r.text
        body = r.json()
        assert body["parameter"] == parameter and words in body["detail"], body
        assert "--" not in body["detail"]


MC = {"bearing": "7218B", "samples": "4", "steps_per_rev": "12", "revolutions": "1", "seed": "3"}


def test_runout_monte_carlo_answers_get_and_post_what_the_command_prints(client):
    from bearinglab import cli

    printed = cli.run_json(["runout", "monte-carlo", "--bearing=7218B", "--samples=4", "--steps-per-rev=12",
                            "--revolutions=1", "--seed=3"])
    assert printed.exit_code == 0, printed.error
    by_get = client.get("/api/runout-monte-carlo", params=MC)
    by_post = client.post("/api/runout-monte-carlo",
                          json={**MC, "samples": 4, "steps_per_rev": 12, "revolutions": 1, "seed": 3})
    assert by_get.status_code == 200 and by_post.status_code == 200, (by_get.text, by_post.text)
    assert by_get.json() == printed.document and by_post.json() == printed.document
    assert by_get.content == client.get("/api/runout-monte-carlo", params=MC).content  # bit-identical


def test_runout_monte_carlo_over_the_case_limit_is_422_naming_samples(client):
    from bearinglab.calculations import CASE_LIMIT

    r = client.get("/api/runout-monte-carlo", params={**MC, "samples": str(CASE_LIMIT + 1)})
    assert r.status_code == 422 and r.json()["parameter"] == "samples", r.text
    assert "more than the limit" in r.json()["detail"]
    r = client.post("/api/runout-monte-carlo", json={**MC, "samples": 1})
    assert r.status_code == 422 and r.json()["parameter"] == "samples"
    r = client.get("/api/runout-monte-carlo", params={"samples": "4"})  # no bearing: no geometry
    assert r.status_code == 422 and r.json()["parameter"] == "bearing" and "--" not in r.json()["detail"]


def test_runout_monte_carlo_is_in_the_openapi_schema(client):
    spec = client.get("/openapi.json").json()
    ops = spec["paths"]["/api/runout-monte-carlo"]
    assert set(ops) == {"get", "post"}
    assert {p["name"] for p in ops["get"]["parameters"]} >= {"bearing", "samples", "seed", "ball_grade",
                                                              "ring_class"}

"""Issue 29, item 5: the web answers hostile requests with 422 and one line, never 500.

The findings: JSON nested 1000 deep; TOML nested 1000 deep in a posted ``errors`` (runout) or
``duty_cycle`` (life) document; a POST body that repeats a key (the last value was kept); the page ``/``
with a list or range of thrust or speed (a jinja UndefinedError); a range whose count overflows. Then the
load: a request's weight is estimated from its parsed size before it is sent to a pool (a duty cycle of
many steps goes to the heavy pool), and the heavy workers run at a lower OS priority.
"""

import json
import os
import re

import pytest

from bearinglab import _bounds, calculations

DEEP = 1000


def one_line_422(r):
    assert r.status_code == 422, r.text
    body = r.json()
    assert set(body) == {"detail", "parameter", "error"}
    assert "\n" not in body["detail"] and "Traceback" not in body["detail"]
    return body


def _post(client, path, body):
    return client.post(path, content=body, headers={"content-type": "application/json"})


# ----------------------------------------------------------------------------- deep JSON bodies
@pytest.mark.parametrize("body", [
    '{"bearing": ' + "[" * DEEP + "]" * DEEP + "}",  # arrays
    '{"a": ' + '{"a": ' * DEEP + "1" + "}" * DEEP + "}",  # objects
    "[" * 100_000 + "]" * 100_000,  # far deeper than Python's recursion
    '{"bearing": ' + "[" * 40 + "]" * 40 + "}",  # just past the depth bound, under the recursion limit
], ids=["arrays-1000", "objects-1000", "arrays-100000", "arrays-40"])
def test_a_deeply_nested_json_body_is_422(client, body):
    out = one_line_422(_post(client, "/api/frequencies", body))
    assert out["error"] == "input"


# ----------------------------------------------------------------------------- repeated keys
@pytest.mark.parametrize("body, name", [
    ('{"bearing": "6205-2RS", "speed": "1797 rpm", "speed": "3000 rpm"}', "speed"),
    ('{"bearing": "6205-2RS", "speed": "1797 rpm", "speed": "1797 rpm"}', "speed"),  # the same value twice
    ('{"bearing": "6205-2RS", "bearing": "6205-2RS", "speed": "1797 rpm"}', "bearing"),
    ('{"nope": 1, "nope": 2}', "nope"),  # an unknown key, twice: the repetition is named first
])
def test_a_post_body_that_repeats_a_key_is_422_naming_it(client, body, name):
    out = one_line_422(_post(client, "/api/frequencies", body))
    assert out["parameter"] == name and out["detail"].startswith(f"{name}: given more than once")


def test_a_query_that_repeats_a_key_is_still_422(client):
    r = client.get("/api/frequencies?bearing=6205-2RS&speed=1797%20rpm&speed=3000%20rpm")
    assert one_line_422(r)["parameter"] == "speed"


def test_a_posted_json_document_that_repeats_a_key_is_422(client):
    cycle = '{"step": [{"fx": "1 kN", "speed": "1000 rpm", "time": 1}], "step": []}'
    out = one_line_422(client.post("/api/life", json={"bearing": "6208", "duty_cycle": cycle}))
    assert out["parameter"] == "duty_cycle" and "'step' given more than once" in out["detail"]


# ----------------------------------------------------------------------------- deep TOML and JSON documents
DEEP_DOCUMENTS = {
    "toml-arrays": "a = " + "[" * DEEP + "]" * DEEP,
    "toml-inline-tables": "a = " + "{b = " * DEEP + "1" + "}" * DEEP,
    "toml-dotted-keys": ".".join(["a"] * DEEP) + " = 1",  # read without recursion: the depth bound refuses it
    "toml-tables": "[" + ".".join(["t"] * DEEP) + "]\nx = 1",
    "json-arrays": '{"a": ' + "[" * DEEP + "]" * DEEP + "}",
    "json-objects": '{"a": ' + '{"a": ' * DEEP + "1" + "}" * DEEP + "}",
}


@pytest.mark.parametrize("kind", sorted(DEEP_DOCUMENTS))
@pytest.mark.parametrize("path, field, extra", [
    ("/api/runout", "errors", {}),
    ("/api/life", "duty_cycle", {"bearing": "6208"}),
])
def test_a_deeply_nested_document_is_422(client, kind, path, field, extra):
    out = one_line_422(client.post(path, json={**extra, field: DEEP_DOCUMENTS[kind]}))
    assert out["parameter"] == field
    assert f"nested more than {_bounds.MAX_DEPTH} levels deep" in out["detail"]


def test_a_deeply_nested_document_in_a_query_is_422(client):
    r = client.get("/api/runout", params={"errors": DEEP_DOCUMENTS["toml-arrays"]})
    assert one_line_422(r)["parameter"] == "errors"


def test_a_document_at_the_depth_bound_is_read():
    doc = _bounds.parse_document("a = " + "[" * (_bounds.MAX_DEPTH - 1) + "]" * (_bounds.MAX_DEPTH - 1))
    assert isinstance(doc["a"], list)
    with pytest.raises(_bounds.InputError, match="nested more than 32"):
        _bounds.parse_document("a = " + "[" * _bounds.MAX_DEPTH + "]" * _bounds.MAX_DEPTH)


# ----------------------------------------------------------------------------- a count that overflows
@pytest.mark.parametrize("method", ["get", "post"])
def test_a_range_whose_count_overflows_is_422(client, method):
    values = {"bearing": "B218", "axial_load": "0 kN:1e300 kN:1e-300 kN", "speed": "3000 rpm"}
    r = client.get("/api/high-speed", params=values) if method == "get" else client.post("/api/high-speed",
                                                                                        json=values)
    one_line_422(r)


# ----------------------------------------------------------------------------- the page with lists and ranges
def _section(html, key):
    m = re.search(rf'<article class="card section([^"]*)" id="section-{key}">(.*?)</article>', html, re.DOTALL)
    assert m, key
    return m.group(1).strip(), m.group(2)


@pytest.mark.parametrize("query, field, count", [
    ({"bearing": "B218", "axial_load": "1 kN, 2 kN", "speed": "3000 rpm"}, "Axial load", 2),
    ({"bearing": "B218", "axial_load": "1kN:3kN:1kN", "speed": "3000 rpm"}, "Axial load", 3),
    ({"bearing": "B218", "axial_load": "2 kN", "speed": "1000 rpm, 3000 rpm"}, "Shaft speed", 2),
    ({"bearing": "B218", "axial_load": "2 kN", "speed": "1000rpm:3000rpm:1000rpm"}, "Shaft speed", 3),
])
def test_the_page_shows_a_table_of_the_cases_of_a_list_or_range(client, query, field, count):
    r = client.get("/", params=query)
    assert r.status_code == 200, r.text[-2000:]
    note = re.search(r'<p class="note" id="lists-note">(.*?)</p>', r.text, re.DOTALL)
    assert note and f"{field}" in note.group(1) and f"holds {count} values" in note.group(1)
    css, body = _section(r.text, "high-speed")
    assert css == "" and f"cases ({count} rows)" in body  # the high-speed map of the cases given
    # every numbered row is a case of the list, as the API computes it
    doc = client.get("/api/high-speed", params=query).json()
    assert len(doc["cases"]) == count
    css, body = _section(r.text, "life")
    if field == "Axial load":  # takes one load: left out, saying why
        assert css == "left-out" and "takes one value of" in body and "not a list or range" in body
    else:  # issue 30: life takes a speed list like film, one row per speed
        assert css == "" and f"cases ({count} rows" in body


def test_the_page_shows_a_list_document_as_a_table_of_cases(client):
    query = {"bearing": "6208", "radial_load": "1 kN", "speed": "1000rpm:3000rpm:1000rpm", "oil": "VG68",
             "temperature": "70 degC"}
    r = client.get("/", params=query)
    assert r.status_code == 200
    css, body = _section(r.text, "film")
    assert css == "" and "cases (3 rows, one per value of the list or range)" in body
    table = re.search(r'<table class="rows" id="cases-film">(.*?)</table>', body, re.DOTALL).group(1)
    assert table.count("<tr>") == 4  # the header and three cases
    assert "speed [rpm]" in body  # the input that differs between the cases comes first


def test_the_page_shows_the_first_rows_of_a_long_table_and_says_so(client):
    from bearinglab.web.page import PAGE_ROWS

    n = PAGE_ROWS + 20
    r = client.get("/", params={"bearing": "4-1006095", "axial_load": f"1N:{n}N:1N"})
    assert r.status_code == 200
    _css, body = _section(r.text, "axial-angle")
    assert f"cases ({n} rows; the first {PAGE_ROWS} shown" in body
    table = re.search(r'<table class="rows"[^>]*>(.*?)</table>', body, re.DOTALL).group(1)
    assert table.count("<tr>") == PAGE_ROWS + 1  # the header and the first rows


# ----------------------------------------------------------------------------- duty cycles: the step limit
def _cycle_toml(steps):
    share = 1 / steps
    return "".join(f'[[step]]\nfx = "1 kN"\nspeed = "1000 rpm"\ntime = {share!r}\n' for _ in range(steps))


def _cycle_json(steps):
    return json.dumps({"step": [{"fx": "1 kN", "speed": "1000 rpm", "time": 1 / steps}] * steps})


@pytest.mark.parametrize("form", ["toml", "json"])
def test_a_duty_cycle_over_the_step_limit_is_422(client, form):
    steps = _bounds.MAX_DUTY_CYCLE_STEPS + 1
    # the shortest steps (their shares do not sum to 1: the count is refused before any step is read)
    text = ('[[step]]\nspeed="1rpm"\ntime=0\n' * steps if form == "toml"
            else json.dumps({"step": [{"speed": "1rpm", "time": 0}] * steps}, separators=(",", ":")))
    assert len(text) <= calculations.DOCUMENT_LIMIT  # the step limit refuses it, not the length
    out = one_line_422(client.post("/api/life", json={"bearing": "6208", "duty_cycle": text}))
    assert out["parameter"] == "duty_cycle"
    assert f"{steps} steps, more than the limit of {_bounds.MAX_DUTY_CYCLE_STEPS} steps" in out["detail"]


def test_a_short_duty_cycle_is_answered_on_the_web(client):
    r = client.post("/api/life", json={"bearing": "6208", "duty_cycle": _cycle_toml(3), "viscosity": "20 cSt"})
    assert r.status_code == 200 and len(r.json()["steps"]) == 3


# ----------------------------------------------------------------------------- weight and pools
def test_the_weight_of_a_request_comes_from_its_parsed_size():
    single = calculations.parse("life", {"bearing": "6208", "radial_load": "1 kN", "speed": "1000 rpm"})
    assert single.weight == 1 and not single.heavy
    few = calculations.parse("life", {"bearing": "6208", "duty_cycle": _cycle_toml(3)})
    assert few.weight == 3 and not few.heavy
    many = calculations.parse("life", {"bearing": "6208", "duty_cycle": _cycle_toml(8000)})
    assert many.weight == 8000 and many.heavy  # issue 29: an 8000-step duty cycle held a light worker
    as_json = calculations.parse("life", {"bearing": "6208", "duty_cycle": _cycle_json(200)})
    assert as_json.weight == 200 and as_json.heavy
    lists = calculations.parse("high-speed", {"bearing": "B218", "axial_load": "1kN:10kN:1kN", "speed": "1 rpm"})
    assert lists.weight == 10 and lists.heavy
    mask = calculations.parse("frequencies", {"bearing": "6205-2RS", "speed": "1797 rpm", "harmonics": "100",
                                              "sidebands": "50"})
    assert mask.weight == 100 * 101 and mask.heavy
    study = calculations.parse("runout-monte-carlo", {"bearing": "B218", "samples": "5000"})
    assert study.weight == 5000 and study.heavy


def test_a_heavy_duty_cycle_runs_in_the_heavy_pool(client, monkeypatch):
    server = client.app.state.server
    seen = []
    for name in ("light", "heavy"):
        pool = getattr(server, name)
        original = pool.call

        async def call(task, *, budget, gone=None, _original=original, _name=name):
            seen.append((_name, task[1]))
            return await _original(task, budget=budget, gone=gone)

        monkeypatch.setattr(pool, "call", call)
    cycle = _cycle_toml(calculations.LIGHT_WEIGHT + 1)
    assert client.post("/api/life", json={"bearing": "6208", "duty_cycle": cycle}).status_code == 200
    assert client.post("/api/life", json={"bearing": "6208", "duty_cycle": _cycle_toml(2)}).status_code == 200
    assert seen == [("heavy", "life"), ("light", "life")]


@pytest.mark.skipif(not hasattr(os, "getpriority"), reason="POSIX priorities")
def test_heavy_workers_run_at_a_lower_priority(client):
    from bearinglab.web.workers import HEAVY_NICENESS

    server = client.app.state.server
    client.get("/api/frequencies", params={"bearing": "6205-2RS", "speed": "1797 rpm"})  # the pools are up
    base = os.getpriority(os.PRIO_PROCESS, 0)
    heavy = [os.getpriority(os.PRIO_PROCESS, pid) for pid in server.heavy.pids()]
    light = [os.getpriority(os.PRIO_PROCESS, pid) for pid in server.light.pids()]
    assert heavy and light
    assert set(light) == {base}
    assert set(heavy) == {min(19, base + HEAVY_NICENESS)}

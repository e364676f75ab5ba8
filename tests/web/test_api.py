"""The web calculator's JSON API and page (bearinglab.web), through FastAPI's TestClient.

The API must answer with exactly what the command line prints with ``--json``; bad input is HTTP 422
with the one-line message and the parameter it names; the page shows results and field messages and
never a traceback.
"""

import json

import pytest
from fastapi.testclient import TestClient

from bearinglab import cli
from bearinglab.web import api, create_app


@pytest.fixture(scope="module")
def client():
    return TestClient(create_app())


def _cli_json(capsys, *argv):
    code = cli.main([*argv, "--json"])
    out, err = capsys.readouterr()
    assert code == 0, err
    return out


def _argv(words, query, flags=()):
    """The command line of a query: ``axial_load`` -> ``--axial-load VALUE``; flags as they are."""
    return [*words, *(x for k, v in query.items() for x in (f"--{k.replace('_', '-')}", v)), *flags]


B218 = {"bearing": "B218", "axial_load": "20 kN", "speed": "10000 rpm"}
STAND = {"bearing": "4-1006095", "axial_load": "2 kgf"}
CWRU = {"bearing": "6205-2RS", "speed": "1797 rpm"}
INLINE = {
    "balls": "9",
    "ball_diameter": "7.94 mm",
    "pitch_diameter": "39.04 mm",
    "contact_angle": "0 deg",
}
FRICTION = {"bearing": "101", "radial_load": "10 N", "axial_load": "5 N", "speed": "3000 rpm"}
LIFE = {"bearing": "6205-2RS", "radial_load": "2 kN", "speed": "3000 rpm"}


@pytest.mark.parametrize(
    "endpoint, words, query, flags",
    [
        ("high-speed", ["high-speed"], B218, {}),
        ("high-speed", ["high-speed"], {**B218, "constants": "harris"}, {}),
        (
            "high-speed",
            ["high-speed"],
            {**B218, "axial_load": "10kN; 20kN", "speed": "0 rpm; 1e4 rpm"},
            {},
        ),
        ("axial-angle", ["axial-angle"], STAND, {}),
        ("axial-angle", ["axial-angle"], STAND, {"legacy": "true"}),
        ("frequencies", ["frequencies"], CWRU, {}),
        ("frequencies", ["frequencies"], {**CWRU, "harmonics": "2"}, {"mask": "true"}),
        ("frequencies", ["frequencies"], {**INLINE, "speed": "1797 rpm"}, {}),
        ("friction", ["friction", "torque"], FRICTION, {}),
        # issue 20: life without a lubricant, and with an oil grade and temperature only
        ("life", ["life"], LIFE, {}),
        ("life", ["life"], {**LIFE, "oil": "VG68", "temperature": "70 degC"}, {}),
    ],
)
def test_api_answers_what_the_cli_prints(client, capsys, endpoint, words, query, flags):
    r = client.get(f"/api/{endpoint}", params={**query, **flags})
    assert r.status_code == 200, r.text
    assert r.headers["content-type"].startswith("application/json")
    assert r.text == _cli_json(capsys, *_argv(words, query, [f"--{k}" for k in flags]))


def test_api_high_speed_reproduces_the_published_angles(client):
    # spec 004 section 7.1 (Harris's constants): 20 kN at 10 000 rpm -> 49.308 / 32.514 deg, 3 decimals printed
    r = client.get(
        "/api/high-speed",
        params={
            "bearing": "B218",
            "axial_load": "20 kN",
            "speed": "10000 rpm",
            "constants": "harris",
        },
    )
    doc = r.json()
    assert doc["contact_angle_inner_deg"] == pytest.approx(49.308, abs=5e-4)
    assert doc["contact_angle_outer_deg"] == pytest.approx(32.514, abs=5e-4)


@pytest.mark.parametrize(
    "query, parameter, words",
    [
        (
            {"bearing": "B218", "axial_load": "2,5 kN", "speed": "10000 rpm"},
            "axial_load",
            "ambiguous",
        ),
        ({"bearing": "B218", "axial_load": "20 m", "speed": "10000 rpm"}, "axial_load", "force"),
        ({"bearing": "B218", "axial_load": "-5 kN", "speed": "10000 rpm"}, "axial_load", "> 0"),
        ({"bearing": "B218", "axial_load": "20 kN", "speed": "fast"}, "speed", "speed"),
        ({"axial_load": "20 kN", "speed": "10000 rpm"}, "bearing", "bearing"),
        ({"bearing": "NOPE", "axial_load": "20 kN", "speed": "10000 rpm"}, "bearing", "NOPE"),
        ({"bearing": "B218", "speed": "10000 rpm"}, "axial_load", "'axial_load'"),
        (
            {"bearing": "B218", "axial_load": "20 kN", "speed": "10000 rpm", "colour": "red"},
            "colour",
            "unknown",
        ),
        (
            {"bearing": "B218", "axial_load": "20 kN", "speed": "1 rpm", "solver": "magic"},
            "solver",
            "solver",
        ),
    ],
)
def test_api_bad_input_is_422_naming_the_parameter(client, query, parameter, words):
    r = client.get("/api/high-speed", params=query)
    assert r.status_code == 422
    body = r.json()
    assert body["parameter"] == parameter and body["error"] == "input"
    assert words in body["detail"] and "Traceback" not in r.text


@pytest.mark.parametrize(
    "option", ["csv", "plot", "bearing_file", "catalog", "executor", "workers", "json"]
)
def test_api_reaches_no_file_or_cluster_option(client, option):
    r = client.get(
        "/api/high-speed",
        params={"bearing": "B218", "axial_load": "20 kN", "speed": "1 rpm", option: "/tmp/x.csv"},
    )
    assert r.status_code == 422 and r.json()["parameter"] == option


def test_api_flag_takes_true_or_false(client):
    r = client.get(
        "/api/axial-angle",
        params={"bearing": "4-1006095", "axial_load": "2 kgf", "legacy": "maybe"},
    )
    assert r.status_code == 422 and r.json()["parameter"] == "legacy"


def test_api_unknown_endpoint_is_404(client):
    r = client.get("/api/warp-drive", params={"bearing": "B218"})
    assert r.status_code == 404 and "high-speed" in r.json()["detail"]


@pytest.mark.parametrize("endpoint", ["load-distribution", "life", "friction"])
def test_api_endpoints_of_newer_commands_reject_unknown_parameters(client, endpoint):
    # 422 when the command exists (the parameter is named), 404 in a version without it
    r = client.get(f"/api/{endpoint}", params={"bearing": "B218", "colour": "red"})
    assert r.status_code in (404, 422)
    if r.status_code == 422:
        assert r.json()["parameter"] == "colour"
    else:
        assert not api.options(endpoint)  # only a command this version lacks answers 404


def _spelled(endpoint):
    """Each spelling of each option the endpoint's command defines, read here from click's own params."""
    command = api._command(api.ENDPOINTS[endpoint])
    return {o for p in command.params for o in (*p.opts, *p.secondary_opts)}


@pytest.mark.parametrize(
    "endpoint, query, parameter, detail",
    [
        # click: a missing option (both spellings, '--axial-load' / '-F')
        ("axial-angle", {"bearing": "4-1006095"}, "axial_load", "Missing parameter 'axial_load'."),
        (
            "high-speed",
            {"bearing": "B218", "speed": "1 rpm"},
            "axial_load",
            "Missing parameter 'axial_load'.",
        ),
        # click: a value of the wrong type
        (
            "friction",
            {**FRICTION, "model": "two-term", "f0": "abc"},
            "f0",
            "Invalid value for 'f0': ",
        ),
        (
            "frequencies",
            {**INLINE, "balls": "x", "speed": "1 rpm"},
            "balls",
            "Invalid value for 'balls': ",
        ),
        # the command's own message, opening with the option's name
        (
            "axial-angle",
            {**STAND, "axial_load": "2 m"},
            "axial_load",
            "axial_load: '2 m' is a length",
        ),
        # a library message that names options inside the sentence
        (
            "life",
            {"bearing": "6205-2RS", "radial_load": "1 kN", "speed": "1000 rpm", "oil": "VG68",
             "viscosity_index": "95", "viscosity_100": "8 cSt", "temperature": "70 degC"},
            "viscosity_index",
            "viscosity_index: give viscosity_index or viscosity_100, not both",
        ),
    ],
)
def test_api_messages_name_query_parameters_not_options(client, endpoint, query, parameter, detail):
    r = client.get(f"/api/{endpoint}", params=query)
    if not api.options(endpoint):
        pytest.skip(f"{endpoint}: not in this version")
    assert r.status_code == 422, r.text
    body = r.json()
    assert body["parameter"] == parameter and body["error"] == "input"
    assert body["detail"].startswith(detail)
    # no spelling of any of the command's options is left in the message
    words = set(body["detail"].replace("'", " ").replace(",", " ").split())
    assert not words & _spelled(endpoint), body["detail"]


def test_web_message_translates_only_what_the_command_defines():
    # spellings come from the command: '-F' is axial-angle's short option, '-Z' and --bearing-file are
    # not web parameters (no such option; a file option) and stay as the command line says them
    assert api.web_message("Missing option '-F' / '--axial-load'.", "axial-angle") == (
        "Missing parameter 'axial_load'."
    )
    assert api.web_message("give --bearing or --bearing-file", "axial-angle") == (
        "give bearing or --bearing-file"
    )
    assert (
        api.web_message("Invalid value for '-Z': bad", "axial-angle")
        == "Invalid value for '-Z': bad"
    )
    assert (
        api.web_message("ball-diameter must be > 0 [m]", "axial-angle")
        == "ball_diameter must be > 0 [m]"
    )
    assert api.web_message("a load of -5 kN --no option here", "axial-angle") == (
        "a load of -5 kN --no option here"
    )


def test_parameter_of_reads_the_cli_messages():
    assert api.parameter_of("axial-load: '2,5 kN' is ambiguous") == "axial_load"
    assert api.parameter_of("speed must be >= 0 [rpm]") == "speed"
    assert api.parameter_of("Missing option '--axial-load' / '-F'.") == "axial_load"
    assert api.parameter_of("Invalid value for '--balls': 'x' is not a valid integer.") == "balls"
    assert api.parameter_of("speed: bad", known={"bearing"}) is None
    assert api.parameter_of("the solve did not converge") is None


# ----------------------------------------------------------------------------- the page
def test_page_has_the_form_and_the_catalog(client):
    r = client.get("/")
    assert r.status_code == 200
    for name in (
        "B218",
        "6205-2RS",
        'name="axial_load"',
        'name="speed"',
        'name="viscosity"',
        'name="radial_load"',
    ):
        assert name in r.text
    assert 'id="results"' not in r.text  # nothing computed before the form is sent


def test_page_shows_the_contact_angles(client):
    r = client.get("/", params={"bearing": "B218", "axial_load": "20 kN", "speed": "10000 rpm", "constants": "harris"})
    assert r.status_code == 200
    # with Harris's constants: the published 49.308 / 32.514 deg (spec 004 section 7.1)
    assert '<span class="value" id="contact-angle-inner">49.308°</span>' in r.text
    assert '<span class="value" id="contact-angle-outer">32.514°</span>' in r.text
    assert 'id="section-frequencies"' in r.text and "<svg" in r.text  # the library's high-speed map


def test_page_constants_select_changes_the_model(client, capsys):
    r = client.get(
        "/",
        params={
            "bearing": "B218",
            "axial_load": "20 kN",
            "speed": "10000 rpm",
            "constants": "mass",
        },
    )
    doc = json.loads(
        _cli_json(capsys, "high-speed", "-b", "B218", "-F", "20 kN", "-n", "10000 rpm")
    )
    assert f'id="contact-angle-inner">{doc["contact_angle_inner_deg"]:.3f}°<' in r.text


@pytest.mark.parametrize(
    "field, value, words",
    [
        ("axial_load", "2,5 kN", "ambiguous"),
        ("axial_load", "20 m", "force"),
        ("speed", "20 kN", "speed"),
        ("ball_diameter", "big", "ball_diameter: cannot read"),
        ("axial_load", "", "Missing parameter &#39;axial_load&#39;."),  # the field's name, not -F
    ],
)
def test_page_shows_a_bad_field_message_next_to_it(client, field, value, words):
    query = {"bearing": "B218", "axial_load": "20 kN", "speed": "10000 rpm", field: value}
    r = client.get("/", params=query)
    assert r.status_code == 200
    start = r.text.index(f'<p class="error" id="error-{field}">')
    message = r.text[start : r.text.index("</p>", start)]
    assert words in message and "--" not in message
    assert "Traceback" not in r.text and 'File "' not in r.text


def test_page_without_a_bearing_names_the_bearing_field(client):
    r = client.get("/", params={"bearing": "", "axial_load": "20 kN", "speed": "10000 rpm"})
    assert 'id="error-bearing"' in r.text and "Traceback" not in r.text


def test_api_life_without_lubricant(client):
    # issue 20: the basic lives need no lubricant; a_ISO, L_nm and L_nmr are null
    r = client.get("/api/life", params=LIFE)
    assert r.status_code == 200, r.text
    doc = r.json()
    assert doc["basic_rating_life_Mrev"] == pytest.approx((14.8 / 2.0) ** 3, rel=1e-12)
    for key in ("viscosity_mm2_s", "viscosity_ratio", "life_modification_factor", "modified_rating_life_Mrev",
                "modified_reference_rating_life_Mrev"):
        assert doc[key] is None, key

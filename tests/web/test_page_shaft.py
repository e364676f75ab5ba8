"""The shaft section of the page without a browser (issue 33 item 5): the editor reads a file back into its
tables and other lines without losing a key, the page computes the section from its own fields, and its
errors name the shaft, never the form's friction model."""

import json
import re
import tomllib
from pathlib import Path

import pytest

from bearinglab.web import shaft as web_shaft

EXAMPLES = Path(__file__).resolve().parents[2] / "examples" / "shaft"

KEYED = """\
speed = "3000 rpm"
housing_material = "aluminium"

[material]
elastic_modulus = "210 GPa"
poisson_ratio = 0.3
density = "7850 kg/m^3"

[[sections]]
length = "300 mm"
diameter = "30 mm"
start = "0 mm"

[[supports]]
name = "A"
position = "20 mm"
bearing = "7206 B"
orientation = "-z"
axial = true
housing = { radial_stiffness = "500 N/um", tilt_stiffness = "1e5 N*m/rad" }

[[supports]]
name = "B"
position = "280 mm"
bearing_set = { bearing = "7206 B", arrangement = "DF", spacing = "20 mm", preload_offset = "5 um" }
axial = false

[[supports]]
name = "C"
position = "150 mm"
radial_stiffness = "200 N/um"
tilt_stiffness = "1e4 N*m/rad"

[[supports]]
name = "D"
position = "100 mm"
rigid = true

[[loads]]
position = "150 mm"
fy = "-2 kN"
mz = "0 N*m"

[[pulleys]]
name = "belt"
position = "0 mm"
force = "1 kN"
direction = "30 deg"

[bearings."MY-7206"]
type = "angular"
balls = 13
"""


def _composed(editor):
    """The file the editor's tables and other lines make, by the rules stated in web/shaft.py (written
    here apart from static/shaft.js, which the browser tests check)."""
    parts = [editor["other"].strip()] if editor["other"].strip() else []
    for name, (_title, columns) in web_shaft.TABLES.items():
        for row in editor["tables"][name]:
            lines = [f"[[{name}]]"]
            if name == "supports":
                for key in ("name", "position"):
                    if row[key]:
                        lines.append(f"{key} = {json.dumps(row[key])}")
                kind = row["kind"]
                if kind == "bearing" and row["value"]:
                    lines.append(f"bearing = {json.dumps(row['value'])}")
                if kind == "set":
                    for key, cell in (("bearing", "value"), ("arrangement", "arrangement"), ("preload", "preload")):
                        if row[cell]:
                            lines.append(f"bearing_set.{key} = {json.dumps(row[cell])}")
                if kind == "linear" and row["value"]:
                    lines.append(f"radial_stiffness = {json.dumps(row['value'])}")
                if kind == "rigid":
                    lines.append("rigid = true")
                lines.append(f"axial = {'true' if row['axial'] else 'false'}")
            else:
                lines += [f"{key} = {json.dumps(row[key])}" for key, _l, _e in columns if row[key]]
            if row["more"]:
                lines.append(row["more"])
            parts.append("\n".join(lines))
    return "\n\n".join(parts) + "\n"


def _explicit(doc):
    for sup in doc.get("supports", []):
        sup.setdefault("axial", "bearing_set" in sup)
    return doc


@pytest.mark.parametrize("text", [(EXAMPLES / "spindle.toml").read_text(encoding="utf-8"),
                                  (EXAMPLES / "gearbox.toml").read_text(encoding="utf-8"), KEYED],
                         ids=["spindle", "gearbox", "every-kind"])
def test_the_editor_keeps_every_key_of_the_file(text):
    editor = web_shaft.editor(text)
    assert editor["error"] == ""
    assert tomllib.loads(_composed(editor)) == _explicit(tomllib.loads(text))


def test_the_editor_shows_what_has_a_column_and_keeps_the_rest_in_the_rows():
    e = web_shaft.editor(KEYED)
    a, b, c, d = e["tables"]["supports"]
    assert (a["kind"], a["value"], a["axial"]) == ("bearing", "7206 B", True)
    assert a["more"].splitlines() == ['orientation = "-z"', 'housing.radial_stiffness = "500 N/um"',
                                      'housing.tilt_stiffness = "1e5 N*m/rad"']
    assert (b["kind"], b["value"], b["arrangement"], b["preload"], b["axial"]) == ("set", "7206 B", "DF", "", False)
    assert b["more"].splitlines() == ['bearing_set.spacing = "20 mm"', 'bearing_set.preload_offset = "5 um"']
    assert (c["kind"], c["value"], c["more"]) == ("linear", "200 N/um", 'tilt_stiffness = "1e4 N*m/rad"')
    assert (d["kind"], d["value"], d["more"], d["axial"]) == ("rigid", "", "", False)
    assert e["tables"]["sections"][0]["more"] == 'start = "0 mm"'
    assert e["tables"]["loads"][0] == {"name": "", "position": "150 mm", "fx": "", "fy": "-2 kN", "fz": "", "mx": "",
                                       "my": "", "more": 'mz = "0 N*m"'}
    assert e["other"].startswith('speed = "3000 rpm"\nhousing_material = "aluminium"\n\n[material]\n')
    assert "[bearings.MY-7206]" in e["other"] and "[[pulleys]]" in e["other"]


@pytest.mark.parametrize("text, why", [("x = ", "not a TOML or JSON document"),
                                       ('sections = "none"', "not arrays of tables")])
def test_a_file_the_tables_cannot_show_stays_as_typed(text, why):
    e = web_shaft.editor(text)
    assert why in e["error"] and e["other"] == text
    assert not any(e["tables"].values())


def test_the_section_takes_its_own_fields_and_is_left_out_without_a_shaft():
    values = {"shaft": "x", "shaft_stiffness_at": "0 mm", "shaft_modes": "", "speed": "3000 rpm", "model": "skf"}
    assert web_shaft.query(values) == {"model": "x", "stiffness_at": "0 mm"}  # not the form's speed nor model
    assert web_shaft.left_out(values) == ""
    assert web_shaft.left_out({"speed": "3000 rpm"}).startswith("Left out: no shaft system given")


def test_the_page_computes_the_shaft_and_names_its_errors_as_the_shaft(client):
    text = (EXAMPLES / "gearbox.toml").read_text(encoding="utf-8")
    html = client.get("/", params={"shaft": text, "shaft_modes": "1"}).text
    section = html[html.index('id="section-shaft"'):]
    doc = client.post("/api/shaft", json={"model": text, "modes": "1"}).json()
    from bearinglab.web import page

    assert f">{page.number(doc['system_life_h'])}<" in section
    assert section.count('id="shaft-result-supports"') == 1 and 'id="shaft-figure"' in section
    bad = text.replace('position = "240 mm"', 'position = "300 mm"')
    html = client.get("/", params={"shaft": bad, "model": "one-term"}).text
    message = re.search(r'id="message-shaft">([^<]*)<', html).group(1)
    assert message == "Shaft system: supports[1].position: B at 300 mm lies outside the shaft (0 ... 260 mm)"
    assert 'id="error-model"' not in html  # the friction model's field is not marked
    assert 'id="error-shaft"' in html


def test_the_api_takes_the_document_as_toml_or_json_text_and_names_the_field(client):
    text = (EXAMPLES / "spindle.toml").read_text(encoding="utf-8")
    as_toml = client.post("/api/shaft", json={"model": text}).json()
    as_json = client.post("/api/shaft", json={"model": json.dumps(tomllib.loads(text))}).json()
    by_get = client.get("/api/shaft", params={"model": text}).json()
    assert as_toml == as_json == by_get and as_toml["system_life_h"] > 0
    cases = [({"model": text.replace('"330 mm"', '"500 mm"')}, "model",
              "model: supports[1].position: rear at 500 mm lies outside the shaft (0 ... 400 mm)"),
             ({"model": "x ="}, "model", "model: document: not valid TOML"),
             ({}, "model", "model: missing; the shaft system"),
             ({"model": text, "modes": "99"}, "modes", "modes must be 0 ... 50, got 99"),
             ({"model": text, "stiffness_at": "900 mm"}, "stiffness_at",
              "stiffness_at: position 900 mm lies outside the shaft (0 ... 400 mm)")]
    for body, parameter, detail in cases:
        r = client.post("/api/shaft", json=body)
        assert r.status_code == 422, body
        assert r.json()["parameter"] == parameter and r.json()["detail"].startswith(detail), r.json()

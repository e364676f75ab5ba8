"""How the calculator page shows numbers and warnings (bearinglab.web.page and the template).

The page rounds what it shows (6 significant digits, float noise next to a larger value of the same
unit as 0); the JSON API keeps every digit. Plausibility warnings of a result are shown with it.
"""

import csv
import io
import json
import re

import pytest

from bearinglab import __version__
from bearinglab.web import page


@pytest.mark.parametrize(
    "value, scale, shown",
    [
        (3000.0000000000005, 0.0, "3000"),  # a unit round trip (issue 15 item 17)
        (12449.999999999998, 0.0, "12450"),
        (0.30000000000000004, 0.0, "0.3"),
        (41.60864009873454, 0.0, "41.6086"),
        (3.454265239433013e-14, 696.35, "0"),  # the off-axis displacement of a symmetric load
        (-5.9e-16, 1.45, "0"),
        (-0.0, 0.0, "0"),
        (2.4e-5, 0.0, "2.4 × 10⁻⁵"),  # small but alone in its unit: a value, not noise
        (9.9e-16, 0.0, "9.9 × 10⁻¹⁶"),  # a residual (dimensionless, never treated as noise)
        (1.0e-3, 696.35, "0.001"),  # 1e-6 of the largest: kept
        (31344565.185519597, 0.0, "3.13446 × 10⁷"),
        (525094035.88305444, 0.0, "5.25094 × 10⁸"),
        (11, 0.0, "11"),
        (True, 0.0, "yes"),
        (None, 0.0, "—"),
        ("41°36'31.11\"", 0.0, "41°36'31.11\""),
    ],
)
def test_number(value, scale, shown):
    assert page.number(value, scale) == shown


def test_scales_group_values_by_unit():
    doc = {"displacement_x_um": 83.6, "displacement_y_um": -3e-14, "displacement_z_um": 696.3,
           "tilt_x_mrad": -5.9e-16, "tilt_y_mrad": 1.45, "residual": 1e-15, "converged": True}
    assert page.scales(doc) == {"displacement_x_um": 696.3, "displacement_y_um": 696.3,
                                "displacement_z_um": 696.3, "tilt_x_mrad": 1.45, "tilt_y_mrad": 1.45,
                                "residual": 0.0, "converged": 0.0}
    assert page.column_scales([{"a_N": 1.0, "b": "x"}, {"a_N": -7.0, "b": "y"}]) == {"a_N": 7.0, "b": 0.0}
    assert page.column_scales([]) == {}


@pytest.mark.parametrize(
    "key, label, unit",
    [
        ("tilt_x_mrad", "tilt x", "mrad"),
        ("basic_rating_life_Mrev", "basic rating life", "10⁶ rev"),
        ("power_loss_W", "power loss", "W"),
        ("curvature_sum_inner_per_mm", "curvature sum inner", "1/mm"),
        ("axial_stiffness_N_per_um", "axial stiffness", "N/µm"),
        ("first_approximation_rad", "first approximation", "rad"),
        ("bpfo_hz", "bpfo", "Hz"),
        ("viscosity_ratio", "viscosity ratio", ""),
    ],
)
def test_every_unit_suffix_of_the_json_is_a_unit_on_the_page(key, label, unit):
    assert page.quantity(key) == (label, unit)


def _cells(html):
    """The text of every table cell and headline value of the page (figures left out)."""
    html = re.sub(r"<svg.*?</svg>", "", html, flags=re.DOTALL)
    return re.findall(r'<(?:td|span class="value[^"]*")[^>]*>([^<]*)<', html)


def _significant_digits(cell):
    """Significant digits of a plain decimal number cell (0 for anything else)."""
    match = re.fullmatch(r"-?(\d+(?:\.\d*)?)(?: × 10\S+)?°?", cell.strip())
    return len(match.group(1).replace(".", "").lstrip("0")) if match else 0


COMBINED = {"bearing": "B218", "axial_load": "20 kN", "radial_load": "3 kN", "speed": "3000 rpm",
            "viscosity": "20 cSt"}


def test_page_rounds_while_the_api_keeps_full_precision(client):
    api = client.get("/api/load-distribution", params={k: v for k, v in COMBINED.items() if k != "viscosity"})
    doc = api.json()
    # the JSON API keeps every digit, the noise too: it is what --json prints
    assert 0 < abs(doc["displacement_y_um"]) < 1e-9 and len(repr(doc["displacement_z_um"])) > 10
    html = client.get("/", params=COMBINED).text
    cells = _cells(html)
    assert cells, "no values on the page"
    noisy = [c for c in cells if re.search(r"\de[-+]", c) or _significant_digits(c) > 6]
    assert not noisy, noisy  # never more than 6 significant digits, never 1e-14 style
    start = html.index("<th>displacement y</th>")
    assert html[start:].startswith('<th>displacement y</th><td class="num">0</td>')
    z = doc["displacement_z_um"]
    assert f'<td class="num">{z:.6g}</td>' in html


def test_page_shows_the_plausibility_warnings(client):
    query = {"bearing": "B218", "axial_load": "1e9 N", "speed": "3000 rpm"}
    html = client.get("/", params=query).text
    api = client.get("/api/high-speed", params=query).json()
    assert api["warnings"]
    start = html.index('<ul class="warnings" id="warnings-high-speed">')
    shown = html[start : html.index("</ul>", start)]
    for note in api["warnings"]:
        assert json.dumps(note)[1:-1].replace("'", "&#39;").replace("<", "&lt;") in shown
    assert "4200 MPa" in shown and "runs over the shoulder" in shown


def test_page_without_warnings_has_no_warning_list(client):
    html = client.get("/", params={"bearing": "B218", "axial_load": "20 kN", "speed": "0 rpm"}).text
    assert 'id="warnings-high-speed"' not in html


def _section(html, key):
    start = html.index(f'id="section-{key}"')
    return html[start:html.index("</article>", start)]


def test_a_radial_only_case_leaves_out_the_thrust_sections_with_one_line(client):
    html = client.get("/", params={"bearing": "B218", "radial_load": "2 kN", "speed": "1797 rpm"}).text
    for key in ("high-speed", "axial-angle"):
        part = _section(html, key)
        assert 'class="card section left-out"' in html[html.index(f'id="section-{key}"') - 60:][:120]
        assert part.count("Left out:") == 1 and 'class="message"' not in part
    assert 'class="error"' not in html  # no field is at fault
    for key in ("load-distribution", "life", "frequencies"):
        assert "Left out" not in _section(html, key) and 'class="num"' in _section(html, key)


def test_skf_friction_for_a_bearing_without_constants_is_left_out_not_an_error(client):
    # issue 24: SKF's angular-contact constants are published for 40 deg single-row bearings (B218 runs);
    # a 15 deg spindle bearing has none
    html = client.get("/", params={"bearing": "7008 C", "radial_load": "2 kN", "speed": "3000 rpm",
                                   "viscosity": "20 cSt", "model": "skf"}).text
    part = _section(html, "friction")
    assert "Left out:" in part and "15 deg is not covered" in part
    assert 'id="error-model"' not in html
    html = client.get("/", params={"bearing": "B218", "radial_load": "2 kN", "speed": "3000 rpm",
                                   "viscosity": "20 cSt", "model": "skf"}).text
    assert "Left out" not in _section(html, "friction")


def test_a_bad_field_is_named_by_its_label_next_to_it(client):
    html = client.get("/", params={"bearing": "B218", "axial_load": "2 m", "speed": "3000 rpm"}).text
    message = re.search(r'<p class="error" id="error-axial_load">([^<]*)</p>', html).group(1)
    assert message.startswith("Axial load F_a: &#39;2 m&#39; is a length")
    assert "--" not in message and "Traceback" not in html


def test_the_bearing_set_section(client):
    query = {"bearing": "7218B", "arrangement": "DB", "preload": "1 kN", "fy": "2 kN", "speed": "0 rpm"}
    html = client.get("/", params=query).text
    api = client.get("/api/bearing-set", params={**{k: v for k, v in query.items() if k != "bearing"},
                                                  "bearing": "7218B, 7218B"}).json()
    part = _section(html, "bearing-set")
    assert "Left out" not in part
    key = next(k for k, v in api.items() if isinstance(v, float) and k.endswith("_um") and v)
    assert f">{page.number(api[key], page.scales(api)[key])}<" in part


def test_the_report_carries_inputs_version_date_and_download_links(client):
    query = {"bearing": "6205-2RS", "radial_load": "2 kN", "speed": "1797 rpm", "oil": "VG68",
             "temperature": "70 degC", "contamination": "normal", "reliability": "95"}
    html = client.get("/", params=query).text
    inputs = html[html.index('id="inputs"'):html.index("</table>", html.index('id="inputs"'))]
    for label, value in (("Radial load F_r", "2 kN"), ("Oil grade", "VG68"), ("Reliability", "95")):
        assert f"<th>{label}</th><td class=\"num\">{value}</td>" in inputs
    assert __version__ in html and re.search(r"\d{4}-\d{2}-\d{2} \d{2}:\d{2} UTC", html)
    part = _section(html, "life")
    links = dict(re.findall(r'<a href="([^"]+)" class="(json|csv)-link"', part))
    by_kind = {v: k.replace("&amp;", "&") for k, v in links.items()}
    doc = client.get(by_kind["json"]).json()
    assert doc["reliability_percent"] == 95.0 if "reliability_percent" in doc else doc
    table = client.get(by_kind["csv"])
    assert table.headers["content-type"].startswith("text/csv")
    rows = {r[0]: r[1] for r in csv.reader(io.StringIO(table.text)) if len(r) == 3}
    key = next(k for k, v in doc.items() if k.endswith("_h") and isinstance(v, float))
    assert float(rows[key]) == doc[key]


def test_to_csv_keeps_every_digit_and_the_rows():
    text = page.to_csv({"a_N": 0.1 + 0.2, "warnings": ["w"], "cases": [{"x_N": 1.5}, {"x_N": 2.5}]})
    lines = text.splitlines()
    assert lines[:3] == ["quantity,value,unit", "a_N,0.30000000000000004,N", "warning,w,"]
    assert lines[-3:] == ["x_N", "1.5", "2.5"]


def test_catalog_stand_load_and_runout_sections(client):
    from pathlib import Path

    text = (Path(__file__).resolve().parents[2] / "examples" / "runout" /
            "example1_oversize_ball.toml").read_text(encoding="utf-8")
    html = client.get("/", params={"bearing": "B218", "speed": "3000 rpm", "errors": text,
                                   "angle": "30 deg"}).text
    for key in ("catalog", "stand-load", "runout"):
        part = _section(html, key)
        assert "Left out" not in part and 'class="message"' not in part, key
        assert part.count('class="num"') > 3, key
    runout = client.post("/api/runout", json={"errors": text, "angle": "30 deg", "bearing": "B218"}).json()
    key = next(k for k, v in runout.items() if k.endswith("_um") and isinstance(v, float) and v)
    assert f">{page.number(runout[key], page.scales(runout)[key])}<" in _section(html, "runout")
    assert "<th>Error set</th><td class=\"num\">pasted," in html  # summarised in the inputs
    empty = client.get("/", params={"radial_load": "1 kN", "balls": "9", "ball_diameter": "7.94 mm",
                                    "pitch_diameter": "39.04 mm", "contact_angle": "0 deg"}).text
    assert "Left out: no catalog bearing picked" in _section(empty, "catalog")
    assert "Left out: no error set pasted." in _section(empty, "runout")

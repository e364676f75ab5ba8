"""How the calculator page shows numbers and warnings (bearinglab.web.page and the template).

The page rounds what it shows (6 significant digits, float noise next to a larger value of the same
unit as 0); the JSON API keeps every digit. Plausibility warnings of a result are shown with it.
"""

import json
import re

import pytest
from fastapi.testclient import TestClient

from bearinglab.web import create_app, page


@pytest.fixture(scope="module")
def client():
    return TestClient(create_app())


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
    return re.findall(r'<(?:td|span class="value")[^>]*>([^<]*)<', html)


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
    noisy = [c for c in cells if "e-" in c or "e+" in c or _significant_digits(c) > 6]
    assert not noisy, noisy  # never more than 6 significant digits, never 1e-14 style
    start = html.index("<th>displacement y</th>")
    assert html[start:].startswith("<th>displacement y</th><td>0</td>")
    assert f"<td>{doc['displacement_z_um']:.6g}</td>" in html


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

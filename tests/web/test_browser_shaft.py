"""The shaft-system section of the web calculator in a real browser (issue 33 item 5): the tables make the
file, the shaft is drawn as you type, a TOML file is uploaded and downloaded, the results are the API's,
and the printed report carries them. The browser and the server are those of ``test_browser.py``."""

import re
import shutil
import subprocess
import tomllib
from pathlib import Path

import httpx
import pytest
from test_browser import ARTIFACTS, base_url, browser, page  # noqa: F401 -- the fixtures

from bearinglab.web import page as web_page
from bearinglab.web import shaft as web_shaft

SPINDLE = Path(__file__).resolve().parents[2] / "examples" / "shaft" / "spindle.toml"


def _document(url, text, **given):
    r = httpx.post(url + "/api/shaft", json={"model": text, **given}, timeout=120)
    assert r.status_code == 200, r.text
    return r.json()


def _explicit(doc):
    """A shaft file with each support's axial location written out (the editor writes it; a set locates by
    default, another support does not)."""
    for sup in doc.get("supports", []):
        sup.setdefault("axial", "bearing_set" in sup)
    return doc


def _open_editor(page, base_url):  # noqa: F811 -- the fixtures' names
    page.goto(base_url + "/")
    page.click("#shaft-details > summary")


def test_browser_the_tables_make_the_file_and_the_drawing_as_you_type(page, base_url):  # noqa: F811
    _open_editor(page, base_url)
    assert page.input_value("#shaft") == ""  # nothing posted until the shaft is edited
    page.click("#shaft-example")
    text = page.input_value("#shaft")
    doc = tomllib.loads(text)  # the tables and the other lines make one TOML file
    assert doc["speed"] == "1500 rpm" and doc["lubricant"]["oil"] == "VG68"
    assert [s["name"] for s in doc["supports"]] == ["A", "B"] and doc["supports"][0]["axial"] is True
    assert doc["gears"][0]["torque"] == "120 N*m" and doc["loads"][0]["mz"] == "-120 N*m"
    assert page.locator("#shaft-drawing rect.s-section").count() == 3
    assert page.locator("#shaft-drawing rect.s-gear").count() == 1
    assert page.locator("#shaft-drawing rect.s-bearing").count() == 4  # a bearing above and below the shaft

    def bearing_x(k):
        return float(page.locator("#shaft-drawing rect.s-bearing").nth(k).get_attribute("x"))

    before = bearing_x(2)
    position = page.locator("#shaft-supports tbody tr").nth(1).locator("[data-key=position]")
    position.fill("200 mm")  # drawn as typed: the bearing moves to scale, the file follows
    assert bearing_x(2) < before
    span = (bearing_x(2) - bearing_x(0))
    assert span == pytest.approx((200 - 20) / 260 * 900, rel=1e-9)  # 900 px for the 260 mm shaft
    assert tomllib.loads(page.input_value("#shaft"))["supports"][1]["position"] == "200 mm"
    position.fill("200 xx")  # not a length: marked at its cell
    assert "bad" in position.get_attribute("class")
    position.fill("200 mm")
    assert "bad" not in (position.get_attribute("class") or "")
    # a support of another kind, a row added and one removed
    supports = page.locator("#shaft-supports tbody tr")
    supports.nth(1).locator("select[data-key=kind]").select_option("set")
    supports.nth(1).locator("[data-key=arrangement]").fill("DB")
    supports.nth(1).locator("[data-key=preload]").fill("300 N")
    b = tomllib.loads(page.input_value("#shaft"))["supports"][1]
    assert b["bearing_set"] == {"bearing": "6207", "arrangement": "DB", "preload": "300 N"} and b["axial"] is False
    page.click("button[data-add=loads]")
    assert page.locator("#shaft-loads tbody tr").count() == 2
    page.locator("#shaft-loads tbody tr").nth(1).locator("button.remove").click()
    assert len(tomllib.loads(page.input_value("#shaft"))["loads"]) == 1
    ARTIFACTS.mkdir(exist_ok=True)
    page.locator("#group-shaft").screenshot(path=ARTIFACTS / "web-shaft-editor.png")


def test_browser_computes_the_shaft_and_shows_the_apis_numbers(page, base_url):  # noqa: F811
    _open_editor(page, base_url)
    page.click("#shaft-example")
    page.fill("#shaft_stiffness_at", "90 mm")
    page.fill("#shaft_modes", "2")
    text = page.input_value("#shaft")
    page.click("#submit")
    page.wait_for_load_state()
    assert page.locator("#section-shaft.left-out").count() == 0
    doc = _document(base_url, text, stiffness_at="90 mm", modes="2")
    summary = page.inner_text("#shaft-summary")
    for label, value, unit in web_shaft.summary_rows(doc):
        assert label in summary and web_page.number(value) in summary, label
    supports = page.inner_text("#shaft-result-supports")
    for p in doc["supports"]:
        assert web_page.number(p["displacement_y_um"]) in supports and web_page.number(p["tilt_x_mrad"]) in supports
    bearings = page.inner_text("#shaft-result-bearings")
    for row in web_shaft.bearing_rows(doc):
        assert web_page.number(row[3]) in bearings and web_page.number(row[7]) in bearings  # L10h, p_max
    assert page.locator("#shaft-figure svg").count() == 1
    # the page reads the posted file back into its tables
    assert page.locator("#shaft-sections tbody tr").count() == 3
    assert page.input_value("#shaft-gears tbody tr >> nth=0 >> [data-key=pitch_diameter]") == "150 mm"
    # the other sections say they do not apply; no error next to a field of the bearing form
    assert page.locator("p.error").count() == 0
    assert "Left out" in page.inner_text("#section-friction")


def test_browser_uploads_a_toml_file_and_downloads_the_tables_file(page, base_url, tmp_path):  # noqa: F811
    _open_editor(page, base_url)
    page.set_input_files("#shaft-upload", str(SPINDLE))  # posted as it is: the page computes it
    page.wait_for_selector("#shaft-summary")
    assert page.locator("#shaft-supports tbody tr").count() == 2
    front = page.locator("#shaft-supports tbody tr").nth(0)
    assert front.locator("select[data-key=kind]").input_value() == "set"
    assert front.locator("[data-key=value]").input_value() == "7014 C"
    assert front.locator("[data-key=arrangement]").input_value() == "DB"
    other = page.input_value("#shaft-other")
    assert "[lubricant]" in other and "[[masses]]" in other and 'gravity = "-y"' in other
    # the file the tables make is the uploaded one, without its comments
    original = _explicit(tomllib.loads(SPINDLE.read_text(encoding="utf-8")))
    assert tomllib.loads(page.input_value("#shaft")) == original
    with page.expect_download() as download:
        page.click("#shaft-download")
    saved = tmp_path / "shaft.toml"
    download.value.save_as(saved)
    assert download.value.suggested_filename == "shaft.toml"
    assert tomllib.loads(saved.read_text(encoding="utf-8")) == original
    doc = _document(base_url, saved.read_text(encoding="utf-8"))
    assert web_page.number(doc["system_life_h"]) in page.inner_text("#shaft-summary")


def test_browser_shows_a_bad_shaft_file_in_one_line(page, base_url):  # noqa: F811
    text = SPINDLE.read_text(encoding="utf-8").replace('position = "330 mm"', 'position = "500 mm"')
    page.goto(base_url + "/?" + httpx.QueryParams({"shaft": text}).__str__())
    message = page.inner_text("#message-shaft")
    assert message == "Shaft system: supports[1].position: rear at 500 mm lies outside the shaft (0 ... 400 mm)"
    assert page.inner_text("#error-shaft") == message  # next to the editor too
    assert page.input_value("#shaft-supports tbody tr >> nth=1 >> [data-key=position]") == "500 mm"
    assert "Traceback" not in page.content()


def test_browser_the_printed_report_carries_the_shaft(browser, base_url):  # noqa: F811
    context = browser.new_context(viewport={"width": 1280, "height": 900})
    context.set_default_timeout(120_000)
    pg = context.new_page()
    text = SPINDLE.read_text(encoding="utf-8")
    pg.goto(base_url + "/?" + str(httpx.QueryParams({"shaft": text, "shaft_stiffness_at": "0 mm",
                                                     "shaft_modes": "2"})))
    assert pg.locator("#shaft-summary").count() == 1
    pg.emulate_media(media="print")
    assert not pg.locator("form").is_visible()
    ARTIFACTS.mkdir(exist_ok=True)
    pdf = ARTIFACTS / "web-report-shaft.pdf"
    pg.pdf(path=pdf, format="A4", print_background=True)
    printed = pg.inner_text("body")
    context.close()
    assert 1 <= len(re.findall(rb"/Type\s*/Page[^s]", pdf.read_bytes())) <= 2
    text_out = printed
    if shutil.which("pdftotext"):
        text_out = subprocess.run(["pdftotext", "-layout", str(pdf), "-"], capture_output=True, text=True,
                                  check=True).stdout
    doc = _document(base_url, text, stiffness_at="0 mm", modes="2")
    for label, value, unit in web_shaft.summary_rows(doc):  # the system, each number with its unit
        if isinstance(value, float) and unit:
            assert re.search(rf"{re.escape(web_page.number(value))}\s+{re.escape(unit)}", text_out), label
    rows, scales = web_shaft.support_rows(doc)
    for row in rows:  # each support's line: its name, position and loads in order
        cells = [row[0]] + [web_page.number(v, s) for v, s in zip(row[1:5], scales[1:5])]
        assert re.search(r"\s+".join(map(re.escape, cells)), text_out), cells
    for row in web_shaft.bearing_rows(doc):
        cells = [row[0], row[1]] + [web_page.number(v) for v in row[2:]]
        assert re.search(r"\s+".join(map(re.escape, cells)), text_out), cells
    assert f"{len(text.strip().splitlines())} lines of TOML" in text_out  # the inputs: the file summarised


@pytest.mark.parametrize("width", [375])
def test_browser_the_shaft_section_fits_a_phone(browser, base_url, width):  # noqa: F811
    context = browser.new_context(viewport={"width": width, "height": 812}, device_scale_factor=2)
    context.set_default_timeout(120_000)
    phone = context.new_page()
    phone.goto(base_url + "/?" + str(httpx.QueryParams({"shaft": SPINDLE.read_text(encoding="utf-8")})))
    assert phone.locator("#shaft-summary").count() == 1 and phone.locator("#shaft-editor").is_visible()
    assert phone.evaluate("document.documentElement.scrollWidth") <= width
    ARTIFACTS.mkdir(exist_ok=True)
    phone.screenshot(path=ARTIFACTS / f"web-{width}-shaft.png", full_page=True)
    context.close()

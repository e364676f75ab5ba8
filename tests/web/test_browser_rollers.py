"""The roller sections of the web calculator in a real browser (issue 32 item 7): the picker finds a roller bearing,
the load distribution shows its rollers and the lamina pressures, the ball bearings' models are left out in one
line, and the printed report holds the numbers. The fixtures (Chromium under Playwright, the app under uvicorn)
are those of ``test_browser.py``; screenshots and the PDF go to ``test-artifacts/``."""

import re
import shutil
import subprocess

import httpx
from test_browser import ARTIFACTS, base_url, browser, page  # noqa: F401 -- the fixtures

ROLLERS = ("?bearing=NU+208+ECP&fx=15+kN&speed=1500+rpm&viscosity=20+cSt&radial_clearance=30+um&model=skf"
           "&contamination=normal")


def test_browser_picker_finds_a_roller_bearing(page, base_url):  # noqa: F811 -- the fixture
    page.goto(base_url + "/")
    page.fill("#bearing", "NU 208")
    page.wait_for_function("document.querySelector('#matches').innerText.includes('NU 208 ECP')")
    assert "cylindrical" in page.inner_text("#matches")
    page.click("#matches button[data-name='NU 208 ECP']")
    assert page.input_value("#bearing") == "NU 208 ECP"
    page.fill("#search-bore", "40 mm")  # by size and part of a designation: many ball bearings share the size
    page.fill("#search-od", "80 mm")
    page.fill("#bearing", "NJ")
    page.wait_for_function("document.querySelector('#matches').innerText.includes('NJ 208 ECP (cylindrical')")


def test_browser_roller_sections_and_their_printed_report(browser, base_url):  # noqa: F811 -- the fixture
    context = browser.new_context(viewport={"width": 1280, "height": 900})
    context.set_default_timeout(120_000)
    tab = context.new_page()
    tab.goto(base_url + "/" + ROLLERS)
    load = tab.locator("#section-load-distribution")
    assert "Left out" not in load.inner_text() and load.locator("svg").count() == 1
    table = tab.locator("#rollers-load-distribution-1")
    assert table.locator("tr").count() == 15  # the header and 14 rollers
    doc = httpx.get(base_url + tab.get_attribute("#section-load-distribution a.json-link", "href"),
                    timeout=60).json()
    first = table.locator("tr").nth(1).inner_text()
    from bearinglab.web import page as web_page

    assert web_page.number(doc["rollers"][0]["load_N"]) in first  # 5164.82 N, the most loaded roller
    for key in ("high-speed", "axial-angle", "stand-load", "runout"):
        assert "a model of ball bearings" in tab.inner_text(f"#left-out-{key}"), key
    for key in ("life", "friction", "film", "frequencies"):
        assert "Left out" not in tab.inner_text(f"#section-{key}"), key
    assert tab.locator("#rollers-film-1 tr").count() == 15
    assert "Traceback" not in tab.content() and tab.locator("p.error").count() == 0
    ARTIFACTS.mkdir(exist_ok=True)
    tab.screenshot(path=ARTIFACTS / "web-rollers-1280.png", full_page=True)
    tab.emulate_media(media="print")
    printed = tab.inner_text("body")
    pdf = ARTIFACTS / "web-report-rollers.pdf"
    tab.pdf(path=pdf, format="A4", print_background=True)
    context.close()
    assert len(re.findall(rb"/Type\s*/Page[^s]", pdf.read_bytes())) >= 1
    text = printed
    if shutil.which("pdftotext"):
        text = subprocess.run(["pdftotext", "-layout", str(pdf), "-"], capture_output=True, text=True,
                              check=True).stdout
    assert "Rollers (14, 30 slices each" in text
    for row in doc["rollers"][:3]:  # the loaded rollers' numbers, as the page rounds them
        assert web_page.number(row["load_N"]) in text and web_page.number(row["max_pressure_MPa"]) in text
    assert web_page.number(doc["max_roller_load_N"]) in text

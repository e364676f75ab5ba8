"""The web calculator in a real browser: the distribution's headless Chromium, driven by Playwright.

The app runs under uvicorn in a background thread on 127.0.0.1 and a free port. Screenshots go to
``test-artifacts/``. Without a browser the tests skip locally and fail under CI (``CI`` set): CI must
never pass by skipping them (``.ci/run`` installs Chromium).
"""

import os
import re
import shutil
import socket
import threading
import time
from pathlib import Path

import pytest
import uvicorn
from playwright.sync_api import sync_playwright

from bearinglab.web import create_app

ARTIFACTS = Path(__file__).resolve().parents[2] / "test-artifacts"
BROWSER_ARGS = [
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--no-first-run",
]


def _chromium():
    """The system's Chromium (never a browser downloaded by `playwright install`)."""
    for name in ("chromium", "chromium-browser", "google-chrome"):
        path = shutil.which(name)
        if path:
            return path
    return None


def _no_browser(reason):
    if os.environ.get("CI"):
        pytest.fail(f"no browser for the web tests under CI: {reason}")
    pytest.skip(f"no browser: {reason}")


@pytest.fixture(scope="module")
def base_url():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    server = uvicorn.Server(
        uvicorn.Config(create_app(), host="127.0.0.1", port=port, log_level="warning")
    )
    thread = threading.Thread(target=server.run, daemon=True)
    thread.start()
    deadline = time.monotonic() + 30
    while not server.started:
        if time.monotonic() > deadline or not thread.is_alive():
            pytest.fail("the web app did not start")
        time.sleep(0.05)
    yield f"http://127.0.0.1:{port}"
    server.should_exit = True
    thread.join(10)


@pytest.fixture(scope="module")
def browser():
    executable = _chromium()
    if executable is None:
        _no_browser("no chromium on PATH (apt-get install chromium)")
    with sync_playwright() as p:
        try:
            b = p.chromium.launch(executable_path=executable, args=BROWSER_ARGS)
        except Exception as exc:  # noqa: BLE001 -- any failure to start is "no browser"
            _no_browser(f"{executable} did not start: {exc}")
        yield b
        b.close()


@pytest.fixture
def page(browser):
    context = browser.new_context(viewport={"width": 1280, "height": 900})
    yield context.new_page()
    context.close()


def _fill_and_submit(page, base_url, axial_load):
    page.goto(base_url + "/")
    page.select_option("#bearing", "B218")
    page.fill("#axial_load", axial_load)
    page.fill("#speed", "10000 rpm")
    page.select_option("#constants", "harris")  # the constants of the published case
    page.click("#submit")
    page.wait_for_load_state()


def test_browser_reads_the_contact_angles(page, base_url):
    _fill_and_submit(page, base_url, "20 kN")
    # spec 004 section 7.1, printed to 3 decimals: alpha_i 49.308, alpha_e 32.514 deg (Harris's constants)
    assert page.inner_text("#contact-angle-inner") == "49.308°"
    assert page.inner_text("#contact-angle-outer") == "32.514°"
    assert page.locator("#section-high-speed svg").count() == 1
    assert "Traceback" not in page.content()
    ARTIFACTS.mkdir(exist_ok=True)
    page.screenshot(path=ARTIFACTS / "web-b218-1280.png", full_page=True)
    assert (ARTIFACTS / "web-b218-1280.png").stat().st_size > 10_000


def test_browser_shows_a_bad_load_next_to_its_field(page, base_url):
    _fill_and_submit(page, base_url, "2,5 kN")
    message = page.locator("#error-axial_load")
    assert message.is_visible()
    assert "ambiguous" in message.inner_text() and "2.5 kN" in message.inner_text()
    assert page.get_attribute("#axial_load", "aria-invalid") == "true"
    assert page.input_value("#axial_load") == "2,5 kN"  # the input is kept for correction
    assert "Traceback" not in page.content()
    ARTIFACTS.mkdir(exist_ok=True)
    page.screenshot(path=ARTIFACTS / "web-bad-load.png")


def test_browser_phone_width_and_print(browser, base_url):
    context = browser.new_context(viewport={"width": 390, "height": 844}, device_scale_factor=2)
    phone = context.new_page()
    phone.goto(base_url + "/?bearing=B218&axial_load=20+kN&speed=10000+rpm&constants=harris")
    assert phone.inner_text("#contact-angle-inner") == "49.308°"
    # nothing wider than the screen: the page does not scroll sideways
    assert phone.evaluate("document.documentElement.scrollWidth") <= 390
    ARTIFACTS.mkdir(exist_ok=True)
    phone.screenshot(path=ARTIFACTS / "web-b218-390.png", full_page=True)
    phone.emulate_media(media="print")
    assert not phone.locator("form").is_visible()  # the report prints without the form
    phone.pdf(path=ARTIFACTS / "web-b218-report.pdf", format="A4")
    pages = re.findall(rb"/Type\s*/Page[^s]", (ARTIFACTS / "web-b218-report.pdf").read_bytes())
    assert len(pages) == 1  # a one-page report
    context.close()


_OVERFLOW = """() => {
  const form = document.querySelector('form');
  const wide = [...form.querySelectorAll('input, select, button, label, .error, legend, summary, .hint')]
    .filter(e => e.getBoundingClientRect().right > window.innerWidth + 0.5)
    .map(e => e.id || e.tagName);
  return {page: document.documentElement.scrollWidth, form: form.scrollWidth - form.clientWidth, wide};
}"""


@pytest.mark.parametrize(
    "query, shot",
    [
        ("", "web-form-390.png"),
        ("?bearing=&balls=16&ball_diameter=22.225+mm&axial_load=2%2C5+kN&speed=fast", "web-form-errors-390.png"),
    ],
)
def test_browser_form_fits_a_phone(browser, base_url, query, shot):
    """At 390 px (a phone) the form does not scroll sideways: empty, and with the geometry open and
    long field messages next to their fields."""
    context = browser.new_context(viewport={"width": 390, "height": 844}, device_scale_factor=2)
    phone = context.new_page()
    phone.goto(base_url + "/" + query)
    phone.evaluate("document.querySelector('details.geometry').open = true")
    if query:
        assert phone.locator("#error-axial_load").is_visible()
    fit = phone.evaluate(_OVERFLOW)
    assert fit["page"] <= 390 and fit["form"] <= 0 and not fit["wide"], fit
    ARTIFACTS.mkdir(exist_ok=True)
    phone.locator("form").screenshot(path=ARTIFACTS / shot)
    assert (ARTIFACTS / shot).stat().st_size > 10_000
    context.close()

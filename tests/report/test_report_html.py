"""The HTML page of a report (bearinglab.report.html), parsed back: tables, embedded figures, conclusions."""

import base64
import dataclasses

import pytest
from report_pages import analysed, write_s1

from bearinglab import report
from bearinglab.lab import analysis


@pytest.fixture(scope="module")
def written(tmp_path_factory):
    return write_s1(tmp_path_factory.mktemp("reports"))


def _table(parser, caption_start):
    k = next(i for i, c in enumerate(parser.captions) if c.startswith(caption_start))
    return parser.tables[k]


def test_report_tables_are_present_with_their_rows(written):
    _, p = written
    t4 = _table(p, "Table 4. Friction torque at tilt β = 45°")
    assert len(t4) == 3  # Q = 0.5, 1, 2 kg
    assert [row[0] for row in t4] == ["0.5", "1", "2"]
    assert t4[2][-1] == "0.0975" and t4[2][-2] == "2"  # T and switch position of Q = 2 kg, column B
    assert [
        "Q [kg]",
        "P0 [N]",
        "A (n = 1467.75 rpm)",
        "B (n = 2728.5 rpm)",
    ] in p.headers  # grouped header
    t5 = _table(p, "Table 5. Friction torque at Q = 2 kg")
    assert len(t5) == 6
    assert [row[1] for row in t5] == ["501.5", "991.25", "1467.75", "1929.5", "2375", "2829.5"]
    task1 = _table(p, "Task 1")
    assert len(task1) == 2 and task1[0][3].startswith("1.434958e-03 ± ")
    task2 = _table(p, "Task 2")
    assert len(task2) == 2 and task2[1][3].startswith("1.486077e-07 ± ")
    task3 = _table(p, "Task 3")
    assert len(task3) == 2 and task3[0][4].startswith("4.692239e-02 ± ")
    bearing = dict(map(tuple, _table(p, "Test bearing")))
    assert bearing["designation"] == "18" and bearing["static load rating C0 [N]"] == "1354"
    assert len(_table(p, "Measurement rows")) == 18


def test_report_images_are_embedded_and_nothing_is_external(written):
    _, p = written
    assert len(p.images) == 3
    for img in p.images:
        assert img["src"].startswith("data:image/svg+xml;base64,")
        svg = base64.b64decode(img["src"].split(",", 1)[1]).decode("utf-8")
        assert "<svg" in svg and "</svg>" in svg and "<metadata>" not in svg
    assert all(ref.startswith("data:") for ref in p.refs)  # no links, no external resources
    assert "link" not in p.tags and "script" not in p.tags
    html_text = written[0].html.read_text(encoding="utf-8")
    assert (
        "@media print" in html_text and "http://" not in html_text and "https://" not in html_text
    )


def test_report_conclusions_and_conditions(written):
    files, p = written
    text = files.html.read_text(encoding="utf-8")
    assert "<h2>5. Conclusions</h2>" in text
    assert "I1, effect of speed on μ (β = 45°): μ(n_max)/μ(n_min) − 1 = +35.9 %" in text
    assert "measured ratio 2.374043, predicted (P0 ratio)^(1+c) = 2.342982" in text
    conditions = dict(map(tuple, _table(p, "Test conditions")))
    assert conditions["tilts β [deg]"] == "0, 45, 60" and conditions["masses Q [kg]"] == "0.5, 1, 2"
    assert "Generated 2024-01-01 00:00 UTC" in text


def test_a_session_without_t5_rows_has_no_task2_table():
    s = analysed("s0_direct").session
    keep = s.rows.series == "T4"
    rows = type(s.rows)(*(field[keep] for field in s.rows))
    r = analysis.analyse(dataclasses.replace(s, rows=rows))
    page = report.render_html(r, [], generated="now")
    assert "Task 1: reduced friction coefficient" in page and "Task 3: load dependence" in page
    assert "Task 2: speed dependence" not in page and "Mean f0 of task 2" not in page
    assert "<li>No T5 rows: task 2 was not run.</li>" in page
    assert "<h2>4. Plots</h2>\n<h2>5. Conclusions</h2>" in page  # no figure given, none shown

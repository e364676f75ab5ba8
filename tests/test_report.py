"""HTML report of the friction lab (bearinglab.report): generated, parsed back, self-contained, atomic."""

import base64
import csv
import json
from html.parser import HTMLParser
from pathlib import Path

import pytest

from bearinglab import report
from bearinglab.errors import InputError
from bearinglab.lab import analysis, measurement

EXAMPLES = Path(__file__).resolve().parent.parent / "examples" / "friction"


class _Parser(HTMLParser):
    """Collects tables (rows of cell texts), images, links and external references."""

    def __init__(self):
        super().__init__()
        self.tables, self.images, self.refs, self.captions, self.tags = [], [], [], [], []
        self.headers = []
        self._row = self._cell = self._caption = None
        self._head = False

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        self.tags.append(tag)
        for key in ("src", "href", "action", "data"):
            if key in a:
                self.refs.append(a[key])
        if tag == "table":
            self.tables.append([])
        elif tag == "thead":
            self._head = True
        elif tag == "tr":
            self._row = []
        elif tag in ("td", "th"):
            self._cell = ""
        elif tag == "caption":
            self._caption = ""
        elif tag == "img":
            self.images.append(a)

    def handle_endtag(self, tag):
        if tag in ("td", "th") and self._cell is not None:
            self._row.append(self._cell.strip())
            self._cell = None
        elif tag == "tr" and self._row is not None:
            if not self._head:  # body rows only; header rows are checked through their texts
                self.tables[-1].append(self._row)
            else:
                self.headers.append(self._row)
            self._row = None
        elif tag == "thead":
            self._head = False
        elif tag == "caption":
            self.captions.append(self._caption.strip())
            self._caption = None

    def handle_data(self, data):
        if self._cell is not None:
            self._cell += data
        if self._caption is not None:
            self._caption += data


@pytest.fixture(scope="module")
def s1_result():
    return analysis.analyse(measurement.read_session(EXAMPLES / "s1_readings.toml"))


@pytest.fixture(scope="module")
def written(s1_result, tmp_path_factory):
    out = tmp_path_factory.mktemp("reports") / "s1"
    files = report.write_report(s1_result, out, generated="2024-01-01 00:00 UTC")
    parser = _Parser()
    parser.feed(files.html.read_text(encoding="utf-8"))
    return files, parser


def _table(parser, caption_start):
    k = next(i for i, c in enumerate(parser.captions) if c.startswith(caption_start))
    return parser.tables[k]


def test_report_files(written):
    files, _ = written
    names = sorted(p.name for p in files.directory.iterdir())
    assert names == sorted(
        [
            report.MARKER,
            "report.html",
            "results.json",
            "rows.csv",
            "table4_tilt45.csv",
            "table5_Q2kg.csv",
            "task1.csv",
            "task2.csv",
            "task3.csv",
            "task1_tilt45.png",
            "task1_tilt45.svg",
            "task2.png",
            "task2.svg",
            "task3_tilt45.png",
            "task3_tilt45.svg",
        ]
    )
    for f in files.figures:
        data = f.read_bytes()
        assert data.startswith(b"\x89PNG\r\n\x1a\n") if f.suffix == ".png" else b"<svg" in data
    assert not [
        p for p in files.directory.parent.iterdir() if p.name.startswith(".s1.")
    ]  # no temporary left


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


def test_results_json_and_csv_tables(written, s1_result):
    files, _ = written
    d = json.loads(files.json.read_text(encoding="utf-8"))
    assert d == json.loads(json.dumps({**analysis.to_dict(s1_result), "files": d["files"]}))
    assert d["files"]["figures"] == [f.name for f in files.figures]
    with open(files.directory / "task1.csv", newline="", encoding="utf-8") as fh:
        rows = list(csv.DictReader(fh))
    assert (
        float(rows[0]["mu"]) == pytest.approx(1.434957683e-03, rel=1e-9)
        and rows[0]["lines"] == "5 6 7"
    )
    with open(files.directory / "table4_tilt45.csv", newline="", encoding="utf-8") as fh:
        t4 = list(csv.reader(fh))
    assert t4[0][:2] == ["Q [kg]", "P0 [N]"] and len(t4) == 4
    assert float(t4[1][1]) == pytest.approx(3.815195, abs=5e-7)


def test_failed_run_leaves_no_half_written_report(s1_result, tmp_path, monkeypatch):
    calls = []

    def failing(plot):
        calls.append(plot.name)
        if len(calls) == 2:
            raise RuntimeError("disk full")
        return b"png", "<svg></svg>"

    monkeypatch.setattr(report, "render_figure", failing)
    with pytest.raises(RuntimeError, match="disk full"):
        report.write_report(s1_result, tmp_path / "out")
    assert list(tmp_path.iterdir()) == []  # neither the target nor a temporary directory


def _fast_figures(monkeypatch):
    """Figures are tested above; the directory-handling tests only need some bytes."""
    monkeypatch.setattr(report, "render_figure", lambda plot: (b"\x89PNG\r\n\x1a\n", "<svg></svg>"))


def test_failed_rerun_keeps_the_previous_report(s1_result, tmp_path, monkeypatch):
    _fast_figures(monkeypatch)
    first = report.write_report(s1_result, tmp_path / "out", generated="first")
    before = first.html.read_text(encoding="utf-8")
    monkeypatch.setattr(
        report, "render_html", lambda *a, **k: (_ for _ in ()).throw(RuntimeError("boom"))
    )
    with pytest.raises(RuntimeError, match="boom"):
        report.write_report(s1_result, tmp_path / "out")
    assert first.html.read_text(encoding="utf-8") == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out"]


def test_previous_report_is_replaced_but_other_directories_are_refused(
    s1_result, tmp_path, monkeypatch
):
    _fast_figures(monkeypatch)
    s0 = analysis.analyse(measurement.read_session(EXAMPLES / "s0_direct.toml"))
    report.write_report(s1_result, tmp_path / "out")
    files = report.write_report(s0, tmp_path / "out")
    assert (files.directory / "table4_tilt90.csv").exists() and not (
        files.directory / "table4_tilt45.csv"
    ).exists()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out"]
    user = tmp_path / "mine"
    user.mkdir()
    (user / "notes.txt").write_text("keep me")
    with pytest.raises(
        InputError, match=r"out: .*mine exists and is not a bearinglab report directory"
    ):
        report.write_report(s0, user)
    assert (user / "notes.txt").read_text() == "keep me" and len(list(user.iterdir())) == 1
    empty = tmp_path / "empty"
    empty.mkdir()
    assert report.write_report(s0, empty).html.exists()

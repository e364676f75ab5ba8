"""The report directory (bearinglab.report.files): its files, results.json and the CSV tables, and the
whole-or-nothing writing of the directory."""

import csv
import json

import pytest
from report_pages import analysed, write_s1

from bearinglab import report
from bearinglab.errors import InputError
from bearinglab.lab import presentation


@pytest.fixture(scope="module")
def s1_result():
    return analysed("s1_readings")


@pytest.fixture(scope="module")
def written(tmp_path_factory):
    return write_s1(tmp_path_factory.mktemp("reports"))


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


def test_results_json_and_csv_tables(written, s1_result):
    files, _ = written
    d = json.loads(files.json.read_text(encoding="utf-8"))
    assert d == json.loads(json.dumps({**presentation.to_dict(s1_result), "files": d["files"]}))
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

    monkeypatch.setattr(report.files, "render_figure", failing)
    with pytest.raises(RuntimeError, match="disk full"):
        report.write_report(s1_result, tmp_path / "out")
    assert list(tmp_path.iterdir()) == []  # neither the target nor a temporary directory


def _fast_figures(monkeypatch):
    """Figures are tested above; the directory-handling tests only need some bytes."""
    monkeypatch.setattr(
        report.files, "render_figure", lambda plot: (b"\x89PNG\r\n\x1a\n", "<svg></svg>")
    )


def test_failed_rerun_keeps_the_previous_report(s1_result, tmp_path, monkeypatch):
    _fast_figures(monkeypatch)
    first = report.write_report(s1_result, tmp_path / "out", generated="first")
    before = first.html.read_text(encoding="utf-8")
    monkeypatch.setattr(
        report.files, "render_html", lambda *a, **k: (_ for _ in ()).throw(RuntimeError("boom"))
    )
    with pytest.raises(RuntimeError, match="boom"):
        report.write_report(s1_result, tmp_path / "out")
    assert first.html.read_text(encoding="utf-8") == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out"]


def test_previous_report_is_replaced_but_other_directories_are_refused(
    s1_result, tmp_path, monkeypatch
):
    s0 = analysed("s0_direct")
    _fast_figures(monkeypatch)
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


def test_csv_and_json_come_from_the_library_writers(written):
    # one CSV dialect (LF line endings) and one JSON dialect (indent 2, UTF-8
    # characters kept, a final newline) for every file of the library
    files, _ = written
    raw = (files.directory / "rows.csv").read_bytes()
    assert b"\r\n" not in raw and raw.endswith(b"\n")
    text = files.json.read_text(encoding="utf-8")
    assert text.startswith('{\n  "format": ') and text.endswith("}\n") and "β" in text


def test_json_writer_turns_nan_and_numpy_into_json():
    import math

    import numpy as np

    from bearinglab._io import json_text

    doc = {"a": np.float64(math.nan), "b": (np.int64(2), np.bool_(True)), 3: np.arange(2.0)}
    assert json.loads(json_text(doc)) == {"a": None, "b": [2, True], "3": [0.0, 1.0]}
    assert json_text({"x": math.inf}) == '{\n  "x": null\n}\n'

"""A result in engineering units (bearinglab.lab.presentation): Tables 4 and 5, plot data, the results
dict, conclusions; the old names in bearinglab.lab.analysis."""

import json
from pathlib import Path

import pytest
from lab_sessions import EXAMPLES, S1_ROWS, write_session

from bearinglab.lab import analysis, measurement, presentation

DATA = Path(__file__).resolve().parents[1] / "data"


def test_negative_intercepts_are_reported_and_flagged(tmp_path):
    # torque falling with speed at beta = 0 makes T_F extrapolate above, so use a steep rise instead:
    rows = S1_ROWS.replace("T5,  0, 2.0, , 11.0, 33.5, 1,", "T5,  0, 2.0, , 11.0, 5.0, 1,")
    r = analysis.analyse(measurement.read_session(write_session(tmp_path, rows=rows)))
    assert r.task2.load_term[0] < 0
    d = presentation.to_dict(r)
    assert d["task2"][0]["negative_intercept"] is True
    assert any(c.startswith("Warning: T_F at β = 0°") for c in d["conclusions"])


def test_tables_4_and_5_layout():
    r = analysis.analyse(measurement.read_session(EXAMPLES / "s1_readings.toml"))
    (t4,) = presentation.table4(r)
    assert t4.name == "table4_tilt45" and len(t4.rows) == 3 and len(t4.columns) == 2 + 2 * 5
    assert [row[0] for row in t4.rows] == [0.5, 1.0, 2.0]
    assert t4.rows[2][-2:] == [
        2,
        pytest.approx(0.0975, abs=1e-12),
    ]  # switch 2 at Q = 2 kg, column B
    (t5,) = presentation.table5(r)
    assert t5.name == "table5_Q2kg" and len(t5.rows) == 6 and len(t5.columns) == 2 + 2 * 3
    assert [row[1] for row in t5.rows] == pytest.approx(
        [501.5, 991.25, 1467.75, 1929.5, 2375.0, 2829.5]
    )
    assert "P0 = 16.9914 N" in t5.columns[-1]
    rows = presentation.rows_table(r)
    assert len(rows.rows) == 18 and rows.rows[0][-1] == "x0·Fr + y0·Fa"


def test_plot_lines_start_at_zero_and_reach_1_1_of_the_largest_abscissa():
    r = analysis.analyse(measurement.read_session(EXAMPLES / "s1_readings.toml"))
    plots = presentation.plots(r)
    assert [p.name for p in plots] == ["task1_tilt45", "task2", "task3_tilt45"]
    for p in plots:
        largest = max(float(s.x.max()) for s in p.series)
        for s in p.series:
            assert s.line_x[0] == 0.0 and s.line_x[-1] == pytest.approx(1.1 * largest, rel=1e-15)
    t2 = plots[1].series[0]
    assert t2.line_y[0] == pytest.approx(
        r.task2.load_term[0] * 1e3, rel=1e-12
    )  # intercept T_F at N = 0


def test_results_dict_is_json_clean():
    d = presentation.to_dict(
        analysis.analyse(measurement.read_session(EXAMPLES / "s1_readings.toml"))
    )
    text = json.dumps(d, allow_nan=False)
    assert json.loads(text)["format"] == presentation.RESULTS_FORMAT
    assert {
        "task1",
        "task2",
        "task3",
        "indicators",
        "conclusions",
        "tables",
        "plots",
        "rows",
    } <= set(d)
    assert (
        d["rows"][0]["tilt_deg"] == 45.0 and d["task2"][1]["tilt_deg"] == 60.0
    )  # no 59.99999999999999


def test_presentation_names_stay_reachable_from_analysis():
    # the names pinned for bearinglab.lab.analysis (tests/data/public_api.json) that moved
    pinned = json.loads((DATA / "public_api.json").read_text(encoding="utf-8"))
    moved = [n for n in pinned["bearinglab.lab.analysis"] if n not in analysis.__all__]
    assert "to_dict" in moved and "TableData" in moved
    for name in moved:
        assert getattr(analysis, name) is getattr(presentation, name), name
        assert name in dir(analysis)
    with pytest.raises(AttributeError, match="no attribute 'table6'"):
        analysis.table6  # noqa: B018

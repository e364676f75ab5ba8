"""The blank session file (bearinglab.lab.template): valid, stops at what is missing, written safely."""

import pytest
from lab_sessions import line_of

from bearinglab.errors import InputError
from bearinglab.lab import analysis, measurement, presentation, template


def test_template_is_valid_and_stops_at_what_is_missing(tmp_path):
    text = template.template()
    path = tmp_path / "new.toml"
    path.write_text(text)
    with pytest.raises(
        InputError, match=r"new\.toml, line \d+, field 'bearing\.bore': is empty; fill it in"
    ):
        measurement.read_session(path)
    text18 = template.template(bearing="18")
    assert 'catalog = "18"' in text18 and "C0 = 1354 N" in text18
    path.write_text(text18)
    header = line_of(text18, "series, tilt [deg]")
    with pytest.raises(
        InputError,
        match=rf"new\.toml, line {header}, field 'measurements\.csv': no measurement rows",
    ):
        measurement.read_session(path)
    # filling in the rows (direct values) gives a session that runs
    rows = "T5, 0, 2, , 1000, , , 1000, 0.03\nT5, 0, 2, , 2000, , , 2000, 0.04\n"
    filled = text18.replace(
        "torque [N*mm], note\n",
        "torque [N*mm], note\n"
        + rows.replace(", 1000, , ,", ", , , ,").replace(", 2000, , ,", ", , , ,"),
    )
    path.write_text(filled)
    r = analysis.analyse(measurement.read_session(path))
    assert r.task2.speed_term_factor.size == 1 and r.task1.tilt.size == 0
    assert any("No T4 rows" in c for c in presentation.conclusions(r))


def test_write_template_is_atomic_and_does_not_overwrite(tmp_path):
    path = template.write_template(tmp_path / "a.toml", bearing="101")
    assert 'catalog = "101"' in path.read_text()
    path.write_text("my data")
    with pytest.raises(InputError, match="file exists"):
        template.write_template(path)
    assert path.read_text() == "my data"
    template.write_template(path, overwrite=True)
    assert "[calibration.speed]" in path.read_text()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.toml"]  # no temporary file left


def test_measurement_reexports_the_template():
    assert measurement.template is template.template
    assert measurement.write_template is template.write_template
    assert measurement.FORMAT == template.FORMAT == "bearinglab-friction-session/1"

"""The measurement-session file (bearinglab.lab.measurement): reading, and errors naming file, line and field."""

import hashlib
import math

import pytest
from lab_sessions import EXAMPLES, S1_ROWS, S1_TEXT, line_of, write_session
from numpy.testing import assert_allclose

from bearinglab.errors import InputError
from bearinglab.lab import analysis, measurement

RPM = 2 * math.pi / 60


def test_example_files_are_read_and_never_modified():
    files = [EXAMPLES / n for n in ("s0_direct.toml", "s1_readings.toml", "s1_readings.csv")]
    before = [hashlib.sha256(f.read_bytes()).hexdigest() for f in files]
    s0 = measurement.read_session(files[0])
    s1 = measurement.read_session(files[1])
    analysis.analyse(s1)
    assert [hashlib.sha256(f.read_bytes()).hexdigest() for f in files] == before
    assert (
        s0.bearing.designation == "1000095"
        and s0.rows.line.size == 18
        and s0.calibration.speed is None
    )
    assert s1.rows_source.endswith("s1_readings.csv") and list(s1.rows.switch).count(2) == 3
    assert s1.calibration.speed.values[-1] == pytest.approx(5000 * RPM, rel=1e-15)
    assert s1.calibration.torque[2].values[-1] == pytest.approx(0.5e-3, rel=1e-15)


def test_non_increasing_calibration_value_names_file_line_and_field(tmp_path):
    text = S1_TEXT.replace("[40, 0.0432],", "[40, 0.0318],")
    path = write_session(tmp_path, toml=text)
    line = line_of(text, "[40, 0.0318],")
    with pytest.raises(
        InputError,
        match=rf"s\.toml, line {line}, field 'calibration\.torque_1\.points': calibration "
        r"torque position 1: values must be strictly increasing \[N\*mm\], point 5 "
        r"\(reading 40\) has 0\.0318 after 0\.0318",
    ):
        measurement.read_session(path)


def test_calibration_table_on_one_line_reports_that_line(tmp_path):
    head = '[calibration.speed]\nunit = "rpm"\n'
    start = S1_TEXT.index(head)
    stop = S1_TEXT.index("[calibration.torque_1]")
    text = S1_TEXT[:start] + head + "points = [[0, 0], [10, 5], [20, 4]]\n\n" + S1_TEXT[stop:]
    line = line_of(text, "points = [[0, 0], [10, 5], [20, 4]]")
    with pytest.raises(
        InputError,
        match=rf"s\.toml, line {line}, field 'calibration\.speed\.points': calibration speed: "
        r"values must be strictly increasing \[rpm\], point 3 \(reading 20\) has 4 after 5",
    ):
        measurement.read_session(write_session(tmp_path, toml=text))


def test_calibration_point_that_is_not_a_pair(tmp_path):
    text = S1_TEXT.replace("[30, 1395],", "[30, 1395, 7],")
    line = line_of(text, "[30, 1395, 7],")
    with pytest.raises(
        InputError,
        match=rf"line {line}, field 'calibration\.speed\.points': point 4 must be \[reading, value\]",
    ):
        measurement.read_session(write_session(tmp_path, toml=text))


@pytest.mark.parametrize(
    "old, new, field, message",
    [
        (
            "T4, 45, 2.0, B, 57.0, 23.0, 2,",
            "T4, 45, 2.0, B, 57.0, 101, 2,",
            "torque_reading",
            r"101 is outside the calibrated range \[0, 100\] of the torque position 2 table",
        ),
        (
            "T4, 45, 0.5, A, 31.5, 45.5, 1,",
            "T4, 45, 0, A, 31.5, 45.5, 1,",
            "mass",
            r"must be > 0 \[kg\], got 0",
        ),
        (
            "T4, 45, 0.5, A, 31.5, 45.5, 1,",
            "T4, 95, 0.5, A, 31.5, 45.5, 1,",
            "tilt",
            r"must be in \[0, 90\] \[deg\], got 95",
        ),
        (
            "T4, 45, 0.5, A, 31.5, 45.5, 1,",
            "T4, 45, 0.5, A, 31.5, 45.5, 3,",
            "switch",
            "must be 1 or 2, got 3",
        ),
        (
            "T4, 45, 0.5, A, 31.5, 45.5, 1,",
            "T4, 45, 0.5, A, 31.5, 45.5, ,",
            "switch",
            "needs its switch position",
        ),
        (
            "T4, 45, 0.5, A, 31.5, 45.5, 1,",
            "T6, 45, 0.5, A, 31.5, 45.5, 1,",
            "series",
            "must be T4 .* or T5",
        ),
        (
            "T4, 45, 0.5, A, 31.5, 45.5, 1,",
            "T4, 45, 0.5, , 31.5, 45.5, 1,",
            "column",
            "needs its speed-column label",
        ),
        (
            "T4, 45, 0.5, A, 31.5, 45.5, 1,",
            "T4, 45, 0.5, A, 31.5, 4x, 1,",
            "torque_reading",
            "cannot read '4x' as a number",
        ),
        (
            "T4, 45, 0.5, A, 31.5, 45.5, 1,",
            "T4, 45, 0.5, A, 131.5, 45.5, 1,",
            "speed_reading",
            "outside the calibrated range",
        ),
        (
            "T4, 45, 0.5, A, 31.5, 45.5, 1,",
            "T4, 45, 0.5, A, , 45.5, 1,",
            "speed",
            "missing: give speed_reading or speed",
        ),
    ],
)
def test_bad_rows_name_file_line_and_field(old, new, field, message, tmp_path):
    rows = S1_ROWS.replace(old, new)
    path = write_session(tmp_path, rows=rows)
    line = line_of(rows, new)
    data = [r for r in rows.splitlines() if r.strip() and not r.startswith("#")][
        1:
    ]  # after the header
    row = next(i for i, r in enumerate(data, 1) if new in r)
    with pytest.raises(
        InputError,
        match=rf"s1_readings\.csv, line {line} \(row {row}\), field '{field}': .*{message}",
    ):
        measurement.read_session(path)


def test_reading_and_direct_value_for_the_same_quantity_is_rejected(tmp_path):
    rows = S1_ROWS.replace(
        "speed_reading, torque_reading, switch, note",
        "speed_reading, torque_reading, switch, note, speed [rpm]",
    )
    rows = rows.replace(
        "T4, 45, 0.5, A, 31.5, 45.5, 1,", "T4, 45, 0.5, A, 31.5, 45.5, 1, , 1467.75"
    )
    path = write_session(tmp_path, rows=rows)
    with pytest.raises(
        InputError, match=r"field 'speed': give the speed reading or the speed, not both"
    ):
        measurement.read_session(path)


@pytest.mark.parametrize(
    "old, new, message",
    [
        (
            "series, tilt [deg]",
            "series, tilt",
            r"field 'tilt': the header needs the unit, e.g. 'tilt \[deg\]'",
        ),
        ("mass [kg]", "mass [m]", r"field 'mass': mass: '1 m' is a length, expected a mass"),
        (", note", ", remark", r"field 'remark': unknown column"),
        ("series, ", "", r"field 'series': required column missing"),
    ],
)
def test_bad_csv_headers(old, new, message, tmp_path):
    rows = S1_ROWS.replace(old, new, 1)
    path = write_session(tmp_path, rows=rows)
    with pytest.raises(InputError, match=rf"s1_readings\.csv, line 3, {message}"):
        measurement.read_session(path)


def test_inline_rows_report_lines_of_the_toml_file(tmp_path):
    text = (
        (EXAMPLES / "s0_direct.toml")
        .read_text()
        .replace("T5, 90, 2.0, , 2500, ", "T5, 95, 2.0, , 2500, ")
    )
    (tmp_path / "s0.toml").write_text(text)
    line = line_of(text, "T5, 95, 2.0")
    with pytest.raises(
        InputError,
        match=rf"s0\.toml, line {line} \(row 17\), field 'tilt': must be in \[0, 90\] \[deg\], got 95",
    ):
        measurement.read_session(tmp_path / "s0.toml")


@pytest.mark.parametrize(
    "old, new, field, message",
    [
        ('catalog = "18"', 'catalog = "no-such"', "bearing.catalog", "unknown name 'no-such'"),
        (
            '[rig]\ntare_mass = "0 kg"',
            '[rig]\ntare_mass = "-1 kg"',
            "rig.tare_mass",
            r"must be >= 0 \[kg\]",
        ),
        ('gravity = "9.81 m/s^2"', 'gravity = "9.81 m"', "rig.gravity", "expected an acceleration"),
        ("[session]\ntitle", '[session]\ntitel = ""\ntitle', "session.titel", "unknown field"),
        ('unit = "rpm"', 'unit = "N"', "calibration.speed.unit", "is a force, expected a speed"),
        (
            'format = "bearinglab-friction-session/1"',
            'format = "other/2"',
            "format",
            "unknown format",
        ),
        ('file = "s1_readings.csv"', 'file = "missing.csv"', "measurements.file", "no such file"),
    ],
)
def test_bad_session_fields_name_file_line_and_field(old, new, field, message, tmp_path):
    text = S1_TEXT.replace(old, new, 1)
    assert text != S1_TEXT
    path = write_session(tmp_path, toml=text)
    line = line_of(text, new.splitlines()[-1] if field != "session.titel" else "titel")
    with pytest.raises(InputError, match=rf"s\.toml, line {line}, field '{field}': .*{message}"):
        measurement.read_session(path)


def test_inline_bearing_and_handbook_overrides(tmp_path):
    text = S1_TEXT.replace(
        'catalog = "18"',
        'designation = "my-18"\ntype = "radial"\nbore = "8 mm"\n'
        'mean_diameter = "13.5 mm"\nstatic_load_rating = "1354 N"',
    )
    text = text.replace("[rig]", "[handbook]\nmu = 0.002\nf = 0.001\n\n[rig]")
    s = measurement.read_session(write_session(tmp_path, toml=text))
    assert s.bearing.designation == "my-18" and s.bearing.outside_diameter == pytest.approx(
        19e-3, rel=1e-14
    )
    assert s.handbook.reduced_friction_coefficient == 0.002 and s.handbook.load_term_factor == 0.001
    assert s.handbook.radial_factor == 0.6 and s.handbook.overridden == ("mu", "f")
    base = analysis.analyse(measurement.read_session(EXAMPLES / "s1_readings.toml"))
    r = analysis.analyse(s)
    assert_allclose(
        r.task1.reduced_friction_coefficient, base.task1.reduced_friction_coefficient, rtol=1e-12
    )
    assert_allclose(
        r.task1.relative_to_handbook + 1,
        (base.task1.relative_to_handbook + 1) * 0.0015 / 0.002,
        rtol=1e-12,
    )


def test_angular_bearing_outside_table1_needs_x0_y0(tmp_path):
    text = S1_TEXT.replace(
        'catalog = "18"',
        'type = "angular"\ncontact_angle = "27 deg"\nbore = "8 mm"\n'
        'outside_diameter = "19 mm"\nstatic_load_rating = "1354 N"',
    )
    path = write_session(tmp_path, toml=text)
    line = line_of(text, "contact_angle")
    with pytest.raises(
        InputError,
        match=rf"line {line}, field 'bearing\.contact_angle': contact_angle must be one of "
        r"the Table 1 or ISO 76 angles .* or give x0 and y0 in \[handbook\]",
    ):
        measurement.read_session(path)
    s = measurement.read_session(
        write_session(
            tmp_path, toml=text.replace("[rig]", "[handbook]\nx0 = 0.5\ny0 = 0.4\n\n[rig]")
        )
    )
    assert (s.handbook.radial_factor, s.handbook.axial_factor) == (0.5, 0.4)
    assert (s.handbook.load_term_factor, s.handbook.load_term_exponent) == (
        0.0010,
        0.33,
    )  # alpha < 30 deg
    assert s.handbook.reduced_friction_coefficient == 0.0020

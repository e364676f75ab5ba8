"""The friction-rig lab (bearinglab.lab): rig loads, calibration, least-squares tasks, the measurement
file (validation with file, line and field) and the analysis of a session."""

import hashlib
import math
from pathlib import Path

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from numpy.testing import assert_allclose
from scipy import stats

from bearinglab import friction
from bearinglab.errors import InputError
from bearinglab.lab import analysis, calibration, fits, measurement, rig

DATA = Path(__file__).resolve().parent / "data"
EXAMPLES = Path(__file__).resolve().parent.parent / "examples" / "friction"
RPM = 2 * math.pi / 60
FAST = settings(max_examples=40, deadline=None)


# ----------------------------------------------------------------------------- rig
def test_vanishing_load_component_is_exactly_zero():
    fa, fr = rig.rig_loads(2.0, math.radians(90.0))
    assert fa == 0.0 and fr == 2 * 9.81
    fa, fr = rig.rig_loads(2.0, 0.0)
    assert fr == 0.0 and fa == 2 * 9.81
    fa, fr = rig.rig_loads([0.5, 1.0], np.radians([90.0, 0.0]))
    assert fa[0] == 0.0 and fr[1] == 0.0


@FAST
@given(q=st.floats(0.01, 50.0), beta=st.floats(0.0, 90.0), tare=st.floats(0.0, 2.0))
def test_rig_loads_resolve_the_weight(q, beta, tare):
    fa, fr = rig.rig_loads(q, math.radians(beta), tare_mass=tare)
    assert math.hypot(fa, fr) == pytest.approx(9.81 * (q + tare), rel=1e-12)
    assert fa >= 0 and fr >= 0
    p = rig.rig_equivalent_load(q, math.radians(beta), tare_mass=tare)
    assert p.equivalent_load == friction.equivalent_static_load(fr, fa)
    switch = math.degrees(rig.branch_switch_tilt())
    if abs(beta - switch) > 1e-9:  # the two branches are equal at the switch itself
        assert bool(p.combined) == (beta < switch)


def test_tare_and_gravity_options():
    assert rig.rig_loads(1.0, math.pi / 2, tare_mass=0.25).radial_load == pytest.approx(
        1.25 * 9.81, rel=1e-15
    )
    assert rig.rig_loads(1.0, math.pi / 2, gravity=9.80665).radial_load == 9.80665
    with pytest.raises(InputError, match=r"tare_mass must be >= 0 \[kg\]"):
        rig.rig_loads(1.0, 0.0, tare_mass=-0.1)


def test_rig_rejects_zero_mass_and_tilt_outside_0_90():
    # spec 001 section 10.3: Q = 0 or beta = 95 -> error
    with pytest.raises(InputError, match=r"mass must be > 0 \[kg\], got 0\.0"):
        rig.rig_loads(0.0, 0.0)
    with pytest.raises(InputError, match=r"tilt must be in \[0, 90\] \[deg\], got 95\.0"):
        rig.rig_loads(1.0, math.radians(95.0))
    with pytest.raises(InputError, match=r"tilt must be in \[0, 90\] \[deg\], got -1\.0"):
        rig.rig_equivalent_load(1.0, math.radians(-1.0))


def test_branch_switch_tilt_errors_and_angular_rows():
    with pytest.raises(InputError, match="radial_factor must be < 1"):
        rig.branch_switch_tilt(1.0, 0.5)
    p = rig.rig_equivalent_load(
        1.0, 0.0, gravity=1.0, bearing_type="angular", contact_angle=math.radians(26)
    )
    assert p.equivalent_load == pytest.approx(0.37, rel=1e-15)


# ----------------------------------------------------------------------------- calibration
def test_calibration_table_checks():
    with pytest.raises(InputError, match="needs at least 2 points, got 1") as exc:
        calibration.calibration_table([0.0], [0.0], name="speed")
    assert exc.value.point is None
    with pytest.raises(
        InputError,
        match=r"values must be strictly increasing .* point 3 \(reading 20\) has 0.5 after 0.5",
    ) as exc:
        calibration.calibration_table(
            [0, 10, 20], [0.0, 0.5, 0.5], name="torque position 1", unit="N*m"
        )
    assert exc.value.point == 2
    with pytest.raises(InputError, match=r"readings must be strictly increasing .* point 2") as exc:
        calibration.calibration_table([0, 0, 20], [0.0, 0.5, 0.7])
    assert exc.value.point == 1
    with pytest.raises(InputError, match="3 readings but 2 values"):
        calibration.calibration_table([0, 1, 2], [0, 1])
    with pytest.raises(InputError, match="values must be finite"):
        calibration.calibration_table([0, 1], [0, float("nan")])


def test_piecewise_linear_conversion_without_extrapolation():
    t = calibration.calibration_table([0, 10, 20, 30], [0.0, 455.0, 920.0, 1395.0], name="speed")
    assert (
        calibration.convert(0.0, t) == 0.0 and calibration.convert(30.0, t) == 1395.0
    )  # table ends are valid
    assert calibration.convert(15.0, t) == pytest.approx(687.5, rel=1e-15)
    assert_allclose(calibration.convert([5.0, 25.0], t), [227.5, 1157.5], rtol=1e-15)
    # spec 001 section 10.3: a reading of 101 with a 0-100 table is an error
    t100 = calibration.calibration_table([0, 100], [0.0, 1.0], name="torque position 2")
    with pytest.raises(
        InputError, match=r"torque position 2 reading must be in \[0, 100\] .*got 101\.0"
    ):
        calibration.convert(101.0, t100)
    with pytest.raises(InputError, match=r"got -0\.5 \(1 of 2 values\)"):
        calibration.convert([1.0, -0.5], t100)


@FAST
@given(a=st.floats(0.0, 1.0), k=st.integers(0, 9))
def test_conversion_is_linear_between_points_and_monotonic(a, k):
    readings = np.arange(0.0, 101.0, 10.0)
    values = np.array([0, 455, 920, 1395, 1880, 2375, 2880, 3395, 3920, 4455, 5000.0])
    t = calibration.calibration_table(readings, values)
    r = readings[k] + a * 10.0
    assert calibration.convert(r, t) == pytest.approx(
        values[k] + a * (values[k + 1] - values[k]), rel=1e-12, abs=1e-12
    )
    assert calibration.convert(min(r + 0.1, 100.0), t) >= calibration.convert(r, t)


def test_convert_torque_by_switch_position():
    t1 = calibration.calibration_table([0, 100], [0.0, 1.2e-4], name="torque position 1")
    t2 = calibration.calibration_table([0, 100], [0.0, 5.0e-4], name="torque position 2")
    cal = calibration.Calibration(None, {1: t1, 2: t2})
    assert_allclose(
        calibration.convert_torque([50.0, 50.0, 100.0], [1, 2, 1], cal),
        [6e-5, 2.5e-4, 1.2e-4],
        rtol=1e-15,
    )
    with pytest.raises(InputError, match=r"switch position must be 1 or 2 \[-\], got 3\.0"):
        calibration.convert_torque(10.0, 3, cal)
    with pytest.raises(InputError, match="need the torque calibration table of position 2"):
        calibration.convert_torque(10.0, 2, calibration.Calibration(None, {1: t1}))


# ----------------------------------------------------------------------------- fits
def test_straight_line_matches_scipy_linregress_with_standard_errors():
    rng = np.random.default_rng(1)
    x = np.linspace(1.0, 9.0, 7)
    y = 0.3 + 1.7 * x + rng.normal(0, 0.05, x.size)
    got = fits.straight_line(x, y)
    ref = stats.linregress(x, y)
    assert got.slope == pytest.approx(ref.slope, rel=1e-12)
    assert got.intercept == pytest.approx(ref.intercept, rel=1e-12)
    assert got.slope_standard_error == pytest.approx(ref.stderr, rel=1e-10)
    assert got.intercept_standard_error == pytest.approx(ref.intercept_stderr, rel=1e-10)
    assert got.residual_rms == pytest.approx(np.sqrt(np.mean(got.residuals**2)), rel=1e-15)
    assert got.count == 7


def test_through_origin_standard_error_and_residuals():
    x = np.array([1.0, 2.0, 4.0])
    y = np.array([2.1, 3.9, 8.2])
    got = fits.through_origin(x, y)
    k = (x * y).sum() / (x * x).sum()
    r = y - k * x
    assert got.slope == pytest.approx(k, rel=1e-15)
    assert got.slope_standard_error == pytest.approx(
        np.sqrt((r**2).sum() / 2 / (x * x).sum()), rel=1e-13
    )
    assert_allclose(got.residuals, r, rtol=1e-13)


def test_standard_errors_are_nan_without_redundancy():
    line = fits.straight_line([1.0, 2.0], [1.0, 3.0])
    assert (
        line.slope == 2.0
        and math.isnan(line.slope_standard_error)
        and math.isnan(line.intercept_standard_error)
    )
    one = fits.through_origin([2.0], [4.0])
    assert one.slope == 2.0 and math.isnan(one.slope_standard_error) and one.residual_rms == 0.0


def test_grouped_fits_equal_fits_one_group_at_a_time():
    rng = np.random.default_rng(7)
    groups = np.repeat(["b", "a", "c"], [4, 5, 3])
    x = rng.uniform(1, 10, groups.size)
    y = 2.0 + 0.5 * x + rng.normal(0, 0.1, x.size)
    got = fits.straight_line(x, y, groups=groups)
    for k, label in enumerate(["a", "b", "c"]):  # ordered like numpy.unique
        one = fits.straight_line(x[groups == label], y[groups == label])
        for field in (
            "slope",
            "intercept",
            "slope_standard_error",
            "intercept_standard_error",
            "residual_rms",
        ):
            assert getattr(got, field)[k] == pytest.approx(getattr(one, field), rel=1e-12), field
        assert_allclose(got.residuals[groups == label], one.residuals, rtol=1e-10, atol=1e-15)


def test_degenerate_groups_are_errors_naming_the_group():
    # spec 001 section 10.3: a task 2 group with all speeds equal -> error
    with pytest.raises(
        InputError,
        match=r"task 2: group 1 needs at least two distinct values of shaft_speed, "
        r"got 3 point\(s\) all at 1500 rpm",
    ) as exc:
        fits.speed_dependence(
            [1e-5, 2e-5, 3e-5, 1e-5, 2e-5, 3e-5],
            np.array([500, 1000, 1500, 1500, 1500, 1500]) * RPM,
            9e-3,
            groups=[0, 0, 0, 1, 1, 1],
        )
    assert exc.value.group == 1
    with pytest.raises(
        InputError, match="task 3: the data needs at least two distinct values of equivalent_load"
    ):
        fits.load_dependence([1e-5, 2e-5], [5.0, 5.0], 9e-3, 392.0)
    with pytest.raises(InputError, match="task 1: the data has all equivalent_load = 0"):
        fits.friction_coefficient([1e-5, 2e-5], [0.0, 0.0], 5e-3)
    with pytest.raises(InputError, match="groups must label every point"):
        fits.straight_line([1, 2, 3], [1, 2, 3], groups=[0, 1])


generating = {
    "f0": st.floats(5e-8, 2e-6),
    "f": st.floats(2e-4, 5e-3),
    "dm": st.floats(5e-3, 0.1),
    "c0": st.floats(1e3, 1e5),
    "p0": st.floats(0.5, 90.0),
    "n": st.floats(100.0, 2e4),
    "spread": st.floats(1.2, 6.0),
    "m": st.integers(2, 8),
}


@FAST
@given(**generating)
def test_noiseless_two_term_data_recovered_by_task2(f0, f, dm, c0, p0, n, spread, m):
    speeds = np.geomspace(n, n * spread, m) * RPM
    t = friction.two_term(p0, speeds, dm, c0, f0, load_term_factor=f)
    got = fits.speed_dependence(t.torque, speeds, dm)
    assert got.speed_term_factor == pytest.approx(f0, rel=1e-9)
    assert got.load_term == pytest.approx(float(t.load_term[0]), rel=1e-9)
    assert got.residual_rms <= 1e-9 * float(t.torque.max())


@FAST
@given(**generating)
def test_noiseless_two_term_data_recovered_by_task3(f0, f, dm, c0, p0, n, spread, m):
    loads = np.geomspace(p0, p0 * spread, m)
    t = friction.two_term(loads, n * RPM, dm, c0, f0, load_term_factor=f)
    # the fit can only see f through the spread of T_F between the points: where that spread is below
    # 1e-6 of the torque, rounding alone limits f to ~1e-10 / 1e-6 relative (a well-posed case only)
    assume(np.ptp(t.load_term) > 1e-6 * float(np.max(t.torque)))
    got = fits.load_dependence(t.torque, loads, dm, c0, load_term_exponent=0.55)
    assert got.load_term_factor == pytest.approx(f, rel=1e-9)
    assert got.speed_term == pytest.approx(float(t.speed_term[0]), rel=1e-9)


@FAST
@given(mu=st.floats(1e-4, 1e-2), d=st.floats(1e-3, 0.1), m=st.integers(1, 6))
def test_noiseless_one_term_data_recovered_by_task1(mu, d, m):
    p0 = np.linspace(1.0, 30.0, m)
    t = friction.one_term(p0, d, friction_coefficient=mu)
    got = fits.friction_coefficient(t, p0, d)
    assert got.friction_coefficient == pytest.approx(mu, rel=1e-12)
    assert got.residual_rms <= 1e-12 * float(np.max(t))


# ----------------------------------------------------------------------------- measurement file
S1_TEXT = (EXAMPLES / "s1_readings.toml").read_text()
S1_ROWS = (EXAMPLES / "s1_readings.csv").read_text()


def _session(tmp_path, toml=S1_TEXT, rows=S1_ROWS):
    (tmp_path / "s.toml").write_text(toml)
    (tmp_path / "s1_readings.csv").write_text(rows)
    return tmp_path / "s.toml"


def _line_of(text, needle):
    return next(i for i, line in enumerate(text.splitlines(), 1) if needle in line)


def test_example_files_are_read_and_never_modified(tmp_path):
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
    path = _session(tmp_path, toml=text)
    line = _line_of(text, "[40, 0.0318],")
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
    line = _line_of(text, "points = [[0, 0], [10, 5], [20, 4]]")
    with pytest.raises(
        InputError,
        match=rf"s\.toml, line {line}, field 'calibration\.speed\.points': calibration speed: "
        r"values must be strictly increasing \[rpm\], point 3 \(reading 20\) has 4 after 5",
    ):
        measurement.read_session(_session(tmp_path, toml=text))


def test_calibration_point_that_is_not_a_pair(tmp_path):
    text = S1_TEXT.replace("[30, 1395],", "[30, 1395, 7],")
    line = _line_of(text, "[30, 1395, 7],")
    with pytest.raises(
        InputError,
        match=rf"line {line}, field 'calibration\.speed\.points': point 4 must be \[reading, value\]",
    ):
        measurement.read_session(_session(tmp_path, toml=text))


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
def test_bad_rows_name_file_line_and_field(tmp_path, old, new, field, message):
    rows = S1_ROWS.replace(old, new)
    path = _session(tmp_path, rows=rows)
    line = _line_of(rows, new)
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
    path = _session(tmp_path, rows=rows)
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
def test_bad_csv_headers(tmp_path, old, new, message):
    rows = S1_ROWS.replace(old, new, 1)
    path = _session(tmp_path, rows=rows)
    with pytest.raises(InputError, match=rf"s1_readings\.csv, line 3, {message}"):
        measurement.read_session(path)


def test_inline_rows_report_lines_of_the_toml_file(tmp_path):
    text = (
        (EXAMPLES / "s0_direct.toml")
        .read_text()
        .replace("T5, 90, 2.0, , 2500, ", "T5, 95, 2.0, , 2500, ")
    )
    (tmp_path / "s0.toml").write_text(text)
    line = _line_of(text, "T5, 95, 2.0")
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
def test_bad_session_fields_name_file_line_and_field(tmp_path, old, new, field, message):
    text = S1_TEXT.replace(old, new, 1)
    assert text != S1_TEXT
    path = _session(tmp_path, toml=text)
    line = _line_of(text, new.splitlines()[-1] if field != "session.titel" else "titel")
    with pytest.raises(InputError, match=rf"s\.toml, line {line}, field '{field}': .*{message}"):
        measurement.read_session(path)


def test_inline_bearing_and_handbook_overrides(tmp_path):
    text = S1_TEXT.replace(
        'catalog = "18"',
        'designation = "my-18"\ntype = "radial"\nbore = "8 mm"\n'
        'mean_diameter = "13.5 mm"\nstatic_load_rating = "1354 N"',
    )
    text = text.replace("[rig]", "[handbook]\nmu = 0.002\nf = 0.001\n\n[rig]")
    s = measurement.read_session(_session(tmp_path, toml=text))
    assert s.bearing.designation == "my-18" and s.bearing.outside_diameter == pytest.approx(
        19e-3, rel=1e-14
    )
    assert s.handbook.friction_coefficient == 0.002 and s.handbook.load_term_factor == 0.001
    assert s.handbook.radial_factor == 0.6 and s.handbook.overridden == ("mu", "f")
    base = analysis.analyse(measurement.read_session(EXAMPLES / "s1_readings.toml"))
    r = analysis.analyse(s)
    assert_allclose(r.task1.friction_coefficient, base.task1.friction_coefficient, rtol=1e-12)
    assert_allclose(
        r.task1.relative_to_handbook + 1,
        (base.task1.relative_to_handbook + 1) * 0.0015 / 0.002,
        rtol=1e-12,
    )


def test_angular_bearing_outside_table1_needs_x0_y0(tmp_path):
    text = S1_TEXT.replace(
        'catalog = "18"',
        'type = "angular"\ncontact_angle = "25 deg"\nbore = "8 mm"\n'
        'outside_diameter = "19 mm"\nstatic_load_rating = "1354 N"',
    )
    path = _session(tmp_path, toml=text)
    line = _line_of(text, "contact_angle")
    with pytest.raises(
        InputError,
        match=rf"line {line}, field 'bearing\.contact_angle': contact_angle must be one of "
        r"the Table 1 angles .* or give x0 and y0 in \[handbook\]",
    ):
        measurement.read_session(path)
    s = measurement.read_session(
        _session(tmp_path, toml=text.replace("[rig]", "[handbook]\nx0 = 0.5\ny0 = 0.4\n\n[rig]"))
    )
    assert (s.handbook.radial_factor, s.handbook.axial_factor) == (0.5, 0.4)
    assert (s.handbook.load_term_factor, s.handbook.load_term_exponent) == (
        0.0010,
        0.33,
    )  # alpha < 30 deg
    assert s.handbook.friction_coefficient == 0.0020


def test_template_is_valid_and_stops_at_what_is_missing(tmp_path):
    text = measurement.template()
    path = tmp_path / "new.toml"
    path.write_text(text)
    with pytest.raises(
        InputError, match=r"new\.toml, line \d+, field 'bearing\.bore': is empty; fill it in"
    ):
        measurement.read_session(path)
    text18 = measurement.template(bearing="18")
    assert 'catalog = "18"' in text18 and "C0 = 1354 N" in text18
    path.write_text(text18)
    header = _line_of(text18, "series, tilt [deg]")
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
    assert any("No T4 rows" in c for c in analysis.conclusions(r))


def test_write_template_is_atomic_and_does_not_overwrite(tmp_path):
    path = measurement.write_template(tmp_path / "a.toml", bearing="101")
    assert 'catalog = "101"' in path.read_text()
    path.write_text("my data")
    with pytest.raises(InputError, match="file exists"):
        measurement.write_template(path)
    assert path.read_text() == "my data"
    measurement.write_template(path, overwrite=True)
    assert "[calibration.speed]" in path.read_text()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.toml"]  # no temporary file left


# ----------------------------------------------------------------------------- analysis
def test_task2_group_with_equal_speeds_names_its_lines(tmp_path):
    # spec 001 section 10.3 through the file: every beta = 0 row at the same speed reading
    rows = (
        "\n".join(
            line.replace(line.split(",")[4], " 31.5") if line.startswith("T5,  0") else line
            for line in S1_ROWS.splitlines()
        )
        + "\n"
    )
    path = _session(tmp_path, rows=rows)
    s = measurement.read_session(path)
    lines = ", ".join(str(n) for n in range(_line_of(rows, "T5,  0"), _line_of(rows, "T5,  0") + 6))
    with pytest.raises(
        InputError,
        match=rf"s1_readings\.csv, lines {lines} \(Table 5 column tilt 0 deg, Q = 2 kg\), "
        r"field 'speed_reading': task 2 needs at least two distinct speeds, got 6 row\(s\) "
        r"all at 1467\.75 rpm",
    ):
        analysis.analyse(s)


def test_task3_group_with_one_load_is_an_error(tmp_path):
    rows = S1_ROWS.replace("T4, 45, 1.0, A", "T4, 45, 0.5, A").replace(
        "T4, 45, 2.0, A", "T4, 45, 0.5, A"
    )
    s = measurement.read_session(_session(tmp_path, rows=rows))
    with pytest.raises(
        InputError,
        match=r"lines 5, 6, 7 \(Table 4 column 'A' at tilt 45 deg\), field 'mass': task 3 "
        r"needs at least two distinct loads P0",
    ):
        analysis.analyse(s)


def test_tare_mass_changes_the_loads_not_the_torques(tmp_path):
    text = S1_TEXT.replace('tare_mass = "0 kg"', 'tare_mass = "0.25 kg"')
    r = analysis.analyse(measurement.read_session(_session(tmp_path, toml=text)))
    base = analysis.analyse(measurement.read_session(EXAMPLES / "s1_readings.toml"))
    assert_allclose(r.rows.torque, base.rows.torque, rtol=0)
    assert_allclose(
        r.rows.equivalent_load,
        base.rows.equivalent_load * (r.session.rows.mass + 0.25) / r.session.rows.mass,
        rtol=1e-12,
    )


def test_negative_intercepts_are_reported_and_flagged(tmp_path):
    # torque falling with speed at beta = 0 makes T_F extrapolate above, so use a steep rise instead:
    rows = S1_ROWS.replace("T5,  0, 2.0, , 11.0, 33.5, 1,", "T5,  0, 2.0, , 11.0, 5.0, 1,")
    r = analysis.analyse(measurement.read_session(_session(tmp_path, rows=rows)))
    assert r.task2.load_term[0] < 0
    d = analysis.to_dict(r)
    assert d["task2"][0]["negative_intercept"] is True
    assert any(c.startswith("Warning: T_F at β = 0°") for c in d["conclusions"])


def test_tables_4_and_5_layout():
    r = analysis.analyse(measurement.read_session(EXAMPLES / "s1_readings.toml"))
    (t4,) = analysis.table4(r)
    assert t4.name == "table4_tilt45" and len(t4.rows) == 3 and len(t4.columns) == 2 + 2 * 5
    assert [row[0] for row in t4.rows] == [0.5, 1.0, 2.0]
    assert t4.rows[2][-2:] == [
        2,
        pytest.approx(0.0975, abs=1e-12),
    ]  # switch 2 at Q = 2 kg, column B
    (t5,) = analysis.table5(r)
    assert t5.name == "table5_Q2kg" and len(t5.rows) == 6 and len(t5.columns) == 2 + 2 * 3
    assert [row[1] for row in t5.rows] == pytest.approx(
        [501.5, 991.25, 1467.75, 1929.5, 2375.0, 2829.5]
    )
    assert "P0 = 16.9914 N" in t5.columns[-1]
    rows = analysis.rows_table(r)
    assert len(rows.rows) == 18 and rows.rows[0][-1] == "x0·Fr + y0·Fa"


def test_plot_lines_start_at_zero_and_reach_1_1_of_the_largest_abscissa():
    r = analysis.analyse(measurement.read_session(EXAMPLES / "s1_readings.toml"))
    plots = analysis.plots(r)
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
    import json

    d = analysis.to_dict(analysis.analyse(measurement.read_session(EXAMPLES / "s1_readings.toml")))
    text = json.dumps(d, allow_nan=False)
    assert json.loads(text)["format"] == analysis.RESULTS_FORMAT
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


def test_benchmark_paths_agree_on_a_small_input(load_bench):
    bench = load_bench("friction_fits")
    t, speed, groups = bench.cases(20, seed=3)
    f0, tf = bench.batched(t, speed, groups)
    f0_ref, tf_ref = bench.baseline(t, speed, 20)
    assert_allclose(f0, f0_ref, rtol=1e-10)
    assert_allclose(tf, tf_ref, rtol=1e-9)


def test_task1_group_whose_p0_are_all_zero_is_an_error(tmp_path):
    # y0 = 0 makes P0 = max(x0 Fr, Fr) = 0 under pure axial load (beta = 0): spec 001 section 9
    text = S1_TEXT.replace("[rig]", "[handbook]\ny0 = 0.0\n\n[rig]")
    rows = S1_ROWS.replace("T4, 45,", "T4, 0,")
    s = measurement.read_session(_session(tmp_path, toml=text, rows=rows))
    assert s.handbook.axial_factor == 0.0 and s.handbook.overridden == ("y0",)
    with pytest.raises(
        InputError,
        match=r"lines 5, 6, 7 \(Table 4 column 'A' at tilt 0 deg\), field 'mass': task 1: all P0 are zero",
    ):
        analysis.analyse(s)

"""Analysis of a session (bearinglab.lab.analysis): groups that cannot be fitted, tare mass, deprecated names."""

import pytest
from lab_sessions import EXAMPLES, S1_ROWS, S1_TEXT, line_of, write_session
from numpy.testing import assert_allclose

from bearinglab.errors import InputError
from bearinglab.lab import analysis, measurement


def test_task2_group_with_equal_speeds_names_its_lines(tmp_path):
    # spec 001 section 10.3 through the file: every beta = 0 row at the same speed reading
    rows = (
        "\n".join(
            line.replace(line.split(",")[4], " 31.5") if line.startswith("T5,  0") else line
            for line in S1_ROWS.splitlines()
        )
        + "\n"
    )
    path = write_session(tmp_path, rows=rows)
    s = measurement.read_session(path)
    lines = ", ".join(str(n) for n in range(line_of(rows, "T5,  0"), line_of(rows, "T5,  0") + 6))
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
    s = measurement.read_session(write_session(tmp_path, rows=rows))
    with pytest.raises(
        InputError,
        match=r"lines 5, 6, 7 \(Table 4 column 'A' at tilt 45 deg\), field 'mass': task 3 "
        r"needs at least two distinct loads P0",
    ):
        analysis.analyse(s)


def test_task1_group_whose_p0_are_all_zero_is_an_error(tmp_path):
    # y0 = 0 makes P0 = max(x0 Fr, Fr) = 0 under pure axial load (beta = 0): spec 001 section 9
    text = S1_TEXT.replace("[rig]", "[handbook]\ny0 = 0.0\n\n[rig]")
    rows = S1_ROWS.replace("T4, 45,", "T4, 0,")
    s = measurement.read_session(write_session(tmp_path, toml=text, rows=rows))
    assert s.handbook.axial_factor == 0.0 and s.handbook.overridden == ("y0",)
    with pytest.raises(
        InputError,
        match=r"lines 5, 6, 7 \(Table 4 column 'A' at tilt 0 deg\), field 'mass': task 1: all P0 are zero",
    ):
        analysis.analyse(s)


def test_tare_mass_changes_the_loads_not_the_torques(tmp_path):
    text = S1_TEXT.replace('tare_mass = "0 kg"', 'tare_mass = "0.25 kg"')
    r = analysis.analyse(measurement.read_session(write_session(tmp_path, toml=text)))
    base = analysis.analyse(measurement.read_session(EXAMPLES / "s1_readings.toml"))
    assert_allclose(r.rows.torque, base.rows.torque, rtol=0)
    assert_allclose(
        r.rows.equivalent_load,
        base.rows.equivalent_load * (r.session.rows.mass + 0.25) / r.session.rows.mass,
        rtol=1e-12,
    )


def test_task1_old_field_name_warns():
    r = analysis.analyse(measurement.read_session(EXAMPLES / "s1_readings.toml"))
    with pytest.warns(DeprecationWarning, match="Task1.friction_coefficient is deprecated"):
        old = r.task1.friction_coefficient
    assert old is r.task1.reduced_friction_coefficient
    with pytest.warns(DeprecationWarning, match="Handbook.friction_coefficient is deprecated"):
        assert r.session.handbook.friction_coefficient == 0.0015

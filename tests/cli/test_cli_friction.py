"""Command line of the friction capability: ``friction torque``, ``friction lab``, ``friction template``,
and every negative case of spec 001 section 10.3 through both the command line and Python."""

import json
import math
import re
from pathlib import Path

import numpy as np
import pytest

from bearinglab import friction
from bearinglab.cli import main
from bearinglab.errors import InputError
from bearinglab.lab import analysis, calibration, fits, measurement, rig

EXAMPLES = Path(__file__).resolve().parents[2] / "examples" / "friction"
RPM = 2 * math.pi / 60


def run(capsys, *args):
    code = main([str(a) for a in args])
    out, err = capsys.readouterr()
    return code, out, err


def one_line_error(code, err):
    assert code == 2, err
    assert "Traceback" not in err
    assert err.count("\n") == 1 and err.startswith("bearinglab: error: ")
    return err


# ----------------------------------------------------------------------------- friction torque
def test_torque_json_of_the_issue_example(capsys):
    code, out, err = run(
        capsys,
        "friction",
        "torque",
        "--bearing",
        "101",
        "--radial-load",
        "10 N",
        "--axial-load",
        "5 N",
        "--speed",
        "3000 rpm",
        "--json",
    )
    assert code == 0, err
    d = json.loads(out)
    assert {
        "equivalent_static_load_N",
        "torque_Nmm",
        "torque_speed_term_Nmm",
        "torque_load_term_Nmm",
    } <= set(d)
    assert d["equivalent_static_load_N"] == 10.0  # max(0.6*10 + 0.5*5, 10)
    assert d["branch"] == "Fr" and d["model"] == "one-term"
    assert d["torque_Nmm"] == pytest.approx(0.0015 * 10 * 12 / 2, rel=1e-14)
    # the one-term model has no speed term: all of its torque depends on the load
    assert d["torque_speed_term_Nmm"] == 0.0 and d["torque_load_term_Nmm"] == d["torque_Nmm"]
    assert d["speed_rpm"] == 3000.0


def test_torque_two_term_and_palmgren_equal_the_python_functions(capsys):
    code, out, _ = run(
        capsys,
        "friction",
        "torque",
        "-b",
        "101",
        "-R",
        "10 N",
        "-A",
        "5 N",
        "-n",
        "3000 rpm",
        "--model",
        "two-term",
        "--f0",
        "2e-7",
        "--json",
    )
    d = json.loads(out)
    t = friction.two_term(10.0, 3000 * RPM, 20e-3, 2227.0, 2e-7)
    assert code == 0
    assert d["torque_speed_term_Nmm"] == pytest.approx(t.speed_term * 1e3, rel=1e-12)
    assert d["torque_load_term_Nmm"] == pytest.approx(t.load_term * 1e3, rel=1e-12)
    assert d["torque_Nmm"] == pytest.approx(t.torque * 1e3, rel=1e-12)
    code, out, _ = run(
        capsys,
        "friction",
        "torque",
        "-b",
        "101",
        "-R",
        "10 N",
        "-A",
        "5 N",
        "-n",
        "3000 rpm",
        "--model",
        "palmgren",
        "--viscosity",
        "20 cSt",
        "--palmgren-f0",
        "2",
        "--json",
    )
    d = json.loads(out)
    assert code == 0
    assert d["torque_speed_term_Nmm"] == pytest.approx(
        friction.palmgren(20e-6, 3000 * RPM, 20e-3, 2.0) * 1e3, rel=1e-12
    )
    assert d["equivalent_f0"] == pytest.approx(1e-7 * 2 * 20 ** (2 / 3), rel=1e-12)


def test_torque_lists_overrides_and_inline_bearing(capsys):
    code, out, _ = run(
        capsys,
        "friction",
        "torque",
        "--type",
        "radial",
        "--bore",
        "8 mm",
        "--mean-diameter",
        "13.5 mm",
        "--static-load-rating",
        "1354 N",
        "-R",
        "0N:20N:10N",
        "-A",
        "10 N",
        "--mu",
        "0.003",
        "--json",
    )
    d = json.loads(out)
    assert code == 0 and len(d["cases"]) == 3 and d["mu"] == 0.003
    assert [c["equivalent_static_load_N"] for c in d["cases"]] == pytest.approx([5.0, 11.0, 20.0])
    assert [c["branch"] for c in d["cases"]] == ["x0*Fr+y0*Fa", "x0*Fr+y0*Fa", "Fr"]
    assert d["cases"][2]["torque_Nmm"] == pytest.approx(0.003 * 20 * 8 / 2, rel=1e-12)
    code, out, _ = run(
        capsys,
        "friction",
        "torque",
        "-b",
        "18",
        "-A",
        "1 kgf",
        "--x0",
        "0.5",
        "--y0",
        "1.0",
        "--json",
    )
    assert json.loads(out)["equivalent_static_load_N"] == pytest.approx(9.80665, rel=1e-12)


def test_torque_json_reports_one_override_with_the_other_tabulated_constant(capsys):
    code, out, _ = run(
        capsys, "friction", "torque", "-b", "18", "-R", "10 N", "--x0", "0.7", "--c", "0.5",
        "--model", "two-term", "--f0", "2e-7", "--json",
    )  # fmt: skip
    d = json.loads(out)
    assert code == 0
    assert (d["x0"], d["y0"]) == (0.7, friction.RADIAL_STATIC_FACTORS[1])
    assert (d["f"], d["c"]) == (friction.RADIAL_LOAD_TERM[0], 0.5)


def test_torque_human_output(capsys):
    code, out, _ = run(
        capsys,
        "friction",
        "torque",
        "-b",
        "1000095",
        "-R",
        "19.62 N",
        "-n",
        "3000 rpm",
        "--model",
        "two-term",
        "--f0",
        "2e-7",
    )
    assert code == 0
    assert (
        "0.0306098" in out and "0.0303276" in out and "…" not in out
    )  # T_F and T0 of spec 001 section 3.5


@pytest.mark.parametrize(
    "args, message",
    [
        (["-b", "101", "-R", "10 N", "--model", "two-term"], "f0: the two-term model needs --f0"),
        (
            ["-b", "101", "-R", "10 N", "--model", "three-term"],
            r"model must be one of \['one-term', 'two-term', 'palmgren', 'skf'\]",
        ),
        (["-b", "101", "-R", "10 m"], "radial-load: '10 m' is a length, expected a force"),
        (["-b", "101", "-R", "-10 N"], "radial-load must be >= 0"),
        (
            ["-b", "101", "--model", "palmgren", "--palmgren-f0", "2"],
            "viscosity: the palmgren model needs --viscosity",
        ),
        (
            ["--type", "angular", "--contact-angle", "27 deg", "--bore", "8 mm", "-R", "1 N"],
            "contact-angle must be one of the Table 1 or ISO 76 angles",
        ),
        (["-R", "1 N"], "bearing: give --bearing NAME"),
        (["-b", "nosuch", "-R", "1 N"], "unknown name 'nosuch'"),
        (["-b", "101", "-R", "1N,2N", "-A", "1N,2N,3N"], "lists are paired element by element \\(rows of a log\\) and must have the same length"),
    ],
)
def test_torque_bad_input_is_one_line(capsys, args, message):
    code, _, err = run(capsys, "friction", "torque", *args)
    assert re.search(message, one_line_error(code, err)), err


# ----------------------------------------------------------------------------- friction lab
def test_lab_json_keys_and_values(capsys, tmp_path):
    code, out, err = run(
        capsys,
        "friction",
        "lab",
        EXAMPLES / "s1_readings.toml",
        "--out",
        tmp_path / "rep",
        "--json",
    )
    assert code == 0, err
    d = json.loads(out)
    assert d["report"] == str(tmp_path / "rep" / "report.html") and Path(d["report"]).exists()
    assert all({"tilt_deg", "speed_rpm", "mu", "residual_rms_Nmm"} <= set(r) for r in d["task1"])
    assert all({"tilt_deg", "f0", "torque_load_term_Nmm"} <= set(r) for r in d["task2"])
    assert all({"speed_rpm", "f", "torque_speed_term_Nmm"} <= set(r) for r in d["task3"])
    assert [r["mu"] for r in d["task1"]] == pytest.approx(
        [1.434957683e-03, 1.950190711e-03], rel=1e-7
    )
    assert [r["f0"] for r in d["task2"]] == pytest.approx(
        [1.497504564e-07, 1.486076994e-07], rel=1e-7
    )
    assert [r["torque_speed_term_Nmm"] for r in d["task3"]] == pytest.approx(
        [4.692238912e-02, 7.186158852e-02], rel=1e-7
    )


def test_lab_human_output_and_no_report_without_out(capsys, tmp_path):
    code, out, _ = run(capsys, "friction", "lab", EXAMPLES / "s0_direct.toml")
    assert code == 0 and "No --out given: no report written." in out and "1.470209e-03" in out
    code, out, _ = run(capsys, "friction", "lab", EXAMPLES / "s0_direct.toml", "-o", tmp_path / "r")
    assert code == 0 and f"Report: {tmp_path / 'r' / 'report.html'}" in out.replace("\n", "")


def test_lab_missing_file_and_refused_directory(capsys, tmp_path):
    code, _, err = run(capsys, "friction", "lab", tmp_path / "nope.toml")
    assert "nope.toml: no such file" in one_line_error(code, err)
    (tmp_path / "keep").mkdir()
    (tmp_path / "keep" / "a.txt").write_text("x")
    code, _, err = run(
        capsys, "friction", "lab", EXAMPLES / "s0_direct.toml", "--out", tmp_path / "keep"
    )
    assert "is not a bearinglab report directory" in one_line_error(code, err)


# ----------------------------------------------------------------------------- friction template
def test_template_to_stdout_file_and_refusal(capsys, tmp_path):
    code, out, _ = run(capsys, "friction", "template", "--bearing", "18")
    assert code == 0 and 'catalog = "18"' in out and "[calibration.torque_2]" in out
    path = tmp_path / "session.toml"
    code, out, _ = run(capsys, "friction", "template", path)
    assert code == 0 and path.exists() and "bearinglab friction lab" in out
    path.write_text("my measurements")
    code, _, err = run(capsys, "friction", "template", path)
    assert "file exists" in one_line_error(code, err)
    assert path.read_text() == "my measurements"
    code, _, _ = run(capsys, "friction", "template", path, "--bearing", "101", "--force")
    assert code == 0 and 'catalog = "101"' in path.read_text()
    # a blank template stops at the first thing to fill in, naming file, line and field
    code, _, err = run(capsys, "friction", "lab", path, "--out", tmp_path / "r")
    assert re.search(
        r"session\.toml, line \d+, field 'measurements\.csv': no measurement rows",
        one_line_error(code, err),
    )
    assert not (tmp_path / "r").exists()


# ----------------------------------------------------------------------------- spec 001 section 10.3
S1_TEXT = (EXAMPLES / "s1_readings.toml").read_text()
S1_ROWS = (EXAMPLES / "s1_readings.csv").read_text()


def _bad_session(tmp_path, toml=S1_TEXT, rows=S1_ROWS):
    (tmp_path / "bad.toml").write_text(toml)
    (tmp_path / "s1_readings.csv").write_text(rows)
    return tmp_path / "bad.toml"


def _line(text, needle):
    return next(i for i, line in enumerate(text.splitlines(), 1) if needle in line)


def _t5_at_one_speed(rows):
    return (
        "\n".join(
            line.replace(line.split(",")[4], " 31.5") if line.startswith("T5,  0") else line
            for line in rows.splitlines()
        )
        + "\n"
    )


NEGATIVE = {
    "calibration value not increasing": {
        "toml": S1_TEXT.replace("[40, 0.0432],", "[40, 0.0318],"),
        "file": "bad.toml",
        "needle": "[40, 0.0318],",
        "field": "calibration.torque_1.points",
        "message": "values must be strictly increasing",
    },
    "torque reading 101": {
        "rows": S1_ROWS.replace("T4, 45, 2.0, B, 57.0, 23.0, 2,", "T4, 45, 2.0, B, 57.0, 101, 2,"),
        "file": "s1_readings.csv",
        "needle": "57.0, 101, 2",
        "field": "torque_reading",
        "message": r"101 is outside the calibrated range \[0, 100\]",
    },
    "task 2 speeds all equal": {
        "rows": _t5_at_one_speed(S1_ROWS),
        "file": "s1_readings.csv",
        "needle": "T5,  0",
        "field": "speed_reading",
        "message": "task 2 needs at least two distinct speeds",
    },
    "Q = 0": {
        "rows": S1_ROWS.replace("T5, 60, 2.0, , 41.0", "T5, 60, 0, , 41.0"),
        "file": "s1_readings.csv",
        "needle": "T5, 60, 0, ",
        "field": "mass",
        "message": r"must be > 0 \[kg\], got 0",
    },
    "beta = 95": {
        "rows": S1_ROWS.replace("T5, 60, 2.0, , 41.0", "T5, 95, 2.0, , 41.0"),
        "file": "s1_readings.csv",
        "needle": "T5, 95, ",
        "field": "tilt",
        "message": r"must be in \[0, 90\] \[deg\], got 95",
    },
}


@pytest.mark.parametrize("case", list(NEGATIVE), ids=list(NEGATIVE))
def test_negative_cases_through_the_cli(capsys, tmp_path, case):
    c = NEGATIVE[case]
    path = _bad_session(tmp_path, toml=c.get("toml", S1_TEXT), rows=c.get("rows", S1_ROWS))
    text = c.get("toml", S1_TEXT) if c["file"] == "bad.toml" else c.get("rows", S1_ROWS)
    line = _line(text, c["needle"])
    code, out, err = run(capsys, "friction", "lab", path, "--out", tmp_path / "report", "--json")
    err = one_line_error(code, err)
    assert out == ""
    assert re.search(
        rf"{re.escape(c['file'])}, lines? {line}\b.*field '{re.escape(c['field'])}': .*{c['message']}",
        err,
    ), err
    assert not (tmp_path / "report").exists()


@pytest.mark.parametrize("case", list(NEGATIVE), ids=list(NEGATIVE))
def test_negative_cases_through_python_files(tmp_path, case):
    c = NEGATIVE[case]
    path = _bad_session(tmp_path, toml=c.get("toml", S1_TEXT), rows=c.get("rows", S1_ROWS))
    with pytest.raises(
        InputError,
        match=rf"{re.escape(c['file'])}, lines? \d+.*field '{re.escape(c['field'])}': .*{c['message']}",
    ):
        analysis.analyse(measurement.read_session(path))


def test_negative_cases_through_python_functions():
    with pytest.raises(InputError, match="values must be strictly increasing"):
        calibration.calibration_table(
            [0, 10, 20, 30, 40], [0, 0.0102, 0.0208, 0.0318, 0.0318], name="torque position 1"
        )
    table = calibration.calibration_table(
        np.arange(0.0, 101.0, 10.0), np.linspace(0, 1.2e-4, 11), name="torque position 1"
    )
    with pytest.raises(
        InputError, match=r"torque position 1 reading must be in \[0, 100\] .*got 101\.0"
    ):
        calibration.convert(101.0, table)
    with pytest.raises(
        InputError, match="task 2: the data needs at least two distinct values of shaft_speed"
    ):
        fits.speed_dependence([3e-5, 4e-5, 5e-5], [150.0, 150.0, 150.0], 13.5e-3)
    with pytest.raises(InputError, match=r"mass must be > 0 \[kg\], got 0\.0"):
        rig.rig_loads(0.0, math.radians(45.0))
    with pytest.raises(InputError, match=r"tilt must be in \[0, 90\] \[deg\], got 95\.0"):
        rig.rig_equivalent_load(2.0, math.radians(95.0))


# ----------------------------------------------------------------------------- SKF model (issue 12)
SKF_KEYS = ("rolling_moment_Nmm", "sliding_moment_Nmm", "seal_moment_Nmm", "drag_moment_Nmm", "total_moment_Nmm",
            "power_loss_W", "sliding_friction_coefficient")
_SKF_61811 = ("friction", "torque", "--model", "skf", "-b", "61811-2RS1", "--radial-load", "6.51 N", "--speed",
              "2000 rpm", "--viscosity", "30 cSt", "--lubrication", "grease")


def test_skf_61811_pair_inside_the_measured_band(capsys):
    code, out, err = run(capsys, *_SKF_61811, "--json")
    assert code == 0, err
    doc = json.loads(out)
    assert set(SKF_KEYS) <= set(doc)
    assert set(doc) - set(SKF_KEYS) == {"bearing", "type", "model", "lubrication", "viscosity_cSt", "radial_load_N",
                                        "axial_load_N", "speed_rpm", "inputs", "warnings"}
    pair = 2 * doc["total_moment_Nmm"] / 1e3  # N m, the measured pair (tests/validation/test_skf_61811.py)
    assert 0.387 - 0.025 <= pair <= 0.387 + 0.025


def test_skf_equals_the_library(capsys):
    from bearinglab import catalog

    args = [a if a not in ("2000 rpm", "grease") else {"2000 rpm": "6000 rpm", "grease": "oil-jet"}[a]
            for a in _SKF_61811]
    code, out, err = run(capsys, *args, "--json")
    assert code == 0, err
    doc = json.loads(out)
    m = friction.skf_for_bearing(catalog.get("61811-2RS1"), 6.51, 0.0, 6000 * math.pi / 30, 30e-6,
                                 lubrication="oil-jet")
    assert doc["total_moment_Nmm"] == pytest.approx(m.total_moment * 1e3, rel=1e-12)
    assert doc["power_loss_W"] == pytest.approx(m.power_loss, rel=1e-12)
    assert doc["sliding_friction_coefficient"] == pytest.approx(m.sliding_friction_coefficient, rel=1e-12)


def test_skf_table(capsys):
    code, out, err = run(capsys, *_SKF_61811)
    assert code == 0, err
    assert "SKF model" in out and "M_seal" in out


@pytest.mark.parametrize("args, name", [(("--lubrication", "oil-bath-low"), "lubrication must be one of"),
                                        (("--viscosity", "30 kg"), "viscosity")])
def test_skf_bad_input_is_one_line_and_exit_2(capsys, args, name):
    code, _, err = run(capsys, *_SKF_61811, *args)
    assert code == 2
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("bearinglab: error:") and name in lines[0]


# ----------------------------------------------------------------------------- guard-rails (issue 15, review)
_SKF_6205 = ("friction", "torque", "--model", "skf", "-b", "6205-2RS", "--radial-load", "100 N", "--speed",
             "1000 rpm", "--viscosity", "30 cSt")


@pytest.mark.parametrize("series, words", [
    ("", "series must be one of ['2', '3', "),
    ("  ", "got '  '"),
    ("99", "(SKF's deep-groove series), got '99'"),
])
def test_skf_series_option_is_checked(capsys, series, words):
    # an empty series is an error, never read as "not given" (and the message is the command line's)
    code, _, err = run(capsys, *_SKF_6205, "--series", series)
    line = one_line_error(code, err)
    assert words in line and "SKFConstants" not in line


@pytest.mark.filterwarnings("ignore:.6205-2RS. is sealed:UserWarning")  # M_seal left out: tested below
def test_skf_series_option_gives_the_library_result(capsys):
    from bearinglab import catalog

    code, out, err = run(capsys, *_SKF_6205, "--series", "63", "--json")  # not the designation's 62
    assert code == 0, err
    m = friction.skf_for_bearing(catalog.get("6205-2RS"), 100.0, 0.0, 1000 * RPM, 30e-6, series="63")
    assert json.loads(out)["total_moment_Nmm"] == pytest.approx(m.total_moment * 1e3, rel=1e-12)
    m62 = friction.skf_for_bearing(catalog.get("6205-2RS"), 100.0, 0.0, 1000 * RPM, 30e-6)
    assert m.total_moment != pytest.approx(m62.total_moment, rel=1e-6)


def test_skf_series_from_a_bearing_file_is_checked(capsys, tmp_path):
    path = tmp_path / "b.toml"
    path.write_text('designation = "x6205"\ntype = "radial"\nbore = "25 mm"\noutside_diameter = "52 mm"\n'
                    'series = ""\n', encoding="utf-8")
    code, _, err = run(capsys, "friction", "torque", "--model", "skf", "--bearing-file", path, "-R", "100 N",
                       "-n", "1000 rpm", "--viscosity", "30 cSt")
    assert "series of 'x6205' must be one of" in one_line_error(code, err)
    path.write_text(path.read_text().replace('series = ""\n', ""), encoding="utf-8")
    code, _, err = run(capsys, "friction", "torque", "--model", "skf", "--bearing-file", path, "-R", "100 N",
                       "-n", "1000 rpm", "--viscosity", "30 cSt")
    assert "--series, e.g. --series 62" in one_line_error(code, err)


def test_skf_refuses_uncovered_angular_contact_and_series_without_skf(capsys):
    # issue 24: SKF's single-row constants cover 40 deg bearings (B218 runs); a 15 deg one is refused
    code, _, err = run(capsys, "friction", "torque", "--model", "skf", "-b", "7008 C", "-R", "100 N", "-n",
                       "1000 rpm", "--viscosity", "30 cSt")
    assert "contact_angle 15 deg is not covered by SKF's published friction constants" in one_line_error(code, err)
    code, _, err = run(capsys, "friction", "torque", "--model", "skf", "-b", "B218", "-R", "100 N", "-n", "1000 rpm",
                       "--viscosity", "30 cSt")
    assert code == 0, err
    code, _, err = run(capsys, "friction", "torque", "-b", "101", "-R", "10 N", "--series", "62")
    assert "only the skf model takes --series" in one_line_error(code, err)


@pytest.mark.parametrize("option, words", [
    ("--bore=-12 mm", "bore must be > 0 [mm], got -12 mm"),
    ("--outside-diameter=-3 mm", "outside-diameter must be > 0 [mm], got -3 mm"),
    ("--static-load-rating=-5 N", "static-load-rating must be > 0 [N] (C0), got -5 N"),
])
def test_torque_bearing_data_messages_in_engineering_units(capsys, option, words):
    code, _, err = run(capsys, "friction", "torque", "--type", "radial", "--bore", "12 mm", "--outside-diameter",
                       "28 mm", "--static-load-rating", "2227 N", option, "-R", "10 N")
    assert words in one_line_error(code, err)


def test_task4_evaluates_the_skf_model_once(monkeypatch):
    import sys

    skf_module = sys.modules["bearinglab.friction.skf"]
    calls = []
    real = skf_module.skf

    def counting(*args, **kwargs):
        calls.append(kwargs.get("sliding_friction_coefficient"))
        return real(*args, **kwargs)

    session = measurement.read_session(EXAMPLES / "skf_6205.toml")
    monkeypatch.setattr(skf_module, "skf", counting)
    t4 = analysis.analyse(session).task4
    assert len(calls) == 1 and np.all(np.isfinite(t4.model_residual_rms))
    # the unfitted model from that one evaluation (mu_sl = 1 and the SKF mu_sl formula) is skf() itself
    fr, n = np.array([50.0, 100.0, 200.0]), np.array([100.0, 200.0, 300.0])
    t = real(fr, 0.0, n, 30e-6, 25e-3, 52e-3, series="62", sliding_friction_coefficient=0.08).total_moment
    fit = fits.skf_friction(t, fr, 0.0, n, 30e-6, 25e-3, 52e-3, series="62", ehl_coefficient=0.04)
    model = real(fr, 0.0, n, 30e-6, 25e-3, 52e-3, series="62", ehl_coefficient=0.04).total_moment
    np.testing.assert_allclose(fit.model_residuals, t - model, rtol=0, atol=1e-16)


_SKF_6205_SEALED = ("friction", "torque", "-b", "6205-2RS", "-R", "1 kN", "-n", "3000 rpm", "-m", "skf", "--viscosity",
             "68 mm^2/s")


def test_skf_sealed_bearing_without_seal_data_says_m_seal_is_left_out(capsys):
    """6205-2RS has no seal data in the catalog: M_seal = 0 is not computed, the warning and the caption say
    so (issue 15); 61811-2RS1, whose seals are known, keeps the caption naming the seal moment."""
    code, out, err = run(capsys, *_SKF_6205_SEALED, "--json")
    assert code == 0, err
    doc = json.loads(out)
    assert doc["seal_moment_Nmm"] == 0.0
    assert [w for w in doc["warnings"] if "M_seal" in w and "not included" in w and "6205-2RS" in w]
    code, out, err = run(capsys, *_SKF_6205_SEALED)
    assert code == 0, err
    flat = " ".join(out.split())
    assert "seal and drag moments" not in flat
    assert "rolling, sliding and drag moments (no seal moment: not included, see the warnings)" in flat
    assert "warning: '6205-2RS' is sealed (RS, by its designation)" in flat
    code, out, err = run(capsys, *_SKF_61811)
    assert code == 0, err
    # one case is a narrow quantity/value table: its caption wraps at the table's width
    assert "rolling, sliding, seal and drag moments" in " ".join(out.split()) and "warning:" not in out


def test_oil_bath_takes_v_m_from_skfs_diagram_and_the_option_overrides_it(capsys):
    # issue 30: --oil-level alone; V_M of SKF's diagram at H/d_m is used and reported; --drag-loss-factor overrides
    from bearinglab.friction.drag import drag_loss_factor

    base = ["friction", "torque", "--model", "skf", "-b", "6205", "-R", "1 kN", "-n", "3000 rpm",
            "--viscosity", "20 cSt", "--lubrication", "oil-bath", "--oil-level", "5 mm", "--json"]
    assert main(base) == 0
    doc = json.loads(capsys.readouterr().out)
    assert doc["drag_loss_factor"] == pytest.approx(float(drag_loss_factor(5e-3, 38.5e-3, "ball")), rel=1e-12)
    assert doc["drag_loss_factor_source"].startswith("SKF's diagram")
    assert main([*base, "--drag-loss-factor", "0.0002"]) == 0
    given = json.loads(capsys.readouterr().out)
    assert given["drag_loss_factor"] == 0.0002 and given["drag_loss_factor_source"] == "given"
    assert given["drag_moment_Nmm"] != doc["drag_moment_Nmm"]

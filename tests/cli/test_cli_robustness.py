"""Issue 15: no tracebacks, no silently wrong numbers. Each test drives the command line in-process and
checks the exit code and the one-line message (input files in other encodings, plot suffixes, ...)."""

import pytest

from bearinglab.cli import main

ERRORS_EXAMPLE = "examples/runout/example1_oversize_ball.toml"
BEARING_FILE = (
    '[bearings."X"]\nballs = 9\nball_diameter = "7.938 mm"\npitch_diameter = "38.5 mm"\n'
    'inner_conformity = 0.52\nouter_conformity = 0.53\ncontact_angle = "15 deg"\n'
)


def run(capsys, *args):
    """Exit code, stdout and stderr of one in-process run."""
    code = main([str(a) for a in args])
    out, err = capsys.readouterr()
    return code, out, err


def one_line_error(code, err, *, exit_code=2):
    assert code == exit_code, err
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("bearinglab: error: "), err
    assert "Traceback" not in err
    return lines[0]


# ----------------------------------------------------------------------------- item 2: encodings
ENCODINGS = {
    "latin1": ('title = "Kugellager für hohe Drehzahl"\n'.encode("latin-1"), "not a UTF-8 text file"),
    "utf16": (BEARING_FILE.encode("utf-16"), "UTF-16"),
    "binary": (bytes(range(256)), "not a UTF-8 text file"),
    "nul": (b"x = 1\n\x00\x00", "not a text file"),
}


def _commands(path):
    return {
        "catalog list --catalog": ["catalog", "list", "--catalog", path],
        "--bearing-file": ["axial-angle", "--bearing-file", path, "-F", "1 kN"],
        "runout --errors": ["runout", "--errors", path],
        "runout --geometry": ["runout", "--errors", ERRORS_EXAMPLE, "--geometry", path],
        "sweep": ["sweep", path],
    }


@pytest.mark.parametrize("encoding", sorted(ENCODINGS))
@pytest.mark.parametrize("command", sorted(_commands("x")))
def test_input_file_not_utf8_is_one_line(tmp_path, capsys, encoding, command):
    data, message = ENCODINGS[encoding]
    path = tmp_path / "input.toml"
    path.write_bytes(data)
    line = one_line_error(*run(capsys, *_commands(path)[command])[::2])
    assert message in line and str(path) in line


@pytest.mark.parametrize("encoding", sorted(ENCODINGS))
def test_catalog_environment_variable_not_utf8(tmp_path, capsys, monkeypatch, encoding):
    path = tmp_path / "cat.toml"
    path.write_bytes(ENCODINGS[encoding][0])
    monkeypatch.setenv("BEARINGLAB_CATALOG", str(path))
    line = one_line_error(*run(capsys, "axial-angle", "-b", "B218", "-F", "1 kN")[::2])
    assert ENCODINGS[encoding][1] in line


def test_byte_order_mark_is_read(tmp_path, capsys):
    path = tmp_path / "bom.toml"
    path.write_bytes(b"\xef\xbb\xbf" + BEARING_FILE.encode())
    code, out, err = run(capsys, "axial-angle", "--bearing-file", path, "-F", "1 kN", "--json")
    assert code == 0, err
    code, out, err = run(capsys, "catalog", "list", "--catalog", path)
    assert code == 0 and "X" in out, err


def test_directory_as_input_file(tmp_path, capsys):
    line = one_line_error(*run(capsys, "sweep", tmp_path)[::2])
    assert "directory" in line


# ----------------------------------------------------------------------------- item 3: output files
@pytest.mark.parametrize("name", ["map.txt", "map.csv", "map"])
def test_high_speed_plot_suffix_checked_before_solving(tmp_path, capsys, monkeypatch, name):
    from bearinglab import quasistatic

    def no_solve(*a, **k):  # the suffix is checked before anything is computed
        raise AssertionError("solved before the suffix was checked")

    monkeypatch.setattr(quasistatic, "sweep", no_solve)
    line = one_line_error(*run(capsys, "high-speed", "-b", "B218", "-F", "5kN:10kN:5kN", "-n", "3000 rpm",
                               "--plot", tmp_path / name)[::2])
    assert "plot" in line and ".png" in line


def test_output_file_that_is_a_directory(tmp_path, capsys):
    line = one_line_error(*run(capsys, "high-speed", "-b", "B218", "-F", "5 kN", "-n", "3000 rpm",
                               "--csv", tmp_path)[::2])
    assert "is a directory" in line


# ----------------------------------------------------------------------------- item 6: plausibility
def _json(capsys, *args):
    import json

    code, out, err = run(capsys, *args, "--json")
    assert code == 0, err
    return json.loads(out)


def test_absurd_thrust_warns_in_json_and_in_the_table(capsys):
    args = ("high-speed", "-b", "B218", "-F", "1e9 N", "-n", "3000 rpm")
    doc = _json(capsys, *args)
    text = " | ".join(doc["warnings"])
    for expected in ("exceeds the ISO 76 limit of 4200 MPa", "exceeds C0", "% of the ball diameter",
                     "runs over the shoulder"):
        assert expected in text
    code, out, _ = run(capsys, *args)
    assert code == 0 and "warning:" in out and "4200 MPa" in " ".join(out.split())


def test_light_load_at_speed_warns(capsys):
    """Issue 11: B218 at 0.05 kN and 15 000 rpm (alpha_e = 0.05 deg) must not pass without a word."""
    doc = _json(capsys, "high-speed", "-b", "B218", "-F", "0.05 kN", "-n", "15000 rpm")
    text = " | ".join(doc["warnings"])
    assert "minimum load: 1 of 1 case(s)" in text and "outer contact angle is driven to zero" in text


def test_moderate_load_at_rest_has_no_warning(capsys):
    doc = _json(capsys, "high-speed", "-b", "B218", "-F", "20 kN", "-n", "0 rpm")
    assert doc["warnings"] == []


def test_sweep_json_carries_warnings(capsys):
    doc = _json(capsys, "high-speed", "-b", "B218", "-F", "20kN,1e8N", "-n", "0 rpm, 3000 rpm")
    assert len(doc["cases"]) == 4 and any("2 of 4 case(s)" in w for w in doc["warnings"])


# ----------------------------------------------------------------------------- item 16: messages, exit codes
@pytest.mark.parametrize("extra, message", [
    (["--x0", "-1"], "x0 must be in (0, 1.36136) [rad]"),
    (["--x0", "nan"], "Invalid value for '--x0': 'nan' is not a number"),  # issue 29: a word is no number
    (["--rows", "0"], "rows must be an integer >= 1"),
])
def test_axial_angle_impossible_start_is_input_error(capsys, extra, message):
    line = one_line_error(*run(capsys, "axial-angle", "-b", "4-1006095", "-F", "2 kgf", *extra)[::2])
    assert message in line and "stand." not in line and "nan)" not in line


def test_axial_angle_absurd_load_converges_and_warns(capsys):
    import json

    code, out, err = run(capsys, "axial-angle", "-b", "4-1006095", "-F", "1e12 N", "--json")
    assert code == 0 and err == ""
    doc = json.loads(out)
    assert 12 < doc["operating_contact_angle_deg"] < 90 and any("ISO 76" in w for w in doc["warnings"])


def test_convergence_error_summary_has_no_function_name_nor_nan():
    from bearinglab.errors import ConvergenceError

    e = ConvergenceError("stand.iteration_table", iterations=0, residual=float("nan"), estimate=0.0,
                         reason="the angle left (alpha0, 90 deg)")
    assert e.summary == "no convergence after 0 iterations: the angle left (alpha0, 90 deg)"
    p = ConvergenceError("x.y", iterations=3, residual=1e-3, estimate=0.0, reason="the ball leaves", physical=True)
    # a physical refusal reads as its reason, not as a weak solver (the iterations stay in str(exc))
    assert p.summary == "no physical solution: the ball leaves"
    assert "no convergence" not in p.summary and "after 3 iterations" in str(p)
    q = ConvergenceError("x.y", iterations=4, residual=1e-3, estimate=0.0, reason="no convergence at F_a = 1 N")
    assert q.summary == "no convergence at F_a = 1 N (after 4 iterations (|residual| = 0.001))"


# ----------------------------------------------------------------------------- item 9: inputs echoed
def test_override_is_in_the_title_and_the_json(capsys):
    doc = _json(capsys, "axial-angle", "-b", "4-1006095", "--balls", "9", "-F", "2 kgf")
    assert doc["bearing"] == "4-1006095 (balls 9)" and doc["catalog_bearing"] == "4-1006095"
    assert doc["overrides"] == {"balls": 9} and doc["geometry"]["balls"] == 9
    assert doc["geometry"]["inner_groove_radius_mm"] == pytest.approx(1.05)
    code, out, _ = run(capsys, "axial-angle", "-b", "4-1006095", "--balls", "9", "-F", "2 kgf")
    assert code == 0 and "Bearing 4-1006095 (balls 9)" in " ".join(out.split())


@pytest.mark.parametrize("args", [
    ["axial-angle", "-b", "B218", "-F", "2 kgf"],
    ["axial-angle", "-b", "B218", "-F", "1kN,2kN"],
    ["stand-load", "-b", "B218", "-n", "3000 rpm"],
    ["frequencies", "-b", "B218", "-n", "3000 rpm"],
    ["high-speed", "-b", "B218", "-F", "5 kN", "-n", "3000 rpm"],
    ["high-speed", "-b", "B218", "-F", "5kN, 10kN", "-n", "3000 rpm"],
    ["sweep", "examples/sweep/stand_geometry_variants.toml"],
])
def test_every_result_echoes_the_geometry_used(capsys, args):
    doc = _json(capsys, *args)
    assert doc["bearing"] and doc["geometry"]["ball_diameter_mm"] > 0 and doc["geometry"]["balls"] >= 1


@pytest.mark.parametrize("speed", ["10000 1/min", "10000 r/min", "3000 rpm", "50 Hz"])
def test_echoed_speed_has_no_float_noise(capsys, speed):
    doc = _json(capsys, "high-speed", "-b", "B218", "-F", "5 kN", "-n", speed)
    assert repr(doc["speed_rpm"]) in ("10000.0", "3000.0")


# ----------------------------------------------------------------------------- item 10: sign change
def test_plot_marks_the_library_sign_change(capsys, monkeypatch, tmp_path):
    import numpy as np

    from bearinglab import catalog, quasistatic
    from bearinglab.plots import high_speed as figures
    from bearinglab.units import RPM

    seen = {}
    real = figures.plot_map

    def spy(state, **kw):
        seen.update(kw)
        return real(state, **kw)

    monkeypatch.setattr(figures, "plot_map", spy)
    code, _, err = run(capsys, "high-speed", "-b", "B218", "-F", "2.5kN:10kN:2.5kN", "-n", "0 rpm, 6000 rpm",
                       "--plot", tmp_path / "map.png")
    assert code == 0, err
    expected = quasistatic.sign_change_thrust(catalog.get("B218"), np.array([0.0, 6000 * RPM]))
    np.testing.assert_allclose(seen["sign_change"], expected, rtol=1e-9)
    assert 2.5e3 < seen["sign_change"][1] < 10e3  # inside the grid, where the figure marks it


# ----------------------------------------------------------------------------- items 17, 18: guard-rails
@pytest.mark.parametrize("args, message", [
    (["runout", "--errors", ERRORS_EXAMPLE, "--revolutions", "1", "--cage-ratio", "1.5"], "cage-ratio must be in (0, 1)"),
    (["runout", "--errors", ERRORS_EXAMPLE, "--steps-per-rev", "2"], "steps-per-rev must be an integer >= 4"),
    (["runout", "monte-carlo", "-b", "B218", "--steps-per-rev", "2"], "steps-per-rev must be an integer >= 4"),
    (["high-speed", "-b", "B218", "-F", "1 kN", "-n", "1e12 rpm"], "speed must be <= 279330 [rpm]"),
    (["stand-load", "-b", "B218", "-n", "1e12 rpm"], "speed must be <= 279330 [rpm]"),
    (["frequencies", "-b", "B218", "-n", "1e12 rpm"], "speed must be <= 279330 [rpm]"),
    (["frequencies", "-b", "B218", "--speed=-3000 rpm"], "speed must be >= 0 [rpm]"),
    (["stand-load", "-b", "B218", "--speed=-3000 rpm"], "speed must be >= 0 [rpm]"),
    (["high-speed", "-b", "B218", "-F", "1 kN", "--speed=-3000 rpm"], "speed must be >= 0 [rpm]"),
])
def test_guard_rails(capsys, args, message):
    line = one_line_error(*run(capsys, *args)[::2])
    assert message in line


def test_errors_name_the_target_not_the_temporary_file():
    from bearinglab.cli import _target_name

    assert _target_name("/x/.s.toml.ab12_Z9q.tmp") == "/x/s.toml"
    assert _target_name("/x/.map.png.k3j4h5g6.png") == "/x/map.png"
    assert _target_name("/x/plain.csv") == "/x/plain.csv"


def test_catalog_aliases():
    from bearinglab import catalog

    assert catalog.aliases()["B218"] == ["7218B"]
    assert "7218B" not in catalog.aliases()


@pytest.mark.parametrize("args", [
    ["high-speed", "-b", "B218", "-F", "5 kN", "-n", "3000 rpm"],
    ["high-speed", "-b", "B218", "-F", "5kN, 10kN", "-n", "3000 rpm"],
    ["axial-angle", "-b", "4-1006095", "-F", "2 kgf"],
    ["axial-angle", "-b", "4-1006095", "-F", "1kgf:3kgf:1kgf"],
])
def test_printed_displacements_are_in_micrometres(capsys, args):
    code, out, err = run(capsys, *args)
    assert code == 0, err
    assert "µm" in out and "δ_a [mm]" not in out and "δ_a mm" not in out


@pytest.mark.parametrize("args", [
    ["runout", "--errors", ERRORS_EXAMPLE, "--revolutions", "1", "--csv", "{tmp}/missing/t.csv"],
    ["runout", "monte-carlo", "-b", "B218", "--samples", "2", "--samples-csv", "{tmp}/missing/s.csv"],
    ["high-speed", "-b", "B218", "-F", "5 kN", "-n", "3000 rpm", "--csv", "{tmp}/missing/h.csv"],
    ["frequencies", "-b", "B218", "-n", "3000 rpm", "--csv", "{tmp}/missing/f.csv"],
])
def test_no_command_creates_a_missing_output_directory(capsys, tmp_path, args):
    line = one_line_error(*run(capsys, *[a.format(tmp=tmp_path) for a in args])[::2])
    assert "does not exist" in line and not (tmp_path / "missing").exists()


# ----------------------------------------------------------------------------- messages in the units typed
@pytest.mark.parametrize("option, words", [
    ("--ball-diameter=-2 mm", "ball-diameter must be > 0 [mm], got -2 mm"),
    ("--pitch-diameter=0 mm", "pitch-diameter must be > 0 [mm], got 0 mm"),
    ("--inner-groove-radius=0.9 mm", "inner-groove-radius must be > D/2 = 1 [mm] (the ball radius), got 0.9 mm"),
    ("--outer-groove-radius=-1 mm", "outer-groove-radius must be > D/2 = 1 [mm] (the ball radius), got -1 mm"),
])
def test_inline_geometry_messages_in_engineering_units(capsys, option, words):
    for command in (["frequencies", "-n", "1000 rpm"], ["axial-angle", "-F", "2 kgf"]):
        line = one_line_error(*run(capsys, *command, "-b", "4-1006095", option)[:3:2])
        assert words in line and "[m]" not in line, line


@pytest.mark.parametrize("option", ["--radial-clearance=-5 um", "--radial-clearance=0 mm"])
def test_zero_or_negative_clearance_is_a_preload_not_a_typing_error(capsys, option):
    """Issue 30: a zero or negative clearance is a preloaded bearing. Frequencies take its contact angle
    (0); the test-stand method, which needs a free contact angle, says so; a preload beyond a ball
    diameter is a unit mistake, refused in the unit typed."""
    code, out, _err = run(capsys, "frequencies", "-n", "1000 rpm", "-b", "4-1006095", option)
    assert code == 0 and "BPFO" in out
    line = one_line_error(*run(capsys, "axial-angle", "-F", "2 kgf", "-b", "4-1006095", option)[:3:2])
    assert "contact_angle must be in (0, 90) [deg]" in line and "got 0" in line
    line = one_line_error(*run(capsys, "frequencies", "-n", "1000 rpm", "-b", "4-1006095",
                               "--radial-clearance=-5 mm")[:3:2])
    assert "radial-clearance must be >= -4 [mm]" in line and "[m]" not in line


def test_physical_refusal_reads_as_its_reason(capsys):
    # no equilibrium for this input (exit 2): the message is the physical reason, not a weak solver
    line = one_line_error(*run(capsys, "high-speed", "-b", "7218B", "-F", "100 N", "-n", "30000 rpm",
                               "--raceway-control", "inner")[:3:2])
    assert line.startswith("bearinglab: error: no physical solution: ") and "leaves the inner raceway" in line
    assert "no convergence" not in line and "iterations" not in line

"""Command line of spec 003: ``runout`` (one angle, a sequence) and ``runout monte-carlo``, in-process."""

import json
import math
from pathlib import Path

import pytest

from bearinglab import runout
from bearinglab.cli import main
from bearinglab.errors import ConvergenceError

EXAMPLES = Path(__file__).resolve().parents[2] / "examples" / "runout"
EX1 = str(EXAMPLES / "example1_oversize_ball.toml")
EX3 = str(EXAMPLES / "example3_mixed.toml")
MC = str(EXAMPLES / "monte_carlo_reference.toml")


def run(capsys, *args):
    code = main(list(args))
    out, err = capsys.readouterr()
    return code, out, err


def assert_one_line_error(code, err, expected_code=2, match=None):
    assert code == expected_code
    assert "Traceback" not in err
    lines = err.strip().splitlines()
    assert len(lines) == 1, err
    assert lines[0].startswith("bearinglab: error:")
    if match:
        assert match in lines[0], lines[0]


def test_single_angle_json(capsys):
    code, out, err = run(capsys, "runout", "--errors", EX3, "--angle", "90", "--json")
    assert code == 0, err
    doc = json.loads(out)
    for key in (
        "a0_um",
        "B_um",
        "D_um",
        "dx_um",
        "dy_um",
        "dz_um",
        "contact_balls",
        "degenerate",
        "free_play_um",
    ):
        assert key in doc
    assert doc["a0_um"] == pytest.approx(-0.162489, abs=1e-6)
    assert doc["B_um"] == pytest.approx(-0.515580, abs=1e-6)
    assert doc["D_um"] == pytest.approx(0.021578, abs=1e-6)
    assert [doc["dx_um"], doc["dy_um"], doc["dz_um"]] == pytest.approx(
        [0.022339, -0.533768, -0.627810], abs=1e-6
    )
    assert doc["contact_balls"] == [7, 12, 16]  # 1-based
    assert doc["degenerate"] is False and doc["free_play_um"] == 0.0
    assert len(doc["balls"]) == 16 and doc["balls"][6]["contact"] is True
    assert doc["balls"][0]["theta_deg"] == pytest.approx(39.249522, rel=1e-6)


def test_single_angle_degenerate_and_units(capsys):
    code, out, err = run(capsys, "runout", "--errors", EX1, "--angle", "0 deg", "--json")
    assert code == 0, err
    doc = json.loads(out)
    assert doc["contact_balls"] == [1, 9] and doc["degenerate"] is True
    assert doc["free_play_um"] == pytest.approx(2 * 0.205929, abs=2e-6)
    _, out2, _ = run(capsys, "runout", "--errors", EX1, "--angle", "0.5 rad", "--json")
    _, out3, _ = run(capsys, "runout", "--errors", EX1, "--angle", str(math.degrees(0.5)), "--json")
    assert json.loads(out2)["dz_um"] == pytest.approx(json.loads(out3)["dz_um"], abs=1e-12)


def test_refine_json(capsys):
    code, out, err = run(capsys, "runout", "--errors", EX3, "--refine", "--json")
    assert code == 0, err
    doc = json.loads(out)
    assert [doc["dx_um"], doc["dy_um"], doc["dz_um"]] == pytest.approx(
        [-0.405947, 0.0, -1.532831], abs=1e-5
    )
    assert doc["refined"] is True and doc["converged"] is True and doc["passes"] >= 1
    assert doc["first_approximation"]["dz_um"] == pytest.approx(-1.531801, abs=1e-6)
    assert "dtau1_rad" in doc["balls"][0]


def test_sequence_json(capsys, tmp_path):
    csv_path = tmp_path / "sub" / "trajectory.csv"
    (tmp_path / "sub").mkdir()  # an output's directory must exist (issue 15 item 17)
    code, out, err = run(
        capsys,
        "runout",
        "--errors",
        EX3,
        "--revolutions",
        "3",
        "--steps-per-rev",
        "360",
        "--json",
        "--csv",
        str(csv_path),
    )
    assert code == 0, err
    doc = json.loads(out)
    expected = {
        "radial_ptp_x_um": 1.341651,
        "radial_ptp_y_um": 1.190242,
        "radial_ptp_max_um": 1.434630,
        "axial_ptp_um": 1.391655,
        "dz_mean_um": -1.232854,
    }
    for key, value in expected.items():
        assert doc[key] == pytest.approx(value, abs=1e-6), key
    assert doc["positions"] == 1080
    assert doc["degenerate_fraction"] == pytest.approx(0.234, abs=0.001)
    assert set(doc["synchronous"]) == set(expected) and set(doc["asynchronous"]) == set(expected)
    assert len(doc["trajectory"]["dx_um"]) == 1080 and doc["trajectory"]["contact_balls"][0] == [
        1,
        9,
    ]
    assert doc["spectrum_lines"] and {"order", "amplitude_um", "label", "source"} <= set(
        doc["spectrum_lines"][0]
    )
    lines = csv_path.read_text().splitlines()
    assert lines[0].startswith("#") and len([ln for ln in lines if not ln.startswith("#")]) == 1081


def test_sequence_defaults_and_text_output(capsys):
    code, out, err = run(
        capsys, "runout", "--errors", EX1, "--revolutions", "1", "--steps-per-rev", "36"
    )
    assert code == 0, err
    assert "radial ptp x" in out and "degenerate positions" in out


def test_text_output_single(capsys):
    code, out, err = run(capsys, "runout", "--errors", EX3)
    assert code == 0, err
    assert "Δz [µm]" in out and "-1.531801" in out


def test_geometry_from_bearing_and_geometry_file(capsys, tmp_path):
    errors_only = tmp_path / "errors.toml"
    errors_only.write_text("[errors.inner.radial]\ncos = { 1 = 0.5 }\n", encoding="utf-8")
    code, out, err = run(
        capsys, "runout", "--bearing", "7218B", "--errors", str(errors_only), "--json"
    )
    assert code == 0, err
    doc = json.loads(out)
    assert doc["geometry"]["balls"] == 16 and doc["geometry"]["contact_angle_deg"] == pytest.approx(
        40.0
    )
    # eccentricity 0.5 um of the inner raceway: the ring centre moves by 0.5 um (a pure first harmonic)
    assert math.hypot(doc["dx_um"], doc["dy_um"]) == pytest.approx(0.5, abs=1e-9)
    code, out, err = run(
        capsys,
        "runout",
        "--geometry",
        MC,
        "--errors",
        str(errors_only),
        "--first-ball-angle",
        "11.25",
        "--json",
    )
    assert code == 0, err
    doc = json.loads(out)
    assert doc["geometry"]["first_ball_angle_deg"] == pytest.approx(11.25)
    assert doc["balls"][0]["theta_deg"] == pytest.approx(11.25)


def test_plots_are_written(capsys, tmp_path):
    code, out, err = run(
        capsys,
        "runout",
        "--errors",
        EX3,
        "--revolutions",
        "2",
        "--steps-per-rev",
        "36",
        "--plot",
        str(tmp_path),
        "--json",
    )
    assert code == 0, err
    figs = json.loads(out)["figures"]
    assert {Path(f).name for f in figs} == {
        "runout_trajectory.png",
        "runout_axial.png",
        "runout_spectrum.png",
        "runout_contact_psi0.png",
    }
    for f in figs:
        assert Path(f).read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert not [p for p in tmp_path.iterdir() if p.name.startswith(".")]  # no temporary files left
    code, out, err = run(
        capsys, "runout", "--errors", EX3, "--angle", "90", "--plot", str(tmp_path)
    )
    assert code == 0, err
    assert (tmp_path / "runout_contact_psi90.png").exists()


def test_monte_carlo_json(capsys, tmp_path):
    csv_path = tmp_path / "samples.csv"
    args = [
        "runout",
        "monte-carlo",
        "--geometry",
        MC,
        "--ball-grade",
        "G5",
        "--ring-class",
        "P4",
        "--samples",
        "20",
        "--seed",
        "3",
        "--steps-per-rev",
        "36",
        "--json",
    ]
    code, out, err = run(capsys, *args, "--samples-csv", str(csv_path), "--plot", str(tmp_path))
    assert code == 0, err
    doc = json.loads(out)
    for metric in ("radial_ptp_x_um", "radial_ptp_y_um", "radial_ptp_max_um", "axial_ptp_um"):
        assert set(doc[metric]) == {"mean", "std", "median", "p95", "max"}
        assert doc[metric]["max"] >= doc[metric]["p95"] >= doc[metric]["median"] > 0
    assert doc["samples"] == 20 and doc["ball_grade"] == "G5" and doc["ring_class"] == "P4"
    assert (tmp_path / "runout_monte_carlo.png").exists()
    rows = [ln for ln in csv_path.read_text().splitlines() if not ln.startswith("#")]
    assert len(rows) == 21 and rows[0].startswith("sample,first_ball_angle_deg,radial_ptp_x_um")
    # the same seed gives the same numbers; they equal the Python API's
    code, out2, _ = run(capsys, *args)
    assert json.loads(out2)["axial_ptp_um"] == doc["axial_ptp_um"]
    g = runout.geometry_from_catalog(16, 7.144e-3, 54e-3, 0.53, 0.52, math.radians(15))
    r = runout.monte_carlo(g, "G5", "P4", 20, 3, steps_per_revolution=36)
    assert doc["radial_ptp_max_um"]["mean"] == pytest.approx(
        r.summary["radial_ptp_max"].mean * 1e6, rel=1e-12
    )


def test_monte_carlo_text_and_bearing(capsys):
    code, out, err = run(
        capsys,
        "runout",
        "monte-carlo",
        "--bearing",
        "7218B",
        "--samples",
        "4",
        "--steps-per-rev",
        "12",
        "--ring-class",
        "p2",
        "--ball-grade",
        "g3",
    )
    assert code == 0, err
    assert "Monte Carlo G3 / P2" in out and "radial ptp max" in out


@pytest.mark.parametrize(
    "args, match",
    [
        (["runout"], "--errors FILE"),
        (["runout", "--errors", "/no/such/file.toml"], "no such file"),
        (["runout", "--errors", EX3, "--angle", "10", "--revolutions", "2"], "not both"),
        (["runout", "--errors", EX3, "--angle", "10 mm"], "is a length, expected an angle"),
        (["runout", "--errors", EX3, "--bearing", "7218B", "--geometry", MC], "not both"),
        (["runout", "--errors", EX3, "--bearing", "nosuch"], "unknown name 'nosuch'"),
        (["runout", "--errors", EX3, "--csv", "x.csv"], "--csv writes a trajectory"),
        (["runout", "--errors", EX3, "--revolutions", "0"], "revolutions must be an integer >= 1"),
        (["runout", "--errors", EX3, "monte-carlo"], "--errors given before 'monte-carlo'"),
        (["runout", "monte-carlo"], "give --geometry FILE or --bearing NAME"),
        (
            ["runout", "monte-carlo", "--geometry", MC, "--ball-grade", "G7"],
            "ball-grade must be one of",
        ),
        (["runout", "monte-carlo", "--geometry", MC, "--samples", "1"], "samples must be >= 2"),
    ],
)
def test_bad_input_is_one_line_and_exit_2(capsys, args, match):
    code, _out, err = run(capsys, *args)
    assert_one_line_error(code, err, 2, match)


def test_ball_count_mismatch_names_the_file(capsys):
    code, _out, err = run(capsys, "runout", "--errors", EX3, "--bearing", "4-1006095")
    assert_one_line_error(code, err, 2, "needs one value per ball: 7 balls, got 16 values")
    assert "example3_mixed.toml" in err


def test_non_convergence_exits_3(capsys, monkeypatch):
    def failing(*args, **kwargs):
        raise ConvergenceError(
            "runout.initial_displacement (refinement)",
            iterations=30,
            residual=[1e-12],
            estimate=[0.0],
        )

    monkeypatch.setattr(runout, "initial_displacement", failing)
    code, _out, err = run(capsys, "runout", "--errors", EX3, "--refine")
    assert_one_line_error(code, err, 3, "no convergence after 30 iterations")


def test_help_of_both_commands(capsys):
    code, out, _ = run(capsys, "runout", "--help")
    assert code == 0 and "monte-carlo" in out and "--errors" in out
    code, out, _ = run(capsys, "runout", "monte-carlo", "--help")
    assert code == 0 and "--ball-grade" in out and "--errors" not in out


def test_geometry_given_as_a_bearing_file(capsys, tmp_path):
    bearing = tmp_path / "spindle.toml"
    bearing.write_text(
        'balls = 16\nball_diameter = "7.144 mm"\npitch_diameter = "54 mm"\ninner_conformity = 0.52\n'
        'outer_conformity = 0.53\ncontact_angle = "15 deg"\n',
        encoding="utf-8",
    )
    code, out, err = run(capsys, "runout", "--geometry", str(bearing), "--errors", EX1, "--json")
    assert code == 0, err
    assert json.loads(out)["dz_um"] == pytest.approx(-3.863703, abs=1e-6)


def test_progress_bar_on_a_terminal(capsys, monkeypatch):
    import sys

    monkeypatch.setattr(sys.stderr, "isatty", lambda: True)
    code, out, err = run(
        capsys,
        "runout",
        "monte-carlo",
        "--geometry",
        MC,
        "--samples",
        "6",
        "--steps-per-rev",
        "12",
        "--chunk-size",
        "2",
        "--json",
    )
    assert code == 0, err
    assert json.loads(out)["samples"] == 6  # stdout stays one JSON document; the bar went to stderr
    code, out, err = run(
        capsys,
        "runout",
        "monte-carlo",
        "--geometry",
        MC,
        "--samples",
        "6",
        "--steps-per-rev",
        "12",
        "--no-progress",
        "--json",
    )
    assert code == 0 and err == ""


def test_negative_seed_is_an_input_error(capsys):
    code, _out, err = run(capsys, "runout", "monte-carlo", "--geometry", MC, "--samples", "4", "--seed", "-1")
    assert_one_line_error(code, err, 2, "seed must be >= 0")

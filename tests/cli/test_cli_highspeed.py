"""Command line of the high-speed model (spec 004): ``bearinglab high-speed``, single cases and sweeps."""

import csv
import dataclasses
import json
import math

import numpy as np
import pytest

from bearinglab import catalog, quasistatic
from bearinglab.cli import main
from bearinglab.units import RPM

KEYS = ("contact_angle_inner_deg", "contact_angle_outer_deg", "axial_displacement_um", "ball_load_inner_N",
        "ball_load_outer_N", "centrifugal_force_N", "gyroscopic_moment_Nmm", "attitude_angle_deg", "cage_speed_rpm",
        "ball_spin_speed_rpm", "converged", "residual")
#: the reduced modulus of spec 004's rounded K prefactor 2.15e5 N/mm^1.5 (see tests/validation/test_high_speed_218.py)
E_ROUNDED = f"{2.15e5 * 3 / 2**1.5:.6f} MPa"


def run(capsys, *args):
    code = main(list(args))
    out, err = capsys.readouterr()
    return code, out, err


def _one_line_error(err):
    lines = err.strip().splitlines()
    assert len(lines) == 1, err
    assert lines[0].startswith("bearinglab: error:") and "Traceback" not in err
    return lines[0]


def test_single_case_json_reproduces_section_7(capsys):
    code, out, err = run(capsys, "high-speed", "--bearing", "B218", "--axial-load", "20 kN", "--speed", "10000 rpm",
                         "--constants", "harris", "--reduced-modulus", E_ROUNDED, "--json")
    assert code == 0, err
    doc = json.loads(out)
    assert set(KEYS) <= set(doc)
    assert doc["contact_angle_inner_deg"] == pytest.approx(49.308, abs=1e-3)
    assert doc["contact_angle_outer_deg"] == pytest.approx(32.514, abs=1e-3)
    assert doc["axial_displacement_um"] == pytest.approx(21.36, abs=5e-3)  # printed 21.36 um
    assert doc["ball_load_inner_N"] == pytest.approx(1648.6, abs=0.05)
    assert doc["ball_load_outer_N"] == pytest.approx(2113.7, abs=0.05)
    assert doc["centrifugal_force_N"] == pytest.approx(635.0, abs=0.05)
    assert doc["gyroscopic_moment_Nmm"] == pytest.approx(1500.7, abs=0.05)
    assert doc["attitude_angle_deg"] == pytest.approx(27.772, abs=5e-4)
    assert doc["cage_speed_rpm"] == pytest.approx(4518.0, abs=0.05)
    assert doc["ball_spin_speed_rpm"] == pytest.approx(29376, abs=0.5)
    assert doc["converged"] is True and doc["residual"] < 1e-12 and doc["status"] == "ok"
    assert doc["bearing"] == "B218" and doc["constants"] == "harris"
    # 20 kN at 10 000 rpm is well above SKF's minimum load 0.01 C (issue 20: the test-stand criterion against
    # gyroscopic slip, 113 kN > C at 15 000 rpm, is no longer the minimum load of a running bearing)
    assert doc["warnings"] == []


def test_single_case_equals_the_python_api(capsys):
    code, out, _ = run(capsys, "high-speed", "-b", "B218", "-F", "5 kN", "-n", "6000 rpm", "--json")
    assert code == 0
    doc = json.loads(out)
    s = quasistatic.high_speed_analysis(catalog.get("B218"), 5e3, 6000 * RPM)
    assert doc["contact_angle_inner_deg"] == pytest.approx(math.degrees(s.contact_angle_inner), rel=1e-14)
    assert doc["axial_stiffness_N_per_um"] == pytest.approx(s.axial_stiffness * 1e-6, rel=1e-14)
    assert doc["constants"] == "mass" and doc["solver"] == "newton"


def test_angle_iteration_solver_agrees(capsys):
    outs = []
    for solver in ("newton", "angle-iteration"):
        code, out, err = run(capsys, "high-speed", "-b", "B218", "-F", "10 kN", "-n", "15000 rpm", "--solver", solver,
                             "--json")
        assert code == 0, err
        outs.append(json.loads(out))
    assert outs[1]["method"] == "search-triangle"
    assert outs[0]["contact_angle_outer_deg"] == pytest.approx(outs[1]["contact_angle_outer_deg"], abs=1e-6)


def test_human_output(capsys):
    code, out, _ = run(capsys, "high-speed", "-b", "B218", "-F", "20 kN", "-n", "15000 rpm", "--constants", "harris")
    assert code == 0
    for text in ("contact angle [deg]", "56.09", "21.12", "gyroscopic moment M_g [N·mm]", "friction coefficient"):
        assert text in out


def test_sweep_json_array_csv_and_plot(capsys, tmp_path):
    csv_file, png = tmp_path / "map.csv", tmp_path / "map.png"
    code, out, err = run(capsys, "high-speed", "-b", "B218", "--axial-load", "2.5kN:45kN:2.5kN",
                         "--speed", "0,3000,6000,10000,15000rpm", "--constants", "harris", "--reduced-modulus",
                         E_ROUNDED, "--json", "--csv", str(csv_file), "--plot", str(png))
    assert code == 0, err
    rows = json.loads(out)["cases"]  # the inputs, the cases and the warnings (issue 15 item 9)
    assert isinstance(rows, list) and len(rows) == 18 * 5
    assert all(set(KEYS) <= set(r) for r in rows)
    assert all(r["converged"] for r in rows)
    by_case = {(r["axial_load_N"] / 1e3, r["speed_rpm"]): r for r in rows}
    assert by_case[(45.0, 15000.0)]["contact_angle_inner_deg"] == pytest.approx(50.746, abs=1e-3)
    assert by_case[(2.5, 6000.0)]["axial_displacement_um"] == pytest.approx(-81.41, abs=5e-3)
    with csv_file.open() as fh:
        table = list(csv.DictReader(fh))
    assert len(table) == 90
    assert float(table[-1]["contact_angle_outer_deg"]) == pytest.approx(33.085, abs=1e-3)
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert not list(tmp_path.glob(".*"))  # no temporary files left


def test_sweep_table_and_failed_case_does_not_stop_it(capsys):
    code, out, err = run(capsys, "high-speed", "-b", "B218", "-F", "300N,20kN", "-n", "3000, 15000rpm",
                         "--raceway-control", "inner")
    assert code == 0, err
    assert "4 cases, 1 failed" in out  # the status column may be cut on a narrow terminal; JSON below
    code, out, _ = run(capsys, "high-speed", "-b", "B218", "-F", "300N,20kN", "-n", "3000, 15000rpm",
                       "--raceway-control", "inner", "--json")
    rows = json.loads(out)["cases"]
    status = {(r["axial_load_N"] / 1e3, r["speed_rpm"]): r["status"] for r in rows}
    assert status[(0.3, 15000.0)] == "inner_contact_lost"
    assert status[(20.0, 3000.0)] == "ok"
    failed = [r for r in rows if not r["converged"]]
    assert failed and all(r["contact_angle_inner_deg"] is None for r in failed)


def test_single_case_without_physical_solution_exits_2_with_one_line(capsys):
    """Issue 15 item 16: no physical solution is an impossible input (2), not a weak solver (3)."""
    code, out, err = run(capsys, "high-speed", "-b", "B218", "-F", "300 N", "-n", "15000 rpm",
                         "--raceway-control", "inner", "--json")
    assert code == 2 and out == ""
    line = _one_line_error(err)
    assert "leaves the inner raceway" in line and "thrust too small for the speed" in line
    assert "quasistatic." not in line  # no internal function names


def test_friction_warning_goes_to_stderr_with_json(capsys):
    code, out, err = run(capsys, "high-speed", "-b", "B218", "-F", "20 kN", "-n", "15000 rpm", "--gyroscopic-sign",
                         "reversed", "--constants", "harris", "--json")
    assert code == 0
    doc = json.loads(out)
    assert doc["gyroscopic_sign"] == "reversed" and doc["warnings"]
    assert "friction coefficient above 0.1" in err


@pytest.mark.parametrize("args,match", [
    (["-F", "20 kN", "-n", "-3000 rpm"], "speed must be >= 0"),
    (["-F", "0 kN", "-n", "3000 rpm"], "axial-load must be > 0"),
    (["-F", "20 m", "-n", "3000 rpm"], "is a length, expected a force"),
    (["-F", "20 kN", "-n", "3000 N"], "expected a speed"),
    (["-F", "20 kN", "-n", "3000 rpm", "--solver", "brent"], r"solver must be one of \['newton', 'angle-iteration'\]"),
    (["-F", "20 kN", "-n", "3000 rpm", "--constants", "jones"], "constants must be one of"),
    (["-F", "20 kN", "-n", "3000 rpm", "--raceway-control", "cage"], "raceway-control must be one of"),
    (["-F", "20 kN", "-n", "3000 rpm", "--gyroscopic-sign", "+"], "gyroscopic-sign must be one of"),
    (["-F", "20 kN", "-n", "3000 rpm", "--reduced-modulus", "-2 GPa"], "reduced-modulus must be > 0"),
    (["-F", "20 kN", "-n", "3000 rpm", "--plot", "x.png"], "plot: needs a sweep"),
    (["-F", "1kN,2kN", "-n", "3000 rpm", "--csv", "/nonexistent/dir/x.csv"], "csv: directory '/nonexistent/dir'"),
])
def test_bad_input_exits_2_with_one_line(capsys, args, match):
    code, out, err = run(capsys, "high-speed", "-b", "B218", *args)
    assert code == 2 and out == ""
    assert pytest.importorskip("re").search(match, _one_line_error(err))


def test_bearing_without_contact_angle_is_rejected(capsys):
    code, _, err = run(capsys, "high-speed", "-b", "6205-2RS", "--inner-conformity", "0.52", "--outer-conformity",
                       "0.52", "-F", "1 kN", "-n", "1000 rpm")
    assert code == 2 and "must be in (0, 90) [deg]" in _one_line_error(err)


def test_inline_ceramic_balls(capsys):
    base = ["high-speed", "-b", "B218", "-F", "10 kN", "-n", "15000 rpm", "--json"]
    _, steel, _ = run(capsys, *base)
    code, ceramic, err = run(capsys, *base, "--ball-material", "silicon_nitride")
    assert code == 0, err
    s, c = json.loads(steel), json.loads(ceramic)
    assert c["centrifugal_force_N"] < 0.45 * s["centrifugal_force_N"]
    assert c["contact_angle_outer_deg"] > s["contact_angle_outer_deg"]
    assert np.isfinite(c["axial_stiffness_N_per_um"])


def test_long_sweep_shows_a_progress_bar_on_stderr(capsys, monkeypatch):
    """A terminal gets a progress bar on stderr during long sweeps; stdout stays one JSON array."""
    from rich.console import Console

    from bearinglab.calculations import high_speed as command  # the solve's chunking lives there
    from bearinglab.cli import _common

    seen = []

    class Terminal(Console):
        def __init__(self):
            super().__init__(stderr=True, force_terminal=True, width=80)

    monkeypatch.setattr(command, "_PROGRESS_MIN_CASES", 4)
    monkeypatch.setattr(command, "_CHUNK", 3)
    monkeypatch.setattr(_common, "_stderr_console", Terminal)
    real = quasistatic.sweep

    def spy(*args, execution=None, **kw):
        def report(done, total):
            seen.append((done, total))
            execution.progress(done, total)
        return real(*args, execution=dataclasses.replace(execution, progress=report), **kw)

    monkeypatch.setattr(quasistatic, "sweep", spy)
    code, out, _err = run(capsys, "high-speed", "-b", "B218", "-F", "5kN,20kN", "-n", "0,3000,6000,15000rpm", "--json")
    assert code == 0
    assert seen == [(3, 8), (6, 8), (8, 8)]
    assert len(json.loads(out)["cases"]) == 8


@pytest.mark.parametrize(("load", "title"), [("2 kgf", "F_a = 19.6133 N at 0 rpm"), ("20 kN", "F_a = 20 kN at 0 rpm")])
def test_the_title_gives_the_thrust_in_n_below_1_kn(capsys, load, title):
    assert main(["high-speed", "-b", "4-1006095", "--axial-load", load, "--speed", "0 rpm"]) == 0
    assert title in capsys.readouterr().out

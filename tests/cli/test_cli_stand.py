"""Command line of the test-stand method: axial-angle and stand-load, and every bad-input case of issue 2."""

import itertools
import json

import pytest

from bearinglab.cli import main


def run(capsys, *args):
    code = main(list(args))
    out, err = capsys.readouterr()
    return code, out, err


def test_axial_angle_json_reproduces_print(capsys):
    code, out, err = run(capsys, "axial-angle", "--bearing", "4-1006095", "--axial-load", "2 kgf", "--hertz", "table",
                         "--elastic-constant", "paper", "--json")
    assert code == 0, err
    doc = json.loads(out)
    for key in ("contact_angle_initial_deg", "load_deflection_constant_kgf", "operating_contact_angle_deg",
                "axial_displacement_ratio", "axial_displacement_um", "ball_load_N", "converged", "iterations"):
        assert key in doc
    assert doc["contact_angle_initial_deg"] == pytest.approx(12.0)
    assert doc["load_deflection_constant_kgf"] == pytest.approx(7792.357, abs=1e-3)
    assert doc["operating_contact_angle_deg"] == pytest.approx(14 + 28 / 60 + 3.38 / 3600, abs=0.01 / 3600)
    assert doc["converged"] is True
    first = doc["iterations"][0]
    assert set(first) >= {"k", "x_rad", "contact_angle_deg", "axial_displacement_ratio", "axial_load_kgf", "error_percent"}
    assert first["x_rad"] == pytest.approx(0.0434005, abs=1e-7)
    assert doc["iterations"][1]["axial_load_kgf"] == pytest.approx(2.00004, abs=1e-5)
    assert doc["ball_load_N"] == pytest.approx(doc["axial_load_N"] / (7 * 0.24984), rel=1e-3)


def test_axial_angle_same_load_in_newtons_and_kgf(capsys):
    _, a, _ = run(capsys, "axial-angle", "-b", "4-1006095", "-F", "2 kgf", "--json")
    _, b, _ = run(capsys, "axial-angle", "-b", "4-1006095", "-F", "19.6133 N", "--json")
    assert json.loads(a)["operating_contact_angle_deg"] == pytest.approx(json.loads(b)["operating_contact_angle_deg"], abs=1e-12)


def test_axial_angle_legacy_rows(capsys):
    code, out, _ = run(capsys, "axial-angle", "-b", "4-1006095", "-F", "2 kgf", "--hertz", "table", "--legacy",
                       "--x0", "0.0433985", "--elastic-constant", "paper", "--json")
    assert code == 0
    rows = json.loads(out)["iterations"]
    assert len(rows) == 2
    assert rows[0]["contact_angle_dms"] == "14°29'16\"" and rows[1]["contact_angle_dms"] == "14°28'05\""
    assert rows[1]["x_rad"] == pytest.approx(0.0430573, abs=1e-7)


def test_axial_angle_human_output_and_load_range(capsys):
    code, out, _ = run(capsys, "axial-angle", "-b", "4-1006095", "-F", "2 kgf", "--hertz", "table",
                       "--elastic-constant", "paper")
    assert code == 0 and "7792.36 kgf" in out and "14°28'03.38\"" in out
    code, out, _ = run(capsys, "axial-angle", "-b", "4-1006095", "-F", "1kgf:4kgf:1kgf", "--json")
    cases = json.loads(out)["cases"]
    assert [c["axial_load_kgf"] for c in cases] == pytest.approx([1, 2, 3, 4])
    assert all(b["operating_contact_angle_deg"] > a["operating_contact_angle_deg"] for a, b in itertools.pairwise(cases))


def test_axial_angle_inline_geometry_equals_catalog(capsys):
    _, a, _ = run(capsys, "axial-angle", "-b", "4-1006095", "-F", "2 kgf", "--json")
    code, b, err = run(capsys, "axial-angle", "--balls", "7", "--ball-diameter", "2 mm", "--pitch-diameter", "0.87355 cm",
                       "--inner-groove-radius", "1.05 mm", "--outer-groove-radius", "1.16 mm", "--contact-angle", "12 deg",
                       "-F", "2 kgf", "--json")
    assert code == 0, err
    assert json.loads(a)["operating_contact_angle_deg"] == pytest.approx(json.loads(b)["operating_contact_angle_deg"], abs=1e-10)


def test_axial_angle_from_clearance(capsys):
    code, out, err = run(capsys, "axial-angle", "-b", "4-1006095", "--radial-clearance", "9.178 um", "-F", "2 kgf", "--json")
    assert code == 0, err
    assert json.loads(out)["contact_angle_initial_deg"] == pytest.approx(12.0, abs=1e-3)


def test_stand_load_json(capsys):
    code, out, _ = run(capsys, "stand-load", "-b", "4-1006095", "--speed", "10000 rpm", "--json")
    assert code == 0
    doc = json.loads(out)
    assert doc["min_axial_load_kgf"] == pytest.approx(1.1549e-10 * 1e8, rel=1e-4)
    assert doc["min_axial_load_N"] == pytest.approx(doc["min_axial_load_kgf"] * 9.80665)
    assert doc["max_axial_load_kgf"] == pytest.approx(1.2 * doc["min_axial_load_kgf"])
    assert doc["max_axial_load_N"] == pytest.approx(1.2 * doc["min_axial_load_N"])
    code, out, _ = run(capsys, "stand-load", "-b", "4-1006095", "--speed", "3000, 10000rpm")
    assert code == 0 and "0.001039" in out


BAD = [
    (["axial-angle", "--balls", "0", "--ball-diameter", "2 mm", "--pitch-diameter", "8.7 mm", "--inner-conformity", "0.52",
      "--outer-conformity", "0.53", "--contact-angle", "12 deg", "-F", "2 kgf"], r"balls must be an integer >= 1"),
    (["axial-angle", "-b", "4-1006095", "--ball-diameter", "-2 mm", "-F", "2 kgf"], r"ball-diameter must be > 0 \[mm\], got -2 mm"),
    (["axial-angle", "-b", "4-1006095", "--inner-conformity", "0.5", "-F", "2 kgf"], r"inner-conformity must be in \(0.5, 10\) \[-\], got 0.5"),
    (["axial-angle", "-b", "4-1006095", "--pitch-diameter", "1.5 mm", "-F", "2 kgf"], r"pitch-diameter must be > ball_diameter \[mm\], got 1.5 mm"),
    (["axial-angle", "-b", "4-1006095", "--radial-clearance", "0.5 mm", "-F", "2 kgf"], r"radial-clearance must be in \[-4, 0.42\) \[mm\].*got 0.5 mm"),  # from -2 D: a preload (issue 30)
    (["axial-angle", "-b", "4-1006095", "--radial-clearance", "0.9 mm", "-F", "2 kgf"], r"radial-clearance must be in \(0, 0.84\) \[mm\] to give a real contact angle, got 0.9 mm"),
    (["axial-angle", "-b", "4-1006095", "--contact-angle", "0 deg", "-F", "2 kgf"], r"contact-angle must be in \(0, 90\) \[deg\]"),
    (["axial-angle", "-b", "4-1006095", "--contact-angle", "95 deg", "-F", "2 kgf"], r"contact-angle must be in \[0, 90\) \[deg\], got 95"),
    (["axial-angle", "-b", "4-1006095", "-F", "0 N"], r"axial-load must be > 0 \[N\], got 0 N \(0 kgf\)"),
    (["axial-angle", "-b", "4-1006095", "-F", "-2 kgf"], r"axial-load must be > 0 \[N\]"),
    (["axial-angle", "-b", "4-1006095", "-F", "2 m"], r"axial-load: '2 m' is a length, expected a force"),
    (["axial-angle", "-b", "4-1006095", "-F", "2"], r"axial-load: '2' has no unit"),
    (["axial-angle", "-b", "no-such-bearing", "-F", "2 kgf"], r"unknown name 'no-such-bearing'; .*catalog list` shows the \d+ names"),
    (["axial-angle", "-b", "B218", "-F", "2 kgf", "--hertz", "table"], r"no tabulated Hertz coefficients"),
    (["stand-load", "-b", "4-1006095", "--speed", "3000 N"], r"speed: '3000 N' is a force, expected a speed"),
    (["stand-load", "-b", "4-1006095", "--speed", "-3000 rpm"], r"speed must be >= 0 \[rpm\].*, got -3000 rpm"),
    (["stand-load", "-b", "1000095", "--speed", "3000 rpm"], r"n_balls of '1000095' is not known"),
]


@pytest.mark.parametrize("args, match", BAD, ids=[" ".join(a[1:4]) + " " + a[-1] for a, _ in BAD])
def test_bad_input_is_one_line_exit_2(capsys, args, match):
    import re

    code, out, err = run(capsys, *args)
    assert code == 2
    assert "Traceback" not in err and out == ""
    lines = err.strip().splitlines()
    assert len(lines) == 1, err
    assert re.search(match, lines[0]), lines[0]


def test_non_convergence_is_one_line_exit_3(capsys, monkeypatch):
    from bearinglab import _solve

    monkeypatch.setattr(_solve, "AXIAL_ANGLE_MAX_ITER", 1)
    import bearinglab.static as st

    monkeypatch.setattr(st.operating_contact_angle, "__kwdefaults__",
                        dict(st.operating_contact_angle.__kwdefaults__, max_iter=1, xtol=0.0, ftol_percent=0.0))
    code, _out, err = run(capsys, "axial-angle", "-b", "4-1006095", "-F", "2 kgf")
    assert code == 3
    assert err.count("\n") == 1 and "no convergence after 1 iterations" in err and "Traceback" not in err


@pytest.mark.parametrize("angle", [88.0, 89.0, 89.5])
def test_axial_angle_at_steep_angles_computes_and_says_the_static_check_is_unavailable(capsys, angle):
    # issue 20 item 17: from about 87.5 deg on (4-1006095), Dw cos(alpha)/Dpw leaves the ISO 281 table that the ratings
    # come from; the optional check of P0 against C0 once refused the whole computation
    import math

    code, out, err = run(capsys, "axial-angle", "-b", "4-1006095", "--contact-angle", f"{angle} deg", "-F", "2 kgf",
                         "--json")
    assert code == 0, err
    doc = json.loads(out)
    alpha, a0 = math.radians(doc["operating_contact_angle_deg"]), math.radians(angle)
    assert a0 < alpha < math.pi / 2 and doc["converged"] is True
    # eq. (1) of spec 000 at the angle found: F_a / C* = sin(alpha) (cos(alpha0)/cos(alpha) - 1)^(3/2)
    ratio = math.sin(alpha) * (math.cos(a0) / math.cos(alpha) - 1.0) ** 1.5
    assert ratio == pytest.approx(doc["axial_load_N"] / doc["load_deflection_constant_N"], rel=1e-9)
    unavailable = [w for w in doc["warnings"] if "check of P0 against C0 is unavailable" in w]
    assert len(unavailable) == 1 and "ISO 281" in unavailable[0]


def test_axial_angle_below_the_steep_angles_keeps_the_static_check(capsys):
    code, out, err = run(capsys, "axial-angle", "-b", "4-1006095", "--contact-angle", "40 deg", "-F", "2000 kgf",
                         "--json")
    assert code == 0, err
    warnings = json.loads(out)["warnings"]
    assert not [w for w in warnings if "unavailable" in w]
    assert [w for w in warnings if w.startswith("static load: P0 = ")]  # the check ran, and 2000 kgf exceeds C0

"""The ``bearinglab frequencies`` command, run in-process through ``bearinglab.cli.main``."""

import csv
import json
import math
import re

import pytest

from bearinglab import catalog, kinematics, static
from bearinglab.cli import main

KEYS = ("ftf", "bpfo", "bpfi", "bsf")


def run(capsys, *argv):
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def run_json(capsys, *argv):
    code, out, err = run(capsys, *argv, "--json")
    assert code == 0, err
    return json.loads(out)


def test_json_cwru_bearing(capsys):
    doc = run_json(capsys, "frequencies", "--bearing", "6205-2RS", "--speed", "1797 rpm")
    assert doc["shaft_hz"] == pytest.approx(1797 / 60, rel=1e-14)
    for name in KEYS + ("two_bsf",):
        assert f"{name}_hz" in doc and f"{name}_order" in doc
        assert doc[f"{name}_hz"] == pytest.approx(doc[f"{name}_order"] * doc["shaft_hz"], rel=1e-14)
        assert doc["nominal"][f"{name}_hz"] == doc[f"{name}_hz"]  # no load: operating = nominal
        assert doc["shift_hz"][name] == 0.0
    # the published CWRU multipliers (see test_kinematics for the FTF discussion)
    assert f"{doc['bpfi_order']:.4f}" == "5.4152"
    assert f"{doc['bpfo_order']:.4f}" == "3.5848"
    assert f"{doc['two_bsf_order']:.4f}" == "4.7135"
    assert doc["contact_angle_deg"] == 0.0
    assert "mask" not in doc


def test_json_at_operating_angle_under_axial_load(capsys):
    doc = run_json(
        capsys, "frequencies", "-b", "4-1006095", "--speed", "3000 rpm", "--axial-load", "2 kgf",
        "--elastic-constant", "paper",  # the source's constant: its printed angle
    )
    b = catalog.get("4-1006095")
    alpha = float(static.stand_analysis(b, 2 * 9.80665, elastic_constant="paper").contact_angle)
    assert doc["contact_angle_deg"] == pytest.approx(math.degrees(alpha), rel=1e-14)
    assert doc["contact_angle_dms"] == "14°27'56.81\""  # spec 000 section 8, exact Hertz
    assert doc["nominal"]["contact_angle_deg"] == pytest.approx(12.0, rel=1e-14)
    op = kinematics.characteristic_frequencies(
        2 * math.pi * 50, b.ball_diameter, b.pitch_diameter, b.n_balls, alpha
    )
    nom = kinematics.characteristic_frequencies(
        2 * math.pi * 50, b.ball_diameter, b.pitch_diameter, b.n_balls, b.contact_angle
    )
    for name in KEYS:
        assert doc[f"{name}_hz"] == pytest.approx(getattr(op, name) / (2 * math.pi), rel=1e-14)
        assert doc["nominal"][f"{name}_hz"] == pytest.approx(
            getattr(nom, name) / (2 * math.pi), rel=1e-14
        )
        assert doc[f"{name}_order"] == pytest.approx(doc[f"{name}_hz"] / 50.0, rel=1e-14)
        assert doc["shift_hz"][name] == pytest.approx(
            doc[f"{name}_hz"] - doc["nominal"][f"{name}_hz"], rel=1e-9
        )
    assert doc["shift_percent"]["bpfi"] < 0 < doc["shift_percent"]["bpfo"]
    assert doc["axial_load_kgf"] == pytest.approx(2.0, rel=1e-15)


def test_table_hertz_gives_the_printed_operating_angle(capsys):
    doc = run_json(
        capsys,
        "frequencies",
        "-b",
        "4-1006095",
        "--speed",
        "3000 rpm",
        "-F",
        "2 kgf",
        "--hertz",
        "table",
        "--elastic-constant",
        "paper",
    )
    assert doc["contact_angle_dms"] == "14°28'03.38\""  # spec 000 section 8, table coefficients


def test_outer_ring_rotating(capsys):
    doc = run_json(
        capsys, "frequencies", "-b", "6205-2RS", "--speed", "0 rpm", "--outer-speed", "1800 rpm"
    )
    o = kinematics.characteristic_orders(7.94e-3, 39.04e-3, 9, 0.0)
    assert doc["bpfo_hz"] == pytest.approx(30.0 * o.bpfo, rel=1e-12)
    assert doc["bpfi_hz"] == pytest.approx(30.0 * o.bpfi, rel=1e-12)
    assert doc["ftf_hz"] == pytest.approx(
        30.0 * (1 - o.ftf), rel=1e-12
    )  # cage follows the outer ring
    assert doc["bpfo_order"] is None  # orders are multiples of the (zero) shaft speed


def test_mask_json_and_csv(capsys, tmp_path):
    path = tmp_path / "mask.csv"
    doc = run_json(
        capsys,
        "frequencies",
        "-b",
        "6205-2RS",
        "--speed",
        "50 Hz",
        "--mask",
        "--harmonics",
        "2",
        "--sidebands",
        "1",
        "--band",
        "4 %",
        "--csv",
        str(path),
    )
    lines = doc["mask"]["lines"]
    assert doc["mask"]["band_percent"] == pytest.approx(4.0)
    m = kinematics.spectral_mask(
        2 * math.pi * 50, 7.94e-3, 39.04e-3, 9, 0.0, harmonics=2, sidebands=1, band=0.04
    )
    assert len(lines) == len(m.name)
    for line, f, lo, hi, name in zip(lines, m.frequency, m.low, m.high, m.name):
        assert line["name"] == name
        assert line["frequency_hz"] == pytest.approx(f / (2 * math.pi), rel=1e-14)
        assert line["low_hz"] == pytest.approx(lo / (2 * math.pi), rel=1e-14)
        assert line["high_hz"] == pytest.approx(hi / (2 * math.pi), rel=1e-14)
        assert line["order"] == pytest.approx(line["frequency_hz"] / 50.0, rel=1e-14)
    with path.open() as fh:
        rows = list(csv.DictReader(fh))
    assert len(rows) == len(lines)
    assert rows[0].keys() == lines[0].keys()
    assert float(rows[7]["frequency_hz"]) == pytest.approx(lines[7]["frequency_hz"], rel=1e-12)
    assert [p.name for p in tmp_path.iterdir()] == ["mask.csv"]  # no temporary file left behind


def test_human_output(capsys, tmp_path):
    code, out, err = run(
        capsys,
        "frequencies",
        "-b",
        "4-1006095",
        "--speed",
        "3000 rpm",
        "-F",
        "2 kgf",
        "--mask",
        "--harmonics",
        "1",
        "--csv",
        str(tmp_path / "m.csv"),
    )
    assert code == 0, err
    assert "BPFI" in out and "2·BSF" in out and "Spectral mask" in out and "shift" in out
    assert "214.1908" in out  # nominal BPFI [Hz] at 3000 rpm, 12 deg
    assert "written to" in out
    assert err == ""


def test_inline_geometry(capsys):
    doc = run_json(
        capsys,
        "frequencies",
        "--balls",
        "9",
        "--ball-diameter",
        "7.94 mm",
        "--pitch-diameter",
        "39.04 mm",
        "--contact-angle",
        "0 deg",
        "--speed",
        "1797 rpm",
    )
    assert f"{doc['bpfi_order']:.4f}" == "5.4152"


@pytest.mark.parametrize(
    "argv, match",
    [
        (["-b", "nope", "--speed", "3000 rpm"], r"unknown name 'nope'; .*catalog list` shows the \d+ names"),
        (["-b", "6205-2RS", "--speed", "3000 m"], r"speed: '3000 m' is a length, expected a speed"),
        (["-b", "6205-2RS", "--speed", "3000"], r"speed: '3000' has no unit"),
        (
            ["-b", "6205-2RS", "--speed", "3000 rpm", "--outer-speed", "3000 rpm"],
            r"rings must turn relative",
        ),
        (
            ["-b", "6205-2RS", "--speed", "3000 rpm", "--band", "0 %"],
            r"band must be in \(0, 200\) \[%\], got 0 %",
        ),
        (["-b", "6205-2RS", "--speed", "3000 rpm", "--band", "wide"], r"band: cannot read 'wide'"),
        (
            ["-b", "6205-2RS", "--speed", "3000 rpm", "--harmonics", "0"],
            r"harmonics must be an integer >= 1",
        ),
        (
            ["-b", "6205-2RS", "--speed", "3000 rpm", "--sidebands", "-1"],
            r"sidebands must be an integer >= 0",
        ),
        (
            ["-b", "4-1006095", "--speed", "3000 rpm", "-F", "2 m"],
            r"axial-load: '2 m' is a length, expected a force",
        ),
        (
            ["-b", "4-1006095", "--speed", "3000 rpm", "-F", "0 kgf"],
            r"axial-load must be > 0 \[N\], got 0 N \(0 kgf\)",
        ),
        (["-b", "4-1006095", "--speed", "3000 rpm", "-F", "-1 N"], r"axial-load must be > 0 \[N\]"),
        (
            ["-b", "4-1006095", "--speed", "3000 rpm", "-F", "2 kgf", "--hertz", "rough"],
            r"hertz must be one of",
        ),
        # the axial-load method needs the groove conformities ...
        (
            ["--balls", "9", "--ball-diameter", "7.94 mm", "--pitch-diameter", "39.04 mm", "--contact-angle",
             "10 deg", "--speed", "3000 rpm", "-F", "2 kgf"],
            r"inner_conformity of 'inline' is not known",
        ),
        # ... and a nominal angle in (0, 90 deg)
        (
            [
                "-b",
                "6205-2RS",
                "--inner-conformity",
                "0.52",
                "--outer-conformity",
                "0.53",
                "--speed",
                "3000 rpm",
                "-F",
                "2 kgf",
            ],
            r"contact_angle must be in \(0, 90\) \[deg\] for the axial-load method, got 0",
        ),
        # the friction-rig bearings have no ball set in the catalog
        (["-b", "18", "--speed", "3000 rpm"], r"n_balls of '18' is not known"),
        (
            [
                "--balls",
                "0",
                "--ball-diameter",
                "2 mm",
                "--pitch-diameter",
                "9 mm",
                "--contact-angle",
                "0 deg",
                "--speed",
                "3000 rpm",
            ],
            r"balls must be an integer >= 1",
        ),
        (
            [
                "--balls",
                "7",
                "--ball-diameter",
                "9 mm",
                "--pitch-diameter",
                "9 mm",
                "--contact-angle",
                "0 deg",
                "--speed",
                "3000 rpm",
            ],
            r"pitch-diameter must be > ball_diameter",
        ),
        (
            [
                "--balls",
                "7",
                "--ball-diameter",
                "-2 mm",
                "--pitch-diameter",
                "9 mm",
                "--contact-angle",
                "0 deg",
                "--speed",
                "3000 rpm",
            ],
            r"ball-diameter must be > 0",
        ),
        (
            [
                "--balls",
                "7",
                "--ball-diameter",
                "2 mm",
                "--pitch-diameter",
                "9 mm",
                "--contact-angle",
                "95 deg",
                "--speed",
                "3000 rpm",
            ],
            r"contact-angle must be in \[0, 90\)",
        ),
        (
            [
                "--balls",
                "7",
                "--ball-diameter",
                "2 mm",
                "--pitch-diameter",
                "9 mm",
                "--inner-conformity",
                "0.5",
                "--outer-conformity",
                "0.52",
                "--contact-angle",
                "10 deg",
                "--speed",
                "3000 rpm",
            ],
            r"inner-conformity must be in \(0.5, 10\)",
        ),
        (
            [
                "--balls",
                "7",
                "--ball-diameter",
                "2 mm",
                "--pitch-diameter",
                "9 mm",
                "--inner-conformity",
                "0.52",
                "--outer-conformity",
                "0.52",
                "--radial-clearance",
                "0.5 mm",
                "--speed",
                "3000 rpm",
            ],
            r"radial-clearance must be in \(0, 0.32\) \[mm\] to give a real contact angle, got 0.5 mm",
        ),
        (["--speed", "3000 rpm"], r"bearing: give --bearing NAME"),
    ],
)
def test_bad_input_one_line_exit_2(capsys, argv, match):
    code, out, err = run(capsys, "frequencies", *argv)
    assert code == 2
    assert out == ""
    assert "Traceback" not in err
    assert len(err.strip().splitlines()) == 1, err
    assert re.search(match, err), err


def test_missing_speed_is_a_usage_error(capsys):
    code, _out, err = run(capsys, "frequencies", "-b", "6205-2RS")
    assert code == 2 and "Traceback" not in err and "--speed" in err
    assert len(err.strip().splitlines()) == 1


def test_bad_option_type_is_a_usage_error(capsys):
    code, _out, err = run(
        capsys, "frequencies", "-b", "6205-2RS", "--speed", "1 rpm", "--harmonics", "many"
    )
    assert code == 2 and "Traceback" not in err and "--harmonics" in err
    assert len(err.strip().splitlines()) == 1


def test_csv_to_missing_directory_writes_nothing(capsys, tmp_path):
    target = tmp_path / "no" / "mask.csv"
    code, _out, err = run(
        capsys, "frequencies", "-b", "6205-2RS", "--speed", "3000 rpm", "--csv", str(target)
    )
    assert code == 2 and "does not exist" in err and len(err.strip().splitlines()) == 1
    assert not target.exists()


def test_csv_failure_keeps_the_old_file(capsys, tmp_path, monkeypatch):
    target = tmp_path / "mask.csv"
    target.write_text("old contents\n")

    def broken(*args, **kwargs):
        raise OSError(28, "No space left on device", str(target))

    import bearinglab._io as mod  # the whole-or-nothing writer every output goes through

    monkeypatch.setattr(mod.os, "replace", broken)
    code, _out, err = run(
        capsys, "frequencies", "-b", "6205-2RS", "--speed", "3000 rpm", "--csv", str(target)
    )
    assert code == 2 and "No space left" in err
    assert target.read_text() == "old contents\n"
    assert [p.name for p in tmp_path.iterdir()] == ["mask.csv"]


def test_default_elastic_constant_comes_from_the_materials(capsys):
    doc = run_json(capsys, "frequencies", "-b", "4-1006095", "--speed", "3000 rpm", "--axial-load", "2 kgf")
    alpha = float(static.stand_analysis(catalog.get("4-1006095"), 2 * 9.80665).contact_angle)
    assert doc["contact_angle_deg"] == pytest.approx(math.degrees(alpha), rel=1e-14)

"""``runout monte-carlo --write-worst N``: the error files of the worst samples, each reproduced exactly by
``runout --errors FILE`` (defect 6: a Monte Carlo outlier could not be re-run)."""

import json
from pathlib import Path

import pytest

from bearinglab import runout
from bearinglab.cli import main

MC = str(
    Path(__file__).resolve().parent.parent / "examples" / "runout" / "monte_carlo_reference.toml"
)
STUDY = ["--ball-grade", "G10", "--ring-class", "P5", "--samples", "15", "--seed", "5"]
ROTATION = ["--steps-per-rev", "40", "--revolutions", "2"]


def run(capsys, *args):
    code = main(list(args))
    out, err = capsys.readouterr()
    return code, out, err


def test_written_worst_samples_rerun_to_the_bit(capsys, tmp_path):
    args = ["runout", "monte-carlo", "--geometry", MC, *STUDY, *ROTATION, "--json"]
    code, out, err = run(
        capsys, *args, "--write-worst", "2", "--worst-by", "axial_ptp", "--worst-dir", str(tmp_path)
    )
    assert code == 0, err
    files = json.loads(out)["worst_error_files"]
    geometry = runout.load_geometry_file(MC)
    study = runout.monte_carlo(geometry, "G10", "P5", 15, 5, steps_per_revolution=40, revolutions=2)
    worst = runout.worst_samples(study, "axial_ptp", 2)
    assert [Path(f).name for f in files] == [f"sample_{i}.toml" for i in worst]
    for i, path in zip(worst, files):
        code, out, err = run(capsys, "runout", "--errors", path, *ROTATION, "--json")
        assert code == 0, err
        doc = json.loads(out)
        for name in runout.METRICS:  # the same float, printed and parsed back by json
            assert doc[f"{name}_um"] == float(getattr(study.samples, name)[i]) / 1e-6, name


def test_text_output_lists_the_files(capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)  # --worst-dir defaults to the working directory
    code, out, err = run(
        capsys, "runout", "monte-carlo", "--geometry", MC, *STUDY, *ROTATION, "--write-worst", "1"
    )
    assert code == 0, err
    assert "worst_error_files: sample_" in out
    assert len(list(tmp_path.glob("sample_*.toml"))) == 1


@pytest.mark.parametrize(
    "extra, match",
    [
        (["--write-worst", "0"], "write-worst must be >= 1"),
        (["--write-worst", "1", "--worst-by", "runout"], "worst-by must be one of ['radial_ptp_x'"),
        (["--worst-dir", "x"], "worst-dir: give --write-worst N too"),
    ],
)
def test_bad_write_worst_options_fail_before_the_study(capsys, extra, match):
    code, _out, err = run(
        capsys, "runout", "monte-carlo", "--geometry", MC, "--samples", "4", *extra
    )
    assert code == 2
    assert err.count("\n") == 1 and match in err and "Traceback" not in err

"""Issue 29, item 4: inputs never touched. Every output of a run, files written inside an ``--out`` or
``--plot`` directory included, is checked against every input file the run read (the session, its
measurements, the error file, its profiles, a geometry, a catalog) before anything is written
(``bearinglab._io.run_files``).

The findings: ``friction lab SESSION --out DIR``, where DIR holds the session, deleted the session and
its measurements; ``runout --plot DIR`` overwrote an input with one of its fixed figure names. Each is
tested with its variants: a relative path, a path through ``..``, a symbolic link, a hard link, the
measurements alone inside the directory.
"""

import os
import shutil
from pathlib import Path

import pytest

from bearinglab import _io
from bearinglab.cli import main
from bearinglab.errors import InputError

ROOT = Path(__file__).resolve().parents[2]
FRICTION = ROOT / "examples" / "friction"
RUNOUT = ROOT / "examples" / "runout"


def run(capsys, *args):
    code = main([str(a) for a in args])
    out, err = capsys.readouterr()
    return code, out, err


def refused(capsys, *args):
    """The one-line error of a refused run (exit 2)."""
    code, _out, err = run(capsys, *args)
    assert code == 2, err
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("bearinglab: error: "), err
    return lines[0]


def snapshot(directory):
    """Every file under ``directory`` (hidden ones too) -> its bytes."""
    return {str(p.relative_to(directory)): p.read_bytes() for p in sorted(Path(directory).rglob("*"))
            if p.is_file() and not p.is_symlink()}


def _report(tmp_path, capsys, name="rep"):
    """A previous report directory (it holds the marker: a next run may replace it)."""
    rep = tmp_path / name
    code, _out, err = run(capsys, "friction", "lab", FRICTION / "s1_readings.toml", "--out", rep)
    assert code == 0, err
    assert (rep / ".bearinglab-report").is_file()
    return rep


# ----------------------------------------------------------------------------- friction lab --out
def test_friction_lab_out_holding_the_session_is_refused(tmp_path, capsys):
    rep = _report(tmp_path, capsys)
    for name in ("s1_readings.toml", "s1_readings.csv"):
        shutil.copy(FRICTION / name, rep / name)
    before = snapshot(rep)
    line = refused(capsys, "friction", "lab", rep / "s1_readings.toml", "--out", rep)
    assert line.startswith(f"bearinglab: error: out: {str(rep)!r} holds an input file of this command")
    assert "s1_readings" in line
    assert snapshot(rep) == before  # the session, its measurements and the old report, all kept
    assert sorted(p.name for p in tmp_path.iterdir()) == ["rep"]  # no temporary directory left


def test_friction_lab_out_holding_only_the_measurements_is_refused(tmp_path, capsys):
    rep = _report(tmp_path, capsys)
    shutil.copy(FRICTION / "s1_readings.csv", rep / "rows.csv")  # the report's own table name, too
    session = tmp_path / "session.toml"
    session.write_text((FRICTION / "s1_readings.toml").read_text(encoding="utf-8")
                       .replace('file = "s1_readings.csv"', 'file = "rep/rows.csv"'), encoding="utf-8")
    before = snapshot(rep)
    line = refused(capsys, "friction", "lab", session, "--out", rep)
    assert "out:" in line and "holds an input file of this command" in line and "rows.csv" in line
    assert snapshot(rep) == before


@pytest.mark.parametrize("spelling", ["relative", "dotdot", "symlink-out", "symlink-session"])
def test_friction_lab_the_same_directory_under_another_name(tmp_path, capsys, monkeypatch, spelling):
    rep = _report(tmp_path, capsys)
    for name in ("s1_readings.toml", "s1_readings.csv"):
        shutil.copy(FRICTION / name, rep / name)
    session, out = rep / "s1_readings.toml", rep
    if spelling == "relative":  # both relative to the working directory
        monkeypatch.chdir(tmp_path)
        session, out = Path("rep/s1_readings.toml"), Path("rep")
    elif spelling == "dotdot":
        (tmp_path / "sub").mkdir()
        out = tmp_path / "sub" / ".." / "rep"
    elif spelling == "symlink-out":  # --out through a link to the directory
        out = tmp_path / "link"
        out.symlink_to(rep, target_is_directory=True)
    else:  # the session read through a link that lives elsewhere: its data are inside rep
        session = tmp_path / "session-link.toml"
        session.symlink_to(rep / "s1_readings.toml")
        shutil.copy(FRICTION / "s1_readings.csv", tmp_path)  # its measurements, read beside the link
    before = snapshot(rep)
    line = refused(capsys, "friction", "lab", session, "--out", out)
    assert "holds an input file of this command" in line
    assert snapshot(rep) == before


def test_friction_lab_out_elsewhere_still_replaces_a_previous_report(tmp_path, capsys):
    rep = _report(tmp_path, capsys)
    (tmp_path / "data").mkdir()
    for name in ("s1_readings.toml", "s1_readings.csv"):
        shutil.copy(FRICTION / name, tmp_path / "data" / name)
    code, _out, err = run(capsys, "friction", "lab", tmp_path / "data" / "s1_readings.toml", "--out", rep)
    assert code == 0, err
    assert (rep / "report.html").is_file() and (tmp_path / "data" / "s1_readings.toml").is_file()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["data", "rep"]


# ----------------------------------------------------------------------------- runout --plot
def test_runout_plot_onto_its_error_file_is_refused(tmp_path, capsys):
    plots = tmp_path / "p"
    plots.mkdir()
    errors = plots / "runout_contact_psi0.png"  # an input may have any name, a figure's one too
    shutil.copy(RUNOUT / "example1_oversize_ball.toml", errors)
    before = errors.read_bytes()
    line = refused(capsys, "runout", "--errors", errors, "--plot", plots)
    assert line == (f"bearinglab: error: plot: {str(errors)!r} is an input file of this command ({errors}); "
                    f"write the output to another file")
    assert errors.read_bytes() == before and [p.name for p in plots.iterdir()] == [errors.name]


@pytest.mark.parametrize("spelling", ["relative", "hardlink", "symlink"])
def test_runout_plot_sequence_writes_nothing_when_one_figure_is_an_input(tmp_path, capsys, monkeypatch,
                                                                         spelling):
    # the third of four figures is the input: nothing is written, not the first two, nor the --csv
    plots = tmp_path / "p"
    plots.mkdir()
    original = tmp_path / "errors.toml"
    shutil.copy(RUNOUT / "example1_oversize_ball.toml", original)
    given = original
    if spelling == "relative":
        shutil.move(original, plots / "runout_spectrum.png")
        monkeypatch.chdir(plots)
        given, out = Path("runout_spectrum.png"), Path(".")
    elif spelling == "hardlink":
        os.link(original, plots / "runout_spectrum.png")
        out = plots
    else:  # the figure's name is a link to the input
        (plots / "runout_spectrum.png").symlink_to(original)
        out = plots
    before = snapshot(tmp_path)
    line = refused(capsys, "runout", "--errors", given, "--plot", out, "--revolutions", "1", "--steps-per-rev",
                   "36", "--csv", tmp_path / "t.csv")
    assert "plot:" in line and "runout_spectrum.png" in line and "is an input file of this command" in line
    assert snapshot(tmp_path) == before
    assert sorted(p.name for p in plots.iterdir()) == ["runout_spectrum.png"]
    assert not (tmp_path / "t.csv").exists()


def test_runout_plot_onto_a_measured_profile_is_refused(tmp_path, capsys):
    # the profile is read through the error file, never named on the command line
    plots = tmp_path / "p"
    plots.mkdir()
    shutil.copy(RUNOUT / "inner_roundness.csv", plots / "runout_contact_psi0.png")
    errors = tmp_path / "measured.toml"
    errors.write_text((RUNOUT / "measured_profile.toml").read_text(encoding="utf-8")
                      .replace('profile = "inner_roundness.csv"', 'profile = "p/runout_contact_psi0.png"'),
                      encoding="utf-8")
    before = snapshot(tmp_path)
    line = refused(capsys, "runout", "--errors", errors, "--plot", plots)
    assert "plot:" in line and "runout_contact_psi0.png" in line and "is an input file" in line
    assert snapshot(tmp_path) == before


def test_runout_plot_beside_its_inputs_writes_the_figures(tmp_path, capsys, monkeypatch):
    # the usual case: the error file in the working directory and the figures there too
    shutil.copy(RUNOUT / "example1_oversize_ball.toml", tmp_path / "ex1.toml")
    monkeypatch.chdir(tmp_path)
    code, _out, err = run(capsys, "runout", "--errors", "ex1.toml", "--plot", ".")
    assert code == 0, err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["ex1.toml", "runout_contact_psi0.png"]


def test_monte_carlo_worst_files_onto_the_geometry_are_refused(tmp_path, capsys):
    geometry = tmp_path / "geometry.toml"
    geometry.write_text('[bearings."X"]\nballs = 9\nball_diameter = "7.938 mm"\npitch_diameter = "38.5 mm"\n'
                        'inner_conformity = 0.52\nouter_conformity = 0.53\ncontact_angle = "15 deg"\n',
                        encoding="utf-8")
    for k in range(2):  # the two samples are the two worst: one of them has the geometry's name
        os.link(geometry, tmp_path / f"sample_{k}.toml")
    before = snapshot(tmp_path)
    line = refused(capsys, "runout", "monte-carlo", "--geometry", tmp_path / "sample_0.toml", "--samples", "2",
                   "--steps-per-rev", "8", "--revolutions", "1", "--max-order", "2", "--write-worst", "2",
                   "--worst-dir", tmp_path, "--samples-csv", tmp_path / "s.csv")
    assert "worst-dir:" in line and "is an input file of this command" in line
    assert snapshot(tmp_path) == before and not (tmp_path / "s.csv").exists()


# ----------------------------------------------------------------------------- the mechanism
def test_a_run_notes_its_inputs_and_refuses_to_write_over_them(tmp_path):
    source = tmp_path / "in.toml"
    source.write_text("a = 1\n", encoding="utf-8")
    link = tmp_path / "link.toml"
    link.symlink_to(source)
    first = tmp_path / "first.csv"
    with pytest.raises(InputError, match=r"^csv: .*in\.toml' is an input file of this command"), _io.run_files() as files:
        from bearinglab._bounds import read_input_bytes

        read_input_bytes(link)
        assert set(files.inputs) == {str(source.resolve())}
        _io.write_text(first, "x\n")
        assert not first.exists()  # staged: put in place when the run ends
        _io.name_output(tmp_path, "csv")
        _io.write_text(tmp_path / "sub" / ".." / "in.toml", "y\n")
    assert source.read_text(encoding="utf-8") == "a = 1\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["in.toml", "link.toml"]  # first.csv discarded too


def test_a_run_puts_its_outputs_in_place_at_its_end(tmp_path):
    with _io.run_files():
        _io.write_text(tmp_path / "a.csv", "a\n")
        _io.write_text(tmp_path / "b.csv", "b\n")
        assert sorted(p.name for p in tmp_path.iterdir() if not p.name.startswith(".")) == []
    assert (tmp_path / "a.csv").read_text() == "a\n" and (tmp_path / "b.csv").read_text() == "b\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.csv", "b.csv"]


def test_an_input_read_after_an_output_was_staged_is_still_protected(tmp_path):
    # the last check at the run's end sees every input the run read, the late ones too
    target = tmp_path / "late.toml"
    target.write_text("a = 1\n", encoding="utf-8")
    with pytest.raises(InputError, match="is an input file"), _io.run_files():
        _io.write_text(target, "b = 2\n")
        _io.note_input(target)
    assert target.read_text(encoding="utf-8") == "a = 1\n"
    assert [p.name for p in tmp_path.iterdir()] == ["late.toml"]


def test_outside_a_run_a_write_is_put_in_place_at_once(tmp_path):
    _io.write_text(tmp_path / "a.csv", "a\n")
    assert (tmp_path / "a.csv").read_text() == "a\n"


def test_runout_plot_onto_its_geometry_file_is_refused(tmp_path, capsys):
    # --geometry FILE (a file with a [geometry] table: the example error file), under a figure's name
    plots = tmp_path / "p"
    plots.mkdir()
    geometry = plots / "runout_contact_psi0.png"
    shutil.copy(RUNOUT / "example1_oversize_ball.toml", geometry)
    before = snapshot(tmp_path)
    line = refused(capsys, "runout", "--errors", RUNOUT / "example1_oversize_ball.toml", "--geometry", geometry,
                   "--plot", plots)
    assert "plot:" in line and "runout_contact_psi0.png" in line and "is an input file of this command" in line
    assert snapshot(tmp_path) == before

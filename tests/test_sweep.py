"""Parameter sweeps: file checking, Cartesian product, executors, per-case failures, output tables."""

import json
import math

import numpy as np
import pytest

from bearinglab import catalog, static, sweep
from bearinglab.cli import main
from bearinglab.errors import CatalogError
from bearinglab.units import KGF

SWEEP = """
model = "axial-angle"
bearing = "4-1006095"
[parameters]
axial_load = "0.5kgf:4kgf:0.5kgf"
contact_angle = ["10 deg", "12 deg", "0 deg"]
[output]
file = "result.csv"
"""


@pytest.fixture
def sweep_file(tmp_path):
    p = tmp_path / "sweep.toml"
    p.write_text(SWEEP)
    return p


def test_sweep_matches_direct_calls_and_flags_bad_cases(sweep_file):
    spec = sweep.load_sweep(sweep_file)
    cols = sweep.run_sweep(spec, chunk_size=5)
    assert len(cols["converged"]) == 8 * 3
    bad = cols["contact_angle_deg"] == 0.0
    assert not cols["converged"][bad].any() and cols["converged"][~bad].all()
    assert set(cols["failure"][bad]) == {"contact_angle must be in (0, 90) deg"}
    b = catalog.get("4-1006095")
    for load, angle, got in zip(cols["axial_load_N"][~bad], cols["contact_angle_deg"][~bad],
                                cols["operating_contact_angle_deg"][~bad]):
        r = static.stand_analysis(b.replace(contact_angle=math.radians(angle)), load)
        assert got == pytest.approx(math.degrees(r.contact_angle), abs=1e-11)


def test_chunking_and_local_cluster_give_identical_results(sweep_file):
    spec = sweep.load_sweep(sweep_file)
    ref = sweep.run_sweep(spec, chunk_size=24)
    for kw in ({"chunk_size": 24, "executor": "local", "workers": 2, "processes": False}, {"chunk_size": 24}):
        got = sweep.run_sweep(spec, **kw)
        for k in ref:
            assert np.array_equal(ref[k], got[k], equal_nan=ref[k].dtype.kind == "f"), k
    # each case's Newton stops on its own convergence, so any chunking gives the same bits
    for size in (1, 5):
        small = sweep.run_sweep(spec, chunk_size=size)
        for k in ref:
            assert np.array_equal(ref[k], small[k], equal_nan=ref[k].dtype.kind == "f"), (size, k)


@pytest.mark.parametrize("threshold", [10, 10**6])
def test_the_sweep_chooses_one_engine_for_all_its_chunks(sweep_file, monkeypatch, threshold):
    # engine="auto" of the stand solve goes by the batch size; a sweep resolves it once from its whole case
    # count (24 here), so that a chunk smaller than the threshold does not switch engines midway
    import importlib.util

    from bearinglab import _solve
    from bearinglab.stand import method as stand

    if threshold == 10 and importlib.util.find_spec("numba") is None:
        pytest.skip("numba is not installed")
    monkeypatch.setattr(_solve, "AXIAL_ANGLE_COMPILED_CASES", threshold)
    engines = []
    real = stand.operating_contact_angle
    monkeypatch.setattr(stand, "operating_contact_angle", lambda *a, engine="auto", **k: engines.append(engine)
                        or real(*a, engine=engine, **k))
    spec = sweep.load_sweep(sweep_file)
    ref = sweep.run_sweep(spec, chunk_size=24)
    got = sweep.run_sweep(spec, chunk_size=5)
    assert set(engines) == {"compiled" if threshold == 10 else "numpy"}
    for k in ref:
        assert np.array_equal(ref[k], got[k], equal_nan=ref[k].dtype.kind == "f"), k


def test_outputs_written_whole_csv_and_parquet(sweep_file, tmp_path):
    spec = sweep.load_sweep(sweep_file)
    cols = sweep.run_sweep(spec)
    sweep.write_table(cols, tmp_path / "r.csv")
    sweep.write_table(cols, tmp_path / "r.parquet")
    import csv

    import pyarrow.parquet as pq

    rows = list(csv.DictReader((tmp_path / "r.csv").open()))
    assert len(rows) == 24 and float(rows[0]["axial_load_N"]) == pytest.approx(0.5 * KGF)
    t = pq.read_table(tmp_path / "r.parquet").to_pydict()
    assert t["operating_contact_angle_deg"][1] == pytest.approx(cols["operating_contact_angle_deg"][1])
    assert not list(tmp_path.glob(".*tmp"))


def test_written_table_is_an_ordinary_file(tmp_path):
    # mkstemp makes a private (0600) file; the renamed result must be readable like any other output
    sweep.write_table({"x": np.arange(3.0)}, tmp_path / "r.csv")
    assert (tmp_path / "r.csv").stat().st_mode & 0o777 == 0o644


@pytest.mark.parametrize("text, match", [
    ('model = "warp-drive"\nbearing = "B218"\n[parameters]\naxial_load = "1 kN"', r"model: must be one of"),
    ('model = "axial-angle"\n[parameters]\naxial_load = "1 kN"', r"bearing: missing"),
    ('model = "axial-angle"\nbearing = "B218"\n[parameters]\naxial_load = "1 m"', r"parameters.axial_load: axial_load: '1 m' is a length"),
    ('model = "axial-angle"\nbearing = "B218"\n[parameters]\nspeed = "1 rpm"', r"parameters.speed: unknown parameter"),
    ('model = "axial-angle"\nbearing = "B218"\n[parameters]\ncontact_angle = "12 deg"', r"model 'axial-angle' needs axial_load"),
    ('model = "axial-angle"\nbearing = "B218"\n[parameters]\naxial_load = "1 kN"\n[output]\nfile = "a.xlsx"', r"output.file: must end in .csv or .parquet"),
    ('model = "axial-angle"\nbearing = "nope"\n[parameters]\naxial_load = "1 kN"', r"unknown name 'nope'"),
])
def test_bad_sweep_files_name_file_and_field(tmp_path, text, match):
    p = tmp_path / "bad.toml"
    p.write_text(text)
    with pytest.raises(CatalogError, match=match):
        sweep.load_sweep(p)


def test_cli_sweep_writes_table_and_json(sweep_file, tmp_path, capsys):
    assert main(["sweep", str(sweep_file), "--chunk-size", "7"]) == 0
    out = capsys.readouterr().out
    assert "cases" in out and (tmp_path / "result.csv").exists()
    assert main(["sweep", str(sweep_file), "--json", "--out", str(tmp_path / "r.parquet")]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert doc["cases"] == 24 and doc["failed"] == 8 and len(doc["results"]) == 24
    assert (tmp_path / "r.parquet").exists()


def test_cli_sweep_errors_are_one_line(tmp_path, capsys):
    p = tmp_path / "bad.toml"
    p.write_text('model = "axial-angle"\nbearing = "B218"\n[parameters]\naxial_load = "1 m"')
    assert main(["sweep", str(p)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "bad.toml: parameters.axial_load" in err
    assert main(["sweep", str(tmp_path / "missing.toml")]) == 2
    assert "no such file" in capsys.readouterr().err
    assert main(["sweep", str(tmp_path / "bad.toml"), "--executor", "tcp://127.0.0.1:9"]) == 2


def test_cli_sweep_unreachable_scheduler(sweep_file, capsys, monkeypatch):
    from bearinglab import parallel

    monkeypatch.setattr(parallel, "_CONNECT_TIMEOUT_S", 1.0)
    code = main(["sweep", str(sweep_file), "--executor", "tcp://127.0.0.1:9"])
    err = capsys.readouterr().err
    assert code == 2 and "cannot reach a dask scheduler at 'tcp://127.0.0.1:9'" in err and err.count("\n") == 1


def test_execution_value_equals_the_keyword_arguments(sweep_file):
    from bearinglab.errors import InputError
    from bearinglab.parallel import Execution

    spec = sweep.load_sweep(sweep_file)
    seen = []
    ref = sweep.run_sweep(spec, chunk_size=7)
    got = sweep.run_sweep(spec, execution=Execution(chunk_size=7, progress=lambda d, t: seen.append((d, t))))
    for k in ref:
        assert np.array_equal(ref[k], got[k], equal_nan=ref[k].dtype.kind == "f"), k
    assert seen == [(7, 24), (14, 24), (21, 24), (24, 24)]
    # chunk size left None: the file's (here the default); executor of the value, not of the file
    assert sweep.run_sweep(spec, execution=Execution())["converged"].sum() == 16
    with pytest.raises(InputError, match="not both"):
        sweep.run_sweep(spec, execution=Execution(), workers=2)


def test_input_columns_carry_no_unit_round_trip_noise(tmp_path):
    path = tmp_path / "s.toml"
    path.write_text('model = "high-speed"\nbearing = "B218"\n[parameters]\naxial_load = "20 kN"\n'
                    'speed = "1797 rpm, 3000 rpm"\n', encoding="utf-8")
    cols = sweep.run_sweep(sweep.load_sweep(path))
    assert cols["speed_rpm"].tolist() == [1797.0, 3000.0]
    assert cols["axial_load_N"].tolist() == [20000.0, 20000.0]

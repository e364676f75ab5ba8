"""Results as engineering-unit columns (bearinglab.tables): conversions, orders, the writers."""

import csv
import json
import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from bearinglab import catalog, kinematics, quasistatic, runout, static, tables
from bearinglab.units import KGF, RPM


@pytest.fixture(scope="module")
def b218_grid():
    """A small thrust x speed grid of bearing B218."""
    return quasistatic.sweep(catalog.get("B218"), np.array([5e3, 20e3]), np.array([0.0, 6000.0]) * RPM)


def test_quasistatic_result_table_is_the_tables_one(b218_grid):
    """One place turns a high-speed state into columns: the old quasistatic spelling answers with it."""
    got, ref = tables.high_speed(b218_grid), quasistatic.result_table(b218_grid)
    assert list(got) == list(ref) == [c.name for c in tables.HIGH_SPEED]
    assert list(ref)[:2] == ["axial_load_N", "speed_rpm"]  # the CLI's column order, pinned by its tests too


def test_high_speed_units(b218_grid):
    cols = tables.high_speed(b218_grid)
    s = b218_grid
    assert cols["axial_load_N"].tolist() == [5e3, 5e3, 20e3, 20e3]  # inputs without round-trip noise
    assert cols["speed_rpm"].tolist() == [0.0, 6000.0, 0.0, 6000.0]
    assert cols["contact_angle_inner_deg"] == pytest.approx(np.degrees(s.contact_angle_inner).ravel(), rel=1e-15)
    assert cols["gyroscopic_moment_Nmm"] == pytest.approx(s.gyroscopic_moment.ravel() * 1000.0, rel=1e-15)
    assert cols["deflection_outer_um"] == pytest.approx(s.deflection_outer.ravel() / 1e-6, rel=1e-15)
    assert cols["max_pressure_inner_MPa"] == pytest.approx(s.max_pressure_inner.ravel() / 1e6, rel=1e-15)
    assert cols["bpfi_hz"] == pytest.approx(s.bpfi.ravel() / (2 * math.pi), rel=1e-15)


@given(st.floats(-1e9, 1e9, allow_nan=False))
def test_a_kgf_column_divides_by_the_kilogram_force(x):
    """Factor and divisor apart: the kgf column is bit for bit ``x / KGF``, as printed elsewhere."""
    assert tables.Column("f", "f", "kgf", 1.0, KGF).convert(x) == x / KGF


def test_axial_angle_columns_match_the_analysis():
    loads = np.array([1.0, 2.0, 5.0]) * KGF
    r = static.stand_analysis(catalog.get("4-1006095"), loads)
    cols = tables.columns(r, tables.AXIAL_ANGLE)
    assert list(cols) == ["axial_load_N", "axial_load_kgf", "operating_contact_angle_deg",
                          "axial_displacement_ratio", "axial_displacement_um", "ball_load_N"]
    assert cols["axial_load_kgf"] == pytest.approx([1.0, 2.0, 5.0], rel=1e-15)
    assert cols["operating_contact_angle_deg"] == pytest.approx(np.degrees(r.contact_angle), rel=1e-15)
    assert cols["axial_displacement_um"] == pytest.approx(r.axial_displacement * 1e6, rel=1e-15)


def test_stand_load_columns():
    speeds = np.array([3000.0, 10000.0]) * RPM
    res = static.min_axial_load(speeds, 9, 2e-3, 8.7355e-3, math.radians(12))
    cols = tables.stand_load(speeds, res)
    assert cols["speed_rpm"] == pytest.approx([3000.0, 10000.0], rel=1e-15)
    assert cols["max_axial_load_N"] == pytest.approx(1.2 * cols["min_axial_load_N"], rel=1e-15)
    assert cols["min_axial_load_kgf"] * KGF == pytest.approx(cols["min_axial_load_N"], rel=1e-15)


def test_record_and_rows():
    g = runout.geometry_from_bearing(catalog.get("B218"))
    rec = tables.record(g, tables.RUNOUT_GEOMETRY)
    assert rec["balls"] == g.n_balls and isinstance(rec["balls"], int)
    assert rec["ball_diameter_mm"] == pytest.approx(catalog.get("B218").ball_diameter * 1e3, rel=1e-14)
    assert rec["contact_angle_deg"] == pytest.approx(math.degrees(g.contact_angle), rel=1e-15)
    rows = tables.rows({"x": np.array([1.5, np.nan]), "ok": np.array([True, False]), "n": np.array([1, 2])})
    assert rows == [{"x": 1.5, "ok": True, "n": 1}, {"x": None, "ok": False, "n": 2}]
    assert [type(v) for v in rows[0].values()] == [float, bool, int]


def test_input_columns_and_significant():
    cols = tables.input_columns({"speed": np.array([3000.0 * RPM]), "contact_angle": np.array([math.pi / 6]),
                                 "axial_load": np.array([10.0])},
                                {"speed": "speed", "contact_angle": "angle", "axial_load": "force"})
    assert list(cols) == ["speed_rpm", "contact_angle_deg", "axial_load_N"]
    assert cols["speed_rpm"][0] == pytest.approx(3000.0, rel=1e-15)
    assert cols["contact_angle_deg"][0] == pytest.approx(30.0, rel=1e-15)
    assert tables.significant(cols["speed_rpm"]).tolist() == [3000.0]
    assert tables.significant([1.0 / 3.0]).tolist() == [0.333333333333]


def test_catalog_entry_and_bearing_summary():
    b = catalog.get("4-1006095")
    entry = tables.catalog_entry("4-1006095", b)
    assert entry["balls"] == b.n_balls
    assert entry["ball_diameter_mm"] == pytest.approx(b.ball_diameter * 1e3, rel=1e-15)
    assert entry["contact_angle_deg"] == pytest.approx(12.0, rel=1e-12)
    s = tables.bearing_summary(b)
    assert s["designation"] == "4-1006095" and s["gamma"] == pytest.approx(b.gamma, rel=1e-15)
    assert s["axial_play_mm"] == pytest.approx(b.axial_play() * 1e3, rel=1e-15)


def test_runout_metrics():
    m = runout.RunoutMetrics(*[k * 1e-6 for k in range(1, len(runout.RunoutMetrics._fields) + 1)])
    got = tables.runout_metrics(m, runout.METRICS)
    assert list(got) == [f"{n}_um" for n in runout.METRICS]
    assert got["radial_ptp_x_um"] == pytest.approx(m.radial_ptp_x * 1e6, rel=1e-15)


# --------------------------------------------------------------------------- writers
def test_csv_cells_nan_bool_and_full_precision(tmp_path):
    path = tmp_path / "t.csv"
    x = np.array([0.1 + 0.2, np.nan, -np.inf])
    tables.write_table({"x": x, "ok": np.array([True, False, True]), "status": np.array(["ok", "", "x"], dtype=object)},
                       path, comments=["source: test"])
    text = path.read_text(encoding="utf-8")
    assert text.splitlines()[:2] == ["# source: test", "x,ok,status"]
    assert "\r" not in text
    rows = list(csv.DictReader(line for line in text.splitlines() if not line.startswith("#")))
    assert float(rows[0]["x"]) == 0.1 + 0.2  # repr: round trip exact
    assert [r["x"] for r in rows[1:]] == ["", ""]
    assert [r["ok"] for r in rows] == ["true", "false", "true"]
    assert path.stat().st_mode & 0o777 == 0o644


@given(st.lists(st.floats(allow_nan=False, allow_infinity=False), min_size=1, max_size=5))
def test_csv_round_trips_every_finite_float(values):
    text = tables.csv_text(["v"], [[v] for v in values])
    assert [float(line) for line in text.splitlines()[1:]] == values


def test_parquet_round_trip(tmp_path):
    pq = pytest.importorskip("pyarrow.parquet")
    cols = {"x": np.array([1.0, np.nan]), "status": np.array(["ok", None], dtype=object)}
    tables.write_table(cols, tmp_path / "t.parquet")
    t = pq.read_table(tmp_path / "t.parquet").to_pydict()
    assert t["x"][0] == 1.0 and math.isnan(t["x"][1]) and t["status"] == ["ok", "None"]


def test_failed_write_keeps_the_old_file(tmp_path, monkeypatch):
    import bearinglab._io as io_module

    path = tmp_path / "t.csv"
    path.write_text("old\n")

    def broken(*args):
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(io_module.os, "replace", broken)
    with pytest.raises(OSError, match="No space"):
        tables.write_table({"x": np.arange(3.0)}, path)
    assert path.read_text() == "old\n" and [p.name for p in tmp_path.iterdir()] == ["t.csv"]


def test_json_text_nan_numpy_and_unicode():
    doc = {"a": np.float64("nan"), "b": np.int64(3), "c": np.array([1.0, np.inf]), "d": (np.bool_(True),), "µ": "α"}
    text = tables.json_text(doc)
    assert text.endswith("}\n") and "µ" in text and "α" in text
    assert json.loads(text) == {"a": None, "b": 3, "c": [1.0, None], "d": [True], "µ": "α"}


def test_frequencies_and_spectral_mask_in_hz_and_orders():
    b = catalog.get("6205-2RS")
    w = 1797 * RPM
    f = kinematics.characteristic_frequencies(w, b.ball_diameter, b.pitch_diameter, b.n_balls, b.contact_angle)
    got = tables.frequencies(f, w)
    assert list(got)[:2] == ["ftf_hz", "ftf_order"]
    assert got["bpfi_hz"] == pytest.approx(float(f.bpfi) / (2 * math.pi), rel=1e-15)
    assert got["bpfi_order"] == pytest.approx(float(f.bpfi) / w, rel=1e-14)
    m = kinematics.spectral_mask(w, b.ball_diameter, b.pitch_diameter, b.n_balls, b.contact_angle, harmonics=2)
    cols = tables.spectral_mask(m, w)
    assert len(cols["name"]) == len(m.name) and cols["name"][0] == "shaft"
    assert cols["order"][0] == pytest.approx(1.0, rel=1e-15)
    # only the outer ring turns: no shaft frequency to refer orders to
    still = kinematics.spectral_mask(0.0, b.ball_diameter, b.pitch_diameter, b.n_balls, b.contact_angle,
                                     outer_speed=w)
    assert np.isnan(tables.spectral_mask(still, 0.0)["order"]).all()
    assert tables.frequencies(f, 0.0)["bpfi_order"] is None

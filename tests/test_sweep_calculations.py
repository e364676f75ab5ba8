"""Sweeps of any calculation (issue 28, item 4): ``model = "<calculation>"``, each case the document the
single command prints with ``--json``, to the last bit, on every executor and chunk size."""

import json
import logging
import math
import re

import numpy as np
import pytest

from bearinglab import _bounds, calculations, sweep, tables
from bearinglab.calculations import CALCULATIONS
from bearinglab.cli import main
from bearinglab.errors import CatalogError


def _file(tmp_path, text, name="s.toml"):
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return path


def _scalars(doc, key=""):
    """The scalars of a document by their dotted path: written here, apart from the code it checks."""
    if isinstance(doc, dict):
        out = {}
        for k, v in doc.items():
            out.update(_scalars(v, f"{key}.{k}" if key else k))
        return out
    return {} if isinstance(doc, list) else {key: doc}


def _document(name, given):
    """The document of the single command for ``given`` (the options as the command line types them)."""
    return calculations.run(calculations.parse(name, given, check=False))


def _same(a, b):
    assert list(a) == list(b)
    for k in a:
        assert a[k].dtype == b[k].dtype, k
        assert np.array_equal(a[k], b[k], equal_nan=a[k].dtype.kind == "f"), k


# one file per calculation, and the options of the single command for each of its cases, in grid order
# (the last parameter fastest), written out by hand
LIFE = """model = "life"
bearing = "6205-2RS"
[parameters]
fx = "1 kN:3 kN:1 kN"
speed = "3000, 6000 rpm"
[constants]
viscosity = "20 cSt"
contamination = "normal"
"""
LIFE_CASES = [{"bearing": "6205-2RS", "viscosity": "20 cSt", "contamination": "normal", "fx": f, "speed": n}
              for f in ("1 kN", "2 kN", "3 kN") for n in ("3000 rpm", "6000 rpm")]
CLEARANCE = """model = "clearance"
bearing = "6205-2RS"
[parameters]
shaft_fit = ["k5", "m5"]
inner_ring_temperature = "20 degC:60 degC:20 degC"
speed = "6000 rpm"
"""
CLEARANCE_CASES = [{"bearing": "6205-2RS", "shaft_fit": f, "inner_ring_temperature": t, "speed": "6000 rpm"}
                   for f in ("k5", "m5") for t in ("20 degC", "40 degC", "60 degC")]
LOAD = """model = "load-distribution"
bearing = "7205 B"
[parameters]
fx = ["500 N", "2 kN"]
fz = "1 kN"
speed = ["0 rpm", "10000 rpm"]
"""
LOAD_CASES = [{"bearing": "7205 B", "fx": f, "fz": "1 kN", "speed": n}
              for f in ("500 N", "2 kN") for n in ("0 rpm", "10000 rpm")]
FRICTION = """model = "friction"
bearing = "6205-2RS"
[parameters]
model = ["one-term", "palmgren"]
radial_load = "100 N, 250 N"
speed = "3000 rpm"
"""
FRICTION_CASES = [{"bearing": "6205-2RS", "model": m, "radial_load": r, "speed": "3000 rpm"}
                  for m in ("one-term", "palmgren") for r in ("100 N", "250 N")]
CASES = {"life": (LIFE, LIFE_CASES), "clearance": (CLEARANCE, CLEARANCE_CASES),
         "load-distribution": (LOAD, LOAD_CASES), "friction": (FRICTION, FRICTION_CASES)}


@pytest.mark.parametrize("name", sorted(CASES))
def test_each_row_equals_the_single_commands_document(tmp_path, name):
    text, given = CASES[name]
    cols = sweep.run_sweep(sweep.load_sweep(_file(tmp_path, text)), chunk_size=4)
    rows = tables.rows(cols)
    assert len(rows) == len(given)
    ran = 0
    for row, request in zip(rows, given):
        try:
            doc = _document(name, request)
        except calculations.RequestError as exc:  # the sweep flags the case with the same message
            assert row["converged"] is False and row["failure"] == str(exc)
            continue
        ran += 1
        assert row["converged"] is True and row["failure"] == ""
        for key, value in _scalars(doc).items():
            assert row[key] == value, key  # == on floats: the same bits
            assert type(row[key]) is type(value) or {type(row[key]), type(value)} == {int, float}, key
        if doc.get("warnings"):
            assert row["warnings"] == " | ".join(doc["warnings"])
    assert ran >= 2


def test_small_numeric_lists_are_columns_by_index_and_tables_are_left_out(tmp_path):
    cols = sweep.run_sweep(sweep.load_sweep(_file(tmp_path, LOAD)))
    doc = _document("load-distribution", LOAD_CASES[3])
    k = doc["stiffness_matrix"]
    assert [cols[f"stiffness_matrix.{i}.{j}"][3] for i in range(5) for j in range(5)] == [x for r in k for x in r]
    assert not any(c.startswith("balls") for c in cols)  # the per-ball table: the single command prints it
    clearance = sweep.run_sweep(sweep.load_sweep(_file(tmp_path, CLEARANCE)))
    pair = _document("clearance", CLEARANCE_CASES[0])["interference_inner_probable_um"]
    assert [clearance[f"interference_inner_probable_um.{i}"][0] for i in range(2)] == pair


def test_the_commands_own_json_is_the_row(tmp_path, capsys):
    # the command line's --json, not only the layer's document: the same numbers
    cols = sweep.run_sweep(sweep.load_sweep(_file(tmp_path, LIFE)))
    assert main(["life", "--bearing", "6205-2RS", "--fx", "2 kN", "--speed", "6000 rpm", "--viscosity", "20 cSt",
                 "--contamination", "normal", "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    row = tables.rows(cols)[3]
    for key, value in _scalars(doc).items():
        assert row[key] == value, key
    assert row["basic_rating_life_h"] == doc["basic_rating_life_h"] and row["fx_N"] == 2000.0


@pytest.fixture(scope="module")
def scheduler():
    """A running cluster of two worker processes, reached by its address: the workers import the package
    and compute the documents in other processes, as on a cluster."""
    distributed = pytest.importorskip("distributed")
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None,
                                  host="127.0.0.1", silence_logs=logging.ERROR) as cluster:
        yield cluster.scheduler_address


def test_every_executor_and_chunk_size_gives_the_same_table(tmp_path, scheduler):
    for text in (LIFE, CLEARANCE, FRICTION):  # FRICTION: two cases fail (palmgren needs a viscosity)
        spec = sweep.load_sweep(_file(tmp_path, text))
        ref = sweep.run_sweep(spec, chunk_size=100)
        for kw in ({"chunk_size": 1}, {"chunk_size": 5}, {"chunk_size": 2, "executor": scheduler},
                   {"chunk_size": 3, "executor": "local", "workers": 2, "processes": False}):
            _same(ref, sweep.run_sweep(spec, **kw))


def test_input_columns_and_the_values_of_each_kind(tmp_path):
    path = _file(tmp_path, """model = "frequencies"
bearing = "6205-2RS"
[parameters]
speed = "0.1 kHz:0.3 kHz:0.1 kHz"
sidebands = "0:2:1"
harmonics = [1, 4]
mask = [false, true]
elastic_constant = ["paper"]
""")
    spec = sweep.load_sweep(path)
    assert spec.path == "document" and spec.parameters["speed"] == ["0.1 kHz", "0.2 kHz", "0.3 kHz"]
    cols = sweep.run_sweep(spec)
    assert len(cols["converged"]) == 3 * 3 * 2 * 2 and cols["converged"].all()
    assert list(cols)[:5] == ["speed_rpm", "sidebands", "harmonics", "mask", "elastic_constant"]
    assert sorted(set(cols["speed_rpm"])) == [6000.0, 12000.0, 18000.0]  # 0.3 kHz: no binary noise
    assert cols["sidebands"].dtype == np.int64 and cols["mask"].dtype == bool
    first = _document("frequencies", {"bearing": "6205-2RS", "speed": "0.1 kHz", "sidebands": 0, "harmonics": 1,
                                      "mask": False, "elastic_constant": "paper"})
    assert cols["bpfo_hz"][0] == first["bpfo_hz"] and cols["shaft_hz"][0] == 100.0


def test_ranges_are_counted_in_their_own_unit_and_lists_share_the_last_unit(tmp_path):
    from bearinglab._sweep_documents import parameter_values

    fx = CALCULATIONS["life"].field("fx")
    assert parameter_values(fx, "0.1 kN:0.5 kN:0.1 kN", limit=10)[0] == [f"0.{k} kN" for k in range(1, 6)]
    assert parameter_values(fx, "1, 2.5 kN", limit=10) == (["1 kN", "2.5 kN"], [1000.0, 2500.0])
    assert parameter_values(fx, ["1 kgf", "2 N"], limit=10)[1] == [9.80665, 2.0]
    balls = CALCULATIONS["life"].field("balls")
    assert parameter_values(balls, "7:9:1", limit=10)[0] == [7, 8, 9]
    bearings = CALCULATIONS["bearing-set"].field("bearing")
    assert parameter_values(bearings, ["7205 B", "7205 B, 7206 B"], limit=10)[0] == [["7205 B"], ["7205 B", "7206 B"]]
    with pytest.raises(Exception, match="one unit"):
        parameter_values(fx, "1 kN:2000 N:100 N", limit=10)
    with pytest.raises(Exception, match="more than the limit of 10"):
        parameter_values(fx, "0 N:1000 N:1 N", limit=10)


def test_a_failed_case_keeps_its_inputs_and_says_why(tmp_path):
    path = _file(tmp_path, """model = "high-speed"
path = "document"
bearing = "B218"
[parameters]
axial_load = ["20 kN", "-5 kN"]
speed = "3000 rpm"
""")
    cols = sweep.run_sweep(sweep.load_sweep(path))
    assert cols["converged"].tolist() == [True, False]
    with pytest.raises(calculations.RequestError) as exc:
        _document("high-speed", {"bearing": "B218", "axial_load": "-5 kN", "speed": "3000 rpm"})
    assert cols["failure"][1] == str(exc.value) and cols["failure"][0] == ""
    # axial_load_N is an input column and a key of the document: the document's value where it ran
    assert cols["axial_load_N"].tolist() == [20000.0, -5000.0]
    assert math.isnan(cols["contact_angle_inner_deg"][1]) and cols["status"][1] is None


def test_the_batch_models_keep_their_path_and_a_field_of_theirs_asks_for_the_document(tmp_path):
    batch = sweep.load_sweep(_file(tmp_path, 'model = "axial-angle"\nbearing = "4-1006095"\n[parameters]\n'
                                             'axial_load = "1 kgf, 2 kgf"\ncontact_angle = "12 deg"\n'))
    assert batch.path == "batch" and batch.model is sweep.MODELS["axial-angle"]
    document = sweep.load_sweep(_file(tmp_path, 'model = "axial-angle"\nbearing = "4-1006095"\n[parameters]\n'
                                                'axial_load = "1 kgf, 2 kgf"\nhertz = "table"\n'))
    assert document.path == "document"
    forced = sweep.load_sweep(_file(tmp_path, 'model = "axial-angle"\npath = "document"\nbearing = "4-1006095"\n'
                                              '[parameters]\naxial_load = "1 kgf, 2 kgf"\n'))
    a, b = sweep.run_sweep(batch), sweep.run_sweep(forced)
    assert b["operating_contact_angle_deg"][1] == _document("axial-angle", {
        "bearing": "4-1006095", "axial_load": "2 kgf"})["operating_contact_angle_deg"]
    # the two paths solve the same angle (the batch solve in one vectorized Newton)
    np.testing.assert_allclose(a["operating_contact_angle_deg"], b["operating_contact_angle_deg"], rtol=1e-12)


def test_a_sweep_over_bearings(tmp_path):
    path = _file(tmp_path, 'model = "life"\n[parameters]\nbearing = ["6205-2RS", "6206"]\nfx = "2 kN"\n'
                           'speed = "3000 rpm"\n')
    spec = sweep.load_sweep(path)
    assert spec.bearing is None
    cols = sweep.run_sweep(spec)
    assert cols["bearing"].tolist() == ["6205-2RS", "6206"]
    for k, name in enumerate(("6205-2RS", "6206")):
        doc = _document("life", {"bearing": name, "fx": "2 kN", "speed": "3000 rpm"})
        assert cols["basic_rating_life_h"][k] == doc["basic_rating_life_h"]
        assert cols["warnings"][k] == " | ".join(doc["warnings"])  # each bearing's own provenance note


def test_a_bearing_table_is_the_bearing_file_of_each_case(tmp_path):
    table = ('[bearing]\ndesignation = "my-7205"\nballs = 12\nball_diameter = "7.938 mm"\n'
             'pitch_diameter = "38.5 mm"\ninner_conformity = 0.52\nouter_conformity = 0.53\n'
             'contact_angle = "25 deg"\n')
    cols = sweep.run_sweep(sweep.load_sweep(_file(tmp_path, 'model = "frequencies"\npath = "document"\n' + table.replace(
        "[bearing]", "[parameters]\nspeed = \"3000 rpm, 6000 rpm\"\n[bearing]"))))
    from bearinglab.calculations.frequencies import document

    bearing_file = _file(tmp_path, table.replace("[bearing]\n", ""), "b.toml")
    doc = document(calculations.parse("frequencies", {"speed": "6000 rpm"}, check=False), bearing_file=bearing_file)
    assert cols["bearing"][1] == "my-7205" and cols["bpfi_hz"][1] == doc["bpfi_hz"]
    with pytest.raises(CatalogError, match="bearing: model 'bearing-set' takes catalog names"):
        sweep.load_sweep(_file(tmp_path, 'model = "bearing-set"\n[parameters]\npreload = "1 kN"\n' + table))


def test_every_calculation_sweeps(tmp_path):
    # one file per calculation of the registry: each runs, and every case is computed or says why
    files = {
        "bearing-set": 'bearing = "7205 B"\n[parameters]\npreload = ["200 N", "500 N"]\n',
        "catalog": '[parameters]\nname = ["6205-2RS", "B218"]\n',
        "catalog-search": '[parameters]\nbore = ["25 mm", "30 mm"]\n',
        "film": 'bearing = "6205-2RS"\n[parameters]\nfx = "2 kN"\nspeed = "3000 rpm"\nviscosity = "20 cSt, 40 cSt"\n',
        "temperature": 'bearing = "6205-2RS"\n[parameters]\nradial_load = "1 kN"\nspeed = "6000 rpm"\n'
                       'oil = ["VG68", "VG32"]\n',
        "stand-load": 'path = "document"\nbearing = "4-1006095"\n[parameters]\nspeed = "3000 rpm, 6000 rpm"\n',
        "runout": 'bearing = "B218"\n[parameters]\nangle = ["0 deg", "90 deg"]\n'
                  '[parameters.errors.errors.balls]\ndiameter = ["2 um"]\n',
        "runout-monte-carlo": 'bearing = "B218"\n[parameters]\nseed = [0, 1]\n[constants]\nsamples = 4\n'
                              'steps_per_rev = 8\nrevolutions = 1\n',
    }
    swept = set(files) | set(CASES) | {"frequencies", "high-speed", "axial-angle"}  # the tests above
    assert swept <= set(CALCULATIONS) and len(swept) >= 15
    for name in CALCULATIONS:  # a calculation added later is a model too: its fields are the parameters
        with pytest.raises(CatalogError, match=f"parameters.no_such_field: unknown parameter of model '{name}'"):
            sweep.load_sweep(_file(tmp_path, f'model = "{name}"\n[parameters]\nno_such_field = 1\n'))
    for name, text in files.items():
        cols = sweep.run_sweep(sweep.load_sweep(_file(tmp_path, f'model = "{name}"\n' + text)))
        assert len(cols["converged"]) == 2, name
        assert all(ok or why for ok, why in zip(cols["converged"], cols["failure"])), name
        assert cols["converged"].any() or name == "runout", name  # runout: 1 diameter for 16 balls
        if name == "runout":  # a document parameter: its position in the list
            assert cols["errors_item"].tolist() == [0, 0] and "16 balls" in cols["failure"][0]


def test_bad_files_are_refused_whole_naming_file_and_field(tmp_path):
    bad = [
        ('model = "life"\n[parameters]\nspeeed = "1 rpm"', r"parameters.speeed: unknown parameter of model 'life'"),
        ('model = "life"\n[parameters]\nfx = "1 m"', r"parameters.fx: fx: '1 m' is a length"),
        ('model = "life"\n[parameters]\nfx = 5', r"parameters.fx: fx: 5 has no unit"),
        ('model = "life"\n[parameters]\ncontamination = "dusty"', r"contamination must be one of extreme"),
        ('model = "life"\n[parameters]\nfx = "1 kN"\n[constants]\nspeed = "1 rpm, 2 rpm"',
         r"constants.speed: one value, the same in every case, got 2"),
        ('model = "life"\n[parameters]\nfx = "1 kN"\n[constants]\nfx = "2 kN"', r"constants.fx: also in \[parameters\]"),
        ('model = "life"\n[parameters]\nballs = "7.5"', r"parameters.balls: balls: expected a whole number"),
        ('model = "life"\n[parameters]\nfx = []', r"parameters.fx: fx: empty list"),
        ('model = "high-speed"\npath = "document"\nbearing = "B218"\n[parameters]\nspeed = "1 rpm"',
         r"model 'high-speed' needs axial_load"),
        ('model = "life"\npath = "batch"\n[parameters]\nfx = "1 kN"', r"path: 'life' has no batch model"),
        ('model = "life"\npath = "fast"\n[parameters]\nfx = "1 kN"', r"path: must be 'batch' or 'document'"),
        ('model = "catalog"\nbearing = "B218"\n[parameters]\nname = "B218"', r"bearing: model 'catalog' takes no bearing"),
        ('model = "life"\nbearing = "nope"\n[parameters]\nfx = "1 kN"', r"unknown name 'nope'"),
        ('model = "life"\n[parameters]\nbearing = ["6205-2RS", "nope"]', r"parameters.bearing: bearing: unknown name 'nope'"),
        ('model = "life"\n[parameters]\nfx = "0 N:1000 N:1 N"\nfy = "0 N:1000 N:1 N"', r"more than the limit of 1e\+06"),
        ('model = "life"\n[parameters]\nfx = "0 N:1e300 N:1e-300 N"', r"parameters.fx: fx: range .* more than the limit"),
    ]
    for text, match in bad:
        with pytest.raises(CatalogError, match=match):
            sweep.load_sweep(_file(tmp_path, text))


def test_the_case_count_is_bounded_before_the_grid_is_built(tmp_path, monkeypatch):
    built = []
    monkeypatch.setattr(sweep, "case_grid", lambda p: built.append(p))
    with pytest.raises(CatalogError, match=re.escape(f"more than the limit of {_bounds.MAX_DOCUMENT_SWEEP_CASES:.4g}")):
        sweep.load_sweep(_file(tmp_path, 'model = "life"\n[parameters]\nfx = "1 N:2000 N:1 N"\n'
                                          'fy = "1 N:1000 N:1 N"\n'))
    assert not built


def test_cli_sweep_of_a_calculation_writes_its_table(tmp_path, capsys):
    path = _file(tmp_path, FRICTION + '[output]\nfile = "friction.csv"\n')
    assert main(["sweep", str(path)]) == 0
    out = capsys.readouterr().out
    assert "Sweep of friction on 6205-2RS" in out and "palmgren model needs" in out
    header = (tmp_path / "friction.csv").read_text().splitlines()[0].split(",")
    assert header[:3] == ["model", "radial_load_N", "speed_rpm"] and header[-2:] == ["converged", "failure"]
    assert main(["sweep", str(path), "--json", "--out", str(tmp_path / "f.parquet")]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert doc["path"] == "document" and doc["cases"] == 4 and doc["failed"] == 2
    assert doc["results"][0]["torque_Nmm"] == _document("friction", FRICTION_CASES[0])["torque_Nmm"]
    import pyarrow.parquet as pq

    t = pq.read_table(tmp_path / "f.parquet").to_pydict()
    assert t["branch"][2] is None and t["branch"][0] == "Fr"  # a failed case's text is null, not 'None'

"""Sweeps over any number of a shaft-system file (issue 33 item 5): ``model = "shaft"`` with a parameter
that addresses a value inside the document (``supports.B.position``); each row is the single command's
``--json`` for the file with that value, to the last bit."""

import json
import re
from pathlib import Path

import numpy as np
import pytest

from bearinglab import _document_paths, sweep, tables
from bearinglab.calculations import CALCULATIONS
from bearinglab.cli import main
from bearinglab.errors import CatalogError, InputError

SHAFT = (Path(__file__).parent / "data" / "two_bearing_shaft.toml").read_text(encoding="utf-8")  # as test_cli's
SPAN = """\
model = "shaft"
[constants]
model = "two.toml"
stiffness_at = "150 mm"
[parameters]
"supports.B.position" = "200 mm:280 mm:40 mm"
"""


@pytest.fixture
def files(tmp_path):
    (tmp_path / "two.toml").write_text(SHAFT, encoding="utf-8")
    path = tmp_path / "span.toml"
    path.write_text(SPAN, encoding="utf-8")
    return tmp_path


def _scalars(doc, key=""):
    """The scalars of a document by their dotted path (mappings only): written here, apart from the code."""
    if isinstance(doc, dict):
        out = {}
        for k, v in doc.items():
            out.update(_scalars(v, f"{key}.{k}" if key else k))
        return out
    return {} if isinstance(doc, list) else {key: doc}


def _single(capsys, path, *options):
    assert main(["shaft", str(path), *options, "--json"]) == 0
    return json.loads(capsys.readouterr().out)


def test_each_row_is_the_single_commands_json_for_the_file_with_that_value(files, capsys):
    cols = sweep.run_sweep(sweep.load_sweep(files / "span.toml"), chunk_size=2)
    rows = tables.rows(cols)
    assert cols["supports.B.position_mm"].tolist() == [200.0, 240.0, 280.0]
    assert cols["converged"].all()
    lives = []
    for row, position in zip(rows, ("200 mm", "240 mm", "280 mm")):
        edited = files / f"at_{position.split()[0]}.toml"
        edited.write_text(SHAFT.replace('position = "280 mm"', f'position = "{position}"'), encoding="utf-8")
        doc = _single(capsys, edited, "--stiffness-at", "150 mm")
        for key, value in _scalars(doc).items():
            assert row[key] == value, key  # == on floats: the same bits
        for support in doc["supports"]:  # the supports, spread by their names
            for key, value in support.items():
                if key != "name" and not isinstance(value, (dict, list)):
                    assert row[f"supports.{support['name']}.{key}"] == value, (support["name"], key)
            for key, value in support["bearings"][0]["loads"].items():
                assert row[f"supports.{support['name']}.bearings.0.loads.{key}"] == value
        assert row["warnings"] == " | ".join(doc["warnings"])
        lives.append(row["system_life_h"])
    assert len(set(lives)) == 3  # the span changes the loads, so the lives


def test_the_rows_do_not_depend_on_the_chunks(files):
    spec = sweep.load_sweep(files / "span.toml")
    a, b = sweep.run_sweep(spec, chunk_size=1), sweep.run_sweep(spec, chunk_size=3)
    assert list(a) == list(b)
    for k in a:
        assert a[k].dtype == b[k].dtype and np.array_equal(a[k], b[k], equal_nan=a[k].dtype.kind == "f"), k


def test_addresses_by_name_index_and_inline_table_give_the_same_cases(files):
    # sections[0].diameter and model.sections.0.diameter; the document as a file and as tables of the
    # sweep file ([constants.model], [[constants.model.sections]] ...)
    from_file = files / "from_file.toml"
    from_file.write_text('model = "shaft"\n[constants]\nmodel = "two.toml"\n[parameters]\n'
                         '"model.sections.0.diameter" = "30, 35 mm"\n', encoding="utf-8")
    inline = files / "inline.toml"
    inline.write_text('model = "shaft"\n[parameters]\n"sections[0].diameter" = ["30 mm", "35 mm"]\n'
                      '[constants.model]\n' + SHAFT.replace("[[", "[[constants.model."), encoding="utf-8")
    a = sweep.run_sweep(sweep.load_sweep(from_file))
    b = sweep.run_sweep(sweep.load_sweep(inline))
    assert a["model.sections.0.diameter_mm"].tolist() == b["sections[0].diameter_mm"].tolist() == [30.0, 35.0]
    assert a["system_life_h"].tolist() == b["system_life_h"].tolist()
    assert a["shaft.mass_kg"][1] > a["shaft.mass_kg"][0]


def test_a_preload_a_bearing_and_a_plain_number_are_addresses_too(tmp_path):
    (tmp_path / "set.toml").write_text(SHAFT.replace('bearing = "6206"\naxial = true',
                                       'bearing_set = { bearing = "7206 B", arrangement = "DB", preload = "200 N" }'),
                                       encoding="utf-8")
    path = tmp_path / "s.toml"
    path.write_text('model = "shaft"\n[constants]\nmodel = "set.toml"\n[parameters]\n'
                    '"supports.A.bearing_set.preload" = "200 N:600 N:400 N"\n"supports.B.bearing" = ["6206", "6306"]\n'
                    '"model.elements" = [20, 40]\n', encoding="utf-8")
    cols = sweep.run_sweep(sweep.load_sweep(path))
    assert cols["supports.A.bearing_set.preload_N"].tolist() == [200.0] * 4 + [600.0] * 4
    assert cols["supports.B.bearing"].tolist() == ["6206", "6206", "6306", "6306"] * 2
    assert cols["model.elements"].dtype == np.int64
    e = cols["shaft.elements"].tolist()[:2]  # at least the elements asked for, refined at every load
    assert 20 <= e[0] < 40 <= e[1]
    assert cols["converged"].all()
    # a stiffer preload: a stiffer front pair
    k = cols["supports.A.bearings.0.stiffness_x_N_per_um"]
    assert k[4] > k[0]


@pytest.mark.parametrize("entry, message", [
    ('"supports.C.position" = "1 mm"', r"supports has no table named 'C' \(names: A, B; or an index from 0 to 1\)"),
    ('"supports.B.position" = "5 N"', r"supports.B.position: '5 N' is a force, expected a length"),
    ('"supports.B" = "5 mm"', r"addresses a whole table; address one value in it"),
    ('"sections.3.diameter" = "5 mm"', r"sections has no table named '3' \(give an index from 0 to 0\)"),
    ('"nothere.x" = 1', r"the document has no 'nothere' \(it has speed, sections, supports, loads\)"),
    ('"supports..position" = "1 mm"', r"an empty step in the path"),
    ('spped = "1 rpm"', r"parameters.spped: unknown parameter of model 'shaft'"),
])
def test_a_bad_address_is_refused_whole_naming_the_entry(files, entry, message):
    path = files / "bad.toml"
    path.write_text(f'model = "shaft"\n[constants]\nmodel = "two.toml"\n[parameters]\n{entry}\n', encoding="utf-8")
    with pytest.raises(CatalogError, match=message) as err:
        sweep.load_sweep(path)
    assert str(err.value).startswith(f"{path}: parameters.")


def test_the_document_must_be_given_and_its_file_exist(files):
    path = files / "bad.toml"
    path.write_text('model = "shaft"\n[parameters]\n"supports.B.position" = "1 mm"\n', encoding="utf-8")
    with pytest.raises(CatalogError, match="addresses the document 'model', which the file does not give"):
        sweep.load_sweep(path)
    path.write_text('model = "shaft"\n[constants]\nmodel = "none.toml"\n[parameters]\nspeed = "1 rpm"\n',
                    encoding="utf-8")
    with pytest.raises(CatalogError, match=re.escape("constants.model: none.toml: no such file")):
        sweep.load_sweep(path)


def test_the_command_line_sweeps_a_span(files, capsys):
    out = files / "span.csv"
    assert main(["sweep", str(files / "span.toml"), "--out", str(out), "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert doc["cases"] == 3 and doc["failed"] == 0 and doc["model"] == "shaft"
    assert [r["supports.B.position_mm"] for r in doc["results"]] == [200.0, 240.0, 280.0]
    assert out.read_text(encoding="utf-8").startswith("supports.B.position_mm,")


# ----------------------------------------------------------------------------- the addresses themselves
def test_an_address_names_a_document_field_and_a_path():
    shaft, life = CALCULATIONS["shaft"], CALCULATIONS["life"]
    assert _document_paths.address(shaft, "supports.front.position") == ("model", ("supports", "front", "position"))
    assert _document_paths.address(shaft, "sections[2].bore") == ("model", ("sections", "2", "bore"))
    assert _document_paths.address(shaft, "model.gravity") == ("model", ("gravity",))
    assert _document_paths.address(shaft, "speed") is None and _document_paths.address(shaft, "gravity") is None
    assert _document_paths.address(life, "step.0.fx") == ("duty_cycle", ("step", "0", "fx"))
    assert _document_paths.address(CALCULATIONS["axial-angle"], "a.b") is None  # no document field


@pytest.mark.parametrize("current, value, kind, unit", [
    ("100 mm", None, "length", "mm"), ("500 N", None, "force", "N"), ("200 N/um", None, "stiffness", "N/um"),
    ("5 kW", None, "power", "kW"), ("3000 rpm", None, "speed", "rpm"), ("20 deg", None, "angle", "deg"),
    ("45 degC", None, "text", "degC"), ("6206", None, "text", ""), (0.3, None, "number", ""),
    (30, None, "int", ""), (True, None, "flag", ""), (None, "1 in:3 in:1 in", "length", "in"),
    (None, ["1 kN", "2 kN"], "force", "kN"), (None, 0.5, "number", ""),
])
def test_an_address_reads_its_values_like_the_value_it_replaces(current, value, kind, unit):
    field = _document_paths.field_of("x.y", current, value)
    assert (field.kind, field.unit) == (kind, unit)


def test_the_values_are_written_into_a_copy_of_the_document_as_json():
    shaft = CALCULATIONS["shaft"]
    cache = {}
    request = {"model": SHAFT, "speed": "1 rpm", "supports.B.position": "200 mm", "model.elements": 12}
    out = _document_paths.with_values(shaft, request, cache)
    assert set(out) == {"model", "speed"} and out["speed"] == "1 rpm"
    doc = json.loads(out["model"])
    assert doc["supports"][1]["position"] == "200 mm" and doc["elements"] == 12
    assert cache[SHAFT]["supports"][1]["position"] == "280 mm"  # the parsed file is not changed
    plain = {"model": SHAFT, "speed": "1 rpm"}
    assert _document_paths.with_values(shaft, plain) is plain
    with pytest.raises(InputError, match="supports has no table named 'C'"):
        _document_paths.with_values(shaft, {"model": SHAFT, "supports.C.position": "1 mm"})

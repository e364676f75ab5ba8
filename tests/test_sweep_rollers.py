"""Sweeps of the calculations with roller bearings (issue 32 item 7): each row is the document the single command
prints with ``--json`` for a roller bearing, to the last bit."""

import pytest

from bearinglab import calculations, sweep, tables


def _scalars(doc, key=""):
    """The scalars of a document by their dotted path (written here, apart from the code it checks)."""
    if isinstance(doc, dict):
        out = {}
        for k, v in doc.items():
            out.update(_scalars(v, f"{key}.{k}" if key else k))
        return out
    return {} if isinstance(doc, list) else {key: doc}


LOAD = """model = "load-distribution"
bearing = "NU 208 ECP"
[parameters]
fx = "5 kN, 15 kN"
my = ["0 N*m", "5 N*m"]
[constants]
radial_clearance = "20 um"
"""
LIFE = """model = "life"
bearing = "30208 J2/Q"
[parameters]
fz = "3 kN, 5 kN"
[constants]
fx = "10 kN"
speed = "1000 rpm"
viscosity = "30 cSt"
contamination = "normal"
"""
FRICTION = """model = "friction"
bearing = "22208 E"
[parameters]
radial_load = "1 kN, 3 kN"
[constants]
model = "skf"
speed = "3500 rpm"
viscosity = "68 cSt"
"""
PAIR = """model = "bearing-set"
bearing = "30208 J2/Q"
[parameters]
fz = "1 kN, 3 kN"
[constants]
spacing = "135 mm"
preload = "2 kN"
fx = "8 kN"
"""
CASES = {
    "load-distribution": (LOAD, [{"bearing": "NU 208 ECP", "radial_clearance": "20 um", "fx": f, "my": m}
                                 for f in ("5 kN", "15 kN") for m in ("0 N*m", "5 N*m")]),
    "life": (LIFE, [{"bearing": "30208 J2/Q", "fx": "10 kN", "speed": "1000 rpm", "viscosity": "30 cSt",
                     "contamination": "normal", "fz": f} for f in ("3 kN", "5 kN")]),
    "friction": (FRICTION, [{"bearing": "22208 E", "model": "skf", "speed": "3500 rpm", "viscosity": "68 cSt",
                             "radial_load": r} for r in ("1 kN", "3 kN")]),
    "bearing-set": (PAIR, [{"bearing": ["30208 J2/Q"], "spacing": "135 mm", "preload": "2 kN", "fx": "8 kN",
                            "fz": f} for f in ("1 kN", "3 kN")]),
}


@pytest.mark.parametrize("name", sorted(CASES))
def test_each_row_of_a_roller_sweep_is_the_single_commands_document(tmp_path, name):
    text, given = CASES[name]
    path = tmp_path / "s.toml"
    path.write_text(text, encoding="utf-8")
    rows = tables.rows(sweep.run_sweep(sweep.load_sweep(path), chunk_size=1))
    assert len(rows) == len(given)
    for row, request in zip(rows, given, strict=True):
        doc = calculations.run(calculations.parse(name, request, check=False))
        assert row["converged"] is True and row["failure"] == ""
        scalars = _scalars(doc)
        assert len(scalars) > 10
        for key, value in scalars.items():
            assert row[key] == value, key  # == on floats: the same bits
        if isinstance(doc.get("stiffness_matrix"), list):  # the 5 x 5 matrix: one column per entry
            for i in range(5):
                for j in range(5):
                    assert row[f"stiffness_matrix.{i}.{j}"] == doc["stiffness_matrix"][i][j], (i, j)
        if doc.get("warnings"):
            assert row["warnings"] == " | ".join(doc["warnings"])

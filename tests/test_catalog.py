"""Tests of bearinglab.catalog: every built-in entry against its source, user catalogs (argument,
BEARINGLAB_CATALOG, --catalog), single-bearing files (--bearing-file), malformed files, unknown names."""

import json
import math
import os
import re

import pytest

from bearinglab import catalog
from bearinglab.bearing import STEEL
from bearinglab.catalog import _rollers, _series
from bearinglab.cli import main
from bearinglab.errors import CatalogError, InputError

MM = 1e-3
# expected values written from the sources cited in the catalog (not read from the catalog file)
BUILTIN = {
    # spec 000 section 7: 5 x 13 x 4 mm, z = 7, d = 2 mm, dm = 8.7355 mm, r_v = 1.05, r_n = 1.16 mm, 12 deg
    "4-1006095": {
        "n_balls": 7,
        "ball_diameter": 2 * MM,
        "pitch_diameter": 8.7355 * MM,
        "inner_conformity": 0.525,
        "outer_conformity": 0.58,
        "contact_angle": math.radians(12),
        "bore": 5 * MM,
        "outside_diameter": 13 * MM,
        "width": 4 * MM,
        "type": "angular",
    },
    # spec 001 section 3.4, Table 3: d, d_m, (D), C0; radial
    "1000095": {
        "bore": 5 * MM,
        "pitch_diameter": 9 * MM,
        "outside_diameter": 13 * MM,
        "static_load_rating": 392.0,
        "type": "radial",
    },
    "18": {
        "bore": 8 * MM,
        "pitch_diameter": 13.5 * MM,
        "outside_diameter": 19 * MM,
        "static_load_rating": 1354.0,
        "type": "radial",
    },
    "101": {
        "bore": 12 * MM,
        "pitch_diameter": 20 * MM,
        "outside_diameter": 28 * MM,
        "static_load_rating": 2227.0,
        "type": "radial",
    },
    # spec 004 section 6: Z = 16, D = 22.23 mm, d_m = 125.3 mm, f = 0.5232, 40 deg
    "B218": {
        "n_balls": 16,
        "ball_diameter": 22.23 * MM,
        "pitch_diameter": 125.3 * MM,
        "inner_conformity": 0.5232,
        "outer_conformity": 0.5232,
        "contact_angle": math.radians(40),
        "type": "angular",
    },
    # CWRU drive-end bearing: 9 balls, 7.94 mm, pitch 39.04 mm, 0 deg; 25 x 52 x 15 mm
    "6205-2RS": {
        "n_balls": 9,
        "ball_diameter": 7.94 * MM,
        "pitch_diameter": 39.04 * MM,
        "contact_angle": 0.0,
        "bore": 25 * MM,
        "outside_diameter": 52 * MM,
        "width": 15 * MM,
        "type": "radial",
        # SKF catalogue (2018), 6205-2RSH: C = 14.8 kN, C0 = 7.8 kN, Pu = 0.335 kN
        "dynamic_load_rating": 14800.0,
        "static_load_rating": 7800.0,
        "fatigue_load_limit": 335.0,
        "series": "62",
    },
    # issue 12: SKF 61811-2RS1, 55 x 72 x 9 mm, d_m = 63.5 mm, RS1 seals on d_s = 59.5 mm
    "61811-2RS1": {
        "pitch_diameter": 63.5 * MM,
        "bore": 55 * MM,
        "outside_diameter": 72 * MM,
        "width": 9 * MM,
        "type": "radial",
        "series": "618",
        "seal": "RS1",
        "seals": 2,
        "seal_diameter": 59.5 * MM,
    },
}


@pytest.mark.parametrize("name", sorted(BUILTIN))
def test_builtin_entry_matches_its_source(name):
    b = catalog.get(name)
    assert b.designation == name
    for field, want in BUILTIN[name].items():
        got = getattr(b, field)
        if isinstance(want, float):
            assert got == pytest.approx(want, rel=1e-12), field
        else:
            assert got == want, field
    assert b.source, "every entry cites its source"
    assert b.ball_material == STEEL and b.ring_material == STEEL


def test_builtin_names_and_aliases():
    names = catalog.names()
    assert set(BUILTIN) <= set(names) and "7218B" not in names  # aliases are not listed as separate bearings
    # and the standard series (issue 21) and the roller bearings (issue 32)
    assert len(names) == len(BUILTIN) + len(_series.records()) + len(_rollers.records())
    assert catalog.get("7218B") is catalog.get("B218")
    assert catalog.get("b218") is catalog.get("B218")  # case-insensitive fallback
    assert catalog.get("4-1006095").hertz_table == {
        "inner": 0.63,
        "outer": 0.852,
    }  # spec 000 section 5.2


def test_unknown_name_lists_known_names():
    with pytest.raises(
        CatalogError,
        match=r"bearing: unknown name 'X999'; `bearinglab catalog list` shows the \d+ names",
    ) as info:
        catalog.get("X999")
    assert isinstance(info.value, InputError) and isinstance(info.value, ValueError)


USER = """
[bearings."MY-7001"]
aliases = ["7001-TEST"]
balls = 10
ball_diameter = "4.762 mm"
pitch_diameter = "19.5 mm"
inner_groove_radius = "2.5 mm"
outer_conformity = 0.53
radial_clearance = "12 um"
bore = "12 mm"
outside_diameter = "28 mm"
width = "8 mm"
type = "angular"
static_load_rating = "1.52 kN"
ball_material = "silicon_nitride"
source = "test"

[bearings."6205-2RS"]
balls = 9
ball_diameter = "0.3126 in"
pitch_diameter = "1.537 in"
contact_angle = "0 deg"
source = "user override in inches"
"""


@pytest.fixture
def user_file(tmp_path):
    path = tmp_path / "user.toml"
    path.write_text(USER)
    return path


def _check_user_bearing(b):
    assert b.n_balls == 10 and b.ball_diameter == pytest.approx(4.762e-3)
    assert b.inner_conformity == pytest.approx(2.5 / 4.762) and b.outer_conformity == 0.53
    assert b.radial_clearance == pytest.approx(12e-6)
    # the angle follows from the clearance (spec 000 section 4)
    b_total = 2.5 / 4.762 + 0.53 - 1
    assert math.cos(b.contact_angle) == pytest.approx(
        1 - 12e-6 / (2 * b_total * 4.762e-3), rel=1e-12
    )
    assert (
        b.static_load_rating == pytest.approx(1520.0) and b.ball_material.name == "silicon nitride"
    )


def test_user_catalog_argument(user_file):
    _check_user_bearing(catalog.get("MY-7001", catalog=user_file))
    _check_user_bearing(catalog.get("7001-TEST", catalog=[user_file]))
    # user entries take precedence over the built-ins
    assert catalog.get("6205-2RS", catalog=user_file).source == "user override in inches"
    assert catalog.get("6205-2RS", catalog=user_file).ball_diameter == pytest.approx(7.94004e-3)
    assert "MY-7001" in catalog.names(catalog=user_file)
    assert "MY-7001" not in catalog.names()


def test_user_catalog_from_environment(user_file, tmp_path, monkeypatch):
    other = tmp_path / "other.toml"
    other.write_text(
        '[bearings."ONE"]\nballs = 3\nball_diameter = "1 mm"\npitch_diameter = "3 mm"\n'
        'contact_angle = "0 deg"\n'
    )
    monkeypatch.setenv(catalog.ENV_VAR, os.pathsep.join([str(user_file), str(other)]))
    _check_user_bearing(catalog.get("MY-7001"))
    assert catalog.get("ONE").n_balls == 3
    assert {"MY-7001", "ONE", "B218"} <= set(catalog.names())


def test_user_catalog_through_the_command_line(user_file, capsys, monkeypatch):
    assert main(["catalog", "show", "MY-7001", "--catalog", str(user_file), "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert doc["balls"] == 10 and doc["radial_clearance_um"] == pytest.approx(12.0)
    monkeypatch.setenv(catalog.ENV_VAR, str(user_file))
    assert main(["frequencies", "-b", "7001-TEST", "--speed", "6000 rpm", "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert doc["bearing"] == "MY-7001" and doc["shaft_hz"] == pytest.approx(100.0)


@pytest.mark.parametrize(
    "text",
    [
        # top-level keys
        (
            'designation = "SINGLE"\nballs = 7\nball_diameter = "2 mm"\npitch_diameter = "8.7355 mm"\n'
            'inner_groove_radius = "1.05 mm"\nouter_groove_radius = "1.16 mm"\ncontact_angle = "12 deg"\n'
        ),
        # or one [bearings."NAME"] table
        (
            '[bearings."SINGLE"]\nballs = 7\nball_diameter = "0.2 cm"\npitch_diameter = "8.7355 mm"\n'
            'inner_conformity = 0.525\nouter_conformity = 0.58\nradial_clearance = "9.178 um"\n'
        ),
    ],
)
def test_bearing_file(tmp_path, text, capsys):
    path = tmp_path / "one.toml"
    path.write_text(text)
    before = path.read_bytes()
    b = catalog.load_bearing_file(path)
    assert b.designation == "SINGLE" and b.n_balls == 7
    assert b.total_curvature == pytest.approx(0.105, rel=1e-12)
    assert math.degrees(b.contact_angle) == pytest.approx(12.0, abs=3.3e-4)  # 9.178 um is rounded
    assert main(["frequencies", "--bearing-file", str(path), "--speed", "3000 rpm", "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert doc["bearing"] == "SINGLE" and doc["nominal_contact_angle_deg"] == pytest.approx(
        12.0, abs=3.3e-4
    )
    assert path.read_bytes() == before  # input files are never modified


def test_bearing_file_name_defaults_to_the_file_stem(tmp_path):
    path = tmp_path / "my-bearing.toml"
    path.write_text(
        'balls = 7\nball_diameter = "2 mm"\npitch_diameter = "9 mm"\ncontact_angle = "0 deg"\n'
    )
    assert catalog.load_bearing_file(path).designation == "my-bearing"


ENTRY = '[bearings."BAD-1"]\nballs = 7\nball_diameter = "2 mm"\npitch_diameter = "8.7355 mm"\n'


@pytest.mark.parametrize(
    "body, field, detail",
    [
        ('ball_diameter = "2 kg"\n', "ball_diameter", r"'2 kg' is a mass, expected a length"),
        ('bore = "5"\n', "bore", r"'5' has no unit"),
        ('colour = "blue"\n', "colour", r"unknown field"),
        (
            'inner_conformity = 0.45\nouter_conformity = 0.52\ncontact_angle = "10 deg"\n',
            "inner_conformity",
            r"inner_conformity must be in \(0.5, 10\)",
        ),
        (
            'inner_groove_radius = "0.9 mm"\nouter_conformity = 0.52\ncontact_angle = "10 deg"\n',
            "inner_groove_radius",
            r"must be in \(0.5, 10\)",
        ),
        (
            'inner_groove_radius = "1.05 mm"\ninner_conformity = 0.525\n',
            "inner_groove_radius",
            r"not both",
        ),
        (
            'contact_angle = "95 deg"\n',
            "contact_angle",
            r"contact_angle must be in \[0, 90\) \[deg\]",
        ),
        ('contact_angle = "12 mm"\n', "contact_angle", r"'12 mm' is a length, expected an angle"),
        (
            'inner_conformity = 0.52\nouter_conformity = 0.52\nradial_clearance = "1 mm"\n',
            "radial_clearance",
            r"radial_clearance must be in \(0, 0.32\) \[mm\] to give a real contact angle",
        ),
        ('ball_material = "wood"\n', "ball_material", r"unknown material 'wood'"),
        ('type = "magneto"\n', "type", r"type must be one of \['radial', 'angular', 'four-point'"),
        ('static_load_rating = "392 mm"\n', "static_load_rating", r"expected a force"),
        (
            'hertz_table = { inner = "x" }\n',
            "hertz_table",
            r"expected \{ inner = 0.63, outer = 0.852 \}",
        ),
        ('aliases = "BAD"\n', "aliases", r"expected a list of names"),
    ],
)
def test_malformed_entry_names_file_entry_and_field(tmp_path, body, field, detail):
    path = tmp_path / "cat.toml"
    text = ENTRY + body
    if "ball_diameter" in body:
        text = text.replace('ball_diameter = "2 mm"\n', "")
    path.write_text(text)
    with pytest.raises(CatalogError) as info:
        catalog.load_catalog(path)
    msg = str(info.value)
    assert msg.startswith(f"{path}, entry 'BAD-1', field '{field}'"), msg
    assert re.search(detail, msg), msg


@pytest.mark.parametrize(
    "text, field, detail",
    [
        ('[bearings."B"]\nballs = 7.5\n', "balls", r"must be a whole number, got 7.5"),
        ('[bearings."B"]\nballs = 0\n', "balls", r"n_balls must be an integer >= 1"),
        ('[bearings."B"]\nballs = "seven"\n', "balls", r"must be a whole number, got 'seven'"),
        (
            '[bearings."B"]\nballs = 7\nball_diameter = "9 mm"\npitch_diameter = "9 mm"\n',
            "pitch_diameter",
            r"pitch_diameter must be > ball_diameter \[mm\], got 9 mm",
        ),
        (
            '[bearings."B"]\nballs = 7\nball_diameter = "-2 mm"\n',
            "ball_diameter",
            r"ball_diameter must be > 0",
        ),
        (
            '[bearings."B"]\nballs = 7\ninner_groove_radius = "1 mm"\n',
            "inner_groove_radius",
            r"needs ball_diameter",
        ),
    ],
)
def test_malformed_numbers(tmp_path, text, field, detail):
    path = tmp_path / "cat.toml"
    path.write_text(text)
    with pytest.raises(
        CatalogError, match=rf"^{re.escape(str(path))}, entry 'B', field '{field}': .*{detail}"
    ):
        catalog.load_catalog(path)


@pytest.mark.parametrize(
    "text, detail",
    [
        ("[bearings\nballs = 7\n", r"not valid TOML"),
        ("title = 'no bearings'\n", r'no \[bearings."NAME"\] tables'),
        ("[bearings]\nX = 3\n", r"entry 'X': expected a table of fields, got int"),
    ],
)
def test_malformed_file(tmp_path, text, detail):
    path = tmp_path / "cat.toml"
    path.write_text(text)
    with pytest.raises(CatalogError, match=rf"^{re.escape(str(path))}.*{detail}"):
        catalog.load_catalog(path)


def test_missing_files(tmp_path):
    with pytest.raises(CatalogError, match=r"nope.toml: no such file"):
        catalog.load_catalog(tmp_path / "nope.toml")
    with pytest.raises(CatalogError, match=r"nope.toml: no such file"):
        catalog.get("B218", catalog=tmp_path / "nope.toml")
    with pytest.raises(CatalogError, match=r"nope.toml: no such file"):
        catalog.load_bearing_file(tmp_path / "nope.toml")


def test_bearing_file_with_two_bearings(tmp_path, user_file):
    with pytest.raises(CatalogError, match=r"a bearing file holds one bearing, found 2"):
        catalog.load_bearing_file(user_file)


def test_bad_catalog_in_environment_is_reported(tmp_path, monkeypatch, capsys):
    path = tmp_path / "env.toml"
    path.write_text('[bearings."E"]\nballs = 7\nball_diameter = "2 kg"\n')
    monkeypatch.setenv(catalog.ENV_VAR, str(path))
    code = main(["catalog", "list"])
    out, err = capsys.readouterr()
    assert code == 2 and out == "" and "Traceback" not in err
    assert err.strip() == (
        f"bearinglab: error: {path}, entry 'E', field 'ball_diameter': ball_diameter: '2 kg' is a "
        "mass, expected a length (e.g. '2 mm', '0.2 cm')"
    )


def test_ratings_seals_and_materials_keys(tmp_path):
    f = tmp_path / "cat.toml"
    f.write_text(
        """
[materials."M50"]
elastic_modulus = "203 GPa"
poisson_ratio = 0.28
density = "7.8 g/cm^3"

[bearings."A"]
balls = 9
ball_diameter = "7.94 mm"
pitch_diameter = "39.04 mm"
contact_angle = "0 deg"
dynamic_load_rating = "14 kN"
fatigue_load_limit = "300 N"
series = "62"
seal = "RS1"
seals = 1
seal_diameter = "30 mm"
ball_material = "M50"
ring_material = "steel"

[bearings."B"]
balls = 9
ball_diameter = "7.94 mm"
pitch_diameter = "39.04 mm"
elastic_modulus = "210 GPa"
poisson_ratio = 0.3
""",
        encoding="utf-8",
    )
    a = catalog.get("A", catalog=f)
    assert (a.dynamic_load_rating, a.fatigue_load_limit, a.series, a.seal, a.seals) == (14000.0, 300.0, "62", "RS1", 1)
    assert a.seal_diameter == pytest.approx(30 * MM)
    assert a.ball_material.elastic_modulus == pytest.approx(203e9) and a.ball_material.density == pytest.approx(7800.0)
    assert a.ring_material == STEEL
    b = catalog.get("B", catalog=f)
    assert b.ball_material == b.ring_material and b.ring_material.elastic_modulus == pytest.approx(210e9)
    assert b.reduced_modulus == pytest.approx(210e9 / (1 - 0.3**2))


@pytest.mark.parametrize(
    ("entry", "message"),
    [
        ('seals = 3', "field 'seals': must be 0, 1 or 2"),
        ('elastic_modulus = "210 GPa"', "field 'elastic_modulus': needs poisson_ratio too"),
        ('elastic_modulus = "210 GPa"\npoisson_ratio = 0.3\nball_material = "steel"', "not both"),
        ('ball_material = "unobtainium"', "unknown material 'unobtainium'"),
        ('dynamic_load_rating = "14 m"', "field 'dynamic_load_rating'"),
    ],
)
def test_new_keys_are_checked(tmp_path, entry, message):
    f = tmp_path / "bad.toml"
    f.write_text(f'[bearings."X"]\nballs = 9\nball_diameter = "7.94 mm"\n{entry}\n', encoding="utf-8")
    with pytest.raises(CatalogError, match=message):
        catalog.load_catalog(f)


@pytest.mark.parametrize(("typed", "hint"), [("b21", "did you mean B218"),
                                             ("7218", "did you mean 7218 BE or 7218 A or 7218 B or 7218 C or 7218 ACD?")])
def test_unknown_name_suggests_the_close_names(typed, hint):
    with pytest.raises(CatalogError, match=re.escape(hint)):
        catalog.get(typed)


def test_unknown_name_in_a_long_catalog_points_to_catalog_list(tmp_path):
    body = "".join(f'[bearings."X{i}"]\nbore = "{10 + i} mm"\noutside_diameter = "{40 + i} mm"\n' for i in range(25))
    path = tmp_path / "big.toml"
    path.write_text(body, encoding="utf-8")
    with pytest.raises(CatalogError, match=r"did you mean X1\b.*catalog list` shows the \d+ names") as err:
        catalog.get("X1Q", catalog=path)
    assert "X24" not in str(err.value)

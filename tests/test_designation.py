"""Designations as engineers write them (bearinglab.designation) and their resolution by catalog.get."""

import math

import pytest

from bearinglab import catalog, designation
from bearinglab.errors import CatalogError, InputError


@pytest.mark.parametrize(("text", "base", "seal", "seals", "clearance", "angle", "tolerance"), [
    ("6208-2RS1/C3", "6208", "RS1", 2, "C3", None, None),
    ("6208 2RS1 C3", "6208", "RS1", 2, "C3", None, None),
    ("6208-2RSH/C3", "6208", "RSH", 2, "C3", None, None),
    ("6208-2RS", "6208", "RS", 2, None, None, None),
    ("6208-RS", "6208", "RS", 1, None, None, None),
    ("6208-2Z", "6208", "Z", 2, None, None, None),
    ("6208ZZ", "6208", "Z", 2, None, None, None),
    ("6208ZZC3", "6208", "Z", 2, "C3", None, None),
    ("6208 DDU", "6208", "DDU", 2, None, None, None),
    ("6208 2RS", "6208", "RS", 2, None, None, None),
    ("6208/C2", "6208", None, None, "C2", None, None),
    ("6208 CN", "6208", None, None, "CN", None, None),
    ("6208C4", "6208", None, None, "C4", None, None),
    ("6208/C5", "6208", None, None, "C5", None, None),
    ("6208/P6", "6208", None, None, None, None, "P6"),
    ("62/22-2Z", "62/22", "Z", 2, None, None, None),
    ("7205 BECBP", "7205", None, None, None, 40.0, None),
    ("7205 BEP", "7205", None, None, None, 40.0, None),
    ("7205 BE", "7205", None, None, None, 40.0, None),
    ("7205 B", "7205", None, None, None, 40.0, None),
    ("7205 BW", "7205", None, None, None, 40.0, None),
    ("7205-B-TVP", "7205", None, None, None, 40.0, None),
    ("7205 AC", "7205", None, None, None, 25.0, None),
    ("7014 CD/P4A", "7014", None, None, None, 15.0, "P4A"),
    ("7014 ACD/P4", "7014", None, None, None, 25.0, "P4"),
    ("7014 C/P5", "7014", None, None, None, 15.0, "P5"),
    ("6805", "61805", None, None, None, None, None),       # NSK spelling of ISO dimension series 18
])
def test_parse(text, base, seal, seals, clearance, angle, tolerance):
    d = designation.parse(text)
    assert (d.base, d.seal, d.seals, d.clearance_class, d.contact_angle, d.tolerance_class) == (
        base, seal, seals, clearance, angle, tolerance)


@pytest.mark.parametrize("text", ["6208-2XX", "6208/C7", "6208-Q", "7205 BQ"])
def test_unknown_suffix_names_the_valid_ones(text):
    with pytest.raises(InputError, match=r"unknown suffix .* valid suffixes: seals/shields 2RS1.*clearance C2, CN, "
                                         r"C3, C4, C5; tolerance P0, P6, P5, P4, P4A"):
        designation.parse(text)


def test_two_suffixes_of_one_kind():
    with pytest.raises(InputError, match="two clearance suffixes"):
        designation.parse("6208/C3/C4")


def test_angle_code_on_a_deep_groove_bearing():
    with pytest.raises(InputError, match="angle code 'B' .* angular-contact"):
        designation.parse("6208 B")


def test_get_6208_2rs1_c3():
    # issue 21: the right geometry, seals and clearance
    b = catalog.get("6208-2RS1/C3")
    assert (b.bore, b.outside_diameter, b.width) == pytest.approx((0.040, 0.080, 0.018))
    assert (b.seal, b.seals, b.clearance_class, b.type) == ("RS1", 2, "C3", "radial")
    # ISO 5753-1, 30 < d <= 40 mm, C3: 15..33 um -> the mean 24 um
    assert b.radial_clearance == pytest.approx(24e-6)
    assert b.dynamic_load_rating == pytest.approx(32.5e3) and b.static_load_rating == pytest.approx(19.0e3)
    assert b.n_balls >= 7 and 0.5 < b.inner_conformity < b.outer_conformity
    assert "n_balls" in b.estimated_fields and "SKF" in b.sources["dynamic_load_rating"]


def test_clearance_choice_min_max():
    lo = catalog.get("6208/C3", clearance="min").radial_clearance
    hi = catalog.get("6208/C3", clearance="max").radial_clearance
    assert (lo, hi) == pytest.approx((15e-6, 33e-6))


def test_no_suffix_is_normal_clearance():
    b = catalog.get("6208")
    assert b.clearance_class is None and b.radial_clearance == pytest.approx((6e-6 + 20e-6) / 2)
    assert "Normal (CN)" in b.sources["radial_clearance"]


def test_angle_codes_of_several_makers_give_the_same_angle():
    for text in ("7205 BECBP", "7205 BEP", "7205-B-TVP", "7205 B", "7205 BW", "7205B"):
        assert math.degrees(catalog.get(text).contact_angle) == pytest.approx(40.0)
    assert math.degrees(catalog.get("7014 CD/P4A").contact_angle) == pytest.approx(15.0)
    assert catalog.get("7014 CD/P4A").tolerance_class == "P4A"
    assert math.degrees(catalog.get("71914 ACD").contact_angle) == pytest.approx(25.0)  # NSK 7914 A5


def test_maker_spelling_resolves_to_the_row_with_a_note():
    b = catalog.get("7205 BW")
    assert b.sources["contact_angle"].endswith("ratings and dimensions are NSK 7205 B's")


def test_the_existing_entries_resolve_as_before():
    assert catalog.get("7218B").designation == "B218" and catalog.get("7218B").n_balls == 16
    assert catalog.get("6205-2RS").pitch_diameter == pytest.approx(39.04e-3)
    assert catalog.get("61811-2RS1").seal_diameter == pytest.approx(59.5e-3)
    for name in ("4-1006095", "1000095", "18", "101"):
        assert catalog.get(name).designation == name


@pytest.mark.parametrize(("text", "hint"), [
    ("7205", "needs its contact-angle code; did you mean 7205 BE or 7205 A or 7205 B or 7205 C or 7205 ACD?"),
    ("7305 CD", "no 7305 with the angle code CD (15 deg)"),
    ("6299", "did you mean 6240 or 6238 or 6236 (series 62)?"),
])
def test_did_you_mean_by_series_and_size(text, hint):
    with pytest.raises(CatalogError, match=hint.replace("(", r"\(").replace(")", r"\)").replace("?", r"\?")):
        catalog.get(text)


def test_angular_bearings_take_no_clearance_class():
    with pytest.raises(InputError, match="deep-groove ball bearing class"):
        catalog.get("7205 BE/C3")

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


# --------------------------------------------------------------------- issue 30: Schaeffler and SKF suffixes
@pytest.mark.parametrize(("text", "base", "seal", "seals", "clearance", "angle", "extra"), [
    ("6208-2RSR", "6208", "RSR", 2, None, None, {}),                       # Schaeffler lip seals
    ("6208-2Z", "6208", "Z", 2, None, None, {}),
    ("6208-C3", "6208", None, None, "C3", None, {}),
    ("6208-2RSR-C3", "6208", "RSR", 2, "C3", None, {}),
    ("7208-B-XL-JP", "7208", None, None, None, 40.0, {"designs": ("XL",), "cage": "JP"}),
    ("6208 N", "6208", None, None, None, None, {"designs": ("N",)}),           # snap-ring groove
    ("6208 NR", "6208", None, None, None, None, {"designs": ("NR",)}),         # groove and snap ring
    ("6208-2ZNR", "6208", "Z", 2, None, None, {"designs": ("NR",)}),
    ("1208 E", "1208", None, None, None, None, {"designs": ("E",)}),
    ("1208 ETN9", "1208", None, None, None, None, {"designs": ("E",), "cage": "TN9"}),
    ("6208 TN9", "6208", None, None, None, None, {"cage": "TN9"}),
    ("6208 J", "6208", None, None, None, None, {"cage": "J"}),
    ("2318 M", "2318", None, None, None, None, {"cage": "M"}),
    ("QJ 208 MA", "QJ208", None, None, None, None, {"cage": "MA"}),
    ("QJ 208 N2MA", "QJ208", None, None, None, None, {"designs": ("N2",), "cage": "MA"}),
    ("6208-2Z/HC5C3", "6208", "Z", 2, "C3", None, {"ball_material": "silicon_nitride"}),
    ("7208 BEGAPH", "7208", None, None, None, 40.0, {"preload_class": "GA", "cage": "PH"}),
    ("7208 BEGBP", "7208", None, None, None, 40.0, {"preload_class": "GB", "cage": "P"}),
    ("7208 BECBP GC", "7208", None, None, None, 40.0, {"preload_class": "GC"}),
    ("7014 CD/P4ADBB", "7014", None, None, None, 15.0, {"preload_class": "B", "arrangement": "DB",
                                                        "tolerance_class": "P4A"}),
    ("7014 CD/P2", "7014", None, None, None, 15.0, {"tolerance_class": "P2"}),
    ("4208 ATN9", "4208", None, None, None, None, {"designs": ("A",), "cage": "TN9"}),
    ("3208 A", "3208", None, None, None, 30.0, {}),
    ("S 6208 E TA UL", "S6208", None, None, None, 25.0, {"cage": "TA", "preload_class": "UL"}),
])
def test_parse_the_suffixes_of_issue_30(text, base, seal, seals, clearance, angle, extra):
    d = designation.parse(text)
    assert (d.base, d.seal, d.seals, d.clearance_class, d.contact_angle) == (base, seal, seals, clearance, angle)
    for key, value in extra.items():
        assert getattr(d, key) == value, key


@pytest.mark.parametrize(("text", "match"), [
    ("6208-2RSX", r"unknown suffix 'X' in '6208-2RSX'; valid suffixes: seals/shields 2RS1"),
    ("1208 EKTN9", r"unknown suffix 'KTN9'"),                      # tapered bore: not in the catalog
    ("6208 NNR", r"two snap-ring suffixes"),
    ("6208 A", r"angle code 'A' .* angular-contact"),
    ("S 6208 B", r"angle code 'B' .* is not GMN's"),
    ("7014 CD GA DBB", r"two preload classes"),
])
def test_unknown_and_contradictory_suffixes_are_refused_in_one_line(text, match):
    with pytest.raises(InputError, match=match) as info:
        designation.parse(text)
    assert "\n" not in str(info.value)


@pytest.mark.parametrize(("text", "match"), [
    ("1215 E", r"'1215 E' asks for the E design, and the catalog has SKF 1215 only"),
    ("3208 B", r"no 3208 with the angle code B \(40 deg\)"),
    ("7208 B GA", None),                                            # GA takes SKF's BE row, not NSK's B
    ("7208 A GB", r"preload class GB of '7208 A GB' is SKF's"),
    ("7208 BE UL", r"preload class UL of '7208 BE UL' is GMN's"),
    ("4208/C3", r"clearance class C3 of '4208/C3' is a single-row deep-groove ball bearing class"),
    ("S 6208 TA", r"needs its contact-angle code; did you mean S 6208 C or S 6208 E"),
])
def test_resolution_refuses_what_the_catalog_does_not_have(text, match):
    if match is None:
        b = catalog.get(text)
        assert b.source.startswith("SKF 7208 BECBP") and b.preload == pytest.approx(80.0)
        return
    with pytest.raises((InputError, CatalogError), match=match):
        catalog.get(text)


def test_the_designations_resolve_to_the_right_rows():
    for text, row in (("6208-2RSR-C3", "6208"), ("6208 ETN9", "6208 ETN9"), ("6208 E", "6208 ETN9"), ("1208", "1208"),
                      ("1208 ETN9", "1208"), ("QJ208-TVP", "QJ 208"), ("QJ 208 N2MA", "QJ 208"), ("62205-2RS1", "62205"),
                      ("4208 ATN9", "4208"), ("3208 ATN9", "3208 A"), ("51208", "51208"), ("7308 AC/P5", "7308 AC"), ("7308 ACD", "7308 AC"),
                      ("7208 AC", "7208 ACD"), ("S 6208 C TA P4 UL", "S 6208 C")):
        assert catalog.details(text)["row"] == row, text

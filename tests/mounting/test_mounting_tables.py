"""ISO 286 fields and ISO 492 tolerances against limits read by hand from the published tables.

Shaft and housing limits: SKF Rolling bearings catalogue (PUB BU/P1 10000/2 EN, 2016), tables 7 and 8
"Shaft / Housing tolerances and resultant fits" (web copies: yumpu.com "SKF - Rolling Bearings" pp. 186,
192, 200; germany-bearing.com articles s66, s67, s68, s70, s74; original-bearing.com s71; pdfcoffee.com
"tolerances-and-resultant-fits-skf"), which print the ISO 286-2 deviations of each seat and the
theoretical interference with a bearing of Normal tolerance. js5/js6 from JIS B 0401-2:1999 (= ISO
286-2) as reproduced by Sumitomo (docs.steelcam.org, technical information p. 28). Integers: exact.
"""

import numpy as np
import pytest

from bearinglab.errors import InputError
from bearinglab.mounting import fits, tables

# (field, over, up to [mm], lower, upper [um]) as printed; the test uses the upper end of each range
SEATS = [
    ("k5", 3, 6, 1, 6), ("k5", 6, 10, 1, 7), ("k5", 10, 18, 1, 9), ("k5", 18, 30, 2, 11),
    ("k5", 30, 50, 2, 13), ("k5", 50, 80, 2, 15), ("k5", 80, 120, 3, 18),
    ("k6", 30, 50, 2, 18), ("k6", 80, 120, 3, 25), ("m5", 30, 50, 9, 20), ("m5", 80, 120, 13, 28),
    ("m6", 30, 50, 9, 25), ("m6", 80, 120, 13, 35), ("n6", 80, 100, 23, 45), ("n6", 120, 140, 27, 52),
    ("n6", 180, 200, 31, 60), ("p6", 80, 100, 37, 59), ("p6", 120, 140, 43, 68), ("p6", 180, 200, 50, 79),
    ("g6", 30, 50, -25, -9), ("g6", 80, 120, -34, -12), ("h5", 30, 50, -11, 0), ("h5", 180, 250, -20, 0),
    ("h6", 30, 50, -16, 0), ("h6", 10, 18, -11, 0), ("j5", 10, 18, -3, 5), ("j5", 50, 80, -7, 6),
    ("j6", 18, 30, -4, 9), ("j6", 50, 80, -7, 12), ("js5", 18, 24, -4.5, 4.5), ("js6", 30, 40, -8, 8),
    ("js6", 50, 65, -9.5, 9.5),
    ("F7", 30, 50, 25, 50), ("F7", 120, 150, 43, 83), ("G6", 30, 50, 9, 25), ("G6", 120, 150, 14, 39),
    ("G7", 30, 50, 9, 34), ("G7", 180, 250, 15, 61), ("H6", 30, 50, 0, 16), ("H6", 250, 315, 0, 32),
    ("H7", 30, 50, 0, 25), ("H7", 80, 120, 0, 35), ("H8", 30, 50, 0, 39), ("H8", 80, 120, 0, 54),
    ("J6", 30, 50, -6, 10), ("J6", 80, 120, -6, 16), ("J7", 30, 50, -11, 14), ("J7", 80, 120, -13, 22),
    ("J7", 180, 250, -16, 30), ("JS6", 30, 50, -8, 8), ("JS6", 80, 120, -11, 11), ("JS6", 180, 250, -14.5, 14.5),
    ("JS7", 30, 50, -12.5, 12.5), ("JS7", 180, 250, -23, 23), ("K6", 30, 50, -13, 3), ("K6", 80, 120, -18, 4),
    ("K6", 180, 250, -24, 5), ("K7", 30, 50, -18, 7), ("K7", 80, 120, -25, 10), ("K7", 180, 250, -33, 13),
    ("M6", 30, 50, -20, -4), ("M6", 80, 120, -28, -6), ("M6", 180, 250, -37, -8), ("M7", 30, 50, -25, 0),
    ("M7", 80, 120, -35, 0), ("M7", 180, 250, -46, 0), ("N6", 30, 50, -28, -12), ("N6", 150, 180, -45, -20),
    ("N6", 250, 315, -57, -25), ("N7", 30, 50, -33, -8), ("N7", 180, 250, -60, -14),
    ("N7", 250, 315, -66, -14), ("P6", 30, 50, -37, -21), ("P6", 250, 315, -79, -47),
    ("P7", 30, 50, -42, -17), ("P7", 250, 315, -88, -36),
]


@pytest.mark.parametrize("row", SEATS, ids=[f"{r[0]}-{r[1]}-{r[2]}" for r in SEATS])
def test_field_limits_match_the_printed_tables(row):
    field, over, up_to, lower, upper = row
    for size_mm in (up_to, 0.5 * (over + up_to)):  # the end of a range belongs to it
        got = tables.field_limits(field, size_mm * 1e-3)
        assert (got.lower * 1e6, got.upper * 1e6) == pytest.approx((lower, upper), abs=1e-9)


def test_m6_special_case_of_iso_286_1():
    """ISO 286-1 table 3 footnote: M6 over 250 up to 315 mm has ES = -9 um, not -20 + 9 = -11 um."""
    got = tables.field_limits("M6", 0.300)
    assert (got.lower * 1e6, got.upper * 1e6) == pytest.approx((-41, -9))
    assert tables.field_limits("M6", 0.320).upper * 1e6 == pytest.approx(-21 + 11)


# SKF tables 7 and 8: theoretical interference (-) / clearance (+) of a seat with a Normal bearing
THEORETICAL = [
    ("k5", 40, -25, -2), ("m6", 100, -55, -13), ("k5", 25, -21, -2), ("n6", 90, -65, -23),
    ("p6", 130, -93, -43), ("j6", 60, -27, 7),
]


@pytest.mark.parametrize("field, d, tight, loose", THEORETICAL)
def test_inner_interference_matches_skf_theoretical(field, d, tight, loose):
    i = fits.inner_interference(tables.field_limits(field, d * 1e-3), tables.bore_limits(d * 1e-3))
    assert (i.largest * 1e6, i.least * 1e6) == pytest.approx((-tight, -loose))


HOUSING_THEORETICAL = [("N7", 40, -33, 3), ("K7", 40, -18, 18), ("P7", 280, -88, -1), ("M7", 100, -35, 15),
                       ("H7", 40, 0, 36), ("N6", 160, -45, 5)]


@pytest.mark.parametrize("field, big, tight, loose", HOUSING_THEORETICAL)
def test_outer_interference_matches_skf_theoretical(field, big, tight, loose):
    i = fits.outer_interference(tables.outside_diameter_limits(big * 1e-3), tables.field_limits(field, big * 1e-3))
    assert (i.largest * 1e6, i.least * 1e6) == pytest.approx((-tight, -loose))


# ISO 492 (SKF catalogue tables 3 to 6): the lower deviation of Delta_dmp / Delta_Dmp, upper 0
BEARING = [("inner", "Normal", 40, -12), ("inner", "Normal", 100, -20), ("inner", "P6", 40, -10),
           ("inner", "P5", 40, -8), ("inner", "P4", 40, -6), ("inner", "P4", 200, -12),
           ("outer", "Normal", 140, -18), ("outer", "Normal", 160, -25), ("outer", "P6", 90, -13),
           ("outer", "P5", 200, -15), ("outer", "P4", 52, -7), ("inner", "P5", 10, -5)]


@pytest.mark.parametrize("ring, klass, size, lower", BEARING)
def test_iso_492_deviations(ring, klass, size, lower):
    f = tables.bore_limits if ring == "inner" else tables.outside_diameter_limits
    got = f(size * 1e-3, klass)
    assert (got.lower * 1e6, got.upper * 1e6) == pytest.approx((lower, 0))


def test_fields_are_vectorized():
    sizes = np.array([0.025, 0.040, 0.100])
    got = tables.field_limits("k5", sizes)
    assert np.allclose(got.upper * 1e6, [11, 13, 18])


def test_standard_tolerance_grades():
    assert [round(tables.standard_tolerance(g, 0.1) * 1e6) for g in (5, 6, 7, 8)] == [15, 22, 35, 54]


@pytest.mark.parametrize("bad, match", [("k9", "field must be one of"), ("X7", "field must be one of")])
def test_unknown_field(bad, match):
    with pytest.raises(InputError, match=match):
        tables.field_limits(bad, 0.04)


def test_sizes_outside_the_tables():
    with pytest.raises(InputError, match="size must be in"):
        tables.field_limits("k5", 0.6)
    with pytest.raises(InputError, match="P4"):
        tables.bore_limits(0.3, "P4")
    with pytest.raises(InputError, match="tolerance-class must be one of"):
        tables.tolerance_class("P3")


def test_class_aliases():
    assert tables.tolerance_class("P0") == tables.tolerance_class("normal") == "Normal"


def test_smoothing_per_din_7190():
    assert fits.smoothing(4e-6, 1.6e-6) == pytest.approx(0.4 * 5.6e-6)
    with pytest.raises(ValueError, match="roughness_a"):
        fits.smoothing(-1e-6, 0.0)


# SKF tables 7 and 8, the "probable interference (-) / clearance (+)" rows: (field, size, printed range)
PROBABLE = [
    ("k5", 2, -11, -1), ("k6", 2, -12, -2), ("m5", 2, -13, -3), ("m6", 2, -14, -4),
    ("k5", 5, -13, -2), ("k6", 5, -15, -3), ("m5", 5, -16, -5), ("m6", 5, -18, -6),
    ("k5", 8, -13, -3), ("k6", 8, -16, -3), ("m5", 8, -18, -8), ("m6", 8, -21, -8),
    ("k5", 15, -15, -3), ("k6", 15, -18, -3), ("m5", 15, -21, -9), ("m6", 15, -24, -9),
    ("k5", 25, -19, -4), ("k6", 25, -22, -5), ("m5", 25, -25, -10), ("m6", 25, -28, -11),
    ("k5", 40, -22, -5), ("k6", 40, -26, -6), ("m5", 40, -29, -12), ("m6", 40, -33, -13),
    ("k5", 60, -26, -6), ("k6", 60, -32, -6), ("m5", 60, -35, -15), ("m6", 60, -41, -15),
    ("N6", 40, -25, -4), ("N7", 40, -29, -1), ("P6", 40, -34, -13), ("P7", 40, -38, -10),
    ("K6", 40, -10, 11), ("K7", 40, -14, 14), ("M6", 40, -17, 4), ("M7", 40, -21, 7),
    ("K6", 100, -13, 14), ("K7", 100, -20, 20), ("M6", 100, -23, 4), ("M7", 100, -30, 10), ("H7", 40, 4, 32),
]


@pytest.mark.parametrize("field, size, tight, loose", PROBABLE)
def test_probable_interference_reproduces_skf(field, size, tight, loose):
    """SKF prints the mean +- half the RSS of the widths, rounded outward to the micrometre."""
    import math

    d = size * 1e-3
    if field.islower():
        p = fits.probable_interference(tables.field_limits(field, d), tables.bore_limits(d))
    else:
        p = fits.probable_interference(tables.outside_diameter_limits(d), tables.field_limits(field, d))
    assert (math.floor(p.least * 1e6 + 1e-9), math.ceil(p.largest * 1e6 - 1e-9)) == (-loose, -tight)

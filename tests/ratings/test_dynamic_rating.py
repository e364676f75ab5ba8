"""ISO 281 dynamic load rating, equivalent load, basic life and reliability factor."""

import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from bearinglab import ratings
from bearinglab.errors import InputError

# ISO 281:2007 table 2 (single-row radial ball bearings), some rows; ISO 281 table 12 (a1)
FC_ROWS = [(0.05, 46.7), (0.10, 55.5), (0.18, 59.9), (0.20, 59.9), (0.30, 56.0), (0.40, 48.4)]
A1_ROWS = [(0.90, 1.0), (0.95, 0.64), (0.96, 0.55), (0.97, 0.47), (0.98, 0.37), (0.99, 0.25), (0.992, 0.22),
           (0.994, 0.19), (0.996, 0.16), (0.998, 0.12), (0.999, 0.093), (0.9992, 0.087), (0.9994, 0.080),
           (0.9995, 0.077)]


@pytest.mark.parametrize(("gamma", "fc"), FC_ROWS)
def test_fc_at_the_table_rows(gamma, fc):
    assert ratings.load_rating_factor(10e-3, 10e-3 / gamma) == pytest.approx(fc, rel=1e-12)


def test_fc_outside_table_raises():
    with pytest.raises(InputError, match=r"Dw cos\(alpha\) / Dpw must be in \[0.01, 0.40\]"):
        ratings.load_rating_factor(10e-3, 20e-3)


def test_dynamic_load_rating_formula_and_large_balls():
    # ISO 281 eq. (2) by hand for the deep-groove 6205 ball set (Z = 9, Dw = 7.94 mm)
    gamma = 7.94 / 39.04
    fc = np.interp(gamma, [0.20, 0.22], [59.9, 59.6])
    assert ratings.dynamic_load_rating(9, 7.94e-3, 39.04e-3) == pytest.approx(
        1.3 * fc * 9 ** (2 / 3) * 7.94**1.8, rel=1e-12)
    # eq. (3) above Dw = 25.4 mm
    assert ratings.dynamic_load_rating(10, 30e-3, 0.2) == pytest.approx(
        1.3 * ratings.load_rating_factor(30e-3, 0.2) * 10 ** (2 / 3) * 3.647 * 30**1.4, rel=1e-12)


def test_equivalent_load_deep_groove_rows_and_limit():
    # ISO 281 table 3: at f0 Fa/C0 = 1.03, e = 0.28, X = 0.56, Y = 1.55
    c0, f0 = 10000.0, 10.3
    fa = 1000.0
    assert ratings.equivalent_dynamic_load(10000.0, fa, c0, static_load_factor=f0) == 10000.0  # Fa/Fr <= e
    assert ratings.equivalent_dynamic_load(1000.0, fa, c0, static_load_factor=f0) == pytest.approx(
        0.56 * 1000 + 1.55 * 1000)
    assert ratings.equivalent_dynamic_load(0.0, fa, c0, static_load_factor=f0) == pytest.approx(1.55 * 1000)
    with pytest.raises(InputError, match="static_load_factor"):
        ratings.equivalent_dynamic_load(1000.0, fa, c0)


def test_equivalent_load_angular_contact():
    # 40 deg: e = 1.14, X = 0.35, Y = 0.57; 15 deg at i Fa/C0 = 0.058: e = 0.43, X = 0.44, Y = 1.30
    a40 = math.radians(40)
    assert ratings.equivalent_dynamic_load(1000.0, 2000.0, 1e4, a40, bearing_type="angular") == pytest.approx(
        0.35 * 1000 + 0.57 * 2000)
    assert ratings.equivalent_dynamic_load(1000.0, 1000.0, 1e4, a40, bearing_type="angular") == 1000.0
    a15 = math.radians(15)
    assert ratings.equivalent_dynamic_load(1000.0, 580.0, 1e4, a15, bearing_type="angular") == pytest.approx(
        0.44 * 1000 + 1.30 * 580)
    with pytest.raises(InputError, match="contact_angle"):
        ratings.equivalent_dynamic_load(1000.0, 580.0, 1e4, math.radians(10), bearing_type="angular")


@pytest.mark.parametrize(("reliability", "a1"), A1_ROWS)
def test_reliability_factor_table(reliability, a1):
    assert ratings.reliability_factor(reliability) == a1


@given(r=st.floats(0.9, 0.9995))
def test_reliability_factor_between_rows_is_near_the_table(r):
    a1 = ratings.reliability_factor(r)
    rows = np.array(A1_ROWS)
    lo = np.interp(r, rows[:, 0], rows[:, 1])
    assert 0.0 < a1 <= 1.0
    assert a1 == pytest.approx(lo, abs=0.03)  # the Weibull relation lies within 0.03 of the chords


def test_reliability_out_of_range():
    with pytest.raises(InputError, match=r"a fraction: 0.99 for 99 %"):
        ratings.reliability_factor(99.0)


@given(p=st.floats(10.0, 1e5), k=st.floats(0.1, 10.0))
def test_life_scales_with_load_to_minus_three(p, k):
    c = 20000.0
    assert ratings.basic_rating_life(c, k * p) == pytest.approx(ratings.basic_rating_life(c, p) / k**3, rel=1e-12)


def test_life_at_zero_load_is_infinite():
    with np.errstate(divide="ignore"):
        assert ratings.basic_rating_life(1000.0, 0.0) == math.inf


@pytest.mark.parametrize("deg", [20.0, 25.0, 30.0, 35.0, 40.0, 45.0])
def test_angular_contact_limit_e_is_where_the_two_loads_meet(deg):
    # ISO 281 table 3: e is the ratio Fa/Fr at which P = X Fr + Y Fa equals P = Fr, e = (1 - X)/Y, to the
    # two decimals printed (checks the X, Y and e columns against each other, row by row)
    x, y, e = ratings.dynamic_load_factors(1.0, 10.0, 1e5, math.radians(deg), bearing_type="angular")
    assert e == pytest.approx((1 - x) / y, abs=0.005 + 1e-12)


def test_deep_groove_f0_matches_skf_calculation_factor_of_6205():
    # SKF product data of the 6205 (PUB BU/P1 17000, product table; also SKF's web page as parsed by two
    # public tools, issue 12): calculation factor f0 = 14, printed as an integer. ISO 76 from the 6205
    # ball set of the catalog (9 x 7.94 mm on 39.04 mm) must round to it.
    from bearinglab import catalog

    b = catalog.get("6205-2RS")
    assert round(float(ratings.static_load_factor(b.ball_diameter, b.pitch_diameter))) == 14


@pytest.mark.parametrize("degrees, words", [
    (12.0, "got 12 deg: angles below 15 deg are not tabulated here;"),
    (50.0, "got 50 deg: above 45 deg the bearing is a thrust bearing, not covered;"),
])
def test_an_angle_outside_table_3_names_it_without_float_noise_and_says_what_to_do(degrees, words):
    # math.radians(12) -> degrees gives 12.000000000000002: the message shows 12 deg (issue 15)
    with pytest.raises(InputError) as error:
        ratings.equivalent_dynamic_load(1000.0, 580.0, 1e4, math.radians(degrees), bearing_type="angular")
    message = str(error.value)
    assert message.startswith("contact_angle must be in [15, 45] [deg] for ISO 281 table 3 (angular contact), ")
    assert words in message and "0000" not in message
    assert "give P from the maker's X and Y (basic_rating_life(C, P))" in message


def test_a_pure_radial_load_needs_no_table_row_for_any_angle():
    # Fa = 0: Fa/Fr = 0 <= e on every row of ISO 281 table 3 (and X0 <= 1 in ISO 76), so P = P0 = Fr,
    # also at 12 deg, which the tables carried here do not cover
    from bearinglab.ratings import static

    fr = np.array([0.0, 19.6133, 500.0])
    for deg in (12.0, 15.0, 25.0, 40.0):
        a = math.radians(deg)
        assert ratings.equivalent_dynamic_load(fr, 0.0, 281.9, a, bearing_type="angular").tolist() == fr.tolist()
        assert static.static_equivalent_load(fr, 0.0, a, bearing_type="angular").tolist() == fr.tolist()
    with pytest.raises(InputError, match="got 12 deg"):
        ratings.equivalent_dynamic_load(fr, 1.0, 281.9, math.radians(12.0), bearing_type="angular")

"""ISO 281 / ISO 76 ratings, X / Y / e, Cu and a_ISO of roller bearings; ISO/TS 16281 over the laminae."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from bearinglab import catalog, ratings
from bearinglab.errors import InputError
from bearinglab.ratings import roller as ro
from bearinglab.ratings import roller_reference as rr
from bearinglab.rollers import with_estimated_geometry


def fc_formula(gamma):
    """f_c of radial roller bearings, ISO/TR 1281-1 (lambda nu = 0.83), typed out again."""
    return (207.9 * 0.83 * gamma ** (2 / 9) * (1 - gamma) ** (29 / 27) / (1 + gamma) ** 0.25
            * (1 + (1.04 * ((1 - gamma) / (1 + gamma)) ** (143 / 108)) ** 4.5) ** (-2 / 9))


def test_every_row_of_table_7_is_the_formula_to_its_printed_rounding():
    for g, f in zip(ro._FC_GAMMA, ro._FC, strict=True):
        assert f == pytest.approx(fc_formula(g), abs=0.051), g  # one decimal printed
    with pytest.raises(InputError, match=r"^D_we cos\(alpha\) / D_pw must be in \[0.01, 0.30\]"):
        ro.roller_load_rating_factor(20e-3, 60e-3)


def test_ratings_by_hand():
    # NU 208 with an assumed set: Z = 14, D_we = 11 mm, L_we = 9.56 mm, D_pw = 60.5 mm (N, mm)
    z, d, length, dpw = 14, 11.0, 9.56, 60.5
    g = d / dpw
    fc = np.interp(g, ro._FC_GAMMA, ro._FC)
    c = 1.1 * fc * length ** (7 / 9) * z ** 0.75 * d ** (29 / 27)
    c0 = 44 * (1 - g) * z * length * d
    assert ro.roller_dynamic_load_rating(z, d * 1e-3, length * 1e-3, dpw * 1e-3) == pytest.approx(c, rel=1e-12)
    assert ro.roller_static_load_rating(z, d * 1e-3, length * 1e-3, dpw * 1e-3) == pytest.approx(c0, rel=1e-12)
    a = math.radians(14.0)
    ga = d * math.cos(a) / dpw
    c_t = 1.1 * np.interp(ga, ro._FC_GAMMA, ro._FC) * (length * math.cos(a)) ** (7 / 9) * z**0.75 * d ** (29 / 27)
    assert ro.roller_dynamic_load_rating(z, d * 1e-3, length * 1e-3, dpw * 1e-3, a, bearing_type="tapered") == \
        pytest.approx(c_t, rel=1e-12)
    assert ro.roller_dynamic_load_rating(z, d * 1e-3, length * 1e-3, dpw * 1e-3, bearing_type="spherical",
                                         rows=2) / ro.roller_dynamic_load_rating(
        z, d * 1e-3, length * 1e-3, dpw * 1e-3) == pytest.approx(1.15 / 1.1 * 2 ** (7 / 9), rel=1e-12)
    # thrust, alpha = 90 deg: C_a = b_m f_c L^(7/9) Z^(3/4) D^(29/27); C0a = 220 Z L D
    assert ro.roller_dynamic_load_rating(z, d * 1e-3, length * 1e-3, dpw * 1e-3, math.pi / 2,
                                         bearing_type="thrust-cylindrical", load_rating_factor=100.0) == \
        pytest.approx(100.0 * length ** (7 / 9) * z**0.75 * d ** (29 / 27), rel=1e-12)
    assert ro.roller_static_load_rating(z, d * 1e-3, length * 1e-3, dpw * 1e-3, math.pi / 2, thrust=True) == \
        pytest.approx(220 * z * length * d, rel=1e-12)


def test_iso_ratings_of_estimated_sets_against_the_catalogue():
    # the documented band (docs/user_guide/roller_bearings.md): ISO 281's C of the estimated roller set is 0.86-0.87
    # of SKF's C for the Explorer ECP cylindrical bearings (SKF's ratings exceed ISO's), 0.95-1.08 for the tapered
    # ones; ISO 76's C0 equals the catalogue's by construction (the set is fitted to it)
    for name, lo, hi in (("NU 208 ECP", 0.85, 0.88), ("NU 2208 ECP", 0.85, 0.88), ("NU 308 ECP", 0.85, 0.88),
                         ("30208 J2/Q", 0.94, 1.09), ("32208 J2/Q", 0.94, 1.09), ("30308 J2/Q", 0.94, 1.09),
                         ("31308 J2/QCL7C", 0.94, 1.09), ("32308 J2/Q", 0.94, 1.09)):
        b = with_estimated_geometry(catalog.get(name))
        c = ro.roller_dynamic_load_rating(b.rollers, b.roller_diameter, b.roller_length, b.pitch_diameter,
                                          b.contact_angle, bearing_type=b.type)
        assert lo <= c / b.dynamic_load_rating <= hi, name


def test_fatigue_load_limit_against_skfs_pu():
    # ISO 281 annex B, roller bearings: Cu = C0 / 8.2 (x (100 / D_pw)^0.3 above 100 mm) against SKF's printed Pu
    # (the band docs/theory/roller_bearings.md gives, measured over the 656 built-in bearings): cylindrical
    # 0.89-1.02, tapered 0.94-1.24, spherical 1.01-1.15
    from bearinglab.catalog import _rollers

    bands = {"cylindrical": (0.889, 1.020), "tapered": (0.941, 1.241), "spherical": (1.013, 1.155)}
    for name in _rollers.records():
        b = catalog.get(name)
        ratio = ro.roller_fatigue_load_limit(b.static_load_rating, b.mean_diameter) / b.fatigue_load_limit
        lo, hi = bands[b.type]
        assert lo - 5e-4 <= ratio <= hi + 5e-4, name
    assert ro.roller_fatigue_load_limit(82e3, 0.2) == pytest.approx(1e4 * 0.5**0.3)


def test_load_factors_of_iso_281_table_8_and_the_catalogues():
    a = math.atan(0.4 / 1.6)  # 30208: Y = 1.6
    f = ro.roller_load_factors(1000.0, [300.0, 500.0], a)
    assert f.limit == pytest.approx(1.5 * math.tan(a)) and f.limit[0] == pytest.approx(0.375)
    assert list(f.radial_factor) == [1.0, 0.4] and f.axial_factor[1] == pytest.approx(1.6)
    # the catalogue's e and Y agree with ISO's for the SKF rows (printed to two digits)
    for name in ("30208 J2/Q", "32208 J2/Q", "30308 J2/Q", "31308 J2/QCL7C"):
        b = catalog.get(name)
        alpha = math.atan(0.4 / b.axial_factor)
        assert 1.5 * math.tan(alpha) == pytest.approx(b.ratio_limit, abs=0.011), name
        assert 0.22 / math.tan(alpha) == pytest.approx(b.static_axial_factor, abs=0.051), name
    s = catalog.get("22208 E")  # double row: Y1 = 0.45 cot a, Y2 = 0.67 cot a with e = 1.5 tan a
    alpha = math.atan(s.ratio_limit / 1.5)
    assert 0.45 / math.tan(alpha) == pytest.approx(s.axial_factor_below, abs=0.05)
    assert 0.67 / math.tan(alpha) == pytest.approx(s.axial_factor, abs=0.05)
    p = ro.roller_equivalent_load([1000.0, 1000.0], [200.0, 400.0], rows=2, ratio_limit=0.28,
                                  axial_factor=3.6, axial_factor_below=2.4)
    assert p == pytest.approx([1000 + 2.4 * 200, 0.67 * 1000 + 3.6 * 400])
    p0 = ro.roller_static_equivalent_load([1000.0, 1000.0], [100.0, 1000.0], static_axial_factor=0.9)
    assert p0 == pytest.approx([1000.0, 0.5 * 1000 + 900])


def test_a_iso_of_roller_bearings_is_continuous_and_capped():
    k = np.array([0.4 - 1e-12, 0.4, 1 - 1e-12, 1.0])
    a = ro.roller_life_modification_factor(k, 0.8, 6700.0, 20000.0)
    assert a[0] == pytest.approx(a[1], rel=1e-4) and a[2] == pytest.approx(a[3], rel=1e-9)
    assert ro.roller_life_modification_factor(4.0, 1.0, 6700.0, 500.0) == 50.0
    # by hand at kappa = 2: 0.1 [1 - (1.5859 - 1.2348 / 2^0.071739) (e_C Cu / P)^0.4]^-9.185
    want = 0.1 * (1 - (1.5859 - 1.2348 / 2**0.071739) * (0.5 * 6700 / 20000) ** 0.4) ** -9.185
    assert ro.roller_life_modification_factor(2.0, 0.5, 6700.0, 20000.0) == pytest.approx(want, rel=1e-12)


def test_lamina_ratings_by_hand():
    c, z, d, dpw = 62e3, 14, 11e-3, 60.5e-3
    g = d / dpw
    ratio = 1.038 * ((1 - g) / (1 + g)) ** (143 / 108)
    qci = c / (0.83 * 0.378 * z) * (1 + ratio**4.5) ** (2 / 9)
    qce = c / (0.83 * 0.364 * z) * (1 + ratio**-4.5) ** (2 / 9)
    got = rr.roller_contact_dynamic_loads(c, z, d, dpw, n_slices=30)
    assert (got.inner, got.outer) == pytest.approx((qci, qce), rel=1e-12)
    assert got.lamina_inner == pytest.approx(qci * 30 ** (-7 / 9), rel=1e-12)


@settings(deadline=None)
@given(n=st.integers(2, 60), q=st.floats(10.0, 1e4))
def test_the_reference_life_of_uniform_laminae_does_not_depend_on_the_slicing(n, q):
    base = rr.roller_reference_rating_life(np.full((14, 1), q), 62e3, 11e-3, 60.5e-3)
    sliced = rr.roller_reference_rating_life(np.full((14, n), q / n), 62e3, 11e-3, 60.5e-3)
    assert sliced == pytest.approx(base, rel=1e-10)


def test_the_reference_life_sums_the_laminae_and_follows_the_load_to_the_fourth():
    q = np.zeros((14, 30))
    q[0] = 100.0
    one = rr.roller_reference_rating_life(q, 62e3, 11e-3, 60.5e-3)
    assert rr.roller_reference_rating_life(2 * q, 62e3, 11e-3, 60.5e-3) == pytest.approx(one / 16, rel=1e-12)
    # lamina life by hand: rotating inner ring (mean of q^4), standing outer ring (mean of q^(9/2))
    qc = rr.roller_contact_dynamic_loads(62e3, 14, 11e-3, 60.5e-3, n_slices=30)
    qei, qee = (100.0**4 / 14) ** 0.25, (100.0**4.5 / 14) ** (2 / 9)
    want = 1e6 * (30 * ((qei / qc.lamina_inner) ** 4.5 + (qee / qc.lamina_outer) ** 4.5)) ** (-8 / 9)
    assert one == pytest.approx(want, rel=1e-12)
    assert np.isinf(rr.roller_reference_rating_life(np.zeros((14, 30)), 62e3, 11e-3, 60.5e-3))


def test_bearing_ratings_of_a_roller_bearing():
    b = catalog.get("NU 208 ECP")
    r = ratings.bearing_ratings(b)
    assert (r.dynamic_load_rating, r.static_load_rating, r.fatigue_load_limit) == (62e3, 53e3, 6.7e3)
    assert set(r.rating_source.values()) == {"catalog"}
    est = with_estimated_geometry(b.replace(dynamic_load_rating=None, fatigue_load_limit=None))
    r = ratings.bearing_ratings(est)
    assert r.rating_source["dynamic_load_rating"] == "ISO 281 (from an estimated roller set)"
    assert r.rating_source["fatigue_load_limit"] == "ISO 281 annex B (C0/8.2)"
    assert r.fatigue_load_limit == pytest.approx(53e3 / 8.2)

"""The rating-life analysis of a BallBearing: sources, NaN rules, load distributions, duty cycles."""

import math
import warnings

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from numpy.testing import assert_allclose

from bearinglab import life, ratings
from bearinglab.bearing import BallBearing
from bearinglab.errors import InputError

B6205 = BallBearing(9, 7.94e-3, 39.04e-3, 0.52, 0.53, contact_angle=0.0, type="radial", designation="6205")
N = 3000 * math.pi / 30  # rad/s


def _quiet(*args, **kw):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ratings.RatingWarning)
        return life.rating_life(*args, **kw)


def test_catalog_values_take_precedence():
    geo = ratings.bearing_ratings(B6205)
    assert geo.rating_source == {"dynamic_load_rating": "ISO 281", "static_load_rating": "ISO 76",
                                 "fatigue_load_limit": "ISO 281 annex B (precise)"}
    cat = ratings.bearing_ratings(B6205.replace(dynamic_load_rating=14800.0, static_load_rating=7800.0,
                                                fatigue_load_limit=335.0))
    assert (cat.dynamic_load_rating, cat.static_load_rating, cat.fatigue_load_limit) == (14800.0, 7800.0, 335.0)
    assert set(cat.rating_source.values()) == {"catalog"}
    simple = ratings.bearing_ratings(B6205.replace(static_load_rating=7800.0), fatigue_method="simplified")
    assert simple.fatigue_load_limit == pytest.approx(7800.0 / 22)


def test_ratings_need_the_ball_set_or_the_catalog():
    with pytest.raises(InputError, match="dynamic_load_rating of 'x' is not in its catalog entry"):
        ratings.bearing_ratings(BallBearing(designation="x", bore=0.02, outside_diameter=0.04))


def test_life_quantities_compose():
    r = _quiet(B6205, [[1000.0, 500.0, 300.0, 0, 0]], N, kinematic_viscosity=20e-6, contamination=0.5,
               reliability=0.99, load_distribution=False)
    fr = math.hypot(1000.0, 500.0)
    p = ratings.equivalent_dynamic_load(fr, 300.0, r.static_load_rating,
                                        static_load_factor=ratings.static_load_factor(7.94e-3, 39.04e-3))
    assert r.equivalent_dynamic_load[0] == pytest.approx(p, rel=1e-14)
    l10 = 1e6 * (r.dynamic_load_rating / p) ** 3
    assert r.basic_rating_life[0] == pytest.approx(l10, rel=1e-14)
    assert r.basic_rating_life_duration[0] == pytest.approx(l10 / (3000 / 60), rel=1e-14)
    kappa = 20e-6 / ratings.rated_viscosity(N, 39.04e-3)
    assert r.viscosity_ratio == pytest.approx(kappa, rel=1e-14)
    a_iso = ratings.life_modification_factor(kappa, 0.5, r.fatigue_load_limit, p)
    assert r.modified_rating_life[0] == pytest.approx(0.25 * a_iso * l10, rel=1e-14)
    p0 = max(0.6 * fr + 0.5 * 300.0, fr)
    assert r.static_safety_factor[0] == pytest.approx(r.static_load_rating / p0, rel=1e-14)
    assert math.isnan(r.reference_rating_life[0])
    assert any("no load distribution" in w for w in r.warnings)


def test_moment_makes_iso281_fields_nan_but_not_the_reference_life():
    loads = np.array([[1000.0, 0, 0, 0, 0], [1000.0, 0, 0, 5.0, 0]])
    q = np.array([[300.0] * 9, [400.0] * 9])
    with pytest.warns(ratings.RatingWarning, match="tilting moment"):
        r = life.rating_life(B6205, loads, N, kinematic_viscosity=20e-6, load_distribution=q)
    assert np.isfinite(r.basic_rating_life[0]) and math.isnan(r.basic_rating_life[1])
    assert math.isnan(r.static_safety_factor[1]) and math.isnan(r.modified_rating_life[1])
    assert np.all(np.isfinite(r.reference_rating_life))
    assert any("tilting moment" in w for w in r.warnings)


def test_load_distribution_forms():
    q = np.full((2, 9), 250.0)

    class Result:  # the shape of the combined-load model's result
        ball_load_inner = q
        ball_load_outer = q

    loads = np.array([[1000.0, 0, 0, 0, 0]] * 2)
    a = _quiet(B6205, loads, N, kinematic_viscosity=20e-6, load_distribution=q)
    b = _quiet(B6205, loads, N, kinematic_viscosity=20e-6, load_distribution=Result())
    c = _quiet(B6205, loads, N, kinematic_viscosity=20e-6, load_distribution=lambda brg, f, n: Result())
    assert_allclose(a.reference_rating_life, b.reference_rating_life, rtol=0)
    assert_allclose(a.reference_rating_life, c.reference_rating_life, rtol=0)
    direct = ratings.reference_rating_life(q, a.dynamic_load_rating, 7.94e-3, 39.04e-3, 0.52, 0.53)
    assert_allclose(a.reference_rating_life, direct, rtol=0)
    p_ref = a.dynamic_load_rating * (direct / 1e6) ** (-1 / 3)
    a_ref = ratings.life_modification_factor(a.viscosity_ratio, 1.0, a.fatigue_load_limit, p_ref)
    assert_allclose(a.modified_reference_rating_life, a_ref * direct, rtol=1e-14)


def test_reference_life_approaches_iso281_for_many_balls():
    # pure radial load, zero clearance: Q_j = Q_max cos^1.5(psi_j) (rigid rings, Hertz balls); with many
    # balls L10r tends to (C/Fr)^3. The TS constants (0.407, 0.389, 1.044) are rounded to 3-4 digits:
    # the limit is 0.999, hence 0.2 %.
    for z in (40, 100):
        dpw = 0.2
        dw = 0.2644 * dpw
        psi = 2 * np.pi * np.arange(z) / z
        shape = np.clip(np.cos(psi), 0, None) ** 1.5
        q = 1000.0 * shape / np.sum(shape * np.cos(psi))
        c = ratings.dynamic_load_rating(z, dw, dpw)
        assert ratings.reference_rating_life(q, c, dw, dpw, 0.52, 0.53) == pytest.approx(
            ratings.basic_rating_life(c, 1000.0), rel=2e-3)


def test_lubricant_from_oil_data():
    a = _quiet(B6205, [1000.0, 0, 0, 0, 0], N, temperature=343.15, iso_vg=68, viscosity_100=8.7e-6)
    nu = ratings.kinematic_viscosity(343.15, iso_vg=68, viscosity_100=8.7e-6)
    b = _quiet(B6205, [1000.0, 0, 0, 0, 0], N, kinematic_viscosity=nu)
    assert a.viscosity_ratio == b.viscosity_ratio
    with pytest.raises(InputError, match="not both"):
        life.rating_life(B6205, [1000.0, 0, 0, 0, 0], N, kinematic_viscosity=nu, iso_vg=68)
    with pytest.raises(InputError, match="give kinematic_viscosity, or temperature"):  # an oil without temperature
        life.rating_life(B6205, [1000.0, 0, 0, 0, 0], N, iso_vg=68)


def test_contamination_class_and_bad_inputs():
    a = _quiet(B6205, [1000.0, 0, 0, 0, 0], N, kinematic_viscosity=20e-6, contamination="normal cleanliness")
    b = _quiet(B6205, [1000.0, 0, 0, 0, 0], N, kinematic_viscosity=20e-6, contamination=0.55)
    assert a.life_modification_factor == b.life_modification_factor
    with pytest.raises(InputError, match="loads must have the five components"):
        life.rating_life(B6205, [1000.0, 0, 0], N, kinematic_viscosity=20e-6)
    with pytest.raises(InputError, match="contamination must be a factor"):
        life.rating_life(B6205, [1000.0, 0, 0, 0, 0], N, kinematic_viscosity=20e-6, contamination=2.0)


@settings(max_examples=30, deadline=None)
@given(fr=st.floats(100.0, 5000.0), fa=st.floats(0.0, 3000.0), rpm=st.floats(10.0, 10000.0))
def test_batch_equals_per_case(fr, fa, rpm):
    loads = np.array([[fr, 0, fa, 0, 0], [fr / 2, fr / 2, fa / 3, 0, 0]])
    speed = np.array([rpm, 2 * rpm]) * math.pi / 30
    batch = _quiet(B6205, loads, speed, kinematic_viscosity=30e-6, contamination=0.4)
    for k in range(2):
        one = _quiet(B6205, loads[k], speed[k], kinematic_viscosity=30e-6, contamination=0.4)
        for name in ("equivalent_dynamic_load", "basic_rating_life", "modified_rating_life",
                     "static_safety_factor", "life_modification_factor"):
            assert getattr(batch, name)[k] == pytest.approx(getattr(one, name), rel=1e-14), name


def test_duty_cycle_is_palmgren_miner():
    loads = np.array([[1000.0, 0, 0, 0, 0], [2000.0, 0, 0, 0, 0], [500.0, 0, 0, 0, 0]])
    speeds = np.array([100.0, 300.0, 50.0])
    t = np.array([0.2, 0.5, 0.3])
    d = life.duty_cycle_life(B6205, loads, speeds, t, kinematic_viscosity=30e-6)
    lives = d.steps.basic_rating_life
    u = t * speeds / np.sum(t * speeds)
    assert d.basic_rating_life == pytest.approx(1 / np.sum(u / lives), rel=1e-14)
    assert d.mean_speed == pytest.approx(np.sum(t * speeds))
    # one step run all the time gives that step's life
    one = life.duty_cycle_life(B6205, loads, speeds, [0.0, 1.0, 0.0], kinematic_viscosity=30e-6)
    assert one.basic_rating_life == pytest.approx(lives[1], rel=1e-14)
    with pytest.raises(InputError, match="time_shares must sum to 1"):
        life.duty_cycle_life(B6205, loads, speeds, [0.2, 0.2, 0.2], kinematic_viscosity=30e-6)


def test_benchmark_paths_agree_on_a_small_input(load_bench):
    bench = load_bench("life")
    from bearinglab import catalog

    bearing = catalog.get("6205-2RS")
    loads, speeds = bench.cases(200, seed=3)
    assert_allclose(bench.batched(bearing, loads, speeds), bench.baseline(bearing, loads, speeds), rtol=1e-12)


# ----------------------------------------------------------------------------- issue 20: no lubricant; nu1 at d_m
B6205_DM = BallBearing(9, 7.94e-3, 39.04e-3, 0.52, 0.53, contact_angle=0.0, type="radial", designation="6205",
                       bore=25e-3, outside_diameter=52e-3)


def test_without_lubricant_the_lubrication_results_are_none():
    loads = [[2000.0, 0, 0, 0, 0], [1000.0, 0, 300.0, 0, 0]]
    bare = _quiet(B6205_DM, loads, N)
    oiled = _quiet(B6205_DM, loads, N, kinematic_viscosity=20e-6)
    for name in ("viscosity_ratio", "life_modification_factor", "modified_rating_life",
                 "modified_rating_life_duration", "modified_reference_rating_life", "kinematic_viscosity"):
        assert getattr(bare, name) is None, name
        assert getattr(oiled, name) is not None, name
    # what does not need the lubricant is the same
    for name in ("equivalent_dynamic_load", "basic_rating_life", "basic_rating_life_duration",
                 "reference_rating_life", "static_safety_factor", "rated_viscosity"):
        np.testing.assert_array_equal(getattr(bare, name), getattr(oiled, name), err_msg=name)
    assert np.all(np.isfinite(bare.reference_rating_life)) and np.all(bare.basic_rating_life > 0)
    # L10 = (C/P)^3 10^6 for the pure radial case, by hand
    assert bare.basic_rating_life[0] == pytest.approx((bare.dynamic_load_rating / 2000.0) ** 3 * 1e6, rel=1e-14)


def test_duty_cycle_without_lubricant():
    with pytest.warns(ratings.RatingWarning, match="no load distribution"):
        d = life.duty_cycle_life(B6205_DM, [[1000.0, 0, 0, 0, 0], [2000.0, 0, 0, 0, 0]], [300.0, 300.0],
                                    [0.5, 0.5], load_distribution=False)
    assert d.modified_rating_life is None and d.modified_reference_rating_life is None
    assert d.basic_rating_life > 0


def test_rated_viscosity_uses_the_mean_diameter_where_bore_and_outside_diameter_are_known():
    # ISO 281 eq. (15) (n >= 1000 rpm): nu1 = 4500 n^-0.5 d_m^-0.5 mm^2/s, d_m = (25 + 52)/2 = 38.5 mm
    nu1 = 4500.0 * 3000.0**-0.5 * 38.5**-0.5 * 1e-6
    r = _quiet(B6205_DM, [1000.0, 0, 0, 0, 0], N, kinematic_viscosity=20e-6, load_distribution=False)
    assert r.rated_viscosity == pytest.approx(nu1, rel=1e-13)
    assert r.viscosity_ratio == pytest.approx(20e-6 / nu1, rel=1e-13)
    assert r.rated_viscosity_diameter == pytest.approx(38.5e-3, rel=1e-15)
    assert r.rated_viscosity_diameter_source == "mean diameter (d + D)/2"
    # the pitch diameter (39.04 mm), used before issue 20, made kappa sqrt(39.04/38.5) - 1 = 0.70 % high
    p = _quiet(B6205, [1000.0, 0, 0, 0, 0], N, kinematic_viscosity=20e-6, load_distribution=False)
    assert p.rated_viscosity_diameter_source == "pitch diameter"
    assert p.viscosity_ratio / r.viscosity_ratio == pytest.approx(math.sqrt(39.04 / 38.5), rel=1e-13)
    assert p.viscosity_ratio / r.viscosity_ratio - 1 == pytest.approx(0.0070, abs=5e-5)


def test_oil_grade_alone_in_the_api():
    # kinematic_viscosity=None with temperature and iso_vg: nu from VI 95 (DEFAULT_VISCOSITY_INDEX)
    r = _quiet(B6205_DM, [1000.0, 0, 0, 0, 0], N, temperature=343.15, iso_vg=68, load_distribution=False)
    nu = ratings.kinematic_viscosity(343.15, iso_vg=68, viscosity_index=95.0)
    assert r.kinematic_viscosity == pytest.approx(nu, rel=1e-14)

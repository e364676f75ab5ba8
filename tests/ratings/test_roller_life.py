"""The life analysis of a RollerBearing (bearinglab.life, roller branch)."""

import math
import warnings

import numpy as np
import pytest

from bearinglab import catalog, life
from bearinglab.ratings import RatingWarning
from bearinglab.ratings import roller as ro
from bearinglab.rollers import RollerBearing

N = 1500 * math.pi / 30


def quiet(*args, **kw):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return life.rating_life(*args, **kw)


def test_a_tapered_bearing_uses_its_catalogue_factors_and_the_roller_exponent():
    b = catalog.get("30208 J2/Q")
    r = quiet(b, [[8e3, 0, 1e3, 0, 0], [8e3, 0, 6e3, 0, 0]], N, kinematic_viscosity=30e-6, contamination=0.5)
    p = np.array([8e3, 0.4 * 8e3 + 1.6 * 6e3])  # Fa/Fr = 0.125 <= e = 0.37 -> P = Fr; 0.75 > e
    assert r.equivalent_dynamic_load == pytest.approx(p)
    assert r.basic_rating_life == pytest.approx(1e6 * (61.6e3 / p) ** (10 / 3), rel=1e-12)
    kappa = r.viscosity_ratio
    want = ro.roller_life_modification_factor(kappa, 0.5, 7.65e3, p)
    assert r.life_modification_factor == pytest.approx(want, rel=1e-12)
    assert r.static_safety_factor == pytest.approx(68e3 / np.maximum(8e3, 0.5 * 8e3 + 0.9 * np.array([1e3, 6e3])))
    assert np.isnan(r.reference_rating_life[0]) and r.reference_rating_life[1] > 0  # 1 kN < F_r tan(alpha)
    assert any("less thrust than F_r tan(alpha)" in w for w in r.warnings)


def test_the_reference_life_of_a_bearing_with_its_roller_set():
    b = RollerBearing("cylindrical", 14, 11e-3, 9.6e-3, 60.5e-3, dynamic_load_rating=62e3, static_load_rating=53e3,
                      bore=40e-3, outside_diameter=80e-3)
    r = life.rating_life(b, [10e3, 0, 0, 0, 0], N)
    # at zero clearance under a pure radial load, with ISO/TS 16281's profile, the laminae's reference life is
    # several times ISO 281's L10 (3.9 here: ISO/TS 16281 takes lambda nu = 0.83 out of the lamina ratings and
    # the slices share the load evenly; the exponent 4 on the laminae against 10/3 moves the ratio with the load)
    assert 2.5 < r.reference_rating_life / r.basic_rating_life < 5.0
    tilted = life.rating_life(b, [10e3, 0, 0, 0, 15.0], N)
    assert tilted.reference_rating_life < r.reference_rating_life  # edge loading costs life
    assert np.isnan(tilted.basic_rating_life)


def test_spherical_and_cylindrical_notes():
    with pytest.warns(RatingWarning, match="no ISO/TS 16281 reference life"):
        r = life.rating_life(catalog.get("22208 E"), [10e3, 0, 1e3, 0, 0], N)
    assert r.equivalent_dynamic_load == pytest.approx(10e3 + 2.4e3) and np.isnan(r.reference_rating_life)
    with pytest.warns(RatingWarning, match="carries no axial load on its raceways"):
        r = life.rating_life(catalog.get("NJ 208 ECP"), [10e3, 0, 1e3, 0, 0], N)
    assert r.equivalent_dynamic_load == 10e3


def test_duty_cycle_of_a_roller_bearing():
    b = catalog.get("NU 208 ECP")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        d = life.duty_cycle_life(b, [[5e3, 0, 0, 0, 0], [10e3, 0, 0, 0, 0]], [100.0, 200.0], [0.5, 0.5])
    l1, l2 = 1e6 * (62e3 / 5e3) ** (10 / 3), 1e6 * (62e3 / 10e3) ** (10 / 3)
    u = np.array([50.0, 100.0]) / 150.0
    assert d.basic_rating_life == pytest.approx(1 / (u[0] / l1 + u[1] / l2), rel=1e-12)

"""SKF's model of roller bearings (bearinglab.friction.skf_roller); the 22208 E example is in
tests/validation/test_roller_examples.py."""

import math

import numpy as np
import pytest

from bearinglab import catalog, friction
from bearinglab.errors import InputError

N = 3000 * math.pi / 30


def by_hand(kind, fr, fa, c, nu=20.0, n=3000.0, d=40.0, big=80.0, y=0.0, kz=5.1, mu_ehl=0.02, krs=6e-8):
    """The model in the catalogue's units, typed out again (N mm)."""
    dm = 0.5 * (d + big)
    if kind == "cylindrical":
        grr, gsl = c.r1 * dm**2.41 * fr**0.31, c.s1 * dm**0.9 * fa + c.s2 * dm * fr
    elif kind == "tapered":
        grr, gsl = c.r1 * dm**2.38 * (fr + c.r2 * y * fa) ** 0.31, c.s1 * dm**0.82 * (fr + c.s2 * y * fa)
    ish = 1 / (1 + 1.84e-9 * (n * dm) ** 1.28 * nu**0.64)
    rs = math.exp(-krs * nu * n * (d + big) * math.sqrt(kz / (2 * (big - d))))
    bl = math.exp(-2.6e-8 * (n * nu) ** 1.4 * dm)
    mu = bl * 0.15 + (1 - bl) * mu_ehl
    return ish * rs * grr * (nu * n) ** 0.6 + mu * gsl


def test_cylindrical_and_tapered_by_hand():
    got = friction.skf_roller(5000.0, 300.0, N, 20e-6, 40e-3, 80e-3, series="2")
    c = friction.CYLINDRICAL_CONSTANTS["2"]
    assert got.total_moment * 1e3 == pytest.approx(by_hand("cylindrical", 5000, 300, c), rel=1e-12)
    got = friction.skf_roller(5000.0, 2000.0, N, 20e-6, 40e-3, 80e-3, bearing_type="tapered", series="302",
                              axial_factor=1.6)
    c = friction.TAPERED_CONSTANTS["302"]
    assert got.total_moment * 1e3 == pytest.approx(by_hand("tapered", 5000, 2000, c, y=1.6, kz=6.0, mu_ehl=0.002),
                                                   rel=1e-12)


def test_the_constants_of_the_tables():
    assert friction.roller_series_constants("cylindrical", "22") == friction.RollerConstants(1.40e-6, s1=0.16, s2=0.0015)
    assert friction.roller_series_constants("tapered", "330").r2 == 11.3
    assert friction.roller_series_constants("spherical", "241").s2 == 86.7
    assert friction.ROLLER_TYPE_CONSTANTS["tapered"] == (6.0, 0.7)
    with pytest.raises(InputError, match="^series must be one of"):
        friction.roller_series_constants("cylindrical", "62")


def test_spherical_takes_the_smaller_variables():
    # light load: the e-branch (0.54 power) is smaller; heavy load: the l-branch (0.31 power)
    c = friction.SPHERICAL_CONSTANTS["222 E"]
    for fr in (500.0, 3e5):
        m = friction.skf_roller(fr, 0.0, N, 20e-6, 40e-3, 80e-3, bearing_type="spherical", series="222 E",
                                sliding_friction_coefficient=0.05, lubrication="oil-jet")
        grr = min(c.r1 * 60**1.85 * fr**0.54, c.r3 * 60**2.3 * fr**0.31)
        gsl = min(c.s1 * 60**0.25 * fr ** (4 / 3), c.s3 * 60**0.94 * fr)
        ish = 1 / (1 + 1.84e-9 * (3000 * 60) ** 1.28 * 20**0.64)
        rs = math.exp(-3e-8 * 20 * 3000 * 120 * math.sqrt(5.5 / 80))
        assert m.total_moment * 1e3 == pytest.approx(ish * rs * grr * (20 * 3000) ** 0.6 + 0.05 * gsl, rel=1e-12)


def test_for_a_bearing_and_the_oil_bath():
    b = catalog.get("30208 J2/Q")
    via = friction.skf_roller_for_bearing(b, 5000.0, 1000.0, N, 20e-6, lubrication="oil-bath", drag_loss_factor=1e-4)
    direct = friction.skf_roller(5000.0, 1000.0, N, 20e-6, 40e-3, 80e-3, bearing_type="tapered", series="302",
                                 axial_factor=1.6, lubrication="oil-bath", width=18e-3, drag_loss_factor=1e-4)
    assert via.total_moment == direct.total_moment
    assert via.drag_moment == pytest.approx(10 * 1e-4 * 0.7 * 6 * 120 / 40 * 1e-12 * 18 * 60**4 * 3000**2 * 1e-3)
    with pytest.raises(InputError, match="^oil_level: an oil bath needs the oil level H"):  # V_M now follows from H
        friction.skf_roller(5000.0, 0.0, N, 20e-6, 40e-3, 80e-3, series="2", lubrication="oil-bath")
    m = friction.skf_roller_for_bearing(catalog.get("22208 E"), np.array([1e3, 2e3]), 0.0, N, 20e-6)
    assert m.total_moment.shape == (2,) and np.all(np.diff(m.total_moment) > 0)

"""The EHL film of one contact (bearinglab.film.ehl) against an independent re-implementation of the
published formulas in plain ``math``, its scaling laws, limits and errors.

The re-implementation below is written from the papers (Hamrock and Dowson 1977 for H_c and H_min;
Hamrock, Schmid and Jacobson 2004 ch. 24 for R_x, R_y; the Hertz ellipticity from the elliptic
integrals by its own bisection with scipy's K, E), not from the library.
"""

import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from scipy.special import ellipe, ellipk

from bearinglab.errors import InputError, ValidityWarning
from bearinglab.film import ehl


def _k_exact(rx, ry):
    """k = a/b from F = (1/Rx - 1/Ry)/(1/Rx + 1/Ry) by bisection on the Hertz relation in k."""
    f = (1 / rx - 1 / ry) / (1 / rx + 1 / ry)
    lo, hi = 1.0 + 1e-12, 100.0
    for _ in range(200):
        k = 0.5 * (lo + hi)
        m = 1 - 1 / k**2
        g = ((k**2 + 1) * ellipe(m) - 2 * ellipk(m)) / ((k**2 - 1) * ellipe(m))
        lo, hi = (k, hi) if g < f else (lo, k)
    return 0.5 * (lo + hi)


def _films(q, u, rx, k, eta, alpha, ep):
    big_u, g, w = eta * u / (ep * rx), alpha * ep, q / (ep * rx * rx)
    hc = 2.69 * big_u**0.67 * g**0.53 * w**-0.067 * (1 - 0.61 * math.exp(-0.73 * k)) * rx
    hm = 3.63 * big_u**0.68 * g**0.49 * w**-0.073 * (1 - math.exp(-0.68 * k)) * rx
    return hc, hm


# Hamrock's 209 deep-groove bearing (Hamrock, Schmid, Jacobson 2004, ch. 24, the ball-bearing problem;
# inputs only): D = 12.7 mm, inner- and outer-race diameters 52.291 and 77.706 mm (d_m = 64.9985 mm),
# groove radii 6.604 mm (f = 0.52), E = 200 GPa, nu = 0.3, alpha = 2.3e-8 m^2/N, omega_i = 400 rad/s.
D, DM, F = 12.7e-3, 0.5 * (52.291e-3 + 77.706e-3), 6.604 / 12.7
EP = 200e9 / (1 - 0.3**2)


@pytest.mark.parametrize("race, sign", [("inner", -1), ("outer", 1)])
def test_radii_ellipticity_and_films_of_the_209_bearing_match_an_independent_implementation(race, sign):
    rx_ref = D * (DM + sign * D) / (2 * DM)
    ry_ref = F * D / (2 * F - 1)
    radii = ehl.contact_radii(D, DM, F, 0.0, race=race)
    assert radii.rx == pytest.approx(rx_ref, rel=1e-14)
    assert radii.ry == pytest.approx(ry_ref, rel=1e-14)
    k_ref = _k_exact(rx_ref, ry_ref)
    k = ehl.ellipticity(radii.rx, radii.ry)
    assert k == pytest.approx(k_ref, rel=1e-9)
    # Hamrock and Brewe's approximation k = 1.0339 (Ry/Rx)^0.636 is 1.5 % above the exact value here
    assert k == pytest.approx(1.0339 * (ry_ref / rx_ref) ** 0.636, rel=0.02)
    u = 400.0 * (DM**2 - D**2) / (4 * DM)
    with pytest.warns(ValidityWarning, match="k <= 8") if k > 8 else _nothing():
        got = ehl.hamrock_dowson(2000.0, u, radii.rx, k, 0.04, 2.3e-8, EP)
    hc, hm = _films(2000.0, u, rx_ref, k_ref, 0.04, 2.3e-8, EP)
    assert got.central == pytest.approx(hc, rel=1e-9)
    assert got.minimum == pytest.approx(hm, rel=1e-9)


class _nothing:
    def __enter__(self):
        return self

    def __exit__(self, *exc):
        return False


@given(q=st.floats(1.0, 1e5), u=st.floats(0.01, 100.0), k=st.floats(1.0, 8.0), s=st.floats(1.1, 10.0))
def test_films_follow_the_exponents_of_the_fit(q, u, k, s):
    rx, eta, alpha = 5e-3, 0.02, 2e-8
    base = ehl.hamrock_dowson(q, u, rx, k, eta, alpha, 2.2e11)
    faster = ehl.hamrock_dowson(q, u * s, rx, k, eta, alpha, 2.2e11)
    heavier = ehl.hamrock_dowson(q * s, u, rx, k, eta, alpha, 2.2e11)
    assert faster.minimum / base.minimum == pytest.approx(s**0.68, rel=1e-11)
    assert faster.central / base.central == pytest.approx(s**0.67, rel=1e-11)
    assert heavier.minimum / base.minimum == pytest.approx(s**-0.073, rel=1e-11)
    assert heavier.central / base.central == pytest.approx(s**-0.067, rel=1e-11)
    # viscosity enters through U only: the same as speed
    thicker = ehl.hamrock_dowson(q, u, rx, k, eta * s, alpha, 2.2e11)
    assert thicker.minimum == pytest.approx(faster.minimum, rel=1e-12)


def test_scalar_and_array_agree_and_unloaded_contact_is_refused():
    # issue 29: Q = 0 gave NaN; the fit has no limit there, so an unloaded contact is an InputError (the
    # film analysis leaves unloaded balls out, tests/film/test_film_analysis.py)
    with pytest.raises(InputError, match=r"load must be > 0 \[N\], got 0.0"):
        ehl.hamrock_dowson(np.array([0.0, 100.0, 1000.0]), 5.0, 5e-3, 6.0, 0.02, 2e-8, 2.2e11)
    with pytest.raises(InputError, match=r"load must be > 0 \[N\], got 0.0"):
        ehl.hamrock_dowson(0.0, 5.0, 5e-3, 6.0, 0.02, 2e-8, 2.2e11)
    q = np.array([100.0, 1000.0])
    got = ehl.hamrock_dowson(q, 5.0, 5e-3, 6.0, 0.02, 2e-8, 2.2e11)
    one = ehl.hamrock_dowson(1000.0, 5.0, 5e-3, 6.0, 0.02, 2e-8, 2.2e11)
    assert got.minimum[1] == one.minimum and np.ndim(one.minimum) == 0
    assert ehl.hamrock_dowson(1000.0, 0.0, 5e-3, 6.0, 0.02, 2e-8, 2.2e11).minimum == 0.0


def test_film_parameter_and_regime_thresholds():
    lam = ehl.film_parameter(0.3e-6, 0.0625e-6, 0.175e-6)
    assert lam == pytest.approx(0.3 / math.hypot(0.0625, 0.175), rel=1e-14)
    assert ehl.lubrication_regime([0.999, 1.0, 2.999, 3.0, np.nan]).tolist() == [
        "boundary", "mixed", "mixed", "full film", ""]
    assert ehl.lubrication_regime(5.0) == "full film"
    with pytest.raises(InputError, match="not both be 0"):
        ehl.film_parameter(1e-6, 0.0, 0.0)
    with pytest.raises(InputError, match="roughness_ball must be >= 0"):
        ehl.film_parameter(1e-6, -1e-7, 1e-7)


def test_thermal_factor_by_hand_and_limits():
    # L = beta eta u^2 / K = 0.03 * 0.01 * 400 / 0.14
    ell = 0.03 * 0.01 * 20.0**2 / 0.14
    ref = (1 - 13.2 * (2e9 / 2.3e11) * ell**0.42) / (1 + 0.213 * ell**0.64)
    assert ehl.thermal_reduction_factor(20.0, 0.01, 0.03, 0.14, 2e9, 2.3e11) == pytest.approx(ref, rel=1e-14)
    assert ehl.thermal_reduction_factor(0.0, 0.01, 0.03, 0.14, 2e9, 2.3e11) == 1.0  # no shear, no heating
    slid = ehl.thermal_reduction_factor(20.0, 0.01, 0.03, 0.14, 2e9, 2.3e11, slide_roll_ratio=0.5)
    assert slid < ref  # sliding heats the inlet more


def test_pressure_viscosity_estimate_and_its_range():
    assert ehl.pressure_viscosity_coefficient(0.1) == pytest.approx((0.6 + 0.965 * 2.0) * 1e-8, rel=1e-14)
    with pytest.raises(InputError, match="dynamic_viscosity must be >= 1 mPa s"):
        ehl.pressure_viscosity_coefficient(5e-4)


@pytest.mark.parametrize("call, match", [
    (lambda: ehl.hamrock_dowson(1.0, 1.0, 5e-3, 0.5, 0.02, 2e-8, 2.2e11), "ellipticity must be >= 1"),
    (lambda: ehl.hamrock_dowson(1.0, 1.0, 5e-3, 2.0, -0.02, 2e-8, 2.2e11), "dynamic_viscosity must be > 0"),
    (lambda: ehl.hamrock_dowson(1.0, 1.0, 5e-3, 2.0, 0.02, 0.0, 2.2e11), "pressure_viscosity_coefficient must"),
    (lambda: ehl.hamrock_dowson(-1.0, 1.0, 5e-3, 2.0, 0.02, 2e-8, 2.2e11), "load must be >= 0"),
    (lambda: ehl.contact_radii(1e-2, 5e-2, 0.5, 0.0, race="inner"), "conformity must be > 0.5"),
    (lambda: ehl.contact_radii(1e-2, 5e-2, 0.52, 0.0, race="middle"), "race must be one of"),
    (lambda: ehl.ellipticity(2e-3, 1e-3), "ry must be >= rx"),
])
def test_bad_inputs_raise(call, match):
    with pytest.raises(InputError, match=match):
        call()

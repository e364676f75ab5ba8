"""Tests written for the survivors of the seventh mutation run (TESTING.md) on bearinglab.film.ehl: the
parameter names and units of the input checks, the sliding term and the clip of Gupta's inlet heating
factor, and the lower limit of Wooster's pressure-viscosity estimate.

The references are the printed formulas (Gupta et al. 1992 as quoted by Harris and Kotzalas; Wooster's
alpha = (0.6 + 0.965 log10 eta[cP]) 1e-8 m^2/N of Stachowiak and Batchelor), evaluated here in ``math``.
"""

import math
import re

import pytest
from hypothesis import given
from hypothesis import strategies as st

from bearinglab.errors import InputError, ValidityWarning
from bearinglab.film import ehl

# the arguments of thermal_reduction_factor in order, all valid
_TRF = {"entrainment_velocity": 20.0, "dynamic_viscosity": 0.01, "temperature_viscosity_coefficient": 0.03,
            "thermal_conductivity": 0.14, "max_pressure": 2e9, "reduced_modulus": 2.3e11}


def _gupta(u, eta, beta, k, p, ep, s):
    ell = beta * eta * u**2 / k
    return (1 - 13.2 * (p / ep) * ell**0.42) / (1 + 0.213 * (1 + 2.23 * s**0.83) * ell**0.64)


@pytest.mark.parametrize("name, rule, unit", [
    ("entrainment_velocity", ">= 0", "m/s"),
    ("dynamic_viscosity", "> 0", "Pa s"),
    ("temperature_viscosity_coefficient", "> 0", "1/K"),
    ("thermal_conductivity", "> 0", "W/(m K)"),
    ("max_pressure", ">= 0", "Pa"),
    ("reduced_modulus", "> 0", "Pa"),
    ("slide_roll_ratio", ">= 0", "-"),
])
def test_thermal_factor_checks_name_the_parameter_and_its_unit(name, rule, unit):
    kw = dict(_TRF, slide_roll_ratio=0.0)
    kw[name] = -1.0
    with pytest.raises(InputError, match="^" + re.escape(f"{name} must be {rule} [{unit}], got -1.0")):
        ehl.thermal_reduction_factor(**kw)


def test_pressure_viscosity_check_names_its_unit():
    with pytest.raises(InputError, match=r"^dynamic_viscosity must be > 0 \[Pa s\], got -1.0"):
        ehl.pressure_viscosity_coefficient(-1.0)


def test_pressure_viscosity_estimate_holds_down_to_one_centipoise():
    # 1 mPa s is the bottom of the estimate's range, not below it: log10(1 cP) = 0, alpha = 0.6e-8 m^2/N
    assert ehl.pressure_viscosity_coefficient(1e-3) == pytest.approx(0.6e-8, rel=1e-14)


@pytest.mark.parametrize("s", [0.1, 0.5, 2.0])
def test_sliding_term_of_the_thermal_factor_by_hand(s):
    # s = 1 would hide the exponent 0.83 (1**0.83 = 1); these ratios do not
    ref = _gupta(20.0, 0.01, 0.03, 0.14, 2e9, 2.3e11, s)
    assert 0 < ref < 1
    assert ehl.thermal_reduction_factor(**_TRF, slide_roll_ratio=s) == pytest.approx(ref, rel=1e-14)


def test_thermal_factor_is_clipped_at_zero_where_the_fit_goes_negative():
    # a heavy, fast, viscous contact: 13.2 (p/E') L^0.42 > 1, the formula's numerator is negative
    kw = {"entrainment_velocity": 100.0, "dynamic_viscosity": 0.1, "temperature_viscosity_coefficient": 0.03,
              "thermal_conductivity": 0.14, "max_pressure": 5e9, "reduced_modulus": 2.3e11}
    assert _gupta(100.0, 0.1, 0.03, 0.14, 5e9, 2.3e11, 0.0) < 0
    assert ehl.thermal_reduction_factor(**kw) == 0.0


@given(u=st.floats(0.0, 200.0), eta=st.floats(1e-4, 1.0), p=st.floats(0.0, 5e9), s=st.floats(0.0, 2.0))
def test_thermal_factor_stays_in_zero_one(u, eta, p, s):
    phi = ehl.thermal_reduction_factor(u, eta, 0.03, 0.14, p, 2.3e11, slide_roll_ratio=s)
    ref = _gupta(u, eta, 0.03, 0.14, p, 2.3e11, s)
    assert 0.0 <= phi <= 1.0
    assert phi == pytest.approx(min(max(ref, 0.0), 1.0), rel=1e-12, abs=1e-15)
    assert math.isfinite(phi)


@pytest.mark.parametrize("call, name", [
    (lambda: ehl.contact_radii(-1.0, 0.065, 0.52, 0.0, race="inner"), "ball_diameter"),
    (lambda: ehl.contact_radii(0.0127, -1.0, 0.52, 0.0, race="inner"), "pitch_diameter"),
    (lambda: ehl.ellipticity(-1.0, 0.1), "rx"),
    (lambda: ehl.ellipticity(0.005, -1.0), "ry"),
])
def test_geometry_checks_name_the_parameter_in_metres(call, name):
    with pytest.raises(InputError, match="^" + re.escape(f"{name} must be > 0 [m], got -1.0")):
        call()


def test_equal_radii_are_a_circular_contact_and_ry_below_rx_is_refused():
    # R_y = R_x (equal principal curvature sums): F = 0, the contact is a circle, k = 1
    assert ehl.ellipticity(0.005, 0.005) == pytest.approx(1.0, abs=1e-9)
    with pytest.raises(InputError, match=r"^ry must be >= rx \[m\] \(the x axis is the rolling direction"):
        ehl.ellipticity(0.005, 0.004)


@pytest.mark.parametrize("name, rule, unit", [
    ("load", ">= 0", "N"), ("entrainment_velocity", ">= 0", "m/s"), ("rx", "> 0", "m"),
    ("dynamic_viscosity", "> 0", "Pa s"), ("pressure_viscosity_coefficient", "> 0", "1/Pa"),
    ("reduced_modulus", "> 0", "Pa"),
])
def test_dimensionless_group_checks_name_the_parameter_and_its_unit(name, rule, unit):
    kw = {"load": 1000.0, "entrainment_velocity": 10.0, "rx": 5e-3, "dynamic_viscosity": 0.04,
          "pressure_viscosity_coefficient": 2.3e-8, "reduced_modulus": 2.2e11}
    kw[name] = -1.0
    with pytest.raises(InputError, match="^" + re.escape(f"{name} must be {rule} [{unit}], got -1.0")):
        ehl.dimensionless_groups(**kw)
    with pytest.raises(InputError, match="^" + re.escape(f"{name} must be {rule} [{unit}], got -1.0")):
        ehl.hamrock_dowson(ellipticity=2.0, **kw)


def test_ellipticity_and_conformity_checks_name_their_unit():
    with pytest.raises(InputError, match=r"^ellipticity must be > 0 \[-\], got -1.0"):
        ehl.hamrock_dowson(1000.0, 10.0, 5e-3, -1.0, 0.04, 2.3e-8, 2.2e11)
    with pytest.raises(InputError, match=r"^conformity must be > 0 \[-\], got -1.0"):
        ehl.contact_radii(0.0127, 0.065, -1.0, 0.0, race="inner")


@pytest.mark.parametrize("dm", [0.0127, 0.010])
def test_pitch_diameter_not_above_the_ball_is_refused(dm):
    with pytest.raises(InputError, match=r"^pitch_diameter must be > ball_diameter \[m\]$"):
        ehl.contact_radii(0.0127, dm, 0.52, 0.0, race="inner")


@pytest.mark.parametrize("race, sign", [("inner", -1), ("outer", 1)])
def test_radius_along_rolling_with_a_contact_angle(race, sign):
    # Hamrock et al. ch. 24: R_x = D (d_m -/+ D cos alpha) / (2 d_m), here at alpha = 40 deg
    d, dm, a = 12.7e-3, 65e-3, math.radians(40.0)
    ref = d * (dm + sign * d * math.cos(a)) / (2 * dm)
    assert ehl.contact_radii(d, dm, 0.52, a, race=race).rx == pytest.approx(ref, rel=1e-14)


@pytest.mark.parametrize("name, args", [
    ("roughness_ball", (1e-6, -1.0, 1e-7)), ("roughness_race", (1e-6, 1e-7, -1.0)),
])
def test_roughness_checks_name_the_parameter_in_metres(name, args):
    with pytest.raises(InputError, match="^" + re.escape(f"{name} must be >= 0 [m], got -1.0")):
        ehl.film_parameter(*args)


def test_zero_roughness_message_is_worded():
    with pytest.raises(InputError, match=r"^roughness_ball and roughness_race must not both be 0 \[m\] "
                                         r"\(Lambda would be infinite\)$"):
        ehl.film_parameter(1e-6, 0.0, 0.0)


def test_ellipticity_eight_is_inside_the_fit_and_the_warning_points_at_the_caller():
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("error")
        ehl.hamrock_dowson(1000.0, 10.0, 5e-3, 8.0, 0.04, 2.3e-8, 2.2e11)  # k = 8 is the fit's own bound
    with pytest.warns(ValidityWarning, match=r"ellipticity k = 9 is beyond the k <= 8") as rec:
        ehl.hamrock_dowson(1000.0, 10.0, 5e-3, 9.0, 0.04, 2.3e-8, 2.2e11)
    # stacklevel=2: the caller's line, not ehl.py (the caller's file is not asserted: a mutation tool's
    # trampoline can stand between the test and the function)
    assert not rec[0].filename.replace("\\", "/").endswith("film/ehl.py")


def test_scalar_regime_is_a_plain_str():
    assert type(ehl.lubrication_regime(2.0)) is str
    assert type(ehl.lubrication_regime(float("nan"))) is str

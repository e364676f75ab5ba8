"""ISO 76 static load rating, ISO 281 fatigue load limit, P0 and s0."""

import csv
import math
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from numpy.testing import assert_allclose

from bearinglab import ratings
from bearinglab.errors import InputError

ROWS = list(csv.DictReader(line for line in (Path(__file__).resolve().parent.parent / "data" / "iso76_f0.csv")
                           .read_text(encoding="utf-8").splitlines() if not line.startswith("#")))


@pytest.mark.parametrize("row", ROWS, ids=[r["gamma"] for r in ROWS])
def test_f0_reproduces_iso76_table(row):
    gamma = float(row["gamma"])
    dw = 10e-3
    dpw = dw / gamma if gamma > 0 else 1e3  # gamma = 0: an (almost) infinite pitch circle
    # the table prints one decimal: half a unit of it
    assert ratings.static_load_factor(dw, dpw) == pytest.approx(float(row["f0"]), abs=0.05)


def test_static_load_rating_is_f0_i_z_dw2_cos_alpha():
    alpha = math.radians(25)
    f0 = ratings.static_load_factor(8e-3, 45e-3, alpha)
    c0 = ratings.static_load_rating(12, 8e-3, 45e-3, alpha, n_rows=2)
    assert c0 == pytest.approx(f0 * 1e6 * 2 * 12 * 8e-3**2 * math.cos(alpha), rel=1e-14)


def test_fatigue_load_limit_precise_is_c0_times_the_stress_ratio_cubed():
    # same contact, 1500 instead of 4200 MPa: Cu / C0 = (1500/4200)^3 = 1/21.95 (Dpw <= 100 mm)
    c0 = ratings.static_load_rating(9, 7.94e-3, 39.04e-3)
    cu = ratings.fatigue_load_limit(9, 7.94e-3, 39.04e-3)
    assert cu == pytest.approx(c0 * (1500 / 4200) ** 3, rel=1e-12)
    assert cu == pytest.approx(ratings.fatigue_load_limit_simplified(c0, 39.04e-3), rel=3e-3)  # 22 vs 21.95


def test_fatigue_load_limit_size_factor_above_100_mm():
    assert ratings.fatigue_load_limit_simplified(22000.0, 0.4) == pytest.approx(1000.0 * 0.5, rel=1e-14)
    big = ratings.fatigue_load_limit(16, 22.23e-3, 0.16)
    c0 = ratings.static_load_rating(16, 22.23e-3, 0.16)
    assert big == pytest.approx(c0 * (1500 / 4200) ** 3 * math.sqrt(0.1 / 0.16), rel=1e-12)


def test_static_equivalent_load_iso76():
    assert ratings.static_equivalent_load(1000.0, 100.0) == 1000.0  # Fr governs
    assert ratings.static_equivalent_load(1000.0, 1000.0) == pytest.approx(1100.0)
    p0 = ratings.static_equivalent_load(1000.0, 2000.0, math.radians(40), bearing_type="angular")
    assert p0 == pytest.approx(0.5 * 1000 + 0.26 * 2000)
    assert ratings.static_load_factors(math.radians(22.5), bearing_type="angular").axial_factor == pytest.approx(0.40)
    with pytest.raises(InputError, match=r"contact_angle must be in \[15, 45\]"):
        ratings.static_load_factors(math.radians(10), bearing_type="angular")
    with pytest.raises(InputError, match="bearing_type"):
        ratings.static_load_factors(0.0, bearing_type="thrust")


def test_static_safety_factor_warns_below_minimum():
    assert ratings.static_safety_factor(7800.0, 0.0) == math.inf
    with pytest.warns(ratings.RatingWarning, match="below 1"):
        assert ratings.static_safety_factor(7800.0, 15600.0) == pytest.approx(0.5)


@given(gamma=st.floats(0.02, 0.4), alpha=st.floats(0.0, 0.7))
def test_c0_scales_with_cos_alpha_at_fixed_gamma(gamma, alpha):
    # f0 depends on gamma only; C0 then carries cos(alpha) once
    dw = 10e-3
    dpw = dw * math.cos(alpha) / gamma
    f0 = ratings.static_load_factor(dw, dpw, alpha)
    assert f0 == pytest.approx(ratings.static_load_factor(dw, dw / gamma, 0.0), rel=1e-12)


def test_vectorized_matches_scalar():
    dpw = np.linspace(30e-3, 60e-3, 7)
    assert_allclose(ratings.static_load_rating(9, 7.94e-3, dpw),
                    [ratings.static_load_rating(9, 7.94e-3, x) for x in dpw], rtol=1e-14)


def test_an_angle_outside_iso76_table_1_names_it_without_float_noise_and_says_what_to_do():
    with pytest.raises(InputError) as error:
        ratings.static_equivalent_load(1000.0, 100.0, math.radians(12.0), bearing_type="angular")
    message = str(error.value)
    assert message.startswith("contact_angle must be in [15, 45] [deg] for ISO 76 table 1 (angular contact), "
                              "got 12 deg: angles below 15 deg are not tabulated here;")
    assert "maker's X0 and Y0" in message and "0000" not in message

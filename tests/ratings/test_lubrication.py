"""Viscosity (ISO VG, ASTM D341), nu1, kappa, e_C and a_ISO of ISO 281."""

import math
import warnings

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from bearinglab import ratings
from bearinglab.errors import InputError

RPM = 2 * math.pi / 60


def _a_iso_by_hand(kappa, ec_cu_p):
    """ISO 281:2007 eq. (B.4), ball bearings, written out for 0.1 <= kappa <= 4 (no cap)."""
    c, p = (2.2649, 0.054381) if kappa < 0.4 else (1.9987, 0.19087) if kappa < 1 else (1.9987, 0.071739)
    return 0.1 * (1 - (2.5671 - c / kappa**p) ** 0.83 * ec_cu_p ** (1 / 3)) ** -9.3


def test_rated_viscosity_both_branches():
    # ISO 281 eqs. (14)-(15) by hand: 500 rpm and 3000 rpm at d_m = 50 mm
    assert ratings.rated_viscosity(500 * RPM, 0.05) * 1e6 == pytest.approx(45000 * 500**-0.83 * 50**-0.5, rel=1e-12)
    assert ratings.rated_viscosity(3000 * RPM, 0.05) * 1e6 == pytest.approx(4500 * 3000**-0.5 * 50**-0.5, rel=1e-12)


@pytest.mark.parametrize(("kappa", "ratio"), [(0.2, 0.05), (0.6, 0.1), (1.0, 0.05), (3.0, 0.2)])
def test_a_iso_equation(kappa, ratio):
    assert ratings.life_modification_factor(kappa, ratio, 1000.0, 1000.0) == pytest.approx(
        _a_iso_by_hand(kappa, ratio), rel=1e-12)


def test_a_iso_cap_and_clamps():
    assert ratings.life_modification_factor(4.0, 1.0, 3000.0, 1000.0) == 50.0  # bracket <= 0
    assert ratings.life_modification_factor(10.0, 0.5, 500.0, 1000.0) == ratings.life_modification_factor(
        4.0, 0.5, 500.0, 1000.0)
    with pytest.warns(ratings.RatingWarning, match="below 0.1"):
        low = ratings.life_modification_factor(0.05, 0.5, 500.0, 1000.0)
    assert low == ratings.life_modification_factor(0.1, 0.5, 500.0, 1000.0)


def test_a_iso_ep_additive_rule():
    with pytest.warns(ratings.RatingWarning, match="EP-additive"):
        ep = ratings.life_modification_factor(0.5, 0.8, 2000.0, 1000.0, ep_additives=True)
    assert ep == 3.0  # kappa = 1 would give more; the rule limits it to 3
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        # e_C < 0.2: the rule does not apply
        assert ratings.life_modification_factor(0.5, 0.1, 100.0, 1000.0, ep_additives=True) == pytest.approx(
            _a_iso_by_hand(0.5, 0.01), rel=1e-12)


@given(k1=st.floats(0.1, 4.0), k2=st.floats(0.1, 4.0), ec=st.floats(0.0, 1.0), load_ratio=st.floats(0.01, 2.0))
def test_a_iso_monotone_in_kappa(k1, k2, ec, load_ratio):
    lo, hi = sorted((k1, k2))
    a_lo = ratings.life_modification_factor(lo, ec, load_ratio * 1000.0, 1000.0)
    a_hi = ratings.life_modification_factor(hi, ec, load_ratio * 1000.0, 1000.0)
    assert a_hi >= a_lo * (1 - 1e-12)
    assert 0.0 < a_lo <= 50.0


@given(e1=st.floats(0.0, 1.0), e2=st.floats(0.0, 1.0), kappa=st.floats(0.1, 4.0))
def test_a_iso_monotone_in_contamination_factor(e1, e2, kappa):
    lo, hi = sorted((e1, e2))
    assert ratings.life_modification_factor(kappa, hi, 300.0, 1000.0) >= ratings.life_modification_factor(
        kappa, lo, 300.0, 1000.0) * (1 - 1e-12)


def test_contamination_classes():
    assert ratings.contamination_factor("extreme cleanliness", 0.05) == 1.0
    assert ratings.contamination_factor("typical-contamination", 0.05) == pytest.approx(0.2)
    assert ratings.contamination_factor("typical_contamination", 0.15) == pytest.approx(0.3)
    assert ratings.contamination_factor("high_cleanliness", 0.05, bound="low") == 0.6
    with pytest.raises(InputError, match="cleanliness must be one of"):
        ratings.contamination_factor("dusty", 0.05)


@given(t1=st.floats(250.0, 350.0), dt=st.floats(10.0, 100.0), nu_hot=st.floats(2e-6, 50e-6),
       factor=st.floats(1.5, 30.0))
def test_walther_round_trip_through_reference_points(t1, dt, nu_hot, factor):
    a, b = ratings.walther_constants((t1, t1 + dt), (nu_hot * factor, nu_hot))
    assert ratings.walther_viscosity(t1, a, b) == pytest.approx(nu_hot * factor, rel=1e-9)
    assert ratings.walther_viscosity(t1 + dt, a, b) == pytest.approx(nu_hot, rel=1e-9)
    # between the points the viscosity lies between them (monotone in T)
    mid = ratings.walther_viscosity(t1 + dt / 2, a, b)
    assert nu_hot < mid < nu_hot * factor


def test_iso_vg_and_temperature():
    assert ratings.iso_vg_viscosity(68) == pytest.approx(68e-6)
    nu = ratings.kinematic_viscosity(np.array([313.15, 373.15]), iso_vg=68, viscosity_100=8.7e-6)
    np.testing.assert_allclose(nu, [68e-6, 8.7e-6], rtol=1e-9)
    with pytest.raises(InputError, match="iso_vg must be one of"):
        ratings.iso_vg_viscosity(70)
    with pytest.raises(InputError, match="viscosity_100 or viscosity_index, not both"):
        ratings.kinematic_viscosity(343.15, iso_vg=68, viscosity_100=8.7e-6, viscosity_index=95.0)
    with pytest.raises(InputError, match=">= 2"):
        ratings.walther_constants((313.15, 373.15), (10e-6, 1e-6))


def test_viscosity_ratio():
    nu1 = ratings.rated_viscosity(1500 * RPM, 0.04)
    assert ratings.viscosity_ratio(2 * nu1, 1500 * RPM, 0.04) == pytest.approx(2.0, rel=1e-14)


@pytest.mark.parametrize("kappa", [0.4, 1.0])
@pytest.mark.parametrize("ratio", [0.02, 0.1, 0.3])
def test_a_iso_is_continuous_where_its_branches_meet(kappa, ratio):
    # the three (c, p) pairs of eq. (B.4) are fitted pieces of one curve: they must meet at kappa = 0.4
    # and 1 to the digits printed (5 significant digits of c and p: a relative step below 1e-4). A wrong
    # digit (one public transcription prints p = 0.019087 for 0.4 <= kappa < 1) breaks this by ~20 %.
    below = ratings.life_modification_factor(kappa * (1 - 1e-12), 1.0, ratio, 1.0)
    above = ratings.life_modification_factor(kappa, 1.0, ratio, 1.0)
    assert above == pytest.approx(below, rel=1e-3)


# ---------------------------------------------------------------- ASTM D2270 (issue 20)
# The worked examples of ASTM D2270-10(2016) (nu40, nu100 in mm^2/s -> VI as the standard reports it, a whole
# number): procedure A (VI <= 100) and procedure B (VI > 100).
D2270_EXAMPLES = [(73.30, 8.86, 92), (22.83, 5.05, 156), (53.47, 7.80, 111), (73.50, 8.86, 92)]


@pytest.mark.parametrize("nu40, nu100, vi", D2270_EXAMPLES)
def test_viscosity_index_reproduces_the_standards_examples(nu40, nu100, vi):
    assert round(float(ratings.viscosity_index(nu40 * 1e-6, nu100 * 1e-6))) == vi


@pytest.mark.parametrize("nu40, nu100, vi", D2270_EXAMPLES)
def test_viscosity_100_from_index_inverts_the_standards_examples(nu40, nu100, vi):
    # the published VI is rounded to a whole number: its nu100 lies within the nu100 of VI +- 0.5, and
    # the printed nu100 (2 decimals) within 0.02 mm^2/s of the one solved at the whole VI
    lo, hi = (ratings.viscosity_100_from_index(nu40 * 1e-6, vi + d) * 1e6 for d in (-0.5, 0.5))
    assert lo <= nu100 <= hi + 0.005
    assert ratings.viscosity_100_from_index(nu40 * 1e-6, vi) * 1e6 == pytest.approx(nu100, abs=0.02)


def test_procedure_a_by_hand():
    # VG68 at nu100 = 8.0 mm^2/s: table 1 row 8.0 gives L = 100.0, H = 59.60 (read from the table, not the
    # code): VI = 100 (L - U)/(L - H) = 100 (100 - 68)/(100 - 59.6) = 79.2079...
    assert ratings.viscosity_index(68e-6, 8.0e-6) == pytest.approx(100 * 32 / 40.4, rel=1e-12)


def test_procedure_b_by_hand():
    # VG32 at nu100 = 6.0: row 6.0 gives H = 38.19 > U = 32, so procedure B:
    # N = (log H - log U)/log Y, VI = (10^N - 1)/0.00715 + 100
    n = (np.log10(38.19) - np.log10(32.0)) / np.log10(6.0)
    assert ratings.viscosity_index(32e-6, 6.0e-6) == pytest.approx((10**n - 1) / 0.00715 + 100, rel=1e-12)


def test_above_70_mm2s_uses_the_equations():
    # nu100 = 100 mm^2/s: L = 0.8353 Y^2 + 14.67 Y - 216, H = 0.1684 Y^2 + 11.85 Y - 97 (eqs. (3)-(4))
    y, u = 100.0, 5000.0
    lo, hi = 0.8353 * y**2 + 14.67 * y - 216, 0.1684 * y**2 + 11.85 * y - 97
    assert u > hi
    assert ratings.viscosity_index(u * 1e-6, y * 1e-6) == pytest.approx(100 * (lo - u) / (lo - hi), rel=1e-12)


@given(nu40=st.floats(10e-6, 3000e-6), vi=st.floats(0.0, 250.0))
def test_viscosity_100_from_index_round_trips(nu40, vi):
    try:
        nu100 = ratings.viscosity_100_from_index(nu40, vi)
    except InputError:  # a VI this low needs nu100 < 2 mm^2/s, outside the standard
        assert ratings.viscosity_index(nu40, 2e-6) > vi
        return
    assert 2e-6 <= nu100 < nu40
    assert ratings.viscosity_index(nu40, nu100) == pytest.approx(vi, abs=1e-7)


def test_viscosity_index_is_increasing_in_nu100():
    y = np.linspace(2.0, 60.0, 2000) * 1e-6
    assert np.all(np.diff(ratings.viscosity_index(70e-6, y[y < 69e-6])) > 0)


def test_default_viscosity_index_and_grade():
    # SKF's viscosity-temperature diagram is compiled for VI 95 (the default); VG68 at 40 degC is 68 mm^2/s
    # and at 100 degC the nu100 of VI 95, whatever path is taken
    assert ratings.DEFAULT_VISCOSITY_INDEX == 95.0
    nu100 = ratings.viscosity_100_from_index(68e-6, 95.0)
    nu = ratings.kinematic_viscosity(np.array([313.15, 373.15]), iso_vg=68)
    np.testing.assert_allclose(nu, [68e-6, nu100], rtol=1e-9)
    np.testing.assert_allclose(ratings.kinematic_viscosity(343.15, iso_vg=68, viscosity_index=95.0),
                               ratings.kinematic_viscosity(343.15, viscosity_40=68e-6, viscosity_100=nu100))


def test_viscosity_index_refusals():
    with pytest.raises(InputError, match="too low"):
        ratings.viscosity_100_from_index(10e-6, -200.0)  # nu100 = 2 gives VI -125
    with pytest.raises(InputError, match=">= 2"):
        ratings.viscosity_index(10e-6, 1.5e-6)
    with pytest.raises(InputError, match="below viscosity_40"):
        ratings.viscosity_index(10e-6, 12e-6)
    with pytest.raises(InputError, match="finite"):
        ratings.viscosity_100_from_index(68e-6, float("nan"))

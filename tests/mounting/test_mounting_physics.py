"""Lamé, thermal and centrifugal limits of the clearance chain, against closed forms written here.

Closed forms (each written independently of bearinglab.mounting):
- a solid shaft of the ring's steel: the inner raceway grows by delta * d / d_1 (issue 23);
- NSK, Rolling Bearings cat. E1102m, table 15.1 (one steel): expansion of the inner raceway on a hollow
  shaft Delta_Di = Delta_d k (1 - k0^2) / (1 - k^2 k0^2), k = d / D_i, k0 = d0 / d; the outer raceway in a
  housing of outside diameter D_0: Delta_De = Delta_D h (1 - h0^2) / (1 - h^2 h0^2), h = D_e / D,
  h0 = D / D_0; surface pressure p = (E / 2)(Delta_d / d)(1 - k^2)(1 - k0^2) / (1 - k^2 k0^2);
- one steel, balls at the mean ring temperature: the thermal loss is alpha (T_i - T_o) d_m;
- Timoshenko & Goodier, section 32: a free rotating ring grows at its bore by
  rho w^2 a / (4E) ((3 + nu) b^2 + (1 - nu) a^2) (radius), at its outside by
  rho w^2 b / (4E) ((3 + nu) a^2 + (1 - nu) b^2); a solid disc by (1 - nu) rho w^2 b^3 / (4E).
"""

import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from bearinglab.mounting import centrifugal, chain, lame, thermal
from bearinglab.mounting.materials import material

E, NU, RHO, ALPHA = 2.075e11, 0.3, 7850.0, 12.5e-6
STEEL = material("steel")
T0 = thermal.REFERENCE_TEMPERATURE

sizes = st.floats(0.01, 0.3)
ratios = st.floats(1.05, 1.6)


@given(d=sizes, r=ratios, delta_um=st.floats(0.5, 80.0))
def test_solid_shaft_same_steel_raceway_grows_by_delta_d_over_d1(d, r, delta_um):
    d1, delta = d * r, delta_um * 1e-6
    p = lame.fit_pressure_inner(delta, d, d1, 0.0, E, NU, E, NU)
    assert lame.inner_raceway_growth(p, d, d1, E) == pytest.approx(delta * d / d1, rel=1e-12)


@given(d=sizes, r=ratios, c0=st.floats(0.0, 0.9), delta_um=st.floats(0.5, 80.0))
def test_hollow_shaft_matches_nsk_table_15_1(d, r, c0, delta_um):
    di, d0, delta = d * r, c0 * d, delta_um * 1e-6
    k, k0 = d / di, d0 / d
    p_nsk = E / 2 * delta / d * (1 - k**2) * (1 - k0**2) / (1 - k**2 * k0**2)
    grow_nsk = delta * k * (1 - k0**2) / (1 - k**2 * k0**2)
    p = lame.fit_pressure_inner(delta, d, di, d0, E, NU, E, NU)
    assert p == pytest.approx(p_nsk, rel=1e-12)
    assert lame.inner_raceway_growth(p, d, di, E) == pytest.approx(grow_nsk, rel=1e-12)


@given(big=sizes, r=st.floats(0.65, 0.95), w=st.one_of(st.just(math.inf), st.floats(1.1, 3.0)),
       delta_um=st.floats(0.5, 80.0))
def test_housing_matches_nsk_table_15_1(big, r, w, delta_um):
    de, d0, delta = big * r, big * w, delta_um * 1e-6
    h, h0 = de / big, big / d0
    p_nsk = E / 2 * delta / big * (1 - h**2) * (1 - h0**2) / (1 - h**2 * h0**2)
    shrink_nsk = delta * h * (1 - h0**2) / (1 - h**2 * h0**2)
    p = lame.fit_pressure_outer(delta, big, de, d0, E, NU, E, NU)
    assert p == pytest.approx(p_nsk, rel=1e-12)
    assert lame.outer_raceway_shrink(p, big, de, E) == pytest.approx(shrink_nsk, rel=1e-12)


def test_clearance_fit_has_no_pressure():
    assert lame.fit_pressure_inner(-5e-6, 0.05, 0.06, 0.0, E, NU, E, NU) == 0.0
    assert lame.fit_pressure_outer(-5e-6, 0.09, 0.08, math.inf, E, NU, E, NU) == 0.0


def test_softer_shaft_takes_less_pressure_and_growth():
    alu = material("aluminium")
    steel = lame.fit_pressure_inner(20e-6, 0.05, 0.06, 0.0, E, NU, E, NU)
    soft = lame.fit_pressure_inner(20e-6, 0.05, 0.06, 0.0, E, NU, alu.elastic_modulus, alu.poisson_ratio)
    assert soft < steel


M = chain.Mounting(0.040, 0.080, 0.0479, 0.0721, 0.0121)  # a 6208-like ring set (d_m = 60 mm)


@given(ti=st.floats(-20.0, 120.0), to=st.floats(-20.0, 120.0))
def test_thermal_loss_one_steel_is_alpha_dT_dm(ti, to):
    """Shaft and housing follow their rings (defaults), so the fits do not change: only alpha dT d_m."""
    c = chain.Conditions(inner_temperature=T0 + ti, outer_temperature=T0 + to)
    r = chain.operating_clearance(20e-6, -5e-6, -5e-6, M, c)
    dm = 0.5 * (M.inner_raceway + M.outer_raceway)
    assert r.thermal_reduction == pytest.approx(ALPHA * (ti - to) * dm, abs=1e-15)
    assert r.fit_reduction == 0.0


def test_aluminium_housing_loosens_the_outer_fit_when_warm():
    m = chain.Mounting(0.040, 0.080, 0.0479, 0.0721, 0.0121, housing=material("aluminium"))
    c = chain.Conditions(inner_temperature=T0 + 60, outer_temperature=T0 + 60)
    r = chain.operating_clearance(20e-6, 0.0, 30e-6, m, c)
    expected = 30e-6 + (ALPHA - 23e-6) * 60 * 0.080  # the housing bore outgrows the ring
    assert r.outer_operating_interference == pytest.approx(expected, rel=1e-12)
    assert r.outer_operating_interference < 30e-6
    cold = chain.operating_clearance(20e-6, 0.0, 30e-6, m, chain.Conditions(T0 - 40, T0 - 40))
    assert cold.outer_operating_interference > 30e-6


@given(d=sizes, r=ratios, n=st.floats(100.0, 30000.0))
def test_rotating_ring_matches_timoshenko(d, r, n):
    w = n * math.pi / 30
    a, b = d / 2, d * r / 2
    bore = RHO * w**2 * a / (4 * E) * ((3 + NU) * b**2 + (1 - NU) * a**2)
    out = RHO * w**2 * b / (4 * E) * ((3 + NU) * a**2 + (1 - NU) * b**2)
    solid = (1 - NU) * RHO * w**2 * a**3 / (4 * E)
    assert centrifugal.disc_growth(w, 2 * a, 2 * b, 2 * a, RHO, E, NU) == pytest.approx(2 * bore, rel=1e-12)
    assert centrifugal.disc_growth(w, 2 * a, 2 * b, 2 * b, RHO, E, NU) == pytest.approx(2 * out, rel=1e-12)
    assert centrifugal.disc_growth(w, 0.0, 2 * a, 2 * a, RHO, E, NU) == pytest.approx(2 * solid, rel=1e-12)


@given(n=st.floats(500.0, 8000.0), k=st.floats(1.1, 3.0))
def test_centrifugal_reduction_goes_as_speed_squared(n, k):
    """With the fit holding at both speeds, the chain is linear in the centrifugal terms: ~ n^2."""
    w = n * math.pi / 30
    r1 = chain.operating_clearance(30e-6, 25e-6, 0.0, M, chain.Conditions(speed=w))
    r2 = chain.operating_clearance(30e-6, 25e-6, 0.0, M, chain.Conditions(speed=k * w))
    assert r2.inner_operating_interference > 0
    assert r2.centrifugal_reduction == pytest.approx(k**2 * r1.centrifugal_reduction, rel=1e-9)


def test_inner_fit_comes_loose_at_speed_and_warns():
    w = 30000 * math.pi / 30
    loss = centrifugal.inner_fit_loss(w, M.bore, M.inner_raceway, 0.0, STEEL, STEEL)
    r = chain.operating_range((10e-6, 20e-6), (0.5 * loss, 0.8 * loss), (0.0, 0.0), M, chain.Conditions(speed=w))
    assert all(c.inner_loosened_by_speed for c in (r.least, r.probable, r.largest))
    assert any("comes loose at speed" in note for note in r.warnings)
    assert r.least.inner_pressure == 0.0


def test_loose_inner_ring_grows_freely_with_speed():
    w = 20000 * math.pi / 30
    r = chain.operating_clearance(20e-6, -10e-6, 0.0, M, chain.Conditions(speed=w))
    free = centrifugal.disc_growth(w, M.bore, M.inner_raceway, M.inner_raceway, RHO, E, NU)
    assert r.centrifugal_reduction == pytest.approx(free, rel=1e-12)


def test_range_brackets_and_orders_the_cases():
    r = chain.operating_range((6e-6, 20e-6), (2e-6, 25e-6), (-30e-6, 5e-6), M)
    assert r.least.operating_clearance < r.probable.operating_clearance < r.largest.operating_clearance
    assert r.least.fit_reduction > r.largest.fit_reduction


def test_negative_clearance_is_a_preload_with_a_warning():
    r = chain.operating_range((0.0, 5e-6), (20e-6, 40e-6), (0.0, 0.0), M)
    assert r.least.operating_clearance < 0
    assert any("preloaded" in note for note in r.warnings)


def test_vectorized_chain_equals_scalar_calls():
    e = np.array([5e-6, 10e-6, 20e-6])
    ii = np.array([-5e-6, 10e-6, 30e-6])
    c = chain.Conditions(T0 + 40, T0 + 30, speed=800.0)
    batch = chain.operating_clearance(e, ii, 0.0, M, c).operating_clearance
    one = [chain.operating_clearance(a, b, 0.0, M, c).operating_clearance for a, b in zip(e, ii)]
    assert np.allclose(batch, one, rtol=0, atol=1e-18)


@pytest.mark.parametrize("kw, match", [({"shaft_bore": 0.05}, "shaft-bore must be"),
                                       ({"housing_outside_diameter": 0.07}, "housing-outside-diameter")])
def test_mounting_checks(kw, match):
    with pytest.raises(ValueError, match=match):
        chain.Mounting(0.040, 0.080, 0.0479, 0.0721, 0.0121, **kw)


@given(i1=st.floats(-30.0, 60.0), di=st.floats(0.0, 30.0), o1=st.floats(-30.0, 60.0), do_=st.floats(0.0, 30.0),
       ti=st.floats(0.0, 80.0), n=st.floats(0.0, 15000.0))
def test_operating_clearance_never_grows_with_interference(i1, di, o1, do_, ti, n):
    """Every stage's loss grows with the interferences: the corners of operating_range are the extremes."""
    c = chain.Conditions(T0 + ti, T0 + 0.5 * ti, speed=n * math.pi / 30)
    a = chain.operating_clearance(20e-6, i1 * 1e-6, o1 * 1e-6, M, c).operating_clearance
    b = chain.operating_clearance(20e-6, (i1 + di) * 1e-6, (o1 + do_) * 1e-6, M, c).operating_clearance
    assert b <= a + 1e-18

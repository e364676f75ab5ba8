"""The SKF four-term friction model: terms written out, limits, tables and properties."""

import dataclasses
import math
import re
import warnings

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from numpy.testing import assert_allclose

from bearinglab import friction
from bearinglab.errors import InputError

RPM = 2 * math.pi / 60


def _by_hand(fr, fa, rpm, nu, d, big, c, *, krs, kz, c0=None, ks=None, ds=None):
    """The catalogue's equations in its units (N, mm, rpm, mm^2/s -> N mm), deep groove."""
    dm = (d + big) / 2
    if fa == 0:
        grr = c.r1 * dm**1.96 * fr**0.54
        gsl = c.s1 * dm**-0.26 * fr ** (5 / 3)
    else:
        s = math.sin(math.radians(24.6 * (fa / c0) ** 0.24))
        grr = c.r1 * dm**1.96 * (fr + c.r2 * fa / s) ** 0.54
        gsl = c.s1 * dm**-0.145 * (fr**5 + c.s2 * dm**1.5 * fa**4 / s) ** (1 / 3)
    ish = 1 / (1 + 1.84e-9 * (rpm * dm) ** 1.28 * nu**0.64)
    rs = math.exp(-krs * nu * rpm * (d + big) * math.sqrt(kz / (2 * (big - d))))
    phi_bl = math.exp(-2.6e-8 * (rpm * nu) ** 1.4 * dm)
    mu = phi_bl * 0.15 + (1 - phi_bl) * 0.05
    seal = 0.0 if ks is None else ks[0] * ds ** ks[1] + ks[2]
    return ish * rs * grr * (nu * rpm) ** 0.6 + gsl * mu + seal


@pytest.mark.parametrize(("fr", "fa", "rpm", "nu"), [(500.0, 0.0, 1500.0, 20.0), (300.0, 400.0, 6000.0, 10.0),
                                                     (2000.0, 50.0, 100.0, 150.0)])
def test_deep_groove_terms_against_the_equations(fr, fa, rpm, nu):
    c = friction.series_constants("62")
    got = friction.skf(fr, fa, rpm * RPM, nu * 1e-6, 25e-3, 52e-3, series="62", static_load_rating=7800.0,
                       lubrication="oil-jet")
    want = _by_hand(fr, fa, rpm, nu, 25.0, 52.0, c, krs=3e-8, kz=3.1, c0=7800.0)
    assert got.total_moment * 1e3 == pytest.approx(want, rel=1e-13)
    assert got.power_loss == pytest.approx(got.total_moment * rpm * RPM, rel=1e-14)
    assert got.total_moment == pytest.approx(got.rolling_moment + got.sliding_moment + got.seal_moment, rel=1e-15)
    assert got.drag_moment == 0.0


def test_issue_example_constants_and_seal_row():
    assert friction.series_constants("62") == friction.SKFConstants(3.9e-7, 1.7, 3.23e-3, 36.5)
    c618 = friction.series_constants("618")
    assert (c618.r1, c618.s1) == (4.7e-7, 6.5e-3)
    assert friction.seal_constants("RS1", 72e-3) == friction.SealConstants(0.018, 2.25, 20.0)
    # SKF General Catalogue 6000/I RU (2006), table 4, p. 96: the other RS1 rows of deep groove bearings
    assert friction.seal_constants("RS1", 52e-3) == friction.SealConstants(0.023, 2.25, 2.0)
    assert friction.seal_constants("RS1", 62e-3) == friction.SealConstants(0.023, 2.25, 2.0)
    assert friction.seal_constants("RS1", 80e-3) == friction.SealConstants(0.018, 2.25, 20.0)
    assert friction.seal_constants("RS1", 90e-3) == friction.SealConstants(0.018, 2.25, 15.0)
    assert friction.seal_constants("RS1", 150e-3) == friction.SealConstants(0.018, 2.25, 0.0)
    with pytest.raises(InputError, match="seal must be one of"):
        friction.seal_constants("LS", 72e-3)


def test_seal_moment_halved_for_one_side_and_zero_for_shields():
    kw = {"series": "618", "seal": "RS1", "seal_diameter": 59.5e-3}
    two = friction.skf(6.51, 0.0, 2000 * RPM, 30e-6, 55e-3, 72e-3, **kw)
    one = friction.skf(6.51, 0.0, 2000 * RPM, 30e-6, 55e-3, 72e-3, seals=1, **kw)
    assert one.seal_moment == pytest.approx(two.seal_moment / 2, rel=1e-15)
    assert two.seal_moment * 1e3 == pytest.approx(0.018 * 59.5**2.25 + 20, rel=1e-14)
    shield = friction.skf(6.51, 0.0, 2000 * RPM, 30e-6, 55e-3, 72e-3, series="618", seal="Z")
    assert shield.seal_moment == 0.0
    with pytest.raises(InputError, match="seal_diameter"):
        friction.skf(6.51, 0.0, 2000 * RPM, 30e-6, 55e-3, 72e-3, series="618", seal="RS1")


def test_refuses_oil_bath_without_its_level_and_unknowns():
    with pytest.raises(InputError, match="oil bath needs the oil level"):  # issue 24: the drag is modelled
        friction.skf(100.0, 0.0, 100.0, 20e-6, 25e-3, 52e-3, series="62", lubrication="oil-bath")
    with pytest.raises(InputError, match="series must be one of"):
        friction.skf(100.0, 0.0, 100.0, 20e-6, 25e-3, 52e-3, series="99")
    with pytest.raises(InputError, match="static_load_rating"):
        friction.skf(100.0, 10.0, 100.0, 20e-6, 25e-3, 52e-3, series="62")
    with pytest.raises(InputError, match="series constants are for deep-groove bearings"):
        friction.skf(100.0, 10.0, 100.0, 20e-6, 25e-3, 52e-3, series="62", bearing_type="angular")


def test_angular_contact_with_given_constants():
    c = friction.SKFConstants(r1=5e-7, r2=2.0, s1=1e-2, s2=0.7, r3=2e-12, s3=2e-12)
    rpm, dm, fr, fa, nu = 3000.0, 47.5, 800.0, 600.0, 20.0
    got = friction.skf(fr, fa, rpm * RPM, nu * 1e-6, 35e-3, 60e-3 + 0.0, constants=c, bearing_type="angular",
                       lubrication="oil-air")
    fg_r, fg_s = c.r3 * dm**4 * rpm**2, c.s3 * dm**4 * rpm**2
    grr = c.r1 * dm**1.97 * (fr + fg_r + c.r2 * fa) ** 0.54
    gsl = c.s1 * dm**0.26 * ((fr + fg_s) ** (4 / 3) + c.s2 * fa ** (4 / 3))
    ish = 1 / (1 + 1.84e-9 * (rpm * dm) ** 1.28 * nu**0.64)
    rs = math.exp(-6e-8 * nu * rpm * 95.0 * math.sqrt(4.4 / (2 * 25.0)))
    mu = friction.sliding_friction_coefficient(nu * 1e-6, rpm * RPM, dm * 1e-3)
    assert got.total_moment * 1e3 == pytest.approx(ish * rs * grr * (nu * rpm) ** 0.6 + gsl * mu, rel=1e-13)


def test_sliding_coefficient_limits_and_override():
    # phi_bl -> 1 at rest (boundary 0.15), -> 0 at high speed and viscosity (EHL 0.05)
    assert friction.sliding_friction_coefficient(30e-6, 0.0, 0.05) == pytest.approx(0.15)
    assert friction.sliding_friction_coefficient(100e-6, 10000 * RPM, 0.05) == pytest.approx(0.05, abs=1e-12)
    m = friction.skf(500.0, 0.0, 1000 * RPM, 20e-6, 25e-3, 52e-3, series="62", sliding_friction_coefficient=0.1)
    assert m.sliding_friction_coefficient == 0.1


@settings(deadline=None)
@given(f1=st.floats(1.0, 5000.0), f2=st.floats(1.0, 5000.0), fa=st.floats(0.0, 2000.0), rpm=st.floats(10.0, 1e4),
       nu=st.floats(2.0, 500.0))
def test_torque_monotone_in_radial_load(f1, f2, fa, rpm, nu):
    lo, hi = sorted((f1, f2))
    kw = {"series": "62", "static_load_rating": 7800.0}
    a = friction.skf(lo, fa, rpm * RPM, nu * 1e-6, 25e-3, 52e-3, **kw).total_moment
    b = friction.skf(hi, fa, rpm * RPM, nu * 1e-6, 25e-3, 52e-3, **kw).total_moment
    assert b >= a * (1 - 1e-12)


@settings(deadline=None)
@given(a1=st.floats(1.0, 3000.0), a2=st.floats(1.0, 3000.0), fr=st.floats(0.0, 3000.0))
def test_torque_monotone_in_axial_load(a1, a2, fr):
    lo, hi = sorted((a1, a2))
    kw = {"series": "63", "static_load_rating": 16000.0}
    a = friction.skf(fr, lo, 3000 * RPM, 30e-6, 30e-3, 72e-3, **kw).total_moment
    b = friction.skf(fr, hi, 3000 * RPM, 30e-6, 30e-3, 72e-3, **kw).total_moment
    assert b >= a * (1 - 1e-12)


def test_vectorized_equals_per_case_and_sign_of_speed():
    rng = np.random.default_rng(1)
    fr, fa = rng.uniform(10, 3000, 50), rng.uniform(0, 1000, 50)
    n = rng.uniform(-500, 500, 50)
    batch = friction.skf(fr, fa, n, 25e-6, 25e-3, 52e-3, series="62", static_load_rating=7800.0)
    for k in range(0, 50, 7):
        one = friction.skf(fr[k], fa[k], abs(n[k]), 25e-6, 25e-3, 52e-3, series="62", static_load_rating=7800.0)
        assert_allclose(batch.total_moment[k], one.total_moment, rtol=1e-14)
        assert_allclose(batch.power_loss[k], one.power_loss, rtol=1e-14)


def test_series_from_designation():
    assert friction.bearing_series("6205-2RSH") == "62"
    assert friction.bearing_series("619/500") == "619"
    assert friction.bearing_series("6305") == "63"
    with pytest.raises(InputError, match="not in the table"):
        friction.bearing_series("7205 BE")
    with pytest.raises(InputError, match="cannot be read"):
        friction.bearing_series("NU 205")


def test_benchmark_paths_agree_on_a_small_input(load_bench):
    bench = load_bench("skf_friction")
    args = bench.cases(200, seed=3)
    assert_allclose(bench.batched(*args), bench.baseline(*args), rtol=1e-12)


# ----------------------------------------------------------------------------- seal data missing (issue 15)
@pytest.mark.parametrize("designation, kind", [("6205-2RS", "RS"), ("6205-2RS1", "RS1"), ("6205-RS", "RS"),
                                               ("6205-2RSH", "RSH"), ("6205-2RSH/C3", "RSH"), ("6205-2RZ", "RZ"),
                                               ("6205-2Z", "Z"), ("6205-Z", "Z"), ("6205ZZ", "ZZ")])
def test_a_sealed_designation_without_seal_data_warns_that_m_seal_is_left_out(designation, kind):
    from bearinglab import catalog

    b = dataclasses.replace(catalog.get("6205-2RS"), designation=designation)
    with pytest.warns(UserWarning, match=rf"{re.escape(repr(designation))} .*\({kind}, by its designation\)"):
        m = friction.skf_for_bearing(b, 1000.0, 0.0, 3000 * RPM, 68e-6)
    assert m.seal_moment == 0.0 and len(m.warnings) == 1
    contact = kind not in ("Z", "ZZ", "RZ")
    assert ("M_seal of its contact seals is not included" in m.warnings[0]) == contact
    assert ("seal_constants_override=SealConstants" in m.warnings[0]) == contact
    # the moments are those of the open bearing: nothing invented for the seals
    open_ = friction.skf(1000.0, 0.0, 3000 * RPM, 68e-6, 25e-3, 52e-3, series="62")
    assert m.total_moment == open_.total_moment


@pytest.mark.parametrize("designation", ["6205", "16004", "618/500", "4-1006095", "7205 BEP", "inline"])
def test_an_open_designation_gives_no_seal_warning(designation):
    from bearinglab import catalog

    b = dataclasses.replace(catalog.get("6205-2RS"), designation=designation)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert friction.skf_for_bearing(b, 1000.0, 0.0, 3000 * RPM, 68e-6).warnings == ()


def test_seal_data_or_no_sealed_side_silence_the_seal_warning():
    from bearinglab import catalog

    with warnings.catch_warnings():
        warnings.simplefilter("error")
        sealed = friction.skf_for_bearing(catalog.get("61811-2RS1"), 6.51, 0.0, 2000 * RPM, 30e-6)
        assert sealed.warnings == () and sealed.seal_moment > 0
        b = catalog.get("6205-2RS")
        given = friction.skf_for_bearing(b, 1000.0, 0.0, 3000 * RPM, 68e-6, seal_diameter=30e-3,
                                         seal_constants_override=friction.SealConstants(0.02, 2.0, 10.0))
        assert given.warnings == () and given.seal_moment * 1e3 == pytest.approx(0.02 * 30.0**2 + 10.0, rel=1e-14)
        none = friction.skf_for_bearing(dataclasses.replace(b, seals=0), 1000.0, 0.0, 3000 * RPM, 68e-6)
        assert none.warnings == ()

"""Handbook friction-torque models of spec 001 section 3 (bearinglab.friction): tables, max rule,
one-term, two-term, Palmgren, overrides, errors and invariants."""

import inspect
import math
import re
import warnings

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from numpy.testing import assert_allclose

from bearinglab import friction
from bearinglab.errors import InputError, ValidityWarning

RPM = 2 * math.pi / 60
DEG = math.pi / 180
FAST = settings(max_examples=40, deadline=None)

loads = st.floats(0.0, 5e3, allow_nan=False)
speeds = st.floats(0.0, 2e4)


# ----------------------------------------------------------------------------- Table 1 and (3.1)
@pytest.mark.parametrize(
    "angle, x0, y0",
    [(18, 0.5, 0.43), (20, 0.5, 0.42), (26, 0.5, 0.37), (30, 0.5, 0.33), (36, 0.5, 0.28)],
)
def test_table1_angular_rows(angle, x0, y0):
    got = friction.static_load_factors("angular", angle * DEG)
    assert (float(got.radial_factor), float(got.axial_factor)) == (x0, y0)


def test_table1_radial_row_and_vectorized_angles():
    assert friction.static_load_factors("radial") == (0.6, 0.5)
    got = friction.static_load_factors("angular", np.radians([18.0, 36.0, 26.0]))
    assert_allclose(got.axial_factor, [0.43, 0.28, 0.37], rtol=0, atol=0)


def test_table1_rejects_untabulated_angle_unless_factors_given():
    with pytest.raises(
        InputError, match=r"contact_angle must be one of the Table 1 or ISO 76 angles .* got 27\.0"
    ):
        friction.static_load_factors("angular", 27 * DEG)
    with pytest.raises(InputError, match="contact_angle must be one of the Table 1"):
        friction.equivalent_static_load(100.0, 50.0, bearing_type="angular", contact_angle=27 * DEG)


def test_iso76_standard_angles_take_the_iso_row():
    """Issue 15 item 12: 15, 25 and 40 deg bearings get X0/Y0 of ISO 76:2006 table 1."""
    got = friction.static_load_factors("angular", np.radians([15.0, 25.0, 40.0, 45.0]))
    assert_allclose(got.radial_factor, 0.5, rtol=0, atol=0)
    assert_allclose(got.axial_factor, [0.46, 0.38, 0.26, 0.22], rtol=0, atol=0)  # ISO 76 table 1
    p0 = friction.equivalent_static_load(
        100.0,
        50.0,
        bearing_type="angular",
        contact_angle=25 * DEG,
        radial_factor=0.5,
        axial_factor=0.4,
    )
    assert p0 == max(0.5 * 100 + 0.4 * 50, 100.0)


def test_angular_needs_contact_angle_and_valid_type():
    with pytest.raises(
        InputError, match="contact_angle: an angular-contact bearing needs its contact angle"
    ):
        friction.static_load_factors("angular")
    with pytest.raises(
        InputError, match=r"bearing_type must be one of \['radial', 'angular'\], got 'thrust'"
    ):
        friction.equivalent_static_load(1.0, 1.0, bearing_type="thrust")
    with pytest.raises(InputError, match=r"contact_angle must be in \(0, 90\)"):
        friction.load_term_constants("angular", 95 * DEG)


def test_max_rule_examples_and_branch():
    # pure axial load on a radial bearing: P0 = 0.5 Fa, not Fa (spec 001 section 4)
    assert friction.equivalent_static_load(0.0, 10.0) == 5.0
    assert friction.equivalent_static_load(10.0, 0.0) == 10.0
    assert friction.equivalent_static_load(10.0, 10.0) == pytest.approx(11.0, rel=1e-15)
    assert bool(friction.combined_branch_governs(0.0, 10.0))
    assert not bool(friction.combined_branch_governs(10.0, 1.0))
    # overrides replace the table
    assert friction.equivalent_static_load(10.0, 10.0, radial_factor=0.5, axial_factor=1.0) == 15.0


@FAST
@given(fr=loads, fa=loads)
def test_max_rule_is_the_larger_branch(fr, fa):
    p0 = friction.equivalent_static_load(fr, fa)
    assert p0 >= fr and p0 >= 0.6 * fr + 0.5 * fa
    assert p0 in (fr, 0.6 * fr + 0.5 * fa)
    assert bool(friction.combined_branch_governs(fr, fa)) == (0.6 * fr + 0.5 * fa >= fr)


@FAST
@given(fr=loads, fa=loads, scale=st.floats(0.01, 100.0))
def test_equivalent_load_is_homogeneous_of_degree_one(fr, fa, scale):
    p0 = friction.equivalent_static_load(fr, fa)
    assert friction.equivalent_static_load(scale * fr, scale * fa) == pytest.approx(
        scale * p0, rel=1e-12, abs=1e-300
    )


def test_scalar_and_array_agree():
    fr = np.array([0.0, 5.0, 19.62, 100.0])
    fa = np.array([19.62, 5.0, 0.0, 30.0])
    arr = friction.equivalent_static_load(fr, fa)
    assert arr.shape == (4,)
    for i in range(4):
        assert friction.equivalent_static_load(fr[i], fa[i]) == arr[i]
    assert np.ndim(friction.equivalent_static_load(1.0, 2.0)) == 0


def test_negative_and_nan_loads_rejected():
    with pytest.raises(InputError, match=r"radial_load must be >= 0 \[N\], got -1\.0"):
        friction.equivalent_static_load(-1.0, 0.0)
    with pytest.raises(InputError, match=r"axial_load must be >= 0 \[N\], got nan"):
        friction.equivalent_static_load(1.0, float("nan"))


# ----------------------------------------------------------------------------- one-term model
def test_one_term_handbook_mu_and_override():
    assert friction.handbook_friction_coefficient("radial") == 0.0015
    assert friction.handbook_friction_coefficient("angular") == 0.0020
    t = friction.one_term(19.62, 5e-3)
    assert t == pytest.approx(0.0015 * 19.62 * 5e-3 / 2, rel=1e-15)
    assert friction.one_term(19.62, 5e-3, bearing_type="angular") == pytest.approx(
        t * 0.002 / 0.0015, rel=1e-14
    )
    assert friction.one_term(19.62, 5e-3, reduced_friction_coefficient=0.003) == pytest.approx(
        2 * t, rel=1e-14
    )
    with pytest.raises(InputError, match=r"bore must be > 0 \[m\], got 0\.0"):
        friction.one_term(1.0, 0.0)
    with pytest.raises(InputError, match=r"equivalent_load must be >= 0 \[N\]"):
        friction.one_term(-1.0, 5e-3)


# ----------------------------------------------------------------------------- Table 2, (3.4), (3.5)
def test_table2_rows_and_30_degree_gap():
    assert friction.load_term_constants("radial") == (0.0009, 0.55)
    assert tuple(map(float, friction.load_term_constants("angular", 29.9 * DEG))) == (0.0010, 0.33)
    # spec 001 section 8.5: alpha >= 30 deg -> 0.0013; "30 deg" in radians is 29.999999999999996 deg
    thirty = 30 * math.pi / 180
    assert math.degrees(thirty) < 30.0
    assert float(friction.load_term_constants("angular", thirty).load_term_factor) == 0.0013
    got = friction.load_term_constants("angular", np.radians([15.0, 40.0]))
    assert_allclose(got.load_term_factor, [0.0010, 0.0013], rtol=0, atol=0)


def test_load_term_overrides_and_warning():
    base = friction.load_term(20.0, 9e-3, 392.0)
    assert base == pytest.approx(0.0009 * 20 * (20 / 392) ** 0.55 * 9e-3, rel=1e-14)
    assert friction.load_term(20.0, 9e-3, 392.0, load_term_factor=0.0018) == pytest.approx(
        2 * base, rel=1e-14
    )
    assert friction.load_term(20.0, 9e-3, 392.0, load_term_exponent=0.0) == pytest.approx(
        0.0009 * 20 * 9e-3, rel=1e-14
    )
    with pytest.warns(ValidityWarning, match="P0/C0 up to 2"):
        friction.load_term(784.0, 9e-3, 392.0)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        friction.load_term(392.0, 9e-3, 392.0)  # P0 = C0 is still inside
    with pytest.raises(InputError, match=r"static_load_rating must be > 0 \[N\]"):
        friction.load_term(1.0, 9e-3, 0.0)


@FAST
@given(p0=st.floats(0.1, 300.0), k=st.floats(0.1, 1.0))
def test_load_term_scales_as_p0_to_one_plus_c(p0, k):
    a = friction.load_term(p0, 13.5e-3, 1354.0)
    b = friction.load_term(k * p0, 13.5e-3, 1354.0)
    assert b / a == pytest.approx(k**1.55, rel=1e-12)


@FAST
@given(n=st.floats(1.0, 3e4), k=st.floats(0.01, 10.0), dm=st.floats(1e-3, 0.3))
def test_speed_term_scaling_and_direction(n, k, dm):
    w = n * RPM
    t = friction.speed_term(w, dm, 2e-7)
    assert friction.speed_term(k * w, dm, 2e-7) == pytest.approx(k ** (2 / 3) * t, rel=1e-12)
    assert friction.speed_term(-w, dm, 2e-7) == t
    assert friction.speed_term(w, 2 * dm, 2e-7) == pytest.approx(8 * t, rel=1e-12)
    # the published-unit formula, evaluated in N*mm / mm / rpm, then converted
    assert t == pytest.approx(2e-7 * (dm * 1e3) ** 3 * n ** (2 / 3) * 1e-3, rel=1e-12)


def test_speed_term_needs_nonnegative_factor_and_zero_speed_gives_zero():
    assert friction.speed_term(0.0, 9e-3, 2e-7) == 0.0
    with pytest.raises(
        InputError, match=r"speed_term_factor must be >= 0 \[N\*mm\^-2\*min\^\(2/3\)\]"
    ):
        friction.speed_term(100.0, 9e-3, -1e-7)


def test_two_term_is_sum_and_broadcasts():
    p0 = np.array([4.905, 9.81, 19.62])
    w = 1500 * RPM
    t = friction.two_term(p0, w, 9e-3, 392.0, 2e-7)
    assert_allclose(t.torque, t.speed_term + t.load_term, rtol=1e-15)
    assert_allclose(t.speed_term, friction.speed_term(w, 9e-3, 2e-7), rtol=0)
    assert_allclose(t.load_term, friction.load_term(p0, 9e-3, 392.0), rtol=0)
    assert t.speed_term.shape == (3,)


def test_spec_s0_generating_model_reproduces_a_table_value():
    # spec 001 section 10.1: T at n = 1500 rpm, Q = 2 kg, beta = 90 deg, f* = 0.0015, f0* = 2e-7
    t = friction.two_term(19.62, 1500 * RPM, 9e-3, 392.0, 2e-7, load_term_factor=0.0015)
    assert t.torque * 1e3 == pytest.approx(0.070121614, abs=5e-10)  # table rounded to 1e-9 N*mm


# ----------------------------------------------------------------------------- Palmgren
@FAST
@given(
    nu_cst=st.floats(1.0, 500.0),
    n=st.floats(1.0, 3e4),
    f0p=st.floats(0.5, 6.0),
    dm=st.floats(2e-3, 0.2),
)
def test_palmgren_equals_seed_speed_term_with_folded_viscosity(nu_cst, n, f0p, dm):
    nu = nu_cst * 1e-6
    m0 = friction.palmgren(nu, n * RPM, dm, f0p)
    if nu_cst * n >= 2000.0:
        f0 = friction.speed_term_factor_from_palmgren(f0p, nu)
        assert m0 == pytest.approx(friction.speed_term(n * RPM, dm, f0), rel=1e-12)
        assert f0 == pytest.approx(1e-7 * f0p * nu_cst ** (2 / 3), rel=1e-12)
    else:
        assert m0 == pytest.approx(160e-7 * f0p * (dm * 1e3) ** 3 * 1e-3, rel=1e-12)


def test_palmgren_branches_and_switch():
    dm, f0p, nu = 20e-3, 2.0, 20e-6
    # nu*n = 2000 exactly at n = 100 rpm: the speed-dependent branch applies from there on
    at_switch = friction.palmgren(nu, 100 * RPM, dm, f0p)
    assert at_switch == pytest.approx(1e-7 * 2 * 2000 ** (2 / 3) * 8000 * 1e-3, rel=1e-12)
    below = friction.palmgren(nu, 50 * RPM, dm, f0p)
    assert below == pytest.approx(160e-7 * 2 * 8000 * 1e-3, rel=1e-12)
    assert friction.palmgren(nu, 0.0, dm, f0p) == below  # a floor, not 0 as in (3.5)
    assert below / at_switch == pytest.approx(160 / 2000 ** (2 / 3), rel=1e-12)  # 0.8 % jump
    got = friction.palmgren(nu, np.array([50, 100, 3000]) * RPM, dm, f0p)
    # the published floor 160 is slightly above 2000^(2/3) = 158.7: M0 drops by 0.8 % at the switch
    assert got.shape == (3,) and got[0] > got[1] and got[2] > got[1]
    with pytest.raises(InputError, match=r"kinematic_viscosity must be >= 0 \[m\^2/s\]"):
        friction.palmgren(-1e-6, 1.0, dm, f0p)


# ----------------------------------------------------------------------------- docstrings
def _documented_parameters(doc):
    m = re.search(
        r"Parameters\n\s*-+\n(.*?)(?:\n\s*\n\s*(?:Returns|Raises|Warns|Notes|Examples|Yields)\n|\Z)",
        doc,
        re.DOTALL,
    )
    if not m:
        return []
    names = []
    for line in m.group(1).splitlines():
        hit = re.match(r"^    (\*{0,2}[A-Za-z_][\w, *]*?) :", line)
        if hit:
            names += [n.strip().lstrip("*") for n in hit.group(1).split(",")]
    return names


@pytest.mark.parametrize("name", friction.__all__)
def test_public_docstrings_document_exactly_the_signature(name):
    obj = getattr(friction, name)
    if not inspect.isfunction(obj):
        return
    params = list(inspect.signature(obj).parameters)
    assert _documented_parameters(inspect.getdoc(obj) and obj.__doc__) == params, name


def test_one_term_old_keyword_still_works_with_a_deprecation_warning():
    with pytest.warns(DeprecationWarning, match="reduced_friction_coefficient"):
        old = friction.one_term(19.62, 5e-3, friction_coefficient=0.003)
    assert old == friction.one_term(19.62, 5e-3, reduced_friction_coefficient=0.003)
    with pytest.raises(InputError, match="reduced_friction_coefficient only"):
        friction.one_term(19.62, 5e-3, friction_coefficient=0.003, reduced_friction_coefficient=0.003)


def test_dispatcher_lists_the_models():
    assert friction.torque("palmgren", 20e-6, 300.0, 20e-3, 2.0) == friction.palmgren(20e-6, 300.0, 20e-3, 2.0)
    with pytest.raises(InputError, match=r"model must be one of \['one-term', 'two-term', 'palmgren', 'skf'\]"):
        friction.torque("coulomb", 1.0)

"""Tests of bearinglab.hertz.

The exact coefficients are checked against an independent evaluation: the complete elliptic integrals by
``scipy.integrate.quad`` of their defining integrals and the ellipticity by ``brentq`` on kappa (the
module uses scipy.special and a safeguarded Newton in m). Plus the table of spec 000 section 5.2, the
classical sphere-on-flat solution, round trips and properties.
"""

import csv
import math
from functools import cache
from pathlib import Path

import numpy as np
import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st
from numpy.testing import assert_allclose
from scipy.integrate import quad
from scipy.optimize import brentq

from bearinglab import hertz
from bearinglab.errors import ConvergenceError, InputError

DATA = Path(__file__).parent / "data" / "hertz_spec000_table.csv"
SPEC_TABLE = list(csv.DictReader(line for line in DATA.open() if not line.startswith("#")))
SETTINGS = settings(max_examples=40, deadline=None)


# ------------------------------------------------------------------------- independent evaluation
def _k(m):
    return quad(
        lambda t: 1.0 / math.sqrt(1.0 - m * math.sin(t) ** 2),
        0.0,
        math.pi / 2,
        epsabs=0,
        epsrel=1e-13,
        limit=200,
    )[0]


def _e(m):
    return quad(
        lambda t: math.sqrt(1.0 - m * math.sin(t) ** 2),
        0.0,
        math.pi / 2,
        epsabs=0,
        epsrel=1e-13,
        limit=200,
    )[0]


def _f_of_kappa(kappa):
    m = 1.0 - 1.0 / kappa**2
    k, e = _k(m), _e(m)
    return ((kappa**2 + 1.0) * e - 2.0 * k) / ((kappa**2 - 1.0) * e)


@cache
def independent(f):
    """kappa, a*, b*, delta* from F(rho) by quadrature and brentq (spec 000 section 5.2)."""
    kappa = brentq(
        lambda x: _f_of_kappa(x) - f, 1.0 + 1e-6, 1e3, xtol=1e-15, rtol=1e-15, maxiter=500
    )
    m = 1.0 - 1.0 / kappa**2
    k, e = _k(m), _e(m)
    a_star = (2.0 * kappa**2 * e / math.pi) ** (1 / 3)
    b_star = (2.0 * e / (math.pi * kappa)) ** (1 / 3)
    delta_star = 2.0 * k / math.pi * (math.pi / (2.0 * kappa**2 * e)) ** (1 / 3)
    return kappa, a_star, b_star, delta_star


F_VALUES = [0.01, 0.1, 0.3, 0.5, 0.7111269, 0.8, 0.9, 0.9287242, 0.95, 0.99, 0.999]


@pytest.mark.parametrize("f", F_VALUES)
def test_exact_coefficients_against_quadrature_and_brentq(f):
    got = hertz.coefficients(f)
    want = independent(f)
    # both are exact to ~1e-13; kappa is ill-conditioned in F as F -> 1 (dkappa/dF large), hence 1e-9 there
    assert_allclose(got, want, rtol=1e-9 if f > 0.98 else 1e-11, err_msg=f"F = {f}")


def test_vectorized_inversion_matches_elementwise():
    f = np.array(F_VALUES).reshape(1, -1)
    got = hertz.coefficients(f)
    assert np.shape(got.ellipticity) == f.shape
    for j, fj in enumerate(F_VALUES):
        one = hertz.coefficients(fj)
        for name in got._fields:
            # the Newton stop is on m to 1e-14 for the whole array at once; kappa = (1 - m)^-1/2
            # amplifies that by 1 / (2 (1 - m)): ~2e-13 at F = 0.9, ~5e-11 at F = 0.999 (kappa = 100)
            rtol = 1e-14 / (2.0 / one.ellipticity**2) * 2
            assert getattr(got, name)[0, j] == pytest.approx(getattr(one, name), rel=rtol), (
                name,
                fj,
            )


@pytest.mark.parametrize("row", SPEC_TABLE, ids=[r["contact"] for r in SPEC_TABLE])
def test_spec000_table_of_section_5_2(row):
    c = hertz.coefficients(float(row["cos_tau"]))
    got = {
        "kappa": c.ellipticity,
        "mu": c.a_star,
        "nu": c.b_star,
        "mu_nu": c.a_star * c.b_star,
        "delta_star": c.delta_star,
    }
    for name, value in got.items():
        printed = row[name]
        half_unit = 0.5 * 10.0 ** -len(printed.split(".")[1])  # tolerance: the printed digits
        assert abs(value - float(printed)) <= half_unit, (name, value, printed)
    # the handbook values the paper used are the exact ones rounded to 2-3 digits
    for name in ("mu_nu", "delta_star"):
        table = row[name + "_table"]
        assert abs(got[name] - float(table)) <= 0.5 * 10.0 ** -len(table.split(".")[1]), name


def test_zero_curvature_difference_is_a_circle():
    c = hertz.coefficients(0.0)
    assert tuple(map(float, c)) == (1.0, 1.0, 1.0, 1.0)
    # just below and above the switch to the series m = 8F/3 the two branches agree
    lo, hi = hertz.ellipticity(0.999999e-5), hertz.ellipticity(1.000001e-5)
    assert hi - lo == pytest.approx(0.0, abs=1e-9)
    # and the series is the limit of the exact relation: kappa^2 - 1 ~ 8F/3
    f = 1e-4
    assert (independent(f)[0] ** 2 - 1) / f == pytest.approx(8 / 3, rel=1e-3)


def test_ellipticity_converges_on_a_large_mixed_batch():
    """10 000 F values over the whole range in one call. Before the cycle check every such batch raised:
    one element in a few hundred made Newton cycle between two neighbouring m whose residuals are +- the
    rounding of F, and the batch cannot stop until every element has."""
    from scipy.special import ellipe, ellipk

    f = np.random.default_rng(2).uniform(1e-5, 0.9999, 10_000)
    kappa = hertz.ellipticity(f)
    m = 1.0 - 1.0 / kappa**2
    back = ((kappa**2 + 1.0) * ellipe(m) - 2.0 * ellipk(m)) / ((kappa**2 - 1.0) * ellipe(m))
    # 1e-15 / F: the rounding of the closed form itself as F -> 0 (see test_ellipticity_satisfies_its_equation)
    assert np.all(np.abs(back - f) <= 1e-12 * f + 1e-15 / f)
    # each element is the one a call of its own gives (no dependence on the batch it was solved in)
    pick = np.arange(0, f.size, 97)
    assert_allclose(kappa[pick], [hertz.ellipticity(x) for x in f[pick]], rtol=1e-13)


def test_ellipticity_reports_non_convergence():
    with pytest.raises(
        ConvergenceError, match="hertz.ellipticity: no convergence after 1 iterations"
    ) as info:
        hertz.ellipticity(np.array([0.5, 0.9]), max_iter=1)
    assert info.value.iterations == 1
    assert np.shape(info.value.estimate) == (2,) and np.all(info.value.estimate > 1)


# ------------------------------------------------------------------------------ contact of given load
def test_sphere_on_flat_is_classical_hertz():
    # F = 0: a sphere of radius R on a flat (curvature sum 2/R); Hertz: a^3 = 3 Q R / (4 E*), E' = 2 E*,
    # delta = a^2 / R, p_max = 3 Q / (2 pi a^2)
    q, r, e_red = 250.0, 6e-3, hertz.reduced_modulus(2.075e11, 0.3, 2.075e11, 0.3)
    e_star = e_red / 2
    c = hertz.point_contact(q, 2.0 / r, 0.0, e_red)
    a = (3 * q * r / (4 * e_star)) ** (1 / 3)
    assert_allclose(
        [c.a, c.b, c.delta, c.p_max], [a, a, a * a / r, 3 * q / (2 * math.pi * a * a)], rtol=1e-13
    )


def test_point_contact_with_the_independent_coefficients():
    q, s, f, e_red = 1000.0, 108.108, 0.926196, 2.28e11
    kappa, a_star, b_star, delta_star = independent(f)
    base = (3 * q / (e_red * s)) ** (1 / 3)  # Harris eqs. 6.38-6.43
    c = hertz.point_contact(q, s, f, e_red)
    assert_allclose(
        [c.a, c.b, c.delta],
        [a_star * base, b_star * base, delta_star * base**2 * s / 2],
        rtol=1e-11,
    )
    assert c.a / c.b == pytest.approx(kappa, rel=1e-11)
    assert c.p_max == pytest.approx(3 * q / (2 * math.pi * c.a * c.b), rel=1e-14)


def test_zero_load():
    c = hertz.point_contact(0.0, 100.0, 0.5, 2e11)
    assert (c.a, c.b, c.delta, c.p_max) == (0.0, 0.0, 0.0, 0.0)


def test_tabulated_override():
    tab = hertz.tabulated([0.63, 0.852])
    assert_allclose(tab.delta_star, [0.63, 0.852])
    assert np.all(np.isnan(tab.ellipticity)) and np.all(np.isnan(tab.a_star))
    exact = hertz.load_deflection_constant(1336.19, 0.9287242, 2.28e11)
    table = hertz.load_deflection_constant(1336.19, 0.9287242, 2.28e11, hertz=hertz.tabulated(0.63))
    # K ~ delta*^-1.5: the table's 0.63 vs the exact 0.62834 changes K by (0.62834 / 0.63)^1.5
    assert table / exact == pytest.approx((independent(0.9287242)[3] / 0.63) ** 1.5, rel=1e-10)


@SETTINGS
@given(
    q=st.floats(1e-3, 1e5),
    s=st.floats(10.0, 1e4),
    f=st.floats(0.0, 0.995),
    e_red=st.floats(5e10, 5e11),
)
def test_load_deflection_round_trip(q, s, f, e_red):
    c = hertz.point_contact(q, s, f, e_red)
    k = hertz.load_deflection_constant(s, f, e_red)
    assert k * c.delta**1.5 == pytest.approx(q, rel=1e-12)


@SETTINGS
@given(f=st.floats(0.0, 0.999), g=st.floats(0.0, 0.999))
@example(f=0.0, g=1e-8)
def test_coefficient_properties(f, g):
    c = hertz.coefficients(np.array([f, g]))
    assert np.all(c.ellipticity >= 1.0) and np.all(c.a_star >= 1.0 - 1e-15)
    assert np.all(c.b_star <= 1.0 + 1e-15) and np.all(c.delta_star <= 1.0 + 1e-15)
    assert_allclose(c.a_star / c.b_star, c.ellipticity, rtol=1e-13)  # a/b = kappa by definition
    if abs(f - g) > 1e-9:  # kappa rises and delta* falls with F(rho)
        i, j = (0, 1) if f < g else (1, 0)
        assert c.ellipticity[i] < c.ellipticity[j] and c.delta_star[i] >= c.delta_star[j]
        # delta* = 1 - (4/9) F^2 + ...: near F = 0 a difference below ~1e-12 in F^2 is below rounding
        if abs(f * f - g * g) > 1e-12:
            assert c.delta_star[i] > c.delta_star[j]


@SETTINGS
@given(f=st.floats(1e-4, 0.999))
# Newton once cycled here between two neighbours whose residuals are +-3.9e-15, the rounding of F
@example(f=0.06832705370719132)
def test_ellipticity_satisfies_its_equation(f):
    from scipy.special import ellipe, ellipk

    kappa = hertz.ellipticity(f)
    m = 1.0 - 1.0 / kappa**2
    back = ((kappa**2 + 1.0) * ellipe(m) - 2.0 * ellipk(m)) / ((kappa**2 - 1.0) * ellipe(m))
    # abs 1e-15 / F: the closed form cancels ((kappa^2 + 1) E - 2 K ~ F (kappa^2 - 1) E) as F -> 0, so in
    # double precision F(kappa) itself is only known to ~1e-16 pi / (kappa^2 - 1) ~ 1.2e-16 / F
    assert back == pytest.approx(f, rel=1e-12, abs=1e-15 / f)


@SETTINGS
@given(q=st.floats(1.0, 1e4), factor=st.floats(0.1, 10.0))
def test_load_scaling(q, factor):
    c1 = hertz.point_contact(q, 500.0, 0.8, 2.2e11)
    c2 = hertz.point_contact(q * factor, 500.0, 0.8, 2.2e11)
    assert c2.a / c1.a == pytest.approx(factor ** (1 / 3), rel=1e-12)
    assert c2.delta / c1.delta == pytest.approx(factor ** (2 / 3), rel=1e-12)
    assert c2.p_max / c1.p_max == pytest.approx(factor ** (1 / 3), rel=1e-12)


def test_reduced_modulus():
    assert hertz.reduced_modulus(2.075e11, 0.3, 2.075e11, 0.3) == pytest.approx(
        2.075e11 / 0.91, rel=1e-15
    )
    hybrid = hertz.reduced_modulus(3.1e11, 0.26, 2.075e11, 0.3)
    assert hybrid == pytest.approx(2 / ((1 - 0.26**2) / 3.1e11 + 0.91 / 2.075e11), rel=1e-15)
    assert hybrid == hertz.reduced_modulus(2.075e11, 0.3, 3.1e11, 0.26)


def test_steel_constants_of_the_handbooks():
    e_red = hertz.reduced_modulus(2.075e11, 0.3, 2.075e11, 0.3)
    # Harris: delta = 2.79e-4 delta* Q^(2/3) Sigma rho^(1/3) in mm and N (printed to 3 digits)
    c = hertz.point_contact(1.0, 1e3, 0.0, e_red)  # Q = 1 N, Sigma rho = 1 /mm, delta* = 1
    assert c.delta * 1e3 == pytest.approx(2.79e-4, abs=0.005e-4)
    # Harris / spec 004 eq. (16): K = 2.15e5 Sigma rho^-1/2 delta*^-3/2 in N and mm (3 digits)
    k = hertz.load_deflection_constant(1e3, 0.0, e_red)  # N/m^1.5 with Sigma rho = 1 /mm
    assert k * 1e-3**1.5 == pytest.approx(2.15e5, abs=0.005e5)
    # spec 000 section 5.3: 0.592e-4 (cm^2/kgf)^(2/3) is (3/E')^(2/3)/2 for steel, E = 2.078e5 MPa
    c = hertz.approach_coefficient(
        1.0, 1.0, 0.0, hertz.reduced_modulus(2.078e11, 0.3, 2.078e11, 0.3)
    )
    cm_kgf = (1e-2) ** (4 / 3) / 9.80665 ** (2 / 3)  # (m^2/N)^(2/3) per (cm^2/kgf)^(2/3)
    assert c / cm_kgf == pytest.approx(0.592e-4, abs=0.0005e-4)


def test_approach_coefficient_definition():
    # delta / D = c (Q / D^2)^(2/3), the same approach as point_contact
    d, s, f, e_red, q = 2e-3, 1336.19, 0.9287242, 2.28e11, 20.0
    c = hertz.approach_coefficient(d, s, f, e_red)
    assert d * c * (q / d**2) ** (2 / 3) == pytest.approx(
        hertz.point_contact(q, s, f, e_red).delta, rel=1e-13
    )


@settings(max_examples=50, deadline=None)
@given(e_red=st.floats(5e10, 5e11), q=st.floats(1e-2, 1e5))
def test_elastic_constant_gives_the_approach_of_the_contact(e_red, q):
    """C* of spec 000 with c_E = (3/E')^(2/3)/2: K = Q / delta^1.5 is load_deflection_constant."""
    s, f = 1336.19, 0.9287242
    delta_star = hertz.coefficients(f).delta_star
    delta = hertz.elastic_constant(e_red) * delta_star * np.cbrt(s) * q ** (2 / 3)  # delta/D times D, D cancels
    assert q / delta**1.5 == pytest.approx(hertz.load_deflection_constant(s, f, e_red), rel=1e-12)
    with pytest.raises(InputError, match=r"reduced_modulus must be > 0 \[Pa\]"):
        hertz.elastic_constant(0.0)


# ------------------------------------------------------------------------------------------ bad input
@pytest.mark.parametrize(
    "call, match",
    [
        (
            lambda: hertz.ellipticity(1.0),
            r"curvature_difference must be in \[0, 1\) \[-\], got 1.0",
        ),
        (
            lambda: hertz.ellipticity([0.5, -0.1]),
            r"curvature_difference must be >= 0 \[-\], got -0.1",
        ),
        (
            lambda: hertz.coefficients(float("nan")),
            r"curvature_difference must be >= 0 \[-\], got nan",
        ),
        (lambda: hertz.point_contact(-1.0, 100.0, 0.5, 2e11), r"load must be >= 0 \[N\], got -1.0"),
        (
            lambda: hertz.point_contact(1.0, 0.0, 0.5, 2e11),
            r"curvature_sum must be > 0 \[1/m\], got 0.0",
        ),
        (
            lambda: hertz.point_contact(1.0, 100.0, 0.5, -2e11),
            r"reduced_modulus must be > 0 \[Pa\]",
        ),
        (lambda: hertz.load_deflection_constant(-5.0, 0.5, 2e11), r"curvature_sum must be > 0"),
        (
            lambda: hertz.approach_coefficient(0.0, 100.0, 0.5, 2e11),
            r"ball_diameter must be > 0 \[m\]",
        ),
        (lambda: hertz.tabulated(0.0), r"delta_star must be > 0 \[-\], got 0.0"),
        (
            lambda: hertz.reduced_modulus(0.0, 0.3, 2e11, 0.3),
            r"elastic_modulus_1 must be > 0 \[Pa\]",
        ),
        (
            lambda: hertz.reduced_modulus([2e11, 2e11], [0.3, 0.6], 2e11, 0.3),
            r"poisson_ratio_1 must be in \(-1, 0.5\) \[-\], got 0.6",
        ),
        (
            lambda: hertz.reduced_modulus(2e11, 0.3, 2e11, -1.0),
            r"poisson_ratio_2 must be in \(-1, 0.5\)",
        ),
    ],
)
def test_bad_input(call, match):
    with pytest.raises(InputError, match=match):
        call()

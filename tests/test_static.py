"""Properties of the test-stand method (spec 000) and the static thrust angle (spec 004 section 5.3)."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from numpy.testing import assert_allclose
from scipy.optimize import brentq

from bearinglab import catalog, geometry, hertz, static
from bearinglab.errors import ConvergenceError, InputError
from bearinglab.units import KGF, RPM

A0 = math.radians(12.0)
CS = 7792.357 * KGF

geometries = st.fixed_dictionaries({
    "z": st.integers(3, 40),
    "d": st.floats(0.5e-3, 40e-3),
    "ratio": st.floats(2.2, 12.0),  # d_m / D
    "fi": st.floats(0.505, 0.58),
    "fo": st.floats(0.505, 0.58),
    "a0": st.floats(math.radians(2), math.radians(45)),
})


def _thrust_residual(alpha, fa, cs, a0):
    return static.thrust_from_angle(alpha, cs, a0) / fa - 1.0


def test_operating_angle_residual_below_1e10():
    loads = np.geomspace(1e-3, 1e4, 60) * KGF
    alpha = static.operating_contact_angle(loads, CS, A0)
    assert np.all(np.abs(_thrust_residual(alpha, loads, CS, A0)) < 1e-10)


def test_operating_angle_tends_to_free_angle_at_zero_load():
    loads = np.array([1e-12, 1e-9, 1e-6]) * KGF
    alpha = static.operating_contact_angle(loads, CS, A0)
    assert np.all(alpha > A0)
    assert np.all(np.diff(alpha - A0) > 0)
    # x ~ (F/C*)^(1/3): at 1e-12 kgf the increment is below 1e-4 rad
    assert alpha[0] - A0 < 1e-4


def test_operating_angle_rises_monotonically_with_load():
    loads = np.linspace(0.01, 500, 2000) * KGF
    alpha = static.operating_contact_angle(loads, CS, A0)
    assert np.all(np.diff(alpha) > 0)
    assert np.all(alpha < math.pi / 2)


def test_first_approximation_is_root_of_quadratic_truncation():
    t = np.geomspace(1e-8, 1e-2, 20)
    a = static.series_coefficients(t, A0)
    x0 = static.first_approximation(t, A0)
    assert_allclose(a[0] + a[1] * x0 + a[2] * x0**2, 0.0, atol=1e-15)
    assert_allclose(x0, a[1] / (2 * a[2]) * (np.sqrt(1 - 4 * a[0] * a[2] / a[1] ** 2) - 1), rtol=1e-12)


def test_series_coefficients_are_taylor_coefficients():
    # compare with finite-difference derivatives of f(x) of eq. (2)
    t = 2.0 / 7792.357

    def f(x):
        return (math.cos(A0) / math.cos(A0 + x) - 1) * math.sin(A0 + x) ** (2 / 3) - t ** (2 / 3)

    a = static.series_coefficients(t, A0)
    h = 1e-3
    d1 = (f(h) - f(-h)) / (2 * h)
    d2 = (f(h) - 2 * f(0) + f(-h)) / h**2
    d3 = (f(2 * h) - 2 * f(h) + 2 * f(-h) - f(-2 * h)) / (2 * h**3)
    assert_allclose([f(0), d1, d2 / 2, d3 / 6], a[:4], rtol=1e-5)


@settings(max_examples=40, deadline=None)
@given(g=geometries, load_ratio=st.floats(1e-7, 3e-3))
def test_random_geometry_and_load(g, load_ratio):
    d, dm = g["d"], g["d"] * g["ratio"]
    c = static.stand_constants(g["z"], d, dm, g["fi"], g["fo"], g["a0"])
    fa = load_ratio * c.force_characteristic
    alpha = static.operating_contact_angle(fa, c.force_characteristic, g["a0"])
    assert g["a0"] < alpha < math.pi / 2
    assert abs(_thrust_residual(alpha, fa, c.force_characteristic, g["a0"])) < 1e-10
    # the same root by bracketing
    ref = brentq(_thrust_residual, g["a0"] + 1e-15, math.pi / 2 - 1e-12, args=(fa, c.force_characteristic, g["a0"]),
                 xtol=1e-15, rtol=1e-15)
    assert_allclose(alpha, ref, atol=1e-11)


def test_array_and_scalar_agree_and_geometry_broadcasts():
    loads = np.array([0.5, 2.0, 8.0]) * KGF
    a0 = np.radians([[10.0], [12.0], [15.0]])
    arr = static.operating_contact_angle(loads, CS, a0)
    assert arr.shape == (3, 3)
    for i in range(3):
        for j in range(3):
            assert arr[i, j] == pytest.approx(static.operating_contact_angle(loads[j], CS, a0[i, 0]), abs=1e-14)
    assert isinstance(static.operating_contact_angle(2 * KGF, CS, A0), float)


def test_iteration_table_ends_at_the_vectorized_solution():
    rows = static.iteration_table(2 * KGF, CS, A0)
    assert rows[-1].contact_angle == pytest.approx(static.operating_contact_angle(2 * KGF, CS, A0), abs=1e-14)
    assert abs(rows[-1].error_percent) < 1e-8
    assert [r.k for r in rows] == list(range(len(rows)))


def test_axial_displacement_consistent_with_geometry():
    # tan a = tan a0 + xi_a / cos a0 and cos a0 / cos a = sqrt(cos^2 a0 + (sin a0 + xi_a)^2)
    alpha = static.operating_contact_angle(np.array([1, 2, 5]) * KGF, CS, A0)
    xa = static.axial_displacement_ratio(alpha, A0)
    assert_allclose(np.cos(A0) / np.cos(alpha), np.sqrt(np.cos(A0) ** 2 + (np.sin(A0) + xa) ** 2), rtol=1e-13)


def test_min_load_printed_constant_matches_physical_derivation():
    b = catalog.get("4-1006095")
    n = np.array([1000, 3000, 10000]) * RPM
    printed = static.min_axial_load(n, b.n_balls, b.ball_diameter, b.pitch_diameter, b.contact_angle).minimum
    derived = static.min_axial_load_gyroscopic(n, b.n_balls, b.ball_diameter, b.pitch_diameter, b.contact_angle)
    assert_allclose(printed, derived, rtol=1.5e-3)  # 5.75 vs 5.745: the printed constant is rounded (0.08 %)
    assert np.all(np.diff(printed) > 0)
    assert static.min_axial_load(0.0, 7, 2e-3, 8.7355e-3, A0).minimum == 0.0


def test_free_stiffness_static_angle_equals_stand_method_with_same_hertz():
    """contact_angle_under_thrust with K at alpha0 is spec 000's method with exact Hertz and the material constant."""
    b = catalog.get("B218")
    ep = b.reduced_modulus
    loads = np.array([2.5e3, 10e3, 45e3])
    r = static.contact_angle_under_thrust(loads, b.n_balls, b.ball_diameter, b.pitch_diameter, b.inner_conformity,
                                          b.outer_conformity, b.contact_angle, ep, stiffness_at="free")
    c = static.stand_constants(b.n_balls, b.ball_diameter, b.pitch_diameter, b.inner_conformity, b.outer_conformity,
                               b.contact_angle, elastic_constant=(3 / ep) ** (2 / 3) / 2)
    alpha = static.operating_contact_angle(loads, c.force_characteristic, b.contact_angle)
    assert_allclose(r.contact_angle, alpha, atol=1e-12)
    # the deflections use K_i, K_e at alpha0 too
    ki = hertz.load_deflection_constant(*b.curvature("inner", b.contact_angle), ep)
    ke = hertz.load_deflection_constant(*b.curvature("outer", b.contact_angle), ep)
    assert_allclose(ki * r.deflection_inner**1.5, r.ball_load, rtol=1e-12)
    assert_allclose(ke * r.deflection_outer**1.5, r.ball_load, rtol=1e-12)


def test_static_thrust_angle_equilibrium_and_compatibility():
    b = catalog.get("B218")
    loads = np.geomspace(100, 1e5, 25)
    r = static.contact_angle_under_thrust(loads, b.n_balls, b.ball_diameter, b.pitch_diameter, b.inner_conformity,
                                          b.outer_conformity, b.contact_angle, b.reduced_modulus)
    ki = hertz.load_deflection_constant(*b.curvature("inner", r.contact_angle), b.reduced_modulus)
    ke = hertz.load_deflection_constant(*b.curvature("outer", r.contact_angle), b.reduced_modulus)
    # each contact carries Q; the ring carries F_a
    assert_allclose(ki * r.deflection_inner**1.5, r.ball_load, rtol=1e-12)
    assert_allclose(ke * r.deflection_outer**1.5, r.ball_load, rtol=1e-12)
    assert_allclose(b.n_balls * r.ball_load * np.sin(r.contact_angle), loads, rtol=1e-12)
    # geometry: the groove centres are B D + delta_i + delta_e apart along the contact line
    bd = b.groove_distance
    total = bd + r.deflection_inner + r.deflection_outer
    assert_allclose(total * np.cos(r.contact_angle), bd * np.cos(b.contact_angle), rtol=1e-9)
    assert_allclose(total * np.sin(r.contact_angle) - bd * np.sin(b.contact_angle), r.axial_displacement, rtol=1e-9)
    assert np.all(np.diff(r.contact_angle) > 0)


def test_static_thrust_angle_of_the_218_bearing():
    """Spec 004 section 7.1/7.2, static column (K constant 2.15e5 N/mm^1.5 as in spec 004 eq. 16)."""
    b = catalog.get("B218")
    ep = 2.15e5 * 1e6 * 3 / 2**1.5  # Pa: the E' for which K = 2.15e5 Sigma rho^-1/2 delta*^-3/2 in N, mm
    loads = np.array([2.5, 5, 10, 20, 30, 45]) * 1e3
    r = static.contact_angle_under_thrust(loads, b.n_balls, b.ball_diameter, b.pitch_diameter, b.inner_conformity,
                                          b.outer_conformity, b.contact_angle, ep)
    assert_allclose(np.degrees(r.contact_angle), [40.421, 40.662, 41.036, 41.609, 42.070, 42.653], atol=1e-3)
    assert_allclose(r.axial_displacement * 1e6, [9.96, 15.72, 24.73, 38.72, 50.20, 64.91], atol=1e-2)


@pytest.mark.parametrize("kwargs, match", [
    ({"axial_load": 0.0}, r"axial_load must be > 0 \[N\], got 0.0"),
    ({"axial_load": -1.0}, r"axial_load must be > 0"),
    ({"free_angle": 0.0}, r"free_angle must be in \(0, 90\) \[deg\], got 0.0"),
    ({"free_angle": math.radians(95)}, r"free_angle must be in \(0, 90\) \[deg\], got 95"),
    ({"force_characteristic": 0.0}, r"force_characteristic must be > 0"),
])
def test_bad_inputs_name_parameter_and_range(kwargs, match):
    args = {"axial_load": 2 * KGF, "force_characteristic": CS, "free_angle": A0}
    args.update(kwargs)
    with pytest.raises(InputError, match=match):
        static.operating_contact_angle(**args)


def test_non_convergence_raises_with_state():
    with pytest.raises(ConvergenceError) as info:
        static.operating_contact_angle(np.array([2.0, 5.0]) * KGF, CS, A0, max_iter=1, xtol=0.0, ftol_percent=0.0)
    err = info.value
    assert err.iterations == 1 and np.shape(err.estimate) == (2,) and np.all(np.isfinite(err.residual))
    assert isinstance(err, RuntimeError)


def test_stand_analysis_needs_an_angle_and_tabulated_hertz():
    with pytest.raises(InputError, match=r"contact_angle must be in \(0, 90\)"):
        static.stand_analysis(catalog.get("4-1006095").replace(contact_angle=0.0), 2 * KGF)
    with pytest.raises(InputError, match="no tabulated Hertz coefficients"):
        static.stand_analysis(catalog.get("B218"), 2e3, hertz="table")
    with pytest.raises(InputError, match="hertz must be one of"):
        static.stand_analysis(catalog.get("B218"), 2e3, hertz="chart")
    with pytest.raises(InputError, match="n_balls of '1000095' is not known"):
        static.stand_analysis(catalog.get("1000095"), 2e3)


def test_stand_constants_exact_hertz_matches_hertz_module():
    c = static.stand_constants(7, 2e-3, 8.7355e-3, 0.525, 0.58, A0)
    ref = hertz.coefficients(geometry.raceway_curvature(2e-3, 8.7355e-3, 0.525, A0, race="inner").curvature_difference)
    assert c.hertz_inner.delta_star == pytest.approx(ref.delta_star, rel=1e-15)
    assert_allclose([c.hertz_inner.delta_star, c.hertz_outer.delta_star], [0.62834, 0.85245], atol=5e-6)

"""Properties of the static contact angle under pure thrust: the load-angle relation of spec 000 section 6,
its first approximation, the axial displacement, and the solution with the stiffness at the loaded angle
(spec 004 section 5.3)."""

import math

import numpy as np
from numpy.testing import assert_allclose

from bearinglab import catalog, hertz, stand, static
from bearinglab.units import KGF

A0 = math.radians(12.0)
CS = 7792.357 * KGF


def test_first_approximation_is_root_of_quadratic_truncation():
    t = np.geomspace(1e-8, 1e-2, 20)
    a = stand.series_coefficients(t, A0)
    x0 = static.first_approximation(t, A0)
    assert_allclose(a[0] + a[1] * x0 + a[2] * x0**2, 0.0, atol=1e-15)
    assert_allclose(x0, a[1] / (2 * a[2]) * (np.sqrt(1 - 4 * a[0] * a[2] / a[1] ** 2) - 1), rtol=1e-12)


def test_axial_displacement_consistent_with_geometry():
    # tan a = tan a0 + xi_a / cos a0 and cos a0 / cos a = sqrt(cos^2 a0 + (sin a0 + xi_a)^2)
    alpha = stand.operating_contact_angle(np.array([1, 2, 5]) * KGF, CS, A0)
    xa = static.axial_displacement_ratio(alpha, A0)
    assert_allclose(np.cos(A0) / np.cos(alpha), np.sqrt(np.cos(A0) ** 2 + (np.sin(A0) + xa) ** 2), rtol=1e-13)


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


def test_single_precision_angles_are_evaluated_in_double_precision():
    # float32 inputs (e.g. from a measurement file) are converted, not computed in float32: eq. (1) is steep
    # near alpha0 and single precision would lose five digits of the load there
    a32, a0_32 = np.array([0.25, 0.4, 1.2], dtype=np.float32), np.float32(0.2)
    a64, a0_64 = a32.astype(float), float(a0_32)
    for got, ref in ((static.thrust_from_angle(a32, 1e4, a0_64), static.thrust_from_angle(a64, 1e4, a0_64)),
                     (static.thrust_from_angle(a64, 1e4, a0_32), static.thrust_from_angle(a64, 1e4, a0_64)),
                     (static.axial_displacement_ratio(a32, a0_64), static.axial_displacement_ratio(a64, a0_64)),
                     (static.axial_displacement_ratio(a64, a0_32), static.axial_displacement_ratio(a64, a0_64))):
        assert got.dtype == np.float64 and np.array_equal(got, ref)

"""Properties of the high-speed quasi-static model (spec 004): constants, kinematics, Jacobian, limits,
equilibrium at the solution, the paper's claims (section 8) over grids of loads and speeds, failures."""

import math
import warnings

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from numpy.testing import assert_allclose

from bearinglab import bearing, catalog, geometry, hertz, kinematics, quasistatic, static
from bearinglab.errors import ConvergenceError, InputError, ValidityWarning
from bearinglab.units import MM, RPM

B218 = catalog.get("B218")
GEO = quasistatic._bearing_args(B218)  # (Z, D, d_m, f_i, f_e, alpha0, E', rho) of the 218 bearing, steel
DEG = math.pi / 180.0
FAST = settings(max_examples=30, deadline=None)

loads = st.floats(2.5e3, 45e3)
speeds = st.floats(3000.0, 15000.0)


def _solve(fa, n_rpm, **kw):
    kw.setdefault("friction_limit", np.inf)
    return quasistatic.contact_angles(fa, np.asarray(n_rpm) * RPM, *GEO, **kw)


def _unknowns(s):
    """(X1, X2, delta_i, delta_e, delta_a) / D of a state, from its outputs."""
    _z, d, _dm, _fi, fo, _a0, _ep, _rho = GEO
    le = (fo - 0.5) * d + s.deflection_outer
    return np.stack([le * np.sin(s.contact_angle_outer), le * np.cos(s.contact_angle_outer), s.deflection_inner,
                     s.deflection_outer, s.axial_displacement], axis=-1) / d


# --------------------------------------------------------------------------- constants of eqs. (8), (12)
def test_printed_constants_from_steel_density():
    """F_c = m (d_m/2) w_m^2 and M_g = (m D^2/10) w_R w_m sin(beta) in N, mm, rpm.

    At 7850 kg/m^3 the centrifugal constant is 2.2537e-11, not the printed 2.26e-11 (0.28 % apart; the
    printed value needs 7872 kg/m^3), and the gyroscopic one 4.5074e-12: the paper's 4.5e-12 to its digits,
    Harris's 4.47e-12 needs 7785 kg/m^3. No single density gives both of Harris's constants.
    """
    c = quasistatic.printed_constants(7850.0)
    assert c.centrifugal == pytest.approx(2.2537e-11, abs=5e-16)
    assert c.gyroscopic == pytest.approx(4.5074e-12, abs=5e-17)
    assert round(c.gyroscopic, 13) == quasistatic.PAPER_GYROSCOPIC_CONSTANT
    assert round(c.centrifugal, 13) != quasistatic.HARRIS_CENTRIFUGAL_CONSTANT  # 2.25e-11 to the printed digits
    rho_fc = 7850.0 * quasistatic.HARRIS_CENTRIFUGAL_CONSTANT / c.centrifugal
    rho_mg = 7850.0 * quasistatic.HARRIS_GYROSCOPIC_CONSTANT / c.gyroscopic
    assert rho_fc == pytest.approx(7872.0, abs=0.5)
    assert rho_mg == pytest.approx(7785.0, abs=0.5)
    assert quasistatic.printed_constants(rho_fc).centrifugal == pytest.approx(2.26e-11, rel=1e-12)


@FAST
@given(rho=st.floats(2000.0, 16000.0), d_mm=st.floats(1.0, 50.0), ratio=st.floats(2.5, 12.0),
       n_m=st.floats(1.0, 3e4), n_b=st.floats(1.0, 2e5), beta=st.floats(0.0, 1.5))
def test_dynamics_equal_the_printed_forms(rho, d_mm, ratio, n_m, n_b, beta):
    """Eqs. (8) and (12) in N, mm, rpm with the constants of the density (any ball material)."""
    d, dm = d_mm * MM, d_mm * ratio * MM
    mass = rho * math.pi * d**3 / 6.0
    c = quasistatic.printed_constants(rho)
    fc = quasistatic.centrifugal_force(n_m * RPM, mass, dm)
    mg = quasistatic.gyroscopic_moment(n_b * RPM, n_m * RPM, beta, mass, d)
    assert fc == pytest.approx(c.centrifugal * (dm / MM) * d_mm**3 * n_m**2, rel=1e-12)
    assert mg / MM == pytest.approx(c.gyroscopic * d_mm**5 * n_b * n_m * math.sin(beta), rel=1e-12, abs=1e-300)


def test_ceramic_balls_lower_the_centrifugal_force():
    steel = _solve(10e3, 15000.0)
    z, d, dm, fi, fo, a0, ep, _rho = GEO
    ceramic = quasistatic.contact_angles(10e3, 15000 * RPM, z, d, dm, fi, fo, a0, ep, bearing.SILICON_NITRIDE.density)
    # F_c = m (d_m/2) w_m^2 with the ceramic mass
    assert ceramic.centrifugal_force == pytest.approx(
        bearing.SILICON_NITRIDE.density * math.pi * d**3 / 6 * dm / 2 * ceramic.cage_speed**2, rel=1e-12)
    assert ceramic.centrifugal_force < 0.45 * steel.centrifugal_force
    # lighter balls: the angles spread less
    assert ceramic.contact_angle_inner < steel.contact_angle_inner
    assert ceramic.contact_angle_outer > steel.contact_angle_outer


# --------------------------------------------------------------------------- kinematics
@FAST
@given(a=st.floats(0.05, 1.5), gamma_over_cos=st.floats(0.05, 0.4))
def test_attitude_angle_paper_form_equals_harris_form(a, gamma_over_cos):
    d, dm = gamma_over_cos * 0.1, 0.1  # D/d_m = gamma_over_cos
    beta = quasistatic.attitude_angle(1.0, a, d, dm)
    gamma_e = d * math.cos(a) / dm
    assert math.tan(beta) == pytest.approx(math.sin(a) * math.cos(a) / (math.cos(a) ** 2 + gamma_e), rel=1e-12)


@FAST
@given(a=st.floats(0.0, 1.4), ratio=st.floats(2.5, 12.0), w=st.floats(1.0, 5000.0))
def test_ball_speeds_reduce_to_pure_rolling_when_angles_are_equal(a, ratio, w):
    """alpha_i = alpha_e = beta = alpha: the classical cage speed and ball spin (kinematics module)."""
    d, dm = 0.01, 0.01 * ratio
    s = quasistatic.ball_speeds(w, a, a, a, d, dm)
    assert s.cage_speed == pytest.approx(kinematics.cage_speed(w, d, dm, a), rel=1e-12)
    assert s.ball_spin_speed == pytest.approx(kinematics.ball_spin_frequency(w, d, dm, a), rel=1e-12)


def test_ball_speeds_of_section_7():
    s = quasistatic.ball_speeds(10000 * RPM, 49.308 * DEG, 32.514 * DEG, 27.772 * DEG, 22.23e-3, 125.3e-3)
    assert s.cage_speed / RPM == pytest.approx(4518.0, abs=0.5)
    assert s.ball_spin_speed / RPM == pytest.approx(29376, abs=5)


# --------------------------------------------------------------------------- Hertz through the tables
@settings(max_examples=15, deadline=None)
@given(d_mm=st.floats(2.0, 40.0), ratio=st.floats(3.0, 12.0), fi=st.floats(0.505, 0.58), fo=st.floats(0.505, 0.58))
def test_interpolated_hertz_equals_the_exact_module(d_mm, ratio, fi, fo):
    """The Chebyshev tables reproduce hertz.load_deflection_constant / hertz.coefficients to 5e-12.

    Up to 1e-13 for usual conformities; at f = 0.505 and D/d_m = 1/3 (kappa ~ 17) the exact module's own
    result scatters by ~1e-12 (its iterative inversion), and more nodes do not reduce the difference."""
    d, dm, ep = d_mm * MM, d_mm * ratio * MM, 2.28e11
    model, _ = quasistatic._prepare(1.0, 10, d, dm, fi, fo, 0.5, ep, 7850.0, "outer", 1, "mass")
    angles = np.linspace(0.0, math.pi / 2, 37)
    k = quasistatic.contact_stiffness(angles, angles, d, dm, fi, fo, ep)
    gid = np.zeros(angles.size, dtype=int)
    assert_allclose(quasistatic._k(model.t_inner, gid, np.cos(angles))[0], k.inner, rtol=5e-12)
    assert_allclose(quasistatic._k(model.t_outer, gid, np.cos(angles))[0], k.outer, rtol=5e-12)
    exact = hertz.coefficients(geometry.raceway_curvature(d, dm, fo, angles, race="outer").curvature_difference)
    table = quasistatic._hertz_coefficients(model.t_outer, gid, np.cos(angles))
    for name in ("a_star", "b_star", "delta_star", "ellipticity"):
        assert_allclose(getattr(table, name), getattr(exact, name), rtol=5e-12, err_msg=name)


def test_maximum_pressure_equals_direct_hertz():
    s = _solve(20e3, 10000.0)
    _z, d, dm, fi, _fo, _a0, ep, _rho = GEO
    inner = geometry.raceway_curvature(d, dm, fi, s.contact_angle_inner, race="inner")
    pc = hertz.point_contact(s.ball_load_inner, inner.curvature_sum, inner.curvature_difference, ep)
    assert s.max_pressure_inner == pytest.approx(pc.p_max, rel=1e-12)
    assert s.deflection_inner == pytest.approx(pc.delta, rel=1e-10)


# --------------------------------------------------------------------------- residual and Jacobian
@settings(max_examples=12, deadline=None)
@given(fa=loads, n=st.floats(0.0, 15000.0), shift=st.lists(st.floats(-0.02, 0.02), min_size=5, max_size=5))
def test_jacobian_matches_central_differences(fa, n, shift):
    s = _solve(fa, n)
    v = _unknowns(s) * (1.0 + np.array(shift) * np.array([1, 1, 0.5, 0.5, 0.5]))
    r = quasistatic.residual(v, fa, n * RPM, *GEO)
    h = 1e-7 * np.maximum(np.abs(v), 1e-4)
    fd = np.empty((5, 5))
    for k in range(5):
        e = np.zeros(5)
        e[k] = h[k]
        fd[:, k] = (quasistatic.residual(v + e, fa, n * RPM, *GEO).residual
                    - quasistatic.residual(v - e, fa, n * RPM, *GEO).residual) / (2 * h[k])
    scale = np.abs(fd).max(axis=1, keepdims=True)
    assert_allclose(r.jacobian / scale, fd / scale, atol=2e-6)


def test_residual_checks_its_unknowns():
    with pytest.raises(InputError, match="last axis of length 5"):
        quasistatic.residual(np.zeros(4), 1e3, 0.0, *GEO)


@FAST
@given(fa=loads, n=st.floats(0.0, 15000.0))
def test_equations_3_to_7_hold_at_the_solution(fa, n):
    """Re-check the solution with the public functions: geometry (3)-(4), ball (5)-(6), ring (7)."""
    s = _solve(fa, n)
    z, d, dm, fi, fo, a0, ep, rho = GEO
    assert s.converged and s.residual < 1e-9
    assert np.all(np.abs(quasistatic.residual(_unknowns(s), fa, n * RPM, *GEO).residual) < 1e-9)
    ai, ae, qi, qe = s.contact_angle_inner, s.contact_angle_outer, s.ball_load_inner, s.ball_load_outer
    bd = (fi + fo - 1.0) * d
    li, le = (fi - 0.5) * d + s.deflection_inner, (fo - 0.5) * d + s.deflection_outer
    # the ball centre lies on both lines of contact: (A_x, A_z) = L_i (sin, cos)(a_i) + L_e (sin, cos)(a_e)
    assert li * math.sin(ai) + le * math.sin(ae) == pytest.approx(bd * math.sin(a0) + s.axial_displacement, abs=1e-15)
    assert li * math.cos(ai) + le * math.cos(ae) == pytest.approx(bd * math.cos(a0), abs=1e-15)
    k = quasistatic.contact_stiffness(ai, ae, d, dm, fi, fo, ep)
    assert qi == pytest.approx(k.inner * s.deflection_inner**1.5, rel=1e-12)
    assert qe == pytest.approx(k.outer * s.deflection_outer**1.5, rel=1e-12)
    mass = rho * math.pi * d**3 / 6.0
    beta = quasistatic.attitude_angle(ai, ae, d, dm)
    sp = quasistatic.ball_speeds(n * RPM, ai, ae, beta, d, dm)
    fc = quasistatic.centrifugal_force(sp.cage_speed, mass, dm)
    mg = quasistatic.gyroscopic_moment(sp.ball_spin_speed, sp.cage_speed, beta, mass, d)
    assert (fc, mg, beta) == pytest.approx((s.centrifugal_force, s.gyroscopic_moment, s.attitude_angle), rel=1e-12)
    scale = fa / z
    assert abs(qi * math.sin(ai) - qe * math.sin(ae) - 2 * mg / d * math.cos(ae)) < 1e-9 * scale  # (5)
    assert abs(qi * math.cos(ai) - qe * math.cos(ae) + 2 * mg / d * math.sin(ae) + fc) < 1e-9 * scale  # (6)
    assert abs(z * qi * math.sin(ai) - fa) < 1e-9 * fa  # (7), lambda_i = 0


@FAST
@given(fa=loads, n=st.floats(500.0, 15000.0))
def test_inner_raceway_control_satisfies_its_equations(fa, n):
    s = _solve(fa, n, raceway_control="inner", on_failure="flag")
    if not s.converged:  # at high speed the thrust cannot carry the friction at the inner contact
        assert s.status in ("inner_contact_lost", "no_convergence")
        assert math.isnan(s.contact_angle_inner)
        return
    z, d = GEO[0], GEO[1]
    ai, ae, qi, qe, mg = (s.contact_angle_inner, s.contact_angle_outer, s.ball_load_inner, s.ball_load_outer,
                          s.gyroscopic_moment)
    beta = quasistatic.attitude_angle(ai, ae, d, GEO[2], raceway_control="inner")
    assert s.attitude_angle == pytest.approx(beta, rel=1e-12)
    assert abs(qi * math.sin(ai) - qe * math.sin(ae) + 2 * mg / d * math.cos(ai)) < 1e-9 * fa / z
    assert abs(z * (qi * math.sin(ai) + 2 * mg / d * math.cos(ai)) - fa) < 1e-9 * fa
    assert s.friction_coefficient == pytest.approx(2 * mg / (d * qi), rel=1e-12)


# --------------------------------------------------------------------------- limits, consistency
@pytest.mark.parametrize("ball_material", [bearing.STEEL, bearing.SILICON_NITRIDE], ids=["steel", "Si3N4"])
def test_zero_speed_limit_is_the_static_solution(ball_material):
    """At n = 0 (and as n -> 0) both angles equal the static angle of the test-stand method to 1e-9 rad."""
    b = B218.replace(ball_material=ball_material, contact_angle=B218.contact_angle)
    fa = np.geomspace(10.0, 1e5, 25)
    ref = static.contact_angle_under_thrust(fa, *quasistatic._bearing_args(b)[:7])
    for n_rpm in (0.0, 1e-3):
        s = quasistatic.high_speed_analysis(b, fa, n_rpm * RPM)
        assert np.all(s.converged)
        assert np.abs(s.contact_angle_inner - ref.contact_angle).max() < 1e-9
        assert np.abs(s.contact_angle_outer - ref.contact_angle).max() < 1e-9
        assert_allclose(s.static_contact_angle, ref.contact_angle, rtol=0, atol=1e-15)
        assert_allclose(s.axial_displacement, ref.axial_displacement, rtol=1e-9)
        assert_allclose(s.ball_load_inner, ref.ball_load, rtol=1e-9)
    zero = quasistatic.high_speed_analysis(b, fa, 0.0)
    assert np.all(zero.centrifugal_force == 0) and np.all(zero.gyroscopic_moment == 0)
    assert np.all(zero.method == "static")


def test_continuation_path_does_not_change_the_solution():
    fa = np.array([200.0, 2.5e3, 10e3, 45e3])[:, None]
    n = np.array([1000.0, 6000.0, 15000.0, 30000.0])
    a = _solve(fa, n)
    b = _solve(fa, n, speed_step=1500 * RPM, max_iter=400)
    for name in ("contact_angle_inner", "contact_angle_outer"):
        assert np.abs(getattr(a, name) - getattr(b, name)).max() < 1e-10


def test_scalar_and_array_results_agree():
    fa, n = np.array([5e3, 20e3]), np.array([6000.0, 15000.0])
    arr = _solve(fa[:, None], n[None, :])
    assert arr.contact_angle_inner.shape == (2, 2)
    one = _solve(20e3, 6000.0)
    assert np.ndim(one.contact_angle_inner) == 0 and isinstance(one.status, str)
    for name in ("contact_angle_inner", "contact_angle_outer", "axial_displacement", "gyroscopic_moment"):
        assert getattr(one, name) == pytest.approx(getattr(arr, name)[1, 0], rel=1e-12, abs=1e-18)


@pytest.mark.parametrize("n", [0.0, 6000.0, 15000.0])
def test_axial_stiffness_is_the_slope_of_the_displacement(n):
    fa, h = 20e3, 1.0
    s = _solve(np.array([fa - h, fa, fa + h]), n)
    slope = (2 * h) / (s.axial_displacement[2] - s.axial_displacement[0])
    assert s.axial_stiffness[1] == pytest.approx(slope, rel=1e-6)
    assert s.axial_stiffness[1] > 0


def test_characteristic_frequencies_at_speed():
    s = _solve(20e3, 10000.0)
    z = GEO[0]
    assert s.bpfo == pytest.approx(z * s.cage_speed, rel=1e-14)
    assert s.bpfi == pytest.approx(z * (10000 * RPM - s.cage_speed), rel=1e-14)
    # the operating angles move the cage speed away from the pure-rolling value at the static angle
    nominal = kinematics.cage_speed(10000 * RPM, GEO[1], GEO[2], s.static_contact_angle)
    assert abs(s.cage_speed / nominal - 1) > 1e-3


# --------------------------------------------------------------------------- the paper's claims (section 8)
@FAST
@given(fa=loads, n1=speeds, n2=speeds)
def test_inner_angle_rises_and_outer_falls_with_speed(fa, n1, n2):
    if abs(n1 - n2) < 50:
        return
    lo, hi = sorted((n1, n2))
    s = _solve(fa, np.array([0.0, lo, hi]))
    assert s.contact_angle_inner[0] < s.contact_angle_inner[1] < s.contact_angle_inner[2]
    assert s.contact_angle_outer[0] > s.contact_angle_outer[1] > s.contact_angle_outer[2]
    assert np.all(s.contact_angle_inner[1:] > s.contact_angle_outer[1:])  # alpha_i > alpha_e at speed


@FAST
@given(fa=loads, n=speeds)
def test_increments_from_the_static_angle(fa, n):
    """Delta alpha_i - Delta alpha_e < 0, the outer increment above the inner one (Fig. 4), so the solution
    lies below the line alpha_i + alpha_e = 2 alpha_s (the paper's search triangle)."""
    s = _solve(fa, n)
    d_i = s.contact_angle_inner - s.static_contact_angle
    d_e = s.static_contact_angle - s.contact_angle_outer
    assert d_i > 0 and d_e > 0
    assert d_i - d_e < 0
    assert s.contact_angle_inner + s.contact_angle_outer < 2 * s.static_contact_angle


def test_reversed_sign_breaks_the_increment_claim():
    """Section 4/8: with the reversed gyroscopic sign Delta alpha_i - Delta alpha_e < 0 fails at >= 10 kN,
    3000 rpm and >= 20 kN, 6000 rpm and at 45 kN, 10 000 rpm; it holds with the physical sign."""
    fa = np.array([10e3, 20e3, 45e3])
    for sign, expect in ((1, False), (-1, True)):
        s = _solve(fa[:, None], np.array([3000.0, 6000.0, 10000.0]), gyroscopic_sign=sign)
        broken = (s.contact_angle_inner - s.static_contact_angle) > (s.static_contact_angle - s.contact_angle_outer)
        if expect:
            assert broken[:, 0].all() and broken[1:, 1].all() and broken[2, 2]
        else:
            assert not broken.any()


@FAST
@given(f1=loads, f2=loads, n=speeds)
def test_increments_shrink_and_approach_each_other_as_thrust_grows(f1, f2, n):
    if abs(f1 - f2) < 100:
        return
    lo, hi = sorted((f1, f2))
    s = _solve(np.array([lo, hi]), n)
    d_i = s.contact_angle_inner - s.static_contact_angle
    d_e = s.static_contact_angle - s.contact_angle_outer
    assert d_i[1] < d_i[0] and d_e[1] < d_e[0]
    assert abs(d_i[1] - d_e[1]) < abs(d_i[0] - d_e[0])


@FAST
@given(fa=loads, n1=speeds, n2=speeds)
def test_increments_grow_with_speed(fa, n1, n2):
    if abs(n1 - n2) < 50:
        return
    lo, hi = sorted((n1, n2))
    s = _solve(fa, np.array([lo, hi]))
    d_i = s.contact_angle_inner - s.static_contact_angle
    d_e = s.static_contact_angle - s.contact_angle_outer
    assert d_i[1] > d_i[0] and d_e[1] > d_e[0]


def test_axial_displacement_negative_at_low_thrust_and_high_speed():
    fa = np.array([2.5e3, 5e3])[:, None]
    s = _solve(fa, np.array([6000.0, 10000.0, 15000.0]))
    assert np.all(s.axial_displacement < 0)
    assert np.all(_solve(fa, 0.0).axial_displacement > 0)


def test_thrust_for_positive_displacement_grows_with_speed():
    n = np.array([0.0, 2000.0, 4000.0, 8000.0, 12000.0, 16000.0])
    f0 = quasistatic.zero_displacement_thrust(n * RPM, *GEO)
    assert f0[0] == 0.0
    assert np.all(np.diff(f0) > 0)
    below = _solve(0.97 * f0[1:], n[1:])
    above = _solve(1.03 * f0[1:], n[1:])
    assert np.all(below.axial_displacement < 0) and np.all(above.axial_displacement > 0)


@pytest.mark.parametrize("fa,n", [(2.5e3, 3000.0), (10e3, 15000.0), (45e3, 6000.0), (2e3, 20000.0)])
def test_search_triangle_holds_the_solution(fa, n):
    """Section 8, last row: restricting the search to alpha_i + alpha_e <= 2 alpha_s loses no solution."""
    a = _solve(fa, n, method="angle-iteration")
    b = _solve(fa, n)
    assert a.method == "search-triangle"
    assert abs(a.contact_angle_inner - b.contact_angle_inner) < 1e-6 * DEG
    assert abs(a.contact_angle_outer - b.contact_angle_outer) < 1e-6 * DEG


# --------------------------------------------------------------------------- the angle search
def test_angle_search_widens_to_the_quadrant_and_says_so():
    """With the reversed sign the solution leaves the triangle; the minimum there is not a root, the
    search covers the whole quadrant and finds the same root as Newton."""
    a = _solve(20e3, 3000.0, method="angle-iteration", gyroscopic_sign=-1)
    b = _solve(20e3, 3000.0, gyroscopic_sign=-1)
    assert a.method == "search-quadrant" and a.converged
    assert abs(a.contact_angle_inner - b.contact_angle_inner) < 1e-6 * DEG
    assert abs(a.contact_angle_outer - b.contact_angle_outer) < 1e-6 * DEG


def test_angle_residual_is_zero_at_the_newton_solution():
    s = _solve(np.array([5e3, 20e3]), 10000.0)
    r = quasistatic.angle_residual(s.contact_angle_inner, s.contact_angle_outer, s.axial_load, s.shaft_speed, *GEO)
    assert np.all(r.valid)
    assert np.all(np.abs(r.radial) < 1e-12) and np.all(np.abs(r.ring) < 1e-12)
    assert_allclose(r.axial_displacement, s.axial_displacement, rtol=1e-9)
    assert_allclose(r.ball_load_outer, s.ball_load_outer, rtol=1e-9)
    off = quasistatic.angle_residual(s.contact_angle_inner + 0.01, s.contact_angle_outer, s.axial_load,
                                     s.shaft_speed, *GEO)
    assert np.all(np.abs(off.radial) + np.abs(off.ring) > 1e-6)


def test_angle_search_without_a_root_fails_with_the_reason():
    """Inner-raceway control at 300 N and 15 000 rpm: the friction at the inner contact exceeds the thrust
    per ball, no (alpha_i, alpha_e) is a root."""
    s = _solve(np.array([300.0, 20e3]), 3000.0 * np.array([5.0, 1.0]), method="angle-iteration",
               raceway_control="inner", on_failure="flag")
    assert list(s.status) == ["search_not_root", "ok"]
    assert np.isnan(s.contact_angle_inner[0]) and np.isnan(s.axial_displacement[0])
    with pytest.raises(ConvergenceError, match="minimum of the contact-angle search is not a root"):
        _solve(300.0, 15000.0, method="angle-iteration", raceway_control="inner")


# --------------------------------------------------------------------------- failures and bad input
def test_thrust_too_small_for_the_speed():
    """Inner-raceway control: at low thrust the inner contact would need Q_i < 0 (the ball leaves it)."""
    s = _solve(np.array([300.0, 20e3]), 15000.0 * np.array([1.0, 0.2]), raceway_control="inner", on_failure="flag")
    assert list(s.status) == ["inner_contact_lost", "ok"]
    assert not s.converged[0] and np.isnan(s.contact_angle_outer[0]) and np.isnan(s.residual[0])
    with pytest.raises(ConvergenceError, match="leaves the inner raceway.*thrust too small for the speed"):
        _solve(300.0, 15000.0, raceway_control="inner")


def test_angle_leaving_the_quadrant():
    """A 60 deg bearing at 100 N: at 3000 rpm the inner contact angle would pass 90 deg."""
    z, d, dm, fi, fo, _a0, ep, rho = GEO
    args = (z, d, dm, fi, fo, 60 * DEG, ep, rho)
    s = quasistatic.contact_angles(100.0, np.array([1000.0, 3000.0]) * RPM, *args, on_failure="flag",
                                   friction_limit=np.inf)
    assert list(s.status) == ["ok", "angle_out_of_range"]
    assert s.contact_angle_inner[0] > 85 * DEG
    with pytest.raises(ConvergenceError, match=r"a contact angle leaves \(0, 90\) deg"):
        quasistatic.contact_angles(100.0, 3000 * RPM, *args)


def test_non_convergence_raises_or_flags():
    with pytest.raises(ConvergenceError, match="no convergence.*F_a = 2500 N, 15000 rpm") as err:
        _solve(2.5e3, 15000.0, max_iter=2)
    assert err.value.iterations == 2
    s = _solve(np.array([2.5e3, 45e3]), np.array([15000.0, 0.0]), max_iter=2, on_failure="flag")
    assert list(s.status) == ["no_convergence", "ok"]
    assert list(s.converged) == [False, True]
    assert np.isnan(s.ball_load_inner[0]) and np.isfinite(s.ball_load_inner[1])


def test_one_failed_case_does_not_stop_a_sweep():
    fa = np.array([300.0, 5e3, 20e3])
    n = np.array([3000.0, 15000.0]) * RPM
    s = quasistatic.sweep(B218, fa, n, raceway_control="inner", friction_limit=np.inf)
    assert s.status.shape == (3, 2)
    assert s.status[0, 1] == "inner_contact_lost"
    ok = s.converged
    assert ok.sum() >= 3
    for i, j in zip(*np.nonzero(ok)):
        one = quasistatic.high_speed_analysis(B218, fa[i], n[j], raceway_control="inner", friction_limit=np.inf)
        assert one.contact_angle_inner == pytest.approx(s.contact_angle_inner[i, j], abs=1e-12)


@pytest.mark.parametrize("kwargs,match", [
    ({"shaft_speed": -100.0}, r"shaft_speed must be >= 0 and finite \[rpm\], got -954.93 rpm.*magnitude"),
    ({"axial_load": 0.0}, r"axial_load must be > 0 \[N\]"),
    ({"free_angle": 0.0}, r"free_angle must be in \(0, 90\) \[deg\]"),
    ({"free_angle": math.pi / 2}, r"free_angle must be in \(0, 90\) \[deg\]"),
    ({"pitch_diameter": 10e-3}, r"pitch_diameter must be > ball_diameter"),
    ({"density": -1.0}, r"density must be > 0"),
    ({"method": "brent"}, r"method must be one of \['newton', 'angle-iteration'\]"),
    ({"raceway_control": "cage"}, r"raceway_control must be one of \['outer', 'inner'\]"),
    ({"gyroscopic_sign": 0}, r"gyroscopic_sign must be \+1"),
    ({"constants": "jones"}, r"constants must be one of \['mass', 'harris', 'paper'\]"),
    ({"constants": (1.0, -1.0)}, r"C_c and C_g must be >= 0"),
    ({"on_failure": "ignore"}, r"on_failure must be one of \['raise', 'flag'\]"),
    ({"speed_step": 0.0}, r"speed_step must be > 0"),
])
def test_bad_input_names_parameter_rule_and_value(kwargs, match):
    z, d, dm, fi, fo, a0, ep, rho = GEO
    args = {"axial_load": 1e4, "shaft_speed": 1000.0, "n_balls": z, "ball_diameter": d, "pitch_diameter": dm,
                "inner_conformity": fi, "outer_conformity": fo, "free_angle": a0, "reduced_modulus": ep, "density": rho}
    args.update(kwargs)
    with pytest.raises(InputError, match=match):
        quasistatic.contact_angles(**args)


def test_bearing_without_a_usable_angle():
    with pytest.raises(InputError, match="contact_angle of '6205-2RS' must be in \\(0, 90\\)"):
        quasistatic.high_speed_analysis(catalog.get("6205-2RS").replace(inner_conformity=0.52, outer_conformity=0.52),
                                        1e3, 100.0)
    with pytest.raises(InputError, match="n_balls of '1000095' is not known"):
        quasistatic.high_speed_analysis(catalog.get("1000095"), 1e3, 100.0)


def test_friction_warning_when_outer_control_needs_too_much_friction():
    with pytest.warns(ValidityWarning, match=r"1 of 1 cases need a friction coefficient above 0.05 .*0.0639 at F_a = 20000 N, 10000 rpm"):
        quasistatic.high_speed_analysis(B218, 20e3, 10000 * RPM, constants="harris", friction_limit=0.05)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        s = quasistatic.high_speed_analysis(B218, 20e3, 10000 * RPM, constants="harris")
    assert s.friction_coefficient == pytest.approx(2 * s.gyroscopic_moment / (B218.ball_diameter * s.ball_load_outer))


def test_result_table_units():
    s = quasistatic.sweep(B218, [20e3], [10000 * RPM], constants="harris")
    t = quasistatic.result_table(s)
    assert t["axial_load_kN"][0] == 20.0 and t["speed_rpm"][0] == 10000.0
    assert t["contact_angle_inner_deg"][0] == pytest.approx(math.degrees(s.contact_angle_inner[0, 0]))
    assert t["gyroscopic_moment_Nmm"][0] == pytest.approx(s.gyroscopic_moment[0, 0] * 1e3)
    assert t["axial_displacement_mm"][0] == pytest.approx(s.axial_displacement[0, 0] * 1e3)
    assert t["status"][0] == "ok" and t["converged"][0]


def test_bench_solvers_agree_on_a_small_map(load_bench):
    bench = load_bench("high_speed")
    fa, n = bench.grid(4, 3)
    state = bench.batched(fa, n)
    ref = bench.baseline(fa.ravel(), n.ravel())
    assert np.all(state.converged)
    assert np.abs(state.contact_angle_inner.ravel() - ref[:, 0]).max() < 1e-9
    assert np.abs(state.contact_angle_outer.ravel() - ref[:, 1]).max() < 1e-9


def test_sweep_in_chunks_reports_progress_and_equals_one_call():
    calls = []
    fa, n = [5e3, 20e3], np.array([0.0, 3000.0, 6000.0, 15000.0]) * RPM
    a = quasistatic.sweep(B218, fa, n, chunk_size=3, progress=lambda done, total: calls.append((done, total)))
    b = quasistatic.sweep(B218, fa, n)
    assert calls == [(3, 8), (6, 8), (8, 8)]
    assert a.contact_angle_inner.shape == (2, 4)
    assert_allclose(a.contact_angle_inner, b.contact_angle_inner, rtol=0, atol=1e-14)
    assert list(a.status.ravel()) == ["ok"] * 8


def test_free_angle_is_not_the_reference_of_the_increments():
    """Section 8: with alpha0 instead of alpha_s the claim "alpha_e < alpha0" is false at high thrust and
    low speed (45 kN, 3000 rpm: alpha_e = 42.30 deg > 40 deg), while alpha_e < alpha_s holds."""
    s = _solve(45e3, 3000.0)
    assert s.contact_angle_outer > GEO[5]
    assert s.contact_angle_outer < s.static_contact_angle


def test_several_bearings_in_one_call():
    """Geometry broadcasts too: two ball sizes (and so two Hertz tables) in one batched solve."""
    z, d, dm, fi, fo, a0, ep, rho = GEO
    balls = np.array([d, 0.8 * d])[:, None]
    both = quasistatic.contact_angles(np.array([5e3, 20e3]), 10000 * RPM, z, balls, dm, fi, fo, a0, ep, rho)
    assert both.contact_angle_inner.shape == (2, 2)
    for k in range(2):
        one = quasistatic.contact_angles(np.array([5e3, 20e3]), 10000 * RPM, z, balls[k, 0], dm, fi, fo, a0, ep, rho)
        assert_allclose(both.contact_angle_inner[k], one.contact_angle_inner, rtol=0, atol=1e-13)
        assert_allclose(both.axial_stiffness[k], one.axial_stiffness, rtol=1e-10)
    assert np.all(both.contact_angle_outer[1] > both.contact_angle_outer[0])  # lighter balls, less spread

"""Ball body forces and kinematics of the high-speed model (spec 004 eqs. 8-13): printed constants,
centrifugal force, gyroscopic moment, attitude angle, ball speeds, the required friction coefficient."""

import math

import pytest
from b218_cases import DEG, FAST, GEO, _solve
from hypothesis import given
from hypothesis import strategies as st

from bearinglab import bearing, kinematics, quasistatic
from bearinglab.units import MM, RPM


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


# --------------------------------------------------------------------------- raceway control
@FAST
@given(mg=st.floats(0.0, 10.0), q=st.floats(1.0, 1e5), d_mm=st.floats(1.0, 50.0))
def test_required_friction_coefficient_is_the_friction_force_over_the_load(mg, q, d_mm):
    """The outer contact carries the friction force 2 M_g / D that balances M_g (spec 004 section 4)."""
    d = d_mm * MM
    mu = quasistatic.required_friction_coefficient(mg, q, d)
    assert mu * q * d / 2 == pytest.approx(mg, rel=1e-12, abs=1e-300)


def test_friction_coefficient_is_a_deprecated_alias():
    with pytest.warns(DeprecationWarning, match="required_friction_coefficient"):
        old = quasistatic.friction_coefficient(2.72, 2835.4, 22.23e-3)
    assert old == quasistatic.required_friction_coefficient(2.72, 2835.4, 22.23e-3)

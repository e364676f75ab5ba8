"""The equilibrium equations of the high-speed model (spec 004 sections 3, 5.1): analytic Jacobian, the
equations at the solution, inner-raceway control."""

import math

import numpy as np
import pytest
from b218_cases import FAST, GEO, _solve, _unknowns, loads
from hypothesis import given, settings
from hypothesis import strategies as st
from numpy.testing import assert_allclose

from bearinglab import quasistatic
from bearinglab.errors import InputError
from bearinglab.units import RPM


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

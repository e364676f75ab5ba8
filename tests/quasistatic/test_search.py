"""The paper's contact-angle search (spec 004 section 5.2) against the Newton solution."""


import numpy as np
import pytest
from b218_cases import DEG, GEO, _solve
from numpy.testing import assert_allclose

from bearinglab import quasistatic
from bearinglab.errors import ConvergenceError


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

"""Contact stiffness of the high-speed model (spec 004 eqs. 14-21): the Chebyshev tables of the exact Hertz
solution and the pressures at the solution."""

import math

import numpy as np
import pytest
from b218_cases import GEO, _solve
from hypothesis import given, settings
from hypothesis import strategies as st
from numpy.testing import assert_allclose

from bearinglab import geometry, hertz, quasistatic
from bearinglab.quasistatic import contact, equations
from bearinglab.units import MM


# --------------------------------------------------------------------------- Hertz through the tables
@settings(max_examples=15, deadline=None)
@given(d_mm=st.floats(2.0, 40.0), ratio=st.floats(3.0, 12.0), fi=st.floats(0.505, 0.58), fo=st.floats(0.505, 0.58))
def test_interpolated_hertz_equals_the_exact_module(d_mm, ratio, fi, fo):
    """The Chebyshev tables reproduce hertz.load_deflection_constant / hertz.coefficients to 5e-12.

    Up to 1e-13 for usual conformities; at f = 0.505 and D/d_m = 1/3 (kappa ~ 17) the exact module's own
    result scatters by ~1e-12 (its iterative inversion), and more nodes do not reduce the difference."""
    d, dm, ep = d_mm * MM, d_mm * ratio * MM, 2.28e11
    model, _ = equations._prepare(1.0, 10, d, dm, fi, fo, 0.5, ep, 7850.0, "outer", 1, "mass")
    angles = np.linspace(0.0, math.pi / 2, 37)
    k = quasistatic.contact_stiffness(angles, angles, d, dm, fi, fo, ep)
    gid = np.zeros(angles.size, dtype=int)
    assert_allclose(contact._k(model.t_inner, gid, np.cos(angles))[0], k.inner, rtol=5e-12)
    assert_allclose(contact._k(model.t_outer, gid, np.cos(angles))[0], k.outer, rtol=5e-12)
    exact = hertz.coefficients(geometry.raceway_curvature(d, dm, fo, angles, race="outer").curvature_difference)
    table = contact._hertz_coefficients(model.t_outer, gid, np.cos(angles))
    for name in ("a_star", "b_star", "delta_star", "ellipticity"):
        assert_allclose(getattr(table, name), getattr(exact, name), rtol=5e-12, err_msg=name)


def test_maximum_pressure_equals_direct_hertz():
    s = _solve(20e3, 10000.0)
    _z, d, dm, fi, _fo, _a0, ep, _rho = GEO
    inner = geometry.raceway_curvature(d, dm, fi, s.contact_angle_inner, race="inner")
    pc = hertz.point_contact(s.ball_load_inner, inner.curvature_sum, inner.curvature_difference, ep)
    assert s.max_pressure_inner == pytest.approx(pc.p_max, rel=1e-12)
    assert s.deflection_inner == pytest.approx(pc.delta, rel=1e-10)

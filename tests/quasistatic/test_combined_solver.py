"""Issue 11 item 8: the numerical pieces of the 5-DOF ring Newton (quasistatic._ring and the outputs taken
from the solver's last evaluation), each against an independent computation, and bit-identity of the
solve for any batch, pass size or single case."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from numpy.testing import assert_allclose
from scipy.optimize import brentq

from bearinglab import catalog
from bearinglab.bearing import BallBearing, Material
from bearinglab.quasistatic import _ring, combined
from bearinglab.units import RPM

STEEL = Material("steel", 210e9, 0.3, 7850.0)
DEEP = BallBearing(n_balls=7, ball_diameter=11.5e-3, pitch_diameter=43.5e-3, inner_conformity=0.52,
                   outer_conformity=0.53, radial_clearance=10e-6, type="radial", ball_material=STEEL,
                   ring_material=STEEL)
TIGHT = BallBearing(n_balls=7, ball_diameter=11.5e-3, pitch_diameter=43.5e-3, inner_conformity=0.52,
                    outer_conformity=0.53, type="radial", ball_material=STEEL, ring_material=STEEL)
B218 = catalog.get("B218")


def _loads(n, seed=0, scale=(1500, 1500, 1500, 15.0, 15.0)):
    return np.random.default_rng(seed).normal(size=(n, 5)) * np.asarray(scale)


@settings(max_examples=20, deadline=None)
@given(seed=st.integers(0, 2**32 - 1), n=st.integers(1, 40))
def test_solve5_matches_lapack(seed, n):
    rng = np.random.default_rng(seed)
    m = rng.normal(size=(n, 5, 5))
    a = m @ m.transpose(0, 2, 1) + 0.5 * np.eye(5) + 0.3 * rng.normal(size=(n, 5, 5))  # not symmetric
    b = rng.normal(size=(n, 5))
    shift = rng.uniform(0.0, 1.0, size=n)
    ref = np.linalg.solve(a + shift[:, None, None] * np.eye(5), b[:, :, None])[:, :, 0]
    got = _ring.solve5(a, b, shift)
    cond = np.linalg.cond(a + shift[:, None, None] * np.eye(5))
    assert np.all(np.abs(got - ref) <= 1e-13 * cond[:, None] * np.abs(ref).max(axis=1, keepdims=True))


def test_solve5_hands_a_system_that_needs_pivoting_to_lapack():
    a = np.array([[[0.0, 1.0, 0, 0, 0], [1.0, 0.0, 0, 0, 0], [0, 0, 2.0, 0, 0], [0, 0, 0, 3.0, 0],
                   [0, 0, 0, 0, 4.0]], np.diag([1.0, 2.0, 3.0, 4.0, 5.0])])
    b = np.array([[1.0, 2.0, 4.0, 9.0, 16.0], [1.0, 2.0, 3.0, 4.0, 5.0]])
    assert_allclose(_ring.solve5(a, b), [[2.0, 1.0, 2.0, 3.0, 4.0], [1.0, 1.0, 1.0, 1.0, 1.0]], rtol=1e-15)


def test_rowwise_rounds_one_row_as_in_a_batch():
    rng = np.random.default_rng(3)
    a, b = rng.normal(size=(9, 7)), rng.normal(size=(7, 25))
    batch = _ring.rowwise(a, b)
    assert all(np.array_equal(_ring.rowwise(a[k:k + 1], b)[0], batch[k]) for k in range(9))
    assert_allclose(batch, a @ b, rtol=1e-14, atol=1e-14)


@pytest.mark.parametrize("bearing", [DEEP, TIGHT, B218])
def test_thrust_offset_matches_an_independent_root(bearing):
    """All balls at one angle: the axial groove-centre offset at which each carries P, against brentq on
    P = K_n (rho - A)^1.5 z / rho written out here (K_n a constant, as in the start)."""
    big_a = (bearing.inner_conformity + bearing.outer_conformity - 1.0) * bearing.ball_diameter
    a0 = bearing.contact_angle or 0.0
    g, kn = big_a * math.cos(a0), 8e9
    per_ball = np.logspace(-3, 5, 17)
    got = _ring.thrust_offset(per_ball, big_a, a0, g, kn)

    def carried(z, p):
        rho = math.hypot(z, g)
        return kn * max(rho - big_a, 0.0) ** 1.5 * z / rho - p

    z0 = big_a * math.sin(a0)
    ref = [brentq(carried, z0, z0 + bearing.ball_diameter, args=(p,), xtol=1e-22, rtol=1e-15) for p in per_ball]
    assert_allclose(got, ref, rtol=1e-8)  # a start: five Newton steps reach ~1e-8
    assert _ring.thrust_offset(np.zeros(1), big_a, a0, g, kn)[0] == 0.0


@pytest.mark.parametrize("w", [0.0, 9000 * RPM])
def test_outputs_from_the_last_newton_evaluation_equal_a_fresh_evaluation(w):
    """The rest solve hands its last evaluation to the outputs (no evaluation at the solution of its own);
    every field equals the one a fresh evaluation at the returned displacement gives, bit for bit."""
    bearing, loads = (DEEP, _loads(50)) if w == 0 else (B218, np.abs(_loads(8, 1, (4e3, 4e3, 4e3, 80, 80))) + 5e3)
    geo = combined._geometry(*combined._bearing_args(bearing), 0.0, "operating", "outer", bearing.type)
    speed = np.full(len(loads), w)
    u, ok, it, final = combined._solve(geo, loads, speed**2, combined.TOL, combined.MAX_ITER, final=True)
    assert ok.all()
    reused = combined._outputs(geo, loads, speed, u, ok, it, final)
    fresh = combined._outputs(geo, loads, speed, u, ok, it)
    for key, value in fresh.items():
        assert np.array_equal(reused[key], value), key


def test_solve_is_bit_identical_for_any_batch_pass_size_or_single_case(monkeypatch):
    loads = _loads(23, seed=5)
    whole = combined.combined_analysis(DEEP, loads)
    monkeypatch.setattr(combined, "_CHUNK", 4)  # passes of 4 cases, the last one short
    passes = combined.combined_analysis(DEEP, loads)
    for field in ("displacement", "ball_load_inner", "contact_angle_inner", "stiffness", "residual", "iterations"):
        assert np.array_equal(getattr(passes, field), getattr(whole, field)), field
    for k in (0, 11, 22):
        one = combined.combined_analysis(DEEP, loads[k])
        assert np.array_equal(one.displacement, whole.displacement[k])
        assert np.array_equal(one.stiffness, whole.stiffness[k])

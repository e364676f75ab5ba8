"""Issue 11 item 8: the numerical pieces of the 5-DOF ring Newton (quasistatic._ring and the outputs taken
from the solver's last evaluation), each against an independent computation, and bit-identity of the
solve for any batch, pass size or single case."""


import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from numpy.testing import assert_allclose

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


@pytest.mark.parametrize("z", [7, 16, 23])
def test_ball_sums_round_a_case_alike_in_any_batch_and_equal_the_matrix_form(z):
    """The sums over the balls (ring load and stiffness) are elementwise products reduced along the balls:
    a case gives the same bits alone and in batches of any size (BLAS rounds the last rows of an odd
    block apart), and the values are those of sum_j J_j^T p_j and sum_j J_j^T H_j J_j."""
    geo = combined._geometry(z, 11.5e-3, 60e-3, 0.52, 0.53, 0.2, 2.3e11, 7850.0, 0.1, "operating", "outer", "radial")
    rng = np.random.default_rng(3)
    pa, pr = rng.normal(size=(2, 9, z))
    h = tuple(rng.normal(size=(4, 9, z)))
    u = rng.normal(size=(9, 5)) * 1e-5
    force, stiff, (ga, gr) = _ring.reaction(geo, pa, pr), _ring.assemble(geo, *h), _ring.offsets(geo, u)
    for n in (1, 2, 3, 5, 8):
        for k in (0, n - 1):
            assert np.array_equal(_ring.reaction(geo, pa[k:k + n][:1], pr[k:k + n][:1])[0], force[k])
            assert np.array_equal(_ring.reaction(geo, pa[k:k + n], pr[k:k + n])[0], force[k])
            assert np.array_equal(_ring.assemble(geo, *(a[k:k + n] for a in h))[0], stiff[k])
            assert np.array_equal(_ring.offsets(geo, u[k:k + n])[0][0], ga[k])
    jj = [[np.einsum("zk,zl->zkl", p, q) for q in (geo.ja, geo.jr)] for p in (geo.ja, geo.jr)]
    ref = sum(np.einsum("nz,zkl->nkl", h[2 * p + q], jj[p][q]) for p in range(2) for q in range(2))
    assert_allclose(stiff, ref, rtol=1e-13, atol=1e-13 * np.abs(ref).max())
    assert_allclose(force, pa @ geo.ja + pr @ geo.jr, rtol=1e-13, atol=1e-13 * np.abs(force).max())
    assert_allclose(ga, u @ geo.ja.T, rtol=1e-13, atol=1e-20)
    assert_allclose(gr, geo.gr0 + u @ geo.jr.T, rtol=1e-13)


@pytest.mark.parametrize("w", [0.0, 9000 * RPM])
def test_outputs_from_the_last_newton_evaluation_equal_a_fresh_evaluation(w):
    """The solve hands its last evaluation to the outputs (no evaluation at the solution of its own). At
    rest every field equals the one a fresh evaluation at the returned displacement gives, bit for bit. At
    speed the last evaluation is that of the block Newton, whose balls are converged to the solve's
    tolerance together with the ring; a fresh evaluation solves each ball again at the returned rings (to
    1e-14 D), so the two agree to that tolerance, not bit for bit."""
    bearing, loads = (DEEP, _loads(50)) if w == 0 else (B218, np.abs(_loads(8, 1, (4e3, 4e3, 4e3, 80, 80))) + 5e3)
    geo = combined._geometry(*combined._bearing_args(bearing), 0.0, "operating", "outer", bearing.type)
    speed = np.full(len(loads), w)
    u, ok, it, final = combined._solve(geo, loads, speed**2, combined.TOL, combined.MAX_ITER, final=True)
    assert ok.all()
    reused = combined._outputs(geo, loads, speed, u, ok, it, final)
    fresh = combined._outputs(geo, loads, speed, u, ok, it)
    for key, value in fresh.items():
        if w == 0:
            assert np.array_equal(reused[key], value), key
        elif key == "residual":
            assert np.all(reused[key] <= combined.TOL) and np.all(value <= 1e-10), key
        elif key != "floor":
            scale = np.max(np.abs(value), axis=tuple(range(1, value.ndim)), keepdims=True)
            assert np.all(np.abs(reused[key] - value) <= 1e-9 * scale), key


@pytest.mark.parametrize("engine", ["numpy", "auto"])
def test_solve_is_bit_identical_for_any_batch_pass_size_or_single_case(monkeypatch, engine):
    loads = _loads(23, seed=5)
    whole = combined.combined_analysis(DEEP, loads, engine=engine)
    monkeypatch.setattr(combined, "_CHUNK", 4)  # passes of 4 cases (numpy), the last one short
    passes = combined.combined_analysis(DEEP, loads, engine=engine)
    for field in ("displacement", "ball_load_inner", "contact_angle_inner", "stiffness", "residual", "iterations"):
        assert np.array_equal(getattr(passes, field), getattr(whole, field)), field
    for k in (0, 11, 22):
        one = combined.combined_analysis(DEEP, loads[k], engine=engine)
        assert np.array_equal(one.displacement, whole.displacement[k])
        assert np.array_equal(one.stiffness, whole.stiffness[k])

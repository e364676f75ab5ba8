"""Issue 31: the compiled 5-DOF kernel (quasistatic._combined_kernel) against the batched numpy path.

The two engines run the same algorithm (the rest Newton, the balls at the rest rings, the block Newton at
speed, the continuation), so they take the same iterations give or take one (a line-search decision on a
residual at rounding level) and agree to rounding: the displacement to 1e-10 of its size, the stiffness and
the ball loads to 1e-9. Each engine gives a case the same bits in any batch.
"""

import importlib.util
import math

import numpy as np
import pytest

from bearinglab import catalog
from bearinglab.bearing import BallBearing, Material
from bearinglab.quasistatic import _combined_kernel, combined
from bearinglab.units import RPM

pytestmark = pytest.mark.skipif(importlib.util.find_spec("numba") is None, reason="numba is not installed")

STEEL = Material("steel", 210e9, 0.3, 7850.0)
DEEP = BallBearing(n_balls=7, ball_diameter=11.5e-3, pitch_diameter=43.5e-3, inner_conformity=0.52,
                   outer_conformity=0.53, radial_clearance=10e-6, type="radial", ball_material=STEEL,
                   ring_material=STEEL)
B218 = catalog.get("B218")
NAN = math.nan
ARM = np.array([1.0, 1.0, 1.0, 1e-2, 1e-2])  # tilts compared at a 10 mm arm


def _loads(n, scale, seed=0):
    return np.random.default_rng(seed).normal(size=(n, 5)) * np.asarray(scale)


def _speed_loads(n, seed=1):
    f = _loads(n, [4e3, 4e3, 4e3, 80.0, 80.0], seed)
    f[:, 2] = np.abs(f[:, 2]) + 5e3
    return f


def _agree(fast, slow):
    assert np.array_equal(fast.converged, slow.converged)
    ok = slow.converged
    assert np.all(np.abs(fast.iterations - slow.iterations)[ok] <= 1)
    size = np.max(np.abs(slow.displacement * ARM), axis=-1, keepdims=True)[ok]
    assert np.all(np.abs((fast.displacement - slow.displacement) * ARM)[ok] <= 1e-10 * size + 1e-18)
    for name in ("ball_load_inner", "ball_load_outer", "centrifugal_force", "gyroscopic_moment", "max_pressure_inner",
                 "max_pressure_outer"):  # the kernel computes the pressures itself
        a, b = getattr(fast, name)[ok], getattr(slow, name)[ok]
        assert np.all(np.abs(a - b) <= 1e-9 * np.max(np.abs(b), axis=-1, keepdims=True) + 1e-12), name
    for name in ("contact_angle_inner", "contact_angle_outer"):
        assert np.all(np.abs(getattr(fast, name) - getattr(slow, name))[ok] <= 1e-10), name
    k, ref = fast.stiffness[ok], slow.stiffness[ok]
    scale = np.sqrt(np.abs(np.diagonal(ref, axis1=-2, axis2=-1)))
    assert np.all(np.abs(k - ref) <= 1e-9 * scale[:, :, None] * scale[:, None, :])
    assert np.all(fast.residual[ok] <= combined.TOL) or np.all(fast.residual[ok] <= 1e-9)


@pytest.mark.parametrize("options", [{}, {"stiffness_at": "free"}, {"raceway_control": "inner"},
                                     {"prescribed_displacement": [NAN, NAN, NAN, 0.0, 0.0]}])
def test_kernel_and_numpy_agree_at_rest_and_at_speed(options):
    rest = _loads(40, [1500, 1500, 1500, 15.0, 15.0])
    if "prescribed_displacement" in options:
        rest[:, 3:] = 0.0
    _agree(combined.combined_analysis(DEEP, rest, engine="compiled", on_failure="flag", **options),
           combined.combined_analysis(DEEP, rest, engine="numpy", on_failure="flag", **options))
    speed = _speed_loads(8)
    if "prescribed_displacement" in options:
        speed[:, 3:] = 0.0
    w = np.linspace(3000, 15000, 8) * RPM
    _agree(combined.combined_analysis(B218, speed, w, engine="compiled", on_failure="flag", **options),
           combined.combined_analysis(B218, speed, w, engine="numpy", on_failure="flag", **options))


@pytest.mark.parametrize("engine", ["compiled", "numpy"])
def test_each_engine_gives_a_case_the_same_bits_in_any_batch(engine):
    loads = np.concatenate([_loads(5, [1500, 1500, 1500, 15.0, 15.0], 3), _speed_loads(4, 4)])
    w = np.array([0.0] * 5 + [6000 * RPM, 9000 * RPM, 12000 * RPM, 15000 * RPM])
    whole = combined.combined_analysis(B218, loads, w, engine=engine, on_failure="flag")
    for sel in ([8], [0, 8], [8, 7, 6], [1, 2, 3, 4, 5, 6, 7, 8], [8] * 7):
        part = combined.combined_analysis(B218, loads[sel], w[sel], engine=engine, on_failure="flag")
        for field in ("displacement", "stiffness", "ball_load_inner", "contact_angle_outer", "iterations"):
            assert np.array_equal(getattr(part, field), getattr(whole, field)[sel], equal_nan=True), (sel, field)


def test_plain_python_runs_the_kernels_steps():
    """The per-case functions run by CPython (the fair baseline of bench/combined.py) take the kernel's
    iterations and agree with it to rounding (CPython and LLVM call different libraries for exp and hypot)."""
    solve_case, _react, work = _combined_kernel.plain()
    loads = np.concatenate([_loads(2, [1500, 1500, 1500, 15.0, 15.0], 5), _speed_loads(1, 6)])
    w2 = np.array([0.0, 0.0, (9000 * RPM) ** 2])
    for k, bearing in enumerate((DEEP, DEEP, B218)):
        geo = combined._geometry(*combined._bearing_args(bearing), 0.0, "operating", "outer", bearing.type)
        par, ser = _combined_kernel.parameters(geo, combined.TOL, combined.MAX_ITER, combined._LAM_MAX,
                                               combined._NOISE, combined._RESOLVABLE, combined._BALL_TOL,
                                               combined._BALL_MAX_ITER)
        start = combined._start(geo, loads[k:k + 1])
        fast = _combined_kernel.solve(geo, loads[k:k + 1], start, None, w2[k:k + 1], par, ser)
        u, out, stiff, force = np.empty(5), np.empty((8, geo.z)), np.empty(25), np.empty(5)
        ok, it, _rel, _floor = solve_case(loads[k], start[0], np.ones(5), w2[k], par, geo.cos_psi, geo.sin_psi, ser,
                                          u, out, stiff, force, work(geo.z), np.zeros((10, geo.z)),
                                          np.zeros((12, geo.z)))
        assert ok and fast[1][0] and abs(it - fast[2][0]) <= 1
        assert np.all(np.abs((u - fast[0][0]) * ARM) <= 1e-10 * np.max(np.abs(u * ARM)))


def test_compiled_reactions_equal_the_numpy_evaluation():
    """bearing_reactions' kernel against combined._evaluate: at rest to rounding, at speed to the balls'
    tolerance (each ball solved alone to 1e-14 D by both)."""
    geo = combined._geometry(*combined._bearing_args(B218), 0.0, "operating", "outer", B218.type)
    par, ser = _combined_kernel.parameters(geo, combined.TOL, combined.MAX_ITER, combined._LAM_MAX, combined._NOISE,
                                           combined._RESOLVABLE, combined._BALL_TOL, combined._BALL_MAX_ITER)
    u = combined.combined_analysis(B218, _speed_loads(6, 7), 10000 * RPM).displacement
    for w in (0.0, 10000 * RPM):
        w2 = np.full(len(u), w * w)
        force, stiff, ok = _combined_kernel.reactions(geo, u, w2, par, ser)
        f_ref, k_ref, balls = combined._evaluate(geo, u, w2)
        assert ok.all() and np.all(balls["ok"])
        assert np.all(np.abs(force - f_ref) <= 1e-10 * np.max(np.abs(f_ref), axis=-1, keepdims=True))
        assert np.all(np.abs(stiff - k_ref) <= 1e-9 * np.max(np.abs(k_ref), axis=(1, 2), keepdims=True))


def test_engine_is_checked():
    with pytest.raises(Exception, match="engine must be one of"):
        combined.combined_analysis(DEEP, [100.0, 0, 0, 0, 0], engine="fast")

"""The compiled fast path of the high-speed Newton solve (:mod:`bearinglab.quasistatic._compiled`).

The compiled kernel and the batched numpy path take the same Newton steps case by case: the same
statuses and iterations, the unknowns to 1e-12 (the two sum in different orders, so not bit for bit).
The numpy path is the fallback (``engine="numpy"``, or numba missing).
"""

import importlib.util
import math

import numpy as np
import pytest
from b218_cases import B218, GEO
from numpy.testing import assert_allclose, assert_array_equal

from bearinglab import _solve, catalog, parallel, quasistatic
from bearinglab.errors import ConvergenceError, InputError
from bearinglab.quasistatic import HighSpeedState, _compiled
from bearinglab.units import RPM

pytestmark = pytest.mark.skipif(importlib.util.find_spec("numba") is None, reason="numba is not installed")

OTHER = catalog.get("4-1006095")  # the 5 x 13 x 4 mm angular bearing of spec 000
ANGLES = ("contact_angle_inner", "contact_angle_outer", "static_contact_angle", "attitude_angle")
SCALED = ("axial_displacement", "ball_load_inner", "ball_load_outer", "deflection_inner", "deflection_outer",
          "centrifugal_force", "gyroscopic_moment", "cage_speed", "ball_spin_speed", "bpfo", "bpfi", "max_pressure_inner",
          "max_pressure_outer", "axial_stiffness", "friction_coefficient")


def _grid(fa_max, n_max, n=7):
    fa, w = np.meshgrid(np.geomspace(fa_max / 200, fa_max, n), np.linspace(0.0, n_max, n) * RPM, indexing="ij")
    return fa, w


def _both(bearing, fa, w, **options):
    options = {"on_failure": "flag", "friction_limit": np.inf, **options}
    fast = quasistatic.high_speed_analysis(bearing, fa, w, engine="compiled", **options)
    slow = quasistatic.high_speed_analysis(bearing, fa, w, engine="numpy", **options)
    return fast, slow


def _assert_same(fast, slow):
    assert_array_equal(fast.status, slow.status)
    assert_array_equal(fast.converged, slow.converged)
    assert_array_equal(fast.iterations, slow.iterations)
    assert_array_equal(fast.method, slow.method)
    for name in ANGLES:
        assert_allclose(getattr(fast, name), getattr(slow, name), rtol=0, atol=1e-12, equal_nan=True, err_msg=name)
    for name in SCALED:
        ref = getattr(slow, name)
        # relative 1e-12 of each value, or of the largest one: delta_a changes sign, so near its zero the
        # relative difference of the two summation orders is unbounded
        scale = np.nanmax(np.abs(ref), initial=0.0)
        assert_allclose(getattr(fast, name), ref, rtol=1e-12, atol=1e-12 * scale, equal_nan=True, err_msg=name)
    # the residual at the solution is rounding noise below the tolerance: the same NaN pattern, both below it
    assert_array_equal(np.isnan(fast.residual), np.isnan(slow.residual))
    assert np.all(np.nan_to_num(fast.residual) < _solve.QUASISTATIC_TOL)


@pytest.mark.parametrize("options", [
    {"constants": "harris"},
    {"constants": "mass", "raceway_control": "inner"},
    {"constants": "paper", "gyroscopic_sign": -1},
    {"constants": (2.26e-11, 0.0)},
    {"constants": "harris", "speed_step": _solve.QUASISTATIC_SPEED_STEP_RPM * RPM},
])
def test_compiled_and_numpy_paths_agree_on_the_218_map(options):
    fa, w = _grid(45e3, 20000.0)
    fast, slow = _both(B218, fa, w, **options)
    assert fast.converged.any()
    _assert_same(fast, slow)


@pytest.mark.parametrize("raceway_control", ["outer", "inner"])
def test_compiled_and_numpy_paths_agree_on_a_small_bearing_including_failures(raceway_control):
    fa, w = _grid(200.0, 300000.0, n=9)
    fast, slow = _both(OTHER, fa, w, raceway_control=raceway_control)
    assert fast.converged.sum() > 10
    if raceway_control == "inner":  # both kinds of failure are covered
        assert {"inner_contact_lost", "no_convergence"} <= set(fast.status.ravel())
    _assert_same(fast, slow)


def test_same_failures_and_iterations_when_the_iteration_limit_is_hit():
    fa, w = _grid(45e3, 15000.0, n=5)
    fast, slow = _both(B218, fa, w, max_iter=3)
    assert (fast.status == "no_convergence").any() and fast.converged.any()
    _assert_same(fast, slow)


def test_continuation_cases_take_several_speed_steps_and_agree():
    # low thrust at high speed: the first step to the target speed fails and the step is cut
    fa = np.array([300.0, 600.0, 1200.0])
    w = np.array([15000.0, 15000.0, 15000.0]) * RPM
    fast, slow = _both(B218, fa, w, raceway_control="inner")
    _assert_same(fast, slow)
    one_step = quasistatic.high_speed_analysis(B218, 20e3, 10.0 * RPM, engine="compiled", friction_limit=np.inf)
    assert (fast.iterations > one_step.iterations).all()


def test_multi_bearing_batches_use_their_own_tables():
    # two bearings broadcast in one call: one Hertz table per geometry (gid)
    fa = np.array([5e3, 5e3, 20e3])
    w = np.array([5000.0, 12000.0, 12000.0]) * RPM
    d = np.array([GEO[1], 1.1 * GEO[1], GEO[1]])
    args = (GEO[0], d, *GEO[2:])
    opts = {"on_failure": "flag", "friction_limit": np.inf, "constants": "harris"}
    _assert_same(quasistatic.contact_angles(fa, w, *args, engine="compiled", **opts),
                 quasistatic.contact_angles(fa, w, *args, engine="numpy", **opts))


def test_same_inputs_give_bit_identical_results():
    fa, w = _grid(45e3, 15000.0, n=5)
    a = quasistatic.high_speed_analysis(B218, fa, w, engine="compiled", on_failure="flag", friction_limit=np.inf)
    b = quasistatic.high_speed_analysis(B218, fa, w, engine="compiled", on_failure="flag", friction_limit=np.inf)
    for name in HighSpeedState._fields:
        assert_array_equal(getattr(a, name), getattr(b, name))


def test_the_kernel_result_of_a_case_does_not_depend_on_its_batch():
    fa, w = (x.ravel() for x in _grid(45e3, 20000.0, n=6))
    model, _ = quasistatic._prepare(fa, *GEO, "inner", 1, "mass")
    idx = np.arange(fa.size)
    v0 = quasistatic._unknowns_from(model, idx, *quasistatic._static_start(model, idx))
    opts = {"tol": _solve.QUASISTATIC_TOL, "max_iter": _solve.QUASISTATIC_MAX_ITER, "speed_step": None}
    whole = _compiled.solve(model, w, v0, **opts)
    assert (whole[1] != 0).any() and (whole[1] == 0).any()
    for chunk in (1, 5, 17):
        parts = []
        for start in range(0, fa.size, chunk):
            sub, _ = quasistatic._prepare(fa[start:start + chunk], *GEO, "inner", 1, "mass")
            parts.append(_compiled.solve(sub, w[start:start + chunk], v0[start:start + chunk], **opts))
        for k in range(3):
            assert_array_equal(np.concatenate([p[k] for p in parts]), whole[k])


def test_sweep_chunks_agree_to_the_last_bits():
    fa, w = _grid(45e3, 15000.0, n=5)
    one = quasistatic.high_speed_analysis(B218, fa, w, engine="compiled", on_failure="flag", friction_limit=np.inf)
    for chunk in (3, 25):
        s = quasistatic.sweep(B218, fa[:, 0], w[0], execution=parallel.Execution(chunk_size=chunk),
                              engine="compiled", friction_limit=np.inf)
        # bit for bit: the compiled engine solves each case alone, static start included
        for name in HighSpeedState._fields:
            assert_array_equal(getattr(s, name), getattr(one, name), err_msg=name)


def test_the_numpy_engine_does_not_call_the_kernel(monkeypatch):
    def fail(*args, **kwargs):
        raise AssertionError("the compiled kernel ran")

    monkeypatch.setattr(_compiled, "solve", fail)
    s = quasistatic.high_speed_analysis(B218, 20e3, 10000.0 * RPM, engine="numpy", constants="harris")
    assert s.converged and math.degrees(s.contact_angle_inner) == pytest.approx(49.308, abs=5e-4)
    with pytest.raises(AssertionError, match="compiled kernel ran"):
        quasistatic.high_speed_analysis(B218, 20e3, 10000.0 * RPM, engine="auto", constants="harris")
    # the angle iteration has no compiled path: "auto" runs it on numpy
    quasistatic.high_speed_analysis(B218, 20e3, 0.0, engine="auto", method="angle-iteration")


def test_auto_falls_back_to_numpy_without_numba(monkeypatch):
    real = importlib.util.find_spec
    monkeypatch.setattr(importlib.util, "find_spec", lambda name, *a: None if name == "numba" else real(name, *a))
    monkeypatch.setattr(_compiled, "solve", lambda *a, **k: pytest.fail("the compiled kernel ran"))
    s = quasistatic.high_speed_analysis(B218, 20e3, 10000.0 * RPM, constants="harris")
    assert s.converged
    with pytest.raises(InputError, match="needs numba"):
        quasistatic.high_speed_analysis(B218, 20e3, 10000.0 * RPM, engine="compiled")


@pytest.mark.parametrize(("kwargs", "match"), [
    ({"engine": "fortran"}, r"engine must be one of \['auto', 'numpy', 'compiled'\], got 'fortran'"),
    ({"engine": "compiled", "method": "angle-iteration"}, "implements method='newton' only"),
])
def test_invalid_engine_is_rejected(kwargs, match):
    with pytest.raises(InputError, match=match):
        quasistatic.high_speed_analysis(B218, 20e3, 10000.0 * RPM, **kwargs)


def test_a_failure_raises_the_same_error_on_both_paths():
    errors = []
    for engine in ("compiled", "numpy"):
        with pytest.raises(ConvergenceError) as info:
            quasistatic.high_speed_analysis(B218, np.array([2.5e3, 45e3]), np.array([15000.0, 0.0]) * RPM,
                                            max_iter=2, engine=engine, friction_limit=np.inf)
        errors.append(info.value)
    assert str(errors[0]) == str(errors[1]) and errors[0].iterations == errors[1].iterations
    assert_allclose(errors[0].estimate, errors[1].estimate, rtol=1e-12)


def test_plain_solver_is_the_kernel_in_plain_python():
    fa, w = np.array([3e3, 30e3]), np.array([14000.0, 4000.0]) * RPM
    model, _ = quasistatic._prepare(fa, *GEO, "outer", 1, "harris")
    v, status, iters, state = _compiled.solve(model, w, tol=_solve.QUASISTATIC_TOL,
                                              max_iter=_solve.QUASISTATIC_MAX_ITER, speed_step=None)
    par, gid, tables = _compiled.case_parameters(model)
    one = _compiled.plain_solver()
    assert not hasattr(one, "py_func")  # plain Python, not a numba dispatcher
    for k in range(2):
        alpha_s, vk, sk, ik, out = one(fa[k], w[k], par[k], *(t[gid[k]] for t in tables), _solve.QUASISTATIC_TOL,
                                       _solve.QUASISTATIC_MAX_ITER, math.inf, [0.0] * 35)
        assert sk == status[k] == 0 and ik == iters[k]
        assert alpha_s == pytest.approx(state["static_contact_angle"][k], rel=1e-14)
        assert_allclose(vk, v[k], rtol=1e-13)
        for j, name in enumerate(_compiled.OUTPUTS):
            # the residual is ~1e-13 at convergence: its value is rounding, compare it by size only
            if name == "residual":
                assert out[j] < _solve.QUASISTATIC_TOL and state[name][k] < _solve.QUASISTATIC_TOL
            else:
                assert_allclose(out[j], state[name][k], rtol=1e-12, err_msg=name)


def test_the_kernel_static_start_is_the_static_solution():
    # the kernel's start (Hertz through the interpolants) against bearinglab.static (exact Hertz)
    fa = np.geomspace(50.0, 200e3, 25)
    for bearing in (B218, OTHER):
        geo = quasistatic._bearing_args(bearing)
        model, _ = quasistatic._prepare(fa, *geo, "outer", 1, "mass")
        idx = np.arange(fa.size)
        ref = quasistatic._static_start(model, idx)
        par, _gid, tables = _compiled.case_parameters(model)
        for k in range(fa.size):
            alpha_s, v0 = _compiled.static_start(fa[k], par[k], *(t[0] for t in tables[:4]), 1e-13, 50)
            # the interpolants reproduce the exact K to ~1e-13 (tests/quasistatic/test_contact.py)
            assert alpha_s == pytest.approx(ref[0][k], rel=0, abs=1e-13)
            assert_allclose(v0, quasistatic._unknowns_from(model, idx[k:k + 1], *(r[k:k + 1] for r in ref))[0],
                            rtol=1e-12, atol=1e-15)

"""The compiled engine of the test-stand solve (``stand.operating_contact_angle(engine=...)``,
``bearinglab._stand_compiled``): the numpy path's angles and convergence case by case, the same results for
any batch, the engine choice of ``engine="auto"``, and the numpy fallback without numba."""

import importlib.util
import math
import subprocess
import sys

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from numpy.testing import assert_allclose

from bearinglab import _solve, catalog, stand
from bearinglab.errors import ConvergenceError, InputError
from bearinglab.units import KGF

numba_missing = importlib.util.find_spec("numba") is None
needs_numba = pytest.mark.skipif(numba_missing, reason="numba is not installed")
CS = 7792.357 * KGF
A0 = math.radians(12.0)


def _cases(n, seed):
    """Per-case bearings and loads from feather (the angle leaves alpha0 by 1e-6 rad) to near 90 deg."""
    rng = np.random.default_rng(seed)
    a0 = rng.uniform(math.radians(0.5), math.radians(85.0), n)
    cs = rng.uniform(1e3, 1e6, n)
    return cs * 10.0 ** rng.uniform(-11.0, 1.5, n), cs, a0


@needs_numba
@pytest.mark.parametrize("ftol_percent", [_solve.AXIAL_ANGLE_FTOL_PERCENT, 0.0])
def test_compiled_engine_gives_the_numpy_angles_and_convergence(ftol_percent):
    # ftol 0: no case passes the load test at the start, so every case runs the Newton of section 6.3
    fa, cs, a0 = _cases(5000, seed=1)
    kw = {"ftol_percent": ftol_percent}
    fast = stand.operating_contact_angle(fa, cs, a0, engine="compiled", **kw)
    ref = stand.operating_contact_angle(fa, cs, a0, engine="numpy", **kw)
    assert_allclose(fast, ref, rtol=0, atol=1e-12)
    # the same operations and the same C library: the same bits (what makes engine="auto" reproducible)
    assert np.array_equal(fast, ref)


@needs_numba
def test_compiled_engine_flags_the_same_cases_with_the_same_residuals():
    from bearinglab import _stand_compiled

    fa, cs, a0 = _cases(700, seed=2)
    # a step tolerance at the rounding of the angle that some cases meet in two steps and others do not
    ref_alpha, ref_ok, ref_res = stand._newton(fa, cs, a0, fa.size, 1e-16, 0.0, 2)
    alpha, iterations, residual, n_bad = _stand_compiled.solve(fa, cs, a0, fa.size, 1e-16, 0.0, 2)
    assert 0 < n_bad < fa.size and n_bad == np.sum(~ref_ok)
    assert np.array_equal(iterations >= 0, ref_ok) and np.all(iterations[~ref_ok] == -2)
    assert np.array_equal(alpha, ref_alpha) and np.array_equal(residual, ref_res)
    assert np.all(residual[ref_ok] == 0.0) and np.all(residual[~ref_ok] != 0.0)


@needs_numba
@pytest.mark.parametrize("max_iter", [0, 1])
def test_compiled_engine_raises_the_same_convergence_error(max_iter):
    loads = np.array([2.0, 5.0]) * KGF
    kw = {"max_iter": max_iter, "xtol": 0.0, "ftol_percent": 0.0}
    errors = []
    for engine in ("compiled", "numpy"):
        with pytest.raises(ConvergenceError) as info:
            stand.operating_contact_angle(loads, CS, A0, engine=engine, **kw)
        errors.append(info.value)
    fast, ref = errors
    assert fast.iterations == ref.iterations == max_iter
    assert np.array_equal(fast.estimate, ref.estimate)
    assert np.array_equal(fast.residual, ref.residual, equal_nan=True)  # no step taken: no residual (NaN)


@needs_numba
@settings(max_examples=30, deadline=None)
@given(lo=st.integers(0, 600), size=st.integers(1, 700))
def test_compiled_angles_do_not_depend_on_the_batch(lo, size):
    fa, cs, a0 = _cases(1300, seed=3)
    whole = stand.operating_contact_angle(fa, cs, a0, engine="compiled")
    part = stand.operating_contact_angle(fa[lo:lo + size], cs[lo:lo + size], a0[lo:lo + size], engine="compiled")
    assert np.array_equal(part, whole[lo:lo + size])


@needs_numba
def test_compiled_engine_broadcasts_like_numpy_and_keeps_scalars():
    loads = np.geomspace(1e-4, 1e3, 101) * KGF
    grid = (loads.reshape(1, 101), np.array([[CS], [2 * CS]]), A0)
    assert np.array_equal(stand.operating_contact_angle(*grid, engine="compiled"),
                          stand.operating_contact_angle(*grid, engine="numpy"))
    one = stand.operating_contact_angle(2 * KGF, CS, A0, engine="compiled")
    assert isinstance(one, float) and one == stand.operating_contact_angle(2 * KGF, CS, A0, engine="numpy")


def test_engine_must_be_a_known_name():
    for bad in ("fast", None, "NUMPY"):
        with pytest.raises(InputError, match=r"engine must be one of \['auto', 'numpy', 'compiled'\]"):
            stand.operating_contact_angle(2 * KGF, CS, A0, engine=bad)


def test_without_numba_auto_falls_back_to_numpy_and_compiled_says_why(monkeypatch):
    real = importlib.util.find_spec
    monkeypatch.setattr(importlib.util, "find_spec", lambda name, *a: None if name == "numba" else real(name, *a))
    monkeypatch.delitem(sys.modules, "bearinglab._stand_compiled", raising=False)
    monkeypatch.setattr(_solve, "AXIAL_ANGLE_COMPILED_CASES", 10)  # a batch large enough for the kernel
    loads = np.geomspace(0.05, 50.0, 50) * KGF
    got = stand.operating_contact_angle(loads, CS, A0)
    assert np.array_equal(got, stand.operating_contact_angle(loads, CS, A0, engine="numpy"))
    assert "bearinglab._stand_compiled" not in sys.modules
    with pytest.raises(InputError, match="engine='compiled' needs numba, which is not installed"):
        stand.operating_contact_angle(loads, CS, A0, engine="compiled")


@needs_numba
def test_auto_runs_the_kernel_for_a_large_batch(monkeypatch):
    from bearinglab import _stand_compiled

    calls = []
    solve = _stand_compiled.solve
    monkeypatch.setattr(_stand_compiled, "solve", lambda *a: calls.append(a[3]) or solve(*a))
    monkeypatch.delitem(sys.modules, "bearinglab._stand_compiled")  # as in a fresh process
    monkeypatch.setattr(_solve, "AXIAL_ANGLE_COMPILED_CASES", 40)
    stand.operating_contact_angle(np.full(39, 2 * KGF), CS, A0)  # small: numpy, the kernel is not loaded
    assert calls == [] and "bearinglab._stand_compiled" not in sys.modules
    monkeypatch.setitem(sys.modules, "bearinglab._stand_compiled", _stand_compiled)
    stand.operating_contact_angle(np.full(40, 2 * KGF), CS, A0)
    stand.operating_contact_angle(2 * KGF, CS, A0)  # once loaded, the kernel runs any batch
    assert calls == [40, 1]
    stand.operating_contact_angle(np.full(40, 2 * KGF), CS, A0, engine="numpy")
    assert calls == [40, 1]


def test_a_one_case_solve_does_not_import_numba():
    code = ("import sys; from bearinglab import catalog, stand; b = catalog.get('4-1006095'); "
            "stand.stand_analysis(b, [1.0, 2.0]); stand.operating_contact_angle(20.0, 7e4, 0.2); "
            "print('numba' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "False"


@needs_numba
def test_the_operating_constants_are_the_same_with_the_kernel_loaded(monkeypatch):
    b = catalog.get("B218")
    args = (np.geomspace(1e2, 5e4, 30), b.n_balls, b.ball_diameter, b.pitch_diameter, b.inner_conformity,
            b.outer_conformity, b.contact_angle)
    monkeypatch.delitem(sys.modules, "bearinglab._stand_compiled", raising=False)
    consts, alpha = stand.constants_at_operating_angle(*args)  # numpy: the kernel not loaded, a small batch
    from bearinglab import _stand_compiled

    monkeypatch.setitem(sys.modules, "bearinglab._stand_compiled", _stand_compiled)
    consts2, alpha2 = stand.constants_at_operating_angle(*args)  # engine="auto" now runs the kernel
    assert np.array_equal(alpha, alpha2)
    assert np.array_equal(consts.force_characteristic, consts2.force_characteristic)

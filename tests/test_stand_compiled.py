"""The compiled engine of the test-stand solve (``stand.operating_contact_angle(engine=...)``,
``bearinglab.stand._compiled``): the numpy path's angles and convergence case by case, the same results for
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


# The two engines run the same operations, but their libraries may round a sine, an arc cosine or a cube root
# differently (numpy's SIMD functions on AVX-512/FMA hosts against the C library that numba calls): across
# engines the angles agree to a few ulp, not bit for bit. Bit-identity is promised, and tested below, for one
# engine across batches, chunks and executors.
ULP_ACROSS_ENGINES = 4  # the stated bound (measured: at most 2 ulp over 10^5 cases of _cases on AVX-512)


def _ulp(a, b):
    """|a - b| in units of the last place of b."""
    return np.abs(np.asarray(a) - b) / np.spacing(np.abs(b))


@needs_numba
def test_compiled_engine_gives_the_numpy_angles_to_a_few_ulp():
    # the default tolerances: every case's answer is the start, which passes the load test of section 6.3
    fa, cs, a0 = _cases(5000, seed=1)
    fast = stand.operating_contact_angle(fa, cs, a0, engine="compiled")
    ref = stand.operating_contact_angle(fa, cs, a0, engine="numpy")
    assert _ulp(fast, ref).max() <= ULP_ACROSS_ENGINES


@needs_numba
def test_compiled_engine_gives_the_numpy_angles_where_the_newton_of_section_6_3_runs():
    # ftol 0: no case passes the load test at the start, so every case runs the Newton of section 6.3 and
    # stops at a step below xtol: both converge, to within xtol (near feather loads the gap cos alpha0 - cos
    # alpha cancels, and a rounding of it moves the Newton's last step by more than a few ulp)
    fa, cs, a0 = _cases(5000, seed=1)
    fast = stand.operating_contact_angle(fa, cs, a0, engine="compiled", ftol_percent=0.0)
    ref = stand.operating_contact_angle(fa, cs, a0, engine="numpy", ftol_percent=0.0)
    assert_allclose(fast, ref, rtol=0, atol=_solve.AXIAL_ANGLE_XTOL)


@needs_numba
def test_compiled_newton_flags_the_same_cases_as_the_numpy_newton():
    from bearinglab.stand import _compiled as _stand_compiled

    fa, cs, a0 = _cases(700, seed=2)
    root = stand.operating_contact_angle(fa, cs, a0, engine="numpy")
    # From halfway between alpha0 and the root, two or three steps of section 6.3 leave steps of 1e-3 to
    # 1e-16 rad: a tolerance of 1e-8 rad splits the cases far from the rounding (a 1-ulp difference moves a
    # step by ~1e-16 of itself, so no case sits within it of the threshold), unlike a tolerance at 1e-16.
    start = 0.5 * (a0 + root)
    for max_iter in (2, 3):
        ref_alpha, ref_ok, ref_res = stand.method._section_newton(fa, cs, a0, np.cos(a0), start, 1e-8, 0.0, max_iter)
        one = [_stand_compiled._section_newton(*x, math.cos(x[2]), s, 1e-8, 0.0, max_iter)
               for *x, s in zip(fa, cs, a0, start)]
        alpha, iterations, residual = (np.array(v) for v in zip(*one))
        assert 0 < np.sum(~ref_ok) < fa.size
        assert np.array_equal(iterations >= 0, ref_ok) and np.all(iterations[~ref_ok] == -max_iter)
        assert np.all(residual[ref_ok] == 0.0) and np.all(ref_res[ref_ok] == 0.0)
        assert_allclose(residual[~ref_ok], ref_res[~ref_ok], rtol=1e-6)  # residuals of 1e-2 to 1e-10
        assert_allclose(alpha, ref_alpha, rtol=0, atol=1e-14)


@needs_numba
def test_compiled_solve_flags_every_case_that_does_not_converge():
    from bearinglab.stand import _compiled as _stand_compiled

    fa, cs, a0 = _cases(700, seed=2)
    # no tolerance can be met: every case runs its max_iter steps and is flagged, on both engines
    ref_alpha, ref_ok, ref_res = stand.method._newton(fa, cs, a0, fa.size, 0.0, 0.0, 2)
    alpha, iterations, residual, n_bad = _stand_compiled.solve(fa, cs, a0, fa.size, 0.0, 0.0, 2)
    assert n_bad == fa.size and not ref_ok.any() and np.all(iterations == -2)
    assert np.all(np.isfinite(residual)) and np.all(np.isfinite(ref_res))
    assert_allclose(alpha, ref_alpha, rtol=0, atol=_solve.AXIAL_ANGLE_XTOL)


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
    fast = stand.operating_contact_angle(*grid, engine="compiled")
    ref = stand.operating_contact_angle(*grid, engine="numpy")
    assert fast.shape == ref.shape == (2, 101) and _ulp(fast, ref).max() <= ULP_ACROSS_ENGINES
    one = stand.operating_contact_angle(2 * KGF, CS, A0, engine="compiled")
    ref = stand.operating_contact_angle(2 * KGF, CS, A0, engine="numpy")
    assert isinstance(one, float) and np.ndim(one) == 0 and _ulp(one, ref) <= ULP_ACROSS_ENGINES


def test_engine_must_be_a_known_name():
    for bad in ("fast", None, "NUMPY"):
        with pytest.raises(InputError, match=r"engine must be one of \['auto', 'numpy', 'compiled'\]"):
            stand.operating_contact_angle(2 * KGF, CS, A0, engine=bad)


def test_without_numba_auto_falls_back_to_numpy_and_compiled_says_why(monkeypatch):
    real = importlib.util.find_spec
    monkeypatch.setattr(importlib.util, "find_spec", lambda name, *a: None if name == "numba" else real(name, *a))
    monkeypatch.delitem(sys.modules, "bearinglab.stand._compiled", raising=False)
    monkeypatch.setattr(_solve, "AXIAL_ANGLE_COMPILED_CASES", 10)  # a batch large enough for the kernel
    loads = np.geomspace(0.05, 50.0, 50) * KGF
    got = stand.operating_contact_angle(loads, CS, A0)
    assert np.array_equal(got, stand.operating_contact_angle(loads, CS, A0, engine="numpy"))
    assert "bearinglab.stand._compiled" not in sys.modules
    with pytest.raises(InputError, match="engine='compiled' needs numba, which is not installed"):
        stand.operating_contact_angle(loads, CS, A0, engine="compiled")


@needs_numba
def test_auto_chooses_the_engine_from_the_batch_size_alone(monkeypatch):
    from bearinglab.stand import _compiled as _stand_compiled

    calls = []
    solve = _stand_compiled.solve
    monkeypatch.setattr(_stand_compiled, "solve", lambda *a: calls.append(a[3]) or solve(*a))
    monkeypatch.delitem(sys.modules, "bearinglab.stand._compiled")  # as in a fresh process
    monkeypatch.setattr(_solve, "AXIAL_ANGLE_COMPILED_CASES", 40)
    stand.operating_contact_angle(np.full(39, 2 * KGF), CS, A0)  # small: numpy, the kernel is not loaded
    assert calls == [] and "bearinglab.stand._compiled" not in sys.modules
    assert stand.engine_for(39) == "numpy" and stand.engine_for(40) == "compiled"
    monkeypatch.setitem(sys.modules, "bearinglab.stand._compiled", _stand_compiled)
    stand.operating_contact_angle(np.full((5, 8), 2 * KGF), CS, A0)  # 40 cases once broadcast: the kernel
    stand.operating_contact_angle(2 * KGF, CS, A0)  # the kernel is loaded now, and still not used for one case
    stand.operating_contact_angle(np.full(39, 2 * KGF), CS, A0)
    assert calls == [40]
    stand.operating_contact_angle(np.full(40, 2 * KGF), CS, A0, engine="numpy")
    assert calls == [40]


@needs_numba
def test_the_same_call_gives_the_same_bits_before_and_after_a_large_batch():
    # engine="auto" must not depend on what ran earlier in the process (it once ran the kernel for any batch
    # as soon as it was loaded, which changes the last bits on hosts where the engines round differently)
    from bearinglab.stand import _compiled as _stand_compiled

    fa, cs, a0 = _cases(2000, seed=4)
    before = stand.operating_contact_angle(fa, cs, a0)
    b = catalog.get("B218")
    args = (np.geomspace(1e2, 5e4, 30), b.n_balls, b.ball_diameter, b.pitch_diameter, b.inner_conformity,
            b.outer_conformity, b.contact_angle)
    consts, alpha = stand.constants_at_operating_angle(*args)
    big = _solve.AXIAL_ANGLE_COMPILED_CASES  # the real threshold: a batch that runs the kernel
    calls = []
    solve = _stand_compiled.solve
    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(_stand_compiled, "solve", lambda *a: calls.append(a[3]) or solve(*a))
        stand.operating_contact_angle(np.geomspace(1e-2, 1e4, big), CS, A0)
        assert calls == [big] and "bearinglab.stand._compiled" in sys.modules
        after = stand.operating_contact_angle(fa, cs, a0)
        consts2, alpha2 = stand.constants_at_operating_angle(*args)
        assert calls == [big]  # the small calls stayed on numpy
    assert np.array_equal(after, before)
    assert np.array_equal(alpha, alpha2)
    assert np.array_equal(consts.force_characteristic, consts2.force_characteristic)


def test_a_one_case_solve_does_not_import_numba():
    code = ("import sys; from bearinglab import catalog, stand; b = catalog.get('4-1006095'); "
            "stand.stand_analysis(b, [1.0, 2.0]); stand.operating_contact_angle(20.0, 7e4, 0.2); "
            "print('numba' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "False"

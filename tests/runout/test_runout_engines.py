"""The two engines of the runout model (issue 31): the numpy path and the compiled kernels of
``runout._compiled``; and the memory of the contact solver, linear in the balls and positions (issue 29).

One engine gives the same bits for a position or a sample alone, in any batch, chunk or executor (tested
with ``==`` here and in test_runout_tolerances.py); the two engines are compared to a stated bound, never
with ``==`` (TESTING.md, "Engines"). The solvers of the contact problem themselves are cross-checked
against the LP and the triple enumeration in test_runout_contact.py, on both engines.
"""

import importlib.util
import math
import os
import subprocess
import sys
import time
import tracemalloc

import numpy as np
import pytest
from numpy.testing import assert_allclose, assert_array_equal

from bearinglab import runout as R
from bearinglab.errors import ConvergenceError, InputError
from bearinglab.runout import _solver

UM = 1e-6
needs_numba = pytest.mark.skipif(importlib.util.find_spec("numba") is None, reason="numba is not installed")
ENGINES = ["numpy", pytest.param("compiled", marks=needs_numba)]
# Across engines: the compiled kernel evaluates the Fourier series of the raceways at
# z = exp(i alpha) exp(i beta) (one complex product a ball and position) where numpy takes exp(i theta),
# so Delta k differs by some ulp of each order's term, and a pose by up to ~20 ulp of its size (measured
# 1.3e-14 um on poses of a few um): compared to 1e-13 um. With the same Delta k (solve_contact), the two
# walks take the same steps and agree to a few ulp of the errors.
ACROSS_UM = 1e-13


def big_bearing(n):
    """n balls of 7.144 mm on a pitch circle that holds them (the reference section, scaled)."""
    return R.geometry_from_catalog(n, 7.144e-3, 1.2 * n * 7.144e-3 / math.pi, 0.53, 0.52, math.radians(15))


def random_errors(n, seed=0):
    rng = np.random.default_rng(seed)
    return R.manufacturing_errors(
        n,
        ball_diameter_deviation=rng.uniform(-0.2, 0.2, n) * UM,
        inner=R.RacewayErrors(radial=R.fourier_series(rng.normal(0, 0.1, 8), rng.normal(0, 0.1, 8), scale=UM)),
        outer=R.RacewayErrors(radial=R.fourier_series(rng.normal(0, 0.1, 8), rng.normal(0, 0.1, 8), scale=UM)),
    )


# ------------------------------------------------------------------------------ the engines agree
@needs_numba
@pytest.mark.parametrize("n", [3, 4, 5, 16, 17, 64])
@pytest.mark.parametrize("rounded", [False, True])
def test_the_engines_solve_the_contact_problem_alike(n, rounded):
    """The same Delta k: the same triangles, so the same contact sets and faces, a0, B, D to a few ulp."""
    rng = np.random.default_rng(n)
    P = 400
    th = rng.uniform(0, 2 * np.pi, P)[:, None] + 2 * np.pi * np.arange(n) / n
    dk = rng.normal(0, 0.3, (P, n))
    if rounded:  # ties: degenerate faces and several optimal triangles
        dk = np.round(dk, 1)
    centre = (rng.normal(0, 0.1, P) * UM, rng.normal(0, 0.1, P) * UM)
    a, b = (R.solve_contact(dk * UM, th, centre=centre, engine=e) for e in ("numpy", "compiled"))
    for name in ("constant", "sine", "cosine", "face_diameter", "slack"):
        assert_allclose(getattr(a, name) / UM, getattr(b, name) / UM, rtol=0, atol=1e-14, err_msg=name)
    for name in ("contact", "degenerate"):
        assert_array_equal(getattr(a, name), getattr(b, name), err_msg=name)
    assert_allclose(a.load_share, b.load_share, rtol=0, atol=1e-14)


@needs_numba
def test_the_engines_agree_on_irregular_ball_sets_and_the_midpoint_rule():
    rng = np.random.default_rng(5)
    n, P = 9, 300
    gaps = rng.uniform(0.4, 1.0, (P, n))
    th = np.cumsum(gaps / gaps.sum(axis=1, keepdims=True) * 2 * np.pi, axis=1) + rng.uniform(0, 6, (P, 1))
    dk = rng.normal(0, 0.5, (P, n)) * UM
    for tie_break in ("centre", "midpoint"):
        a, b = (R.solve_contact(dk, th, tie_break=tie_break, engine=e) for e in ("numpy", "compiled"))
        for name in ("constant", "sine", "cosine", "face_diameter"):
            assert_allclose(getattr(a, name) / UM, getattr(b, name) / UM, rtol=0, atol=1e-14, err_msg=name)
        assert_array_equal(a.contact, b.contact)


@needs_numba
@pytest.mark.parametrize("refine", [False, True])
def test_the_engines_agree_on_a_trajectory_with_tilt(g, refine):
    e = random_errors(16)._replace(tilt_x=R.fourier_series({0: 5.0, 1: 10.0}, scale=UM), tilt_y=-3 * UM)
    a, b = (
        R.rotation_sequence(g, e, revolutions=2, steps_per_revolution=90, refine=refine, engine=eng)
        for eng in ("numpy", "compiled")
    )
    for name in ("x", "y", "z"):
        assert_allclose(getattr(a.displacement, name) / UM, getattr(b.displacement, name) / UM, rtol=0,
                        atol=ACROSS_UM, err_msg=name)
    assert_allclose(a.displacement.generalized_error / UM, b.displacement.generalized_error / UM, rtol=0,
                    atol=ACROSS_UM)
    assert_array_equal(a.displacement.contact.contact, b.displacement.contact.contact)
    assert_array_equal(a.displacement.passes, b.displacement.passes)
    for name in R.METRICS:
        assert abs(getattr(a.metrics, name) - getattr(b.metrics, name)) / UM < ACROSS_UM, name


@needs_numba
@pytest.mark.parametrize(("grade", "rings"), [("G5", "P4"), ("G10", "P5")])
def test_the_engines_agree_on_the_monte_carlo(g, grade, rings):
    a, b = (R.monte_carlo_chunk(g, grade, rings, np.arange(40), 3, engine=e) for e in ("numpy", "compiled"))
    for name in R.METRICS:
        assert_allclose(getattr(a, name) / UM, getattr(b, name) / UM, rtol=0, atol=ACROSS_UM, err_msg=name)
    assert_array_equal(a.degenerate_fraction, b.degenerate_fraction)
    assert_array_equal(a.first_ball_angle, b.first_ball_angle)


@needs_numba
def test_long_series_are_summed_by_horner_alike(g, monkeypatch):
    """Above n (K + 1) = TABLE_LIMIT the kernel sums each ring's series by Horner's rule instead of its
    table: the same answers to rounding, and a sample still gives its rotation sequence's bits."""
    from bearinglab.runout import _compiled

    tabled = R.monte_carlo_chunk(g, "G5", "P4", np.arange(6), 4, steps_per_revolution=60, engine="compiled")
    monkeypatch.setattr(_compiled, "TABLE_LIMIT", 0)
    horner = R.monte_carlo_chunk(g, "G5", "P4", np.arange(6), 4, steps_per_revolution=60, engine="compiled")
    for name in R.METRICS:
        assert_allclose(getattr(horner, name) / UM, getattr(tabled, name) / UM, rtol=0, atol=ACROSS_UM)
    (s,) = R.monte_carlo_errors(g, "G5", "P4", [5], 4)
    t = R.rotation_sequence(s.geometry, s.errors, revolutions=2, steps_per_revolution=60, engine="compiled")
    for name in R.METRICS:
        assert getattr(t.metrics, name) == getattr(horner, name)[5], name


@needs_numba
def test_the_engines_find_the_same_diameter():
    """Both take the square root of the largest dx^2 + dy^2 of an antipodal pair: the same bits here."""
    rng = np.random.default_rng(3)
    psi = 2 * np.pi * np.arange(360) / 180
    x = np.cos(3.7 * psi) * rng.uniform(0.5, 1, (50, 1)) + rng.normal(0, 0.1, (50, 360))
    y = np.sin(2.1 * psi) * rng.uniform(0.5, 1, (50, 1)) + rng.normal(0, 0.1, (50, 360))
    a, b = (R.runout_metrics(x, y, 0 * x, engine=e).radial_ptp_max for e in ("numpy", "compiled"))
    assert_array_equal(a, b)


# ------------------------------------------------------------------------------ one engine, the same bits
@pytest.mark.parametrize("engine", ENGINES)
def test_a_sample_gives_the_same_bits_in_any_chunk(g, engine):
    whole = R.monte_carlo_chunk(g, "G5", "P4", np.arange(9), 21, steps_per_revolution=60, engine=engine)
    for part in (np.arange(4), np.arange(4, 9), np.array([7])):
        got = R.monte_carlo_chunk(g, "G5", "P4", part, 21, steps_per_revolution=60, engine=engine)
        for name in got._fields:
            assert_array_equal(getattr(got, name), getattr(whole, name)[part], err_msg=name)


@pytest.mark.parametrize("engine", ENGINES)
def test_a_position_of_solve_contact_gives_the_same_bits_alone(engine):
    """A big batch runs the compiled loop over numba's threads, a single position on the calling thread:
    the same scalar code, the same bits (and the numpy walk's rows are independent)."""
    rng = np.random.default_rng(9)
    th = rng.uniform(0, 2 * np.pi, (3000, 1)) + 2 * np.pi * np.arange(16) / 16
    dk = np.round(rng.normal(0, 0.3, (3000, 16)), 1) * UM  # ties included
    batch = R.solve_contact(dk, th, engine=engine)
    for p in (0, 1234, 2999):
        one = R.solve_contact(dk[p], th[p], engine=engine)
        for name in one._fields:
            assert_array_equal(getattr(one, name), getattr(batch, name)[p], err_msg=name)


@pytest.mark.parametrize("engine", ENGINES)
def test_the_numpy_blocks_of_samples_do_not_change_the_bits(g, engine, monkeypatch):
    """The numpy engine solves a chunk in blocks of samples (memory); a block of one sample gives the
    same bits as one block of all."""
    from bearinglab.runout import tolerances

    whole = R.monte_carlo_chunk(g, "G3", "P2", np.arange(5), 8, steps_per_revolution=40, engine=engine)
    monkeypatch.setattr(tolerances, "_NUMPY_BLOCK", 1)
    blocks = R.monte_carlo_chunk(g, "G3", "P2", np.arange(5), 8, steps_per_revolution=40, engine=engine)
    for name in whole._fields:
        assert_array_equal(getattr(blocks, name), getattr(whole, name), err_msg=name)


# ------------------------------------------------------------------------------ engine choice
def test_the_numpy_engine_does_not_load_the_kernels(g):
    code = (
        "import math, sys, numpy as np\n"
        "from bearinglab import runout as R\n"
        "g = R.geometry_from_catalog(16, 7.144e-3, 54e-3, 0.53, 0.52, math.radians(15))\n"
        "e = R.manufacturing_errors(16, ball_diameter_deviation=np.r_[2e-6, np.zeros(15)])\n"
        "R.rotation_sequence(g, e, revolutions=1, steps_per_revolution=36, engine='numpy')\n"
        "R.monte_carlo(g, 'G5', 'P4', 4, 1, steps_per_revolution=12, engine='numpy')\n"
        "print('numba' in sys.modules, 'bearinglab.runout._compiled' in sys.modules)\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120, check=True)
    assert out.stdout.split() == ["False", "False"]


def test_auto_falls_back_to_numpy_without_numba(g, monkeypatch):
    real = importlib.util.find_spec
    monkeypatch.setattr(importlib.util, "find_spec", lambda name, *a: None if name == "numba" else real(name, *a))
    monkeypatch.setattr(_solver, "solve_dual", _numpy_only(_solver.solve_dual))
    e = R.manufacturing_errors(16, ball_diameter_deviation=np.r_[2e-6, np.zeros(15)])
    t = R.rotation_sequence(g, e)
    assert t.metrics.radial_ptp_x / UM == pytest.approx(2.070550, abs=1e-6)  # spec 003 example 1
    with pytest.raises(InputError, match="needs numba"):
        R.rotation_sequence(g, e, engine="compiled")


def _numpy_only(solve):
    def wrapped(*args, kernel=None, **kwargs):
        assert kernel is None, "the compiled kernel ran"
        return solve(*args, **kwargs)

    return wrapped


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        ({"engine": "fortran"}, r"engine must be one of \['auto', 'numpy', 'compiled'\], got 'fortran'"),
        ({"engine": "compiled", "method": "lp"}, "implements method='dual' only"),
    ],
)
def test_invalid_engines_are_refused(g, kwargs, match):
    e = R.manufacturing_errors(16)
    with pytest.raises(InputError, match=match):
        R.initial_displacement(0.0, g, e, **kwargs)
    with pytest.raises(InputError, match=match):
        R.solve_contact(np.zeros(16), 2 * np.pi * np.arange(16) / 16, **kwargs)
    if "method" not in kwargs:
        with pytest.raises(InputError, match=match):
            R.monte_carlo(g, "G5", "P4", 4, 1, **kwargs)


# ------------------------------------------------------------------------------ the walk
def test_a_walk_that_does_not_end_is_a_convergence_error(monkeypatch):
    """Never seen (a walk takes a few pivots); forced here by allowing none."""
    monkeypatch.setattr(_solver, "PIVOTS_PER_BALL", 0)
    monkeypatch.setattr(_solver, "PIVOTS_EXTRA", 0)
    th = 2 * np.pi * np.arange(16) / 16
    dk = np.zeros(16)
    dk[[2, 7, 12]] = -1.0  # the start triangle (the lowest ball and the balls nearest to +-120 deg) is not it
    dk[0] = -0.9
    with pytest.raises(ConvergenceError, match="dual walk"):
        R.solve_contact(dk * UM, th, engine="numpy")


@pytest.mark.parametrize("engine", ENGINES)
def test_a_thousand_random_balls_are_solved_exactly(engine):
    """Against scipy's LP, at the allowed maximum of balls (the triple enumeration would need C(1000, 3)
    triples; it is refused above 64 balls)."""
    from scipy.optimize import linprog

    rng = np.random.default_rng(11)
    n = 1000
    th = rng.uniform(0, 2 * np.pi, (3, 1)) + 2 * np.pi * np.arange(n) / n
    dk = rng.normal(0, 0.3, (3, n)) + 0.5 * np.cos(3 * th)
    s = R.solve_contact(dk * UM, th, engine=engine)
    for p in range(3):
        rows = np.column_stack([np.ones(n), np.sin(th[p]), np.cos(th[p])])
        lp = linprog([-1.0, 0.0, 0.0], A_ub=rows, b_ub=dk[p], bounds=[(None, None)] * 3, method="highs")
        assert s.constant[p] / UM == pytest.approx(lp.x[0], abs=1e-9)
    assert np.all(s.slack / UM >= -1e-9)
    with pytest.raises(InputError, match="n_balls <= 64"):
        R.solve_contact(dk * UM, th, method="triples")


# ------------------------------------------------------------------------------ memory (issue 29)
@pytest.mark.parametrize("engine", ENGINES)
def test_a_thousand_balls_take_little_memory_and_time(engine):
    """Issue 29: a runout of 1000 balls (the allowed maximum) needed more than 8 GB at 4 positions (400
    balls: 1.3 GB), the O(n^3) candidate triangles of the former dual enumeration. The walk holds O(n)
    a position: a few hundred kB here, in a fraction of a second."""
    g, e = big_bearing(1000), random_errors(1000)
    R.rotation_sequence(big_bearing(16), random_errors(16), revolutions=1, steps_per_revolution=4,
                        engine=engine)  # loads the kernels (compiled from source on a fresh install)
    tracemalloc.start()
    start = time.perf_counter()
    t = R.rotation_sequence(g, e, revolutions=1, steps_per_revolution=4, engine=engine)
    elapsed = time.perf_counter() - start
    peak = tracemalloc.get_traced_memory()[1]
    tracemalloc.stop()
    assert peak < 4e6, f"peak {peak / 1e6:.1f} MB"  # 0.3 MB measured: 4 positions x 1000 balls
    assert elapsed < 5.0, f"{elapsed:.2f} s"  # about 0.01 s on one core
    assert np.all(t.displacement.contact.slack >= -1e-9 * UM)


def test_memory_grows_linearly_with_balls_and_positions():
    """Peak traced memory per ball-position of the numpy engine, at 250 and at 1000 balls, and at 8 and
    32 positions: the same within the fixed overheads (the former solver grew as n^3)."""

    def peak(n, positions):
        g, e = big_bearing(n), random_errors(n)
        tracemalloc.start()
        R.initial_displacement(2 * np.pi * np.arange(positions) / positions, g, e, engine="numpy")
        out = tracemalloc.get_traced_memory()[1]
        tracemalloc.stop()
        return out

    per = {(n, p): peak(n, p) / (n * p) for n in (250, 1000) for p in (8, 32)}
    assert max(per.values()) < 400, per  # bytes a ball-position (75-86 measured)
    assert per[(1000, 32)] < 1.5 * per[(250, 32)], per
    assert per[(1000, 32)] < 1.5 * per[(1000, 8)], per


def test_a_thousand_ball_monte_carlo_stays_small(monkeypatch):
    """The numpy engine of the Monte Carlo works in blocks of samples (and of positions) of about 2^20
    ball-positions; the compiled one holds O(n) per sample and thread."""
    from bearinglab.runout import tolerances

    monkeypatch.setattr(tolerances, "_NUMPY_BLOCK", 1 << 14)
    g = big_bearing(1000)
    tracemalloc.start()
    r = R.monte_carlo_chunk(g, "G5", "P4", np.arange(3), 2, steps_per_revolution=8, revolutions=1,
                            engine="numpy")
    peak = tracemalloc.get_traced_memory()[1]
    tracemalloc.stop()
    assert peak < 20e6, f"peak {peak / 1e6:.1f} MB"
    assert np.all(np.isfinite(r.radial_ptp_max))


@pytest.mark.skipif(not os.path.exists("/proc/self/clear_refs"), reason="needs Linux's /proc peak RSS")
def test_the_resident_memory_of_the_issue_29_case_is_small():
    """The issue's case as a whole process on the default engine: the peak resident set size during a
    1000-ball runout at 4 positions (it needed more than 8 GB), over the process's size before it. The
    kernels are loaded (or compiled, on a fresh install: that alone takes some 400 MB) by a small case
    first, and the peak is reset after it (Linux: /proc/self/clear_refs)."""
    code = (
        "import math, numpy as np\n"
        "from bearinglab import runout as R\n"
        "def status(key):\n"
        "    return next(int(x.split()[1]) for x in open('/proc/self/status') if x.startswith(key))\n"
        "def bearing(n):\n"
        "    g = R.geometry_from_catalog(n, 7.144e-3, 1.2 * n * 7.144e-3 / math.pi, 0.53, 0.52, math.radians(15))\n"
        "    return g, R.manufacturing_errors(n, ball_diameter_deviation=np.linspace(-0.2, 0.2, n) * 1e-6)\n"
        "R.rotation_sequence(*bearing(16), revolutions=1, steps_per_revolution=4)\n"
        "g, e = bearing(1000)\n"
        "before = status('VmRSS:')\n"
        "open('/proc/self/clear_refs', 'w').write('5')\n"
        "R.rotation_sequence(g, e, revolutions=1, steps_per_revolution=4)\n"
        "print(before, status('VmHWM:'))\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=600, check=True)
    before, peak = (int(v) / 1024 for v in out.stdout.split()[-2:])  # kB -> MB
    assert peak - before < 50, f"{peak - before:.0f} MB over {before:.0f} MB"  # 0.3 MB measured


def test_too_many_ball_positions_are_refused_before_allocation(g):
    n = 1000
    limit = R.contact.MAX_BALL_POSITIONS // n
    big, e = big_bearing(n), R.manufacturing_errors(n)
    with pytest.raises(InputError, match=f"at most {limit} positions for 1000 balls"):
        R.initial_displacement(np.zeros(limit + 1), big, e)
    with pytest.raises(InputError, match="ball-positions"):
        R.rotation_sequence(big, e, revolutions=100, steps_per_revolution=3600)


# ------------------------------------------------------------------------------ the benchmark's goal row
def test_the_scaling_benchmark_writes_its_goal_row(load_bench, tmp_path, monkeypatch):
    """bench/scaling.py (run by make bench) replaces its row of the goals table, or adds it at the end of
    the table, and leaves every other line as it was."""
    monkeypatch.setattr(sys, "argv", ["scaling.py", "10"])
    bench = load_bench("scaling")
    md = tmp_path / "BENCHMARKS.md"
    head = ["# B", "", "## Where the goals stand", "", "| goal (issue) | measured | met |", "|---|---|---|",
            "| other goal (1) | 5 | yes |"]
    md.write_text("\n".join([*head, "", "## Next", "text"]) + "\n")
    row = bench.goal_row(2345.6, 1200.0, 0.977, (1.25, 1.5), 100000, "2026-11-29 03:00 UTC")
    assert row.startswith(bench.GOAL_ROW) and row.endswith("| yes |") and "load average (1 min) 1.25" in row
    bench.write_goal_row(row, md)
    assert md.read_text().splitlines() == [*head, row, "", "## Next", "text"]
    slower = bench.goal_row(1500.0, 800.0, 0.94, (3.0, 3.5), 100000, "2026-11-29 04:00 UTC")
    assert slower.endswith("| no |")
    bench.write_goal_row(slower, md)
    assert md.read_text().splitlines() == [*head, slower, "", "## Next", "text"]

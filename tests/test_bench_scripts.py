"""Smoke tests of the benchmark scripts under bench/.

The benchmarks themselves are not run by the tests (``make bench``); here each script's paths run on a
few cases and must agree (axial_angle and its fair baseline, friction_fits, high_speed and its scalar and compiled kernels,
combined at speed, run_all, scaling). More next to their models: tests/lab/test_fits.py
(friction_fits), tests/runout/test_runout_contact.py (runout), tests/quasistatic/test_thrust.py
(high_speed), tests/quasistatic/test_combined.py (combined at rest), tests/ratings/test_rating_life.py
(life), tests/friction/test_skf.py (skf_friction); cli_help has its smoke test here.
"""

import math
import sys

import numpy as np
import pytest
from numpy.testing import assert_allclose

UM_MRAD = np.array([1e-6, 1e-6, 1e-6, 1e-3, 1e-3])  # displacements in um, tilts in mrad
ULP_ACROSS_ENGINES = 4  # numpy, plain Python and numba round some library functions differently


def _ulp(a, b):
    """|a - b| in units of the last place of b."""
    b = np.asarray(b, dtype=float)
    return np.abs(np.asarray(a, dtype=float) - b) / np.spacing(np.abs(b))


def test_axial_angle_paths_agree_case_by_case(load_bench):
    bench = load_bench("axial_angle")
    m = bench.measure(n_batch=300, n_baseline=50, n_brentq=10, repeat=1, n_small=100)
    assert m["diff"] < 1e-12 and m["diff_brentq"] < 1e-10 and m["diff_numpy"] < 1e-12


def test_axial_angle_baseline_takes_the_library_steps_case_by_case(load_bench):
    bench = load_bench("axial_angle")
    kernels = bench._kernels
    from bearinglab import stand

    a0 = np.array([0.1, 0.3, 0.6, 1.0, 1.3] * 4)  # per-case bearings, loads from feather to near 90 deg
    cs = np.full(a0.size, 5e4)
    fa = cs * np.repeat([1e-9, 1e-5, 1e-3, 1e-1], 5)
    lib = stand.operating_contact_angle(fa, cs, a0, engine="numpy")
    one = [kernels.solve_one(f, c, a, math.cos(a), math.sin(a), *bench.TOL) for f, c, a in zip(fa, cs, a0)]
    # the same operations, but plain Python calls the C library where numpy may call its own SIMD functions
    # (AVX-512 hosts): a few ulp apart, as the two engines of the library (tests/test_stand_compiled.py)
    assert _ulp([x[0] for x in one], lib).max() <= ULP_ACROSS_ENGINES
    assert all(x[1] == 0 for x in one)  # the start passes the load test of section 6.3
    # with the load test off (ftol 0) the Newton of section 6.3 runs: the same angles, steps as the kernel's
    xtol, _, max_iter = bench.TOL
    newton = [kernels.solve_one(f, c, a, math.cos(a), math.sin(a), xtol, 0.0, max_iter) for f, c, a in zip(fa, cs, a0)]
    assert_allclose([x[0] for x in newton], lib, rtol=0, atol=1e-12)
    # where the Newton runs, the engines agree to its step tolerance (tests/test_stand_compiled.py)
    assert_allclose([x[0] for x in newton], stand.operating_contact_angle(fa, cs, a0, ftol_percent=0.0,
                                                                           engine="numpy"), rtol=0, atol=xtol)
    if kernels.available():
        from bearinglab.stand import _compiled as _stand_compiled

        alpha, iterations, residual, n_bad = _stand_compiled.solve(fa, cs, a0, fa.size, xtol, 0.0, max_iter)
        assert np.all(residual == 0.0)
        assert_allclose(alpha, [x[0] for x in newton], rtol=0, atol=xtol)
        assert n_bad == 0
        assert np.array_equal(iterations, [x[1] for x in newton]) and np.all(iterations >= 1)
    # a case that has not converged is flagged (negative count, the last residual), never silently kept
    fail = [kernels.solve_one(f, c, a, math.cos(a), math.sin(a), 0.0, 0.0, 1) for f, c, a in zip(fa, cs, a0)]
    assert all(x[1] == -1 and math.isfinite(x[2]) for x in fail)


def test_axial_angle_main_prints_a_result_line(load_bench, capsys):
    bench = load_bench("axial_angle")
    assert bench.main(n_batch=200, n_baseline=20, n_brentq=5, repeat=1) == 0
    line = [x for x in capsys.readouterr().out.splitlines() if x.startswith("RESULT axial_angle ")]
    assert len(line) == 1 and "baseline_label=fair_scalar" in line[0]
    keys = [kv.split("=")[0] for kv in line[0].split()[2:]]
    assert keys[:5] == ["cases_per_s", "baseline_cases_per_s", "ratio", "baseline_label", "former_brentq_ratio"]


def test_friction_fits_fair_and_former_baselines_agree(load_bench):
    bench = load_bench("friction_fits")
    t, speed, groups = bench.cases(30, seed=5)
    f0, tf = bench.batched(t, speed, groups)
    for fit in (bench.baseline, bench.linregress_baseline):
        f0_ref, tf_ref = fit(t, speed, 30)
        assert_allclose(f0, f0_ref, rtol=1e-9)
        assert_allclose(tf, tf_ref, rtol=1e-9)


def test_scaling_study_is_importable_and_names_its_parts(load_bench, monkeypatch):
    monkeypatch.setattr(sys, "argv", ["scaling.py", "10"])
    bench = load_bench("scaling")  # the study needs a dask cluster and minutes: only its parts here
    assert callable(bench.study) and callable(bench.main)


def test_run_all_leaves_a_failed_script_out_of_the_table(load_bench, tmp_path, monkeypatch):
    bench = load_bench("run_all")
    (tmp_path / "bench").mkdir()
    good, bad = tmp_path / "bench" / "good.py", tmp_path / "bench" / "bad.py"
    good.write_text("print('RESULT good cases_per_s=10 baseline_cases_per_s=1 ratio=10')\n")
    bad.write_text("import sys\nprint('RESULT bad cases_per_s=1e9 baseline_cases_per_s=1 ratio=1e9')\nsys.exit(1)\n")
    (tmp_path / "BENCHMARKS.md").write_text("# B\n\n<!-- results:begin -->\nold\n<!-- results:end -->\n")
    monkeypatch.setattr(bench, "HERE", tmp_path / "bench")
    monkeypatch.setattr(bench, "ROOT", tmp_path)
    monkeypatch.setattr(bench, "__file__", str(tmp_path / "bench" / "run_all.py"))
    assert bench.main() == 1
    text = (tmp_path / "BENCHMARKS.md").read_text()
    assert "### good" in text and "1e9" not in text and "### bad" not in text
    assert "Left out" in text and "bad.py" in text and "old" not in text


def test_cli_help_times_the_help_and_prints_a_result_line(load_bench, capsys):
    bench = load_bench("cli_help")
    assert bench.main(repeat=1) == 0
    out = capsys.readouterr().out
    line = [x for x in out.splitlines() if x.startswith("RESULT cli_help ")]
    assert len(line) == 1 and "seconds=" in line[0] and "within_goal=" in line[0]
    assert "bearinglab high-speed --help" in out and "0.3 s goal" in out
    catalog = [x for x in out.splitlines() if x.startswith("RESULT catalog_startup ")]
    assert len(catalog) == 1 and "baseline_label=goal_0.5_s" in catalog[0] and "within_goal=" in catalog[0]
    assert "bearinglab catalog show 6208-2RS1/C3" in out and "0.5 s goal" in out


def test_high_speed_fair_baseline_and_batched_agree_case_by_case(load_bench):
    bench = load_bench("high_speed")
    m = bench.measure(n_loads=4, n_speeds=5, n_baseline=20, n_former=3, repeat=1)
    assert m["failed"] == m["failed_base"] == m["failed_former"] == 0
    assert m["diff"] < 1e-12 and m["diff_former"] < 1e-9
    assert m["diff_state"] < 1e-12  # the baseline computes the whole state too
    if "compiled_rate" in m:  # numba installed
        assert m["diff_compiled"] < 1e-12 and m["diff_state_compiled"] < 1e-12
        assert m["diff_state_compiled_scalar"] < 1e-12


def test_high_speed_scalar_solver_takes_the_same_newton_steps(load_bench):
    bench = load_bench("high_speed")
    kernels = load_bench("_kernels_highspeed")
    fa, n = bench.grid(3, 4)
    state = bench.batched(fa, n)
    solve = kernels.solver(*kernels.bearing_parameters(bench.GEO, constants=bench.OPTIONS["constants"]))
    for f, w, it, ai in zip(fa.ravel(), n.ravel(), state.iterations.ravel(), state.contact_angle_inner.ravel(),
                            strict=True):
        _alpha_s, _v, status, iterations, out = solve(float(f), float(w))
        assert status == 0 and iterations == it
        assert out[0] == pytest.approx(ai, rel=0, abs=1e-12)


def test_high_speed_main_prints_a_result_line(load_bench, capsys):
    bench = load_bench("high_speed")
    assert bench.main(n_loads=3, n_speeds=3, n_baseline=9, n_former=2, repeat=1) == 0
    line = [x for x in capsys.readouterr().out.splitlines() if x.startswith("RESULT high_speed ")]
    assert len(line) == 1 and "baseline_label=fair_scalar" in line[0] and "former_fsolve_ratio" in line[0]
    assert line[0].endswith("baseline_work=static_start+solve+state")


@pytest.mark.parametrize("name", ["combined", "life", "skf_friction", "runout", "high_speed", "film", "thermal"])
def test_every_script_has_a_main(load_bench, name):
    assert callable(load_bench(name).main)


def test_combined_shipped_kernel_takes_the_steps_of_the_numpy_path(load_bench):
    """Issue 31: the shipped path (the compiled kernel where numba is installed) and the numpy path run one
    algorithm: the same iterations give or take one, the displacement to 1e-10 um / mrad."""
    bench = load_bench("combined")
    loads = bench.cases(16, [1500, 1500, 1500, 15.0, 15.0], seed=4)
    state, slow = bench.batched(bench.DEEP, loads), bench.batched(bench.DEEP, loads, engine="numpy")
    assert state.converged.all() and np.all(np.abs(state.iterations - slow.iterations) <= 1)
    assert_allclose(state.displacement / UM_MRAD, slow.displacement / UM_MRAD, rtol=0, atol=1e-10)  # um, mrad


def test_combined_fair_baseline_at_speed_agrees_with_the_batched_path(load_bench):
    bench = load_bench("combined")
    loads = bench.speed_cases(3)
    state = bench.batched(bench.B218, loads, bench.SPEED)
    assert state.converged.all()
    ref = bench.baseline(bench.B218, loads, bench.SPEED)()  # the kernel's per-case functions in CPython
    assert_allclose(ref / UM_MRAD, state.displacement / UM_MRAD, rtol=0, atol=1e-9)  # um, mrad


def test_combined_main_prints_both_result_lines(load_bench, capsys):
    bench = load_bench("combined")
    assert bench.main(n_rest=20, n_base=5, n_speed=4, n_speed_base=2, repeat=1) == 0
    lines = [x for x in capsys.readouterr().out.splitlines() if x.startswith("RESULT combined_")]
    assert [x.split()[1] for x in lines] == ["combined_rest", "combined_speed"]
    assert all("baseline_label=fair_scalar" in x and " load_average=" in x and " goal_met=" in x for x in lines)
    assert "goal_cases_per_s=1e+05" in lines[0] and "goal_cases_per_s=1e+04" in lines[1]


@pytest.mark.parametrize("name, kwargs", [("film", {"n_side": 4, "n_base": 8, "repeat": 1}),
                                          ("thermal", {"n_batch": 40, "n_base": 10, "repeat": 1})])
def test_film_and_thermal_scripts_agree_with_their_baselines(load_bench, capsys, name, kwargs):
    assert load_bench(name).main(**kwargs) == 0  # 0: the per-case baseline agreed case by case
    assert [x.split()[1] for x in capsys.readouterr().out.splitlines() if x.startswith("RESULT ")] == [name]


@pytest.mark.parametrize(("kind", "rpm"), [("four-point", 0.0), ("self-aligning", 12000.0), ("thrust", 0.0)])
def test_ball_types_batch_and_case_by_case_agree_bit_for_bit(load_bench, kind, rpm):
    """bench/ball_types.py (issue 30): every case converges and the batch gives each case the bits it has alone."""
    bench = load_bench("ball_types")
    m = bench.measure(kind, rpm * math.pi / 30, n=12, n_base=4, repeat=1)
    assert m["same"] and m["failed"] == 0

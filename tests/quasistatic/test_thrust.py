"""The bearing under thrust at speed (spec 004): the paper's claims (section 8) over grids of loads and
speeds, failures and bad input, sweeps and the result table."""

import math
import warnings

import numpy as np
import pytest
from b218_cases import B218, DEG, FAST, GEO, _solve, loads, speeds
from hypothesis import given

from bearinglab import catalog, parallel, quasistatic
from bearinglab.errors import ConvergenceError, InputError, ValidityWarning
from bearinglab.units import RPM


# --------------------------------------------------------------------------- the paper's claims (section 8)
@FAST
@given(fa=loads, n1=speeds, n2=speeds)
def test_inner_angle_rises_and_outer_falls_with_speed(fa, n1, n2):
    if abs(n1 - n2) < 50:
        return
    lo, hi = sorted((n1, n2))
    s = _solve(fa, np.array([0.0, lo, hi]))
    assert s.contact_angle_inner[0] < s.contact_angle_inner[1] < s.contact_angle_inner[2]
    assert s.contact_angle_outer[0] > s.contact_angle_outer[1] > s.contact_angle_outer[2]
    assert np.all(s.contact_angle_inner[1:] > s.contact_angle_outer[1:])  # alpha_i > alpha_e at speed


@FAST
@given(fa=loads, n=speeds)
def test_increments_from_the_static_angle(fa, n):
    """Delta alpha_i - Delta alpha_e < 0, the outer increment above the inner one (Fig. 4), so the solution
    lies below the line alpha_i + alpha_e = 2 alpha_s (the paper's search triangle)."""
    s = _solve(fa, n)
    d_i = s.contact_angle_inner - s.static_contact_angle
    d_e = s.static_contact_angle - s.contact_angle_outer
    assert d_i > 0 and d_e > 0
    assert d_i - d_e < 0
    assert s.contact_angle_inner + s.contact_angle_outer < 2 * s.static_contact_angle


def test_reversed_sign_breaks_the_increment_claim():
    """Section 4/8: with the reversed gyroscopic sign Delta alpha_i - Delta alpha_e < 0 fails at >= 10 kN,
    3000 rpm and >= 20 kN, 6000 rpm and at 45 kN, 10 000 rpm; it holds with the physical sign."""
    fa = np.array([10e3, 20e3, 45e3])
    for sign, expect in ((1, False), (-1, True)):
        s = _solve(fa[:, None], np.array([3000.0, 6000.0, 10000.0]), gyroscopic_sign=sign)
        broken = (s.contact_angle_inner - s.static_contact_angle) > (s.static_contact_angle - s.contact_angle_outer)
        if expect:
            assert broken[:, 0].all() and broken[1:, 1].all() and broken[2, 2]
        else:
            assert not broken.any()


@FAST
@given(f1=loads, f2=loads, n=speeds)
def test_increments_shrink_and_approach_each_other_as_thrust_grows(f1, f2, n):
    if abs(f1 - f2) < 100:
        return
    lo, hi = sorted((f1, f2))
    s = _solve(np.array([lo, hi]), n)
    d_i = s.contact_angle_inner - s.static_contact_angle
    d_e = s.static_contact_angle - s.contact_angle_outer
    assert d_i[1] < d_i[0] and d_e[1] < d_e[0]
    assert abs(d_i[1] - d_e[1]) < abs(d_i[0] - d_e[0])


@FAST
@given(fa=loads, n1=speeds, n2=speeds)
def test_increments_grow_with_speed(fa, n1, n2):
    if abs(n1 - n2) < 50:
        return
    lo, hi = sorted((n1, n2))
    s = _solve(fa, np.array([lo, hi]))
    d_i = s.contact_angle_inner - s.static_contact_angle
    d_e = s.static_contact_angle - s.contact_angle_outer
    assert d_i[1] > d_i[0] and d_e[1] > d_e[0]


def test_axial_displacement_negative_at_low_thrust_and_high_speed():
    fa = np.array([2.5e3, 5e3])[:, None]
    s = _solve(fa, np.array([6000.0, 10000.0, 15000.0]))
    assert np.all(s.axial_displacement < 0)
    assert np.all(_solve(fa, 0.0).axial_displacement > 0)


def test_thrust_for_positive_displacement_grows_with_speed():
    n = np.array([0.0, 2000.0, 4000.0, 8000.0, 12000.0, 16000.0])
    f0 = quasistatic.zero_displacement_thrust(n * RPM, *GEO)
    assert f0[0] == 0.0
    assert np.all(np.diff(f0) > 0)
    below = _solve(0.97 * f0[1:], n[1:])
    above = _solve(1.03 * f0[1:], n[1:])
    assert np.all(below.axial_displacement < 0) and np.all(above.axial_displacement > 0)


# --------------------------------------------------------------------------- failures and bad input
def test_thrust_too_small_for_the_speed():
    """Inner-raceway control: at low thrust the inner contact would need Q_i < 0 (the ball leaves it)."""
    s = _solve(np.array([300.0, 20e3]), 15000.0 * np.array([1.0, 0.2]), raceway_control="inner", on_failure="flag")
    assert list(s.status) == ["inner_contact_lost", "ok"]
    assert not s.converged[0] and np.isnan(s.contact_angle_outer[0]) and np.isnan(s.residual[0])
    with pytest.raises(ConvergenceError, match="leaves the inner raceway.*thrust too small for the speed"):
        _solve(300.0, 15000.0, raceway_control="inner")


def test_angle_leaving_the_quadrant():
    """A 60 deg bearing at 100 N: at 3000 rpm the inner contact angle would pass 90 deg."""
    z, d, dm, fi, fo, _a0, ep, rho = GEO
    args = (z, d, dm, fi, fo, 60 * DEG, ep, rho)
    s = quasistatic.contact_angles(100.0, np.array([1000.0, 3000.0]) * RPM, *args, on_failure="flag",
                                   friction_limit=np.inf)
    assert list(s.status) == ["ok", "angle_out_of_range"]
    assert s.contact_angle_inner[0] > 85 * DEG
    with pytest.raises(ConvergenceError, match=r"a contact angle leaves \(0, 90\) deg"):
        quasistatic.contact_angles(100.0, 3000 * RPM, *args)


def test_non_convergence_raises_or_flags():
    with pytest.raises(ConvergenceError, match="no convergence.*F_a = 2500 N, 15000 rpm") as err:
        _solve(2.5e3, 15000.0, max_iter=2)
    assert err.value.iterations == 2
    s = _solve(np.array([2.5e3, 45e3]), np.array([15000.0, 0.0]), max_iter=2, on_failure="flag")
    assert list(s.status) == ["no_convergence", "ok"]
    assert list(s.converged) == [False, True]
    assert np.isnan(s.ball_load_inner[0]) and np.isfinite(s.ball_load_inner[1])


def test_one_failed_case_does_not_stop_a_sweep():
    fa = np.array([300.0, 5e3, 20e3])
    n = np.array([3000.0, 15000.0]) * RPM
    s = quasistatic.sweep(B218, fa, n, raceway_control="inner", friction_limit=np.inf)
    assert s.status.shape == (3, 2)
    assert s.status[0, 1] == "inner_contact_lost"
    ok = s.converged
    assert ok.sum() >= 3
    for i, j in zip(*np.nonzero(ok)):
        one = quasistatic.high_speed_analysis(B218, fa[i], n[j], raceway_control="inner", friction_limit=np.inf)
        assert one.contact_angle_inner == pytest.approx(s.contact_angle_inner[i, j], abs=1e-12)


@pytest.mark.parametrize("kwargs,match", [
    ({"shaft_speed": -100.0}, r"shaft_speed must be >= 0 and finite \[rpm\], got -954.93 rpm.*magnitude"),
    ({"axial_load": 0.0}, r"axial_load must be > 0 \[N\]"),
    ({"free_angle": 0.0}, r"free_angle must be in \(0, 90\) \[deg\]"),
    ({"free_angle": math.pi / 2}, r"free_angle must be in \(0, 90\) \[deg\]"),
    ({"pitch_diameter": 10e-3}, r"pitch_diameter must be > ball_diameter"),
    ({"density": -1.0}, r"density must be > 0"),
    ({"method": "brent"}, r"method must be one of \['newton', 'angle-iteration'\]"),
    ({"raceway_control": "cage"}, r"raceway_control must be one of \['outer', 'inner'\]"),
    ({"gyroscopic_sign": 0}, r"gyroscopic_sign must be \+1"),
    ({"constants": "jones"}, r"constants must be one of \['mass', 'harris', 'paper'\]"),
    ({"constants": (1.0, -1.0)}, r"C_c and C_g must be >= 0"),
    ({"on_failure": "ignore"}, r"on_failure must be one of \['raise', 'flag'\]"),
    ({"speed_step": 0.0}, r"speed_step must be > 0"),
])
def test_bad_input_names_parameter_rule_and_value(kwargs, match):
    z, d, dm, fi, fo, a0, ep, rho = GEO
    args = {"axial_load": 1e4, "shaft_speed": 1000.0, "n_balls": z, "ball_diameter": d, "pitch_diameter": dm,
                "inner_conformity": fi, "outer_conformity": fo, "free_angle": a0, "reduced_modulus": ep, "density": rho}
    args.update(kwargs)
    with pytest.raises(InputError, match=match):
        quasistatic.contact_angles(**args)


def test_bearing_without_a_usable_angle():
    with pytest.raises(InputError, match="contact_angle of '6205-2RS' must be in \\(0, 90\\)"):
        quasistatic.high_speed_analysis(catalog.get("6205-2RS").replace(inner_conformity=0.52, outer_conformity=0.52),
                                        1e3, 100.0)
    with pytest.raises(InputError, match="n_balls of '1000095' is not known"):
        quasistatic.high_speed_analysis(catalog.get("1000095"), 1e3, 100.0)


def test_friction_warning_when_outer_control_needs_too_much_friction():
    with pytest.warns(ValidityWarning, match=r"1 of 1 cases need a friction coefficient above 0.05 .*0.0639 at F_a = 20000 N, 10000 rpm"):
        quasistatic.high_speed_analysis(B218, 20e3, 10000 * RPM, constants="harris", friction_limit=0.05)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        s = quasistatic.high_speed_analysis(B218, 20e3, 10000 * RPM, constants="harris")
    assert s.friction_coefficient == pytest.approx(2 * s.gyroscopic_moment / (B218.ball_diameter * s.ball_load_outer))


def test_result_table_units():
    s = quasistatic.sweep(B218, [20e3], [10000 * RPM], constants="harris")
    t = quasistatic.result_table(s)
    assert t["axial_load_N"][0] == 20e3 and t["speed_rpm"][0] == 10000.0
    assert t["contact_angle_inner_deg"][0] == pytest.approx(math.degrees(s.contact_angle_inner[0, 0]))
    assert t["gyroscopic_moment_Nmm"][0] == pytest.approx(s.gyroscopic_moment[0, 0] * 1e3)
    assert t["axial_displacement_um"][0] == pytest.approx(s.axial_displacement[0, 0] * 1e6)
    assert t["status"][0] == "ok" and t["converged"][0]


def test_bench_solvers_agree_on_a_small_map(load_bench):
    bench = load_bench("high_speed")
    fa, n = bench.grid(4, 3)
    state = bench.batched(fa, n)
    ref = bench.baseline(fa.ravel(), n.ravel())
    assert np.all(state.converged)
    assert np.abs(state.contact_angle_inner.ravel() - ref[:, 0]).max() < 1e-9
    assert np.abs(state.contact_angle_outer.ravel() - ref[:, 1]).max() < 1e-9


def test_sweep_in_chunks_reports_progress_and_equals_one_call():
    calls = []
    fa, n = [5e3, 20e3], np.array([0.0, 3000.0, 6000.0, 15000.0]) * RPM
    ex = parallel.Execution(chunk_size=3, progress=lambda done, total: calls.append((done, total)))
    a = quasistatic.sweep(B218, fa, n, execution=ex)
    b = quasistatic.sweep(B218, fa, n)
    assert calls == [(3, 8), (6, 8), (8, 8)]
    assert a.contact_angle_inner.shape == (2, 4)
    assert np.array_equal(a.contact_angle_inner, b.contact_angle_inner)  # bit for bit: cases are independent
    assert list(a.status.ravel()) == ["ok"] * 8


@pytest.mark.parametrize("engine", ["numpy", "compiled"])
def test_sweep_is_bit_identical_for_any_chunk_size(engine):
    fa, n = np.linspace(1e3, 30e3, 5), np.array([0.0, 4000.0, 9000.0, 15000.0]) * RPM
    whole = quasistatic.sweep(B218, fa, n, engine=engine)
    for size in (1, 3, 7):
        part = quasistatic.sweep(B218, fa, n, engine=engine, execution=parallel.Execution(chunk_size=size))
        for field in ("contact_angle_inner", "contact_angle_outer", "axial_displacement", "ball_load_inner"):
            assert np.array_equal(getattr(part, field), getattr(whole, field)), (size, field)


def test_sweep_keeps_the_old_execution_keywords():
    """chunk_size, progress, executor, ... still work (public since 0.1) and give the same chunks."""
    fa, n = [5e3, 20e3], np.array([0.0, 6000.0]) * RPM
    old, new = [], []
    a = quasistatic.sweep(B218, fa, n, chunk_size=3, executor="serial", progress=lambda d, t: old.append((d, t)))
    b = quasistatic.sweep(B218, fa, n, execution=parallel.Execution(chunk_size=3, progress=lambda d, t: new.append((d, t))))
    assert old == new == [(3, 4), (4, 4)]
    assert np.array_equal(a.contact_angle_inner, b.contact_angle_inner)
    with pytest.raises(InputError, match="not both"):
        quasistatic.sweep(B218, fa, n, execution=parallel.Execution(), chunk_size=3)
    with pytest.raises(InputError, match="chunk_size"):
        quasistatic.sweep(B218, fa, n, chunk_size=0)


def test_sweep_default_chunk_is_20000_cases(monkeypatch):
    seen = {}
    real = parallel.run_cases

    def spy(func, cases, **kw):
        seen["execution"] = kw["execution"]
        return real(func, cases, **kw)

    monkeypatch.setattr(parallel, "run_cases", spy)
    quasistatic.sweep(B218, [5e3], [0.0])
    assert seen["execution"].chunk_size == 20_000
    quasistatic.sweep(B218, [5e3], [0.0], execution=parallel.Execution(executor="serial"))
    assert seen["execution"].chunk_size == 20_000

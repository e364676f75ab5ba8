"""The least-squares tasks of the friction lab (bearinglab.lab.fits): generic fits against scipy, grouped
fits, degenerate groups, noiseless recovery of the model coefficients, the deprecated names."""

import math

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from numpy.testing import assert_allclose
from scipy import stats

from bearinglab import friction
from bearinglab.errors import InputError
from bearinglab.lab import fits

RPM = 2 * math.pi / 60
FAST = settings(max_examples=40, deadline=None)


def test_straight_line_matches_scipy_linregress_with_standard_errors():
    rng = np.random.default_rng(1)
    x = np.linspace(1.0, 9.0, 7)
    y = 0.3 + 1.7 * x + rng.normal(0, 0.05, x.size)
    got = fits.straight_line(x, y)
    ref = stats.linregress(x, y)
    assert got.slope == pytest.approx(ref.slope, rel=1e-12)
    assert got.intercept == pytest.approx(ref.intercept, rel=1e-12)
    assert got.slope_standard_error == pytest.approx(ref.stderr, rel=1e-10)
    assert got.intercept_standard_error == pytest.approx(ref.intercept_stderr, rel=1e-10)
    assert got.residual_rms == pytest.approx(np.sqrt(np.mean(got.residuals**2)), rel=1e-15)
    assert got.count == 7


def test_through_origin_standard_error_and_residuals():
    x = np.array([1.0, 2.0, 4.0])
    y = np.array([2.1, 3.9, 8.2])
    got = fits.through_origin(x, y)
    k = (x * y).sum() / (x * x).sum()
    r = y - k * x
    assert got.slope == pytest.approx(k, rel=1e-15)
    assert got.slope_standard_error == pytest.approx(
        np.sqrt((r**2).sum() / 2 / (x * x).sum()), rel=1e-13
    )
    assert_allclose(got.residuals, r, rtol=1e-13)


def test_standard_errors_are_nan_without_redundancy():
    line = fits.straight_line([1.0, 2.0], [1.0, 3.0])
    assert (
        line.slope == 2.0
        and math.isnan(line.slope_standard_error)
        and math.isnan(line.intercept_standard_error)
    )
    one = fits.through_origin([2.0], [4.0])
    assert one.slope == 2.0 and math.isnan(one.slope_standard_error) and one.residual_rms == 0.0


def test_grouped_fits_equal_fits_one_group_at_a_time():
    rng = np.random.default_rng(7)
    groups = np.repeat(["b", "a", "c"], [4, 5, 3])
    x = rng.uniform(1, 10, groups.size)
    y = 2.0 + 0.5 * x + rng.normal(0, 0.1, x.size)
    got = fits.straight_line(x, y, groups=groups)
    for k, label in enumerate(["a", "b", "c"]):  # ordered like numpy.unique
        one = fits.straight_line(x[groups == label], y[groups == label])
        for field in (
            "slope",
            "intercept",
            "slope_standard_error",
            "intercept_standard_error",
            "residual_rms",
        ):
            assert getattr(got, field)[k] == pytest.approx(getattr(one, field), rel=1e-12), field
        assert_allclose(got.residuals[groups == label], one.residuals, rtol=1e-10, atol=1e-15)


def test_degenerate_groups_are_errors_naming_the_group():
    # spec 001 section 10.3: a task 2 group with all speeds equal -> error
    with pytest.raises(
        InputError,
        match=r"task 2: group 1 needs at least two distinct values of shaft_speed, "
        r"got 3 point\(s\) all at 1500 rpm",
    ) as exc:
        fits.speed_dependence(
            [1e-5, 2e-5, 3e-5, 1e-5, 2e-5, 3e-5],
            np.array([500, 1000, 1500, 1500, 1500, 1500]) * RPM,
            9e-3,
            groups=[0, 0, 0, 1, 1, 1],
        )
    assert exc.value.group == 1
    with pytest.raises(
        InputError, match="task 3: the data needs at least two distinct values of equivalent_load"
    ):
        fits.load_dependence([1e-5, 2e-5], [5.0, 5.0], 9e-3, 392.0)
    with pytest.raises(InputError, match="task 1: the data has all equivalent_load = 0"):
        fits.reduced_friction_coefficient([1e-5, 2e-5], [0.0, 0.0], 5e-3)
    with pytest.raises(InputError, match="groups must label every point"):
        fits.straight_line([1, 2, 3], [1, 2, 3], groups=[0, 1])


generating = {
    "f0": st.floats(5e-8, 2e-6),
    "f": st.floats(2e-4, 5e-3),
    "dm": st.floats(5e-3, 0.1),
    "c0": st.floats(1e3, 1e5),
    "p0": st.floats(0.5, 90.0),
    "n": st.floats(100.0, 2e4),
    "spread": st.floats(1.2, 6.0),
    "m": st.integers(2, 8),
}


@FAST
@given(**generating)
def test_noiseless_two_term_data_recovered_by_task2(f0, f, dm, c0, p0, n, spread, m):
    speeds = np.geomspace(n, n * spread, m) * RPM
    t = friction.two_term(p0, speeds, dm, c0, f0, load_term_factor=f)
    got = fits.speed_dependence(t.torque, speeds, dm)
    assert got.speed_term_factor == pytest.approx(f0, rel=1e-9)
    assert got.load_term == pytest.approx(float(t.load_term[0]), rel=1e-9)
    assert got.residual_rms <= 1e-9 * float(t.torque.max())


@FAST
@given(**generating)
def test_noiseless_two_term_data_recovered_by_task3(f0, f, dm, c0, p0, n, spread, m):
    loads = np.geomspace(p0, p0 * spread, m)
    t = friction.two_term(loads, n * RPM, dm, c0, f0, load_term_factor=f)
    # the fit can only see f through the spread of T_F between the points: where that spread is below
    # 1e-6 of the torque, rounding alone limits f to ~1e-10 / 1e-6 relative (a well-posed case only)
    assume(np.ptp(t.load_term) > 1e-6 * float(np.max(t.torque)))
    got = fits.load_dependence(t.torque, loads, dm, c0, load_term_exponent=0.55)
    assert got.load_term_factor == pytest.approx(f, rel=1e-9)
    assert got.speed_term == pytest.approx(float(t.speed_term[0]), rel=1e-9)


@FAST
@given(mu=st.floats(1e-4, 1e-2), d=st.floats(1e-3, 0.1), m=st.integers(1, 6))
def test_noiseless_one_term_data_recovered_by_task1(mu, d, m):
    p0 = np.linspace(1.0, 30.0, m)
    t = friction.one_term(p0, d, reduced_friction_coefficient=mu)
    got = fits.reduced_friction_coefficient(t, p0, d)
    assert got.reduced_friction_coefficient == pytest.approx(mu, rel=1e-12)
    assert got.residual_rms <= 1e-12 * float(np.max(t))


def test_benchmark_paths_agree_on_a_small_input(load_bench):
    bench = load_bench("friction_fits")
    t, speed, groups = bench.cases(20, seed=3)
    f0, tf = bench.batched(t, speed, groups)
    f0_ref, tf_ref = bench.baseline(t, speed, 20)
    assert_allclose(f0, f0_ref, rtol=1e-10)
    assert_allclose(tf, tf_ref, rtol=1e-9)


def test_deprecated_task1_names_warn_and_give_the_same_fit():
    t, p0 = np.array([0.025, 0.037, 0.070]) * 1e-3, [4.905, 9.81, 19.62]
    new = fits.reduced_friction_coefficient(t, p0, 5e-3)
    with pytest.warns(DeprecationWarning, match="use reduced_friction_coefficient"):
        old = fits.friction_coefficient(t, p0, 5e-3)
    assert old.reduced_friction_coefficient == new.reduced_friction_coefficient
    with pytest.warns(DeprecationWarning, match=r"\.friction_coefficient is deprecated"):
        assert new.friction_coefficient == new.reduced_friction_coefficient
    with pytest.warns(DeprecationWarning, match="use ReducedFrictionCoefficientFit"):
        assert fits.FrictionCoefficientFit is fits.ReducedFrictionCoefficientFit
    with pytest.raises(AttributeError, match="no attribute 'no_such_name'"):
        fits.no_such_name  # noqa: B018
